//! JWildfire's `mobius_strip`, a variation of its own under a name Fractorium also uses: the
//! plane wrapped onto a strip with a whole number of half twists, its x range mapped around
//! the strip and its y range across it, each range wrapped, clamped, hidden or left alone
//! outside (Fractorium's maps a rectangle with one twist and no modes).
//!
//! The formula follows JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{PI, TAU};

use crate::flame::variations::*;

pub(in crate::flame::variations) const DEFS: &[VarDef] =
    &[VarDef::new("mobius_strip", mobius_strip)
        .params(&[
            p("mobius_strip_radius", 1.0),
            p("mobius_strip_width", 1.0),
            p("mobius_strip_range x", 1.0),
            p("mobius_strip_range y", 1.0),
            p("mobius_strip_rotate x", 0.0),
            p("mobius_strip_rotate y", 0.0),
            p("mobius_strip_twists", 1.0),
            p("mobius_strip_modify z", 1.0),
            p("mobius_strip_width mode", 0.0),
            p("mobius_strip_radial mode", 0.0),
        ])
        .flags(flag::WRITES_Z | flag::READS_ACC | flag::HIDES)
        .prepare(mobius_strip_prepare)];

/// What a range does with a coordinate outside it.
const WRAP: i32 = 0;
const EDGE: i32 = 1;
const HIDE: i32 = 2;
const LEAVE: i32 = 3;

/// JWildfire's modes: a whole number 0–3, anything else wraps.
fn mode(v: f64) -> i32 {
    match v as i32 {
        m @ 0..=3 => m,
        _ => WRAP,
    }
}

fn mobius_strip_prepare(v: &mut Prepared) {
    let [_, _, _, _, rx, ry] = v.params();
    let (sx, cx) = (rx * TAU).sin_cos();
    let (sy, cy) = (ry * TAU).sin_cos();
    v.p.extend_from_slice(&[sx, cx, sy, cy]);
}

/// A coordinate of the range [−range/2, range/2] in `mode` (wrapped by Java's remainder or
/// clamped; hidden and left points are handled before).
fn into_range(c: f64, range: f64, mode: i32) -> f64 {
    let half = range / 2.0;
    match mode {
        WRAP => c % half,
        EDGE if c > half => half,
        EDGE if c < -half => -half,
        _ => c,
    }
}

/// mobius_strip (JWildfire's): x goes around the strip (the range onto a full turn), y across
/// it (the range onto the width), the strip turning `twists` half turns; then rotated about
/// y and x.
fn mobius_strip(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [
        radius,
        width,
        range_x,
        range_y,
        _,
        _,
        twists,
        modify_z,
        wmode,
        rmode,
    ] = v.params();
    let [rx_sin, rx_cos, ry_sin, ry_cos] = v.derived();
    let (wmode, rmode) = (mode(wmode), mode(rmode));
    let (x, y) = (t.x, t.y);
    let out_x = x > range_x / 2.0 || x < -range_x / 2.0;
    let out_y = y > range_y / 2.0 || y < -range_y / 2.0;
    if (rmode == HIDE && out_x) || (wmode == HIDE && out_y) {
        acc.hide = true;
        return [0.0; 3];
    }
    if (rmode == LEAVE && out_x) || (wmode == LEAVE && out_y) {
        // Added unweighted, with no z.
        return [x, y, 0.0];
    }
    let tt = if range_x == 0.0 {
        0.0
    } else {
        into_range(x, range_x, rmode) * (PI / (range_x / 2.0)) + PI
    };
    let s = if range_y == 0.0 {
        0.0
    } else {
        into_range(y, range_y, wmode) * ((width / 2.0) / (range_y / 2.0))
    };
    let twists = twists.trunc();
    let (st, ct) = (twists * tt / 2.0).sin_cos();
    let (mx, my, mz) = (
        (radius + s * ct) * tt.cos(),
        (radius + s * ct) * tt.sin(),
        s * st,
    );
    let (rx, ry, rz) = (mx, my * ry_cos + mz * ry_sin, mz * ry_cos - my * ry_sin);
    let (mx, my, mz) = (rx * rx_cos - rz * rx_sin, ry, rz * rx_cos + rx * rx_sin);
    let z = if modify_z != 0.0 {
        v.w * mz * modify_z
    } else {
        v.w * acc.z
    };
    [v.w * mx, v.w * my, z]
}
