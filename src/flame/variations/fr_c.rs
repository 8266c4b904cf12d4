//! Variations (slice fr_c of the registry): Fractorium's catalogue from `fdisc` to `julia3Dq`.
//!
//! Each formula reproduces the numbers of Fractorium's CPU renderer (double precision),
//! including its pole guards (an exact 0 replaced by `f64::EPSILON`) and its integer
//! conversions, so that files made with Fractorium render the same.

use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, PI, TAU};

use super::util::{
    crand, floor_f, floor_i64, jacobi_elliptic, ln_gamma, lrint, mix, sine_hash, sqr, trunc_i32,
    zeps,
};
use super::*;

const INF: f64 = f64::INFINITY;
const NEG_INF: f64 = f64::NEG_INFINITY;
/// Largest 32-bit signed integer, the upper bound of some integer parameters.
const I32_MAX: f64 = 2147483647.0;

/// √3 / 2.
const HALF_SQRT3: f64 = 0.866_025_403_784_438_6;
/// √3.
const SQRT3: f64 = 1.732_050_807_568_877_2;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("fdisc", fdisc).needs(need::SQRT | need::ATAN_YX),
    VarDef::new("fibonacci", fibonacci).prepare(fib_prepare),
    VarDef::new("fibonacci2", fibonacci2)
        .params(&[p("fibonacci2_sc", 1.0), p("fibonacci2_sc2", 1.0)])
        .prepare(fib_prepare),
    VarDef::new("flatten", flatten)
        .batch(super::inline_batch!(flatten))
        .flags(flag::WRITES_ACC | flag::WRITES_Z),
    VarDef::new("flipcircle", flipcircle).needs(need::SUMSQ),
    VarDef::new("flipx", flipx),
    VarDef::new("flipy", flipy),
    VarDef::new("flowerdb", flowerdb)
        .params(&[
            p("flowerdb_petals", 6.0),
            p("flowerdb_petal_split", 0.0),
            p("flowerdb_petal_spread", 1.0),
        ])
        .needs(need::SQRT | need::ATAN_YX)
        .prepare(flowerdb_prepare),
    VarDef::new("foci_3D", foci_3d)
        .needs(need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("foci_p", foci_p).params(&[p("foci_p_c1", 0.5), p("foci_p_c2", 0.5)]),
    VarDef::new("fourth", fourth)
        .params(&[
            p_cyclic("fourth_spin", PI, 0.0, TAU),
            p("fourth_space", 0.0),
            p("fourth_twist", 0.0),
            p("fourth_x", 0.0),
            p("fourth_y", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES),
    VarDef::new("funnel", funnel).params(&[p_int("funnel_effect", 8.0, NEG_INF, INF)]),
    VarDef::new("gamma", gamma).needs(need::SQRT | need::ATAN_YX),
    VarDef::new("gaussian", gaussian)
        .batch(super::inline_batch!(gaussian))
        .flags(flag::RANDOM),
    VarDef::new("gdoffs", gdoffs)
        .params(&[
            p_range("gdoffs_delta_x", 0.0, 0.0, 16.0),
            p_range("gdoffs_delta_y", 0.0, 0.0, 16.0),
            p("gdoffs_area_x", 2.0),
            p("gdoffs_area_y", 2.0),
            p("gdoffs_center_x", 0.0),
            p("gdoffs_center_y", 0.0),
            p_int("gdoffs_gamma", 1.0, 1.0, 6.0),
            p_int("gdoffs_square", 0.0, 0.0, 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(gdoffs_prepare),
    VarDef::new("glynnia", glynnia)
        .batch(super::inline_batch!(glynnia))
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(glynnia_prepare),
    VarDef::new("glynnia2", glynnia2)
        .needs(need::SQRT)
        .flags(flag::RANDOM)
        .prepare(glynnia2_prepare),
    VarDef::new("GlynnSim1", glynnsim1)
        .params(&[
            p("GlynnSim1_radius", 1.0),
            p("GlynnSim1_radius1", 0.1),
            p("GlynnSim1_phi1", 0.0),
            p_range("GlynnSim1_thickness", 0.1, 0.0, 1.0),
            p("GlynnSim1_contrast", 1.5),
            p_range("GlynnSim1_pow", 0.5, 0.0, 1.0),
        ])
        .needs(need::SQRT)
        .flags(flag::RANDOM)
        .prepare(glynnsim1_prepare),
    VarDef::new("GlynnSim2", glynnsim2)
        .params(&[
            p_range("GlynnSim2_radius", 1.0, 0.0, INF),
            p_range("GlynnSim2_thickness", 0.1, 0.0, 1.0),
            p_range("GlynnSim2_contrast", 0.5, 0.0, 1.0),
            p("GlynnSim2_pow", 1.5),
            p("GlynnSim2_Phi1", 0.0),
            p("GlynnSim2_Phi2", 360.0),
        ])
        .needs(need::SQRT)
        .flags(flag::RANDOM)
        .prepare(glynnsim2_prepare),
    VarDef::new("GlynnSim3", glynnsim3)
        .params(&[
            p("GlynnSim3_radius", 1.0),
            p("GlynnSim3_thickness", 0.1),
            p("GlynnSim3_thickness2", 0.1),
            p_range("GlynnSim3_contrast", 0.5, 0.0, 1.0),
            p("GlynnSim3_pow", 1.5),
        ])
        .needs(need::SQRT)
        .flags(flag::RANDOM)
        .prepare(glynnsim3_prepare),
    VarDef::new("GlynnSim4", glynnsim4)
        .params(&[
            p("GlynnSim4_radius", 1.0),
            p_range("GlynnSim4_contrast", 0.5, 0.0, 1.0),
            p("GlynnSim4_pow", 1.5),
            p("GlynnSim4_X", 0.0),
            p("GlynnSim4_Y", 0.0),
        ])
        .needs(need::SQRT)
        .flags(flag::RANDOM),
    VarDef::new("GlynnSim5", glynnsim5)
        .params(&[
            p("GlynnSim5_radius", 1.0),
            p("GlynnSim5_thickness", 0.1),
            p_range("GlynnSim5_contrast", 0.5, 0.0, 1.0),
            p("GlynnSim5_pow", 1.5),
        ])
        .needs(need::SQRT)
        .flags(flag::RANDOM),
    VarDef::new("gnarly", gnarly)
        .params(&[p("gnarly_cellsize", 1.0), p("gnarly_twist", 1.0)])
        .prepare(gnarly_prepare),
    VarDef::new("gridout", gridout),
    VarDef::new("heat", heat)
        .params(&[
            p("heat_theta_period", 1.0),
            p("heat_theta_phase", 0.0),
            p("heat_theta_amp", 1.0),
            p("heat_phi_period", 1.0),
            p("heat_phi_phase", 0.0),
            p("heat_phi_amp", 0.0),
            p("heat_r_period", 1.0),
            p("heat_r_phase", 0.0),
            p("heat_r_amp", 0.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(heat_prepare),
    VarDef::new("helicoid", helicoid)
        .params(&[p("helicoid_frequency", 1.0)])
        .needs(need::SQRT | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("helix", helix)
        .params(&[p("helix_frequency", 1.0), p("helix_width", 0.5)])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("hemisphere", hemisphere)
        .batch(super::inline_batch!(hemisphere))
        .needs(need::SUMSQ)
        .flags(flag::WRITES_Z),
    VarDef::new("henon", henon).params(&[p("henon_a", 0.5), p("henon_b", 1.0)]),
    VarDef::new("hex_modulus", hex_modulus)
        .params(&[p("hex_modulus_size", 1.0)])
        .prepare(hex_modulus_prepare),
    VarDef::new("hex_rand", hex_rand)
        .params(&[
            p("hex_rand_x", 10.0),
            p("hex_rand_y", 10.0),
            p("hex_rand_size", 1.0),
            p("hex_rand_power", 1.0),
            p_range("hex_rand_density", 1.0, 0.0, 1.0),
            p("hex_rand_seed", 1.0),
        ])
        .flags(flag::RANDOM),
    VarDef::new("hex_truchet", hex_truchet)
        .params(&[
            p_range("hex_truchet_size", 1.0, -1.0, 1.0),
            p("hex_truchet_side", 1.0),
            p("hex_truchet_seed", 1.0),
        ])
        .flags(flag::RANDOM)
        .prepare(hex_truchet_prepare),
    VarDef::new("hexaplay3D", hexaplay3d)
        .params(&[
            p("hexaplay3D_majp", 1.0),
            p("hexaplay3D_scale", 0.25),
            p("hexaplay3D_zlift", 0.25),
        ])
        .flags(
            flag::RANDOM
                | flag::STATEFUL
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::READS_ACC
                | flag::WRITES_ACC,
        )
        .prepare(hexaplay3d_prepare),
    VarDef::new("hexcrop", hexcrop)
        .params(&[
            p("hexcrop_scale_x", 1.0),
            p("hexcrop_scale_y", 1.0),
            p("hexcrop_center_x", 0.0),
            p("hexcrop_center_y", 0.0),
            p("hexcrop_dropoff", 1e10),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::READS_ACC | flag::WRITES_ACC)
        .prepare(hexcrop_prepare),
    VarDef::new("hexes", hexes)
        .batch(super::inline_batch!(hexes))
        .params(&[
            p("hexes_cellsize", 1.0),
            p("hexes_power", 1.0),
            p("hexes_rotate", 0.166),
            p("hexes_scale", 1.0),
        ])
        .prepare(hexes_prepare),
    VarDef::new("hexnix3D", hexnix3d)
        .params(&[
            p("hexnix3D_majp", 1.0),
            p("hexnix3D_scale", 0.25),
            p("hexnix3D_zlift", 0.0),
            p("hexnix3D_3side", 0.667),
        ])
        .flags(
            flag::RANDOM
                | flag::STATEFUL
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::USES_AFFINE
                | flag::USES_COLOR
                | flag::READS_ACC
                | flag::WRITES_ACC,
        )
        .prepare(hexnix3d_prepare),
    VarDef::new("ho", ho)
        .params(&[p("ho_xpow", 3.0), p("ho_ypow", 3.0), p("ho_zpow", 3.0)])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("hole", hole)
        .batch(super::inline_batch!(hole))
        .params(&[p("hole_a", 1.0), p_int("hole_inside", 0.0, 0.0, 1.0)])
        .needs(need::SQRT | need::ANGLES | need::ATAN_YX),
    VarDef::new("hypercrop", hypercrop)
        .params(&[
            p("hypercrop_n", 4.0),
            p("hypercrop_rad", 1.0),
            p("hypercrop_zero", 0.0),
        ])
        .needs(need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(hypercrop_prepare),
    VarDef::new("hypershift", hypershift)
        .params(&[p("hypershift_shift", 0.01)])
        .needs(need::SUMSQ)
        .flags(flag::WRITES_ACC | flag::COMPAT)
        .prepare(hypershift_prepare),
    VarDef::new("hypershift2", hypershift2)
        .params(&[
            p_range("hypershift2_p", 3.0, 2.0, INF),
            p_range("hypershift2_q", 7.0, 2.0, INF),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC | flag::COMPAT)
        .prepare(hypershift2_prepare),
    VarDef::new("hypertile", hypertile)
        .params(&[
            p("hypertile_p", 3.0),
            p("hypertile_q", 7.0),
            p("hypertile_n", 0.0),
        ])
        .prepare(hypertile_prepare),
    VarDef::new("hypertile1", hypertile1)
        .params(&[p("hypertile1_p", 3.0), p("hypertile1_q", 7.0)])
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(hypertile12_prepare),
    VarDef::new("hypertile2", hypertile2)
        .batch(super::inline_batch!(hypertile2))
        .params(&[p("hypertile2_p", 3.0), p("hypertile2_q", 7.0)])
        .flags(flag::RANDOM)
        .prepare(hypertile12_prepare),
    VarDef::new("hypertile3D", hypertile3d)
        .params(&[
            p_int("hypertile3D_p", 3.0, 3.0, I32_MAX),
            p_int("hypertile3D_q", 7.0, 3.0, I32_MAX),
            p_int("hypertile3D_n", 0.0, NEG_INF, INF),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(hypertile3d_prepare),
    VarDef::new("hypertile3D1", hypertile3d1)
        .params(&[
            p_int("hypertile3D1_p", 3.0, 3.0, I32_MAX),
            p_int("hypertile3D1_q", 7.0, 3.0, I32_MAX),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(hypertile3d12_prepare),
    VarDef::new("hypertile3D2", hypertile3d2)
        .params(&[
            p_int("hypertile3D2_p", 3.0, 3.0, I32_MAX),
            p_int("hypertile3D2_q", 7.0, 3.0, I32_MAX),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(hypertile3d12_prepare),
    VarDef::new("idisc", idisc).needs(need::SQRT | need::ATAN_YX),
    VarDef::new("inkdrop", inkdrop).params(&[
        p_range("inkdrop_r", 0.5, 0.0, INF),
        p("inkdrop_x", 0.0),
        p("inkdrop_y", 0.0),
    ]),
    VarDef::new("interference2", interference2).params(&[
        p("interference2_a1", 1.0),
        p("interference2_b1", 1.0),
        p("interference2_c1", 0.0),
        p("interference2_p1", 1.0),
        p_int("interference2_t1", 0.0, 0.0, 2.0),
        p("interference2_a2", 1.0),
        p("interference2_b2", 1.0),
        p("interference2_c2", 0.0),
        p("interference2_p2", 1.0),
        p_int("interference2_t2", 0.0, 0.0, 2.0),
    ]),
    VarDef::new("jac_cn", jac_cn).params(&[p_range("jac_cn_k", 0.5, -1.0, 1.0)]),
    VarDef::new("jac_dn", jac_dn).params(&[p_range("jac_dn_k", 0.5, -1.0, 1.0)]),
    VarDef::new("jac_sn", jac_sn).params(&[p_range("jac_sn_k", 0.5, -1.0, 1.0)]),
    VarDef::new("julia3D", julia3d)
        .batch(super::inline_batch!(julia3d))
        .params(&[p_int_nonzero("julia3D_power", 2.0, NEG_INF, INF)])
        .needs(need::SQRT | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(julia3d_prepare),
    VarDef::new("julia3Dq", julia3dq)
        .params(&[
            p_int_nonzero("julia3Dq_power", 3.0, NEG_INF, INF),
            p_int_nonzero("julia3Dq_divisor", 2.0, NEG_INF, INF),
        ])
        .needs(need::SQRT | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(julia3dq_prepare),
];

/// `t` unless the variation is applied as a regular one: then the xform's running sum, which
/// is cleared (x and y) so that the variation's output replaces it.
#[inline(always)]
fn take_sum_xy(v: &Prepared, t: &VarIn, acc: &mut Acc) -> (f64, f64) {
    if v.form == Form::Regular {
        let s = (acc.x, acc.y);
        acc.x = 0.0;
        acc.y = 0.0;
        s
    } else {
        (t.x, t.y)
    }
}

// ---------------------------------------------------------------------------------------------
// f

/// A disc folded the other way: the distance from the origin picks the angle 2π/(r+1) and the
/// polar angle picks the radius (from 0 at angle −π to 1 at π).
fn fdisc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let ang = TAU / (t.sqrt + 1.0);
    let rad = (t.atan_yx * FRAC_1_PI + 1.0) * 0.5;
    let (s, c) = ang.sin_cos();
    [v.w * rad * c, v.w * rad * s, 0.0]
}

/// Appends ln φ (φ the golden ratio), the growth rate of the Fibonacci numbers.
fn fib_prepare(v: &mut Prepared) {
    v.p.push(1.618_033_988_749_895_f64.ln());
}
/// 1/√5.
const INV_SQRT5: f64 = 1.0 / 2.236_067_977_499_79;

/// Binet's formula for the Fibonacci numbers extended to the complex plane:
/// (φ^z − φ^(−z)·e^(iπz)) / √5 with z = x + iy.
fn fibonacci(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [ln_phi] = v.derived();
    fib_common(v.w, 1.0, 1.0, ln_phi, t)
}

/// [`fibonacci`] with both powers scaled by `sc` and their exponents by `sc2`.
fn fibonacci2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sc, sc2] = v.params();
    let [ln_phi] = v.derived();
    fib_common(v.w, sc, sc2, ln_phi, t)
}

#[inline(always)]
fn fib_common(w: f64, sc: f64, sc2: f64, lp: f64, t: &VarIn) -> V3 {
    let (s1, c1) = (t.y * lp).sin_cos();
    let (s2, c2) = (-(t.x * PI + t.y * lp)).sin_cos();
    let e1 = sc * (sc2 * (t.x * lp)).exp();
    let e2 = sc * (sc2 * -(t.x * lp - t.y * PI)).exp();
    [
        w * (e1 * c1 - e2 * c2) * INV_SQRT5,
        w * (e1 * s1 - e2 * s2) * INV_SQRT5,
        0.0,
    ]
}

/// Drops the z coordinate: as a regular variation it zeroes the xform's running z and adds
/// nothing; as pre_/post_ it keeps x and y and sets z to 0.
fn flatten(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    if v.form == Form::Regular {
        acc.z = 0.0;
        [0.0, 0.0, 0.0]
    } else {
        [t.x, t.y, 0.0]
    }
}

/// Mirrors the inside of the circle of radius |weight| top to bottom (y → −y); outside the
/// circle the point is only scaled.
fn flipcircle(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let y = if t.sumsq > v.w * v.w {
        v.w * t.y
    } else {
        -(v.w * t.y)
    };
    [v.w * t.x, y, 0.0]
}

/// Mirrors the lower half-plane (y > 0) left to right.
fn flipx(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let x = if t.y > 0.0 { -(v.w * t.x) } else { v.w * t.x };
    [x, v.w * t.y, 0.0]
}

/// Mirrors the right half-plane (x > 0) top to bottom.
fn flipy(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let y = if t.x > 0.0 { -(v.w * t.y) } else { v.w * t.y };
    [v.w * t.x, y, 0.0]
}

fn flowerdb_prepare(v: &mut Prepared) {
    let [petals, petal_split] = v.params();
    let split_petals = petals * petal_split;
    v.p.push(split_petals);
}

/// A rose: the radius is scaled by |(spread + sin(petals·θ))·cos(petals·split·θ)|, giving
/// `petals` lobes, each split in two when `split` is non-zero.
fn flowerdb(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [petals, _, spread] = v.params();
    let [split_petals] = v.derived();
    let th = t.atan_yx;
    let rad = v.w * t.sqrt;
    let r2 = rad * ((spread + (petals * th).sin()) * (split_petals * th).cos()).abs();
    [r2 * th.cos(), r2 * th.sin(), 0.0]
}

/// 3-D foci: elliptic-like coordinates where the input z (or the polar angle when z is 0)
/// plays the role of a second angle.
fn foci_3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let ex = t.x.exp() * 0.5;
    let enx = 0.25 / zeps(ex);
    let second = if t.z == 0.0 { t.atan_yx } else { t.z };
    let k = v.w / zeps(ex + enx - t.y.cos() * second.cos());
    [(ex - enx) * k, t.y.sin() * k, second.sin() * k]
}

/// foci with adjustable weights `c1`, `c2` on eˣ and e⁻ˣ.
fn foci_p(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [c1, c2] = v.params();
    let ex = zeps(t.x.exp());
    let a = ex * c1;
    let b = c2 / ex;
    let (sy, cy) = t.y.sin_cos();
    let k = v.w / zeps(a + b - cy);
    [(a - b) * k, sy * k, 0.0]
}

/// A different map in each quadrant: spherical where x, y > 0, loonie where x > 0 > y,
/// a lazysusan-like swirl (centre (x, −y) params, `spin`, `twist`, `space`) where x < 0 < y,
/// linear elsewhere.
fn fourth(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [spin, space, twist, cx, cy] = v.params();
    let w = v.w;
    let (x, y) = (t.x, t.y);
    if x > 0.0 && y > 0.0 {
        let inv = 1.0 / t.sqrt;
        [w * inv * t.ux, w * inv * t.uy, 0.0]
    } else if x > 0.0 && y < 0.0 {
        let w2 = w * w;
        if t.sumsq < w2 {
            let k = w * (w2 / t.sumsq - 1.0).sqrt();
            [k * x, k * y, 0.0]
        } else {
            [w * x, w * y, 0.0]
        }
    } else if x < 0.0 && y > 0.0 {
        let dx = x - cx;
        let dy = y + cy;
        let r = (dx * dx + dy * dy).sqrt();
        if r < w {
            let a = dy.atan2(dx) + spin + twist * (w - r);
            let rr = r * w;
            [rr * a.cos() + cx, rr * a.sin() - cy, 0.0]
        } else {
            let k = w * (1.0 + space / zeps(r));
            [k * dx + cx, k * dy - cy, 0.0]
        }
    } else {
        [w * x, w * y, 0.0]
    }
}

/// tanh of each coordinate, scaled by sec(y) + effect·π: a funnel opening along the bands
/// where cos y vanishes.
fn funnel(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [effect] = v.params();
    let k = 1.0 / zeps(t.y.cos()) + effect * PI;
    [v.w * (t.x.tanh() * k), v.w * (t.y.tanh() * k), 0.0]
}

// ---------------------------------------------------------------------------------------------
// g

/// Polar coordinates remapped: x = ln Γ(r), y = θ.
fn gamma(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [v.w * ln_gamma(t.sqrt), v.w * t.atan_yx, 0.0]
}

/// Adds a roughly Gaussian offset (sum of four uniforms) in a random direction to the point.
fn gaussian(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let ang = rng.f01() * TAU;
    let spread = rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0;
    let k = v.w * spread;
    let (s, c) = ang.sin_cos();
    [k * c + t.x, k * s + t.y, 0.0]
}

fn gdoffs_prepare(v: &mut Prepared) {
    let [delta_x, delta_y, area_x, area_y, centre_x, centre_y, gam] = v.params();
    let dx = delta_x * 0.1;
    let dy = delta_y * 0.1;
    let ax = if area_x.abs() < 0.1 {
        0.1
    } else {
        area_x.abs()
    } * 2.0;
    let ay = if area_y.abs() < 0.1 {
        0.1
    } else {
        area_y.abs()
    } * 2.0;
    let b = gam * 2.0 / ax.max(ay);
    v.p.extend_from_slice(&[dx, dy, centre_x, centre_y, b]);
}

/// Signed fractional part of |a| (keeps the sign of `a`).
#[inline(always)]
fn gd_wrap(a: f64) -> f64 {
    let f = a.abs() % 1.0;
    if a < 0.0 { -f } else { f }
}

/// A cosine oscillation of `p·a` mapped into [0, 1).
#[inline(always)]
fn gd_osc(p: f64, a: f64) -> f64 {
    gd_wrap((-(p * a * TAU).cos() + 1.0) / 2.0)
}

/// Gradient-domain offsets: each coordinate is blended with cosine oscillations of itself,
/// giving a rippled, folded copy of the plane; z is scaled.
fn gdoffs(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, square] = v.params();
    let [dx, dy, cx, cy, b] = v.derived();
    let osc_x = gd_osc(dx, 1.0);
    let osc_y = if square != 0.0 {
        osc_x
    } else {
        gd_osc(dy, 1.0)
    };
    let fold = |a: f64, osc: f64| {
        mix(
            mix(a, gd_osc(a, 4.0), osc),
            gd_osc(gd_wrap(b * a), 4.0),
            osc,
        )
    };
    let ox = fold(t.x + cx, osc_x);
    let oy = fold(t.y + cy, osc_y);
    [v.w * ox, v.w * oy, v.w * t.z]
}

/// Appends w·(√2/2).
fn glynnia_prepare(v: &mut Prepared) {
    let k = v.w * (2f64.sqrt() / 2.0);
    v.p.push(k);
}

/// Appends (w·√2)/2 (Fractorium's order of operations for glynnia2).
fn glynnia2_prepare(v: &mut Prepared) {
    let k = v.w * 2f64.sqrt() / 2.0;
    v.p.push(k);
}

/// Glynn's two square-root–like maps of the plane, one picked at random: on the `outer` side
/// (of the unit circle for glynnia, of the x axis for glynnia2) as they are, on the other side
/// mirrored and with their poles guarded.
#[inline(always)]
fn glynnia_maps(w: f64, v2: f64, t: &VarIn, outer: bool, rng: &mut FastRng) -> V3 {
    let r = t.sqrt;
    if outer {
        if rng.f01() > 0.5 {
            let d = (r + t.x).sqrt();
            [v2 * d, -(v2 / d * t.y), 0.0]
        } else {
            let d = r + t.x;
            let k = w / (r * (t.y * t.y + d * d)).sqrt();
            [k * d, k * t.y, 0.0]
        }
    } else if rng.f01() > 0.5 {
        let d = zeps((r + t.x).sqrt());
        [-(v2 * d), -(v2 / d * t.y), 0.0]
    } else {
        let d = r + t.x;
        let k = w / zeps((r * (t.y * t.y + d * d)).sqrt());
        [-(k * d), k * t.y, 0.0]
    }
}

/// A random choice between two square-root–like maps of the plane (Glynn's "glynnia"), with
/// different branches inside and outside the unit circle.
fn glynnia(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [v2] = v.derived();
    if v.compat {
        glynnia_maps(v.w, v2, t, t.sqrt > 1.0, rng)
    } else {
        let r = t.sqrt;
        let side = if t.sumsq > 1.0 { 1.0 } else { -1.0 };
        let root = (r + t.x).sqrt();
        if rng.f01() < 0.5 {
            [v2 * side * root, v2 * (-t.y / zeps(root)), 0.0]
        } else {
            let k = v2 / zeps(r);
            [k * side * root, k * (t.y / zeps(root)), 0.0]
        }
    }
}

/// glynnia with the branch chosen by the upper half-plane (y > 0) instead of the unit circle.
fn glynnia2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [v2] = v.derived();
    glynnia_maps(v.w, v2, t, t.sqrt > 0.0 && t.y > 0.0, rng)
}

/// The shared outside rule of the GlynnSim family: with probability contrast·α^pow
/// (α = radius/r) the point is pulled in by α², else it is kept.
#[inline(always)]
fn glynn_pull(t: &VarIn, radius: f64, contrast: f64, pow: f64, rng: &mut FastRng) -> (f64, f64) {
    let alpha = (radius / zeps(t.sqrt)).abs();
    let a2 = alpha * alpha;
    if rng.f01() > contrast * alpha.powf(pow) {
        (t.x, t.y)
    } else {
        (a2 * t.x, a2 * t.y)
    }
}

fn glynnsim1_prepare(v: &mut Prepared) {
    let [radius, _, phi1, _, _, pow] = v.params();
    let ang = PI / 180.0 * phi1;
    let pow = pow.abs();
    v.p.extend_from_slice(&[radius * ang.cos(), radius * ang.sin(), pow]);
}

/// A random point of the ring of radius `radius1` (inner fraction `thickness`) around (cx, cy).
#[inline(always)]
fn glynn1_ring(radius1: f64, thickness: f64, cx: f64, cy: f64, rng: &mut FastRng) -> (f64, f64) {
    let r = radius1 * (thickness + (1.0 - thickness) * rng.f01());
    let (s, c) = (TAU * rng.f01()).sin_cos();
    (r * c + cx, r * s + cy)
}

/// Glynn's "GlynnSim1": points inside the circle of radius `radius` become a small ring centred
/// on that circle at angle `phi1`; outside points are randomly pulled inwards, and those that
/// land in the small ring are replaced by ring points.
fn glynnsim1(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, radius1, _, thickness, contrast] = v.params();
    let [cx, cy, pow] = v.derived();
    let (x, y) = if t.sqrt < radius {
        glynn1_ring(radius1, thickness, cx, cy, rng)
    } else {
        let (x, y) = glynn_pull(t, radius, contrast, pow, rng);
        if sqr(x - cx) + sqr(y - cy) < radius1 * radius1 {
            glynn1_ring(radius1, thickness, cx, cy, rng)
        } else {
            (x, y)
        }
    };
    [v.w * x, v.w * y, 0.0]
}

fn glynnsim2_prepare(v: &mut Prepared) {
    let [radius, thickness, _, pow, phi1, phi2] = v.params();
    let pow = pow.abs();
    let phi10 = PI * phi1 / 180.0;
    let phi20 = PI * phi2 / 180.0;
    let gam = thickness * (2.0 * radius + thickness) / zeps(radius + thickness);
    v.p.extend_from_slice(&[pow, phi10, gam, phi20 - phi10]);
}

/// Glynn's "GlynnSim2": points inside the circle of radius `radius` become an arc (from `Phi1`
/// to `Phi2` degrees) of a ring just outside it; outside points are randomly pulled inwards.
fn glynnsim2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, thickness, contrast] = v.params();
    let [pow, phi10, gam, delta] = v.derived();
    if t.sqrt < radius {
        let r = radius + thickness - gam * rng.f01();
        let (s, c) = (phi10 + delta * rng.f01()).sin_cos();
        [v.w * (r * c), v.w * (r * s), 0.0]
    } else {
        glynn_scaled(v.w, t, radius, contrast, pow, rng)
    }
}

/// Weighted output of [`glynn_pull`], with Fractorium's order of products (w·α² first).
#[inline(always)]
fn glynn_scaled(w: f64, t: &VarIn, radius: f64, contrast: f64, pow: f64, rng: &mut FastRng) -> V3 {
    let alpha = (radius / zeps(t.sqrt)).abs();
    if rng.f01() > contrast * alpha.powf(pow) {
        [w * t.x, w * t.y, 0.0]
    } else {
        let k = w * (alpha * alpha);
        [k * t.x, k * t.y, 0.0]
    }
}

fn glynnsim3_prepare(v: &mut Prepared) {
    let [radius, thickness] = v.params();
    let radius1 = radius + thickness;
    let radius2 = radius * radius / zeps(radius1);
    let gam = radius1 / zeps(radius1 + radius2);
    v.p.extend_from_slice(&[radius1, radius2, gam]);
}

/// Glynn's "GlynnSim3": points inside radius + thickness land on one of two circles (radii
/// radius + thickness and radius²/(radius + thickness)); outside points are randomly pulled in.
fn glynnsim3(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, _, _, contrast, pow] = v.params();
    let [radius1, radius2, gam] = v.derived();
    if t.sqrt < radius1 {
        // Fractorium draws a radius that the circle choice then overrides.
        let _ = rng.f01();
        let (s, c) = (TAU * rng.f01()).sin_cos();
        let r = if rng.f01() < gam { radius1 } else { radius2 };
        [v.w * (r * c), v.w * (r * s), 0.0]
    } else {
        glynn_scaled(v.w, t, radius, contrast, pow, rng)
    }
}

/// Glynn's "GlynnSim4": points inside the circle collapse onto the point (X, Y); outside points
/// are randomly pulled in.
fn glynnsim4(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, contrast, pow, px, py] = v.params();
    if t.sqrt < radius {
        [v.w * px, v.w * py, 0.0]
    } else {
        glynn_scaled(v.w, t, radius, contrast, pow, rng)
    }
}

/// Glynn's "GlynnSim5": points inside radius + thickness go to the origin; outside points are
/// either kept or sent to the diagonal point (α², α²).
fn glynnsim5(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, thickness, contrast, pow] = v.params();
    if t.sqrt < radius + thickness {
        return [0.0, 0.0, 0.0];
    }
    let alpha = (radius / zeps(t.sqrt)).abs();
    if rng.f01() > contrast * alpha.powf(pow) {
        [v.w * t.x, v.w * t.y, 0.0]
    } else {
        let k = v.w * (alpha * alpha);
        [k, k, 0.0]
    }
}

fn gnarly_prepare(v: &mut Prepared) {
    let [cellsize] = v.params();
    let half = 0.5 * cellsize;
    v.p.push(zeps(half * half));
}

/// Cuts the plane into square cells and twists the disc inscribed in each cell by an angle
/// growing with the logarithm of the distance to the cell centre.
fn gnarly(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cell, twist] = v.params();
    let [rr] = v.derived();
    let (mut x, mut y) = (t.x, t.y);
    if cell != 0.0 {
        let cx = (floor_f(x / cell) + 0.5) * cell;
        let cy = (floor_f(y / cell) + 0.5) * cell;
        let lx = x - cx;
        let ly = y - cy;
        let d2 = lx * lx + ly * ly;
        if d2 <= rr {
            let (s, c) = (twist * (d2 / rr).ln()).sin_cos();
            x = cx + c * lx + s * ly;
            y = cy - s * lx + c * ly;
        }
    }
    [v.w * x, v.w * y, 0.0]
}

/// Pushes each point one unit out of its grid square, towards the square's nearest side
/// (a square spiral away from the origin).
fn gridout(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let gx = lrint(t.x);
    let gy = lrint(t.y);
    let (dx, dy) = if gy <= 0.0 {
        if gx > 0.0 {
            if -gy >= gx { (1.0, 0.0) } else { (0.0, 1.0) }
        } else if gy <= gx {
            (1.0, 0.0)
        } else {
            (0.0, -1.0)
        }
    } else if gx > 0.0 {
        if gy >= gx { (-1.0, 0.0) } else { (0.0, 1.0) }
    } else if gy > -gx {
        (-1.0, 0.0)
    } else {
        (0.0, -1.0)
    };
    [v.w * (t.x + dx), v.w * (t.y + dy), 0.0]
}

// ---------------------------------------------------------------------------------------------
// h

fn heat_prepare(v: &mut Prepared) {
    let [
        theta_period,
        theta_phase,
        theta_amp,
        phi_period,
        phi_phase,
        phi_amp,
        r_period,
        r_phase,
        r_amp,
    ] = v.params();
    let inv = |period: f64| if period == 0.0 { 0.0 } else { 1.0 / period };
    let (tx, px, rx) = (inv(theta_period), inv(phi_period), inv(r_period));
    let w = v.w;
    let derived = [
        w * theta_amp,
        TAU * tx,
        theta_phase * tx,
        w * phi_amp,
        TAU * px,
        phi_phase * px,
        w * r_amp,
        TAU * rx,
        r_phase * rx,
    ];
    v.p.extend_from_slice(&derived);
}

/// Spherical coordinates made wavy: the radius, azimuth and inclination each get a sine
/// ripple (period, phase, amplitude) driven by the radius.
fn heat(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [at, bt, ct, ap, bp, cp, ar, br, cr] = v.derived();
    let mut r = (t.sumsq + t.z).abs().sqrt();
    r += ar * br.mul_add(r, cr).sin();
    if r == 0.0 {
        r = f64::EPSILON;
    }
    let (st, ct_) = at.mul_add(bt.mul_add(r, ct).sin(), t.atan_yx).sin_cos();
    let incl = (t.z / r).clamp(-1.0, 1.0).acos();
    let (sp, cp_) = ap.mul_add(bp.mul_add(r, cp).sin(), incl).sin_cos();
    [r * ct_ * sp, r * st * sp, r * cp_]
}

/// A helicoid: the polar angle is advanced by 2π·frequency·z, the radius kept, z scaled.
fn helicoid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [frequency] = v.params();
    let ang = t.z * (frequency * TAU) + t.atan_yx;
    let k = v.w * t.sqrt;
    [k * ang.cos(), k * ang.sin(), v.w * t.z]
}

/// A helix: the point is shifted by a circle of radius `width` whose angle turns with z.
fn helix(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [frequency, width] = v.params();
    let ang = t.z * (frequency * TAU);
    [
        v.w * (t.x + ang.cos() * width),
        v.w * (t.y + ang.sin() * width),
        v.w * t.z,
    ]
}

/// Projects the plane onto the upper unit hemisphere: (x, y, 1)/√(r² + 1).
fn hemisphere(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let k = v.w / (t.sumsq + 1.0).sqrt();
    [t.x * k, t.y * k, k]
}

/// One step of the Hénon map: (1 − a·x² + y, b·x).
fn henon(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b] = v.params();
    [(1.0 - a * (t.x * t.x) + t.y) * v.w, b * t.x * v.w, 0.0]
}

fn hex_modulus_prepare(v: &mut Prepared) {
    let [size] = v.params();
    let hsize = HALF_SQRT3 / zeps(size);
    let wk = v.w / HALF_SQRT3;
    v.p.extend_from_slice(&[hsize, wk]);
}

/// The plane modulo a hexagonal lattice: each point is replaced by its offset from the centre
/// of its hexagon (cube-coordinate rounding).
fn hex_modulus(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [hsize, wk] = v.derived();
    let px = t.x * hsize;
    let py = t.y * hsize;
    let third = py / 3.0;
    let cx = 0.577_350_269_189_625_7 * px - third;
    let cz = 2.0 * third;
    let cy = -cx - cz;
    let (mut rx, ry, mut rz) = (cx.round(), cy.round(), cz.round());
    let (ex, ey, ez) = ((rx - cx).abs(), (ry - cy).abs(), (rz - cz).abs());
    // The coordinate with the largest rounding error is rebuilt from the other two (when that
    // is y, x and z are already right).
    if ex > ey && ex > ez {
        rx = -ry - rz;
    } else if ey <= ez {
        rz = -rx - ry;
    }
    let hx = SQRT3 * rx + HALF_SQRT3 * rz;
    let hy = 1.5 * rz;
    [(px - hx) * wk, (py - hy) * wk, 0.0]
}

/// Random hexagons: a random cell of a (2x+1)·(2y+1) hexagonal grid is kept with probability
/// `density` (by a hash of the cell), and a random point of its hexagon is drawn, shrunk by
/// hash^power.
fn hex_rand(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [gx, gy, size, power, density, seed] = v.params();
    let k = rng.f01() * 6.0;
    let sector = floor_i64(k);
    let frac = k - sector as f64;
    let edge = (1.0 + frac * frac - frac).sqrt();
    let odd = sector.wrapping_sub(floor_i64(k / 2.0).wrapping_mul(2)) == 1;
    let sign = if odd { 1.0 } else { -1.0 };
    let ang = 2.094_395_102_393_195_5 * (sector / 2) as f64
        + sign * (HALF_SQRT3 * frac / edge).asin()
        - FRAC_PI_2;
    let cell_x = (rng.f01() * gx * 2.0).floor() - gx;
    let cell_y = (rng.f01() * gy * 2.0).floor() - gy;
    let hx = cell_x + 0.5 * cell_y;
    let hy = cell_y * HALF_SQRT3;
    if sine_hash(hy, hx, seed) < density {
        let reach = edge * rng.f01().sqrt() * 1.154_700_538_379_251_5;
        let shrink = sine_hash(hx, hy, seed);
        let r = size * 0.5 * reach * shrink.powf(power);
        [(ang.cos() * r + hx) * v.w, (ang.sin() * r + hy) * v.w, 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// The tile rotation of hex_truchet: 60° as Fractorium writes it, to four decimals (not π/3).
#[allow(clippy::approx_constant)]
const TRUNCATED_60_DEG: f64 = 1.0471;

fn hex_truchet_prepare(v: &mut Prepared) {
    let [size, side] = v.params();
    let shrink = (1.0 - size) * 0.85;
    let lo = sqr(0.15 + shrink * 0.5);
    let hi = sqr(1.0 - shrink * 0.5);
    v.p.extend_from_slice(&[lo, hi - lo, side * 2.0 + 1.0]);
}

/// Hexagonal Truchet tiles: random points on the three arcs of a random hexagon of the grid,
/// the tile rotated by 60° or not according to a hash of its cell.
fn hex_truchet(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, side, seed] = v.params();
    let [lo, span, cells] = v.derived();
    let ang = rng.f01() * TAU;
    let r = (rng.f01() * span + lo).sqrt();
    let (ox, oy) = if ang < 2.0943 {
        (1.0, 0.5773)
    } else if ang < 4.1887 {
        (-1.0, 0.5773)
    } else {
        (0.0, -1.1547)
    };
    let gx = 2.0 * (floor_f(rng.f01() * cells) - side);
    let gy = 2.0 * (floor_f(rng.f01() * cells) - side);
    let hx = gx + 0.5 * gy;
    let hy = 0.8660 * gy;
    let turn = if sine_hash(gx, gy, seed) < 0.5 {
        0.0
    } else {
        TRUNCATED_60_DEG
    };
    let a = ang + 2.6179 - turn;
    let (st, ct) = turn.sin_cos();
    let cx = ox * ct + oy * st;
    let cy = -ox * st + oy * ct;
    [
        (a.cos() * r + cx + hx) * v.w,
        (a.sin() * r + cy + hy) * v.w,
        0.0,
    ]
}

// State slots of the two hexagon walkers.
const ST_SIXFOLD: usize = 0;
const ST_SIX_STEP: usize = 1;
const ST_THREE_STEP: usize = 2;

fn hexaplay3d_prepare(v: &mut Prepared) {
    let [majp, scale] = v.params();
    let majp = majp.abs();
    let (plane, boost) = if majp <= 1.0 {
        (1.0, 0.0)
    } else {
        (2.0, (majp - 1.0) * 0.5)
    };
    let lift = (PI / 3.0).sin();
    let half_scale = scale * 0.5;
    v.p.extend_from_slice(&[plane, boost, lift, half_scale]);
    // Fractorium starts on the six-node walk two times in three (global random); start there.
    v.state.set(ST_SIXFOLD, 1.0);
    v.state.set(ST_SIX_STEP, 0.0);
    v.state.set(ST_THREE_STEP, 0.0);
}

/// Advances the walker's cycles: a finished cycle of six or three nodes picks the next kind of
/// cycle at random. Returns (six-node walk?, node index) and records the step.
#[inline(always)]
fn hex_walk_step(v: &Prepared, rng: &mut FastRng) -> (bool, usize) {
    let mut six = v.state.get(ST_SIXFOLD);
    let mut i6 = v.state.get(ST_SIX_STEP);
    let mut i3 = v.state.get(ST_THREE_STEP);
    if i6 > 5.0 {
        i6 = 0.0;
        six = if rng.bit() { 1.0 } else { 0.0 };
    }
    if i3 > 2.0 {
        i3 = 0.0;
        six = if rng.bit() { 1.0 } else { 0.0 };
    }
    v.state.set(ST_SIXFOLD, six);
    v.state.set(ST_SIX_STEP, i6);
    v.state.set(ST_THREE_STEP, i3);
    (
        six != 0.0,
        if six != 0.0 { i6 as usize } else { i3 as usize },
    )
}

/// Counts one step of the current walk.
#[inline(always)]
fn hex_walk_advance(v: &Prepared, six: bool) {
    let slot = if six { ST_SIX_STEP } else { ST_THREE_STEP };
    v.state.set(slot, v.state.get(slot) + 1.0);
}

/// A hexagon chaos game: each call halves the (running sum + point) and adds the next vertex of
/// a hexagon (or of a triangle, 120° steps), vertices taken in order; with |majp| > 1 the copies
/// are stacked above and below the plane.
fn hexaplay3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, zlift] = v.params();
    let [plane, boost, lift, half_scale] = v.derived();
    let (six, node) = hex_walk_step(v, rng);
    let (sx, sy) = take_sum_xy(v, t, acc);
    let updown = if rng.bit() { -1.0 } else { 1.0 };
    let z = if plane == 2.0 {
        t.z * 0.5 * zlift + updown * boost
    } else {
        t.z * 0.5 * zlift
    };
    let (vx, vy) = if six {
        const X6: [f64; 6] = [1.0, 0.5, -0.5, -1.0, -0.5, 0.5];
        const Y6: [f64; 6] = [0.0, 1.0, 1.0, 0.0, -1.0, -1.0];
        (X6[node], Y6[node] * lift)
    } else {
        const X3: [f64; 3] = [1.0, -0.5, -0.5];
        const Y3: [f64; 3] = [0.0, 1.0, -1.0];
        (X3[node], Y3[node] * lift)
    };
    hex_walk_advance(v, six);
    [
        (sx + t.x) * half_scale + v.w * vx,
        (sy + t.y) * half_scale + v.w * vy,
        z,
    ]
}

fn hexcrop_prepare(v: &mut Prepared) {
    let [sx, sy] = v.params();
    const H: f64 = 1.060_660_171_779_821_2;
    const S2: f64 = std::f64::consts::SQRT_2;
    let xs = [-0.5 * sx, 0.5 * sx, S2 * sx, 0.5 * sx, -0.5 * sx, -S2 * sx];
    let ys = [H * sy, H * sy, 0.0 * sy, -H * sy, -H * sy, 0.0 * sy];
    v.p.extend_from_slice(&xs);
    v.p.extend_from_slice(&ys);
}

/// Crops to a hexagon (scaled by scale_x/scale_y, shifted by the centre): points inside are
/// kept, the others sent to the far `dropoff` point. As a regular variation the xform's running
/// sum is carried along inside the hexagon and dropped outside.
fn hexcrop(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, cx, cy, drop] = v.params();
    let (xs, ys) = v.table(0).split_at(6);
    let ix = t.x + cx;
    let iy = t.y + cy;
    let mut inside = false;
    let mut prev = 5;
    for cur in 0..6 {
        let (ya, yb) = (ys[cur], ys[prev]);
        if ((ya <= iy && iy < yb) || (yb <= iy && iy < ya))
            && ix < (xs[prev] - xs[cur]) * (iy - ya) / zeps(yb - ya) + xs[cur]
        {
            inside = !inside;
        }
        prev = cur;
    }
    let z = v.w * t.z;
    if v.form == Form::Regular {
        let (sx, sy) = (acc.x, acc.y);
        acc.x = 0.0;
        acc.y = 0.0;
        if inside {
            [sx + ix * v.w, sy + iy * v.w, z]
        } else {
            [drop, drop, z]
        }
    } else if inside {
        [ix * v.w, iy * v.w, z]
    } else {
        [drop, drop, z]
    }
}

fn hexes_prepare(v: &mut Prepared) {
    let [_, _, rotate] = v.params();
    let (s, c) = (rotate * TAU).sin_cos();
    v.p.extend_from_slice(&[s, c]);
}

/// Index of the point of `pts` nearest to `u` (first on ties).
#[inline(always)]
fn nearest(pts: &[(f64, f64)], u: (f64, f64)) -> usize {
    let mut best = f64::MAX;
    let mut k = 0;
    for (i, p) in pts.iter().enumerate() {
        let d2 = sqr(p.0 - u.0) + sqr(p.1 - u.1);
        if d2 < best {
            best = d2;
            k = i;
        }
    }
    k
}

/// How far `u` lies from `centre` towards the bisector between `centre` and each other site,
/// as the largest such ratio (1 on the Voronoi cell boundary).
#[inline(always)]
fn cell_ratio(pts: &[(f64, f64)], centre: usize, u: (f64, f64)) -> f64 {
    let q = pts[centre];
    let mut most = f64::MIN;
    for (i, p) in pts.iter().enumerate() {
        if i == centre {
            continue;
        }
        let (ex, ey) = (p.0 - q.0, p.1 - q.1);
        let ratio = if ex == 0.0 && ey == 0.0 {
            1.0
        } else {
            2.0 * ((u.0 - q.0) * ex + (u.1 - q.1) * ey) / zeps(ex * ex + ey * ey)
        };
        if ratio > most {
            most = ratio;
        }
    }
    most
}

/// Hexagonal cells: each point is rotated about the centre of its hexagon and its distance
/// to the centre remapped by a power law, smoothly blended near the cell edges.
fn hexes(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, power, _, scale] = v.params();
    let [rs, rc] = v.derived();
    const HX_X: f64 = 1.0 / 3.0;
    const HX_Y: f64 = SQRT3 / 3.0;
    const HY_X: f64 = -1.0 / 3.0;
    const HY_Y: f64 = SQRT3 / 3.0;
    const OX_H: f64 = 1.5;
    const OX_K: f64 = -1.5;
    const OY_H: f64 = SQRT3 / 2.0;
    const OY_K: f64 = SQRT3 / 2.0;
    if s == 0.0 {
        return [0.0, 0.0, 0.0];
    }
    let u = (t.x, t.y);
    let mut h = floor_f((HX_X * u.0 + HX_Y * u.1) / s);
    let mut k = floor_f((HY_X * u.0 + HY_Y * u.1) / s);
    let mut corners = [(0.0, 0.0); 4];
    for (n, c) in corners.iter_mut().enumerate() {
        let (di, dj) = (h + (n / 2) as f64, k + (n % 2) as f64);
        *c = ((OX_H * di + OX_K * dj) * s, (OY_H * di + OY_K * dj) * s);
    }
    let pick = nearest(&corners, u);
    h += (pick / 2) as f64;
    k += (pick % 2) as f64;
    let ox = (OX_H * h + OX_K * k) * s;
    let oy = (OY_H * h + OY_K * k) * s;
    let sites = [
        (ox, oy),
        (ox + OX_K * s, oy + OY_K * s),
        (ox + (OX_H + OX_K) * s, oy + (OY_H + OY_K) * s),
        (ox + OX_H * s, oy + OY_H * s),
        (ox - OX_K * s, oy - OY_K * s),
        (ox - (OX_H + OX_K) * s, oy - (OY_H + OY_K) * s),
        (ox - OX_H * s, oy - OY_H * s),
    ];
    let l1 = cell_ratio(&sites, 0, u);
    let dx = u.0 - ox;
    let dy = u.1 - oy;
    let target = l1.abs().powf(power) * scale;
    let rx = dx * rc + dy * rs;
    let ry = -dx * rs + dy * rc;
    let l2 = cell_ratio(&sites, 0, (rx + ox, ry + oy));
    let l = if l1 < l2 { l2 } else { l1 };
    let f = if l < 0.5 {
        target / l1
    } else if l > 0.8 {
        target / l2
    } else {
        ((target / l1) * (0.8 - l) + (target / l2) * (l - 0.5)) / 0.3
    };
    [v.w * (rx * f + ox), v.w * (ry * f + oy), 0.0]
}

fn hexnix3d_prepare(v: &mut Prepared) {
    let [majp] = v.params();
    let amajp = majp.abs();
    let (plane, boost) = if amajp <= 1.0 {
        (0.0, 0.0)
    } else if amajp < 2.0 {
        (1.0, 0.0)
    } else {
        (2.0, (amajp - 2.0) * 0.5)
    };
    let gentle = if plane == 1.0 && majp < 0.0 {
        if (-2.0..-1.0).contains(&majp) {
            amajp - 1.0
        } else {
            1.0
        }
    } else {
        0.0
    };
    let smooth = if v.w.abs() <= 0.5 { v.w * 2.0 } else { 1.0 };
    let lift = (PI / 3.0).sin();
    let c7 = (7.0 * PI / 6.0).cos();
    let c11 = (11.0 * PI / 6.0).cos();
    v.p.extend_from_slice(&[smooth, plane, boost, gentle, lift, c7, c11]);
    // Fractorium picks the first walk from its global generator; start on the six-node walk.
    v.state.set(ST_SIXFOLD, 1.0);
    v.state.set(ST_SIX_STEP, 0.0);
    v.state.set(ST_THREE_STEP, 0.0);
}

/// A hexagon/triangle chaos game in 3-D: each call rotates and scales the (running sum and)
/// point about a random vertex of a hexagon (or a triangle) and moves towards it; `majp` stacks
/// copies above and below the plane, `zlift` scales z. Weights below 0.5 blend with the input.
fn hexnix3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [majp, scale, zlift, side3] = v.params();
    let [smooth, plane, boost, gentle, lift, c7, c11] = v.derived();
    let (six, _) = hex_walk_step(v, rng);
    let regular = v.form == Form::Regular;
    let (sx, sy, sz) = if regular {
        let s = (acc.x, acc.y, acc.z);
        acc.x = 0.0;
        acc.y = 0.0;
        s
    } else {
        (t.x, t.y, t.z)
    };
    let updown = if rng.bit() { -1.0 } else { 1.0 };
    let z = if plane == 0.0 {
        smooth * t.z * scale * zlift
    } else if plane == 1.0 && majp < 0.0 {
        // Fractorium leaves z unset for the upper copy; it is 0 here.
        if updown < 0.0 {
            -2.0 * (sz * gentle)
        } else {
            0.0
        }
    } else if plane == 2.0 && majp < 0.0 {
        if updown > 0.0 {
            smooth * (t.z * scale * zlift + boost)
        } else {
            if regular {
                acc.z = 0.0;
            }
            (sz - 2.0 * smooth * sz) + smooth * updown * (t.z * scale * zlift + boost)
        }
    } else {
        smooth * (t.z * scale * zlift + updown * boost)
    };
    let (vx, vy, reach) = if six {
        const X6: [f64; 6] = [1.0, 0.5, -0.5, -1.0, -0.5, 0.5];
        const Y6: [f64; 6] = [0.0, -1.0, -1.0, 0.0, 1.0, 1.0];
        let n = rng.below(6) as usize;
        (X6[n], Y6[n] * lift, 1.0)
    } else {
        let n = rng.below(3) as usize;
        let vx = [0.0, c7, c11][n];
        let vy = [-1.0, 0.5, 0.5][n];
        (vx, vy, side3)
    };
    hex_walk_advance(v, six);
    let ss = smooth * scale;
    let rot_sum_x = ss * sx * vx - ss * sy * vy;
    let rot_sum_y = ss * sy * vx + ss * sx * vy;
    let rot_pt_x = t.x * smooth * scale * vx - t.y * smooth * scale * vy;
    let rot_pt_y = t.y * smooth * scale * vx + t.x * smooth * scale * vy;
    let pull = smooth * v.w * reach;
    [
        sx * (1.0 - smooth) + rot_sum_x + rot_pt_x + pull * vx,
        sy * (1.0 - smooth) + rot_sum_y + rot_pt_y + pull * vy,
        z,
    ]
}

/// "ho": x, y and z become powers of products of sines and cosines of the input plus small
/// arctangent terms (a knotted 3-D surface).
fn ho(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [px, py, pz] = v.params();
    let (xx, yy, zz) = (t.x * t.x, t.y * t.y, t.z * t.z);
    let om_x = yy.atan2(zz);
    let om_y = xx.atan2(zz);
    let (su, cu) = t.x.sin_cos();
    let (sv, cv) = t.y.sin_cos();
    let cucv = cu * cv;
    let sucv = su * cv;
    let x = cucv.abs().powf(px) + cucv * px + 0.25 * om_x;
    let y = sucv.abs().powf(py) + sucv * py + 0.25 * om_y;
    let z = sv.abs().powf(pz) + sv * pz;
    [v.w * x, v.w * y, v.w * z]
}

/// Opens a hole at the origin whose size varies with the polar angle (power `a`); with
/// `inside` the plane is squeezed into the hole instead.
fn hole(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, inside] = v.params();
    let delta = (t.atan_yx / PI + 1.0).powf(a);
    let r = if inside != 0.0 {
        v.w * delta / (t.sqrt + delta)
    } else {
        v.w * t.sqrt + delta
    };
    [r * t.ux, r * t.uy, 0.0]
}

fn hypercrop_prepare(v: &mut Prepared) {
    let [n, rad] = v.params();
    let n = zeps(n);
    let coeff = zeps(n * 0.5 / PI);
    let a0 = PI / n;
    let len = 1.0 / zeps(a0.cos());
    let d = rad * a0.sin() * len;
    v.p.extend_from_slice(&[coeff, a0, len, d]);
}

/// Crops the discs of a hyperbolic n-gon tiling: points inside the disc around one of the n
/// polygon vertices are pushed to its edge (or to the vertex, or to the origin, by `zero`).
fn hypercrop(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, zero] = v.params();
    let [coeff, a0, len, d] = v.derived();
    let ang = floor_f(t.atan_yx * coeff) / coeff + a0;
    let x0 = ang.cos() * len;
    let y0 = ang.sin() * len;
    let (mut fx, mut fy, mut fz) = (t.x, t.y, t.z);
    if (sqr(t.x - x0) + sqr(t.y - y0)).sqrt() < d {
        fz = 0.0;
        if zero > 1.5 {
            fx = x0;
            fy = y0;
        } else if zero > 0.5 {
            fx = 0.0;
            fy = 0.0;
        } else {
            let ra = (t.y - y0).atan2(t.x - x0);
            fx = x0 + ra.cos() * d;
            fy = y0 + ra.sin() * d;
        }
    }
    [fx * v.w, fy * v.w, fz * v.w]
}

