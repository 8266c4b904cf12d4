//! Tests of the `.ifs` reader and writer and of the conversions to and from flames.

use super::*;
use crate::flame::model::FlameKind;
use crate::io::diag::Pos;

const LIB: &str = "; a test library in Fractint's syntax\r\n\
fern {\r\n    0    0    0  .16 0   0 .01\r\n   .85  .04 -.04 .85 0 1.6 .85\r\n   .2  -.26  .23 .22 0 1.6 .07\r\n  -.15  .28  .26 .24 0 .44 .07\r\n  }\r\n\
binary { ; comment allowed here\n  ; and here\n  .5  .0 .0 .5 -2.563477 -0.000003 .333333   ; also comment allowed here\n  .5  .0 .0 .5  2.436544 -0.000003 .333333\n  .0 -.5 .5 .0  4.873085  7.563492 .333333\n  }\n\
3dfern (3D) {\n   .00  .00 0 .0 .18 .0 0  0.0 0.00 0 0.0 0 .01\n   .85  .00 0 .0 .85 .1 0 -0.1 0.85 0 1.6 0 .85\n   .20 -.20 0 .2 .20 .0 0  0.0 0.30 0 0.8 0 .07\n  -.20  .20 0 .2 .20 .0 0  0.0 0.30 0 0.8 0 .07\n  }\n\
tri(3d){\n 1 0 0 0 1 0 0 0 1 0 0 0 1 }\n";

#[test]
fn reads_the_fixture_syntax() {
    let p = parse(LIB, "lib.ifs").unwrap();
    let f = p.value;
    assert_eq!(f.entries.len(), 4);
    let fern = f.get("FERN").unwrap();
    assert_eq!(fern.rows.len(), 4);
    assert_eq!(fern.rows[1], vec![0.85, 0.04, -0.04, 0.85, 0.0, 1.6, 0.85]);
    let bin = f.get("binary").unwrap();
    assert_eq!(bin.rows.len(), 3);
    assert!(f.get("3dfern").unwrap().three_d);
    assert!(f.get("tri").unwrap().three_d);
    // binary's Σp = 0.999999 is within tolerance; tri's map is not contractive? (3-D: not checked)
    assert!(
        p.warnings.iter().all(|w| w.code != "IFS011"),
        "{:?}",
        p.warnings
    );
}

#[test]
fn bad_inputs_have_codes_and_positions() {
    let cases: &[(&str, &str, (usize, usize))] = &[
        ("1 2 3\n", "IFS001", (1, 1)),
        ("fern\n{\n1 2 3 4 5 6 1\n}\n", "IFS002", (1, 1)),
        (" {\n1 2 3 4 5 6 1\n}\n", "IFS002", (1, 2)),
        ("fern { 1 2 3 4 5 6 1\n}\n", "IFS003", (1, 8)),
        ("\nfern {\n1 2 3 4 5 6 1\n", "IFS004", (4, 1)),
        ("a {\n1 2 3 4 5 6 1\nb {\n}\n", "IFS005", (3, 3)),
        ("a {\n1 2 x 4 5 6 1\n}\n", "IFS006", (2, 5)),
        ("a {\n1 2 3 4 5 6 1 7\n}\n", "IFS007", (3, 1)),
        ("a {\n}\n", "IFS007", (2, 1)),
        ("a {\n1 2 nan 4 5 6 1\n}\n", "IFS006", (2, 5)),
        ("a {\n1 2 1e999 4 5 6 1\n}\n", "IFS008", (2, 5)),
        ("a (4D) {\n1 2 3 4 5 6 1\n}\n", "IFS009", (1, 3)),
        ("a {\n0,5 0 0 0.5 0 0 1\n}\n", "IFS006", (2, 1)),
    ];
    for (src, code, (l, c)) in cases {
        let e = parse(src, "x.ifs").unwrap_err();
        assert_eq!(e.code, *code, "{src:?}: {e}");
        assert_eq!(e.pos, Pos::LineCol(*l, *c), "{src:?}: {e}");
    }
    let e = parse("\nfern {\n1 2 3 4 5 6 1\n", "x.ifs").unwrap_err();
    assert!(
        e.message
            .contains("unterminated entry 'fern' opened at 2:1"),
        "{e}"
    );
    let e = parse("a {\n0,5 0 0 0.5 0 0 1\n}\n", "x.ifs").unwrap_err();
    assert!(e.message.contains("decimal separator"), "{e}");
}

