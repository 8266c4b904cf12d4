//! Sound-driven motion in the editor: a sound file's loudness in a frequency band becomes the
//! keyframe curve of the parameter chosen on the timeline (as `ugnis animate --sound` does on
//! the command line), one undo step, then edited like any other curve.

use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::sync::atomic::{AtomicBool, Ordering};

use eframe::egui;

use super::super::FlameTab;
use super::{Mode, keys};
use crate::app::worker::{Repaint, TaskWorker, repaint_of, task_worker};
use crate::flame::keyframes::Target;
use crate::io::audio::{AudioError, read_sound, read_sound_with};
use crate::sound::{Band, Drive, Smoothing, Sound, drive_flame};

/// The sound window's settings.
#[derive(Clone, Debug, PartialEq)]
pub struct SoundDialog {
    /// The sound file (WAV, FLAC or MP3), once chosen.
    pub path: Option<PathBuf>,
    /// The band listened to.
    pub band: Band,
    /// The target's value at silence and at the loudest frame.
    pub low: f64,
    /// See `low`.
    pub high: f64,
    /// How fast the motion follows the sound.
    pub smooth: Smoothing,
    /// What the last Make curve came to: what follows the sound, or why it could not be made.
    pub result: Option<Result<String, String>>,
}

impl Default for SoundDialog {
    fn default() -> Self {
        SoundDialog {
            path: None,
            band: Band::BASS,
            low: 0.0,
            high: 1.0,
            smooth: Smoothing {
                attack: 1.0,
                release: 0.3,
            },
            result: None,
        }
    }
}

/// What the window asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SoundAsk {
    /// Choose the sound file.
    Browse,
    /// Make the curve.
    Make,
    /// Stop decoding.
    Cancel,
}

/// A sound file decoding in a background thread (a long MP3 takes seconds), and the curve to
/// make of it.
pub struct SoundJob {
    worker: TaskWorker<Result<Sound, AudioError>>,
    /// The window's settings when Make curve was pressed.
    dialog: SoundDialog,
    target: Target,
    path: PathBuf,
    /// The window has shown the job: its result is taken from the next frame on (so that
    /// "decoding…" is seen at least once).
    shown: AtomicBool,
}

impl std::fmt::Debug for SoundJob {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "SoundJob({})", self.path.display())
    }
}

impl SoundJob {
    /// Start decoding `path` in the background.
    fn start(path: PathBuf, target: Target, dialog: SoundDialog, repaint: Repaint) -> SoundJob {
        let worker = task_worker("ugnis-sound", move || repaint());
        let p = path.clone();
        worker.submit(Box::new(move |cancel, progress| {
            read_sound_with(&p, cancel, progress)
        }));
        SoundJob {
            worker,
            dialog,
            target,
            path,
            shown: AtomicBool::new(false),
        }
    }

    /// The share decoded so far, in [0, 1] (0 while the file's length is unknown).
    pub fn progress(&self) -> f64 {
        self.worker.progress()
    }
}

impl FlameTab {
    /// The parameter and sound file the dialog's curve is made for, or why it cannot be made.
    fn sound_inputs(&self, d: &SoundDialog) -> Result<(Target, PathBuf), String> {
        let target = self.timeline.target.ok_or_else(|| {
            "Choose the parameter the sound moves on the timeline first".to_string()
        })?;
        let path = d
            .path
            .clone()
            .ok_or_else(|| "Choose a sound file first".to_string())?;
        Ok((target, path))
    }

    /// Make the curve the dialog describes for the timeline's parameter (one undo step),
    /// decoding the sound here: what follows the sound, or why it could not be made.
    pub fn drive_by_sound(&mut self, d: &SoundDialog) -> Result<String, String> {
        let (target, path) = self.sound_inputs(d)?;
        let sound = read_sound(&path).map_err(|e| e.to_string())?;
        self.sound_curve(d, target, &path, &sound)
    }

    /// Start decoding the dialog's sound in the background; the curve is made when it is
    /// decoded (see [`FlameTab::poll_sound`]).
    fn start_sound(&mut self, d: &SoundDialog, ctx: &egui::Context) {
        match self.sound_inputs(d) {
            Ok((target, path)) => {
                let job = SoundJob::start(path, target, d.clone(), repaint_of(Some(ctx)));
                self.timeline.sound_job = Some(Rc::new(job));
                if let Some(w) = &mut self.timeline.sound_dialog {
                    w.result = None;
                }
            }
            Err(e) => {
                if let Some(w) = &mut self.timeline.sound_dialog {
                    w.result = Some(Err(e));
                }
            }
        }
    }

