//! JWildfire's drawings of many figures (the variations built on its `DrawFunc`): a list of
//! figures made once from the parameters, of which each call draws one at random and returns
//! a random point of it, with the figure's colour. The figures are filled regular polygons
//! (sampled as FractalDesire's nBlur samples them, optionally with a hole of `fill` times
//! their size). Here: `sunflower` (Vogel's sunflower of polygons shrinking outwards).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew. Random numbers are drawn in
//! the order JWildfire draws them.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("sunflower", sunflower)
    .params(&[
        p_int("sunflower_nPoints", 500.0, 10.0, 1000.0),
        p_int("sunflower_shape", 10.0, 3.0, 20.0),
        p_range("sunflower_scale", 0.02, 0.0, 100.0),
        p_range("sunflower_angle", 180.0, 0.0, 360.0),
        p_range("sunflower_color", 0.0, 0.0, 1.0),
        p_range("sunflower_F. filling", 0.0, 0.0, 1.0),
        p_int("sunflower_invert", 0.0, 0.0, 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
    .prepare(sunflower_prepare)];

/// The values one polygon takes in a figure table.
const NGON: usize = 8;

/// Appends a filled regular polygon of `sides` sides to a figure table: its size, turn
/// (degrees), centre, colour and hole.
fn push_ngon(
    table: &mut Vec<f64>,
    sides: f64,
    scale: f64,
    angle: f64,
    (x, y): (f64, f64),
    color: f64,
    fill: f64,
) {
    let a = angle * PI / 180.0;
    table.extend_from_slice(&[sides, scale, a.cos(), a.sin(), x, y, color, fill]);
}

/// Java's `random(n)`: ⌊draw·n⌋, at most n − 1.
pub(super) fn java_below(rng: &mut FastRng, n: i32) -> i32 {
    ((rng.f01() * f64::from(n)) as i32).min(n - 1)
}

/// A random point of the regular polygon of `sides` sides of radius 1 about the origin, with
/// a hole of `hole` times its size (FractalDesire's nBlur: a corner chosen at random, an angle
/// within it bunched towards the middle, a radius up to the edge).
pub(super) fn nblur_point(rng: &mut FastRng, sides: i32, hole: f64) -> (f64, f64) {
    let n = sides.max(3);
    let mid = TAU / f64::from(n);
    let tan90_m_2 = (FRAC_PI_2 + mid / 2.0).tan();
    let arc1 = 13.0 / f64::from(n).powf(1.3);
    let arc2 = 2.0 * (arc1 / -2.0).atan();
    let pick = (arc1 * (rng.f01() - 0.5)).atan() / arc2 + 0.5;
    let mut ang = (pick + f64::from(java_below(rng, 32767) % n)) * mid;
    let (x, y) = (ang.sin(), ang.cos());
    for _ in 0..=n {
        if ang <= mid {
            break;
        }
        ang -= mid;
    }
    let xt = tan90_m_2 / (tan90_m_2 - ang.tan());
    let yt = xt * ang.tan();
    let outer = (xt * xt + yt * yt).sqrt();
    // JWildfire draws a radius it then replaces.
    rng.f01();
    let inner = hole * outer;
    let r = inner + rng.f01().sqrt() * (outer - inner);
    let (x, y) = (x * r, y * r);
    let (s, c) = (mid / 2.0).sin_cos();
    (c * x - s * y, s * x + c * y)
}

/// One random figure of table `table` (values `NGON` apart) and a random point of it, placed
/// and coloured: (x, y, colour).
fn draw_figure(table: &[f64], rng: &mut FastRng) -> Option<(f64, f64, f64)> {
    let count = table.len() / NGON;
    if count == 0 {
        return None;
    }
    let i = ((rng.f01() * count as f64) as usize).min(count - 1);
    let [sides, scale, cosa, sina, px, py, color, fill] =
        table[i * NGON..(i + 1) * NGON].try_into().ok()?;
    let (x, y) = nblur_point(rng, sides as i32, fill);
    Some((
        x * scale * cosa + y * scale * sina + px,
        -x * scale * sina + y * scale * cosa + py,
        color,
    ))
}

/// sunflower's figures: `nPoints` polygons on Vogel's spiral (turning by `angle`·(3 − √5)
/// degrees), each of size `scale`·(1 − r/rmax) (r/rmax with `invert`) and coloured so.
fn sunflower_prepare(v: &mut Prepared) {
    let [n, shape, scale, angle, _, fill, invert] = v.params();
    let ang = angle * (3.0 - 5f64.sqrt());
    let rmax = (n + 1.0).sqrt() / 30.0;
    for i in 1..=n as i32 {
        let r = f64::from(i).sqrt() / 30.0;
        let t = f64::from(i) * ang * PI / 180.0;
        let (x, y) = (r * t.cos() / rmax, r * t.sin() / rmax);
        let sc = if invert == 1.0 {
            r / rmax
        } else {
            1.0 - r / rmax
        };
        push_ngon(&mut v.p, shape, scale * sc, 0.0, (x, y), sc, fill);
    }
}

/// sunflower: a random point of a random polygon of the sunflower.
fn sunflower(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    match draw_figure(v.table(0), rng) {
        Some((x, y, color)) => {
            acc.color = color;
            [v.w * x, v.w * y, 0.0]
        }
        None => [0.0; 3],
    }
}
