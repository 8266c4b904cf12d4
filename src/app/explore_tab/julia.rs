//! The Julia set of z² + c by inverse iteration, beside the escape-time picture of the same c
//! (rendered small by the escape engine in the background): one sees where the preimages
//! under-sample the set. c is edited by its fields or by dragging either picture.

use eframe::egui::{self, Color32, Rect, Vec2};

use super::{ExploreRequest, INK, Picture, ScreenFraming, explanation, key_of, section};
use crate::app::worker::{Repaint, TaskWorker, task_worker};
use crate::escape::{C, EscapeDoc, Family, View};
use crate::explore::Bounds;
use crate::explore::julia::InverseJulia;
use crate::explore::raster::{Density, Framing};

/// The square of the plane shown.
const HALF: f64 = 1.8;
/// Most points of the inverse iteration (computed when c changes, on the UI thread).
pub const MAX_POINTS: f64 = 1_000_000.0;
/// Largest |Re c| and |Im c| offered.
pub const C_LIMIT: f64 = 2.0;

/// The Julia topic.
pub struct JuliaView {
    pub c: [f64; 2],
    /// Points of the inverse iteration.
    pub points: f64,
    /// Pixels the inverse iteration hit, and pixels the escape picture has near the set.
    pub covered: usize,
    pub problem: Option<String>,
    inverse: Picture,
    escape: Picture,
    escape_key: Option<u64>,
    escape_worker: Option<TaskWorker<(u64, Result<image::RgbImage, String>)>>,
    repaint: Repaint,
}

impl JuliaView {
    pub fn new(repaint: Repaint) -> JuliaView {
        JuliaView {
            c: [-0.12, 0.75],
            points: 100_000.0,
            covered: 0,
            problem: None,
            inverse: Picture::default(),
            escape: Picture::default(),
            escape_key: None,
            escape_worker: None,
            repaint,
        }
    }

    pub fn reset(&mut self) {
        self.c = [-0.12, 0.75];
        self.points = 100_000.0;
        self.problem = None;
    }

    /// Take a finished escape-time picture.
    pub(super) fn poll(&mut self, ctx: &egui::Context) {
        let Some(w) = &self.escape_worker else {
            return;
        };
        for (k, r) in w.poll() {
            if Some(k) != self.escape_key {
                continue;
            }
            match r {
                Ok(img) => self.escape.set(ctx, "explore-julia-escape", &img),
                Err(e) => self.problem = Some(e),
            }
        }
    }

    /// Whether the orbit of 0 stays bounded (c in the Mandelbrot set: J_c is connected).
    fn connected(&self) -> bool {
        let (cr, ci) = (self.c[0], self.c[1]);
        let (mut x, mut y) = (0.0f64, 0.0f64);
        for _ in 0..2000 {
            let t = x * x - y * y + cr;
            y = 2.0 * x * y + ci;
            x = t;
            if x * x + y * y > 4.0 {
                return false;
            }
        }
        true
    }

