//! `svg_wf`, JWildfire's SVG variation: a blur whose points are the lit pixels of an SVG
//! drawing (JWildfire 9.00, `SVGWFFunc`; formulas and behaviour written anew).
//!
//! JWildfire renders the SVG (the text resource `svg`, by default a small Inkscape drawing
//! of strokes and a purple shape) with SVG Salamander into a transparent image of
//! FTOI(width·m) × FTOI(height·m) pixels for the document's width and height and the
//! `resolution_multiplier` m, anti-aliased when `pre_antialias` is not 0, and keeps every
//! pixel that is not fully transparent — an edge pixel counts as much as an inner one — with
//! its colour. A point's position is relative to the box of those pixels: x = (column −
//! x_min − Δx/2)/Δ, y = (row − y_min − Δy/2)/Δ for the box's extents Δx, Δy and the larger
//! of them Δ. Each call takes one of those points at random, moves it by a small random
//! amount (`antialias_radius`), scales and offsets it; the weight does not scale it. With
//! `true_color` 1 the point takes the pixel's colour as its own, and its colour coordinate
//! becomes that of the palette entry nearest to that colour.
//!
//! ugnis reads the SVG with its own reader ([`super::jwf_aa_svgdoc`], the subset drawings
//! mostly use; what it leaves out is reported when a flame is read, [`svg_problem`]) and
//! draws it with its own anti-aliased rasteriser ([`super::jwf_aa_raster`]), so the pixels
//! along the edges can differ from Java2D's; the points' distribution matches.

use std::f64::consts::PI;

use super::jwf_aa_raster::{FillRule, fill, stroke};
use super::jwf_aa_svgdoc::{Paint, read};
use super::jwf_h9b_images::ftoi;
use super::*;

/// The SVG drawn by default: a drawing of ugnis' own. JWildfire's default (an Inkscape
/// drawing in `SVGWFFunc`'s source) is not copied, so a flame that relies on it draws this
/// one instead — unless the user names a JWildfire installation to read it from
/// ([`JWILDFIRE_DEFAULT`]); a flame that carries its SVG draws that.
const DEFAULT_SVG: &str = include_str!("jwf_aa_svg_default.svg");

/// Where JWildfire's own default drawing is: the longest string constant of `SVGWFFunc`'s
/// class, read from the user's JWildfire installation when one is named. It replaces ugnis'
/// default drawing there.
const JWILDFIRE_DEFAULT: &str = "jwildfire:org/jwildfire/create/tina/variation/SVGWFFunc.class";

/// Most bytes of SVG text read.
const MAX_SVG: usize = 8 << 20;

/// Most pixels of the image drawn: a larger multiplier draws at the largest that fits (the
/// points are relative to the drawing, so only the edges' share changes). The image takes 4
/// bytes a pixel while it is drawn, the points 8 bytes each.
const MAX_PIXELS: f64 = 12.0e6;

/// Values before the points in the shared data: image width, x_min, y_min, Δx, Δy, Δ.
const HEADER: usize = 6;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("svg_wf", svg_wf)
    .params(&[
        p("svg_wf_antialias_radius", 0.5),
        p_range("svg_wf_resolution_multiplier", 2.0, 0.1, 100.0),
        p_int("svg_wf_true_color", 1.0, -2147483648.0, 2147483647.0),
        p_int("svg_wf_pre_antialias", 1.0, -2147483648.0, 2147483647.0),
        p("svg_wf_scale_x", 1.0),
        p("svg_wf_scale_y", 1.0),
        p("svg_wf_offset_x", 0.0),
        p("svg_wf_offset_y", 0.0),
    ])
    .texts(&[TextParam {
        name: "svg_wf_svg",
        default: DEFAULT_SVG,
        max_len: MAX_SVG,
    }])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR | flag::PALETTE)
    .sum()
    .shared(&[1, 3], svg_points)];

/// The reader's warning for an SVG text with parts ugnis does not draw; `None` when it draws
/// all of it (or for another variation).
pub fn svg_problem(name: &str, texts: &[String]) -> Option<String> {
    if name != "svg_wf" {
        return None;
    }
    let text = texts.first()?;
    let doc = read(text, 1.0);
    if doc.problems.is_empty() {
        return None;
    }
    Some(format!(
        "svg_wf: parts of the SVG are not drawn: {}",
        doc.problems.join("; ")
    ))
}

