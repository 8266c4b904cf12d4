//! The desktop application (egui/eframe, glow renderer): menus, toolbar, status bar, the file
//! contents panel, the live preview, the triangle editor, the gradient window, options, export.

pub mod dialogs;
pub mod document;
pub mod editor;
pub mod escape_view;
pub mod export;
pub mod gradients;
pub mod mutations;
pub mod options;
pub mod preview;
pub mod scene_view;

use std::collections::{HashMap, HashSet};
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::sync::mpsc::Receiver;

use eframe::egui::{self, Key, KeyboardShortcut, Modifiers, Vec2};

use crate::flame::animate::RotationAnimation;
use crate::flame::random::{self, VariationMode};
use crate::flame::rng::FastRng;
use crate::flame::variations::{self, VarId};
use crate::flame::{Affine, Flame};
use crate::gradient::Gradient;
use crate::io;
use dialogs::{Confirm, FileBrowser, Purpose};
use document::Document;
use editor::{EditorAction, EditorState};
use escape_view::{EscapeRequest, EscapeTab};
use export::{ExportJob, ExportSettings};
use gradients::{GradientAction, GradientWindow};
use mutations::MutationWindow;
use options::{Options, OptionsTab};
use preview::{PreviewEvent, PreviewJob, PreviewWorker, ThumbnailWorker};
use scene_view::{SceneRequest, SceneTab};

/// Start the editor window.
pub fn run(file: Option<PathBuf>) -> Result<(), eframe::Error> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("ugnis")
            .with_inner_size([1280.0, 820.0])
            .with_drag_and_drop(true),
        renderer: eframe::Renderer::Glow,
        ..Default::default()
    };
    eframe::run_native(
        "ugnis",
        options,
        Box::new(move |cc| {
            let ctx = cc.egui_ctx.clone();
            let start = match file {
                Some(p) => Start::File(p),
                None => Start::Random(seed_from_time()),
            };
            Ok(Box::new(UgnisApp::new(Options::load(), start, Some(ctx))))
        }),
    )
}

fn seed_from_time() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(1, |d| d.as_nanos() as u64)
}

/// How the application starts.
pub enum Start {
    /// A random flame from this seed.
    Random(u64),
    File(PathBuf),
    Flames(Vec<Flame>),
}

/// Every command of the menus, toolbar and shortcuts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    Open,
    Save,
    SaveAs,
    LoadGradient,
    GradientFromImage,
    Export,
    RandomBatch,
    Exit,
    Undo,
    Redo,
    CopyFlame,
    PasteFlame,
    ToggleToolbar,
    ToggleStatusBar,
    ToggleFilePanel,
    ToggleEditor,
    FitPreview,
    ZoomIn,
    ZoomOut,
    /// None: "Random" (one of the seven per transform).
    SetVariation(Option<VarId>),
    ShowGradient,
    ShowMutations,
    RandomFlame,
    ToggleAnimate,
    /// Play flam3-style in-betweens from the current flame to the next one of the file.
    ToggleMorph,
    RandomWeights,
    EqualWeights,
    AreaWeights,
    ShowOptions,
}

/// A menu entry: menu, label, action, shortcut.
pub struct MenuItem {
    pub menu: &'static str,
    pub label: &'static str,
    pub action: Action,
    pub shortcut: Option<KeyboardShortcut>,
}

const fn sc(m: Modifiers, k: Key) -> Option<KeyboardShortcut> {
    Some(KeyboardShortcut::new(m, k))
}

/// The menus (the thesis program's, with Apophysis conventions where it is silent).
pub const MENU: &[MenuItem] = &[
    MenuItem {
        menu: "File",
        label: "Open…",
        action: Action::Open,
        shortcut: sc(Modifiers::COMMAND, Key::O),
    },
    MenuItem {
        menu: "File",
        label: "Save",
        action: Action::Save,
        shortcut: sc(Modifiers::COMMAND, Key::S),
    },
    MenuItem {
        menu: "File",
        label: "Save As…",
        action: Action::SaveAs,
        shortcut: sc(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::S),
    },
    MenuItem {
        menu: "File",
        label: "Load gradient…",
        action: Action::LoadGradient,
        shortcut: None,
    },
    MenuItem {
        menu: "File",
        label: "Create gradient from image…",
        action: Action::GradientFromImage,
        shortcut: None,
    },
    MenuItem {
        menu: "File",
        label: "Export image…",
        action: Action::Export,
        shortcut: sc(Modifiers::COMMAND, Key::E),
    },
    MenuItem {
        menu: "File",
        label: "Random batch",
        action: Action::RandomBatch,
        shortcut: sc(Modifiers::COMMAND, Key::B),
    },
    MenuItem {
        menu: "File",
        label: "Exit",
        action: Action::Exit,
        shortcut: sc(Modifiers::COMMAND, Key::Q),
    },
    MenuItem {
        menu: "Edit",
        label: "Undo",
        action: Action::Undo,
        shortcut: sc(Modifiers::COMMAND, Key::Z),
    },
    MenuItem {
        menu: "Edit",
        label: "Redo",
        action: Action::Redo,
        shortcut: sc(Modifiers::COMMAND, Key::Y),
    },
    MenuItem {
        menu: "Edit",
        label: "Copy flame (XML)",
        action: Action::CopyFlame,
        shortcut: sc(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::C),
    },
    MenuItem {
        menu: "Edit",
        label: "Paste flame (XML)",
        action: Action::PasteFlame,
        shortcut: sc(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::V),
    },
    MenuItem {
        menu: "View",
        label: "Toolbar",
        action: Action::ToggleToolbar,
        shortcut: None,
    },
    MenuItem {
        menu: "View",
        label: "Status bar",
        action: Action::ToggleStatusBar,
        shortcut: None,
    },
    MenuItem {
        menu: "View",
        label: "File contents",
        action: Action::ToggleFilePanel,
        shortcut: None,
    },
    MenuItem {
        menu: "View",
        label: "Fit preview",
        action: Action::FitPreview,
        shortcut: sc(Modifiers::COMMAND, Key::Num0),
    },
    MenuItem {
        menu: "View",
        label: "Zoom in",
        action: Action::ZoomIn,
        shortcut: sc(Modifiers::COMMAND, Key::Plus),
    },
    MenuItem {
        menu: "View",
        label: "Zoom out",
        action: Action::ZoomOut,
        shortcut: sc(Modifiers::COMMAND, Key::Minus),
    },
    MenuItem {
        menu: "Tools",
        label: "Editor",
        action: Action::ToggleEditor,
        shortcut: sc(Modifiers::NONE, Key::F4),
    },
    MenuItem {
        menu: "Tools",
        label: "Gradient",
        action: Action::ShowGradient,
        shortcut: sc(Modifiers::COMMAND, Key::G),
    },
    MenuItem {
        menu: "Tools",
        label: "Random flame",
        action: Action::RandomFlame,
        shortcut: sc(Modifiers::COMMAND, Key::R),
    },
    MenuItem {
        menu: "Tools",
        label: "Mutations…",
        action: Action::ShowMutations,
        shortcut: sc(Modifiers::COMMAND, Key::U),
    },
    MenuItem {
        menu: "Tools",
        label: "Animate",
        action: Action::ToggleAnimate,
        shortcut: sc(Modifiers::COMMAND, Key::M),
    },
    MenuItem {
        menu: "Tools",
        label: "Morph to next flame",
        action: Action::ToggleMorph,
        shortcut: sc(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::M),
    },
    MenuItem {
        menu: "Tools",
        label: "Random weights",
        action: Action::RandomWeights,
        shortcut: None,
    },
    MenuItem {
        menu: "Tools",
        label: "Equal weights",
        action: Action::EqualWeights,
        shortcut: None,
    },
    MenuItem {
        menu: "Tools",
        label: "Weights from triangle areas",
        action: Action::AreaWeights,
        shortcut: None,
    },
    MenuItem {
        menu: "Tools",
        label: "Options…",
        action: Action::ShowOptions,
        shortcut: sc(Modifiers::COMMAND, Key::Comma),
    },
];

