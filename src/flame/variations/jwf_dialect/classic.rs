//! JWildfire's formulas for flam3's classic variations, where they differ from flam3's: its
//! constants (`polar`'s 0.31830989 for 1/π, `rings2`'s 1e-8), its unweighted `rings`, its
//! `bubble` z, its `elliptic` modes, its `splits` shears, and its guard 1e-300 added to the
//! radius (so that the origin gives what JWildfire gives there).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{FRAC_2_PI, FRAC_PI_4};

use super::{SMALL_EPSILON, jwf_sqrt};
use crate::flame::variations::util::jwf_math as jm;
use crate::flame::variations::*;

pub(in crate::flame::variations) const DEFS: &[VarDef] = &[
    VarDef::new("bubble", bubble).flags(flag::WRITES_Z),
    VarDef::new("cross", cross),
    VarDef::new("elliptic", elliptic)
        .params(&[p_int("elliptic_mode", 1.0, 0.0, 2.0)])
        .flags(flag::RANDOM),
    VarDef::new("flower", flower)
        .params(&[p("flower_petals", 0.0), p("flower_holes", 0.0)])
        .flags(flag::RANDOM),
    VarDef::new("polar", polar),
    VarDef::new("rings", rings).flags(flag::USES_AFFINE),
    VarDef::new("rings2", rings2).params(&[p("rings2_val", 1.0)]),
    VarDef::new("spiral", spiral),
    VarDef::new("splits", splits).params(&[
        p("splits_x", 0.0),
        p("splits_y", 0.0),
        p("splits_lshear", 0.0),
        p("splits_rshear", 0.0),
        p("splits_ushear", 0.0),
        p("splits_dshear", 0.0),
    ]),
    VarDef::new("super_shape", super_shape)
        .params(&[
            p("super_shape_rnd", 0.0),
            p("super_shape_m", 0.0),
            p("super_shape_n1", 1.0),
            p("super_shape_n2", 1.0),
            p("super_shape_n3", 1.0),
            p("super_shape_holes", 0.0),
        ])
        .flags(flag::RANDOM),
];

/// x, y as flam3's; z the weighted height 2/r − 1 of the sphere (always, not only with
/// "preserve Z").
fn bubble(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let r = (t.x * t.x + t.y * t.y) / 4.0 + 1.0;
    let s = v.w / r;
    [s * t.x, s * t.y, v.w * (2.0 / r - 1.0)]
}

/// x² − y² as it stands (flam3: (x − y)(x + y)), guarded by 1e-300.
fn cross(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let s = t.x * t.x - t.y * t.y;
    let r = v.w * (1.0 / (s * s + SMALL_EPSILON)).sqrt();
    [t.x * r, t.y * r, 0.0]
}

/// Mode 0: the Apophysis plug-in; 1 (the default): y mirrored at random; 2: Claude
/// Heiland-Allen's precise form (√(1+u) − 1 and ln(1+u)).
fn elliptic(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode] = v.params();
    let (x, y) = (t.x, t.y);
    let k = v.w * FRAC_2_PI;
    let sq = x * x + y * y;
    let x2 = 2.0 * x;
    if mode == 2.0 {
        let xmaxm1 = 0.5 * (sqrt1pm1(sq + x2) + sqrt1pm1(sq - x2));
        let ssx = if xmaxm1 < 0.0 { 0.0 } else { xmaxm1.sqrt() };
        let a = x / (1.0 + xmaxm1);
        let sign = if y > 0.0 { 1.0 } else { -1.0 };
        return [
            k * a.clamp(-1.0, 1.0).asin(),
            sign * k * (xmaxm1 + ssx).ln_1p(),
            0.0,
        ];
    }
    // JWildfire's table-based square root and arctangent (FAST_MATH): near the origin xmax is
    // 1 plus a few ulps, and which ulps decides the height of the result.
    let safe_sqrt = |u: f64| if u < SMALL_EPSILON { 0.0 } else { jm::sqrt(u) };
    let tmp = sq + 1.0;
    let xmax = 0.5 * (jm::sqrt(tmp + x2) + jm::sqrt(tmp - x2));
    let a = x / xmax;
    let b = safe_sqrt(1.0 - a * a);
    let sign = if mode == 1.0 {
        if rng.f01() < 0.5 { 1.0 } else { -1.0 }
    } else if y > 0.0 {
        1.0
    } else {
        -1.0
    };
    [
        k * jm::atan2(a, b),
        sign * k * (xmax + safe_sqrt(xmax - 1.0)).ln(),
        0.0,
    ]
}

