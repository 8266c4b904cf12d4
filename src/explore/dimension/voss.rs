//! Voss's mass distribution: how many points of the set a box of side Γ centred on one of them
//! holds, its moments, the dimension they give and the lacunarity.

use rayon::prelude::*;

use super::fit::{LineFit, fit_line};
use crate::explore::{Bounds, ExploreError, P2};

/// Most box centres sampled per box size by [`voss`].
pub const VOSS_MAX_CENTRES: usize = 20_000;
/// Most points [`voss`] accepts.
pub const VOSS_MAX_POINTS: usize = 2_000_000;

/// Voss's mass distribution at one box size Γ: p(m, Γ) is the probability that a box of side Γ
/// centred on a point of the set holds m points (R. F. Voss, "Random fractals: characterization
/// and measurement", 1986).
#[derive(Clone, Debug, PartialEq)]
pub struct VossLevel {
    /// Box side Γ in world units.
    pub gamma: f64,
    /// Boxes counted (centred on points whose box lies inside the bounding square).
    pub centres: usize,
    /// (m, p(m, Γ)) for every m that occurs, m ascending.
    pub distribution: Vec<(u64, f64)>,
    /// N(Γ) = Σ p(m, Γ)/m.
    pub n: f64,
    /// M(Γ) = Σ m·p(m, Γ).
    pub m1: f64,
    /// M₂(Γ) = Σ m²·p(m, Γ).
    pub m2: f64,
    /// Λ(Γ) = (M₂ − M²)/M².
    pub lacunarity: f64,
}

impl VossLevel {
    /// Moments of a distribution given as (m, p) pairs.
    pub fn from_distribution(gamma: f64, centres: usize, distribution: Vec<(u64, f64)>) -> Self {
        let n = distribution.iter().map(|&(m, p)| p / m as f64).sum();
        let m1: f64 = distribution.iter().map(|&(m, p)| m as f64 * p).sum();
        let m2: f64 = distribution
            .iter()
            .map(|&(m, p)| (m as f64) * (m as f64) * p)
            .sum();
        VossLevel {
            gamma,
            centres,
            distribution,
            n,
            m1,
            m2,
            lacunarity: (m2 - m1 * m1) / (m1 * m1),
        }
    }
}

/// Mandelbrot's lacunarity of box masses: E[(M/E(M) − 1)²].
pub fn lacunarity_of_masses(masses: &[u64]) -> f64 {
    let n = masses.len() as f64;
    let mean = masses.iter().map(|&m| m as f64).sum::<f64>() / n;
    masses
        .iter()
        .map(|&m| (m as f64 / mean - 1.0).powi(2))
        .sum::<f64>()
        / n
}

/// The mass distribution of a point set at each box size. Boxes are closed squares of side Γ
/// centred on points of the set; only boxes lying inside the set's bounding square are counted
/// (so the edge of a finite sample does not pose as a gap), and at most
/// [`VOSS_MAX_CENTRES`] centres, evenly spread over the points, are used per size. Sizes
/// without any such box are left out.
pub fn voss(points: &[P2], gammas: &[f64]) -> Result<Vec<VossLevel>, ExploreError> {
    if points.len() < 2 {
        return Err(ExploreError::Invalid(
            "the mass distribution needs at least two points".into(),
        ));
    }
    if points.len() > VOSS_MAX_POINTS {
        return Err(ExploreError::TooLarge {
            what: "points for the mass distribution".into(),
            count: points.len() as f64,
            limit: VOSS_MAX_POINTS as f64,
            hint: String::new(),
        });
    }
    if gammas.is_empty() || gammas.len() > 64 {
        return Err(ExploreError::Invalid(format!(
            "{} box sizes given; give 1 to 64",
            gammas.len()
        )));
    }
    let b = Bounds::of(points.iter().copied());
    let side = b.width().max(b.height());
    if side.is_nan() || side <= 0.0 {
        return Err(ExploreError::Invalid("all points coincide".into()));
    }
    // The bounding square, centred on the bounding box.
    let cx = 0.5 * (b.min[0] + b.max[0]);
    let cy = 0.5 * (b.min[1] + b.max[1]);
    let sq = [
        cx - side / 2.0,
        cy - side / 2.0,
        cx + side / 2.0,
        cy + side / 2.0,
    ];
    let mut out = Vec::new();
    for &g in gammas {
        if !(g > 0.0 && g.is_finite() && g >= side * 1e-6) {
            return Err(ExploreError::Invalid(format!(
                "box size {g} must be positive and at least a millionth of the set's extent {side}"
            )));
        }
        // Points sorted into cells of side Γ.
        let cell = |p: P2| -> (i64, i64) {
            (
                ((p[0] - sq[0]) / g).floor() as i64,
                ((p[1] - sq[1]) / g).floor() as i64,
            )
        };
        let mut idx: Vec<((i64, i64), u32)> = points
            .iter()
            .enumerate()
            .map(|(i, p)| (cell(*p), i as u32))
            .collect();
        idx.sort_unstable();
        let cells: Vec<(i64, i64)> = idx.iter().map(|e| e.0).collect();
        let h = g / 2.0;
        let centres: Vec<usize> = (0..points.len())
            .filter(|&i| {
                let p = points[i];
                p[0] - h >= sq[0] && p[0] + h <= sq[2] && p[1] - h >= sq[1] && p[1] + h <= sq[3]
            })
            .collect();
        if centres.is_empty() {
            continue;
        }
        let stride = centres.len().div_ceil(VOSS_MAX_CENTRES);
        let chosen: Vec<usize> = centres.iter().step_by(stride).copied().collect();
        let masses: Vec<u64> = chosen
            .par_iter()
            .map(|&i| {
                let p = points[i];
                let (x0, y0) = cell([p[0] - h, p[1] - h]);
                let (x1, y1) = cell([p[0] + h, p[1] + h]);
                let mut m = 0u64;
                for cxi in x0..=x1 {
                    for cyi in y0..=y1 {
                        let lo = cells.partition_point(|c| *c < (cxi, cyi));
                        let hi = cells.partition_point(|c| *c <= (cxi, cyi));
                        for e in &idx[lo..hi] {
                            let q = points[e.1 as usize];
                            if (q[0] - p[0]).abs() <= h && (q[1] - p[1]).abs() <= h {
                                m += 1;
                            }
                        }
                    }
                }
                m
            })
            .collect();
        let mut sorted = masses.clone();
        sorted.sort_unstable();
        let total = sorted.len() as f64;
        let mut dist: Vec<(u64, f64)> = Vec::new();
        for m in sorted {
            match dist.last_mut() {
                Some((lm, c)) if *lm == m => *c += 1.0,
                _ => dist.push((m, 1.0)),
            }
        }
        for d in &mut dist {
            d.1 /= total;
        }
        out.push(VossLevel::from_distribution(g, chosen.len(), dist));
    }
    Ok(out)
}

