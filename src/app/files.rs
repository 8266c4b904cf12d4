//! Opening and saving: the file chooser for every purpose, what happens with the chosen file,
//! the view a file opens in (by [`io::view_of`], for Open, Recent files, dropped files and
//! the file given at start), and the "save changes?" question before anything would discard
//! unsaved work.

use std::path::{Path, PathBuf};

use super::dialogs::{FileBrowser, Purpose};
use super::explore_tab::{ExploreRequest, Topic};
use super::loading::{Loaded, load_any};
use super::notice::Notice;
use super::shell::{Pending, Tab, UgnisApp};
use crate::io::{self, View};

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
            Purpose::ExportAnimation => self
                .flame
                .anim_export
                .as_ref()
                .and_then(|d| d.settings.output.file_stem())
                .map(|n| format!("{}.mp4", n.to_string_lossy()))
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
            Purpose::ExportAnimation => self
                .flame
                .anim_export
                .as_ref()
                .map(|d| d.settings.output.clone()),
            Purpose::OpenLSystem | Purpose::ExportLSystem => self.explore.lsystem.file.clone(),
            Purpose::BoxCountImage => None,
            Purpose::SoundFile => self
                .flame
                .timeline
                .sound_dialog
                .as_ref()
                .and_then(|d| d.path.clone()),
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

    /// Open `path` in the view that opens its kind ([`io::view_of`]), as Recent files and
    /// dropped files do. Flames replace the open flames after the question about unsaved
    /// changes (`what` says what would discard them).
    pub fn open_file(&mut self, path: &Path, what: &str) {
        match io::view_of(io::kind_of(path)) {
            View::Flame => {
                self.tab = Tab::Flame;
                self.guard_dirty(Pending::Open(path.to_path_buf()), what);
            }
            view => self.open_in(view, path),
        }
    }

    /// Open `path` in the view that opens its kind now (for flames the caller asked about
    /// unsaved changes), as File › Open does.
    pub fn open_path(&mut self, path: &Path) {
        self.open_in(io::view_of(io::kind_of(path)), path);
    }

    /// Open `path` in `view` now, showing the view; a document that opens is remembered in
    /// the recent files.
    pub(super) fn open_in(&mut self, view: View, path: &Path) {
        let document = matches!(
            view,
            View::Flame | View::Escape | View::Scene | View::LSystem
        );
        if self.load_into(view, path) && document {
            self.remember(path);
        }
    }

    /// Open `path` in `view` and show it; true when it opened. Failures are told in the
    /// view's message box.
    pub(super) fn load_into(&mut self, view: View, path: &Path) -> bool {
        match view {
            View::Flame => {
                self.tab = Tab::Flame;
                self.open_flames(path)
            }
            View::Escape => {
                self.tab = Tab::Escape;
                self.escape.open(path)
            }
            View::Scene => {
                self.tab = Tab::Scene;
                self.scene.open(path)
            }
            View::LSystem => {
                self.tab = Tab::Explore;
                self.explore.topic = Topic::LSystems;
                let n = self.explore.lsystem.open(path);
                let opened = matches!(n, Notice::Status(_));
                self.explore.notices.push(n);
                opened
            }
            View::Gradients => self.load_gradients(path),
            View::GradientFromImage => self.gradient_from_image(path),
            View::RenderState => {
                self.tab = Tab::Flame;
                self.flame.open_resume_dialog(path);
                true
            }
        }
    }

    /// Replace the open flames by the flames of `path`; true when it opened.
    fn open_flames(&mut self, path: &Path) -> bool {
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
                true
            }
            Err(e) => {
                self.flame.notices.message("Cannot open", e);
                false
            }
        }
    }

    /// Add the gradients of a gradient file to the gradient list and apply the first.
    fn load_gradients(&mut self, path: &Path) -> bool {
        match io::read_gradients(path) {
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
                true
            }
            Err(e) => {
                self.flame
                    .notices
                    .message("Cannot load gradient", e.to_string());
                false
            }
        }
    }

    /// Make a gradient of an image's colours, add it to the gradient list and apply it.
    fn gradient_from_image(&mut self, path: &Path) -> bool {
        match io::image_in::gradient_from_image(path, 1) {
            Ok(g) => {
                self.flame.gradients.add(vec![g.clone()]);
                self.flame.apply_gradient(g);
                self.flame.gradients.open = true;
                true
            }
            Err(e) => {
                self.flame
                    .notices
                    .message("Cannot read the image", e.to_string());
                false
            }
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
            Purpose::LoadGradient => {
                self.load_gradients(&path);
            }
            Purpose::GradientFromImage => {
                self.gradient_from_image(&path);
            }
            Purpose::Export => {
                if let Some(s) = &mut self.flame.export_dialog {
                    s.path = path;
                }
            }
            Purpose::ExportAnimation => {
                if let Some(d) = &mut self.flame.anim_export {
                    d.settings.output = path;
                }
            }
            Purpose::SoundFile => {
                if let Some(d) = &mut self.flame.timeline.sound_dialog {
                    d.path = Some(path);
                }
            }
            Purpose::OpenView => self.open_in(View::Escape, &path),
            Purpose::SaveView => {
                let p = with_ext(path, "esc");
                if self.escape.save(&p) {
                    self.remember(&p);
                }
            }
            Purpose::ExportEscape => self.escape.export(with_ext(path, "png")),
            Purpose::OpenScene => self.open_in(View::Scene, &path),
            Purpose::SaveScene => {
                let p = with_ext(path, "toml");
                if self.scene.save(&p) {
                    self.remember(&p);
                }
            }
            Purpose::SceneTexture => self.scene.set_image_texture(&path),
            Purpose::ExportScene => self.scene.export(with_ext(path, "png")),
            Purpose::OpenLSystem => self.open_in(View::LSystem, &path),
            Purpose::ExportLSystem => {
                let n = self.explore.lsystem.export(with_ext(path, "svg"));
                self.explore.notices.push(n);
            }
            Purpose::BoxCountImage => self.explore.dimension.count_image(&path),
            Purpose::ResumeState => self.open_in(View::RenderState, &path),
        }
    }
}
