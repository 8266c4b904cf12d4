//! The progressive renderer: chaos game into per-thread histograms, then density estimation,
//! spatial filter and tone mapping.
//!
//! ```text
//! let mut r = Renderer::new(&flame, &RenderOptions::default())?;
//! while !r.is_done() {
//!     r.run(r.total_samples() / 10, &cancel);   // one pass
//!     show(r.preview());                        // correctly exposed mid-render
//! }
//! let image = r.finish();
//! ```
//!
//! Determinism: the samples are cut into sub-batches of 10 000; sub-batch j is iterated with
//! a generator seeded from (seed, j) by thread j mod T into that thread's histogram. The image
//! therefore depends only on the flame, the seed and the thread count — not on timing or on how
//! the work was split into passes.

use std::sync::atomic::{AtomicBool, Ordering};

use image::DynamicImage;
use rayon::prelude::*;

use crate::flame::chaos::{Chaos, ChaosError, Lanes, SUB_BATCH};
use crate::flame::density::{DeError, DeFilters};
use crate::flame::framing;
use crate::flame::geometry::Geometry;
use crate::flame::histogram::{Bucket, Histogram, PlotPalette, scale_bucket};
use crate::flame::ifs3d::Ifs3dSystem;
use crate::flame::model::{Flame, PaletteMode};
use crate::flame::rng::FastRng;
use crate::flame::state::{Part, RenderState};
use crate::flame::tonemap::{LogScale, LogTable, OutputFormat, ToneMap};
use crate::memory::MemoryError;
use crate::threads::Threads;

/// Options of one render.
#[derive(Clone, Debug)]
pub struct RenderOptions {
    pub seed: u64,
    /// Worker threads; 0 means all cores. Requests above [`crate::threads::max_threads`] are
    /// clamped (see [`crate::threads::Threads`]).
    pub threads: usize,
    /// Refuse renders whose buffers would exceed this many bytes; `None`: the budget of
    /// [`crate::memory::budget`] (available memory, `ulimit -v`, cgroup limit).
    pub memory_limit: Option<u64>,
    pub format: OutputFormat,
    /// Keep every plotted sample (12 bytes each) so that [`Renderer::recolor`] can change the
    /// palette without iterating again. Ignored above [`MAX_KEPT_SAMPLES`].
    pub keep_samples: bool,
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
        }
    }
}

