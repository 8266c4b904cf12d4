//! `ugnis render`: render a flame file to PNG or BMP.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::Args;

use ugnis::flame::Part;
use ugnis::flame::render::{MAX_QUALITY, MIN_QUALITY, Plan, RenderOptions, Renderer, short_num};
use ugnis::flame::strips::{self, Strip};
use ugnis::flame::{Flame, OutputFormat};
use ugnis::io::flam3_xml::{LibrarySource, ReadOptions};
use ugnis::io::render_state::StateReader;
use ugnis::io::strip_png::{StripError, StripFiles, StripHooks, StripProgress, render_strips};
use ugnis::io::{self, FileKind};

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// Flame file: .fla, .flame, .flam3, .ifs, or a PNG with an embedded flame
    #[arg(required_unless_present = "resume", conflicts_with = "resume")]
    pub input: Option<PathBuf>,
    /// Output image (.png or .bmp); default: the input name with .png
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Render the flame with this index (0-based) in a multi-flame file
    #[arg(long, conflicts_with = "name")]
    pub index: Option<usize>,
    /// Render the flame with this name
    #[arg(long)]
    pub name: Option<String>,
    /// Apply a flam3 template's render settings (size, quality, filter, oversampling,
    /// background, density estimator …) as flam3-genome's `template=` does; --size,
    /// --quality and --supersample still win
    #[arg(long, value_name = "TEMPLATE", conflicts_with = "resume")]
    pub template: Option<PathBuf>,
    /// Image size WxH (keeps the framing: pixels per unit scale with the width)
    #[arg(long, value_parser = super::parse_size)]
    pub size: Option<(u32, u32)>,
    /// Samples per pixel (default: the flame's own quality; 0.01 to 1000000)
    #[arg(long, value_parser = super::finite)]
    pub quality: Option<f64>,
    /// Supersampling factor (default: the flame's own)
    #[arg(long)]
    pub supersample: Option<u32>,
    /// Random seed; the same flame, seed and thread count give the same image
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Worker threads (default: all cores; at most 4 per core)
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Write 16 bits per channel (PNG only)
    #[arg(long)]
    pub bits16: bool,
    /// Transparent background (PNG only)
    #[arg(long)]
    pub transparent: bool,
    /// Treat variations ugnis cannot render as an error
    #[arg(long)]
    pub strict: bool,
    /// flam3-palettes.xml for flames that use palette="N"
    #[arg(long)]
    pub palettes: Option<PathBuf>,
    /// Also save the render state (histogram, orbits, settings) to continue or merge it later
    #[arg(long, value_name = "STATE")]
    pub save_state: Option<PathBuf>,
    /// Continue a saved render state (instead of a flame file); see --add-quality
    #[arg(long, value_name = "STATE")]
    pub resume: Option<PathBuf>,
    /// With --resume: samples per pixel to add (0: develop the state as it is)
    #[arg(long, requires = "resume", value_parser = super::finite, default_value_t = 0.0)]
    pub add_quality: f64,
    /// Render share I of N of the samples (0-based, e.g. 2/4), with its own random streams;
    /// save it with --save-state and sum the parts with `ugnis merge`
    #[arg(long, value_parser = parse_part, conflicts_with = "resume")]
    pub part: Option<Part>,
    /// Render the image in K bands (posters larger than memory); automatic when the render
    /// does not fit in memory
    #[arg(long)]
    pub strips: Option<usize>,
    /// Memory the render may use, e.g. 512M or 2G (default: what the system has available)
    #[arg(long, value_parser = super::parse_bytes)]
    pub memory_limit: Option<u64>,
}

/// Parse "I/N".
pub fn parse_part(s: &str) -> Result<Part, String> {
    let (i, n) = s
        .split_once('/')
        .ok_or_else(|| format!("part '{s}' must be I/N, e.g. 0/4 (parts are numbered from 0)"))?;
    let p = Part {
        index: i
            .trim()
            .parse()
            .map_err(|_| format!("part index '{i}' is not a whole number"))?,
        count: n
            .trim()
            .parse()
            .map_err(|_| format!("part count '{n}' is not a whole number"))?,
    };
    p.validate()?;
    Ok(p)
}

/// Load the flames of an input file, printing warnings to stderr (or failing with --strict).
pub fn load_flames(input: &Path, palettes: Option<&PathBuf>, strict: bool) -> Result<Vec<Flame>> {
    let opts = ReadOptions {
        library: match palettes {
            Some(p) => LibrarySource::Paths(vec![p.clone()]),
            None => LibrarySource::Search,
        },
        ..ReadOptions::default()
    };
    let parsed = super::read_flame_file(input, &opts)?;
    for w in &parsed.warnings {
        if strict && w.code == "XML020" {
            bail!("{w} (--strict)");
        }
        stderr!("{w}");
    }
    Ok(parsed.value.flames)
}

