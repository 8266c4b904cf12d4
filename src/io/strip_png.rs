//! Rendering in strips to files: a flame picture larger than memory is made band by band
//! (see [`crate::flame::strips`]), its PNG streamed and its render state written chunk by
//! chunk as each band is done, so neither the picture nor the whole histogram is ever in
//! memory. Both files are written atomically once the last band is in. The command line's
//! `render` and `merge` and the editor's Export use it.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

use image::DynamicImage;

use crate::flame::OutputFormat;
use crate::flame::histogram::Bucket;
use crate::flame::render::Renderer;
use crate::flame::state::RenderState;
use crate::flame::strips::Strip;
use crate::io::atomic::AtomicFile;
use crate::io::png::{PngMeta, PngStream};
use crate::io::render_state::StateWriter;

/// What stopped a render in strips.
#[derive(Debug)]
pub enum StripError {
    /// A file could not be written (nothing of it is left behind).
    Write {
        /// The file.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// A strip's renderer could not be made (the message says why).
    Render(String),
    /// The render was cancelled; nothing was written.
    Cancelled,
    /// A render state is to be saved but a strip's render has none (it was interrupted).
    NoState,
}

impl std::fmt::Display for StripError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            StripError::Write { path, source } => {
                write!(f, "cannot write '{}': {source}", path.display())
            }
            StripError::Render(m) => f.write_str(m),
            StripError::Cancelled => f.write_str("the render was cancelled; nothing was written"),
            StripError::NoState => f.write_str("the render was interrupted; no state to save"),
        }
    }
}

impl std::error::Error for StripError {}

/// The files a render in strips fills band by band: a PNG streamed row band by row band
/// and/or a render state written chunk by chunk. Created before the first band; nothing is
/// visible under their names before [`StripFiles::finish`].
#[derive(Default)]
pub struct StripFiles {
    png: Option<(PathBuf, AtomicFile, PngStream<File>)>,
    state: Option<StateOut>,
}

/// The render state being written: its header goes out with the first rows (or at once when
/// the state is known in advance).
struct StateOut {
    path: PathBuf,
    file: AtomicFile,
    writer: Option<StateWriter<BufWriter<File>>>,
}

/// A write error of `path`.
fn cannot<E: Into<std::io::Error>>(path: &Path) -> impl FnOnce(E) -> StripError + '_ {
    move |e| StripError::Write {
        path: path.to_path_buf(),
        source: e.into(),
    }
}

impl StripFiles {
    /// No files yet: add them with [`StripFiles::with_png`] and [`StripFiles::with_state`].
    pub fn new() -> StripFiles {
        StripFiles::default()
    }

    /// Also stream a `width`×`height` PNG to `path`, with `meta`.
    pub fn with_png(
        mut self,
        path: &Path,
        (width, height): (u32, u32),
        format: OutputFormat,
        meta: &PngMeta,
    ) -> Result<StripFiles, StripError> {
        let mut file = AtomicFile::create(path).map_err(cannot(path))?;
        let out = file.file().try_clone().map_err(cannot(path))?;
        let png = PngStream::new(out, width, height, format, meta).map_err(cannot(path))?;
        self.png = Some((path.to_path_buf(), file, png));
        Ok(self)
    }

    /// Also write the render state to `path`. With `header` its header is written now;
    /// otherwise the first strip's state gives it (every strip iterates the same samples
    /// with the same orbits, so any strip's counters are the whole render's).
    pub fn with_state(
        mut self,
        path: &Path,
        header: Option<&RenderState>,
    ) -> Result<StripFiles, StripError> {
        let mut file = AtomicFile::create(path).map_err(cannot(path))?;
        let writer = match header {
            Some(st) => Some(state_writer(&mut file, path, st)?),
            None => None,
        };
        self.state = Some(StateOut {
            path: path.to_path_buf(),
            file,
            writer,
        });
        Ok(self)
    }

    /// Is a PNG written?
    pub fn has_png(&self) -> bool {
        self.png.is_some()
    }

    /// Is a render state written?
    pub fn has_state(&self) -> bool {
        self.state.is_some()
    }

    /// Append the next band of the picture (no PNG: nothing happens).
    pub fn write_image(&mut self, img: &DynamicImage) -> Result<(), StripError> {
        match &mut self.png {
            Some((path, _, png)) => png.write_rows(img).map_err(cannot(path)),
            None => Ok(()),
        }
    }

