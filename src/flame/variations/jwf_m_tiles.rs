//! JWildfire's tilings drawn at random: `arctruchet` (Jesus Sosa's Truchet tiles of two
//! quarter rings, each tile turned by a multiple of 90° drawn once from `seed`) and
//! `geometricPrimitives` (a grid of random circles, squares, triangles and hexagons, filled
//! or outlined, and lines between neighbouring cells; the input picks the cell, points of
//! empty cells are hidden).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew; JWildfire rounds the points
//! to single precision, as here. The tile turns come from Java's generator seeded as
//! JWildfire seeds it, so a seed gives JWildfire's tiling.

use std::f64::consts::PI;

use super::jwf_a_cuts::JavaRandom;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("arctruchet", arctruchet)
        .params(&[
            p_int("arctruchet_seed", 10000.0, 0.0, 100000.0),
            p_range("arctruchet_thickness", 0.025, 0.0, 1.0),
            p_int("arctruchet_TilesPerRow", 10.0, 1.0, 100.0),
            p_int("arctruchet_TilesPerColumn", 10.0, 1.0, 100.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .prepare(arctruchet_prepare),
    VarDef::new("geometricPrimitives", geometric_primitives)
        .params(&[
            p_range("geometricPrimitives_line_vs_shape_mix", 0.5, 0.0, 1.0),
            p("geometricPrimitives_density", 0.5),
            p("geometricPrimitives_scale", 2.0),
            p("geometricPrimitives_gridSize", 1.0),
            p("geometricPrimitives_seed", 0.0),
            p("geometricPrimitives_grid_jitter", 0.0),
            p_int("geometricPrimitives_shape_type", 0.0, 0.0, 3.0),
            p_int("geometricPrimitives_shape_mix_enable", 0.0, 0.0, 1.0),
            p("geometricPrimitives_fill_prob", 0.5),
            p("geometricPrimitives_radius", 0.45),
            p_range("geometricPrimitives_hollow", 0.8, 0.0, 1.0),
            p("geometricPrimitives_square_size", 0.9),
            p_int("geometricPrimitives_connection_mode", 0.0, 0.0, 1.0),
            p_int("geometricPrimitives_recursion_depth", 0.0, 0.0, 50.0),
            p_range("geometricPrimitives_recursion_shape_mix", 0.5, 0.0, 1.0),
            p("geometricPrimitives_recursion_scale", 0.25),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::HIDES),
];

/// The quarter rings' radius (the tiles' side is twice it).
const ARC_RADIUS: f64 = 0.25;

/// Each tile's turn (0–3 quarter turns), row by row, from Java's generator.
fn arctruchet_prepare(v: &mut Prepared) {
    let [seed, _, rows, cols] = v.params();
    let (rows, cols) = (rows as usize, cols as usize);
    let mut r = JavaRandom::new(seed as i64);
    r.next_f64();
    let mut tilts = vec![0.0; rows * cols];
    for i in 0..rows {
        for j in 0..cols {
            tilts[j * rows + i] = (r.next_f64() * 4.0).floor();
        }
    }
    v.p.extend_from_slice(&tilts);
}

/// Rounded to single precision, as JWildfire stores its points.
fn f32r(x: f64) -> f64 {
    x as f32 as f64
}

/// A random point of the ring from `phi1` to `phi2` degrees (of `radius` and `thickness`),
/// turned by `tilt` degrees and moved so that its centre lies on the tile's corner.
fn arc_point(rng: &mut FastRng, thickness: f64, (phi1, phi2): (f64, f64), tilt: f64) -> (f64, f64) {
    let (p1, p2) = (PI * phi1 / 180.0, PI * phi2 / 180.0);
    let gamma = thickness * (2.0 * ARC_RADIUS + thickness) / (ARC_RADIUS + thickness);
    let r = ARC_RADIUS + thickness - gamma * rng.f01();
    let phi = p1 + (p2 - p1) * rng.f01();
    let (xp, yp) = (r * phi.cos(), r * phi.sin());
    let (s, c) = (tilt * PI / 180.0).sin_cos();
    let (x, y) = (f32r(xp * c + yp * s), f32r(-xp * s + yp * c));
    let radio = if phi2 == 270.0 {
        -ARC_RADIUS
    } else {
        ARC_RADIUS
    };
    let (dx, dy) = (f32r(radio * c + radio * s), f32r(-radio * s + radio * c));
    (f32r(x - dx), f32r(y - dy))
}

/// arctruchet: a random point of one of the two quarter rings of a random tile.
fn arctruchet(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, thickness, rows, cols] = v.params();
    let tilts = v.table(0);
    let size = 2.0 * ARC_RADIUS;
    let i = (rng.f01() * rows) as usize;
    let j = (rng.f01() * cols) as usize;
    let x = f32r(i as f64 * size + size / 2.0);
    let y = f32r(j as f64 * size + size / 2.0);
    let tilt = tilts.get(j * rows as usize + i).copied().unwrap_or(0.0) * 90.0;
    let arc = if rng.f01() < 0.5 {
        (0.0, 90.0)
    } else {
        (180.0, 270.0)
    };
    let (px, py) = arc_point(rng, thickness, arc, tilt);
    [
        v.w * (f32r(px + x) - size * rows / 2.0),
        v.w * (f32r(py + y) - size * cols / 2.0),
        0.0,
    ]
}

/// The cell hash of geometricPrimitives: frac(sin(13.9898·x + 73.233·y + salt)·43758.5453),
/// with Java's truncating fraction (negative for negative values).
fn cell_hash(x: f64, y: f64, salt: f64) -> f64 {
    let v = (x * 13.9898 + y * 73.233 + salt).sin() * 43758.5453;
    v - v.trunc()
}

/// A random point of the disc (filled) or of the ring from hollow·r to r about c.
fn prim_circle(
    rng: &mut FastRng,
    filled: bool,
    (cx, cy): (f64, f64),
    rad: f64,
    hollow: f64,
) -> (f64, f64) {
    let a = rng.f01() * 2.0 * PI;
    let r = if filled {
        rng.f01().sqrt() * rad
    } else {
        let inner = rad * hollow;
        inner + rng.f01() * (rad - inner)
    };
    (cx + r * a.cos(), cy + r * a.sin())
}

/// A random point of the square (or of its outline) of side `size` about c.
fn prim_square(rng: &mut FastRng, filled: bool, (cx, cy): (f64, f64), size: f64) -> (f64, f64) {
    let h = size * 0.5;
    if filled {
        let x = cx + (rng.f01() * 2.0 - 1.0) * h;
        return (x, cy + (rng.f01() * 2.0 - 1.0) * h);
    }
    let side = (rng.f01() * 4.0).floor();
    let t = (rng.f01() * 2.0 - 1.0) * h;
    match side as i32 {
        0 => (cx + t, cy + h),
        1 => (cx + t, cy - h),
        2 => (cx + h, cy + t),
        _ => (cx - h, cy + t),
    }
}

/// A random point of the triangle (v1, v2, v3), filled, or of the edge from corner `side`.
fn prim_triangle(rng: &mut FastRng, filled: bool, v: [(f64, f64); 3]) -> (f64, f64) {
    if filled {
        let (mut r1, mut r2) = (rng.f01(), rng.f01());
        if r1 + r2 > 1.0 {
            (r1, r2) = (1.0 - r1, 1.0 - r2);
        }
        let r0 = 1.0 - r1 - r2;
        return (
            r0 * v[0].0 + r1 * v[1].0 + r2 * v[2].0,
            r0 * v[0].1 + r1 * v[1].1 + r2 * v[2].1,
        );
    }
    let side = ((rng.f01() * 3.0).floor() as usize).min(2);
    let t = rng.f01();
    let (a, b) = (v[side], v[(side + 1) % 3]);
    (a.0 * (1.0 - t) + b.0 * t, a.1 * (1.0 - t) + b.1 * t)
}

/// A random point of the hexagon of radius `size` about c (or of its outline).
fn prim_hexagon(rng: &mut FastRng, filled: bool, (cx, cy): (f64, f64), size: f64) -> (f64, f64) {
    let corner = |k: f64| {
        let a = k * (PI / 3.0);
        (cx + size * a.cos(), cy + size * a.sin())
    };
    if filled {
        let seg = (rng.f01() * 6.0).floor();
        return prim_triangle(rng, true, [(cx, cy), corner(seg), corner(seg + 1.0)]);
    }
    let seg = (rng.f01() * 2.0 * PI / (PI / 3.0)).floor();
    let (a, b) = (corner(seg), corner(seg + 1.0));
    let t = rng.f01();
    (a.0 * (1.0 - t) + b.0 * t, a.1 * (1.0 - t) + b.1 * t)
}

/// The shape a geometricPrimitives cell holds, drawn: its type, filled or not, size by cell
/// hash.
fn prim_shape(v: &Prepared, rng: &mut FastRng, (gx, gy): (f64, f64), c: (f64, f64)) -> (f64, f64) {
    let [
        _,
        _,
        _,
        grid,
        seed,
        _,
        shape,
        mix,
        fill,
        radius,
        hollow,
        square,
    ] = v.params();
    let kind = if mix == 1.0 {
        (cell_hash(gx, gy, seed + 10.0) * 4.0).floor()
    } else {
        shape
    };
    let filled = cell_hash(gx, gy, seed + 20.0) < fill;
    match kind as i32 {
        0 => {
            let r = cell_hash(gx, gy, -seed) * radius * grid;
            prim_circle(rng, filled, c, r, hollow)
        }
        1 => prim_square(
            rng,
            filled,
            c,
            cell_hash(gx, gy, 1.0 - seed) * square * grid,
        ),
        2 => {
            let s = cell_hash(gx, gy, 2.0 - seed) * radius * grid;
            let (cx, cy) = c;
            let v = [
                (cx, cy + s),
                (cx - s * 0.866, cy - s * 0.5),
                (cx + s * 0.866, cy - s * 0.5),
            ];
            prim_triangle(rng, filled, v)
        }
        3 => prim_hexagon(
            rng,
            filled,
            c,
            cell_hash(gx, gy, 3.0 - seed) * radius * grid,
        ),
        _ => (0.0, 0.0),
    }
}

/// geometricPrimitives: the shape of the input's cell, or a line (or a row of smaller shapes)
/// to a neighbouring cell's; hidden where the cell is empty.
fn geometric_primitives(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [line_mix, density, scale, grid, seed, jitter] = v.params();
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        fill,
        radius,
        hollow,
        square,
        conn,
        depth,
        rmix,
        rscale,
    ] = v.params();
    let (gx, gy) = ((t.x * scale + 0.5).floor(), (t.y * scale + 0.5).floor());
    let exists = |x: f64, y: f64| cell_hash(x, y, seed) < density;
    let centre = |x: f64, y: f64| {
        let (mut jx, mut jy) = (0.0, 0.0);
        if jitter > 0.0 {
            let m = jitter * grid * 0.5;
            jx = (cell_hash(x, y, seed + 40.0) * 2.0 - 1.0) * m;
            jy = (cell_hash(x, y, seed + 50.0) * 2.0 - 1.0) * m;
        }
        (x * grid + jx, y * grid + jy)
    };
    let c = centre(gx, gy);
    let mut out = None;
    if rng.f01() < line_mix {
        if exists(gx, gy) {
            let (mut nx, mut ny) = (gx, gy);
            if conn == 0.0 {
                let dir = rng.f01() * 4.0;
                if dir < 1.0 {
                    nx += 1.0;
                } else if dir < 2.0 {
                    nx -= 1.0;
                } else if dir < 3.0 {
                    ny += 1.0;
                } else {
                    ny -= 1.0;
                }
            } else {
                let all = [
                    (gx + 1.0, gy),
                    (gx - 1.0, gy),
                    (gx, gy + 1.0),
                    (gx, gy - 1.0),
                ];
                let valid: Vec<(f64, f64)> =
                    all.into_iter().filter(|&(x, y)| exists(x, y)).collect();
                if !valid.is_empty() {
                    let k =
                        ((rng.f01() * valid.len() as f64).floor() as usize).min(valid.len() - 1);
                    (nx, ny) = valid[k];
                }
            }
            if nx != gx || ny != gy {
                let nc = centre(nx, ny);
                out = Some(if depth > 0.0 {
                    let step = (rng.f01() * depth).floor();
                    let f = (step + 0.5) / depth;
                    let sc = (c.0 * (1.0 - f) + nc.0 * f, c.1 * (1.0 - f) + nc.1 * f);
                    let filled = cell_hash(gx, gy, seed + 30.0 + step) < fill;
                    if rng.f01() < rmix {
                        prim_square(rng, filled, sc, square * rscale)
                    } else {
                        prim_circle(rng, filled, sc, radius * rscale, hollow)
                    }
                } else {
                    let f = rng.f01();
                    (c.0 * (1.0 - f) + nc.0 * f, c.1 * (1.0 - f) + nc.1 * f)
                });
            }
        }
    } else if exists(gx, gy) {
        out = Some(prim_shape(v, rng, (gx, gy), c));
    }
    match out {
        Some((x, y)) => {
            acc.hide = false;
            [x * v.w, y * v.w, 0.0]
        }
        None => {
            acc.hide = true;
            [0.0; 3]
        }
    }
}
