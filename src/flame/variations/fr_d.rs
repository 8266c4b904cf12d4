//! Variations (slice fr_d of the registry): Fractorium's catalogue from `julia3Dz` to
//! `pow_block` in alphabetical order (the julia/julian family, lazy*, linear*, loonie*, mirrors,
//! Möbius maps, murls, nBlur, octagon/octapol, ortho, ovoids, panoramas, Poincaré maps, …).
//!
//! Every formula returns its weighted output. Derived constants of the parameters are computed
//! once in the `prepare` functions and appended to `v.p` after the parameters.

use std::f64::consts::{E, FRAC_1_PI, FRAC_PI_2, PI, SQRT_2, TAU};

use super::util::{
    cpp_max, crand, mix, rand_size, sign, signed_pow, sqr, trunc_i32, wang_hash, zeps,
};
use super::*;

const INF: f64 = f64::INFINITY;
const NINF: f64 = f64::NEG_INFINITY;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("julia3Dz", julia3dz)
        .batch(super::inline_batch!(julia3dz))
        .params(&[p_int_nonzero("julia3Dz_power", 2.0, NINF, INF)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_julia3dz),
    VarDef::new("Juliac", juliac)
        .params(&[
            p("Juliac_re", 2.0),
            p("Juliac_im", 1.0),
            p("Juliac_dist", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_juliac),
    VarDef::new("julian2", julian2)
        .params(&[
            p("julian2_a", 1.0),
            p("julian2_b", 0.0),
            p("julian2_c", 0.0),
            p("julian2_d", 1.0),
            p("julian2_e", 0.0),
            p("julian2_f", 0.0),
            p_nonzero("julian2_power", 2.0, NINF, INF),
            p("julian2_dist", 1.0),
        ])
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(prep_julian2),
    VarDef::new("julian3Dx", julian3dx)
        .params(&[
            p("julian3Dx_dist", 1.0),
            p_int_nonzero("julian3Dx_power", 2.0, NINF, INF),
            p("julian3Dx_a", 1.0),
            p("julian3Dx_b", 0.0),
            p("julian3Dx_c", 0.0),
            p("julian3Dx_d", 1.0),
            p("julian3Dx_e", 0.0),
            p("julian3Dx_f", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_julian3dx),
    VarDef::new("juliaNab", julianab)
        .params(&[
            p("juliaNab_n", 1.0),
            p("juliaNab_a", 1.0),
            p("juliaNab_b", 1.0),
            p("juliaNab_separ", 1.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(prep_julianab),
    VarDef::new("juliaq", juliaq)
        .params(&[
            p_nonzero("juliaq_power", 3.0, NINF, INF),
            p_nonzero("juliaq_divisor", 2.0, NINF, INF),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_juliaq),
    VarDef::new("Kaleidoscope", kaleidoscope)
        .params(&[
            p("Kaleidoscope_pull", 0.0),
            p("Kaleidoscope_rotate", 1.0),
            p("Kaleidoscope_line_up", 1.0),
            p("Kaleidoscope_x", 0.0),
            p("Kaleidoscope_y", 0.0),
        ])
        .prepare(prep_kaleidoscope),
    VarDef::new("lazyjess", lazyjess)
        .params(&[
            p_nonzero("lazyjess_n", 4.0, 2.0, INF),
            p("lazyjess_spin", PI),
            p("lazyjess_space", 0.0),
            p("lazyjess_corner", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .prepare(prep_lazyjess),
    VarDef::new("lazyTravis", lazytravis)
        .params(&[
            p_cyclic("lazyTravis_spin_in", 1.0, 0.0, 2.0),
            p_cyclic("lazyTravis_spin_out", 0.0, 0.0, 2.0),
            p("lazyTravis_space", 0.0),
        ])
        .prepare(prep_lazytravis),
    VarDef::new("lens", lens),
    VarDef::new("line", line)
        .params(&[p("line_delta", 0.0), p("line_phi", 0.0)])
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum()
        .prepare(prep_line),
    VarDef::new("linear3D", linear3d)
        .batch(super::inline_batch!(linear3d))
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("linearT", linear_t).params(&[p("linearT_powX", 1.0), p("linearT_powY", 1.0)]),
    VarDef::new("linearT3D", linear_t3d)
        .params(&[
            p("linearT3D_powX", 1.0),
            p("linearT3D_powY", 1.0),
            p("linearT3D_powZ", 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("Lissajous", lissajous)
        .params(&[
            p("Lissajous_tmin", -PI),
            p("Lissajous_tmax", PI),
            p("Lissajous_a", 3.0),
            p("Lissajous_b", 2.0),
            p("Lissajous_c", 0.0),
            p("Lissajous_d", 0.0),
            p("Lissajous_e", 0.0),
        ])
        .flags(flag::RANDOM)
        .sum(),
    VarDef::new("log_db", log_db)
        .params(&[p("log_db_base", 1.0), p("log_db_fix_period", 1.0)])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_log_db),
    VarDef::new("loonie2", loonie2)
        .params(&[
            p_int("loonie2_sides", 4.0, 1.0, 50.0),
            p_range("loonie2_star", 0.0, -1.0, 1.0),
            p_range("loonie2_circle", 0.0, -1.0, 1.0),
            p("loonie2_power", 4.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::COMPAT)
        .prepare(prep_loonie2),
    VarDef::new("loonie3", loonie3)
        .needs(need::SUMSQ)
        .prepare(prep_weight_squared),
    VarDef::new("loonie_3D", loonie_3d)
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_weight_squared),
    VarDef::new("loq", loq)
        .params(&[p_range("loq_base", E, f64::EPSILON, INF)])
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_loq),
    VarDef::new("lozi", lozi).params(&[p("lozi_a", 0.5), p("lozi_b", 1.0)]),
    VarDef::new("mask", mask).needs(need::SUMSQ),
    VarDef::new("mcarpet", mcarpet)
        .params(&[
            p("mcarpet_x", 0.0),
            p("mcarpet_y", 0.0),
            p("mcarpet_twist", 0.0),
            p("mcarpet_tilt", 0.0),
        ])
        .needs(need::SUMSQ),
    VarDef::new("mirror_x", mirror::<0>).flags(MIRROR_FLAGS),
    VarDef::new("mirror_y", mirror::<1>).flags(MIRROR_FLAGS),
    VarDef::new("mirror_z", mirror::<2>).flags(MIRROR_FLAGS),
    VarDef::new("mobiq", mobiq)
        .params(&[
            p("mobiq_at", 1.0),
            p("mobiq_ax", 0.0),
            p("mobiq_ay", 0.0),
            p("mobiq_az", 0.0),
            p("mobiq_bt", 0.0),
            p("mobiq_bx", 0.0),
            p("mobiq_by", 0.0),
            p("mobiq_bz", 0.0),
            p("mobiq_ct", 0.0),
            p("mobiq_cx", 0.0),
            p("mobiq_cy", 0.0),
            p("mobiq_cz", 0.0),
            p("mobiq_dt", 1.0),
            p("mobiq_dx", 0.0),
            p("mobiq_dy", 0.0),
            p("mobiq_dz", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("mobius_strip", mobius_strip)
        .params(&[
            p("mobius_strip_radius", 2.0),
            p("mobius_strip_width", 1.0),
            p("mobius_strip_rect_x", TAU),
            p("mobius_strip_rect_y", 1.0),
            p("mobius_strip_rotate_x", 0.0),
            p("mobius_strip_rotate_y", 0.0),
        ])
        .prepare(prep_mobius_strip),
    VarDef::new("MobiusN", mobius_n)
        .params(&[
            p("MobiusNRe_A", 1.0),
            p("MobiusNIm_A", 0.0),
            p("MobiusNRe_B", 0.0),
            p("MobiusNIm_B", 0.0),
            p("MobiusNRe_C", 0.0),
            p("MobiusNIm_C", 0.0),
            p("MobiusNRe_D", 1.0),
            p("MobiusNIm_D", 0.0),
            p("MobiusN_Power", 2.0),
            p("MobiusN_Dist", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_mobius_n),
    VarDef::new("modulusx", modulus::<0>)
        .params(&[p("modulusx_x", 1.0), p("modulusx_shift", 0.0)])
        .prepare(prep_modulus),
    VarDef::new("modulusy", modulus::<1>)
        .params(&[p("modulusy_y", 1.0), p("modulusy_shift", 0.0)])
        .prepare(prep_modulus),
    VarDef::new("murl", murl)
        .params(&[p("murl_c", 0.0), p_range("murl_power", 2.0, 2.0, INF)])
        .needs(need::SUMSQ | need::ATAN_YX)
        .prepare(prep_murl),
    VarDef::new("murl2", murl2)
        .params(&[p_range("murl2_c", 0.0, -1.0, 1.0), p("murl2_power", 1.0)])
        .needs(need::SUMSQ | need::ATAN_YX)
        .prepare(prep_murl2),
    VarDef::new("nBlur", nblur)
        .batch(super::inline_batch!(nblur))
        .params(&[
            p_int("nBlur_numEdges", 3.0, NINF, INF),
            p_int("nBlur_numStripes", 0.0, NINF, INF),
            p_range("nBlur_ratioStripes", 1.0, 0.0, 2.0),
            p_range("nBlur_ratioHole", 0.0, 0.0, 1.0),
            p_int("nBlur_circumCircle", 0.0, 0.0, 1.0),
            p_int("nBlur_adjustToLinear", 1.0, 0.0, 1.0),
            p_int("nBlur_equalBlur", 1.0, 0.0, 1.0),
            p_int("nBlur_exactCalc", 0.0, 0.0, 1.0),
            p("nBlur_highlightEdges", 1.0),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_nblur),
    VarDef::new("npolar", npolar)
        .params(&[p("npolar_parity", 0.0), p("npolar_n", 1.0)])
        .needs(need::SUMSQ | need::ATAN_XY | need::ATAN_YX)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(prep_npolar),
    VarDef::new("octagon", octagon)
        .params(&[
            p("octagon_x", 0.0),
            p("octagon_y", 0.0),
            p("octagon_z", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("octapol", octapol)
        .params(&[
            p("octapol_polarweight", 0.0),
            p("octapol_radius", 1.0),
            p("octapol_s", 0.5),
            p("octapol_t", 0.5),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(prep_octapol),
    VarDef::new("ortho", ortho)
        .batch(super::inline_batch!(ortho))
        .params(&[
            p_cyclic("ortho_in", 0.0, -PI, PI),
            p_cyclic("ortho_out", 0.0, -PI, PI),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES),
    VarDef::new("oscilloscope2", oscilloscope2)
        .params(&[
            p_range("oscilloscope2_separation", 1.0, 0.0, INF),
            p("oscilloscope2_frequencyx", PI),
            p("oscilloscope2_frequencyy", PI),
            p("oscilloscope2_amplitude", 1.0),
            p("oscilloscope2_perturbation", 1.0),
            p("oscilloscope2_damping", 0.0),
        ])
        .prepare(prep_oscilloscope2),
    VarDef::new("ovoid", ovoid)
        .params(&[p("ovoid_x", 1.0), p("ovoid_y", 1.0)])
        .needs(need::SUMSQ),
    VarDef::new("ovoid3d", ovoid3d)
        .params(&[
            p("ovoid3d_x", 1.0),
            p("ovoid3d_y", 1.0),
            p("ovoid3d_z", 1.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("panorama1", panorama::<false>).needs(need::SUMSQ),
    VarDef::new("panorama2", panorama::<true>).needs(need::SUMSQ | need::SQRT),
    VarDef::new("petal", petal),
    VarDef::new("phoenix_julia", phoenix_julia)
        .params(&[
            p("phoenix_julia_power", 2.0),
            p("phoenix_julia_dist", 1.0),
            p("phoenix_julia_x_distort", -0.5),
            p("phoenix_julia_y_distort", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::COMPAT)
        .prepare(prep_phoenix_julia),
    VarDef::new("pie3D", pie3d)
        .params(&[
            p_int_nonzero("pie3D_slices", 6.0, 1.0, INF),
            p_cyclic("pie3D_rotation", 0.5, 0.0, TAU),
            p_range("pie3D_thickness", 0.5, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
    VarDef::new("pixel_flow", pixel_flow)
        .params(&[
            p("pixel_flow_angle", 90.0),
            p("pixel_flow_len", 0.1),
            p("pixel_flow_width", 200.0),
            p_int("pixel_flow_seed", 42.0, NINF, INF),
            p_int("pixel_flow_enable_dc", 0.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::SETS_COLOR)
        .prepare(prep_pixel_flow),
    VarDef::new("poincare", poincare)
        .batch(super::inline_batch!(poincare))
        .params(&[
            p("poincare_c1r", 1.0),
            p_cyclic("poincare_c1a", -1.0, -PI, PI),
            p("poincare_c2r", 1.0),
            p_cyclic("poincare_c2a", 1.0, -PI, PI),
        ])
        .prepare(prep_poincare),
    VarDef::new("poincare2", poincare2)
        .params(&[p("poincare2_p", 3.0), p("poincare2_q", 7.0)])
        .prepare(prep_poincare2),
    VarDef::new("poincare3D", poincare3d)
        .params(&[
            p("poincare3D_r", 0.0),
            p("poincare3D_a", 0.0),
            p("poincare3D_b", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_poincare3d),
    VarDef::new("point_symmetry", point_symmetry)
        .params(&[
            p("point_symmetry_centre_x", 0.15),
            p("point_symmetry_centre_y", 0.5),
            p("point_symmetry_order", 3.0),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_point_symmetry),
    VarDef::new("polynomial", polynomial)
        .params(&[
            p("polynomial_powx", 1.0),
            p("polynomial_powy", 1.0),
            p("polynomial_lcx", 0.0),
            p("polynomial_lcy", 0.0),
            p("polynomial_scx", 0.0),
            p("polynomial_scy", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("popcorn2_3D", popcorn2_3d)
        .params(&[
            p("popcorn2_3D_x", 0.1),
            p("popcorn2_3D_y", 0.1),
            p("popcorn2_3D_z", 0.1),
            p("popcorn2_3D_c", 3.0),
        ])
        .needs(need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::READS_ACC)
        .prepare(prep_popcorn2_3d),
    VarDef::new("post_smartcrop", post_smartcrop)
        .params(&[
            p("post_smartcrop_power", 4.0),
            p("post_smartcrop_radius", 1.0),
            p("post_smartcrop_roundstr", 0.0),
            p("post_smartcrop_roundwidth", 1.0),
            p("post_smartcrop_distortion", 1.0),
            p("post_smartcrop_edge", 0.0),
            p("post_smartcrop_scatter", 0.0),
            p("post_smartcrop_offset", 0.0),
            p("post_smartcrop_rotation", 0.0),
            p_range("post_smartcrop_cropmode", 1.0, -1.0, 2.0),
            p_range("post_smartcrop_static", 1.0, -1.0, 3.0),
        ])
        .flags(
            flag::POST_ONLY
                | flag::RANDOM
                | flag::STATEFUL
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::SETS_COLOR
                | flag::USES_COLOR,
        )
        .prepare(prep_post_smartcrop),
    VarDef::new("pow_block", pow_block)
        .params(&[
            p("pow_block_numerator", 3.0),
            p("pow_block_denominator", 2.0),
            p("pow_block_root", 1.0),
            p("pow_block_correctn", 1.0),
            p("pow_block_correctd", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_pow_block),
];

const MIRROR_FLAGS: u32 = flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC;

// ---------------------------------------------------------------------------------------------
// Shared helpers.

/// Derived value shared by the loonies: the squared weight.
fn prep_weight_squared(v: &mut Prepared) {
    let w2 = v.w * v.w;
    v.p.push(w2);
}

// ---------------------------------------------------------------------------------------------
// julia family.

fn prep_julia3dz(v: &mut Prepared) {
    let [n] = v.params();
    v.p.push(n.abs());
    v.p.push(1.0 / n / 2.0);
}

/// julia3Dz: the n-th root julia map in the plane (one of |n| branches at random); z is scaled by
/// the same radial factor over the input radius, making a 3-D cone of julia sheets.
fn julia3dz(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n] = v.params();
    let [abs_n, exponent] = v.derived();
    let radius = v.w * t.sumsq.powf(exponent);
    let branch = TAU * rand_size(rng, abs_n as u32 as f64);
    let ang = (t.atan_yx + branch) / n;
    [
        radius * ang.cos(),
        radius * ang.sin(),
        radius * t.z / zeps(t.sqrt * abs_n),
    ]
}

fn prep_juliac(v: &mut Prepared) {
    let [re, im, dist] = v.params();
    let re_inv = 1.0 / zeps(re);
    v.p.extend_from_slice(&[dist * 0.5, re_inv, 1.0 / re_inv, im * 0.01]);
}

/// Juliac: a complex power z^(1/(re + i·im/100)) with a random integer winding; the imaginary
/// part of the exponent spirals the branches.
fn juliac(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [half_dist, re_inv, period, im_scaled] = v.derived();
    let turn = (rng.u32() as f64) % period;
    let arg = t.atan_yx + turn * TAU;
    let log_mod = half_dist * t.sumsq.ln();
    let ang = arg * re_inv + log_mod * im_scaled;
    let magnitude = (log_mod * re_inv - arg * im_scaled).exp();
    [
        v.w * magnitude * ang.cos(),
        v.w * magnitude * ang.sin(),
        0.0,
    ]
}

fn prep_julian2(v: &mut Prepared) {
    let [_, _, _, _, _, _, power, dist] = v.params();
    let power = if power == 0.0 { 2.0 } else { power };
    let abs_n = if v.compat {
        power.abs().trunc()
    } else {
        power.abs()
    };
    let exponent = dist / power / 2.0;
    v.p.extend_from_slice(&[power, abs_n, exponent]);
}

/// julian2: julian (the power-th root with a random branch) applied after its own affine map
/// (a b c d e f) of the input point.
fn julian2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a, b, c, d, e, f] = v.params();
    let [power, abs_n, exponent] = v.derived();
    let x = a * t.x + b * t.y + e;
    let y = c * t.x + d * t.y + f;
    let radius = v.w * (x * x + y * y).powf(exponent);
    let ang = if v.compat {
        (y.atan2(x) + TAU * rand_size(rng, abs_n)) / power
    } else {
        let branch = trunc_i32(abs_n * rng.f01()) as f64;
        (y.atan2(x) + branch * TAU) / power
    };
    [radius * ang.cos(), radius * ang.sin(), 0.0]
}

fn prep_julian3dx(v: &mut Prepared) {
    let [dist, power] = v.params();
    v.p.push(power.abs());
    v.p.push((dist / power - 1.0) / 2.0);
}

/// julian3Dx: a 3-D julian whose planar angle comes from an affine-transformed copy of the
/// point; the radius combines the planar radius and z scaled by 1/|power|.
fn julian3dx(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, power, a, b, c, d, e, f] = v.params();
    let [abs_n, exponent] = v.derived();
    let z = t.z / abs_n;
    let radius = v.w * (t.sumsq + z * z).powf(exponent);
    let x = a * t.x + b * t.y + e;
    let y = c * t.x + d * t.y + f;
    let branch = trunc_i32(rng.f01() * abs_n) as f64;
    let ang = (y.atan2(x) + TAU * branch) / power;
    let planar = radius * t.sqrt;
    [planar * ang.cos(), planar * ang.sin(), radius * z]
}

fn prep_julianab(v: &mut Prepared) {
    let [n] = v.params();
    let div = zeps(n.abs());
    v.p.push(n.abs());
    v.p.push(1.0 / div / 2.0);
}

/// juliaNab: a julia-like root whose angle is taken from (|x|^separ, y), with an exponent scaled
/// by `a` and both outputs shifted by `b`; z passes through (and the running z is reset).
fn julianab(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n, a, b, separ] = v.params();
    let [abs_n, exponent] = v.derived();
    let div = zeps(n.abs());
    let branch = (rng.f01() * abs_n).floor();
    let ang = (t.y.atan2(t.x.abs().powf(separ)) + TAU * branch) / div;
    let radius = v.w * t.sumsq.powf(exponent * a);
    if v.form == Form::Regular {
        acc.z = 0.0;
    }
    [radius * ang.cos() + b, radius * ang.sin() + b, t.z]
}

fn prep_juliaq(v: &mut Prepared) {
    let [power, divisor] = v.params();
    let pz = zeps(power);
    v.p.extend_from_slice(&[0.5 * (divisor / pz), divisor / pz, TAU / pz]);
}

/// juliaq: the rational power z^(divisor/power), with a random multiple of 2π/power added to
/// the angle.
fn juliaq(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [half_ratio, ratio, step] = v.derived();
    let ang = t.atan_yx * ratio + crand(rng) * step;
    let radius = v.w * t.sumsq.powf(half_ratio);
    [radius * ang.cos(), radius * ang.sin(), 0.0]
}

// ---------------------------------------------------------------------------------------------
// K, L.

fn prep_kaleidoscope(v: &mut Prepared) {
    // 45° in radians as Fractorium forms it; its sine and cosine differ in the last bit.
    let quarter = 45.0 * (PI / 180.0);
    v.p.push(quarter.sin());
    v.p.push(quarter.cos());
}

/// Kaleidoscope: rotates the plane by 45° (scaling by `rotate`) and splits it along y = 0, the
/// two halves being pushed apart by `pull` and shifted by `line_up`; the weight is not used.
fn kaleidoscope(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [pull, rotate, line_up, sx, sy] = v.params();
    let [s45, c45] = v.derived();
    let x = ((rotate * t.x) * c45 - t.y * s45 + line_up) + sx;
    let y = if t.y > 0.0 {
        ((rotate * t.y) * c45 + t.x * s45 + pull + line_up) + sy
    } else {
        (rotate * t.y) * c45 + t.x * s45 - pull - line_up
    };
    [x, y, 0.0]
}

fn prep_lazyjess(v: &mut Prepared) {
    let [n, _, _, corner] = v.params();
    let vertex = PI * (n - 2.0) / zeps(2.0 * n);
    let slice = TAU / zeps(n);
    v.p.extend_from_slice(&[
        vertex,
        vertex.sin(),
        slice,
        slice / 2.0,
        (corner - 1.0) * slice,
    ]);
}

/// lazyjess: inside a regular n-gon (of circumradius tied to the weight) points are spun by
/// `spin`; spun corners that leave the polygon are mirrored back; outside points are pushed out
/// by `space`.
fn lazyjess(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [n, spin, space] = v.params();
    let [vertex, sin_vertex, slice, half_slice, corner_turn] = v.derived();
    let w = v.w;
    let (x, y) = (t.x, t.y);
    let m = t.sqrt;
    let push_out = || {
        let k = 1.0 + space / zeps(m);
        [w * k * x, w * k * y, 0.0]
    };
    // Distance from the centre to the polygon's edge in direction `ang` (ang includes +2π).
    let edge_at = |ang: f64| {
        let off = (ang + half_slice) % slice;
        w * SQRT_2 * sin_vertex / zeps((PI - off - vertex).sin())
    };
    if n == 2.0 {
        if x.abs() < w {
            let ang = y.atan2(x) + spin;
            let (rx, ry) = (w * m * ang.cos(), w * m * ang.sin());
            if rx.abs() < w {
                return [rx, ry, 0.0];
            }
            // A spun corner that left the band is mirrored back into place.
            let back = ry.atan2(rx) - spin + corner_turn;
            return [w * m * back.cos(), -(w * m * back.sin()), 0.0];
        }
        return push_out();
    }
    if m < edge_at(y.atan2(x) + TAU) {
        let ang = y.atan2(x) + spin + TAU;
        let (rx, ry) = (w * m * ang.cos(), w * m * ang.sin());
        let m2 = (rx * rx + ry * ry).sqrt();
        if m2 < edge_at(ang) {
            return [rx, ry, 0.0];
        }
        let back = ry.atan2(rx) - spin + corner_turn + TAU;
        return [w * m2 * back.cos(), -(w * m2 * back.sin()), 0.0];
    }
    push_out()
}

fn prep_lazytravis(v: &mut Prepared) {
    let [spin_in, spin_out] = v.params();
    v.p.push(4.0 * spin_in);
    v.p.push(4.0 * spin_out);
}

/// lazyTravis: each point's square ring (max(|x|, |y|)) is treated as a loop of perimeter 8s
/// and the point is slid along it (by `spin_in` inside the weight square, `spin_out` outside,
/// where the rings are also spaced out by `space`).
fn lazytravis(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [_, _, space] = v.params();
    let [turn_in, turn_out] = v.derived();
    let w = v.w;
    let (ax, ay) = (t.x.abs(), t.y.abs());
    let outside = ax > w || ay > w;
    let turn = if outside { turn_out } else { turn_in };
    let (s, pos) = if ax > ay {
        let base = if t.x > 0.0 { ax + t.y } else { 5.0 * ax - t.y };
        (ax, base + ax * turn)
    } else {
        let base = if t.y > 0.0 {
            3.0 * ay - t.x
        } else {
            7.0 * ay + t.x
        };
        (ay, base + ay * turn)
    };
    let pos = pos % (s * 8.0);
    if outside {
        let widen = |u: f64| u + u / s * space;
        let (x2, y2) = if pos <= 2.0 * s {
            (s + space, widen(-(s - pos)))
        } else if pos <= 4.0 * s {
            (widen(3.0 * s - pos), s + space)
        } else if pos <= 6.0 * s {
            (-(s + space), widen(5.0 * s - pos))
        } else {
            (widen(-(7.0 * s - pos)), -(s + space))
        };
        [w * x2, w * y2, 0.0]
    } else if pos <= 2.0 * s {
        [w * s, -(w * (s - pos)), 0.0]
    } else if pos <= 4.0 * s {
        [w * (3.0 * s - pos), w * s, 0.0]
    } else if pos <= 6.0 * s {
        [-(w * s), w * (5.0 * s - pos), 0.0]
    } else {
        [-(w * (7.0 * s - pos)), -(w * s), 0.0]
    }
}

/// lens: half the complex square, ((x² − y²)/2, x·y).
fn lens(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [0.5 * (t.x * t.x - t.y * t.y) * v.w, t.x * t.y * v.w, 0.0]
}

fn prep_line(v: &mut Prepared) {
    let [delta, phi] = v.params();
    let (delta, phi) = (delta * PI, phi * PI);
    let ux = delta.cos() * phi.cos();
    let uy = delta.sin() * phi.cos();
    let uz = phi.sin();
    let len = (ux * ux + uy * uy + uz * uz).sqrt();
    v.p.extend_from_slice(&[ux / len, uy / len, uz / len]);
}

/// line: a random point on a segment of length `weight` from the origin, in the 3-D direction
/// given by the angles `delta` (azimuth) and `phi` (elevation), in half turns.
fn line(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ux, uy, uz] = v.derived();
    let r = rng.f01() * v.w;
    [ux * r, uy * r, uz * r]
}

/// linear3D: the identity in 3-D, scaled by the weight.
fn linear3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w * t.x, v.w * t.y, v.w * t.z]
}

/// linearT: each coordinate raised to its own power, keeping its sign.
fn linear_t(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [pow_x, pow_y] = v.params();
    [
        signed_pow(t.x, pow_x) * v.w,
        signed_pow(t.y, pow_y) * v.w,
        0.0,
    ]
}

/// linearT3D: linearT in 3-D (z with its own power).
fn linear_t3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [pow_x, pow_y, pow_z] = v.params();
    [
        signed_pow(t.x, pow_x) * v.w,
        signed_pow(t.y, pow_y) * v.w,
        signed_pow(t.z, pow_z) * v.w,
    ]
}

/// Lissajous: a random point of the Lissajous curve (sin(a·s + d), sin(b·s)) for s in
/// [tmin, tmax], drifted along the diagonal by c·s and thickened by e.
fn lissajous(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [tmin, tmax, a, b, c, d, e] = v.params();
    let s = (tmax - tmin) * rng.f01() + tmin;
    let thick = rng.f01() - 0.5;
    let cx = (a * s + d).sin();
    let cy = (b * s).sin();
    [
        v.w * (cx + c * s + e * thick),
        v.w * (cy + c * s + e * thick),
        0.0,
    ]
}

fn prep_log_db(v: &mut Prepared) {
    let [base, fix_period] = v.params();
    let mut scale = 0.5;
    if base > f64::EPSILON {
        scale /= (E * base).ln();
    }
    scale *= v.w;
    let mut period = PI;
    if fix_period > f64::EPSILON {
        period *= fix_period;
    }
    v.p.push(scale);
    v.p.push(period);
}

/// log_db: the complex logarithm in base e·base, with the angle shifted by a random small
/// multiple of π·fix_period (the sum of seven draws in −2..=2); z is scaled.
fn log_db(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scale, period] = v.derived();
    let mut turns = 0i32;
    for _ in 0..7 {
        let d = rng.below(10) as i32 - 5;
        if d.abs() < 3 {
            turns += d;
        }
    }
    let shift = turns as f64 * period;
    [scale * t.sumsq.ln(), v.w * (t.atan_yx + shift), v.w * t.z]
}

fn prep_loonie2(v: &mut Prepared) {
    let [sides, star, circle, power] = v.params();
    let a = TAU / sides;
    let s = -FRAC_PI_2 * star;
    let c = FRAC_PI_2 * circle;
    let alpha = TAU / zeps(power);
    v.p.extend_from_slice(&[
        v.w * v.w,
        a.sin(),
        a.cos(),
        s.sin(),
        s.cos(),
        c.sin(),
        c.cos(),
        alpha,
        (alpha * 0.5).tan() * 2.0,
    ]);
}

/// loonie2: loonie with a polygon/star/circle-shaped hole (compatible mode): points inside the
/// shape of "radius" weight are pushed outwards. With the compatibility switch off: a
/// polygonal inversion that maps the unit disc's inside out onto a `power`-gon.
fn loonie2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [sides] = v.params();
    let [
        w2,
        sin_a,
        cos_a,
        sin_s,
        cos_s,
        sin_c,
        cos_c,
        alpha,
        tan_half2,
    ] = v.derived();
    let w = v.w;
    if v.compat {
        let (mut xr, mut yr) = (t.x, t.y);
        let mut r2 = xr * cos_s + yr.abs() * sin_s;
        let mut turns = 0i32;
        while (turns as f64) < sides - 1.0 {
            let nx = xr * cos_a - yr * sin_a;
            yr = xr * sin_a + yr * cos_a;
            xr = nx;
            r2 = cpp_max(r2, xr * cos_s + yr.abs() * sin_s);
            turns += 1;
        }
        r2 = r2 * cos_c + t.sqrt * sin_c;
        r2 = if turns > 1 { r2 * r2 } else { r2.abs() * r2 };
        let k = if r2 > 0.0 && r2 < w2 {
            w * (w2 / r2 - 1.0).abs().sqrt()
        } else if r2 < 0.0 {
            w / ((w2 / r2).abs() - 1.0).sqrt()
        } else {
            w
        };
        [k * t.x, k * t.y, 0.0]
    } else {
        let r2 = t.sumsq;
        let k = if r2 < 1.0 {
            (1.0 / zeps(r2) - 1.0).sqrt()
        } else {
            1.0
        };
        let (nx, ny) = (t.x * k, t.y * k);
        let sector = (ny.atan2(nx) + PI) / alpha;
        let rad = (nx * nx + ny * ny).sqrt();
        let whole = sector.floor();
        let frac = sector - whole;
        let (dist, index, dir) = if frac > 0.5 {
            (1.0 - frac, whole + 1.0, -1.0)
        } else {
            (frac, whole, 1.0)
        };
        let local = (dist * tan_half2).atan() / alpha;
        let stretch = 1.0 / zeps((local * alpha).cos());
        let ang = (index + dir * local) * alpha - PI;
        let r = w * stretch * rad;
        [r * ang.cos(), r * ang.sin(), 0.0]
    }
}

/// loonie3: loonie with a hole bounded by the circle through the origin tangent to the y axis
/// (|r²/x| < weight): points inside are pushed out, the others only scaled.
fn loonie3(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [w2] = v.derived();
    let r2 = if t.x > f64::EPSILON {
        sqr(t.sumsq / t.x)
    } else {
        2.0 * w2
    };
    let k = if r2 < w2 {
        v.w * (w2 / r2 - 1.0).sqrt()
    } else {
        v.w
    };
    [k * t.x, k * t.y, 0.0]
}

/// loonie_3D: loonie in 3-D; a zero z is replaced by the point's angle, and z comes out halved.
fn loonie_3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [w2] = v.derived();
    let z = if t.z == 0.0 { t.atan_yx } else { t.z };
    let r2 = t.sumsq + z * z;
    let k = if r2 < w2 {
        v.w * (w2 / r2 - 1.0).sqrt()
    } else {
        v.w
    };
    [k * t.x, k * t.y, k * z * 0.5]
}

fn prep_loq(v: &mut Prepared) {
    let [base] = v.params();
    v.p.push(0.5 / base.ln());
}

/// loq: the quaternion logarithm of (x, y, z) in base `base`: log of the norm on x, the unit
/// imaginary part times the angle on (y, z).
fn loq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scale] = v.derived();
    let im = (t.y * t.y + t.z * t.z).sqrt();
    let k = v.w * im.atan2(t.x) / zeps(im);
    [(t.x * t.x + im * im).ln() * scale, k * t.y, k * t.z]
}

/// lozi: the Lozi map (1 − a·|x| + y, b·x).
fn lozi(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b] = v.params();
    [(1.0 - (a * t.x.abs()) + t.y) * v.w, b * t.x * v.w, 0.0]
}

// ---------------------------------------------------------------------------------------------
// M.

/// mask: sin³x·(cosh y + 1) and sin²x·cos x·(cosh y + 1), divided by r².
fn mask(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let d = v.w / zeps(t.sumsq);
    let (sx, cx) = (t.x.sin(), t.x.cos());
    let sx2 = sx * sx;
    let ch = t.y.cosh() + 1.0;
    [d * sx * ch * sx2, d * cx * ch * sx2, 0.0]
}

/// mcarpet: a damped scaling x·r·(x, y)/(1 + r²/4) plus a Lozi/Hénon-like term
/// (1 − twist·x² + y, tilt·x).
fn mcarpet(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [sx, sy, twist, tilt] = v.params();
    let k = v.w / (t.sumsq * 0.25 + 1.0);
    let x = t.x * k * sx + (1.0 - (twist * (t.x * t.x)) + t.y) * v.w;
    let y = t.y * k * sy + tilt * t.x * v.w;
    [x, y, 0.0]
}

/// mirror_x / mirror_y / mirror_z: the point itself with axis `AXIS` folded to a random side
/// (±|coordinate|). Unweighted; as a regular variation it replaces what earlier variations
/// summed.
fn mirror<const AXIS: usize>(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let mut o = [t.x, t.y, t.z];
    o[AXIS] = o[AXIS].abs();
    if rng.bit() {
        o[AXIS] = -o[AXIS];
    }
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    o
}

/// mobiq: a quaternion Möbius map (A·q + B)(C·q + D)⁻¹ of q = x + y·i + z·j, each coefficient a
/// quaternion (t, x, y, z).
fn mobiq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        at,
        ax,
        ay,
        az,
        bt,
        bx,
        by,
        bz,
        ct,
        cx,
        cy,
        cz,
        dt,
        dx,
        dy,
        dz,
    ] = v.params();
    let (p0, p1, p2) = (t.x, t.y, t.z);
    let nt = at * p0 - ax * p1 - ay * p2 + bt;
    let nx = at * p1 + ax * p0 - az * p2 + bx;
    let ny = at * p2 + ay * p0 + az * p1 + by;
    let nz = az * p0 + ax * p2 - ay * p1 + bz;
    let et = ct * p0 - cx * p1 - cy * p2 + dt;
    let ex = ct * p1 + cx * p0 - cz * p2 + dx;
    let ey = ct * p2 + cy * p0 + cz * p1 + dy;
    let ez = cz * p0 + cx * p2 - cy * p1 + dz;
    let inv = v.w / (et * et + ex * ex + ey * ey + ez * ez);
    [
        (nt * et + nx * ex + ny * ey + nz * ez) * inv,
        (nx * et - nt * ex - ny * ez + nz * ey) * inv,
        (ny * et - nt * ey - nz * ex + nx * ez) * inv,
    ]
}

fn prep_mobius_strip(v: &mut Prepared) {
    let [_, _, _, _, rotate_x, rotate_y] = v.params();
    let (rx, ry) = (rotate_x * TAU, rotate_y * TAU);
    v.p.extend_from_slice(&[rx.sin(), rx.cos(), ry.sin(), ry.cos()]);
}

/// mobius_strip: wraps the rectangle [−rect_x, rect_x]×[−rect_y, rect_y] (tiled) onto a Möbius
/// band of the given radius and width, rotates it about x then y and projects onto the plane.
fn mobius_strip(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [radius, width, rect_x, rect_y] = v.params();
    let [rx_sin, rx_cos, ry_sin, ry_cos] = v.derived();
    let u = if rect_x == 0.0 {
        0.0
    } else {
        let f = (t.x + rect_x) / (2.0 * rect_x);
        TAU * (f - f.floor())
    };
    let s = if rect_y == 0.0 {
        0.0
    } else {
        let f = (t.y + rect_y) / (2.0 * rect_y);
        2.0 * width * (f - f.floor()) - width
    };
    let half_c = (u / 2.0).cos();
    let bx = (radius + s * half_c) * u.cos();
    let by = (radius + s * half_c) * u.sin();
    let bz = s * (u / 2.0).sin();
    let y1 = by * ry_cos + bz * ry_sin;
    let z1 = bz * ry_cos - by * ry_sin;
    let x2 = bx * rx_cos - z1 * rx_sin;
    [v.w * x2, v.w * y1, 0.0]
}

fn prep_mobius_n(v: &mut Prepared) {
    let [_, _, _, _, _, _, _, _, power] = v.params();
    let power = if power.abs() < 1.0 { 1.0 } else { power };
    v.p.push(power);
    v.p.push(power.floor());
}

/// MobiusN: conjugates a Möbius map (A·z + B)/(C·z + D) by z ↦ z^power: the input is raised to
/// the power, mapped, then one of the power-th roots is taken at random.
fn mobius_n(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [re_a, im_a, re_b, im_b, re_c, im_c, re_d, im_d, _, dist] = v.params();
    let [power, whole_power] = v.derived();
    let e = 4.0 * dist / power;
    let r = t.sqrt.powf(e);
    let ang = t.atan_yx * power;
    let (x, y) = (r * ang.cos(), r * ang.sin());
    let re_u = re_a * x - im_a * y + re_b;
    let im_u = re_a * y + im_a * x + im_b;
    let re_v = re_c * x - im_c * y + re_d;
    let im_v = re_c * y + im_c * x + im_d;
    let den = re_v * re_v + im_v * im_v;
    let x = (re_u * re_v + im_u * im_v) / den;
    let y = (im_u * re_v - re_u * im_v) / den;
    let r = (x * x + y * y).sqrt().powf(1.0 / e);
    let branch = (power * rng.f01()).floor();
    let ang = (y.atan2(x) + branch * TAU) / whole_power;
    [v.w * r * ang.cos(), v.w * r * ang.sin(), 0.0]
}

fn prep_modulus(v: &mut Prepared) {
    let [size] = v.params();
    let period = 2.0 * size;
    v.p.push(period);
}

/// modulusx / modulusy: wraps one coordinate (shifted by `shift`) into [−size, size); the other
/// coordinate is only scaled.
fn modulus<const AXIS: usize>(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [size, shift] = v.params();
    let [period] = v.derived();
    let (u, other) = if AXIS == 0 { (t.x, t.y) } else { (t.y, t.x) };
    let f = (u + size + shift) % period;
    let wrapped = if f >= 0.0 {
        v.w * (f - size)
    } else {
        v.w * (f + size)
    };
    if AXIS == 0 {
        [wrapped, v.w * other, 0.0]
    } else {
        [v.w * other, wrapped, 0.0]
    }
}

fn prep_murl(v: &mut Prepared) {
    let [c, power] = v.params();
    let cp = if power != 1.0 { c / (power - 1.0) } else { c };
    v.p.extend_from_slice(&[cp, power / 2.0, v.w * (cp + 1.0)]);
}

/// murl: divides the point by 1 + c'·z^power (c' = c/(power − 1)), normalised so that the
/// map is the identity scaled by the weight at c = 0.
fn murl(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [_, power] = v.params();
    let [cp, half_power, scale] = v.derived();
    let ang = t.atan_yx * power;
    let r = cp * t.sumsq.powf(half_power);
    let re = r * ang.cos() + 1.0;
    let im = r * ang.sin();
    let k = scale / (re * re + im * im);
    [k * (t.x * re + t.y * im), k * (t.y * re - t.x * im), 0.0]
}

fn prep_murl2(v: &mut Prepared) {
    let [c, power] = v.params();
    let scale = if c == -1.0 {
        0.0
    } else {
        v.w * (c + 1.0).powf(2.0 / power)
    };
    v.p.extend_from_slice(&[power / 2.0, 1.0 / power, 2.0 / power, scale]);
}

/// murl2: like murl but divides by the (2/power)-th power of 1 + c·z^power.
fn murl2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [c, power] = v.params();
    let [half_power, inv_p, two_inv_p, scale] = v.derived();
    let ang = t.atan_yx * power;
    let r = c * t.sumsq.powf(half_power);
    let re = r * ang.cos() + 1.0;
    let im = r * ang.sin();
    let rr = (re * re + im * im).powf(inv_p);
    let ang2 = im.atan2(re) * two_inv_p;
    let (re, im) = (rr * ang2.cos(), rr * ang2.sin());
    let k = scale / (rr * rr);
    [k * (t.x * re + t.y * im), k * (t.y * re - t.x * im), 0.0]
}

// ---------------------------------------------------------------------------------------------
// nBlur.

/// Derived values: exact, circum, the sine and cosine of half a sector, the weight (adjusted to
/// linear), edges (at least 3), the hole ratio, the sector angle, the stripes' start and width,
/// has/negative stripes, the most stripes, tan(π/2 + sector/2), the two highlight arctangent
/// factors, the complement of the stripe ratio and the two stripe speeds.
fn prep_nblur(v: &mut Prepared) {
    let [
        edges,
        stripes,
        ratio_stripes,
        ratio_hole,
        circum,
        adjust,
        _,
        exact,
        highlight,
    ] = v.params();
    let edges = if edges < 3.0 { 3.0 } else { edges };
    let (mut ratio_hole, mut exact, mut highlight) = (ratio_hole, exact, highlight);
    let has_stripes = stripes != 0.0;
    let neg_stripes = stripes < 0.0;
    let abs_stripes = stripes.abs();
    let mid = TAU / edges;
    let (mut ang_stripes, mut ang_start, mut complement) = (0.0, 0.0, 0.0);
    if has_stripes {
        ang_stripes = mid / (2.0 * abs_stripes);
        ang_start = ang_stripes / 2.0;
        complement = 2.0 - ratio_stripes;
    }
    if ratio_hole > 0.95 && exact == 1.0 && circum == 0.0 {
        ratio_hole = 0.95;
    }
    let tan90m2 = (FRAC_PI_2 + mid / 2.0).tan();
    let (sin_h, cos_h) = ((mid / 2.0).sin(), (mid / 2.0).cos());
    if highlight <= 0.1 {
        highlight = 0.1;
    }
    let weight = if adjust == 1.0 {
        let steps = if (edges as i32) % 4 == 0 {
            edges / 2.0 - 1.0
        } else {
            (edges / 2.0).floor()
        };
        v.w / zeps((2.0 - 2.0 * (mid * steps).cos()).sqrt() / 2.0)
    } else {
        v.w
    };
    if circum == 1.0 {
        exact = 0.0;
        highlight = 0.1;
    }
    let speed1 = complement * ang_start;
    let speed2 = ratio_stripes * ang_start;
    let max_stripes = 2.0 * abs_stripes;
    let spread = if neg_stripes { 7.5 } else { 13.0 };
    let atan1 = (spread / edges.powf(1.3)) * highlight;
    let atan2 = 2.0 * (atan1 / -2.0).atan();
    let flag = |b: bool| if b { 1.0 } else { 0.0 };
    v.p.extend_from_slice(&[
        exact,
        circum,
        sin_h,
        cos_h,
        weight,
        edges,
        ratio_hole,
        mid,
        ang_start,
        ang_stripes,
        flag(has_stripes),
        flag(neg_stripes),
        max_stripes,
        tan90m2,
        atan1,
        atan2,
        complement,
        speed1,
        speed2,
    ]);
}

/// One random point of nBlur's polygon: its (sin, cos)-ordered coordinates and the inner and
/// outer edge distances in its direction.
struct NbSample {
    x: f64,
    y: f64,
    inner: f64,
    outer: f64,
    len: f64,
}

/// Draw one point in nBlur's polygon (possibly striped, with a hole).
fn nblur_sample(v: &Prepared, rng: &mut FastRng) -> NbSample {
    let [_, _, ratio_stripes, _, _, _, equal] = v.params();
    let [
        exact,
        circum,
        _sin_h,
        _cos_h,
        _weight,
        edges,
        ratio_hole,
        mid,
        ang_start,
        ang_stripes,
        has_stripes,
        neg_stripes,
        max_stripes,
        tan90m2,
        atan1,
        atan2,
        ratio_complement,
        speed1,
        speed2,
    ] = v.derived();
    let exact = exact == 1.0;
    let circum = circum == 1.0;
    let equal = equal == 1.0;
    let mut ang = if exact {
        rng.f01() * TAU
    } else {
        ((atan1 * (rng.f01() - 0.5)).atan() / atan2 + 0.5 + rand_size(rng, edges)) * mid
    };
    // Note: x takes the sine and y the cosine of the direction.
    let (mut x, mut y) = (ang.sin(), ang.cos());
    let mut mem = ang;
    while ang > mid {
        ang -= mid;
    }
    if has_stripes == 1.0 {
        let neg = neg_stripes == 1.0;
        // The negative-stripe mode swaps the roles of the stripe ratio and its complement, and
        // of which stripe parity gets shifted and which gets rescaled.
        let (ratio, speed) = if neg {
            (ratio_complement, speed1)
        } else {
            (ratio_stripes, speed2)
        };
        let shifted = if neg { 0 } else { 1 };
        let mut count = 0i32;
        let mut edge = ang_start;
        while ang > edge {
            edge += ang_stripes;
            if edge > mid {
                edge = mid;
            }
            count += 1;
        }
        if edge != mid {
            edge -= ang_start;
        }
        let at_last = |count: i32| count as f64 == max_stripes;
        if count & 1 == shifted {
            let forward = ang > edge && (!neg || !at_last(count));
            if forward {
                ang += ang_start;
                mem += ang_start;
                edge += ang_stripes;
                count += 1;
            } else {
                ang -= ang_start;
                mem -= ang_start;
                edge -= ang_stripes;
                count -= 1;
            }
            (x, y) = (mem.sin(), mem.cos());
        }
        let rescaled = count & 1 != shifted;
        if rescaled && ratio > 1.0 {
            if ang > edge && !at_last(count) {
                mem = mem - ang + edge + (ang - edge) / ang_start * ratio * ang_start;
            } else {
                mem = mem - ang + edge - (edge - ang) / ang_start * ratio * ang_start;
            }
            ang = edge + (ang - edge) / ang_start * ratio * ang_start;
            (x, y) = (mem.sin(), mem.cos());
        }
        if rescaled && ratio < 1.0 {
            let squeeze_down = |ang: f64, edge: f64| {
                let num = (edge - speed - ang) * speed;
                num / (ang_start - speed)
            };
            if (ang - edge).abs() > speed && !at_last(count) {
                if ang - edge > speed {
                    let num = (ang - (edge + speed)) * speed;
                    let k = num / (ang_start - speed);
                    let a = mem - ang + edge + k;
                    (x, y) = (a.sin(), a.cos());
                    ang = edge + k;
                }
                if edge - ang > speed {
                    let k = squeeze_down(ang, edge);
                    let a = mem - ang + edge - k;
                    (x, y) = (a.sin(), a.cos());
                    ang = edge - k;
                }
            }
            if at_last(count) {
                if neg {
                    edge = mid;
                }
                if edge - ang > speed {
                    let k = squeeze_down(ang, edge);
                    let a = mem - ang + edge - k;
                    (x, y) = (a.sin(), a.cos());
                    ang = edge - k;
                }
            }
        }
    }
    let tan_ang = ang.tan();
    let ex = tan90m2 / (tan90m2 - tan_ang);
    let ey = ex * tan_ang;
    let outer = (ex * ex + ey * ey).sqrt();
    let draw = |rng: &mut FastRng| {
        if equal { rng.f01().sqrt() } else { rng.f01() }
    };
    let mut radius = if exact || circum {
        draw(rng)
    } else {
        draw(rng) * outer
    };
    let inner = ratio_hole * outer;
    if !exact && radius < inner {
        radius = if circum {
            inner + draw(rng) * (1.0 - inner + f64::EPSILON)
        } else {
            inner + draw(rng) * (outer - inner)
        };
    }
    x *= radius;
    y *= radius;
    NbSample {
        x,
        y,
        inner,
        outer,
        len: (x * x + y * y).sqrt(),
    }
}

/// nBlur: a blur filling a regular polygon (optionally striped, with a central hole,
/// highlighted edges, or its circumcircle), turned by half a sector.
fn nblur(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [exact, circum, sn, cs, weight] = v.derived();
    let mut s = nblur_sample(v, rng);
    if exact == 1.0 && circum == 0.0 {
        while s.len < s.inner || s.len > s.outer {
            s = nblur_sample(v, rng);
        }
    }
    let x = cs * s.x - sn * s.y;
    let y = sn * s.x + cs * s.y;
    [weight * x, weight * y, 0.0]
}

// ---------------------------------------------------------------------------------------------
// N, O.

fn prep_npolar(v: &mut Prepared) {
    let [parity, n] = v.params();
    let nnz = if n == 0.0 { 1.0 } else { n };
    let vvar = v.w / PI;
    v.p.extend_from_slice(&[
        nnz,
        vvar,
        vvar * 0.5,
        nnz.abs(),
        1.0 / nnz / 2.0,
        parity.abs() % 2.0,
    ]);
}

/// npolar: with odd parity a julian-style n-th root; with even parity the same root taken of
/// the point's log-polar image, the result mapped back through the log-polar map.
fn npolar(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [parity] = v.params();
    let [nnz, vvar, vvar2, abs_n, exponent, odd] = v.derived();
    let (x, y) = if odd != 0.0 {
        let ang = (t.atan_yx + TAU * rand_size(rng, abs_n)) / nnz;
        let mut r = v.w * t.sumsq.powf(exponent);
        if v.compat {
            r *= parity;
        }
        (ang.cos() * r, ang.sin() * r)
    } else {
        let lx = vvar * t.atan_xy;
        let ly = vvar2 * t.sumsq.ln();
        let ang = (ly.atan2(lx) + TAU * rand_size(rng, abs_n)) / nnz;
        let mut r = v.w * (lx * lx + ly * ly).powf(exponent);
        if !v.compat {
            r *= parity;
        }
        let (s, c) = (ang.sin() * r, ang.cos() * r);
        let x = if v.compat {
            vvar2 * (c * c + s * s).ln()
        } else {
            vvar2 * 2.0 * r.ln()
        };
        (x, vvar * c.atan2(s))
    };
    [x, y, 0.0]
}

/// octagon: a 3-D inversion in the "octagonal" norm x⁴ + y⁴ + 2z² where it is strong (factor
/// below 2); elsewhere the point is scaled and pushed away from the axes by (x, y, z).
fn octagon(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [ox, oy, oz] = v.params();
    let (x2, y2, z2) = (t.x * t.x, t.y * t.y, t.z * t.z);
    let k = v.w / zeps(x2 * x2 + z2 + y2 * y2 + z2);
    if k < 2.0 {
        return [k * t.x, k * t.y, k * t.z];
    }
    let away = |u: f64, off: f64| {
        if u >= 0.0 {
            v.w * (u + off)
        } else {
            v.w * (u - off)
        }
    };
    [away(t.x, ox), away(t.y, oy), away(t.z, oz)]
}

/// Fractorium's rounded 1/√2 for octapol's disc radius (kept rounded to reproduce it).
#[allow(clippy::approx_constant)]
const OCTAPOL_HALF_SQRT2: f64 = 0.707_106_781;

/// Derived values: the disc radius, the half-size of the shape, then the corner points A..L as
/// x, y pairs.
fn prep_octapol(v: &mut Prepared) {
    let [_, radius, s, t] = v.params();
    let (s, t) = (s.abs(), t.abs());
    let h = 0.5 * s;
    let rad = OCTAPOL_HALF_SQRT2 * s * radius.abs();
    v.p.extend_from_slice(&[
        rad,
        h + t,
        // A B C D
        -h,
        h + t,
        h,
        h + t,
        t,
        h,
        t,
        -h,
        // E F G H
        h,
        -h - t,
        -h,
        -h - t,
        -t,
        -h,
        -t,
        h,
        // I J K L
        -h,
        h,
        h,
        h,
        -h,
        -h,
        h,
        -h,
    ]);
}

/// octapol: keeps the points of an octagon-like shape built from rectangles and triangles
/// (sizes s and t), with a polar-warped disc in its centre; points elsewhere are removed from
/// the running sum. The output adds a scaled copy of the (shrunken) input.
fn octapol(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [pw] = v.params();
    let [rad, st] = v.derived();
    let corners = v.table(2);
    let w = v.w;
    let pt = |i: usize| (corners[2 * i], corners[2 * i + 1]);
    let (a, b, c, d, e, f) = (pt(0), pt(1), pt(2), pt(3), pt(4), pt(5));
    let (g, h, i, j, k, l) = (pt(6), pt(7), pt(8), pt(9), pt(10), pt(11));
    let x = t.x * 0.15;
    let y = t.y * 0.15;
    let in_rect = |tl: (f64, f64), br: (f64, f64)| x >= tl.0 && y >= tl.1 && x <= br.0 && y <= br.1;
    let in_tri = |a: (f64, f64), b: (f64, f64), c: (f64, f64)| {
        let (v0x, v0y) = (c.0 - a.0, c.1 - a.1);
        let (v1x, v1y) = (b.0 - a.0, b.1 - a.1);
        let (v2x, v2y) = (x - a.0, y - a.1);
        let d00 = v0x * v0x + v0y * v0y;
        let d01 = v0x * v1x + v0y * v1y;
        let d02 = v0x * v2x + v0y * v2y;
        let d11 = v1x * v1x + v1y * v1y;
        let d12 = v1x * v2x + v1y * v2y;
        let den = d00 * d11 - d01 * d01;
        let (u, vv) = if den != 0.0 {
            ((d11 * d02 - d01 * d12) / den, (d00 * d12 - d01 * d02) / den)
        } else {
            (0.0, 0.0)
        };
        (u + vv) < 1.0 && u > 0.0 && vv > 0.0
    };
    let mut extra = (0.0, 0.0);
    let mut keep = true;
    let r = if rad > 0.0 {
        (x * x + y * y).sqrt()
    } else {
        0.0
    };
    if rad > 0.0 && r <= rad {
        let rd = (sqr(r / rad)).ln();
        let phi = y.atan2(x);
        extra = (w * mix(x, phi, rd * pw), w * mix(y, r, rd * pw));
    } else if x.abs() <= st && y.abs() <= st {
        if in_rect(h, k)
            || in_rect(j, d)
            || in_rect(a, j)
            || in_rect(k, e)
            || in_tri(i, a, h)
            || in_tri(j, b, c)
            || in_tri(l, d, e)
            || in_tri(k, f, g)
        {
            extra = (w * x, w * y);
        } else {
            keep = false;
        }
    } else {
        keep = false;
    }
    if !keep && v.form != Form::Pre {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [extra.0 + w * x, extra.1 + w * y, w * t.z]
}

/// One ortho step: the circle through the point orthogonal to the unit circle (centre `xo` on
/// the x axis, radius `ro`), on which the point is moved by the angle `turn`·θ, wrapped into
/// (−θ, θ]. Works on x ≥ 0 (callers mirror). Returns the new point.
#[inline(always)]
fn ortho_step(x: f64, y: f64, xo: f64, turn: f64) -> (f64, f64) {
    let ro = ((x - xo) * (x - xo) + y * y).sqrt();
    let theta = 1.0f64.atan2(ro);
    let a = (turn * theta + y.atan2(xo - x) + theta) % (2.0 * theta) - theta;
    (xo - a.cos() * ro, a.sin() * ro)
}

/// ortho: moves points along circles orthogonal to the unit circle (by `in` inside the disc,
/// by `out` for the inverted image of outside points).
fn ortho(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [turn_in, turn_out] = v.params();
    let w = v.w;
    let r = t.sumsq;
    if r < 1.0 {
        if t.x >= 0.0 {
            let xo = (r + 1.0) / zeps(2.0 * t.x);
            let ro = ((t.x - xo) * (t.x - xo) + t.y * t.y).sqrt();
            let theta = 1.0f64.atan2(ro);
            let a = (turn_in * theta + t.y.atan2(xo - t.x) + theta) % (2.0 * theta) - theta;
            [w * (xo - a.cos() * ro), w * a.sin() * ro, 0.0]
        } else {
            let xo = -(r + 1.0) / (2.0 * t.x);
            let ro = ((-t.x - xo) * (-t.x - xo) + t.y * t.y).sqrt();
            let theta = 1.0f64.atan2(ro);
            let a = (turn_in * theta + t.y.atan2(xo + t.x) + theta) % (2.0 * theta) - theta;
            [-(w * (xo - a.cos() * ro)), w * a.sin() * ro, 0.0]
        }
    } else {
        let inv = 1.0 / r.sqrt();
        let x = inv * t.ux;
        let y = inv * t.uy;
        let mirrored = x < 0.0;
        let (nx, ny) = if !mirrored {
            let xo = (x * x + y * y + 1.0) / zeps(2.0 * x);
            ortho_step(x, y, xo, turn_out)
        } else {
            let xo = -(x * x + y * y + 1.0) / (2.0 * x);
            ortho_step(-x, y, xo, turn_out)
        };
        let ang = ny.atan2(nx);
        let k = 1.0 / (nx * nx + ny * ny).sqrt();
        let ox = w * k * ang.cos();
        [if mirrored { -ox } else { ox }, w * k * ang.sin(), 0.0]
    }
}

fn prep_oscilloscope2(v: &mut Prepared) {
    let [_, fx, fy] = v.params();
    v.p.push(TAU * fx);
    v.p.push(TAU * fy);
}

/// oscilloscope2: points inside a (damped, y-perturbed) cosine band around the x axis are
/// reflected through the origin, the others kept.
fn oscilloscope2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [sep, _, _, amp, pert, damp] = v.params();
    let [kx, ky] = v.derived();
    let wobble = pert * (ky * t.y).sin();
    let band = if damp == 0.0 {
        amp * (kx * t.x + wobble).cos() + sep
    } else {
        amp * (-t.x.abs() * damp).exp() * (kx * t.x + wobble).cos() + sep
    };
    if t.y.abs() <= band {
        [-(v.w * t.x), -(v.w * t.y), 0.0]
    } else {
        [v.w * t.x, v.w * t.y, 0.0]
    }
}

/// ovoid: spherical inversion with separate x and y stretches.
fn ovoid(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scale_x, scale_y] = v.params();
    let k = v.w / zeps(t.sumsq);
    [t.x * k * scale_x, t.y * k * scale_y, 0.0]
}

/// ovoid3d: 3-D spherical inversion with separate x, y and z stretches.
fn ovoid3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scale_x, scale_y, scale_z] = v.params();
    let k = v.w / zeps(t.sumsq + t.z * t.z);
    [t.x * k * scale_x, t.y * k * scale_y, t.z * k * scale_z]
}

// ---------------------------------------------------------------------------------------------
// P.

/// panorama1 / panorama2: squeeze the plane into the unit disc (by 1/√(r² + 1), or 1/(r + 1)
/// for panorama2) and unroll the disc into a strip: angle along x, radius along y.
fn panorama<const LINEAR: bool>(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let k = if LINEAR {
        1.0 / (t.sqrt + 1.0)
    } else {
        1.0 / (t.sumsq + 1.0).sqrt()
    };
    let (x1, y1) = (t.x * k, t.y * k);
    let rr = (x1 * x1 + y1 * y1).sqrt();
    [v.w * x1.atan2(y1) * FRAC_1_PI, v.w * (rr - 0.5), 0.0]
}

/// petal: cos x·(cos x·cos y)³ and cos x·(sin x·cos y)³.
fn petal(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (sx, cx) = (t.x.sin(), t.x.cos());
    let cy = t.y.cos();
    let a = cx * cy;
    let b = sx * cy;
    [v.w * cx * (a * a * a), v.w * cx * (b * b * b), 0.0]
}

fn prep_phoenix_julia(v: &mut Prepared) {
    let [power, dist] = v.params();
    let pz = zeps(power);
    let inv_n = dist / pz;
    v.p.extend_from_slice(&[inv_n, TAU / pz, inv_n / 2.0]);
}

/// phoenix_julia: a julia-style root whose angle is taken from the point stretched by
/// (1 + x_distort, 1 + y_distort); z is scaled in compatible mode.
fn phoenix_julia(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, _, xd, yd] = v.params();
    let [inv_n, step, exponent] = v.derived();
    let px = t.x * (xd + 1.0);
    let py = t.y * (yd + 1.0);
    let r = v.w * t.sumsq.powf(exponent);
    if v.compat {
        let ang = py.atan2(px) * inv_n + crand(rng) * step;
        [r * ang.cos(), r * ang.sin(), v.w * t.z]
    } else {
        let root = trunc_i32(rng.f01() * power) as f64;
        let ang = py.atan2(px) * inv_n + root * step;
        [r * ang.cos(), r * ang.sin(), v.default_z(t)]
    }
}

/// pie3D: a random point in one of `slices` pie wedges (rotated, of angular `thickness`), of
/// radius r up to the weight, lifted to z = weight·sin r.
fn pie3d(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [slices, rotation, thickness] = v.params();
    let slice = trunc_i32(rng.f01() * slices + 0.5) as f64;
    let ang = rotation + TAU * (slice + rng.f01() * thickness) / slices;
    let r = v.w * rng.f01();
    [r * ang.cos(), r * ang.sin(), v.w * r.sin()]
}

fn prep_pixel_flow(v: &mut Prepared) {
    let [angle] = v.params();
    let rad = angle * (PI / 180.0);
    v.p.push(rad.cos());
    v.p.push(rad.sin());
}

/// pixel_flow: streaks: a random displacement along the direction `angle`, of a length hashed
/// from the pixel block (of size 1/width) the point falls in; optionally sets the colour to the
/// random fade.
fn pixel_flow(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, len, width, seed, dc] = v.params();
    let [dir_x, dir_y] = v.derived();
    let block = |u: f64| -> i32 {
        let b = (u * width).floor() as i64 as i32;
        let jitter = 2.0 - 4.0 * wang_hash(trunc_i32(b as f64 * seed + 1.0));
        b.wrapping_add(trunc_i32(jitter))
    };
    let bx = block(t.x);
    let by = block(t.y);
    let h1 = wang_hash(trunc_i32(by as f64 + bx as f64 * -seed));
    let h2 = wang_hash(trunc_i32(bx as f64 + by as f64 * seed * 0.5));
    let streak = (h1 + h2) * 0.5;
    let r = rng.f01();
    let fade = streak * r * r * r * r;
    if dc != 0.0 {
        acc.color = r;
    }
    [v.w * len * dir_x * fade, v.w * len * dir_y * fade, 0.0]
}

fn prep_poincare(v: &mut Prepared) {
    let [c1r, c1a, c2r, c2a] = v.params();
    let d1 = (1.0 + c1r * c1r).sqrt();
    let d2 = (1.0 + c2r * c2r).sqrt();
    let (a1, a2) = (c1a % PI, c2a % PI);
    v.p.extend_from_slice(&[d1 * a1.cos(), d1 * a1.sin(), d2 * a2.cos(), d2 * a2.sin()]);
}

/// poincare: two successive inversions in circles of radii c1r, c2r orthogonal to the unit
/// circle, centred in the directions c1a, c2a (weight not used).
fn poincare(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [c1r, _, c2r] = v.params();
    let [c1x, c1y, c2x, c2y] = v.derived();
    let invert = |x: f64, y: f64, cx: f64, cy: f64, rr: f64| {
        let (dx, dy) = (x - cx, y - cy);
        let den = zeps(dx * dx + dy * dy);
        (cx + (rr * dx) / den, cy + (rr * dy) / den)
    };
    let (x, y) = invert(t.x, t.y, c1x, c1y, c1r * c1r);
    let (x, y) = invert(x, y, c2x, c2y, c2r * c2r);
    [x, y, 0.0]
}

fn prep_poincare2(v: &mut Prepared) {
    let [pp, qq] = v.params();
    let a0 = TAU / pp;
    let dist2 = 1.0 - (a0.cos() - 1.0) / (a0.cos() + (TAU / qq).cos());
    let dist = if dist2 > 0.0 { 1.0 / dist2.sqrt() } else { 1.0 };
    let (cx, cy) = if 1.0 / pp + 1.0 / qq < 0.5 {
        (a0.cos() * dist, a0.sin() * dist)
    } else {
        (0.0, 0.0)
    };
    v.p.push(cx);
    v.p.push(cy);
}

/// poincare2: the hyperbolic translation of the Poincaré disc (z − c)/(1 − c̄·z) that moves the
/// centre c of a neighbouring tile of the {p, q} tiling to the origin.
fn poincare2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cx, cy] = v.derived();
    let a = t.x - cx;
    let b = t.y - cy;
    let c = 1.0 - cx * t.x - cy * t.y;
    let d = cy * t.x - cx * t.y;
    let k = v.w / zeps(c * c + d * d);
    [(a * c + b * d) * k, (b * c - a * d) * k, 0.0]
}

fn prep_poincare3d(v: &mut Prepared) {
    let [r, a, b] = v.params();
    let cx = -r * (a * FRAC_PI_2).cos() * (b * FRAC_PI_2).cos();
    let cy = r * (a * FRAC_PI_2).sin() * (b * FRAC_PI_2).cos();
    let cz = -r * (b * FRAC_PI_2).sin();
    let (sx, sy, sz) = (cx * cx, cy * cy, cz * cz);
    v.p.extend_from_slice(&[
        cx,
        cy,
        cz,
        sx + sy + sz,
        2.0 * cx,
        2.0 * cy,
        2.0 * cz,
        sx - sy - sz + 1.0,
        sy - sx - sz + 1.0,
        sz - sy - sx + 1.0,
    ]);
}

/// poincare3D: the 3-D Möbius translation of the unit ball moving the point c (of length r,
/// direction given by the angles a and b) to the origin.
fn poincare3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cx, cy, cz, c2, c2x, c2y, c2z, s2x, s2y, s2z] = v.derived();
    let r2 = t.sumsq + t.z * t.z;
    let px = c2x * t.x;
    let py = c2y * t.y;
    let pz = c2z * t.z;
    let d = v.w / zeps(c2 * r2 - px - py - pz + 1.0);
    [
        d * (t.x * s2x + cx * (py + pz - r2 - 1.0)),
        d * (t.y * s2y + cy * (px + pz - r2 - 1.0)),
        d * (t.z * s2z + cz * (py + px - r2 - 1.0)),
    ]
}

fn prep_point_symmetry(v: &mut Prepared) {
    let [_, _, order] = v.params();
    v.p.push(TAU / zeps(order));
}

/// point_symmetry: rotates the point (scaled by the weight about the centre) about the centre
/// by a random multiple of 2π/order.
fn point_symmetry(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [cx, cy, order] = v.params();
    let [step] = v.derived();
    let ang = (rng.f01() * order).floor() * step;
    let dx = (t.x - cx) * v.w;
    let dy = (t.y - cy) * v.w;
    let (s, c) = (ang.sin(), ang.cos());
    [cx + dx * c + dy * s, cy + dy * c - dx * s, 0.0]
}

/// polynomial: per coordinate a signed power of |weight·u| plus a linear term lc·u and a
/// constant sc; z is scaled by the weight.
fn polynomial(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [powx, powy, lcx, lcy, scx, scy] = v.params();
    let aw = v.w.abs();
    let xp = (aw * t.x.abs()).powf(powx);
    let yp = (aw * t.y.abs()).powf(powy);
    [
        xp * sign(t.x) + lcx * t.x + scx,
        yp * sign(t.y) + lcy * t.y + scy,
        v.w * t.z,
    ]
}

fn prep_popcorn2_3d(v: &mut Prepared) {
    let [_, _, _, c] = v.params();
    let w = v.w;
    let vv = if w.abs() <= 1.0 { w.abs() * w } else { w };
    v.p.extend_from_slice(&[c.tan().sin(), w * 0.5, vv]);
}

/// popcorn2_3D: popcorn2 (x + px·sin tan(c·y), y + py·sin tan(c·x)), halved, with a z made
/// from the input z (or the angle when z is 0) and, when the running z is still 0, the angle.
fn popcorn2_3d(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [px, py, pz, c] = v.params();
    let [sin_tan_c, half_w, vv] = v.derived();
    let from_angle = vv * sin_tan_c * t.atan_yx;
    let z_in = if t.z == 0.0 { from_angle } else { t.z };
    let other_z = if v.form == Form::Pre { t.z } else { acc.z };
    let lift = if other_z == 0.0 { from_angle } else { 0.0 };
    [
        half_w * (t.x + px * (c * t.y).tan().sin()),
        half_w * (t.y + py * (c * t.x).tan().sin()),
        lift + vv * (pz * sin_tan_c * z_in),
    ]
}

/// post_smartcrop's state slots: the last kept point (x, y, z) and its colour.
mod sc {
    pub const SX: usize = 0;
    pub const SY: usize = 1;
    pub const SZ: usize = 2;
    pub const SC: usize = 3;
}

/// Derived values: the crop mode (1 keeps the inside), radial (1 for a sector), |radius|, the
/// working power, the polygon's angle, the rounding factor and the rotation.
fn prep_post_smartcrop(v: &mut Prepared) {
    let [power, radius, roundstr, _, _, _, _, _, rotation] = v.params();
    let mode = if (power > 0.0) == (radius > 0.0) {
        1.0
    } else {
        0.0
    };
    let mut work_power = zeps(power).abs();
    let (radial, mut alpha, mut round, mut work_rot) = (work_power < 2.0, 0.0, 0.0, 0.0);
    if radial {
        work_power *= PI;
    } else {
        alpha = TAU / work_power;
        round = roundstr / zeps((alpha / 2.0).sin()) / work_power * 2.0;
        work_rot = rotation * alpha;
    }
    v.p.extend_from_slice(&[
        mode,
        if radial { 1.0 } else { 0.0 },
        radius.abs(),
        work_power,
        alpha,
        round,
        work_rot,
    ]);
    for i in 0..4 {
        v.state.set(i, 0.0);
    }
}

/// post_smartcrop: crops the summed point to a polygon (power ≥ 2 sides, optionally rounded
/// and distorted) or to an angular sector (power < 2); cropped points are removed, pushed onto
/// the crop edge (scattered), or replaced by the last kept point. Fractorium's `static` modes
/// ≤ 1 read the xform's pre-variation point, which this framework does not pass to post_
/// variations: the summed point is used instead.
fn post_smartcrop(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _power,
        _radius,
        roundstr,
        roundwidth,
        distortion,
        edge_p,
        scatter,
        offset,
        _rotation,
        cropmode,
        stat,
    ] = v.params();
    let [mode, radial, radius, power, alpha, round, rotation] = v.derived();
    let w = v.w;
    let mode = mode as i32;
    let absolute = stat > 1.0 || stat == -1.0;
    let (xi, yi, zi) = (t.x, t.y, t.z);
    let ang = yi.atan2(xi);
    let rad = (xi * xi + yi * yi).sqrt();
    let st = &v.state;
    let last_kept = |acc: &mut Acc| -> V3 {
        acc.color = st.get(sc::SC);
        let s = [st.get(sc::SX), st.get(sc::SY), st.get(sc::SZ)];
        if absolute {
            s
        } else {
            [t.x + s[0], t.y + s[1], t.z + s[2]]
        }
    };
    let placed = |r: f64, a: f64| -> V3 {
        let o = [w * r * a.cos(), w * r * a.sin(), w * zi];
        if absolute {
            o
        } else {
            [t.x + o[0], t.y + o[1], t.z + o[2]]
        }
    };
    if radial != 0.0 {
        let edge = edge_p * (rng.f01() - 0.5);
        let mut xang = ang / TAU + 1.0 + edge;
        xang = (xang - xang.trunc()) * TAU;
        if ((xang > power) as i32) == mode {
            if cropmode == 2.0 {
                return last_kept(acc);
            }
            let a = if trunc_i32(rng.f01() * 2.0) != 0 {
                power + (rng.f01() * scatter + offset + edge) * PI
            } else {
                -(rng.f01() * scatter + offset + edge) * PI
            };
            return placed(rad, a);
        }
    } else {
        let coeff = if distortion == 0.0 {
            1.0
        } else {
            let mut xang = (ang + PI) / alpha;
            xang -= xang.trunc();
            xang = if xang < 0.5 { xang } else { 1.0 - xang };
            let mut k = 1.0 / (xang * alpha).cos();
            if roundstr != 0.0 {
                let ww = if roundwidth != 1.0 {
                    ((xang * 2.0).ln() * roundwidth).exp()
                } else {
                    xang * 2.0
                } * round;
                k = ((1.0 - ww) * k + ww).abs();
            }
            if distortion != 1.0 {
                k = (k.ln() * distortion).exp();
            }
            k
        };
        let xr = coeff
            * if edge_p != 0.0 {
                radius + edge_p * (rng.f01() - 0.5)
            } else {
                radius
            };
        if ((rad > xr) as i32) == mode {
            if cropmode == 2.0 {
                return last_kept(acc);
            }
            if cropmode != 0.0 {
                let rdc = if cropmode == -1.0 {
                    rad
                } else {
                    xr + coeff * (rng.f01() * scatter + offset)
                };
                return placed(rdc, ang + rotation);
            }
            // Removed: the origin in the absolute modes; otherwise the point is left as is.
            return if absolute {
                [0.0, 0.0, 0.0]
            } else {
                [t.x, t.y, t.z]
            };
        }
    }
    // Kept: remember it (scaled by the weight) for the "last kept point" crop mode.
    let s = [w * xi, w * yi, w * zi];
    st.set(sc::SX, s[0]);
    st.set(sc::SY, s[1]);
    st.set(sc::SZ, s[2]);
    if cropmode == 2.0 {
        st.set(sc::SC, acc.color);
    }
    if stat > 0.0 {
        s
    } else {
        [t.x + s[0], t.y + s[1], t.z + s[2]]
    }
}

fn prep_pow_block(v: &mut Prepared) {
    let [num, den, _, cn, cd] = v.params();
    v.p.push(num / zeps(den * cn * (1.0 / cd)));
}

/// pow_block: the power z^(numerator/denominator·corrections) with a random root branch
/// (scaled by `root`), the angle taken as numerator·(θ + 2π·k·root)/denominator.
fn pow_block(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [num, den, root] = v.params();
    let [power] = v.derived();
    let r = t.sumsq.powf(power * 0.5) * v.w;
    let dz = zeps(den);
    let ang = (t.atan_yx / dz + (root * TAU * (rng.f01() * den).floor() / dz)) * num;
    [r * ang.cos(), r * ang.sin(), 0.0]
}
