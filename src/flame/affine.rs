//! Affine maps of the plane, as flame xforms use them.

/// An affine map in the Fractint/Fraktalai letters: x' = a·x + b·y + e, y' = c·x + d·y + f.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Affine {
    /// Coefficient of x in x'.
    pub a: f64,
    /// Coefficient of y in x'.
    pub b: f64,
    /// Coefficient of x in y'.
    pub c: f64,
    /// Coefficient of y in y'.
    pub d: f64,
    /// Translation in x.
    pub e: f64,
    /// Translation in y.
    pub f: f64,
}

impl Default for Affine {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Affine {
    /// The map that changes nothing.
    pub const IDENTITY: Affine = Affine {
        a: 1.0,
        b: 0.0,
        c: 0.0,
        d: 1.0,
        e: 0.0,
        f: 0.0,
    };

    /// The map with these letters, in the order a b c d e f.
    pub const fn new(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64) -> Self {
        Self { a, b, c, d, e, f }
    }

    /// The image (x', y') of (x, y).
    #[inline(always)]
    pub fn apply(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.a * x + self.b * y + self.e,
            self.c * x + self.d * y + self.f,
        )
    }

    /// Whether this is exactly the identity.
    pub fn is_identity(&self) -> bool {
        *self == Self::IDENTITY
    }

    /// Signed area ratio a·d − b·c.
    pub fn det(&self) -> f64 {
        self.a * self.d - self.b * self.c
    }

    /// flam3 `coefs` order: c00 c01 c10 c11 c20 c21 = a c b d e f.
    pub fn to_coefs(&self) -> [f64; 6] {
        [self.a, self.c, self.b, self.d, self.e, self.f]
    }

    /// From flam3's `coefs` order a c b d e f (the inverse of [`Affine::to_coefs`]).
    pub fn from_coefs(v: [f64; 6]) -> Self {
        Self::new(v[0], v[2], v[1], v[3], v[4], v[5])
    }

    /// self ∘ other (apply `other` first).
    pub fn compose(&self, other: &Affine) -> Affine {
        Affine {
            a: self.a * other.a + self.b * other.c,
            b: self.a * other.b + self.b * other.d,
            c: self.c * other.a + self.d * other.c,
            d: self.c * other.b + self.d * other.d,
            e: self.a * other.e + self.b * other.f + self.e,
            f: self.c * other.e + self.d * other.f + self.f,
        }
    }

    /// The editor triangle (O′, X′, Y′): the images of O = (0, 0), X = (1, 0) and Y = (0, −1)
    /// (y points down on screen, so Y appears above O, as in Apophysis).
    pub fn triangle(&self) -> [[f64; 2]; 3] {
        [
            [self.e, self.f],
            [self.a + self.e, self.c + self.f],
            [self.e - self.b, self.f - self.d],
        ]
    }

    /// Coefficients from an editor triangle (O′, X′, Y′).
    pub fn from_triangle(t: [[f64; 2]; 3]) -> Self {
        let [o, x, y] = t;
        Affine {
            a: x[0] - o[0],
            c: x[1] - o[1],
            b: o[0] - y[0],
            d: o[1] - y[1],
            e: o[0],
            f: o[1],
        }
    }

    /// Largest singular value of the linear part (contractivity).
    pub fn max_singular_value(&self) -> f64 {
        let (a, b, c, d) = (self.a, self.b, self.c, self.d);
        let s1 = a * a + b * b + c * c + d * d;
        let det = a * d - b * c;
        let disc = (s1 * s1 - 4.0 * det * det).max(0.0).sqrt();
        ((s1 + disc) / 2.0).sqrt()
    }
}
