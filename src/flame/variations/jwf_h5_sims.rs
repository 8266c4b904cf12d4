//! JWildfire's simulations: `truchet_ae` (an iterated function system of four half-size maps
//! whose colour follows Truchet tiles, after Apophysis' truchet_ae by Eralex) and `dla_wf` (a
//! diffusion-limited aggregate grown once on a square grid from `seed`, of which each call
//! returns a random particle).
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `TruchetAEFunc` and `DLAWFFunc`, written
//! anew. The aggregate is grown with JWildfire's Marsaglia generator seeded as JWildfire seeds
//! it, so a seed gives JWildfire's aggregate.

use std::f64::consts::PI;

use super::util::{Mwc, lattice_noise};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("truchet_ae", truchet_ae)
        .params(&[
            p_int("truchet_ae_seed", 0.0, -2147483648.0, 2147483647.0),
            p("truchet_ae_step", 0.5),
            p("truchet_ae_width", 0.25),
            p("truchet_ae_angle", 0.0),
            p_int("truchet_ae_layout", 0.0, 0.0, 4.0),
            p_int("truchet_ae_style", 0.0, 0.0, 5.0),
            p("truchet_ae_K01A", 0.5),
            p("truchet_ae_K02A", 0.5),
            p("truchet_ae_K01B", 0.5),
            p("truchet_ae_K02B", 0.5),
            p("truchet_ae_K11A", 0.5),
            p("truchet_ae_K12A", 0.5),
            p("truchet_ae_K11B", 0.5),
            p("truchet_ae_K12B", 0.5),
            p("truchet_ae_K21A", 0.5),
            p("truchet_ae_K22A", 0.5),
            p("truchet_ae_K21B", 0.5),
            p("truchet_ae_K22B", 0.5),
            p("truchet_ae_K31A", 0.5),
            p("truchet_ae_K32A", 0.5),
            p("truchet_ae_K31B", 0.5),
            p("truchet_ae_K32B", 0.5),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::STATEFUL | flag::SETS_COLOR)
        .prepare(truchet_ae_prepare),
    VarDef::new("dla_wf", dla_wf)
        .params(&[
            // The grid is buffer_size² cells: at most 4000 (16 MB).
            p_int("dla_wf_buffer_size", 800.0, 0.0, 4000.0),
            // At most a million particles.
            p_int("dla_wf_max_iter", 6000.0, 0.0, 1_000_000.0),
            p_int("dla_wf_seed", 666.0, -2147483648.0, 2147483647.0),
            p("dla_wf_scale", 10.0),
            p_range("dla_wf_jitter", 0.01, 0.01, f64::MAX),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0, 1, 2, 3, 4], dla_points),
];

/// √3 / 2.
const SQ3_2: f64 = 0.866_025_403_784_438_6;

/// Derived: sin and cos of angle·π.
fn truchet_ae_prepare(v: &mut Prepared) {
    let [_, _, _, angle] = v.params();
    let (s, c) = (angle * PI).sin_cos();
    v.p.extend_from_slice(&[s, c]);
}

/// JWildfire's fmod2: the remainder of a / b, moved into [0, b) for b > 0.
fn fmod2(a: f64, b: f64) -> f64 {
    let r = a % b;
    if r < 0.0 && b > 0.0 { r + b } else { r }
}

/// Whether (u, v) lies in a tile's ring of circles about two corners (style 2/3's quarter
/// circles), `diag` choosing the corners (0,0)–(1,1) or (1,0)–(0,1).
fn truchet_ring(u: f64, v: f64, width: f64, diag: bool) -> bool {
    let d = |a: f64, b: f64| (a * a + b * b).sqrt();
    let c = if diag {
        d(u - 1.0, v - 1.0).min(d(u, v))
    } else {
        d(u - 1.0, v).min(d(u, v - 1.0))
    };
    ((c - 0.5).abs() - 0.5).abs() - 0.5 * (1.0 - width) < 0.0
}

