//! Fractal interpolation: click to add data points, drag them, one slider per vertical
//! scaling d_i; the curve through the points and its dimension.

use eframe::egui::{self, Color32, Stroke};

use super::{ExploreRequest, explanation, section};
use crate::explore::Bounds;
use crate::explore::fif::{Fif, MAX_POINTS};

/// Most curve points drawn.
pub const CURVE_POINTS: f64 = 60_000.0;
/// Largest |d_i| the sliders offer (the engine needs |d_i| < 1).
pub const MAX_D: f64 = 0.99;
/// The world shown: points can be placed and dragged inside it.
const WORLD: Bounds = Bounds {
    min: [-0.05, -1.0],
    max: [1.05, 1.6],
};

/// The world shown stretched over a rectangle of the screen (a graph: x and y scaled apart).
#[derive(Clone, Copy)]
struct Graph {
    rect: egui::Rect,
}

impl Graph {
    fn to_screen(self, p: [f64; 2]) -> egui::Pos2 {
        let r = self.rect;
        egui::pos2(
            r.left() + ((p[0] - WORLD.min[0]) / WORLD.width()) as f32 * r.width(),
            r.bottom() - ((p[1] - WORLD.min[1]) / WORLD.height()) as f32 * r.height(),
        )
    }

    fn to_world(self, s: egui::Pos2) -> [f64; 2] {
        let r = self.rect;
        [
            WORLD.min[0] + ((s.x - r.left()) / r.width()) as f64 * WORLD.width(),
            WORLD.min[1] + ((r.bottom() - s.y) / r.height()) as f64 * WORLD.height(),
        ]
    }
}

/// The fractal interpolation topic.
pub struct FifView {
    pub fif: Fif,
    dragging: Option<usize>,
    pub problem: Option<String>,
    /// Where the graph was last drawn.
    graph: Option<Graph>,
}

impl Default for FifView {
    fn default() -> Self {
        FifView {
            fif: Fif::new(
                vec![[0.0, 0.0], [1.0 / 3.0, 0.6], [2.0 / 3.0, 0.2], [1.0, 0.7]],
                vec![0.5, -0.5, 0.5],
            )
            .expect("valid default data"),
            dragging: None,
            problem: None,
            graph: None,
        }
    }
}

impl FifView {
    /// Where the world point `p` was last shown on the screen.
    pub fn screen_of(&self, p: [f64; 2]) -> Option<egui::Pos2> {
        self.graph.map(|g| g.to_screen(p))
    }

    /// The dimension line (the tests read it).
    pub fn dimension_text(&self) -> String {
        format!("Dimension D = {:.5}", self.fif.dimension())
    }

    /// Set d_i (1-based); a refused value is explained in `problem`.
    pub fn set_scaling(&mut self, i: usize, d: f64) {
        match self.fif.set_scaling(i, d) {
            Ok(()) => self.problem = None,
            Err(e) => self.problem = Some(e.to_string()),
        }
    }

    /// Add a data point at `p`, between the points around its x (the new interval gets the
    /// scaling of the one it splits).
    pub fn add_point(&mut self, p: [f64; 2]) {
        let pts = self.fif.points();
        if pts.len() >= MAX_POINTS {
            self.problem = Some(format!("At most {MAX_POINTS} data points"));
            return;
        }
        let i = pts.partition_point(|q| q[0] < p[0]);
        if pts.get(i).is_some_and(|q| q[0] == p[0]) {
            self.problem = Some("A data point with this x is already there".into());
            return;
        }
        let mut points = pts.to_vec();
        let mut d = self.fif.scalings().to_vec();
        points.insert(i, p);
        // Splitting interval j (1-based, between points j−1 and j): both halves keep its d;
        // a point beyond either end opens a new interval with d = 0.3.
        if i == 0 || i == pts.len() {
            d.insert(if i == 0 { 0 } else { d.len() }, 0.3);
        } else {
            d.insert(i - 1, d[i - 1]);
        }
        match Fif::new(points, d) {
            Ok(f) => {
                self.fif = f;
                self.problem = None;
            }
            Err(e) => self.problem = Some(e.to_string()),
        }
    }

    /// Remove data point `i` (at least two stay).
    pub fn remove_point(&mut self, i: usize) {
        let n = self.fif.points().len();
        if n <= 2 || i >= n {
            self.problem = Some("A curve needs at least two data points".into());
            return;
        }
        let mut points = self.fif.points().to_vec();
        let mut d = self.fif.scalings().to_vec();
        points.remove(i);
        d.remove(i.saturating_sub(1).min(d.len() - 1));
        if let Ok(f) = Fif::new(points, d) {
            self.fif = f;
        }
    }

