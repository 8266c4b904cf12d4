//! Background rendering for the GUI: the progressive live preview (restarted within
//! milliseconds by new edits, recoloured without iterating when only the gradient changes) and
//! thumbnails. The UI thread never renders.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, Sender, TryRecvError};
use std::thread::JoinHandle;
use std::time::Instant;

use eframe::egui;

use crate::flame::render::{RenderOptions, Renderer};
use crate::flame::{Flame, PaletteMode};
use crate::gradient::Gradient;

/// Iteration time allowed for the first frame after an edit.
const FIRST_FRAME_BUDGET_S: f64 = 0.022;
/// The first frame has at least this many samples per pixel (a readable picture).
const MIN_FIRST_QUALITY: f64 = 1.0;

/// A preview to render.
#[derive(Clone, Debug)]
pub struct PreviewJob {
    pub flame: Flame,
    pub width: u32,
    pub height: u32,
    /// Quality of the first pass (fast feedback).
    pub first_quality: f64,
    /// Quality at which refinement stops.
    pub final_quality: f64,
    pub threads: usize,
    pub generation: u64,
}

/// One rendered preview frame.
#[derive(Clone)]
pub struct PreviewFrame {
    pub generation: u64,
    pub image: egui::ColorImage,
    /// Fraction of the final quality done.
    pub fraction: f64,
    /// Milliseconds since the job was submitted.
    pub elapsed_ms: f64,
    pub done: bool,
}

enum Msg {
    Job(Box<PreviewJob>, Instant),
    Recolor(Gradient, PaletteMode, u64, Instant),
    Quit,
}

/// Worker output.
pub enum PreviewEvent {
    Frame(PreviewFrame),
    Error { generation: u64, message: String },
}

/// Convert a rendered image to an egui image.
pub fn to_color_image(img: &image::DynamicImage) -> egui::ColorImage {
    let rgba = img.to_rgba8();
    egui::ColorImage::from_rgba_unmultiplied(
        [rgba.width() as usize, rgba.height() as usize],
        rgba.as_raw(),
    )
}

/// The live preview renderer thread.
pub struct PreviewWorker {
    tx: Sender<Msg>,
    rx: Receiver<PreviewEvent>,
    cancel: Arc<AtomicBool>,
    handle: Option<JoinHandle<()>>,
}

impl PreviewWorker {
    /// Start the worker; `repaint` is called whenever a frame is ready.
    pub fn new(repaint: impl Fn() + Send + 'static) -> PreviewWorker {
        let (tx, jobs) = mpsc::channel::<Msg>();
        let (events, rx) = mpsc::channel::<PreviewEvent>();
        let cancel = Arc::new(AtomicBool::new(false));
        let c = cancel.clone();
        let handle = std::thread::Builder::new()
            .name("ugnis-preview".into())
            .spawn(move || worker(jobs, events, c, repaint))
            .expect("spawn preview thread");
        PreviewWorker {
            tx,
            rx,
            cancel,
            handle: Some(handle),
        }
    }

    /// Replace whatever is rendering by this job (the running pass stops within about a
    /// millisecond).
    pub fn submit(&self, job: PreviewJob) {
        self.cancel.store(true, Ordering::SeqCst);
        let _ = self.tx.send(Msg::Job(Box::new(job), Instant::now()));
    }

    /// Change the gradient of the current job without iterating again.
    pub fn recolor(&self, g: Gradient, mode: PaletteMode, generation: u64) {
        let _ = self
            .tx
            .send(Msg::Recolor(g, mode, generation, Instant::now()));
    }

    /// All events ready now.
    pub fn poll(&self) -> Vec<PreviewEvent> {
        self.rx.try_iter().collect()
    }

    /// Block until the next event (tests, benchmarks).
    pub fn wait(&self, timeout: std::time::Duration) -> Option<PreviewEvent> {
        self.rx.recv_timeout(timeout).ok()
    }
}

