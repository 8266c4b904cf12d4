//! Blurs from Fractorium's catalogue whose size grows with the distance from a centre: the
//! depth blurs (`depth_blur`, `depth_gaussian`, `depth_ngon`, `depth_sine` and their `2`
//! variants), the falloff blurs, `farblur`, `rblur` and `blur_zoom`.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::util::{sign_nz, sqr, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

/// The parameters of the anisotropic depth blurs (`NAME` = depth_blur2, depth_gaussian2, …):
/// any leading ones given, then blur, radius, centre (x0, y0), distance multipliers and the
/// exponent of the growth.
macro_rules! depth2_params {
    ($name:literal $(, $lead:expr)*) => {
        &[
            $($lead,)*
            p(concat!($name, "_blur"), 1.0),
            p(concat!($name, "_radius"), 1.0),
            p(concat!($name, "_x0"), 0.0),
            p(concat!($name, "_y0"), 0.0),
            p(concat!($name, "_mulx"), 1.0),
            p(concat!($name, "_muly"), 1.0),
            p(concat!($name, "_exp"), 1.0),
        ]
    };
}

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("blur_zoom", blur_zoom)
        .params(&[
            p("blur_zoom_length", 0.0),
            p("blur_zoom_x", 0.0),
            p("blur_zoom_y", 0.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z),
    super::inlined!("depth_blur", depth_blur)
        .params(&[
            p("depth_blur_power", 5.0),
            p("depth_blur_range", 0.401623),
            p("depth_blur_blur", 1.0),
            p("depth_blur_radius", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM)
        .prepare(depth_blur_prepare),
    super::inlined!("depth_blur2", depth_blur2)
        .params(depth2_params!(
            "depth_blur2",
            p("depth_blur2_power", 5.0),
            p("depth_blur2_range", 0.401623)
        ))
        .flags(flag::RANDOM)
        .prepare(depth_blur2_prepare),
    super::inlined!("depth_gaussian", depth_gaussian)
        .params(&[
            p("depth_gaussian_blur", 1.0),
            p("depth_gaussian_radius", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM),
    super::inlined!("depth_gaussian2", depth_gaussian2)
        .params(depth2_params!("depth_gaussian2"))
        .flags(flag::RANDOM)
        .prepare(depth_gaussian2_prepare),
    super::inlined_drawn!("depth_ngon", depth_ngon, 1)
        .params(&[
            p("depth_ngon_power", 5.0),
            p("depth_ngon_blur", 1.0),
            p("depth_ngon_radius", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM)
        .prepare(depth_ngon_prepare),
    super::inlined!("depth_ngon2", depth_ngon2)
        .params(depth2_params!("depth_ngon2", p("depth_ngon2_power", 5.0)))
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(depth_ngon2_prepare),
    super::inlined!("depth_sine", depth_sine)
        .params(&[
            p_range("depth_sine_power", 1.0, 0.0, INF),
            p("depth_sine_blur", 1.0),
            p("depth_sine_radius", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM),
    super::inlined!("depth_sine2", depth_sine2)
        .params(depth2_params!(
            "depth_sine2",
            p_range("depth_sine2_power", 1.0, 0.0, INF)
        ))
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(depth_sine2_prepare),
    super::inlined!("falloff", falloff)
        .params(&[
            p_range("falloff_scatter", 1.0, f64::EPSILON, INF),
            p_range("falloff_mindist", 0.5, 0.0, INF),
            p_range("falloff_mul_x", 1.0, 0.0, 1.0),
            p_range("falloff_mul_y", 1.0, 0.0, 1.0),
            p_range("falloff_mul_z", 0.0, 0.0, 1.0),
            p("falloff_x0", 0.0),
            p("falloff_y0", 0.0),
            p("falloff_z0", 0.0),
            p_int("falloff_invert", 0.0, 0.0, 1.0),
            p_int("falloff_type", 0.0, 0.0, 2.0),
            p_int("falloff_boxpow", 2.0, 2.0, 32.0),
        ])
        .needs(need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z),
    super::inlined!("falloff2", falloff2)
        .params(&[
            p("falloff2_scatter", 1.0),
            p("falloff2_mindist", 0.5),
            p("falloff2_mul_x", 1.0),
            p("falloff2_mul_y", 1.0),
            p("falloff2_mul_z", 0.0),
            p("falloff2_mul_c", 0.0),
            p("falloff2_x0", 0.0),
            p("falloff2_y0", 0.0),
            p("falloff2_z0", 0.0),
            p_range("falloff2_invert", 0.0, 0.0, 1.0),
            p_range("falloff2_type", 0.0, 0.0, 2.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR),
    super::inlined!("falloff3", falloff3)
        .params(&[
            p_int("falloff3_blur_type", 0.0, 0.0, 3.0),
            p_int("falloff3_blur_shape", 0.0, 0.0, 1.0),
            p_range("falloff3_blur_strength", 1.0, f64::EPSILON, INF),
            p_range("falloff3_min_distance", 0.5, 0.0, INF),
            p_int("falloff3_invert_distance", 0.0, 0.0, 1.0),
            p_range("falloff3_mul_x", 1.0, 0.0, 1.0),
            p_range("falloff3_mul_y", 1.0, 0.0, 1.0),
            p_range("falloff3_mul_z", 0.0, 0.0, 1.0),
            p_range("falloff3_mul_c", 0.0, 0.0, 1.0),
            p("falloff3_center_x", 0.0),
            p("falloff3_center_y", 0.0),
            p("falloff3_center_z", 0.0),
            p("falloff3_alpha", 0.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR),
    super::inlined!("farblur", farblur)
        .params(&[
            p("farblur_x", 1.0),
            p("farblur_y", 1.0),
            p("farblur_z", 1.0),
            p("farblur_x_origin", 0.0),
            p("farblur_y_origin", 0.0),
            p("farblur_z_origin", 0.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z),
    super::inlined!("rblur", rblur)
        .params(&[
            p("rblur_strength", 1.0),
            p("rblur_offset", 1.0),
            p("rblur_center_x", 0.0),
            p("rblur_center_y", 0.0),
        ])
        .flags(flag::RANDOM),
];

/// Zoom blur: a random enlargement (1 to 1 + length) about the centre (x₀, −y₀).
#[inline(always)]
fn blur_zoom(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [len, cx, cy] = v.params();
    let z = 1.0 + len * rng.f01();
    [
        v.w * ((t.x - cx) * z + cx),
        v.w * ((t.y + cy) * z - cy),
        v.w * t.z,
    ]
}

/// Apophysis' symmetric logarithmic compression of a value (0 stays 0).
#[inline(always)]
fn log_scale(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        ((x.abs() + 1.0) * std::f64::consts::E).ln() * sign_nz(x) / std::f64::consts::E
    }
}

/// Apophysis' logarithmic remapping of a multiplier (0 stays 0).
#[inline(always)]
fn log_map(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        (std::f64::consts::E + (x * std::f64::consts::E).ln()) * 0.25 * sign_nz(x)
    }
}

/// Star-blur geometry shared by depth_blur and depth_blur2: (length, alpha).
fn star_shape(power: f64, range: f64) -> (f64, f64) {
    let a0 = PI / zeps(power);
    let length = (1.0 + range * range - 2.0 * range * a0.fcos()).sqrt();
    let alpha = (a0.fsin() * range / zeps(length)).asin();
    (length, alpha)
}

fn depth_blur_prepare(v: &mut Prepared) {
    let [power, range, blur] = v.params();
    let (length, alpha) = star_shape(power, range);
    let (s, c) = alpha.fsin_cos();
    v.p.extend_from_slice(&[length, blur / 10.0, power * 2.0, TAU / zeps(power), s, c]);
}

/// A random offset inside a star with `power2`/2 points (unit size): a random arm, a random
/// position along its edge and a random fraction of that radius. `plus_on_odd` selects which
/// side of each arm leans which way.
#[inline(always)]
fn star_offset(
    rng: &mut FastRng,
    power2: f64,
    length: f64,
    sin_a: f64,
    cos_a: f64,
    step: f64,
    plus_on_odd: bool,
) -> (f64, f64) {
    let f0 = rng.f01() * power2;
    let whole = f0.trunc();
    let f = f0 - whole;
    let x = f * length;
    let mut z = (1.0 + x * x - 2.0 * x * cos_a).sqrt();
    let arm = whole as i64;
    let lean = (sin_a * x / zeps(z)).asin();
    let odd = arm & 1 != 0;
    let ang = if odd == plus_on_odd {
        step * (arm / 2) as f64 + lean
    } else {
        step * (arm / 2) as f64 - lean
    };
    z *= rng.f01().sqrt();
    let (s, c) = (ang - FRAC_PI_2).fsin_cos();
    (z * c, z * s)
}

/// The last step of the depth blurs: a point at distance `rad` beyond `radius` is moved by a
/// kernel offset drawn by `offset`, scaled by `amount` of the distance past the radius (points
/// within the radius stay, and draw nothing); the result is weighted.
#[inline(always)]
fn depth_push(
    w: f64,
    t: &VarIn,
    rad: f64,
    radius: f64,
    rng: &mut FastRng,
    offset: impl FnOnce(&mut FastRng) -> (f64, f64),
    amount: impl FnOnce(f64) -> f64,
) -> V3 {
    let (mut bx, mut by) = (0.0, 0.0);
    if rad > radius {
        let (ox, oy) = offset(rng);
        let aux = amount(rad - radius);
        bx = aux * ox;
        by = aux * oy;
    }
    [w * (t.x + bx), w * (t.y + by), 0.0]
}

/// Blurs points beyond `radius` with a star-shaped kernel whose size grows linearly with the
/// distance past the radius.
#[inline(always)]
fn depth_blur(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, radius] = v.params();
    let [length, blur10, power2, step, sa, ca] = v.derived();
    let rad = t.sqrt;
    depth_push(
        v.w,
        t,
        rad,
        radius,
        rng,
        |r| star_offset(r, power2, length, sa, ca, step, false),
        |d| blur10 * d,
    )
}

fn depth_blur2_prepare(v: &mut Prepared) {
    let [power, range, blur, _, _, _, mx, my] = v.params();
    let (length, alpha) = star_shape(power, range);
    let (s, c) = alpha.fsin_cos();
    v.p.extend_from_slice(&[
        length,
        blur / 10.0,
        power * 2.0,
        TAU / zeps(power),
        s,
        c,
        1.0 / zeps(mx),
        1.0 / zeps(my),
    ]);
}

/// depth_blur around (x0, y0) with an elliptic distance (mulx, muly) and a kernel growing as a
/// power (`exp`) of the distance past the radius.
#[inline(always)]
fn depth_blur2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, radius, x0, y0, _, _, ex] = v.params();
    let [length, blur10, power2, step, sa, ca, imx, imy] = v.derived();
    let rad = (sqr((t.x - x0) * imx) + sqr((t.y - y0) * imy)).sqrt();
    depth_push(
        v.w,
        t,
        rad,
        radius,
        rng,
        |r| star_offset(r, power2, length, sa, ca, step, true),
        |d| blur10 * (d.ln() * ex).exp(),
    )
}

/// A standard normal radius and a uniform angle: (r·cos, r·sin).
#[inline(always)]
fn gaussian_offset(rng: &mut FastRng) -> (f64, f64) {
    let r = (-2.0 * rng.f01().ln()).sqrt();
    let (s, c) = (rng.f01() * TAU).fsin_cos();
    (r * c, r * s)
}

/// Gaussian blur of the points beyond `radius`, its width growing with the distance past it.
#[inline(always)]
fn depth_gaussian(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [blur, radius] = v.params();
    let rad = t.sqrt;
    depth_push(v.w, t, rad, radius, rng, gaussian_offset, |d| {
        blur / 10.0 * d
    })
}

fn depth_gaussian2_prepare(v: &mut Prepared) {
    let [blur, _, _, _, mx, my] = v.params();
    v.p.extend_from_slice(&[blur / 10.0, 1.0 / zeps(mx * mx), 1.0 / zeps(my * my)]);
}

/// depth_gaussian around (x0, y0) with an anisotropic distance and a width growing as a power
/// (`exp`) of the distance past the radius.
#[inline(always)]
fn depth_gaussian2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, radius, x0, y0, _, _, ex] = v.params();
    let [blur10, kx, ky] = v.derived();
    let rad = (sqr((t.x - x0) / kx) + sqr((t.y - y0) / ky)).sqrt();
    depth_push(v.w, t, rad, radius, rng, gaussian_offset, |d| {
        blur10 * (d.ln() * ex).exp()
    })
}

/// A random direction with the radius of a regular polygon's boundary in that direction
/// (1/cos of the angle to the nearest side normal): (r·cos, r·sin).
#[inline(always)]
fn polygon_offset(rng: &mut FastRng, side: f64, half: f64) -> (f64, f64) {
    polygon_offset_at(rng.f01() * TAU, side, half)
}

/// [`polygon_offset`] at the angle `ang`.
#[inline(always)]
fn polygon_offset_at(ang: f64, side: f64, half: f64) -> (f64, f64) {
    let mut phi = ang - side * (ang / zeps(side)).floor();
    if phi > half {
        phi -= side;
    }
    let amp = 1.0 / zeps(phi.fcos());
    let (s, c) = ang.fsin_cos();
    (amp * c, amp * s)
}

fn depth_ngon_prepare(v: &mut Prepared) {
    let [power, blur] = v.params();
    let side = TAU / zeps(power);
    v.p.extend_from_slice(&[side, side / 2.0, blur / 10.0]);
}

/// Blurs the points beyond `radius` onto the outline of a regular polygon whose size grows with
/// the distance past the radius.
#[inline(always)]
fn depth_ngon<R: Draws>(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut R) -> V3 {
    let [_, _, radius] = v.params();
    let [side, half, blur10] = v.derived();
    let rad = t.sqrt;
    // [`depth_push`] with the angle drawn for every point, pushed or not: one draw per point,
    // which the batch loop draws beforehand (and no branch around the offset).
    let (ox, oy) = polygon_offset_at(rng.f01() * TAU, side, half);
    let aux = blur10 * (rad - radius);
    let (bx, by) = if rad > radius {
        (aux * ox, aux * oy)
    } else {
        (0.0, 0.0)
    };
    [v.w * (t.x + bx), v.w * (t.y + by), 0.0]
}

fn depth_ngon2_prepare(v: &mut Prepared) {
    let [power, blur, _, _, _, mx, my] = v.params();
    let side = TAU / zeps(power);
    v.p.extend_from_slice(&[
        side,
        side / 2.0,
        blur / 10.0,
        1.0 / zeps(mx * mx),
        1.0 / zeps(my * my),
    ]);
}

/// depth_ngon around (x0, y0), anisotropic, with a size growing as a power (`exp`) of the
/// distance past the radius (in flam3-compatibility mode: plain depth_ngon).
#[inline(always)]
fn depth_ngon2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, radius, x0, y0, _, _, ex] = v.params();
    let [side, half, blur10, kx, ky] = v.derived();
    let polygon = |r: &mut FastRng| polygon_offset(r, side, half);
    if v.compat {
        depth_push(v.w, t, t.sqrt, radius, rng, polygon, |d| blur10 * d)
    } else {
        let rad = (sqr(t.x - x0) * kx + sqr(t.y - y0) * ky).sqrt();
        depth_push(v.w, t, rad, radius, rng, polygon, |d| {
            blur10 * (d.ln() * ex).exp()
        })
    }
}

/// A random direction with a radius distributed like acos(2u−1)/π (sharpened by `power`).
#[inline(always)]
fn sine_offset(rng: &mut FastRng, power: f64) -> (f64, f64) {
    let ang = rng.f01() * TAU;
    let r = if power == 1.0 {
        (rng.f01() * 2.0 - 1.0).acos() / PI
    } else {
        (((1.0 - rng.f01()).ln() * power).exp() * 2.0 - 1.0).acos() / PI
    };
    let (s, c) = ang.fsin_cos();
    (r * c, r * s)
}

/// Blurs the points beyond `radius` with a disc kernel of sine-shaped radial profile, its size
/// growing with the distance past the radius.
#[inline(always)]
fn depth_sine(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, blur, radius] = v.params();
    let rad = t.sqrt;
    depth_push(
        v.w,
        t,
        rad,
        radius,
        rng,
        |r| sine_offset(r, power),
        |d| blur / 10.0 * d,
    )
}

fn depth_sine2_prepare(v: &mut Prepared) {
    let [power, blur, _, _, _, mx, my] = v.params();
    v.p[0] = power.max(0.0);
    v.p.extend_from_slice(&[blur / 10.0, 1.0 / zeps(mx * mx), 1.0 / zeps(my * my)]);
}

/// depth_sine around (x0, y0), anisotropic, with a size growing as a power (`exp`) of the
/// distance past the radius.
#[inline(always)]
fn depth_sine2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, _, radius, x0, y0, mx, my, ex] = v.params();
    let [blur10, kx, ky] = v.derived();
    let rad = if v.compat {
        (sqr((t.x - x0) / zeps(mx)) + sqr((t.y - y0) / zeps(my))).sqrt()
    } else {
        (sqr(t.x - x0) * kx + sqr(t.y - y0) * ky).sqrt()
    };
    depth_push(
        v.w,
        t,
        rad,
        radius,
        rng,
        |r| sine_offset(r, power),
        |d| blur10 * (d.ln() * ex).exp(),
    )
}

/// A uniform value in [−0.5, 0.5).
#[inline(always)]
fn centred(rng: &mut FastRng) -> f64 {
    rng.f01() - 0.5
}

/// A 3-D blur whose strength grows with the distance from a centre beyond `mindist`: uniform
/// box jitter, radial/angular jitter, or snapping towards a grid whose cell grows with distance.
#[inline(always)]
fn falloff(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        scatter,
        mindist,
        mx,
        my,
        mz,
        x0,
        y0,
        z0,
        invert,
        kind,
        boxpow,
    ] = v.params();
    let ax = centred(rng);
    let ay = centred(rng);
    let az = centred(rng);
    let w = v.w;
    let r = (sqr(t.x - x0) + sqr(t.y - y0) + sqr(t.z - z0)).sqrt();
    let rs = falloff_amount(r, invert, mindist, 0.04 * scatter);
    match kind as i32 {
        0 => [
            w * (t.x + mx * ax * rs),
            w * (t.y + my * ay * rs),
            w * (t.z + mz * az * rs),
        ],
        1 => {
            let elevation = if r == 0.0 { 0.0 } else { t.z / r };
            radial_falloff(t, w, r, elevation, rs, [ax, ay, az], [mx, my, mz])
        }
        _ => {
            let scale = rs.clamp(0.0, 0.9) + 0.1;
            let inv = 1.0 / scale;
            let snap = |c: f64, a: f64, m: f64| {
                let target = (c * inv).floor() + scale * a;
                w * (c + (target - c) * (m * rs)) + m * a.powf(boxpow) * rs * inv
            };
            [snap(t.x, ax, mx), snap(t.y, ay, my), snap(t.z, az, mz)]
        }
    }
}

/// Distance-dependent blur after falloff, in three styles (box, radial, Gaussian-like), that
/// can also jitter the colour (`mul_c`).
#[inline(always)]
fn falloff2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scatter, mindist, mx, my, mz, mc, x0, y0, z0, invert, kind] = v.params();
    let rx = centred(rng);
    let ry = centred(rng);
    let rz = centred(rng);
    let rc = centred(rng);
    let w = v.w;
    let da = (sqr(t.x - x0) + sqr(t.y - y0) + sqr(t.z - z0)).sqrt();
    let dist = falloff_amount(da, invert, mindist, 0.04 * scatter);
    let o = match kind as i32 {
        0 => [
            (t.x + mx * rx * dist) * w,
            (t.y + my * ry * dist) * w,
            (t.z + mz * rz * dist) * w,
        ],
        1 => {
            if t.x == 0.0 && t.y == 0.0 && t.z == 0.0 {
                return [t.x * w, t.y * w, t.z * w];
            }
            let rin = zeps((t.sumsq + t.z * t.z).sqrt());
            radial_falloff(t, w, rin, t.z / rin, dist, [rx, ry, rz], [mx, my, mz])
        }
        _ => gaussian_falloff(t, w, dist, [rx, ry, rz], [mx, my, mz]),
    };
    acc.color = falloff_color(acc.color, mc * rc * dist);
    o
}

