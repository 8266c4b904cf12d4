//! Export image: size, quality, PNG/BMP; rendered in the background with progress, Stop and
//! Cancel. The render can keep refining past the asked quality until it is stopped, write the
//! picture whenever asked ("Save now"), save its render state beside the picture, and
//! continue a saved render state.
//!
//! Stop takes effect between passes (about a quarter of a second each), so the render is
//! whole and its state can be saved; Cancel stops at once and writes nothing. Every write is
//! atomic, so a file saved before is never lost.
//!
//! Here the export's settings and what a job reports; the job itself is in `job.rs`, a saved
//! state to continue in `resume.rs`, and the two windows (the settings dialog and the running
//! export's window) in `window.rs`.

mod job;
mod resume;
mod window;

use std::path::{Path, PathBuf};

pub use job::ExportJob;
pub use resume::ResumeInfo;
pub use window::{dialog, job_window};

/// The extension of render state files.
pub const STATE_EXTENSION: &str = "ugnis-state";

/// Where the render state of an exported picture is saved: beside it, `NAME.ugnis-state`.
pub fn state_path(image: &Path) -> PathBuf {
    image.with_extension(STATE_EXTENSION)
}

/// Settings of the export dialog.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportSettings {
    pub width: u32,
    pub height: u32,
    /// Samples per pixel; when continuing a saved state, the samples per pixel to add.
    pub quality: f64,
    pub supersample: u32,
    pub bits16: bool,
    pub transparent: bool,
    pub path: PathBuf,
    /// Width and height keep the flame's proportions.
    pub lock_aspect: bool,
    /// After the quality is reached, go on adding passes until Stop.
    pub refine: bool,
    /// Also write the render state beside the picture ([`state_path`]).
    pub save_state: bool,
    /// Continue this saved state instead of rendering the flame.
    pub resume: Option<ResumeInfo>,
    /// Memory the render may use (`None`: what the system allows); larger exports are
    /// rendered in strips.
    pub memory_limit: Option<u64>,
}

impl ExportSettings {
    /// The state file written with the picture, if any.
    pub fn state_file(&self) -> Option<PathBuf> {
        self.save_state.then(|| state_path(&self.path))
    }
}

/// What a running export has done, for the window and the tests.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct JobStatus {
    /// The histogram of a saved state is being read.
    pub loading: bool,
    /// The quality asked for (with a resumed state: its quality plus the added quality).
    pub asked: f64,
    /// The quality the samples done amount to.
    pub quality_done: f64,
    pub samples_done: u64,
    pub samples_per_second: f64,
    /// The asked quality is reached and the render goes on.
    pub refining: bool,
    /// Pictures written by "Save now".
    pub saves: u32,
    /// The last thing worth telling: a save, a failed save.
    pub note: String,
    /// Rendered in this many strips (0 or 1: the whole image at once); the picture is written
    /// when the last one is done.
    pub strips: usize,
}

/// How a finished export ended.
#[derive(Clone, Debug, PartialEq)]
pub struct Finished {
    pub quality_done: f64,
    pub samples_done: u64,
    /// The state file written, if any.
    pub state: Option<PathBuf>,
    /// Why refining ended by itself (the quality limit), if it did.
    pub limit: Option<String>,
}

/// What the running export's window asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JobAction {
    SaveNow,
    Stop,
    Cancel,
}

/// A quality for people: whole numbers as they are, others with one decimal.
pub fn quality_text(q: f64) -> String {
    if (q - q.round()).abs() < 1e-9 {
        format!("{q:.0}")
    } else {
        format!("{q:.1}")
    }
}
