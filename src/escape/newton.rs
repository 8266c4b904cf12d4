//! Newton's method for a polynomial: its roots (Aberth–Ehrlich) and the iteration that
//! colours each starting point by the root it converges to.

use super::complex::C;
use super::family::Sample;

/// Newton's method settings and the polynomial's roots.
#[derive(Clone, Debug)]
pub struct NewtonSystem {
    pub coeffs: Vec<C>,
    pub roots: Vec<C>,
}

/// g(z) and g′(z) by Horner's scheme (coefficients highest degree first).
pub fn horner(coeffs: &[C], z: C) -> (C, C) {
    let mut g = C::ZERO;
    let mut d = C::ZERO;
    for &a in coeffs {
        d = d * z + g;
        g = g * z + a;
    }
    (g, d)
}

/// All roots of a polynomial (highest degree first) by the Aberth–Ehrlich method.
pub fn polynomial_roots(coeffs: &[C]) -> Vec<C> {
    // Drop leading zeros.
    let first = coeffs
        .iter()
        .position(|c| c.norm2() > 0.0)
        .unwrap_or(coeffs.len());
    let p = &coeffs[first..];
    let deg = p.len().saturating_sub(1);
    if deg == 0 {
        return Vec::new();
    }
    let lead = p[0];
    let monic: Vec<C> = p.iter().map(|&a| a / lead).collect();
    // Cauchy bound for the starting circle.
    let bound = 1.0 + monic[1..].iter().map(|a| a.abs()).fold(0.0, f64::max);
    let mut z: Vec<C> = (0..deg)
        .map(|k| {
            C::from_polar(
                0.5 * bound,
                0.4 + 2.0 * std::f64::consts::PI * k as f64 / deg as f64,
            )
        })
        .collect();
    for _ in 0..500 {
        let mut moved = 0.0f64;
        for i in 0..deg {
            let (g, d) = horner(&monic, z[i]);
            if g.norm2() == 0.0 {
                continue;
            }
            let ratio = g / d;
            let mut s = C::ZERO;
            for j in 0..deg {
                if j != i {
                    s = s + C::ONE / (z[i] - z[j]);
                }
            }
            let w = ratio / (C::ONE - ratio * s);
            if w.is_finite() {
                z[i] = z[i] - w;
                moved = moved.max(w.abs());
            }
        }
        if moved < 1e-15 {
            break;
        }
    }
    z
}

impl NewtonSystem {
    pub fn new(coeffs: &[C]) -> NewtonSystem {
        let first = coeffs
            .iter()
            .position(|c| c.norm2() > 0.0)
            .unwrap_or(coeffs.len());
        let coeffs = coeffs[first..].to_vec();
        let roots = polynomial_roots(&coeffs);
        NewtonSystem { coeffs, roots }
    }

    /// One Newton step N(z) = z − g/g′ (None where g′ = 0 or a value is not finite).
    pub fn step(&self, z: C) -> Option<C> {
        let (g, d) = horner(&self.coeffs, z);
        if d.norm2() == 0.0 {
            return None;
        }
        let n = z - g / d;
        n.is_finite().then_some(n)
    }

