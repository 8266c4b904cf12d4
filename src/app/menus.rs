//! The shell's bars and input: menu bar, toolbar, status bar, keyboard shortcuts, pasted
//! flames and dropped files.

use std::path::PathBuf;

use eframe::egui;

use super::actions::{self, Action, MENU, MENUS, VARIATION_MENU};
use super::shell::{Tab, UgnisApp};
use crate::flame::random::VariationMode;

impl UgnisApp {
    /// Shortcuts, pasted flames and dropped files.
    pub(super) fn handle_input(&mut self, ctx: &egui::Context) {
        let typing = ctx.memory(|m| m.focused().is_some());
        let timeline_keys = self.tab == Tab::Flame && self.flame.timeline.open && !typing;
        let mut fired = Vec::new();
        let all = actions::shortcuts();
        ctx.input_mut(|i| {
            for (s, a) in &all {
                // Let text fields keep their own Ctrl+Z etc.
                if typing && matches!(a, Action::Undo | Action::Redo) {
                    continue;
                }
                // Plain keys drive the timeline only while it is shown and nothing types.
                if actions::is_timeline_key(*a) && !timeline_keys {
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
        if !typing && !self.modal_open() && ctx.input(|i| i.key_pressed(egui::Key::Escape)) {
            self.escape_pressed(ctx);
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
            self.open_file(&p, "opening the dropped file");
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
            Action::ToggleFullView => Some(f.full_view),
            Action::ShowHistory => Some(f.history_open),
            Action::TogglePreviewWindow => Some(f.preview_window),
            Action::ToggleAnimate => Some(f.animation.is_some()),
            Action::ToggleMorph => Some(f.morph.is_some()),
            Action::ToggleTimeline => Some(f.timeline.open),
            Action::PlayPause => Some(f.timeline.playing()),
            _ => None,
        };
        let enabled = match (a, self.tab) {
            (Action::Undo, Tab::Flame) => f.doc().can_undo(),
            (Action::Redo, Tab::Flame) => f.doc().can_redo(),
            (Action::Undo, Tab::Escape) => self.escape.can_go_back(),
            (Action::Redo, Tab::Escape) => self.escape.can_go_forward(),
            (Action::Undo | Action::Redo, Tab::Scene | Tab::Explore) => false,
            (Action::RandomBatch, _) => !f.batch_running(),
            (Action::AddKey | Action::DeleteKey, _) => {
                f.timeline.target.is_some() && !f.timeline.plays_sequence()
            }
            _ => true,
        };
        (checked, enabled)
    }

    /// Tools › Random variations: Random, the seven, the variations filter.
    fn variations_menu(&self, ui: &mut egui::Ui, chosen: &mut Option<Action>) {
        ui.menu_button("Random variations", |ui| {
            for (label, v) in VARIATION_MENU {
                let sel = match (&self.flame.variation_mode, v) {
                    (VariationMode::Single(a), Some(b)) => *a == b,
                    (VariationMode::Random(_), None) => true,
                    _ => false,
                };
                if ui.selectable_label(sel, label).clicked() {
                    *chosen = Some(Action::SetVariation(v));
                    ui.close();
                }
            }
            ui.separator();
            let sel = matches!(self.flame.variation_mode, VariationMode::FromList(_));
            if ui
                .selectable_label(sel, "From the variations filter")
                .on_hover_text("one or two of the ticked variations per transform")
                .clicked()
            {
                *chosen = Some(Action::UseVariationFilter);
                ui.close();
            }
        })
        .response
        .on_hover_text("which variations Random flame and Random batch use");
    }

    /// File › Recent: the files opened or saved lately.
    fn recent_menu(&self, ui: &mut egui::Ui, open: &mut Option<PathBuf>) {
        ui.menu_button("Recent", |ui| {
            if self.options.recent_files.is_empty() {
                ui.label("(none yet)");
            }
            for p in &self.options.recent_files {
                let name = p.file_name().map_or_else(
                    || p.display().to_string(),
                    |n| n.to_string_lossy().into_owned(),
                );
                if ui
                    .button(name)
                    .on_hover_text(p.display().to_string())
                    .clicked()
                {
                    *open = Some(p.clone());
                    ui.close();
                }
            }
        });
    }

    pub(super) fn menu_bar(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let mut chosen = None;
        let mut recent = None;
        egui::MenuBar::new().ui(ui, |ui| {
            for menu in MENUS {
                ui.menu_button(menu, |ui| {
                    for m in MENU.iter().filter(|m| m.menu == menu) {
                        if m.action == Action::ToggleEditor {
                            self.variations_menu(ui, &mut chosen);
                        }
                        if m.action == Action::Save {
                            self.recent_menu(ui, &mut recent);
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
            // The tabs, at the right of the menu bar: always in reach, whatever the width.
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                for (t, label, tip) in [
                    (
                        Tab::Explore,
                        "Explore",
                        "classic fractals, chaos game, L-systems, dimension",
                    ),
                    (Tab::Scene, "Scene", "textured Bézier scenes"),
                    (
                        Tab::Escape,
                        "Escape-time",
                        "Mandelbrot, Julia and relatives",
                    ),
                    (Tab::Flame, "Flame", "fractal flames and IFS"),
                ] {
                    ui.selectable_value(&mut self.tab, t, label)
                        .on_hover_text(tip);
                }
            });
        });
        if let Some(a) = chosen {
            self.act(&ctx, a);
        }
        if let Some(p) = recent {
            self.open_file(&p, "opening another file");
        }
    }

    /// The toolbar: the current tab's commands.
    pub(super) fn toolbar(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let mut chosen = None;
        let buttons: &[(&str, &str, Action)] = match self.tab {
            Tab::Flame => &[
                ("Random", "Random flame (Ctrl+R)", Action::RandomFlame),
                ("New", "New flame (Ctrl+N)", Action::New),
                ("Open", "Open a flame or IFS file (Ctrl+O)", Action::Open),
                ("Save", "Save the flames (Ctrl+S)", Action::Save),
                ("Undo", "Undo (Ctrl+Z)", Action::Undo),
                ("Redo", "Redo (Ctrl+Y)", Action::Redo),
                (
                    "Editor",
                    "Show or hide the triangle editor (F4)",
                    Action::ToggleEditor,
                ),
                (
                    "Gradient",
                    "Gradient library (Ctrl+G)",
                    Action::ShowGradient,
                ),
                (
                    "Palette",
                    "Palette editor (Ctrl+Shift+G)",
                    Action::ShowPaletteEditor,
                ),
                ("Export", "Export image… (Ctrl+E)", Action::Export),
                (
                    "Batch",
                    "Random batch of 100 flames (Ctrl+B)",
                    Action::RandomBatch,
                ),
                (
                    "Mutate",
                    "Mutations of this flame (Ctrl+U)",
                    Action::ShowMutations,
                ),
                (
                    "Animate",
                    "Turn the triangles (Ctrl+M)",
                    Action::ToggleAnimate,
                ),
                (
                    "Timeline",
                    "Keyframes, playback and curves under the preview (Ctrl+T)",
                    Action::ToggleTimeline,
                ),
            ],
            Tab::Escape => &[
                (
                    "New",
                    "The Mandelbrot set's default view (Ctrl+N)",
                    Action::New,
                ),
                ("Open", "Open a view file (.esc) (Ctrl+O)", Action::Open),
                ("Save", "Save the view (Ctrl+S)", Action::Save),
                ("Export", "Export image… (Ctrl+E)", Action::Export),
            ],
            Tab::Scene => &[
                ("New", "The default scene (Ctrl+N)", Action::New),
                ("Open", "Open a scene file (.toml) (Ctrl+O)", Action::Open),
                ("Save", "Save the scene (Ctrl+S)", Action::Save),
                ("Export", "Export image… (Ctrl+E)", Action::Export),
            ],
            Tab::Explore => &[
                ("New", "This topic back to its start (Ctrl+N)", Action::New),
                (
                    "Open",
                    "Open a Fractint L-system file (.l) (Ctrl+O)",
                    Action::Open,
                ),
                (
                    "Export",
                    "Export the L-system as SVG or PNG (Ctrl+E)",
                    Action::Export,
                ),
            ],
        };
        ui.horizontal_wrapped(|ui| {
            for (label, tip, a) in buttons {
                let (_, enabled) = self.menu_state(*a);
                if ui
                    .add_enabled(enabled, egui::Button::new(*label))
                    .on_hover_text(*tip)
                    .on_disabled_hover_text(*tip)
                    .clicked()
                {
                    chosen = Some(*a);
                }
            }
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
                Tab::Explore => {
                    ui.label(self.explore.status_text());
                    ui.separator();
                }
            }
            // A long line (a file's warnings) ends in "…" at the window's edge; the pointer
            // shows all of it, a click opens it in a message box.
            let text = self.status().to_string();
            if !text.is_empty() {
                let r = ui
                    .add(
                        egui::Label::new(&text)
                            .truncate()
                            .sense(egui::Sense::click()),
                    )
                    .on_hover_text(format!("{text}\n\n(click to see it in a window)"));
                if r.clicked() {
                    self.show_message("Status", text);
                }
            }
        });
    }
}
