//! An L-system compiled for drawing: productions merged by symbol and turned into tokens, the
//! heading table, and what a derivation holds at an order (predicted from the production
//! lengths, or the derived string itself).

use std::collections::HashMap;

use super::lex::{Lexeme, RESERVED, lex};
use super::system::{
    ANGLE_DIVISIONS, Angle, LSystem, MAX_DRAW_SYMBOLS, MAX_ORDER, MAX_RULE_LEN, MAX_STRING,
};
use crate::explore::{ExploreError, P2};

impl LSystem {
    /// Check and prepare the system for drawing.
    pub fn compile(&self) -> Result<Compiled, ExploreError> {
        Compiled::new(self)
    }
}

/// What a token does when the turtle reaches it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Cmd {
    Draw,
    Move,
    DrawDeg,
    MoveDeg,
    Turn(f64),
    Reverse,
    DegTurn(f64),
    SetColor(i64),
    AddColor(i64),
    Swap,
    Scale(f64),
    Push,
    Pop,
    Nop,
}

pub(super) const NO_RULE: u32 = u32::MAX;

#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Token {
    /// Index of the production to expand, or NO_RULE.
    pub(super) rule: u32,
    pub(super) cmd: Cmd,
}

/// A token list with the source text of every token.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Str {
    pub(super) tokens: Vec<Token>,
    texts: Vec<Box<str>>,
}

/// An L-system ready to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct Compiled {
    /// The L-system compiled.
    pub system: LSystem,
    pub(super) axiom: Str,
    /// Productions by index; symbols without one are not rewritten.
    pub(super) rules: Vec<Str>,
    /// Lower-cased symbol of each production.
    rule_symbols: Vec<char>,
    /// Half-turn in units of δ for `|`.
    pub(super) half_turn: f64,
    /// δ in radians.
    pub(super) delta: f64,
    /// Unit vectors for the headings k·δ (k = 0..n−1) when δ = 360°/n.
    pub(super) table: Option<Vec<P2>>,
}

/// How big the derivation gets at one order.
#[derive(Clone, Debug, PartialEq)]
pub struct Counts {
    /// The order (number of rewriting steps) counted.
    pub order: u32,
    /// Length of the derived string (a command with its number counts once).
    pub symbols: f64,
    /// Segments drawn (`F`, `D` and the extra draw symbols).
    pub segments: f64,
    /// Symbol visits of the depth-first walk (leaves and expanded symbols).
    pub visits: f64,
}

impl Compiled {
    fn new(sys: &LSystem) -> Result<Compiled, ExploreError> {
        let delta_deg = sys.angle.degrees();
        check_system(sys)?;
        let (rule_symbols, bodies) = merged_rules(sys)?;
        let draws: Vec<char> = sys
            .draw_symbols
            .chars()
            .map(|c| c.to_ascii_lowercase())
            .collect();
        let index: HashMap<char, u32> = rule_symbols
            .iter()
            .enumerate()
            .map(|(i, c)| (*c, i as u32))
            .collect();
        let compile = |what: &str, s: &str| compile_str(sys, what, s, &index, &draws);
        let axiom = compile("axiom", &sys.axiom)?;
        let rules = rule_symbols
            .iter()
            .zip(&bodies)
            .map(|(c, b)| compile(&format!("production {c}"), b))
            .collect::<Result<Vec<_>, _>>()?;
        let (half_turn, table) = match sys.angle {
            Angle::Divisions(n) => {
                let start = sys.start_heading.to_radians();
                let t = (0..n)
                    .map(|k| {
                        let a = start + std::f64::consts::TAU * k as f64 / n as f64;
                        let (s, c) = a.sin_cos();
                        [c, s]
                    })
                    .collect();
                ((n / 2) as f64, Some(t))
            }
            Angle::Degrees(d) => (180.0 / d, None),
        };
        Ok(Compiled {
            system: sys.clone(),
            axiom,
            rules,
            rule_symbols,
            half_turn,
            delta: delta_deg.to_radians(),
            table,
        })
    }

