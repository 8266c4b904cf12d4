//! JWildfire's spatial filter kernels and the square 2-D filters it builds from them: an odd
//! number of taps per side, each weighted by the kernel at its distance from the centre (a
//! radial filter, not the product of two 1-D filters as flam3's), normalised to sum os².

use std::f64::consts::PI;

use crate::flame::FilterShape;
use crate::flame::filter::{self, mitchell, sinc};

/// A JWildfire filter kernel (`filter_kernel`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum JwfKernel {
    /// Quadratic B-spline (box ∗ box ∗ box).
    Bell,
    /// Blackman-windowed sinc.
    Blackman,
    /// Box.
    Box,
    /// Cubic B-spline.
    Bspline,
    /// Catmull–Rom.
    Catrom,
    /// Gaussian.
    Gaussian,
    /// Hamming-windowed sinc.
    Hamming,
    /// Hanning-windowed sinc.
    Hanning,
    /// Hermite cubic.
    Hermite,
    /// Lanczos, two lobes (with a second window).
    Lanczos2,
    /// Lanczos, three lobes (with a second window).
    Lanczos3,
    /// Mitchell–Netravali with b = c = 1/3.
    Mitchell,
    /// Mitchell–Netravali with b = 0.42, c = 0.29 (JWildfire's default).
    #[default]
    MitchellSmooth,
    /// Quadratic.
    Quadratic,
    /// JWildfire's sine power kernel of power 5.
    SinePow5,
    /// JWildfire's sine power kernel of power 10.
    SinePow10,
    /// JWildfire's sine power kernel of power 15.
    SinePow15,
    /// Triangle (tent).
    Triangle,
    /// JWildfire's adaptive filter: drawn here with its sharp kernel everywhere.
    MitchellSinePow,
}

impl JwfKernel {
    /// Every kernel, in JWildfire's order.
    pub const ALL: [JwfKernel; 19] = [
        JwfKernel::Bell,
        JwfKernel::Blackman,
        JwfKernel::Box,
        JwfKernel::Bspline,
        JwfKernel::Catrom,
        JwfKernel::Gaussian,
        JwfKernel::Hamming,
        JwfKernel::Hanning,
        JwfKernel::Hermite,
        JwfKernel::Lanczos2,
        JwfKernel::Lanczos3,
        JwfKernel::Mitchell,
        JwfKernel::MitchellSmooth,
        JwfKernel::Quadratic,
        JwfKernel::SinePow5,
        JwfKernel::SinePow10,
        JwfKernel::SinePow15,
        JwfKernel::Triangle,
        JwfKernel::MitchellSinePow,
    ];

