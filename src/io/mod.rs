//! Readers and writers of every file format ugnis opens or saves. Parsers report errors with
//! file, line and column and never panic.

pub mod animation;
pub mod atomic;
pub mod audio;
pub mod bmp;
pub mod diag;
pub(crate) mod error;
mod escape_values;
pub mod escape_view;
pub mod exr;
pub mod flam3_xml;
mod fractint_text;
pub mod ggr;
pub mod ifs;
pub mod image_in;
pub mod jwf_install;
pub mod lsystem;
pub mod map;
mod open;
pub mod palettes;
pub mod png;
pub mod render_state;
pub mod scene;
pub mod strip_png;
pub mod svg;
pub mod target;
pub mod ugr;
pub mod var_images;
pub mod video;
pub(crate) mod xml;

use std::path::Path;

use crate::flame::model::Flame;
use crate::io::diag::{Diagnostic, Parsed, Pos};
pub use crate::io::error::{LSystemWriteError, WriteError};
use open::read_limited;
pub use open::{
    MAX_FILE_SIZE, MAX_FLAME_FILE_SIZE, is_stdin, max_file_size, open_regular, read_bytes,
    read_bytes_limited,
};

/// File kinds ugnis opens, by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    /// flam3/Apophysis/ugnis XML: .flame, .flam3, .fla, .xml
    FlameXml,
    /// ugnis native .fla (validated more strictly)
    Fla,
    /// PNG image (may carry a flame in its text chunks)
    Png,
    /// Fractint IFS (.ifs)
    Ifs,
    /// ugnis gradient list (.ugr)
    Ugr,
    /// Fractint palette (.map)
    Map,
    /// GIMP gradient (.ggr)
    Ggr,
    /// BMP image
    Bmp,
    /// JPEG image
    Jpeg,
    /// GIF image
    Gif,
    /// ugnis escape-time view (.esc)
    EscapeView,
    /// Fractint L-system (.l)
    LSystem,
    /// ugnis textured Bézier scene (.toml)
    Scene,
    /// A saved flame render to continue or merge (.ugnis-state)
    RenderState,
    /// An extension ugnis does not know
    Unknown,
}

impl FileKind {
    /// What a file of this kind is, for messages ("a Fractint L-system file (.l)").
    pub fn describe(self) -> &'static str {
        match self {
            FileKind::FlameXml => "a flame file (.flame, .flam3, .xml)",
            FileKind::Fla => "a flame file (.fla)",
            FileKind::Png => "a PNG image",
            FileKind::Ifs => "a Fractint IFS file (.ifs)",
            FileKind::Ugr => "a gradient file (.ugr)",
            FileKind::Map => "a gradient file (.map)",
            FileKind::Ggr => "a GIMP gradient (.ggr)",
            FileKind::Bmp => "a BMP image",
            FileKind::Jpeg => "a JPEG image",
            FileKind::Gif => "a GIF image",
            FileKind::EscapeView => "an escape-time view (.esc)",
            FileKind::LSystem => "a Fractint L-system file (.l)",
            FileKind::Scene => "a scene (.toml)",
            FileKind::RenderState => "a render state (.ugnis-state)",
            FileKind::Unknown => "a file of unknown kind",
        }
    }
}

/// The kind of a file, by its extension (any case).
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
        "toml" => FileKind::Scene,
        "ugnis-state" => FileKind::RenderState,
        _ => FileKind::Unknown,
    }
}

/// Where ugnis opens a file: the view (and in it the document) a kind of file belongs to.
/// The editor's Open, Recent files, dropped files and the file given at start all go by
/// [`view_of`], and so do the command line's readers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// The flames of the flame editor: flame XML, a PNG with a flame, the entries of an IFS
    /// file, and any file of unknown kind (read as flame XML).
    Flame,
    /// The escape-time view (.esc).
    Escape,
    /// The scene view (.toml).
    Scene,
    /// The L-system topic of Explore (.l).
    LSystem,
    /// The flame editor's gradient list (.ugr, .map, .ggr).
    Gradients,
    /// A gradient made from the colours of an image (.bmp, .jpg, .gif; a PNG opens as a flame).
    GradientFromImage,
    /// Continuing a saved render in the flame editor's export (.ugnis-state).
    RenderState,
}

