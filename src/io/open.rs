//! Opening the files ugnis reads: regular files only (no devices, FIFOs or directories),
//! standard input by name, and a size limit per kind of file read before the bytes are.

use std::path::Path;

use super::{FileKind, kind_of};
use crate::io::diag::{Diagnostic, Pos};

/// Largest file ugnis reads (text formats, images).
pub const MAX_FILE_SIZE: u64 = 64 << 20;
/// Largest flame XML file (.fla, .flame, .flam3, .xml): batches of random flames with many
/// transforms are larger than other files, and writers refuse what readers would refuse.
pub const MAX_FLAME_FILE_SIZE: u64 = 256 << 20;

/// The read limit for a kind of file.
pub fn max_file_size(kind: FileKind) -> u64 {
    match kind {
        FileKind::Fla | FileKind::FlameXml => MAX_FLAME_FILE_SIZE,
        _ => MAX_FILE_SIZE,
    }
}

/// Open a regular file for reading. Devices, FIFOs, sockets and directories are refused
/// before they are opened (a FIFO would block, `/dev/zero` never ends); symlinks are followed.
pub fn open_regular(path: &Path) -> Result<(std::fs::File, std::fs::Metadata), Diagnostic> {
    let name = path.display().to_string();
    let not_regular = |m: &std::fs::Metadata| {
        if m.is_dir() {
            Some("is a directory, not a file")
        } else if !m.is_file() {
            Some(
                "is not a regular file (a device, pipe or socket); \
                 ugnis reads regular files, or standard input given as '-'",
            )
        } else {
            None
        }
    };
    let cannot_open = |e: std::io::Error| {
        Diagnostic::error(&name, Pos::File, "IO001", format!("cannot open: {e}"))
    };
    let meta = std::fs::metadata(path).map_err(cannot_open)?;
    if let Some(m) = not_regular(&meta) {
        return Err(Diagnostic::error(&name, Pos::File, "IO004", m));
    }
    let f = std::fs::File::open(path).map_err(cannot_open)?;
    // The path may have been replaced between the two looks.
    let meta = f.metadata().map_err(cannot_open)?;
    if let Some(m) = not_regular(&meta) {
        return Err(Diagnostic::error(&name, Pos::File, "IO004", m));
    }
    Ok((f, meta))
}

/// True for the names that mean standard input: `-` and `/dev/stdin`.
pub fn is_stdin(path: &Path) -> bool {
    path.as_os_str() == "-" || path == Path::new("/dev/stdin")
}

/// Read a file into memory, refusing files over the size limit of its kind.
pub fn read_bytes(path: &Path) -> Result<Vec<u8>, Diagnostic> {
    read_bytes_limited(path, max_file_size(kind_of(path)))
}

/// Read at most `limit` bytes of a regular file (see [`open_regular`]) or of standard input
/// (`-`). The limit is enforced while reading, so a file that grows is cut off too.
pub fn read_bytes_limited(path: &Path, limit: u64) -> Result<Vec<u8>, Diagnostic> {
    let name = path.display().to_string();
    if is_stdin(path) {
        read_limited(std::io::stdin().lock(), None, limit, &name)
    } else {
        let (f, meta) = open_regular(path)?;
        read_limited(f, Some(meta.len()), limit, &name)
    }
}

/// Read at most `limit` bytes from `r`, whose length is `len` when known (a longer file is
/// refused before anything is read).
pub(super) fn read_limited(
    r: impl std::io::Read,
    len: Option<u64>,
    limit: u64,
    name: &str,
) -> Result<Vec<u8>, Diagnostic> {
    use std::io::Read;
    let too_big = |size: Option<u64>| {
        Diagnostic::error(
            name,
            Pos::File,
            "IO002",
            match size {
                Some(n) => format!(
                    "file is {} MiB; the limit is {} MiB",
                    n.div_ceil(1 << 20),
                    limit >> 20
                ),
                None => format!(
                    "more than {} MiB; the limit is {} MiB",
                    limit >> 20,
                    limit >> 20
                ),
            },
        )
    };
    let mut out = Vec::new();
    if let Some(n) = len {
        if n > limit {
            return Err(too_big(Some(n)));
        }
        out.reserve(n as usize);
    }
    r.take(limit + 1)
        .read_to_end(&mut out)
        .map_err(|e| Diagnostic::error(name, Pos::File, "IO001", format!("cannot read: {e}")))?;
    if out.len() as u64 > limit {
        return Err(too_big(None));
    }
    Ok(out)
}