    /// The name JWildfire writes.
    pub fn name(self) -> &'static str {
        match self {
            JwfKernel::Bell => "BELL",
            JwfKernel::Blackman => "BLACKMAN",
            JwfKernel::Box => "BOX",
            JwfKernel::Bspline => "BSPLINE",
            JwfKernel::Catrom => "CATROM",
            JwfKernel::Gaussian => "GAUSSIAN",
            JwfKernel::Hamming => "HAMMING",
            JwfKernel::Hanning => "HANNING",
            JwfKernel::Hermite => "HERMITE",
            JwfKernel::Lanczos2 => "LANCZOS2",
            JwfKernel::Lanczos3 => "LANCZOS3",
            JwfKernel::Mitchell => "MITCHELL",
            JwfKernel::MitchellSmooth => "MITCHELL_SMOOTH",
            JwfKernel::Quadratic => "QUADRATIC",
            JwfKernel::SinePow5 => "SINEPOW5",
            JwfKernel::SinePow10 => "SINEPOW10",
            JwfKernel::SinePow15 => "SINEPOW15",
            JwfKernel::Triangle => "TRIANGLE",
            JwfKernel::MitchellSinePow => "MITCHELL_SINEPOW",
        }
    }

    /// The kernel JWildfire names `s`.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == s)
    }

    /// Sharpening kernels take only the colour through the kernel; the density goes through
    /// a Gaussian of radius 0.75 (JWildfire's "sharpening" kernels).
    pub fn is_sharpening(self) -> bool {
        matches!(
            self,
            JwfKernel::Blackman
                | JwfKernel::Catrom
                | JwfKernel::Hamming
                | JwfKernel::Hanning
                | JwfKernel::Lanczos2
                | JwfKernel::Lanczos3
                | JwfKernel::Mitchell
                | JwfKernel::MitchellSmooth
                | JwfKernel::MitchellSinePow
        )
    }

    /// The kernel's support σ (taps reach σ·radius pixels to either side).
    pub fn support(self) -> f64 {
        match self {
            JwfKernel::Box => 0.5,
            JwfKernel::Blackman
            | JwfKernel::Hamming
            | JwfKernel::Hanning
            | JwfKernel::Hermite
            | JwfKernel::Triangle
            | JwfKernel::SinePow5
            | JwfKernel::SinePow10
            | JwfKernel::SinePow15 => 1.0,
            JwfKernel::Bell | JwfKernel::Gaussian | JwfKernel::Quadratic => 1.5,
            JwfKernel::Bspline
            | JwfKernel::Catrom
            | JwfKernel::Lanczos2
            | JwfKernel::Mitchell
            | JwfKernel::MitchellSmooth
            | JwfKernel::MitchellSinePow => 2.0,
            JwfKernel::Lanczos3 => 3.0,
        }
    }

    /// The kernel's value at distance `x` from the centre (in units of its support's scale).
    pub fn value(self, x: f64) -> f64 {
        let t = x.abs();
        match self {
            JwfKernel::Bell => filter::kernel(FilterShape::Bell, x),
            JwfKernel::Blackman => {
                sinc(x) * (0.42 + 0.5 * (PI * x).cos() + 0.08 * (2.0 * PI * x).cos())
            }
            JwfKernel::Box => filter::kernel(FilterShape::Box, x),
            JwfKernel::Bspline => filter::kernel(FilterShape::Bspline, x),
            JwfKernel::Catrom => filter::kernel(FilterShape::Catrom, x),
            JwfKernel::Gaussian => filter::gaussian(x),
            JwfKernel::Hamming => sinc(x) * (0.54 + 0.46 * (PI * x).cos()),
            JwfKernel::Hanning => sinc(x) * (0.5 + 0.5 * (PI * x).cos()),
            JwfKernel::Hermite => filter::kernel(FilterShape::Hermite, x),
            JwfKernel::Lanczos2 => {
                if t < 2.0 {
                    sinc(t / 2.0) * sinc(t) * sinc(t / 2.0)
                } else {
                    0.0
                }
            }
            JwfKernel::Lanczos3 => {
                if t < 3.0 {
                    sinc(t / 3.0) * sinc(t) * sinc(t / 3.0)
                } else {
                    0.0
                }
            }
            JwfKernel::Mitchell => mitchell(t, 1.0 / 3.0, 1.0 / 3.0),
            JwfKernel::MitchellSmooth | JwfKernel::MitchellSinePow => mitchell(t, 0.42, 0.29),
            JwfKernel::Quadratic => filter::kernel(FilterShape::Quadratic, x),
            JwfKernel::SinePow5 => sine_pow(x, 5.0),
            JwfKernel::SinePow10 => sine_pow(x, 10.0),
            JwfKernel::SinePow15 => sine_pow(x, 15.0),
            JwfKernel::Triangle => filter::kernel(FilterShape::Triangle, x),
        }
    }
}

/// JWildfire's "sine power" kernels: acos(4·x^(p/ln 10) − 1)/π, 0 where that is undefined.
fn sine_pow(x: f64, p: f64) -> f64 {
    let v = (2.0 * (p * x.log10()).exp() * 2.0 - 1.0).acos() / PI;
    if v.is_finite() { v } else { 0.0 }
}

