//! Square-grid patterns from Fractorium's catalogue: cells, checks, Voronoi cells and crackle,
//! bubble wraps, shredded strips, tilings by copying, grids of circles and the grid walks.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::noise::simplex_noise3;
use super::util::{
    floor_f, floor_i64, lattice_noise, lattice_noise_2d, lrint, round_half_out, sine_hash, sqr,
    trunc_i32, zeps,
};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("boarders2", boarders2)
        .params(&[
            p("boarders2_c", 0.5),
            p("boarders2_left", 0.5),
            p("boarders2_right", 0.5),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_boarders2),
    super::inlined!("bwraps", bwraps)
        .params(&[
            p("bwraps_cellsize", 1.0),
            p("bwraps_space", 0.0),
            p("bwraps_gain", 1.0),
            p("bwraps_inner_twist", 0.0),
            p("bwraps_outer_twist", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_bwraps),
    super::inlined!("bwraps_rand", bwraps_rand)
        .params(&[
            p("bwraps_rand_cellsize", 1.0),
            p("bwraps_rand_space", 0.0),
            p("bwraps_rand_gain", 2.0),
            p("bwraps_rand_inner_twist", 0.0),
            p("bwraps_rand_outer_twist", 0.0),
            p("bwraps_rand_symm", 0.0),
            p("bwraps_rand_seed", 1.0),
        ])
        .prepare(prep_bwraps_rand),
    super::inlined!("checks", checks)
        .params(&[
            p("checks_x", 0.5),
            p("checks_y", 0.5),
            p("checks_size", 0.5),
            p("checks_rnd", 0.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_checks),
    super::inlined!("Circle_Rand", circle_rand_hash)
        .params(&[
            p("Circle_Rand_X", 10.0),
            p("Circle_Rand_Y", 10.0),
            p_range("Circle_Rand_size", 1.0, 0.0, f64::INFINITY),
            p("Circle_Rand_power", 1.0),
            p_range("Circle_Rand_density", 1.0, 0.0, 1.0),
            p("Circle_Rand_seed", 1.0),
        ])
        .flags(flag::RANDOM),
    super::inlined!("CircleLinear", circle_linear).params(&[
        p_nonzero("CircleLinear_Sc", 1.0, f64::NEG_INFINITY, f64::INFINITY),
        p("CircleLinear_K", 0.5),
        p("CircleLinear_Dens1", 0.5),
        p("CircleLinear_Dens2", 0.5),
        p("CircleLinear_Reverse", 1.0),
        p("CircleLinear_X", 10.0),
        p("CircleLinear_Y", 10.0),
        p_int("CircleLinear_Seed", 0.0, f64::NEG_INFINITY, f64::INFINITY),
    ]),
    super::inlined!("CircleRand", circle_rand)
        .params(&[
            p_nonzero("CircleRand_Sc", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p("CircleRand_Dens", 0.5),
            p("CircleRand_X", 10.0),
            p("CircleRand_Y", 10.0),
            p_int("CircleRand_Seed", 0.0, f64::NEG_INFINITY, f64::INFINITY),
        ])
        .flags(flag::RANDOM)
        .sum(),
    super::inlined!("CircleTrans1", circle_trans1)
        .params(&[
            p_nonzero("CircleTrans1_Sc", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p("CircleTrans1_Dens", 0.5),
            p("CircleTrans1_X", 10.0),
            p("CircleTrans1_Y", 10.0),
            p_int("CircleTrans1_Seed", 0.0, f64::NEG_INFINITY, f64::INFINITY),
        ])
        .flags(flag::RANDOM),
    super::inlined!("crackle", crackle)
        .params(&[
            p_range("crackle_cellsize", 1.0, 0.0001, f64::INFINITY),
            p("crackle_power", 0.2),
            p("crackle_distort", 0.0),
            p("crackle_scale", 1.0),
            p("crackle_z", 0.0),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_crackle),
    super::inlined!("crackle2", crackle2)
        .params(&[p_range("crackle2_cellsize", 1.0, 0.0001, f64::INFINITY)])
        .flags(flag::RANDOM),
    super::inlined!("dust", dust).params(&[
        p_nonzero("dust_density", 5.0, NEG_INF, INF),
        p("dust_distortion", 1.0),
        p("dust_power", 1.0),
    ]),
    super::inlined!("gnarly", gnarly)
        .params(&[p("gnarly_cellsize", 1.0), p("gnarly_twist", 1.0)])
        .prepare(gnarly_prepare),
    super::inlined!("gridout", gridout),
    VarDef::new("modulusx", modulus::<0>)
        .batch(super::inline_batch!(modulus::<0>))
        .params(&[p("modulusx_x", 1.0), p("modulusx_shift", 0.0)])
        .prepare(prep_modulus),
    VarDef::new("modulusy", modulus::<1>)
        .batch(super::inline_batch!(modulus::<1>))
        .params(&[p("modulusy_y", 1.0), p("modulusy_shift", 0.0)])
        .prepare(prep_modulus),
    super::inlined!("shredlin", shredlin)
        .params(&[
            p_nonzero("shredlin_xdistance", 1.0, -INF, INF),
            p_range("shredlin_xwidth", 0.5, -1.0, 1.0),
            p_nonzero("shredlin_ydistance", 1.0, -INF, INF),
            p_range("shredlin_ywidth", 0.5, -1.0, 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(shredlin_prep),
    super::inlined!("SplitBrdr", split_brdr)
        .params(&[
            p("SplitBrdr_x", 0.25),
            p("SplitBrdr_y", 0.25),
            p("SplitBrdr_px", 0.0),
            p("SplitBrdr_py", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM),
    super::inlined!("squares", squares).params(&[
        p("squares_cellsize", 0.0),
        p_range("squares_min", 0.0, 0.0, INF),
        p_range("squares_max", 10.0, 0.0, INF),
        p("squares_num", 10.0),
        p("squares_seed", 1.0),
        p("squares_zero", 0.5),
        p("squares_zero_seed", 1.0),
    ]),
    super::inlined!("sschecks", sschecks)
        .params(&[
            p("sschecks_x", 0.5),
            p("sschecks_y", 0.5),
            p("sschecks_size", 0.5),
            p("sschecks_rnd", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM)
        .prepare(sschecks_prep),
    super::inlined!("tile_hlp", tile_hlp)
        .params(&[p_nonzero(
            "tile_hlp_width",
            1.0,
            f64::NEG_INFINITY,
            f64::INFINITY,
        )])
        .flags(flag::RANDOM)
        .prepare(tile_hlp_prep),
    super::inlined!("tile_log", tile_log)
        .params(&[p("tile_log_spread", 1.0)])
        .flags(flag::RANDOM),
    super::inlined!("Voron", voron).params(&[
        p("Voron_K", 0.99),
        p_nonzero("Voron_Step", 0.25, f64::NEG_INFINITY, f64::INFINITY),
        p_int("Voron_Num", 1.0, 1.0, 25.0),
        p_int("Voron_XSeed", 3.0, f64::NEG_INFINITY, f64::INFINITY),
        p_int("Voron_YSeed", 7.0, f64::NEG_INFINITY, f64::INFINITY),
    ]),
];

/// Derived values: |c|, |c|·|left|, |c| + |c|·|right| (zeros replaced by ε).
fn prep_boarders2(v: &mut Prepared) {
    let [c, left, right] = v.params();
    let c = zeps(c.abs());
    let left = zeps(left.abs());
    let right = zeps(right.abs());
    v.p.push(c);
    v.p.push(c * left);
    v.p.push(c + c * right);
}

/// Tiles of the integer grid shrunk by c about their centres; with probability set by
/// `right`, a point is instead pushed out towards the tile's border (by `left`), along the
/// axis of its larger offset, drawing the gaps between tiles.
#[inline(always)]
fn boarders2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [c, cl, cr] = v.derived();
    let rx = if t.x >= 0.0 {
        trunc_i32(t.x + 0.5)
    } else {
        trunc_i32(t.x - 0.5)
    } as f64;
    let ry = if t.y >= 0.0 {
        trunc_i32(t.y + 0.5)
    } else {
        trunc_i32(t.y - 0.5)
    } as f64;
    let (ox, oy) = (t.x - rx, t.y - ry);
    let w = v.w;
    if rng.f01() >= cr {
        return [w * (ox * c + rx), w * (oy * c + ry), 0.0];
    }
    if ox.abs() >= oy.abs() {
        let e = if ox >= 0.0 { cl } else { -cl };
        [w * (ox * c + rx + e), w * (oy * c + ry + e * oy / ox), 0.0]
    } else {
        let e = if oy >= 0.0 { cl } else { -cl };
        [w * (ox * c + rx + ox / oy * e), w * (oy * c + ry + e), 0.0]
    }
}

/// Derived values: gain² + 10⁻⁶, bubble radius², radius / maximal bubble size.
fn prep_bwraps(v: &mut Prepared) {
    let [cell, space, gain, _, _] = v.params();
    let radius = 0.5 * (cell / (1.0 + space * space));
    let g2 = gain * gain + 1.0e-6;
    let mut max_bubble = g2 * radius;
    if max_bubble > 2.0 {
        max_bubble = 1.0;
    } else {
        max_bubble *= 1.0 / (max_bubble * max_bubble / 4.0 + 1.0);
    }
    v.p.push(g2);
    v.p.push(zeps(radius * radius));
    v.p.push(radius / max_bubble);
}

/// Bubble wrap: each grid cell holds a bubble; points inside it are magnified like `bubble`
/// and twisted (inner twist at the centre, outer twist at the rim).
#[inline(always)]
fn bwraps(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cell, _, _, inner, outer] = v.params();
    let [g2, r2, rfactor] = v.derived();
    let z = v.w * t.z;
    if cell == 0.0 {
        return [v.w * t.x, v.w * t.y, z];
    }
    let cx = (floor_i64(t.x / cell) as f64 + 0.5) * cell;
    let cy = (floor_i64(t.y / cell) as f64 + 0.5) * cell;
    let (mut lx, mut ly) = (t.x - cx, t.y - cy);
    if lx * lx + ly * ly > r2 {
        return [v.w * t.x, v.w * t.y, z];
    }
    lx *= g2;
    ly *= g2;
    let r = rfactor / zeps((lx * lx + ly * ly) / 4.0 + 1.0);
    lx *= r;
    ly *= r;
    let f = (lx * lx + ly * ly) / r2;
    let (s, c) = (inner * (1.0 - f) + outer * f).fsin_cos();
    [
        v.w * (cx + c * lx + s * ly),
        v.w * (cy - s * lx + c * ly),
        z,
    ]
}

/// Derived values: gain², 1/cell size, cell size / (2(1 + space²)).
fn prep_bwraps_rand(v: &mut Prepared) {
    let [cell, space, gain] = v.params();
    v.p.push(gain * gain);
    v.p.push(1.0 / zeps(cell));
    v.p.push(0.5 * (cell / (1.0 + space * space)));
}

/// `bwraps` with a bubble of random size in each cell (a hash of the cell's centre, or of its
/// square for symmetric layouts).
#[inline(always)]
fn bwraps_rand(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cell, _, _, inner, outer, symm, seed] = v.params();
    let [g2, inv_cell, half] = v.derived();
    let w = v.w;
    if cell == 0.0 {
        return [t.x * w, t.y * w, 0.0];
    }
    let cx = (floor_i64(t.x * inv_cell) as f64 + 0.5) * cell;
    let cy = (floor_i64(t.y * inv_cell) as f64 + 0.5) * cell;
    let (lx, ly) = (t.x - cx, t.y - cy);
    let radius = if symm == 0.0 {
        half * sine_hash(cx, cy, seed)
    } else {
        half * sine_hash(cx * cx, cy * cy, seed)
    };
    let mb = g2 * radius;
    let max_bubble = if mb > 2.0 {
        1.0
    } else {
        mb / (mb * mb * 0.25 + 1.0)
    };
    let r2 = radius * radius;
    if lx * lx + ly * ly > r2 {
        return [t.x * w, t.y * w, 0.0];
    }
    let rfactor = radius / zeps(max_bubble);
    let (lx2, ly2) = (lx * g2, ly * g2);
    let r = rfactor / ((lx2 * lx2 + ly2 * ly2) * 0.25 + 1.0);
    let (lx3, ly3) = (lx2 * r, ly2 * r);
    let f = (lx3 * lx3 + ly3 * ly3) / zeps(r2);
    let theta = inner * (1.0 - f) + outer * f;
    let (st, ct) = (theta.fsin(), theta.fcos());
    [
        (cx + ct * lx3 + st * ly3) * w,
        (cy - st * lx3 + ct * ly3) * w,
        0.0,
    ]
}

/// Derived value: 1/size.
fn prep_checks(v: &mut Prepared) {
    let [_, _, size] = v.params();
    let inv = 1.0 / zeps(size);
    v.p.push(inv);
}

/// Checkerboard: points in light squares (of side `size`) shift by (x, y) plus a random jitter
/// in y, points in dark squares by −(x, y) plus a jitter in x; z is scaled.
#[inline(always)]
fn checks(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ox, oy, _, rnd] = v.params();
    let [inv] = v.derived();
    let jx = rnd * rng.f01();
    let jy = rnd * rng.f01();
    let parity = trunc_i32(lrint(t.x * inv) + lrint(t.y * inv));
    let (dx, dy) = if parity & 1 != 0 {
        (-ox + jx, -oy)
    } else {
        (ox, oy + jy)
    };
    [v.w * (t.x + dx), v.w * (t.y + dy), v.w * t.z]
}

/// Random discs on a grid of spacing 2 inside [−X, X]×[−Y, Y]: a random grid node is picked,
/// kept with probability `density` (by a hash of the node), and a uniform point of a disc of
/// hashed radius around it is returned. Rejected draws give the origin (Fractorium leaves the
/// output unset there).
#[inline(always)]
fn circle_rand_hash(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [nx, ny, size, power, dens, seed] = v.params();
    let (half_x, half_y) = (nx * 0.5, ny * 0.5);
    let a = rng.f01() * TAU;
    let r = rng.f01().sqrt();
    let gx = 2.0 * (floor_i64(rng.f01() * half_x * 2.0 + 0.5) as f64 - half_x);
    let gy = 2.0 * (floor_i64(rng.f01() * half_y * 2.0 + 0.5) as f64 - half_y);
    let ret = if sine_hash(gy, gx, seed) < dens {
        size * r * (sine_hash(gx, gy, seed).ln() * power).exp()
    } else {
        0.0
    };
    if ret > 0.0 {
        let (s, c) = a.fsin_cos();
        [v.w * (c * ret + gx), v.w * (s * ret + gy), 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// Circles on a grid of spacing 2·Sc, present where the lattice noise is below `Dens1`, each of
/// noisy radius: points inside are pulled towards the circle's centre, by a constant factor K
/// or linearly in the distance (which of the two is chosen by `Dens2` and `Reverse`).
#[inline(always)]
fn circle_linear(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sc, k, dens1, dens2, reverse, _, _, seed] = v.params();
    let m = floor_i64(0.5 * t.x / sc) as i32;
    let n = floor_i64(0.5 * t.y / sc) as i32;
    let mx = m.wrapping_mul(2).wrapping_add(1) as f64 * sc;
    let ny = n.wrapping_mul(2).wrapping_add(1) as f64 * sc;
    let (mut x, mut y) = (t.x - mx, t.y - ny);
    let u = zeps((x * x + y * y).sqrt());
    let size = (0.3 + 0.7 * lattice_noise_2d(m.wrapping_add(10), n.wrapping_add(3))) * sc;
    let z1 = lattice_noise_2d(trunc_i32(m as f64 + seed), n);
    if z1 < dens1 && u < size {
        let constant = if reverse > 0.0 {
            z1 < dens1 * dens2
        } else {
            z1 > dens1 * dens2
        };
        let f = if constant {
            k
        } else {
            size / u * (1.0 - k) + k
        };
        x *= f;
        y *= f;
    }
    [v.w * (x + mx), v.w * (y + ny), 0.0]
}

/// Is the grid cell (m, n) of [`circle_rand`]-style layouts empty, or the offset (x, y) from its
/// centre outside the cell's circle?
#[inline(always)]
fn circle_cell_rejects(m: i64, n: i64, x: f64, y: f64, sc: f64, dens: f64, seed: f64) -> bool {
    let u = (x * x + y * y).sqrt();
    lattice_noise_2d(trunc_i32(m as f64 + seed), n as i32) > dens
        || u > (0.3 + 0.7 * lattice_noise_2d(m.wrapping_add(10) as i32, n.wrapping_add(3) as i32))
            * sc
}

/// A random point of one of the circles of the `CircleLinear` layout, within [−X, X]×[−Y, Y]
/// (rejection sampling, at most 11 draws).
#[inline(always)]
fn circle_rand(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    circle_rand_draws(v, rng, 10)
}

/// CircleRand as JWildfire 9.00 computes it (`CircleRandFunc`): the same rejection sampling
/// with at most 101 draws (`maxIter` 100), so that a point outside every circle is all but
/// never plotted.
pub(super) fn circle_rand_jwildfire(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    circle_rand_draws(v, rng, 100)
}

/// CircleRand's sampling: draws until a point lies in a circle or `retries` draws after the
/// first were rejected (the last draw is then kept).
#[inline(always)]
fn circle_rand_draws(v: &Prepared, rng: &mut FastRng, retries: u32) -> V3 {
    let [sc, dens, ax, ay, seed] = v.params();
    let mut tries = 0;
    let (mut m, mut n, mut x, mut y);
    loop {
        x = ax * (1.0 - 2.0 * rng.f01());
        y = ay * (1.0 - 2.0 * rng.f01());
        m = floor_i64(0.5 * x / sc);
        n = floor_i64(0.5 * y / sc);
        x -= m.wrapping_mul(2).wrapping_add(1) as f64 * sc;
        y -= n.wrapping_mul(2).wrapping_add(1) as f64 * sc;
        tries += 1;
        if tries > retries || !circle_cell_rejects(m, n, x, y, sc, dens, seed) {
            break;
        }
    }
    [
        v.w * (x + m.wrapping_mul(2).wrapping_add(1) as f64 * sc),
        v.w * (y + n.wrapping_mul(2).wrapping_add(1) as f64 * sc),
        0.0,
    ]
}

/// The plane halved towards (X, Y); points that land inside a circle of the `CircleLinear`
/// layout are replaced by a random point of a random circle of the layout.
#[inline(always)]
fn circle_trans1(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sc, dens, ax, ay, seed] = v.params();
    let sc = zeps(sc);
    let ux = (t.x - ax) * 0.5 + ax;
    let uy = (t.y - ay) * 0.5 + ay;
    let m = floor_i64(0.5 * ux / sc);
    let n = floor_i64(0.5 * uy / sc);
    let x = ux - m.wrapping_mul(2).wrapping_add(1) as f64 * sc;
    let y = uy - n.wrapping_mul(2).wrapping_add(1) as f64 * sc;
    if circle_cell_rejects(m, n, x, y, sc, dens, seed) {
        return [v.w * ux, v.w * uy, 0.0];
    }
    let mut tries = 0;
    let (mut m, mut n, mut x, mut y);
    loop {
        let px = ax.abs() * (1.0 - 2.0 * rng.f01());
        let py = ay.abs() * (1.0 - 2.0 * rng.f01());
        m = floor_i64(0.5 * px / sc);
        n = floor_i64(0.5 * py / sc);
        let alpha = TAU * rng.f01();
        let u = 0.3 + 0.7 * lattice_noise_2d(m.wrapping_add(10) as i32, n.wrapping_add(3) as i32);
        x = u * alpha.fcos();
        y = u * alpha.fsin();
        tries += 1;
        if tries > 10 || lattice_noise_2d(trunc_i32(m as f64 + seed), n as i32) <= dens {
            break;
        }
    }
    [
        v.w * (x + m.wrapping_mul(2).wrapping_add(1) as f64 * sc),
        v.w * (y + n.wrapping_mul(2).wrapping_add(1) as f64 * sc),
        0.0,
    ]
}

/// Half-width of the cache of cell sites kept by a prepared `crackle`.
const CRACKLE_CACHE: i32 = 10;

/// Sites per row of that cache.
const CRACKLE_CACHE_W: usize = 2 * CRACKLE_CACHE as usize + 1;

/// Index of the first cached site in a prepared `crackle`'s derived values (after the half cell
/// size).
const CRACKLE_SITES: usize = 1;

/// The site of grid cell (i, j): the cell corner displaced by `distort` times two noise values
/// taken at depth z, scaled by the half cell size `s`.
fn crackle_site(i: i32, j: i32, z: f64, s: f64, distort: f64) -> [f64; 2] {
    let (fi, fj) = (i as f64, j as f64);
    let nx = simplex_noise3([fi * 2.5, fj * 2.5, z * 2.5]);
    let ny = simplex_noise3([fj * 2.5 + 30.2, fi * 2.5 - 12.1, z * 2.5 + 19.8]);
    [(fi + distort * nx) * s, (fj + distort * ny) * s]
}

/// Derived values: half cell size, then the sites of the cells within the cache.
pub(super) fn prep_crackle(v: &mut Prepared) {
    let [cell, _, distort, _, z] = v.params();
    let half = zeps(cell.abs() / 2.0);
    v.p.push(half);
    for i in -CRACKLE_CACHE..=CRACKLE_CACHE {
        for j in -CRACKLE_CACHE..=CRACKLE_CACHE {
            let s = crackle_site(i, j, z, half, distort);
            v.p.push(s[0]);
            v.p.push(s[1]);
        }
    }
}

/// The site of cell (i, j), from the cache when it holds it.
#[inline(always)]
fn crackle_site_cached(v: &Prepared, i: i32, j: i32) -> [f64; 2] {
    if i.abs() <= CRACKLE_CACHE && j.abs() <= CRACKLE_CACHE {
        let k = 2 * ((i + CRACKLE_CACHE) as usize * CRACKLE_CACHE_W + (j + CRACKLE_CACHE) as usize);
        let sites = v.table(CRACKLE_SITES);
        [sites[k], sites[k + 1]]
    } else {
        let [_, _, distort, _, z] = v.params();
        let [half] = v.derived();
        crackle_site(i, j, z, half, distort)
    }
}

/// The sites of the 3×3 cells around cell (ci, cj), row by row in i.
#[inline(always)]
fn crackle_block(v: &Prepared, ci: i32, cj: i32) -> [[f64; 2]; 9] {
    let mut out = [[0.0; 2]; 9];
    for (k, o) in out.iter_mut().enumerate() {
        let (di, dj) = (k as i32 / 3 - 1, k as i32 % 3 - 1);
        *o = crackle_site_cached(v, ci + di, cj + dj);
    }
    out
}

/// Crackle: a random point near the origin is moved relative to the site of its Voronoi cell,
/// its distance to the cell's edge (in the Voronoi ratio) raised to `power` and scaled; the
/// input point is not used.
#[inline(always)]
fn crackle(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y, _) = crackle_cell(v, rng);
    [v.w * x, v.w * y, 0.0]
}

/// The crackle map before the weight, with the Voronoi ratio it used.
pub(super) fn crackle_cell(v: &Prepared, rng: &mut FastRng) -> (f64, f64, f64) {
    let [_, power, _, scale] = v.params();
    let [half] = v.derived();
    let blur = (rng.f01() + rng.f01()) / 2.0 + (rng.f01() - 0.5) / 4.0;
    let theta = TAU * rng.f01();
    let u = [blur * theta.fsin(), blur * theta.fcos()];
    let mut ci = floor_i64(u[0] / half) as i32;
    let mut cj = floor_i64(u[1] / half) as i32;
    // Re-centre the 3×3 block on the cell whose site is nearest.
    let sites = crackle_block(v, ci, cj);
    let mut best = (f64::MAX, 0);
    for (k, s) in sites.iter().enumerate() {
        let d2 = sqr(s[0] - u[0]) + sqr(s[1] - u[1]);
        if d2 < best.0 {
            best = (d2, k);
        }
    }
    ci += best.1 as i32 / 3 - 1;
    cj += best.1 as i32 % 3 - 1;
    let sites = crackle_block(v, ci, cj);
    let centre = sites[4];
    // Largest Voronoi ratio of u between the centre site and each neighbour.
    let mut l = f64::MIN;
    for (k, s) in sites.iter().enumerate() {
        if k == 4 {
            continue;
        }
        let (dx, dy) = (s[0] - centre[0], s[1] - centre[1]);
        let ratio = if dx == 0.0 && dy == 0.0 {
            1.0
        } else {
            2.0 * ((u[0] - centre[0]) * dx + (u[1] - centre[1]) * dy) / zeps(dx * dx + dy * dy)
        };
        if ratio > l {
            l = ratio;
        }
    }
    let target = zeps(l).abs().powf(power) * scale;
    let r = target / zeps(l);
    (
        (u[0] - centre[0]) * r + centre[0],
        (u[1] - centre[1]) * r + centre[1],
        l,
    )
}

/// A random point on a segment from the jittered site of the input's unit cell to the site of
/// one of its four neighbours, scaled by the cell size (the weight is not applied).
#[inline(always)]
fn crackle2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [cell] = v.params();
    const SEED: f64 = 34554.0;
    let inv = 1.0 / zeps(cell);
    let site = |x: f64, y: f64| {
        [
            x + inv * sine_hash(x, y, SEED),
            y + inv * sine_hash(y, x * 3.0, SEED + 7.0),
        ]
    };
    let (cx, cy) = (floor_i64(t.x) as f64, floor_i64(t.y) as f64);
    let a = site(cx, cy);
    let (nx, ny) = if rng.f01() < 0.5 {
        if rng.f01() < 0.5 {
            (cx, cy + 1.0)
        } else {
            (cx, cy - 1.0)
        }
    } else if rng.f01() < 0.5 {
        (cx + 1.0, cy)
    } else {
        (cx - 1.0, cy)
    };
    let b = site(nx, ny);
    let f = rng.f01();
    [
        (a[0] + (b[0] - a[0]) * f) * cell,
        (a[1] + (b[1] - a[1]) * f) * cell,
        0.0,
    ]
}

/// Scatters each unit cell of the plane to a pseudo-random point of a polar "dust" pattern
/// (the cell's index modulo `density` picks the angle and radius).
#[inline(always)]
fn dust(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [dens, dist, power] = v.params();
    let dens = zeps(dens);
    let cx = (t.x.abs().floor() % dens) / dens;
    let cy = (t.y.abs().floor() % dens) / dens;
    let hx = sine_hash(cx, cy, 1.0);
    let hy = sine_hash(cy, cx, 2.0);
    let a = (cx + hx * dist) * TAU;
    let r = ((cy + hy * dist).ln() * power).exp();
    let (s, c) = a.fsin_cos();
    [v.w * c * r, v.w * s * r, 0.0]
}

fn gnarly_prepare(v: &mut Prepared) {
    let [cellsize] = v.params();
    let half = 0.5 * cellsize;
    v.p.push(zeps(half * half));
}

/// Cuts the plane into square cells and twists the disc inscribed in each cell by an angle
/// growing with the logarithm of the distance to the cell centre.
#[inline(always)]
fn gnarly(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cell, twist] = v.params();
    let [rr] = v.derived();
    let (mut x, mut y) = (t.x, t.y);
    if cell != 0.0 {
        let cx = (floor_f(x / cell) + 0.5) * cell;
        let cy = (floor_f(y / cell) + 0.5) * cell;
        let lx = x - cx;
        let ly = y - cy;
        let d2 = lx * lx + ly * ly;
        if d2 <= rr {
            let (s, c) = (twist * (d2 / rr).ln()).fsin_cos();
            x = cx + c * lx + s * ly;
            y = cy - s * lx + c * ly;
        }
    }
    [v.w * x, v.w * y, 0.0]
}

/// Pushes each point one unit out of its grid square, towards the square's nearest side
/// (a square spiral away from the origin).
#[inline(always)]
fn gridout(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let gx = lrint(t.x);
    let gy = lrint(t.y);
    let (dx, dy) = if gy <= 0.0 {
        if gx > 0.0 {
            if -gy >= gx { (1.0, 0.0) } else { (0.0, 1.0) }
        } else if gy <= gx {
            (1.0, 0.0)
        } else {
            (0.0, -1.0)
        }
    } else if gx > 0.0 {
        if gy >= gx { (-1.0, 0.0) } else { (0.0, 1.0) }
    } else if gy > -gx {
        (-1.0, 0.0)
    } else {
        (0.0, -1.0)
    };
    [v.w * (t.x + dx), v.w * (t.y + dy), 0.0]
}

fn prep_modulus(v: &mut Prepared) {
    let [size] = v.params();
    let period = 2.0 * size;
    v.p.push(period);
}

/// modulusx / modulusy: wraps one coordinate (shifted by `shift`) into [−size, size); the other
/// coordinate is only scaled.
#[inline(always)]
fn modulus<const AXIS: usize>(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [size, shift] = v.params();
    let [period] = v.derived();
    let (u, other) = if AXIS == 0 { (t.x, t.y) } else { (t.y, t.x) };
    let f = crate::flame::fastmath::fmod(u + size + shift, period);
    let wrapped = if f >= 0.0 {
        v.w * (f - size)
    } else {
        v.w * (f + size)
    };
    if AXIS == 0 {
        [wrapped, v.w * other, 0.0]
    } else {
        [v.w * other, wrapped, 0.0]
    }
}

/// Shreds the plane into parallel strips: each cell of size `distance` along an axis is
/// squeezed to `width` of itself, leaving gaps between the strips; z is scaled.
#[inline(always)]
fn shredlin(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [xdistance, xwidth, ydistance, ywidth] = v.params();
    let [xw, yw, gx, gy] = v.derived();
    let strip = |c: f64, dist: f64, width: f64, gap: f64| {
        let neg = if c < 0.0 { 1.0 } else { 0.0 };
        let u = c / dist;
        let i = trunc_i32(u) as f64;
        (u - i) * width + i + (0.5 - neg) * gap
    };
    [
        xw * strip(t.x, xdistance, xwidth, gx),
        yw * strip(t.y, ydistance, ywidth, gy),
        v.w * t.z,
    ]
}

fn shredlin_prep(v: &mut Prepared) {
    let [xd, xwid, yd, ywid] = v.params();
    v.p.extend([v.w * xd, v.w * yd, 1.0 - xwid, 1.0 - ywid]);
}

/// A bubble-like contraction plus a grid of unit cells, each cell's content halved toward its
/// centre and, three times in four, pushed out toward the nearest cell border.
#[inline(always)]
fn split_brdr(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [bx, by, px, py] = v.params();
    let w = v.w;
    let b = w / (t.sumsq * 0.25 + 1.0);
    let (rx, ry) = (t.x.round_ties_even(), t.y.round_ties_even());
    let (ox, oy) = (t.x - rx, t.y - ry);
    let mut x = t.x * b;
    let mut y = t.y * b;
    if rng.f01() >= 0.75 {
        x += w * (ox * 0.5 + rx);
        y += w * (oy * 0.5 + ry);
    } else if ox.abs() >= oy.abs() {
        if ox >= 0.0 {
            x += w * (ox * 0.5 + rx + bx);
            y += w * (oy * 0.5 + ry + by * oy / zeps(ox));
        } else {
            x += w * (ox * 0.5 + rx - by);
            y += w * (oy * 0.5 + ry - by * oy / zeps(ox));
        }
    } else if oy >= 0.0 {
        y += w * (oy * 0.5 + ry + by);
        x += w * (ox * 0.5 + rx + ox / zeps(oy) * by);
    } else {
        y += w * (oy * 0.5 + ry - by);
        x += w * (ox * 0.5 + rx - ox / zeps(oy) * bx);
    }
    x += t.x * px;
    y += t.y * py;
    [x, y, 0.0]
}

/// A grid of square cells; inside each cell, concentric square rings are rotated by quarter
/// turns according to their level, with hashed per-cell limits and hashed cells left still.
#[inline(always)]
fn squares(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cell, lo, hi, num, seed, zero, zero_seed] = v.params();
    if cell == 0.0 {
        return [t.x * v.w, t.y * v.w, 0.0];
    }
    let cx = (floor_f(t.x / cell) + 0.5) * cell;
    let cy = (floor_f(t.y / cell) + 0.5) * cell;
    let (lx, ly) = (t.x - cx, t.y - cy);
    let ring_x = floor_f(lx * num * 2.0 / cell + 0.5).abs();
    let ring_y = floor_f(ly * num * 2.0 / cell + 0.5).abs();
    let m = ring_x.max(ring_y);
    let (hx, hy) = (cx * cx, cy * cy);
    let top = hi + floor_f(sine_hash(hx, hy, seed) * (num - hi));
    let level = if m > top || m < lo { 0.0 } else { m - lo };
    let angle = if sine_hash(hx, hy, zero_seed) < zero {
        0.0
    } else {
        level * FRAC_PI_2
    };
    let (s, c) = angle.fsin_cos();
    [
        (cx + lx * c - ly * s) * v.w,
        (cy + lx * s + ly * c) * v.w,
        0.0,
    ]
}

/// Checkerboard-shifted spherical sines: sin(p)/r² plus an offset that depends on the colour
/// of the checkerboard square the point falls in, with optional random jitter.
#[inline(always)]
fn sschecks(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ox, oy, _, jitter] = v.params();
    let [inv_size] = v.derived();
    let r = v.w / zeps(t.sumsq);
    let parity = trunc_i32(lrint(t.x * inv_size) + lrint(t.y * inv_size));
    let (dx, dy) = if parity & 1 != 0 {
        (-ox + jitter * rng.f01(), -oy)
    } else {
        (ox, oy + jitter * rng.f01())
    };
    [
        v.w * (t.x.fsin() * r + dx),
        v.w * (t.y.fsin() * r + dy),
        0.0,
    ]
}

fn sschecks_prep(v: &mut Prepared) {
    let [_, _, size] = v.params();
    let inv = 1.0 / zeps(size);
    v.p.push(inv);
}

/// Derived value of tile_hlp: the weighted tile width.
fn tile_hlp_prep(v: &mut Prepared) {
    let [width] = v.params();
    let vw = width * v.w;
    v.p.push(vw);
}

/// tile_hlp: copies the plane and randomly shifts points by one tile width along x, with a
/// probability that fades smoothly across each tile (a soft half-plane tiling).
#[inline(always)]
fn tile_hlp(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [width] = v.params();
    let [width_w] = v.derived();
    let x = t.x / width;
    let pos = x > 0.0;
    let k = trunc_i32(x) as f64;
    let frac = if pos { x - k } else { x + k };
    let shift = if (frac * PI).fcos() < rng.f11() {
        if pos { -width_w } else { width_w }
    } else {
        0.0
    };
    [v.w * t.x + shift, v.w * t.y, 0.0]
}

/// tile_log: copies the plane at integer x offsets drawn from a two-sided, geometrically
/// decaying distribution (`spread` its scale).
#[inline(always)]
fn tile_log(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [spread] = v.params();
    let l = rng.f01().ln();
    let shift = round_half_out(l * if rng.bit() { spread } else { -spread });
    [v.w * (t.x + shift), v.w * t.y, 0.0]
}

/// Voron: Voronoi cells of hashed seed points (1 … `Num` per grid square of side `Step`);
/// each point is pulled toward its cell's seed, keeping the fraction K of its offset.
#[inline(always)]
fn voron(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k, step, num, xseed, yseed] = v.params();
    let m = trunc_i32((t.x / step).floor());
    let n = trunc_i32((t.y / step).floor());
    let mut nearest = 20.0;
    let (mut x0, mut y0) = (0.0, 0.0);
    for i in -1..2 {
        let ci = m.wrapping_add(i);
        for j in -1..2 {
            let cj = n.wrapping_add(j);
            let cell = 19i32.wrapping_mul(ci).wrapping_add(257i32.wrapping_mul(cj));
            let count = 1.0 + (num * lattice_noise(trunc_i32(cell as f64 + xseed))).floor();
            let kx = 64 * ci as i64 + 15 * cj as i64;
            let ky = 21 * ci as i64 + 33 * cj as i64;
            let mut l = 0.0;
            while l < count {
                let li = l as i64;
                let sx = (lattice_noise(trunc_i32((li + kx) as f64 + xseed)) + ci as f64) * step;
                let sy = (lattice_noise(trunc_i32((li + ky) as f64 + yseed)) + cj as f64) * step;
                let r = (sqr(t.x - sx) + sqr(t.y - sy)).sqrt();
                if r < nearest {
                    nearest = r;
                    x0 = sx;
                    y0 = sy;
                }
                l += 1.0;
            }
        }
    }
    [
        v.w * (k * (t.x - x0) + x0),
        v.w * (k * (t.y - y0) + y0),
        0.0,
    ]
}
