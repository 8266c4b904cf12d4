//! Ultra Fractal / Apophysis `.ugr` gradient files: several named gradients
//! per file, keys at positions 0..399 on a circle, colour = R + 256·G + 65536·B.

use std::fmt::Write as _;

use crate::gradient::{Gradient, Stop};
use crate::io::diag::{Diagnostic, Parsed, SourceMap, parse_int};

/// Sanity limit on gradients per file.
pub const MAX_GRADIENTS: usize = 10_000;

struct Key {
    index: i64,
    color: i64,
}

/// Parse the text of a `.ugr` file.
pub fn parse(text: &str, file: &str) -> Result<Parsed<Vec<Gradient>>, Diagnostic> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let rd = Reader {
        file,
        map: SourceMap::new(text),
    };
    let mut warnings = Vec::new();
    let mut out = Vec::new();
    let mut i = 0;
    while let Some(e) = rd.next_entry(text, &mut i)? {
        if e.name.contains("(3D)") {
            continue;
        }
        if out.len() >= MAX_GRADIENTS {
            return Err(rd.err(
                e.start,
                "UGR007",
                format!("more than {MAX_GRADIENTS} gradients"),
            ));
        }
        out.push(rd.gradient(&e, &mut warnings)?);
    }
    Ok(Parsed {
        value: out,
        warnings,
    })
}

/// Numbers with the offsets they were read at.
type Located = Vec<(i64, usize)>;

/// One `name { … }` entry of a `.ugr` file.
struct Entry<'t> {
    name: String,
    /// Offset of the header.
    start: usize,
    /// The text between the braces and its offset.
    body: &'t str,
    body_off: usize,
}

/// The reader of a `.ugr` file: the file and its positions.
struct Reader<'a> {
    file: &'a str,
    map: SourceMap<'a>,
}

impl Reader<'_> {
    fn err(&self, off: usize, code: &'static str, msg: String) -> Diagnostic {
        Diagnostic::error(self.file, self.map.pos(off), code, msg)
    }

    /// The next entry from byte `*i` on (skipping whitespace and `;` comments), None at the
    /// end of the text.
    fn next_entry<'t>(
        &self,
        text: &'t str,
        i: &mut usize,
    ) -> Result<Option<Entry<'t>>, Diagnostic> {
        let b = text.as_bytes();
        loop {
            while *i < b.len() && b[*i].is_ascii_whitespace() {
                *i += 1;
            }
            if *i >= b.len() {
                return Ok(None);
            }
            if b[*i] != b';' {
                break;
            }
            while *i < b.len() && b[*i] != b'\n' && b[*i] != b'\r' {
                *i += 1;
            }
        }
        // Header: name … "{" on the same line.
        let start = *i;
        let line_end = text[start..]
            .find(['\n', '\r'])
            .map_or(text.len(), |e| start + e);
        let header = &text[start..line_end];
        let Some(brace) = header.find('{') else {
            return Err(self.err(
                start,
                "UGR001",
                format!("expected 'name {{' on this line, found '{}'", header.trim()),
            ));
        };
        let name = header[..brace].trim().to_string();
        if name.is_empty() {
            return Err(self.err(
                start + brace,
                "UGR001",
                "'{' without a gradient name".into(),
            ));
        }
        let body_off = start + brace + 1;
        // Body up to the matching "}" (quoted strings may contain braces).
        let mut j = body_off;
        let mut in_quote = false;
        while j < b.len() && (in_quote || b[j] != b'}') {
            if b[j] == b'"' {
                in_quote = !in_quote;
            }
            j += 1;
        }
        if j >= b.len() {
            return Err(self.err(
                start,
                "UGR002",
                format!("gradient '{name}' has no closing '}}'"),
            ));
        }
        *i = j + 1;
        Ok(Some(Entry {
            name,
            start,
            body: &text[body_off..j],
            body_off,
        }))
    }

    /// The gradient of an entry: the index/color keys of its `gradient:` section.
    fn gradient(&self, e: &Entry, warnings: &mut Vec<Diagnostic>) -> Result<Gradient, Diagnostic> {
        let (name, start) = (&e.name, e.start);
        let (indices, colors) = self.keys(e)?;
        if indices.is_empty() || colors.is_empty() {
            return Err(self.err(
                start,
                "UGR004",
                format!("gradient '{name}' has no index/color pair"),
            ));
        }
        if indices.len() != colors.len() {
            return Err(self.err(
                start,
                "UGR005",
                format!(
                    "gradient '{name}' has {} index and {} color values",
                    indices.len(),
                    colors.len()
                ),
            ));
        }
        let outside: Vec<&(i64, usize)> = indices
            .iter()
            .filter(|(n, _)| !(0..400).contains(n))
            .collect();
        if let Some(&&(n, off)) = outside.first() {
            let more = match outside.len() {
                1 => String::new(),
                k => format!(" ({} more indices are outside too)", k - 1),
            };
            warnings.push(Diagnostic::warning(
                self.file,
                self.map.pos(off),
                "UGR009",
                format!(
                    "index {n} of gradient '{name}' is outside 0..399; taken modulo 400 ({}){more}",
                    n.rem_euclid(400)
                ),
            ));
        }
        let keys: Vec<Key> = indices
            .iter()
            .zip(&colors)
            .map(|(&(index, _), &(color, _))| Key { index, color })
            .collect();
        let (g, dup) = from_keys(name, &keys);
        if dup {
            warnings.push(Diagnostic::warning(
                self.file,
                self.map.pos(start),
                "UGR008",
                format!(
                    "gradient '{name}' has two keys at the same position; the later one is used"
                ),
            ));
        }
        Ok(g)
    }

    /// The `index=` and `color=` values of an entry's `gradient:` section (up to `opacity:`),
    /// with their offsets.
    fn keys(&self, e: &Entry) -> Result<(Located, Located), Diagnostic> {
        let Some(gpos) = e.body.find("gradient:") else {
            return Err(self.err(
                e.start,
                "UGR003",
                format!("gradient '{}' has no 'gradient:' section", e.name),
            ));
        };
        let section_end = e.body[gpos..]
            .find("opacity:")
            .map_or(e.body.len(), |o| gpos + o);
        let section = &e.body[gpos + "gradient:".len()..section_end];
        let sec_off = e.body_off + gpos + "gradient:".len();
        let mut indices: Located = Vec::new();
        let mut colors: Located = Vec::new();
        for (tok, off) in ugr_tokens(section, sec_off) {
            let Some((k, v)) = tok.split_once('=') else {
                continue;
            };
            match k.to_ascii_lowercase().as_str() {
                "index" => {
                    let n = parse_int(v).map_err(|_| {
                        self.err(off, "UGR006", format!("index '{v}' is not an integer"))
                    })?;
                    indices.push((n, off));
                }
                "color" => {
                    let n = parse_int(v).map_err(|_| {
                        self.err(off, "UGR006", format!("color '{v}' is not an integer"))
                    })?;
                    if !(0..=16_777_215).contains(&n) {
                        return Err(self.err(
                            off,
                            "UGR006",
                            format!("color {n} is outside 0..16777215"),
                        ));
                    }
                    colors.push((n, off));
                }
                _ => {}
            }
        }
        Ok((indices, colors))
    }
}

