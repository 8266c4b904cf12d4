//! JWildfire's `glynnSim1` (eralex61's GlynnSim1), whose parameters JWildfire keeps otherwise
//! than Fractorium: `pow` any value (1.5 by default, where Fractorium's lies in [0, 1]) and
//! `contrast` in [0, 1] (0.5 by default), `phi1` 110 degrees by default.
//!
//! The formula follows JWildfire's (LGPL-2.1) `GlynnSim1Func`, written anew.

use std::f64::consts::PI;

use crate::flame::variations::*;

pub(in crate::flame::variations) const DEFS: &[VarDef] = &[VarDef::new("glynnSim1", glynnsim1)
    .params(&[
        p("glynnSim1_radius", 1.0),
        p("glynnSim1_radius1", 0.1),
        p("glynnSim1_phi1", 110.0),
        p_range("glynnSim1_thickness", 0.1, 0.0, 1.0),
        p_range("glynnSim1_contrast", 0.5, 0.0, 1.0),
        p("glynnSim1_pow", 1.5),
    ])
    .flags(flag::RANDOM)
    .prepare(glynnsim1_prepare)];

/// Derived: the small circle's centre (radius at angle `phi1`) and |pow|.
fn glynnsim1_prepare(v: &mut Prepared) {
    let [radius, _, phi1, _, _, pow] = v.params();
    let (s, c) = (PI * phi1 / 180.0).sin_cos();
    v.p.extend_from_slice(&[radius * c, radius * s, pow.abs()]);
}

/// A random point of the ring about (cx, cy) from `thickness`·radius1 to radius1.
fn ring(radius1: f64, thickness: f64, cx: f64, cy: f64, rng: &mut FastRng) -> (f64, f64) {
    let r = radius1 * (thickness + (1.0 - thickness) * rng.f01());
    let (s, c) = (2.0 * PI * rng.f01()).sin_cos();
    (r * c + cx, r * s + cy)
}

/// glynnSim1: inside the circle of `radius` a point of the small ring about the circle's point
/// at `phi1`; outside, the point pulled in by (radius/r)² with probability
/// `contrast`·(radius/r)^|pow|, replaced by a ring point when it lands in the small circle.
fn glynnsim1(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, radius1, _, thickness, contrast] = v.params();
    let [cx, cy, abs_pow] = v.derived();
    let r = (t.x * t.x + t.y * t.y).sqrt();
    let alpha = radius / r;
    let (x, y) = if r < radius {
        ring(radius1, thickness, cx, cy, rng)
    } else {
        let (x, y) = if rng.f01() > contrast * alpha.powf(abs_pow) {
            (t.x, t.y)
        } else {
            (alpha * alpha * t.x, alpha * alpha * t.y)
        };
        if (x - cx) * (x - cx) + (y - cy) * (y - cy) < radius1 * radius1 {
            ring(radius1, thickness, cx, cy, rng)
        } else {
            (x, y)
        }
    };
    [v.w * x, v.w * y, v.default_z(t)]
}
