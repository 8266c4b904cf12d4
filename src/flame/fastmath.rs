//! Fast sin, cos, tan, atan and atan2 for the chaos game, ln, exp and pow for the variations
//! and tone mapping, and sinh, cosh and tanh.
//!
//! glibc's versions save and restore the floating-point control register on every call, which
//! dominated the iteration time. These use the classic fdlibm minimax polynomials (public
//! coefficients, errors around 1 ulp) with a two-constant Cody–Waite reduction by π/2 (or ln 2),
//! and are written without branches so that loops over arrays of points (or pixels) vectorise.

#![allow(clippy::excessive_precision)] // the published fdlibm coefficients, kept verbatim

use std::f64::consts::{FRAC_2_PI, FRAC_PI_2, FRAC_PI_4, PI};

/// Whether this CPU has AVX2 and FMA, for the loops compiled twice (baseline and AVX2+FMA)
/// and chosen at run time. (The standard library caches the detection: this is one load.)
#[inline]
pub fn has_avx2_fma() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// The vector instruction sets the batch loops are compiled for, narrowest first: the
/// baseline CPU (2 lanes of f64), AVX2 with FMA (4 lanes), AVX-512F (8 lanes). Every copy of a
/// loop gives the same bits (Rust never fuses a multiply and an add on its own).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Simd {
    /// The baseline x86-64 (SSE2) or other CPU.
    Baseline,
    /// AVX2 with fused multiply-add.
    Avx2Fma,
    /// AVX-512 Foundation.
    Avx512,
}

thread_local! {
    /// The widest set this thread's batch loops may use (see [`limit_simd`]).
    static SIMD_LIMIT: std::cell::Cell<Simd> = const { std::cell::Cell::new(Simd::Avx512) };
}

/// Limit the batch loops of the calling thread to `s` and narrower (benches compare the
/// copies, tests check that they agree); the default is no limit.
pub fn limit_simd(s: Simd) {
    SIMD_LIMIT.with(|l| l.set(s));
}

/// The widest instruction set this CPU has among [`Simd`]'s, within the calling thread's
/// [`limit_simd`]: which copy of a batch loop runs. (A thread-local load and the standard
/// library's cached detection: a few loads per batch of points.)
#[inline]
pub fn simd() -> Simd {
    let cpu = if !has_avx2_fma() {
        Simd::Baseline
    } else if has_avx512f() {
        Simd::Avx512
    } else {
        Simd::Avx2Fma
    };
    cpu.min(SIMD_LIMIT.with(|l| l.get()))
}

#[inline]
fn has_avx512f() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::is_x86_feature_detected!("avx512f")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

const S1: f64 = -1.666_666_666_666_663_243_48e-01;
const S2: f64 = 8.333_333_333_322_489_461_24e-03;
const S3: f64 = -1.984_126_982_985_794_931_34e-04;
const S4: f64 = 2.755_731_370_707_006_767_89e-06;
const S5: f64 = -2.505_076_025_340_686_341_95e-08;
const S6: f64 = 1.589_690_995_211_550_102_21e-10;

const C1: f64 = 4.166_666_666_666_660_190_37e-02;
const C2: f64 = -1.388_888_888_887_410_957_49e-03;
const C3: f64 = 2.480_158_728_947_672_941_78e-05;
const C4: f64 = -2.755_731_435_139_066_330_35e-07;
const C5: f64 = 2.087_572_321_298_174_827_90e-09;
const C6: f64 = -1.135_964_755_778_819_482_65e-11;

/// π/2 split: the first 33 bits, and the rest.
const PIO2_1: f64 = 1.570_796_326_734_125_614_17e+00;
const PIO2_1T: f64 = 6.077_100_506_506_192_249_32e-11;
const INV_PIO2: f64 = FRAC_2_PI;

#[inline(always)]
fn kernel_sin(x: f64) -> f64 {
    let z = x * x;
    let v = z * x;
    let r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    x + v * (S1 + z * r)
}

#[inline(always)]
fn kernel_cos(x: f64) -> f64 {
    let z = x * x;
    let r = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    w + (((1.0 - w) - hz) + z * r)
}

/// 1.5·2⁵²: adding it rounds a double of magnitude < 2⁵¹ to an integer (ties to even) whose low
/// bits can be read from the mantissa.
const MAGIC: f64 = 6_755_399_441_055_744.0;

