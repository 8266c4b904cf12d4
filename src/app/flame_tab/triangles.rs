//! The triangle editor's canvas: draws every transform's triangle over a grid and the dashed
//! reference triangle; drag inside a triangle to move it, drag a corner to reshape it, Rotate
//! and Scale modes turn or grow it about its centre or the origin (Shift: 15° steps); wheel
//! zooms at the pointer, right or middle drag pans; the context menu adds, duplicates and
//! deletes. At a frame of the timeline the triangles are the maps of that frame (with their
//! keyed turns and scales), and what is dragged is keyed there or changes the base (see
//! [`crate::flame::shown_maps`]).

use eframe::egui::{self, Color32, Pos2, Sense, Shape, Stroke, Vec2};

use super::document::Document;
use super::editor_state::{
    Drag, EditorState, Gesture, Mode, Pivot, Selected, TRIANGLE_COLORS, centroid,
    point_in_triangle, rotate_about, scale_about, xform_of, xform_of_mut,
};
use super::editor_tools::EditorAction;
use crate::flame::keyframes::XformRef;
use crate::flame::shown_maps::set_shown_map;
use crate::flame::{Affine, Flame};

/// The timeline's frame the triangles show, and whether edits are keyed there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KeyedView {
    pub frame: f64,
    pub auto_key: bool,
}

/// The flame whose maps are drawn: `f` at the frame of `keyed`, or `f` itself.
fn view_of(f: &Flame, keyed: Option<KeyedView>) -> Flame {
    match keyed {
        Some(k) => f.keys.apply(f, k.frame),
        None => f.clone(),
    }
}

const FINAL_COLOR: Color32 = Color32::from_rgb(255, 255, 255);

/// What happened in the canvas this frame.
#[derive(Default)]
pub struct CanvasOutput {
    /// The flame changed (live, during a drag too).
    pub changed: bool,
    /// A drag is in progress.
    pub dragging: bool,
    pub action: Option<EditorAction>,
}

/// A triangle on the canvas: which transform, its corners in world coordinates, its colour.
type Entry = (Selected, [[f64; 2]; 3], Color32);

/// The canvas: draws and edits the triangles.
pub fn canvas(
    ui: &mut egui::Ui,
    doc: &mut Document,
    st: &mut EditorState,
    auto_weights: bool,
    keyed: Option<KeyedView>,
) -> CanvasOutput {
    let mut out = CanvasOutput::default();
    let size = ui.available_size().max(Vec2::new(120.0, 120.0));
    let (rect, resp) = ui.allocate_exact_size(size, Sense::click_and_drag());
    let resized = (st.canvas.size() - rect.size()).length() > 1.0;
    st.canvas = rect;
    st.fix_selection(doc.flame());
    // A view that was fitted stays fitted when the canvas changes size (the first layout, a
    // resized window): every triangle stays in sight.
    if resized && st.fitted {
        st.auto_zoom(doc.flame());
    }
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 0.0, Color32::from_gray(18));
    zoom_at_pointer(ui, &resp, st);
    if st.grid {
        draw_grid(&painter, rect, st);
    }
    let reference = draw_reference(&painter, st);
    let flame = view_of(doc.flame(), keyed);
    let entries = triangle_entries(&flame, st);
    for e in &entries {
        draw_triangle(&painter, st, e);
    }
    // Interaction.
    if resp.drag_started() {
        start_gesture(ui, &resp, doc, &flame, st, &entries, reference);
    }
    if resp.dragged()
        && let Some(g) = st.gesture.clone()
    {
        out.dragging = true;
        out.changed = drag_gesture(ui, &resp, doc, st, &g, auto_weights, keyed);
    }
    if resp.drag_stopped()
        && let Some(g) = st.gesture.take()
        && !matches!(g.drag, Drag::Pan)
    {
        doc.end_gesture(g.before);
    }
    // Click selects.
    if resp.clicked()
        && let Some(pos) = resp.interact_pointer_pos()
    {
        let w = st.world_from_screen(pos);
        if let Some((sel, _, _)) = entries
            .iter()
            .rev()
            .find(|(_, t, _)| point_in_triangle(w, t))
        {
            st.selected = *sel;
        }
    }
    resp.context_menu(|ui| {
        for (label, a) in [
            ("Auto zoom", EditorAction::AutoZoom),
            ("Delete triangle", EditorAction::Delete),
            ("Duplicate", EditorAction::Duplicate),
            ("Add", EditorAction::Add),
            ("Undo", EditorAction::Undo),
            ("Redo", EditorAction::Redo),
        ] {
            if ui.button(label).clicked() {
                out.action = Some(a);
                ui.close();
            }
        }
    });
    out
}

