//! The Lorenz attractor (E. N. Lorenz, "Deterministic nonperiodic flow", 1963):
//! ẋ = σ(y − x), ẏ = r x − y − x z, ż = −b z + x y, integrated by the classical fourth-order
//! Runge–Kutta method, with the sensitivity demonstration (two starts 1e-9 apart).

use super::{ExploreError, P2, check_range};

/// A point of space (x, y, z).
pub type P3 = [f64; 3];

/// Default step (0.005 for high-quality plots).
pub const DEFAULT_STEP: f64 = 0.01;
/// Default start.
pub const DEFAULT_START: P3 = [1.0, 1.0, 1.0];
/// Default time discarded before plotting (the transient).
pub const DEFAULT_TRANSIENT: f64 = 10.0;
/// Most integration steps of one orbit.
pub const MAX_STEPS: u64 = 100_000_000;

/// The parameters σ, r, b.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lorenz {
    /// σ, the Prandtl number.
    pub sigma: f64,
    /// r, the relative Rayleigh number.
    pub r: f64,
    /// b, the geometric factor.
    pub b: f64,
}

impl Default for Lorenz {
    /// Lorenz's values: σ = 10, r = 28, b = 8/3.
    fn default() -> Self {
        Lorenz {
            sigma: 10.0,
            r: 28.0,
            b: 8.0 / 3.0,
        }
    }
}

impl Lorenz {
    /// Parameters within 0 < σ ≤ 100, 0 < r ≤ 1000, 0 < b ≤ 100.
    pub fn new(sigma: f64, r: f64, b: f64) -> Result<Lorenz, ExploreError> {
        check_range("σ (sigma)", sigma, 1e-6, 100.0)?;
        check_range("r", r, 1e-6, 1000.0)?;
        check_range("b", b, 1e-6, 100.0)?;
        Ok(Lorenz { sigma, r, b })
    }

    /// The vector field at p.
    #[inline]
    pub fn deriv(&self, p: P3) -> P3 {
        let [x, y, z] = p;
        [
            self.sigma * (y - x),
            self.r * x - y - x * z,
            -self.b * z + x * y,
        ]
    }

