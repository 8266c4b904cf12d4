//! Iteration families and the scalar per-point iteration.

use super::complex::C;
pub use super::newton::NewtonSystem;
use super::warp::Warp;

/// What is iterated.
#[derive(Clone, Debug, PartialEq)]
// A handful of these exist at a time; boxing the warp would only add indirection.
#[allow(clippy::large_enum_variant)]
pub enum Family {
    /// z₀ = 0, z ← z^m + c, c = pixel (m = 2: the Mandelbrot set).
    Mandelbrot {
        /// The exponent m.
        power: u32,
    },
    /// z₀ = pixel, z ← z^m + c.
    Julia {
        /// The exponent m.
        power: u32,
        /// The constant c.
        c: C,
    },
    /// Newton's method for a polynomial given by its coefficients, highest degree first.
    Newton {
        /// The polynomial's coefficients, highest degree first.
        coeffs: Vec<C>,
    },
    /// Parameter plane of λz(1 − z) (or Köse's λz(z − 1)), λ = pixel, from z₀.
    Logistic {
        /// The starting value z₀.
        z0: C,
        /// Iterate Köse's λz(z − 1) instead of λz(1 − z).
        kose: bool,
    },
    /// The Burning Ship (Michelitsch and Rössler): z₀ = 0, z ← (|Re z| + i·|Im z|)² + c,
    /// c = pixel.
    BurningShip,
    /// Julia set of z³ + z + p.
    Cubic {
        /// The parameter p.
        p: C,
    },
    /// Warped quadratic Julia texture (Borowicz).
    WarpedJulia(Warp),
}

impl Family {
    /// The family's name as written in view files: "mandelbrot" (power 2), "multibrot", "julia",
    /// "burning-ship", "newton", "logistic", "cubic" or "warped-julia".
    pub fn name(&self) -> &'static str {
        match self {
            Family::Mandelbrot { power: 2 } => "mandelbrot",
            Family::Mandelbrot { .. } => "multibrot",
            Family::Julia { .. } => "julia",
            Family::BurningShip => "burning-ship",
            Family::Newton { .. } => "newton",
            Family::Logistic { .. } => "logistic",
            Family::Cubic { .. } => "cubic",
            Family::WarpedJulia(_) => "warped-julia",
        }
    }

    /// Degree of the map (for smooth colouring).
    pub fn degree(&self) -> f64 {
        match self {
            Family::Mandelbrot { power } | Family::Julia { power, .. } => *power as f64,
            Family::Newton { coeffs } => (coeffs.len().max(2) - 1) as f64,
            Family::Logistic { .. } | Family::WarpedJulia(_) | Family::BurningShip => 2.0,
            Family::Cubic { .. } => 3.0,
        }
    }

    /// Default escape radius for integer colouring and for smooth/distance colouring.
    pub fn default_bailout(&self, smooth: bool) -> f64 {
        match self {
            Family::Logistic { kose: false, .. } => 1e6,
            Family::WarpedJulia(_) | Family::Cubic { .. } => {
                if smooth {
                    256.0
                } else {
                    2.0
                }
            }
            _ => {
                if smooth {
                    256.0
                } else {
                    2.0
                }
            }
        }
    }

    /// The default view: centre and half-height.
    pub fn default_view(&self) -> ([f64; 2], f64) {
        match self {
            Family::Mandelbrot { power: 2 } => ([-0.7, 0.0], 1.25),
            Family::Mandelbrot { .. } => ([0.0, 0.0], 1.4),
            Family::Julia { .. } => ([0.0, 0.0], 1.5),
            Family::BurningShip => ([-0.4, -0.55], 1.25),
            Family::Newton { .. } => ([0.0, 0.0], 2.0),
            Family::Logistic { kose: false, .. } => ([1.0, 0.0], 2.0),
            Family::Logistic { kose: true, .. } => ([0.085, 1.073], 1.5),
            Family::Cubic { .. } => ([0.0, 0.0], 2.1),
            Family::WarpedJulia(_) => ([0.5, 0.5], 0.5),
        }
    }

    /// True when the symmetric quadratic lane engine applies.
    pub fn is_quadratic(&self) -> bool {
        matches!(
            self,
            Family::Mandelbrot { power: 2 }
                | Family::Julia { power: 2, .. }
                | Family::WarpedJulia(_)
        )
    }
}

