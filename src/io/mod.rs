//! Readers and writers of every file format ugnis opens or saves. Parsers report errors with
//! file, line and column and never panic.

pub mod atomic;
pub mod bmp;
pub mod diag;
pub mod error;
pub mod escape_view;
pub mod flam3_xml;
mod fractint_text;
pub mod ggr;
pub mod ifs;
pub mod image_in;
pub mod lsystem;
pub mod map;
pub mod palettes;
pub mod png;
pub mod render_state;
pub mod scene;
pub mod svg;
pub mod ugr;
pub mod xml;

use std::path::Path;

use crate::flame::model::Flame;
use crate::io::diag::{Diagnostic, Parsed, Pos};
pub use crate::io::error::WriteError;

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
    use std::io::Read;
    let name = path.display().to_string();
    let too_big = |size: Option<u64>| {
        Diagnostic::error(
            &name,
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
    let read_err = |e: std::io::Error| {
        Diagnostic::error(&name, Pos::File, "IO001", format!("cannot read: {e}"))
    };
    let mut out = Vec::new();
    if is_stdin(path) {
        std::io::stdin()
            .lock()
            .take(limit + 1)
            .read_to_end(&mut out)
            .map_err(read_err)?;
    } else {
        let (f, meta) = open_regular(path)?;
        if meta.len() > limit {
            return Err(too_big(Some(meta.len())));
        }
        out.reserve(meta.len() as usize);
        f.take(limit + 1).read_to_end(&mut out).map_err(read_err)?;
    }
    if out.len() as u64 > limit {
        return Err(too_big(None));
    }
    Ok(out)
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
    /// GIMP gradient (.ggr)
    Ggr,
    Bmp,
    Jpeg,
    Gif,
    /// ugnis escape-time view (.esc)
    EscapeView,
    /// Fractint L-system (.l)
    LSystem,
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
        "ggr" => FileKind::Ggr,
        "bmp" => FileKind::Bmp,
        "jpg" | "jpeg" => FileKind::Jpeg,
        "gif" => FileKind::Gif,
        "esc" => FileKind::EscapeView,
        "l" => FileKind::LSystem,
        _ => FileKind::Unknown,
    }
}

/// Read the flames of any flame source: XML (.flame/.flam3/.fla), PNG with an embedded flame.
pub fn read_flames(
    path: &Path,
    opts: &flam3_xml::ReadOptions,
) -> Result<Parsed<Vec<Flame>>, Diagnostic> {
    let p = read_flame_file(path, opts)?;
    Ok(Parsed {
        value: p.value.flames,
        warnings: p.warnings,
    })
}

/// As [`read_flames`], keeping the document's `<flames name>`.
pub fn read_flame_file(
    path: &Path,
    opts: &flam3_xml::ReadOptions,
) -> Result<Parsed<flam3_xml::FlameFile>, Diagnostic> {
    let name = path.display().to_string();
    let kind = kind_of(path);
    if kind == FileKind::LSystem {
        return Err(Diagnostic::error(
            &name,
            Pos::File,
            "IO005",
            "a Fractint L-system file (.l), not a flame; L-systems open in the L-system view",
        ));
    }
    let mut o = opts.clone();
    o.file = name.clone();
    o.fla = kind == FileKind::Fla;
    let text = if kind == FileKind::Png || (!is_stdin(path) && starts_with_png(path)?) {
        // Streamed: a PNG of any size opens as long as the genome precedes the image data.
        o.fla = false;
        if is_stdin(path) {
            png::read_genome(&read_bytes(path)?, &name)?
        } else {
            let (f, _) = open_regular(path)?;
            png::read_genome_from(std::io::BufReader::new(f), &name)?
        }
    } else {
        let bytes = read_bytes(path)?;
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
    };
    flam3_xml::read(&text, &o)
}

