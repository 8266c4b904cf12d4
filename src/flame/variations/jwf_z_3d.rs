//! JWildfire's 3-D curves and maps, from the end of its alphabet: the spirograph in space
//! `spirograph3D`, the cone-wound spiral `conicalSpiral`, the ripple blur `waveblur_wf`, the
//! quaternion Möbius maps `mobiqN` (between powers and roots) and `mobius3D_with_inverse`,
//! Zueuk's `hypertile3Db`, `juliascope3Db` and the raised board
//! `checkerboard_wf`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: weights multiply the output linearly unless
//! said otherwise, and random numbers are drawn in the order JWildfire draws them.

use std::f64::consts::{PI, TAU};

use super::fr_quaternions::mobius_quotient;
use super::*;

pub(super) const DRAWN_3D: u32 = flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("spirograph3D", spirograph3d)
        .params(&[
            p("spirograph3D_a", 1.0),
            p("spirograph3D_b", -0.3),
            p("spirograph3D_c", 0.4),
            p("spirograph3D_tmin", 0.0),
            p("spirograph3D_tmax", 1000.0),
            p("spirograph3D_width", 0.0),
            p_int("spirograph3D_mode", 0.0, 0.0, 4.0),
            p_int("spirograph3D_direct_color", 0.0, 0.0, 1.0),
        ])
        .flags(DRAWN_3D),
    VarDef::new("conicalSpiral", conical_spiral)
        .params(&[
            p("conicalSpiral_turns", 8.0),
            p("conicalSpiral_radius", 1.2),
            p("conicalSpiral_height", 1.0),
            p_int("conicalSpiral_mode", 0.0, 0.0, 3.0),
            p("conicalSpiral_z_wave_freq", 0.0),
            p("conicalSpiral_z_wave_amp", 0.0),
            p("conicalSpiral_twist", 0.0),
            p("conicalSpiral_thickness", 0.0),
            p_int("conicalSpiral_solid", 0.0, 0.0, 1.0),
            p_int("conicalSpiral_colorize", 0.0, 0.0, 1.0),
            p_int("conicalSpiral_colorMode", 0.0, 0.0, 4.0),
            p("conicalSpiral_colorSpeed", 1.0),
            p("conicalSpiral_colorOffset", 0.0),
        ])
        .flags(DRAWN_3D | flag::USES_Z),
    VarDef::new("waveblur_wf", waveblur_wf)
        .params(&[
            p_int("waveblur_wf_count", 5.0, 1.0, INF),
            p("waveblur_wf_phase", 0.0),
            p("waveblur_wf_amplitude_z", 0.5),
            p_range("waveblur_wf_damping_z", 0.0, 0.0, INF),
            p_int("waveblur_wf_direct_color", 0.0, 0.0, 1.0),
            p("waveblur_wf_color_scale", 0.5),
            p("waveblur_wf_color_offset", 0.0),
        ])
        .flags(DRAWN_3D),
    VarDef::new("mobiqN", mobiq_n)
        .params(&[
            p("mobiqN_qat", 1.0),
            p("mobiqN_qax", 0.0),
            p("mobiqN_qay", 0.0),
            p("mobiqN_qaz", 0.0),
            p("mobiqN_qbt", 0.0),
            p("mobiqN_qbx", 0.0),
            p("mobiqN_qby", 0.0),
            p("mobiqN_qbz", 0.0),
            p("mobiqN_qct", 0.0),
            p("mobiqN_qcx", 0.0),
            p("mobiqN_qcy", 0.0),
            p("mobiqN_qcz", 1.0),
            p("mobiqN_qdt", 1.0),
            p("mobiqN_qdx", 0.0),
            p("mobiqN_qdy", 0.0),
            p("mobiqN_qdz", 0.0),
            p("mobiqN_power", 2.0),
            p("mobiqN_dist", 1.0),
            p_int("mobiqN_colorMode", 0.0, NEG_INF, INF),
            p_int("mobiqN_iterations", 1.0, NEG_INF, 1000.0).limited(),
            p_int("mobiqN_spaceType", 0.0, NEG_INF, INF),
        ])
        .flags(DRAWN_3D | flag::USES_Z),
    VarDef::new("mobius3D_with_inverse", mobius3d_with_inverse)
        .params(&[
            p("mobius3D_with_inverse_a_re", 2.0),
            p("mobius3D_with_inverse_a_im", 0.0),
            p("mobius3D_with_inverse_aj", 0.0),
            p("mobius3D_with_inverse_ak", 0.0),
            p("mobius3D_with_inverse_b_re", 0.0),
            p("mobius3D_with_inverse_b_im", -1.0),
            p("mobius3D_with_inverse_bj", 0.0),
            p("mobius3D_with_inverse_bk", 0.0),
            p("mobius3D_with_inverse_c_re", 0.0),
            p("mobius3D_with_inverse_c_im", -1.0),
            p("mobius3D_with_inverse_cj", 0.0),
            p("mobius3D_with_inverse_ck", 0.0),
            p("mobius3D_with_inverse_d_re", 0.0),
            p("mobius3D_with_inverse_d_im", 0.0),
            p("mobius3D_with_inverse_dj", 0.0),
            p("mobius3D_with_inverse_dk", 0.0),
            p_int("mobius3D_with_inverse_normalize", 1.0, NEG_INF, INF),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::USES_Z)
        .prepare(mobius3d_prepare),
    VarDef::new("hypertile3Db", hypertile3db)
        .params(&[
            p_int("hypertile3Db_p", 3.0, 3.0, 2147483647.0),
            p_int("hypertile3Db_q", 7.0, 3.0, 2147483647.0),
            p_int("hypertile3Db_n", 0.0, 0.0, 2147483647.0),
            p("hypertile3Db_b", 2.0),
            p("hypertile3Db_c", 2.0),
            p("hypertile3Db_d", 1.0),
            p("hypertile3Db_e", 1.0),
            p("hypertile3Db_f", 1.0),
            p("hypertile3Db_g", 2.0),
            p("hypertile3Db_h", 2.0),
            p("hypertile3Db_i", 1.0),
            p("hypertile3Db_j", 1.0),
            p("hypertile3Db_k", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_Z | flag::USES_Z)
        .prepare(hypertile3db_prepare),
    VarDef::new("juliascope3Db", juliascope3db)
        .params(&[
            // JWildfire draws this default at random; the value of its test vectors.
            p("juliascope3Db_power", -7.0),
            p("juliascope3Db_dist", 1.0),
            p_int("juliascope3Db_type", 0.0, 0.0, 1.0),
            p("juliascope3Db_warp", 0.0),
            p("juliascope3Db_za", 1.0),
            p("juliascope3Db_zb", 1.0),
            p("juliascope3Db_zamount", 1.0),
            p("juliascope3Db_zdist", 1.0),
            p_int("juliascope3Db_mode", 0.0, 0.0, 1.0),
            p("juliascope3Db_wave1", 1.0),
            p("juliascope3Db_wave2", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::USES_Z),
    VarDef::new("checkerboard_wf", checkerboard_wf)
        .params(&[
            p("checkerboard_wf_position", 3.0),
            p("checkerboard_wf_size", 10.0),
            p_int("checkerboard_wf_axis", 2.0, 0.0, 2.0),
            // JWildfire draws these four defaults at random; the values of its test vectors.
            p("checkerboard_wf_checker_size", 0.1440320606030942),
            p("checkerboard_wf_displ_amount", 0.05),
            p_range(
                "checkerboard_wf_checker_color1",
                0.156_298_392_697_674_6,
                0.0,
                1.0,
            ),
            p_range(
                "checkerboard_wf_checker_color2",
                0.983_093_288_855_01,
                0.0,
                1.0,
            ),
            p_range(
                "checkerboard_wf_side_color",
                0.568_552_805_322_582_3,
                0.0,
                1.0,
            ),
            p_int("checkerboard_wf_with_sides", 1.0, 0.0, 1.0),
        ])
        .flags(DRAWN_3D),
];

/// A uniform number in [−width/2, width/2).
fn centred(width: f64, rng: &mut FastRng) -> f64 {
    width * rng.f01() - width / 2.0
}

/// The sum of four uniform numbers less 2, times width/2 (a rounded bell).
fn bell(width: f64, rng: &mut FastRng) -> f64 {
    width * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0) / 2.0
}

/// spirograph3D: the epitrochoid ((a+b)·cos t − c·cos((a+b)/b·t), (a+b)·sin t − c·sin(…),
/// c·sin(…)) at a uniform t in [tmin, tmax], widened by `mode`'s kind of jitter of `width`;
/// with `direct_color` the colour is t/2π modulo 1.
fn spirograph3d(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a, b, c, tmin, tmax, width, mode, direct_color] = v.params();
    let t = (tmax - tmin) * rng.f01() + tmin;
    let (w1, w2, w3) = match mode as i64 {
        0 => {
            let w = centred(width, rng);
            (w, w, w)
        }
        1 => {
            let w = centred(width, rng);
            (
                w * (36.0 * t).sin(),
                w * (36.0 * t + TAU / 3.0).sin(),
                w * (36.0 * t + 2.0 * TAU / 3.0).sin(),
            )
        }
        2 => (
            centred(width, rng),
            centred(width, rng),
            centred(width, rng),
        ),
        3 => (bell(width, rng), bell(width, rng), bell(width, rng)),
        4 => (if rng.f01() < 0.5 { width } else { -width }, 0.0, 0.0),
        _ => (0.0, 0.0, 0.0),
    };
    let k = (a + b) / b * t;
    let x = (a + b) * t.cos() - c * k.cos();
    let y = (a + b) * t.sin() - c * k.sin();
    let z = c * k.sin();
    if direct_color != 0.0 {
        acc.color = (t / TAU) % 1.0;
    }
    [v.w * (x + w1), v.w * (y + w2), v.w * (z + w3)]
}

/// conicalSpiral: a spiral of `turns` turns wound on a cone of `radius` and `height`, driven
/// by |x|, |y| or |z| modulo 1 (`mode`), its height waved and its angle twisted with the
/// height; thickened by the input point or (solid) by uniform noise; colour by progression,
/// radius, angle or height.
fn conical_spiral(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        turns,
        radius,
        height,
        mode,
        freq,
        amp,
        twist,
        thick,
        solid,
        colorize,
        cmode,
        speed,
        off,
    ] = v.params();
    let s = match mode as i64 {
        1 => t.y.abs() % 1.0,
        2 => t.z.abs() % 1.0,
        _ => t.x.abs() % 1.0,
    };
    let angle = s * TAU * turns;
    let r = s * radius;
    let mut z = s * height;
    if amp != 0.0 {
        z += (s * TAU * freq).sin() * amp;
    }
    let a = if twist != 0.0 {
        angle + z * twist
    } else {
        angle
    };
    let mut x = r * a.cos();
    let mut y = r * a.sin();
    if thick > 0.0 {
        if solid > 0.0 {
            x += rng.f01() * thick;
            y += rng.f01() * thick;
            z += rng.f01() * thick;
        } else {
            x += t.x * thick;
            y += t.y * thick;
            z += t.z * thick;
        }
    }
    if colorize > 0.0 {
        let driver = match cmode as i64 {
            0 => s,
            1 => r,
            2 => (angle % TAU) / TAU,
            _ => z,
        };
        acc.color = (driver * speed + off).abs() % 1.0;
    }
    [v.w * x, v.w * y, v.w * z]
}

/// waveblur_wf: a disc blur whose radius follows acos of a uniform number less a random
/// whole number (1–count) of half-turns plus `phase`, over count·π; z rises by
/// (cos u − 1/2)·amplitude, damped by exp(r·damping); with `direct_color` the colour is
/// acos u·scale + offset (clamped to [0, 1]).
fn waveblur_wf(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [count, phase, amp_z, damping, direct_color, cscale, coff] = v.params();
    let ang = rng.f01() * TAU;
    let rnd = 1.0 - 2.0 * rng.f01();
    let arc = if rng.f01() < 0.5 {
        rnd.acos()
    } else {
        (-rnd).acos()
    };
    let k = ((rng.f01() * count) as i64 as f64).min(count - 1.0);
    let r = (arc - (k + 1.0) * PI + phase) * (v.w / (count * PI));
    if direct_color == 1.0 {
        acc.color = (rnd.acos() * cscale + coff).clamp(0.0, 1.0);
    }
    let mut z = 0.0;
    if amp_z != 0.0 {
        let mut zamp = (rnd.cos() - 0.5) * amp_z;
        if damping.abs() > 1e-300 {
            zamp *= (r * damping).exp();
        }
        z = v.w * zamp;
    }
    [r * ang.cos(), r * ang.sin(), z]
}

/// Spherical coordinates (ρ, θ = atan2(y, x), φ = acos(z/ρ), 0 at the origin).
fn spherical(x: f64, y: f64, z: f64) -> (f64, f64, f64) {
    let rho = (x * x + y * y + z * z).sqrt();
    let phi = if rho == 0.0 { 0.0 } else { (z / rho).acos() };
    (rho, y.atan2(x), phi)
}

/// The point of spherical coordinates (ρ, θ, φ).
fn from_spherical(rho: f64, theta: f64, phi: f64) -> [f64; 3] {
    let s = phi.sin();
    [
        rho * s * theta.cos(),
        rho * s * theta.sin(),
        rho * phi.cos(),
    ]
}

/// One step of the quaternion Möbius map (a·q + b)/(c·q + d) on q = (x, y, z, 0) read as
/// (t, x, y): the new (t, x, y, z) and |c·q + d|².
fn mobiq_step(q: &[f64; 16], p: [f64; 3]) -> ([f64; 4], f64) {
    let (n, d2) = mobius_quotient(q, p);
    if d2 == 0.0 {
        return ([0.0; 4], d2);
    }
    let inv = 1.0 / d2;
    (n.map(|c| c * inv), d2)
}

/// mobiqN: the quaternion Möbius map between an n-th power and a random n-th root in
/// spherical coordinates (ρ to the power 4·dist/n, both angles times n), applied `iterations`
/// times in flat, hyperbolic (sinh/asinh) or spherical (sin/asin) space; colour by one of six
/// measures (`colorMode` 1–6).
fn mobiq_n(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 21] = v.params();
    let quat: [f64; 16] = q[..16].try_into().expect("16 coefficients");
    let [power, dist, color_mode, iterations, space] = [q[16], q[17], q[18], q[19], q[20]];
    let z_scale = if power != 0.0 {
        4.0 * dist / power
    } else {
        0.0
    };
    let (rho, theta, phi) = spherical(t.x, t.y, t.z);
    let new_rho = rho.powf(z_scale);
    let mut p = from_spherical(new_rho, theta * power, phi * power);
    match space as i64 {
        1 => p = p.map(f64::sinh),
        2 => p = p.map(f64::sin),
        _ => {}
    }
    let (mut tq, mut d2) = (0.0, 0.0);
    for _ in 0..(iterations as i64).max(1) {
        let (r, d) = mobiq_step(&quat, p);
        (tq, d2) = (r[0], d);
        p = [r[1], r[2], r[3]];
    }
    match space as i64 {
        1 => p = p.map(f64::asinh),
        2 => p = p.map(f64::asin),
        _ => {}
    }
    let inv_scale = if z_scale != 0.0 { 1.0 / z_scale } else { 0.0 };
    let (rho_r, theta_r, phi_r) = spherical(p[0], p[1], p[2]);
    let final_rho = rho_r.powf(inv_scale);
    let fp = power.floor();
    let n_theta = (power * rng.f01()).floor();
    let n_phi = (power * rng.f01()).floor();
    let (ft, fphi) = if fp != 0.0 {
        ((theta_r + n_theta * TAU) / fp, (phi_r + n_phi * TAU) / fp)
    } else {
        (theta_r, phi_r)
    };
    let f = from_spherical(final_rho, ft, fphi);
    match color_mode as i64 {
        1 => acc.color = new_rho * inv_scale * 0.1,
        2 => acc.color = (tq + 1.0) * 0.5,
        3 => acc.color = d2.sqrt().atan() / (PI * 0.5),
        4 => {
            let len = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
            acc.color = if len > 1e-8 {
                (f[2] / len + 1.0) * 0.5
            } else {
                0.5
            };
        }
        5 => {
            acc.color = if rho > 1e-8 {
                (final_rho / rho).atan() / (PI * 0.5)
            } else {
                0.5
            };
        }
        6 => {
            let n = (ft - theta) / TAU;
            acc.color = n - n.floor();
        }
        _ => {}
    }
    f.map(|c| v.w * c)
}

