//! JWildfire's direct-colour cell maps by Andreas Maschke: `dc_crackle_wf` and
//! `dc_cracklep_wf` (crackle, slobo777's Voronoi cells) and `dc_hexes_wf` (hexes, his
//! hexagonal cells), each moving the point as the plain map does and taking the cell ratio
//! it used, scaled and offset (clamped to [0, 1]), as the palette index.
//!
//! `dc_cracklep_wf`'s `preset` only fills in the other parameters in JWildfire's editor (a
//! flame stores the values in use), so it changes nothing here; it comes last so that the
//! other parameters sit where crackle's formula reads them.

use super::fr_grids::{crackle_cell, prep_crackle};
use super::fr_hexagons::{hexes_cell, hexes_prepare};
use super::*;

const FLAGS: u32 = flag::JWILDFIRE | flag::SETS_COLOR;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("dc_crackle_wf", dc_crackle)
        .params(&[
            p_range("dc_crackle_wf_cellsize", 1.0, 0.0001, INF),
            p("dc_crackle_wf_power", 0.2),
            p("dc_crackle_wf_distort", 0.0),
            p("dc_crackle_wf_scale", 1.0),
            p("dc_crackle_wf_z", 0.0),
            p("dc_crackle_wf_color_scale", 0.5),
            p("dc_crackle_wf_color_offset", 0.0),
        ])
        .flags(FLAGS | flag::RANDOM)
        .prepare(prep_crackle),
    VarDef::new("dc_cracklep_wf", dc_crackle)
        .params(&[
            p_range("dc_cracklep_wf_cellsize", 1.0, 0.0001, INF),
            p("dc_cracklep_wf_power", 0.2),
            p("dc_cracklep_wf_distort", 0.0),
            p("dc_cracklep_wf_scale", 1.0),
            p("dc_cracklep_wf_z", 0.0),
            p("dc_cracklep_wf_color_scale", 0.5),
            p("dc_cracklep_wf_color_offset", 0.0),
            p_int("dc_cracklep_wf_preset", 0.0, NEG_INF, INF),
        ])
        .flags(FLAGS | flag::RANDOM)
        .prepare(prep_crackle),
    VarDef::new("dc_hexes_wf", dc_hexes)
        .params(&[
            p("dc_hexes_wf_cellsize", 1.0),
            p("dc_hexes_wf_power", 1.0),
            p("dc_hexes_wf_rotate", 0.166),
            p("dc_hexes_wf_scale", 1.0),
            p("dc_hexes_wf_color_scale", 0.5),
            p("dc_hexes_wf_color_offset", 0.0),
        ])
        .flags(FLAGS)
        .prepare(hexes_prepare),
];

/// The palette index from a cell ratio: ratio·scale + offset, clamped to [0, 1].
fn cell_colour(l: f64, scale: f64, offset: f64) -> f64 {
    (l * scale + offset).clamp(0.0, 1.0)
}

/// dc_crackle_wf, dc_cracklep_wf: crackle, coloured by its Voronoi ratio.
fn dc_crackle(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, scale, offset] = v.params();
    let (x, y, l) = crackle_cell(v, rng);
    acc.color = cell_colour(l, scale, offset);
    [v.w * x, v.w * y, 0.0]
}

/// dc_hexes_wf: hexes, coloured by its cell ratio (nothing for a cell size of 0).
fn dc_hexes(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, _, scale, offset] = v.params();
    match hexes_cell(v, t) {
        Some((x, y, l)) => {
            acc.color = cell_colour(l, scale, offset);
            [v.w * x, v.w * y, 0.0]
        }
        None => [0.0, 0.0, 0.0],
    }
}