/// √(1 + x) − 1: JWildfire's [4,4] Padé approximant near 0.
fn sqrt1pm1(x: f64) -> f64 {
    if -0.0625 < x && x < 0.0625 {
        let num = (((x / 32.0 + 5.0 / 16.0) * x + 0.75) * x + 0.5) * x;
        let den = (((x / 256.0 + 5.0 / 32.0) * x + 15.0 / 16.0) * x + 1.75) * x + 1.0;
        return num / den;
    }
    (1.0 + x).sqrt() - 1.0
}

/// The radius r + 1e-300 (nothing at the origin, where x and y are 0).
fn flower(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [petals, holes] = v.params();
    let d = jwf_sqrt(t);
    let r = v.w * (rng.f01() - holes) * (petals * t.y.atan2(t.x)).cos() / d;
    [r * t.x, r * t.y, 0.0]
}

/// polar as JWildfire computes it: the angle from the y axis over π, the radius less 1.
fn polar(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    // JWildfire's rounded 1/π (kept: the vectors follow it, not the nearest double).
    #[allow(clippy::approx_constant)]
    const R_PI: f64 = 0.31830989;
    let ny = (t.x * t.x + t.y * t.y).sqrt() - 1.0;
    [v.w * t.x.atan2(t.y) * R_PI, v.w * ny, 0.0]
}

/// Unweighted; the ring width is the square of the affine x offset plus 1e-300.
fn rings(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let c = v.aff.e;
    let dx = c * c + SMALL_EPSILON;
    let r = jwf_sqrt(t);
    let q = r + dx - ((r + dx) / (2.0 * dx)).trunc() * 2.0 * dx - dx + r * (1.0 - dx);
    [q * t.y / r, q * t.x / r, 0.0]
}

/// The ring width val² + 1e-8; nothing at the origin.
fn rings2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [val] = v.params();
    let dx = val * val + 1e-8;
    let l = jwf_sqrt(t);
    let r = v.w * (2.0 - dx * (((l / dx + 1.0) / 2.0).trunc() * 2.0 / l + 1.0));
    [r * t.x, r * t.y, 0.0]
}

fn spiral(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let r = jwf_sqrt(t);
    let (sin_a, cos_a) = (t.x / r, t.y / r);
    let (sr, cr) = r.sin_cos();
    let k = v.w / r;
    [(cos_a + sr) * k, (sin_a - cr) * k, 0.0]
}

/// flam3's splits with DarkBeam's shears (emulating splits.dll).
fn splits(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sx, sy, lshear, rshear, ushear, dshear] = v.params();
    let w = v.w;
    let (mut x, mut y) = if t.x >= 0.0 {
        (w * (t.x + sx), w * rshear)
    } else {
        (w * (t.x - sx), -w * lshear)
    };
    if t.y >= 0.0 {
        y += w * (t.y + sy);
        x += w * ushear;
    } else {
        y += w * (t.y - sy);
        x -= w * dshear;
    }
    [x, y, 0.0]
}

/// The radius r + 1e-300: nothing at the origin.
fn super_shape(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [rnd, m, n1, n2, n3, holes] = v.params();
    let theta = m / 4.0 * t.y.atan2(t.x) + FRAC_PI_4;
    let (st, ct) = theta.sin_cos();
    let t1 = ct.abs().powf(n2);
    let t2 = st.abs().powf(n3);
    let d = jwf_sqrt(t);
    let r = v.w * ((rnd * rng.f01() + (1.0 - rnd) * d) - holes) * (t1 + t2).powf(-1.0 / n1) / d;
    [r * t.x, r * t.y, 0.0]
}