/// A quaternion (real part first).
type Quat = [f64; 4];

fn qmul(a: Quat, b: Quat) -> Quat {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

fn qadd(a: Quat, b: Quat) -> Quat {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]]
}

/// b⁻¹·a (the conjugate of b over its squared norm, times a).
fn qdiv_left(a: Quat, b: Quat) -> Quat {
    let n = (b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3]).sqrt();
    let n2 = n * n;
    qmul([b[0] / n2, -b[1] / n2, -b[2] / n2, -b[3] / n2], a)
}

/// The matrix (a, b, c, d), divided by (ad − bc)² when `normalize` is 1, and its inverse
/// (d, −b, −c, a): 32 derived values.
fn mobius3d_prepare(v: &mut Prepared) {
    let q: [f64; 17] = v.params();
    let quat = |i: usize| -> Quat { [q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]] };
    let mut m = [quat(0), quat(1), quat(2), quat(3)];
    if q[16] == 1.0 {
        let bc = qmul(m[1], m[2]);
        let ad = qmul(m[0], m[3]);
        let det = [ad[0] - bc[0], ad[1] - bc[1], ad[2] - bc[2], ad[3] - bc[3]];
        let den = qmul(det, det);
        m = m.map(|x| qdiv_left(x, den));
    }
    let neg = |x: Quat| qmul(x, [-1.0, 0.0, 0.0, 0.0]);
    let inv = [m[3], neg(m[1]), neg(m[2]), m[0]];
    for x in m.iter().chain(inv.iter()) {
        v.p.extend_from_slice(x);
    }
}

