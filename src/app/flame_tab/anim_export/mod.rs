//! Export animation: the frames of this flame's keys, of the timeline's sequence, of the
//! file's flam3 sequence, of the rotation or of in-betweens through the file, rendered in the
//! background by the same animation job as `ugnis animate` (every frame saved atomically, the
//! frames already on disk skipped, so a cancelled or failed export resumes where it stopped),
//! as PNG frames or a video (ffmpeg's containers, GIF and APNG built in).
//!
//! `settings.rs` holds the window's settings and makes the engine's job, `job.rs` runs it,
//! `window.rs` draws the settings window and the running export's window.

mod job;
mod settings;
mod window;

use std::path::Path;

use eframe::egui;

pub use job::AnimJob;
pub use settings::{AnimExportSettings, SourceKind, Sources, is_sequence};
pub use window::{Ask, Offer};

use super::timeline::Mode;
use super::{FlameRequest, FlameTab};
use crate::app::options::Options;
use crate::io;

/// The settings window's state: the settings, and what is slow to find out (the sources and
/// their frames, ffmpeg, the frames on disk), found out when it opens.
pub struct AnimDialog {
    pub settings: AnimExportSettings,
    offer: Offer,
    on_disk: Option<(AnimExportSettings, usize)>,
}

impl AnimDialog {
    fn on_disk(&mut self) -> usize {
        match &self.on_disk {
            Some((s, n)) if *s == self.settings => *n,
            _ => {
                let n = self.settings.frames_on_disk();
                self.on_disk = Some((self.settings.clone(), n));
                n
            }
        }
    }
}

impl FlameTab {
    /// The sequence the timeline plays, if any.
    fn timeline_sequence(&self) -> Option<&[crate::flame::Flame]> {
        match &self.timeline.mode {
            Mode::Sequence(s) => Some(&s.cps),
            Mode::Keys => None,
        }
    }

    /// What can be exported now, and the frames each source spans.
    fn offer(&self, probe: &AnimExportSettings) -> Offer {
        let f = self.doc().flame();
        let flames = &self.doc().flames;
        let mut sources = Vec::new();
        if self.timeline_sequence().is_some() {
            sources.push(SourceKind::Timeline);
        }
        if !f.keys.is_empty() {
            sources.push(SourceKind::Keys);
        }
        if is_sequence(flames) {
            sources.push(SourceKind::FileSequence);
        }
        sources.push(SourceKind::Rotation);
        if flames.len() > 1 {
            sources.push(SourceKind::Interpolation);
        }
        let src = Sources {
            flame: f,
            flames,
            timeline: self.timeline_sequence(),
        };
        let ranges = sources
            .iter()
            .filter(|k| k.timed())
            .filter_map(|k| {
                let probe = AnimExportSettings {
                    source: *k,
                    ..probe.clone()
                };
                probe.source(&src).ok().map(|s| (*k, s.default_range()))
            })
            .collect();
        Offer {
            sources,
            anim: f.anim,
            ranges,
            ffmpeg: io::video::ffmpeg_available(&probe.ffmpeg),
        }
    }

    /// Settings for the current flame: what the timeline plays, at the flame's size and
    /// quality, into a folder beside the file.
    fn default_anim_settings(&self, options: &Options) -> AnimExportSettings {
        let f = self.doc().flame();
        let source = if self.timeline.plays_sequence() {
            SourceKind::Timeline
        } else if !f.keys.is_empty() {
            SourceKind::Keys
        } else if is_sequence(&self.doc().flames) {
            SourceKind::FileSequence
        } else {
            SourceKind::Rotation
        };
        let (dir, name) = self.export_place();
        AnimExportSettings {
            source,
            first: 0.0,
            last: 0.0,
            total: 90,
            width: f.width,
            height: f.height,
            lock_aspect: true,
            quality: f.quality.clamp(
                crate::flame::render::MIN_QUALITY,
                options.main_quality.max(f.quality),
            ),
            blur: true,
            output: dir.join(format!("{name}-animation")),
            fps: f.keys.fps,
            ffmpeg: "ffmpeg".into(),
            seed: 1,
        }
    }