    /// Take the decoded sound, once the window has shown the job, and make its curve.
    fn poll_sound(&mut self) {
        let Some(job) = self.timeline.sound_job.clone() else {
            return;
        };
        if self.timeline.sound_dialog.is_none() {
            // The window was closed: nothing is made.
            job.worker.cancel();
            self.timeline.sound_job = None;
            return;
        }
        if !job.shown.load(Ordering::Relaxed) {
            return;
        }
        let Some(decoded) = job.worker.poll().pop() else {
            return;
        };
        self.timeline.sound_job = None;
        let result = decoded
            .map_err(|e| e.to_string())
            .and_then(|sound| self.sound_curve(&job.dialog, job.target, &job.path, &sound));
        if let Some(w) = &mut self.timeline.sound_dialog {
            w.result = Some(result);
        }
    }

    /// The curve of `target` following `sound` as `d` says, as one undo step.
    fn sound_curve(
        &mut self,
        d: &SoundDialog,
        target: Target,
        path: &Path,
        sound: &Sound,
    ) -> Result<String, String> {
        let drive = Drive {
            target,
            band: d.band,
            low: d.low,
            high: d.high,
            smooth: d.smooth,
        };
        // Tried on a copy first, so that a refusal leaves no undo step.
        let mut f = self.doc().flame().clone();
        let replaced = drive_flame(&mut f, sound, &drive)?;
        let keys = f.keys;
        self.doc_mut().edit(|f| f.keys = keys);
        let t = &mut self.timeline;
        t.mode = Mode::Keys;
        t.open = true;
        t.selected_key = None;
        let text = format!(
            "'{}' follows {}{}",
            keys::label(&target),
            path.file_name()
                .map_or(String::new(), |n| n.to_string_lossy().into_owned()),
            if replaced {
                " (its earlier keys are replaced; Undo returns them)"
            } else {
                ""
            }
        );
        self.notices.status(text.clone());
        Ok(text)
    }

