//! The progressive live preview, rendered in the background: restarted within milliseconds by
//! new edits, refined in passes of doubling size until the picture is clean (a noise target,
//! see `convergence.rs`, whatever quality the file asks for its export), recoloured without
//! iterating when only the gradient changes. When it is clean the worker waits: no CPU.

use std::time::Instant;

use eframe::egui;

use super::convergence;
use super::preview_motion::MotionJob;
use crate::app::worker::{JobContext, Worker};
use crate::flame::Flame;
use crate::flame::render::{RenderOptions, Renderer, Spare};

/// Iteration time allowed for the first frame after an edit.
const FIRST_FRAME_BUDGET_S: f64 = 0.018;
/// The first frame has at least this many samples per pixel (a readable picture).
const MIN_FIRST_QUALITY: f64 = 1.0;
/// Seconds of sampling a pass takes at most: later passes add this much, not twice the samples.
const PASS_S: f64 = 1.5;
/// Samples a pass adds at least.
const SUB_PASS_MIN: u64 = 100_000;
/// A refining preview keeps its samples for instant recolouring up to this quality; past it
/// the render grows without them (a recolour then starts it again).
const KEEP_QUALITY: f64 = 64.0;

/// A preview to render.
#[derive(Clone, Debug)]
pub struct PreviewJob {
    /// The flame to render.
    pub flame: Flame,
    /// Picture width in pixels.
    pub width: u32,
    /// Picture height in pixels.
    pub height: u32,
    /// Quality of the first pass (fast feedback).
    pub first_quality: f64,
    /// Quality at which refinement stops (with a noise target: the most it goes to).
    pub final_quality: f64,
    /// Refine until the estimated noise is at most this many 8-bit levels (root mean square
    /// over the flame's pixels); `None`: until `final_quality`.
    pub noise_target: Option<f64>,
    /// With a noise target: the quality it refines to at least (density estimation keeps
    /// sharpening a picture whose grain is gone).
    pub least_quality: f64,
    /// Worker threads (0: all cores).
    pub threads: usize,
    /// Number of the job: a frame carries it, so that frames of older jobs can be told apart.
    pub generation: u64,
    /// The frame is motion-blurred: drawn from the sub-frames of this animation's frame (the
    /// flame is then the frame at its instant, for the status and the background).
    pub motion: Option<MotionJob>,
}

/// One rendered preview frame.
#[derive(Clone)]
pub struct PreviewFrame {
    /// The job's number.
    pub generation: u64,
    /// The picture.
    pub image: egui::ColorImage,
    /// How far the job has got, in [0, 1]: the share of the final quality's samples done, or
    /// with a noise target the share of the samples a clean picture needs (estimated).
    pub fraction: f64,
    /// Samples per pixel the picture shows.
    pub quality: f64,
    /// The estimated noise of the picture (8-bit levels), once two refined pictures exist.
    pub noise: Option<f64>,
    /// Milliseconds since the job was submitted.
    pub elapsed_ms: f64,
    /// The final quality is reached.
    pub done: bool,
}

/// Worker output.
pub enum PreviewEvent {
    /// A picture, better than the last one of its job.
    Frame(PreviewFrame),
    /// The job could not be rendered.
    Error {
        /// The job's number.
        generation: u64,
        /// Why.
        message: String,
    },
}

/// What the preview worker is asked to do.
pub enum PreviewMsg {
    /// Render this job from scratch.
    Render(PreviewJob),
    /// The same job with another gradient: recolour the kept samples when they belong to this
    /// generation, otherwise render from scratch.
    Recolor(PreviewJob),
}

/// Convert a rendered image to an egui image.
pub fn to_color_image(img: &image::DynamicImage) -> egui::ColorImage {
    if let image::DynamicImage::ImageRgb8(rgb) = img {
        // The previews' usual format: one pass, no RGBA copy.
        return egui::ColorImage::from_rgb(
            [rgb.width() as usize, rgb.height() as usize],
            rgb.as_raw(),
        );
    }
    let rgba = img.to_rgba8();
    egui::ColorImage::from_rgba_unmultiplied(
        [rgba.width() as usize, rgba.height() as usize],
        rgba.as_raw(),
    )
}

/// Run `f` on the preview's own threads, or on the global pool when it has none.
fn on_pool<R: Send>(pool: &Option<(usize, rayon::ThreadPool)>, f: impl FnOnce() -> R + Send) -> R {
    match pool {
        Some((_, p)) => p.install(f),
        None => f(),
    }
}

/// The live preview renderer: a background worker whose newest job wins.
pub struct PreviewWorker {
    worker: Worker<PreviewMsg, PreviewEvent>,
}