/// A hyperbolic translation of the Poincaré disc by `shift` along x (inversion, shift,
/// inversion); as a regular variation (compat mode) it replaces the xform's running sum.
fn hypershift_prepare(v: &mut Prepared) {
    let [shift] = v.params();
    v.p.push(1.0 - shift * shift);
}

fn hypershift(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [shift] = v.params();
    let [scale] = v.derived();
    let inv = 1.0 / zeps(t.sumsq);
    let x = inv * t.x + shift;
    let y = inv * t.y;
    let k = v.w * scale / zeps(x * x + y * y);
    if v.compat && v.form == Form::Regular {
        *acc = Acc {
            color: acc.color,
            ..Acc::default()
        };
    }
    [k * x + shift, k * y, 0.0]
}

fn hypershift2_prepare(v: &mut Prepared) {
    let [p_, q_] = v.params();
    let pq = PI / q_;
    let pp = PI / p_;
    let spq = pq.sin();
    let spp = pp.sin();
    let shift = (PI * 0.5 - pq - pp).sin() / (1.0 - sqr(spq) - sqr(spp)).sqrt();
    let lean = (PI / 2.0 + pp).sin();
    let scale2 = 1.0 / (sqr(lean) / sqr(spq) - 1.0).sqrt() * (lean / spq - 1.0);
    let scale = 1.0 - shift * shift;
    v.p.extend_from_slice(&[shift, scale, scale2]);
}

