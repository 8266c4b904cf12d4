//! The least-squares line through log-log points, from which every estimator here reads its
//! dimension.

/// A least-squares line y = slope·x + intercept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineFit {
    /// Slope of the line.
    pub slope: f64,
    /// Value of the line at x = 0.
    pub intercept: f64,
    /// Coefficient of determination (1 for points exactly on the line).
    pub r2: f64,
    /// Points used.
    pub n: usize,
}

/// Fit a line to (x, y) points by least squares; `None` for fewer than 2 distinct x.
pub fn fit_line(pts: &[(f64, f64)]) -> Option<LineFit> {
    let n = pts.len();
    if n < 2 {
        return None;
    }
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / n as f64;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / n as f64;
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let syy: f64 = pts.iter().map(|p| (p.1 - my) * (p.1 - my)).sum();
    if sxx <= 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let r2 = if syy > 0.0 {
        (sxy * sxy) / (sxx * syy)
    } else {
        1.0
    };
    Some(LineFit {
        slope,
        intercept: my - slope * mx,
        r2,
        n,
    })
}