/// mobius3D_with_inverse: the quaternion Möbius map (a·q + b)/(c·q + d) of q = (x, y, z, 0) or,
/// with odds 1/2, its inverse map (the division from the left).
fn mobius3d_with_inverse(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let m = if rng.f01() < 0.5 {
        v.table(0)
    } else {
        v.table(16)
    };
    let q = |i: usize| -> Quat { [m[4 * i], m[4 * i + 1], m[4 * i + 2], m[4 * i + 3]] };
    let z: Quat = [t.x, t.y, t.z, 0.0];
    let out = qdiv_left(qadd(qmul(z, q(0)), q(1)), qadd(qmul(z, q(2)), q(3)));
    [v.w * out[0], v.w * out[1], v.w * out[2]]
}

/// hypertile3Db's constants from the tiling {p, q}, the rotation n and the free factors
/// b … k: [c2x, c2y, c2, s2x, s2y, s2z, cx, cy].
fn hypertile3db_prepare(v: &mut Prepared) {
    let [p, q, n, b, c, d, e, f, g, h, i, j, k] = v.params();
    let (pa, qa) = (b * PI / p, c * PI / q);
    let r = -(pa.cos() - d) / (pa.cos() + qa.cos());
    let r = if r > 0.0 { e / (f + r).sqrt() } else { 1.0 };
    let (cx, cy) = (r * (n * pa).cos(), r * (n * pa).sin());
    let (cx2, cy2) = (cx * cx, cy * cy);
    v.p.extend_from_slice(&[
        g * cx,
        h * cy,
        cx2 + cy2,
        i + cx2 - cy2,
        j + cy2 - cx2,
        k - cy2 - cx2,
        cx,
        cy,
    ]);
}

