//! The centre of a view to any number of decimal digits: each coordinate is an integer over
//! 10^digits, so a location pasted or read with thousands of digits is kept exactly and
//! written back digit for digit. Deep zoom converts it to binary fixed point at the precision
//! the zoom needs ([`Centre::to_binary`]); pans and zooms add offsets rounded to the digits
//! the view needs, which grow as it zooms in.

use dashu_int::{IBig, UBig};

use super::fx::{Fx, ldexp};

/// Most digits after the decimal point a centre may have (a width of about 1e-20000).
pub const MAX_DIGITS: u32 = 20_000;
/// Largest magnitude of a centre coordinate.
const MAX_ABS: f64 = 1e15;

/// A point (x, y) = (X, Y) / 10^digits.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Centre {
    x: IBig,
    y: IBig,
    digits: u32,
}

fn pow10(d: u32) -> UBig {
    UBig::from(10u8).pow(d as usize)
}

/// round(a / b) for b > 0, halves away from zero.
fn div_round(a: IBig, b: &UBig) -> IBig {
    let b = IBig::from(b.clone());
    let half = &b / IBig::from(2u8);
    if a < IBig::ZERO {
        -((-a + half) / b)
    } else {
        (a + half) / b
    }
}

/// A big integer as an extended real (relative error below 2^-60).
pub fn ibig_to_fx(v: &IBig) -> Fx {
    use dashu_base::BitTest;
    let len = v.bit_len();
    if len <= 120 {
        return Fx::from_f64(v.to_f64().value());
    }
    let shift = len - 120;
    let top = v >> shift;
    Fx::new(top.to_f64().value(), shift as i32)
}

/// An f64 as an integer times 10^digits, rounded (exact arithmetic throughout).
fn f64_scaled(v: Fx, digits: u32) -> IBig {
    if v.is_zero() || !v.is_finite() {
        return IBig::ZERO;
    }
    // v = M·2^k with M an integer of 53 bits.
    let m = (v.m * (1u64 << 53) as f64) as i64;
    let k = v.e as i64 - 53;
    let n = IBig::from(m) * IBig::from(pow10(digits));
    if k >= 0 {
        n << k as usize
    } else if -k > (digits as i64 * 4 + 4200) {
        IBig::ZERO
    } else {
        div_round(n, &(UBig::ONE << (-k) as usize))
    }
}

/// Parse one decimal coordinate: (X, D) with value X / 10^D, D ≥ 0.
fn parse_coord(s: &str) -> Result<(IBig, u32), String> {
    let s = s.trim();
    let (mant, exp) = match s.find(['e', 'E']) {
        Some(k) => (
            &s[..k],
            s[k + 1..]
                .parse::<i64>()
                .map_err(|_| format!("'{s}' is not a number"))?,
        ),
        None => (s, 0),
    };
    let (neg, body) = match mant.as_bytes().first() {
        Some(b'-') => (true, &mant[1..]),
        Some(b'+') => (false, &mant[1..]),
        _ => (false, mant),
    };
    let (int, frac) = body.split_once('.').unwrap_or((body, ""));
    if int.is_empty() && frac.is_empty()
        || !int.bytes().chain(frac.bytes()).all(|c| c.is_ascii_digit())
    {
        return Err(format!("'{s}' is not a number"));
    }
    let frac_digits = frac.len() as i64 - exp;
    let sig = int.trim_start_matches('0').len() as i64 + frac.len() as i64;
    if frac_digits > MAX_DIGITS as i64 || sig > MAX_DIGITS as i64 + 20 {
        return Err(format!(
            "a coordinate with more than {MAX_DIGITS} digits after the point \
             (a view narrower than 1e-{MAX_DIGITS}) is not supported"
        ));
    }
    let text: String = int.chars().chain(frac.chars()).collect();
    let text = text.trim_start_matches('0');
    let mut v: IBig = if text.is_empty() {
        IBig::ZERO
    } else {
        text.parse::<UBig>()
            .map_err(|_| format!("'{s}' is not a number"))?
            .into()
    };
    let digits = if frac_digits < 0 {
        if frac_digits < -20 && !v.is_zero() {
            return Err(format!("'{s}' is too large for a centre"));
        }
        v *= IBig::from(pow10((-frac_digits) as u32));
        0
    } else {
        frac_digits as u32
    };
    if ibig_to_fx(&v)
        .mul(Fx::pow10(-(digits as i64)))
        .abs()
        .to_f64()
        > MAX_ABS
    {
        return Err(format!("'{s}' is too large for a centre (at most 1e15)"));
    }
    Ok((if neg { -v } else { v }, digits))
}

