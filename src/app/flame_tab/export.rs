//! Export image: size, quality, PNG/BMP; rendered in the background with progress and Cancel.

use std::path::PathBuf;

use eframe::egui;

use crate::app::a11y::named;
use crate::app::worker::{TaskWorker, task_worker};
use crate::flame::render::{RenderOptions, Renderer};
use crate::flame::{Flame, OutputFormat};

/// Settings of the export dialog.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportSettings {
    pub width: u32,
    pub height: u32,
    pub quality: f64,
    pub supersample: u32,
    pub bits16: bool,
    pub transparent: bool,
    pub path: PathBuf,
    /// Width and height keep the flame's proportions.
    pub lock_aspect: bool,
}

/// A running export, with progress and Cancel.
pub struct ExportJob {
    pub path: PathBuf,
    worker: TaskWorker<Result<(), String>>,
}

impl ExportJob {
    pub fn start(
        flame: &Flame,
        s: &ExportSettings,
        threads: usize,
        repaint: impl Fn() + Send + 'static,
    ) -> ExportJob {
        let mut f = flame.clone();
        f.resize_keep_framing(s.width, s.height);
        f.quality = s.quality;
        f.supersample = s.supersample.max(1);
        let settings = s.clone();
        let worker = task_worker("ugnis-export", repaint);
        worker.submit(Box::new(move |cancel, progress| {
            let opts = RenderOptions {
                seed: f.seed.unwrap_or(1),
                threads,
                format: OutputFormat {
                    bits16: settings.bits16,
                    transparent: settings.transparent,
                },
                ..RenderOptions::default()
            };
            let mut r = Renderer::new(&f, &opts).map_err(|e| e.to_string())?;
            if !r.run_all(200, cancel, progress) {
                return Err("export cancelled".into());
            }
            let samples = r.samples_done();
            let rendered = r.flame().clone();
            let img = r.finish();
            let is_bmp = settings
                .path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("bmp"));
            if is_bmp {
                crate::io::bmp::save(&settings.path, &img)
            } else {
                let mut meta = crate::io::png::PngMeta::for_flame(&rendered);
                meta.samples = Some(samples);
                crate::io::png::save(&settings.path, &img, &meta)
            }
            .map_err(|e| format!("cannot write {}: {e}", settings.path.display()))
        }));
        ExportJob {
            path: s.path.clone(),
            worker,
        }
    }

    pub fn fraction(&self) -> f64 {
        self.worker.progress()
    }

    pub fn cancel(&self) {
        self.worker.cancel();
    }

    /// The result once the job has finished.
    pub fn poll(&mut self) -> Option<Result<(), String>> {
        self.worker.poll().pop()
    }
}

/// The export settings dialog. Returns Some(true) to start, Some(false) to cancel; `browse`
/// is set when the user wants to choose the file.
pub fn dialog(ui: &mut egui::Ui, s: &mut ExportSettings, browse: &mut bool) -> Option<bool> {
    let mut r = None;
    egui::Grid::new("export-grid")
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("Size");
            ui.horizontal(|ui| {
                let aspect = s.width as f64 / s.height.max(1) as f64;
                let w = named(
                    ui.add(egui::DragValue::new(&mut s.width).range(1..=30000)),
                    "Export width",
                )
                .on_hover_text("width in pixels");
                ui.label("×");
                let h = named(
                    ui.add(egui::DragValue::new(&mut s.height).range(1..=30000)),
                    "Export height",
                )
                .on_hover_text("height in pixels");
                ui.checkbox(&mut s.lock_aspect, "keep proportions")
                    .on_hover_text("changing one side changes the other");
                if s.lock_aspect {
                    if w.changed() {
                        s.height = ((s.width as f64 / aspect).round() as u32).clamp(1, 30000);
                    } else if h.changed() {
                        s.width = ((s.height as f64 * aspect).round() as u32).clamp(1, 30000);
                    }
                }
            });
            ui.end_row();
            let l = ui.label("Quality");
            ui.add(
                egui::DragValue::new(&mut s.quality)
                    .range(0.1..=100000.0)
                    .speed(1.0),
            )
            .labelled_by(l.id)
            .on_hover_text("samples per pixel (more: smoother, slower)");
            ui.end_row();
            let l = ui.label("Supersample");
            ui.add(egui::DragValue::new(&mut s.supersample).range(1..=4))
                .labelled_by(l.id)
                .on_hover_text("render this many times larger and shrink (smoother edges)");
            ui.end_row();
            ui.label("File");
            ui.horizontal(|ui| {
                let mut t = s.path.display().to_string();
                if named(ui.text_edit_singleline(&mut t), "Export file")
                    .on_hover_text("where the picture is written (.png or .bmp)")
                    .changed()
                {
                    s.path = PathBuf::from(t);
                }
                if ui
                    .button("Choose…")
                    .on_hover_text("choose the file")
                    .clicked()
                {
                    *browse = true;
                }
            });
            ui.end_row();
            let png = !s
                .path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("bmp"));
            ui.label("PNG options");
            ui.horizontal(|ui| {
                ui.add_enabled(png, egui::Checkbox::new(&mut s.bits16, "16 bits"));
                ui.add_enabled(png, egui::Checkbox::new(&mut s.transparent, "transparent"));
            });
            ui.end_row();
        });
    let ext_ok = s
        .path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png") || e.eq_ignore_ascii_case("bmp"));
    if !ext_ok {
        ui.colored_label(
            egui::Color32::from_rgb(230, 150, 80),
            "The file must end in .png or .bmp",
        );
    }
    ui.horizontal(|ui| {
        if ui
            .add_enabled(ext_ok, egui::Button::new("Render"))
            .clicked()
        {
            r = Some(true);
        }
        if ui.button("Cancel").clicked() {
            r = Some(false);
        }
    });
    r
}
