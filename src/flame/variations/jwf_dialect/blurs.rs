//! JWildfire's formulas for blurs of Fractorium's catalogue, where they differ from
//! Fractorium's: Xyrus02's `falloff2` (random amounts in [0, 1) rather than centred ones, its
//! radial style's z, its draws in JWildfire's order) and JWildfire's `post_falloff2`, which
//! adds the blurred sum to the sum (Fractorium's post form replaces it).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{PI, TAU};

use crate::flame::variations::*;

/// falloff2's parameters with JWildfire's limits (the `post_` form's names add the prefix).
const FALLOFF2_PARAMS: &[Param] = &[
    p_range("falloff2_scatter", 1.0, 1e-6, f64::INFINITY),
    p_range("falloff2_mindist", 0.5, 0.0, f64::INFINITY),
    p_range("falloff2_mul_x", 1.0, 0.0, 1.0),
    p_range("falloff2_mul_y", 1.0, 0.0, 1.0),
    p_range("falloff2_mul_z", 0.0, 0.0, 1.0),
    p_range("falloff2_mul_c", 0.0, 0.0, 1.0),
    p("falloff2_x0", 0.0),
    p("falloff2_y0", 0.0),
    p("falloff2_z0", 0.0),
    p_int("falloff2_invert", 0.0, 0.0, 1.0),
    p_int("falloff2_type", 0.0, 0.0, 2.0),
];

const FALLOFF2_FLAGS: u32 = flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR;

pub(in crate::flame::variations) const DEFS: &[VarDef] = &[
    VarDef::new("falloff2", falloff2)
        .params(FALLOFF2_PARAMS)
        .flags(FALLOFF2_FLAGS),
    VarDef::new("post_falloff2", falloff2)
        .params(FALLOFF2_PARAMS)
        .flags(FALLOFF2_FLAGS)
        .sum(),
];

/// Xyrus02's falloff2 as JWildfire computes it: a blur growing with the distance from
/// (x0, y0, z0) beyond `mindist` (0.04·scatter per unit), of the box (type 0), radial (1) or
/// Gaussian (2) kind; `mul_c` shifts the colour by a random part of it.
fn falloff2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scatter, mindist, mx, my, mz, mc, x0, y0, z0, invert, kind] = v.params();
    let (x, y, z) = (t.x, t.y, t.z);
    let mut d = ((x - x0) * (x - x0) + (y - y0) * (y - y0) + (z - z0) * (z - z0)).sqrt();
    if invert != 0.0 {
        d = 1.0 - d;
    }
    d = ((d.max(0.0) - mindist) * (0.04 * scatter)).max(0.0);
    let w = v.w;
    let out = match kind as i32 {
        1 => {
            let r_in = (x * x + y * y + z * z).sqrt() + 1e-6;
            let sigma = (z / r_in).asin() + mz * rng.f01() * d;
            let phi = y.atan2(x) + my * rng.f01() * d;
            let r = r_in + mx * rng.f01() * d;
            let (ss, cs) = sigma.sin_cos();
            let (sp, cp) = phi.sin_cos();
            [w * (r * cs * cp), w * (r * cs * sp), w * ss]
        }
        2 => {
            let sigma = d * rng.f01() * TAU;
            let phi = d * rng.f01() * PI;
            let r = d * rng.f01();
            let (ss, cs) = sigma.sin_cos();
            let (sp, cp) = phi.sin_cos();
            [
                w * (x + mx * r * cs * cp),
                w * (y + my * r * cs * sp),
                w * (z + mz * r * ss),
            ]
        }
        _ => [
            w * (x + mx * rng.f01() * d),
            w * (y + my * rng.f01() * d),
            w * (z + mz * rng.f01() * d),
        ],
    };
    let c = acc.color + mc * rng.f01() * d;
    acc.color = (c - c.trunc()).abs();
    out
}