/// How strongly the falloff blurs act at distance `r` from their centre (1 − r with
/// `invert`): the part beyond `mindist`, times `k`, never negative.
#[inline(always)]
fn falloff_amount(r: f64, invert: f64, mindist: f64, k: f64) -> f64 {
    let base = if invert != 0.0 {
        (1.0 - r).max(0.0)
    } else {
        r.max(0.0)
    };
    ((base - mindist) * k).max(0.0)
}

/// The colour of the falloff blurs: shifted by `shift`, wrapped into [0, 1) by |c mod 1|.
#[inline(always)]
fn falloff_color(color: f64, shift: f64) -> f64 {
    ((color + shift) % 1.0).abs()
}

/// The "radial" style of the falloff blurs: the point's spherical coordinates (radius `rin`,
/// azimuth, elevation asin(`elevation`)) each jittered by `dist` times a random number `r` and
/// a multiplier `m`.
#[inline(always)]
fn radial_falloff(t: &VarIn, w: f64, rin: f64, elevation: f64, dist: f64, r: V3, m: V3) -> V3 {
    let rad = rin + m[0] * r[0] * dist;
    let phi = t.atan_yx + m[1] * r[1] * dist;
    let sigma = elevation.asin() + m[2] * r[2] * dist;
    let (ss, sc) = sigma.fsin_cos();
    let (ps, pc) = phi.fsin_cos();
    let (ss, sc) = (ss * w, sc * w);
    [rad * sc * pc, rad * sc * ps, rad * ss]
}

