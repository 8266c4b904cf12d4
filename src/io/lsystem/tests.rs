//! Tests of the `.l` reader and writer: every entry read, round trips, the presets written,
//! Fractint's own forms (comment blocks, `angle=6`, stray text), one bad entry among good
//! ones, and errors that name line and expectation.

use super::*;
use crate::explore::lsystem::presets;
use crate::io::diag::Pos;

const OWN: &str = "; test systems in Fractint's syntax\r\n\
    \r\n\
    Koch1 { ; the Koch curve\r\n\
    \x20 Angle 6\r\n\
    \x20 Axiom F\r\n\
    \x20 F=F+F--F+F\r\n\
    \x20 }\r\n\
    Dragon {\r\n\
    Angle 8 ; comment right after the number\r\n\
    Axiom FX\r\n\
    F=\r\n\
    y=+FX--FY+\r\n\
    x=-FX++FY-\r\n\
    }\r\n\
    Split*1 {\n\
    \x20 angle 12\n\
    \x20 axiom |c9f\n\
    \x20 f = f[@iq2+f]@.5f\n\
    \x20 f=>1f\n\
    \x20 G=GG ; upper case\n\
    }\n";

#[test]
fn reads_every_entry() {
    let p = parse(OWN, "own.l").unwrap();
    assert!(p.warnings.is_empty(), "{:?}", p.warnings);
    let f = p.value;
    assert_eq!(f.entries.len(), 3);
    assert_eq!(f.entries[0].name, "Koch1");
    assert_eq!(f.entries[0].angle, Angle::Divisions(6));
    assert_eq!(f.entries[0].rules, vec![('F', "F+F--F+F".to_string())]);
    let d = f.get("dragon").unwrap();
    assert_eq!(d.rules[0], ('F', String::new()));
    assert_eq!(d.axiom, "FX");
    let s = f.get("SPLIT*1").unwrap();
    assert_eq!(s.rules.len(), 3);
    assert_eq!(s.rules[0], ('f', "f[@iq2+f]@.5f".to_string()));
    // Repeated productions concatenate: f → f[@iq2+f]@.5f>1f.
    let c = s.compile().unwrap();
    assert_eq!(c.derive_string(1).unwrap(), "|c9f[@iq2+f]@.5f>1f");
    // The Koch curve of the file draws like the preset.
    let k = f.entries[0].compile().unwrap();
    assert_eq!(k.counts(5).segments, 1024.0);
    let dk = d.compile().unwrap();
    assert_eq!(dk.counts(10).segments, 1024.0);
}

#[test]
fn round_trip() {
    let f = parse(OWN, "own.l").unwrap().value;
    let text = write(&f.entries).unwrap();
    assert!(text.contains("\r\n") && !text.replace("\r\n", "").contains('\n'));
    let g = parse(&text, "again.l").unwrap();
    assert!(g.warnings.is_empty());
    assert_eq!(g.value, f);
    assert_eq!(write(&g.value.entries).unwrap(), text);
}

#[test]
fn presets_that_fit_the_format_are_written() {
    let mut written = 0;
    for p in presets::all() {
        let Ok(text) = write(std::slice::from_ref(&p.system)) else {
            continue;
        };
        written += 1;
        let back = parse(&text, "p.l").unwrap().value.entries.remove(0);
        // Same drawing: the same segments at the preset's order.
        let a: Vec<_> = p
            .system
            .compile()
            .unwrap()
            .segments(p.order.min(4))
            .unwrap()
            .collect();
        let b: Vec<_> = back
            .compile()
            .unwrap()
            .segments(p.order.min(4))
            .unwrap()
            .collect();
        assert_eq!(a.len(), b.len(), "{}", p.system.name);
        for (x, y) in a.iter().zip(&b) {
            for i in 0..2 {
                assert!((x.b[i] - y.b[i]).abs() < 1e-9, "{}", p.system.name);
            }
        }
    }
    assert!(written >= 6, "{written}");
    // 25° cannot be written; neither can extra draw symbols.
    assert!(write(&[presets::plant_kovacs().system]).is_err());
    assert!(write(&[presets::koch_kovacs().system]).is_err());
}

fn code_of(text: &str) -> (String, usize) {
    let e = parse(text, "bad.l").unwrap_err();
    (e.code.to_string(), e.line().unwrap_or(0))
}

#[test]
fn bad_inputs_name_line_and_expectation() {
    assert_eq!(code_of("K {\n Angle 6\n Axiom F\n"), ("LSY003".into(), 1));
    assert_eq!(code_of("K\n Angle 6\n"), ("LSY002".into(), 1));
    assert_eq!(code_of(" Angle 6\n"), ("LSY001".into(), 1));
    assert_eq!(code_of("K {\n Axiom F\n}\n"), ("LSY005".into(), 3));
    assert_eq!(code_of("K {\n Angle 4\n}\n"), ("LSY006".into(), 3));
    assert_eq!(
        code_of("K {\n Angle 2\n Axiom F\n}\n"),
        ("LSY007".into(), 2)
    );
    assert_eq!(
        code_of("K {\n Angle 50\n Axiom F\n}\n"),
        ("LSY007".into(), 2)
    );
    assert_eq!(
        code_of("K {\n Angle 4.5\n Axiom F\n}\n"),
        ("LSY007".into(), 2)
    );
    assert_eq!(
        code_of("K {\n Angle 4\n Axiom F\n +=F\n}\n"),
        ("LSY008".into(), 4)
    );
    assert_eq!(
        code_of("K {\n Angle 4\n Axiom F\n c=F\n}\n"),
        ("LSY008".into(), 4)
    );
    assert_eq!(code_of("K {\n Angle 4\nL {\n}\n"), ("LSY004".into(), 3));
    assert_eq!(code_of("K {\n Angle\n}\n"), ("LSY016".into(), 2));
    let e = parse("K {\n Angle 4\n", "bad.l").unwrap_err();
    assert!(
        e.message.contains("unterminated entry 'K' opened at 1:1"),
        "{e}"
    );
}

