//! Two more of JWildfire's escape-time crops of the summed point: `post_asurf_crop` (Jesus
//! Sosa's "amazing surface": a box fold of x and y (and z with `mode` 0), a ball fold between
//! `minR` and `maxR`, a turn by `angle` degrees about (rot_x, rot_y, rot_z), plus the start)
//! and `post_mandelbulb3d_crop` (Whittaker Courtney's crop by Inigo Quilez's Mandelbulb,
//! hiding the points whose last iteration escapes; with `filled` it crops a random point of a
//! cube instead), and JWildfire's internal `_slice_indicator_wf` (colours the points whose z
//! lies within `thickness` of one of two slice positions, for its slice preview).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew, quirks included (the weight
//! is applied once per iteration, so it acts as a power).

use std::f64::consts::{PI, TAU};

use super::jwf_d_crops::crop_steps;
use super::*;

const CROP: u32 = flag::JWILDFIRE | flag::POST_ONLY | flag::USES_Z | flag::WRITES_Z;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("post_asurf_crop", asurf_crop)
        .params(&[
            p_int("post_asurf_crop_iterations", 12.0, 0.0, 250.0),
            p("post_asurf_crop_bailout", 16.0),
            p("post_asurf_crop_scaleX", 1.0),
            p("post_asurf_crop_scaleY", 1.0),
            p("post_asurf_crop_scaleZ", 1.0),
            p_range("post_asurf_crop_color", 1.0, 0.0, 1.0),
            p_int("post_asurf_crop_mode", 1.0, 0.0, 1.0),
            p("post_asurf_crop_angle", 0.0),
            p("post_asurf_crop_rot_x", 0.0),
            p("post_asurf_crop_rot_y", 0.0),
            p("post_asurf_crop_rot_z", 1.0),
            p("post_asurf_crop_minR", 0.25),
            p("post_asurf_crop_maxR", 1.0),
        ])
        .flags(CROP | flag::SETS_COLOR)
        .prepare(asurf_prepare),
    VarDef::new("post_mandelbulb3d_crop", mandelbulb3d_crop)
        .params(&[
            p("post_mandelbulb3d_crop_power", 9.0),
            p("post_mandelbulb3d_crop_xz", 0.0),
            p_int("post_mandelbulb3d_crop_iterations", 12.0, 0.0, 250.0),
            p("post_mandelbulb3d_crop_bailout", 2.0),
            p_int("post_mandelbulb3d_crop_filled", 0.0, 0.0, 1.0),
        ])
        .flags(CROP | flag::SETS_COLOR | flag::HIDES | flag::RANDOM),
    VarDef::new("_slice_indicator_wf", slice_indicator)
        .params(&[
            p("_slice_indicator_wf_thickness", 0.01),
            p("_slice_indicator_wf_position_1", 0.0),
            p_int("_slice_indicator_wf_dc_red_1", 255.0, NEG_INF, INF),
            p_int("_slice_indicator_wf_dc_green_1", 0.0, NEG_INF, INF),
            p_int("_slice_indicator_wf_dc_blue_1", 0.0, NEG_INF, INF),
            p("_slice_indicator_wf_position_2", 0.0),
            p_int("_slice_indicator_wf_dc_red_2", 255.0, NEG_INF, INF),
            p_int("_slice_indicator_wf_dc_green_2", 0.0, NEG_INF, INF),
            p_int("_slice_indicator_wf_dc_blue_2", 0.0, NEG_INF, INF),
            p_int("_slice_indicator_wf_random_fill", 0.0, 0.0, 1.0),
        ])
        .flags(CROP | flag::RANDOM),
];

/// The turn by `angle` degrees about the unit axis (rot_x, rot_y, rot_z), as the nine
/// coefficients that map (x, y, z) to (x·m0 + y·m1 + z·m2, x·m3 + …).
fn asurf_prepare(v: &mut Prepared) {
    let [_, _, _, _, _, _, _, angle, ax, ay, az] = v.params();
    let l = (ax * ax + ay * ay + az * az).sqrt();
    let (x, y, z) = (ax / l, ay / l, az / l);
    let a = angle * PI / 180.0;
    let (s, c) = (a.sin(), a.cos());
    let k = 1.0 - c;
    v.p.extend_from_slice(&[
        c + k * x * x,
        k * x * y - s * z,
        k * x * z + s * y,
        k * x * y + s * z,
        c + k * y * y,
        k * y * z - s * x,
        k * x * z - s * y,
        k * y * z + s * x,
        c + k * z * z,
    ]);
}

