//! The palette editor, the Editor page of the gradient window (Fractorium's Palette tab and
//! curves): key colours on a strip (drag a key to move it, click to pick its colour),
//! adjustments (hue, saturation, brightness, contrast, frequency, blur) and colour curves.
//! Every change recolours the preview at once; a drag is one undo step. A palette of 256
//! colours without keys is edited as keys fitted to reproduce it exactly.

use eframe::egui::{self, Color32, Pos2, Sense, Stroke, Vec2};

use super::document::Document;
use super::gradients::strip;
use crate::app::a11y::named;
use crate::gradient::{Gradient, Stop};
use crate::palette::{self, Adjust, Curve, Curves, MAX_BLUR, MAX_FREQUENCY};

/// Which curve the plot edits.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Channel {
    #[default]
    All,
    Red,
    Green,
    Blue,
}

/// Palette editor state.
#[derive(Default)]
pub struct PaletteEditor {
    pub open: bool,
    /// The keys the palette is built from; none: the palette as it came (256 colours).
    pub keys: Option<Vec<Stop>>,
    /// The palette when editing started.
    original: Gradient,
    pub adjust: Adjust,
    pub curves: Curves,
    pub channel: Channel,
    selected_key: usize,
    dragged_key: Option<usize>,
    dragged_point: Option<usize>,
    /// The palette this editor last produced (anything else on the flame means it was
    /// changed elsewhere: start again from it).
    produced: Option<Gradient>,
    name: String,
}

impl PaletteEditor {
    /// Start editing `g`: its keys (if it was built from keys), no adjustments, straight
    /// curves.
    pub fn start_from(&mut self, g: &Gradient) {
        self.keys = (g.stops.len() >= 2).then(|| g.stops.clone());
        self.original = g.clone();
        self.adjust = Adjust::default();
        self.curves = Curves::default();
        self.selected_key = 0;
        self.name = g.name.clone();
        self.produced = Some(g.clone());
    }

    /// The palette the editor's settings give.
    pub fn result(&self) -> Gradient {
        let base = match &self.keys {
            Some(k) => palette::from_keys(&self.name, k),
            None => self.original.clone(),
        };
        palette::apply_curves(&palette::adjust(&base, &self.adjust), &self.curves)
    }

    fn curve_mut(&mut self) -> &mut Curve {
        match self.channel {
            Channel::All => &mut self.curves.all,
            Channel::Red => &mut self.curves.red,
            Channel::Green => &mut self.curves.green,
            Channel::Blue => &mut self.curves.blue,
        }
    }

    /// Forget what the editor made (the window was closed: the next opening starts from the
    /// flame's palette as it is then).
    pub fn forget(&mut self) {
        self.produced = None;
    }

    /// The editor's page; changes go to the current flame's palette.
    pub fn ui(&mut self, ui: &mut egui::Ui, doc: &mut Document, dragging: bool) {
        let current = doc.flame().palette.clone();
        // Keys built from 256 exact colours, and an untouched start, reproduce the palette;
        // anything the editor did not make starts a new edit.
        let from_elsewhere = match &self.produced {
            Some(p) => p.colors != current.colors,
            None => true,
        };
        if from_elsewhere {
            self.start_from(&current);
        }
        let before = (self.keys.clone(), self.adjust, self.curves.clone());
        ui.set_width(340.0);
        strip(ui, &current, Vec2::new(340.0, 24.0));
        ui.separator();
        self.keys_ui(ui);
        ui.separator();
        self.adjust_ui(ui);
        ui.separator();
        self.curves_ui(ui);
        let changed = (self.keys.clone(), self.adjust, self.curves.clone()) != before;
        if changed {
            let g = self.result();
            self.produced = Some(g.clone());
            doc.edit_while(dragging, |f| f.palette = g);
        }
    }

