//! L-systems (deterministic, context-free: D0L) drawn by a turtle, with the command set of
//! Fractint's L-system type.
//!
//! The derivation is never built as a string for drawing: the turtle walks the derivation tree
//! depth-first (a symbol at depth d > 0 with a production is replaced by the symbols of its
//! production at depth d − 1), so memory grows with the order, not with the string length,
//! and segments come out one at a time ([`Segments`]).
//!
//! Turn convention: `+` turns counter-clockwise (left) by δ on screen and `−` clockwise, as in
//! Prusinkiewicz & Lindenmayer, *The Algorithmic Beauty of Plants* (1990). Fractint's `+` also
//! appears as a left turn on screen. Sources disagree for some systems, so every system carries
//! a swap flag (Fractint's `!` swaps at run time).
//!
//! Commands (case-insensitive, from Fractint's documentation): `F` draw forward, `G` move
//! forward, `+`/`-` turn by ±δ, `|` turn 180° (the largest multiple of δ below 180° when 360°/δ
//! is odd), `D`/`M` draw/move along a separate heading kept in degrees and turned by `\nn`
//! (+nn°) and `/nn` (−nn°), `Cnn` set colour, `<nn`/`>nn` add/subtract from the colour, `!`
//! swap `+`/`-` and `\`/`/`, `@nnn` multiply the step (`@I…` by the inverse, `@Q…` by the
//! square root), `[`/`]` save/restore the turtle. Any other symbol draws nothing.

use std::collections::HashMap;

use super::{Bounds, ExploreError, P2, raster};

/// Symbols a derived string may have ([`Compiled::derive_string`]).
pub const MAX_STRING: f64 = 1e7;
/// Symbols the turtle may visit when drawing (the string is never built).
pub const MAX_DRAW_SYMBOLS: f64 = 5e8;
/// Highest order (derivation steps).
pub const MAX_ORDER: u32 = 64;
/// Deepest nesting of `[` the turtle keeps.
pub const MAX_STACK: usize = 100_000;
/// Colour of the turtle at the start (white in Fractint's 16-colour palette).
pub const DEFAULT_COLOR: i64 = 15;
/// Fractint's range for the angle divisions n (δ = 360°/n).
pub const ANGLE_DIVISIONS: std::ops::RangeInclusive<u32> = 3..=49;
/// Most symbols in one axiom or production.
pub const MAX_RULE_LEN: usize = 100_000;

/// The turning angle δ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Angle {
    /// Fractint's `Angle n`: δ = 360°/n.
    Divisions(u32),
    /// δ in degrees.
    Degrees(f64),
}

impl Angle {
    pub fn degrees(self) -> f64 {
        match self {
            Angle::Divisions(n) => 360.0 / n as f64,
            Angle::Degrees(d) => d,
        }
    }
}

/// An L-system as written: axiom, productions, angle and interpretation flags.
#[derive(Clone, Debug, PartialEq)]
pub struct LSystem {
    pub name: String,
    pub axiom: String,
    /// Productions in file order: symbol (as written) and replacement. Repeated symbols are
    /// concatenated when compiled; an empty replacement deletes the symbol.
    pub rules: Vec<(char, String)>,
    pub angle: Angle,
    /// Start with `+` and `-` (and `\` and `/`) swapped.
    pub swap_signs: bool,
    /// Symbols that draw a step besides `F` and `D` (e.g. "S", "01").
    pub draw_symbols: String,
    /// `[` also turns by +δ after saving the turtle (Kovács' graftal).
    pub bracket_turn: bool,
    /// Start heading in degrees, counter-clockwise from +x (90 = up).
    pub start_heading: f64,
}

impl LSystem {
    /// A system with Fractint's defaults: no swap, heading +x, only `F`/`D` draw.
    pub fn new(name: &str, axiom: &str, rules: &[(char, &str)], angle: Angle) -> LSystem {
        LSystem {
            name: name.to_string(),
            axiom: axiom.to_string(),
            rules: rules.iter().map(|(c, s)| (*c, s.to_string())).collect(),
            angle,
            swap_signs: false,
            draw_symbols: String::new(),
            bracket_turn: false,
            start_heading: 0.0,
        }
    }

