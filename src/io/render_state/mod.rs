//! Render state files (`.ugnis-state`): a flame render's histogram and everything needed to
//! continue it or merge it with other parts of the same render.
//!
//! Layout (little-endian):
//!
//! ```text
//! "UGNISRS\x1a"                        8-byte magic
//! u32 version                          FORMAT_VERSION
//! u32 n, n bytes                       header: UTF-8 lines "key value", then "flame" and the
//!                                      flame's XML element on the following lines
//! u32 k, k × lane set                  each worker's orbits: 256 × (x, y, z, c as f64, last
//!                                      as u16, consec as u8, step as i32), started as u8,
//!                                      then 256 × own colour as u32, 256 × hidden as u8 and
//!                                      the steps taken as u64
//! u32 m, m × (u32 n, n × f64)          each worker's state of the flame's stateful
//!                                      variations (version 4 on)
//! repeated: "ROWS" u32 row0 u32 rows u64 n, n bytes
//!                                      bucket rows row0.. of the grid: deflate of a bit per
//!                                      bucket (empty or not), then the non-empty buckets'
//!                                      alphas and colours as byte planes (see `compress`)
//! "END\0" u32 chunk count              the end (a truncated file has none)
//! ```
//!
//! The chunks tile the bucket rows in order, so a reader can fetch any band of rows without
//! holding the whole histogram (renders in strips, merges of posters).

use std::io::BufWriter;
use std::path::Path;

use crate::flame::chaos::LANES;
use crate::flame::histogram::Histogram;
use crate::flame::state::RenderState;
use crate::io::diag::{Diagnostic, Pos};
use crate::io::error::WriteError;

mod chunk;
mod read;
mod write;

#[cfg(test)]
mod tests;

pub use read::StateReader;
pub use write::StateWriter;

/// The file's first eight bytes.
pub const MAGIC: &[u8; 8] = b"UGNISRS\x1a";
/// The version this ugnis writes.
/// 4: each worker's state of the stateful (orbit) variations follows the orbits, and the
/// header says the samples skipped after a partial sub-batch ("gap", after "bad_values"): a
/// resumed render of such a flame, or of an extended render, continues the same orbits over
/// the same sub-batches.
/// 3: each orbit's own colour and hide flag, and the steps taken, follow the orbits' other
/// state (a resumed render of a flame JWildfire's renderer draws keeps which points are
/// hidden and when waiting orbits restart).
/// 2: colours in palette units (whole numbers for 8-bit palettes), stored as integers when
/// whole. Version 1 held them in units of 1.0.
pub const FORMAT_VERSION: u32 = 4;
/// The oldest version this ugnis reads: version 2 differs only in its orbits (read with no
/// own colours and no hidden points), versions 2 and 3 in having no variation state and no
/// gap (read as none).
pub const OLDEST_READ_VERSION: u32 = 2;
/// Rows per compressed chunk.
pub const CHUNK_ROWS: usize = 32;
/// Longest header accepted.
const MAX_HEADER: u32 = 64 << 20;
/// Most orbit sets accepted.
const MAX_LANE_SETS: u32 = 4096;
/// Most values of one worker's variation state accepted (8 per stateful variation).
const MAX_VAR_STATE: u32 = 1 << 20;
/// Bytes of one orbit set in version 2.
const LANE_SET_BYTES_V2: usize = LANES * (4 * 8 + 2 + 1 + 4) + 1;
/// Bytes of one orbit set.
const LANE_SET_BYTES: usize = LANE_SET_BYTES_V2 + LANES * (4 + 1) + 8;

fn err(file: &str, pos: Pos, msg: impl Into<String>) -> Diagnostic {
    Diagnostic::error(file, pos, "STATE001", msg)
}

fn io_err(file: &str, e: std::io::Error) -> Diagnostic {
    if e.kind() == std::io::ErrorKind::UnexpectedEof {
        err(
            file,
            Pos::File,
            "the file ends early (truncated: was it still being written?)",
        )
    } else {
        err(file, Pos::File, format!("cannot read: {e}"))
    }
}

/// Check that a state's flame survives the trip through its XML (3-D IFS flames, for one, have
/// no XML form).
pub fn check_saveable(st: &RenderState) -> Result<(), WriteError> {
    if st.flame.ifs3d.is_some() {
        return Err(WriteError::Ifs3dState);
    }
    Ok(())
}

/// Save a whole state atomically.
pub fn save(path: &Path, st: &RenderState, hist: &Histogram) -> std::io::Result<()> {
    crate::io::atomic::write_atomic_with(path, |f| {
        let mut w = StateWriter::new(BufWriter::new(f), st)?;
        w.write_rows(&hist.data)?;
        w.finish()?;
        Ok(())
    })
}
