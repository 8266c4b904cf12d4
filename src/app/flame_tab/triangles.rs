//! The triangle editor: every xform drawn as the image of the reference triangle O = (0, 0),
//! X = (1, 0), Y = (0, −1) (the triangle of an affine map x' = a·x + b·y + e,
//! y' = c·x + d·y + f has the corners O′ = (e, f), X′ = (a + e, c + f), Y′ = (e − b, f − d));
//! drag inside to move, drag a vertex to reshape, rotate and scale modes about the triangle's
//! centre or the world origin, post and final xforms, grid, wheel zoom and pan.

use eframe::egui::{self, Color32, Pos2, Rect, Sense, Shape, Stroke, Vec2};

use super::document::Document;
use crate::app::a11y::named;
use crate::flame::{Affine, Flame, Xform};

/// What a drag does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Mode {
    #[default]
    Move,
    Rotate,
    Scale,
}

/// Centre of rotation and scaling.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Pivot {
    /// The triangle's centroid.
    #[default]
    Local,
    /// The world origin.
    World,
}

/// Which xform is selected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Selected {
    Xform(usize),
    Final,
}

#[derive(Clone, Debug)]
enum Drag {
    /// Vertex k (0 = O/A, 1 = X/B, 2 = Y/C) of the selected triangle.
    Vertex(usize),
    Body,
    Rotate,
    Scale,
    Pan,
}

#[derive(Clone, Debug)]
struct Gesture {
    drag: Drag,
    start_world: [f64; 2],
    start_tri: [[f64; 2]; 3],
    before: Flame,
}

/// Editor state kept between frames.
#[derive(Clone, Debug)]
pub struct EditorState {
    /// World point at the centre of the canvas.
    pub view_center: [f64; 2],
    /// Pixels per world unit.
    pub zoom: f64,
    pub selected: Selected,
    pub mode: Mode,
    pub pivot: Pivot,
    /// Edit post transforms instead of the pre-affine maps.
    pub edit_post: bool,
    pub show_final: bool,
    pub grid: bool,
    /// Mouse position in world coordinates (for the status bar).
    pub hover_world: Option<[f64; 2]>,
    /// The canvas rectangle of the last frame.
    pub canvas: Rect,
    gesture: Option<Gesture>,
    /// Variation list filter in the panel.
    pub var_filter: String,
    pub show_all_vars: bool,
}

impl Default for EditorState {
    fn default() -> Self {
        EditorState {
            view_center: [0.3, -0.3],
            zoom: 120.0,
            selected: Selected::Xform(0),
            mode: Mode::Move,
            pivot: Pivot::Local,
            edit_post: false,
            show_final: true,
            grid: true,
            hover_world: None,
            canvas: Rect::from_min_size(Pos2::ZERO, Vec2::splat(100.0)),
            gesture: None,
            var_filter: String::new(),
            show_all_vars: false,
        }
    }
}

/// Distinct colours for the triangles (Apophysis-like).
pub const TRIANGLE_COLORS: [Color32; 12] = [
    Color32::from_rgb(255, 80, 80),
    Color32::from_rgb(255, 220, 60),
    Color32::from_rgb(80, 220, 90),
    Color32::from_rgb(70, 200, 255),
    Color32::from_rgb(150, 110, 255),
    Color32::from_rgb(255, 120, 220),
    Color32::from_rgb(255, 160, 60),
    Color32::from_rgb(160, 255, 200),
    Color32::from_rgb(200, 200, 200),
    Color32::from_rgb(120, 150, 255),
    Color32::from_rgb(220, 255, 90),
    Color32::from_rgb(255, 130, 130),
];
const FINAL_COLOR: Color32 = Color32::from_rgb(255, 255, 255);

impl EditorState {
    pub fn screen_from_world(&self, w: [f64; 2]) -> Pos2 {
        let c = self.canvas.center();
        Pos2::new(
            c.x + ((w[0] - self.view_center[0]) * self.zoom) as f32,
            c.y + ((w[1] - self.view_center[1]) * self.zoom) as f32,
        )
    }

