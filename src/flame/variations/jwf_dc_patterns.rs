//! JWildfire's pattern direct-colour stamps (Jesus Sosa's shader ports): `dc_sunflower`
//! (a phyllotaxis grid of dots and lines in polar coordinates), `dc_hexagons` (pulsing
//! hexagons, scattered over a square or a disc), `dc_fingerprint` (ridges winding around 50
//! hashed singular points) and `dc_quadtree` (cells split at random into four, brighter with
//! depth).
//!
//! Each colours its points through `jwf_direct_colour`'s common part. The formulas follow
//! JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics, written anew.

use std::f64::consts::TAU;

use super::jwf_a_dc::rot;
use super::jwf_dc_maths::{length2, step};
use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail, gmod};
use super::util::jwf_math as jm;
use super::util::{atan2_approx, fract, signum_java, smoothstep};
use super::*;

const SUNFLOWER_TAIL: [Param; 5] = dc_tail!("dc_sunflower");
const HEXAGONS_TAIL: [Param; 5] = dc_tail!("dc_hexagons");
const FINGERPRINT_TAIL: [Param; 5] = dc_tail!("dc_fingerprint");
const QUADTREE_TAIL: [Param; 5] = dc_tail!("dc_quadtree");

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("dc_sunflower", dc_sunflower)
        .params(&[
            p_range("dc_sunflower_zoom", 7.0, 0.1, 50.0),
            p_range("dc_sunflower_step", 0.1, -1.0, 1.0),
            p_int("dc_sunflower_N", 30.0, NEG_INF, INF),
            p_int("dc_sunflower_Polar", 1.0, 0.0, 1.0),
            p_int("dc_sunflower_Dots", 1.0, 0.0, 1.0),
            p_int("dc_sunflower_GridX", 1.0, 0.0, 1.0),
            p_int("dc_sunflower_GridY", 1.0, 0.0, 1.0),
            SUNFLOWER_TAIL[0],
            SUNFLOWER_TAIL[1],
            SUNFLOWER_TAIL[2],
            SUNFLOWER_TAIL[3],
            SUNFLOWER_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_hexagons", dc_hexagons)
        .params(&[
            p_int("dc_hexagons_shape", 0.0, 0.0, 1.0),
            p_int("dc_hexagons_seed", 10000.0, NEG_INF, INF),
            p("dc_hexagons_time", 0.0),
            p("dc_hexagons_zoom", 4.0),
            HEXAGONS_TAIL[0],
            HEXAGONS_TAIL[1],
            HEXAGONS_TAIL[2],
            HEXAGONS_TAIL[3],
            HEXAGONS_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_fingerprint", dc_fingerprint)
        .params(&[
            p_range("dc_fingerprint_zoom", 50.0, 1.0, 100.0),
            p_int("dc_fingerprint_seed", 10000.0, 0.0, 10000.0),
            p("dc_fingerprint_time", 0.0),
            p_range("dc_fingerprint_width", 0.8, 0.0, 1.0),
            FINGERPRINT_TAIL[0],
            FINGERPRINT_TAIL[1],
            FINGERPRINT_TAIL[2],
            FINGERPRINT_TAIL[3],
            FINGERPRINT_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_quadtree", dc_quadtree)
        .params(&[
            p_range("dc_quadtree_zoom", 1.0, 0.1, 50.0),
            p_int("dc_quadtree_seed", 10000.0, 0.0, 10000.0),
            p("dc_quadtree_time", 0.0),
            p_range("dc_quadtree_width", 1000.0, 100.0, 1000.0),
            p_int("dc_quadtree_levels", 30.0, 1.0, 50.0).limited(),
            QUADTREE_TAIL[0],
            QUADTREE_TAIL[1],
            QUADTREE_TAIL[2],
            QUADTREE_TAIL[3],
            QUADTREE_TAIL[4],
        ])
        .flags(DC_FLAGS),
];

/// The sunflower shader's 2π to 3 digits (kept).
#[allow(clippy::approx_constant)]
const SUNFLOWER_TAU: f64 = 6.28;

/// Distance from p to the segment a–b.
fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (px, py) = (p.0 - a.0, p.1 - a.1);
    let (bx, by) = (b.0 - a.0, b.1 - a.1);
    let h = ((px * bx + py * by) / (bx * bx + by * by)).clamp(0.0, 1.0);
    length2(px - bx * h, py - by * h)
}

/// Distance from u to the segment ±(x, y) about u's nearest lattice point.
fn lattice_segment(u: (f64, f64), x: f64, y: f64) -> f64 {
    let (cx, cy) = ((u.0 + 0.5).floor(), (u.1 + 0.5).floor());
    segment_distance(u, (cx - x, cy - y), (cx + x, cy + y))
}

/// dc_sunflower: the zoomed plane in polar coordinates (angle/2π, radius)·N, rows shifted
/// by `step`, drawn as grid lines (red along x, green along y, blue between when neither),
/// circles (Polar) and dots (Dots), all soft.
fn dc_sunflower(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, r, n, polar, dots, grid_x, grid_y, tail @ ..] = v.params::<12>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let soft = |d: f64, w: f64| smoothstep(w, 0.0, d);
        let (ux, uy) = (x * zoom, y * zoom);
        let l = length2(ux, uy);
        let jx = l * SUNFLOWER_TAU;
        let mut u = (atan2_approx(uy, ux) / SUNFLOWER_TAU * n, l * n);
        let w = 0.1;
        u.0 += r * (u.1 + 0.5).floor();
        let mut o = [0.0; 3];
        let sign_r = |k: f64| if r < 0.0 { -k } else { k };
        if grid_x as i64 == 1 {
            o[0] = soft(lattice_segment(u, sign_r(1.0) - r, 1.0), w);
        }
        if grid_y as i64 == 1 {
            o[1] = soft(lattice_segment(u, -r, 1.0), w);
        }
        if grid_x as i64 == 0 && grid_y as i64 == 0 {
            o[2] = soft(lattice_segment(u, sign_r(0.5) - r, 1.0), w);
            u.0 += 0.5;
            o[2] += soft(lattice_segment(u, sign_r(0.5) - r, 1.0), w);
            u.0 -= 0.5;
        }
        if polar as i64 == 1 {
            let c = 0.5 * soft(lattice_segment(u, 1.0, 0.0), w);
            o = o.map(|k| k + c);
        }
        if dots as i64 == 1 {
            let (dx, dy) = (fract(u.0 + 0.5) - 0.5, fract(u.1 + 0.5) - 0.5);
            let c = soft(length2(dx * jx, dy) - 0.3, n * 2.0 / 2000.0);
            o = o.map(|k| k + c);
        }
        o
    })
}

/// The hexagonal grid's distance field at p (0 on the cell edges).
fn hex_field(px: f64, py: f64) -> f64 {
    let px = px * (0.57735 * 2.0);
    let py = py + gmod(px.floor(), 2.0) * 0.5;
    let (qx, qy) = ((gmod(px, 1.0) - 0.5).abs(), (gmod(py, 1.0) - 0.5).abs());
    ((qx * 1.5 + qy).max(qy * 2.0) - 1.0).abs()
}

/// dc_hexagons: hexagon outlines whose width pulses outwards from the centre with time, the
/// grid turned by a time-driven angle; the points scattered over [−1, 1]² (shape 0) or a
/// disc of radius 1 with a tent-shaped radial density (1).
fn dc_hexagons(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [shape, _, time, zoom, tail @ ..] = v.params::<9>();
    let pattern = |x: f64, y: f64| {
        let (px, py) = (x * zoom, y * zoom);
        let s = ((px * px + py * py) / -64.0 + time * 4.0).sin();
        let s = s.abs().powf(0.5) * signum_java(s);
        let r = 0.35 + 0.25 * s;
        let st = (time * 4.0).sin();
        let turn = st.abs().powf(0.2) * signum_java(st) * 10.25;
        let (px, py) = rot(px, py, -turn);
        [smoothstep(r - 0.1, r + 0.1, hex_field(px, py)); 3]
    };
    if shape as i64 == 1 && tail[0] as i64 != 1 {
        let r = 2.0 * rng.f01() + 2.0 * rng.f01();
        let r = if r > 2.0 { 4.0 - r } else { r };
        let (s, c) = (rng.f01() * TAU).sin_cos();
        let disc = VarIn {
            x: 0.5 * r * s,
            y: 0.5 * r * c,
            ..*t
        };
        let mut tail = tail;
        tail[0] = 1.0;
        return dc_common(v, tail, &disc, acc, rng, 1.0, pattern);
    }
    dc_common(v, tail, t, acc, rng, 1.0, pattern)
}

/// The fingerprint's hash of p into [−1, 1]², with JWildfire's table sine: the 50 chained
/// hashes turn its last bits into different points.
fn fingerprint_hash(x: f64, y: f64) -> (f64, f64) {
    let a = x * 63.31 + y * 127.63;
    let b = x * 395.467 + y * 213.799;
    (
        fract(jm::sin(a) * 43141.59265) * 2.0 - 1.0,
        fract(jm::sin(b) * 43141.59265) * 2.0 - 1.0,
    )
}

/// dc_fingerprint: rings about a shifted centre, wound by the angles to 50 hashed points
/// (alternately with the sign of the previous one), cut into ridges of pressure `width`
/// that fade outside an ellipse.
fn dc_fingerprint(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, _, time, width, tail @ ..] = v.params::<9>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let (mut ux, mut uy) = (x * zoom, y * zoom);
        let (ex, ey) = (ux * 0.7, uy * 0.5);
        let bounds = smoothstep(9.0, 10.0, jm::sqrt(ex * ex + ey * ey));
        let mut a = 0.0;
        let mut h = ((7.0 * time).floor(), 0.0);
        for _ in 0..50 {
            let s = signum_java(h.0);
            let (hx, hy) = fingerprint_hash(h.0, h.1);
            h = (hx * 15.0, hy * 20.0);
            a += s * atan2_approx(ux - h.0, uy - h.1);
        }
        let (hx, hy) = fingerprint_hash(h.0, h.1);
        ux += hx.abs();
        uy += hy.abs();
        a += atan2_approx(uy, ux);
        let p = (1.0 - bounds) * width;
        let s = p.min(0.3);
        let l = jm::sqrt(ux * ux + uy * uy) + 0.319 * a;
        let m = gmod(l, 2.0);
        let c = (1.0 - smoothstep(2.0 - s, 2.0, m)) * smoothstep(p, p + s, m);
        [c, c, c]
    })
}

