//! JWildfire's formulas for variations it runs after the others (priority 1) where flam3 or
//! Fractorium run them with the others. Each reads its registry entry's parameters (see
//! [`super::FORMULAS`]) and returns the new sum.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::TAU;

use crate::flame::fastmath::FastTrig;
use crate::flame::variations::*;

/// farblur: the sum so far moved in a random direction of 3-D space by the weight times its
/// squared distance from the origin point times (ξ₁ + ξ₂ + ξ₃ + ξ₄ − 2) (JWildfire 9.00,
/// `FarBlurFunc`, which keeps the four numbers in a ring and renews one per point: each point
/// sees the same distribution of their sum).
pub(super) fn farblur(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sx, sy, sz, x0, y0, z0] = v.params();
    let (dx, dy, dz) = (t.x - x0, t.y - y0, t.z - z0);
    let spread = rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0;
    let r = v.w * (dx * dx + dy * dy + dz * dz) * spread;
    let (su, cu) = (rng.f01() * TAU).fsin_cos();
    let (sv, cv) = (rng.f01() * TAU).fsin_cos();
    [
        t.x + sx * r * sv * cu,
        t.y + sy * r * sv * su,
        t.z + sz * r * cv,
    ]
}

/// post_depth: the sum so far (x, y, z) moved by the weight times the point the regular
/// variations saw plus the sum scaled by |z|^power (JWildfire 9.00, `PostDepthFunc`, after
/// Zy0rg's "Blur Package"). The input `t` is that affine point
/// ([`flag::READS_AFFINE_POINT`]); the sum is read from `acc`.
pub(super) fn post_depth(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [power] = v.params();
    let mut k = acc.z.abs();
    if k != 0.0 && power != 1.0 {
        k = (k.ln() * power).exp();
    }
    [
        acc.x + v.w * (t.x + acc.x * k),
        acc.y + v.w * (t.y + acc.y * k),
        acc.z + v.w * (t.z + acc.z * k),
    ]
}
