//! Variations (slice fr_a of the registry): Fractorium's catalogue from `arcsech` to
//! `crescents`.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions
//! and pole guards included) so that a flame renders the same; the code is ugnis's own.

use std::f64::consts::{FRAC_1_PI, FRAC_2_PI, FRAC_PI_2, FRAC_PI_4, PI, TAU};

use super::noise::simplex_noise3;
use super::util::{
    Cplx, bipolar, crand, floor_i64, from_bipolar, lattice_noise_2d, lrint, quat_mul_conj,
    safe_sqrt, sign, sign_nz, sine_hash, sqr, square_arc, trunc_i32, zeps,
};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("arcsech", arcsech).prepare(prep_arcsech),
    VarDef::new("arcsech2", arcsech2).prepare(prep_arcsech2),
    VarDef::new("arcsinh", arcsinh).prepare(prep_arcsinh),
    VarDef::new("arctanh", arctanh).prepare(prep_arcsech),
    VarDef::new("asteria", asteria)
        .params(&[p_cyclic("asteria_alpha", 0.0, 0.0, 1.0)])
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(prep_asteria),
    VarDef::new("barycentroid", barycentroid)
        .params(&[
            p("barycentroid_a", 1.0),
            p("barycentroid_b", 0.0),
            p("barycentroid_c", 0.0),
            p("barycentroid_d", 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("bcircle", bcircle)
        .params(&[p("bcircle_scale", 1.0), p("bcircle_borderwidth", 0.0)])
        .flags(flag::RANDOM)
        .prepare(prep_bcircle),
    VarDef::new("bCollide", bcollide)
        .params(&[
            p_cyclic("bCollide_a", 0.0, -1.0, 1.0),
            p_range("bCollide_num", 1.0, f64::EPSILON, 2147483647.0),
        ])
        .prepare(prep_bcollide),
    VarDef::new("bisplit", bisplit),
    VarDef::new("blade3D", blade3d)
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("blob2", blob2)
        .params(&[
            p("blob2_mode", 0.5),
            p("blob2_n", 1.0),
            p("blob2_radius", 0.0),
            p("blob2_prescale", 1.0),
            p("blob2_postscale", 0.5),
            p_range("blob2_symmetry", 0.0, -1.0, 1.0),
            p("blob2_compensation", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_blob2),
    VarDef::new("blob3D", blob3d)
        .params(&[
            p("blob3D_low", 0.0),
            p("blob3D_high", 1.0),
            p("blob3D_waves", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES | need::ATAN_XY)
        .flags(flag::WRITES_Z),
    VarDef::new("block", block).needs(need::SUMSQ),
    VarDef::new("blocky", blocky)
        .params(&[
            p("blocky_x", 1.0),
            p("blocky_y", 1.0),
            p_nonzero("blocky_mp", 4.0, f64::NEG_INFINITY, f64::INFINITY),
        ])
        .needs(need::SUMSQ),
    VarDef::new("blur3D", blur3d)
        .batch(super::inline_batch!(blur3d))
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
    VarDef::new("blur_circle", blur_circle)
        .batch(super::inline_batch!(blur_circle))
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .sum(),
    VarDef::new("blur_heart", blur_heart)
        .params(&[
            p("blur_heart_p", 0.5),
            p("blur_heart_a", -0.6),
            p("blur_heart_b", 0.7),
        ])
        .flags(flag::RANDOM)
        .sum(),
    VarDef::new("blur_linear", blur_linear)
        .batch(super::inline_batch!(blur_linear))
        .params(&[
            p("blur_linear_length", 0.0),
            p_cyclic("blur_linear_angle", 0.0, 0.0, TAU),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_blur_linear),
    VarDef::new("blur_pixelize", blur_pixelize)
        .params(&[
            p_range("blur_pixelize_size", 0.1, f64::EPSILON, f64::INFINITY),
            p("blur_pixelize_scale", 1.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_blur_pixelize),
    VarDef::new("blur_square", blur_square)
        .flags(flag::RANDOM)
        .sum(),
    VarDef::new("blur_zoom", blur_zoom)
        .batch(super::inline_batch!(blur_zoom))
        .params(&[
            p("blur_zoom_length", 0.0),
            p("blur_zoom_x", 0.0),
            p("blur_zoom_y", 0.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("bMod", bmod).params(&[
        p_range("bMod_radius", 1.0, 0.0, f64::INFINITY),
        p_cyclic("bMod_distance", 0.0, 0.0, 2.0),
    ]),
    VarDef::new("boarders2", boarders2)
        .params(&[
            p("boarders2_c", 0.5),
            p("boarders2_left", 0.5),
            p("boarders2_right", 0.5),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_boarders2),
    VarDef::new("bSwirl", bswirl).params(&[p("bSwirl_in", 0.0), p("bSwirl_out", 0.0)]),
    VarDef::new("bTransform", btransform)
        .batch(super::inline_batch!(btransform))
        .params(&[
            p("bTransform_rotate", 0.0),
            p_nonzero("bTransform_power", 0.0, 1.0, 2147483647.0),
            p("bTransform_move", 0.0),
            p("bTransform_split", 0.0),
        ]),
    VarDef::new("bubble2", bubble2)
        .batch(super::inline_batch!(bubble2))
        .params(&[
            p("bubble2_x", 1.0),
            p("bubble2_y", 1.0),
            p("bubble2_z", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("bubbleT3D", bubble_t3d)
        .params(&[
            p_int(
                "bubbleT3D_number_of_stripes",
                0.0,
                f64::NEG_INFINITY,
                f64::INFINITY,
            ),
            p_range("bubbleT3D_ratio_of_stripes", 1.0, 0.0, 2.0),
            p_range("bubbleT3D_angle_of_hole", 0.0, -360.0, 360.0),
            p("bubbleT3D_exponentZ", 1.0),
            p_int("bubbleT3D_symmetryZ", 0.0, 0.0, 1.0),
            p_int("bubbleT3D_modusBlur", 0.0, 0.0, 1.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::WRITES_Z)
        .prepare(prep_bubble_t3d),
    VarDef::new("bwraps", bwraps)
        .batch(super::inline_batch!(bwraps))
        .params(&[
            p("bwraps_cellsize", 1.0),
            p("bwraps_space", 0.0),
            p("bwraps_gain", 1.0),
            p("bwraps_inner_twist", 0.0),
            p("bwraps_outer_twist", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_bwraps),
    VarDef::new("bwraps_rand", bwraps_rand)
        .params(&[
            p("bwraps_rand_cellsize", 1.0),
            p("bwraps_rand_space", 0.0),
            p("bwraps_rand_gain", 2.0),
            p("bwraps_rand_inner_twist", 0.0),
            p("bwraps_rand_outer_twist", 0.0),
            p("bwraps_rand_symm", 0.0),
            p("bwraps_rand_seed", 1.0),
        ])
        .prepare(prep_bwraps_rand),
    VarDef::new("cardioid", cardioid)
        .params(&[p("cardioid_a", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES | need::ATAN_YX),
    VarDef::new("checks", checks)
        .params(&[
            p("checks_x", 0.5),
            p("checks_y", 0.5),
            p("checks_size", 0.5),
            p("checks_rnd", 0.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_checks),
    VarDef::new("Circle_Rand", circle_rand_hash)
        .params(&[
            p("Circle_Rand_X", 10.0),
            p("Circle_Rand_Y", 10.0),
            p_range("Circle_Rand_size", 1.0, 0.0, f64::INFINITY),
            p("Circle_Rand_power", 1.0),
            p_range("Circle_Rand_density", 1.0, 0.0, 1.0),
            p("Circle_Rand_seed", 1.0),
        ])
        .flags(flag::RANDOM),
    VarDef::new("circleblur", circleblur)
        .flags(flag::RANDOM)
        .sum(),
    VarDef::new("circlecrop", circlecrop)
        .batch(super::inline_batch!(circlecrop))
        .params(&[
            p("circlecrop_radius", 1.0),
            p("circlecrop_x", 0.0),
            p("circlecrop_y", 0.0),
            p("circlecrop_scatter_area", 0.0),
            p_range("circlecrop_zero", 1.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC | flag::COMPAT),
    VarDef::new("circlecrop2", circlecrop2)
        .params(&[
            p("circlecrop2_inner", 0.5),
            p("circlecrop2_outer", 1.0),
            p_range("circlecrop2_zero", 1.0, 0.0, 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(prep_circlecrop2),
    VarDef::new("CircleLinear", circle_linear).params(&[
        p_nonzero("CircleLinear_Sc", 1.0, f64::NEG_INFINITY, f64::INFINITY),
        p("CircleLinear_K", 0.5),
        p("CircleLinear_Dens1", 0.5),
        p("CircleLinear_Dens2", 0.5),
        p("CircleLinear_Reverse", 1.0),
        p("CircleLinear_X", 10.0),
        p("CircleLinear_Y", 10.0),
        p_int("CircleLinear_Seed", 0.0, f64::NEG_INFINITY, f64::INFINITY),
    ]),
    VarDef::new("CircleRand", circle_rand)
        .params(&[
            p_nonzero("CircleRand_Sc", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p("CircleRand_Dens", 0.5),
            p("CircleRand_X", 10.0),
            p("CircleRand_Y", 10.0),
            p_int("CircleRand_Seed", 0.0, f64::NEG_INFINITY, f64::INFINITY),
        ])
        .flags(flag::RANDOM)
        .sum(),
    VarDef::new("circlesplit", circlesplit)
        .params(&[p("circlesplit_radius", 1.0), p("circlesplit_split", 0.5)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX),
    VarDef::new("CircleTrans1", circle_trans1)
        .params(&[
            p_nonzero("CircleTrans1_Sc", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p("CircleTrans1_Dens", 0.5),
            p("CircleTrans1_X", 10.0),
            p("CircleTrans1_Y", 10.0),
            p_int("CircleTrans1_Seed", 0.0, f64::NEG_INFINITY, f64::INFINITY),
        ])
        .flags(flag::RANDOM),
    VarDef::new("circlize", circlize).params(&[p("circlize_hole", 0.0)]),
    VarDef::new("circlize2", circlize2).params(&[p("circlize2_hole", 0.0)]),
    VarDef::new("circus", circus)
        .params(&[p("circus_scale", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES),
    VarDef::new("collideoscope", collideoscope)
        .params(&[p("collideoscope_a", 0.0), p("collideoscope_num", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(prep_collideoscope),
    VarDef::new("concentric", concentric)
        .params(&[
            p("concentric_radius", 1.0),
            p_nonzero("concentric_density", 10.0, f64::NEG_INFINITY, f64::INFINITY),
            p("concentric_R_blur", 0.0),
            p("concentric_Z_blur", 0.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::WRITES_ACC)
        .sum(),
    VarDef::new("coshq", coshq).flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("cosq", cosq).flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("coswrap", coswrap)
        .params(&[
            p_int_nonzero("coswrap_repeat", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p("coswrap_amount_x", 0.0),
            p("coswrap_amount_y", 0.0),
            p_cyclic("coswrap_phase_x", 0.0, -1.0, 1.0),
            p_cyclic("coswrap_phase_y", 0.0, -1.0, 1.0),
        ])
        .prepare(prep_coswrap),
    VarDef::new("coth_spiral", coth_spiral)
        .params(&[p("coth_spiral_a", 4.0)])
        .flags(flag::RANDOM),
    VarDef::new("cothq", cothq).flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("cotq", cotq).flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("cpow2", cpow2)
        .params(&[
            p("cpow2_r", 1.0),
            p("cpow2_a", 0.0),
            p("cpow2_divisor", 1.0),
            p("cpow2_spread", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_cpow2),
    VarDef::new("cpow3", cpow3)
        .params(&[
            p("cpow3_r", 1.0),
            p_nonzero("cpow3_d", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p_nonzero("cpow3_divisor", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p("cpow3_spread", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_cpow3),
    VarDef::new("crackle", crackle)
        .batch(super::inline_batch!(crackle))
        .params(&[
            p_range("crackle_cellsize", 1.0, 0.0001, f64::INFINITY),
            p("crackle_power", 0.2),
            p("crackle_distort", 0.0),
            p("crackle_scale", 1.0),
            p("crackle_z", 0.0),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_crackle),
    VarDef::new("crackle2", crackle2)
        .params(&[p_range("crackle2_cellsize", 1.0, 0.0001, f64::INFINITY)])
        .flags(flag::RANDOM),
    VarDef::new("crescents", crescents),
];

// ---------------------------------------------------------------------------------------------
// arcsech … blur_zoom

/// Derived value: w/π.
fn prep_arcsech(v: &mut Prepared) {
    let k = v.w * FRAC_1_PI;
    v.p.push(k);
}

/// Derived value: 2w/π.
fn prep_arcsech2(v: &mut Prepared) {
    let k = v.w * FRAC_1_PI * 2.0;
    v.p.push(k);
}

/// Derived value: 2w/π.
fn prep_arcsinh(v: &mut Prepared) {
    let k = v.w * FRAC_2_PI;
    v.p.push(k);
}

/// arcsech(1/z) = ln(1/z + √(1/z + 1)·√(1/z − 1)) scaled by w/π: the plane folds into a
/// horizontal strip.
fn arcsech_raw(t: &VarIn) -> Cplx {
    let z = Cplx::new(t.x, t.y).recip();
    let root = z.add_re(1.0).sqrt() * z.add_re(-1.0).sqrt();
    (z + root).ln()
}

/// Inverse hyperbolic secant, scaled by w/π: the plane maps into the strip |y| ≤ w.
fn arcsech(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let r = arcsech_raw(t).scale(k);
    [r.re, r.im, 0.0]
}

/// Inverse hyperbolic secant scaled by 2w/π, with the two halves of the strip swapped and
/// mirrored so that they tile around the real axis.
fn arcsech2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let r = arcsech_raw(t).scale(k);
    if r.im < 0.0 {
        [r.re, r.im + 1.0, 0.0]
    } else {
        [-r.re, r.im - 1.0, 0.0]
    }
}

/// Inverse hyperbolic sine ln(z + √(z² + 1)), scaled by 2w/π: a strip again.
fn arcsinh(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let z = Cplx::new(t.x, t.y);
    let r = (z + (z * z).add_re(1.0).sqrt()).ln().scale(k);
    [r.re, r.im, 0.0]
}

/// Twice the inverse hyperbolic tangent, ln((1 + z)/(1 − z)), scaled by w/π.
fn arctanh(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let z = Cplx::new(t.x, t.y);
    let r = (z.add_re(1.0) / (-z).add_re(1.0)).ln().scale(k);
    [r.re, r.im, 0.0]
}

/// Derived values: sin πα, cos πα.
fn prep_asteria(v: &mut Prepared) {
    let [alpha] = v.params();
    let (s, c) = (PI * alpha).sin_cos();
    v.p.push(s);
    v.p.push(c);
}

/// A four-pointed star: points inside the unit disc but outside the four unit discs centred
/// on (±1, ±1) stay (65 % of the time, the other points always move); the others are pushed
/// along a rotated axis onto the star's arms.
fn asteria(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    let (x0, y0) = (v.w * t.x, v.w * t.y);
    let inside_disc = x0 * x0 + y0 * y0 < 1.0;
    let near_corner = (sqr(y0.abs() - 1.0) + sqr(x0.abs() - 1.0)).sqrt() < 1.0;
    let keep = if inside_disc && near_corner {
        rng.f01() > 0.35
    } else {
        !inside_disc
    };
    if keep {
        return [x0, y0, 0.0];
    }
    let u = if v.compat {
        x0 * c - y0 * s
    } else {
        x0 * c + y0 * s
    };
    let h = x0 * s + y0 * c;
    let nx = u / (1.0 - h * h).sqrt() * (1.0 - (1.0 - sqr(1.0 - h.abs())).sqrt());
    [nx * c + h * s, -nx * s + h * c, 0.0]
}

/// Barycentric coordinates (u, v) of the point in the basis (a, b), (c, d), each combined
/// in quadrature with the matching input coordinate (keeping the sign of u or v); z is scaled.
fn barycentroid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c, d] = v.params();
    let g00 = a * a + b * b;
    let g01 = a * c + b * d;
    let g11 = c * c + d * d;
    let p0 = a * t.x + b * t.y;
    let p1 = c * t.x + d * t.y;
    let inv = 1.0 / zeps(g00 * g11 - g01 * g01);
    let u = (g11 * p0 - g01 * p1) * inv;
    let w = (g00 * p1 - g01 * p0) * inv;
    let um = (u * u + t.x * t.x).sqrt() * sign(u);
    let wm = (w * w + t.y * t.y).sqrt() * sign(w);
    [v.w * um, v.w * wm, v.w * t.z]
}

/// Derived values: |border width|, |border width| / 5.
fn prep_bcircle(v: &mut Prepared) {
    let [_, borderwidth] = v.params();
    let bw = borderwidth.abs();
    v.p.push(bw);
    v.p.push(0.2 * bw);
}

/// Keeps the scaled point inside the unit disc; outside it, the point goes to a random radius
/// in a thin ring just beyond the circle (or to the origin when the ring has no width).
fn bcircle(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scale] = v.params();
    let [bw, bw_fifth] = v.derived();
    let (x, y) = (t.x * scale, t.y * scale);
    if (x * x + y * y).sqrt() <= 1.0 {
        return [v.w * x, v.w * y, 0.0];
    }
    if bw == 0.0 {
        return [0.0, 0.0, 0.0];
    }
    let (s, c) = y.atan2(x).sin_cos();
    let rad = v.w * (bw_fifth * rng.f01() + 1.0);
    [rad * c, rad * s, 0.0]
}

/// Derived values: num/π, π/num, π·a/num.
fn prep_bcollide(v: &mut Prepared) {
    let [a, num] = v.params();
    let n = zeps(num);
    v.p.push(num * FRAC_1_PI);
    v.p.push(PI / n);
    v.p.push(PI * a / n);
}

/// Bipolar coordinates: the angle σ is cut into `num` sectors, alternately rotated by ±πa/num
/// (modulo the sector), which makes the circles through the foci collide and interleave.
fn bcollide(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [n_pi, pi_n, a_n] = v.derived();
    let (tau, sigma) = bipolar(t.x, t.y);
    let sector = trunc_i32(sigma * n_pi);
    let shift = if sector & 1 == 0 { a_n } else { -a_n };
    let sigma = sector as f64 * pi_n + (sigma + shift) % pi_n;
    let (x, y) = from_bipolar(v.w, tau, sigma);
    [x, y, 0.0]
}

/// (w/10)·(cos y / tan x, −y / sin x): a field of split, mirrored bands.
fn bisplit(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let k = v.w * 0.1;
    [k / t.x.tan() * t.y.cos(), k / t.x.sin() * -t.y, 0.0]
}

/// 3-D blade: x drives all three coordinates through the sine and cosine of a random fraction
/// of w·r.
fn blade3d(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let (s, c) = (rng.f01() * v.w * t.sqrt).sin_cos();
    let wx = v.w * t.x;
    [wx * (c + s), wx * (c - s), v.w * t.z * (s - c)]
}

/// Derived value: the compensation divisor 1 + compensation·|symmetry|.
fn prep_blob2(v: &mut Prepared) {
    let [_, _, _, _, _, sym, comp] = v.params();
    let flip = if sym < 0.0 { -1.0 } else { 1.0 };
    v.p.push(1.0 + comp * sym * flip);
}

/// Blob with a hole: inside `radius` the point is kept; outside, its distance beyond the radius
/// is modulated by a power of the angular wave sin(n·θ) + symmetry.
fn blob2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [mode, n, radius, pre, post, sym, _comp] = v.params();
    let [help] = v.derived();
    if t.sqrt < radius {
        // Fractorium leaves z unset on this branch; the point keeps its default z.
        return [v.w * t.x, v.w * t.y, v.default_z(t)];
    }
    let delta = ((t.atan_yx * n).sin() + sym) / help;
    let sgn = if delta < 0.0 { -1.0 } else { 1.0 };
    let amp = ((delta * sgn).ln() * pre).exp() * post;
    let delta = if mode != 0.0 { amp * mode } else { amp * sgn };
    let rad = radius + (t.sqrt - radius) * delta;
    [v.w * rad * t.ux, v.w * rad * t.uy, v.w * t.z]
}

/// 3-D blob: the radius oscillates between `low` and `high` with the angle atan2(x, y), and the
/// same wave lifts the point in z.
fn blob3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [low, high, waves] = v.params();
    let wave = (waves * t.atan_xy).sin();
    let r = t.sqrt * (low + (high - low) * (0.5 + 0.5 * wave));
    [v.w * t.ux * r, v.w * t.uy * r, v.w * wave * r]
}

/// The coordinate a/m mapped through arcsin, where m is half the sum of the distances to
/// (±1, 0) along that axis: squares the plane into the block [−w, w]².
#[inline(always)]
fn block_axis(c: f64, sumsq: f64) -> f64 {
    let base = sumsq + 1.0;
    let m = 0.5 * ((base + 2.0 * c).sqrt() + (base - 2.0 * c).sqrt());
    let a = c / zeps(m);
    a.atan2(safe_sqrt(1.0 - a * a))
}

/// Maps the plane into a square: each coordinate becomes the arcsine of its elliptic
/// coordinate, scaled by 2w/π.
fn block(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let k = v.w * FRAC_2_PI;
    [
        k * block_axis(t.x, t.sumsq),
        k * block_axis(t.y, t.sumsq),
        0.0,
    ]
}

/// `block` with independent x/y scales, divided by 1 + (cos x + cos y)/mp, which bulges the
/// square into rounded blocks.
fn blocky(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sx, sy, mp] = v.params();
    let r = v.w / zeps((t.x.cos() + t.y.cos()) / mp + 1.0);
    let k = v.w / FRAC_PI_2;
    [
        k * sx * block_axis(t.x, t.sumsq) * r,
        k * sy * block_axis(t.y, t.sumsq) * r,
        0.0,
    ]
}

/// A random point of the ball of radius 2w (the sum of four uniforms sets the radius, two
/// random angles the direction).
fn blur3d(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let azimuth = rng.f01() * TAU;
    let r = v.w * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
    let polar = rng.f01() * PI;
    let (sa, ca) = azimuth.sin_cos();
    let (sp, cp) = polar.sin_cos();
    [r * sp * ca, r * sp * sa, r * cp]
}

/// A uniform point of the square [−1, 1]² mapped onto the disc of radius w (squares of
/// half-side s go to circles of radius s); z is scaled.
fn blur_circle(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let x = 2.0 * rng.f01() - 1.0;
    let y = 2.0 * rng.f01() - 1.0;
    let (side, per) = square_arc(x, y);
    let r = v.w * side;
    let (s, c) = (FRAC_PI_4 * per / side - FRAC_PI_4).sin_cos();
    [r * c, r * s, v.w * t.z]
}

/// A random point inside a heart-shaped outline |x|^p, ±√(1 − x²) (scaled by a and b).
fn blur_heart(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pw, a, b] = v.params();
    let x = (rng.f01() - 0.5) * 2.0;
    let mut y = (rng.f01() - 0.5) * 2.0;
    let k = sign_nz(y);
    let lim =
        ((a * x.abs().powf(pw) + k * b * (1.0 - x * x).abs().sqrt()) - a) / zeps(a.abs() + b.abs());
    if k > 0.0 {
        if y > lim {
            y = lim;
        }
    } else if y < lim {
        y = lim;
    }
    [x * v.w, y * v.w, 0.0]
}

/// Derived values: sin and cos of the angle.
fn prep_blur_linear(v: &mut Prepared) {
    let [_, angle] = v.params();
    let (s, c) = angle.sin_cos();
    v.p.push(s);
    v.p.push(c);
}

/// Motion blur: the point is pushed a random distance up to `length` along a fixed direction.
fn blur_linear(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [length] = v.params();
    let [s, c] = v.derived();
    let d = length * rng.f01();
    [v.w * (t.x + d * c), v.w * (t.y + d * s), 0.0]
}

/// Derived values: w·size, 1/size.
fn prep_blur_pixelize(v: &mut Prepared) {
    let [size] = v.params();
    let size = zeps(size);
    v.p.push(v.w * size);
    v.p.push(1.0 / size);
}

/// Pixelation: the point goes to a random spot of the grid cell (of side `size`) it falls in,
/// the spot's spread set by `scale`.
fn blur_pixelize(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, sc] = v.params();
    let [k, inv] = v.derived();
    let cx = floor_i64(t.x * inv) as f64;
    let cy = floor_i64(t.y * inv) as f64;
    [
        k * (cx + sc * (rng.f01() - 0.5) + 0.5),
        k * (cy + sc * (rng.f01() - 0.5) + 0.5),
        v.w * t.z,
    ]
}

/// A uniform point of the square [−w, w]².
fn blur_square(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let k = 2.0 * v.w;
    [k * (rng.f01() - 0.5), k * (rng.f01() - 0.5), 0.0]
}

/// Zoom blur: a random enlargement (1 to 1 + length) about the centre (x₀, −y₀).
fn blur_zoom(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [len, cx, cy] = v.params();
    let z = 1.0 + len * rng.f01();
    [
        v.w * ((t.x - cx) * z + cx),
        v.w * ((t.y + cy) * z - cy),
        v.w * t.z,
    ]
}

// ---------------------------------------------------------------------------------------------
// bMod … CircleTrans1

/// Bipolar coordinates: inside the band |τ| < radius, τ is shifted by distance·radius and
/// wrapped back into the band, sliding the circles around the foci.
fn bmod(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [radius, dist] = v.params();
    let (mut tau, sigma) = bipolar(t.x, t.y);
    if tau < radius && -tau < radius {
        tau = (tau + radius + dist * radius) % (2.0 * radius) - radius;
    }
    let (x, y) = from_bipolar(v.w, tau, sigma);
    [x, y, 0.0]
}

/// Derived values: |c|, |c|·|left|, |c| + |c|·|right| (zeros replaced by ε).
fn prep_boarders2(v: &mut Prepared) {
    let [c, left, right] = v.params();
    let c = zeps(c.abs());
    let left = zeps(left.abs());
    let right = zeps(right.abs());
    v.p.push(c);
    v.p.push(c * left);
    v.p.push(c + c * right);
}

/// Tiles of the integer grid shrunk by c about their centres; with probability set by
/// `right`, a point is instead pushed out towards the tile's border (by `left`), along the
/// axis of its larger offset, drawing the gaps between tiles.
fn boarders2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [c, cl, cr] = v.derived();
    let rx = if t.x >= 0.0 {
        trunc_i32(t.x + 0.5)
    } else {
        trunc_i32(t.x - 0.5)
    } as f64;
    let ry = if t.y >= 0.0 {
        trunc_i32(t.y + 0.5)
    } else {
        trunc_i32(t.y - 0.5)
    } as f64;
    let (ox, oy) = (t.x - rx, t.y - ry);
    let w = v.w;
    if rng.f01() >= cr {
        return [w * (ox * c + rx), w * (oy * c + ry), 0.0];
    }
    if ox.abs() >= oy.abs() {
        let e = if ox >= 0.0 { cl } else { -cl };
        [w * (ox * c + rx + e), w * (oy * c + ry + e * oy / ox), 0.0]
    } else {
        let e = if oy >= 0.0 { cl } else { -cl };
        [w * (ox * c + rx + ox / oy * e), w * (oy * c + ry + e), 0.0]
    }
}

/// Bipolar swirl: the angle σ turns by out·τ + in/τ, twisting near the foci and far away.
fn bswirl(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [in_, out] = v.params();
    let (tau, sigma) = bipolar(t.x, t.y);
    let sigma = sigma + tau * out + in_ / zeps(tau);
    let (x, y) = from_bipolar(v.w, tau, sigma);
    [x, y, 0.0]
}

/// Bipolar transform: τ is divided by `power` and moved, σ rotated and divided by `power`
/// (one of `power` random copies), and the two half-planes are split apart along τ.
fn btransform(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [rotate, power, mv, split] = v.params();
    let (tau, sigma) = bipolar(t.x, t.y);
    let mut tau = tau / power + mv;
    let copy = floor_i64(rng.f01() * power) as f64;
    let sigma = (sigma + rotate) / power + TAU / power * copy;
    if t.x >= 0.0 {
        tau += split;
    } else {
        tau -= split;
    }
    let (x, y) = from_bipolar(v.w, tau, sigma);
    [x, y, 0.0]
}

/// 3-D bubble with per-axis scales; z is pushed away from the plane by `z` as well.
fn bubble2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sx, sy, sz] = v.params();
    let r = v.w / zeps(0.25 * (t.sumsq + t.z * t.z) + 1.0);
    let lift = if t.z >= 0.0 {
        v.w * (t.z + sz)
    } else {
        v.w * (t.z - sz)
    };
    [t.x * r * sx, t.y * r * sy, lift + t.z * r * sz]
}

fn prep_bubble_t3d(v: &mut Prepared) {
    let [stripes, ratio, hole, _, sym, _] = v.params();
    let abs_n = stripes.abs();
    let inv_stripes = if stripes < 0.0 { 1.0 } else { 0.0 };
    let (mut strip1, mut strip2, mut s, mut c, mut ratio) = (0.0, 0.0, 0.0, 0.0, ratio);
    if abs_n != 0.0 {
        let strip = PI / abs_n;
        strip2 = 2.0 * strip;
        (s, c) = strip.sin_cos();
        ratio = ratio.clamp(0.01, 1.99);
        strip1 = zeps(ratio * strip);
    }
    let mut h = if sym == 1.0 {
        if hole < 0.0 {
            hole.abs()
        } else {
            hole.min(179.9)
        }
    } else {
        hole
    };
    let inv_hole;
    if h < 0.0 {
        inv_hole = 1.0;
        h = (hole.abs() / 360.0 * TAU) / 2.0;
    } else {
        inv_hole = 0.0;
        h = PI - (h / 360.0 * TAU) / 2.0;
    }
    v.p.extend_from_slice(&[
        abs_n,
        inv_stripes,
        strip1,
        strip2,
        s,
        c,
        h,
        inv_hole,
        PI - h,
        ratio,
    ]);
}

/// Rotates (x, y) by the angle with sine `s` and cosine `c`.
#[inline(always)]
fn rot(x: f64, y: f64, s: f64, c: f64) -> (f64, f64) {
    (c * x - s * y, s * x + c * y)
}

/// The bubble lifted onto a sphere, with optional stripes cut out of it (or, in blur mode,
/// rotated onto their neighbours) and a hole of a given angle at the pole (or at both poles
/// with z-symmetry), which blur mode squeezes the cap into instead of cutting.
fn bubble_t3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, exp_z, sym_z, blur] = v.params();
    let [abs_n, inv_stripes, strip1, strip2, sin_ratio, cos_ratio] = v.derived();
    let [_, _, _, _, _, _, hole, inv_hole, comp, ratio] = v.derived();
    let (mut x, mut y) = (t.x, t.y);
    let rad = zeps(t.sumsq / 4.0 + 1.0);
    if abs_n != 0.0 {
        let mut ang = t.x.atan2(t.y);
        if ang < 0.0 {
            ang += TAU;
        }
        while ang > strip2 {
            ang -= strip2;
        }
        let outside = if inv_stripes == 0.0 {
            ang > strip1
        } else {
            ang < strip1
        };
        if outside {
            if blur == 0.0 {
                x = 0.0;
                y = 0.0;
            } else {
                let fixed = if inv_stripes == 0.0 {
                    ratio == 1.0
                } else {
                    abs_n == 1.0
                };
                let (s, c) = if fixed {
                    (sin_ratio, cos_ratio)
                } else if inv_stripes == 0.0 {
                    let f = (ang - strip1) / zeps(strip2 - strip1);
                    (ang - f * strip1).sin_cos()
                } else {
                    let f = (ang - strip1) / strip1;
                    (ang - f * (strip2 - strip1)).sin_cos()
                };
                (x, y) = rot(x, y, s, c);
            }
        }
    }
    x /= rad;
    y /= rad;
    let (mut z, ang_z) = if x != 0.0 || y != 0.0 {
        let z = 2.0 / rad.powf(exp_z) - 1.0;
        let a = if exp_z <= 2.0 {
            PI - (z / (x * x + y * y + z * z)).acos()
        } else {
            PI - sqr(x * x + y * y).atan2(z)
        };
        (z, a)
    } else {
        (0.0, 0.0)
    };
    let squeeze = blur != 0.0 && exp_z == 1.0;
    let bent = if sym_z == 0.0 {
        let inv = inv_hole != 0.0;
        let in_hole = if inv { ang_z < hole } else { ang_z > hole };
        if !in_hole {
            None
        } else if inv {
            Some(PI - ang_z / zeps(comp * hole - FRAC_PI_2))
        } else {
            Some((PI - ang_z) / zeps(comp * hole - FRAC_PI_2))
        }
    } else if ang_z > hole || ang_z < PI - hole {
        Some(if ang_z > hole {
            (PI - ang_z) / comp * (PI - 2.0 * comp) + comp - FRAC_PI_2
        } else {
            FRAC_PI_2 - (ang_z / comp * (PI - 2.0 * comp) + comp)
        })
    } else {
        None
    };
    if let Some(a) = bent {
        if squeeze {
            let b = ang_z - FRAC_PI_2;
            let fac = a.cos() / b.cos();
            x *= fac;
            y *= fac;
            z *= a.sin() / b.sin();
        } else {
            x = 0.0;
            y = 0.0;
            z = 0.0;
        }
    }
    [v.w * x, v.w * y, v.w * z]
}

/// Derived values: gain² + 10⁻⁶, bubble radius², radius / maximal bubble size.
fn prep_bwraps(v: &mut Prepared) {
    let [cell, space, gain, _, _] = v.params();
    let radius = 0.5 * (cell / (1.0 + space * space));
    let g2 = gain * gain + 1.0e-6;
    let mut max_bubble = g2 * radius;
    if max_bubble > 2.0 {
        max_bubble = 1.0;
    } else {
        max_bubble *= 1.0 / (max_bubble * max_bubble / 4.0 + 1.0);
    }
    v.p.push(g2);
    v.p.push(zeps(radius * radius));
    v.p.push(radius / max_bubble);
}

/// Bubble wrap: each grid cell holds a bubble; points inside it are magnified like `bubble`
/// and twisted (inner twist at the centre, outer twist at the rim).
fn bwraps(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cell, _, _, inner, outer] = v.params();
    let [g2, r2, rfactor] = v.derived();
    let z = v.w * t.z;
    if cell == 0.0 {
        return [v.w * t.x, v.w * t.y, z];
    }
    let cx = (floor_i64(t.x / cell) as f64 + 0.5) * cell;
    let cy = (floor_i64(t.y / cell) as f64 + 0.5) * cell;
    let (mut lx, mut ly) = (t.x - cx, t.y - cy);
    if lx * lx + ly * ly > r2 {
        return [v.w * t.x, v.w * t.y, z];
    }
    lx *= g2;
    ly *= g2;
    let r = rfactor / zeps((lx * lx + ly * ly) / 4.0 + 1.0);
    lx *= r;
    ly *= r;
    let f = (lx * lx + ly * ly) / r2;
    let (s, c) = (inner * (1.0 - f) + outer * f).sin_cos();
    [
        v.w * (cx + c * lx + s * ly),
        v.w * (cy - s * lx + c * ly),
        z,
    ]
}

/// Derived values: gain², 1/cell size, cell size / (2(1 + space²)).
fn prep_bwraps_rand(v: &mut Prepared) {
    let [cell, space, gain] = v.params();
    v.p.push(gain * gain);
    v.p.push(1.0 / zeps(cell));
    v.p.push(0.5 * (cell / (1.0 + space * space)));
}

/// `bwraps` with a bubble of random size in each cell (a hash of the cell's centre, or of its
/// square for symmetric layouts).
fn bwraps_rand(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cell, _, _, inner, outer, symm, seed] = v.params();
    let [g2, inv_cell, half] = v.derived();
    let w = v.w;
    if cell == 0.0 {
        return [t.x * w, t.y * w, 0.0];
    }
    let cx = (floor_i64(t.x * inv_cell) as f64 + 0.5) * cell;
    let cy = (floor_i64(t.y * inv_cell) as f64 + 0.5) * cell;
    let (lx, ly) = (t.x - cx, t.y - cy);
    let radius = if symm == 0.0 {
        half * sine_hash(cx, cy, seed)
    } else {
        half * sine_hash(cx * cx, cy * cy, seed)
    };
    let mb = g2 * radius;
    let max_bubble = if mb > 2.0 {
        1.0
    } else {
        mb / (mb * mb * 0.25 + 1.0)
    };
    let r2 = radius * radius;
    if lx * lx + ly * ly > r2 {
        return [t.x * w, t.y * w, 0.0];
    }
    let rfactor = radius / zeps(max_bubble);
    let (lx2, ly2) = (lx * g2, ly * g2);
    let r = rfactor / ((lx2 * lx2 + ly2 * ly2) * 0.25 + 1.0);
    let (lx3, ly3) = (lx2 * r, ly2 * r);
    let f = (lx3 * lx3 + ly3 * ly3) / zeps(r2);
    let theta = inner * (1.0 - f) + outer * f;
    let (st, ct) = (theta.sin(), theta.cos());
    [
        (cx + ct * lx3 + st * ly3) * w,
        (cy - st * lx3 + ct * ly3) * w,
        0.0,
    ]
}

/// Cardioid-like radial warp: r ← √(r² + sin(a·θ) + 1), angle kept.
fn cardioid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a] = v.params();
    let r = v.w * (t.sumsq + (t.atan_yx * a).sin() + 1.0).sqrt();
    [r * t.ux, r * t.uy, 0.0]
}

/// Derived value: 1/size.
fn prep_checks(v: &mut Prepared) {
    let [_, _, size] = v.params();
    let inv = 1.0 / zeps(size);
    v.p.push(inv);
}

/// Checkerboard: points in light squares (of side `size`) shift by (x, y) plus a random jitter
/// in y, points in dark squares by −(x, y) plus a jitter in x; z is scaled.
fn checks(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ox, oy, _, rnd] = v.params();
    let [inv] = v.derived();
    let jx = rnd * rng.f01();
    let jy = rnd * rng.f01();
    let parity = trunc_i32(lrint(t.x * inv) + lrint(t.y * inv));
    let (dx, dy) = if parity & 1 != 0 {
        (-ox + jx, -oy)
    } else {
        (ox, oy + jy)
    };
    [v.w * (t.x + dx), v.w * (t.y + dy), v.w * t.z]
}

/// Random discs on a grid of spacing 2 inside [−X, X]×[−Y, Y]: a random grid node is picked,
/// kept with probability `density` (by a hash of the node), and a uniform point of a disc of
/// hashed radius around it is returned. Rejected draws give the origin (Fractorium leaves the
/// output unset there).
fn circle_rand_hash(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [nx, ny, size, power, dens, seed] = v.params();
    let (half_x, half_y) = (nx * 0.5, ny * 0.5);
    let a = rng.f01() * TAU;
    let r = rng.f01().sqrt();
    let gx = 2.0 * (floor_i64(rng.f01() * half_x * 2.0 + 0.5) as f64 - half_x);
    let gy = 2.0 * (floor_i64(rng.f01() * half_y * 2.0 + 0.5) as f64 - half_y);
    let ret = if sine_hash(gy, gx, seed) < dens {
        size * r * (sine_hash(gx, gy, seed).ln() * power).exp()
    } else {
        0.0
    };
    if ret > 0.0 {
        let (s, c) = a.sin_cos();
        [v.w * (c * ret + gx), v.w * (s * ret + gy), 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// A uniform random point of the disc of radius w.
fn circleblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let rad = rng.f01().sqrt();
    let (s, c) = (rng.f01() * TAU).sin_cos();
    [v.w * c * rad, v.w * s * rad, 0.0]
}

/// Crops to the disc of `radius` about (x₀, y₀): points outside go to the origin (`zero` = 1)
/// or onto a thin random ring just outside the rim.
fn circlecrop(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, cx, cy, scatter, zero] = v.params();
    let (xi, yi) = (t.x - cx, t.y - cy);
    // flam3-compatible regular use: z is weighted (and, as in Fractorium, the crop also clears
    // what earlier variations summed); otherwise z passes through.
    let legacy = v.compat && v.form == Form::Regular;
    let z = if legacy { v.w * t.z } else { t.z };
    let rad = (xi * xi + yi * yi).sqrt();
    let rdc = radius + rng.f01() * 0.5 * scatter.clamp(-1.0, 1.0);
    if rad > radius {
        if zero as i32 != 0 {
            if legacy {
                acc.x = 0.0;
                acc.y = 0.0;
            }
            [0.0, 0.0, z]
        } else {
            let (s, c) = yi.atan2(xi).sin_cos();
            [v.w * rdc * c + cx, v.w * rdc * s + cy, z]
        }
    } else {
        [v.w * xi + cx, v.w * yi + cy, z]
    }
}

/// Derived values: inner and outer radii in order, outer radius · w.
fn prep_circlecrop2(v: &mut Prepared) {
    let [a, b] = v.params();
    let (lo, hi) = (a.min(b), a.max(b));
    v.p.push(lo);
    v.p.push(hi);
    v.p.push(hi * v.w);
}

/// Keeps the annulus between the two radii; points outside it go to the origin, or
/// (zero = 0) onto the outer circle, mirrored across the diagonal (sine of their angle in x,
/// cosine in y).
fn circlecrop2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, zero] = v.params();
    let [lo, hi, hi_w] = v.derived();
    let r = t.sqrt;
    if r > hi || r < lo {
        if zero == 0.0 {
            let (s, c) = (t.atan_yx.sin(), t.atan_yx.cos());
            [s * hi_w, c * hi_w, 0.0]
        } else {
            [0.0, 0.0, 0.0]
        }
    } else {
        [t.x * v.w, t.y * v.w, 0.0]
    }
}

/// Circles on a grid of spacing 2·Sc, present where the lattice noise is below `Dens1`, each of
/// noisy radius: points inside are pulled towards the circle's centre, by a constant factor K
/// or linearly in the distance (which of the two is chosen by `Dens2` and `Reverse`).
fn circle_linear(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sc, k, dens1, dens2, reverse, _, _, seed] = v.params();
    let m = floor_i64(0.5 * t.x / sc) as i32;
    let n = floor_i64(0.5 * t.y / sc) as i32;
    let mx = m.wrapping_mul(2).wrapping_add(1) as f64 * sc;
    let ny = n.wrapping_mul(2).wrapping_add(1) as f64 * sc;
    let (mut x, mut y) = (t.x - mx, t.y - ny);
    let u = zeps((x * x + y * y).sqrt());
    let size = (0.3 + 0.7 * lattice_noise_2d(m.wrapping_add(10), n.wrapping_add(3))) * sc;
    let z1 = lattice_noise_2d(trunc_i32(m as f64 + seed), n);
    if z1 < dens1 && u < size {
        let constant = if reverse > 0.0 {
            z1 < dens1 * dens2
        } else {
            z1 > dens1 * dens2
        };
        let f = if constant {
            k
        } else {
            size / u * (1.0 - k) + k
        };
        x *= f;
        y *= f;
    }
    [v.w * (x + mx), v.w * (y + ny), 0.0]
}

/// Is the grid cell (m, n) of [`circle_rand`]-style layouts empty, or the offset (x, y) from its
/// centre outside the cell's circle?
#[inline(always)]
fn circle_cell_rejects(m: i64, n: i64, x: f64, y: f64, sc: f64, dens: f64, seed: f64) -> bool {
    let u = (x * x + y * y).sqrt();
    lattice_noise_2d(trunc_i32(m as f64 + seed), n as i32) > dens
        || u > (0.3 + 0.7 * lattice_noise_2d((m + 10) as i32, (n + 3) as i32)) * sc
}

/// A random point of one of the circles of the `CircleLinear` layout, within [−X, X]×[−Y, Y]
/// (rejection sampling, at most 11 draws).
fn circle_rand(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sc, dens, ax, ay, seed] = v.params();
    let mut tries = 0;
    let (mut m, mut n, mut x, mut y);
    loop {
        x = ax * (1.0 - 2.0 * rng.f01());
        y = ay * (1.0 - 2.0 * rng.f01());
        m = floor_i64(0.5 * x / sc);
        n = floor_i64(0.5 * y / sc);
        x -= (m * 2 + 1) as f64 * sc;
        y -= (n * 2 + 1) as f64 * sc;
        tries += 1;
        if tries > 10 || !circle_cell_rejects(m, n, x, y, sc, dens, seed) {
            break;
        }
    }
    [
        v.w * (x + (m * 2 + 1) as f64 * sc),
        v.w * (y + (n * 2 + 1) as f64 * sc),
        0.0,
    ]
}

/// Splits the disc of `radius − split` from the rest of the plane, pushing outer points out by
/// `split`.
fn circlesplit(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [radius, split] = v.params();
    if t.sqrt < radius - split {
        return [v.w * t.x, v.w * t.y, 0.0];
    }
    let len = t.sqrt + split;
    let (s, c) = (t.atan_yx.sin(), t.atan_yx.cos());
    [v.w * (c * len), v.w * (s * len), 0.0]
}

/// The plane halved towards (X, Y); points that land inside a circle of the `CircleLinear`
/// layout are replaced by a random point of a random circle of the layout.
fn circle_trans1(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sc, dens, ax, ay, seed] = v.params();
    let sc = zeps(sc);
    let ux = (t.x - ax) * 0.5 + ax;
    let uy = (t.y - ay) * 0.5 + ay;
    let m = floor_i64(0.5 * ux / sc);
    let n = floor_i64(0.5 * uy / sc);
    let x = ux - (m * 2 + 1) as f64 * sc;
    let y = uy - (n * 2 + 1) as f64 * sc;
    if circle_cell_rejects(m, n, x, y, sc, dens, seed) {
        return [v.w * ux, v.w * uy, 0.0];
    }
    let mut tries = 0;
    let (mut m, mut n, mut x, mut y);
    loop {
        let px = ax.abs() * (1.0 - 2.0 * rng.f01());
        let py = ay.abs() * (1.0 - 2.0 * rng.f01());
        m = floor_i64(0.5 * px / sc);
        n = floor_i64(0.5 * py / sc);
        let alpha = TAU * rng.f01();
        let u = 0.3 + 0.7 * lattice_noise_2d((m + 10) as i32, (n + 3) as i32);
        x = u * alpha.cos();
        y = u * alpha.sin();
        tries += 1;
        if tries > 10 || lattice_noise_2d(trunc_i32(m as f64 + seed), n as i32) <= dens {
            break;
        }
    }
    [
        v.w * (x + (m * 2 + 1) as f64 * sc),
        v.w * (y + (n * 2 + 1) as f64 * sc),
        0.0,
    ]
}

// ---------------------------------------------------------------------------------------------
// circlize … crescents

/// Squares to circles: the square of half-side s becomes the circle of radius (4w/π)·s + hole,
/// the position along the square's perimeter becoming the angle.
fn circlize(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [hole] = v.params();
    let (side, per) = square_arc(t.x, t.y);
    let r = v.w / FRAC_PI_4 * side + hole;
    let (s, c) = (FRAC_PI_4 * per / side - FRAC_PI_4).sin_cos();
    [r * c, r * s, 0.0]
}

/// `circlize` with the hole inside the weight: radius w·(s + hole).
fn circlize2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [hole] = v.params();
    let (side, per) = square_arc(t.x, t.y);
    let r = v.w * (side + hole);
    let (s, c) = (FRAC_PI_4 * per / side - FRAC_PI_4).sin_cos();
    [r * c, r * s, 0.0]
}

/// Radial scaling by `scale` inside the unit circle and by 1/scale outside it.
fn circus(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scale] = v.params();
    let r = if t.sqrt <= 1.0 {
        t.sqrt * scale
    } else {
        t.sqrt * (1.0 / scale)
    };
    [v.w * r * t.ux, v.w * r * t.uy, 0.0]
}

/// Derived values: num/π, π/num, π·a/num (num replaced by ε when 0).
fn prep_collideoscope(v: &mut Prepared) {
    let [a, num] = v.params();
    let num = zeps(num);
    v.p.push(num * FRAC_1_PI);
    v.p.push(PI / num);
    v.p.push(PI * a / num);
}

/// Kaleidoscope of `num` sectors per half-turn: alternate sectors are rotated by ±πa/num
/// (modulo the sector), mirrored between the upper and lower half-planes.
fn collideoscope(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [n_pi, pi_n, a_n] = v.derived();
    let a = t.atan_yx;
    let r = v.w * t.sqrt;
    let a = if a >= 0.0 {
        let sector = trunc_i32(a * n_pi);
        let shift = if sector & 1 == 0 { a_n } else { -a_n };
        sector as f64 * pi_n + (shift + a) % pi_n
    } else {
        let sector = trunc_i32(-a * n_pi);
        let shift = if sector & 1 == 1 { -a_n } else { a_n };
        -(sector as f64 * pi_n + (shift - a) % pi_n)
    };
    [r * a.cos(), r * a.sin(), 0.0]
}

/// Random concentric rings: a random ring index k < density sets the radius k/density·radius
/// (optionally blurred) and the depth −k/density (optionally blurred); in regular use it
/// replaces what earlier variations summed.
fn concentric(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, density, r_blur, z_blur] = v.params();
    let level = floor_i64(rng.f01() * density) as f64 / zeps(density);
    let angle = rng.f01() * TAU;
    let mut r = level * radius;
    if r_blur != 0.0 {
        r += (rng.f01().sqrt() * 2.0 - 1.0) * r_blur;
    }
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    let zb = if z_blur != 0.0 {
        (rng.f01() * 2.0 - 1.0) * z_blur
    } else {
        0.0
    };
    let (s, c) = angle.sin_cos();
    [r * c * v.w, r * s * v.w, (-level + zb) * v.w]
}

/// Quaternion hyperbolic cosine of (x, y, z) taken as x + y·i + z·j.
fn coshq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = (t.y * t.y + t.z * t.z).sqrt();
    let (s, c) = m.sin_cos();
    let (sh, ch) = (t.x.sinh(), t.x.cosh());
    let d = v.w * sh * s / zeps(m);
    [v.w * c * ch, d * t.y, d * t.z]
}

/// Quaternion cosine of (x, y, z) taken as x + y·i + z·j.
fn cosq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let m = (t.y * t.y + t.z * t.z).sqrt();
    let (s, c) = t.x.sin_cos();
    let (sh, ch) = (m.sinh(), m.cosh());
    let d = -v.w * s * sh / zeps(m);
    [v.w * c * ch, d * t.y, d * t.z]
}

/// Derived values: π·phase_x, π·phase_y, |repeat|, 2w and the two blend amounts
/// ½ − ½cos(amount + π·phase).
fn prep_coswrap(v: &mut Prepared) {
    let [repeat, ax, ay, phx, phy] = v.params();
    let (px, py) = (PI * phx, PI * phy);
    v.p.push(px);
    v.p.push(py);
    v.p.push(repeat.abs());
    v.p.push(2.0 * v.w);
    v.p.push(0.5 - (ax + px).cos() * 0.5);
    v.p.push(0.5 - (ay + py).cos() * 0.5);
}

/// One coordinate of `coswrap`: u = (c + 1)/2 blended towards a cosine wave of u and of the
/// fractional part of repeat·u.
#[inline(always)]
fn coswrap_axis(c: f64, phase: f64, repeat: f64, blend: f64, w2: f64) -> f64 {
    let u = 0.5 * c + 0.5;
    let b = (repeat * u).fract();
    let wave = |q: f64| 0.5 - (q * 4.0 + phase).cos() * 0.5;
    let first = u + (wave(u) - u) * blend;
    -1.0 + w2 * (first + (wave(b) - first) * blend)
}

/// Wraps the plane onto cosine waves: each coordinate is blended with a cosine of itself and of
/// its repeated fractional part (phase and amount per axis), mapped back to [−1, −1 + 2w].
fn coswrap(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [px, py, rep, w2, bx, by] = v.derived();
    [
        coswrap_axis(t.x, px, rep, bx, w2),
        coswrap_axis(t.y, py, rep, by, w2),
        0.0,
    ]
}

/// A random point of the spiral curve (−sinh s, sin(a·s)) / (cos(a·s) − cosh s), s uniform in
/// [−π, π): the hyperbolic cotangent of a line through the origin.
fn coth_spiral(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a] = v.params();
    let s = (rng.f01() - 0.5) * TAU;
    let den = zeps((a * s).cos() - s.cosh());
    [v.w * (-s.sinh() / den), v.w * ((a * s).sin() / den), 0.0]
}

/// Quaternion hyperbolic cotangent of (x, y, z) taken as x + y·i + z·j (Fractorium's form, whose
/// normalisation divides by |q|⁴).
fn cothq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let yz2 = t.y * t.y + t.z * t.z;
    let m = yz2.sqrt();
    let k = v.w / zeps(sqr(t.x * t.x + yz2));
    let (s, c) = m.sin_cos();
    let (sh, ch) = (t.x.sinh(), t.x.cosh());
    let d = ch * s / zeps(m);
    let b = sh * s / zeps(m);
    quat_mul_conj(sh * c, d, ch * c, b, t.y, t.z, k)
}

/// Quaternion cotangent of (x, y, z) taken as x + y·i + z·j (Fractorium's form, normalised by
/// |q|²).
fn cotq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let yz2 = t.y * t.y + t.z * t.z;
    let m = yz2.sqrt();
    let k = v.w / zeps(t.x * t.x + yz2);
    let (s, c) = t.x.sin_cos();
    let (sh, ch) = (m.sinh(), m.cosh());
    let d = c * sh / zeps(m);
    let b = -s * sh / zeps(m);
    let [x, y, z] = quat_mul_conj(s * ch, d, c * ch, b, t.y, t.z, k);
    [x, -y, -z]
}

fn prep_cpow2(v: &mut Prepared) {
    let [r, a, div, spread] = v.params();
    let spread = zeps(spread);
    let c = r * (PI / 2.0 * a).cos() / div;
    let d = r * (PI / 2.0 * a).sin() / div;
    v.p.extend_from_slice(&[
        c,
        d,
        c / 2.0,
        d / 2.0,
        TAU / div,
        0.5 / spread,
        TAU * spread,
        // C's conversion to unsigned: negative spreads give 0 branches.
        spread.clamp(0.0, 4294967295.0).trunc(),
    ]);
}

/// Complex power z^((r/divisor)·e^(iπa/2)) with a random choice among the branches of the
/// logarithm (about `spread` of them, favouring the principal one) and of the divisor's roots.
fn cpow2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [c, d, half_c, half_d, ang, inv_spread, full_spread, branches] = v.derived();
    let mut a = t.atan_yx;
    let branches = branches as u64;
    let mut n = if branches == 0 {
        rng.u32() as i32
    } else {
        rng.below(branches) as i32
    };
    if a < 0.0 {
        n = n.wrapping_add(1);
    }
    a += TAU * n as f64;
    if (a * inv_spread).cos() < rng.f11() {
        a -= full_spread;
    }
    let lnr2 = t.sumsq.ln();
    let r = v.w * (half_c * lnr2 - d * a).exp();
    let th = c * a + half_d * lnr2 + ang * crand(rng);
    let (s, c) = th.sin_cos();
    [r * c, r * s, 0.0]
}

fn prep_cpow3(v: &mut Prepared) {
    let [r, d, div, spread] = v.params();
    let div = zeps(div);
    let ld = if d < 0.0 { -(-d).ln() } else { d.ln() };
    let a = (ld * r).atan2(TAU);
    let (sa, ca) = (a.sin(), a.cos());
    let pc = ca * r * ca / div;
    let pd = ca * r * sa / div;
    let coeff = if pd == 0.0 { 0.0 } else { -0.095 * spread / pd };
    v.p.extend_from_slice(&[pc, pd, pc / 2.0, pd / 2.0, TAU / div, coeff]);
}

/// Complex power along a logarithmic spiral (exponent set by r and d), with random branches of
/// the logarithm drawn from a geometric-like law whose width is `spread`, and random roots of
/// the divisor.
fn cpow3(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [c, d, half_c, half_d, ang, coeff] = v.derived();
    let mut a = t.atan_yx;
    if a < 0.0 {
        a += TAU;
    }
    if (a / 2.0).cos() < rng.f11() {
        a -= TAU;
    }
    let turn = if rng.bit() { TAU } else { -TAU };
    a += turn * (rng.f01().ln() * coeff).round();
    let lnr2 = t.sumsq.ln();
    let r = v.w * (half_c * lnr2 - d * a).exp();
    let th = c * a + half_d * lnr2 + ang * crand(rng);
    let (s, c) = th.sin_cos();
    [r * c, r * s, 0.0]
}

// ---------------------------------------------------------------------------------------------
// crackle: Voronoi cells over a jittered grid, with 3-D simplex noise distorting the sites.

/// Half-width of the cache of cell sites kept by a prepared `crackle`.
const CRACKLE_CACHE: i32 = 10;
/// Sites per row of that cache.
const CRACKLE_CACHE_W: usize = 2 * CRACKLE_CACHE as usize + 1;
/// Index of the first cached site in a prepared `crackle`'s derived values (after the half cell
/// size).
const CRACKLE_SITES: usize = 1;

/// The site of grid cell (i, j): the cell corner displaced by `distort` times two noise values
/// taken at depth z, scaled by the half cell size `s`.
fn crackle_site(i: i32, j: i32, z: f64, s: f64, distort: f64) -> [f64; 2] {
    let (fi, fj) = (i as f64, j as f64);
    let nx = simplex_noise3([fi * 2.5, fj * 2.5, z * 2.5]);
    let ny = simplex_noise3([fj * 2.5 + 30.2, fi * 2.5 - 12.1, z * 2.5 + 19.8]);
    [(fi + distort * nx) * s, (fj + distort * ny) * s]
}

/// Derived values: half cell size, then the sites of the cells within the cache.
fn prep_crackle(v: &mut Prepared) {
    let [cell, _, distort, _, z] = v.params();
    let half = zeps(cell.abs() / 2.0);
    v.p.push(half);
    for i in -CRACKLE_CACHE..=CRACKLE_CACHE {
        for j in -CRACKLE_CACHE..=CRACKLE_CACHE {
            let s = crackle_site(i, j, z, half, distort);
            v.p.push(s[0]);
            v.p.push(s[1]);
        }
    }
}

/// The site of cell (i, j), from the cache when it holds it.
#[inline(always)]
fn crackle_site_cached(v: &Prepared, i: i32, j: i32) -> [f64; 2] {
    if i.abs() <= CRACKLE_CACHE && j.abs() <= CRACKLE_CACHE {
        let k = 2 * ((i + CRACKLE_CACHE) as usize * CRACKLE_CACHE_W + (j + CRACKLE_CACHE) as usize);
        let sites = v.table(CRACKLE_SITES);
        [sites[k], sites[k + 1]]
    } else {
        let [_, _, distort, _, z] = v.params();
        let [half] = v.derived();
        crackle_site(i, j, z, half, distort)
    }
}

/// The sites of the 3×3 cells around cell (ci, cj), row by row in i.
#[inline(always)]
fn crackle_block(v: &Prepared, ci: i32, cj: i32) -> [[f64; 2]; 9] {
    let mut out = [[0.0; 2]; 9];
    for (k, o) in out.iter_mut().enumerate() {
        let (di, dj) = (k as i32 / 3 - 1, k as i32 % 3 - 1);
        *o = crackle_site_cached(v, ci + di, cj + dj);
    }
    out
}

/// Crackle: a random point near the origin is moved relative to the site of its Voronoi cell,
/// its distance to the cell's edge (in the Voronoi ratio) raised to `power` and scaled; the
/// input point is not used.
fn crackle(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, power, _, scale] = v.params();
    let [half] = v.derived();
    let blur = (rng.f01() + rng.f01()) / 2.0 + (rng.f01() - 0.5) / 4.0;
    let theta = TAU * rng.f01();
    let u = [blur * theta.sin(), blur * theta.cos()];
    let mut ci = floor_i64(u[0] / half) as i32;
    let mut cj = floor_i64(u[1] / half) as i32;
    // Re-centre the 3×3 block on the cell whose site is nearest.
    let sites = crackle_block(v, ci, cj);
    let mut best = (f64::MAX, 0);
    for (k, s) in sites.iter().enumerate() {
        let d2 = sqr(s[0] - u[0]) + sqr(s[1] - u[1]);
        if d2 < best.0 {
            best = (d2, k);
        }
    }
    ci += best.1 as i32 / 3 - 1;
    cj += best.1 as i32 % 3 - 1;
    let sites = crackle_block(v, ci, cj);
    let centre = sites[4];
    // Largest Voronoi ratio of u between the centre site and each neighbour.
    let mut l = f64::MIN;
    for (k, s) in sites.iter().enumerate() {
        if k == 4 {
            continue;
        }
        let (dx, dy) = (s[0] - centre[0], s[1] - centre[1]);
        let ratio = if dx == 0.0 && dy == 0.0 {
            1.0
        } else {
            2.0 * ((u[0] - centre[0]) * dx + (u[1] - centre[1]) * dy) / zeps(dx * dx + dy * dy)
        };
        if ratio > l {
            l = ratio;
        }
    }
    let target = zeps(l).abs().powf(power) * scale;
    let r = target / zeps(l);
    [
        v.w * ((u[0] - centre[0]) * r + centre[0]),
        v.w * ((u[1] - centre[1]) * r + centre[1]),
        0.0,
    ]
}

/// A random point on a segment from the jittered site of the input's unit cell to the site of
/// one of its four neighbours, scaled by the cell size (the weight is not applied).
fn crackle2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [cell] = v.params();
    const SEED: f64 = 34554.0;
    let inv = 1.0 / zeps(cell);
    let site = |x: f64, y: f64| {
        [
            x + inv * sine_hash(x, y, SEED),
            y + inv * sine_hash(y, x * 3.0, SEED + 7.0),
        ]
    };
    let (cx, cy) = (floor_i64(t.x) as f64, floor_i64(t.y) as f64);
    let a = site(cx, cy);
    let (nx, ny) = if rng.f01() < 0.5 {
        if rng.f01() < 0.5 {
            (cx, cy + 1.0)
        } else {
            (cx, cy - 1.0)
        }
    } else if rng.f01() < 0.5 {
        (cx + 1.0, cy)
    } else {
        (cx - 1.0, cy)
    };
    let b = site(nx, ny);
    let f = rng.f01();
    [
        (a[0] + (b[0] - a[0]) * f) * cell,
        (a[1] + (b[1] - a[1]) * f) * cell,
        0.0,
    ]
}

/// Crescents: (sin x, cos x) scaled by sin²x·(cosh y + 1).
fn crescents(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (s, c) = t.x.sin_cos();
    let k = (t.y.cosh() + 1.0) * (s * s);
    [v.w * s * k, v.w * c * k, 0.0]
}
