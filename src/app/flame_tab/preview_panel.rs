//! The central picture of the flame tab: the current flame (or morph frame) rendered by the
//! preview worker at the panel's size, quick while dragging or animating, refined when still.

use eframe::egui::{self, Vec2};

use super::FlameTab;
use super::preview::{PreviewEvent, PreviewJob, PreviewWorker};
use crate::app::a11y::named;
use crate::app::options::Options;
use crate::flame::Flame;
use crate::gradient::Gradient;

/// A change to the flame, made once the camera gesture is known.
type FlameEdit = Box<dyn FnOnce(&mut Flame)>;

/// The live preview: worker, texture and what was submitted.
pub struct Preview {
    worker: PreviewWorker,
    texture: Option<egui::TextureHandle>,
    /// Generation of the newest job.
    pub generation: u64,
    /// The flame, size and quality of the last job.
    submitted: Option<(Flame, [u32; 2], bool)>,
    fraction: f64,
    elapsed_ms: f64,
    error: Option<String>,
    /// Generation of the picture on screen.
    pub shown_generation: u64,
}

/// The flame without its palette, for "did only the gradient change?".
fn without_palette(f: &Flame) -> Flame {
    let mut g = f.clone();
    g.palette = Gradient::grey_ramp();
    g.palette_mode = crate::flame::PaletteMode::Step;
    g
}

impl Preview {
    pub fn new(ctx: &egui::Context) -> Preview {
        let c = ctx.clone();
        Preview {
            worker: PreviewWorker::new(move || c.request_repaint()),
            texture: None,
            generation: 0,
            submitted: None,
            fraction: 0.0,
            elapsed_ms: 0.0,
            error: None,
            shown_generation: 0,
        }
    }

    /// Render `f` at `px` unless that is what is on its way already.
    fn request(&mut self, f: &Flame, px: [u32; 2], quick: bool, job: impl Fn(u64) -> PreviewJob) {
        let need = match &self.submitted {
            Some((sf, size, q)) => sf != f || *size != px || *q != quick,
            None => true,
        };
        if !need {
            return;
        }
        let only_palette = match &self.submitted {
            Some((sf, size, q)) => {
                *size == px && *q == quick && without_palette(sf) == without_palette(f)
            }
            None => false,
        };
        if only_palette {
            self.worker.recolor(job(self.generation));
        } else {
            self.generation += 1;
            self.worker.submit(job(self.generation));
        }
        self.submitted = Some((f.clone(), px, quick));
    }

    /// Take the frames the worker finished.
    fn poll(&mut self, ctx: &egui::Context) {
        for ev in self.worker.poll() {
            match ev {
                PreviewEvent::Frame(fr) if fr.generation == self.generation => {
                    match &mut self.texture {
                        Some(t) => t.set(fr.image, egui::TextureOptions::LINEAR),
                        None => {
                            self.texture = Some(ctx.load_texture(
                                "preview",
                                fr.image,
                                egui::TextureOptions::LINEAR,
                            ))
                        }
                    }
                    self.fraction = fr.fraction;
                    self.elapsed_ms = fr.elapsed_ms;
                    self.error = None;
                    self.shown_generation = fr.generation;
                }
                PreviewEvent::Error {
                    generation,
                    message,
                } if generation == self.generation => {
                    self.error = Some(message);
                    self.shown_generation = generation;
                }
                _ => {}
            }
        }
    }

    /// The preview's part of the status bar.
    pub fn status(&self, ui: &mut egui::Ui) {
        if let Some(e) = &self.error {
            ui.colored_label(egui::Color32::from_rgb(230, 120, 90), e);
        } else {
            ui.label(format!(
                "preview {:>3.0}%  {:.0} ms",
                self.fraction * 100.0,
                self.elapsed_ms
            ));
        }
    }
}

