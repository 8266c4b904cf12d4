//! JWildfire's 3-D surfaces and maps of z: Enneper's surface (`ennepers2`), Whitney's umbrella,
//! `butterfly3D`, `petal3D_apo`, the z inflations `inflateZ_2/4/6`, the 3-D inversions `sph3D`
//! and `spherical3D_wf`, `onion2`, the box fold `boxfold`, `erf3D`, `petal3D` and the
//! stepped shreds `shredded`, the hyperbolic tiling in 3-D `hypertile3D2b` and the quaternion
//! Möbius julia `jubiQ`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: weights multiply the output linearly, and
//! random numbers are drawn in the order JWildfire draws them.

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, PI, TAU};

use super::*;

/// Flags of a variation that reads and writes z.
const F3D: u32 = flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("ennepers2", ennepers2)
        .params(&[
            p("ennepers2_a", 1.0),
            p("ennepers2_b", 0.3333),
            p("ennepers2_c", 0.075),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("petal3D_apo", petal3d_apo)
        .params(&[
            p("petal3D_apo_width", 1.0),
            p("petal3D_apo_Zshape", 0.25),
            p("petal3D_apo_scale1", 0.25),
            p("petal3D_apo_scale2", 0.25),
            p("petal3D_apo_style", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("whitney_umbrella", whitney_umbrella).flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("butterfly3D", butterfly3d).flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("inflateZ_2", inflatez_2).flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("inflateZ_4", inflatez_4).flags(flag::JWILDFIRE | flag::WRITES_Z | flag::RANDOM),
    VarDef::new("inflateZ_6", inflatez_6).flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("sph3D", sph3d)
        .params(&[p("sph3D_x", 0.75), p("sph3D_y", 1.0), p("sph3D_z", 0.5)])
        .flags(F3D),
    VarDef::new("spherical3D_wf", spherical3d_wf)
        .params(&[
            p_int("spherical3D_wf_invert", 0.0, NEG_INF, INF),
            p("spherical3D_wf_exponent", 2.0),
        ])
        .flags(F3D),
    VarDef::new("onion2", onion2)
        .params(&[
            p("onion2_meeting_pt", 0.5),
            p("onion2_circle_a", 1.0),
            p("onion2_circle_b", 1.0),
            p("onion2_shift_x", 0.0),
            p("onion2_shift_y", 0.0),
            p("onion2_shift_z", 0.0),
            p("onion2_top_crop", 0.0),
            p_range("onion2_stretch", 1.0, f64::MIN_POSITIVE, f64::MAX),
        ])
        .flags(F3D),
    VarDef::new("boxfold", boxfold)
        .params(&[
            p_range("boxfold_foldLimit", 1.0, 1e-9, 10000.0),
            p("boxfold_rotateX", 0.0),
            p("boxfold_rotateY", 0.0),
            p("boxfold_rotateZ", 0.0),
        ])
        .flags(F3D),
    VarDef::new("erf3D", erf3d).flags(F3D),
    VarDef::new("petal3D", petal3d)
        .params(&[
            p_int("petal3D_mode", 1.0, 0.0, 4.0),
            p("petal3D_x1", 0.0),
            p("petal3D_x2", 0.0),
            p("petal3D_x3", 0.0),
            p("petal3D_x4", 0.0),
            p("petal3D_x5", 0.0),
            p("petal3D_x6", 0.0),
            p("petal3D_y1", 0.0),
            p("petal3D_y2", 0.0),
            p("petal3D_y3", 0.0),
            p("petal3D_y4", 0.0),
            p("petal3D_y5", 0.0),
            p("petal3D_y6", 0.0),
            p("petal3D_z1", 0.0),
            p("petal3D_z2", 0.0),
            p("petal3D_z3", 0.0),
            p("petal3D_z4", 0.0),
            p("petal3D_z5", 0.0),
            p("petal3D_z6", 0.0),
            p("petal3D_warp", 1.0),
        ])
        .flags(F3D),
    VarDef::new("shredded", shredded)
        .params(&[
            p("shredded_x1", 1.0),
            p("shredded_x2", 3.0),
            p("shredded_x3", 1.0),
            p("shredded_x_blur_amount", 0.1),
            p("shredded_y1", 1.0),
            p("shredded_y2", 3.0),
            p("shredded_y3", 1.0),
            p("shredded_y_blur_amount", 0.1),
            p("shredded_z1", 1.0),
            p("shredded_z2", 3.0),
            p("shredded_z3", 1.0),
            p("shredded_z_blur_amount", 0.1),
            p_int("shredded_type", 0.0, 0.0, 2.0),
            p_int("shredded_blur", 0.0, 0.0, 1.0),
        ])
        .flags(F3D | flag::RANDOM),
    VarDef::new("hypertile3D2b", hypertile3d2b)
        .params(&[
            p_int("hypertile3D2b_p", 3.0, 3.0, 2147483647.0),
            p_int("hypertile3D2b_q", 7.0, 3.0, 2147483647.0),
            p("hypertile3D2b_b", 2.0),
            p("hypertile3D2b_c", 2.0),
            p("hypertile3D2b_d", 1.0),
            p("hypertile3D2b_e", 1.0),
            p("hypertile3D2b_f", 1.0),
            p("hypertile3D2b_g", 2.0),
            p("hypertile3D2b_h", 1.0),
            p("hypertile3D2b_i", 1.0),
            p("hypertile3D2b_j", 1.0),
            p("hypertile3D2b_k", 1.0),
        ])
        .flags(F3D | flag::RANDOM)
        .prepare(hypertile3d2b_prepare),
    VarDef::new("jubiQ", jubiq)
        .params(&[
            // JWildfire draws this default at random; the value of its test vectors.
            p_int_nonzero("jubiQ_power", -3.0, NEG_INF, INF),
            p("jubiQ_dist", 1.0),
            p("jubiQ_a", 1.0),
            p("jubiQ_b", 0.0),
            p("jubiQ_c", 0.0),
            p("jubiQ_d", 1.0),
            p("jubiQ_e", 0.0),
            p("jubiQ_f", 0.0),
            p("jubiQ_qat", 0.0),
            p("jubiQ_qax", 0.0),
            p("jubiQ_qay", 0.0),
            p("jubiQ_qaz", 0.0),
            p("jubiQ_qbt", 0.0),
            p("jubiQ_qbx", 0.0),
            p("jubiQ_qby", 0.0),
            p("jubiQ_qbz", 0.0),
            p("jubiQ_qct", 0.0),
            p("jubiQ_qcx", 0.0),
            p("jubiQ_qcy", 0.0),
            p("jubiQ_qcz", 0.0),
            p("jubiQ_qdt", 1.0),
            p("jubiQ_qdx", 0.0),
            p("jubiQ_qdy", 0.0),
            p("jubiQ_qdz", 0.0),
            p_int("jubiQ_zmode", 0.0, 0.0, 2.0),
        ])
        .flags(F3D | flag::RANDOM),
];

/// ennepers2 (DarkBeam): a variant of Enneper's minimal surface over the plane.
fn ennepers2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c] = v.params();
    let (x, y) = (t.x, t.y);
    let r2 = 1.0 / (x * x + y * y);
    let dxy = (a * x) * (a * x) - (b * y) * (b * y);
    [
        v.w * x * (a * a - dxy * r2 - c * x.abs().sqrt()),
        v.w * y * (b * b - dxy * r2 - c * y.abs().sqrt()),
        v.w * dxy * 0.5 * r2.sqrt(),
    ]
}

/// petal3D_apo (Larry Berlin's petal3D): the petal cos x·(cos x·cos y)³, cos x·(sin x·cos y)³
/// lifted in z by a blend of two wave shapes chosen by `style`.
fn petal3d_apo(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [width, zshape, scale1, scale2, style] = v.params();
    let (x, y) = (t.x, t.y);
    let style_sign = if style >= 0.0 { 1.0 } else { -1.0 };
    let a = x.cos();
    let bx = (x.cos() * y.cos()).powi(3);
    let by = (x.sin() * y.cos()).powi(3);
    let ox = v.w * a * bx;
    let tmp_py = v.w * a * by * width;
    let wave = -(x * scale1 * PI).sin() * 0.5;
    let squeeze = if scale1.abs() > 1.0 {
        scale1.abs() - 1.0
    } else {
        0.0
    };
    let shaper = wave + x * squeeze * 0.5 + (y * scale2 * PI).abs().sin();
    let shaper2 = wave + x * squeeze * 0.5 + tmp_py * scale2 * 0.5;
    let smooth = 0.5 - style * style;
    let pz = if style.abs() > FRAC_1_SQRT_2 {
        shaper2 * style_sign
    } else if style < 0.0 {
        smooth * 2.0 * shaper - (1.0 - smooth * 2.0) * shaper2
    } else if style > 0.0 {
        smooth * 2.0 * shaper + (1.0 - smooth * 2.0) * shaper2
    } else {
        shaper
    };
    [ox, tmp_py, v.w * pz * zshape]
}

/// whitney_umbrella: Whitney's umbrella (u·v, u, v²) over the plane.
fn whitney_umbrella(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (u, w) = (t.x, t.y);
    [v.w * u * w, v.w * u, v.w * w * w]
}

/// butterfly3D: Apophysis' butterfly with a z lift of |2y|·r/4.
fn butterfly3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let wx = v.w * 1.302_940_031_741_119_8;
    let y2 = t.y * 2.0;
    let r = wx * ((t.y * t.x).abs() / (1e-300 + t.x * t.x + y2 * y2)).sqrt();
    [
        r * t.x,
        r * y2,
        r * y2.abs() * (t.x * t.x + t.y * t.y).sqrt() / 4.0,
    ]
}

/// inflateZ_2: adds z = 0.25 − (2y + 2x)·0.333333 (x and y are left alone).
fn inflatez_2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let aval = (t.y * 2.0 + t.x * 2.0) * 0.333333;
    [0.0, 0.0, v.w * (0.25 - aval)]
}

