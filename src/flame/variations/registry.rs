//! The registry: every variation ugnis knows, by id, and the lookup tables built from it.
//!
//! The ids follow one order: flam3's list in flam3's order (ids 0–98, which flam3's numeric
//! `var` lists name), then Fractorium's catalogue alphabetically (ignoring case), then the
//! JWildfire variations in the order ugnis took them in ([`JWILDFIRE_ORDER`]). `ugnis info
//! --variations` and the editor's variation menu list them in this order.

use std::collections::HashMap;
use std::sync::LazyLock;

use super::VarId;
use super::def::{VarDef, flag};
use super::{
    flam3, fr_3d, fr_bipolar_elliptic, fr_blurs, fr_complex, fr_crops, fr_curves, fr_direct_colour,
    fr_distance_blurs, fr_grids, fr_hexagons, fr_hyperbolic, fr_inversions, fr_julias, fr_moves,
    fr_polynomial_maps, fr_quaternions, fr_radial, fr_synth, fr_trig, fr_truchet, fr_waves, jwf_3d,
    jwf_direct_colour, jwf_drawings, jwf_knots, jwf_maps, jwf_symmetry, jwf_text,
};
// JWildfire variations, second part.
use super::{jwf_b_3d, jwf_b_complex, jwf_b_crops, jwf_b_cuts, jwf_b_dc, jwf_b_ifs, jwf_b_shapes};

/// Every variation, by id.
pub fn all() -> &'static [&'static VarDef] {
    &REGISTRY.defs
}

/// Number of variations in the registry.
pub fn count() -> usize {
    REGISTRY.defs.len()
}

/// The registry entry of variation `id` (panics for an id not below [`count`]).
pub fn info(id: VarId) -> &'static VarDef {
    REGISTRY.defs[id as usize]
}

/// The formulas' files, each with its table of variations.
const FILES: [&[VarDef]; 35] = [
    fr_3d::DEFS,
    fr_bipolar_elliptic::DEFS,
    fr_blurs::DEFS,
    fr_complex::DEFS,
    fr_crops::DEFS,
    fr_curves::DEFS,
    fr_direct_colour::DEFS,
    fr_distance_blurs::DEFS,
    fr_grids::DEFS,
    fr_hexagons::DEFS,
    fr_hyperbolic::DEFS,
    fr_inversions::DEFS,
    fr_julias::DEFS,
    fr_moves::DEFS,
    fr_polynomial_maps::DEFS,
    fr_quaternions::DEFS,
    fr_radial::DEFS,
    fr_synth::DEFS,
    fr_trig::DEFS,
    fr_truchet::DEFS,
    fr_waves::DEFS,
    jwf_3d::DEFS,
    jwf_direct_colour::DEFS,
    jwf_drawings::DEFS,
    jwf_knots::DEFS,
    jwf_maps::DEFS,
    jwf_symmetry::DEFS,
    jwf_text::DEFS,
    // JWildfire variations, second part.
    jwf_b_3d::DEFS,
    jwf_b_complex::DEFS,
    jwf_b_crops::DEFS,
    jwf_b_cuts::DEFS,
    jwf_b_dc::DEFS,
    jwf_b_ifs::DEFS,
    jwf_b_shapes::DEFS,
];

/// The JWildfire variations, in the order ugnis took them in (which gives them their ids). A
/// variation missing here comes after these, in the order of [`FILES`].
const JWILDFIRE_ORDER: [&str; 131] = [
    "rose_wf",
    "chrysanthemum",
    "complex",
    "exblur",
    "glitchy1",
    "pyramid",
    "rosoni",
    "xheart_blur_wf",
    "epispiral_wf",
    "post_mirror_wf",
    "crop_stars",
    "plane_wf",
    "julian2dc",
    "szubieta",
    "nsudoku",
    "snowflake_wf",
    "polarplot3d_wf",
    "knots3D",
    "text_wf",
    "sym_ng1",
    "sym_ng2",
    "sym_ng3",
    "sym_ng4",
    "sym_ng5",
    "sym_ng6",
    "sym_ng7",
    "sym_ng8",
    "sym_ng9",
    "sym_ng10",
    "sym_ng11",
    "sym_ng12",
    "sym_ng13",
    "sym_ng14",
    "sym_ng15",
    "sym_ng16",
    "sym_ng17",
    "sym_bg1",
    "sym_bg2",
    "sym_bg3",
    "sym_bg4",
    "sym_bg5",
    "sym_bg6",
    "sym_bg7",
    "hilbert_js",
    "rsquares_js",
    "tree_js",
    "svensson_js",
    "dla3d_wf",
    "dc_mandala",
    "dc_inversion",
    "dc_poincaredisc",
    "dc_circuits",
    "dc_turbulence",
    "dc_gabornoise",
    // JWildfire variations, second part.
    "affine3D",
    "tangent3D",
    "inflateZ_1",
    "inflateZ_3",
    "inflateZ_5",
    "cylinder_apo",
    "onion",
    "sphere_nja",
    "ztwister",
    "post_zscale_wf",
    "swirl3D_wf",
    "pdj3D",
    "log_tile2",
    "dinis_surface_wf",
    "lorenz_js",
    "gingerbread_man",
    "spherecrop",
    "seashell3D",
    "cos2_bs",
    "csc2_bs",
    "csch2_bs",
    "sech2_bs",
    "sinh2_bs",
    "exp2_bs",
    "atan",
    "acoth",
    "sqrt_acoth",
    "sqrt_asech",
    "sqrt_asinh",
    "exp_multi",
    "csin",
    "plusrecip",
    "inverted_julia",
    "julia_outside",
    "cpow3_wf",
    "csc_squared",
    "bipolar2",
    "bulge",
    "crop_box",
    "crop_x",
    "crop_trapezoid",
    "crop_polygon",
    "cut_tileillusion",
    "cut_sqcir",
    "cut_rgrid",
    "cut_zigzag",
    "dc_acrilic",
    "dc_vortex",
    "dc_portal",
    "glsl_hoshi",
    "invtree_js",
    "wallpaper_js",
    "woggle_js",
    "crown_js",
    "triangle",
    "cell2",
    "waves2_wf",
    "waves4_wf",
    "cloverleaf_wf",
    "yin_yang",
    "heart_wf",
    "layered_spiral",
    "holesq",
    "stripfit",
    "squircular",
    "hole2",
    "devil_warp",
    "bsplit",
    "minkowskope",
    "circular2",
    "vogel",
    "fresnel",
    "hyperbolicellipse",
    "whirligig",
    "glynnia3",
    "vortex",
    "oak_leaf",
];