    pub fn world_from_screen(&self, p: Pos2) -> [f64; 2] {
        let c = self.canvas.center();
        [
            self.view_center[0] + (p.x - c.x) as f64 / self.zoom,
            self.view_center[1] + (p.y - c.y) as f64 / self.zoom,
        ]
    }

    /// The affine map the editor shows for an xform (pre or post).
    pub fn map_of(&self, x: &Xform) -> Affine {
        if self.edit_post { x.post } else { x.coefs }
    }

    pub fn set_map(&self, x: &mut Xform, m: Affine) {
        if self.edit_post {
            x.post = m;
        } else {
            x.coefs = m;
        }
    }

    /// Keep the selection valid for a flame.
    pub fn fix_selection(&mut self, f: &Flame) {
        match self.selected {
            Selected::Final if f.final_xform.is_none() => self.selected = Selected::Xform(0),
            Selected::Xform(i) if i >= f.xforms.len() => {
                self.selected = Selected::Xform(f.xforms.len().saturating_sub(1))
            }
            _ => {}
        }
    }

    /// Zoom and centre so that every triangle (and the reference triangle) is visible.
    pub fn auto_zoom(&mut self, f: &Flame) {
        let mut pts: Vec<[f64; 2]> = vec![[0.0, 0.0], [1.0, 0.0], [0.0, -1.0]];
        for x in f.xforms.iter().chain(f.final_xform.iter()) {
            pts.extend(self.map_of(x).triangle());
        }
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for p in &pts {
            if p[0].is_finite() && p[1].is_finite() {
                x0 = x0.min(p[0]);
                x1 = x1.max(p[0]);
                y0 = y0.min(p[1]);
                y1 = y1.max(p[1]);
            }
        }
        self.view_center = [(x0 + x1) / 2.0, (y0 + y1) / 2.0];
        let w = (x1 - x0).max(0.1);
        let h = (y1 - y0).max(0.1);
        let s = self.canvas.size();
        self.zoom = (0.85 * (s.x as f64 / w).min(s.y as f64 / h)).clamp(5.0, 5000.0);
    }
}

pub fn xform_of(f: &Flame, s: Selected) -> Option<&Xform> {
    match s {
        Selected::Xform(i) => f.xforms.get(i),
        Selected::Final => f.final_xform.as_ref(),
    }
}

pub fn xform_of_mut(f: &mut Flame, s: Selected) -> Option<&mut Xform> {
    match s {
        Selected::Xform(i) => f.xforms.get_mut(i),
        Selected::Final => f.final_xform.as_mut(),
    }
}

fn point_in_triangle(p: [f64; 2], t: &[[f64; 2]; 3]) -> bool {
    let sign = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (a[0] - c[0]) * (b[1] - c[1]) - (b[0] - c[0]) * (a[1] - c[1])
    };
    let d1 = sign(p, t[0], t[1]);
    let d2 = sign(p, t[1], t[2]);
    let d3 = sign(p, t[2], t[0]);
    let neg = d1 < 0.0 || d2 < 0.0 || d3 < 0.0;
    let pos = d1 > 0.0 || d2 > 0.0 || d3 > 0.0;
    !(neg && pos)
}

fn centroid(t: &[[f64; 2]; 3]) -> [f64; 2] {
    [
        (t[0][0] + t[1][0] + t[2][0]) / 3.0,
        (t[0][1] + t[1][1] + t[2][1]) / 3.0,
    ]
}

fn rotate_about(t: &[[f64; 2]; 3], c: [f64; 2], ang: f64) -> [[f64; 2]; 3] {
    let (s, co) = ang.sin_cos();
    t.map(|p| {
        let (dx, dy) = (p[0] - c[0], p[1] - c[1]);
        [c[0] + dx * co - dy * s, c[1] + dx * s + dy * co]
    })
}

fn scale_about(t: &[[f64; 2]; 3], c: [f64; 2], k: f64) -> [[f64; 2]; 3] {
    t.map(|p| [c[0] + (p[0] - c[0]) * k, c[1] + (p[1] - c[1]) * k])
}

/// Actions the editor's context menu asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EditorAction {
    AutoZoom,
    Delete,
    Duplicate,
    Add,
    Undo,
    Redo,
}

