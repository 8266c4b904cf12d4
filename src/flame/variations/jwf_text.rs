//! `text_wf`, JWildfire's text variation: a blur whose points lie on a line of text.
//!
//! JWildfire draws the text, without anti-aliasing, centred in an image that leaves one font
//! size of margin on each side, and keeps every lit pixel as a point: x = (column − W/2)/W,
//! y = (row − H/2)/H for the image's width W and height H (rows go down, as y does in a flame).
//! Each sample picks one of those points, moves it by a small random amount (`antialias`) and
//! scales it: (x·scale_x + offset_x)·3, (y·scale_y + offset_y)·3. The weight does not scale it.
//!
//! JWildfire uses the font named by `font_name` from the system. ugnis draws every font name
//! with one bundled sans-serif (Ubuntu Light, the editor's own font), so that a flame renders
//! the same on every machine; the letters' proportions differ a little from those of, say,
//! Arial. Kerning is not applied (Java's default text drawing does not apply it either).

use std::f64::consts::PI;

use skrifa::instance::{LocationRef, Size};
use skrifa::outline::{DrawSettings, OutlinePen};
use skrifa::{FontRef, MetadataProvider};

use super::*;

/// Most pixels of the image the text is drawn into: larger font sizes or longer texts are
/// drawn at a lower resolution with the same proportions (the points are relative to the
/// image), so the memory they take stays below 16 bytes × this.
const MAX_PIXELS: f64 = 4.0e6;

/// Most bytes of text drawn.
const MAX_TEXT: usize = 1000;

const TEXTS: &[TextParam] = &[
    TextParam {
        name: "text_wf_text",
        default: "JWildfire",
        max_len: MAX_TEXT,
    },
    TextParam {
        name: "text_wf_font_name",
        default: "Arial",
        max_len: 200,
    },
];

pub(super) static DEFS: &[VarDef] = &[VarDef::new("text_wf", text_wf)
    .params(&[
        p_int("text_wf_font_size", 320.0, 1.0, 4000.0),
        p("text_wf_antialias", 0.5),
        p("text_wf_scale_x", 1.0),
        p("text_wf_scale_y", 1.0),
        p("text_wf_offset_x", 0.0),
        p("text_wf_offset_y", 0.0),
        p_int("text_wf_baseline", 0.0, -100_000.0, 100_000.0),
    ])
    .texts(TEXTS)
    .flags(flag::JWILDFIRE | flag::RANDOM)
    .sum()
    .shared(&[0, 6], text_points)];

/// text_wf: a random point of the drawn text.
fn text_wf(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, aa, scale_x, scale_y, offset_x, offset_y] = v.params();
    const SCALE: f64 = 3.0;
    let pts = v.data();
    let n = pts.len() / 2;
    if n <= 1 {
        // Nothing drawn (an empty text): JWildfire scatters the points over a unit square.
        return [rng.f01(), rng.f01(), 0.0];
    }
    let k = rng.below(n as u64) as usize;
    let (mut x, mut y) = (pts[2 * k], pts[2 * k + 1]);
    if aa > 0.01 {
        let dr = ((aa * (-rng.f01().max(f64::MIN_POSITIVE).ln()).sqrt()).exp() - 1.0) * 0.001;
        let da = rng.f01() * 2.0 * PI;
        x += dr * da.cos();
        y += dr * da.sin();
    }
    [
        (x * scale_x + offset_x) * SCALE,
        (y * scale_y + offset_y) * SCALE,
        0.0,
    ]
}

