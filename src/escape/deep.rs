//! Deep zoom for z² + c by perturbation: one reference orbit Z at the view centre C, computed
//! in double-double arithmetic and stored as f64; every pixel c = C + δc of the Mandelbrot set
//! then iterates only its difference δ from the reference in f64,
//!
//! ```text
//! δ(n+1) = 2·Z(n)·δ(n) + δ(n)² + δc,      z(n) = Z(n) + δ(n),
//! ```
//!
//! which stays accurate because δ is small where Z is not. When the pixel's orbit comes closer
//! to 0 than its difference (|z| < |δ|), or the reference ends (it escaped), the pixel
//! rebases onto the start of the reference (δ := z, n := 0), which removes the "glitches" of
//! single-reference perturbation (Zhuoran's method). Julia sets work the same way with δ(0)
//! the pixel's offset and no δc term; they rebase onto the orbit of 0 (the critical orbit).

use super::complex::C;
use super::dd::Dd;
use super::family::{IterSettings, Sample};

/// What the pixels of a deep view iterate around.
#[derive(Clone, Debug)]
pub struct Reference {
    /// The orbit of the view centre: for the Mandelbrot set the orbit of 0 under z² + C (C
    /// the centre), for a Julia set the orbit of the centre under z² + c.
    pub orbit: Vec<C>,
    /// Julia sets: the orbit of 0 under the same map. Pixels rebase onto it (a Mandelbrot
    /// reference starts at 0 itself).
    pub critical: Option<Vec<C>>,
}

impl Reference {
    pub fn mandelbrot(centre: [Dd; 2], s: &IterSettings) -> Reference {
        Reference {
            orbit: orbit_dd([Dd::ZERO; 2], centre, s),
            critical: None,
        }
    }

    pub fn julia(centre: [Dd; 2], c: C, s: &IterSettings) -> Reference {
        let c = [Dd::from_f64(c.re), Dd::from_f64(c.im)];
        Reference {
            orbit: orbit_dd(centre, c, s),
            critical: Some(orbit_dd([Dd::ZERO; 2], c, s)),
        }
    }

    fn is_julia(&self) -> bool {
        self.critical.is_some()
    }
}

/// The orbit of z0 under z² + c in double-double arithmetic, stored as f64, until it escapes
/// past the bailout or reaches the iteration limit. Always at least two entries.
fn orbit_dd(z0: [Dd; 2], c: [Dd; 2], s: &IterSettings) -> Vec<C> {
    let [cx, cy] = c;
    let [mut x, mut y] = z0;
    let mut out = Vec::with_capacity(s.max_iter.min(1 << 20) as usize + 1);
    out.push(C::new(x.to_f64(), y.to_f64()));
    for _ in 0..s.max_iter {
        let xx = x * x;
        let yy = y * y;
        let xy = x * y;
        x = xx - yy + cx;
        y = xy + xy + cy;
        let z = C::new(x.to_f64(), y.to_f64());
        out.push(z);
        if !(z.norm2() <= s.bailout2) {
            break;
        }
    }
    out
}

/// Series approximation: δ(n) ≈ A(n)·δc + B(n)·δc² + C(n)·δc³ for every pixel of the view
/// lets all pixels start at iteration `skip` instead of 0 (the iterations every pixel spends
/// shadowing the reference).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Series {
    pub skip: usize,
    pub a: C,
    pub b: C,
    pub c: C,
}

impl Series {
    pub const NONE: Series = Series {
        skip: 0,
        a: C::ZERO,
        b: C::ZERO,
        c: C::ZERO,
    };

    /// The coefficients and the number of iterations they skip, for pixels within `radius`
    /// of the reference. The skip is the last iteration at which the series still matches the
    /// exact perturbation of probe points on the view's border (relative error 1e-13),
    /// checked at every step up to it.
    pub fn for_view(r: &Reference, probes: &[C], s: &IterSettings) -> Series {
        let orbit = &r.orbit;
        let julia = r.is_julia();
        let last = orbit.len().saturating_sub(2);
        let mut best = Series::NONE;
        // Mandelbrot: δ(0) = 0 and δc is added every step; Julia: δ(0) = δc, nothing added.
        let (one, add) = if julia { (C::ZERO, 0.0) } else { (C::ONE, 1.0) };
        let (mut a, mut b, mut c) = (C::ONE - one, C::ZERO, C::ZERO);
        let mut d: Vec<C> = probes.iter().map(|&p| p * (1.0 - add)).collect();
        for n in 0..last.min(s.max_iter as usize) {
            let z = orbit[n];
            // Coefficients and the probes' exact differences at step n + 1.
            let c1 = z * c * 2.0 + a * b * 2.0;
            let b1 = z * b * 2.0 + a * a;
            let a1 = z * a * 2.0 + one;
            (a, b, c) = (a1, b1, c1);
            let mut ok = true;
            for (dk, &dc) in d.iter_mut().zip(probes) {
                *dk = z * *dk * 2.0 + *dk * *dk + dc * add;
                let full = orbit[n + 1] + *dk;
                // A probe that rebases or escapes ends the shared stretch.
                if full.norm2() < dk.norm2() || !(full.norm2() <= s.bailout2) {
                    ok = false;
                }
                let dc2 = dc * dc;
                let approx = a * dc + b * dc2 + c * dc2 * dc;
                if !((approx - *dk).norm2() <= 1e-26 * dk.norm2()) {
                    ok = false;
                }
            }
            if !ok {
                break;
            }
            best = Series {
                skip: n + 1,
                a,
                b,
                c,
            };
        }
        best
    }
}

