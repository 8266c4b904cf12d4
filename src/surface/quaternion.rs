//! Quaternion Julia sets: q ← q² + c iterated in Hamilton's quaternions (Norton, "Generation
//! and display of geometric fractals in 3-D", 1982), shown as a 3-D slice of the 4-D set and
//! rendered by distance-estimated ray marching (Hart, Sandin & Kauffman, "Ray tracing
//! deterministic 3-D fractals", SIGGRAPH 1989).
//!
//! A quaternion q = a₀ + a₁i + a₂j + a₃k with i² = j² = k² = −1, ij = −ji = k, jk = −kj = i,
//! ki = −ik = j. Squaring needs no general product: with q = a₀ + v (v the vector part),
//! q² = (a₀² − |v|²) + 2a₀v. |pq| = |p||q|, so the derivative of the orbit only needs its
//! length: |q′ₙ₊₁| = 2|qₙ||q′ₙ|, which gives the distance bound of the complex case,
//! b = 2|q| ln|q| / |q′| with the true distance at least b/4 (the Koebe ¼ bound of complex
//! dynamics; Hart et al. use the same b/4 step for the quaternion sets).

use std::ops::{Add, Mul, Neg, Sub};

use glam::DVec3;

/// A quaternion a₀ + a₁i + a₂j + a₃k.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Quaternion(pub [f64; 4]);

impl Quaternion {
    pub const ONE: Quaternion = Quaternion([1.0, 0.0, 0.0, 0.0]);
    pub const I: Quaternion = Quaternion([0.0, 1.0, 0.0, 0.0]);
    pub const J: Quaternion = Quaternion([0.0, 0.0, 1.0, 0.0]);
    pub const K: Quaternion = Quaternion([0.0, 0.0, 0.0, 1.0]);

    pub fn norm2(self) -> f64 {
        self.0.iter().map(|a| a * a).sum()
    }

    pub fn abs(self) -> f64 {
        self.norm2().sqrt()
    }

    /// q² = (a₀² − |v|²) + 2a₀v.
    #[inline]
    pub fn square(self) -> Quaternion {
        let [a, b, c, d] = self.0;
        let t = 2.0 * a;
        Quaternion([a * a - b * b - c * c - d * d, t * b, t * c, t * d])
    }
}

impl Add for Quaternion {
    type Output = Quaternion;
    fn add(self, o: Quaternion) -> Quaternion {
        Quaternion(std::array::from_fn(|k| self.0[k] + o.0[k]))
    }
}

impl Sub for Quaternion {
    type Output = Quaternion;
    fn sub(self, o: Quaternion) -> Quaternion {
        Quaternion(std::array::from_fn(|k| self.0[k] - o.0[k]))
    }
}

impl Neg for Quaternion {
    type Output = Quaternion;
    fn neg(self) -> Quaternion {
        Quaternion(self.0.map(|a| -a))
    }
}

/// Hamilton's product (not commutative).
impl Mul for Quaternion {
    type Output = Quaternion;
    fn mul(self, o: Quaternion) -> Quaternion {
        let [a1, b1, c1, d1] = self.0;
        let [a2, b2, c2, d2] = o.0;
        Quaternion([
            a1 * a2 - b1 * b2 - c1 * c2 - d1 * d2,
            a1 * b2 + b1 * a2 + c1 * d2 - d1 * c2,
            a1 * c2 - b1 * d2 + c1 * a2 + d1 * b2,
            a1 * d2 + b1 * c2 - c1 * b2 + d1 * a2,
        ])
    }
}

/// Which quaternion component a 3-D slice holds fixed; the other three, in the order
/// 1, i, j, k, become x, y and z.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SliceAxis {
    /// The real part 1.
    Real,
    /// The i part.
    I,
    /// The j part.
    J,
    /// The k part (the default).
    #[default]
    K,
}

impl SliceAxis {
    /// Index of the fixed component in (1, i, j, k): 0–3.
    pub fn index(self) -> usize {
        match self {
            SliceAxis::Real => 0,
            SliceAxis::I => 1,
            SliceAxis::J => 2,
            SliceAxis::K => 3,
        }
    }

