//! Reading `.ifs` text: `name { … }` entries (2-D rows of 7 numbers, `(3D)` rows of 13) with
//! Fractint's tolerances and warnings, and old files of bare rows without a header.

use std::collections::HashMap;

use super::{FRACTINT_MAX_ROWS, IfsEntry, IfsFile, MAX_ENTRIES, MAX_ROWS, NAME_LEN, name_key};
use crate::io::diag::{Diagnostic, NumberError, Parsed, Pos, lines, parse_number};
use crate::io::fractint_text::{Header, Reporter, Word, check_name, header, strip_comment, words};

/// An entry being read.
struct OpenEntry {
    name: String,
    three_d: bool,
    /// Offset of the header (where the entry's warnings point).
    hdr: usize,
    /// The numbers so far, with their offsets.
    nums: Vec<(f64, usize)>,
}

impl OpenEntry {
    fn row_len(&self) -> usize {
        if self.three_d { 13 } else { 7 }
    }
}

/// The reader of `name { … }` entries: the file, its positions, what was read and said.
struct Reader<'a> {
    rep: Reporter<'a>,
    out: IfsFile,
    /// The entries so far by the part of their name Fractint compares (index of the first).
    names: HashMap<String, usize>,
}

type R<T> = Result<T, Diagnostic>;

