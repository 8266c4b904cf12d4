//! More of JWildfire's "cut" variations (Jesus Sosa's ports of shader patterns; see
//! `jwf_a_cuts` for how a cut keeps or hides a point): `cut_spiral` (bands of a turning
//! spiral), `cut_wood` (wood grain: lines twisted by value noise), `cut_metaballs` (a
//! Worley-style field of blobs), `cut_vasarely` (Vasarely's bulging stripes),
//! `cut_apollonian` (an Apollonian gasket), `cut_spots` (fractal-noise spots),
//! `cut_celtic` (interlaced celtic rings), `cut_truchet` (random Truchet tiles),
//! `cut_jigsaw` (jigsaw pieces), `cut_circdes` (nested circles), `cut_pattern` (turned tiles
//! of sine waves), `cut_swarp` (warped rings of circles, squares, hexagons or octagons) and
//! `cut_kaleido` (interference of n circular waves).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew.

use super::jwf_a_cuts::{CUT, cut_end, cut_point, seed_offset};
use super::util::{atan2_approx, fract, mix, smoothstep};
use std::f64::consts::PI;

use super::*;

// The shaders' rounded constants, kept as JWildfire has them.
#[allow(clippy::approx_constant)]
const ROUNDED_TAU: f64 = 6.2831;
#[allow(clippy::approx_constant)]
const ROUNDED_PI: f64 = 3.14159;
#[allow(clippy::approx_constant)]
const COARSE_PI: f64 = 3.14;
#[allow(clippy::approx_constant)]
const ROUNDED_SQRT_HALF: f64 = 0.7071;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("cut_spiral", cut_spiral)
        .params(&[
            p("cut_spiral_time", 0.0),
            p_int("cut_spiral_mode", 1.0, 0.0, 1.0),
            p("cut_spiral_zoom", 2.5),
            p_int("cut_spiral_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_wood", cut_wood)
        .params(&[
            p("cut_wood_shiftX", 0.0),
            p("cut_wood_shiftY", 0.0),
            p_range("cut_wood_freq", 1.8, 0.1, 2.0),
            p_range("cut_wood_smooth", 1.0, 0.0, 1.0),
            p_range("cut_wood_LineCount", 20.0, 1.0, 50.0),
            p_range("cut_wood_LineWidth", 0.2, 0.1, 0.5),
            p_int("cut_wood_mode", 1.0, 0.0, 1.0),
            p("cut_wood_zoom", 2.5),
            p_int("cut_wood_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_metaballs", cut_metaballs)
        .params(&[
            p_int("cut_metaballs_mode", 1.0, 0.0, 1.0),
            p("cut_metaballs_zoom", 7.0),
            p_int("cut_metaballs_invert", 0.0, 0.0, 1.0),
            p("cut_metaballs_time", 0.0),
        ])
        .flags(CUT),
    VarDef::new("cut_vasarely", cut_vasarely)
        .params(&[
            p_int("cut_vasarely_mode", 1.0, 0.0, 1.0),
            p("cut_vasarely_zoom", 1.0),
            p_int("cut_vasarely_invert", 0.0, 0.0, 1.0),
            p("cut_vasarely_size", 0.5),
        ])
        .flags(CUT),
    VarDef::new("cut_apollonian", cut_apollonian)
        .params(&[
            p_int("cut_apollonian_mode", 1.0, 0.0, 1.0),
            p_int("cut_apollonian_levels", 4.0, 1.0, 10.0),
            p_range("cut_apollonian_zoom", 2.0, 0.1, 50.0),
            p_int("cut_apollonian_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_spots", cut_spots)
        .params(&[
            p_int("cut_spots_mode", 1.0, 0.0, 1.0),
            p_int("cut_spots_seed", 0.0, NEG_INF, INF),
            p("cut_spots_zoom", 0.3),
            p_int("cut_spots_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(cut_spots_prepare),
    VarDef::new("cut_celtic", cut_celtic)
        .params(&[
            p_int("cut_celtic_mode", 1.0, 0.0, 1.0),
            p("cut_celtic_zoom", 5.0),
            p_int("cut_celtic_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_truchet", cut_truchet)
        .params(&[
            p_int("cut_truchet_mode", 1.0, 0.0, 1.0),
            p_int("cut_truchet_type", 0.0, 0.0, 2.0),
            p_int("cut_truchet_seed", 1000.0, NEG_INF, INF),
            p("cut_truchet_zoom", 10.0),
            p_int("cut_truchet_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_jigsaw", cut_jigsaw)
        .params(&[
            p_int("cut_jigsaw_seed", 1000.0, NEG_INF, INF),
            p("cut_jigsaw_time", 0.0),
            p_int("cut_jigsaw_mode", 1.0, 0.0, 1.0),
            p("cut_jigsaw_zoom", 4.0),
            p_int("cut_jigsaw_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_circdes", cut_circdes)
        .params(&[
            p_int("cut_circdes_seed", 1000.0, NEG_INF, INF),
            p_int("cut_circdes_mode", 1.0, 0.0, 1.0),
            p("cut_circdes_time", 0.0),
            p("cut_circdes_zoom", 10.0),
            p_int("cut_circdes_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_pattern", cut_pattern)
        .params(&[
            p_int("cut_pattern_seed", 1000.0, NEG_INF, INF),
            p_int("cut_pattern_mode", 1.0, 0.0, 1.0),
            p("cut_pattern_time", 0.9),
            p("cut_pattern_zoom", 0.5),
            p_int("cut_pattern_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_swarp", cut_swarp)
        .params(&[
            p_int("cut_swarp_seed", 1000.0, NEG_INF, INF),
            p_int("cut_swarp_mode", 1.0, 0.0, 1.0),
            p("cut_swarp_time", 0.0),
            p_int("cut_swarp_type", 0.0, 0.0, 3.0),
            p("cut_swarp_zoom", 1.0),
            p_int("cut_swarp_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_kaleido", cut_kaleido)
        .params(&[
            p_int("cut_kaleido_seed", 1000.0, NEG_INF, INF),
            p_int("cut_kaleido_mode", 1.0, 0.0, 1.0),
            p("cut_kaleido_time", 0.0),
            p_int("cut_kaleido_n", 6.0, 2.0, 20.0),
            p("cut_kaleido_zoom", 0.5),
            p_int("cut_kaleido_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
];

/// The shader hash fract(sin(12.9898·x + 78.233·y)·43758.5453123).
fn hash(x: f64, y: f64) -> f64 {
    fract((x * 12.9898 + y * 78.233).sin() * 43758.5453123)
}

/// The shader's two-component hash of a cell.
fn hash2v(x: f64, y: f64) -> (f64, f64) {
    let a = (x * 127.1 + y * 311.7).sin() * 43758.5453;
    let b = (x * 269.5 + y * 183.3).sin() * 43758.5453;
    (fract(a), fract(b))
}

/// cut_spiral: the point turned and grown by 1.1 until it leaves y ≤ 1 (at most 64 times);
/// an odd count of turns cuts.
fn cut_spiral(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [time, mode, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -1.0, 2.0, 0.0);
    let (s, c) = time.sin_cos();
    let (a00, a10, a01, a11) = (1.1 * s, 1.1 * c, -1.1 * c, 1.1 * s);
    let (mut ux, mut uy) = (x * zoom, y * zoom);
    let mut l = 0;
    for _ in 0..64 {
        (ux, uy) = (a00 * ux + a01 * uy, a10 * ux + a11 * uy);
        if uy > 1.0 {
            break;
        }
        l ^= 1;
    }
    cut_end(v, acc, l > 0, invert, (x, y), 0.0)
}

/// Smoothly interpolated value noise of the cell hashes at `density` cells per unit.
fn value_noise(x: f64, y: f64, density: f64) -> f64 {
    let (cx, cy) = (x * density, y * density);
    let (fx, fy) = (fract(cx), fract(cy));
    let (ix, iy) = (cx.floor(), cy.floor());
    let (bl, br) = (hash(ix, iy), hash(ix + 1.0, iy));
    let (tl, tr) = (hash(ix, iy + 1.0), hash(ix + 1.0, iy + 1.0));
    let (ux, uy) = (smoothstep(0.0, 1.0, fx), smoothstep(0.0, 1.0, fy));
    mix(mix(bl, br, ux), mix(tl, tr, ux), uy)
}

/// cut_wood: `LineCount` lines per unit of width `LineWidth`, each region turned about
/// (½, ½) by its noise (raised to `smooth`).
fn cut_wood(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [x0, y0, freq, smooth, count, width, mode, zoom, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let (sx, sy) = (x * zoom + x0, y * zoom + y0);
    let angle = value_noise(sx, sy, freq).powf(smooth);
    let (s, co) = angle.sin_cos();
    let (dx, dy) = (sx - 0.5, sy - 0.5);
    let ty = s * dx + co * dy + 0.5;
    let cy = fract(ty * count);
    let line = smoothstep(0.5 - width, 0.5 - width + 0.04, cy)
        - smoothstep(0.5 + width - 0.04, 0.5 + width, cy);
    cut_end(v, acc, line > 0.0, invert, (x, y), c)
}

/// cut_metaballs: the product of the distances to the moving points of the 3 × 3 cells
/// around; cuts where it falls below 0.06.
fn cut_metaballs(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, invert, time] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let (sx, sy) = (x * zoom, y * zoom);
    let (ix, iy, fx, fy) = (sx.floor(), sy.floor(), fract(sx), fract(sy));
    let mut m: f64 = 1.0;
    for j in -1..=1 {
        for i in -1..=1 {
            let (nx, ny) = (i as f64, j as f64);
            let (ox, oy) = hash2v(ix + nx, iy + ny);
            let ox = (ox * ROUNDED_TAU + time).sin() * 0.5 + 0.5;
            let oy = (oy * ROUNDED_TAU + time).sin() * 0.5 + 0.5;
            let (px, py) = (nx + ox - fx, ny + oy - fy);
            m = m.min(m * (px * px + py * py).sqrt());
        }
    }
    cut_end(v, acc, m < 0.06, invert, (x, y), c)
}

/// cut_vasarely: stripes sin(150·r·sin(θ + 1.57 + 4b²)) within |x| < 1, bulging where
/// b = max(0, 2 − r/size) is positive.
fn cut_vasarely(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, invert, size] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -1.0, 2.0, 0.0);
    let (ux, uy) = (x * zoom, y * zoom);
    let l = (ux * ux + uy * uy).sqrt();
    let b = (2.0 - l / size).max(0.0);
    let color = if ux.abs() < 1.0 {
        let s = (l * (atan2_approx(uy, ux) + 1.57 + 4.0 * b * b).sin() * 150.0).sin();
        let c1 = 0.0 - 0.5 - s;
        c1 - (c1 - 0.5 - s)
    } else {
        0.0
    };
    cut_end(v, acc, color < 0.1, invert, (x, y), 0.0)
}

/// cut_apollonian: `levels` folds and inversions of an Apollonian gasket; cuts off the thin
/// band around the final |y|.
fn cut_apollonian(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, levels, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (mut px, mut py) = (x * zoom, y * zoom);
    let mut scale = 1.0;
    for _ in 0..levels as i32 {
        px = fract(px * 0.5 + 0.5) * 2.0 - 1.0;
        py = fract(py * 0.5 + 0.5) * 2.0 - 1.0;
        let k = 1.34 / (px * px + py * py);
        px *= k;
        py *= k;
        scale *= k;
    }
    let d = smoothstep(0.001, 0.002, 0.25 * py.abs() / scale);
    cut_end(v, acc, d > 0.0, invert, (x, y), 0.0)
}

fn cut_spots_prepare(v: &mut Prepared) {
    let [_, seed, _, _] = v.params();
    seed_offset(v, seed);
}

/// Value noise with the cubic fade, as the spots' fractal noise sums it.
fn fade_noise(x: f64, y: f64) -> f64 {
    let (ix, iy, fx, fy) = (x.floor(), y.floor(), fract(x), fract(y));
    let a = hash(ix, iy);
    let b = hash(ix + 1.0, iy);
    let c = hash(ix, iy + 1.0);
    let d = hash(ix + 1.0, iy + 1.0);
    let ux = fx * fx * (3.0 - fx * 2.0);
    let uy = fy * fy * (3.0 - fy * 2.0);
    mix(a, b, ux) + (c - a) * uy * (1.0 - ux) + (d - b) * ux * uy
}

/// Six octaves of [`fade_noise`].
fn fbm(mut x: f64, mut y: f64) -> f64 {
    let (mut value, mut amplitude) = (0.0, 0.5);
    for _ in 0..6 {
        value += amplitude * fade_noise(x, y);
        x *= 2.0;
        y *= 2.0;
        amplitude *= 0.5;
    }
    value
}

/// cut_spots: keeps where the fractal noise is below 0.4 (the spots), cuts elsewhere.
fn cut_spots(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, _, zoom, invert] = v.params();
    let [x0, y0] = v.derived();
    let (x, y, _) = cut_point(mode, t, rng, -1.0, 2.0, 0.0);
    let (ux, uy) = (x * zoom * 43.0 + x0, y * zoom * 43.0 + y0);
    let color = if fbm(ux, uy) < 0.4 { 1.0 } else { 0.0 };
    cut_end(v, acc, color == 0.0, invert, (x, y), 0.0)
}

/// A celtic knot cell: the ring of radii 0.38–0.45 less three neighbouring discs.
fn celtic_cell(x: f64, y: f64) -> f64 {
    let circ = |ux: f64, uy: f64, r: f64| {
        let d = (ux * ux + uy * uy).sqrt();
        smoothstep(d, d + 0.02, r)
    };
    let c1 = circ(x, y, 0.38);
    let c5 = circ(x, y, 0.45);
    let c2 = circ(x + 0.5, y - 0.288675, 0.45);
    let c3 = circ(x - 0.5, y - 0.288675, 0.45);
    let c4 = circ(x, y + 0.57735, 0.45);
    mix(0.0, c5 - c2 - c3 - c4, c1)
}

/// One of the celtic pattern's three shifted hexagonal layers at (ux, uy) (already zoomed).
fn celtic_layer(ux: f64, uy: f64) -> f64 {
    let m = uy - 2.0 * (uy / 2.0).floor();
    let ux = ux + if m < 1.0 { 0.0 } else { 0.5 };
    let (fx, fy) = (fract(ux), fract(uy));
    celtic_cell(fx - 1.155 / 2.0, fy / 1.155 - 0.5)
}

/// cut_celtic: three interlaced hexagonal layers of celtic rings.
fn cut_celtic(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let (ux, uy) = (x * zoom, y * 1.155 * zoom);
    let f = celtic_layer(ux, uy);
    let g = celtic_layer(ux - 0.5, uy - 0.288675);
    let h = celtic_layer(ux + 1.0, uy - 0.65);
    cut_end(v, acc, f + g + h > 0.0, invert, (x, y), c)
}

/// cut_truchet: Truchet tiles (diagonal bands, arcs or triangles by `type`) chosen by a hash
/// of each cell, the grid shifted by `seed`.
fn cut_truchet(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, kind, seed, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let h = (7.0 * seed).floor();
    let (rx, ry) = hash2v(h, h);
    let (sx, sy) = (x * zoom + h * rx, y * zoom + h * ry);
    let (ix, iy) = (sx.floor(), sy.floor());
    let (mut tx, mut ty) = (fract(sx), fract(sy));
    let index = fract((hash(ix, iy) - 0.5) * 2.0);
    if index > 0.75 {
        (tx, ty) = (1.0 - tx, 1.0 - ty);
    } else if index > 0.5 {
        tx = 1.0 - tx;
    } else if index > 0.25 {
        (tx, ty) = (1.0 - (1.0 - tx), 1.0 - ty);
    }
    // GLSL's step(l, r) - step(l, r'): 1 on the ring r' < l <= r.
    let ring = |l: f64| {
        let inside = |r: f64| if r < l { 0.0 } else { 1.0 };
        inside(0.6) - inside(0.4)
    };
    let color = match kind as i32 {
        0 => smoothstep(tx - 0.3, tx, ty) - smoothstep(tx, tx + 0.3, ty),
        1 => {
            ring((tx * tx + ty * ty).sqrt())
                + ring(((tx - 1.0).powi(2) + (ty - 1.0).powi(2)).sqrt())
        }
        _ => {
            if ty < tx {
                0.0
            } else {
                1.0
            }
        }
    };
    cut_end(v, acc, color == 0.0, invert, (x, y), 0.0)
}

/// cut_jigsaw: jigsaw pieces with round tabs (the tab direction hashed per cell); `time`
/// slides the pattern along x.
fn cut_jigsaw(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, mode, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (ux, uy) = (x * zoom + time, y * zoom);
    let (ix, iy) = (ux.ceil(), uy.ceil());
    let gm = |a: f64| a - 2.0 * (a / 2.0).floor() - 0.5;
    let (mx, my) = (gm(ix), gm(iy));
    let (ux, uy) = (ux - (ix - 0.5), uy - (iy - 0.5));
    let (dx, dy) = if mx * ux + my * uy < 0.0 {
        (-mx, -my)
    } else {
        (mx, my)
    };
    let f = ((ux - dx).abs() + (uy - dy).abs()) * 0.7 - 0.65;
    let c = ((ux - dx * 0.2).powi(2) + (uy - dy * 0.2).powi(2)).sqrt() - 0.2;
    let d = (ix * 27.0 + iy * 57.0).sin() * 1e5;
    let tab = if (fract(d) - 0.5) * dx < 0.0 {
        f.max(0.1 - c)
    } else {
        f
    };
    let color = 1.0 - tab.min(c) * 1e4 / 8.0;
    cut_end(v, acc, color > 0.0, invert, (x, y), 0.0)
}

/// cut_circdes: per cell, a disc of radius 0.8 with nine rings of four discs each taken
/// away and added in turn (their radii shrinking with `time`).
fn cut_circdes(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, time, zoom, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let (ux, uy) = (fract(x * zoom) - 0.5, fract(y * zoom) - 0.5);
    let inside = |px: f64, py: f64, r: f64| {
        if r < (px * px + py * py).sqrt() {
            0.0
        } else {
            1.0
        }
    };
    let mut r = 0.8;
    let mut d = inside(ux, uy, r);
    for i in 0..9 {
        r *= 0.5 + 0.1 * (i as f64 + time).sin();
        let ring = inside(ux, uy + r, r)
            + inside(ux + r, uy, r)
            + inside(ux, uy - r, r)
            + inside(ux - r, uy, r);
        // GLSL adds the four one step at a time; the order does not change integers.
        d += if i % 2 == 0 { -ring } else { ring };
    }
    cut_end(v, acc, d > 0.5, invert, (x, y), c)
}

/// A point of the unit tile turned by `a` about (½, ½).
fn turn_tile(x: f64, y: f64, a: f64) -> (f64, f64) {
    let (s, c) = a.sin_cos();
    let (x, y) = (x - 0.5, y - 0.5);
    (c * x + s * y + 0.5, -s * x + c * y + 0.5)
}

/// cut_pattern: tiles of a sine-wave pattern, each quarter tile turned by a quarter or three
/// quarters of a turn.
fn cut_pattern(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, time, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (sx, sy) = (fract(x * zoom) * 2.0, fract(y * zoom) * 2.0);
    let gm = |a: f64| a - 2.0 * (a / 2.0).floor();
    let index = (if gm(sx) < 1.0 { 0.0 } else { 1.0 }) + (if gm(sy) < 1.0 { 0.0 } else { 2.0 });
    let quarter = if index == 0.0 || index == 2.0 {
        PI * 2.0 * 1.0 / 4.0
    } else {
        PI * 2.0 * 3.0 / 4.0
    };
    let (ux, uy) = turn_tile(fract(sx), fract(sy), quarter);
    let (px, py) = (0.0 - ux, 5.0 - uy);
    let radius = (px * px + py * py).sqrt();
    let inner = ((ux * PI * 3.0).sin() * PI * 2.0 + (uy * PI * 15.0).sin()).cos();
    let r = (radius
        * (uy * PI * 5.0 + time + inner).sin()
        * 1.0
        * (uy * PI + (ux * PI * 5.0).sin()).sin())
    .sin();
    let b = (r * PI * 2.0 + PI * 2.0).cos() * 0.9 + (r * PI * 2.0 + PI * 2.0).sin() * 0.7;
    cut_end(v, acc, b > 0.0, invert, (x, y), 0.0)
}

/// cut_swarp: the point warped by sines, then rings of the distance of `type` (circle,
/// square, hexagon, octagon), the two halves x ≤ 0 and x > 0 shifted apart.
fn cut_swarp(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, time, kind, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (mut ux, mut uy) = (x * zoom, y * zoom);
    let v0x = ux * 5.0 + (ux * 11.0 + time).cos() + time;
    let v0y = uy * 5.0 + (uy * 11.0 + time).cos() + time;
    let t0 = v0x.sin() * 0.5 + v0y.sin() * 0.5;
    ux += t0 * 0.02;
    uy += t0 * 0.02;
    uy += (ux * 7.0 + (ux * 4.0 + time * 2.0).cos() * 1.0 + time).sin() * 0.05;
    let s = ux.ceil() * 2.0 - 1.0;
    let m = 6.0;
    uy += s / m;
    let (ax, ay) = (ux.abs(), uy.abs());
    let dist = match kind as i32 {
        0 => (ux * ux + uy * uy).sqrt(),
        1 => ax.max(ay),
        2 => (ax * 0.8660254 + ay * 0.5).max(ay),
        _ => ax.max(ay).max((ax + ay) * ROUNDED_SQRT_HALF),
    };
    let k = (s * ROUNDED_PI / 2.0 + dist * 5.0 * m * ROUNDED_PI / 2.0).sin();
    cut_end(v, acc, k.max(0.0).sqrt() > 0.5, invert, (x, y), 0.0)
}

/// cut_kaleido: the mean of sin(k·distance) to n points on a circle of radius ½, through
/// −cos(13·mean); `time` turns the points and changes k.
fn cut_kaleido(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, time, n, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (ux, uy) = (x * zoom, y * zoom);
    let k = 100.0 + 10.0 * (time / 5.0).sin();
    let mut d = 1.0;
    for i in 0..n as i32 {
        let fi = 2.0 * COARSE_PI * (i as f64 + 0.02 * time) / n;
        let (cx, cy) = (0.5 * fi.sin(), 0.5 * fi.cos());
        d += (k * ((ux - cx).powi(2) + (uy - cy).powi(2)).sqrt()).sin();
    }
    let color = 0.0 - (d / n * 13.0).cos();
    cut_end(v, acc, color > 0.0, invert, (x, y), 0.0)
}
