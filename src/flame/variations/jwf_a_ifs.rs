//! JWildfire's small iterated function systems in one variation, each call applying one of a
//! few maps chosen at random (after Roger Bagula's and Paul Bourke's examples): `dustpoint`,
//! `threepoint_js`, `hadamard_js`, `lace_js`, `apollony`, `apocarpet_js`, `siercarpet_js`,
//! `sattractor_js`; and the random-sign or random-angle maps `bubble_wf` and `circular`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew, with its random draws in its order.

use std::f64::consts::{PI, SQRT_2};

use super::*;

/// Flags of a random choice between maps of the plane.
const IFS: u32 = flag::JWILDFIRE | flag::RANDOM;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("bubble_wf", bubble_wf).flags(IFS | flag::WRITES_Z),
    VarDef::new("dustpoint", dustpoint).flags(IFS),
    VarDef::new("threepoint_js", threepoint_js).flags(IFS),
    VarDef::new("hadamard_js", hadamard_js).flags(IFS),
    VarDef::new("lace_js", lace_js).flags(IFS),
    VarDef::new("circular", circular)
        .params(&[p("circular_angle", 90.0), p("circular_seed", 0.0)])
        .flags(IFS),
    VarDef::new("apollony", apollony).flags(IFS),
    VarDef::new("apocarpet_js", apocarpet_js).flags(IFS),
    VarDef::new("siercarpet_js", siercarpet_js)
        .params(&[p("siercarpet_js_m", 3.0)])
        .flags(IFS),
    VarDef::new("sattractor_js", sattractor_js)
        .params(&[p("sattractor_js_m", 10.0)])
        .flags(IFS),
];

/// bubble_wf: the bubble (inverse stereographic projection) with the sphere's lower or upper
/// half chosen at random.
fn bubble_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let r = (t.x * t.x + t.y * t.y) / 4.0 + 1.0;
    let k = v.w / r;
    let z = v.w * (2.0 / r - 1.0);
    let z = if rng.f01() < 0.5 { -z } else { z };
    [k * t.x, k * t.y, z]
}

/// dustpoint: with odds ½ the unit direction shifted left (y mirrored at random), else one of
/// two thirds-scalings.
fn dustpoint(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let s = if rng.f01() < 0.5 { 1.0 } else { -1.0 };
    let r = (t.x * t.x + t.y * t.y).sqrt();
    let w = rng.f01();
    let (x, y) = if w < 0.5 {
        (t.x / r - 1.0, s * t.y / r)
    } else if w < 0.75 {
        (t.x / 3.0, t.y / 3.0)
    } else {
        (t.x / 3.0 + 2.0 / 3.0, t.y / 3.0)
    };
    [x * v.w, y * v.w, 0.0]
}

/// threepoint_js: one of three affine maps (odds 0.333, then 0.666 of the rest).
fn threepoint_js(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = if rng.f01() < 0.333 {
        (t.x / 2.0 - t.y / 2.0 + 0.5, -t.x / 2.0 - t.y / 2.0 + 0.5)
    } else if rng.f01() < 0.666 {
        (t.y, t.x)
    } else {
        (-t.y / 2.0 + 0.5, -t.x / 2.0 + 0.5)
    };
    [x * v.w, y * v.w, 0.0]
}

/// hadamard_js: one of three half-scale maps (a scaling and two rotations by ±90° with a
/// shift).
fn hadamard_js(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = if rng.f01() < 0.333 {
        (t.x / 2.0, t.y / 2.0)
    } else if rng.f01() < 0.666 {
        (t.y / 2.0, -t.x / 2.0 - 0.5)
    } else {
        (-t.y / 2.0 - 0.5, t.x / 2.0)
    };
    [x * v.w, y * v.w, 0.0]
}

/// lace_js: Paul Bourke's lace: the point's distance halved and turned to face one of three
/// centres of a triangle (or the origin), chosen at random.
fn lace_js(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let r0 = (t.x * t.x + t.y * t.y).sqrt();
    let h = 3.0_f64.sqrt() / 2.0;
    let weight = rng.f01();
    let (w, cx, cy) = if weight > 0.75 {
        (t.y.atan2(t.x - 1.0), 0.0, 1.0)
    } else if weight > 0.5 {
        ((t.y - h).atan2(t.x + 0.5), h, -0.5)
    } else if weight > 0.25 {
        ((t.y + h).atan2(t.x + 0.5), -h, -0.5)
    } else {
        (t.y.atan2(t.x), 0.0, 0.0)
    };
    let x = -r0 * w.sin() / 2.0 + cx;
    let y = -r0 * w.cos() / 2.0 + cy;
    [x * v.w, y * v.w, 0.0]
}

