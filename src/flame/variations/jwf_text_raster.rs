//! The image `text_wf` samples: one line of text drawn, without anti-aliasing, the way a Java VM
//! draws it into the image JWildfire 9.00's `TextWFFunc` builds (through its `TextTransformer`).
//!
//! Font: JWildfire's default font name is "Arial"; a Java VM on a Linux system without Arial
//! (OpenJDK 17 on Debian 12, for instance) falls back to its logical font Dialog, whose Latin
//! glyphs come from DejaVu Sans. ugnis bundles DejaVu Sans (`fonts/`, Bitstream Vera licence)
//! and uses it for every font name, so a flame renders the same on every machine.
//!
//! Metrics, as Java 2D reports them for a TrueType font scaled by FreeType (OpenJDK's
//! `freetypeScaler.c`): the scale is FreeType's 16.16 `size·64 / units_per_em`; the ascent,
//! descent and leading are the `hhea` values times that scale (not rounded); a glyph's advance
//! without fractional metrics is its scaled advance rounded to a whole pixel; the integer ascent
//! `FontMetrics.getMaxAscent()` is ⌊ascent + 0.95⌋. JWildfire's `TextTransformer` sizes the text
//! with `Font.getStringBounds`: width = the sum of the advances, height = ascent + descent +
//! leading, each rounded half up to an integer, plus the baseline offset for the height. The
//! image is that size plus twice the font size in each direction, the text is centred in it
//! (integer halves) and drawn with its baseline `getMaxAscent()` below its box's top.
//!
//! Drawing: glyphs taller than 100 pixels are drawn by Java 2D as filled outlines
//! (`OutlineTextRenderer`): FreeType's unhinted outline, points rounded to 1/64 pixel, filled
//! non-zero by `ProcessPath.c`'s scan converter, which with the default stroke control lights
//! pixel (column, row) when the point (column, row) itself (the pixel's corner, not its
//! centre) is inside, edges being half-open at their lower end and spans at their right end.
//! Smaller glyphs are drawn by Java from FreeType's hinted monochrome bitmaps; ugnis fills the
//! outlines for those too, which can differ from Java along the edges.
//!
//! Kerning is not applied (Java's default text drawing does not apply it either).

use skrifa::instance::{LocationRef, Size};
use skrifa::outline::{DrawSettings, Engine, HintingInstance, HintingOptions, OutlinePen, Target};
use skrifa::raw::TableProvider;
use skrifa::{FontRef, GlyphId, MetadataProvider};

/// DejaVu Sans 2.37 (see the module documentation and `fonts/LICENSE-DejaVu.txt`).
const DEJAVU_SANS: &[u8] = include_bytes!("../../../fonts/DejaVuSans.ttf");

/// Most characters of a text laid out (longer texts are cut).
const MAX_CHARS: usize = 2000;

/// The lit pixels of `text` drawn at `size` pixels with the baseline moved down by `baseline`
/// pixels, as points relative to the image: x = (column − W/2)/W, y = (row − H/2)/H for the
/// image's width W and height H, row by row. When the image has more than `max_pixels`
/// pixels, it is sampled on a coarser grid with the same proportions (the pixel budget then
/// bounds the number of points). Empty when nothing is drawn.
pub(super) fn text_points(text: &str, size: i64, baseline: i64, max_pixels: f64) -> Vec<f64> {
    let Some(image) = layout(text, size, baseline, max_pixels) else {
        return Vec::new();
    };
    let (w, h, k) = (image.width as f64, image.height as f64, image.k);
    let (cols, rows) = ((w * k).ceil() as usize, (h * k).ceil() as usize);
    let mut out = Vec::new();
    fill(&image.edges, k, cols, rows, |c, r| {
        let (x, y) = (c as f64 / k, r as f64 / k);
        if x < w && y < h {
            out.push((x - w / 2.0) / w);
            out.push((y - h / 2.0) / h);
        }
    });
    out
}

/// The drawn text: the image size and the outline edges in its pixels.
struct TextImage {
    width: i64,
    height: i64,
    /// Sampling step k ≤ 1 within `max_pixels`: the grid's points are (c/k, r/k) in pixels.
    k: f64,
    edges: Vec<[f64; 4]>,
}

/// FreeType's `FT_DivFix` for positive operands: a/b in 16.16.
fn div_fix(a: i64, b: i64) -> i64 {
    (a * 65536 + b / 2) / b
}