/// The "Gaussian" style of falloff2/falloff3: offsets along a random spherical direction.
#[inline(always)]
fn gaussian_falloff(t: &VarIn, w: f64, dist: f64, r: [f64; 3], m: [f64; 3]) -> V3 {
    let sigma = dist * r[1] * TAU;
    let phi = dist * r[2] * PI;
    let rad = dist * r[0];
    let (ss, sc) = sigma.fsin_cos();
    let (ps, pc) = phi.fsin_cos();
    [
        (t.x + m[0] * rad * sc * pc) * w,
        (t.y + m[1] * rad * sc * ps) * w,
        (t.z + m[2] * rad * ss) * w,
    ]
}

/// falloff2 with a round or square distance and a logarithmic style (blend `alpha`).
#[inline(always)]
fn falloff3(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        kind,
        shape,
        strength,
        mindist,
        invert,
        mx,
        my,
        mz,
        mc,
        cx,
        cy,
        cz,
        alpha,
    ] = v.params();
    let rx = centred(rng);
    let ry = centred(rng);
    let rz = centred(rng);
    let rc = centred(rng);
    let w = v.w;
    let radius = if shape == 0.0 {
        (sqr(t.x - cx) + sqr(t.y - cy) + sqr(t.z - cz)).sqrt()
    } else {
        (t.x - cx).abs().max((t.y - cy).abs().max((t.z - cz).abs()))
    };
    let rmax = 0.04 * strength;
    let dist = falloff_amount(radius, invert, mindist, rmax);
    match kind as i32 {
        0 => {
            let o = gaussian_falloff(t, w, dist, [rx, ry, rz], [mx, my, mz]);
            acc.color = falloff_color(acc.color, mc * rc * dist);
            o
        }
        1 => {
            if t.x == 0.0 && t.y == 0.0 && t.z == 0.0 {
                return [t.x * w, t.y * w, t.z * w];
            }
            let rin = (t.sumsq + t.z * t.z).sqrt();
            acc.color = falloff_color(acc.color, mc * rc * dist);
            radial_falloff(t, w, rin, t.z / rin, dist, [rx, ry, rz], [mx, my, mz])
        }
        _ => {
            let coeff = if rmax <= f64::EPSILON {
                dist
            } else {
                dist + alpha * (log_map(dist) - dist)
            };
            let o = [
                (t.x + log_map(mx) * log_scale(rx) * coeff) * w,
                (t.y + log_map(my) * log_scale(ry) * coeff) * w,
                (t.z + log_map(mz) * log_scale(rz) * coeff) * w,
            ];
            acc.color = falloff_color(acc.color, log_map(mc) * log_scale(rc) * coeff);
            o
        }
    }
}

