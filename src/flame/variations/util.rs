//! Helpers shared by the variation formulas.
//!
//! Most variations come from programs written in C++ (Fractorium, Apophysis plugins) or Java
//! (JWildfire), and a few of their numbers depend on what those languages do at the edges: how
//! a double becomes an integer on x86-64, how a bounded random draw treats a count of 0, which
//! argument `std::max` keeps when one is NaN. The helpers here reproduce those behaviours once,
//! each documented with the semantics it mimics, so that every formula that needs one uses the
//! same code.
//!
//! Sections: small arithmetic; C conversions as x86-64 performs them; random draws; hashes;
//! Java and GLSL idioms; coordinate systems; complex numbers; special functions.

use std::f64::consts::{FRAC_2_SQRT_PI, FRAC_PI_4, LN_2, PI, TAU};

use crate::flame::rng::FastRng;

// ---------------------------------------------------------------------------------------------
// Small arithmetic

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

/// C's `fmod` (the remainder has the sign of `a`): Rust's `%` on f64.
#[inline(always)]
pub fn fmod(a: f64, b: f64) -> f64 {
    a % b
}

/// Round half away from zero (C's `round`).
#[inline(always)]
pub fn round(x: f64) -> f64 {
    x.round()
}

/// (sin a, cos a).
#[inline(always)]
pub fn sincos(a: f64) -> (f64, f64) {
    a.sin_cos()
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

// ---------------------------------------------------------------------------------------------
// C conversions as x86-64 performs them
//
// C leaves the conversion of an out-of-range double to an integer undefined; x86-64's
// `cvttsd2si` answers with the "integer indefinite" value, the most negative integer, for NaN
// and for every value outside the target range. Fractorium's formulas convert freely (cell
// indices of huge coordinates, parities of NaN), so the helpers below return that value where
// Rust's saturating `as` would not.

/// 2⁶³, the first double above the i64 range.
const TWO_63: f64 = 9_223_372_036_854_775_808.0;

/// C's `(int)x` on x86-64: truncation toward zero; NaN and values outside the i32 range give
/// `i32::MIN`.
#[inline(always)]
pub fn trunc_i32(x: f64) -> i32 {
    if x > -2_147_483_649.0 && x < 2_147_483_648.0 {
        x as i32
    } else {
        i32::MIN
    }
}

/// C's `(int64_t)x` on x86-64: truncation toward zero; NaN and values outside the i64 range
/// give `i64::MIN`.
#[inline(always)]
pub fn trunc_i64(x: f64) -> i64 {
    if (-TWO_63..TWO_63).contains(&x) {
        x as i64
    } else {
        i64::MIN
    }
}

/// ⌊x⌋ as a 64-bit integer the way Fractorium's integer `Floor` computes it: truncate (as
/// [`trunc_i64`]), then step down by one for a negative non-integer. It equals ⌊x⌋ in the
/// i64 range; NaN and x ≥ 2⁶³ give `i64::MIN`, and x < −2⁶³ gives `i64::MAX` (the step down
/// wraps around from `i64::MIN`, as the C code's signed overflow does on x86-64).
#[inline(always)]
pub fn floor_i64(x: f64) -> i64 {
    let i = trunc_i64(x);
    if x >= 0.0 {
        i
    } else {
        i.wrapping_sub(((i as f64) > x) as i64)
    }
}

/// [`floor_i64`] as a double, computed in floating point: ⌊x⌋ in the i64 range, −2⁶³ for NaN
/// and x ≥ 2⁶³, 2⁶³ − 1 (as a double, 2⁶³) for x < −2⁶³.
#[inline(always)]
pub fn floor_f(x: f64) -> f64 {
    if (-TWO_63..TWO_63).contains(&x) {
        x.floor()
    } else if x < -TWO_63 {
        i64::MAX as f64
    } else {
        i64::MIN as f64
    }
}

/// Apophysis' `LRint` as Fractorium has it: round half away from zero by converting x ± ½ to a
/// 64-bit integer (x86-64 semantics of [`trunc_i64`]: NaN and huge values give −2⁶³).
#[inline(always)]
pub fn lrint(x: f64) -> f64 {
    let shifted = if x >= 0.0 { x + 0.5 } else { x - 0.5 };
    trunc_i64(shifted) as f64
}

// ---------------------------------------------------------------------------------------------
// Random draws

/// Fractorium's bounded draw `Rand(size_t(n))` for a count held in a double: a uniform integer
/// in 0..k (as a double), k being `n` converted to an unsigned integer (truncated; negative
/// and NaN counts give 0). A count of 0 draws a full 32-bit number instead, as Fractorium's
/// generator does for `Rand(0)` — so that, for example, a julian power below 1 picks an
/// arbitrary root.
#[inline(always)]
pub fn rand_size(rng: &mut FastRng, n: f64) -> f64 {
    let k = n as u64;
    if k == 0 {
        rng.u32() as f64
    } else {
        rng.below(k) as f64
    }
}

/// Fractorium's `Crand()`: an integer in 0..=32766 (the range of C's `rand()` on some
/// platforms, minus one), as a double.
#[inline(always)]
pub fn crand(rng: &mut FastRng) -> f64 {
    rng.below(32767) as f64
}

/// George Marsaglia's multiply-with-carry generator pair (two 16-bit lag-1 MWC generators
/// concatenated), seeded and scaled as JWildfire's `MarsagliaRandomGenerator`: the seed is
/// shifted left by 16 bits into a 32-bit state, and each number is |r| / (2³¹ − 1) for the
/// signed 32-bit combination r. All arithmetic wraps as Java's `int` does. Variations that
/// build a structure from a seed (snow crystals, aggregates) use it so that a seed gives
/// JWildfire's shape.
#[derive(Clone, Debug)]
pub struct Mwc {
    u: i32,
    v: i32,
}

impl Mwc {
    pub fn new(seed: i64) -> Mwc {
        let s = seed.wrapping_shl(16) as i32;
        Mwc { u: s, v: s >> 16 }
    }

    /// The next number, in [0, 1].
    pub fn next_f64(&mut self) -> f64 {
        self.v = 36969i32
            .wrapping_mul(self.v & 65535)
            .wrapping_add(self.v >> 16);
        self.u = 18000i32
            .wrapping_mul(self.u & 65535)
            .wrapping_add(self.u >> 16);
        let bits = (self.v << 16).wrapping_add(self.u);
        (bits as f64 * (1.0 / 2147483647.0)).abs()
    }
}

// ---------------------------------------------------------------------------------------------
// Hashes

/// The "shadertoy" hash: fract(sin(12.9898·x + 78.233·y + seed) · 43758.5453), a cheap
/// deterministic pseudo-random value in [0, 1) for a lattice point (x, y), popularised by
/// GPU shader code and used by Chaotica-style variations for random cells. NaN inputs give
/// NaN.
#[inline(always)]
pub fn sine_hash(x: f64, y: f64, seed: f64) -> f64 {
    fract((x * 12.9898 + y * 78.233 + seed).sin() * 43758.5453)
}

/// Thomas Wang's 32-bit integer hash (the `(a ^ 61) ^ (a >> 16)`, `a * 0x27d4eb2d` variant),
/// with C's wrapping 32-bit arithmetic and arithmetic right shifts, divided by `i32::MAX`: a
/// pseudo-random value in about [−1, 1] for an integer seed.
#[inline(always)]
pub fn wang_hash(seed: i32) -> f64 {
    let mut h = (seed ^ 61) ^ (seed >> 16);
    h = h.wrapping_add(h.wrapping_shl(3));
    h ^= h >> 4;
    h = h.wrapping_mul(0x27d4_eb2d);
    h ^= h >> 15;
    h as f64 / i32::MAX as f64
}

/// The classic integer lattice noise of Hugo Elias's "Perlin noise" tutorial: n ^= n << 13,
/// then the polynomial n·(n²·15731 + 789221) + 1376312589, in wrapping 32-bit arithmetic,
/// masked to 31 bits and scaled into [0, 1]. Two-dimensional lattices hash `x + 57·y`.
#[inline(always)]
pub fn lattice_noise(n: i32) -> f64 {
    let n = n ^ n.wrapping_shl(13);
    let h = n
        .wrapping_mul(n.wrapping_mul(n).wrapping_mul(15731).wrapping_add(789221))
        .wrapping_add(1376312589);
    (h & 0x7fff_ffff) as f64 * (1.0 / 2147483647.0)
}

/// [`lattice_noise`] of the 2-D lattice point (x, y), hashed as x + 57·y (wrapping).
#[inline(always)]
pub fn lattice_noise_2d(x: i32, y: i32) -> f64 {
    lattice_noise(x.wrapping_add(y.wrapping_mul(57)))
}

// ---------------------------------------------------------------------------------------------
// Java and GLSL idioms

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

// ---------------------------------------------------------------------------------------------
// Coordinate systems

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
    let den = zeps(tau.cosh() - sigma.cos());
    (w * tau.sinh() / den, w * sigma.sin() / den)
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
    [w * mu.cosh() * c, w * mu.sinh() * s, 0.0]
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

// ---------------------------------------------------------------------------------------------
// Complex numbers with C99 semantics (signed zeros, branch cuts, division by zero and
// infinities as C's <complex.h> handles them, Annex G), as the inverse hyperbolic variations
// need them.

/// A complex number.
#[derive(Clone, Copy, Debug)]
pub struct Cplx {
    pub re: f64,
    pub im: f64,
}

impl Cplx {
    #[inline(always)]
    pub const fn new(re: f64, im: f64) -> Cplx {
        Cplx { re, im }
    }

    /// Adds a real number (the imaginary part, even a signed zero, is kept).
    #[inline(always)]
    pub fn add_re(self, r: f64) -> Cplx {
        Cplx::new(self.re + r, self.im)
    }

    #[inline(always)]
    pub fn scale(self, k: f64) -> Cplx {
        Cplx::new(self.re * k, self.im * k)
    }

    /// 1 / self.
    #[inline(always)]
    pub fn recip(self) -> Cplx {
        Cplx::new(1.0, 0.0) / self
    }

    /// Principal square root (cut along the negative reals, side chosen by the sign of im).
    #[inline]
    pub fn sqrt(self) -> Cplx {
        let (x, y) = (self.re, self.im);
        if !x.is_finite() || !y.is_finite() {
            if y.is_infinite() {
                return Cplx::new(f64::INFINITY, y);
            }
            if x == f64::NEG_INFINITY {
                let re = if y.is_nan() { f64::NAN } else { 0.0 };
                return Cplx::new(re, f64::INFINITY.copysign(y));
            }
            if x == f64::INFINITY {
                let im = if y.is_nan() {
                    f64::NAN
                } else {
                    0.0_f64.copysign(y)
                };
                return Cplx::new(x, im);
            }
            return Cplx::new(f64::NAN, f64::NAN);
        }
        if y == 0.0 {
            return if x < 0.0 {
                Cplx::new(0.0, (-x).sqrt().copysign(y))
            } else {
                Cplx::new(x.sqrt().abs(), 0.0_f64.copysign(y))
            };
        }
        if x == 0.0 {
            let r = (0.5 * y.abs()).sqrt();
            return Cplx::new(r, r.copysign(y));
        }
        let h = x.hypot(y);
        let (re, im) = if x > 0.0 {
            let r = (0.5 * (h + x)).sqrt();
            (r, 0.5 * (y / r))
        } else {
            let s = (0.5 * (h - x)).sqrt();
            ((0.5 * (y / s)).abs(), s)
        };
        Cplx::new(re, im.copysign(y))
    }

    /// Principal logarithm: ln|z| + i·arg z.
    #[inline]
    pub fn ln(self) -> Cplx {
        let (x, y) = (self.re, self.im);
        if x.is_nan() || y.is_nan() {
            let re = if x.is_infinite() || y.is_infinite() {
                f64::INFINITY
            } else {
                f64::NAN
            };
            return Cplx::new(re, f64::NAN);
        }
        if x == 0.0 && y == 0.0 {
            let im = if x.is_sign_negative() {
                PI.copysign(y)
            } else {
                0.0_f64.copysign(y)
            };
            return Cplx::new(f64::NEG_INFINITY, im);
        }
        let (big, small) = if x.abs() >= y.abs() {
            (x.abs(), y.abs())
        } else {
            (y.abs(), x.abs())
        };
        // Near the unit circle ln|z| is small: compute |z|² − 1 without cancellation.
        let re = if (0.5..2.0).contains(&big) && small < 1.0 {
            let m1 = small.mul_add(small, big.mul_add(big, -1.0));
            0.5 * m1.ln_1p()
        } else {
            big.hypot(small).ln()
        };
        Cplx::new(re, y.atan2(x))
    }
}

impl std::ops::Add for Cplx {
    type Output = Cplx;
    #[inline(always)]
    fn add(self, o: Cplx) -> Cplx {
        Cplx::new(self.re + o.re, self.im + o.im)
    }
}

impl std::ops::Neg for Cplx {
    type Output = Cplx;
    #[inline(always)]
    fn neg(self) -> Cplx {
        Cplx::new(-self.re, -self.im)
    }
}

/// Product, with C's recovery of infinities from NaN results.
impl std::ops::Mul for Cplx {
    type Output = Cplx;
    #[inline]
    fn mul(self, o: Cplx) -> Cplx {
        let (a, b, c, d) = (self.re, self.im, o.re, o.im);
        let (ac, bd, ad, bc) = (a * c, b * d, a * d, b * c);
        let (x, y) = (ac - bd, ad + bc);
        if x.is_nan() && y.is_nan() {
            return mul_recover(a, b, c, d, ac, bd, ad, bc);
        }
        Cplx::new(x, y)
    }
}

/// Quotient by Smith's method, with C's handling of zero and infinite operands.
impl std::ops::Div for Cplx {
    type Output = Cplx;
    #[inline]
    fn div(self, o: Cplx) -> Cplx {
        let (a, b, c, d) = (self.re, self.im, o.re, o.im);
        let (x, y) = if c.abs() < d.abs() {
            let q = c / d;
            let den = c * q + d;
            ((a * q + b) / den, (b * q - a) / den)
        } else {
            let q = d / c;
            let den = d * q + c;
            ((b * q + a) / den, (b - a * q) / den)
        };
        if x.is_nan() && y.is_nan() {
            if c == 0.0 && d == 0.0 && (!a.is_nan() || !b.is_nan()) {
                let inf = f64::INFINITY.copysign(c);
                return Cplx::new(inf * a, inf * b);
            }
            if (a.is_infinite() || b.is_infinite()) && c.is_finite() && d.is_finite() {
                let a1 = inf_unit(a);
                let b1 = inf_unit(b);
                return Cplx::new(
                    f64::INFINITY * (a1 * c + b1 * d),
                    f64::INFINITY * (b1 * c - a1 * d),
                );
            }
            if (c.is_infinite() || d.is_infinite()) && a.is_finite() && b.is_finite() {
                let c1 = inf_unit(c);
                let d1 = inf_unit(d);
                return Cplx::new(0.0 * (a * c1 + b * d1), 0.0 * (b * c1 - a * d1));
            }
        }
        Cplx::new(x, y)
    }
}

/// ±1 for an infinite value, ±0 otherwise (the sign of `v` kept).
#[inline(always)]
fn inf_unit(v: f64) -> f64 {
    let m: f64 = if v.is_infinite() { 1.0 } else { 0.0 };
    m.copysign(v)
}

/// The infinite cases of a complex product whose direct formula gave NaN + i·NaN.
#[allow(clippy::too_many_arguments)]
#[cold]
fn mul_recover(
    mut a: f64,
    mut b: f64,
    mut c: f64,
    mut d: f64,
    ac: f64,
    bd: f64,
    ad: f64,
    bc: f64,
) -> Cplx {
    let nan_to_zero = |v: f64| if v.is_nan() { 0.0_f64.copysign(v) } else { v };
    let mut again = false;
    if a.is_infinite() || b.is_infinite() {
        a = inf_unit(a);
        b = inf_unit(b);
        c = nan_to_zero(c);
        d = nan_to_zero(d);
        again = true;
    }
    if c.is_infinite() || d.is_infinite() {
        c = inf_unit(c);
        d = inf_unit(d);
        a = nan_to_zero(a);
        b = nan_to_zero(b);
        again = true;
    }
    if !again && (ac.is_infinite() || bd.is_infinite() || ad.is_infinite() || bc.is_infinite()) {
        a = nan_to_zero(a);
        b = nan_to_zero(b);
        c = nan_to_zero(c);
        d = nan_to_zero(d);
        again = true;
    }
    if again {
        Cplx::new(
            f64::INFINITY * (a * c - b * d),
            f64::INFINITY * (a * d + b * c),
        )
    } else {
        Cplx::new(ac - bd, ad + bc)
    }
}

// ---------------------------------------------------------------------------------------------
// Quaternions (x, y, z, 0) whose imaginary parts point the same way

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

// ---------------------------------------------------------------------------------------------
// Special functions

/// The error function erf(x), to about 1e-15 relative (10 ulp at worst, near |x| = 2.5).
/// Below 2.5 the series erf a = 2/√π·e^(−a²)·Σ 2ⁿa^(2n+1) / (1·3·…·(2n+1)) (Abramowitz &
/// Stegun 7.1.6), whose terms are all positive, so nothing cancels; up to 6.5 the complementary
/// function by its continued fraction (A&S 7.1.14) evaluated bottom-up; beyond, 1 to double
/// precision. Odd by construction: erf(−x) = −erf(x) exactly.
#[inline]
pub fn erf(x: f64) -> f64 {
    if x.is_nan() {
        return x;
    }
    let a = x.abs();
    let r = if a < 2.5 {
        let a2 = a * a;
        let mut term = a;
        let mut sum = a;
        let mut k = 1.0;
        loop {
            k += 2.0;
            term *= 2.0 * a2 / k;
            sum += term;
            if term <= sum * 1e-17 {
                break;
            }
        }
        FRAC_2_SQRT_PI * (-a2).exp() * sum
    } else if a < 6.5 {
        // erfc(a) = e^(−a²)/√π · 1/(a + ½/(a + 1/(a + (3/2)/(a + …)))).
        let mut f = a;
        for n in (1..=60).rev() {
            f = a + (n as f64 * 0.5) / f;
        }
        1.0 - (-a * a).exp() * (FRAC_2_SQRT_PI * 0.5) / f
    } else {
        1.0
    };
    r.copysign(x)
}

/// ln Γ(x) for x ≥ 0 by the Lanczos approximation (g = 7, nine coefficients; Press et al.,
/// "Numerical Recipes", §6.1): about 1e-15 relative, and exactly 0 at the zeros 1 and 2; +∞
/// at 0 and for +∞, NaN for NaN. Negative arguments give +∞ (the variations that use it pass
/// a radius).
#[inline]
pub fn ln_gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x.is_nan() {
        return x;
    }
    if x <= 0.0 || x == f64::INFINITY {
        return f64::INFINITY;
    }
    if x < 0.5 {
        // Γ(x) = Γ(x + 1) / x.
        return ln_gamma(x + 1.0) - x.ln();
    }
    if x == 1.0 || x == 2.0 {
        return 0.0;
    }
    let z = x - 1.0;
    let mut series = C[0];
    for (k, c) in C.iter().enumerate().skip(1) {
        series += c / (z + k as f64);
    }
    let t = z + G + 0.5;
    0.5 * TAU.ln() + (z + 0.5) * t.ln() - t + series.ln()
}

