//! Files of other programs that their own program reads: flam3's space-padded palettes and
//! template files, JWildfire's doubled variations (`log#1#`), several final xforms and
//! attribute names written without a value, Fractint's own `.l` syntax. The fixtures are small
//! files of our own in each program's syntax (tests/fixtures/foreign/).

mod common;

use std::path::PathBuf;

use ugnis::io;
use ugnis::io::flam3_xml::{self, LibrarySource, ReadOptions};

fn fixture(name: &str) -> PathBuf {
    common::fixture(&format!("foreign/{name}"))
}

fn opts() -> ReadOptions<'static> {
    ReadOptions {
        library: LibrarySource::Paths(vec![]),
        ..ReadOptions::default()
    }
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
