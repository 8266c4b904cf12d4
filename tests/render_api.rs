//! The progressive render API: determinism, passes, preview exposure, cancel, memory checks,
//! automatic framing.

mod common;

use std::sync::atomic::AtomicBool;

use ugnis::flame::render::{RenderError, RenderOptions, Renderer, estimate_memory, render};
use ugnis::flame::{Affine, Flame, OutputFormat, Xform};
use ugnis::io::flam3_xml::ReadOptions;

fn example(name: &str) -> Flame {
    let mut f = ugnis::io::read_flames(&common::example(name), &ReadOptions::default())
        .unwrap()
        .value
        .remove(0);
    f.resize_keep_framing(96, 72);
    f.quality = 40.0;
    f
}

fn opts(seed: u64, threads: usize) -> RenderOptions {
    RenderOptions {
        seed,
        threads,
        ..RenderOptions::default()
    }
}

fn mean(img: &image::DynamicImage) -> f64 {
    let v = img.to_rgb8();
    v.as_raw().iter().map(|&b| b as f64).sum::<f64>() / v.as_raw().len() as f64
}

#[test]
fn same_seed_and_threads_give_identical_images() {
    let f = example("ember-swirl.flame");
    let a = render(&f, &opts(3, 2)).unwrap();
    let b = render(&f, &opts(3, 2)).unwrap();
    assert_eq!(a.as_bytes(), b.as_bytes());
    let c = render(&f, &opts(4, 2)).unwrap();
    assert_ne!(a.as_bytes(), c.as_bytes());
}

#[test]
fn pass_schedule_does_not_change_the_image() {
    let f = example("features.flame");
    let never = AtomicBool::new(false);
    let mut one = Renderer::new(&f, &opts(9, 3)).unwrap();
    one.run_all(1, &never, |_| {});
    let mut many = Renderer::new(&f, &opts(9, 3)).unwrap();
    let mut fractions = Vec::new();
    many.run_all(37, &never, |p| fractions.push(p));
    assert!(fractions.len() > 10);
    assert!(fractions.windows(2).all(|w| w[1] >= w[0]));
    assert_eq!(*fractions.last().unwrap(), 1.0);
    assert_eq!(one.finish().as_bytes(), many.finish().as_bytes());
}

#[test]
fn previews_are_correctly_exposed_mid_render() {
    let f = example("orchid.flame");
    let never = AtomicBool::new(false);
    let mut r = Renderer::new(&f, &opts(1, 2)).unwrap();
    r.run(r.total_samples() / 10, &never);
    assert!(
        r.fraction() > 0.05 && r.fraction() < 0.2,
        "{}",
        r.fraction()
    );
    let early = mean(&r.preview());
    r.run_all(4, &never, |_| {});
    let fin = mean(&r.finish());
    // Exposure follows the samples done: a 10 % preview is as bright as the final image
    // (within noise), not ten times darker.
    assert!(
        early > 0.75 * fin && early < 1.25 * fin,
        "preview {early} vs final {fin}"
    );
}

#[test]
fn cancel_stops_the_render() {
    let mut f = example("lagoon-post.flame");
    f.quality = 1e6;
    let cancel = AtomicBool::new(true);
    let mut r = Renderer::new(&f, &opts(1, 2)).unwrap();
    assert!(!r.run(r.total_samples(), &cancel));
    assert!(r.is_cancelled() && r.is_done());
    assert_eq!(r.samples_done(), 0);
    // A cancelled render still yields a (dark) preview without panicking.
    let _ = r.preview();
}

