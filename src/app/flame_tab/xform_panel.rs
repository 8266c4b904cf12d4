//! The numbers of the selected transform: name, triangle corners (y up, as in Apophysis),
//! coefficients as the file stores them, weight, colour, colour speed and opacity; and its
//! variations (see `variations_panel.rs`). A drag of any number or slider is one undo step.

use eframe::egui::{self, Color32, Sense, Vec2};

use super::document::Document;
use super::editor_state::{EditorState, Selected, xform_of, xform_of_mut};
use super::transform_list::{set_xform_name, xform_name};
use super::transform_tools;
use super::triangles::KeyedView;
use super::variations_panel;
use crate::app::a11y::named;
use crate::flame::keyframes::XformRef;
use crate::flame::shown_maps::set_shown_map;
use crate::flame::{Affine, Xform};

/// A named number; returns true when changed.
fn num(ui: &mut egui::Ui, v: &mut f64, name: &str, tip: &str) -> bool {
    named(
        ui.add(egui::DragValue::new(v).speed(0.01).max_decimals(6)),
        name,
    )
    .on_hover_text(tip)
    .changed()
}

/// A slider from 0 to 1 with a named number beside it.
fn unit_slider(ui: &mut egui::Ui, v: &mut f64, name: &str, tip: &str) {
    ui.horizontal(|ui| {
        named(
            ui.add(
                egui::Slider::new(v, 0.0..=1.0)
                    .show_value(false)
                    .clamping(egui::SliderClamping::Edits),
            ),
            name,
        )
        .on_hover_text(tip);
        named(
            ui.add(
                egui::DragValue::new(v)
                    .range(0.0..=1.0)
                    .clamp_existing_to_range(false)
                    .speed(0.005)
                    .max_decimals(4),
            ),
            name,
        )
        .on_hover_text(tip);
    });
}

/// The base transform `t` with the numbers of `x` (the transform as shown at a frame) other
/// than its maps and variations, which stay the base's.
fn numbers_on_base(t: &mut Xform, x: &Xform) -> Xform {
    Xform {
        coefs: t.coefs,
        post: t.post,
        vars: std::mem::take(&mut t.vars),
        ..x.clone()
    }
}

/// Apply an edited copy of the selected transform: one undo step per click, per typed value,
/// or per drag (`dragging`: a pointer is held). Triangle edits re-derive area weights when the
/// flame follows them.
fn apply(
    doc: &mut Document,
    sel: Selected,
    (x0, x): (&Xform, Xform),
    auto_weights: bool,
    dragging: bool,
    keyed: Option<KeyedView>,
) {
    let geometry = x0.coefs != x.coefs;
    doc.edit_while(dragging, |f| {
        match keyed {
            // The maps shown are the frame's: a changed one is keyed there or worked back
            // into the base; the other numbers are the base's (held at the frame).
            Some(k) => {
                let r = match sel {
                    Selected::Xform(i) => XformRef::Index(i),
                    Selected::Final => XformRef::Final,
                };
                if let Some(t) = xform_of_mut(f, sel) {
                    *t = numbers_on_base(t, &x);
                }
                if x.coefs != x0.coefs {
                    set_shown_map(f, r, false, k.frame, x.coefs, k.auto_key);
                }
                if x.post != x0.post {
                    set_shown_map(f, r, true, k.frame, x.post, k.auto_key);
                }
            }
            None => {
                if let Some(t) = xform_of_mut(f, sel) {
                    *t = x;
                }
            }
        }
        if auto_weights && geometry && sel != Selected::Final {
            f.set_determinant_weights();
        }
    });
}

