//! The Animation export windows: the settings (source, frames, size, quality, motion blur,
//! output, frames per second; how many frames are on disk already and will be kept) and the
//! running export (frames done, the frame being rendered, Cancel).

use std::path::PathBuf;

use eframe::egui;

use super::job::AnimJob;
use super::settings::{AnimExportSettings, SourceKind};
use crate::app::a11y::named;
use crate::app::flame_tab::export::size_fields;
use crate::flame::render::{MAX_QUALITY, MIN_QUALITY};
use crate::flame::sequence::Animation;
use crate::io::animation::MAX_FRAMES;

/// What the settings window knows about the document.
pub struct Offer {
    /// The sources that can be chosen now.
    pub sources: Vec<SourceKind>,
    /// The motion blur the flame asks for.
    pub anim: Animation,
    /// The frames each timed source spans (first, last), for "Whole".
    pub ranges: Vec<(SourceKind, (f64, f64))>,
    /// ffmpeg is on PATH.
    pub ffmpeg: bool,
}

/// What the settings window asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ask {
    Start,
    Close,
    Browse,
}

/// The running export's window; true when Cancel was pressed.
pub fn job_window(ui: &mut egui::Ui, job: &AnimJob) -> bool {
    let p = job.progress();
    ui.set_width(420.0);
    let out = job.video.as_ref().unwrap_or(&job.dir);
    ui.add(egui::Label::new(format!("Writing {}", out.display())).truncate());
    let text = format!(
        "frame {} of {}{}",
        (p.done + 1).min(p.total),
        p.total,
        if p.skipped > 0 {
            format!(" ({} on disk kept)", p.skipped)
        } else {
            String::new()
        }
    );
    ui.add(
        egui::ProgressBar::new(job.fraction() as f32)
            .desired_width(400.0)
            .text(text),
    );
    ui.button("Cancel")
        .on_hover_text("stop at once; the frames written so far stay and a new export resumes")
        .clicked()
}

/// The settings window. `on_disk`: frames of these settings already in the output folder.
pub fn dialog(
    ui: &mut egui::Ui,
    s: &mut AnimExportSettings,
    offer: &Offer,
    on_disk: usize,
) -> Option<Ask> {
    let mut ask = None;
    egui::Grid::new("anim-export-grid")
        .num_columns(2)
        .show(ui, |ui| {
            source_row(ui, s, offer);
            frames_row(ui, s, offer);
            size_row(ui, s);
            let l = ui.label("Quality");
            ui.add(
                egui::DragValue::new(&mut s.quality)
                    .range(MIN_QUALITY..=MAX_QUALITY)
                    .speed(1.0),
            )
            .labelled_by(l.id)
            .on_hover_text("samples per pixel of every frame");
            ui.end_row();
            ui.label("Motion blur");
            let a = &offer.anim;
            ui.checkbox(
                &mut s.blur,
                format!(
                    "{} sub-frames over {} frame(s), {}",
                    a.temporal_samples,
                    a.temporal_filter_width,
                    a.temporal_filter_type.name()
                ),
            )
            .on_hover_text(
                "each frame drawn from the flames over its exposure, as the flame's Motion \
                 blur settings say (Settings section); off: every frame at its instant",
            );
            ui.end_row();
            ask = output_row(ui, s).or(ask);
            let l = ui.label("fps");
            ui.add(
                egui::DragValue::new(&mut s.fps)
                    .range(crate::io::video::MIN_FPS..=crate::io::video::MAX_FPS)
                    .speed(0.5),
            )
            .labelled_by(l.id)
            .on_hover_text("frames per second of the video");
            ui.end_row();
        });
    let problem = s.check().err();
    let n = s.frames().map_or(0, |f| f.len());
    match &problem {
        Some(p) => {
            ui.colored_label(egui::Color32::from_rgb(230, 150, 80), p);
        }
        None => {
            ui.label(if on_disk > 0 {
                format!("{n} frames; {on_disk} of them are in the folder already and are kept")
            } else {
                format!("{n} frames")
            });
        }
    }
    if s.needs_ffmpeg() && !offer.ffmpeg {
        ui.colored_label(
            egui::Color32::from_rgb(230, 150, 80),
            "ffmpeg is not on PATH: the frames are written and kept, the video is not \
             (install ffmpeg, then export again to encode them)",
        );
    }
    ui.horizontal(|ui| {
        let label = if on_disk > 0 && problem.is_none() {
            "Resume"
        } else {
            "Render"
        };
        if ui
            .add_enabled(problem.is_none(), egui::Button::new(label))
            .on_hover_text("render the frames not yet on disk, then the video")
            .clicked()
        {
            ask = Some(Ask::Start);
        }
        if ui.button("Cancel").clicked() {
            ask = Some(Ask::Close);
        }
    });
    ask
}