fn format_coord(v: &IBig, digits: u32) -> String {
    let neg = *v < IBig::ZERO;
    let s = if neg { (-v).to_string() } else { v.to_string() };
    let d = digits as usize;
    let (int, frac) = if s.len() > d {
        (s[..s.len() - d].to_string(), s[s.len() - d..].to_string())
    } else {
        ("0".to_string(), format!("{}{s}", "0".repeat(d - s.len())))
    };
    let frac = frac.trim_end_matches('0');
    let sign = if neg && (int != "0" || !frac.is_empty()) {
        "-"
    } else {
        ""
    };
    if frac.is_empty() {
        format!("{sign}{int}")
    } else {
        format!("{sign}{int}.{frac}")
    }
}

impl Centre {
    /// The point given by two f64 (their shortest decimal forms, so that printing gives them
    /// back as typed).
    pub fn from_f64(v: [f64; 2]) -> Centre {
        let fmt = |x: f64| {
            if x.is_finite() {
                format!("{x:e}")
            } else {
                "0".to_string()
            }
        };
        Centre::parse(&fmt(v[0]), &fmt(v[1])).unwrap_or(Centre {
            x: IBig::ZERO,
            y: IBig::ZERO,
            digits: 0,
        })
    }

    /// The point given by two f64, exactly (every binary digit as a decimal one).
    pub fn from_f64_exact(v: [f64; 2]) -> Centre {
        let one = |x: f64| -> (IBig, u32) {
            if x == 0.0 || !x.is_finite() {
                return (IBig::ZERO, 0);
            }
            let (m, e) = super::fx::frexp(x);
            let m = IBig::from((m * (1u64 << 53) as f64) as i64);
            let k = e - 53;
            if k >= 0 {
                (m << k as usize, 0)
            } else {
                (
                    m * IBig::from(UBig::from(5u8).pow((-k) as usize)),
                    (-k) as u32,
                )
            }
        };
        let ((x, dx), (y, dy)) = (one(v[0]), one(v[1]));
        let d = dx.max(dy);
        Centre {
            x: x * IBig::from(pow10(d - dx)),
            y: y * IBig::from(pow10(d - dy)),
            digits: d,
        }
    }

    /// Parse decimal coordinates (`-0.75`, `1.25e-3`, thousands of digits).
    pub fn parse(x: &str, y: &str) -> Result<Centre, String> {
        let (x, dx) = parse_coord(x)?;
        let (y, dy) = parse_coord(y)?;
        let d = dx.max(dy);
        Ok(Centre {
            x: x * IBig::from(pow10(d - dx)),
            y: y * IBig::from(pow10(d - dy)),
            digits: d,
        })
    }

    /// Digits after the decimal point.
    pub fn digits(&self) -> u32 {
        self.digits
    }

    /// The point with at least `d` digits after the decimal point (exact).
    pub fn with_digits(&self, d: u32) -> Centre {
        let d = d.min(MAX_DIGITS);
        if d <= self.digits {
            return self.clone();
        }
        let k = IBig::from(pow10(d - self.digits));
        Centre {
            x: &self.x * &k,
            y: &self.y * &k,
            digits: d,
        }
    }

