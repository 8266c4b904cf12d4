//! The registry: every variation ugnis knows, by id, and the lookup tables built from it.
//!
//! The ids follow one order: flam3's list in flam3's order (ids 0–98, which flam3's numeric
//! `var` lists name), then Fractorium's catalogue alphabetically (ignoring case), then the
//! JWildfire variations in the order ugnis took them in ([`JWILDFIRE_ORDER`]). `ugnis info
//! --variations` and the editor's variation menu list them in this order.

use std::collections::HashMap;
use std::sync::LazyLock;

use super::VarId;
use super::def::{Dialect, Form, VarDef, flag};
use super::names::lookup_in;
use super::params::Param;
use super::{
    flam3, fr_3d, fr_bipolar_elliptic, fr_blurs, fr_complex, fr_crops, fr_curves, fr_direct_colour,
    fr_distance_blurs, fr_grids, fr_hexagons, fr_hyperbolic, fr_inversions, fr_julias, fr_moves,
    fr_polynomial_maps, fr_quaternions, fr_radial, fr_synth, fr_trig, fr_truchet, fr_waves, jwf_3d,
    jwf_dialect, jwf_direct_colour, jwf_drawings, jwf_knots, jwf_maps, jwf_post_symmetry,
    jwf_prepost, jwf_symmetry, jwf_text,
};
// JWildfire variations, first set of files.
use super::{
    jwf_a_complex, jwf_a_crops, jwf_a_cuts, jwf_a_dc, jwf_a_fractals, jwf_a_ifs, jwf_a_plane,
    jwf_a_sdf3d, jwf_a_shapes, jwf_a_surfaces, jwf_a_warps,
};
// JWildfire variations, second part.
use super::{jwf_b_3d, jwf_b_complex, jwf_b_crops, jwf_b_cuts, jwf_b_dc, jwf_b_ifs, jwf_b_shapes};
// JWildfire variations, third part.
use super::{jwf_c_escape, jwf_c_glsl, jwf_c_orbits};
// JWildfire variations, fourth part.
use super::{jwf_d_crops, jwf_d_cuts, jwf_d_cvar, jwf_d_plane, jwf_d_solids};
// JWildfire's direct-colour stamps.
use super::{
    jwf_dc_cells, jwf_dc_fields, jwf_dc_folds, jwf_dc_mandel, jwf_dc_maps, jwf_dc_patterns,
    jwf_dc_tiles, jwf_dc_twins,
};
// JWildfire variations, the cut and single-formula ones added last.
use super::{
    jwf_m_crops, jwf_m_curves, jwf_m_cuts, jwf_m_draw, jwf_m_foam, jwf_m_ifs3d, jwf_m_polylog,
    jwf_m_quaternion, jwf_m_stabilize, jwf_m_tilecuts, jwf_m_tiles, jwf_m_trig,
};
// JWildfire variations added by helper h5.
use super::{
    jwf_h5_crops, jwf_h5_draw, jwf_h5_glsl, jwf_h5_octree, jwf_h5_shapes, jwf_h5_sims,
    jwf_h5_triantess,
};
// JWildfire variations driven by formula text or Java code, added by helper h1 (session 9).
use super::{jwf_h9a_code, jwf_h9a_fract, jwf_h9a_plots};
// JWildfire variations driven by Java code, their default code (session 10).
use super::{jwf_s10_code, jwf_s10_code_dc};
// JWildfire's sunflower Voronoi diagram (helper h3, session 11).
use super::jwf_sv_sunvoroni;
// JWildfire variations that sample an anti-aliased drawing (session 11).
use super::{jwf_aa_svg, jwf_aa_truchet};
// JWildfire's Taprats star patterns (helper h1, session 12).
use super::jwf_tp;
// JWildfire variations, from the end of the alphabet.
use super::{
    jwf_z_3d, jwf_z_drawings, jwf_z_figures, jwf_z_flora, jwf_z_noise, jwf_z_orbits, jwf_z_plane,
    jwf_z_solids, jwf_z_warps,
};
// JWildfire's sub-flame and L-system variations (helper h3).
use super::{jwf_h9c_lsystem, jwf_h9c_subflame};
// JWildfire variations not yet implemented, part 1 (helper h4).
use super::{
    jwf_h4_cells, jwf_h4_hamid, jwf_h4_ifs, jwf_h4_inversion, jwf_h4_kifs, jwf_h4_klein,
    jwf_h4_mandala, jwf_h4_metaballs, jwf_h4_recurrence, jwf_h4_shapes, jwf_h4_terrain,
};
// JWildfire variations driven by images, meshes and other resources (helper h2, session 9).
use super::{jwf_h9b_code, jwf_h9b_images, jwf_h9b_meshes};
// JWildfire's 3-D shapes and meshes (helper h5, session 10).
use super::{jwf_s10_geo_attractor, jwf_s10_geo_mesh};
// JWildfire's Maurer lines (helper h2, session 10).
use super::jwf_s10_maurer;
// JWildfire variations added in session 10 by helper h3.
use super::{jwf_s10_quad, jwf_s10_tritile};
// JWildfire's kaleidoscope over an image (helper h1, session 10).
use super::jwf_pal_kaleido;
// JWildfire's 3-D L-systems (helper h6, session 11).
use super::jwf_ls_mesh;
// JWildfire's IFlames (helper h5, session 11).
use super::jwf_br_brush;
use super::jwf_tx_iflames;
use super::jwf_wt_wangtiles;

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