#[test]
fn old_fractint_files_without_a_header_are_one_entry() {
    let text = "; fern, saved one IFS per file\r\n0 0 0 .16 0 0 .01\r\n.85 .04 -.04 .85 0 1.6 .85\r\n\
                    .2 -.26 .23 .22 0 1.6 .07\r\n-.15 .28 .26 .24 0 .44 .07\r\n";
    let p = parse(text, "old/FERN.IFS").unwrap();
    assert_eq!(p.value.entries.len(), 1);
    let e = &p.value.entries[0];
    assert_eq!(
        (e.name.as_str(), e.three_d, e.rows.len()),
        ("FERN", false, 4)
    );
    assert_eq!(e.rows[1], vec![0.85, 0.04, -0.04, 0.85, 0.0, 1.6, 0.85]);
    assert_eq!(p.warnings[0].code, "IFS017");
    assert!(
        p.warnings[0].message.contains("'FERN' (4 rows)"),
        "{}",
        p.warnings[0]
    );
    // 3-D rows (13 numbers) are recognised by their count.
    let p = parse(&"1 0 0 0 1 0 0 0 1 0 0 0 1\n".repeat(2), "cube.ifs").unwrap();
    assert!(p.value.entries[0].three_d);
    // Errors point into the file itself.
    let e = parse("0 0 0 .5 0 0 1\n1 2 3 4 5 6 7 8\n", "x.ifs").unwrap_err();
    assert_eq!((e.code, e.pos), ("IFS007", Pos::File));
    let p = parse("2 0 0 2 0 0 1\n", "big.ifs").unwrap();
    assert!(p.warnings.iter().any(|w| w.code == "IFS014"));
    // Text that is not numbers is not an old file.
    assert_eq!(
        parse("0 0 0 .5 0 0 1 x\n", "x.ifs").unwrap_err().code,
        "IFS001"
    );
}

#[test]
fn accepted_with_warnings() {
    let p = parse("a {\n.5 0 0 .5 0 0 .33}\n", "x.ifs").unwrap();
    assert!(p.warnings.iter().any(|w| w.code == "IFS010"));
    assert!(p.warnings.iter().any(|w| w.code == "IFS011"));
    let p = parse("a {\n2 0 0 2 0 0 1\n}\nA {\n.5 0 0 .5 0 0 1\n}\n", "x.ifs").unwrap();
    assert!(p.warnings.iter().any(|w| w.code == "IFS014"));
    assert!(p.warnings.iter().any(|w| w.code == "IFS012"));
    let many: String = std::iter::once("big {\n".to_string())
        .chain((0..64).map(|_| ".1 0 0 .1 0 0 1\n".to_string()))
        .chain(std::iter::once("}\n".to_string()))
        .collect();
    let p = parse(&many, "x.ifs").unwrap();
    assert!(p.warnings.iter().any(|w| w.code == "IFS013"));
}

#[test]
fn write_read_round_trip_is_exact() {
    let f = parse(LIB, "lib.ifs").unwrap().value;
    let text = write(&f).unwrap();
    assert!(text.contains("\r\n") && text.contains("3dfern (3D) {\r\n"));
    assert!(
        text.starts_with("fern {\r\n  0 0 0 0.16 0 0 0.01\r\n"),
        "{text}"
    );
    let g = parse(&text, "w.ifs").unwrap().value;
    assert_eq!(f, g);
    assert_eq!(write(&g).unwrap(), text);
    let dup = IfsFile {
        entries: vec![
            f.entries[0].clone(),
            IfsEntry {
                name: "FERN".into(),
                ..f.entries[0].clone()
            },
        ],
    };
    assert!(
        write(&dup)
            .unwrap_err()
            .to_string()
            .contains("same for Fractint")
    );
}

