//! Complex numbers with C99 semantics (signed zeros, branch cuts, division by zero and
//! infinities as C's `<complex.h>` handles them, Annex G), as the inverse hyperbolic variations
//! need them.

use std::f64::consts::PI;

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
