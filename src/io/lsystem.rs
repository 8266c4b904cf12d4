//! Fractint L-system files (`.l`): read every entry, write them back.
//!
//! ```text
//! Name {            ; comment
//!   Angle n         ; δ = 360°/n, n an integer from 3 to 49
//!   Axiom string
//!   a=string        ; production for symbol a (case-insensitive); "F=" deletes F
//! }
//! ```
//!
//! One item per line (Fractint reads a line's first word and the string after it); `;` starts a
//! comment anywhere. Repeated productions for one symbol are concatenated. Strings are checked
//! with the turtle's command syntax, so a missing number after `@`, `C`, `<`, `>`, `\` or `/`
//! is reported at its line and column.

use crate::explore::lsystem::{self, ANGLE_DIVISIONS, Angle, LSystem, MAX_RULE_LEN, RESERVED};
use crate::io::diag::{Diagnostic, Parsed, Pos, SourceMap, lines, parse_int};
use crate::io::error::LSystemWriteError;
use crate::io::fractint_text::{self, Reporter, Word, check_name, header, strip_comment, words};

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

/// An entry being read.
struct Open {
    name: String,
    at: usize,
    angle: Option<u32>,
    axiom: Option<String>,
    rules: Vec<(char, String)>,
}

type R<T> = Result<T, Diagnostic>;

/// The reader of an `.l` file: the file, its positions, the warnings so far.
struct Reader<'a> {
    rep: Reporter<'a>,
}

/// Parse the text of an `.l` file.
pub fn parse(text: &str, file: &str) -> R<Parsed<LFile>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut rd = Reader {
        rep: Reporter::new(text, file),
    };
    let mut out = LFile::default();
    let mut cur: Option<Open> = None;
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
        let mut base = base;
        let mut code = strip_comment(line);
        if cur.is_none() {
            let toks = words(code, base);
            if toks.is_empty() {
                continue;
            }
            let (open, brace) = rd.header(code, base, &toks, &out)?;
            cur = Some(open);
            // The rest of the header line is read as the entry's first line.
            code = &code[brace - base + 1..];
            base = brace + 1;
        }
        let Some(open) = cur.as_mut() else {
            continue;
        };
        let toks = words(code, base);
        if toks.is_empty() {
            continue;
        }
        if rd.item(open, code, base, &toks)? {
            let Some(o) = cur.take() else { continue };
            let close_off = toks.last().map_or(base, |t| t.off + t.text.len() - 1);
            out.entries.push(rd.finish(o, close_off)?);
        }
    }
    if let Some(o) = cur {
        return Err(rd.rep.err(
            o.at,
            "LSY003",
            format!(
                "unterminated entry '{}' opened at {}: end of file before '}}'",
                o.name,
                match rd.rep.map.pos(o.at) {
                    Pos::LineCol(l, c) => format!("{l}:{c}"),
                    _ => String::new(),
                }
            ),
        ));
    }
    Ok(Parsed {
        value: out,
        warnings: rd.rep.warnings,
    })
}

