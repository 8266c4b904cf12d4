//! Fractal interpolation functions (Barnsley, *Fractals Everywhere*, ch. 6): an IFS of shears
//! whose attractor is the graph of a continuous function through given data points, with a
//! free vertical scaling d_i per interval.

use super::ifs::{ChaosGame, Ifs};
use super::{ExploreError, P2};
use crate::flame::model::Affine;

/// Most data points.
pub const MAX_POINTS: usize = 1000;
/// Most points [`Fif::curve`] produces.
pub const MAX_CURVE_POINTS: usize = 4_000_000;

/// One map w_i(x, y) = (a x + e, c x + d y + f).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FifMap {
    /// Coefficient of x in x′.
    pub a: f64,
    /// Translation of x.
    pub e: f64,
    /// Coefficient of x in y′.
    pub c: f64,
    /// Coefficient of y in y′: the vertical scaling d_i.
    pub d: f64,
    /// Translation of y.
    pub f: f64,
}

impl FifMap {
    /// The image w_i(p).
    #[inline]
    pub fn apply(&self, p: P2) -> P2 {
        [
            self.a * p[0] + self.e,
            self.c * p[0] + self.d * p[1] + self.f,
        ]
    }

    /// The same map as a general affine map.
    pub fn affine(&self) -> Affine {
        Affine::new(self.a, 0.0, self.c, self.d, self.e, self.f)
    }
}

/// A fractal interpolation function: data (x_i, F_i), i = 0..N, and scalings d_1..d_N.
#[derive(Clone, Debug, PartialEq)]
pub struct Fif {
    points: Vec<P2>,
    scalings: Vec<f64>,
    maps: Vec<FifMap>,
}

impl Fif {
    /// Data points with strictly increasing x and one scaling |d_i| < 1 per interval.
    pub fn new(points: Vec<P2>, scalings: Vec<f64>) -> Result<Fif, ExploreError> {
        let mut f = Fif {
            points,
            scalings,
            maps: Vec::new(),
        };
        f.rebuild()?;
        Ok(f)
    }

    fn rebuild(&mut self) -> Result<(), ExploreError> {
        let n = self.points.len();
        if n < 2 {
            return Err(ExploreError::Invalid(
                "a fractal interpolation function needs at least two data points".into(),
            ));
        }
        if n > MAX_POINTS {
            return Err(ExploreError::TooLarge {
                what: "data points".into(),
                count: n as f64,
                limit: MAX_POINTS as f64,
                hint: String::new(),
            });
        }
        if self.scalings.len() != n - 1 {
            return Err(ExploreError::Invalid(format!(
                "{} data points need {} vertical scalings, {} given",
                n,
                n - 1,
                self.scalings.len()
            )));
        }
        for (i, p) in self.points.iter().enumerate() {
            if !(p[0].is_finite() && p[1].is_finite()) {
                return Err(ExploreError::Invalid(format!(
                    "data point {i} is not a pair of finite numbers"
                )));
            }
            if i > 0 && p[0] <= self.points[i - 1][0] {
                return Err(ExploreError::Invalid(format!(
                    "data point {i}: x = {} must be greater than the previous x = {}",
                    p[0],
                    self.points[i - 1][0]
                )));
            }
        }
        for (i, d) in self.scalings.iter().enumerate() {
            if d.is_nan() || d.abs() >= 1.0 {
                return Err(ExploreError::Invalid(format!(
                    "vertical scaling d_{} = {d} must lie strictly between −1 and 1",
                    i + 1
                )));
            }
        }
        let [x0, f0] = self.points[0];
        let [xn, fnn] = self.points[n - 1];
        let l = xn - x0;
        self.maps = (1..n)
            .map(|i| {
                let [xi, fi] = self.points[i];
                let [xp, fp] = self.points[i - 1];
                let d = self.scalings[i - 1];
                FifMap {
                    a: (xi - xp) / l,
                    e: (xn * xp - x0 * xi) / l,
                    c: (fi - fp - d * (fnn - f0)) / l,
                    d,
                    f: (xn * fp - x0 * fi - d * (xn * f0 - x0 * fnn)) / l,
                }
            })
            .collect();
        Ok(())
    }

    /// The data points (x_i, F_i), x increasing.
    pub fn points(&self) -> &[P2] {
        &self.points
    }

    /// The vertical scalings d_1..d_N, one per interval.
    pub fn scalings(&self) -> &[f64] {
        &self.scalings
    }

    /// The maps w_1..w_N, one per interval.
    pub fn maps(&self) -> &[FifMap] {
        &self.maps
    }

    /// Move data point `i` (a live editor drags points); refused if x would no longer
    /// increase.
    pub fn set_point(&mut self, i: usize, p: P2) -> Result<(), ExploreError> {
        let old = *self
            .points
            .get(i)
            .ok_or_else(|| ExploreError::Invalid(format!("there is no data point {i}")))?;
        self.points[i] = p;
        if let Err(e) = self.rebuild() {
            self.points[i] = old;
            self.rebuild()?;
            return Err(e);
        }
        Ok(())
    }