/// hypertile3Db: Zueuk's 3-D hyperbolic tile map with every constant a parameter (Brad
/// Stefanov's form).
fn hypertile3db(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [c2x, c2y, c2, s2x, s2y, s2z, cx, cy] = v.derived();
    let r2 = t.x * t.x + t.y * t.y + t.z * t.z;
    let (x2cx, y2cy) = (c2x * t.x, c2y * t.y);
    let d = v.w / (c2 * r2 + x2cx - y2cy + 1.0);
    [
        d * (t.x * s2x - cx * (y2cy - r2 - 1.0)),
        d * (t.y * s2y + cy * (-x2cx - r2 - 1.0)),
        d * (t.z * s2z),
    ]
}

/// JWildfire's `Tools.FTOI`: round half away from zero.
fn ftoi(x: f64) -> i64 {
    if x > 0.0 {
        (x + 0.5) as i64
    } else if x < 0.0 {
        (x - 0.5) as i64
    } else {
        0
    }
}

/// JWildfire's bounded draw `random(n)`: ⌊u·n⌋, or n − 1 where that is not below n.
pub(super) fn draw_below(rng: &mut FastRng, n: i64) -> i64 {
    let k = (rng.f01() * n as f64) as i64;
    if k < n { k } else { n.wrapping_sub(1) }
}

