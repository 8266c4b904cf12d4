//! Fractint `.ifs` files: read, write, and conversion to and from flames.

use std::fmt::Write as _;

use crate::flame::model::{Affine, Flame, FlameKind, Ifs3d, NewFlame, Xform};
use crate::flame::variations;
use crate::io::diag::{
    Diagnostic, NumberError, Parsed, Pos, SourceMap, fmt_num, lines, parse_number,
};

/// Rows per entry above which Fractint cannot read the entry.
pub const FRACTINT_MAX_ROWS: usize = 63;
/// Sanity limit on rows per entry.
pub const MAX_ROWS: usize = 1000;
/// Sanity limit on entries per file.
pub const MAX_ENTRIES: usize = 10_000;
/// Fractint compares only this many characters of a name.
pub const NAME_LEN: usize = 18;

/// One entry of an `.ifs` file.
#[derive(Clone, Debug, PartialEq)]
pub struct IfsEntry {
    pub name: String,
    pub three_d: bool,
    /// Rows of 7 numbers (a b c d e f p) or 13 (a b c d e f g h i j k l p).
    pub rows: Vec<Vec<f64>>,
}

impl IfsEntry {
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

struct Tok<'a> {
    text: &'a str,
    start: usize,
}

/// Split a line (without its end) into tokens, stopping at a `;` comment.
fn tokens(line: &str, base: usize) -> Vec<Tok<'_>> {
    let code = match line.find(';') {
        Some(i) => &line[..i],
        None => line,
    };
    let mut out = Vec::new();
    let mut start: Option<usize> = None;
    for (i, ch) in code.char_indices() {
        if ch.is_whitespace() {
            if let Some(s) = start.take() {
                out.push(Tok {
                    text: &code[s..i],
                    start: base + s,
                });
            }
        } else if start.is_none() {
            start = Some(i);
        }
    }
    if let Some(s) = start {
        out.push(Tok {
            text: &code[s..],
            start: base + s,
        });
    }
    out
}

/// An entry being read: name, 3-D, header offset, numbers with their offsets.
type OpenEntry = (String, bool, usize, Vec<(f64, usize)>);

/// Parse the text of an `.ifs` file. A file of bare rows without any `name {` header (as
/// Fractint wrote one IFS per file before version 16) is read as one entry named after the
/// file, with a warning.
pub fn parse(text: &str, file: &str) -> Result<Parsed<IfsFile>, Diagnostic> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    match legacy_numbers(text) {
        Some(n) => parse_legacy(text, file, n),
        None => parse_entries(text, file),
    }
}

/// The count of numbers when the whole file is numbers and comments (no braces, at least one
/// row); None otherwise.
fn legacy_numbers(text: &str) -> Option<usize> {
    let mut n = 0usize;
    for (base, line) in lines(text) {
        for t in tokens(line, base) {
            if t.text.contains(['{', '}']) || parse_number(t.text).is_err() {
                return None;
            }
            n += 1;
        }
    }
    (n >= 7).then_some(n)
}

/// An old single-IFS file: the rows are read as the body of one entry named after the file.
fn parse_legacy(text: &str, file: &str, numbers: usize) -> Result<Parsed<IfsFile>, Diagnostic> {
    let stem = std::path::Path::new(file)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut name: String = stem
        .chars()
        .filter(|c| !c.is_whitespace() && !"(){};".contains(*c))
        .collect();
    if name.is_empty() {
        name = "ifs".into();
    }
    // 3-D rows have 13 numbers; a count that only 13 divides is a 3-D system.
    let three_d = !numbers.is_multiple_of(7) && numbers.is_multiple_of(13);
    let wrapped = format!(
        "{name}{} {{\n{text}\n}}\n",
        if three_d { " (3D)" } else { "" }
    );
    let body_lines = lines(text).len().max(1);
    // Positions in the wrapped text are one line below the file's; the added header and
    // closing lines are the whole file.
    let shift = |d: Diagnostic| {
        let pos = match d.pos {
            Pos::LineCol(l, c) if l >= 2 && l <= body_lines + 1 => Pos::LineCol(l - 1, c),
            Pos::LineCol(..) => Pos::File,
            other => other,
        };
        Diagnostic { pos, ..d }
    };
    let mut p = parse_entries(&wrapped, file).map_err(shift)?;
    p.warnings = p.warnings.into_iter().map(shift).collect();
    p.warnings.insert(
        0,
        Diagnostic::warning(
            file,
            Pos::File,
            "IFS017",
            format!(
                "no 'name {{' header: read as one entry '{name}' ({} rows), as Fractint wrote IFS files before version 16",
                numbers / if three_d { 13 } else { 7 }
            ),
        ),
    );
    Ok(p)
}