/// Whitespace-separated tokens with byte offsets; a `"…"` string stays in one token.
fn ugr_tokens(s: &str, base: usize) -> Vec<(&str, usize)> {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        while i < b.len() && b[i].is_ascii_whitespace() {
            i += 1;
        }
        if i >= b.len() {
            break;
        }
        let st = i;
        let mut q = false;
        while i < b.len() && (q || !b[i].is_ascii_whitespace()) {
            if b[i] == b'"' {
                q = !q;
            }
            i += 1;
        }
        out.push((&s[st..i], base + st));
    }
    out
}

fn rgb_of(c: i64) -> [f64; 3] {
    [
        (c % 256) as f64,
        ((c / 256) % 256) as f64,
        (c / 65536) as f64,
    ]
}

/// Build the 256-entry table from keys. Returns the gradient and whether a
/// duplicate slot was replaced.
fn from_keys(name: &str, keys: &[Key]) -> (Gradient, bool) {
    // slot j = round(I·255/399) of I mod 400; later duplicates replace earlier ones.
    let mut slots: Vec<(usize, [f64; 3])> = Vec::new();
    let mut dup = false;
    for k in keys {
        let i = k.index.rem_euclid(400);
        let j = ((i as f64) * 255.0 / 399.0).round() as usize;
        let rgb = rgb_of(k.color);
        if let Some(s) = slots.iter_mut().find(|s| s.0 == j) {
            s.1 = rgb;
            dup = true;
        } else {
            slots.push((j, rgb));
        }
    }
    slots.sort_by_key(|s| s.0);
    let mut table = [[0.0f64; 3]; 256];
    if slots.len() == 1 {
        table = [slots[0].1; 256];
    } else {
        // Consecutive keys, plus the wrap from the last key to the first (+256).
        for w in 0..slots.len() {
            let (j0, c0) = slots[w];
            let (j1, c1) = if w + 1 < slots.len() {
                slots[w + 1]
            } else {
                (slots[0].0 + 256, slots[0].1)
            };
            let span = (j1 - j0) as f64;
            for j in j0..j1 {
                let u = (j - j0) as f64 / span;
                let c = [
                    (c0[0] + (c1[0] - c0[0]) * u).round(),
                    (c0[1] + (c1[1] - c0[1]) * u).round(),
                    (c0[2] + (c1[2] - c0[2]) * u).round(),
                ];
                table[j % 256] = c;
            }
        }
    }
    let colors = table
        .iter()
        .map(|c| [c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, 1.0])
        .collect();
    let stops = slots
        .iter()
        .map(|(j, c)| Stop {
            pos: *j as f64 / 255.0,
            rgb: [c[0] / 255.0, c[1] / 255.0, c[2] / 255.0],
        })
        .collect();
    (
        Gradient {
            name: name.to_string(),
            colors,
            stops,
            map_entries: None,
        },
        dup,
    )
}