impl PreviewWorker {
    /// Start the worker; `repaint` is called whenever a frame is ready.
    pub fn new(repaint: impl Fn() + Send + 'static) -> PreviewWorker {
        let mut state = State::default();
        PreviewWorker {
            worker: Worker::new("ugnis-preview", repaint, move |m, cx| state.run(m, cx)),
        }
    }

    /// Replace whatever is rendering by this job (the running pass stops within about a
    /// millisecond).
    pub fn submit(&self, job: PreviewJob) {
        self.worker.submit(PreviewMsg::Render(job));
    }

    /// The current job with another gradient: recoloured without iterating again when its
    /// samples are kept (the running pass finishes first).
    pub fn recolor(&self, job: PreviewJob) {
        self.worker.queue(PreviewMsg::Recolor(job));
    }

    /// All events ready now.
    pub fn poll(&self) -> Vec<PreviewEvent> {
        self.worker.poll()
    }

    /// Block until the next event (tests, benchmarks).
    pub fn wait(&self, timeout: std::time::Duration) -> Option<PreviewEvent> {
        self.worker.wait(timeout)
    }
}

struct Active {
    job: PreviewJob,
    renderer: Renderer,
    started: Instant,
    /// Samples the next pass brings the render to.
    target_samples: u64,
    /// Frames sent for this job.
    passes: u32,
    /// With one thread: the refined picture (RGB8) the next measurement compares with, and
    /// its samples.
    last: Option<(Vec<u8>, u64)>,
    /// The last measurement of the noise: at which quality, how much.
    measured: Option<(f64, f64)>,
    /// The estimated noise of the last picture.
    noise: Option<f64>,
    /// The progress shown last (it never goes back).
    shown_fraction: f64,
    /// Nothing more to do: the final quality or the noise target is reached.
    done: bool,
}

impl Active {
    /// The frame of `image` as it stands.
    fn frame(&self, image: egui::ColorImage) -> PreviewFrame {
        PreviewFrame {
            generation: self.job.generation,
            image,
            fraction: self.shown_fraction,
            quality: self.quality_done(),
            noise: self.noise,
            elapsed_ms: self.started.elapsed().as_secs_f64() * 1000.0,
            done: self.done,
        }
    }

    /// Samples per pixel done.
    fn quality_done(&self) -> f64 {
        let f = self.renderer.flame();
        let px = f.width as f64 * f.height as f64 * 4f64.powf(f.zoom);
        self.renderer.samples_done() as f64 / px.max(1.0)
    }

    /// Measure the noise of the refined picture `image` when it is due (see
    /// `convergence.rs`): from a quarter of the least quality on, at every doubling of the
    /// samples, and whenever the square-root law says the target may be met. False when
    /// `stop` was set meanwhile.
    fn measure_noise(
        &mut self,
        image: &image::DynamicImage,
        pool: &Option<(usize, rayon::ThreadPool)>,
        stop: &std::sync::atomic::AtomicBool,
    ) -> bool {
        let (q, least) = (self.quality_done(), self.job.least_quality);
        let target = self.job.noise_target.unwrap_or(0.0);
        if q < least / 4.0 {
            return true;
        }
        let bg = self.job.flame.background.map(|v| (v * 255.0).round() as u8);
        let r = &self.renderer;
        if r.threads() < 2 {
            let n = r.samples_done();
            if self.last.as_ref().is_some_and(|(_, n0)| n < 2 * n0) {
                return true;
            }
            let now = image.to_rgb8().into_raw();
            if let Some((before, n0)) = &self.last
                && let Some(e) = convergence::noise_between(before, &now, *n0, n, bg)
            {
                self.noise = Some(e);
                self.measured = Some((q, e));
            }
            self.last = Some((now, n));
            return true;
        }
        let due = match self.measured {
            None => true,
            Some((q0, e0)) => q >= 2.0 * q0 || (q >= least && e0 * (q0 / q).sqrt() <= target),
        };
        if !due {
            return true;
        }
        let Some([(a, sa), (b, sb)]) = on_pool(pool, || r.preview_halves(stop)) else {
            return false;
        };
        let (a, b) = (a.to_rgb8(), b.to_rgb8());
        if let Some(e) = convergence::noise_of_halves(a.as_raw(), b.as_raw(), [sa, sb], bg) {
            self.noise = Some(e);
            self.measured = Some((q, e));
        }
        true
    }

