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

mod after;
mod blurs;
mod branches;
mod classic;
mod direct_colour;
mod fractorium;
mod h9c_glynn;
mod origin;
mod phases;
mod pv_guards;
mod quaternions;
mod renamed;
mod stats_crops;
mod stats_shapes;
mod surfaces;
mod tablemath;
mod wider;

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
pub(super) const TABLES: &[&[VarDef]] = &[
    blurs::DEFS,
    classic::DEFS,
    direct_colour::DEFS,
    renamed::DEFS,
    surfaces::DEFS,
    wider::DEFS,
    stats_shapes::DEFS,
    stats_crops::DEFS,
    super::fr_synth::JWF_DEFS,
    h9c_glynn::DEFS,
];

/// Variations whose JWildfire twin is the registry's entry (parameters, derived values) with
/// JWildfire's formula: name, formula, flags it drops, flags it adds.
pub(super) const FORMULAS: &[(&str, EvalFn, u32, u32)] = &[
    ("bSwirl", origin::bswirl, 0, 0),
    ("cardioid", origin::cardioid, 0, 0),
    ("coshq", quaternions::coshq, 0, 0),
    ("cosq", quaternions::cosq, 0, 0),
    ("cot", origin::cot, 0, 0),
    ("cothq", quaternions::tanhq, 0, 0),
    ("cotq", quaternions::cotq, 0, 0),
    ("cschq", quaternions::cschq, 0, 0),
    ("cscq", quaternions::cscq, 0, 0),
    ("estiq", quaternions::estiq, 0, 0),
    ("foci_3D", origin::foci_3d, 0, 0),
    ("glynnia", origin::glynnia, 0, 0),
    ("loonie_3D", origin::loonie_3d, 0, 0),
    ("post_curl", phases::post_curl, 0, 0),
    ("post_curl3D", phases::post_curl3d, 0, 0),
    ("post_flatten", phases::post_flatten, 0, 0),
    ("post_heat", phases::post_heat, 0, 0),
    ("pre_zscale", phases::pre_zscale, 0, 0),
    ("pre_sinusoidal3D", phases::pre_sinusoidal3d, 0, 0),
    ("loq", quaternions::loq, 0, 0),
    ("rays1", origin::rays1, 0, 0),
    ("rays2", origin::rays2, 0, 0),
    ("roundspher", origin::roundspher, 0, 0),
    ("scry_3D", origin::scry_3d, 0, 0),
    ("sechq", quaternions::sechq, 0, 0),
    ("secq", quaternions::secq, 0, 0),
    ("sinhq", quaternions::sinhq, 0, 0),
    ("sinq", quaternions::sinq, 0, 0),
    ("sphericalN", origin::spherical_n, 0, 0),
    ("spiralwing", origin::spiralwing, 0, 0),
    ("swirl3", origin::swirl3, 0, 0),
    ("tanhq", quaternions::tanhq, 0, 0),
    ("tanq", quaternions::tanq, 0, 0),
    ("wedge_sph", origin::wedge_sph, 0, 0),
    ("arctanh", tablemath::arctanh, 0, 0),
    ("boarders", fractorium::boarders, 0, 0),
    (
        "checks",
        fractorium::checks,
        flag::USES_Z | flag::WRITES_Z,
        0,
    ),
    ("cpow3", fractorium::cpow3, 0, 0),
    ("crob", fractorium::crob, 0, 0),
    ("funnel", fractorium::funnel, 0, 0),
    ("gamma", fractorium::gamma, 0, 0),
    ("hypertile3D", fractorium::hypertile3d, 0, 0),
    ("hypertile3D1", fractorium::hypertile3d1, 0, 0),
    ("hypertile3D2", fractorium::hypertile3d2, 0, 0),
    ("julian3Dx", fractorium::julian3dx, flag::USES_Z, 0),
    ("squirrel", fractorium::squirrel, 0, flag::WRITES_ACC),
    ("ho", fractorium::ho, 0, 0),
    (
        "crop",
        fractorium::crop,
        flag::WRITES_Z | flag::USES_Z,
        CROP,
    ),
    ("ennepers", fractorium::ennepers, 0, flag::WRITES_ACC),
    ("erf", fractorium::erf, 0, 0),
    ("xerf", fractorium::xerf, 0, flag::USES_Z | flag::WRITES_Z),
    ("waves2b", fractorium::waves2b, 0, 0),
    ("hole", fractorium::hole, 0, 0),
    ("kaleidoscope", fractorium::kaleidoscope, 0, 0),
    ("shredlin", fractorium::shredlin, 0, flag::WRITES_ACC),
    ("sintrange", fractorium::sintrange, 0, flag::WRITES_ACC),
    (
        "truchet_hex_fill",
        super::fr_truchet::truchet_hex_fill_jwildfire,
        0,
        0,
    ),
    ("sinusgrid", fractorium::sinusgrid, 0, flag::WRITES_Z),
    ("CircleRand", super::fr_grids::circle_rand_jwildfire, 0, 0),
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
    ("arcsech2", tablemath::arcsech2, 0, 0),
    ("d_spherical", tablemath::d_spherical, 0, 0),
    ("eCollide", tablemath::e_collide, 0, 0),
    ("eMod", tablemath::e_mod, 0, 0),
    ("eMotion", tablemath::e_motion, 0, 0),
    ("ePush", tablemath::e_push, 0, 0),
    ("eRotate", tablemath::e_rotate, 0, 0),
    ("eSwirl", tablemath::e_swirl, 0, 0),
    ("edisc", tablemath::edisc, 0, 0),
    ("hypershift2", tablemath::hypershift2, 0, 0),
    ("lazyjess", tablemath::lazyjess, 0, 0),
    ("npolar", tablemath::npolar, 0, 0),
    ("ortho", tablemath::ortho, 0, 0),
    ("rays3", tablemath::rays3, 0, 0),
    ("rays", tablemath::rays, 0, 0),
    ("blade3D", stats_shapes::blade3d, flag::USES_Z, 0),
    ("superShape3d", stats_shapes::super_shape3d, 0, 0),
    ("squish", stats_shapes::squish, 0, 0),
    ("splitbrdr", stats_shapes::split_brdr, 0, 0),
    ("hexnix3D", stats_shapes::hexnix3d, 0, 0),
    ("dc_carpet", stats_crops::dc_carpet, 0, 0),
    (
        "dc_triangle",
        stats_crops::dc_triangle,
        flag::USES_Z | flag::WRITES_Z,
        0,
    ),
    ("pixel_flow", stats_crops::pixel_flow, 0, 0),
    ("juliaq", branches::juliaq, 0, 0),
    ("post_juliaq", branches::juliaq, 0, 0),
    ("julia3Dq", branches::julia3dq, 0, 0),
    ("post_julia3Dq", branches::julia3dq, 0, 0),
    ("juliac", branches::juliac, 0, 0),
    ("phoenix_julia", branches::phoenix_julia, flag::WRITES_Z, 0),
    ("wedge_julia", branches::wedge_julia, 0, 0),
    ("hypertile1", branches::hypertile1, 0, 0),
    ("hypertile2", branches::hypertile2, 0, 0),
    ("farblur", after::farblur, 0, flag::POST_ONLY),
    (
        "post_depth",
        after::post_depth,
        0,
        flag::READS_AFFINE_POINT | flag::READS_ACC,
    ),
    ("csc", pv_guards::csc, flag::WRITES_Z, 0),
    ("csch", pv_guards::csch, flag::WRITES_Z, 0),
    ("sec", pv_guards::sec, flag::WRITES_Z, 0),
    ("sech", pv_guards::sech, flag::WRITES_Z, 0),
    ("tan", pv_guards::tan, flag::WRITES_Z, 0),
    ("tanh", pv_guards::tanh, flag::WRITES_Z, 0),
    ("coth", pv_guards::coth, flag::WRITES_Z, 0),
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
    "rays3",
    "rectangles",
    "separation",
    "shredlin",
    "shredrad",
    "sinusoidal",
    "spherical",
    "square",
    "swirl",
    "tile_log",
    "waves2",
    "wedge",
];