    /// The point rounded to `d` digits after the point (when it has more).
    pub fn rounded(&self, d: u32) -> Centre {
        if d >= self.digits {
            return self.clone();
        }
        let k = pow10(self.digits - d);
        Centre {
            x: div_round(self.x.clone(), &k),
            y: div_round(self.y.clone(), &k),
            digits: d,
        }
    }

    /// The coordinates as decimal text (trailing zeros dropped).
    pub fn format(&self) -> [String; 2] {
        [
            format_coord(&self.x, self.digits),
            format_coord(&self.y, self.digits),
        ]
    }

    /// The nearest f64 coordinates.
    pub fn to_f64(&self) -> [f64; 2] {
        let p = pow10(self.digits);
        let one = |v: &IBig| {
            // round(v·2^k / 10^d) with about 128 significant bits, then scaled back.
            use dashu_base::BitTest;
            let k = (p.bit_len() as i64 + 128 - v.bit_len() as i64).max(0) as usize;
            let q = div_round(v << k, &p);
            let f = ibig_to_fx(&q);
            ldexp(f.m, f.e - k as i32)
        };
        [one(&self.x), one(&self.y)]
    }

    /// The coordinates in binary fixed point: round(x·2^bits) and round(y·2^bits).
    pub fn to_binary(&self, bits: u32) -> [IBig; 2] {
        let p = pow10(self.digits);
        [
            div_round(&self.x << bits as usize, &p),
            div_round(&self.y << bits as usize, &p),
        ]
    }

    /// The point moved by (dx, dy), rounded to its digits.
    pub fn shifted(&self, dx: Fx, dy: Fx) -> Centre {
        Centre {
            x: &self.x + f64_scaled(dx, self.digits),
            y: &self.y + f64_scaled(dy, self.digits),
            digits: self.digits,
        }
    }

    /// other − self as extended reals.
    pub fn offset_to(&self, other: &Centre) -> [Fx; 2] {
        let d = self.digits.max(other.digits);
        let (a, b) = (self.with_digits(d), other.with_digits(d));
        let s = Fx::pow10(-(d as i64));
        [
            ibig_to_fx(&(&b.x - &a.x)).mul(s),
            ibig_to_fx(&(&b.y - &a.y)).mul(s),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centres_keep_every_digit_and_convert_exactly() {
        let long = format!("-1.{}", "0123456789".repeat(150));
        let c = Centre::parse(&long, "2.5e-3").unwrap();
        assert_eq!(c.digits(), 1500);
        assert_eq!(c.format(), [long.clone(), "0.0025".to_string()]);
        assert_eq!(c.to_f64(), [-1.0123456789012346, 0.0025]);
        // f64 centres print as typed.
        let f = Centre::from_f64([-0.7436438870371587, 0.13182590420531198]);
        assert_eq!(
            f.format(),
            ["-0.7436438870371587", "0.13182590420531198"].map(String::from)
        );
        assert_eq!(f.to_f64(), [-0.7436438870371587, 0.13182590420531198]);
        // Binary fixed point: 0.0025·2^20 = 2621.44 → 2621.
        assert_eq!(c.to_binary(20)[1], IBig::from(2621));
        // A shift of 1e-1400 at 1500 digits is exact, and the offset between the two reads it
        // back.
        let tiny = Fx::parse("3e-1400").unwrap();
        let d = c.shifted(tiny, Fx::ZERO);
        let [ox, oy] = c.offset_to(&d);
        assert!((ox.div(tiny).to_f64() - 1.0).abs() < 1e-12 && oy.is_zero());
        assert!(c.with_digits(1600).format()[0] == long);
        assert_eq!(
            Centre::parse("0.123456", "0").unwrap().rounded(3).format()[0],
            "0.123"
        );
        // Bad input.
        assert!(Centre::parse("abc", "0").is_err());
        assert!(Centre::parse(&format!("0.{}", "1".repeat(20_001)), "0").is_err());
        assert!(Centre::parse("1e30", "0").is_err());
        assert!(Centre::parse("1e-20001", "0").is_err());
    }
}