/// A hyperbolic {p, q} tiling step: a hyperbolic shift of the scaled point, then a rotation by
/// a random odd multiple of π/p; z is scaled like the point.
fn hypershift2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [p_] = v.params();
    let [shift, scale, scale2] = v.derived();
    let fx = t.x * scale2;
    let fy = t.y * scale2;
    let inv = 1.0 / zeps(fx * fx + fy * fy);
    let x = inv * fx + shift;
    let y = inv * fy;
    let k = v.w * scale / zeps(x * x + y * y);
    let ang = (floor_i64(rng.f01() * p_) * 2 + 1) as f64 * PI / p_;
    let bx = k * x + shift;
    let by = k * y;
    let (sa, ca) = ang.sin_cos();
    if v.compat && v.form == Form::Regular {
        *acc = Acc {
            color: acc.color,
            ..Acc::default()
        };
    }
    [ca * bx - sa * by, sa * bx + ca * by, t.z * k]
}

fn hypertile_prepare(v: &mut Prepared) {
    let [p_, q_, n] = v.params();
    let pa = TAU / zeps(p_);
    let cs = pa.cos();
    let r2 = (1.0 - cs) / (cs + (TAU / zeps(q_)).cos()) + 1.0;
    let r = if r2 > 0.0 { 1.0 / r2.sqrt() } else { 1.0 };
    let a = n * pa;
    v.p.extend_from_slice(&[r * a.cos(), r * a.sin()]);
}

