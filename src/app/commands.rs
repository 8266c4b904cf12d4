//! What every command does. File commands (New, Open, Save, Save As, Export) and Undo/Redo
//! act on the current tab's document; the flame commands act on the flame tab.

use eframe::egui;

use super::actions::{Action, VARIATION_MENU};
use super::dialogs::Purpose;
use super::explore_tab::Topic;
use super::help::HelpPage;
use super::options_dialog::OptionsTab;
use super::shell::Pending;
use super::shell::{Tab, UgnisApp};
use crate::flame::random::VariationMode;
use crate::io;

impl UgnisApp {
    /// Carry out a command.
    pub fn act(&mut self, ctx: &egui::Context, a: Action) {
        let tab = self.tab;
        // Commands about the file work on the open file, not on the batch.
        if tab == Tab::Flame
            && matches!(
                a,
                Action::New | Action::Open | Action::Save | Action::SaveAs | Action::Exit
            )
        {
            self.flame.view_file();
        }
        let o = &self.options;
        match a {
            Action::New => match tab {
                Tab::Flame => self.guard_dirty(Pending::New, "starting a new flame"),
                Tab::Escape => self.escape.new_view(),
                Tab::Scene => self.scene.new_scene(),
                Tab::Explore => self.explore.reset_topic(),
            },
            Action::Open => match tab {
                Tab::Flame => self.guard_dirty(Pending::BrowseOpen, "opening another file"),
                Tab::Escape => self.browse(Purpose::OpenView),
                Tab::Scene => self.browse(Purpose::OpenScene),
                Tab::Explore => match self.explore.topic {
                    Topic::Dimension => self.browse(Purpose::BoxCountImage),
                    _ => {
                        self.explore.topic = Topic::LSystems;
                        self.browse(Purpose::OpenLSystem)
                    }
                },
            },
            Action::Save => self.save(),
            Action::SaveAs => match tab {
                Tab::Flame => self.browse(Purpose::SaveAs),
                Tab::Escape => self.browse(Purpose::SaveView),
                Tab::Scene => self.browse(Purpose::SaveScene),
                Tab::Explore => self.explore_export(),
            },
            Action::LoadGradient => self.browse(Purpose::LoadGradient),
            Action::GradientFromImage => self.browse(Purpose::GradientFromImage),
            Action::Export => match tab {
                Tab::Flame => self.flame.open_export_dialog(o),
                Tab::Escape => self.browse(Purpose::ExportEscape),
                Tab::Scene => self.browse(Purpose::ExportScene),
                Tab::Explore => self.explore_export(),
            },
            Action::ResumeState => self.browse(Purpose::ResumeState),
            Action::RandomBatch => self.flame.start_batch(o),
            Action::Exit => self.guard_dirty(Pending::Exit, "quitting"),
            Action::Undo => match tab {
                Tab::Flame => self.flame.undo(),
                Tab::Escape => self.escape.go_back(),
                Tab::Scene => self.scene.notices.status("The scene tab has no undo"),
                Tab::Explore => self.explore.notices.status("The Explore tab has no undo"),
            },
            Action::Redo => match tab {
                Tab::Flame => self.flame.redo(),
                Tab::Escape => self.escape.go_forward(),
                Tab::Scene => self.scene.notices.status("The scene tab has no redo"),
                Tab::Explore => self.explore.notices.status("The Explore tab has no redo"),
            },
            Action::ShowHistory => {
                self.tab = Tab::Flame;
                self.flame.history_open = !self.flame.history_open;
            }
            Action::CopyFlame => {
                ctx.copy_text(io::flam3_xml::flame_element(self.flame.doc().flame()));
                self.flame.notices.status("Flame copied as XML");
            }
            Action::PasteFlame => {
                self.expect_paste = true;
                ctx.send_viewport_cmd(egui::ViewportCommand::RequestPaste);
            }
            Action::ToggleToolbar => self.show_toolbar = !self.show_toolbar,
            Action::ToggleStatusBar => self.show_status = !self.show_status,
            Action::ToggleFilePanel => self.flame.show_files = !self.flame.show_files,
            Action::ToggleEditor => self.flame.show_editor = !self.flame.show_editor,
            Action::ToggleFullView => {
                self.tab = Tab::Flame;
                self.flame.full_view = !self.flame.full_view;
            }
            Action::TogglePreviewWindow => {
                self.tab = Tab::Flame;
                self.flame.full_view = false;
                self.flame.preview_window = !self.flame.preview_window;
            }
            Action::FitPreview => self.flame.preview_zoom = 1.0,
            Action::ZoomIn => self.flame.preview_zoom = (self.flame.preview_zoom * 1.25).min(8.0),
            Action::ZoomOut => {
                self.flame.preview_zoom = (self.flame.preview_zoom / 1.25).max(0.125)
            }
            Action::SetVariation(v) => {
                let label = VARIATION_MENU.iter().find(|m| m.1 == v).map_or("", |m| m.0);
                self.flame.set_variation(o, v, label);
                if self.options.use_variation_filter {
                    self.options.use_variation_filter = false;
                    self.save_options();
                }
            }
            Action::UseVariationFilter => {
                let list = self.options.filter_list();
                if list.is_empty() {
                    self.flame.variation_filter.open = true;
                    self.flame
                        .notices
                        .status("Tick the variations random flames may use");
                } else {
                    self.flame
                        .notices
                        .status(format!("Variations: {} from the filter", list.len()));
                }
                self.flame.variation_mode = VariationMode::FromList(list);
                self.options.use_variation_filter = true;
                self.save_options();
            }
            Action::ShowVariationFilter => {
                self.flame.variation_filter.open = !self.flame.variation_filter.open
            }
            // One window, two pages: the key shows its page, or closes the window showing it.
            Action::ShowGradient => {
                let (g, e) = (&mut self.flame.gradients, &mut self.flame.palette_editor);
                g.open = !g.open || e.open;
                e.open = false;
            }
            Action::ShowPaletteEditor => {
                let (g, e) = (&mut self.flame.gradients, &mut self.flame.palette_editor);
                e.open = !(g.open && e.open);
                g.open = e.open;
            }
            Action::ShowMutations => self.flame.mutations.open = !self.flame.mutations.open,
            Action::RandomFlame => self.flame.random_flame(o),
            Action::ToggleAnimate => self.flame.toggle_animation(),
            Action::ToggleMorph => self.flame.toggle_morph(),
            Action::ToggleTimeline => self.flame.toggle_timeline(),
            Action::PlayPause => self.flame.toggle_play(),
            Action::PreviousFrame => self.flame.timeline_step(-1.0),
            Action::NextFrame => self.flame.timeline_step(1.0),
            Action::FirstFrame => self.flame.timeline_go(0.0),
            Action::LastFrame => self.flame.timeline_go(f64::INFINITY),
            Action::AddKey => self.flame.key_here(),
            Action::DeleteKey => self.flame.delete_key_here(),
            Action::ShowLoopTools => {
                self.flame.timeline.loop_dialog = Some(Default::default());
            }
            Action::ExportAnimation => self.flame.open_anim_export(o),
            Action::RandomWeights => self.flame.random_weights(),
            Action::EqualWeights => self.flame.equal_weights(),
            Action::AreaWeights => self.flame.area_weights(),
            Action::ShowOptions => {
                self.options_dialog = Some((self.options.clone(), OptionsTab::default()))
            }
            Action::ShowShortcuts => self.help = Some(HelpPage::Shortcuts),
            Action::ShowPanelHelp => self.help = Some(HelpPage::Panels),
            Action::ShowAbout => self.help = Some(HelpPage::About),
        }
    }

    /// Save the current tab's document where it came from, or ask where.
    fn save(&mut self) {
        match self.tab {
            Tab::Flame => match self
                .flame
                .file
                .path
                .clone()
                .filter(|p| io::kind_of(p) != io::FileKind::Png)
            {
                Some(p) => {
                    self.save_to(&p);
                }
                None => self.browse(Purpose::SaveAs),
            },
            Tab::Escape => match self.escape.path.clone() {
                Some(p) => self.file_chosen(Purpose::SaveView, p),
                None => self.browse(Purpose::SaveView),
            },
            Tab::Scene => match self.scene.path.clone() {
                Some(p) => self.file_chosen(Purpose::SaveScene, p),
                None => self.browse(Purpose::SaveScene),
            },
            Tab::Explore => self.explore_export(),
        }
    }

    /// Save and Export in the Explore tab: the L-system picture (the only thing it saves).
    fn explore_export(&mut self) {
        if self.explore.topic == Topic::LSystems {
            self.browse(Purpose::ExportLSystem);
        } else {
            self.explore
                .notices
                .status("Explore saves only L-system pictures (L-systems › Export)");
        }
    }
}