/// The drawn text's points, x and y interleaved (see the module documentation). Built once per
/// text, font size and baseline ([`super::shared`]).
fn text_points(p: &[f64], texts: &[String]) -> Vec<f64> {
    let text = texts.first().map_or("", |t| t.as_str());
    let [font_size, _, _, _, _, _, baseline] = params_of(p);
    let font_size = font_size.max(1.0);
    let Ok(font) = FontRef::new(epaint_default_fonts::UBUNTU_LIGHT) else {
        return Vec::new();
    };
    // Lay the text out at one pixel per em unit of the font size, then scale it to fit.
    let unit = Size::new(1.0);
    let charmap = font.charmap();
    let gm = font.glyph_metrics(unit, LocationRef::default());
    let m = font.metrics(unit, LocationRef::default());
    let (ascent, descent) = (m.ascent as f64, -(m.descent as f64));
    let glyphs: Vec<_> = text
        .chars()
        .filter(|c| !c.is_control())
        .map(|c| charmap.map(c).unwrap_or_default())
        .collect();
    let advance: f64 = glyphs
        .iter()
        .map(|&g| gm.advance_width(g).unwrap_or(0.0) as f64)
        .sum();
    // Image size in em: the text plus one font size of margin on each side.
    let (w_em, h_em) = (advance + 2.0, ascent + descent + 2.0);
    let px = font_size.min((MAX_PIXELS / (w_em * h_em)).sqrt()).max(1.0);
    let (w, h) = ((w_em * px).ceil() as usize, (h_em * px).ceil() as usize);
    // The text box centred; `baseline` moves it down by that many pixels of the font size.
    let x0 = (w as f64 - advance * px) / 2.0;
    let base = (h as f64 - (ascent + descent) * px) / 2.0 + ascent * px + baseline * px / font_size;
    let mut edges = Edges::default();
    let outlines = font.outline_glyphs();
    let mut pen_x = x0;
    for &g in &glyphs {
        if let Some(glyph) = outlines.get(g) {
            edges.origin = (pen_x, base);
            edges.scale = px;
            let settings = DrawSettings::unhinted(unit, LocationRef::default());
            let _ = glyph.draw(settings, &mut edges);
            edges.close();
        }
        pen_x += gm.advance_width(g).unwrap_or(0.0) as f64 * px;
    }
    let (wf, hf) = (w as f64, h as f64);
    let mut out = Vec::new();
    edges.fill(w, h, |col, row| {
        out.push((col as f64 - wf / 2.0) / wf);
        out.push((row as f64 - hf / 2.0) / hf);
    });
    out
}

/// The edges of glyph outlines in image pixels (y down), for a non-zero winding fill.
#[derive(Default)]
struct Edges {
    /// (x0, y0, x1, y1) per edge.
    lines: Vec<[f64; 4]>,
    /// Pen position of the glyph on the baseline, and pixels per font unit of the outline.
    origin: (f64, f64),
    scale: f64,
    start: (f64, f64),
    at: (f64, f64),
}

impl Edges {
    fn to_image(&self, x: f32, y: f32) -> (f64, f64) {
        (
            self.origin.0 + x as f64 * self.scale,
            self.origin.1 - y as f64 * self.scale,
        )
    }

    fn segment(&mut self, to: (f64, f64)) {
        if to.1 != self.at.1 {
            self.lines.push([self.at.0, self.at.1, to.0, to.1]);
        }
        self.at = to;
    }

