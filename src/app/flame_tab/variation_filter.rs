//! The variations filter (as in Fractorium): which variations random flames and random
//! batches may use. The list is kept in the options; "Use for random flames" makes Random
//! flame, Random batch and the mutations draw from it.

use eframe::egui;

use super::variations_panel::{NAMES, matching};
use crate::app::options::Options;
use crate::flame::variations;

/// The window's state.
#[derive(Default)]
pub struct VariationFilter {
    pub open: bool,
    pub find: String,
}

impl VariationFilter {
    /// Show the window; returns true when the options changed.
    pub fn show(&mut self, ctx: &egui::Context, options: &mut Options) -> bool {
        if !self.open {
            return false;
        }
        let before = (
            options.variation_filter.clone(),
            options.use_variation_filter,
        );
        let mut open = self.open;
        egui::Window::new("Variations filter")
            .open(&mut open)
            .default_size([360.0, 480.0])
            .show(ctx, |ui| {
                ui.checkbox(&mut options.use_variation_filter, "Use for random flames")
                    .on_hover_text(
                        "Random flame, Random batch and Mutations draw one or two of the ticked \
                         variations per transform",
                    );
                ui.horizontal(|ui| {
                    let l = ui.label("Find");
                    ui.text_edit_singleline(&mut self.find)
                        .labelled_by(l.id)
                        .on_hover_text("part of a variation name");
                });
                let shown = matching(&self.find);
                ui.horizontal(|ui| {
                    if ui
                        .button("Tick shown")
                        .on_hover_text("tick every variation in the list below")
                        .clicked()
                    {
                        for &i in &shown {
                            let n = &NAMES[i].name;
                            if !options.variation_filter.contains(n) {
                                options.variation_filter.push(n.clone());
                            }
                        }
                    }
                    if ui
                        .button("Untick shown")
                        .on_hover_text("untick every variation in the list below")
                        .clicked()
                    {
                        let gone: Vec<&String> = shown.iter().map(|&i| &NAMES[i].name).collect();
                        options.variation_filter.retain(|n| !gone.contains(&n));
                    }
                    if ui
                        .button("Thesis seven")
                        .on_hover_text(
                            "linear, sinusoidal, spherical, swirl, horseshoe, polar, bent",
                        )
                        .clicked()
                    {
                        options.variation_filter = variations::THESIS_SEVEN
                            .iter()
                            .map(|&id| variations::info(id).name.to_string())
                            .collect();
                    }
                });
                ui.label(format!(
                    "{} ticked; {} shown of {}",
                    options.variation_filter.len(),
                    shown.len(),
                    NAMES.len()
                ));
                ui.separator();
                let row_h = ui.spacing().interact_size.y + ui.spacing().item_spacing.y;
                egui::ScrollArea::vertical()
                    .id_salt("filter-list")
                    .auto_shrink([false, false])
                    .show_rows(ui, row_h, shown.len(), |ui, range| {
                        for &i in &shown[range] {
                            let n = &NAMES[i].name;
                            let mut on = options.variation_filter.contains(n);
                            if ui.checkbox(&mut on, n.as_str()).changed() {
                                if on {
                                    options.variation_filter.push(n.clone());
                                } else {
                                    options.variation_filter.retain(|m| m != n);
                                }
                            }
                        }
                    });
            });
        self.open = open;
        (
            options.variation_filter.clone(),
            options.use_variation_filter,
        ) != before
    }
}
