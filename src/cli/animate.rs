//! `ugnis animate`: the frames of an animation as PNGs, and a video of them. What moves is
//! decided by the file (`--mode auto`): flames carrying `time` attributes are a flam3 sequence
//! (frame t is time t, motion-blurred as flam3-animate renders it); a flame with keyframes
//! plays them; otherwise Fraktalai's rotation. `--mode loop` makes flam3-genome's loops and
//! transitions through the file's flames; `--mode interpolate` plain in-betweens.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::{Args, ValueEnum};

use ugnis::flame::Flame;
use ugnis::flame::loops::sequence;
use ugnis::flame::render::{MAX_QUALITY, MIN_QUALITY, RenderOptions, short_num};
use ugnis::io::animation::{
    AnimError, FrameSpec, Job, MAX_FRAMES, Source, adjuster, frames_by_time,
};
use ugnis::io::video::{VideoKind, VideoOptions};

use super::animate_sound::{self, SoundArgs};

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Mode {
    /// A sequence if the flames carry times, keyframes if the flame has them, else rotate
    Auto,
    /// flam3 sequence: frame t is the flames' blend at time t, with their motion blur
    Sequence,
    /// The flame's keyframes
    Keys,
    /// Every triangle turns about its centre, 2° a frame, in 180° turns (Fraktalai's animation)
    Rotate,
    /// In-betweens through the flames of the file in order (or --from → --to)
    Interpolate,
    /// flam3-genome's sequence: each flame turns once (--turns) in --loop-frames frames, then
    /// morphs into the next in as many, the last back into the first: a seamless loop
    Loop,
}

#[derive(Args, Debug)]
pub struct AnimateArgs {
    /// Flame file (.fla, .flame, .flam3, .ifs or a PNG with an embedded flame)
    pub input: PathBuf,
    /// Frames to render. Sequences and keyframes: times A..B (whole numbers, inclusive; default
    /// as flam3-animate: from the first flame's time to one before the last's, or the
    /// keyframes' frames). Rotate and interpolate: a count N, or a range A..B (from 1) of an
    /// animation of --total frames, e.g. for one task of an array job
    #[arg(long, value_parser = parse_frames)]
    pub frames: Option<Frames>,
    /// Frames of the whole animation, with --frames A..B in rotate and interpolate modes
    /// (file names and in-betweens depend on it, never on the range)
    #[arg(long)]
    pub total: Option<usize>,
    /// Time between frames of a sequence (flam3-animate's dtime)
    #[arg(long, default_value_t = 1.0, value_parser = super::finite)]
    pub step: f64,
    /// Output: a folder of PNG frames, or a video (.mp4, .webm, .mkv, .mov through ffmpeg;
    /// .gif, .apng built in) whose frames are kept in NAME.frames/, or a flame file (.flam3,
    /// .flame, .fla): the animation as a flam3 sequence, one flame per frame, not rendered
    #[arg(short, long)]
    pub output: PathBuf,
    #[arg(long, value_enum, default_value_t = Mode::Auto)]
    pub mode: Mode,
    /// Prefix of the frame names of sequences and keyframes (flam3-animate's `prefix`)
    #[arg(long, default_value = "")]
    pub prefix: String,
    /// Render every frame at its instant, without the flames' motion blur
    #[arg(long)]
    pub no_blur: bool,
    /// Sub-frames of motion blur per frame (default: the flames' temporal_samples)
    #[arg(long)]
    pub temporal_samples: Option<u32>,
    /// Loop: frames per loop and per transition
    #[arg(long, default_value_t = 100)]
    pub loop_frames: usize,
    /// Loop: whole turns per loop
    #[arg(long, default_value_t = 1.0, value_parser = super::finite)]
    pub turns: f64,
    /// Loop: transitions only, no loops
    #[arg(long)]
    pub no_loops: bool,
    /// Rotate and keys: the flame to animate (0-based index; default the first)
    #[arg(long, conflicts_with = "name")]
    pub index: Option<usize>,
    /// Rotate and keys: the flame to animate, by name
    #[arg(long)]
    pub name: Option<String>,
    /// Interpolate: first flame (0-based index)
    #[arg(long, requires = "to")]
    pub from: Option<usize>,
    /// Interpolate: last flame (0-based index)
    #[arg(long, requires = "from")]
    pub to: Option<usize>,
    /// Frame size WxH (default: the flame's own)
    #[arg(long, value_parser = super::parse_size)]
    pub size: Option<(u32, u32)>,
    /// Samples per pixel (default: the flame's own quality; 0.01 to 1000000)
    #[arg(long, value_parser = super::finite)]
    pub quality: Option<f64>,
    /// Video frames per second (default: the keyframes' fps, else 25)
    #[arg(long, value_parser = super::finite)]
    pub fps: Option<f64>,
    /// A sound file to put in the video (ffmpeg outputs)
    #[arg(long)]
    pub audio: Option<PathBuf>,
    /// Video quality: ffmpeg's constant rate factor (lower is better)
    #[arg(long, default_value_t = 18)]
    pub crf: u32,
    /// Seed of the rotation directions and of the renders
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Worker threads (default: all cores; at most 4 per core)
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// flam3-palettes.xml for flames that use palette="N"
    #[arg(long)]
    pub palettes: Option<PathBuf>,
    #[command(flatten)]
    pub sound: SoundArgs,
}