/// A square filter of `size`×`size` taps (odd size, 0 for no filter), as JWildfire builds it
/// for a kernel, radius and oversampling.
#[derive(Clone, Debug, PartialEq)]
pub struct JwfFilter {
    /// Taps per side (odd), or 0 when the radius is 0 (each pixel takes its own buckets).
    pub size: usize,
    /// Row-major weights, summing to os².
    pub taps: Vec<f64>,
}

impl JwfFilter {
    /// The filter of `kernel` at `radius` pixels for oversampling `os`.
    pub fn new(kernel: JwfKernel, radius: f64, os: usize) -> JwfFilter {
        if radius < 1e-6 {
            return JwfFilter {
                size: 0,
                taps: Vec::new(),
            };
        }
        let support = kernel.support();
        let fw = (2.0 * os as f64 * support * radius) as usize;
        let mut size = fw + 1;
        if size.is_multiple_of(2) {
            size += 1;
        }
        let adjust = if fw > 0 {
            support * size as f64 / fw as f64
        } else {
            1.0
        };
        let coord = |i: usize| ((2 * i + 1) as f64 / size as f64 - 1.0) * adjust;
        let mut taps = Vec::with_capacity(size * size);
        for i in 0..size {
            for j in 0..size {
                taps.push(kernel.value(coord(i).hypot(coord(j))));
            }
        }
        let sum: f64 = taps.iter().sum();
        let norm = (os * os) as f64 / sum;
        for t in &mut taps {
            *t *= norm;
        }
        JwfFilter { size, taps }
    }

    /// True for the empty filter (size 0 or 1: each pixel takes its own buckets).
    pub fn is_empty(&self) -> bool {
        self.size <= 1
    }

    /// JWildfire reads the taps from `size/2 − 1` buckets before the pixel's first bucket:
    /// its filtered picture sits one bucket off centre.
    pub fn lead(&self) -> isize {
        self.size as isize / 2 - 1
    }

    /// The border of buckets JWildfire adds around the picture for this filter.
    pub fn border(&self, os: usize) -> usize {
        self.size.saturating_sub(os) / 2
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for k in JwfKernel::ALL {
            assert_eq!(JwfKernel::from_name(k.name()), Some(k));
        }
        assert_eq!(JwfKernel::from_name("mitchell_smooth"), None);
    }

    /// JWildfire's default filter, MITCHELL_SMOOTH at radius 0.75: five taps per side at
    /// distances ±4/3 and ±8/3 from the centre, so only the centre and its eight neighbours
    /// weigh anything; the Gaussian of radius 0.75 that blurs the density has three.
    #[test]
    fn the_default_filters() {
        let f = JwfFilter::new(JwfKernel::MitchellSmooth, 0.75, 1);
        assert_eq!((f.size, f.lead(), f.border(1)), (5, 1, 2));
        let sum: f64 = f.taps.iter().sum();
        assert!((sum - 1.0).abs() < 1e-12);
        let at = |i: usize, j: usize| f.taps[i * 5 + j];
        let (c, e) = (mitchell(0.0, 0.42, 0.29), mitchell(4.0 / 3.0, 0.42, 0.29));
        let d = mitchell((32.0f64 / 9.0).sqrt(), 0.42, 0.29);
        let total = c + 4.0 * e + 4.0 * d;
        assert!((at(2, 2) - c / total).abs() < 1e-12);
        assert!((at(2, 3) - e / total).abs() < 1e-12);
        assert!((at(1, 1) - d / total).abs() < 1e-12);
        assert_eq!(at(0, 2), 0.0);
        let g = JwfFilter::new(JwfKernel::Gaussian, 0.75, 1);
        assert_eq!((g.size, g.lead()), (3, 0));
        assert!(JwfFilter::new(JwfKernel::Gaussian, 0.0, 1).is_empty());
    }

    #[test]
    fn every_kernel_normalises() {
        for k in JwfKernel::ALL {
            for os in 1..=2 {
                let f = JwfFilter::new(k, 1.0, os);
                let sum: f64 = f.taps.iter().sum();
                assert!((sum - (os * os) as f64).abs() < 1e-9, "{k:?}");
                assert_eq!(f.size % 2, 1);
            }
        }
    }
}
