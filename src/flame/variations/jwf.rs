//! Variations (slice jwf of the registry): JWildfire variations that real flame files use, plus
//! `julian2dc` (Georg Kiehne's Apophysis direct-colour plugin).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire conventions kept: `atan_xy` is its `getPrecalcAtan` (atan2(x, y)),
//! weights multiply the output linearly, integer parameters are rounded, and random numbers are
//! drawn with `rng.f01()` in the order JWildfire draws them (so that the tests can replay
//! JWildfire's own code on the same stream). Variations that build a structure once (snow
//! crystal, sudoku layers, knot mesh) keep it in `v.p` after their parameters.

use std::f64::consts::{FRAC_1_PI, FRAC_PI_4, PI, TAU};

use super::util::{Mwc, atan2_approx, signum_java, sqr, wang_hash};
use super::{
    Acc, Prepared, V3, VarDef, VarIn, flag, need, p, p_int, p_int_nonzero, p_range, params_of,
};
use crate::flame::rng::FastRng;

/// Parameters of `complex` in JWildfire's order: for each function its weight ("pow") then the
/// factors applied to x and y inside the trigonometric parts.
const COMPLEX_PARAMS: &[super::Param] = &[
    p("complex_cospow", 1.0),
    p("complex_cosx1", 1.0),
    p("complex_cosx2", 1.0),
    p("complex_cosy1", 1.0),
    p("complex_cosy2", 1.0),
    p("complex_coshpow", 0.0),
    p("complex_coshx1", 1.0),
    p("complex_coshx2", 1.0),
    p("complex_coshy1", 1.0),
    p("complex_coshy2", 1.0),
    p("complex_cotpow", 0.0),
    p("complex_cotx1", 2.0),
    p("complex_cotx2", 2.0),
    p("complex_coty1", 2.0),
    p("complex_coty2", 2.0),
    p("complex_cothpow", 0.0),
    p("complex_cothx1", 2.0),
    p("complex_cothx2", 2.0),
    p("complex_cothy1", 2.0),
    p("complex_cothy2", 2.0),
    p("complex_cscpow", 0.0),
    p("complex_cscx1", 1.0),
    p("complex_cscx2", 1.0),
    p("complex_cscy1", 1.0),
    p("complex_cscy2", 1.0),
    p("complex_cschpow", 0.0),
    p("complex_cschx1", 1.0),
    p("complex_cschx2", 1.0),
    p("complex_cschy1", 1.0),
    p("complex_cschy2", 1.0),
    p("complex_exppow", 0.0),
    p("complex_expx1", 1.0),
    p("complex_expy1", 1.0),
    p("complex_expy2", 1.0),
    p("complex_secpow", 0.0),
    p("complex_secx1", 1.0),
    p("complex_secx2", 1.0),
    p("complex_secy1", 1.0),
    p("complex_secy2", 1.0),
    p("complex_sechpow", 0.0),
    p("complex_sechx1", 1.0),
    p("complex_sechx2", 1.0),
    p("complex_sechy1", 1.0),
    p("complex_sechy2", 1.0),
    p("complex_sinpow", 0.0),
    p("complex_sinx1", 1.0),
    p("complex_sinx2", 1.0),
    p("complex_siny1", 1.0),
    p("complex_siny2", 1.0),
    p("complex_sinhpow", 0.0),
    p("complex_sinhx1", 1.0),
    p("complex_sinhx2", 1.0),
    p("complex_sinhy1", 1.0),
    p("complex_sinhy2", 1.0),
    p("complex_tanpow", 0.0),
    p("complex_tanx1", 2.0),
    p("complex_tanx2", 2.0),
    p("complex_tany1", 2.0),
    p("complex_tany2", 2.0),
    p("complex_tanhpow", 0.0),
    p("complex_tanhx1", 2.0),
    p("complex_tanhx2", 2.0),
    p("complex_tanhy1", 2.0),
    p("complex_tanhy2", 2.0),
];

