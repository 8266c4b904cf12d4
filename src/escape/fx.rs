//! Extended-exponent floating point ("floatexp"): an f64 mantissa with its own i32 binary
//! exponent, for the deep-zoom quantities that leave f64's range (view widths of 1e-1000,
//! pixel offsets from the reference, coefficients of long bilinear steps). [`Fx`] is a real
//! number, [`Cx`] a complex number whose parts share one exponent.

// Named methods (not operators) keep each extended operation, several times an f64 one,
// visible in the hot loops.
#![allow(clippy::should_implement_trait)]

use super::complex::C;

/// 2^e as an f64 for e in −1022..=1023.
#[inline]
fn pow2(e: i32) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// x·2^e without intermediate overflow or underflow (underflows to 0 and overflows to ±∞
/// only where the result does).
#[inline]
pub fn ldexp(x: f64, e: i32) -> f64 {
    if (-1022..=1023).contains(&e) {
        x * pow2(e)
    } else if e > 0 {
        let e = e.min(2 * 1023 + 60);
        x * pow2(1023) * pow2((e - 1023).min(1023))
    } else {
        let e = e.max(-2 * 1022 - 60);
        x * pow2(-1022) * pow2((e + 1022).max(-1022))
    }
}

/// (m, e) with x = m·2^e and 0.5 ≤ |m| < 1 (m = x, e = 0 for 0 and non-finite x).
#[inline]
pub fn frexp(x: f64) -> (f64, i32) {
    if x == 0.0 || !x.is_finite() {
        return (x, 0);
    }
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    if exp == 0 {
        let (m, e) = frexp(x * pow2(64));
        return (m, e - 64);
    }
    let m = f64::from_bits((bits & !(0x7ff << 52)) | (1022 << 52));
    (m, exp - 1022)
}

/// A real number m·2^e with an f64 mantissa (0.5 ≤ |m| < 1, or m = 0 with e = 0).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Fx {
    /// The mantissa.
    pub m: f64,
    /// The binary exponent.
    pub e: i32,
}

impl Fx {
    /// Zero.
    pub const ZERO: Fx = Fx { m: 0.0, e: 0 };

    /// m·2^e, normalised.
    pub fn new(m: f64, e: i32) -> Fx {
        let (mm, ee) = frexp(m);
        if mm == 0.0 {
            return Fx::ZERO;
        }
        Fx {
            m: mm,
            e: e.saturating_add(ee),
        }
    }

    /// An f64 (exact).
    pub fn from_f64(v: f64) -> Fx {
        Fx::new(v, 0)
    }

    /// The nearest f64 (0 or ±∞ out of range).
    pub fn to_f64(self) -> f64 {
        ldexp(self.m, self.e)
    }

    /// Neither infinite nor NaN.
    pub fn is_finite(self) -> bool {
        self.m.is_finite()
    }

    /// |x|.
    pub fn abs(self) -> Fx {
        Fx {
            m: self.m.abs(),
            e: self.e,
        }
    }

    /// x = 0.
    pub fn is_zero(self) -> bool {
        self.m == 0.0
    }

    /// x·o.
    pub fn mul(self, o: Fx) -> Fx {
        Fx::new(self.m * o.m, self.e.saturating_add(o.e))
    }

    /// x/o.
    pub fn div(self, o: Fx) -> Fx {
        Fx::new(self.m / o.m, self.e.saturating_sub(o.e))
    }

    /// x·v.
    pub fn scale(self, v: f64) -> Fx {
        Fx::new(self.m * v, self.e)
    }

    /// x + o.
    pub fn add(self, o: Fx) -> Fx {
        if self.m == 0.0 {
            return o;
        }
        if o.m == 0.0 {
            return self;
        }
        if self.e >= o.e {
            Fx::new(self.m + ldexp(o.m, o.e - self.e), self.e)
        } else {
            Fx::new(ldexp(self.m, self.e - o.e) + o.m, o.e)
        }
    }

    /// x − o.
    pub fn sub(self, o: Fx) -> Fx {
        self.add(Fx { m: -o.m, e: o.e })
    }

    /// √x for x ≥ 0.
    pub fn sqrt(self) -> Fx {
        if self.e % 2 == 0 {
            Fx::new(self.m.sqrt(), self.e / 2)
        } else {
            Fx::new((self.m * 2.0).sqrt(), (self.e - 1) / 2)
        }
    }

    /// log₂|x| (−∞ for 0).
    pub fn log2(self) -> f64 {
        self.m.abs().log2() + self.e as f64
    }