    /// The name in scene files: "1", "i", "j" or "k".
    pub fn name(self) -> &'static str {
        ["1", "i", "j", "k"][self.index()]
    }

    /// The axis a name stands for ("real" and "r" also name the real part); None if unknown.
    pub fn from_name(s: &str) -> Option<SliceAxis> {
        Some(match s {
            "1" | "real" | "r" => SliceAxis::Real,
            "i" => SliceAxis::I,
            "j" => SliceAxis::J,
            "k" => SliceAxis::K,
            _ => return None,
        })
    }
}

/// Largest iteration count a scene may ask for (each ray-marching step iterates this often).
pub const MAX_ITERATIONS: u32 = 200;
/// Largest |c| and |slice value| accepted: beyond |c| = 2 the set is a thin dust that ray
/// marching cannot resolve, and slices beyond the escape radius are empty.
pub const MAX_PARAMETER: f64 = 4.0;

/// Escape radius used while estimating distances: large, so that b is accurate (the
/// estimate converges as R grows; R = 1e3 is already within about 1e-5 of the limit).
const DE_BAILOUT2: f64 = 1e6;

/// A quaternion Julia set and the 3-D slice shown.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuaternionJulia {
    /// c = c₀ + c₁i + c₂j + c₃k.
    pub c: [f64; 4],
    /// Which component the slice holds fixed.
    pub slice: SliceAxis,
    /// The value of the fixed component.
    pub slice_value: f64,
    /// Iterations per distance estimate (more: finer detail, slower).
    pub iterations: u32,
}

impl Default for QuaternionJulia {
    fn default() -> Self {
        QuaternionJulia {
            c: [-0.2, 0.8, 0.0, 0.0],
            slice: SliceAxis::K,
            slice_value: 0.0,
            iterations: 12,
        }
    }
}

/// The outcome of iterating one point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    /// Escape iteration (None: bounded for the iterations done).
    pub escaped_at: Option<u32>,
    /// The distance bound b = 2|q| ln|q| / |q′| (0 for points that did not escape).
    pub b: f64,
    /// Smallest |qₙ| along the orbit (an orbit trap, for colouring).
    pub trap: f64,
}

impl QuaternionJulia {
    /// Check the parameters (finite, within limits); the message says what is expected.
    pub fn validate(&self) -> Result<(), String> {
        if !self.c.iter().all(|v| v.is_finite()) || !self.slice_value.is_finite() {
            return Err("c and slice_value must be finite numbers".into());
        }
        let c = Quaternion(self.c).abs();
        if c > MAX_PARAMETER {
            return Err(format!(
                "|c| = {c} is too large: expected |c| ≤ {MAX_PARAMETER}"
            ));
        }
        if self.slice_value.abs() > MAX_PARAMETER {
            return Err(format!(
                "slice_value {} must be between −{MAX_PARAMETER} and {MAX_PARAMETER}",
                self.slice_value
            ));
        }
        if !(1..=MAX_ITERATIONS).contains(&self.iterations) {
            return Err(format!(
                "iterations {} must be between 1 and {MAX_ITERATIONS}",
                self.iterations
            ));
        }
        Ok(())
    }

    /// The quaternion of a point of the slice.
    pub fn point(&self, p: DVec3) -> Quaternion {
        let fixed = self.slice.index();
        let mut q = [0.0; 4];
        let mut free = [p.x, p.y, p.z].into_iter();
        for (k, v) in q.iter_mut().enumerate() {
            *v = if k == fixed {
                self.slice_value
            } else {
                free.next().unwrap_or(0.0)
            };
        }
        Quaternion(q)
    }

    /// Every orbit that leaves the ball |q| ≤ r with r = (1 + √(1 + 4|c|))/2 escapes
    /// (|q² + c| ≥ |q|² − |c| > |q| there), so the set lies inside it.
    pub fn escape_radius(&self) -> f64 {
        let c = Quaternion(self.c).abs();
        0.5 * (1.0 + (1.0 + 4.0 * c).sqrt())
    }