const INF: f64 = f64::INFINITY;
const NINF: f64 = f64::NEG_INFINITY;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("rose_wf", rose_wf)
        .params(&[
            p("rose_wf_amp", 0.5),
            p_int("rose_wf_waves", 4.0, NINF, INF),
            p_int("rose_wf_filled", 0.0, NINF, INF),
        ])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("chrysanthemum", chrysanthemum).flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("complex", complex)
        .params(COMPLEX_PARAMS)
        .flags(flag::JWILDFIRE),
    VarDef::new("exblur", exblur)
        .params(&[
            p("exblur_dist", 0.5),
            p("exblur_r", 0.0),
            p("exblur_x_origin", 0.0),
            p("exblur_y_origin", 0.0),
            p("exblur_z_origin", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::STATEFUL | flag::USES_Z | flag::WRITES_Z)
        .prepare(exblur_prepare),
    VarDef::new("glitchy1", glitchy1)
        .params(&[
            p("glitchy1_scale_x", 1.0),
            p("glitchy1_shift_x", 0.0),
            p_int("glitchy1_n_x", 2.0, 1.0, 100.0),
            p("glitchy1_scale_y", 1.0),
            p("glitchy1_shift_y", 0.0),
            p_int("glitchy1_n_y", 2.0, 1.0, 100.0),
            p("glitchy1_scale_z", 0.0),
            p("glitchy1_shift_z", 0.0),
            p_int("glitchy1_n_z", 2.0, 1.0, 100.0),
            p("glitchy1_width", 1.0),
            p_int("glitchy1_seed", 42.0, NINF, INF),
            p("glitchy1_angle", 30.0),
            p("glitchy1_u", 1.0),
            p("glitchy1_v", 1.0),
            p("glitchy1_w", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z)
        .prepare(glitchy1_prepare),
    VarDef::new("pyramid", pyramid).flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("rosoni", rosoni)
        .params(&[
            p_int("rosoni_maxiter", 25.0, 1.0, 1024.0),
            p_int("rosoni_sweetiter", 3.0, 0.0, 1023.0),
            p_int("rosoni_altshapes", 0.0, NINF, INF),
            p("rosoni_cutoff", 1.0),
            p("rosoni_radius", 0.4),
            p("rosoni_dx", 0.6),
            p("rosoni_dy", 0.0),
        ])
        .needs(need::SQRT)
        .flags(flag::JWILDFIRE)
        .prepare(rosoni_prepare),
    VarDef::new("xheart_blur_wf", xheart_blur_wf)
        .params(&[
            p("xheart_blur_wf_angle", 0.0),
            p("xheart_blur_wf_ratio", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .prepare(xheart_blur_prepare),
    VarDef::new("epispiral_wf", epispiral_wf)
        .params(&[p_int("epispiral_wf_waves", 4.0, NINF, INF)])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE),
    VarDef::new("post_mirror_wf", post_mirror_wf)
        .params(&[
            p_int("post_mirror_wf_xaxis", 1.0, NINF, INF),
            p_int("post_mirror_wf_yaxis", 0.0, NINF, INF),
            p_int("post_mirror_wf_zaxis", 0.0, NINF, INF),
            p("post_mirror_wf_xshift", 0.0),
            p("post_mirror_wf_yshift", 0.0),
            p("post_mirror_wf_zshift", 0.0),
            p("post_mirror_wf_xscale", 1.0),
            p("post_mirror_wf_yscale", 1.0),
            p("post_mirror_wf_xcolorshift", 0.0),
            p("post_mirror_wf_ycolorshift", 0.0),
            p("post_mirror_wf_zcolorshift", 0.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::POST_ONLY
                | flag::RANDOM
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::USES_COLOR
                | flag::SETS_COLOR,
        ),
    VarDef::new("crop_stars", crop_stars)
        .params(&[
            p("crop_stars_radius", 0.35),
            p_int("crop_stars_n", 3.0, 3.0, 9.0),
            p_range("crop_stars_r2", 0.333, 0.0, 1.0),
            p_int("crop_stars_invert", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_ACC | flag::HIDES)
        .prepare(crop_stars_prepare),
    VarDef::new("plane_wf", plane_wf)
        .params(&[
            p("plane_wf_position", 3.0),
            p("plane_wf_size", 10.0),
            p_int("plane_wf_axis", 2.0, 0.0, 2.0),
            p_int("plane_wf_direct_color", 1.0, 0.0, 1.0),
            p_int("plane_wf_color_mode", 3.0, 0.0, 3.0),
            p_int("plane_wf_blend_colormap", 1.0, 0.0, 1.0),
            p("plane_wf_displ_amount", 0.1),
            p_int("plane_wf_blend_displ_map", 1.0, 0.0, 1.0),
            p_int("plane_wf_calc_color_idx", 0.0, 0.0, 1.0),
            p_int("plane_wf_receive_only_shadows", 0.0, 0.0, 1.0),
        ])
        .flags(
            flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::USES_COLOR,
        ),
    VarDef::new("julian2dc", julian2dc)
        .params(&[
            p_int_nonzero("julian2dc_power", 2.0, NINF, INF),
            p("julian2dc_dist", 1.0),
            p("julian2dc_col", 0.0),
            p("julian2dc_a", 1.0),
            p("julian2dc_b", 0.0),
            p("julian2dc_c", 0.0),
            p("julian2dc_d", 1.0),
            p("julian2dc_e", 0.0),
            p("julian2dc_f", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR),
    VarDef::new("szubieta", szubieta)
        .params(&[
            p_int("szubieta_width", 128.0, 32.0, 256.0),
            p_int("szubieta_height", 128.0, 32.0, 256.0),
            p_int("szubieta_type", 0.0, 0.0, 1.0),
            p_range("szubieta_scale", 0.5, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .prepare(szubieta_prepare),
    VarDef::new("nsudoku", nsudoku)
        .params(&[
            p_int("nsudoku_Level", 5.0, 1.0, 9.0),
            p_range("nsudoku_thickness", 0.5, 0.0, 1.0),
            p_range("nsudoku_size", 0.5, 0.3, 1.0),
            p("nsudoku_angle", 0.0),
            p_int("nsudoku_type", 4.0, 3.0, 6.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .prepare(nsudoku_prepare),
    VarDef::new("snowflake_wf", snowflake_wf)
        .params(&[
            p_int("snowflake_wf_buffer_size", 128.0, 1.0, 2048.0),
            p_int("snowflake_wf_max_iter", 500.0, 0.0, 100_000.0),
            p("snowflake_wf_bg_freeze_level", 0.5),
            p("snowflake_wf_fg_freeze_speed", 0.0005),
            p("snowflake_wf_diffusion_speed", 0.01),
            p("snowflake_wf_diffusion_asymmetry", 1.0),
            p("snowflake_wf_rnd_bg_noise", 0.25),
            p("snowflake_wf_threshold", 0.65),
            p_int("snowflake_wf_seed", 12345.0, NINF, INF),
            p("snowflake_wf_scale", 1.0),
            p("snowflake_wf_jitter", 0.001),
            p_int("snowflake_wf_dc_color", 1.0, NINF, INF),
            p("snowflake_wf_dc_color_scale", 2.0),
            p("snowflake_wf_dc_color_offset", 0.1),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .shared(&[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10], snowflake_points),
    VarDef::new("polarplot3d_wf", polarplot3d_wf)
        .params(&[
            p_int("polarplot3d_wf_preset_id", 2.0, NINF, INF),
            p("polarplot3d_wf_tmin", -PI),
            p("polarplot3d_wf_tmax", PI),
            p("polarplot3d_wf_umin", 0.0),
            p("polarplot3d_wf_umax", PI),
            p("polarplot3d_wf_rmin", -2.0),
            p("polarplot3d_wf_rmax", 2.0),
            p_int("polarplot3d_wf_cylindrical", 0.0, NINF, INF),
            p_int("polarplot3d_wf_direct_color", 1.0, NINF, INF),
            p_int("polarplot3d_wf_color_mode", 2.0, NINF, INF),
            p_int("polarplot3d_wf_blend_colormap", 1.0, 0.0, 1.0),
            p("polarplot3d_wf_displ_amount", 0.1),
            p_int("polarplot3d_wf_blend_displ_map", 1.0, 0.0, 1.0),
            p("polarplot3d_wf_param_a", 0.0),
            p("polarplot3d_wf_param_b", 0.0),
            p("polarplot3d_wf_param_c", 0.0),
            p("polarplot3d_wf_param_d", 0.0),
            p("polarplot3d_wf_param_e", 0.0),
            p("polarplot3d_wf_param_f", 0.0),
        ])
        .flags(
            flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::USES_COLOR,
        )
        .prepare(polarplot_prepare),
    VarDef::new("knots3D", knots3d)
        .params(&[
            p_int("knots3D_presetId", 0.0, NINF, INF),
            p_int("knots3D_steps", 1000.0, 1.0, 1_000_000.0),
            p("knots3D_radius", 1.05),
            p_int("knots3D_facets", 4.0, 1.0, 1000.0),
            p("knots3D_param_a", 0.0),
            p("knots3D_param_b", 0.0),
            p("knots3D_param_c", 0.0),
            p("knots3D_param_d", 0.0),
            p("knots3D_param_e", 0.0),
            p("knots3D_param_f", 0.0),
            p("knots3D_param_g", 0.0),
            p("knots3D_param_h", 0.0),
            p("knots3D_scale_x", 0.02),
            p("knots3D_scale_y", 0.02),
            p("knots3D_scale_z", 0.02),
            p("knots3D_offset_x", 0.0),
            p("knots3D_offset_y", 0.0),
            p("knots3D_offset_z", 0.0),
            p_int("knots3D_subdiv_level", 0.0, 0.0, 6.0),
            p_int("knots3D_subdiv_smooth_passes", 12.0, 0.0, 24.0),
            p("knots3D_subdiv_smooth_lambda", 0.42),
            p("knots3D_subdiv_smooth_mu", -0.45),
            p_int("knots3D_blend_colormap", 1.0, 0.0, 1.0),
            p("knots3D_displ_amount", 0.1),
            p_int("knots3D_blend_displ_map", 1.0, 0.0, 1.0),
            p_int("knots3D_receive_only_shadows", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z)
        .shared(
            &[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17],
            knots3d_faces,
        ),
];

// ---------------------------------------------------------------------------------------------
// rose_wf, epispiral_wf

/// rose_wf: the rose curve r = amp·cos(waves·θ) drawn along the input's direction (θ measured
/// from the y axis, JWildfire's atan2(x, y)); `filled` = 1 scatters points inside the petals.
fn rose_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [amp, waves, filled] = v.params();
    let a = t.atan_xy;
    let mut r = amp * (waves * a).cos();
    if filled == 1.0 {
        r *= rng.f01();
    }
    let (s, c) = a.sin_cos();
    [v.w * s * r, v.w * c * r, 0.0]
}

/// epispiral_wf: the epispiral r = 0.5 / cos(waves·θ) along the input's direction (θ from the
/// y axis).
fn epispiral_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [waves] = v.params();
    let a = t.atan_xy;
    let r = 0.5 / (waves * a).cos();
    let (s, c) = a.sin_cos();
    [v.w * s * r, v.w * c * r, 0.0]
}

// ---------------------------------------------------------------------------------------------
// chrysanthemum

/// chrysanthemum: Paul Bourke's chrysanthemum curve, a point at a random parameter
/// u ∈ [0, 21π) (the input point is ignored).
fn chrysanthemum(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let u = 21.0 * PI * rng.f01();
    let s4 = (17.0 * u / 3.0).sin();
    let s8 = (2.0 * (3.0 * u).cos() - 28.0 * u).sin();
    let s4_2 = s4 * s4;
    let s8_2 = s8 * s8;
    let s8_4 = s8_2 * s8_2;
    let r = 5.0 * (1.0 + (11.0 * u / 5.0).sin()) - 4.0 * (s4_2 * s4_2) * (s8_4 * s8_4);
    let r = r * v.w;
    let (s, c) = u.sin_cos();
    [r * c, r * s, 0.0]
}

// ---------------------------------------------------------------------------------------------
// complex

/// complex: a weighted sum of the complex cos, cosh, cot, coth, csc, csch, exp, sec, sech, tan,
/// tanh, sin and sinh of the input, each with factors that detune its real and imaginary
/// parts. A vanishing denominator drops the whole output (the point contributes nothing).
fn complex(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        cospow,
        cosx1,
        cosx2,
        cosy1,
        cosy2,
        coshpow,
        coshx1,
        coshx2,
        coshy1,
        coshy2,
        cotpow,
        cotx1,
        cotx2,
        coty1,
        coty2,
        cothpow,
        cothx1,
        cothx2,
        cothy1,
        cothy2,
        cscpow,
        cscx1,
        cscx2,
        cscy1,
        cscy2,
        cschpow,
        cschx1,
        cschx2,
        cschy1,
        cschy2,
        exppow,
        expx1,
        expy1,
        expy2,
        secpow,
        secx1,
        secx2,
        secy1,
        secy2,
        sechpow,
        sechx1,
        sechx2,
        sechy1,
        sechy2,
        sinpow,
        sinx1,
        sinx2,
        siny1,
        siny2,
        sinhpow,
        sinhx1,
        sinhx2,
        sinhy1,
        sinhy2,
        tanpow,
        tanx1,
        tanx2,
        tany1,
        tany2,
        tanhpow,
        tanhx1,
        tanhx2,
        tanhy1,
        tanhy2,
    ] = v.params();
    let (x, y) = (t.x, t.y);
    let (mut ox, mut oy) = (0.0, 0.0);
    // cos
    if cospow != 0.0 {
        ox += cospow * (x * cosx2).cos() * (y * cosy2).cosh();
        oy -= cospow * (x * cosx1).sin() * (y * cosy1).sinh();
    }
    // cosh
    if coshpow != 0.0 {
        ox += coshpow * (x * coshx2).cosh() * (y * coshy2).cos();
        oy += coshpow * (x * coshx1).sinh() * (y * coshy1).sin();
    }
    // cot
    if cotpow != 0.0 {
        let k = 1.0 / ((coty2 * y).cosh() - (cotx2 * x).cos());
        ox += cotpow * k * (cotx1 * x).sin();
        oy -= cotpow * k * (coty1 * y).sinh();
    }
    // coth
    if cothpow != 0.0 {
        let d = (cothx2 * x).cosh() - (cothy2 * y).cos();
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 1.0 / d;
        ox += cothpow * k * (cothx1 * x).sinh();
        oy += cothpow * k * (cothy1 * y).sin();
    }
    // csc
    if cscpow != 0.0 {
        let d = (2.0 * y).cosh() - (2.0 * x).cos();
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 2.0 / d;
        ox += cscpow * k * (x * cscx1).sin() * (y * cscy2).cosh();
        oy -= cscpow * k * (x * cscx2).cos() * (y * cscy1).sinh();
    }
    // csch
    if cschpow != 0.0 {
        let d = (2.0 * x).cosh() - (2.0 * y).cos();
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 2.0 / d;
        ox += cschpow * k * (x * cschx1).sinh() * (y * cschy2).cos();
        oy -= cschpow * k * (x * cschx2).cosh() * (y * cschy1).sin();
    }
    // exp
    if exppow != 0.0 {
        let e = (x * expx1).exp();
        ox += exppow * e * (y * expy2).cos();
        oy += exppow * e * (y * expy1).sin();
    }
    // sec
    if secpow != 0.0 {
        let d = (2.0 * x).cos() + (2.0 * y).cosh();
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 2.0 / d;
        ox += secpow * k * (x * secx2).cos() * (y * secy2).cosh();
        oy += secpow * k * (x * secx1).sin() * (y * secy1).sinh();
    }
    // sech
    if sechpow != 0.0 {
        let d = (2.0 * y).cos() + (2.0 * x).cosh();
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 2.0 / d;
        ox += sechpow * k * (x * sechx2).cosh() * (y * sechy2).cos();
        oy -= sechpow * k * (x * sechx1).sinh() * (y * sechy1).sin();
    }
    // tan
    if tanpow != 0.0 {
        let d = (tanx2 * x).cos() + (tany2 * y).cosh();
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 1.0 / d;
        ox += tanpow * k * (tanx1 * x).sin();
        oy += tanpow * k * (tany1 * y).sinh();
    }
    // tanh
    if tanhpow != 0.0 {
        let d = (y * tanhy2).cos() + (x * tanhx2).cosh();
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 1.0 / d;
        ox += tanhpow * k * (x * tanhx1).sinh();
        oy += tanhpow * k * (y * tanhy1).sin();
    }
    // sin
    if sinpow != 0.0 {
        ox += sinpow * (x * sinx1).sin() * (y * siny2).cosh();
        oy += sinpow * (x * sinx2).cos() * (y * siny1).sinh();
    }
    // sinh
    if sinhpow != 0.0 {
        ox += sinhpow * (x * sinhx1).sinh() * (y * sinhy2).cos();
        oy += sinhpow * (x * sinhx2).cosh() * (y * sinhy1).sin();
    }
    [v.w * ox, v.w * oy, 0.0]
}

// ---------------------------------------------------------------------------------------------
// exblur

/// Seeds the four carried random values (JWildfire draws them from the render's generator when
/// the variation is initialised; any uniform values serve).
fn exblur_prepare(v: &mut Prepared) {
    let mut r = FastRng::new(0x6578_626c_7572);
    for i in 0..4 {
        v.state.set(i, r.f01());
    }
}

/// exblur: a 3-D blur around an origin: the point's direction (spherical angles about the
/// origin) scaled by |p - o|^(2·dist) times a smooth random factor (the sum of the last four
/// uniform draws, minus 2), plus a random sphere of relative radius r.
fn exblur(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [dist, r, x_origin, y_origin, z_origin] = v.params();
    let ox = t.x - x_origin;
    let oy = t.y + y_origin;
    let oz = t.z - z_origin;
    let n = ox * ox + oy * oy + oz * oz;
    let (s0, s1, s2, s3) = (
        v.state.get(0),
        v.state.get(1),
        v.state.get(2),
        v.state.get(3),
    );
    let rr = v.w * n.powf(dist) * (s0 + s1 + s2 + s3 - 2.0);
    let theta = oy.atan2(ox);
    let phi = (oz / n.sqrt()).acos();
    let (su, cu) = theta.sin_cos();
    let (sv, cv) = phi.sin_cos();
    let (sru, cru) = (rng.f01() * TAU).sin_cos();
    let (srv, crv) = (rng.f01() * TAU).sin_cos();
    // The oldest of the four values gives way to a new draw.
    v.state.set(0, s1);
    v.state.set(1, s2);
    v.state.set(2, s3);
    v.state.set(3, rng.f01());
    let rsrv = r * srv;
    [
        rr * (sv * cu + rsrv * cru),
        rr * (sv * su + rsrv * sru),
        rr * (cv + r * crv),
    ]
}

// ---------------------------------------------------------------------------------------------
// glitchy1

fn glitchy1_prepare(v: &mut Prepared) {
    let [_, _, _, _, _, _, _, _, _, _, _, angle] = v.params();
    let a = angle.to_radians();
    v.p.push(a.sin());
    v.p.push(a.cos());
}

/// Mirrors `c` about `shift` in every `n`-th band of width 1/scale (glitchy1's folding).
fn glitch_fold(c: f64, scale: f64, shift: f64, n: f64) -> f64 {
    if scale == 0.0 {
        return c;
    }
    let band = ((c - shift) * scale).floor() as i32 as f64;
    let flip = if band >= 0.0 {
        band % n == n - 1.0
    } else {
        band % n == 0.0
    };
    if flip { 2.0 * shift - c } else { c }
}

/// glitchy1: folds x, y, z in periodic bands and scales the point by a hash of the rotated
/// block it falls in, giving blocky, glitch-like stretches.
fn glitchy1(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        scale_x,
        shift_x,
        n_x,
        scale_y,
        shift_y,
        n_y,
        scale_z,
        shift_z,
        n_z,
        width,
        seed,
        _angle,
        u,
        v_scale,
        w_scale,
    ] = v.params();
    let [h, k] = v.derived();
    let x = glitch_fold(t.x, scale_x, shift_x, n_x);
    let y = glitch_fold(t.y, scale_y, shift_y, n_y);
    let z = glitch_fold(t.z, scale_z, shift_z, n_z);
    let seed = seed as i32;
    let uu = u * t.x;
    let vv = v_scale * (k * uu + h * t.y);
    let ww = w_scale * (k * uu - h * t.y);
    let block = |c: f64| -> i32 {
        let b = (c * width).floor() as i32;
        (b as f64 + (2.0 - 4.0 * wang_hash(b.wrapping_mul(seed).wrapping_add(1)))) as i32
    };
    let (bu, bv, bw) = (block(uu), block(vv), block(ww));
    let base = bu.wrapping_add(bv);
    let len = wang_hash(base.wrapping_add(bw.wrapping_mul(seed.wrapping_neg())))
        + wang_hash(base.wrapping_add(bw.wrapping_mul(seed) / 2));
    let s = v.w * len;
    [s * x, s * y, s * z]
}

// ---------------------------------------------------------------------------------------------
// pyramid

/// pyramid: cubes the coordinates (|z|³ for z) and normalises them by their L1 norm, pushing
/// points onto the surface of an octahedron-like pyramid.
fn pyramid(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let x = t.x * t.x * t.x;
    let y = t.y * t.y * t.y;
    let z = (t.z * t.z * t.z).abs();
    let r = v.w / (x.abs() + y.abs() + z + 1e-9);
    [x * r, y * r, z * r]
}

// ---------------------------------------------------------------------------------------------
// rosoni

fn rosoni_prepare(v: &mut Prepared) {
    let [maxiter] = v.params();
    let phi = TAU / maxiter;
    v.p.push(phi.sin());
    v.p.push(phi.cos());
}

/// rosoni: inside a cut-off disc (or square), rotates the point through `maxiter` steps around
/// the origin and counts how often it falls into a shape placed at (dx, dy) (a circle, square,
/// lemniscate or wedge); an odd count replaces the point by its rotation at step `sweetiter`.
fn rosoni(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [maxiter, sweetiter, alt, cutoff, radius, dx, dy] = v.params();
    let [sina, cosa] = v.derived();
    let (maxiter, sweetiter) = (maxiter as i32, sweetiter as i32);
    let (x, y) = (t.x, t.y);
    let outside = if cutoff < 0.0 {
        x.abs().max(y.abs()) + cutoff
    } else {
        t.sqrt - cutoff
    };
    if outside > 0.0 {
        return [v.w * x, v.w * y, 0.0];
    }
    let mut odd = dx > 0.0;
    let (mut xr, mut yr) = (x, y);
    let (mut sx, mut sy) = (x, y);
    for i in 0..maxiter {
        let inside_measure = if alt == 0.0 {
            if radius < 0.0 {
                // square (JWildfire measures y from the unrotated point here)
                (xr - dx).abs().max((y - dy).abs()) + radius
            } else {
                sqr(xr - dx) + sqr(yr - dy) - sqr(radius)
            }
        } else if radius < 0.0 {
            // wedge (again with the unrotated y)
            (y - dy).atan2(xr - dx).abs() * FRAC_1_PI + radius
        } else if xr - dx < 0.0 {
            dx - xr
        } else {
            sqr(yr - dy) - sqr(xr - dx) * (sqr(radius) - sqr(xr - dx))
        };
        odd ^= inside_measure <= 0.0;
        if i == sweetiter {
            sx = xr;
            sy = yr;
        }
        let nx = xr * cosa - yr * sina;
        yr = xr * sina + yr * cosa;
        xr = nx;
    }
    if !odd {
        return [v.w * x, v.w * y, 0.0];
    }
    if sweetiter == 0 {
        let ox = if dy != 0.0 { -sx } else { sx };
        [v.w * ox, -v.w * sy, 0.0]
    } else {
        [v.w * sx, v.w * sy, 0.0]
    }
}

// ---------------------------------------------------------------------------------------------
// xheart_blur_wf

fn xheart_blur_prepare(v: &mut Prepared) {
    let [angle, ratio] = v.params();
    let ang = FRAC_PI_4 + 0.5 * FRAC_PI_4 * angle;
    let (s, c) = ang.sin_cos();
    let rat = 6.0 + 2.0 * ratio;
    v.p.extend_from_slice(&[s, c, rat]);
}

/// xheart_blur_wf: xheart applied to a uniformly random point of the square [-2, 2]², a heart
/// shape filled with points (the input point is ignored).
fn xheart_blur_wf(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sina, cosa, rat] = v.derived();
    let dx = 2.0 - rng.f01() * 4.0;
    let dy = 2.0 - rng.f01() * 4.0;
    let mut r2_4 = dx * dx + dy * dy + 4.0;
    if r2_4 == 0.0 {
        r2_4 = 1.0;
    }
    let bx = 4.0 / r2_4 * dx;
    let by = rat / r2_4 * dy;
    let x = cosa * bx - sina * by;
    let y = sina * bx + cosa * by;
    let ys = if x > 0.0 { y } else { -y };
    [v.w * x, v.w * ys, 0.0]
}

// ---------------------------------------------------------------------------------------------
// post_mirror_wf

/// post_mirror_wf: after the xform's variations, mirrors the point with probability ½ per
/// enabled axis (x: about x = -xshift/2, y: about y = -yshift/2, z: about z = -zshift/2), scaling
/// and shifting the colour on each mirror. The weight is not used.
fn post_mirror_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        xaxis,
        yaxis,
        zaxis,
        xshift,
        yshift,
        zshift,
        xscale,
        yscale,
        xcolorshift,
        ycolorshift,
        zcolorshift,
    ] = v.params();
    let (mut x, mut y, mut z) = (t.x, t.y, t.z);
    let mut c = acc.color;
    if xaxis > 0.0 && rng.f01() < 0.5 {
        x = xscale * (-x - xshift);
        y *= yscale;
        c = (c + xcolorshift) % 1.0;
    }
    if yaxis > 0.0 && rng.f01() < 0.5 {
        x *= xscale;
        y = yscale * (-y - yshift);
        c = (c + ycolorshift) % 1.0;
    }
    if zaxis > 0.0 && rng.f01() < 0.5 {
        z = -z - zshift;
        c = (c + zcolorshift) % 1.0;
    }
    acc.color = c;
    [x, y, z]
}

// ---------------------------------------------------------------------------------------------
// crop_stars

// JWildfire rounds π to 6 decimals here; kept so that the star's edges agree.
#[allow(clippy::approx_constant)]
fn crop_stars_prepare(v: &mut Prepared) {
    let [radius, n, r2] = v.params();
    // Inner angle of a sector and the star's external angle; JWildfire uses 6-digit π here.
    let an = 3.141593 / n;
    let m = 4.0 + r2 * r2 * (n * 2.0 - 4.0);
    let en = 6.283185 / m;
    let (asin, acos) = an.sin_cos();
    let (esin, ecos) = en.sin_cos();
    v.p.extend_from_slice(&[an, acos, asin, ecos, esin, radius * asin / esin]);
}

/// crop_stars: keeps the points inside a star (n points, outer radius `radius`, inner angle set
/// by r2) and sends the others to the origin (`invert` swaps inside and outside). It replaces
/// the xform's sum so far, as JWildfire's crop variations do.
fn crop_stars(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [radius, _, _, invert] = v.params();
    let [an, acos, asin, ecos, esin, kmax] = v.derived();
    // Signed distance to the star, computed in its first sector.
    let a = atan2_approx(t.x, t.y);
    let period = 2.0 * an;
    let bn = a - period * (a / period).floor() - an;
    let len = (t.x * t.x + t.y * t.y).sqrt();
    let (sb, cb) = bn.sin_cos();
    let mut px = cb * len - acos * radius;
    let mut py = sb.abs() * len - asin * radius;
    let k = (-(px * ecos + py * esin)).max(0.0).min(kmax);
    px += ecos * k;
    py += esin * k;
    let d = (px * px + py * py).sqrt() * signum_java(px);
    // Hidden (d > 0) outside, or (d <= 0) inside when inverted; NaN is kept.
    let keep = if invert == 0.0 {
        d.is_nan() || d <= 0.0
    } else {
        d.is_nan() || d > 0.0
    };
    acc.x = 0.0;
    acc.y = 0.0;
    if keep {
        [v.w * t.x, v.w * t.y, 0.0]
    } else {
        // The orbit goes on from the origin; the sample is not drawn.
        acc.hide = true;
        [0.0, 0.0, 0.0]
    }
}

// ---------------------------------------------------------------------------------------------
// plane_wf

/// plane_wf: a uniformly filled square of side `size` in the xy, yz or zx plane, placed at
/// `position` along the remaining axis; the colour can follow the square's u, v or u·v
/// coordinate. (JWildfire's colour-map and displacement-map images are not supported.)
fn plane_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [position, size, axis, direct_color, color_mode] = v.params();
    let a = 0.5 - rng.f01();
    let b = 0.5 - rng.f01();
    // (u, v) of the colour modes and the output.
    let (u, w, out) = match axis as i32 {
        0 => (a, b, [a * size, b * size, position]),
        1 => (a, b, [position, a * size, b * size]),
        _ => (b, a, [a * size, position, b * size]),
    };
    if direct_color > 0.0 {
        let c = match color_mode as i32 {
            0 => acc.color,
            2 => w + 0.5,
            3 => (w + 0.5) * (u + 0.5),
            _ => u + 0.5,
        };
        acc.color = c.clamp(0.0, 1.0);
    }
    [v.w * out[0], v.w * out[1], v.w * out[2]]
}

// ---------------------------------------------------------------------------------------------
// julian2dc

/// julian2dc: julian (the power-th root, one branch at random, radius scaled by
/// |z|^(dist/power)) of an affine image of the point; the colour is set from a blend of the
/// output radius and the branch angle (`col` = 0: angle, 1: radius).
fn julian2dc(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, dist, col, a, b, c, d, e, f] = v.params();
    let x = a * t.x + b * t.y + e;
    let y = c * t.x + d * t.y + f;
    let branches = power.abs();
    let k = (rng.f01() * branches).floor().min(branches - 1.0);
    let angle = (y.atan2(x) + TAU * k) / power;
    let r = v.w * (x * x + y * y).powf(dist / power / 2.0);
    let (s, c) = angle.sin_cos();
    acc.color = ((r * col + angle / TAU * (1.0 - col)).abs()) % 1.0;
    [r * c, r * s, 0.0]
}

// ---------------------------------------------------------------------------------------------
// Filled regular polygons (JWildfire's DrawFunc, after FractalDesire's nBlur): szubieta, nsudoku

/// Constants of the polygon sampler for `sides` sides, appended to `p`: [sides, mid angle,
/// tan(π/2 + mid/2), spread, spread normaliser, sin(mid/2), cos(mid/2)].
fn push_polygon(p: &mut Vec<f64>, sides: f64) {
    let n = sides.max(3.0);
    let mid = TAU / n;
    let spread = 13.0 / n.powf(1.3);
    let (s, c) = (mid / 2.0).sin_cos();
    p.extend_from_slice(&[
        n,
        mid,
        (PI / 2.0 + mid / 2.0).tan(),
        spread,
        2.0 * (spread / -2.0).atan(),
        s,
        c,
    ]);
}

/// A random point of the regular polygon described at `g` (see [`push_polygon`]) with unit
/// circumradius, uniform in area between the hole (relative size `hole`) and the edge. Draws
/// four numbers, as JWildfire does (one of them unused).
fn polygon_point(g: [f64; 7], hole: f64, rng: &mut FastRng) -> (f64, f64) {
    let [n, mid, tan90, spread, norm, s, c] = g;
    let jitter = rng.f01() - 0.5;
    let corner = ((rng.f01() * 32767.0) as i32).min(32766) as f64 % n;
    let mut ang = ((spread * jitter).atan() / norm + 0.5 + corner) * mid;
    let (dx, dy) = ang.sin_cos();
    while ang > mid {
        ang -= mid;
    }
    let ta = ang.tan();
    let ex = tan90 / (tan90 - ta);
    let ey = ex * ta;
    let outer = (ex * ex + ey * ey).sqrt();
    rng.f01();
    let inner = hole * outer;
    let len = inner + rng.f01().sqrt() * (outer - inner);
    let (x, y) = (dx * len, dy * len);
    (c * x - s * y, s * x + c * y)
}

fn szubieta_prepare(v: &mut Prepared) {
    push_polygon(&mut v.p, 20.0);
}

/// Grey level of cell (i, j) of Paul Bourke's "circle squares" (kind 0) or "square tile"
/// (kind 1) integer patterns, in [0, 1].
fn bourke_pattern(kind: f64, i: i32, j: i32) -> f64 {
    if kind == 0.0 {
        let x = i
            .wrapping_mul(i)
            .wrapping_sub(2 * (i | j))
            .wrapping_add(j.wrapping_mul(j));
        (x % 255).abs() as f64 / 255.0
    } else {
        let x = i & (j - 2 * (i ^ j) + j) & i;
        (x % 256).abs() as f64 / 255.0
    }
}

/// szubieta: a width × height grid of small filled 20-gons (radius `scale`, spacing 1, the
/// whole scaled by 0.1), coloured by one of Paul Bourke's integer patterns; the point lands in
/// a random cell (the input point is ignored).
fn szubieta(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [width, height, kind, scale] = v.params();
    let cells = width as usize * height as usize;
    let idx = ((rng.f01() * cells as f64) as usize).min(cells - 1);
    let (i, j) = (
        (idx / height as usize) as i32,
        (idx % height as usize) as i32,
    );
    let (px, py) = (i as f64 - width / 2.0, j as f64 - height / 2.0);
    let (ox, oy) = polygon_point(v.derived(), 0.0, rng);
    acc.color = bourke_pattern(kind, i, j);
    let k = v.w * 0.1;
    [k * (ox * scale + px), k * (oy * scale + py), 0.0]
}

/// Where nsudoku's layers start in its derived values: after the polygon (7 values, see
/// [`push_polygon`]), the rotation's cosine and sine, and the layer count.
const SUDOKU_LAYERS: usize = 10;
/// Per layer: polygon radius, hole size, then the 81 digits (cell i·9 + j).
const SUDOKU_LAYER_LEN: usize = 83;

/// A valid, randomly relabelled and shuffled 9×9 sudoku solution (digits 1–9).
fn random_sudoku(rng: &mut FastRng) -> [[u8; 9]; 9] {
    let shuffle = |rng: &mut FastRng, a: &mut [usize]| {
        for i in (1..a.len()).rev() {
            let k = rng.below(i as u64 + 1) as usize;
            a.swap(i, k);
        }
    };
    let mut digits = [0usize, 1, 2, 3, 4, 5, 6, 7, 8];
    shuffle(rng, &mut digits);
    // Row and column orders: bands (stacks) shuffled, rows (columns) shuffled within them.
    let order = |rng: &mut FastRng| {
        let mut bands = [0usize, 1, 2];
        shuffle(rng, &mut bands);
        let mut out = [0usize; 9];
        for (b, &band) in bands.iter().enumerate() {
            let mut within = [0usize, 1, 2];
            shuffle(rng, &mut within);
            for (k, &w) in within.iter().enumerate() {
                out[3 * b + k] = 3 * band + w;
            }
        }
        out
    };
    let rows = order(rng);
    let cols = order(rng);
    let mut g = [[0u8; 9]; 9];
    for (r, row) in g.iter_mut().enumerate() {
        for (c, cell) in row.iter_mut().enumerate() {
            let (rr, cc) = (rows[r], cols[c]);
            let base = (3 * (rr % 3) + rr / 3 + cc) % 9;
            *cell = digits[base] as u8 + 1;
        }
    }
    g
}

/// The 1296 row permutations that keep a sudoku valid (rows permuted within each band, bands
/// permuted), as 1-based row numbers.
fn sudoku_row_permutations() -> Vec<[u8; 9]> {
    const P3: [[u8; 3]; 6] = [
        [1, 2, 3],
        [1, 3, 2],
        [2, 1, 3],
        [2, 3, 1],
        [3, 1, 2],
        [3, 2, 1],
    ];
    let mut out = Vec::with_capacity(1296);
    for a in P3 {
        for b in P3 {
            for c in P3 {
                for bands in P3 {
                    let within = [a, b, c];
                    let mut row = [0u8; 9];
                    for k in 0..9 {
                        row[k] = within[k / 3][k % 3] + 3 * bands[k / 3] - 3;
                    }
                    out.push(row);
                }
            }
        }
    }
    out
}

fn nsudoku_prepare(v: &mut Prepared) {
    let [level, thickness, size, angle, sides] = v.params();
    let hole = 1.0 - thickness;
    push_polygon(&mut v.p, sides);
    let (s, c) = (angle * PI / 180.0).sin_cos();
    v.p.extend_from_slice(&[c, s]);
    let count_at = v.p.len();
    v.p.push(0.0);
    // JWildfire draws a fresh random sudoku each time; a fixed seed keeps renders repeatable.
    let mut rng = FastRng::new(0x7375_646f_6b75);
    let base = random_sudoku(&mut rng);
    let mut candidates = sudoku_row_permutations();
    let mut perm: [u8; 9] = [1, 2, 3, 4, 5, 6, 7, 8, 9];
    let mut layers = 0;
    let mut n = level;
    while n >= 1.0 {
        if n != level {
            if candidates.is_empty() {
                break;
            }
            let k = ((rng.f01() * candidates.len() as f64) as usize).min(candidates.len() - 1);
            perm = candidates[k];
        }
        v.p.push(size * (n / level) / 9.0);
        v.p.push(if 1.0 - 1.0 / n == 0.0 { 0.0 } else { hole });
        // Cell (i, j) shows row j, column i of the row-permuted grid.
        v.p.extend((0..9).flat_map(|i| {
            perm.iter()
                .map(move |&row| base[row as usize - 1][i] as f64)
        }));
        layers += 1;
        // Later layers use permutations sharing no row position with this one.
        candidates.retain(|c| c.iter().zip(&perm).all(|(a, b)| a != b));
        n -= 1.0;
    }
    v.p[count_at] = layers as f64;
}

/// nsudoku: `Level` stacked layers of a sudoku grid drawn as filled polygons on the unit square
/// (each layer's rows permuted, polygons shrinking layer by layer, hollow by `thickness`); the
/// colour is the cell's digit / 9 (the input point is ignored).
fn nsudoku(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, c, s, layers] = v.derived();
    let layers = layers as usize;
    let total = layers * 81;
    let idx = ((rng.f01() * total as f64) as usize).min(total - 1);
    let (layer, cell) = (idx / 81, idx % 81);
    let l = &v.table(SUDOKU_LAYERS)[layer * SUDOKU_LAYER_LEN..];
    let (radius, hole) = (l[0], l[1]);
    let (px, py) = ((cell / 9) as f64 / 9.0 - 0.5, (cell % 9) as f64 / 9.0 - 0.5);
    let (ox, oy) = polygon_point(v.derived(), hole, rng);
    acc.color = l[2 + cell] / 9.0;
    [
        v.w * (ox * radius * c + oy * radius * s + px),
        v.w * (-ox * radius * s + oy * radius * c + py),
        0.0,
    ]
}

// ---------------------------------------------------------------------------------------------
// snowflake_wf

/// Ratio JWildfire uses to lay the hexagonal grid out on a square canvas.
const SNOW_STRETCH: f64 = 1.5 / 1.7321;

/// Clifford Reiter's local cellular model of snow crystal growth on a hexagonal grid of
/// `width` columns; returns the canvas of frozen values above the threshold (0 elsewhere).
fn snow_crystal(q: &[f64]) -> Vec<Vec<f32>> {
    let [
        size,
        max_iter,
        bg,
        freeze,
        diffusion,
        asym,
        noise,
        threshold,
        seed,
    ] = params_of(q);
    let w = size.max(1.0) as usize;
    let iters = max_iter.max(0.0) as usize;
    let h = 2 * w - 1;
    let cells = w * h + (w - 1) * (h - 1);
    let (wi, ci) = (w as i64, cells as i64);
    let offsets = [-wi - (wi - 1), -(wi - 1), wi, wi + (wi - 1), wi - 1, -wi];
    let neighbour = |n: usize, k: usize| -> Option<usize> {
        let m = n as i64 + offsets[k];
        (m >= 0 && m < ci).then_some(m as usize)
    };
    let mut rnd = Mwc::new(seed as i64);
    let mut field: Vec<f64> = (0..cells)
        .map(|_| bg + (noise - 2.0 * noise * rnd.next_f64()))
        .collect();
    field[cells / 2] = 1.0;
    let mut diffusing = vec![0.0; cells];
    let mut spread = vec![0.0; cells];
    let mut frozen = vec![0.0; cells];
    let t_freeze = freeze / 1000.0;
    let t_diff = diffusion / 1000.0 + 1.0;
    let c_weight = 0.5 * asym / t_diff;
    let n_weight = (t_diff - c_weight) / 6.0;
    for _ in 0..iters {
        diffusing.copy_from_slice(&field);
        frozen.iter_mut().for_each(|f| *f = 0.0);
        for i in 0..cells {
            if field[i] >= 1.0 {
                frozen[i] = field[i];
                for k in 0..6 {
                    if let Some(m) = neighbour(i, k) {
                        diffusing[m] = 0.0;
                        frozen[m] = if field[m] > 0.0 {
                            field[m] + t_freeze
                        } else {
                            field[m]
                        };
                    }
                }
            }
        }
        for i in 0..cells {
            let mut s = diffusing[i] * c_weight;
            for k in 0..6 {
                if let Some(m) = neighbour(i, k) {
                    s += diffusing[m] * n_weight;
                }
            }
            spread[i] = s;
        }
        for i in 0..cells {
            field[i] = spread[i] + frozen[i];
        }
    }
    // Render the hexagonal cells onto a rectangular canvas.
    let cw = (2.0 * w as f64 * SNOW_STRETCH).floor() as usize;
    let mut canvas = vec![vec![0f32; cw]; h];
    let mut put = |value: f64, x: i64, y: usize| {
        if value > threshold + 1e-8 && x >= 0 && (x as usize) < cw {
            canvas[y][x as usize] = (value - threshold) as f32;
        }
    };
    for i in 0..h {
        for j in 0..w {
            let base = (2 * w - 1) * i + j;
            put(field[base], ((2 * j) as f64 * SNOW_STRETCH + 0.5) as i64, i);
            let (a, b) = (base as i64 - wi + 1, (base + w) as i64);
            if a >= 0 && a < ci && b < ci {
                let avg = (field[a as usize] + field[b as usize]) * 0.5;
                put(avg, ((2 * j + 1) as f64 * SNOW_STRETCH + 0.5) as i64, i);
            }
        }
    }
    canvas
}

/// snowflake_wf's shared data: the count of points, then x, y and intensity per point (from
/// parameters 0–10: the crystal's growth, its seed, scale and jitter).
fn snowflake_points(q: &[f64], _: &[String]) -> Vec<f64> {
    let canvas = snow_crystal(q);
    let [_, _, _, _, _, _, _, _, seed, scale, jitter] = params_of(q);
    let jitter = jitter.clamp(0.0, 1.0);
    let mut rnd = Mwc::new(seed as i64);
    let mut out = vec![0.0];
    let rows = canvas.len() as f64;
    let mut count = 0;
    for (i, row) in canvas.iter().enumerate() {
        let cols = row.len() as f64;
        for (j, &val) in row.iter().enumerate() {
            // The jitter draw happens for every cell so that growth keeps earlier points fixed.
            let a = if jitter > 1e-8 { rnd.next_f64() } else { 0.0 };
            if (val as f64) > 1e-8 {
                let mut x = (i as f64 - rows * 0.5) * scale / rows;
                let mut y = (j as f64 - cols * 0.5) * scale / cols * SNOW_STRETCH;
                if jitter > 1e-8 {
                    let (s, c) = (a * 2.0 * PI).sin_cos();
                    x += jitter * c;
                    y += jitter * s;
                }
                out.extend_from_slice(&[x, y, val as f64]);
                count += 1;
            }
        }
    }
    out[0] = count as f64;
    out
}

/// snowflake_wf: a random cell of a simulated snow crystal (Reiter's cellular growth model);
/// with `dc_color` the colour follows the cell's frozen amount (the input point is ignored).
fn snowflake_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _buffer_size,
        _max_iter,
        _bg_freeze_level,
        _fg_freeze_speed,
        _diffusion_speed,
        _diffusion_asymmetry,
        _rnd_bg_noise,
        _threshold,
        _seed,
        _scale,
        _jitter,
        dc_color,
        dc_color_scale,
        dc_color_offset,
    ] = v.params();
    let pts = v.data();
    let count = pts[0] as usize;
    // With fewer than two cells JWildfire falls back to the origin with intensity 0.
    let pt = if count < 2 {
        &[0.0; 3][..]
    } else {
        // JWildfire rounds to the nearest index, so the first and last cells are half as likely.
        let k = (rng.f01() * (count - 1) as f64 + 0.5) as usize;
        &pts[1 + 3 * k..]
    };
    if dc_color > 0.0 {
        acc.color = pt[2] * dc_color_scale + dc_color_offset;
    }
    [v.w * pt[0], v.w * pt[1], 0.0]
}

// ---------------------------------------------------------------------------------------------
// polarplot3d_wf

fn polarplot_prepare(v: &mut Prepared) {
    let sorted = |a: f64, b: f64| if a > b { (b, a - b) } else { (a, b - a) };
    let [_, t0, t1, u0, u1, r0, r1] = v.params();
    let (tmin, dt) = sorted(t0, t1);
    let (umin, du) = sorted(u0, u1);
    let (rmin, dr) = sorted(r0, r1);
    v.p.extend_from_slice(&[tmin, dt, umin, du, rmin, dr]);
}

/// The radius r(t, u) of polarplot3d_wf's stock formula `preset` (JWildfire's presets 0–9) with
/// parameters a, b, c; `None` for other ids (custom formulas, which ugnis cannot read).
fn polar_preset(preset: f64, t: f64, u: f64, a: f64, b: f64, c: f64) -> Option<f64> {
    Some(match preset as i32 {
        0 | 1 => (a * u).sin() + b,
        2 => u,
        3 => ((a * t).sin() + (b * u).cos()) + c,
        4 | 5 => (a * t + b * u).sin() + c,
        6 => (a * t).sin() + b * u,
        7 => t / (a + u) + b,
        8 => u * u + a,
        9 => (a * t + (b * u).sin()).cos() + c,
        _ => return None,
    })
}

/// polarplot3d_wf: a surface r = f(t, u) in spherical coordinates (t the azimuth, u the polar
/// angle) or cylindrical ones (r·cos t, r·sin t, u), sampled at uniformly random (t, u); the
/// colour can follow t, u, r or t·u. Only JWildfire's stock formulas (by preset id) are known.
fn polarplot3d_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        preset_id,
        _tmin,
        _tmax,
        _umin,
        _umax,
        _rmin,
        _rmax,
        cylindrical,
        direct_color,
        color_mode,
        _blend_colormap,
        _displ_amount,
        _blend_displ_map,
        param_a,
        param_b,
        param_c,
    ] = v.params();
    let [tmin, dt, umin, du, rmin, dr] = v.derived();
    let rt = rng.f01();
    let ru = rng.f01();
    let t = tmin + rt * dt;
    let u = umin + ru * du;
    let Some(r) = polar_preset(preset_id, t, u, param_a, param_b, param_c) else {
        return [0.0; 3];
    };
    let (st, ct) = t.sin_cos();
    let out = if cylindrical == 0.0 {
        let (su, cu) = u.sin_cos();
        [r * su * ct, r * su * st, r * cu]
    } else {
        [r * ct, r * st, u]
    };
    if direct_color > 0.0 {
        let c = match color_mode as i32 {
            1 => (t - tmin) / dt,
            2 => (u - umin) / du,
            3 => (r - rmin) / dr,
            4 => (t - tmin) / dt * (u - umin) / du,
            _ => acc.color,
        };
        acc.color = c.clamp(0.0, 1.0);
    }
    [v.w * out[0], v.w * out[1], v.w * out[2]]
}

// ---------------------------------------------------------------------------------------------
// knots3D

/// The function of a Fourier knot term.
#[derive(Clone, Copy)]
enum Trig {
    Cos,
    Sin,
}
use Trig::{Cos, Sin};

impl Trig {
    fn of(self, a: f64) -> f64 {
        match self {
            Cos => a.cos(),
            Sin => a.sin(),
        }
    }
}

/// One term c·cos(k·t) or c·sin(k·t) of a Fourier knot coordinate: (c, k, function).
type KnotTerm = (i16, u8, Trig);

enum KnotCurve {
    /// x, y and z as sums of terms.
    Fourier([&'static [KnotTerm]; 3]),
    /// ((a + b·cos(c·t))·cos(d·t), (a + b·cos(c·t))·sin(d·t), b·sin(c·t)).
    Torus,
    /// (a·cos(b·t + e), a·cos(c·t + f), a·cos(d·t + g)).
    Lissajous,
}

/// knots3D's stock curves, by preset id (JWildfire's knots3d_wf presets 0-23): Fourier sums
/// Σ c·cos(k·t) / c·sin(k·t) per axis (terms (c, k, Cos|Sin)), torus knots and Lissajous knots.
#[rustfmt::skip]
static KNOT_CURVES: [KnotCurve; 24] = [
    KnotCurve::Fourier([
        &[(-10, 1, Cos), (-2, 5, Cos), (15, 2, Sin)],
        &[(-15, 2, Cos), (10, 1, Sin), (-2, 5, Sin)],
        &[(10, 3, Cos)],
    ]),
    KnotCurve::Fourier([
        &[(-22, 1, Cos), (-128, 1, Sin), (-44, 3, Cos), (-78, 3, Sin)],
        &[(-10, 2, Cos), (-27, 2, Sin), (38, 4, Cos), (46, 4, Sin)],
        &[(70, 3, Cos), (-40, 3, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-22, 1, Cos), (-128, 1, Sin), (-44, 3, Cos), (-78, 3, Sin)],
        &[(11, 1, Cos), (-43, 3, Cos), (34, 5, Cos), (-39, 5, Sin)],
        &[(70, 3, Cos), (-40, 3, Sin), (8, 5, Cos), (-9, 5, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(10, 1, Cos), (10, 3, Cos)],
        &[(6, 1, Sin), (10, 3, Sin)],
        &[(4, 3, Sin), (-10, 6, Sin)],
    ]),
    KnotCurve::Torus,
    KnotCurve::Torus,
    KnotCurve::Fourier([
        &[(41, 1, Cos), (-18, 1, Sin), (-83, 2, Cos), (-83, 2, Sin), (-11, 3, Cos), (27, 3, Sin)],
        &[(6, 1, Cos), (27, 1, Sin), (-113, 2, Cos), (30, 2, Sin), (11, 3, Cos), (-27, 3, Sin)],
        &[(45, 1, Sin), (-30, 2, Cos), (113, 2, Sin), (-11, 3, Cos), (27, 3, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(32, 1, Cos), (-51, 1, Sin), (-104, 2, Cos), (-34, 2, Sin), (104, 3, Cos), (-91, 3, Sin)],
        &[(94, 1, Cos), (41, 1, Sin), (113, 2, Cos), (-68, 3, Cos), (-124, 3, Sin)],
        &[(16, 1, Cos), (73, 1, Sin), (-211, 2, Cos), (-39, 2, Sin), (-99, 3, Cos), (-21, 3, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(88, 1, Cos), (115, 1, Sin), (-475, 2, Cos), (-127, 2, Sin), (-87, 3, Cos), (36, 3, Sin),
          (11, 4, Cos), (-19, 4, Sin)],
        &[(89, 1, Cos), (-32, 1, Sin), (-172, 2, Cos), (294, 2, Sin), (76, 3, Cos), (102, 3, Sin),
          (-61, 4, Cos), (113, 4, Sin)],
        &[(44, 1, Cos), (-69, 1, Sin), (34, 2, Cos), (223, 2, Sin), (16, 3, Cos), (120, 3, Sin),
          (42, 4, Cos), (-125, 4, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-33, 1, Cos), (43, 1, Sin), (214, 2, Sin), (-101, 3, Cos), (-47, 3, Sin), (11, 4, Sin)],
        &[(-57, 1, Cos), (99, 1, Sin), (-54, 2, Cos), (-159, 2, Sin), (-117, 3, Cos), (-5, 3, Sin),
          (-31, 4, Cos), (-45, 4, Sin)],
        &[(34, 1, Cos), (-21, 1, Sin), (-100, 2, Cos), (-93, 2, Sin), (-27, 3, Cos), (-16, 3, Sin),
          (52, 4, Cos), (84, 4, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(12, 1, Cos), (20, 1, Sin), (-163, 2, Cos), (76, 2, Sin), (-87, 3, Cos), (-15, 3, Sin),
          (-21, 4, Cos), (14, 4, Sin), (24, 5, Cos), (-50, 5, Sin)],
        &[(29, 1, Cos), (78, 1, Sin), (-180, 2, Cos), (58, 2, Sin), (88, 3, Cos), (72, 3, Sin),
          (-14, 4, Sin)],
        &[(-30, 1, Cos), (-78, 1, Sin), (-111, 2, Cos), (37, 2, Sin), (-67, 3, Cos), (-51, 3, Sin),
          (31, 4, Cos), (8, 4, Sin), (-11, 5, Cos), (65, 5, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-6, 1, Cos), (-21, 1, Sin), (-195, 2, Cos), (92, 2, Sin), (-64, 3, Cos), (-23, 3, Sin),
          (-6, 4, Cos), (13, 4, Sin), (24, 5, Cos), (15, 5, Sin), (41, 6, Sin)],
        &[(-21, 1, Cos), (-24, 1, Sin), (-207, 2, Cos), (-72, 2, Sin), (112, 3, Cos), (-7, 3, Sin),
          (-13, 4, Cos), (-40, 4, Sin), (-27, 5, Cos), (-3, 5, Sin), (-17, 6, Cos)],
        &[(-18, 1, Cos), (-13, 1, Sin), (113, 2, Cos), (-107, 2, Sin), (86, 3, Cos), (-9, 3, Sin),
          (-26, 4, Cos), (-7, 4, Sin), (24, 5, Cos), (33, 5, Sin), (21, 6, Cos), (31, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-40, 1, Cos), (32, 1, Sin), (69, 2, Cos), (-12, 2, Sin), (120, 3, Cos), (-52, 3, Sin),
          (-56, 4, Cos), (46, 4, Sin), (-17, 5, Sin), (14, 6, Cos), (19, 6, Sin)],
        &[(90, 1, Cos), (89, 1, Sin), (-142, 2, Cos), (147, 2, Sin), (74, 3, Cos), (85, 3, Sin),
          (-56, 4, Sin), (23, 5, Cos), (16, 6, Cos), (7, 6, Sin)],
        &[(52, 1, Cos), (64, 1, Sin), (53, 2, Cos), (35, 2, Sin), (77, 3, Cos), (-87, 3, Sin),
          (101, 4, Cos), (-19, 4, Sin), (-5, 5, Cos), (2, 5, Sin), (3, 6, Cos), (9, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(54, 1, Cos), (-4, 1, Sin), (-239, 2, Cos), (-44, 2, Sin), (-45, 3, Cos), (-17, 3, Sin),
          (-33, 4, Cos), (-27, 4, Sin), (19, 5, Cos), (19, 5, Sin), (-8, 6, Cos), (15, 6, Sin)],
        &[(-16, 1, Cos), (-43, 1, Sin), (11, 2, Cos), (170, 2, Sin), (-22, 3, Cos), (41, 3, Sin),
          (21, 4, Cos), (2, 5, Cos), (-12, 5, Sin), (-43, 6, Cos), (26, 6, Sin)],
        &[(-55, 1, Sin), (-78, 2, Cos), (189, 2, Sin), (-38, 3, Cos), (41, 3, Sin), (10, 4, Cos),
          (-16, 4, Sin), (-38, 5, Cos), (18, 5, Sin), (22, 6, Cos), (-15, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(10, 1, Cos), (115, 1, Sin), (-184, 2, Cos), (10, 2, Sin), (101, 3, Sin), (23, 4, Cos),
          (55, 4, Sin), (-38, 5, Cos), (-6, 5, Sin), (-14, 6, Cos), (8, 6, Sin), (16, 6, Cos),
          (14, 6, Sin)],
        &[(42, 1, Cos), (-104, 1, Sin), (-252, 2, Cos), (47, 2, Sin), (-21, 3, Cos), (-65, 3, Sin),
          (-23, 4, Cos), (-23, 4, Sin), (36, 5, Cos), (-10, 5, Sin), (-13, 6, Cos), (2, 6, Sin),
          (-18, 7, Cos), (-9, 7, Sin)],
        &[(30, 1, Sin), (20, 2, Cos), (19, 2, Sin), (6, 3, Cos), (-31, 3, Sin), (-4, 4, Cos),
          (-24, 4, Sin), (-44, 5, Cos), (-50, 5, Sin), (31, 6, Cos), (39, 6, Sin), (-16, 7, Cos),
          (23, 7, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-14, 1, Cos), (-19, 1, Sin), (-53, 2, Cos), (-120, 2, Sin), (71, 3, Cos), (-50, 3, Sin),
          (-47, 4, Cos), (-86, 4, Sin), (9, 5, Cos), (-5, 5, Sin), (12, 6, Cos), (22, 6, Sin)],
        &[(-11, 1, Cos), (13, 1, Sin), (-294, 2, Cos), (112, 2, Sin), (29, 3, Cos), (-22, 3, Sin),
          (4, 4, Cos), (11, 4, Sin), (-6, 5, Cos), (-14, 6, Cos), (18, 6, Sin)],
        &[(28, 1, Cos), (9, 1, Sin), (-39, 2, Cos), (-60, 2, Sin), (-60, 3, Cos), (21, 3, Sin),
          (50, 4, Cos), (-11, 4, Sin), (44, 5, Cos), (-63, 5, Sin), (14, 6, Cos), (9, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(32, 1, Cos), (10, 1, Sin), (-12, 2, Cos), (10, 2, Sin), (48, 3, Cos), (75, 3, Sin),
          (-32, 4, Cos), (12, 4, Sin), (3, 5, Cos), (-8, 5, Sin), (-2, 6, Cos), (-4, 6, Sin)],
        &[(-16, 1, Cos), (-10, 1, Sin), (-90, 2, Cos), (129, 2, Sin), (-6, 3, Cos), (-8, 3, Sin),
          (-19, 4, Cos), (-6, 4, Sin), (-8, 5, Cos), (6, 5, Sin), (4, 6, Cos), (13, 6, Sin)],
        &[(-12, 1, Cos), (1, 1, Sin), (-55, 2, Cos), (32, 2, Sin), (-10, 3, Cos), (-13, 3, Sin),
          (2, 4, Cos), (26, 4, Sin), (17, 5, Cos), (9, 5, Sin), (15, 6, Cos), (-21, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(5, 1, Cos), (5, 1, Sin), (-163, 2, Cos), (-80, 2, Sin), (-28, 3, Cos), (15, 3, Sin),
          (-20, 4, Cos), (13, 4, Sin), (-11, 5, Cos), (-12, 5, Sin), (4, 6, Cos), (-19, 6, Sin),
          (12, 7, Cos), (2, 7, Sin)],
        &[(-31, 1, Cos), (6, 1, Sin), (-113, 2, Cos), (81, 2, Sin), (87, 3, Cos), (4, 3, Sin),
          (5, 4, Cos), (18, 4, Sin), (-4, 5, Cos), (11, 5, Sin), (-17, 6, Cos), (5, 6, Sin),
          (-6, 7, Cos), (-13, 7, Sin)],
        &[(-11, 1, Cos), (-3, 1, Sin), (21, 2, Cos), (31, 2, Sin), (8, 3, Cos), (2, 3, Sin),
          (2, 4, Cos), (13, 4, Sin), (27, 5, Cos), (7, 5, Sin), (-8, 6, Cos), (-29, 6, Sin),
          (11, 7, Cos), (-8, 7, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-17, 1, Cos), (80, 1, Sin), (-70, 2, Cos), (-190, 2, Sin), (-26, 3, Cos), (-145, 3, Sin),
          (-62, 4, Cos), (-31, 4, Sin), (26, 5, Cos), (13, 5, Sin), (-2, 6, Cos), (8, 6, Sin),
          (-10, 7, Cos), (9, 7, Sin)],
        &[(102, 1, Cos), (-151, 1, Sin), (-36, 2, Cos), (-25, 2, Sin), (200, 3, Cos), (-18, 3, Sin),
          (-30, 4, Cos), (28, 4, Sin), (-7, 5, Cos), (2, 5, Sin), (13, 6, Cos), (-11, 6, Sin),
          (-5, 7, Cos), (-1, 7, Sin)],
        &[(58, 1, Cos), (-17, 1, Sin), (-5, 2, Cos), (-27, 2, Sin), (66, 3, Cos), (-38, 3, Sin),
          (28, 4, Cos), (-80, 4, Sin), (-35, 5, Cos), (28, 5, Sin), (-26, 6, Cos), (-34, 6, Sin),
          (32, 7, Cos), (1, 7, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-5, 1, Cos), (8, 2, Cos), (83, 2, Sin), (87, 3, Cos), (100, 3, Sin), (-5, 4, Cos),
          (22, 4, Sin), (-10, 5, Cos), (10, 5, Sin), (-2, 6, Cos), (-10, 6, Sin), (5, 7, Cos),
          (6, 7, Sin)],
        &[(17, 1, Cos), (21, 1, Sin), (-174, 2, Cos), (13, 2, Sin), (-15, 3, Cos), (3, 3, Sin),
          (-9, 4, Cos), (46, 4, Sin), (16, 5, Cos), (-25, 5, Sin), (-21, 6, Cos), (7, 6, Sin),
          (-9, 7, Cos), (-3, 7, Sin)],
        &[(-28, 1, Cos), (9, 1, Sin), (110, 2, Cos), (4, 2, Sin), (11, 3, Cos), (-6, 3, Sin),
          (-46, 4, Cos), (-17, 4, Sin), (32, 5, Cos), (-9, 5, Sin), (-12, 6, Cos), (-9, 6, Sin),
          (-9, 7, Cos), (18, 7, Sin)],
    ]),
    KnotCurve::Lissajous,
    KnotCurve::Lissajous,
    KnotCurve::Lissajous,
    KnotCurve::Lissajous,
];
/// Point `step` of `steps` along a knot curve (t = 2π·step/steps); `k` = params a…h.
fn knot_point(curve: &KnotCurve, k: &[f64], step: usize, steps: f64) -> [f64; 3] {
    let t = 2.0 * PI * step as f64 / steps;
    match curve {
        KnotCurve::Fourier(axes) => axes.map(|terms| {
            terms
                .iter()
                .fold(0.0, |s, &(c, m, f)| s + c as f64 * f.of(m as f64 * t))
        }),
        KnotCurve::Torus => {
            let ring = k[0] + k[1] * (k[2] * t).cos();
            let (sd, cd) = (k[3] * t).sin_cos();
            [ring * cd, ring * sd, k[1] * (k[2] * t).sin()]
        }
        KnotCurve::Lissajous => [
            k[0] * (k[1] * t + k[4]).cos(),
            k[0] * (k[2] * t + k[5]).cos(),
            k[0] * (k[3] * t + k[6]).cos(),
        ],
    }
}

/// An affine rotation through `angle` about the axis through `at` with direction `dir` (as in
/// Ammeraal's "Interactive 3D Computer Graphics"): rows of a 4×3 matrix.
struct AxisRotation([f64; 12]);

impl AxisRotation {
    fn new(at: [f64; 3], dir: [f64; 3], angle: f64) -> Self {
        let (sal, cal) = angle.sin_cos();
        let cal1 = 1.0 - cal;
        let [v1, v2, v3] = dir;
        let rho = (v1 * v1 + v2 * v2 + v3 * v3).sqrt();
        let (theta, cph, sph) = if rho == 0.0 {
            (0.0, 1.0, 0.0)
        } else {
            let theta = if v1 == 0.0 {
                if v2 >= 0.0 { 0.5 * PI } else { 1.5 * PI }
            } else if v1 < 0.0 {
                (v2 / v1).atan() + PI
            } else {
                (v2 / v1).atan()
            };
            let cph = v3 / rho;
            (theta, cph, (1.0 - cph * cph).sqrt())
        };
        let (sth, cth) = theta.sin_cos();
        let cph2 = cph * cph;
        let sph2 = 1.0 - cph2;
        let cth2 = cth * cth;
        let sth2 = 1.0 - cth2;
        let r11 = (cal * cph2 + sph2) * cth2 + cal * sth2;
        let r12 = sal * cph + cal1 * sph2 * cth * sth;
        let r13 = sph * (cph * cth * cal1 - sal * sth);
        let r21 = sph2 * cth * sth * cal1 - sal * cph;
        let r22 = sth2 * (cal * cph2 + sph2) + cal * cth2;
        let r23 = sph * (cph * sth * cal1 + sal * cth);
        let r31 = sph * (cph * cth * cal1 + sal * sth);
        let r32 = sph * (cph * sth * cal1 - sal * cth);
        let r33 = cal * sph2 + cph2;
        let [a1, a2, a3] = at;
        let r41 = a1 - a1 * r11 - a2 * r21 - a3 * r31;
        let r42 = a2 - a1 * r12 - a2 * r22 - a3 * r32;
        let r43 = a3 - a1 * r13 - a2 * r23 - a3 * r33;
        AxisRotation([r11, r12, r13, r21, r22, r23, r31, r32, r33, r41, r42, r43])
    }

    fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        let r = &self.0;
        [
            p[0] * r[0] + p[1] * r[3] + p[2] * r[6] + r[9],
            p[0] * r[1] + p[1] * r[4] + p[2] * r[7] + r[10],
            p[0] * r[2] + p[1] * r[5] + p[2] * r[8] + r[11],
        ]
    }
}

/// JWildfire's `Tools.FTOI`: round half away from zero, saturating.
fn ftoi(v: f64) -> i32 {
    if v > 0.0 {
        (v + 0.5) as i32
    } else if v < 0.0 {
        (-(v.abs() + 0.5)) as i32
    } else {
        0
    }
}

/// A mesh with single-precision vertices merged when they agree to 1e-4, as JWildfire stores
/// them.
#[derive(Default)]
struct KnotMesh {
    vertices: Vec<[f32; 3]>,
    index: std::collections::HashMap<(i32, i32, i32), usize>,
    faces: Vec<[usize; 3]>,
}

impl KnotMesh {
    fn add(&mut self, p: [f64; 3]) {
        let key = (ftoi(p[0] * 1e4), ftoi(p[1] * 1e4), ftoi(p[2] * 1e4));
        if !self.index.contains_key(&key) {
            self.index.insert(key, self.vertices.len());
            self.vertices.push([p[0] as f32, p[1] as f32, p[2] as f32]);
        }
    }
    fn get(&self, i: usize) -> Option<[f64; 3]> {
        self.vertices
            .get(i)
            .map(|v| [v[0] as f64, v[1] as f64, v[2] as f64])
    }
}

/// Sweeps a ring of `facets` points (radius `radius`) along the knot curve, rotating it from
/// one curve segment to the next about the intersection line of the segments' planes; then
/// joins consecutive rings with triangles.
fn knot_tube(curve: &KnotCurve, k: &[f64], steps: usize, radius: f64, facets: usize) -> KnotMesh {
    let mut mesh = KnotMesh::default();
    let pt = |i: usize| knot_point(curve, k, i, steps as f64);
    let (c0, c1, c2) = (pt(0), pt(1), pt(2));
    let n = facets;
    // Normal (a, b, c) of the plane of the current ring, and its offset d.
    let (mut a, mut b, mut c) = (c2[0] - c0[0], c2[1] - c0[1], c2[2] - c0[2]);
    let mut d = a * c1[0] + b * c1[1] + c * c1[2];
    let tiny = |x: f64| x.abs() < 1e-5;
    let (mut rx, mut ry, mut rz) = if tiny(a) && tiny(b) {
        (0.0, c, -b)
    } else {
        (b, -a, 0.0)
    };
    let len = (rx * rx + ry * ry + rz * rz).sqrt();
    rx /= len;
    ry /= len;
    rz /= len;
    mesh.add([
        c1[0] + rx * radius,
        c1[1] + ry * radius,
        c1[2] + rz * radius,
    ]);
    let turn = AxisRotation::new(c1, [a, b, c], 2.0 * PI / n as f64);
    for i in 1..n {
        let Some(prev) = mesh.get(i - 1) else { break };
        mesh.add(turn.apply(prev));
    }
    'rings: for j in 1..steps {
        let prev_ring = (j - 1) * n;
        let pa = pt(j - 1);
        let pb = pt(j);
        let (dx, dy, dz) = (pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]);
        let c1 = a * a + b * b + c * c;
        let c2 = a * dx + b * dy + c * dz;
        let c0 = d - a * pa[0] - b * pa[1] - c * pa[2];
        let mid = [
            0.5 * (pa[0] + pb[0]),
            0.5 * (pa[1] + pb[1]),
            0.5 * (pa[2] + pb[2]),
        ];
        let d0 = dx * mid[0] + dy * mid[1] + dz * mid[2];
        let e1 = dx * a + dy * b + dz * c;
        let e2 = dx * dx + dy * dy + dz * dz;
        let e0 = d0 - dx * pa[0] - dy * pa[1] - dz * pa[2];
        let denom = c1 * e2 - c2 * e1;
        if denom.abs() < 1e-12 {
            // Same direction: the ring is repeated (and merges with the previous one).
            for i in 0..n {
                let Some(v) = mesh.get(prev_ring + i) else {
                    break 'rings;
                };
                mesh.add(v);
            }
        } else {
            let lambda = (c0 * e2 - c2 * e0) / denom;
            let mu = (c1 * e0 - c0 * e1) / denom;
            let centre = [
                pa[0] + lambda * a + mu * dx,
                pa[1] + lambda * b + mu * dy,
                pa[2] + lambda * c + mu * dz,
            ];
            let ap = [pa[0] - centre[0], pa[1] - centre[1], pa[2] - centre[2]];
            let bp = [pb[0] - centre[0], pb[1] - centre[1], pb[2] - centre[2]];
            let axis = [
                ap[1] * bp[2] - bp[1] * ap[2],
                bp[0] * ap[2] - ap[0] * bp[2],
                ap[0] * bp[1] - bp[0] * ap[1],
            ];
            let cosphi = (ap[0] * bp[0] + ap[1] * bp[1] + ap[2] * bp[2])
                / ((ap[0] * ap[0] + ap[1] * ap[1] + ap[2] * ap[2])
                    * (bp[0] * bp[0] + bp[1] * bp[1] + bp[2] * bp[2]))
                    .sqrt();
            let phi = if cosphi == 0.0 {
                0.5 * PI
            } else {
                ((1.0 - cosphi * cosphi).sqrt() / cosphi).atan()
            };
            let rot = AxisRotation::new(centre, axis, phi);
            for i in 0..n {
                let Some(v) = mesh.get(prev_ring + i) else {
                    break 'rings;
                };
                mesh.add(rot.apply(v));
            }
            let normal = AxisRotation::new([0.0; 3], axis, phi).apply([a, b, c]);
            (a, b, c) = (normal[0], normal[1], normal[2]);
        }
        d = a * pb[0] + b * pb[1] + c * pb[2];
    }
    // Two triangles per quad between rings j-1 and j (vertex indices as JWildfire numbers them).
    for j in 1..steps {
        let cur = j * n;
        let prev = cur - n;
        for i in 0..n.saturating_sub(1) {
            mesh.faces.push([cur + i + 1, prev + i, prev + i + 1]);
            mesh.faces.push([prev + i, cur + i + 1, cur + i]);
        }
        mesh.faces.push([cur, prev + n - 1, prev]);
        mesh.faces.push([prev + n - 1, cur, cur + n - 1]);
    }
    mesh
}

/// knots3D's shared data: the count of triangles, then 9 coordinates per triangle (from
/// parameters 0–17: the curve, the tube and its placement).
fn knots3d_faces(q: &[f64], _: &[String]) -> Vec<f64> {
    let [
        preset,
        steps,
        radius,
        facets,
        curve_params @ ..,
        scale_x,
        scale_y,
        scale_z,
        offset_x,
        offset_y,
        offset_z,
    ] = params_of::<18>(q);
    let mut out = vec![0.0];
    if !(0.0..24.0).contains(&preset) {
        return out;
    }
    let curve = &KNOT_CURVES[preset as usize];
    let (steps, facets) = (steps as usize, facets as usize);
    let mesh = knot_tube(curve, &curve_params, steps, radius, facets);
    let (scale, offset) = ([scale_x, scale_y, scale_z], [offset_x, offset_y, offset_z]);
    let placed: Vec<[f64; 3]> = mesh
        .vertices
        .iter()
        .map(|p| std::array::from_fn(|i| (p[i] as f64 * scale[i] + offset[i]) as f32 as f64))
        .collect();
    let mut count = 0;
    for f in &mesh.faces {
        // Faces that point past the merged vertex list are left out.
        if f.iter().all(|&i| i < placed.len()) {
            for &i in f {
                out.extend_from_slice(&placed[i]);
            }
            count += 1;
        }
    }
    out[0] = count as f64;
    out
}

/// knots3D: a tube of `facets` sides and radius `radius` around one of JWildfire's stock knot
/// curves (preset id), as a triangle mesh scaled and offset; points are uniform on a random
/// triangle. Custom formulas (preset -1) are not supported and give no output.
fn knots3d(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q = v.data();
    let n = q[0] as usize;
    if n == 0 {
        return [0.0; 3];
    }
    let k = ((rng.f01() * n as f64) as usize).min(n - 1);
    let f = &q[1 + 9 * k..][..9];
    let s = rng.f01().sqrt();
    let r2 = rng.f01();
    let (a, b, c) = (1.0 - s, s * (1.0 - r2), r2 * s);
    [
        v.w * (a * f[0] + b * f[3] + c * f[6]),
        v.w * (a * f[1] + b * f[4] + c * f[7]),
        v.w * (a * f[2] + b * f[5] + c * f[8]),
    ]
}

#[cfg(test)]
mod tests {
    //! Reference numbers come from running JWildfire's own variation code (harness outside the
    //! project, JWildfire's random draws replayed from the same `FastRng` stream).

    use std::f64::consts::PI;

    use crate::flame::affine::Affine;
    use crate::flame::rng::FastRng;
    use crate::flame::variations::{
        Acc, Form, Prepared, VarId, all, eval_prepared, info, param_of, parse_name,
    };

    const PTS: [[f64; 3]; 6] = [
        [0.3, -0.7, 0.2],
        [-1.2, 0.4, -0.5],
        [0.05, 0.9, 1.1],
        [2.5, -1.5, 0.3],
        [-0.4, -0.3, -0.8],
        [0.7, 0.1, -0.25],
    ];

    /// The stream JWildfire's draws were replayed from.
    const SEED: u64 = 12345;

    fn make(name: &str, params: &[(&str, f64)], w: f64) -> Prepared {
        // Post-only variations are looked up directly: `parse_name` currently returns `None`
        // for them (see the slice's report).
        let (id, form) = parse_name(name)
            .or_else(|| {
                let i = all().iter().position(|d| d.name == name)?;
                Some((i as VarId, Form::Post))
            })
            .unwrap_or_else(|| panic!("{name} not registered"));
        let mut vals = info(id).defaults();
        for (k, val) in params {
            let (pid, _, idx) = param_of(k).unwrap_or_else(|| panic!("{k} unknown"));
            assert_eq!(pid, id, "{k}");
            vals[idx] = *val;
        }
        Prepared::new(id, form, w, &vals, Affine::default(), true)
    }

    fn run(v: &Prepared, pts: &[[f64; 3]], color: f64, rng: &mut FastRng) -> Vec<[f64; 4]> {
        pts.iter()
            .map(|p| {
                let acc = Acc {
                    x: 0.0,
                    y: 0.0,
                    z: 0.0,
                    color,
                    hide: false,
                };
                let a = eval_prepared(v, *p, acc, true, rng);
                [a.x, a.y, a.z, a.color]
            })
            .collect()
    }

    fn close(a: f64, b: f64) -> bool {
        if a.is_nan() || b.is_nan() {
            return a.is_nan() && b.is_nan();
        }
        a == b || (a - b).abs() <= 1e-9 * a.abs().max(b.abs()) || (a - b).abs() <= 1e-14
    }

    fn check(tag: &str, got: &[[f64; 4]], want: &[[f64; 4]]) {
        assert_eq!(got.len(), want.len(), "{tag}");
        for (i, (g, w)) in got.iter().zip(want).enumerate() {
            for k in 0..4 {
                assert!(
                    close(g[k], w[k]),
                    "{tag} row {i} comp {k}: got {g:?} want {w:?}"
                );
            }
        }
    }

    /// Runs `cases` (name, params, weight, colour, points, expected) on one random stream.
    #[allow(clippy::type_complexity)]
    fn run_cases(
        rng: &mut FastRng,
        cases: &[(&str, &[(&str, f64)], f64, f64, &[[f64; 3]], &[[f64; 4]])],
    ) {
        for (i, (name, params, w, color, pts, want)) in cases.iter().enumerate() {
            let v = make(name, params, *w);
            let got = run(&v, pts, *color, rng);
            check(&format!("{name} case {i}"), &got, want);
        }
    }

    #[test]
    fn rose_wf_matches_jwildfire() {
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("rose_wf", &[], 1.3, 0.5, &PTS, ROSE_DEF),
                (
                    "rose_wf",
                    &[
                        ("rose_wf_amp", 0.8),
                        ("rose_wf_waves", 5.0),
                        ("rose_wf_filled", 1.0),
                    ],
                    0.7,
                    0.5,
                    &PTS,
                    ROSE_FILLED,
                ),
            ],
        );
    }

    #[test]
    fn chrysanthemum_matches_jwildfire() {
        let mut rng = FastRng::new(SEED);
        run_cases(&mut rng, &[("chrysanthemum", &[], 0.9, 0.5, &PTS, CHRYS)]);
    }

    #[test]
    fn complex_matches_jwildfire() {
        let all: &[(&str, f64)] = &[
            ("complex_cospow", 0.3),
            ("complex_coshpow", 0.2),
            ("complex_cotpow", 0.1),
            ("complex_cothpow", 0.15),
            ("complex_cscpow", 0.05),
            ("complex_cschpow", 0.07),
            ("complex_exppow", 0.2),
            ("complex_secpow", 0.11),
            ("complex_sechpow", 0.13),
            ("complex_sinpow", 0.4),
            ("complex_sinhpow", 0.25),
            ("complex_tanpow", 0.09),
            ("complex_tanhpow", 0.12),
            ("complex_cosx1", 1.1),
            ("complex_cosy2", 0.9),
            ("complex_coshx2", 1.3),
            ("complex_cotx1", 1.7),
            ("complex_coty2", 2.2),
            ("complex_cothy1", 2.5),
            ("complex_cscx2", 0.8),
            ("complex_cschy1", 1.2),
            ("complex_expy2", 1.4),
            ("complex_secx1", 0.6),
            ("complex_sechy2", 1.5),
            ("complex_sinx2", 0.7),
            ("complex_sinhy1", 1.9),
            ("complex_tanx2", 2.3),
            ("complex_tanhy2", 1.6),
        ];
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("complex", &[], 1.1, 0.5, &PTS, COMPLEX_DEF),
                ("complex", all, 0.8, 0.5, &PTS, COMPLEX_ALL),
            ],
        );
    }

    #[test]
    fn exblur_matches_jwildfire() {
        let mut rng = FastRng::new(SEED);
        // JWildfire drew its four carried values first; the harness then replaced them.
        for _ in 0..4 {
            rng.f01();
        }
        let carried = [0.11, 0.52, 0.83, 0.27];
        let alt: &[(&str, f64)] = &[
            ("exblur_dist", 0.3),
            ("exblur_r", 0.4),
            ("exblur_x_origin", 0.2),
            ("exblur_y_origin", -0.1),
            ("exblur_z_origin", 0.3),
        ];
        for (params, w, want) in [(&[][..], 1.2, EXBLUR_DEF), (alt, 0.9, EXBLUR_ALT)] {
            let v = make("exblur", params, w);
            for (i, c) in carried.iter().enumerate() {
                v.state.set(i, *c);
            }
            check("exblur", &run(&v, &PTS, 0.0, &mut rng), want);
        }
    }

    #[test]
    fn glitchy1_matches_jwildfire() {
        let alt: &[(&str, f64)] = &[
            ("glitchy1_scale_x", 2.5),
            ("glitchy1_shift_x", 0.3),
            ("glitchy1_n_x", 3.0),
            ("glitchy1_scale_y", -1.5),
            ("glitchy1_shift_y", -0.2),
            ("glitchy1_n_y", 4.0),
            ("glitchy1_scale_z", 3.0),
            ("glitchy1_shift_z", 0.1),
            ("glitchy1_n_z", 2.0),
            ("glitchy1_width", 3.3),
            ("glitchy1_seed", 7.0),
            ("glitchy1_angle", 50.0),
            ("glitchy1_u", 1.2),
            ("glitchy1_v", 0.8),
            ("glitchy1_w", 1.5),
        ];
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("glitchy1", &[], 1.0, 0.5, &PTS, GLITCHY_DEF),
                ("glitchy1", alt, 0.6, 0.5, &PTS, GLITCHY_ALT),
            ],
        );
    }

    #[test]
    fn pyramid_matches_jwildfire() {
        let mut rng = FastRng::new(SEED);
        run_cases(&mut rng, &[("pyramid", &[], 1.4, 0.5, &PTS, PYRAMID)]);
    }

    #[test]
    fn rosoni_matches_jwildfire() {
        let file: &[(&str, f64)] = &[
            ("rosoni_maxiter", 8.0),
            ("rosoni_sweetiter", 4.0),
            ("rosoni_cutoff", 3.0),
            ("rosoni_radius", 1.536),
            ("rosoni_dx", 1.324),
            ("rosoni_dy", 0.0),
        ];
        let lemn: &[(&str, f64)] = &[
            ("rosoni_maxiter", 7.0),
            ("rosoni_sweetiter", 0.0),
            ("rosoni_altshapes", 1.0),
            ("rosoni_cutoff", 2.8),
            ("rosoni_radius", 0.9),
            ("rosoni_dx", 0.5),
            ("rosoni_dy", 0.2),
        ];
        let square: &[(&str, f64)] = &[
            ("rosoni_maxiter", 5.0),
            ("rosoni_sweetiter", 0.0),
            ("rosoni_cutoff", -2.6),
            ("rosoni_radius", -0.3),
            ("rosoni_dx", 0.7),
        ];
        let wedge: &[(&str, f64)] = &[
            ("rosoni_maxiter", 6.0),
            ("rosoni_sweetiter", 2.0),
            ("rosoni_altshapes", 1.0),
            ("rosoni_cutoff", 3.0),
            ("rosoni_radius", -0.4),
            ("rosoni_dx", -0.6),
            ("rosoni_dy", 0.3),
        ];
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("rosoni", &[], 1.0, 0.5, &PTS, ROSONI_DEF),
                ("rosoni", file, 1.0, 0.5, &PTS, ROSONI_FILE),
                ("rosoni", lemn, 0.8, 0.5, &PTS, ROSONI_LEMN),
                ("rosoni", square, 1.1, 0.5, &PTS, ROSONI_SQUARE),
                ("rosoni", wedge, 0.9, 0.5, &PTS, ROSONI_WEDGE),
            ],
        );
    }

    #[test]
    fn xheart_blur_wf_matches_jwildfire() {
        let alt: &[(&str, f64)] = &[
            ("xheart_blur_wf_angle", 0.7),
            ("xheart_blur_wf_ratio", -1.2),
        ];
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("xheart_blur_wf", &[], 1.0, 0.5, &PTS, XHB_DEF),
                ("xheart_blur_wf", alt, 0.7, 0.5, &PTS, XHB_ALT),
            ],
        );
    }

    #[test]
    fn epispiral_wf_matches_jwildfire() {
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("epispiral_wf", &[], 1.0, 0.5, &PTS, EPI_DEF),
                (
                    "epispiral_wf",
                    &[("epispiral_wf_waves", 3.0)],
                    0.6,
                    0.5,
                    &PTS,
                    EPI_3,
                ),
            ],
        );
    }

    #[test]
    fn post_mirror_wf_matches_jwildfire() {
        let all: &[(&str, f64)] = &[
            ("post_mirror_wf_xaxis", 1.0),
            ("post_mirror_wf_yaxis", 1.0),
            ("post_mirror_wf_zaxis", 1.0),
            ("post_mirror_wf_xshift", 0.2),
            ("post_mirror_wf_yshift", -0.3),
            ("post_mirror_wf_zshift", 0.4),
            ("post_mirror_wf_xscale", 1.1),
            ("post_mirror_wf_yscale", 0.9),
            ("post_mirror_wf_xcolorshift", 0.25),
            ("post_mirror_wf_ycolorshift", 0.5),
            ("post_mirror_wf_zcolorshift", 0.6),
        ];
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("post_mirror_wf", &[], 1.0, 0.3, &PTS, PM_DEF),
                ("post_mirror_wf", all, 1.0, 0.3, &PTS, PM_ALL),
            ],
        );
    }

    #[test]
    fn crop_stars_matches_jwildfire() {
        // A 7×7 grid around the star.
        let grid: Vec<[f64; 3]> = (0..49)
            .map(|k| {
                [
                    -0.33 + 0.11 * (k / 7) as f64,
                    -0.31 + 0.1 * (k % 7) as f64,
                    0.2,
                ]
            })
            .collect();
        let pts = &grid[..];
        let n5: &[(&str, f64)] = &[
            ("crop_stars_n", 5.0),
            ("crop_stars_r2", 0.7),
            ("crop_stars_radius", 0.28),
        ];
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("crop_stars", &[], 1.2, 0.5, pts, CS_DEF),
                (
                    "crop_stars",
                    &[("crop_stars_invert", 1.0)],
                    1.0,
                    0.5,
                    pts,
                    CS_INV,
                ),
                ("crop_stars", n5, 0.8, 0.5, pts, CS_N5),
            ],
        );
    }

    #[test]
    fn plane_wf_matches_jwildfire() {
        let pts: &[[f64; 3]] = &[[0.3, -0.7, 0.2], [-1.2, 0.4, -0.5]];
        let want = [
            PLANE_0, PLANE_1, PLANE_2, PLANE_3, PLANE_4, PLANE_5, PLANE_6, PLANE_7, PLANE_8,
            PLANE_9, PLANE_10, PLANE_11,
        ];
        let mut rng = FastRng::new(SEED);
        for (i, want) in want.iter().enumerate() {
            let params = [
                ("plane_wf_axis", (i / 4) as f64),
                ("plane_wf_color_mode", (i % 4) as f64),
                ("plane_wf_position", 1.5),
                ("plane_wf_size", 4.0),
            ];
            let v = make("plane_wf", &params, 0.9);
            check(
                &format!("plane_wf {i}"),
                &run(&v, pts, 0.42, &mut rng),
                want,
            );
        }
        let v = make("plane_wf", &[("plane_wf_direct_color", 0.0)], 1.0);
        check("plane_wf dc0", &run(&v, pts, 0.42, &mut rng), PLANE_12);
    }

    #[test]
    fn szubieta_matches_jwildfire() {
        let t1: &[(&str, f64)] = &[
            ("szubieta_width", 40.0),
            ("szubieta_height", 57.0),
            ("szubieta_type", 1.0),
            ("szubieta_scale", 0.8),
        ];
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("szubieta", &[], 1.0, 0.5, &PTS, SZUBIETA_DEF),
                ("szubieta", t1, 0.7, 0.5, &PTS, SZUBIETA_T1),
            ],
        );
    }

    #[test]
    fn snowflake_wf_matches_jwildfire() {
        let a: &[(&str, f64)] = &[
            ("snowflake_wf_buffer_size", 40.0),
            ("snowflake_wf_max_iter", 120.0),
        ];
        let b: &[(&str, f64)] = &[
            ("snowflake_wf_buffer_size", 30.0),
            ("snowflake_wf_max_iter", 90.0),
            ("snowflake_wf_jitter", 0.0),
            ("snowflake_wf_seed", 777.0),
            ("snowflake_wf_threshold", 0.55),
            ("snowflake_wf_rnd_bg_noise", 0.4),
            ("snowflake_wf_diffusion_asymmetry", 1.3),
            ("snowflake_wf_scale", 1.7),
            ("snowflake_wf_dc_color_scale", 1.5),
            ("snowflake_wf_dc_color_offset", 0.2),
        ];
        // Number of crystal cells JWildfire finds for these settings.
        assert_eq!(make("snowflake_wf", a, 1.0).data()[0], 200.0);
        assert_eq!(make("snowflake_wf", b, 1.0).data()[0], 94.0);
        let mut rng = FastRng::new(SEED);
        run_cases(
            &mut rng,
            &[
                ("snowflake_wf", a, 1.0, 0.5, &PTS, SNOW_A),
                ("snowflake_wf", b, 0.8, 0.5, &PTS, SNOW_B),
            ],
        );
    }

    #[test]
    fn snowflake_wf_default_crystal_size() {
        assert_eq!(make("snowflake_wf", &[], 1.0).data()[0], 1622.0);
    }

    #[test]
    fn nsudoku_layers_are_sudokus_and_points_stay_in_their_cells() {
        let v = make(
            "nsudoku",
            &[("nsudoku_Level", 4.0), ("nsudoku_angle", 30.0)],
            1.0,
        );
        let [_, _, _, _, _, _, _, _, _, layers] = v.derived();
        let layers = layers as usize;
        assert_eq!(layers, 4);
        for l in 0..layers {
            let d = &v.table(super::SUDOKU_LAYERS)[l * super::SUDOKU_LAYER_LEN + 2..][..81];
            let digit = |i: usize, j: usize| d[i * 9 + j] as usize;
            for a in 0..9 {
                let (mut row, mut col, mut bx) = (0u32, 0u32, 0u32);
                for b in 0..9 {
                    row |= 1 << digit(a, b);
                    col |= 1 << digit(b, a);
                    bx |= 1 << digit(3 * (a / 3) + b / 3, 3 * (a % 3) + b % 3);
                }
                assert_eq!((row, col, bx), (0x3fe, 0x3fe, 0x3fe), "layer {l} line {a}");
            }
        }
        let mut rng = FastRng::new(SEED);
        for _ in 0..2000 {
            let a = eval_prepared(&v, [0.0; 3], Acc::default(), true, &mut rng);
            let digit = a.color * 9.0;
            assert!((digit - digit.round()).abs() < 1e-12 && (1.0..=9.0).contains(&digit));
            // Nearest cell centre on the 9×9 grid of the unit square.
            let (ci, cj) = (((a.x + 0.5) * 9.0).round(), ((a.y + 0.5) * 9.0).round());
            let (dx, dy) = (a.x - (ci / 9.0 - 0.5), a.y - (cj / 9.0 - 0.5));
            // Largest polygon radius: size (0.5) / 9.
            assert!((dx * dx + dy * dy).sqrt() <= 0.5 / 9.0 + 1e-12, "{a:?}");
        }
    }

    #[test]
    fn polygon_sampler_fills_the_polygon() {
        // A square (4 sides, circumradius 1) without hole: points inside, quadrants balanced.
        let mut g = Vec::new();
        super::push_polygon(&mut g, 4.0);
        let g: [f64; 7] = g.try_into().unwrap();
        let mut rng = FastRng::new(SEED);
        let mut quad = [0usize; 4];
        for _ in 0..20000 {
            let (x, y) = super::polygon_point(g, 0.0, &mut rng);
            // Vertices at 45°, 135°, …: the square |x|, |y| ≤ 1/√2.
            assert!(x.abs() <= 0.5f64.sqrt() + 1e-12 && y.abs() <= 0.5f64.sqrt() + 1e-12);
            quad[(x < 0.0) as usize * 2 + (y < 0.0) as usize] += 1;
        }
        for q in quad {
            assert!((q as f64 - 5000.0).abs() < 300.0, "{quad:?}");
        }
    }

    #[test]
    fn polarplot3d_wf_matches_jwildfire() {
        let pts: &[[f64; 3]] = &PTS[..3];
        let want = [
            POLAR_0, POLAR_1, POLAR_2, POLAR_3, POLAR_4, POLAR_5, POLAR_6, POLAR_7, POLAR_8,
            POLAR_9,
        ];
        let mut rng = FastRng::new(SEED);
        for (i, want) in want.iter().enumerate() {
            let params = [
                ("polarplot3d_wf_preset_id", i as f64),
                ("polarplot3d_wf_param_a", 1.3),
                ("polarplot3d_wf_param_b", 0.7),
                ("polarplot3d_wf_param_c", 0.4),
                ("polarplot3d_wf_cylindrical", (i % 2) as f64),
                ("polarplot3d_wf_color_mode", (i % 6) as f64),
                ("polarplot3d_wf_tmin", 1.5),
                ("polarplot3d_wf_tmax", -2.0),
                ("polarplot3d_wf_umin", 0.2),
                ("polarplot3d_wf_umax", 2.9),
                ("polarplot3d_wf_rmin", 1.0),
                ("polarplot3d_wf_rmax", -1.5),
            ];
            let v = make("polarplot3d_wf", &params, 0.9);
            check(
                &format!("polarplot3d_wf {i}"),
                &run(&v, pts, 0.37, &mut rng),
                want,
            );
        }
        // A custom formula (unknown preset) draws nothing.
        let v = make("polarplot3d_wf", &[("polarplot3d_wf_preset_id", -1.0)], 1.0);
        assert_eq!(run(&v, pts, 0.37, &mut rng), vec![[0.0, 0.0, 0.0, 0.37]; 3]);
    }

    #[test]
    // The Lissajous presets use 1.5707963 (not π/2) for their phases.
    #[allow(clippy::approx_constant)]
    fn knots3d_matches_jwildfire() {
        const KNOT_PARAMS: [&str; 8] = [
            "knots3D_param_a",
            "knots3D_param_b",
            "knots3D_param_c",
            "knots3D_param_d",
            "knots3D_param_e",
            "knots3D_param_f",
            "knots3D_param_g",
            "knots3D_param_h",
        ];
        // (preset, steps, radius, facets, params a…h, scale, offset, weight, expected, faces)
        #[allow(clippy::type_complexity)]
        let cases: [(
            f64,
            f64,
            f64,
            f64,
            [f64; 8],
            f64,
            [f64; 3],
            f64,
            &[[f64; 4]],
            f64,
        ); 4] = [
            (
                0.0, 1000.0, 1.05, 4.0, [0.0; 8], 0.02, [0.0; 3], 1.0, KNOT_0, 7992.0,
            ),
            (
                4.0,
                300.0,
                2.5,
                5.0,
                [100.0, 25.0, 5.0, 3.0, 0.0, 0.0, 0.0, 0.0],
                0.01,
                [0.1, -0.2, 0.3],
                0.8,
                KNOT_4,
                2990.0,
            ),
            (
                21.0,
                200.0,
                3.0,
                3.0,
                [100.0, 1.0, 5.0, 3.0, 0.0, 1.5707963, 1.5707963, 0.0],
                0.015,
                [0.0; 3],
                1.2,
                KNOT_21,
                1194.0,
            ),
            (
                14.0, 500.0, 1.0, 6.0, [0.0; 8], 0.005, [0.0; 3], 1.0, KNOT_14, 5988.0,
            ),
        ];
        let mut rng = FastRng::new(SEED);
        for (preset, steps, radius, facets, k, scale, off, w, want, faces) in cases {
            let mut params = vec![
                ("knots3D_presetId", preset),
                ("knots3D_steps", steps),
                ("knots3D_radius", radius),
                ("knots3D_facets", facets),
                ("knots3D_scale_x", scale),
                ("knots3D_scale_y", scale),
                ("knots3D_scale_z", scale),
                ("knots3D_offset_x", off[0]),
                ("knots3D_offset_y", off[1]),
                ("knots3D_offset_z", off[2]),
            ];
            params.extend(KNOT_PARAMS.iter().copied().zip(k));
            let v = make("knots3D", &params, w);
            assert_eq!(v.data()[0], faces, "preset {preset}");
            check("knots3D", &run(&v, &PTS, 0.5, &mut rng), want);
        }
        // A custom formula (preset -1) draws nothing.
        let v = make("knots3D", &[("knots3D_presetId", -1.0)], 1.0);
        assert_eq!(
            run(&v, &PTS[..1], 0.5, &mut rng),
            vec![[0.0, 0.0, 0.0, 0.5]]
        );
    }

    #[test]
    fn julian2dc_is_a_root_of_the_affine_image() {
        let params: &[(&str, f64)] = &[
            ("julian2dc_power", 2.0),
            ("julian2dc_a", 0.9),
            ("julian2dc_b", -0.3),
            ("julian2dc_c", 0.2),
            ("julian2dc_d", 1.1),
            ("julian2dc_e", 0.05),
            ("julian2dc_f", -0.4),
        ];
        let w = 0.8;
        let mut rng = FastRng::new(SEED);
        let mut branches = [0usize; 2];
        for col in [0.0, 1.0, 0.35] {
            let mut p = params.to_vec();
            p.push(("julian2dc_col", col));
            let v = make("julian2dc", &p, w);
            for pt in PTS {
                let a = eval_prepared(&v, pt, Acc::default(), true, &mut rng);
                let (x, y) = (
                    0.9 * pt[0] - 0.3 * pt[1] + 0.05,
                    0.2 * pt[0] + 1.1 * pt[1] - 0.4,
                );
                // (out / w)² is the affine image.
                let (ox, oy) = (a.x / w, a.y / w);
                assert!((ox * ox - oy * oy - x).abs() < 1e-12 && (2.0 * ox * oy - y).abs() < 1e-12);
                let angle = oy.atan2(ox);
                let branch = ((angle - 0.5 * y.atan2(x)) / PI).round();
                branches[branch.rem_euclid(2.0) as usize] += 1;
                let r = w * (x * x + y * y).sqrt().sqrt();
                let want = (r * col + angle / (2.0 * PI) * (1.0 - col)).abs() % 1.0;
                // The colour uses the branch angle (before wrapping into (-π, π]).
                let alt = (r * col + (angle + 2.0 * PI) / (2.0 * PI) * (1.0 - col)).abs() % 1.0;
                assert!(
                    (a.color - want).abs() < 1e-12 || (a.color - alt).abs() < 1e-12,
                    "{a:?} {want} {alt}"
                );
            }
        }
        assert!(branches[0] > 0 && branches[1] > 0, "{branches:?}");
    }

    #[test]
    fn names_and_parameters_resolve() {
        for d in super::DEFS {
            let (id, form) = parse_name(d.name)
                .or_else(|| {
                    Some((
                        all().iter().position(|e| e.name == d.name)? as VarId,
                        Form::Post,
                    ))
                })
                .unwrap();
            assert_eq!(info(id).name, d.name);
            if d.has(crate::flame::variations::flag::POST_ONLY) {
                assert_eq!(form, Form::Post);
            }
            for (k, p) in d.params.iter().enumerate() {
                assert!(p.name.starts_with(d.name), "{}", p.name);
                let (pid, _, pk) = param_of(p.name).unwrap();
                assert_eq!((pid, pk), (id, k), "{}", p.name);
            }
            // Defaults give finite output at an ordinary point.
            let v = make(d.name, &[], 1.0);
            let mut rng = FastRng::new(SEED);
            let a = eval_prepared(&v, [0.3, -0.2, 0.1], Acc::default(), true, &mut rng);
            assert!(
                a.x.is_finite() && a.y.is_finite() && a.z.is_finite(),
                "{} {a:?}",
                d.name
            );
        }
    }

    // rose default w1.3 (randoms used: 0)
    const ROSE_DEF: &[[f64; 4]] = &[
        [-0.012482698343798915, 0.029126296135530798, 0.0, 0.5],
        [-0.17266036024519352, 0.057553453415064515, 0.0, 0.5],
        [0.03517072327241479, 0.6330730189034662, 0.0, 0.5],
        [-0.31050738642151443, 0.18630443185290857, 0.0, 0.5],
        [0.4384639999999999, 0.3288479999999998, 0.0, 0.5],
        [0.5425715184858123, 0.07751021692654458, 0.0, 0.5],
    ];

    // rose amp0.8 waves5 filled1 w0.7 (randoms used: 6)
    const ROSE_FILLED: &[[f64; 4]] = &[
        [0.053467561705904436, -0.12475764398044367, 0.0, 0.5],
        [-0.10880685912994624, 0.03626895304331541, 0.0, 0.5],
        [0.0025430482359702195, 0.04577486824746394, 0.0, 0.5],
        [-0.03586342158132896, 0.021518052948797366, 0.0, 0.5],
        [-0.009024571168785194, -0.006768428376588894, 0.0, 0.5],
        [0.2620478914216858, 0.037435413060240806, 0.0, 0.5],
    ];

    // chrys w0.9 (randoms used: 6)
    const CHRYS: &[[f64; 4]] = &[
        [0.012918840223207814, -0.03451497162799062, 0.0, 0.5],
        [0.01153248819748011, 0.016307452617299285, 0.0, 0.5],
        [2.775276203593209, -2.1866069044488428, 0.0, 0.5],
        [3.3214620004502606, -5.0175517701701295, 0.0, 0.5],
        [1.476769835397269, -5.914538110730877, 0.0, 0.5],
        [0.13090436820618584, 0.12123534715915193, 0.0, 0.5],
    ];

    // complex default w1.1 (randoms used: 0)
    const COMPLEX_DEF: &[[f64; 4]] = &[
        [1.3190196262086173, 0.2465944935712972, 0.0, 0.5],
        [0.4309084527947695, 0.42112094453018534, 0.0, 0.5],
        [1.5744249406989892, -0.05643489851268651, 0.0, 0.5],
        [-2.073079738843681, 1.4017458849758095, 0.0, 0.5],
        [1.05910258398233, -0.1304443666608831, 0.0, 0.5],
        [0.8455365447384112, -0.07098211123948986, 0.0, 0.5],
    ];

    // complex all w0.8 (randoms used: 0)
    const COMPLEX_ALL: &[[f64; 4]] = &[
        [1.0435311306747272, -0.5267576236970796, 0.0, 0.5],
        [-0.3766181757947312, 0.4239493204625466, 0.0, 0.5],
        [0.6510528938770723, 0.6452602713770216, 0.0, 0.5],
        [-0.5247145698150242, -2.968305202730588, 0.0, 0.5],
        [-0.04680711096401241, -0.24145827632598033, 0.0, 0.5],
        [1.833248564503797, 0.10924949317626463, 0.0, 0.5],
    ];

    // exblur default w1.2 state .11 .52 .83 .27 (used 22)
    const EXBLUR_DEF: &[[f64; 4]] = &[
        [-0.0972, 0.2268, -0.0648, 0.0],
        [
            0.20980154634124654,
            -0.06993384878041553,
            0.0874173109755194,
            0.0,
        ],
        [
            0.006012539806032687,
            0.10822571650858816,
            0.13227587573271893,
            0.0,
        ],
        [
            -1.4634020137134278,
            0.8780412082280568,
            -0.17560824164561142,
            0.0,
        ],
        [
            -0.04716236284589302,
            -0.03537177213441976,
            -0.094324725691786,
            0.0,
        ],
        [
            0.32658897471610393,
            0.04665556781658629,
            -0.11663891954146571,
            0.0,
        ],
    ];

    // exblur alt w0.9 (used 40)
    const EXBLUR_ALT: &[[f64; 4]] = &[
        [
            -0.01824104208971019,
            0.21033425009548132,
            0.11181984091737478,
            0.0,
        ],
        [
            0.18868962745414072,
            -0.10195722597673287,
            0.06648157854053659,
            0.0,
        ],
        [
            -0.023631008516208155,
            -0.09158409153335974,
            -0.17741927455280918,
            0.0,
        ],
        [
            -1.4307257974582346,
            0.6952539306025697,
            -0.5880264153227732,
            0.0,
        ],
        [
            0.13344504218449504,
            0.009298350185932216,
            0.4481331376489121,
            0.0,
        ],
        [
            0.07808168305070683,
            -0.02074107837421534,
            -0.04859444778976931,
            0.0,
        ],
    ];

    // glitchy1 default w1.0 (randoms used: 0)
    const GLITCHY_DEF: &[[f64; 4]] = &[
        [
            0.29691076869932503,
            -0.6927917936317584,
            0.1979405124662167,
            0.5,
        ],
        [
            1.3631178467362737,
            0.4543726155787579,
            -0.5679657694734473,
            0.5,
        ],
        [
            0.06384136996410852,
            1.1491446593539534,
            1.4045101392103876,
            0.5,
        ],
        [
            2.8398288473672366,
            1.7038973084203421,
            0.3407794616840684,
            0.5,
        ],
        [
            -0.2954349437241605,
            -0.2215762077931204,
            -0.590869887448321,
            0.5,
        ],
        [
            0.6927917936317584,
            0.09897025623310834,
            -0.24742564058277086,
            0.5,
        ],
    ];

    // glitchy1 alt w0.6 (randoms used: 0)
    const GLITCHY_ALT: &[[f64; 4]] = &[
        [
            0.1945924455833586,
            -0.4540490396945034,
            0.1297282970555724,
            0.5,
        ],
        [
            -0.7630581370196576,
            0.2543527123398859,
            0.44511724659480023,
            0.5,
        ],
        [
            0.02698428842564313,
            0.4857171916615764,
            -0.4857171916615764,
            0.5,
        ],
        [
            -1.5499648936325519,
            -1.2236564949730673,
            0.24473129899461346,
            0.5,
        ],
        [
            -0.23752861495946,
            -0.17814646121959501,
            -0.47505722991892,
            0.5,
        ],
        [
            0.35986248775378915,
            0.051408926821969875,
            0.23134017069886448,
            0.5,
        ],
    ];

    // pyramid w1.4 (randoms used: 0)
    const PYRAMID: &[[f64; 4]] = &[
        [
            0.09999999973544973,
            -1.2703703670096018,
            0.029629629551244374,
            0.5,
        ],
        [
            -1.2619718303276097,
            0.046739697419541114,
            0.09128847152254121,
            0.5,
        ],
        [
            8.494630176084153E-5,
            0.4954068318692278,
            0.9045082211494407,
            0.5,
        ],
        [
            1.1496820307379154,
            -0.24833131863938973,
            0.001986650549115118,
            0.5,
        ],
        [
            -0.1485903811797838,
            -0.06268656706022127,
            1.1887230494382703,
            0.5,
        ],
        [
            1.3352798016398195,
            0.003892944028104432,
            0.06082725043913174,
            0.5,
        ],
    ];

    // rosoni default w1 (randoms used: 0)
    const ROSONI_DEF: &[[f64; 4]] = &[
        [0.6978735623765054, -0.30491390741638147, 0.0, 0.5],
        [-1.2, 0.4, 0.0, 0.5],
        [0.05, 0.9, 0.0, 0.5],
        [2.5, -1.5, 0.0, 0.5],
        [-0.4, -0.3, 0.0, 0.5],
        [0.44182332860211915, 0.5520798368922232, 0.0, 0.5],
    ];

    // rosoni file w1 (randoms used: 0)
    const ROSONI_FILE: &[[f64; 4]] = &[
        [-0.2999999999999997, 0.7, 0.0, 0.5],
        [1.1999999999999997, -0.4000000000000004, 0.0, 0.5],
        [0.05, 0.9, 0.0, 0.5],
        [-2.499999999999999, 1.5000000000000004, 0.0, 0.5],
        [-0.4, -0.3, 0.0, 0.5],
        [-0.7, -0.09999999999999964, 0.0, 0.5],
    ];

    // rosoni alt1 w0.8 (randoms used: 0)
    const ROSONI_LEMN: &[[f64; 4]] = &[
        [-0.24, 0.5599999999999999, 0.0, 0.5],
        [-0.96, 0.32000000000000006, 0.0, 0.5],
        [-0.04000000000000001, -0.7200000000000001, 0.0, 0.5],
        [2.0, -1.2000000000000002, 0.0, 0.5],
        [0.32000000000000006, 0.24, 0.0, 0.5],
        [0.5599999999999999, 0.08000000000000002, 0.0, 0.5],
    ];

    // rosoni sq w1.1 (randoms used: 0)
    const ROSONI_SQUARE: &[[f64; 4]] = &[
        [0.33, 0.77, 0.0, 0.5],
        [-1.32, -0.44000000000000006, 0.0, 0.5],
        [0.05500000000000001, -0.9900000000000001, 0.0, 0.5],
        [2.75, 1.6500000000000001, 0.0, 0.5],
        [-0.44000000000000006, -0.33, 0.0, 0.5],
        [0.77, 0.11000000000000001, 0.0, 0.5],
    ];

    // rosoni ang w0.9 (randoms used: 0)
    const ROSONI_WEDGE: &[[f64; 4]] = &[
        [0.41059600438419647, 0.5488268590217983, 0.0, 0.5],
        [-1.08, 0.36000000000000004, 0.0, 0.5],
        [0.045000000000000005, 0.81, 0.0, 0.5],
        [0.044134295108992805, 2.623557158514987, 0.0, 0.5],
        [0.41382685902179844, -0.17676914536239804, 0.0, 0.5],
        [-0.39294228634059936, 0.5005960043841964, 0.0, 0.5],
    ];

    // xhb default w1 (randoms used: 12)
    const XHB_DEF: &[[f64; 4]] = &[
        [-1.0311506215519455, -0.8104133406209412, 0.0, 0.5],
        [-0.0963024681046114, -1.2087795673945796, 0.0, 0.5],
        [1.138250521562202, -0.20672059857792147, 0.0, 0.5],
        [1.233276103535395, -0.3194055755841843, 0.0, 0.5],
        [1.0769644055389467, -0.6211947884457614, 0.0, 0.5],
        [-0.400705596526807, -1.2352809248198737, 0.0, 0.5],
    ];

    // xhb alt w0.7 (randoms used: 24)
    const XHB_ALT: &[[f64; 4]] = &[
        [0.10734604103181057, 0.5749371592824896, 0.0, 0.5],
        [0.3995672774944551, -0.4627607692492766, 0.0, 0.5],
        [0.33691611565606644, 0.0779334455634745, 0.0, 0.5],
        [0.5070637423925365, -0.33447874312117987, 0.0, 0.5],
        [0.08777666061154832, -0.5959803958429699, 0.0, 0.5],
        [-0.009331342103298819, -0.061872646537246806, 0.0, 0.5],
    ];

    // episp default w1 (randoms used: 0)
    const EPI_DEF: &[[f64; 4]] = &[
        [-4.040074757379, 9.426841100550998, 0.0, 0.5],
        [-1.6940773179473458, 0.564692439315782, 0.0, 0.5],
        [0.028432739135175057, 0.511789304433151, 0.0, 0.5],
        [-0.7696132159345513, 0.4617679295607306, 0.0, 0.5],
        [0.4743833017077802, 0.355787476280835, 0.0, 0.5],
        [0.5870193866586613, 0.08385991237980872, 0.0, 0.5],
    ];

    // episp 3 w0.6 (randoms used: 0)
    const EPI_3: &[[f64; 4]] = &[
        [-0.3389610389610384, 0.7909090909090896, 0.0, 0.5],
        [0.3461538461538461, -0.11538461538461539, 0.0, 0.5],
        [0.01687435098650052, 0.3037383177570093, 0.0, 0.5],
        [0.2575757575757576, -0.1545454545454545, 0.0, 0.5],
        [-0.2564102564102564, -0.1923076923076922, 0.0, 0.5],
        [-0.7191780821917814, -0.1027397260273973, 0.0, 0.5],
    ];

    // pm default (randoms used: 6)
    const PM_DEF: &[[f64; 4]] = &[
        [0.3, -0.7, 0.2, 0.3],
        [1.2, 0.4, -0.5, 0.3],
        [-0.05, 0.9, 1.1, 0.3],
        [-2.5, -1.5, 0.3, 0.3],
        [0.4, -0.3, -0.8, 0.3],
        [0.7, 0.1, -0.25, 0.3],
    ];

    // pm all (randoms used: 24)
    const PM_ALL: &[[f64; 4]] = &[
        [-0.55, -0.63, -0.6000000000000001, 0.1499999999999999],
        [
            -1.32,
            -0.09000000000000004,
            0.09999999999999998,
            0.3999999999999999,
        ],
        [-0.30250000000000005, -0.459, 1.1, 0.050000000000000044],
        [2.75, 1.62, 0.3, 0.8],
        [-0.4, -0.3, -0.8, 0.3],
        [0.77, 0.18, -0.15000000000000002, 0.3999999999999999],
    ];

    // cs default w1.2 (randoms used: 0)
    const CS_DEF: &[[f64; 4]] = &[
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [-0.264, -0.13199999999999998, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [-0.132, -0.13199999999999998, 0.0, 0.5],
        [-0.132, -0.011999999999999943, 0.0, 0.5],
        [-0.132, 0.10800000000000003, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, -0.13199999999999998, 0.0, 0.5],
        [0.0, -0.011999999999999943, 0.0, 0.5],
        [0.0, 0.10800000000000003, 0.0, 0.5],
        [0.0, 0.22799999999999998, 0.0, 0.5],
        [0.0, 0.3480000000000001, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.13199999999999998, -0.13199999999999998, 0.0, 0.5],
        [0.13199999999999998, -0.011999999999999943, 0.0, 0.5],
        [0.13199999999999998, 0.10800000000000003, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.264, -0.13199999999999998, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
    ];

    // cs invert w1 (randoms used: 0)
    const CS_INV: &[[f64; 4]] = &[
        [-0.33, -0.31, 0.0, 0.5],
        [-0.33, -0.21, 0.0, 0.5],
        [-0.33, -0.10999999999999999, 0.0, 0.5],
        [-0.33, -0.009999999999999953, 0.0, 0.5],
        [-0.33, 0.09000000000000002, 0.0, 0.5],
        [-0.33, 0.19, 0.0, 0.5],
        [-0.33, 0.2900000000000001, 0.0, 0.5],
        [-0.22000000000000003, -0.31, 0.0, 0.5],
        [-0.22000000000000003, -0.21, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [-0.22000000000000003, -0.009999999999999953, 0.0, 0.5],
        [-0.22000000000000003, 0.09000000000000002, 0.0, 0.5],
        [-0.22000000000000003, 0.19, 0.0, 0.5],
        [-0.22000000000000003, 0.2900000000000001, 0.0, 0.5],
        [-0.11000000000000001, -0.31, 0.0, 0.5],
        [-0.11000000000000001, -0.21, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [-0.11000000000000001, 0.19, 0.0, 0.5],
        [-0.11000000000000001, 0.2900000000000001, 0.0, 0.5],
        [0.0, -0.31, 0.0, 0.5],
        [0.0, -0.21, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.10999999999999999, -0.31, 0.0, 0.5],
        [0.10999999999999999, -0.21, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.10999999999999999, 0.19, 0.0, 0.5],
        [0.10999999999999999, 0.2900000000000001, 0.0, 0.5],
        [0.22000000000000003, -0.31, 0.0, 0.5],
        [0.22000000000000003, -0.21, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.22000000000000003, -0.009999999999999953, 0.0, 0.5],
        [0.22000000000000003, 0.09000000000000002, 0.0, 0.5],
        [0.22000000000000003, 0.19, 0.0, 0.5],
        [0.22000000000000003, 0.2900000000000001, 0.0, 0.5],
        [0.33, -0.31, 0.0, 0.5],
        [0.33, -0.21, 0.0, 0.5],
        [0.33, -0.10999999999999999, 0.0, 0.5],
        [0.33, -0.009999999999999953, 0.0, 0.5],
        [0.33, 0.09000000000000002, 0.0, 0.5],
        [0.33, 0.19, 0.0, 0.5],
        [0.33, 0.2900000000000001, 0.0, 0.5],
    ];

    // cs n5 w0.8 (randoms used: 0)
    const CS_N5: &[[f64; 4]] = &[
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [-0.08800000000000002, -0.088, 0.0, 0.5],
        [-0.08800000000000002, -0.007999999999999964, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, -0.007999999999999964, 0.0, 0.5],
        [0.0, 0.07200000000000002, 0.0, 0.5],
        [0.0, 0.15200000000000002, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.088, -0.088, 0.0, 0.5],
        [0.088, -0.007999999999999964, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
        [0.0, 0.0, 0.0, 0.5],
    ];

    // plane ax0 cm0 w0.9 (randoms used: 4)
    const PLANE_0: &[[f64; 4]] = &[
        [-0.19097210409481366, 1.0621596351947589, 1.35, 0.42],
        [1.4935563351850878, 1.168092085251397, 1.35, 0.42],
    ];

    // plane ax0 cm1 w0.9 (randoms used: 8)
    const PLANE_1: &[[f64; 4]] = &[
        [
            0.843791199057841,
            -0.8121941952048654,
            1.35,
            0.7343864441827336,
        ],
        [
            0.9565038658531165,
            -1.0834109669391256,
            1.35,
            0.7656955182925324,
        ],
    ];

    // plane ax0 cm2 w0.9 (randoms used: 12)
    const PLANE_2: &[[f64; 4]] = &[
        [
            0.38537757648614634,
            -0.9572562542150777,
            1.35,
            0.23409548494025623,
        ],
        [
            0.8575489989704409,
            1.1206806273392327,
            1.35,
            0.811300174260898,
        ],
    ];

    // plane ax0 cm3 w0.9 (randoms used: 16)
    const PLANE_3: &[[f64; 4]] = &[
        [
            0.9288348048180752,
            0.34880639104125793,
            1.35,
            0.4524488941889586,
        ],
        [
            -0.4185450029286159,
            -1.2818001378003117,
            1.35,
            0.055236866444248627,
        ],
    ];

    // plane ax1 cm0 w0.9 (randoms used: 20)
    const PLANE_4: &[[f64; 4]] = &[
        [1.35, 0.3231181972750376, -0.3949144298736759, 0.42],
        [1.35, -0.08944544730027566, -1.3662847565262228, 0.42],
    ];

    // plane ax1 cm1 w0.9 (randoms used: 24)
    const PLANE_5: &[[f64; 4]] = &[
        [
            1.35,
            -0.8512703032919801,
            -0.7291530225682036,
            0.2635360268633389,
        ],
        [
            1.35,
            0.06368407016108568,
            0.05493947295702455,
            0.5176900194891905,
        ],
    ];

    // plane ax1 cm2 w0.9 (randoms used: 28)
    const PLANE_6: &[[f64; 4]] = &[
        [
            1.35,
            1.3649697816521245,
            -0.29351314845835,
            0.41846856987268055,
        ],
        [
            1.35,
            -1.3361983446492658,
            -0.28130292140313135,
            0.4218602996102413,
        ],
    ];

    // plane ax1 cm3 w0.9 (randoms used: 32)
    const PLANE_7: &[[f64; 4]] = &[
        [
            1.35,
            -1.3721288230975828,
            1.208213329348534,
            0.0993154149384179,
        ],
        [
            1.35,
            1.526505994770052,
            -0.6059280396427654,
            0.30648823567246675,
        ],
    ];

    // plane ax2 cm0 w0.9 (randoms used: 36)
    const PLANE_8: &[[f64; 4]] = &[
        [-1.5718173477739292, 1.35, -1.2121798527582013, 0.42],
        [1.15160475115098, 1.35, 0.510450974411489, 0.42],
    ];

    // plane ax2 cm1 w0.9 (randoms used: 40)
    const PLANE_9: &[[f64; 4]] = &[
        [
            -0.42810528981748286,
            1.35,
            0.42703035168388265,
            0.6186195421344118,
        ],
        [
            -1.1234907488128552,
            1.35,
            -0.4062331896316582,
            0.3871574473245394,
        ],
    ];

    // plane ax2 cm2 w0.9 (randoms used: 44)
    const PLANE_10: &[[f64; 4]] = &[
        [
            1.769978868543426,
            1.35,
            -1.4929994193573088,
            0.9916607968176183,
        ],
        [
            0.3816924218552777,
            1.35,
            -1.5582063690780552,
            0.6060256727375771,
        ],
    ];

    // plane ax2 cm3 w0.9 (randoms used: 48)
    const PLANE_11: &[[f64; 4]] = &[
        [
            0.24674049722411442,
            1.35,
            0.3207015811365995,
            0.33491711486415815,
        ],
        [
            1.2454449861409982,
            1.35,
            0.6770302454202775,
            0.5820724800489807,
        ],
    ];

    // plane default dc0 w1 (randoms used: 52)
    const PLANE_12: &[[f64; 4]] = &[
        [0.13907038192763732, 3.0, 4.270619752057109, 0.42],
        [2.6787480802855113, 3.0, 0.5315505950110289, 0.42],
    ];

    // szubieta default w1 (randoms used: 30)
    const SZUBIETA_DEF: &[[f64; 4]] = &[
        [
            0.6056063247817902,
            3.67506021185556,
            0.0,
            0.4117647058823529,
        ],
        [
            2.842226004324767,
            4.809902159067757,
            0.0,
            0.4117647058823529,
        ],
        [
            -3.09165033743555,
            0.06194993810529619,
            0.0,
            0.0784313725490196,
        ],
        [
            4.463303199222472,
            0.9282855193692754,
            0.0,
            0.6352941176470588,
        ],
        [
            3.013242458686671,
            -2.9890201677723307,
            0.0,
            0.19607843137254902,
        ],
        [
            1.0148164640495627,
            -0.8863285688125052,
            0.0,
            0.3411764705882353,
        ],
    ];

    // szubieta t1 w0.7 (randoms used: 60)
    const SZUBIETA_T1: &[[f64; 4]] = &[
        [
            -1.1887512302978032,
            -1.8784734333037125,
            0.0,
            0.00784313725490196,
        ],
        [
            -0.46168307739178865,
            -0.7231673475956977,
            0.0,
            0.047058823529411764,
        ],
        [-1.3842373211304981, -0.6980791889948968, 0.0, 0.0],
        [-0.27382911207331967, -0.30129857163865287, 0.0, 0.0],
        [
            -0.8216957631040593,
            -0.8572377764476694,
            0.0,
            0.03137254901960784,
        ],
        [0.8434785672999937, 0.6298011610214586, 0.0, 0.0],
    ];

    // snow b40 i120 w1 (randoms used: 6)
    const SNOW_A: &[[f64; 4]] = &[
        [
            -0.006852034922374664,
            -0.01967848568027235,
            0.0,
            0.7934069991111755,
        ],
        [
            -0.0687080960157103,
            -0.006685208798298107,
            0.0,
            0.8090435028076172,
        ],
        [
            -0.10773120662260748,
            0.01981677627470578,
            0.0,
            0.7314254999160766,
        ],
        [
            -0.0691047206870712,
            -0.11837512530162894,
            0.0,
            0.8431183457374573,
        ],
        [
            -0.05793876165702347,
            -0.08179423003396345,
            0.0,
            0.8062153220176697,
        ],
        [
            0.03256946099723052,
            0.01920875936359536,
            0.0,
            0.8314956188201904,
        ],
    ];

    // snow b30 nojitter w0.8 (randoms used: 12)
    const SNOW_B: &[[f64; 4]] = &[
        [
            -0.08067796610169492,
            0.05773338721782807,
            0.0,
            0.7372562557458877,
        ],
        [
            0.057627118644067804,
            -0.011546677443565615,
            0.0,
            0.5521302118897438,
        ],
        [
            -0.03457627118644068,
            0.03464003233069684,
            0.0,
            0.6822273403406143,
        ],
        [
            0.057627118644067804,
            -0.08082674210495931,
            0.0,
            0.9037148624658584,
        ],
        [
            -0.08067796610169492,
            0.10392009699209054,
            0.0,
            0.8821639835834503,
        ],
        [
            -0.08067796610169492,
            -0.05773338721782807,
            0.0,
            0.5252480402588844,
        ],
    ];
    // polar preset 0 (randoms used: 6)
    const POLAR_0: &[[f64; 4]] = &[
        [
            0.9401664843327137,
            -0.06056700551217851,
            1.0044619808180884,
            0.37,
        ],
        [
            -0.10794363348136447,
            -0.8175589972547397,
            1.0325311653707188,
            0.37,
        ],
        [
            0.3694579918129906,
            -0.6755755792817791,
            -0.5137197284253534,
            0.37,
        ],
    ];

    // polar preset 1 (randoms used: 12)
    const POLAR_1: &[[f64; 4]] = &[
        [
            0.2640947065958182,
            -0.6409086654393177,
            2.12630240268391,
            0.23430448170746768,
        ],
        [
            0.6512437469154144,
            -0.4695381453597726,
            2.0411479715951772,
            0.3929506731982927,
        ],
        [
            0.6305924997166926,
            -1.190632803066821,
            0.6385405765460179,
            0.2617919447304331,
        ],
    ];

    // polar preset 2 (randoms used: 18)
    const POLAR_2: &[[f64; 4]] = &[
        [
            0.4518157689981463,
            -1.0178518396901266,
            0.3231246390610246,
            0.4031093358218728,
        ],
        [
            1.3156707311233613,
            0.20816480329332507,
            -1.825992937727013,
            0.8560555938334198,
        ],
        [
            1.3511954215614583,
            -0.8549494972400805,
            -0.45181631611632656,
            0.6096984527426877,
        ],
    ];

    // polar preset 3 (randoms used: 24)
    const POLAR_3: &[[f64; 4]] = &[
        [
            -0.035352422910976254,
            0.005815448768760096,
            2.3172422106552006,
            0.5840766449961237,
        ],
        [
            0.8935596879356489,
            0.582402277096967,
            1.8871782902335372,
            1.0,
        ],
        [
            0.42636121526545706,
            -0.1374760708207684,
            1.3579158557540083,
            0.7991009699455904,
        ],
    ];

    // polar preset 4 (randoms used: 30)
    const POLAR_4: &[[f64; 4]] = &[
        [
            0.001794256429355979,
            0.28672735537079164,
            0.057926219326461206,
            0.07027326250678893,
        ],
        [
            0.40454997873502774,
            0.7037600720491897,
            -0.15626798247554635,
            0.5036557698162177,
        ],
        [
            0.34331640034143207,
            0.6486701186154914,
            0.9778698800506729,
            0.1448474965353759,
        ],
    ];

    // polar preset 5 (randoms used: 36)
    const POLAR_5: &[[f64; 4]] = &[
        [
            0.05151852924531744,
            0.31266152259751995,
            1.8040014267588664,
            0.37,
        ],
        [
            0.04178373682993048,
            0.13868242935656985,
            2.213221400611786,
            0.37,
        ],
        [
            -0.0757477212670569,
            0.3714226222885521,
            1.0504455922722449,
            0.37,
        ],
    ];

    // polar preset 6 (randoms used: 42)
    const POLAR_6: &[[f64; 4]] = &[
        [
            0.8993788416683474,
            0.15088090779344332,
            0.3236866534039932,
            0.37,
        ],
        [
            1.2580771361686978,
            1.410014114050802,
            -0.5513304125587889,
            0.37,
        ],
        [
            -0.21047576971163778,
            -0.4977991619988967,
            -1.0591427949927639,
            0.37,
        ],
    ];

    // polar preset 7 (randoms used: 48)
    const POLAR_7: &[[f64; 4]] = &[
        [
            0.39922467299522074,
            -0.2856674523925565,
            2.4467892991276874,
            0.3939743272624229,
        ],
        [
            0.4068149258278953,
            -0.21693100230179613,
            1.1785264327327951,
            0.43146097299330155,
        ],
        [
            0.007534771585789019,
            -0.06825455659678666,
            0.9380045843413127,
            0.15404305940527832,
        ],
    ];

    // polar preset 8 (randoms used: 54)
    const POLAR_8: &[[f64; 4]] = &[
        [
            0.4846784567428753,
            -0.1492250592941951,
            1.2098090276763678,
            0.07293802479428912,
        ],
        [
            1.0883498688225322,
            -2.6994940979701028,
            0.4826115727514756,
            0.44684494049889717,
        ],
        [
            2.6139151941685532,
            2.229810541391295,
            -6.775792519537915,
            0.9156693080944034,
        ],
    ];

    // polar preset 9 (randoms used: 60)
    const POLAR_9: &[[f64; 4]] = &[
        [
            -0.07612440694670185,
            -0.4925387786717664,
            2.164876687601288,
            0.3784947683014694,
        ],
        [
            0.016284847295833068,
            0.018299605057009297,
            1.321387502306692,
            0.6108872724123613,
        ],
        [
            0.960843356506103,
            -0.8050630373019632,
            1.1641176996204077,
            1.0,
        ],
    ];

    // knots preset 0 verts 4000 faces 7992 v0 -11.797076 -16.048721 9.998223 vlast -11.960164 -13.99425 9.712923
    const KNOT_0: &[[f64; 4]] = &[
        [
            0.37677389633019537,
            -0.24845656209356126,
            -0.11293492222215035,
            0.5,
        ],
        [
            0.10967749717030195,
            0.37671332301613214,
            -0.18613477492419822,
            0.5,
        ],
        [
            0.009565921902322576,
            0.4687422579476865,
            -0.059889223735898445,
            0.5,
        ],
        [
            -0.10355039554406947,
            0.14440488156246345,
            -0.05809525407549899,
            0.5,
        ],
        [
            0.01538398368439449,
            0.44424210679222265,
            -0.025274038965751557,
            0.5,
        ],
        [
            -0.42362108550312005,
            -0.12254557889779635,
            -0.17790080885974952,
            0.5,
        ],
    ];

    // knots preset 4 verts 1500 faces 2990 v0 127.10475 8.083897 2.6132116 vlast 123.005005 0.28214753 -0.010362493
    const KNOT_4: &[[f64; 4]] = &[
        [
            -0.4967794737776732,
            -0.5017553691264934,
            0.09844543110414716,
            0.5,
        ],
        [
            0.5354058846841226,
            0.2624145156908297,
            0.21215684172102858,
            0.5,
        ],
        [
            -0.42138941826641824,
            0.31040460702074574,
            0.08697581968409673,
            0.5,
        ],
        [
            -0.039293120518537686,
            -1.1040168065675533,
            0.12958099853556249,
            0.5,
        ],
        [
            0.10994154835744774,
            0.4575738488145398,
            0.36323995399987924,
            0.5,
        ],
        [
            -0.7933227294530033,
            -0.24191180212626537,
            0.4480163047718446,
            0.5,
        ],
    ];

    // knots preset 21 verts 600 faces 1194 v0 96.950714 -15.624288 -9.410829 vlast 99.57845 -1.3502281 2.0729973
    const KNOT_21: &[[f64; 4]] = &[
        [
            -1.2875897753432066,
            -1.224129238496178,
            1.3605863253395232,
            0.5,
        ],
        [
            -1.416312601683565,
            -0.6116941703820012,
            1.51169980663846,
            0.5,
        ],
        [
            -1.4807135564587868,
            0.242752512327842,
            -1.6666084508609973,
            0.5,
        ],
        [
            -1.515995811391429,
            -0.7753419591155298,
            -1.8049097487512629,
            0.5,
        ],
        [
            -1.7517300193097634,
            -0.6213078312533346,
            -0.3485787868595981,
            0.5,
        ],
        [
            -1.7483943827860162,
            -1.986319269249661,
            -1.3161141246426284,
            0.5,
        ],
    ];

    // knots preset 14 verts 3000 faces 5988 v0 -177.78893 -254.74458 -6.6459246 vlast -186.71043 -248.55331 -6.413316
    const KNOT_14: &[[f64; 4]] = &[
        [
            -1.4081217602221636,
            -0.8665852101516152,
            -0.0013389691115515527,
            0.5,
        ],
        [
            -0.6602971760934945,
            -1.8592439484394507,
            0.021303902104756148,
            0.5,
        ],
        [
            0.6750682619936513,
            0.9031618228808195,
            0.5936168598246476,
            0.5,
        ],
        [
            0.7817929329268889,
            1.3610346162605353,
            0.272514188138534,
            0.5,
        ],
        [
            0.6153346323602453,
            1.5048096400496445,
            -0.8028456078952729,
            0.5,
        ],
        [
            0.16290739893573786,
            1.1737979412465203,
            -0.8255954231888349,
            0.5,
        ],
    ];
}