/// Extra shortcuts: Ctrl+Shift+Z redo.
const EXTRA_SHORTCUTS: &[(KeyboardShortcut, Action)] = &[(
    KeyboardShortcut::new(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::Z),
    Action::Redo,
)];

/// The Variations submenu: "Random" and the seven thesis variations.
pub const VARIATION_MENU: [(&str, Option<VarId>); 8] = [
    ("Random", None),
    ("Linear", Some(variations::LINEAR)),
    ("Sinusoidal", Some(variations::SINUSOIDAL)),
    ("Spherical", Some(variations::SPHERICAL)),
    ("Swirl", Some(variations::SWIRL)),
    ("Horseshoe", Some(variations::HORSESHOE)),
    ("Polar", Some(variations::POLAR)),
    ("Bent", Some(variations::BENT)),
];

/// Which view of the main window is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tab {
    Flame,
    Escape,
    Scene,
}

/// Something to do once the user has answered "save changes?".
#[derive(Clone, Debug)]
enum Pending {
    Exit,
    Open(PathBuf),
    BrowseOpen,
    ReplaceWith(Vec<Flame>, Option<PathBuf>, String),
}

struct Animation {
    before: Flame,
    anim: RotationAnimation,
    waiting_for: u64,
}

/// In-betweens from one flame of the file to the next, played forth and back in the preview;
/// the document is not changed.
pub struct Morph {
    /// The flame being edited when the morph started (any edit stops the morph).
    source: Flame,
    pub frames: Vec<Flame>,
    pub index: usize,
    forward: bool,
    waiting_for: u64,
    label: String,
}

/// Frames in one direction of a morph (about 4 s at the animation density).
pub const MORPH_FRAMES: usize = 60;

struct Preview {
    worker: PreviewWorker,
    texture: Option<egui::TextureHandle>,
    generation: u64,
    /// The flame, size and quality of the last job.
    submitted: Option<(Flame, [u32; 2], bool)>,
    fraction: f64,
    elapsed_ms: f64,
    error: Option<String>,
    shown_generation: u64,
}

/// The application state.
pub struct UgnisApp {
    pub options: Options,
    pub doc: Document,
    pub editor: EditorState,
    pub tab: Tab,
    pub show_toolbar: bool,
    pub show_status: bool,
    pub show_files: bool,
    pub show_editor: bool,
    /// Preview zoom (1 = fit).
    pub preview_zoom: f32,
    pub variation_mode: VariationMode,
    /// Messages for the status bar.
    pub status: String,
    pub gradients: GradientWindow,
    /// The document not being edited: the open file while a batch flame is shown, otherwise
    /// the last random batch (if any).
    parked: Option<Document>,
    /// True while the editor shows a flame of the random batch.
    pub viewing_batch: bool,
    pub mutations: MutationWindow,
    pub escape: EscapeTab,
    pub scene: SceneTab,
    escape_export: Option<Receiver<Result<PathBuf, String>>>,
    /// UI time per frame in ms when UGNIS_FRAME_TIMES is set.
    frame_log: Option<Vec<f64>>,
    /// Where the last random batch is kept (the platform data directory; none in tests
    /// unless they set one).
    pub data_dir: Option<PathBuf>,
    preview: Option<Preview>,
    thumbs: Option<ThumbnailWorker>,
    thumb_textures: HashMap<u64, egui::TextureHandle>,
    thumbs_requested: HashSet<u64>,
    browser: Option<FileBrowser>,
    pending: Option<Pending>,
    confirm_what: String,
    message: Option<(String, String)>,
    options_dialog: Option<(Options, OptionsTab)>,
    export_dialog: Option<ExportSettings>,
    export_job: Option<ExportJob>,
    batch_job: Option<Receiver<Vec<Flame>>>,
    animation: Option<Animation>,
    pub morph: Option<Morph>,
    rng: FastRng,
    allow_close: bool,
    expect_paste: bool,
    last_export_dir: Option<PathBuf>,
}

fn flame_key(f: &Flame) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    io::flam3_xml::flame_element(f).hash(&mut h);
    h.finish()
}

/// The flame without its palette, for "did only the gradient change?".
fn without_palette(f: &Flame) -> Flame {
    let mut g = f.clone();
    g.palette = Gradient::grey_ramp();
    g.palette_mode = crate::flame::PaletteMode::Step;
    g
}

impl UgnisApp {
    /// A new application. With `ctx` the background renderers start (the live preview and the
    /// thumbnails); without it (tests) nothing renders.
    pub fn new(options: Options, start: Start, ctx: Option<egui::Context>) -> UgnisApp {
        let mut message = None;
        // A view file opens in the escape-time tab (next to a random flame).
        let mut escape_start = None;
        let start = match start {
            Start::File(p) if io::kind_of(&p) == io::FileKind::EscapeView => {
                match io::escape_view::read(&p) {
                    Ok(v) => escape_start = Some((v.value, p)),
                    Err(e) => message = Some(("Cannot open".to_string(), e.to_string())),
                }
                Start::Random(seed_from_time())
            }
            s => s,
        };
        let defaults = options.new_flame();
        let random_flame = |seed: u64| {
            vec![
                random::generate(
                    seed,
                    &options.random_options(VariationMode::default()),
                    &defaults,
                )
                .flame,
            ]
        };
        let (flames, path) = match start {
            Start::Flames(f) if !f.is_empty() => (f, None),
            Start::Flames(_) => (random_flame(1), None),
            Start::Random(seed) => (random_flame(seed), None),
            Start::File(p) => match load_any(&p, &options) {
                Ok((f, w)) => {
                    if !w.is_empty() {
                        message = Some(("Warnings".to_string(), w.join("\n")));
                    }
                    (f, Some(p))
                }
                Err(e) => {
                    message = Some(("Cannot open".to_string(), e));
                    (random_flame(1), None)
                }
            },
        };
        let mut doc = Document::new(flames, path.clone());
        if path.is_none() {
            doc.name = "untitled".into();
        }
        let preview = ctx.as_ref().map(|c| {
            let c = c.clone();
            Preview {
                worker: PreviewWorker::new(move || c.request_repaint()),
                texture: None,
                generation: 0,
                submitted: None,
                fraction: 0.0,
                elapsed_ms: 0.0,
                error: None,
                shown_generation: 0,
            }
        });
        let thumbs = ctx.as_ref().map(|c| {
            let c = c.clone();
            ThumbnailWorker::new(96, 72, 8.0, move || c.request_repaint())
        });
        let data_dir = ctx.as_ref().and_then(|_| options::data_dir());
        let mut editor = EditorState::default();
        editor.canvas = egui::Rect::from_min_size(egui::Pos2::ZERO, Vec2::new(420.0, 360.0));
        editor.auto_zoom(doc.flame());
        UgnisApp {
            options,
            doc,
            editor,
            tab: if escape_start.is_some() {
                Tab::Escape
            } else {
                Tab::Flame
            },
            show_toolbar: true,
            show_status: true,
            show_files: true,
            show_editor: true,
            preview_zoom: 1.0,
            variation_mode: VariationMode::default(),
            status: String::new(),
            gradients: GradientWindow::default(),
            parked: data_dir.as_deref().and_then(load_last_batch),
            data_dir,
            viewing_batch: false,
            mutations: MutationWindow::default(),
            escape: {
                let mut t = EscapeTab::new(ctx.is_some());
                if let Some((d, p)) = escape_start.clone() {
                    t.doc = d;
                    t.path = Some(p);
                }
                t
            },
            scene: SceneTab::new(ctx.is_some()),
            escape_export: None,
            frame_log: std::env::var_os("UGNIS_FRAME_TIMES").map(|_| Vec::new()),
            preview,
            thumbs,
            thumb_textures: HashMap::new(),
            thumbs_requested: HashSet::new(),
            browser: None,
            pending: None,
            confirm_what: String::new(),
            message,
            options_dialog: None,
            export_dialog: None,
            export_job: None,
            batch_job: None,
            animation: None,
            morph: None,
            rng: FastRng::new(seed_from_time()),
            allow_close: false,
            expect_paste: false,
            last_export_dir: None,
        }
    }

