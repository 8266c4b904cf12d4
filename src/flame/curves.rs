//! Colour curves (Fractorium's): an overall curve and one per channel, applied to the final
//! colour of every pixel — the overall curve first, then the channel's own.
//!
//! Each curve passes through control points (x, y) in [0, 1]² and is the piecewise cubic that
//! Fractorium evaluates: on each interval a cubic through the two end points whose second
//! derivatives at the inner points are estimated from the neighbouring slopes (3·Δslope / width)
//! and are 0 at both ends. The curve is tabulated at 65 536 points, as Fractorium does.

/// Control points of the overall, red, green and blue curves.
#[derive(Clone, Debug, PartialEq)]
pub struct Curves {
    pub points: [Vec<[f64; 2]>; 4],
}

/// The identity curve's control points (Fractorium's default).
const IDENTITY: [[f64; 2]; 5] = [
    [0.0, 0.0],
    [0.25, 0.25],
    [0.5, 0.5],
    [0.75, 0.75],
    [1.0, 1.0],
];

/// Entries of a tabulated curve.
pub const LUT_LEN: usize = 65_536;

/// Most control points of one curve in a file.
pub const MAX_POINTS: usize = 256;

impl Default for Curves {
    fn default() -> Self {
        Curves {
            points: std::array::from_fn(|_| IDENTITY.to_vec()),
        }
    }
}

impl Curves {
    /// True when every curve is the identity (nothing to apply).
    pub fn is_identity(&self) -> bool {
        self.points
            .iter()
            .all(|c| c.iter().all(|p| (p[0] - p[1]).abs() < 1e-12))
    }

    /// Control points as read from a file: clamped to [0, 1], sorted by x, and with
    /// Fractorium's repair of a doubled first or last point (two points at (0,0) make the
    /// second (0.25, 0.25); two at (1,1) make the fourth (0.75, 0.75)).
    pub fn normalised(mut pts: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
        for p in &mut pts {
            p[0] = p[0].clamp(0.0, 1.0);
            p[1] = p[1].clamp(0.0, 1.0);
        }
        pts.sort_by(|a, b| a[0].total_cmp(&b[0]));
        if pts.len() >= 4 {
            if pts[0] == [0.0, 0.0] && pts[1] == [0.0, 0.0] {
                pts[1] = [0.25, 0.25];
            }
            if pts[2] == [1.0, 1.0] && pts[3] == [1.0, 1.0] {
                pts[3] = [0.75, 0.75];
            }
        }
        pts
    }

    /// The curves tabulated for rendering.
    pub fn lut(&self) -> CurveLut {
        let mut t = vec![[0f32; 4]; LUT_LEN];
        for (ci, pts) in self.points.iter().enumerate() {
            let s = Spline::new(pts);
            for (j, e) in t.iter_mut().enumerate() {
                e[ci] = s.at(j as f64 / (LUT_LEN - 1) as f64) as f32;
            }
        }
        CurveLut { t }
    }
}

/// Tabulated curves: entry j holds the overall, red, green and blue curves at j / 65 535.
#[derive(Clone, Debug)]
pub struct CurveLut {
    t: Vec<[f32; 4]>,
}

impl CurveLut {
    /// Apply the overall curve, then the curve of `channel` (0 red, 1 green, 2 blue) to a value
    /// in [0, 1].
    #[inline]
    pub fn apply(&self, v: f64, channel: usize) -> f64 {
        let m = (LUT_LEN - 1) as f64;
        let i = (v * m).clamp(0.0, m) as usize;
        let j = (self.t[i][0] as f64 * m).clamp(0.0, m) as usize;
        self.t[j][channel + 1] as f64
    }
}

/// The piecewise cubic through sorted control points.
struct Spline {
    x: Vec<f64>,
    coef: Vec<[f64; 4]>,
}