/// Zoom at the pointer with the wheel, and remember where the pointer is in the world.
fn zoom_at_pointer(ui: &egui::Ui, resp: &egui::Response, st: &mut EditorState) {
    if let Some(hp) = resp.hover_pos() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            let before = st.world_from_screen(hp);
            st.zoom =
                (st.zoom * (1.0 + scroll as f64 * 0.002).clamp(0.5, 2.0)).clamp(2.0, 20_000.0);
            let after = st.world_from_screen(hp);
            st.view_center[0] += before[0] - after[0];
            st.view_center[1] += before[1] - after[1];
            st.fitted = false;
        }
        st.hover_world = Some(st.world_from_screen(hp));
    } else if st.gesture.is_none() {
        st.hover_world = None;
    }
}

/// Grid lines about 60 pixels apart at round world coordinates; the axes brighter.
fn draw_grid(painter: &egui::Painter, rect: egui::Rect, st: &EditorState) {
    let tl = st.world_from_screen(rect.min);
    let br = st.world_from_screen(rect.max);
    let step = {
        let target = 60.0 / st.zoom; // about 60 px between lines
        let p = 10f64.powf(target.log10().ceil());
        if p / 2.0 >= target { p / 2.0 } else { p }
    };
    let mut x = (tl[0] / step).floor() * step;
    while x <= br[0] {
        let s = st.screen_from_world([x, 0.0]).x;
        let c = if x.abs() < step / 2.0 { 70 } else { 38 };
        painter.line_segment(
            [Pos2::new(s, rect.top()), Pos2::new(s, rect.bottom())],
            Stroke::new(1.0, Color32::from_gray(c)),
        );
        x += step;
    }
    let mut y = (tl[1] / step).floor() * step;
    while y <= br[1] {
        let s = st.screen_from_world([0.0, y]).y;
        let c = if y.abs() < step / 2.0 { 70 } else { 38 };
        painter.line_segment(
            [Pos2::new(rect.left(), s), Pos2::new(rect.right(), s)],
            Stroke::new(1.0, Color32::from_gray(c)),
        );
        y += step;
    }
}

/// The dashed reference triangle O, X, Y; returns its corners.
fn draw_reference(painter: &egui::Painter, st: &EditorState) -> [[f64; 2]; 3] {
    let reference = Affine::IDENTITY.triangle();
    let ref_pts: Vec<Pos2> = reference.iter().map(|p| st.screen_from_world(*p)).collect();
    painter.add(Shape::dashed_line(
        &[ref_pts[0], ref_pts[1], ref_pts[2], ref_pts[0]],
        Stroke::new(1.0, Color32::from_gray(140)),
        6.0,
        4.0,
    ));
    for (p, l) in ref_pts.iter().zip(["O", "X", "Y"]) {
        painter.text(
            *p + Vec2::new(4.0, -4.0),
            egui::Align2::LEFT_BOTTOM,
            l,
            egui::FontId::proportional(11.0),
            Color32::from_gray(140),
        );
    }
    reference
}

/// Every transform's triangle in drawing order (the final transform last, when shown).
fn triangle_entries(flame: &Flame, st: &EditorState) -> Vec<Entry> {
    let mut entries: Vec<Entry> = flame
        .xforms
        .iter()
        .enumerate()
        .map(|(i, x)| {
            (
                Selected::Xform(i),
                st.map_of(x).triangle(),
                TRIANGLE_COLORS[i % TRIANGLE_COLORS.len()],
            )
        })
        .collect();
    if st.show_final
        && let Some(fx) = &flame.final_xform
    {
        entries.push((Selected::Final, st.map_of(fx).triangle(), FINAL_COLOR));
    }
    entries
}

