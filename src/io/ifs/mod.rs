//! Fractint `.ifs` files: read, write, and conversion to and from flames.

use std::fmt::Write as _;

pub use crate::explore::ifs::conjugate_y;
use crate::explore::ifs::linear_flame;
use crate::flame::model::{Affine, Flame, Ifs3d, NewFlame, Xform};
use crate::flame::variations;
use crate::io::diag::fmt_num;
use crate::io::fractint_text;

mod read;

pub use read::parse;

/// Rows per entry above which Fractint cannot read the entry.
pub const FRACTINT_MAX_ROWS: usize = 63;
/// Sanity limit on rows per entry.
pub const MAX_ROWS: usize = 1000;
/// Sanity limit on entries per file.
pub const MAX_ENTRIES: usize = 10_000;
/// Fractint compares only this many characters of a name.
pub const NAME_LEN: usize = 18;

/// Why flames or entries cannot be written as a Fractint `.ifs` file.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum IfsWriteError {
    /// Names are one word without Fractint's reserved characters.
    #[error("'{0}' cannot be an .ifs entry name (no spaces or ( ) {{ }} ;)")]
    EntryName(String),
    /// Fractint compares names by their first [`NAME_LEN`] characters, ignoring case.
    #[error(
        "entry names '{first}' and '{second}' are the same for Fractint (first {NAME_LEN} characters, ignoring case)"
    )]
    SameName {
        /// The first entry's name.
        first: String,
        /// The name that Fractint takes for the first.
        second: String,
    },
    /// The weights give no probabilities.
    #[error("the flame's weights sum to 0")]
    ZeroWeights,
    /// An xform (numbered from 1) with a variation other than linear.
    #[error("xform {xform} uses variation '{variation}'; only linear flames can be saved as .ifs")]
    NotLinear {
        /// The xform, from 1.
        xform: usize,
        /// The variation's name.
        variation: String,
    },
    /// An xform (numbered from 1) with xaos.
    #[error("xform {0} uses xaos; .ifs files have no xaos")]
    Xaos(usize),
    /// A final xform.
    #[error("the flame has a final xform; .ifs files have none")]
    FinalXform,
}

/// One entry of an `.ifs` file.
#[derive(Clone, Debug, PartialEq)]
pub struct IfsEntry {
    /// The entry's name.
    pub name: String,
    /// A `(3D)` entry: rows of 13 numbers instead of 7.
    pub three_d: bool,
    /// Rows of 7 numbers (a b c d e f p) or 13 (a b c d e f g h i j k l p).
    pub rows: Vec<Vec<f64>>,
}

impl IfsEntry {
    /// Numbers in a row: 13 for a 3-D entry, 7 otherwise.
    pub fn row_len(&self) -> usize {
        if self.three_d { 13 } else { 7 }
    }

    /// The probabilities p of the rows.
    pub fn probabilities(&self) -> Vec<f64> {
        self.rows.iter().map(|r| r[r.len() - 1]).collect()
    }

    /// 2-D maps (a..f in Fractint coordinates).
    pub fn maps2d(&self) -> Vec<Affine> {
        self.rows
            .iter()
            .map(|r| Affine::new(r[0], r[1], r[2], r[3], r[4], r[5]))
            .collect()
    }
}

/// The entries of an `.ifs` file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IfsFile {
    /// The entries, in file order.
    pub entries: Vec<IfsEntry>,
}

impl IfsFile {
    /// Find an entry by name (case-insensitive, as Fractint).
    pub fn get(&self, name: &str) -> Option<&IfsEntry> {
        self.entries
            .iter()
            .find(|e| e.name.eq_ignore_ascii_case(name))
    }
}

/// What Fractint compares of a name: its first [`NAME_LEN`] characters, ignoring case (two
/// names with the same key are the same for Fractint). Kept in a hash map, so that checking
/// every name of a file takes time linear in its entries.
fn name_key(name: &str) -> String {
    name.chars()
        .take(NAME_LEN)
        .collect::<String>()
        .to_lowercase()
}

/// Write an `.ifs` file: CRLF, two-space indent, a blank line between entries. Names that
/// Fractint would confuse (equal in their first 18 characters, ignoring case) are an error.
pub fn write(f: &IfsFile) -> Result<String, IfsWriteError> {
    let mut seen = std::collections::HashMap::new();
    for a in &f.entries {
        if a.name.is_empty()
            || a.name
                .contains(|c: char| c.is_whitespace() || "(){};".contains(c))
        {
            return Err(IfsWriteError::EntryName(a.name.clone()));
        }
        if let Some(b) = seen.insert(name_key(&a.name), &a.name) {
            return Err(IfsWriteError::SameName {
                first: b.clone(),
                second: a.name.clone(),
            });
        }
    }
    let mut s = String::new();
    for (i, e) in f.entries.iter().enumerate() {
        if i > 0 {
            s.push_str("\r\n");
        }
        let _ = write!(
            s,
            "{}{} {{\r\n",
            e.name,
            if e.three_d { " (3D)" } else { "" }
        );
        for r in &e.rows {
            let nums: Vec<String> = r.iter().map(|v| fmt_num(*v)).collect();
            let _ = write!(s, "  {}\r\n", nums.join(" "));
        }
        s.push_str("  }\r\n");
    }
    Ok(s)
}

