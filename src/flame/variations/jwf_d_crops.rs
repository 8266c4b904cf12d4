//! JWildfire's escape-time crops of the summed point (Jesus Sosa's post variations):
//! `post_benesi_crop`, `post_bristorbrot_crop`, `post_aexion_crop`, `post_coastalbrot_crop`
//! (3-D escape-time fractals, the point kept, scaled by the weight once per iteration that
//! stays within the bailout, and coloured by the sine of the last radius inside; zero once
//! an iteration escapes) and `post_mandelbox3d_crop` (a Mandelbox, hiding the points whose
//! last iteration escapes).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew, quirks included (the
//! weight is applied once per iteration, so it acts as a power).

use std::f64::consts::PI;

use super::*;

const CROP: u32 = flag::JWILDFIRE | flag::POST_ONLY | flag::USES_Z | flag::WRITES_Z;

/// The six parameters of the bulb crops, named for variation `$n`.
macro_rules! bulb_crop_params {
    ($n:literal) => {
        &[
            p_int(concat!($n, "_iterations"), 12.0, 0.0, 250.0),
            p(concat!($n, "_bailout"), 16.0),
            p(concat!($n, "_scaleX"), 1.0),
            p(concat!($n, "_scaleY"), 1.0),
            p(concat!($n, "_ScaleZ"), 1.0),
            p_range(concat!($n, "_color"), 1.0, 0.0, 1.0),
        ]
    };
}

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("post_benesi_crop", benesi_crop)
        .params(bulb_crop_params!("post_benesi_crop"))
        .flags(CROP | flag::SETS_COLOR),
    VarDef::new("post_bristorbrot_crop", bristorbrot_crop)
        .params(bulb_crop_params!("post_bristorbrot_crop"))
        .flags(CROP | flag::SETS_COLOR),
    VarDef::new("post_coastalbrot_crop", coastalbrot_crop)
        .params(&[
            p_int("post_coastalbrot_crop_iterations", 12.0, 0.0, 250.0),
            p("post_coastalbrot_crop_bailout", 16.0),
            p("post_coastalbrot_crop_scaleX", 1.0),
            p("post_coastalbrot_crop_scaleY", 1.0),
            p("post_coastalbrot_crop_ScaleZ", 1.0),
            p_range("post_coastalbrot_crop_color", 1.0, 0.0, 1.0),
            p("post_coastalbrot_crop_alpha", 0.0),
            p("post_coastalbrot_crop_beta", 0.0),
            p("post_coastalbrot_crop_gamma", 0.0),
        ])
        .flags(CROP | flag::SETS_COLOR),
    VarDef::new("post_aexion_crop", aexion_crop)
        .params(&[
            p_int("post_aexion_crop_Iters", 100.0, 1.0, 250.0),
            p("post_aexion_crop_cadd", -0.8),
            p("post_aexion_crop_bailout", 10.0),
            p("post_aexion_crop_scaleX", 1.0),
            p("post_aexion_crop_scaleY", 1.0),
            p("post_aexion_crop_ScaleZ", 1.0),
            p_range("post_aexion_crop_color", 1.0, 0.0, 1.0),
        ])
        .flags(CROP | flag::SETS_COLOR),
    VarDef::new("post_mandelbox3d_crop", mandelbox3d_crop)
        .params(&[
            p("post_mandelbox3d_crop_scale", 2.0),
            p("post_mandelbox3d_crop_radius", 0.5),
            p("post_mandelbox3d_crop_f", 1.0),
            p_int("post_mandelbox3d_crop_iterations", 12.0, 0.0, 250.0),
            p("post_mandelbox3d_crop_bailout", 16.0),
        ])
        .flags(CROP | flag::HIDES),
];

/// The point kept through `iterations` steps of an escape-time map: each step returns the
/// radius it reached; a step within `bailout` scales the point by the weight and sets the
/// colour to sin(radius)·`pcolor`, one beyond it zeroes the point.
pub(super) fn crop_steps(
    v: &Prepared,
    t: &VarIn,
    acc: &mut Acc,
    (iterations, bailout, pcolor): (f64, f64, f64),
    mut step: impl FnMut() -> f64,
) -> V3 {
    let mut o = [t.x, t.y, t.z];
    for _ in 0..iterations as i32 {
        let r = step();
        if r < bailout {
            o = o.map(|c| c * v.w);
            acc.color = r.sin() * pcolor;
        } else {
            o = [0.0; 3];
        }
    }
    o
}

