//! `ugnis merge`: sum the histograms of saved render parts, then density estimation and tone
//! mapping once.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::Args;

use ugnis::flame::OutputFormat;
use ugnis::flame::RenderState;
use ugnis::flame::render::{RenderOptions, develop_rows, geometry_of};
use ugnis::flame::strips;
use ugnis::io::render_state::StateReader;
use ugnis::io::strip_png::StripFiles;
use ugnis::io::{self, FileKind};

/// Most states one merge reads.
pub const MAX_INPUTS: usize = 10_000;

#[derive(Args, Debug)]
pub struct MergeArgs {
    /// Render states of parts of one render (in any order)
    #[arg(required = true)]
    pub states: Vec<PathBuf>,
    /// Output image (.png; .bmp unless in strips)
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Also save the merged state (to continue it with `render --resume`)
    #[arg(long, value_name = "STATE")]
    pub save_state: Option<PathBuf>,
    /// Develop in K bands (automatic when the image does not fit in memory)
    #[arg(long)]
    pub strips: Option<usize>,
    /// Write 16 bits per channel (PNG only)
    #[arg(long)]
    pub bits16: bool,
    /// Transparent background (PNG only)
    #[arg(long)]
    pub transparent: bool,
    /// Memory the merge may use, e.g. 512M or 2G (default: what the system has available)
    #[arg(long, value_parser = super::parse_bytes)]
    pub memory_limit: Option<u64>,
}

pub fn run(a: MergeArgs) -> Result<()> {
    if a.output.is_none() && a.save_state.is_none() {
        bail!("nothing to write: give -o IMAGE and/or --save-state STATE");
    }
    if a.states.len() > MAX_INPUTS {
        bail!(
            "{} states: at most {MAX_INPUTS} in one merge",
            a.states.len()
        );
    }
    if let Some(o) = &a.output {
        if !matches!(io::kind_of(o), FileKind::Png | FileKind::Bmp) {
            bail!("output '{}' must end in .png or .bmp", o.display());
        }
        if io::kind_of(o) == FileKind::Bmp && (a.bits16 || a.transparent) {
            bail!("--bits16 and --transparent need PNG output");
        }
    }
    let inputs: Vec<&Path> = a.states.iter().map(PathBuf::as_path).collect();
    let outputs: Vec<&Path> = [&a.output, &a.save_state]
        .into_iter()
        .flatten()
        .map(PathBuf::as_path)
        .collect();
    super::check_outputs(&inputs, &outputs)?;
    // The image and the state are put in place together, or neither.
    let held = io::atomic::hold();
    let mut readers = Vec::with_capacity(a.states.len());
    for p in &a.states {
        readers.push(StateReader::open(p)?);
    }
    // Summed in the order of the parts, whatever the order of the files: the sum of floating
    // point numbers depends on its order, the merged picture must not.
    readers.sort_by_key(|r| r.state.parts.first().copied().unwrap_or(0));
    let merged = {
        let states: Vec<&RenderState> = readers.iter().map(|r| &r.state).collect();
        RenderState::merged(&states).map_err(|e| {
            anyhow::anyhow!(
                "{}: {} (compared with {})",
                readers[e.index].file_name(),
                e.message,
                readers[0].file_name()
            )
        })?
    };
    if !merged.is_complete() {
        stderr!(
            "warning: the parts hold {} of {} shares of the samples; the image is noisier than the full render",
            merged.parts.len(),
            merged.part_count
        );
    }
    let flame = merged.flame.clone();
    let format = OutputFormat {
        bits16: a.bits16,
        transparent: a.transparent,
    };
    // Developing needs the summed histogram, the DE accumulator and the image: one thread's
    // render of the same size.
    let opts = RenderOptions {
        threads: 1,
        memory_limit: a.memory_limit,
        save_state: a.save_state.is_some(),
        format,
        ..RenderOptions::default()
    };
    let (k, _) = super::render::choose_strips(&flame, &opts, a.strips, "merging")?;
    let plan = strips::plan(&flame, k)?;
    let geom = geometry_of(&flame)?;
    let density = merged.density();
    let cannot = |p: &std::path::Path| format!("cannot write '{}'", p.display());
    let whole_bmp = a
        .output
        .as_ref()
        .is_some_and(|o| io::kind_of(o) == FileKind::Bmp);
    if whole_bmp && k > 1 {
        bail!("a merge in strips writes PNG only (BMP needs the whole image in memory)");
    }
    let mut files = StripFiles::new();
    if let Some(o) = a.output.as_ref().filter(|_| !whole_bmp) {
        let mut meta = io::png::PngMeta::for_flame(&flame);
        meta.samples = Some(merged.samples_done);
        files = files.with_png(o, (flame.width, flame.height), format, &meta)?;
    }
    if let Some(p) = &a.save_state {
        files = files.with_state(p, Some(&merged))?;
    }
    let pb = super::progress_bar(k as u64, "merging");
    for strip in &plan {
        let rows = if k == 1 {
            0..geom.full_bh
        } else {
            strip.hist_rows.clone()
        };
        let mut sum = readers[0].read_rows(rows.clone())?;
        for r in &mut readers[1..] {
            let h = r.read_rows(rows.clone())?;
            sum.add(&h);
        }
        let core = &strip.core_rows;
        let (lo, hi) = (
            (core.start - rows.start) * geom.bw,
            (core.end - rows.start) * geom.bw,
        );
        files.write_state(&merged, &sum.data[lo..hi])?;
        if let Some(o) = &a.output {
            let g = geom.window(rows.clone());
            let img = develop_rows(&flame, &g, &sum, density, format, strip.out_rows.clone());
            if files.has_png() {
                files.write_image(&img)?;
            } else {
                io::bmp::save(o, &img).with_context(|| cannot(o))?;
            }
        }
        pb.inc(1);
    }
    pb.finish_and_clear();
    files.finish()?;
    Ok(held.commit()?)
}
