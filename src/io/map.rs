//! Fractint `.map` palettes: up to 256 lines `R G B [comment]`.

use std::fmt::Write as _;

use crate::gradient::Gradient;
use crate::io::diag::{Diagnostic, Parsed, Pos, SourceMap, lines, parse_int};

/// Parse a `.map` file. Fewer than 256 colours are kept (in `map_entries`) and resampled to
/// 256 by linear interpolation at positions i·(k − 1)/255 for the flame view.
pub fn parse(text: &str, file: &str, name: &str) -> Result<Parsed<Gradient>, Diagnostic> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.contains('\0') {
        let off = text.find('\0').unwrap_or(0);
        return Err(Diagnostic::error(
            file,
            Pos::Byte(off as u64),
            "MAP003",
            "binary content (NUL bytes); not a text .map palette",
        ));
    }
    let map = SourceMap::new(text);
    let mut colors: Vec<[u8; 3]> = Vec::new();
    let mut warnings = Vec::new();
    // Colour lines past the 256th (counted, not read) and values above 255 (clamped).
    let mut extra_lines = 0usize;
    let mut first_extra: Option<usize> = None;
    let mut clamped: Vec<(usize, String)> = Vec::new();
    for (base, content) in lines(text) {
        let toks: Vec<(usize, &str)> = content
            .split_whitespace()
            .map(|t| (t.as_ptr() as usize - content.as_ptr() as usize, t))
            .collect();
        if toks.is_empty() {
            continue;
        }
        // A colour line starts with a number; anything else ends the palette.
        let numeric = |t: &str| {
            t.starts_with(|c: char| c.is_ascii_digit() || c == '-' || c == '+' || c == '.')
        };
        if !numeric(toks[0].1) {
            if colors.is_empty() {
                return Err(Diagnostic::error(
                    file,
                    map.pos(base + toks[0].0),
                    "MAP001",
                    "no colour line: expected 'R G B' with values 0..255",
                ));
            }
            break;
        }
        if colors.len() == 256 {
            extra_lines += 1;
            first_extra.get_or_insert(base);
            continue;
        }
        let mut c = [0u8; 3];
        for (k, slot) in c.iter_mut().enumerate() {
            let Some(&(off, t)) = toks.get(k) else {
                return Err(Diagnostic::error(
                    file,
                    map.pos(base + content.len()),
                    "MAP002",
                    format!(
                        "colour line {} has {k} values; expected 3 (R G B)",
                        colors.len() + 1
                    ),
                ));
            };
            let v = parse_int(t).ok().filter(|v| *v >= 0).ok_or_else(|| {
                Diagnostic::error(
                    file,
                    map.pos(base + off),
                    "MAP002",
                    format!("'{t}' is not an integer 0..255"),
                )
            })?;
            if v > 255 {
                // Some programs (gnofract4d) write 256 for full intensity.
                clamped.push((base + off, t.to_string()));
            }
            *slot = v.min(255) as u8;
        }
        colors.push(c);
    }
    if colors.is_empty() {
        return Err(Diagnostic::error(
            file,
            Pos::File,
            "MAP001",
            "no colour line: expected 'R G B' with values 0..255",
        ));
    }
    if let Some((off, t)) = clamped.first() {
        let more = match clamped.len() {
            1 => String::new(),
            n => format!(" (and {} more values above 255)", n - 1),
        };
        warnings.push(Diagnostic::warning(
            file,
            map.pos(*off),
            "MAP004",
            format!("value {t} is above 255; using 255{more}"),
        ));
    }
    if let Some(off) = first_extra {
        warnings.push(Diagnostic::warning(
            file,
            map.pos(off),
            "MAP005",
            format!(
                "a palette has at most 256 colours; the {extra_lines} colour line{} from here on {} ignored",
                if extra_lines == 1 { "" } else { "s" },
                if extra_lines == 1 { "is" } else { "are" }
            ),
        ));
    }
    Ok(Parsed {
        value: from_entries(name, &colors),
        warnings,
    })
}

/// A gradient from k map entries (k = 256: used directly; fewer: resampled for flames and kept
/// for the escape-time view).
pub fn from_entries(name: &str, colors: &[[u8; 3]]) -> Gradient {
    let k = colors.len();
    if k == 256 {
        return Gradient::from_rgb8(name, colors);
    }
    let f = |c: [u8; 3]| [c[0] as f64, c[1] as f64, c[2] as f64];
    let table: Vec<[f64; 3]> = (0..256)
        .map(|i| {
            if k == 1 {
                return f(colors[0]).map(|v| v / 255.0);
            }
            let t = i as f64 * (k - 1) as f64 / 255.0;
            let j = (t.floor() as usize).min(k - 2);
            let u = t - j as f64;
            let (a, b) = (f(colors[j]), f(colors[j + 1]));
            [
                (a[0] + (b[0] - a[0]) * u) / 255.0,
                (a[1] + (b[1] - a[1]) * u) / 255.0,
                (a[2] + (b[2] - a[2]) * u) / 255.0,
            ]
        })
        .collect();
    let mut g = Gradient::from_rgb(name, &table);
    g.map_entries = Some(colors.iter().map(|c| f(*c).map(|v| v / 255.0)).collect());
    g
}