/// Lays the text out as Java and JWildfire do (module documentation). `None` when the image
/// would be empty or the text draws nothing.
fn layout(text: &str, size: i64, baseline: i64, max_pixels: f64) -> Option<TextImage> {
    let font = FontRef::new(DEJAVU_SANS).ok()?;
    let upem = i64::from(font.head().ok()?.units_per_em()).max(1);
    let hhea = font.hhea().ok()?;
    let (asc_u, desc_u, gap_u) = (
        f32::from(hhea.ascender().to_i16()),
        f32::from(hhea.descender().to_i16()),
        f32::from(hhea.line_gap().to_i16()),
    );
    let size = size.clamp(1, 100_000);
    let baseline = baseline.clamp(-1_000_000, 1_000_000);
    // Pixels per font unit, in FreeType's 16.16 (`FT_Set_Char_Size` at 72 dpi).
    let scale = div_fix(size * 64, upem);
    let px = |units: f32| units * scale as f32 / 65536.0 / 64.0;
    let ascent = px(asc_u);
    let descent = -px(desc_u);
    let leading = px(asc_u - desc_u + gap_u) - ascent - descent;
    let max_ascent = (ascent + 0.95) as i64;

    let charmap = font.charmap();
    let unscaled = Size::unscaled();
    let metrics = font.glyph_metrics(unscaled, LocationRef::default());
    let glyphs: Vec<_> = text
        .chars()
        .filter(|c| !c.is_control())
        .take(MAX_CHARS)
        .map(|c| charmap.map(c).unwrap_or_default())
        .collect();
    if glyphs.is_empty() {
        return None;
    }
    // Whole-pixel advances: FreeType's advance for a hinted monochrome glyph (Java loads its
    // glyphs with `FT_LOAD_TARGET_MONO`), where the TrueType instructions may move the advance;
    // without hinting, the scaled advance rounded.
    let outlines = font.outline_glyphs();
    let hinting = HintingInstance::new(
        &outlines,
        Size::new(size as f32),
        LocationRef::default(),
        HintingOptions {
            engine: Engine::Interpreter,
            target: Target::Mono,
        },
    )
    .ok();
    let mut cache: Vec<(GlyphId, i64)> = Vec::new();
    let mut advances = Vec::with_capacity(glyphs.len());
    for &g in &glyphs {
        let adv = match cache.iter().find(|c| c.0 == g) {
            Some(&(_, a)) => a,
            None => {
                let hinted = hinting.as_ref().and_then(|h| {
                    let glyph = outlines.get(g)?;
                    let m = glyph
                        .draw(DrawSettings::hinted(h, false), &mut NoPen)
                        .ok()?;
                    m.advance_width
                });
                let a = match hinted {
                    Some(a) if a.is_finite() => a.round() as i64,
                    _ => {
                        let units = metrics.advance_width(g).unwrap_or(0.0) as f64;
                        let a26 = (units * scale as f64 / 65536.0).round() as i64;
                        (a26 + 32).div_euclid(64)
                    }
                };
                cache.push((g, a));
                a
            }
        };
        advances.push(adv);
    }
    let text_w: i64 = advances.iter().sum();
    let text_h = (f64::from(ascent + descent + leading) + 0.5) as i64 + baseline;
    let (width, height) = (text_w + 2 * size, text_h + 2 * size);
    if width <= 0 || height <= 0 {
        return None;
    }
    let left = (width - text_w) / 2;
    let top = (height - text_h) / 2 + baseline;

    let k = (max_pixels.max(1.0) / (width as f64 * height as f64))
        .sqrt()
        .min(1.0);
    let mut pen = Edges {
        scale: scale as f64 / 65536.0,
        flatness: FLATNESS / k,
        ..Edges::default()
    };
    let mut pen_x = left;
    for (&g, &adv) in glyphs.iter().zip(&advances) {
        if let Some(glyph) = outlines.get(g) {
            pen.origin = (pen_x as f64, (top + max_ascent) as f64);
            let settings = DrawSettings::unhinted(unscaled, LocationRef::default());
            let _ = glyph.draw(settings, &mut pen);
            pen.close();
        }
        pen_x += adv;
    }
    Some(TextImage {
        width,
        height,
        k,
        edges: pen.lines,
    })
}

