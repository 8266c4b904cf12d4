//! What a flame render is asked to do and whether it can: the render options, the error of a
//! render that cannot run, the limits of quality and work, the validation of the settings the
//! renderer divides by, and the bucket geometry of a flame.

use crate::flame::chaos::ChaosError;
use crate::flame::density::{DeError, DeFilters};
use crate::flame::geometry::Geometry;
use crate::flame::model::Flame;
use crate::flame::tonemap::OutputFormat;
use crate::memory::MemoryError;

/// Options of one render.
#[derive(Clone, Debug)]
pub struct RenderOptions {
    /// Seed of the random numbers: the same seed and thread count give the same picture.
    pub seed: u64,
    /// Worker threads; 0 means all cores. Requests above [`crate::threads::max_threads`] are
    /// clamped (see [`crate::threads::Threads`]).
    pub threads: usize,
    /// Refuse renders whose buffers would exceed this many bytes; `None`: the budget of
    /// [`crate::memory::budget`] (available memory, `ulimit -v`, cgroup limit).
    pub memory_limit: Option<u64>,
    /// Bits per channel and transparency of the image.
    pub format: OutputFormat,
    /// Keep every plotted sample (12 bytes each) so that `Renderer::recolor` can change the
    /// palette without iterating again. Ignored above [`MAX_KEPT_SAMPLES`].
    pub keep_samples: bool,
    /// The render state will be saved: the memory estimate counts the buffers its writer
    /// compresses in (see [`crate::flame::render::SAVE_BUFFER_BYTES`]).
    pub save_state: bool,
}

/// Largest render whose samples are kept for recolouring.
pub const MAX_KEPT_SAMPLES: u64 = 40_000_000;

/// Largest quality (samples per pixel). Artists' final renders use a few thousand; a million
/// at 640×480 is already 3·10¹¹ samples, hours on a desktop.
pub const MAX_QUALITY: f64 = 1e6;
/// Smallest quality: below one sample per hundred pixels the picture is a few scattered dots
/// (and at 1e-300 the log-density scale overflows to a black image).
pub const MIN_QUALITY: f64 = 0.01;
/// Most samples one render iterates (quality × 4^zoom × width × height): 10¹³ is about half a
/// day on eight cores.
pub const MAX_TOTAL_SAMPLES: f64 = 1e13;

impl Default for RenderOptions {
    fn default() -> Self {
        Self {
            seed: 1,
            threads: 0,
            memory_limit: None,
            format: OutputFormat::default(),
            keep_samples: false,
            save_state: false,
        }
    }
}

/// Why a render cannot run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RenderError {
    /// The flame cannot be iterated.
    #[error(transparent)]
    Chaos(#[from] ChaosError),
    /// The density-estimation settings are invalid.
    #[error(transparent)]
    De(#[from] DeError),
    /// A render setting is out of range (the message says which).
    #[error("invalid render settings: {0}")]
    Settings(String),
    /// The render would not fit in the memory allowed.
    #[error(transparent)]
    OutOfMemory(#[from] MemoryError),
    /// The saved histogram of a resumed render could not be read.
    #[error("{0}")]
    Saved(String),
}

/// The bucket geometry of a (framed) flame.
pub fn geometry_of(flame: &Flame) -> Result<Geometry, RenderError> {
    let de = DeFilters::shared(
        flame.estimator_radius,
        flame.estimator_minimum,
        flame.estimator_curve,
        flame.supersample.max(1),
    )?;
    Ok(Geometry::new(flame, de))
}

/// A number for a message: plain, or with an exponent when very large or small (1e12, 1e-300).
pub fn short_num(v: f64) -> String {
    if v != 0.0 && v.is_finite() && !(1e-3..1e9).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// Validate the settings that the renderer divides by, and the limits of the work.
pub fn validate_settings(flame: &Flame) -> Result<(), RenderError> {
    let bad = |m: String| Err(RenderError::Settings(m));
    if flame.width == 0 || flame.height == 0 {
        return bad(format!(
            "image size {}×{} must be at least 1×1",
            flame.width, flame.height
        ));
    }
    if !(flame.scale > 0.0 && flame.scale.is_finite()) {
        return bad(format!("scale {} must be positive", flame.scale));
    }
    if !(flame.quality > 0.0 && flame.quality.is_finite()) {
        return bad(format!("quality {} must be positive", flame.quality));
    }
    if !(MIN_QUALITY..=MAX_QUALITY).contains(&flame.quality) {
        return bad(format!(
            "quality {} is outside {MIN_QUALITY}..{MAX_QUALITY} samples per pixel",
            short_num(flame.quality)
        ));
    }
    if flame.gamma.is_nan() || flame.gamma <= 0.0 {
        return bad(format!("gamma {} must be positive", flame.gamma));
    }
    if flame.contrast.is_nan() || flame.contrast <= 0.0 {
        return bad(format!("contrast {} must be positive", flame.contrast));
    }
    if flame.brightness.is_nan() || flame.brightness <= 0.0 {
        return bad(format!("brightness {} must be positive", flame.brightness));
    }
    if flame.supersample == 0 || flame.supersample > 16 {
        return bad(format!(
            "supersample {} must be in 1..16",
            flame.supersample
        ));
    }
    if !(flame.filter >= 0.0 && flame.filter <= 100.0) {
        return bad(format!("filter radius {} must be in 0..100", flame.filter));
    }
    if !flame.zoom.is_finite() || flame.zoom.abs() > 50.0 {
        return bad(format!("zoom {} is out of range", flame.zoom));
    }
    let samples = flame.quality * 4f64.powf(flame.zoom) * flame.width as f64 * flame.height as f64;
    // NaN (from an infinite zoom factor times zero) is refused too.
    if samples.is_nan() || samples > MAX_TOTAL_SAMPLES {
        return bad(format!(
            "{samples:.3e} samples (quality {} × 4^zoom {} × {}×{} pixels) are more than the \
             limit of {MAX_TOTAL_SAMPLES:.0e}; lower the quality, the zoom or the size",
            short_num(flame.quality),
            flame.zoom,
            flame.width,
            flame.height
        ));
    }
    Ok(())
}

/// The highest quality a render of `flame` may reach: [`MAX_QUALITY`], or less when the
/// samples of its zoom and size would pass [`MAX_TOTAL_SAMPLES`] first. `Renderer::extend`
/// refuses to go past it.
pub fn quality_limit(flame: &Flame) -> f64 {
    let per_quality = flame.samples_per_quality();
    let by_samples = MAX_TOTAL_SAMPLES / per_quality;
    if by_samples.is_finite() && by_samples > 0.0 {
        by_samples.min(MAX_QUALITY)
    } else {
        MAX_QUALITY
    }
}

/// Quality (samples per pixel, before the zoom's 4^zoom) that `samples` iterations give
/// `flame`: the inverse of [`Flame::total_samples`].
pub fn quality_of_samples(flame: &Flame, samples: u64) -> f64 {
    let per_quality = flame.samples_per_quality();
    if per_quality.is_finite() && per_quality > 0.0 {
        samples as f64 / per_quality
    } else {
        0.0
    }
}
