//! Still more of JWildfire's "cut" variations (Jesus Sosa's ports of shader patterns; see
//! `jwf_a_cuts` for how a cut keeps or hides a point): `cut_2ewangtile` (Wang tiles of arcs
//! and bars on the edges of a two-colour edge set), `cut_alientext` (glyphs of random strokes
//! on a randomly subdivided grid), `cut_fingerprint` (rings bent by fifty random whorls),
//! `cut_kleinian` (Jos Leys' Kleinian group limit set), `cut_magfield` (the field lines of
//! fifteen alternating magnetic poles on a circle) and `cut_mandala` (rings of spirals and
//! roses in polar coordinates). The cuts along tilings are in `jwf_m_tilecuts`.
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew.

use std::f64::consts::PI;

use super::jwf_a_cuts::{CUT, cut_end, cut_point, seed_offset};
use super::jwf_direct_colour::gmod;
use super::util::{atan2_approx, fract, mix, signum_java, smoothstep};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("cut_2ewangtile", cut_2ewangtile)
        .params(&[
            p_int("cut_2ewangtile_seed", 1000.0, NEG_INF, INF),
            p_int("cut_2ewangtile_mode", 1.0, 0.0, 1.0),
            p("cut_2ewangtile_zoom", 25.0),
            p_int("cut_2ewangtile_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(seed_first_prepare),
    VarDef::new("cut_alientext", cut_alientext)
        .params(&[
            p_int("cut_alientext_seed", 1000.0, NEG_INF, INF),
            p_int("cut_alientext_mode", 1.0, 0.0, 1.0),
            p_int("cut_alientext_subdivisions", 3.0, 0.0, 4.0),
            p("cut_alientext_zoom", 1.0),
            p_int("cut_alientext_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(seed_first_prepare),
    VarDef::new("cut_fingerprint", cut_fingerprint)
        .params(&[
            p_int("cut_fingerprint_seed", 10000.0, NEG_INF, INF),
            p_int("cut_fingerprint_mode", 1.0, 0.0, 1.0),
            p_range("cut_fingerprint_zoom", 20.0, 1.0, 100.0),
            p_range("cut_fingerprint_width", 0.8, 0.02, 1.0),
            p_int("cut_fingerprint_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_kleinian", cut_kleinian)
        .params(&[
            p_int("cut_kleinian_mode", 1.0, 0.0, 1.0),
            p("cut_kleinian_zoom", 2.0),
            p("cut_kleinian_boxSize", 1.0),
            p("cut_kleinian_time", 0.0),
            p_int("cut_kleinian_NIters", 150.0, 0.0, 150.0),
            p("cut_kleinian_Dx", 0.0),
            p("cut_kleinian_Dy", -0.955),
            p_int("cut_kleinian_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_magfield", cut_magfield)
        .params(&[
            p_int("cut_magfield_randomize", 0.0, NEG_INF, INF),
            p("cut_magfield_time", 0.0),
            p_range("cut_magfield_density", 3.0, 1.0, 10.0),
            p("cut_magfield_zoom", 3.0),
            p_int("cut_magfield_mode", 1.0, 0.0, 1.0),
            p_int("cut_magfield_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_mandala", cut_mandala)
        .params(&[
            p_int("cut_mandala_seed", 1000.0, NEG_INF, INF),
            p_int("cut_mandala_mode", 1.0, 0.0, 1.0),
            p("cut_mandala_time", 0.0),
            p("cut_mandala_zoom", 2.0),
            p_int("cut_mandala_invert", 1.0, 0.0, 1.0),
        ])
        .flags(CUT),
];

/// The pattern's offset from the seed, the first parameter.
pub(super) fn seed_first_prepare(v: &mut Prepared) {
    let [seed] = v.params();
    seed_offset(v, seed);
}

pub(super) fn length(x: f64, y: f64) -> f64 {
    (x * x + y * y).sqrt()
}

/// Dave Hoskins' "hash without sine" of a cell.
fn hash_nosine(x: f64, y: f64) -> f64 {
    const SCALE: f64 = 0.1031;
    let (a, b, c) = (fract(x * SCALE), fract(y * SCALE), fract(x * SCALE));
    let d = a * (b + 19.19) + b * (c + 19.19) + c * (a + 19.19);
    let (a, b, c) = (a + d, b + d, c + d);
    fract((a + b) * c)
}

const WANG_K: f64 = 0.1;
const WANG_K2: f64 = (1.0 - WANG_K) / 2.0;

/// A corner arc meeting a straight piece (the tile joining two edges at right angles).
fn wang_tile0(x: f64, y: f64) -> f64 {
    let k3 = 2f64.sqrt() * 0.5 - WANG_K2;
    let v = length(x, y) - k3;
    let w = WANG_K2 - length(x.abs() - 0.5, y - 0.5);
    mix(v, w, if y < x.abs() { 0.0 } else { 1.0 })
}

fn wang_tile1(x: f64, y: f64) -> f64 {
    (length(x - 0.5, y - 0.5) - 0.5).abs() - WANG_K * 0.5
}

fn wang_tile2(x: f64, _y: f64) -> f64 {
    x.abs() - WANG_K * 0.5
}

fn wang_tile3(x: f64, y: f64) -> f64 {
    (-x - WANG_K * 0.5).max(WANG_K2 - length(x - 0.5, y.abs() - 0.5))
}

/// The distance to the strokes of tile `b` (its four edge bits) at (x, y) of [−½, ½]².
fn wang_tile(x: f64, y: f64, b: u32) -> f64 {
    match b {
        1 => wang_tile0(x, y).max(0.15 - length(x, y)),
        2 => wang_tile0(y, x),
        3 => wang_tile1(x, y),
        4 => wang_tile0(x, -y),
        5 => wang_tile2(x, y),
        6 => wang_tile1(x, -y),
        7 => wang_tile3(x, y),
        8 => wang_tile0(y, -x),
        9 => wang_tile1(-x, y),
        10 => wang_tile2(y, x),
        11 => wang_tile3(y, x),
        12 => wang_tile1(-x, -y),
        13 => wang_tile3(-x, y),
        14 => wang_tile3(-y, x),
        15 => WANG_K2 - length(x.abs() - 0.5, y.abs() - 0.5),
        _ => 1.414,
    }
}

/// The Wang tiling's distance field: each cell's edges set by the hashes of it and its
/// neighbours.
fn wang_map(x: f64, y: f64) -> f64 {
    let (x, y) = (x + 0.5, y + 0.5);
    let (ix, iy) = (x.floor(), y.floor());
    let mut b = 0;
    if hash_nosine(ix, iy) >= 0.5 {
        b += 1;
    }
    if hash_nosine(-ix, -iy) >= 0.5 {
        b += 8;
    }
    if hash_nosine(ix, iy - 1.0) >= 0.5 {
        b += 4;
    }
    if hash_nosine(-(ix + 1.0), -iy) >= 0.5 {
        b += 2;
    }
    wang_tile(fract(x) - 0.5, fract(y) - 0.5, b)
}

/// cut_2ewangtile: cuts along the outlined strokes of a random Wang tiling (`zoom` tiles
/// per unit).
fn cut_2ewangtile(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, zoom, invert] = v.params();
    let [x0, y0] = v.derived();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let d = wang_map(x * zoom + x0, y * zoom + y0);
    let s = smoothstep(0.0, 2.0 / 2000.0, d.min((d - 0.1).abs() - 0.1) / zoom);
    let color = mix(1.0, 0.0, s).sqrt();
    cut_end(v, acc, color > 0.30, invert, (x, y), c)
}

/// The shader hash fract(sin(129.9898·x + 4.1414·y)·2398.5453).
fn alien_hash(x: f64, y: f64) -> f64 {
    fract((x * 129.9898 + y * 4.1414).sin() * 2398.5453)
}

/// A glyph of 7×7 strokes at `coord` in cells of `size`.
fn alien_letter(x: f64, y: f64, size: f64) -> f64 {
    let (gx, gy) = ((x / size * 7.0).floor(), (y / size * 7.0).floor());
    let (rx, ry) = (
        (fract(x / size) * 7.0).floor(),
        (fract(y / size) * 7.0).floor(),
    );
    let (ox, oy) = (fract(rx * 0.5) * 2.0, fract(ry * 0.5) * 2.0);
    let lines = if alien_hash(gx, gy) < 0.5 { 0.0 } else { 1.0 };
    let mut c = ox.max(oy) * lines;
    c += ox.min(oy);
    c *= rx * (6.0 - rx);
    c *= ry * (6.0 - ry);
    c.clamp(0.0, 1.0)
}

/// cut_alientext: cuts along glyphs on a grid halved up to `subdivisions` times at random.
fn cut_alientext(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, subdivisions, zoom, invert] = v.params();
    let [x0, y0] = v.derived();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let ux = x * zoom + x0;
    let uy = (y * zoom + y0) - y0;
    let mut dims = 2.0;
    for _ in 0..=subdivisions as i32 {
        let (ix, iy) = ((ux * dims).floor() / dims, (uy * dims).floor() / dims);
        dims *= 2.0;
        if alien_hash(ix + 454.4543, iy + 454.4543) > 0.3 {
            break;
        }
    }
    let set = alien_letter(ux, uy, 1.0 / dims) > 0.0;
    cut_end(v, acc, set, invert, (x, y), c)
}

/// The fingerprint's hash of a point into [−1, 1]².
fn print_hash(x: f64, y: f64) -> (f64, f64) {
    let (a, b) = (x * 63.31 + y * 127.63, x * 395.467 + y * 213.799);
    (
        fract(a.sin() * 43141.59265) * 2.0 - 1.0,
        fract(b.sin() * 43141.59265) * 2.0 - 1.0,
    )
}

/// The fingerprint's ridge at (x, y) (0 in the valleys).
fn fingerprint(x: f64, y: f64, zoom: f64, width: f64, seed: f64) -> f64 {
    let (mut ux, mut uy) = (x * zoom, y * zoom);
    let bounds = smoothstep(9.0, 10.0, length(ux * 0.7, uy * 0.5));
    let mut a = 0.0;
    let mut h = ((7.0 * seed).floor(), 0.0);
    for _ in 0..50 {
        let s = signum_java(h.0);
        let (hx, hy) = print_hash(h.0, h.1);
        h = (hx * 15.0, hy * 20.0);
        a += s * atan2_approx(ux - h.0, uy - h.1);
    }
    let (hx, hy) = print_hash(h.0, h.1);
    ux += hx.abs();
    uy += hy.abs();
    a += atan2_approx(uy, ux);
    let p = (1.0 - bounds) * width;
    let s = p.min(0.3);
    let l = length(ux, uy) + 0.319 * a;
    let m = gmod(l, 2.0);
    (1.0 - smoothstep(2.0 - s, 2.0, m)) * smoothstep(p, p + s, m)
}

/// cut_fingerprint: cuts along the ridges of a fingerprint (a uniform point of [−½, ½]² with
/// `mode` 1).
fn cut_fingerprint(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [seed, mode, zoom, width, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let set = fingerprint(x, y, zoom, width, seed) == 0.0;
    cut_end(v, acc, set, invert, (x, y), c)
}

/// Whether Jos Leys' Kleinian group iteration leaves the strip 0 ≤ y ≤ a from (x, y) within
/// `iters` steps (the limit set is where it does not).
fn kleinian_escapes(x: f64, y: f64, box_size: f64, time: f64, iters: i32) -> bool {
    let a = 1.8462756 + (1.958591 - 1.8462756) * 0.5 + 0.5 * (1.958591 - 1.8462756) * time;
    let b = 0.09627581 + (0.0112786 - 0.09627581) * 0.5 + 0.5 * (0.0112786 - 0.09627581) * time;
    let f = signum_java(b);
    let (mut zx, mut zy) = (x, y);
    let (mut lz, mut llz) = ((x + 1.0, y + 1.0), (x - 1.0, y - 1.0));
    let period = 2.0 * box_size;
    for _ in 0..iters {
        zx += f * b / a * zy;
        let w = zx + box_size;
        zx = (w - period * (w / period).floor()) - box_size;
        zx -= f * b / a * zy;
        let side = signum_java(zx + b * 0.5);
        let bend = 1.0 - (-(7.2 - (1.95 - a) * 15.0) * (zx + b * 0.5).abs()).exp();
        if zy >= a * 0.5 + f * (2.0 * a - 1.95) / 4.0 * side * bend {
            (zx, zy) = (-b - zx, a - zy);
        }
        let ir = 1.0 / (zx * zx + zy * zy);
        (zx, zy) = (-b + zx * ir, a - zy * ir);
        let (dx, dy) = (zx - llz.0, zy - llz.1);
        if dx * dx + dy * dy < 1e-6 {
            break;
        }
        if zy < 0.0 || zy > a {
            return true;
        }
        llz = lz;
        lz = (zx, zy);
    }
    false
}

/// cut_kleinian: cuts along a Kleinian group's limit set (a uniform point of [−½, ½]² with
/// `mode` 1, scaled by `zoom` and shifted by −(Dx, Dy)).
fn cut_kleinian(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, box_size, time, iters, dx, dy, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let hit = kleinian_escapes(x * zoom - dx, y * zoom - dy, box_size, time, iters as i32);
    cut_end(v, acc, !hit, invert, (x, y), c)
}

/// The unit field direction at (x, y) of fifteen poles of alternating sign on the unit
/// circle, placed by `time`.
fn magfield_velocity(x: f64, y: f64, time: f64) -> (f64, f64) {
    let rand = |n: f64| fract(n.sin() * 43758.5453123);
    const LIMIT: f64 = 15.0;
    let (mut vx, mut vy) = (0.0, 0.0);
    let mut s = 1.0;
    for k in 0..15 {
        let i = f64::from(k);
        let r = rand(i / LIMIT) - 0.5;
        let m = (rand(i + 1.0) - 0.5) * ((time + 23.78 * 1000.0) * 2.0);
        let o = i + r + m;
        let (ax, ay) = ((o / LIMIT * PI * 2.0).sin(), (o / LIMIT * PI * 2.0).cos());
        s = -s;
        let (px, py) = (x - ax, y - ay);
        let d = px * px + py * py;
        vx -= px / d * s;
        vy -= py / d * s;
    }
    let l = length(vx, vy);
    (vx / l, vy / l)
}

/// cut_magfield: cuts along the field lines of alternating poles (`density` lines; a uniform
/// point of [−1, 1]² with `mode` 1).
fn cut_magfield(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, density, zoom, mode, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, -1.0, 2.0, 0.0);
    let (px, py) = (x * zoom, y * zoom);
    let spacing = 1.0 / (10.0 * density);
    let (vx, vy) = magfield_velocity(px, py, time);
    let a = atan2_approx(vx, vy) / PI / 2.0;
    let mut lines = fract(a / spacing);
    lines = lines.min(1.0 - lines) * 2.0;
    let d = 2.0 / 600.0;
    let dv = |ox: f64, oy: f64| {
        let (wx, wy) = magfield_velocity(px + ox, py + oy, time);
        length(vx - wx, vy - wy)
    };
    let deriv = (dv(0.0, d) + dv(d, 0.0) + dv(d, d) + dv(d, -d)) / 4.0;
    lines /= deriv / spacing;
    lines -= 1000.0 * 0.0005;
    lines = lines.clamp(0.0, 1.0);
    let disc = ((length(px, py) - 1.0) / 0.001).clamp(0.0, 1.0);
    lines = mix(1.0 - lines, lines, disc);
    lines = lines.powf(1.0 / 2.2);
    cut_end(v, acc, lines == 0.0, invert, (x, y), c)
}

/// A line of the mandala: 1 on |d| = 0, falling to 0 at |d| = 1/`width`.
fn band(d: f64, width: f64) -> f64 {
    smoothstep(1.0, 0.0, width * d.abs())
}

/// The four mirrored copies of the curve x = g(y) (`g` of a·y).
fn mirrored(x: f64, g: f64, width: f64) -> f64 {
    band(x - g, width)
        + band(x - g.abs(), width)
        + band(x.abs() - g, width)
        + band(x.abs() - g.abs(), width)
}

/// Roses x = sin(6y) (`cosine`: cos 6y), x stretched by 7 + 8t.
fn mandala_rose((x, y): (f64, f64), t: f64, width: f64, cosine: bool) -> f64 {
    let x = x * (7.0 + 8.0 * t);
    let g = if cosine {
        (6.0 * y).cos()
    } else {
        (6.0 * y).sin()
    };
    mirrored(x, g, width)
}

/// Spirals x = y/(2π).
fn mandala_spiral((x, y): (f64, f64), width: f64) -> f64 {
    band(x - 0.5 * y / PI, width)
        + band(x - 0.5 * y.abs() / PI, width)
        + band(x.abs() - 0.5 * y / PI, width)
        + band(x.abs() - 0.5 * y.abs() / PI, width)
}

/// The mandala's ink at the polar point (r, a) at `time`.
fn mandala_ink(r: f64, mut a: f64, time: f64) -> f64 {
    let t0 = (0.3 * time).cos();
    let t1 = 0.5 + 0.5 * (0.3 * time).cos();
    let cell = |a: f64, cr: f64| (gmod(r, cr) - cr * 0.5, gmod(a, PI / 4.0) - PI / 8.0);
    let scaled = |(x, y): (f64, f64), k: f64| (x * k, y * k);
    let mut m = 0.0;
    if r < 0.7325 {
        a += 0.1 * time;
        let cr = 0.225 - 0.1 * t0;
        if r < 0.25 {
            m += 2.0 * mandala_spiral(cell(a, cr), 192.0);
        }
        let cr = 0.225 + 0.1 * t0;
        if r > 0.43 {
            for _ in 0..2 {
                a += PI / 8.0;
                let f2 = cell(a, cr);
                m += mandala_rose(scaled(f2, 0.75 - 0.5 * t0), 0.4 * t1, 24.0, false);
                m += mandala_rose(scaled(f2, 0.5 + 0.5 * t1), 0.2 + 0.2 * t0, 36.0, true);
            }
        }
        let cr = 0.6 - 0.2 * t0;
        if r > 0.265 {
            for _ in 0..2 {
                a += PI / 8.0;
                let f2 = cell(a, cr);
                m += mandala_spiral(((0.25 + 0.5 * t1) * f2.0, f2.1), 392.0);
                m += mandala_rose(scaled(f2, 1.0 + 0.25 * t0), 0.5, 24.0, true);
            }
        }
        let cr = 0.4 + 0.23 * t0;
        if r < 0.265 {
            for _ in 0..2 {
                a += PI / 8.0;
                let f2 = cell(a, cr);
                m += mandala_spiral(f2, 256.0);
                m += mandala_rose(f2, 1.5 * t1, 16.0, false);
            }
        }
        m += band(r - 0.040, 192.0) + band(r - 0.265, 192.0) + band(r - 0.430, 192.0);
    }
    m += band(r - 0.7325, 192.0);
    (m * m).clamp(0.0, 1.0)
}

/// cut_mandala: cuts along a mandala of spirals and roses (a uniform point of [−½, ½]² with
/// `mode` 1); by default it keeps the ink.
fn cut_mandala(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, time, zoom, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (px, py) = (x * zoom, y * zoom);
    let ink = mandala_ink((px * px + py * py).sqrt(), atan2_approx(py, px), time);
    cut_end(v, acc, ink > 0.0, invert, (x, y), c)
}
