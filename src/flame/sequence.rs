//! Animation settings of a flame, as flam3 keeps them: the control point's `time`, how
//! in-betweens are computed (`interpolation`, `interpolation_type`, `palette_interpolation`),
//! the motion blur of a frame (`temporal_samples`, `temporal_filter_*`) and an xform's
//! `<motion>` elements. The formulas are those of flam3 3.1.1 (`flam3_create_temporal_filter`,
//! `motion_funcs`), whose `flam3-animate` is the reference for sequences.

/// How the control points around a time are blended (`interpolation`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Interpolation {
    /// Between the two control points around the time.
    #[default]
    Linear,
    /// Catmull-Rom through four control points (not on the first or last segment).
    Smooth,
}

impl Interpolation {
    /// The value's name in flame XML (the `interpolation` attribute).
    pub fn name(self) -> &'static str {
        match self {
            Interpolation::Linear => "linear",
            Interpolation::Smooth => "smooth",
        }
    }
    /// The value named `s` in flame XML (the inverse of [`Self::name`]); `None` for a name
    /// flam3 does not know.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "linear" => Some(Interpolation::Linear),
            "smooth" => Some(Interpolation::Smooth),
            _ => None,
        }
    }
}

/// How the affine maps of xforms are blended (`interpolation_type`, formerly
/// `interpolation_space`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum InterpolationType {
    /// Coefficients blended linearly; padding xforms do not turn in rotations.
    Linear,
    /// Each column of the linear part in polar form (angle linearly, length logarithmically),
    /// translation linearly; padding xforms chosen to match their partners.
    #[default]
    Log,
    /// flam3 2.7's behaviour (`old`): linear, padding xforms plain (no matching to their
    /// partners, no parameters carried over) and not turned in rotations.
    Compat,
    /// flam3 2.6's behaviour (`older`): blended exactly as `old`, as flam3 3.1.1 does too;
    /// kept apart so that a file says what it said.
    Older,
}

impl InterpolationType {
    /// The value's name in flame XML (the `interpolation_type` attribute).
    pub fn name(self) -> &'static str {
        match self {
            InterpolationType::Linear => "linear",
            InterpolationType::Log => "log",
            InterpolationType::Compat => "old",
            InterpolationType::Older => "older",
        }
    }
    /// The value named `s` in flame XML (the inverse of [`Self::name`]); `None` for a name
    /// flam3 does not know.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "linear" => Some(InterpolationType::Linear),
            "log" => Some(InterpolationType::Log),
            "old" => Some(InterpolationType::Compat),
            "older" => Some(InterpolationType::Older),
            _ => None,
        }
    }
}

/// How palettes are blended (`palette_interpolation`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum PaletteInterpolation {
    /// Entry by entry in HSV.
    Hsv,
    /// In HSV with the hue along the shorter way round, mixed with RGB by
    /// `hsv_rgb_palette_blend`.
    #[default]
    HsvCircular,
    /// Entry by entry in RGB.
    Rgb,
    /// The first palette's entries up to the blend point, the second's after it.
    Sweep,
}

impl PaletteInterpolation {
    /// The value's name in flame XML (the `palette_interpolation` attribute).
    pub fn name(self) -> &'static str {
        match self {
            PaletteInterpolation::Hsv => "hsv",
            PaletteInterpolation::HsvCircular => "hsv_circular",
            PaletteInterpolation::Rgb => "rgb",
            PaletteInterpolation::Sweep => "sweep",
        }
    }
    /// The value named `s` in flame XML (the inverse of [`Self::name`]); `None` for a name
    /// flam3 does not know.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "hsv" => Some(PaletteInterpolation::Hsv),
            "hsv_circular" => Some(PaletteInterpolation::HsvCircular),
            "rgb" => Some(PaletteInterpolation::Rgb),
            "sweep" => Some(PaletteInterpolation::Sweep),
            _ => None,
        }
    }
}

/// The weighting of the sub-frames of a motion-blurred frame (`temporal_filter_type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum TemporalFilterType {
    /// Every sub-frame weighs the same (flam3's default).
    #[default]
    Box,
    /// flam3's Gaussian kernel exp(−2x²) over the exposure, x running from 1.5 at its start to
    /// 0 at the sub-frame `n/2` (the later middle one for an even count), so the middle of the
    /// exposure weighs most.
    Gaussian,
    /// `pow(x, |temporal_filter_exp|)`, rising towards the end of the exposure for a positive
    /// exponent and towards its start for a negative one.
    Exp,
}

impl TemporalFilterType {
    /// The value's name in flame XML (the `temporal_filter_type` attribute).
    pub fn name(self) -> &'static str {
        match self {
            TemporalFilterType::Box => "box",
            TemporalFilterType::Gaussian => "gaussian",
            TemporalFilterType::Exp => "exp",
        }
    }
    /// The value named `s` in flame XML (the inverse of [`Self::name`]); `None` for a name
    /// flam3 does not know.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "box" => Some(TemporalFilterType::Box),
            "gaussian" => Some(TemporalFilterType::Gaussian),
            "exp" => Some(TemporalFilterType::Exp),
            _ => None,
        }
    }
}

