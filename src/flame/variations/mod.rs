//! Variations: the non-linear functions an xform applies after its affine map.
//!
//! One registry holds every variation ugnis knows: flam3's classic list (ids 0–98 in flam3's
//! order, so that flam3's numeric `var` lists keep working), Fractorium's catalogue and the
//! JWildfire variations that real files use. Each entry ([`VarDef`]) names the variation, its
//! parameters with defaults and ranges, which per-point quantities it reads, and its formula.
//!
//! A variation is used in one of three forms ([`Form`]), as Fractorium and JWildfire do:
//! - regular: the outputs of an xform's regular variations are summed;
//! - `pre_NAME`: applied to the affine-transformed point before the regular variations,
//!   replacing it (or adding to it, for the variations whose [`Assign`] is `Sum`);
//! - `post_NAME`: applied to the summed result, replacing (or adding to) it.
//!
//! A formula receives the point as a [`VarIn`] (with r², r, x/r, y/r and both angles computed
//! once for the xform, as flam3 and Fractorium precompute them), the xform's running output as
//! an [`Acc`] (a few variations read or rewrite what earlier variations summed, or set the
//! colour), and returns its own weighted output `[x, y, z]`.
//!
//! Conventions: angles follow flam3 — `atan_xy` = atan2(x, y), `atan_yx` = atan2(y, x) (the usual
//! polar angle); `ux` = x/r, `uy` = y/r, with r replaced by `f64::EPSILON` when it is 0.
//! Fractorium's affine letters A B C D E F are [`Affine`]'s a b e c d f
//! (x' = A·x + B·y + C, y' = D·x + E·y + F).
//!
//! Helpers the formulas share live in [`util`] (the C/x86 and Java behaviours the source
//! programs rely on, hashes, coordinate systems, complex numbers, special functions) and in
//! `noise` (simplex noise); data that takes long to build (grown aggregates, crystals, meshes,
//! recursive drawings) is built once per parameter values and shared through [`shared`].
//!
//! The framework, by file: `def` (a registry entry and a prepared variation), `params`
//! (parameter kinds and constructors), `point` (what a formula reads and writes), `prepare`
//! (preparing a variation, and evaluating one at one point), `batch` (batches of points),
//! `registry` (the table of every variation, by id) and `names` (attribute names and aliases).

pub use crate::flame::affine::Affine;

mod batch;
mod def;
mod names;
mod params;
mod point;
mod prepare;
mod registry;

mod flam3;
mod fr_a;
mod fr_b;
mod fr_c;
mod fr_d;
mod fr_e;
mod fr_f;
mod jwf;
mod jwf2;
mod noise;
pub mod shared;
mod text;
pub mod util;

pub(crate) use batch::inline_batch;
pub use batch::{batch_with, generic_batch};
pub use def::{Assign, BatchFn, EvalFn, Form, PrepareFn, Prepared, VarDef, VarState, flag};
pub use flam3::*;
pub use names::{
    attr_name, by_name, from_flam3_index, is_foreign_variation_name, param_attr_name, param_of,
    parse_name, text_attr_name, text_of,
};
pub use params::{
    Param, ParamKind, TextParam, p, p_cyclic, p_int, p_int_nonzero, p_nonzero, p_range, params_of,
};
pub use point::{Acc, SoaAcc, SoaIn, VarIn, need};
pub use prepare::{eval_point, eval_prepared};
pub use registry::{all, count, info};
pub use shared::{BuildFn, SharedDef};

use crate::flame::rng::FastRng;

/// flam3's `EPS`, the guard its formulas add to denominators.
pub const EPS: f64 = 1e-10;

/// Index of a variation in the registry ([`all`]). Ids 0–98 are flam3's list, in flam3's order.
pub type VarId = u16;

/// An output point `[x, y, z]`.
pub type V3 = [f64; 3];
