//! flam3's palette library `flam3-palettes.xml`: 701 numbered gradients,
//! referenced by `palette="N"` in flames. The file ships with flam3 (Debian: `flam3-palette`);
//! ugnis looks for it and never copies it.

use std::path::{Path, PathBuf};

use quick_xml::events::Event;

use crate::gradient::Gradient;
use crate::io::diag::{Diagnostic, Parsed, Pos, SourceMap};
use crate::io::xml::{XmlCursor, scan_attrs};

/// The numbered palettes of a library file.
#[derive(Clone, Debug, Default)]
pub struct PaletteLibrary {
    /// Index = palette number; `None` for numbers the file does not define.
    pub palettes: Vec<Option<Gradient>>,
    /// The file the library was read from.
    pub path: PathBuf,
}

impl PaletteLibrary {
    /// Palette number `n`, if the file defines it.
    pub fn get(&self, n: usize) -> Option<&Gradient> {
        self.palettes.get(n).and_then(|p| p.as_ref())
    }

    /// Number of palettes defined.
    pub fn len(&self) -> usize {
        self.palettes.iter().filter(|p| p.is_some()).count()
    }

    /// Whether no palette is defined.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The palettes defined, with their numbers, in order.
    pub fn iter(&self) -> impl Iterator<Item = (usize, &Gradient)> {
        self.palettes
            .iter()
            .enumerate()
            .filter_map(|(i, p)| p.as_ref().map(|g| (i, g)))
    }
}

/// Where ugnis looks for `flam3-palettes.xml`: `$FLAM3_PALETTES`, then the usual install
/// locations.
pub fn default_paths() -> Vec<PathBuf> {
    let mut v = Vec::new();
    if let Some(p) = std::env::var_os("FLAM3_PALETTES") {
        v.push(PathBuf::from(p));
    }
    for p in [
        "/usr/share/flam3/flam3-palettes.xml",
        "/usr/local/share/flam3/flam3-palettes.xml",
        "/opt/homebrew/share/flam3/flam3-palettes.xml",
    ] {
        v.push(PathBuf::from(p));
    }
    v
}

/// Find the library among `paths` (or the defaults); `None` if no file exists.
pub fn find(paths: Option<&[PathBuf]>) -> Option<PathBuf> {
    let defaults;
    let paths = match paths {
        Some(p) => p,
        None => {
            defaults = default_paths();
            &defaults
        }
    };
    paths.iter().find(|p| p.is_file()).cloned()
}

/// Read a library file.
pub fn load(path: &Path) -> Result<Parsed<PaletteLibrary>, Diagnostic> {
    let name = path.display().to_string();
    let bytes = super::read_bytes_limited(path, super::MAX_FILE_SIZE).map_err(|e| Diagnostic {
        code: if e.code == "IO001" { "PAL000" } else { e.code },
        ..e
    })?;
    let text = String::from_utf8(bytes)
        .map_err(|_| Diagnostic::error(&name, Pos::File, "XML001", "file is not UTF-8"))?;
    let mut lib = parse(&text, &name)?;
    lib.value.path = path.to_path_buf();
    Ok(lib)
}

/// Decode `00RRGGBB…` colours (whitespace allowed between colours).
pub fn decode_hex_colors(data: &str, digits_per_color: usize) -> Option<Vec<[u8; 4]>> {
    let compact: Vec<u8> = data.bytes().filter(|c| !c.is_ascii_whitespace()).collect();
    if !compact.len().is_multiple_of(digits_per_color) {
        return None;
    }
    let hex = |c: u8| (c as char).to_digit(16).map(|v| v as u8);
    compact
        .chunks(digits_per_color)
        .map(|ch| {
            let mut v = [0u8; 4];
            for (k, pair) in ch.chunks(2).enumerate() {
                v[k] = hex(pair[0])? * 16 + hex(pair[1])?;
            }
            Some(v)
        })
        .collect()
}