/// Does a regular file start with the PNG signature?
fn starts_with_png(path: &Path) -> Result<bool, Diagnostic> {
    use std::io::Read;
    let (f, _) = open_regular(path)?;
    let mut head = [0u8; 4];
    let n = f.take(4).read(&mut head).unwrap_or(0);
    Ok(n == 4 && &head == b"\x89PNG")
}

/// Read a Fractint `.ifs` file (UTF-8, or Windows-1252 with a warning).
pub fn read_ifs(path: &Path) -> Result<Parsed<ifs::IfsFile>, Diagnostic> {
    let name = path.display().to_string();
    let bytes = read_bytes(path)?;
    let (text, w) = diag::decode_text(&bytes, &name);
    let mut p = ifs::parse(&text, &name)?;
    p.warnings.extend(w);
    Ok(p)
}

/// Read a Fractint `.ifs` file as flames, one per entry (3-D entries through the fixed view).
pub fn ifs_flames(path: &Path) -> Result<Parsed<Vec<Flame>>, Diagnostic> {
    ifs_flames_with(path, &crate::flame::NewFlame::default())
}

/// As [`ifs_flames`], with the display settings and gradient for the new flames.
pub fn ifs_flames_with(
    path: &Path,
    defaults: &crate::flame::NewFlame,
) -> Result<Parsed<Vec<Flame>>, Diagnostic> {
    let p = read_ifs(path)?;
    Ok(Parsed {
        value: p
            .value
            .entries
            .iter()
            .map(|e| ifs::entry_to_flame(e, defaults))
            .collect(),
        warnings: p.warnings,
    })
}

/// Read a Fractint L-system file (`.l`; UTF-8, or Windows-1252 with a warning).
pub fn read_lsystems(path: &Path) -> Result<Parsed<lsystem::LFile>, Diagnostic> {
    let name = path.display().to_string();
    let bytes = read_bytes(path)?;
    let (text, w) = diag::decode_text(&bytes, &name);
    let mut p = lsystem::parse(&text, &name)?;
    p.warnings.extend(w);
    Ok(p)
}

