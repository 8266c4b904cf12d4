//! `ugnis random`: a batch of random flames into one `.fla`, with thumbnails.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use anyhow::{Context, Result, bail};
use clap::Args;
use rayon::prelude::*;

use ugnis::flame::random::{self, RandomOptions, SymmetryMode, VariationMode};
use ugnis::flame::render::{MAX_QUALITY, MIN_QUALITY, RenderOptions, Renderer, estimate_memory};
use ugnis::flame::{Flame, NewFlame, variations};
use ugnis::io;

#[derive(Args, Debug)]
pub struct RandomArgs {
    /// How many flames
    #[arg(long, default_value_t = 100)]
    pub count: usize,
    /// Output .fla (or .flame)
    #[arg(short, long, default_value = "random.fla")]
    pub output: PathBuf,
    /// Master seed; the same seed and options give the same batch (default: from the clock)
    #[arg(long)]
    pub seed: Option<u64>,
    /// Fewest transforms per flame
    #[arg(long, default_value_t = 2)]
    pub min_xforms: usize,
    /// Most transforms per flame
    #[arg(long, default_value_t = 6)]
    pub max_xforms: usize,
    /// A variation name for every transform, "random" (one of the seven variations of Fraktalai per
    /// transform) or "mix" (2–3 of all variations per transform)
    #[arg(long, default_value = "random")]
    pub variation: String,
    /// The variations random flames may use, comma separated (NAME, pre_NAME or post_NAME):
    /// every transform gets one or two of them (replaces --variation)
    #[arg(long, value_delimiter = ',')]
    pub variations: Vec<String>,
    /// Symmetry order: N ≥ 2 rotational, −N rotational and mirror, −1 mirror, or "random"
    #[arg(long, allow_hyphen_values = true)]
    pub symmetry: Option<String>,
    /// Write a PNG thumbnail of every flame (with the flame embedded) into this directory
    #[arg(long)]
    pub thumbs: Option<PathBuf>,
    /// Thumbnail size WxH
    #[arg(long, value_parser = super::parse_size, default_value = "128x128")]
    pub size: (u32, u32),
    /// Thumbnail quality (samples per pixel)
    #[arg(long, default_value_t = 50.0, value_parser = super::finite)]
    pub quality: f64,
    /// Worker threads (default: all cores; at most 4 per core)
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
}

/// Parse the --variation argument.
pub fn variation_mode(s: &str) -> Result<VariationMode> {
    Ok(match s.trim().to_ascii_lowercase().as_str() {
        "random" => VariationMode::default(),
        "mix" => VariationMode::Mix,
        name => match variations::by_name(name) {
            Some(id) => VariationMode::Single(id),
            None => bail!(
                "unknown variation '{s}': give a flam3 variation name (e.g. swirl), 'random' or 'mix'"
            ),
        },
    })
}

/// Parse the --variations list: every name must be a variation (NAME, pre_NAME, post_NAME).
pub fn variation_list(names: &[String]) -> Result<VariationMode> {
    let mut list = Vec::new();
    let mut unknown = Vec::new();
    for n in names.iter().map(|n| n.trim()).filter(|n| !n.is_empty()) {
        match variations::parse_name(n) {
            Some(e) => list.push(e),
            None => unknown.push(n.to_string()),
        }
    }
    if !unknown.is_empty() {
        bail!(
            "--variations: unknown variation name(s) {}; give names such as julia, pre_blur or post_mirror_wf",
            unknown.join(", ")
        );
    }
    if list.is_empty() {
        bail!("--variations needs at least one variation name");
    }
    if list.len() > 5000 {
        bail!("--variations: {} names; at most 5000", list.len());
    }
    Ok(VariationMode::FromList(list))
}

/// Parse the --symmetry argument.
pub fn symmetry_mode(s: Option<&str>) -> Result<SymmetryMode> {
    match s.map(str::trim) {
        None => Ok(SymmetryMode::None),
        Some(r) if r.eq_ignore_ascii_case("random") => Ok(SymmetryMode::Random),
        Some(n) => match n.parse::<i32>() {
            Ok(k) if (-100..=100).contains(&k) => Ok(SymmetryMode::Order(k)),
            _ => bail!("--symmetry '{n}' must be an order between -100 and 100, or 'random'"),
        },
    }
}