    /// One classical Runge–Kutta step of size h.
    #[inline]
    pub fn rk4_step(&self, p: P3, h: f64) -> P3 {
        let add = |p: P3, k: P3, s: f64| [p[0] + s * k[0], p[1] + s * k[1], p[2] + s * k[2]];
        let k1 = self.deriv(p);
        let k2 = self.deriv(add(p, k1, h / 2.0));
        let k3 = self.deriv(add(p, k2, h / 2.0));
        let k4 = self.deriv(add(p, k3, h));
        let mut out = p;
        for i in 0..3 {
            out[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        out
    }

    /// The equilibria: the origin, and for r > 1 the centres of the two wings
    /// (±√(b(r − 1)), ±√(b(r − 1)), r − 1).
    pub fn equilibria(&self) -> Vec<P3> {
        let mut v = vec![[0.0, 0.0, 0.0]];
        if self.r > 1.0 {
            let q = (self.b * (self.r - 1.0)).sqrt();
            v.push([q, q, self.r - 1.0]);
            v.push([-q, -q, self.r - 1.0]);
        }
        v
    }

    /// An orbit from `start` with step `h` (1e-5 ≤ h ≤ 0.1).
    pub fn orbit(&self, start: P3, h: f64) -> Result<Orbit, ExploreError> {
        check_range("the step h", h, 1e-5, 0.1)?;
        if !start.iter().all(|v| v.is_finite() && v.abs() <= 1e6) {
            return Err(ExploreError::Invalid(
                "the start point must be finite, each coordinate at most 1e6 in size".into(),
            ));
        }
        Ok(Orbit {
            system: *self,
            p: start,
            h,
            steps: 0,
        })
    }

    /// Two orbits from `a` and `b` side by side: their largest coordinate difference at every
    /// step (the sensitivity demonstration).
    pub fn twin(&self, a: P3, b: P3, h: f64) -> Result<Twin, ExploreError> {
        Ok(Twin {
            a: self.orbit(a, h)?,
            b: self.orbit(b, h)?,
        })
    }
}

/// An orbit being integrated; an iterator over its points after each step.
#[derive(Clone, Debug)]
pub struct Orbit {
    system: Lorenz,
    p: P3,
    h: f64,
    steps: u64,
}

impl Orbit {
    /// The current point.
    pub fn point(&self) -> P3 {
        self.p
    }

    /// Time integrated so far (steps × step size).
    pub fn time(&self) -> f64 {
        self.steps as f64 * self.h
    }

    /// Integration steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Integrate until time `t` (no points returned).
    pub fn advance_to(&mut self, t: f64) {
        let n = (t / self.h).round() as u64;
        while self.steps < n.min(MAX_STEPS) {
            self.next();
        }
    }
}

impl Iterator for Orbit {
    type Item = P3;

    #[inline]
    fn next(&mut self) -> Option<P3> {
        self.p = self.system.rk4_step(self.p, self.h);
        self.steps += 1;
        Some(self.p)
    }
}

/// Two orbits integrated together.
#[derive(Clone, Debug)]
pub struct Twin {
    /// The orbit from the first start.
    pub a: Orbit,
    /// The orbit from the second start.
    pub b: Orbit,
}

impl Twin {
    /// Step both; the new points.
    pub fn step(&mut self) -> (P3, P3) {
        (
            self.a.next().unwrap_or_default(),
            self.b.next().unwrap_or_default(),
        )
    }

    /// The largest coordinate difference of the current points.
    pub fn separation(&self) -> f64 {
        let (p, q) = (self.a.point(), self.b.point());
        (0..3).map(|i| (p[i] - q[i]).abs()).fold(0.0, f64::max)
    }

    /// The Euclidean distance of the current points.
    pub fn distance(&self) -> f64 {
        let (p, q) = (self.a.point(), self.b.point());
        ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
    }

    /// Time integrated so far.
    pub fn time(&self) -> f64 {
        self.a.time()
    }
}

/// How a 3-D point is shown in the plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum View {
    /// Along z: (x, y).
    Xy,
    /// Along y: (x, z) — the familiar butterfly.
    Xz,
    /// Along x: (y, z).
    Yz,
    /// Turned by `yaw` about z, then tilted by `pitch` about x (radians), seen along the new y.
    Turned {
        /// Turn about z, radians.
        yaw: f64,
        /// Tilt about x, radians.
        pitch: f64,
    },
}

impl View {
    /// The plane point showing `p`.
    pub fn project(self, p: P3) -> P2 {
        match self {
            View::Xy => [p[0], p[1]],
            View::Xz => [p[0], p[2]],
            View::Yz => [p[1], p[2]],
            View::Turned { yaw, pitch } => {
                let (sy, cy) = yaw.sin_cos();
                let (sp, cp) = pitch.sin_cos();
                let x = cy * p[0] - sy * p[1];
                let y = sy * p[0] + cy * p[1];
                // Pitch about the x axis; the screen shows (x, z′).
                let z = -sp * y + cp * p[2];
                [x, z]
            }
        }
    }
}

/// What [`Lorenz::render`] draws.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    /// The start of the orbit.
    pub start: P3,
    /// Integration step size.
    pub h: f64,
    /// Time integrated before drawing starts.
    pub transient: f64,
    /// Time drawn after the transient.
    pub time: f64,
    /// How the orbit is projected onto the picture.
    pub view: View,
    /// Picture width in pixels.
    pub width: u32,
    /// Picture height in pixels.
    pub height: u32,
    /// Colour of the orbit (RGB).
    pub color: [u8; 3],
    /// Colour of the background (RGB).
    pub background: [u8; 3],
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            start: DEFAULT_START,
            h: DEFAULT_STEP,
            transient: DEFAULT_TRANSIENT,
            time: 200.0,
            view: View::Xz,
            width: 800,
            height: 600,
            color: [255, 170, 60],
            background: [8, 8, 16],
        }
    }
}