/// The Triangle section: corners, coefficients, weight and colour.
pub fn triangle_section(
    ui: &mut egui::Ui,
    doc: &mut Document,
    st: &mut EditorState,
    auto_weights: bool,
    dragging: bool,
    keyed: Option<KeyedView>,
) {
    st.fix_selection(doc.flame());
    let sel = st.selected;
    // At a frame of the timeline: the maps of that frame (with their keyed turns and scales).
    let shown = keyed.map(|k| doc.flame().keys.apply(doc.flame(), k.frame));
    let Some(x0) = xform_of(shown.as_ref().unwrap_or(doc.flame()), sel).cloned() else {
        ui.label("No transform selected");
        return;
    };
    let mut x = x0.clone();
    let mut follow_areas = auto_weights;
    if let Selected::Xform(i) = sel {
        ui.horizontal(|ui| {
            let l = ui.label("Name");
            let mut name = xform_name(&x, i);
            if ui
                .text_edit_singleline(&mut name)
                .labelled_by(l.id)
                .on_hover_text("the transform's name (saved as its name attribute)")
                .changed()
            {
                set_xform_name(&mut x, &name);
            }
        });
    }
    corners_and_coefficients(ui, st, &mut x);
    ui.separator();
    egui::Grid::new("wc-grid").num_columns(2).show(ui, |ui| {
        if sel != Selected::Final {
            let l = ui.label("Weight");
            ui.horizontal(|ui| {
                let r = ui
                    .add(
                        egui::DragValue::new(&mut x.weight)
                            .speed(0.01)
                            .range(0.0..=1e6)
                            .clamp_existing_to_range(false)
                            .max_decimals(6),
                    )
                    .labelled_by(l.id)
                    .on_hover_text(if auto_weights {
                        "how often this transform is chosen. The weights follow the triangle \
                         areas now; typing a weight switches that off for this flame"
                    } else {
                        "how often this transform is chosen (relative to the others)"
                    });
                if r.changed() {
                    follow_areas = false;
                }
                ui.checkbox(&mut follow_areas, "from areas").on_hover_text(
                    "weights follow the triangle areas after every triangle edit (the thesis \
                     rule; Options › General sets it for new flames)",
                );
            });
            ui.end_row();
        }
        ui.label("Colour");
        ui.horizontal(|ui| {
            unit_slider(
                ui,
                &mut x.color,
                "Colour",
                "the transform's place in the gradient (0 … 1)",
            );
            let f = doc.flame();
            let [r, g, b] = f.palette.rgb8((x.color.clamp(0.0, 1.0) * 255.0) as usize);
            let (rect, resp) = ui.allocate_exact_size(Vec2::new(18.0, 18.0), Sense::hover());
            ui.painter()
                .rect_filled(rect, 2.0, Color32::from_rgb(r, g, b));
            resp.on_hover_text("this colour of the gradient");
        });
        ui.end_row();
        ui.label("Colour speed");
        unit_slider(
            ui,
            &mut x.color_speed,
            "Colour speed",
            "how fast points take on this transform's colour (0: keep theirs, 1: at once)",
        );
        ui.end_row();
        ui.label("Opacity");
        unit_slider(
            ui,
            &mut x.opacity,
            "Opacity",
            "how visible the points this transform makes are (0: hidden, still iterated)",
        );
        ui.end_row();
    });
    let switched = follow_areas != auto_weights;
    if x != x0 || switched {
        if switched || (x.weight != x0.weight && auto_weights) {
            // A typed weight, or the switch: this flame's own choice from now on.
            doc.edit(|f| {
                f.auto_weights = Some(follow_areas);
                if let Some(t) = xform_of_mut(f, sel) {
                    *t = match keyed {
                        // The maps shown are the frame's, not the base's.
                        Some(_) => numbers_on_base(t, &x),
                        None => x.clone(),
                    };
                }
                if follow_areas {
                    f.set_determinant_weights();
                }
            });
        } else {
            apply(doc, sel, (&x0, x), auto_weights, dragging, keyed);
        }
    }
    ui.separator();
    egui::CollapsingHeader::new("Turn, scale, move by amounts")
        .default_open(true)
        .show(ui, |ui| {
            let mut amounts = st.amounts;
            transform_tools::tools_ui(ui, doc, st, &mut amounts, auto_weights);
            st.amounts = amounts;
        });
}