/// Bytes of a written random flame: the header and palette, each transform (one variation,
/// or a mix of two or three with their parameters) and each symmetry transform; the means of
/// batches of 200, rounded up.
const FLAME_BYTES: u64 = 2_600;
const XFORM_BYTES: u64 = 240;
const MIX_XFORM_BYTES: u64 = 360;
const SYMMETRY_XFORM_BYTES: u64 = 170;

/// The expected size of a batch's file.
fn batch_bytes(count: usize, opts: &RandomOptions) -> u64 {
    let xforms = (opts.min_xforms + opts.max_xforms) as u64 / 2;
    let per_xform = if opts.variations == VariationMode::Mix {
        MIX_XFORM_BYTES
    } else {
        XFORM_BYTES
    };
    let symmetry = match opts.symmetry {
        SymmetryMode::None => 0,
        SymmetryMode::Random => 3,
        SymmetryMode::Order(k) => k.unsigned_abs() as u64,
    };
    count as u64 * (FLAME_BYTES + xforms * per_xform + symmetry * SYMMETRY_XFORM_BYTES)
}

pub fn run(a: RandomArgs) -> Result<()> {
    let opts = options(&a)?;
    let seed = a.seed.unwrap_or_else(|| {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(1, |d| d.as_nanos() as u64)
    });
    let threads = super::threads(a.threads);
    let thumbs: Vec<PathBuf> = match &a.thumbs {
        Some(dir) => {
            std::fs::create_dir_all(dir)
                .with_context(|| format!("cannot create '{}'", dir.display()))?;
            check_thumbnail_memory(&a, threads)?;
            (0..a.count)
                .map(|i| dir.join(format!("{}.png", flame_name(i, a.count))))
                .collect()
        }
        None => Vec::new(),
    };
    let mut outputs = vec![a.output.as_path()];
    outputs.extend(thumbs.iter().map(PathBuf::as_path));
    super::check_outputs(&[], &outputs)?;
    // The batch and its thumbnails are put in place together: a batch that fails leaves
    // no thumbnail behind.
    let held = io::atomic::hold();
    let pool = super::pool_of(threads)?;
    let work = a.count as u64 * if a.thumbs.is_some() { 2 } else { 1 };
    let pb = super::progress_bar(work, "random flames");
    let (flames, passed) = generate(&pool, &a, &opts, seed, &pb)?;
    if let Some(dir) = &a.thumbs {
        thumbnails(&pool, &a, dir, &flames, &pb)?;
    }
    pb.finish_and_clear();
    let name = a
        .output
        .file_stem()
        .map_or_else(|| "random".into(), |s| s.to_string_lossy().into_owned());
    io::write_flames(&a.output, &name, &flames)
        .with_context(|| format!("cannot write '{}'", a.output.display()))?;
    held.commit()?;
    if a.count > 1 {
        super::print_stdout(&format!(
            "wrote {} flames to {} (seed {seed}; {passed} passed the quality check){}\n",
            a.count,
            a.output.display(),
            a.thumbs
                .as_ref()
                .map(|d| format!("; thumbnails in {}", d.display()))
                .unwrap_or_default()
        ))?;
    }
    Ok(())
}

/// Check the arguments and make the options of the batch's flames. The batch must be
/// readable again: what would exceed the read limit is refused at once (the writer checks
/// the exact size again).
fn options(a: &RandomArgs) -> Result<RandomOptions> {
    let max_count = ugnis::io::flam3_xml::MAX_FLAMES;
    if a.count == 0 || a.count > max_count {
        bail!(
            "--count {} must be between 1 and {max_count} (the most flames ugnis reads from one file)",
            a.count
        );
    }
    if a.min_xforms < 1 || a.min_xforms > a.max_xforms || a.max_xforms > 100 {
        bail!(
            "--min-xforms {} and --max-xforms {} need 1 ≤ min ≤ max ≤ 100",
            a.min_xforms,
            a.max_xforms
        );
    }
    if !(MIN_QUALITY..=MAX_QUALITY).contains(&a.quality) {
        bail!(
            "--quality {} must be between {MIN_QUALITY} and {MAX_QUALITY}",
            a.quality
        );
    }
    let kind = io::kind_of(&a.output);
    match kind {
        io::FileKind::FlameXml | io::FileKind::Fla => {}
        _ => bail!("output '{}' must end in .fla or .flame", a.output.display()),
    }
    let opts = RandomOptions {
        min_xforms: a.min_xforms,
        max_xforms: a.max_xforms,
        variations: if a.variations.is_empty() {
            variation_mode(&a.variation)?
        } else if a.variation != "random" {
            bail!("give either --variation or --variations, not both");
        } else {
            variation_list(&a.variations)?
        },
        symmetry: symmetry_mode(a.symmetry.as_deref())?,
        ..RandomOptions::default()
    };
    let bytes = batch_bytes(a.count, &opts);
    let limit = io::max_file_size(kind);
    if bytes > limit {
        bail!(
            "{} flames of {}–{} transforms would make a file of about {} MiB, more than ugnis \
             reads ({} MiB); use fewer flames (--count) or transforms, in several files",
            a.count,
            a.min_xforms,
            a.max_xforms,
            bytes >> 20,
            limit >> 20
        );
    }
    Ok(opts)
}

