//! Diagnostics shared by every parser: file, 1-based line and column (in Unicode
//! scalar values) or byte offset, a stable code and a message.

use std::fmt;

/// Where a diagnostic points.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Pos {
    /// 1-based line and column.
    LineCol(usize, usize),
    /// Byte offset (binary formats).
    Byte(u64),
    /// The whole file.
    File,
}

/// An error or warning of a parser.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// The file's name as shown in messages.
    pub file: String,
    /// Where in the file.
    pub pos: Pos,
    /// A stable code naming the kind of problem (e.g. `IO001`).
    pub code: &'static str,
    /// What is wrong, for a person.
    pub message: String,
    /// A warning (the value was still read) rather than an error.
    pub warning: bool,
}

impl Diagnostic {
    /// An error of `file` at `pos`.
    pub fn error(file: &str, pos: Pos, code: &'static str, message: impl Into<String>) -> Self {
        Diagnostic {
            file: file.to_string(),
            pos,
            code,
            message: message.into(),
            warning: false,
        }
    }

    /// A warning of `file` at `pos`.
    pub fn warning(file: &str, pos: Pos, code: &'static str, message: impl Into<String>) -> Self {
        Diagnostic {
            warning: true,
            ..Self::error(file, pos, code, message)
        }
    }

    /// The line (from 1) for a text position; None otherwise.
    pub fn line(&self) -> Option<usize> {
        match self.pos {
            Pos::LineCol(l, _) => Some(l),
            _ => None,
        }
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = if self.warning { "warning" } else { "error" };
        match self.pos {
            Pos::LineCol(l, c) => write!(f, "{}:{}:{}: ", self.file, l, c)?,
            Pos::Byte(b) => write!(f, "{}: byte {}: ", self.file, b)?,
            Pos::File => write!(f, "{}: ", self.file)?,
        }
        write!(f, "{kind}[{}]: {}", self.code, self.message)
    }
}

impl std::error::Error for Diagnostic {}

/// A parsed value and the warnings met on the way.
#[derive(Clone, Debug)]
pub struct Parsed<T> {
    /// The value read.
    pub value: T,
    /// Warnings about it (unknown names, values replaced, …).
    pub warnings: Vec<Diagnostic>,
}

/// Byte offset → (line, column) for a text.
#[derive(Clone, Debug)]
pub struct SourceMap<'a> {
    text: &'a str,
    line_starts: Vec<usize>,
}

impl<'a> SourceMap<'a> {
    /// Lines end at LF, CRLF or a lone CR.
    pub fn new(text: &'a str) -> Self {
        let b = text.as_bytes();
        let mut line_starts = vec![0];
        let mut i = 0;
        while i < b.len() {
            match b[i] {
                b'\n' => line_starts.push(i + 1),
                b'\r' => {
                    if b.get(i + 1) == Some(&b'\n') {
                        i += 1;
                    }
                    line_starts.push(i + 1);
                }
                _ => {}
            }
            i += 1;
        }
        SourceMap { text, line_starts }
    }

    /// 1-based line and column (Unicode scalar values) of a byte offset.
    pub fn pos(&self, offset: usize) -> Pos {
        let offset = offset.min(self.text.len());
        let line = match self.line_starts.binary_search(&offset) {
            Ok(i) => i,
            Err(i) => i - 1,
        };
        let start = self.line_starts[line];
        let mut end = offset;
        while !self.text.is_char_boundary(end) {
            end -= 1;
        }
        let col = self.text[start..end].chars().count() + 1;
        Pos::LineCol(line + 1, col)
    }
}

/// Lines with their byte offsets; LF, CRLF and lone CR end a line.
pub fn lines(text: &str) -> Vec<(usize, &str)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut start = 0;
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'\n' || b[i] == b'\r' {
            out.push((start, &text[start..i]));
            if b[i] == b'\r' && b.get(i + 1) == Some(&b'\n') {
                i += 1;
            }
            start = i + 1;
        }
        i += 1;
    }
    if start < b.len() {
        out.push((start, &text[start..]));
    }
    out
}

/// Why a number token is rejected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NumberError {
    /// `0,5`: a comma used as decimal separator.
    Comma,
    /// nan, inf, hex, stray characters.
    Syntax,
    /// Does not fit an f64.
    Overflow,
}

impl NumberError {
    /// The message for token `tok` failing this way.
    pub fn describe(&self, tok: &str) -> String {
        match self {
            NumberError::Comma => format!(
                "'{tok}' uses a comma as decimal separator; write numbers with a point, e.g. '{}'",
                tok.replace(',', ".")
            ),
            NumberError::Syntax => format!("'{tok}' is not a number"),
            NumberError::Overflow => format!("'{tok}' is too large"),
        }
    }
}

