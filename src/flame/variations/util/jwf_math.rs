//! JWildfire's default maths (`FAST_MATH`, class `FastMathLibImpl` in JWildfire 9.00), to the
//! bit: JWildfire's `MathLib.sin`, `cos`, `tan`, `atan2`, `exp`, `sqrt`, `pow`, `sinh`, `cosh`,
//! `tanh`, `atan`, `acos` and `asin` go through it, and a variation whose result is sensitive to
//! the last bits (near a singularity, or through a long chain) needs the same numbers.
//!
//! The method is Jafama's (Jeff Hain; version 1.2, `odk.lang.FastMath`, is what JWildfire
//! bundles; Jafama 2 at github.com/jeffhain/jafama, Apache-2.0, has the same algorithms): a table
//! of the function and its first four derivatives at fixed steps, and the Taylor polynomial
//! from the nearest step; fdlibm's formulas outside the tables. Two of JWildfire's own choices
//! differ from Jafama: its `atan2` returns +0 or +π for y = −0 (and 0 for atan2(±0, −0)), and
//! `log` is `java.lang.Math.log` (here `f64::ln`), while `pow` uses Jafama's table logarithm.
//!
//! These are scalar and slower than `crate::flame::fastmath`: they are for the JWildfire
//! variations that need JWildfire's exact numbers, not for batch loops.

use super::jwf_math_tables::{
    ASIN_MAX_VALUE_FOR_TABS, ATAN_MAX_VALUE_FOR_TABS, EXP_HI_TAB_SIZE, INVPIO2, PIO2_HI, PIO2_LO,
    SIN_COS_TABS_SIZE, TAN_TABS_SIZE, TAN_VIRTUAL_TABS_SIZE, Tables, asin_delta, atan_delta,
    sin_cos_delta, tan_delta,
};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};
use std::sync::OnceLock;

fn tables() -> &'static Tables {
    static T: OnceLock<Tables> = OnceLock::new();
    T.get_or_init(Tables::build)
}

const ONE_DIV_F2: f64 = 0.5;
const ONE_DIV_F3: f64 = 1.0 / 6.0;
const ONE_DIV_F4: f64 = 1.0 / 24.0;
const TWO_POW_N27: f64 = f64::from_bits(0x3e40_0000_0000_0000);
const TWO_POW_N28: f64 = f64::from_bits(0x3e30_0000_0000_0000);
#[allow(dead_code)] // tanh's
const TWO_POW_N55: f64 = f64::from_bits(0x3c80_0000_0000_0000);
const TWO_POW_52: f64 = f64::from_bits(0x4330_0000_0000_0000);
const TWO_POW_N26: f64 = f64::from_bits(0x3e50_0000_0000_0000);
const TWO_POW_66: f64 = f64::from_bits(0x4410_0000_0000_0000);
const TWO_POW_N54: f64 = f64::from_bits(0x3c90_0000_0000_0000);
const TWO_POW_24: f64 = 16_777_216.0;
/// 2π in five parts of 24 bits (fdlibm's `TWOPI_TAB0..4`, as Jafama has them).
const TWO_PI_PARTS: [u64; 5] = [
    0x4019_21fb_4000_0000,
    0x3e94_442d_0000_0000,
    0x3d18_4698_8000_0000,
    0x3b98_cc51_6000_0000,
    0x3a10_1b83_8000_0000,
];
const TWO_POW_450: f64 = f64::from_bits(0x5c10_0000_0000_0000);
const TWO_POW_N450: f64 = f64::from_bits(0x23d0_0000_0000_0000);
const TWO_POW_750: f64 = f64::from_bits(0x6ed0_0000_0000_0000);
const TWO_POW_N750: f64 = f64::from_bits(0x1110_0000_0000_0000);
/// ln 2 and ln 2²⁷ as fdlibm gives them.
const LOG_2: f64 = f64::from_bits(0x3fe6_2e42_fefa_39ef);
const LOG_TWO_POW_27: f64 = f64::from_bits(0x4032_b708_8723_20e2);
/// ln(f64::MAX): the overflow limit of exp.
const EXP_OVERFLOW_LIMIT: f64 = f64::from_bits(0x4086_2e42_fefa_39ef);
/// ln of the smallest subnormal: the underflow limit of exp.
const EXP_UNDERFLOW_LIMIT: f64 = f64::from_bits(0xc087_4910_d52d_3051);
/// Steps of 2⁻¹⁰ in the low exp table.
const EXP_LO_INDEXING: f64 = 1024.0;
const EXP_LO_SHIFT: u32 = 10;
const EXP_LO_MID: i32 = 1024;