/// A gradient name as `.ugr` entry names allow (spaces → `_`).
pub fn sanitize_name(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_whitespace() || c == '{' || c == '}' || c == '"' {
                '_'
            } else {
                c
            }
        })
        .collect();
    if s.is_empty() { "gradient".into() } else { s }
}

/// Write gradients as a `.ugr` file: 256 keys at I = round(i·399/255), CRLF line ends.
pub fn write(gradients: &[Gradient]) -> String {
    let mut s = String::new();
    for (gi, g) in gradients.iter().enumerate() {
        if gi > 0 {
            s.push_str("\r\n");
        }
        let name = sanitize_name(&g.name);
        let _ = write!(
            s,
            "{name} {{\r\ngradient:\r\n title=\"{name}\" smooth=no\r\n"
        );
        for i in 0..256 {
            let [r, gg, b] = g.rgb8(i);
            let idx = ((i as f64) * 399.0 / 255.0).round() as i64;
            let c = r as i64 + 256 * gg as i64 + 65536 * b as i64;
            let _ = write!(s, " index={idx} color={c}\r\n");
        }
        s.push_str("}\r\n");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A hand-written file in the syntax Ultra Fractal and Apophysis write.
    const HAND: &str = "; gradients written by hand for the tests\r\n\
two-tone {\r\ngradient:\r\n title=\"two tone {braces}\" smooth=yes\r\n index=0 color=255\r\n index=399 color=16711680\r\nopacity:\r\n smooth=no index=0 opacity=255\r\n}\r\n\
\r\nwrapped {\ngradient:\n index=100 color=65280 index=300 color=255\n}\n\
\nflat {\ngradient:\n index=7 color=8421504\n}\n\
skip(3D) {\ngradient:\n index=0 color=0\n}\n";

    #[test]
    fn reads_keys_interpolates_and_wraps() {
        let p = parse(HAND, "hand.ugr").unwrap();
        let g = p.value;
        assert_eq!(g.len(), 3);
        assert_eq!(g[0].name, "two-tone");
        assert_eq!(g[0].rgb8(0), [255, 0, 0]);
        assert_eq!(g[0].rgb8(255), [0, 0, 255]);
        assert_eq!(g[0].rgb8(128), [127, 0, 128]);
        // Keys at slots 64 (I = 100) and 192 (I = 300): green and red, wrapping through 255 → 0.
        let w = &g[1];
        assert_eq!(w.rgb8(64), [0, 255, 0]);
        assert_eq!(w.rgb8(192), [255, 0, 0]);
        assert_eq!(w.rgb8(0), [128, 128, 0]);
        assert!(g[2].colors.iter().all(|c| c[0] == 128.0 / 255.0));
    }

    #[test]
    fn write_read_is_exact() {
        for g in crate::gradient::builtin() {
            let text = write(std::slice::from_ref(&g));
            let back = parse(&text, "w.ugr").unwrap().value.remove(0);
            assert_eq!(back.colors, g.colors, "{}", g.name);
            assert_eq!(back.name, sanitize_name(&g.name));
        }
    }

    #[test]
    fn bad_inputs() {
        let cases = [
            ("name\ngradient:\n}\n", "UGR001"),
            ("n {\ngradient:\n index=0 color=0\n", "UGR002"),
            ("n {\n index=0 color=0\n}\n", "UGR003"),
            ("n {\ngradient:\n title=\"x\"\n}\n", "UGR004"),
            ("n {\ngradient:\n index=0 color=0 index=4\n}\n", "UGR005"),
            ("n {\ngradient:\n index=0.5 color=0\n}\n", "UGR006"),
            ("n {\ngradient:\n index=0 color=16777216\n}\n", "UGR006"),
        ];
        for (src, code) in cases {
            assert_eq!(parse(src, "b.ugr").unwrap_err().code, code, "{src:?}");
        }
        let p = parse(
            "n {\ngradient:\n index=0 color=0 index=400 color=255\n}\n",
            "d.ugr",
        )
        .unwrap();
        assert!(p.warnings.iter().any(|w| w.code == "UGR008"));
    }

    #[test]
    fn indices_outside_the_circle_are_reduced_with_a_warning() {
        let p = parse(
            "n {\ngradient:\n index=-5 color=255 index=99999999999 color=65280\n}\n",
            "i.ugr",
        )
        .unwrap();
        // -5 → 395 (slot 252), 99999999999 → 399 (slot 255).
        assert_eq!(p.value[0].rgb8(252), [255, 0, 0]);
        assert_eq!(p.value[0].rgb8(255), [0, 255, 0]);
        let w: Vec<_> = p.warnings.iter().filter(|w| w.code == "UGR009").collect();
        assert_eq!(w.len(), 1);
        assert_eq!(w[0].pos, crate::io::diag::Pos::LineCol(3, 2));
        assert!(
            w[0].message.contains("index -5") && w[0].message.contains("(395)"),
            "{}",
            w[0]
        );
        assert!(w[0].message.contains("1 more"), "{}", w[0]);
        // Indices on the circle give no warning.
        let p = parse(
            "n {\ngradient:\n index=0 color=0 index=399 color=1\n}\n",
            "o.ugr",
        )
        .unwrap();
        assert!(p.warnings.is_empty());
    }
}
