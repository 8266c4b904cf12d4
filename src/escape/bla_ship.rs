//! Bilinear approximation of perturbed Burning Ship orbits. The ship's step is not
//! holomorphic, so a run of l iterations from reference index m maps the difference
//! δ = (x, y) and the pixel's offset δc by real 2×2 matrices:
//!
//! ```text
//! δ(m + l) = A·δ(m) + B·δc,      valid while |δ(m)| < R.
//! ```
//!
//! One step around Z = X + iY: while X + x keeps the sign of X and Y + y that of Y, the fold
//! |X + x|·|Y + y| = s·(X + x)(Y + y) with s = sgn(XY) (Claude Heiland-Allen, "At the Helm of
//! the Burning Ship", EVA 2019: the perturbed series takes the branch sgn(XY) and is valid
//! in a region that crosses no axis), so
//!
//! ```text
//! x' = 2X·x − 2Y·y + (x² − y²) + Re δc,     y' = 2s·(Y·x + X·y) + 2s·x·y + Im δc,
//! ```
//!
//! A = 2·[[X, −Y], [sY, sX]], B = I (the Mandelbrot kind; 0 without δc). Both singular
//! values of A are 2|Z| and the dropped terms (x² − y², 2s·xy) have size |δ|², so they stay
//! below ε of the linear ones while |δ| < 2ε|Z| (the criterion of the z² table, [`super::bla`]);
//! the signs hold while |x| < |X| and |y| < |Y|, which |δ| < min(|X|, |Y|) ensures:
//! R = min(2ε|Z|, |X|, |Y|). (Fractalshades' `numba_make_BLA_BS` takes ε·min(|X|, |Y|), which
//! is smaller wherever |X| and |Y| are of the same size.) Two steps x then y merge into
//! A = A_y·A_x, B = A_y·B_x + B_y, R = min(R_x, max(0, (R_y − ‖B_x‖·|δc|max) / ‖A_x‖)), with
//! ‖·‖ the spectral norm (the largest stretch of a vector) and |δc|max the largest pixel
//! offset of the view. The table's layout and search are those of [`super::bla::Bla`].

use super::complex::C;
use super::fx::{Cx, Fx, frexp, ldexp};

/// A real 2×2 matrix [[a, b], [c, d]]·2^e whose entries share one exponent, normalised so
/// that the largest entry lies in [0.5, 1) (or all are 0 with e = 0).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Mx {
    /// a, b, c, d (row by row).
    pub m: [f64; 4],
    pub e: i32,
}

impl Mx {
    /// The matrix m·2^e, normalised.
    pub fn new(m: [f64; 4], e: i32) -> Mx {
        let big = m.iter().fold(0.0f64, |b, v| b.max(v.abs()));
        if big == 0.0 || !big.is_finite() {
            return Mx { m, e: 0 };
        }
        let (_, k) = frexp(big);
        let s = ldexp(1.0, -k);
        Mx {
            m: m.map(|v| v * s),
            e: e.saturating_add(k),
        }
    }

    /// The identity.
    pub fn identity() -> Mx {
        Mx::new([1.0, 0.0, 0.0, 1.0], 0)
    }

    /// All entries 0.
    pub fn is_zero(&self) -> bool {
        self.m.iter().all(|v| *v == 0.0)
    }

    /// self·o.
    pub fn mul(&self, o: &Mx) -> Mx {
        let [a, b, c, d] = self.m;
        let [p, q, r, s] = o.m;
        Mx::new(
            [a * p + b * r, a * q + b * s, c * p + d * r, c * q + d * s],
            self.e.saturating_add(o.e),
        )
    }

    /// self + o.
    pub fn add(&self, o: &Mx) -> Mx {
        if self.is_zero() {
            return *o;
        }
        if o.is_zero() {
            return *self;
        }
        let e = self.e.max(o.e);
        let (x, y) = (self.e - e, o.e - e);
        let mut m = [0.0; 4];
        for (k, v) in m.iter_mut().enumerate() {
            *v = ldexp(self.m[k], x) + ldexp(o.m[k], y);
        }
        Mx::new(m, e)
    }

    /// self·v.
    pub fn apply(&self, v: Cx) -> Cx {
        let [a, b, c, d] = self.m;
        Cx::new(
            a * v.re + b * v.im,
            c * v.re + d * v.im,
            self.e.saturating_add(v.e),
        )
    }

    /// The spectral norm (largest singular value): for F² the sum of the squared entries and
    /// D the determinant, σ² = (F² + √(F⁴ − 4D²)) / 2.
    pub fn norm(&self) -> Fx {
        let [a, b, c, d] = self.m;
        let f2 = a * a + b * b + c * c + d * d;
        let det = a * d - b * c;
        let s2 = 0.5 * (f2 + (f2 * f2 - 4.0 * det * det).max(0.0).sqrt());
        Fx::new(s2.sqrt(), self.e)
    }