/// JWildfire's own formula for variation `id` used in `form`, where it differs from the one
/// flam3's and Fractorium's flames get (see `jwf_dialect`).
pub fn jwildfire_twin(id: VarId, form: Form) -> Option<&'static VarDef> {
    REGISTRY.twins.get(&(id, form)).copied()
}

/// Whether JWildfire runs variation `id`, written as a regular one, after the others unless
/// the flame gives it another priority (its twin is post-only: `flatten`, whose
/// `getPriority()` is +1 in JWildfire 9.00).
pub fn jwildfire_runs_after(id: VarId) -> bool {
    jwildfire_twin(id, Form::Regular)
        .is_some_and(|d| d.has(flag::POST_ONLY) && !info(id).has(flag::POST_ONLY))
}

/// The registry entry whose formula and parameter names variation `id` used in `form` has in
/// a flame of `dialect`: its JWildfire twin in a JWildfire flame, else its own.
pub fn def_in(dialect: Dialect, id: VarId, form: Form) -> &'static VarDef {
    match dialect {
        Dialect::JWildfire => jwildfire_twin(id, form).unwrap_or_else(|| info(id)),
        _ => info(id),
    }
}

/// The values a new use of variation `id` stores: its parameters' defaults, then those of the
/// parameters only its JWildfire formula has.
pub fn param_defaults(id: VarId) -> Vec<f64> {
    match REGISTRY.twin_params.get(&id) {
        Some(ps) => ps.iter().map(|p| p.default).collect(),
        None => info(id).defaults(),
    }
}