/// Most sub-frames of one frame ugnis renders (flam3 has no limit; a frame needs at least one
/// sample per sub-frame to mean anything).
pub const MAX_TEMPORAL_SAMPLES: u32 = 100_000;

/// A flame's animation settings. The defaults are flam3's for a file that does not say.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Animation {
    /// The control point's time (`time`): frame t of a sequence is time t.
    pub time: f64,
    /// How the control points around a time are chosen and blended (`interpolation`;
    /// default linear).
    pub interpolation: Interpolation,
    /// How the affine maps of xforms are blended and padding xforms chosen
    /// (`interpolation_type`; default log).
    pub interpolation_type: InterpolationType,
    /// How palettes are blended (`palette_interpolation`; default hsv_circular).
    pub palette_interpolation: PaletteInterpolation,
    /// With `hsv_circular`: 0 blends palettes in HSV, 1 in RGB (`hsv_rgb_palette_blend`).
    pub hsv_rgb_palette_blend: f64,
    /// Sub-frames of a frame (`temporal_samples`), each drawn from the flame at its own time.
    /// Default 1000, as in flam3; at most [`MAX_TEMPORAL_SAMPLES`] are used.
    pub temporal_samples: u32,
    /// The weighting of the sub-frames (`temporal_filter_type`; default box).
    pub temporal_filter_type: TemporalFilterType,
    /// The exposure, in frames (`temporal_filter_width`): sub-frames span time ± width/2.
    pub temporal_filter_width: f64,
    /// The exponent of the `exp` filter (`temporal_filter_exp`).
    pub temporal_filter_exp: f64,
}

impl Default for Animation {
    fn default() -> Self {
        Animation {
            time: 0.0,
            interpolation: Interpolation::Linear,
            interpolation_type: InterpolationType::Log,
            palette_interpolation: PaletteInterpolation::HsvCircular,
            hsv_rgb_palette_blend: 0.0,
            temporal_samples: 1000,
            temporal_filter_type: TemporalFilterType::Box,
            temporal_filter_width: 1.0,
            temporal_filter_exp: 0.0,
        }
    }
}

/// The periodic function of a `<motion>` element (`motion_function`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MotionFunction {
    /// sin(2πt).
    Sin,
    /// A triangle wave: 0 at t = 0, 1 at ¼, −1 at ¾.
    Triangle,
    /// (1 − cos 2πt)/2: from 0 up to 1 at ½ and back. flam3 uses it when none is named.
    #[default]
    Hill,
}

impl MotionFunction {
    /// The value's name in flame XML (the `motion_function` attribute).
    pub fn name(self) -> &'static str {
        match self {
            MotionFunction::Sin => "sin",
            MotionFunction::Triangle => "triangle",
            MotionFunction::Hill => "hill",
        }
    }
    /// The value named `s` in flame XML (the inverse of [`Self::name`]); `None` for a name
    /// flam3 does not know.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "sin" => Some(MotionFunction::Sin),
            "triangle" => Some(MotionFunction::Triangle),
            "hill" => Some(MotionFunction::Hill),
            _ => None,
        }
    }

    /// The function at `t` (period 1, 0 at whole numbers).
    pub fn eval(self, t: f64) -> f64 {
        use std::f64::consts::PI;
        match self {
            MotionFunction::Sin => (2.0 * PI * t).sin(),
            MotionFunction::Triangle => {
                let mut fr = t % 1.0;
                if fr < 0.0 {
                    fr += 1.0;
                }
                if fr <= 0.25 {
                    4.0 * fr
                } else if fr <= 0.75 {
                    -4.0 * fr + 2.0
                } else {
                    4.0 * fr - 4.0
                }
            }
            MotionFunction::Hill => (1.0 - (2.0 * PI * t).cos()) * 0.5,
        }
    }
}

/// The sub-frame times (offsets from the frame's time) and weights of a motion-blurred frame,
/// and the mean weight (flam3's `sumfilt`, which the log-density scale divides by).
#[derive(Clone, Debug, PartialEq)]
pub struct TemporalFilter {
    /// Each sub-frame's time less the frame's, in frames, rising from −width/2 to width/2
    /// (a single sub-frame sits at 0).
    pub deltas: Vec<f64>,
    /// Each sub-frame's weight, in (0, 1], the largest 1 (as many as `deltas`).
    pub weights: Vec<f64>,
    /// The mean of `weights` (flam3's `sumfilt`); 1 for the box filter.
    pub mean_weight: f64,
}

