//! An L-system as written (axiom, productions, angle, interpretation flags) and the limits of
//! what is derived and drawn from one.

/// Symbols a derived string may have
/// ([`Compiled::derive_string`](super::Compiled::derive_string)).
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
    /// δ in degrees.
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
    /// The system's name (the entry name in a `.l` file).
    pub name: String,
    /// The starting string.
    pub axiom: String,
    /// Productions in file order: symbol (as written) and replacement. Repeated symbols are
    /// concatenated when compiled; an empty replacement deletes the symbol.
    pub rules: Vec<(char, String)>,
    /// The turning angle δ.
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
}
