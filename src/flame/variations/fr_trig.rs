//! Fractorium's formulas built from trigonometric and hyperbolic functions of x and y:
//! `bisplit`, `crescents`, `mask`, `petal`, `spiralwing`, `squirrel`, `tancos`, `rippled`,
//! `sintrange`, `funnel`, `sigmoid`, `cylinder2`, `stwin` and the `rays` family.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_2_PI, PI, TAU};

use super::util::zeps;
use super::*;
use crate::flame::fastmath::{self as fm, FastTrig};

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("bisplit", bisplit),
    super::inlined!("crescents", crescents),
    super::inlined!("cylinder2", cylinder2),
    super::inlined!("funnel", funnel).params(&[p_int("funnel_effect", 8.0, NEG_INF, INF)]),
    super::inlined!("mask", mask).needs(need::SUMSQ),
    super::inlined!("petal", petal),
    super::inlined!("rays1", rays1)
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC),
    super::inlined!("rays2", rays2)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC),
    super::inlined!("rays3", rays3)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC),
    super::inlined!("rippled", rippled).needs(need::SUMSQ),
    super::inlined!("sigmoid", sigmoid)
        .params(&[p("sigmoid_shiftx", 1.0), p("sigmoid_shifty", 1.0)])
        .prepare(sigmoid_prep),
    super::inlined!("sintrange", sintrange).params(&[p("sintrange_w", 1.0)]),
    super::inlined!("spiralwing", spiralwing).needs(need::SUMSQ),
    super::inlined!("squirrel", squirrel).params(&[p("squirrel_a", 1.0), p("squirrel_b", 1.0)]),
    super::inlined!("stwin", stwin).params(&[p("stwin_distort", 1.0)]),
    super::inlined!("tancos", tancos).needs(need::SUMSQ),
];

/// (w/10)·(cos y / tan x, −y / sin x): a field of split, mirrored bands.
#[inline(always)]
fn bisplit(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let k = v.w * 0.1;
    [k / t.x.ftan() * t.y.fcos(), k / t.x.fsin() * -t.y, 0.0]
}

/// Crescents: (sin x, cos x) scaled by sin²x·(cosh y + 1).
#[inline(always)]
fn crescents(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (s, c) = t.x.fsin_cos();
    let k = (fm::cosh(t.y) + 1.0) * (s * s);
    [v.w * s * k, v.w * c * k, 0.0]
}

/// Squeezes x into (−1, 1) by x/√(x²+1); y unchanged.
#[inline(always)]
fn cylinder2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w * (t.x / zeps((t.x * t.x + 1.0).sqrt())), v.w * t.y, 0.0]
}

/// tanh of each coordinate, scaled by sec(y) + effect·π: a funnel opening along the bands
/// where cos y vanishes.
#[inline(always)]
fn funnel(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [effect] = v.params();
    let k = 1.0 / zeps(t.y.fcos()) + effect * PI;
    [v.w * (t.x.tanh() * k), v.w * (t.y.tanh() * k), 0.0]
}

/// mask: sin³x·(cosh y + 1) and sin²x·cos x·(cosh y + 1), divided by r².
#[inline(always)]
fn mask(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let d = v.w / zeps(t.sumsq);
    let (sx, cx) = (t.x.fsin(), t.x.fcos());
    let sx2 = sx * sx;
    let ch = fm::cosh(t.y) + 1.0;
    [d * sx * ch * sx2, d * cx * ch * sx2, 0.0]
}

/// petal: cos x·(cos x·cos y)³ and cos x·(sin x·cos y)³.
#[inline(always)]
fn petal(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (sx, cx) = (t.x.fsin(), t.x.fcos());
    let cy = t.y.fcos();
    let a = cx * cy;
    let b = sx * cy;
    [v.w * cx * (a * a * a), v.w * cx * (b * b * b), 0.0]
}

/// Replaces negatives and non-finite values with 0 (Fractorium's guard before a square root).
#[inline(always)]
fn finite_non_negative(x: f64) -> f64 {
    if x < 0.0 || !x.is_finite() { 0.0 } else { x }
}

/// Rays from the axes: r²/x and r²/y scaled by 1/tan(r) (plus a weight-dependent constant),
/// z scaled by the weight. Replaces the x and y that earlier variations summed.
#[inline(always)]
fn rays1(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let u = 1.0 / zeps(t.sqrt.tan()) + v.w * (FRAC_2_PI * FRAC_2_PI);
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    let k = v.w * u;
    [k * t.sumsq / zeps(t.x), k * t.sumsq / zeps(t.y), v.w * t.z]
}