    /// Progress and done after a pass.
    fn after_pass(&mut self) {
        // Nothing more to add: the final quality (or the engine's limit) is reached.
        let at_cap = self.renderer.is_done() && !self.can_grow();
        let fraction = match self.job.noise_target {
            Some(t) => {
                let q = self.quality_done();
                let least = self.job.least_quality.min(self.job.final_quality);
                let clean = q >= least && self.noise.is_some_and(|e| e <= t);
                self.done = clean || at_cap;
                let needed =
                    convergence::quality_needed(least, self.job.final_quality, self.measured, t);
                (q / needed.max(1e-9)).clamp(0.0, 1.0)
            }
            None => {
                self.done = self.renderer.is_done();
                self.renderer.fraction()
            }
        };
        self.shown_fraction = if self.done {
            1.0
        } else {
            fraction.max(self.shown_fraction)
        };
    }

    /// Can the render take more samples (a job with a noise target below its final quality
    /// and the engine's limit)?
    fn can_grow(&self) -> bool {
        let f = self.renderer.flame();
        self.job.noise_target.is_some()
            && f.quality < self.job.final_quality
            && f.quality < crate::flame::render::quality_limit(f)
    }

    /// Grow the render when the next pass wants more samples than it holds (a job with a noise
    /// target starts small and grows up to its final quality).
    fn grow_to_target(&mut self) {
        let total = self.renderer.total_samples();
        if self.job.noise_target.is_none() || self.target_samples <= total {
            return;
        }
        let q = self.renderer.flame().quality;
        let want = (q * self.target_samples as f64 / total as f64).min(self.job.final_quality);
        if want > q {
            // Refused only past the engine's limits: the render then ends where it is.
            let _ = self.renderer.extend(want - q);
        }
    }
}

/// What the worker keeps between jobs.
#[derive(Default)]
struct State {
    /// The job being refined (kept when finished, for recolouring).
    active: Option<Active>,
    /// Samples per second of the latest passes (exponential average).
    rate: Option<f64>,
    /// The preview's own threads (and their count): an export or a batch keeping the global
    /// pool busy must not hold back the editor's frames.
    pool: Option<(usize, rayon::ThreadPool)>,
    /// Memory of a cancelled job, for the next one.
    spare: Spare,
}

impl State {
    fn run(&mut self, msg: PreviewMsg, cx: &JobContext<PreviewEvent>) {
        let threads = match &msg {
            PreviewMsg::Render(j) | PreviewMsg::Recolor(j) => j.threads,
        }
        .clamp(1, crate::threads::max_threads());
        if self.pool.as_ref().is_none_or(|(n, _)| *n != threads) {
            self.pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .thread_name(|i| format!("ugnis-preview-{i}"))
                .build()
                .ok()
                .map(|p| (threads, p));
        }
        let t = Instant::now();
        let job = match msg {
            PreviewMsg::Render(job) => job,
            PreviewMsg::Recolor(job) => match self.recolor(job, cx) {
                None => {
                    self.refine(cx);
                    return;
                }
                Some(job) => job,
            },
        };
        if self.start(job, t, cx) {
            self.refine(cx);
        }
    }

    /// Recolour the active job's kept samples with `job`'s palette and send the frame; the job
    /// back when that cannot be done (it is then rendered from scratch).
    fn recolor(&mut self, job: PreviewJob, cx: &JobContext<PreviewEvent>) -> Option<PreviewJob> {
        let pool = &self.pool;
        let Some(a) = self
            .active
            .as_mut()
            .filter(|a| a.job.generation == job.generation)
        else {
            return Some(job);
        };
        let palette = (&job.flame.palette, job.flame.palette_mode);
        if !on_pool(pool, || a.renderer.recolor(palette.0, palette.1)) {
            return Some(job);
        }
        a.job.flame.palette = job.flame.palette;
        a.job.flame.palette_mode = job.flame.palette_mode;
        // The earlier pictures had other colours: the next one is compared with this one (the
        // noise, a matter of samples, stays as it was).
        a.started = Instant::now();
        let refined = a.passes > 1;
        let image = on_pool(pool, || {
            if refined {
                a.renderer.preview()
            } else {
                a.renderer.preview_draft()
            }
        });
        if refined && a.last.is_some() {
            // One thread: the comparisons go on from the picture in its new colours.
            a.last = Some((image.to_rgb8().into_raw(), a.renderer.samples_done()));
        }
        a.after_pass();
        cx.send(PreviewEvent::Frame(a.frame(to_color_image(&image))));
        None
    }

    /// Drop the active job, keeping its memory for the next one.
    fn retire_active(&mut self) {
        if let Some(a) = self.active.take() {
            self.spare = a.renderer.into_spare();
        }
    }

