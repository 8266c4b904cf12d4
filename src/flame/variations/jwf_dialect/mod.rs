//! JWildfire's own formulas for names flam3 or Fractorium also use, where JWildfire computes
//! them differently (its constants, its special cases, its phase): a flame JWildfire wrote
//! gets these ([`Prepared::for_flame`] picks them once, when the flame is compiled), every
//! other flame the registry's. Each twin keeps its variation's name and parameters, so a
//! JWildfire flame written back keeps its names.
//!
//! [`FLAT`] lists the variations that JWildfire computes as 2-D ones where flam3's (as
//! Fractorium extends them) or Fractorium's carry the weighted z along: their JWildfire twin
//! is their own formula with the framework's z (0, or the weighted input z when the flame's
//! "preserve Z" is on).

use super::*;

mod classic;
mod fractorium;

/// JWildfire's `SMALL_EPSILON`, which it adds to radii and denominators.
const SMALL_EPSILON: f64 = 1e-300;

/// JWildfire's `getPrecalcSqrt`: the radius plus 1e-300 (never 0).
#[inline(always)]
fn jwf_sqrt(t: &VarIn) -> f64 {
    (t.x * t.x + t.y * t.y).sqrt() + SMALL_EPSILON
}

/// The twins, by file: each named as the attribute JWildfire writes (`NAME`, `pre_NAME`,
/// `post_NAME`), with the parameters of the registry's variation of that name in its order
/// (named as JWildfire names them), then those only JWildfire's formula has.
pub(super) const TABLES: &[&[VarDef]] = &[classic::DEFS];

/// Variations whose JWildfire twin is the registry's entry (parameters, derived values) with
/// JWildfire's formula: name, formula, flags it drops, flags it adds.
pub(super) const FORMULAS: &[(&str, EvalFn, u32, u32)] = &[
    ("arctanh", fractorium::arctanh, 0, 0),
    ("boarders", fractorium::boarders, 0, 0),
    (
        "crop",
        fractorium::crop,
        flag::WRITES_Z | flag::USES_Z,
        CROP,
    ),
    ("hole", fractorium::hole, 0, 0),
    ("kaleidoscope", fractorium::kaleidoscope, 0, 0),
    (
        "post_crop",
        fractorium::crop,
        flag::WRITES_Z | flag::USES_Z,
        CROP,
    ),
    (
        "pre_crop",
        fractorium::crop,
        flag::WRITES_Z | flag::USES_Z,
        CROP,
    ),
    (
        "tile_log",
        fractorium::tile_log,
        0,
        flag::USES_Z | flag::WRITES_Z,
    ),
];

/// JWildfire's crop replaces the sum so far and hides or shows the point.
const CROP: u32 = flag::WRITES_ACC | flag::HIDES;

/// Variations JWildfire runs after the others (on their sum), whatever their name says.
pub(super) const AFTER: &[&str] = &["flatten"];

/// Variations whose JWildfire twin only drops the z they carry along.
pub(super) const FLAT: &[&str] = &[
    "auger",
    "barycentroid",
    "bipolar",
    "blur",
    "blur_circle",
    "blur_pixelize",
    "blur_zoom",
    "cross",
    "cylinder",
    "dc_linear",
    "disc",
    "escher",
    "eyefish",
    "fan2",
    "flux",
    "foci",
    "gaussian_blur",
    "gdoffs",
    "horseshoe",
    "hyperbolic",
    "julian",
    "juliascope",
    "lazysusan",
    "linear",
    "log",
    "log_db",
    "loonie",
    "mobius",
    "ngon",
    "noise",
    "pdj",
    "phoenix_julia",
    "polar2",
    "post_spherical",
    "pre_blur",
    "pre_disc",
    "pre_flatten",
    "pre_spherical",
    "radial_blur",
    "rays1",
    "rays2",
    "rectangles",
    "separation",
    "shredlin",
    "shredrad",
    "sinusgrid",
    "sinusoidal",
    "spherical",
    "square",
    "swirl",
    "tile_log",
    "waves2",
    "wedge",
];
