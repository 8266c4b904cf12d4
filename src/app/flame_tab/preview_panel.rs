//! The central picture of the flame tab: the current flame (or morph frame) rendered by the
//! preview worker at the panel's size, quick while dragging or animating, refined when still.

use eframe::egui::{self, Vec2};

use super::FlameTab;
use super::preview::{PreviewEvent, PreviewJob, PreviewWorker};
use super::preview_motion::MotionJob;
use super::preview_window::PreviewPlace;
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
    /// The last job.
    submitted: Option<PreviewJob>,
    fraction: f64,
    elapsed_ms: f64,
    /// Samples per pixel and estimated noise of the picture shown, and whether it is final.
    quality: f64,
    noise: Option<f64>,
    done: bool,
    /// The submitted job refines to a noise target (not a drag or animation frame).
    refining: bool,
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
            quality: 0.0,
            noise: None,
            done: false,
            refining: false,
            error: None,
            shown_generation: 0,
        }
    }

    /// Render `job` unless that is what is on its way already (its generation is set here).
    fn request(&mut self, mut job: PreviewJob) {
        let same_settings = |s: &PreviewJob| {
            (s.width, s.height, s.first_quality, s.final_quality)
                == (job.width, job.height, job.first_quality, job.final_quality)
                && (s.noise_target, s.least_quality) == (job.noise_target, job.least_quality)
                && s.threads == job.threads
                && s.motion == job.motion
        };
        let only_palette = match &self.submitted {
            Some(s) if same_settings(s) => {
                if s.flame == job.flame {
                    return;
                }
                without_palette(&s.flame) == without_palette(&job.flame)
            }
            _ => false,
        };
        if !only_palette {
            self.generation += 1;
        }
        job.generation = self.generation;
        self.refining = job.noise_target.is_some();
        self.done = false;
        self.submitted = Some(job.clone());
        if only_palette {
            self.worker.recolor(job);
        } else {
            self.worker.submit(job);
        }
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
                    self.quality = fr.quality;
                    self.noise = fr.noise;
                    self.done = fr.done;
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

    /// The preview's part of the status bar: how far the refinement has got.
    pub fn status(&self, ui: &mut egui::Ui) {
        if let Some(e) = &self.error {
            ui.colored_label(egui::Color32::from_rgb(230, 120, 90), e);
            return;
        }
        let noise = self
            .noise
            .map_or(String::new(), |n| format!("  noise {n:.1}"));
        let blur = self
            .submitted
            .as_ref()
            .and_then(|j| j.motion.as_ref())
            .map_or(String::new(), |m| format!("  {}", m.describe()));
        let text = if !self.refining {
            format!("preview {:.0} ms{blur}", self.elapsed_ms)
        } else if self.done {
            format!(
                "preview clean  quality {:.0}{noise}  {:.1} s{blur}",
                self.quality,
                self.elapsed_ms / 1000.0
            )
        } else {
            format!(
                "refining {:>3.0}%  quality {:.0}{noise}{blur}",
                self.fraction * 100.0,
                self.quality
            )
        };
        ui.label(text).on_hover_text(
            "the preview adds samples until its noise reaches the target of Options › Display \
             (levels of 255), then stops; quality: samples per pixel so far",
        );
    }

    /// True while the preview is still adding samples to a still picture.
    pub fn refining(&self) -> bool {
        self.refining && !self.done && self.error.is_none()
    }

    /// How far the refinement has got, in [0, 1].
    pub fn fraction(&self) -> f64 {
        self.fraction
    }
}

/// The largest size of aspect `aspect` (width/height) that fits in `avail`.
pub(super) fn fit_aspect(avail: Vec2, aspect: f32) -> (f32, f32) {
    let aspect = if aspect.is_finite() && aspect > 0.0 {
        aspect
    } else {
        1.0
    };
    let (w, h) = (avail.x.max(1.0), avail.x.max(1.0) / aspect);
    if h > avail.y.max(1.0) {
        (avail.y.max(1.0) * aspect, avail.y.max(1.0))
    } else {
        (w, h)
    }
}