#[test]
fn fern_becomes_an_upright_flame_and_back() {
    let f = parse(LIB, "lib.ifs").unwrap().value;
    let flame = entry_to_flame(f.get("fern").unwrap(), &NewFlame::default());
    assert_eq!(flame.xforms.len(), 4);
    assert_eq!(flame.kind, FlameKind::Ifs);
    assert!(!flame.has_camera);
    // coefs="0.85 0.04 -0.04 0.85 0 -1.6" for the second row.
    assert_eq!(
        flame.xforms[1].coefs.to_coefs(),
        [0.85, 0.04, -0.04, 0.85, 0.0, -1.6]
    );
    assert_eq!(flame.xforms[0].color, 0.0);
    assert_eq!(flame.xforms[3].color, 1.0);
    assert!((flame.xforms[1].weight - 0.85).abs() < 1e-12);
    let (e, warn) = flame_to_entry(&flame).unwrap();
    assert!(warn.unwrap().contains("lost"));
    for (a, b) in e.rows.iter().zip(&f.get("fern").unwrap().rows) {
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() < 1e-12, "{a:?} vs {b:?}");
        }
    }
}

#[test]
fn only_linear_flames_export() {
    let f = parse(LIB, "lib.ifs").unwrap().value;
    let mut flame = entry_to_flame(f.get("fern").unwrap(), &NewFlame::default());
    flame.xforms[2].vars = vec![crate::flame::model::Var::new(variations::SWIRL, 1.0)];
    assert_eq!(
        flame_to_entry(&flame).unwrap_err().to_string(),
        "xform 3 uses variation 'swirl'; only linear flames can be saved as .ifs"
    );
    // Linear weight and post fold into the map.
    let mut flame = entry_to_flame(f.get("binary").unwrap(), &NewFlame::default());
    flame.xforms[0].vars[0].weight = 2.0;
    flame.xforms[0].post = Affine::new(1.0, 0.0, 0.0, 1.0, 0.5, 0.0);
    let (e, _) = flame_to_entry(&flame).unwrap();
    assert!((e.rows[0][0] - 1.0).abs() < 1e-12);
    assert!((e.rows[0][4] - (2.0 * -2.563477 + 0.5)).abs() < 1e-9);
}

#[test]
fn negative_probabilities_follow_fractint() {
    let p = parse(
        "h {\n.5 0 0 .5 0 0 -0.2\n.5 0 0 .5 1 0 0.5\n.5 0 0 .5 0 1 0.5\n}\n",
        "h.ifs",
    )
    .unwrap();
    let w = p.warnings.iter().find(|w| w.code == "IFS008").unwrap();
    assert_eq!(w.pos, Pos::LineCol(2, 15));
    let flame = entry_to_flame(&p.value.entries[0], &NewFlame::default());
    let ws: Vec<f64> = flame.xforms.iter().map(|x| x.weight).collect();
    // Cumulative −0.2, 0.3, 0.8 → shares 0, 0.3, 0.7 (the last row takes the rest).
    for (a, b) in ws.iter().zip([0.0, 0.3, 0.7]) {
        assert!((a - b).abs() < 1e-12, "{ws:?}");
    }
    assert_eq!(
        fractint_shares(&[0.25, 0.25, 0.25, 0.25]),
        vec![0.25, 0.25, 0.25, 0.25]
    );
}

#[test]
fn zero_probabilities_use_the_determinant_rule() {
    let p = parse("z {\n.5 0 0 .5 0 0 0\n.25 0 0 .25 1 0 0\n}\n", "z.ifs").unwrap();
    assert!(p.warnings.iter().any(|w| w.code == "IFS008"));
    let flame = entry_to_flame(&p.value.entries[0], &NewFlame::default());
    let w: Vec<f64> = flame.xforms.iter().map(|x| x.weight).collect();
    assert!(
        (w[0] - 0.8).abs() < 1e-12 && (w[1] - 0.2).abs() < 1e-12,
        "{w:?}"
    );
}