/// A Möbius map of the Poincaré disc carrying the origin to the n-th vertex of the {p, q}
/// hyperbolic tiling's central polygon.
fn hypertile(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [re, im] = v.derived();
    let a = t.x + re;
    let b = t.y - im;
    let c = re * t.x - im * t.y + 1.0;
    let d = re * t.y + im * t.x;
    let k = v.w / (c * c + d * d);
    [k * (a * c + b * d), k * (b * c - a * d), 0.0]
}

fn hypertile12_prepare(v: &mut Prepared) {
    let [p_, q_] = v.params();
    let pa = TAU / zeps(p_);
    let cs = pa.cos();
    let r2 = 1.0 - (cs - 1.0) / (cs + (TAU / zeps(q_)).cos());
    let r = if r2 > 0.0 { 1.0 / r2.sqrt() } else { 1.0 };
    let whole_p = trunc_i32(p_) as f64;
    v.p.extend_from_slice(&[pa, r, whole_p]);
}

/// The {p, q} tiling map of `hypertile` towards a random vertex of the central polygon.
fn hypertile1(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, r, whole_p] = v.derived();
    let ang = if v.compat {
        crand(rng) * pa
    } else {
        floor_f(rng.f01() * whole_p) * pa
    };
    let (sa, ca) = ang.sin_cos();
    let re = r * ca;
    let im = r * sa;
    let a = t.x + re;
    let b = t.y - im;
    let c = re * t.x - im * t.y + 1.0;
    let d = re * t.y + im * t.x;
    let k = v.w / zeps(c * c + d * d);
    [k * (a * c + b * d), k * (b * c - a * d), 0.0]
}