/// Pick one flame by --index or --name (default: the first).
pub fn select(
    flames: Vec<Flame>,
    index: Option<usize>,
    name: Option<&str>,
    input: &Path,
) -> Result<Flame> {
    let n = flames.len();
    if let Some(name) = name {
        return flames
            .into_iter()
            .find(|f| f.name == name)
            .with_context(|| format!("{}: no flame named '{name}'", input.display()));
    }
    let i = index.unwrap_or(0);
    flames.into_iter().nth(i).with_context(|| {
        format!(
            "{}: flame index {i} is out of range (the file holds {n})",
            input.display()
        )
    })
}

/// Where the samples come from: a fresh render or a saved state to continue.
enum Source {
    Fresh(Box<Flame>, Part),
    Resume(Box<StateReader>, f64),
}

impl Source {
    /// A renderer for the whole image or one strip.
    fn renderer(&mut self, opts: &RenderOptions, strip: Option<Strip>) -> Result<Renderer> {
        match self {
            Source::Fresh(f, part) => Renderer::with_plan(f, opts, &Plan { part: *part, strip })
                .with_context(|| format!("cannot render '{}'", f.name)),
            Source::Resume(rd, add) => rd.renderer(*add, opts, strip).map_err(anyhow::Error::msg),
        }
    }

    /// The flame as it will be rendered (framed, at its final quality).
    fn flame(&self) -> Flame {
        match self {
            Source::Fresh(f, _) => {
                let mut f = (**f).clone();
                if !f.has_camera {
                    ugnis::flame::apply_auto_frame(&mut f);
                }
                f
            }
            Source::Resume(rd, add) => {
                let mut f = rd.state.flame.clone();
                f.quality += add;
                f
            }
        }
    }
}

/// How many strips: the asked number, or the fewest that fit in memory (1 when all fits),
/// with the options to render them with (for a chosen number, the budget it was chosen for:
/// see [`strips::Fit::options`]).
pub fn choose_strips(
    flame: &Flame,
    opts: &RenderOptions,
    asked: Option<usize>,
    what: &str,
) -> Result<(usize, RenderOptions)> {
    // Strips would draw a solid flame as a density flame: refused rather than drawn otherwise.
    let solid_in_strips = |k: usize| -> Result<()> {
        if k > 1 && flame.draws_solid() {
            bail!(
                "{what}: a flame JWildfire draws solid (sld_render_enabled) cannot be rendered in {k} strips; render it whole (a larger --memory-limit or a smaller size)"
            );
        }
        Ok(())
    };
    if let Some(k) = asked {
        solid_in_strips(k)?;
        strips::plan(flame, k)?;
        return Ok((k, opts.clone()));
    }
    let fit = strips::fit(flame, opts)?;
    solid_in_strips(fit.strips)?;
    if fit.strips > 1 {
        stderr!(
            "{what}: {}: rendering in {} strips (each iterates all the samples again)",
            fit.describe(),
            fit.strips
        );
    }
    Ok((fit.strips, fit.options(opts)))
}

pub fn run(a: RenderArgs) -> Result<()> {
    let default_out = a
        .input
        .as_ref()
        .or(a.resume.as_ref())
        .map(|p| p.with_extension("png"));
    // A part alone is a share of the samples: its image is written only when asked for.
    let is_part = a.part.is_some_and(|p| p.count > 1);
    let out = match (&a.output, is_part) {
        (Some(o), _) => Some(o.clone()),
        (None, true) => None,
        (None, false) => default_out,
    };
    if is_part && a.save_state.is_none() {
        bail!("--part renders a share of the samples: save it with --save-state to merge it");
    }
    if let Some(out) = &out {
        let is_bmp = io::kind_of(out) == FileKind::Bmp;
        if !is_bmp && io::kind_of(out) != FileKind::Png {
            bail!("output '{}' must end in .png or .bmp", out.display());
        }
        if is_bmp && (a.bits16 || a.transparent) {
            bail!("--bits16 and --transparent need PNG output");
        }
    }
    let inputs = [&a.input, &a.resume, &a.template, &a.palettes];
    let inputs: Vec<&Path> = inputs.into_iter().flatten().map(PathBuf::as_path).collect();
    let outputs: Vec<&Path> = [out.as_deref(), a.save_state.as_deref()]
        .into_iter()
        .flatten()
        .collect();
    super::check_outputs(&inputs, &outputs)?;
    let mut source = if let Some(state) = &a.resume {
        if a.size.is_some() || a.quality.is_some() || a.supersample.is_some() {
            bail!(
                "--size, --quality and --supersample belong to the saved render; use --add-quality to continue it"
            );
        }
        let rd = StateReader::open(state)?;
        Source::Resume(Box::new(rd), a.add_quality)
    } else {
        let input = a.input.as_ref().context("no flame file given")?;
        let flames = load_flames(input, a.palettes.as_ref(), a.strict)?;
        // A JWildfire flame shows its motion curves at its frame.
        let mut flame = select(flames, a.index, a.name.as_deref(), input)?.at_jwildfire_frame();
        if let Some(t) = &a.template {
            let t = io::read_template_file(t, &ReadOptions::default())?;
            for w in &t.warnings {
                stderr!("{w}");
            }
            t.value.apply(&mut flame);
        }
        if let Some((w, h)) = a.size {
            flame.resize_keep_framing(w, h);
        }
        if let Some(q) = a.quality {
            if !(MIN_QUALITY..=MAX_QUALITY).contains(&q) {
                bail!(
                    "--quality {} must be between {MIN_QUALITY} and {MAX_QUALITY}",
                    short_num(q)
                );
            }
            flame.quality = q;
        }
        if let Some(s) = a.supersample {
            flame.supersample = s;
        }
        if a.save_state.is_some() && flame.ifs3d.is_some() {
            bail!(
                "a render state of a 3-D IFS cannot be saved (its maps have no flame XML form); render it in one go"
            );
        }
        if a.save_state.is_some() && flame.draws_solid() {
            bail!(
                "a render state of a flame JWildfire draws solid (sld_render_enabled) cannot be saved (its depth buffers are kept in memory only); render it in one go"
            );
        }
        Source::Fresh(Box::new(flame), a.part.unwrap_or_default())
    };
    let opts = RenderOptions {
        seed: match &source {
            Source::Resume(rd, _) => rd.state.seed,
            Source::Fresh(..) => a.seed,
        },
        threads: super::threads(a.threads),
        memory_limit: a.memory_limit,
        keep_samples: false,
        save_state: a.save_state.is_some(),
        format: OutputFormat {
            bits16: a.bits16,
            transparent: a.transparent,
        },
    };
    let flame = source.flame();
    let label = if flame.name.is_empty() {
        "flame".to_string()
    } else {
        flame.name.clone()
    };
    // Settings errors (size, quality…) first, with their own message.
    ugnis::flame::render::validate_settings(&flame)
        .with_context(|| format!("cannot render '{}'", flame.name))?;
    let (k, opts) = choose_strips(&flame, &opts, a.strips, &format!("rendering {label}"))?;
    // The image and the state are put in place together, or neither.
    let held = io::atomic::hold();
    if k == 1 {
        run_whole(&a, &mut source, &opts, out.as_deref(), &label)?;
    } else {
        run_strips(&a, &mut source, &opts, out.as_deref(), &label, k)?;
    }
    Ok(held.commit()?)
}

