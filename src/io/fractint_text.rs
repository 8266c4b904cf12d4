//! The text of Fractint's entry files (`.ifs`, `.l`): lines without their `;` comments, words
//! with their byte offsets, entry headers `name {`, the rule for entry names, and where
//! problems are reported. Each format reads its entries on top of these and reports problems
//! with its own codes.

use crate::io::diag::{Diagnostic, SourceMap};

/// Diagnostics at byte offsets of a file, and the warnings so far.
pub(super) struct Reporter<'a> {
    pub(super) file: &'a str,
    pub(super) map: SourceMap<'a>,
    pub(super) warnings: Vec<Diagnostic>,
}

impl<'a> Reporter<'a> {
    pub(super) fn new(text: &'a str, file: &'a str) -> Self {
        Reporter {
            file,
            map: SourceMap::new(text),
            warnings: Vec::new(),
        }
    }

    /// An error at byte `off`.
    pub(super) fn err(&self, off: usize, code: &'static str, msg: String) -> Diagnostic {
        Diagnostic::error(self.file, self.map.pos(off), code, msg)
    }

    /// A warning at byte `off`, kept.
    pub(super) fn warn(&mut self, off: usize, code: &'static str, msg: String) {
        let d = Diagnostic::warning(self.file, self.map.pos(off), code, msg);
        self.warnings.push(d);
    }
}

/// A whitespace-separated word and the byte offset of its first character in the file.
pub(super) struct Word<'a> {
    pub(super) text: &'a str,
    pub(super) off: usize,
}

/// A line's code: the text before its `;` comment.
pub(super) fn strip_comment(line: &str) -> &str {
    match line.find(';') {
        Some(i) => &line[..i],
        None => line,
    }
}

/// The whitespace-separated words of `code`, which starts at byte `base` of the file.
pub(super) fn words(code: &str, base: usize) -> Vec<Word<'_>> {
    let mut out = Vec::new();
    let mut start: Option<usize> = None;
    for (i, ch) in code.char_indices() {
        if ch.is_whitespace() {
            if let Some(s) = start.take() {
                out.push(Word {
                    text: &code[s..i],
                    off: base + s,
                });
            }
        } else if start.is_none() {
            start = Some(i);
        }
    }
    if let Some(s) = start {
        out.push(Word {
            text: &code[s..],
            off: base + s,
        });
    }
    out
}

/// An entry header `name {`, split at its first `{`.
pub(super) struct Header<'a> {
    /// The code from the first word up to `{` (the name, in `.ifs` files with a qualifier).
    pub(super) before: &'a str,
    /// Offset of the first word in the file.
    pub(super) start: usize,
    /// Offset of `{` in the file.
    pub(super) brace: usize,
    /// The code after `{`.
    pub(super) after: &'a str,
}

/// The header on a line whose code is `code` (at byte `base` of the file): None when the line
/// has no word or no `{`.
pub(super) fn header(code: &str, base: usize) -> Option<Header<'_>> {
    let first = code.find(|c: char| !c.is_whitespace())?;
    let brace = code.find('{')?;
    Some(Header {
        before: &code[first..brace],
        start: base + first,
        brace: base + brace,
        after: &code[brace + 1..],
    })
}

/// An entry name that is not one: where, what, and whether it is missing (nothing before
/// `{`) rather than more than one word.
pub(super) struct BadName {
    pub(super) missing: bool,
    pub(super) off: usize,
    pub(super) message: String,
}

/// Check the entry name `name` (trimmed) of header `h`: present, and one word (no spaces, no
/// `}`).
pub(super) fn check_name(name: &str, h: &Header) -> Result<(), BadName> {
    if name.is_empty() {
        Err(BadName {
            missing: true,
            off: h.brace,
            message: "'{' without an entry name before it".into(),
        })
    } else if name.contains(char::is_whitespace) || name.contains('}') {
        Err(BadName {
            missing: false,
            off: h.start,
            message: format!("'{name}' is not an entry name (names have no spaces)"),
        })
    } else {
        Ok(())
    }
}

/// A valid entry name from any name: whitespace and the `reserved` characters become `_`;
/// an empty name becomes `fallback`.
pub(super) fn entry_name(name: &str, reserved: &str, fallback: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_whitespace() || reserved.contains(c) {
                '_'
            } else {
                c
            }
        })
        .collect();
    if s.is_empty() { fallback.into() } else { s }
}