/// Write a gradient as a 256-line `.map` (CRLF; the name as free text on line 1).
pub fn write(g: &Gradient) -> String {
    let mut s = String::new();
    for i in 0..256 {
        let [r, gg, b] = g.rgb8(i);
        let _ = write!(s, "{r:>3} {gg:>3} {b:>3}");
        if i == 0 && !g.name.is_empty() {
            let _ = write!(s, "  {}", g.name.replace(['\r', '\n'], " "));
        }
        s.push_str("\r\n");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_maps_keep_their_entries_and_resample() {
        let text = "0 0 0   The first line may carry a name\r\n252 252 252\r\n  0 0 252 ; blue\r\nThe end: notes follow\r\n1 2 3\r\n";
        let g = parse(text, "s.map", "s").unwrap().value;
        let e = g.map_entries.as_ref().unwrap();
        assert_eq!(e.len(), 3);
        assert_eq!(g.rgb8(0), [0, 0, 0]);
        assert_eq!(g.rgb8(255), [0, 0, 252]);
        // Position 127.5 of 255 is entry 1 (t = 0.996…) — nearly the grey.
        assert_eq!(g.rgb8(127), [251, 251, 251]);
    }

    #[test]
    fn full_maps_round_trip() {
        for g in crate::gradient::builtin() {
            let text = write(&g);
            assert_eq!(text.lines().count(), 256);
            let back = parse(&text, "w.map", &g.name).unwrap().value;
            assert_eq!(back.colors, g.colors, "{}", g.name);
            assert!(back.map_entries.is_none());
        }
        // More than 256 lines: the rest is ignored (chroma.map has 356), with a warning.
        let long: String = (0..356).map(|i| format!("{} 0 0\n", i % 256)).collect();
        let p = parse(&long, "l.map", "l").unwrap();
        assert_eq!(p.value.rgb8(255), [255, 0, 0]);
        assert_eq!(p.warnings.len(), 1);
        assert_eq!(p.warnings[0].code, "MAP005");
        assert_eq!(p.warnings[0].pos, Pos::LineCol(257, 1));
        assert!(
            p.warnings[0].message.contains("the 100 colour lines"),
            "{}",
            p.warnings[0]
        );
        let huge: String = (0..10_000).map(|i| format!("{} 0 0\n", i % 256)).collect();
        let p = parse(&huge, "l.map", "l").unwrap();
        assert!(
            p.warnings[0].message.contains("9744 colour lines"),
            "{}",
            p.warnings[0]
        );
    }

    #[test]
    fn values_above_255_are_clamped_with_a_warning() {
        // As gnofract4d writes them: one 256 among ordinary values.
        let p = parse("0 0 0\n1 256 3\n255 255 255\n", "g.map", "g").unwrap();
        assert_eq!(p.value.map_entries.as_ref().unwrap()[1][1], 1.0);
        assert_eq!(p.warnings.len(), 1);
        let w = &p.warnings[0];
        assert_eq!((w.code, w.pos.clone()), ("MAP004", Pos::LineCol(2, 3)));
        assert!(w.message.contains("256"), "{w}");
        let p = parse("256 256 256\n0 0 0\n", "g.map", "g").unwrap();
        assert!(
            p.warnings[0].message.contains("and 2 more"),
            "{}",
            p.warnings[0]
        );
    }

    #[test]
    fn bad_inputs() {
        assert_eq!(parse("hello\n", "a.map", "a").unwrap_err().code, "MAP001");
        assert_eq!(parse("", "a.map", "a").unwrap_err().code, "MAP001");
        let e = parse("0 0 0\n1 2.5 3\n", "a.map", "a").unwrap_err();
        assert_eq!((e.code, e.pos.clone()), ("MAP002", Pos::LineCol(2, 3)));
        assert_eq!(parse("0 0 -1\n", "a.map", "a").unwrap_err().code, "MAP002");
        assert_eq!(parse("0 0 1.5\n", "a.map", "a").unwrap_err().code, "MAP002");
        assert_eq!(parse("0 0\n", "a.map", "a").unwrap_err().code, "MAP002");
        assert_eq!(
            parse("0 0 0\n\0\n", "a.map", "a").unwrap_err().code,
            "MAP003"
        );
    }
}
