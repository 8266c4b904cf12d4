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
//!
//! The renderer drives parts that live beside it: `settings` (options, errors, limits),
//! `budget` (the memory estimate and check), `plot` (samples into the histograms), `develop`
//! (histogram to image) and `strips` (renders larger than memory). Their public items are
//! re-exported here.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use image::DynamicImage;
use rayon::prelude::*;

use crate::flame::chaos::{Chaos, Lanes, SUB_BATCH};
use crate::flame::develop::{develop_draft, develop_rows_until};
use crate::flame::framing;
use crate::flame::geometry::Geometry;
use crate::flame::histogram::{Histogram, PlotPalette};
use crate::flame::ifs3d::Ifs3dSystem;
use crate::flame::jwf_render::solid_draw::{SolidPlane, draws_solid, iterate_solid};
use crate::flame::model::Flame;
use crate::flame::motion_blur::MotionFrame;
use crate::flame::plot::{Pending, accumulate, iterate_3d, iterate_into};
use crate::flame::rng::FastRng;
use crate::flame::sources::{SourceTools, Sources};
use crate::flame::state::{Part, RenderState};
use crate::flame::strips::Strip;
use crate::flame::tonemap::OutputFormat;

pub use crate::flame::budget::{
    MemoryEstimate, PNG_ENCODER_BYTES, SAVE_BUFFER_BYTES, SAVE_CHUNK_ROWS, available_memory,
    check_memory, estimate_memory, estimate_memory_rows, save_chunks_in_flight,
};
pub use crate::flame::develop::{develop, develop_rows};
pub use crate::flame::settings::{
    MAX_KEPT_SAMPLES, MAX_QUALITY, MAX_TOTAL_SAMPLES, MIN_QUALITY, RenderError, RenderOptions,
    geometry_of, quality_limit, quality_of_samples, short_num, validate_settings,
};
pub use crate::flame::strips::check_memory_rows;

