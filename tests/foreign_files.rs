//! Files of other programs that their own program reads: flam3's space-padded palettes and
//! template files, JWildfire's doubled variations (`log#1#`), several final xforms and
//! attribute names written without a value, Fractint's own `.l` syntax. The fixtures are small
//! files of our own in each program's syntax (tests/fixtures/foreign/).

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use ugnis::flame::variations::{self, Form};
use ugnis::io::flam3_xml::{self, LibrarySource, ReadOptions};
use ugnis::io::{self, lsystem};

fn fixture(name: &str) -> PathBuf {
    common::fixture(&format!("foreign/{name}"))
}

fn opts() -> ReadOptions<'static> {
    ReadOptions {
        library: LibrarySource::Paths(vec![]),
        ..ReadOptions::default()
    }
}

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

/// flam3 3.1 writes palette bytes with `%2x` (a space before a single digit); flam3-render
/// reads them byte field by byte field. The colours are those flam3-genome 3.1.1 prints for
/// the same file (`clone=FILE flam3-genome`), misreadings included.
#[test]
fn flam3_space_padded_palette_reads_as_flam3_reads_it() {
    let p = io::read_flame_file(&fixture("flam3-padded-palette.flam3"), &opts()).unwrap();
    let codes: Vec<&str> = p.warnings.iter().map(|w| w.code).collect();
    assert_eq!(codes, ["XML023"], "{:?}", p.warnings);
    assert_eq!(p.warnings[0].line(), Some(4));
    let flam3: [[u8; 3]; 16] = [
        [19, 129, 225],
        [19, 128, 209],
        [29, 131, 0],
        [81, 35, 74],
        [171, 188, 12],
        [10, 95, 255],
        [15, 15, 241],
        [35, 69, 6],
        [1, 2, 52],
        [5, 6, 7],
        [15, 8, 0],
        [0, 0, 15],
        [237, 203, 10],
        [153, 153, 3],
        [52, 4, 86],
        [103, 120, 8],
    ];
    let colors = &p.value.flames[0].palette.colors;
    for (i, want) in flam3.iter().enumerate() {
        let got: Vec<u8> = colors[i][..3]
            .iter()
            .map(|c| (c * 255.0).round() as u8)
            .collect();
        assert_eq!(got, want, "colour {i}");
    }
    // Data flam3 cannot read either is refused where it goes wrong.
    let text = std::fs::read_to_string(fixture("flam3-padded-palette.flam3")).unwrap();
    let short = text.replace(" 5667788", " 56677");
    let e = flam3_xml::read(&short, &opts()).unwrap_err();
    assert_eq!(e.code, "XML010");
    assert!(e.message.contains("16 hex colours of 6 digits"), "{e}");
}

