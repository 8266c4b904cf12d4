//! `ugnis render`: render a flame file to PNG or BMP.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::Args;

use ugnis::flame::render::{MAX_QUALITY, MIN_QUALITY, RenderOptions, Renderer, short_num};
use ugnis::flame::{Flame, OutputFormat};
use ugnis::io::flam3_xml::{LibrarySource, ReadOptions};
use ugnis::io::{self, FileKind};

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// Flame file: .fla, .flame, .flam3, .ifs, or a PNG with an embedded flame
    pub input: PathBuf,
    /// Output image (.png or .bmp); default: the input name with .png
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Render the flame with this index (0-based) in a multi-flame file
    #[arg(long, conflicts_with = "name")]
    pub index: Option<usize>,
    /// Render the flame with this name
    #[arg(long)]
    pub name: Option<String>,
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
    let parsed = match io::kind_of(input) {
        FileKind::Ifs => io::ifs_flames(input)?,
        _ => io::read_flames(input, &opts)?,
    };
    for w in &parsed.warnings {
        if strict && w.code == "XML020" {
            bail!("{w} (--strict)");
        }
        eprintln!("{w}");
    }
    Ok(parsed.value)
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

pub fn run(a: RenderArgs) -> Result<()> {
    let out = a
        .output
        .clone()
        .unwrap_or_else(|| a.input.with_extension("png"));
    let is_bmp = io::kind_of(&out) == FileKind::Bmp;
    if !is_bmp && io::kind_of(&out) != FileKind::Png {
        bail!("output '{}' must end in .png or .bmp", out.display());
    }
    if is_bmp && (a.bits16 || a.transparent) {
        bail!("--bits16 and --transparent need PNG output");
    }
    super::check_output(&out)?;
    let flames = load_flames(&a.input, a.palettes.as_ref(), a.strict)?;
    let mut flame = select(flames, a.index, a.name.as_deref(), &a.input)?;
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
    let opts = RenderOptions {
        seed: a.seed,
        threads: super::threads(a.threads),
        memory_limit: None,
        keep_samples: false,
        format: OutputFormat {
            bits16: a.bits16,
            transparent: a.transparent,
        },
    };
    let mut r =
        Renderer::new(&flame, &opts).with_context(|| format!("cannot render '{}'", flame.name))?;
    let pb = super::progress_bar(
        1000,
        &format!(
            "rendering {}",
            if flame.name.is_empty() {
                "flame"
            } else {
                &flame.name
            }
        ),
    );
    let done = r.run_all(100, super::interrupt_flag(), |f| {
        pb.set_position((f * 1000.0) as u64)
    });
    pb.finish_and_clear();
    if !done {
        return Err(super::Interrupted.into());
    }
    let samples = r.samples_done();
    let rate = r.bad_values() as f64 / samples.max(1) as f64;
    let rendered = r.flame().clone();
    let img = r.finish();
    if is_bmp {
        io::bmp::save(&out, &img).with_context(|| format!("cannot write '{}'", out.display()))?;
    } else {
        let mut meta = io::png::PngMeta::for_flame(&rendered);
        meta.samples = Some(samples);
        meta.error_rate = Some(rate);
        io::png::save(&out, &img, &meta)
            .with_context(|| format!("cannot write '{}'", out.display()))?;
    }
    Ok(())
}
