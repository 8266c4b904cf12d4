//! Fast sin, cos and atan2 for the chaos game.
//!
//! glibc's versions save and restore the floating-point control register on every call, which
//! dominated the iteration time. These use the classic fdlibm minimax polynomials (public
//! coefficients, errors around 1 ulp) with a two-constant Cody–Waite reduction by π/2 for
//! |x| < 2²⁰ and fall back to the standard library outside that range and for non-finite input.

use std::f64::consts::{FRAC_PI_2, PI};

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
const INV_PIO2: f64 = 6.366_197_723_675_813_824_33e-01;
const REDUCE_LIMIT: f64 = 1_048_576.0;

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

/// Reduce x to r in [−π/4, π/4] and the quadrant k mod 4.
#[inline(always)]
fn reduce(x: f64) -> (f64, i64) {
    let k = (x * INV_PIO2).round_ties_even();
    let r = (x - k * PIO2_1) - k * PIO2_1T;
    (r, k as i64)
}

/// (sin x, cos x).
#[inline(always)]
pub fn sin_cos(x: f64) -> (f64, f64) {
    if !(x.abs() < REDUCE_LIMIT) {
        return x.sin_cos();
    }
    let (r, k) = reduce(x);
    let s = kernel_sin(r);
    let c = kernel_cos(r);
    match k & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

#[inline(always)]
pub fn sin(x: f64) -> f64 {
    if !(x.abs() < REDUCE_LIMIT) {
        return x.sin();
    }
    let (r, k) = reduce(x);
    match k & 3 {
        0 => kernel_sin(r),
        1 => kernel_cos(r),
        2 => -kernel_sin(r),
        _ => -kernel_cos(r),
    }
}

#[inline(always)]
pub fn cos(x: f64) -> f64 {
    if !(x.abs() < REDUCE_LIMIT) {
        return x.cos();
    }
    let (r, k) = reduce(x);
    match k & 3 {
        0 => kernel_cos(r),
        1 => -kernel_sin(r),
        2 => -kernel_cos(r),
        _ => kernel_sin(r),
    }
}

const ATANHI: [f64; 4] = [
    4.636_476_090_008_060_935_15e-01,
    7.853_981_633_974_482_789_99e-01,
    9.827_937_232_473_290_540_82e-01,
    1.570_796_326_794_896_558_00e+00,
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

/// atan(x) for finite or infinite x.
#[inline(always)]
pub fn atan(x: f64) -> f64 {
    let neg = x.is_sign_negative();
    let mut t = x.abs();
    if t.is_nan() {
        return x;
    }
    let id: isize;
    if t < 0.4375 {
        id = -1;
    } else if t < 1.1875 {
        if t < 0.6875 {
            id = 0;
            t = (2.0 * t - 1.0) / (2.0 + t);
        } else {
            id = 1;
            t = (t - 1.0) / (t + 1.0);
        }
    } else if t < 2.4375 {
        id = 2;
        t = (t - 1.5) / (1.0 + 1.5 * t);
    } else {
        id = 3;
        t = -1.0 / t;
    }
    let z = t * t;
    let w = z * z;
    let s1 = z * (AT[0] + w * (AT[2] + w * (AT[4] + w * (AT[6] + w * (AT[8] + w * AT[10])))));
    let s2 = w * (AT[1] + w * (AT[3] + w * (AT[5] + w * (AT[7] + w * AT[9]))));
    let r = if id < 0 {
        t - t * (s1 + s2)
    } else {
        let i = id as usize;
        ATANHI[i] - ((t * (s1 + s2) - ATANLO[i]) - t)
    };
    if neg { -r } else { r }
}

/// atan2(y, x) with the standard quadrant and signed-zero conventions.
#[inline(always)]
pub fn atan2(y: f64, x: f64) -> f64 {
    if x.is_nan() || y.is_nan() {
        return f64::NAN;
    }
    if x == 0.0 {
        if y == 0.0 {
            return if x.is_sign_negative() {
                if y.is_sign_negative() { -PI } else { PI }
            } else {
                y // ±0
            };
        }
        return if y > 0.0 { FRAC_PI_2 } else { -FRAC_PI_2 };
    }
    if x.is_infinite() || y.is_infinite() {
        return y.atan2(x);
    }
    let a = atan(y / x);
    if x > 0.0 {
        a
    } else if y.is_sign_negative() {
        a - PI
    } else {
        a + PI
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::rng::FastRng;

    fn ulps(a: f64, b: f64) -> f64 {
        let scale = a.abs().max(b.abs()).max(f64::MIN_POSITIVE);
        (a - b).abs() / (scale * f64::EPSILON)
    }

    #[test]
    fn sin_cos_match_std() {
        let mut rng = FastRng::new(1);
        let mut worst: f64 = 0.0;
        for i in 0..200_000 {
            let mag = [1e-8, 1.0, 10.0, 1000.0, 1e5, 2e6][i % 6];
            let x = rng.f11() * mag;
            let (s, c) = sin_cos(x);
            // Absolute error relative to 1 (the reduction loses relative accuracy near zeros
            // of sin/cos far from the origin; the absolute error stays tiny).
            assert!((s - x.sin()).abs() < 4e-16 * x.abs().max(1.0), "sin {x}");
            assert!((c - x.cos()).abs() < 4e-16 * x.abs().max(1.0), "cos {x}");
            assert_eq!(sin(x), s);
            assert_eq!(cos(x), c);
            if x.abs() < 10.0 && x.sin().abs() > 0.1 {
                worst = worst.max(ulps(s, x.sin()));
            }
        }
        assert!(worst <= 2.0, "worst {worst} ulp");
        assert!(sin_cos(f64::NAN).0.is_nan());
        assert!(sin(f64::INFINITY).is_nan());
        assert_eq!(sin(0.0), 0.0);
        assert_eq!(cos(0.0), 1.0);
    }

    #[test]
    fn atan2_matches_std() {
        let mut rng = FastRng::new(2);
        for i in 0..200_000 {
            let m = [1e-10, 1.0, 1e5][i % 3];
            let (y, x) = (rng.f11() * m, rng.f11() * [1e-10, 1.0, 1e5][(i / 3) % 3]);
            let a = atan2(y, x);
            let b = y.atan2(x);
            assert!(ulps(a, b) <= 2.0, "atan2({y}, {x}) = {a} vs {b}");
        }
        for &(y, x) in &[
            (0.0, -1.0),
            (-0.0, -1.0),
            (0.0, 1.0),
            (-0.0, 1.0),
            (0.0, 0.0),
            (-0.0, -0.0),
            (0.0, -0.0),
            (1.0, 0.0),
            (-1.0, 0.0),
            (1.0, f64::INFINITY),
            (f64::INFINITY, 1.0),
            (-1e-20, -1.0),
            (1e300, 1e-300),
        ] {
            let (a, b) = (atan2(y, x), y.atan2(x));
            assert!(a == b || ulps(a, b) <= 1.0, "atan2({y}, {x}) = {a} vs {b}");
            assert_eq!(a.is_sign_negative(), b.is_sign_negative(), "sign of atan2({y}, {x})");
        }
        assert!(atan2(f64::NAN, 1.0).is_nan());
    }
}