impl View {
    /// The view's name in messages ("the escape-time view").
    pub fn describe(self) -> &'static str {
        match self {
            View::Flame => "the flame editor",
            View::Escape => "the escape-time view",
            View::Scene => "the scene view",
            View::LSystem => "the L-system view",
            View::Gradients => "the gradient list",
            View::GradientFromImage => "a gradient made from the image",
            View::RenderState => "the export that continues it",
        }
    }
}

/// The view that opens a kind of file (see [`View`]).
pub fn view_of(kind: FileKind) -> View {
    match kind {
        FileKind::FlameXml | FileKind::Fla | FileKind::Png | FileKind::Ifs | FileKind::Unknown => {
            View::Flame
        }
        FileKind::EscapeView => View::Escape,
        FileKind::Scene => View::Scene,
        FileKind::LSystem => View::LSystem,
        FileKind::Ugr | FileKind::Map | FileKind::Ggr => View::Gradients,
        FileKind::Bmp | FileKind::Jpeg | FileKind::Gif => View::GradientFromImage,
        FileKind::RenderState => View::RenderState,
    }
}

/// Read the flames of any flame source (see [`View::Flame`]): flame XML (.flame/.flam3/.fla),
/// a PNG with an embedded flame, or a Fractint `.ifs` file (a flame per entry, 3-D entries
/// through the fixed view). A file another view opens is refused, naming that view.
pub fn read_flames(
    path: &Path,
    opts: &flam3_xml::ReadOptions,
) -> Result<Parsed<Vec<Flame>>, Diagnostic> {
    read_flames_with(path, opts, &crate::flame::NewFlame::default())
}

/// As [`read_flames`], with the display settings and gradient for flames made from the
/// entries of an IFS file.
pub fn read_flames_with(
    path: &Path,
    opts: &flam3_xml::ReadOptions,
    ifs_defaults: &crate::flame::NewFlame,
) -> Result<Parsed<Vec<Flame>>, Diagnostic> {
    let p = read_flame_file_with(path, opts, ifs_defaults)?;
    Ok(Parsed {
        value: p.value.flames,
        warnings: p.warnings,
    })
}

/// As [`read_flames`], keeping the document's `<flames name>` (empty for an IFS file).
pub fn read_flame_file(
    path: &Path,
    opts: &flam3_xml::ReadOptions,
) -> Result<Parsed<flam3_xml::FlameFile>, Diagnostic> {
    read_flame_file_with(path, opts, &crate::flame::NewFlame::default())
}

/// [`read_flame_file`] with the defaults of flames made from IFS entries. The file is
/// opened once: its first bytes tell a PNG from text.
fn read_flame_file_with(
    path: &Path,
    opts: &flam3_xml::ReadOptions,
    ifs_defaults: &crate::flame::NewFlame,
) -> Result<Parsed<flam3_xml::FlameFile>, Diagnostic> {
    if kind_of(path) == FileKind::Ifs {
        let p = ifs_flames_with(path, ifs_defaults)?;
        return Ok(Parsed {
            value: flam3_xml::FlameFile {
                name: String::new(),
                flames: p.value,
            },
            warnings: p.warnings,
        });
    }
    let (text, o) = flame_text(path, opts)?;
    let mut p = flam3_xml::read(&text, &o)?;
    // The image files the flame's variations name (JWildfire's image resources).
    if !is_stdin(path) {
        let w = var_images::load_variation_images(&mut p.value.flames, path, &o.file);
        p.warnings.extend(w);
    }
    Ok(p)
}

/// A flam3 template file: render settings to apply to flames ([`flam3_xml::Template`]).
pub fn read_template_file(
    path: &Path,
    opts: &flam3_xml::ReadOptions,
) -> Result<Parsed<flam3_xml::Template>, Diagnostic> {
    let (text, o) = flame_text(path, opts)?;
    flam3_xml::read_template(&text, &o)
}

