//! JWildfire's `flora`: 25 leaves and flowers drawn as polar curves of the input's angle
//! (ginkgo, cannabis, clover, rose, daisy, butterfly, oak, teardrop, lotus, sycamore, ash,
//! monstera, star anise, holly, sweetgum, grape, castor bean, hosta, alocasia, dandelion,
//! columbine, birch, tulip, linden and a fiddlehead spiral), each shaped by `shapeMod`,
//! filled towards the centre at random and waved by `distort`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("flora", flora)
    .params(&[
        p_int("flora_leafType", 0.0, 0.0, 24.0),
        p_range("flora_filled", 1.0, 0.0, 1.0),
        p("flora_scale", 1.0),
        p("flora_distort", 0.1),
        p("flora_shapeMod", 0.5),
    ])
    .needs(need::ATAN_YX)
    .flags(flag::JWILDFIRE | flag::RANDOM)];

/// The point (r·cos t, r·sin t).
fn polar(r: f64, t: f64) -> (f64, f64) {
    (r * t.cos(), r * t.sin())
}

/// The point (r·sin t, −r·cos t): the curve turned a quarter back.
fn upright(r: f64, t: f64) -> (f64, f64) {
    (r * t.sin(), -r * t.cos())
}

/// Leaves 0–12 at the angle `a` (atan2(y, x)), shaped by `m`.
fn leaf_a(kind: i64, a: f64, m: f64) -> (f64, f64) {
    let t = a + FRAC_PI_2;
    match kind {
        0 => {
            let r = if t.sin() > 0.0 {
                (1.0 - m * 0.8 * t.cos().powf(50.0)) * (1.0 + 0.05 * (8.0 * t).cos())
            } else {
                0.0
            };
            polar(r, t)
        }
        1 => {
            let r = (1.0 + (0.5 + m * 0.8) * (8.0 * t).cos())
                * (1.0 + 0.1 * (24.0 * t).cos())
                * (0.9 + 0.05 * (200.0 * t).cos())
                * (1.0 + t.sin());
            upright(r, t)
        }
        2 => {
            let cleft = 0.5 + (-6.0 * m + 0.5) * 0.5;
            let t = a + FRAC_PI_4;
            let r = (1.0 + 0.8 * (4.0 * t).cos()) * (1.0 - cleft * (4.0 * t).sin().powf(2.0));
            polar(r, t)
        }
        3 => {
            let r = t.sin().max(0.0) * (1.0 + m * 0.1 * (40.0 * t).cos());
            (r * t.cos() * 0.7, r * t.sin())
        }
        4 => polar(0.6 * (1.2 + ((8.0 + m * 16.0) * t).cos()), t),
        5 => {
            let r = (t.cos().exp() - 2.0 * (4.0 * t).cos() + (t / 12.0).sin().powf(5.0))
                * (0.7 + m * 0.6);
            upright(r, t)
        }
        6 => upright(
            (1.0 + 0.8 * t.sin()) * (1.0 + (0.1 + m * 0.2) * (14.0 * t).cos()),
            t,
        ),
        7 => {
            let r = (1.0 - 0.9 * t.sin()) * (1.0 + 0.02 * (60.0 * t).cos());
            (r * t.cos() * (0.6 + m * 0.4), r * t.sin())
        }
        8 => {
            let r = 1.0 + 0.05 * (12.0 * a).cos();
            (r * a.cos(), r * a.sin() + (0.1 + m * 0.4) * (1.0 - r))
        }
        9 => {
            let r = (1.0 - 0.5 * t.sin())
                * (1.0 + (0.1 + m * 0.4) * (5.0 * t).cos())
                * (1.0 + 0.05 * (25.0 * t).cos());
            upright(r, t)
        }
        10 => {
            let r = if t.sin() > 0.0 {
                t.sin() * (1.0 + (0.05 + m * 0.3) * (30.0 * t).cos())
            } else {
                0.0
            };
            (r * t.cos() * 0.6, r * t.sin())
        }
        11 => {
            let base = (1.0 - 0.9 * t.sin()).max(0.0);
            let holes = (1.0 - m * 0.8 * (t * 2.5).sin().powf(10.0))
                * (1.0 - m * 0.7 * (t * 3.5).cos().powf(10.0));
            polar(base * holes, t)
        }
        _ => polar(1.0 + (0.2 + m * 0.4) * (8.0 * t).cos(), t),
    }
}