/// Calls `lit(column, row)`, row by row, for every grid point (column/k, row/k) inside the
/// outlines (non-zero winding), for columns below `cols` and rows below `rows`. An edge counts
/// on the rows from its upper end (included) to its lower end (excluded); a span lights the
/// columns from its left crossing (included) to its right one (excluded).
fn fill(edges: &[[f64; 4]], k: f64, cols: usize, rows: usize, mut lit: impl FnMut(usize, usize)) {
    // Edges as (y_top, y_bottom, x at y_top, dx/dy, winding), in grid units, by y_top.
    let mut sorted: Vec<(f64, f64, f64, f64, i32)> = edges
        .iter()
        .filter_map(|&[x0, y0, x1, y1]| {
            let (x0, y0, x1, y1) = (x0 * k, y0 * k, x1 * k, y1 * k);
            if !(y0 != y1 && x0.is_finite() && x1.is_finite() && y0.is_finite() && y1.is_finite()) {
                return None;
            }
            let slope = (x1 - x0) / (y1 - y0);
            Some(if y0 < y1 {
                (y0, y1, x0, slope, 1)
            } else {
                (y1, y0, x1, slope, -1)
            })
        })
        .collect();
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut next = 0;
    let mut active: Vec<usize> = Vec::new();
    let mut cross: Vec<(f64, i32)> = Vec::new();
    for row in 0..rows {
        let y = row as f64;
        while next < sorted.len() && sorted[next].0 <= y {
            active.push(next);
            next += 1;
        }
        active.retain(|&i| sorted[i].1 > y);
        cross.clear();
        for &i in &active {
            let (top, _, x, slope, dir) = sorted[i];
            if top <= y {
                cross.push((x + (y - top) * slope, dir));
            }
        }
        cross.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut wind = 0;
        for pair in cross.windows(2) {
            wind += pair[0].1;
            if wind == 0 {
                continue;
            }
            let c0 = pair[0].0.ceil().clamp(0.0, cols as f64) as usize;
            let c1 = pair[1].0.ceil().clamp(0.0, cols as f64) as usize;
            for col in c0..c1 {
                lit(col, row);
            }
        }
    }
}

/// A pen that draws nothing (for a glyph's hinted metrics).
struct NoPen;

impl OutlinePen for NoPen {
    fn move_to(&mut self, _: f32, _: f32) {}
    fn line_to(&mut self, _: f32, _: f32) {}
    fn quad_to(&mut self, _: f32, _: f32, _: f32, _: f32) {}
    fn curve_to(&mut self, _: f32, _: f32, _: f32, _: f32, _: f32, _: f32) {}
    fn close(&mut self) {}
}

/// Outline edges in image pixels (y down), from glyph outlines in font units.
#[derive(Default)]
struct Edges {
    /// (x0, y0, x1, y1) per edge.
    lines: Vec<[f64; 4]>,
    /// Pen position of the glyph on the baseline.
    origin: (f64, f64),
    /// Pixels per font unit times 64 (FreeType's 26.6 scale).
    scale: f64,
    /// Largest distance allowed between a flattened curve and the curve, in pixels.
    flatness: f64,
    start: (f64, f64),
    at: (f64, f64),
}

/// Largest distance allowed between a flattened curve and the curve, in sampling steps.
const FLATNESS: f64 = 0.02;

impl Edges {
    /// A point in font units to image pixels, rounded to 1/64 pixel as FreeType scales it.
    fn to_image(&self, x: f32, y: f32) -> (f64, f64) {
        let q = |v: f32| (v as f64 * self.scale).round() / 64.0;
        (self.origin.0 + q(x), self.origin.1 - q(y))
    }

    fn segment(&mut self, to: (f64, f64)) {
        if to.1 != self.at.1 {
            self.lines.push([self.at.0, self.at.1, to.0, to.1]);
        }
        self.at = to;
    }

    /// Number of line segments that keep a curve with the given second differences within
    /// the flatness (at most 256).
    fn steps(&self, dd: f64) -> usize {
        // A curve's distance to its chords is at most |second difference|·(1/n)²/8 per step.
        let n = (dd / (8.0 * self.flatness)).sqrt().ceil();
        if n.is_finite() {
            n.clamp(1.0, 256.0) as usize
        } else {
            1
        }
    }
}

impl OutlinePen for Edges {
    fn move_to(&mut self, x: f32, y: f32) {
        self.close();
        let p = self.to_image(x, y);
        self.start = p;
        self.at = p;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let p = self.to_image(x, y);
        self.segment(p);
    }

    fn quad_to(&mut self, cx0: f32, cy0: f32, x: f32, y: f32) {
        let (a, c, b) = (self.at, self.to_image(cx0, cy0), self.to_image(x, y));
        let dd = (a.0 - 2.0 * c.0 + b.0).hypot(a.1 - 2.0 * c.1 + b.1) * 2.0;
        let n = self.steps(dd);
        for i in 1..=n {
            let t = i as f64 / n as f64;
            let u = 1.0 - t;
            let q = (
                u * u * a.0 + 2.0 * u * t * c.0 + t * t * b.0,
                u * u * a.1 + 2.0 * u * t * c.1 + t * t * b.1,
            );
            self.segment(q);
        }
    }