    /// Iterate q₀ with the strict test |q|² > bailout².
    pub fn iterate(&self, q0: Quaternion, max_iter: u32, bailout: f64) -> Orbit {
        let c = Quaternion(self.c);
        let r2 = bailout * bailout;
        let mut q = q0;
        // |q′| with q′₀ = 1 (derivative with respect to the starting point).
        let mut dq = 1.0;
        let mut trap = q.norm2();
        for n in 1..=max_iter {
            dq *= 2.0 * q.abs();
            q = q.square() + c;
            let m2 = q.norm2();
            trap = trap.min(m2);
            if m2 > r2 || m2.is_nan() {
                let a = m2.sqrt();
                return Orbit {
                    escaped_at: Some(n),
                    b: 2.0 * a * a.ln() / dq,
                    trap: trap.sqrt(),
                };
            }
        }
        Orbit {
            escaped_at: None,
            b: 0.0,
            trap: trap.sqrt(),
        }
    }

    /// A lower bound of the distance from slice point p to the set: b/4, or 0 for points
    /// that stay bounded for `iterations` steps (they count as inside).
    pub fn distance(&self, p: DVec3) -> f64 {
        let o = self.iterate(self.point(p), self.iterations, DE_BAILOUT2.sqrt());
        0.25 * o.b
    }

    /// The surface normal at p: the gradient of the distance estimate (central differences
    /// with step h), pointing outwards.
    pub fn normal(&self, p: DVec3, h: f64) -> DVec3 {
        let d = |q: DVec3| self.distance(q);
        let g = DVec3::new(
            d(p + DVec3::X * h) - d(p - DVec3::X * h),
            d(p + DVec3::Y * h) - d(p - DVec3::Y * h),
            d(p + DVec3::Z * h) - d(p - DVec3::Z * h),
        );
        if g.length_squared() > 0.0 {
            g.normalize()
        } else {
            // Deep inside (all six samples bounded): point away from the centre.
            p.normalize_or(DVec3::Y)
        }
    }

    /// Texture coordinates of a surface point: s runs around the y axis, t is the orbit
    /// trap (smallest |qₙ|) relative to the escape radius.
    pub fn tex_coords(&self, p: DVec3) -> [f64; 2] {
        let o = self.iterate(self.point(p), self.iterations, DE_BAILOUT2.sqrt());
        let s = 0.5 + p.z.atan2(p.x) / std::f64::consts::TAU;
        let t = (o.trap / self.escape_radius()).clamp(0.0, 1.0);
        [s, t]
    }

    /// March along o + t·d (d of unit length, object space) from t0 to t1: the first t where
    /// the distance bound falls below `eps(t)` (the surface), or None.
    pub fn march(
        &self,
        o: DVec3,
        d: DVec3,
        t0: f64,
        t1: f64,
        eps: impl Fn(f64) -> f64,
    ) -> Option<f64> {
        let mut t = t0.max(0.0);
        for _ in 0..MAX_MARCH_STEPS {
            if t > t1 {
                return None;
            }
            let dist = self.distance(o + d * t);
            let e = eps(t);
            if dist < e {
                return Some(t);
            }
            t += dist.max(0.25 * e);
        }
        None
    }
}

/// Steps before a ray that keeps grazing the set is given up (counted as a miss).
pub const MAX_MARCH_STEPS: u32 = 600;