/// inflateZ_4: adds z = ±(π/2 − angle)/4, the sign at random.
fn inflatez_4(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let ang = t.y.atan2(t.x);
    let mut val = FRAC_PI_2 - ang;
    if rng.f01() < 0.5 {
        val = -val;
    }
    [0.0, 0.0, v.w * val * 0.25]
}

/// inflateZ_6: adds z = 1.5 − acos(sin a · a·sin(y − x) / 2), a the point's angle.
fn inflatez_6(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let ang = t.y.atan2(t.x);
    let kik = ang * (t.y - t.x).sin();
    [0.0, 0.0, v.w * (1.5 - (ang.sin() * kik * 0.5).acos())]
}

/// sph3D: a 3-D inversion in an ellipsoid (JWildfire scales z by the x factor, as kept here).
fn sph3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [px, py, _] = v.params();
    let (xx, yy, zz) = (px * t.x, py * t.y, px * t.z);
    let r = v.w / (xx * xx + yy * yy + zz * zz + 1e-29);
    [t.x * r, t.y * r, t.z * r]
}

/// spherical3D_wf: the 3-D inversion p / |p|^exponent (subtracted when `invert` is not 0).
fn spherical3d_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [invert, exponent] = v.params();
    let d = t.x * t.x + t.y * t.y + t.z * t.z + 1e-300;
    let r = if (exponent - 2.0).abs() < 1e-8 {
        v.w / d
    } else {
        v.w / d.powf(exponent / 2.0)
    };
    let s = if invert == 0.0 { r } else { -r };
    [t.x * s, t.y * s, t.z * s]
}