/// circular (Tatyana Zabanova): rotates the point by a random angle within ±`angle` degrees,
/// offset by a hash of the point.
fn circular(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [angle, seed] = v.params();
    let ca = angle * PI / 180.0;
    let aux = (t.x * 12.9898 + t.y * 78.233 + seed).sin() * 43758.5453;
    // Java's `aux - (int) aux`: the fraction with the sign of aux.
    let aux = aux - aux.trunc();
    let rnd = (2.0 * (rng.f01() + aux) - 2.0) * ca;
    let rad = (t.x * t.x + t.y * t.y).sqrt();
    let ang = t.y.atan2(t.x) + rnd;
    [v.w * ang.cos() * rad, v.w * ang.sin() * rad, 0.0]
}

/// apollony: the three maps of Apollonius' gasket (an inversion and its two rotations by
/// ±120°), picked with odds 2:1:1.
fn apollony(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let r = 3.0_f64.sqrt();
    let d = (1.0 + r - t.x).powi(2) + t.y * t.y;
    let a0 = 3.0 * (1.0 + r - t.x) / d - (1.0 + r) / (2.0 + r);
    let b0 = 3.0 * t.y / d;
    let m = a0 * a0 + b0 * b0;
    let (f1x, f1y) = (a0 / m, -b0 / m);
    let w = (4.0 * rng.f01()) as i32;
    let (x, y) = match w % 3 {
        0 => (a0, b0),
        1 => (-f1x / 2.0 - f1y * r / 2.0, f1x * r / 2.0 - f1y / 2.0),
        _ => (-f1x / 2.0 + f1y * r / 2.0, -f1x * r / 2.0 - f1y / 2.0),
    };
    [x * v.w, y * v.w, 0.0]
}

/// apocarpet_js: Roger Bagula's Apollonian carpet: one of six maps (two inversions, four
/// corner scalings by 1/(1 + √2)).
fn apocarpet_js(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let r = 1.0 / (1.0 + SQRT_2);
    let denom = t.x * t.x + t.y * t.y;
    let (x, y) = match (6.0 * rng.f01()) as i32 {
        0 => (2.0 * t.x * t.y / denom, (t.x * t.x - t.y * t.y) / denom),
        1 => (t.x * r - r, t.y * r - r),
        2 => (t.x * r + r, t.y * r + r),
        3 => (t.x * r + r, t.y * r - r),
        4 => (t.x * r - r, t.y * r + r),
        _ => ((t.x * t.x - t.y * t.y) / denom, 2.0 * t.x * t.y / denom),
    };
    [x * v.w, y * v.w, 0.0]
}

/// siercarpet_js: Roger Bagula's cross carpet: the point scaled by 1/3 and moved towards one
/// of the m vertices or edge midpoints of a regular m-gon (rotated by 45°), at random.
fn siercarpet_js(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [m] = v.params();
    let m = (m as i32).clamp(3, 12);
    let mf = m as f64;
    let l = 1 + (2.0 * mf * rng.f01()) as i32;
    let i = (l + 1) / 2;
    let ang = |k: i32| 2.0 * PI * k as f64 / mf;
    let (a, b) = if l % 2 == 1 {
        (ang(i).cos(), ang(i).sin())
    } else {
        (
            (ang(i).cos() + ang(i - 1).cos()) / 2.0,
            (ang(i).sin() + ang(i - 1).sin()) / 2.0,
        )
    };
    let x = t.x / 3.0 + (a - b) / SQRT_2;
    let y = t.y / 3.0 + (a + b) / SQRT_2;
    [x * v.w, y * v.w, 0.0]
}

/// sattractor_js: Roger Bagula's Hénon-like attractor: towards one of m points on the unit
/// circle, by a half-scaling or a quadratic map, both halved, at random.
fn sattractor_js(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [m] = v.params();
    let m = (m as i32).clamp(2, 12) as f64;
    let l = ((rng.f01() * m) as i32 + 1) as f64;
    let (b, a) = (2.0 * PI * l / m).sin_cos();
    let (x, y) = if rng.f01() < 0.5 {
        (t.x / 2.0 + a, t.y / 2.0 + b)
    } else {
        (
            t.x * a + t.y * b + t.x * t.x * b,
            t.y * a - t.x * b + t.x * t.x * a,
        )
    };
    [x / 2.0 * v.w, y / 2.0 * v.w, 0.0]
}