/// Corners (with y up) and coefficients of the pre or post map.
fn corners_and_coefficients(ui: &mut egui::Ui, st: &EditorState, x: &mut Xform) {
    let m0 = st.map_of(x);
    let mut m = m0;
    let t0 = m.triangle();
    // Shown with y up: world y negated.
    let mut shown = t0.map(|p| [p[0], -p[1]]);
    let mut tri_changed = false;
    let mut coef_changed = false;
    ui.strong(if st.edit_post {
        "Post triangle"
    } else {
        "Triangle"
    })
    .on_hover_text("corners of the triangle; y points up, as in Apophysis");
    egui::Grid::new("tri-grid").num_columns(3).show(ui, |ui| {
        for (k, (l, what)) in [("A", "O"), ("B", "X"), ("C", "Y")].iter().enumerate() {
            ui.label(format!("{l} ({what})"))
                .on_hover_text(format!("the image of the reference corner {what}"));
            tri_changed |= num(ui, &mut shown[k][0], &format!("{l} x"), "x of the corner");
            tri_changed |= num(
                ui,
                &mut shown[k][1],
                &format!("{l} y"),
                "y of the corner (up is positive)",
            );
            ui.end_row();
        }
    });
    ui.label("Coefficients, as the file stores them: x' = a·x + b·y + e, y' = c·x + d·y + f")
        .on_hover_text("in the image, y points down; the triangle above shows y up");
    // Three pairs a row; two in a narrow panel (a small window), so that it fits.
    let per_row = if ui.available_width() < 380.0 { 2 } else { 3 };
    egui::Grid::new("coef-grid")
        .num_columns(2 * per_row)
        .show(ui, |ui| {
            let cells: [(&str, &mut f64); 6] = if per_row == 3 {
                [
                    ("a", &mut m.a),
                    ("b", &mut m.b),
                    ("e", &mut m.e),
                    ("c", &mut m.c),
                    ("d", &mut m.d),
                    ("f", &mut m.f),
                ]
            } else {
                [
                    ("a", &mut m.a),
                    ("b", &mut m.b),
                    ("c", &mut m.c),
                    ("d", &mut m.d),
                    ("e", &mut m.e),
                    ("f", &mut m.f),
                ]
            };
            for (k, (l, v)) in cells.into_iter().enumerate() {
                ui.label(l);
                coef_changed |= num(ui, v, l, &format!("coefficient {l}"));
                if (k + 1) % per_row == 0 {
                    ui.end_row();
                }
            }
        });
    ui.horizontal(|ui| {
        if ui
            .button("Reset")
            .on_hover_text("the identity map")
            .clicked()
        {
            m = Affine::IDENTITY;
            coef_changed = true;
        }
        if ui
            .button("Flip H")
            .on_hover_text("mirror left and right about the y axis")
            .clicked()
        {
            m = Affine::new(-1.0, 0.0, 0.0, 1.0, 0.0, 0.0).compose(&m);
            coef_changed = true;
        }
        if ui
            .button("Flip V")
            .on_hover_text("mirror up and down about the x axis")
            .clicked()
        {
            m = Affine::new(1.0, 0.0, 0.0, -1.0, 0.0, 0.0).compose(&m);
            coef_changed = true;
        }
        ui.label(format!("det {:.4}", m.det()))
            .on_hover_text("a·d − b·c: the area ratio (negative: mirrored)");
    });
    if tri_changed {
        st.set_map(x, Affine::from_triangle(shown.map(|p| [p[0], -p[1]])));
    } else if coef_changed {
        st.set_map(x, m);
    }
}

/// The Variations section.
pub fn variations_section(
    ui: &mut egui::Ui,
    doc: &mut Document,
    st: &mut EditorState,
    dragging: bool,
) {
    st.fix_selection(doc.flame());
    let sel = st.selected;
    let Some(x0) = xform_of(doc.flame(), sel).cloned() else {
        ui.label("No transform selected");
        return;
    };
    let mut x = x0.clone();
    variations_panel::panel(ui, &mut x, &mut st.var_find);
    if x != x0 {
        apply(doc, sel, (&x0, x), false, dragging, None);
    }
}