/// One pixel at offset `dc` from the reference point, without the series approximation.
#[cfg(test)]
pub fn iterate_perturbed(r: &Reference, dc: C, s: &IterSettings) -> Sample {
    iterate_perturbed_from(r, &Series::NONE, dc, s)
}

/// One pixel at offset `dc` from the reference point (the parameter offset for the
/// Mandelbrot set, the starting-point offset for a Julia set), starting where the series
/// approximation leaves off.
pub fn iterate_perturbed_from(r: &Reference, sa: &Series, dc: C, s: &IterSettings) -> Sample {
    let julia = r.is_julia();
    let mut orbit: &[C] = &r.orbit;
    let mut last = orbit.len() - 1;
    let skip = sa.skip.min(last.saturating_sub(1)).min(s.max_iter as usize);
    let dc2 = dc * dc;
    // Mandelbrot: δ(0) = 0, δc added each step, dz/dc; Julia: δ(0) = δz0, dz/dz0.
    let (add, one) = if julia {
        (C::ZERO, C::ZERO)
    } else {
        (dc, C::ONE)
    };
    let mut d = if skip > 0 {
        sa.a * dc + sa.b * dc2 + sa.c * dc2 * dc
    } else if julia {
        dc
    } else {
        C::ZERO
    };
    let mut m = skip;
    // The derivative for the distance estimate, on the full orbit value.
    let mut der = if skip > 0 {
        sa.a + sa.b * dc * 2.0 + sa.c * dc2 * 3.0
    } else {
        C::ONE - one
    };
    for n in skip as u32 + 1..=s.max_iter {
        let zm = orbit[m];
        if s.want_de {
            der = (zm + d) * der * 2.0 + one;
        }
        d = zm * d * 2.0 + d * d + add;
        m += 1;
        let z = orbit[m] + d;
        let r2 = z.norm2();
        if s.escaped(r2) {
            return s.escape_sample(n, z, r2, der, 2.0);
        }
        if r2 < d.norm2() || m == last {
            // Rebase onto an orbit that starts at 0.
            d = z;
            m = 0;
            if let Some(k) = &r.critical {
                orbit = k;
                last = k.len() - 1;
            }
        }
    }
    Sample::inside(s.max_iter)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::escape::family::{Family, iterate_point};

    fn settings(max_iter: u32) -> IterSettings {
        IterSettings {
            max_iter,
            bailout2: 4.0,
            strict: true,
            period_tol: 0.0,
            want_de: false,
        }
    }

    #[test]
    fn perturbation_agrees_with_direct_iteration_where_f64_suffices() {
        // Reference at a boundary point of seahorse valley; pixels up to 1e-3 away, where
        // plain f64 is exact enough to compare counts.
        let s = settings(2000);
        let centre = [Dd::from_f64(-0.7453), Dd::from_f64(0.1127)];
        let orbit = Reference::mandelbrot(centre, &s);
        let mut same = 0;
        let total = 40 * 40;
        for a in 0..40 {
            for b in 0..40 {
                let dc = C::new((a as f64 - 20.0) * 2.5e-5, (b as f64 - 20.0) * 2.5e-5);
                let p = iterate_perturbed(&orbit, dc, &s);
                let c = C::new(-0.7453 + dc.re, 0.1127 + dc.im);
                let q = iterate_point(&Family::Mandelbrot { power: 2 }, c, &s);
                if (p.n, p.inside) == (q.n, q.inside) {
                    same += 1;
                }
            }
        }
        // Rounding differs in the last bits; near the boundary the orbits are chaotic and a
        // count can move by a few iterations.
        assert!(same * 100 >= total * 99, "{same} of {total}");
    }

    #[test]
    fn rebasing_handles_a_reference_that_escapes_early() {
        // Reference outside the set (escapes at once); the pixel 0.5 away is inside the main
        // cardioid. Without rebasing the pixel would be lost when the reference ends.
        let s = settings(500);
        let orbit = Reference::mandelbrot([Dd::from_f64(0.5), Dd::ZERO], &s);
        assert!(orbit.orbit.len() < 10);
        let p = iterate_perturbed(&orbit, C::new(-0.5, 0.0), &s);
        assert!(p.inside);
        let q = iterate_perturbed(&orbit, C::new(-0.2, 0.0), &s);
        assert_eq!(
            q.n,
            iterate_point(&Family::Mandelbrot { power: 2 }, C::new(0.3, 0.0), &s).n
        );
    }

    #[test]
    fn deep_offsets_below_f64_resolution_still_separate() {
        // At |C| ≈ 0.75, f64 cannot tell c and c + 1e-20 apart; the perturbed pixels can.
        let s = settings(20_000);
        let centre = [
            Dd::parse("-0.743643887037158704752191506114774").unwrap(),
            Dd::parse("0.131825904205311970493132056385139").unwrap(),
        ];
        let orbit = Reference::mandelbrot(centre, &s);
        let counts: Vec<u32> = (0..16)
            .map(|k| iterate_perturbed(&orbit, C::new(k as f64 * 1e-20, 0.0), &s).n)
            .collect();
        let distinct = {
            let mut c = counts.clone();
            c.sort();
            c.dedup();
            c.len()
        };
        assert!(distinct >= 3, "{counts:?}");
    }
}
