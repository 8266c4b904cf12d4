//! `ugnis thumbnail IN OUT SIZE`: a small PNG picture of a file, for the freedesktop
//! thumbnailer (`contrib/desktop/ugnis.thumbnailer`) that lets file managers show flames as
//! their pictures.
//!
//! Made for being run on any file a file manager hands over, many at once: the picture is at
//! most SIZE pixels on its longer side (at most 1024), rendered in a fixed time budget (the
//! samples that fit in it, exposed for what was done), on at most two threads, from files of
//! at most 32 MB; any failure — an unreadable file, a flame that cannot render, even a bug —
//! is an error message and exit status 1 (the file manager then shows its icon), never a
//! panic. Flames (.flame, .flam3, .fla, .ifs, a PNG with a flame) show their first flame;
//! gradient lists (.ugr, .map, .ggr) their first gradients as bands; escape-time views (.esc)
//! their picture.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use clap::Args;
use image::{DynamicImage, RgbImage};
use ugnis::flame::render::{RenderOptions, Renderer};
use ugnis::io::{self, View};

/// Largest thumbnail side.
const MAX_SIZE: u32 = 1024;
/// Largest input file.
const MAX_INPUT_BYTES: u64 = 32 << 20;
/// Time for iterating a flame (the rest of the process — start, reading, writing — takes a few
/// tens of milliseconds more).
const FLAME_BUDGET: Duration = Duration::from_millis(150);
/// Time for an escape-time view's coarse-to-fine passes.
const ESCAPE_BUDGET: Duration = Duration::from_millis(200);
/// Samples per pixel a flame thumbnail aims at (fewer when the budget runs out first).
const FLAME_QUALITY: f64 = 40.0;
/// Most gradients shown in a gradient list's thumbnail.
const MAX_BANDS: usize = 8;

#[derive(Args, Debug)]
pub struct ThumbnailArgs {
    /// The file to picture: a flame, IFS, gradient or escape-time view file
    pub input: PathBuf,
    /// The PNG to write (whatever its name ends in)
    pub output: PathBuf,
    /// Longest side in pixels (1 to 1024), as the file manager asks
    #[arg(default_value_t = 256)]
    pub size: u32,
}

pub fn run(a: ThumbnailArgs) -> Result<()> {
    if !(1..=MAX_SIZE).contains(&a.size) {
        bail!("size {} must be between 1 and {MAX_SIZE} pixels", a.size);
    }
    let len = std::fs::metadata(&a.input)
        .with_context(|| format!("cannot read '{}'", a.input.display()))?
        .len();
    if len > MAX_INPUT_BYTES {
        bail!(
            "'{}' is {} MB: thumbnails are made of files up to {} MB",
            a.input.display(),
            len >> 20,
            MAX_INPUT_BYTES >> 20
        );
    }
    super::check_outputs(&[&a.input], &[&a.output])?;
    // A bug must not crash a file manager's helper with a backtrace: it becomes the error.
    let (input, size) = (a.input.clone(), a.size);
    let img = std::panic::catch_unwind(move || picture(&input, size))
        .unwrap_or_else(|_| bail!("internal error while picturing '{}'", a.input.display()))?;
    io::png::save(&a.output, &img, &Default::default())
        .with_context(|| format!("cannot write '{}'", a.output.display()))
}

/// The picture of `path`, at most `size` pixels on its longer side.
fn picture(path: &Path, size: u32) -> Result<DynamicImage> {
    let pool = super::pool_of(2.min(ugnis::threads::max_threads()).max(1))?;
    match io::view_of(io::kind_of(path)) {
        View::Flame => pool.install(|| flame_picture(path, size)),
        View::Gradients => gradient_picture(path, size),
        View::Escape => pool.install(|| escape_picture(path, size)),
        _ => bail!(
            "'{}' is {}: thumbnails are made of flame, IFS, gradient and escape-time files",
            path.display(),
            io::kind_of(path).describe()
        ),
    }
}

/// `w`×`h` scaled so that the longer side is `size` (at least 1×1).
fn fit(w: u32, h: u32, size: u32) -> (u32, u32) {
    let (w, h) = (w.max(1) as f64, h.max(1) as f64);
    let k = size as f64 / w.max(h);
    (
        ((w * k).round() as u32).clamp(1, size),
        ((h * k).round() as u32).clamp(1, size),
    )
}

/// The file's first flame, iterated for the time budget.
fn flame_picture(path: &Path, size: u32) -> Result<DynamicImage> {
    let mut f = io::read_flames(path, &Default::default())
        .map_err(|e| anyhow::anyhow!("{e}"))?
        .value
        .into_iter()
        .next()
        .with_context(|| format!("'{}' holds no flame", path.display()))?;
    let (w, h) = fit(f.width, f.height, size);
    f.resize_keep_framing(w, h);
    f.supersample = 1;
    f.quality = FLAME_QUALITY;
    let opts = RenderOptions {
        seed: 1,
        threads: 2,
        ..RenderOptions::default()
    };
    let mut r = Renderer::new(&f, &opts).map_err(|e| anyhow::anyhow!("{e}"))?;
    let start = Instant::now();
    let never = AtomicBool::new(false);
    // Passes of a twentieth of the samples until done or out of time (exposure follows the
    // samples done, so a cut-short render is as bright as a finished one).
    let step = (r.total_samples() / 20).max(1);
    while !r.is_done() && start.elapsed() < FLAME_BUDGET {
        r.run(step, &never);
    }
    Ok(r.preview())
}

/// The first gradients of a gradient file as horizontal bands.
fn gradient_picture(path: &Path, size: u32) -> Result<DynamicImage> {
    let gs = io::read_gradients(path)
        .map_err(|e| anyhow::anyhow!("{e}"))?
        .value;
    if gs.is_empty() {
        bail!("'{}' holds no gradient", path.display());
    }
    let bands = gs.len().min(MAX_BANDS) as u32;
    let (w, h) = (size, (size / 2).max(bands));
    let img = RgbImage::from_fn(w, h, |x, y| {
        let g = &gs[((y * bands / h) as usize).min(gs.len() - 1)];
        let i = (x as usize * g.colors.len() / w as usize).min(g.colors.len() - 1);
        image::Rgb(g.rgb8(i))
    });
    Ok(DynamicImage::ImageRgb8(img))
}

/// An escape-time view, coarse to fine for the time budget.
fn escape_picture(path: &Path, size: u32) -> Result<DynamicImage> {
    let doc = io::escape_view::read(path)
        .map_err(|e| anyhow::anyhow!("{e}"))?
        .value;
    let (w, h) = fit(doc.width, doc.height, size);
    let mut r = ugnis::escape::EscapeRenderer::new(&doc.params, doc.view, w, h)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    // A timer stops a pass that would overrun; the picture is that of the passes done.
    let stop = std::sync::Arc::new(AtomicBool::new(false));
    let s = stop.clone();
    std::thread::spawn(move || {
        std::thread::sleep(ESCAPE_BUDGET);
        s.store(true, Ordering::Relaxed);
    });
    while !r.is_done() && r.run_pass(&stop) {}
    if r.fraction() == 0.0 {
        bail!(
            "'{}': not even a coarse picture within the time budget",
            path.display()
        );
    }
    Ok(DynamicImage::ImageRgb8(r.image()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_fit_the_longer_side() {
        assert_eq!(fit(640, 480, 256), (256, 192));
        assert_eq!(fit(480, 640, 256), (192, 256));
        assert_eq!(fit(10_000, 1, 128), (128, 1));
        assert_eq!(fit(0, 0, 64), (64, 64));
    }
}