impl FlameTab {
    pub(super) fn preview_panel(&mut self, ui: &mut egui::Ui, options: &Options, dragging: bool) {
        let avail = ui.available_size();
        let f = self.shown_flame();
        // The preview keeps the flame's aspect ratio and is at most preview_size pixels.
        let ppp = ui.ctx().pixels_per_point();
        let aspect = f.width as f32 / f.height.max(1) as f32;
        let (mut w, mut h) = (avail.x, avail.x / aspect);
        if h > avail.y {
            h = avail.y;
            w = h * aspect;
        }
        let cap = options.preview_size as f32 / ppp;
        if w.max(h) > cap {
            let k = cap / w.max(h);
            w *= k;
            h *= k;
        }
        let px = [(w * ppp).max(16.0) as u32, (h * ppp).max(12.0) as u32];
        let animating = self.animation.is_some() || self.morph.is_some() || self.timeline.playing();
        let dragging = dragging || self.camera_drag || self.timeline.scrubbing;
        if let Some(p) = &mut self.preview {
            let quick = dragging || animating;
            let first = options.preview_quality.min(f.quality);
            let final_q = if quick {
                if animating {
                    options.animation_quality
                } else {
                    options.preview_quality
                }
            } else {
                f.quality
            };
            let first_q = if animating {
                options.animation_quality
            } else {
                first
            };
            let threads = options.threads;
            p.request(&f, px, quick, |generation| PreviewJob {
                flame: f.clone(),
                width: px[0],
                height: px[1],
                first_quality: first_q,
                final_quality: final_q,
                threads,
                generation,
            });
            p.poll(ui.ctx());
        }
        let size = Vec2::new(w, h) * self.preview_zoom;
        let mut image = None;
        egui::ScrollArea::both()
            .scroll_source(egui::scroll_area::ScrollSource::SCROLL_BAR)
            .show(ui, |ui| {
                ui.centered_and_justified(|ui| {
                    let r = match self.preview.as_ref().and_then(|p| p.texture.as_ref()) {
                        Some(t) => ui.add(
                            egui::Image::new((t.id(), size)).sense(egui::Sense::click_and_drag()),
                        ),
                        None => {
                            // Until the first picture arrives: its place, already movable.
                            let (rect, r) =
                                ui.allocate_exact_size(size, egui::Sense::click_and_drag());
                            ui.painter().text(
                                rect.center(),
                                egui::Align2::CENTER_CENTER,
                                "rendering…",
                                egui::FontId::proportional(14.0),
                                ui.visuals().weak_text_color(),
                            );
                            r
                        }
                    };
                    image = Some(r);
                });
            });
        self.preview_rect = image.as_ref().map(|r| r.rect);
        if let Some(r) = image
            && self.morph.is_none()
            && !self.timeline.plays_sequence()
        {
            let r = named(r, "Preview").on_hover_text(
                "wheel: zoom at the pointer · drag: move · right-drag: rotate · double-click: fit",
            );
            self.camera(ui, &r, &f);
        }
    }

    /// The camera by mouse on the picture: wheel zooms at the pointer, a drag moves the view,
    /// a right-drag turns it about the centre, a double click frames the flame. Each gesture
    /// is one undo step.
    fn camera(&mut self, ui: &egui::Ui, r: &egui::Response, f: &Flame) {
        let rect = r.rect;
        // Screen points per world unit of the shown picture.
        let k = f.ppu() * rect.width() as f64 / f.width.max(1) as f64;
        if !(k.is_finite() && k > 0.0) {
            return;
        }
        let (s, c) = f.rotate.to_radians().sin_cos();
        // World offset of a screen offset o (points, y down): R(−θ)·o/k.
        let world = |o: Vec2| {
            let (x, y) = (o.x as f64 / k, o.y as f64 / k);
            [c * x + s * y, -s * x + c * y]
        };
        let mut edit: Option<FlameEdit> = None;
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if r.hovered()
            && scroll != 0.0
            && let Some(p) = r.hover_pos()
        {
            let factor = (scroll as f64 * 0.0025).exp();
            let o = world(p - rect.center());
            let (cx, cy) = (f.center[0], f.center[1]);
            edit = Some(Box::new(move |g: &mut Flame| {
                // Keep the world point under the pointer where it is: the offset from the
                // centre shrinks by the zoom factor.
                let p = [cx + o[0], cy + o[1]];
                g.zoom = (g.zoom + factor.log2()).clamp(-20.0, 20.0);
                g.center = [p[0] - o[0] / factor, p[1] - o[1] / factor];
            }));
        }
        self.camera_drag = r.dragged();
        if r.dragged_by(egui::PointerButton::Primary) {
            let d = world(r.drag_delta());
            edit = Some(Box::new(move |g: &mut Flame| {
                g.center = [g.center[0] - d[0], g.center[1] - d[1]];
            }));
        } else if r.dragged_by(egui::PointerButton::Secondary)
            && let Some(p) = r.interact_pointer_pos()
        {
            let now = p - rect.center();
            let before = now - r.drag_delta();
            if now.length() > 4.0 && before.length() > 4.0 {
                let turn = (now.y.atan2(now.x) - before.y.atan2(before.x)) as f64;
                let deg = turn.to_degrees();
                edit = Some(Box::new(move |g: &mut Flame| {
                    g.rotate = (g.rotate + deg + 180.0).rem_euclid(360.0) - 180.0;
                }));
            }
        }
        if r.double_clicked() {
            edit = Some(Box::new(crate::flame::framing::apply_auto_frame));
        }
        if let Some(e) = edit {
            let doc = super::pick(self.showing, &mut self.batch, &mut self.file);
            doc.edit_while(true, e);
            if r.double_clicked() {
                doc.commit_live();
            }
        }
    }
}