/// (sin x, cos x), branch-free (so loops over arrays vectorise). Accurate to about 1 ulp for
/// |x| < 2²⁰; beyond, the two-part reduction loses about |x|·10⁻¹⁶ of absolute accuracy, which
/// is irrelevant for the chaos game; beyond 2⁵¹ the result is unspecified. Non-finite input
/// gives NaN.
#[inline(always)]
pub fn sin_cos(x: f64) -> (f64, f64) {
    let (r, q) = reduce_small(x);
    sin_cos_reduced(r, q)
}

/// x − k·π/2 (two constants) and the bits of k + [`MAGIC`] (k's low bits), k = round(x·2/π).
#[inline(always)]
fn reduce_small(x: f64) -> (f64, u64) {
    let t = x * INV_PIO2 + MAGIC;
    let k = t - MAGIC;
    ((x - k * PIO2_1) - k * PIO2_1T, t.to_bits())
}

/// (sin x, cos x) from x reduced by π/2: the residue r (|r| ≤ π/4) and the quadrant in the low
/// two bits of q.
#[inline(always)]
fn sin_cos_reduced(r: f64, q: u64) -> (f64, f64) {
    let s = kernel_sin(r);
    let c = kernel_cos(r);
    let swap = q & 1 != 0;
    let (s1, c1) = if swap { (c, s) } else { (s, c) };
    // sin is negative in quadrants 2 and 3, cos in quadrants 1 and 2.
    let sin_sign = (q & 2) << 62;
    let cos_sign = (q.wrapping_add(1) & 2) << 62;
    (
        f64::from_bits(s1.to_bits() ^ sin_sign),
        f64::from_bits(c1.to_bits() ^ cos_sign),
    )
}

/// (sin x, cos x) for any x, branch-free (so loops over arrays vectorise): [`sin_cos`], bit for
/// bit, where that is accurate (|x| < 2²⁰, the arguments of nearly every formula); beyond, the
/// argument reduced exactly by Payne and Hanek's method (within 3 ulp of the standard
/// library's, measured over every exponent). Both reductions are computed and one is chosen,
/// so a loop pays for the long one (about 40 operations) on every point, and runs 4 or 8
/// points at a time instead of one. Non-finite input gives NaN.
#[inline(always)]
pub fn sin_cos_any(x: f64) -> (f64, f64) {
    let (rs, qs) = reduce_small(x);
    let (rh, qh) = huge::reduce(x);
    let a = x.abs();
    let big = (1_048_576.0..f64::INFINITY).contains(&a);
    let (r, q) = if big { (rh, qh) } else { (rs, qs) };
    sin_cos_reduced(r, q)
}

/// (sin x, cos x) for any x, for a formula whose loop stays scalar (one that draws random
/// numbers point by point): [`sin_cos`] for |x| < 2²⁰, the standard library beyond. A branch
/// that is practically never taken costs such a loop less than [`sin_cos_any`]'s long
/// reduction, which that function computes on every call so that loops vectorise.
#[inline(always)]
pub fn sin_cos_scalar(x: f64) -> (f64, f64) {
    if x.abs() < 1_048_576.0 {
        sin_cos(x)
    } else {
        x.sin_cos()
    }
}

/// This module's functions for any argument as methods, for formulas written with the standard
/// library's method syntax (`a.fsin_cos()` for `a.sin_cos()`, `a.fln()` for `a.ln()`): the
/// same special values as the standard library's, a few ulp apart elsewhere, and no calls, so
/// a loop over a batch of points vectorises where the formula allows.
#[allow(dead_code)] // the full set; formulas take them up one by one
pub trait FastTrig {
    /// [`sin_cos_any`].
    fn fsin_cos(self) -> (f64, f64);
    /// sin through [`sin_cos_any`].
    fn fsin(self) -> f64;
    /// cos through [`sin_cos_any`].
    fn fcos(self) -> f64;
    /// tan as sin / cos of [`sin_cos_any`].
    fn ftan(self) -> f64;
    /// [`ln`].
    fn fln(self) -> f64;
    /// [`exp_any`].
    fn fexp(self) -> f64;
    /// [`pow`].
    fn fpowf(self, y: f64) -> f64;
    /// [`atan2_any`] (self is y).
    fn fatan2(self, x: f64) -> f64;
    /// [`atan`].
    fn fatan(self) -> f64;
    /// [`asin`].
    fn fasin(self) -> f64;
    /// [`acos`].
    fn facos(self) -> f64;
}