fn run_whole(
    a: &RenderArgs,
    source: &mut Source,
    opts: &RenderOptions,
    out: Option<&Path>,
    label: &str,
) -> Result<()> {
    let mut r = source.renderer(opts, None)?;
    let pb = super::progress_bar(1000, &format!("rendering {label}"));
    let done = r.run_all(100, super::no_cancel(), |f| {
        pb.set_position((f * 1000.0) as u64)
    });
    pb.finish_and_clear();
    if !done {
        return Err(super::stopped_early());
    }
    let samples = r.samples_done();
    let rate = r.bad_values() as f64 / samples.max(1) as f64;
    let rendered = r.flame().clone();
    let (img, state) = if out.is_some() {
        let (img, st) = r.finish_with_state();
        (Some(img), st)
    } else {
        (None, r.into_state())
    };
    if let Some(path) = &a.save_state {
        let (st, hist) = state.context("the render was interrupted; no state to save")?;
        io::render_state::save(path, &st, &hist)
            .with_context(|| format!("cannot write '{}'", path.display()))?;
    }
    if let (Some(out), Some(img)) = (out, img) {
        io::save_flame_image(out, &img, &rendered, samples, Some(rate))
            .with_context(|| format!("cannot write '{}'", out.display()))?;
    }
    Ok(())
}

/// Render band by band ([`io::strip_png`]): the PNG is streamed and the state written chunk
/// by chunk, so neither the image nor the whole histogram is ever in memory.
fn run_strips(
    a: &RenderArgs,
    source: &mut Source,
    opts: &RenderOptions,
    out: Option<&Path>,
    label: &str,
    k: usize,
) -> Result<()> {
    let flame = source.flame();
    let plan = strips::plan(&flame, k)?;
    if out.is_some_and(|o| io::kind_of(o) == FileKind::Bmp) {
        bail!("a render in strips writes PNG only (BMP needs the whole image in memory)");
    }
    let mut files = StripFiles::new();
    if let Some(o) = out {
        let meta = io::png::PngMeta::for_flame(&flame);
        files = files.with_png(o, (flame.width, flame.height), opts.format, &meta)?;
    }
    if let Some(p) = &a.save_state {
        files = files.with_state(p, None)?;
    }
    let pb = super::progress_bar(
        (k * 1000) as u64,
        &format!("rendering {label} in {k} strips"),
    );
    let mut report =
        |p: &StripProgress| pb.set_position(((p.strip as f64 + p.strip_fraction) * 1000.0) as u64);
    let renderer = |strip: &Strip| {
        source
            .renderer(opts, Some(strip.clone()))
            .map_err(|e| StripError::Render(format!("{e:#}")))
    };
    let hooks = StripHooks {
        cancel: super::no_cancel(),
        pass: None,
        progress: &mut report,
    };
    let done = render_strips(&plan, files, renderer, hooks);
    pb.finish_and_clear();
    match done {
        Ok(_) => Ok(()),
        Err(StripError::Cancelled) => Err(super::stopped_early()),
        Err(e) => Err(e.into()),
    }
}