impl Drop for PreviewWorker {
    fn drop(&mut self) {
        self.cancel.store(true, Ordering::SeqCst);
        let _ = self.tx.send(Msg::Quit);
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
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

fn worker(
    jobs: Receiver<Msg>,
    events: Sender<PreviewEvent>,
    cancel: Arc<AtomicBool>,
    repaint: impl Fn(),
) {
    let mut active: Option<Active> = None;
    let mut finished = true;
    // Samples per second of the latest passes (exponential average).
    let mut rate: Option<f64> = None;
    loop {
        // Take the newest job; block only when idle.
        let mut msgs = Vec::new();
        if finished {
            match jobs.recv() {
                Ok(m) => msgs.push(m),
                Err(_) => return,
            }
        }
        loop {
            match jobs.try_recv() {
                Ok(m) => msgs.push(m),
                Err(TryRecvError::Empty) => break,
                Err(TryRecvError::Disconnected) => return,
            }
        }
        let mut new_job: Option<(Box<PreviewJob>, Instant)> = None;
        for m in msgs {
            match m {
                Msg::Quit => return,
                Msg::Job(j, t) => new_job = Some((j, t)),
                Msg::Recolor(g, mode, generation, t) => {
                    if new_job.is_none()
                        && let Some(a) = active.as_mut()
                        && a.job.generation == generation
                        && a.renderer.recolor(&g, mode)
                    {
                        a.job.flame.palette = g;
                        a.job.flame.palette_mode = mode;
                        let frame = PreviewFrame {
                            generation,
                            image: to_color_image(&a.renderer.preview()),
                            fraction: a.renderer.fraction(),
                            elapsed_ms: t.elapsed().as_secs_f64() * 1000.0,
                            done: finished,
                        };
                        let _ = events.send(PreviewEvent::Frame(frame));
                        repaint();
                    }
                }
            }
        }
        if let Some((job, t)) = new_job {
            cancel.store(false, Ordering::SeqCst);
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
            match Renderer::new(&flame, &opts) {
                Ok(r) => {
                    let mut first = (job.first_quality / flame.quality).clamp(0.0, 1.0);
                    // Keep the first frame within its time budget on this machine: fewer
                    // samples for a costly flame (the next passes refine it).
                    if let Some(rate) = rate {
                        let budget = rate * FIRST_FRAME_BUDGET_S / r.total_samples().max(1) as f64;
                        let floor = MIN_FIRST_QUALITY / flame.quality;
                        first = first.min(budget.max(floor));
                    }
                    active = Some(Active {
                        job: *job,
                        renderer: r,
                        started: t,
                        target_fraction: first,
                        passes: 0,
                    });
                    finished = false;
                }
                Err(e) => {
                    let _ = events.send(PreviewEvent::Error {
                        generation: job.generation,
                        message: e.to_string(),
                    });
                    repaint();
                    active = None;
                    finished = true;
                    continue;
                }
            }
        }
        let Some(a) = active.as_mut() else {
            finished = true;
            continue;
        };
        if finished {
            continue;
        }
        // One pass up to the target fraction, then double the target.
        let total = a.renderer.total_samples();
        let want = ((a.target_fraction * total as f64) as u64)
            .saturating_sub(a.renderer.samples_done())
            .max(1);
        let t_pass = Instant::now();
        let before = a.renderer.samples_done();
        let ok = a.renderer.run(want, &cancel);
        let (n, secs) = (
            a.renderer.samples_done() - before,
            t_pass.elapsed().as_secs_f64(),
        );
        if ok && n >= 50_000 && secs > 0.0 {
            let r = n as f64 / secs;
            rate = Some(rate.map_or(r, |old| 0.5 * old + 0.5 * r));
        }
        if !ok {
            // Cancelled by a newer job: it is already waiting in the channel.
            finished = false;
            active = None;
            continue;
        }
        let done = a.renderer.is_done();
        // The first frame of an edit, and every frame of a drag (one pass at preview quality),
        // skips density estimation so that it arrives within tens of milliseconds.
        let first_pass = a.passes == 0;
        a.passes += 1;
        let quick = a.job.final_quality <= a.job.first_quality;
        let image = if first_pass || quick {
            a.renderer.preview_draft()
        } else {
            a.renderer.preview()
        };
        let frame = PreviewFrame {
            generation: a.job.generation,
            image: to_color_image(&image),
            fraction: a.renderer.fraction(),
            elapsed_ms: a.started.elapsed().as_secs_f64() * 1000.0,
            done,
        };
        let _ = events.send(PreviewEvent::Frame(frame));
        repaint();
        a.target_fraction = (a.target_fraction * 2.0).min(1.0);
        finished = done;
    }
}

/// Renders small pictures of flames one after the other, in the background.
pub struct ThumbnailWorker {
    tx: Sender<Option<(u64, Flame)>>,
    rx: Receiver<(u64, Result<egui::ColorImage, String>)>,
    handle: Option<JoinHandle<()>>,
}

impl ThumbnailWorker {
    pub fn new(
        width: u32,
        height: u32,
        quality: f64,
        repaint: impl Fn() + Send + 'static,
    ) -> ThumbnailWorker {
        let (tx, jobs) = mpsc::channel::<Option<(u64, Flame)>>();
        let (out, rx) = mpsc::channel();
        let handle = std::thread::Builder::new()
            .name("ugnis-thumbnails".into())
            .spawn(move || {
                while let Ok(Some((key, mut f))) = jobs.recv() {
                    f.resize_keep_framing(width, height);
                    f.quality = quality;
                    let o = RenderOptions {
                        seed: 1,
                        threads: 1,
                        ..RenderOptions::default()
                    };
                    let r = crate::flame::render::render(&f, &o)
                        .map(|img| to_color_image(&img))
                        .map_err(|e| e.to_string());
                    if out.send((key, r)).is_err() {
                        return;
                    }
                    repaint();
                }
            })
            .expect("spawn thumbnail thread");
        ThumbnailWorker {
            tx,
            rx,
            handle: Some(handle),
        }
    }

    pub fn request(&self, key: u64, flame: Flame) {
        let _ = self.tx.send(Some((key, flame)));
    }

    pub fn poll(&self) -> Vec<(u64, Result<egui::ColorImage, String>)> {
        self.rx.try_iter().collect()
    }
}

impl Drop for ThumbnailWorker {
    fn drop(&mut self) {
        let _ = self.tx.send(None);
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
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
        w.recolor(
            crate::gradient::builtin_named("ice").unwrap(),
            PaletteMode::Step,
            2,
        );
        match w.wait(Duration::from_secs(20)) {
            Some(PreviewEvent::Frame(f)) => {
                assert_eq!(f.generation, 2);
                assert_ne!(f.image.pixels, before.pixels);
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

    #[test]
    fn thumbnails() {
        let t = ThumbnailWorker::new(32, 24, 5.0, || {});
        t.request(9, flame());
        let start = Instant::now();
        loop {
            let got = t.poll();
            if let Some((k, r)) = got.into_iter().next() {
                assert_eq!(k, 9);
                assert_eq!(r.unwrap().size, [32, 24]);
                break;
            }
            assert!(start.elapsed() < Duration::from_secs(20));
            std::thread::sleep(Duration::from_millis(5));
        }
    }
}
