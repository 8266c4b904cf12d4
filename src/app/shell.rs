//! The window around the tabs: it owns the options, the four tabs, the file chooser, the
//! "save changes?" question and the message boxes, and draws menus, toolbar and status bar
//! (`menus.rs`) around the current tab.

use std::collections::VecDeque;
use std::path::PathBuf;

use eframe::egui;

use super::dialogs::{self, Confirm, FileBrowser, Purpose};
use super::escape_tab::{EscapeRequest, EscapeTab};
use super::explore_tab::ExploreTab;
use super::flame_tab::first_flame::striking_flame;
use super::flame_tab::{FlameRequest, FlameTab};
use super::help::{self, HelpPage};
use super::loading::{Loaded, load_any};
use super::options::Options;
use super::options_dialog::{self, OptionsTab};
use super::scene_tab::{SceneRequest, SceneTab};
use super::worker::{Repaint, repaint_of};
use crate::flame::Flame;
use crate::flame::random::{self, VariationMode};
use crate::io::{self, View};

/// How the application starts.
pub enum Start {
    /// A random flame from this seed.
    Random(u64),
    /// This file, in the view its kind opens in.
    File(PathBuf),
    /// These flames, as a new unsaved document.
    Flames(Vec<crate::flame::Flame>),
}

/// Which view of the main window is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tab {
    /// Flames and IFS.
    Flame,
    /// Escape-time fractals.
    Escape,
    /// Textured Bézier scenes.
    Scene,
    /// The teaching topics.
    Explore,
}

/// Something to do once the user has answered "save changes?".
#[derive(Clone, Debug)]
pub(super) enum Pending {
    Exit,
    /// File › New in the flame tab.
    New,
    Open(PathBuf),
    BrowseOpen,
    /// Replace the open file by these flames (a new, unsaved document of this name) and show
    /// the flame tab.
    Flames(Vec<Flame>, String),
}

/// The application.
pub struct UgnisApp {
    /// The persisted options.
    pub options: Options,
    /// The view shown.
    pub tab: Tab,
    /// The flame tab.
    pub flame: FlameTab,
    /// The escape-time tab.
    pub escape: EscapeTab,
    /// The scene tab.
    pub scene: SceneTab,
    /// The Explore tab.
    pub explore: ExploreTab,
    /// The toolbar is shown.
    pub show_toolbar: bool,
    /// The status bar is shown.
    pub show_status: bool,
    pub(super) browser: Option<FileBrowser>,
    pub(super) pending: Option<Pending>,
    pub(super) confirm_what: String,
    /// Message boxes waiting to be shown, oldest first.
    messages: VecDeque<(String, String)>,
    pub(super) options_dialog: Option<(Options, OptionsTab)>,
    pub(super) allow_close: bool,
    pub(super) expect_paste: bool,
    /// The window title last sent (sending it every frame would keep the app awake).
    title: String,
    /// The open Help window.
    pub help: Option<HelpPage>,
    /// Whether option changes are written to the options file (off in tests).
    persist: bool,
    ctx: Option<egui::Context>,
    /// UI time per frame in ms when UGNIS_FRAME_TIMES is set.
    frame_log: Option<Vec<f64>>,
}

pub(super) fn seed_from_time() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(1, |d| d.as_nanos() as u64)
}

/// The flames to start with, their file and a status note; what went wrong is added to
/// `messages`.
fn start_flames(
    start: Start,
    options: &Options,
    messages: &mut Vec<(String, String)>,
) -> (Vec<Flame>, Option<PathBuf>, Option<String>) {
    let random_flame = |seed: u64| {
        let opts = options.random_options(VariationMode::default());
        vec![random::generate(seed, &opts, &options.new_flame()).flame]
    };
    match start {
        Start::Flames(f) if !f.is_empty() => (f, None, None),
        Start::Flames(_) => (random_flame(1), None, None),
        Start::Random(seed) => (vec![striking_flame(seed, options)], None, None),
        Start::File(p) => match load_any(&p, options) {
            Ok(Loaded {
                flames,
                warnings,
                notes,
            }) => {
                if !warnings.is_empty() {
                    messages.push(("Warnings".to_string(), warnings.join("\n")));
                }
                (flames, Some(p), notes.into_iter().next())
            }
            Err(e) => {
                messages.push(("Cannot open".to_string(), e));
                (random_flame(1), None, None)
            }
        },
    }
}

impl UgnisApp {
    /// A new application. With `ctx` the background renderers start (the live preview and the
    /// thumbnails); without it (tests) nothing renders.
    ///
    /// A file to start with opens in the view that opens its kind ([`io::view_of`]): flames
    /// are the flame document, any other file opens beside a random flame.
    pub fn new(options: Options, start: Start, ctx: Option<egui::Context>) -> UgnisApp {
        let (start, other) = match start {
            Start::File(p) => match io::view_of(io::kind_of(&p)) {
                View::Flame => (Start::File(p), None),
                view => (Start::Random(seed_from_time()), Some((view, p))),
            },
            s => (s, None),
        };
        let mut messages = Vec::new();
        let (flames, path, start_note) = start_flames(start, &options, &mut messages);
        let mut flame = FlameTab::new(flames, path, ctx.as_ref(), seed_from_time(), &options);
        if let Some(n) = start_note {
            flame.notices.status(n);
        }
        let mut app = UgnisApp {
            escape: EscapeTab::new(ctx.as_ref()),
            scene: SceneTab::new(ctx.as_ref()),
            explore: ExploreTab::new(ctx.as_ref()),
            options,
            tab: Tab::Flame,
            flame,
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
            help: None,
            persist: false,
            ctx,
            frame_log: std::env::var_os("UGNIS_FRAME_TIMES").map(|_| Vec::new()),
        };
        if let Some((view, p)) = other {
            app.load_into(view, &p);
        }
        app
    }