/// `-o seq.flam3`: the animation written as a flam3 sequence (one flame per frame) instead of
/// rendered.
fn export_sequence(a: &AnimateArgs, source: &Source, frames: &[FrameSpec]) -> Result<()> {
    super::check_outputs(&inputs(a), &[&a.output])?;
    let flames = source.sequence_of(frames, &adjuster(a.size, a.quality));
    let name = a
        .output
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    ugnis::io::write_flames(&a.output, &name, &flames)
        .with_context(|| format!("cannot write '{}'", a.output.display()))?;
    stderr!(
        "{} flames written to '{}' (render them with flam3-animate, Fractorium or ugnis animate)",
        flames.len(),
        a.output.display()
    );
    Ok(())
}

/// `--frames`: a count or an inclusive range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Frames {
    Count(u64),
    Range(f64, f64),
}

fn parse_frames(s: &str) -> Result<Frames, String> {
    let num = |t: &str| -> Result<f64, String> {
        t.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("'{t}' is not a number"))
    };
    match s.split_once("..") {
        Some((a, b)) => {
            let (a, b) = (num(a)?, num(b.strip_prefix('=').unwrap_or(b))?);
            if b < a {
                return Err(format!("frame range {s} must be A..B with A ≤ B"));
            }
            Ok(Frames::Range(a, b))
        }
        None => {
            let n = num(s)?;
            if n < 1.0 || n.fract() != 0.0 || n > MAX_FRAMES as f64 {
                return Err(format!(
                    "{s} frames: must be a whole number between 1 and {MAX_FRAMES}"
                ));
            }
            Ok(Frames::Count(n as u64))
        }
    }
}

/// The files an animation reads.
fn inputs(a: &AnimateArgs) -> Vec<&Path> {
    let mut v = vec![a.input.as_path()];
    v.extend(
        [&a.palettes, &a.sound.sound, &a.audio]
            .into_iter()
            .flatten()
            .map(PathBuf::as_path),
    );
    v
}

/// The mode `auto` stands for.
fn resolve_mode(mode: Mode, flames: &[Flame], picked: &Flame) -> Mode {
    match mode {
        Mode::Auto if flames.len() > 1 && flames.iter().any(|f| f.anim.time != 0.0) => {
            Mode::Sequence
        }
        Mode::Auto if !picked.keys.is_empty() => Mode::Keys,
        Mode::Auto => Mode::Rotate,
        m => m,
    }
}