/// svg_wf: a random lit pixel of the drawing.
fn svg_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [aa, _, true_color, _, scale_x, scale_y, offset_x, offset_y] = v.params();
    let d = v.data();
    let n = d.len().saturating_sub(HEADER);
    if n <= 1 {
        // Nothing drawn: JWildfire scatters the points over a unit square, black.
        acc.rgb = Some([0.0; 3]);
        return [rng.f01(), rng.f01(), 0.0];
    }
    let k = rng.below(n as u64) as usize;
    let (x, y, rgb) = point_at(d, k);
    let (mut x, mut y) = (x, y);
    if aa > 0.01 {
        let dr = ((aa * (-rng.f01().max(f64::MIN_POSITIVE).ln()).sqrt()).exp() - 1.0) * 0.001;
        let da = rng.f01() * 2.0 * PI;
        x += dr * da.cos();
        y += dr * da.sin();
    }
    let [r, g, b] = rgb.map(f64::from);
    if true_color == 1.0 {
        acc.rgb = Some([r, g, b]);
    }
    if let Some(c) = v.palette_coordinate(r, g, b) {
        acc.color = c;
    }
    [x * scale_x + offset_x, y * scale_y + offset_y, 0.0]
}

/// The position and colour of point `k` of the shared data.
fn point_at(d: &[f64], k: usize) -> (f64, f64, [u8; 3]) {
    let [w, x_min, y_min, dx, dy, size] = [d[0], d[1], d[2], d[3], d[4], d[5]];
    let packed = d[HEADER + k] as u64;
    let rgb = [(packed >> 16) as u8, (packed >> 8) as u8, packed as u8];
    let idx = (packed >> 24) as f64;
    let row = (idx / w).floor();
    let col = idx - row * w;
    (
        ((col - x_min) - dx / 2.0) / size,
        ((row - y_min) - dy / 2.0) / size,
        rgb,
    )
}

/// The lit pixels of the drawing: the header (see [`HEADER`]), then per pixel its index
/// (row·width + column) times 2²⁴ plus its colour 0xRRGGBB. Built once per SVG text,
/// multiplier and anti-aliasing switch.
fn svg_points(p: &[f64], texts: &[String]) -> Vec<f64> {
    let [_, multiplier, _, pre_antialias] = params_of(p);
    let mut text = texts.first().map_or(DEFAULT_SVG, |t| t.as_str());
    let jwildfire = (text == DEFAULT_SVG)
        .then(|| super::resources::text(JWILDFIRE_DEFAULT))
        .flatten();
    if let Some(t) = &jwildfire {
        text = t.as_str();
    }
    // The document's size first (at scale 1), then the multiplier that fits.
    let size = read(text, 1.0);
    let area = size.width * size.height;
    let mut m = multiplier;
    if area * m * m > MAX_PIXELS {
        m = (MAX_PIXELS / area).sqrt();
    }
    let (w, h) = (ftoi(size.width * m), ftoi(size.height * m));
    if !(w > 0 && h > 0 && f64::from(w) * f64::from(h) <= MAX_PIXELS * 1.01) {
        return Vec::new();
    }
    let (w, h) = (w as usize, h as usize);
    let doc = read(text, m);
    let img = draw(&doc.shapes, w, h, pre_antialias != 0.0);
    lit_points(&img, w, h)
}

/// A drawing as premultiplied RGBA bytes, on a transparent image.
fn draw(shapes: &[super::jwf_aa_svgdoc::Shape], w: usize, h: usize, aa: bool) -> Vec<[u8; 4]> {
    let mut img = vec![[0u8; 4]; w * h];
    let mut paint_with = |polys: &[Vec<(f64, f64)>], rule: FillRule, paint: Paint| {
        if paint.alpha <= 0.0 {
            return;
        }
        let src = paint.rgb.map(f64::from);
        fill(polys, rule, aa, w, h, |x, y, cov| {
            // The coverage as Java2D's mask keeps it: a byte.
            let m = (cov * 255.0 + 0.5).floor();
            if m < 1.0 {
                return;
            }
            let a = m / 255.0 * paint.alpha;
            let px = &mut img[y * w + x];
            for c in 0..3 {
                px[c] = (src[c] * a + f64::from(px[c]) * (1.0 - a) + 0.5).min(255.0) as u8;
            }
            px[3] = (255.0 * a + f64::from(px[3]) * (1.0 - a) + 0.5).min(255.0) as u8;
        });
    };
    for s in shapes {
        if let Some((paint, rule)) = s.fill {
            let polys: Vec<Vec<(f64, f64)>> = s.subpaths.iter().map(|p| p.0.clone()).collect();
            paint_with(&polys, rule, paint);
        }
        if let Some(st) = s.stroke {
            let polys: Vec<Vec<(f64, f64)>> = s
                .subpaths
                .iter()
                .flat_map(|(pts, closed)| stroke(pts, *closed, st.width, st.cap, st.join))
                .collect();
            paint_with(&polys, FillRule::NonZero, st.paint);
        }
    }
    img
}