/// How a render's work is cut: which share of the samples (for other processes or machines)
/// and which band of the image (for renders in strips).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Plan {
    /// The share of the samples this render iterates (the whole render by default).
    pub part: Part,
    /// Accumulate only this band; `None`: the whole image.
    pub strip: Option<Strip>,
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
    /// Each worker's own copy of the compiled flame, for a flame whose variations carry state
    /// from call to call ([`Chaos::has_variation_state`]); empty otherwise.
    thread_chaos: Vec<Chaos>,
    /// Each worker's orbits of each layer, for a flame of layers (a layer's orbits stay on its
    /// own attractor); empty otherwise.
    layer_lanes: Vec<Vec<Box<Lanes>>>,
    /// Each worker's plotted samples, when kept for recolouring.
    logs: Option<Vec<Vec<Pending>>>,
    seed: u64,
    format: OutputFormat,
    part: Part,
    /// Samples of the whole render (every part), counting `gap`: sub-batch g draws samples
    /// g·SUB_BATCH.. of it.
    total: u64,
    /// Samples of this part (without `gap`).
    part_total: u64,
    /// Samples in `total` that are never drawn: a render in one part that finished on a
    /// partial sub-batch and was then extended goes on with whole sub-batches after it.
    gap: u64,
    /// Sub-batches of this part; `next_batch` counts them too (local indices).
    batches_total: u64,
    next_batch: u64,
    samples_done: u64,
    badvals: u64,
    cancelled: bool,
    /// Set for a motion-blurred frame or a flame of layers: the sub-frames or layers its
    /// sub-batches draw from.
    motion: Option<Arc<Sources>>,
    /// Each worker's buckets of a flame JWildfire draws solid (all `None` otherwise).
    solid: Vec<Option<SolidPlane>>,
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
        let mut geom = geometry_of(&flame)?;
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
        let solid_on = draws_solid(&flame, &geom) && plan.strip.is_none() && ifs3d.is_none();
        let solid = (0..threads)
            .map(|_| solid_on.then(|| SolidPlane::new(geom.bw * geom.bh)))
            .collect();
        let total_samples = flame.total_samples();
        let logs = (opts.keep_samples && total_samples <= MAX_KEPT_SAMPLES && plan.strip.is_none())
            .then(|| (0..threads).map(|_| spare.log()).collect());
        let total = flame.total_samples().max(1);
        let part = plan.part;
        let layers = if flame.has_sources() {
            let l = flame.sources();
            for s in &l {
                Chaos::new(&s.flame)?;
            }
            Some(Sources::layers(&flame, l))
        } else {
            None
        };
        let thread_chaos = if chaos.has_variation_state() {
            (0..threads).map(|_| chaos.clone()).collect()
        } else {
            Vec::new()
        };
        let mut r = Renderer {
            palette: PlotPalette::new(&flame),
            chaos,
            ifs3d,
            geom,
            out_rows,
            hists,
            layer_lanes: (0..threads).map(|_| Vec::new()).collect(),
            thread_chaos,
            lanes,
            logs,
            seed: opts.seed,
            format: opts.format,
            part,
            total,
            part_total: part.samples(total),
            gap: 0,
            batches_total: part.local_batches(total.div_ceil(SUB_BATCH)),
            next_batch: 0,
            samples_done: 0,
            badvals: 0,
            cancelled: false,
            motion: None,
            solid,
            flame,
        };
        if let Some(l) = layers {
            let total = l.total().max(1);
            r.draw_from(l, total);
        }
        Ok(r)
    }

    /// Prepare a motion-blurred frame (see [`crate::flame::motion_blur::frame_at`]): every
    /// sub-frame's samples drawn from its own flame into one histogram, colours weighted by the
    /// temporal filter, developed with the frame's settings. A frame in which nothing moves is
    /// rendered as a still. Saved render states and recolouring are not available for moving
    /// frames.
    pub fn motion(frame: &MotionFrame, opts: &RenderOptions) -> Result<Renderer, RenderError> {
        Self::motion_with_plan(frame, opts, &Plan::default())
    }

    /// As [`Renderer::motion`] for one part of the samples and/or one strip of the image.
    pub fn motion_with_plan(
        frame: &MotionFrame,
        opts: &RenderOptions,
        plan: &Plan,
    ) -> Result<Renderer, RenderError> {
        if frame.is_still() {
            return Self::with_plan(&frame.develop, opts, plan);
        }
        // Every sub-frame must be a flame the chaos game can run.
        let checked: Result<Vec<()>, RenderError> = frame
            .subframes
            .par_iter()
            .map(|s| {
                validate_settings(&s.flame)?;
                Chaos::new(&s.flame)?;
                Ok(())
            })
            .collect();
        checked?;
        let mut r = Self::build(&frame.develop, opts, plan, &mut Spare::default())?;
        r.draw_from(Sources::motion(frame), frame.total_samples().max(1));
        Ok(r)
    }

    /// Draw the samples from `sources` (`total` samples in all) instead of the flame.
    fn draw_from(&mut self, sources: Sources, total: u64) {
        self.total = total;
        self.part_total = self.part.samples(total);
        self.batches_total = self.part.local_batches(sources.batches.len() as u64);
        self.logs = None;
        let n = if sources.layers {
            sources.flames.len()
        } else {
            0
        };
        if self.layer_lanes.first().is_none_or(|l| l.len() != n) {
            self.layer_lanes = (0..self.lanes.len())
                .map(|_| (0..n).map(|_| Lanes::new()).collect())
                .collect();
        }
        self.motion = Some(Arc::new(sources));
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
        strip: Option<Strip>,
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
        strip: Option<Strip>,
        fill: impl FnOnce(&mut Histogram) -> Result<(), String>,
    ) -> Result<Renderer, RenderError> {
        let (part, next) = state.continuation().map_err(RenderError::Settings)?;
        let mut flame = state.flame.clone();
        flame.has_camera = true;
        let mut r = Self::with_plan(&flame, opts, &Plan { part, strip })?;
        fill(&mut r.hists[0]).map_err(RenderError::Saved)?;
        r.logs = None;
        if part.count == 1 && state.gap > 0 {
            // The render's range with the samples it skipped after a partial sub-batch: the
            // sub-batches go on where the saved render's would have.
            r.gap = state.gap;
            r.total = r.total.saturating_add(state.gap);
            r.part_total = part.samples(r.total) - r.gap.min(r.total);
            r.batches_total = part.local_batches(r.total.div_ceil(SUB_BATCH));
        }
        if part.count == 1 && state.is_finished() {
            // A finished render (perhaps extended before, with gaps after partial sub-batches)
            // goes on after its last sub-batch.
            r.batches_total = r.batches_total.max(next);
        }
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
        // The orbits the stateful variations of each worker's copy of the flame had reached.
        if state.var_states.len() == r.thread_chaos.len() {
            for (c, s) in r.thread_chaos.iter().zip(&state.var_states) {
                c.restore_variation_state(s);
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
        if let Some(m) = &self.motion {
            if !m.layers {
                return Err(RenderError::Settings(
                    "a motion-blurred frame cannot continue".into(),
                ));
            }
            // The layers' shares of the added samples follow the ones drawn so far.
            let mut add = self.flame.clone();
            add.quality = add_quality;
            let all = m.extended(Sources::layers(&add, add.sources()));
            self.flame.quality = f.quality;
            let total = all.total().max(1);
            self.draw_from(all, total);
            self.batches_total = self.batches_total.max(self.next_batch);
            return Ok(());
        }
        let add = f.total_samples().saturating_sub(self.flame.total_samples());
        self.flame.quality = f.quality;
        self.logs = None;
        if self.part.count == 1 {
            // The added samples follow the ones drawn; a render that finished on a partial
            // sub-batch goes on with the next whole one (else the rest of that sub-batch's
            // range would never be drawn, and the extended render would fall short).
            let boundary = self.next_batch * SUB_BATCH;
            if self.next_batch >= self.batches_total && boundary > self.total {
                self.gap += boundary - self.total;
                self.total = boundary;
            }
            self.total = (self.total + add).max(1);
        } else {
            self.total = self.flame.total_samples().max(1);
        }
        self.part_total = self.part.samples(self.total) - self.gap.min(self.total);
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

    /// Samples iterated so far by this render (its part's share; with those of a continued
    /// saved state), bad ones included.
    pub fn samples_done(&self) -> u64 {
        self.samples_done
    }

    /// Samples so far that were bad values (flam3's term: a coordinate NaN, infinite or
    /// beyond 10¹⁰, a wider limit for flames with Fractorium's variations); each point was
    /// restarted at a random place of [−1, 1]².
    pub fn bad_values(&self) -> u64 {
        self.badvals
    }

    /// The quality the samples done so far amount to (the flame's quality once the render
    /// is complete; less while it runs or after a stop between passes).
    pub fn quality_done(&self) -> f64 {
        quality_of_samples(&self.flame, self.samples_done)
    }

    /// Worker threads, one histogram each: the image depends on this count.
    pub fn threads(&self) -> usize {
        self.hists.len()
    }

    /// The share of the whole render's samples this render iterates.
    pub fn part(&self) -> Part {
        self.part
    }

    /// Fraction of the samples done, in [0, 1].
    pub fn fraction(&self) -> f64 {
        (self.samples_done as f64 / self.total_samples() as f64).min(1.0)
    }

    /// True when every sub-batch of this part has been iterated, or the render was cancelled.
    pub fn is_done(&self) -> bool {
        self.cancelled || self.next_batch >= self.batches_total
    }

    /// True once a pass was cancelled: the render stops there and cannot continue.
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
        let motion = self.motion.as_deref();
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
            .zip(self.layer_lanes.par_iter_mut())
            .zip(self.solid.par_iter_mut())
            .zip(
                self.thread_chaos
                    .par_iter()
                    .map(Some)
                    .chain(rayon::iter::repeat_n(
                        None,
                        threads as usize - self.thread_chaos.len().min(threads as usize),
                    )),
            )
            .enumerate()
            .with_max_len(1)
            .map(
                |(t, (((((hist, lanes), log), layer_lanes), plane), own_chaos))| {
                    // This thread's copy, when the variations carry state.
                    let chaos = own_chaos.unwrap_or(chaos);
                    let mut done = 0u64;
                    let mut bad = 0u64;
                    // First batch index ≥ start that belongs to thread t.
                    let first = start + (t as u64 + threads - start % threads) % threads;
                    let mut j = first;
                    let mut buf = Vec::with_capacity(SUB_BATCH as usize);
                    // The source this thread drew its last sub-batch from (sub-frame or layer).
                    let mut tools: Option<SourceTools> = None;
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
                        let mut n = SUB_BATCH.min(total.saturating_sub(g * SUB_BATCH));
                        let (mut chaos, mut geom, mut pal) = (chaos, geom, pal);
                        let mut layer = None;
                        if let Some(m) = motion {
                            let (s, k) = m.batches[g as usize];
                            n = k as u64;
                            if tools.as_ref().is_none_or(|t| t.index != s) {
                                let t = SourceTools::new(m, s, geom);
                                if tools.as_ref().is_none_or(|o| o.n_xforms != t.n_xforms) {
                                    lanes.forget_last_xforms();
                                }
                                tools = Some(t);
                            }
                            let t = tools.as_ref().expect("just set");
                            (chaos, geom, pal) = (&t.chaos, &t.geom, &t.palette);
                            layer = Some(s as usize);
                        }
                        // A layer's own orbits, or the thread's.
                        let orbits: &mut Lanes = match layer.and_then(|s| layer_lanes.get_mut(s)) {
                            Some(l) => l,
                            None => lanes,
                        };
                        let mut rng = FastRng::for_stream(seed, g);
                        bad += match ifs3d {
                            None if plane.is_some() => match plane.as_mut() {
                                Some(p) => iterate_solid(chaos, geom, p, orbits, n, &mut rng),
                                None => 0,
                            },
                            None => {
                                let b = iterate_into(
                                    chaos, geom, pal, hist, &mut buf, orbits, n, &mut rng,
                                );
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
                },
            )
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
}

/// Render a flame to the end in one call.
pub fn render(flame: &Flame, opts: &RenderOptions) -> Result<DynamicImage, RenderError> {
    let mut r = Renderer::new(flame, opts)?;
    let never = AtomicBool::new(false);
    r.run_all(1, &never, |_| {});
    Ok(r.finish())
}

mod output;

#[cfg(test)]
mod tests;
