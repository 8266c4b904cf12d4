//! Mutated inputs for every parser: they must return a value or an error, never panic.
//! 10 000 cases per format (proptest, deterministic seed), plus hostile hand-made inputs.

mod common;

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use ugnis::io::{
    diag, escape_view, flam3_xml, ggr, ifs, image_in, lsystem, map, palettes, png, scene, ugr,
};

const CASES: u32 = 10_000;

/// More cases on request: `UGNIS_FUZZ_CASES=200000 cargo test --test fuzz_parsers`.
fn cases() -> u32 {
    std::env::var("UGNIS_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(CASES)
}

/// One edit of a byte string.
#[derive(Clone, Debug)]
enum Edit {
    Flip(usize, u8),
    Insert(usize, u8),
    Delete(usize),
    /// Copy a span elsewhere (duplicates tokens, tags, lines).
    Splice(usize, usize, usize),
    Truncate(usize),
    /// Insert an interesting token.
    Token(usize, usize),
}

const TOKENS: &[&str] = &[
    "{",
    "}",
    "(3D)",
    ";",
    "\n",
    "\r",
    "\0",
    "<",
    ">",
    "/>",
    "\"",
    "=",
    "nan",
    "inf",
    "-1",
    "1e308",
    "1e999",
    "0,5",
    "99999999999999999999",
    "-0",
    "<flame>",
    "</flame>",
    "<xform weight=\"1\"/>",
    "index=",
    "color=",
    "gradient:",
    "&amp;",
    "&#0;",
    "<![CDATA[",
    "é",
    "\u{feff}",
    "256",
    "-5",
    "99999999999",
    "LIGMA Gradient",
    "chaos=\"1 1 1 1 1 1 1\"",
    " levels = 99\n",
    " degree = [9999999999999, 3]\n",
    " colors = []\n",
];

fn edits() -> impl Strategy<Value = Vec<Edit>> {
    let e = prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(p, b)| Edit::Flip(p, b)),
        (any::<usize>(), any::<u8>()).prop_map(|(p, b)| Edit::Insert(p, b)),
        any::<usize>().prop_map(Edit::Delete),
        (any::<usize>(), any::<usize>(), any::<usize>())
            .prop_map(|(a, b, c)| Edit::Splice(a, b, c)),
        any::<usize>().prop_map(Edit::Truncate),
        (any::<usize>(), any::<usize>()).prop_map(|(p, t)| Edit::Token(p, t)),
    ];
    prop::collection::vec(e, 1..6)
}

fn apply(src: &[u8], edits: &[Edit]) -> Vec<u8> {
    let mut v = src.to_vec();
    for e in edits {
        let n = v.len().max(1);
        match *e {
            Edit::Flip(p, b) => {
                if !v.is_empty() {
                    let i = p % v.len();
                    v[i] ^= b | 1;
                }
            }
            Edit::Insert(p, b) => v.insert(p % (v.len() + 1), b),
            Edit::Delete(p) => {
                if !v.is_empty() {
                    v.remove(p % v.len());
                }
            }
            Edit::Splice(a, b, c) => {
                if !v.is_empty() {
                    let a = a % v.len();
                    let len = (b % 64).min(v.len() - a);
                    let chunk = v[a..a + len].to_vec();
                    let at = c % (v.len() + 1);
                    v.splice(at..at, chunk);
                }
            }
            Edit::Truncate(p) => v.truncate(p % n),
            Edit::Token(p, t) => {
                let tok = TOKENS[t % TOKENS.len()].as_bytes();
                let at = p % (v.len() + 1);
                v.splice(at..at, tok.iter().copied());
            }
        }
    }
    v
}

