//! The Options dialog: display densities, random-flame settings, general settings.

use eframe::egui;

use super::a11y::named;
use super::options::Options;
use crate::flame::random::SymmetryMode;
use crate::gradient;

/// Tabs of the Options dialog.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum OptionsTab {
    #[default]
    Display,
    Random,
    General,
}

/// The Options dialog. Returns true when the user pressed OK with valid options.
pub fn dialog(ui: &mut egui::Ui, draft: &mut Options, tab: &mut OptionsTab) -> Option<bool> {
    let mut result = None;
    // One width for every tab: the window does not move when the tab changes.
    ui.set_width(440.0);
    ui.horizontal(|ui| {
        ui.selectable_value(tab, OptionsTab::Display, "Display")
            .on_hover_text("densities, gamma, brightness and contrast");
        ui.selectable_value(tab, OptionsTab::Random, "Random")
            .on_hover_text("how random flames are made");
        ui.selectable_value(tab, OptionsTab::General, "General")
            .on_hover_text("gradient, preview size, new flame size, threads, weights");
    });
    ui.separator();
    match tab {
        OptionsTab::Display => display_tab(ui, draft),
        OptionsTab::Random => random_tab(ui, draft),
        OptionsTab::General => general_tab(ui, draft),
    }
    let problems = draft.problems();
    for p in &problems {
        ui.colored_label(egui::Color32::from_rgb(230, 90, 80), p);
    }
    ui.separator();
    ui.horizontal(|ui| {
        if ui
            .add_enabled(problems.is_empty(), egui::Button::new("OK"))
            .clicked()
        {
            result = Some(true);
        }
        if ui.button("Cancel").clicked() {
            result = Some(false);
        }
        if ui.button("Defaults").clicked() {
            *draft = Options::default();
        }
    });
    result
}

/// One labelled number row of a grid.
fn num(ui: &mut egui::Ui, label: &str, v: &mut f64, speed: f64) {
    let l = ui.label(label);
    ui.add(egui::DragValue::new(v).speed(speed).range(0.0..=1e6))
        .labelled_by(l.id);
    ui.end_row();
}

/// Display: the densities and tone mapping of the main render, the preview and animations.
fn display_tab(ui: &mut egui::Ui, draft: &mut Options) {
    egui::Grid::new("opt-display")
        .num_columns(2)
        .show(ui, |ui| {
            ui.strong("Main render");
            ui.end_row();
            num(ui, "Density (quality)", &mut draft.main_quality, 0.5);
            num(ui, "Gamma", &mut draft.main_gamma, 0.05);
            num(ui, "Brightness", &mut draft.main_brightness, 0.05);
            num(ui, "Contrast", &mut draft.main_contrast, 0.05);
            ui.strong("Preview");
            ui.end_row();
            num(ui, "Density", &mut draft.preview_quality, 0.5);
            let l = ui.label("Noise target (levels)");
            ui.add(
                egui::DragValue::new(&mut draft.preview_noise)
                    .speed(0.05)
                    .range(super::options::PREVIEW_NOISE_RANGE),
            )
            .labelled_by(l.id)
            .on_hover_text(
                "the preview keeps refining until its noise is at most this many of 255 \
                 levels (lower: cleaner, slower); the file's quality is for export",
            );
            ui.end_row();
            let l = ui.label("Least quality");
            ui.add(
                egui::DragValue::new(&mut draft.preview_least_quality)
                    .speed(5.0)
                    .range(0.0..=crate::flame::render::MAX_QUALITY),
            )
            .labelled_by(l.id)
            .on_hover_text(
                "the preview refines to at least this many samples per pixel before its \
                 noise may stop it (density estimation keeps sharpening the picture)",
            );
            ui.end_row();
            let l = ui.label("Most quality");
            ui.add(
                egui::DragValue::new(&mut draft.preview_max_quality)
                    .speed(10.0)
                    .range(1.0..=crate::flame::render::MAX_QUALITY),
            )
            .labelled_by(l.id)
            .on_hover_text("the preview stops refining at this many samples per pixel");
            ui.end_row();
            num(ui, "Gamma", &mut draft.preview_gamma, 0.05);
            ui.strong("Animation");
            ui.end_row();
            num(ui, "Density", &mut draft.animation_quality, 0.1);
        });
}