/// The frames of the rotate and interpolate modes: 1-based names `frame-NNNN.png` of a whole
/// animation of `n` frames, `range` of them rendered.
fn numbered_frames(a: &AnimateArgs) -> Result<(u64, Vec<FrameSpec>)> {
    let (n, range) = match (a.frames, a.total) {
        (None, None) => (90, 1..=90),
        (Some(Frames::Count(n)), None) => (n, 1..=n),
        (None | Some(Frames::Count(_)), Some(_)) => {
            bail!("--total goes with a frame range: --frames A..B --total N")
        }
        (Some(Frames::Range(..)), None) => bail!(
            "--frames A..B needs --total N, the frames of the whole animation (frame names and in-betweens depend on it)"
        ),
        (Some(Frames::Range(x, y)), Some(t)) => {
            let t = t as u64;
            if x < 1.0 || x.fract() != 0.0 || y.fract() != 0.0 {
                bail!("--frames {x}..{y}: frames are whole numbers, numbered from 1");
            }
            if y as u64 > t {
                bail!("--frames {x}..{y} goes past the last frame ({t}) of --total {t}");
            }
            (t, x as u64..=y as u64)
        }
    };
    if n == 0 || n > MAX_FRAMES {
        bail!("{n} frames: must be between 1 and {MAX_FRAMES}");
    }
    let digits = n.to_string().len().max(4);
    Ok((
        n,
        range
            .map(|k| FrameSpec {
                time: (k - 1) as f64,
                name: format!("frame-{k:0digits$}.png"),
            })
            .collect(),
    ))
}

/// The frames of sequences and keyframes: times, named by the time.
fn timed_frames(a: &AnimateArgs, source: &Source) -> Result<Vec<FrameSpec>> {
    if a.total.is_some() {
        bail!(
            "--total is for rotate and interpolate; a sequence's frames are its times (--frames A..B)"
        );
    }
    let (first, last) = match a.frames {
        None => source.default_range(),
        Some(Frames::Range(x, y)) => (x, y),
        Some(Frames::Count(n)) => {
            let (first, _) = source.default_range();
            (first, first + (n - 1) as f64 * a.step)
        }
    };
    Ok(frames_by_time(first, last, a.step, &a.prefix)?)
}

/// Where the frames go, and the video if the output names one.
fn outputs(out: &Path) -> Result<(PathBuf, Option<PathBuf>)> {
    match VideoKind::of(out) {
        Some(_) => {
            let mut dir = out.as_os_str().to_owned();
            dir.push(".frames");
            Ok((PathBuf::from(dir), Some(out.to_path_buf())))
        }
        None => {
            if out.exists() && !out.is_dir() {
                bail!(
                    "output '{}' is neither a folder nor a video name (.mp4, .webm, .mkv, .mov, .gif, .apng)",
                    out.display()
                );
            }
            Ok((out.to_path_buf(), None))
        }
    }
}

/// What moves and the frames to make, by mode.
fn source_of(
    a: &AnimateArgs,
    mode: Mode,
    flames: Vec<Flame>,
    picked: Flame,
) -> Result<(Source, Vec<FrameSpec>)> {
    Ok(match mode {
        Mode::Sequence | Mode::Loop => {
            let cps = if mode == Mode::Loop {
                loop_cps(a, &flames)?
            } else {
                flames
            };
            let source = Source::Sequence(cps);
            source
                .check()
                .map_err(|e| anyhow::anyhow!("{}: {e}", a.input.display()))?;
            let frames = timed_frames(a, &source)?;
            (source, frames)
        }
        Mode::Keys => {
            if picked.keys.is_empty() {
                bail!("{}: the flame has no keyframes", a.input.display());
            }
            let source = Source::Keys(picked.clone());
            let frames = timed_frames(a, &source)?;
            (source, frames)
        }
        Mode::Rotate => {
            let (_, frames) = numbered_frames(a)?;
            (
                Source::Rotation {
                    flame: picked,
                    seed: a.seed,
                },
                frames,
            )
        }
        Mode::Interpolate => {
            let keys = match (a.from, a.to) {
                (Some(i), Some(j)) => {
                    let n = flames.len();
                    let get = |k: usize| {
                        flames.get(k).cloned().with_context(|| {
                            format!(
                                "{}: flame index {k} is out of range (the file holds {n})",
                                a.input.display()
                            )
                        })
                    };
                    vec![get(i)?, get(j)?]
                }
                _ => flames,
            };
            if keys.len() < 2 {
                bail!(
                    "{}: interpolation needs at least two flames in the file",
                    a.input.display()
                );
            }
            let (n, frames) = numbered_frames(a)?;
            (
                Source::Interpolation {
                    flames: keys,
                    frames: n,
                },
                frames,
            )
        }
        Mode::Auto => unreachable!("resolved above"),
    })
}