/// The box fold of a coordinate at ±1: |a + 1| − |a − 1| − a.
fn fold(a: f64) -> f64 {
    (a + 1.0).abs() - (a - 1.0).abs() - a
}

/// post_asurf_crop: the summed point kept (times the weight) while the amazing-surface
/// iteration of it (scaled by scaleX, scaleY, scaleZ) stays within the bailout (of |p|²).
fn asurf_crop(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [
        iterations,
        bailout,
        sx,
        sy,
        sz,
        pcolor,
        mode,
        _,
        _,
        _,
        _,
        min_r,
        max_r,
    ] = v.params();
    let m: [f64; 9] = v.derived();
    let c = [t.x * sx, t.y * sy, t.z * sz];
    let mut p = c;
    crop_steps(v, t, acc, (iterations, bailout, pcolor), || {
        p[0] = fold(p[0]);
        p[1] = fold(p[1]);
        if mode == 0.0 {
            p[2] = fold(p[2]);
        }
        let rr = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        if rr < min_r {
            p = p.map(|a| a * (max_r / min_r));
        } else if rr < max_r {
            p = p.map(|a| a * (max_r / rr));
        }
        p = [
            p[0] * m[0] + p[1] * m[1] + p[2] * m[2] + c[0],
            p[0] * m[3] + p[1] * m[4] + p[2] * m[5] + c[1],
            p[0] * m[6] + p[1] * m[7] + p[2] * m[8] + c[2],
        ];
        p[0] * p[0] + p[1] * p[1] + p[2] * p[2]
    })
}

/// post_mandelbulb3d_crop: the summed point (or, with `filled`, a uniform point of the cube
/// of side 2·(weight + 1)) kept while Quilez's Mandelbulb of it stays within the bailout.
fn mandelbulb3d_crop(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, xz, iterations, bailout, filled] = v.params();
    let mut o = [t.x, t.y, t.z];
    if filled == 1.0 {
        let fill = (v.w + 1.0) * 2.0;
        o = [0; 3].map(|_| rng.f01() * fill - fill / 2.0);
    }
    let [mut x, mut y, mut z] = o;
    for i in 0..iterations as i32 {
        let r = (x * x + y * y + z * z).sqrt().powf(power);
        let theta = ((x * x + z * z).sqrt() + xz).atan2(y) * power;
        let zangle = x.atan2(z) * power;
        x += zangle.sin() * theta.sin() * r;
        y += theta.cos() * r;
        z += theta.sin() * zangle.cos() * r;
        acc.color = (8.0 / f64::from(i + 1)).min(1.0);
        if (x * x + y * y + z * z).sqrt() < bailout {
            acc.hide = false;
            o = o.map(|a| a * v.w);
        } else {
            acc.hide = true;
            o = [0.0; 3];
        }
    }
    o
}

/// _slice_indicator_wf: the summed point coloured (its channels times 4) where its z lies in
/// one of the two slices; with `random_fill`, a quarter of the others moved onto a slice
/// (turned at random) and coloured.
fn slice_indicator(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [thickness, pos1, r1, g1, b1, pos2, r2, g2, b2, fill] = v.params();
    let h = 0.5 * thickness.abs();
    let slices = [(pos1, [r1, g1, b1]), (pos2, [r2, g2, b2])];
    for (pos, rgb) in slices {
        if t.z >= pos - h && t.z <= pos + h {
            acc.rgb = Some(rgb.map(|c| c * 4.0));
            return [t.x, t.y, t.z];
        }
    }
    for (pos, rgb) in slices {
        if fill == 1.0 && rng.f01() > 0.75 {
            let (s, c) = (TAU * rng.f01()).sin_cos();
            acc.rgb = Some(rgb);
            return [s * t.x + c * t.y, c * t.x - s * t.y, pos - h];
        }
    }
    [t.x, t.y, t.z]
}