    /// Check and prepare the system for drawing.
    pub fn compile(&self) -> Result<Compiled, ExploreError> {
        Compiled::new(self)
    }
}

/// Symbols that cannot have productions (Fractint's reserved commands).
pub const RESERVED: &str = "+-<>[]|!@/\\c";

/// A syntax error in an axiom or production: byte offset and what was expected.
#[derive(Clone, Debug, PartialEq)]
pub struct LexError {
    pub offset: usize,
    pub message: String,
}

/// One command of a string, as read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lexeme {
    /// A symbol that may be rewritten (lower-cased).
    Symbol(char),
    Plus,
    Minus,
    Reverse,
    Swap,
    Push,
    Pop,
    /// `\nn`: +nn° on the degree heading.
    DegreesLeft(f64),
    /// `/nn`: −nn° on the degree heading.
    DegreesRight(f64),
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

/// What a token does when the turtle reaches it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Cmd {
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

const NO_RULE: u32 = u32::MAX;

#[derive(Clone, Copy, Debug, PartialEq)]
struct Token {
    /// Index of the production to expand, or NO_RULE.
    rule: u32,
    cmd: Cmd,
}

/// A token list with the source text of every token.
#[derive(Clone, Debug, PartialEq)]
struct Str {
    tokens: Vec<Token>,
    texts: Vec<Box<str>>,
}

/// An L-system ready to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct Compiled {
    pub system: LSystem,
    axiom: Str,
    /// Productions by index; symbols without one are not rewritten.
    rules: Vec<Str>,
    /// Lower-cased symbol of each production.
    rule_symbols: Vec<char>,
    /// Half-turn in units of δ for `|`.
    half_turn: f64,
    /// δ in radians.
    delta: f64,
    /// Unit vectors for the headings k·δ (k = 0..n−1) when δ = 360°/n.
    table: Option<Vec<P2>>,
}

/// How big the derivation gets at one order.
#[derive(Clone, Debug, PartialEq)]
pub struct Counts {
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
        // Production symbols, concatenating repeated rules.
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
        let compile = |what: &str, s: &str| -> Result<Str, ExploreError> {
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
        };
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

    fn check_order(&self, order: u32) -> Result<Counts, ExploreError> {
        super::check_range("the order", order as f64, 0.0, MAX_ORDER as f64)?;
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
        super::check_range("the order", order as f64, 0.0, MAX_ORDER as f64)?;
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

    /// The turtle's segments after `order` steps, one at a time.
    pub fn segments(&self, order: u32) -> Result<Segments<'_>, ExploreError> {
        let counts = self.check_order(order)?;
        Ok(Segments {
            sys: self,
            frames: vec![Frame {
                s: &self.axiom,
                pos: 0,
                depth: order,
            }],
            turtle: Turtle {
                pos: [0.0, 0.0],
                heading: 0.0,
                degrees: 0.0,
                step: 1.0,
                color: DEFAULT_COLOR,
                reversed: self.system.swap_signs,
            },
            saved: Vec::new(),
            drawn: 0,
            counts,
            error: None,
        })
    }

    /// Bounds of the drawn segments and their number (one full walk).
    pub fn extent(&self, order: u32) -> Result<(Bounds, u64), ExploreError> {
        let mut segs = self.segments(order)?;
        let mut b = Bounds::EMPTY;
        for s in segs.by_ref() {
            b.add(s.a);
            b.add(s.b);
        }
        if let Some(e) = segs.error() {
            return Err(e.clone());
        }
        Ok((b, segs.drawn()))
    }
}

impl Compiled {
    /// Draw the system at `order` into a width×height image on `background`, framed to fit
    /// with a small margin, each segment in its turtle colour ([`raster::palette_color`]).
    pub fn render(
        &self,
        order: u32,
        width: u32,
        height: u32,
        background: [u8; 3],
    ) -> Result<image::RgbImage, ExploreError> {
        raster::check_size(width, height)?;
        let (b, _) = self.extent(order)?;
        let margin = 2.0 + 0.03 * width.min(height) as f64;
        let f = raster::Framing::fit(b, width, height, margin);
        let mut c = raster::Canvas::new(width, height, background)?;
        let mut segs = self.segments(order)?;
        for s in segs.by_ref() {
            c.line(
                f.pixel_from_world(s.a),
                f.pixel_from_world(s.b),
                raster::palette_color(s.color),
            );
        }
        if let Some(e) = segs.error() {
            return Err(e.clone());
        }
        Ok(c.image)
    }
}

