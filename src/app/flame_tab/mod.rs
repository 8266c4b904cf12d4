//! The flame tab: the open file and the last random batch, the live preview, the triangle
//! editor with its numeric panels, and the flame's windows (gradient, mutations, export).
//!
//! | file | what |
//! |---|---|
//! | `document.rs` | the flames of a file or batch and the undo history |
//! | `file_panel.rs` | the left panel: the file's flames and the batch, with thumbnails |
//! | `preview_panel.rs` / `preview.rs` | the central picture and its background renderer |
//! | `triangles.rs` | the triangle editor canvas and its toolbar |
//! | `xform_panel.rs` | numbers of the selected transform |
//! | `settings.rs` | flame-wide settings (size, camera, tone) |
//! | `animation.rs` | rotating triangles and morphs between flames |
//! | `gradients.rs`, `mutations.rs`, `export.rs` | the tab's windows |

pub mod animation;
pub mod document;
pub mod export;
pub mod file_panel;
pub mod gradients;
pub mod mutations;
pub mod preview;
pub mod preview_panel;
pub mod settings;
pub mod thumbnails;
pub mod triangles;
pub mod xform_panel;

use std::path::{Path, PathBuf};

use eframe::egui::{self, Vec2};

use crate::app::notice::Notices;
use crate::app::options::Options;
use crate::app::worker::{Repaint, TaskWorker, repaint_of, task_worker};
use crate::flame::random::{self, VariationMode};
use crate::flame::rng::FastRng;
use crate::flame::variations::VarId;
use crate::flame::{Flame, NewFlame};
use crate::gradient::Gradient;
use crate::io;
use animation::{Animation, Morph};
use document::Document;
use export::{ExportJob, ExportSettings};
use gradients::{GradientAction, GradientWindow};
use mutations::MutationWindow;
use preview_panel::Preview;
use thumbnails::Thumbnails;
use triangles::{EditorAction, EditorState, Selected};

pub use animation::MORPH_FRAMES;

/// Which document the editor shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Showing {
    File,
    Batch,
}

/// What the flame tab asks the shell for (file choosers live in the shell).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FlameRequest {
    LoadGradient,
    GradientFromImage,
    ChooseExportFile,
}

/// State of the flame tab.
pub struct FlameTab {
    /// The open file.
    pub file: Document,
    /// The last random batch, if any.
    pub batch: Option<Document>,
    pub showing: Showing,
    pub editor: EditorState,
    pub show_files: bool,
    pub show_editor: bool,
    /// Preview zoom (1 = fit).
    pub preview_zoom: f32,
    pub variation_mode: VariationMode,
    pub notices: Notices,
    pub gradients: GradientWindow,
    pub mutations: MutationWindow,
    pub export_dialog: Option<ExportSettings>,
    pub export_job: Option<ExportJob>,
    pub animation: Option<Animation>,
    pub morph: Option<Morph>,
    /// Where the last random batch is kept (the platform data directory; none in tests
    /// unless they set one).
    pub data_dir: Option<PathBuf>,
    preview: Option<Preview>,
    thumbs: Thumbnails,
    batch_job: Option<TaskWorker<Vec<Flame>>>,
    rng: FastRng,
    last_export_dir: Option<PathBuf>,
    /// Wakes the UI when a background job finishes.
    repaint: Repaint,
}

impl FlameTab {
    /// A tab editing `flames`. With `ctx` the background renderers start.
    pub fn new(
        flames: Vec<Flame>,
        path: Option<PathBuf>,
        ctx: Option<&egui::Context>,
        seed: u64,
    ) -> FlameTab {
        let mut file = Document::new(flames, path.clone());
        if path.is_none() {
            file.name = "untitled".into();
        }
        let data_dir = ctx.and_then(|_| crate::app::options::data_dir());
        let mut editor = EditorState::default();
        editor.canvas = egui::Rect::from_min_size(egui::Pos2::ZERO, Vec2::new(420.0, 360.0));
        editor.auto_zoom(file.flame());
        FlameTab {
            file,
            batch: data_dir.as_deref().and_then(load_last_batch),
            showing: Showing::File,
            editor,
            show_files: true,
            show_editor: true,
            preview_zoom: 1.0,
            variation_mode: VariationMode::default(),
            notices: Notices::default(),
            gradients: GradientWindow::default(),
            mutations: MutationWindow::default(),
            export_dialog: None,
            export_job: None,
            animation: None,
            morph: None,
            data_dir,
            preview: ctx.map(Preview::new),
            thumbs: Thumbnails::new(ctx, 96, 72, 8.0),
            batch_job: None,
            rng: FastRng::new(seed),
            last_export_dir: None,
            repaint: repaint_of(ctx),
        }
    }