/// juliascope3Db: juliascope in space (Brad Stefanov's form): a random root of the angle,
/// alternately mirrored, at radius r^dist/power (r of x, y or of x, y, z by `type`), z from
/// the weighted (x², y², z/|power| + warp) norm, optionally waved by sin wave1·cos wave2.
fn juliascope3db(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        power,
        dist,
        kind,
        warp,
        za,
        zb,
        zamount,
        zdist,
        mode,
        wave1,
        wave2,
    ] = v.params();
    let abs_power = ftoi(power).wrapping_abs();
    let c_power = dist / power * 0.5;
    let z = t.z / abs_power as f64 + warp;
    let r2d = t.x * t.x * za + t.y * t.y * zb;
    let rz = v.w * zamount * (r2d + z * z).powf(c_power * zdist);
    let rnd = draw_below(rng, abs_power);
    let ang = t.y.atan2(t.x);
    let a = if rnd & 1 == 0 {
        (2.0 * PI * rnd as f64 + ang) / power
    } else {
        (2.0 * PI * rnd as f64 - ang) / power
    };
    let rr = if kind != 0.0 {
        t.x * t.x + t.y * t.y + t.z * t.z
    } else {
        t.x * t.x + t.y * t.y
    };
    let r = v.w * rr.powf(c_power);
    let wave = if mode != 0.0 {
        wave1.sin() * wave2.cos()
    } else {
        1.0
    };
    [r * a.cos(), r * a.sin(), rz * z * wave]
}