/// One drawn segment with its colour index.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub a: P2,
    pub b: P2,
    pub color: i64,
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Turtle {
    pos: P2,
    /// Heading in units of δ (for `F`, `G`).
    heading: f64,
    /// Heading in degrees (for `D`, `M`).
    degrees: f64,
    step: f64,
    color: i64,
    reversed: bool,
}

#[derive(Clone, Debug)]
struct Frame<'a> {
    s: &'a Str,
    pos: usize,
    depth: u32,
}

/// The depth-first walk of a derivation: yields the segments the turtle draws. The memory is
/// one frame per order plus the saved turtles of open `[`.
#[derive(Clone, Debug)]
pub struct Segments<'a> {
    sys: &'a Compiled,
    frames: Vec<Frame<'a>>,
    turtle: Turtle,
    saved: Vec<Turtle>,
    drawn: u64,
    counts: Counts,
    error: Option<ExploreError>,
}

impl Segments<'_> {
    /// Segments drawn so far.
    pub fn drawn(&self) -> u64 {
        self.drawn
    }

    /// The predicted size of the whole walk.
    pub fn counts(&self) -> &Counts {
        &self.counts
    }

    /// Why the walk stopped early (too deeply nested `[`), if it did.
    pub fn error(&self) -> Option<&ExploreError> {
        self.error.as_ref()
    }

    #[inline]
    fn direction(&self) -> P2 {
        let t = &self.turtle;
        match &self.sys.table {
            Some(tab) if t.heading.fract() == 0.0 => {
                let n = tab.len() as i64;
                tab[(t.heading as i64).rem_euclid(n) as usize]
            }
            _ => {
                let a = self.sys.system.start_heading.to_radians() + t.heading * self.sys.delta;
                let (s, c) = a.sin_cos();
                [c, s]
            }
        }
    }

    #[inline]
    fn degree_direction(&self) -> P2 {
        let a = (self.sys.system.start_heading + self.turtle.degrees).to_radians();
        let (s, c) = a.sin_cos();
        [c, s]
    }

    fn forward(&mut self, dir: P2, draw: bool) -> Option<Segment> {
        let t = &mut self.turtle;
        let a = t.pos;
        t.pos = [a[0] + dir[0] * t.step, a[1] + dir[1] * t.step];
        if draw {
            self.drawn += 1;
            Some(Segment {
                a,
                b: t.pos,
                color: t.color,
            })
        } else {
            None
        }
    }

    fn turn(&mut self, units: f64) {
        let sign = if self.turtle.reversed { -1.0 } else { 1.0 };
        let h = self.turtle.heading + sign * units;
        // Keep whole-δ headings small and exact.
        self.turtle.heading = match &self.sys.table {
            Some(t) if h.fract() == 0.0 => h.rem_euclid(t.len() as f64),
            _ => h,
        };
    }
}