/// The result for one point.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Sample {
    /// Iterations done (the escape iteration for escaped points; Newton steps).
    pub n: u32,
    /// Did not escape (or, for Newton, did not converge) within the limit.
    pub inside: bool,
    /// Normalised (smooth) iteration count.
    pub nu: f64,
    /// Exterior distance estimate b in world units (0 when not computed).
    pub de: f32,
    /// Newton: index of the root reached (255: none).
    pub root: u8,
}

impl Sample {
    /// A point that did not escape within `max_iter` iterations.
    pub fn inside(max_iter: u32) -> Sample {
        Sample {
            n: max_iter,
            inside: true,
            nu: max_iter as f64,
            de: 0.0,
            root: 255,
        }
    }

    /// A point that escaped before the first iteration.
    pub fn escaped_at_zero() -> Sample {
        Sample {
            n: 0,
            inside: false,
            nu: 0.0,
            de: 0.0,
            root: 255,
        }
    }
}

/// ν = n + 1 − ln(ln|z|)/ln m.
pub fn smooth_count(n: u32, z_norm2: f64, degree: f64) -> f64 {
    let ln_abs = 0.5 * z_norm2.ln();
    if !(ln_abs > 0.0) || !ln_abs.is_finite() {
        return n as f64;
    }
    n as f64 + 1.0 - ln_abs.ln() / degree.ln()
}

/// b = 2|z| ln|z| / |z′|.
pub fn distance_estimate(z: C, dz: C) -> f64 {
    let a = z.abs();
    2.0 * a * a.ln() / dz.abs()
}

/// Iteration limits and tests for one render.
#[derive(Clone, Copy, Debug)]
pub struct IterSettings {
    pub max_iter: u32,
    /// R², compared strictly (|z|² > R²) except for the warped textures (|z| ≥ 2).
    pub bailout2: f64,
    pub strict: bool,
    /// Periodicity tolerance (0: off).
    pub period_tol: f64,
    pub want_de: bool,
}

impl IterSettings {
    /// Has an orbit with |z|² = r2 escaped? (A NaN, an overflowed orbit, has.)
    #[inline]
    pub fn escaped(&self, r2: f64) -> bool {
        if self.strict {
            !(r2 <= self.bailout2)
        } else {
            !(r2 < self.bailout2)
        }
    }

    /// The sample of an orbit that escaped at iteration n with z (|z|² = r2) and derivative
    /// dz, for a map of degree `deg`.
    #[inline]
    pub fn escape_sample(&self, n: u32, z: C, r2: f64, dz: C, deg: f64) -> Sample {
        Sample {
            n,
            inside: false,
            nu: smooth_count(n, r2, deg),
            de: if self.want_de {
                distance_estimate(z, dz) as f32
            } else {
                0.0
            },
            root: 255,
        }
    }
}

/// Main cardioid and period-2 bulb of the Mandelbrot set.
pub fn in_cardioid_or_bulb(x: f64, y: f64) -> bool {
    let xq = x - 0.25;
    let q = xq * xq + y * y;
    q * (q + xq) <= 0.25 * y * y || (x + 1.0) * (x + 1.0) + y * y <= 0.0625
}

/// Periodicity checking (Brent's): the orbit is saved at iterations 2, 4, 8, …, and a later
/// point within `tol` of the saved one in both parts means a cycle.
struct Cycle {
    saved: C,
    next_save: u32,
}

