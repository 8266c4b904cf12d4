//! The escape-time tab's control panel: history buttons, the fractal family and its
//! parameters, colouring, export size and the file buttons.

use eframe::egui;

use super::{EscapeRequest, EscapeTab, KINDS};
use crate::app::a11y::named;
use crate::escape::{C, Coloring, Family, Fill, Preset, Sampling, View, Warp};
use crate::gradient;
use crate::io::escape_view;

impl EscapeTab {
    pub(super) fn controls(&mut self, ui: &mut egui::Ui) -> Option<EscapeRequest> {
        self.history_buttons(ui);
        ui.separator();
        self.family_choice(ui);
        let mut doc = self.doc.clone();
        egui::Grid::new("escape-params")
            .num_columns(2)
            .show(ui, |ui| {
                self.family_params(ui, &mut doc.params.family);
                self.iteration_row(ui, &mut doc);
                colour_params(ui, &mut doc);
            });
        if doc != self.doc {
            // Parameter edits are history steps too; a slider drag is one step.
            if !self.editing {
                self.push_history();
            }
            self.editing = ui.ctx().input(|i| i.pointer.any_down());
            self.doc = doc;
        } else if !ui.ctx().input(|i| i.pointer.any_down()) {
            self.editing = false;
        }
        ui.separator();
        let req = self.export_and_files(ui);
        ui.separator();
        ui.label("Wheel: zoom at the cursor · drag: pan · right-drag: zoom to a rectangle");
        if matches!(self.doc.params.family, Family::Mandelbrot { .. }) {
            ui.label("Click: open the Julia set of the point (preview below)");
        }
        req
    }

    /// The iteration limit (automatic from the depth unless set), the depth, and while a
    /// deep view computes its reference orbit, its progress and Stop.
    fn iteration_row(&mut self, ui: &mut egui::Ui, doc: &mut escape_view::EscapeDoc) {
        let l = ui.label("Max iterations");
        ui.horizontal(|ui| {
            let r = ui
                .add(
                    egui::DragValue::new(&mut doc.params.max_iter)
                        .range(1..=10_000_000)
                        .clamp_existing_to_range(false)
                        .speed(10.0),
                )
                .labelled_by(l.id)
                .on_hover_text("iterations before a point counts as inside (more: finer edges)");
            if r.changed() {
                self.auto_iter = false;
            }
            let deep = crate::escape::supports_deep_zoom(&doc.params.family);
            let c = ui
                .add_enabled(deep, egui::Checkbox::new(&mut self.auto_iter, "auto"))
                .on_hover_text("choose the iterations from the depth of the zoom");
            if c.changed() && self.auto_iter {
                doc.params.max_iter = crate::escape::auto_max_iter(doc.view.half_height_fx());
            }
        });
        ui.end_row();
        ui.label("Depth");
        ui.label(self.depth_text())
            .on_hover_text("the view's width in the plane; wheel or right-drag to zoom deeper");
        ui.end_row();
        let busy = self.busy();
        let progress = self.orbit_progress();
        if busy || progress.is_some() {
            ui.label("Rendering");
            ui.horizontal(|ui| {
                if let Some((done, of)) = progress {
                    ui.add(
                        egui::ProgressBar::new((done as f64 / of.max(1) as f64) as f32)
                            .desired_width(120.0)
                            .text(format!("reference orbit {done}")),
                    );
                } else if let Some(d) = &self.main {
                    ui.add(
                        egui::ProgressBar::new(d.fraction as f32)
                            .desired_width(120.0)
                            .show_percentage(),
                    );
                }
                if ui
                    .button("Stop")
                    .on_hover_text("stop computing this view")
                    .clicked()
                {
                    self.stop();
                }
            });
            ui.end_row();
        }
    }