impl Iterator for Segments<'_> {
    type Item = Segment;

    fn next(&mut self) -> Option<Segment> {
        loop {
            let frame = self.frames.last_mut()?;
            let Some(tok) = frame.s.tokens.get(frame.pos) else {
                self.frames.pop();
                continue;
            };
            frame.pos += 1;
            let depth = frame.depth;
            if depth > 0 && tok.rule != NO_RULE {
                self.frames.push(Frame {
                    s: &self.sys.rules[tok.rule as usize],
                    pos: 0,
                    depth: depth - 1,
                });
                continue;
            }
            match tok.cmd {
                Cmd::Draw => {
                    let d = self.direction();
                    return self.forward(d, true);
                }
                Cmd::Move => {
                    let d = self.direction();
                    self.forward(d, false);
                }
                Cmd::DrawDeg => {
                    let d = self.degree_direction();
                    return self.forward(d, true);
                }
                Cmd::MoveDeg => {
                    let d = self.degree_direction();
                    self.forward(d, false);
                }
                Cmd::Turn(u) => self.turn(u),
                Cmd::Reverse => {
                    // A half turn is the same either way round.
                    let h = self.sys.half_turn;
                    let r = self.turtle.reversed;
                    self.turtle.reversed = false;
                    self.turn(h);
                    self.turtle.reversed = r;
                }
                Cmd::DegTurn(v) => {
                    let sign = if self.turtle.reversed { -1.0 } else { 1.0 };
                    self.turtle.degrees = (self.turtle.degrees + sign * v).rem_euclid(360.0);
                }
                Cmd::SetColor(c) => self.turtle.color = c,
                Cmd::AddColor(c) => self.turtle.color = self.turtle.color.saturating_add(c),
                Cmd::Swap => self.turtle.reversed = !self.turtle.reversed,
                Cmd::Scale(f) => self.turtle.step *= f,
                Cmd::Push => {
                    if self.saved.len() >= MAX_STACK {
                        self.error = Some(ExploreError::TooLarge {
                            what: format!("'{}': nesting of '['", self.sys.system.name),
                            count: self.saved.len() as f64 + 1.0,
                            limit: MAX_STACK as f64,
                            hint: "; lower the order".into(),
                        });
                        self.frames.clear();
                        return None;
                    }
                    self.saved.push(self.turtle);
                    if self.sys.system.bracket_turn {
                        self.turn(1.0);
                    }
                }
                Cmd::Pop => {
                    // A `]` without its `[` is ignored.
                    if let Some(t) = self.saved.pop() {
                        self.turtle = t;
                    }
                }
                Cmd::Nop => {}
            }
        }
    }
}

/// A ready-made system with the order it is shown at and a note on its source.
#[derive(Clone, Debug, PartialEq)]
pub struct Preset {
    pub system: LSystem,
    pub order: u32,
    pub note: &'static str,
}

/// The systems of the teaching sources.
pub mod presets {
    use super::*;

    fn sys(name: &str, axiom: &str, rules: &[(char, &str)], angle: Angle) -> LSystem {
        LSystem::new(name, axiom, rules, angle)
    }

    pub fn koch_curve() -> Preset {
        Preset {
            system: sys("Koch curve", "F", &[('F', "F+F--F+F")], Angle::Divisions(6)),
            order: 4,
            note: "4ⁿ segments of length 3⁻ⁿ; D = log 4/log 3 = 1.26186",
        }
    }

    pub fn koch_kovacs() -> Preset {
        let mut s = sys(
            "Koch (Kovács)",
            "S",
            &[('S', "S+S-S-S+S")],
            Angle::Degrees(90.0),
        );
        s.draw_symbols = "S".into();
        Preset {
            system: s,
            order: 3,
            note: "With 90° turns this is the quadratic Koch curve, D = log 5/log 3 = 1.46497 \
                   (the article quotes 1.261, the value of the 60° Koch curve).",
        }
    }

    pub fn plant_kovacs() -> Preset {
        let mut s = sys(
            "Fractal plant (Kovács)",
            "S",
            &[('S', "F-[[S]+S]+F[+FS]-S"), ('F', "FF")],
            Angle::Degrees(25.0),
        );
        s.swap_signs = true;
        s.start_heading = 90.0;
        Preset {
            system: s,
            order: 5,
            note: "Lindenmayer's fractal plant (the article calls it the Barnsley fern, which is \
                   an IFS). Its − turns left, so + and − are swapped here; S draws nothing.",
        }
    }

    pub fn graftal() -> Preset {
        let mut s = sys(
            "Graftal (Kovács)",
            "0",
            &[('0', "1[0]1[0]0"), ('1', "11")],
            Angle::Degrees(45.0),
        );
        s.draw_symbols = "01".into();
        s.bracket_turn = true;
        s.start_heading = 90.0;
        Preset {
            system: s,
            order: 5,
            note: "0 and 1 draw a step; [ saves the turtle and turns by δ, so every branch turns \
                   the same way. The article gives neither axiom nor angle (0 and 45° assumed).",
        }
    }

