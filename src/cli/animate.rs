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
    /// Number of frames
    #[arg(long, default_value_t = 90)]
    pub frames: usize,
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

pub fn run(a: AnimateArgs) -> Result<()> {
    if a.frames == 0 || a.frames > 1_000_000 {
        bail!("--frames {} must be between 1 and 1000000", a.frames);
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
    let n_frames = a.frames;
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
    super::check_output(&frame_path(0))?;
    let opts = RenderOptions {
        seed: a.seed,
        threads: super::threads(a.threads),
        ..RenderOptions::default()
    };
    let pb = super::progress_bar(n_frames as u64, "animating");
    for (k, mut f) in frames.enumerate() {
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