/// Parse `name { … }` entries.
fn parse_entries(text: &str, file: &str) -> Result<Parsed<IfsFile>, Diagnostic> {
    let map = SourceMap::new(text);
    let err = |off: usize, code, msg: String| Diagnostic::error(file, map.pos(off), code, msg);
    let mut warnings = Vec::new();
    let mut out = IfsFile::default();
    // Current entry: (name, 3d, header offset, numbers with offsets).
    let mut cur: Option<OpenEntry> = None;
    for (base, line) in lines(text) {
        let toks = tokens(line, base);
        let mut k = 0;
        if cur.is_none() {
            if toks.is_empty() {
                continue;
            }
            // A header: name [ "(" qualifier ")" ] "{" — the name may be glued to "(" or "{".
            let header_text = &text[toks[0].start..base + line.find(';').unwrap_or(line.len())];
            let Some(brace) = header_text.find('{') else {
                let first = toks[0].text;
                return Err(
                    if first.parse::<f64>().is_ok() || first.starts_with(['-', '+', '.']) {
                        err(
                            toks[0].start,
                            "IFS001",
                            format!("'{first}' outside any entry; an entry starts with 'name {{'"),
                        )
                    } else {
                        err(
                            toks[0].start,
                            "IFS002",
                            format!(
                                "expected '{{' after the entry name '{first}' on the same line"
                            ),
                        )
                    },
                );
            };
            let before = &header_text[..brace];
            let (name_part, qual) = match before.find('(') {
                Some(p) => {
                    let close = before[p..].find(')').map(|c| p + c).ok_or_else(|| {
                        err(
                            toks[0].start + p,
                            "IFS009",
                            "unclosed '(' in the entry header".into(),
                        )
                    })?;
                    let q = before[p + 1..close].trim();
                    if !before[close + 1..].trim().is_empty() {
                        return Err(err(
                            toks[0].start + close + 1,
                            "IFS002",
                            "unexpected text before '{'".into(),
                        ));
                    }
                    (&before[..p], Some((q, toks[0].start + p)))
                }
                None => (before, None),
            };
            let name = name_part.trim();
            if name.is_empty() {
                return Err(err(
                    toks[0].start + brace,
                    "IFS002",
                    "'{' without an entry name before it".into(),
                ));
            }
            if name.contains(char::is_whitespace) || name.contains('}') {
                return Err(err(
                    toks[0].start,
                    "IFS001",
                    format!("'{name}' is not an entry name (names have no spaces)"),
                ));
            }
            let three_d = match qual {
                None => false,
                Some((q, _)) if q.eq_ignore_ascii_case("3d") => true,
                Some((q, off)) => {
                    return Err(err(
                        off,
                        "IFS009",
                        format!("unknown qualifier '({q})'; only (3D) is known"),
                    ));
                }
            };
            // Nothing may follow '{' on the header line but a comment.
            let after = header_text[brace + 1..].trim_start();
            if !after.is_empty() {
                let off =
                    toks[0].start + brace + 1 + (header_text[brace + 1..].len() - after.len());
                return Err(err(
                    off,
                    "IFS003",
                    format!(
                        "'{}' after '{{' on the header line (Fractint skips the rest of this line); put the numbers on the next line",
                        after.split_whitespace().next().unwrap_or(after)
                    ),
                ));
            }
            if out.entries.len() >= MAX_ENTRIES {
                return Err(err(
                    toks[0].start,
                    "IFS016",
                    format!("more than {MAX_ENTRIES} entries"),
                ));
            }
            cur = Some((name.to_string(), three_d, toks[0].start, Vec::new()));
            continue;
        }
        if let Some(b) = line[..line.find(';').unwrap_or(line.len())].find('{') {
            let name = &cur.as_ref().expect("inside an entry").0;
            return Err(err(
                base + b,
                "IFS005",
                format!("'{{' inside entry '{name}' (entries cannot nest)"),
            ));
        }
        while k < toks.len() {
            let t = &toks[k];
            k += 1;
            let (name, three_d, hdr, nums) = cur.as_mut().expect("inside an entry");
            let mut s = t.text;
            let mut closes = false;
            if s == "}" {
                closes = true;
                s = "";
            } else if let Some(stripped) = s.strip_suffix('}') {
                // `.33}`: Fractint does not see the end here; accept with a warning.
                warnings.push(Diagnostic::warning(
                    file,
                    map.pos(t.start + stripped.len()),
                    "IFS010",
                    "'}' glued to a number; Fractint would not recognise the end of the entry",
                ));
                closes = true;
                s = stripped;
            }
            if s.contains('{') {
                return Err(err(
                    t.start,
                    "IFS005",
                    format!("'{{' inside entry '{name}' (entries cannot nest)"),
                ));
            }
            if !s.is_empty() {
                match parse_number(s) {
                    Ok(v) => {
                        if nums.len() >= MAX_ROWS * if *three_d { 13 } else { 7 } {
                            return Err(err(
                                t.start,
                                "IFS016",
                                format!("entry '{name}' has more than {MAX_ROWS} rows"),
                            ));
                        }
                        nums.push((v, t.start));
                    }
                    Err(NumberError::Overflow) => {
                        return Err(err(
                            t.start,
                            "IFS008",
                            format!("'{s}' is not a finite number"),
                        ));
                    }
                    Err(e) => {
                        let code = "IFS006";
                        let lower = s.to_ascii_lowercase();
                        let msg = if lower.contains("nan") || lower.contains("inf") {
                            format!("'{s}' is not a finite number")
                        } else {
                            format!(
                                "{} (expected a number, a ';' comment or '}}')",
                                e.describe(s)
                            )
                        };
                        return Err(err(t.start, code, msg));
                    }
                }
            }
            if closes {
                let row = if *three_d { 13 } else { 7 };
                let n = nums.len();
                if n == 0 || n % row != 0 {
                    return Err(err(
                        t.start,
                        "IFS007",
                        format!(
                            "entry '{name}' holds {n} numbers; {} entries need a multiple of {row} ({row} per row) and at least one row",
                            if *three_d { "3-D" } else { "2-D" }
                        ),
                    ));
                }
                let rows: Vec<Vec<f64>> = nums
                    .chunks(row)
                    .map(|c| c.iter().map(|v| v.0).collect())
                    .collect();
                let mut psum = 0.0;
                for (ri, chunk) in nums.chunks(row).enumerate() {
                    let (p, off) = chunk[row - 1];
                    if p < 0.0 {
                        // Real collections have these (Fractint walks the cumulative sum, so
                        // the row is never chosen and shrinks the others' share): accept with
                        // Fractint's semantics and warn.
                        warnings.push(Diagnostic::warning(
                            file,
                            map.pos(off),
                            "IFS008",
                            format!("row {} of '{name}' has negative probability {p}; using Fractint's cumulative selection", ri + 1),
                        ));
                    }
                    psum += p;
                }
                let entry = IfsEntry {
                    name: name.clone(),
                    three_d: *three_d,
                    rows,
                };
                if psum == 0.0 {
                    warnings.push(Diagnostic::warning(
                        file,
                        map.pos(*hdr),
                        "IFS008",
                        format!("all probabilities of '{name}' are 0; weights will follow the determinant rule"),
                    ));
                } else if (psum - 1.0).abs() > 1e-6 + 1e-12
                    && entry.rows.iter().all(|r| r[row - 1] >= 0.0)
                {
                    warnings.push(Diagnostic::warning(
                        file,
                        map.pos(*hdr),
                        "IFS011",
                        format!(
                            "probabilities of '{name}' sum to {psum}, not 1; they are renormalised"
                        ),
                    ));
                }
                if entry.rows.len() > FRACTINT_MAX_ROWS {
                    warnings.push(Diagnostic::warning(
                        file,
                        map.pos(*hdr),
                        "IFS013",
                        format!(
                            "'{name}' has {} rows; Fractint reads at most {FRACTINT_MAX_ROWS}",
                            entry.rows.len()
                        ),
                    ));
                }
                if !entry.three_d {
                    for (ri, m) in entry.maps2d().iter().enumerate() {
                        let s = m.max_singular_value();
                        if s >= 1.0 {
                            warnings.push(Diagnostic::warning(
                                file,
                                map.pos(*hdr),
                                "IFS014",
                                format!("map {} of '{name}' is not contractive (largest singular value {s:.4}); the attractor may not exist", ri + 1),
                            ));
                        }
                    }
                }
                if let Some(prev) = out.entries.iter().find(|e| same_name(&e.name, name)) {
                    warnings.push(Diagnostic::warning(
                        file,
                        map.pos(*hdr),
                        "IFS012",
                        format!("entry name '{name}' repeats '{}' (Fractint compares the first {NAME_LEN} characters, ignoring case)", prev.name),
                    ));
                }
                out.entries.push(entry);
                cur = None;
                // Anything after '}' on the same line starts over as outside text.
                if k < toks.len() {
                    return Err(err(
                        toks[k].start,
                        "IFS001",
                        format!(
                            "'{}' after the end of entry; start the next entry on a new line",
                            toks[k].text
                        ),
                    ));
                }
                break;
            }
        }
    }
    if let Some((name, _, hdr, _)) = cur {
        let Pos::LineCol(l, c) = map.pos(hdr) else {
            unreachable!()
        };
        return Err(err(
            text.len(),
            "IFS004",
            format!("unterminated entry '{name}' opened at {l}:{c}"),
        ));
    }
    Ok(Parsed {
        value: out,
        warnings,
    })
}