    /// log₁₀|x| (−∞ for 0).
    pub fn log10(self) -> f64 {
        self.log2() * std::f64::consts::LOG10_2
    }

    /// self < o for non-negative numbers (both normalised).
    pub fn lt(self, o: Fx) -> bool {
        self.sub(o).m < 0.0
    }

    /// Parse a decimal number of any exponent (`1e-1000`, `-2.5E+40000`); None when it is not
    /// a finite number. The mantissa's first 17 significant digits count.
    pub fn parse(s: &str) -> Option<Fx> {
        let s = s.trim();
        let (mant, exp) = match s.find(['e', 'E']) {
            Some(k) => (&s[..k], s[k + 1..].parse::<i64>().ok()?),
            None => (s, 0),
        };
        let (sign, body) = match mant.as_bytes().first()? {
            b'-' => (-1.0, &mant[1..]),
            b'+' => (1.0, &mant[1..]),
            _ => (1.0, mant),
        };
        let (int, frac) = body.split_once('.').unwrap_or((body, ""));
        if int.is_empty() && frac.is_empty()
            || !int.bytes().chain(frac.bytes()).all(|c| c.is_ascii_digit())
        {
            return None;
        }
        // Significant digits d₁d₂… as an f64 and the decimal exponent of the last one kept.
        let digits = int.bytes().chain(frac.bytes()).skip_while(|&c| c == b'0');
        let lead_zeros_frac = if int.bytes().all(|c| c == b'0') {
            frac.bytes().take_while(|&c| c == b'0').count() as i64
        } else {
            0
        };
        let int_sig = int.trim_start_matches('0').len() as i64;
        let mut m = 0.0f64;
        let mut kept = 0i64;
        for c in digits.take(17) {
            m = m * 10.0 + (c - b'0') as f64;
            kept += 1;
        }
        if m == 0.0 {
            return Some(Fx::ZERO);
        }
        // value = m · 10^(int_sig − lead_zeros_frac − kept + exp)
        let dexp = exp.checked_add(int_sig - lead_zeros_frac - kept)?;
        if dexp.abs() > 400_000_000 {
            return None;
        }
        Some(Fx::from_f64(sign * m).mul(Fx::pow10(dexp)))
    }

    /// 10^k for any k (relative error a few ulps).
    pub fn pow10(k: i64) -> Fx {
        let mut result = Fx::from_f64(1.0);
        let mut base = Fx::from_f64(if k < 0 { 0.1 } else { 10.0 });
        let mut n = k.unsigned_abs();
        // Exact factors for the small part keep common exponents exact.
        while n > 0 {
            if n & 1 == 1 {
                result = result.mul(base);
            }
            base = base.mul(base);
            n >>= 1;
        }
        result
    }
}

impl std::fmt::Display for Fx {
    /// Scientific notation with 6 significant digits (`1.5e-1000`).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.m == 0.0 {
            return write!(f, "0");
        }
        let l = self.log10();
        let mut k = l.floor();
        let mut mant = 10f64.powf(l - k) * self.m.signum();
        if mant.abs() >= 9.999995 {
            mant /= 10.0;
            k += 1.0;
        }
        let p = f.precision().unwrap_or(6).saturating_sub(1);
        let text = format!("{mant:.p$}");
        let text = if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.')
        } else {
            &text
        };
        write!(f, "{text}e{k}")
    }
}

/// A complex number (re + i·im)·2^e whose parts share one exponent, normalised so that the
/// larger part lies in [0.5, 1) (or both are 0 with e = 0).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Cx {
    /// Real part of the mantissa.
    pub re: f64,
    /// Imaginary part of the mantissa.
    pub im: f64,
    /// The shared binary exponent.
    pub e: i32,
}

impl Cx {
    /// Zero.
    pub const ZERO: Cx = Cx {
        re: 0.0,
        im: 0.0,
        e: 0,
    };

    /// (re + i·im)·2^e, normalised.
    #[inline]
    pub fn new(re: f64, im: f64, e: i32) -> Cx {
        let big = re.abs().max(im.abs());
        if big == 0.0 || !big.is_finite() {
            return Cx { re, im, e: 0 };
        }
        let (_, k) = frexp(big);
        let s = ldexp(1.0, -k);
        Cx {
            re: re * s,
            im: im * s,
            e: e.saturating_add(k),
        }
    }

    /// An f64 complex number (exact).
    pub fn from_c(c: C) -> Cx {
        Cx::new(c.re, c.im, 0)
    }