/// Why a render cannot run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RenderError {
    #[error(transparent)]
    Chaos(#[from] ChaosError),
    #[error(transparent)]
    De(#[from] DeError),
    #[error("invalid render settings: {0}")]
    Settings(String),
    #[error(transparent)]
    OutOfMemory(#[from] MemoryError),
    /// The saved histogram of a resumed render could not be read.
    #[error("{0}")]
    Saved(String),
}

/// Memory the buffers of a render will need, in bytes, part by part.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MemoryEstimate {
    /// Threads the estimate is for (resolved and clamped).
    pub threads: usize,
    /// One histogram (os·W + 2g by os·H + 2g buckets of 16 bytes).
    pub histogram: u64,
    /// Every thread's histogram, orbit lanes and plot buffer.
    pub workers: u64,
    /// Developing: the density-estimation accumulator and the merged copy a preview makes.
    pub develop: u64,
    /// The output image and the copy made while encoding it.
    pub image: u64,
    /// Kept samples for recolouring (0 unless asked for).
    pub kept_samples: u64,
    pub total: u64,
}

impl MemoryEstimate {
    /// What to change when the estimate does not fit: the largest part first.
    pub fn hint(&self, flame: &Flame) -> String {
        let mut h = String::from("reduce the image size");
        if flame.supersample > 1 {
            h.push_str(&format!(" or the supersample ({})", flame.supersample));
        }
        if self.threads > 1 {
            h.push_str(&format!(
                ", or use fewer threads ({} histograms of {} each)",
                self.threads,
                crate::memory::fmt_bytes(self.histogram)
            ));
        }
        if self.kept_samples > 0 {
            h.push_str(", or do not keep samples for recolouring");
        }
        h
    }
}

/// Estimate the buffers of a render before allocating anything. The threads are resolved
/// as the renderer resolves them. A render in strips estimates one strip with
/// [`estimate_memory_rows`].
pub fn estimate_memory(flame: &Flame, opts: &RenderOptions) -> MemoryEstimate {
    estimate_memory_rows(flame, opts, None)
}

/// As [`estimate_memory`] for a band of the image: `rows` = (bucket rows held, output rows
/// made) of one strip; `None` for the whole image.
pub fn estimate_memory_rows(
    flame: &Flame,
    opts: &RenderOptions,
    rows: Option<(u64, u64)>,
) -> MemoryEstimate {
    let threads = Threads::resolve(opts.threads).count as u64;
    let os = flame.supersample.max(1) as u64;
    let g = {
        let f =
            crate::flame::filter::SpatialFilter::new(flame.filter_shape, flame.filter, os as u32);
        let de = if flame.estimator_radius > 0.0 {
            flame.estimator_radius.ceil() as u64 * os + (os - 1)
        } else {
            0
        };
        (f.gutter as u64).max(de)
    };
    let bw = os * flame.width as u64 + 2 * g;
    let bh = match rows {
        Some((hist_rows, _)) => hist_rows,
        None => os * flame.height as u64 + 2 * g,
    };
    let bucket = std::mem::size_of::<Bucket>() as u64;
    let hist = bw.saturating_mul(bh).saturating_mul(bucket);
    let per_worker =
        std::mem::size_of::<Lanes>() as u64 + SUB_BATCH * std::mem::size_of::<Pending>() as u64;
    let workers = (hist + per_worker).saturating_mul(threads);
    let develop = hist.saturating_mul(2);
    let px = flame.width as u64
        * match rows {
            Some((_, out_rows)) => out_rows,
            None => flame.height as u64,
        };
    let channels = if opts.format.transparent { 4 } else { 3 };
    let depth = if opts.format.bits16 { 2 } else { 1 };
    let image = px.saturating_mul(channels * depth * 2);
    let samples = flame.total_samples();
    let kept_samples = if opts.keep_samples && samples <= MAX_KEPT_SAMPLES {
        samples * std::mem::size_of::<Pending>() as u64
    } else {
        0
    };
    MemoryEstimate {
        threads: threads as usize,
        histogram: hist,
        workers,
        develop,
        image,
        kept_samples,
        total: workers
            .saturating_add(develop)
            .saturating_add(image)
            .saturating_add(kept_samples),
    }
}

/// As [`check_memory`] for one strip of a render in strips.
pub fn check_memory_rows(
    flame: &Flame,
    opts: &RenderOptions,
    strip: &crate::flame::strips::Strip,
) -> Result<MemoryEstimate, RenderError> {
    let rows = (strip.hist_rows.len() as u64, strip.out_rows.len() as u64);
    let est = estimate_memory_rows(flame, opts, Some(rows));
    crate::memory::check(
        est.total,
        opts.memory_limit,
        || {
            format!(
                "a strip of {} rows of a {}×{} flame render at supersample {} with {} thread(s)",
                rows.1, flame.width, flame.height, flame.supersample, est.threads
            )
        },
        || format!("use more strips, or {}", est.hint(flame)),
    )?;
    Ok(est)
}

/// Refuse a render whose estimate exceeds the memory budget (`opts.memory_limit`, or what
/// the system allows: see [`crate::memory`]).
pub fn check_memory(flame: &Flame, opts: &RenderOptions) -> Result<MemoryEstimate, RenderError> {
    let est = estimate_memory(flame, opts);
    crate::memory::check(
        est.total,
        opts.memory_limit,
        || {
            format!(
                "a {}×{} flame render at supersample {} with {} thread(s)",
                flame.width, flame.height, flame.supersample, est.threads
            )
        },
        || est.hint(flame),
    )?;
    Ok(est)
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

/// Memory available to this process (Linux `MemAvailable`), if known.
pub fn available_memory() -> Option<u64> {
    crate::memory::available_memory()
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
/// samples of its zoom and size would pass [`MAX_TOTAL_SAMPLES`] first. [`Renderer::extend`]
/// refuses to go past it.
pub fn quality_limit(flame: &Flame) -> f64 {
    let per_quality = 4f64.powf(flame.zoom) * flame.width as f64 * flame.height as f64;
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
    let per_quality = 4f64.powf(flame.zoom) * flame.width as f64 * flame.height as f64;
    if per_quality.is_finite() && per_quality > 0.0 {
        samples as f64 / per_quality
    } else {
        0.0
    }
}

/// How a render's work is cut: which share of the samples (for other processes or machines)
/// and which band of the image (for renders in strips).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Plan {
    pub part: Part,
    /// Accumulate only this band; `None`: the whole image.
    pub strip: Option<crate::flame::strips::Strip>,
}

/// Memory of an earlier render that a new one may reuse: histograms (cleared before use) and
/// sample logs (emptied, their capacity kept).
#[derive(Default)]
pub struct Spare {
    hists: Vec<Histogram>,
    logs: Vec<Vec<Pending>>,
}

impl Spare {
    /// A zeroed `bw`×`bh` histogram: a spare one when one has room for it without holding
    /// more than twice the memory needed, otherwise a new one.
    fn histogram(&mut self, bw: usize, bh: usize) -> Histogram {
        let n = bw * bh;
        let fits = |h: &Histogram| (n..=2 * n.max(1)).contains(&h.data.capacity());
        match self.hists.iter().position(fits) {
            Some(i) => {
                let mut h = self.hists.swap_remove(i);
                h.data.clear();
                h.data.resize(n, [0.0; 4]);
                h.bw = bw;
                h.bh = bh;
                h
            }
            None => Histogram::new(bw, bh),
        }
    }

    /// An empty sample log (a spare one keeps its capacity).
    fn log(&mut self) -> Vec<Pending> {
        let mut l = self.logs.pop().unwrap_or_default();
        l.clear();
        l
    }
}

/// A render in progress.
pub struct Renderer {
    flame: Flame,
    chaos: Chaos,
    /// Set for flames made from 3-D IFS entries: iterated instead of the xforms.
    ifs3d: Option<Ifs3dSystem>,
    geom: Geometry,
    /// Output rows this render develops (all, or the strip's).
    out_rows: std::ops::Range<usize>,
    palette: PlotPalette,
    hists: Vec<Histogram>,
    /// Each worker's orbits, kept between passes.
    lanes: Vec<Box<Lanes>>,
    /// Each worker's plotted samples, when kept for recolouring.
    logs: Option<Vec<Vec<Pending>>>,
    seed: u64,
    format: OutputFormat,
    part: Part,
    /// Samples of the whole render (every part).
    total: u64,
    /// Samples of this part.
    part_total: u64,
    /// Sub-batches of this part; `next_batch` counts them too (local indices).
    batches_total: u64,
    next_batch: u64,
    samples_done: u64,
    badvals: u64,
    cancelled: bool,
}

impl Renderer {
    /// Prepare a render: validates the flame, frames it automatically when it has no camera,
    /// estimates memory and allocates the histograms.
    pub fn new(flame: &Flame, opts: &RenderOptions) -> Result<Renderer, RenderError> {
        Self::with_plan(flame, opts, &Plan::default())
    }

    /// As [`Renderer::new`], taking its histograms and sample logs from `spare` (the memory
    /// of an earlier render, see [`Renderer::into_spare`]) where they fit. An editor that
    /// restarts its preview after every edit so skips the page faults of fresh memory and the
    /// unmapping of the old (together about 10 ms at 640×480 on 2 threads).
    pub fn reusing(
        flame: &Flame,
        opts: &RenderOptions,
        spare: &mut Spare,
    ) -> Result<Renderer, RenderError> {
        Self::build(flame, opts, &Plan::default(), spare)
    }

    /// This render's histograms and sample logs, for [`Renderer::reusing`].
    pub fn into_spare(self) -> Spare {
        Spare {
            hists: self.hists,
            logs: self.logs.unwrap_or_default(),
        }
    }

    /// As [`Renderer::new`] for one part of the samples and/or one strip of the image.
    pub fn with_plan(
        flame: &Flame,
        opts: &RenderOptions,
        plan: &Plan,
    ) -> Result<Renderer, RenderError> {
        Self::build(flame, opts, plan, &mut Spare::default())
    }

    fn build(
        flame: &Flame,
        opts: &RenderOptions,
        plan: &Plan,
        spare: &mut Spare,
    ) -> Result<Renderer, RenderError> {
        plan.part.validate().map_err(RenderError::Settings)?;
        let mut flame = flame.clone();
        validate_settings(&flame)?;
        let chaos = Chaos::new(&flame)?;
        let ifs3d = match &flame.ifs3d {
            Some(i) => Some(
                Ifs3dSystem::new(i)
                    .ok_or_else(|| RenderError::Settings("the 3-D IFS has no maps".into()))?,
            ),
            None => None,
        };
        if !flame.has_camera {
            framing::apply_auto_frame(&mut flame);
        }
        let threads = match &plan.strip {
            None => check_memory(&flame, opts)?.threads,
            Some(s) => check_memory_rows(&flame, opts, s)?.threads,
        };
        let de = DeFilters::shared(
            flame.estimator_radius,
            flame.estimator_minimum,
            flame.estimator_curve,
            flame.supersample.max(1),
        )?;
        let mut geom = Geometry::new(&flame, de);
        if geom.buckets() > u32::MAX as usize {
            return Err(RenderError::Settings(format!(
                "a {}×{} render at supersample {} has too many histogram buckets",
                flame.width, flame.height, flame.supersample
            )));
        }
        let out_rows = match &plan.strip {
            Some(s) => {
                if s.out_rows.end > geom.height || s.hist_rows.end > geom.full_bh {
                    return Err(RenderError::Settings(format!(
                        "strip rows {:?} are outside the {}×{} image",
                        s.out_rows, flame.width, flame.height
                    )));
                }
                geom = geom.window(s.hist_rows.clone());
                s.out_rows.clone()
            }
            None => 0..geom.height,
        };
        let hists = (0..threads)
            .map(|_| spare.histogram(geom.bw, geom.bh))
            .collect();
        let lanes = (0..threads).map(|_| Lanes::new()).collect();
        let total_samples = flame.total_samples();
        let logs = (opts.keep_samples && total_samples <= MAX_KEPT_SAMPLES && plan.strip.is_none())
            .then(|| (0..threads).map(|_| spare.log()).collect());
        let total = flame.total_samples().max(1);
        let part = plan.part;
        Ok(Renderer {
            palette: PlotPalette::new(&flame),
            chaos,
            ifs3d,
            geom,
            out_rows,
            hists,
            lanes,
            logs,
            seed: opts.seed,
            format: opts.format,
            part,
            total,
            part_total: part.samples(total),
            batches_total: part.local_batches(total.div_ceil(SUB_BATCH)),
            next_batch: 0,
            samples_done: 0,
            badvals: 0,
            cancelled: false,
            flame,
        })
    }

    /// Continue a saved render with `add_quality` more samples per pixel. `hist` holds the
    /// state's histogram: the whole bucket grid, or the rows of `strip` for a render in
    /// strips. With as many threads as the saved render had, the result is the picture of
    /// one render at the summed quality (up to the rounding of the sums).
    pub fn resume(
        state: &RenderState,
        hist: Histogram,
        add_quality: f64,
        opts: &RenderOptions,
        strip: Option<crate::flame::strips::Strip>,
    ) -> Result<Renderer, RenderError> {
        Self::resume_with(state, add_quality, opts, strip, |h| {
            if (hist.bw, hist.bh) != (h.bw, h.bh) {
                return Err(format!(
                    "the saved histogram is {}×{} buckets, the render needs {}×{}",
                    hist.bw, hist.bh, h.bw, h.bh
                ));
            }
            *h = hist;
            Ok(())
        })
    }

    /// [`Renderer::resume`] with the saved histogram written by `fill` into the renderer's
    /// first histogram (zeroed, of the render's size, allocated after the memory check), so
    /// that a saved histogram read from a file is never held twice. `fill`'s error is the
    /// resume's error.
    pub fn resume_with(
        state: &RenderState,
        add_quality: f64,
        opts: &RenderOptions,
        strip: Option<crate::flame::strips::Strip>,
        fill: impl FnOnce(&mut Histogram) -> Result<(), String>,
    ) -> Result<Renderer, RenderError> {
        let (part, next) = state.continuation().map_err(RenderError::Settings)?;
        let mut flame = state.flame.clone();
        flame.has_camera = true;
        let mut r = Self::with_plan(&flame, opts, &Plan { part, strip })?;
        fill(&mut r.hists[0]).map_err(RenderError::Saved)?;
        r.logs = None;
        r.next_batch = next.min(r.batches_total);
        r.samples_done = state.samples_done;
        r.badvals = state.bad_values;
        if state.lanes.len() == r.lanes.len() {
            for (l, s) in r.lanes.iter_mut().zip(&state.lanes) {
                if let Some(restored) = Lanes::restore(s) {
                    *l = restored;
                }
            }
        }
        r.extend(add_quality)?;
        Ok(r)
    }

    /// Raise the quality by `add_quality` samples per pixel and keep going: the next passes
    /// iterate the new sub-batches (a render that refines until it is stopped calls this
    /// whenever it is done). Kept samples for recolouring are dropped.
    pub fn extend(&mut self, add_quality: f64) -> Result<(), RenderError> {
        if !(add_quality >= 0.0 && add_quality.is_finite()) {
            return Err(RenderError::Settings(format!(
                "added quality {add_quality} must be a finite number ≥ 0"
            )));
        }
        if add_quality == 0.0 {
            return Ok(());
        }
        if self.cancelled {
            return Err(RenderError::Settings(
                "a cancelled render cannot continue".into(),
            ));
        }
        let mut f = self.flame.clone();
        f.quality += add_quality;
        validate_settings(&f)?;
        self.flame.quality = f.quality;
        self.logs = None;
        self.total = self.flame.total_samples().max(1);
        self.part_total = self.part.samples(self.total);
        self.batches_total = self
            .part
            .local_batches(self.total.div_ceil(SUB_BATCH))
            .max(self.next_batch);
        Ok(())
    }

    /// The flame as rendered (with its automatic framing applied).
    pub fn flame(&self) -> &Flame {
        &self.flame
    }

    /// Samples this render iterates in all (its part's share).
    pub fn total_samples(&self) -> u64 {
        self.part_total.max(1)
    }

    pub fn samples_done(&self) -> u64 {
        self.samples_done
    }

    pub fn bad_values(&self) -> u64 {
        self.badvals
    }

    /// The quality the samples done so far amount to (the flame's quality once the render
    /// is complete; less while it runs or after a stop between passes).
    pub fn quality_done(&self) -> f64 {
        quality_of_samples(&self.flame, self.samples_done)
    }

    pub fn threads(&self) -> usize {
        self.hists.len()
    }

    pub fn part(&self) -> Part {
        self.part
    }

    /// Fraction of the samples done, in [0, 1].
    pub fn fraction(&self) -> f64 {
        (self.samples_done as f64 / self.total_samples() as f64).min(1.0)
    }

    pub fn is_done(&self) -> bool {
        self.cancelled || self.next_batch >= self.batches_total
    }

    pub fn is_cancelled(&self) -> bool {
        self.cancelled
    }

    /// Run one pass of about `samples` more samples (whole sub-batches, at least one) on all
    /// threads. Returns false if `cancel` was set (checked between sub-batches, i.e. within
    /// about a millisecond); a cancelled render is finished and cannot continue. (A render
    /// that is to be saved and continued should stop between passes instead.)
    pub fn run(&mut self, samples: u64, cancel: &AtomicBool) -> bool {
        if self.is_done() {
            return !self.cancelled;
        }
        let n_batches = samples.div_ceil(SUB_BATCH).max(1);
        let start = self.next_batch;
        let end = (start + n_batches).min(self.batches_total);
        let threads = self.hists.len() as u64;
        let (chaos, geom, pal) = (&self.chaos, &self.geom, &self.palette);
        let ifs3d = self.ifs3d.as_ref();
        let (seed, total, part) = (self.seed, self.total, self.part);
        let mut logs: Vec<Option<&mut Vec<Pending>>> = match &mut self.logs {
            Some(l) => l.iter_mut().map(Some).collect(),
            None => (0..self.hists.len()).map(|_| None).collect(),
        };
        // One job per histogram on the rayon pool (at most its size run at once): the pool's
        // threads stay warm for the tone map that usually follows, where fresh threads per pass
        // were sometimes stacked on one core by the scheduler. Thread t always fills histogram
        // t with the same sub-batches, whichever pool thread runs it: the image does not
        // depend on the pool.
        let per_thread = (end - start).div_ceil(threads) * SUB_BATCH;
        let results: Vec<(u64, u64, bool)> = self
            .hists
            .par_iter_mut()
            .zip(self.lanes.par_iter_mut())
            .zip(logs.par_iter_mut())
            .enumerate()
            .with_max_len(1)
            .map(|(t, ((hist, lanes), log))| {
                let mut done = 0u64;
                let mut bad = 0u64;
                // First batch index ≥ start that belongs to thread t.
                let first = start + (t as u64 + threads - start % threads) % threads;
                let mut j = first;
                let mut buf = Vec::with_capacity(SUB_BATCH as usize);
                if let Some(log) = log.as_deref_mut() {
                    // The pass's samples, without the copies of a doubling vector.
                    log.reserve(per_thread as usize);
                }
                while j < end {
                    if cancel.load(Ordering::Relaxed) {
                        return (done, bad, true);
                    }
                    // Each sub-batch has its own stream, named by its index in the
                    // whole render (the same for every part and strip layout).
                    let g = part.global(j);
                    let n = SUB_BATCH.min(total.saturating_sub(g * SUB_BATCH));
                    let mut rng = FastRng::for_stream(seed, g);
                    bad += match ifs3d {
                        None => {
                            let b =
                                iterate_into(chaos, geom, pal, hist, &mut buf, lanes, n, &mut rng);
                            if let Some(log) = log.as_deref_mut() {
                                log.extend_from_slice(&buf);
                            }
                            b
                        }
                        Some(sys) => iterate_3d(sys, geom, pal, hist, n, &mut rng),
                    };
                    done += n;
                    j += threads;
                }
                (done, bad, false)
            })
            .collect();
        for (done, bad, cancelled) in results {
            self.samples_done += done;
            self.badvals += bad;
            self.cancelled |= cancelled;
        }
        self.next_batch = end;
        !self.cancelled
    }

    /// Run to the end, calling `progress(fraction)` after every pass of about 1/`passes` of
    /// the work. Returns false if cancelled.
    pub fn run_all(
        &mut self,
        passes: u64,
        cancel: &AtomicBool,
        mut progress: impl FnMut(f64),
    ) -> bool {
        let left = self
            .total_samples()
            .saturating_sub(self.samples_done)
            .max(1);
        let step = left.div_ceil(passes.max(1));
        while !self.is_done() {
            if !self.run(step, cancel) {
                return false;
            }
            progress(self.fraction());
        }
        true
    }

    /// Is every sub-batch of the whole render done (one part of one, run to the end)?
    fn complete(&self) -> bool {
        self.part.count == 1 && self.next_batch >= self.batches_total && !self.cancelled
    }

    /// Density used by the log scaling: the flame's quality·4^zoom when done, otherwise the
    /// samples actually done per pixel (so that previews are correctly exposed).
    fn density(&self) -> f64 {
        if self.complete() {
            return self.flame.quality * 4f64.powf(self.flame.zoom);
        }
        let px = self.flame.width as f64 * self.flame.height as f64;
        (self.samples_done.max(1) as f64) / px
    }

    fn merged(&self) -> Histogram {
        let mut m = self.hists[0].clone();
        for h in &self.hists[1..] {
            m.add(h);
        }
        m
    }

    /// The image as it stands (any time during the render).
    pub fn preview(&self) -> DynamicImage {
        self.preview_until(&AtomicBool::new(false))
            .expect("not stopped")
    }

    /// [`Renderer::preview`], or `None` as soon as `stop` is set (density estimation at low
    /// density takes tens of milliseconds; an editor drops a picture that an edit made stale).
    pub fn preview_until(&self, stop: &AtomicBool) -> Option<DynamicImage> {
        let m = self.merged();
        develop_rows_until(
            &self.flame,
            &self.geom,
            &m,
            self.density(),
            self.format,
            self.out_rows.clone(),
            stop,
        )
    }

    /// A quick look at the image as it stands: like [`Renderer::preview`] but without density
    /// estimation (a few milliseconds instead of tens at low densities, where DE kernels are
    /// widest). Same exposure; noisier. The GUI shows it first after an edit and while
    /// dragging.
    pub fn preview_draft(&self) -> DynamicImage {
        // The thread histograms are summed and log-scaled row by row inside the filter's bands
        // (no merged copy, one pass over memory).
        let src = Rows::Draft {
            hists: &self.hists,
            ls: LogTable::new(LogScale::new(&self.flame, self.density())),
        };
        let never = AtomicBool::new(false);
        filter_and_tonemap(
            &self.flame,
            &self.geom,
            &src,
            self.format,
            self.out_rows.clone(),
            &never,
        )
        .expect("not stopped")
    }

    /// True when the samples are kept and [`Renderer::recolor`] can be used.
    pub fn can_recolor(&self) -> bool {
        self.logs.is_some() && self.ifs3d.is_none()
    }

    /// Change the palette (and palette mode) by re-accumulating the kept samples: no iteration.
    /// Returns false when the samples were not kept (the caller must render again).
    pub fn recolor(
        &mut self,
        palette: &crate::gradient::Gradient,
        mode: crate::flame::PaletteMode,
    ) -> bool {
        let Some(logs) = &self.logs else { return false };
        if self.ifs3d.is_some() {
            return false;
        }
        self.flame.palette = palette.clone();
        self.flame.palette_mode = mode;
        self.palette = PlotPalette::new(&self.flame);
        let pal = &self.palette;
        self.hists
            .par_iter_mut()
            .zip(logs.par_iter())
            .for_each(|(h, log)| {
                h.clear();
                accumulate(pal, h, log);
            });
        true
    }

    /// The state to save (a copy: the render can go on). `None` after a cancel, whose
    /// bookkeeping of finished sub-batches is not exact.
    pub fn snapshot(&self) -> Option<(RenderState, Histogram)> {
        Some((self.state()?, self.merged()))
    }

    /// Finish into the state to save: merges the thread histograms in place. `None` after a
    /// cancel.
    pub fn into_state(mut self) -> Option<(RenderState, Histogram)> {
        let st = self.state()?;
        Some((st, self.take_merged()))
    }

    /// The bucket geometry (with the strip's window of rows, if any).
    pub fn geometry(&self) -> &Geometry {
        &self.geom
    }

    fn state(&self) -> Option<RenderState> {
        if self.cancelled {
            return None;
        }
        let mut flame = self.flame.clone();
        flame.has_camera = true;
        Some(RenderState {
            flame,
            seed: self.seed,
            part_count: self.part.count,
            parts: vec![self.part.index],
            batches_done: self.next_batch,
            samples_done: self.samples_done,
            bad_values: self.badvals,
            lanes: self.lanes.iter().map(|l| l.state()).collect(),
        })
    }

    fn take_merged(&mut self) -> Histogram {
        let mut hists = std::mem::take(&mut self.hists);
        let mut first = hists.swap_remove(0);
        for h in hists.drain(..) {
            first.add(&h);
        }
        first
    }

    /// Finish: merge the thread histograms in place (freeing them) and develop the image
    /// (the strip's rows for a render in strips).
    pub fn finish(mut self) -> DynamicImage {
        let density = self.density();
        let first = self.take_merged();
        develop_rows(
            &self.flame,
            &self.geom,
            &first,
            density,
            self.format,
            self.out_rows.clone(),
        )
    }

    /// As [`Renderer::finish`], also returning the state to save (`None` after a cancel).
    pub fn finish_with_state(mut self) -> (DynamicImage, Option<(RenderState, Histogram)>) {
        let density = self.density();
        let st = self.state();
        let first = self.take_merged();
        let img = develop_rows(
            &self.flame,
            &self.geom,
            &first,
            density,
            self.format,
            self.out_rows.clone(),
        );
        (img, st.map(|s| (s, first)))
    }
}

/// A plotted point waiting to be accumulated: bucket, colour coordinate, visibility.
type Pending = (u32, f32, f32);

/// Iterate one sub-batch into a histogram. The plotted points are first collected in `buf`
/// and then added in a tight loop, so the cache misses of the scattered adds overlap.
///
/// The loop is compiled twice: for the baseline CPU and with AVX2 and FMA, chosen at run
/// time. Rust never fuses a multiply and an add on its own, so both give the same bits.
#[allow(clippy::too_many_arguments)]
fn iterate_into(
    chaos: &Chaos,
    geom: &Geometry,
    pal: &PlotPalette,
    hist: &mut Histogram,
    buf: &mut Vec<Pending>,
    lanes: &mut Lanes,
    n: u64,
    rng: &mut FastRng,
) -> u64 {
    #[cfg(target_arch = "x86_64")]
    if crate::flame::fastmath::has_avx2_fma() {
        // SAFETY: the CPU has just reported AVX2 and FMA.
        return unsafe { iterate_into_avx2(chaos, geom, pal, hist, buf, lanes, n, rng) };
    }
    iterate_into_generic(chaos, geom, pal, hist, buf, lanes, n, rng)
}

/// [`iterate_into`] for CPUs with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[allow(clippy::too_many_arguments)]
fn iterate_into_avx2(
    chaos: &Chaos,
    geom: &Geometry,
    pal: &PlotPalette,
    hist: &mut Histogram,
    buf: &mut Vec<Pending>,
    lanes: &mut Lanes,
    n: u64,
    rng: &mut FastRng,
) -> u64 {
    iterate_into_generic(chaos, geom, pal, hist, buf, lanes, n, rng)
}

#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn iterate_into_generic(
    chaos: &Chaos,
    geom: &Geometry,
    pal: &PlotPalette,
    hist: &mut Histogram,
    buf: &mut Vec<Pending>,
    lanes: &mut Lanes,
    n: u64,
    rng: &mut FastRng,
) -> u64 {
    const L: usize = crate::flame::chaos::LANES;
    buf.clear();
    // At most n samples are kept, and each step writes up to L places beyond the kept ones.
    buf.reserve(n as usize + L);
    let map = geom.bucket_map();
    let (mut idx, mut keep) = ([0u32; L], [0u32; L]);
    let bad = chaos.run_lanes(n, rng, lanes, |xs, ys, _zs, cs, vs| {
        // Buckets as arrays (vectorised), then a branch-free compaction of the visible
        // points that land in the histogram.
        let m = xs.len().min(ys.len()).min(cs.len()).min(vs.len()).min(L);
        for j in 0..m {
            let (i, inside) = map.index(xs[j], ys[j]);
            idx[j] = i;
            keep[j] = (inside & (vs[j] > 0.0)) as u32;
        }
        // Written straight into the spare capacity of `buf`: every place is written before
        // it is counted, only the kept ones are counted.
        let len = buf.len();
        assert!(buf.capacity() - len >= L);
        let spare = buf.as_mut_ptr().wrapping_add(len);
        let mut k = 0;
        for j in 0..m {
            // SAFETY: k ≤ j < m ≤ L places after `len`, within the capacity just checked.
            unsafe {
                spare
                    .add(k & (L - 1))
                    .write((idx[j], cs[j] as f32, vs[j] as f32))
            };
            k += keep[j] as usize;
        }
        // SAFETY: places len..len + k were initialised just above (k ≤ m ≤ L).
        unsafe { buf.set_len(len + k.min(m)) };
    });
    accumulate(pal, hist, buf);
    bad
}

/// Add pending samples to a histogram.
#[inline(always)]
fn accumulate(pal: &PlotPalette, hist: &mut Histogram, buf: &[Pending]) {
    // The adds scatter over a histogram larger than the caches: ask for the bucket a few
    // samples ahead so its cache miss overlaps the adds in between.
    const AHEAD: usize = 40;
    // With a stepped palette the entries are looked up for a block of samples first, in a
    // loop of conversions the compiler vectorises (the same entry as `PlotPalette::lookup`).
    const BLOCK: usize = 64;
    let data = &mut hist.data;
    let colors = &pal.colors[..];
    let step = pal.mode == PaletteMode::Step && !colors.is_empty();
    let (scale, offset) = (pal.scale, pal.offset);
    let top = colors.len().saturating_sub(1) as f64;
    let add = |data: &mut [Bucket], i: usize, idx: u32, p: [f32; 4], v: f32| {
        if let Some(&(ahead, _, _)) = buf.get(i + AHEAD) {
            prefetch(data.as_ptr().wrapping_add(ahead as usize));
        }
        let b = &mut data[idx as usize];
        b[0] += p[0] * v;
        b[1] += p[1] * v;
        b[2] += p[2] * v;
        b[3] += p[3] * v;
    };
    if !step {
        for (i, &(idx, c, v)) in buf.iter().enumerate() {
            add(data, i, idx, pal.lookup(c as f64), v);
        }
        return;
    }
    let mut entry = [0u32; BLOCK];
    for (b, block) in buf.chunks(BLOCK).enumerate() {
        for (e, &(_, c, _)) in entry.iter_mut().zip(block) {
            // max/min also send NaN to 0, as the saturating cast of `lookup` does.
            let f = (c as f64 * scale + offset).max(0.0).min(top);
            // SAFETY: f is finite and within 0..=top, which fits a u32.
            *e = unsafe { f.to_int_unchecked::<u32>() };
        }
        for (j, (&(idx, _, v), &e)) in block.iter().zip(&entry).enumerate() {
            // SAFETY: e ≤ top = colors.len() - 1.
            let p = unsafe { *colors.get_unchecked(e as usize) };
            add(data, b * BLOCK + j, idx, p, v);
        }
    }
}

/// Hint the CPU to fetch the cache line at `p` (no effect on other targets).
#[inline(always)]
fn prefetch<T>(p: *const T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch never faults and does not read memory into the program; any
    // address, valid or not, is allowed.
    unsafe {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        _mm_prefetch::<_MM_HINT_T0>(p.cast::<i8>());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = p;
}

/// Iterate a 3-D IFS sub-batch into a histogram.
fn iterate_3d(
    sys: &Ifs3dSystem,
    geom: &Geometry,
    pal: &PlotPalette,
    hist: &mut Histogram,
    n: u64,
    rng: &mut FastRng,
) -> u64 {
    let data = &mut hist.data;
    sys.run_sub_batch(n, rng, |x, y, c, _| {
        if let Some(idx) = geom.bucket_of(x, y) {
            let p = pal.lookup(c);
            let b = &mut data[idx];
            b[0] += p[0];
            b[1] += p[1];
            b[2] += p[2];
            b[3] += p[3];
        }
    })
}

/// Turn a histogram into an image: log scaling (with density estimation when enabled),
/// spatial filter with downsampling, tone mapping.
pub fn develop(
    flame: &Flame,
    geom: &Geometry,
    hist: &Histogram,
    density: f64,
    format: OutputFormat,
) -> DynamicImage {
    develop_rows(flame, geom, hist, density, format, 0..geom.height)
}

/// As [`develop`] for output rows `out_rows` of the image, from a histogram holding bucket rows
/// `geom.row0 .. geom.row0 + geom.bh` of the whole grid. Those rows must reach the
/// density-estimation radius and the filter beyond the rows used (see
/// [`crate::flame::strips::plan`]); then every pixel is the one of the whole image.
pub fn develop_rows(
    flame: &Flame,
    geom: &Geometry,
    hist: &Histogram,
    density: f64,
    format: OutputFormat,
    out_rows: std::ops::Range<usize>,
) -> DynamicImage {
    let never = AtomicBool::new(false);
    develop_rows_until(flame, geom, hist, density, format, out_rows, &never).expect("not stopped")
}

/// [`develop_rows`], or `None` when `stop` is set before it is done (checked between bands).
fn develop_rows_until(
    flame: &Flame,
    geom: &Geometry,
    hist: &Histogram,
    density: f64,
    format: OutputFormat,
    out_rows: std::ops::Range<usize>,
    stop: &AtomicBool,
) -> Option<DynamicImage> {
    let ls = LogTable::new(LogScale::new(flame, density));
    let mut acc: Vec<Bucket> = Vec::new();
    let acc: &[Bucket] = match &geom.de {
        Some(de) => {
            acc.resize(geom.buckets(), [0.0; 4]);
            de.splat_until(hist, &mut acc, |a| ls.factor(a), stop);
            &acc
        }
        None => {
            acc = hist
                .data
                .par_iter()
                .map(|&b| scale_bucket(b, ls.factor(b[3])))
                .collect();
            &acc
        }
    };
    filter_and_tonemap(flame, geom, &Rows::Acc(acc), format, out_rows, stop)
}

/// Where the filter reads its bucket rows from.
enum Rows<'a> {
    /// Log-scaled (density-estimated) buckets.
    Acc(&'a [Bucket]),
    /// Raw thread histograms, summed and log-scaled as they are read.
    Draft {
        hists: &'a [Histogram],
        ls: LogTable,
    },
}

impl<'a> Rows<'a> {
    /// Bucket row `r` (`bw` buckets), in `buf` when it has to be computed.
    #[inline(always)]
    fn row<'b>(&'b self, r: usize, bw: usize, buf: &'b mut Vec<Bucket>) -> &'b [Bucket] {
        match self {
            Rows::Acc(acc) => &acc[r * bw..(r + 1) * bw],
            Rows::Draft { hists, ls } => {
                let scale = |b: Bucket| {
                    if b[3] <= 0.0 {
                        [0.0; 4]
                    } else {
                        scale_bucket(b, ls.factor(b[3]))
                    }
                };
                let sum =
                    |b: &Bucket, o: &Bucket| [b[0] + o[0], b[1] + o[1], b[2] + o[2], b[3] + o[3]];
                let at = |h: &'a Histogram| &h.data[r * bw..(r + 1) * bw];
                // Plain loops (no iterator adaptors) so that they are compiled for the
                // caller's CPU features.
                buf.resize(bw, [0.0; 4]);
                match hists {
                    [h] => {
                        for (d, &b) in buf.iter_mut().zip(at(h)) {
                            *d = scale(b);
                        }
                    }
                    [h0, h1] => {
                        for ((d, b), o) in buf.iter_mut().zip(at(h0)).zip(at(h1)) {
                            *d = scale(sum(b, o));
                        }
                    }
                    _ => {
                        buf.copy_from_slice(at(&hists[0]));
                        for h in &hists[1..] {
                            for (b, o) in buf.iter_mut().zip(at(h)) {
                                *b = sum(b, o);
                            }
                        }
                        for b in buf.iter_mut() {
                            *b = scale(*b);
                        }
                    }
                }
                buf
            }
        }
    }
}

/// Spatial filter (separable, downsampling by os) and tone mapping into the output image, or
/// `None` when `stop` is set before it is done (checked between bands).
fn filter_and_tonemap(
    flame: &Flame,
    geom: &Geometry,
    acc: &Rows,
    format: OutputFormat,
    out_rows: std::ops::Range<usize>,
    stop: &AtomicBool,
) -> Option<DynamicImage> {
    if stop.load(Ordering::Relaxed) {
        return None;
    }
    let (w, h) = (geom.width, out_rows.len());
    let channels = if format.transparent { 4 } else { 3 };
    let band = Band {
        geom,
        acc,
        tm: ToneMap::new(flame, format.transparent),
        channels,
        y_first: out_rows.start,
        h,
    };
    let row_len = w * channels;
    let (wu, hu) = (w as u32, h as u32);
    Some(if format.bits16 {
        let mut buf = vec![0u16; row_len * h];
        in_bands(&mut buf, row_len * BAND, |sc, b, chunk| {
            if !stop.load(Ordering::Relaxed) {
                band.encode(sc, b * BAND, Out::U16(chunk))
            }
        });
        if stop.load(Ordering::Relaxed) {
            return None;
        }
        if channels == 4 {
            DynamicImage::ImageRgba16(
                image::ImageBuffer::from_raw(wu, hu, buf).expect("buffer size"),
            )
        } else {
            DynamicImage::ImageRgb16(
                image::ImageBuffer::from_raw(wu, hu, buf).expect("buffer size"),
            )
        }
    } else {
        let mut buf = vec![0u8; row_len * h];
        in_bands(&mut buf, row_len * BAND, |sc, b, chunk| {
            if !stop.load(Ordering::Relaxed) {
                band.encode(sc, b * BAND, Out::U8(chunk))
            }
        });
        if stop.load(Ordering::Relaxed) {
            return None;
        }
        if channels == 4 {
            DynamicImage::ImageRgba8(
                image::ImageBuffer::from_raw(wu, hu, buf).expect("buffer size"),
            )
        } else {
            DynamicImage::ImageRgb8(image::ImageBuffer::from_raw(wu, hu, buf).expect("buffer size"))
        }
    })
}

/// Run `f(scratch, index, chunk)` over the chunks of `buf` in parallel, with one scratch per
/// worker (reused from band to band).
fn in_bands<T: Send>(
    buf: &mut [T],
    chunk: usize,
    f: impl Fn(&mut Scratch, usize, &mut [T]) + Sync,
) {
    buf.par_chunks_mut(chunk)
        .enumerate()
        .for_each_init(Scratch::default, |sc, (i, c)| f(sc, i, c));
}

/// Output rows filtered and tone-mapped together (bounded scratch memory per band).
const BAND: usize = 16;

/// Where a band's output values go.
enum Out<'a> {
    U8(&'a mut [u8]),
    U16(&'a mut [u16]),
}

/// Rows a band works in, kept from band to band (every value is written before it is read).
#[derive(Default)]
struct Scratch {
    /// Horizontally filtered bucket rows.
    tmp: Vec<[f64; 4]>,
    /// A bucket row computed on the fly.
    row: Vec<Bucket>,
    /// One output row, filtered.
    line: Vec<[f64; 4]>,
    alphas: Vec<f64>,
    /// The row tone-mapped: output values and alpha.
    toned: Vec<[f64; 4]>,
}

/// What every band of [`filter_and_tonemap`] shares.
struct Band<'a> {
    geom: &'a Geometry,
    acc: &'a Rows<'a>,
    tm: ToneMap,
    channels: usize,
    /// First output row of the image (of the whole picture's rows).
    y_first: usize,
    /// Output rows.
    h: usize,
}

impl Band<'_> {
    /// Filter and tone-map the output rows `y0..y0 + BAND` into `out`.
    fn encode(&self, sc: &mut Scratch, y0: usize, out: Out) {
        #[cfg(target_arch = "x86_64")]
        if crate::flame::fastmath::has_avx2_fma() {
            // SAFETY: the CPU has just reported AVX2 and FMA.
            return unsafe { self.encode_avx2(sc, y0, out) };
        }
        self.encode_generic(sc, y0, out)
    }

    /// [`Band::encode`] for CPUs with AVX2 and FMA (the compiler contracts nothing into FMA, so
    /// the values are the same as the generic copy's).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn encode_avx2(&self, sc: &mut Scratch, y0: usize, out: Out) {
        self.encode_generic(sc, y0, out)
    }

    #[inline(always)]
    fn encode_generic(&self, sc: &mut Scratch, y0: usize, mut out: Out) {
        let geom = self.geom;
        let (w, os, bw, delta) = (geom.width, geom.os, geom.bw, geom.delta);
        let taps = &geom.filter.taps;
        let fw = geom.filter.width;
        let channels = self.channels;
        let row_len = w * channels;
        let rows = BAND.min(self.h - y0);
        // Horizontally filtered acc rows needed by this band (rows of `acc`, which starts at
        // row `geom.row0` of the whole grid).
        let r0 = (self.y_first + y0) * os + delta - geom.row0;
        let nr = (rows - 1) * os + fw;
        // Loops run along a row (tap by tap) so that they vectorise; each sum still adds its
        // terms in tap order, starting from 0 as a plain dot product would.
        // (Plain loops, no iterator adaptors: they are compiled for the caller's CPU features.)
        let Scratch {
            tmp,
            row,
            line,
            alphas,
            toned,
        } = sc;
        tmp.resize(nr * w, [0.0; 4]);
        line.resize(w, [0.0; 4]);
        alphas.resize(w, 0.0);
        toned.resize(w, [0.0; 4]);
        let t0 = taps[0];
        let first = |b: &Bucket| {
            [
                0.0 + t0 * b[0] as f64,
                0.0 + t0 * b[1] as f64,
                0.0 + t0 * b[2] as f64,
                0.0 + t0 * b[3] as f64,
            ]
        };
        for (r, dst) in tmp[..nr * w].chunks_exact_mut(w).enumerate() {
            let src = self.acc.row(r0 + r, bw, row);
            if os == 1 {
                for (d, b) in dst.iter_mut().zip(&src[delta..delta + w]) {
                    *d = first(b);
                }
            } else {
                for (x, d) in dst.iter_mut().enumerate() {
                    *d = first(&src[x * os + delta]);
                }
            }
            for (i, &t) in taps.iter().enumerate().skip(1) {
                let add = |d: &mut [f64; 4], b: &Bucket| {
                    d[0] += t * b[0] as f64;
                    d[1] += t * b[1] as f64;
                    d[2] += t * b[2] as f64;
                    d[3] += t * b[3] as f64;
                };
                if os == 1 {
                    for (d, b) in dst.iter_mut().zip(&src[delta + i..delta + i + w]) {
                        add(d, b);
                    }
                } else {
                    for (x, d) in dst.iter_mut().enumerate() {
                        add(d, &src[x * os + delta + i]);
                    }
                }
            }
        }
        for yy in 0..rows {
            let tmp_row = |j: usize| &tmp[(yy * os + j) * w..(yy * os + j + 1) * w];
            for (d, b) in line.iter_mut().zip(tmp_row(0)) {
                *d = [
                    0.0 + t0 * b[0],
                    0.0 + t0 * b[1],
                    0.0 + t0 * b[2],
                    0.0 + t0 * b[3],
                ];
            }
            for (j, &t) in taps.iter().enumerate().skip(1) {
                for (d, b) in line.iter_mut().zip(tmp_row(j)) {
                    d[0] += t * b[0];
                    d[1] += t * b[1];
                    d[2] += t * b[2];
                    d[3] += t * b[3];
                }
            }
            for (al, s) in alphas.iter_mut().zip(line.iter()) {
                *al = self.tm.alpha(s[3]);
            }
            self.tm.row(line, alphas, toned);
            let o = yy * row_len;
            match &mut out {
                Out::U8(buf) => {
                    let dst = buf[o..o + row_len].chunks_exact_mut(channels);
                    for (px, t) in dst.zip(toned.iter()) {
                        px[0] = t[0] as u8;
                        px[1] = t[1] as u8;
                        px[2] = t[2] as u8;
                        if channels == 4 {
                            px[3] = (255.0 * t[3]) as u8;
                        }
                    }
                }
                Out::U16(buf) => {
                    let dst = buf[o..o + row_len].chunks_exact_mut(channels);
                    for (px, t) in dst.zip(toned.iter()) {
                        px[0] = (256.0 * t[0]) as u16;
                        px[1] = (256.0 * t[1]) as u16;
                        px[2] = (256.0 * t[2]) as u16;
                        if channels == 4 {
                            px[3] = (65535.0 * t[3]) as u16;
                        }
                    }
                }
            }
        }
    }
}

