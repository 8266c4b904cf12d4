//! The gradient window: the library (built-in gradients and loaded files), a preview strip,
//! rotate/shift, reverse, random gradients; choosing one recolours the preview at once.

use eframe::egui::{self, Color32, Rect, Sense, Vec2};

use crate::flame::rng::FastRng;
use crate::gradient::{Gradient, Stop};

/// Gradient window state.
pub struct GradientWindow {
    pub open: bool,
    /// The library: built-ins first, then loaded gradients.
    pub library: Vec<Gradient>,
    pub filter: String,
    pub shift: i32,
    rng: FastRng,
}

/// What the user asked for.
pub enum GradientAction {
    /// Use this gradient for the current flame.
    Apply(Gradient),
    Load,
    FromImage,
    /// Open the palette editor.
    Edit,
}

impl Default for GradientWindow {
    fn default() -> Self {
        GradientWindow {
            open: false,
            library: crate::gradient::builtin(),
            filter: String::new(),
            shift: 0,
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
    /// Show the window; `current` is the current flame's palette.
    pub fn show(&mut self, ctx: &egui::Context, current: &Gradient) -> Option<GradientAction> {
        let mut action = None;
        let mut open = self.open;
        let screen = ctx.content_rect();
        egui::Window::new("Gradient")
            .open(&mut open)
            .default_size([360.0, 480.0])
            .default_pos([screen.right() - 400.0, screen.top() + 80.0])
            .show(ctx, |ui| {
                ui.label(format!(
                    "Current: {}",
                    if current.name.is_empty() {
                        "(unnamed)"
                    } else {
                        &current.name
                    }
                ));
                strip(ui, current, Vec2::new(ui.available_width(), 28.0));
                ui.horizontal(|ui| {
                    let l = ui.label("Rotate");
                    let r = ui
                        .add(egui::Slider::new(&mut self.shift, -128..=128).show_value(false))
                        .labelled_by(l.id)
                        .on_hover_text("shift the colours along the gradient (release to apply)");
                    if r.drag_stopped() || (r.changed() && !r.dragged()) {
                        let mut g = current.rotated(self.shift);
                        g.name = current.name.clone();
                        self.shift = 0;
                        action = Some(GradientAction::Apply(g));
                    }
                });
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
                        .button("Edit…")
                        .on_hover_text("the palette editor: keys, adjustments, curves")
                        .clicked()
                    {
                        action = Some(GradientAction::Edit);
                    }
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
            });
        self.open = open;
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
