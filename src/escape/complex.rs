//! A minimal complex number for the escape-time families.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// A complex number `re + i·im` in f64.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct C {
    /// Real part.
    pub re: f64,
    /// Imaginary part.
    pub im: f64,
}

impl C {
    /// Zero.
    pub const ZERO: C = C { re: 0.0, im: 0.0 };
    /// One.
    pub const ONE: C = C { re: 1.0, im: 0.0 };
    /// The imaginary unit i.
    pub const I: C = C { re: 0.0, im: 1.0 };

    /// `re + i·im`.
    pub const fn new(re: f64, im: f64) -> C {
        C { re, im }
    }

    /// |z|², the squared modulus.
    pub fn norm2(self) -> f64 {
        self.re * self.re + self.im * self.im
    }

    /// |z|, the modulus.
    pub fn abs(self) -> f64 {
        self.re.hypot(self.im)
    }

    /// The complex conjugate `re − i·im`.
    pub fn conj(self) -> C {
        C::new(self.re, -self.im)
    }

    /// Whether both parts are finite (neither NaN nor infinite).
    pub fn is_finite(self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }

    /// z^m for a small integer m ≥ 0 by repeated multiplication.
    pub fn powi(self, m: u32) -> C {
        let mut r = C::ONE;
        for _ in 0..m {
            r = r * self;
        }
        r
    }

    /// r·e^(iθ): the number with modulus `r` and argument `theta` (radians).
    pub fn from_polar(r: f64, theta: f64) -> C {
        let (s, c) = theta.sin_cos();
        C::new(r * c, r * s)
    }
}

impl Add for C {
    type Output = C;
    fn add(self, o: C) -> C {
        C::new(self.re + o.re, self.im + o.im)
    }
}

impl Sub for C {
    type Output = C;
    fn sub(self, o: C) -> C {
        C::new(self.re - o.re, self.im - o.im)
    }
}

impl Mul for C {
    type Output = C;
    fn mul(self, o: C) -> C {
        C::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
}

impl Mul<f64> for C {
    type Output = C;
    fn mul(self, k: f64) -> C {
        C::new(self.re * k, self.im * k)
    }
}

impl Div for C {
    type Output = C;
    fn div(self, o: C) -> C {
        let d = o.norm2();
        C::new(
            (self.re * o.re + self.im * o.im) / d,
            (self.im * o.re - self.re * o.im) / d,
        )
    }
}

impl Neg for C {
    type Output = C;
    fn neg(self) -> C {
        C::new(-self.re, -self.im)
    }
}