    /// The entries as f64 (0 or ±∞ out of range).
    pub fn to_f64(self) -> [f64; 4] {
        self.m.map(|v| ldexp(v, self.e))
    }

    /// Every entry has an f64 value well within range.
    fn in_f64(&self) -> bool {
        self.is_zero() || (-1000..1000).contains(&self.e)
    }
}

/// A merged step.
#[derive(Clone, Copy, Debug)]
pub struct ShipStep {
    pub a: Mx,
    pub b: Mx,
    /// Validity radius (of |δ|), and the same as f64 (0 below f64's range).
    pub r: Fx,
    pub r64: f64,
    /// Iterations skipped.
    pub len: u32,
}

/// A step's coefficients in f64: A's entries, then B's.
pub type Coeffs = [f64; 8];

/// The bilinear steps of one Burning Ship reference orbit.
#[derive(Clone, Debug, Default)]
pub struct ShipBla {
    /// levels[k − 1][j]: the step of up to 2^k iterations from m = 1 + j·2^k.
    levels: Vec<Vec<ShipStep>>,
    /// Per level the radii in f64 (0 where A or B leave f64's range) apart from the
    /// coefficients, as in [`super::bla::Bla`].
    radii: Vec<Vec<f64>>,
    coeffs: Vec<Vec<Coeffs>>,
    /// The radius of the first level by starting index (0 at even indices).
    first: Vec<f64>,
    /// The orbit's last index (steps end there).
    last: usize,
}

/// Bytes the table of an orbit of `len` points takes (about one merged step per point, its
/// f64 copy and the first level's radii by index).
pub fn table_bytes(len: u64) -> u64 {
    len * (std::mem::size_of::<ShipStep>() + std::mem::size_of::<Coeffs>() + 16) as u64
}

fn merge(x: &ShipStep, y: &ShipStep, dc_max: Fx) -> ShipStep {
    let a = y.a.mul(&x.a);
    let b = y.a.mul(&x.b).add(&y.b);
    let ax = x.a.norm();
    let ry = y.r.sub(x.b.norm().mul(dc_max));
    let ry = if ry.m > 0.0 && !ax.is_zero() {
        ry.div(ax)
    } else {
        Fx::ZERO
    };
    let r = if ry.lt(x.r) { ry } else { x.r };
    ShipStep {
        a,
        b,
        r,
        r64: r.to_f64(),
        len: x.len + y.len,
    }
}

/// The single step around reference point z (see the module's notes).
fn single(z: C, with_c: bool, eps: f64) -> ShipStep {
    let (x, y) = (z.re, z.im);
    let s = if x * y < 0.0 { -1.0 } else { 1.0 };
    let r = (2.0 * eps * z.abs()).min(x.abs()).min(y.abs());
    let r = if r.is_finite() { r } else { 0.0 };
    let r = Fx::from_f64(r);
    ShipStep {
        a: Mx::new([2.0 * x, -2.0 * y, 2.0 * s * y, 2.0 * s * x], 0),
        b: if with_c {
            Mx::identity()
        } else {
            Mx::default()
        },
        r,
        r64: r.to_f64(),
        len: 1,
    }
}

impl ShipBla {
    /// The table for the Burning Ship orbit `z`, pixels within `dc_max` of the reference,
    /// with (`with_c`) or without a δc term, dropping non-linear terms below `eps` relative
    /// to the linear ones.
    pub fn new(z: &[C], dc_max: Fx, with_c: bool, eps: f64) -> ShipBla {
        let last = z.len().saturating_sub(1);
        if last < 3 {
            return ShipBla::default();
        }
        let one = |m: usize| single(z[m], with_c, eps);
        // Single steps from m = 1 to last − 1 (the last lands on the final point).
        let levels = super::bla::levels(last, one, |x, y| merge(x, y, dc_max));
        let radii: Vec<Vec<f64>> = levels
            .iter()
            .map(|l| {
                l.iter()
                    .map(|st| {
                        if st.a.in_f64() && st.b.in_f64() {
                            st.r64
                        } else {
                            0.0
                        }
                    })
                    .collect()
            })
            .collect();
        let coeffs = levels
            .iter()
            .map(|l| {
                l.iter()
                    .map(|st| {
                        let ([a0, a1, a2, a3], [b0, b1, b2, b3]) = (st.a.to_f64(), st.b.to_f64());
                        [a0, a1, a2, a3, b0, b1, b2, b3]
                    })
                    .collect()
            })
            .collect();
        let first = super::bla::first_radii(last, &radii);
        ShipBla {
            levels,
            radii,
            coeffs,
            first,
            last,
        }
    }

    /// The longest step from reference index m admitting |δ| = `d` and at most `room`
    /// iterations (the search of [`super::bla::Bla::find`]).
    #[inline]
    pub fn find(&self, m: usize, d: Fx, room: u32) -> Option<&ShipStep> {
        super::bla::climb(&self.levels, m, |st| st.len <= room && d.lt(st.r))
    }