    /// Set up the renderer of a new job; false (and an error event) when it cannot render.
    fn start(&mut self, job: PreviewJob, t: Instant, cx: &JobContext<PreviewEvent>) -> bool {
        let mut flame = job.flame.clone();
        let (w, h) = (job.width.max(1), job.height.max(1));
        flame.resize_keep_framing(w, h);
        let last = job.final_quality.max(job.first_quality).max(1e-3);
        let opts = RenderOptions {
            seed: 1,
            threads: job.threads,
            // Kept for instant recolouring, except for the one-pass frames of a drag.
            keep_samples: job.final_quality > job.first_quality,
            ..RenderOptions::default()
        };
        // The replaced render's memory is reused (a new job is never recoloured with the old
        // samples); what the new one does not take is freed.
        self.retire_active();
        // A motion-blurred frame cannot grow: it holds the samples of its final quality from
        // the start (the passes still stop at the noise target).
        let blurred = job
            .motion
            .as_ref()
            .and_then(|m| m.renderer(w, h, last, &opts));
        // A job with a noise target starts at the quality whose samples are kept and grows.
        flame.quality = match job.noise_target {
            Some(_) if blurred.is_none() => last.min(KEEP_QUALITY.max(job.first_quality)),
            _ => last,
        };
        let made = match blurred {
            Some(made) => made,
            None => Renderer::reusing(&flame, &opts, &mut self.spare),
        };
        self.spare = Spare::default();
        match made {
            Ok(r) => {
                let mut first_flame = flame.clone();
                first_flame.quality = job.first_quality.min(flame.quality).max(1e-3);
                let mut first = first_flame.total_samples();
                // Keep the first frame within its time budget on this machine: fewer samples
                // for a costly flame (the next passes refine it).
                if let Some(rate) = self.rate {
                    first_flame.quality = MIN_FIRST_QUALITY;
                    let floor = first_flame.total_samples();
                    let budget = (rate * FIRST_FRAME_BUDGET_S) as u64;
                    first = first.min(budget.max(floor));
                }
                self.active = Some(Active {
                    job,
                    renderer: r,
                    started: t,
                    target_samples: first.max(1),
                    passes: 0,
                    last: None,
                    measured: None,
                    noise: None,
                    shown_fraction: 0.0,
                    done: false,
                });
                true
            }
            Err(e) => {
                self.active = None;
                cx.send(PreviewEvent::Error {
                    generation: job.generation,
                    message: e.to_string(),
                });
                false
            }
        }
    }