    fn auto_weights(&self) -> bool {
        self.doc
            .flame()
            .auto_weights
            .unwrap_or(self.options.auto_weights)
    }

    /// Settings of new random flames: the Options defaults, with the current gradient (used
    /// when "random gradient" is off).
    fn random_defaults(&self) -> crate::flame::NewFlame {
        let mut d = self.options.new_flame();
        d.gradient = self.doc.flame().palette.clone();
        d
    }

    /// The open file's document (whichever document the editor shows).
    pub fn file_doc(&self) -> &Document {
        match (&self.parked, self.viewing_batch) {
            (Some(p), true) => p,
            _ => &self.doc,
        }
    }

    /// The last random batch, if there is one.
    pub fn batch_doc(&self) -> Option<&Document> {
        if self.viewing_batch {
            Some(&self.doc)
        } else {
            self.parked.as_ref()
        }
    }

    /// Edit the open file again (after browsing the batch).
    pub fn view_file(&mut self) {
        if self.viewing_batch
            && let Some(p) = self.parked.as_mut()
        {
            std::mem::swap(&mut self.doc, p);
            self.viewing_batch = false;
            self.editor.selected = editor::Selected::Xform(0);
            self.editor.auto_zoom(self.doc.flame());
        }
    }

    /// Show flame `i` of the random batch in the editor.
    pub fn view_batch(&mut self, i: usize) {
        if !self.viewing_batch
            && let Some(p) = self.parked.as_mut()
        {
            std::mem::swap(&mut self.doc, p);
            self.viewing_batch = true;
        }
        if self.viewing_batch {
            self.doc.current = i.min(self.doc.flames.len() - 1);
            self.editor.selected = editor::Selected::Xform(0);
            self.editor.auto_zoom(self.doc.flame());
        }
    }

    /// Replace the random batch.
    pub fn set_batch(&mut self, flames: Vec<Flame>, path: Option<PathBuf>) {
        let mut d = Document::new(flames, path);
        d.name = "last batch".into();
        if self.viewing_batch {
            self.doc = d;
            self.doc.current = 0;
            self.editor.selected = editor::Selected::Xform(0);
            self.editor.auto_zoom(self.doc.flame());
        } else {
            self.parked = Some(d);
        }
    }

    /// Copy flame `i` of the batch (as edited) into the open file, as one undo step there,
    /// and edit it.
    pub fn keep_from_batch(&mut self, i: usize) {
        let Some(f) = self.batch_doc().and_then(|b| b.flames.get(i)).cloned() else {
            return;
        };
        self.view_file();
        let name = f.name.clone();
        self.doc.edit_document(|fl, cur| {
            fl.push(f);
            *cur = fl.len() - 1;
        });
        self.editor.selected = editor::Selected::Xform(0);
        self.editor.auto_zoom(self.doc.flame());
        self.status = format!("'{name}' kept in {}", self.doc.name);
    }

    /// Carry out a command.
    pub fn act(&mut self, ctx: &egui::Context, a: Action) {
        // Commands about the file work on the open file, not on the batch.
        if matches!(
            a,
            Action::Open | Action::Save | Action::SaveAs | Action::Exit
        ) {
            self.view_file();
        }
        match a {
            Action::Open => self.guard_dirty(Pending::BrowseOpen, "opening another file"),
            Action::Save => {
                if let Some(p) = self
                    .doc
                    .path
                    .clone()
                    .filter(|p| io::kind_of(p) != io::FileKind::Png)
                {
                    self.save_to(&p);
                } else {
                    self.browse(Purpose::SaveAs);
                }
            }
            Action::SaveAs => self.browse(Purpose::SaveAs),
            Action::LoadGradient => self.browse(Purpose::LoadGradient),
            Action::GradientFromImage => self.browse(Purpose::GradientFromImage),
            Action::Export => {
                let f = self.doc.flame();
                let dir = self.last_export_dir.clone().or_else(|| {
                    self.doc
                        .path
                        .as_ref()
                        .and_then(|p| p.parent().map(Path::to_path_buf))
                });
                let name = if f.name.is_empty() {
                    "flame".to_string()
                } else {
                    io::ifs::entry_name(&f.name)
                };
                self.export_dialog = Some(ExportSettings {
                    width: f.width,
                    height: f.height,
                    quality: f.quality.max(self.options.main_quality),
                    supersample: f.supersample,
                    bits16: false,
                    transparent: false,
                    path: dir.unwrap_or_default().join(format!("{name}.png")),
                });
            }
            Action::RandomBatch => self.start_batch(),
            Action::Exit => self.guard_dirty(Pending::Exit, "quitting"),
            Action::Undo => {
                if !self.doc.undo() {
                    self.status = "Nothing to undo".into();
                }
            }
            Action::Redo => {
                if !self.doc.redo() {
                    self.status = "Nothing to redo".into();
                }
            }
            Action::CopyFlame => {
                ctx.copy_text(io::flam3_xml::flame_element(self.doc.flame()));
                self.status = "Flame copied as XML".into();
            }
            Action::PasteFlame => {
                self.expect_paste = true;
                ctx.send_viewport_cmd(egui::ViewportCommand::RequestPaste);
            }
            Action::ToggleToolbar => self.show_toolbar = !self.show_toolbar,
            Action::ToggleStatusBar => self.show_status = !self.show_status,
            Action::ToggleFilePanel => self.show_files = !self.show_files,
            Action::ToggleEditor => self.show_editor = !self.show_editor,
            Action::FitPreview => self.preview_zoom = 1.0,
            Action::ZoomIn => self.preview_zoom = (self.preview_zoom * 1.25).min(8.0),
            Action::ZoomOut => self.preview_zoom = (self.preview_zoom / 1.25).max(0.125),
            Action::SetVariation(v) => self.set_variation(v),
            Action::ShowGradient => self.gradients.open = !self.gradients.open,
            Action::ShowMutations => self.mutations.open = !self.mutations.open,
            Action::RandomFlame => self.random_flame(),
            Action::ToggleAnimate => self.toggle_animation(),
            Action::ToggleMorph => self.toggle_morph(),
            Action::RandomWeights => {
                let mut rng = FastRng::new(self.rng.u64());
                self.doc.edit(|f| {
                    let mut w: Vec<f64> = f.xforms.iter().map(|_| rng.f01()).collect();
                    let s: f64 = w.iter().sum();
                    if s < 0.001 {
                        f.set_equal_weights();
                    } else {
                        w.iter_mut().for_each(|v| *v /= s);
                        for (x, v) in f.xforms.iter_mut().zip(w) {
                            x.weight = v;
                        }
                    }
                    f.auto_weights = Some(false);
                });
            }
            Action::EqualWeights => self.doc.edit(|f| {
                f.set_equal_weights();
                f.auto_weights = Some(false);
            }),
            Action::AreaWeights => self.doc.edit(|f| f.set_determinant_weights()),
            Action::ShowOptions => {
                self.options_dialog = Some((self.options.clone(), OptionsTab::default()))
            }
        }
    }