/// The formulas' files, each with its table of variations.
const FILES: [&[VarDef]; 127] = [
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
    jwf_post_symmetry::DEFS,
    jwf_prepost::DEFS,
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
    // JWildfire variations, first set of files.
    jwf_a_complex::DEFS,
    jwf_a_surfaces::DEFS,
    jwf_a_warps::DEFS,
    jwf_a_crops::DEFS,
    jwf_a_plane::DEFS,
    jwf_a_ifs::DEFS,
    jwf_a_shapes::DEFS,
    jwf_a_sdf3d::DEFS,
    jwf_a_cuts::DEFS,
    jwf_a_fractals::DEFS,
    jwf_a_dc::DEFS,
    // JWildfire variations, third part.
    jwf_c_escape::DEFS,
    jwf_c_glsl::DEFS,
    jwf_c_orbits::DEFS,
    // JWildfire variations, fourth part.
    jwf_d_crops::DEFS,
    jwf_d_cuts::DEFS,
    jwf_d_cvar::DEFS,
    jwf_d_plane::DEFS,
    jwf_d_solids::DEFS,
    // JWildfire variations, from the end of the alphabet.
    jwf_z_plane::DEFS,
    jwf_z_3d::DEFS,
    jwf_z_warps::DEFS,
    jwf_z_flora::DEFS,
    jwf_z_noise::DEFS,
    jwf_z_drawings::DEFS,
    jwf_z_solids::DEFS,
    jwf_z_orbits::DEFS,
    jwf_z_figures::DEFS,
    // JWildfire's direct-colour stamps.
    jwf_dc_twins::DEFS,
    jwf_dc_tiles::DEFS,
    jwf_dc_patterns::DEFS,
    jwf_dc_fields::DEFS,
    jwf_dc_folds::DEFS,
    jwf_dc_cells::DEFS,
    jwf_dc_maps::DEFS,
    jwf_dc_mandel::DEFS,
    // JWildfire variations, the cut and single-formula ones added last.
    jwf_m_trig::DEFS,
    jwf_m_crops::DEFS,
    jwf_m_cuts::DEFS,
    jwf_m_draw::DEFS,
    jwf_m_tiles::DEFS,
    jwf_m_curves::DEFS,
    jwf_m_polylog::DEFS,
    jwf_m_stabilize::DEFS,
    jwf_m_quaternion::DEFS,
    jwf_m_tilecuts::DEFS,
    jwf_m_ifs3d::DEFS,
    jwf_m_foam::DEFS,
    jwf_h4_mandala::DEFS,
    jwf_h4_klein::DEFS,
    jwf_h4_cells::DEFS,
    jwf_h4_kifs::DEFS,
    jwf_h4_hamid::DEFS,
    jwf_h4_ifs::DEFS,
    jwf_h4_shapes::DEFS,
    jwf_h4_recurrence::DEFS,
    jwf_h4_inversion::DEFS,
    jwf_h4_terrain::DEFS,
    jwf_h4_metaballs::DEFS,
    jwf_h5_shapes::DEFS,
    jwf_h5_sims::DEFS,
    jwf_h5_draw::DEFS,
    jwf_h5_crops::DEFS,
    jwf_h5_glsl::DEFS,
    jwf_h5_octree::DEFS,
    jwf_h5_triantess::DEFS,
    // JWildfire's sub-flame and L-system variations (helper h3).
    jwf_h9c_subflame::DEFS,
    jwf_h9c_lsystem::DEFS,
    jwf_h9a_plots::DEFS,
    jwf_h9a_code::DEFS,
    jwf_h9a_fract::DEFS,
    jwf_h9b_images::DEFS,
    jwf_h9b_meshes::DEFS,
    jwf_h9b_code::DEFS,
    // JWildfire's 3-D shapes and meshes (helper h5, session 10).
    jwf_s10_geo_mesh::DEFS,
    jwf_s10_geo_attractor::DEFS,
    // JWildfire's Maurer lines (helper h2, session 10).
    jwf_s10_maurer::DEFS,
    jwf_s10_quad::DEFS,
    jwf_s10_tritile::DEFS,
    jwf_pal_kaleido::DEFS,
    jwf_s10_code::DEFS,
    jwf_s10_code_dc::DEFS,
    // JWildfire's sunflower Voronoi diagram (helper h3, session 11).
    jwf_sv_sunvoroni::DEFS,
    // JWildfire's variations that sample an anti-aliased drawing (helper h4, session 11).
    jwf_aa_svg::DEFS,
    jwf_aa_truchet::DEFS,
    // JWildfire's 3-D L-systems (helper h6, session 11).
    jwf_ls_mesh::DEFS,
    // JWildfire's IFlames, its image part (helper h5, session 11).
    jwf_tx_iflames::DEFS,
    // JWildfire's Taprats star patterns (helper h1, session 12).
    jwf_tp::DEFS,
    // JWildfire's brush strokes (helper h2, session 12).
    jwf_br_brush::DEFS,
    // JWildfire's Wang tiles (helper h3, session 12).
    jwf_wt_wangtiles::DEFS,
];

