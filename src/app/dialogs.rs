//! File choosers: a built-in file browser (always works, also without a desktop portal) with a
//! button for the system dialog (rfd, xdg-portal), plus small message and confirm dialogs.

use std::path::{Path, PathBuf};

use eframe::egui;

use super::worker::{Repaint, TaskWorker, task_worker};

/// What a file chooser is for; decides the title, filters and whether the file must exist.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    Open,
    SaveAs,
    LoadGradient,
    GradientFromImage,
    Export,
    OpenView,
    SaveView,
    ExportEscape,
    OpenScene,
    SaveScene,
    ExportScene,
    SceneTexture,
    OpenLSystem,
    ExportLSystem,
    BoxCountImage,
    ResumeState,
    /// The video file of an animation export.
    ExportAnimation,
    /// A sound whose loudness moves a parameter.
    SoundFile,
}

impl Purpose {
    pub fn title(self) -> &'static str {
        match self {
            Purpose::Open => "Open",
            Purpose::SaveAs => "Save As",
            Purpose::LoadGradient => "Load gradient",
            Purpose::GradientFromImage => "Create gradient from image",
            Purpose::Export => "Export image",
            Purpose::OpenView => "Open escape-time view",
            Purpose::SaveView => "Save escape-time view",
            Purpose::ExportEscape => "Export escape-time image",
            Purpose::OpenScene => "Open scene",
            Purpose::SaveScene => "Save scene",
            Purpose::ExportScene => "Export scene image",
            Purpose::SceneTexture => "Texture image",
            Purpose::OpenLSystem => "Open L-system file",
            Purpose::ExportLSystem => "Export L-system picture",
            Purpose::BoxCountImage => "Image to box-count",
            Purpose::ResumeState => "Resume render state",
            Purpose::ExportAnimation => "Export animation",
            Purpose::SoundFile => "Sound for the motion",
        }
    }

    pub fn extensions(self) -> &'static [&'static str] {
        match self {
            Purpose::Open => &["fla", "flame", "flam3", "xml", "ifs", "png"],
            Purpose::SaveAs => &["fla", "flame", "flam3", "ifs"],
            Purpose::LoadGradient => &["ugr", "map", "ggr", "gradient"],
            Purpose::GradientFromImage => &["png", "jpg", "jpeg", "bmp", "gif"],
            Purpose::Export | Purpose::ExportEscape | Purpose::ExportScene => &["png", "bmp"],
            Purpose::OpenScene | Purpose::SaveScene => &["toml"],
            Purpose::SceneTexture => &["png", "jpg", "jpeg", "bmp", "gif"],
            Purpose::OpenView | Purpose::SaveView => &["esc"],
            Purpose::OpenLSystem => &["l"],
            Purpose::ExportLSystem => &["svg", "png"],
            Purpose::BoxCountImage => &["png", "jpg", "jpeg", "bmp", "gif"],
            Purpose::ResumeState => &["ugnis-state"],
            Purpose::ExportAnimation => &["mp4", "webm", "mkv", "mov", "gif", "apng"],
            Purpose::SoundFile => &["wav", "flac", "mp3"],
        }
    }

    pub fn saving(self) -> bool {
        matches!(
            self,
            Purpose::SaveAs
                | Purpose::Export
                | Purpose::SaveView
                | Purpose::SaveScene
                | Purpose::ExportEscape
                | Purpose::ExportScene
                | Purpose::ExportLSystem
                | Purpose::ExportAnimation
        )
    }
}

/// `dir` as an absolute path without `.` and `..` (as it is when it cannot be resolved).
fn absolute_dir(dir: &Path) -> PathBuf {
    std::fs::canonicalize(dir)
        .or_else(|_| std::path::absolute(dir))
        .unwrap_or_else(|_| dir.to_path_buf())
}

/// The built-in file browser.
pub struct FileBrowser {
    pub purpose: Purpose,
    pub dir: PathBuf,
    pub name: String,
    /// The Folder field's text: the folder shown, or what is being typed.
    pub folder: String,
    entries: Vec<(String, bool)>,
    error: Option<String>,
    /// The platform's dialog, run in the background while this one waits.
    system: Option<TaskWorker<Option<PathBuf>>>,
    repaint: Repaint,
}

