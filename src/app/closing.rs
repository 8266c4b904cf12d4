//! Esc: closes the floating window on top (the one drawn last of those open), or leaves the
//! full-window preview when none is open. A text field being edited keeps its own Esc, and
//! the file chooser, message boxes and the "save changes?" question answer it themselves.

use eframe::egui;

use super::help::HelpPage;
use super::shell::{Tab, UgnisApp};

/// A floating window Esc can close.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Floating {
    Gradient,
    Mutations,
    VariationFilter,
    Help(HelpPage),
    Export,
    AnimationExport,
    LoopTools,
    Sound,
    History,
    Options,
}

impl Floating {
    /// The window's title, which is its layer's id.
    fn title(self) -> &'static str {
        match self {
            Floating::Gradient => "Gradient",
            Floating::Mutations => "Mutations",
            Floating::VariationFilter => "Variations filter",
            Floating::Help(p) => super::help::title(p),
            Floating::Export => "Export image",
            Floating::AnimationExport => "Export animation",
            Floating::LoopTools => "Loop tools",
            Floating::Sound => "Sound-driven motion",
            Floating::History => "History",
            Floating::Options => "Options",
        }
    }
}

/// The layer id of the window titled `title`: `egui::Window::new` makes it from the title's
/// text as an `Option<Cow<str>>`.
fn window_id(title: &str) -> egui::Id {
    egui::Id::unique(Some(std::borrow::Cow::Borrowed(title)))
}

impl UgnisApp {
    /// The floating windows open now.
    fn open_windows(&self) -> Vec<Floating> {
        let f = &self.flame;
        let mut v = Vec::new();
        if f.gradients.open || f.palette_editor.open {
            v.push(Floating::Gradient);
        }
        if f.mutations.open {
            v.push(Floating::Mutations);
        }
        if f.variation_filter.open {
            v.push(Floating::VariationFilter);
        }
        if let Some(p) = self.help {
            v.push(Floating::Help(p));
        }
        if f.export_dialog.is_some() {
            v.push(Floating::Export);
        }
        if f.anim_export.is_some() {
            v.push(Floating::AnimationExport);
        }
        if f.timeline.loop_dialog.is_some() {
            v.push(Floating::LoopTools);
        }
        if f.timeline.sound_dialog.is_some() {
            v.push(Floating::Sound);
        }
        if f.history_open {
            v.push(Floating::History);
        }
        if self.options_dialog.is_some() {
            v.push(Floating::Options);
        }
        v
    }

    fn close_window(&mut self, w: Floating) {
        let f = &mut self.flame;
        match w {
            Floating::Gradient => {
                f.gradients.open = false;
                f.palette_editor.open = false;
            }
            Floating::Mutations => f.mutations.open = false,
            Floating::VariationFilter => f.variation_filter.open = false,
            Floating::Help(_) => self.help = None,
            Floating::Export => f.export_dialog = None,
            Floating::AnimationExport => f.anim_export = None,
            Floating::LoopTools => f.timeline.loop_dialog = None,
            Floating::Sound => f.timeline.sound_dialog = None,
            Floating::History => f.history_open = false,
            Floating::Options => self.options_dialog = None,
        }
    }

    /// Esc was pressed (no text field has the keyboard and no modal dialog is up): close the
    /// window on top, or leave the full-window preview. True when it did something.
    pub(super) fn escape_pressed(&mut self, ctx: &egui::Context) -> bool {
        let open = self.open_windows();
        if !open.is_empty() {
            // Back to front: the last of the open windows' layers is on top.
            let layers: Vec<egui::LayerId> = ctx.memory(|m| m.layer_ids().collect());
            let top = layers.iter().rev().find_map(|l| {
                open.iter()
                    .find(|w| l.order == egui::Order::Middle && l.id == window_id(w.title()))
                    .copied()
            });
            // A window not drawn yet has no layer: the newest of them.
            let w = top.unwrap_or(open[open.len() - 1]);
            self.close_window(w);
            return true;
        }
        if self.tab == Tab::Flame && self.flame.full_view {
            self.flame.full_view = false;
            return true;
        }
        false
    }
}