/// A 3-D blur along a random direction whose size grows with the squared distance from an
/// origin (per-axis scales).
#[inline(always)]
fn farblur(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sx, sy, sz, x0, y0, z0] = v.params();
    let d2 = sqr(t.x - x0) + sqr(t.y - y0) + sqr(t.z - z0);
    let r = v.w * d2 * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
    let (su, cu) = (rng.f01() * TAU).fsin_cos();
    let (sv, cv) = (rng.f01() * TAU).fsin_cos();
    [sx * r * sv * cu, sy * r * sv * su, sz * r * cv]
}

/// Replaces negatives with 0 (NaN passes through).
#[inline(always)]
fn non_negative(x: f64) -> f64 {
    if x < 0.0 { 0.0 } else { x }
}

/// A blur whose size grows with the distance from a centre (beyond an offset): sharp near the
/// centre, smeared further out.
#[inline(always)]
fn rblur(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [strength, offset, center_x, center_y] = v.params();
    let (dx, dy) = (t.x - center_x, t.y - center_y);
    let r = non_negative((dx * dx + dy * dy).sqrt() - offset) * (2.0 * strength);
    let x = v.w * (t.x + (rng.f01() - 0.5) * r);
    let y = v.w * (t.y + (rng.f01() - 0.5) * r);
    [x, y, 0.0]
}
