//! The flame tab: the open file and the last random batch, the live preview, the triangle
//! editor with its numeric panels, and the flame's windows (gradient, mutations, export).
//!
//! | file | what |
//! |---|---|
//! | `document.rs`, `history.rs` | the flames of a file or batch, the undo history and its window |
//! | `commands.rs` | random flames, batches, weights, save, paste, export; the windows |
//! | `file_panel.rs` | the left panel: the file's flames and the batch, with thumbnails |
//! | `preview_panel.rs` / `preview.rs` / `convergence.rs` | the central picture (camera by mouse), its renderer and when it is clean |
//! | `preview_window.rs` | the preview over the whole window or in a window of its own |
//! | `editor_panel.rs` | the right panel: triangle editor and the sections below it |
//! | `editor_state.rs`, `triangles.rs`, `editor_tools.rs` | the triangle editor |
//! | `transform_tools.rs` | turn, scale and move by typed amounts (Apophysis' triangle buttons) |
//! | `transform_list.rs`, `xform_panel.rs`, `variations_panel.rs`, `xaos.rs`, `settings.rs` | the sections |
//! | `animation.rs` | rotating triangles and morphs between flames |
//! | `timeline/` | the timeline under the preview: keys, curves, playback, loop tools |
//! | `anim_export/` | the Animation export window: frames and videos in the background |
//! | `gradients.rs`, `palette_editor.rs`, `mutations.rs`, `export.rs`, `variation_filter.rs` | windows |
//! | `first_flame.rs` | the striking random flame of the first start |

pub(crate) mod anim_export;
pub use anim_export::SourceKind;
pub use timeline::rotation_loop;
pub(crate) mod animation;
pub(crate) mod commands;
pub(crate) mod convergence;
pub(crate) mod document;
pub(crate) mod editor_panel;
pub(crate) mod editor_state;
pub(crate) mod editor_tools;
pub(crate) mod export;
pub(crate) mod file_panel;
pub(crate) mod first_flame;
pub(crate) mod gradients;
pub(crate) mod history;
pub(crate) mod mutations;
pub(crate) mod palette_editor;
pub mod preview;
pub mod preview_motion;
pub(crate) mod preview_panel;
pub(crate) mod preview_window;
pub(crate) mod settings;
pub(crate) mod thumbnails;
pub(crate) mod timeline;
pub(crate) mod transform_list;
pub(crate) mod transform_tools;
pub(crate) mod triangles;
pub(crate) mod variation_filter;
pub(crate) mod variations_panel;
pub(crate) mod xaos;
pub(crate) mod xform_panel;

use std::path::{Path, PathBuf};

use eframe::egui::{self, Vec2};

use crate::app::notice::Notices;
use crate::app::options::Options;
use crate::app::worker::{Repaint, TaskWorker, repaint_of};
use crate::flame::Flame;
use crate::flame::random::VariationMode;
use crate::flame::rng::FastRng;
use crate::io;
use animation::{Animation, Morph};
use document::Document;
use editor_state::{EditorState, Selected};
use export::{ExportJob, ExportSettings};
use gradients::GradientWindow;
use mutations::MutationWindow;
use palette_editor::PaletteEditor;
use preview_panel::Preview;
use preview_window::PreviewPlace;
use thumbnails::Thumbnails;
use timeline::Timeline;
use variation_filter::VariationFilter;

pub use animation::MORPH_FRAMES;

/// Which document the editor shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Showing {
    /// The open file.
    File,
    /// The last random batch.
    Batch,
}

/// What the flame tab asks the shell for (file choosers live in the shell).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FlameRequest {
    /// Choose a gradient file to load.
    LoadGradient,
    /// Choose a picture to make a gradient from.
    GradientFromImage,
    /// Choose the file an export writes.
    ChooseExportFile,
    /// Choose the folder or video an animation export writes.
    ChooseAnimationFile,
    /// Choose the sound that drives a parameter.
    ChooseSoundFile,
}

