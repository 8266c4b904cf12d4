//! JWildfire's random octree stamps, `glsl_randomoctree` and `dc_randomoctree` (Jesus Sosa's
//! ports of a shader flying through a randomly subdivided octree of coloured cubes): a ray
//! from a camera moving with the time is marched cell by cell, each cell empty, split into
//! eight or solid by a hash of its corner and size; the first solid cell's colour, shaded by
//! the face hit and darkened (or lightened) at its borders, is the pixel's.
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `GLSLRandomOctreeFunc` and
//! `DC_RandomOctreeFunc`, written anew. Their `Seed` sets the time from a generator (or the
//! clock) in JWildfire's editor only: a flame stores the time, which is what is used here.

use std::f64::consts::PI;

use super::jwf_c_glsl::{GLSL_RES_Y, GlslIndex, glsl_frame};
use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail};
use super::util::jwf_math as jm;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("glsl_randomoctree", glsl_randomoctree)
        .params(&[
            p_int("glsl_randomoctree_Density Pixels", 1e6, 100.0, 1e7),
            p_int(
                "glsl_randomoctree_Seed",
                10000.0,
                -2147483648.0,
                2147483647.0,
            ),
            p("glsl_randomoctree_time", 0.0),
            // JWildfire's bound: 3 to 100 cells marched.
            p_int("glsl_randomoctree_Steps", 10.0, 3.0, 100.0),
            p_range("glsl_randomoctree_Rot. L-R", 0.0, 0.0, 1.0),
            p_range("glsl_randomoctree_Rot. U-D", 0.0, 0.0, 1.0),
            p_int("glsl_randomoctree_Grid", 0.0, 0.0, 1.0),
            p_int("glsl_randomoctree_Borders", 1.0, 0.0, 1.0),
            p_int("glsl_randomoctree_Black Borders", 1.0, 0.0, 1.0),
            p_int("glsl_randomoctree_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR),
    VarDef::new("dc_randomoctree", dc_randomoctree)
        .params(P_DC_RANDOMOCTREE)
        .flags(DC_FLAGS),
];

const P_DC_RANDOMOCTREE: &[Param] = &{
    let tail = dc_tail!("dc_randomoctree");
    [
        p_int("dc_randomoctree_seed", 10000.0, -2147483648.0, 2147483647.0),
        p("dc_randomoctree_time", 0.0),
        // JWildfire's bound: 3 to 100 cells marched.
        p_int("dc_randomoctree_steps", 10.0, 3.0, 100.0),
        p("dc_randomoctree_rotLR", 0.0),
        p("dc_randomoctree_rotUD", 0.0),
        p_int("dc_randomoctree_grid", 0.0, 0.0, 1.0),
        p_int("dc_randomoctree_borders", 1.0, 0.0, 1.0),
        p_int("dc_randomoctree_bBorders", 1.0, 0.0, 1.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

type V = [f64; 3];

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn mul(a: V, b: V) -> V {
    [a[0] * b[0], a[1] * b[1], a[2] * b[2]]
}
fn scale(a: V, s: f64) -> V {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn fract(x: f64) -> f64 {
    x - x.floor()
}
/// GLSL's sign.
fn sign(x: f64) -> f64 {
    if x == 0.0 || x.is_nan() {
        x
    } else {
        x.signum()
    }
}

/// The octree's cells at most this many levels below the unit cells.
const DETAIL: i32 = 5;

/// A cell's state from a hash of its corner `p` and size: 0 empty (half of them, and every
/// cell on the z axis), 1 split in eight (45 %), 2 solid.
fn voxel_state(p: V, size: f64) -> i32 {
    if p[0] == 0.0 && p[1] == 0.0 {
        return 0;
    }
    let d = p[0] * 13.46 + p[1] * 41.74 + p[2] * -73.36 + size * 14.24;
    let val = fract(4e4 * jm::sin(d + 17.34));
    if val < 0.5 {
        0
    } else if val < 0.95 {
        1
    } else {
        2
    }
}

/// The settings of the octree flight: time, cells marched, camera turn (mouse position in
/// [0, 1]² and the scale that tells whether it is near the corner), grid, borders, black
/// borders.
struct Octree {
    time: f64,
    steps: f64,
    mouse: (f64, f64),
    mouse_scale: (f64, f64),
    grid: bool,
    borders: bool,
    black: bool,
}

/// The colour of the octree seen along the view direction (uv, 1).
fn octree_rgb(o: &Octree, uv: (f64, f64)) -> V {
    let mut size = 1.0f64;
    let ro = [
        0.5 + jm::sin(o.time) * 0.4,
        0.5 + jm::cos(o.time) * 0.4,
        o.time,
    ];
    let n = jm::sqrt(uv.0 * uv.0 + uv.1 * uv.1 + 1.0);
    let mut rd = [uv.0 / n, uv.1 / n, 1.0 / n];
    let (mx, my) = o.mouse;
    let (mxs, mys) = (mx * o.mouse_scale.0, my * o.mouse_scale.1);
    if jm::sqrt(mxs * mxs + mys * mys) > 40.0 {
        let (s, c) = (jm::sin(my * PI - PI / 2.0), jm::cos(my * PI - PI / 2.0));
        rd = [rd[0], c * rd[1] + s * rd[2], -s * rd[1] + c * rd[2]];
        let (s, c) = (jm::sin(2.0 * mx * PI - PI), jm::cos(2.0 * mx * PI - PI));
        rd = [c * rd[0] + s * rd[2], rd[1], -s * rd[0] + c * rd[2]];
    }
    let sgn = rd.map(sign);
    let mut lro = ro.map(|x| x - size * (x / size).floor());
    let mut fro = sub(ro, lro);
    let ird = rd.map(|x| 1.0 / x.abs().max(0.001));
    let mut mask = [0.0; 3];
    let mut exit = false;
    let mut depth = 0;
    let mut dist = 0.0;
    let mut edge = 1.0f64;
    let mut last = [0.0; 3];
    // At most 100 cells (the parameter's bound).
    for _ in 0..(o.steps as i32).clamp(0, 100) {
        if dist > 6.0 {
            break;
        }
        let state = voxel_state(fro, size);
        if exit {
            let nf = fro.map(|x| (x / (size / 0.5) + 0.25).floor() * size * 2.0);
            lro = add(lro, sub(fro, nf));
            fro = nf;
            depth -= 1;
            size *= 2.0;
            let v0 = fro.map(|x| {
                let a = x / size + 0.5;
                a - 2.0 * (a / 2.0).floor()
            });
            let v1 = add(v0.map(|x| x - 1.0), scale(mul(mask, sgn), 0.5));
            exit = depth > 0 && dot(v1, mask).abs() < 0.1;
        } else if state == 1 && depth <= DETAIL {
            depth += 1;
            size *= 0.5;
            let m2 = lro.map(|x| if x < size { 0.0 } else { 1.0 });
            fro = add(fro, scale(m2, size));
            lro = sub(lro, scale(m2, size));
        } else {
            let h = size * 0.5;
            let hit: V = std::array::from_fn(|k| -(sgn[k] * (lro[k] - h) - h) * ird[k]);
            mask = if hit[0] < hit[1].min(hit[2]) {
                [1.0, 0.0, 0.0]
            } else if hit[1] < hit[2] {
                [0.0, 1.0, 0.0]
            } else {
                [0.0, 0.0, 1.0]
            };
            let len = dot(hit, mask);
            if state == 2 {
                break;
            }
            dist += len;
            let step = scale(mul(mask, sgn), size);
            lro = sub(add(lro, scale(rd, len)), step);
            fro = add(fro, step);
            // JWildfire compares two new vectors by reference here: always unequal.
            exit = depth > 0;
            last = mask;
        }
        if o.grid {
            let q: V = std::array::from_fn(|k| (lro[k] / size - 0.5).abs() * (1.0 - last[k]));
            edge = edge.min(-(q[0].max(q[1]).max(q[2]) - 0.5) * 80.0 * size);
        }
    }
    let color: V = if dist < 6.0 {
        let val = fract(dot(fro, [15.23, 754.345, 3.454]));
        let normal: V = std::array::from_fn(|k| -(last[k] * sgn[k]));
        let base = [39.896, 57.3225, 48.25];
        let mut c: V = std::array::from_fn(|k| {
            (jm::sin(base[k] * val) * 0.5 + 0.5) * (normal[k] * 0.25 + 0.75)
        });
        if o.borders {
            let q: V = std::array::from_fn(|k| (lro[k] / size - 0.5).abs() * (1.0 - last[k]));
            edge = (-(q[0].max(q[1]).max(q[2]) - 0.5) * 20.0 * size)
                .max(0.0)
                .min(edge);
        }
        if o.black {
            c = scale(c, edge);
        } else {
            c = c.map(|x| 1.0 - (1.0 - x) * edge);
        }
        c
    } else if o.black {
        [edge; 3]
    } else {
        [1.0 - edge; 3]
    };
    color.map(jm::sqrt)
}

/// glsl_randomoctree: the octree seen through the pixel, on the glsl_ frame (view directions
/// over [−1, 1]²).
fn glsl_randomoctree(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, steps, lr, ud, grid, borders, black, gradient] = v.params();
    let o = Octree {
        time,
        steps,
        mouse: (lr, ud),
        mouse_scale: (res, GLSL_RES_Y),
        grid: grid == 1.0,
        borders: borders == 1.0,
        black: black == 1.0,
    };
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let uv = (
            2.0 * (i + 0.5) / res - 1.0,
            2.0 * (j + 0.5) / GLSL_RES_Y - 1.0,
        );
        octree_rgb(&o, uv)
    })
}

/// dc_randomoctree: the octree seen along the point's direction (view directions over
/// [−½, ½]²); the camera turn is rotLR and rotUD mod 1.
fn dc_randomoctree(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, steps, lr, ud, grid, borders, black, tail @ ..] = v.params::<13>();
    let o = Octree {
        time,
        steps,
        mouse: (lr % 1.0, ud % 1.0),
        mouse_scale: (1000.0, 1000.0),
        grid: grid == 1.0,
        borders: borders == 1.0,
        black: black == 1.0,
    };
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| octree_rgb(&o, (x, y)))
}