    pub(super) fn controls(&mut self, ui: &mut egui::Ui) -> Option<ExploreRequest> {
        explanation(
            ui,
            "Run z² + c backwards: each point has two square roots, ±√(z − c), and picking one \
             at random again and again pulls any start onto the Julia set, because the set \
             repels under z² + c and so attracts under its inverse. It is quick, but the two \
             roots are not equally good: points crowd where the inverse map shrinks most and \
             hardly reach the thin tips and deep fjords, which the escape-time picture beside it \
             shows in full.",
        );
        section(ui, "Parameter c");
        ui.horizontal(|ui| {
            ui.label("c =");
            super::checked_drag(
                ui,
                "c real part",
                &mut self.c[0],
                "Re c",
                -C_LIMIT,
                C_LIMIT,
                0.002,
                &mut self.problem,
            );
            ui.label("+");
            super::checked_drag(
                ui,
                "c imaginary part",
                &mut self.c[1],
                "Im c",
                -C_LIMIT,
                C_LIMIT,
                0.002,
                &mut self.problem,
            );
            ui.label("i");
        });
        ui.horizontal(|ui| {
            for (name, c) in [
                ("Douady rabbit", [-0.12, 0.75]),
                ("Dendrite", [0.0, 1.0]),
                ("Basilica", [-1.0, 0.0]),
                ("Dust", [0.3, 0.5]),
            ] {
                if ui.small_button(name).clicked() {
                    self.c = c;
                }
            }
        });
        ui.horizontal(|ui| {
            ui.label("Points");
            super::checked_drag(
                ui,
                "points",
                &mut self.points,
                "the number of points",
                1000.0,
                MAX_POINTS,
                1000.0,
                &mut self.problem,
            );
        });
        self.points = self.points.round();
        super::problem_label(ui, &self.problem);
        section(ui, "Numbers");
        ui.label(format!(
            "c = {:.4} {:+.4}i, |c| = {:.4}",
            self.c[0],
            self.c[1],
            (self.c[0].powi(2) + self.c[1].powi(2)).sqrt()
        ));
        ui.label(if self.connected() {
            "c is in the Mandelbrot set: J_c is connected"
        } else {
            "c is outside the Mandelbrot set: J_c is dust"
        });
        ui.label(format!(
            "Pixels hit by {} preimages: {}",
            self.points, self.covered
        ));
        ui.add(
            egui::Label::new(egui::RichText::new("Drag either picture to move c.").weak()).wrap(),
        );
        None
    }

    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let (rect, resp, ppp, _size, painter) = super::dark_canvas(ui);
        // Two squares side by side (or one above the other in a tall area).
        let wide = rect.width() >= rect.height();
        let (a, b) = if wide {
            let w = rect.width() / 2.0;
            (
                Rect::from_min_size(rect.min, Vec2::new(w - 4.0, rect.height())),
                Rect::from_min_size(
                    rect.min + Vec2::new(w + 4.0, 0.0),
                    Vec2::new(w - 4.0, rect.height()),
                ),
            )
        } else {
            let h = rect.height() / 2.0;
            (
                Rect::from_min_size(rect.min, Vec2::new(rect.width(), h - 4.0)),
                Rect::from_min_size(
                    rect.min + Vec2::new(0.0, h + 4.0),
                    Vec2::new(rect.width(), h - 4.0),
                ),
            )
        };
        let px = |r: Rect| {
            [
                ((r.width() * ppp) as u32).max(16),
                ((r.height() * ppp) as u32).max(16),
            ]
        };
        let bounds = Bounds {
            min: [-HALF, -HALF],
            max: [HALF, HALF],
        };
        let (sa, sb) = (px(a), px(b));
        let fa = Framing::fit(bounds, sa[0], sa[1], 4.0);
        let sf = ScreenFraming {
            f: fa,
            rect: a,
            ppp,
        };
        if resp.dragged() {
            let d = resp.drag_delta();
            let k = sf.world_per_point();
            self.c[0] = (self.c[0] + d.x as f64 * k).clamp(-C_LIMIT, C_LIMIT);
            self.c[1] = (self.c[1] - d.y as f64 * k).clamp(-C_LIMIT, C_LIMIT);
        }
        let (c, n) = (self.c, self.points as u64);
        let mut covered = None;
        self.inverse.update(
            &ctx,
            "explore-julia-inverse",
            key_of((super::bits(&c), n, sa)),
            || {
                let mut it = InverseJulia::new(C::new(c[0], c[1]), 1).ok()?;
                let mut d = Density::new(sa[0], sa[1]).ok()?;
                for _ in 0..n {
                    d.plot(fa.pixel_from_world(it.next_point()));
                }
                covered = Some(d.covered());
                Some(super::density_image(&d.counts, d.width, d.height, INK))
            },
        );
        if let Some(k) = covered {
            self.covered = k;
        }
        // The escape-time picture at half resolution, in the background.
        let ek = key_of((super::bits(&c), sb));
        if self.escape_key != Some(ek) {
            self.escape_key = Some(ek);
            let r = self.repaint.clone();
            let w = self
                .escape_worker
                .get_or_insert_with(|| task_worker("ugnis-explore-julia", move || r()));
            let (w2, h2) = ((sb[0] / 2).max(16), (sb[1] / 2).max(16));
            let fb = Framing::fit(bounds, w2, h2, 2.0);
            w.submit(Box::new(move |_, _| {
                let mut doc = EscapeDoc::new(Family::Julia {
                    power: 2,
                    c: C::new(c[0], c[1]),
                });
                doc.params.max_iter = 300;
                let view = View::new([0.0, 0.0], h2 as f64 / 2.0 / fb.scale);
                let r = crate::escape::render(&doc.params, view, w2, h2)
                    .map(|(img, _)| img)
                    .map_err(|e| e.to_string());
                (ek, r)
            }));
        }
        self.inverse.paint(&painter, a);
        self.escape.paint(&painter, b);
        for (r, title) in [(a, "inverse iteration"), (b, "escape time")] {
            painter.rect_stroke(
                r,
                0.0,
                egui::Stroke::new(1.0, Color32::from_gray(50)),
                egui::StrokeKind::Inside,
            );
            painter.text(
                r.left_top() + Vec2::new(8.0, 6.0),
                egui::Align2::LEFT_TOP,
                title,
                egui::FontId::proportional(14.0),
                Color32::from_gray(220),
            );
        }
    }
}