    fn keys_ui(&mut self, ui: &mut egui::Ui) {
        ui.strong("Keys");
        let Some(keys) = &self.keys else {
            ui.horizontal(|ui| {
                ui.label("This palette has 256 colours and no keys.");
                if ui
                    .button("Edit as keys")
                    .on_hover_text(
                        "keys placed where the colours turn, as many as reproduce the palette \
                         exactly (the colours do not change until a key is edited)",
                    )
                    .clicked()
                {
                    self.keys = Some(fit_keys(&self.original));
                }
            });
            return;
        };
        let preview = palette::from_keys(&self.name, keys);
        let size = Vec2::new(340.0, 20.0);
        strip(ui, &preview, size);
        // Key handles below the strip: drag to move, click to select.
        let (rect, resp) = ui.allocate_exact_size(Vec2::new(size.x, 14.0), Sense::click_and_drag());
        let x_of = |pos: f64| rect.left() + pos as f32 * rect.width();
        let p = ui.painter_at(rect);
        let keys = self.keys.get_or_insert_with(Vec::new);
        for (k, s) in keys.iter().enumerate() {
            let x = x_of(s.pos);
            let col = Color32::from_rgb(
                (s.rgb[0] * 255.0) as u8,
                (s.rgb[1] * 255.0) as u8,
                (s.rgb[2] * 255.0) as u8,
            );
            let tri = vec![
                Pos2::new(x, rect.top()),
                Pos2::new(x - 6.0, rect.bottom()),
                Pos2::new(x + 6.0, rect.bottom()),
            ];
            let stroke = if k == self.selected_key {
                Stroke::new(2.0, Color32::WHITE)
            } else {
                Stroke::new(1.0, Color32::GRAY)
            };
            p.add(egui::Shape::convex_polygon(tri, col, stroke));
        }
        let nearest = |x: f32, keys: &[Stop]| {
            keys.iter()
                .enumerate()
                .min_by(|a, b| {
                    (x_of(a.1.pos) - x)
                        .abs()
                        .total_cmp(&(x_of(b.1.pos) - x).abs())
                })
                .map(|(k, _)| k)
        };
        if (resp.clicked() || resp.drag_started())
            && let Some(pos) = resp.interact_pointer_pos()
            && let Some(k) = nearest(pos.x, keys)
        {
            self.selected_key = k;
            self.dragged_key = resp.drag_started().then_some(k);
        }
        if resp.dragged()
            && let (Some(k), Some(pos)) = (self.dragged_key, resp.interact_pointer_pos())
            && let Some(s) = keys.get_mut(k)
        {
            s.pos = ((pos.x - rect.left()) / rect.width()).clamp(0.0, 1.0) as f64;
        }
        if resp.drag_stopped() {
            self.dragged_key = None;
        }
        named(resp, "palette keys").on_hover_text("drag a key to move it; click to choose it");
        self.selected_key = self.selected_key.min(keys.len().saturating_sub(1));
        let mut add = false;
        ui.horizontal(|ui| {
            if let Some(s) = keys.get_mut(self.selected_key) {
                let l = ui.label("Key");
                let mut c = [s.rgb[0] as f32, s.rgb[1] as f32, s.rgb[2] as f32];
                if ui
                    .color_edit_button_rgb(&mut c)
                    .on_hover_text("the key's colour")
                    .changed()
                {
                    s.rgb = c.map(|v| v as f64);
                }
                ui.add(
                    egui::DragValue::new(&mut s.pos)
                        .range(0.0..=1.0)
                        .speed(0.002)
                        .max_decimals(3),
                )
                .labelled_by(l.id)
                .on_hover_text("the key's position along the palette (0 … 1)");
            }
            if ui
                .button("Add")
                .on_hover_text("a new key in the middle of the widest gap")
                .clicked()
            {
                add = true;
            }
            if ui
                .add_enabled(keys.len() > 2, egui::Button::new("Remove"))
                .on_hover_text("remove the chosen key (at least two stay)")
                .clicked()
            {
                keys.remove(self.selected_key);
            }
            if ui
                .button("Even")
                .on_hover_text("space the keys evenly")
                .clicked()
            {
                let n = keys.len().max(2);
                keys.sort_by(|a, b| a.pos.total_cmp(&b.pos));
                for (k, s) in keys.iter_mut().enumerate() {
                    s.pos = k as f64 / (n - 1) as f64;
                }
            }
        });
        if add {
            self.add_key();
        }
    }

    fn add_key(&mut self) {
        let Some(keys) = &mut self.keys else {
            return;
        };
        let mut k = keys.clone();
        k.sort_by(|a, b| a.pos.total_cmp(&b.pos));
        let g = palette::from_keys("", &k);
        let (mut best, mut at) = (0.0, 0.5);
        for w in k.windows(2) {
            if w[1].pos - w[0].pos > best {
                best = w[1].pos - w[0].pos;
                at = (w[0].pos + w[1].pos) / 2.0;
            }
        }
        // On a palette entry, so that the new key takes that entry's colour exactly and the
        // palette does not change.
        let i = (at * 255.0).round() as usize;
        let c = g.colors[i];
        keys.push(Stop {
            pos: i as f64 / 255.0,
            rgb: [c[0], c[1], c[2]],
        });
        self.selected_key = keys.len() - 1;
    }