/// Whether the point (u, v) of a tile with random value `chance` takes the first colour.
fn truchet_first(style: f64, u: f64, v: f64, width: f64, chance: f64, (m, n): (i32, i32)) -> bool {
    let square = (u - 0.5).abs().max((v - 0.5).abs()) - 0.5 * (1.0 - width);
    let sq = square < 0.0;
    match style as i32 {
        1 => {
            let side = if chance < 0.25 {
                u > v
            } else if chance < 0.5 {
                u > 1.0 - v
            } else if chance < 0.75 {
                u < v
            } else {
                u < 1.0 - v
            };
            sq ^ side
        }
        2 => truchet_ring(u, v, width, chance < 0.5),
        3 => {
            if chance < 0.333333 {
                truchet_ring(u, v, width, true)
            } else if chance < 0.666666 {
                truchet_ring(u, v, width, false)
            } else {
                0.5 * width - (u - 0.5).abs().min((v - 0.5).abs()) < 0.0
            }
        }
        4 => {
            let side = if chance < 0.125 {
                u > v
            } else if chance < 0.25 {
                u > 1.0 - v
            } else if chance < 0.375 {
                u < v
            } else if chance < 0.5 {
                u < 1.0 - v
            } else if chance < 0.625 {
                u < 0.5
            } else if chance < 0.75 {
                v < 0.5
            } else if chance < 0.875 {
                u > 0.5
            } else {
                v > 0.5
            };
            sq ^ side
        }
        5 => {
            let inv = (m % 2 == 0) ^ (n % 2 == 0);
            let d = |a: f64, b: f64| (a * a + b * b).sqrt();
            let (near, far) = if chance < 0.5 {
                let c = d(u - 1.0, v - 1.0).min(d(u, v));
                (c, c.min(d(u - 1.0, v)).min(d(u, v - 1.0)))
            } else {
                let c = d(u - 1.0, v).min(d(u, v - 1.0));
                (c, c.min(d(u - 1.0, v - 1.0)).min(d(u, v)))
            };
            let hit = (near.abs() - 0.5 < 0.0) ^ (far.abs() - width < 0.0) ^ inv;
            if chance < 0.5 { hit } else { !hit }
        }
        _ => {
            if chance > 0.5 {
                (v < u + 1.0 - width && v > u + width) || (v < u - width && v > u - 1.0 + width)
            } else {
                (v < -u + 1.0 - width && v > -u + width)
                    || (v > -u + 1.0 + width && v < -u + 2.0 - width)
            }
        }
    }
}

/// truchet_ae: one step of the chaos game of four half-size maps (the layout: asymmetric or
/// symmetrised square, Sierpiński 45°, chair, equilateral triangle) on the variation's own
/// point, whatever the input; the new point is added unweighted. Two colours follow the maps
/// (`K..A`, `K..B`: c ↦ k·c + k' mod 1), and the Truchet tile of side `step` (turned by
/// angle·π, chosen by a lattice hash of the tile and `seed`, drawn in `style`) under the point
/// picks one of them as its colour. State: the point and the two colours.
fn truchet_ae(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [seed, step, width, _, layout, style] = v.params();
    let k = &v.p[6..22];
    let [sinang, cosang] = v.derived();
    let (x, y) = (v.state.get(0), v.state.get(1));
    let (z1, z2) = (v.state.get(2), v.state.get(3));
    let i = ((4.0 * rng.f01()).floor() as usize).min(3);
    let (u1, v1) = match (layout as i32, i) {
        (1, 0) => (-x * 0.5 + 1.0, y * 0.5 + 1.0),
        (1, 1) => (x * 0.5 - 1.0, y * 0.5 + 1.0),
        (1, 2) => (-x * 0.5 + 1.0, -y * 0.5 - 1.0),
        (1, _) => (x * 0.5 - 1.0, -y * 0.5 - 1.0),
        (2, 0) => (x * 0.5 + 1.0, y * 0.5 + 1.0),
        (2, 1) => (x * 0.5 - 1.0, y * 0.5 - 1.0),
        (2, 2) => (x * 0.5 - 1.0, y * 0.5 + 1.0),
        (2, _) => (-x * 0.5 - 1.0, -y * 0.5 + 1.0),
        (3, 0) => (x * 0.5, y * 0.5),
        (3, 1) => (x * 0.5 - 1.0, y * 0.5 + 1.0),
        (3, 2) => (-y * 0.5 - 1.0, x * 0.5 - 1.0),
        (3, _) => (y * 0.5 + 1.0, -x * 0.5 + 1.0),
        (4, 0) => (x * 0.5 + 1.0, y * 0.5 + SQ3_2),
        (4, 1) => (x * 0.5 - 1.0, y * 0.5 + SQ3_2),
        (4, 2) => (x * 0.5, y * 0.5 - SQ3_2),
        (4, _) => (x * 0.5, -y * 0.5 + SQ3_2),
        (_, 0) => {
            let j = y * 0.5 + 1.0 + 0.7;
            (x * 0.5 + 1.0, if j > 2.0 { j - 2.0 } else { j })
        }
        (_, 1) => (x * 0.5 - 1.0, y * 0.5 + 1.0),
        (_, 2) => (x * 0.5 + 1.0, y * 0.5 - 1.0),
        (_, _) => (x * 0.5 - 1.0, y * 0.5 - 1.0),
    };
    // The third map's second colour wraps at ½.
    let z1 = fmod2(k[4 * i] * z1 + k[4 * i + 1], 1.0);
    let z2 = fmod2(
        k[4 * i + 2] * z2 + k[4 * i + 3],
        if i == 2 { 0.5 } else { 1.0 },
    );
    let uu = cosang * u1 - sinang * v1;
    let vv = sinang * u1 + cosang * v1;
    let m = (uu / step).floor() as i32;
    let n = (vv / step).floor() as i32;
    let u = uu / step - f64::from(m);
    let w = vv / step - f64::from(n);
    let chance = lattice_noise(m.wrapping_add(n.wrapping_mul(34)).wrapping_add(seed as i32));
    let z = if truchet_first(style, u, w, width, chance, (m, n)) {
        z1
    } else {
        z2
    };
    v.state.set(0, u1);
    v.state.set(1, v1);
    v.state.set(2, z);
    v.state.set(3, z);
    acc.color = z;
    [u1, v1, 0.0]
}