impl FastTrig for f64 {
    #[inline(always)]
    fn fsin_cos(self) -> (f64, f64) {
        sin_cos_any(self)
    }
    #[inline(always)]
    fn fsin(self) -> f64 {
        sin_cos_any(self).0
    }
    #[inline(always)]
    fn fcos(self) -> f64 {
        sin_cos_any(self).1
    }
    #[inline(always)]
    fn ftan(self) -> f64 {
        let (s, c) = sin_cos_any(self);
        s / c
    }
    #[inline(always)]
    fn fln(self) -> f64 {
        ln(self)
    }
    #[inline(always)]
    fn fexp(self) -> f64 {
        exp_any(self)
    }
    #[inline(always)]
    fn fpowf(self, y: f64) -> f64 {
        pow(self, y)
    }
    #[inline(always)]
    fn fatan2(self, x: f64) -> f64 {
        atan2_any(self, x)
    }
    #[inline(always)]
    fn fatan(self) -> f64 {
        atan(self)
    }
    #[inline(always)]
    fn fasin(self) -> f64 {
        asin(self)
    }
    #[inline(always)]
    fn facos(self) -> f64 {
        acos(self)
    }
}

#[inline(always)]
pub fn sin(x: f64) -> f64 {
    sin_cos(x).0
}

#[inline(always)]
pub fn cos(x: f64) -> f64 {
    sin_cos(x).1
}

/// tan x as sin x / cos x of [`sin_cos`], branch-free (so loops over arrays vectorise): a few
/// ulps for |x| < 2²⁰ away from the poles; near a pole the relative error grows as the reduced
/// argument's absolute error (about |x|·10⁻²⁶) over its distance to the pole. Non-finite input
/// gives NaN.
#[inline(always)]
pub fn tan(x: f64) -> f64 {
    let (s, c) = sin_cos(x);
    s / c
}

const ATANHI: [f64; 4] = [
    4.636_476_090_008_060_935_15e-01,
    FRAC_PI_4,
    9.827_937_232_473_290_540_82e-01,
    FRAC_PI_2,
];
const ATANLO: [f64; 4] = [
    2.269_877_745_296_168_709_24e-17,
    3.061_616_997_868_383_017_93e-17,
    1.390_331_103_123_099_845_16e-17,
    6.123_233_995_736_766_035_87e-17,
];
const AT: [f64; 11] = [
    3.333_333_333_333_293_180_27e-01,
    -1.999_999_999_987_648_324_76e-01,
    1.428_571_427_250_346_637_11e-01,
    -1.111_111_040_546_235_578_80e-01,
    9.090_887_133_436_506_561_96e-02,
    -7.691_876_205_044_829_994_95e-02,
    6.661_073_137_387_531_206_69e-02,
    -5.833_570_133_790_573_486_45e-02,
    4.976_877_994_615_932_360_17e-02,
    -3.653_157_274_421_691_552_70e-02,
    1.628_582_011_536_578_236_23e-02,
];

/// atan(x) for finite or infinite x, branch-free (fdlibm's intervals chosen by selects).
#[inline(always)]
pub fn atan(x: f64) -> f64 {
    let sign = x.to_bits() & (1 << 63);
    let a = x.abs();
    // Interval: t' = (a − b)/(1 + b·a) around atan(b), or −1/a for large a.
    let (b, hi, lo) = if a < 0.4375 {
        (0.0, 0.0, 0.0)
    } else if a < 0.6875 {
        (0.5, ATANHI[0], ATANLO[0])
    } else if a < 1.1875 {
        (1.0, ATANHI[1], ATANLO[1])
    } else if a < 2.4375 {
        (1.5, ATANHI[2], ATANLO[2])
    } else {
        (0.0, ATANHI[3], ATANLO[3])
    };
    let big = a >= 2.4375;
    let num = if big { -1.0 } else { a - b };
    let den = if big { a } else { 1.0 + b * a };
    let t = num / den;
    let z = t * t;
    let w = z * z;
    let s1 = z * (AT[0] + w * (AT[2] + w * (AT[4] + w * (AT[6] + w * (AT[8] + w * AT[10])))));
    let s2 = w * (AT[1] + w * (AT[3] + w * (AT[5] + w * (AT[7] + w * AT[9]))));
    let r = hi - ((t * (s1 + s2) - lo) - t);
    f64::from_bits(r.to_bits() ^ sign)
}

