//! JWildfire's formulas for direct-colour variations of Fractorium's catalogue, where they
//! differ from Fractorium's: `dc_perlin` with JWildfire's noise (exact skew factors, every
//! coordinate scaled per octave), its signed square edge and its `color_only` switch (the
//! input point, not a random one, is coloured; with weight 0 as well).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::TAU;

use super::SMALL_EPSILON;
use crate::flame::variations::noise::jwf_fractal_noise;
use crate::flame::variations::*;

pub(in crate::flame::variations) const DEFS: &[VarDef] = &[VarDef::new("dc_perlin", dc_perlin)
    .params(&[
        p_int("dc_perlin_shape", 0.0, 0.0, 2.0),
        p_int("dc_perlin_map", 0.0, 0.0, 5.0),
        p_range("dc_perlin_select_centre", 0.0, -1.0, 1.0),
        p_range("dc_perlin_select_range", 1.0, 0.1, 2.0),
        p("dc_perlin_centre", 0.25),
        p("dc_perlin_range", 0.25),
        p("dc_perlin_edge", 0.0),
        p("dc_perlin_scale", 1.0),
        p_int("dc_perlin_octaves", 2.0, 1.0, 5.0),
        p("dc_perlin_amps", 2.0),
        p("dc_perlin_freqs", 2.0),
        p("dc_perlin_z", 0.0),
        // Rejection draws of 5 octaves of noise each: 100 are tens of microseconds.
        p_int("dc_perlin_select_bailout", 10.0, 2.0, 100.0).limited(),
        p_int("dc_perlin_color_only", 0.0, 0.0, 1.0),
    ])
    .flags(flag::RANDOM | flag::SETS_COLOR)
    .prepare(super::super::fr_direct_colour::dc_perlin_prepare)];

/// The blur point of `shape` (square, disc, radial) and its edge weight; with `color_only`
/// the square's point is the input point moved by −½.
fn perlin_sample(
    shape: i32,
    edge: f64,
    color_only: bool,
    t: &VarIn,
    rng: &mut FastRng,
) -> (f64, f64, f64) {
    let edge_of = |r: f64| {
        if r > 1.0 - edge {
            0.5 * (r - 1.0 + edge) / edge
        } else {
            0.0
        }
    };
    match shape {
        0 => {
            let (sx, sy) = if color_only {
                (t.x, t.y)
            } else {
                (rng.f01(), rng.f01())
            };
            let vx = (1.0 + edge) * (sx - 0.5);
            let vy = (1.0 + edge) * (sy - 0.5);
            // JWildfire keeps the sign of the larger coordinate.
            let r = if vx * vx > vy * vy { vx } else { vy };
            (vx, vy, edge_of(r))
        }
        1 => {
            let mut r = rng.f01() + rng.f01();
            if r > 1.0 {
                r = 2.0 - r;
            }
            r *= 1.0 + edge;
            let e = edge_of(r);
            let (s, c) = (rng.f01() * TAU).sin_cos();
            (0.5 * r * s, 0.5 * r * c, e)
        }
        _ => {
            let r = (1.0 + edge) * rng.f01();
            let e = edge_of(r);
            let (s, c) = (rng.f01() * TAU).sin_cos();
            (0.5 * r * s, 0.5 * r * c, e)
        }
    }
}

/// slobo777's dc_perlin as JWildfire computes it: a blur whose samples are kept when a 3-D
/// fractal simplex noise, read through one of six mappings, falls in a band; the noise sets
/// the colour. With weight 0 the input point itself is coloured.
pub(super) fn dc_perlin(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        shape,
        map,
        _,
        _,
        centre,
        range,
        edge,
        scale,
        octaves,
        amps,
        freqs,
        z,
        bailout,
        color_only,
    ] = v.params();
    let [notch_bottom, notch_top] = v.derived();
    let (shape, octaves, bailout) = (shape as i32, octaves as i32, bailout as i32);
    let mut tries = 0;
    let (mut vx, mut vy, mut noise);
    loop {
        let mut e = 0.0;
        if v.w == 0.0 {
            (vx, vy) = (t.x, t.y);
        } else {
            (vx, vy, e) = perlin_sample(shape, edge, color_only > 0.0, t, rng);
        }
        let d2 = vx * vx + vy * vy;
        let pos = match map as i32 {
            0 => [vx, vy, z],
            1 => [vx / (d2 + SMALL_EPSILON), vy / (d2 + SMALL_EPSILON), z],
            2 => [vx / (d2 + 0.5), vy / (d2 + 0.5), z],
            3 => [vx / (d2 + 0.25), vy / (d2 + 0.25), z],
            m => {
                let h = (0.25 - d2).abs().sqrt();
                let lift = if m == 4 { h } else { 2.0 * h };
                [vx, vy, lift + z]
            }
        };
        noise = jwf_fractal_noise(pos.map(|c| scale * c), amps, freqs, octaves);
        e = if noise > 0.0 {
            noise * (1.0 + e * e * 20.0) + 2.0 * e
        } else {
            noise * (1.0 + e * e * 20.0) - 2.0 * e
        };
        let rejected = e < notch_bottom || e > notch_top;
        let again = rejected && tries < bailout;
        tries += 1;
        if !again {
            break;
        }
    }
    let col = centre + range * noise;
    acc.color = col - col.floor();
    [v.w * vx, v.w * vy, 0.0]
}
