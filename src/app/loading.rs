//! Reading the flames of a file for the editor: any flame source (see [`io::View::Flame`]),
//! with the Options' defaults for flames made from IFS entries; the reader's diagnostics
//! sorted into message-box warnings and status-line notes.

use std::path::Path;

use super::options::Options;
use crate::flame::Flame;
use crate::io;

/// The flames of a file with what reading them had to say.
pub struct Loaded {
    pub flames: Vec<Flame>,
    /// Shown in a message box.
    pub warnings: Vec<String>,
    /// Shown in the status line.
    pub notes: Vec<String>,
}

/// Load flames from any flame source, with the Options' defaults for IFS files.
pub fn load_any(path: &Path, options: &Options) -> Result<Loaded, String> {
    let p = io::read_flames_with(path, &Default::default(), &options.new_flame())
        .map_err(|e| e.to_string())?;
    if p.value.is_empty() {
        return Err(format!("{}: no flames", path.display()));
    }
    let mut flames = p.value;
    for f in &mut flames {
        keep_file_weights(f);
    }
    // Attributes of other programs are kept and written back: worth a status line, not a
    // message box that must be dismissed before anything else.
    let (notes, warnings): (Vec<_>, Vec<_>) = p
        .warnings
        .iter()
        .partition(|w| INFORMATIONAL.contains(&w.code));
    Ok(Loaded {
        flames,
        warnings: warnings.iter().map(|w| w.to_string()).collect(),
        notes: notes.iter().map(|w| w.to_string()).collect(),
    })
}

/// Reader diagnostics that lose nothing (kept and written back unchanged).
const INFORMATIONAL: &[&str] = &["XML021"];

/// A flame from a file keeps its own weights: triangle edits re-derive weights from the
/// areas only when the file asks for it (ugnis' `ugnis_auto_weights="1"`) or the user ticks
/// "from areas". Weights that happen to follow the areas are no request: Apophysis, JWildfire
/// and flam3 never change a weight when a triangle moves.
pub fn keep_file_weights(f: &mut Flame) {
    if f.auto_weights.is_none() {
        f.auto_weights = Some(false);
    }
}
