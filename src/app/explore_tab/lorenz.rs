//! The Lorenz attractor in 3-D: drag to turn it, σ, r, b sliders, and the sensitivity
//! demonstration — two starts 1e-9 apart drawn in two colours, with their distance.

use eframe::egui::{self, Color32, Pos2, Stroke, Vec2};

use super::{ExploreRequest, explanation, key_of, section};
use crate::explore::lorenz::{DEFAULT_START, Lorenz, P3, View};

/// Integration step.
const H: f64 = 0.01;
/// Longest time shown.
pub const MAX_TIME: f64 = 100.0;
/// How far apart the two starts are (in x).
pub const OFFSET: f64 = 1e-9;

const COLOR_A: Color32 = Color32::from_rgb(240, 170, 60);
const COLOR_B: Color32 = Color32::from_rgb(90, 190, 255);

/// The Lorenz topic.
pub struct LorenzView {
    pub sigma: f64,
    pub r: f64,
    pub b: f64,
    /// Time integrated (both orbits).
    pub time: f64,
    pub yaw: f64,
    pub pitch: f64,
    pub playing: bool,
    pub problem: Option<String>,
    /// Distance of the two orbits at `time`, and the first time it exceeded 1.
    pub distance: f64,
    pub apart_at: Option<f64>,
    orbit_a: Vec<P3>,
    orbit_b: Vec<P3>,
    /// log10 of the distance at every 10th step.
    log_distance: Vec<f32>,
    key: Option<u64>,
}

impl Default for LorenzView {
    fn default() -> Self {
        let d = Lorenz::default();
        LorenzView {
            sigma: d.sigma,
            r: d.r,
            b: d.b,
            time: 40.0,
            // Seen across the line of the two holes (which lies along x = y), a little from above.
            yaw: -0.7,
            pitch: 0.25,
            playing: false,
            problem: None,
            distance: 0.0,
            apart_at: None,
            orbit_a: Vec::new(),
            orbit_b: Vec::new(),
            log_distance: Vec::new(),
            key: None,
        }
    }
}

impl LorenzView {
    /// Integrate both orbits again when a parameter changed.
    pub fn sync(&mut self) {
        let k = key_of(super::bits(&[self.sigma, self.r, self.b, self.time]));
        if self.key == Some(k) {
            return;
        }
        self.key = Some(k);
        let sys = match Lorenz::new(self.sigma, self.r, self.b) {
            Ok(s) => s,
            Err(e) => {
                self.problem = Some(e.to_string());
                return;
            }
        };
        let a = DEFAULT_START;
        let b = [a[0] + OFFSET, a[1], a[2]];
        let Ok(mut twin) = sys.twin(a, b, H) else {
            return;
        };
        let steps = (self.time.clamp(0.0, MAX_TIME) / H).round() as usize;
        self.orbit_a.clear();
        self.orbit_b.clear();
        self.log_distance.clear();
        self.orbit_a.push(a);
        self.orbit_b.push(b);
        self.apart_at = None;
        for i in 0..steps {
            let (p, q) = twin.step();
            self.orbit_a.push(p);
            self.orbit_b.push(q);
            let d = twin.distance();
            if self.apart_at.is_none() && d > 1.0 {
                self.apart_at = Some(twin.time());
            }
            if i % 10 == 0 {
                self.log_distance.push(d.max(1e-300).log10() as f32);
            }
        }
        self.distance = twin.distance();
    }

    pub fn status_text(&self) -> String {
        format!(
            "Lorenz σ {} r {} b {:.4}: t = {:.2}, distance {:.3e}",
            self.sigma, self.r, self.b, self.time, self.distance
        )
    }

