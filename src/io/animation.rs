//! Rendering an animation to files, for the command line and the editor alike: the frames of a
//! flam3 sequence (frame t is time t, motion-blurred as flam3-animate does), of a flame's
//! keyframes, of Fraktalai's rotation or of in-betweens through a file's flames — written as
//! numbered PNGs, each saved atomically, and optionally encoded into a video as they come.
//!
//! A run that stops (cancelled, a full disk, a crash) leaves only whole frames; the next run
//! skips the frames already on disk, so long animations resume where they stopped.

use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

use image::DynamicImage;

use crate::flame::animate::{RotationAnimation, interpolate};
use crate::flame::interpolate::{check_times, interpolate_at};
use crate::flame::model::Flame;
use crate::flame::motion_blur::{MotionFrame, frame_from};
use crate::flame::render::{RenderError, RenderOptions, Renderer};
use crate::flame::sequence::MAX_TEMPORAL_SAMPLES;
use crate::io::video::{Video, VideoError, VideoKind, VideoOptions};

/// Most frames one animation may have.
pub const MAX_FRAMES: u64 = 10_000_000;

/// What moves.
#[derive(Clone, Debug, PartialEq)]
pub enum Source {
    /// A flam3 sequence: control points sorted by time; frame t is the flame at time t.
    Sequence(Vec<Flame>),
    /// One flame with keyframes; frame k applies its curves at k.
    Keys(Flame),
    /// Fraktalai's rotation: every triangle turns about its centre, 2° a frame.
    Rotation {
        /// The flame of frame 0, whose triangles turn.
        flame: Flame,
        /// The seed of the turn directions (the same seed, the same animation).
        seed: u64,
    },
    /// In-betweens through the flames in order over `frames` frames (flam3's blend).
    Interpolation {
        /// The flames passed through, at least two: the first is frame 0, the last frame
        /// `frames` − 1.
        flames: Vec<Flame>,
        /// Frames of the animation.
        frames: u64,
    },
}

/// Why an animation could not be rendered.
#[derive(Debug, thiserror::Error)]
pub enum AnimError {
    /// The animation cannot be made as asked (an empty or unordered sequence, too few flames
    /// to interpolate, a bad frame range, too many frames); the message says why.
    #[error("{0}")]
    Settings(String),
    /// A frame's flame could not be rendered (its settings, the memory it needs).
    #[error("frame {frame}: {source}")]
    Render {
        /// The frame's file name.
        frame: String,
        /// Why the renderer refused it.
        source: RenderError,
    },
    /// The folder of frames could not be made, or a frame could not be written or read back.
    #[error("'{path}': {source}")]
    Io {
        /// The folder or frame.
        path: PathBuf,
        /// The system's error.
        source: std::io::Error,
    },
    /// The video could not be written; the frames written so far stay in their folder.
    #[error(
        "{source}\nThe frames written so far are kept in '{frames}'; run the same command again \
         to encode them (frames already on disk are not rendered again)."
    )]
    Video {
        /// What went wrong with the video.
        source: VideoError,
        /// The folder of the frames.
        frames: PathBuf,
    },
    /// The run was cancelled while a frame was rendered; the frames finished before it stay
    /// on disk.
    #[error("interrupted")]
    Interrupted,
}

/// One frame to make: its time (or index) and its file name.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameSpec {
    /// The frame's time: the control points' time for a sequence, the frame number for
    /// keyframes, rotations and in-betweens (sequences and keyframes blend fractional times;
    /// rotations and in-betweens take the whole frame below).
    pub time: f64,
    /// The frame's file name in the job's folder (`00003.png`).
    pub name: String,
}

impl Source {
    /// Checks the source can be animated (a sequence's times strictly increase).
    pub fn check(&self) -> Result<(), AnimError> {
        match self {
            Source::Sequence(cps) => {
                if cps.is_empty() {
                    return Err(AnimError::Settings("the sequence holds no flame".into()));
                }
                check_times(cps).map_err(|i| {
                    AnimError::Settings(format!(
                        "flame {} ('{}') has time {}, but the times of a sequence must be numbers \
                         that increase from flame to flame (the one before has {})",
                        i + 1,
                        cps[i].name,
                        cps[i].anim.time,
                        i.checked_sub(1)
                            .map_or("none".to_string(), |j| cps[j].anim.time.to_string())
                    ))
                })
            }
            Source::Interpolation { flames, .. } if flames.len() < 2 => Err(AnimError::Settings(
                "interpolation needs at least two flames".into(),
            )),
            _ => Ok(()),
        }
    }

