//! The shell's bars and input: menu bar, toolbar, status bar, keyboard shortcuts, pasted
//! flames and dropped files.

use std::path::PathBuf;

use eframe::egui;

use super::actions::{self, Action, MENU, MENUS, VARIATION_MENU};
use super::dialogs::Purpose;
use super::files::Pending;
use super::shell::{Tab, UgnisApp};
use crate::flame::random::VariationMode;
use crate::io;

impl UgnisApp {
    /// Shortcuts, pasted flames and dropped files.
    pub(super) fn handle_input(&mut self, ctx: &egui::Context) {
        let typing = ctx.memory(|m| m.focused().is_some());
        let mut fired = Vec::new();
        let all = actions::shortcuts();
        ctx.input_mut(|i| {
            for (s, a) in &all {
                // Let text fields keep their own Ctrl+Z etc.
                if typing && matches!(a, Action::Undo | Action::Redo) {
                    continue;
                }
                if i.consume_shortcut(s) {
                    fired.push(*a);
                }
            }
        });
        for a in fired {
            self.act(ctx, a);
        }
        // Pasted text that is a flame becomes a new flame of the document.
        let pasted: Vec<String> = ctx.input(|i| {
            i.events
                .iter()
                .filter_map(|e| match e {
                    egui::Event::Paste(s) => Some(s.clone()),
                    _ => None,
                })
                .collect()
        });
        for text in pasted {
            if !(self.expect_paste || (!typing && text.contains("<flame"))) {
                continue;
            }
            self.expect_paste = false;
            self.flame.paste(&text);
        }
        // Files dropped on the window open.
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_path_buf())
                .filter(|p| !p.as_os_str().is_empty())
                .collect()
        });
        if let Some(p) = dropped.into_iter().next() {
            match io::kind_of(&p) {
                io::FileKind::Ugr | io::FileKind::Map | io::FileKind::Ggr => {
                    self.file_chosen(Purpose::LoadGradient, p)
                }
                io::FileKind::Jpeg | io::FileKind::Gif | io::FileKind::Bmp => {
                    self.file_chosen(Purpose::GradientFromImage, p)
                }
                _ => self.guard_dirty(Pending::Open(p), "opening the dropped file"),
            }
        }
    }

    /// Whether a menu entry shows a tick, and whether it can be used now.
    fn menu_state(&self, a: Action) -> (Option<bool>, bool) {
        let f = &self.flame;
        let checked = match a {
            Action::ToggleToolbar => Some(self.show_toolbar),
            Action::ToggleStatusBar => Some(self.show_status),
            Action::ToggleFilePanel => Some(f.show_files),
            Action::ToggleEditor => Some(f.show_editor),
            Action::ToggleAnimate => Some(f.animation.is_some()),
            Action::ToggleMorph => Some(f.morph.is_some()),
            _ => None,
        };
        let enabled = match a {
            Action::Undo => f.doc().can_undo(),
            Action::Redo => f.doc().can_redo(),
            Action::RandomBatch => !f.batch_running(),
            _ => true,
        };
        (checked, enabled)
    }

    pub(super) fn menu_bar(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let mut chosen = None;
        egui::MenuBar::new().ui(ui, |ui| {
            for menu in MENUS {
                ui.menu_button(menu, |ui| {
                    for m in MENU.iter().filter(|m| m.menu == menu) {
                        if menu == "Tools" && m.action == Action::ToggleEditor {
                            ui.menu_button("Variations", |ui| {
                                for (label, v) in VARIATION_MENU {
                                    let sel = match (&self.flame.variation_mode, v) {
                                        (VariationMode::Single(a), Some(b)) => *a == b,
                                        (VariationMode::Random(_), None) => true,
                                        _ => false,
                                    };
                                    if ui.selectable_label(sel, label).clicked() {
                                        chosen = Some(Action::SetVariation(v));
                                        ui.close();
                                    }
                                }
                            });
                        }
                        let (checked, enabled) = self.menu_state(m.action);
                        let mut b = egui::Button::new(m.label).selected(checked == Some(true));
                        if let Some(s) = &m.shortcut {
                            b = b.shortcut_text(ctx.format_shortcut(s));
                        }
                        if ui.add_enabled(enabled, b).clicked() {
                            chosen = Some(m.action);
                            ui.close();
                        }
                    }
                });
            }
        });
        if let Some(a) = chosen {
            self.act(&ctx, a);
        }
    }

    pub(super) fn toolbar(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let mut chosen = None;
        ui.horizontal(|ui| {
            for (label, tip, a) in [
                ("Random", "Random flame (Ctrl+R)", Action::RandomFlame),
                ("Open", "Open… (Ctrl+O)", Action::Open),
                ("Save", "Save (Ctrl+S)", Action::Save),
                ("Undo", "Undo (Ctrl+Z)", Action::Undo),
                ("Redo", "Redo (Ctrl+Y)", Action::Redo),
                ("Editor", "Triangle editor (F4)", Action::ToggleEditor),
                ("Gradient", "Gradient (Ctrl+G)", Action::ShowGradient),
                ("Export", "Export image… (Ctrl+E)", Action::Export),
                ("Batch", "Random batch (Ctrl+B)", Action::RandomBatch),
                ("Mutate", "Mutations (Ctrl+U)", Action::ShowMutations),
                ("Animate", "Animate (Ctrl+M)", Action::ToggleAnimate),
            ] {
                if ui.button(label).on_hover_text(tip).clicked() {
                    chosen = Some(a);
                }
            }
            ui.separator();
            ui.selectable_value(&mut self.tab, Tab::Flame, "Flame");
            ui.selectable_value(&mut self.tab, Tab::Escape, "Escape-time");
            ui.selectable_value(&mut self.tab, Tab::Scene, "Scene");
        });
        if let Some(a) = chosen {
            self.act(&ctx, a);
        }
    }

    pub(super) fn status_bar(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            match self.tab {
                Tab::Flame => self.flame.status_bar(ui),
                Tab::Escape => {
                    ui.label(self.escape.status_text());
                    ui.separator();
                }
                Tab::Scene => {
                    ui.label(self.scene.status_text());
                    ui.separator();
                }
            }
            ui.label(self.status().to_string());
        });
    }
}