fn same_name(a: &str, b: &str) -> bool {
    let k = |s: &str| s.chars().take(NAME_LEN).collect::<String>().to_lowercase();
    k(a) == k(b)
}

/// Write an `.ifs` file: CRLF, two-space indent, a blank line between entries. Names that
/// Fractint would confuse (equal in their first 18 characters, ignoring case) are an error.
pub fn write(f: &IfsFile) -> Result<String, String> {
    for (i, a) in f.entries.iter().enumerate() {
        if a.name.is_empty()
            || a.name
                .contains(|c: char| c.is_whitespace() || "(){};".contains(c))
        {
            return Err(format!(
                "'{}' cannot be an .ifs entry name (no spaces or ( ) {{ }} ;)",
                a.name
            ));
        }
        if let Some(b) = f.entries[..i].iter().find(|b| same_name(&a.name, &b.name)) {
            return Err(format!(
                "entry names '{}' and '{}' are the same for Fractint (first {NAME_LEN} characters, ignoring case)",
                b.name, a.name
            ));
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

/// Fractint (y up) ↔ flame (y down): conjugation with y → −y, its own inverse.
pub fn conjugate_y(m: &Affine) -> Affine {
    Affine::new(m.a, -m.b, -m.c, m.d, m.e, -m.f)
}

/// A 2-D entry as a flame; a 3-D entry as a flame that iterates the 3-D
/// system and shows it through Fractint's default 30°/30°/30° view. The camera is left to
/// automatic framing (the renderer frames flames without a camera).
pub fn entry_to_flame(e: &IfsEntry, defaults: &NewFlame) -> Flame {
    let mut f = defaults.flame();
    f.name = e.name.clone();
    f.kind = FlameKind::Ifs;
    f.has_camera = false;
    let p = e.probabilities();
    let psum: f64 = p.iter().sum();
    if e.three_d {
        f.ifs3d = Some(Ifs3d {
            rows: e
                .rows
                .iter()
                .map(|r| r.clone().try_into().expect("13 numbers"))
                .collect(),
            view_degrees: Ifs3d::FRACTINT_VIEW,
        });
        // One placeholder xform keeps the flame valid for code that expects xforms.
        f.xforms = vec![Xform::linear(Affine::IDENTITY, 1.0, 0.0)];
        return f;
    }
    let n = e.rows.len();
    let maps: Vec<Affine> = e.maps2d().iter().map(conjugate_y).collect();
    let weights = if p.iter().any(|v| *v < 0.0) {
        fractint_shares(&p)
    } else if psum > 0.0 {
        p.iter().map(|v| v / psum).collect()
    } else {
        Flame::determinant_weights(&maps)
    };
    f.xforms = maps
        .iter()
        .zip(weights)
        .enumerate()
        .map(|(i, (m, w))| {
            let c = if n > 1 {
                i as f64 / (n - 1) as f64
            } else {
                0.0
            };
            Xform::linear(*m, w, c)
        })
        .collect();
    f
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
pub fn flame_to_entry(f: &Flame) -> Result<(IfsEntry, Option<String>), String> {
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
        return Err("the flame's weights sum to 0".into());
    }
    let mut lost: Vec<&str> = Vec::new();
    for (i, x) in f.xforms.iter().enumerate() {
        let l = linear_weight(x).map_err(|v| {
            format!(
                "xform {} uses variation '{v}'; only linear flames can be saved as .ifs",
                i + 1
            )
        })?;
        if (0..n).any(|j| x.chaos_to(j) != 1.0) {
            return Err(format!(
                "xform {} uses xaos; .ifs files have no xaos",
                i + 1
            ));
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
            return Err("the flame has a final xform; .ifs files have none".into());
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
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_whitespace() || "(){};".contains(c) {
                '_'
            } else {
                c
            }
        })
        .collect();
    if s.is_empty() { "ifs".into() } else { s }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LIB: &str = "; a test library in Fractint's syntax\r\n\
fern {\r\n    0    0    0  .16 0   0 .01\r\n   .85  .04 -.04 .85 0 1.6 .85\r\n   .2  -.26  .23 .22 0 1.6 .07\r\n  -.15  .28  .26 .24 0 .44 .07\r\n  }\r\n\
binary { ; comment allowed here\n  ; and here\n  .5  .0 .0 .5 -2.563477 -0.000003 .333333   ; also comment allowed here\n  .5  .0 .0 .5  2.436544 -0.000003 .333333\n  .0 -.5 .5 .0  4.873085  7.563492 .333333\n  }\n\
3dfern (3D) {\n   .00  .00 0 .0 .18 .0 0  0.0 0.00 0 0.0 0 .01\n   .85  .00 0 .0 .85 .1 0 -0.1 0.85 0 1.6 0 .85\n   .20 -.20 0 .2 .20 .0 0  0.0 0.30 0 0.8 0 .07\n  -.20  .20 0 .2 .20 .0 0  0.0 0.30 0 0.8 0 .07\n  }\n\
tri(3d){\n 1 0 0 0 1 0 0 0 1 0 0 0 1 }\n";

    #[test]
    fn reads_the_fixture_syntax() {
        let p = parse(LIB, "lib.ifs").unwrap();
        let f = p.value;
        assert_eq!(f.entries.len(), 4);
        let fern = f.get("FERN").unwrap();
        assert_eq!(fern.rows.len(), 4);
        assert_eq!(fern.rows[1], vec![0.85, 0.04, -0.04, 0.85, 0.0, 1.6, 0.85]);
        let bin = f.get("binary").unwrap();
        assert_eq!(bin.rows.len(), 3);
        assert!(f.get("3dfern").unwrap().three_d);
        assert!(f.get("tri").unwrap().three_d);
        // binary's Σp = 0.999999 is within tolerance; tri's map is not contractive? (3-D: not checked)
        assert!(
            p.warnings.iter().all(|w| w.code != "IFS011"),
            "{:?}",
            p.warnings
        );
    }

    #[test]
    fn bad_inputs_have_codes_and_positions() {
        let cases: &[(&str, &str, (usize, usize))] = &[
            ("1 2 3\n", "IFS001", (1, 1)),
            ("fern\n{\n1 2 3 4 5 6 1\n}\n", "IFS002", (1, 1)),
            (" {\n1 2 3 4 5 6 1\n}\n", "IFS002", (1, 2)),
            ("fern { 1 2 3 4 5 6 1\n}\n", "IFS003", (1, 8)),
            ("\nfern {\n1 2 3 4 5 6 1\n", "IFS004", (4, 1)),
            ("a {\n1 2 3 4 5 6 1\nb {\n}\n", "IFS005", (3, 3)),
            ("a {\n1 2 x 4 5 6 1\n}\n", "IFS006", (2, 5)),
            ("a {\n1 2 3 4 5 6 1 7\n}\n", "IFS007", (3, 1)),
            ("a {\n}\n", "IFS007", (2, 1)),
            ("a {\n1 2 nan 4 5 6 1\n}\n", "IFS006", (2, 5)),
            ("a {\n1 2 1e999 4 5 6 1\n}\n", "IFS008", (2, 5)),
            ("a (4D) {\n1 2 3 4 5 6 1\n}\n", "IFS009", (1, 3)),
            ("a {\n0,5 0 0 0.5 0 0 1\n}\n", "IFS006", (2, 1)),
        ];
        for (src, code, (l, c)) in cases {
            let e = parse(src, "x.ifs").unwrap_err();
            assert_eq!(e.code, *code, "{src:?}: {e}");
            assert_eq!(e.pos, Pos::LineCol(*l, *c), "{src:?}: {e}");
        }
        let e = parse("\nfern {\n1 2 3 4 5 6 1\n", "x.ifs").unwrap_err();
        assert!(
            e.message
                .contains("unterminated entry 'fern' opened at 2:1"),
            "{e}"
        );
        let e = parse("a {\n0,5 0 0 0.5 0 0 1\n}\n", "x.ifs").unwrap_err();
        assert!(e.message.contains("decimal separator"), "{e}");
    }

    #[test]
    fn old_fractint_files_without_a_header_are_one_entry() {
        let text = "; fern, saved one IFS per file\r\n0 0 0 .16 0 0 .01\r\n.85 .04 -.04 .85 0 1.6 .85\r\n\
                    .2 -.26 .23 .22 0 1.6 .07\r\n-.15 .28 .26 .24 0 .44 .07\r\n";
        let p = parse(text, "old/FERN.IFS").unwrap();
        assert_eq!(p.value.entries.len(), 1);
        let e = &p.value.entries[0];
        assert_eq!(
            (e.name.as_str(), e.three_d, e.rows.len()),
            ("FERN", false, 4)
        );
        assert_eq!(e.rows[1], vec![0.85, 0.04, -0.04, 0.85, 0.0, 1.6, 0.85]);
        assert_eq!(p.warnings[0].code, "IFS017");
        assert!(
            p.warnings[0].message.contains("'FERN' (4 rows)"),
            "{}",
            p.warnings[0]
        );
        // 3-D rows (13 numbers) are recognised by their count.
        let p = parse(&"1 0 0 0 1 0 0 0 1 0 0 0 1\n".repeat(2), "cube.ifs").unwrap();
        assert!(p.value.entries[0].three_d);
        // Errors point into the file itself.
        let e = parse("0 0 0 .5 0 0 1\n1 2 3 4 5 6 7 8\n", "x.ifs").unwrap_err();
        assert_eq!((e.code, e.pos), ("IFS007", Pos::File));
        let p = parse("2 0 0 2 0 0 1\n", "big.ifs").unwrap();
        assert!(p.warnings.iter().any(|w| w.code == "IFS014"));
        // Text that is not numbers is not an old file.
        assert_eq!(
            parse("0 0 0 .5 0 0 1 x\n", "x.ifs").unwrap_err().code,
            "IFS001"
        );
    }

    #[test]
    fn accepted_with_warnings() {
        let p = parse("a {\n.5 0 0 .5 0 0 .33}\n", "x.ifs").unwrap();
        assert!(p.warnings.iter().any(|w| w.code == "IFS010"));
        assert!(p.warnings.iter().any(|w| w.code == "IFS011"));
        let p = parse("a {\n2 0 0 2 0 0 1\n}\nA {\n.5 0 0 .5 0 0 1\n}\n", "x.ifs").unwrap();
        assert!(p.warnings.iter().any(|w| w.code == "IFS014"));
        assert!(p.warnings.iter().any(|w| w.code == "IFS012"));
        let many: String = std::iter::once("big {\n".to_string())
            .chain((0..64).map(|_| ".1 0 0 .1 0 0 1\n".to_string()))
            .chain(std::iter::once("}\n".to_string()))
            .collect();
        let p = parse(&many, "x.ifs").unwrap();
        assert!(p.warnings.iter().any(|w| w.code == "IFS013"));
    }

    #[test]
    fn write_read_round_trip_is_exact() {
        let f = parse(LIB, "lib.ifs").unwrap().value;
        let text = write(&f).unwrap();
        assert!(text.contains("\r\n") && text.contains("3dfern (3D) {\r\n"));
        assert!(
            text.starts_with("fern {\r\n  0 0 0 0.16 0 0 0.01\r\n"),
            "{text}"
        );
        let g = parse(&text, "w.ifs").unwrap().value;
        assert_eq!(f, g);
        assert_eq!(write(&g).unwrap(), text);
        let dup = IfsFile {
            entries: vec![
                f.entries[0].clone(),
                IfsEntry {
                    name: "FERN".into(),
                    ..f.entries[0].clone()
                },
            ],
        };
        assert!(write(&dup).unwrap_err().contains("same for Fractint"));
    }

    #[test]
    fn fern_becomes_an_upright_flame_and_back() {
        let f = parse(LIB, "lib.ifs").unwrap().value;
        let flame = entry_to_flame(f.get("fern").unwrap(), &NewFlame::default());
        assert_eq!(flame.xforms.len(), 4);
        assert_eq!(flame.kind, FlameKind::Ifs);
        assert!(!flame.has_camera);
        // coefs="0.85 0.04 -0.04 0.85 0 -1.6" for the second row.
        assert_eq!(
            flame.xforms[1].coefs.to_coefs(),
            [0.85, 0.04, -0.04, 0.85, 0.0, -1.6]
        );
        assert_eq!(flame.xforms[0].color, 0.0);
        assert_eq!(flame.xforms[3].color, 1.0);
        assert!((flame.xforms[1].weight - 0.85).abs() < 1e-12);
        let (e, warn) = flame_to_entry(&flame).unwrap();
        assert!(warn.unwrap().contains("lost"));
        for (a, b) in e.rows.iter().zip(&f.get("fern").unwrap().rows) {
            for (x, y) in a.iter().zip(b) {
                assert!((x - y).abs() < 1e-12, "{a:?} vs {b:?}");
            }
        }
    }

    #[test]
    fn only_linear_flames_export() {
        let f = parse(LIB, "lib.ifs").unwrap().value;
        let mut flame = entry_to_flame(f.get("fern").unwrap(), &NewFlame::default());
        flame.xforms[2].vars = vec![crate::flame::model::Var::new(variations::SWIRL, 1.0)];
        assert_eq!(
            flame_to_entry(&flame).unwrap_err(),
            "xform 3 uses variation 'swirl'; only linear flames can be saved as .ifs"
        );
        // Linear weight and post fold into the map.
        let mut flame = entry_to_flame(f.get("binary").unwrap(), &NewFlame::default());
        flame.xforms[0].vars[0].weight = 2.0;
        flame.xforms[0].post = Affine::new(1.0, 0.0, 0.0, 1.0, 0.5, 0.0);
        let (e, _) = flame_to_entry(&flame).unwrap();
        assert!((e.rows[0][0] - 1.0).abs() < 1e-12);
        assert!((e.rows[0][4] - (2.0 * -2.563477 + 0.5)).abs() < 1e-9);
    }

    #[test]
    fn negative_probabilities_follow_fractint() {
        let p = parse(
            "h {\n.5 0 0 .5 0 0 -0.2\n.5 0 0 .5 1 0 0.5\n.5 0 0 .5 0 1 0.5\n}\n",
            "h.ifs",
        )
        .unwrap();
        let w = p.warnings.iter().find(|w| w.code == "IFS008").unwrap();
        assert_eq!(w.pos, Pos::LineCol(2, 15));
        let flame = entry_to_flame(&p.value.entries[0], &NewFlame::default());
        let ws: Vec<f64> = flame.xforms.iter().map(|x| x.weight).collect();
        // Cumulative −0.2, 0.3, 0.8 → shares 0, 0.3, 0.7 (the last row takes the rest).
        for (a, b) in ws.iter().zip([0.0, 0.3, 0.7]) {
            assert!((a - b).abs() < 1e-12, "{ws:?}");
        }
        assert_eq!(
            fractint_shares(&[0.25, 0.25, 0.25, 0.25]),
            vec![0.25, 0.25, 0.25, 0.25]
        );
    }

    #[test]
    fn zero_probabilities_use_the_determinant_rule() {
        let p = parse("z {\n.5 0 0 .5 0 0 0\n.25 0 0 .25 1 0 0\n}\n", "z.ifs").unwrap();
        assert!(p.warnings.iter().any(|w| w.code == "IFS008"));
        let flame = entry_to_flame(&p.value.entries[0], &NewFlame::default());
        let w: Vec<f64> = flame.xforms.iter().map(|x| x.weight).collect();
        assert!(
            (w[0] - 0.8).abs() < 1e-12 && (w[1] - 0.2).abs() < 1e-12,
            "{w:?}"
        );
    }
}