impl FileBrowser {
    pub fn new(
        purpose: Purpose,
        start: Option<&Path>,
        name: &str,
        repaint: Repaint,
    ) -> FileBrowser {
        let dir = start
            .map(|p| {
                if p.is_dir() {
                    p.to_path_buf()
                } else {
                    p.parent().map(Path::to_path_buf).unwrap_or_default()
                }
            })
            .filter(|d| d.is_dir())
            .or_else(|| std::env::current_dir().ok())
            .unwrap_or_else(|| PathBuf::from("."));
        // A relative folder (from a relative file name on the command line) has no parent to
        // go up to: work with the absolute one.
        let dir = absolute_dir(&dir);
        let mut b = FileBrowser {
            purpose,
            folder: dir.display().to_string(),
            dir,
            name: name.to_string(),
            entries: Vec::new(),
            error: None,
            system: None,
            repaint,
        };
        b.refresh();
        b
    }

    fn refresh(&mut self) {
        self.folder = self.dir.display().to_string();
        self.entries.clear();
        match std::fs::read_dir(&self.dir) {
            Ok(rd) => {
                for e in rd.flatten() {
                    let name = e.file_name().to_string_lossy().into_owned();
                    if name.starts_with('.') {
                        continue;
                    }
                    let is_dir = e.path().is_dir();
                    let ext_ok = Path::new(&name)
                        .extension()
                        .map(|x| x.to_string_lossy().to_ascii_lowercase())
                        .is_some_and(|x| self.purpose.extensions().contains(&x.as_str()));
                    if is_dir || ext_ok {
                        self.entries.push((name, is_dir));
                    }
                }
                self.entries.sort_by(|a, b| {
                    b.1.cmp(&a.1)
                        .then(a.0.to_lowercase().cmp(&b.0.to_lowercase()))
                });
                self.error = None;
            }
            Err(e) => self.error = Some(format!("{}: {e}", self.dir.display())),
        }
    }

    /// Go to the folder typed in the Folder field (relative to the folder shown; `~` is the
    /// home folder); a name that is no folder is told and the field keeps it for correcting.
    pub fn go_to_typed_folder(&mut self) {
        let typed = self.folder.trim().to_string();
        let expanded = match (typed.strip_prefix('~'), std::env::var_os("HOME")) {
            (Some(rest), Some(home)) if rest.is_empty() || rest.starts_with('/') => {
                PathBuf::from(home).join(rest.trim_start_matches('/'))
            }
            _ => PathBuf::from(&typed),
        };
        let p = self.dir.join(expanded);
        if p.is_dir() {
            self.dir = absolute_dir(&p);
            self.refresh();
        } else {
            self.error = Some(format!("{}: not a folder", p.display()));
        }
    }

