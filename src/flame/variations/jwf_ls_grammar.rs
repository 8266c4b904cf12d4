//! The grammar text of JWildfire's `lsystem3D_js` (JWildfire 9.00, `LSystem3DWFFunc`, a
//! translation of Laurens Lapre's LParser; the behaviour written anew): how it is read and
//! how its axiom is rewritten into the production the turtle draws.
//!
//! The text is read line by line. Empty lines, lines starting with `#` and lines shorter than
//! five characters are skipped; otherwise the first word (up to a space or `#`) is the keyword
//! and the rest of the line (from the character after that word, up to a `#`) its argument:
//! * `recursion n` (rewriting rounds, default 1), `angle a` (degrees, default 45),
//!   `thickness t` (percent of a segment's length, default 100), `min_thickness t` (percent),
//!   `shape s` (1, the default: attached cylinders; anything else: blocks), `poly_limit n`,
//!   `color i r g b` (colour i, 0–99, from bytes), and `mutation`, `switch_yz`, `trace`,
//!   `no_wait`, which are read (an integer) and not used;
//! * `axiom text` and `rule X = text`, their white space removed, the text ending at a `#`.
//!
//! Any other keyword, or an argument that is not a number of the right kind (Java's
//! `Integer.parseInt`, no surrounding spaces; `Float.parseFloat`), and the text is not
//! used. A rule's left side is everything before the first `=`; the rule is looked up by its
//! first character and replaces it by everything after that character and one more (so
//! `rule AB = x` turns `A` into `=x`, as JWildfire's does). Characters without a rule become
//! `_` in the next round (the turtle's commands and digits keep themselves).

/// Most characters of a production (JWildfire's: 4 MiB − 50); a round that would go past it
/// stops where it is and ends the rewriting (the drawing then warns).
pub(super) const MAX_PRODUCTION: usize = 4 * 1024 * 1024 - 50;
/// Most characters read over all rewriting rounds (a production that neither grows nor
/// settles, such as `a`↔`b`, is not rewritten forever).
const MAX_WORK: usize = 1 << 28;
/// Most rules JWildfire's rule table takes (200 less its 42 built-in rules).
const MAX_USER_RULES: usize = 158;
/// Colour slots.
pub(super) const MAX_COLORS: usize = 100;
/// JWildfire's value of π (LParser's, six decimals: not `std`'s).
#[allow(clippy::approx_constant)]
pub(super) const PI: f64 = 3.141592;

/// A grammar read from its text.
#[derive(Clone, Debug)]
pub(super) struct Grammar {
    /// Rewriting rounds.
    pub recursion: i32,
    /// Turning angle, radians (rounded to a `float` as JWildfire does).
    pub angle: f64,
    /// Thickness as a fraction of a segment's length.
    pub thickness: f64,
    /// Smallest thickness (absolute).
    pub min_thickness: f32,
    /// Attached cylinders (else blocks).
    pub cylinders: bool,
    /// `poly_limit`, if given.
    pub poly_limit: Option<i32>,
    /// The colour table (red, green, blue in [0, 1]).
    pub colors: [[f32; 3]; MAX_COLORS],
    /// The axiom.
    pub axiom: Vec<char>,
    /// The rules as JWildfire keeps them, `X=text`, the built-in ones last.
    pub rules: Vec<Vec<char>>,
}

/// JWildfire's colour table before the text's `color` lines: grey, with 13 colours at 2–15.
fn default_colors() -> [[f32; 3]; MAX_COLORS] {
    let mut c = [[0.5f32; 3]; MAX_COLORS];
    let set: [[f32; 3]; 14] = [
        [0.8, 0.4, 0.4],
        [0.8, 0.8, 0.4],
        [0.4, 0.8, 0.4],
        [0.4, 0.8, 0.8],
        [0.4, 0.4, 0.8],
        [0.8, 0.4, 0.8],
        [0.2, 0.5, 0.2],
        [0.2, 0.5, 0.5],
        [0.2, 0.2, 0.5],
        [0.5, 0.2, 0.5],
        [0.6, 0.2, 0.2],
        [0.5, 0.5, 0.5],
        [0.75, 0.75, 0.75],
        [1.0, 1.0, 1.0],
    ];
    c[2..16].copy_from_slice(&set);
    c
}

/// The built-in rules JWildfire adds after the text's: each command and digit keeps itself;
/// `_` (last) is the rule of every character without one.
const BUILT_IN: &str = "+-&^<>%|!?:;'\"c[]{}FftgZz*$~.1234567890()_";

/// Java's `Character.isWhitespace`.
fn java_space(c: char) -> bool {
    (c.is_whitespace() && !matches!(c, '\u{a0}' | '\u{2007}' | '\u{202f}'))
        || ('\u{1c}'..='\u{1f}').contains(&c)
}