    /// The frames flam3-animate makes by default: for a sequence, the whole times from the first
    /// flame's up to one before the last's; for keyframes, frames 0 … frames − 1.
    pub fn default_range(&self) -> (f64, f64) {
        match self {
            Source::Sequence(cps) => {
                let first = cps[0].anim.time.trunc();
                let last = (cps[cps.len() - 1].anim.time.trunc() - 1.0).max(first);
                (first, last)
            }
            Source::Keys(f) => (0.0, f.keys.frames.saturating_sub(1) as f64),
            Source::Rotation { .. } => (0.0, 89.0),
            Source::Interpolation { frames, .. } => (0.0, frames.saturating_sub(1) as f64),
        }
    }

    /// The frame at `time`, with the motion blur its flames ask for (sequences and keyframes;
    /// `blur` false renders the instant only). `adjust` changes every flame before it is used
    /// (size, quality). `cursor` keeps the rotation's state from one frame to the next, so
    /// frames in order cost one step each.
    pub fn frame(
        &self,
        time: f64,
        blur: bool,
        adjust: &(dyn Fn(&mut Flame) + Sync),
        cursor: &mut Cursor,
    ) -> MotionFrame {
        let limit = if blur { MAX_TEMPORAL_SAMPLES } else { 1 };
        let adjusted = |mut f: Flame| {
            adjust(&mut f);
            f
        };
        match self {
            Source::Sequence(cps) => {
                frame_from(time, limit, &cps[0], |t| adjusted(interpolate_at(cps, t)))
            }
            Source::Keys(base) => {
                frame_from(time, limit, base, |t| adjusted(base.keys.apply(base, t)))
            }
            Source::Rotation { flame, seed } => {
                let k = time.max(0.0) as u64;
                let (at, f, anim) = match cursor.rotation.take() {
                    Some(c) if c.0 <= k => c,
                    _ => (0, flame.clone(), RotationAnimation::new(*seed)),
                };
                let (mut f, mut anim) = (f, anim);
                for _ in at..k {
                    anim.step(&mut f);
                }
                cursor.rotation = Some((k, f.clone(), anim));
                still(adjusted(f))
            }
            Source::Interpolation { flames, frames } => {
                let n = *frames;
                let m = flames.len();
                let k = time.max(0.0) as u64;
                let f = if n <= 1 {
                    flames[0].clone()
                } else {
                    let s = k as f64 * (m - 1) as f64 / (n - 1) as f64;
                    let i = (s.floor() as usize).min(m - 2);
                    interpolate(&flames[i], &flames[i + 1], s - i as f64)
                };
                still(adjusted(f))
            }
        }
    }
}

impl Source {
    /// The animation as a flam3 sequence: one flame per frame, its `time` the frame's (or
    /// the frame's index for rotations and in-betweens), carrying the temporal samples and
    /// filter it is blurred with, without ugnis's keyframes — what flam3-animate, Fractorium and
    /// older programs render as the same animation. `adjust` changes every flame (size,
    /// quality).
    pub fn sequence_of(
        &self,
        frames: &[FrameSpec],
        adjust: &(dyn Fn(&mut Flame) + Sync),
    ) -> Vec<Flame> {
        let mut cursor = Cursor::default();
        frames
            .iter()
            .map(|spec| {
                let mut f = self.frame(spec.time, false, adjust, &mut cursor).develop;
                f.anim.time = spec.time;
                f.keys = Default::default();
                f.name = spec.name.trim_end_matches(".png").to_string();
                f
            })
            .collect()
    }
}

/// What [`Source::frame`] keeps between frames.
#[derive(Default)]
pub struct Cursor {
    rotation: Option<(u64, Flame, RotationAnimation)>,
}

/// A frame without motion blur.
fn still(f: Flame) -> MotionFrame {
    frame_from(0.0, 1, &f.clone(), |_| f.clone())
}

/// The frames of times `first` to `last` every `step`, named by the time as flam3-animate names
/// them (`prefix` and five digits: `00003.png`).
pub fn frames_by_time(
    first: f64,
    last: f64,
    step: f64,
    prefix: &str,
) -> Result<Vec<FrameSpec>, AnimError> {
    if !(first.is_finite() && last.is_finite() && step.is_finite() && step > 0.0) {
        return Err(AnimError::Settings(format!(
            "frames {first} to {last} every {step}: expected numbers, the step positive"
        )));
    }
    let count = ((last - first) / step).floor() + 1.0;
    if count < 1.0 {
        return Err(AnimError::Settings(format!(
            "no frame from {first} to {last}"
        )));
    }
    if count > MAX_FRAMES as f64 {
        return Err(AnimError::Settings(format!(
            "{count} frames; an animation has at most {MAX_FRAMES}"
        )));
    }
    Ok((0..count as u64)
        .map(|k| {
            let t = first + k as f64 * step;
            let name = if t.fract() == 0.0 && t >= 0.0 {
                format!("{prefix}{:05}.png", t as i64)
            } else {
                format!("{prefix}{t}.png")
            };
            FrameSpec { time: t, name }
        })
        .collect())
}

