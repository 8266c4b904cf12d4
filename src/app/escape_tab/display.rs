//! The escape-time renderer in the background: each job renders progressively (coarse to
//! fine) and every pass is sent as a frame; the newest view wins.

use std::time::Instant;

use eframe::egui::{self, Color32};

use crate::app::worker::{JobContext, Worker};
use crate::escape::{EscapeParams, EscapeRenderer, View};

/// A render request.
pub struct Job {
    params: EscapeParams,
    view: View,
    w: u32,
    h: u32,
    generation: u64,
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
    let mut r = match EscapeRenderer::new(&job.params, job.view, job.w, job.h) {
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
        }
    }

    pub fn request(&mut self, params: &EscapeParams, view: View, size: [u32; 2]) {
        let key = (params.clone(), view.clone(), size);
        if self.submitted.as_ref() != Some(&key) {
            self.generation += 1;
            self.worker.submit(Job {
                params: params.clone(),
                view,
                w: size[0],
                h: size[1],
                generation: self.generation,
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
