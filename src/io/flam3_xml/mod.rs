//! flam3 / Apophysis flame XML (`.flame`, `.flam3`) and ugnis `.fla`.
//!
//! Reading accepts any well-formed document and takes every `<flame>` element at any depth.
//! Everything ugnis does not interpret — unknown attributes, `<edit>` histories, variations it
//! cannot render — is kept and written back, so a read/write round trip is lossless.
//!
//! The reader is [`read()`] (the document in `read.rs`, a flame's attributes in `flame.rs`, its
//! children in `children.rs`, colours in `palette.rs`, xforms in `xform.rs`, animation
//! settings, `<motion>` elements and keyframes in `anim.rs`, JWildfire's motion curves in
//! `jwf_curves.rs`); the writer is [`write()`] (`write.rs`). flam3's template files (render
//! settings to apply to other flames) are read by [`read_template()`] (`template.rs`).

use std::path::PathBuf;

use crate::flame::model::Flame;
use crate::gradient::Gradient;
use crate::io::palettes::PaletteLibrary;

mod anim;
mod children;
mod context;
mod flame;
mod jwf_curves;
mod jwf_defaults;
mod jwf_look;
mod jwf_solid;
mod layers;
mod palette;
mod read;
mod subflame;
mod template;
mod write;
mod xform;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_jwf;
#[cfg(test)]
mod tests_writers;

pub use read::read;
pub use template::{Template, read_template};
pub use write::{flame_element, write};

/// Revision of the `.fla` format this version writes.
pub const FLA_FORMAT: u32 = 1;
/// Flames per file (sanity limit).
pub const MAX_FLAMES: usize = 10_000;
/// Xforms per flame (sanity limit).
pub const MAX_XFORMS: usize = 10_000;
/// Most colours in one `<palette>` (Fractorium writes up to a few thousand).
pub const MAX_PALETTE: i64 = 65_536;
/// Largest image side accepted from a file.
pub const MAX_SIDE: i64 = 1_000_000;
/// Warnings of one kind listed per file; the rest are counted in one line.
pub const MAX_WARNINGS_PER_CODE: usize = 20;

/// The contents of a flame file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FlameFile {
    /// `name` of the `<flames>` root, if any.
    pub name: String,
    /// The flames in document order (every `<flame>` element, at any depth).
    pub flames: Vec<Flame>,
}

/// Where `palette="N"` looks up flam3's library.
#[derive(Clone, Debug, Default)]
pub enum LibrarySource<'a> {
    /// Search `$FLAM3_PALETTES` and the usual install paths.
    #[default]
    Search,
    /// These paths, in order.
    Paths(Vec<PathBuf>),
    /// An already loaded library.
    Loaded(&'a PaletteLibrary),
}

/// Reader options.
#[derive(Clone, Debug)]
pub struct ReadOptions<'a> {
    /// File name used in diagnostics.
    pub file: String,
    /// Where a `palette="N"` attribute finds flam3's palette library (searched by default).
    pub library: LibrarySource<'a>,
    /// Quality for flames without a `quality` attribute (the Options main density).
    pub default_quality: f64,
    /// Palette for flames without colour data.
    pub default_gradient: Gradient,
    /// Validate as a `.fla` file (`<flames>` root, unique non-empty names).
    pub fla: bool,
    /// Accept flames without xforms: flam3's template files (render settings only, see
    /// [`read_template`]).
    pub templates: bool,
}

impl Default for ReadOptions<'_> {
    fn default() -> Self {
        Self {
            file: "<input>".to_string(),
            library: LibrarySource::Search,
            default_quality: 15.0,
            default_gradient: Gradient::default(),
            fla: false,
            templates: false,
        }
    }
}