    /// String length, segments and walk visits after `order` steps, from the production
    /// lengths (nothing is expanded). Saturates at f64's range.
    pub fn counts(&self, order: u32) -> Counts {
        type C3 = (f64, f64, f64);
        let draws = |cmd: Cmd| matches!(cmd, Cmd::Draw | Cmd::DrawDeg) as u8 as f64;
        // e[r]: (symbols, segments, visits) of the walk below one symbol of production r at
        // the current remaining depth; at depth 0 the symbol is a leaf.
        let body = |s: &Str, e: &[C3]| -> C3 {
            let mut acc = (0.0, 0.0, 0.0);
            for t in &s.tokens {
                let v = if t.rule != NO_RULE {
                    e[t.rule as usize]
                } else {
                    (1.0, draws(t.cmd), 1.0)
                };
                acc = (acc.0 + v.0, acc.1 + v.1, acc.2 + v.2);
            }
            acc
        };
        let mut e: Vec<C3> = self
            .rule_symbols
            .iter()
            .map(|&c| (1.0, draws(self.symbol_cmd(c)), 1.0))
            .collect();
        for _ in 0..order {
            // One more level: a visit of the symbol plus the walk of its production.
            e = self
                .rules
                .iter()
                .map(|s| {
                    let b = body(s, &e);
                    (b.0, b.1, b.2 + 1.0)
                })
                .collect();
        }
        let (symbols, segments, visits) = body(&self.axiom, &e);
        Counts {
            order,
            symbols,
            segments,
            visits,
        }
    }

    /// What a rewritable symbol does at a leaf.
    fn symbol_cmd(&self, c: char) -> Cmd {
        match c {
            'f' => Cmd::Draw,
            'g' => Cmd::Move,
            'd' => Cmd::DrawDeg,
            'm' => Cmd::MoveDeg,
            c if self
                .system
                .draw_symbols
                .chars()
                .any(|x| x.to_ascii_lowercase() == c) =>
            {
                Cmd::Draw
            }
            _ => Cmd::Nop,
        }
    }

    pub(super) fn check_order(&self, order: u32) -> Result<Counts, ExploreError> {
        crate::explore::check_range("the order", order as f64, 0.0, MAX_ORDER as f64)?;
        let c = self.counts(order);
        if c.visits > MAX_DRAW_SYMBOLS {
            return Err(ExploreError::TooLarge {
                what: format!("'{}' at order {order}", self.system.name),
                count: c.visits,
                limit: MAX_DRAW_SYMBOLS,
                hint: " symbol visits; lower the order".into(),
            });
        }
        Ok(c)
    }

    /// The derived string after `order` steps (refused when its predicted length exceeds
    /// [`MAX_STRING`]).
    pub fn derive_string(&self, order: u32) -> Result<String, ExploreError> {
        crate::explore::check_range("the order", order as f64, 0.0, MAX_ORDER as f64)?;
        let c = self.counts(order);
        if c.symbols > MAX_STRING {
            return Err(ExploreError::TooLarge {
                what: format!("the string of '{}' at order {order}", self.system.name),
                count: c.symbols,
                limit: MAX_STRING,
                hint: " symbols; lower the order".into(),
            });
        }
        let mut out = String::new();
        self.walk_texts(&self.axiom, order, &mut out);
        Ok(out)
    }

    fn walk_texts(&self, s: &Str, depth: u32, out: &mut String) {
        for (t, text) in s.tokens.iter().zip(&s.texts) {
            if depth > 0 && t.rule != NO_RULE {
                self.walk_texts(&self.rules[t.rule as usize], depth - 1, out);
            } else {
                out.push_str(text);
            }
        }
    }
}

/// Refuse an angle outside Fractint's range, a non-finite start heading or an empty axiom.
fn check_system(sys: &LSystem) -> Result<(), ExploreError> {
    match sys.angle {
        Angle::Divisions(n) if !ANGLE_DIVISIONS.contains(&n) => {
            return Err(ExploreError::Invalid(format!(
                "angle {n} must be an integer from 3 to 49 (δ = 360°/n)"
            )));
        }
        Angle::Degrees(d) if !(d.is_finite() && d > 0.0 && d <= 360.0) => {
            return Err(ExploreError::Invalid(format!(
                "angle {d}° must be above 0° and at most 360°"
            )));
        }
        _ => {}
    }
    if !sys.start_heading.is_finite() {
        return Err(ExploreError::Invalid(
            "the start heading must be finite".into(),
        ));
    }
    if sys.axiom.is_empty() {
        return Err(ExploreError::Invalid(format!(
            "'{}': the axiom is empty",
            sys.name
        )));
    }
    Ok(())
}

/// The production symbols (lower-cased) and their bodies, repeated rules concatenated;
/// reserved commands cannot have one.
fn merged_rules(sys: &LSystem) -> Result<(Vec<char>, Vec<String>), ExploreError> {
    let mut rule_symbols: Vec<char> = Vec::new();
    let mut bodies: Vec<String> = Vec::new();
    for (c, body) in &sys.rules {
        let lc = c.to_ascii_lowercase();
        if RESERVED.contains(lc) {
            return Err(ExploreError::Invalid(format!(
                "'{}': '{c}' is a command and cannot have a production",
                sys.name
            )));
        }
        match rule_symbols.iter().position(|s| *s == lc) {
            Some(i) => bodies[i].push_str(body),
            None => {
                rule_symbols.push(lc);
                bodies.push(body.clone());
            }
        }
    }
    Ok((rule_symbols, bodies))
}

