//! Errors of the writers: what could not be saved, and why. Readers report a
//! [`Diagnostic`](super::diag::Diagnostic) with a file position instead.

use std::path::PathBuf;

use crate::explore::ExploreError;
use crate::io::ifs::IfsWriteError;

/// Why a file could not be written.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// The file name's extension is not one this kind of data is saved as.
    #[error("{path}: {what} are saved as {expected}")]
    Extension {
        /// The file asked for.
        path: PathBuf,
        /// What was to be saved ("gradients", "flames", …).
        what: &'static str,
        /// The extensions it can be saved as.
        expected: &'static str,
    },
    /// The format holds fewer items than were given.
    #[error("a .{ext} file holds one gradient; {count} given (use .ugr)")]
    OneGradientOnly {
        /// The format's extension, without the dot.
        ext: &'static str,
        /// Number of gradients given.
        count: usize,
    },
    /// A 3-D IFS entry cannot become a flame.
    #[error(
        "'{name}' is a 3-D IFS entry; 3-D IFS entries cannot be represented as flames (save as .ifs)"
    )]
    Ifs3dAsFlame {
        /// The entry's name.
        name: String,
    },
    /// A flame the `.ifs` format cannot hold.
    #[error("'{name}': {reason}")]
    FlameAsIfs {
        /// The flame's name.
        name: String,
        /// What the format cannot hold.
        reason: IfsWriteError,
    },
    /// Entries an `.ifs` file cannot hold.
    #[error(transparent)]
    Ifs(#[from] IfsWriteError),
    /// L-systems an `.l` file cannot hold.
    #[error(transparent)]
    LSystem(#[from] LSystemWriteError),
    /// A drawing that is refused (its size, its number of segments).
    #[error(transparent)]
    Explore(#[from] ExploreError),
    /// The file would be larger than ugnis reads back.
    #[error(
        "{path}: the file would be {mib} MiB, more than ugnis reads ({limit_mib} MiB); save fewer items per file"
    )]
    TooLarge {
        /// The file asked for.
        path: PathBuf,
        /// The size it would have, rounded up.
        mib: u64,
        /// The read limit of its kind.
        limit_mib: u64,
    },
    /// A render state of a 3-D IFS: its maps have no flame XML form.
    #[error(
        "a render state of a 3-D IFS cannot be saved (its maps have no flame XML form); render it in one go"
    )]
    Ifs3dState,
    /// The operating system refused the write.
    #[error("cannot write '{path}': {source}")]
    Io {
        /// The file being written.
        path: PathBuf,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
}

/// Why L-systems cannot be written as a Fractint `.l` file.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LSystemWriteError {
    /// The system does not compile.
    #[error("'{name}' cannot be saved: {reason}")]
    Invalid {
        /// The system's name.
        name: String,
        /// Why it does not compile.
        reason: ExploreError,
    },
    /// Fractint opens the first of two entries with one name.
    #[error("two entries are named '{0}'; Fractint would only find the first")]
    SameName(String),
    /// `.l` angles are 360°/n for n from 3 to 49.
    #[error(
        "'{name}': angle {degrees}° is not 360°/n for an integer n from 3 to 49; .l files cannot hold it"
    )]
    Angle {
        /// The system's name.
        name: String,
        /// Its angle δ in degrees.
        degrees: f64,
    },
    /// Only F and D draw in `.l` files.
    #[error("'{name}': in .l files only F and D draw; '{symbols}' cannot be made to draw")]
    DrawSymbols {
        /// The system's name.
        name: String,
        /// Its draw symbols besides F and D.
        symbols: String,
    },
    /// A system whose `[` also turns (`bracket_turn`) has no `.l` form; the system's name.
    #[error("'{0}': brackets that also turn cannot be written to a .l file")]
    TurningBrackets(String),
    /// The start heading is written as turns of δ.
    #[error("'{name}': the start heading {heading}° is not a multiple of δ = {delta}°")]
    StartHeading {
        /// The system's name.
        name: String,
        /// The start heading in degrees.
        heading: f64,
        /// The angle δ in degrees.
        delta: f64,
    },
}