/// Parse the text of a library file.
pub fn parse(text: &str, file: &str) -> Result<Parsed<PaletteLibrary>, Diagnostic> {
    let map = SourceMap::new(text);
    let err = |off: usize, code, msg: String| Diagnostic::error(file, map.pos(off), code, msg);
    let mut cur = XmlCursor::new(text);
    let mut lib = PaletteLibrary::default();
    let mut warnings = Vec::new();
    loop {
        let p = cur.next_event().map_err(|(o, m)| err(o, "XML001", m))?;
        let e = match &p.event {
            Event::Eof => break,
            Event::Start(e) | Event::Empty(e) => e,
            _ => continue,
        };
        if e.name().as_ref() != "palette" {
            continue;
        }
        let attrs = scan_attrs(e, p.start + 1).map_err(|(o, m)| err(o, "XML001", m))?;
        let get = |n: &str| attrs.iter().find(|a| a.name == n);
        let Some(num) = get("number") else {
            return Err(err(
                p.start,
                "PAL002",
                "palette without a 'number' attribute".into(),
            ));
        };
        let n: usize = num.value.trim().parse().map_err(|_| {
            err(
                num.offset,
                "PAL002",
                format!("'{}' is not a palette number", num.value),
            )
        })?;
        let name = get("name").map(|a| a.value.to_string()).unwrap_or_default();
        let colors = get("data").and_then(|d| decode_hex_colors(&d.value, 8));
        match colors {
            Some(c) if c.len() == 256 => {
                if lib.palettes.len() <= n {
                    lib.palettes.resize(n + 1, None);
                }
                if lib.palettes[n].is_some() {
                    return Err(err(
                        num.offset,
                        "PAL002",
                        format!("palette number {n} defined twice"),
                    ));
                }
                let rgb: Vec<[u8; 3]> = c.iter().map(|v| [v[1], v[2], v[3]]).collect();
                lib.palettes[n] = Some(Gradient::from_rgb8(name, &rgb));
            }
            other => warnings.push(Diagnostic::warning(
                file,
                map.pos(p.start),
                "PAL001",
                format!(
                    "palette {n} does not hold 256 colours ({}); skipped",
                    other.map_or("undecodable data".to_string(), |c| format!(
                        "{} colours",
                        c.len()
                    ))
                ),
            )),
        }
        if matches!(p.event, Event::Start(_)) {
            cur.skip_element().map_err(|(o, m)| err(o, "XML001", m))?;
        }
    }
    Ok(Parsed {
        value: lib,
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hex256(first: &str, last: &str) -> String {
        let mut s = String::from(first);
        for _ in 1..255 {
            s.push_str("00102030");
        }
        s.push_str(last);
        s
    }

    #[test]
    fn parses_numbered_palettes() {
        let text = format!(
            "<palettes>\n<palette number=\"0\" name=\"south-sea-bather\" data=\"{}\"/>\n<palette number=\"3\" data=\"00ff\"/>\n</palettes>",
            hex256("00b9eaeb", "005d5938")
        );
        let lib = parse(&text, "lib.xml").unwrap();
        assert_eq!(lib.warnings.len(), 1);
        assert_eq!(lib.warnings[0].code, "PAL001");
        let g = lib.value.get(0).unwrap();
        assert_eq!(g.name, "south-sea-bather");
        assert_eq!(g.rgb8(0), [185, 234, 235]);
        assert_eq!(g.rgb8(255), [93, 89, 56]);
        assert!(lib.value.get(3).is_none());
        let dup = format!(
            "<palettes><palette number=\"1\" data=\"{0}\"/><palette number=\"1\" data=\"{0}\"/></palettes>",
            hex256("00000000", "00000000")
        );
        assert_eq!(parse(&dup, "x").unwrap_err().code, "PAL002");
    }

    /// The installed flam3 library, when present (Debian flam3-palette), has 701 palettes and
    /// the known colours of palettes 0 and 700.
    #[test]
    fn installed_library_if_present() {
        let Some(p) = find(None) else { return };
        let lib = load(&p).unwrap().value;
        assert_eq!(lib.len(), 701);
        assert_eq!(lib.get(0).unwrap().rgb8(1), [193, 238, 235]);
        assert_eq!(lib.get(700).unwrap().rgb8(0), [0, 68, 38]);
        assert_eq!(lib.get(700).unwrap().rgb8(255), [1, 74, 45]);
    }
}
