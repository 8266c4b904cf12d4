//! The Export dialog's settings: size, quality, file, refining, the render state beside the
//! picture, a saved state to continue and the memory limit.

use std::path::{Path, PathBuf};

use super::resume::ResumeInfo;

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
