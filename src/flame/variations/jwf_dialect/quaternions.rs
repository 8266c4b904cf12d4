//! JWildfire's quaternion functions (zephyrtronium's quaternion plug-in pack as JWildfire
//! computes it) where they differ from Fractorium's: no guard against a zero vector part (a
//! point on the x axis gives NaN, as in JWildfire), `cotq`'s and `cothq`'s normalisation by
//! |q|² (JWildfire's `cothq` is its `tanhq`), and `loq`'s real part weighted like the others.
//! The point (x, y, z) is the quaternion x + y·i + z·j; m = |(y, z)| is its vector part's norm.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use crate::flame::variations::*;

/// The norm of the vector part, |(y, z)|.
fn vnorm(t: &VarIn) -> f64 {
    t.y.hypot(t.z)
}

/// The quaternion x + k·(y·i + z·j).
fn along(x: f64, k: f64, t: &VarIn) -> V3 {
    [x, k * t.y, k * t.z]
}

/// sin q = sin x·cosh m + cos x·sinh m·v/m.
pub(super) fn sinq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = vnorm(t);
    let (s, c) = t.x.sin_cos();
    along(v.w * s * m.cosh(), v.w * c * m.sinh() / m, t)
}

/// cos q = cos x·cosh m − sin x·sinh m·v/m.
pub(super) fn cosq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = vnorm(t);
    let (s, c) = t.x.sin_cos();
    along(v.w * c * m.cosh(), -v.w * s * m.sinh() / m, t)
}

/// sinh q = sinh x·cos m + cosh x·sin m·v/m.
pub(super) fn sinhq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = vnorm(t);
    let (s, c) = m.sin_cos();
    along(v.w * t.x.sinh() * c, v.w * t.x.cosh() * s / m, t)
}

/// cosh q = cosh x·cos m + sinh x·sin m·v/m.
pub(super) fn coshq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = vnorm(t);
    let (s, c) = m.sin_cos();
    along(v.w * t.x.cosh() * c, v.w * t.x.sinh() * s / m, t)
}

/// exp q = eˣ·(cos m + sin m·v/m).
pub(super) fn estiq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = vnorm(t);
    let e = t.x.exp();
    let (s, c) = m.sin_cos();
    along(v.w * e * c, v.w * e * s / m, t)
}

/// The weight over |q|², the scale of the reciprocal functions.
fn inv_norm(v: &Prepared, t: &VarIn) -> f64 {
    v.w / (t.x * t.x + t.y * t.y + t.z * t.z)
}

/// sec q = 1/cos q.
pub(super) fn secq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = vnorm(t);
    let ni = inv_norm(v, t);
    let (s, c) = (-t.x).sin_cos();
    along(c * m.cosh() * ni, -ni * s * m.sinh() / m, t)
}

/// sech q = 1/cosh q.
pub(super) fn sechq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = vnorm(t);
    let ni = inv_norm(v, t);
    let (s, c) = m.sin_cos();
    along(t.x.cosh() * c * ni, -ni * t.x.sinh() * s / m, t)
}

/// csc q = 1/sin q.
pub(super) fn cscq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = vnorm(t);
    let ni = inv_norm(v, t);
    let (s, c) = t.x.sin_cos();
    along(s * m.cosh() * ni, -ni * c * m.sinh() / m, t)
}

/// csch q = 1/sinh q.
pub(super) fn cschq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = vnorm(t);
    let ni = inv_norm(v, t);
    let (s, c) = m.sin_cos();
    along(t.x.sinh() * c * ni, -ni * t.x.cosh() * s / m, t)
}

/// The quotient form the tangents share: with a = stcv, d = ctcv and the vector parts
/// b·v/m, k·v/m of numerator and denominator, x = (a·d + k·b·|v|²)·n and the vector part
/// `sign`·(k·d − a·b)·n·v, n the weight over |q|².
fn tan_like(v: &Prepared, t: &VarIn, [a, d, k, b]: [f64; 4], sign: f64) -> V3 {
    let sysz = t.y * t.y + t.z * t.z;
    let ni = v.w / (t.x * t.x + sysz);
    let x = (a * d + k * b * sysz) * ni;
    let (y, z) = (-a * b * t.y + k * t.y * d, -a * b * t.z + k * t.z * d);
    [x, sign * y * ni, sign * z * ni]
}

/// The circular parts of tan q and cot q: sin x·cosh m, cos x·cosh m, cos x·sinh m/m,
/// −sin x·sinh m/m.
fn circular_parts(t: &VarIn) -> [f64; 4] {
    let m = vnorm(t);
    let (s, c) = t.x.sin_cos();
    let (sh, ch) = (m.sinh(), m.cosh());
    [s * ch, c * ch, c * sh / m, -s * sh / m]
}

/// The hyperbolic parts of tanh q (and JWildfire's coth q): sinh x·cos m, cosh x·cos m,
/// cosh x·sin m/m, sinh x·sin m/m.
fn hyperbolic_parts(t: &VarIn) -> [f64; 4] {
    let m = vnorm(t);
    let (s, c) = m.sin_cos();
    let (sh, ch) = (t.x.sinh(), t.x.cosh());
    [sh * c, ch * c, ch * s / m, sh * s / m]
}

/// tan q.
pub(super) fn tanq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    tan_like(v, t, circular_parts(t), 1.0)
}

/// cot q: tan q's quotient with the vector part negated.
pub(super) fn cotq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    tan_like(v, t, circular_parts(t), -1.0)
}

/// tanh q; JWildfire computes its `cothq` with this same formula.
pub(super) fn tanhq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    tan_like(v, t, hyperbolic_parts(t), 1.0)
}

/// log q in base b: ln|q|²·w/(2 ln b) + w·atan2(m, x)·v/m (reads the registry's derived
/// 1/(2 ln b)).
pub(super) fn loq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [half_inv_ln_base] = v.derived();
    let m = vnorm(t);
    let x = (t.x * t.x + m * m).ln() * half_inv_ln_base * v.w;
    along(x, v.w * m.atan2(t.x) / m, t)
}
