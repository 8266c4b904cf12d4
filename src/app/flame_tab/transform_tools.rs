//! Apophysis' triangle buttons: turn the selected triangle by a typed number of degrees, grow
//! or shrink it by a typed percentage, move it by a typed distance along x or y — about the
//! editor's pivot (the triangle's centre or the world origin) — or turn or scale every
//! transform about the world origin. One undo step per click.

use eframe::egui;

use super::document::Document;
use super::editor_state::{
    EditorState, Pivot, Selected, centroid, rotate_about, scale_about, xform_of,
};
use crate::app::a11y::named;
use crate::flame::{Affine, Flame};

/// The amounts typed, kept between frames.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Amounts {
    /// Degrees of a turn.
    pub degrees: f64,
    /// Percent of a scaling.
    pub percent: f64,
    /// World units of a move.
    pub distance: f64,
    /// The turn and scaling apply to every transform, about the world origin.
    pub all: bool,
}

impl Default for Amounts {
    fn default() -> Self {
        Amounts {
            degrees: 15.0,
            percent: 10.0,
            distance: 0.1,
            all: false,
        }
    }
}

/// One click of a tool.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tool {
    /// Turn by this many degrees, counter-clockwise as the editor shows it (y up).
    Rotate(f64),
    /// Multiply the size by this factor.
    Scale(f64),
    /// Move by this offset, x right and y up as the editor shows it.
    Move([f64; 2]),
}

/// Apply `tool` to the triangles (pre or post maps, as the editor shows) of `f`: the
/// selected transform about the pivot, or with `all` every transform (the final one too) about
/// the world origin. A move with `all` moves every transform.
pub fn apply(f: &mut Flame, st: &EditorState, tool: Tool, all: bool) {
    let sel = st.selected;
    let each = |x: &mut crate::flame::Xform, pivot: Option<[f64; 2]>| {
        let t = st.map_of(x).triangle();
        let c = pivot.unwrap_or_else(|| centroid(&t));
        let moved = match tool {
            // World y points down: a counter-clockwise turn on screen is a negative angle.
            Tool::Rotate(deg) => rotate_about(&t, c, -deg.to_radians()),
            Tool::Scale(k) => scale_about(&t, c, k),
            Tool::Move([dx, dy]) => t.map(|p| [p[0] + dx, p[1] - dy]),
        };
        st.set_map(x, Affine::from_triangle(moved));
    };
    if all {
        for x in f.xforms.iter_mut().chain(f.final_xform.iter_mut()) {
            each(x, Some([0.0, 0.0]));
        }
        return;
    }
    let pivot = match st.pivot {
        Pivot::Local => None,
        Pivot::World => Some([0.0, 0.0]),
    };
    let x = match sel {
        Selected::Xform(i) => f.xforms.get_mut(i),
        Selected::Final => f.final_xform.as_mut(),
    };
    if let Some(x) = x {
        each(x, pivot);
    }
}

/// A button's drawn symbol (the interface font has no arrows).
#[derive(Clone, Copy)]
enum Glyph {
    /// A turning arrow: counter-clockwise for 1, clockwise for −1.
    Turn(f32),
    /// A straight arrow along (x, y up).
    Arrow([f64; 2]),
}

/// A small button showing `glyph`, named `name` for screen readers and tests.
fn icon_button(ui: &mut egui::Ui, glyph: Glyph, name: &str) -> egui::Response {
    use egui::{Pos2, Shape, Stroke, Vec2};
    let size = Vec2::new(26.0, ui.spacing().interact_size.y.max(20.0));
    let (rect, resp) = ui.allocate_exact_size(size, egui::Sense::click());
    resp.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, name));
    if !ui.is_rect_visible(rect) {
        return resp;
    }
    let v = ui.style().interact(&resp);
    ui.painter()
        .rect_filled(rect, v.corner_radius, v.weak_bg_fill);
    let c = rect.center();
    let stroke = Stroke::new(1.5, v.fg_stroke.color);
    // An arrowhead at `tip` pointing along the unit vector `d` (screen coordinates).
    let head = |tip: Pos2, d: Vec2| {
        let n = Vec2::new(-d.y, d.x);
        Shape::convex_polygon(
            vec![tip, tip - d * 4.5 + n * 3.5, tip - d * 4.5 - n * 3.5],
            v.fg_stroke.color,
            Stroke::NONE,
        )
    };
    let shapes = match glyph {
        Glyph::Arrow([x, y]) => {
            let d = Vec2::new(x as f32, -y as f32);
            vec![
                Shape::line_segment([c - d * 6.0, c + d * 3.0], stroke),
                head(c + d * 7.0, d),
            ]
        }
        Glyph::Turn(sense) => {
            // Three quarters of a circle, from the top round to the right (counter-clockwise
            // on screen for sense 1), and the arrowhead at its end.
            let r = 6.0;
            let start = -std::f32::consts::FRAC_PI_2;
            let at = |t: f32| {
                let a = start - sense * t * 1.5 * std::f32::consts::PI;
                c + Vec2::new(a.cos(), a.sin()) * r
            };
            let pts: Vec<Pos2> = (0..=16).map(|k| at(k as f32 / 16.0)).collect();
            let end = at(1.0);
            let before = at(0.93);
            vec![
                Shape::line(pts, stroke),
                head(
                    end + (end - before).normalized() * 2.0,
                    (end - before).normalized(),
                ),
            ]
        }
    };
    ui.painter().extend(shapes);
    resp
}