/// onion2: the plane wrapped onto an onion: a circular profile up to `meeting_pt`, then an
/// exponential spire (cut at `top_crop`), positive z curling inside.
fn onion2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        meeting_pt,
        circle_a,
        circle_b,
        sx,
        sy,
        sz,
        top_crop,
        stretch,
    ] = v.params();
    let (x, y, z0) = (t.x - sx, t.y - sy, t.z - sz);
    let len = (x * x + y * y).sqrt() + 1e-300;
    let tt = len / stretch - PI / 2.0;
    let (mut r, mut z);
    if tt > meeting_pt {
        r = tt.cos();
        let tm = meeting_pt.tan();
        if tm != 0.0 {
            z = (meeting_pt.cos() - r).exp() / tm + meeting_pt.sin() - 1.0 / tm;
            if z > top_crop && top_crop > 0.0 {
                z = top_crop;
                r = 0.0;
            }
        } else {
            z = top_crop;
        }
    } else {
        r = tt.cos();
        z = tt.sin();
    }
    r *= circle_a * v.w;
    z *= circle_b * v.w;
    let (ux, uy) = (x / len, y / len);
    [
        r * ux + r * z0 * ux + sx,
        r * uy + r * z0 * uy + sy,
        z + z0 * z / (r * r + z * z) + sz,
    ]
}

/// Rotation about z, then y, then x (angles in radians; a zero angle is skipped).
fn rotate_zyx(p: V3, ax: f64, ay: f64, az: f64) -> V3 {
    let [mut x, mut y, mut z] = p;
    if az != 0.0 {
        let (s, c) = az.sin_cos();
        (x, y) = (x * c - y * s, x * s + y * c);
    }
    if ay != 0.0 {
        let (s, c) = ay.sin_cos();
        (x, z) = (x * c + z * s, -x * s + z * c);
    }
    if ax != 0.0 {
        let (s, c) = ax.sin_cos();
        (y, z) = (y * c - z * s, y * s + z * c);
    }
    [x, y, z]
}

