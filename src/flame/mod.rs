//! Fractal flames and IFS: model, variations, chaos game, histogram, density estimation,
//! tone mapping, automatic framing and the progressive renderer.

pub mod affine;
pub mod animate;
pub mod animated;
mod budget;
pub mod chaos;
pub mod curves;
pub mod density;
mod develop;
pub mod fastmath;
pub mod filter;
pub mod framing;
pub mod geometry;
pub mod histogram;
pub mod ifs3d;
pub mod interpolate;
pub mod jwf_curve;
pub mod keyframes;
pub mod loops;
pub mod model;
pub mod motion_blur;
pub mod mutate;
mod plot;
pub mod random;
pub mod render;
pub mod sequence;
/// The seeded generator lives at the crate root (gradients, noise and scenes use it too).
pub use crate::rng;
mod settings;
pub mod state;
pub mod strips;
pub mod symmetry;
pub mod tonemap;
pub mod variations;

pub use model::{
    Affine, Camera3d, FilterShape, Flame, FlameKind, Ifs3d, NewFlame, PaletteIndex, PaletteMode,
    Var, Xform,
};
pub use render::{RenderError, RenderOptions, Renderer, render};
pub use tonemap::OutputFormat;
