//! The window around the tabs: it owns the options, the three tabs, the file chooser, the
//! "save changes?" question and the message boxes, and draws menus, toolbar and status bar
//! (`menus.rs`) around the current tab.

use std::collections::VecDeque;
use std::path::PathBuf;

use eframe::egui;

use super::actions::Action;
use super::dialogs::{self, Confirm, FileBrowser, Purpose};
use super::escape_tab::{EscapeRequest, EscapeTab};
use super::files::{Pending, load_any};
use super::flame_tab::{FlameRequest, FlameTab};
use super::options::Options;
use super::options_dialog::{self, OptionsTab};
use super::scene_tab::{SceneRequest, SceneTab};
use super::worker::{Repaint, repaint_of};
use crate::flame::random::{self, VariationMode};
use crate::io;

/// How the application starts.
pub enum Start {
    /// A random flame from this seed.
    Random(u64),
    File(PathBuf),
    Flames(Vec<crate::flame::Flame>),
}

/// Which view of the main window is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tab {
    Flame,
    Escape,
    Scene,
}

/// The application.
pub struct UgnisApp {
    pub options: Options,
    pub tab: Tab,
    pub flame: FlameTab,
    pub escape: EscapeTab,
    pub scene: SceneTab,
    pub show_toolbar: bool,
    pub show_status: bool,
    pub(super) browser: Option<FileBrowser>,
    pub(super) pending: Option<Pending>,
    pub(super) confirm_what: String,
    /// Message boxes waiting to be shown, oldest first.
    messages: VecDeque<(String, String)>,
    options_dialog: Option<(Options, OptionsTab)>,
    pub(super) allow_close: bool,
    pub(super) expect_paste: bool,
    /// The window title last sent (sending it every frame would keep the app awake).
    title: String,
    ctx: Option<egui::Context>,
    /// UI time per frame in ms when UGNIS_FRAME_TIMES is set.
    frame_log: Option<Vec<f64>>,
}

pub(super) fn seed_from_time() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(1, |d| d.as_nanos() as u64)
}

impl UgnisApp {
    /// A new application. With `ctx` the background renderers start (the live preview and the
    /// thumbnails); without it (tests) nothing renders.
    pub fn new(options: Options, start: Start, ctx: Option<egui::Context>) -> UgnisApp {
        let mut messages = Vec::new();
        // A view file opens in the escape-time tab (next to a random flame).
        let mut escape_start = None;
        let start = match start {
            Start::File(p) if io::kind_of(&p) == io::FileKind::EscapeView => {
                match io::escape_view::read(&p) {
                    Ok(v) => escape_start = Some((v.value, p)),
                    Err(e) => messages.push(("Cannot open".to_string(), e.to_string())),
                }
                Start::Random(seed_from_time())
            }
            s => s,
        };
        let defaults = options.new_flame();
        let random_flame = |seed: u64| {
            let opts = options.random_options(VariationMode::default());
            vec![random::generate(seed, &opts, &defaults).flame]
        };
        let (flames, path) = match start {
            Start::Flames(f) if !f.is_empty() => (f, None),
            Start::Flames(_) => (random_flame(1), None),
            Start::Random(seed) => (random_flame(seed), None),
            Start::File(p) => match load_any(&p, &options) {
                Ok((f, w)) => {
                    if !w.is_empty() {
                        messages.push(("Warnings".to_string(), w.join("\n")));
                    }
                    (f, Some(p))
                }
                Err(e) => {
                    messages.push(("Cannot open".to_string(), e));
                    (random_flame(1), None)
                }
            },
        };
        let flame = FlameTab::new(flames, path, ctx.as_ref(), seed_from_time());
        let mut escape = EscapeTab::new(ctx.as_ref());
        let tab = match escape_start {
            Some((d, p)) => {
                escape.doc = d;
                escape.path = Some(p);
                Tab::Escape
            }
            None => Tab::Flame,
        };
        UgnisApp {
            options,
            tab,
            flame,
            escape,
            scene: SceneTab::new(ctx.as_ref()),
            show_toolbar: true,
            show_status: true,
            browser: None,
            pending: None,
            confirm_what: String::new(),
            messages: messages.into(),
            options_dialog: None,
            allow_close: false,
            expect_paste: false,
            title: String::new(),
            ctx,
            frame_log: std::env::var_os("UGNIS_FRAME_TIMES").map(|_| Vec::new()),
        }
    }

