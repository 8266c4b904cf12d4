//! The divider (coastline) method: the length of a curve walked with rulers of several sizes,
//! and the dimension from how it grows as the ruler shrinks.

use super::fit::{LineFit, fit_line};
use crate::explore::{ExploreError, P2};

/// Ruler lengths and measured lengths (km) of the coastline example of the Su Xiaohong slides
/// (after Mandelbrot, "How long is the coast of Britain?", Science 1967).
pub const COASTLINE_DATA: [(f64, f64); 4] = [
    (500.0, 2500.0),
    (100.0, 3800.0),
    (50.0, 5700.0),
    (17.0, 8640.0),
];

/// The divider method: measured length u ∝ s^{1−D}. Returns the least-squares line of ln u
/// against ln s and D = 1 − slope.
pub fn divider_dimension(data: &[(f64, f64)]) -> Result<(LineFit, f64), ExploreError> {
    for &(s, u) in data {
        if !(s > 0.0 && u > 0.0 && s.is_finite() && u.is_finite()) {
            return Err(ExploreError::Invalid(format!(
                "ruler {s} and length {u}: both must be positive"
            )));
        }
    }
    let pts: Vec<(f64, f64)> = data.iter().map(|&(s, u)| (s.ln(), u.ln())).collect();
    let fit = fit_line(&pts).ok_or_else(|| {
        ExploreError::Invalid("the divider fit needs at least two different rulers".into())
    })?;
    Ok((fit, 1.0 - fit.slope))
}

/// Walk a polyline with dividers of opening `ruler`: from the start, each step goes to the
/// first later point of the curve at distance `ruler`. Returns the number of full steps and the
/// measured length (steps·ruler plus the last, shorter piece to the end point).
pub fn divider_length(curve: &[P2], ruler: f64) -> Result<(u64, f64), ExploreError> {
    if !(ruler > 0.0 && ruler.is_finite()) {
        return Err(ExploreError::Invalid(format!(
            "ruler length {ruler} must be positive"
        )));
    }
    if curve.len() < 2 {
        return Err(ExploreError::Invalid(
            "the divider method needs a curve of at least two points".into(),
        ));
    }
    let total: f64 = curve.windows(2).map(|w| dist(w[0], w[1])).sum();
    if total / ruler > 1e8 {
        return Err(ExploreError::TooLarge {
            what: "divider steps".into(),
            count: total / ruler,
            limit: 1e8,
            hint: "; use a longer ruler".into(),
        });
    }
    let mut c = curve[0];
    let mut seg = 0usize;
    let mut t0 = 0.0;
    let mut steps = 0u64;
    let r2 = ruler * ruler;
    while seg + 1 < curve.len() {
        let (a, b) = (curve[seg], curve[seg + 1]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let f = [a[0] - c[0], a[1] - c[1]];
        // |f + t d|² = r²; the curve leaves the circle at the larger root.
        let qa = d[0] * d[0] + d[1] * d[1];
        let qb = 2.0 * (f[0] * d[0] + f[1] * d[1]);
        let qc = f[0] * f[0] + f[1] * f[1] - r2;
        let disc = qb * qb - 4.0 * qa * qc;
        if qa > 0.0 && disc >= 0.0 {
            let t = (-qb + disc.sqrt()) / (2.0 * qa);
            // A step ending exactly on a vertex may round to just past it.
            if t >= t0 && t <= 1.0 + 1e-12 {
                let t = t.min(1.0);
                c = [a[0] + t * d[0], a[1] + t * d[1]];
                t0 = t;
                steps += 1;
                continue;
            }
        }
        seg += 1;
        t0 = 0.0;
    }
    let rest = dist(c, curve[curve.len() - 1]);
    Ok((steps, steps as f64 * ruler + rest))
}

fn dist(a: P2, b: P2) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explore::dimension::testing::close;

    #[test]
    fn divider_on_the_coastline_data() {
        let (fit, d) = divider_dimension(&COASTLINE_DATA).unwrap();
        assert!(close(fit.slope, -0.371221, 1e-6), "{}", fit.slope);
        assert!(close(d, 1.371, 5e-4), "{d}");
        assert!(divider_dimension(&[(1.0, 2.0)]).is_err());
        assert!(divider_dimension(&[(1.0, 2.0), (-1.0, 3.0)]).is_err());
    }

    #[test]
    fn divider_walk_on_curves() {
        // A straight line measures its own length with any ruler.
        let line = [[0.0, 0.0], [3.0, 4.0], [6.0, 8.0]];
        let (steps, len) = divider_length(&line, 2.0).unwrap();
        assert_eq!(steps, 5);
        assert!(close(len, 10.0, 1e-12));
        // On a Koch curve (order 7), rulers 3^−2..3^−5 step exactly along the segments of
        // the corresponding level: lengths (4/3)^k, D = log 4 / log 3.
        let pts = crate::explore::classic::koch_curve_points(7);
        let data: Vec<(f64, f64)> = (2..=5)
            .map(|k| {
                let s = 3f64.powi(-k);
                (s, divider_length(&pts, s).unwrap().1)
            })
            .collect();
        for (k, &(_, u)) in (2..=5).zip(&data) {
            assert!(close(u, (4.0f64 / 3.0).powi(k), 1e-6), "k={k}: {u}");
        }
        let (_, d) = divider_dimension(&data).unwrap();
        assert!(close(d, 1.26186, 1e-5), "{d}");
        assert!(divider_length(&line, 0.0).is_err());
        assert!(divider_length(&line[..1], 1.0).is_err());
    }
}