    /// Append the next rows of the histogram to the render state, whose header `st` gives
    /// if it is not written yet (no state: nothing happens).
    pub fn write_state(&mut self, st: &RenderState, rows: &[Bucket]) -> Result<(), StripError> {
        let Some(out) = &mut self.state else {
            return Ok(());
        };
        if out.writer.is_none() {
            out.writer = Some(state_writer(&mut out.file, &out.path, st)?);
        }
        match &mut out.writer {
            Some(w) => w.write_rows(rows).map_err(cannot(&out.path)),
            None => Ok(()),
        }
    }

    /// End both files and put them in place: the state first, then the picture.
    pub fn finish(self) -> Result<(), StripError> {
        if let Some(out) = self.state {
            if let Some(w) = out.writer {
                w.finish().map_err(cannot(&out.path))?;
            }
            out.file.commit().map_err(cannot(&out.path))?;
        }
        if let Some((path, file, png)) = self.png {
            png.finish().map_err(cannot(&path))?;
            file.commit().map_err(cannot(&path))?;
        }
        Ok(())
    }
}

/// A state writer on a copy of `file`'s handle, its header written.
fn state_writer(
    file: &mut AtomicFile,
    path: &Path,
    st: &RenderState,
) -> Result<StateWriter<BufWriter<File>>, StripError> {
    let f = file.file().try_clone().map_err(cannot(path))?;
    StateWriter::new(BufWriter::new(f), st).map_err(cannot(path))
}

/// Where a render in strips is, after a pass.
#[derive(Clone, Copy, Debug)]
pub struct StripProgress {
    /// The strip being rendered (from 0).
    pub strip: usize,
    /// Number of strips.
    pub strips: usize,
    /// How much of this strip is done (0 to 1).
    pub strip_fraction: f64,
    /// Samples done by all strips so far (every strip iterates all samples of the render).
    pub samples_done: u64,
}

impl StripProgress {
    /// How much of the whole render is done (0 to 1).
    pub fn fraction(&self) -> f64 {
        (self.strip as f64 + self.strip_fraction) / self.strips.max(1) as f64
    }
}

/// How a render in strips runs: when it reports and what stops it.
pub struct StripHooks<'a> {
    /// Checked between sub-batches: when set, the render ends at once and nothing is written.
    pub cancel: &'a AtomicBool,
    /// Samples in a pass, between two progress reports (`None`: a twentieth of a strip).
    pub pass: Option<u64>,
    /// Told after every pass.
    pub progress: &'a mut dyn FnMut(&StripProgress),
}

/// Render the strips of `plan` into `files` and put the files in place: `renderer` makes
/// each strip's renderer (a fresh render or a continued state, the same settings for every
/// strip). Returns the samples done by all strips.
pub fn render_strips(
    plan: &[Strip],
    mut files: StripFiles,
    mut renderer: impl FnMut(&Strip) -> Result<Renderer, StripError>,
    hooks: StripHooks<'_>,
) -> Result<u64, StripError> {
    let mut samples = 0;
    for (i, strip) in plan.iter().enumerate() {
        let mut r = renderer(strip)?;
        let step = hooks.pass.unwrap_or_else(|| {
            r.total_samples()
                .saturating_sub(r.samples_done())
                .max(1)
                .div_ceil(20)
        });
        while !r.is_done() {
            if !r.run(step, hooks.cancel) {
                return Err(StripError::Cancelled);
            }
            (hooks.progress)(&StripProgress {
                strip: i,
                strips: plan.len(),
                strip_fraction: r.fraction(),
                samples_done: samples + r.samples_done(),
            });
        }
        samples += r.samples_done();
        write_strip(r, strip, &mut files)?;
    }
    files.finish()?;
    Ok(samples)
}

/// Develop a finished strip into the picture and add its core rows to the state.
fn write_strip(r: Renderer, strip: &Strip, files: &mut StripFiles) -> Result<(), StripError> {
    let (row0, bw) = (r.geometry().row0, r.geometry().bw);
    let (img, state) = match (files.has_png(), files.has_state()) {
        (true, true) => {
            let (img, st) = r.finish_with_state();
            (Some(img), Some(st.ok_or(StripError::NoState)?))
        }
        (true, false) => (Some(r.finish()), None),
        (false, true) => (None, Some(r.into_state().ok_or(StripError::NoState)?)),
        (false, false) => (None, None),
    };
    if let Some(img) = img {
        files.write_image(&img)?;
    }
    if let Some((st, hist)) = state {
        let core = &strip.core_rows;
        let (lo, hi) = ((core.start - row0) * bw, (core.end - row0) * bw);
        files.write_state(&st, &hist.data[lo..hi])?;
    }
    Ok(())
}
