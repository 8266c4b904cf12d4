//! The gradient window, one window with two pages: the library (built-in gradients and loaded
//! files, a preview strip, rotate, reverse, random gradients; choosing one recolours the
//! preview at once) and the palette editor (`palette_editor.rs`).

use eframe::egui::{self, Color32, Rect, Sense, Vec2};

use super::document::Document;
use super::palette_editor::PaletteEditor;
use crate::app::a11y::named;
use crate::flame::rng::FastRng;
use crate::gradient::{Gradient, Stop};

/// Gradient window state.
pub struct GradientWindow {
    pub open: bool,
    /// The library: built-ins first, then loaded gradients.
    pub library: Vec<Gradient>,
    pub filter: String,
    /// The rotation shown on the Rotate slider, in palette entries, relative to `rotate_base`.
    pub shift: i32,
    /// The palette the rotation started from (none: no rotation under way).
    rotate_base: Option<Gradient>,
    rng: FastRng,
}

/// What the user asked for.
pub enum GradientAction {
    /// Use this gradient for the current flame.
    Apply(Gradient),
    Load,
    FromImage,
}

impl Default for GradientWindow {
    fn default() -> Self {
        GradientWindow {
            open: false,
            library: crate::gradient::builtin(),
            filter: String::new(),
            shift: 0,
            rotate_base: None,
            rng: FastRng::new(0x5eed),
        }
    }
}

/// Paint a gradient as a strip.
pub fn strip(ui: &mut egui::Ui, g: &Gradient, size: Vec2) -> egui::Response {
    let (rect, resp) = ui.allocate_exact_size(size, Sense::click());
    let p = ui.painter_at(rect);
    let n = g.colors.len().max(1);
    let w = rect.width() / n as f32;
    for (i, c) in g.colors.iter().enumerate() {
        let [r, gg, b] = g.rgb8(i);
        let _ = c;
        let x = rect.left() + i as f32 * w;
        p.rect_filled(
            Rect::from_min_max(
                egui::pos2(x, rect.top()),
                egui::pos2(x + w + 0.5, rect.bottom()),
            ),
            0.0,
            Color32::from_rgb(r, gg, b),
        );
    }
    resp
}

/// A random gradient: 3–6 random keys, darker first.
pub fn random_gradient(rng: &mut FastRng) -> Gradient {
    let n = 3 + rng.below(4) as usize;
    let mut stops: Vec<Stop> = (0..n)
        .map(|i| {
            let h = rng.f01() * 6.0;
            let s = 0.3 + 0.7 * rng.f01();
            let v = 0.2 + 0.8 * (i as f64 / (n - 1) as f64) * (0.6 + 0.4 * rng.f01());
            Stop {
                pos: i as f64 / (n - 1) as f64,
                rgb: crate::gradient::hsv_to_rgb([h, s, v]),
            }
        })
        .collect();
    stops[0].rgb = stops[0].rgb.map(|v| v * 0.3);
    let mut g = Gradient::from_stops("random", &stops);
    for c in &mut g.colors {
        for v in c.iter_mut().take(3) {
            *v = (*v * 255.0).round() / 255.0;
        }
    }
    g
}

