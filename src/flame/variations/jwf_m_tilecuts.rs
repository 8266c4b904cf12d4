//! JWildfire's cuts along tilings (Jesus Sosa's ports of shader patterns; see `jwf_a_cuts`
//! for how a cut keeps or hides a point): `cut_hextruchetflow` (Truchet arcs on a hexagonal
//! grid, optionally with the grid), `cut_truchetweaving` (Truchet tiles of arcs and beams on a
//! hexagonal grid, woven over and under), `cut_randomtile` (Shane's random tiles of quarter
//! rings), `cut_tstruchet` (Shane's multi-scale Truchet tiles of arcs, over three levels of
//! subdivision) and `cut_triantess` (knighty's tessellation by the triangle group (p, q, r):
//! spherical, Euclidean or hyperbolic in the Poincaré disc).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew.

use std::f64::consts::PI;

use super::jwf_a_cuts::{CUT, cut_end, cut_point};
use super::jwf_direct_colour::gmod;
use super::jwf_m_cuts::{length, seed_first_prepare};
use super::util::{fract, signum_java, smoothstep};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("cut_hextruchetflow", cut_hextruchetflow)
        .params(&[
            p_int("cut_hextruchetflow_randomize", 0.0, NEG_INF, INF),
            p_int("cut_hextruchetflow_mode", 1.0, 0.0, 1.0),
            p_int("cut_hextruchetflow_grid", 0.0, 0.0, 1.0),
            p_range("cut_hextruchetflow_zoom", 10.0, 0.1, 50.0),
            p_int("cut_hextruchetflow_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_truchetweaving", cut_truchetweaving)
        .params(&[
            p_int("cut_truchetweaving_randomize", 0.0, NEG_INF, INF),
            p_int("cut_truchetweaving_mode", 1.0, 0.0, 1.0),
            p_int("cut_truchetweaving_type", 0.0, 0.0, 1.0),
            p_range("cut_truchetweaving_width", 0.15, 0.0, 0.25),
            p_range("cut_truchetweaving_zoom", 8.0, 0.1, 50.0),
            p_int("cut_truchetweaving_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_randomtile", cut_randomtile)
        .params(&[
            p_int("cut_randomtile_seed", 1000.0, NEG_INF, INF),
            p_int("cut_randomtile_mode", 1.0, 0.0, 1.0),
            p("cut_randomtile_zoom", 5.0),
            p_int("cut_randomtile_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(seed_first_prepare),
    VarDef::new("cut_tstruchet", cut_tstruchet)
        .params(&[
            p_int("cut_tstruchet_seed", 1000.0, NEG_INF, INF),
            p_int("cut_tstruchet_mode", 1.0, 0.0, 1.0),
            p_int("cut_tstruchet_shape", 0.0, 0.0, 3.0),
            p_int("cut_tstruchet_levels", 0.0, 0.0, 1.0),
            p_int("cut_tstruchet_arcs", 0.0, 0.0, 1.0),
            p("cut_tstruchet_zoom", 5.0),
            p_int("cut_tstruchet_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(seed_first_prepare),
    VarDef::new("cut_triantess", cut_triantess)
        .params(&[
            p_int("cut_triantess_mode", 1.0, 0.0, 1.0),
            p_int("cut_triantess_Iters", 20.0, 0.0, 20.0),
            p_range("cut_triantess_SRadius", 0.01, 0.001, 0.1),
            p_int("cut_triantess_pParam", 3.0, 1.0, 12.0),
            p_int("cut_triantess_qParam", 3.0, 1.0, 12.0),
            p_int("cut_triantess_rParam", 4.0, 1.0, 12.0),
            p_range("cut_triantess_uBaryc", 1.0, 0.0, 1.0),
            p_range("cut_triantess_vBaryc", 1.0, 0.0, 1.0),
            p_range("cut_triantess_wBaryc", 0.0, 0.0, 1.0),
            p("cut_triantess_zoom", 2.0),
            p_int("cut_triantess_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(triantess_prepare),
];

/// The shaders' rounded 2π (two ways), and √½.
#[allow(clippy::approx_constant)]
const SHADER_TAU: f64 = 6.28;
#[allow(clippy::approx_constant)]
const SHADER_TAU_3: f64 = 6.283;
#[allow(clippy::approx_constant)]
const SHADER_SQRT_HALF: f64 = 0.7071;

/// The shader's rounded √3.
#[allow(clippy::approx_constant)]
const SQRT3_5: f64 = 1.73205;

/// The hexagon (axial coordinates) holding (x, y): cube coordinates rounded, the coordinate
/// rounded farthest fixed up.
fn pix_to_hex(x: f64, y: f64) -> (f64, f64) {
    let cx = (1.0 / SQRT3_5) * x - (1.0 / 3.0) * y;
    let cz = (2.0 / 3.0) * y;
    let c = [cx, -cx - cz, cz];
    let r = c.map(|v| (v + 0.5).floor());
    let d = [0, 1, 2].map(|k| (r[k] - c[k]).abs());
    let sum = r[0] + r[1] + r[2];
    let step = |lim: f64, v: f64| if v < lim { 0.0 } else { 1.0 };
    let fix = |k: usize| r[k] - step(d[(k + 1) % 3], d[k]) * step(d[(k + 2) % 3], d[k]) * sum;
    (fix(0), fix(2))
}

/// The hexagonal Truchet arcs (and the grid lines with `grid`) at (x, y): 1 on them.
fn hex_truchet(x: f64, y: f64, grid: bool) -> f64 {
    let (hx, hy) = pix_to_hex(x, y);
    let (pcx, pcy) = (SQRT3_5 * (hx + 0.5 * hy), 1.5 * hy);
    let hash = fract((hx * 37.0 + hy * 39.0).sin() * 43758.54);
    let dir = 2.0 * if 0.5 < hash { 0.0 } else { 1.0 } - 1.0;
    let dist2 = |qx: f64, qy: f64| (qx - x) * (qx - x) + (qy - y) * (qy - y);
    let mut best = dist2(pcx, pcy - dir);
    for qx in [pcx + SQRT3_5 / 2.0, pcx - SQRT3_5 / 2.0] {
        let d = dist2(qx, pcy + 0.5 * dir);
        if d < best {
            best = d;
        }
    }
    let arc = (best.sqrt() - 0.5).abs();
    let mut col = 0.0;
    if grid {
        let (ex, ey) = ((x - pcx).abs(), (y - pcy).abs());
        let d = (SQRT3_5 / 2.0) - ex + 0.5 * (ex - SQRT3_5 * ey).min(0.0);
        let t = smoothstep(0.01, 0.02, d);
        col = 1.0 * (1.0 - t) + smoothstep(1.0, 1.0, d) * t;
    }
    if arc < 0.25 { 1.0 } else { col }
}

/// cut_hextruchetflow: cuts along hexagonal Truchet arcs (a uniform point of [−½, ½]² with
/// `mode` 1), shifted by randomize·sin(randomize·180/π).
fn cut_hextruchetflow(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [seed, mode, grid, zoom, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let shift = seed * (seed * 180.0 / PI).sin();
    let col = hex_truchet(x * zoom - shift, y * zoom - shift, grid == 1.0);
    cut_end(v, acc, col > 0.9, invert, (x, y), c)
}

/// The shader's rounded constants of the hexagonal weave.
#[allow(clippy::approx_constant)]
mod weave {
    pub const I3: f64 = 0.333333333;
    pub const I6: f64 = 0.166666666;
    pub const R3: f64 = 1.732050807;
    pub const IR3: f64 = 0.577350269;
    pub const HIR3: f64 = 0.288675134;
    pub const S60: f64 = 0.866025404;
    pub const C60: f64 = 0.5;
}

/// GLSL's mix as the shader port computes it: x·(1 − a) + y·a.
fn gmix(x: f64, y: f64, a: f64) -> f64 {
    x * (1.0 - a) + y * a
}

/// A strand's (mask, alpha) at distance `d` from its centre line, of `thickness`.
fn strand(d: f64, thickness: f64, circle: bool) -> (f64, f64) {
    let t = thickness / 2.0;
    let mask = smoothstep(t + 0.01, t, d.abs());
    let alpha = smoothstep(t + 0.1, t, d.abs());
    let alpha = if circle {
        alpha * alpha * gmix(0.5, 1.0, mask)
    } else {
        alpha * alpha * (0.5 + 0.5 * mask)
    };
    (mask, alpha)
}

/// An arc of `radius` about (cx, cy).
fn weave_arc((x, y): (f64, f64), (cx, cy): (f64, f64), radius: f64, w: f64) -> (f64, f64) {
    strand(radius - length(x - cx, y - cy), w, true)
}

/// The mask of the woven Truchet tile `n` at (x, y) of the unit cell.
fn weave_tile(x: f64, y: f64, n: f64, w: f64) -> f64 {
    use weave::*;
    let (x, y) = ((x - 0.5) / R3, y - 0.5);
    let r = (fract(n * 5.0) * 6.0).floor() / 6.0 * SHADER_TAU;
    let (s, c) = (r.sin(), r.cos());
    let uv = (c * x - s * y, s * x + c * y);
    let beam = |(_, y): (f64, f64)| strand(y, w, false);
    let (v1, v2, v3) = if n < 0.1 {
        (
            weave_arc(uv, (0.0, I3), I6, w),
            weave_arc(uv, (HIR3, -I6), I6, w),
            weave_arc(uv, (-HIR3, -I6), I6, w),
        )
    } else if n < 0.2 {
        (
            weave_arc(uv, (0.0, I3), I6, w),
            weave_arc(uv, (0.0, -I3), I6, w),
            beam(uv),
        )
    } else if n < 0.4 {
        (
            weave_arc(uv, (-HIR3, -I6), I6, w),
            weave_arc(uv, (IR3, 0.0), 0.5, w),
            weave_arc(uv, (HIR3, 0.5), 0.5, w),
        )
    } else if n < 0.8 {
        (
            weave_arc(uv, (IR3, 0.0), 0.5, w),
            weave_arc(uv, (-IR3, 0.0), 0.5, w),
            beam(uv),
        )
    } else {
        let (ux, uy) = uv;
        (
            beam(uv),
            beam((C60 * ux - S60 * uy, S60 * ux + C60 * uy)),
            beam((C60 * ux + S60 * uy, -S60 * ux + C60 * uy)),
        )
    };
    // Which strand lies on top: over (a) the mix of the other two (b over c).
    let over =
        |a: (f64, f64), b: (f64, f64), c: (f64, f64)| gmix(a.0, gmix(b.0, c.0, c.1), b.1.max(c.1));
    let d1 = fract(n * 10.0);
    if d1 < 0.166 {
        over(v1, v2, v3)
    } else if d1 < 0.333 {
        over(v1, v3, v2)
    } else if d1 < 0.5 {
        over(v2, v1, v3)
    } else if d1 < 0.666 {
        over(v2, v3, v1)
    } else if d1 < 0.833 {
        over(v3, v1, v2)
    } else {
        over(v3, v2, v1)
    }
}

/// cut_truchetweaving: cuts along woven Truchet strands (a uniform point of [−½, ½]² with
/// `mode` 1; `type` 1 varies the strands' width), shifted by
/// randomize·sin(randomize·180/π).
fn cut_truchetweaving(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    use weave::R3;
    let [seed, mode, kind, width, zoom, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let shift = seed * (seed * 180.0 / PI).sin();
    let (ux, uy) = (x * zoom - shift, y * zoom - shift);
    let w = if kind == 1.0 {
        gmix(
            0.05,
            0.25,
            ((ux + uy.sin()).sin() + (uy * 0.35).sin()) * 0.25 + 0.5,
        )
    } else {
        width
    };
    let (ax, ay) = (gmod(ux, 1.0) * 2.0 - 1.0, gmod(uy, R3) * 2.0 - R3);
    let (bx, by) = (
        gmod(ux + 0.5, 1.0) * 2.0 - 1.0,
        gmod(uy + R3 * 0.5, R3) * 2.0 - R3,
    );
    let (mut sx, mut sy) = (ux / 1.0, uy / R3);
    let (ix, iy) = if ax * ax + ay * ay < bx * bx + by * by {
        (sx.floor(), sy.floor())
    } else {
        sx += 0.5;
        sy += 0.5;
        (sx.floor() - 0.5, sy.floor() - 0.5)
    };
    let n = fract((ix * 324.23 + iy * 5604.342).sin() * 87654.53);
    let col = weave_tile(fract(sx), fract(sy), n, w);
    cut_end(v, acc, col > 0.0, invert, (x, y), c)
}

/// The distance to the rings of a random tile (each cell turned by a random quarter turn),
/// less the rings' half width.
fn random_tile_distance(x: f64, y: f64) -> f64 {
    let hash = |x: f64, y: f64| fract((x * 127.183 + y * 157.927).sin() * 43758.5453);
    let (ix, iy) = (x.floor(), y.floor());
    let (px, py) = (x - (ix + 0.5), y - (iy + 0.5));
    let rnd = hash(ix, iy);
    let rnd2 = hash(ix + 27.93, iy + 27.93);
    #[allow(clippy::approx_constant)]
    let a = (rnd * 4.0).floor() * 3.14159 / 2.0;
    let (s, c) = (a.sin(), a.cos());
    let (px, py) = (c * px - s * py, s * px + c * py);
    let l = length(px + 0.5, py - 0.5);
    let (d1, d2) = ((l - 0.25).abs(), (l - 0.5).abs());
    let d3 = if rnd2 > 0.33 {
        (length(px - 0.125, py - 0.5) - 0.125).abs()
    } else {
        (l - 0.75).abs()
    };
    let mut d = d1.min(d2).min(d3);
    let d2 = (length(px - 0.5, py - 0.125) - 0.125).abs();
    let d3 = (length(px - 0.5, py + 0.5) - 0.25).abs();
    d = d.min(1e5f64.min(d2.min(d3)));
    let l = length(px + 0.5, py + 0.5);
    d = d.max(-(l - 0.75));
    let d1 = (l - 0.5).abs();
    d = d.min(d1.min((d1 - 0.25).abs()));
    d - 0.0625
}

/// cut_randomtile: cuts along random tiles of quarter rings (`zoom` tiles per unit).
fn cut_randomtile(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, zoom, invert] = v.params();
    let [x0, y0] = v.derived();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let d = random_tile_distance(x * zoom + x0, y * zoom + y0);
    let ink = 1.0 - smoothstep(0.0, 5.0 / 1000.0, d + 0.025);
    cut_end(v, acc, ink.max(0.0).sqrt() > 0.0, invert, (x, y), c)
}

/// The "radius" of (x, y) for `shape`: 0 a circle, 1 an octagon, 2 a dodecagon, 3 a
/// hexadecagon.
fn shape_dist(x: f64, y: f64, shape: f64) -> f64 {
    if shape == 0.0 {
        return length(x, y);
    }
    let (x, y) = (x.abs(), y.abs());
    let octagon = |x: f64, y: f64| x.max(y).max((x + y) * SHADER_SQRT_HALF);
    if shape == 1.0 {
        octagon(x, y)
    } else if shape == 2.0 {
        let (x2, y2) = (x * 0.8660254 + y * 0.5, y * 0.8660254 + x * 0.5);
        x2.max(y2).max(x.max(y))
    } else {
        #[allow(clippy::approx_constant)]
        let (s, c) = (3.14159f64 / 8.0).sin_cos();
        octagon(c * x - s * y, s * x + c * y).max(octagon(x, y))
    }
}

/// The distance field of the multi-scale Truchet tiling at (x, y) and the cell size's
/// reciprocal it was found at.
fn tstruchet_field(x: f64, y: f64, shape: f64, levels: f64, arcs: f64) -> (f64, f64) {
    let hash = |x: f64, y: f64| {
        let n = (x * 57.0 + y * 27.0).sin();
        (fract(262144.0 * n), fract(32768.0 * n))
    };
    // JWildfire's thresholds (its second and third levels always subdivide no further).
    let th = [if levels == 1.0 { 0.5 } else { 0.35 }, 1.0, 1.0];
    let dist = |x: f64, y: f64| shape_dist(x, y, shape);
    let mut dim = 2.0;
    let mut d = 1e5;
    for (k, &th) in th.iter().enumerate() {
        let (ix, iy) = ((x * dim).floor(), (y * dim).floor());
        let (rx, ry) = hash(ix, iy);
        if rx < th {
            let (px, mut py) = (x - (ix + 0.5) / dim, y - (iy + 0.5) / dim);
            let kk = (k * 57 + 1) as f64;
            let ry = fract(ry * 27.63 + kk);
            if ry >= 0.5 {
                py = -py;
            }
            let (h, aw) = (0.5 / dim, 0.5 / 3.0 / dim);
            let c1 = (dist(px - h, py - h) - h).abs() - aw;
            let c2 = if arcs != 1.0 && fract(ry * 57.53 + 0.47) < 0.35 {
                (dist(px + h, py) - aw).min(dist(px, py + h) - aw)
            } else {
                (dist(px + h, py + h) - h).abs() - aw
            };
            d = c1.min(c2);
            if k == 1 {
                d = -d;
            }
            if k < 2 {
                d = d.min(dist(px.abs() - h, py.abs() - h) - aw);
            }
            d -= 0.01;
            break;
        }
        dim *= 2.0;
    }
    (d, dim)
}

/// cut_tstruchet: cuts along multi-scale Truchet arcs (`zoom` tiles per unit; `shape` the
/// arcs' curve, `levels` 1 for more large tiles, `arcs` 1 for arcs only).
fn cut_tstruchet(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, shape, levels, arcs, zoom, invert] = v.params();
    let [x0, y0] = v.derived();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let (d, dim) = tstruchet_field(x * zoom + x0, y * zoom + y0, shape, levels, arcs);
    let fo = 10.0 / 1e3 / dim.sqrt();
    let sh = (0.75 - d * 10.0).max(0.0)
        * (((-(d * SHADER_TAU_3 * 18.0).sin()) + 0.75).clamp(-0.25, 1.0) + 0.25);
    let a = 1.0 - smoothstep(0.0, fo, d + 0.015);
    let b = 1.0 - smoothstep(0.0, fo, (d + 0.1).max(-(d + 0.14)));
    let col = gmix(gmix(0.0, sh, a), 0.0, b);
    cut_end(v, acc, col > 0.30, invert, (x, y), c)
}

/// The triangle group's geometry: the space's curvature sign, the mirrors' normals b and c
/// (a is x = 0) and the vertex p the lines are drawn to (from the barycentric u, v, w).
fn triantess_prepare(v: &mut Prepared) {
    let [_, _, _, pp, qq, rr, u, vv, w] = v.params();
    let st = signum_java(qq * rr + pp * rr + pp * qq - pp * qq * rr);
    let (cp, sp) = ((PI / pp).cos(), (PI / pp).sin());
    let cq = (PI / qq).cos();
    let (cr, sr) = ((PI / rr).cos(), (PI / rr).sin());
    let k = (cq + cp * cr) / sp;
    let nb = [-cp, sp, 0.0];
    let mut nc = [-cr, -k, ((k + sr) * (-k + sr)).abs().sqrt()];
    if st == 0.0 {
        nc[2] = 0.25;
    }
    let pa = [nb[1] * nc[2], -nb[0] * nc[2], nb[0] * nc[1] - nb[1] * nc[0]];
    let pb = [0.0, nc[2], -nc[1]];
    let pc = [0.0, 0.0, nb[1]];
    let q: [f64; 3] = [0, 1, 2].map(|i| pa[i] * u + pb[i] * vv + pc[i] * w);
    let l = 1.0 / hdot_t(st, q, q).abs().sqrt();
    let p = q.map(|c| c * l);
    v.p.push(st);
    v.p.extend_from_slice(&nb);
    v.p.extend_from_slice(&nc);
    v.p.extend_from_slice(&p);
}

/// The "time-like" product of the space of curvature sign `st`.
fn hdot_t(st: f64, a: [f64; 3], b: [f64; 3]) -> f64 {
    (a[0] * b[0] + a[1] * b[1]) * st + a[2] * b[2]
}

/// The "space-like" product.
fn hdot_s(st: f64, a: [f64; 3], b: [f64; 3]) -> f64 {
    (a[0] * b[0] + a[1] * b[1]) + st * a[2] * b[2]
}

/// The distance from z to the segment from p along the mirror of normal n.
fn triantess_segment(
    st: f64,
    z: [f64; 3],
    p: [f64; 3],
    n: [f64; 3],
    (r, radius): (f64, f64),
) -> f64 {
    let (vx, vy) = (hdot_t(st, z, p), hdot_s(st, z, n));
    let (vx, vy) = (vx - hdot_t(st, p, n) * vy, -hdot_s(st, p, n) * vx + vy);
    let vy = vy.min(0.0);
    let m: [f64; 3] = [0, 1, 2].map(|i| p[i] * vx + n[i] * vy);
    let l = 1.0 / hdot_t(st, m, m).abs().sqrt();
    let m = m.map(|c| c * l);
    let diff = [0, 1, 2].map(|i| m[i] - z[i]);
    let sum = [0, 1, 2].map(|i| m[i] + z[i]);
    let tha = hdot_s(st, diff, diff).abs().sqrt() / hdot_t(st, sum, sum).abs().sqrt();
    let tha = (tha - radius) / (1.0 + st * tha * radius);
    tha * (1.0 + st * r * r) / (1.0 + st * st * r * tha)
}

/// The tessellation's ink at (x, y): 0 on its lines, 1 elsewhere.
fn triantess_color(v: &Prepared, x: f64, y: f64) -> f64 {
    let [_, iters, radius] = v.params();
    let d = v.table(0);
    let st = d[0];
    let (nb, nc, p) = ([d[1], d[2], d[3]], [d[4], d[5], d[6]], [d[7], d[8], d[9]]);
    let r = length(x, y);
    if st == -1.0 && r >= 1.0 {
        return 1.0;
    }
    let k = 1.0 / (1.0 + st * r * r);
    let mut z = [2.0 * x * k, 2.0 * y * k, (1.0 - st * r * r) * k];
    let reflect = |z: &mut [f64; 3], n: [f64; 3]| {
        let t = -2.0 * (n[0] * z[0] + n[1] * z[1] + n[2] * z[2]).min(0.0);
        z[0] += n[0] * t;
        z[1] += n[1] * t;
        z[2] += n[2] * st * t;
    };
    for _ in 0..iters as i32 {
        z[0] = z[0].abs();
        reflect(&mut z, nb);
        reflect(&mut z, nc);
    }
    let nc_s = [nc[0], nc[1], nc[2] * st];
    let ds = [[1.0, 0.0, 0.0], nb, nc_s]
        .map(|n| triantess_segment(st, z, p, n, (r, radius)))
        .into_iter()
        .fold(f64::INFINITY, f64::min);
    let mut color = gmix(0.0, 1.0, smoothstep(-1.0, 1.0, ds * 0.5 / 0.0005));
    if st == -1.0 {
        color = gmix(1.0, color, smoothstep(0.0, 1.0, (1.0 - r) * 0.5 / 0.0005));
    }
    color
}

/// cut_triantess: cuts along the lines of a triangle group's tessellation (a uniform point
/// of [−½, ½]² with `mode` 1).
fn cut_triantess(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, _, _, _, _, _, _, _, _, zoom, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let color = triantess_color(v, x * zoom, y * zoom);
    cut_end(v, acc, color > 0.0, invert, (x, y), c)
}