#[test]
fn oversized_renders_are_refused_before_allocating() {
    let mut f = example("sierpinski.flame");
    f.resize_keep_framing(20_000, 15_000);
    let o = RenderOptions {
        memory_limit: Some(1 << 30),
        threads: 2,
        ..RenderOptions::default()
    };
    let est = estimate_memory(&f, &o);
    assert!(est.total > 1 << 30);
    assert_eq!(est.threads, 2);
    match Renderer::new(&f, &o) {
        Err(e @ RenderError::OutOfMemory { .. }) => {
            let m = e.to_string();
            assert!(
                m.contains("20000×15000") && m.contains("GiB") && m.contains("configured"),
                "{m}"
            );
        }
        Err(e) => panic!("wrong error {e}"),
        Ok(_) => panic!("a 20000×15000 render was not refused"),
    }
    // 4000×3000 at supersample 1 with 2 threads fits in 1 GiB.
    f.resize_keep_framing(4000, 3000);
    f.supersample = 1;
    assert!(estimate_memory(&f, &o).total < 1 << 30);
}

#[test]
fn flames_without_camera_are_framed_automatically() {
    // A Sierpinski triangle far from the origin and without a camera.
    let mut f = Flame {
        width: 64,
        height: 64,
        quality: 30.0,
        has_camera: false,
        center: [0.0, 0.0],
        scale: 1.0,
        ..Flame::default()
    };
    for (e, ff) in [(100.0, 100.0), (101.0, 100.0), (100.0, 101.0)] {
        f.xforms.push(Xform::linear(
            Affine::new(0.5, 0.0, 0.0, 0.5, e, ff),
            1.0,
            0.0,
        ));
    }
    f.palette = ugnis::gradient::Gradient::from_rgb("white", &vec![[1.0, 1.0, 1.0]; 256]);
    let r = Renderer::new(&f, &opts(1, 1)).unwrap();
    let fr = r.flame();
    assert!(fr.has_camera);
    assert!(
        (fr.center[0] - 200.0).abs() < 2.0 && (fr.center[1] - 200.0).abs() < 2.0,
        "{:?}",
        fr.center
    );
    let img = render(&f, &opts(1, 1)).unwrap().to_rgb8();
    // The triangle fills a good part of the image, centred.
    let lit = img.pixels().filter(|p| p.0[0] > 20).count();
    assert!(lit > 64 * 64 / 8, "{lit} lit pixels");
    assert!(img.get_pixel(0, 0).0[0] < 20);
}

#[test]
fn unrenderable_flames_are_errors_not_panics() {
    let mut f = example("sierpinski.flame");
    for x in &mut f.xforms {
        x.weight = 0.0;
    }
    let e = Renderer::new(&f, &opts(1, 1)).err().expect("must fail");
    assert!(e.to_string().contains("cannot iterate empty flame"), "{e}");
    let mut f = example("sierpinski.flame");
    f.gamma = 0.0;
    assert!(Renderer::new(&f, &opts(1, 1)).is_err());
    let mut f = example("sierpinski.flame");
    f.width = 0;
    assert!(Renderer::new(&f, &opts(1, 1)).is_err());
}

#[test]
fn transparent_and_16_bit_outputs() {
    let f = example("sierpinski.flame");
    let o = RenderOptions {
        format: OutputFormat {
            bits16: true,
            transparent: true,
        },
        ..opts(1, 2)
    };
    let img = render(&f, &o).unwrap();
    let rgba = img.as_rgba16().expect("16-bit RGBA");
    // Empty corners are fully transparent, the middle is not.
    assert_eq!(rgba.get_pixel(0, 0).0[3], 0);
    assert!(rgba.pixels().any(|p| p.0[3] > 60000));
    let o8 = render(&f, &opts(1, 2)).unwrap();
    assert!(o8.as_rgb8().is_some());
}

#[test]
fn recolor_reuses_the_samples() {
    let f = example("orchid.flame");
    let keep = RenderOptions {
        keep_samples: true,
        ..opts(5, 2)
    };
    let never = AtomicBool::new(false);
    let mut r = Renderer::new(&f, &keep).unwrap();
    r.run_all(1, &never, |_| {});
    assert!(r.can_recolor());
    let g = ugnis::gradient::builtin_named("lagoon").unwrap();
    assert!(r.recolor(&g, f.palette_mode));
    let recoloured = r.finish();
    // Rendering from scratch with the new gradient gives the very same image.
    let mut f2 = f.clone();
    f2.palette = g;
    let direct = render(&f2, &opts(5, 2)).unwrap();
    assert_eq!(recoloured.as_bytes(), direct.as_bytes());
    let mut plain = Renderer::new(&f, &opts(5, 2)).unwrap();
    assert!(!plain.can_recolor());
    assert!(!plain.recolor(&ugnis::gradient::Gradient::grey_ramp(), f.palette_mode));
}

