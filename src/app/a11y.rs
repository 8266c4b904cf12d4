//! Accessible names for widgets that have no visible label of their own (a number in a grid
//! cell, a drag handle): screen readers read them, and the UI tests find widgets by them.

use eframe::egui;

/// Give `resp`'s widget the accessible name `name`.
pub fn named(resp: egui::Response, name: &str) -> egui::Response {
    resp.ctx.accesskit_node_builder(resp.id, |b| {
        b.set_label(name.to_string());
    });
    resp
}
