//! JWildfire's formulas for crops and direct-colour variations of Fractorium's catalogue,
//! where they differ from Fractorium's: Xyrus02's `circlecrop` and JWildfire's own
//! `pre_circlecrop` and `post_circlecrop` (the point outside the circle hidden, only when
//! `zero` is exactly 1; no z of their own), `dc_carpet` and `dc_triangle` reading the xform's
//! affine map in its own order (Fractorium's mixes up its letters), `dc_triangle` scattering
//! the points inside the triangle (Fractorium's those outside), and `pixel_flow` with Java's
//! integer arithmetic and its rounded degree.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use crate::flame::variations::util::wang_hash;
use crate::flame::variations::*;

/// circlecrop's parameters as JWildfire keeps them: `zero` any whole number (only 1 crops to
/// the origin), the others as set.
const CIRCLECROP_PARAMS: &[Param] = &[
    p("circlecrop_radius", 1.0),
    p("circlecrop_x", 0.0),
    p("circlecrop_y", 0.0),
    p("circlecrop_scatter_area", 0.0),
    p_int("circlecrop_zero", 1.0, NEG_INF, INF),
];

const CIRCLECROP_FLAGS: u32 = flag::RANDOM | flag::HIDES;

pub(in crate::flame::variations) const DEFS: &[VarDef] = &[
    VarDef::new("circlecrop", circlecrop)
        .params(CIRCLECROP_PARAMS)
        .flags(CIRCLECROP_FLAGS | flag::WRITES_ACC),
    VarDef::new("pre_circlecrop", circlecrop)
        .params(CIRCLECROP_PARAMS)
        .flags(CIRCLECROP_FLAGS),
    VarDef::new("post_circlecrop", circlecrop)
        .params(CIRCLECROP_PARAMS)
        .flags(CIRCLECROP_FLAGS),
];

/// Xyrus02's circlecrop as JWildfire computes it, about (x, y): inside the circle the point
/// (relative to the centre) is weighted and moved back; outside it, with `zero` = 1, the
/// point is hidden (the regular form also clears the x and y summed so far); with any other
/// `zero` it goes onto a random ring of `radius` + ξ·scatter/2 (scatter within ±1). The
/// regular form adds to the sum; the `pre_` and `post_` forms replace x and y of the point
/// they transform and keep its z.
fn circlecrop(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, x0, y0, scatter, zero] = v.params();
    let (xi, yi) = (t.x - x0, t.y - y0);
    let rad = (xi * xi + yi * yi).sqrt();
    let ang = yi.atan2(xi);
    let rdc = radius + rng.f01() * 0.5 * scatter.clamp(-1.0, 1.0);
    let outside = rad > radius;
    acc.hide = false;
    if outside && zero == 1.0 {
        acc.hide = true;
        if v.form == Form::Regular {
            acc.x = 0.0;
            acc.y = 0.0;
        }
        return [0.0; 3];
    }
    if outside {
        let (s, c) = ang.sin_cos();
        [v.w * rdc * c + x0, v.w * rdc * s + y0, 0.0]
    } else {
        [v.w * xi + x0, v.w * yi + y0, 0.0]
    }
}

/// Xyrus02's dc_carpet as JWildfire computes it: the point moved by (±1, ±1) and mapped by
/// the xform's affine map (a·x + b·y + e, c·x + d·y + f in ugnis' letters); the colour mixes
/// towards the xor of the two signs. Reads nothing derived.
pub(super) fn dc_carpet(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [origin] = v.params();
    let h = 0.1 * origin;
    let x0: i32 = if rng.f01() < 0.5 { -1 } else { 1 };
    let y0: i32 = if rng.f01() > 0.5 { -1 } else { 1 };
    let (x, y) = (t.x + x0 as f64, t.y + y0 as f64);
    let xor = (x0 ^ y0) as f64;
    let hh = -h + (1.0 - xor) * h;
    let a = &v.aff;
    acc.color = (acc.color * 0.5 * (1.0 + hh) + xor * (1.0 - hh) * 0.5).abs() % 1.0;
    [
        v.w * (a.a * x + a.b * y + a.e),
        v.w * (a.c * x + a.d * y + a.f),
        0.0,
    ]
}