/// atan2(y, x) with the standard quadrant and signed-zero conventions, branch-free.
#[inline(always)]
pub fn atan2(y: f64, x: f64) -> f64 {
    let ysign = y.to_bits() & (1 << 63);
    let a = atan(y / x);
    let pi_y = f64::from_bits(PI.to_bits() | ysign);
    let r = if x < 0.0 { a + pi_y } else { a };
    // x = ±0: ±π/2 for y ≠ 0; for y = ±0: ±0 when x = +0, ±π when x = −0.
    let on_axis = if y == 0.0 {
        if x.is_sign_negative() { pi_y } else { y }
    } else {
        f64::from_bits(FRAC_PI_2.to_bits() | ysign)
    };
    if x == 0.0 { on_axis } else { r }
}

/// atan2(y, x) for any y and x: [`atan2`], where both are infinite the standard library's
/// ±π/4 (x = +∞) or ±3π/4 (x = −∞) rather than NaN, and NaN where either is NaN ([`atan2`]
/// alone gives ±π/2 for a NaN y over x = 0). Branch-free.
#[inline(always)]
pub fn atan2_any(y: f64, x: f64) -> f64 {
    let a = atan2(y, x);
    let corner = if x > 0.0 { FRAC_PI_4 } else { 3.0 * FRAC_PI_4 };
    let corner = f64::from_bits(corner.to_bits() | (y.to_bits() & (1 << 63)));
    let a = if x.is_infinite() && y.is_infinite() {
        corner
    } else {
        a
    };
    // NaN in, NaN out (the sum of two numbers one of which is NaN is NaN).
    if x.is_nan() || y.is_nan() { x + y } else { a }
}

/// asin x = atan2(x, √((1 − x)(1 + x))), branch-free: within a few ulp of the standard
/// library's (1 − x is exact near 1, where √(1 − x²) would lose the digits that matter);
/// |x| > 1 and NaN give NaN (of unspecified sign, as the standard library's), ±0 and ±1 as
/// the standard library gives them.
#[allow(dead_code)] // the full set; formulas take them up one by one
#[inline(always)]
pub fn asin(x: f64) -> f64 {
    atan2_any(x, ((1.0 - x) * (1.0 + x)).sqrt())
}

/// acos x = atan2(√((1 − x)(1 + x)), x), branch-free: within a few ulp of the standard
/// library's; |x| > 1 and NaN give NaN, acos 1 = 0 and acos −1 = π.
#[allow(dead_code)] // the full set; formulas take them up one by one
#[inline(always)]
pub fn acos(x: f64) -> f64 {
    atan2_any(((1.0 - x) * (1.0 + x)).sqrt(), x)
}

/// ln 2 split: the first 32 bits, and the rest (fdlibm).
const LN2_HI: f64 = 6.931_471_803_691_238_164_90e-01;
const LN2_LO: f64 = 1.908_214_929_270_587_700_02e-10;
const INV_LN2: f64 = std::f64::consts::LOG2_E;

const LG1: f64 = 6.666_666_666_666_735_130e-01;
const LG2: f64 = 3.999_999_999_940_941_908e-01;
const LG3: f64 = 2.857_142_874_366_239_149e-01;
const LG4: f64 = 2.222_219_843_214_978_396e-01;
const LG5: f64 = 1.818_357_216_161_805_012e-01;
const LG6: f64 = 1.531_383_769_920_937_332e-01;
const LG7: f64 = 1.479_819_860_511_658_591e-01;

const P1: f64 = 1.666_666_666_666_660_190_37e-01;
const P2: f64 = -2.777_777_777_701_559_338_42e-03;
const P3: f64 = 6.613_756_321_437_934_361_17e-05;
const P4: f64 = -1.653_390_220_546_525_153_90e-06;
const P5: f64 = 4.138_136_797_057_238_460_39e-08;

