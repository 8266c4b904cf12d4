//! The quaternion functions of Fractorium's catalogue: the trigonometric and hyperbolic
//! functions (`sinq` … `cothq`), the exponential (`estiq`), the logarithm (`loq`) and a Möbius map
//! (`mobiq`) of the point taken as the quaternion x + y·i + z·j.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::E;

use super::util::{quat_mul_conj, sqr, zeps};
use super::*;
use crate::flame::fastmath::{self as fm, FastTrig};

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("coshq", coshq).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("cosq", cosq).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("cothq", cothq).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("cotq", cotq).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("cschq", cschq)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("cscq", cscq)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("estiq", estiq).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("loq", loq)
        .params(&[p_range("loq_base", E, f64::EPSILON, INF)])
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_loq),
    super::inlined!("mobiq", mobiq)
        .params(&[
            p("mobiq_at", 1.0),
            p("mobiq_ax", 0.0),
            p("mobiq_ay", 0.0),
            p("mobiq_az", 0.0),
            p("mobiq_bt", 0.0),
            p("mobiq_bx", 0.0),
            p("mobiq_by", 0.0),
            p("mobiq_bz", 0.0),
            p("mobiq_ct", 0.0),
            p("mobiq_cx", 0.0),
            p("mobiq_cy", 0.0),
            p("mobiq_cz", 0.0),
            p("mobiq_dt", 1.0),
            p("mobiq_dx", 0.0),
            p("mobiq_dy", 0.0),
            p("mobiq_dz", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("sechq", sechq)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("secq", secq)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("sinhq", sinhq).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("sinq", sinq).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("tanhq", tanhq).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("tanq", tanq).flags(flag::USES_Z | flag::WRITES_Z),
];

/// Quaternion hyperbolic cosine of (x, y, z) taken as x + y·i + z·j.
#[inline(always)]
fn coshq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = (t.y * t.y + t.z * t.z).sqrt();
    let (s, c) = m.fsin_cos();
    let (sh, ch) = (fm::sinh(t.x), fm::cosh(t.x));
    let d = v.w * sh * s / zeps(m);
    [v.w * c * ch, d * t.y, d * t.z]
}

/// Quaternion cosine of (x, y, z) taken as x + y·i + z·j.
#[inline(always)]
fn cosq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = (t.y * t.y + t.z * t.z).sqrt();
    let (s, c) = t.x.fsin_cos();
    let (sh, ch) = (fm::sinh(m), fm::cosh(m));
    let d = -v.w * s * sh / zeps(m);
    [v.w * c * ch, d * t.y, d * t.z]
}

/// Quaternion hyperbolic cotangent of (x, y, z) taken as x + y·i + z·j (Fractorium's form, whose
/// normalisation divides by |q|⁴).
#[inline(always)]
fn cothq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let yz2 = t.y * t.y + t.z * t.z;
    let m = yz2.sqrt();
    let k = v.w / zeps(sqr(t.x * t.x + yz2));
    let (s, c) = m.fsin_cos();
    let (sh, ch) = (fm::sinh(t.x), fm::cosh(t.x));
    let d = ch * s / zeps(m);
    let b = sh * s / zeps(m);
    quat_mul_conj(sh * c, d, ch * c, b, t.y, t.z, k)
}

/// Quaternion cotangent of (x, y, z) taken as x + y·i + z·j (Fractorium's form, normalised by
/// |q|²).
#[inline(always)]
fn cotq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let yz2 = t.y * t.y + t.z * t.z;
    let m = yz2.sqrt();
    let k = v.w / zeps(t.x * t.x + yz2);
    let (s, c) = t.x.fsin_cos();
    let (sh, ch) = (fm::sinh(m), fm::cosh(m));
    let d = c * sh / zeps(m);
    let b = -s * sh / zeps(m);
    let [x, y, z] = quat_mul_conj(s * ch, d, c * ch, b, t.y, t.z, k);
    [x, -y, -z]
}

/// Hyperbolic cosecant of the quaternion x + (y, z): 1/sinh(q).
#[inline(always)]
fn cschq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let av = (t.y * t.y + t.z * t.z).sqrt();
    let ni = v.w / zeps(t.sumsq + t.z * t.z);
    let (s, c) = av.fsin_cos();
    let (sh, ch) = (fm::sinh(t.x), fm::cosh(t.x));
    let d = ni * ch * s / zeps(av);
    [sh * c * ni, -(d * t.y), -(d * t.z)]
}

/// Cosecant of the quaternion x + (y, z): 1/sin(q).
#[inline(always)]
fn cscq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let av = (t.y * t.y + t.z * t.z).sqrt();
    let ni = v.w / zeps(t.sumsq + t.z * t.z);
    let (s, c) = t.x.fsin_cos();
    let (sh, ch) = (fm::sinh(av), fm::cosh(av));
    let d = ni * c * sh / zeps(av);
    [s * ch * ni, -(d * t.y), -(d * t.z)]
}

/// Exponential of the quaternion x + (y, z).
#[inline(always)]
fn estiq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let av = (t.y * t.y + t.z * t.z).sqrt();
    let e = t.x.exp();
    let (s, c) = av.fsin_cos();
    let a = e * s / zeps(av);
    [v.w * e * c, v.w * a * t.y, v.w * a * t.z]
}

fn prep_loq(v: &mut Prepared) {
    let [base] = v.params();
    v.p.push(0.5 / base.ln());
}