/// Write L-systems atomically as a Fractint `.l` file.
pub fn write_lsystems(
    path: &Path,
    systems: &[crate::explore::lsystem::LSystem],
) -> Result<(), WriteError> {
    let text = lsystem::write(systems)?;
    atomic::write_atomic(path, text.as_bytes()).map_err(|source| WriteError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Read the gradients of a gradient file (.ugr: several; .map, .ggr: one) or make one from an
/// image.
pub fn read_gradients(path: &Path) -> Result<Parsed<Vec<crate::gradient::Gradient>>, Diagnostic> {
    let name = path.display().to_string();
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    match kind_of(path) {
        FileKind::Ugr => {
            let bytes = read_bytes(path)?;
            let (text, w) = diag::decode_text(&bytes, &name);
            let mut p = ugr::parse(&text, &name)?;
            p.warnings.extend(w);
            Ok(p)
        }
        FileKind::Map => {
            let bytes = read_bytes(path)?;
            if bytes.contains(&0) {
                let off = bytes.iter().position(|&b| b == 0).unwrap_or(0);
                return Err(Diagnostic::error(
                    &name,
                    Pos::Byte(off as u64),
                    "MAP003",
                    "binary content (NUL bytes); not a text .map palette",
                ));
            }
            let (text, w) = diag::decode_text(&bytes, &name);
            let p = map::parse(&text, &name, &stem)?;
            Ok(Parsed {
                value: vec![p.value],
                warnings: p.warnings.into_iter().chain(w).collect(),
            })
        }
        FileKind::Ggr => {
            let bytes = read_bytes(path)?;
            let (text, w) = diag::decode_text(&bytes, &name);
            let p = ggr::parse(&text, &name, &stem)?;
            Ok(Parsed {
                value: vec![p.value],
                warnings: p.warnings.into_iter().chain(w).collect(),
            })
        }
        FileKind::Png | FileKind::Bmp | FileKind::Jpeg | FileKind::Gif => Ok(Parsed {
            value: vec![image_in::gradient_from_image(path, 1)?],
            warnings: Vec::new(),
        }),
        _ => Err(Diagnostic::error(
            &name,
            Pos::File,
            "IO003",
            "not a gradient file (expected .ugr, .map, .ggr, or an image)",
        )),
    }
}

/// Write gradients atomically as .ugr (any number), .map or .ggr (exactly one).
pub fn write_gradients(
    path: &Path,
    gradients: &[crate::gradient::Gradient],
) -> Result<(), WriteError> {
    let one = |ext: &'static str| match gradients {
        [g] => Ok(g),
        _ => Err(WriteError::OneGradientOnly {
            ext,
            count: gradients.len(),
        }),
    };
    let text = match kind_of(path) {
        FileKind::Ugr => ugr::write(gradients),
        FileKind::Map => map::write(one("map")?),
        FileKind::Ggr => ggr::write(one("ggr")?),
        _ => {
            return Err(WriteError::Extension {
                path: path.to_path_buf(),
                what: "gradients",
                expected: ".ugr, .map or .ggr",
            });
        }
    };
    check_readable_size(path, text.len())?;
    atomic::write_atomic(path, text.as_bytes()).map_err(|source| WriteError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Refuse to write what ugnis would refuse to read: a text larger than the read limit of
/// the file's kind.
pub fn check_readable_size(path: &Path, bytes: usize) -> Result<(), WriteError> {
    let limit = max_file_size(kind_of(path));
    if bytes as u64 > limit {
        return Err(WriteError::TooLarge {
            path: path.to_path_buf(),
            mib: (bytes as u64).div_ceil(1 << 20),
            limit_mib: limit >> 20,
        });
    }
    Ok(())
}

/// Write a rendered flame picture atomically, as BMP or PNG by the file's extension. A PNG
/// carries the flame (to open it again), the samples done and, when known, the share of bad
/// values.
pub fn save_flame_image(
    path: &Path,
    img: &image::DynamicImage,
    flame: &Flame,
    samples: u64,
    error_rate: Option<f64>,
) -> std::io::Result<()> {
    if kind_of(path) == FileKind::Bmp {
        bmp::save(path, img)
    } else {
        let mut meta = png::PngMeta::for_flame(flame);
        meta.samples = Some(samples);
        meta.error_rate = error_rate;
        png::save(path, img, &meta)
    }
}

/// Write flames atomically as .fla/.flame/.flam3 (XML) or .ifs (linear flames only; the
/// returned strings are warnings about what .ifs cannot keep).
pub fn write_flames(path: &Path, name: &str, flames: &[Flame]) -> Result<Vec<String>, WriteError> {
    let mut warnings = Vec::new();
    let text = match kind_of(path) {
        FileKind::Ifs => {
            let mut f = ifs::IfsFile::default();
            for fl in flames {
                let (e, w) = ifs::flame_to_entry(fl).map_err(|reason| WriteError::FlameAsIfs {
                    name: fl.name.clone(),
                    reason,
                })?;
                warnings.extend(w);
                f.entries.push(e);
            }
            ifs::write(&f)?
        }
        FileKind::Fla | FileKind::FlameXml => {
            if let Some(f) = flames.iter().find(|f| f.ifs3d.is_some()) {
                return Err(WriteError::Ifs3dAsFlame {
                    name: f.name.clone(),
                });
            }
            flam3_xml::write(&flam3_xml::FlameFile {
                name: name.to_string(),
                flames: flames.to_vec(),
            })
        }
        _ => {
            return Err(WriteError::Extension {
                path: path.to_path_buf(),
                what: "flames",
                expected: ".fla, .flame, .flam3 or .ifs",
            });
        }
    };
    check_readable_size(path, text.len())?;
    atomic::write_atomic(path, text.as_bytes()).map_err(|source| WriteError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    Ok(warnings)
}