/// dc_quadtree: the unit square (the point divided by zoom, shifted by ½) split into
/// quarters down to `levels` levels while a time-driven hash of the cell allows; each level
/// adds 0.13 to the grey, a cell border (thinner than 0.3/width of the cell) subtracts 1.
fn dc_quadtree(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, _, time, width, levels, tail @ ..] = v.params::<10>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let rnd = |p: f64| {
            0.5 + 0.5 * (p + time).sin() * (p * 2.17 - time).sin() * (p * 5.7 + time).sin()
        };
        let (mut r, mut id) = (1.0, 1.0);
        let (mut ux, mut uy) = (x / zoom + 0.5, y / zoom + 0.5);
        // The shader's dark blue background is lost in JWildfire (it sets a colour alias
        // of the vector that its arithmetic does not carry), so the levels start from black.
        let mut o = [0.0; 3];
        for _ in 0..levels as i64 {
            let (fx, fy) = (ux.min(1.0 - ux), uy.min(1.0 - uy));
            if fx.min(fy) < 0.3 * r / width {
                o = o.map(|k| k - 1.0);
                break;
            }
            if rnd(id) > 0.7 {
                break;
            }
            let (sx, sy) = (step(0.5, ux), step(0.5, uy));
            id = 4.0 * id + 2.0 * sy + sx;
            ux = ux * 2.0 - sx;
            uy = uy * 2.0 - sy;
            r *= 2.0;
            if r > width {
                break;
            }
            o = o.map(|k| k + 0.13);
        }
        o
    })
}