/// The {p, q} tiling map towards the first vertex, followed by a rotation by a random multiple
/// of 2π/p.
fn hypertile2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, r] = v.derived();
    let a = t.x + r;
    let b = t.y;
    let c = r * t.x + 1.0;
    let d = r * t.y;
    let x = a * c + b * d;
    let y = b * c - a * d;
    let k = v.w / zeps(c * c + d * d);
    let (sa, ca) = (crand(rng) * pa).sin_cos();
    [k * (x * ca + y * sa), k * (y * ca - x * sa), 0.0]
}

/// Radius of the {p, q} tiling's vertex circle (the 3-D hypertiles' shared constant), and 2π/p.
#[inline(always)]
fn tile3d_radius(p_: f64, q_: f64) -> (f64, f64) {
    let pa = TAU / zeps(p_);
    let qa = TAU / zeps(q_);
    let r = -(pa.cos() - 1.0) / zeps(pa.cos() + qa.cos());
    let r = if r > 0.0 {
        1.0 / zeps((1.0 + r).sqrt())
    } else {
        1.0
    };
    (r, pa)
}

fn hypertile3d_prepare(v: &mut Prepared) {
    let [p, q, n] = v.params();
    let (r, pa) = tile3d_radius(p, q);
    let na = n * pa;
    let cx = r * na.cos();
    let cy = r * na.sin();
    let (cx2, cy2) = (cx * cx, cy * cy);
    v.p.extend_from_slice(&[
        cx,
        cy,
        cx2 + cy2,
        2.0 * cx,
        2.0 * cy,
        1.0 + cx2 - cy2,
        1.0 + cy2 - cx2,
        1.0 - cy2 - cx2,
    ]);
}