/// Without density estimation the quick preview (thread histograms summed and log-scaled row by
/// row inside the filter) is the developed picture, byte for byte.
#[test]
fn the_draft_is_the_picture_when_density_estimation_is_off() {
    let mut f = example("orchid.flame");
    f.quality = 20.0;
    f.supersample = 2;
    f.estimator_radius = 0.0;
    let mut r = Renderer::new(&f, &opts(1, 2)).unwrap();
    r.run(40_000, &AtomicBool::new(false));
    let (draft, full) = (r.preview_draft().to_rgb8(), r.preview().to_rgb8());
    assert!(draft.pixels().any(|p| p.0 != [0, 0, 0]));
    assert_eq!(draft.as_raw(), full.as_raw());
}

/// A preview asked to stop gives nothing (an editor drops a stale frame at once); not asked,
/// it is the preview.
#[test]
fn a_stopped_preview_gives_nothing() {
    let mut f = example("orchid.flame");
    f.quality = 5.0;
    let mut r = Renderer::new(&f, &opts(1, 2)).unwrap();
    r.run(20_000, &AtomicBool::new(false));
    assert!(r.preview_until(&AtomicBool::new(true)).is_none());
    let full = r.preview_until(&AtomicBool::new(false)).unwrap();
    assert_eq!(full.as_bytes(), r.preview().as_bytes());
}

/// An orbit variation (gingerbread_man keeps its own point from call to call): each worker
/// thread keeps its own orbit, as each of JWildfire's render threads has its own copy of the
/// flame. Threads sharing one state tore its steps apart: with 2 threads the picture was
/// another attractor (12 dB against JWildfire's own picture of sidwellr's example, 48 dB
/// now), and it changed from run to run.
#[test]
fn orbit_variations_keep_one_orbit_per_thread() {
    let dir = std::env::temp_dir().join(format!("ugnis-orbit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("gingerbread.flame");
    std::fs::write(
        &path,
        r#"<flame name="g" version="JWildfire V6.00" size="64 48" center="1 1.5" scale="5" quality="30" brightness="4" gamma="4" background="0 0 0">
<xform weight="1" color="0" gingerbread_man="1" coefs="1 0 0 1 0 0"/>
<palette count="2" format="RGB">FFFFFF FF8000</palette></flame>"#,
    )
    .unwrap();
    let f = ugnis::io::read_flames(&path, &ReadOptions::default())
        .unwrap()
        .value
        .remove(0);
    let one = render(&f, &opts(2, 1)).unwrap().to_rgb8();
    let two = render(&f, &opts(2, 2)).unwrap().to_rgb8();
    let again = render(&f, &opts(2, 2)).unwrap().to_rgb8();
    assert_eq!(two.as_raw(), again.as_raw(), "the same image on every run");
    // The gingerbread man's orbit from (−0.1, 0) visits a few hundred points in a hexagon
    // around (1, 1): the two renders light the same pixels.
    let lit = |img: &image::RgbImage| -> Vec<bool> {
        img.pixels().map(|p| p.0.iter().any(|&c| c > 0)).collect()
    };
    let (a, b) = (lit(&one), lit(&two));
    let n1 = a.iter().filter(|&&x| x).count();
    let both = a.iter().zip(&b).filter(|(x, y)| **x && **y).count();
    let either = a.iter().zip(&b).filter(|(x, y)| **x || **y).count();
    assert!(n1 > 50, "{n1} pixels lit");
    assert!(
        both as f64 >= 0.9 * either as f64,
        "1 and 2 threads light {either} pixels, {both} in both"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
