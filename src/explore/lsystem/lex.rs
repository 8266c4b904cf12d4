//! The lexer of axioms and productions: Fractint's command set split into commands.

/// Symbols that cannot have productions (Fractint's reserved commands).
pub const RESERVED: &str = "+-<>[]|!@/\\c";

/// A syntax error in an axiom or production: byte offset and what was expected.
#[derive(Clone, Debug, PartialEq)]
pub struct LexError {
    /// Byte offset of the error in the string.
    pub offset: usize,
    /// What was expected there.
    pub message: String,
}

/// One command of a string, as read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lexeme {
    /// A symbol that may be rewritten (lower-cased).
    Symbol(char),
    /// `+`: turn by +δ.
    Plus,
    /// `-`: turn by −δ.
    Minus,
    /// `|`: turn half way round.
    Reverse,
    /// `!`: swap the meanings of `+` and `-`.
    Swap,
    /// `[`: save the turtle's state.
    Push,
    /// `]`: restore the last state saved.
    Pop,
    /// `\nn`: +nn° on the degree heading.
    DegreesLeft(f64),
    /// `/nn`: −nn° on the degree heading.
    DegreesRight(f64),
    /// `cnn`: colour index nn.
    SetColor(i64),
    /// `<nn`
    ColorUp(i64),
    /// `>nn`
    ColorDown(i64),
    /// `@…`: the step factor (inverse and square root already applied).
    Scale(f64),
}

/// Read a number at `i`: digits with an optional fraction (`12`, `1.5`, `.5`).
fn number(s: &[u8], i: usize, fraction: bool) -> Option<(f64, usize)> {
    let mut j = i;
    while j < s.len() && s[j].is_ascii_digit() {
        j += 1;
    }
    let mut digits = j - i;
    if fraction && j < s.len() && s[j] == b'.' {
        let k = j + 1;
        let mut e = k;
        while e < s.len() && s[e].is_ascii_digit() {
            e += 1;
        }
        digits += e - k;
        if e > k || digits > 0 {
            j = e;
        }
    }
    if digits == 0 {
        return None;
    }
    let v: f64 = std::str::from_utf8(&s[i..j]).ok()?.parse().ok()?;
    v.is_finite().then_some((v, j))
}

/// Split an axiom or production into commands, each with its byte offset and text.
pub fn lex(s: &str) -> Result<Vec<(usize, &str, Lexeme)>, LexError> {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let start = i;
        let ch = s[i..].chars().next().unwrap_or(' ');
        let err = |m: &str| LexError {
            offset: start,
            message: m.to_string(),
        };
        i += ch.len_utf8();
        let lx = match ch.to_ascii_lowercase() {
            '+' => Lexeme::Plus,
            '-' => Lexeme::Minus,
            '|' => Lexeme::Reverse,
            '!' => Lexeme::Swap,
            '[' => Lexeme::Push,
            ']' => Lexeme::Pop,
            '\\' | '/' => {
                let (v, j) = number(b, i, true).ok_or_else(|| {
                    err(&format!(
                        "expected a number of degrees after '{ch}' (e.g. {ch}30)"
                    ))
                })?;
                i = j;
                if ch == '\\' {
                    Lexeme::DegreesLeft(v)
                } else {
                    Lexeme::DegreesRight(v)
                }
            }
            'c' | '<' | '>' => {
                let (v, j) = number(b, i, false).ok_or_else(|| {
                    err(&format!(
                        "expected a colour number after '{ch}' (e.g. {ch}12)"
                    ))
                })?;
                i = j;
                let v = v as i64;
                match ch {
                    '<' => Lexeme::ColorUp(v),
                    '>' => Lexeme::ColorDown(v),
                    _ => Lexeme::SetColor(v),
                }
            }
            '@' => {
                let (mut inv, mut sqrt) = (false, false);
                while i < b.len() {
                    match b[i].to_ascii_lowercase() {
                        b'i' => inv = !inv,
                        b'q' => sqrt = !sqrt,
                        _ => break,
                    }
                    i += 1;
                }
                let (mut v, j) = number(b, i, true).ok_or_else(|| {
                    err("expected a step factor after '@' (e.g. @.5, @I2 for 1/2, @Q2 for √2)")
                })?;
                i = j;
                if sqrt {
                    v = v.sqrt();
                }
                if inv {
                    if v == 0.0 {
                        return Err(err("'@I0' would divide the step by zero"));
                    }
                    v = 1.0 / v;
                }
                Lexeme::Scale(v)
            }
            c if c.is_whitespace() => {
                return Err(err("unexpected space inside a string of commands"));
            }
            c => Lexeme::Symbol(c),
        };
        out.push((start, &s[start..i], lx));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lexer() {
        let l = lex("f[@iq2-x]|[+!+!@.5x]C12<3>1\\46.37236/12").unwrap();
        let kinds: Vec<Lexeme> = l.iter().map(|x| x.2).collect();
        assert_eq!(kinds[0], Lexeme::Symbol('f'));
        assert_eq!(kinds[2], Lexeme::Scale(1.0 / 2f64.sqrt()));
        assert!(kinds.contains(&Lexeme::Scale(0.5)));
        assert!(kinds.contains(&Lexeme::SetColor(12)));
        assert!(kinds.contains(&Lexeme::ColorUp(3)));
        assert!(kinds.contains(&Lexeme::ColorDown(1)));
        assert!(kinds.contains(&Lexeme::DegreesLeft(46.37236)));
        assert!(kinds.contains(&Lexeme::DegreesRight(12.0)));
        assert_eq!(l[2].1, "@iq2");
        for bad in ["F@", "Fc", "\\", "@I0", "F F", "<x"] {
            assert!(lex(bad).is_err(), "{bad}");
        }
        assert_eq!(lex("F@q").unwrap_err().offset, 1);
    }
}