    pub(super) fn controls(&mut self, ui: &mut egui::Ui) -> Option<ExploreRequest> {
        explanation(
            ui,
            "Join data points by a curve that is rough at every scale. Each interval between \
             two neighbouring points gets a shrunken copy of the whole curve, sheared to fit \
             its end points, and squashed vertically by its factor d. With all d = 0 the copies \
             are flat and you get the straight-line join; the larger the d, the rougher the \
             curve. Click in the picture to add a point, drag points to move them, right-click \
             to remove one.",
        );
        section(ui, "Vertical scalings");
        let n = self.fif.scalings().len();
        let mut change = None;
        egui::Grid::new("explore-fif-d")
            .num_columns(2)
            .show(ui, |ui| {
                for i in 1..=n {
                    let mut d = self.fif.scalings()[i - 1];
                    let l = ui.label(format!("d{i}"));
                    if ui
                        .add(egui::Slider::new(&mut d, -MAX_D..=MAX_D).max_decimals(3))
                        .labelled_by(l.id)
                        .on_hover_text(format!(
                            "vertical scaling of interval {i}: −{MAX_D} to {MAX_D}"
                        ))
                        .changed()
                    {
                        change = Some((i, d));
                    }
                    ui.end_row();
                }
            });
        if let Some((i, d)) = change {
            self.set_scaling(i, d);
        }
        ui.horizontal(|ui| {
            if ui.button("All d = 0").clicked() {
                for i in 1..=n {
                    self.set_scaling(i, 0.0);
                }
            }
            if ui.button("All d = 0.6").clicked() {
                for i in 1..=n {
                    self.set_scaling(i, 0.6);
                }
            }
        });
        super::problem_label(ui, &self.problem);
        section(ui, "Numbers");
        let sum: f64 = self.fif.scalings().iter().map(|d| d.abs()).sum();
        ui.label(format!("Data points: {}", self.fif.points().len()));
        ui.label(format!("Σ|d_i| = {sum:.4}"));
        ui.label(self.dimension_text());
        let why = if self.fif.collinear() {
            "the data lie on a line, so the curve is that line: D = 1"
        } else if sum <= 1.0 {
            "Σ|d_i| ≤ 1: the copies shrink fast enough to leave a curve of dimension 1"
        } else {
            "D solves Σ|d_i|·a_i^(D−1) = 1, a_i the share of each interval in the x range"
        };
        ui.add(egui::Label::new(egui::RichText::new(why).weak()).wrap());
        None
    }

    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let (rect, resp, _ppp, _size, painter) = super::dark_canvas(ui);
        let sf = Graph {
            rect: rect.shrink(20.0),
        };
        self.graph = Some(sf);
        // The axis y = 0.
        painter.line_segment(
            [
                sf.to_screen([WORLD.min[0], 0.0]),
                sf.to_screen([WORLD.max[0], 0.0]),
            ],
            Stroke::new(1.0, Color32::from_gray(60)),
        );
        // Interaction: drag a point, click to add, right-click to remove.
        let near = |pos: egui::Pos2, pts: &[[f64; 2]]| {
            pts.iter()
                .enumerate()
                .map(|(i, p)| (i, sf.to_screen(*p).distance(pos)))
                .filter(|(_, d)| *d < 10.0)
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(i, _)| i)
        };
        // The press position picks the point (a quick drag is already away from it when the
        // drag is recognised).
        if resp.drag_started_by(egui::PointerButton::Primary)
            && let Some(pos) = ui.input(|i| i.pointer.press_origin())
        {
            self.dragging = near(pos, self.fif.points());
        }
        if let (Some(i), Some(pos)) = (self.dragging, resp.interact_pointer_pos())
            && resp.dragged()
        {
            let mut w = sf.to_world(pos);
            w[0] = w[0].clamp(WORLD.min[0], WORLD.max[0]);
            w[1] = w[1].clamp(WORLD.min[1], WORLD.max[1]);
            // Points keep their order along x: a refused move leaves the point where it was.
            match self.fif.set_point(i, w) {
                Ok(()) => self.problem = None,
                Err(_) => self.problem = Some("Points keep their order from left to right".into()),
            }
        }
        if resp.drag_stopped() {
            self.dragging = None;
        }
        if resp.clicked()
            && let Some(pos) = resp.interact_pointer_pos()
            && near(pos, self.fif.points()).is_none()
        {
            self.add_point(sf.to_world(pos));
        }
        if resp.secondary_clicked()
            && let Some(pos) = resp.interact_pointer_pos()
            && let Some(i) = near(pos, self.fif.points())
        {
            self.remove_point(i);
        }
        // The curve, as deep as the point budget allows.
        let n = self.fif.maps().len().max(2) as f64;
        let depth = ((CURVE_POINTS.ln() / n.ln()).floor() as u32)
            .saturating_sub(1)
            .min(30);
        if let Ok(curve) = self.fif.curve(depth) {
            let pts: Vec<egui::Pos2> = curve.iter().map(|p| sf.to_screen(*p)).collect();
            painter.add(egui::Shape::line(
                pts,
                Stroke::new(1.2, super::rgb(super::INK)),
            ));
        }
        for (i, p) in self.fif.points().iter().enumerate() {
            let s = sf.to_screen(*p);
            let col = if Some(i) == self.dragging {
                Color32::WHITE
            } else {
                Color32::from_rgb(120, 200, 255)
            };
            painter.circle_filled(s, 5.0, col);
        }
        painter.text(
            rect.left_top() + egui::vec2(10.0, 8.0),
            egui::Align2::LEFT_TOP,
            self.dimension_text(),
            egui::FontId::proportional(15.0),
            Color32::from_gray(220),
        );
    }
}