#[test]
fn warnings() {
    let long = format!("K {{\n Angle 4\n Axiom {}\n}}\n", "F".repeat(170));
    let p = parse(&long, "w.l").unwrap();
    assert_eq!(p.warnings[0].code, "LSY011");
    let p = parse(
        "K {\n Angle 4\n Angle 6\n Axiom F\n}\nk {\n Angle 4\n Axiom F}\n",
        "w.l",
    )
    .unwrap();
    let codes: Vec<&str> = p.warnings.iter().map(|w| w.code).collect();
    assert_eq!(codes, ["LSY012", "LSY014", "LSY013"]);
    assert_eq!(p.value.entries[0].angle, Angle::Divisions(6));
    assert_eq!(p.value.entries[1].axiom, "F");
}

#[test]
fn never_panics_on_odd_input() {
    for t in [
        "",
        "{",
        "}",
        "{}",
        "a{",
        "a {}",
        "a { } b",
        "a {\n=\n}",
        "a {\n Axiom\u{00e9}@\n}",
        "a {\n x=\u{1F600}\n Angle 3\n Axiom x\n}\n",
        "\u{feff}a {\n angle 3\n axiom f\n}",
        "a {\n Angle 99999999999999999999\n}",
    ] {
        let _ = parse(t, "x.l");
    }
}

/// What Fractint does not understand inside an entry is ignored, with one warning per entry
/// that names the lines; the entry still opens.
#[test]
fn stray_text_is_ignored_with_one_warning_per_entry() {
    for (text, entry, axiom, rules) in [
        ("K {\n Angle 4\n Axiom F\n bogus\n}\n", "K", "F", vec![]),
        ("K {\n Angle 4\n Axiom F + F\n}\n", "K", "F", vec![]),
        ("K {\n Angle 4\n Axiom F\n FG=F\n}\n", "K", "F", vec![]),
        ("K {\n Angle 4\n Axiom F@\n}\n", "K", "F", vec![]),
        (
            "K {\n Angle 4\n Axiom F\n F=F@x+F<\n}\n",
            "K",
            "F",
            vec![('F', "Fx+F")],
        ),
    ] {
        let p = parse(text, "stray.l").unwrap_or_else(|e| panic!("{text:?}: {e}"));
        let e = &p.value.entries[0];
        assert_eq!(
            (e.name.as_str(), e.axiom.as_str()),
            (entry, axiom),
            "{text:?}"
        );
        let rules: Vec<(char, String)> = rules.iter().map(|(c, s)| (*c, s.to_string())).collect();
        assert_eq!(e.rules, rules, "{text:?}");
        let w: Vec<&str> = p.warnings.iter().map(|w| w.code).collect();
        assert_eq!(w, ["LSY017"], "{text:?}");
        assert!(
            p.warnings[0].message.contains("in 'K', ignored"),
            "{}",
            p.warnings[0]
        );
    }
    let p = parse("K {\n Angle 4\n Axiom F@ x\n bogus\n F=F@\n}\n", "stray.l").unwrap();
    assert_eq!(p.warnings.len(), 1, "{:?}", p.warnings);
    let m = &p.warnings[0].message;
    assert!(
        m.contains("line 3") && m.contains("line 4") && m.contains("line 5"),
        "{m}"
    );
    assert_eq!(p.warnings[0].pos, Pos::LineCol(3, 8));
}

/// Fractint's own files: an anonymous comment block at the top, `angle=6;`, productions
/// written `F = …` or `F …`, a `comment { … }` block, an entry that cannot be drawn between
/// two that can (reported, skipped), an entry whose `}` is missing before the next one.
#[test]
fn fractint_files_open_entry_by_entry() {
    let text = "{ This file holds L-systems for Fractint.\n\
        \x20 Load it with the lsystem type. }\n\
        {\n  a second block, over\n  several lines\n}\n\
        Koch { ; angle=6; form\n\
        \x20 angle=6;\n\
        \x20 axiom=F\n\
        \x20 F = F+F--F+F\n\
        }\n\
        Bad {\n  Angle 4\n  Axiom F\n  +=F\n  F=FF\n}\n\
        comment {\n  Angle 7\n}\n\
        Plain {\n  Angle 4\n  Axiom X\n  X X+F\n  F\n}\n\
        Open {\n  Angle 4\n\
        Last {\n  Angle 8\n  Axiom F\n}\n";
    let p = parse(text, "fractint.l").unwrap();
    let names: Vec<&str> = p.value.entries.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["Koch", "Plain", "Last"]);
    let koch = &p.value.entries[0];
    assert_eq!(koch.angle, Angle::Divisions(6));
    assert_eq!(koch.axiom, "F");
    assert_eq!(koch.rules, vec![('F', "F+F--F+F".to_string())]);
    assert_eq!(koch.compile().unwrap().counts(2).segments, 16.0);
    let plain = &p.value.entries[1];
    assert_eq!(
        plain.rules,
        vec![('X', "X+F".to_string()), ('F', String::new())]
    );
    let w: Vec<(&str, usize)> = p
        .warnings
        .iter()
        .map(|w| (w.code, w.line().unwrap_or(0)))
        .collect();
    assert_eq!(w, [("LSY008", 15), ("LSY004", 29)], "{:?}", p.warnings);
    assert!(p.warnings.iter().all(|w| w.warning));
    assert!(p.warnings[0].message.contains("entry 'Bad' is skipped"));
}