/// Bessel function of the first kind of order 1, J₁(x): its power series
/// Σ (−1)ᵏ (x/2)^(2k+1) / (k!(k+1)!) up to |x| = 12, Hankel's asymptotic expansion
/// √(2/(πx))·(P cos χ − Q sin χ), χ = x − 3π/4, beyond (summed until its terms stop
/// shrinking; Abramowitz & Stegun 9.2.5).
#[inline]
pub fn bessel_j1(x: f64) -> f64 {
    let ax = x.abs();
    if ax < 12.0 {
        let h = 0.5 * x;
        let q = -h * h;
        let mut term = h;
        let mut sum = h;
        let mut k = 0.0;
        loop {
            k += 1.0;
            term *= q / (k * (k + 1.0));
            sum += term;
            if term.abs() <= 1e-17 * sum.abs().max(1e-300) {
                break;
            }
        }
        return sum;
    }
    // μ = 4ν² = 4 for ν = 1.
    let mu = 4.0;
    let z8 = 8.0 * ax;
    let mut p = 1.0;
    let mut q = 0.0;
    let mut term = 1.0;
    let mut k = 1.0;
    let mut best = f64::INFINITY;
    loop {
        let odd = 2.0 * k - 1.0;
        term *= (mu - odd * odd) / (k * z8);
        if term.abs() >= best {
            break;
        }
        best = term.abs();
        if (k as i32) % 2 == 1 {
            q += if (k as i32 / 2) % 2 == 0 { term } else { -term };
        } else {
            p += if (k as i32 / 2) % 2 == 1 { -term } else { term };
        }
        if best < 1e-17 || k > 60.0 {
            break;
        }
        k += 1.0;
    }
    let chi = ax - 0.75 * PI;
    let v = (2.0 / (PI * ax)).sqrt() * (p * chi.cos() - q * chi.sin());
    if x < 0.0 { -v } else { v }
}

