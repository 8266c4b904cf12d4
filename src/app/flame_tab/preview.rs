//! The progressive live preview, rendered in the background: restarted within milliseconds by
//! new edits, refined in passes of doubling size, recoloured without iterating when only the
//! gradient changes.

use std::time::Instant;

use eframe::egui;

use crate::app::worker::{JobContext, Worker};
use crate::flame::Flame;
use crate::flame::render::{RenderOptions, Renderer, Spare};

/// Iteration time allowed for the first frame after an edit.
const FIRST_FRAME_BUDGET_S: f64 = 0.018;
/// The first frame has at least this many samples per pixel (a readable picture).
const MIN_FIRST_QUALITY: f64 = 1.0;

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
    /// Quality at which refinement stops.
    pub final_quality: f64,
    /// Worker threads (0: all cores).
    pub threads: usize,
    /// Number of the job: a frame carries it, so that frames of older jobs can be told apart.
    pub generation: u64,
}

/// One rendered preview frame.
#[derive(Clone)]
pub struct PreviewFrame {
    /// The job's number.
    pub generation: u64,
    /// The picture.
    pub image: egui::ColorImage,
    /// Fraction of the final quality done.
    pub fraction: f64,
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
    target_fraction: f64,
    /// Frames sent for this job.
    passes: u32,
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
            PreviewMsg::Recolor(job) => {
                let g = job.generation;
                let pool = &self.pool;
                let recoloured = match self.active.as_mut() {
                    Some(a) if a.job.generation == g => on_pool(pool, || {
                        a.renderer
                            .recolor(&job.flame.palette, job.flame.palette_mode)
                    }),
                    _ => false,
                };
                match self.active.as_mut() {
                    Some(a) if recoloured => {
                        a.job.flame.palette = job.flame.palette;
                        a.job.flame.palette_mode = job.flame.palette_mode;
                        cx.send(PreviewEvent::Frame(PreviewFrame {
                            generation: g,
                            image: to_color_image(&on_pool(pool, || a.renderer.preview())),
                            fraction: a.renderer.fraction(),
                            elapsed_ms: t.elapsed().as_secs_f64() * 1000.0,
                            done: a.renderer.is_done(),
                        }));
                        self.refine(cx);
                        return;
                    }
                    _ => job,
                }
            }
        };
        if self.start(job, t, cx) {
            self.refine(cx);
        }
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
        flame.resize_keep_framing(job.width.max(1), job.height.max(1));
        flame.quality = job.final_quality.max(job.first_quality).max(1e-3);
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
        let made = Renderer::reusing(&flame, &opts, &mut self.spare);
        self.spare = Spare::default();
        match made {
            Ok(r) => {
                let mut first = (job.first_quality / flame.quality).clamp(0.0, 1.0);
                // Keep the first frame within its time budget on this machine: fewer samples
                // for a costly flame (the next passes refine it).
                if let Some(rate) = self.rate {
                    let budget = rate * FIRST_FRAME_BUDGET_S / r.total_samples().max(1) as f64;
                    let floor = MIN_FIRST_QUALITY / flame.quality;
                    first = first.min(budget.max(floor));
                }
                self.active = Some(Active {
                    job,
                    renderer: r,
                    started: t,
                    target_fraction: first,
                    passes: 0,
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
            if a.renderer.is_done() || cx.is_stale() {
                return;
            }
            // One pass up to the target fraction, then double the target.
            let total = a.renderer.total_samples();
            let want = ((a.target_fraction * total as f64) as u64)
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
            let image = if first_pass || quick {
                on_pool(&self.pool, || a.renderer.preview_draft())
            } else {
                match on_pool(&self.pool, || a.renderer.preview_until(cancel)) {
                    Some(image) => image,
                    // A newer job waits: its frame, not this one, is wanted.
                    None => return,
                }
            };
            cx.send(PreviewEvent::Frame(PreviewFrame {
                generation: a.job.generation,
                image: to_color_image(&image),
                fraction: a.renderer.fraction(),
                elapsed_ms: a.started.elapsed().as_secs_f64() * 1000.0,
                done: a.renderer.is_done(),
            }));
            a.target_fraction = (a.target_fraction * 2.0).min(1.0);
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
            threads: 2,
            generation,
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
