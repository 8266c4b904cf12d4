//! The transform list: every transform with its name, on/off switch, colour, weight and the
//! variations it uses; a click selects, the arrows reorder (the xaos matrix follows), the
//! switch takes a transform out of the picture and back.

use eframe::egui::{self, Color32, Sense, Vec2};

use super::editor_state::{Selected, TRIANGLE_COLORS};
use crate::flame::variations;
use crate::flame::{Flame, Xform};

/// The name a transform shows: its `name` attribute (Apophysis writes one) or its number.
pub fn xform_name(x: &Xform, i: usize) -> String {
    x.extra_attrs
        .iter()
        .find(|(k, _)| k == "name")
        .map(|(_, v)| v.clone())
        .filter(|v| !v.is_empty())
        .unwrap_or_else(|| format!("Transform {}", i + 1))
}

/// Set (or clear, with an empty string) a transform's `name` attribute.
pub fn set_xform_name(x: &mut Xform, name: &str) {
    x.extra_attrs.retain(|(k, _)| k != "name");
    if !name.trim().is_empty() {
        x.extra_attrs.push(("name".into(), name.trim().to_string()));
    }
}

/// Swap transforms `i` and `j`, with their rows and columns of the xaos matrix.
pub fn swap_xforms(f: &mut Flame, i: usize, j: usize) {
    let n = f.xforms.len();
    if i >= n || j >= n || i == j {
        return;
    }
    f.xforms.swap(i, j);
    for x in &mut f.xforms {
        if x.chaos.len() <= i.max(j) && x.chaos.iter().all(|&c| c == 1.0) {
            continue;
        }
        if x.chaos.len() < n {
            x.chaos.resize(n, 1.0);
        }
        x.chaos.swap(i, j);
    }
}

/// What the user did in the list.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ListAction {
    Select(Selected),
    MoveUp(usize),
    MoveDown(usize),
    /// Switch transform i on (true) or off.
    Toggle(usize, bool),
}

fn swatch(ui: &mut egui::Ui, c: Color32, size: Vec2, tip: &str) {
    let (r, resp) = ui.allocate_exact_size(size, Sense::hover());
    ui.painter().rect_filled(r, 2.0, c);
    resp.on_hover_text(tip);
}

/// Draw the list; returns what the user asked for.
pub fn list(ui: &mut egui::Ui, f: &Flame, selected: Selected) -> Option<ListAction> {
    let mut action = None;
    let n = f.xforms.len();
    let rows: Vec<(Selected, &Xform)> = f
        .xforms
        .iter()
        .enumerate()
        .map(|(i, x)| (Selected::Xform(i), x))
        .chain(f.final_xform.iter().map(|x| (Selected::Final, x)))
        .collect();
    egui::Grid::new("xform-list")
        .num_columns(6)
        .striped(true)
        .show(ui, |ui| {
            ui.label("");
            ui.label("");
            ui.strong("Transform");
            ui.strong("Weight");
            ui.strong("Variations");
            ui.label("");
            ui.end_row();
            for (sel, x) in rows {
                let (i, tri) = match sel {
                    Selected::Xform(i) => (i, TRIANGLE_COLORS[i % TRIANGLE_COLORS.len()]),
                    Selected::Final => (n, Color32::WHITE),
                };
                let mut on = x.weight > 0.0 || sel == Selected::Final;
                let r = ui.add_enabled(
                    sel != Selected::Final,
                    egui::Checkbox::without_text(&mut on),
                );
                if r.changed() {
                    action = Some(ListAction::Toggle(i, on));
                }
                r.on_hover_text("on: the transform is drawn; off: weight 0 (switch on to restore)");
                let [cr, cg, cb] = f.palette.rgb8(((x.color.clamp(0.0, 1.0)) * 255.0) as usize);
                ui.horizontal(|ui| {
                    swatch(
                        ui,
                        tri,
                        Vec2::new(6.0, 16.0),
                        "triangle colour in the editor",
                    );
                    swatch(
                        ui,
                        Color32::from_rgb(cr, cg, cb),
                        Vec2::new(16.0, 16.0),
                        "the transform's colour in the gradient",
                    );
                });
                let name = match sel {
                    Selected::Final => "Final".to_string(),
                    _ => xform_name(x, i),
                };
                if ui.selectable_label(sel == selected, name).clicked() {
                    action = Some(ListAction::Select(sel));
                }
                if sel == Selected::Final {
                    ui.label("—");
                } else {
                    ui.label(format!("{:.3}", x.weight));
                }
                let vars: Vec<String> = x
                    .vars
                    .iter()
                    .map(|v| variations::attr_name(v.id, v.form))
                    .collect();
                let text = vars.join(", ");
                let short = if text.chars().count() > 28 {
                    format!("{}…", text.chars().take(27).collect::<String>())
                } else {
                    text.clone()
                };
                ui.label(short).on_hover_text(text);
                ui.horizontal(|ui| {
                    if sel != Selected::Final {
                        if ui
                            .add_enabled(i > 0, egui::Button::new("Up").small())
                            .on_hover_text("move up")
                            .clicked()
                        {
                            action = Some(ListAction::MoveUp(i));
                        }
                        if ui
                            .add_enabled(i + 1 < n, egui::Button::new("Down").small())
                            .on_hover_text("move down")
                            .clicked()
                        {
                            action = Some(ListAction::MoveDown(i));
                        }
                    }
                });
                ui.end_row();
            }
        });
    action
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn swapping_moves_the_xaos_rows_and_columns() {
        let mut f = Flame::default();
        for k in 0..3 {
            f.xforms.push(Xform {
                color: k as f64,
                chaos: vec![
                    10.0 * k as f64,
                    10.0 * k as f64 + 1.0,
                    10.0 * k as f64 + 2.0,
                ],
                ..Default::default()
            });
        }
        let before = f.clone();
        swap_xforms(&mut f, 0, 2);
        // Entry (from a, to b) moves to (from σa, to σb).
        let s = |k: usize| [2, 1, 0][k];
        for a in 0..3 {
            for b in 0..3 {
                assert_eq!(f.xforms[s(a)].chaos[s(b)], before.xforms[a].chaos[b]);
            }
            assert_eq!(f.xforms[s(a)].color, before.xforms[a].color);
        }
        swap_xforms(&mut f, 2, 0);
        assert_eq!(f, before);
        let mut x = Xform::default();
        set_xform_name(&mut x, "wing");
        assert_eq!(xform_name(&x, 0), "wing");
        set_xform_name(&mut x, "");
        assert_eq!(xform_name(&x, 4), "Transform 5");
    }
}