/// boxfold: Mandelbox's box fold (each coordinate beyond ±limit reflected back) in a frame
/// rotated by the three angles (degrees).
fn boxfold(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [f, rx, ry, rz] = v.params();
    let (ax, ay, az) = (rx.to_radians(), ry.to_radians(), rz.to_radians());
    let local = rotate_zyx([t.x, t.y, t.z], -ax, -ay, -az);
    let fold = |c: f64| {
        if c > f {
            2.0 * f - c
        } else if c < -f {
            -2.0 * f - c
        } else {
            c
        }
    };
    let o = rotate_zyx(local.map(fold), ax, ay, az);
    [o[0] * v.w, o[1] * v.w, o[2] * v.w]
}

/// The error function as JWildfire computes it: the Chebyshev fit of Numerical Recipes (§6.2),
/// fractional error below 1.2e-7.
pub(super) fn erf_nr(z: f64) -> f64 {
    let t = 1.0 / (1.0 + 0.5 * z.abs());
    let poly = -z * z - 1.26551223
        + t * (1.00002368
            + t * (0.37409196
                + t * (0.09678418
                    + t * (-0.18628806
                        + t * (0.27886807
                            + t * (-1.13520398
                                + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277))))))));
    let ans = 1.0 - t * poly.exp();
    if z >= 0.0 { ans } else { -ans }
}

/// erf3D: the error function of each coordinate.
fn erf3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [erf_nr(t.x) * v.w, erf_nr(t.y) * v.w, erf_nr(t.z) * v.w]
}

/// Product of three (sin(a + s_k)·cos(b + c_k)) factors (cos·cos with `cos_first`), the
/// phase pairs taken from `ph` in order.
fn petal_prod(a: f64, b: f64, ph: &[f64], cos_first: bool) -> f64 {
    let f = |u: f64| if cos_first { u.cos() } else { u.sin() };
    (f(a + ph[0]) * (b + ph[1]).cos())
        * (f(a + ph[2]) * (b + ph[3]).cos())
        * (f(a + ph[4]) * (b + ph[5]).cos())
}

/// petal3D (Raykoid666's petal with phases by Brad Stefanov): the petal cos(warp·x)·(…)³
/// with a phase in every factor, and z from one of four such products of z with x or y
/// (`mode`; 0 passes z through).
fn petal3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let q: [f64; 20] = v.params();
    let (mode, xs, ys, zs, warp) = (q[0], &q[1..7], &q[7..13], &q[13..19], q[19]);
    let (x, y, z) = (t.x, t.y, t.z);
    let ax = (x * warp).cos();
    let bx = petal_prod(x, y, xs, true);
    let by = petal_prod(x, y, ys, false);
    let oz = match mode as i32 {
        m if m <= 0 => v.w * z,
        1 => v.w * ax * petal_prod(z, x, zs, false),
        2 => v.w * ax * petal_prod(z, y, zs, false),
        3 => v.w * ax * petal_prod(y, z, zs, false),
        _ => v.w * ax * petal_prod(x, z, zs, false),
    };
    [v.w * ax * bx, v.w * ax * by, oz]
}

/// shredded (Brad Stefanov and Rick Sidwell): each coordinate times a sine or cosine of its
/// own floored multiple (type 2), of the other coordinate (type 1), or of a sum of both (type
/// 0); with `blur`, the factors are added instead and a random sine jitter joins.
fn shredded(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [x1, x2, x3, xb, y1, y2, y3, yb, z1, z2, z3, zb, kind, blur] = v.params();
    let (x, y, z) = (t.x, t.y, t.z);
    let w = v.w;
    let sx = (x1 * (x2 * x).floor()).sin();
    let cy = (y1 * (y2 * y).floor()).cos();
    let sz = (z1 * (z2 * z).floor()).sin();
    let (fx, fy, fz) = match kind as i32 {
        0 => (
            sx + (x1 * (x2 * y).floor()).cos(),
            cy + (y1 * (y2 * x).floor()).sin(),
            sz + (z1 * (z2 * z).floor()).cos(),
        ),
        _ => (sx, cy, sz),
    };
    // The coordinate each factor multiplies (or each jitter scales).
    let (mx, my, mz) = match kind as i32 {
        2 => (x, y, z),
        _ => (y, x, z),
    };
    if blur != 0.0 {
        let jx = xb * (std::f64::consts::TAU * rng.f01()).sin();
        let jy = yb * (std::f64::consts::TAU * rng.f01()).sin();
        let jz = zb * (std::f64::consts::TAU * rng.f01()).sin();
        let jz = if kind == 0.0 { jz * z } else { jz };
        [
            w * x3 * fx + jx * mx,
            w * y3 * fy + jy * my,
            w * z3 * fz + jz,
        ]
    } else {
        [w * x3 * fx * mx, w * y3 * fy * my, w * z3 * fz * mz]
    }
}

