//! Helpers shared by the variation formulas.
//!
//! Most variations come from programs written in C++ (Fractorium, Apophysis plugins) or Java
//! (JWildfire), and a few of their numbers depend on what those languages do at the edges: how
//! a double becomes an integer on x86-64, how a bounded random draw treats a count of 0, which
//! argument `std::max` keeps when one is NaN. The helpers here reproduce those behaviours once,
//! each documented with the semantics it mimics, so that every formula that needs one uses the
//! same code.
//!
//! By file: `arith` (small arithmetic, Java and GLSL idioms), `c_ints` (C conversions as x86-64
//! performs them), `random` (random draws and hashes), `coords` (coordinate systems),
//! `complex` (complex numbers with C99 semantics), `special` (special functions), `formula`
//! (JWildfire's formula texts) and `jwf_math` (JWildfire's table-based sin, cos, atan2, √, …,
//! used as `jwf_math::sin` by the JWildfire variations that need its exact numbers).

mod arith;
mod c_ints;
mod complex;
mod coords;
pub mod formula;
pub mod jwf_math;
mod jwf_math_tables;
mod random;
mod special;

pub use arith::*;
pub use c_ints::*;
pub use complex::*;
pub use coords::*;
pub(in crate::flame::variations) use random::Draw;
pub use random::*;
pub use special::*;