    /// Show the browser. Returns Some(Some(path)) when chosen, Some(None) when cancelled.
    pub fn show(&mut self, ctx: &egui::Context) -> Option<Option<PathBuf>> {
        // A pending system dialog answers first.
        if let Some(w) = &self.system
            && let Some(r) = w.poll().pop()
        {
            self.system = None;
            match r {
                Some(p) => return Some(Some(p)),
                None => {
                    self.error =
                        Some("the system dialog was closed or is not available; choose here".into())
                }
            }
        }
        let mut result = None;
        egui::Modal::new(egui::Id::unique("file-browser")).show(ctx, |ui| {
            ui.set_width(520.0);
            ui.heading(self.purpose.title());
            ui.horizontal(|ui| {
                if ui.button("Up").on_hover_text("the parent folder").clicked()
                    && let Some(p) = self.dir.parent()
                {
                    self.dir = p.to_path_buf();
                    self.refresh();
                }
                if ui
                    .button("Home")
                    .on_hover_text("your home folder")
                    .clicked()
                    && let Some(h) = std::env::var_os("HOME")
                {
                    self.dir = absolute_dir(Path::new(&h));
                    self.refresh();
                }
                let l = ui.label("Folder");
                let r = ui
                    .add(egui::TextEdit::singleline(&mut self.folder).desired_width(f32::INFINITY))
                    .labelled_by(l.id)
                    .on_hover_text("type a folder and press Enter");
                // The text stays as typed until Enter goes there (or a folder is chosen).
                if r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                    self.go_to_typed_folder();
                }
            });
            egui::ScrollArea::vertical()
                .max_height(280.0)
                .show(ui, |ui| {
                    let entries = self.entries.clone();
                    for (name, is_dir) in entries {
                        let label = if is_dir {
                            format!("{name}/")
                        } else {
                            name.clone()
                        };
                        let r = ui.selectable_label(self.name == name, label);
                        if r.clicked() {
                            if is_dir {
                                self.dir = self.dir.join(&name);
                                self.refresh();
                            } else {
                                self.name = name.clone();
                            }
                        }
                        if r.double_clicked() && !is_dir {
                            result = Some(Some(self.dir.join(&name)));
                        }
                    }
                });
            ui.horizontal(|ui| {
                let l = ui.label("File name");
                let r = ui.text_edit_singleline(&mut self.name).labelled_by(l.id);
                if r.lost_focus()
                    && ui.input(|i| i.key_pressed(egui::Key::Enter))
                    && !self.name.is_empty()
                {
                    result = Some(Some(self.dir.join(&self.name)));
                }
            });
            ui.label(format!("Types: {}", self.purpose.extensions().join(", ")));
            if let Some(e) = &self.error {
                ui.colored_label(egui::Color32::from_rgb(230, 150, 80), e);
            }
            ui.horizontal(|ui| {
                let ok = if self.purpose.saving() {
                    "Save"
                } else {
                    "Open"
                };
                if ui
                    .add_enabled(!self.name.trim().is_empty(), egui::Button::new(ok))
                    .clicked()
                {
                    let p = PathBuf::from(self.name.trim());
                    result = Some(Some(if p.is_absolute() { p } else { self.dir.join(p) }));
                }
                if ui.button("Cancel").clicked() {
                    result = Some(None);
                }
                if ui
                    .add_enabled(self.system.is_none(), egui::Button::new("System dialog…"))
                    .clicked()
                {
                    let r = self.repaint.clone();
                    let w = task_worker("ugnis-file-dialog", move || r());
                    w.submit(system_dialog(self.purpose, &self.dir, &self.name));
                    self.system = Some(w);
                }
            });
        });
        if ctx.input(|i| i.key_pressed(egui::Key::Escape)) {
            result = Some(None);
        }
        if let Some(Some(p)) = &result
            && !self.purpose.saving()
            && !p.is_file()
        {
            self.error = Some(format!("{} does not exist", p.display()));
            return None;
        }
        result
    }
}

impl Drop for FileBrowser {
    fn drop(&mut self) {
        // The platform's dialog cannot be closed from here: let it finish on its own.
        if let Some(w) = self.system.take() {
            w.detach();
        }
    }
}

/// The platform's file dialog, as a background task.
fn system_dialog(
    purpose: Purpose,
    dir: &Path,
    name: &str,
) -> crate::app::worker::Task<Option<PathBuf>> {
    let dir = dir.to_path_buf();
    let name = name.to_string();
    Box::new(move |_, _| {
        let d = rfd::FileDialog::new()
            .set_title(purpose.title())
            .set_directory(&dir)
            .add_filter(purpose.title(), purpose.extensions());
        if purpose.saving() {
            d.set_file_name(&name).save_file()
        } else {
            d.pick_file()
        }
    })
}

/// The choices of a confirm dialog.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Confirm {
    Save,
    Discard,
    Cancel,
}

/// "Save changes?" — shown before anything would discard unsaved work.
pub fn confirm_discard(ctx: &egui::Context, what: &str) -> Option<Confirm> {
    let mut r = None;
    egui::Modal::new(egui::Id::unique("confirm-discard")).show(ctx, |ui| {
        ui.heading("Unsaved changes");
        ui.label(format!(
            "The flames have unsaved changes. Save them before {what}?"
        ));
        if ui.input(|i| i.key_pressed(egui::Key::Escape)) {
            r = Some(Confirm::Cancel);
        }
        ui.horizontal(|ui| {
            if ui.button("Save").clicked() {
                r = Some(Confirm::Save);
            }
            if ui.button("Discard").clicked() {
                r = Some(Confirm::Discard);
            }
            if ui.button("Cancel").clicked() {
                r = Some(Confirm::Cancel);
            }
        });
    });
    r
}

/// A message box; returns true when dismissed.
pub fn message(ctx: &egui::Context, title: &str, text: &str) -> bool {
    let mut done = false;
    egui::Modal::new(egui::Id::unique("message-box")).show(ctx, |ui| {
        ui.set_max_width(520.0);
        ui.heading(title);
        ui.label(text);
        if ui.button("OK").clicked() || ui.input(|i| i.key_pressed(egui::Key::Escape)) {
            done = true;
        }
    });
    done
}