/// ln x for finite x > 0 (subnormals included), branch-free; about 1 ulp. Other input gives an
/// unspecified finite value.
#[inline(always)]
pub fn ln_pos(x: f64) -> f64 {
    // Subnormals are scaled into the normal range first.
    let sub = x < f64::MIN_POSITIVE;
    let xs = if sub { x * 18_014_398_509_481_984.0 } else { x }; // 2^54
    let bits = xs.to_bits();
    // m in [1, 2), x = m·2^e.
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    // The biased exponent as a double, exactly (no integer conversion, so it vectorises).
    let e =
        f64::from_bits(0x4330_0000_0000_0000 | ((bits >> 52) & 0x7ff)) - 4_503_599_627_370_496.0;
    let big = m > std::f64::consts::SQRT_2;
    let m = if big { 0.5 * m } else { m };
    let k = e - 1023.0 + if big { 1.0 } else { 0.0 } - if sub { 54.0 } else { 0.0 };
    // ln m with m in (√2/2, √2]: fdlibm's s = f/(2+f) series.
    let f = m - 1.0;
    let s = f / (2.0 + f);
    let z = s * s;
    let w = z * z;
    let t1 = w * (LG2 + w * (LG4 + w * LG6));
    let t2 = z * (LG1 + w * (LG3 + w * (LG5 + w * LG7)));
    let r = t2 + t1;
    let hfsq = 0.5 * f * f;
    k * LN2_HI - ((hfsq - (s * (hfsq + r) + k * LN2_LO)) - f)
}

/// eˣ, branch-free; about 1 ulp. x is clamped to [−708, 709] (results below e⁻⁷⁰⁸ ≈ 3·10⁻³⁰⁸
/// are returned as that; NaN gives an unspecified value).
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    let x = x.clamp(-708.0, 709.0);
    let t = x * INV_LN2 + MAGIC;
    let kf = t - MAGIC;
    // k (|k| ≤ 1023) from the low bits of t; 2^k built from its exponent field.
    let k = (t.to_bits() as i64).wrapping_sub(MAGIC.to_bits() as i64);
    let two_k = f64::from_bits((k.wrapping_add(1023) as u64) << 52);
    let hi = x - kf * LN2_HI;
    let lo = kf * LN2_LO;
    let r = hi - lo;
    let z = r * r;
    let c = r - z * (P1 + z * (P2 + z * (P3 + z * (P4 + z * P5))));
    let y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);
    y * two_k
}

/// xʸ for finite x > 0 and moderate y (|y·ln x| < 700), branch-free: relative error about
/// |y·ln x|·10⁻¹⁶ — far below what 16-bit output can show.
#[inline(always)]
pub fn pow_pos(x: f64, y: f64) -> f64 {
    exp(y * ln_pos(x))
}

/// a mod b with the sign of a (Rust's `%`, C's `fmod`), bit for bit, without the library's
/// loop in the usual case: with q = trunc(a/b) right, a − q·b is exact in one fused
/// multiply-add; when q is not (a/b rounded across an integer, or a quotient beyond 2⁵²,
/// infinities, NaN, b = 0) the result shows it and `%` is used.
#[inline(always)]
pub fn fmod(a: f64, b: f64) -> f64 {
    let q = (a / b).trunc();
    let r = (-q).mul_add(b, a);
    let r = if r == 0.0 { 0f64.copysign(a) } else { r };
    let same_sign = r.is_sign_negative() == a.is_sign_negative();
    if q.abs() < 4_503_599_627_370_496.0 && same_sign && r.abs() < b.abs() {
        r
    } else {
        a % b
    }
}

/// xʸ for x ≥ 0 (0 and +∞ included) and finite y, branch-free (so loops over arrays
/// vectorise), for the variations' powers of radii: 0 and ∞ as libm gives them, results beyond
/// the double range ∞ and below e⁻⁷⁰⁸ 0 (libm: a subnormal); otherwise relative error about
/// |y·ln x|·10⁻¹⁶. Negative or NaN x gives an unspecified value.
#[inline(always)]
pub fn pow_nonneg(x: f64, y: f64) -> f64 {
    let l = y * ln_pos(x);
    let p = exp(l);
    let p = if l > 709.782_712_893_384 {
        f64::INFINITY
    } else {
        p
    };
    let p = if l < -708.0 { 0.0 } else { p };
    // 0^y and ∞^y: ln_pos is not defined there.
    let (small, large) = if y > 0.0 {
        (0.0, f64::INFINITY)
    } else if y < 0.0 {
        (f64::INFINITY, 0.0)
    } else {
        (1.0, 1.0)
    };
    if x == 0.0 {
        small
    } else if x == f64::INFINITY {
        large
    } else {
        p
    }
}