/// JWildfire's points of an image: every pixel not fully transparent, placed in the box of
/// those pixels (found as `SVGWFFunc` finds it), with its colour (straight, not
/// premultiplied).
fn lit_points(img: &[[u8; 4]], w: usize, h: usize) -> Vec<f64> {
    let (mut x_min, mut x_max, mut y_min, mut y_max) = (w as i64 - 1, 0i64, h as i64 - 1, 0i64);
    let mut count = 0usize;
    for i in 0..h {
        for j in 0..w {
            if img[i * w + j][3] == 0 {
                continue;
            }
            count += 1;
            let (j, i) = (j as i64, i as i64);
            // A new least value is not also tested as a greatest one (as in JWildfire).
            if j < x_min {
                x_min = j;
            } else if j > x_max {
                x_max = j;
            }
            if i < y_min {
                y_min = i;
            } else if i > y_max {
                y_max = i;
            }
        }
    }
    let (dx, dy) = (x_max - x_min, y_max - y_min);
    let size = dx.max(dy);
    if size <= 0 {
        return Vec::new();
    }
    let mut out = Vec::with_capacity(HEADER + count);
    out.extend([
        w as f64,
        x_min as f64,
        y_min as f64,
        dx as f64,
        dy as f64,
        size as f64,
    ]);
    for (k, px) in img.iter().enumerate() {
        if px[3] == 0 {
            continue;
        }
        let a = f64::from(px[3]);
        let straight = |c: u8| ((f64::from(c) * 255.0 / a).round()).min(255.0) as u64;
        let rgb = straight(px[0]) << 16 | straight(px[1]) << 8 | straight(px[2]);
        out.push(((k as u64) << 24 | rgb) as f64);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_drawing_is_read_whole_and_fills_its_box() {
        assert_eq!(svg_problem("svg_wf", &[DEFAULT_SVG.to_string()]), None);
        let d = svg_points(&[0.5, 2.0, 1.0, 1.0], &[DEFAULT_SVG.to_string()]);
        let n = d.len() - HEADER;
        assert!(n > 10_000, "{n}");
        // The image is the document's width times the multiplier, as JWildfire's.
        assert_eq!(d[0], 480.0);
        let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
        let mut purple = 0;
        for k in 0..n {
            let (x, y, rgb) = point_at(&d, k);
            lo = [lo[0].min(x), lo[1].min(y)];
            hi = [hi[0].max(x), hi[1].max(y)];
            purple += usize::from(rgb == [128, 0, 128]);
        }
        // The box's longer side (the height: the wave hangs below the ring) spans −1/2 … 1/2.
        assert!(
            (lo[1] + 0.5).abs() < 1e-9 && (hi[1] - 0.5).abs() < 1e-9,
            "{lo:?} {hi:?}"
        );
        assert!(lo[0] > -0.5 && hi[0] < 0.5, "{lo:?} {hi:?}");
        // Most points are inside the purple shape.
        assert!(purple * 2 > n, "{purple} of {n}");
    }

    #[test]
    fn an_svg_without_shapes_gives_no_points() {
        let t = ["<svg width='10' height='10'/>".to_string()];
        assert!(svg_points(&[0.5, 2.0, 1.0, 1.0], &t).is_empty());
        let t = ["not svg".to_string()];
        assert!(svg_points(&[0.5, 2.0, 1.0, 1.0], &t).is_empty());
        assert!(svg_problem("svg_wf", &t).is_some());
    }
}