impl Cycle {
    fn new(z: C) -> Cycle {
        Cycle {
            saved: z,
            next_save: 2,
        }
    }

    /// After iteration n reached z: has the orbit been found to cycle?
    #[inline]
    fn found(&mut self, n: u32, z: C, tol: f64) -> bool {
        if tol <= 0.0 {
            return false;
        }
        if n == self.next_save {
            self.saved = z;
            self.next_save = self.next_save.saturating_mul(2);
            false
        } else {
            (z.re - self.saved.re).abs() < tol && (z.im - self.saved.im).abs() < tol
        }
    }
}

/// Iterate one point of a polynomial family (everything except Newton) in scalar code:
/// returns the sample. `z0`, `c` as the family defines them; `deg` for smooth colouring.
/// `step` maps (z, c) → z′ and `dstep` (z, dz, c) → dz′ for distance estimation.
fn iterate_poly(
    s: &IterSettings,
    mut z: C,
    c: C,
    mut dz: C,
    deg: f64,
    step: impl Fn(C, C) -> C,
    dstep: impl Fn(C, C) -> C,
) -> Sample {
    let mut cycle = Cycle::new(z);
    for n in 1..=s.max_iter {
        if s.want_de {
            dz = dstep(z, dz);
        }
        z = step(z, c);
        let r2 = z.norm2();
        if s.escaped(r2) {
            return s.escape_sample(n, z, r2, dz, deg);
        }
        if cycle.found(n, z, s.period_tol) {
            return Sample::inside(s.max_iter);
        }
    }
    Sample::inside(s.max_iter)
}

/// The Burning Ship's fold: (|Re z|, |Im z|) and the signs of the parts (the fold's
/// Jacobian, diagonal).
#[inline]
pub fn ship_fold(z: C) -> (C, f64, f64) {
    (
        C::new(z.re.abs(), z.im.abs()),
        1f64.copysign(z.re),
        1f64.copysign(z.im),
    )
}

/// One step of a column v of the Burning Ship's Jacobian ∂z/∂c: v ← 2·F(z)·(sx·v.re,
/// sy·v.im) + e, with F the fold and e the column's unit vector. The map is not holomorphic,
/// so dz/dc is a real 2×2 matrix, carried as its two columns.
#[inline]
pub fn ship_jacobian_step(v: C, z: C, e: C) -> C {
    let (f, sx, sy) = ship_fold(z);
    f * 2.0 * C::new(sx * v.re, sy * v.im) + e
}

/// The size of a Jacobian with columns a and b that stands for |dz/dc| in the distance
/// estimate: its Frobenius norm over √2, which is |dz/dc| for a holomorphic map.
pub fn jacobian_size(a: f64, b: f64) -> f64 {
    ((a * a + b * b) * 0.5).sqrt()
}

/// The Burning Ship at c, from z₀ = 0; distance estimates from the Jacobian.
fn iterate_ship(s: &IterSettings, c: C) -> Sample {
    let mut z = C::ZERO;
    let (mut jx, mut jy) = (C::ZERO, C::ZERO);
    let mut cycle = Cycle::new(z);
    for n in 1..=s.max_iter {
        if s.want_de {
            jx = ship_jacobian_step(jx, z, C::ONE);
            jy = ship_jacobian_step(jy, z, C::new(0.0, 1.0));
        }
        let f = ship_fold(z).0;
        z = C::new(f.re * f.re - f.im * f.im + c.re, 2.0 * f.re * f.im + c.im);
        let r2 = z.norm2();
        if s.escaped(r2) {
            let size = jacobian_size(jx.abs(), jy.abs());
            return s.escape_sample(n, z, r2, C::new(size, 0.0), 2.0);
        }
        if cycle.found(n, z, s.period_tol) {
            return Sample::inside(s.max_iter);
        }
    }
    Sample::inside(s.max_iter)
}

