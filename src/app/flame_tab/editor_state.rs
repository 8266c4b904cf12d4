//! What the triangle editor keeps between frames: the view (centre, zoom), the selection,
//! the drag mode and pivot, the section shown below the canvas; and the geometry of editor
//! triangles. Every xform is drawn as the image of the reference triangle O = (0, 0),
//! X = (1, 0), Y = (0, −1): the triangle of x' = a·x + b·y + e, y' = c·x + d·y + f has the
//! corners O′ = (e, f), X′ = (a + e, c + f), Y′ = (e − b, f − d). World y points down, as in
//! the rendered image; the numbers the editor shows have y up (world y negated), as in
//! Apophysis, so the Y corner reads y = +1 and is drawn above O.

use std::collections::HashMap;

use eframe::egui::{Color32, Pos2, Rect, Vec2};

use super::transform_tools::Amounts;
use super::variations_panel::VarFind;
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
    /// The xform of this index.
    Xform(usize),
    /// The final xform.
    Final,
}

#[derive(Clone, Debug)]
pub(super) enum Drag {
    /// Vertex k (0 = O/A, 1 = X/B, 2 = Y/C) of the selected triangle.
    Vertex(usize),
    Body,
    Rotate,
    Scale,
    Pan,
}

#[derive(Clone, Debug)]
pub(super) struct Gesture {
    pub(super) drag: Drag,
    pub(super) start_world: [f64; 2],
    pub(super) start_tri: [[f64; 2]; 3],
    pub(super) before: Flame,
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
    /// The view was fitted to the triangles and not moved since: it is fitted again when the
    /// canvas changes size.
    pub fitted: bool,
    pub(super) gesture: Option<Gesture>,
    /// The Find box of the variations section.
    pub var_find: VarFind,
    /// The section shown below the canvas.
    pub section: Section,
    /// Weights of transforms switched off in the transform list, by (flame, transform).
    pub off_weights: HashMap<(usize, usize), f64>,
    /// The amounts of the typed-amount tools (turn, scale, move).
    pub amounts: Amounts,
}

/// The sections below the triangle canvas.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Section {
    /// The list of transforms.
    Transforms,
    /// Corners, coefficients, weight and colour of the selected transform.
    #[default]
    Triangle,
    Variations,
    Xaos,
    /// Flame-wide settings.
    Flame,
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
            fitted: false,
            gesture: None,
            var_find: VarFind::default(),
            section: Section::default(),
            off_weights: HashMap::new(),
            amounts: Amounts::default(),
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
        self.fitted = true;
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

pub(super) fn point_in_triangle(p: [f64; 2], t: &[[f64; 2]; 3]) -> bool {
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

pub(super) fn centroid(t: &[[f64; 2]; 3]) -> [f64; 2] {
    [
        (t[0][0] + t[1][0] + t[2][0]) / 3.0,
        (t[0][1] + t[1][1] + t[2][1]) / 3.0,
    ]
}

pub(super) fn rotate_about(t: &[[f64; 2]; 3], c: [f64; 2], ang: f64) -> [[f64; 2]; 3] {
    let (s, co) = ang.sin_cos();
    t.map(|p| {
        let (dx, dy) = (p[0] - c[0], p[1] - c[1]);
        [c[0] + dx * co - dy * s, c[1] + dx * s + dy * co]
    })
}

pub(super) fn scale_about(t: &[[f64; 2]; 3], c: [f64; 2], k: f64) -> [[f64; 2]; 3] {
    t.map(|p| [c[0] + (p[0] - c[0]) * k, c[1] + (p[1] - c[1]) * k])
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