/// The frames `first` to `last` (1-based, inclusive) of a numbered animation of `total`
/// frames (rotations, in-betweens): `frame-0001.png` … with at least four digits, frame k at
/// time k − 1. Names depend on `total` only, so parts of one animation rendered apart (an
/// array job, a resumed run) fit together.
pub fn numbered_frames(total: u64, first: u64, last: u64) -> Result<Vec<FrameSpec>, AnimError> {
    if total == 0 || total > MAX_FRAMES {
        return Err(AnimError::Settings(format!(
            "{total} frames: must be between 1 and {MAX_FRAMES}"
        )));
    }
    if first < 1 || first > last || last > total {
        return Err(AnimError::Settings(format!(
            "frames {first} to {last}: expected 1 ≤ first ≤ last ≤ {total}"
        )));
    }
    let digits = total.to_string().len().max(4);
    Ok((first..=last)
        .map(|k| FrameSpec {
            time: (k - 1) as f64,
            name: format!("frame-{k:0digits$}.png"),
        })
        .collect())
}

/// Where an animation written to `out` goes: a video name (.mp4, .webm, .mkv, .mov, .gif,
/// .apng) keeps its frames in the folder `NAME.frames` beside it; anything else is the folder
/// of the frames. Err when `out` is a file that is not a video.
pub fn output_paths(out: &Path) -> Result<(PathBuf, Option<PathBuf>), AnimError> {
    if VideoKind::of(out).is_some() {
        let mut dir = out.as_os_str().to_owned();
        dir.push(".frames");
        return Ok((PathBuf::from(dir), Some(out.to_path_buf())));
    }
    if out.exists() && !out.is_dir() {
        return Err(AnimError::Settings(format!(
            "output '{}' is neither a folder nor a video name (.mp4, .webm, .mkv, .mov, .gif, .apng)",
            out.display()
        )));
    }
    Ok((out.to_path_buf(), None))
}

/// An animation to write.
pub struct Job {
    /// What moves.
    pub source: Source,
    /// The frames to make, in order (see [`frames_by_time`]).
    pub frames: Vec<FrameSpec>,
    /// Where the PNG frames go.
    pub dir: PathBuf,
    /// A video made of the frames, with its settings.
    pub video: Option<(PathBuf, VideoOptions)>,
    /// The renderer's settings (seed, threads, memory limit, output format) for every frame.
    pub render: RenderOptions,
    /// Another picture size for every flame (width and height in pixels), keeping its framing;
    /// `None`: the flames' own.
    pub size: Option<(u32, u32)>,
    /// Another quality (samples per pixel) for every flame; `None`: the flames' own.
    pub quality: Option<f64>,
    /// Motion blur as the flames ask (false: every frame at its instant).
    pub blur: bool,
}

/// How far a job has got.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Progress {
    /// Frames finished (rendered or found on disk).
    pub done: usize,
    /// Frames of the job.
    pub total: usize,
    /// The share of the frame being rendered that is done, in [0, 1].
    pub fraction: f64,
    /// Frames found on disk and not rendered again.
    pub skipped: usize,
}

/// What a finished job did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Summary {
    /// Frames rendered and written.
    pub rendered: usize,
    /// Frames found on disk (of the right size) and not rendered again.
    pub skipped: usize,
    /// The video written, if the job made one.
    pub video: Option<PathBuf>,
    /// Frames found on disk incomplete or damaged (cut short, a checksum wrong) and rendered
    /// again.
    pub damaged: Vec<PathBuf>,
}

impl Summary {
    /// One line for each damaged frame rendered again.
    pub fn notes(&self) -> Vec<String> {
        self.damaged
            .iter()
            .map(|p| {
                format!(
                    "'{}' was incomplete or damaged; rendered again",
                    p.display()
                )
            })
            .collect()
    }
}

/// What is on disk where a frame goes.
#[derive(Debug, PartialEq)]
enum OnDisk {
    /// Nothing (or something that is not a PNG at all).
    Nothing,
    /// A PNG read whole to its end chunk, every checksum right, of this size.
    Whole(u32, u32),
    /// A PNG that breaks off or is damaged.
    Damaged,
}

/// What an earlier run left at `path`: a frame is kept only when it decodes completely.
fn on_disk(path: &Path) -> OnDisk {
    let Ok(f) = std::fs::File::open(path) else {
        return OnDisk::Nothing;
    };
    let Ok(mut r) = png::Decoder::new(std::io::BufReader::new(f)).read_info() else {
        // The signature and header are the first 33 bytes: a file shorter than that, or
        // with a bad header, is damaged if it starts as a PNG does.
        return match std::fs::read(path) {
            Ok(b) if b.starts_with(b"\x89PNG") => OnDisk::Damaged,
            _ => OnDisk::Nothing,
        };
    };
    let Some(n) = r.output_buffer_size() else {
        return OnDisk::Damaged;
    };
    let mut buf = vec![0u8; n];
    if r.next_frame(&mut buf).is_err() || r.finish().is_err() {
        return OnDisk::Damaged;
    }
    OnDisk::Whole(r.info().width, r.info().height)
}