/// The hyperbolic tiling map of `hypertile` extended to 3-D (a Möbius map of the ball).
fn hypertile3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cx, cy, c2, c2x, c2y, s2x, s2y, s2z] = v.derived();
    let r2 = t.sumsq + t.z;
    let x2cx = c2x * t.x;
    let y2cy = c2y * t.y;
    let d = v.w / zeps(c2 * r2 + x2cx - y2cy + 1.0);
    [
        d * (t.x * s2x - cx * (y2cy - r2 - 1.0)),
        d * (t.y * s2y + cy * (-x2cx - r2 - 1.0)),
        d * (t.z * s2z),
    ]
}

fn hypertile3d12_prepare(v: &mut Prepared) {
    let [p, q] = v.params();
    let (r, pa) = tile3d_radius(p, q);
    let c2 = r * r;
    v.p.extend_from_slice(&[pa, r, c2, 1.0 - c2, 2.0 * r, 1.0 + c2]);
}

/// The 3-D hyperbolic tiling map towards a random vertex of the central polygon.
fn hypertile3d1(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, r, c2, s2z] = v.derived();
    let (sa, ca) = (crand(rng) * pa).sin_cos();
    let cx = r * ca;
    let cy = r * sa;
    let s2x = 1.0 + cx * cx - cy * cy;
    let s2y = 1.0 + cy * cy - cx * cx;
    let r2 = t.sumsq + t.z * t.z;
    let x2cx = 2.0 * cx * t.x;
    let y2cy = 2.0 * cy * t.y;
    let d = v.w / zeps(c2 * r2 + x2cx - y2cy + 1.0);
    [
        d * (t.x * s2x - cx * (y2cy - r2 - 1.0)),
        d * (t.y * s2y + cy * (-x2cx - r2 - 1.0)),
        d * (t.z * s2z),
    ]
}