/// ln x for any x, with the standard library's special values (ln 0 = −∞, ln of a negative
/// number or NaN = NaN, ln ∞ = ∞), branch-free; about 1 ulp (see [`ln_pos`]).
#[allow(dead_code)] // the full set; formulas take them up one by one
#[inline(always)]
pub fn ln(x: f64) -> f64 {
    let l = ln_pos(x);
    let l = if x == f64::INFINITY { x } else { l };
    let l = if x == 0.0 { f64::NEG_INFINITY } else { l };
    if x < 0.0 || x.is_nan() { f64::NAN } else { l }
}

/// eˣ for any x, with the standard library's special values and the whole range (results
/// below the normal range rounded to subnormals, beyond the double range ∞), branch-free;
/// about 1 ulp (subnormal results: within one ulp of the subnormal grid).
#[allow(dead_code)] // the full set; formulas take them up one by one
#[inline(always)]
pub fn exp_any(x: f64) -> f64 {
    exp_scaled(x, 0)
}

/// eˣ·2ᵐ for m = 0 or −1 ([`exp_any`] and half of it), with one rounding of the scaling
/// (the power of two joins the exponent): ½·eˣ stays finite up to x = ln(2·f64::MAX).
#[inline(always)]
fn exp_scaled(x: f64, m: i64) -> f64 {
    let xc = x.clamp(-746.0, 711.0);
    let t = xc * INV_LN2 + MAGIC;
    let kf = t - MAGIC;
    let k = (t.to_bits() as i64).wrapping_sub(MAGIC.to_bits() as i64) + m;
    // 2^k in two factors, so that k beyond the normal exponents (subnormal or near-overflow
    // results) is still exact: 2^(k − s) · 2^s.
    let s: i64 = if k < -1000 {
        -100
    } else if k > 1000 {
        100
    } else {
        0
    };
    let two_k = f64::from_bits(((k - s + 1023) as u64) << 52);
    let two_s = f64::from_bits(((s + 1023) as u64) << 52);
    let hi = xc - kf * LN2_HI;
    let lo = kf * LN2_LO;
    let r = hi - lo;
    let z = r * r;
    let c = r - z * (P1 + z * (P2 + z * (P3 + z * (P4 + z * P5))));
    let y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);
    let e = y * two_k * two_s;
    // Beyond these the result overflows (ln f64::MAX, and ln 2 more for the half).
    let limit = if m == 0 {
        709.782_712_893_384
    } else {
        710.475_860_073_943_9
    };
    let e = if x > limit { f64::INFINITY } else { e };
    let e = if x < -745.133_219_101_941_2 { 0.0 } else { e };
    if x.is_nan() { x } else { e }
}

/// sinh x, branch-free, within 3 ulp: an odd Taylor polynomial for |x| < 1 (its 9 terms leave
/// less than 10⁻¹⁷ relative), (eˣ − e⁻ˣ)/2 up to 22 and ½·eˣ beyond (no overflow before the
/// true result overflows). ±0, ±∞ and NaN as the standard library gives them.
#[allow(dead_code)] // the full set; formulas take them up one by one
#[inline(always)]
pub fn sinh(x: f64) -> f64 {
    sinh_cosh(x).0
}

/// cosh x, branch-free, within 3 ulp: an even Taylor polynomial for |x| < 1, (eˣ + e⁻ˣ)/2 up
/// to |x| = 22 and ½·e^|x| beyond.
#[allow(dead_code)] // the full set; formulas take them up one by one
#[inline(always)]
pub fn cosh(x: f64) -> f64 {
    sinh_cosh_abs(x).1
}

/// tanh x, branch-free, within 4 ulp: sinh x / cosh x up to |x| = 22 and ±1 beyond (where
/// 1 − tanh |x| < 2⁻⁶³). ±0 and NaN as the standard library gives them.
#[allow(dead_code)] // the full set; formulas take them up one by one
#[inline(always)]
pub fn tanh(x: f64) -> f64 {
    let (s, c) = sinh_cosh_abs(x);
    let t = if x.abs() < 22.0 { s / c } else { 1.0 };
    let t = if x.is_nan() { x } else { t };
    f64::from_bits(t.to_bits() | (x.to_bits() & (1 << 63)))
}

/// (sinh x, cosh x) from one exponential, branch-free (so loops over arrays vectorise):
/// each within 3 ulp, as [`sinh`] and [`cosh`] give them.
#[inline(always)]
pub fn sinh_cosh(x: f64) -> (f64, f64) {
    let (s, c) = sinh_cosh_abs(x);
    (f64::from_bits(s.to_bits() | (x.to_bits() & (1 << 63))), c)
}