/// The largest |angle| that sin and cos index directly: (2²² − 1) steps, with 1 % margin.
fn sin_cos_max_for_int_modulo() -> f64 {
    4_194_303.0 / sin_cos_indexer() * 0.99
}

fn sin_cos_indexer() -> f64 {
    let (hi, lo) = sin_cos_delta();
    1.0 / (hi + lo)
}

fn tan_indexer() -> f64 {
    let (hi, lo) = tan_delta();
    1.0 / (hi + lo)
}

/// `angle` reduced to [−π, π] by a multiple of 2π (2π in two parts), as Jafama's
/// `remainderTwoPi` does up to 2²⁰·2π. Beyond that Jafama switches to a many-word reduction,
/// which this does not reproduce bit for bit: up to 2²⁴·2π the remainder is accurate to about
/// an ulp of 2π, beyond it is only approximate.
fn remainder_two_pi(angle: f64) -> f64 {
    let (neg, a) = if angle < 0.0 {
        (true, -angle)
    } else {
        (false, angle)
    };
    let r = if a <= f64::from_bits(0x4159_21fb_5444_2d18) {
        let two_pi_hi = 4.0 * PIO2_HI;
        let two_pi_lo = 4.0 * PIO2_LO;
        let k = f64::from((a * (INVPIO2 / 4.0) + 0.5) as i32);
        a - k * two_pi_hi - k * two_pi_lo
    } else if a <= TWO_POW_24 * TAU {
        // Jafama reduces larger angles with many words of 1/2π. Up to 2²⁴·2π, 2π in five
        // parts of 24 bits (fdlibm's) times the integer quotient are exact products and give
        // the remainder to about an ulp of 2π (not always JWildfire's last bit).
        let k = (a * (INVPIO2 / 4.0) + 0.5).floor();
        TWO_PI_PARTS
            .iter()
            .fold(a, |r, &p| r - k * f64::from_bits(p))
    } else if a.is_finite() {
        // Beyond 2²⁴·2π: not JWildfire's remainder (it needs more words of 1/2π).
        let m = a % TAU;
        if m > PI { m - TAU } else { m }
    } else {
        f64::NAN
    };
    if neg { -r } else { r }
}

/// The index of the nearest step and the offset from it, for a table of steps `hi + lo`.
#[inline]
fn step(x: f64, indexer: f64, hi: f64, lo: f64) -> (i32, f64) {
    // Java's (int) cast: saturating, NaN to 0, as Rust's `as`.
    let i = (x * indexer + 0.5) as i32;
    let d = x - f64::from(i) * hi - f64::from(i) * lo;
    (i, d)
}

/// JWildfire's sine.
pub fn sin(angle: f64) -> f64 {
    let t = tables();
    let (neg, mut a) = if angle < 0.0 {
        (true, -angle)
    } else {
        (false, angle)
    };
    if a > sin_cos_max_for_int_modulo() {
        a = remainder_two_pi(a);
        if a < 0.0 {
            a += TAU;
        }
    }
    let (hi, lo) = sin_cos_delta();
    let (i, d) = step(a, sin_cos_indexer(), hi, lo);
    let i = (i & (SIN_COS_TABS_SIZE as i32 - 2)) as usize;
    let (s, c) = (t.sin[i], t.cos[i]);
    let r = s + d * (c + d * (-s * ONE_DIV_F2 + d * (-c * ONE_DIV_F3 + d * s * ONE_DIV_F4)));
    if neg { -r } else { r }
}

/// JWildfire's cosine.
pub fn cos(angle: f64) -> f64 {
    let t = tables();
    let mut a = angle.abs();
    if a > sin_cos_max_for_int_modulo() {
        a = remainder_two_pi(a);
        if a < 0.0 {
            a += TAU;
        }
    }
    let (hi, lo) = sin_cos_delta();
    let (i, d) = step(a, sin_cos_indexer(), hi, lo);
    let i = (i & (SIN_COS_TABS_SIZE as i32 - 2)) as usize;
    let (s, c) = (t.sin[i], t.cos[i]);
    c + d * (-s + d * (-c * ONE_DIV_F2 + d * (s * ONE_DIV_F3 + d * c * ONE_DIV_F4)))
}

