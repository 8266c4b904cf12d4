//! Variations (slice fr_b of the registry): Fractorium's catalogue from `crob` to `farblur`
//! (cropping, the "depth" blurs, the elliptic-coordinate family `eCollide` … `eSwirl`, the
//! direct-colour `dc_*` variations, the falloff blurs and a few analytic maps).
//!
//! Formulas follow Fractorium's behaviour (its numbers are the reference); the code is ugnis's.

use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, PI, TAU};

use super::noise::fractal_noise;
use super::util::{
    acosh, elliptic, erf, from_elliptic, lrint, sign_nz, signed_pow_or_id, sine_hash, sqr, zeps,
};
#[allow(unused_imports)]
use super::*;

const INF: f64 = f64::INFINITY;
const NEG_INF: f64 = f64::NEG_INFINITY;

/// The parameters of the anisotropic depth blurs (`NAME` = depth_blur2, depth_gaussian2, …):
/// any leading ones given, then blur, radius, centre (x0, y0), distance multipliers and the
/// exponent of the growth.
macro_rules! depth2_params {
    ($name:literal $(, $lead:expr)*) => {
        &[
            $($lead,)*
            p(concat!($name, "_blur"), 1.0),
            p(concat!($name, "_radius"), 1.0),
            p(concat!($name, "_x0"), 0.0),
            p(concat!($name, "_y0"), 0.0),
            p(concat!($name, "_mulx"), 1.0),
            p(concat!($name, "_muly"), 1.0),
            p(concat!($name, "_exp"), 1.0),
        ]
    };
}

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("crob", crob)
        .params(&[
            p("crob_top", -1.0),
            p("crob_bottom", 1.0),
            p("crob_left", -1.0),
            p("crob_right", 1.0),
            p_int("crob_blur", 1.0, NEG_INF, INF),
            p_range("crob_ratioBlur", 0.5, 0.0, 1.0),
            p("crob_directBlur", 2.0),
        ])
        .flags(flag::RANDOM)
        .prepare(crob_prepare),
    VarDef::new("crop", crop)
        .batch(super::inline_batch!(crop))
        .params(&[
            p("crop_left", -1.0),
            p("crop_top", -1.0),
            p("crop_right", 1.0),
            p("crop_bottom", 1.0),
            p("crop_scatter_area", 0.0),
            p_int("crop_zero", 0.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(crop_prepare),
    VarDef::new("cropn", cropn)
        .params(&[
            p("cropn_power", 5.0),
            p("cropn_radius", 1.0),
            p("cropn_scatterdist", 0.0),
            p("cropn_zero", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES | need::ATAN_YX)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(cropn_prepare),
    VarDef::new("cschq", cschq)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("cscq", cscq)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("cubic3D", cubic3d)
        .params(&[p("cubic3D_xpand", 0.25), p("cubic3D_style", 0.0)])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::READS_ACC)
        .prepare(cubic3d_prepare),
    VarDef::new("cubicLattice_3D", cubic_lattice_3d)
        .params(&[
            p("cubicLattice_3D_xpand", 0.2),
            p_int("cubicLattice_3D_style", 1.0, 1.0, 2.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::READS_ACC)
        .prepare(cubic_lattice_3d_prepare),
    VarDef::new("curl3D", curl3d)
        .batch(super::inline_batch!(curl3d))
        .params(&[
            p("curl3D_cx", 0.0),
            p("curl3D_cy", 0.0),
            p("curl3D_cz", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(curl3d_prepare),
    VarDef::new("curl_sp", curl_sp)
        .params(&[
            p_nonzero("curl_sp_pow", 1.0, NEG_INF, INF),
            p("curl_sp_c1", 0.0),
            p("curl_sp_c2", 0.0),
            p("curl_sp_sx", 0.0),
            p("curl_sp_sy", 0.0),
            p("curl_sp_dc", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR | flag::COMPAT)
        .prepare(curl_sp_prepare),
    VarDef::new("curvature", curvature).needs(need::SUMSQ | need::SQRT | need::ATAN_YX),
    VarDef::new("cylinder2", cylinder2).batch(super::inline_batch!(cylinder2)),
    VarDef::new("d_spherical", d_spherical)
        .params(&[p("d_spherical_weight", 0.5)])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM),
    VarDef::new("dc_bubble", dc_bubble)
        .params(&[
            p("dc_bubble_centerx", 0.0),
            p("dc_bubble_centery", 0.0),
            p("dc_bubble_scale", 1.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC)
        .prepare(dc_bubble_prepare),
    VarDef::new("dc_carpet", dc_carpet)
        .params(&[p("dc_carpet_origin", 0.0)])
        .flags(flag::RANDOM | flag::USES_AFFINE | flag::SETS_COLOR),
    VarDef::new("dc_cube", dc_cube)
        .params(&[
            p("dc_cube_c1", 0.0),
            p("dc_cube_c2", 0.0),
            p("dc_cube_c3", 0.0),
            p("dc_cube_c4", 0.0),
            p("dc_cube_c5", 0.0),
            p("dc_cube_c6", 0.0),
            p("dc_cube_x", 1.0),
            p("dc_cube_y", 1.0),
            p("dc_cube_z", 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR)
        .sum()
        .prepare(dc_cube_prepare),
    VarDef::new("dc_cylinder", dc_cylinder)
        .params(&[
            p("dc_cylinder_offset", 0.0),
            p("dc_cylinder_angle", 0.0),
            p("dc_cylinder_scale", 0.5),
            p("dc_cylinder_x", 0.125),
            p("dc_cylinder_y", 0.125),
            p("dc_cylinder_blur", 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC)
        .prepare(dc_cylinder_prepare),
    VarDef::new("dc_gridout", dc_gridout).flags(flag::SETS_COLOR),
    VarDef::new("dc_linear", dc_linear)
        .batch(super::inline_batch!(dc_linear))
        .params(&[
            p("dc_linear_offset", 0.0),
            p("dc_linear_angle", 0.0),
            p("dc_linear_scale", 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC)
        .prepare(dc_linear_prepare),
    VarDef::new("dc_perlin", dc_perlin)
        .params(&[
            p_int("dc_perlin_shape", 0.0, 0.0, 2.0),
            p_int("dc_perlin_map", 0.0, 0.0, 5.0),
            p_range("dc_perlin_select_centre", 0.0, -1.0, 1.0),
            p_range("dc_perlin_select_range", 1.0, 0.1, 2.0),
            p("dc_perlin_centre", 0.25),
            p("dc_perlin_range", 0.25),
            p("dc_perlin_edge", 0.0),
            p("dc_perlin_scale", 1.0),
            p_int("dc_perlin_octaves", 2.0, 1.0, 5.0),
            p("dc_perlin_amps", 2.0),
            p("dc_perlin_freqs", 2.0),
            p("dc_perlin_z", 0.0),
            p_int("dc_perlin_select_bailout", 10.0, 2.0, 1000.0),
        ])
        .flags(flag::RANDOM | flag::SETS_COLOR)
        .prepare(dc_perlin_prepare),
    VarDef::new("dc_triangle", dc_triangle)
        .params(&[
            p_range("dc_triangle_scatter_area", 0.0, -1.0, 1.0),
            p_int("dc_triangle_zero_edges", 0.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::USES_AFFINE | flag::SETS_COLOR),
    VarDef::new("dc_ztransl", dc_ztransl)
        .params(&[
            p_range("dc_ztransl_x0", 0.0, 0.0, 1.0),
            p_range("dc_ztransl_x1", 1.0, 0.0, 1.0),
            p("dc_ztransl_factor", 1.0),
            p_int("dc_ztransl_overwrite", 1.0, 0.0, 1.0),
            p_int("dc_ztransl_clamp", 0.0, 0.0, 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::USES_COLOR)
        .prepare(dc_ztransl_prepare),
    VarDef::new("deltaa", deltaa),
    VarDef::new("depth", depth)
        .params(&[p("depth_power", 1.0)])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("depth_blur", depth_blur)
        .params(&[
            p("depth_blur_power", 5.0),
            p("depth_blur_range", 0.401623),
            p("depth_blur_blur", 1.0),
            p("depth_blur_radius", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM)
        .prepare(depth_blur_prepare),
    VarDef::new("depth_blur2", depth_blur2)
        .params(depth2_params!(
            "depth_blur2",
            p("depth_blur2_power", 5.0),
            p("depth_blur2_range", 0.401623)
        ))
        .flags(flag::RANDOM)
        .prepare(depth_blur2_prepare),
    VarDef::new("depth_gaussian", depth_gaussian)
        .params(&[
            p("depth_gaussian_blur", 1.0),
            p("depth_gaussian_radius", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM),
    VarDef::new("depth_gaussian2", depth_gaussian2)
        .params(depth2_params!("depth_gaussian2"))
        .flags(flag::RANDOM)
        .prepare(depth_gaussian2_prepare),
    VarDef::new("depth_ngon", depth_ngon)
        .params(&[
            p("depth_ngon_power", 5.0),
            p("depth_ngon_blur", 1.0),
            p("depth_ngon_radius", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM)
        .prepare(depth_ngon_prepare),
    VarDef::new("depth_ngon2", depth_ngon2)
        .params(depth2_params!("depth_ngon2", p("depth_ngon2_power", 5.0)))
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(depth_ngon2_prepare),
    VarDef::new("depth_sine", depth_sine)
        .params(&[
            p_range("depth_sine_power", 1.0, 0.0, INF),
            p("depth_sine_blur", 1.0),
            p("depth_sine_radius", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM),
    VarDef::new("depth_sine2", depth_sine2)
        .params(depth2_params!(
            "depth_sine2",
            p_range("depth_sine2_power", 1.0, 0.0, INF)
        ))
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(depth_sine2_prepare),
    VarDef::new("disc3d", disc3d)
        .params(&[p("disc3d_pi", PI)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("dragonfire", dragonfire)
        .params(&[
            p("dragonfire_c1", 0.5),
            p("dragonfire_c2", 0.25),
            p_range("dragonfire_fuzzyMode", 0.0, 0.0, 7.0),
            p("dragonfire_fuzzyRadius", 1.0),
            p_range("dragonfire_fuzzyInterpolationMode", 0.0, 0.0, 6.0),
            p("dragonfire_fuzzyInterpolationPosition", 1.0),
            p("dragonfire_logScalarFuzzy", TAU),
            p("dragonfire_adjustedFuzzyScalar", 0.5),
        ])
        .prepare(dragonfire_prepare),
    VarDef::new("dust", dust).params(&[
        p_nonzero("dust_density", 5.0, NEG_INF, INF),
        p("dust_distortion", 1.0),
        p("dust_power", 1.0),
    ]),
    VarDef::new("eclipse", eclipse).params(&[p_cyclic("eclipse_shift", 0.0, -2.0, 2.0)]),
    VarDef::new("eCollide", e_collide)
        .params(&[
            p_cyclic("eCollide_a", 0.0, 0.0, 1.0),
            p_int("eCollide_num", 1.0, 1.0, 2147483647.0),
        ])
        .needs(need::SUMSQ)
        .prepare(e_collide_prepare),
    VarDef::new("eJulia", e_julia)
        .params(&[p_int_nonzero("eJulia_power", 2.0, NEG_INF, INF)])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM),
    VarDef::new("eMod", e_mod)
        .params(&[
            p_range("eMod_radius", 1.0, 0.0, INF),
            p_cyclic("eMod_distance", 0.0, 0.0, 2.0),
        ])
        .needs(need::SUMSQ),
    VarDef::new("eMotion", e_motion)
        .params(&[
            p("eMotion_move", 0.0),
            p_cyclic("eMotion_rotate", 0.0, 0.0, TAU),
        ])
        .needs(need::SUMSQ),
    VarDef::new("ennepers", ennepers),
    VarDef::new("epispiral", epispiral)
        .batch(super::inline_batch!(epispiral))
        .params(&[
            p("epispiral_n", 6.0),
            p("epispiral_thickness", 0.0),
            p("epispiral_holes", 1.0),
        ])
        .needs(need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(epispiral_prepare),
    VarDef::new("ePush", e_push)
        .params(&[
            p("ePush_push", 0.0),
            p("ePush_dist", 1.0),
            p_cyclic("ePush_rotate", 0.0, -PI, PI),
        ])
        .needs(need::SUMSQ),
    VarDef::new("erf", erf_var),
    VarDef::new("eRotate", e_rotate)
        .params(&[p_cyclic("eRotate_rotate", 0.0, -PI, PI)])
        .needs(need::SUMSQ),
    VarDef::new("eScale", e_scale)
        .params(&[
            p_nonzero("eScale_scale", 1.0, 0.0, 1.0),
            p_cyclic("eScale_angle", 0.0, 0.0, TAU),
        ])
        .needs(need::SUMSQ),
    VarDef::new("estiq", estiq).flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("eSwirl", e_swirl)
        .params(&[p("eSwirl_in", 0.0), p("eSwirl_out", 0.0)])
        .needs(need::SUMSQ),
    VarDef::new("excinis", excinis)
        .params(&[
            p("excinis_lengthscalar", 1.0),
            p_range("excinis_radiusFunc", 0.0, 0.0, 5.0),
            p("excinis_eps", 0.1),
        ])
        .needs(need::SUMSQ | need::SQRT),
    VarDef::new("exp2", exp2),
    VarDef::new("expo", expo)
        .params(&[p("expo_real", -1.0), p("expo_imaginary", 1.0)])
        .prepare(expo_prepare),
    VarDef::new("extrude", extrude)
        .params(&[p("extrude_root_face", 0.5)])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::WRITES_ACC),
    VarDef::new("falloff", falloff)
        .params(&[
            p_range("falloff_scatter", 1.0, f64::EPSILON, INF),
            p_range("falloff_mindist", 0.5, 0.0, INF),
            p_range("falloff_mul_x", 1.0, 0.0, 1.0),
            p_range("falloff_mul_y", 1.0, 0.0, 1.0),
            p_range("falloff_mul_z", 0.0, 0.0, 1.0),
            p("falloff_x0", 0.0),
            p("falloff_y0", 0.0),
            p("falloff_z0", 0.0),
            p_int("falloff_invert", 0.0, 0.0, 1.0),
            p_int("falloff_type", 0.0, 0.0, 2.0),
            p_int("falloff_boxpow", 2.0, 2.0, 32.0),
        ])
        .needs(need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("falloff2", falloff2)
        .batch(super::inline_batch!(falloff2))
        .params(&[
            p("falloff2_scatter", 1.0),
            p("falloff2_mindist", 0.5),
            p("falloff2_mul_x", 1.0),
            p("falloff2_mul_y", 1.0),
            p("falloff2_mul_z", 0.0),
            p("falloff2_mul_c", 0.0),
            p("falloff2_x0", 0.0),
            p("falloff2_y0", 0.0),
            p("falloff2_z0", 0.0),
            p_range("falloff2_invert", 0.0, 0.0, 1.0),
            p_range("falloff2_type", 0.0, 0.0, 2.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR),
    VarDef::new("falloff3", falloff3)
        .params(&[
            p_int("falloff3_blur_type", 0.0, 0.0, 3.0),
            p_int("falloff3_blur_shape", 0.0, 0.0, 1.0),
            p_range("falloff3_blur_strength", 1.0, f64::EPSILON, INF),
            p_range("falloff3_min_distance", 0.5, 0.0, INF),
            p_int("falloff3_invert_distance", 0.0, 0.0, 1.0),
            p_range("falloff3_mul_x", 1.0, 0.0, 1.0),
            p_range("falloff3_mul_y", 1.0, 0.0, 1.0),
            p_range("falloff3_mul_z", 0.0, 0.0, 1.0),
            p_range("falloff3_mul_c", 0.0, 0.0, 1.0),
            p("falloff3_center_x", 0.0),
            p("falloff3_center_y", 0.0),
            p("falloff3_center_z", 0.0),
            p("falloff3_alpha", 0.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR),
    VarDef::new("farblur", farblur)
        .params(&[
            p("farblur_x", 1.0),
            p("farblur_y", 1.0),
            p("farblur_z", 1.0),
            p("farblur_x_origin", 0.0),
            p("farblur_y_origin", 0.0),
            p("farblur_z_origin", 0.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z),
];

// ---------------------------------------------------------------------------------------------
// Shared helpers.

/// The point (x, y) of a `pre_` form, else the xform's running sum: what the variations that
/// look at "the sum so far" read.
#[inline(always)]
fn sum_or_input(v: &Prepared, t: &VarIn, acc: &Acc) -> (f64, f64, f64) {
    if v.form == Form::Pre {
        (t.x, t.y, t.z)
    } else {
        (acc.x, acc.y, acc.z)
    }
}

/// The length of (a, b), signed like a (negative unless a > 0).
#[inline(always)]
fn signed_len(a: f64, b: f64) -> f64 {
    let l = (a * a + b * b).sqrt();
    if a > 0.0 { l } else { -l }
}

/// Apophysis' symmetric logarithmic compression of a value (0 stays 0).
#[inline(always)]
fn log_scale(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        ((x.abs() + 1.0) * std::f64::consts::E).ln() * sign_nz(x) / std::f64::consts::E
    }
}

/// Apophysis' logarithmic remapping of a multiplier (0 stays 0).
#[inline(always)]
fn log_map(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        (std::f64::consts::E + (x * std::f64::consts::E).ln()) * 0.25 * sign_nz(x)
    }
}

// ---------------------------------------------------------------------------------------------
// crob, crop, cropn.

/// Derived values: the edges of the kept region (top, bottom, left, right), the sorted edges of
/// the rectangle, blur (0 or 1), the direct-blur exponent, the half sizes, the smaller half size,
/// the corner (x0c, y0c) the bands are cut from and the probability of the vertical bands.
fn crob_prepare(v: &mut Prepared) {
    let [top0, bottom0, left0, right0, blur0, ratio, direct0] = v.params();
    let (mut top, mut bottom) = if top0 > bottom0 {
        (bottom0, top0)
    } else {
        (top0, bottom0)
    };
    if top == bottom {
        (top, bottom) = (-1.0, 1.0);
    }
    let (mut left, mut right) = if left0 > right0 {
        (right0, left0)
    } else {
        (left0, right0)
    };
    if left == right {
        (left, right) = (-1.0, 1.0);
    }
    let direct = if direct0 < 0.0 { 0.0 } else { direct0 };
    let blur = if blur0 != 0.0 { 1.0 } else { 0.0 };
    let xint = right.abs() - left;
    let yint = bottom.abs() - top;
    let (xint2, yint2) = (xint / 2.0, yint / 2.0);
    let minint2 = if xint2 > yint2 { yint2 } else { xint2 };
    let x0 = right - xint2;
    let y0 = top + yint2;
    let (x0c, y0c) = if xint2 > yint2 {
        (right - minint2, y0)
    } else if xint2 < yint2 {
        (x0, top + minint2)
    } else {
        (x0, y0)
    };
    let prob = yint / (xint + yint);
    let border = if blur == 0.0 {
        [top, bottom, left, right]
    } else {
        let m = minint2 * ratio;
        [top + m, bottom - m, left + m, right - m]
    };
    v.p.extend_from_slice(&border);
    v.p.extend_from_slice(&[
        top, bottom, left, right, blur, direct, xint2, yint2, minint2, x0c, y0c, prob,
    ]);
}

/// Crops to a rectangle: points inside vanish (0), points outside are thrown back onto a band
/// along the rectangle's inner edge (or to 0 without blur). Unweighted.
fn crob(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, ratio] = v.params();
    let [
        b_top,
        b_bottom,
        b_left,
        b_right,
        top,
        bottom,
        left,
        right,
        blur,
        direct,
        xint2,
        yint2,
        minint2,
        x0c,
        y0c,
        prob,
    ] = v.derived();
    let outside = t.x < b_left || t.x > b_right || t.y < b_top || t.y > b_bottom;
    if !outside || blur == 0.0 {
        return [0.0, 0.0, 0.0];
    }
    let sec = rng.f01();
    let (mut x, mut y);
    // The rejection loops accept well over half of their draws for any sensible rectangle; the
    // cap only guards against degenerate parameters.
    let mut tries = 0;
    if sec < prob {
        loop {
            y = top + rng.f01() * yint2;
            x = right - rng.f01().powf(direct) * ratio * minint2;
            tries += 1;
            if (y - y0c) / zeps(x - x0c) >= -1.0 || tries > 100_000 {
                break;
            }
        }
        if sec < 0.5 * prob {
            x = left + right - x;
        }
        if sec > 0.25 * prob && sec < 0.75 * prob {
            y = bottom + top - y;
        }
    } else {
        loop {
            x = right - rng.f01() * xint2;
            y = top + rng.f01().powf(direct) * ratio * minint2;
            let grad = (y - y0c) / zeps(x - x0c);
            tries += 1;
            if !(grad <= 0.0 && grad > -1.0) || tries > 100_000 {
                break;
            }
        }
        if sec > 0.5 * prob {
            y = bottom + top - y;
        }
        if sec > 0.25 * prob && sec < 0.75 * prob {
            x = left + right - x;
        }
    }
    [x, y, 0.0]
}

fn crop_prepare(v: &mut Prepared) {
    let [left, top, right, bottom, s] = v.params();
    let (x0, x1) = if left < right {
        (left, right)
    } else {
        (right, left)
    };
    let (y0, y1) = if top < bottom {
        (top, bottom)
    } else {
        (bottom, top)
    };
    let w = (x1 - x0) * 0.5 * s;
    let h = (y1 - y0) * 0.5 * s;
    v.p.extend_from_slice(&[x0, y0, x1, y1, w, h]);
}

/// Crops to a rectangle: outside points are zeroed (`crop_zero`) or pulled back inside, scattered
/// over a band of relative width `crop_scatter_area` along the violated edge.
fn crop(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, zero] = v.params();
    let [x0, y0, x1, y1, w, h] = v.derived();
    let (mut x, mut y) = (t.x, t.y);
    let outside = x < x0 || x > x1 || y < y0 || y > y1;
    if outside && zero != 0.0 {
        x = 0.0;
        y = 0.0;
    } else {
        if x < x0 {
            x = x0 + rng.f01() * w;
        } else if x > x1 {
            x = x1 - rng.f01() * w;
        }
        if y < y0 {
            y = y0 + rng.f01() * h;
        } else if y > y1 {
            y = y1 - rng.f01() * h;
        }
    }
    [v.w * x, v.w * y, v.w * t.z]
}

fn cropn_prepare(v: &mut Prepared) {
    let [power] = v.params();
    let alpha = TAU / power.abs().max(2.0);
    v.p.extend_from_slice(&[alpha, alpha / 2.0]);
}

/// Crops to a regular polygon of `cropn_power` sides (outside it for a negative power): points
/// beyond the edge go to the edge (optionally scattered outwards) or to 0.
fn cropn(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, radius, scatter, zero] = v.params();
    let [alpha, half] = v.derived();
    let w = v.w;
    if v.compat {
        let mut a = (t.atan_yx + PI) / alpha;
        a = (a - a.trunc()) * alpha;
        let c = (if a < half { a } else { alpha - a }).cos();
        let edge = if c > 0.0 { radius / c } else { 1.0 };
        if (t.sqrt > edge) == (power > 0.0) {
            if zero == 1.0 {
                [0.0, 0.0, 0.0]
            } else {
                let rd = edge + rng.f01() * 0.5 * scatter;
                [w * rd * t.ux, w * rd * t.uy, 0.0]
            }
        } else {
            [w * t.x, w * t.y, 0.0]
        }
    } else {
        let r2 = t.sumsq;
        let a = (t.atan_yx + PI) % alpha;
        let c = (if a < half { a } else { alpha - a }).cos();
        let edge = if c > 0.0 { radius / zeps(c) } else { 1.0 };
        if (r2 > edge * edge) == (power > 0.0) {
            if zero == 0.0 {
                [0.0, 0.0, 0.0]
            } else {
                let k = (edge + rng.f01() * scatter) * w / zeps(r2.sqrt());
                [k * t.x, k * t.y, 0.0]
            }
        } else {
            [w * t.x, w * t.y, 0.0]
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Quaternion-style 3-D maps.

/// Hyperbolic cosecant of the quaternion x + (y, z): 1/sinh(q).
fn cschq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let av = (t.y * t.y + t.z * t.z).sqrt();
    let ni = v.w / zeps(t.sumsq + t.z * t.z);
    let (s, c) = av.sin_cos();
    let (sh, ch) = (t.x.sinh(), t.x.cosh());
    let d = ni * ch * s / zeps(av);
    [sh * c * ni, -(d * t.y), -(d * t.z)]
}

/// Cosecant of the quaternion x + (y, z): 1/sin(q).
fn cscq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let av = (t.y * t.y + t.z * t.z).sqrt();
    let ni = v.w / zeps(t.sumsq + t.z * t.z);
    let (s, c) = t.x.sin_cos();
    let (sh, ch) = (av.sinh(), av.cosh());
    let d = ni * c * sh / zeps(av);
    [s * ch * ni, -(d * t.y), -(d * t.z)]
}

/// Exponential of the quaternion x + (y, z).
fn estiq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let av = (t.y * t.y + t.z * t.z).sqrt();
    let e = t.x.exp();
    let (s, c) = av.sin_cos();
    let a = e * s / zeps(av);
    [v.w * e * c, v.w * a * t.y, v.w * a * t.z]
}

// ---------------------------------------------------------------------------------------------
// Cubic lattices.

/// The sign pattern of corner `node` (0–7) of a cube: (±x, ±y, ±z).
#[inline(always)]
fn cube_corner(node: u32, h: f64) -> [f64; 3] {
    [
        if node & 4 != 0 { -h } else { h },
        if node & 1 != 0 { -h } else { h },
        if node & 2 != 0 { -h } else { h },
    ]
}

fn cubic_fill(xpand: f64) -> f64 {
    if xpand.abs() <= 1.0 {
        xpand * 0.5
    } else {
        xpand.sqrt() * 0.5
    }
}

fn cubic3d_prepare(v: &mut Prepared) {
    let [xpand, style] = v.params();
    let fill = cubic_fill(xpand);
    let smooth = if v.w.abs() <= 0.5 { v.w * 2.0 } else { 1.0 };
    let smooth_style = if style.abs() <= 1.0 {
        style
    } else if style > 1.0 {
        1.0 + (style - 1.0) * 0.25
    } else {
        (style + 1.0) * 0.25 - 1.0
    };
    v.p.extend_from_slice(&[
        smooth_style,
        smooth * fill,
        smooth * (1.0 - fill),
        v.w * 0.5,
    ]);
}

/// Copies the point to a random corner of a cube lattice, blending between the running sum and
/// the input (the blend is shaped by the point's direction with `cubic3D_style`).
fn cubic3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ss, sfill, s1mfill, half_w] = v.derived();
    let node = rng.u32() & 7;
    let ex = 1.0 - ss * (1.0 - t.x.atan2(t.z).cos());
    let wy = 1.0 - ss * (1.0 - t.y.atan2(t.z).sin());
    let zn = if ss > 1.0 {
        1.0 - ss * (1.0 - ((ex + wy) / 2.0 * ss))
    } else {
        1.0 - ss * (1.0 - ((ex + wy) * 0.5))
    };
    let (px, py, pz) = sum_or_input(v, t, acc);
    let a = (px - (s1mfill * px * ex)) + (t.x * sfill * ex);
    let b = (py - (s1mfill * py * wy)) + (t.y * sfill * wy);
    let c = (pz - (s1mfill * pz * zn)) + (t.z * sfill * zn);
    let k = cube_corner(node, half_w);
    [a + k[0], b + k[1], c + k[2]]
}

fn cubic_lattice_3d_prepare(v: &mut Prepared) {
    let [xpand] = v.params();
    let fill = cubic_fill(xpand);
    v.p.push(fill);
}

/// Copies the point (plus the running sum, scaled) to a random corner of a cube lattice of
/// half-size `weight`; style 2 shapes the copy by the point's direction.
fn cubic_lattice_3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, style] = v.params();
    let [fill] = v.derived();
    let node = rng.u32() & 7;
    let (ex, wy, zn) = if style == 2.0 {
        let ex = t.x.atan2(t.z).cos();
        let wy = t.y.atan2(t.z).sin();
        (ex, wy, (ex + wy) * 0.5)
    } else {
        (1.0, 1.0, 1.0)
    };
    let (px, py, pz) = sum_or_input(v, t, acc);
    let a = (px + t.x) * fill * ex;
    let b = (py + t.y) * fill * wy;
    let c = (pz + t.z) * fill * zn;
    let k = cube_corner(node, v.w);
    [a + k[0], b + k[1], c + k[2]]
}

// ---------------------------------------------------------------------------------------------
// curl3D, curl_sp, curvature, cylinder2, d_spherical.

fn curl3d_prepare(v: &mut Prepared) {
    let [cx, cy, cz] = v.params();
    v.p.extend_from_slice(&[cx * cx + cy * cy + cz * cz, 2.0 * cx, 2.0 * cy, 2.0 * cz]);
}

/// The 3-D Möbius-like curl: x ↦ (x + c·r²) / (1 + 2c·x + |c|² r²), with y's term reversed.
fn curl3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cx, cy, cz] = v.params();
    let [c2, c2x, c2y, c2z] = v.derived();
    let r2 = t.sumsq + t.z * t.z;
    let r = v.w / zeps(r2 * c2 + c2x * t.x - c2y * t.y + c2z * t.z + 1.0);
    [
        r * (t.x + cx * r2),
        r * (t.y - cy * r2),
        r * (t.z + cz * r2),
    ]
}

fn curl_sp_prepare(v: &mut Prepared) {
    let [pow, _, c2, _, _, dc] = v.params();
    let power = zeps(pow);
    v.p[0] = power;
    v.p.extend_from_slice(&[2.0 * c2, 0.1 * dc, 1.0 / power]);
}

/// curl with each coordinate first raised to a signed power and the denominator's terms
/// spread by `sx`/`sy`; also shifts the colour by the denominator (`curl_sp_dc`).
fn curl_sp(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [power, c1, c2, sx, sy] = v.params();
    let [c2x2, dc_adjust, power_inv] = v.derived();
    let x = signed_pow_or_id(t.x, power);
    let y = signed_pow_or_id(t.y, power);
    let z = signed_pow_or_id(t.z, power);
    let d = x * x - y * y;
    let re = signed_len(c1 * x + c2 * d, sx) + 1.0;
    let im = signed_len(c1 * y + c2x2 * x * y, sy);
    let c = zeps(signed_pow_or_id(re * re + im * im, power_inv));
    let r = v.w / c;
    if v.compat {
        acc.color = (acc.color + dc_adjust * c).clamp(0.0, 1.0);
    }
    [(x * re + y * im) * r, (y * re - x * im) * r, (z * v.w) / c]
}

/// Maps the point to (weight / r, angle): unweighted polar angle on y.
fn curvature(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w / zeps(t.sqrt), t.atan_yx, 0.0]
}

/// Squeezes x into (−1, 1) by x/√(x²+1); y unchanged.
fn cylinder2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w * (t.x / zeps((t.x * t.x + 1.0).sqrt())), v.w * t.y, 0.0]
}

/// Randomly either spherical inversion (with probability `d_spherical_weight`) or linear.
fn d_spherical(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [weight] = v.params();
    if rng.f01() < weight {
        let r = v.w / zeps(t.sumsq);
        [t.x * r, t.y * r, 0.0]
    } else {
        [t.x * v.w, t.y * v.w, 0.0]
    }
}

// ---------------------------------------------------------------------------------------------
// Direct-colour variations.

/// 1/s, with s = 0 read as 1e-5 (the dc_* scale guard).
#[inline(always)]
fn dc_inv_scale(s: f64) -> f64 {
    1.0 / (if s == 0.0 { 10e-6 } else { s })
}

fn dc_bubble_prepare(v: &mut Prepared) {
    let [_, _, scale] = v.params();
    let s = dc_inv_scale(scale);
    v.p.push(s);
}

/// bubble (inverse stereographic projection onto a sphere), coloured by the squared distance of
/// the new running sum from a centre.
fn dc_bubble(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cx, cy] = v.params();
    let [bdcs] = v.derived();
    let k = v.w / zeps(t.sumsq / 4.0 + 1.0);
    let o = [k * t.x, k * t.y, v.w * (2.0 / k - 1.0)];
    let (sx, sy, _) = sum_or_input(v, t, acc);
    let (tx, ty) = (o[0] + sx, o[1] + sy);
    acc.color = (bdcs * (sqr(tx + cx) + sqr(ty + cy))).abs() % 1.0;
    o
}

/// Moves the point to one of four quadrant copies (±1, ±1) through the xform's own affine map,
/// colouring the copies with a carpet pattern.
fn dc_carpet(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [origin] = v.params();
    let h = 0.1 * origin;
    let x0: i32 = if rng.bit() { -1 } else { 1 };
    let y0: i32 = if rng.bit() { -1 } else { 1 };
    let x = t.x + x0 as f64;
    let y = t.y + y0 as f64;
    let xor = (x0 ^ y0) as f64;
    let hh = -h + (1.0 - xor) * h;
    let a = &v.aff;
    // Fractorium feeds (A, B, E) and (C, D, F) of its affine letters here.
    let ox = v.w * (a.a * x + a.b * y + a.d);
    let oy = v.w * (a.e * x + a.c * y + a.f);
    acc.color = (acc.color * 0.5 * (1.0 + hh) + xor * (1.0 - hh) * 0.5).abs() % 1.0;
    [ox, oy, 0.0]
}

fn dc_cube_prepare(v: &mut Prepared) {
    let colours: [f64; 6] = v.params();
    for c in colours {
        v.p.push(c.clamp(0.0, 1.0));
    }
}

/// A random point on the surface of the cube [−1, 1]³ (scaled per axis), each face with its
/// own colour.
fn dc_cube(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, scale_x, scale_y, scale_z] = v.params();
    let w = v.w;
    let p1 = 2.0 * rng.f01() - 1.0;
    let q1 = 2.0 * rng.f01() - 1.0;
    let face = rng.below(3) as usize;
    let neg = rng.bit();
    let side = if neg { -1.0 } else { 1.0 };
    let (x, y, z) = match face {
        0 => (w * side, w * p1, w * q1),
        1 => (w * p1, w * side, w * q1),
        _ => (w * p1, w * q1, w * side),
    };
    // The clamped colours of the faces, two per axis (positive side first).
    acc.color = v.table(0)[2 * face + usize::from(!neg)];
    [x * scale_x, y * scale_y, z * scale_z]
}

fn dc_cylinder_prepare(v: &mut Prepared) {
    let [_, angle, scale] = v.params();
    let (s, c) = angle.sin_cos();
    let l = dc_inv_scale(scale);
    v.p.extend_from_slice(&[s, c, l]);
}

/// A blurred cylinder: x wraps around a circle (sin/cos into x and z), y passes scaled, with a
/// random radial blur; coloured by a linear gradient across the new running sum.
fn dc_cylinder(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [offset, _, _, sx, sy, blur] = v.params();
    let [sina, cosa, ldcs] = v.derived();
    let (sr, cr) = (rng.f01() * TAU).sin_cos();
    let r = blur * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
    let o = [
        v.w * (t.x + r * sr).sin() * sx,
        r + t.y * sy,
        v.w * (t.x + r * cr).cos(),
    ];
    let (px, py, _) = sum_or_input(v, t, acc);
    let (tx, ty) = (o[0] + px, o[1] + py);
    acc.color = (0.5 * (ldcs * (cosa * tx + sina * ty + offset) + 1.0)).abs() % 1.0;
    o
}

/// Steps the point one unit along a square spiral grid (which way depends on the nearest grid
/// point's octant), adding 1/4 or 3/4 to the colour.
fn dc_gridout(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let x = lrint(t.x);
    let y = lrint(t.y);
    let w = v.w;
    // Either an x step (colour + 1/4) or a y step (colour + 3/4).
    let (dx, dy) = if y <= 0.0 {
        if x > 0.0 {
            if -y >= x { (1.0, 0.0) } else { (0.0, 1.0) }
        } else if y <= x {
            (1.0, 0.0)
        } else {
            (0.0, -1.0)
        }
    } else if x > 0.0 {
        if y >= x { (-1.0, 0.0) } else { (0.0, 1.0) }
    } else if y > -x {
        (-1.0, 0.0)
    } else {
        (0.0, -1.0)
    };
    let (o, add) = if dy == 0.0 {
        ([w * (t.x + dx), w * t.y, 0.0], 0.25)
    } else {
        ([w * t.x, w * (t.y + dy), 0.0], 0.75)
    };
    acc.color = (acc.color + add) % 1.0;
    o
}

fn dc_linear_prepare(v: &mut Prepared) {
    let [_, angle, scale] = v.params();
    let l = dc_inv_scale(scale);
    let (s, c) = angle.sin_cos();
    v.p.extend_from_slice(&[l, s, c]);
}

/// linear (3-D), coloured by a linear gradient (angle, scale, offset) across the new running sum.
fn dc_linear(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [offset] = v.params();
    let [ldcs, sina, cosa] = v.derived();
    let o = [v.w * t.x, v.w * t.y, v.w * t.z];
    let (px, py, _) = sum_or_input(v, t, acc);
    let (tx, ty) = (o[0] + px, o[1] + py);
    acc.color = (0.5 * (ldcs * (cosa * tx + sina * ty + offset) + 1.0)).abs() % 1.0;
    o
}

fn dc_perlin_prepare(v: &mut Prepared) {
    let [_, _, centre, range] = v.params();
    let mut bottom = centre - range;
    if bottom > 0.75 {
        bottom = 0.75;
    }
    if bottom < -2.0 {
        bottom = -3.0;
    }
    let top = (centre + range).clamp(-0.75, 3.0);
    v.p.extend_from_slice(&[bottom, top]);
}

/// A blur (square, disc or radial) whose samples are kept when a 3-D simplex-noise field,
/// read through one of six mappings of the sample, falls in a band; the noise sets the colour.
fn dc_perlin(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        shape,
        map,
        _select_centre,
        _select_range,
        centre,
        range,
        edge,
        scale,
        octaves,
        amps,
        freqs,
        z,
        bailout,
    ] = v.params();
    let [notch_bottom, notch_top] = v.derived();
    let (shape, map, octaves, bailout) = (shape as i32, map as i32, octaves as i32, bailout as i32);
    let mut tries = 0;
    let (mut vx, mut vy, mut noise);
    loop {
        let mut e = 0.0;
        let r;
        match shape {
            0 => {
                vx = (1.0 + edge) * (rng.f01() - 0.5);
                vy = (1.0 + edge) * (rng.f01() - 0.5);
                r = if vx * vx > vy * vy {
                    (vx * vx).sqrt()
                } else {
                    (vy * vy).sqrt()
                };
            }
            1 => {
                let mut rr = rng.f01() + rng.f01();
                if rr > 1.0 {
                    rr = 2.0 - rr;
                }
                r = rr * (1.0 + edge);
                let (s, c) = (rng.f01() * TAU).sin_cos();
                vx = 0.5 * r * s;
                vy = 0.5 * r * c;
            }
            _ => {
                r = (1.0 + edge) * rng.f01();
                let (s, c) = (rng.f01() * TAU).sin_cos();
                vx = 0.5 * r * s;
                vy = 0.5 * r * c;
            }
        }
        if r > 1.0 - edge {
            e = 0.5 * (r - 1.0 + edge) / edge;
        }
        let d2 = vx * vx + vy * vy;
        let pos = match map {
            0 => [scale * vx, scale * vy, scale * z],
            1 => {
                let k = 1.0 / zeps(d2);
                [scale * vx * k, scale * vy * k, scale * z]
            }
            2 => {
                let k = 1.0 / (d2 + 0.5);
                [scale * vx * k, scale * vy * k, scale * z]
            }
            3 => {
                let k = 1.0 / (d2 + 0.25);
                [scale * vx * k, scale * vy * k, scale * z]
            }
            m => {
                let h = 0.25 - d2;
                let h = if h < 0.0 { (-h).sqrt() } else { h.sqrt() };
                let lift = if m == 4 { h } else { 2.0 * h };
                [scale * vx, scale * vy, scale * (lift + z)]
            }
        };
        noise = fractal_noise(pos, amps, freqs, octaves);
        e = if noise > 0.0 {
            noise * (1.0 + e * e * 20.0) + 2.0 * e
        } else {
            noise * (1.0 + e * e * 20.0) - 2.0 * e
        };
        let rejected = e < notch_bottom || e > notch_top;
        let again = rejected && tries < bailout;
        tries += 1;
        if !again {
            break;
        }
    }
    let col = centre + range * noise;
    acc.color = col - col.floor();
    [v.w * vx, v.w * vy, 0.0]
}

/// Barycentric (u, v) moved onto the triangle's far edge u + v = 1, keeping the larger one
/// (at most 1).
#[inline(always)]
fn onto_far_edge(u: f64, v: f64) -> (f64, f64) {
    if u > v {
        let u = if u > 1.0 { 1.0 } else { u };
        (u, 1.0 - u)
    } else {
        let v = if v > 1.0 { 1.0 } else { v };
        (1.0 - v, v)
    }
}

/// Projects the point onto the triangle spanned by the xform's affine map (barycentric
/// coordinates clamped to the triangle, outside points optionally scattered inwards or zeroed);
/// colour = u + v.
fn dc_triangle(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scatter, zero_edges] = v.params();
    let a = &v.aff;
    let scatter = scatter.clamp(-1.0, 1.0);
    let zero_edges = zero_edges != 0.0;
    // Fractorium's triangle: X = (A, B), Y = −(C, D), O = (E, F) in its affine letters.
    let (xx, xy) = (a.a, a.b);
    let (yx, yy) = (-a.e, -a.c);
    let (ox, oy) = (a.d, a.f);
    let (px, py) = (t.x - ox, t.y - oy);
    let d00 = xx * xx + xy * xy;
    let d01 = xx * yx + xy * yy;
    let d02 = xx * px + xy * py;
    let d11 = yx * yx + yy * yy;
    let d12 = yx * px + yy * py;
    let den = d00 * d11 - d01 * d01;
    let mut u = (d11 * d02 - d01 * d12) / den;
    let mut w = (d00 * d12 - d01 * d02) / den;
    let mut inside = false;
    let mut f = 1.0;
    if u + w > 1.0 {
        f = -1.0;
        (u, w) = onto_far_edge(u, w);
    } else if u < 0.0 || w < 0.0 {
        u = u.clamp(0.0, 1.0);
        w = w.clamp(0.0, 1.0);
    } else {
        inside = true;
    }
    if !inside {
        if zero_edges {
            u = 0.0;
            w = 0.0;
        } else {
            u = (u + rng.f01() * scatter * f).clamp(-1.0, 1.0);
            w = (w + rng.f01() * scatter * f).clamp(-1.0, 1.0);
            if u + w > 1.0 && scatter > 0.0 {
                (u, w) = onto_far_edge(u, w);
            }
        }
    }
    acc.color = (u + w).abs() % 1.0;
    [
        v.w * (ox + u * xx + w * yx),
        v.w * (oy + u * xy + w * yy),
        v.w * t.z,
    ]
}

fn dc_ztransl_prepare(v: &mut Prepared) {
    let [a, b] = v.params();
    let lo = if a < b { a } else { b };
    let hi = if a > b { a } else { b };
    v.p.extend_from_slice(&[lo, zeps(hi - lo)]);
}

/// linear in x and y; z set from (or scaled by) the colour coordinate mapped from [x0, x1].
fn dc_ztransl(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [_, _, factor, overwrite, clamp] = v.params();
    let [lo, span] = v.derived();
    let mut zf = factor * (acc.color - lo) / span;
    if clamp != 0.0 {
        zf = zf.clamp(0.0, 1.0);
    }
    let z = if overwrite == 0.0 {
        v.w * t.z * zf
    } else {
        v.w * zf
    };
    [v.w * t.x, v.w * t.y, z]
}

// ---------------------------------------------------------------------------------------------
// deltaa, depth and the depth blurs.

/// Half the angle and the ratio of distances as seen from the points (−1, 0) and (1, 0):
/// a bipolar-coordinate map.
fn deltaa(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let y2 = t.y * t.y;
    let r = v.w * ((y2 + sqr(t.x + 1.0)).sqrt() / (y2 + sqr(t.x - 1.0)).sqrt());
    let a = (t.y.atan2(t.x - 1.0) - t.y.atan2(t.x + 1.0)) / 2.0;
    let (s, c) = a.sin_cos();
    [r * c, r * s, 0.0]
}

/// Adds to the point a copy scaled by |z|^power: a perspective-like depth push. (Fractorium
/// reads the affine-transformed point for the first term; it equals the input unless a `pre_`
/// variation moved it.)
fn depth(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let mut k = t.z.abs();
    if k != 0.0 && power != 1.0 {
        k = (k.ln() * power).exp();
    }
    [
        v.w * (t.x + t.x * k),
        v.w * (t.y + t.y * k),
        v.w * (t.z + t.z * k),
    ]
}

/// Star-blur geometry shared by depth_blur and depth_blur2: (length, alpha).
fn star_shape(power: f64, range: f64) -> (f64, f64) {
    let a0 = PI / zeps(power);
    let length = (1.0 + range * range - 2.0 * range * a0.cos()).sqrt();
    let alpha = (a0.sin() * range / zeps(length)).asin();
    (length, alpha)
}

fn depth_blur_prepare(v: &mut Prepared) {
    let [power, range, blur] = v.params();
    let (length, alpha) = star_shape(power, range);
    let (s, c) = alpha.sin_cos();
    v.p.extend_from_slice(&[length, blur / 10.0, power * 2.0, TAU / zeps(power), s, c]);
}

/// A random offset inside a star with `power2`/2 points (unit size): a random arm, a random
/// position along its edge and a random fraction of that radius. `plus_on_odd` selects which
/// side of each arm leans which way.
#[inline(always)]
fn star_offset(
    rng: &mut FastRng,
    power2: f64,
    length: f64,
    sin_a: f64,
    cos_a: f64,
    step: f64,
    plus_on_odd: bool,
) -> (f64, f64) {
    let f0 = rng.f01() * power2;
    let whole = f0.trunc();
    let f = f0 - whole;
    let x = f * length;
    let mut z = (1.0 + x * x - 2.0 * x * cos_a).sqrt();
    let arm = whole as i64;
    let lean = (sin_a * x / zeps(z)).asin();
    let odd = arm & 1 != 0;
    let ang = if odd == plus_on_odd {
        step * (arm / 2) as f64 + lean
    } else {
        step * (arm / 2) as f64 - lean
    };
    z *= rng.f01().sqrt();
    let (s, c) = (ang - FRAC_PI_2).sin_cos();
    (z * c, z * s)
}

/// The last step of the depth blurs: a point at distance `rad` beyond `radius` is moved by a
/// kernel offset drawn by `offset`, scaled by `amount` of the distance past the radius (points
/// within the radius stay, and draw nothing); the result is weighted.
#[inline(always)]
fn depth_push(
    w: f64,
    t: &VarIn,
    rad: f64,
    radius: f64,
    rng: &mut FastRng,
    offset: impl FnOnce(&mut FastRng) -> (f64, f64),
    amount: impl FnOnce(f64) -> f64,
) -> V3 {
    let (mut bx, mut by) = (0.0, 0.0);
    if rad > radius {
        let (ox, oy) = offset(rng);
        let aux = amount(rad - radius);
        bx = aux * ox;
        by = aux * oy;
    }
    [w * (t.x + bx), w * (t.y + by), 0.0]
}

/// Blurs points beyond `radius` with a star-shaped kernel whose size grows linearly with the
/// distance past the radius.
fn depth_blur(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, radius] = v.params();
    let [length, blur10, power2, step, sa, ca] = v.derived();
    let rad = t.sqrt;
    depth_push(
        v.w,
        t,
        rad,
        radius,
        rng,
        |r| star_offset(r, power2, length, sa, ca, step, false),
        |d| blur10 * d,
    )
}

fn depth_blur2_prepare(v: &mut Prepared) {
    let [power, range, blur, _, _, _, mx, my] = v.params();
    let (length, alpha) = star_shape(power, range);
    let (s, c) = alpha.sin_cos();
    v.p.extend_from_slice(&[
        length,
        blur / 10.0,
        power * 2.0,
        TAU / zeps(power),
        s,
        c,
        1.0 / zeps(mx),
        1.0 / zeps(my),
    ]);
}

/// depth_blur around (x0, y0) with an elliptic distance (mulx, muly) and a kernel growing as a
/// power (`exp`) of the distance past the radius.
fn depth_blur2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, radius, x0, y0, _, _, ex] = v.params();
    let [length, blur10, power2, step, sa, ca, imx, imy] = v.derived();
    let rad = (sqr((t.x - x0) * imx) + sqr((t.y - y0) * imy)).sqrt();
    depth_push(
        v.w,
        t,
        rad,
        radius,
        rng,
        |r| star_offset(r, power2, length, sa, ca, step, true),
        |d| blur10 * (d.ln() * ex).exp(),
    )
}

/// A standard normal radius and a uniform angle: (r·cos, r·sin).
#[inline(always)]
fn gaussian_offset(rng: &mut FastRng) -> (f64, f64) {
    let r = (-2.0 * rng.f01().ln()).sqrt();
    let (s, c) = (rng.f01() * TAU).sin_cos();
    (r * c, r * s)
}

/// Gaussian blur of the points beyond `radius`, its width growing with the distance past it.
fn depth_gaussian(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [blur, radius] = v.params();
    let rad = t.sqrt;
    depth_push(v.w, t, rad, radius, rng, gaussian_offset, |d| {
        blur / 10.0 * d
    })
}

fn depth_gaussian2_prepare(v: &mut Prepared) {
    let [blur, _, _, _, mx, my] = v.params();
    v.p.extend_from_slice(&[blur / 10.0, 1.0 / zeps(mx * mx), 1.0 / zeps(my * my)]);
}

/// depth_gaussian around (x0, y0) with an anisotropic distance and a width growing as a power
/// (`exp`) of the distance past the radius.
fn depth_gaussian2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, radius, x0, y0, _, _, ex] = v.params();
    let [blur10, kx, ky] = v.derived();
    let rad = (sqr((t.x - x0) / kx) + sqr((t.y - y0) / ky)).sqrt();
    depth_push(v.w, t, rad, radius, rng, gaussian_offset, |d| {
        blur10 * (d.ln() * ex).exp()
    })
}

/// A random direction with the radius of a regular polygon's boundary in that direction
/// (1/cos of the angle to the nearest side normal): (r·cos, r·sin).
#[inline(always)]
fn polygon_offset(rng: &mut FastRng, side: f64, half: f64) -> (f64, f64) {
    let ang = rng.f01() * TAU;
    let mut phi = ang - side * (ang / zeps(side)).floor();
    if phi > half {
        phi -= side;
    }
    let amp = 1.0 / zeps(phi.cos());
    let (s, c) = ang.sin_cos();
    (amp * c, amp * s)
}

fn depth_ngon_prepare(v: &mut Prepared) {
    let [power, blur] = v.params();
    let side = TAU / zeps(power);
    v.p.extend_from_slice(&[side, side / 2.0, blur / 10.0]);
}

/// Blurs the points beyond `radius` onto the outline of a regular polygon whose size grows with
/// the distance past the radius.
fn depth_ngon(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, radius] = v.params();
    let [side, half, blur10] = v.derived();
    let rad = t.sqrt;
    depth_push(
        v.w,
        t,
        rad,
        radius,
        rng,
        |r| polygon_offset(r, side, half),
        |d| blur10 * d,
    )
}

fn depth_ngon2_prepare(v: &mut Prepared) {
    let [power, blur, _, _, _, mx, my] = v.params();
    let side = TAU / zeps(power);
    v.p.extend_from_slice(&[
        side,
        side / 2.0,
        blur / 10.0,
        1.0 / zeps(mx * mx),
        1.0 / zeps(my * my),
    ]);
}

/// depth_ngon around (x0, y0), anisotropic, with a size growing as a power (`exp`) of the
/// distance past the radius (in flam3-compatibility mode: plain depth_ngon).
fn depth_ngon2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, radius, x0, y0, _, _, ex] = v.params();
    let [side, half, blur10, kx, ky] = v.derived();
    let polygon = |r: &mut FastRng| polygon_offset(r, side, half);
    if v.compat {
        depth_push(v.w, t, t.sqrt, radius, rng, polygon, |d| blur10 * d)
    } else {
        let rad = (sqr(t.x - x0) * kx + sqr(t.y - y0) * ky).sqrt();
        depth_push(v.w, t, rad, radius, rng, polygon, |d| {
            blur10 * (d.ln() * ex).exp()
        })
    }
}

/// A random direction with a radius distributed like acos(2u−1)/π (sharpened by `power`).
#[inline(always)]
fn sine_offset(rng: &mut FastRng, power: f64) -> (f64, f64) {
    let ang = rng.f01() * TAU;
    let r = if power == 1.0 {
        (rng.f01() * 2.0 - 1.0).acos() / PI
    } else {
        (((1.0 - rng.f01()).ln() * power).exp() * 2.0 - 1.0).acos() / PI
    };
    let (s, c) = ang.sin_cos();
    (r * c, r * s)
}

/// Blurs the points beyond `radius` with a disc kernel of sine-shaped radial profile, its size
/// growing with the distance past the radius.
fn depth_sine(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, blur, radius] = v.params();
    let rad = t.sqrt;
    depth_push(
        v.w,
        t,
        rad,
        radius,
        rng,
        |r| sine_offset(r, power),
        |d| blur / 10.0 * d,
    )
}

fn depth_sine2_prepare(v: &mut Prepared) {
    let [power, blur, _, _, _, mx, my] = v.params();
    v.p[0] = power.max(0.0);
    v.p.extend_from_slice(&[blur / 10.0, 1.0 / zeps(mx * mx), 1.0 / zeps(my * my)]);
}

/// depth_sine around (x0, y0), anisotropic, with a size growing as a power (`exp`) of the
/// distance past the radius.
fn depth_sine2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, _, radius, x0, y0, mx, my, ex] = v.params();
    let [blur10, kx, ky] = v.derived();
    let rad = if v.compat {
        (sqr((t.x - x0) / zeps(mx)) + sqr((t.y - y0) / zeps(my))).sqrt()
    } else {
        (sqr(t.x - x0) * kx + sqr(t.y - y0) * ky).sqrt()
    };
    depth_push(
        v.w,
        t,
        rad,
        radius,
        rng,
        |r| sine_offset(r, power),
        |d| blur10 * (d.ln() * ex).exp(),
    )
}

// ---------------------------------------------------------------------------------------------
// disc3d, dragonfire, dust, eclipse.

/// disc with an adjustable "π" and a z from the radius and cos z.
fn disc3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [pi] = v.params();
    let r = t.sqrt;
    let (sr, cr) = (r * pi).sin_cos();
    let k = v.w * t.atan_xy / zeps(pi);
    [k * sr, k * cr, k * (r * t.z.cos())]
}

fn dragonfire_prepare(v: &mut Prepared) {
    let [_, _, _, _, mode, pos, _, adj] = v.params();
    let val = if mode < 2.0 {
        pos
    } else {
        let a = pos * PI;
        let trig = if mode < 3.0 {
            a.cos()
        } else if mode < 4.0 {
            a.tan()
        } else if mode < 5.0 {
            a.sinh()
        } else {
            a.asinh()
        };
        (1.0 - trig) * adj
    };
    v.p.extend_from_slice(&[val, 1.0 - val]);
}

/// With u = c1·eˣ and v = c2/u: (u − v, sin y)/(u + v − cos y), a coth-like map, with optional
/// "fuzzy" perturbations driven by the logarithm of the result, blended in by a chosen curve.
fn dragonfire(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [c1, c2, mode, radius, interp, _, scalar] = v.params();
    let [val, one_m_val] = v.derived();
    let ex = t.x.exp() * c1;
    let enx = c2 / zeps(ex);
    let (sy, cy) = t.y.sin_cos();
    let r = v.w / zeps(ex + enx - cy);
    let fx = (ex - enx) * r;
    let fy = sy * r;
    if mode < 1.0 {
        return [fx, fy, 0.0];
    }
    let zx = (scalar / zeps(fx.abs().ln())).cos();
    let zy = (scalar / zeps(fy.abs().ln())).cos();
    let dir = |a: f64| if a < 0.0 { -radius } else { radius };
    let (nx, ny) = if mode < 2.0 {
        (fx + zx, fy + zy)
    } else if mode < 3.0 {
        (fx * zx.sin(), fy * zy.sin())
    } else if mode < 4.0 {
        (fx * zx.sin().exp(), fy * zy.sin().exp())
    } else if mode < 5.0 {
        (fx + dir(zx), fy + dir(zy))
    } else if mode < 6.0 {
        (fx + dir(zx).exp(), fy + dir(zy).exp())
    } else {
        (fx + dir(zx).sin().exp(), fy + dir(zy).cos().exp())
    };
    if interp < 1.0 {
        [nx, ny, 0.0]
    } else {
        [fx * one_m_val + nx * val, fy * one_m_val + ny * val, 0.0]
    }
}

/// Scatters each unit cell of the plane to a pseudo-random point of a polar "dust" pattern
/// (the cell's index modulo `density` picks the angle and radius).
fn dust(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [dens, dist, power] = v.params();
    let dens = zeps(dens);
    let cx = (t.x.abs().floor() % dens) / dens;
    let cy = (t.y.abs().floor() % dens) / dens;
    let hx = sine_hash(cx, cy, 1.0);
    let hy = sine_hash(cy, cx, 2.0);
    let a = (cx + hx * dist) * TAU;
    let r = ((cy + hy * dist).ln() * power).exp();
    let (s, c) = a.sin_cos();
    [v.w * c * r, v.w * s * r, 0.0]
}

/// Inside the disc of radius `weight`, shifts each horizontal chord by `shift`·weight, mirroring
/// points pushed past the chord's end; outside, linear.
fn eclipse(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [shift] = v.params();
    let w = v.w;
    if t.y.abs() <= w {
        let c2 = (w * w - t.y * t.y).sqrt();
        let ox = if t.x.abs() <= c2 {
            let x = t.x + shift * w;
            if x.abs() >= c2 { -(w * t.x) } else { w * x }
        } else {
            w * t.x
        };
        [ox, w * t.y, 0.0]
    } else {
        [w * t.x, w * t.y, 0.0]
    }
}

// ---------------------------------------------------------------------------------------------
// Elliptic-coordinate family (foci at ±1).

fn e_collide_prepare(v: &mut Prepared) {
    let [a, num] = v.params();
    let ca = PI * a;
    v.p.extend_from_slice(&[num * FRAC_1_PI, PI / num, ca / num]);
}

/// Elliptic coordinates: the angle ν is cut into `num` sectors and shifted within each,
/// alternately forwards and backwards, like balls colliding.
fn e_collide(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cn_pi, pi_cn, ca_cn] = v.derived();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
    let sector = (nu * cn_pi) as i32;
    nu = if sector & 1 == 0 {
        sector as f64 * pi_cn + (nu + ca_cn) % pi_cn
    } else {
        sector as f64 * pi_cn + (nu - ca_cn) % pi_cn
    };
    if t.y <= 0.0 {
        nu = -nu;
    }
    let (s, c) = nu.sin_cos();
    [
        v.w * xmax * c,
        v.w * (xmax - 1.0).sqrt() * (xmax + 1.0).sqrt() * s,
        0.0,
    ]
}

/// An elliptic-coordinate analogue of julian: μ divided by the power, ν divided and rotated to a
/// random one of `power` branches (inverted first for negative powers).
fn e_julia(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let mut r2 = t.sumsq;
    let x = if power >= 0.0 {
        t.x
    } else {
        r2 = 1.0 / zeps(r2);
        t.x * r2
    };
    let (xmax, mut nu) = elliptic(x, r2, true);
    let mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = nu / power + TAU / power * (rng.f01() * power).floor();
    from_elliptic(v.w, mu / power, nu)
}

/// Elliptic coordinates with μ wrapped into [−radius, radius) after a shift of `distance`·radius.
fn e_mod(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [radius, distance] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
    let mut mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    if mu < radius && -mu < radius {
        mu = if nu > 0.0 {
            (mu + radius + distance * radius) % (2.0 * radius) - radius
        } else {
            (mu - radius - distance * radius) % (2.0 * radius) + radius
        };
    }
    from_elliptic(v.w, mu, nu)
}

/// Elliptic coordinates: μ moved by `move` (towards or away from the focal segment depending
/// on the side), reflected through the segment when it crosses it, then ν rotated.
fn e_motion(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [mv, rot] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
    let mut mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    if nu < 0.0 {
        mu += mv;
    } else {
        mu -= mv;
    }
    if mu <= 0.0 {
        mu = -mu;
        nu = -nu;
    }
    from_elliptic(v.w, mu, nu + rot)
}

/// Elliptic coordinates: μ scaled by `dist` and pushed by `push`, ν rotated.
fn e_push(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [push, dist, rot] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
    let mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    from_elliptic(v.w, mu * dist + push, nu + rot)
}

/// Elliptic coordinates: rotates ν (wrapped to [−π, π)), keeping the confocal ellipse.
fn e_rotate(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [rot] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = (nu + rot + PI) % TAU - PI;
    let (s, c) = nu.sin_cos();
    [v.w * xmax * c, v.w * (xmax * xmax - 1.0).sqrt() * s, 0.0]
}

/// Elliptic coordinates: μ and ν scaled by `scale` (ν about the angle `angle`, wrapped).
fn e_scale(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scale, angle] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
    let mu = acosh(xmax) * scale;
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = ((scale * (nu + PI + angle)) % (TAU * scale) - angle - scale * PI) % TAU;
    if nu > PI {
        nu -= TAU;
    }
    if nu < -PI {
        nu += TAU;
    }
    from_elliptic(v.w, mu, nu)
}

/// Elliptic coordinates: ν twisted by `out`·μ + `in`/μ (a swirl about the focal segment).
fn e_swirl(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [win, wout] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, false);
    let mu = acosh(if xmax < -1.0 { -1.0 } else { xmax });
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = nu + mu * wout + win / mu;
    from_elliptic(v.w, mu, nu)
}

// ---------------------------------------------------------------------------------------------
// ennepers, epispiral, erf, excinis, exp2, expo, extrude.

/// The plane projection of Enneper's minimal surface (weight applies to the cubic part only).
fn ennepers(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (x2, y2) = (t.x * t.x, t.y * t.y);
    [
        v.w * (t.x - ((x2 * t.x) / 3.0)) + t.x * y2,
        v.w * (t.y - ((y2 * t.y) / 3.0)) + t.y * x2,
        0.0,
    ]
}

fn epispiral_prepare(v: &mut Prepared) {
    let [_, thick, holes] = v.params();
    v.p.extend_from_slice(&[thick * v.w, holes * v.w]);
}

/// Maps the point's direction θ onto the epispiral r = 1/cos(nθ), shifted by `holes` and
/// randomly thickened.
fn epispiral(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n] = v.params();
    let [thick_w, holes_w] = v.derived();
    let theta = t.atan_yx;
    let num = if thick_w == 0.0 {
        v.w
    } else {
        thick_w * rng.f01()
    };
    let r = num / (n * theta).cos() - holes_w;
    if r.abs() != 0.0 {
        let (s, c) = theta.sin_cos();
        [r * c, r * s, 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// The error function applied to each coordinate.
fn erf_var(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w * erf(t.x), v.w * erf(t.y), 0.0]
}

/// Squares the point as a complex number and scales by a function of 1/r (kept away from the
/// pole by `eps`): identity, cos, exp, log or reciprocal by `radiusFunc`.
fn excinis(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [ls, func, eps] = v.params();
    let rp = t.sqrt * ls;
    let sign = if rp >= 0.0 { 1.0 } else { -1.0 };
    let reps = if rp.abs() > eps { 0.0 } else { sign * eps };
    let r = v.w / zeps(rp + reps);
    let f = if func < 1.0 {
        r
    } else if func < 2.0 {
        r.cos()
    } else if func < 3.0 {
        r.exp()
    } else if func < 4.0 {
        (r.abs() + reps.abs()).ln()
    } else {
        1.0 / zeps(r + reps)
    };
    [(t.x - t.y) * (t.x + t.y) * f, 2.0 * t.x * t.y * f, 0.0]
}

/// The complex exponential of π·z.
fn exp2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let k = v.w * (t.x * PI).exp();
    let (s, c) = (t.y * PI).sin_cos();
    [k * c, k * s, 0.0]
}

fn expo_prepare(v: &mut Prepared) {
    let [re, im] = v.params();
    let k = 0.5 * zeps(re * re + im * im).ln();
    let th = im.atan2(re);
    v.p.extend_from_slice(&[k, th]);
}

/// The complex power c^z for a fixed complex base c = real + i·imaginary.
fn expo(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [k, th] = v.derived();
    let m = (t.x * k - t.y * th).exp();
    let (s, c) = (t.x * th + t.y * k).sin_cos();
    [v.w * m * c, v.w * m * s, 0.0]
}

/// Gives the point a random depth: z = max(weight, 0) with probability `root_face`, else uniform
/// in [0, weight). As a regular variation it contributes nothing to x, y and overwrites the
/// running z; as pre_/post_ it keeps x, y.
fn extrude(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [root_face] = v.params();
    let z = if rng.f01() < root_face {
        v.w.max(0.0)
    } else {
        v.w * rng.f01()
    };
    if v.form == Form::Regular {
        acc.z = z;
        [0.0, 0.0, 0.0]
    } else {
        [t.x, t.y, z]
    }
}

// ---------------------------------------------------------------------------------------------
// Falloff blurs and farblur.

/// A uniform value in [−0.5, 0.5).
#[inline(always)]
fn centred(rng: &mut FastRng) -> f64 {
    rng.f01() - 0.5
}

/// A 3-D blur whose strength grows with the distance from a centre beyond `mindist`: uniform
/// box jitter, radial/angular jitter, or snapping towards a grid whose cell grows with distance.
fn falloff(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        scatter,
        mindist,
        mx,
        my,
        mz,
        x0,
        y0,
        z0,
        invert,
        kind,
        boxpow,
    ] = v.params();
    let ax = centred(rng);
    let ay = centred(rng);
    let az = centred(rng);
    let w = v.w;
    let r = (sqr(t.x - x0) + sqr(t.y - y0) + sqr(t.z - z0)).sqrt();
    let rs = falloff_amount(r, invert, mindist, 0.04 * scatter);
    match kind as i32 {
        0 => [
            w * (t.x + mx * ax * rs),
            w * (t.y + my * ay * rs),
            w * (t.z + mz * az * rs),
        ],
        1 => {
            let elevation = if r == 0.0 { 0.0 } else { t.z / r };
            radial_falloff(t, w, r, elevation, rs, [ax, ay, az], [mx, my, mz])
        }
        _ => {
            let scale = rs.clamp(0.0, 0.9) + 0.1;
            let inv = 1.0 / scale;
            let snap = |c: f64, a: f64, m: f64| {
                let target = (c * inv).floor() + scale * a;
                w * (c + (target - c) * (m * rs)) + m * a.powf(boxpow) * rs * inv
            };
            [snap(t.x, ax, mx), snap(t.y, ay, my), snap(t.z, az, mz)]
        }
    }
}

/// Distance-dependent blur after falloff, in three styles (box, radial, Gaussian-like), that
/// can also jitter the colour (`mul_c`).
fn falloff2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scatter, mindist, mx, my, mz, mc, x0, y0, z0, invert, kind] = v.params();
    let rx = centred(rng);
    let ry = centred(rng);
    let rz = centred(rng);
    let rc = centred(rng);
    let w = v.w;
    let da = (sqr(t.x - x0) + sqr(t.y - y0) + sqr(t.z - z0)).sqrt();
    let dist = falloff_amount(da, invert, mindist, 0.04 * scatter);
    let o = match kind as i32 {
        0 => [
            (t.x + mx * rx * dist) * w,
            (t.y + my * ry * dist) * w,
            (t.z + mz * rz * dist) * w,
        ],
        1 => {
            if t.x == 0.0 && t.y == 0.0 && t.z == 0.0 {
                return [t.x * w, t.y * w, t.z * w];
            }
            let rin = zeps((t.sumsq + t.z * t.z).sqrt());
            radial_falloff(t, w, rin, t.z / rin, dist, [rx, ry, rz], [mx, my, mz])
        }
        _ => gaussian_falloff(t, w, dist, [rx, ry, rz], [mx, my, mz]),
    };
    acc.color = falloff_color(acc.color, mc * rc * dist);
    o
}

/// How strongly the falloff blurs act at distance `r` from their centre (1 − r with
/// `invert`): the part beyond `mindist`, times `k`, never negative.
#[inline(always)]
fn falloff_amount(r: f64, invert: f64, mindist: f64, k: f64) -> f64 {
    let base = if invert != 0.0 {
        (1.0 - r).max(0.0)
    } else {
        r.max(0.0)
    };
    ((base - mindist) * k).max(0.0)
}

/// The colour of the falloff blurs: shifted by `shift`, wrapped into [0, 1) by |c mod 1|.
#[inline(always)]
fn falloff_color(color: f64, shift: f64) -> f64 {
    ((color + shift) % 1.0).abs()
}

/// The "radial" style of the falloff blurs: the point's spherical coordinates (radius `rin`,
/// azimuth, elevation asin(`elevation`)) each jittered by `dist` times a random number `r` and
/// a multiplier `m`.
#[inline(always)]
fn radial_falloff(t: &VarIn, w: f64, rin: f64, elevation: f64, dist: f64, r: V3, m: V3) -> V3 {
    let rad = rin + m[0] * r[0] * dist;
    let phi = t.atan_yx + m[1] * r[1] * dist;
    let sigma = elevation.asin() + m[2] * r[2] * dist;
    let (ss, sc) = sigma.sin_cos();
    let (ps, pc) = phi.sin_cos();
    let (ss, sc) = (ss * w, sc * w);
    [rad * sc * pc, rad * sc * ps, rad * ss]
}

/// The "Gaussian" style of falloff2/falloff3: offsets along a random spherical direction.
#[inline(always)]
fn gaussian_falloff(t: &VarIn, w: f64, dist: f64, r: [f64; 3], m: [f64; 3]) -> V3 {
    let sigma = dist * r[1] * TAU;
    let phi = dist * r[2] * PI;
    let rad = dist * r[0];
    let (ss, sc) = sigma.sin_cos();
    let (ps, pc) = phi.sin_cos();
    [
        (t.x + m[0] * rad * sc * pc) * w,
        (t.y + m[1] * rad * sc * ps) * w,
        (t.z + m[2] * rad * ss) * w,
    ]
}

/// falloff2 with a round or square distance and a logarithmic style (blend `alpha`).
fn falloff3(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        kind,
        shape,
        strength,
        mindist,
        invert,
        mx,
        my,
        mz,
        mc,
        cx,
        cy,
        cz,
        alpha,
    ] = v.params();
    let rx = centred(rng);
    let ry = centred(rng);
    let rz = centred(rng);
    let rc = centred(rng);
    let w = v.w;
    let radius = if shape == 0.0 {
        (sqr(t.x - cx) + sqr(t.y - cy) + sqr(t.z - cz)).sqrt()
    } else {
        (t.x - cx).abs().max((t.y - cy).abs().max((t.z - cz).abs()))
    };
    let rmax = 0.04 * strength;
    let dist = falloff_amount(radius, invert, mindist, rmax);
    match kind as i32 {
        0 => {
            let o = gaussian_falloff(t, w, dist, [rx, ry, rz], [mx, my, mz]);
            acc.color = falloff_color(acc.color, mc * rc * dist);
            o
        }
        1 => {
            if t.x == 0.0 && t.y == 0.0 && t.z == 0.0 {
                return [t.x * w, t.y * w, t.z * w];
            }
            let rin = (t.sumsq + t.z * t.z).sqrt();
            acc.color = falloff_color(acc.color, mc * rc * dist);
            radial_falloff(t, w, rin, t.z / rin, dist, [rx, ry, rz], [mx, my, mz])
        }
        _ => {
            let coeff = if rmax <= f64::EPSILON {
                dist
            } else {
                dist + alpha * (log_map(dist) - dist)
            };
            let o = [
                (t.x + log_map(mx) * log_scale(rx) * coeff) * w,
                (t.y + log_map(my) * log_scale(ry) * coeff) * w,
                (t.z + log_map(mz) * log_scale(rz) * coeff) * w,
            ];
            acc.color = falloff_color(acc.color, log_map(mc) * log_scale(rc) * coeff);
            o
        }
    }
}

/// A 3-D blur along a random direction whose size grows with the squared distance from an
/// origin (per-axis scales).
fn farblur(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sx, sy, sz, x0, y0, z0] = v.params();
    let d2 = sqr(t.x - x0) + sqr(t.y - y0) + sqr(t.z - z0);
    let r = v.w * d2 * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
    let (su, cu) = (rng.f01() * TAU).sin_cos();
    let (sv, cv) = (rng.f01() * TAU).sin_cos();
    [sx * r * sv * cu, sy * r * sv * su, sz * r * cv]
}
