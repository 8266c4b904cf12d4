//! The Explore commands run as a user would: `ugnis lsystem`, `ugnis dimension`,
//! `ugnis lorenz` — outputs, numbers, limits and messages.

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

/// The number after "D ≈ " on the line starting with `name`.
fn estimate(out: &str, name: &str) -> f64 {
    let line = out
        .lines()
        .find(|l| l.starts_with(name))
        .unwrap_or_else(|| panic!("no line for {name} in {out}"));
    let rest = line.split("D ≈ ").nth(1).expect("an estimate");
    rest.split_whitespace().next().unwrap().parse().unwrap()
}

#[test]
fn lsystem_draws_svg_and_png() {
    let dir = common::temp_dir("cli-lsystem");
    let l = common::fixture("explore.l");
    let svg = dir.join("koch.svg");
    let (code, out, err) = ugnis(&[
        "lsystem",
        l.to_str().unwrap(),
        "--name",
        "kochcurve",
        "--order",
        "3",
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("KochCurve: order 3, 64 segments"), "{out}");
    let s = std::fs::read_to_string(&svg).unwrap();
    // One connected white path of 64 segments.
    assert_eq!(s.matches("<path").count(), 1);
    assert_eq!(s.matches('L').count(), 64);
    // PNG: the default entry is the first one; the size is as asked.
    let png = dir.join("first.png");
    let (code, out, err) = ugnis(&[
        "lsystem",
        l.to_str().unwrap(),
        "--order",
        "4",
        "--size",
        "120x90",
        "-o",
        png.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("KochCurve: order 4, 256 segments"), "{out}");
    let img = image::open(&png).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (120, 90));
    let lit = img.pixels().filter(|p| p.0 != [0, 0, 0]).count();
    assert!(lit > 100, "{lit}");
    // Every entry of the fixture draws.
    for name in [
        "Snowflake",
        "TwinDragon",
        "Bush",
        "Rainbow",
        "Pinwheel",
        "Empty",
    ] {
        let (code, _, err) = ugnis(&[
            "lsystem",
            l.to_str().unwrap(),
            "--name",
            name,
            "--order",
            "3",
            "--size",
            "64x64",
            "-o",
            dir.join("e.png").to_str().unwrap(),
        ]);
        assert_eq!(code, 0, "{name}: {err}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn lsystem_refuses_bad_input_with_one_message() {
    let dir = common::temp_dir("cli-lsystem-bad");
    let l = common::fixture("explore.l");
    let out = dir.join("x.png");
    let bad = dir.join("bad.l");
    std::fs::write(
        &bad,
        "Good {\n Angle 6\n Axiom F\n}\nBad {\n Angle 4\n Axiom F\n +=F\n}\n",
    )
    .unwrap();
    // One bad entry does not block the others (Fractint reads entry by entry): the good one
    // draws, with the bad one's problem as a warning; the bad one asked for is the error.
    let (code, _, err) = ugnis(&[
        "lsystem",
        bad.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("bad.l:8:2: warning[LSY008]"), "{err}");
    std::fs::remove_file(&out).unwrap();
    let (code, _, err) = ugnis(&[
        "lsystem",
        bad.to_str().unwrap(),
        "--name",
        "bad",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 1);
    assert!(
        err.contains(
            "bad.l:8:2: error[LSY008]: '+' is a turtle command and cannot have a production; \
             entry 'Bad' is skipped"
        ),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    let cases: [(&[&str], &str); 6] = [
        (
            &["--name", "nope"],
            "no entry named 'nope'; the file has 7 entries: KochCurve",
        ),
        (&["--order", "65"], "--order 65 must be between 0 and 64"),
        (&["--order", "16"], "lower the order"),
        (&["--size", "0x10"], "must be between 1x1"),
        (&["--size", "20000x10"], "the image width is 20000"),
        (&["--background", "red"], "expected a colour RRGGBB"),
    ];
    for (extra, want) in cases {
        let mut args = vec!["lsystem", l.to_str().unwrap(), "-o", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        let (code, _, err) = ugnis(&args);
        assert_eq!(code, 1, "{extra:?}");
        assert!(err.contains(want), "{extra:?}: {err}");
    }
    let (code, _, err) = ugnis(&["lsystem", l.to_str().unwrap(), "-o", "x.jpg"]);
    assert_eq!(code, 1);
    assert!(err.contains("must end in .svg or .png"), "{err}");
    assert!(!out.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn dimension_of_an_ifs_an_image_and_a_flame() {
    let dir = common::temp_dir("cli-dimension");
    let ifs = dir.join("own.ifs");
    std::fs::write(
        &ifs,
        "gasket { ; three halvings\n .5 0 0 .5 0 0 .333333\n .5 0 0 .5 1 0 .333333\n \
         .5 0 0 .5 .5 .866025 .333334\n }\n\
         carpetish {\n .5 0 0 .5 0 0 .25\n .5 0 0 .5 1 0 .25\n .5 0 0 .5 0 1 .25\n \
         .5 0 0 .5 1 1 .25\n }\n",
    )
    .unwrap();
    let (code, out, err) = ugnis(&["dimension", ifs.to_str().unwrap(), "--levels"]);
    assert_eq!(code, 0, "{err}");
    let d = estimate(&out, "gasket");
    assert!((d - 1.585).abs() < 0.05, "{out}");
    assert!(out.contains("fit over levels 3–"), "{out}");
    assert!(out.contains("similarity dimension 1.58496"), "{out}");
    // Four half-size copies of the square fill it: D = 2.
    assert!((estimate(&out, "carpetish") - 2.0).abs() < 0.02, "{out}");
    // --name picks one entry.
    let (code, out, _) = ugnis(&["dimension", ifs.to_str().unwrap(), "--name", "GASKET"]);
    assert_eq!(code, 0);
    assert_eq!(out.lines().filter(|l| l.contains("D ≈")).count(), 1);
    // An image: a filled square is 2-dimensional, a circle's outline 1-dimensional.
    let png = dir.join("square.png");
    image::GrayImage::from_fn(300, 300, |x, y| {
        let inside = (20..276).contains(&x) && (30..286).contains(&y);
        image::Luma([if inside { 255 } else { 0 }])
    })
    .save(&png)
    .unwrap();
    let (code, out, err) = ugnis(&["dimension", png.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!((estimate(&out, "square.png") - 2.0).abs() < 0.02, "{out}");
    // What `ugnis lsystem` writes, `ugnis dimension` reads: a Koch curve drawn at order 7
    // measures D = 1.262 ± 0.05.
    let koch = dir.join("koch.png");
    let l = common::fixture("explore.l");
    let (code, _, err) = ugnis(&[
        "lsystem",
        l.to_str().unwrap(),
        "--order",
        "7",
        "--size",
        "1024x400",
        "-o",
        koch.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let (code, out, err) = ugnis(&["dimension", koch.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!((estimate(&out, "koch.png") - 1.262).abs() < 0.05, "{out}");
    // A flame: the IFS fixture library's triangle entry as a flame file.
    let flame = dir.join("tri.flame");
    std::fs::write(
        &flame,
        "<flame name=\"tri\" size=\"100 100\" center=\"0 0\" scale=\"50\">\n\
         <xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>\n\
         <xform weight=\"1\" color=\"0.5\" linear=\"1\" coefs=\"0.5 0 0 0.5 1 0\"/>\n\
         <xform weight=\"1\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 1\"/>\n\
         </flame>\n",
    )
    .unwrap();
    let (code, out, err) = ugnis(&["dimension", flame.to_str().unwrap(), "--points", "500000"]);
    assert_eq!(code, 0, "{err}");
    assert!((estimate(&out, "tri") - 1.585).abs() < 0.05, "{out}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn dimension_limits_and_errors() {
    let dir = common::temp_dir("cli-dimension-bad");
    let ifs = dir.join("a.ifs");
    std::fs::write(&ifs, "a {\n .5 0 0 .5 0 0 .5\n .5 0 0 .5 1 0 .5\n }\n").unwrap();
    for (args, want) in [
        (
            vec!["--points", "10"],
            "--points 10 must be between 100 and 50000000",
        ),
        (
            vec!["--points", "60000000"],
            "must be between 100 and 50000000",
        ),
        (vec!["--threshold", "300"], "300"),
        (vec!["--name", "zz"], "no entry named 'zz'"),
    ] {
        let mut a = vec!["dimension", ifs.to_str().unwrap()];
        a.extend(args.iter());
        let (code, _, err) = ugnis(&a);
        assert_eq!(code, 1, "{args:?}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
    let txt = dir.join("notes.txt");
    std::fs::write(&txt, "hello").unwrap();
    let (code, _, err) = ugnis(&["dimension", txt.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.contains("expected a flame"), "{err}");
    // A blank image has no set.
    let blank = dir.join("blank.png");
    image::GrayImage::new(32, 32).save(&blank).unwrap();
    let (code, _, err) = ugnis(&["dimension", blank.to_str().unwrap(), "--ink", "light"]);
    assert_eq!(code, 1);
    assert!(err.contains("no pixel belongs to the set"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn lorenz_draws_and_shows_sensitivity() {
    let dir = common::temp_dir("cli-lorenz");
    let png = dir.join("l.png");
    let (code, out, err) = ugnis(&[
        "lorenz",
        "-o",
        png.to_str().unwrap(),
        "--size",
        "160x120",
        "--time",
        "40",
        "--transient",
        "0",
        "--sensitivity",
    ]);
    assert_eq!(code, 0, "{err}");
    let img = image::open(&png).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (160, 120));
    // Within 1e-6 at t = 20, more than 1 apart before t = 40.
    let at20 = out
        .lines()
        .find(|l| l.trim_start().starts_with("t =   20.00"))
        .unwrap_or_else(|| panic!("{out}"));
    let v: f64 = at20.split_whitespace().last().unwrap().parse().unwrap();
    assert!(v < 1e-6 && v > 1e-8, "{at20}");
    let first: f64 = out
        .lines()
        .find_map(|l| l.strip_prefix("more than 1 apart first at t = "))
        .unwrap_or_else(|| panic!("{out}"))
        .parse()
        .unwrap();
    assert!(first > 20.0 && first < 40.0, "{first}");
    for (args, want) in [
        (vec!["--sigma", "0"], "σ (sigma) is 0"),
        (vec!["--r", "5000"], "r is 5000"),
        (vec!["--h", "0.5"], "the step h is 0.5"),
        (vec!["--time", "1e7"], "shorten the time"),
        (
            vec!["--transient=-1"],
            "--transient -1 must be between 0 and 1e9",
        ),
        (vec!["--start", "1,2"], "expected three numbers"),
        (vec!["--yaw", "1000", "--view", "turned"], "--yaw 1000"),
    ] {
        let mut a = vec!["lorenz", "-o", png.to_str().unwrap()];
        a.extend(args.iter());
        let (code, _, err) = ugnis(&a);
        assert_eq!(code, 1, "{args:?}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