/// JWildfire's tangent.
pub fn tan(angle: f64) -> f64 {
    let t = tables();
    let mut a = angle;
    if a.abs() > 4_194_303.0 / tan_indexer() * 0.99 {
        a = remainder_two_pi(a);
        if a < -FRAC_PI_2 {
            a += PI;
        } else if a > FRAC_PI_2 {
            a -= PI;
        }
    }
    let mut neg = a < 0.0;
    if neg {
        a = -a;
    }
    let (hi, lo) = tan_delta();
    let (i, mut d) = step(a, tan_indexer(), hi, lo);
    let virt = TAN_VIRTUAL_TABS_SIZE as i32 - 1;
    // The index modulo π: the second half mirrors the first with the sign changed.
    let mut i = i & (2 * virt - 1);
    if i > virt {
        i = 2 * virt - i;
        d = -d;
        neg = !neg;
    }
    let r = if (i as usize) < TAN_TABS_SIZE {
        let k = i as usize;
        let p = &t.tan;
        p.f[k] + d * (p.d1[k] + d * (p.d2[k] + d * (p.d3[k] + d * p.d4[k])))
    } else {
        // Above 77°: 1/tan of the complement.
        let k = (virt - i) as usize;
        let p = &t.tan;
        1.0 / (p.f[k] - d * (p.d1[k] - d * (p.d2[k] - d * (p.d3[k] - d * p.d4[k]))))
    };
    if neg { -r } else { r }
}

/// JWildfire's arctangent.
pub fn atan(value: f64) -> f64 {
    let t = tables();
    let (neg, v) = if value < 0.0 {
        (true, -value)
    } else {
        (false, value)
    };
    let r = if v == 1.0 {
        FRAC_PI_4
    } else if v <= ATAN_MAX_VALUE_FOR_TABS {
        let delta = atan_delta();
        let k = (v * (1.0 / delta) + 0.5) as usize;
        let d = v - k as f64 * delta;
        let p = &t.atan;
        p.f[k] + d * (p.d1[k] + d * (p.d2[k] + d * (p.d3[k] + d * p.d4[k])))
    } else if v < TWO_POW_66 {
        // fdlibm's atan for |x| > 2.4375: π/2 − atan(1/x), its published coefficients.
        const AT: [u64; 11] = [
            0x3fd5_5555_5555_550d,
            0xbfc9_9999_9998_ebc4,
            0x3fc2_4924_9200_83ff,
            0xbfbc_71c6_fe23_1671,
            0x3fb7_45cd_c54c_206e,
            0xbfb3_b0f2_af74_9a6d,
            0x3fb1_0d66_a0d0_3d51,
            0xbfad_de2d_52de_fd9a,
            0x3fa9_7b4b_2476_0deb,
            0xbfa2_b444_2c6a_6c2f,
            0x3f90_ad3a_e322_da11,
        ];
        let at = |k: usize| f64::from_bits(AT[k]);
        let x = -1.0 / v;
        let x2 = x * x;
        let x4 = x2 * x2;
        let s1 =
            x2 * (at(0) + x4 * (at(2) + x4 * (at(4) + x4 * (at(6) + x4 * (at(8) + x4 * at(10))))));
        let s2 = x4 * (at(1) + x4 * (at(3) + x4 * (at(5) + x4 * (at(7) + x4 * at(9)))));
        let lo3 = f64::from_bits(0x3c91_a626_3314_5c07);
        FRAC_PI_2 - ((x * (s1 + s2) - lo3) - x)
    } else if v.is_nan() {
        return f64::NAN;
    } else {
        FRAC_PI_2
    };
    if neg { -r } else { r }
}