/// Random: how random flames are made.
fn random_tab(ui: &mut egui::Ui, draft: &mut Options) {
    egui::Grid::new("opt-random").num_columns(2).show(ui, |ui| {
        let l = ui.label("Transforms, minimum");
        ui.add(egui::DragValue::new(&mut draft.min_xforms).range(2..=100))
            .labelled_by(l.id);
        ui.end_row();
        let l = ui.label("Transforms, maximum");
        ui.add(egui::DragValue::new(&mut draft.max_xforms).range(2..=100))
            .labelled_by(l.id);
        ui.end_row();
        let l = ui.label("Random gradient");
        ui.checkbox(&mut draft.random_gradient, "")
            .labelled_by(l.id)
            .on_hover_text("each random flame gets a gradient of the library");
        ui.end_row();
        ui.label("Symmetry");
        ui.horizontal(|ui| {
            let fixed = matches!(draft.symmetry, SymmetryMode::Order(_));
            if ui
                .selectable_label(draft.symmetry == SymmetryMode::None, "none")
                .clicked()
            {
                draft.symmetry = SymmetryMode::None;
            }
            if ui
                .selectable_label(draft.symmetry == SymmetryMode::Random, "random")
                .clicked()
            {
                draft.symmetry = SymmetryMode::Random;
            }
            if ui.selectable_label(fixed, "order").clicked() && !fixed {
                draft.symmetry = SymmetryMode::Order(4);
            }
            if let SymmetryMode::Order(k) = &mut draft.symmetry {
                ui.add(egui::DragValue::new(k).range(-100..=100))
                    .on_hover_text("N: rotational; −N: rotational and mirror; −1: mirror");
            }
        });
        ui.end_row();
        let l = ui.label("Chance of post transforms");
        ui.add(egui::Slider::new(&mut draft.post_probability, 0.0..=1.0))
            .labelled_by(l.id);
        ui.end_row();
        let l = ui.label("Chance of a final transform");
        ui.add(egui::Slider::new(&mut draft.final_probability, 0.0..=1.0))
            .labelled_by(l.id);
        ui.end_row();
        ui.strong("Variation probabilities");
        ui.end_row();
        for (i, id) in crate::flame::variations::THESIS_SEVEN.iter().enumerate() {
            let l = ui.label(crate::flame::variations::info(*id).name);
            ui.add(
                egui::DragValue::new(&mut draft.probabilities[i])
                    .speed(0.01)
                    .range(0.0..=1.0),
            )
            .labelled_by(l.id);
            ui.end_row();
        }
    });
}

/// General: the default gradient, the preview and new flame sizes, threads and weights.
fn general_tab(ui: &mut egui::Ui, draft: &mut Options) {
    egui::Grid::new("opt-general")
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("Default gradient");
            egui::ComboBox::from_id_salt("opt-gradient")
                .selected_text(draft.default_gradient.clone())
                .show_ui(ui, |ui| {
                    for g in gradient::builtin() {
                        ui.selectable_value(&mut draft.default_gradient, g.name.clone(), g.name);
                    }
                });
            ui.end_row();
            let l = ui.label("Preview size (pixels)");
            ui.add(egui::DragValue::new(&mut draft.preview_size).range(64..=4096))
                .labelled_by(l.id);
            ui.end_row();
            ui.label("New flame size");
            ui.horizontal(|ui| {
                named(
                    ui.add(egui::DragValue::new(&mut draft.width).range(1..=20000)),
                    "New flame width",
                );
                ui.label("×");
                named(
                    ui.add(egui::DragValue::new(&mut draft.height).range(1..=20000)),
                    "New flame height",
                );
            });
            ui.end_row();
            let l = ui.label("Render threads (0 = all)");
            ui.add(egui::DragValue::new(&mut draft.threads).range(0..=256))
                .labelled_by(l.id);
            ui.end_row();
            let l = ui.label("Weights from triangle areas after edits");
            ui.checkbox(&mut draft.auto_weights, "")
                .labelled_by(l.id)
                .on_hover_text(
                    "for new and random flames; a typed weight turns it off for that flame",
                );
            ui.end_row();
            let l = ui.label("JWildfire installation");
            ui.add(
                egui::TextEdit::singleline(&mut draft.jwildfire)
                    .hint_text("…/j-wildfire.jar")
                    .desired_width(260.0),
            )
            .labelled_by(l.id)
            .on_hover_text(
                "JWildfire's jar (or its resource folders, separated by ':'): brush_stroke_wf, \
                 wangtiles, obj_mesh_primitive_wf and svg_wf read JWildfire's own images, meshes \
                 and drawing from it, for flames opened afterwards",
            );
            ui.end_row();
        });
}