    /// The sound window; asks for a file when Choose is pressed.
    pub(crate) fn sound_window(&mut self, ctx: &egui::Context) -> Option<SoundAsk> {
        self.poll_sound();
        let target = self.timeline.target;
        let job = self.timeline.sound_job.clone();
        let d = self.timeline.sound_dialog.as_mut()?;
        let mut open = true;
        let mut ask = None;
        egui::Window::new("Sound-driven motion")
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .pivot(egui::Align2::CENTER_CENTER)
            .default_pos(ctx.content_rect().center())
            .show(ctx, |ui| ask = sound_dialog(ui, d, target, job.as_deref()));
        let d = d.clone();
        if let Some(j) = &job {
            j.shown.store(true, Ordering::Relaxed);
            // The progress moves without events.
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
        if !open || ask == Some(SoundAsk::Cancel) {
            if let Some(j) = self.timeline.sound_job.take() {
                j.worker.cancel();
            }
            if !open {
                self.timeline.sound_dialog = None;
            } else if let Some(w) = &mut self.timeline.sound_dialog {
                w.result = Some(Err("Cancelled".into()));
            }
        }
        if ask == Some(SoundAsk::Make) {
            self.start_sound(&d, ctx);
            return None;
        }
        ask
    }
}

const BANDS: [(&str, Band); 3] = [
    ("Bass (20–150 Hz)", Band::BASS),
    ("Middle (150–2000 Hz)", Band::MIDDLE),
    ("High (2–16 kHz)", Band::HIGH),
];

/// The window's contents.
fn sound_dialog(
    ui: &mut egui::Ui,
    d: &mut SoundDialog,
    target: Option<Target>,
    job: Option<&SoundJob>,
) -> Option<SoundAsk> {
    let mut ask = None;
    egui::Grid::new("sound-grid").num_columns(2).show(ui, |ui| {
        ui.label("Sound");
        ui.horizontal(|ui| {
            let name = d
                .path
                .as_ref()
                .and_then(|p| p.file_name())
                .map_or("(none)".to_string(), |n| n.to_string_lossy().into_owned());
            ui.label(name);
            if ui
                .button("Choose…")
                .on_hover_text("a WAV, FLAC or MP3 file")
                .clicked()
            {
                ask = Some(SoundAsk::Browse);
            }
        });
        ui.end_row();
        ui.label("Moves");
        ui.label(target.as_ref().map_or(
            "(choose a parameter on the timeline)".to_string(),
            keys::label,
        ));
        ui.end_row();
        let l = ui.label("Band");
        let shown = BANDS.iter().find(|(_, b)| *b == d.band).map_or_else(
            || format!("{:.0}–{:.0} Hz", d.band.low, d.band.high),
            |(n, _)| n.to_string(),
        );
        egui::ComboBox::from_id_salt("sound-band")
            .selected_text(shown)
            .show_ui(ui, |ui| {
                for (name, band) in BANDS {
                    ui.selectable_value(&mut d.band, band, name);
                }
            })
            .response
            .labelled_by(l.id);
        ui.end_row();
        let l = ui.label("Band, Hz");
        ui.horizontal(|ui| {
            let low = ui.add(egui::DragValue::new(&mut d.band.low).range(0.0..=399_000.0));
            ui.label("to");
            let high = ui.add(egui::DragValue::new(&mut d.band.high).range(1.0..=400_000.0));
            if low.changed() || high.changed() {
                d.band.high = d.band.high.max(d.band.low + 1.0);
            }
            low.labelled_by(l.id);
        });
        ui.end_row();
        let l = ui.label("Value at silence");
        ui.add(egui::DragValue::new(&mut d.low).speed(0.01))
            .labelled_by(l.id);
        ui.end_row();
        let l = ui.label("Value when loudest");
        ui.add(egui::DragValue::new(&mut d.high).speed(0.01))
            .labelled_by(l.id);
        ui.end_row();
        let l = ui.label("Attack");
        ui.add(egui::Slider::new(&mut d.smooth.attack, 0.0..=1.0))
            .labelled_by(l.id)
            .on_hover_text("the part of the way to a louder level taken in one frame (1: at once)");
        ui.end_row();
        let l = ui.label("Release");
        ui.add(egui::Slider::new(&mut d.smooth.release, 0.0..=1.0))
            .labelled_by(l.id)
            .on_hover_text("the part of the way to a quieter level taken in one frame");
        ui.end_row();
    });
    ui.separator();
    if let Some(j) = job {
        ui.horizontal(|ui| {
            ui.spinner();
            let p = j.progress();
            ui.label(if p > 0.0 {
                format!("decoding… {:.0}%", p * 100.0)
            } else {
                "decoding…".to_string()
            });
            if ui.button("Cancel").clicked() {
                ask = Some(SoundAsk::Cancel);
            }
        });
        return ask;
    }
    match &d.result {
        Some(Ok(text)) => {
            ui.label(text);
        }
        Some(Err(e)) => {
            ui.colored_label(egui::Color32::from_rgb(230, 120, 90), e);
        }
        None => {}
    }
    let ready = d.path.is_some() && target.is_some();
    if ui
        .add_enabled(ready, egui::Button::new("Make curve"))
        .on_hover_text(
            "a key per frame, the parameter's value following the band's loudness; a flame \
             without keys gets a timeline as long as the sound (the file is decoded in the \
             background)",
        )
        .on_disabled_hover_text("choose a sound and a parameter first")
        .clicked()
    {
        ask = Some(SoundAsk::Make);
    }
    ask
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::flame_tab::FlameTab;
    use crate::flame::keyframes::{FlameParam, Target};

    #[test]
    fn a_sound_becomes_the_chosen_parameters_curve_in_one_undo_step() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("beat.wav");
        // Two seconds: a 60 Hz tone in the second half only.
        let rate = 8000;
        let samples: Vec<f32> = (0..2 * rate)
            .map(|i| {
                let t = i as f64 / rate as f64;
                if t < 1.0 {
                    0.0
                } else {
                    (2.0 * std::f64::consts::PI * 60.0 * t).sin() as f32 * 0.8
                }
            })
            .collect();
        std::fs::write(&path, crate::io::audio::wav_bytes(&samples, rate)).unwrap();
        let flame = crate::app::flame_tab::commands::new_flame(&Default::default());
        let mut tab = FlameTab::new(vec![flame], None, None, 1, &Default::default());
        let d = SoundDialog {
            path: Some(path),
            low: 1.0,
            high: 3.0,
            ..SoundDialog::default()
        };
        assert!(tab.drive_by_sound(&d).is_err(), "no parameter chosen yet");
        let zoom = Target::Flame(FlameParam::Zoom);
        tab.timeline.target = Some(zoom);
        assert!(tab.drive_by_sound(&d).unwrap().contains("follows"));
        let f = tab.doc().flame();
        let fps = f.keys.fps;
        assert_eq!(f.keys.frames as f64, (2.0 * fps).ceil());
        let c = f.keys.curve(&zoom).unwrap();
        let early = c.eval(0.25 * fps, None).unwrap();
        let late = c.eval(1.75 * fps, None).unwrap();
        assert!(
            (early - 1.0).abs() < 0.05 && (late - 3.0).abs() < 0.05,
            "{early} {late}"
        );
        tab.doc_mut().undo();
        assert!(tab.doc().flame().keys.is_empty(), "one undo step");
    }
}