    /// As [`ShipBla::find`] for a difference in f64's range, measured by |re| + |im| (at
    /// least |δ|): the oracle of [`ShipBla::find_plain`] in tests.
    #[cfg(test)]
    pub fn find_f64(&self, m: usize, d: C, room: u32) -> Option<&ShipStep> {
        let d = d.re.abs() + d.im.abs();
        super::bla::climb(&self.levels, m, |st| d < st.r64 && st.len <= room)
    }

    /// As [`ShipBla::find_f64`] with the coefficients in f64 (A's and B's entries, length).
    /// `m` must be odd and `d1` is |re| + |im| of the difference.
    #[inline(always)]
    pub fn find_plain(&self, m: usize, d1: f64, room: u32) -> Option<(&Coeffs, u32)> {
        let found = super::bla::climb_plain(&self.radii, self.last, m, d1, room);
        found.map(|(k, j, len)| (&self.coeffs[k][j], len))
    }

    /// The radius of the first level's step from reference index m (0 where none starts).
    #[inline(always)]
    pub fn first_radius(&self, m: usize) -> f64 {
        self.first.get(m).copied().unwrap_or(0.0)
    }

    /// Number of steps stored.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.levels.iter().map(Vec::len).sum()
    }
}

/// A·δ + B·δc with a step's f64 coefficients.
#[inline(always)]
pub fn apply_plain(k: &Coeffs, d: C, dc: C) -> C {
    C::new(
        k[0] * d.re + k[1] * d.im + (k[4] * dc.re + k[5] * dc.im),
        k[2] * d.re + k[3] * d.im + (k[6] * dc.re + k[7] * dc.im),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One perturbed step of the ship, without cancellation (Kalles Fraktaler's diffabs).
    fn exact_step(z: C, d: C, dc: C) -> C {
        crate::escape::deep_plain::ship_step(z, d, dc)
    }

    #[test]
    fn merged_steps_follow_the_perturbed_orbit() {
        // The orbit of c ≈ −1.136 − 0.620i lands after four steps on a repelling fixed point
        // off the axes, z ≈ 1.705 + 0.257i (in f64 it leaves after about 30 iterations), and a
        // small δc: the merged steps over the first 25 iterations land where stepping does.
        let c = C::new(-1.135970435068669, -0.620043386399648);
        let mut z = vec![C::ZERO];
        for _ in 0..26 {
            let v = *z.last().unwrap();
            let (x, y) = (v.re.abs(), v.im.abs());
            z.push(C::new(x * x - y * y, 2.0 * x * y) + c);
        }
        let dc = C::new(3e-13, -2e-13);
        let bla = ShipBla::new(&z, Fx::from_f64(dc.abs()), true, 1e-6);
        assert!(bla.len() > 20);
        let mut d = dc; // δ after the first step from 0.
        let mut m = 1;
        let mut taken = 0;
        assert!(z.iter().all(|v| v.abs() < 2.0));
        while m < 24 {
            if let Some(st) = bla.find_f64(m, d, 1000) {
                let got =
                    st.a.apply(Cx::from_c(d))
                        .add(st.b.apply(Cx::from_c(dc)))
                        .to_c();
                let mut want = d;
                for k in 0..st.len as usize {
                    want = exact_step(z[m + k], want, dc);
                }
                let plain = bla.find_plain(m, d.re.abs() + d.im.abs(), 1000).unwrap();
                assert_eq!(plain.1, st.len);
                let p = apply_plain(plain.0, d, dc);
                assert!(
                    (got - want).abs() <= 1e-5 * want.abs(),
                    "{m}: {got:?} {want:?}"
                );
                assert!((p - got).abs() <= 1e-12 * got.abs(), "{m}: {p:?} {got:?}");
                d = got;
                m += st.len as usize;
                taken += 1;
            } else {
                d = exact_step(z[m], d, dc);
                m += 1;
            }
        }
        assert!(taken > 0);
    }

    #[test]
    fn spectral_norm_of_known_matrices() {
        // A rotation-scaling by 3 and a shear [[1, 2], [0, 1]] (σ = 1 + √2).
        let r = Mx::new([0.0, -3.0, 3.0, 0.0], 0).norm().to_f64();
        assert!((r - 3.0).abs() < 1e-15);
        let s = Mx::new([1.0, 2.0, 0.0, 1.0], 4).norm().to_f64();
        assert!((s - 16.0 * (1.0 + 2f64.sqrt())).abs() < 1e-12, "{s}");
        let p = Mx::new([1.0, 2.0, 3.0, 4.0], 0).mul(&Mx::new([0.5, 0.0, 0.0, 2.0], 3));
        assert_eq!(p.to_f64(), [4.0, 32.0, 12.0, 64.0]);
        let q = Mx::new([1.0, 0.0, 0.0, 1.0], 60).add(&Mx::new([0.0, 1.0, 0.0, 0.0], 0));
        assert_eq!(q.to_f64(), [ldexp(1.0, 60), 1.0, 0.0, ldexp(1.0, 60)]);
    }
}
