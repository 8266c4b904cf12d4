//! A saved render state to continue in the Export dialog, as its file describes it, and how
//! qualities are written for people.

use std::path::{Path, PathBuf};

use crate::flame::render::quality_of_samples;
use crate::io::render_state::StateReader;

/// A saved render state to continue, as its file describes it.
#[derive(Clone, Debug, PartialEq)]
pub struct ResumeInfo {
    pub path: PathBuf,
    /// The flame's name (may be empty).
    pub name: String,
    pub width: u32,
    pub height: u32,
    pub supersample: u32,
    /// The quality the saved render was heading for.
    pub quality: f64,
    /// The quality its samples amount to.
    pub quality_done: f64,
    pub samples_done: u64,
}

impl ResumeInfo {
    /// Read the description of a state file. Errors name the file (not a state, another
    /// version, truncated, or parts that must be merged first).
    pub fn open(path: &Path) -> Result<ResumeInfo, String> {
        let rd = StateReader::open(path).map_err(|e| e.to_string())?;
        let st = &rd.state;
        st.continuation()
            .map_err(|e| format!("{}: {e}", path.display()))?;
        let f = &st.flame;
        Ok(ResumeInfo {
            path: path.to_path_buf(),
            name: f.name.clone(),
            width: f.width,
            height: f.height,
            supersample: f.supersample,
            quality: f.quality,
            quality_done: quality_of_samples(f, st.samples_done),
            samples_done: st.samples_done,
        })
    }

    /// One line: file, flame, size and the quality done.
    pub fn summary(&self) -> String {
        let file = self
            .path
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
        let name = if self.name.is_empty() {
            "(unnamed)"
        } else {
            &self.name
        };
        format!(
            "{file}: '{name}', {}×{}, supersample {}, quality done {} of {} ({} samples)",
            self.width,
            self.height,
            self.supersample,
            quality_text(self.quality_done),
            quality_text(self.quality),
            self.samples_done
        )
    }
}

/// A quality for people: whole numbers as they are, others with one decimal.
pub fn quality_text(q: f64) -> String {
    if (q - q.round()).abs() < 1e-9 {
        format!("{q:.0}")
    } else {
        format!("{q:.1}")
    }
}