/// checkerboard_wf: a checkerboard of square cells `checker_size` across on the unit square
/// (scaled by `size`, lifted to `position`), one colour raised by `displ_amount`; with
/// `with_sides` the raised cells' walls too, in their own colour, with odds by their area.
/// `axis` lays it in the xy, yz or zx plane.
fn checkerboard_wf(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        position,
        size,
        axis,
        cs,
        displ,
        c1,
        c2,
        side_color,
        with_sides,
    ] = v.params();
    let first = |u: f64, w: f64| ((u / cs).floor() + (w / cs).floor()) % 2.0 < 1.0;
    let top = |rng: &mut FastRng, acc: &mut Acc| {
        let (x, y) = (rng.f01(), rng.f01());
        let f = first(x, y);
        acc.color = if f { c1 } else { c2 };
        (x, y, if f { displ } else { 0.0 })
    };
    let (x, y, z) = if with_sides == 0.0 || displ.abs() < 1e-8 {
        top(rng, acc)
    } else {
        let side_area = 4.0 * displ;
        let side_prob = side_area / (1.0 + side_area);
        let mut max_checks = ftoi(1.0 / cs);
        if max_checks as f64 * cs >= 1.0 {
            max_checks -= 1;
        }
        if max_checks > 0 && rng.f01() < side_prob {
            acc.color = side_color;
            let (x, y) = if rng.f01() < 0.5 {
                let x = draw_below(rng, max_checks.wrapping_add(1)) as f64 * cs;
                (x, rng.f01())
            } else {
                let x = rng.f01();
                (x, draw_below(rng, max_checks.wrapping_add(1)) as f64 * cs)
            };
            (x, y, displ * rng.f01())
        } else {
            top(rng, acc)
        }
    };
    let (x, y, z) = ((x - 0.5) * size, (y - 0.5) * size, z * size + position);
    let o = match axis as i64 {
        0 => [x, y, z],
        1 => [z, x, y],
        _ => [y, z, x],
    };
    o.map(|c| v.w * c)
}