/// Thumbnails render in parallel, one single-threaded render per worker: refuse at once
/// when that many at once do not fit in memory.
fn check_thumbnail_memory(a: &RandomArgs, threads: usize) -> Result<()> {
    let (tw, th) = a.size;
    let probe = ugnis::flame::Flame {
        width: tw,
        height: th,
        quality: a.quality,
        ..NewFlame::default().flame()
    };
    let ro = RenderOptions {
        threads: 1,
        ..RenderOptions::default()
    };
    let one = estimate_memory(&probe, &ro);
    ugnis::memory::check(
        one.total.saturating_mul(threads as u64),
        None,
        || format!("{threads} thumbnails of {tw}×{th} rendered at once"),
        || "use a smaller --size or fewer --threads".into(),
    )?;
    Ok(())
}

/// The batch's flames, named random-001…, and how many passed the quality check.
fn generate(
    pool: &rayon::ThreadPool,
    a: &RandomArgs,
    opts: &RandomOptions,
    seed: u64,
    pb: &super::Progress,
) -> Result<(Vec<Flame>, u64)> {
    let defaults = NewFlame::default();
    let passed = AtomicU64::new(0);
    let mut flames: Vec<Flame> = pool.install(|| {
        (0..a.count)
            .into_par_iter()
            .map(|i| {
                let g = random::generate(random::batch_seed(seed, i), opts, &defaults);
                if g.passed {
                    passed.fetch_add(1, Ordering::Relaxed);
                }
                pb.inc(1);
                g.flame
            })
            .collect()
    });
    for (i, f) in flames.iter_mut().enumerate() {
        f.name = flame_name(i, a.count);
    }
    Ok((flames, passed.load(Ordering::Relaxed)))
}

/// The name of flame `i` (from 0) of a batch of `count`: random-001…
fn flame_name(i: usize, count: usize) -> String {
    let width = count.to_string().len().max(3);
    format!("random-{:0width$}", i + 1)
}

/// A PNG thumbnail of every flame (with the flame embedded) in `dir`, rendered in parallel.
fn thumbnails(
    pool: &rayon::ThreadPool,
    a: &RandomArgs,
    dir: &Path,
    flames: &[Flame],
    pb: &super::Progress,
) -> Result<()> {
    let (tw, th) = a.size;
    let results: Vec<Result<()>> = pool.install(|| {
        flames
            .par_iter()
            .map(|f| {
                let mut t = f.clone();
                t.resize_keep_framing(tw, th);
                t.quality = a.quality;
                let ro = RenderOptions {
                    seed: 1,
                    threads: 1,
                    ..RenderOptions::default()
                };
                let mut r = Renderer::new(&t, &ro)
                    .with_context(|| format!("cannot render '{}'", f.name))?;
                if !r.run_all(1, super::no_cancel(), |_| {}) {
                    return Err(super::stopped_early());
                }
                let img = r.finish();
                let path = dir.join(format!("{}.png", f.name));
                io::png::save(&path, &img, &io::png::PngMeta::for_flame(f))
                    .with_context(|| format!("cannot write '{}'", path.display()))?;
                pb.inc(1);
                Ok(())
            })
            .collect()
    });
    results.into_iter().collect::<Result<Vec<()>>>()?;
    Ok(())
}