/// `--mode loop`: flam3-genome's sequence through the flames and back to the first, so that the
/// frame after the last (not rendered: a sequence stops one time before its end) is the first.
fn loop_cps(a: &AnimateArgs, flames: &[Flame]) -> Result<Vec<Flame>> {
    if flames.len() as u64 * 2 * a.loop_frames as u64 > MAX_FRAMES {
        bail!("the loop would have more than {MAX_FRAMES} frames");
    }
    let mut ring = flames.to_vec();
    let n = ring.len();
    if n > 1 {
        ring.push(ring[0].clone());
    }
    let mut cps = sequence(&ring, a.loop_frames, !a.no_loops, a.turns);
    if n > 1 && !a.no_loops {
        // Not the first flame's loop again: its first frame ends the ring.
        cps.truncate(2 * n * a.loop_frames + 1);
    }
    Ok(cps)
}

pub fn run(a: AnimateArgs) -> Result<()> {
    if let Some(q) = a.quality
        && !(MIN_QUALITY..=MAX_QUALITY).contains(&q)
    {
        bail!(
            "--quality {} must be between {MIN_QUALITY} and {MAX_QUALITY}",
            short_num(q)
        );
    }
    if a.loop_frames == 0 || a.loop_frames as u64 > MAX_FRAMES {
        bail!(
            "--loop-frames {} must be between 1 and {MAX_FRAMES}",
            a.loop_frames
        );
    }
    let mut flames = super::render::load_flames(&a.input, a.palettes.as_ref(), false)?;
    if let Some(n) = a.temporal_samples {
        if n == 0 {
            bail!("--temporal-samples must be at least 1");
        }
        for f in &mut flames {
            f.anim.temporal_samples = n;
        }
    }
    let mut picked = super::render::select(flames.clone(), a.index, a.name.as_deref(), &a.input)?;
    if a.sound.sound.is_some() {
        if !matches!(a.mode, Mode::Auto | Mode::Keys) {
            bail!("--sound makes keyframes: use it with --mode keys (or auto)");
        }
        animate_sound::drive(&a.sound, &mut picked, a.fps, &a.input)?;
    }
    let mode = match a.sound.sound {
        Some(_) => Mode::Keys,
        None => resolve_mode(a.mode, &flames, &picked),
    };
    let (source, frames) = source_of(&a, mode, flames, picked)?;
    if matches!(
        ugnis::io::kind_of(&a.output),
        ugnis::io::FileKind::FlameXml | ugnis::io::FileKind::Fla
    ) {
        return export_sequence(&a, &source, &frames);
    }
    let (dir, video) = outputs(&a.output)?;
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create '{}'", dir.display()))?;
    // The frames are checked as the first one and those named as an input (a PNG with an
    // embedded flame may be one): checking a million names would take a while.
    let ins = inputs(&a);
    let names: std::collections::HashSet<_> = ins.iter().filter_map(|p| p.file_name()).collect();
    let frame_paths: Vec<PathBuf> = frames
        .iter()
        .enumerate()
        .filter(|(k, f)| *k == 0 || names.contains(std::ffi::OsStr::new(&f.name)))
        .map(|(_, f)| dir.join(&f.name))
        .collect();
    let mut outs: Vec<&Path> = frame_paths.iter().map(PathBuf::as_path).collect();
    outs.extend(video.as_deref());
    super::check_outputs(&ins, &outs)?;
    let fps = a.fps.unwrap_or(match &source {
        Source::Keys(f) => f.keys.fps,
        _ => 25.0,
    });
    let first_time = frames.first().map_or(0.0, |f| f.time);
    let job = Job {
        source,
        frames,
        dir,
        video: video.map(|p| {
            (
                p,
                VideoOptions {
                    fps,
                    audio: animate_sound::audio(&a.sound, &a.audio),
                    // A sound-driven animation from its middle: the sound from there too.
                    audio_start: match (&a.audio, &a.sound.sound, first_time) {
                        (None, Some(_), t) if t > 0.0 => t / fps,
                        _ => 0.0,
                    },
                    crf: a.crf,
                    ..VideoOptions::default()
                },
            )
        }),
        render: RenderOptions {
            seed: a.seed,
            threads: super::threads(a.threads),
            ..RenderOptions::default()
        },
        size: a.size,
        quality: a.quality,
        blur: !a.no_blur,
    };
    let pb = super::progress_bar(job.frames.len() as u64, "animating");
    let mut long = LongRunNote::new();
    let result = job.run(super::no_cancel(), |p| {
        pb.set_position(p.done as u64);
        if let Some(note) = long.check(&p) {
            pb.note(&note);
        }
    });
    pb.finish_and_clear();
    match result {
        Ok(s) => {
            for note in s.notes() {
                stderr!("{note}");
            }
            if s.skipped > 0 {
                stderr!("{} frames were already on disk and kept", s.skipped);
            }
            Ok(())
        }
        Err(AnimError::Interrupted) => Err(super::stopped_early()),
        Err(e) => Err(anyhow::anyhow!("{}: {e}", a.input.display())),
    }
}