/// (u, v) moved onto the triangle's far edge u + v = 1, the larger of the two kept (at most
/// 1).
fn onto_far_edge(u: f64, w: f64) -> (f64, f64) {
    if u > w {
        let u = u.min(1.0);
        (u, 1.0 - u)
    } else {
        let w = w.min(1.0);
        (1.0 - w, w)
    }
}

/// Xyrus02's dc_triangle as JWildfire computes it: the triangle spanned by the xform's affine
/// map (origin (e, f), edges (a, b) and −(c, d) in ugnis' letters), the point's barycentric
/// coordinates clamped onto it; outside points zeroed with `zero_edges`, inside points
/// scattered by ξ·scatter_area (and pulled back onto the far edge); colour |u + v| mod 1.
pub(super) fn dc_triangle(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scatter, zero_edges] = v.params();
    let a = &v.aff;
    let area = scatter.clamp(-1.0, 1.0);
    let (xx, xy) = (a.a, a.b);
    let (yx, yy) = (-a.c, -a.d);
    let (ox, oy) = (a.e, a.f);
    let (px, py) = (t.x - ox, t.y - oy);
    let d00 = xx * xx + xy * xy;
    let d01 = xx * yx + xy * yy;
    let d02 = xx * px + xy * py;
    let d11 = yx * yx + yy * yy;
    let d12 = yx * px + yy * py;
    let den = d00 * d11 - d01 * d01;
    let mut u = (d11 * d02 - d01 * d12) / den;
    let mut w = (d00 * d12 - d01 * d02) / den;
    let inside = if u + w > 1.0 {
        (u, w) = onto_far_edge(u, w);
        false
    } else if u < 0.0 || w < 0.0 {
        u = u.clamp(0.0, 1.0);
        w = w.clamp(0.0, 1.0);
        false
    } else {
        true
    };
    if zero_edges == 1.0 && !inside {
        u = 0.0;
        w = 0.0;
    } else if inside {
        u = (u + rng.f01() * area).clamp(-1.0, 1.0);
        w = (w + rng.f01() * area).clamp(-1.0, 1.0);
        if u + w > 1.0 && area > 0.0 {
            (u, w) = onto_far_edge(u, w);
        }
    }
    acc.color = (u + w).abs() % 1.0;
    [
        v.w * (ox + u * xx + w * yx),
        v.w * (oy + u * xy + w * yy),
        0.0,
    ]
}

/// bezo97's pixel_flow as JWildfire computes it: the angle in degrees times 0.0174532925; the
/// block indices ⌊x·width⌋ moved by a jitter hashed (Bob Jenkins' integer hash) in Java's
/// `int` arithmetic (the sum truncated, products wrapping, the halving an integer division);
/// the streak length the mean of two hashes of the blocks, faded by ξ⁴; `enable_dc` 1 sets
/// the colour to ξ.
pub(super) fn pixel_flow(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [angle, len, width, seed, dc] = v.params();
    let (sina, cosa) = (angle * 0.0174532925).sin_cos();
    // Java's (int) of a double: truncation, saturating, NaN to 0 (as Rust's `as`).
    let seed = seed as i32;
    let block = |u: f64| -> i32 {
        let b = (u * width).floor() as i32;
        let jitter = 2.0 - 4.0 * wang_hash(b.wrapping_mul(seed).wrapping_add(1));
        (b as f64 + jitter) as i32
    };
    let bx = block(t.x);
    let by = block(t.y);
    let h1 = wang_hash(by.wrapping_add(bx.wrapping_mul(seed.wrapping_neg())));
    let h2 = wang_hash(bx.wrapping_add(by.wrapping_mul(seed) / 2));
    let streak = (h1 + h2) * 0.5;
    let r = rng.f01();
    let fade = streak * r * r * r * r;
    if dc == 1.0 {
        acc.color = r;
    }
    [v.w * len * cosa * fade, v.w * len * sina * fade, 0.0]
}