    /// Set d_i (1-based, as in the formulas).
    pub fn set_scaling(&mut self, i: usize, d: f64) -> Result<(), ExploreError> {
        if i == 0 || i > self.scalings.len() {
            return Err(ExploreError::Invalid(format!(
                "there is no scaling d_{i} (1 to {})",
                self.scalings.len()
            )));
        }
        let old = self.scalings[i - 1];
        self.scalings[i - 1] = d;
        if let Err(e) = self.rebuild() {
            self.scalings[i - 1] = old;
            self.rebuild()?;
            return Err(e);
        }
        Ok(())
    }

    /// Whether all data points lie on one straight line.
    pub fn collinear(&self) -> bool {
        let p0 = self.points[0];
        let pn = self.points[self.points.len() - 1];
        let (dx, dy) = (pn[0] - p0[0], pn[1] - p0[1]);
        let scale = dx.abs() + dy.abs();
        self.points.iter().all(|p| {
            let cross = dx * (p[1] - p0[1]) - dy * (p[0] - p0[0]);
            cross.abs() <= 1e-12 * scale * (scale + (p[0] - p0[0]).abs() + (p[1] - p0[1]).abs())
        })
    }

    /// The box dimension of the graph: if Σ|d_i| > 1 and the data are not collinear, the D
    /// that solves Σ |d_i|·a_i^(D−1) = 1; otherwise 1 (Barnsley, *Fractals Everywhere*,
    /// Theorem 6.3.2). It depends only on the spacing and the scalings.
    pub fn dimension(&self) -> f64 {
        let sd: f64 = self.scalings.iter().map(|d| d.abs()).sum();
        if sd <= 1.0 || self.collinear() {
            return 1.0;
        }
        let g = |s: f64| -> f64 {
            self.maps
                .iter()
                .map(|m| m.d.abs() * m.a.powf(s))
                .sum::<f64>()
                - 1.0
        };
        // g(0) = Σ|d| − 1 > 0 and g(1) = Σ|d_i|a_i − 1 < Σa_i − 1 = 0.
        let (mut lo, mut hi) = (0.0, 1.0);
        while hi - lo > 1e-13 {
            let m = 0.5 * (lo + hi);
            if g(m) > 0.0 {
                lo = m;
            } else {
                hi = m;
            }
        }
        1.0 + 0.5 * (lo + hi)
    }

    /// The curve by deterministic iteration: start with the polyline through the data and
    /// replace it `depth` times by the union of its images under the maps. Each level
    /// multiplies the number of segments by N.
    pub fn curve(&self, depth: u32) -> Result<Vec<P2>, ExploreError> {
        let n = self.maps.len() as f64;
        let count = n.powi(depth as i32 + 1) + 1.0;
        if count > MAX_CURVE_POINTS as f64 {
            return Err(ExploreError::TooLarge {
                what: format!("the curve at depth {depth}"),
                count,
                limit: MAX_CURVE_POINTS as f64,
                hint: " points; lower the depth".into(),
            });
        }
        let mut pts = self.points.clone();
        for _ in 0..depth {
            let mut next = Vec::with_capacity(pts.len() * self.maps.len());
            next.push(pts[0]);
            for m in &self.maps {
                next.extend(pts[1..].iter().map(|p| m.apply(*p)));
            }
            pts = next;
        }
        Ok(pts)
    }

    /// The maps as an IFS with probabilities a_i (each map's share of the x range).
    pub fn to_ifs(&self) -> Ifs {
        Ifs::new(
            "fractal interpolation",
            self.maps.iter().map(FifMap::affine).collect(),
            self.maps.iter().map(|m| m.a).collect(),
        )
        .expect("maps of a valid interpolation function")
    }

