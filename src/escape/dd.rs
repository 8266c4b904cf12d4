//! Double-double numbers: an unevaluated sum hi + lo of two f64 with |lo| ≤ ½ ulp(hi), about
//! 106 bits (31 decimal digits) of precision. The deep-zoom view keeps its centre in this
//! form and computes the reference orbit with it (Dekker/Knuth error-free transformations).

use std::ops::{Add, Div, Mul, Neg, Sub};

#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Dd {
    pub hi: f64,
    pub lo: f64,
}

/// a + b = s + e exactly.
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// a + b = s + e exactly, for |a| ≥ |b|.
#[inline]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// a·b = p + e exactly.
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl Dd {
    pub const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };

    pub fn new(hi: f64, lo: f64) -> Dd {
        let (hi, lo) = two_sum(hi, lo);
        Dd { hi, lo }
    }

    pub fn from_f64(v: f64) -> Dd {
        Dd { hi: v, lo: 0.0 }
    }

    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    pub fn is_finite(self) -> bool {
        self.hi.is_finite() && self.lo.is_finite()
    }

    /// self · v for an f64 v.
    pub fn mul_f64(self, v: f64) -> Dd {
        let (p, e) = two_prod(self.hi, v);
        let (hi, lo) = quick_two_sum(p, e + self.lo * v);
        Dd { hi, lo }
    }

    /// 10^k (k may be negative), accurate to a few units in the last place.
    pub fn pow10(k: i32) -> Dd {
        let mut p = Dd::from_f64(1.0);
        for _ in 0..k.unsigned_abs() {
            p = p.mul_f64(10.0);
        }
        if k < 0 { Dd::from_f64(1.0) / p } else { p }
    }

    /// Parse a decimal number (`[+-]digits[.digits][e[+-]digits]`) to double-double
    /// precision; None when it is not a finite number.
    pub fn parse(s: &str) -> Option<Dd> {
        let s = s.trim();
        let (neg, body) = match s.as_bytes().first()? {
            b'-' => (true, &s[1..]),
            b'+' => (false, &s[1..]),
            _ => (false, s),
        };
        let (mant, exp) = match body.find(['e', 'E']) {
            Some(k) => (&body[..k], body[k + 1..].parse::<i32>().ok()?),
            None => (body, 0),
        };
        let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
        if int.is_empty() && frac.is_empty()
            || !int.bytes().chain(frac.bytes()).all(|c| c.is_ascii_digit())
        {
            return None;
        }
        // Up to 32 significant digits are exact in a double-double integer.
        let mut acc = Dd::ZERO;
        let mut scale = exp;
        let mut sig = 0;
        for (k, c) in int.bytes().chain(frac.bytes()).enumerate() {
            let d = (c - b'0') as f64;
            let fraction = k >= int.len();
            if sig >= 32 {
                // Digits past the precision are dropped (integer ones still count).
                if !fraction {
                    scale = scale.checked_add(1)?;
                }
                continue;
            }
            if acc.hi != 0.0 || d != 0.0 {
                sig += 1;
            }
            acc = acc.mul_f64(10.0) + Dd::from_f64(d);
            if fraction {
                scale = scale.checked_sub(1)?;
            }
        }
        if !(-400..=400).contains(&scale) {
            return if acc.hi == 0.0 || scale < 0 {
                Some(Dd::ZERO)
            } else {
                None
            };
        }
        let v = if scale >= 0 {
            acc * Dd::pow10(scale)
        } else {
            acc / Dd::pow10(-scale)
        };
        let v = if neg { -v } else { v };
        v.is_finite().then_some(v)
    }
}

impl std::fmt::Display for Dd {
    /// Up to 32 significant digits (trailing zeros dropped), plain for moderate exponents and
    /// with an exponent otherwise; [`Dd::parse`] reads it back.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let v = *self;
        if v.hi == 0.0 || !v.is_finite() {
            return write!(f, "{}", v.hi);
        }
        let neg = v.hi < 0.0;
        let x = if neg { -v } else { v };
        let mut e = x.hi.abs().log10().floor() as i32;
        let mut y = x / Dd::pow10(e);
        if y.hi >= 10.0 {
            y = y / Dd::from_f64(10.0);
            e += 1;
        } else if y.hi < 1.0 {
            y = y.mul_f64(10.0);
            e -= 1;
        }
        let mut digits = Vec::with_capacity(32);
        for _ in 0..32 {
            let d = y.hi.floor().clamp(0.0, 9.0);
            digits.push(b'0' + d as u8);
            y = (y - Dd::from_f64(d)).mul_f64(10.0);
        }
        while digits.len() > 1 && digits.last() == Some(&b'0') {
            digits.pop();
        }
        let ds = String::from_utf8(digits).unwrap_or_default();
        let sign = if neg { "-" } else { "" };
        if (-7..0).contains(&e) {
            write!(f, "{sign}0.{}{ds}", "0".repeat((-e - 1) as usize))
        } else if (0..16).contains(&e) && ds.len() as i32 > e + 1 {
            let (a, b) = ds.split_at(e as usize + 1);
            write!(f, "{sign}{a}.{b}")
        } else if (0..16).contains(&e) && ds.len() as i32 == e + 1 {
            write!(f, "{sign}{ds}")
        } else {
            let (a, b) = ds.split_at(1);
            if b.is_empty() {
                write!(f, "{sign}{a}e{e}")
            } else {
                write!(f, "{sign}{a}.{b}e{e}")
            }
        }
    }
}

