//! Widgets the tabs share: the picture area that fills the rest of a panel.

use eframe::egui::{Rect, Response, Sense, Ui, Vec2};

/// The rest of the panel as an interactive picture area: its rectangle, its response, the
/// pixels per point and its size in device pixels (at least 16×16).
pub(crate) fn canvas_area(ui: &mut Ui) -> (Rect, Response, f32, [u32; 2]) {
    let avail = ui.available_size().max(Vec2::splat(32.0));
    let (rect, resp) = ui.allocate_exact_size(avail, Sense::click_and_drag());
    let ppp = ui.ctx().pixels_per_point();
    let size = [
        ((rect.width() * ppp) as u32).max(16),
        ((rect.height() * ppp) as u32).max(16),
    ];
    (rect, resp, ppp, size)
}
