//! File formats end to end: the IFS library against flam3's renders of the .fla ugnis wrote,
//! byte-stable .fla round trips, hand-written .map/.ugr files, the shipped gradients.

mod common;

use ugnis::flame::render::{RenderOptions, render};
use ugnis::io::{self, flam3_xml};

fn render_at(flame: &ugnis::flame::Flame, w: u32, h: u32, q: f64, seed: u64) -> image::RgbImage {
    let mut f = flame.clone();
    f.resize_keep_framing(w, h);
    f.quality = q;
    let o = RenderOptions {
        seed,
        threads: 2,
        ..RenderOptions::default()
    };
    render(&f, &o).unwrap().to_rgb8()
}

/// tests/fixtures/library.fla was written by `ugnis convert library.ifs library.fla`; the
/// ifs-*.flam3.png images are flam3-render's pictures of that file (quality 1000, 160×120).
/// ugnis's own render of the same file must be the same picture (PSNR ≥ 36 dB, 3×3 blur).
#[test]
fn fla_written_by_ugnis_renders_the_same_in_flam3() {
    let flames = io::read_flames(&common::fixture("library.fla"), &Default::default())
        .unwrap()
        .value;
    assert_eq!(flames.len(), 7);
    let mut report = Vec::new();
    for f in &flames {
        let golden = common::load_rgb(&common::fixture(&format!("ifs-{}.flam3.png", f.name)));
        let img = render_at(f, 160, 120, 1000.0, 5);
        let p = common::psnr_blurred(&img, &golden);
        report.push(format!("{}: {p:.1} dB", f.name));
        assert!(p >= 36.0, "{}: {p:.2} dB\n{}", f.name, report.join("\n"));
    }
    eprintln!("{}", report.join("\n"));
}