impl GradientWindow {
    /// Show the window (library or palette editor page) while either is open; changes go to
    /// `doc`'s current flame (`dragging`: a pointer is held, a drag is one undo step).
    pub fn show(
        &mut self,
        ctx: &egui::Context,
        doc: &mut Document,
        editor: &mut PaletteEditor,
        dragging: bool,
    ) -> Option<GradientAction> {
        if !(self.open || editor.open) {
            editor.open = false;
            editor.forget();
            return None;
        }
        let mut action = None;
        let mut open = true;
        let screen = ctx.content_rect();
        egui::Window::new("Gradient")
            .open(&mut open)
            .default_size([380.0, 520.0])
            .default_pos([screen.right() - 420.0, screen.top() + 80.0])
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
                    let mut editing = editor.open;
                    ui.selectable_value(&mut editing, false, "Library")
                        .on_hover_text("the gradients to choose from (Ctrl+G)");
                    ui.selectable_value(&mut editing, true, "Editor")
                        .on_hover_text("keys, adjustments and curves (Ctrl+Shift+G)");
                    editor.open = editing;
                });
                ui.separator();
                if editor.open {
                    editor.ui(ui, doc, dragging);
                } else {
                    action = self.library_ui(ui, doc, dragging);
                }
            });
        if !open {
            self.open = false;
            editor.open = false;
        } else {
            self.open = true;
        }
        if !editor.open {
            editor.forget();
        }
        action
    }

    /// The Rotate slider: turns the palette live while it is dragged (one undo step), and
    /// shows by how many entries it is turned.
    fn rotate_ui(&mut self, ui: &mut egui::Ui, doc: &mut Document, dragging: bool) {
        let current = doc.flame().palette.clone();
        // The palette changed elsewhere: a new rotation starts from it.
        if self
            .rotate_base
            .as_ref()
            .is_none_or(|b| b.rotated(self.shift).colors != current.colors)
        {
            self.rotate_base = None;
            self.shift = 0;
        }
        ui.horizontal(|ui| {
            let l = ui.label("Rotate");
            let r = ui
                .add(
                    egui::Slider::new(&mut self.shift, -128..=128)
                        .suffix(" entries")
                        .clamping(egui::SliderClamping::Always),
                )
                .labelled_by(l.id)
                .on_hover_text("shift the colours along the gradient; the preview follows");
            if r.changed() {
                let base = self.rotate_base.get_or_insert_with(|| current.clone());
                let mut g = base.rotated(self.shift);
                g.name = base.name.clone();
                doc.edit_while(dragging, |f| f.palette = g);
            }
        });
    }

    /// The library page.
    fn library_ui(
        &mut self,
        ui: &mut egui::Ui,
        doc: &mut Document,
        dragging: bool,
    ) -> Option<GradientAction> {
        let mut action = None;
        let current = doc.flame().palette.clone();
        ui.label(format!(
            "Current: {}",
            if current.name.is_empty() {
                "(unnamed)"
            } else {
                &current.name
            }
        ));
        named(
            strip(ui, &current, Vec2::new(ui.available_width(), 28.0)),
            "Current gradient",
        );
        self.rotate_ui(ui, doc, dragging);
        ui.horizontal(|ui| {
            if ui
                .button("Reverse")
                .on_hover_text("the colours in the opposite order")
                .clicked()
            {
                let mut g = current.reversed();
                g.name = current.name.clone();
                action = Some(GradientAction::Apply(g));
            }
            if ui
                .button("Random")
                .on_hover_text("a new random gradient")
                .clicked()
            {
                action = Some(GradientAction::Apply(random_gradient(&mut self.rng)));
            }
            if ui
                .button("Random from library")
                .on_hover_text("one of the gradients below, at random")
                .clicked()
                && !self.library.is_empty()
            {
                let k = self.rng.below(self.library.len() as u64) as usize;
                action = Some(GradientAction::Apply(self.library[k].clone()));
            }
        });
        ui.horizontal(|ui| {
            if ui
                .button("Load…")
                .on_hover_text("add gradients from a .ugr, .map or .ggr file")
                .clicked()
            {
                action = Some(GradientAction::Load);
            }
            if ui
                .button("From image…")
                .on_hover_text("make a gradient from the colours of a picture")
                .clicked()
            {
                action = Some(GradientAction::FromImage);
            }
        });
        ui.horizontal(|ui| {
            let l = ui.label("Find");
            ui.text_edit_singleline(&mut self.filter)
                .labelled_by(l.id)
                .on_hover_text("part of a gradient's name");
        });
        ui.separator();
        egui::ScrollArea::vertical().show(ui, |ui| {
            for g in &self.library {
                if !self.filter.is_empty()
                    && !g.name.to_lowercase().contains(&self.filter.to_lowercase())
                {
                    continue;
                }
                ui.horizontal(|ui| {
                    let r = strip(ui, g, Vec2::new(200.0, 16.0));
                    let l = ui.selectable_label(g.name == current.name, &g.name);
                    if r.clicked() || l.clicked() {
                        action = Some(GradientAction::Apply(g.clone()));
                    }
                });
            }
        });
        action
    }

    /// Add loaded gradients to the library (replacing same-named ones).
    pub fn add(&mut self, gs: Vec<Gradient>) {
        for g in gs {
            self.library.retain(|h| h.name != g.name);
            self.library.push(g);
        }
    }
}