/// The axiom or a production (`what`, for messages) as tokens: each symbol with the index of
/// its production in `index`, and the command it stands for (`draws`: the extra drawing
/// symbols).
fn compile_str(
    sys: &LSystem,
    what: &str,
    s: &str,
    index: &HashMap<char, u32>,
    draws: &[char],
) -> Result<Str, ExploreError> {
    if s.len() > MAX_RULE_LEN {
        return Err(ExploreError::TooLarge {
            what: format!("'{}': {what}", sys.name),
            count: s.len() as f64,
            limit: MAX_RULE_LEN as f64,
            hint: String::new(),
        });
    }
    let lx = lex(s).map_err(|e| {
        ExploreError::Invalid(format!(
            "'{}': {what}, character {}: {}",
            sys.name,
            s[..e.offset].chars().count() + 1,
            e.message
        ))
    })?;
    let mut tokens = Vec::with_capacity(lx.len());
    let mut texts = Vec::with_capacity(lx.len());
    for (_, text, l) in lx {
        let (rule, cmd) = match l {
            Lexeme::Symbol(c) => (
                index.get(&c).copied().unwrap_or(NO_RULE),
                match c {
                    'f' => Cmd::Draw,
                    'g' => Cmd::Move,
                    'd' => Cmd::DrawDeg,
                    'm' => Cmd::MoveDeg,
                    c if draws.contains(&c) => Cmd::Draw,
                    _ => Cmd::Nop,
                },
            ),
            Lexeme::Plus => (NO_RULE, Cmd::Turn(1.0)),
            Lexeme::Minus => (NO_RULE, Cmd::Turn(-1.0)),
            Lexeme::Reverse => (NO_RULE, Cmd::Reverse),
            Lexeme::Swap => (NO_RULE, Cmd::Swap),
            Lexeme::Push => (NO_RULE, Cmd::Push),
            Lexeme::Pop => (NO_RULE, Cmd::Pop),
            Lexeme::DegreesLeft(v) => (NO_RULE, Cmd::DegTurn(v)),
            Lexeme::DegreesRight(v) => (NO_RULE, Cmd::DegTurn(-v)),
            Lexeme::SetColor(v) => (NO_RULE, Cmd::SetColor(v)),
            Lexeme::ColorUp(v) => (NO_RULE, Cmd::AddColor(v)),
            Lexeme::ColorDown(v) => (NO_RULE, Cmd::AddColor(-v)),
            Lexeme::Scale(v) => (NO_RULE, Cmd::Scale(v)),
        };
        tokens.push(Token { rule, cmd });
        texts.push(text.into());
    }
    Ok(Str { tokens, texts })
}

#[cfg(test)]
mod tests {
    use super::super::presets::*;
    use super::*;

    fn count(s: &str, c: char) -> usize {
        s.chars().filter(|x| *x == c).count()
    }

    #[test]
    fn kovacs_koch_strings() {
        let c = koch_kovacs().system.compile().unwrap();
        for (n, len) in [(1, 9), (2, 49), (3, 249)] {
            let s = c.derive_string(n).unwrap();
            assert_eq!(s.len(), len);
            assert_eq!(count(&s, 'S'), 5usize.pow(n));
            let k = c.counts(n);
            assert_eq!(k.symbols, len as f64);
            assert_eq!(k.segments, 5f64.powi(n as i32));
            assert_eq!(c.segments(n).unwrap().count(), 5usize.pow(n));
        }
        assert_eq!(c.derive_string(1).unwrap(), "S+S-S-S+S");
        // 90° turns: the quadratic Koch curve, D = log 5/log 3 = 1.46497.
        let d = crate::explore::dimension::equal_ratio_dimension(5, 1.0 / 3.0);
        assert!((d - 1.46497).abs() < 5e-6);
    }

    #[test]
    fn kovacs_plant_strings() {
        let c = plant_kovacs().system.compile().unwrap();
        for (n, f, s, len) in [(1, 3, 4, 18), (2, 18, 16, 89), (3, 84, 64, 379)] {
            let st = c.derive_string(n).unwrap();
            assert_eq!(count(&st, 'F'), f, "n={n}");
            assert_eq!(count(&st, 'S'), s, "n={n}");
            assert_eq!(st.len(), len, "n={n}");
            assert_eq!(c.counts(n).segments, f as f64);
            assert_eq!(c.segments(n).unwrap().count(), f);
        }
    }

