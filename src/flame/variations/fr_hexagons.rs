//! Hexagonal and triangular tilings from Fractorium's catalogue: `hexes`, `hex_modulus`,
//! `hex_rand`, the hexagon chaos games `hexaplay3D` and `hexnix3D`, and `xtrb`.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::util::{floor_f, floor_i64, rand_size, sine_hash, sqr, trunc_i32, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("hex_modulus", hex_modulus)
        .params(&[p("hex_modulus_size", 1.0)])
        .prepare(hex_modulus_prepare),
    super::inlined!("hex_rand", hex_rand)
        .params(&[
            p("hex_rand_x", 10.0),
            p("hex_rand_y", 10.0),
            p("hex_rand_size", 1.0),
            p("hex_rand_power", 1.0),
            p_range("hex_rand_density", 1.0, 0.0, 1.0),
            p("hex_rand_seed", 1.0),
        ])
        .flags(flag::RANDOM),
    super::inlined!("hexaplay3D", hexaplay3d)
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
    super::inlined!("hexes", hexes)
        .params(&[
            p("hexes_cellsize", 1.0),
            p("hexes_power", 1.0),
            p("hexes_rotate", 0.166),
            p("hexes_scale", 1.0),
        ])
        .prepare(hexes_prepare),
    super::inlined!("hexnix3D", hexnix3d)
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
    super::inlined!("xtrb", xtrb)
        .params(&[
            p_int_nonzero("xtrb_power", 2.0, f64::NEG_INFINITY, f64::INFINITY),
            p("xtrb_radius", 1.0),
            p("xtrb_width", 0.5),
            p("xtrb_dist", 1.0),
            p("xtrb_a", 1.0),
            p("xtrb_b", 1.0),
        ])
        .flags(flag::RANDOM)
        .prepare(xtrb_prep),
];

/// √3 / 2.
const HALF_SQRT3: f64 = 0.866_025_403_784_438_6;

/// √3.
const SQRT3: f64 = 1.732_050_807_568_877_2;

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

fn hex_modulus_prepare(v: &mut Prepared) {
    let [size] = v.params();
    let hsize = HALF_SQRT3 / zeps(size);
    let wk = v.w / HALF_SQRT3;
    v.p.extend_from_slice(&[hsize, wk]);
}

