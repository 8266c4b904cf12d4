//! The Animation export window's settings, and the animation job they make: what moves (this
//! flame's keys, the timeline's sequence, the file's flam3 sequence, the rotation, in-betweens
//! through the file), which frames, size, quality, motion blur, and where (a folder of PNG
//! frames, or a video whose frames are kept beside it).

use std::path::PathBuf;

use crate::flame::Flame;
use crate::flame::render::{MAX_QUALITY, MIN_QUALITY, RenderOptions, short_num};
use crate::io::animation::{
    FrameSpec, Job, MAX_FRAMES, Source, frames_by_time, numbered_frames, output_paths,
};
use crate::io::video::{MAX_FPS, MIN_FPS, VideoKind, VideoOptions};

/// What the animation shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SourceKind {
    /// The current flame's keyframes.
    Keys,
    /// The sequence the timeline plays (a morph, loops, the file's sequence).
    Timeline,
    /// The file's flames as a flam3 sequence (they carry times).
    FileSequence,
    /// Fraktalai's rotation of the current flame: every triangle turns about its centre.
    Rotation,
    /// In-betweens through the file's flames in order.
    Interpolation,
}

impl SourceKind {
    /// The source's name in the window.
    pub fn label(self) -> &'static str {
        match self {
            SourceKind::Keys => "keys of this flame",
            SourceKind::Timeline => "the timeline's sequence",
            SourceKind::FileSequence => "flam3 sequence of the file",
            SourceKind::Rotation => "rotation of this flame",
            SourceKind::Interpolation => "in-betweens through the file",
        }
    }

    /// Frames are times named by the time (`00012.png`); otherwise numbered from 1
    /// (`frame-0012.png`) out of a total.
    pub fn timed(self) -> bool {
        matches!(
            self,
            SourceKind::Keys | SourceKind::Timeline | SourceKind::FileSequence
        )
    }
}

/// Settings of the Animation export window.
#[derive(Clone, Debug, PartialEq)]
pub struct AnimExportSettings {
    pub source: SourceKind,
    /// First and last frame (inclusive): times for timed sources, 1-based frame numbers of
    /// the `total` otherwise.
    pub first: f64,
    pub last: f64,
    /// Frames of the whole rotation or in-between animation.
    pub total: u64,
    pub width: u32,
    pub height: u32,
    pub lock_aspect: bool,
    pub quality: f64,
    /// Motion blur as the flames ask (temporal samples, exposure, shape).
    pub blur: bool,
    /// A folder for PNG frames, or a video file (.mp4, .webm, .mkv, .mov, .gif, .apng).
    pub output: PathBuf,
    pub fps: f64,
    /// The ffmpeg program (tests name a missing one).
    pub ffmpeg: PathBuf,
    pub seed: u64,
}

/// What the settings need from the document.
pub struct Sources<'a> {
    /// The flame being edited.
    pub flame: &'a Flame,
    /// The file's flames.
    pub flames: &'a [Flame],
    /// The sequence the timeline plays, if any.
    pub timeline: Option<&'a [Flame]>,
}

/// The file's flames carry times: a flam3 sequence.
pub fn is_sequence(flames: &[Flame]) -> bool {
    flames.len() > 1 && flames.iter().any(|f| f.anim.time != 0.0)
}

impl AnimExportSettings {
    /// The engine's source for these settings.
    pub fn source(&self, s: &Sources) -> Result<Source, String> {
        let src = match self.source {
            SourceKind::Keys => {
                if s.flame.keys.is_empty() {
                    return Err(
                        "the flame has no keys: key a parameter on the timeline first".into(),
                    );
                }
                Source::Keys(s.flame.clone())
            }
            SourceKind::Timeline => match s.timeline {
                Some(cps) => Source::Sequence(cps.to_vec()),
                None => return Err("the timeline plays no sequence".into()),
            },
            SourceKind::FileSequence => {
                if !is_sequence(s.flames) {
                    return Err("the file's flames carry no times: it is no sequence".into());
                }
                Source::Sequence(s.flames.to_vec())
            }
            SourceKind::Rotation => Source::Rotation {
                flame: s.flame.clone(),
                seed: self.seed,
            },
            SourceKind::Interpolation => {
                if s.flames.len() < 2 {
                    return Err("in-betweens need a file with two or more flames".into());
                }
                Source::Interpolation {
                    flames: s.flames.to_vec(),
                    frames: self.total,
                }
            }
        };
        src.check().map_err(|e| e.to_string())?;
        Ok(src)
    }

    /// The frames these settings make, or why they make none.
    pub fn frames(&self) -> Result<Vec<FrameSpec>, String> {
        if self.source.timed() {
            frames_by_time(self.first, self.last, 1.0, "")
        } else {
            if self.first.fract() != 0.0 || self.last.fract() != 0.0 || self.first < 1.0 {
                return Err(format!(
                    "frames {} to {}: whole numbers from 1",
                    self.first, self.last
                ));
            }
            numbered_frames(self.total, self.first as u64, self.last as u64)
        }
        .map_err(|e| e.to_string())
    }

