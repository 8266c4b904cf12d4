//! JWildfire's `colordomain`: a domain colouring of a complex function. Each call picks a
//! random node of a `size` × `size` grid over the unit square, centred on the origin, and
//! gives the point the colour of f iterated `nIters` times at the matching point of the
//! rectangle [re_min, re_max] × [im_min, im_max]: its argument as the hue, its modulus, on a
//! scale of powers of e, as saturation and value (after Hans Lundmark's domain-colouring
//! notes, users.mai.liu.se/hanlu09/complex/domain_coloring.html).
//!
//! The formula follows JWildfire 9.00's (LGPL-2.1) `ColorDomainFunc`, written anew. Its
//! function is Java code in the `code` resource, compiled when JWildfire runs; ugnis evaluates
//! the default function only, f(z) = sin²(πz), and draws a flame whose `code` holds another
//! function with the default.
//!
//! JWildfire shrinks the rectangle to its middle half each time `zoomIn` is set and widens it
//! by half each time `zoomOut` is set; as both are always set, one after the other, a
//! rectangle with `re_min` < `re_max` and `im_min` < `im_max` comes back to itself (up to
//! rounding), and ugnis uses the stored one.

use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("colordomain", colordomain)
    .params(&[
        // JWildfire's own bounds.
        p_int("colordomain_size", 1000.0, 100.0, 10000.0),
        p("colordomain_re_min", -1.0),
        p("colordomain_re_max", 1.0),
        p("colordomain_im_min", -1.0),
        p("colordomain_im_max", 1.0),
        p_int("colordomain_zoomIn", 1.0, 1.0, 1.0),
        p_int("colordomain_zoomOut", 1.0, 1.0, 1.0),
        p_int("colordomain_nIters", 1.0, 1.0, 20.0).limited(),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)];

/// JWildfire's default function, sin²(πz), with its hyperbolic functions written out as
/// JWildfire's complex class computes them.
fn default_f(x: f64, y: f64) -> (f64, f64) {
    let (a, b) = (x * std::f64::consts::PI, y * std::f64::consts::PI);
    let cosh = (b.exp() + (-b).exp()) / 2.0;
    let sinh = (b.exp() - (-b).exp()) / 2.0;
    let (sr, si) = (cosh * a.sin(), sinh * a.cos());
    (sr * sr - si * si, sr * si + si * sr)
}

/// Hue, saturation and value (each in [0, 1]) to red, green and blue (JWildfire's `SetHSV`).
pub(super) fn set_hsv(h: f64, s: f64, v: f64) -> [f64; 3] {
    if s == 0.0 {
        return [v, v, v];
    }
    let h = if h == 1.0 { 0.0 } else { h };
    let z = (h * 6.0).floor();
    let f = h * 6.0 - z;
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f)));
    match z as i32 {
        0 => [v, t, p],
        1 => [q, v, p],
        2 => [p, v, t],
        3 => [p, q, v],
        4 => [t, p, v],
        5 => [v, p, q],
        _ => [0.0; 3],
    }
}

/// The colour of the value w = (u, v) of the function as bytes, as JWildfire's `SetHSV` gives
/// them: a channel is 256 times its value, truncated and kept below 256.
fn domain_colour(u: f64, v: f64) -> [f64; 3] {
    domain_rgb(u, v).map(|c| f64::from(((256.0 * c) as i32).min(255)))
}

/// The domain colouring of w = (u, v) that JWildfire's `colordomain` and its followers use
/// (see the module documentation): the argument as hue, the modulus on a scale of powers of
/// e as saturation and value; red, green and blue in [0, 1].
pub(super) fn domain_rgb(u: f64, v: f64) -> [f64; 3] {
    const TAU: f64 = std::f64::consts::TAU;
    let mut a = v.atan2(u);
    // The argument in [0, 2π) (a NaN argument stays NaN).
    if a < 0.0 {
        a += TAU;
    }
    a /= TAU;
    let m = if u != 0.0 || v != 0.0 {
        (u * u + v * v).sqrt()
    } else {
        0.0
    };
    // The powers of e around the modulus: e^(k−1) ≤ … < m ≤ e^k, with 0 below 1. Past 710
    // steps e^k is infinite and the loop would not end; such a modulus is infinite itself.
    let (mut lo, mut hi) = (0.0, 1.0);
    let mut steps = 0;
    while m > hi && steps < 720 {
        lo = hi;
        hi *= std::f64::consts::E;
        steps += 1;
    }
    let k = (m - lo) / (hi - lo);
    let tri = if k >= 0.5 {
        1.0 - (k - 0.5) * 2.0
    } else {
        k * 2.0
    };
    let sat = 0.4 + (1.0 - (1.0 - tri).powf(3.0)) * 0.6;
    let val = 0.6 + (1.0 - tri.powf(3.0)) * 0.4;
    set_hsv(a, sat, val)
}

/// colordomain: a random node of the grid, coloured by the function there.
fn colordomain(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [size, re_min, re_max, im_min, im_max, _, _, iters] = v.params();
    let j = (rng.f01() * size).trunc();
    let i = (rng.f01() * size).trunc();
    let im = im_max - ((im_max - im_min) * j) / (size - 1.0);
    let re = re_min - ((re_min - re_max) * i) / (size - 1.0);
    let (mut x, mut y) = (re, im);
    for _ in 0..iters as usize {
        (x, y) = default_f(x, y);
    }
    acc.rgb = Some(domain_colour(x, y));
    [v.w * (i / size - 0.5), v.w * (j / size - 0.5), 0.0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_follow_the_argument_and_modulus() {
        // f = 1, modulus 1: k = 1, so saturation 0.4 and value 1; hue 0: red, (1, 0.6, 0.6).
        assert_eq!(domain_colour(1.0, 0.0), [255.0, 153.0, 153.0]);
        // Hue ⅓ (argument 2π/3), modulus e^0.5 (k ≈ 0.38).
        let c = domain_colour(-0.5 * 0.5f64.exp(), 0.75f64.sqrt() * 0.5f64.exp());
        assert!(c[1] > c[0] && c[1] > c[2], "{c:?}");
        // sin²(π/2) = 1.
        let (u, v) = default_f(0.5, 0.0);
        assert!((u - 1.0).abs() < 1e-15 && v == 0.0);
    }
}