    /// The complex number with parts given as extended reals.
    pub fn from_parts(re: Fx, im: Fx) -> Cx {
        let e = re.e.max(im.e);
        Cx::new(ldexp(re.m, re.e - e), ldexp(im.m, im.e - e), e)
    }

    /// The nearest f64 complex number (parts below f64's range become 0).
    #[inline]
    pub fn to_c(self) -> C {
        let s = ldexp(1.0, self.e.clamp(-1100, 1100));
        if (-1022..=1023).contains(&self.e) {
            C::new(self.re * s, self.im * s)
        } else {
            C::new(ldexp(self.re, self.e), ldexp(self.im, self.e))
        }
    }

    /// z = 0.
    pub fn is_zero(self) -> bool {
        self.re == 0.0 && self.im == 0.0
    }

    /// Both parts finite.
    pub fn is_finite(self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }

    /// z·o.
    #[inline]
    pub fn mul(self, o: Cx) -> Cx {
        Cx::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
            self.e + o.e,
        )
    }

    /// z·o for an f64 complex o.
    #[inline]
    pub fn mul_c(self, o: C) -> Cx {
        Cx::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
            self.e,
        )
    }

    /// z·v.
    #[inline]
    pub fn scale(self, v: f64) -> Cx {
        Cx::new(self.re * v, self.im * v, self.e)
    }

    /// z + o.
    #[inline]
    pub fn add(self, o: Cx) -> Cx {
        if self.is_zero() {
            return o;
        }
        if o.is_zero() {
            return self;
        }
        if self.e >= o.e {
            let s = ldexp(1.0, (o.e - self.e).max(-1100));
            Cx::new(self.re + o.re * s, self.im + o.im * s, self.e)
        } else {
            let s = ldexp(1.0, (self.e - o.e).max(-1100));
            Cx::new(self.re * s + o.re, self.im * s + o.im, o.e)
        }
    }

    /// |z|² as an extended real.
    #[inline]
    pub fn norm2(self) -> Fx {
        Fx::new(
            self.re * self.re + self.im * self.im,
            self.e.saturating_mul(2),
        )
    }

    /// |z| as an extended real.
    pub fn abs(self) -> Fx {
        Fx::new(self.re.hypot(self.im), self.e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extended_numbers_reach_far_beyond_f64_and_round_trip() {
        let w = Fx::parse("1e-1000").unwrap();
        assert!((w.log10() + 1000.0).abs() < 1e-9, "{w:?}");
        assert_eq!(w.to_f64(), 0.0);
        let x = Fx::parse("-2.5E+40000").unwrap();
        assert!(x.m < 0.0 && (x.abs().log10() - 40_000.397_940_008_672).abs() < 1e-6);
        assert!((Fx::parse("0.000123").unwrap().to_f64() / 0.000123 - 1.0).abs() < 1e-15);
        assert_eq!(Fx::parse("1.5").unwrap().to_f64(), 1.5);
        assert_eq!(Fx::parse("0"), Some(Fx::ZERO));
        for bad in [
            "",
            "e5",
            "1e",
            "abc",
            "1.2.3",
            "nan",
            "inf",
            "1e99999999999",
        ] {
            assert!(Fx::parse(bad).is_none(), "{bad}");
        }
        assert_eq!(format!("{}", Fx::parse("1.5e-1000").unwrap()), "1.5e-1000");
        // Arithmetic keeps its precision across the exponent range.
        let a = Fx::parse("3e-700").unwrap();
        let b = Fx::parse("4e-700").unwrap();
        let h = a.mul(a).add(b.mul(b)).sqrt();
        assert!((h.div(Fx::parse("5e-700").unwrap()).to_f64() - 1.0).abs() < 1e-15);
        assert!(a.lt(b) && !b.lt(a));
        let z = Cx::from_parts(a, b.scale(-1.0));
        let p = z.mul(z);
        // (3 − 4i)² = −7 − 24i, times 1e-1400.
        let q = p.abs();
        assert!((q.div(Fx::parse("25e-1400").unwrap()).to_f64() - 1.0).abs() < 1e-14);
        assert_eq!(Cx::from_c(C::new(0.75, -3.0)).to_c(), C::new(0.75, -3.0));
        assert_eq!(ldexp(1.0, -1074), f64::from_bits(1));
        assert_eq!(ldexp(1.0, 1024), f64::INFINITY);
        assert_eq!(frexp(f64::from_bits(1)), (0.5, -1073));
    }
}
