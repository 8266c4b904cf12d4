//! Opening and saving: the file chooser for every purpose, what happens with the chosen file,
//! and the "save changes?" question before anything would discard unsaved work.

use std::path::{Path, PathBuf};

use super::dialogs::{FileBrowser, Purpose};
use super::explore_tab::ExploreRequest;
use super::options::Options;
use super::shell::{Tab, UgnisApp};
use crate::flame::{Affine, Flame};
use crate::io;

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

impl UgnisApp {
    /// Do `p` now, or after asking about unsaved changes of the open file.
    pub(super) fn guard_dirty(&mut self, p: Pending, what: &str) {
        if self.flame.file.dirty {
            self.pending = Some(p);
            self.confirm_what = what.to_string();
        } else {
            self.run_pending(p);
        }
    }

    pub(super) fn run_pending(&mut self, p: Pending) {
        match p {
            Pending::Exit => self.allow_close = true,
            Pending::New => {
                let f = crate::app::flame_tab::commands::new_flame(&self.options);
                self.flame.replace_file(vec![f], None, "untitled".into());
                self.flame.notices.status("New flame");
            }
            Pending::Open(path) => self.open_path(&path),
            Pending::BrowseOpen => self.browse(Purpose::Open),
            Pending::Flames(flames, name) => {
                self.flame.replace_file(flames, None, name.clone());
                self.flame
                    .notices
                    .status(format!("Opened '{name}' from Explore"));
                self.tab = Tab::Flame;
            }
        }
    }

    /// Carry out what the Explore tab asked for.
    pub(super) fn explore_request(&mut self, r: ExploreRequest) {
        match r {
            ExploreRequest::OpenInFlameTab(ifs) => {
                let f = ifs.to_flame(&self.options.new_flame());
                let name = f.name.clone();
                self.guard_dirty(
                    Pending::Flames(vec![f], name),
                    "opening the IFS in the flame tab",
                );
            }
            ExploreRequest::MengerScene(step) => {
                let text = format!(
                    "[[object]]\nkind = \"menger\"\nname = \"menger\"\nstep = {step}\nsize = 2\n"
                );
                let parsed = io::scene::parse(&text, "menger scene", Path::new("."));
                match (parsed, text.parse::<toml::Table>()) {
                    (Ok(l), Ok(t)) => {
                        self.scene.load(l.scene, l.texture_names, None, t);
                        self.scene
                            .notices
                            .status(format!("Menger sponge, step {step}"));
                        self.tab = Tab::Scene;
                    }
                    (Err(e), _) => self.explore.notices.message("Menger sponge", e.to_string()),
                    (_, Err(e)) => self.explore.notices.message("Menger sponge", e.to_string()),
                }
            }
            ExploreRequest::OpenLFile => self.browse(Purpose::OpenLSystem),
            ExploreRequest::ExportLSystem => self.browse(Purpose::ExportLSystem),
            ExploreRequest::BoxCountImage => self.browse(Purpose::BoxCountImage),
        }
    }

    /// Show the file chooser for `purpose`, starting where its document lives.
    pub(super) fn browse(&mut self, purpose: Purpose) {
        let name_of = |p: &Option<PathBuf>, default: String| {
            p.as_ref()
                .and_then(|p| p.file_name())
                .map_or(default, |n| n.to_string_lossy().into_owned())
        };
        let family = self.escape.doc.params.family.name();
        let name = match purpose {
            Purpose::SaveAs => name_of(
                &self.flame.file.path,
                format!("{}.fla", self.flame.file.name),
            ),
            Purpose::SaveView => name_of(&self.escape.path, format!("{family}.esc")),
            Purpose::SaveScene => name_of(&self.scene.path, "scene.toml".into()),
            Purpose::ExportEscape => format!("{family}.png"),
            Purpose::ExportScene => "scene.png".into(),
            Purpose::ExportLSystem => format!(
                "{}.svg",
                io::lsystem::entry_name(
                    self.explore
                        .lsystem
                        .system()
                        .map_or("lsystem", |s| s.name.as_str())
                )
            ),
            Purpose::Export => self
                .flame
                .export_dialog
                .as_ref()
                .and_then(|s| s.path.file_name())
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default(),
            _ => String::new(),
        };
        let start = match purpose {
            Purpose::OpenView | Purpose::SaveView | Purpose::ExportEscape => {
                self.escape.path.clone()
            }
            Purpose::OpenScene
            | Purpose::SaveScene
            | Purpose::ExportScene
            | Purpose::SceneTexture => self.scene.path.clone(),
            Purpose::Export => self.flame.export_dialog.as_ref().map(|s| s.path.clone()),
            Purpose::OpenLSystem | Purpose::ExportLSystem => self.explore.lsystem.file.clone(),
            Purpose::BoxCountImage => None,
            Purpose::ResumeState => self.flame.last_export_dir.clone(),
            _ => self.flame.file.path.clone(),
        };
        self.browser = Some(FileBrowser::new(
            purpose,
            start.as_deref(),
            &name,
            self.repaint(),
        ));
    }