    fn curve_to(&mut self, cx0: f32, cy0: f32, cx1: f32, cy1: f32, x: f32, y: f32) {
        let a = self.at;
        let (c0, c1, b) = (
            self.to_image(cx0, cy0),
            self.to_image(cx1, cy1),
            self.to_image(x, y),
        );
        let d0 = (a.0 - 2.0 * c0.0 + c1.0).hypot(a.1 - 2.0 * c0.1 + c1.1);
        let d1 = (c0.0 - 2.0 * c1.0 + b.0).hypot(c0.1 - 2.0 * c1.1 + b.1);
        let n = self.steps(6.0 * d0.max(d1));
        for i in 1..=n {
            let t = i as f64 / n as f64;
            let u = 1.0 - t;
            let (k0, k1, k2, k3) = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t);
            let q = (
                k0 * a.0 + k1 * c0.0 + k2 * c1.0 + k3 * b.0,
                k0 * a.1 + k1 * c0.1 + k2 * c1.1 + k3 * b.1,
            );
            self.segment(q);
        }
    }

    fn close(&mut self) {
        let s = self.start;
        self.segment(s);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Java 2D's layout of JWildfire's default text (OpenJDK 17, Dialog → DejaVu Sans, 320
    /// pixels, no fractional metrics): the glyph advances 94 316 89 89 203 113 89 132 197, a
    /// 1322 × 373 text box (ascent 297.03125, descent 75.46875) and so a 1962 × 1013 image.
    #[test]
    fn default_text_is_laid_out_as_java_does() {
        let image = layout("JWildfire", 320, 0, 4.0e6).expect("drawn");
        assert_eq!((image.width, image.height), (1962, 1013));
        // The J's stem starts 201 font units (31.40625 px) right of the pen at x = 320, its
        // top is 1493 units (233.28125 px) above the baseline at y = 320 + 297.
        let left = image
            .edges
            .iter()
            .map(|e| e[0].min(e[2]))
            .fold(f64::INFINITY, f64::min);
        let top = image
            .edges
            .iter()
            .map(|e| e[1].min(e[3]))
            .fold(f64::INFINITY, f64::min);
        assert!((left - (320.0 - 16.5625)).abs() < 1e-9, "{left}");
        assert!((top - (617.0 - 243.125)).abs() < 1e-9, "{top}");
        // With baseline 10 the image is 10 pixels taller and the text 10 pixels lower.
        let moved = layout("JWildfire", 320, 10, 4.0e6).expect("drawn");
        assert_eq!((moved.width, moved.height), (1962, 1023));
    }

    /// Java's hinted advances differ from the rounded scaled ones for some glyphs: "AVWXYK" at
    /// 320 pixels is 1379 pixels wide in Java (its rounded unhinted advances sum to 1377).
    #[test]
    fn advances_are_hinted_like_java() {
        let image = layout("AVWXYK", 320, 0, 4.0e6).expect("drawn");
        assert_eq!(image.width, 1379 + 640);
        let image = layout("AVWXYK", 321, 0, 4.0e6).expect("drawn");
        assert_eq!(image.width, 1384 + 642);
    }

    /// Java lights 101154 pixels for "JWildfire" at 320 pixels; the fill here agrees but for a
    /// few hundred edge pixels where curves are flattened differently.
    #[test]
    fn lit_pixels_match_java_closely() {
        let n = text_points("JWildfire", 320, 0, 4.0e6).len() / 2;
        assert!(n.abs_diff(101_154) < 400, "{n}");
        let n = text_points("HILTEFZ", 320, 0, 4.0e6).len() / 2;
        assert!(n.abs_diff(92_400) < 30, "{n}");
        assert!(text_points("", 320, 0, 4.0e6).is_empty());
        assert!(text_points("   ", 320, 0, 4.0e6).is_empty());
    }

    /// A huge text is sampled within the pixel budget with the same proportions.
    #[test]
    fn pixel_budget_bounds_the_points() {
        let full = text_points("JWildfire", 320, 0, 4.0e6);
        let coarse = text_points("JWildfire", 320, 0, 4.0e5);
        let (nf, nc) = (full.len() / 2, coarse.len() / 2);
        assert!(
            nc < 400_000 && (nc as f64 / nf as f64 - 0.2).abs() < 0.02,
            "{nf} {nc}"
        );
        let mean = |p: &[f64]| p.iter().step_by(2).sum::<f64>() / (p.len() / 2) as f64;
        assert!((mean(&full) - mean(&coarse)).abs() < 0.003);
        let long = "flame ".repeat(400);
        let big = text_points(&long, 4000, 0, 4.0e6);
        assert!(
            big.len() / 2 < 4_000_000 && big.len() > 1000,
            "{}",
            big.len()
        );
    }
}
