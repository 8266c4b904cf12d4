//! The command line, run as a user would: exit codes, messages, output files.

mod common;

use std::process::Command;

fn ugnis(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ugnis"))
        .args(args)
        .output()
        .expect("run ugnis");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn render_writes_png_with_embedded_flame_and_bmp() {
    let dir = common::temp_dir("cli-render");
    let png = dir.join("s.png");
    let ex = common::example("sierpinski.flame");
    let (code, _, err) = ugnis(&[
        "render",
        ex.to_str().unwrap(),
        "-o",
        png.to_str().unwrap(),
        "--size",
        "64x48",
        "--quality",
        "5",
        "--seed",
        "2",
    ]);
    assert_eq!(code, 0, "{err}");
    let img = image::open(&png).unwrap();
    assert_eq!((img.width(), img.height()), (64, 48));
    // The PNG carries its flame: rendering the PNG reproduces the image exactly.
    let png2 = dir.join("again.png");
    let (code, _, err) = ugnis(&[
        "render",
        png.to_str().unwrap(),
        "-o",
        png2.to_str().unwrap(),
        "--seed",
        "2",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        image::open(&png2).unwrap().to_rgb8(),
        img.to_rgb8(),
        "re-rendering the embedded flame must give the same picture"
    );
    let bmp = dir.join("s.bmp");
    let (code, _, err) = ugnis(&[
        "render",
        ex.to_str().unwrap(),
        "-o",
        bmp.to_str().unwrap(),
        "--size",
        "33x21",
        "--quality",
        "2",
    ]);
    assert_eq!(code, 0, "{err}");
    let b = std::fs::read(&bmp).unwrap();
    assert_eq!(&b[..2], b"BM");
    assert_eq!(b.len(), 54 + ((3 * 33 + 3) & !3) * 21);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_exits_1_with_one_clear_message() {
    let dir = common::temp_dir("cli-bad");
    let bad = dir.join("bad.flame");
    std::fs::write(
        &bad,
        "<flames>\n<flame size=\"10 ten\">\n<xform weight=\"1\"/></flame></flames>\n",
    )
    .unwrap();
    let (code, _, err) = ugnis(&["render", bad.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.contains("bad.flame:2:14: error[XML003]"), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(!err.contains("panicked"));

    let (code, _, err) = ugnis(&["render", dir.join("missing.flame").to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        err.contains("missing.flame") && err.contains("cannot open"),
        "{err}"
    );

    let ex = common::example("sierpinski.flame");
    let (code, _, err) = ugnis(&["render", ex.to_str().unwrap(), "--index", "5"]);
    assert_eq!(code, 1);
    assert!(err.contains("index 5 is out of range"), "{err}");

    let (code, _, err) = ugnis(&["render", ex.to_str().unwrap(), "--size", "0x10"]);
    assert_eq!(code, 1);
    assert!(err.contains("size"), "{err}");

    let (code, _, err) = ugnis(&[
        "render",
        ex.to_str().unwrap(),
        "-o",
        dir.join("x.gif").to_str().unwrap(),
    ]);
    assert_eq!(code, 1);
    assert!(err.contains(".png or .bmp"), "{err}");

    let (code, _, _) = ugnis(&["--help"]);
    assert_eq!(code, 0);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn unsupported_variations_warn_and_strict_refuses() {
    let dir = common::temp_dir("cli-strict");
    let f = dir.join("plugin.flame");
    std::fs::write(
        &f,
        "<flame name=\"p\" size=\"40 30\" scale=\"10\"><xform weight=\"1\" linear=\"1\" frobnicate_wf=\"0.5\" frobnicate_wf_fx_priority=\"0\" coefs=\"0.5 0 0 0.5 0 0\"/>\
         <xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 1 0\"/></flame>",
    )
    .unwrap();
    let out = dir.join("p.png");
    let (code, _, err) = ugnis(&[
        "render",
        f.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--quality",
        "2",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("variation 'frobnicate_wf' (weight 0.5) not supported; ignored"),
        "{err}"
    );
    let (code, _, err) = ugnis(&[
        "render",
        f.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--strict",
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("--strict"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn failed_output_leaves_existing_file_intact() {
    let dir = common::temp_dir("cli-atomic");
    let out = dir.join("keep.png");
    std::fs::write(&out, b"old content").unwrap();
    // Rendering fails (empty flame) before anything is written.
    let bad = dir.join("empty.flame");
    std::fs::write(&bad, "<flame><xform weight=\"0\"/></flame>").unwrap();
    let (code, _, _) = ugnis(&["render", bad.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert_eq!(std::fs::read(&out).unwrap(), b"old content");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn info_lists_every_variation_on_one_line() {
    let (code, out, err) = ugnis(&["info", "--variations"]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    let n = ugnis::flame::variations::all()
        .iter()
        .filter(|d| !d.has(ugnis::flame::variations::flag::HIDDEN))
        .count();
    // One line per variation and the summary: a text default of several lines (svg_wf's
    // drawing, lsystem_js' grammar) is shown by its size.
    assert_eq!(lines.len(), n + 1, "{}", lines.len());
    assert!(
        lines[n].starts_with(&format!("{n} variations")),
        "{}",
        lines[n]
    );
    let svg = lines
        .iter()
        .find(|l| l.starts_with("svg_wf "))
        .expect("svg_wf listed");
    assert!(svg.contains("svg_wf_svg=<text of "), "{svg}");
    let text = lines
        .iter()
        .find(|l| l.starts_with("text_wf "))
        .expect("text_wf listed");
    assert!(text.contains("text_wf_text=\"JWildfire\""), "{text}");
}

#[test]
fn info_lists_file_contents_and_fails_cleanly() {
    let (code, out, err) = ugnis(&["info", common::fixture("library.ifs").to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("8 entries") && out.contains("3dfern") && out.contains("3-D"),
        "{out}"
    );
    let (code, out, _) = ugnis(&["info", common::example("features.flame").to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(
        out.contains("features") && out.contains("+ final") && out.contains("swirl"),
        "{out}"
    );
    let (code, out, _) = ugnis(&["info", common::fixture("hand.ugr").to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(
        out.contains("2 gradient(s)") && out.contains("fire-and-ice"),
        "{out}"
    );
    let dir = common::temp_dir("cli-info");
    let bad = dir.join("bad.ifs");
    std::fs::write(&bad, "fern {\n1 2 3\n}\n").unwrap();
    let (code, _, err) = ugnis(&["info", bad.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.contains("bad.ifs:3:1: error[IFS007]"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn convert_between_formats() {
    let dir = common::temp_dir("cli-convert");
    let d = |n: &str| dir.join(n).to_str().unwrap().to_string();
    // .ifs → .fla (3-D entries skipped with a warning) → .ifs again.
    let (code, _, err) = ugnis(&[
        "convert",
        common::fixture("library.ifs").to_str().unwrap(),
        &d("lib.fla"),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("skipping '3dfern'"), "{err}");
    let (code, _, err) = ugnis(&["convert", &d("lib.fla"), &d("lib.ifs")]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("lost"), "{err}");
    let back = ugnis::io::read_ifs(std::path::Path::new(&d("lib.ifs")))
        .unwrap()
        .value;
    assert_eq!(back.entries.len(), 7);
    assert!((back.get("fern").unwrap().rows[1][5] - 1.6).abs() < 1e-12);
    // A non-linear flame cannot become .ifs.
    let (code, _, err) = ugnis(&[
        "convert",
        common::example("features.flame").to_str().unwrap(),
        &d("f.ifs"),
    ]);
    assert_eq!(code, 1);
    assert!(
        err.contains("only linear flames can be saved as .ifs"),
        "{err}"
    );
    // PNG with embedded flame → .fla.
    let png = d("s.png");
    let (code, _, _) = ugnis(&[
        "render",
        common::example("sierpinski.flame").to_str().unwrap(),
        "-o",
        &png,
        "--size",
        "32x24",
        "--quality",
        "1",
    ]);
    assert_eq!(code, 0);
    let (code, _, err) = ugnis(&["convert", &png, &d("from-png.fla")]);
    assert_eq!(code, 0, "{err}");
    let f = ugnis::io::read_flames(
        std::path::Path::new(&d("from-png.fla")),
        &Default::default(),
    )
    .unwrap()
    .value;
    assert_eq!(f[0].name, "sierpinski");
    // .ugr ↔ .map
    let (code, _, err) = ugnis(&[
        "convert",
        common::fixture("hand.ugr").to_str().unwrap(),
        &d("h.map"),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("writing the first"), "{err}");
    let (code, _, err) = ugnis(&["convert", &d("h.map"), &d("h.ugr")]);
    assert_eq!(code, 0, "{err}");
    let g = ugnis::io::read_gradients(std::path::Path::new(&d("h.ugr")))
        .unwrap()
        .value;
    assert_eq!(g[0].rgb8(64), [255, 0, 0]);
    // .map ↔ .ggr (GIMP) keeps every entry.
    let (code, _, err) = ugnis(&["convert", &d("h.map"), &d("h.ggr")]);
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = ugnis(&["convert", &d("h.ggr"), &d("back.map")]);
    assert_eq!(code, 0, "{err}");
    let back = ugnis::io::read_gradients(std::path::Path::new(&d("back.map")))
        .unwrap()
        .value;
    for i in 0..256 {
        assert_eq!(back[0].rgb8(i), g[0].rgb8(i), "entry {i}");
    }
    let (code, out, _) = ugnis(&["info", common::fixture("hand.ggr").to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(out.contains("Dusk (hand-written)"), "{out}");
    // image → gradient
    let (code, _, err) = ugnis(&["convert", &png, &d("from-image.map")]);
    assert_eq!(code, 0, "{err}");
    // Unsupported pair.
    let (code, _, err) = ugnis(&["convert", &d("h.map"), &d("x.fla")]);
    assert_eq!(code, 1);
    assert!(err.contains("cannot convert"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn random_writes_a_reproducible_batch_with_thumbnails() {
    let dir = common::temp_dir("cli-random");
    let _cleanup = common::Cleanup(dir.clone());
    let out = dir.join("batch.fla");
    let thumbs = dir.join("thumbs");
    let args = |o: &std::path::Path| -> Vec<String> {
        [
            "random",
            "--count",
            "6",
            "--seed",
            "11",
            "--min-xforms",
            "3",
            "--max-xforms",
            "3",
            "--variation",
            "sinusoidal",
            "--symmetry",
            "-2",
            "--thumbs",
            thumbs.to_str().unwrap(),
            "--size",
            "40x30",
            "--quality",
            "5",
            "-o",
            o.to_str().unwrap(),
        ]
        .iter()
        .map(|s| s.to_string())
        .collect()
    };
    let a: Vec<String> = args(&out);
    let (code, stdout, err) = ugnis(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, 0, "{err}");
    assert!(stdout.contains("wrote 6 flames"), "{stdout}");
    let flames = ugnis::io::read_flames(&out, &Default::default())
        .unwrap()
        .value;
    assert_eq!(flames.len(), 6);
    let sin = ugnis::flame::variations::by_name("sinusoidal").unwrap();
    for (i, f) in flames.iter().enumerate() {
        assert_eq!(f.name, format!("random-{:03}", i + 1));
        assert!(f.seed.is_some());
        // 3 transforms plus the mirror and one rotation of symmetry −2.
        assert_eq!(f.xforms.len(), 5);
        assert!(f.xforms[..3].iter().all(|x| x.vars[0].id == sin));
        let png = thumbs.join(format!("{}.png", f.name));
        let img = image::open(&png).unwrap();
        assert_eq!((img.width(), img.height()), (40, 30));
        // The thumbnail carries its flame.
        let back = ugnis::io::read_flames(&png, &Default::default())
            .unwrap()
            .value;
        assert_eq!(back[0].xforms, f.xforms);
    }
    // The same seed gives the same file.
    let out2 = dir.join("again.fla");
    let b = args(&out2);
    let (code, _, err) = ugnis(&b.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        std::fs::read_to_string(&out).unwrap().replace("batch", "X"),
        std::fs::read_to_string(&out2)
            .unwrap()
            .replace("again", "X")
    );
    // --count 1 prints nothing and writes one flame.
    let one = dir.join("one.fla");
    let (code, stdout, err) = ugnis(&["random", "--count", "1", "-o", one.to_str().unwrap()]);
    assert_eq!((code, stdout.as_str(), err.as_str()), (0, "", ""));
    assert_eq!(
        ugnis::io::read_flames(&one, &Default::default())
            .unwrap()
            .value
            .len(),
        1
    );
    // Bad arguments: one clear message, exit 1.
    for (bad, want) in [
        (
            vec!["random", "--variation", "nonesuch"],
            "unknown variation",
        ),
        (
            vec!["random", "--min-xforms", "5", "--max-xforms", "3"],
            "min",
        ),
        (vec!["random", "--symmetry", "x"], "--symmetry"),
        (vec!["random", "-o", "out.png"], ".fla"),
    ] {
        let (code, _, err) = ugnis(&bad);
        assert_eq!(code, 1, "{bad:?}");
        assert!(err.contains(want), "{bad:?}: {err}");
    }
}

#[test]
fn animate_writes_rotation_and_interpolation_frames() {
    let dir = common::temp_dir("cli-animate");
    let _cleanup = common::Cleanup(dir.clone());
    let ex = common::example("sierpinski.flame");
    let rot = dir.join("rot");
    let (code, _, err) = ugnis(&[
        "animate",
        ex.to_str().unwrap(),
        "--frames",
        "3",
        "-o",
        rot.to_str().unwrap(),
        "--size",
        "48x36",
        "--quality",
        "3",
    ]);
    assert_eq!(code, 0, "{err}");
    let f1 = ugnis::io::read_flames(&rot.join("frame-0001.png"), &Default::default())
        .unwrap()
        .value
        .remove(0);
    let f3 = ugnis::io::read_flames(&rot.join("frame-0003.png"), &Default::default())
        .unwrap()
        .value
        .remove(0);
    // Two steps of 2° turn every triangle by 4° about its centroid.
    for (a, b) in f1.xforms.iter().zip(&f3.xforms) {
        let turn = (b.coefs.c.atan2(b.coefs.a) - a.coefs.c.atan2(a.coefs.a)).to_degrees();
        let turn = (turn + 540.0).rem_euclid(360.0) - 180.0;
        assert!((turn.abs() - 4.0).abs() < 1e-3, "{turn}");
    }
    // Interpolation through a three-flame file: the first and last frames are the keys.
    let lib = common::fixture("library.fla");
    let keys = ugnis::io::read_flames(&lib, &Default::default())
        .unwrap()
        .value;
    let int = dir.join("int");
    let (code, _, err) = ugnis(&[
        "animate",
        lib.to_str().unwrap(),
        "--mode",
        "interpolate",
        "--from",
        "0",
        "--to",
        "1",
        "--frames",
        "5",
        "-o",
        int.to_str().unwrap(),
        "--size",
        "32x24",
        "--quality",
        "2",
    ]);
    assert_eq!(code, 0, "{err}");
    let last = ugnis::io::read_flames(&int.join("frame-0005.png"), &Default::default())
        .unwrap()
        .value
        .remove(0);
    for (x, y) in last.xforms.iter().zip(&keys[1].xforms) {
        assert!(
            x.coefs
                .to_coefs()
                .iter()
                .zip(y.coefs.to_coefs())
                .all(|(p, q)| (p - q).abs() < 1e-5)
        );
    }
    assert_eq!(std::fs::read_dir(&int).unwrap().count(), 5);
}

#[test]
fn escape_renders_kinds_views_and_rejects_bad_input() {
    let dir = common::temp_dir("cli-escape");
    let _cleanup = common::Cleanup(dir.clone());
    let png = dir.join("m.png");
    let view = dir.join("m.esc");
    let (code, _, err) = ugnis(&[
        "escape",
        "mandelbrot",
        "--center=-0.7,0",
        "--width",
        "3",
        "--size",
        "120x90",
        "--max-iter",
        "200",
        "--coloring",
        "bands",
        "-o",
        png.to_str().unwrap(),
        "--save-view",
        view.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let img = image::open(&png).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (120, 90));
    // The centre of the main cardioid (−0.25, 0) is inside: black; the far corner is outside.
    let [i, j] = [((-0.25 + 2.2) / 3.0 * 120.0) as u32, 45];
    assert_eq!(img.get_pixel(i, j).0, [0, 0, 0]);
    assert_ne!(img.get_pixel(0, 0).0, [0, 0, 0]);
    // The saved view renders the same picture again.
    let again = dir.join("again.png");
    let (code, _, err) = ugnis(&[
        "escape",
        "--view",
        view.to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(image::open(&again).unwrap().to_rgb8(), img);
    // Deep zoom: a 1e-18 view of the Mandelbrot set renders, and its view file keeps the
    // centre's 32 digits.
    let deep_png = dir.join("deep.png");
    let deep_esc = dir.join("deep.esc");
    let (code, _, err) = ugnis(&[
        "escape",
        "mandelbrot",
        "--center=-0.743643887037158704752191506114774,0.131825904205311970493132056385139",
        "--width",
        "1e-18",
        "--max-iter",
        "12000",
        "--size",
        "48x36",
        "-o",
        deep_png.to_str().unwrap(),
        "--save-view",
        deep_esc.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let deep = image::open(&deep_png).unwrap().to_rgb8();
    let mut colours: Vec<[u8; 3]> = deep.pixels().map(|p| p.0).collect();
    colours.sort();
    colours.dedup();
    assert!(
        colours.len() > 50,
        "a deep view has structure, not one colour"
    );
    let text = std::fs::read_to_string(&deep_esc).unwrap();
    // The centre keeps the digits a 1e-18 view of 36 pixels needs (rounded past them).
    assert!(
        text.contains("center = -0.74364388703715870475219150611"),
        "{text}"
    );
    // Every kind renders.
    for (kind, extra) in [
        ("julia", vec!["--c=-0.8,0.156"]),
        ("multibrot", vec!["--power", "4"]),
        ("newton", vec!["--poly", "1 0 0 0 -1"]),
        ("logistic", vec![]),
        ("cubic", vec![]),
        (
            "warped-julia",
            vec!["--alpha=-0.3,0", "--turbulence", "0.2", "--polar"],
        ),
    ] {
        let out = dir.join(format!("{kind}.bmp"));
        let mut args = vec![
            "escape",
            kind,
            "--size",
            "64x48",
            "--max-iter",
            "100",
            "-o",
            out.to_str().unwrap(),
        ];
        args.extend(extra);
        let (code, _, err) = ugnis(&args);
        assert_eq!(code, 0, "{kind}: {err}");
        assert_eq!(image::open(&out).unwrap().width(), 64);
    }
    // Bad input: one message, exit 1.
    for (args, want) in [
        (vec!["escape", "snowflake", "-o", "x.png"], "unknown kind"),
        (vec!["escape", "julia", "--c", "abc", "-o", "x.png"], "--c"),
        (
            vec!["escape", "mandelbrot", "--power", "12", "-o", "x.png"],
            "power",
        ),
        (vec!["escape", "mandelbrot", "-o", "x.txt"], ".png"),
        (
            vec![
                "escape",
                "mandelbrot",
                "--bla-tolerance",
                "0.5",
                "-o",
                "x.png",
            ],
            "--bla-tolerance 0.5: expected a number from 1.1e-16",
        ),
        (
            vec![
                "escape",
                "multibrot",
                "--power",
                "4",
                "--width",
                "1e-14",
                "--center",
                "0.3,0",
                "-o",
                "x.png",
            ],
            "limit of 64-bit",
        ),
        (
            vec![
                "escape",
                "mandelbrot",
                "--width",
                "1e-10001",
                "--center",
                "0.3,0",
                "-o",
                "x.png",
            ],
            "deep-zoom limit",
        ),
        (
            vec!["escape", "warped-julia", "--alpha", "1,0", "-o", "x.png"],
            "α",
        ),
        (
            vec!["escape", "--view", "/no/such.esc", "-o", "x.png"],
            "no/such.esc",
        ),
    ] {
        let (code, _, err) = ugnis(&args);
        assert_eq!(code, 1, "{args:?}");
        assert!(err.contains(want), "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
    }
}

#[test]
fn scene_renders_files_and_reports_bad_ones() {
    let dir = common::temp_dir("cli-scene");
    let _cleanup = common::Cleanup(dir.clone());
    let out = dir.join("jug.png");
    let ex = common::example("teapot.toml");
    let (code, _, err) = ugnis(&[
        "scene",
        ex.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--size",
        "200x150",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(image::open(&out).unwrap().width(), 200);
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "[camera]\ndistance = 7\n\n[[object]]\nkind = \"jug\"\ntexture = \"missing\"\n",
    )
    .unwrap();
    let (code, _, err) = ugnis(&["scene", bad.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        err.contains("bad.toml:4:1") && err.contains("no texture named 'missing'"),
        "{err}"
    );
    let (code, _, err) = ugnis(&["scene", "/no/such.toml", "-o", out.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.contains("/no/such.toml"), "{err}");
}

#[test]
fn random_draws_only_from_the_variations_list() {
    let dir = common::temp_dir("cli-random-list");
    let out = dir.join("list.fla");
    let (code, _, err) = ugnis(&[
        "random",
        "--count",
        "4",
        "--seed",
        "5",
        "--variations",
        "julia,pre_blur,swirl",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    use ugnis::flame::variations::{self, Form};
    let allowed = [
        variations::parse_name("julia").unwrap(),
        variations::parse_name("pre_blur").unwrap(),
        variations::parse_name("swirl").unwrap(),
        (variations::LINEAR, Form::Regular),
    ];
    for f in ugnis::io::read_flames(&out, &Default::default())
        .unwrap()
        .value
    {
        for x in &f.xforms {
            for v in &x.vars {
                assert!(allowed.contains(&(v.id, v.form)), "{:?}", (v.id, v.form));
            }
        }
    }
    // Unknown names are named in the message.
    let (code, _, err) = ugnis(&[
        "random",
        "--variations",
        "julia,no_such_thing",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("no_such_thing"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn scene_ray_casts_new_kinds_and_refuses_what_does_not_fit() {
    let dir = common::temp_dir("cli-scene-raycast");
    let _cleanup = common::Cleanup(dir.clone());
    let out = dir.join("menger.png");
    let ex = common::example("menger.toml");
    let (code, stdout, err) = ugnis(&[
        "scene",
        ex.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--size",
        "160x120",
        "--shadows",
        "off",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        stdout.contains("8000 cubes") && stdout.contains("2.72683"),
        "{stdout}"
    );
    assert_eq!(image::open(&out).unwrap().width(), 160);
    // The quaternion Julia example through the z-buffer (marched per pixel there).
    let q = common::example("quaternion-julia.toml");
    let out_q = dir.join("julia.bmp");
    let (code, _, err) = ugnis(&[
        "scene",
        q.to_str().unwrap(),
        "-o",
        out_q.to_str().unwrap(),
        "--size",
        "96x72",
        "--render",
        "zbuffer",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(image::open(&out_q).unwrap().height(), 72);
    for (args, want) in [
        (
            vec!["--render", "zbuffer", "--shadows", "on"],
            "--shadows needs the ray caster",
        ),
        (vec!["--render", "phong"], "phong"),
        // Too large a picture is refused before the scene is even read.
        (
            vec!["--size", "100000x100000", "--supersample", "4"],
            "at most 16384x16384",
        ),
    ] {
        let mut a = vec!["scene", ex.to_str().unwrap(), "-o", out.to_str().unwrap()];
        a.extend(args.iter().copied());
        let (code, _, err) = ugnis(&a);
        assert_eq!(code, 1, "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
}