/// The plane modulo a hexagonal lattice: each point is replaced by its offset from the centre
/// of its hexagon (cube-coordinate rounding).
#[inline(always)]
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
#[inline(always)]
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
        // x¹ = x exactly: the default power skips the library's pow (a call per point).
        let shrunk = if power == 1.0 {
            shrink
        } else {
            shrink.powf(power)
        };
        let r = size * 0.5 * reach * shrunk;
        // |ang| < 4: the short reduction, bit for bit what `fsin_cos` gives there, once, and
        // without the long reduction that function computes on every call.
        let (s, c) = crate::flame::fastmath::sin_cos(ang);
        [(c * r + hx) * v.w, (s * r + hy) * v.w, 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

// State slots of the two hexagon walkers.
pub(super) const ST_SIXFOLD: usize = 0;

pub(super) const ST_SIX_STEP: usize = 1;

pub(super) const ST_THREE_STEP: usize = 2;

fn hexaplay3d_prepare(v: &mut Prepared) {
    let [majp, scale] = v.params();
    let majp = majp.abs();
    let (plane, boost) = if majp <= 1.0 {
        (1.0, 0.0)
    } else {
        (2.0, (majp - 1.0) * 0.5)
    };
    let lift = (PI / 3.0).fsin();
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
#[inline(always)]
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

pub(super) fn hexes_prepare(v: &mut Prepared) {
    let [_, _, rotate] = v.params();
    let (s, c) = (rotate * TAU).fsin_cos();
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
#[inline(always)]
fn hexes(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    match hexes_cell(v, t) {
        Some((x, y, _)) => [v.w * x, v.w * y, 0.0],
        None => [0.0, 0.0, 0.0],
    }
}

/// The hexes map of the input before the weight, with the cell ratio it used (the larger
/// of the point's and its turned image's); `None` for a cell size of 0.
pub(super) fn hexes_cell(v: &Prepared, t: &VarIn) -> Option<(f64, f64, f64)> {
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
        return None;
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
    Some((rx * f + ox, ry * f + oy, l))
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
    let lift = (PI / 3.0).fsin();
    let c7 = (7.0 * PI / 6.0).fcos();
    let c11 = (11.0 * PI / 6.0).fcos();
    v.p.extend_from_slice(&[smooth, plane, boost, gentle, lift, c7, c11]);
    // Fractorium picks the first walk from its global generator; start on the six-node walk.
    v.state.set(ST_SIXFOLD, 1.0);
    v.state.set(ST_SIX_STEP, 0.0);
    v.state.set(ST_THREE_STEP, 0.0);
}

/// A hexagon/triangle chaos game in 3-D: each call rotates and scales the (running sum and)
/// point about a random vertex of a hexagon (or a triangle) and moves towards it; `majp` stacks
/// copies above and below the plane, `zlift` scales z. Weights below 0.5 blend with the input.
#[inline(always)]
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

/// Derived values of xtrb: the triangle (angles 0.047 + a, 0.047 + b and the rest, inradius
/// `radius`) — its side lengths, heights and their ratios, the band widths, and the root
/// count and radius exponent of the final power map.
fn xtrb_prep(v: &mut Prepared) {
    let [power, radius, width, dist, a, b] = v.params();
    let br = 0.047 + a;
    let cr = 0.047 + b;
    let ar = PI - br - cr;
    let (sa2, ca2) = (ar / 2.0).fsin_cos();
    let (sb2, cb2) = (br / 2.0).fsin_cos();
    let (sc2, cc2) = (cr / 2.0).fsin_cos();
    let (sinc, cosc) = cr.fsin_cos();
    let la = radius * (sc2 / cc2 + sb2 / cb2);
    let lb = radius * (sc2 / cc2 + sa2 / ca2);
    let lc = radius * (sb2 / cb2 + sa2 / ca2);
    let s2 = radius * (la + lb + lc);
    let ha = s2 / la / 6.0;
    let hb = s2 / lb / 6.0;
    let hc = s2 / lc / 6.0;
    let power = if power == 0.0 { 2.0 } else { power };
    v.p.extend_from_slice(&[
        sinc,
        cosc,
        ha,
        hb,
        hc,
        la / lb,
        la / lc,
        lb / la,
        lb / lc,
        lc / la,
        lc / lb,
        6.0 * ha,
        6.0 * hb,
        6.0 * hc,
        s2 / (la + lb) / 6.0,
        s2 / (la + lc) / 6.0,
        s2 / (lb + lc) / 6.0,
        1.0 - width,
        2.0 * width,
        1.0 - width * width,
        power,
        trunc_i32(power.abs()) as f64,
        dist / power / 2.0,
    ]);
}

/// xtrb's per-triangle map in trilinear coordinates (al, be, ga): points are pulled into a
/// hexagonal band pattern inside the triangle, randomly (with probability 1 − width²) or
/// scaled by `width` toward the nearest vertex.
fn xtrb_hex(hex: &[f64; 16], al: f64, be: f64, ga: f64, rng: &mut FastRng) -> (f64, f64) {
    let [
        width,
        ha,
        hb,
        hc,
        ab,
        ba,
        ca,
        cb,
        s2a,
        s2b,
        s2ab,
        s2ac,
        s2bc,
        w1,
        w2,
        w3,
    ] = *hex;
    let r = rng.f01();
    if be < al {
        if ga < be {
            let (side, gam) = if r >= w3 {
                (width * be, width * ga)
            } else {
                (
                    w1 * be + w2 * s2ab * (3.0 - ga / be),
                    w1 * ga + w2 * hc * ga / be,
                )
            };
            (s2a - ba * side - ca * gam, side)
        } else if ga < al {
            let (side, gam) = if r >= w3 {
                (width * be, width * ga)
            } else {
                (
                    w1 * be + w2 * hb * be / ga,
                    w1 * ga + w2 * s2ac * (3.0 - be / ga),
                )
            };
            (s2a - ba * side - ca * gam, side)
        } else if r >= w3 {
            (width * al, width * be)
        } else {
            (
                w1 * al + w2 * s2ac * (3.0 - be / al),
                w1 * be + w2 * hb * be / al,
            )
        }
    } else if ga < al {
        let (side, gam) = if r >= w3 {
            (width * al, width * ga)
        } else {
            (
                w1 * al + w2 * s2ab * (3.0 - ga / al),
                w1 * ga + w2 * hc * ga / al,
            )
        };
        (side, s2b - ab * side - cb * gam)
    } else if ga < be {
        let (side, gam) = if r >= w3 {
            (width * al, width * ga)
        } else {
            (
                w1 * al + w2 * ha * al / ga,
                w1 * ga + w2 * s2bc * (3.0 - al / ga),
            )
        };
        (side, s2b - ab * side - cb * gam)
    } else if r >= w3 {
        (width * al, width * be)
    } else {
        (
            w1 * al + w2 * ha * al / be,
            w1 * be + w2 * s2bc * (3.0 - al / be),
        )
    }
}

/// xtrb: a triangular tiling (in trilinear coordinates) with hexagonal bands in each
/// triangle, followed by a random root of a power map (as julian, n = `power`).
#[inline(always)]
fn xtrb(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, radius, width] = v.params();
    let [
        sinc,
        cosc,
        ha,
        hb,
        hc,
        ab,
        ac,
        ba,
        bc,
        ca,
        cb,
        s2a,
        s2b,
        s2c,
        s2ab,
        s2ac,
        s2bc,
        w1,
        w2,
        w3,
        power,
        roots,
        cn,
    ] = v.derived();
    let hex = [
        width, ha, hb, hc, ab, ba, ca, cb, s2a, s2b, s2ab, s2ac, s2bc, w1, w2, w3,
    ];
    // To trilinear coordinates (distances from two sides of the triangle).
    let al = t.y + radius;
    let be = t.x * sinc - t.y * cosc + radius;
    let m = (al / s2a).floor();
    let n = (be / s2b).floor();
    let mut oa = al - m * s2a;
    let mut ob = be - n * s2b;
    let og = s2c - ac * oa - bc * ob;
    let (mut al, mut be);
    if og > 0.0 {
        (al, be) = xtrb_hex(&hex, oa, ob, og, rng);
    } else {
        oa = s2a - oa;
        ob = s2b - ob;
        (al, be) = xtrb_hex(&hex, oa, ob, -og, rng);
        al = s2a - al;
        be = s2b - be;
    }
    al += m * s2a;
    be += n * s2b;
    // Back to the plane, then the power map.
    let ix = (be - radius + (al - radius) * cosc) / sinc;
    let iy = al - radius;
    let angle = (iy.atan2(ix) + TAU * rand_size(rng, roots)) / power;
    let r = v.w * (sqr(ix) + sqr(iy)).powf(cn);
    let (s, c) = angle.fsin_cos();
    [v.w * (r * c), v.w * (r * s), 0.0]
}
