//! GIMP `.ggr` gradients: a header line `GIMP Gradient`, an optional `Name: …` line, the
//! number of segments, then one segment a line:
//!
//! ```text
//! left middle right  r0 g0 b0 a0  r1 g1 b1 a1  [blend [coloring [left_type right_type]]]
//! ```
//!
//! Positions are in `[0, 1]` with left ≤ middle ≤ right; colours are RGBA in `[0, 1]`. Blend:
//! 0 linear, 1 curved, 2 sine, 3 sphere increasing, 4 sphere decreasing, 5 step. Colouring:
//! 0 RGB, 1 HSV counter-clockwise, 2 HSV clockwise. The optional endpoint types (GIMP 2.8+)
//! name foreground/background colours; ugnis has none and uses the stored colours (warning).
//!
//! Reading samples the 256 entries at x = i/255 (as every other ugnis gradient source), so
//! the ends of the file's range are the ends of the table. Writing emits 255 linear RGB
//! segments between consecutive entries, which reads back to the same table.

use std::fmt::Write as _;

use crate::gradient::{Gradient, hsv_to_rgb, rgb_to_hsv};
use crate::io::diag::{Diagnostic, Parsed, Pos, SourceMap, lines, parse_int, parse_number};

/// Sanity limit on segments per file (GIMP's own gradients have a few dozen).
pub const MAX_SEGMENTS: usize = 100_000;

/// How a segment's colour moves from its left to its right colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Blend {
    /// Piecewise linear, half way at the middle point.
    Linear,
    /// A power curve putting half way at the middle point.
    Curved,
    /// A sine ease in and out.
    Sine,
    /// A quarter circle rising fast at first.
    SphereIncreasing,
    /// A quarter circle rising slowly at first.
    SphereDecreasing,
    /// The left colour up to the middle point, then the right one.
    Step,
}

/// In which colour space the segment interpolates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Coloring {
    /// In RGB.
    Rgb,
    /// In HSV, the hue turning counter-clockwise.
    HsvCcw,
    /// In HSV, the hue turning clockwise.
    HsvCw,
}

/// One segment of a GIMP gradient.
#[derive(Clone, Debug, PartialEq)]
pub struct Segment {
    /// Left end, 0–1.
    pub left: f64,
    /// The middle point, between `left` and `right`.
    pub middle: f64,
    /// Right end, 0–1.
    pub right: f64,
    /// RGBA at the left end, 0–1.
    pub left_color: [f64; 4],
    /// RGBA at the right end, 0–1.
    pub right_color: [f64; 4],
    /// How the colour moves from left to right.
    pub blend: Blend,
    /// In which colour space.
    pub coloring: Coloring,
}

const EPS: f64 = 1e-10;
/// Half the quantum of the six decimals GIMP writes.
const SNAP: f64 = 5e-7;

