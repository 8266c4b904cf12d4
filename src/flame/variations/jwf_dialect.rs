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

/// The twins: each named as the attribute JWildfire writes (`NAME`, `pre_NAME`, `post_NAME`),
/// with the parameters of the registry's variation of that name.
pub(super) const DEFS: &[VarDef] = &[];

/// Variations whose JWildfire twin only drops the z they carry along.
pub(super) const FLAT: &[&str] = &[
    "auger",
    "barycentroid",
    "bipolar",
    "blur",
    "blur_circle",
    "blur_pixelize",
    "blur_zoom",
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
    "post_flatten",
    "post_spherical",
    "pre_blur",
    "pre_disc",
    "pre_flatten",
    "pre_spherical",
    "radial_blur",
    "rectangles",
    "separation",
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