/// The JWildfire variations, in the order ugnis took them in (which gives them their ids). A
/// variation missing here comes after these, in the order of [`FILES`].
const JWILDFIRE_ORDER: [&str; 164] = [
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
    "jac_elk",
    "jac_asn",
    "glynnspiro",
    "juliascopePlus",
    "mobiqN",
    "mobius3D_with_inverse",
    "hypertile3Db",
    "juliascope3Db",
    "checkerboard_wf",
    "shape_warp",
    "drunken_tiles",
    "bwrands",
    "glitchy2",
    "flora",
    "camouflage",
    "truchetflow",
    "kaplan",
    "htree_js",
    "koch_js",
    "dragon_js",
    "gosperisland_js",
    "brownian_js",
    "mobius_dragon_3D",
    "polySurf",
    "primitives_wf",
    "glynnSim2B",
    "gumowski_mira",
    "starfractal",
    "iconattractor_js",
    "sphtiling3v2",
    "harmonograph_js",
    "tqmirror",
    "rhodonea",
];

/// The JWildfire variations added with the first set of files, in the order ugnis took them in
/// (after [`JWILDFIRE_ORDER`]).
const JWILDFIRE_ORDER_A: &[&str] = &[
    "sin2_bs",
    "cosh2_bs",
    "cot2_bs",
    "tan2_bs",
    "tanh2_bs",
    "coth2_bs",
    "sec2_bs",
    "acosh",
    "acosech",
    "sqrt_acosh",
    "sqrt_atanh",
    "sqrt_acosech",
    "log_apo",
    "invpolar",
    "bi_linear",
    "joukowski",
    "ennepers2",
    "petal3D_apo",
    "whitney_umbrella",
    "butterfly3D",
    "inflateZ_2",
    "inflateZ_4",
    "inflateZ_6",
    "sph3D",
    "spherical3D_wf",
    "onion2",
    "boxfold",
    "erf3D",
    "bwraps7",
    "rings3",
    "waves3_wf",
    "invsquircular",
    "c_symmetry",
    "tunnel",
    "corners",
    "disc3",
    "lazysensen",
    "pTransform",
    "spligon",
    "anamorphcyl",
    "clifford_js",
    "gridout2",
    "chunk",
    "crop_triangle",
    "crop_rhombus",
    "crop_cross",
    "crop_vesica",
    "crop3D",
    "flower_db",
    "atan2_spirals",
    "minkQM",
    "scrambly",
    "colorscale_wf",
    "bubble_wf",
    "dustpoint",
    "threepoint_js",
    "hadamard_js",
    "lace_js",
    "circular",
    "apollony",
    "apocarpet_js",
    "siercarpet_js",
    "sattractor_js",
    "cannabiscurve_wf",
    "maple_leaf",
    "japanese_maple_leaf",
    "cone",
    "r_circleblur",
    "spliptic_bs",
    "tile_reverse",
    "target_sp",
    "box3D",
    "bbox3D",
    "ellipsoid3D",
    "hexprism3D",
    "ocylinder3D",
    "pyramid3D",
    "solidangle3D",
    "cappedtorus3D",
    "ocappedcone3D",
    "oroundcone3D",
    "cut_fun",
    "mandelbrot",
    "dc_starsfield",
    "petal3D",
    "mandelbox2D",
    "truchet2",
    "combimirror",
    "post_bulbtorus_crop",
    "dc_voronoise",
    "dc_menger",
    "elliptic2",
    "parallel",
    "shredded",
    "hypertile3D2b",
    "glynnlissa",
    "glynnSShape",
    "jubiQ",
    "cut_triskel",
    "cut_yuebing",
    "cut_hexdots",
    "cut_x",
    "cut_sincos",
    "cut_sqsplits",
    "cut_chains",
    "cut_fractal",
    "cut_btruchet",
    "cut_btree",
    "cut_spiralcb",
    "cut_snowflake",
    "cut_booleans",
    "cut_web",
    "cut_glypho",
    "cut_bricks",
    "dc_booleans",
    "dc_glypho",
    "dc_moebiuslog",
    // JWildfire's own pre_/post_ classes and prepost variations.
    "pre_affine3D",
    "post_affine3D",
    "pre_spin_z",
    "post_spin_z",
    "post_ztranslate_wf",
    "pre_dcztransl",
    "post_dcztransl",
    "pre_wave3D_wf",
    "post_log_tile2",
    "pre_c_symmetry",
    "post_c_symmetry",
    "post_crosscrop",
    "prepost_mobius",
    "prepost_affine",
    "prepost_circlize",
    "prepost_blob",
    "ringtile",
    "post_point_symmetry_wf",
    "post_axis_symmetry_wf",
    "bwraps2",
    // JWildfire variations, third part.
    "fract_julia_wf",
    "fract_mandelbrot_wf",
    "fract_dragon_wf",
    "fract_meteors_wf",
    "fract_pearls_wf",
    "fract_salamander_wf",
    "glsl_acrilic",
    "glsl_starsfield",
    "glsl_mandelbox2D",
    "glsl_apollonian",
    "glsl_kaliset",
    "glsl_kaliset2",
    "glsl_squares",
    "glsl_circlesblue",
    "glsl_grid3D",
    "glsl_hyperbolictile",
    "glsl_mandala",
    "glsl_kaleidoscopic",
    "glsl_kaleidocomplex",
    "glsl_fractaldots",
    "macmillan",
    "hopalong",
    "threeply",
    "curliecue2",
    // JWildfire variations, fourth part.
    "cone3D",
    "torus3D",
    "cylinder3D",
    "capsule3D",
    "cappedcone3D",
    "rhombus3D",
    "triprism3D",
    "octahedron3D",
    "octogonprism3D",
    "rbox3D",
    "hourglass3D",
    "gridout3D",
    "post_benesi_crop",
    "post_bristorbrot_crop",
    "post_coastalbrot_crop",
    "post_aexion_crop",
    "post_mandelbox3d_crop",
    "pre_rect_wf",
    "cut_spiral",
    "cut_wood",
    "cut_metaballs",
    "cut_vasarely",
    "cut_apollonian",
    "cut_spots",
    "cut_celtic",
    "cut_truchet",
    "de_stijl",
    "pointgrid_wf",
    "pointgrid3d_wf",
    "cut_jigsaw",
    "cut_circdes",
    "cut_pattern",
    "cut_swarp",
    "cut_kaleido",
    "meeple",
    "waveblur_wf",
    "conicalSpiral",
    "intersection",
    "c_var",
    "pre_c_var",
    "post_c_var",
    "cut_c",
    "spirograph3D",
    // JWildfire's direct-colour stamps.
    "dc_apollonian",
    "dc_circlesblue",
    "dc_fractaldots",
    "dc_grid3D",
    "dc_hoshi",
    "dc_hyperbolictile",
    "dc_kaleidocomplex",
    "dc_kaleidoscopic",
    "dc_kaliset",
    "dc_kaliset2",
    "dc_mandelbox2D",
    "dc_squares",
    "dc_truchet",
    "dc_worley",
    "dc_pentatiles",
    "dc_cairotiles",
    "dc_sunflower",
    "dc_hexagons",
    "dc_fingerprint",
    "dc_quadtree",
    "dc_layers",
    "dc_tree",
    "dc_tesla",
    "dc_rotations",
    "dc_ducks",
    "dc_mandbrot",
    "dc_spacefold",
    "dc_warping",
    "dc_fractcolor",
    "dc_butterflies",
    "dc_crackle_wf",
    "dc_cracklep_wf",
    "dc_hexes_wf",
    "dc_cylinder2",
    "dc_dmodulus",
    "dc_kaleidotile",
    "dc_carpet3D",
    "dc_gnarly",
    "dc_gmandelbroot",
];