#[test]
fn fla_round_trip_is_byte_stable() {
    let path = common::fixture("library.fla");
    let text = std::fs::read_to_string(&path).unwrap();
    let file = flam3_xml::read(
        &text,
        &flam3_xml::ReadOptions {
            fla: true,
            ..Default::default()
        },
    )
    .unwrap()
    .value;
    assert_eq!(flam3_xml::write(&file), text);
    // And through the atomic writer.
    let dir = common::temp_dir("fla-stable");
    let out = dir.join("again.fla");
    io::write_flames(&out, &file.name, &file.flames).unwrap();
    assert_eq!(std::fs::read_to_string(&out).unwrap(), text);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn ifs_library_converts_like_the_committed_fla() {
    // library.ifs → flames (framed) gives the flames of library.fla.
    let from_ifs = io::ifs_flames(&common::fixture("library.ifs"))
        .unwrap()
        .value;
    let fla = io::read_flames(&common::fixture("library.fla"), &Default::default())
        .unwrap()
        .value;
    let two_d: Vec<_> = from_ifs.into_iter().filter(|f| f.ifs3d.is_none()).collect();
    assert_eq!(two_d.len(), fla.len());
    for (mut a, b) in two_d.into_iter().zip(fla) {
        ugnis::flame::apply_auto_frame(&mut a);
        assert_eq!(a.name, b.name);
        assert_eq!(a.center, b.center);
        assert_eq!(a.scale, b.scale);
        for (x, y) in a.xforms.iter().zip(&b.xforms) {
            assert_eq!(x.coefs, y.coefs);
            assert_eq!(x.weight, y.weight);
        }
    }
}

/// The 3-D fern has no flam3 counterpart: its reference picture is ugnis's own (quality 1000,
/// seed 11), checked by eye when it was made; this guards against regressions.
#[test]
fn three_d_fern_matches_its_reference() {
    let flames = io::ifs_flames(&common::fixture("library.ifs"))
        .unwrap()
        .value;
    let fern = flames.iter().find(|f| f.name == "3dfern").unwrap();
    assert!(fern.ifs3d.is_some());
    let img = render_at(fern, 160, 120, 300.0, 2);
    let golden = common::load_rgb(&common::fixture("ifs-3dfern.ugnis.png"));
    let p = common::psnr_blurred(&img, &golden);
    assert!(p >= 36.0, "3dfern: {p:.2} dB");
    // Saving a 3-D entry as .fla is refused with the documented message.
    let dir = common::temp_dir("fern3d");
    let e = io::write_flames(&dir.join("f.fla"), "x", std::slice::from_ref(fern)).unwrap_err();
    assert!(matches!(e, io::WriteError::Ifs3dAsFlame { .. }), "{e:?}");
    assert!(
        e.to_string()
            .contains("3-D IFS entries cannot be represented as flames"),
        "{e}"
    );
    // …but it round-trips through .ifs.
    io::write_flames(&dir.join("f.ifs"), "x", std::slice::from_ref(fern)).unwrap();
    let back = io::read_ifs(&dir.join("f.ifs")).unwrap().value;
    assert!(back.entries[0].three_d);
    assert_eq!(back.entries[0].rows.len(), 4);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn hand_written_gradient_files_load() {
    let m = io::read_gradients(&common::fixture("hand.map"))
        .unwrap()
        .value;
    assert_eq!(m.len(), 1);
    assert_eq!(m[0].name, "hand");
    assert_eq!(m[0].map_entries.as_ref().unwrap().len(), 6);
    assert_eq!(m[0].rgb8(0), [0, 0, 0]);
    assert_eq!(m[0].rgb8(255), [252, 252, 252]);
    let u = io::read_gradients(&common::fixture("hand.ugr"))
        .unwrap()
        .value;
    let names: Vec<&str> = u.iter().map(|g| g.name.as_str()).collect();
    assert_eq!(names, ["fire-and-ice", "sea"]);
    assert_eq!(u[0].rgb8(0), [0, 0, 0]);
    assert_eq!(u[0].rgb8(64), [255, 0, 0]);
    assert_eq!(u[0].rgb8(255), [255, 255, 255]);
    // sea: keys at slots 0, 85 and 170, wrapping from 170 back to 0.
    assert_eq!(u[1].rgb8(85), [0, 102, 153]);
    // GIMP: four segments (linear, curved, sine with its middle at the right end, linear
    // fading to transparent).
    let g = io::read_gradients(&common::fixture("hand.ggr"))
        .unwrap()
        .value;
    assert_eq!(g.len(), 1);
    assert_eq!(g[0].name, "Dusk (hand-written)");
    assert_eq!(g[0].rgb8(0), [0, 0, 0]);
    assert_eq!(g[0].rgb8(255), [255, 255, 255]);
    assert_eq!(g[0].colors[255][3], 0.0);
    // Entry 32 (x = 32/255, linear segment with its middle at 0.125): factor 0.50196.
    assert_eq!(g[0].rgb8(32), [26, 0, 51]);
    // Entry 127: curved segment 0.25..0.5 with middle 0.4, factor pos^(ln ½ / ln 0.6).
    let pos: f64 = (127.0 / 255.0 - 0.25) / 0.25;
    let f = pos.powf(0.5f64.ln() / 0.6f64.ln());
    let want = [0.2 + 0.8 * f, 0.4 * f, 0.4 - 0.4 * f];
    for (got, want) in g[0].colors[127].iter().zip(want) {
        assert!((got - want).abs() < 1e-9);
    }
    // Entry 128 starts the sine segment: its left colour, up to (1 − cos(π·0.0039))/2.
    assert_eq!(g[0].rgb8(128), [255, 102, 0]);
}

/// gradients/ holds the built-in gradients as .ugr (all in one file) and one .map each.
/// Regenerate with `UGNIS_BLESS=1 cargo test --test formats shipped_gradients`.
#[test]
fn shipped_gradients_are_the_builtins() {
    let dir = common::root().join("gradients");
    let builtin = ugnis::gradient::builtin();
    if std::env::var_os("UGNIS_BLESS").is_some() {
        io::write_gradients(&dir.join("ugnis.ugr"), &builtin).unwrap();
        for g in &builtin {
            io::write_gradients(
                &dir.join(format!("{}.map", g.name)),
                std::slice::from_ref(g),
            )
            .unwrap();
        }
    }
    let ugr = io::read_gradients(&dir.join("ugnis.ugr")).unwrap().value;
    assert!(ugr.len() >= 30);
    assert_eq!(ugr.len(), builtin.len());
    for (a, b) in ugr.iter().zip(&builtin) {
        assert_eq!(a.name, b.name);
        assert_eq!(a.colors, b.colors, "{}", a.name);
        let m = io::read_gradients(&dir.join(format!("{}.map", b.name)))
            .unwrap()
            .value;
        assert_eq!(m[0].colors, b.colors, "{}.map", b.name);
    }
}