    /// Wakes the UI from background threads.
    pub(super) fn repaint(&self) -> Repaint {
        repaint_of(self.ctx.as_ref())
    }

    /// The status line of the current tab.
    pub fn status(&self) -> &str {
        match self.tab {
            Tab::Flame => &self.flame.notices.status,
            Tab::Escape => &self.escape.notices.status,
            Tab::Scene => &self.scene.notices.status,
        }
    }

    /// Carry out a command.
    pub fn act(&mut self, ctx: &egui::Context, a: Action) {
        // Commands about the file work on the open file, not on the batch.
        if matches!(
            a,
            Action::Open | Action::Save | Action::SaveAs | Action::Exit
        ) {
            self.flame.view_file();
        }
        let o = &self.options;
        match a {
            Action::Open => self.guard_dirty(Pending::BrowseOpen, "opening another file"),
            Action::Save => {
                match self
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
                }
            }
            Action::SaveAs => self.browse(Purpose::SaveAs),
            Action::LoadGradient => self.browse(Purpose::LoadGradient),
            Action::GradientFromImage => self.browse(Purpose::GradientFromImage),
            Action::Export => self.flame.open_export_dialog(o),
            Action::RandomBatch => self.flame.start_batch(o),
            Action::Exit => self.guard_dirty(Pending::Exit, "quitting"),
            Action::Undo => self.flame.undo(),
            Action::Redo => self.flame.redo(),
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
            Action::FitPreview => self.flame.preview_zoom = 1.0,
            Action::ZoomIn => self.flame.preview_zoom = (self.flame.preview_zoom * 1.25).min(8.0),
            Action::ZoomOut => {
                self.flame.preview_zoom = (self.flame.preview_zoom / 1.25).max(0.125)
            }
            Action::SetVariation(v) => {
                let label = super::actions::VARIATION_MENU
                    .iter()
                    .find(|m| m.1 == v)
                    .map_or("", |m| m.0);
                self.flame.set_variation(o, v, label)
            }
            Action::ShowGradient => self.flame.gradients.open = !self.flame.gradients.open,
            Action::ShowMutations => self.flame.mutations.open = !self.flame.mutations.open,
            Action::RandomFlame => self.flame.random_flame(o),
            Action::ToggleAnimate => self.flame.toggle_animation(),
            Action::ToggleMorph => self.flame.toggle_morph(),
            Action::RandomWeights => self.flame.random_weights(),
            Action::EqualWeights => self.flame.equal_weights(),
            Action::AreaWeights => self.flame.area_weights(),
            Action::ShowOptions => {
                self.options_dialog = Some((self.options.clone(), OptionsTab::default()))
            }
        }
    }

    /// The file chooser, the "save changes?" question, message boxes and the Options dialog.
    fn dialogs(&mut self, ctx: &egui::Context) {
        if let Some(b) = &mut self.browser
            && let Some(r) = b.show(ctx)
        {
            let purpose = b.purpose;
            self.browser = None;
            match r {
                Some(p) => self.file_chosen(purpose, p),
                None => {
                    if matches!(self.pending, Some(Pending::Exit)) {
                        self.pending = None;
                    }
                }
            }
        }
        if self.browser.is_none()
            && let Some(p) = self.pending.clone()
            && self.flame.file.dirty
        {
            match dialogs::confirm_discard(ctx, &self.confirm_what) {
                Some(Confirm::Save) => {
                    let saved = match self
                        .flame
                        .file
                        .path
                        .clone()
                        .filter(|p| io::kind_of(p) != io::FileKind::Png)
                    {
                        Some(path) => self.save_to(&path),
                        None => {
                            self.browse(Purpose::SaveAs);
                            false
                        }
                    };
                    if saved {
                        self.pending = None;
                        self.run_pending(p);
                    }
                }
                Some(Confirm::Discard) => {
                    self.pending = None;
                    self.flame.file.dirty = false;
                    self.run_pending(p);
                }
                Some(Confirm::Cancel) => self.pending = None,
                None => {}
            }
        } else if !self.flame.file.dirty
            && self.browser.is_none()
            && let Some(p) = self.pending.take()
        {
            self.run_pending(p);
        }
        for n in [
            &mut self.flame.notices,
            &mut self.escape.notices,
            &mut self.scene.notices,
        ] {
            self.messages.extend(n.take_messages());
        }
        if let Some((title, text)) = self.messages.front()
            && dialogs::message(ctx, title, text)
        {
            self.messages.pop_front();
        }
        if let Some((draft, tab)) = &mut self.options_dialog {
            let mut r = None;
            egui::Window::new("Options")
                .collapsible(false)
                .pivot(egui::Align2::CENTER_CENTER)
                .default_pos(ctx.content_rect().center())
                .resizable(false)
                .show(ctx, |ui| {
                    r = options_dialog::dialog(ui, draft, tab);
                });
            match r {
                Some(true) => {
                    self.options = draft.clone();
                    if let Err(e) = self.options.save() {
                        self.messages.push_back(("Options".into(), e));
                    }
                    self.options_dialog = None;
                }
                Some(false) => self.options_dialog = None,
                None => {}
            }
        }
    }

    /// The whole user interface of one frame.
    pub fn ui(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        self.handle_input(&ctx);
        // Close requests ask about unsaved changes.
        if ctx.input(|i| i.viewport().close_requested()) && !self.allow_close {
            if self.flame.file.dirty {
                self.flame.view_file();
                ctx.send_viewport_cmd(egui::ViewportCommand::CancelClose);
                self.pending = Some(Pending::Exit);
                self.confirm_what = "quitting".into();
            } else {
                self.allow_close = true;
            }
        }
        if self.allow_close {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        let file = &self.flame.file;
        let title = format!(
            "ugnis — {}{}",
            file.name,
            if file.dirty { " *" } else { "" }
        );
        if title != self.title {
            ctx.send_viewport_cmd(egui::ViewportCommand::Title(title.clone()));
            self.title = title;
        }

        egui::Panel::top("menu").show(ui, |ui| self.menu_bar(ui));
        if self.show_toolbar {
            egui::Panel::top("toolbar").show(ui, |ui| self.toolbar(ui));
        }
        if self.show_status {
            egui::Panel::bottom("status").show(ui, |ui| self.status_bar(ui));
        }
        match self.tab {
            Tab::Flame => self.flame.ui(ui, &self.options),
            Tab::Escape => match self.escape.ui(ui) {
                Some(EscapeRequest::OpenView) => self.browse(Purpose::OpenView),
                Some(EscapeRequest::SaveView) => self.browse(Purpose::SaveView),
                Some(EscapeRequest::Export) => self.browse(Purpose::ExportEscape),
                None => {}
            },
            Tab::Scene => {
                match self
                    .scene
                    .ui(ui, self.flame.doc().flame(), &self.escape.doc)
                {
                    Some(SceneRequest::OpenScene) => self.browse(Purpose::OpenScene),
                    Some(SceneRequest::Export) => self.browse(Purpose::ExportScene),
                    Some(SceneRequest::TextureImage) => self.browse(Purpose::SceneTexture),
                    None => {}
                }
            }
        }
        match self.flame.windows(&ctx, &self.options) {
            Some(FlameRequest::LoadGradient) => self.browse(Purpose::LoadGradient),
            Some(FlameRequest::GradientFromImage) => self.browse(Purpose::GradientFromImage),
            Some(FlameRequest::ChooseExportFile) => self.browse(Purpose::Export),
            None => {}
        }
        self.dialogs(&ctx);
    }

    /// UGNIS_FRAME_TIMES=1: print how long the UI thread spent per frame (responsiveness),
    /// every 120 frames and at exit.
    fn report_frame_times(&mut self) {
        if let Some(log) = &mut self.frame_log
            && !log.is_empty()
        {
            let mut v = std::mem::take(log);
            v.sort_by(f64::total_cmp);
            let q = |p: f64| v[((v.len() - 1) as f64 * p) as usize];
            eprintln!(
                "ugnis: {} frames, UI time per frame: median {:.2} ms, p95 {:.2} ms, max {:.2} ms",
                v.len(),
                q(0.5),
                q(0.95),
                q(1.0)
            );
        }
    }
}

impl eframe::App for UgnisApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let t = std::time::Instant::now();
        UgnisApp::ui(self, ui);
        if let Some(log) = &mut self.frame_log {
            log.push(t.elapsed().as_secs_f64() * 1000.0);
            if log.len() >= 120 {
                self.report_frame_times();
            }
        }
    }
}

impl Drop for UgnisApp {
    fn drop(&mut self) {
        self.report_frame_times();
    }
}