/// z^m with m ≥ 1.
fn pow(z: C, m: u32) -> C {
    match m {
        2 => z * z,
        3 => z * z * z,
        _ => z.powi(m),
    }
}

/// The scalar iteration of a point for every family but Newton and the warped textures
/// (whose starting values the renderer computes). `point` is the pixel's complex value.
pub fn iterate_point(family: &Family, point: C, s: &IterSettings) -> Sample {
    match family {
        Family::Mandelbrot { power } => {
            let m = *power;
            if m == 2 && in_cardioid_or_bulb(point.re, point.im) {
                return Sample::inside(s.max_iter);
            }
            iterate_poly(
                s,
                C::ZERO,
                point,
                C::ZERO,
                m as f64,
                |z, c| pow(z, m) + c,
                |z, dz| pow(z, m - 1) * dz * m as f64 + C::ONE,
            )
        }
        Family::Julia { power, c } => {
            let m = *power;
            iterate_poly(
                s,
                point,
                *c,
                C::ONE,
                m as f64,
                |z, c| pow(z, m) + c,
                |z, dz| pow(z, m - 1) * dz * m as f64,
            )
        }
        Family::BurningShip => iterate_ship(s, point),
        Family::Logistic { z0, kose } => {
            let sign = if *kose { -1.0 } else { 1.0 };
            // f = s·λ z (1 − z); d/dλ: dz′ = s·(z(1 − z) + λ(1 − 2z) dz).
            let lam = point;
            iterate_poly(
                s,
                *z0,
                lam,
                C::ZERO,
                2.0,
                move |z, l| l * z * (C::ONE - z) * sign,
                move |z, dz| (z * (C::ONE - z) + lam * (C::ONE - z * 2.0) * dz) * sign,
            )
        }
        Family::Cubic { p } => iterate_poly(
            s,
            point,
            *p,
            C::ONE,
            3.0,
            |z, p| z * z * z + z + p,
            |z, dz| (z * z * 3.0 + C::ONE) * dz,
        ),
        Family::Newton { coeffs } => NewtonSystem::new(coeffs).iterate(point, s.max_iter),
        Family::WarpedJulia(w) => {
            let z0 = w.start(point);
            if !z0.is_finite() {
                return Sample::escaped_at_zero();
            }
            iterate_quadratic_scalar(z0, w.c, s)
        }
    }
}