/// What happened in the canvas this frame.
#[derive(Default)]
pub struct CanvasOutput {
    /// The flame changed (live, during a drag too).
    pub changed: bool,
    /// A drag is in progress.
    pub dragging: bool,
    pub action: Option<EditorAction>,
}

/// Delete the selected xform, refused below 2 (a flame needs two maps to be more than a single
/// curve; the thesis program's rule). Returns an explanation when refused.
pub fn delete_selected(doc: &mut Document, st: &mut EditorState) -> Result<(), String> {
    match st.selected {
        Selected::Final => {
            doc.edit(|f| f.final_xform = None);
            st.selected = Selected::Xform(0);
            Ok(())
        }
        Selected::Xform(i) => {
            if doc.flame().xforms.len() <= 2 {
                return Err("Delete refused: a flame needs at least 2 transforms".into());
            }
            doc.edit(|f| {
                f.xforms.remove(i);
                for x in &mut f.xforms {
                    if i < x.chaos.len() {
                        x.chaos.remove(i);
                    }
                }
            });
            st.selected = Selected::Xform(i.saturating_sub(1));
            Ok(())
        }
    }
}

/// Duplicate the selected xform (the copy is selected).
pub fn duplicate_selected(doc: &mut Document, st: &mut EditorState, auto_weights: bool) {
    let Some(x) = xform_of(doc.flame(), st.selected).cloned() else {
        return;
    };
    doc.edit(|f| {
        let mut x = x;
        x.weight = x.weight.max(0.0);
        f.xforms.push(x);
        if auto_weights {
            f.set_determinant_weights();
        }
    });
    st.selected = Selected::Xform(doc.flame().xforms.len() - 1);
}

/// Add a new linear xform: weight 0.5, colour 1, a half-size square beside the reference
/// triangle.
pub fn add_xform(doc: &mut Document, st: &mut EditorState, auto_weights: bool) {
    doc.edit(|f| {
        let n = f.xforms.len() + 1;
        f.xforms.push(Xform {
            weight: 0.5,
            ..Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 0.25, -0.25), 0.5, 1.0)
        });
        // Spread the colours i/(n − 1).
        for (i, x) in f.xforms.iter_mut().enumerate() {
            if n > 1 && i == n - 1 {
                x.color = 1.0;
            }
        }
        if auto_weights {
            f.set_determinant_weights();
        }
    });
    st.selected = Selected::Xform(doc.flame().xforms.len() - 1);
}