/// The JWildfire variations added with the cut and single-formula files, in the order ugnis
/// took them in (after [`JWILDFIRE_ORDER_A`]).
const JWILDFIRE_ORDER_M: &[&str] = &[
    "pre_recip",
    "post_trig",
    "post_asurf_crop",
    "post_mandelbulb3d_crop",
    "cut_2ewangtile",
    "cut_alientext",
    "cut_fingerprint",
    "cut_kleinian",
    "cut_magfield",
    "sunflower",
    "arctruchet",
    "maurer_rose",
    "butterfly_fay",
    "polylogarithm",
    "pre_stabilize",
    "quaternion",
    "cut_hextruchetflow",
    "cut_mandala",
    "cut_truchetweaving",
    "cut_randomtile",
    "cut_tstruchet",
    "cut_triantess",
    "_slice_indicator_wf",
    "geometricPrimitives",
    "chaosCubes",
    "romanesco",
    "natural_foam",
    "mandala",
    "mandala2",
    "klein_group",
    "cell3D",
    "kifs3d",
    "hamid_js",
    "multi_ifs",
    "cut_shapes",
    "recurrenceplot",
    "inversion",
    "terrain3D",
    "metaballs3d_wf",
    "cactusGlobe",
    "tess_shape",
    "flame_bulb",
    "grid3d_wf",
    "truchet_ae",
    "dla_wf",
    "curliecue",
    "gpattern",
    "triantruchet",
    "ringer",
    "post_point_crop",
    "point_mirror_symmetry",
    "glsl_circuits",
    "glsl_randomoctree",
    "dc_randomoctree",
    "dc_triantess",
    "subflame_wf",
    "pre_subflame_wf",
    "ringsubflame",
    "glynns3subfl",
    "lsystem_js",
    "parplot2d_wf",
    "polarplot2d_wf",
    "yplot2d_wf",
    "yplot3d_wf",
    "isosfplot3d_wf",
    "custom_wf",
    "custom_wf_full",
    "pre_custom_wf",
    "post_custom_wf",
    "fract_formula_julia_wf",
    "fract_formula_mand_wf",
    "colormap_wf",
    "post_colormap_wf",
    "displacemap_wf",
    "post_displacemap_wf",
    "post_bumpmap_wf",
    "obj_mesh_wf",
    "colordomain",
    "obj_mesh_primitive_wf",
    "sattractor3D",
    "maurer_lines",
    "quad",
    "dc_triTile",
    "kaleidoimg",
    "glsl_code",
    "f_complex",
    "ducks",
    "dc_code",
    "sunvoroni",
    "svg_wf",
    "msTruchet",
    "lsystem3D_js",
    "iflames_wf",
    "taprats",
    "brush_stroke_wf",
    "post_brush_stroke_wf",
    "wangtiles",
];