/// State of the flame tab.
pub struct FlameTab {
    /// The open file.
    pub file: Document,
    /// The last random batch, if any.
    pub batch: Option<Document>,
    /// Which of the two the editor shows.
    pub showing: Showing,
    /// The triangle editor's selection, mode and view.
    pub editor: EditorState,
    /// The file-contents panel is shown.
    pub show_files: bool,
    /// The triangle editor is shown.
    pub show_editor: bool,
    /// Preview zoom (1 = fit).
    pub preview_zoom: f32,
    /// The preview covers the whole window (F11).
    pub full_view: bool,
    /// The preview is in a window of its own; the editor takes its room.
    pub preview_window: bool,
    /// The History window is open.
    pub history_open: bool,
    /// The last random batch is unfolded in the left panel.
    pub batch_shown: bool,
    /// Which variations new random flames get.
    pub variation_mode: VariationMode,
    /// Status lines and message boxes of the tab.
    pub notices: Notices,
    /// The gradient window.
    pub gradients: GradientWindow,
    /// The palette editor window.
    pub palette_editor: PaletteEditor,
    /// The mutations window.
    pub mutations: MutationWindow,
    /// The variations filter window.
    pub variation_filter: VariationFilter,
    /// The export dialog's settings, while it is open.
    pub export_dialog: Option<ExportSettings>,
    /// The running export, if any.
    pub export_job: Option<ExportJob>,
    /// The running rotation animation, if any.
    pub animation: Option<Animation>,
    /// The running morph to the next flame, if any.
    pub morph: Option<Morph>,
    /// The timeline under the preview.
    pub timeline: Timeline,
    /// The Animation export window, when open.
    pub anim_export: Option<anim_export::AnimDialog>,
    /// The running animation export.
    pub anim_job: Option<anim_export::AnimJob>,
    /// Where the last random batch is kept (the platform data directory; none in tests
    /// unless they set one).
    pub data_dir: Option<PathBuf>,
    preview: Option<Preview>,
    /// Where the preview picture was drawn last frame (tests look at it).
    pub preview_rect: Option<egui::Rect>,
    /// The camera is being dragged on the preview (quick frames, like a triangle drag).
    camera_drag: bool,
    thumbs: Thumbnails,
    batch_job: Option<TaskWorker<Vec<Flame>>>,
    rng: FastRng,
    /// Where the last export was written (the file choosers start there).
    pub last_export_dir: Option<PathBuf>,
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
        options: &Options,
    ) -> FlameTab {
        let mut file = Document::new(flames, path.clone());
        if path.is_none() {
            file.name = "untitled".into();
        }
        let data_dir = ctx.and_then(|_| crate::app::options::data_dir());
        let mut editor = EditorState {
            canvas: egui::Rect::from_min_size(egui::Pos2::ZERO, Vec2::new(420.0, 360.0)),
            ..Default::default()
        };
        editor.auto_zoom(file.flame());
        FlameTab {
            file,
            batch: data_dir.as_deref().and_then(load_last_batch),
            showing: Showing::File,
            editor,
            show_files: true,
            show_editor: true,
            preview_zoom: 1.0,
            full_view: false,
            preview_window: false,
            history_open: false,
            batch_shown: true,
            variation_mode: options.variation_mode(),
            notices: Notices::default(),
            gradients: GradientWindow::default(),
            palette_editor: PaletteEditor::default(),
            mutations: MutationWindow::default(),
            variation_filter: VariationFilter::default(),
            export_dialog: None,
            export_job: None,
            animation: None,
            morph: None,
            timeline: Timeline::default(),
            anim_export: None,
            anim_job: None,
            data_dir,
            preview: ctx.map(Preview::new),
            preview_rect: None,
            camera_drag: false,
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

    /// Start the live preview's renderer if it is not running (the application starts it
    /// with the window; tests that look at the picture start it here).
    pub fn start_preview(&mut self, ctx: &egui::Context) {
        if self.preview.is_none() {
            self.preview = Some(Preview::new(ctx));
        }
    }

    /// How far the preview has got: its refining progress in [0, 1] and whether it is clean
    /// (done); `None` without a preview renderer.
    pub fn preview_progress(&self) -> Option<(f64, bool)> {
        self.preview.as_ref().map(|p| (p.fraction(), !p.refining()))
    }

    /// The document the editor shows (the file or the batch).
    pub fn doc(&self) -> &Document {
        match (self.showing, &self.batch) {
            (Showing::Batch, Some(b)) => b,
            _ => &self.file,
        }
    }

    /// The document the editor shows, to change it.
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

    /// The tab's panels: timeline (when shown), file contents, editor, preview.
    pub fn ui(&mut self, ui: &mut egui::Ui, options: &Options) {
        // A drag of a number, slider or the camera has ended: it becomes one undo step.
        let idle = ui.input(|i| !i.pointer.any_down() && i.smooth_scroll_delta == Vec2::ZERO);
        if idle {
            self.file.commit_live();
            if let Some(b) = &mut self.batch {
                b.commit_live();
            }
        }
        if self.full_view {
            self.full_window_ui(ui, options);
            self.end_frame(ui.ctx());
            return;
        }
        if self.timeline.open {
            let h = ui.available_height();
            // The whole width, as in animation programs (the ruler wants room); each layout
            // keeps its own height: the curve editor needs more.
            let (id, size) = if self.timeline.show_curve {
                ("timeline-with-curve", 330.0)
            } else {
                ("timeline", 130.0)
            };
            egui::Panel::bottom(id)
                .resizable(true)
                .default_size(size)
                .min_size(90.0)
                .max_size((h * 0.6).max(90.0))
                .show(ui, |ui| self.timeline_panel(ui));
        }
        // The side panels leave the preview most of the room: narrower in a small window,
        // never more than a fifth and two fifths of the width.
        let width = ui.available_width();
        let mut dragging = false;
        if self.show_files {
            egui::Panel::left("files")
                .default_size((width * 0.16).clamp(120.0, 190.0))
                .min_size(90.0)
                .max_size((width * 0.2).max(100.0))
                .resizable(true)
                .show(ui, |ui| self.file_panel(ui));
        }
        if self.preview_window {
            // The preview has its own window: the editor takes the middle.
            egui::CentralPanel::default().show(ui, |ui| {
                dragging = self.editor_panel(ui, options);
            });
            self.preview_viewport(ui.ctx(), options, dragging);
        } else {
            if self.show_editor {
                egui::Panel::right("editor")
                    .default_size((width * 0.36).clamp(280.0, 460.0))
                    .min_size(220.0)
                    .max_size((width * 0.5).max(220.0))
                    .resizable(true)
                    .show(ui, |ui| {
                        dragging = self.editor_panel(ui, options);
                    });
            }
            egui::CentralPanel::default().show(ui, |ui| {
                self.preview_panel(ui, options, dragging, PreviewPlace::Panel)
            });
        }
        self.end_frame(ui.ctx());
    }

    /// What runs every frame after the panels: thumbnails, animations, the timeline.
    fn end_frame(&mut self, ctx: &egui::Context) {
        self.thumbs.end_frame(ctx);
        self.step_animations(ctx);
        self.timeline_frame(ctx);
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
        // Editor coordinates are shown with y up, as the triangle panel shows them.
        match self.editor.hover_world {
            Some([x, y]) => ui.label(format!("x {x:.4}  y {:.4}", -y)),
            None => ui.label("x —  y —"),
        }
        .on_hover_text("the pointer in the triangle editor (y up)");
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
            let st = j.status();
            let text = if st.refining {
                format!("export: quality {}", export::quality_text(st.quality_done))
            } else {
                format!("export {:.0}%", j.fraction() * 100.0)
            };
            ui.add(
                egui::ProgressBar::new(j.fraction() as f32)
                    .desired_width(140.0)
                    .text(text),
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
pub(super) fn pick<'a>(
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
