//! Errors of the writers: what could not be saved, and why. Readers report a
//! [`Diagnostic`](super::diag::Diagnostic) with a file position instead.

use std::path::PathBuf;

/// Why a file could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// The file name's extension is not one this kind of data is saved as.
    #[error("{path}: {what} are saved as {expected}")]
    Extension {
        path: PathBuf,
        what: &'static str,
        expected: &'static str,
    },
    /// The format holds fewer items than were given.
    #[error("a .{ext} file holds one gradient; {count} given (use .ugr)")]
    OneGradientOnly { ext: &'static str, count: usize },
    /// A 3-D IFS entry cannot become a flame.
    #[error(
        "'{name}' is a 3-D IFS entry; 3-D IFS entries cannot be represented as flames (save as .ifs)"
    )]
    Ifs3dAsFlame { name: String },
    /// The data cannot be expressed in the format (the reason says what).
    #[error("{0}")]
    NotRepresentable(String),
    /// The file would be larger than ugnis reads back (the reason says how large).
    #[error("{0}")]
    TooLarge(String),
    /// The operating system refused the write.
    #[error("cannot write '{path}': {source}")]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
}