    /// Back, Forward and Reset view.
    fn history_buttons(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            if ui
                .add_enabled(!self.back.is_empty(), egui::Button::new("Back"))
                .on_hover_text("previous view (Alt+Left)")
                .clicked()
            {
                self.go_back();
            }
            if ui
                .add_enabled(!self.forward.is_empty(), egui::Button::new("Forward"))
                .on_hover_text("next view (Alt+Right)")
                .clicked()
            {
                self.go_forward();
            }
            if ui
                .button("Reset view")
                .on_hover_text("the fractal's whole default view")
                .clicked()
            {
                let (c, hh) = self.doc.params.family.default_view();
                self.push_history();
                self.doc.view = View::new(c, hh);
            }
        });
    }

    /// The fractal family.
    fn family_choice(&mut self, ui: &mut egui::Ui) {
        let current = self.doc.params.family.name();
        let mut chosen = None;
        let fractal = egui::ComboBox::from_label("Fractal")
            .selected_text(
                KINDS
                    .iter()
                    .find(|k| k.0 == current)
                    .map_or(current, |k| k.1),
            )
            .show_ui(ui, |ui| {
                for (k, label) in KINDS {
                    if ui.selectable_label(k == current, label).clicked() {
                        chosen = Some(k);
                    }
                }
            });
        fractal
            .response
            .on_hover_text("the family of escape-time fractals");
        if let Some(k) = chosen
            && k != current
        {
            self.set_kind(k);
        }
    }

    /// The rows of the family's own parameters.
    fn family_params(&mut self, ui: &mut egui::Ui, family: &mut Family) {
        match family {
            Family::Mandelbrot { power } => power_row(ui, power),
            Family::Julia { power, c } => {
                power_row(ui, power);
                complex_row(ui, "c", c);
            }
            Family::Newton { coeffs } => {
                ui.label("Polynomial");
                let r = ui
                    .text_edit_singleline(&mut self.poly_text)
                    .on_hover_text("coefficients, highest degree first: 1 0 0 -1 is z³ − 1");
                if r.lost_focus() {
                    match escape_view::parse_poly(&self.poly_text) {
                        Some(p) => *coeffs = p,
                        None => {
                            self.notices.status =
                                "polynomial: give 2–33 numbers, highest degree first".into()
                        }
                    }
                }
                ui.end_row();
            }
            Family::Logistic { z0, kose } => {
                complex_row(ui, "z₀", z0);
                let l = ui.label("Köse λz(z − 1)");
                ui.checkbox(kose, "").labelled_by(l.id);
                ui.end_row();
            }
            Family::Cubic { p } => complex_row(ui, "p", p),
            Family::BurningShip => {}
            Family::WarpedJulia(w) => self.warp_params(ui, w),
        }
    }

    /// The rows of a warped Julia set: c, the warp, turbulence, polar sampling and presets.
    fn warp_params(&mut self, ui: &mut egui::Ui, w: &mut Warp) {
        let (mut c, mut alpha, mut lambda, mut polar) = (
            w.c,
            w.alpha,
            w.lambda,
            matches!(w.sampling, Sampling::Polar { .. }),
        );
        complex_row(ui, "c", &mut c);
        complex_row(ui, "warp α", &mut alpha);
        let l = ui.label("Turbulence λ");
        ui.add(egui::Slider::new(&mut lambda, 0.0..=1.0))
            .labelled_by(l.id);
        ui.end_row();
        let l = ui.label("Polar (seamless)");
        ui.checkbox(&mut polar, "").labelled_by(l.id);
        ui.end_row();
        ui.label("Presets");
        ui.horizontal(|ui| {
            for (l, p) in [
                ("Polar", Preset::PolarJulia),
                ("Warped", Preset::WarpedJulia),
                ("Galaxy", Preset::Galaxy),
            ] {
                if ui.small_button(l).clicked() {
                    let pw = Warp::preset(p);
                    (c, alpha, lambda, polar) = (pw.c, pw.alpha, pw.lambda, true);
                }
            }
        });
        ui.end_row();
        let sampling = if polar {
            Sampling::Polar { radius: 1.0 }
        } else {
            Sampling::Rect { scale: 3.0 }
        };
        if (c, alpha, lambda, sampling) != (w.c, w.alpha, w.lambda, w.sampling) {
            match Warp::new(c, alpha, lambda, w.fbm, sampling, w.zero_mean) {
                Ok(n) => *w = n,
                Err(e) => self.notices.status = e.to_string(),
            }
        }
    }

    /// Export size and the Export, Open and Save buttons.
    fn export_and_files(&mut self, ui: &mut egui::Ui) -> Option<EscapeRequest> {
        let mut req = None;
        ui.horizontal(|ui| {
            ui.label("Export size");
            named(
                ui.add(egui::DragValue::new(&mut self.export_size[0]).range(16..=20000)),
                "Export width",
            )
            .on_hover_text("width of the exported picture in pixels");
            ui.label("×");
            named(
                ui.add(egui::DragValue::new(&mut self.export_size[1]).range(16..=20000)),
                "Export height",
            )
            .on_hover_text("height of the exported picture in pixels");
        });
        ui.horizontal(|ui| {
            if ui
                .button("Export image…")
                .on_hover_text("render the view at the export size (PNG keeps the view)")
                .clicked()
            {
                req = Some(EscapeRequest::Export);
            }
            if ui
                .button("Open view…")
                .on_hover_text("open a view file (.esc)")
                .clicked()
            {
                req = Some(EscapeRequest::OpenView);
            }
            if ui
                .button("Save view…")
                .on_hover_text("save this view as a .esc file")
                .clicked()
            {
                req = Some(EscapeRequest::SaveView);
            }
        });
        req
    }
}