/// Parse the text of an `.ifs` file. A file of bare rows without any `name {` header (as
/// Fractint wrote one IFS per file before version 16) is read as one entry named after the
/// file, with a warning.
pub fn parse(text: &str, file: &str) -> R<Parsed<IfsFile>> {
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
        for t in words(strip_comment(line), base) {
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
fn parse_entries(text: &str, file: &str) -> R<Parsed<IfsFile>> {
    let mut rd = Reader {
        rep: Reporter::new(text, file),
        out: IfsFile::default(),
        names: HashMap::new(),
    };
    let mut cur: Option<OpenEntry> = None;
    for (base, line) in lines(text) {
        let code = strip_comment(line);
        let toks = words(code, base);
        let Some(open) = cur.as_mut() else {
            if !toks.is_empty() {
                cur = Some(rd.header(code, base, &toks)?);
            }
            continue;
        };
        if let Some(b) = code.find('{') {
            return Err(rd.rep.err(
                base + b,
                "IFS005",
                format!("'{{' inside entry '{}' (entries cannot nest)", open.name),
            ));
        }
        if rd.body_line(open, &toks)? {
            cur = None;
        }
    }
    if let Some(open) = cur {
        let Pos::LineCol(l, c) = rd.rep.map.pos(open.hdr) else {
            unreachable!()
        };
        return Err(rd.rep.err(
            text.len(),
            "IFS004",
            format!("unterminated entry '{}' opened at {l}:{c}", open.name),
        ));
    }
    Ok(Parsed {
        value: rd.out,
        warnings: rd.rep.warnings,
    })
}

impl Reader<'_> {
    /// A header line outside any entry: name [ "(" qualifier ")" ] "{" — the name may be glued
    /// to "(" or "{"; nothing but a comment may follow "{".
    fn header(&self, code: &str, base: usize, toks: &[Word]) -> R<OpenEntry> {
        let Some(h) = header(code, base) else {
            let first = toks[0].text;
            return Err(
                if first.parse::<f64>().is_ok() || first.starts_with(['-', '+', '.']) {
                    self.rep.err(
                        toks[0].off,
                        "IFS001",
                        format!("'{first}' outside any entry; an entry starts with 'name {{'"),
                    )
                } else {
                    self.rep.err(
                        toks[0].off,
                        "IFS002",
                        format!("expected '{{' after the entry name '{first}' on the same line"),
                    )
                },
            );
        };
        let (name_part, qual) = self.qualifier(&h)?;
        let name = name_part.trim();
        check_name(name, &h).map_err(|b| {
            let code = if b.missing { "IFS002" } else { "IFS001" };
            self.rep.err(b.off, code, b.message)
        })?;
        let three_d = match qual {
            None => false,
            Some((q, _)) if q.eq_ignore_ascii_case("3d") => true,
            Some((q, off)) => {
                return Err(self.rep.err(
                    off,
                    "IFS009",
                    format!("unknown qualifier '({q})'; only (3D) is known"),
                ));
            }
        };
        let after = h.after.trim_start();
        if !after.is_empty() {
            return Err(self.rep.err(
                h.brace + 1 + (h.after.len() - after.len()),
                "IFS003",
                format!(
                    "'{}' after '{{' on the header line (Fractint skips the rest of this line); put the numbers on the next line",
                    after.split_whitespace().next().unwrap_or(after)
                ),
            ));
        }
        if self.out.entries.len() >= MAX_ENTRIES {
            return Err(self.rep.err(
                h.start,
                "IFS016",
                format!("more than {MAX_ENTRIES} entries"),
            ));
        }
        Ok(OpenEntry {
            name: name.to_string(),
            three_d,
            hdr: h.start,
            nums: Vec::new(),
        })
    }

    /// The name part of a header and its qualifier `(…)` with the qualifier's offset.
    fn qualifier<'h>(&self, h: &Header<'h>) -> R<(&'h str, Option<(&'h str, usize)>)> {
        let before = h.before;
        let Some(p) = before.find('(') else {
            return Ok((before, None));
        };
        let close = before[p..].find(')').map(|c| p + c).ok_or_else(|| {
            self.rep.err(
                h.start + p,
                "IFS009",
                "unclosed '(' in the entry header".into(),
            )
        })?;
        let q = before[p + 1..close].trim();
        if !before[close + 1..].trim().is_empty() {
            return Err(self.rep.err(
                h.start + close + 1,
                "IFS002",
                "unexpected text before '{'".into(),
            ));
        }
        Ok((&before[..p], Some((q, h.start + p))))
    }

    /// A line inside an entry: numbers, and the `}` that ends it (nothing may follow). True
    /// when the entry ended.
    fn body_line(&mut self, open: &mut OpenEntry, toks: &[Word]) -> R<bool> {
        for (k, t) in toks.iter().enumerate() {
            let mut s = t.text;
            let mut closes = false;
            if s == "}" {
                closes = true;
                s = "";
            } else if let Some(stripped) = s.strip_suffix('}') {
                // `.33}`: Fractint does not see the end here; accept with a warning.
                self.rep.warn(
                    t.off + stripped.len(),
                    "IFS010",
                    "'}' glued to a number; Fractint would not recognise the end of the entry"
                        .into(),
                );
                closes = true;
                s = stripped;
            }
            if s.contains('{') {
                return Err(self.rep.err(
                    t.off,
                    "IFS005",
                    format!("'{{' inside entry '{}' (entries cannot nest)", open.name),
                ));
            }
            if !s.is_empty() {
                self.push_number(open, s, t.off)?;
            }
            if closes {
                let entry = self.close_entry(open, t.off)?;
                self.out.entries.push(entry);
                // Anything after '}' on the same line starts over as outside text.
                if let Some(next) = toks.get(k + 1) {
                    return Err(self.rep.err(
                        next.off,
                        "IFS001",
                        format!(
                            "'{}' after the end of entry; start the next entry on a new line",
                            next.text
                        ),
                    ));
                }
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// One number of an entry's rows.
    fn push_number(&self, open: &mut OpenEntry, s: &str, off: usize) -> R<()> {
        match parse_number(s) {
            Ok(v) => {
                if open.nums.len() >= MAX_ROWS * open.row_len() {
                    return Err(self.rep.err(
                        off,
                        "IFS016",
                        format!("entry '{}' has more than {MAX_ROWS} rows", open.name),
                    ));
                }
                open.nums.push((v, off));
                Ok(())
            }
            Err(NumberError::Overflow) => {
                Err(self
                    .rep
                    .err(off, "IFS008", format!("'{s}' is not a finite number")))
            }
            Err(e) => {
                let lower = s.to_ascii_lowercase();
                let msg = if lower.contains("nan") || lower.contains("inf") {
                    format!("'{s}' is not a finite number")
                } else {
                    format!(
                        "{} (expected a number, a ';' comment or '}}')",
                        e.describe(s)
                    )
                };
                Err(self.rep.err(off, "IFS006", msg))
            }
        }
    }

    /// The entry ended by the `}` at `at`: whole rows, with warnings about probabilities, rows
    /// Fractint cannot read, maps that do not contract and names Fractint would confuse.
    fn close_entry(&mut self, open: &OpenEntry, at: usize) -> R<IfsEntry> {
        let name = &open.name;
        let row = open.row_len();
        let n = open.nums.len();
        if n == 0 || !n.is_multiple_of(row) {
            return Err(self.rep.err(
                at,
                "IFS007",
                format!(
                    "entry '{name}' holds {n} numbers; {} entries need a multiple of {row} ({row} per row) and at least one row",
                    if open.three_d { "3-D" } else { "2-D" }
                ),
            ));
        }
        let rows: Vec<Vec<f64>> = open
            .nums
            .chunks(row)
            .map(|c| c.iter().map(|v| v.0).collect())
            .collect();
        let mut psum = 0.0;
        for (ri, chunk) in open.nums.chunks(row).enumerate() {
            let (p, off) = chunk[row - 1];
            if p < 0.0 {
                // Real collections have these (Fractint walks the cumulative sum, so the row
                // is never chosen and shrinks the others' share): accept with Fractint's
                // semantics and warn.
                self.rep.warn(
                    off,
                    "IFS008",
                    format!("row {} of '{name}' has negative probability {p}; using Fractint's cumulative selection", ri + 1),
                );
            }
            psum += p;
        }
        let entry = IfsEntry {
            name: name.clone(),
            three_d: open.three_d,
            rows,
        };
        self.entry_warnings(&entry, psum, open.hdr);
        Ok(entry)
    }

    /// Warnings about a whole entry (at its header `hdr`); `psum` is the sum of its
    /// probabilities.
    fn entry_warnings(&mut self, entry: &IfsEntry, psum: f64, hdr: usize) {
        let name = &entry.name;
        let row = entry.row_len();
        if psum == 0.0 {
            self.rep.warn(
                hdr,
                "IFS008",
                format!(
                    "all probabilities of '{name}' are 0; weights will follow the determinant rule"
                ),
            );
        } else if (psum - 1.0).abs() > 1e-6 + 1e-12 && entry.rows.iter().all(|r| r[row - 1] >= 0.0)
        {
            self.rep.warn(
                hdr,
                "IFS011",
                format!("probabilities of '{name}' sum to {psum}, not 1; they are renormalised"),
            );
        }
        if entry.rows.len() > FRACTINT_MAX_ROWS {
            self.rep.warn(
                hdr,
                "IFS013",
                format!(
                    "'{name}' has {} rows; Fractint reads at most {FRACTINT_MAX_ROWS}",
                    entry.rows.len()
                ),
            );
        }
        if !entry.three_d {
            for (ri, m) in entry.maps2d().iter().enumerate() {
                let s = m.max_singular_value();
                if s >= 1.0 {
                    self.rep.warn(
                        hdr,
                        "IFS014",
                        format!("map {} of '{name}' is not contractive (largest singular value {s:.4}); the attractor may not exist", ri + 1),
                    );
                }
            }
        }
        let next = self.out.entries.len();
        if let Some(&prev) = self.names.get(&name_key(name)) {
            let msg = format!(
                "entry name '{name}' repeats '{}' (Fractint compares the first {NAME_LEN} characters, ignoring case)",
                self.out.entries[prev].name
            );
            self.rep.warn(hdr, "IFS012", msg);
        } else {
            self.names.insert(name_key(name), next);
        }
    }
}