    fn adjust_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.strong("Adjust");
            if ui
                .small_button("Reset")
                .on_hover_text("no adjustments")
                .clicked()
            {
                self.adjust = Adjust::default();
            }
        });
        let a = &mut self.adjust;
        egui::Grid::new("palette-adjust")
            .num_columns(2)
            .show(ui, |ui| {
                let row =
                    |ui: &mut egui::Ui, label: &str, tip: &str, v: &mut f64, r: (f64, f64)| {
                        let l = ui.label(label);
                        ui.add(
                            egui::DragValue::new(v)
                                .range(r.0..=r.1)
                                .speed(0.005)
                                .max_decimals(3),
                        )
                        .labelled_by(l.id)
                        .on_hover_text(tip);
                        ui.end_row();
                    };
                row(
                    ui,
                    "Hue",
                    "turns of the colour wheel",
                    &mut a.hue,
                    (-1.0, 1.0),
                );
                row(
                    ui,
                    "Saturation",
                    "−1 grey … 1 vivid",
                    &mut a.saturation,
                    (-1.0, 1.0),
                );
                row(
                    ui,
                    "Brightness",
                    "−1 black … 1 white",
                    &mut a.brightness,
                    (-1.0, 1.0),
                );
                row(
                    ui,
                    "Contrast",
                    "−1 flat … 1 hard",
                    &mut a.contrast,
                    (-1.0, 0.98),
                );
                let l = ui.label("Frequency");
                ui.add(egui::DragValue::new(&mut a.frequency).range(1..=MAX_FREQUENCY))
                    .labelled_by(l.id)
                    .on_hover_text("repeat the palette this many times");
                ui.end_row();
                let l = ui.label("Blur");
                ui.add(egui::DragValue::new(&mut a.blur).range(0..=MAX_BLUR))
                    .labelled_by(l.id)
                    .on_hover_text("smooth over this many neighbouring entries");
                ui.end_row();
            });
    }

    fn curves_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.strong("Curves");
            for (c, l) in [
                (Channel::All, "All"),
                (Channel::Red, "Red"),
                (Channel::Green, "Green"),
                (Channel::Blue, "Blue"),
            ] {
                ui.selectable_value(&mut self.channel, c, l)
                    .on_hover_text(format!("edit the {} curve", l.to_lowercase()));
            }
            if ui
                .small_button("Straight")
                .on_hover_text("reset this curve")
                .clicked()
            {
                *self.curve_mut() = Curve::identity();
            }
        });
        let colour = match self.channel {
            Channel::All => Color32::WHITE,
            Channel::Red => Color32::from_rgb(255, 90, 90),
            Channel::Green => Color32::from_rgb(90, 230, 90),
            Channel::Blue => Color32::from_rgb(110, 140, 255),
        };
        let (rect, resp) = ui.allocate_exact_size(Vec2::new(200.0, 160.0), Sense::click_and_drag());
        let p = ui.painter_at(rect);
        p.rect_filled(rect, 2.0, Color32::from_gray(20));
        let to_screen = |q: [f64; 2]| {
            Pos2::new(
                rect.left() + q[0] as f32 * rect.width(),
                rect.bottom() - q[1] as f32 * rect.height(),
            )
        };
        let to_curve = |s: Pos2| {
            [
                ((s.x - rect.left()) / rect.width()).clamp(0.0, 1.0) as f64,
                ((rect.bottom() - s.y) / rect.height()).clamp(0.0, 1.0) as f64,
            ]
        };
        let curve = self.curve_mut().clone();
        let line: Vec<Pos2> = curve
            .table()
            .iter()
            .enumerate()
            .map(|(i, y)| to_screen([i as f64 / 255.0, *y]))
            .collect();
        p.add(egui::Shape::line(line, Stroke::new(1.5, colour)));
        for q in curve.points() {
            p.circle_stroke(to_screen(*q), 4.0, Stroke::new(1.5, colour));
        }
        let hit = |s: Pos2| {
            curve
                .points()
                .iter()
                .position(|q| to_screen(*q).distance(s) <= 8.0)
        };
        let mut pts = curve.points().to_vec();
        let mut changed = false;
        // The point under the press, not under the pointer once the drag is recognised (by
        // then it has left the point's hit radius).
        if resp.drag_started()
            && let Some(s) = ui
                .input(|i| i.pointer.press_origin())
                .or(resp.interact_pointer_pos())
        {
            self.dragged_point = hit(s);
        }
        if resp.dragged()
            && let (Some(k), Some(s)) = (self.dragged_point, resp.interact_pointer_pos())
            && k < pts.len()
        {
            pts[k] = to_curve(s);
            changed = true;
        }
        if resp.drag_stopped() {
            self.dragged_point = None;
        }
        if resp.clicked()
            && let Some(s) = resp.interact_pointer_pos()
            && hit(s).is_none()
        {
            pts.push(to_curve(s));
            changed = true;
        }
        if resp.secondary_clicked()
            && let Some(s) = resp.interact_pointer_pos()
            && let Some(k) = hit(s)
            && pts.len() > 2
        {
            pts.remove(k);
            changed = true;
        }
        named(resp, "colour curve").on_hover_text(
            "click to add a point, drag a point to move it, right-click a point to remove it",
        );
        if changed {
            *self.curve_mut() = Curve::new(&pts);
        }
    }
}