/// The canvas: draws and edits the triangles.
pub fn canvas(
    ui: &mut egui::Ui,
    doc: &mut Document,
    st: &mut EditorState,
    auto_weights: bool,
) -> CanvasOutput {
    let mut out = CanvasOutput::default();
    let size = ui.available_size().max(Vec2::new(120.0, 120.0));
    let (rect, resp) = ui.allocate_exact_size(size, Sense::click_and_drag());
    st.canvas = rect;
    st.fix_selection(doc.flame());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 0.0, Color32::from_gray(18));

    // Zoom at the cursor with the wheel.
    if let Some(hp) = resp.hover_pos() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            let before = st.world_from_screen(hp);
            st.zoom =
                (st.zoom * (1.0 + scroll as f64 * 0.002).clamp(0.5, 2.0)).clamp(2.0, 20_000.0);
            let after = st.world_from_screen(hp);
            st.view_center[0] += before[0] - after[0];
            st.view_center[1] += before[1] - after[1];
        }
        st.hover_world = Some(st.world_from_screen(hp));
    } else if st.gesture.is_none() {
        st.hover_world = None;
    }

    // Grid.
    if st.grid {
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

    // Reference triangle.
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

    // Triangles.
    let flame = doc.flame().clone();
    let mut entries: Vec<(Selected, [[f64; 2]; 3], Color32)> = flame
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
    for (sel, t, col) in &entries {
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
        if is_sel {
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
                let pivot = match st.pivot {
                    Pivot::Local => centroid(t),
                    Pivot::World => [0.0, 0.0],
                };
                let pp = st.screen_from_world(pivot);
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
    }

    // Interaction.
    let middle = ui.input(|i| i.pointer.middle_down());
    if resp.drag_started() {
        // Hit-test where the button went down, not where egui recognised the drag, so the
        // grabbed point stays under the pointer.
        let pos = ui
            .input(|i| i.pointer.press_origin())
            .or(resp.interact_pointer_pos())
            .unwrap_or(rect.center());
        let w = st.world_from_screen(pos);
        let pan = middle || resp.dragged_by(egui::PointerButton::Secondary);
        let mut drag = None;
        if !pan {
            // The selected triangle's vertices first, then any triangle's body (topmost last).
            if let Some(x) = xform_of(&flame, st.selected) {
                let t = st.map_of(x).triangle();
                for (k, v) in t.iter().enumerate() {
                    if st.screen_from_world(*v).distance(pos) <= 8.0 {
                        drag = Some(Drag::Vertex(k));
                    }
                }
            }
            if drag.is_none() {
                if let Some((sel, _, _)) = entries
                    .iter()
                    .rev()
                    .find(|(s, t, _)| *s == st.selected && point_in_triangle(w, t))
                {
                    st.selected = *sel;
                    drag = Some(Drag::Body);
                } else if let Some((sel, _, _)) = entries
                    .iter()
                    .rev()
                    .find(|(_, t, _)| point_in_triangle(w, t))
                {
                    st.selected = *sel;
                    drag = Some(Drag::Body);
                }
            }
            if matches!(drag, Some(Drag::Body)) {
                drag = Some(match st.mode {
                    Mode::Move => Drag::Body,
                    Mode::Rotate => Drag::Rotate,
                    Mode::Scale => Drag::Scale,
                });
            }
        }
        let drag = drag.unwrap_or(Drag::Pan);
        let start_tri = xform_of(&flame, st.selected)
            .map(|x| st.map_of(x).triangle())
            .unwrap_or(reference);
        st.gesture = Some(Gesture {
            drag,
            start_world: w,
            start_tri,
            before: doc.begin_gesture(),
        });
    }
    if resp.dragged()
        && let Some(g) = st.gesture.clone()
    {
        out.dragging = true;
        let pos = resp.interact_pointer_pos().unwrap_or(rect.center());
        let w = st.world_from_screen(pos);
        let (dx, dy) = (w[0] - g.start_world[0], w[1] - g.start_world[1]);
        let shift = ui.input(|i| i.modifiers.shift);
        let new_tri = match g.drag {
            Drag::Pan => {
                let d = resp.drag_delta();
                st.view_center[0] -= d.x as f64 / st.zoom;
                st.view_center[1] -= d.y as f64 / st.zoom;
                None
            }
            Drag::Vertex(k) => {
                let mut t = g.start_tri;
                t[k] = [g.start_tri[k][0] + dx, g.start_tri[k][1] + dy];
                Some(t)
            }
            Drag::Body => Some(g.start_tri.map(|p| [p[0] + dx, p[1] + dy])),
            Drag::Rotate => {
                let c = match st.pivot {
                    Pivot::Local => centroid(&g.start_tri),
                    Pivot::World => [0.0, 0.0],
                };
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
                let c = match st.pivot {
                    Pivot::Local => centroid(&g.start_tri),
                    Pivot::World => [0.0, 0.0],
                };
                let d0 =
                    ((g.start_world[0] - c[0]).powi(2) + (g.start_world[1] - c[1]).powi(2)).sqrt();
                let d1 = ((w[0] - c[0]).powi(2) + (w[1] - c[1]).powi(2)).sqrt();
                let k = if d0 > 1e-9 { d1 / d0 } else { 1.0 };
                Some(scale_about(&g.start_tri, c, k))
            }
        };
        if let Some(t) = new_tri {
            let sel = st.selected;
            let mut m = Affine::from_triangle(t);
            if matches!(g.drag, Drag::Body)
                && let Some(x) = xform_of(&g.before, sel)
            {
                // A move changes only the translation: keep the linear part bit for bit.
                let s = st.map_of(x);
                (m.a, m.b, m.c, m.d) = (s.a, s.b, s.c, s.d);
            }
            let edit_post = st.edit_post;
            let f = doc.flame_mut_in_gesture();
            if let Some(x) = xform_of_mut(f, sel) {
                if edit_post {
                    x.post = m;
                } else {
                    x.coefs = m;
                }
            }
            if auto_weights && !edit_post && sel != Selected::Final {
                f.set_determinant_weights();
            }
            out.changed = true;
        }
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

/// The editor's toolbar: modes, pivot, post/final toggles, grid.
pub fn toolbar(ui: &mut egui::Ui, st: &mut EditorState, flame: &Flame) -> Option<EditorAction> {
    let mut action = None;
    ui.horizontal_wrapped(|ui| {
        ui.selectable_value(&mut st.mode, Mode::Move, "Move");
        ui.selectable_value(&mut st.mode, Mode::Rotate, "Rotate");
        ui.selectable_value(&mut st.mode, Mode::Scale, "Scale");
        ui.separator();
        ui.selectable_value(&mut st.pivot, Pivot::Local, "Local pivot");
        ui.selectable_value(&mut st.pivot, Pivot::World, "World pivot");
        ui.separator();
        ui.toggle_value(&mut st.edit_post, "Post");
        ui.toggle_value(&mut st.show_final, "Final");
        ui.toggle_value(&mut st.grid, "Grid");
        if ui.button("Auto zoom").clicked() {
            action = Some(EditorAction::AutoZoom);
        }
        ui.separator();
        let r = egui::ComboBox::from_id_salt("xform-select")
            .selected_text(match st.selected {
                Selected::Xform(i) => format!("Transform {}", i + 1),
                Selected::Final => "Final".to_string(),
            })
            .show_ui(ui, |ui| {
                for i in 0..flame.xforms.len() {
                    ui.selectable_value(
                        &mut st.selected,
                        Selected::Xform(i),
                        format!("Transform {}", i + 1),
                    );
                }
                if flame.final_xform.is_some() {
                    ui.selectable_value(&mut st.selected, Selected::Final, "Final");
                }
            });
        named(r.response, "Selected transform");
    });
    action
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn screen_world_round_trip_and_y_down() {
        let mut st = EditorState {
            canvas: Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(400.0, 300.0)),
            view_center: [1.0, 2.0],
            zoom: 50.0,
            ..EditorState::default()
        };
        let p = st.screen_from_world([1.0, 2.0]);
        assert_eq!(p, st.canvas.center());
        // The reference Y = (0, −1) is above O on screen.
        assert!(st.screen_from_world([0.0, -1.0]).y < st.screen_from_world([0.0, 0.0]).y);
        let w = st.world_from_screen(Pos2::new(100.0, 40.0));
        let back = st.screen_from_world(w);
        assert!((back.x - 100.0).abs() < 1e-3 && (back.y - 40.0).abs() < 1e-3);
        let f = Flame {
            xforms: vec![Xform::linear(
                Affine::new(2.0, 0.0, 0.0, 2.0, 5.0, 5.0),
                1.0,
                0.0,
            )],
            ..Flame::default()
        };
        st.auto_zoom(&f);
        let t = f.xforms[0].coefs.triangle();
        for p in t {
            assert!(st.canvas.contains(st.screen_from_world(p)));
        }
    }

    #[test]
    fn rotation_and_scaling_keep_shape() {
        let t = Affine::new(0.5, 0.2, -0.1, 0.7, 0.3, 0.4).triangle();
        let c = centroid(&t);
        let r = rotate_about(&t, c, 0.7);
        let m0 = Affine::from_triangle(t);
        let m1 = Affine::from_triangle(r);
        assert!((m0.det() - m1.det()).abs() < 1e-12);
        let c1 = centroid(&r);
        assert!((c1[0] - c[0]).abs() < 1e-12 && (c1[1] - c[1]).abs() < 1e-12);
        let s = scale_about(&t, c, 2.0);
        assert!((Affine::from_triangle(s).det() - 4.0 * m0.det()).abs() < 1e-12);
        assert!(point_in_triangle(c, &t));
        assert!(!point_in_triangle([10.0, 10.0], &t));
    }
}