/// Every variation in registry order (see the module documentation).
fn ordered() -> Vec<&'static VarDef> {
    let others = || FILES.iter().flat_map(|f| f.iter());
    let mut fractorium: Vec<&'static VarDef> =
        others().filter(|d| !d.has(flag::JWILDFIRE)).collect();
    fractorium.sort_by_key(|d| d.name.to_ascii_lowercase());
    let mut jwildfire: Vec<&'static VarDef> = others().filter(|d| d.has(flag::JWILDFIRE)).collect();
    jwildfire.sort_by_key(|d| {
        JWILDFIRE_ORDER
            .iter()
            .position(|n| *n == d.name)
            .unwrap_or(JWILDFIRE_ORDER.len())
    });
    flam3::DEFS
        .iter()
        .chain(fractorium)
        .chain(jwildfire)
        .collect()
}

pub(super) struct Registry {
    pub(super) defs: Vec<&'static VarDef>,
    /// Lower-case name → id (hidden entries excluded).
    pub(super) names: HashMap<String, VarId>,
    /// Lower-case full parameter name → (id, parameter index).
    pub(super) params: HashMap<String, (VarId, usize)>,
    /// Lower-case full text parameter name → (id, text index).
    pub(super) texts: HashMap<String, (VarId, usize)>,
}

pub(super) static REGISTRY: LazyLock<Registry> = LazyLock::new(|| {
    let defs = ordered();
    let mut names = HashMap::new();
    let mut params = HashMap::new();
    let mut texts = HashMap::new();
    for (i, d) in defs.iter().enumerate() {
        if d.has(flag::HIDDEN) {
            continue;
        }
        let prev = names.insert(d.name.to_ascii_lowercase(), i as VarId);
        debug_assert!(prev.is_none(), "variation {} registered twice", d.name);
        for (k, pa) in d.params.iter().enumerate() {
            params.insert(pa.name.to_ascii_lowercase(), (i as VarId, k));
        }
        for (k, t) in d.texts.iter().enumerate() {
            texts.insert(t.name.to_ascii_lowercase(), (i as VarId, k));
        }
    }
    Registry {
        defs,
        names,
        params,
        texts,
    }
});

#[cfg(test)]
mod tests {
    use super::*;

    /// Every JWildfire variation has its place in [`JWILDFIRE_ORDER`] (a new one is appended
    /// there, so that the ids of the others stay), and the list names each once.
    #[test]
    fn every_jwildfire_variation_has_its_place() {
        let jwildfire: Vec<&str> = all()
            .iter()
            .filter(|d| d.has(flag::JWILDFIRE))
            .map(|d| d.name)
            .collect();
        assert_eq!(jwildfire, JWILDFIRE_ORDER);
    }

    /// flam3's list keeps its ids and Fractorium's catalogue follows in alphabetical order.
    #[test]
    fn flam3_then_fractorium_alphabetically() {
        assert_eq!(all()[0].name, "linear");
        assert_eq!(all()[98].name, "mobius");
        let fractorium: Vec<String> = all()[99..]
            .iter()
            .take_while(|d| !d.has(flag::JWILDFIRE))
            .map(|d| d.name.to_ascii_lowercase())
            .collect();
        assert!(
            fractorium.is_sorted(),
            "Fractorium's catalogue out of order"
        );
        assert_eq!(99 + fractorium.len() + JWILDFIRE_ORDER.len(), count());
    }
}