    /// Wakes the UI from background threads.
    pub(super) fn repaint(&self) -> Repaint {
        repaint_of(self.ctx.as_ref())
    }

    /// Write option changes to the options file from now on (the real application; tests
    /// leave the user's options alone).
    pub fn persist_options(&mut self, on: bool) {
        self.persist = on;
    }

    /// Save the options if they are persisted; a failure is told in a message box.
    pub(super) fn save_options(&mut self) {
        if self.persist
            && let Err(e) = self.options.save()
        {
            self.messages.push_back(("Options".into(), e));
        }
    }

    /// Remember a file opened or saved in the recent files.
    pub(super) fn remember(&mut self, path: &std::path::Path) {
        self.options.remember(path);
        self.save_options();
    }

    /// Show a message box.
    pub(super) fn show_message(&mut self, title: &str, text: String) {
        self.messages.push_back((title.to_string(), text));
    }

    /// A modal dialog is up (the file chooser, a message box or "save changes?"): it answers
    /// Esc itself.
    pub(super) fn modal_open(&self) -> bool {
        self.browser.is_some()
            || !self.messages.is_empty()
            || (self.pending.is_some() && self.flame.file.dirty)
    }

    /// The file chooser, if one is open.
    pub fn file_browser(&self) -> Option<&FileBrowser> {
        self.browser.as_ref()
    }

    /// The status line of the current tab.
    pub fn status(&self) -> &str {
        match self.tab {
            Tab::Flame => &self.flame.notices.status,
            Tab::Escape => &self.escape.notices.status,
            Tab::Scene => &self.scene.notices.status,
            Tab::Explore => &self.explore.notices.status,
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
            &mut self.explore.notices,
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
            // Anchored at its top centre with a fixed width: the tabs stay where they are when
            // the contents change height.
            let r0 = ctx.content_rect();
            egui::Window::new("Options")
                .collapsible(false)
                .pivot(egui::Align2::CENTER_TOP)
                .default_pos([r0.center().x, r0.top() + 60.0])
                .resizable(false)
                .show(ctx, |ui| {
                    r = options_dialog::dialog(ui, draft, tab);
                });
            match r {
                Some(true) => {
                    self.options = draft.clone();
                    self.save_options();
                    self.options_dialog = None;
                    if let Some(p) = self.options.apply_jwildfire() {
                        self.flame.notices.message("Options", p);
                    }
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

        if self.tab == Tab::Explore {
            self.explore.tick();
        }
        // The full-window preview leaves out the bars too.
        let bars = !(self.tab == Tab::Flame && self.flame.full_view);
        if bars {
            egui::Panel::top("menu").show(ui, |ui| self.menu_bar(ui));
        }
        if self.show_toolbar && bars {
            egui::Panel::top("toolbar").show(ui, |ui| self.toolbar(ui));
        }
        if self.show_status && bars {
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
                    Some(SceneRequest::SaveScene) => self.browse(Purpose::SaveScene),
                    Some(SceneRequest::Export) => self.browse(Purpose::ExportScene),
                    Some(SceneRequest::TextureImage) => self.browse(Purpose::SceneTexture),
                    None => {}
                }
            }
            Tab::Explore => {
                if let Some(r) = self
                    .explore
                    .ui(ui, self.flame.doc().flame(), &self.escape.doc)
                {
                    self.explore_request(r);
                }
            }
        }
        if self.flame.variation_filter.show(&ctx, &mut self.options) {
            if self.options.use_variation_filter {
                self.flame.variation_mode =
                    crate::flame::random::VariationMode::FromList(self.options.filter_list());
            } else if matches!(
                self.flame.variation_mode,
                crate::flame::random::VariationMode::FromList(_)
            ) {
                self.flame.variation_mode = VariationMode::Random(self.options.probabilities);
            }
            self.save_options();
        }
        if let Some(p) = self.help
            && !help::show(&ctx, p)
        {
            self.help = None;
        }
        match self.flame.windows(&ctx, &self.options) {
            Some(FlameRequest::LoadGradient) => self.browse(Purpose::LoadGradient),
            Some(FlameRequest::GradientFromImage) => self.browse(Purpose::GradientFromImage),
            Some(FlameRequest::ChooseExportFile) => self.browse(Purpose::Export),
            Some(FlameRequest::ChooseAnimationFile) => self.browse(Purpose::ExportAnimation),
            Some(FlameRequest::ChooseSoundFile) => self.browse(Purpose::SoundFile),
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
