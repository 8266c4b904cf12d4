//! Fractorium's direct-colour variations: `dc_*` maps that set the palette coordinate from
//! where the point lands, and `pixel_flow`.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{PI, TAU};

use super::noise::fractal_noise;
use super::util::{lrint, sqr, trunc_i32, wang_hash, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("dc_bubble", dc_bubble)
        .params(&[
            p("dc_bubble_centerx", 0.0),
            p("dc_bubble_centery", 0.0),
            p("dc_bubble_scale", 1.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC)
        .prepare(dc_bubble_prepare),
    super::inlined!("dc_carpet", dc_carpet)
        .params(&[p("dc_carpet_origin", 0.0)])
        .flags(flag::RANDOM | flag::USES_AFFINE | flag::SETS_COLOR),
    super::inlined!("dc_cube", dc_cube)
        .params(&[
            p("dc_cube_c1", 0.0),
            p("dc_cube_c2", 0.0),
            p("dc_cube_c3", 0.0),
            p("dc_cube_c4", 0.0),
            p("dc_cube_c5", 0.0),
            p("dc_cube_c6", 0.0),
            p("dc_cube_x", 1.0),
            p("dc_cube_y", 1.0),
            p("dc_cube_z", 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR)
        .sum()
        .prepare(dc_cube_prepare),
    super::inlined_drawn!("dc_cylinder", dc_cylinder, 5)
        .params(&[
            p("dc_cylinder_offset", 0.0),
            p("dc_cylinder_angle", 0.0),
            p("dc_cylinder_scale", 0.5),
            p("dc_cylinder_x", 0.125),
            p("dc_cylinder_y", 0.125),
            p("dc_cylinder_blur", 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC)
        .prepare(dc_cylinder_prepare),
    super::inlined!("dc_gridout", dc_gridout).flags(flag::SETS_COLOR),
    super::inlined!("dc_linear", dc_linear)
        .params(&[
            p("dc_linear_offset", 0.0),
            p("dc_linear_angle", 0.0),
            p("dc_linear_scale", 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC)
        .prepare(dc_linear_prepare),
    super::inlined!("dc_perlin", dc_perlin)
        .params(&[
            p_int("dc_perlin_shape", 0.0, 0.0, 2.0),
            p_int("dc_perlin_map", 0.0, 0.0, 5.0),
            p_range("dc_perlin_select_centre", 0.0, -1.0, 1.0),
            p_range("dc_perlin_select_range", 1.0, 0.1, 2.0),
            p("dc_perlin_centre", 0.25),
            p("dc_perlin_range", 0.25),
            p("dc_perlin_edge", 0.0),
            p("dc_perlin_scale", 1.0),
            p_int("dc_perlin_octaves", 2.0, 1.0, 5.0),
            p("dc_perlin_amps", 2.0),
            p("dc_perlin_freqs", 2.0),
            p("dc_perlin_z", 0.0),
            // Rejection draws of 5 octaves of noise each: 100 are tens of microseconds.
            p_int("dc_perlin_select_bailout", 10.0, 2.0, 100.0).limited(),
        ])
        .flags(flag::RANDOM | flag::SETS_COLOR)
        .prepare(dc_perlin_prepare),
    super::inlined!("dc_triangle", dc_triangle)
        .params(&[
            p_range("dc_triangle_scatter_area", 0.0, -1.0, 1.0),
            p_int("dc_triangle_zero_edges", 0.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::USES_AFFINE | flag::SETS_COLOR),
    super::inlined!("dc_ztransl", dc_ztransl)
        .params(&[
            p_range("dc_ztransl_x0", 0.0, 0.0, 1.0),
            p_range("dc_ztransl_x1", 1.0, 0.0, 1.0),
            p("dc_ztransl_factor", 1.0),
            p_int("dc_ztransl_overwrite", 1.0, 0.0, 1.0),
            p_int("dc_ztransl_clamp", 0.0, 0.0, 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::USES_COLOR)
        .prepare(dc_ztransl_prepare),
    super::inlined!("pixel_flow", pixel_flow)
        .params(&[
            p("pixel_flow_angle", 90.0),
            p("pixel_flow_len", 0.1),
            p("pixel_flow_width", 200.0),
            p_int("pixel_flow_seed", 42.0, NEG_INF, INF),
            p_int("pixel_flow_enable_dc", 0.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::SETS_COLOR)
        .prepare(prep_pixel_flow),
];

/// 1/s, with s = 0 read as 1e-5 (the dc_* scale guard).
#[inline(always)]
fn dc_inv_scale(s: f64) -> f64 {
    1.0 / (if s == 0.0 { 10e-6 } else { s })
}

fn dc_bubble_prepare(v: &mut Prepared) {
    let [_, _, scale] = v.params();
    let s = dc_inv_scale(scale);
    v.p.push(s);
}

/// bubble (inverse stereographic projection onto a sphere), coloured by the squared distance of
/// the new running sum from a centre.
#[inline(always)]
fn dc_bubble(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cx, cy] = v.params();
    let [bdcs] = v.derived();
    let k = v.w / zeps(t.sumsq / 4.0 + 1.0);
    let o = [k * t.x, k * t.y, v.w * (2.0 / k - 1.0)];
    let (sx, sy, _) = sum_or_input(v, t, acc);
    let (tx, ty) = (o[0] + sx, o[1] + sy);
    acc.color = (bdcs * (sqr(tx + cx) + sqr(ty + cy))).abs() % 1.0;
    o
}

/// Moves the point to one of four quadrant copies (±1, ±1) through the xform's own affine map,
/// colouring the copies with a carpet pattern.
#[inline(always)]
fn dc_carpet(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [origin] = v.params();
    let h = 0.1 * origin;
    let x0: i32 = if rng.bit() { -1 } else { 1 };
    let y0: i32 = if rng.bit() { -1 } else { 1 };
    let x = t.x + x0 as f64;
    let y = t.y + y0 as f64;
    let xor = (x0 ^ y0) as f64;
    let hh = -h + (1.0 - xor) * h;
    let a = &v.aff;
    // Fractorium feeds (A, B, E) and (C, D, F) of its affine letters here.
    let ox = v.w * (a.a * x + a.b * y + a.d);
    let oy = v.w * (a.e * x + a.c * y + a.f);
    acc.color = (acc.color * 0.5 * (1.0 + hh) + xor * (1.0 - hh) * 0.5).abs() % 1.0;
    [ox, oy, 0.0]
}

fn dc_cube_prepare(v: &mut Prepared) {
    let colours: [f64; 6] = v.params();
    for c in colours {
        v.p.push(c.clamp(0.0, 1.0));
    }
}

/// A random point on the surface of the cube [−1, 1]³ (scaled per axis), each face with its
/// own colour.
#[inline(always)]
fn dc_cube(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, scale_x, scale_y, scale_z] = v.params();
    let w = v.w;
    let p1 = 2.0 * rng.f01() - 1.0;
    let q1 = 2.0 * rng.f01() - 1.0;
    let face = rng.below(3) as usize;
    let neg = rng.bit();
    let side = if neg { -1.0 } else { 1.0 };
    let (x, y, z) = match face {
        0 => (w * side, w * p1, w * q1),
        1 => (w * p1, w * side, w * q1),
        _ => (w * p1, w * q1, w * side),
    };
    // The clamped colours of the faces, two per axis (positive side first).
    acc.color = v.table(0)[2 * face + usize::from(!neg)];
    [x * scale_x, y * scale_y, z * scale_z]
}

fn dc_cylinder_prepare(v: &mut Prepared) {
    let [_, angle, scale] = v.params();
    let (s, c) = angle.fsin_cos();
    let l = dc_inv_scale(scale);
    v.p.extend_from_slice(&[s, c, l]);
}

/// A blurred cylinder: x wraps around a circle (sin/cos into x and z), y passes scaled, with a
/// random radial blur; coloured by a linear gradient across the new running sum.
#[inline(always)]
fn dc_cylinder<R: Draws>(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut R) -> V3 {
    let [offset, _, _, sx, sy, blur] = v.params();
    let [sina, cosa, ldcs] = v.derived();
    let (sr, cr) = (rng.f01() * TAU).fsin_cos();
    let r = blur * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
    let o = [
        v.w * (t.x + r * sr).fsin() * sx,
        r + t.y * sy,
        v.w * (t.x + r * cr).fcos(),
    ];
    let (px, py, _) = sum_or_input(v, t, acc);
    let (tx, ty) = (o[0] + px, o[1] + py);
    acc.color = crate::flame::fastmath::fmod(
        (0.5 * (ldcs * (cosa * tx + sina * ty + offset) + 1.0)).abs(),
        1.0,
    );
    o
}

/// Steps the point one unit along a square spiral grid (which way depends on the nearest grid
/// point's octant), adding 1/4 or 3/4 to the colour.
#[inline(always)]
fn dc_gridout(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let x = lrint(t.x);
    let y = lrint(t.y);
    let w = v.w;
    // Either an x step (colour + 1/4) or a y step (colour + 3/4).
    let (dx, dy) = if y <= 0.0 {
        if x > 0.0 {
            if -y >= x { (1.0, 0.0) } else { (0.0, 1.0) }
        } else if y <= x {
            (1.0, 0.0)
        } else {
            (0.0, -1.0)
        }
    } else if x > 0.0 {
        if y >= x { (-1.0, 0.0) } else { (0.0, 1.0) }
    } else if y > -x {
        (-1.0, 0.0)
    } else {
        (0.0, -1.0)
    };
    let (o, add) = if dy == 0.0 {
        ([w * (t.x + dx), w * t.y, 0.0], 0.25)
    } else {
        ([w * t.x, w * (t.y + dy), 0.0], 0.75)
    };
    acc.color = (acc.color + add) % 1.0;
    o
}

fn dc_linear_prepare(v: &mut Prepared) {
    let [_, angle, scale] = v.params();
    let l = dc_inv_scale(scale);
    let (s, c) = angle.fsin_cos();
    v.p.extend_from_slice(&[l, s, c]);
}

/// linear (3-D), coloured by a linear gradient (angle, scale, offset) across the new running sum.
#[inline(always)]
fn dc_linear(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [offset] = v.params();
    let [ldcs, sina, cosa] = v.derived();
    let o = [v.w * t.x, v.w * t.y, v.w * t.z];
    let (px, py, _) = sum_or_input(v, t, acc);
    let (tx, ty) = (o[0] + px, o[1] + py);
    acc.color = (0.5 * (ldcs * (cosa * tx + sina * ty + offset) + 1.0)).abs() % 1.0;
    o
}

pub(super) fn dc_perlin_prepare(v: &mut Prepared) {
    let [_, _, centre, range] = v.params();
    let mut bottom = centre - range;
    if bottom > 0.75 {
        bottom = 0.75;
    }
    if bottom < -2.0 {
        bottom = -3.0;
    }
    let top = (centre + range).clamp(-0.75, 3.0);
    v.p.extend_from_slice(&[bottom, top]);
}

/// A blur (square, disc or radial) whose samples are kept when a 3-D simplex-noise field,
/// read through one of six mappings of the sample, falls in a band; the noise sets the colour.
#[inline(always)]
fn dc_perlin(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        shape,
        map,
        _select_centre,
        _select_range,
        centre,
        range,
        edge,
        scale,
        octaves,
        amps,
        freqs,
        z,
        bailout,
    ] = v.params();
    let [notch_bottom, notch_top] = v.derived();
    let (shape, map, octaves, bailout) = (shape as i32, map as i32, octaves as i32, bailout as i32);
    let mut tries = 0;
    let (mut vx, mut vy, mut noise);
    loop {
        let mut e = 0.0;
        let r;
        match shape {
            0 => {
                vx = (1.0 + edge) * (rng.f01() - 0.5);
                vy = (1.0 + edge) * (rng.f01() - 0.5);
                r = if vx * vx > vy * vy {
                    (vx * vx).sqrt()
                } else {
                    (vy * vy).sqrt()
                };
            }
            1 => {
                let mut rr = rng.f01() + rng.f01();
                if rr > 1.0 {
                    rr = 2.0 - rr;
                }
                r = rr * (1.0 + edge);
                let (s, c) = (rng.f01() * TAU).fsin_cos();
                vx = 0.5 * r * s;
                vy = 0.5 * r * c;
            }
            _ => {
                r = (1.0 + edge) * rng.f01();
                let (s, c) = (rng.f01() * TAU).fsin_cos();
                vx = 0.5 * r * s;
                vy = 0.5 * r * c;
            }
        }
        if r > 1.0 - edge {
            e = 0.5 * (r - 1.0 + edge) / edge;
        }
        let d2 = vx * vx + vy * vy;
        let pos = match map {
            0 => [scale * vx, scale * vy, scale * z],
            1 => {
                let k = 1.0 / zeps(d2);
                [scale * vx * k, scale * vy * k, scale * z]
            }
            2 => {
                let k = 1.0 / (d2 + 0.5);
                [scale * vx * k, scale * vy * k, scale * z]
            }
            3 => {
                let k = 1.0 / (d2 + 0.25);
                [scale * vx * k, scale * vy * k, scale * z]
            }
            m => {
                let h = 0.25 - d2;
                let h = if h < 0.0 { (-h).sqrt() } else { h.sqrt() };
                let lift = if m == 4 { h } else { 2.0 * h };
                [scale * vx, scale * vy, scale * (lift + z)]
            }
        };
        noise = fractal_noise(pos, amps, freqs, octaves);
        e = if noise > 0.0 {
            noise * (1.0 + e * e * 20.0) + 2.0 * e
        } else {
            noise * (1.0 + e * e * 20.0) - 2.0 * e
        };
        let rejected = e < notch_bottom || e > notch_top;
        let again = rejected && tries < bailout;
        tries += 1;
        if !again {
            break;
        }
    }
    let col = centre + range * noise;
    acc.color = col - col.floor();
    [v.w * vx, v.w * vy, 0.0]
}

/// Barycentric (u, v) moved onto the triangle's far edge u + v = 1, keeping the larger one
/// (at most 1).
#[inline(always)]
fn onto_far_edge(u: f64, v: f64) -> (f64, f64) {
    if u > v {
        let u = if u > 1.0 { 1.0 } else { u };
        (u, 1.0 - u)
    } else {
        let v = if v > 1.0 { 1.0 } else { v };
        (1.0 - v, v)
    }
}

/// Projects the point onto the triangle spanned by the xform's affine map (barycentric
/// coordinates clamped to the triangle, outside points optionally scattered inwards or zeroed);
/// colour = u + v.
#[inline(always)]
fn dc_triangle(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scatter, zero_edges] = v.params();
    let a = &v.aff;
    let scatter = scatter.clamp(-1.0, 1.0);
    let zero_edges = zero_edges != 0.0;
    // Fractorium's triangle: X = (A, B), Y = −(C, D), O = (E, F) in its affine letters.
    let (xx, xy) = (a.a, a.b);
    let (yx, yy) = (-a.e, -a.c);
    let (ox, oy) = (a.d, a.f);
    let (px, py) = (t.x - ox, t.y - oy);
    let d00 = xx * xx + xy * xy;
    let d01 = xx * yx + xy * yy;
    let d02 = xx * px + xy * py;
    let d11 = yx * yx + yy * yy;
    let d12 = yx * px + yy * py;
    let den = d00 * d11 - d01 * d01;
    let mut u = (d11 * d02 - d01 * d12) / den;
    let mut w = (d00 * d12 - d01 * d02) / den;
    let mut inside = false;
    let mut f = 1.0;
    if u + w > 1.0 {
        f = -1.0;
        (u, w) = onto_far_edge(u, w);
    } else if u < 0.0 || w < 0.0 {
        u = u.clamp(0.0, 1.0);
        w = w.clamp(0.0, 1.0);
    } else {
        inside = true;
    }
    if !inside {
        if zero_edges {
            u = 0.0;
            w = 0.0;
        } else {
            u = (u + rng.f01() * scatter * f).clamp(-1.0, 1.0);
            w = (w + rng.f01() * scatter * f).clamp(-1.0, 1.0);
            if u + w > 1.0 && scatter > 0.0 {
                (u, w) = onto_far_edge(u, w);
            }
        }
    }
    acc.color = (u + w).abs() % 1.0;
    [
        v.w * (ox + u * xx + w * yx),
        v.w * (oy + u * xy + w * yy),
        v.w * t.z,
    ]
}

fn dc_ztransl_prepare(v: &mut Prepared) {
    let [a, b] = v.params();
    let lo = if a < b { a } else { b };
    let hi = if a > b { a } else { b };
    v.p.extend_from_slice(&[lo, zeps(hi - lo)]);
}

/// linear in x and y; z set from (or scaled by) the colour coordinate mapped from [x0, x1].
#[inline(always)]
fn dc_ztransl(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    ztransl_by(v, t, acc.color)
}

/// x and y weighted; z from (or scaled by, unless `overwrite`) `color`'s place in the range
/// [lo, lo + span] of the derived values, times `factor` (clamped to [0, 1] with `clamp`).
/// Parameters: x0, x1, factor, overwrite, clamp.
pub(super) fn ztransl_by(v: &Prepared, t: &VarIn, color: f64) -> V3 {
    let [_, _, factor, overwrite, clamp] = v.params();
    let [lo, span] = v.derived();
    let mut zf = factor * (color - lo) / span;
    if clamp != 0.0 {
        zf = zf.clamp(0.0, 1.0);
    }
    let z = if overwrite == 0.0 {
        v.w * t.z * zf
    } else {
        v.w * zf
    };
    [v.w * t.x, v.w * t.y, z]
}

fn prep_pixel_flow(v: &mut Prepared) {
    let [angle] = v.params();
    let rad = angle * (PI / 180.0);
    v.p.push(rad.fcos());
    v.p.push(rad.fsin());
}

/// pixel_flow: streaks: a random displacement along the direction `angle`, of a length hashed
/// from the pixel block (of size 1/width) the point falls in; optionally sets the colour to the
/// random fade.
#[inline(always)]
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
