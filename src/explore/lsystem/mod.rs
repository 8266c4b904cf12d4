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

mod compile;
mod lex;
pub mod presets;
mod system;
mod turtle;

pub use compile::{Compiled, Counts};
pub use lex::{LexError, Lexeme, RESERVED, lex};
pub use presets::Preset;
pub use system::{
    ANGLE_DIVISIONS, Angle, DEFAULT_COLOR, LSystem, MAX_DRAW_SYMBOLS, MAX_ORDER, MAX_RULE_LEN,
    MAX_STACK, MAX_STRING,
};
pub use turtle::{Segment, Segments};