impl Segment {
    /// Blend factor in `[0, 1]` at position `x` inside the segment.
    pub fn factor(&self, x: f64) -> f64 {
        let len = self.right - self.left;
        let (mid, pos) = if len < EPS {
            (0.5, 0.5)
        } else if (x - self.right).abs() <= SNAP {
            // Positions in files have six decimals: a sample within half a unit of the last
            // one of an end takes that end's colour exactly (writing what was read is then
            // byte-stable).
            ((self.middle - self.left) / len, 1.0)
        } else if (x - self.left).abs() <= SNAP {
            ((self.middle - self.left) / len, 0.0)
        } else {
            (
                (self.middle - self.left) / len,
                ((x - self.left) / len).clamp(0.0, 1.0),
            )
        };
        let linear = || {
            if pos <= mid {
                if mid < EPS { 0.0 } else { 0.5 * pos / mid }
            } else {
                let m = 1.0 - mid;
                if m < EPS {
                    1.0
                } else {
                    0.5 + 0.5 * (pos - mid) / m
                }
            }
        };
        match self.blend {
            Blend::Linear => linear(),
            Blend::Curved => pos.powf(0.5f64.ln() / mid.max(EPS).ln()),
            Blend::Sine => {
                let f = linear();
                ((std::f64::consts::PI * f - std::f64::consts::FRAC_PI_2).sin() + 1.0) / 2.0
            }
            Blend::SphereIncreasing => {
                let f = linear() - 1.0;
                (1.0 - f * f).max(0.0).sqrt()
            }
            Blend::SphereDecreasing => {
                let f = linear();
                1.0 - (1.0 - f * f).max(0.0).sqrt()
            }
            Blend::Step => {
                if pos >= mid {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }

    /// RGBA colour at position `x` inside the segment.
    pub fn color(&self, x: f64) -> [f64; 4] {
        let f = self.factor(x);
        let (l, r) = (self.left_color, self.right_color);
        let alpha = l[3] + (r[3] - l[3]) * f;
        let rgb = match self.coloring {
            Coloring::Rgb => [
                l[0] + (r[0] - l[0]) * f,
                l[1] + (r[1] - l[1]) * f,
                l[2] + (r[2] - l[2]) * f,
            ],
            Coloring::HsvCcw | Coloring::HsvCw => {
                // Hue in turns; counter-clockwise increases it, clockwise decreases it; equal
                // hues go once round the circle.
                let a = rgb_to_hsv([l[0], l[1], l[2]]);
                let b = rgb_to_hsv([r[0], r[1], r[2]]);
                let (ha, hb) = (a[0] / 6.0, b[0] / 6.0);
                let h = if self.coloring == Coloring::HsvCcw {
                    let d = if ha < hb { hb - ha } else { 1.0 - (ha - hb) };
                    (ha + d * f).rem_euclid(1.0)
                } else {
                    let d = if hb < ha { ha - hb } else { 1.0 - (hb - ha) };
                    (ha - d * f).rem_euclid(1.0)
                };
                hsv_to_rgb([6.0 * h, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f])
            }
        };
        [rgb[0], rgb[1], rgb[2], alpha].map(|v| v.clamp(0.0, 1.0))
    }
}

/// A parsed GIMP gradient: its name and segments.
#[derive(Clone, Debug, PartialEq)]
pub struct GimpGradient {
    /// The gradient's name.
    pub name: String,
    /// The segments, left to right.
    pub segments: Vec<Segment>,
}

impl GimpGradient {
    /// Colour at `x` in `[0, 1]`: the first segment whose right end is at or past `x`.
    pub fn color_at(&self, x: f64) -> [f64; 4] {
        let seg = self
            .segments
            .iter()
            .find(|s| x <= s.right + SNAP)
            .or(self.segments.last())
            .expect("a GIMP gradient has at least one segment");
        seg.color(x)
    }

    /// The 256-entry table, sampled at x = i/255.
    pub fn to_gradient(&self) -> Gradient {
        Gradient {
            name: self.name.clone(),
            colors: (0..Gradient::LEN)
                .map(|i| self.color_at(i as f64 / 255.0))
                .collect(),
            stops: Vec::new(),
            map_entries: None,
        }
    }
}

/// Parse the text of a `.ggr` file; `stem` names the gradient when the file has no `Name:`.
pub fn parse(text: &str, file: &str, stem: &str) -> Result<Parsed<Gradient>, Diagnostic> {
    let p = parse_segments(text, file, stem)?;
    Ok(Parsed {
        value: p.value.to_gradient(),
        warnings: p.warnings,
    })
}

/// Parse a `.ggr` file into its segments (exact, before sampling).
pub fn parse_segments(
    text: &str,
    file: &str,
    stem: &str,
) -> Result<Parsed<GimpGradient>, Diagnostic> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut rd = Reader {
        file,
        map: SourceMap::new(text),
        end: text.len(),
        warnings: Vec::new(),
        endpoint_warned: false,
    };
    // Blank lines are skipped everywhere; GIMP writes none, hand-edited files may have some.
    let mut rows = lines(text)
        .into_iter()
        .filter(|(_, l)| !l.trim().is_empty());
    let (name, count) = rd.header(&mut rows, stem)?;
    let mut segments = Vec::with_capacity(count.min(1024));
    for k in 0..count {
        let Some((off, line)) = rows.next() else {
            return Err(rd.err(
                rd.end,
                "GGR003",
                format!("file ends after {k} of {count} segments"),
            ));
        };
        segments.push(rd.segment(k, off, line)?);
    }
    if let Some((off, line)) = rows.next() {
        rd.warnings.push(Diagnostic::warning(
            file,
            rd.map.pos(off),
            "GGR007",
            format!(
                "text after the {count} segments is ignored: '{}'",
                clip(line.trim())
            ),
        ));
    }
    let gaps = segments
        .windows(2)
        .any(|w| (w[0].right - w[1].left).abs() > 1e-6);
    let first = segments[0].left;
    let last = segments[segments.len() - 1].right;
    if gaps || first > 1e-6 || last < 1.0 - 1e-6 {
        rd.warnings.push(Diagnostic::warning(
            file,
            Pos::File,
            "GGR008",
            "segments do not cover 0..1 without gaps; each position takes the next segment's colour",
        ));
    }
    Ok(Parsed {
        value: GimpGradient { name, segments },
        warnings: rd.warnings,
    })
}

/// The reader of a `.ggr` file: the file, its positions, the warnings so far.
struct Reader<'a> {
    file: &'a str,
    map: SourceMap<'a>,
    /// The text's length (where "file ends" errors point).
    end: usize,
    warnings: Vec<Diagnostic>,
    /// GGR006 is said once per file.
    endpoint_warned: bool,
}

impl Reader<'_> {
    fn err(&self, off: usize, code: &'static str, msg: String) -> Diagnostic {
        Diagnostic::error(self.file, self.map.pos(off), code, msg)
    }

