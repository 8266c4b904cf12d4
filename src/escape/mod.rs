//! Escape-time fractals: Mandelbrot, Julia, z^m + c, Newton, logistic, the cubic
//! z³ + z + p, and the Borowicz warped-Julia textures; colouring; progressive parallel
//! rendering with a vectorised lane engine; perturbation deep zoom for z² + c and z³ + c
//! (arbitrary-precision reference, extended exponents, bilinear approximation).

// Escape tests are written `!(r2 <= bailout²)` on purpose: a NaN (an overflowed orbit) must
// count as escaped, which `r2 > bailout²` would not do.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub(crate) mod bla;
mod bla_quad;
mod bla_ship;
pub mod centre;
mod color;
mod complex;
pub(crate) mod dd;
mod deep;
mod deep_plain;
mod deep_ship;
mod doc;
pub(crate) mod family;
pub mod fx;
mod guess;
mod job;
mod lanes;
mod newton;
mod params;
pub(crate) mod render;
mod view;
mod warp;

/// The bilinear tolerances a deep zoom accepts (relative size of the terms a step may drop).
pub use bla::EPSILON_RANGE as BLA_TOLERANCE_RANGE;
pub use color::{Coloring, Palette};
pub use complex::C;
pub use doc::EscapeDoc;
pub use family::{Family, Sample};
pub use params::supports_deep_zoom;
pub use render::{
    EscapeError, EscapeParams, EscapeRenderer, Fill, OrbitProgress, View, auto_max_iter,
    check_memory, check_view_for, estimate_memory, is_deep, render,
};
pub use warp::{Preset, Sampling, Warp};