    #[test]
    fn graftal_strings() {
        let c = graftal().system.compile().unwrap();
        assert_eq!(c.derive_string(1).unwrap(), "1[0]1[0]0");
        assert_eq!(
            c.derive_string(2).unwrap(),
            "11[1[0]1[0]0]11[1[0]1[0]0]1[0]1[0]0"
        );
        for (n, zeros, ones, len) in [(1, 3, 2, 9), (2, 9, 10, 35), (3, 27, 38, 117)] {
            let s = c.derive_string(n).unwrap();
            assert_eq!(
                (count(&s, '0'), count(&s, '1'), s.len()),
                (zeros, ones, len)
            );
            assert_eq!(c.segments(n).unwrap().count(), zeros + ones);
        }
        // Every branch turns the same way (by +δ): no segment heads right of vertical.
        for s in c.segments(3).unwrap() {
            assert!(s.b[0] - s.a[0] <= 1e-12, "{s:?}");
        }
    }

    #[test]
    fn fibonacci_strings() {
        let c = fibonacci().system.compile().unwrap();
        let want = [
            "b",
            "a",
            "ab",
            "aba",
            "abaab",
            "abaababa",
            "abaababaabaab",
            "abaababaabaababaababa",
        ];
        for (n, w) in want.iter().enumerate() {
            assert_eq!(c.derive_string(n as u32).unwrap(), *w);
        }
        let (mut prev, mut cur) = (1.0, 2.0);
        for n in 2..40 {
            assert_eq!(c.counts(n).symbols, cur, "n={n}");
            (prev, cur) = (cur, prev + cur);
        }
        assert_eq!(c.counts(5).segments, 0.0);
    }

    #[test]
    fn slide_system_counts() {
        let c = koch_snowflake().system.compile().unwrap();
        for (n, f, len) in [(1, 12, 28), (2, 48, 112), (3, 192, 448)] {
            let s = c.derive_string(n).unwrap();
            assert_eq!((count(&s, 'F'), s.len()), (f, len));
        }
        let c = quadratic_koch_island().system.compile().unwrap();
        for (n, f, len) in [(1, 32, 59), (2, 256, 475)] {
            let s = c.derive_string(n).unwrap();
            assert_eq!((count(&s, 'F'), s.len()), (f, len));
        }
        // With a fixed step each side spans 4ⁿ steps (its 8ⁿ segments end 4ⁿ further along
        // x): drawn at one size, the step shrinks 4× per level.
        for n in 0..4u32 {
            let end = c.segments(n).unwrap().nth(8usize.pow(n) - 1).unwrap().b;
            assert!((end[0] - 4f64.powi(n as i32)).abs() < 1e-9 && end[1].abs() < 1e-9);
        }
        let c = plant_a().system.compile().unwrap();
        for (n, len) in [(1, 11), (2, 61), (3, 311), (4, 1561), (5, 7811)] {
            let s = c.derive_string(n).unwrap();
            assert_eq!(s.len(), len);
            assert_eq!(count(&s, 'F'), 5usize.pow(n));
            assert_eq!(c.counts(n).symbols, len as f64);
        }
    }

    #[test]
    fn limits() {
        let c = koch_curve().system.compile().unwrap();
        assert!(c.segments(MAX_ORDER + 1).is_err());
        // 4¹⁵ segments exceed the walk limit; the refusal comes before any drawing.
        let e = c.segments(15).unwrap_err();
        assert!(e.to_string().contains("lower the order"), "{e}");
        assert!(c.derive_string(12).is_err());
        let bad = LSystem::new("b", "F", &[('+', "F")], Angle::Divisions(4));
        assert!(bad.compile().is_err());
        let bad = LSystem::new("b", "F", &[], Angle::Divisions(2));
        assert!(bad.compile().is_err());
        let bad = LSystem::new("b", "F", &[], Angle::Divisions(50));
        assert!(bad.compile().is_err());
        let bad = LSystem::new("b", "", &[], Angle::Divisions(4));
        assert!(bad.compile().is_err());
        let bad = LSystem::new("b", "F@", &[], Angle::Divisions(4));
        let e = bad.compile().unwrap_err().to_string();
        assert!(e.contains("character 2") && e.contains("'@'"), "{e}");
        // Push without pop: the walk stops at the nesting limit instead of eating memory.
        let deep = LSystem::new("d", "X", &[('X', "[[XX")], Angle::Divisions(4));
        let c = deep.compile().unwrap();
        let mut s = c.segments(20).unwrap();
        assert_eq!(s.by_ref().count(), 0);
        assert!(s.error().is_some());
    }
}