/// JWildfire's atan2 (`FastMathLibImpl.atan2`): Jafama's, except that a zero y counts as +0
/// (atan2(−0, x) is +0 for x > 0 and +π for x < 0) and atan2(±0, −0) is 0.
pub fn atan2(y: f64, x: f64) -> f64 {
    if x > 0.0 {
        if y == 0.0 {
            0.0
        } else if x == f64::INFINITY {
            if y == f64::INFINITY {
                FRAC_PI_4
            } else if y == f64::NEG_INFINITY {
                -FRAC_PI_4
            } else if y > 0.0 {
                0.0
            } else if y < 0.0 {
                -0.0
            } else {
                f64::NAN
            }
        } else {
            atan(y / x)
        }
    } else if x < 0.0 {
        if y == 0.0 {
            PI
        } else if x == f64::NEG_INFINITY {
            if y == f64::INFINITY {
                3.0 * FRAC_PI_4
            } else if y == f64::NEG_INFINITY {
                -3.0 * FRAC_PI_4
            } else if y > 0.0 {
                PI
            } else if y < 0.0 {
                -PI
            } else {
                f64::NAN
            }
        } else if y > 0.0 {
            FRAC_PI_2 + atan(-x / y)
        } else if y < 0.0 {
            -FRAC_PI_2 - atan(x / y)
        } else {
            f64::NAN
        }
    } else if x == 0.0 {
        if y == 0.0 {
            0.0
        } else if y > 0.0 {
            FRAC_PI_2
        } else if y < 0.0 {
            -FRAC_PI_2
        } else {
            f64::NAN
        }
    } else {
        f64::NAN
    }
}

/// JWildfire's arcsine.
pub fn asin(value: f64) -> f64 {
    let t = tables();
    let (neg, v) = if value < 0.0 {
        (true, -value)
    } else {
        (false, value)
    };
    let r = if v <= ASIN_MAX_VALUE_FOR_TABS {
        let delta = asin_delta();
        let k = (v * (1.0 / delta) + 0.5) as usize;
        let d = v - k as f64 * delta;
        let p = &t.asin;
        p.f[k] + d * (p.d1[k] + d * (p.d2[k] + d * (p.d3[k] + d * p.d4[k])))
    } else if v < 1.0 {
        // fdlibm's asin for |x| ≥ 0.975: π/2 − 2·asin(√((1−x)/2)), its published coefficients.
        const PS: [u64; 6] = [
            0x3fc5_5555_5555_5555,
            0xbfd4_d612_03eb_6f7d,
            0x3fc9_c155_0e88_4455,
            0xbfa4_8228_b568_8f3b,
            0x3f49_efe0_7501_b288,
            0x3f02_3de1_0dfd_f709,
        ];
        const QS: [u64; 4] = [
            0xc003_3a27_1c8a_2d4b,
            0x4000_2ae5_9c59_8ac8,
            0xbfe6_066c_1b8d_0159,
            0x3fb3_b8c5_b12e_9282,
        ];
        let ps = |k: usize| f64::from_bits(PS[k]);
        let qs = |k: usize| f64::from_bits(QS[k]);
        let u = (1.0 - v) * 0.5;
        let p = u * (ps(0) + u * (ps(1) + u * (ps(2) + u * (ps(3) + u * (ps(4) + u * ps(5))))));
        let q = 1.0 + u * (qs(0) + u * (qs(1) + u * (qs(2) + u * qs(3))));
        let s = sqrt(u);
        let z = s + s * (p / q);
        let lo = f64::from_bits(0x3c91_a626_3314_5c07);
        FRAC_PI_2 - ((z + z) - lo)
    } else if v == 1.0 {
        FRAC_PI_2
    } else {
        return f64::NAN;
    };
    if neg { -r } else { r }
}

/// JWildfire's arccosine: π/2 − asin.
pub fn acos(value: f64) -> f64 {
    FRAC_PI_2 - asin(value)
}

/// JWildfire's square root: a first guess from two tables (by exponent and by the first 12
/// bits of the mantissa) and three Newton steps on x/4.
pub fn sqrt(value: f64) -> f64 {
    if value.is_nan() || value <= 0.0 {
        return if value == 0.0 { value } else { f64::NAN };
    }
    if value == f64::INFINITY {
        return f64::INFINITY;
    }
    let t = tables();
    let (mut v, scale) = if value < f64::MIN_POSITIVE {
        (value * TWO_POW_52, 2.0 * TWO_POW_N26)
    } else {
        (value, 2.0)
    };
    let bits_hi = (v.to_bits() >> 32) as u32;
    let exp_index = ((bits_hi >> 20) + 51) as usize;
    let man_index = ((bits_hi << 12) >> 20) as usize;
    let mut r = t.sqrt_x_hi[exp_index] * t.sqrt_x_lo[man_index];
    let slope = t.sqrt_slope_hi[exp_index] * t.sqrt_slope_lo[man_index];
    v *= 0.25;
    r += (v - r * r) * slope;
    r += (v - r * r) * slope;
    scale * (r + (v - r * r) * slope)
}

