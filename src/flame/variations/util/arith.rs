//! Small arithmetic the formulas share, in the forms the source programs use: pole guards,
//! signs, C's `fmod` and `round`, signed powers, C++'s `std::max`/`std::min` (NaN handling),
//! the "safe" square root, and the Java and GLSL idioms (`Math.signum`, a fast atan2).

use std::f64::consts::FRAC_PI_4;

/// `x`, or `f64::EPSILON` when it is exactly 0 (Fractorium's pole guard).
#[inline(always)]
pub fn zeps(x: f64) -> f64 {
    if x == 0.0 { f64::EPSILON } else { x }
}

/// -1 for negative values, else 1.
#[inline(always)]
pub fn sign_nz(x: f64) -> f64 {
    if x < 0.0 { -1.0 } else { 1.0 }
}

/// -1, 0 or 1.
#[inline(always)]
pub fn sign(x: f64) -> f64 {
    if x < 0.0 {
        -1.0
    } else if x > 0.0 {
        1.0
    } else {
        0.0
    }
}

/// Fractorium's rounding: half away from zero, computed as floor(x + ½) for positive values
/// and ceil(x − ½) otherwise (differs from `f64::round` just below the halves).
#[inline(always)]
pub fn round_half_out(x: f64) -> f64 {
    if x > 0.0 {
        (x + 0.5).floor()
    } else {
        (x - 0.5).ceil()
    }
}

/// x².
#[inline(always)]
pub fn sqr(x: f64) -> f64 {
    x * x
}

/// Fractional part x − ⌊x⌋, in [0, 1) (GLSL's `fract`). NaN and ±∞ give NaN.
#[inline(always)]
pub fn fract(x: f64) -> f64 {
    x - x.floor()
}

/// GLSL's `smoothstep(e0, e1, x)`: 0 before e0, 1 after e1, the cubic 3t² − 2t³ between (the
/// edges in either order, as shader code passes them).
#[inline(always)]
pub fn smoothstep(e0: f64, e1: f64, x: f64) -> f64 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Linear interpolation from `a` (at t = 0) to `b` (at t = 1): a + (b − a)·t (GLSL's `mix`).
#[inline(always)]
pub fn mix(a: f64, b: f64, t: f64) -> f64 {
    a + (b - a) * t
}

/// sign(x)·|x|^e, the sign of 0 taken as + (so −0 gives +0): a power that keeps the sign of
/// its base, as Fractorium writes `SignNz(x) * pow(fabs(x), e)`.
#[inline(always)]
pub fn signed_pow(x: f64, e: f64) -> f64 {
    sign_nz(x) * x.abs().powf(e)
}

/// [`signed_pow`], but x itself when e = 1 (so that −0 stays −0): the variant of the
/// sign-keeping power that returns its base unchanged for the exponent 1.
#[inline(always)]
pub fn signed_pow_or_id(x: f64, e: f64) -> f64 {
    if e == 1.0 {
        x
    } else {
        x.abs().powf(e) * sign_nz(x)
    }
}

/// C++'s `std::max(a, b)`: `b` only when `a < b`, so a NaN in `a` is kept and a NaN in `b` is
/// ignored (unlike `f64::max`, which ignores either). GLSL helper code written in Java has the
/// same rule.
#[inline(always)]
pub fn cpp_max(a: f64, b: f64) -> f64 {
    if a < b { b } else { a }
}

/// C++'s `std::min(a, b)`: `b` only when `b < a` (a NaN in `a` is kept).
#[inline(always)]
pub fn cpp_min(a: f64, b: f64) -> f64 {
    if b < a { b } else { a }
}

/// √x, or 0 for x ≤ 0: the "safe" square root of Fractorium's formulas, for radicands that
/// are mathematically non-negative but can come out slightly negative after rounding. NaN
/// stays NaN.
#[inline(always)]
pub fn safe_sqrt(x: f64) -> f64 {
    if x <= 0.0 { 0.0 } else { x.sqrt() }
}

/// Java's `Math.signum`: −1, 1, or x itself for ±0 and NaN.
#[inline(always)]
pub fn signum_java(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        x
    }
}

/// The fast atan2 of JWildfire's GLSL helpers: a first-order approximation of the angle of
/// (x, y), exact at multiples of π/4 and off by up to about 0.07 rad between them.
#[inline(always)]
pub fn atan2_approx(y: f64, x: f64) -> f64 {
    let ay = y.abs();
    let a = if x >= 0.0 {
        FRAC_PI_4 - FRAC_PI_4 * ((x - ay) / (x + ay))
    } else {
        3.0 * FRAC_PI_4 - FRAC_PI_4 * ((x + ay) / (ay - x))
    };
    if y < 0.0 { -a } else { a }
}
