//! Reading an `.l` file as Fractint reads it: entry by entry, each on its own. Between
//! entries, lines that start none are skipped, and a `{ … }` block without a name (or named
//! `comment`) is a comment. Inside an entry a line is `Angle n`, `Axiom string`, a production
//! `X string` or `}`, its words split at blanks and `=` as Fractint splits them (`angle=6`,
//! `F=F+F`, `F = F+F`, `F F+F`). What Fractint would not understand — other lines, extra words,
//! a command without its number — is ignored with one warning per entry; an entry that cannot
//! be drawn (no angle, no axiom, a turtle command given a production, no `}`) is reported and
//! skipped, and the entries around it open. Only a file without any entry that opens is an
//! error: its first problem.

use std::collections::HashMap;

use super::{LFile, LINE_LIMIT, MAX_ENTRIES};
use crate::explore::lsystem::{self, ANGLE_DIVISIONS, Angle, LSystem, MAX_RULE_LEN, RESERVED};
use crate::io::diag::{Diagnostic, Parsed, Pos, lines};
use crate::io::fractint_text::{Reporter, Word, header, strip_comment, words};

type R<T> = Result<T, Diagnostic>;

/// An entry being read.
struct Open {
    name: String,
    at: usize,
    angle: Option<u32>,
    axiom: Option<String>,
    rules: Vec<(char, String)>,
    /// What was ignored: (offset, what), reported in one warning when the entry closes.
    ignored: Vec<(usize, String)>,
}

/// Where the reader is.
enum State {
    /// Between entries.
    Outside,
    /// Inside a comment block `{ … }`.
    Comment,
    /// Inside an entry.
    Entry(Box<Open>),
    /// In the rest of an entry that could not be read, up to its `}`.
    Skip,
}

/// The reader of an `.l` file: the file, its positions, the warnings and the problems of
/// skipped entries so far.
struct Reader<'a> {
    rep: Reporter<'a>,
    /// Errors of entries that were skipped (or of lines between entries), in file order.
    problems: Vec<Diagnostic>,
    state: State,
    out: LFile,
    /// The entries so far by their name in lower case (index of the first): finding a repeated
    /// name takes constant time, reading a file linear time.
    names: HashMap<String, usize>,
}

/// Parse the text of an `.l` file.
pub fn parse(text: &str, file: &str) -> R<Parsed<LFile>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut rd = Reader {
        rep: Reporter::new(text, file),
        problems: Vec::new(),
        state: State::Outside,
        out: LFile::default(),
        names: HashMap::new(),
    };
    for (base, line) in lines(text) {
        if line.chars().count() >= LINE_LIMIT {
            rd.rep.warn(
                base,
                "LSY011",
                format!(
                    "line of {} characters; Fractint reads only the first {}",
                    line.chars().count(),
                    LINE_LIMIT - 1
                ),
            );
        }
        rd.line(strip_comment(line), base)?;
    }
    if let State::Entry(o) = std::mem::replace(&mut rd.state, State::Outside) {
        let at = match rd.rep.map.pos(o.at) {
            Pos::LineCol(l, c) => format!(" opened at {l}:{c}"),
            _ => String::new(),
        };
        let e = rd.rep.err(
            o.at,
            "LSY003",
            format!(
                "unterminated entry '{}'{at}: end of file before '}}'",
                o.name
            ),
        );
        rd.problems.push(e);
    }
    if rd.out.entries.is_empty()
        && let Some(first) = rd.problems.first()
    {
        return Err(first.clone());
    }
    let mut warnings = rd.rep.warnings;
    warnings.extend(rd.problems.into_iter().map(|mut d| {
        d.warning = true;
        d
    }));
    warnings.sort_by_key(|d| match d.pos {
        Pos::LineCol(l, c) => (l, c),
        _ => (0, 0),
    });
    Ok(Parsed {
        value: rd.out,
        warnings,
    })
}

