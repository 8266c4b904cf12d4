//! The desktop application (egui/eframe, glow renderer).
//!
//! How it is put together, from the outside in:
//!
//! * `shell` — the window: the options, the four tabs, message boxes, the file chooser and
//!   the "save changes?" question. `menus` draws its menu bar, toolbar and status bar and
//!   handles shortcuts, pasted flames and dropped files (`closing` is Esc); `actions` lists every command with
//!   its menu and shortcut; `files` opens and saves, every file in the view
//!   [`crate::io::view_of`] names, with the flames read by `loading.rs`.
//! * One folder per tab, each owning its document, background worker and panels:
//!   [`flame_tab`] (flames: file and batch, live preview, triangle editor, gradient,
//!   mutations, export), `escape_tab` (escape-time fractals), `scene_tab` (textured
//!   Bézier scenes), `explore_tab` (the teaching topics: classic constructions, chaos game,
//!   L-systems, fractal interpolation, inverse-iteration Julia sets, Lorenz, dimension).
//!   `commands` says what every command does in which tab; `help` holds
//!   the Help menu's windows.
//! * Shared pieces: `worker` (the one background worker: newest job wins, cancel,
//!   progress, join on drop), `notice` (status lines and message boxes), `options` (the
//!   persisted settings and their dialog), `dialogs` (file browser, message and confirm),
//!   `widgets.rs` (the picture area of the escape-time, scene and Explore tabs).

pub(crate) mod a11y;
pub(crate) mod actions;
mod closing;
pub(crate) mod commands;
pub(crate) mod dialogs;
pub(crate) mod escape_tab;
pub(crate) mod explore_tab;
pub(crate) mod files;
pub mod flame_tab;
pub(crate) mod help;
mod loading;
pub(crate) mod menus;
pub(crate) mod notice;
pub(crate) mod options;
pub(crate) mod options_dialog;
pub(crate) mod scene_tab;
pub(crate) mod shell;
mod widgets;
pub(crate) mod worker;

use std::path::PathBuf;

use eframe::egui;

pub use actions::{Action, MENU, MENUS, MenuItem};
pub use explore_tab::Topic;
pub use explore_tab::dimension::BoxSource;
pub use flame_tab::MORPH_FRAMES;
pub use flame_tab::editor_state::Selected;
pub use flame_tab::first_flame::{colour_share, colourfulness};
pub use help::HelpPage;
pub use options::Options;
pub use scene_tab::TextureSource;
pub use shell::{Start, Tab, UgnisApp};

/// Start the editor window.
pub fn run(file: Option<PathBuf>) -> Result<(), eframe::Error> {
    let native = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("ugnis")
            .with_inner_size([1280.0, 820.0])
            .with_drag_and_drop(true),
        renderer: eframe::Renderer::Glow,
        ..Default::default()
    };
    eframe::run_native(
        "ugnis",
        native,
        Box::new(move |cc| {
            let ctx = cc.egui_ctx.clone();
            let start = match file {
                Some(p) => Start::File(p),
                None => Start::Random(shell::seed_from_time()),
            };
            let (options, problem) = options::Options::load();
            // Before the first file is read: its variations may draw JWildfire's resources.
            let jwildfire = options.apply_jwildfire();
            let mut app = UgnisApp::new(options, start, Some(ctx));
            app.persist_options(true);
            if let Some(p) = problem {
                app.flame.notices.message("Options", p);
            }
            if let Some(p) = jwildfire {
                app.flame.notices.message("Options", p);
            }
            Ok(Box::new(app))
        }),
    )
}