/// The source chooser; a new source shows its whole range.
fn source_row(ui: &mut egui::Ui, s: &mut AnimExportSettings, offer: &Offer) {
    let l = ui.label("Source");
    let before = s.source;
    egui::ComboBox::from_id_salt("anim-source")
        .selected_text(s.source.label())
        .width(220.0)
        .show_ui(ui, |ui| {
            for k in &offer.sources {
                ui.selectable_value(&mut s.source, *k, k.label());
            }
        })
        .response
        .labelled_by(l.id)
        .on_hover_text("what moves");
    if s.source != before {
        whole(s, offer);
    }
    ui.end_row();
}

/// The first and last frame to render.
pub fn whole(s: &mut AnimExportSettings, offer: &Offer) {
    if let Some((_, r)) = offer.ranges.iter().find(|(k, _)| *k == s.source) {
        (s.first, s.last) = *r;
    } else {
        s.first = 1.0;
        s.last = s.total as f64;
    }
}

fn frames_row(ui: &mut egui::Ui, s: &mut AnimExportSettings, offer: &Offer) {
    ui.label("Frames");
    ui.horizontal(|ui| {
        named(
            ui.add(
                egui::DragValue::new(&mut s.first)
                    .speed(0.25)
                    .max_decimals(0),
            ),
            "First frame to export",
        );
        ui.label("to");
        named(
            ui.add(
                egui::DragValue::new(&mut s.last)
                    .speed(0.25)
                    .max_decimals(0),
            ),
            "Last frame to export",
        );
        if !s.source.timed() {
            ui.label("of");
            let r = named(
                ui.add(egui::DragValue::new(&mut s.total).range(1..=MAX_FRAMES)),
                "Frames of the animation",
            )
            .on_hover_text("frames of the whole animation (names and in-betweens depend on it)");
            if r.changed() {
                s.last = s.last.min(s.total as f64);
            }
        }
        if ui
            .button("Whole")
            .on_hover_text("every frame of the source")
            .clicked()
        {
            whole(s, offer);
        }
    })
    .response
    .on_hover_text(if s.source.timed() {
        "frames by their time (files named 00012.png as flam3-animate names them)"
    } else {
        "frames numbered from 1 (files named frame-0012.png)"
    });
    ui.end_row();
}

fn size_row(ui: &mut egui::Ui, s: &mut AnimExportSettings) {
    ui.label("Size");
    ui.horizontal(|ui| {
        size_fields(
            ui,
            (&mut s.width, &mut s.height, &mut s.lock_aspect),
            ["Animation width", "Animation height"],
        )
    });
    ui.end_row();
}

fn output_row(ui: &mut egui::Ui, s: &mut AnimExportSettings) -> Option<Ask> {
    let mut ask = None;
    ui.label("Output");
    ui.horizontal(|ui| {
        let mut t = s.output.display().to_string();
        if named(
            ui.add(egui::TextEdit::singleline(&mut t).desired_width(260.0)),
            "Animation output",
        )
        .on_hover_text(
            "a folder for PNG frames, or a video: .mp4, .webm, .mkv, .mov (through ffmpeg), \
             .gif or .apng (built in); a video's frames are kept in NAME.frames beside it",
        )
        .changed()
        {
            s.output = PathBuf::from(t);
        }
        if ui
            .button("Choose…")
            .on_hover_text("choose a video file")
            .clicked()
        {
            ask = Some(Ask::Browse);
        }
    });
    ui.end_row();
    ask
}
