//! Flame-wide settings: name, size, camera, tone mapping, background.

use eframe::egui;

use super::document::Document;
use crate::app::a11y::named;

/// Flame-wide settings: name, size, camera, tone mapping.
pub fn flame_settings(ui: &mut egui::Ui, doc: &mut Document) {
    let mut f = doc.flame().clone();
    let before = f.clone();
    egui::CollapsingHeader::new("Flame")
        .default_open(false)
        .show(ui, |ui| {
            egui::Grid::new("flame-grid").num_columns(2).show(ui, |ui| {
                let l = ui.label("Name");
                ui.text_edit_singleline(&mut f.name).labelled_by(l.id);
                ui.end_row();
                ui.label("Size");
                ui.horizontal(|ui| {
                    named(
                        ui.add(egui::DragValue::new(&mut f.width).range(1..=20000)),
                        "Width",
                    );
                    ui.label("×");
                    named(
                        ui.add(egui::DragValue::new(&mut f.height).range(1..=20000)),
                        "Height",
                    );
                });
                ui.end_row();
                let row = |ui: &mut egui::Ui,
                           l: &str,
                           v: &mut f64,
                           speed: f64,
                           r: std::ops::RangeInclusive<f64>| {
                    let lb = ui.label(l);
                    ui.add(
                        egui::DragValue::new(v)
                            .speed(speed)
                            .range(r)
                            .max_decimals(5),
                    )
                    .labelled_by(lb.id);
                    ui.end_row();
                };
                row(ui, "Centre x", &mut f.center[0], 0.01, -1e6..=1e6);
                row(ui, "Centre y", &mut f.center[1], 0.01, -1e6..=1e6);
                row(ui, "Scale", &mut f.scale, 0.5, 0.001..=1e7);
                row(ui, "Zoom", &mut f.zoom, 0.01, -20.0..=20.0);
                row(ui, "Rotate (°)", &mut f.rotate, 0.5, -3600.0..=3600.0);
                row(ui, "Quality", &mut f.quality, 1.0, 0.01..=1e6);
                row(ui, "Brightness", &mut f.brightness, 0.05, 0.01..=1000.0);
                row(ui, "Gamma", &mut f.gamma, 0.05, 0.01..=100.0);
                row(
                    ui,
                    "Gamma threshold",
                    &mut f.gamma_threshold,
                    0.001,
                    0.0..=10.0,
                );
                row(ui, "Vibrancy", &mut f.vibrancy, 0.01, 0.0..=10.0);
                row(
                    ui,
                    "Highlight power",
                    &mut f.highlight_power,
                    0.05,
                    -1.0..=100.0,
                );
                row(ui, "Contrast", &mut f.contrast, 0.01, 0.01..=100.0);
                row(ui, "DE radius", &mut f.estimator_radius, 0.1, 0.0..=50.0);
                ui.label("Background");
                let mut bg = [
                    f.background[0] as f32,
                    f.background[1] as f32,
                    f.background[2] as f32,
                ];
                if named(ui.color_edit_button_rgb(&mut bg), "Background colour").changed() {
                    f.background = bg.map(|v| v as f64);
                }
                ui.end_row();
            });
        });
    if f.estimator_radius < f.estimator_minimum {
        f.estimator_minimum = f.estimator_radius;
    }
    if f != before {
        doc.edit(|g| *g = f);
    }
}