impl FlameTab {
    /// The picture, as large as `ui` allows at the flame's aspect, with the buttons of `place`
    /// on it; `dragging`: a triangle or control is being dragged (quick frames).
    pub(super) fn preview_panel(
        &mut self,
        ui: &mut egui::Ui,
        options: &Options,
        dragging: bool,
        place: PreviewPlace,
    ) {
        let avail = ui.available_size();
        let f = self.shown_flame();
        let (w, h) = fit_aspect(avail, f.width as f32 / f.height.max(1) as f32);
        // Rendered at the screen's pixels, at most preview_size on the longer side (a larger
        // area shows it scaled up).
        let ppp = ui.ctx().pixels_per_point();
        let k = (options.preview_size as f32 / (w.max(h) * ppp)).min(1.0);
        let px = [
            (w * ppp * k).round().max(16.0) as u32,
            (h * ppp * k).round().max(12.0) as u32,
        ];
        self.request_preview(ui.ctx(), options, &f, px, dragging);
        let size = Vec2::new(w, h) * self.preview_zoom;
        let mut image = None;
        egui::ScrollArea::both()
            .scroll_source(egui::scroll_area::ScrollSource::SCROLL_BAR)
            .show(ui, |ui| {
                // The picture in the middle of the room (or of its zoomed size).
                let room = ui.available_size().max(size);
                let (area, _) = ui.allocate_exact_size(room, egui::Sense::hover());
                let rect = egui::Rect::from_center_size(area.center(), size);
                let r = ui.interact(
                    rect,
                    ui.scope_id().with("picture"),
                    egui::Sense::click_and_drag(),
                );
                match self.preview.as_ref().and_then(|p| p.texture.as_ref()) {
                    Some(t) => egui::Image::new((t.id(), size)).paint_at(ui, rect),
                    // Until the first picture arrives: its place, already movable.
                    None => {
                        ui.painter().text(
                            rect.center(),
                            egui::Align2::CENTER_CENTER,
                            "rendering…",
                            egui::FontId::proportional(14.0),
                            ui.visuals().weak_text_color(),
                        );
                    }
                }
                image = Some(r);
            });
        let Some(r) = image else { return };
        let clip = ui.clip_rect();
        self.preview_rect = Some(r.rect);
        self.progress_line(ui, r.rect.intersect(clip));
        if self.morph.is_none() && !self.timeline.plays_sequence() {
            let r = named(r.clone(), "Preview").on_hover_text(
                "wheel: zoom at the pointer · drag: move · right-drag: rotate · double-click: fit",
            );
            self.camera(ui, &r, &f);
        }
        self.place_buttons(ui, r.rect.intersect(clip), place);
    }

    /// Ask the worker for the picture of `f` at `px` pixels: quick frames while dragging or
    /// animating, otherwise refined to the noise target.
    fn request_preview(
        &mut self,
        ctx: &egui::Context,
        options: &Options,
        f: &Flame,
        px: [u32; 2],
        dragging: bool,
    ) {
        let animating = self.animation.is_some() || self.morph.is_some() || self.timeline.playing();
        let dragging = dragging || self.camera_drag || self.timeline.scrubbing;
        let motion = match self.morph {
            Some(_) => None,
            None => {
                // Quick frames (playing, scrubbing, a drag) draw from fewer sub-frames.
                let moving = animating || dragging;
                self.timeline
                    .motion_source(self.doc().flame())
                    .and_then(|(source, time)| MotionJob::of(source, time, f, moving))
            }
        };
        let Some(p) = &mut self.preview else { return };
        // A still picture refines to the preview's noise target, whatever the file's quality
        // (that is for export); a drag or animation frame is one quick pass.
        let (first_q, final_q, noise) = if animating {
            (options.animation_quality, options.animation_quality, None)
        } else if dragging {
            (options.preview_quality, options.preview_quality, None)
        } else {
            (
                options.preview_quality,
                options.preview_max_quality.max(options.preview_quality),
                Some(options.preview_noise),
            )
        };
        p.request(PreviewJob {
            flame: f.clone(),
            width: px[0],
            height: px[1],
            first_quality: first_q,
            final_quality: final_q,
            noise_target: noise,
            least_quality: options.preview_least_quality,
            threads: options.threads,
            generation: 0,
            motion,
        });
        p.poll(ctx);
    }

    /// A thin bar along the bottom of the picture while it refines: how far it has got.
    fn progress_line(&self, ui: &egui::Ui, rect: egui::Rect) {
        let Some(p) = self.preview.as_ref().filter(|p| p.refining()) else {
            return;
        };
        let bar = egui::Rect::from_min_size(
            egui::pos2(rect.left(), rect.bottom() - 3.0),
            Vec2::new(rect.width() * p.fraction().clamp(0.02, 1.0) as f32, 3.0),
        );
        ui.painter()
            .rect_filled(bar, 0.0, ui.visuals().selection.bg_fill);
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