    fn set_variation(&mut self, v: Option<VarId>) {
        match v {
            None => {
                self.variation_mode = VariationMode::Random(self.options.probabilities);
                self.status = "Variation: Random".into();
            }
            Some(id) => {
                self.variation_mode = VariationMode::Single(id);
                self.doc.edit(|f| {
                    for x in &mut f.xforms {
                        x.vars = vec![crate::flame::Var::new(id, 1.0)];
                    }
                });
                let name = VARIATION_MENU
                    .iter()
                    .find(|m| m.1 == Some(id))
                    .map_or("", |m| m.0);
                self.status = format!("Variation: {name}");
            }
        }
    }

    fn random_flame(&mut self) {
        let seed = self.rng.u64();
        let opts = self.options.random_options(self.variation_mode.clone());
        let mut g = random::generate(seed, &opts, &self.random_defaults()).flame;
        g.name = format!("random-{:08x}", seed as u32);
        let cur = self.doc.current;
        self.doc.edit_document(|fl, c| {
            fl[cur] = g;
            *c = cur;
        });
        self.editor.selected = editor::Selected::Xform(0);
        self.editor.auto_zoom(self.doc.flame());
        self.status = format!("Random flame (seed {seed})");
    }

    fn start_batch(&mut self) {
        if self.batch_job.is_some() {
            return;
        }
        let seed = self.rng.u64();
        let opts = self.options.random_options(self.variation_mode.clone());
        let defaults = self.random_defaults();
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let _ = tx.send(random::generate_batch(100, seed, &opts, &defaults));
        });
        self.batch_job = Some(rx);
        self.status = "Generating a random batch…".into();
    }

    fn toggle_morph(&mut self) {
        if self.morph.take().is_some() {
            self.status = "Morph stopped".into();
            return;
        }
        let n = self.doc.flames.len();
        if n < 2 {
            self.status = "Morphing needs a file with two or more flames".into();
            return;
        }
        if let Some(a) = self.animation.take() {
            self.doc.end_gesture(a.before);
        }
        let a = self.doc.flame().clone();
        let b = &self.doc.flames[(self.doc.current + 1) % n];
        let name = |f: &Flame| {
            if f.name.is_empty() {
                "(unnamed)".to_string()
            } else {
                f.name.clone()
            }
        };
        let label = format!("{} -> {}", name(&a), name(b));
        self.morph = Some(Morph {
            frames: crate::flame::animate::interpolation_frames(
                &[a.clone(), b.clone()],
                MORPH_FRAMES,
            ),
            source: a,
            index: 0,
            forward: true,
            waiting_for: 0,
            label: label.clone(),
        });
        self.status = format!("Morphing {label}");
    }

    fn morph_step(&mut self) {
        let Some(m) = self.morph.as_mut() else {
            return;
        };
        if self.doc.flame() != &m.source {
            self.morph = None;
            self.status = "Morph stopped (the flame changed)".into();
            return;
        }
        if let Some(p) = &self.preview
            && p.shown_generation < m.waiting_for
        {
            return;
        }
        let last = m.frames.len() - 1;
        if m.forward && m.index == last {
            m.forward = false;
        } else if !m.forward && m.index == 0 {
            m.forward = true;
        }
        m.index = if m.forward { m.index + 1 } else { m.index - 1 }.min(last);
        if let Some(p) = &self.preview {
            m.waiting_for = p.generation + 1;
        }
    }

    fn toggle_animation(&mut self) {
        self.morph = None;
        if let Some(a) = self.animation.take() {
            // Stopping keeps the coefficients; one undo step returns to the start.
            self.doc.end_gesture(a.before);
            self.status = "Animation stopped".into();
        } else {
            self.animation = Some(Animation {
                before: self.doc.begin_gesture(),
                anim: RotationAnimation::new(self.rng.u64()),
                waiting_for: 0,
            });
            self.status = "Animating".into();
        }
    }

    fn animate_step(&mut self) {
        let Some(a) = self.animation.as_mut() else {
            return;
        };
        // Wait for the preview of the previous step (so the renderer keeps up).
        if let Some(p) = &self.preview
            && p.shown_generation < a.waiting_for
        {
            return;
        }
        a.anim.step(self.doc.flame_mut_in_gesture());
        if let Some(p) = &self.preview {
            a.waiting_for = p.generation + 1;
        }
    }

    fn guard_dirty(&mut self, p: Pending, what: &str) {
        if self.doc.dirty {
            self.pending = Some(p);
            self.confirm_what = what.to_string();
        } else {
            self.run_pending(p);
        }
    }

    fn run_pending(&mut self, p: Pending) {
        match p {
            Pending::Exit => self.allow_close = true,
            Pending::Open(path) => self.open_path(&path),
            Pending::BrowseOpen => self.browse(Purpose::Open),
            Pending::ReplaceWith(flames, path, name) => {
                let mut d = Document::new(flames, path);
                d.name = name;
                self.doc = d;
                self.editor.selected = editor::Selected::Xform(0);
                self.editor.auto_zoom(self.doc.flame());
            }
        }
    }

    fn browse(&mut self, purpose: Purpose) {
        let name = match purpose {
            Purpose::SaveAs => self
                .doc
                .path
                .as_ref()
                .and_then(|p| p.file_name())
                .map_or_else(
                    || format!("{}.fla", self.doc.name),
                    |n| n.to_string_lossy().into_owned(),
                ),
            Purpose::SaveView => self
                .escape
                .path
                .as_ref()
                .and_then(|p| p.file_name())
                .map_or_else(
                    || format!("{}.esc", self.escape.doc.params.family.name()),
                    |n| n.to_string_lossy().into_owned(),
                ),
            Purpose::ExportEscape => format!("{}.png", self.escape.doc.params.family.name()),
            Purpose::ExportScene => "scene.png".into(),
            _ => String::new(),
        };
        let start = match purpose {
            Purpose::OpenView | Purpose::SaveView | Purpose::ExportEscape => {
                self.escape.path.clone()
            }
            Purpose::OpenScene | Purpose::ExportScene | Purpose::SceneTexture => {
                self.scene.path.clone()
            }
            _ => self.doc.path.clone(),
        };
        self.browser = Some(FileBrowser::new(purpose, start.as_deref(), &name));
    }

    /// Open a file, replacing the document (the caller asked about unsaved changes).
    pub fn open_path(&mut self, path: &Path) {
        match load_any(path, &self.options) {
            Ok((flames, warnings)) => {
                let name = path
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                self.run_pending(Pending::ReplaceWith(flames, Some(path.to_path_buf()), name));
                self.status = format!("Opened {}", path.display());
                if !warnings.is_empty() {
                    self.message = Some(("Warnings".into(), warnings.join("\n")));
                }
            }
            Err(e) => self.message = Some(("Cannot open".into(), e)),
        }
    }

    /// Save the document (atomically). Returns true on success.
    pub fn save_to(&mut self, path: &Path) -> bool {
        match io::write_flames(path, &self.doc.name, &self.doc.flames) {
            Ok(w) => {
                self.doc.path = Some(path.to_path_buf());
                self.doc.dirty = false;
                self.status = format!("Saved {}", path.display());
                if !w.is_empty() {
                    self.message = Some(("Saved with losses".into(), w.join("\n")));
                }
                true
            }
            Err(e) => {
                self.message = Some(("Cannot save".into(), e));
                false
            }
        }
    }

    fn apply_gradient(&mut self, g: Gradient) {
        self.doc.edit(|f| f.palette = g);
    }

    fn file_chosen(&mut self, purpose: Purpose, path: PathBuf) {
        match purpose {
            Purpose::Open => self.open_path(&path),
            Purpose::SaveAs => {
                let mut p = path;
                if p.extension().is_none() {
                    p.set_extension("fla");
                }
                if self.save_to(&p) && matches!(self.pending, Some(Pending::Exit)) {
                    self.allow_close = true;
                }
            }
            Purpose::LoadGradient => match io::read_gradients(&path) {
                Ok(p) => {
                    let n = p.value.len();
                    if let Some(first) = p.value.first().cloned() {
                        self.apply_gradient(first);
                    }
                    self.gradients.add(p.value);
                    self.gradients.open = true;
                    self.status = format!("Loaded {n} gradient(s) from {}", path.display());
                }
                Err(e) => self.message = Some(("Cannot load gradient".into(), e.to_string())),
            },
            Purpose::GradientFromImage => match io::image_in::gradient_from_image(&path, 1) {
                Ok(g) => {
                    self.gradients.add(vec![g.clone()]);
                    self.apply_gradient(g);
                    self.gradients.open = true;
                }
                Err(e) => self.message = Some(("Cannot read the image".into(), e.to_string())),
            },
            Purpose::Export => {
                if let Some(s) = &mut self.export_dialog {
                    s.path = path;
                }
            }
            Purpose::OpenView => match io::escape_view::read(&path) {
                Ok(p) => {
                    if !p.warnings.is_empty() {
                        let w: Vec<String> = p.warnings.iter().map(|w| w.to_string()).collect();
                        self.message = Some(("Warnings".into(), w.join("\n")));
                    }
                    self.escape.load(p.value, Some(path.clone()));
                    self.status = format!("Opened {}", path.display());
                }
                Err(e) => self.message = Some(("Cannot open".into(), e.to_string())),
            },
            Purpose::SaveView => {
                let mut p = path;
                if p.extension().is_none() {
                    p.set_extension("esc");
                }
                match io::escape_view::save(&p, &self.escape.doc) {
                    Ok(()) => {
                        self.status = format!("Saved {}", p.display());
                        self.escape.path = Some(p);
                    }
                    Err(e) => {
                        self.message = Some(("Cannot save".into(), format!("{}: {e}", p.display())))
                    }
                }
            }
            Purpose::OpenScene => match io::scene::read(&path) {
                Ok(l) => {
                    self.scene
                        .load(l.scene, l.texture_names, Some(path.clone()));
                    self.status = format!("Opened {}", path.display());
                }
                Err(e) => self.message = Some(("Cannot open".into(), e.to_string())),
            },
            Purpose::SceneTexture => self.scene.set_image_texture(&path),
            Purpose::ExportScene => {
                let mut p = path;
                if p.extension().is_none() {
                    p.set_extension("png");
                }
                let scene = self.scene.export_scene();
                let (tx, rx) = std::sync::mpsc::channel();
                let out = p.clone();
                std::thread::spawn(move || {
                    let r = crate::surface::render(&scene, None)
                        .ok_or_else(|| "cancelled".to_string())
                        .and_then(|img| {
                            let img = image::DynamicImage::ImageRgb8(img);
                            let res = if io::kind_of(&out) == io::FileKind::Bmp {
                                io::bmp::save(&out, &img)
                            } else {
                                io::png::save(&out, &img, &Default::default())
                            };
                            res.map_err(|e| format!("{}: {e}", out.display()))
                        });
                    let _ = tx.send(r.map(|()| out));
                });
                self.escape_export = Some(rx);
                self.status = format!("Exporting {}…", p.display());
            }
            Purpose::ExportEscape => {
                let mut p = path;
                if p.extension().is_none() {
                    p.set_extension("png");
                }
                let doc = self.escape.export_doc();
                let (tx, rx) = std::sync::mpsc::channel();
                let out = p.clone();
                std::thread::spawn(move || {
                    let r = crate::escape::render(&doc.params, doc.view, doc.width, doc.height)
                        .map_err(|e| e.to_string())
                        .and_then(|(img, _)| {
                            let img = image::DynamicImage::ImageRgb8(img);
                            let res = if io::kind_of(&out) == io::FileKind::Bmp {
                                io::bmp::save(&out, &img)
                            } else {
                                let meta = io::png::PngMeta {
                                    text: vec![(
                                        "ugnis_escape_view".into(),
                                        io::escape_view::write(&doc),
                                    )],
                                    ..Default::default()
                                };
                                io::png::save(&out, &img, &meta)
                            };
                            res.map_err(|e| format!("{}: {e}", out.display()))
                        });
                    let _ = tx.send(r.map(|()| out));
                });
                self.escape_export = Some(rx);
                self.status = format!("Exporting {}…", p.display());
            }
        }
    }

    fn handle_shortcuts(&mut self, ctx: &egui::Context) {
        let typing = ctx.memory(|m| m.focused().is_some());
        let mut fired = Vec::new();
        // egui matches shortcuts ignoring extra Shift, so try the ones with more modifiers
        // first (Ctrl+Shift+S is Save As, not Save).
        let mut all: Vec<(KeyboardShortcut, Action)> = EXTRA_SHORTCUTS
            .iter()
            .copied()
            .chain(
                MENU.iter()
                    .filter_map(|m| m.shortcut.map(|s| (s, m.action))),
            )
            .collect();
        let weight = |m: Modifiers| m.shift as u8 + m.alt as u8 + (m.command || m.ctrl) as u8;
        all.sort_by_key(|(s, _)| std::cmp::Reverse(weight(s.modifiers)));
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
                .filter_map(|e| {
                    if let egui::Event::Paste(s) = e {
                        Some(s.clone())
                    } else {
                        None
                    }
                })
                .collect()
        });
        for text in pasted {
            if !(self.expect_paste || (!typing && text.contains("<flame"))) {
                continue;
            }
            self.expect_paste = false;
            match io::flam3_xml::read(&text, &Default::default()) {
                Ok(p) => {
                    let new: Vec<Flame> = p.value.flames;
                    let n = new.len();
                    self.doc.edit_document(|fl, cur| {
                        fl.extend(new);
                        *cur = fl.len() - 1;
                    });
                    self.status = format!("Pasted {n} flame(s)");
                }
                Err(e) => self.status = format!("Clipboard holds no flame: {e}"),
            }
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

    fn menu_bar(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let mut chosen = None;
        egui::MenuBar::new().ui(ui, |ui| {
            for menu in ["File", "Edit", "View", "Tools"] {
                ui.menu_button(menu, |ui| {
                    for m in MENU.iter().filter(|m| m.menu == menu) {
                        if menu == "Tools" && m.action == Action::ToggleEditor {
                            ui.menu_button("Variations", |ui| {
                                for (label, v) in VARIATION_MENU {
                                    let sel = match (&self.variation_mode, v) {
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
                        let checked = match m.action {
                            Action::ToggleToolbar => Some(self.show_toolbar),
                            Action::ToggleStatusBar => Some(self.show_status),
                            Action::ToggleFilePanel => Some(self.show_files),
                            Action::ToggleEditor => Some(self.show_editor),
                            Action::ToggleAnimate => Some(self.animation.is_some()),
                            Action::ToggleMorph => Some(self.morph.is_some()),
                            _ => None,
                        };
                        let mut b = egui::Button::new(m.label).selected(checked == Some(true));
                        if let Some(s) = &m.shortcut {
                            b = b.shortcut_text(ctx.format_shortcut(s));
                        }
                        let enabled = match m.action {
                            Action::Undo => self.doc.can_undo(),
                            Action::Redo => self.doc.can_redo(),
                            Action::RandomBatch => self.batch_job.is_none(),
                            _ => true,
                        };
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

    fn toolbar(&mut self, ui: &mut egui::Ui) {
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

    fn status_bar(&mut self, ui: &mut egui::Ui) {
        if self.tab == Tab::Scene {
            ui.horizontal(|ui| {
                ui.label(self.scene.status_text());
                ui.separator();
                ui.label(&self.status);
            });
            return;
        }
        if self.tab == Tab::Escape {
            ui.horizontal(|ui| {
                ui.label(self.escape.status_text());
                ui.separator();
                ui.label(&self.status);
            });
            return;
        }
        ui.horizontal(|ui| {
            let f = self.doc.flame();
            ui.label(format!(
                "{}{}  {}×{}  {} transforms",
                if f.name.is_empty() {
                    "(unnamed)"
                } else {
                    &f.name
                },
                if self.doc.dirty { " *" } else { "" },
                f.width,
                f.height,
                f.xforms.len()
            ));
            ui.separator();
            match self.editor.hover_world {
                Some([x, y]) => ui.label(format!("x {x:.4}  y {y:.4}")),
                None => ui.label("x —  y —"),
            };
            ui.separator();
            if let Some(p) = &self.preview {
                if let Some(e) = &p.error {
                    ui.colored_label(egui::Color32::from_rgb(230, 120, 90), e);
                } else {
                    ui.label(format!(
                        "preview {:>3.0}%  {:.0} ms",
                        p.fraction * 100.0,
                        p.elapsed_ms
                    ));
                }
                ui.separator();
            }
            if let Some(m) = &self.morph {
                ui.label(format!(
                    "morph {}  {}/{}",
                    m.label,
                    m.index + 1,
                    m.frames.len()
                ));
                ui.separator();
            }
            if let Some(j) = &self.export_job {
                ui.add(
                    egui::ProgressBar::new(j.fraction() as f32)
                        .desired_width(140.0)
                        .text(format!("export {:.0}%", j.fraction() * 100.0)),
                );
                if ui.button("Cancel").clicked() {
                    j.cancel();
                }
                ui.separator();
            }
            if let Some(n) = self.editor.notice.take() {
                self.status = n;
            }
            ui.label(&self.status);
        });
    }

    /// Ask the thumbnail worker for a flame's picture once; its texture when ready.
    fn thumbnail(&mut self, f: &Flame) -> Option<egui::TextureId> {
        let key = flame_key(f);
        if !self.thumbs_requested.contains(&key)
            && let Some(t) = &self.thumbs
        {
            t.request(key, f.clone());
            self.thumbs_requested.insert(key);
        }
        self.thumb_textures.get(&key).map(|t| t.id())
    }

    fn file_panel(&mut self, ui: &mut egui::Ui) {
        let file = self.file_doc();
        let (name, n, dirty) = (file.name.clone(), file.flames.len(), file.dirty);
        ui.heading(format!("{name}{}", if dirty { " *" } else { "" }));
        ui.label(format!("{n} flame(s)"));
        ui.separator();
        let mut select = None;
        let batch_len = self.batch_doc().map_or(0, |b| b.flames.len());
        let list_height = if batch_len > 0 {
            (ui.available_height() * 0.35).max(80.0)
        } else {
            f32::INFINITY
        };
        egui::ScrollArea::vertical()
            .id_salt("file-flames")
            .max_height(list_height)
            .show(ui, |ui| {
                let flames = self.file_doc().flames.clone();
                let current = (!self.viewing_batch).then_some(self.file_doc().current);
                for (i, f) in flames.iter().enumerate() {
                    let label = if f.name.is_empty() {
                        format!("flame {}", i + 1)
                    } else {
                        f.name.clone()
                    };
                    let tex = self.thumbnail(f);
                    ui.horizontal(|ui| {
                        let size = Vec2::new(64.0, 48.0);
                        let r = match tex {
                            Some(t) => {
                                ui.add(egui::Image::new((t, size)).sense(egui::Sense::click()))
                            }
                            None => ui.add(egui::Button::new("…").min_size(size)),
                        };
                        let l = ui.selectable_label(current == Some(i), label);
                        if r.clicked() || l.clicked() {
                            select = Some(i);
                        }
                    });
                }
            });
        if let Some(i) = select {
            self.view_file();
            self.doc.current = i;
            self.editor.selected = editor::Selected::Xform(0);
            self.editor.auto_zoom(self.doc.flame());
        }
        if batch_len == 0 {
            return;
        }
        ui.separator();
        ui.horizontal(|ui| {
            ui.strong(format!("Last random batch ({batch_len})"));
        });
        ui.label("Click to edit; Keep copies into the file.");
        // A grid of thumbnails; only the visible rows are drawn and asked for, so the
        // pictures in view render first.
        let cols = ((ui.available_width() / 86.0).floor() as usize).max(1);
        let rows = batch_len.div_ceil(cols);
        let row_h = 60.0 + 2.0 * ui.spacing().interact_size.y + 6.0;
        let mut open = None;
        let mut keep = None;
        let current = self.viewing_batch.then_some(self.doc.current);
        egui::ScrollArea::vertical()
            .id_salt("batch-grid")
            .show_rows(ui, row_h, rows, |ui, range| {
                for r in range {
                    ui.horizontal(|ui| {
                        for c in 0..cols {
                            let i = r * cols + c;
                            let Some(f) = self.batch_doc().and_then(|b| b.flames.get(i)).cloned()
                            else {
                                break;
                            };
                            let tex = self.thumbnail(&f);
                            ui.vertical(|ui| {
                                ui.set_width(80.0);
                                let size = Vec2::new(80.0, 60.0);
                                let r = match tex {
                                    Some(t) => ui.add(
                                        egui::Image::new((t, size)).sense(egui::Sense::click()),
                                    ),
                                    None => ui.add(egui::Button::new("…").min_size(size)),
                                };
                                let l = ui.selectable_label(current == Some(i), &f.name);
                                if r.clicked() || l.clicked() {
                                    open = Some(i);
                                }
                                if ui
                                    .small_button("Keep")
                                    .on_hover_text("copy this flame into the open file")
                                    .clicked()
                                {
                                    keep = Some(i);
                                }
                            });
                        }
                    });
                }
            });
        if let Some(i) = open {
            self.view_batch(i);
        }
        if let Some(i) = keep {
            self.keep_from_batch(i);
        }
    }

    fn preview_panel(&mut self, ui: &mut egui::Ui, dragging: bool) {
        let avail = ui.available_size();
        let f = match &self.morph {
            Some(m) => m.frames[m.index].clone(),
            None => self.doc.flame().clone(),
        };
        // The preview keeps the flame's aspect ratio and is at most preview_size pixels.
        let ppp = ui.ctx().pixels_per_point();
        let aspect = f.width as f32 / f.height.max(1) as f32;
        let (mut w, mut h) = (avail.x, avail.x / aspect);
        if h > avail.y {
            h = avail.y;
            w = h * aspect;
        }
        let cap = self.options.preview_size as f32 / ppp;
        if w.max(h) > cap {
            let k = cap / w.max(h);
            w *= k;
            h *= k;
        }
        let px = [(w * ppp).max(16.0) as u32, (h * ppp).max(12.0) as u32];
        if let Some(p) = &mut self.preview {
            let animating = self.animation.is_some() || self.morph.is_some();
            let quick = dragging || animating;
            let first = self.options.preview_quality.min(f.quality);
            let final_q = if quick {
                if animating {
                    self.options.animation_quality
                } else {
                    self.options.preview_quality
                }
            } else {
                f.quality
            };
            let need = match &p.submitted {
                Some((sf, size, q)) => sf != &f || *size != px || *q != quick,
                None => true,
            };
            if need {
                let only_palette = match &p.submitted {
                    Some((sf, size, q)) => {
                        *size == px && *q == quick && without_palette(sf) == without_palette(&f)
                    }
                    None => false,
                };
                if only_palette {
                    p.worker
                        .recolor(f.palette.clone(), f.palette_mode, p.generation);
                } else {
                    p.generation += 1;
                    p.worker.submit(PreviewJob {
                        flame: f.clone(),
                        width: px[0],
                        height: px[1],
                        first_quality: if animating {
                            self.options.animation_quality
                        } else {
                            first
                        },
                        final_quality: final_q,
                        threads: self.options.threads,
                        generation: p.generation,
                    });
                }
                p.submitted = Some((f.clone(), px, quick));
            }
            for ev in p.worker.poll() {
                match ev {
                    PreviewEvent::Frame(fr) if fr.generation == p.generation => {
                        match &mut p.texture {
                            Some(t) => t.set(fr.image, egui::TextureOptions::LINEAR),
                            None => {
                                p.texture = Some(ui.ctx().load_texture(
                                    "preview",
                                    fr.image,
                                    egui::TextureOptions::LINEAR,
                                ))
                            }
                        }
                        p.fraction = fr.fraction;
                        p.elapsed_ms = fr.elapsed_ms;
                        p.error = None;
                        p.shown_generation = fr.generation;
                    }
                    PreviewEvent::Error {
                        generation,
                        message,
                    } if generation == p.generation => {
                        p.error = Some(message);
                        p.shown_generation = generation;
                    }
                    _ => {}
                }
            }
        }
        let size = Vec2::new(w, h) * self.preview_zoom;
        egui::ScrollArea::both().show(ui, |ui| {
            ui.centered_and_justified(|ui| {
                match self.preview.as_ref().and_then(|p| p.texture.as_ref()) {
                    Some(t) => {
                        ui.add(egui::Image::new((t.id(), size)));
                    }
                    None => {
                        ui.label("rendering…");
                    }
                }
            });
        });
    }

    fn editor_panel(&mut self, ui: &mut egui::Ui) -> bool {
        let auto = self.auto_weights();
        let flame = self.doc.flame().clone();
        if let Some(a) = editor::toolbar(ui, &mut self.editor, &flame) {
            self.editor_action(ui.ctx(), a);
        }
        let h = (ui.available_height() * 0.55).max(160.0);
        let mut dragging = false;
        ui.allocate_ui(Vec2::new(ui.available_width(), h), |ui| {
            let out = editor::canvas(ui, &mut self.doc, &mut self.editor, auto);
            dragging = out.dragging;
            if let Some(a) = out.action {
                self.editor_action(ui.ctx(), a);
            }
        });
        ui.separator();
        egui::ScrollArea::vertical()
            .id_salt("xform-panels")
            .show(ui, |ui| {
                editor::panels(ui, &mut self.doc, &mut self.editor, auto);
                ui.separator();
                flame_settings(ui, &mut self.doc);
            });
        dragging
    }

    fn editor_action(&mut self, ctx: &egui::Context, a: EditorAction) {
        let auto = self.auto_weights();
        match a {
            EditorAction::AutoZoom => self.editor.auto_zoom(self.doc.flame()),
            EditorAction::Delete => {
                if let Err(e) = editor::delete_selected(&mut self.doc, &mut self.editor) {
                    self.status = e;
                }
            }
            EditorAction::Duplicate => {
                editor::duplicate_selected(&mut self.doc, &mut self.editor, auto)
            }
            EditorAction::Add => editor::add_xform(&mut self.doc, &mut self.editor, auto),
            EditorAction::Undo => self.act(ctx, Action::Undo),
            EditorAction::Redo => self.act(ctx, Action::Redo),
        }
    }

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
            && self.doc.dirty
        {
            match dialogs::confirm_discard(ctx, &self.confirm_what) {
                Some(Confirm::Save) => {
                    let saved = match self
                        .doc
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
                    self.doc.dirty = false;
                    self.run_pending(p);
                }
                Some(Confirm::Cancel) => self.pending = None,
                None => {}
            }
        } else if !self.doc.dirty
            && self.browser.is_none()
            && let Some(p) = self.pending.take()
        {
            self.run_pending(p);
        }
        if let Some((title, text)) = self.message.clone()
            && dialogs::message(ctx, &title, &text)
        {
            self.message = None;
        }
        if let Some((draft, tab)) = &mut self.options_dialog {
            let mut r = None;
            egui::Window::new("Options")
                .collapsible(false)
                .pivot(egui::Align2::CENTER_CENTER)
                .default_pos(ctx.content_rect().center())
                .resizable(false)
                .show(ctx, |ui| {
                    r = options::dialog(ui, draft, tab);
                });
            match r {
                Some(true) => {
                    self.options = draft.clone();
                    if let Err(e) = self.options.save() {
                        self.message = Some(("Options".into(), e));
                    }
                    self.options_dialog = None;
                }
                Some(false) => self.options_dialog = None,
                None => {}
            }
        }
        if let Some(s) = &mut self.export_dialog {
            let mut browse = false;
            let mut r = None;
            egui::Window::new("Export image")
                .collapsible(false)
                .pivot(egui::Align2::CENTER_CENTER)
                .default_pos(ctx.content_rect().center())
                .show(ctx, |ui| {
                    r = export::dialog(ui, s, &mut browse);
                });
            if browse {
                let p = s.path.clone();
                let name = p
                    .file_name()
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or_default();
                self.browser = Some(FileBrowser::new(Purpose::Export, p.parent(), &name));
            }
            match r {
                Some(true) => {
                    let s = s.clone();
                    self.last_export_dir = s.path.parent().map(Path::to_path_buf);
                    self.export_job =
                        Some(ExportJob::start(self.doc.flame(), &s, self.options.threads));
                    self.export_dialog = None;
                }
                Some(false) => self.export_dialog = None,
                None => {}
            }
        }
        if let Some(j) = &mut self.export_job {
            match j.poll() {
                Some(Ok(())) => {
                    self.status = format!("Exported {}", j.path.display());
                    self.export_job = None;
                }
                Some(Err(e)) => {
                    self.status = e;
                    self.export_job = None;
                }
                None => ctx.request_repaint_after(std::time::Duration::from_millis(100)),
            }
        }
        if let Some(rx) = &self.escape_export {
            match rx.try_recv() {
                Ok(Ok(p)) => {
                    self.escape_export = None;
                    self.status = format!("Exported {}", p.display());
                }
                Ok(Err(e)) => {
                    self.escape_export = None;
                    self.message = Some(("Export failed".into(), e));
                }
                Err(std::sync::mpsc::TryRecvError::Empty) => {
                    ctx.request_repaint_after(std::time::Duration::from_millis(100))
                }
                Err(_) => self.escape_export = None,
            }
        }
        if let Some(rx) = &self.batch_job {
            match rx.try_recv() {
                Ok(flames) => {
                    self.batch_job = None;
                    let path = self.data_dir.as_ref().map(|d| d.join("last-batch.fla"));
                    if let Some(p) = &path {
                        let _ = std::fs::create_dir_all(p.parent().unwrap_or(Path::new(".")));
                        if let Err(e) = io::write_flames(p, "last-batch", &flames) {
                            self.status = e;
                        }
                    }
                    self.show_files = true;
                    self.set_batch(flames, path);
                    self.status = "Random batch ready".into();
                }
                Err(std::sync::mpsc::TryRecvError::Empty) => {
                    ctx.request_repaint_after(std::time::Duration::from_millis(100))
                }
                Err(_) => self.batch_job = None,
            }
        }
        let opts = self.options.random_options(self.variation_mode.clone());
        let centre = self.doc.flame().clone();
        if let Some(m) = self
            .mutations
            .show(ctx, &centre, &opts, self.preview.is_some())
        {
            self.doc.edit(|f| *f = m);
            self.editor.fix_selection(self.doc.flame());
            self.editor.auto_zoom(self.doc.flame());
            self.status = "Mutant chosen (Undo returns)".into();
        }
        let current = self.doc.flame().palette.clone();
        if let Some(a) = self.gradients.show(ctx, &current) {
            match a {
                GradientAction::Apply(g) => self.apply_gradient(g),
                GradientAction::Load => self.browse(Purpose::LoadGradient),
                GradientAction::FromImage => self.browse(Purpose::GradientFromImage),
            }
        }
    }

    /// The whole user interface of one frame.
    pub fn ui(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        self.handle_shortcuts(&ctx);
        if let Some(t) = &self.thumbs {
            for (key, r) in t.poll() {
                if let Ok(img) = r {
                    self.thumb_textures.insert(
                        key,
                        ctx.load_texture(format!("thumb-{key}"), img, egui::TextureOptions::LINEAR),
                    );
                }
            }
        }
        // Close requests ask about unsaved changes.
        if ctx.input(|i| i.viewport().close_requested()) && !self.allow_close {
            if self.file_doc().dirty {
                self.view_file();
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
        let title = format!(
            "ugnis — {}{}",
            self.file_doc().name,
            if self.file_doc().dirty { " *" } else { "" }
        );
        ctx.send_viewport_cmd(egui::ViewportCommand::Title(title));

        egui::Panel::top("menu").show(ui, |ui| self.menu_bar(ui));
        if self.show_toolbar {
            egui::Panel::top("toolbar").show(ui, |ui| self.toolbar(ui));
        }
        if self.show_status {
            egui::Panel::bottom("status").show(ui, |ui| self.status_bar(ui));
        }
        let mut dragging = false;
        match self.tab {
            Tab::Flame => {
                if self.show_files {
                    egui::Panel::left("files")
                        .default_size(200.0)
                        .resizable(true)
                        .show(ui, |ui| self.file_panel(ui));
                }
                if self.show_editor {
                    egui::Panel::right("editor")
                        .default_size(520.0)
                        .resizable(true)
                        .show(ui, |ui| {
                            dragging = self.editor_panel(ui);
                        });
                }
                egui::CentralPanel::default().show(ui, |ui| self.preview_panel(ui, dragging));
            }
            Tab::Escape => {
                if let Some(r) = self.escape.ui(ui) {
                    match r {
                        EscapeRequest::OpenView => self.browse(Purpose::OpenView),
                        EscapeRequest::SaveView => self.browse(Purpose::SaveView),
                        EscapeRequest::Export => self.browse(Purpose::ExportEscape),
                    }
                }
                if !self.escape.status.is_empty() {
                    self.status = std::mem::take(&mut self.escape.status);
                }
            }
            Tab::Scene => {
                if let Some(r) = self.scene.ui(ui, self.doc.flame(), &self.escape.doc) {
                    match r {
                        SceneRequest::OpenScene => self.browse(Purpose::OpenScene),
                        SceneRequest::Export => self.browse(Purpose::ExportScene),
                        SceneRequest::TextureImage => self.browse(Purpose::SceneTexture),
                    }
                }
                if !self.scene.status.is_empty() {
                    self.status = std::mem::take(&mut self.scene.status);
                }
            }
        }
        self.dialogs(&ctx);
        if self.animation.is_some() {
            self.animate_step();
            ctx.request_repaint();
        }
        if self.morph.is_some() {
            self.morph_step();
            ctx.request_repaint();
        }
    }
}

/// Flame-wide settings: name, size, camera, tone mapping.
fn flame_settings(ui: &mut egui::Ui, doc: &mut Document) {
    let mut f = doc.flame().clone();
    let before = f.clone();
    egui::CollapsingHeader::new("Flame")
        .default_open(false)
        .show(ui, |ui| {
            egui::Grid::new("flame-grid").num_columns(2).show(ui, |ui| {
                ui.label("Name");
                ui.text_edit_singleline(&mut f.name);
                ui.end_row();
                ui.label("Size");
                ui.horizontal(|ui| {
                    ui.add(egui::DragValue::new(&mut f.width).range(1..=20000));
                    ui.label("×");
                    ui.add(egui::DragValue::new(&mut f.height).range(1..=20000));
                });
                ui.end_row();
                let row = |ui: &mut egui::Ui,
                           l: &str,
                           v: &mut f64,
                           speed: f64,
                           r: std::ops::RangeInclusive<f64>| {
                    ui.label(l);
                    ui.add(
                        egui::DragValue::new(v)
                            .speed(speed)
                            .range(r)
                            .max_decimals(5),
                    );
                    ui.end_row();
                };
                row(ui, "Centre x", &mut f.center[0], 0.01, -1e6..=1e6);
                row(ui, "Centre y", &mut f.center[1], 0.01, -1e6..=1e6);
                row(ui, "Scale", &mut f.scale, 0.5, 0.001..=1e7);
                row(ui, "Zoom", &mut f.zoom, 0.01, -20.0..=20.0);
                row(ui, "Rotate (°)", &mut f.rotate, 0.5, -3600.0..=3600.0);
                row(ui, "Quality", &mut f.quality, 1.0, 0.01..=1e6);
                row(ui, "Brightness", &mut f.brightness, 0.05, 0.01..=1000.0);
                row(ui, "Gamma", &mut f.gamma, 0.05, 0.01..=100.0);
                row(
                    ui,
                    "Gamma threshold",
                    &mut f.gamma_threshold,
                    0.001,
                    0.0..=10.0,
                );
                row(ui, "Vibrancy", &mut f.vibrancy, 0.01, 0.0..=10.0);
                row(
                    ui,
                    "Highlight power",
                    &mut f.highlight_power,
                    0.05,
                    -1.0..=100.0,
                );
                row(ui, "Contrast", &mut f.contrast, 0.01, 0.01..=100.0);
                row(ui, "DE radius", &mut f.estimator_radius, 0.1, 0.0..=50.0);
                ui.label("Background");
                let mut bg = [
                    f.background[0] as f32,
                    f.background[1] as f32,
                    f.background[2] as f32,
                ];
                if ui.color_edit_button_rgb(&mut bg).changed() {
                    f.background = bg.map(|v| v as f64);
                }
                ui.end_row();
            });
        });
    if f.estimator_radius < f.estimator_minimum {
        f.estimator_minimum = f.estimator_radius;
    }
    if f != before {
        doc.edit(|g| *g = f);
    }
}

/// Load flames from any supported file, with the Options' defaults for IFS files.
/// The last random batch from the data directory (absent or unreadable: none).
fn load_last_batch(dir: &Path) -> Option<Document> {
    let path = dir.join("last-batch.fla");
    let flames = io::read_flames(&path, &Default::default()).ok()?.value;
    if flames.is_empty() {
        return None;
    }
    let mut d = Document::new(flames, Some(path));
    d.name = "last batch".into();
    Some(d)
}

fn load_any(path: &Path, options: &Options) -> Result<(Vec<Flame>, Vec<String>), String> {
    let p = match io::kind_of(path) {
        io::FileKind::Ifs => io::ifs_flames_with(path, &options.new_flame()),
        _ => io::read_flames(path, &Default::default()),
    }
    .map_err(|e| e.to_string())?;
    if p.value.is_empty() {
        return Err(format!("{}: no flames", path.display()));
    }
    let mut flames = p.value;
    for f in &mut flames {
        keep_foreign_weights(f);
    }
    Ok((flames, p.warnings.iter().map(|w| w.to_string()).collect()))
}

/// A flame from another program keeps its own weights: triangle edits re-derive weights from
/// the areas only when the file asks for it or the weights already follow the areas.
fn keep_foreign_weights(f: &mut Flame) {
    if f.auto_weights.is_none() {
        let maps: Vec<Affine> = f.xforms.iter().map(|x| x.coefs).collect();
        let rule = Flame::determinant_weights(&maps);
        let total: f64 = f.xforms.iter().map(|x| x.weight).sum();
        let follows = total > 0.0
            && f.xforms
                .iter()
                .zip(&rule)
                .all(|(x, w)| (x.weight / total - w).abs() < 1e-6);
        if !follows {
            f.auto_weights = Some(false);
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

impl UgnisApp {
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