/// z ← z² + c from z₀ (the warped textures and the lane engine's reference).
pub fn iterate_quadratic_scalar(z0: C, c: C, s: &IterSettings) -> Sample {
    iterate_poly(
        s,
        z0,
        c,
        C::ONE,
        2.0,
        |z, c| {
            // The same operation order as the lane engine: (x + x)·y + cy.
            C::new(
                z.re * z.re - z.im * z.im + c.re,
                (z.re + z.re) * z.im + c.im,
            )
        },
        |z, dz| z * dz * 2.0,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings(max: u32, r: f64) -> IterSettings {
        IterSettings {
            max_iter: max,
            bailout2: r * r,
            strict: true,
            period_tol: 0.0,
            want_de: false,
        }
    }

    fn mandel(c: C, max: u32, r: f64) -> Sample {
        iterate_point(&Family::Mandelbrot { power: 2 }, c, &settings(max, r))
    }

    #[test]
    fn mandelbrot_oracles_7_1() {
        let esc = |re, im| {
            let s = mandel(C::new(re, im), 10_000, 2.0);
            (!s.inside).then_some(s.n)
        };
        assert_eq!(esc(1.0, 0.0), Some(3));
        assert_eq!(esc(2.0, 0.0), Some(2));
        assert_eq!(esc(-2.0, 0.0), None, "strict inequality");
        for (re, im) in [
            (0.0, 0.0),
            (-1.0, 0.0),
            (0.0, 1.0),
            (0.0, -1.0),
            (0.25, 0.0),
            (-0.75, 0.0),
        ] {
            assert_eq!(esc(re, im), None, "{re}+{im}i is bounded");
        }
        assert_eq!(esc(0.2, 0.75), Some(6));
        assert_eq!(esc(0.0, 0.64), Some(55));
        assert_eq!(esc(0.0, -0.66), Some(17));
        assert_eq!(esc(0.26, 0.0), Some(30));
        assert_eq!(esc(2.1, 0.3), Some(1));
        assert_eq!(esc(-1.5, -1.5), Some(1));
        // Köse z² − μ: μ = −1 is c = 1.
        assert_eq!(esc(1.0, 0.0), Some(3));
    }

    #[test]
    fn smooth_and_distance_oracles_7_3() {
        for (c, r, n, nu) in [
            (C::new(1.0, 0.0), 2.0, 3, 3.313443),
            (C::new(1.0, 0.0), 1000.0, 6, 3.295643),
            (C::new(1.0, 0.0), 1e6, 7, 3.295643),
            (C::new(0.2, 0.75), 2.0, 6, 6.588449),
            (C::new(0.2, 0.75), 1000.0, 9, 6.617342),
            (C::new(-0.75, 0.1), 2.0, 33, 34.007382),
            (C::new(-0.75, 0.1), 1000.0, 36, 33.953334),
        ] {
            let s = mandel(c, 1000, r);
            assert_eq!(s.n, n, "{c:?} R={r}");
            assert!((s.nu - nu).abs() < 5e-7, "{c:?} R={r}: ν {} vs {nu}", s.nu);
        }
        let de = |f: &Family, p: C| {
            let s = IterSettings {
                want_de: true,
                ..settings(10_000, 1e10)
            };
            iterate_point(f, p, &s).de as f64
        };
        let m = Family::Mandelbrot { power: 2 };
        for (c, b) in [
            (C::new(1.0, 0.0), 1.295310),
            (C::new(2.0, 0.0), 4.538240),
            (C::new(-2.5, 0.0), 1.910552),
            (C::new(0.0, 1.1), 0.182758),
            (C::new(-0.75, 0.1), 0.001126),
        ] {
            let got = de(&m, c);
            assert!((got - b).abs() < 2e-6 * b.max(1.0), "{c:?}: {got} vs {b}");
        }
        let j0 = Family::Julia {
            power: 2,
            c: C::ZERO,
        };
        assert!((de(&j0, C::new(2.0, 0.0)) - 4.0 * 2f64.ln()).abs() < 1e-5);
        let j1 = Family::Julia {
            power: 2,
            c: C::new(-1.0, 0.0),
        };
        assert!((de(&j1, C::new(2.0, 0.0)) - 1.359082).abs() < 1e-5);
    }

    #[test]
    fn other_families_7_4() {
        let cubic = Family::Cubic {
            p: C::new(0.171, 0.0),
        };
        let esc = |f: &Family, z: C, r: f64| {
            let s = iterate_point(f, z, &settings(5000, r));
            (!s.inside).then_some(s.n)
        };
        assert_eq!(esc(&cubic, C::ZERO, 2.0), Some(6));
        assert_eq!(esc(&cubic, C::ONE, 2.0), Some(1));
        assert_eq!(esc(&cubic, C::new(0.5, 0.0), 2.0), Some(3));
        assert_eq!(esc(&cubic, C::new(-0.5, 0.0), 2.0), Some(10));
        assert_eq!(esc(&cubic, C::new(0.2, 0.0), 2.0), Some(4));
        assert_eq!(esc(&cubic, C::new(0.0, 0.1), 2.0), Some(6));
        let k = 1.0 / 3f64.sqrt();
        assert_eq!(esc(&cubic, C::new(0.0, k), 2.0), None);
        assert_eq!(esc(&cubic, C::new(0.0, -k), 2.0), None);

        let logistic = Family::Logistic {
            z0: C::new(0.5, 0.0),
            kose: false,
        };
        for l in [1.0, 2.0, 3.0, 3.2, 4.0] {
            assert_eq!(esc(&logistic, C::new(l, 0.0), 1e6), None, "λ = {l}");
        }
        assert_eq!(esc(&logistic, C::new(4.1, 0.0), 1e6), Some(7));
        assert_eq!(esc(&logistic, C::new(1.0, 1.0), 1e6), Some(9));
        let kose = Family::Logistic {
            z0: C::new(0.25, 0.75),
            kose: true,
        };
        assert_eq!(esc(&kose, C::new(1.0, 0.0), 2.0), Some(4));
        assert_eq!(esc(&kose, C::new(2.0, 0.0), 2.0), Some(2));
        assert_eq!(esc(&kose, C::new(3.0, 0.0), 2.0), Some(1));
        assert_eq!(esc(&kose, C::new(-1.0, 0.0), 2.0), None);
        assert_eq!(esc(&kose, C::new(0.5, 0.5), 2.0), None);
        // Conjugacy w = λ(½ − z): λ(½ − f(z)) = w² + c(λ), c = λ/2 − λ²/4.
        let (l, z) = (C::new(2.7, 0.3), C::new(0.3, 0.1));
        let f = l * z * (C::ONE - z);
        let w = l * (C::new(0.5, 0.0) - z);
        let c = l * 0.5 - l * l * 0.25;
        let lhs = l * (C::new(0.5, 0.0) - f);
        let rhs = w * w + c;
        assert!((lhs - rhs).abs() < 1e-12);
        assert!((rhs - C::new(-0.1692, -0.4944)).abs() < 1e-12);
        // Higher powers: z⁴ + c Mandelbrot has 3-fold symmetry.
        let m4 = Family::Mandelbrot { power: 4 };
        let rot = C::from_polar(1.0, 2.0 * std::f64::consts::PI / 3.0);
        for p in [C::new(0.4, 0.3), C::new(-0.2, 0.9), C::new(0.7, -0.1)] {
            let a = iterate_point(&m4, p, &settings(200, 2.0));
            let b = iterate_point(&m4, p * rot, &settings(200, 2.0));
            assert_eq!(a.n, b.n, "{p:?}");
        }
    }

    #[test]
    fn burning_ship_oracles() {
        let ship = Family::BurningShip;
        let esc = |re, im| {
            let s = iterate_point(&ship, C::new(re, im), &settings(10_000, 2.0));
            (!s.inside).then_some(s.n)
        };
        // −i: 0 → −i → −1 − i → i → −1 − i, a cycle; +i: i → −1 + i → 3i escapes.
        assert_eq!(esc(0.0, -1.0), None);
        assert_eq!(esc(0.0, 1.0), Some(3));
        // The fold matters off the real axis: −0.5 + 0.5i escapes at the 4th iteration for
        // the ship but is bounded for z² + c.
        assert_eq!(esc(-0.5, 0.5), Some(4));
        let m = iterate_point(
            &Family::Mandelbrot { power: 2 },
            C::new(-0.5, 0.5),
            &settings(10_000, 2.0),
        );
        assert!(m.inside);
        // On the real axis the ship is z² + c; where the orbit stays positive the fold is the
        // identity and the Jacobian conformal: the same distance estimates too.
        let s = IterSettings {
            want_de: true,
            ..settings(10_000, 1e10)
        };
        for c in [C::new(2.0, 0.0), C::new(1.0, 0.0), C::new(0.3, 0.0)] {
            let a = iterate_point(&ship, c, &s);
            let b = iterate_point(&Family::Mandelbrot { power: 2 }, c, &s);
            assert_eq!((a.n, a.nu), (b.n, b.nu), "{c:?}");
            assert!(
                (a.de - b.de).abs() <= 1e-6 * b.de,
                "{c:?}: {} {}",
                a.de,
                b.de
            );
        }
        assert_eq!(esc(-1.75, 0.0), None, "the period-3 window");
    }
}