/// A 2-D entry as a flame; a 3-D entry as a flame that iterates the 3-D
/// system and shows it through Fractint's default 30°/30°/30° view. The camera is left to
/// automatic framing (the renderer frames flames without a camera).
pub fn entry_to_flame(e: &IfsEntry, defaults: &NewFlame) -> Flame {
    if e.three_d {
        // One placeholder xform (the identity) keeps the flame valid for code that expects
        // xforms.
        let mut f = linear_flame(&e.name, &[Affine::IDENTITY], [1.0], defaults);
        f.ifs3d = Some(Ifs3d {
            rows: e
                .rows
                .iter()
                .map(|r| r.clone().try_into().expect("13 numbers"))
                .collect(),
            view_degrees: Ifs3d::FRACTINT_VIEW,
        });
        return f;
    }
    let p = e.probabilities();
    let psum: f64 = p.iter().sum();
    let maps = e.maps2d();
    let weights = if p.iter().any(|v| *v < 0.0) {
        fractint_shares(&p)
    } else if psum > 0.0 {
        p.iter().map(|v| v / psum).collect()
    } else {
        // |det| is the same for a map and its y-flipped conjugate.
        Flame::determinant_weights(&maps)
    };
    linear_flame(&e.name, &maps, weights, defaults)
}

/// The share of r ∈ [0, 1) each row gets under Fractint's selection: the first row whose
/// cumulative probability exceeds r, the last row taking whatever is left.
pub fn fractint_shares(p: &[f64]) -> Vec<f64> {
    let n = p.len();
    let mut out = Vec::with_capacity(n);
    let mut cum = 0.0;
    let mut covered: f64 = 0.0;
    for (i, v) in p.iter().enumerate() {
        cum += v;
        let top = if i + 1 == n { 1.0 } else { cum.clamp(0.0, 1.0) };
        out.push((top - covered).max(0.0));
        covered = covered.max(top);
    }
    out
}

/// Convert a flame to a 2-D `.ifs` entry. Returns the entry and a warning
/// listing what the `.ifs` format cannot keep, or an error naming the first xform that is not
/// a plain linear map.
pub fn flame_to_entry(f: &Flame) -> Result<(IfsEntry, Option<String>), IfsWriteError> {
    if let Some(i3) = &f.ifs3d {
        return Ok((
            IfsEntry {
                name: entry_name(&f.name),
                three_d: true,
                rows: i3.rows.iter().map(|r| r.to_vec()).collect(),
            },
            None,
        ));
    }
    let n = f.xforms.len();
    let mut rows = Vec::with_capacity(n);
    let wsum: f64 = f.xforms.iter().map(|x| x.weight).sum();
    if wsum <= 0.0 {
        return Err(IfsWriteError::ZeroWeights);
    }
    let mut lost: Vec<&str> = Vec::new();
    for (i, x) in f.xforms.iter().enumerate() {
        let l = linear_weight(x).map_err(|variation| IfsWriteError::NotLinear {
            xform: i + 1,
            variation,
        })?;
        if (0..n).any(|j| x.chaos_to(j) != 1.0) {
            return Err(IfsWriteError::Xaos(i + 1));
        }
        let scaled = Affine::new(
            l * x.coefs.a,
            l * x.coefs.b,
            l * x.coefs.c,
            l * x.coefs.d,
            l * x.coefs.e,
            l * x.coefs.f,
        );
        let m = conjugate_y(&x.post.compose(&scaled));
        rows.push(vec![m.a, m.b, m.c, m.d, m.e, m.f, x.weight / wsum]);
        if x.opacity < 1.0 && !lost.contains(&"opacity") {
            lost.push("opacity");
        }
    }
    if let Some(fx) = &f.final_xform {
        let identity =
            fx.coefs.is_identity() && fx.post.is_identity() && linear_weight(fx) == Ok(1.0);
        if !identity {
            return Err(IfsWriteError::FinalXform);
        }
    }
    lost.extend(["colours", "gradient", "camera"]);
    Ok((
        IfsEntry {
            name: entry_name(&f.name),
            three_d: false,
            rows,
        },
        Some(format!(
            "saving '{}' as .ifs keeps only the maps and probabilities; lost: {}",
            f.name,
            lost.join(", ")
        )),
    ))
}

/// The weight of an xform's only variation if it is linear; otherwise the offending name.
fn linear_weight(x: &Xform) -> Result<f64, String> {
    if let Some((name, _)) = x.unsupported_vars().into_iter().next() {
        return Err(name);
    }
    match x.vars.as_slice() {
        [v] if v.id == variations::LINEAR && v.weight != 0.0 => Ok(v.weight),
        [] => Err("none".into()),
        vs => Err(vs
            .iter()
            .find(|v| v.id != variations::LINEAR)
            .map_or("linear", |v| v.name())
            .to_string()),
    }
}

/// A valid entry name from a flame name (spaces and reserved characters become '_').
pub fn entry_name(name: &str) -> String {
    fractint_text::entry_name(name, "(){};", "ifs")
}

#[cfg(test)]
mod tests;