impl Spline {
    fn new(pts: &[[f64; 2]]) -> Spline {
        if pts.len() < 2 {
            // A single point (or none) is a constant.
            let y = pts.first().map_or(0.0, |p| p[1]);
            return Spline {
                x: vec![0.0],
                coef: vec![[0.0, 0.0, 0.0, y]],
            };
        }
        let n = pts.len() - 1;
        let width: Vec<f64> = (0..n).map(|i| pts[i + 1][0] - pts[i][0]).collect();
        let slope: Vec<f64> = (0..n)
            .map(|i| (pts[i + 1][1] - pts[i][1]) / width[i])
            .collect();
        // Second derivatives: 0 at the ends, estimated in between.
        let mut dd = vec![0.0; n + 1];
        for i in 0..n.saturating_sub(1) {
            dd[i + 1] = 3.0 * (slope[i + 1] - slope[i]) / (width[i + 1] + width[i]);
        }
        let coef = (0..n)
            .map(|i| {
                [
                    (dd[i + 1] - dd[i]) / (6.0 * width[i]),
                    dd[i] / 2.0,
                    slope[i] - width[i] * (dd[i + 1] + 2.0 * dd[i]) / 6.0,
                    pts[i][1],
                ]
            })
            .collect();
        Spline {
            x: pts.iter().map(|p| p[0]).collect(),
            coef,
        }
    }

    fn at(&self, x: f64) -> f64 {
        let n = self.coef.len();
        let x = x.clamp(self.x[0], *self.x.last().unwrap_or(&0.0));
        let mut j = 0;
        while j + 1 < n && x > self.x[j + 1] {
            j += 1;
        }
        let d = x - self.x[j];
        let [a, b, c, e] = self.coef[j];
        let v = a * d * d * d + b * d * d + c * d + e;
        if v.is_finite() { v } else { e }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identity_curves_change_nothing() {
        let c = Curves::default();
        assert!(c.is_identity());
        let lut = c.lut();
        for v in [0.0, 0.1, 0.5, 0.9, 1.0] {
            for ch in 0..3 {
                assert!((lut.apply(v, ch) - v).abs() < 5e-5, "{v} {ch}");
            }
        }
    }

    #[test]
    fn curves_pass_through_their_points_and_stay_in_order() {
        let mut c = Curves::default();
        c.points[1] = Curves::normalised(vec![[0.0, 0.0], [0.5, 0.8], [1.0, 1.0]]);
        let lut = c.lut();
        // Red through (0.5, 0.8); green and blue untouched.
        assert!((lut.apply(0.5, 0) - 0.8).abs() < 1e-4);
        assert!((lut.apply(0.5, 1) - 0.5).abs() < 1e-4);
        // Three points: one inner second derivative of 3·(0.4 − 1.6)/1 = −3.6; at x = 0.25 the
        // cubic a·d³ + c·d gives −1.2·0.015625 + 1.9·0.25 = 0.45625.
        assert!((lut.apply(0.25, 0) - 0.45625).abs() < 1e-4);
        let mut prev = 0.0;
        for i in 0..=100 {
            let v = lut.apply(i as f64 / 100.0, 0);
            assert!(v >= prev - 1e-6, "not increasing at {i}");
            prev = v;
        }
    }

    #[test]
    fn overall_curve_applies_before_the_channel_curve() {
        let mut c = Curves::default();
        c.points[0] = vec![[0.0, 0.0], [1.0, 0.5]];
        c.points[3] = vec![[0.0, 1.0], [1.0, 0.0]];
        let lut = c.lut();
        // 0.8 → 0.4 (overall) → 0.6 (blue inverted).
        assert!((lut.apply(0.8, 2) - 0.6).abs() < 1e-4);
        assert!((lut.apply(0.8, 0) - 0.4).abs() < 1e-4);
    }

    #[test]
    fn files_repair_doubled_end_points() {
        let p = Curves::normalised(vec![
            [0.0, 0.0],
            [0.0, 0.0],
            [1.0, 1.0],
            [1.0, 1.0],
            [2.0, -1.0],
        ]);
        assert_eq!(p[1], [0.25, 0.25]);
        assert_eq!(p[4], [1.0, 0.0]);
    }
}