/// √(x² + y²) as Jafama's `hypot` (JWildfire's `Complex.Radius`): scaled away from overflow
/// and underflow, with JWildfire's square root.
pub fn hypot(x: f64, y: f64) -> f64 {
    let (mut a, mut b) = (x.abs(), y.abs());
    if b < a {
        std::mem::swap(&mut a, &mut b);
    } else if a.is_nan() || b.is_nan() {
        return if a == f64::INFINITY || b == f64::INFINITY {
            f64::INFINITY
        } else {
            f64::NAN
        };
    }
    if b - a == b {
        return b;
    }
    let factor = if a > TWO_POW_450 {
        a *= TWO_POW_N750;
        b *= TWO_POW_N750;
        TWO_POW_750
    } else if b < TWO_POW_N450 {
        a *= TWO_POW_750;
        b *= TWO_POW_750;
        TWO_POW_N750
    } else {
        1.0
    };
    factor * sqrt(a * a + b * b)
}

/// The Taylor polynomial of e^δ to the 4th order.
#[inline]
fn exp_poly(d: f64) -> f64 {
    1.0 + d * (1.0 + d * (1.0 / 2.0 + d * (1.0 / 6.0 + d * (1.0 / 24.0))))
}

/// JWildfire's e^x: e^⌊x⌋ (or e^−⌈−x⌉) and e^z, z the part in steps of 2⁻¹⁰, from tables, times
/// a polynomial for the rest.
pub fn exp(value: f64) -> f64 {
    let t = tables();
    if value >= 0.0 {
        if value > EXP_OVERFLOW_LIMIT {
            return f64::INFINITY;
        }
        let mut i = (value * EXP_LO_INDEXING) as i32;
        let n = i >> EXP_LO_SHIFT;
        i -= n << EXP_LO_SHIFT;
        let d = (value - f64::from(n)) - f64::from(i) * (1.0 / EXP_LO_INDEXING);
        let hi = t.exp_hi[(n as usize).min(EXP_HI_TAB_SIZE - 1)];
        hi * (t.exp_lo_pos[(i + EXP_LO_MID) as usize] * exp_poly(d))
    } else {
        if value.is_nan() || value < EXP_UNDERFLOW_LIMIT {
            return if value.is_nan() { f64::NAN } else { 0.0 };
        }
        let mut i = -((-(value * EXP_LO_INDEXING)) as i32);
        let n = -((-i) >> EXP_LO_SHIFT);
        i -= n << EXP_LO_SHIFT;
        let d = (value - f64::from(n)) - f64::from(i) * (1.0 / EXP_LO_INDEXING);
        let r =
            t.exp_hi_inv[(-n) as usize] * (t.exp_lo_pos[(i + EXP_LO_MID) as usize] * exp_poly(d));
        // Below −705 the table holds e^−n·2⁵⁴ (normal numbers only).
        if f64::from(n) >= -705.0 {
            r
        } else {
            r * TWO_POW_N54
        }
    }
}

/// JWildfire's e^x − 1 (Jafama's `expm1`, used by sinh and tanh).
pub fn expm1(value: f64) -> f64 {
    let t = tables();
    if value.abs() < 1.0 {
        let i = (value * EXP_LO_INDEXING) as i32;
        let d = value - f64::from(i) * (1.0 / EXP_LO_INDEXING);
        let k = (i + EXP_LO_MID) as usize;
        let poly = 1.0 + d * (1.0 / 2.0 + d * (1.0 / 6.0 + d * (1.0 / 24.0 + d * (1.0 / 120.0))));
        t.exp_lo_pos[k] * (t.exp_lo_neg[k] + d * poly)
    } else {
        exp(value) - 1.0
    }
}

/// Jafama's table logarithm (used by JWildfire's pow; JWildfire's own `log` is Java's).
fn log_table(value: f64) -> f64 {
    if value > 0.0 {
        if value == f64::INFINITY {
            return f64::INFINITY;
        }
        let t = tables();
        let (v, h) = if value > 0.95 {
            if value < 1.14 {
                // ln x = 2·artanh((x−1)/(x+1)), to z¹¹.
                let z = (value - 1.0) / (value + 1.0);
                let z2 = z * z;
                return z
                    * (2.0
                        + z2 * ((2.0 / 3.0)
                            + z2 * ((2.0 / 5.0)
                                + z2 * ((2.0 / 7.0) + z2 * ((2.0 / 9.0) + z2 * (2.0 / 11.0))))));
            }
            (value, 0.0)
        } else if value < f64::MIN_POSITIVE {
            (value * TWO_POW_52, -52.0 * LOG_2)
        } else {
            (value, 0.0)
        };
        let bits_hi = (v.to_bits() >> 32) as u32 as i32;
        let e = (bits_hi >> 20) - 1023;
        let k = ((bits_hi as u32) << 12 >> 20) as usize;
        // v·2^−e is 1.mantissa; over the table's 1 + k/2¹², minus 1.
        let mut z = (v * two_pow(-e)) * t.log_x_inv[k] - 1.0;
        z *= 1.0 - z * ((1.0 / 2.0) - z * (1.0 / 3.0));
        h + f64::from(e) * LOG_2 + (t.log_x_log[k] + z)
    } else if value == 0.0 {
        f64::NEG_INFINITY
    } else {
        f64::NAN
    }
}