/// One triangle: filled and with its corners A, B, C and the pivot when selected; the final
/// transform's dashed.
fn draw_triangle(painter: &egui::Painter, st: &EditorState, (sel, t, col): &Entry) {
    let pts: Vec<Pos2> = t.iter().map(|p| st.screen_from_world(*p)).collect();
    let is_sel = *sel == st.selected;
    let fill = if is_sel {
        col.gamma_multiply(0.18)
    } else {
        Color32::TRANSPARENT
    };
    painter.add(Shape::convex_polygon(pts.clone(), fill, Stroke::NONE));
    let width = if is_sel { 2.0 } else { 1.0 };
    let stroke = Stroke::new(
        width,
        if is_sel {
            *col
        } else {
            col.gamma_multiply(0.7)
        },
    );
    if *sel == Selected::Final {
        painter.add(Shape::dashed_line(
            &[pts[0], pts[1], pts[2], pts[0]],
            stroke,
            5.0,
            3.0,
        ));
    } else {
        painter.add(Shape::closed_line(pts.clone(), stroke));
    }
    if !is_sel {
        return;
    }
    for (k, (p, l)) in pts.iter().zip(["A", "B", "C"]).enumerate() {
        let r = if k == 0 { 5.0 } else { 4.0 };
        painter.circle_filled(*p, r, *col);
        painter.text(
            *p + Vec2::new(6.0, -6.0),
            egui::Align2::LEFT_BOTTOM,
            l,
            egui::FontId::proportional(13.0),
            *col,
        );
    }
    if st.mode != Mode::Move {
        let pp = st.screen_from_world(pivot_of(st, t));
        painter.circle_stroke(pp, 6.0, Stroke::new(1.5, Color32::WHITE));
        painter.line_segment(
            [pp - Vec2::new(9.0, 0.0), pp + Vec2::new(9.0, 0.0)],
            Stroke::new(1.0, Color32::WHITE),
        );
        painter.line_segment(
            [pp - Vec2::new(0.0, 9.0), pp + Vec2::new(0.0, 9.0)],
            Stroke::new(1.0, Color32::WHITE),
        );
    }
}

/// The point Rotate and Scale turn a triangle about: its centre or the origin.
fn pivot_of(st: &EditorState, t: &[[f64; 2]; 3]) -> [f64; 2] {
    match st.pivot {
        Pivot::Local => centroid(t),
        Pivot::World => [0.0, 0.0],
    }
}

/// A drag begins: what it grabs (the selected triangle's corner, a triangle's body, or the
/// view to pan) and the triangle as it was.
fn start_gesture(
    ui: &egui::Ui,
    resp: &egui::Response,
    doc: &mut Document,
    shown: &Flame,
    st: &mut EditorState,
    entries: &[Entry],
    reference: [[f64; 2]; 3],
) {
    // Hit-test where the button went down, not where egui recognised the drag, so the
    // grabbed point stays under the pointer.
    let pos = ui
        .input(|i| i.pointer.press_origin())
        .or(resp.interact_pointer_pos())
        .unwrap_or(resp.rect.center());
    let w = st.world_from_screen(pos);
    let middle = ui.input(|i| i.pointer.middle_down());
    let pan = middle || resp.dragged_by(egui::PointerButton::Secondary);
    let flame = shown;
    let drag = if pan {
        Drag::Pan
    } else {
        grabbed(flame, st, entries, pos, w).unwrap_or(Drag::Pan)
    };
    let start_tri = xform_of(flame, st.selected)
        .map(|x| st.map_of(x).triangle())
        .unwrap_or(reference);
    st.gesture = Some(Gesture {
        drag,
        start_world: w,
        start_tri,
        before: doc.begin_gesture(),
    });
}

