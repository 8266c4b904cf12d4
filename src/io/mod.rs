//! Readers and writers of every file format ugnis opens or saves. Parsers report errors with
//! file, line and column (formats.md §1) and never panic.

pub mod atomic;
pub mod bmp;
pub mod diag;
pub mod flam3_xml;
pub mod palettes;
pub mod png;
pub mod xml;

use std::path::Path;

use crate::flame::model::Flame;
use crate::io::diag::{Diagnostic, Parsed, Pos};

/// Largest file ugnis reads (formats.md §1).
pub const MAX_FILE_SIZE: u64 = 64 << 20;

/// Read a file into memory, refusing files over the size limit.
pub fn read_bytes(path: &Path) -> Result<Vec<u8>, Diagnostic> {
    let name = path.display().to_string();
    let meta = std::fs::metadata(path)
        .map_err(|e| Diagnostic::error(&name, Pos::File, "IO001", format!("cannot open: {e}")))?;
    if meta.is_dir() {
        return Err(Diagnostic::error(
            &name,
            Pos::File,
            "IO001",
            "is a directory, not a file",
        ));
    }
    if meta.len() > MAX_FILE_SIZE {
        return Err(Diagnostic::error(
            &name,
            Pos::File,
            "IO002",
            format!(
                "file is {} MiB; the limit is {} MiB",
                meta.len() >> 20,
                MAX_FILE_SIZE >> 20
            ),
        ));
    }
    std::fs::read(path)
        .map_err(|e| Diagnostic::error(&name, Pos::File, "IO001", format!("cannot read: {e}")))
}

/// File kinds ugnis opens, by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    /// flam3/Apophysis/ugnis XML: .flame, .flam3, .fla, .xml
    FlameXml,
    /// ugnis native .fla (validated more strictly)
    Fla,
    Png,
    Ifs,
    Ugr,
    Map,
    Bmp,
    Unknown,
}

pub fn kind_of(path: &Path) -> FileKind {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    match ext.as_str() {
        "flame" | "flam3" | "xml" | "flames" => FileKind::FlameXml,
        "fla" => FileKind::Fla,
        "png" => FileKind::Png,
        "ifs" => FileKind::Ifs,
        "ugr" | "gradient" => FileKind::Ugr,
        "map" => FileKind::Map,
        "bmp" => FileKind::Bmp,
        _ => FileKind::Unknown,
    }
}

/// Read the flames of any flame source: XML (.flame/.flam3/.fla), PNG with an embedded flame.
pub fn read_flames(
    path: &Path,
    opts: &flam3_xml::ReadOptions,
) -> Result<Parsed<Vec<Flame>>, Diagnostic> {
    let name = path.display().to_string();
    let bytes = read_bytes(path)?;
    let mut o = opts.clone();
    o.file = name.clone();
    let text = match kind_of(path) {
        FileKind::Png => png::read_genome(&bytes, &name)?,
        kind => {
            o.fla = kind == FileKind::Fla;
            if bytes.starts_with(b"\x89PNG") {
                png::read_genome(&bytes, &name)?
            } else {
                String::from_utf8(bytes).map_err(|e| {
                    Diagnostic::error(
                        &name,
                        Pos::Byte(e.utf8_error().valid_up_to() as u64),
                        "XML001",
                        "file is not valid UTF-8 text",
                    )
                })?
            }
        }
    };
    let p = flam3_xml::read(&text, &o)?;
    Ok(Parsed {
        value: p.value.flames,
        warnings: p.warnings,
    })
}

/// Read a Fractint `.ifs` file as flames (one per 2-D entry).
pub fn ifs_flames(path: &Path) -> Result<Parsed<Vec<Flame>>, Diagnostic> {
    Err(Diagnostic::error(
        &path.display().to_string(),
        Pos::File,
        "IFS000",
        "reading .ifs files is not implemented yet",
    ))
}