    /// The header lines: `GIMP Gradient`, an optional `Name:` (else `stem`), the segment
    /// count.
    fn header<'t>(
        &self,
        rows: &mut impl Iterator<Item = (usize, &'t str)>,
        stem: &str,
    ) -> Result<(String, usize), Diagnostic> {
        let Some((h_off, header)) = rows.next() else {
            return Err(Diagnostic::error(
                self.file,
                Pos::File,
                "GGR001",
                "empty file; expected the header 'GIMP Gradient'",
            ));
        };
        // GIMP's development builds (2.99, 3.0 release candidates) write "LIGMA Gradient".
        if !matches!(header.trim(), "GIMP Gradient" | "LIGMA Gradient") {
            return Err(self.err(
                h_off,
                "GGR001",
                format!(
                    "expected the header 'GIMP Gradient', found '{}'",
                    clip(header.trim())
                ),
            ));
        }
        let Some((mut off, mut line)) = rows.next() else {
            return Err(self.err(
                self.end,
                "GGR002",
                "file ends after the header; expected the number of segments".into(),
            ));
        };
        let mut name = stem.to_string();
        if let Some(n) = line.trim_start().strip_prefix("Name:") {
            let n = n.trim();
            if !n.is_empty() {
                name = n.to_string();
            }
            (off, line) = rows.next().ok_or_else(|| {
                self.err(
                    self.end,
                    "GGR002",
                    "file ends after the name; expected the number of segments".into(),
                )
            })?;
        }
        let count_tok = line.trim();
        let count = parse_int(count_tok)
            .ok()
            .filter(|&n| n >= 1 && n as u64 <= MAX_SEGMENTS as u64)
            .ok_or_else(|| {
                self.err(
                    off + (line.len() - line.trim_start().len()),
                    "GGR002",
                    format!(
                        "'{}' is not a segment count; expected an integer 1..{MAX_SEGMENTS}",
                        clip(count_tok)
                    ),
                )
            })? as usize;
        Ok((name, count))
    }