/// Jacobi's elliptic functions (sn, cn, dn) of `u` for the complementary parameter `mc`
/// (= 1 − m), by the descending Landen / arithmetic–geometric-mean scheme (Bulirsch's
/// algorithm, as in "Numerical Recipes" §6.11) with Fractorium's coarse tolerance: the AGM
/// stops once two means agree to 3·10⁻⁴ relative, after at most 8 steps, which the
/// variations' shapes depend on. mc = 0 is the hyperbolic limit (tanh u, sech u, sech u); a
/// negative mc is handled by the reciprocal-modulus transformation.
#[inline(always)]
pub fn jacobi_elliptic(u: f64, mc: f64) -> (f64, f64, f64) {
    if mc == 0.0 {
        let sech = 1.0 / u.cosh();
        return (u.tanh(), sech, sech);
    }
    const TOL: f64 = 0.0003;
    let negative = mc < 0.0;
    let mut m = mc;
    let mut arg = u;
    let mut scale = 1.0;
    if negative {
        scale = 1.0 - m;
        m = -m / scale;
        scale = scale.sqrt();
        arg *= scale;
    }
    let mut arith = [0.0f64; 8];
    let mut geom = [0.0f64; 8];
    let mut a = 1.0;
    let mut mean = 0.0;
    let mut steps = 0;
    for k in 0..8 {
        steps = k;
        arith[k] = a;
        m = m.sqrt();
        geom[k] = m;
        mean = 0.5 * (a + m);
        if (a - m).abs() <= TOL * a {
            break;
        }
        m *= a;
        a = mean;
    }
    arg *= mean;
    let (mut sn, mut cn) = (arg.sin(), arg.cos());
    let mut dn = 1.0;
    if sn != 0.0 {
        let mut ratio = cn / sn;
        let mut c = mean * ratio;
        for k in (0..=steps).rev() {
            let b = arith[k];
            ratio *= c;
            c *= dn;
            dn = (geom[k] + ratio) / (b + ratio);
            ratio = c / b;
        }
        let s = 1.0 / (c * c + 1.0).sqrt();
        sn = if sn < 0.0 { -s } else { s };
        cn = c * sn;
    }
    if negative {
        (sn / scale, dn, cn)
    } else {
        (sn, cn, dn)
    }
}

/// sn(u | 1 − mc) alone: [`jacobi_elliptic`]'s first value, without computing the others.
#[inline]
pub fn jacobi_sn(u: f64, mc: f64) -> f64 {
    jacobi_elliptic(u, mc).0
}

/// acosh(x), accurate near 1 where the textbook ln(x + √(x² − 1)) (and std's `acosh`) lose
/// digits: ln1p(t + √(2t + t²)) with t = x − 1 up to 2, ln(2x − 1/(x + √(x² − 1))) above, and
/// ln x + ln 2 from 2²⁸ on (where x + √(x² − 1) = 2x in double precision). NaN below 1.
#[inline]
pub fn acosh(x: f64) -> f64 {
    if x < 1.0 {
        f64::NAN
    } else if x >= 268435456.0 {
        if x.is_finite() { x.ln() + LN_2 } else { x }
    } else if x > 2.0 {
        (2.0 * x - 1.0 / (x + (x * x - 1.0).sqrt())).ln()
    } else {
        let t = x - 1.0;
        (t + (2.0 * t + t * t).sqrt()).ln_1p()
    }
}