/// Voss's dimension estimate: N(Γ) ∝ Γ^−D, so D is the slope of −ln N(Γ) against ln Γ.
pub fn voss_dimension(levels: &[VossLevel]) -> Option<LineFit> {
    let pts: Vec<(f64, f64)> = levels.iter().map(|l| (l.gamma.ln(), -l.n.ln())).collect();
    fit_line(&pts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explore::dimension::testing::{close, random_points};

    #[test]
    fn lacunarity_of_a_regular_lattice_is_zero() {
        // A 60×60 lattice: every box of side 3 centred on an interior point holds 9 points.
        let pts: Vec<P2> = (0..3600)
            .map(|i| [(i % 60) as f64, (i / 60) as f64])
            .collect();
        let lv = voss(&pts, &[3.0, 5.0]).unwrap();
        assert_eq!(lv[0].distribution, vec![(9, 1.0)]);
        assert_eq!(lv[0].m1, 9.0);
        assert_eq!(lv[0].m2, 81.0);
        assert_eq!(lv[0].lacunarity, 0.0);
        assert_eq!(lv[1].distribution, vec![(25, 1.0)]);
        // N(Γ) = 1/m: for the lattice (a filled square) D = 2 from these two sizes.
        let fit = voss_dimension(&lv).unwrap();
        assert!(close(fit.slope, 2.0, 1e-12));
        assert_eq!(lacunarity_of_masses(&[9; 10]), 0.0);
    }

    #[test]
    fn lacunarity_definitions_agree() {
        // Voss's (M₂ − M²)/M² and Mandelbrot's E[(M/E(M) − 1)²] on the same masses.
        let masses = [1u64, 1, 2, 3, 3, 3, 7, 12];
        let mut dist: Vec<(u64, f64)> = Vec::new();
        for &m in &masses {
            match dist.iter_mut().find(|d| d.0 == m) {
                Some(d) => d.1 += 1.0 / 8.0,
                None => dist.push((m, 1.0 / 8.0)),
            }
        }
        let v = VossLevel::from_distribution(1.0, 8, dist);
        assert!(close(v.lacunarity, lacunarity_of_masses(&masses), 1e-12));
        assert!(v.lacunarity > 0.5);
        // A set with a dense clump and sparse surroundings is far more lacunar (its box
        // masses vary more) than a uniform set at the same box size.
        let uniform = random_points(20_000, 5, |u, v| [u, v]);
        let clumpy = random_points(20_000, 6, |u, v| {
            if u < 0.5 {
                [2.0 * u, v]
            } else {
                [0.5 + 0.06 * (u - 0.5), 0.5 + 0.03 * v]
            }
        });
        let lu = voss(&uniform, &[0.1]).unwrap()[0].lacunarity;
        let lc = voss(&clumpy, &[0.1]).unwrap()[0].lacunarity;
        assert!(lc > 2.0 * lu, "{lc} vs {lu}");
    }
}
