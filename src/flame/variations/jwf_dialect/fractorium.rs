//! JWildfire's formulas for names of Fractorium's catalogue, where they differ from
//! Fractorium's. Each reads the registry entry's parameters and derived values (the twin is
//! that entry with this formula, see [`super::FORMULAS`]).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{FRAC_2_PI, PI};

use crate::flame::variations::*;

/// atanh(z) = ½·ln((1 + z)/(1 − z)), times the weight·2/π (Fractorium: weight/π).
pub(super) fn arctanh(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (x, y) = (t.x, t.y);
    // (1 + z)/(1 − z), then its logarithm.
    let (nr, ni) = (1.0 + x, y);
    let (dr, di) = (1.0 - x, -y);
    let d = dr * dr + di * di;
    let (qr, qi) = ((nr * dr + ni * di) / d, (ni * dr - nr * di) / d);
    let k = v.w * FRAC_2_PI;
    [k * 0.5 * (qr * qr + qi * qi).ln(), k * qi.atan2(qr), 0.0]
}

/// Xyrus02's crop as JWildfire computes it: the point replaces the sum so far (rather than
/// adding to it); outside the rectangle with `zero` the point is hidden, else it is shown.
/// Reads the registry's derived corners and sizes.
pub(super) fn crop(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, zero] = v.params();
    let [x0, y0, x1, y1, w, h] = v.derived();
    let (mut x, mut y) = (t.x, t.y);
    acc.x = 0.0;
    acc.y = 0.0;
    if (x < x0 || x > x1 || y < y0 || y > y1) && zero != 0.0 {
        acc.hide = true;
        return [0.0; 3];
    }
    acc.hide = false;
    if x < x0 {
        x = x0 + rng.f01() * w;
    } else if x > x1 {
        x = x1 - rng.f01() * w;
    }
    if y < y0 {
        y = y0 + rng.f01() * h;
    } else if y > y1 {
        y = y1 - rng.f01() * h;
    }
    [v.w * x, v.w * y, 0.0]
}

/// The radius from (r² + δ) rather than (r + δ), δ = (θ/π + 1)^a, along the polar angle.
pub(super) fn hole(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, inside] = v.params();
    let alpha = t.y.atan2(t.x);
    let delta = (alpha / PI + 1.0).powf(a);
    let r2 = t.x * t.x + t.y * t.y;
    let r = if inside != 0.0 {
        v.w * delta / (r2 + delta)
    } else {
        v.w * (r2 + delta).sqrt()
    };
    let (s, c) = alpha.sin_cos();
    [r * c, r * s, 0.0]
}

/// Will Evans's kaleidoscope with JWildfire's angle: 45 radians (not degrees).
pub(super) fn kaleidoscope(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [pull, rotate, line_up, sx, sy] = v.params();
    let (s45, c45) = 45f64.sin_cos();
    let x = ((rotate * t.x) * c45 - t.y * s45 + line_up) + sx;
    let y = if t.y > 0.0 {
        ((rotate * t.y) * c45 + t.x * s45 + pull + line_up) + sy
    } else {
        (rotate * t.y) * c45 + t.x * s45 - pull - line_up
    };
    [x, y, 0.0]
}

/// Zy0rg's tile_log with Java's rounding (⌊x + ½⌋) and the weighted z carried along.
pub(super) fn tile_log(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [spread] = v.params();
    let s = if rng.f01() < 0.5 { spread } else { -spread };
    let shift = (s * rng.f01().ln() + 0.5).floor();
    [v.w * (t.x + shift), v.w * t.y, v.w * t.z]
}

/// The Apophysis plug-in's boarders with Java's rounding (half to even); at a cell centre the
/// slope 0/0 gives NaN, as in JWildfire.
pub(super) fn boarders(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let (rx, ry) = (t.x.round_ties_even(), t.y.round_ties_even());
    let (ox, oy) = (t.x - rx, t.y - ry);
    let w = v.w;
    if rng.f01() >= 0.75 {
        return [w * (ox * 0.5 + rx), w * (oy * 0.5 + ry), 0.0];
    }
    if ox.abs() >= oy.abs() {
        let q = if ox >= 0.0 { 0.25 } else { -0.25 };
        [
            w * (ox * 0.5 + rx + q),
            w * (oy * 0.5 + ry + q * oy / ox),
            0.0,
        ]
    } else {
        let q = if oy >= 0.0 { 0.25 } else { -0.25 };
        [
            w * (ox * 0.5 + rx + ox / oy * q),
            w * (oy * 0.5 + ry + q),
            0.0,
        ]
    }
}