    pub fn fibonacci() -> Preset {
        Preset {
            system: sys(
                "Fibonacci",
                "b",
                &[('a', "ab"), ('b', "a")],
                Angle::Degrees(90.0),
            ),
            order: 7,
            note: "Draws nothing: the lengths of the strings b, a, ab, aba, abaab, … are the \
                   Fibonacci numbers.",
        }
    }

    pub fn koch_snowflake() -> Preset {
        Preset {
            system: sys(
                "Koch snowflake",
                "F++F++F",
                &[('F', "F-F++F-F")],
                Angle::Degrees(60.0),
            ),
            order: 3,
            note: "3·4ⁿ segments; the area tends to 8/5 of the triangle's",
        }
    }

    pub fn quadratic_koch_island() -> Preset {
        Preset {
            system: sys(
                "Quadratic Koch island",
                "F-F-F-F",
                &[('F', "F+F-F-FF+F+F-F")],
                Angle::Degrees(90.0),
            ),
            order: 2,
            note: "4·8ⁿ segments; the step shrinks 4× per level, D = 1.5",
        }
    }

    pub fn square_inner_tree() -> Preset {
        Preset {
            system: sys(
                "Square inner tree",
                "F+F+F+F",
                &[('F', "FF+F++F+F")],
                Angle::Degrees(90.0),
            ),
            order: 3,
            note: "",
        }
    }

    fn plant(name: &str, rule: &str, deg: f64, order: u32, note: &'static str) -> Preset {
        let mut s = sys(name, "F", &[('F', rule)], Angle::Degrees(deg));
        s.start_heading = 90.0;
        Preset {
            system: s,
            order,
            note,
        }
    }

    pub fn plant_a() -> Preset {
        plant(
            "Plant (a)",
            "F[+F]F[-F]F",
            30.0,
            5,
            "5ⁿ segments; the slides' introductory plant. The book uses 25.7°.",
        )
    }

    pub fn plant_b() -> Preset {
        plant("Plant (b)", "F[+F]F[-F][F]", 20.0, 5, "")
    }

    pub fn plant_c() -> Preset {
        plant(
            "Plant (c)",
            "FF-[-F+F+F]+[+F-F-F]",
            20.5,
            4,
            "The book uses 22.5°.",
        )
    }

    pub fn arborvitae() -> Preset {
        plant(
            "Arborvitae",
            "F[+F]F[-F][F]",
            90.0,
            4,
            "90° as the slides print it — probably a misprint for a small angle.",
        )
    }

    pub fn dragon() -> Preset {
        Preset {
            system: sys(
                "Dragon",
                "FX",
                &[('F', ""), ('y', "+FX--FY+"), ('x', "-FX++FY-")],
                Angle::Divisions(8),
            ),
            order: 10,
            note: "Fractint's example; F= deletes F, so only the last generation's F draw.",
        }
    }

