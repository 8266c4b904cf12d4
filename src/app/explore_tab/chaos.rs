//! The chaos game, animated: Kovács' triangle game or any textbook IFS, a number of points per
//! frame, pause and reset; an IFS opens in the flame tab as a flame.

use eframe::egui::{self, Color32, Stroke};

use super::{ExploreRequest, INK, Picture, ScreenFraming, checked_drag, explanation, section};
use crate::explore::Bounds;
use crate::explore::ifs::{ChaosGame, Ifs, presets};
use crate::explore::raster::{Density, Framing};

/// Most points one run may be set to plot.
pub const MAX_PLOTTED: f64 = 5_000_000.0;
/// Most points per frame.
pub const MAX_SPEED: f64 = 200_000.0;

const SQRT3_2: f64 = 0.866_025_403_784_438_6;

/// The chaos game topic.
pub struct ChaosView {
    /// 0: Kovács' triangle game; i > 0: `presets()[i − 1]`.
    pub choice: usize,
    presets: Vec<Ifs>,
    game: ChaosGame,
    /// Points plotted so far.
    pub plotted: u64,
    /// Points per frame.
    pub speed: f64,
    /// Points after which the game stops by itself (an idle window must not keep working).
    pub limit: f64,
    pub paused: bool,
    seed: u64,
    density: Option<(Density, Framing)>,
    picture: Picture,
    problem: Option<String>,
}

impl Default for ChaosView {
    fn default() -> Self {
        ChaosView {
            choice: 0,
            presets: presets::all(),
            game: ChaosGame::triangle(1),
            plotted: 0,
            speed: 20.0,
            limit: 200_000.0,
            paused: false,
            seed: 1,
            density: None,
            picture: Picture::default(),
            problem: None,
        }
    }
}

impl ChaosView {
    /// The IFS being played.
    pub fn ifs(&self) -> Ifs {
        match self.choice {
            0 => presets::kovacs_sierpinski(),
            i => self.presets[i - 1].clone(),
        }
    }

    fn name(&self) -> String {
        match self.choice {
            0 => "Triangle (three corners, halfway)".into(),
            i => self.presets[i - 1].name.clone(),
        }
    }

    /// Start again from no points (same choice, a new seed).
    pub fn reset(&mut self) {
        self.seed = self.seed.wrapping_add(1);
        self.game = match self.choice {
            0 => ChaosGame::triangle(self.seed),
            i => self.presets[i - 1].chaos_game([0.0, 0.0], 20, self.seed),
        };
        self.plotted = 0;
        self.density = None;
        self.picture.invalidate();
    }

    /// Whether points are still being added.
    pub fn running(&self) -> bool {
        !self.paused && self.plotted < self.limit as u64
    }

    pub fn status_text(&self) -> String {
        format!(
            "{}: {} points{}",
            self.name(),
            self.plotted,
            if self.paused { " (paused)" } else { "" }
        )
    }