    /// Passes of doubling size until the job is done or a newer job waits.
    fn refine(&mut self, cx: &JobContext<PreviewEvent>) {
        loop {
            let Some(a) = self.active.as_mut() else {
                return;
            };
            if a.done || cx.is_stale() {
                return;
            }
            a.grow_to_target();
            if a.renderer.is_done() {
                // Nothing left to add (the engine's limits): this picture is the last.
                a.done = true;
                return;
            }
            // One pass up to the target, then double the target.
            let want = a
                .target_samples
                .saturating_sub(a.renderer.samples_done())
                .max(1);
            let t_pass = Instant::now();
            let before = a.renderer.samples_done();
            let cancel = cx.cancel_flag();
            if !on_pool(&self.pool, || a.renderer.run(want, cancel)) {
                // Cancelled by a newer job in the middle of a pass.
                self.retire_active();
                return;
            }
            let (n, secs) = (
                a.renderer.samples_done() - before,
                t_pass.elapsed().as_secs_f64(),
            );
            if n >= 50_000 && secs > 0.0 {
                let r = n as f64 / secs;
                self.rate = Some(self.rate.map_or(r, |old| 0.5 * old + 0.5 * r));
            }
            // The first frame of an edit, and every frame of a drag (one pass at preview
            // quality), skips density estimation so that it arrives within tens of
            // milliseconds.
            let first_pass = a.passes == 0;
            a.passes += 1;
            let quick = a.job.final_quality <= a.job.first_quality;
            let (image, refined) = if first_pass || quick {
                (on_pool(&self.pool, || a.renderer.preview_draft()), false)
            } else {
                match on_pool(&self.pool, || a.renderer.preview_until(cancel)) {
                    Some(image) => (image, true),
                    // A newer job waits: its frame, not this one, is wanted.
                    None => return,
                }
            };
            if refined
                && a.job.noise_target.is_some()
                && !a.measure_noise(&image, &self.pool, cancel)
            {
                // A newer job waits.
                return;
            }
            a.after_pass();
            cx.send(PreviewEvent::Frame(a.frame(to_color_image(&image))));
            // Twice the samples, or at most about PASS_S more seconds of them: a frame at
            // least that often.
            let most = self
                .rate
                .map_or(u64::MAX, |r| (r * PASS_S) as u64)
                .max(SUB_PASS_MIN);
            a.target_samples = a.target_samples.saturating_add(a.target_samples.min(most));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::PaletteMode;
    use std::time::Duration;

    fn flame() -> Flame {
        let mut f = crate::io::read_flames(
            std::path::Path::new(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/examples/orchid.flame"
            )),
            &Default::default(),
        )
        .unwrap()
        .value
        .remove(0);
        f.quality = 20.0;
        f
    }

    fn job(generation: u64) -> PreviewJob {
        PreviewJob {
            flame: flame(),
            width: 160,
            height: 120,
            first_quality: 1.0,
            final_quality: 8.0,
            noise_target: None,
            least_quality: 0.0,
            threads: 2,
            generation,
            motion: None,
        }
    }

    #[test]
    fn progressive_frames_then_done_and_restart() {
        let w = PreviewWorker::new(|| {});
        w.submit(job(1));
        let mut frames = Vec::new();
        while let Some(PreviewEvent::Frame(f)) = w.wait(Duration::from_secs(20)) {
            let done = f.done;
            frames.push(f);
            if done {
                break;
            }
        }
        assert!(frames.len() >= 3, "{}", frames.len());
        assert!(frames.windows(2).all(|p| p[1].fraction > p[0].fraction));
        assert_eq!(frames[0].image.size, [160, 120]);
        // A new job replaces the old one; recolouring the finished job sends a new frame.
        w.submit(job(2));
        let mut last = None;
        while let Some(PreviewEvent::Frame(f)) = w.wait(Duration::from_secs(20)) {
            assert_eq!(f.generation, 2);
            if f.done {
                last = Some(f);
                break;
            }
        }
        let before = last.unwrap().image;
        let mut j = job(2);
        j.flame.palette = crate::gradient::builtin_named("ice").unwrap();
        j.flame.palette_mode = PaletteMode::Step;
        w.recolor(j);
        match w.wait(Duration::from_secs(20)) {
            Some(PreviewEvent::Frame(f)) => {
                assert_eq!(f.generation, 2);
                assert_ne!(f.image.pixels, before.pixels);
                // Recoloured from the kept samples: complete at once, not a first pass.
                assert!(f.done);
            }
            _ => panic!("no recoloured frame"),
        }
    }

    /// Frames of a job until it is done.
    fn until_done(w: &PreviewWorker) -> Vec<PreviewFrame> {
        let mut frames = Vec::new();
        while let Some(PreviewEvent::Frame(f)) = w.wait(Duration::from_secs(60)) {
            let done = f.done;
            frames.push(f);
            if done {
                return frames;
            }
        }
        panic!("no end after {} frames", frames.len());
    }

    #[test]
    fn a_noise_target_refines_past_the_files_quality_then_stops() {
        let w = PreviewWorker::new(|| {});
        let mut j = job(1);
        // The file asks for quality 1: the preview does not stop there.
        j.flame.quality = 1.0;
        j.final_quality = 400.0;
        j.least_quality = 30.0;
        j.noise_target = Some(3.0);
        w.submit(j.clone());
        let frames = until_done(&w);
        let last = frames.last().unwrap();
        assert!(last.quality >= 30.0, "{}", last.quality);
        assert!(
            last.noise.is_some_and(|n| n <= 3.0) || last.quality >= 399.0,
            "{:?} at {}",
            last.noise,
            last.quality
        );
        assert!(frames.windows(2).all(|p| p[1].quality > p[0].quality));
        assert!(frames.windows(2).all(|p| p[1].fraction >= p[0].fraction));
        assert_eq!(last.fraction, 1.0);
        // Done means idle: nothing more comes.
        assert!(w.wait(Duration::from_millis(300)).is_none());
        // An unreachable target stops at the most quality.
        let mut k = j.clone();
        k.generation = 2;
        k.noise_target = Some(0.01);
        k.final_quality = 40.0;
        w.submit(k);
        let last = until_done(&w).pop().unwrap();
        assert!((last.quality - 40.0).abs() < 1.0, "{}", last.quality);
        assert!(last.noise.is_some_and(|n| n > 0.01));
    }

    #[test]
    fn errors_are_reported() {
        let w = PreviewWorker::new(|| {});
        let mut j = job(7);
        for x in &mut j.flame.xforms {
            x.weight = 0.0;
        }
        w.submit(j);
        match w.wait(Duration::from_secs(20)) {
            Some(PreviewEvent::Error {
                generation,
                message,
            }) => {
                assert_eq!(generation, 7);
                assert!(message.contains("empty flame"));
            }
            _ => panic!("expected an error"),
        }
    }
}
