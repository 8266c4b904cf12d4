//! Spatial filter kernels.

use std::f64::consts::PI;

/// Spatial filter kernels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FilterShape {
    /// The Gaussian (the default).
    #[default]
    Gaussian,
    /// Hermite.
    Hermite,
    /// Box.
    Box,
    /// Triangle (tent).
    Triangle,
    /// Bell.
    Bell,
    /// B-spline.
    Bspline,
    /// Mitchell–Netravali.
    Mitchell,
    /// Blackman.
    Blackman,
    /// Catmull–Rom.
    Catrom,
    /// Hanning.
    Hanning,
    /// Hamming.
    Hamming,
    /// Lanczos, three lobes.
    Lanczos3,
    /// Lanczos, two lobes.
    Lanczos2,
    /// Quadratic.
    Quadratic,
}

impl FilterShape {
    /// Every kernel, in menu order.
    pub const ALL: [FilterShape; 14] = [
        FilterShape::Gaussian,
        FilterShape::Hermite,
        FilterShape::Box,
        FilterShape::Triangle,
        FilterShape::Bell,
        FilterShape::Bspline,
        FilterShape::Mitchell,
        FilterShape::Blackman,
        FilterShape::Catrom,
        FilterShape::Hanning,
        FilterShape::Hamming,
        FilterShape::Lanczos3,
        FilterShape::Lanczos2,
        FilterShape::Quadratic,
    ];

    /// The kernel's name in flame files (`filter_shape`).
    pub fn name(self) -> &'static str {
        match self {
            FilterShape::Gaussian => "gaussian",
            FilterShape::Hermite => "hermite",
            FilterShape::Box => "box",
            FilterShape::Triangle => "triangle",
            FilterShape::Bell => "bell",
            FilterShape::Bspline => "bspline",
            FilterShape::Mitchell => "mitchell",
            FilterShape::Blackman => "blackman",
            FilterShape::Catrom => "catrom",
            FilterShape::Hanning => "hanning",
            FilterShape::Hamming => "hamming",
            FilterShape::Lanczos3 => "lanczos3",
            FilterShape::Lanczos2 => "lanczos2",
            FilterShape::Quadratic => "quadratic",
        }
    }

    /// The kernel a name stands for; None if unknown.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|f| f.name() == s)
    }
}

/// Kernel support σ.
pub fn support(shape: FilterShape) -> f64 {
    match shape {
        FilterShape::Gaussian => 1.5,
        FilterShape::Hermite => 1.0,
        FilterShape::Box => 0.5,
        FilterShape::Triangle => 1.0,
        FilterShape::Bell => 1.5,
        FilterShape::Bspline => 2.0,
        FilterShape::Mitchell => 2.0,
        FilterShape::Blackman => 1.0,
        FilterShape::Catrom => 2.0,
        FilterShape::Hanning => 1.0,
        FilterShape::Hamming => 1.0,
        FilterShape::Lanczos3 => 3.0,
        FilterShape::Lanczos2 => 2.0,
        FilterShape::Quadratic => 1.5,
    }
}

pub(crate) fn sinc(x: f64) -> f64 {
    let x = x * PI;
    if x != 0.0 { x.sin() / x } else { 1.0 }
}

/// The Mitchell–Netravali cubic with parameters b and c at distance t ≥ 0.
pub(crate) fn mitchell(t: f64, b: f64, c: f64) -> f64 {
    let tt = t * t;
    if t < 1.0 {
        ((12.0 - 9.0 * b - 6.0 * c) * (t * tt)
            + (-18.0 + 12.0 * b + 6.0 * c) * tt
            + (6.0 - 2.0 * b))
            / 6.0
    } else if t < 2.0 {
        ((-b - 6.0 * c) * (t * tt)
            + (6.0 * b + 30.0 * c) * tt
            + (-12.0 * b - 48.0 * c) * t
            + (8.0 * b + 24.0 * c))
            / 6.0
    } else {
        0.0
    }
}

/// G(x) = e^(−2x²)·√(2/π).
pub fn gaussian(x: f64) -> f64 {
    (-2.0 * x * x).exp() * (2.0 / PI).sqrt()
}

