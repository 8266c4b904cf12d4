//! JWildfire's symmetries applied after an xform's variations: `post_point_symmetry_wf` (the
//! point turned about a centre by a random multiple of 360°/order) and `post_axis_symmetry_wf`
//! (the point moved to a random side of an axis, the two sides half a weight apart and turned
//! against each other), each shifting the colour per copy.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew, its quirks included (the y axis's second side shifts the colour only when
//! turned; the z axis's turned z is measured from centre_y).

use std::f64::consts::TAU;

use super::*;

/// JWildfire's `EPSILON`: smaller weights and angles count as 0.
const EPSILON: f64 = 1e-8;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("post_point_symmetry_wf", post_point_symmetry_wf)
        .params(&[
            p("post_point_symmetry_wf_centre_x", 0.25),
            p("post_point_symmetry_wf_centre_y", 0.5),
            p_int("post_point_symmetry_wf_order", 3.0, 1.0, INF),
            p("post_point_symmetry_wf_colorshift", 0.0),
        ])
        .flags(SYMMETRY),
    VarDef::new("post_axis_symmetry_wf", post_axis_symmetry_wf)
        .params(&[
            p_int("post_axis_symmetry_wf_axis", 0.0, 0.0, 2.0),
            p("post_axis_symmetry_wf_centre_x", 0.25),
            p("post_axis_symmetry_wf_centre_y", 0.5),
            p("post_axis_symmetry_wf_centre_z", 0.5),
            p("post_axis_symmetry_wf_rotation", 30.0),
            p("post_axis_symmetry_wf_x1colorshift", 0.0),
            p("post_axis_symmetry_wf_y1colorshift", 0.0),
            p("post_axis_symmetry_wf_z1colorshift", 0.0),
            p("post_axis_symmetry_wf_x2colorshift", 0.0),
            p("post_axis_symmetry_wf_y2colorshift", 0.0),
            p("post_axis_symmetry_wf_z2colorshift", 0.0),
        ])
        .flags(SYMMETRY | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_axis),
];

const SYMMETRY: u32 =
    flag::JWILDFIRE | flag::POST_ONLY | flag::RANDOM | flag::USES_COLOR | flag::SETS_COLOR;

/// post_point_symmetry_wf: the offset from the centre, scaled by the weight, turned by a
/// random one of `order` equal steps; the colour shifted by `colorshift` per step.
fn post_point_symmetry_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [cx, cy, order, colorshift] = v.params();
    let (dx, dy) = ((t.x - cx) * v.w, (t.y - cy) * v.w);
    let idx = (rng.f01() * order).trunc();
    let (s, c) = (idx * TAU / order).sin_cos();
    acc.color = (acc.color + idx * colorshift) % 1.0;
    [cx + dx * c + dy * s, cy + dy * c - dx * s, t.z]
}

/// Derived values of post_axis_symmetry_wf: sin and cos of half the rotation, whether it
/// turns at all (1 or 0), half the weight.
fn prep_axis(v: &mut Prepared) {
    let [_, _, _, _, rotation] = v.params();
    let a = rotation * TAU / 180.0 / 2.0;
    let turns = if a.abs() > EPSILON { 1.0 } else { 0.0 };
    let half = v.w / 2.0;
    v.p.extend_from_slice(&[a.sin(), a.cos(), turns, half]);
}

/// post_axis_symmetry_wf: along the axis (0 x, 1 y, 2 z), the point on one side or the
/// other (odds ½), half a weight apart, each side turned by ± half the rotation (in the
/// plane of x and y, or of x and z for the z axis); the colour shifted per side.
fn post_axis_symmetry_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [axis, cx, cy, cz, _, x1, y1, z1, x2, y2, z2] = v.params();
    let [sa, ca, turns, half] = v.derived();
    if v.w.abs() <= EPSILON {
        return [t.x, t.y, t.z];
    }
    let first = rng.f01() < 0.5;
    let sign = if first { 1.0 } else { -1.0 };
    // The point (u, w) offset from (cu, cw), turned, placed about (ou, ow).
    let turn = |u: f64, w: f64, cu: f64, cw: f64, ou: f64, ow: f64| {
        if turns == 0.0 {
            return (u, w);
        }
        let (du, dw) = (u - cu, w - cw);
        (ou + du * ca + sign * dw * sa, ow + dw * ca - sign * du * sa)
    };
    let shift = |c: f64, s: f64| (c + s) % 1.0;
    match axis as i32 {
        0 => {
            let x = cx + sign * (t.x - cx + half);
            let (x, y) = turn(x, t.y, cx, cy, cx, cy);
            acc.color = shift(acc.color, if first { x1 } else { x2 });
            [x, y, t.z]
        }
        1 => {
            let y = cy + sign * (t.y - cy + half);
            let (x, y) = turn(t.x, y, cx, cy, cx, cy);
            if first {
                acc.color = shift(acc.color, y1);
            } else if turns != 0.0 {
                acc.color = shift(acc.color, y2);
            }
            [x, y, t.z]
        }
        _ => {
            let z = cz + sign * (t.z - cz + half);
            let (x, z) = turn(t.x, z, cx, cz, cx, cy);
            acc.color = shift(acc.color, if first { z1 } else { z2 });
            [x, t.y, z]
        }
    }
}