fn fuzz(name: &str, seed: [u8; 32], src: Vec<u8>, f: impl Fn(&[u8])) -> u32 {
    let mut runner = TestRunner::new_with_rng(
        Config {
            cases: cases(),
            failure_persistence: None,
            ..Config::default()
        },
        TestRng::from_seed(RngAlgorithm::ChaCha, &seed),
    );
    let count = std::cell::Cell::new(0u32);
    runner
        .run(&edits(), |e| {
            let input = apply(&src, &e);
            f(&input);
            count.set(count.get() + 1);
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(count.get() >= cases(), "{name}: only {} cases", count.get());
    count.get()
}

fn text(b: &[u8]) -> String {
    diag::decode_text(b, "fuzz").0
}

#[test]
fn ifs_parser_never_panics() {
    let src = std::fs::read(common::fixture("library.ifs")).unwrap();
    fuzz("ifs", [1; 32], src, |b| {
        if let Ok(p) = ifs::parse(&text(b), "f.ifs") {
            for e in &p.value.entries {
                let f = ifs::entry_to_flame(e, &Default::default());
                let _ = ifs::flame_to_entry(&f);
            }
            let _ = ifs::write(&p.value);
        }
    });
}

/// Fractint's files from before version 16: bare rows, no header.
#[test]
fn headerless_ifs_parser_never_panics() {
    let src = b"; old fern\n0 0 0 .16 0 0 .01\n.85 .04 -.04 .85 0 1.6 .85\n\
                .2 -.26 .23 .22 0 1.6 .07\n-.15 .28 .26 .24 0 .44 .07\n"
        .to_vec();
    assert_eq!(
        ifs::parse(&text(&src), "FERN.IFS")
            .unwrap()
            .value
            .entries
            .len(),
        1
    );
    fuzz("ifs-old", [15; 32], src, |b| {
        if let Ok(p) = ifs::parse(&text(b), "f.ifs") {
            let _ = ifs::write(&p.value);
        }
    });
}

#[test]
fn flame_xml_parser_never_panics() {
    let mut src = std::fs::read(common::example("features.flame")).unwrap();
    src.extend(
        std::fs::read(common::fixture("library.fla"))
            .unwrap()
            .iter()
            .take(3000),
    );
    let opts = flam3_xml::ReadOptions {
        library: flam3_xml::LibrarySource::Paths(vec![]),
        ..Default::default()
    };
    fuzz("xml", [2; 32], src, |b| {
        if let Ok(p) = flam3_xml::read(&text(b), &opts) {
            // Whatever parses must also write and parse again.
            let again = flam3_xml::write(&p.value);
            flam3_xml::read(&again, &opts).expect("re-reading what ugnis wrote");
        }
    });
}

#[test]
fn fla_parser_never_panics() {
    let src = std::fs::read(common::fixture("library.fla")).unwrap();
    let opts = flam3_xml::ReadOptions {
        fla: true,
        ..Default::default()
    };
    fuzz("fla", [3; 32], src, |b| {
        let _ = flam3_xml::read(&text(b), &opts);
    });
}

#[test]
fn ugr_parser_never_panics() {
    let src = std::fs::read(common::fixture("hand.ugr")).unwrap();
    fuzz("ugr", [4; 32], src, |b| {
        if let Ok(p) = ugr::parse(&text(b), "f.ugr") {
            let _ = ugr::write(&p.value);
        }
    });
}

#[test]
fn ggr_parser_never_panics() {
    let src = std::fs::read(common::fixture("hand.ggr")).unwrap();
    fuzz("ggr", [12; 32], src, |b| {
        if let Ok(p) = ggr::parse(&text(b), "f.ggr", "f") {
            assert_eq!(p.value.colors.len(), 256);
            assert!(
                p.value
                    .colors
                    .iter()
                    .flatten()
                    .all(|v| (0.0..=1.0).contains(v))
            );
            let _ = ggr::write(&p.value);
        }
    });
}

#[test]
fn escape_view_parser_never_panics() {
    let mut src = Vec::new();
    for f in ["seahorse.esc", "galaxy.esc", "newton-septic.esc"] {
        src.extend(std::fs::read(common::root().join("examples").join(f)).unwrap());
    }
    fuzz("esc", [13; 32], src, |b| {
        if let Ok(p) = escape_view::parse(&text(b), "f.esc", None) {
            let _ = escape_view::write(&p.value);
        }
    });
}

/// Scenes build their textures while loading, so the cases are fewer (each still parses,
/// validates and builds geometry and a small checker texture).
#[test]
fn scene_parser_never_panics() {
    let src = std::fs::read(common::root().join("examples/teapot.toml")).unwrap();
    let base = common::root().join("examples");
    let cases = (cases() / 5).max(1);
    let mut runner = TestRunner::new_with_rng(
        Config {
            cases,
            failure_persistence: None,
            ..Config::default()
        },
        TestRng::from_seed(RngAlgorithm::ChaCha, &[14; 32]),
    );
    runner
        .run(&edits(), |e| {
            let _ = scene::parse(&text(&apply(&src, &e)), "f.toml", &base);
            Ok(())
        })
        .unwrap_or_else(|e| panic!("scene: {e}"));
}

/// Fractint L-systems: whatever parses is written back and read again, and its first orders are
/// counted, derived and walked (small ones only: the limits are tested elsewhere).
#[test]
fn lsystem_parser_never_panics() {
    let src = std::fs::read(common::fixture("explore.l")).unwrap();
    fuzz("lsystem", [16; 32], src, |b| {
        if let Ok(p) = lsystem::parse(&text(b), "f.l") {
            if let Ok(out) = lsystem::write(&p.value.entries) {
                let back = lsystem::parse(&out, "back.l").expect("re-reading what ugnis wrote");
                assert_eq!(back.value.entries.len(), p.value.entries.len());
            }
            for e in p.value.entries.iter().take(3) {
                let Ok(c) = e.compile() else { continue };
                for order in 0..4 {
                    if c.counts(order).visits < 1e5 {
                        let _ = c.derive_string(order);
                        let _ = c.extent(order);
                    }
                }
            }
        }
    });
}

/// Render states are binary (lengths, offsets, deflate): a damaged one is an error naming the
/// file, never a panic or an allocation its size does not justify. Whatever opens is read band
/// by band and continued under a memory limit.
#[test]
fn render_state_reader_never_panics() {
    use ugnis::flame::render::{RenderOptions, Renderer};
    use ugnis::io::render_state::{self, StateReader};
    let flames = flam3_xml::read(
        &std::fs::read_to_string(common::example("sierpinski.flame")).unwrap(),
        &Default::default(),
    )
    .unwrap();
    let mut f = flames.value.flames[0].clone();
    f.width = 24;
    f.height = 16;
    f.quality = 2.0;
    let mut r = Renderer::new(&f, &RenderOptions::default()).unwrap();
    r.run(500, &std::sync::atomic::AtomicBool::new(false)); // unfinished: it can be continued
    let (st, hist) = r.into_state().unwrap();
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.ugnis-state");
    render_state::save(&good, &st, &hist).unwrap();
    let src = std::fs::read(&good).unwrap();
    let path = dir.path().join("m.ugnis-state");
    let opts = RenderOptions {
        threads: 1,
        memory_limit: Some(64 << 20),
        ..RenderOptions::default()
    };
    fuzz("state", [17; 32], src, |b| {
        std::fs::write(&path, b).unwrap();
        let Ok(mut rd) = StateReader::open(&path) else {
            return;
        };
        let (bw, bh) = rd.state.grid().unwrap_or((0, 0));
        if bw.saturating_mul(bh) <= 1 << 16 {
            let _ = rd.read_rows(0..bh.min(40));
        }
        if let Ok(mut r) = rd.renderer(0.5, &opts, None) {
            r.run(200, &std::sync::atomic::AtomicBool::new(false));
        }
    });
}

#[test]
fn map_parser_never_panics() {
    let mut src = std::fs::read(common::fixture("hand.map")).unwrap();
    src.extend(std::fs::read(common::root().join("gradients/ember.map")).unwrap());
    fuzz("map", [5; 32], src, |b| {
        if let Ok(p) = map::parse(&text(b), "f.map", "f") {
            let _ = map::write(&p.value);
        }
    });
}

#[test]
fn png_genome_reader_never_panics() {
    let img = image::DynamicImage::ImageRgb8(image::RgbImage::new(4, 3));
    let xml = std::fs::read_to_string(common::example("sierpinski.flame")).unwrap();
    let src = png::encode(
        &img,
        &png::PngMeta {
            flame_xml: Some(xml),
            ..Default::default()
        },
    )
    .unwrap();
    fuzz("png", [6; 32], src, |b| {
        let _ = png::read_genome(b, "f.png");
        let _ = image_in::decode_rgb(b, "f.png");
    });
}

#[test]
fn bmp_reader_never_panics() {
    let img = image::DynamicImage::ImageRgb8(image::RgbImage::from_fn(5, 4, |x, y| {
        image::Rgb([x as u8 * 40, y as u8 * 60, 7])
    }));
    let src = ugnis::io::bmp::encode(&img).unwrap();
    fuzz("bmp", [7; 32], src, |b| {
        let _ = image_in::decode_rgb(b, "f.bmp");
    });
}

#[test]
fn palette_library_parser_never_panics() {
    let mut s = String::from("<palettes>\n");
    for n in 0..3 {
        s.push_str(&format!("<palette number=\"{n}\" name=\"p{n}\" data=\""));
        for i in 0..256 {
            s.push_str(&format!("00{:02x}{:02x}{:02x}", i, 255 - i, n * 40));
        }
        s.push_str("\"/>\n");
    }
    s.push_str("</palettes>\n");
    fuzz("palettes", [8; 32], s.into_bytes(), |b| {
        let _ = palettes::parse(&text(b), "p.xml");
    });
}

#[test]
fn hostile_inputs_are_refused_cleanly() {
    // Huge rows, many entries, deep nesting, gigantic numbers, NaN/inf.
    let many_rows: String = std::iter::once("big {\n".to_string())
        .chain((0..1200).map(|_| ".1 0 0 .1 0 0 1\n".to_string()))
        .chain(std::iter::once("}\n".to_string()))
        .collect();
    assert_eq!(
        ifs::parse(&many_rows, "x").err().map(|e| e.code),
        Some("IFS016")
    );
    let long_line = format!("a {{\n{}\n}}\n", ".5 ".repeat(2_000_000));
    assert!(ifs::parse(&long_line, "x").is_err());
    let deep = format!(
        "{}<flame><xform weight=\"1\"/></flame>{}",
        "<a>".repeat(100_000),
        "</a>".repeat(100_000)
    );
    assert!(flam3_xml::read(&deep, &Default::default()).is_ok());
    let deep_in_flame = format!(
        "<flame><xform weight=\"1\"/>{}{}</flame>",
        "<edit>".repeat(50_000),
        "</edit>".repeat(50_000)
    );
    assert!(flam3_xml::read(&deep_in_flame, &Default::default()).is_ok());
    for bad in ["1e400", "nan", "inf", "-inf", "1.#INF"] {
        let x = format!("<flame><xform weight=\"1\" coefs=\"1 0 0 1 0 {bad}\"/></flame>");
        assert!(flam3_xml::read(&x, &Default::default()).is_err(), "{bad}");
    }
    let size = "<flame size=\"99999999 99999999\"><xform weight=\"1\"/></flame>";
    assert_eq!(
        flam3_xml::read(size, &Default::default())
            .err()
            .map(|e| e.code),
        Some("XML003")
    );
    let many_flames = "<flame><xform weight=\"1\"/></flame>".repeat(10_001);
    assert!(
        flam3_xml::read(
            &format!("<flames>{many_flames}</flames>"),
            &Default::default()
        )
        .is_err()
    );
    let many_xforms = format!("<flame>{}</flame>", "<xform weight=\"1\"/>".repeat(10_001));
    assert!(flam3_xml::read(&many_xforms, &Default::default()).is_err());
    // Cases of the hardening pass: each ends in a value (with warnings) or an error.
    let map_text = "0 0 0\n1 99999999999999999999 3\n";
    assert_eq!(
        map::parse(map_text, "x", "x").err().map(|e| e.code),
        Some("MAP002")
    );
    let p = map::parse("0 256 0\n", "x", "x").unwrap();
    assert_eq!(p.warnings[0].code, "MAP004");
    let p = ugr::parse("g {\ngradient:\n index=-99999999999 color=1\n}\n", "x").unwrap();
    assert_eq!(p.warnings[0].code, "UGR009");
    let rows = ".1 0 0 .1 0 0 1\n".repeat(1200);
    assert_eq!(ifs::parse(&rows, "x").err().map(|e| e.code), Some("IFS016"));
    assert_eq!(
        ggr::parse("LIGMA Gradient\n0\n", "x", "x")
            .err()
            .map(|e| e.code),
        Some("GGR002")
    );
    let xaos = "<flame><xform weight=\"1\" chaos=\"1 1 1 1 1 1 1 1\"/></flame>";
    let p = flam3_xml::read(xaos, &Default::default()).unwrap();
    assert!(p.warnings.iter().any(|w| w.code == "XML022"));
    let attrs: String = (0..100_000).map(|k| format!(" a{k}=\"1\"")).collect();
    let wide = format!("<flame{attrs}><xform weight=\"1\"{attrs}/></flame>");
    assert!(flam3_xml::read(&wide, &Default::default()).is_ok());
    let base = common::root().join("examples");
    for bad in [
        "[[object]]\nkind = \"bezier\"\ndegree = [9223372036854775807, 3]\nnet = [[0, 0, 0]]\n",
        "[[texture]]\nname = \"a\"\nkind = \"checker\"\ncolors = []\n",
        "[[texture]]\nname = \"a\"\nkind = \"fbm\"\nsize = [99999, 99999]\n",
    ] {
        assert!(scene::parse(bad, "s.toml", &base).is_err(), "{bad}");
    }
    let many = "[[light]]\nposition = [0, 1, 2]\n".repeat(300);
    assert_eq!(
        scene::parse(&many, "s.toml", &base).err().map(|e| e.code),
        Some("SCN007")
    );
    let huge_ugr = format!(
        "g {{\ngradient:\n{}}}\n",
        " index=0 color=99999999999999999999\n"
    );
    assert_eq!(
        ugr::parse(&huge_ugr, "x").err().map(|e| e.code),
        Some("UGR006")
    );
}