/// 2^e exactly, for e in the range of normal and subnormal doubles.
fn two_pow(e: i32) -> f64 {
    if e >= -1022 {
        f64::from_bits(((e + 1023).clamp(0, 2046) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (e + 1074).clamp(0, 51))
    }
}

/// JWildfire's x^p: x·x for p = 2, else e^(p·ln x) with Jafama's table logarithm, with
/// Java's rules for negative and zero bases.
pub fn pow(value: f64, power: f64) -> f64 {
    if power == 0.0 {
        return 1.0;
    }
    if power == 1.0 {
        return value;
    }
    if power == 2.0 {
        // JWildfire's copy of Jafama squares directly.
        return value * value;
    }
    if value <= 0.0 {
        // 0: not an integer, 1: even integer, −1: odd integer.
        let info: i32 = if power.abs() >= 2.0 * TWO_POW_52 {
            1
        } else if power.is_nan() {
            return f64::NAN;
        } else if power == power.trunc() {
            if (power % 2.0) == 0.0 { 1 } else { -1 }
        } else {
            0
        };
        if value == 0.0 {
            if power < 0.0 {
                if info < 0 { 1.0 / value } else { f64::INFINITY }
            } else if info < 0 {
                value
            } else {
                0.0
            }
        } else if value == f64::NEG_INFINITY {
            if info < 0 {
                if power < 0.0 { -0.0 } else { f64::NEG_INFINITY }
            } else if power < 0.0 {
                0.0
            } else {
                f64::INFINITY
            }
        } else if info != 0 {
            f64::from(info) * exp(power * log_table(-value))
        } else {
            f64::NAN
        }
    } else {
        exp(power * log_table(value))
    }
}

/// JWildfire's sinh.
pub fn sinh(value: f64) -> f64 {
    let (h, v) = if value < 0.0 {
        (-0.5, -value)
    } else {
        (0.5, value)
    };
    if v < 22.0 {
        if v < TWO_POW_N28 {
            if h < 0.0 { -v } else { v }
        } else {
            let t = expm1(v);
            h * (t + t / (t + 1.0))
        }
    } else if v < EXP_OVERFLOW_LIMIT {
        h * exp(v)
    } else {
        let t = exp(v * 0.5);
        (h * t) * t
    }
}

/// JWildfire's cosh.
pub fn cosh(value: f64) -> f64 {
    let v = value.abs();
    if v < LOG_TWO_POW_27 {
        if v < TWO_POW_N27 {
            1.0
        } else {
            let t = exp(v);
            0.5 * (t + 1.0 / t)
        }
    } else if v < EXP_OVERFLOW_LIMIT {
        0.5 * exp(v)
    } else {
        let t = exp(v * 0.5);
        (0.5 * t) * t
    }
}

/// JWildfire's tanh (`MathLib.tanh`; no variation ported so far needs its exact bits).
#[allow(dead_code)]
pub fn tanh(value: f64) -> f64 {
    let (neg, v) = if value < 0.0 {
        (true, -value)
    } else {
        (false, value)
    };
    let z = if v < 22.0 {
        if v < TWO_POW_N55 {
            return if neg { -v * (1.0 - v) } else { v * (1.0 + v) };
        } else if v >= 1.0 {
            1.0 - 2.0 / (expm1(v + v) + 2.0)
        } else {
            let t = expm1(-(v + v));
            -t / (t + 2.0)
        }
    } else if v.is_nan() {
        f64::NAN
    } else {
        1.0
    };
    if neg { -z } else { z }
}

#[cfg(test)]
#[path = "jwf_math_tests.rs"]
mod tests;