impl TemporalFilter {
    /// `steps` sub-frames spread evenly over [−width/2, width/2], weighted by the filter and
    /// scaled so that the largest weight is 1.
    pub fn new(steps: usize, kind: TemporalFilterType, exp: f64, width: f64) -> TemporalFilter {
        if steps <= 1 {
            return TemporalFilter {
                deltas: vec![0.0],
                weights: vec![1.0],
                mean_weight: 1.0,
            };
        }
        let n = steps as f64;
        let deltas = (0..steps)
            .map(|i| (i as f64 / (n - 1.0) - 0.5) * width)
            .collect();
        let mut weights: Vec<f64> = match kind {
            TemporalFilterType::Exp => (0..steps)
                .map(|i| {
                    let slpx = if exp >= 0.0 {
                        (i as f64 + 1.0) / n
                    } else {
                        (n - i as f64) / n
                    };
                    slpx.powf(exp.abs())
                })
                .collect(),
            TemporalFilterType::Gaussian => {
                let half = n / 2.0;
                (0..steps)
                    .map(|i| gaussian_kernel(1.5 * (i as f64 - half).abs() / half))
                    .collect()
            }
            TemporalFilterType::Box => vec![1.0; steps],
        };
        let max = weights.iter().cloned().fold(0.0, f64::max);
        if max > 0.0 {
            for w in &mut weights {
                *w /= max;
            }
        }
        let mean_weight = weights.iter().sum::<f64>() / n;
        TemporalFilter {
            deltas,
            weights,
            mean_weight,
        }
    }

    /// The filter of a flame's settings (`temporal_samples` sub-frames).
    pub fn of(a: &Animation) -> TemporalFilter {
        TemporalFilter::new(
            a.temporal_samples.clamp(1, MAX_TEMPORAL_SAMPLES) as usize,
            a.temporal_filter_type,
            a.temporal_filter_exp,
            a.temporal_filter_width,
        )
    }
}

/// flam3's Gaussian spatial kernel, exp(−2x²)·√(2/π), whose support is 1.5.
fn gaussian_kernel(x: f64) -> f64 {
    (-2.0 * x * x).exp() * (2.0 / std::f64::consts::PI).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_filter_spans_the_exposure_evenly() {
        let f = TemporalFilter::new(5, TemporalFilterType::Box, 0.0, 1.0);
        assert_eq!(f.deltas, vec![-0.5, -0.25, 0.0, 0.25, 0.5]);
        assert_eq!(f.weights, vec![1.0; 5]);
        assert_eq!(f.mean_weight, 1.0);
        let one = TemporalFilter::new(1, TemporalFilterType::Exp, 3.0, 2.0);
        assert_eq!(
            (one.deltas, one.weights, one.mean_weight),
            (vec![0.0], vec![1.0], 1.0)
        );
    }

    #[test]
    fn exp_filter_rises_towards_the_end_for_a_positive_exponent() {
        // weights ((i+1)/n)^2 for n = 4: 1/16, 4/16, 9/16, 1, already max 1.
        let f = TemporalFilter::new(4, TemporalFilterType::Exp, 2.0, 1.0);
        assert_eq!(f.weights, vec![0.0625, 0.25, 0.5625, 1.0]);
        assert!((f.mean_weight - 1.875 / 4.0).abs() < 1e-15);
        let g = TemporalFilter::new(4, TemporalFilterType::Exp, -2.0, 1.0);
        assert_eq!(g.weights, vec![1.0, 0.5625, 0.25, 0.0625]);
    }

    #[test]
    fn gaussian_filter_peaks_at_the_middle_sample() {
        // flam3 measures |i − n/2| / (n/2), so the peak is at i = n/2 (the later of the two
        // middle samples of an even count) and the first sample sits at the kernel's edge.
        let f = TemporalFilter::new(4, TemporalFilterType::Gaussian, 0.0, 1.0);
        assert_eq!(f.weights[2], 1.0);
        let edge = (-2.0f64 * 1.5 * 1.5).exp();
        assert!((f.weights[0] - edge).abs() < 1e-15);
        assert!((f.weights[1] - f.weights[3]).abs() < 1e-15);
    }

    #[test]
    fn motion_functions_are_periodic_and_zero_at_whole_numbers() {
        for func in [
            MotionFunction::Sin,
            MotionFunction::Triangle,
            MotionFunction::Hill,
        ] {
            for k in -2..3 {
                assert!(func.eval(k as f64).abs() < 1e-12, "{func:?} at {k}");
            }
            assert!((func.eval(0.3) - func.eval(2.3)).abs() < 1e-12);
        }
        assert!((MotionFunction::Triangle.eval(0.25) - 1.0).abs() < 1e-15);
        assert!((MotionFunction::Triangle.eval(0.75) + 1.0).abs() < 1e-15);
        assert!((MotionFunction::Triangle.eval(-0.25) + 1.0).abs() < 1e-15);
        assert!((MotionFunction::Hill.eval(0.5) - 1.0).abs() < 1e-15);
        assert!((MotionFunction::Sin.eval(0.25) - 1.0).abs() < 1e-15);
    }
}