    /// Calls `lit(column, row)` for every pixel whose centre lies inside the outlines
    /// (non-zero winding), row by row.
    fn fill(&self, w: usize, h: usize, mut lit: impl FnMut(usize, usize)) {
        let mut cross: Vec<(f64, i32)> = Vec::new();
        for row in 0..h {
            let yc = row as f64 + 0.5;
            cross.clear();
            for &[x0, y0, x1, y1] in &self.lines {
                let (lo, hi) = if y0 < y1 { (y0, y1) } else { (y1, y0) };
                if yc < lo || yc >= hi {
                    continue;
                }
                let x = x0 + (yc - y0) / (y1 - y0) * (x1 - x0);
                cross.push((x, if y1 > y0 { 1 } else { -1 }));
            }
            cross.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut wind = 0;
            for pair in cross.windows(2) {
                wind += pair[0].1;
                if wind == 0 {
                    continue;
                }
                // Pixels with centre in [pair[0].x, pair[1].x).
                let c0 = (pair[0].0 - 0.5).ceil().max(0.0) as usize;
                let c1 = ((pair[1].0 - 0.5).ceil().max(0.0) as usize).min(w);
                for col in c0..c1 {
                    lit(col, row);
                }
            }
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
        const STEPS: usize = 8;
        let (a, c, b) = (self.at, self.to_image(cx0, cy0), self.to_image(x, y));
        for i in 1..=STEPS {
            let t = i as f64 / STEPS as f64;
            let u = 1.0 - t;
            let q = (
                u * u * a.0 + 2.0 * u * t * c.0 + t * t * b.0,
                u * u * a.1 + 2.0 * u * t * c.1 + t * t * b.1,
            );
            self.segment(q);
        }
    }

    fn curve_to(&mut self, cx0: f32, cy0: f32, cx1: f32, cy1: f32, x: f32, y: f32) {
        const STEPS: usize = 12;
        let a = self.at;
        let (c0, c1, b) = (
            self.to_image(cx0, cy0),
            self.to_image(cx1, cy1),
            self.to_image(x, y),
        );
        for i in 1..=STEPS {
            let t = i as f64 / STEPS as f64;
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

    fn points(text: &str, size: f64) -> Vec<f64> {
        let mut p = DEFS[0].defaults();
        p[0] = size;
        text_points(&p, &[text.to_string(), "Arial".to_string()])
    }

    /// The letters' points lie in the middle of the image, within the text box, and their
    /// share of the image matches a filled glyph's area.
    #[test]
    fn text_points_cover_the_letters() {
        let pts = points("SYM", 320.0);
        let n = pts.len() / 2;
        assert!(n > 10_000, "{n} points");
        let xs: Vec<f64> = pts.iter().step_by(2).copied().collect();
        let ys: Vec<f64> = pts.iter().skip(1).step_by(2).copied().collect();
        let (x_lo, x_hi) = (
            xs.iter().copied().fold(1.0, f64::min),
            xs.iter().copied().fold(-1.0, f64::max),
        );
        let (y_lo, y_hi) = (
            ys.iter().copied().fold(1.0, f64::min),
            ys.iter().copied().fold(-1.0, f64::max),
        );
        // Three capitals of about 0.6 em in an image 2 em wider: |x| well inside ±0.5.
        assert!(
            x_lo > -0.35 && x_hi < 0.35 && x_hi - x_lo > 0.25,
            "{x_lo} {x_hi}"
        );
        assert!(
            y_lo > -0.3 && y_hi < 0.3 && y_hi - y_lo > 0.15,
            "{y_lo} {y_hi}"
        );
        // Roughly symmetric about the centre (the text is centred).
        assert!((x_lo + x_hi).abs() < 0.05, "{x_lo} {x_hi}");
        // "S" is at the left, "M" at the right: more points right of centre (M is wider).
        let right = xs.iter().filter(|&&x| x > 0.0).count();
        assert!(right > n / 3 && right < 2 * n / 3, "{right} of {n}");
    }

    /// The points do not depend on the font size except for the pixel grid, and a huge size
    /// or a long text is drawn within the pixel budget.
    #[test]
    fn text_points_scale_and_stay_bounded() {
        let a = points("ugnis", 100.0);
        let b = points("ugnis", 400.0);
        let area = |p: &[f64]| {
            // Share of the image lit: points × pixel area (1/(W·H)) is independent of the size;
            // compare the spreads instead.
            let xs: Vec<f64> = p.iter().step_by(2).copied().collect();
            let mean = xs.iter().sum::<f64>() / xs.len() as f64;
            (xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / xs.len() as f64).sqrt()
        };
        assert!(
            (area(&a) - area(&b)).abs() < 0.01,
            "{} {}",
            area(&a),
            area(&b)
        );
        let long = "flame ".repeat(150);
        let big = points(&long, 4000.0);
        assert!(big.len() / 2 < MAX_PIXELS as usize, "{}", big.len() / 2);
        assert!(big.len() > 1000);
        assert!(points("", 320.0).is_empty());
    }

    #[test]
    fn text_wf_draws_the_text_scaled_and_ignores_the_weight() {
        let mut p = DEFS[0].defaults();
        p[1] = 0.0; // no jitter
        p[2] = 0.5;
        p[4] = 0.1;
        let texts = ["AB".to_string(), "Arial".to_string()];
        let v = Prepared::with_texts(
            by_name("text_wf").unwrap(),
            Form::Regular,
            7.0,
            &p,
            &texts,
            Affine::default(),
            true,
        );
        let data = v.data().to_vec();
        let mut rng = FastRng::new(3);
        let t = VarIn::default();
        let mut acc = Acc::default();
        for _ in 0..200 {
            let o = v.eval(&t, &mut acc, &mut rng);
            // Some drawn point k: x = (x_k·0.5 + 0.1)·3, y = y_k·3.
            let hit = data.chunks(2).any(|q| {
                ((q[0] * 0.5 + 0.1) * 3.0 - o[0]).abs() < 1e-12 && (q[1] * 3.0 - o[1]).abs() < 1e-12
            });
            assert!(hit, "{o:?}");
        }
    }
}