/// JWildfire's flame with a variation used twice in an xform (`log`, `log#1#`), parameter
/// names holding spaces (`glsl_apollonian_Density Pixels`) and two final xforms: read as
/// JWildfire reads it, written back so that JWildfire reads it again.
#[test]
fn jwildfire_doubled_variations_and_final_xforms() {
    let path = fixture("jwf-doubled-and-finals.flame");
    let p = io::read_flame_file(&path, &opts()).unwrap();
    let f = &p.value.flames[0];
    let log = variations::by_name("log").unwrap();
    let lin = variations::by_name("linear3D").unwrap();
    let x = &f.xforms[0];
    let got: Vec<(variations::VarId, f64, Vec<f64>)> = x
        .vars
        .iter()
        .map(|v| (v.id, v.weight, v.params.clone()))
        .collect();
    assert_eq!(
        got,
        [
            (lin, 0.3, vec![]),
            (log, 0.25, vec![2.0]),
            (log, 0.125, vec![3.0]),
            (lin, 0.2, vec![]),
        ]
    );
    // A further use with its own priority: `spherical#1#` runs before the others; the
    // direct-colour glsl_apollonian of amount 0 is kept (JWildfire runs it: it colours points).
    let forms: Vec<(Form, f64)> = f.xforms[1]
        .vars
        .iter()
        .map(|v| (v.form, v.weight))
        .collect();
    assert_eq!(
        forms,
        [
            (Form::Regular, 0.5),
            (Form::Pre, 0.25),
            (Form::Regular, 0.0)
        ]
    );
    // Names JWildfire wrote with spaces are kept whole, with one warning each at their line:
    // the kept glsl_apollonian's own parameter is read, the others kept as they stand.
    assert_eq!(f.xforms[1].vars[2].params[0], 800.0);
    let kept: Vec<&str> = f.xforms[1]
        .extra_attrs
        .iter()
        .map(|(k, _)| k.as_str())
        .collect();
    for name in ["dc_acrilic_Red Fac.", "dc_acrilic_Size (N PowersOf 2)"] {
        assert!(kept.contains(&name), "{name} not in {kept:?}");
    }
    let spaced: Vec<_> = p.warnings.iter().filter(|w| w.code == "XML024").collect();
    assert_eq!(spaced.len(), 3, "{:?}", p.warnings);
    assert!(spaced.iter().all(|w| w.line() == Some(3)));
    assert!(spaced[0].message.contains("'glsl_apollonian_Density'"));
    // Two final xforms, in file order.
    assert!(f.final_xform.is_some());
    assert_eq!(f.more_finals.len(), 1);
    assert_eq!(f.more_finals[0].coefs.e, 1.0);
    // Written back as JWildfire writes them, and read again the same.
    let text = flam3_xml::write(&p.value);
    for part in [
        "log=\"0.25\"",
        "log#1#=\"0.125\"",
        "log#1#_base=\"3\"",
        "linear3D#1#=\"0.2\"",
        "glsl_apollonian_Density Pixels=\"800\"",
    ] {
        assert!(text.contains(part), "{part} not written");
    }
    assert_eq!(text.matches("<finalxform").count(), 2);
    let again = flam3_xml::read(&text, &opts()).unwrap().value;
    let g = &again.flames[0];
    assert_eq!(g.xforms, f.xforms);
    // (A final xform's xaos row of ones means nothing and is not written.)
    let no_xaos = |x: &ugnis::flame::Xform| ugnis::flame::Xform {
        chaos: Vec::new(),
        ..x.clone()
    };
    let finals = |f: &ugnis::flame::Flame| f.finals().map(no_xaos).collect::<Vec<_>>();
    assert_eq!(finals(g), finals(f));
    assert_eq!(finals(g).len(), 2);
    // `info` counts the finals.
    let (code, out, err) = ugnis(&["info", path.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("2 xforms + 2 finals"), "{out}");
    assert!(err.contains("XML024"), "{err}");
}

/// A flam3 template (render settings, no xform) is described by `info`, and `render
/// --template` applies it as flam3-genome's `template=` does: the values are those
/// flam3-genome 3.1.1 prints for `template=template.flam3 clone_all=…` (the scale follows the
/// height, 240·240/480 = 120; the centre, rotation, brightness, gamma and vibrancy stay).
#[test]
fn flam3_templates_are_described_and_applied() {
    let t = fixture("template.flam3");
    let (code, out, err) = ugnis(&["info", t.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("320x240  template"), "{out}");
    assert!(
        out.contains("applies: size, zoom, oversample, filter"),
        "{out}"
    );
    assert!(
        out.contains("center, scale, brightness, gamma, vibrancy"),
        "{out}"
    );
    let tpl = io::read_template_file(&t, &opts()).unwrap().value;
    let text = "<flame name=\"target\" size=\"640 480\" center=\"0.1 0.2\" scale=\"240\" \
        rotate=\"30\" quality=\"10\" brightness=\"4\" gamma=\"4\" vibrancy=\"1\" \
        palette_mode=\"linear\"><xform weight=\"1\" color=\"0\" linear=\"1\" \
        coefs=\"0.5 0 0 0.5 0 0\"/><color index=\"0\" rgb=\"255 0 0\"/></flame>";
    let mut f = flam3_xml::read(text, &opts())
        .unwrap()
        .value
        .flames
        .remove(0);
    tpl.apply(&mut f);
    assert_eq!((f.width, f.height, f.scale), (320, 240, 120.0));
    assert_eq!(
        (f.zoom, f.supersample, f.filter, f.quality),
        (0.5, 2, 0.75, 7.0)
    );
    assert_eq!(f.filter_shape.name(), "mitchell");
    assert_eq!(f.background, [0.25, 0.5, 1.0]);
    assert_eq!((f.estimator_radius, f.highlight_power), (5.0, 2.0));
    assert!(
        f.extra_attrs
            .contains(&("passes".to_string(), "2".to_string()))
    );
    assert_eq!((f.center, f.rotate), ([0.1, 0.2], 30.0));
    assert_eq!((f.brightness, f.gamma, f.vibrancy), (4.0, 4.0, 1.0));
    assert_eq!(f.palette_mode.name(), "linear");
    // The command line: the template's size (a small one here) and quality.
    let dir = common::temp_dir("foreign-template");
    let _cleanup = common::Cleanup(dir.clone());
    let small = dir.join("small.flam3");
    std::fs::write(&small, "<flame size=\"40 30\" quality=\"2\"/>").unwrap();
    let ex = common::example("sierpinski.flame");
    let png = dir.join("s.png");
    let (code, _, err) = ugnis(&[
        "render",
        ex.to_str().unwrap(),
        "--template",
        small.to_str().unwrap(),
        "-o",
        png.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let img = image::open(&png).unwrap();
    assert_eq!((img.width(), img.height()), (40, 30));
    // A template rendered as a flame is refused with how to use it.
    let (code, _, err) = ugnis(&["render", small.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        err.contains("error[XML007]") && err.contains("--template"),
        "{err}"
    );
}

/// Fractint's own `.l` syntax: every entry that Fractint can draw opens, the one it cannot is
/// reported and skipped, and stray text draws one warning per entry.
#[test]
fn fractint_l_file_opens_entry_by_entry() {
    let p = io::read_lsystems(&fixture("fractint-forms.l")).unwrap();
    let names: Vec<&str> = p.value.entries.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["Koch", "Dragon", "Squares"]);
    for e in &p.value.entries {
        let c = e.compile().unwrap();
        assert!(c.counts(3).segments > 0.0, "{}", e.name);
    }
    let w: Vec<(&str, Option<usize>)> = p.warnings.iter().map(|w| (w.code, w.line())).collect();
    assert_eq!(
        w,
        [
            ("LSY017", Some(16)),
            ("LSY008", Some(26)),
            ("LSY017", Some(31)),
        ],
        "{:?}",
        p.warnings
    );
}

/// With UGNIS_FRACTINT_DIR set to a folder of Fractint's own `.l` files (not part of the
/// project), every entry of every file opens and draws.
#[test]
fn fractint_l_files_of_a_folder_open() {
    let Ok(dir) = std::env::var("UGNIS_FRACTINT_DIR") else {
        return;
    };
    let mut files = 0;
    for e in std::fs::read_dir(Path::new(&dir)).unwrap() {
        let path = e.unwrap().path();
        if path.extension().is_none_or(|x| x != "l") {
            continue;
        }
        files += 1;
        let text = String::from_utf8_lossy(&std::fs::read(&path).unwrap()).into_owned();
        let p =
            lsystem::parse(&text, &path.display().to_string()).unwrap_or_else(|e| panic!("{e}"));
        let skipped: Vec<String> = p
            .warnings
            .iter()
            .filter(|w| w.message.contains("is skipped"))
            .map(|w| w.to_string())
            .collect();
        assert!(skipped.is_empty(), "{skipped:?}");
        for s in &p.value.entries {
            let c = s
                .compile()
                .unwrap_or_else(|e| panic!("{}: {}: {e}", path.display(), s.name));
            assert!(c.counts(2).segments >= 0.0);
        }
    }
    assert!(files > 0, "no .l files in {dir}");
}
