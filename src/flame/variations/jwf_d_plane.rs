//! JWildfire's variations built on cells of the plane: `de_stijl` (a Mondrian-like grid whose
//! cell size changes from region to region; the lines get colour 0, each cell a colour drawn
//! from JWildfire's generator seeded by the cell), `pointgrid_wf` and `pointgrid3d_wf` (a
//! random node of a grid, each node moved by a fixed random offset).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew.

use super::util::Mwc;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("de_stijl", de_stijl)
        .params(&[
            p("de_stijl_max_size", 0.5),
            p("de_stijl_min_size", 0.1),
            p("de_stijl_chaos", 5.0),
            p("de_stijl_line_thickness", 0.02),
            p_int("de_stijl_seed", 12345.0, NEG_INF, INF),
        ])
        .flags(flag::JWILDFIRE | flag::SETS_COLOR),
    VarDef::new("pointgrid_wf", pointgrid_wf)
        .params(&[
            p("pointgrid_wf_xmin", -3.0),
            p("pointgrid_wf_xmax", 3.0),
            p_int("pointgrid_wf_xcount", 32.0, NEG_INF, INF),
            p("pointgrid_wf_ymin", -3.0),
            p("pointgrid_wf_ymax", 3.0),
            p_int("pointgrid_wf_ycount", 32.0, NEG_INF, INF),
            p("pointgrid_wf_distortion", 2.3),
            p_int("pointgrid_wf_seed", 1234.0, NEG_INF, INF),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("pointgrid3d_wf", pointgrid3d_wf)
        .params(&[
            p("pointgrid3d_wf_xmin", -3.0),
            p("pointgrid3d_wf_xmax", 3.0),
            p_int("pointgrid3d_wf_xcount", 10.0, NEG_INF, INF),
            p("pointgrid3d_wf_ymin", -3.0),
            p("pointgrid3d_wf_ymax", 3.0),
            p_int("pointgrid3d_wf_ycount", 10.0, NEG_INF, INF),
            p("pointgrid3d_wf_zmin", -1.0),
            p("pointgrid3d_wf_zmax", 1.0),
            p_int("pointgrid3d_wf_zcount", 10.0, NEG_INF, INF),
            p("pointgrid3d_wf_distortion", 2.3),
            p_int("pointgrid3d_wf_seed", 1234.0, NEG_INF, INF),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z),
];

/// Thomas Wang's integer hash of seed + n, as a fraction of 2³¹ − 1 in [0, 1].
fn de_stijl_hash(seed: i32, n: i32) -> f64 {
    let mut h = seed.wrapping_add(n);
    h = (h ^ 61) ^ (h >> 16);
    h = h.wrapping_add(h.wrapping_shl(3));
    h ^= h >> 4;
    h = h.wrapping_mul(0x27d4_eb2d);
    h ^= h >> 15;
    (h & 0x7fff_ffff) as f64 / 0x7fff_ffff as f64
}

/// Java's `Math.round`: the nearest integer, halves rounded up.
fn java_round(x: f64) -> f64 {
    (x + 0.5).floor()
}

/// de_stijl: the point itself (times the weight), coloured 0 on the grid lines and by its
/// cell's random number inside a cell; the grid's size is hashed per `chaos`-sized region.
fn de_stijl(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [max_size, min_size, chaos, thickness, seed] = v.params();
    let seed = seed as i32;
    let (x, y) = (t.x, t.y);
    let rx = (x / chaos).floor() as i32;
    let ry = (y / chaos).floor() as i32;
    let n = rx.wrapping_mul(31337) ^ ry.wrapping_mul(8191);
    let size = (min_size + (max_size - min_size) * de_stijl_hash(seed, n)).max(1e-6);
    let dx = (x - java_round(x / size) * size).abs();
    let dy = (y - java_round(y / size) * size).abs();
    let half = thickness * 0.025;
    acc.color = if dx < half || dy < half {
        0.0
    } else {
        // Java keeps the low 32 bits of the rounded cell index.
        let ix = java_round(x / size) as i64 as i32 as i64;
        let iy = java_round(y / size) as i64 as i32 as i64;
        let cell =
            (seed as i64).wrapping_add(ix.wrapping_mul(73_856_093)) ^ iy.wrapping_mul(19_349_663);
        Mwc::new(cell).next_f64()
    };
    [x * v.w, y * v.w, 0.0]
}

/// JWildfire's `random(n)`: ⌊u·n⌋ for a uniform u, at most n − 1.
fn index_below(rng: &mut FastRng, n: i32) -> i32 {
    let k = (rng.f01() * n as f64) as i32;
    if k < n { k } else { n.wrapping_sub(1) }
}

/// The fixed offset of a grid node along one axis: (½ − the first number of JWildfire's
/// generator seeded with `(seed + salt)·a + b`) times `distortion`.
fn node_offset(seed: i32, salt: i32, a: i32, b: i32, distortion: f64) -> f64 {
    let s = seed.wrapping_add(salt).wrapping_mul(a).wrapping_add(b);
    (0.5 - Mwc::new(s as i64).next_f64()) * distortion
}

/// pointgrid_wf: one of xcount × ycount grid nodes at random, moved by its offset.
fn pointgrid_wf(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [xmin, xmax, xcount, ymin, ymax, ycount, distortion, seed] = v.params();
    let (nx, ny, seed) = (xcount as i32, ycount as i32, seed as i32);
    let xi = index_below(rng, nx);
    let yi = index_below(rng, ny);
    let mut x = xmin + (xmax - xmin) / xcount * xi as f64;
    let mut y = ymin + (ymax - ymin) / ycount * yi as f64;
    if distortion > 0.0 {
        x += node_offset(seed, 1563, xi, yi, distortion);
        y += node_offset(seed, 6715, yi, xi, distortion);
    }
    [x * v.w, y * v.w, 0.0]
}

/// pointgrid3d_wf: one of xcount × ycount × zcount grid nodes at random, moved by its offset.
fn pointgrid3d_wf(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        xmin,
        xmax,
        xcount,
        ymin,
        ymax,
        ycount,
        zmin,
        zmax,
        zcount,
        distortion,
        seed,
    ] = v.params();
    let seed = seed as i32;
    let xi = index_below(rng, xcount as i32);
    let yi = index_below(rng, ycount as i32);
    let zi = index_below(rng, zcount as i32);
    let mut x = xmin + (xmax - xmin) / xcount * xi as f64;
    let mut y = ymin + (ymax - ymin) / ycount * yi as f64;
    let mut z = zmin + (zmax - zmin) / zcount * zi as f64;
    if distortion > 0.0 {
        x += node_offset(seed, 1563, xi, zi, distortion);
        y += node_offset(seed, 6715, yi, xi, distortion);
        z += node_offset(seed, 4761, zi, yi, distortion);
    }
    [x * v.w, y * v.w, z * v.w]
}