/// Leaves 13–24 at the angle `a` (atan2(y, x)), shaped by `m`.
fn leaf_b(kind: i64, a: f64, m: f64) -> (f64, f64) {
    let t = a + FRAC_PI_2;
    match kind {
        13 => {
            let r = 1.0 - (0.15 + m * 0.2) * (t * 10.0 / 2.0).sin().abs();
            (r * t.cos() * 0.7, r * t.sin())
        }
        14 => {
            let r = (1.0 - (0.3 + m * 0.4) * (t * 5.0 / 2.0).sin().abs())
                * (1.0 + 0.04 * (40.0 * t).cos());
            polar(r, t)
        }
        15 => {
            let depth = 0.1 + m * 0.2;
            let base = 1.0 + depth * (3.0 * t).cos() - depth * 0.5 * (5.0 * t).cos();
            polar(
                base * (1.0 + 0.03 * (20.0 * t).cos() + 0.02 * (35.0 * t).cos()),
                t,
            )
        }
        16 => {
            let r = (1.0 + (0.3 + m * 0.5) * (7.0 * t).cos()) * (1.0 + 0.05 * (42.0 * t).cos());
            polar(r, t)
        }
        17 => {
            let r = (1.0 - 0.9 * t.sin()) * (1.0 + (0.02 + m * 0.05) * (10.0 * t).sin());
            (r * t.cos() * 1.2, r * t.sin())
        }
        18 => {
            let r = (1.0 - a.sin())
                * (1.0 - (0.1 + m * 0.4) * a.cos().powf(2.0))
                * (1.0 + 0.03 * (15.0 * a).sin());
            (r * a.cos() * 0.7, r * a.sin())
        }
        19 => polar(0.8 * (1.1 + ((20.0 + m * 40.0) * t).cos() * 0.3), t),
        20 => polar(
            1.0 + t.sin() + (0.2 + m * 0.6) * (5.0 * t - FRAC_PI_2).sin(),
            t,
        ),
        21 => {
            let r = (1.0 - 0.9 * a.sin())
                * (1.0 + 0.05 * (20.0 * a).cos())
                * (1.0 + (0.02 + m * 0.03) * (40.0 * a).cos());
            (r * a.cos() * 0.8, r * a.sin())
        }
        22 => {
            let r = t.cos().abs().powf(0.3) + t.sin().abs().powf(2.0 + m * 2.0);
            (r * t.sin(), -r * t.cos() * 0.6)
        }
        23 => {
            let r = 1.0 - 0.9 * (t + (m - 0.5) * 0.2).sin();
            (r * t.sin() * 1.1, -r * t.cos())
        }
        _ => {
            let t = a * (2.0 + m * 4.0) * PI;
            polar(0.05 * t, t)
        }
    }
}

/// flora: the leaf or flower `leafType` at the input's angle, filled towards the centre with
/// odds `filled`, its outline waved by distort·(sin 5y, cos 5x), scaled by `scale`.
fn flora(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [kind, filled, scale, distort, m] = v.params();
    let r = if filled > 0.0 && filled > rng.f01() {
        v.w * rng.f01()
    } else {
        v.w
    };
    let kind = kind as i64;
    let (mut lx, mut ly) = if kind <= 12 {
        leaf_a(kind, t.atan_yx, m)
    } else {
        leaf_b(kind, t.atan_yx, m)
    };
    if distort != 0.0 {
        lx += distort * (t.y * 5.0).sin();
        ly += distort * (t.x * 5.0).cos();
    }
    [r * lx * scale, r * ly * scale, 0.0]
}
