//! The escape-time renderer in the background: each job renders progressively (coarse to
//! fine) and every pass is sent as a frame; the newest view wins. A deep view first computes
//! its reference orbit, whose progress the tab shows and which Stop ends.

use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::Instant;

use eframe::egui::{self, Color32};

use crate::app::worker::{JobContext, Worker};
use crate::escape::{EscapeParams, EscapeRenderer, OrbitProgress, View};

/// A render request.
pub struct Job {
    params: EscapeParams,
    view: View,
    w: u32,
    h: u32,
    generation: u64,
    orbit: Arc<OrbitProgress>,
}

/// A frame from the worker.
pub struct EscapeFrame {
    pub generation: u64,
    pub image: egui::ColorImage,
    pub fraction: f64,
    pub elapsed_ms: f64,
    pub error: Option<String>,
}

fn color_image(img: &image::RgbImage) -> egui::ColorImage {
    egui::ColorImage::from_rgb([img.width() as usize, img.height() as usize], img.as_raw())
}

/// Render one job pass by pass until it is done or a newer job waits.
fn render(job: Job, cx: &JobContext<EscapeFrame>) {
    let t = Instant::now();
    let mut r = match EscapeRenderer::with_progress(&job.params, job.view, job.w, job.h, &job.orbit)
    {
        Ok(r) => r,
        Err(e) => {
            cx.send(EscapeFrame {
                generation: job.generation,
                image: egui::ColorImage::new([1, 1], vec![Color32::BLACK]),
                fraction: 0.0,
                elapsed_ms: 0.0,
                error: Some(e.to_string()),
            });
            return;
        }
    };
    while !r.is_done() && !cx.is_stale() {
        if !r.run_pass(cx.cancel_flag()) {
            return;
        }
        cx.send(EscapeFrame {
            generation: job.generation,
            image: color_image(&r.image()),
            fraction: r.fraction(),
            elapsed_ms: t.elapsed().as_secs_f64() * 1000.0,
            error: None,
        });
    }
}

/// A picture of the tab (the main view or the Julia preview): its worker and texture.
pub struct Display {
    worker: Worker<Job, EscapeFrame>,
    pub texture: Option<egui::TextureHandle>,
    generation: u64,
    shown: u64,
    submitted: Option<(EscapeParams, View, [u32; 2])>,
    /// The view of the texture on screen (to draw it shifted/zoomed until the new frame).
    pub shown_view: Option<View>,
    pub fraction: f64,
    pub elapsed_ms: f64,
    pub error: Option<String>,
    /// The reference orbit of the newest job (iterations done; its cancel flag stops it).
    orbit: Arc<OrbitProgress>,
    /// The newest frame, kept to tell whether the picture shows anything.
    pub last_image: Option<egui::ColorImage>,
    /// Stop was pressed for the newest job.
    stopped: bool,
}

impl Display {
    pub fn new(ctx: &egui::Context) -> Display {
        let c = ctx.clone();
        Display {
            worker: Worker::new("ugnis-escape", move || c.request_repaint(), render),
            texture: None,
            generation: 0,
            shown: 0,
            submitted: None,
            shown_view: None,
            fraction: 0.0,
            elapsed_ms: 0.0,
            error: None,
            orbit: Arc::default(),
            last_image: None,
            stopped: false,
        }
    }

    /// Whether the newest job is still running (no final frame yet).
    pub fn busy(&self) -> bool {
        self.submitted.is_some()
            && !self.stopped
            && self.error.is_none()
            && (self.shown != self.generation || self.fraction < 1.0)
    }

    /// While a deep view computes its reference orbit: the iterations done and the limit.
    pub fn orbit_progress(&self) -> Option<(u64, u64)> {
        let (params, _, _) = self.submitted.as_ref()?;
        let done = self.orbit.done.load(Ordering::Relaxed);
        (self.shown != self.generation && self.error.is_none() && !self.stopped && done > 0)
            .then_some((done, params.max_iter as u64))
    }

    /// Stop the running job (the reference orbit or the passes); the picture keeps what it
    /// has, and the same view is not started again until it changes.
    pub fn stop(&mut self) {
        self.orbit.cancel.store(true, Ordering::Relaxed);
        self.worker.cancel();
        self.stopped = true;
    }

    pub fn request(&mut self, params: &EscapeParams, view: View, size: [u32; 2]) {
        let key = (params.clone(), view.clone(), size);
        if self.submitted.as_ref() != Some(&key) {
            self.generation += 1;
            // The previous reference orbit is no longer wanted.
            self.orbit.cancel.store(true, Ordering::Relaxed);
            self.orbit = Arc::default();
            self.stopped = false;
            self.worker.submit(Job {
                params: params.clone(),
                view,
                w: size[0],
                h: size[1],
                generation: self.generation,
                orbit: self.orbit.clone(),
            });
            self.submitted = Some(key);
        }
    }

    pub fn poll(&mut self, ctx: &egui::Context, name: &str) {
        for f in self.worker.poll() {
            if f.generation != self.generation {
                continue;
            }
            self.error = f.error;
            if self.error.is_none() {
                self.last_image = Some(f.image.clone());
                match &mut self.texture {
                    Some(t) => t.set(f.image, egui::TextureOptions::NEAREST),
                    None => {
                        self.texture =
                            Some(ctx.load_texture(name, f.image, egui::TextureOptions::NEAREST))
                    }
                }
                self.shown = f.generation;
                self.shown_view = self.submitted.as_ref().map(|s| s.1.clone());
            }
            self.fraction = f.fraction;
            self.elapsed_ms = f.elapsed_ms;
        }
    }
}
