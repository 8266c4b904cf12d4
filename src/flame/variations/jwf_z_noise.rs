//! JWildfire's noise-driven variations, from the end of its alphabet: `camouflage` (the
//! point turned, moved and lifted by steps of a fractal value, Perlin or cellular noise
//! quantised into `levels` bands, each band its own colour) and the shader pattern
//! `truchetflow` (Jesus Sosa after a Shadertoy sketch: flowing bands on random Truchet
//! tiles, kept or cut out) and `kaplan` (Jesus Sosa after Craig Kaplan's Shadertoy: the
//! rounding error of |p|²'s mantissa on an N × N grid, kept or cut out).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew; the gradient noise is Ken Perlin's "improved noise" (2002) with his
//! reference permutation.

use std::f64::consts::PI;

use super::util::{fract, signum_java, smoothstep};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("camouflage", camouflage)
        .params(&[
            p("camouflage_seed", 1000.0),
            p("camouflage_scale", 2.0),
            p_range("camouflage_noiseType", 0.0, 0.0, 2.0),
            p_range("camouflage_levels", 4.0, 1.0, INF),
            p_range("camouflage_octaves", 5.0, 1.0, 64.0).limited(),
            p("camouflage_persistence", 0.5),
            p("camouflage_lacunarity", 2.0),
            p("camouflage_stretch", 1.0),
            p("camouflage_rotation", 0.5),
            p("camouflage_displacement", 0.1),
            p("camouflage_zOffset", 0.1),
            p("camouflage_colorize", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_Z | flag::USES_Z | flag::SETS_COLOR),
    VarDef::new("truchetflow", truchetflow)
        .params(&[
            p_int("truchetflow_randomize", 0.0, NEG_INF, INF),
            p_range("truchetflow_zoom", 5.0, 0.1, 50.0),
            p_int("truchetflow_invert", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::HIDES | flag::WRITES_ACC),
    VarDef::new("kaplan", kaplan)
        .params(&[
            p_int("kaplan_seed", 1000.0, NEG_INF, INF),
            p_int("kaplan_N", 800.0, 50.0, 1500.0),
            p("kaplan_time", 10.0),
            p_int("kaplan_invert", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::HIDES | flag::WRITES_ACC),
];

/// Ken Perlin's reference permutation of 0–255.
const PERM: [u8; 256] = [
    151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69,
    142, 8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219,
    203, 117, 35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175,
    74, 165, 71, 134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230,
    220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76,
    132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173,
    186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206,
    59, 227, 47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163,
    70, 221, 153, 101, 155, 167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232,
    178, 185, 112, 104, 218, 246, 97, 228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162,
    241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192, 214, 31, 181, 199, 106, 157, 184, 84, 204,
    176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93, 222, 114, 67, 29, 24, 72, 243, 141,
    128, 195, 78, 66, 215, 61, 156, 180,
];

fn perm(i: i32) -> i32 {
    PERM[(i & 255) as usize] as i32
}

/// A lattice value in about [−1, 1] for (x, y, z): a multiplicative hash in wrapping 32-bit
/// arithmetic.
fn lattice(x: i32, y: i32, z: i32) -> f64 {
    let mut h = x
        .wrapping_mul(374_761_393)
        .wrapping_add(y.wrapping_mul(668_265_263))
        .wrapping_add(z.wrapping_mul(1_103_515_245));
    h = (h ^ (h >> 13)).wrapping_mul(1_274_126_177);
    h ^= h >> 16;
    (h & 0x7fff_ffff) as f64 / 1073741823.5 - 1.0
}

fn lerp(a: f64, b: f64, t: f64) -> f64 {
    a + t * (b - a)
}

/// Value noise: [`lattice`] values blended with the cubic smoothstep.
fn value_noise(x: f64, y: f64, z: f64) -> f64 {
    let (ix, iy, iz) = (x.floor() as i32, y.floor() as i32, z.floor() as i32);
    let s = |f: f64| f * f * (3.0 - 2.0 * f);
    let (u, v, w) = (s(x - ix as f64), s(y - iy as f64), s(z - iz as f64));
    let n = |dx: i32, dy: i32, dz: i32| {
        lattice(
            ix.wrapping_add(dx),
            iy.wrapping_add(dy),
            iz.wrapping_add(dz),
        )
    };
    let x00 = lerp(n(0, 0, 0), n(1, 0, 0), u);
    let x10 = lerp(n(0, 1, 0), n(1, 1, 0), u);
    let x01 = lerp(n(0, 0, 1), n(1, 0, 1), u);
    let x11 = lerp(n(0, 1, 1), n(1, 1, 1), u);
    lerp(lerp(x00, x10, v), lerp(x01, x11, v), w)
}

/// Cellular noise: twice the distance to the nearest of the feature points of the 27
/// neighbouring cells, less 1.
fn cellular_noise(x: f64, y: f64, z: f64) -> f64 {
    let (ix, iy, iz) = (x.floor() as i32, y.floor() as i32, z.floor() as i32);
    let mut best = f64::MAX;
    for dz in -1..=1 {
        for dy in -1..=1 {
            for dx in -1..=1 {
                let (cx, cy, cz) = (
                    ix.wrapping_add(dx),
                    iy.wrapping_add(dy),
                    iz.wrapping_add(dz),
                );
                let px = cx as f64 + 0.5 * (1.0 + lattice(cx, cy, cz));
                let py = cy as f64 + 0.5 * (1.0 + lattice(cy, cz, cx));
                let pz = cz as f64 + 0.5 * (1.0 + lattice(cz, cx, cy));
                best = best.min((x - px).powi(2) + (y - py).powi(2) + (z - pz).powi(2));
            }
        }
    }
    best.sqrt() * 2.0 - 1.0
}

/// Perlin's gradient of hash `h` at the offset (x, y, z).
fn grad(h: i32, x: f64, y: f64, z: f64) -> f64 {
    let h = h & 15;
    let u = if h < 8 { x } else { y };
    let v = if h < 4 {
        y
    } else if h == 12 || h == 14 {
        x
    } else {
        z
    };
    (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
}

/// Ken Perlin's improved noise, as JWildfire writes it: its blends pass the factor as the
/// first end point of [`lerp`] (so the result is not Perlin's smooth noise but its own).
fn perlin_noise(x: f64, y: f64, z: f64) -> f64 {
    let (xi, yi, zi) = (
        x.floor() as i32 & 255,
        y.floor() as i32 & 255,
        z.floor() as i32 & 255,
    );
    let (x, y, z) = (x - x.floor(), y - y.floor(), z - z.floor());
    let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let (u, v, w) = (fade(x), fade(y), fade(z));
    let a = perm(xi) + yi;
    let (aa, ab) = (perm(a) + zi, perm(a + 1) + zi);
    let b = perm(xi + 1) + yi;
    let (ba, bb) = (perm(b) + zi, perm(b + 1) + zi);
    // JWildfire passes the blend factor first to a lerp(a, b, t): kept as it draws.
    lerp(
        w,
        lerp(
            v,
            lerp(u, grad(perm(aa), x, y, z), grad(perm(ba), x - 1.0, y, z)),
            lerp(
                u,
                grad(perm(ab), x, y - 1.0, z),
                grad(perm(bb), x - 1.0, y - 1.0, z),
            ),
        ),
        lerp(
            v,
            lerp(
                u,
                grad(perm(aa + 1), x, y, z - 1.0),
                grad(perm(ba + 1), x - 1.0, y, z - 1.0),
            ),
            lerp(
                u,
                grad(perm(ab + 1), x, y - 1.0, z - 1.0),
                grad(perm(bb + 1), x - 1.0, y - 1.0, z - 1.0),
            ),
        ),
    )
}

/// camouflage: `octaves` of the chosen noise (0 value, 1 Perlin, 2 cellular) at the scaled,
/// y-stretched point, quantised into steps of 1/levels; the step k turns the point by
/// k·2π·rotation/levels, moves it by k·displacement/levels and lifts it by k·zOffset/levels;
/// with `colorize` the colour is k modulo levels over levels.
fn camouflage(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [
        seed,
        scale,
        kind,
        levels,
        octaves,
        persistence,
        lacunarity,
        stretch,
        rotation,
        displ,
        z_off,
        colorize,
    ] = v.params();
    let (kind, levels, octaves) = (kind.trunc(), levels.trunc(), octaves.trunc());
    let (x, y, z) = (t.x * scale, t.y * scale * stretch, t.z * scale);
    let (mut sum, mut freq, mut amp) = (0.0, 1.0, 1.0);
    for _ in 0..octaves as i64 {
        let n = match kind as i64 {
            1 => perlin_noise(x * freq + seed, y * freq + seed, z * freq + seed),
            2 => cellular_noise(x * freq + seed, y * freq + seed, z * freq + seed),
            _ => value_noise(x * freq, y * freq, z * freq + seed),
        };
        sum += n * amp;
        freq *= lacunarity;
        amp *= persistence;
    }
    let k = (sum * levels).floor();
    if colorize > 0.5 {
        acc.color = ((k % levels + levels) % levels) / levels;
    }
    let angle = k * PI * 2.0 * rotation / levels;
    let mag = k * displ / levels;
    let (s, c) = angle.sin_cos();
    let nx = t.x * c - t.y * s + mag;
    let ny = t.x * s + t.y * c + mag;
    [(nx - t.x) * v.w, (ny - t.y) * v.w, k * z_off / levels * v.w]
}

/// The Shadertoy hash of a tile: fract of the product of the coordinates after two mixing
/// steps.
fn n21(x: f64, y: f64) -> f64 {
    let (px, py) = (fract(x * 234.234), fract(y * 823.923));
    let d = px * (px + 42.34) + py * (py + 42.34);
    fract((px + d) * (py + d))
}

/// truchetflow: a uniform point of the unit square (centred) is kept where the pattern of
/// triple bands on quarter circles (random Truchet tiles, `zoom` per unit, shifted by
/// `randomize`) is dark, else hidden at −(½, ½)·weight (`invert` swaps them); replaces the
/// sum so far.
fn truchetflow(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [seed, zoom, invert] = v.params();
    let (x, y) = (rng.f01(), rng.f01());
    let shift = seed * (seed * 180.0 / PI).sin();
    let (ux, uy) = ((x - 0.5) * zoom - shift, (y - 0.5) * zoom - shift);
    let (mut gx, gy) = (fract(ux) - 0.5, fract(uy) - 0.5);
    let n = n21(ux.floor(), uy.floor());
    let band = -0.03 + (0.5 * y).powf(1.5);
    let width = 0.01 + 0.1 * x;
    if n > 0.5 {
        gx = -gx;
    }
    let s = 0.5 * signum_java(gx + gy + 0.001);
    let mut d = ((gx - s).powi(2) + (gy - s).powi(2)).sqrt() - 0.5;
    d = d.abs();
    for _ in 0..3 {
        d = (d - band).abs();
    }
    d = d.abs() - width;
    let fuzzy = 0.01 + 0.2 * ((x - 0.5).abs() + (y - 0.5).abs()).powf(2.0);
    let col = smoothstep(fuzzy, 0.0, d);
    let hide = if invert == 0.0 { col > 0.0 } else { col <= 0.0 };
    let (x, y) = if hide { (0.0, 0.0) } else { (x, y) };
    acc.hide = hide;
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [v.w * (x - 0.5), v.w * (y - 0.5), 0.0]
}

/// kaplan: a random node (i, j) of an N × N grid over the unit square (centred) is kept
/// where the sign of the rounding error of the mantissa of |p|² at 16 bits is not positive,
/// p being the node's offset from the centre times ⌊time⌋, turned by atan of its own ratio
/// (`invert` swaps kept and hidden; hidden nodes sit at −(½, ½)·weight); replaces the sum.
fn kaplan(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, n, time, invert] = v.params();
    let i = (n * rng.f01()).trunc();
    let j = (n * rng.f01()).trunc();
    let zoom = time.floor();
    let (xv, yv) = (zoom * (i - n / 2.0), zoom * (j - n / 2.0));
    let (s, c) = (xv / yv).atan().sin_cos();
    let (ux, uy) = (c * xv - s * yv, s * xv + c * yv);
    let value = ux * ux + uy * uy;
    let exponent = (value.ln() / 2f64.ln()).floor();
    let mantissa = value * 2f64.powf(-exponent) - 1.0;
    let scale = 2f64.powf(16.0);
    let r = mantissa - (mantissa * scale + 0.5).floor() / scale;
    let col = signum_java(r);
    let hide = if invert == 0.0 { col > 0.0 } else { col <= 0.0 };
    let (i, j) = if hide { (0.0, 0.0) } else { (i, j) };
    acc.hide = hide;
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [v.w * (i / n - 0.5), v.w * (j / n - 0.5), 0.0]
}