/// Every JWildfire variation's name in registry order.
fn jwildfire_order() -> impl Iterator<Item = &'static str> {
    (JWILDFIRE_ORDER.iter().chain(JWILDFIRE_ORDER_A))
        .chain(JWILDFIRE_ORDER_M)
        .copied()
}

/// Every variation in registry order (see the module documentation).
fn ordered() -> Vec<&'static VarDef> {
    let others = || FILES.iter().flat_map(|f| f.iter());
    let mut fractorium: Vec<&'static VarDef> =
        others().filter(|d| !d.has(flag::JWILDFIRE)).collect();
    fractorium.sort_by_key(|d| d.name.to_ascii_lowercase());
    let mut jwildfire: Vec<&'static VarDef> = others().filter(|d| d.has(flag::JWILDFIRE)).collect();
    jwildfire.sort_by_key(|d| {
        jwildfire_order()
            .position(|n| n == d.name)
            .unwrap_or(usize::MAX)
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
    /// (id, form) → JWildfire's formula where it differs.
    pub(super) twins: HashMap<(VarId, Form), &'static VarDef>,
    /// id → the longest parameter list of its twins (the registry's parameters, then those
    /// only JWildfire's formula has).
    pub(super) twin_params: HashMap<VarId, &'static [Param]>,
}

/// The JWildfire twins by the variation and form their names denote: the formulas of
/// [`jwf_dialect::TABLES`]; the variations JWildfire computes as 2-D ones where flam3's or
/// Fractorium's carry z along (their own formula, the framework's z); those it runs after the
/// others whatever their name says.
fn twins(
    names: &HashMap<String, VarId>,
    defs: &[&'static VarDef],
) -> HashMap<(VarId, Form), &'static VarDef> {
    let mut out = HashMap::new();
    let flat = jwf_dialect::FLAT
        .iter()
        .map(|n| (*n, None, flag::WRITES_Z, 0));
    let after = jwf_dialect::AFTER
        .iter()
        .map(|n| (*n, None, 0, flag::POST_ONLY));
    let formulas = (jwf_dialect::FORMULAS.iter()).map(|&(n, f, off, on)| (n, Some(f), off, on));
    for (name, eval, off, on) in flat.chain(after).chain(formulas) {
        let key = lookup_in(names, defs, &name.to_ascii_lowercase());
        let key = key.unwrap_or_else(|| panic!("JWildfire twin {name} is not registered"));
        let d = out.get(&key).copied().unwrap_or(defs[key.0 as usize]);
        let twin: &'static VarDef = Box::leak(Box::new(VarDef {
            flags: (d.flags & !off) | on,
            eval: eval.unwrap_or(d.eval),
            // A batch loop inlines the registry's formula.
            batch: if eval.is_some() { None } else { d.batch },
            form_batch: if eval.is_some() { None } else { d.form_batch },
            ..*d
        }));
        out.insert(key, twin);
    }
    for d in jwf_dialect::TABLES.iter().copied().flatten() {
        let key = lookup_in(names, defs, &d.name.to_ascii_lowercase());
        let (id, form) =
            key.unwrap_or_else(|| panic!("JWildfire twin {} is not registered", d.name));
        let base = defs[id as usize];
        assert!(
            d.params.len() >= base.params.len() && d.texts.len() == base.texts.len(),
            "JWildfire twin {} lacks parameters of {}",
            d.name,
            base.name
        );
        out.insert((id, form), d);
    }
    out
}

/// The parameter names JWildfire uses where they differ from the registry's, and the
/// parameters only JWildfire's formula has (after the registry's), as further entries of the
/// table of parameter names; the longest parameter list of each variation's twins.
fn twin_params(
    twins: &HashMap<(VarId, Form), &'static VarDef>,
    params: &mut HashMap<String, (VarId, usize)>,
) -> HashMap<VarId, &'static [Param]> {
    let mut longest: HashMap<VarId, &'static [Param]> = HashMap::new();
    for (&(id, _), d) in twins {
        for (k, p) in d.params.iter().enumerate() {
            params.entry(p.name.to_ascii_lowercase()).or_insert((id, k));
        }
        let l = longest.entry(id).or_insert(d.params);
        if d.params.len() > l.len() {
            *l = d.params;
        }
    }
    longest
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
    let twins = twins(&names, &defs);
    let twin_params = twin_params(&twins, &mut params);
    Registry {
        defs,
        names,
        params,
        texts,
        twins,
        twin_params,
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
        assert_eq!(jwildfire, jwildfire_order().collect::<Vec<_>>());
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
        assert_eq!(99 + fractorium.len() + jwildfire_order().count(), count());
    }
}