impl Reader<'_> {
    /// A header line `Name {` outside any entry (`out`: the entries so far): the new entry and
    /// the offset of its `{`.
    fn header(&mut self, code: &str, base: usize, toks: &[Word], out: &LFile) -> R<(Open, usize)> {
        let first = &toks[0];
        let Some(h) = header(code, base) else {
            let l = first.text.to_ascii_lowercase();
            return Err(
                if l == "angle" || l == "axiom" || first.text.contains('=') {
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
                },
            );
        };
        let name = h.before.trim();
        check_name(name, &h).map_err(|b| self.rep.err(b.off, "LSY002", b.message))?;
        if out.entries.len() >= MAX_ENTRIES {
            return Err(self.rep.err(
                first.off,
                "LSY015",
                format!("more than {MAX_ENTRIES} entries in one file"),
            ));
        }
        if let Some(prev) = out
            .entries
            .iter()
            .find(|e| e.name.eq_ignore_ascii_case(name))
        {
            self.rep.warn(
                first.off,
                "LSY014",
                format!(
                    "a second entry named '{name}' (Fractint opens only the first, '{}')",
                    prev.name
                ),
            );
        }
        let open = Open {
            name: name.to_string(),
            at: first.off,
            angle: None,
            axiom: None,
            rules: Vec::new(),
        };
        Ok((open, h.brace))
    }

    /// One item of an entry (`code` at byte `base`, split into `toks`): `Angle n`, `Axiom s`,
    /// a production `X=s` or `}`. True when the line closes the entry.
    fn item(&mut self, open: &mut Open, code: &str, base: usize, toks: &[Word]) -> R<bool> {
        if let Some(t) = toks.iter().find(|t| t.text.contains('{')) {
            return Err(self.rep.err(
                t.off + t.text.find('{').unwrap_or(0),
                "LSY004",
                format!("'{{' inside entry '{}' (is its '}}' missing?)", open.name),
            ));
        }
        let first = &toks[0];
        let lower = first.text.to_ascii_lowercase();
        if first.text == "}" {
            if let Some(t) = toks.get(1) {
                return Err(self.rep.err(
                    t.off,
                    "LSY001",
                    format!("'{}' after the '}}' that closes '{}'", t.text, open.name),
                ));
            }
            Ok(true)
        } else if lower == "angle" {
            self.angle(open, toks)
        } else if lower == "axiom" {
            self.axiom(open, toks)
        } else if let Some(eq) = code.find('=') {
            self.production(open, code, base, eq)
        } else {
            Err(self.rep.err(
                first.off,
                "LSY009",
                format!(
                    "expected 'Angle n', 'Axiom string', a production 'X=string' or '}}' in '{}', found '{}'",
                    open.name, first.text
                ),
            ))
        }
    }

    /// `Angle n` (δ = 360°/n); true when `}` follows.
    fn angle(&mut self, open: &mut Open, toks: &[Word]) -> R<bool> {
        let first = &toks[0];
        let v = toks.get(1).ok_or_else(|| {
            self.rep.err(
                first.off + first.text.len(),
                "LSY016",
                "expected the angle divisions n after 'Angle' (δ = 360°/n)".into(),
            )
        })?;
        let (vt, glued) = self.unglue(v);
        let n = parse_int(&vt)
            .ok()
            .filter(|n| *n >= 0 && ANGLE_DIVISIONS.contains(&(*n as u32)))
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
        open.angle = Some(n as u32);
        Ok(glued || self.rest_closes(&toks[2..], "the angle")?)
    }

    /// `Axiom string`; true when `}` follows.
    fn axiom(&mut self, open: &mut Open, toks: &[Word]) -> R<bool> {
        let first = &toks[0];
        let v = toks.get(1).ok_or_else(|| {
            self.rep.err(
                first.off + first.text.len(),
                "LSY016",
                "expected the axiom string after 'Axiom'".into(),
            )
        })?;
        let (s, glued) = self.unglue(v);
        check_string(&s, v.off, &self.rep.map, self.rep.file)?;
        if open.axiom.is_some() {
            self.rep.warn(
                first.off,
                "LSY012",
                format!("a second Axiom in '{}'; the last one counts", open.name),
            );
        }
        open.axiom = Some(s);
        Ok(glued || self.rest_closes(&toks[2..], "the axiom")?)
    }

    /// A production `X=string` with its `=` at `eq` of `code`; true when `}` follows.
    fn production(&mut self, open: &mut Open, code: &str, base: usize, eq: usize) -> R<bool> {
        let lhs = code[..eq].trim();
        let lhs_off = base + code[..eq].find(|c: char| !c.is_whitespace()).unwrap_or(0);
        let mut chars = lhs.chars();
        let sym = match (chars.next(), chars.next()) {
            (Some(c), None) => c,
            (None, _) => {
                return Err(self.rep.err(
                    base + eq,
                    "LSY009",
                    "a production needs its symbol before '=' (e.g. F=F+F)".into(),
                ));
            }
            _ => {
                return Err(self.rep.err(
                    lhs_off,
                    "LSY009",
                    format!("'{lhs}' before '=': a production rewrites one symbol (e.g. F=F+F)"),
                ));
            }
        };
        if RESERVED.contains(sym.to_ascii_lowercase()) {
            return Err(self.rep.err(
                lhs_off,
                "LSY008",
                format!("'{sym}' is a turtle command and cannot have a production"),
            ));
        }
        let rtoks = words(&code[eq + 1..], base + eq + 1);
        let (body, closes) = match rtoks.first() {
            None => (String::new(), false),
            Some(t) if t.text == "}" => (String::new(), self.rest_closes(&rtoks, "")?),
            Some(t) => {
                let (s, glued) = self.unglue(t);
                check_string(&s, t.off, &self.rep.map, self.rep.file)?;
                let closes =
                    glued || self.rest_closes(&rtoks[1..], &format!("the production {sym}="))?;
                (s, closes)
            }
        };
        open.rules.push((sym, body));
        Ok(closes)
    }

    /// What follows the item on its line: nothing, or the closing brace.
    fn rest_closes(&self, rest: &[Word], what: &str) -> R<bool> {
        match rest {
            [] => Ok(false),
            [t] if t.text == "}" => Ok(true),
            [t, ..] => Err(self.rep.err(
                t.off,
                "LSY009",
                format!(
                    "unexpected '{}' after {what}; put each item on its own line (strings have no spaces)",
                    t.text
                ),
            )),
        }
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

    /// The entry closed at `close_off`: it needs an angle and an axiom.
    fn finish(&self, o: Open, close_off: usize) -> R<LSystem> {
        let Some(n) = o.angle else {
            return Err(self.rep.err(
                close_off,
                "LSY005",
                format!("entry '{}' has no 'Angle n' line", o.name),
            ));
        };
        let Some(axiom) = o.axiom else {
            return Err(self.rep.err(
                close_off,
                "LSY006",
                format!("entry '{}' has no 'Axiom' line", o.name),
            ));
        };
        let mut s = LSystem::new(&o.name, &axiom, &[], Angle::Divisions(n));
        s.rules = o.rules;
        Ok(s)
    }
}