/// The 3-D hyperbolic tiling map towards the first vertex, then a random rotation by a
/// multiple of 2π/p about the z axis.
fn hypertile3d2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, cx, c2, s2z, c2x, s2x] = v.derived();
    let s2y = s2z;
    let r2 = t.sumsq + t.z * t.z;
    let x2cx = c2x * t.x;
    let x = t.x * s2x - cx * (-r2 - 1.0);
    let y = t.y * s2y;
    let k = v.w / (c2 * r2 + x2cx + 1.0);
    let (sa, ca) = (crand(rng) * pa).sin_cos();
    [
        k * (x * ca + y * sa),
        k * (y * ca - x * sa),
        k * (t.z * s2z),
    ]
}

// ---------------------------------------------------------------------------------------------
// i, j

/// An inverted disc: the angle is π/(r + 1), the radius the polar angle over π.
fn idisc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (s, c) = (PI / (t.sqrt + 1.0)).sin_cos();
    let r = t.atan_yx * (v.w * FRAC_1_PI);
    [r * c, r * s, 0.0]
}

/// A drop of ink at (x, y) with radius `r`: every point is pushed radially away from the drop
/// centre so that the drop's area is inserted (√(d² + r²) − d).
fn inkdrop(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [r, cx, cy] = v.params();
    let dx = t.x - cx;
    let dy = t.y - cy;
    let d2 = dx * dx + dy * dy;
    let push = (d2 + r * r).sqrt() - d2.sqrt();
    let (s, c) = dy.atan2(dx).sin_cos();
    [v.w * (t.x + c * push), v.w * (t.y + s * push), 0.0]
}