/// Render a flame to the end in one call.
pub fn render(flame: &Flame, opts: &RenderOptions) -> Result<DynamicImage, RenderError> {
    let mut r = Renderer::new(flame, opts)?;
    let never = AtomicBool::new(false);
    r.run_all(1, &never, |_| {});
    Ok(r.finish())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gradient::Gradient;

    /// An 8-bit palette adds whole palette units, so the colour sums of a render are whole
    /// numbers (exact, whatever the order of the adds) — what makes saved states small.
    #[test]
    fn an_8_bit_palette_accumulates_whole_colour_sums() {
        let flame = Flame {
            palette: Gradient::grey_ramp(),
            ..crate::flame::model::test_sierpinski(64, 48, 20.0)
        };
        let opts = RenderOptions {
            threads: 2,
            ..RenderOptions::default()
        };
        let mut r = Renderer::new(&flame, &opts).unwrap();
        assert!(r.run_all(1, &AtomicBool::new(false), |_| {}));
        let (_, hist) = r.into_state().unwrap();
        let mut hit = 0;
        for b in &hist.data {
            for v in &b[..3] {
                assert_eq!(v.fract(), 0.0, "{b:?}");
            }
            hit += (b[0] > 0.0) as usize;
        }
        assert!(hit > 100, "{hit} buckets with colour");
    }

    /// A render made from the memory of another (a different flame and size, its buckets and
    /// kept samples still full) is the render made from fresh memory, bit for bit — and it
    /// does reuse that memory when it fits.
    #[test]
    fn a_render_reusing_spare_memory_is_a_fresh_render() {
        let opts = RenderOptions {
            threads: 2,
            keep_samples: true,
            ..RenderOptions::default()
        };
        let never = AtomicBool::new(false);
        let flame = crate::flame::model::test_sierpinski(64, 48, 20.0);
        let fresh = {
            let mut r = Renderer::new(&flame, &opts).unwrap();
            assert!(r.run_all(3, &never, |_| {}));
            r.into_state().unwrap().1
        };
        for (w, h) in [(64, 48), (70, 50), (200, 150), (8, 6)] {
            let mut other = Renderer::new(
                &Flame {
                    palette: Gradient::grey_ramp(),
                    ..crate::flame::model::test_sierpinski(w, h, 30.0)
                },
                &opts,
            )
            .unwrap();
            assert!(other.run_all(2, &never, |_| {}));
            let mut spare = other.into_spare();
            let held: Vec<*const Bucket> = spare.hists.iter().map(|h| h.data.as_ptr()).collect();
            let mut r = Renderer::reusing(&flame, &opts, &mut spare).unwrap();
            let reused = r.hists.iter().any(|h| held.contains(&h.data.as_ptr()));
            // Buffers are taken when they hold the 64×48 grid without twice its size.
            assert_eq!(reused, (w, h) == (64, 48) || (w, h) == (70, 50), "{w}×{h}");
            assert!(r.logs.as_ref().unwrap().iter().all(|l| l.is_empty()));
            assert!(r.run_all(3, &never, |_| {}));
            let hist = r.into_state().unwrap().1;
            assert_eq!((hist.bw, hist.bh), (fresh.bw, fresh.bh));
            let bits = |h: &Histogram| -> Vec<u32> {
                h.data.iter().flatten().map(|v| v.to_bits()).collect()
            };
            assert!(bits(&hist) == bits(&fresh), "{w}×{h}: histograms differ");
        }
    }

    /// The block-wise palette lookup of `accumulate` adds what `PlotPalette::lookup` gives,
    /// bit for bit, at the edges too (NaN, negative, 1 and beyond), in both palette modes.
    #[test]
    fn accumulate_adds_the_entries_lookup_gives() {
        let edge = [
            f32::NAN,
            -1.0,
            -0.0,
            0.0,
            1e-9,
            0.5,
            0.999_999,
            1.0,
            1.5,
            f32::INFINITY,
        ];
        let buf: Vec<Pending> = (0..300u32)
            .map(|i| {
                let c = match edge.get(i as usize % 13) {
                    Some(&e) => e,
                    None => (i as f32 * 0.618_034).fract(),
                };
                (i % 7, c, 0.25 + (i % 3) as f32)
            })
            .collect();
        for (mode, index) in [PaletteMode::Step, PaletteMode::Linear]
            .into_iter()
            .flat_map(|m| crate::flame::PaletteIndex::ALL.map(|r| (m, r)))
        {
            let flame = Flame {
                palette: Gradient::grey_ramp(),
                palette_mode: mode,
                palette_index: index,
                ..Flame::default()
            };
            let pal = PlotPalette::new(&flame);
            let mut got = Histogram::new(7, 1);
            accumulate(&pal, &mut got, &buf);
            let mut want = Histogram::new(7, 1);
            for &(idx, c, v) in &buf {
                let p = pal.lookup(c as f64);
                for (w, p) in want.data[idx as usize].iter_mut().zip(p) {
                    *w += p * v;
                }
            }
            let bits = |h: &Histogram| -> Vec<u32> {
                h.data.iter().flatten().map(|v| v.to_bits()).collect()
            };
            assert_eq!(bits(&got), bits(&want), "{mode:?} {index:?}");
        }
    }
}