    pub(super) fn controls(&mut self, ui: &mut egui::Ui) -> Option<ExploreRequest> {
        explanation(
            ui,
            "Three equations for a fluid heated from below: the point (x, y, z) moves along the \
             flow and winds around two holes without ever repeating or settling down. Start a \
             second point a billionth away and the two move as one for a while, then part and \
             go their own ways: the distance grows about tenfold every couple of time units. \
             This sensitivity is why the weather cannot be forecast far ahead. Drag the picture \
             to turn it.",
        );
        section(ui, "Parameters");
        egui::Grid::new("explore-lorenz")
            .num_columns(2)
            .show(ui, |ui| {
                for (label, v, max, what) in [
                    ("σ", &mut self.sigma, 50.0, "σ (sigma)"),
                    ("r", &mut self.r, 200.0, "r"),
                    ("b", &mut self.b, 20.0, "b"),
                ] {
                    let l = ui.label(label);
                    ui.add(egui::Slider::new(v, 0.01..=max).max_decimals(4))
                        .labelled_by(l.id)
                        .on_hover_text(format!("{what}: 0.01 to {max}"));
                    ui.end_row();
                }
                let l = ui.label("time t");
                ui.add(egui::Slider::new(&mut self.time, 0.0..=MAX_TIME).max_decimals(2))
                    .labelled_by(l.id)
                    .on_hover_text(format!("0 to {MAX_TIME}"));
                ui.end_row();
            });
        ui.horizontal(|ui| {
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).on_hover_text("let time run").clicked() {
                self.playing = !self.playing;
                if self.playing && self.time >= MAX_TIME {
                    self.time = 0.0;
                }
            }
            if ui.button("Lorenz's values").clicked() {
                let d = Lorenz::default();
                (self.sigma, self.r, self.b) = (d.sigma, d.r, d.b);
            }
        });
        self.sync();
        super::problem_label(ui, &self.problem);
        section(ui, "Sensitivity");
        ui.label(format!(
            "Starts: (1, 1, 1) and (1 + 1e-9, 1, 1)\nDistance at t = {:.2}: {:.3e}",
            self.time, self.distance
        ));
        match self.apart_at {
            Some(t) => ui.label(format!("More than 1 apart from t = {t:.2}")),
            None => ui.label("Still less than 1 apart"),
        };
        // log10 of the distance over time.
        let (rect, _) =
            ui.allocate_exact_size(Vec2::new(ui.available_width(), 90.0), egui::Sense::hover());
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 2.0, Color32::from_gray(20));
        if self.log_distance.len() > 1 {
            let n = self.log_distance.len() as f32;
            let to = |i: usize, v: f32| {
                Pos2::new(
                    rect.left() + i as f32 / (n - 1.0) * rect.width(),
                    rect.bottom() - (v + 10.0) / 12.0 * rect.height(),
                )
            };
            let pts: Vec<Pos2> = self
                .log_distance
                .iter()
                .enumerate()
                .map(|(i, v)| to(i, v.clamp(-10.0, 2.0)))
                .collect();
            painter.add(egui::Shape::line(pts, Stroke::new(1.2, COLOR_B)));
            let y1 = rect.bottom() - 10.0 / 12.0 * rect.height();
            painter.line_segment(
                [Pos2::new(rect.left(), y1), Pos2::new(rect.right(), y1)],
                Stroke::new(1.0, Color32::from_gray(70)),
            );
        }
        painter.text(
            rect.left_top() + Vec2::new(4.0, 2.0),
            egui::Align2::LEFT_TOP,
            "log10 of the distance (−10 to 2; line at distance 1)",
            egui::FontId::proportional(11.0),
            Color32::from_gray(180),
        );
        section(ui, "Numbers");
        if let Ok(sys) = Lorenz::new(self.sigma, self.r, self.b) {
            for e in sys.equilibria() {
                ui.label(format!(
                    "Equilibrium ({:.4}, {:.4}, {:.4})",
                    e[0], e[1], e[2]
                ));
            }
        }
        ui.label(format!(
            "Steps: {} of h = {H}",
            self.orbit_a.len().saturating_sub(1)
        ));
        None
    }

    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        if self.playing {
            self.time = (self.time + 0.05).min(MAX_TIME);
            if self.time >= MAX_TIME {
                self.playing = false;
            }
            ctx.request_repaint();
        }
        self.sync();
        let (rect, resp, _ppp, _size, painter) = super::dark_canvas(ui);
        if resp.dragged() {
            let d = resp.drag_delta();
            self.yaw += d.x as f64 * 0.01;
            self.pitch = (self.pitch + d.y as f64 * 0.01).clamp(-1.5, 1.5);
        }
        let view = View::Turned {
            yaw: self.yaw,
            pitch: self.pitch,
        };
        // Centre the attractor (about z = r − 1) and fit its half-size (about r) in the view.
        let z0 = (self.r - 1.0).max(0.0);
        let size = (0.9 * self.r + 2.0).max(5.0);
        let scale = rect.width().min(rect.height()) as f64 / (2.2 * size);
        let to = |p: P3| {
            let q = view.project([p[0], p[1], p[2] - z0]);
            rect.center() + Vec2::new((q[0] * scale) as f32, (-q[1] * scale) as f32)
        };
        let line = |pts: &[P3], stroke: Stroke| {
            // Long paths in pieces (the tessellator handles them better).
            for i in (0..pts.len().saturating_sub(1)).step_by(4000) {
                let chunk = &pts[i..(i + 4001).min(pts.len())];
                let v: Vec<Pos2> = chunk.iter().map(|p| to(*p)).collect();
                painter.add(egui::Shape::line(v, stroke));
            }
        };
        line(&self.orbit_a, Stroke::new(1.6, COLOR_A));
        line(&self.orbit_b, Stroke::new(0.8, COLOR_B));
        if let (Some(a), Some(b)) = (self.orbit_a.last(), self.orbit_b.last()) {
            painter.circle_filled(to(*a), 5.0, COLOR_A);
            painter.circle_filled(to(*b), 5.0, COLOR_B);
        }
        painter.text(
            rect.left_top() + Vec2::new(10.0, 8.0),
            egui::Align2::LEFT_TOP,
            format!(
                "t = {:.2}   distance {:.3e}\norange: start (1, 1, 1); blue: 1e-9 further in x",
                self.time, self.distance
            ),
            egui::FontId::proportional(14.0),
            Color32::from_gray(220),
        );
    }
}