    /// Iterate from z₀ until |Δz|² < 1e-10.
    pub fn iterate(&self, z0: C, max_iter: u32) -> Sample {
        let mut z = z0;
        for n in 1..=max_iter {
            let Some(next) = self.step(z) else {
                return Sample::inside(max_iter);
            };
            let done = (next - z).norm2() < 1e-10;
            z = next;
            if done {
                let root = self
                    .roots
                    .iter()
                    .enumerate()
                    .map(|(k, r)| (k, (*r - z).norm2()))
                    .min_by(|a, b| a.1.total_cmp(&b.1))
                    .filter(|(_, d)| *d < 1e-6)
                    .map_or(255, |(k, _)| k.min(254) as u8);
                return Sample {
                    n,
                    inside: false,
                    nu: n as f64,
                    de: 0.0,
                    root,
                };
            }
        }
        Sample::inside(max_iter)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn newton_oracles_7_5() {
        let cube = NewtonSystem::new(&[C::ONE, C::ZERO, C::ZERO, C::new(-1.0, 0.0)]);
        let mut z = C::new(2.0, 0.0);
        for want in [17.0 / 12.0, 1.110534, 1.010637, 1.000112, 1.0000000124] {
            z = cube.step(z).unwrap();
            assert!(
                (z.re - want).abs() < 5e-7 && z.im.abs() < 1e-15,
                "{z:?} vs {want}"
            );
        }
        let s = cube.iterate(C::new(2.0, 0.0), 100);
        assert_eq!(s.n, 6);
        let root_of = |s: Sample| cube.roots[s.root as usize];
        assert!((root_of(s) - C::ONE).abs() < 1e-9);
        let w = C::new(-0.5, 0.866_025_403_784_438_6);
        for (z0, target, n) in [
            (C::new(-1.0, 1.0), w, 5),
            (C::new(-1.0, -1.0), w.conj(), 5),
            (C::new(0.0, 0.5), w, 9),
            (C::new(-2.0, 0.0), C::ONE, 10),
            (C::new(1.0, 1.0), C::ONE, 8),
        ] {
            let s = cube.iterate(z0, 100);
            assert_eq!(s.n, n, "from {z0:?}");
            assert!((root_of(s) - target).abs() < 1e-6, "from {z0:?}");
        }
        // Real form at (0.3, 0.7).
        let (x, y) = (0.3f64, 0.7f64);
        let r2 = x * x + y * y;
        let xr = 2.0 * x / 3.0 + (x * x - y * y) / (3.0 * r2 * r2);
        let yr = 2.0 * y / 3.0 - 2.0 * x * y / (3.0 * r2 * r2);
        let n = cube.step(C::new(x, y)).unwrap();
        assert!((n.re - xr).abs() < 1e-12 && (n.im - yr).abs() < 1e-12);
        assert!((n.re + 0.196354).abs() < 1e-6 && (n.im - 0.050495).abs() < 1e-6);
        // z⁴ − 1 from 2.
        let quart = NewtonSystem::new(&[C::ONE, C::ZERO, C::ZERO, C::ZERO, C::new(-1.0, 0.0)]);
        let mut z = C::new(2.0, 0.0);
        for want in [1.53125, 1.218068, 1.051884, 1.003714, 1.000021] {
            z = quart.step(z).unwrap();
            assert!((z.re - want).abs() < 5e-7, "{z:?} vs {want}");
        }
        // The Urbonavičius septic.
        let r = |v: f64| C::new(v, 0.0);
        let sep = NewtonSystem::new(&[
            r(1.0),
            r(0.0),
            r(-3.0),
            r(0.0),
            r(6.0),
            r(0.0),
            r(-3.0),
            r(3.0),
        ]);
        assert!((sep.step(C::ZERO).unwrap() - C::ONE).abs() < 1e-15);
        assert!((sep.step(C::ONE).unwrap() - r(3.0 / 7.0)).abs() < 1e-15);
        for want in [
            C::new(-1.208810, 0.0),
            C::new(-1.226405, 0.774499),
            C::new(-1.226405, -0.774499),
            C::new(1.367403, 0.647038),
            C::new(1.367403, -0.647038),
            C::new(0.463407, 0.548372),
            C::new(0.463407, -0.548372),
        ] {
            assert!(
                sep.roots.iter().any(|z| (*z - want).abs() < 2e-6),
                "root {want:?} missing from {:?}",
                sep.roots
            );
        }
    }

    #[test]
    fn newton_basins_turn_with_the_roots() {
        // basin(e^{2πi/3} z) = basin(z) + 1 (mod 3) in the order of the roots.
        let cube = NewtonSystem::new(&[C::ONE, C::ZERO, C::ZERO, C::new(-1.0, 0.0)]);
        let rot = C::from_polar(1.0, 2.0 * std::f64::consts::PI / 3.0);
        let index_of = |z: C| {
            cube.roots
                .iter()
                .position(|r| (*r - z).abs() < 1e-6)
                .unwrap()
        };
        let one = index_of(C::ONE);
        let next = index_of(rot);
        let mut checked = 0;
        for i in -20..=20 {
            for j in -20..=20 {
                let z = C::new(i as f64 * 0.0731 + 0.013, j as f64 * 0.0689 - 0.007);
                let a = cube.iterate(z, 200);
                let b = cube.iterate(z * rot, 200);
                if a.root == 255 || b.root == 255 {
                    continue;
                }
                let ra = cube.roots[a.root as usize];
                let rb = cube.roots[b.root as usize];
                // The basin of z·ω is the root ω·(root of z).
                if (ra * rot - rb).abs() < 1e-6 {
                    checked += 1;
                } else {
                    // Points on the Julia set itself may go either way: skip them.
                    let near = cube.iterate(z + C::new(1e-3, 0.0), 200).root != a.root
                        || cube.iterate(z - C::new(1e-3, 0.0), 200).root != a.root;
                    assert!(near, "z = {z:?}: basins {} and {}", a.root, b.root);
                }
            }
        }
        assert!(checked > 1500, "{checked}");
        assert_ne!(one, next);
    }
}