/// Where a ray o + t·d (d of unit length) meets the sphere |p − centre| = r: (t_in, t_out).
pub fn ray_sphere(o: DVec3, d: DVec3, centre: DVec3, r: f64) -> Option<(f64, f64)> {
    let oc = o - centre;
    let b = oc.dot(d);
    let c = oc.length_squared() - r * r;
    let disc = b * b - c;
    if disc < 0.0 {
        return None;
    }
    let s = disc.sqrt();
    Some((-b - s, -b + s))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::escape::C;
    use crate::escape::family::{IterSettings, iterate_quadratic_scalar};

    fn julia(c: [f64; 4]) -> QuaternionJulia {
        QuaternionJulia {
            c,
            ..QuaternionJulia::default()
        }
    }

    #[test]
    fn hamilton_product_rules() {
        let (one, i, j, k) = (Quaternion::ONE, Quaternion::I, Quaternion::J, Quaternion::K);
        for u in [i, j, k] {
            assert_eq!(u * u, -one);
            assert_eq!(u.square(), -one);
        }
        assert_eq!(i * j, k);
        assert_eq!(j * i, -k);
        assert_eq!(j * k, i);
        assert_eq!(k * j, -i);
        assert_eq!(k * i, j);
        assert_eq!(i * k, -j);
        // q² = (a₀² − |v|²) + 2a₀v equals the general product q·q.
        let q = Quaternion([0.3, -1.2, 0.7, 2.5]);
        let (a, b) = (q.square(), q * q);
        for k in 0..4 {
            assert!((a.0[k] - b.0[k]).abs() < 1e-12);
        }
        assert_eq!(q.square().0, [0.09 - 1.44 - 0.49 - 6.25, -0.72, 0.42, 1.5]);
        // |pq| = |p||q|.
        let p = Quaternion([1.0, 2.0, -0.5, 0.25]);
        assert!(((p * q).abs() - p.abs() * q.abs()).abs() < 1e-12);
    }

    /// Escape iteration of q₀ with R = 2 (strict).
    fn esc(j: &QuaternionJulia, q0: Quaternion, max: u32) -> Option<u32> {
        j.iterate(q0, max, 2.0).escaped_at
    }

    #[test]
    fn complex_plane_reproduces_the_complex_oracles() {
        // From q₀ = 0 the orbit of q² + c is the Mandelbrot orbit of c: 0.64i escapes at 55,
        // −0.66i at 17, 0.2 + 0.75i at 6, c = 1 at 3, c = 2 at 2; −2, i and −0.75 stay bounded.
        for (c, want) in [
            ([0.0, 0.64], Some(55)),
            ([0.0, -0.66], Some(17)),
            ([0.0, 0.66], Some(17)),
            ([0.2, 0.75], Some(6)),
            ([1.0, 0.0], Some(3)),
            ([2.0, 0.0], Some(2)),
            ([-2.0, 0.0], None),
            ([0.0, 1.0], None),
            ([-0.75, 0.0], None),
        ] {
            // c along i, along j and along k: every unit imaginary squares to −1, so the
            // counts agree.
            for axis in 1..4 {
                let mut cq = [c[0], 0.0, 0.0, 0.0];
                cq[axis] = c[1];
                assert_eq!(
                    esc(&julia(cq), Quaternion::default(), 10_000),
                    want,
                    "c = {cq:?}"
                );
            }
        }
        // The slice's complex plane equals the complex Julia set point for point.
        let s = IterSettings {
            max_iter: 200,
            bailout2: 4.0,
            strict: true,
            period_tol: 0.0,
            want_de: false,
        };
        let jc = julia([-0.8, 0.156, 0.0, 0.0]);
        for y in -10..=10 {
            for x in -15..=15 {
                let z = C::new(x as f64 * 0.1, y as f64 * 0.1);
                let complex = iterate_quadratic_scalar(z, C::new(-0.8, 0.156), &s);
                let quat = esc(&jc, Quaternion([z.re, z.im, 0.0, 0.0]), 200);
                assert_eq!(quat, (!complex.inside).then_some(complex.n), "z = {z:?}");
            }
        }
    }

    #[test]
    fn distance_estimate_oracles() {
        // Julia c = 0 from z₀ = 2: b = 4 ln 2 for every n; Julia c = −1 from 2: b = 1.359082
        // (R = 1e10).
        let o = julia([0.0; 4]).iterate(Quaternion([2.0, 0.0, 0.0, 0.0]), 100, 1e10);
        assert!((o.b - 4.0 * 2f64.ln()).abs() < 1e-12, "{}", o.b);
        let o = julia([-1.0, 0.0, 0.0, 0.0]).iterate(Quaternion([2.0, 0.0, 0.0, 0.0]), 100, 1e10);
        assert!((o.b - 1.359082).abs() < 5e-7, "{}", o.b);
        // Off the real axis too: start 2j with c = 0 is the same orbit's length.
        let o = julia([0.0; 4]).iterate(Quaternion([0.0, 0.0, 2.0, 0.0]), 100, 1e10);
        assert!((o.b - 4.0 * 2f64.ln()).abs() < 1e-12);
        // c = 0: the set is the unit ball; b/4 ≤ true distance ≤ b.
        let j0 = QuaternionJulia {
            c: [0.0; 4],
            iterations: 60,
            ..QuaternionJulia::default()
        };
        for r in [1.1, 1.5, 3.0] {
            let p = DVec3::new(r, 0.0, 0.0).normalize() * r;
            let d = j0.distance(p);
            assert!(d <= r - 1.0 && 4.0 * d >= (r - 1.0) * 0.999, "r {r}: {d}");
        }
        assert_eq!(j0.distance(DVec3::new(0.5, 0.2, 0.1)), 0.0);
    }

    #[test]
    fn symmetry_of_the_slices() {
        // With c in the complex plane (c₂ = c₃ = 0) the set is unchanged by rotations of the
        // (j, k) plane: the slice k = 0 equals the slice j = 0.
        let base = julia([-0.2, 0.8, 0.0, 0.0]);
        let kslice = QuaternionJulia {
            slice: SliceAxis::K,
            ..base
        };
        let jslice = QuaternionJulia {
            slice: SliceAxis::J,
            ..base
        };
        for k in 0..200 {
            let p = DVec3::new(
                ((k * 37) % 41) as f64 / 20.0 - 1.0,
                ((k * 11) % 23) as f64 / 11.0 - 1.0,
                ((k * 7) % 19) as f64 / 9.0 - 1.0,
            );
            let a = kslice.iterate(kslice.point(p), 30, 2.0);
            let b = jslice.iterate(jslice.point(p), 30, 2.0);
            assert_eq!(a.escaped_at, b.escaped_at, "{p:?}");
        }
        // Point symmetry q → −q of q² + c.
        for p in [DVec3::new(0.3, 0.4, -0.2), DVec3::new(-0.9, 0.1, 0.5)] {
            let a = base.iterate(base.point(p), 50, 2.0);
            let b = base.iterate(base.point(-p), 50, 2.0);
            assert_eq!(a.escaped_at, b.escaped_at);
        }
        // The slice maps the free components in order.
        let s = QuaternionJulia {
            slice: SliceAxis::I,
            slice_value: 0.5,
            ..base
        };
        assert_eq!(s.point(DVec3::new(1.0, 2.0, 3.0)).0, [1.0, 0.5, 2.0, 3.0]);
    }

    #[test]
    fn escape_radius_bounds_the_set_and_marching_finds_the_ball() {
        let j = julia([-0.2, 0.8, 0.3, 0.1]);
        let r = j.escape_radius();
        // Just outside the radius everything escapes.
        for k in 0..50 {
            let a = k as f64 * 0.7;
            let p = DVec3::new(a.cos(), (a * 1.3).sin(), a.sin()).normalize() * (r * 1.0001);
            assert!(j.iterate(j.point(p), 1000, r).escaped_at.is_some());
        }
        // c = 0: a ray from z = 3 towards the origin meets the unit ball at t ≈ 2.
        let j0 = QuaternionJulia {
            c: [0.0; 4],
            iterations: 40,
            ..QuaternionJulia::default()
        };
        let t = j0
            .march(DVec3::new(0.0, 0.0, 3.0), -DVec3::Z, 0.0, 6.0, |_| 1e-5)
            .unwrap();
        assert!((t - 2.0).abs() < 1e-3, "{t}");
        let n = j0.normal(DVec3::new(0.0, 0.0, 3.0 - t), 1e-4);
        assert!(n.dot(DVec3::Z) > 0.999, "{n:?}");
        // A ray passing beside the ball misses.
        assert!(
            j0.march(DVec3::new(1.2, 0.0, 3.0), -DVec3::Z, 0.0, 6.0, |_| 1e-5)
                .is_none()
        );
        // Closest approach of the bounding-sphere helper.
        let (t0, t1) = ray_sphere(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z, DVec3::ZERO, 2.0).unwrap();
        assert!((t0 - 3.0).abs() < 1e-12 && (t1 - 7.0).abs() < 1e-12);
    }

    #[test]
    fn parameters_have_limits() {
        assert!(julia([0.0; 4]).validate().is_ok());
        assert!(julia([5.0, 0.0, 0.0, 0.0]).validate().is_err());
        assert!(julia([f64::NAN, 0.0, 0.0, 0.0]).validate().is_err());
        let j = QuaternionJulia {
            iterations: 0,
            ..QuaternionJulia::default()
        };
        assert!(j.validate().unwrap_err().contains("iterations"));
        let j = QuaternionJulia {
            slice_value: 9.0,
            ..QuaternionJulia::default()
        };
        assert!(j.validate().unwrap_err().contains("slice_value"));
    }
}
