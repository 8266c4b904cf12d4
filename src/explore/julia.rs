//! Julia sets of z² + c by inverse iteration (the first algorithm of Köse's 1990 thesis; also
//! Peitgen & Saupe, *The Science of Fractal Images*, 1988, "inverse iteration method"): the
//! preimages ±√(z − c) of any point accumulate on the Julia set J_c, because J_c repels under
//! z² + c and so attracts under its inverse.
//!
//! Fast, but the two branches are picked with equal probability while J_c is not evenly
//! covered by the natural measure: points pile up where preimages contract most and thin
//! parts of J_c (near the tips of a dendrite, deep inside the fjords of a basilica) stay
//! nearly empty — where the escape-time picture of the same c has no such gaps.

use super::{ExploreError, P2};
use crate::escape::C;
use crate::flame::rng::FastRng;

/// Points skipped before plotting (the start converges onto J_c).
pub const SKIP: u64 = 50;
/// Largest |c| accepted (beyond 2 the set is dust well inside |z| ≤ 2 anyway).
pub const MAX_C: f64 = 10.0;

/// The principal square root (real part ≥ 0; the cut along the negative real axis).
pub fn principal_sqrt(z: C) -> C {
    let r = z.abs();
    let re = ((r + z.re) / 2.0).max(0.0).sqrt();
    let im = ((r - z.re) / 2.0).max(0.0).sqrt();
    C::new(re, if z.im < 0.0 { -im } else { im })
}

/// The repelling fixed point (1 + √(1 − 4c))/2 of z² + c (for c ≠ 1/4 the other fixed point
/// is attracting, neutral or also repelling; this one always has |2z| ≥ 1).
pub fn repelling_fixed_point(c: C) -> C {
    let s = principal_sqrt(C::new(1.0 - 4.0 * c.re, -4.0 * c.im));
    C::new((1.0 + s.re) / 2.0, s.im / 2.0)
}

/// Inverse iteration: z ← ±√(z − c) with a random sign; a point source.
#[derive(Clone, Debug)]
pub struct InverseJulia {
    c: C,
    z: C,
    rng: FastRng,
    steps: u64,
}

impl InverseJulia {
    /// Start at the repelling fixed point (which lies on J_c).
    pub fn new(c: C, seed: u64) -> Result<InverseJulia, ExploreError> {
        if !(c.is_finite() && c.abs() <= MAX_C) {
            return Err(ExploreError::Invalid(format!(
                "c = {}{:+}i must be finite with |c| ≤ {MAX_C}",
                c.re, c.im
            )));
        }
        Ok(InverseJulia {
            c,
            z: repelling_fixed_point(c),
            rng: FastRng::new(seed),
            steps: 0,
        })
    }

    /// One inverse step (not skipped): the new point.
    #[inline]
    pub fn step(&mut self) -> C {
        let w = principal_sqrt(self.z - self.c);
        self.z = if self.rng.bit() {
            w
        } else {
            C::new(-w.re, -w.im)
        };
        self.steps += 1;
        self.z
    }

    /// The next point to plot (the first [`SKIP`] are taken but not returned).
    #[inline]
    pub fn next_point(&mut self) -> P2 {
        while self.steps < SKIP {
            self.step();
        }
        let z = self.step();
        [z.re, z.im]
    }
}

impl Iterator for InverseJulia {
    type Item = P2;

    fn next(&mut self) -> Option<P2> {
        Some(self.next_point())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_roots() {
        for z in [
            C::new(4.0, 0.0),
            C::new(-4.0, 0.0),
            C::new(0.3, -1.7),
            C::new(-2.0, 1e-300),
            C::new(0.0, 0.0),
        ] {
            let w = principal_sqrt(z);
            let w2 = w * w;
            assert!((w2.re - z.re).abs() < 1e-14 && (w2.im - z.im).abs() < 1e-14);
            assert!(w.re >= 0.0);
        }
        assert_eq!(principal_sqrt(C::new(-4.0, 0.0)), C::new(0.0, 2.0));
    }

    #[test]
    fn fixed_point_is_repelling_and_fixed() {
        for c in [
            C::new(-1.0, 0.0),
            C::new(0.0, 1.0),
            C::new(-0.2, 0.75),
            C::new(0.3, 0.0),
        ] {
            let z = repelling_fixed_point(c);
            let f = z * z + c;
            assert!((f.re - z.re).abs() < 1e-14 && (f.im - z.im).abs() < 1e-14);
            assert!(2.0 * z.abs() >= 1.0);
        }
    }

    #[test]
    fn points_lie_on_known_julia_sets() {
        // c = 0: J is the unit circle.
        let mut g = InverseJulia::new(C::new(0.0, 0.0), 1).unwrap();
        for _ in 0..10_000 {
            let p = g.next_point();
            assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-12);
        }
        // c = −2: J is the segment [−2, 2].
        let mut g = InverseJulia::new(C::new(-2.0, 0.0), 2).unwrap();
        for _ in 0..10_000 {
            let p = g.next_point();
            assert!(p[1].abs() < 1e-12 && p[0].abs() <= 2.0 + 1e-12);
        }
    }

    #[test]
    fn forward_iteration_retraces_the_orbit() {
        // f(z_{n+1}) = z_n exactly (up to rounding), and points of J do not escape: the orbit
        // of a plotted point stays in |z| ≤ 2 for as many steps as it was built from.
        for c in [C::new(-1.0, 0.0), C::new(0.0, 1.0), C::new(-0.2, 0.75)] {
            let mut g = InverseJulia::new(c, 5).unwrap();
            let orbit: Vec<C> = (0..200).map(|_| g.step()).collect();
            for w in orbit.windows(2) {
                let f = w[1] * w[1] + c;
                assert!((f.re - w[0].re).abs() < 1e-9 && (f.im - w[0].im).abs() < 1e-9);
            }
            let mut z = orbit[199];
            for _ in 0..20 {
                z = z * z + c;
                assert!(z.norm2() <= 4.0, "c = {c:?}");
            }
        }
    }

    #[test]
    fn symmetric_under_negation() {
        // J_c = −J_c: both signs are taken equally often.
        let mut g = InverseJulia::new(C::new(-0.2, 0.75), 9).unwrap();
        let right = (0..100_000).filter(|_| g.next_point()[0] > 0.0).count();
        assert!((right as f64 / 1e5 - 0.5).abs() < 0.01);
        assert!(InverseJulia::new(C::new(f64::NAN, 0.0), 1).is_err());
        assert!(InverseJulia::new(C::new(11.0, 0.0), 1).is_err());
    }
}
