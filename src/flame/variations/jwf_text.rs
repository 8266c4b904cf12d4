//! `text_wf`, JWildfire's text variation: a blur whose points lie on a line of text.
//!
//! JWildfire draws the text, without anti-aliasing, centred in an image that leaves one font
//! size of margin on each side, and keeps every lit pixel as a point: x = (column − W/2)/W,
//! y = (row − H/2)/H for the image's width W and height H (rows go down, as y does in a flame).
//! Each sample picks one of those points, moves it by a small random amount (`antialias`) and
//! scales it: (x·scale_x + offset_x)·3, (y·scale_y + offset_y)·3. The weight does not scale it.
//!
//! JWildfire uses the font named by `font_name` from the system; ugnis draws every font name
//! with the font a Java VM without Arial uses for JWildfire's default "Arial", DejaVu Sans,
//! bundled, laid out and filled as Java 2D does it ([`jwf_text_raster`]).

use std::f64::consts::PI;

use super::jwf_text_raster;
use super::*;

/// Most pixels of the image the text is drawn into: larger font sizes or longer texts are
/// drawn at a lower resolution with the same proportions (the points are relative to the
/// image), so the memory they take stays below 16 bytes × this.
const MAX_PIXELS: f64 = 4.0e6;

/// Most bytes of text kept.
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

/// The drawn text's points, x and y interleaved (see [`jwf_text_raster::text_points`]). Built
/// once per text, font size and baseline ([`super::shared`]).
fn text_points(p: &[f64], texts: &[String]) -> Vec<f64> {
    let text = texts.first().map_or("", |t| t.as_str());
    let [font_size, _, _, _, _, _, baseline] = params_of(p);
    jwf_text_raster::text_points(text, font_size as i64, baseline as i64, MAX_PIXELS)
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