/// loq: the quaternion logarithm of (x, y, z) in base `base`: log of the norm on x, the unit
/// imaginary part times the angle on (y, z).
#[inline(always)]
fn loq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scale] = v.derived();
    let im = (t.y * t.y + t.z * t.z).sqrt();
    let k = v.w * im.atan2(t.x) / zeps(im);
    [(t.x * t.x + im * im).ln() * scale, k * t.y, k * t.z]
}

/// mobiq: a quaternion Möbius map (A·q + B)(C·q + D)⁻¹ of q = x + y·i + z·j, each coefficient a
/// quaternion (t, x, y, z).
#[inline(always)]
fn mobiq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (n, d2) = mobius_quotient(&v.params(), [t.x, t.y, t.z]);
    let inv = v.w / d2;
    [n[0] * inv, n[1] * inv, n[2] * inv]
}

/// The quaternion Möbius map (A·q + B)(C·q + D)⁻¹ of q = (p₀, p₁, p₂, 0), coefficients
/// A, B, C, D as (t, x, y, z) in `q`, before the division: (A·q + B)·conj(C·q + D) and
/// |C·q + D|².
#[inline(always)]
pub(super) fn mobius_quotient(q: &[f64; 16], p: [f64; 3]) -> ([f64; 4], f64) {
    let [
        at,
        ax,
        ay,
        az,
        bt,
        bx,
        by,
        bz,
        ct,
        cx,
        cy,
        cz,
        dt,
        dx,
        dy,
        dz,
    ] = *q;
    let [p0, p1, p2] = p;
    let nt = at * p0 - ax * p1 - ay * p2 + bt;
    let nx = at * p1 + ax * p0 - az * p2 + bx;
    let ny = at * p2 + ay * p0 + az * p1 + by;
    let nz = az * p0 + ax * p2 - ay * p1 + bz;
    let et = ct * p0 - cx * p1 - cy * p2 + dt;
    let ex = ct * p1 + cx * p0 - cz * p2 + dx;
    let ey = ct * p2 + cy * p0 + cz * p1 + dy;
    let ez = cz * p0 + cx * p2 - cy * p1 + dz;
    (
        [
            nt * et + nx * ex + ny * ey + nz * ez,
            nx * et - nt * ex - ny * ez + nz * ey,
            ny * et - nt * ey - nz * ex + nx * ez,
            nz * et - nx * ey + ny * ex - nt * ez,
        ],
        et * et + ex * ex + ey * ey + ez * ez,
    )
}

/// |(y, z)|, the length of the "imaginary" part of the quaternion (x, y, z).
#[inline(always)]
fn imag_len(t: &VarIn) -> f64 {
    (t.y * t.y + t.z * t.z).sqrt()
}

/// Quaternion hyperbolic secant of (x, y, z, 0): 1/cosh q.
#[inline(always)]
fn sechq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = imag_len(t);
    let ni = v.w / zeps(t.sumsq + t.z * t.z);
    let (s, c) = a.fsin_cos();
    let (sh, ch) = (fm::sinh(t.x), fm::cosh(t.x));
    let d = ni * sh * s / zeps(a);
    [ch * c * ni, -(d * t.y), -(d * t.z)]
}

/// Quaternion secant of (x, y, z, 0): 1/cos q.
#[inline(always)]
fn secq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = imag_len(t);
    let ni = v.w / zeps(t.sumsq + t.z * t.z);
    let (s, c) = (-t.x).fsin_cos();
    let (sh, ch) = (fm::sinh(a), fm::cosh(a));
    let d = ni * s * sh / zeps(a);
    [c * ch * ni, -(d * t.y), -(d * t.z)]
}

/// Quaternion hyperbolic sine of (x, y, z, 0).
#[inline(always)]
fn sinhq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = imag_len(t);
    let (s, c) = a.fsin_cos();
    let (sh, ch) = (fm::sinh(t.x), fm::cosh(t.x));
    let d = v.w * ch * s / zeps(a);
    [v.w * sh * c, d * t.y, d * t.z]
}

/// Quaternion sine of (x, y, z, 0).
#[inline(always)]
fn sinq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = imag_len(t);
    let (s, c) = t.x.fsin_cos();
    let (sh, ch) = (fm::sinh(a), fm::cosh(a));
    let d = v.w * c * sh / zeps(a);
    [v.w * s * ch, d * t.y, d * t.z]
}

/// tanhq: the hyperbolic tangent of the quaternion (x, y, z, 0).
#[inline(always)]
fn tanhq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (x, y, z) = (t.x, t.y, t.z);
    let yz_sq = sqr(y) + sqr(z);
    let yz_len = yz_sq.sqrt();
    let k = v.w / zeps(sqr(x) + yz_sq);
    let (s, c) = yz_len.fsin_cos();
    let sh = fm::sinh(x);
    let ch = fm::cosh(x);
    let d = ch * s / zeps(yz_len);
    let b = sh * s / zeps(yz_len);
    quat_mul_conj(sh * c, d, c * ch, b, y, z, k)
}

/// tanq: the tangent of the quaternion (x, y, z, 0).
#[inline(always)]
fn tanq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (x, y, z) = (t.x, t.y, t.z);
    let yz_sq = sqr(y) + sqr(z);
    let yz_len = yz_sq.sqrt();
    let k = v.w / zeps(sqr(x) + yz_sq);
    let (s, c) = x.fsin_cos();
    let sh = fm::sinh(yz_len);
    let ch = fm::cosh(yz_len);
    let d = c * sh / zeps(yz_len);
    let b = -s * sh / zeps(yz_len);
    quat_mul_conj(s * ch, d, c * ch, b, y, z, k)
}
