//! `ugnis animate`: frames of the thesis rotation animation, or in-betweens of the flames of a
//! file (flam3-style interpolation), as numbered PNGs.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::{Args, ValueEnum};

use ugnis::flame::Flame;
use ugnis::flame::animate::{RotationAnimation, interpolate};
use ugnis::flame::render::{MAX_QUALITY, MIN_QUALITY, RenderOptions, Renderer, short_num};
use ugnis::io;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Mode {
    /// Every triangle turns about its centre, 2° a frame, in 180° turns (the thesis animation)
    Rotate,
    /// In-betweens through the flames of the file in order (or --from → --to)
    Interpolate,
}

#[derive(Args, Debug)]
pub struct AnimateArgs {
    /// Flame file (.fla, .flame, .flam3, .ifs or a PNG with an embedded flame)
    pub input: PathBuf,
    /// Frames to render: a count N (frames 1..N), or a range A..B (1-based, inclusive) of an
    /// animation of --total frames, e.g. for one task of an array job
    #[arg(long, default_value = "90", value_parser = parse_frames)]
    pub frames: Frames,
    /// Frames of the whole animation, with --frames A..B (file names and in-betweens depend
    /// on it, never on the range)
    #[arg(long)]
    pub total: Option<usize>,
    /// Output directory for frame-0001.png, frame-0002.png, …
    #[arg(short, long)]
    pub output: PathBuf,
    #[arg(long, value_enum, default_value_t = Mode::Rotate)]
    pub mode: Mode,
    /// Rotate: the flame to animate (0-based index; default the first)
    #[arg(long, conflicts_with = "name")]
    pub index: Option<usize>,
    /// Rotate: the flame to animate, by name
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
    /// Seed of the rotation directions and of the renders
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Worker threads (default: all cores; at most 4 per core)
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// flam3-palettes.xml for flames that use palette="N"
    #[arg(long)]
    pub palettes: Option<PathBuf>,
}

/// `--frames`: a count or a 1-based inclusive range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Frames {
    Count(usize),
    Range(usize, usize),
}

/// Most frames of one animation.
pub const MAX_FRAMES: usize = 1_000_000;

fn parse_frames(s: &str) -> Result<Frames, String> {
    let int = |t: &str| -> Result<usize, String> {
        t.trim()
            .parse()
            .map_err(|_| format!("'{t}' is not a whole number"))
    };
    match s.split_once("..") {
        Some((a, b)) => {
            let (a, b) = (int(a)?, int(b.strip_prefix('=').unwrap_or(b))?);
            if a == 0 || b < a {
                return Err(format!(
                    "frame range {s} must be A..B with 1 ≤ A ≤ B (frames are numbered from 1)"
                ));
            }
            Ok(Frames::Range(a, b))
        }
        None => Ok(Frames::Count(int(s)?)),
    }
}

pub fn run(a: AnimateArgs) -> Result<()> {
    let (n_frames, range) = match (a.frames, a.total) {
        (Frames::Count(n), None) => (n, 0..n),
        (Frames::Count(_), Some(_)) => {
            bail!("--total goes with a frame range: --frames A..B --total N")
        }
        (Frames::Range(..), None) => bail!(
            "--frames A..B needs --total N, the frames of the whole animation (frame names and in-betweens depend on it)"
        ),
        (Frames::Range(x, y), Some(t)) => {
            if y > t {
                bail!("--frames {x}..{y} goes past the last frame ({t}) of --total {t}");
            }
            (t, x - 1..y)
        }
    };
    if n_frames == 0 || n_frames > MAX_FRAMES {
        bail!("{n_frames} frames: must be between 1 and {MAX_FRAMES}");
    }
    if let Some(q) = a.quality
        && !(MIN_QUALITY..=MAX_QUALITY).contains(&q)
    {
        bail!(
            "--quality {} must be between {MIN_QUALITY} and {MAX_QUALITY}",
            short_num(q)
        );
    }
    if a.output.exists() && !a.output.is_dir() {
        bail!("output '{}' is not a directory", a.output.display());
    }
    let flames = super::render::load_flames(&a.input, a.palettes.as_ref(), false)?;
    // Frames are made one at a time as they are rendered (a million frames held at once
    // would need gigabytes).
    let frames: Box<dyn Iterator<Item = Flame>> = match a.mode {
        Mode::Rotate => {
            let mut f = super::render::select(flames, a.index, a.name.as_deref(), &a.input)?;
            let mut anim = RotationAnimation::new(a.seed);
            Box::new((0..n_frames).map(move |_| {
                let frame = f.clone();
                anim.step(&mut f);
                frame
            }))
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
            let m = keys.len();
            Box::new((0..n_frames).map(move |k| {
                if n_frames == 1 {
                    return keys[0].clone();
                }
                // As flame::animate::interpolation_frames: key i to i + 1 over equal spans.
                let s = k as f64 * (m - 1) as f64 / (n_frames - 1) as f64;
                let i = (s.floor() as usize).min(m - 2);
                interpolate(&keys[i], &keys[i + 1], s - i as f64)
            }))
        }
    };
    std::fs::create_dir_all(&a.output)
        .with_context(|| format!("cannot create '{}'", a.output.display()))?;
    let digits = n_frames.to_string().len().max(4);
    let frame_path = |k: usize| a.output.join(format!("frame-{:0digits$}.png", k + 1));
    super::check_output(&frame_path(range.start))?;
    let opts = RenderOptions {
        seed: a.seed,
        threads: super::threads(a.threads),
        ..RenderOptions::default()
    };
    let pb = super::progress_bar(range.len() as u64, "animating");
    // Frames before the range are made (cheap: no render) so that the rotation steps are the
    // same as in the whole animation.
    for (k, mut f) in frames.enumerate().take(range.end).skip(range.start) {
        if let Some((w, h)) = a.size {
            f.resize_keep_framing(w, h);
        }
        if let Some(q) = a.quality {
            f.quality = q;
        }
        // Every frame is checked (size, quality, memory) before its buffers are made.
        let mut r =
            Renderer::new(&f, &opts).with_context(|| format!("cannot render frame {}", k + 1))?;
        if !r.run_all(10, super::interrupt_flag(), |_| {}) {
            return Err(super::Interrupted.into());
        }
        let img = r.finish();
        let path = frame_path(k);
        io::png::save(&path, &img, &io::png::PngMeta::for_flame(&f))
            .with_context(|| format!("cannot write '{}'", path.display()))?;
        pb.inc(1);
    }
    pb.finish_and_clear();
    Ok(())
}
