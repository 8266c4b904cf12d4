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
        "<flame name=\"p\" size=\"40 30\" scale=\"10\"><xform weight=\"1\" linear=\"1\" hemisphere=\"0.5\" coefs=\"0.5 0 0 0.5 0 0\"/>\
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
        err.contains("variation 'hemisphere' (weight 0.5) not supported; ignored"),
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
