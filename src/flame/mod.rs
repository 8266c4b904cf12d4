//! Fractal flames and IFS: model, variations, chaos game, histogram, density estimation,
//! tone mapping, automatic framing and the progressive renderer.

pub(crate) mod affine;
pub mod animate;
pub mod animated;
mod budget;
pub(crate) mod chaos;
pub(crate) mod curves;
pub(crate) mod density;
mod develop;
pub(crate) mod fastmath;
pub(crate) mod filter;
pub(crate) mod framing;
pub(crate) mod geometry;
pub(crate) mod histogram;
pub(crate) mod ifs3d;
pub mod interpolate;
pub mod jwf_curve;
pub mod jwf_render;
pub(crate) mod keyframe_target;
pub mod keyframes;
pub mod layers;
pub mod loops;
pub mod model;
pub mod motion_blur;
pub mod mutate;
pub(crate) mod palette_rule;
mod plot;
pub mod random;
pub mod render;
pub mod sequence;
pub mod shown_maps;
/// The seeded generator lives at the crate root (gradients, noise and scenes use it too).
pub use crate::rng;
mod settings;
mod sources;
pub(crate) mod state;
pub mod strips;
pub(crate) mod symmetry;
pub(crate) mod tonemap;
pub mod variations;

pub use chaos::Chaos;
pub use framing::apply_auto_frame;
pub use histogram::Histogram;
pub use model::{
    Affine, Camera3d, FilterShape, Flame, FlameKind, Ifs3d, NewFlame, PaletteIndex, PaletteMode,
    Var, Xform,
};
pub use render::{RenderError, RenderOptions, Renderer, render};
pub use state::{Part, RenderState};
pub use tonemap::OutputFormat;
