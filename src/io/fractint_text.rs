//! The text of Fractint's entry files (`.ifs`, `.l`): lines without their `;` comments, words
//! with their byte offsets, entry headers `name {` and the rule for entry names. Each format
//! reads its entries on top of these and reports problems with its own codes.

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

/// What is wrong with an entry name.
pub(super) enum BadName {
    /// Nothing before `{`.
    Missing,
    /// Spaces or `}` in it: names are one word.
    NotOneWord,
}

/// Check an entry name (trimmed): present, and one word.
pub(super) fn check_name(name: &str) -> Result<(), BadName> {
    if name.is_empty() {
        Err(BadName::Missing)
    } else if name.contains(char::is_whitespace) || name.contains('}') {
        Err(BadName::NotOneWord)
    } else {
        Ok(())
    }
}
