//! The numeric panels of the selected transform: its triangle (or post triangle) and
//! coefficients, weight and colour, and its variations.

use eframe::egui;

use super::document::Document;
use super::triangles::{EditorState, Selected, xform_of, xform_of_mut};
use crate::app::a11y::named;
use crate::flame::variations::{self, Form, VarId};
use crate::flame::{Affine, Var};

/// A numeric field with an accessible name; returns true when changed.
fn num(ui: &mut egui::Ui, v: &mut f64, speed: f64, name: &str) -> bool {
    named(
        ui.add(egui::DragValue::new(v).speed(speed).max_decimals(6)),
        name,
    )
    .changed()
}

/// A slider without its own number, and a named number beside it.
fn slider(ui: &mut egui::Ui, v: &mut f64, name: &str) {
    ui.horizontal(|ui| {
        named(
            ui.add(egui::Slider::new(v, 0.0..=1.0).show_value(false)),
            name,
        );
        named(
            ui.add(egui::DragValue::new(v).range(0.0..=1.0).speed(0.005)),
            name,
        );
    });
}

/// The numeric panels of the selected xform. Returns true when the flame changed.
pub fn panels(
    ui: &mut egui::Ui,
    doc: &mut Document,
    st: &mut EditorState,
    auto_weights: bool,
) -> bool {
    st.fix_selection(doc.flame());
    let sel = st.selected;
    let Some(x0) = xform_of(doc.flame(), sel).cloned() else {
        ui.label("No transform selected");
        return false;
    };
    let mut x = x0.clone();
    let mut m = st.map_of(&x);
    let mut tri = m.triangle();
    let mut tri_changed = false;
    let mut coef_changed = false;
    egui::CollapsingHeader::new(if st.edit_post {
        "Post triangle"
    } else {
        "Triangle"
    })
    .default_open(true)
    .show(ui, |ui| {
        egui::Grid::new("tri-grid").num_columns(3).show(ui, |ui| {
            for (k, l) in ["A (O)", "B (X)", "C (Y)"].iter().enumerate() {
                ui.label(*l);
                tri_changed |= num(ui, &mut tri[k][0], 0.01, &format!("{} x", &l[..1]));
                tri_changed |= num(ui, &mut tri[k][1], 0.01, &format!("{} y", &l[..1]));
                ui.end_row();
            }
        });
        ui.label("Coefficients  x' = a·x + b·y + e,  y' = c·x + d·y + f");
        egui::Grid::new("coef-grid").num_columns(6).show(ui, |ui| {
            for (l, v) in [("a", &mut m.a), ("b", &mut m.b), ("e", &mut m.e)] {
                ui.label(l);
                coef_changed |= num(ui, v, 0.01, l);
            }
            ui.end_row();
            for (l, v) in [("c", &mut m.c), ("d", &mut m.d), ("f", &mut m.f)] {
                ui.label(l);
                coef_changed |= num(ui, v, 0.01, l);
            }
            ui.end_row();
        });
        ui.horizontal(|ui| {
            if ui.button("Reset").on_hover_text("identity map").clicked() {
                m = Affine::IDENTITY;
                coef_changed = true;
            }
            if ui.button("Flip H").clicked() {
                m = Affine::new(-1.0, 0.0, 0.0, 1.0, 0.0, 0.0).compose(&m);
                coef_changed = true;
            }
            if ui.button("Flip V").clicked() {
                m = Affine::new(1.0, 0.0, 0.0, -1.0, 0.0, 0.0).compose(&m);
                coef_changed = true;
            }
            ui.label(format!("det {:.4}", m.det()));
        });
    });
    if tri_changed {
        st.set_map(&mut x, Affine::from_triangle(tri));
    } else if coef_changed {
        st.set_map(&mut x, m);
    }
    egui::CollapsingHeader::new("Weight and colour")
        .default_open(true)
        .show(ui, |ui| {
            egui::Grid::new("wc-grid").num_columns(2).show(ui, |ui| {
                if sel != Selected::Final {
                    let l = ui.label("Weight");
                    ui.add_enabled(
                        !auto_weights,
                        egui::DragValue::new(&mut x.weight)
                            .speed(0.01)
                            .range(0.0..=1e6),
                    )
                    .labelled_by(l.id)
                    .on_disabled_hover_text(
                        "weights follow the triangle areas (Options › General)",
                    );
                    ui.end_row();
                }
                ui.label("Colour");
                slider(ui, &mut x.color, "Colour");
                ui.end_row();
                ui.label("Colour speed");
                slider(ui, &mut x.color_speed, "Colour speed");
                ui.end_row();
                ui.label("Opacity");
                slider(ui, &mut x.opacity, "Opacity");
                ui.end_row();
            });
        });
    egui::CollapsingHeader::new("Variations")
        .default_open(true)
        .show(ui, |ui| {
            ui.horizontal(|ui| {
                let l = ui.label("Find");
                ui.text_edit_singleline(&mut st.var_filter)
                    .labelled_by(l.id);
                ui.checkbox(&mut st.show_all_vars, "all");
                if ui
                    .button("Normalise")
                    .on_hover_text("divide the weights by their sum")
                    .clicked()
                {
                    let s: f64 = x.vars.iter().map(|v| v.weight).sum();
                    if s != 0.0 {
                        for v in &mut x.vars {
                            v.weight /= s;
                        }
                    }
                }
            });
            let filter = st.var_filter.trim().to_ascii_lowercase();
            // The variations in use first (every form), then the others that match the Find
            // box — all of them when "all" is ticked.
            let mut rows: Vec<(VarId, Form)> = x.vars.iter().map(|v| (v.id, v.form)).collect();
            if st.show_all_vars || !filter.is_empty() {
                for id in 0..variations::count() as VarId {
                    let info = variations::info(id);
                    if info.has(variations::flag::HIDDEN) {
                        continue;
                    }
                    for form in [Form::Regular, Form::Pre, Form::Post] {
                        if info.has(variations::flag::POST_ONLY) && form != Form::Post {
                            continue;
                        }
                        let name = variations::attr_name(id, form);
                        if (filter.is_empty() || name.to_ascii_lowercase().contains(&filter))
                            && !rows.contains(&(id, form))
                        {
                            rows.push((id, form));
                        }
                    }
                }
            }
            egui::ScrollArea::vertical()
                .max_height(320.0)
                .id_salt("var-scroll")
                .show(ui, |ui| {
                    egui::Grid::new("var-grid")
                        .num_columns(2)
                        .striped(true)
                        .show(ui, |ui| {
                            for &(id, form) in rows.iter().take(400) {
                                let info = variations::info(id);
                                let pos = x.vars.iter().position(|v| v.id == id && v.form == form);
                                let mut w = pos.map_or(0.0, |i| x.vars[i].weight);
                                let name = variations::attr_name(id, form);
                                ui.label(&name);
                                if num(ui, &mut w, 0.01, &name) {
                                    match pos {
                                        Some(i) => x.vars[i].weight = w,
                                        None if w != 0.0 => {
                                            x.vars.push(Var::with_form(id, form, w));
                                        }
                                        None => {}
                                    }
                                    x.vars.retain(|v| v.weight != 0.0);
                                }
                                ui.end_row();
                                if let Some(v) =
                                    x.vars.iter_mut().find(|v| v.id == id && v.form == form)
                                {
                                    for pi in 0..info.params.len() {
                                        let pn = variations::param_attr_name(id, form, pi);
                                        ui.label(format!("    {pn}"));
                                        num(ui, &mut v.params[pi], 0.01, &pn);
                                        ui.end_row();
                                    }
                                }
                            }
                            if rows.len() > 400 {
                                ui.label(format!(
                                    "… {} more: type in Find to narrow the list",
                                    rows.len() - 400
                                ));
                                ui.end_row();
                            }
                        });
                });
            for (n, w) in x.unsupported_vars() {
                ui.label(format!("{n} = {w} (kept, not rendered)"));
            }
        });
    if x != x0 {
        let geometry = x.coefs != x0.coefs;
        doc.edit(|f| {
            if let Some(t) = xform_of_mut(f, sel) {
                *t = x;
            }
            if auto_weights && geometry && sel != Selected::Final {
                f.set_determinant_weights();
            }
        });
        return true;
    }
    false
}
