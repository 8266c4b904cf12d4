//! Simple moves from Fractorium's catalogue: the linear variants (`linear3D`, `linearT`),
//! rotations (`rotate`, `rotate_x/y/z`), `shift`, mirrors and flips, point symmetry, and the
//! helpers that only touch z (`flatten`, `extrude`, `zcone`, `zscale`, `ztranslate`).
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::util::{signed_pow, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("extrude", extrude)
        .params(&[p("extrude_root_face", 0.5)])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::WRITES_ACC),
    super::inlined!("flatten", flatten).flags(flag::WRITES_ACC | flag::WRITES_Z),
    super::inlined!("flipx", flipx),
    super::inlined!("flipy", flipy),
    super::inlined!("linear3D", linear3d).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("linearT", linear_t).params(&[p("linearT_powX", 1.0), p("linearT_powY", 1.0)]),
    super::inlined!("linearT3D", linear_t3d)
        .params(&[
            p("linearT3D_powX", 1.0),
            p("linearT3D_powY", 1.0),
            p("linearT3D_powZ", 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("mirror_x", mirror::<0>).flags(MIRROR_FLAGS),
    VarDef::new("mirror_y", mirror::<1>).flags(MIRROR_FLAGS),
    VarDef::new("mirror_z", mirror::<2>).flags(MIRROR_FLAGS),
    super::inlined!("point_symmetry", point_symmetry)
        .params(&[
            p("point_symmetry_centre_x", 0.15),
            p("point_symmetry_centre_y", 0.5),
            p("point_symmetry_order", 3.0),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_point_symmetry),
    super::inlined!("rotate", rotate)
        .params(&[p("rotate_angle", 0.0)])
        .prepare(rotate_prep),
    super::inlined!("rotate_x", rotate_x)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(quarter_turns_prep),
    super::inlined!("rotate_y", rotate_y)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(quarter_turns_prep),
    super::inlined!("rotate_z", rotate_z)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(quarter_turns_prep),
    super::inlined!("shift", shift)
        .params(&[p("shift_x", 0.0), p("shift_y", 0.0), p("shift_angle", 0.0)])
        .prepare(shift_prep),
    super::inlined!("zcone", zcone)
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::WRITES_Z),
    super::inlined!("zscale", zscale).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("ztranslate", ztranslate)
        .flags(flag::WRITES_Z)
        .sum(),
];

/// Gives the point a random depth: z = max(weight, 0) with probability `root_face`, else uniform
/// in [0, weight). As a regular variation it contributes nothing to x, y and overwrites the
/// running z; as pre_/post_ it keeps x, y.
#[inline(always)]
fn extrude(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [root_face] = v.params();
    let z = if rng.f01() < root_face {
        v.w.max(0.0)
    } else {
        v.w * rng.f01()
    };
    if v.form == Form::Regular {
        acc.z = z;
        [0.0, 0.0, 0.0]
    } else {
        [t.x, t.y, z]
    }
}

/// Drops the z coordinate: as a regular variation it zeroes the xform's running z and adds
/// nothing; as pre_/post_ it keeps x and y and sets z to 0. A JWildfire flame's `flatten`
/// moved before or after the others by its priority adds its output to the point
/// ([`Assign::Sum`]), and still only clears z, as JWildfire 9.00's `FlattenFunc` does
/// (`pVarTP.z = 0`).
#[inline(always)]
fn flatten(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    match (v.form, v.assign) {
        (Form::Regular, _) | (Form::Post, Assign::Sum) => {
            // After the others the point is the running sum.
            acc.z = 0.0;
            [0.0, 0.0, 0.0]
        }
        (Form::Pre, Assign::Sum) => [0.0, 0.0, -t.z],
        _ => [t.x, t.y, 0.0],
    }
}

/// Mirrors the lower half-plane (y > 0) left to right.
#[inline(always)]
fn flipx(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let x = if t.y > 0.0 { -(v.w * t.x) } else { v.w * t.x };
    [x, v.w * t.y, 0.0]
}

/// Mirrors the right half-plane (x > 0) top to bottom.
#[inline(always)]
fn flipy(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let y = if t.x > 0.0 { -(v.w * t.y) } else { v.w * t.y };
    [v.w * t.x, y, 0.0]
}

const MIRROR_FLAGS: u32 = flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC;

/// linear3D: the identity in 3-D, scaled by the weight.
#[inline(always)]
fn linear3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w * t.x, v.w * t.y, v.w * t.z]
}

/// linearT: each coordinate raised to its own power, keeping its sign.
#[inline(always)]
fn linear_t(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [pow_x, pow_y] = v.params();
    [
        signed_pow(t.x, pow_x) * v.w,
        signed_pow(t.y, pow_y) * v.w,
        0.0,
    ]
}