impl Lorenz {
    /// Steps of an orbit for `time` at step `h`, refused beyond [`MAX_STEPS`].
    pub fn steps_for(time: f64, h: f64) -> Result<u64, ExploreError> {
        check_range("the time", time, 0.0, 1e9)?;
        let n = (time / h).round();
        if n > MAX_STEPS as f64 {
            return Err(ExploreError::TooLarge {
                what: format!("integrating for t = {time} with h = {h}"),
                count: n,
                limit: MAX_STEPS as f64,
                hint: " steps; shorten the time or lengthen the step".into(),
            });
        }
        Ok(n as u64)
    }

    /// The orbit drawn as a density picture: the path between successive steps is sampled
    /// about once per pixel, and the hit counts are shown on a log scale. The framing fits
    /// the projected orbit (two passes over the same deterministic orbit).
    pub fn render(&self, o: &RenderOptions) -> Result<image::RgbImage, ExploreError> {
        super::raster::check_size(o.width, o.height)?;
        let skip = Self::steps_for(o.transient, o.h)?;
        let steps = Self::steps_for(o.time, o.h)?;
        if steps == 0 {
            return Err(ExploreError::Invalid(
                "nothing to draw: the time is 0".into(),
            ));
        }
        let run = |f: &mut dyn FnMut(P2)| -> Result<(), ExploreError> {
            let mut orbit = self.orbit(o.start, o.h)?;
            for _ in 0..skip {
                orbit.next();
            }
            f(o.view.project(orbit.point()));
            for p in orbit.take(steps as usize) {
                f(o.view.project(p));
            }
            Ok(())
        };
        let mut b = super::Bounds::EMPTY;
        run(&mut |p| b.add(p))?;
        if b.is_empty() || !(b.width().is_finite() && b.height().is_finite()) {
            return Err(ExploreError::Invalid(
                "the orbit left every finite range; try a smaller step h".into(),
            ));
        }
        let margin = 0.04 * o.width.min(o.height) as f64;
        let f = super::raster::Framing::fit(b, o.width, o.height, margin);
        let mut d = super::raster::Density::new(o.width, o.height)?;
        let mut last: Option<P2> = None;
        run(&mut |p| {
            let q = f.pixel_from_world(p);
            match last {
                Some(a) => d.line(a, q),
                None => d.plot(q),
            }
            last = Some(q);
        })?;
        Ok(d.to_image(o.color, o.background))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close3(a: P3, b: P3, tol: f64) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() <= tol)
    }

    #[test]
    fn field_and_steps() {
        let l = Lorenz::default();
        let d = l.deriv([1.0, 1.0, 1.0]);
        assert!(close3(d, [0.0, 26.0, -5.0 / 3.0], 1e-15));
        let p = l.rk4_step([1.0, 1.0, 1.0], 0.01);
        assert!(close3(p, [1.0125672, 1.2599178, 0.9848910], 5e-8), "{p:?}");
        let mut o = l.orbit(DEFAULT_START, 0.01).unwrap();
        o.advance_to(1.0);
        assert_eq!(o.steps(), 100);
        assert!(
            close3(o.point(), [-9.378616, -8.357060, 29.362404], 1e-6),
            "{:?}",
            o.point()
        );
    }

    #[test]
    fn equilibria() {
        let l = Lorenz::default();
        let e = l.equilibria();
        assert_eq!(e.len(), 3);
        assert!(close3(e[1], [8.485281, 8.485281, 27.0], 5e-7));
        assert!(close3(e[2], [-8.485281, -8.485281, 27.0], 5e-7));
        for p in e {
            assert!(close3(l.deriv(p), [0.0; 3], 1e-12));
        }
        assert_eq!(
            Lorenz::new(10.0, 0.5, 8.0 / 3.0)
                .unwrap()
                .equilibria()
                .len(),
            1
        );
    }

    #[test]
    fn sensitivity() {
        // Within 1e-6 (in every coordinate) at t = 20, more than 1 apart by t = 40. The
        // Euclidean distance at t = 20 is 1.07e-6 with h = 0.01: the figure holds for the
        // coordinate-wise difference.
        let l = Lorenz::default();
        let mut t = l
            .twin([1.0, 1.0, 1.0], [1.0 + 1e-9, 1.0, 1.0], 0.01)
            .unwrap();
        let mut max_after_40 = 0.0f64;
        for i in 1..=4000 {
            t.step();
            if i == 2000 {
                assert!((t.time() - 20.0).abs() < 1e-9);
                assert!(t.separation() < 1e-6, "{}", t.separation());
            }
            max_after_40 = max_after_40.max(t.separation());
        }
        assert!((t.time() - 40.0).abs() < 1e-9);
        assert!(
            max_after_40 > 1.0 && t.separation() > 1.0,
            "{}",
            t.separation()
        );
    }

    #[test]
    fn attractor_extent() {
        let l = Lorenz::default();
        let mut o = l.orbit(DEFAULT_START, 0.01).unwrap();
        o.advance_to(DEFAULT_TRANSIENT);
        let (mut lo, mut hi) = ([f64::MAX; 3], [f64::MIN; 3]);
        for p in o.take(100_000) {
            for i in 0..3 {
                lo[i] = lo[i].min(p[i]);
                hi[i] = hi[i].max(p[i]);
            }
        }
        // Roughly x ∈ [−19, 19], y ∈ [−26, 26], z ∈ [3, 47].
        let want = [(-19.0, 19.0), (-26.0, 26.0), (3.0, 47.0)];
        for i in 0..3 {
            assert!((lo[i] - want[i].0).abs() < 1.5, "{lo:?}");
            assert!((hi[i] - want[i].1).abs() < 1.5, "{hi:?}");
        }
    }

    #[test]
    fn views_and_limits() {
        let p = [1.0, 2.0, 3.0];
        assert_eq!(View::Xz.project(p), [1.0, 3.0]);
        let t = View::Turned {
            yaw: 0.0,
            pitch: 0.0,
        };
        assert_eq!(t.project(p), [1.0, 3.0]);
        let q = View::Turned {
            yaw: std::f64::consts::FRAC_PI_2,
            pitch: 0.0,
        }
        .project(p);
        assert!((q[0] + 2.0).abs() < 1e-15 && (q[1] - 3.0).abs() < 1e-15);
        assert!(Lorenz::new(0.0, 28.0, 1.0).is_err());
        assert!(Lorenz::new(10.0, f64::NAN, 1.0).is_err());
        assert!(Lorenz::new(10.0, 2000.0, 1.0).is_err());
        let l = Lorenz::default();
        assert!(l.orbit([1.0; 3], 0.5).is_err());
        assert!(l.orbit([f64::INFINITY, 1.0, 1.0], 0.01).is_err());
        assert!(Lorenz::steps_for(1e7, 0.01).is_err());
        assert_eq!(Lorenz::steps_for(20.0, 0.01).unwrap(), 2000);
    }

    #[test]
    fn picture_shows_both_wings() {
        let l = Lorenz::default();
        let o = RenderOptions {
            width: 120,
            height: 90,
            time: 50.0,
            ..RenderOptions::default()
        };
        let img = l.render(&o).unwrap();
        assert_eq!(img.dimensions(), (120, 90));
        // In the x–z view the wing centres (x = ±8.5, z = 27) are holes left and right of the
        // middle, ringed by the orbit.
        let lit = |x: u32, y: u32| img.get_pixel(x, y).0 != o.background;
        let lit_count = img.pixels().filter(|p| p.0 != o.background).count();
        assert!(lit_count > 120 * 90 / 10, "{lit_count}");
        let left = (0..60).filter(|&x| lit(x, 45)).count();
        let right = (60..120).filter(|&x| lit(x, 45)).count();
        assert!(left > 3 && right > 3);
        assert!(l.render(&RenderOptions { time: 0.0, ..o }).is_err());
    }
}