fn hypertile3d2b_prepare(v: &mut Prepared) {
    let [p, q, b, c, d, e, f, g, _, i, j, k] = v.params();
    let pa = b * PI / p;
    let qa = c * PI / q;
    let r = -(pa.cos() - d) / (pa.cos() + qa.cos());
    let cx = if r > 0.0 { e / (f + r).sqrt() } else { 1.0 };
    let c2 = cx * cx;
    v.p.extend_from_slice(&[pa, cx, c2, g * cx, i + c2, j - c2, k - c2]);
}

/// hypertile3D2b: hypertile3D2 with every constant a parameter: a Möbius-like map of the
/// ball followed by a rotation by a random multiple of b·π/p.
fn hypertile3d2b(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, _, h] = v.params();
    let [pa, cx, c2, c2x, s2x, s2y, s2z] = v.derived();
    let r2 = t.x * t.x + t.y * t.y + t.z * t.z;
    let x = t.x * s2x - cx * (-r2 - 1.0);
    let y = t.y * s2y;
    let vr = v.w / (c2 * r2 + c2x * t.x + h);
    let a = (rng.f01() * 2147483647.0).floor().min(2147483646.0) * pa;
    let (sa, ca) = a.sin_cos();
    [
        vr * (x * ca + y * sa),
        vr * (y * ca - x * sa),
        vr * (t.z * s2z),
    ]
}

/// jubiQ: a quaternion Möbius map (qa·q + qb)(qc·q + qd)⁻¹ of q = (x, y, z, 0) added to an
/// affine map of (x, y), then julian's random root of power `power`; z from the quaternion's
/// third part plus a z term chosen by `zmode`.
fn jubiq(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 25] = v.params();
    let (power, dist, a, b, c, d, e, f) = (q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]);
    let [
        t1,
        x1,
        y1,
        z1,
        t3,
        x3,
        y3,
        z3,
        t4,
        x4,
        y4,
        z4,
        t5,
        x5,
        y5,
        z5,
    ] = std::array::from_fn(|i| q[8 + i]);
    let zmode = q[24];
    let (t2, x2, y2) = (t.x, t.y, t.z);
    let nt = t1 * t2 - x1 * x2 - y1 * y2 + t3;
    let nx = t1 * x2 + x1 * t2 - z1 * y2 + x3;
    let ny = t1 * y2 + y1 * t2 + z1 * x2 + y3;
    let nz = z1 * t2 + x1 * y2 - y1 * x2 + z3;
    let dt = t4 * t2 - x4 * x2 - y4 * y2 + t5;
    let dx = t4 * x2 + x4 * t2 - z4 * y2 + x5;
    let dy = t4 * y2 + y4 * t2 + z4 * x2 + y5;
    let dz = z4 * t2 + x4 * y2 - y4 * x2 + z5;
    let ni = v.w / (dt * dt + dx * dx + dy * dy + dz * dz);
    let x = a * t.x + b * t.y + (nt * dt + nx * dx + ny * dy + nz * dz) * ni + e;
    let y = c * t.x + d * t.y + (nx * dt - nt * dx - ny * dz + nz * dy) * ni + f;
    let abs_n = power.abs();
    let k = ((rng.f01() * 2147483647.0).floor().min(2147483646.0)) % abs_n;
    let angle = (y.atan2(x) + TAU * k) / power;
    let r = v.w * (x * x + y * y).powf(dist / power * 0.5);
    let quat_z = (ny * dt - nt * dy - nz * dx + nx * dz) * ni;
    let r2d = t.x * t.x + t.y * t.y;
    let oz = match zmode as i32 {
        0 => {
            let z = t.z / 2.0;
            let r3d = (r2d + z * z).sqrt();
            quat_z + v.w / (r3d.sqrt() * r3d) * z
        }
        1 => {
            let z = t.z / abs_n;
            quat_z + v.w * (r2d + z * z).powf((1.0 / power - 1.0) * 0.5) * z
        }
        _ => quat_z + t.z,
    };
    [r * angle.cos(), r * angle.sin(), oz]
}