/// linearT3D: linearT in 3-D (z with its own power).
#[inline(always)]
fn linear_t3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [pow_x, pow_y, pow_z] = v.params();
    [
        signed_pow(t.x, pow_x) * v.w,
        signed_pow(t.y, pow_y) * v.w,
        signed_pow(t.z, pow_z) * v.w,
    ]
}

/// mirror_x / mirror_y / mirror_z: the point itself with axis `AXIS` folded to a random side
/// (±|coordinate|). Unweighted; as a regular variation it replaces what earlier variations
/// summed.
fn mirror<const AXIS: usize>(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let mut o = [t.x, t.y, t.z];
    o[AXIS] = o[AXIS].abs();
    if rng.bit() {
        o[AXIS] = -o[AXIS];
    }
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    o
}

fn prep_point_symmetry(v: &mut Prepared) {
    let [_, _, order] = v.params();
    v.p.push(TAU / zeps(order));
}

/// point_symmetry: rotates the point (scaled by the weight about the centre) about the centre
/// by a random multiple of 2π/order.
#[inline(always)]
fn point_symmetry(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [cx, cy, order] = v.params();
    let [step] = v.derived();
    let ang = (rng.f01() * order).floor() * step;
    let dx = (t.x - cx) * v.w;
    let dy = (t.y - cy) * v.w;
    let (s, c) = (ang.fsin(), ang.fcos());
    [cx + dx * c + dy * s, cy + dy * c - dx * s, 0.0]
}

/// sin and cos of the angle `deg` given in degrees.
fn degrees_sin_cos(deg: f64) -> (f64, f64) {
    (deg / 180.0 * PI).fsin_cos()
}

/// A rotation of the plane by `angle` degrees.
#[inline(always)]
fn rotate(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    [v.w * (t.x * c - t.y * s), v.w * (t.x * s + t.y * c), 0.0]
}

/// sin and cos of rotate's angle (in degrees).
fn rotate_prep(v: &mut Prepared) {
    let [angle] = v.params();
    v.p.extend(<[f64; 2]>::from(degrees_sin_cos(angle)));
}

/// sin and cos of shift's angle (in degrees).
fn shift_prep(v: &mut Prepared) {
    let [_, _, angle] = v.params();
    v.p.extend(<[f64; 2]>::from(degrees_sin_cos(angle)));
}

/// sin and cos of a quarter turn times the weight (the rotate_x/y/z angle).
fn quarter_turns_prep(v: &mut Prepared) {
    let (s, c) = (v.w * FRAC_PI_2).fsin_cos();
    v.p.extend([s, c]);
}

/// A 3-D rotation about the x axis by w quarter turns (the weight is the angle). x passes
/// through unweighted, replacing the x that earlier variations summed.
#[inline(always)]
fn rotate_x(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    if v.form == Form::Regular {
        acc.x = 0.0;
    }
    [t.x, s * t.z + c * t.y, c * t.z - s * t.y]
}

/// A 3-D rotation about the y axis by w quarter turns (the weight is the angle). y passes
/// through unweighted, replacing the y that earlier variations summed.
#[inline(always)]
fn rotate_y(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    let y = if v.form == Form::Regular {
        acc.y = t.y;
        0.0
    } else {
        t.y
    };
    [c * t.x - s * t.z, y, s * t.x + c * t.z]
}

/// A rotation about the z axis by w quarter turns (the weight is the angle). z passes through
/// unweighted, replacing the z that earlier variations summed.
#[inline(always)]
fn rotate_z(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    if v.form == Form::Regular {
        acc.z = 0.0;
    }
    [s * t.y + c * t.x, c * t.y - s * t.x, t.z]
}

/// A translation by (x, y) rotated by `angle` degrees (the y offset mirrored).
#[inline(always)]
fn shift(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [dx, dy] = v.params();
    let [s, c] = v.derived();
    [
        v.w * (t.x + c * dx - s * dy),
        v.w * (t.y - c * dy - s * dx),
        0.0,
    ]
}

/// zcone: z set to the distance from the z axis (a cone); as a pre_/post_ form x and y pass
/// through.
#[inline(always)]
fn zcone(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let z = v.w * t.sqrt;
    if v.form == Form::Regular {
        [0.0, 0.0, z]
    } else {
        [t.x, t.y, z]
    }
}

/// zscale: z scaled by the weight (x, y contribute nothing).
#[inline(always)]
fn zscale(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [0.0, 0.0, v.w * t.z]
}

/// ztranslate: z shifted by the weight.
#[inline(always)]
fn ztranslate(v: &Prepared, _: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [0.0, 0.0, v.w]
}