/// Check an axiom or production body that starts at byte `off` of the file.
fn check_string(s: &str, off: usize, map: &SourceMap, file: &str) -> Result<(), Diagnostic> {
    if s.len() > MAX_RULE_LEN {
        return Err(Diagnostic::error(
            file,
            map.pos(off),
            "LSY015",
            format!(
                "string of {} characters; the limit is {MAX_RULE_LEN}",
                s.len()
            ),
        ));
    }
    lsystem::lex(s)
        .map(|_| ())
        .map_err(|e| Diagnostic::error(file, map.pos(off + e.offset), "LSY010", e.message))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explore::lsystem::presets;

    const OWN: &str = "; test systems in Fractint's syntax\r\n\
        \r\n\
        Koch1 { ; the Koch curve\r\n\
        \x20 Angle 6\r\n\
        \x20 Axiom F\r\n\
        \x20 F=F+F--F+F\r\n\
        \x20 }\r\n\
        Dragon {\r\n\
        Angle 8 ; comment right after the number\r\n\
        Axiom FX\r\n\
        F=\r\n\
        y=+FX--FY+\r\n\
        x=-FX++FY-\r\n\
        }\r\n\
        Split*1 {\n\
        \x20 angle 12\n\
        \x20 axiom |c9f\n\
        \x20 f = f[@iq2+f]@.5f\n\
        \x20 f=>1f\n\
        \x20 G=GG ; upper case\n\
        }\n";

    #[test]
    fn reads_every_entry() {
        let p = parse(OWN, "own.l").unwrap();
        assert!(p.warnings.is_empty(), "{:?}", p.warnings);
        let f = p.value;
        assert_eq!(f.entries.len(), 3);
        assert_eq!(f.entries[0].name, "Koch1");
        assert_eq!(f.entries[0].angle, Angle::Divisions(6));
        assert_eq!(f.entries[0].rules, vec![('F', "F+F--F+F".to_string())]);
        let d = f.get("dragon").unwrap();
        assert_eq!(d.rules[0], ('F', String::new()));
        assert_eq!(d.axiom, "FX");
        let s = f.get("SPLIT*1").unwrap();
        assert_eq!(s.rules.len(), 3);
        assert_eq!(s.rules[0], ('f', "f[@iq2+f]@.5f".to_string()));
        // Repeated productions concatenate: f → f[@iq2+f]@.5f>1f.
        let c = s.compile().unwrap();
        assert_eq!(c.derive_string(1).unwrap(), "|c9f[@iq2+f]@.5f>1f");
        // The Koch curve of the file draws like the preset.
        let k = f.entries[0].compile().unwrap();
        assert_eq!(k.counts(5).segments, 1024.0);
        let dk = d.compile().unwrap();
        assert_eq!(dk.counts(10).segments, 1024.0);
    }

    #[test]
    fn round_trip() {
        let f = parse(OWN, "own.l").unwrap().value;
        let text = write(&f.entries).unwrap();
        assert!(text.contains("\r\n") && !text.replace("\r\n", "").contains('\n'));
        let g = parse(&text, "again.l").unwrap();
        assert!(g.warnings.is_empty());
        assert_eq!(g.value, f);
        assert_eq!(write(&g.value.entries).unwrap(), text);
    }

    #[test]
    fn presets_that_fit_the_format_are_written() {
        let mut written = 0;
        for p in presets::all() {
            let Ok(text) = write(std::slice::from_ref(&p.system)) else {
                continue;
            };
            written += 1;
            let back = parse(&text, "p.l").unwrap().value.entries.remove(0);
            // Same drawing: the same segments at the preset's order.
            let a: Vec<_> = p
                .system
                .compile()
                .unwrap()
                .segments(p.order.min(4))
                .unwrap()
                .collect();
            let b: Vec<_> = back
                .compile()
                .unwrap()
                .segments(p.order.min(4))
                .unwrap()
                .collect();
            assert_eq!(a.len(), b.len(), "{}", p.system.name);
            for (x, y) in a.iter().zip(&b) {
                for i in 0..2 {
                    assert!((x.b[i] - y.b[i]).abs() < 1e-9, "{}", p.system.name);
                }
            }
        }
        assert!(written >= 6, "{written}");
        // 25° cannot be written; neither can extra draw symbols.
        assert!(write(&[presets::plant_kovacs().system]).is_err());
        assert!(write(&[presets::koch_kovacs().system]).is_err());
    }

    fn code_of(text: &str) -> (String, usize) {
        let e = parse(text, "bad.l").unwrap_err();
        (e.code.to_string(), e.line().unwrap_or(0))
    }

    #[test]
    fn bad_inputs_name_line_and_expectation() {
        assert_eq!(code_of("K {\n Angle 6\n Axiom F\n"), ("LSY003".into(), 1));
        assert_eq!(code_of("K\n Angle 6\n"), ("LSY002".into(), 1));
        assert_eq!(code_of(" Angle 6\n"), ("LSY001".into(), 1));
        assert_eq!(code_of("K {\n Axiom F\n}\n"), ("LSY005".into(), 3));
        assert_eq!(code_of("K {\n Angle 4\n}\n"), ("LSY006".into(), 3));
        assert_eq!(
            code_of("K {\n Angle 2\n Axiom F\n}\n"),
            ("LSY007".into(), 2)
        );
        assert_eq!(
            code_of("K {\n Angle 50\n Axiom F\n}\n"),
            ("LSY007".into(), 2)
        );
        assert_eq!(
            code_of("K {\n Angle 4.5\n Axiom F\n}\n"),
            ("LSY007".into(), 2)
        );
        assert_eq!(
            code_of("K {\n Angle 4\n Axiom F\n +=F\n}\n"),
            ("LSY008".into(), 4)
        );
        assert_eq!(
            code_of("K {\n Angle 4\n Axiom F\n c=F\n}\n"),
            ("LSY008".into(), 4)
        );
        assert_eq!(
            code_of("K {\n Angle 4\n Axiom F@\n}\n"),
            ("LSY010".into(), 3)
        );
        assert_eq!(
            code_of("K {\n Angle 4\n Axiom F\n F=F<\n}\n"),
            ("LSY010".into(), 4)
        );
        assert_eq!(
            code_of("K {\n Angle 4\n Axiom F\n bogus\n}\n"),
            ("LSY009".into(), 4)
        );
        assert_eq!(
            code_of("K {\n Angle 4\n Axiom F + F\n}\n"),
            ("LSY009".into(), 3)
        );
        assert_eq!(
            code_of("K {\n Angle 4\n Axiom F\n FG=F\n}\n"),
            ("LSY009".into(), 4)
        );
        assert_eq!(code_of("K {\n Angle 4\nL {\n}\n"), ("LSY004".into(), 3));
        assert_eq!(code_of("K {\n Angle\n}\n"), ("LSY016".into(), 2));
        let e = parse("K {\n Angle 4\n Axiom F\n F=F@x\n}\n", "bad.l").unwrap_err();
        assert_eq!(e.pos, Pos::LineCol(4, 5));
        assert!(
            e.to_string()
                .starts_with("bad.l:4:5: error[LSY010]: expected a step factor")
        );
        let e = parse("K {\n Angle 4\n", "bad.l").unwrap_err();
        assert!(
            e.message.contains("unterminated entry 'K' opened at 1:1"),
            "{e}"
        );
    }

    #[test]
    fn warnings() {
        let long = format!("K {{\n Angle 4\n Axiom {}\n}}\n", "F".repeat(170));
        let p = parse(&long, "w.l").unwrap();
        assert_eq!(p.warnings[0].code, "LSY011");
        let p = parse(
            "K {\n Angle 4\n Angle 6\n Axiom F\n}\nk {\n Angle 4\n Axiom F}\n",
            "w.l",
        )
        .unwrap();
        let codes: Vec<&str> = p.warnings.iter().map(|w| w.code).collect();
        assert_eq!(codes, ["LSY012", "LSY014", "LSY013"]);
        assert_eq!(p.value.entries[0].angle, Angle::Divisions(6));
        assert_eq!(p.value.entries[1].axiom, "F");
    }

    #[test]
    fn never_panics_on_odd_input() {
        for t in [
            "",
            "{",
            "}",
            "{}",
            "a{",
            "a {}",
            "a { } b",
            "a {\n=\n}",
            "a {\n Axiom\u{00e9}@\n}",
            "a {\n x=\u{1F600}\n Angle 3\n Axiom x\n}\n",
            "\u{feff}a {\n angle 3\n axiom f\n}",
            "a {\n Angle 99999999999999999999\n}",
        ] {
            let _ = parse(t, "x.l");
        }
    }
}