/// Parse a number in the grammar shared by every text format:
/// `[+-]? ( digits [ "." digits? ] | "." digits ) ( [eE] [+-]? digits )?`.
pub fn parse_number(tok: &str) -> Result<f64, NumberError> {
    let b = tok.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let int_start = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    let int_digits = i - int_start;
    let mut frac_digits = 0;
    if i < b.len() && b[i] == b'.' {
        i += 1;
        let fs = i;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        frac_digits = i - fs;
    } else if i < b.len() && b[i] == b',' && int_digits > 0 {
        return Err(NumberError::Comma);
    }
    if int_digits == 0 && frac_digits == 0 {
        return Err(NumberError::Syntax);
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        i += 1;
        if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
            i += 1;
        }
        let es = i;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        if i == es {
            return Err(NumberError::Syntax);
        }
    }
    if i != b.len() {
        return Err(NumberError::Syntax);
    }
    // Rust's parser does not accept a leading '+' before '.', normalise it away.
    let v: f64 = tok
        .strip_prefix('+')
        .unwrap_or(tok)
        .parse()
        .map_err(|_| NumberError::Syntax)?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(NumberError::Overflow)
    }
}

/// Parse an integer token (no fraction, no exponent).
pub fn parse_int(tok: &str) -> Result<i64, NumberError> {
    let t = tok.strip_prefix('+').unwrap_or(tok);
    let digits = t.strip_prefix('-').unwrap_or(t);
    if digits.is_empty() || !digits.bytes().all(|c| c.is_ascii_digit()) {
        return Err(NumberError::Syntax);
    }
    t.parse().map_err(|_| NumberError::Overflow)
}

/// Format a number as ugnis writes it: shortest round-trip representation, never in exponent
/// form (Rust's `Display`), and `-0` written as `0`.
pub fn fmt_num(v: f64) -> String {
    if v == 0.0 {
        "0".to_string()
    } else {
        format!("{v}")
    }
}

/// Decode a legacy text file: UTF-8 (BOM skipped), or Windows-1252 with a warning.
pub fn decode_text(bytes: &[u8], file: &str) -> (String, Option<Diagnostic>) {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    match std::str::from_utf8(bytes) {
        Ok(s) => (s.to_string(), None),
        Err(_) => {
            let s: String = bytes.iter().map(|&c| cp1252(c)).collect();
            (
                s,
                Some(Diagnostic::warning(
                    file,
                    Pos::File,
                    "TXT001",
                    "file is not valid UTF-8; read as Windows-1252",
                )),
            )
        }
    }
}

fn cp1252(c: u8) -> char {
    const HIGH: [char; 32] = [
        '€', '\u{81}', '‚', 'ƒ', '„', '…', '†', '‡', 'ˆ', '‰', 'Š', '‹', 'Œ', '\u{8d}', 'Ž',
        '\u{8f}', '\u{90}', '‘', '’', '“', '”', '•', '–', '—', '˜', '™', 'š', '›', 'œ', '\u{9d}',
        'ž', 'Ÿ',
    ];
    match c {
        0x80..=0x9f => HIGH[(c - 0x80) as usize],
        _ => c as char,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers() {
        assert_eq!(parse_number("0.5"), Ok(0.5));
        assert_eq!(parse_number(".5"), Ok(0.5));
        assert_eq!(parse_number("-.5e1"), Ok(-5.0));
        assert_eq!(parse_number("+3."), Ok(3.0));
        assert_eq!(parse_number("+.25"), Ok(0.25));
        assert_eq!(parse_number("1E-3"), Ok(0.001));
        assert_eq!(parse_number("0,5"), Err(NumberError::Comma));
        for bad in [
            "nan", "inf", "-inf", "0x10", "", ".", "-", "1e", "1.2.3", "1 2", "e5",
        ] {
            assert_eq!(parse_number(bad), Err(NumberError::Syntax), "{bad}");
        }
        assert_eq!(parse_number("1e400"), Err(NumberError::Overflow));
        assert_eq!(parse_int("12"), Ok(12));
        assert_eq!(parse_int("-3"), Ok(-3));
        assert!(parse_int("1.0").is_err());
        assert!(parse_int("99999999999999999999999").is_err());
    }

    #[test]
    fn number_format_round_trips_without_exponent() {
        for v in [0.1, 1e-7, 1e21, -2.5, 1.0 / 3.0, 123456789.125] {
            let s = fmt_num(v);
            assert!(!s.contains('e'), "{s}");
            assert_eq!(s.parse::<f64>().unwrap(), v);
        }
        assert_eq!(fmt_num(-0.0), "0");
        assert_eq!(fmt_num(1.0), "1");
    }

    #[test]
    fn positions() {
        let m = SourceMap::new("ab\ncd\r\nef\rgh");
        assert_eq!(m.pos(0), Pos::LineCol(1, 1));
        assert_eq!(m.pos(4), Pos::LineCol(2, 2));
        assert_eq!(m.pos(7), Pos::LineCol(3, 1));
        assert_eq!(m.pos(10), Pos::LineCol(4, 1));
        let m = SourceMap::new("ää x");
        assert_eq!(m.pos(5), Pos::LineCol(1, 4));
        let d = Diagnostic::error("f.ifs", Pos::LineCol(3, 1), "IFS004", "unterminated");
        assert_eq!(d.to_string(), "f.ifs:3:1: error[IFS004]: unterminated");
    }

    #[test]
    fn legacy_decoding() {
        let (s, w) = decode_text(b"caf\xe9 \x80", "x.map");
        assert_eq!(s, "café €");
        assert!(w.is_some());
        let (s, w) = decode_text("\u{feff}ok".as_bytes(), "x");
        assert_eq!(s, "ok");
        assert!(w.is_none());
    }
}