    /// Open the Animation export window.
    pub fn open_anim_export(&mut self, options: &Options) {
        if self.anim_job.is_some() {
            self.notices
                .status("An animation export is running: cancel it before starting another");
            return;
        }
        let mut settings = self.default_anim_settings(options);
        let offer = self.offer(&settings);
        window::whole(&mut settings, &offer);
        self.anim_export = Some(AnimDialog {
            settings,
            offer,
            on_disk: None,
        });
    }

    /// Start the export the window describes.
    fn start_anim_export(&mut self, options: &Options) {
        let Some(d) = &self.anim_export else {
            return;
        };
        let s = d.settings.clone();
        let src = Sources {
            flame: self.doc().flame(),
            flames: &self.doc().flames,
            timeline: self.timeline_sequence(),
        };
        match s.job(&src, options.threads) {
            Ok(job) => {
                self.last_export_dir = s.output.parent().map(Path::to_path_buf);
                self.anim_job = Some(AnimJob::start(job, self.repaint()));
                self.anim_export = None;
            }
            Err(e) => self.notices.message("Cannot export the animation", e),
        }
    }

    /// What a finished export said.
    fn poll_anim_job(&mut self) {
        let Some(r) = self.anim_job.as_mut().and_then(|j| j.poll()) else {
            return;
        };
        let video = self.anim_job.take().and_then(|j| j.video);
        match r {
            Ok(end) => {
                let s = &end.summary;
                let mut text = format!(
                    "Animation: {} frames rendered, {} on disk kept, in {}",
                    s.rendered,
                    s.skipped,
                    end.dir.display()
                );
                if let Some(v) = &s.video {
                    text.push_str(&format!("; video {}", v.display()));
                }
                for note in s.notes() {
                    text.push_str(&format!("; {note}"));
                }
                if let Some(why) = end.no_video {
                    self.notices.message(
                        "Video not made",
                        format!(
                            "{why}\n\nThe frames are kept in {}; export again once ffmpeg is \
                             installed (frames on disk are not rendered again).",
                            end.dir.display()
                        ),
                    );
                } else if video.is_some() && s.video.is_none() {
                    text.push_str("; no video");
                }
                self.notices.status(text);
            }
            Err(e) if e.starts_with("Animation export cancelled") => self.notices.status(e),
            Err(e) => self.notices.message("Animation export failed", e),
        }
    }

    /// The Animation export windows. Returns a request for the shell (the file chooser).
    pub(super) fn anim_windows(
        &mut self,
        ctx: &egui::Context,
        options: &Options,
    ) -> Option<FlameRequest> {
        self.poll_anim_job();
        if let Some(j) = &self.anim_job {
            let r0 = ctx.content_rect();
            let mut cancel = false;
            egui::Window::new("Export animation")
                .id(egui::Id::unique("anim-export-running"))
                .collapsible(false)
                .resizable(false)
                .pivot(egui::Align2::CENTER_TOP)
                .default_pos([r0.center().x, r0.top() + 80.0])
                .show(ctx, |ui| cancel = window::job_window(ui, j));
            if cancel {
                j.cancel();
            }
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
        let d = self.anim_export.as_mut()?;
        let on_disk = d.on_disk();
        let mut ask = None;
        egui::Window::new("Export animation")
            .collapsible(false)
            .pivot(egui::Align2::CENTER_CENTER)
            .default_pos(ctx.content_rect().center())
            .show(ctx, |ui| {
                ask = window::dialog(ui, &mut d.settings, &d.offer, on_disk)
            });
        match ask {
            Some(Ask::Start) => self.start_anim_export(options),
            Some(Ask::Close) => self.anim_export = None,
            Some(Ask::Browse) => return Some(FlameRequest::ChooseAnimationFile),
            None => {}
        }
        None
    }
}