    pub(super) fn controls(&mut self, ui: &mut egui::Ui) -> Option<ExploreRequest> {
        let mut req = None;
        explanation(
            ui,
            "Pick one of the three corners of a triangle at random and move halfway towards it; \
             mark the point and repeat. However the dice fall, the points settle on the \
             Sierpinski triangle: each move is one of three maps that shrink the plane by half, \
             and the triangle is the one set the three maps together reproduce. Any such list \
             of shrinking maps (an IFS) plays the same game, with probabilities that decide how \
             often each map is picked.",
        );
        section(ui, "Game");
        let mut chosen = None;
        egui::ComboBox::from_id_salt("explore-chaos-ifs")
            .selected_text(self.name())
            .width(260.0)
            .show_ui(ui, |ui| {
                if ui
                    .selectable_label(self.choice == 0, "Triangle (three corners, halfway)")
                    .clicked()
                {
                    chosen = Some(0);
                }
                for (i, p) in self.presets.iter().enumerate() {
                    if ui
                        .selectable_label(self.choice == i + 1, p.name.as_str())
                        .clicked()
                    {
                        chosen = Some(i + 1);
                    }
                }
            });
        if let Some(c) = chosen
            && c != self.choice
        {
            self.choice = c;
            self.reset();
        }
        ui.horizontal(|ui| {
            ui.label("Points per frame");
            checked_drag(
                ui,
                "points per frame",
                &mut self.speed,
                "points per frame",
                1.0,
                MAX_SPEED,
                1.0,
                &mut self.problem,
            );
        });
        ui.horizontal(|ui| {
            ui.label("Stop after");
            checked_drag(
                ui,
                "stop after points",
                &mut self.limit,
                "the number of points",
                1.0,
                MAX_PLOTTED,
                1000.0,
                &mut self.problem,
            );
            ui.label("points");
        });
        self.speed = self.speed.round();
        self.limit = self.limit.round();
        super::problem_label(ui, &self.problem);
        ui.horizontal(|ui| {
            let label = if self.paused { "Resume" } else { "Pause" };
            if ui.button(label).clicked() {
                self.paused = !self.paused;
            }
            if ui
                .button("Reset")
                .on_hover_text("start again from no points")
                .clicked()
            {
                self.reset();
            }
            if ui
                .button("Open in Flame tab")
                .on_hover_text("edit this IFS as a flame (linear transforms)")
                .clicked()
            {
                req = Some(ExploreRequest::OpenInFlameTab(Box::new(self.ifs())));
            }
        });
        section(ui, "Numbers");
        let ifs = self.ifs();
        ui.label(format!("Points plotted: {}", self.plotted));
        ui.label(format!("Steps taken: {}", self.game.steps()));
        ui.label(format!("Maps: {}", ifs.maps.len()));
        let probs = ifs.normalised_probs();
        ui.label(format!(
            "Probabilities: {}",
            probs
                .iter()
                .map(|p| format!("{p:.3}"))
                .collect::<Vec<_>>()
                .join(", ")
        ));
        let sum = ifs.probability_sum();
        if (sum - 1.0).abs() > 1e-9 {
            ui.label(format!("(as given they sum to {sum:.3}; normalised)"));
        }
        match ifs.similarity_dimension() {
            Some(d) => ui.label(format!("Similarity dimension: {d:.5}")),
            None => ui.label("Similarity dimension: none (the maps are not similarities)"),
        };
        if self.plotted >= self.limit as u64 {
            ui.label(format!("Stopped after {} points.", self.limit));
        }
        req
    }

    /// Add this frame's points (before the numbers are shown, so they are this frame's).
    pub(super) fn tick(&mut self) {
        if self.running()
            && let Some((d, f)) = &mut self.density
        {
            let n = (self.speed as u64).min((self.limit as u64).saturating_sub(self.plotted));
            self.game.run(n, |p, _| d.plot(f.pixel_from_world(p)));
            self.plotted += n;
        }
    }

    /// A picture of the canvas size (a new size starts the game again).
    fn fit(&mut self, size: [u32; 2]) {
        let fresh = !matches!(&self.density, Some((d, _)) if [d.width, d.height] == size);
        if fresh {
            // A new size starts the picture again.
            if self.plotted > 0 {
                self.reset();
            }
            let Ok(d) = Density::new(size[0], size[1]) else {
                return;
            };
            let bounds = match self.choice {
                0 => Bounds {
                    min: [0.0, 0.0],
                    max: [1.0, SQRT3_2],
                },
                _ => Bounds::of(self.ifs().points(20_000, 7)),
            };
            let margin = 12.0 + 0.04 * size[0].min(size[1]) as f64;
            self.density = Some((d, Framing::fit(bounds, size[0], size[1], margin)));
        }
    }

    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let (rect, _resp, ppp, size, painter) = super::dark_canvas(ui);
        self.fit(size);
        let Some((d, f)) = &self.density else {
            return;
        };
        let key = super::key_of((self.plotted, size, self.choice, self.seed));
        self.picture.update(&ctx, "explore-chaos", key, || {
            Some(super::density_image(&d.counts, d.width, d.height, INK))
        });
        self.picture.paint(&painter, rect);
        let sf = ScreenFraming { f: *f, rect, ppp };
        if self.choice == 0 {
            let corners = [[0.0, 0.0], [1.0, 0.0], [0.5, SQRT3_2]];
            for (i, c) in corners.iter().enumerate() {
                let p = sf.to_screen(*c);
                painter.circle_filled(p, 5.0, Color32::from_rgb(120, 200, 255));
                painter.text(
                    p + egui::vec2(0.0, if i == 2 { -10.0 } else { 10.0 }),
                    if i == 2 {
                        egui::Align2::CENTER_BOTTOM
                    } else {
                        egui::Align2::CENTER_TOP
                    },
                    ["A", "B", "C"][i],
                    egui::FontId::proportional(14.0),
                    Color32::from_rgb(120, 200, 255),
                );
            }
        }
        // The current point, so slow games show the walk.
        let p = sf.to_screen(self.game.point());
        if rect.contains(p) {
            painter.circle_stroke(p, 4.0, Stroke::new(1.5, Color32::from_rgb(255, 90, 90)));
        }
        if self.running() {
            ctx.request_repaint();
        }
    }
}