/// Most steps of random walk `dla_points` takes in all (about a second's work): an aggregate
/// of hostile parameters stops growing there.
const DLA_MAX_STEPS: u64 = 400_000_000;

/// The particles of dla_wf's aggregate as (x, y) pairs: JWildfire's growth of `max_iter`
/// particles on a buffer_size² grid (each released on a circle just outside the aggregate,
/// walking until it touches it or strays beyond a larger circle, then released again), each
/// particle then placed on the grid scaled to `scale` and moved by `jitter` (at most 1) in a
/// random direction.
fn dla_points(p: &[f64], _texts: &[String]) -> Vec<f64> {
    let [size, max_iter, seed, scale, jitter] = params_of(p);
    let size = size as i64;
    if size < 3 {
        return Vec::new();
    }
    let n = size as usize;
    let centre = size / 2;
    let inner = size - 2;
    let mut q = vec![false; n * n];
    let at = |i: i64, j: i64| i as usize * n + j as usize;
    q[at(centre, centre)] = true;
    let mut rnd = Mwc::new(seed as i64);
    let (mut r1, mut r2) = (3.0f64, 9.0f64);
    let mut steps = 0u64;
    let mut placed = 0.0;
    'grow: while placed < max_iter {
        let phi = 2.0 * PI * rnd.next_f64();
        let mut ci = centre + (r1 * phi.cos() + 0.5) as i64;
        let mut cj = centre + (r1 * phi.sin() + 0.5) as i64;
        loop {
            steps += 1;
            if steps > DLA_MAX_STEPS {
                break 'grow;
            }
            match (rnd.next_f64() * 4.0) as i32 {
                0 => ci += 1,
                1 => cj -= 1,
                2 => ci -= 1,
                _ => cj += 1,
            }
            if !(1..=inner).contains(&ci) || !(1..=inner).contains(&cj) {
                // Strayed off the grid: release another.
                continue 'grow;
            }
            let touching =
                q[at(ci - 1, cj)] || q[at(ci + 1, cj)] || q[at(ci, cj - 1)] || q[at(ci, cj + 1)];
            let (di, dj) = ((ci - centre) as f64, (cj - centre) as f64);
            let r3 = (di * di + dj * dj).sqrt();
            if touching {
                q[at(ci, cj)] = true;
                if r3 > r1 {
                    r1 = r3;
                    r2 = 2.1 * r1;
                }
                placed += 1.0;
                continue 'grow;
            }
            if r3 > r2 {
                continue 'grow;
            }
        }
    }
    let radius = jitter.clamp(0.0, 1.0);
    let mut jit = Mwc::new(seed as i64);
    let half = (size / 2) as f64;
    let mut out = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let a = if radius > 1e-8 { jit.next_f64() } else { 0.0 };
            if !q[i * n + j] {
                continue;
            }
            let mut x = (i as f64 - half) / size as f64 * scale;
            let mut y = (j as f64 - half) / size as f64 * scale;
            if radius > 1e-8 {
                let (s, c) = (a * 2.0 * PI).sin_cos();
                x += radius * c;
                y += radius * s;
            }
            out.extend_from_slice(&[x, y]);
        }
    }
    out
}

/// dla_wf: a random particle of the aggregate, weighted (the origin when it is empty).
fn dla_wf(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let pts = v.data();
    let count = pts.len() / 2;
    if count == 0 {
        return [0.0; 3];
    }
    let i = ((rng.f01() * count as f64) as usize).min(count - 1);
    [v.w * pts[2 * i], v.w * pts[2 * i + 1], 0.0]
}