/// The kernel function k(x) of a shape (the classic Graphics Gems filters flam3 uses).
pub fn kernel(shape: FilterShape, x: f64) -> f64 {
    match shape {
        FilterShape::Gaussian => gaussian(x),
        FilterShape::Hermite => {
            let t = x.abs();
            if t < 1.0 {
                (2.0 * t - 3.0) * t * t + 1.0
            } else {
                0.0
            }
        }
        FilterShape::Box => {
            if x > -0.5 && x <= 0.5 {
                1.0
            } else {
                0.0
            }
        }
        FilterShape::Triangle => {
            let t = x.abs();
            if t < 1.0 { 1.0 - t } else { 0.0 }
        }
        FilterShape::Bell => {
            let t = x.abs();
            if t < 0.5 {
                0.75 - t * t
            } else if t < 1.5 {
                let u = t - 1.5;
                0.5 * u * u
            } else {
                0.0
            }
        }
        FilterShape::Bspline => {
            let t = x.abs();
            if t < 1.0 {
                let tt = t * t;
                0.5 * tt * t - tt + 2.0 / 3.0
            } else if t < 2.0 {
                let u = 2.0 - t;
                u * u * u / 6.0
            } else {
                0.0
            }
        }
        FilterShape::Mitchell => mitchell(x.abs(), 1.0 / 3.0, 1.0 / 3.0),
        FilterShape::Blackman => 0.42 + 0.5 * (PI * x).cos() + 0.08 * (2.0 * PI * x).cos(),
        FilterShape::Catrom => {
            if x < -2.0 {
                0.0
            } else if x < -1.0 {
                0.5 * (4.0 + x * (8.0 + x * (5.0 + x)))
            } else if x < 0.0 {
                0.5 * (2.0 + x * x * (-5.0 - 3.0 * x))
            } else if x < 1.0 {
                0.5 * (2.0 + x * x * (-5.0 + 3.0 * x))
            } else if x < 2.0 {
                0.5 * (4.0 + x * (-8.0 + x * (5.0 - x)))
            } else {
                0.0
            }
        }
        FilterShape::Hanning => 0.5 + 0.5 * (PI * x).cos(),
        FilterShape::Hamming => 0.54 + 0.46 * (PI * x).cos(),
        FilterShape::Lanczos3 => {
            let t = x.abs();
            if t < 3.0 {
                sinc(t) * sinc(t / 3.0)
            } else {
                0.0
            }
        }
        FilterShape::Lanczos2 => {
            let t = x.abs();
            if t < 2.0 {
                sinc(t) * sinc(t / 2.0)
            } else {
                0.0
            }
        }
        FilterShape::Quadratic => {
            if x < -1.5 {
                0.0
            } else if x < -0.5 {
                let u = x + 1.5;
                0.5 * u * u
            } else if x < 0.5 {
                0.75 - x * x
            } else if x < 1.5 {
                let u = x - 1.5;
                0.5 * u * u
            } else {
                0.0
            }
        }
    }
}

/// The separable spatial filter: 1-D taps whose outer product is the normalised 2-D kernel.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialFilter {
    /// fwidth, same parity as the supersample factor.
    pub width: usize,
    /// Normalised 1-D taps (sum 1); `K[i][j] = taps[i]·taps[j]`.
    pub taps: Vec<f64>,
    /// Gutter (fwidth − os)/2.
    pub gutter: usize,
}

impl SpatialFilter {
    pub fn new(shape: FilterShape, radius: f64, os: u32) -> SpatialFilter {
        let os_i = os as usize;
        if radius <= 0.0 {
            // No filter: each pixel takes the first bucket of its block, as Fractorium does
            // (flam3 has no such case and averages the block: a 2×2 box at supersample 2).
            // Thin lines of flames made in Fractorium with filter 0 keep their width.
            return SpatialFilter {
                width: 1,
                taps: vec![1.0],
                gutter: 0,
            };
        }
        let sigma = support(shape);
        let fw = 2.0 * sigma * os as f64 * radius;
        let mut width = fw.floor() as usize + 1;
        if (width + os_i) % 2 == 1 {
            width += 1;
        }
        let adjust = if fw > 0.0 {
            sigma * width as f64 / fw
        } else {
            1.0
        };
        let mut taps: Vec<f64> = (0..width)
            .map(|i| {
                let x = ((2 * i + 1) as f64 / width as f64 - 1.0) * adjust;
                kernel(shape, x)
            })
            .collect();
        let sum: f64 = taps.iter().sum();
        if sum != 0.0 && sum.is_finite() {
            for t in &mut taps {
                *t /= sum;
            }
        } else {
            // Degenerate kernel: fall back to a box.
            taps = vec![1.0 / width as f64; width];
        }
        let gutter = width.saturating_sub(os_i) / 2;
        SpatialFilter {
            width,
            taps,
            gutter,
        }
    }

    /// The 2-D weight `K[i][j]`.
    pub fn weight(&self, i: usize, j: usize) -> f64 {
        self.taps[i] * self.taps[j]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn oracles() {
        let f = SpatialFilter::new(FilterShape::Gaussian, 0.5, 1);
        assert_eq!(f.width, 3);
        assert_eq!(f.gutter, 1);
        assert!(
            (f.weight(1, 1) - 0.998659).abs() < 1e-6,
            "{}",
            f.weight(1, 1)
        );
        let f = SpatialFilter::new(FilterShape::Gaussian, 1.0, 1);
        assert_eq!(f.width, 5);
        assert!(
            (f.weight(2, 2) - 0.618694).abs() < 1e-6,
            "{}",
            f.weight(2, 2)
        );
        let f = SpatialFilter::new(FilterShape::Gaussian, 0.5, 2);
        assert_eq!(f.width, 4);
        assert!(
            (f.weight(1, 1) - 0.241088).abs() < 1e-6,
            "{}",
            f.weight(1, 1)
        );
        let f = SpatialFilter::new(FilterShape::Gaussian, 1.0, 2);
        assert_eq!(f.width, 8);
        assert_eq!(f.gutter, 3);
    }

    #[test]
    fn a_zero_radius_takes_one_bucket_per_pixel() {
        for os in 1..=3 {
            let f = SpatialFilter::new(FilterShape::Gaussian, 0.0, os);
            assert_eq!((f.width, f.taps.clone(), f.gutter), (1, vec![1.0], 0));
        }
    }

    #[test]
    fn every_shape_normalises() {
        for s in FilterShape::ALL {
            for os in 1..=3 {
                let f = SpatialFilter::new(s, 0.75, os);
                let sum: f64 = f.taps.iter().sum();
                assert!((sum - 1.0).abs() < 1e-12, "{s:?}");
                assert_eq!((f.width + os as usize) % 2, 0);
            }
        }
    }
}