/// A row "Power m" for z^m + c.
fn power_row(ui: &mut egui::Ui, power: &mut u32) {
    let l = ui.label("Power m");
    ui.add(egui::DragValue::new(power).range(2..=9))
        .labelled_by(l.id)
        .on_hover_text("the power of z in z^m + c");
    ui.end_row();
}

/// A row for a complex number: real and imaginary part.
fn complex_row(ui: &mut egui::Ui, label: &str, c: &mut C) {
    ui.label(label);
    ui.horizontal(|ui| {
        named(
            ui.add(egui::DragValue::new(&mut c.re).speed(0.001).max_decimals(8)),
            &format!("{label} real part"),
        )
        .on_hover_text("real part");
        named(
            ui.add(egui::DragValue::new(&mut c.im).speed(0.001).max_decimals(8)),
            &format!("{label} imaginary part"),
        )
        .on_hover_text("imaginary part");
        ui.label("i");
    });
    ui.end_row();
}

/// The rows every family shares: iterations, colouring, gradient, offset, repeat and block
/// guessing.
fn colour_params(ui: &mut egui::Ui, doc: &mut escape_view::EscapeDoc) {
    ui.label("Colouring");
    let r = egui::ComboBox::from_id_salt("escape-coloring")
        .selected_text(doc.params.coloring.name())
        .show_ui(ui, |ui| {
            for c in Coloring::ALL {
                ui.selectable_value(&mut doc.params.coloring, c, c.name());
            }
        });
    named(r.response, "Colouring").on_hover_text("how escape counts become colours");
    ui.end_row();
    ui.label("Gradient");
    let r = egui::ComboBox::from_id_salt("escape-gradient")
        .selected_text(doc.gradient_source.clone())
        .show_ui(ui, |ui| {
            for g in gradient::builtin() {
                if ui
                    .selectable_label(doc.gradient_source == g.name, &g.name)
                    .clicked()
                {
                    doc.gradient_source = g.name.clone();
                    doc.params.palette.gradient = g;
                }
            }
        });
    named(r.response, "Gradient").on_hover_text("the colours of the picture");
    ui.end_row();
    let l = ui.label("Offset");
    ui.add(
        egui::Slider::new(&mut doc.params.palette.offset, 0.0..=1.0)
            .clamping(egui::SliderClamping::Edits),
    )
    .labelled_by(l.id)
    .on_hover_text("shift the colours along the gradient");
    ui.end_row();
    let l = ui.label("Repeat");
    ui.add(
        egui::DragValue::new(&mut doc.params.palette.repeat)
            .range(0.01..=256.0)
            .clamp_existing_to_range(false)
            .speed(0.05),
    )
    .labelled_by(l.id)
    .on_hover_text("how many times the gradient repeats");
    ui.end_row();
    let l = ui.label("Block guessing");
    let mut guess = doc.params.fill == Fill::Guess;
    ui.checkbox(&mut guess, "")
        .labelled_by(l.id)
        .on_hover_text("Mariani–Silver: faster, may miss thin filaments");
    doc.params.fill = if guess { Fill::Guess } else { Fill::Exact };
    ui.end_row();
}