    /// Segment `k` on the line at `off`: positions, two RGBA colours, then optional blend,
    /// colouring and endpoint colour types.
    fn segment(&mut self, k: usize, off: usize, line: &str) -> Result<Segment, Diagnostic> {
        let toks: Vec<(usize, &str)> = line
            .split_whitespace()
            .map(|t| (off + (t.as_ptr() as usize - line.as_ptr() as usize), t))
            .collect();
        if !(11..=15).contains(&toks.len()) {
            return Err(self.err(
                off,
                "GGR003",
                format!(
                    "segment {} has {} values; expected 'left middle right', two RGBA colours, \
                     then blend and colouring types (11 to 15 values)",
                    k + 1,
                    toks.len()
                ),
            ));
        }
        let mut v = [0f64; 11];
        for (slot, &(o, t)) in v.iter_mut().zip(&toks) {
            *slot = parse_number(t).map_err(|e| self.err(o, "GGR004", e.describe(t)))?;
        }
        let blend = match self.type_at(&toks, 11, 5, "blend")? {
            0 => Blend::Linear,
            1 => Blend::Curved,
            2 => Blend::Sine,
            3 => Blend::SphereIncreasing,
            4 => Blend::SphereDecreasing,
            _ => Blend::Step,
        };
        let coloring = match self.type_at(&toks, 12, 2, "colouring")? {
            0 => Coloring::Rgb,
            1 => Coloring::HsvCcw,
            _ => Coloring::HsvCw,
        };
        for i in [13, 14] {
            if self.type_at(&toks, i, 4, "endpoint colour")? != 0 && !self.endpoint_warned {
                self.endpoint_warned = true;
                self.warnings.push(Diagnostic::warning(
                    self.file,
                    self.map.pos(toks[i].0),
                    "GGR006",
                    "segment uses GIMP's foreground/background colour; the stored colour is used",
                ));
            }
        }
        let [l, m, r] = [v[0], v[1], v[2]];
        let in_unit = |x: f64| (-1e-6..=1.0 + 1e-6).contains(&x);
        if !(in_unit(l) && in_unit(m) && in_unit(r) && l <= m + 1e-6 && m <= r + 1e-6) {
            return Err(self.err(
                toks[0].0,
                "GGR004",
                format!(
                    "segment {} has positions {l} {m} {r}; expected 0 ≤ left ≤ middle ≤ right ≤ 1",
                    k + 1
                ),
            ));
        }
        let color = |c: &[f64]| -> Result<[f64; 4], Diagnostic> {
            if c.iter().any(|x| !in_unit(*x)) {
                return Err(self.err(
                    toks[3].0,
                    "GGR004",
                    format!("segment {} has a colour value outside 0..1", k + 1),
                ));
            }
            Ok([c[0], c[1], c[2], c[3]].map(|x| x.clamp(0.0, 1.0)))
        };
        Ok(Segment {
            left: l.clamp(0.0, 1.0),
            middle: m.clamp(l.clamp(0.0, 1.0), r.clamp(0.0, 1.0)),
            right: r.clamp(0.0, 1.0),
            left_color: color(&v[3..7])?,
            right_color: color(&v[7..11])?,
            blend,
            coloring,
        })
    }

    /// The type number at token `i` (0 when absent), from 0 to `max`.
    fn type_at(
        &self,
        toks: &[(usize, &str)],
        i: usize,
        max: i64,
        what: &str,
    ) -> Result<i64, Diagnostic> {
        match toks.get(i) {
            None => Ok(0),
            Some(&(o, t)) => parse_int(t)
                .ok()
                .filter(|n| (0..=max).contains(n))
                .ok_or_else(|| {
                    self.err(
                        o,
                        "GGR005",
                        format!("'{}' is not a {what} type; expected 0..{max}", clip(t)),
                    )
                }),
        }
    }
}

fn clip(s: &str) -> String {
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s.to_string()
    }
}