/// Rays from the axes: r²/x and r²/y scaled by sec(r²·tan(1/r²)) and w/10, z scaled by the
/// weight. Replaces the x and y that earlier variations summed.
#[inline(always)]
fn rays2(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = t.sumsq;
    let u = 1.0 / (r2 * (1.0 / zeps(r2)).tan()).fcos();
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    let k = v.w / 10.0 * u;
    [k * r2 / zeps(t.x), k * r2 / zeps(t.y), v.w * t.z]
}

/// Rays from the axes: r²/x and r²/y modulated by cos(r²) and tan(r²) and a factor built from
/// r⁴, z scaled by the weight. Replaces the x and y that earlier variations summed.
#[inline(always)]
fn rays3(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = t.sumsq;
    let r4 = r2 * r2;
    let u = 1.0 / (r4.fsin() * (1.0 / zeps(r4)).fsin()).fcos().sqrt();
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    let k = v.w / 10.0 * u;
    [
        k * r2.fcos() * r2 / zeps(t.x),
        k * r2.tan() * r2 / zeps(t.y),
        v.w * t.z,
    ]
}

/// x scaled by tanh(r²), y by cos(r²): horizontal saturation and vertical rippling.
#[inline(always)]
fn rippled(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let d = zeps(t.sumsq);
    let h = v.w / 2.0;
    [
        h * (d.tanh() * (2.0 * t.x)),
        h * (d.fcos() * (2.0 * t.y)),
        0.0,
    ]
}

/// A logistic squashing of each axis into (-|w|, |w|); |shift| < 1 uses the reciprocal
/// steepness and flips by the shift's sign.
#[inline(always)]
fn sigmoid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sx, sy, ax, ay, vv] = v.derived();
    let c0 = ax / zeps(1.0 + (sx * t.x).exp());
    let c1 = ay / zeps(1.0 + (sy * t.y).exp());
    [vv * (2.0 * (c0 - 0.5)), vv * (2.0 * (c1 - 0.5)), 0.0]
}

fn sigmoid_prep(v: &mut Prepared) {
    let [shiftx, shifty] = v.params();
    let steep = |shift: f64| -> (f64, f64) {
        if shift < 1.0 && shift > -1.0 {
            if shift == 0.0 {
                (f64::EPSILON, 1.0)
            } else {
                (1.0 / shift, if shift < 0.0 { -1.0 } else { 1.0 })
            }
        } else {
            (shift, 1.0)
        }
    };
    let (sx, ax) = steep(shiftx);
    let (sy, ay) = steep(shifty);
    let vv = v.w.abs();
    v.p.extend([sx * -5.0, sy * -5.0, ax, ay, vv]);
}

/// sin of each coordinate times a quadratic "range" factor (its square plus w, minus w·r²).
#[inline(always)]
fn sintrange(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.params();
    let (xx, yy) = (t.x * t.x, t.y * t.y);
    let m = (xx + yy) * k;
    [
        v.w * t.x.fsin() * (xx + k - m),
        v.w * t.y.fsin() * (yy + k - m),
        0.0,
    ]
}

/// Wing-like spirals: (cos x², sin x²)·sin y² / r².
#[inline(always)]
fn spiralwing(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let inv = 1.0 / zeps(t.sumsq);
    let a = zeps(t.x * t.x);
    let b = zeps(t.y * t.y);
    let (sa, ca) = a.fsin_cos();
    let sb = b.fsin();
    [v.w * (inv * ca * sb), v.w * (inv * sa * sb), 0.0]
}

/// (cos u·tan x, sin u·tan y) with u = √(a x² + b y²).
#[inline(always)]
fn squirrel(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b] = v.params();
    let u = finite_non_negative(zeps(a) * (t.x * t.x) + zeps(b) * (t.y * t.y)).sqrt();
    let (s, c) = u.fsin_cos();
    [c * t.x.tan() * v.w, s * t.y.tan() * v.w, 0.0]
}

/// Twin interference: w·p plus (x² − y²)/(x² + y²)·sin(2π·distort·(x + y)) of the scaled
/// point, added to both coordinates.
#[inline(always)]
fn stwin(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [distort] = v.params();
    let x = t.x * v.w * 0.05;
    let y = t.y * v.w * 0.05;
    let (xx, yy) = (x * x, y * y);
    let sum2 = xx + yy;
    let mut e = (xx - yy) * (TAU * distort * (x + y)).fsin();
    e /= if sum2 != 0.0 { sum2 } else { 1.0 };
    [v.w * t.x + e, v.w * t.y + e, 0.0]
}

/// tancos: x scaled by tanh(r²)/r² and y by cos(r²)/r² (doubled).
#[inline(always)]
fn tancos(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let d = zeps(t.sumsq);
    let k = v.w / d;
    [
        k * (d.tanh() * (2.0 * t.x)),
        k * (d.fcos() * (2.0 * t.y)),
        0.0,
    ]
}