impl Reader<'_> {
    /// One line's code (its comment removed), at byte `base` of the file.
    fn line(&mut self, code: &str, base: usize) -> R<()> {
        match std::mem::replace(&mut self.state, State::Outside) {
            State::Outside => self.outside(code, base),
            State::Comment => {
                if !code.contains('}') {
                    self.state = State::Comment;
                }
                Ok(())
            }
            State::Skip => {
                if code.contains('{') {
                    // The skipped entry had no `}`: this line starts the next one.
                    self.outside(code, base)
                } else {
                    if !code.contains('}') {
                        self.state = State::Skip;
                    }
                    Ok(())
                }
            }
            State::Entry(mut open) => {
                if let Some(t) = words(code, base).iter().find(|t| t.text.contains('{')) {
                    // Fractint starts the next entry here: this one never closed.
                    let e = self.rep.err(
                        t.off,
                        "LSY004",
                        format!(
                            "'{{' inside entry '{}' (is its '}}' missing?); the entry is skipped",
                            open.name
                        ),
                    );
                    self.problems.push(e);
                    return self.outside(code, base);
                }
                match self.item(&mut open, code, base) {
                    Ok(false) => self.state = State::Entry(open),
                    Ok(true) => self.close(*open, code, base),
                    Err(e) => {
                        self.skip_entry(&open, e);
                        if !code.contains('}') {
                            self.state = State::Skip;
                        }
                    }
                }
                Ok(())
            }
        }
    }

    /// A line between entries: the header `Name {` of an entry (the rest of the line is its
    /// first line), a comment block, or a line Fractint skips.
    fn outside(&mut self, code: &str, base: usize) -> R<()> {
        let toks = words(code, base);
        let Some(first) = toks.first() else {
            return Ok(());
        };
        let Some(h) = header(code, base) else {
            let l = first.text.to_ascii_lowercase();
            let e = if l == "angle" || l == "axiom" || first.text.contains('=') {
                self.rep.err(
                    first.off,
                    "LSY001",
                    format!(
                        "'{}' outside any entry; an entry starts with 'Name {{'",
                        first.text
                    ),
                )
            } else {
                self.rep.err(
                    first.off,
                    "LSY002",
                    format!(
                        "expected '{{' after the entry name '{}' on the same line",
                        first.text
                    ),
                )
            };
            self.problems.push(e);
            return Ok(());
        };
        let name_words = words(h.before, h.start);
        let rest = &code[h.brace - base + 1..];
        let Some(name) = name_words.first().map(|w| w.text) else {
            // `{ … }` without a name: a comment block.
            if !rest.contains('}') {
                self.state = State::Comment;
            }
            return Ok(());
        };
        if name.eq_ignore_ascii_case("comment") {
            if !rest.contains('}') {
                self.state = State::Comment;
            }
            return Ok(());
        }
        if name_words.len() > 1 {
            self.rep.warn(
                name_words[1].off,
                "LSY002",
                format!(
                    "'{}' is not an entry name (names have no spaces); read as '{name}', as Fractint does",
                    h.before.trim()
                ),
            );
        }
        if self.out.entries.len() >= MAX_ENTRIES {
            return Err(self.rep.err(
                first.off,
                "LSY015",
                format!("more than {MAX_ENTRIES} entries in one file"),
            ));
        }
        if let Some(&prev) = self.names.get(&name.to_ascii_lowercase()) {
            let msg = format!(
                "a second entry named '{name}' (Fractint opens only the first, '{}')",
                self.out.entries[prev].name
            );
            self.rep.warn(first.off, "LSY014", msg);
        }
        self.state = State::Entry(Box::new(Open {
            name: name.to_string(),
            at: first.off,
            angle: None,
            axiom: None,
            rules: Vec::new(),
            ignored: Vec::new(),
        }));
        // The rest of the header line is read as the entry's first line.
        self.line(rest, h.brace + 1)
    }

    /// The entry closes on the line `code`: it opens if it has an angle and an axiom.
    fn close(&mut self, o: Open, code: &str, base: usize) {
        let toks = words(code, base);
        let close_off = toks.last().map_or(base, |t| t.off + t.text.len() - 1);
        if let Some((at, _)) = o.ignored.first() {
            let shown: Vec<String> = o
                .ignored
                .iter()
                .take(4)
                .map(|(off, what)| match self.rep.map.pos(*off) {
                    Pos::LineCol(l, _) => format!("line {l}: {what}"),
                    _ => what.clone(),
                })
                .collect();
            let more = o.ignored.len().saturating_sub(shown.len());
            self.rep.warn(
                *at,
                "LSY017",
                format!(
                    "in '{}', ignored what Fractint does not understand: {}{}",
                    o.name,
                    shown.join("; "),
                    if more > 0 {
                        format!("; and {more} more")
                    } else {
                        String::new()
                    }
                ),
            );
        }
        let Some(n) = o.angle else {
            let e = self.rep.err(
                close_off,
                "LSY005",
                format!("entry '{}' has no 'Angle n' line", o.name),
            );
            return self.problems.push(e);
        };
        let Some(axiom) = o.axiom else {
            let e = self.rep.err(
                close_off,
                "LSY006",
                format!("entry '{}' has no 'Axiom' line", o.name),
            );
            return self.problems.push(e);
        };
        let mut s = LSystem::new(&o.name, &axiom, &[], Angle::Divisions(n));
        s.rules = o.rules;
        self.names
            .entry(o.name.to_ascii_lowercase())
            .or_insert(self.out.entries.len());
        self.out.entries.push(s);
    }

    /// An entry that cannot be drawn: its problem is kept (with the entry's name) and the
    /// entry is skipped.
    fn skip_entry(&mut self, open: &Open, mut e: Diagnostic) {
        e.message = format!("{}; entry '{}' is skipped", e.message, open.name);
        self.problems.push(e);
    }

    /// One line of an entry (`code` at byte `base`): `Angle n`, `Axiom s`, a production or
    /// `}`; anything else is noted and ignored. True when the line closes the entry.
    fn item(&mut self, open: &mut Open, code: &str, base: usize) -> R<bool> {
        let toks = fractint_words(code, base);
        let Some(first) = toks.first() else {
            return Ok(false);
        };
        let lower = first.text.to_ascii_lowercase();
        let rest = &toks[1..];
        if first.text == "}" {
            self.extra(open, rest, "the '}' that closes the entry");
            return Ok(true);
        }
        if first.text.chars().count() == 1 {
            return self.production(open, first, rest);
        }
        match lower.as_str() {
            "angle" => self.angle(open, first, rest),
            "axiom" => self.axiom(open, first, rest),
            _ => {
                let (word, closes) = match first.text.strip_suffix('}') {
                    Some(w) => (w, true),
                    None => (first.text, false),
                };
                open.ignored.push((first.off, format!("'{word}'")));
                Ok(closes || self.extra(open, rest, ""))
            }
        }
    }

    /// Words after an item: a `}` closes the entry (true); anything else is ignored.
    fn extra(&mut self, open: &mut Open, rest: &[Word], after: &str) -> bool {
        let closes = rest.last().is_some_and(|t| t.text == "}");
        let extra = &rest[..rest.len() - closes as usize];
        if let Some(t) = extra.first() {
            let what = if after.is_empty() {
                format!("'{}'", t.text)
            } else {
                format!("'{}' after {after}", t.text)
            };
            open.ignored.push((t.off, what));
        }
        closes
    }

    /// `Angle n` (δ = 360°/n); true when `}` follows.
    fn angle(&mut self, open: &mut Open, first: &Word, rest: &[Word]) -> R<bool> {
        let v = rest.first().ok_or_else(|| {
            self.rep.err(
                first.off + first.text.len(),
                "LSY016",
                "expected the angle divisions n after 'Angle' (δ = 360°/n)".into(),
            )
        })?;
        let (vt, glued) = self.unglue(v);
        let n = vt
            .parse::<u32>()
            .ok()
            .filter(|n| ANGLE_DIVISIONS.contains(n))
            .ok_or_else(|| {
                self.rep.err(
                    v.off,
                    "LSY007",
                    format!("angle '{vt}' must be an integer from 3 to 49 (δ = 360°/n)"),
                )
            })?;
        if open.angle.is_some() {
            self.rep.warn(
                first.off,
                "LSY012",
                format!("a second Angle in '{}'; the last one counts", open.name),
            );
        }
        open.angle = Some(n);
        Ok(glued || self.extra(open, &rest[1..], "the angle"))
    }

    /// `Axiom string`; true when `}` follows.
    fn axiom(&mut self, open: &mut Open, first: &Word, rest: &[Word]) -> R<bool> {
        let v = rest.first().ok_or_else(|| {
            self.rep.err(
                first.off + first.text.len(),
                "LSY016",
                "expected the axiom string after 'Axiom'".into(),
            )
        })?;
        let (s, glued) = self.unglue(v);
        let s = self.commands(open, &s, v.off)?;
        if open.axiom.is_some() {
            self.rep.warn(
                first.off,
                "LSY012",
                format!("a second Axiom in '{}'; the last one counts", open.name),
            );
        }
        open.axiom = Some(s);
        Ok(glued || self.extra(open, &rest[1..], "the axiom"))
    }

    /// A production `X string` (`X=string`, `X string`; a missing string deletes X); true when
    /// `}` follows.
    fn production(&mut self, open: &mut Open, first: &Word, rest: &[Word]) -> R<bool> {
        let sym = first.text.chars().next().unwrap_or(' ');
        if RESERVED.contains(sym.to_ascii_lowercase()) {
            return Err(self.rep.err(
                first.off,
                "LSY008",
                format!("'{sym}' is a turtle command and cannot have a production"),
            ));
        }
        let (body, closes) = match rest.first() {
            None => (String::new(), false),
            Some(t) if t.text == "}" => (String::new(), true),
            Some(t) => {
                let (s, glued) = self.unglue(t);
                let s = self.commands(open, &s, t.off)?;
                let what = format!("the production {sym}=");
                (s, glued || self.extra(open, &rest[1..], &what))
            }
        };
        open.rules.push((sym, body));
        Ok(closes)
    }

    /// A string glued to the closing brace (`F+F}`): the string, and whether it closes.
    fn unglue(&mut self, t: &Word) -> (String, bool) {
        match t.text.strip_suffix('}') {
            Some(s) if !s.is_empty() => {
                self.rep.warn(
                    t.off + s.len(),
                    "LSY013",
                    "'}' glued to the string; Fractint needs it on its own".into(),
                );
                (s.to_string(), true)
            }
            _ => (t.text.to_string(), false),
        }
    }

    /// An axiom or production body at byte `off`: commands the turtle cannot read (`@`
    /// without its factor, `C` without its colour …) are dropped and noted.
    fn commands(&mut self, open: &mut Open, s: &str, off: usize) -> R<String> {
        if s.len() > MAX_RULE_LEN {
            return Err(self.rep.err(
                off,
                "LSY015",
                format!(
                    "string of {} characters; the limit is {MAX_RULE_LEN}",
                    s.len()
                ),
            ));
        }
        let mut s = s.to_string();
        // Each pass removes one character, so this ends.
        while let Err(e) = lsystem::lex(&s) {
            let Some(c) = s.get(e.offset..).and_then(|t| t.chars().next()) else {
                break;
            };
            open.ignored
                .push((off, format!("'{c}' in '{s}' ({})", e.message)));
            s.replace_range(e.offset..e.offset + c.len_utf8(), "");
        }
        Ok(s)
    }
}

/// The words of an entry's line as Fractint splits them: the first word ends at a blank or
/// `=`, and so does a production's string; `=` between words is skipped.
fn fractint_words(code: &str, base: usize) -> Vec<Word<'_>> {
    let mut out = Vec::new();
    let mut i = 0;
    let b = code.as_bytes();
    let sep = |c: u8| c.is_ascii_whitespace() || c == b'=';
    while i < b.len() {
        while i < b.len() && sep(b[i]) {
            i += 1;
        }
        let s = i;
        while i < b.len() && !sep(b[i]) {
            i += 1;
        }
        if i > s {
            out.push(Word {
                text: &code[s..i],
                off: base + s,
            });
        }
    }
    out
}