/// The flame XML of a flame file (or of the genome a PNG carries), with the reader options
/// for it (its name; the `.fla` rules for `.fla` files).
fn flame_text<'a>(
    path: &Path,
    opts: &flam3_xml::ReadOptions<'a>,
) -> Result<(String, flam3_xml::ReadOptions<'a>), Diagnostic> {
    let name = path.display().to_string();
    let kind = kind_of(path);
    let view = view_of(kind);
    if view != View::Flame {
        return Err(Diagnostic::error(
            &name,
            Pos::File,
            "IO005",
            format!(
                "{}, not a flame; ugnis opens it in {}",
                kind.describe(),
                view.describe()
            ),
        ));
    }
    let mut o = opts.clone();
    o.file = name.clone();
    o.fla = kind == FileKind::Fla;
    let text = if is_stdin(path) {
        let bytes = read_bytes(path)?;
        if bytes.starts_with(PNG_SIGNATURE) {
            o.fla = false;
            png::read_genome(&bytes, &name)?
        } else {
            utf8_text(bytes, &name)?
        }
    } else {
        let (f, meta) = open_regular(path)?;
        let mut r = std::io::BufReader::new(f);
        if kind == FileKind::Png || starts_with_png(&mut r) {
            // Streamed: a PNG of any size opens as long as the genome precedes the image data.
            o.fla = false;
            png::read_genome_from(r, &name)?
        } else {
            utf8_text(
                read_limited(r, Some(meta.len()), max_file_size(kind), &name)?,
                &name,
            )?
        }
    };
    Ok((text, o))
}

/// The first bytes of every PNG file.
const PNG_SIGNATURE: &[u8] = b"\x89PNG";

/// Does the file start with the PNG signature? Looks at the reader's buffer without taking
/// anything from it.
fn starts_with_png(r: &mut impl std::io::BufRead) -> bool {
    r.fill_buf()
        .is_ok_and(|head| head.starts_with(PNG_SIGNATURE))
}

/// Bytes as UTF-8 text; an error names the first byte that is not.
fn utf8_text(bytes: Vec<u8>, name: &str) -> Result<String, Diagnostic> {
    String::from_utf8(bytes).map_err(|e| {
        Diagnostic::error(
            name,
            Pos::Byte(e.utf8_error().valid_up_to() as u64),
            "XML001",
            "file is not valid UTF-8 text",
        )
    })
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

#[cfg(test)]
mod tests {
    use super::*;

    fn fixture(name: &str) -> std::path::PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fixtures")
            .join(name)
    }

    #[test]
    fn every_kind_opens_in_its_view() {
        for (name, kind, view) in [
            ("a.flame", FileKind::FlameXml, View::Flame),
            ("a.flam3", FileKind::FlameXml, View::Flame),
            ("a.FLA", FileKind::Fla, View::Flame),
            ("a.png", FileKind::Png, View::Flame),
            ("a.ifs", FileKind::Ifs, View::Flame),
            ("notes.txt", FileKind::Unknown, View::Flame),
            ("a.esc", FileKind::EscapeView, View::Escape),
            ("a.toml", FileKind::Scene, View::Scene),
            ("a.l", FileKind::LSystem, View::LSystem),
            ("a.ugr", FileKind::Ugr, View::Gradients),
            ("a.map", FileKind::Map, View::Gradients),
            ("a.ggr", FileKind::Ggr, View::Gradients),
            ("a.jpg", FileKind::Jpeg, View::GradientFromImage),
            ("a.bmp", FileKind::Bmp, View::GradientFromImage),
            ("a.ugnis-state", FileKind::RenderState, View::RenderState),
        ] {
            assert_eq!(kind_of(Path::new(name)), kind, "{name}");
            assert_eq!(view_of(kind), view, "{name}");
        }
    }

    #[test]
    fn flames_are_read_from_ifs_entries_too() {
        let ifs = fixture("library.ifs");
        let direct = ifs_flames(&ifs).unwrap().value;
        let read = read_flames(&ifs, &Default::default()).unwrap().value;
        assert!(!read.is_empty());
        assert_eq!(read, direct);
        assert!(
            read_flame_file(&ifs, &Default::default())
                .unwrap()
                .value
                .name
                .is_empty()
        );
    }

    #[test]
    fn a_file_of_another_view_is_refused_naming_that_view() {
        for (name, view) in [
            ("explore.l", "L-system view"),
            ("hand.ugr", "gradient list"),
        ] {
            let e = read_flames(&fixture(name), &Default::default()).unwrap_err();
            assert_eq!(e.code, "IO005", "{name}");
            assert!(e.to_string().contains(view), "{name}: {e}");
        }
    }
}
