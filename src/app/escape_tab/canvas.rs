//! The escape-time picture: wheel zoom at the cursor, drag to pan, right-drag to zoom to a
//! rectangle, click on the Mandelbrot set to open the Julia set of the point.

use eframe::egui::{self, Color32, Pos2, Rect, Stroke, Vec2};

use super::EscapeTab;
use crate::escape::Family;
use crate::escape::fx::Fx;

/// Device pixel coordinates of a screen point in the canvas `rect`.
fn pixel_of(p: Pos2, rect: Rect, ppp: f32) -> [f64; 2] {
    [
        ((p.x - rect.left()) * ppp) as f64,
        ((p.y - rect.top()) * ppp) as f64,
    ]
}

impl EscapeTab {
    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let (rect, resp, ppp, size) = crate::app::widgets::canvas_area(ui);
        let warped = matches!(self.doc.params.family, Family::WarpedJulia(_));
        let render_size = self.fit_to_panel(size, warped);
        // Interaction (not for textures).
        if !warped {
            self.hover_and_zoom(&ctx, &resp, rect, ppp);
            self.pan(&ctx, &resp, ppp);
            self.rectangle_zoom(&ctx, &resp, rect, ppp);
            if resp.clicked()
                && matches!(self.doc.params.family, Family::Mandelbrot { .. })
                && let Some(c) = self.hover
            {
                self.open_julia(c);
            }
        }
        // Render and draw.
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(12));
        self.draw_picture(&ctx, &painter, rect, ppp, size, render_size, warped);
        if let (Some(a), Some(b)) = (self.rect_start, resp.interact_pointer_pos())
            && resp.dragged_by(egui::PointerButton::Secondary)
        {
            painter.rect_stroke(
                Rect::from_two_pos(a, b),
                0.0,
                Stroke::new(1.0, Color32::WHITE),
                egui::StrokeKind::Middle,
            );
        }
    }

    /// The size to render at for a panel of `size` device pixels: the document follows the
    /// panel, keeping the world width; a texture keeps its own aspect, fitted in.
    fn fit_to_panel(&mut self, size: [u32; 2], warped: bool) -> [u32; 2] {
        if !warped && [self.doc.width, self.doc.height] != size {
            self.doc.resize(size[0], size[1]);
        }
        if warped {
            // Textures keep their own aspect (2:1 for a sky dome), fitted into the panel.
            let aspect = self.doc.width as f32 / self.doc.height.max(1) as f32;
            let w = (size[0] as f32).min(size[1] as f32 * aspect);
            [w.max(16.0) as u32, (w / aspect).max(16.0) as u32]
        } else {
            size
        }
    }

    /// The point under the pointer, and the wheel zooming at it.
    fn hover_and_zoom(&mut self, ctx: &egui::Context, resp: &egui::Response, rect: Rect, ppp: f32) {
        if let Some(hp) = resp.hover_pos() {
            let px = pixel_of(hp, rect, ppp);
            self.hover = Some(self.doc.view.world_from_pixel(
                px[0] - 0.5,
                px[1] - 0.5,
                self.doc.width,
                self.doc.height,
            ));
            let scroll = ctx.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                let factor = (scroll as f64 * 0.004).exp();
                self.zoom_at([px[0] + 0.5, px[1] + 0.5], factor);
            }
        } else if self.pan_start.is_none() {
            self.hover = None;
        }
    }

    /// Dragging with the primary button pans the view (one history step).
    fn pan(&mut self, ctx: &egui::Context, resp: &egui::Response, ppp: f32) {
        if resp.drag_started_by(egui::PointerButton::Primary) {
            self.push_history();
            self.pan_start = Some(self.doc.view.clone());
        }
        if resp.dragged_by(egui::PointerButton::Primary)
            && let (Some(v0), Some(origin), Some(now)) = (
                self.pan_start.clone(),
                ctx.input(|i| i.pointer.press_origin()),
                resp.interact_pointer_pos(),
            )
        {
            let d = (now - origin) * ppp;
            let px = self.doc.view.pixel_size(self.doc.height);
            self.doc.view = v0.shifted(-d.x as f64 * px, d.y as f64 * px);
        }
        if resp.drag_stopped_by(egui::PointerButton::Primary) {
            self.pan_start = None;
        }
    }

    /// Dragging with the secondary button zooms to the rectangle drawn, if the view allows.
    fn rectangle_zoom(&mut self, ctx: &egui::Context, resp: &egui::Response, rect: Rect, ppp: f32) {
        if resp.drag_started_by(egui::PointerButton::Secondary) {
            self.rect_start = ctx.input(|i| i.pointer.press_origin());
        }
        if resp.drag_stopped_by(egui::PointerButton::Secondary)
            && let (Some(a), Some(b)) = (self.rect_start.take(), resp.interact_pointer_pos())
        {
            let r = Rect::from_two_pos(a, b);
            if r.width() > 4.0 && r.height() > 4.0 {
                let c = pixel_of(r.center(), rect, ppp);
                let o = self.doc.view.offset_from_pixel_fx(
                    c[0] - 0.5,
                    c[1] - 0.5,
                    self.doc.width,
                    self.doc.height,
                );
                let factor = (rect.width() / r.width()).min(rect.height() / r.height()) as f64;
                let v = self
                    .doc
                    .view
                    .scaled(1.0 / factor)
                    .shifted_fx(Fx::new(o.re, o.e), Fx::new(o.im, o.e));
                match crate::escape::render::check_view_for(
                    &self.doc.params.family,
                    &v,
                    self.doc.width,
                    self.doc.height,
                ) {
                    Ok(()) => {
                        self.push_history();
                        self.doc.view = v;
                    }
                    Err(e) => self.notices.status = e.to_string(),
                }
            }
        }
    }

    /// Ask for the picture of the current view and draw the newest one (until the new frame
    /// arrives, the old one where its view now lies), or the render's error.
    #[allow(clippy::too_many_arguments)]
    fn draw_picture(
        &mut self,
        ctx: &egui::Context,
        painter: &egui::Painter,
        rect: Rect,
        ppp: f32,
        size: [u32; 2],
        render_size: [u32; 2],
        warped: bool,
    ) {
        if let Some(d) = &mut self.main {
            d.request(&self.doc.params, self.doc.view.clone(), render_size);
            d.poll(ctx, "escape-main");
            if let Some(t) = &d.texture {
                let img_rect = match (d.shown_view.clone(), warped) {
                    // Until the new frame arrives, draw the old one where its view now lies.
                    (Some(v), false) if v != self.doc.view => {
                        let corner =
                            |i: f64, j: f64| self.doc.view.pixel_of(&v, i, j, size[0], size[1]);
                        let a = corner(-0.5, -0.5);
                        let b = corner(size[0] as f64 - 0.5, size[1] as f64 - 0.5);
                        Rect::from_min_max(
                            rect.min + Vec2::new(a[0] as f32, a[1] as f32) / ppp,
                            rect.min + Vec2::new(b[0] as f32, b[1] as f32) / ppp,
                        )
                    }
                    _ => Rect::from_min_size(
                        rect.min,
                        Vec2::new(render_size[0] as f32, render_size[1] as f32) / ppp,
                    ),
                };
                painter.image(
                    t.id(),
                    img_rect,
                    Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                    Color32::WHITE,
                );
            }
            if let Some(e) = &d.error {
                painter.text(
                    rect.center(),
                    egui::Align2::CENTER_CENTER,
                    e,
                    egui::FontId::proportional(14.0),
                    Color32::from_rgb(240, 140, 100),
                );
            }
        }
    }
}
