//! The mutation window: a 3×3 grid with the current flame in the centre and eight mutants
//! around it; a "how far" slider; clicking a mutant makes it the current flame (one undo step).

use eframe::egui::{self, Vec2};

use super::thumbnails::Thumbnails;
use crate::flame::Flame;
use crate::flame::mutate::{self, GRID, Mutation};
use crate::flame::random::RandomOptions;
use crate::flame::rng::FastRng;

const THUMB: (u32, u32) = (160, 120);

/// Mutation window state.
pub struct MutationWindow {
    pub open: bool,
    /// How far the mutants move, 0.05–1.
    pub distance: f64,
    seed: u64,
    /// The centre, distance and seed the mutants were made for.
    made_for: Option<(Flame, u64, u64)>,
    pub mutants: Vec<Flame>,
    thumbs: Option<Thumbnails>,
}

impl Default for MutationWindow {
    fn default() -> Self {
        MutationWindow {
            open: false,
            distance: 0.3,
            seed: 1,
            made_for: None,
            mutants: Vec::new(),
            thumbs: None,
        }
    }
}

fn label(k: Mutation) -> &'static str {
    match k {
        Mutation::Coefficients => "triangles",
        Mutation::Variations => "variations",
        Mutation::Colours => "colours",
        Mutation::AddTransform => "+ transform",
        Mutation::RemoveTransform => "− transform",
        Mutation::Symmetry => "symmetry",
        Mutation::Mixed => "mixed",
    }
}

impl MutationWindow {
    /// Make the mutants of `centre` if they are stale.
    pub fn refresh(&mut self, centre: &Flame, opts: &RandomOptions) {
        let fresh = match &self.made_for {
            Some((c, d, s)) => c != centre || *d != self.distance.to_bits() || *s != self.seed,
            None => true,
        };
        if fresh {
            self.mutants = mutate::grid(centre, self.distance, self.seed, opts);
            self.made_for = Some((centre.clone(), self.distance.to_bits(), self.seed));
        }
    }

    /// Show the window. Returns the mutant the user chose. `render`: draw thumbnails (false
    /// in tests without a renderer).
    pub fn show(
        &mut self,
        ctx: &egui::Context,
        centre: &Flame,
        opts: &RandomOptions,
        render: bool,
    ) -> Option<Flame> {
        if !self.open {
            return None;
        }
        self.refresh(centre, opts);
        if render && self.thumbs.is_none() {
            self.thumbs = Some(Thumbnails::new(Some(ctx), THUMB.0, THUMB.1, 15.0));
        }
        let mut open = self.open;
        let mut chosen = None;
        let screen = ctx.content_rect();
        egui::Window::new("Mutations")
            .open(&mut open)
            .resizable(false)
            .default_pos([screen.center().x - 270.0, screen.top() + 70.0])
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
                    ui.label("How far");
                    ui.add(egui::Slider::new(&mut self.distance, 0.05..=1.0));
                    if ui
                        .button("New mutants")
                        .on_hover_text("another set at the same distance")
                        .clicked()
                    {
                        self.seed = FastRng::new(self.seed).u64();
                    }
                });
                let size = Vec2::new(THUMB.0 as f32, THUMB.1 as f32);
                let mutants = self.mutants.clone();
                egui::Grid::new("mutant-grid")
                    .spacing([6.0, 6.0])
                    .show(ui, |ui| {
                        for cell in 0..9 {
                            // Reading order with the centre flame in the middle.
                            let (f, what) = match cell {
                                4 => (centre, "current"),
                                c => {
                                    let i = if c < 4 { c } else { c - 1 };
                                    (&mutants[i], label(GRID[i]))
                                }
                            };
                            let tex = self.thumbs.as_mut().and_then(|t| t.get((0, cell), f));
                            ui.vertical(|ui| {
                                let r = match tex {
                                    Some(t) => {
                                        let r = ui.add(
                                            egui::Image::new((t, size)).sense(egui::Sense::click()),
                                        );
                                        ui.label(what);
                                        r
                                    }
                                    None => ui.add(egui::Button::new(what).min_size(size)),
                                };
                                if cell != 4 && r.clicked() {
                                    chosen = Some(f.clone());
                                }
                            });
                            if cell % 3 == 2 {
                                ui.end_row();
                            }
                        }
                    });
                ui.label("Click a mutant to make it the current flame (Undo returns).");
            });
        if let Some(t) = &mut self.thumbs {
            t.end_frame(ctx);
        }
        self.open = open;
        chosen
    }
}
