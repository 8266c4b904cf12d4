//! Fractint L-system files (`.l`): read every entry, write them back.
//!
//! ```text
//! Name {            ; comment
//!   Angle n         ; δ = 360°/n, n an integer from 3 to 49 (also `angle=n`)
//!   Axiom string
//!   a=string        ; production for symbol a (case-insensitive); "F=" deletes F
//! }
//! ```
//!
//! One item per line (Fractint reads a line's first word and the string after it); `;` starts a
//! comment anywhere. Repeated productions for one symbol are concatenated. The reader
//! (`lsystem/read.rs`) takes the file entry by entry as Fractint does: comment blocks `{ … }`
//! are skipped, what Fractint would not understand is ignored with a warning, and an entry that
//! cannot be drawn is reported and skipped without blocking the others.

use crate::explore::lsystem::{ANGLE_DIVISIONS, Angle, LSystem};
use crate::io::error::LSystemWriteError;
use crate::io::fractint_text;

mod read;
#[cfg(test)]
mod tests;

pub use read::parse;

/// Most entries per file.
pub const MAX_ENTRIES: usize = 10_000;
/// Lines this long or longer draw a warning (Fractint reads at most 160 characters a line).
pub const LINE_LIMIT: usize = 160;

/// The entries of an `.l` file, in file order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LFile {
    /// The systems, in file order.
    pub entries: Vec<LSystem>,
}

impl LFile {
    /// An entry by name (case-insensitive, as Fractint).
    pub fn get(&self, name: &str) -> Option<&LSystem> {
        self.entries
            .iter()
            .find(|e| e.name.eq_ignore_ascii_case(name))
    }
}

/// A valid entry name from any name (spaces and reserved characters become '_').
pub fn entry_name(name: &str) -> String {
    fractint_text::entry_name(name, "{};=", "lsystem")
}

/// The angle divisions n with δ = 360°/n, if δ is such an angle.
fn divisions(a: Angle) -> Option<u32> {
    match a {
        Angle::Divisions(n) => Some(n),
        Angle::Degrees(d) => {
            let n = (360.0 / d).round();
            ((360.0 / n - d).abs() < 1e-9 && n >= 0.0).then_some(n as u32)
        }
    }
}

/// Write systems as an `.l` file (CRLF line ends, as Fractint's DOS files). A system that the
/// format cannot hold (an angle that is not 360°/n for n in 3..49, extra draw symbols, turning
/// brackets, a start heading that is not a multiple of δ) is refused with the reason. The swap
/// flag becomes a leading `!` and the start heading leading `+`, which Fractint reads the same.
pub fn write(systems: &[LSystem]) -> Result<String, LSystemWriteError> {
    let mut s = String::new();
    let mut names: Vec<String> = Vec::new();
    for (i, sys) in systems.iter().enumerate() {
        sys.compile().map_err(|reason| LSystemWriteError::Invalid {
            name: sys.name.clone(),
            reason,
        })?;
        let name = entry_name(&sys.name);
        if names.iter().any(|n| n.eq_ignore_ascii_case(&name)) {
            return Err(LSystemWriteError::SameName(name));
        }
        let n = divisions(sys.angle)
            .filter(|n| ANGLE_DIVISIONS.contains(n))
            .ok_or_else(|| LSystemWriteError::Angle {
                name: sys.name.clone(),
                degrees: sys.angle.degrees(),
            })?;
        if !sys.draw_symbols.is_empty() {
            return Err(LSystemWriteError::DrawSymbols {
                name: sys.name.clone(),
                symbols: sys.draw_symbols.clone(),
            });
        }
        if sys.bracket_turn {
            return Err(LSystemWriteError::TurningBrackets(sys.name.clone()));
        }
        let delta = 360.0 / n as f64;
        let turns = (sys.start_heading / delta).round();
        if (turns * delta - sys.start_heading).abs() > 1e-9 {
            return Err(LSystemWriteError::StartHeading {
                name: sys.name.clone(),
                heading: sys.start_heading,
                delta,
            });
        }
        let turns = (turns as i64).rem_euclid(n as i64) as usize;
        // The start heading as leading turns, written before the swap so they turn left; the
        // degree heading of D and M turns with `\`.
        let mut axiom = "+".repeat(turns);
        let uses_degrees = std::iter::once(&sys.axiom)
            .chain(sys.rules.iter().map(|r| &r.1))
            .any(|t| {
                t.chars()
                    .any(|c| matches!(c.to_ascii_lowercase(), 'd' | 'm'))
            });
        if turns > 0 && uses_degrees {
            axiom.push_str(&format!(
                "\\{}",
                crate::io::diag::fmt_num(sys.start_heading.rem_euclid(360.0))
            ));
        }
        if sys.swap_signs {
            axiom.push('!');
        }
        axiom.push_str(&sys.axiom);
        if i > 0 {
            s.push_str("\r\n");
        }
        s.push_str(&format!("{name} {{\r\n  Angle {n}\r\n  Axiom {axiom}\r\n"));
        for (c, body) in &sys.rules {
            s.push_str(&format!("  {c}={body}\r\n"));
        }
        s.push_str("  }\r\n");
        names.push(name);
    }
    Ok(s)
}
