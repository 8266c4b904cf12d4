//! Export image: size, quality, PNG/BMP; rendered in the background with progress, Stop and
//! Cancel. The render can keep refining past the asked quality until it is stopped, write the
//! picture whenever asked ("Save now"), save its render state beside the picture, and
//! continue a saved render state.
//!
//! Stop takes effect between passes (about a quarter of a second each), so the render is
//! whole and its state can be saved; Cancel stops at once and writes nothing. Every write is
//! atomic, so a file saved before is never lost.
//!
//! The export's settings are in `settings.rs`, the job and what it reports in `job.rs`, a
//! saved state to continue in `resume.rs`, and the two windows (the settings dialog and the
//! running export's window) in `window.rs`.

mod job;
mod resume;
mod settings;
mod window;

pub use job::{ExportJob, JobAction};
pub use resume::{ResumeInfo, quality_text};
pub use settings::ExportSettings;
pub(super) use window::size_fields;
pub use window::{dialog, job_window};