    /// The chaos game on the maps, from the first data point (which is on the graph).
    pub fn chaos_game(&self, seed: u64) -> ChaosGame {
        self.to_ifs().chaos_game(self.points[0], 0, seed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    fn map_eq(m: &FifMap, want: [f64; 5]) -> bool {
        [m.a, m.e, m.c, m.d, m.f]
            .iter()
            .zip(want)
            .all(|(x, y)| close(*x, y))
    }

    #[test]
    fn triangle_data() {
        let f = Fif::new(vec![[0.0, 0.0], [0.5, 1.0], [1.0, 0.0]], vec![0.5, 0.5]).unwrap();
        assert!(map_eq(&f.maps()[0], [0.5, 0.0, 1.0, 0.5, 0.0]));
        assert!(map_eq(&f.maps()[1], [0.5, 0.5, -1.0, 0.5, 1.0]));
        assert_eq!(f.maps()[0].apply([0.0, 0.0]), [0.0, 0.0]);
        assert_eq!(f.maps()[0].apply([1.0, 0.0]), [0.5, 1.0]);
        assert_eq!(f.maps()[1].apply([0.0, 0.0]), [0.5, 1.0]);
        assert_eq!(f.maps()[1].apply([1.0, 0.0]), [1.0, 0.0]);
        // Σ|d| = 1: D = 1.
        assert_eq!(f.dimension(), 1.0);
        let g = Fif::new(vec![[0.0, 0.0], [0.5, 1.0], [1.0, 0.0]], vec![0.7, 0.7]).unwrap();
        assert!((g.dimension() - 1.485427).abs() < 5e-7, "{}", g.dimension());
        assert!(close(g.dimension(), 1.0 + 1.4f64.ln() / 2f64.ln()));
        // D does not depend on the data values, only on non-collinearity.
        let h = Fif::new(vec![[0.0, 3.0], [0.5, -2.0], [1.0, 7.0]], vec![0.7, -0.7]).unwrap();
        assert!(close(h.dimension(), g.dimension()));
        let flat = Fif::new(vec![[0.0, 0.0], [0.5, 0.5], [1.0, 1.0]], vec![0.7, 0.7]).unwrap();
        assert_eq!(flat.dimension(), 1.0);
    }

    #[test]
    fn four_point_data() {
        let data = vec![[1.0, 2.0], [2.0, -1.0], [4.0, 3.0], [5.0, 0.5]];
        let f = Fif::new(data.clone(), vec![0.3, -0.4, 0.6]).unwrap();
        let want = [
            [0.25, 0.75, -0.6375, 0.3, 2.0375],
            [0.5, 1.5, 0.85, -0.4, -1.05],
            [0.25, 3.75, -0.4, 0.6, 2.2],
        ];
        for (m, w) in f.maps().iter().zip(want) {
            assert!(map_eq(m, w), "{m:?} vs {w:?}");
        }
        for (i, m) in f.maps().iter().enumerate() {
            let a = m.apply(data[0]);
            let b = m.apply(data[3]);
            assert!(close(a[0], data[i][0]) && close(a[1], data[i][1]));
            assert!(close(b[0], data[i + 1][0]) && close(b[1], data[i + 1][1]));
        }
        // Unequal spacing: Σ|d| = 1.3 > 1, D solves Σ|d_i| a_i^(D−1) = 1.
        let d = f.dimension();
        let s: f64 = f.maps().iter().map(|m| m.d.abs() * m.a.powf(d - 1.0)).sum();
        assert!((s - 1.0).abs() < 1e-10 && d > 1.0 && d < 2.0);
    }

    #[test]
    fn equal_spacing_formula_and_curve() {
        let data: Vec<P2> = (0..=4).map(|i| [i as f64, ((i * 7) % 5) as f64]).collect();
        let d = vec![0.5, -0.6, 0.4, 0.45];
        let f = Fif::new(data.clone(), d.clone()).unwrap();
        let sd: f64 = d.iter().map(|v: &f64| v.abs()).sum();
        assert!((f.dimension() - (1.0 + sd.ln() / 4f64.ln())).abs() < 1e-10);
        // The curve passes through every data point and is the graph of a function.
        let c = f.curve(3).unwrap();
        assert_eq!(c.len(), 4usize.pow(4) + 1);
        for p in &data {
            assert!(c.iter().any(|q| close(q[0], p[0]) && close(q[1], p[1])));
        }
        assert!(c.windows(2).all(|w| w[1][0] > w[0][0]));
        // d = 0 everywhere: the piecewise-linear interpolant.
        let lin = Fif::new(data.clone(), vec![0.0; 4]).unwrap();
        for q in lin.curve(2).unwrap() {
            let i = (q[0].floor() as usize).min(3);
            let t = q[0] - i as f64;
            let y = data[i][1] * (1.0 - t) + data[i + 1][1] * t;
            assert!((q[1] - y).abs() < 1e-12);
        }
        // From a data point, k chaos-game steps land on vertices of the depth-k polyline,
        // which are vertices of every deeper one.
        let fine = f.curve(6).unwrap();
        for seed in 0..20 {
            let mut g = f.chaos_game(seed);
            for _ in 0..6 {
                let p = g.next_point();
                let on = fine
                    .iter()
                    .any(|q| (q[0] - p[0]).abs() < 1e-9 && (q[1] - p[1]).abs() < 1e-9);
                assert!(on, "{p:?}");
            }
        }
        assert!(f.curve(20).is_err());
    }

    #[test]
    fn editing_keeps_it_valid() {
        let mut f = Fif::new(vec![[0.0, 0.0], [0.5, 1.0], [1.0, 0.0]], vec![0.5, 0.5]).unwrap();
        assert!(f.set_point(1, [1.5, 0.0]).is_err());
        assert_eq!(f.points()[1], [0.5, 1.0]);
        f.set_point(1, [0.25, 2.0]).unwrap();
        assert!(close(f.maps()[0].a, 0.25));
        assert!(f.set_scaling(2, 1.0).is_err());
        assert!(f.set_scaling(3, 0.1).is_err());
        f.set_scaling(2, -0.9).unwrap();
        assert_eq!(f.scalings(), &[0.5, -0.9]);
        assert!(Fif::new(vec![[0.0, 0.0]], vec![]).is_err());
        assert!(Fif::new(vec![[0.0, 0.0], [1.0, 1.0]], vec![]).is_err());
    }
}