/// What a drag from screen point `pos` (world point `w`) grabs: the selected triangle's
/// corners first, then any triangle's body (the topmost; the selected one before others),
/// which the mode makes a move, a turn or a scaling. Grabbing a body selects it.
fn grabbed(
    flame: &Flame,
    st: &mut EditorState,
    entries: &[Entry],
    pos: Pos2,
    w: [f64; 2],
) -> Option<Drag> {
    let mut drag = None;
    if let Some(x) = xform_of(flame, st.selected) {
        let t = st.map_of(x).triangle();
        for (k, v) in t.iter().enumerate() {
            if st.screen_from_world(*v).distance(pos) <= 8.0 {
                drag = Some(Drag::Vertex(k));
            }
        }
    }
    if drag.is_some() {
        return drag;
    }
    let body = entries
        .iter()
        .rev()
        .find(|(s, t, _)| *s == st.selected && point_in_triangle(w, t))
        .or_else(|| {
            entries
                .iter()
                .rev()
                .find(|(_, t, _)| point_in_triangle(w, t))
        })?;
    st.selected = body.0;
    Some(match st.mode {
        Mode::Move => Drag::Body,
        Mode::Rotate => Drag::Rotate,
        Mode::Scale => Drag::Scale,
    })
}

/// Follow a drag: pan the view, or reshape, move, turn or scale the selected triangle (live,
/// within the gesture's undo step). Returns whether the flame changed.
fn drag_gesture(
    ui: &egui::Ui,
    resp: &egui::Response,
    doc: &mut Document,
    st: &mut EditorState,
    g: &Gesture,
    auto_weights: bool,
    keyed: Option<KeyedView>,
) -> bool {
    let pos = resp.interact_pointer_pos().unwrap_or(resp.rect.center());
    let w = st.world_from_screen(pos);
    let (dx, dy) = (w[0] - g.start_world[0], w[1] - g.start_world[1]);
    let shift = ui.input(|i| i.modifiers.shift);
    let new_tri = match g.drag {
        Drag::Pan => {
            let d = resp.drag_delta();
            st.view_center[0] -= d.x as f64 / st.zoom;
            st.view_center[1] -= d.y as f64 / st.zoom;
            st.fitted = false;
            None
        }
        Drag::Vertex(k) => {
            let mut t = g.start_tri;
            t[k] = [g.start_tri[k][0] + dx, g.start_tri[k][1] + dy];
            Some(t)
        }
        Drag::Body => Some(g.start_tri.map(|p| [p[0] + dx, p[1] + dy])),
        Drag::Rotate => {
            let c = pivot_of(st, &g.start_tri);
            let a0 = (g.start_world[1] - c[1]).atan2(g.start_world[0] - c[0]);
            let a1 = (w[1] - c[1]).atan2(w[0] - c[0]);
            let mut ang = a1 - a0;
            if shift {
                let step = 15f64.to_radians();
                ang = (ang / step).round() * step;
            }
            Some(rotate_about(&g.start_tri, c, ang))
        }
        Drag::Scale => {
            let c = pivot_of(st, &g.start_tri);
            let d0 = ((g.start_world[0] - c[0]).powi(2) + (g.start_world[1] - c[1]).powi(2)).sqrt();
            let d1 = ((w[0] - c[0]).powi(2) + (w[1] - c[1]).powi(2)).sqrt();
            let k = if d0 > 1e-9 { d1 / d0 } else { 1.0 };
            Some(scale_about(&g.start_tri, c, k))
        }
    };
    let Some(t) = new_tri else {
        return false;
    };
    let sel = st.selected;
    let mut m = Affine::from_triangle(t);
    let before = view_of(&g.before, keyed);
    if matches!(g.drag, Drag::Body)
        && let Some(x) = xform_of(&before, sel)
    {
        // A move changes only the translation: keep the linear part bit for bit.
        let s = st.map_of(x);
        (m.a, m.b, m.c, m.d) = (s.a, s.b, s.c, s.d);
    }
    let edit_post = st.edit_post;
    let f = doc.flame_mut_in_gesture();
    if let Some(k) = keyed {
        // The keys and base as they were when the drag began, then this drag's map.
        *f = g.before.clone();
        let x = match sel {
            Selected::Xform(i) => XformRef::Index(i),
            Selected::Final => XformRef::Final,
        };
        set_shown_map(f, x, edit_post, k.frame, m, k.auto_key);
    } else if let Some(x) = xform_of_mut(f, sel) {
        if edit_post {
            x.post = m;
        } else {
            x.coefs = m;
        }
    }
    if auto_weights && !edit_post && sel != Selected::Final {
        f.set_determinant_weights();
    }
    true
}