    /// Open a flame, IFS or view file, replacing the document (the caller asked about
    /// unsaved changes).
    pub fn open_path(&mut self, path: &Path) {
        if io::kind_of(path) == io::FileKind::EscapeView {
            self.file_chosen(Purpose::OpenView, path.to_path_buf());
            self.tab = Tab::Escape;
            return;
        }
        match load_any(path, &self.options) {
            Ok(Loaded {
                flames,
                warnings,
                notes,
            }) => {
                let name = path
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                self.flame
                    .replace_file(flames, Some(path.to_path_buf()), name);
                self.flame
                    .notices
                    .status(format!("Opened {}", path.display()));
                if let Some(n) = notes.first() {
                    self.flame.notices.status(n.clone());
                }
                if !warnings.is_empty() {
                    self.flame.notices.message("Warnings", warnings.join("\n"));
                }
                self.remember(path);
            }
            Err(e) => self.flame.notices.message("Cannot open", e),
        }
    }

    /// Save the open file (atomically). Returns true on success.
    pub fn save_to(&mut self, path: &Path) -> bool {
        let ok = self.flame.save_to(path);
        if ok {
            self.remember(path);
        }
        ok
    }

    /// The user chose `path` for `purpose`.
    pub(super) fn file_chosen(&mut self, purpose: Purpose, path: PathBuf) {
        let with_ext = |mut p: PathBuf, ext: &str| {
            if p.extension().is_none() {
                p.set_extension(ext);
            }
            p
        };
        match purpose {
            Purpose::Open => self.open_path(&path),
            Purpose::SaveAs => {
                if self.save_to(&with_ext(path, "fla"))
                    && matches!(self.pending, Some(Pending::Exit))
                {
                    self.allow_close = true;
                }
            }
            Purpose::LoadGradient => match io::read_gradients(&path) {
                Ok(p) => {
                    let n = p.value.len();
                    if let Some(first) = p.value.first().cloned() {
                        self.flame.apply_gradient(first);
                    }
                    self.flame.gradients.add(p.value);
                    self.flame.gradients.open = true;
                    self.flame
                        .notices
                        .status(format!("Loaded {n} gradient(s) from {}", path.display()));
                }
                Err(e) => self
                    .flame
                    .notices
                    .message("Cannot load gradient", e.to_string()),
            },
            Purpose::GradientFromImage => match io::image_in::gradient_from_image(&path, 1) {
                Ok(g) => {
                    self.flame.gradients.add(vec![g.clone()]);
                    self.flame.apply_gradient(g);
                    self.flame.gradients.open = true;
                }
                Err(e) => self
                    .flame
                    .notices
                    .message("Cannot read the image", e.to_string()),
            },
            Purpose::Export => {
                if let Some(s) = &mut self.flame.export_dialog {
                    s.path = path;
                }
            }
            Purpose::OpenView => {
                if self.escape.open(&path) {
                    self.remember(&path);
                }
            }
            Purpose::SaveView => {
                let p = with_ext(path, "esc");
                if self.escape.save(&p) {
                    self.remember(&p);
                }
            }
            Purpose::ExportEscape => self.escape.export(with_ext(path, "png")),
            Purpose::OpenScene => {
                if self.scene.open(&path) {
                    self.remember(&path);
                }
            }
            Purpose::SaveScene => {
                let p = with_ext(path, "toml");
                if self.scene.save(&p) {
                    self.remember(&p);
                }
            }
            Purpose::SceneTexture => self.scene.set_image_texture(&path),
            Purpose::ExportScene => self.scene.export(with_ext(path, "png")),
            Purpose::OpenLSystem => {
                let n = self.explore.lsystem.open(&path);
                self.explore.notices.push(n);
            }
            Purpose::ExportLSystem => {
                let n = self.explore.lsystem.export(with_ext(path, "svg"));
                self.explore.notices.push(n);
            }
            Purpose::BoxCountImage => self.explore.dimension.count_image(&path),
            Purpose::ResumeState => {
                self.tab = Tab::Flame;
                self.flame.open_resume_dialog(&path);
            }
        }
    }
}

/// Load flames from any supported file, with the Options' defaults for IFS files.
pub fn load_any(path: &Path, options: &Options) -> Result<Loaded, String> {
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
    // Attributes of other programs are kept and written back: worth a status line, not a
    // message box that must be dismissed before anything else.
    let (notes, warnings): (Vec<_>, Vec<_>) = p
        .warnings
        .iter()
        .partition(|w| INFORMATIONAL.contains(&w.code));
    Ok(Loaded {
        flames,
        warnings: warnings.iter().map(|w| w.to_string()).collect(),
        notes: notes.iter().map(|w| w.to_string()).collect(),
    })
}

/// Reader diagnostics that lose nothing (kept and written back unchanged).
const INFORMATIONAL: &[&str] = &["XML021"];

/// The flames of a file with what reading them had to say.
pub struct Loaded {
    pub flames: Vec<Flame>,
    /// Shown in a message box.
    pub warnings: Vec<String>,
    /// Shown in the status line.
    pub notes: Vec<String>,
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
