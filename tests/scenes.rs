//! Textured Bézier scenes (issue #7): the jug against its committed reference image, the
//! convex-hull silhouette check, every example renders, and projections differ as they should.

mod common;

use glam::DVec3;
use ugnis::surface::{Geometry, Projection, render};

fn jug_image(w: u32, h: u32) -> image::RgbImage {
    let mut s = ugnis::io::scene::read(&common::example("jug.toml"))
        .unwrap()
        .scene;
    s.width = w;
    s.height = h;
    render(&s, None).unwrap()
}

#[test]
fn jug_matches_its_reference_image() {
    let img = jug_image(320, 240);
    let fixture = common::fixture("jug.ugnis.png");
    if std::env::var_os("UGNIS_BLESS").is_some() {
        img.save(&fixture).unwrap();
    }
    let reference = common::load_rgb(&fixture);
    let psnr = common::psnr_blurred(&img, &reference);
    // Same code, same textures (fixed-thread flame render): only floating-point differences
    // between CPUs may remain.
    assert!(
        psnr >= 40.0,
        "jug differs from tests/fixtures/jug.ugnis.png: {psnr:.1} dB"
    );
    // The jug covers a sensible part of the frame and the background stays black.
    let covered = img.pixels().filter(|p| p.0 != [0, 0, 0]).count() as f64 / (320.0 * 240.0);
    assert!((0.2..0.6).contains(&covered), "{covered}");
    assert_eq!(img.get_pixel(2, 2).0, [0, 0, 0]);
}

#[test]
fn silhouette_lies_inside_the_projected_control_nets() {
    let s = ugnis::io::scene::read(&common::example("jug.toml"))
        .unwrap()
        .scene;
    let img = render(&s, None).unwrap();
    let Geometry::Patches(p) = &s.objects[0].geometry else {
        unreachable!()
    };
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for sp in p {
        for c in sp.patch.control_points() {
            let q = ugnis::surface::raster::project(&s, s.objects[0].transform.apply(c)).unwrap();
            x0 = x0.min(q[0]);
            x1 = x1.max(q[0]);
            y0 = y0.min(q[1]);
            y1 = y1.max(q[1]);
        }
    }
    for (x, y, px) in img.enumerate_pixels() {
        if px.0 != [0, 0, 0] {
            let (fx, fy) = (x as f64 + 0.5, y as f64 + 0.5);
            assert!(
                fx >= x0 - 1.0 && fx <= x1 + 1.0 && fy >= y0 - 1.0 && fy <= y1 + 1.0,
                "pixel ({x}, {y}) outside the nets' box"
            );
        }
    }
}

#[test]
fn examples_render_and_projections_differ() {
    for name in [
        "jug.toml",
        "julia-vase.toml",
        "teapot.toml",
        "mountain.toml",
    ] {
        let mut s = ugnis::io::scene::read(&common::example(name))
            .unwrap_or_else(|e| panic!("{name}: {e}"))
            .scene;
        s.width = 160;
        s.height = 120;
        let img = render(&s, None).unwrap();
        let bg = s.background;
        let bgc = [bg.x, bg.y, bg.z].map(|v| (v * 255.0).round() as u8);
        let drawn = img.pixels().filter(|p| p.0 != bgc).count();
        assert!(drawn > 1500, "{name}: only {drawn} pixels drawn");
    }
    // Perspective, orthographic and isometric views of the same jug are different pictures;
    // the stereo pair has the jug once in each half.
    let base = ugnis::io::scene::read(&common::example("jug.toml"))
        .unwrap()
        .scene;
    let mut imgs = Vec::new();
    for p in [
        Projection::Perspective,
        Projection::Orthographic,
        Projection::Axonometric {
            phi: std::f64::consts::FRAC_PI_4,
            theta: (1.0f64 / 3.0).sqrt().asin(),
        },
    ] {
        let mut s = base.clone();
        s.width = 160;
        s.height = 120;
        s.camera.projection = p;
        imgs.push(render(&s, None).unwrap());
    }
    assert_ne!(imgs[0], imgs[1]);
    assert_ne!(imgs[1], imgs[2]);
    let mut s = base.clone();
    s.width = 320;
    s.height = 120;
    s.camera.projection = Projection::Stereo;
    let st = render(&s, None).unwrap();
    let count = |x0: u32| {
        (0..120)
            .flat_map(|y| (x0..x0 + 160).map(move |x| (x, y)))
            .filter(|&(x, y)| st.get_pixel(x, y).0 != [0, 0, 0])
            .count()
    };
    assert!(count(0) > 1000 && count(160) > 1000);
    // A light moved behind the jug darkens the visible side.
    let mut dark = base.clone();
    dark.width = 160;
    dark.height = 120;
    let lit = render(&dark, None).unwrap();
    dark.lights[0].position = DVec3::new(5.0, 8.0, -6.0) * 1.0;
    dark.camera.azimuth_deg = 35.0;
    let behind = render(&dark, None).unwrap();
    let sum = |i: &image::RgbImage| {
        i.pixels()
            .map(|p| p.0.iter().map(|&v| v as u64).sum::<u64>())
            .sum::<u64>()
    };
    assert!(sum(&behind) < sum(&lit));
}