/// Keys that reproduce `g` to 8 bits: the first and last entry, then, while some entry's
/// 8-bit colour differs, a key on the entry that is farthest off (each key sits on an entry
/// with that entry's colour, so entries with a key are exact).
pub fn fit_keys(g: &Gradient) -> Vec<Stop> {
    let key = |i: usize| {
        let c = g.colors[i];
        Stop {
            pos: i as f64 / 255.0,
            rgb: [c[0], c[1], c[2]],
        }
    };
    let last = g.colors.len().saturating_sub(1).min(255);
    let mut keys = vec![key(0), key(last)];
    loop {
        let fit = palette::from_keys("", &keys);
        let worst = fit
            .colors
            .iter()
            .zip(&g.colors)
            .enumerate()
            // Entries whose 8-bit colour differs, the farthest off first.
            .filter(|(i, _)| fit.rgb8(*i) != g.rgb8(*i))
            .map(|(i, (a, b))| {
                let e = (0..3).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max);
                (i, e)
            })
            .max_by(|a, b| a.1.total_cmp(&b.1));
        match worst {
            Some((i, _)) => keys.push(key(i)),
            None => break,
        }
    }
    keys.sort_by(|a, b| a.pos.total_cmp(&b.pos));
    keys
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_untouched_editor_reproduces_the_palette_and_adding_a_key_keeps_the_colours() {
        // A palette without keys comes back exactly.
        let plain = crate::gradient::default_gradient().rotated(10);
        let mut e = PaletteEditor::default();
        e.start_from(&plain);
        assert!(e.keys.is_none());
        assert_eq!(e.result().colors, plain.colors);
        // As keys, the same colours to 8 bits, with fewer keys than entries for a smooth one.
        e.keys = Some(fit_keys(&plain));
        let k = e.keys.as_ref().unwrap().len();
        assert!((2..=256).contains(&k), "{k}");
        let r = e.result();
        for i in 0..256 {
            assert_eq!(r.rgb8(i), plain.rgb8(i), "entry {i}");
        }
        // A palette of random colours needs a key on nearly every entry, and still fits.
        let mut rng = crate::flame::rng::FastRng::new(4);
        let mut noisy = plain.clone();
        for c in &mut noisy.colors {
            for v in c.iter_mut().take(3) {
                *v = (rng.f01() * 255.0).round() / 255.0;
            }
        }
        let keys = fit_keys(&noisy);
        let fit = palette::from_keys("", &keys);
        assert!(fit.rgb8(100) == noisy.rgb8(100) && fit.rgb8(7) == noisy.rgb8(7));
        // A keyed palette is rebuilt from its keys (the built-ins are rounded to 8 bits).
        let g = crate::gradient::builtin_named("lagoon").unwrap();
        e.start_from(&g);
        assert!(e.keys.is_some());
        e.add_key();
        let r = e.result();
        for (a, b) in r.colors.iter().zip(&g.colors) {
            for k in 0..3 {
                assert!((a[k] - b[k]).abs() <= 0.5 / 255.0 + 1e-9, "{a:?} vs {b:?}");
            }
        }
    }
}