/// post_benesi_crop: Benesi's "pine tree" Mandelbulb.
fn benesi_crop(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [iterations, bailout, sx, sy, sz, pcolor] = v.params();
    let c = [t.x * sx, t.y * sy, t.z * sz];
    let [mut x, mut y, mut z] = c;
    crop_steps(v, t, acc, (iterations, bailout, pcolor), || {
        let r1 = y * y + z * z;
        let nx = if c[0] < 0.0 || x < r1.sqrt() {
            x * x - r1
        } else {
            -x * x + r1
        };
        let k = -1.0 / r1.sqrt() * 2.0 * x.abs();
        let ny = k * (y * y - z * z);
        let nz = k * 2.0 * y * z;
        (x, y, z) = (nx + c[0], ny + c[1], nz + c[2]);
        (x * x + y * y + z * z).sqrt()
    })
}

/// post_bristorbrot_crop: the Bristorbrot (x² − y² − z², y(2x − z), z(2x + y)) + c.
fn bristorbrot_crop(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [iterations, bailout, sx, sy, sz, pcolor] = v.params();
    let c = [t.x * sx, t.y * sy, t.z * sz];
    let [mut x, mut y, mut z] = c;
    crop_steps(v, t, acc, (iterations, bailout, pcolor), || {
        let nx = x * x - y * y - z * z;
        let ny = y * (2.0 * x - z);
        let nz = z * (2.0 * x + y);
        (x, y, z) = (nx + c[0], ny + c[1], nz + c[2]);
        (x * x + y * y + z * z).sqrt()
    })
}

/// post_coastalbrot_crop: each coordinate through sin(sin(sin(π/3 + πc))), z scaled by
/// r^8.7, plus c. (JWildfire turns the point by the Euler angles alpha, beta, gamma before
/// taking its radius; a turn keeps the radius, so they change nothing.)
fn coastalbrot_crop(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [iterations, bailout, sx, sy, sz, pcolor, _, _, _] = v.params();
    let c = [t.x * sx, t.y * sy, t.z * sz];
    let [mut x, mut y, mut z] = c;
    let mut r = (x * x + y * y + z * z).sqrt();
    let f = |a: f64| (PI / 3.0 + a * PI).sin().sin().sin();
    crop_steps(v, t, acc, (iterations, bailout, pcolor), || {
        let temp = r.powf(7.7) * r;
        x = f(x) + c[0];
        y = f(y) + c[1];
        z = f(z) * temp + c[2];
        r = (x * x + y * y + z * z).sqrt();
        r
    })
}

/// post_aexion_crop: Aexion's 4-D "Quadray" set (the fourth coordinate fixed), offset by
/// `cadd`.
fn aexion_crop(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [iterations, cadd, bailout, sx, sy, sz, pcolor] = v.params();
    let (a, b, c) = (t.x, t.y, t.z);
    let p0 = [
        (a + b + c).abs() + cadd,
        (-a - b + c).abs() + cadd,
        (-a + b - c).abs() + cadd,
        (a - b - c).abs() + cadd,
    ];
    let aux = [p0[0] * sx, p0[1] * sy, p0[2] * sz];
    let w0 = p0[3];
    let mut z = [p0[0] * p0[0], p0[1] * p0[1], p0[2] * p0[2], w0 * p0[3]];
    crop_steps(v, t, acc, (iterations, bailout, pcolor), || {
        let nx = z[0] * z[0] - z[1] * z[1] + 2.0 * z[3] * z[2] + aux[0];
        let ny = z[1] * z[1] - z[0] * z[0] + 2.0 * z[3] * z[2] + aux[1];
        let nz = z[2] * z[2] - z[3] * z[3] + 2.0 * z[0] * z[1] + aux[2];
        z = [nx + p0[0], ny + p0[1], nz + p0[2], w0 + p0[3]];
        (z[0] * z[0] + z[1] * z[1] + z[2] * z[2] + z[3] * z[3]).sqrt()
    })
}

/// One Mandelbox fold of a coordinate: reflected into [−1, 1] at ±1.
fn box_fold(a: f64) -> f64 {
    if a > 1.0 {
        2.0 - a
    } else if a < -1.0 {
        -2.0 - a
    } else {
        a
    }
}

/// post_mandelbox3d_crop: a Mandelbox of the point times 6 (box fold, ball fold at `radius`
/// and 1, times `scale`, plus the start); each iteration whose ball radius stays within the
/// bailout scales the point by the weight and shows it, one beyond hides it at the origin.
fn mandelbox3d_crop(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [scale, radius, f, iterations, bailout] = v.params();
    let c = [t.x * 6.0, t.y * 6.0, t.z * 6.0];
    let mut p = c;
    let mut o = [t.x, t.y, t.z];
    for _ in 0..iterations as i32 {
        p = p.map(|a| box_fold(a) * f);
        let mag = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        if mag < radius {
            p = p.map(|a| a / (radius * radius));
        } else if mag < 1.0 {
            p = p.map(|a| a / (mag * mag));
        }
        p = [0, 1, 2].map(|k| p[k] * scale + c[k]);
        if mag < bailout {
            acc.hide = false;
            o = o.map(|a| a * v.w);
        } else {
            acc.hide = true;
            o = [0.0; 3];
        }
    }
    o
}