/// The change a job makes to every flame: another size (keeping the framing) and quality.
pub fn adjuster(size: Option<(u32, u32)>, quality: Option<f64>) -> impl Fn(&mut Flame) + Sync {
    move |f: &mut Flame| {
        if let Some((w, h)) = size {
            f.resize_keep_framing(w, h);
        }
        if let Some(q) = quality {
            f.quality = q;
        }
    }
}

impl Job {
    /// The flame adjustments of the job (size and quality).
    fn adjust(&self) -> impl Fn(&mut Flame) + Sync {
        adjuster(self.size, self.quality)
    }

    /// Render every frame not yet on disk, then (or meanwhile) the video. `progress` is called
    /// after each pass of a frame and after each frame.
    pub fn run(
        &self,
        cancel: &AtomicBool,
        mut progress: impl FnMut(Progress),
    ) -> Result<Summary, AnimError> {
        self.source.check()?;
        if self.frames.len() as u64 > MAX_FRAMES {
            return Err(AnimError::Settings(format!(
                "{} frames; an animation has at most {MAX_FRAMES}",
                self.frames.len()
            )));
        }
        std::fs::create_dir_all(&self.dir).map_err(|source| AnimError::Io {
            path: self.dir.clone(),
            source,
        })?;
        let adjust = self.adjust();
        let total = self.frames.len();
        let mut summary = Summary::default();
        let mut video: Option<Video> = None;
        let mut cursor = Cursor::default();
        for (k, spec) in self.frames.iter().enumerate() {
            let path = self.dir.join(&spec.name);
            let frame = self
                .source
                .frame(spec.time, self.blur, &adjust, &mut cursor);
            let (w, h) = (frame.develop.width, frame.develop.height);
            let found = on_disk(&path);
            if found == OnDisk::Damaged {
                summary.damaged.push(path.clone());
            }
            let img = if found == OnDisk::Whole(w, h) {
                summary.skipped += 1;
                let on_disk = image::open(&path).map_err(|e| AnimError::Io {
                    path: path.clone(),
                    source: std::io::Error::other(e),
                });
                // Only needed for the video.
                if self.video.is_some() {
                    Some(on_disk?)
                } else {
                    None
                }
            } else {
                let img = self.render_frame(&frame, spec, cancel, |fraction| {
                    progress(Progress {
                        done: k,
                        total,
                        fraction,
                        skipped: summary.skipped,
                    })
                })?;
                crate::io::save_flame_image(
                    &path,
                    &img,
                    &frame.develop,
                    frame.total_samples(),
                    None,
                )
                .map_err(|source| AnimError::Io {
                    path: path.clone(),
                    source,
                })?;
                summary.rendered += 1;
                Some(img)
            };
            if let (Some((vpath, vopts)), Some(img)) = (&self.video, img) {
                let v = match &mut video {
                    Some(v) => v,
                    None => video.insert(
                        Video::create(vpath, w, h, total as u32, vopts)
                            .map_err(|e| self.video_error(e))?,
                    ),
                };
                let bg = frame
                    .develop
                    .background
                    .map(|c| (c * 255.0).round().clamp(0.0, 255.0) as u8);
                v.push(&img.to_rgba8(), bg)
                    .map_err(|e| self.video_error(e))?;
            }
            progress(Progress {
                done: k + 1,
                total,
                fraction: 1.0,
                skipped: summary.skipped,
            });
        }
        if let Some(v) = video {
            v.finish().map_err(|e| self.video_error(e))?;
            summary.video = self.video.as_ref().map(|(p, _)| p.clone());
        }
        Ok(summary)
    }

    fn video_error(&self, source: VideoError) -> AnimError {
        AnimError::Video {
            source,
            frames: self.dir.clone(),
        }
    }

    fn render_frame(
        &self,
        frame: &MotionFrame,
        spec: &FrameSpec,
        cancel: &AtomicBool,
        progress: impl FnMut(f64),
    ) -> Result<DynamicImage, AnimError> {
        let mut r = Renderer::motion(frame, &self.render).map_err(|source| AnimError::Render {
            frame: spec.name.clone(),
            source,
        })?;
        if !r.run_all(10, cancel, progress) {
            return Err(AnimError::Interrupted);
        }
        Ok(r.finish())
    }
}

#[cfg(test)]
#[path = "animation_tests.rs"]
mod tests;