/// An estimate of the whole run once the first frame is rendered, said when the animation will
/// take more than [`LongRunNote::SAID_FROM`] (a million frames are accepted, and take days).
struct LongRunNote {
    start: std::time::Instant,
    said: bool,
}

impl LongRunNote {
    /// Runs estimated to take longer than this are announced.
    const SAID_FROM: std::time::Duration = std::time::Duration::from_secs(3600);

    fn new() -> Self {
        Self {
            start: std::time::Instant::now(),
            said: false,
        }
    }

    /// The note to print after progress `p`, once.
    fn check(&mut self, p: &ugnis::io::animation::Progress) -> Option<String> {
        let rendered = p.done.saturating_sub(p.skipped);
        if self.said || rendered == 0 {
            return None;
        }
        self.said = true;
        let each = self.start.elapsed().as_secs_f64() / rendered as f64;
        let left = each * (p.total - p.done) as f64;
        (left > Self::SAID_FROM.as_secs_f64()).then(|| {
            format!(
                "warning: {} frames at about {} each will take about {}; frames already \
                 written are kept if you stop (Ctrl+C) and skipped when run again",
                p.total,
                duration_text(each),
                duration_text(left)
            )
        })
    }
}

/// "40 ms", "3.2 s", "12 min", "5.4 h", "3.1 days".
fn duration_text(secs: f64) -> String {
    if secs < 1.0 {
        format!("{:.0} ms", secs * 1000.0)
    } else if secs < 60.0 {
        format!("{secs:.1} s")
    } else if secs < 3600.0 {
        format!("{:.0} min", secs / 60.0)
    } else if secs < 48.0 * 3600.0 {
        format!("{:.1} h", secs / 3600.0)
    } else {
        format!("{:.1} days", secs / 86400.0)
    }
}