/// Write a gradient as a GIMP `.ggr`: 255 linear RGB segments joining consecutive entries
/// (LF line ends, six decimals, as GIMP writes).
pub fn write(g: &Gradient) -> String {
    let name: String = g
        .name
        .chars()
        .map(|c| if c == '\n' || c == '\r' { ' ' } else { c })
        .collect();
    let mut s = format!("GIMP Gradient\nName: {}\n255\n", name.trim());
    for i in 0..255 {
        let (l, r) = (i as f64 / 255.0, (i + 1) as f64 / 255.0);
        let _ = write!(s, "{l:.6} {:.6} {r:.6}", (l + r) / 2.0);
        for c in [g.colors[i], g.colors[i + 1]] {
            for v in c {
                let _ = write!(s, " {:.6}", v.clamp(0.0, 1.0));
            }
        }
        s.push_str(" 0 0 0 0\n");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Written by hand in the syntax GIMP 2.10 saves.
    const HAND: &str = "GIMP Gradient\nName: Sunrise test\n3\n\
0.000000 0.250000 0.500000 0.000000 0.000000 1.000000 1.000000 1.000000 0.000000 0.000000 1.000000 0 0 0 0\n\
0.500000 0.600000 0.700000 1.000000 0.000000 0.000000 1.000000 0.000000 1.000000 0.000000 0.500000 5 0 0 0\n\
0.700000 0.850000 1.000000 1.000000 0.000000 0.000000 1.000000 0.000000 0.000000 1.000000 1.000000 0 1 1 0\n";

    fn seg(blend: Blend, middle: f64) -> Segment {
        Segment {
            left: 0.0,
            middle,
            right: 1.0,
            left_color: [0.0, 0.0, 0.0, 1.0],
            right_color: [1.0, 1.0, 1.0, 1.0],
            blend,
            coloring: Coloring::Rgb,
        }
    }

    #[test]
    fn blend_factors() {
        // Every blend is 0 at the left end, 1 at the right end and 1/2 at the middle.
        for b in [
            Blend::Linear,
            Blend::Curved,
            Blend::Sine,
            Blend::SphereIncreasing,
            Blend::SphereDecreasing,
        ] {
            let s = seg(b, 0.3);
            assert!(s.factor(0.0).abs() < 1e-12, "{b:?}");
            assert!((s.factor(1.0) - 1.0).abs() < 1e-12, "{b:?}");
            let mid = s.factor(0.3);
            let want = match b {
                Blend::SphereIncreasing => 0.75f64.sqrt(),
                Blend::SphereDecreasing => 1.0 - 0.75f64.sqrt(),
                _ => 0.5,
            };
            assert!((mid - want).abs() < 1e-12, "{b:?}: {mid}");
        }
        // Linear with middle 0.3: halfway between the middle and the right end → 0.75.
        assert!((seg(Blend::Linear, 0.3).factor(0.65) - 0.75).abs() < 1e-12);
        // Curved: x^(ln ½ / ln m); with m = ½ it is the identity.
        assert!((seg(Blend::Curved, 0.5).factor(0.2) - 0.2).abs() < 1e-12);
        // Sine at a quarter of a linear ramp: (sin(−π/4) + 1)/2.
        let q = seg(Blend::Sine, 0.5).factor(0.25);
        assert!((q - (1.0 - 0.5f64.sqrt()) / 2.0).abs() < 1e-12);
        let st = seg(Blend::Step, 0.4);
        assert_eq!((st.factor(0.39), st.factor(0.4)), (0.0, 1.0));
    }

    #[test]
    fn hsv_interpolation_goes_round_the_requested_way() {
        // Red (hue 0) to blue (hue 2/3): counter-clockwise passes green, clockwise magenta.
        let mut s = seg(Blend::Linear, 0.5);
        s.left_color = [1.0, 0.0, 0.0, 1.0];
        s.right_color = [0.0, 0.0, 1.0, 1.0];
        s.coloring = Coloring::HsvCcw;
        let c = s.color(0.5); // hue 1/3: green
        assert!((c[0]).abs() < 1e-9 && (c[1] - 1.0).abs() < 1e-9 && c[2].abs() < 1e-9);
        s.coloring = Coloring::HsvCw;
        let c = s.color(0.5); // hue 5/6: magenta
        assert!((c[0] - 1.0).abs() < 1e-9 && c[1].abs() < 1e-9 && (c[2] - 1.0).abs() < 1e-9);
        // Red to red goes once round (GIMP's "Full saturation spectrum"): a third of the way
        // is green counter-clockwise and blue clockwise.
        s.right_color = s.left_color;
        s.coloring = Coloring::HsvCcw;
        let c = s.color(1.0 / 3.0);
        assert!(c[0].abs() < 1e-9 && (c[1] - 1.0).abs() < 1e-9 && c[2].abs() < 1e-9);
        s.coloring = Coloring::HsvCw;
        let c = s.color(1.0 / 3.0);
        assert!(c[0].abs() < 1e-9 && c[1].abs() < 1e-9 && (c[2] - 1.0).abs() < 1e-9);
    }

    #[test]
    fn reads_a_gimp_file() {
        let p = parse(HAND, "hand.ggr", "hand").unwrap();
        let g = p.value;
        assert_eq!(g.name, "Sunrise test");
        assert_eq!(g.colors.len(), 256);
        // x = 0: blue, opaque.
        assert_eq!(g.colors[0], [0.0, 0.0, 1.0, 1.0]);
        // Entry 64 (x = 0.25098): just past the middle of segment 1, factor ≈ 0.504.
        let f = 0.5 + 0.5 * (64.0 / 255.0 - 0.25) / 0.25;
        let c = g.colors[64];
        assert!((c[0] - f).abs() < 1e-9 && (c[2] - (1.0 - f)).abs() < 1e-9);
        assert_eq!(c[3], 1.0);
        // The step segment's right colour has alpha ½.
        assert_eq!(g.colors[160][3], 0.5);
        // Step segment (0.5..0.7, middle 0.6): red before the middle, green from it on.
        assert_eq!(g.rgb8(140), [255, 0, 0]); // x = 0.549
        assert_eq!(g.rgb8(160), [0, 255, 0]); // x = 0.627
        // Last segment, HSV counter-clockwise red → blue: green in the middle.
        let c = g.colors[(0.85f64 * 255.0).round() as usize];
        assert!(c[1] > 0.9 && c[0] < 0.2 && c[2] < 0.2, "{c:?}");
        assert_eq!(g.rgb8(255), [0, 0, 255]);
        // The foreground-colour endpoint type is reported, not silently dropped.
        assert!(p.warnings.iter().any(|w| w.code == "GGR006"));
    }

    #[test]
    fn development_builds_header_is_read() {
        let ligma = HAND.replacen("GIMP Gradient", "LIGMA Gradient", 1);
        assert_ne!(ligma, HAND);
        let a = parse(HAND, "hand.ggr", "hand").unwrap();
        let b = parse(&ligma, "hand.ggr", "hand").unwrap();
        assert_eq!(b.value, a.value);
        assert_eq!(b.warnings, a.warnings, "no warning of its own");
    }

    #[test]
    fn write_then_read_is_the_same_table() {
        let g = crate::gradient::builtin()[3].clone();
        let text = write(&g);
        let back = parse(&text, "x.ggr", "x").unwrap();
        assert!(back.warnings.is_empty(), "{:?}", back.warnings);
        assert_eq!(back.value.name, g.name);
        for i in 0..256 {
            for k in 0..4 {
                assert!(
                    (back.value.colors[i][k] - g.colors[i][k]).abs() < 1e-5,
                    "entry {i}"
                );
            }
        }
        // Writing what was read gives the same bytes.
        assert_eq!(write(&back.value), text);
    }

    #[test]
    fn bad_files_name_line_and_expectation() {
        let e = parse("GIMP Palette\n", "p.ggr", "p").unwrap_err();
        assert_eq!((e.code, e.line()), ("GGR001", Some(1)));
        let e = parse("GIMP Gradient\nName: x\nmany\n", "p.ggr", "p").unwrap_err();
        assert_eq!((e.code, e.line()), ("GGR002", Some(3)));
        let e = parse(
            "GIMP Gradient\n2\n0 0.5 1 0 0 0 1 1 1 1 1 0 0\n",
            "p.ggr",
            "p",
        )
        .unwrap_err();
        assert_eq!((e.code, e.line()), ("GGR003", Some(4)));
        assert!(e.message.contains("1 of 2"), "{}", e.message);
        let e = parse("GIMP Gradient\n1\n0 0.5 1 0 0 0 1 1 1 1\n", "p.ggr", "p").unwrap_err();
        assert_eq!((e.code, e.line()), ("GGR003", Some(3)));
        let e = parse(
            "GIMP Gradient\n1\n0 0.5 1 0 0 nan 1 1 1 1 1\n",
            "p.ggr",
            "p",
        )
        .unwrap_err();
        assert_eq!(e.code, "GGR004");
        assert_eq!(e.pos, Pos::LineCol(3, 13));
        let e = parse(
            "GIMP Gradient\n1\n0.6 0.5 1 0 0 0 1 1 1 1 1\n",
            "p.ggr",
            "p",
        )
        .unwrap_err();
        assert_eq!(e.code, "GGR004");
        let e = parse(
            "GIMP Gradient\n1\n0 0.5 1 0 0 0 1 1 1 1 1 9 0\n",
            "p.ggr",
            "p",
        )
        .unwrap_err();
        assert_eq!((e.code, e.pos.clone()), ("GGR005", Pos::LineCol(3, 25)));
        // Eleven values (no types) are a linear RGB segment; the stem names the gradient.
        let p = parse("GIMP Gradient\n1\n0 0.5 1 0 0 0 1 1 1 1 1\n", "p.ggr", "p").unwrap();
        assert_eq!(p.value.name, "p");
        assert_eq!(p.value.rgb8(255), [255, 255, 255]);
    }
}
