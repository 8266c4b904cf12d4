//! Inversions and their relatives from Fractorium's catalogue: spherical inversions (2-D and
//! 3-D), `loonie` variants, ovoids, Glynn's `GlynnSim` and `glynnia` maps, and the other maps that
//! turn a disc inside out.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_2_PI, FRAC_PI_2, PI, TAU};

use super::util::{cpp_max, signed_pow_or_id, sqr, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("asteria", asteria)
        .params(&[p_cyclic("asteria_alpha", 0.0, 0.0, 1.0)])
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(prep_asteria),
    super::inlined!("curl3D", curl3d)
        .params(&[
            p("curl3D_cx", 0.0),
            p("curl3D_cy", 0.0),
            p("curl3D_cz", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(curl3d_prepare),
    super::inlined!("curl_sp", curl_sp)
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
    super::inlined!("d_spherical", d_spherical)
        .params(&[p("d_spherical_weight", 0.5)])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM),
    super::inlined!("eclipse", eclipse).params(&[p_cyclic("eclipse_shift", 0.0, -2.0, 2.0)]),
    super::inlined!("flipcircle", flipcircle).needs(need::SUMSQ),
    super::inlined!("glynnia", glynnia)
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(glynnia_prepare),
    super::inlined!("glynnia2", glynnia2)
        .needs(need::SQRT)
        .flags(flag::RANDOM)
        .prepare(glynnia2_prepare),
    super::inlined!("GlynnSim1", glynnsim1)
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
    super::inlined!("GlynnSim2", glynnsim2)
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
    super::inlined!("GlynnSim3", glynnsim3)
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
    super::inlined!("GlynnSim4", glynnsim4)
        .params(&[
            p("GlynnSim4_radius", 1.0),
            p_range("GlynnSim4_contrast", 0.5, 0.0, 1.0),
            p("GlynnSim4_pow", 1.5),
            p("GlynnSim4_X", 0.0),
            p("GlynnSim4_Y", 0.0),
        ])
        .needs(need::SQRT)
        .flags(flag::RANDOM),
    super::inlined!("GlynnSim5", glynnsim5)
        .params(&[
            p("GlynnSim5_radius", 1.0),
            p("GlynnSim5_thickness", 0.1),
            p_range("GlynnSim5_contrast", 0.5, 0.0, 1.0),
            p("GlynnSim5_pow", 1.5),
        ])
        .needs(need::SQRT)
        .flags(flag::RANDOM),
    super::inlined!("inkdrop", inkdrop).params(&[
        p_range("inkdrop_r", 0.5, 0.0, INF),
        p("inkdrop_x", 0.0),
        p("inkdrop_y", 0.0),
    ]),
    super::inlined!("loonie2", loonie2)
        .params(&[
            p_int("loonie2_sides", 4.0, 1.0, 50.0),
            p_range("loonie2_star", 0.0, -1.0, 1.0),
            p_range("loonie2_circle", 0.0, -1.0, 1.0),
            p("loonie2_power", 4.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::COMPAT)
        .prepare(prep_loonie2),
    super::inlined!("loonie3", loonie3)
        .needs(need::SUMSQ)
        .prepare(prep_weight_squared),
    super::inlined!("loonie_3D", loonie_3d)
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_weight_squared),
    super::inlined!("ovoid", ovoid)
        .params(&[p("ovoid_x", 1.0), p("ovoid_y", 1.0)])
        .needs(need::SUMSQ),
    super::inlined!("ovoid3d", ovoid3d)
        .params(&[
            p("ovoid3d_x", 1.0),
            p("ovoid3d_y", 1.0),
            p("ovoid3d_z", 1.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("roundspher", roundspher).needs(need::SUMSQ),
    super::inlined!("roundspher3D", roundspher3d)
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::READS_ACC | flag::WRITES_ACC),
    super::inlined!("scry_3D", scry_3d)
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(inv_weight_prep),
    super::inlined!("spher", spher)
        .needs(need::SUMSQ)
        .flags(flag::RANDOM),
    super::inlined!("Spherical3D", spherical3d)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("spherivoid", spherivoid)
        .params(&[p("spherivoid_radius", 0.0)])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("sphyp3D", sphyp3d)
        .params(&[
            p("sphyp3D_stretchX", 1.0),
            p("sphyp3D_stretchY", 1.0),
            p("sphyp3D_stretchZ", 1.0),
            p_int("sphyp3D_zOn", 1.0, 0.0, 1.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("trade", trade)
        .params(&[
            p_range("trade_r1", 1.0, f64::EPSILON, f64::INFINITY),
            p_range("trade_d1", 1.0, 0.0, f64::INFINITY),
            p_range("trade_r2", 1.0, f64::EPSILON, f64::INFINITY),
            p_range("trade_d2", 1.0, 0.0, f64::INFINITY),
        ])
        .prepare(trade_prep),
    super::inlined!("twoface", twoface).needs(need::SUMSQ),
];

/// Derived values: sin πα, cos πα.
fn prep_asteria(v: &mut Prepared) {
    let [alpha] = v.params();
    let (s, c) = (PI * alpha).fsin_cos();
    v.p.push(s);
    v.p.push(c);
}

/// A four-pointed star: points inside the unit disc but outside the four unit discs centred
/// on (±1, ±1) stay (65 % of the time, the other points always move); the others are pushed
/// along a rotated axis onto the star's arms.
#[inline(always)]
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

/// The length of (a, b), signed like a (negative unless a > 0).
#[inline(always)]
fn signed_len(a: f64, b: f64) -> f64 {
    let l = (a * a + b * b).sqrt();
    if a > 0.0 { l } else { -l }
}

fn curl3d_prepare(v: &mut Prepared) {
    let [cx, cy, cz] = v.params();
    v.p.extend_from_slice(&[cx * cx + cy * cy + cz * cz, 2.0 * cx, 2.0 * cy, 2.0 * cz]);
}

/// The 3-D Möbius-like curl: x ↦ (x + c·r²) / (1 + 2c·x + |c|² r²), with y's term reversed.
#[inline(always)]
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
#[inline(always)]
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

/// Randomly either spherical inversion (with probability `d_spherical_weight`) or linear.
#[inline(always)]
fn d_spherical(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [weight] = v.params();
    if rng.f01() < weight {
        let r = v.w / zeps(t.sumsq);
        [t.x * r, t.y * r, 0.0]
    } else {
        [t.x * v.w, t.y * v.w, 0.0]
    }
}

/// Inside the disc of radius `weight`, shifts each horizontal chord by `shift`·weight, mirroring
/// points pushed past the chord's end; outside, linear.
#[inline(always)]
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

/// Mirrors the inside of the circle of radius |weight| top to bottom (y → −y); outside the
/// circle the point is only scaled.
#[inline(always)]
fn flipcircle(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let y = if t.sumsq > v.w * v.w {
        v.w * t.y
    } else {
        -(v.w * t.y)
    };
    [v.w * t.x, y, 0.0]
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
#[inline(always)]
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
#[inline(always)]
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
    v.p.extend_from_slice(&[radius * ang.fcos(), radius * ang.fsin(), pow]);
}

/// A random point of the ring of radius `radius1` (inner fraction `thickness`) around (cx, cy).
#[inline(always)]
fn glynn1_ring(radius1: f64, thickness: f64, cx: f64, cy: f64, rng: &mut FastRng) -> (f64, f64) {
    let r = radius1 * (thickness + (1.0 - thickness) * rng.f01());
    let (s, c) = (TAU * rng.f01()).fsin_cos();
    (r * c + cx, r * s + cy)
}

/// Glynn's "GlynnSim1": points inside the circle of radius `radius` become a small ring centred
/// on that circle at angle `phi1`; outside points are randomly pulled inwards, and those that
/// land in the small ring are replaced by ring points.
#[inline(always)]
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
#[inline(always)]
fn glynnsim2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, thickness, contrast] = v.params();
    let [pow, phi10, gam, delta] = v.derived();
    if t.sqrt < radius {
        let r = radius + thickness - gam * rng.f01();
        let (s, c) = (phi10 + delta * rng.f01()).fsin_cos();
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
#[inline(always)]
fn glynnsim3(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, _, _, contrast, pow] = v.params();
    let [radius1, radius2, gam] = v.derived();
    if t.sqrt < radius1 {
        // Fractorium draws a radius that the circle choice then overrides.
        let _ = rng.f01();
        let (s, c) = (TAU * rng.f01()).fsin_cos();
        let r = if rng.f01() < gam { radius1 } else { radius2 };
        [v.w * (r * c), v.w * (r * s), 0.0]
    } else {
        glynn_scaled(v.w, t, radius, contrast, pow, rng)
    }
}

/// Glynn's "GlynnSim4": points inside the circle collapse onto the point (X, Y); outside points
/// are randomly pulled in.
#[inline(always)]
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
#[inline(always)]
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

/// A drop of ink at (x, y) with radius `r`: every point is pushed radially away from the drop
/// centre so that the drop's area is inserted (√(d² + r²) − d).
#[inline(always)]
fn inkdrop(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [r, cx, cy] = v.params();
    let dx = t.x - cx;
    let dy = t.y - cy;
    let d2 = dx * dx + dy * dy;
    let push = (d2 + r * r).sqrt() - d2.sqrt();
    let (s, c) = dy.atan2(dx).fsin_cos();
    [v.w * (t.x + c * push), v.w * (t.y + s * push), 0.0]
}

/// Derived value shared by the loonies: the squared weight.
fn prep_weight_squared(v: &mut Prepared) {
    let w2 = v.w * v.w;
    v.p.push(w2);
}

fn prep_loonie2(v: &mut Prepared) {
    let [sides, star, circle, power] = v.params();
    let a = TAU / sides;
    let s = -FRAC_PI_2 * star;
    let c = FRAC_PI_2 * circle;
    let alpha = TAU / zeps(power);
    v.p.extend_from_slice(&[
        v.w * v.w,
        a.fsin(),
        a.fcos(),
        s.fsin(),
        s.fcos(),
        c.fsin(),
        c.fcos(),
        alpha,
        (alpha * 0.5).tan() * 2.0,
    ]);
}

/// loonie2: loonie with a polygon/star/circle-shaped hole (compatible mode): points inside the
/// shape of "radius" weight are pushed outwards. With the compatibility switch off: a
/// polygonal inversion that maps the unit disc's inside out onto a `power`-gon.
#[inline(always)]
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
        let stretch = 1.0 / zeps((local * alpha).fcos());
        let ang = (index + dir * local) * alpha - PI;
        let r = w * stretch * rad;
        [r * ang.fcos(), r * ang.fsin(), 0.0]
    }
}

/// loonie3: loonie with a hole bounded by the circle through the origin tangent to the y axis
/// (|r²/x| < weight): points inside are pushed out, the others only scaled.
#[inline(always)]
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
#[inline(always)]
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

/// ovoid: spherical inversion with separate x and y stretches.
#[inline(always)]
fn ovoid(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scale_x, scale_y] = v.params();
    let k = v.w / zeps(t.sumsq);
    [t.x * k * scale_x, t.y * k * scale_y, 0.0]
}

/// ovoid3d: 3-D spherical inversion with separate x, y and z stretches.
#[inline(always)]
fn ovoid3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scale_x, scale_y, scale_z] = v.params();
    let k = v.w / zeps(t.sumsq + t.z * t.z);
    [t.x * k * scale_x, t.y * k * scale_y, t.z * k * scale_z]
}

/// Clamps into [lo, hi], sending NaN to `lo` (Fractorium's clamp for doubles).
#[inline(always)]
fn clamp_nan_low(x: f64, lo: f64, hi: f64) -> f64 {
    if x < lo {
        lo
    } else if x > hi {
        hi
    } else if x.is_nan() {
        lo
    } else {
        x
    }
}

/// An inversion softened near the origin: w²·p / (r²·(1/r² + (2/π)²)), i.e. the spherical
/// map with its blow-up at the centre rounded off.
#[inline(always)]
fn roundspher(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = zeps(t.sumsq);
    let e = 1.0 / r2 + FRAC_2_PI * FRAC_2_PI;
    let k = v.w / r2;
    [v.w * (k * t.x / e), v.w * (k * t.y / e), 0.0]
}

/// The 3-D rounded inversion; a zero z is replaced by cos(r), and the z summed so far (or
/// cos(r) if it is zero) is carried into the output z instead of being added to.
#[inline(always)]
fn roundspher3d(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let other = if v.form == Form::Pre { t.z } else { acc.z };
    let tz = if t.z == 0.0 { t.sqrt.fcos() } else { t.z };
    let pz = if other == 0.0 { t.sqrt.fcos() } else { other };
    if v.form != Form::Pre {
        acc.z = 0.0;
    }
    let d = t.sumsq + tz * tz;
    let e = 1.0 / d + FRAC_2_PI * FRAC_2_PI;
    let k = v.w / d;
    [
        v.w * (k * t.x / e),
        v.w * (k * t.y / e),
        pz + v.w * (k * tz / e),
    ]
}

/// scry in 3-D: p / (|p|·(|p|² + 1/w)); a zero z is replaced by the polar angle.
#[inline(always)]
fn scry_3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [inv_w] = v.derived();
    let d2 = t.sumsq + t.z * t.z;
    let r = 1.0 / zeps(d2.sqrt() * (d2 + inv_w));
    let z = if t.z == 0.0 { t.atan_yx } else { t.z };
    [t.x * r, t.y * r, z * r]
}

fn inv_weight_prep(v: &mut Prepared) {
    let iw = 1.0 / zeps(v.w);
    v.p.push(iw);
}

/// Outside the unit circle, randomly either the spherical inversion p/r² or the identity;
/// inside it, the origin.
#[inline(always)]
fn spher(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let r2 = zeps(t.sumsq);
    if r2 > 1.0 {
        let k = if rng.f01() < 0.5 { v.w / r2 } else { v.w };
        [k * t.x, k * t.y, 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// Spherical inversion in 3-D: p / |p|².
#[inline(always)]
fn spherical3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let k = v.w / zeps(t.sumsq + t.z * t.z);
    [k * t.x, k * t.y, k * t.z]
}

/// Pushes every point of 3-D space `radius` further from the origin (along its direction),
/// hollowing out a spherical void.
#[inline(always)]
fn spherivoid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [radius] = v.params();
    let zr = (t.z * t.z + t.sqrt * t.sqrt).sqrt();
    let phi = clamp_nan_low(t.z / zr, -1.0, 1.0).acos();
    let (ps, pc) = phi.fsin_cos();
    let grow = zr + radius;
    [
        v.w * t.ux * ps * grow,
        v.w * t.uy * ps * grow,
        v.w * pc * grow,
    ]
}

/// A 3-D spherical inversion with a separate power of |p|² per axis; z only when `zOn` is 1
/// (otherwise 0).
#[inline(always)]
fn sphyp3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [stretch_x, stretch_y, stretch_z, z_on] = v.params();
    let d = zeps(t.sumsq + t.z * t.z);
    let z = if z_on == 1.0 {
        t.z * (v.w / d.powf(stretch_z))
    } else {
        0.0
    };
    [
        t.x * (v.w / d.powf(stretch_x)),
        t.y * (v.w / d.powf(stretch_y)),
        z,
    ]
}

/// Derived values of trade: the two disc centres' distances from the origin.
fn trade_prep(v: &mut Prepared) {
    let [r1, d1, r2, d2] = v.params();
    v.p.extend_from_slice(&[r1 + d1, r2 + d2]);
}

/// trade: swaps two discs — points inside the disc right of the y axis (radius r1) move,
/// rescaled and mirrored, into the disc left of it (radius r2), and vice versa.
#[inline(always)]
fn trade(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [r1, _, r2] = v.params();
    let [c1, c2] = v.derived();
    let w = v.w;
    if t.x > 0.0 {
        let dx = c1 - t.x;
        let mut r = (sqr(dx) + sqr(t.y)).sqrt();
        if r <= r1 {
            r *= r2 / r1;
            let a = t.y.atan2(dx);
            return [w * (r * a.fcos() - c2), w * r * a.fsin(), 0.0];
        }
    } else {
        let dx = -c2 - t.x;
        let mut r = (sqr(dx) + sqr(t.y)).sqrt();
        if r <= r2 {
            r *= r1 / r2;
            let a = t.y.atan2(dx);
            return [w * (r * a.fcos() + c1), w * r * a.fsin(), 0.0];
        }
    }
    [w * t.x, w * t.y, 0.0]
}

/// twoface: the right half-plane inverted (divided by r²), the left half passed through.
#[inline(always)]
fn twoface(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let mut r = v.w;
    if t.x > 0.0 {
        r /= t.sumsq;
    }
    [r * t.x, r * t.y, 0.0]
}