impl Add for Dd {
    type Output = Dd;
    fn add(self, b: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, b.hi);
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = quick_two_sum(s, e + t);
        let (hi, lo) = quick_two_sum(s, e + f);
        Dd { hi, lo }
    }
}

impl Sub for Dd {
    type Output = Dd;
    fn sub(self, b: Dd) -> Dd {
        self + (-b)
    }
}

impl Neg for Dd {
    type Output = Dd;
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Div for Dd {
    type Output = Dd;
    fn div(self, b: Dd) -> Dd {
        let q1 = self.hi / b.hi;
        let r = self - b.mul_f64(q1);
        let q2 = r.hi / b.hi;
        let r = r - b.mul_f64(q2);
        let q3 = r.hi / b.hi;
        let (hi, lo) = quick_two_sum(q1, q2);
        Dd { hi, lo } + Dd::from_f64(q3)
    }
}

impl Mul for Dd {
    type Output = Dd;
    fn mul(self, b: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, b.hi);
        let (hi, lo) = quick_two_sum(p, e + (self.hi * b.lo + self.lo * b.hi));
        Dd { hi, lo }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_and_products_keep_what_f64_loses() {
        // 1 + 2^-80 − 1 = 2^-80 exactly.
        let tiny = 2f64.powi(-80);
        let a = Dd::from_f64(1.0) + Dd::from_f64(tiny);
        assert_eq!((a - Dd::from_f64(1.0)).to_f64(), tiny);
        // (1 + 2^-60)² = 1 + 2^-59 + 2^-120: the 2^-59 survives.
        let b = Dd::from_f64(1.0) + Dd::from_f64(2f64.powi(-60));
        let sq = b * b - Dd::from_f64(1.0);
        assert_eq!(sq.hi, 2f64.powi(-59));
        // Division: 1/3 · 3 = 1 to ~1e-32.
        let third = Dd::from_f64(1.0) / Dd::from_f64(3.0);
        let back = third.mul_f64(3.0) - Dd::from_f64(1.0);
        assert!(back.to_f64().abs() < 1e-31, "{back:?}");
    }

    #[test]
    fn prints_what_it_parses() {
        for s in [
            "-0.743643887037158704752191506114774",
            "0.131825904205311970493132056385139",
            "1.25",
            "-3",
            "0.000123456789012345678901234567891",
            "1.5e-20",
            "123456789012345678.5",
        ] {
            let d = Dd::parse(s).unwrap();
            let t = d.to_string();
            let back = Dd::parse(&t).unwrap();
            let rel = ((back - d).to_f64() / d.to_f64()).abs();
            assert!(rel < 1e-30, "{s} → {t}: {rel:e}");
        }
        assert_eq!(Dd::parse("1.25").unwrap().to_string(), "1.25");
        assert_eq!(Dd::parse("-3").unwrap().to_string(), "-3");
        assert_eq!(Dd::parse("0.005").unwrap().to_string(), "0.005");
        assert_eq!(Dd::parse("1.5e-20").unwrap().to_string(), "1.5e-20");
        assert_eq!(Dd::ZERO.to_string(), "0");
    }

    #[test]
    fn parses_thirty_digits() {
        let s = "-0.743643887037158704752191506114774";
        let d = Dd::parse(s).unwrap();
        assert_eq!(d.hi, -0.7436438870371587);
        // The low part carries the digits past f64: compare with the exact difference
        // −0.743643887037158704752191506114774 − (−0.7436438870371587047521915061147740…)
        let rest = Dd::parse("-0.000000000000000004752191506114774").unwrap();
        let hi_exact = Dd::parse("-0.7436438870371587").unwrap();
        let diff = (d - hi_exact - rest).to_f64();
        assert!(diff.abs() < 1e-31, "{diff:e}");
        assert_eq!(Dd::parse("1.5e3").unwrap().to_f64(), 1500.0);
        assert_eq!(Dd::parse("+.25").unwrap().to_f64(), 0.25);
        assert_eq!(Dd::parse("7.").unwrap().to_f64(), 7.0);
        assert_eq!(Dd::parse("1e-500").unwrap(), Dd::ZERO);
        for bad in [
            "", "-", ".", "1.2.3", "nan", "inf", "1e", "0x10", "1,5", "1e999",
        ] {
            assert!(Dd::parse(bad).is_none(), "{bad}");
        }
        // A power of ten and a value given with more digits than a double-double holds.
        let p = Dd::pow10(-20);
        assert!((p.mul_f64(1e20) - Dd::from_f64(1.0)).to_f64().abs() < 1e-30);
        let long = Dd::parse("0.1234567890123456789012345678901234567890").unwrap();
        assert!(
            (long - Dd::parse("0.12345678901234567890123456789012").unwrap())
                .to_f64()
                .abs()
                < 1e-31
        );
    }
}
