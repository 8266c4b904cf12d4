//! The similarity dimension of a set of contractions (Moran's equation) and of N equal copies.

use crate::explore::ExploreError;

/// Upper end of the bisection interval of the similarity-dimension solver.
pub const SOLVER_MAX: f64 = 64.0;
/// Most maps the similarity-dimension solver accepts.
pub const MAX_RATIOS: usize = 100_000;

/// The similarity dimension of maps with contraction ratios r₁…r_n: the unique s ≥ 0 with
/// r₁^s + … + r_n^s = 1 (Moran's equation; exact for self-similar sets under the open set
/// condition). Solved by bisection on [0, 64] to 1e-12; the left side decreases strictly in s.
pub fn similarity_dimension(ratios: &[f64]) -> Result<f64, ExploreError> {
    if ratios.is_empty() {
        return Err(ExploreError::Invalid(
            "no contraction ratios given; give at least one ratio between 0 and 1".into(),
        ));
    }
    if ratios.len() > MAX_RATIOS {
        return Err(ExploreError::TooLarge {
            what: "contraction ratios".into(),
            count: ratios.len() as f64,
            limit: MAX_RATIOS as f64,
            hint: String::new(),
        });
    }
    for (i, &r) in ratios.iter().enumerate() {
        if !(r > 0.0 && r < 1.0) {
            return Err(ExploreError::Invalid(format!(
                "ratio {} is {r}; contraction ratios must lie strictly between 0 and 1",
                i + 1
            )));
        }
    }
    let f = |s: f64| ratios.iter().map(|r| r.powf(s)).sum::<f64>() - 1.0;
    if ratios.len() == 1 {
        return Ok(0.0);
    }
    let (mut lo, mut hi) = (0.0, SOLVER_MAX);
    if f(hi) > 0.0 {
        return Err(ExploreError::Invalid(format!(
            "the dimension of these {} ratios exceeds {SOLVER_MAX}",
            ratios.len()
        )));
    }
    while hi - lo > 1e-12 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// Dimension of N copies scaled by r: D = log N / log(1/r).
pub fn equal_ratio_dimension(n: u64, r: f64) -> f64 {
    (n as f64).ln() / (1.0 / r).ln()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explore::dimension::testing::close;

    #[test]
    fn similarity_dimension_table() {
        let phi2 = 2.0 / (3.0 + 5f64.sqrt());
        let cases: Vec<(Vec<f64>, f64)> = vec![
            (vec![1.0 / 3.0; 2], 0.63093),
            (vec![1.0 / 3.0; 4], 1.26186),
            (vec![1.0 / 3.0; 5], 1.46497),
            (vec![0.25; 8], 1.5),
            (vec![0.5; 3], 1.58496),
            (vec![phi2; 5], 1.67228),
            (vec![1.0 / 3.0; 8], 1.89279),
            (vec![1.0 / 3.0; 9], 2.0),
            (vec![0.5; 4], 2.0),
            (vec![1.0 / 3.0; 20], 2.72683),
            (vec![0.5, 0.25, 0.25], 1.0),
            (vec![0.5, 0.5, 0.25], 1.27155),
        ];
        for (r, d) in cases {
            let s = similarity_dimension(&r).unwrap();
            assert!(close(s, d, 5e-6), "{r:?}: {s} vs {d}");
        }
        // Exact forms.
        let s = similarity_dimension(&[1.0 / 3.0; 2]).unwrap();
        assert!(close(s, 2f64.ln() / 3f64.ln(), 1e-11));
        assert!(close(
            similarity_dimension(&[0.5, 0.25, 0.25]).unwrap(),
            1.0,
            1e-11
        ));
        let x = 2f64.sqrt() - 1.0;
        assert!(close(
            similarity_dimension(&[0.5, 0.5, 0.25]).unwrap(),
            -x.log2(),
            1e-11
        ));
        // Dürer pentagon: ln 5 / ln((3 + √5)/2), not the slides' misprint log 5/log(3 + √5/2).
        let durer = 5f64.ln() / ((3.0 + 5f64.sqrt()) / 2.0).ln();
        assert!(close(
            similarity_dimension(&[phi2; 5]).unwrap(),
            durer,
            1e-11
        ));
        assert!(!close(
            durer,
            5f64.ln() / (3.0 + 5f64.sqrt() / 2.0).ln(),
            0.1
        ));
        assert!(close(equal_ratio_dimension(20, 1.0 / 3.0), 2.72683, 5e-6));
        // Scaling by B = 3 gives M = 3, 9, 27 copies of a segment, square, cube: d = 1, 2, 3.
        for (m, d) in [(3, 1.0), (9, 2.0), (27, 3.0)] {
            assert!(close(equal_ratio_dimension(m, 1.0 / 3.0), d, 1e-12));
        }
    }

    #[test]
    fn similarity_dimension_refuses_bad_ratios() {
        assert!(similarity_dimension(&[]).is_err());
        assert!(similarity_dimension(&[0.5, 1.0]).is_err());
        assert!(similarity_dimension(&[0.5, 0.0]).is_err());
        assert!(similarity_dimension(&[0.5, f64::NAN]).is_err());
        assert_eq!(similarity_dimension(&[0.5]).unwrap(), 0.0);
    }
}