    /// The first and last frame and the total that show the whole of a source.
    pub fn whole(&mut self, src: &Source) {
        if self.source.timed() {
            (self.first, self.last) = src.default_range();
        } else {
            self.first = 1.0;
            self.last = self.total as f64;
        }
    }

    /// Everything that would stop the export, checked before any work.
    pub fn check(&self) -> Result<(), String> {
        if !(MIN_QUALITY..=MAX_QUALITY).contains(&self.quality) {
            return Err(format!(
                "quality {} must be between {MIN_QUALITY} and {MAX_QUALITY}",
                short_num(self.quality)
            ));
        }
        if !(MIN_FPS..=MAX_FPS).contains(&self.fps) {
            return Err(format!(
                "{} frames per second: {MIN_FPS} to {MAX_FPS}",
                self.fps
            ));
        }
        if self.total == 0 || self.total > MAX_FRAMES {
            return Err(format!("{} frames: 1 to {MAX_FRAMES}", self.total));
        }
        if self.output.as_os_str().is_empty() {
            return Err("choose where the frames go".into());
        }
        output_paths(&self.output).map_err(|e| e.to_string())?;
        self.frames().map(|_| ())
    }

    /// The engine's job for these settings (the same one `ugnis animate` runs).
    pub fn job(&self, s: &Sources, threads: usize) -> Result<Job, String> {
        self.check()?;
        let source = self.source(s)?;
        let frames = self.frames()?;
        let (dir, video) = output_paths(&self.output).map_err(|e| e.to_string())?;
        Ok(Job {
            source,
            frames,
            dir,
            video: video.map(|p| {
                (
                    p,
                    VideoOptions {
                        fps: self.fps,
                        ffmpeg: self.ffmpeg.clone(),
                        ..VideoOptions::default()
                    },
                )
            }),
            render: RenderOptions {
                seed: self.seed,
                threads,
                ..RenderOptions::default()
            },
            size: Some((self.width, self.height)),
            quality: Some(self.quality),
            blur: self.blur,
        })
    }

    /// How many of the frames are already in the output folder at this size (a new run
    /// keeps them: resume).
    pub fn frames_on_disk(&self) -> usize {
        let (Ok(frames), Ok((dir, _))) = (self.frames(), output_paths(&self.output)) else {
            return 0;
        };
        frames
            .iter()
            .filter(|f| {
                image::image_dimensions(dir.join(&f.name))
                    .is_ok_and(|d| d == (self.width, self.height))
            })
            .count()
    }

    /// The output is a video that needs ffmpeg.
    pub fn needs_ffmpeg(&self) -> bool {
        matches!(VideoKind::of(&self.output), Some(VideoKind::Ffmpeg(_)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings(source: SourceKind) -> AnimExportSettings {
        AnimExportSettings {
            source,
            first: 0.0,
            last: 2.0,
            total: 90,
            width: 32,
            height: 24,
            lock_aspect: true,
            quality: 5.0,
            blur: true,
            output: std::env::temp_dir().join("ugnis-anim-settings-test"),
            fps: 25.0,
            ffmpeg: "ffmpeg".into(),
            seed: 1,
        }
    }

    #[test]
    fn frames_are_named_as_the_command_line_names_them() {
        let s = settings(SourceKind::Keys);
        let names: Vec<String> = s.frames().unwrap().into_iter().map(|f| f.name).collect();
        assert_eq!(names, ["00000.png", "00001.png", "00002.png"]);
        let mut r = settings(SourceKind::Rotation);
        r.first = 89.0;
        r.last = 90.0;
        let names: Vec<String> = r.frames().unwrap().into_iter().map(|f| f.name).collect();
        assert_eq!(names, ["frame-0089.png", "frame-0090.png"]);
        r.last = 91.0;
        assert!(r.check().is_err(), "past the total");
        let mut q = settings(SourceKind::Keys);
        q.quality = 0.0;
        assert!(q.check().unwrap_err().contains("quality"));
    }

    #[test]
    fn a_flame_without_keys_is_no_keyframe_source() {
        let f = Flame::default();
        let s = Sources {
            flame: &f,
            flames: std::slice::from_ref(&f),
            timeline: None,
        };
        let e = settings(SourceKind::Keys).source(&s).unwrap_err();
        assert!(e.contains("no keys"), "{e}");
        assert!(settings(SourceKind::Timeline).source(&s).is_err());
        assert!(settings(SourceKind::FileSequence).source(&s).is_err());
        assert!(settings(SourceKind::Interpolation).source(&s).is_err());
    }
}