/// A tokenizer as JWildfire's `strTok`: each call skips the character the last token ended
/// on, then the delimiters, and returns the characters up to the next delimiter.
struct Tokens {
    s: Vec<char>,
    /// Position of the last token's end (−1 before the first).
    at: isize,
}

impl Tokens {
    fn new(s: Vec<char>) -> Tokens {
        Tokens { s, at: -1 }
    }

    fn next(&mut self, delims: &str) -> Option<String> {
        let n = self.s.len() as isize;
        if self.at == n {
            return None;
        }
        let is_delim = |c: char| delims.contains(c);
        self.at += 1;
        while self.at < n && is_delim(self.s[self.at as usize]) {
            self.at += 1;
        }
        if self.at >= n {
            self.at = n;
            return None;
        }
        let start = self.at as usize;
        loop {
            self.at += 1;
            if self.at >= n || is_delim(self.s[self.at as usize]) {
                break;
            }
        }
        Some(self.s[start..self.at as usize].iter().collect())
    }
}

/// Java's `Integer.parseInt`: an optional sign and decimal digits, nothing else.
fn parse_int(s: Option<&str>) -> Option<i32> {
    let s = s?;
    let digits = s.strip_prefix(['+', '-']).unwrap_or(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}

/// Java's `Double.parseDouble` for the decimal forms (surrounding control characters and
/// spaces trimmed, an optional `f`/`d` suffix, `NaN`, `Infinity`); hexadecimal forms are not
/// taken.
pub(super) fn parse_double(s: &str) -> Option<f64> {
    let s = s.trim_matches(|c: char| c <= ' ');
    let (sign, body) = match s.strip_prefix('-') {
        Some(b) => (-1.0, b),
        None => (1.0, s.strip_prefix('+').unwrap_or(s)),
    };
    match body {
        "NaN" => return Some(f64::NAN),
        "Infinity" => return Some(sign * f64::INFINITY),
        _ => {}
    }
    let body = body.strip_suffix(['f', 'F', 'd', 'D']).unwrap_or(body);
    let ok = body
        .bytes()
        .all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-'));
    if !ok || body.starts_with(['+', '-']) || !body.bytes().any(|b| b.is_ascii_digit()) {
        return None;
    }
    body.parse::<f64>().ok().map(|v| sign * v)
}

/// Java's `Float.parseFloat` (the decimal rounded to a `float` directly).
fn parse_float(s: Option<&str>) -> Option<f32> {
    let s = s?;
    let v = parse_double(s)?;
    if v.is_nan() || v.is_infinite() {
        return Some(v as f32);
    }
    // Round the decimal text to a float directly (not through a double).
    let t = s.trim_matches(|c: char| c <= ' ');
    let t = t.strip_suffix(['f', 'F', 'd', 'D']).unwrap_or(t);
    t.parse::<f32>().ok()
}

/// Reads a grammar as JWildfire's `readGrammar` does; `None` where JWildfire's gives up (an
/// empty text, an unknown keyword, an argument it cannot read, more rules than it holds).
pub(super) fn read_grammar(text: &str) -> Option<Grammar> {
    if text.is_empty() {
        return None;
    }
    let mut g = Grammar {
        recursion: 1,
        angle: 45.0,
        thickness: 100.0,
        min_thickness: 0.0,
        cylinders: true,
        poly_limit: None,
        colors: default_colors(),
        axiom: Vec::new(),
        rules: Vec::new(),
    };
    let mut axiom_missing = false;
    let mut shape = 1.0f64;
    // Java's readLine: lines end at \n, \r or \r\n.
    for line in text.split('\n').flat_map(|l| l.split('\r')) {
        let chars: Vec<char> = line.chars().collect();
        if chars.is_empty() || chars[0] == '#' || chars.len() < 5 {
            continue;
        }
        let mut tok = Tokens::new(chars);
        let keyword = tok.next(" \r\n#")?;
        let command = tok.next("\r\n#");
        let command = command.as_deref();
        match keyword.as_str() {
            "recursion" => g.recursion = parse_int(command)?,
            "mutation" | "switch_yz" | "trace" | "no_wait" => {
                parse_int(command)?;
            }
            "angle" => g.angle = f64::from(parse_float(command)?),
            "thickness" => g.thickness = f64::from(parse_float(command)?),
            "min_thickness" => g.min_thickness = parse_float(command)?,
            "poly_limit" => g.poly_limit = Some(parse_int(command)?),
            "shape" => shape = f64::from(parse_float(command)?),
            "color" => {
                let mut words = command?.split(' ').filter(|w| !w.is_empty());
                let mut num = || parse_int(words.next());
                let (i, r, gr, b) = (num()?, num()?, num()?, num()?);
                let slot = g.colors.get_mut(usize::try_from(i).ok()?)?;
                *slot = [r as f32 / 255.0, gr as f32 / 255.0, b as f32 / 255.0];
            }
            "axiom" => {
                let squeezed: Vec<char> = command?.chars().filter(|&c| !java_space(c)).collect();
                match Tokens::new(squeezed).next("\r\n\t#") {
                    Some(a) => {
                        g.axiom = a.chars().collect();
                        axiom_missing = false;
                    }
                    None => axiom_missing = true,
                }
            }
            "rule" => {
                let squeezed: Vec<char> = command?.chars().filter(|&c| !java_space(c)).collect();
                let mut t = Tokens::new(squeezed);
                // Java writes a missing part as "null".
                let left = t.next("=").unwrap_or_else(|| "null".into());
                let right = t.next("\r\n\t#").unwrap_or_else(|| "null".into());
                g.rules.push(format!("{left}={right}").chars().collect());
                if g.rules.len() > MAX_USER_RULES {
                    return None;
                }
            }
            _ => return None,
        }
    }
    if axiom_missing {
        return None;
    }
    g.rules.extend(BUILT_IN.chars().map(|c| vec![c, '=', c]));
    g.cylinders = shape == 1.0;
    g.angle = f64::from((g.angle / 180.0 * PI) as f32);
    g.thickness /= 100.0;
    g.min_thickness = (f64::from(g.min_thickness) / 100.0) as f32;
    Some(g)
}

/// The production after the grammar's rounds of rewriting, and whether a limit cut it short;
/// `None` where JWildfire's fails (a character beyond Latin-1 to rewrite).
pub(super) fn expand(g: &Grammar) -> Option<(Vec<char>, bool)> {
    // The rule of each character: the first rule starting with it, else the last (`_`).
    let last = g.rules.len().checked_sub(1)?;
    let mut rule_of = [last; 256];
    for (i, r) in g.rules.iter().enumerate().rev() {
        let c = *r.first()? as usize;
        *rule_of.get_mut(c)? = i;
    }
    let mut s = g.axiom.clone();
    let mut work = 0usize;
    let mut cut = false;
    for _ in 0..g.recursion.max(0) {
        let mut next = Vec::with_capacity(s.len());
        for &c in &s {
            let r = &g.rules[*rule_of.get(c as usize)?];
            let body = r.get(2..).unwrap_or(&[]);
            if next.len() + body.len() >= MAX_PRODUCTION {
                cut = true;
                break;
            }
            next.extend_from_slice(body);
        }
        work += s.len();
        let settled = next == s;
        s = next;
        if cut || settled {
            break;
        }
        if work > MAX_WORK {
            cut = true;
            break;
        }
    }
    Some((s, cut))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_follow_strtok() {
        let mut t = Tokens::new("recursion  2 # x".chars().collect());
        assert_eq!(t.next(" \r\n#").as_deref(), Some("recursion"));
        // The argument starts after the space that ended the keyword.
        assert_eq!(t.next("\r\n#").as_deref(), Some(" 2 "));
        assert_eq!(t.next("\r\n#").as_deref(), Some(" x"));
        assert_eq!(t.next("\r\n#"), None);
    }

    #[test]
    fn a_grammar_is_read_and_expanded() {
        let g = read_grammar(
            "recursion 2\nangle 90\nthickness 10\nshape 0\ncolor 5 255 0 51\n\
             axiom A B # comment\nrule A = F[+A]   # grow\n",
        )
        .unwrap();
        assert_eq!(g.recursion, 2);
        assert!((g.angle - PI / 2.0).abs() < 1e-6);
        assert!((g.thickness - 0.1).abs() < 1e-9);
        assert!(!g.cylinders);
        assert_eq!(g.colors[5], [1.0, 0.0, 0.2]);
        assert_eq!(g.axiom, "AB".chars().collect::<Vec<_>>());
        let (s, cut) = expand(&g).unwrap();
        assert!(!cut);
        // A → F[+A] → F[+F[+A]]; B has no rule: `_`, then `_` again.
        assert_eq!(s.iter().collect::<String>(), "F[+F[+A]]_");
    }

    #[test]
    fn texts_jwildfire_refuses_are_refused() {
        assert!(read_grammar("").is_none());
        assert!(read_grammar("recursion 2 \naxiom F").is_none());
        assert!(read_grammar("colour 1 2 3 4\naxiom F").is_none());
        assert!(read_grammar("color 100 1 2 3\naxiom F").is_none());
        assert!(read_grammar("angle 4x5\naxiom F").is_none());
        // Trailing spaces are fine for a float.
        assert!(read_grammar("angle 45  \naxiom FF").is_some());
    }

    #[test]
    fn a_production_that_settles_or_explodes_is_bounded() {
        let mut g = read_grammar("axiom F\nrule F = FF").unwrap();
        g.recursion = 1_000_000;
        let (s, cut) = expand(&g).unwrap();
        assert!(cut && s.len() < MAX_PRODUCTION && s.len() >= MAX_PRODUCTION / 2);
        let mut g = read_grammar("axiom F+F").unwrap();
        g.recursion = i32::MAX;
        assert_eq!(expand(&g).unwrap(), ("F+F".chars().collect(), false));
    }
}
