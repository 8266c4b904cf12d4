//! Coordinate systems the formulas convert to and from: bipolar, elliptic, the square rings
//! of the square-to-circle maps, and the quaternion quotient of the quaternion trigonometric
//! variations.

use crate::flame::fastmath as fm;
use std::f64::consts::PI;

use super::arith::{safe_sqrt, zeps};

/// Bipolar coordinates (τ, σ) of (x, y) with foci at (±1, 0): τ = ln(d₊/d₋) from the distances
/// d± to the foci, σ = the angle the foci subtend at the point (π minus the two base angles).
#[inline(always)]
pub fn bipolar(x: f64, y: f64) -> (f64, f64) {
    let y2 = y * y;
    let tau = 0.5 * (((x + 1.0) * (x + 1.0) + y2).ln() - ((x - 1.0) * (x - 1.0) + y2).ln());
    let sigma = PI - y.atan2(x + 1.0) - y.atan2(1.0 - x);
    (tau, sigma)
}

/// The point of bipolar coordinates (τ, σ), scaled by `w`:
/// w·(sinh τ, sin σ) / (cosh τ − cos σ), the denominator guarded against 0.
#[inline(always)]
pub fn from_bipolar(w: f64, tau: f64, sigma: f64) -> (f64, f64) {
    let den = zeps(fm::cosh(tau) - sigma.cos());
    (w * fm::sinh(tau) / den, w * sigma.sin() / den)
}

/// Elliptic coordinates of (x, y) with foci (±1, 0), from x and x² + y²: returns (ξ, ν) where
/// ξ = cosh μ is half the sum of the distances to the foci (raised to 1 if below, with
/// `floor_one`, as rounding can leave it just under) and ν = acos(x/ξ) ∈ [0, π] (callers
/// negate it below the x axis).
#[inline(always)]
pub fn elliptic(x: f64, sumsq: f64, floor_one: bool) -> (f64, f64) {
    let s = sumsq + 1.0;
    let d = 2.0 * x;
    let mut xmax = (safe_sqrt(s + d) + safe_sqrt(s - d)) * 0.5;
    if floor_one && xmax < 1.0 {
        xmax = 1.0;
    }
    let nu = (x / xmax).clamp(-1.0, 1.0).acos();
    (xmax, nu)
}

/// The point of elliptic coordinates (μ, ν), scaled by `w`: w·(cosh μ·cos ν, sinh μ·sin ν).
#[inline(always)]
pub fn from_elliptic(w: f64, mu: f64, nu: f64) -> [f64; 3] {
    let (s, c) = nu.sin_cos();
    [w * fm::cosh(mu) * c, w * fm::sinh(mu) * s, 0.0]
}

/// Where (x, y) lies on the boundary of its square ring: returns (s, p) with s = max(|x|, |y|)
/// the half-side and p ∈ [0, 8s) the arc length from (s, 0) counter-clockwise (a point on a
/// diagonal counts to the vertical side). The inverse of [`square_point`].
#[inline(always)]
pub fn square_arc(x: f64, y: f64) -> (f64, f64) {
    let (ax, ay) = (x.abs(), y.abs());
    if ax >= ay {
        let per = if x >= ay { ax + y } else { 5.0 * ax - y };
        (ax, per)
    } else {
        let per = if y >= ax { 3.0 * ay - x } else { 7.0 * ay + x };
        (ay, per)
    }
}

/// The point at arc length `p` along the boundary of the square of half-side `s` (starting at
/// (s, 0), counter-clockwise, 8s long), scaled by `w`. Without `close`, the last stretch
/// (below the x axis) is mirrored, as squish has it.
#[inline(always)]
pub fn square_point(w: f64, s: f64, p: f64, close: bool) -> [f64; 3] {
    if p <= s {
        [w * s, w * p, 0.0]
    } else if p <= 3.0 * s {
        [w * (2.0 * s - p), w * s, 0.0]
    } else if p <= 5.0 * s {
        [-(w * s), w * (4.0 * s - p), 0.0]
    } else if p <= 7.0 * s {
        [-(w * (6.0 * s - p)), -(w * s), 0.0]
    } else {
        let y = w * (8.0 * s - p);
        [w * s, if close { -y } else { y }, 0.0]
    }
}

/// k·P·conj(Q) for the quaternions P = p0 + p1·v and Q = q0 + q1·v that share the imaginary
/// direction v = (0, y, z) (so they commute): the quotient P/Q of the quaternion tan, tanh, cot
/// and coth variations, k being the weight over the norm they divide by. `p1` and `q1` are
/// per unit of |v|.
#[inline(always)]
pub fn quat_mul_conj(p0: f64, p1: f64, q0: f64, q1: f64, y: f64, z: f64, k: f64) -> [f64; 3] {
    let v2 = y * y + z * z;
    [
        (p0 * q0 + p1 * q1 * v2) * k,
        (-p0 * q1 * y + p1 * y * q0) * k,
        (-p0 * q1 * z + p1 * z * q0) * k,
    ]
}
