//! The scene picture, rendered in the background (half resolution while the mouse moves the
//! view): drag to orbit, wheel to zoom, right-drag to pan, Ctrl+drag to move the selected
//! light.

use eframe::egui::{self, Color32, Pos2, Rect, Stroke, Vec2};

use super::{SceneJob, SceneTab};

impl SceneTab {
    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let (rect, resp, ppp, size) = crate::app::widgets::canvas_area(ui);
        // Interaction.
        let px_per_unit = self.scene.camera.scale * size[1] as f64 / 480.0 / ppp as f64;
        let ctrl = ctx.input(|i| i.modifiers.command);
        let d = resp.drag_delta();
        if resp.dragged_by(egui::PointerButton::Primary) && d != Vec2::ZERO {
            if ctrl {
                self.move_light(d, px_per_unit);
            } else {
                self.orbit(d);
            }
        }
        if (resp.dragged_by(egui::PointerButton::Secondary)
            || resp.dragged_by(egui::PointerButton::Middle))
            && d != Vec2::ZERO
        {
            self.pan(d, px_per_unit);
        }
        if resp.hovered() {
            let scroll = ctx.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                self.scene.camera.scale =
                    (self.scene.camera.scale * (scroll as f64 * 0.003).exp()).clamp(1.0, 5000.0);
                self.version += 1;
            }
        }
        let dragging = resp.dragged();
        // Render: half resolution while the mouse moves the view, full when it stops.
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(12));
        if let Some(w) = &self.worker {
            let key = (self.version, size, dragging);
            if self.submitted != Some(key) {
                let mut s = self.scene.clone();
                let k = if dragging { 2 } else { 1 };
                s.width = size[0] / k;
                s.height = size[1] / k;
                if dragging {
                    s.supersample = 1;
                }
                self.generation += 1;
                w.submit(SceneJob {
                    scene: s,
                    generation: self.generation,
                });
                self.submitted = Some(key);
            }
            for f in w.poll() {
                if f.generation != self.generation {
                    continue;
                }
                self.last_ms = f.ms;
                match &mut self.texture {
                    Some(t) => t.set(f.image, egui::TextureOptions::LINEAR),
                    None => {
                        self.texture =
                            Some(ctx.load_texture("scene", f.image, egui::TextureOptions::LINEAR))
                    }
                }
            }
        }
        if let Some(t) = &self.texture {
            painter.image(
                t.id(),
                rect,
                Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                Color32::WHITE,
            );
        }
        // Light handles.
        let mut s = self.scene.clone();
        s.width = size[0];
        s.height = size[1];
        for (i, l) in self.scene.lights.iter().enumerate() {
            if let Some(p) = crate::surface::project(&s, l.position) {
                let q = rect.min + Vec2::new(p[0] as f32, p[1] as f32) / ppp;
                if rect.contains(q) {
                    let col = if i == self.selected_light {
                        Color32::YELLOW
                    } else {
                        Color32::from_gray(200)
                    };
                    painter.circle_stroke(q, 6.0, Stroke::new(2.0, col));
                }
            }
        }
    }
}