/// One interference wave a·wave(b·x + c)^p: sine (|sin|), triangle or square shape.
#[inline(always)]
fn wave(kind: f64, a: f64, b: f64, c: f64, p_: f64, x: f64) -> f64 {
    if kind == 1.0 {
        a * 2.0 * ((b * x + c - FRAC_PI_2).cos().asin().abs() * FRAC_1_PI).powf(p_)
    } else if kind == 2.0 {
        let base = if (b * x + c).sin() < 0.0 {
            f64::EPSILON
        } else {
            1.0
        };
        a * base.powf(p_)
    } else {
        a * (b * x + c).sin().abs().powf(p_)
    }
}

/// The sum of two periodic waves (sine, triangle or square, each with amplitude, frequency,
/// phase and power) applied to each coordinate.
fn interference2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a1, b1, c1, p1, k1, a2, b2, c2, p2, k2] = v.params();
    let x = wave(k1, a1, b1, c1, p1, t.x) + wave(k2, a2, b2, c2, p2, t.x);
    let y = wave(k1, a1, b1, c1, p1, t.y) + wave(k2, a2, b2, c2, p2, t.y);
    [v.w * x, v.w * y, 0.0]
}

/// The Jacobi functions at x (parameter k) and at y (parameter 1 − k), and the common
/// denominator sn²(x)·sn²(y)·k + cn²(y) of the complex-argument addition formulas.
#[inline(always)]
fn jac_parts(t: &VarIn, k: f64) -> ((f64, f64, f64), (f64, f64, f64), f64) {
    let jx = jacobi_elliptic(t.x, k);
    let jy = jacobi_elliptic(t.y, 1.0 - k);
    let den = jx.0 * jx.0 * (jy.0 * jy.0) * k + jy.1 * jy.1;
    (jx, jy, den)
}

/// The Jacobi elliptic function cn of the complex number x + iy.
fn jac_cn(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [m] = v.params();
    let ((snx, cnx, dnx), (sny, cny, dny), den) = jac_parts(t, m);
    let k = v.w / zeps(den);
    [k * (cnx * cny), k * (-dnx * snx * dny * sny), 0.0]
}

/// The Jacobi elliptic function dn of the complex number x + iy.
fn jac_dn(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [m] = v.params();
    let ((snx, cnx, dnx), (sny, cny, dny), den) = jac_parts(t, m);
    let k = v.w / zeps(den);
    [k * (dnx * cny * dny), k * (-cnx * snx * sny * m), 0.0]
}

/// The Jacobi elliptic function sn of the complex number x + iy.
fn jac_sn(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [m] = v.params();
    let ((snx, cnx, dnx), (sny, cny, dny), den) = jac_parts(t, m);
    let k = v.w / zeps(den);
    [k * (snx * dny), k * (cnx * dnx * cny * sny), 0.0]
}

/// julia in 3-D: a random |power|-th root of the point in the plane, z divided by |power| and
/// the whole point scaled by its 3-D length to the power (1/power − 1)/2.
fn julia3d_prepare(v: &mut Prepared) {
    let [n] = v.params();
    v.p.extend_from_slice(&[n.abs(), (1.0 / n - 1.0) / 2.0]);
}

fn julia3d(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n] = v.params();
    let [abs_n, expo] = v.derived();
    let z = t.z / abs_n;
    let r = v.w * (t.sumsq + z * z).powf(expo);
    let k = r * t.sqrt;
    let branch = rng.below(abs_n as u64) as f64;
    let (sa, ca) = ((t.atan_yx + TAU * branch) / n).sin_cos();
    [k * ca, k * sa, r * z]
}

fn julia3dq_prepare(v: &mut Prepared) {
    let [power, divisor] = v.params();
    let inv = divisor / power;
    v.p.extend_from_slice(&[inv, inv.abs(), 0.5 * inv - 0.5, TAU / power]);
}

/// julia3D with a rational power divisor/power and Fractorium's wide random branch choice
/// (any multiple of 2π/power).
fn julia3dq(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [inv, abs_inv, half_inv, step] = v.derived();
    let ang = t.atan_yx * inv + crand(rng) * step;
    let (sa, ca) = ang.sin_cos();
    let z = t.z * abs_inv;
    let r = v.w * (t.sumsq + z * z).powf(half_inv);
    let k = r * t.sqrt;
    [k * ca, k * sa, r * z]
}