/// The tools' rows; a click is one undo step (areas weights follow a scaling when the flame
/// asks for them).
pub fn tools_ui(
    ui: &mut egui::Ui,
    doc: &mut Document,
    st: &EditorState,
    amounts: &mut Amounts,
    auto_weights: bool,
) {
    if xform_of(doc.flame(), st.selected).is_none() {
        return;
    }
    let mut tool = None;
    let a = amounts;
    let about = if a.all {
        "every transform about the origin"
    } else {
        match st.pivot {
            Pivot::Local => "about the triangle's centre",
            Pivot::World => "about the origin",
        }
    };
    egui::Grid::new("transform-tools")
        .num_columns(4)
        .show(ui, |ui| {
            ui.label("Rotate");
            if icon_button(ui, Glyph::Turn(1.0), "Rotate counter-clockwise")
                .on_hover_text(format!("turn counter-clockwise {about}"))
                .clicked()
            {
                tool = Some(Tool::Rotate(a.degrees));
            }
            named(
                ui.add(
                    egui::DragValue::new(&mut a.degrees)
                        .range(0.0..=360.0)
                        .speed(0.5)
                        .suffix("°"),
                ),
                "Rotate by",
            )
            .on_hover_text("degrees of one turn");
            if icon_button(ui, Glyph::Turn(-1.0), "Rotate clockwise")
                .on_hover_text(format!("turn clockwise {about}"))
                .clicked()
            {
                tool = Some(Tool::Rotate(-a.degrees));
            }
            ui.end_row();
            ui.label("Scale");
            let k = 1.0 + a.percent / 100.0;
            if named(ui.button("−"), "Shrink")
                .on_hover_text(format!("shrink {about} (the inverse of growing)"))
                .clicked()
            {
                tool = Some(Tool::Scale(1.0 / k));
            }
            named(
                ui.add(
                    egui::DragValue::new(&mut a.percent)
                        .range(0.1..=1000.0)
                        .speed(0.5)
                        .suffix(" %"),
                ),
                "Scale by",
            )
            .on_hover_text("percent of one scaling");
            if named(ui.button("+"), "Grow")
                .on_hover_text(format!("grow {about}"))
                .clicked()
            {
                tool = Some(Tool::Scale(k));
            }
            ui.end_row();
            ui.label("Move");
            ui.horizontal(|ui| {
                for (d, tip) in [([-1.0, 0.0], "left"), ([1.0, 0.0], "right")] {
                    if icon_button(ui, Glyph::Arrow(d), &format!("Move {tip}"))
                        .on_hover_text(format!("move {tip}"))
                        .clicked()
                    {
                        tool = Some(Tool::Move(d));
                    }
                }
            });
            named(
                ui.add(
                    egui::DragValue::new(&mut a.distance)
                        .range(0.0..=1e6)
                        .speed(0.01),
                ),
                "Move by",
            )
            .on_hover_text("distance of one move, in world units");
            ui.horizontal(|ui| {
                for (d, tip) in [([0.0, 1.0], "up"), ([0.0, -1.0], "down")] {
                    if icon_button(ui, Glyph::Arrow(d), &format!("Move {tip}"))
                        .on_hover_text(format!("move {tip}"))
                        .clicked()
                    {
                        tool = Some(Tool::Move(d));
                    }
                }
            });
            ui.end_row();
        });
    ui.checkbox(&mut a.all, "All transforms, about the origin")
        .on_hover_text("turn, scale or move every transform (the final one too) at once");
    let Some(mut tool) = tool else {
        return;
    };
    if let Tool::Move(d) = tool {
        tool = Tool::Move([d[0] * a.distance, d[1] * a.distance]);
    }
    let all = a.all;
    doc.edit(|f| {
        apply(f, st, tool, all);
        if auto_weights && !st.edit_post && matches!(tool, Tool::Scale(_)) {
            f.set_determinant_weights();
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::Xform;

    fn flame() -> Flame {
        Flame {
            xforms: vec![
                Xform::linear(Affine::new(0.5, 0.1, -0.2, 0.6, 0.3, -0.4), 1.0, 0.0),
                Xform::linear(Affine::new(0.4, 0.0, 0.0, 0.4, -0.5, 0.2), 1.0, 1.0),
            ],
            ..Flame::default()
        }
    }

    fn close(a: [[f64; 2]; 3], b: [[f64; 2]; 3]) -> bool {
        a.iter()
            .flatten()
            .zip(b.iter().flatten())
            .all(|(x, y)| (x - y).abs() < 1e-12)
    }

    #[test]
    fn a_turn_keeps_the_centre_and_its_inverse_restores() {
        let st = EditorState::default();
        let mut f = flame();
        let t0 = f.xforms[0].coefs.triangle();
        apply(&mut f, &st, Tool::Rotate(90.0), false);
        let t1 = f.xforms[0].coefs.triangle();
        let (c0, c1) = (centroid(&t0), centroid(&t1));
        assert!((c0[0] - c1[0]).abs() < 1e-12 && (c0[1] - c1[1]).abs() < 1e-12);
        // Counter-clockwise with y up: the vector from the centre to O, (x, y) shown, becomes
        // (−y, x) shown; in world coordinates (y down) (x, y) becomes (y, −x).
        let v0 = [t0[0][0] - c0[0], t0[0][1] - c0[1]];
        let v1 = [t1[0][0] - c1[0], t1[0][1] - c1[1]];
        assert!((v1[0] - v0[1]).abs() < 1e-12 && (v1[1] + v0[0]).abs() < 1e-12);
        assert_eq!(
            f.xforms[1],
            flame().xforms[1],
            "only the selected one turns"
        );
        apply(&mut f, &st, Tool::Rotate(-90.0), false);
        assert!(close(f.xforms[0].coefs.triangle(), t0));
    }

    #[test]
    fn scaling_and_moving_by_amounts() {
        let mut st = EditorState::default();
        let mut f = flame();
        let t0 = f.xforms[0].coefs.triangle();
        apply(&mut f, &st, Tool::Scale(1.1), false);
        let d0 = f.xforms[0].coefs.det();
        assert!((d0 - 1.21 * flame().xforms[0].coefs.det()).abs() < 1e-12);
        apply(&mut f, &st, Tool::Scale(1.0 / 1.1), false);
        assert!(close(f.xforms[0].coefs.triangle(), t0));
        // Up is −y in the world: O moves from (e, f) to (e + 0.2, f − 0.3).
        apply(&mut f, &st, Tool::Move([0.2, 0.3]), false);
        let m = f.xforms[0].coefs;
        assert!((m.e - 0.5).abs() < 1e-12 && (m.f + 0.7).abs() < 1e-12);
        assert!((m.a - 0.5).abs() < 1e-12 && (m.d - 0.6).abs() < 1e-12);
        // The post map when the editor shows post maps.
        st.edit_post = true;
        let pre = f.xforms[0].coefs;
        apply(&mut f, &st, Tool::Scale(2.0), false);
        assert_eq!(f.xforms[0].coefs, pre);
        assert!((f.xforms[0].post.det() - 4.0).abs() < 1e-12);
    }

    #[test]
    fn all_transforms_turn_about_the_origin() {
        let st = EditorState::default();
        let mut f = flame();
        f.final_xform = Some(Xform::linear(Affine::IDENTITY, 0.0, 0.0));
        apply(&mut f, &st, Tool::Rotate(180.0), true);
        for (a, b) in f.xforms.iter().zip(&flame().xforms) {
            let (ta, tb) = (a.coefs.triangle(), b.coefs.triangle());
            assert!(close(ta, tb.map(|p| [-p[0], -p[1]])));
        }
        let fin = f.final_xform.as_ref().unwrap().coefs;
        assert!((fin.a + 1.0).abs() < 1e-12 && (fin.d + 1.0).abs() < 1e-12);
    }
}