    fn repaint(&self) -> impl Fn() + Send + 'static {
        let r = self.repaint.clone();
        move || r()
    }

    /// The document the editor shows (the file or the batch).
    pub fn doc(&self) -> &Document {
        match (self.showing, &self.batch) {
            (Showing::Batch, Some(b)) => b,
            _ => &self.file,
        }
    }

    pub fn doc_mut(&mut self) -> &mut Document {
        pick(self.showing, &mut self.batch, &mut self.file)
    }

    /// True while the editor shows a flame of the random batch.
    pub fn viewing_batch(&self) -> bool {
        self.showing == Showing::Batch && self.batch.is_some()
    }

    fn edit_started(&mut self) {
        self.editor.selected = Selected::Xform(0);
        let f = self.doc().flame().clone();
        self.editor.auto_zoom(&f);
    }

    /// Edit the open file again (after browsing the batch).
    pub fn view_file(&mut self) {
        if self.viewing_batch() {
            self.showing = Showing::File;
            self.edit_started();
        }
    }

    /// Show flame `i` of the random batch in the editor.
    pub fn view_batch(&mut self, i: usize) {
        if let Some(b) = &mut self.batch {
            b.current = i.min(b.flames.len() - 1);
            self.showing = Showing::Batch;
            self.edit_started();
        }
    }

    /// Replace the random batch.
    pub fn set_batch(&mut self, flames: Vec<Flame>, path: Option<PathBuf>) {
        let mut d = Document::new(flames, path);
        d.name = "last batch".into();
        self.batch = Some(d);
        self.thumbs.truncate(1, 0);
        if self.showing == Showing::Batch {
            self.edit_started();
        }
    }

    /// Copy flame `i` of the batch (as edited) into the open file, as one undo step there,
    /// and edit it.
    pub fn keep_from_batch(&mut self, i: usize) {
        let Some(f) = self.batch.as_ref().and_then(|b| b.flames.get(i)).cloned() else {
            return;
        };
        self.showing = Showing::File;
        let name = f.name.clone();
        self.file.edit_document(|fl, cur| {
            fl.push(f);
            *cur = fl.len() - 1;
        });
        self.edit_started();
        let n = self.file.name.clone();
        self.notices.status(format!("'{name}' kept in {n}"));
    }

    /// Replace the open file by new flames.
    pub fn replace_file(&mut self, flames: Vec<Flame>, path: Option<PathBuf>, name: String) {
        let mut d = Document::new(flames, path);
        d.name = name;
        self.file = d;
        self.showing = Showing::File;
        self.thumbs.truncate(0, 0);
        self.edit_started();
    }

    /// Whether triangle edits re-derive the weights from the triangle areas.
    pub fn auto_weights(&self, options: &Options) -> bool {
        self.doc()
            .flame()
            .auto_weights
            .unwrap_or(options.auto_weights)
    }

    /// Settings of new random flames: the Options defaults, with the current gradient (used
    /// when "random gradient" is off).
    fn random_defaults(&self, options: &Options) -> NewFlame {
        let mut d = options.new_flame();
        d.gradient = self.doc().flame().palette.clone();
        d
    }

    pub fn set_variation(&mut self, options: &Options, v: Option<VarId>, label: &str) {
        match v {
            None => self.variation_mode = VariationMode::Random(options.probabilities),
            Some(id) => {
                self.variation_mode = VariationMode::Single(id);
                self.doc_mut().edit(|f| {
                    for x in &mut f.xforms {
                        x.vars = vec![crate::flame::Var::new(id, 1.0)];
                    }
                });
            }
        }
        self.notices.status(format!("Variation: {label}"));
    }

    pub fn random_flame(&mut self, options: &Options) {
        let seed = self.rng.u64();
        let opts = options.random_options(self.variation_mode.clone());
        let mut g = random::generate(seed, &opts, &self.random_defaults(options)).flame;
        g.name = format!("random-{:08x}", seed as u32);
        let doc = self.doc_mut();
        let cur = doc.current;
        doc.edit_document(|fl, c| {
            fl[cur] = g;
            *c = cur;
        });
        self.edit_started();
        self.notices.status(format!("Random flame (seed {seed})"));
    }

    pub fn batch_running(&self) -> bool {
        self.batch_job.as_ref().is_some_and(|w| w.is_busy())
    }

    pub fn start_batch(&mut self, options: &Options) {
        if self.batch_running() {
            return;
        }
        let seed = self.rng.u64();
        let opts = options.random_options(self.variation_mode.clone());
        let defaults = self.random_defaults(options);
        let w = task_worker("ugnis-batch", self.repaint());
        w.submit(Box::new(move |_, _| {
            random::generate_batch(100, seed, &opts, &defaults)
        }));
        self.batch_job = Some(w);
        self.notices.status("Generating a random batch…");
    }

    pub fn random_weights(&mut self) {
        let mut rng = FastRng::new(self.rng.u64());
        self.doc_mut().edit(|f| {
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

    pub fn equal_weights(&mut self) {
        self.doc_mut().edit(|f| {
            f.set_equal_weights();
            f.auto_weights = Some(false);
        });
    }

    pub fn area_weights(&mut self) {
        self.doc_mut().edit(|f| f.set_determinant_weights());
    }

    pub fn undo(&mut self) {
        if !self.doc_mut().undo() {
            self.notices.status("Nothing to undo");
        }
    }

    pub fn redo(&mut self) {
        if !self.doc_mut().redo() {
            self.notices.status("Nothing to redo");
        }
    }

    /// Open the export dialog for the current flame.
    pub fn open_export_dialog(&mut self, options: &Options) {
        let f = self.doc().flame();
        let dir = self.last_export_dir.clone().or_else(|| {
            self.doc()
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
            quality: f.quality.max(options.main_quality),
            supersample: f.supersample,
            bits16: false,
            transparent: false,
            path: dir.unwrap_or_default().join(format!("{name}.png")),
        });
    }

    /// Save the open file (atomically). Returns true on success.
    pub fn save_to(&mut self, path: &Path) -> bool {
        let d = &self.file;
        match io::write_flames(path, &d.name, &d.flames) {
            Ok(w) => {
                self.file.path = Some(path.to_path_buf());
                self.file.dirty = false;
                self.notices.status(format!("Saved {}", path.display()));
                if !w.is_empty() {
                    self.notices.message("Saved with losses", w.join("\n"));
                }
                true
            }
            Err(e) => {
                self.notices.message("Cannot save", e.to_string());
                false
            }
        }
    }

    pub fn apply_gradient(&mut self, g: Gradient) {
        self.doc_mut().edit(|f| f.palette = g);
    }

    /// Add the flames of pasted XML to the document.
    pub fn paste(&mut self, text: &str) {
        match io::flam3_xml::read(text, &Default::default()) {
            Ok(p) => {
                let new: Vec<Flame> = p.value.flames;
                let n = new.len();
                self.doc_mut().edit_document(|fl, cur| {
                    fl.extend(new);
                    *cur = fl.len() - 1;
                });
                self.notices.status(format!("Pasted {n} flame(s)"));
            }
            Err(e) => self
                .notices
                .status(format!("Clipboard holds no flame: {e}")),
        }
    }

    /// Collect what the background jobs finished.
    fn poll_jobs(&mut self) {
        if let Some(j) = &mut self.export_job {
            match j.poll() {
                Some(Ok(())) => {
                    let p = j.path.display().to_string();
                    self.export_job = None;
                    self.notices.status(format!("Exported {p}"));
                }
                Some(Err(e)) => {
                    self.export_job = None;
                    self.notices.status(e);
                }
                None => {}
            }
        }
        let done = self.batch_job.as_ref().and_then(|w| w.poll().pop());
        if let Some(flames) = done {
            self.batch_job = None;
            let path = self.data_dir.as_ref().map(|d| d.join("last-batch.fla"));
            if let Some(p) = &path {
                let _ = std::fs::create_dir_all(p.parent().unwrap_or(Path::new(".")));
                if let Err(e) = io::write_flames(p, "last-batch", &flames) {
                    self.notices.status(e.to_string());
                }
            }
            self.show_files = true;
            self.set_batch(flames, path);
            self.notices.status("Random batch ready");
        }
    }

    /// The tab's windows: export settings, mutations, gradients. Returns a request for the
    /// shell.
    pub fn windows(&mut self, ctx: &egui::Context, options: &Options) -> Option<FlameRequest> {
        let mut req = None;
        self.poll_jobs();
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
                req = Some(FlameRequest::ChooseExportFile);
            }
            match r {
                Some(true) => {
                    let s = s.clone();
                    self.last_export_dir = s.path.parent().map(Path::to_path_buf);
                    let f = self.doc().flame().clone();
                    self.export_job =
                        Some(ExportJob::start(&f, &s, options.threads, self.repaint()));
                    self.export_dialog = None;
                }
                Some(false) => self.export_dialog = None,
                None => {}
            }
        }
        let opts = options.random_options(self.variation_mode.clone());
        let centre = self.doc().flame().clone();
        if let Some(m) = self
            .mutations
            .show(ctx, &centre, &opts, self.preview.is_some())
        {
            self.doc_mut().edit(|f| *f = m);
            let f = self.doc().flame().clone();
            self.editor.fix_selection(&f);
            self.editor.auto_zoom(&f);
            self.notices.status("Mutant chosen (Undo returns)");
        }
        let current = self.doc().flame().palette.clone();
        if let Some(a) = self.gradients.show(ctx, &current) {
            match a {
                GradientAction::Apply(g) => self.apply_gradient(g),
                GradientAction::Load => req = Some(FlameRequest::LoadGradient),
                GradientAction::FromImage => req = Some(FlameRequest::GradientFromImage),
            }
        }
        req
    }

    /// The tab's panels: file contents, editor, preview.
    pub fn ui(&mut self, ui: &mut egui::Ui, options: &Options) {
        let mut dragging = false;
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
                    dragging = self.editor_panel(ui, options);
                });
        }
        egui::CentralPanel::default().show(ui, |ui| self.preview_panel(ui, options, dragging));
        self.thumbs.end_frame(ui.ctx());
        self.step_animations(ui.ctx());
    }

    fn editor_panel(&mut self, ui: &mut egui::Ui, options: &Options) -> bool {
        let auto = self.auto_weights(options);
        let flame = self.doc().flame().clone();
        if let Some(a) = triangles::toolbar(ui, &mut self.editor, &flame) {
            self.editor_action(a, options);
        }
        let h = (ui.available_height() * 0.55).max(160.0);
        let mut dragging = false;
        ui.allocate_ui(Vec2::new(ui.available_width(), h), |ui| {
            let (doc, editor) = self.doc_and_editor();
            let out = triangles::canvas(ui, doc, editor, auto);
            dragging = out.dragging;
            if let Some(a) = out.action {
                self.editor_action(a, options);
            }
        });
        ui.separator();
        egui::ScrollArea::vertical()
            .id_salt("xform-panels")
            .show(ui, |ui| {
                let (doc, editor) = self.doc_and_editor();
                xform_panel::panels(ui, doc, editor, auto);
                ui.separator();
                settings::flame_settings(ui, doc);
            });
        dragging
    }

    fn doc_and_editor(&mut self) -> (&mut Document, &mut EditorState) {
        (
            pick(self.showing, &mut self.batch, &mut self.file),
            &mut self.editor,
        )
    }

    fn editor_action(&mut self, a: EditorAction, options: &Options) {
        let auto = self.auto_weights(options);
        let doc = pick(self.showing, &mut self.batch, &mut self.file);
        let editor = &mut self.editor;
        match a {
            EditorAction::AutoZoom => editor.auto_zoom(doc.flame()),
            EditorAction::Delete => {
                if let Err(e) = triangles::delete_selected(doc, editor) {
                    self.notices.status(e);
                }
            }
            EditorAction::Duplicate => triangles::duplicate_selected(doc, editor, auto),
            EditorAction::Add => triangles::add_xform(doc, editor, auto),
            EditorAction::Undo => self.undo(),
            EditorAction::Redo => self.redo(),
        }
    }

    /// The tab's part of the status bar.
    pub fn status_bar(&mut self, ui: &mut egui::Ui) {
        let f = self.doc().flame();
        ui.label(format!(
            "{}{}  {}×{}  {} transforms",
            if f.name.is_empty() {
                "(unnamed)"
            } else {
                &f.name
            },
            if self.doc().dirty { " *" } else { "" },
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
            p.status(ui);
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
            // The progress bar moves without events from the worker.
            ui.ctx()
                .request_repaint_after(std::time::Duration::from_millis(100));
        }
    }
}

/// The document shown: the batch when it is shown and exists, otherwise the file.
fn pick<'a>(
    showing: Showing,
    batch: &'a mut Option<Document>,
    file: &'a mut Document,
) -> &'a mut Document {
    match (showing, batch) {
        (Showing::Batch, Some(b)) => b,
        _ => file,
    }
}

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
