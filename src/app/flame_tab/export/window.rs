//! The export windows: the settings dialog (size, quality, file, render state) and the
//! running export's window (progress, Save now, Stop, Cancel).

use std::path::PathBuf;

use eframe::egui;

use super::job::{ExportJob, JobAction};
use super::resume::quality_text;
use super::settings::{ExportSettings, state_path};
use crate::app::a11y::named;
use crate::flame::render::{MAX_QUALITY, MIN_QUALITY};

/// Millions with one decimal, or the number itself below a million.
fn count(n: f64) -> String {
    if n >= 1e6 {
        format!("{:.1} M", n / 1e6)
    } else {
        format!("{n:.0}")
    }
}

/// The running export's window: what is done, Save now, Stop and Cancel.
pub fn job_window(ui: &mut egui::Ui, job: &ExportJob) -> Option<JobAction> {
    let st = job.status();
    let mut r = None;
    ui.set_width(440.0);
    ui.add(egui::Label::new(format!("Rendering {}", job.path.display())).truncate());
    if st.loading {
        ui.label("Reading the render state…");
    } else {
        let text = format!(
            "Quality reached: {} of {}",
            quality_text(st.quality_done),
            quality_text(st.asked)
        );
        if st.refining || st.quality_done >= st.asked {
            ui.label(format!("{text} — refining until stopped"));
        } else {
            ui.add(
                egui::ProgressBar::new((st.quality_done / st.asked.max(MIN_QUALITY)) as f32)
                    .desired_width(420.0)
                    .text(text),
            );
        }
        ui.label(format!(
            "Samples: {}, {} per second",
            count(st.samples_done as f64),
            count(st.samples_per_second)
        ));
    }
    // Always one line (empty until there is something to say), so the buttons stay put.
    ui.add(egui::Label::new(&st.note).truncate());
    ui.horizontal(|ui| {
        let whole = st.strips <= 1;
        if ui
            .add_enabled(whole && st.samples_done > 0, egui::Button::new("Save now"))
            .on_hover_text("write the picture of what is rendered so far and go on")
            .clicked()
        {
            r = Some(JobAction::SaveNow);
        }
        if ui
            .add_enabled(whole, egui::Button::new("Stop"))
            .on_hover_text("end after this pass and write the picture of what is rendered")
            .on_disabled_hover_text(
                "a render in strips writes its picture when the last strip is done",
            )
            .clicked()
        {
            r = Some(JobAction::Stop);
        }
        if ui
            .button("Cancel")
            .on_hover_text("end at once and write nothing (files saved before stay)")
            .clicked()
        {
            r = Some(JobAction::Cancel);
        }
    });
    r
}

/// The export settings dialog. Returns Some(true) to start, Some(false) to cancel; `browse`
/// is set when the user wants to choose the file.
pub fn dialog(ui: &mut egui::Ui, s: &mut ExportSettings, browse: &mut bool) -> Option<bool> {
    let mut r = None;
    if let Some(info) = &s.resume {
        ui.label(format!("Continue the render state {}", info.summary()));
    }
    let resuming = s.resume.is_some();
    egui::Grid::new("export-grid")
        .num_columns(2)
        .show(ui, |ui| {
            if !resuming {
                size_row(ui, s);
            }
            if resuming {
                let l = ui.label("Add quality");
                ui.add(
                    egui::DragValue::new(&mut s.quality)
                        .range(0.0..=MAX_QUALITY)
                        .speed(1.0),
                )
                .labelled_by(l.id)
                .on_hover_text("samples per pixel to add to the saved render (0: as it is)");
            } else {
                let l = ui.label("Quality");
                ui.add(
                    egui::DragValue::new(&mut s.quality)
                        .range(0.1..=100000.0)
                        .speed(1.0),
                )
                .labelled_by(l.id)
                .on_hover_text("samples per pixel (more: smoother, slower)");
            }
            ui.end_row();
            if !resuming {
                let l = ui.label("Supersample");
                ui.add(egui::DragValue::new(&mut s.supersample).range(1..=4))
                    .labelled_by(l.id)
                    .on_hover_text("render this many times larger and shrink (smoother edges)");
                ui.end_row();
            }
            ui.label("Refine");
            ui.checkbox(&mut s.refine, "keep refining until stopped")
                .on_hover_text(
                    "after the quality is reached, go on adding samples until Stop; \
                     Save now and Stop write the picture of what is rendered",
                );
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
            ui.label("Render state");
            ui.checkbox(&mut s.save_state, "also save the render state")
                .on_hover_text(format!(
                    "write {} beside the picture, to continue the render later \
                     (File › Resume render state…)",
                    state_path(&s.path)
                        .file_name()
                        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
                ));
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

/// The size row: width × height, optionally keeping the proportions.
fn size_row(ui: &mut egui::Ui, s: &mut ExportSettings) {
    ui.label("Size");
    ui.horizontal(|ui| {
        size_fields(
            ui,
            (&mut s.width, &mut s.height, &mut s.lock_aspect),
            ["Export width", "Export height"],
        )
    });
    ui.end_row();
}

/// Width × height in pixels (named `names` for screen readers and tests) and "keep
/// proportions": changing one side then changes the other.
pub(in crate::app::flame_tab) fn size_fields(
    ui: &mut egui::Ui,
    (width, height, lock): (&mut u32, &mut u32, &mut bool),
    names: [&str; 2],
) {
    let aspect = *width as f64 / (*height).max(1) as f64;
    let w = named(
        ui.add(egui::DragValue::new(width).range(1..=30000)),
        names[0],
    )
    .on_hover_text("width in pixels");
    ui.label("×");
    let h = named(
        ui.add(egui::DragValue::new(height).range(1..=30000)),
        names[1],
    )
    .on_hover_text("height in pixels");
    ui.checkbox(lock, "keep proportions")
        .on_hover_text("changing one side changes the other");
    if *lock {
        if w.changed() {
            *height = ((*width as f64 / aspect).round() as u32).clamp(1, 30000);
        } else if h.changed() {
            *width = ((*height as f64 * aspect).round() as u32).clamp(1, 30000);
        }
    }
}