/// (sinh |x|, cosh |x|) for [`sinh`], [`cosh`] and [`tanh`]: one exponential, e^|x| up to
/// |x| = 22 and ½·e^|x| beyond (both sinh and cosh, no overflow before the true result
/// overflows).
#[inline(always)]
fn sinh_cosh_abs(x: f64) -> (f64, f64) {
    let a = x.abs();
    // |x| < 1: sinh by its Taylor series (coefficients 1/(2k+1)!).
    let z = a * a;
    let mut poly = 1.0 / 355_687_428_096_000.0;
    for c in [
        1.0 / 1_307_674_368_000.0,
        1.0 / 6_227_020_800.0,
        1.0 / 39_916_800.0,
        1.0 / 362_880.0,
        1.0 / 5040.0,
        1.0 / 120.0,
        1.0 / 6.0,
    ] {
        poly = c + z * poly;
    }
    let series = a + a * z * poly;
    // cosh by its even series (coefficients 1/(2k)!) too: (eˣ + e⁻ˣ)/2 would carry e's
    // rounding into cosh − 1, which formulas subtracting 1 or a cosine read.
    let mut even = 1.0 / 6_402_373_705_728_000.0;
    for c in [
        1.0 / 20_922_789_888_000.0,
        1.0 / 87_178_291_200.0,
        1.0 / 479_001_600.0,
        1.0 / 3_628_800.0,
        1.0 / 40_320.0,
        1.0 / 720.0,
        1.0 / 24.0,
        0.5,
    ] {
        even = c + z * even;
    }
    let cseries = 1.0 + z * even;
    let big = a >= 22.0;
    let e = exp_scaled(a, if big { -1 } else { 0 });
    let inv = 1.0 / e;
    let s = if a < 1.0 { series } else { 0.5 * (e - inv) };
    let c = if a < 1.0 { cseries } else { 0.5 * (e + inv) };
    let (s, c) = if big { (e, e) } else { (s, c) };
    if a.is_nan() { (a, a) } else { (s, c) }
}

/// xʸ for any x and y with C's `pow` special values (x < 0 with an integral y gives the sign
/// of its parity, with a non-integral y NaN; x⁰ = 1ˣ = 1 even for NaN), branch-free: the
/// relative error is about (1 + |y·ln|x||)·4 ulp (the rounding of y·ln|x| amplified by exp;
/// a correctly rounded pow needs ln in double-double, which the variations' 16-bit output
/// cannot show).
#[allow(dead_code)] // the full set; formulas take them up one by one
#[inline(always)]
pub fn pow(x: f64, y: f64) -> f64 {
    let a = x.abs();
    let p = exp_any(y * ln_pos(a));
    // 0^y and ∞^y: ln_pos is not defined there.
    let (small, large) = if y > 0.0 {
        (0.0, f64::INFINITY)
    } else if y < 0.0 {
        (f64::INFINITY, 0.0)
    } else {
        (1.0, 1.0)
    };
    let p = if a == 0.0 { small } else { p };
    let p = if a == f64::INFINITY { large } else { p };
    // ±∞ exponents: 0 or ∞ by whether |x| is below or above 1 (1 handled below).
    let p = if y == f64::INFINITY {
        if a < 1.0 { 0.0 } else { f64::INFINITY }
    } else if y == f64::NEG_INFINITY {
        if a < 1.0 { f64::INFINITY } else { 0.0 }
    } else {
        p
    };
    let integral = y == y.trunc();
    let odd = integral && y.abs() < 9_007_199_254_740_992.0 && (0.5 * y) != (0.5 * y).trunc();
    let neg = x.is_sign_negative();
    let p = if neg && odd { -p } else { p };
    let p = if x < 0.0 && x.is_finite() && !integral && y.is_finite() {
        f64::NAN
    } else {
        p
    };
    let p = if x.is_nan() || y.is_nan() {
        f64::NAN
    } else {
        p
    };
    if y == 0.0 || x == 1.0 || (x == -1.0 && y.is_infinite()) {
        1.0
    } else {
        p
    }
}

#[path = "fastmath_huge.rs"]
mod huge;

#[cfg(test)]
#[path = "fastmath_tests.rs"]
mod tests;
