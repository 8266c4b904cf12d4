//! `ugnis dimension`: estimate the fractal dimension of a flame, an IFS or an image by box
//! counting.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::{Args, ValueEnum};

use ugnis::explore::dimension::{
    BoxCount, Ink, MAX_SAMPLES, MIN_SAMPLES, Mask, box_count_flame, box_count_mask,
    box_count_stream,
};
use ugnis::explore::ifs::Ifs;
use ugnis::flame::Affine;
use ugnis::io::{self, FileKind};

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum InkArg {
    /// The class rarer along the image border
    Auto,
    /// Dark pixels (a drawing on paper)
    Dark,
    /// Light pixels (a render on black)
    Light,
}

#[derive(Args, Debug)]
pub struct DimensionArgs {
    /// A flame (.flame/.flam3/.fla/.xml), an IFS (.ifs) or an image (.png/.bmp/.jpg/.gif)
    pub file: PathBuf,
    /// Only the flame or IFS entry with this name (default: every entry)
    #[arg(long)]
    pub name: Option<String>,
    /// Chaos-game points for flames and IFS (100 to 50 000 000)
    #[arg(long, default_value_t = 1_000_000)]
    pub points: u64,
    /// Random seed of the chaos game
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Images: grey level 0–255 separating the set from the background
    #[arg(long, default_value_t = 128)]
    pub threshold: u8,
    /// Images: which side of the threshold is the set
    #[arg(long, value_enum, default_value_t = InkArg::Auto)]
    pub ink: InkArg,
    /// Also print the count of every level (the log-log plot)
    #[arg(long)]
    pub levels: bool,
}

fn report(name: &str, what: &str, b: &BoxCount, levels: bool) {
    match (b.dimension(), b.fit_range, b.fit) {
        (Some(d), Some((k0, k1)), Some(fit)) => println!(
            "{name}: D ≈ {d:.4} (box counting of {} {what}; fit over levels {k0}–{k1}, cells of \
             side 2^-{k0} to 2^-{k1} of the bounding square, r² = {:.5})",
            b.samples, fit.r2
        ),
        _ => println!(
            "{name}: no estimate — fewer than two levels qualify for the fit ({} {what}; \
             use more points or a larger image)",
            b.samples
        ),
    }
    if levels {
        println!("  k   N(2^-k)      ln(1/e)   ln N   fit");
        for l in &b.levels {
            let used = b.fit_range.is_some_and(|(a, z)| (a..=z).contains(&l.k));
            println!(
                "  {:<3} {:<12} {:<9.4} {:<6.3} {}",
                l.k,
                l.count,
                l.ln_inv_size(),
                l.ln_count(),
                if used { "*" } else { "" }
            );
            // Past the fit, stop once the counts no longer grow (every point in its own cell).
            let past = b.fit_range.is_none_or(|(_, z)| l.k > z);
            if past
                && b.levels
                    .get(l.k as usize)
                    .is_none_or(|n| n.count == l.count)
            {
                break;
            }
        }
    }
}

pub fn run(a: DimensionArgs) -> Result<()> {
    if !(MIN_SAMPLES..=MAX_SAMPLES).contains(&a.points) {
        bail!(
            "--points {} must be between {MIN_SAMPLES} and {MAX_SAMPLES}",
            a.points
        );
    }
    let path = &a.file;
    let pick = |n: &str| a.name.as_ref().is_none_or(|w| w.eq_ignore_ascii_case(n));
    match io::kind_of(path) {
        FileKind::Ifs => {
            let p = io::read_ifs(path)?;
            for w in &p.warnings {
                stderr!("{w}");
            }
            let mut any = false;
            for e in p.value.entries.iter().filter(|e| pick(&e.name)) {
                any = true;
                if e.three_d {
                    println!(
                        "{}: skipped (a 3-D entry; box counting works on plane sets)",
                        e.name
                    );
                    continue;
                }
                let maps: Vec<Affine> = e.maps2d();
                let ifs = Ifs::new(&e.name, maps, e.probabilities())
                    .with_context(|| format!("{}: entry '{}'", path.display(), e.name))?;
                let b = box_count_stream(|sink| {
                    let mut g = ifs.chaos_game([0.0, 0.0], 20, a.seed);
                    for _ in 0..a.points {
                        sink(g.next_point());
                    }
                })
                .with_context(|| format!("entry '{}'", e.name))?;
                report(&e.name, "points", &b, a.levels);
                if let Some(s) = ifs.similarity_dimension() {
                    println!(
                        "  similarity dimension {s:.5} (every map is a similarity; exact when \
                         the pieces do not overlap)"
                    );
                }
            }
            if !any {
                bail!(
                    "{}: no entry named '{}'",
                    path.display(),
                    a.name.as_deref().unwrap_or("")
                );
            }
        }
        FileKind::Png | FileKind::Bmp | FileKind::Jpeg | FileKind::Gif => {
            let img = io::image_in::read_rgb(path)?;
            let ink = match a.ink {
                InkArg::Auto => Ink::Auto,
                InkArg::Dark => Ink::Dark,
                InkArg::Light => Ink::Light,
            };
            let mask = Mask::from_image(&image::DynamicImage::ImageRgb8(img), a.threshold, ink);
            let b = box_count_mask(&mask).with_context(|| format!("{}", path.display()))?;
            let name = path
                .file_name()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default();
            report(&name, "set pixels", &b, a.levels);
        }
        FileKind::FlameXml | FileKind::Fla => {
            let p = io::read_flames(path, &Default::default())?;
            for w in &p.warnings {
                stderr!("{w}");
            }
            let mut any = false;
            for (i, f) in p.value.iter().enumerate() {
                let name = if f.name.is_empty() {
                    format!("flame {}", i + 1)
                } else {
                    f.name.clone()
                };
                if !pick(&name) {
                    continue;
                }
                any = true;
                match box_count_flame(f, a.points, a.seed) {
                    Ok(b) => report(&name, "points", &b, a.levels),
                    Err(e) => println!("{name}: skipped ({e})"),
                }
            }
            if !any {
                bail!(
                    "{}: no flame named '{}'",
                    path.display(),
                    a.name.as_deref().unwrap_or("")
                );
            }
        }
        _ => bail!(
            "{}: expected a flame (.flame, .flam3, .fla, .xml), an IFS (.ifs) or an image (.png, .bmp, .jpg, .gif)",
            path.display()
        ),
    }
    Ok(())
}
