//! Where the preview is shown: in the flame tab between its panels, over the whole window
//! (full-window view, F11), or in a window of its own (a second native window where the
//! platform allows it, otherwise a floating window inside the main one), leaving the main
//! window to the editor.

use eframe::egui::{self, Vec2};

use super::FlameTab;
use crate::app::options::Options;

/// Where the picture is drawn, and so which buttons it carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PreviewPlace {
    /// Between the flame tab's panels.
    Panel,
    /// Over the whole window.
    FullWindow,
    /// In its own window.
    OwnWindow,
}

/// The preview window's viewport.
fn viewport_id() -> egui::ViewportId {
    egui::ViewportId::from_hash_of("ugnis-preview-window")
}

impl FlameTab {
    /// The buttons on the picture (shown while the pointer is over it): full window and own
    /// window, or the way back.
    pub(super) fn place_buttons(
        &mut self,
        ui: &mut egui::Ui,
        rect: egui::Rect,
        place: PreviewPlace,
    ) {
        let hovered = ui.rect_contains_pointer(rect);
        if !hovered && place == PreviewPlace::Panel {
            return;
        }
        let area = egui::Rect::from_min_size(
            rect.left_top() + Vec2::new(6.0, 6.0),
            Vec2::new((rect.width() - 12.0).max(0.0), 24.0),
        );
        let mut child = ui.new_child(
            egui::UiBuilder::new()
                .max_rect(area)
                .layout(egui::Layout::right_to_left(egui::Align::Min)),
        );
        let ui = &mut child;
        match place {
            PreviewPlace::Panel => {
                if ui
                    .small_button("Own window")
                    .on_hover_text(
                        "show the preview in a window of its own; the editor takes this room",
                    )
                    .clicked()
                {
                    self.preview_window = true;
                }
                if ui
                    .small_button("Full window")
                    .on_hover_text("the preview over the whole window (F11; Esc returns)")
                    .clicked()
                {
                    self.full_view = true;
                }
            }
            PreviewPlace::FullWindow => {
                if ui
                    .small_button("Leave full window")
                    .on_hover_text("back to the panels (F11 or Esc)")
                    .clicked()
                {
                    self.full_view = false;
                }
            }
            PreviewPlace::OwnWindow => {
                if ui
                    .small_button("Back to the main window")
                    .on_hover_text("close this window; the preview returns between the panels")
                    .clicked()
                {
                    self.preview_window = false;
                }
            }
        }
    }

    /// The whole window is the preview (nothing else is drawn in the flame tab).
    pub(super) fn full_window_ui(&mut self, ui: &mut egui::Ui, options: &Options) {
        egui::CentralPanel::default()
            .frame(egui::Frame::NONE.fill(egui::Color32::from_gray(8)))
            .show(ui, |ui| {
                self.preview_panel(ui, options, false, PreviewPlace::FullWindow)
            });
    }

    /// The preview's own window, while it is open; closing it brings the preview back.
    pub(super) fn preview_viewport(
        &mut self,
        ctx: &egui::Context,
        options: &Options,
        dragging: bool,
    ) {
        if !self.preview_window {
            return;
        }
        let builder = egui::ViewportBuilder::default()
            .with_title("ugnis — preview")
            .with_inner_size([800.0, 600.0])
            .with_min_inner_size([200.0, 150.0]);
        let closed = ctx.show_viewport_immediate(viewport_id(), builder, |ui, class| {
            let frame = egui::Frame::NONE.fill(egui::Color32::from_gray(8));
            if class == egui::ViewportClass::EmbeddedWindow {
                // No second native window here: a floating window of the main one.
                ui.set_min_size(Vec2::new(480.0, 360.0));
                frame.show(ui, |ui| {
                    self.preview_panel(ui, options, dragging, PreviewPlace::OwnWindow)
                });
                return false;
            }
            egui::CentralPanel::default().frame(frame).show(ui, |ui| {
                self.preview_panel(ui, options, dragging, PreviewPlace::OwnWindow)
            });
            // Its own close button, or Esc in it, brings the preview back.
            ui.ctx()
                .input(|i| i.viewport().close_requested() || i.key_pressed(egui::Key::Escape))
        });
        if closed {
            self.preview_window = false;
        }
    }
}