    pub fn all() -> Vec<Preset> {
        vec![
            koch_curve(),
            koch_kovacs(),
            koch_snowflake(),
            quadratic_koch_island(),
            square_inner_tree(),
            plant_kovacs(),
            graftal(),
            fibonacci(),
            plant_a(),
            plant_b(),
            plant_c(),
            arborvitae(),
            dragon(),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::presets::*;
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
    fn every_preset_compiles_and_draws() {
        for p in presets::all() {
            let c = p.system.compile().unwrap();
            let n = c.segments(p.order).unwrap().count() as f64;
            assert_eq!(n, c.counts(p.order).segments, "{}", p.system.name);
        }
    }

    fn polygon_area(segs: &[Segment]) -> f64 {
        segs.iter()
            .map(|s| s.a[0] * s.b[1] - s.b[0] * s.a[1])
            .sum::<f64>()
            / 2.0
    }

    #[test]
    fn turtle_geometry() {
        // The snowflake is a closed curve whose area is 8/5·(1 − …) of the triangle: with
        // + = left, F++F++F runs counter-clockwise and the bumps point outwards.
        let c = koch_snowflake().system.compile().unwrap();
        for n in 0..4 {
            let segs: Vec<Segment> = c.segments(n).unwrap().collect();
            let last = segs.last().unwrap().b;
            assert!(last[0].abs() < 1e-9 && last[1].abs() < 1e-9);
            let side = 3f64.powi(n as i32);
            let want = crate::explore::classic::Construction::KochSnowflake
                .stats(n)
                .unwrap()
                .area
                .unwrap()
                * side
                * side;
            assert!((polygon_area(&segs) - want).abs() < 1e-9 * want, "n={n}");
        }
        // The Koch curve of order 10: 4¹⁰ segments, from (0, 0) to (3¹⁰, 0).
        let c = koch_curve().system.compile().unwrap();
        let mut segs = c.segments(10).unwrap();
        let mut last = [0.0, 0.0];
        let mut n = 0u64;
        for s in segs.by_ref() {
            assert_eq!(s.a, last);
            last = s.b;
            n += 1;
        }
        assert_eq!(n, 1_048_576);
        assert_eq!(segs.drawn(), 1_048_576);
        assert!((last[0] - 59049.0).abs() < 1e-6 && last[1].abs() < 1e-6);
        // + turns left (counter-clockwise), − right; ! swaps them; | turns around.
        let one = |axiom: &str, n: u32| {
            let s = LSystem::new("t", axiom, &[], Angle::Divisions(n));
            let c = s.compile().unwrap();
            c.segments(0).unwrap().last().unwrap()
        };
        let s = one("+F", 4);
        assert!((s.b[1] - 1.0).abs() < 1e-15 && s.b[0].abs() < 1e-15);
        let s = one("-F", 4);
        assert!((s.b[1] + 1.0).abs() < 1e-15);
        let s = one("!+F", 4);
        assert!((s.b[1] + 1.0).abs() < 1e-15);
        let s = one("|F", 4);
        assert!((s.b[0] + 1.0).abs() < 1e-15);
        // Odd n: | turns by the largest multiple of δ below 180° (2·72° = 144°).
        let s = one("|F", 5);
        let a = 144f64.to_radians();
        assert!((s.b[0] - a.cos()).abs() < 1e-15 && (s.b[1] - a.sin()).abs() < 1e-15);
        // @ scales the step; @IQ2 divides it by √2; [ ] restore the turtle.
        let s = one("@3F", 4);
        assert!((s.b[0] - 3.0).abs() < 1e-15);
        let s = one("@IQ2F", 4);
        assert!((s.b[0] - 0.5f64.sqrt()).abs() < 1e-15);
        let s = one("F[+F@2F]F", 4);
        assert_eq!((s.a, s.b), ([1.0, 0.0], [2.0, 0.0]));
        // D and M follow the degree heading turned by \ and /.
        let s = one("\\30D", 4);
        let a = 30f64.to_radians();
        assert!((s.b[0] - a.cos()).abs() < 1e-15 && (s.b[1] - a.sin()).abs() < 1e-15);
        let s = one("/45.5M\\45.5D+D", 4);
        let a = (-45.5f64).to_radians();
        assert!((s.b[0] - a.cos() - 2.0).abs() < 1e-12 && (s.b[1] - a.sin()).abs() < 1e-12);
        assert!((s.b[0] - s.a[0] - 1.0).abs() < 1e-12);
        // Colours: C sets, < adds, > subtracts.
        let s = one("C10F<3F", 4);
        assert_eq!(s.color, 13);
        let s = one("C10>4F", 4);
        assert_eq!(s.color, 6);
        assert_eq!(one("F", 4).color, DEFAULT_COLOR);
    }

    #[test]
    fn plants_grow_upwards_with_swap() {
        // The Kovács plant with − = left leans like the book's figure; with the swap flag
        // cleared it is the mirror image.
        let p = plant_kovacs();
        let c = p.system.compile().unwrap();
        let b = c.extent(4).unwrap().0;
        let mut m = p.system.clone();
        m.swap_signs = false;
        let bm = m.compile().unwrap().extent(4).unwrap().0;
        assert!(b.max[1] > 10.0 && b.min[1] >= -1e-9);
        assert!((b.min[0] + bm.max[0]).abs() < 1e-9 && (b.max[0] + bm.min[0]).abs() < 1e-9);
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
