//! More of JWildfire's direct-colour stamps (Jesus Sosa's `dc_*` shader ports), which scatter
//! points over the square [−½, ½]² (or take the input with `ColorOnly`) and colour them by a
//! pattern: `dc_starsfield` (layers of glowing stars), `dc_voronoise` (Inigo Quilez's
//! blend of cell noise and value noise), `dc_menger` (a Sierpinski carpet), `dc_booleans`
//! (hues from x XOR/AND/OR y), `dc_glypho` (rings of blobs) and `dc_moebiuslog` (a grid seen
//! through a Möbius map and a logarithmic spiral).
//!
//! They share `jwf_direct_colour`'s common part (the palette index is the pattern colour's
//! luminance; see there). The patterns follow JWildfire's (LGPL-2.1) code, written anew.

use super::jwf_a_cuts::{glypho_pattern, seed_offset};
use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail};
use super::util::{atan2_approx, fract, smoothstep};
use super::*;

const DC_STARSFIELD_TAIL: [Param; 5] = dc_tail!("dc_starsfield");
const DC_VORONOISE_TAIL: [Param; 5] = dc_tail!("dc_voronoise");
const DC_MENGER_TAIL: [Param; 5] = dc_tail!("dc_menger");
const DC_BOOLEANS_TAIL: [Param; 5] = dc_tail!("dc_booleans");
const DC_GLYPHO_TAIL: [Param; 5] = dc_tail!("dc_glypho");
const DC_MOEBIUSLOG_TAIL: [Param; 5] = dc_tail!("dc_moebiuslog");

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("dc_starsfield", dc_starsfield)
        .params(&[
            p_int("dc_starsfield_seed", 10000.0, NEG_INF, INF),
            p("dc_starsfield_time", 0.0),
            p_range("dc_starsfield_zdistance", 2.0, 2.0, 150.0),
            p_range("dc_starsfield_glow", 1.0, 0.0, 1.0),
            DC_STARSFIELD_TAIL[0],
            DC_STARSFIELD_TAIL[1],
            DC_STARSFIELD_TAIL[2],
            DC_STARSFIELD_TAIL[3],
            DC_STARSFIELD_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_voronoise", dc_voronoise)
        .params(&[
            p("dc_voronoise_zoom", 8.0),
            p_range("dc_voronoise_deltaX", 0.5, 0.0, 1.0),
            p_range("dc_voronoise_deltaY", 0.5, 0.0, 1.0),
            DC_VORONOISE_TAIL[0],
            DC_VORONOISE_TAIL[1],
            DC_VORONOISE_TAIL[2],
            DC_VORONOISE_TAIL[3],
            DC_VORONOISE_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_menger", dc_menger)
        .params(&[
            p("dc_menger_zoom", 1.0),
            p_int("dc_menger_level", 3.0, 1.0, 5.0),
            DC_MENGER_TAIL[0],
            DC_MENGER_TAIL[1],
            DC_MENGER_TAIL[2],
            DC_MENGER_TAIL[3],
            DC_MENGER_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_booleans", dc_booleans)
        .params(&[
            p_int("dc_booleans_randomize", 1000.0, NEG_INF, INF),
            p_int("dc_booleans_type", 1.0, 0.0, 2.0),
            p("dc_booleans_zoom", 1000.0),
            DC_BOOLEANS_TAIL[0],
            DC_BOOLEANS_TAIL[1],
            DC_BOOLEANS_TAIL[2],
            DC_BOOLEANS_TAIL[3],
            DC_BOOLEANS_TAIL[4],
        ])
        .flags(DC_FLAGS)
        .prepare(dc_booleans_prepare),
    VarDef::new("dc_glypho", dc_glypho)
        .params(&[
            p_range("dc_glypho_zoom", 7.0, 0.1, 50.0),
            p_range("dc_glypho_seed", 10000.0, 0.0, 10000.0),
            p("dc_glypho_time", 0.0),
            p("dc_glypho_f1", 0.115),
            p("dc_glypho_f2", 0.75),
            p("dc_glypho_f3", 1.5),
            DC_GLYPHO_TAIL[0],
            DC_GLYPHO_TAIL[1],
            DC_GLYPHO_TAIL[2],
            DC_GLYPHO_TAIL[3],
            DC_GLYPHO_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_moebiuslog", dc_moebiuslog)
        .params(&[
            p_range("dc_moebiuslog_zoom", 7.0, 0.1, 50.0),
            p_range("dc_moebiuslog_seed", 10000.0, 0.0, 10000.0),
            p("dc_moebiuslog_time", 0.0),
            p_int("dc_moebiuslog_Log", 1.0, 0.0, 1.0),
            p_int("dc_moebiuslog_Moebius", 1.0, 0.0, 1.0),
            p_range("dc_moebiuslog_scale", 5.0, 1.0, 10.0),
            p_range("dc_moebiuslog_angle", 5.0, 1.0, 10.0),
            DC_MOEBIUSLOG_TAIL[0],
            DC_MOEBIUSLOG_TAIL[1],
            DC_MOEBIUSLOG_TAIL[2],
            DC_MOEBIUSLOG_TAIL[3],
            DC_MOEBIUSLOG_TAIL[4],
        ])
        .flags(DC_FLAGS),
];

/// (x, y)·R(a) for GLSL's row-vector product with the rotation matrix mat2(c, s, −s, c).
pub(super) fn rot(x: f64, y: f64, a: f64) -> (f64, f64) {
    let (s, c) = a.sin_cos();
    (c * x + s * y, -s * x + c * y)
}

/// The shader's 2π to 3 digits.
#[allow(clippy::approx_constant)]
const SHADER_TAU: f64 = 6.28;

/// The stars' one-to-one hash.
fn hash11(p: f64) -> f64 {
    let p = fract(p * 35.35);
    let p = p + p * (p + 45.85);
    fract(p * 7858.58)
}

/// The stars' two-to-one hash.
fn hash21(x: f64, y: f64) -> f64 {
    let (px, py) = (fract(x * 451.45), fract(y * 231.95));
    let d = px * (px + 78.78) + py * (py + 78.78);
    fract((px + d) * (py + d))
}

/// The stars' two-to-two hash.
fn hash22(x: f64, y: f64) -> (f64, f64) {
    let q = [fract(x * 451.45), fract(y * 231.95), fract(x * 7878.5)];
    let d = q[0] * (q[0] + 78.78) + q[1] * (q[1] + 78.78) + q[2] * (q[2] + 78.78);
    let q = q.map(|c| c + d);
    (fract(q[0] * q[1]), fract(q[2] * q[1]))
}

/// One layer of stars: a star per unit cell of 5·uv, jittered, glowing as 1/d.
fn star_layer(x: f64, y: f64, zdistance: f64) -> f64 {
    let (ux, uy) = (x * 5.0, y * 5.0);
    let (ix, iy) = (ux.floor(), uy.floor());
    let (fx, fy) = (fract(ux) * zdistance - 1.0, fract(uy) * zdistance - 1.0);
    let (hx, hy) = hash22(ix, iy);
    let (dx, dy) = (fx - hx * 0.3, fy - hy * 0.3);
    let d = (dx * dx + dy * dy).sqrt();
    let c = smoothstep(0.1 + 0.8 * hash21(ix, iy), 0.01, d);
    c * (1.0 / d) * 0.2
}

/// dc_starsfield's grey level at (x, y): eleven rotated, zooming layers of stars (the loop
/// steps 0.1 to below 1 in floating point, as JWildfire's does) plus a glow hash.
pub(super) fn starsfield_grey(x: f64, y: f64, time: f64, zdistance: f64, glow: f64) -> f64 {
    let (mut ux, mut uy) = rot(x, y, time);
    ux += time.cos() * 2.0;
    uy += time.sin() * 2.0;
    let mut col = 0.0;
    let mut i = 0.0;
    while i < 1.0 {
        (ux, uy) = rot(ux, uy, hash11(i) * SHADER_TAU);
        let t = fract(i - time);
        let s = smoothstep(0.0, 1.0, t);
        let f = smoothstep(0.0, 1.0, t) * smoothstep(1.0, 0.0, t);
        let (kx, ky) = hash22(i, i * 5.0);
        let l = star_layer((ux - kx * 0.1) * s, (uy - ky * 0.1) * s, zdistance);
        col += l * f;
        i += 0.1;
    }
    col + glow * hash21(ux + time, uy + time)
}

/// dc_starsfield: a field of stars seen in flight.
fn dc_starsfield(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, zdistance, glow, t0, t1, t2, t3, t4] = v.params();
    dc_common(v, [t0, t1, t2, t3, t4], t, acc, rng, 0.5, |x, y| {
        let g = starsfield_grey(x, y, time, zdistance, glow);
        [g, g, g]
    })
}

/// Inigo Quilez's voronoise at (x, y): cell points jittered by `u`, blended from cell noise
/// (v = 0) to value noise (v = 1) over the 5 × 5 neighbouring cells.
fn iq_noise(x: f64, y: f64, u: f64, v: f64) -> f64 {
    let (px, py) = (x.floor(), y.floor());
    let (fx, fy) = (fract(x), fract(y));
    let k = 1.0 + 63.0 * (1.0 - v).powf(4.0);
    let (mut va, mut wt) = (0.0, 0.0);
    for j in -2..=2 {
        for i in -2..=2 {
            let (gx, gy) = (i as f64, j as f64);
            let (cx, cy) = (px + gx, py + gy);
            let h = |a: f64, b: f64| fract((cx * a + cy * b).sin() * 43758.5453);
            let (ox, oy, oz) = (h(127.1, 311.7) * u, h(269.5, 183.3) * u, h(419.2, 371.9));
            let (rx, ry) = (gx - fx + ox, gy - fy + oy);
            let d = rx * rx + ry * ry;
            let ww = (1.0 - smoothstep(0.0, 1.414, d.sqrt())).powf(k);
            va += oz * ww;
            wt += ww;
        }
    }
    va / wt
}

/// dc_voronoise: grey voronoise at zoom `zoom`.
fn dc_voronoise(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, dx, dy, t0, t1, t2, t3, t4] = v.params();
    dc_common(v, [t0, t1, t2, t3, t4], t, acc, rng, 0.5, |x, y| {
        let n = iq_noise(x * zoom, y * zoom, dx, dy);
        [n, n, n]
    })
}

/// Distance to a square of half-side 1 (negative inside).
fn sd_unit_box(x: f64, y: f64) -> f64 {
    let (px, py) = (x.abs() - 1.0, y.abs() - 1.0);
    (px.max(0.0).powi(2) + py.max(0.0).powi(2)).sqrt() + px.max(py).min(0.0)
}

/// Distance to a Sierpinski carpet of `level` levels on the square [−1, 1]².
fn sierpinski_carpet(x: f64, y: f64, level: f64) -> f64 {
    let mut d = sd_unit_box(x, y);
    let mut s = 1.0;
    for _ in 0..level as i32 {
        let gm = |c: f64| c * s - 2.0 * (c * s / 2.0).floor() - 1.0;
        let (rx, ry) = (1.0 - gm(x).abs() * 3.0, 1.0 - gm(y).abs() * 3.0);
        s *= 3.0;
        let c = (rx.abs().min(ry.abs()) - 1.0) / s;
        d = d.max(c);
    }
    d
}

/// dc_menger: a white Sierpinski carpet on black.
fn dc_menger(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, level, t0, t1, t2, t3, t4] = v.params();
    dc_common(v, [t0, t1, t2, t3, t4], t, acc, rng, 0.5, |x, y| {
        let d = sierpinski_carpet(x * zoom * 1.3, y * zoom * 1.3, level);
        let c = if d > 0.0 { 0.0 } else { 1.0 };
        [c, c, c]
    })
}

fn dc_booleans_prepare(v: &mut Prepared) {
    let [seed] = v.params();
    seed_offset(v, seed);
}

/// The shader idiom hsv2rgb for saturation 1: the pure hue h scaled by the value `val`.
fn hue_rgb(h: f64, val: f64) -> [f64; 3] {
    let k = [1.0, 2.0 / 3.0, 1.0 / 3.0];
    k.map(|kk| ((fract(h + kk) * 6.0 - 3.0).abs() - 1.0).clamp(0.0, 1.0) * val)
}

/// dc_booleans: the hue sin(b) at value cos(b) for b = (int x) XOR, AND or OR (int y) on a
/// grid shifted by the seed.
fn dc_booleans(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, kind, zoom, t0, t1, t2, t3, t4] = v.params();
    let [x0, y0] = v.derived();
    dc_common(v, [t0, t1, t2, t3, t4], t, acc, rng, 0.5, |x, y| {
        let (ix, iy) = ((x * zoom + x0) as i32, (y * zoom + y0) as i32);
        let b = match kind as i32 {
            0 => ix ^ iy,
            1 => ix & iy,
            _ => ix | iy,
        } as f64;
        hue_rgb(b.sin(), b.cos())
    })
}

/// dc_glypho: white bands of cut_glypho's blob rings on black, turning with `time`.
fn dc_glypho(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, _, time, f1, f2, f3, t0, t1, t2, t3, t4] = v.params();
    dc_common(v, [t0, t1, t2, t3, t4], t, acc, rng, 0.5, |x, y| {
        let m = glypho_pattern(x * zoom, y * zoom, [f1, f2, f3], time);
        [m, m, m]
    })
}

/// dc_moebiuslog: |fract(scale·U)| (grey) of U = the zoomed point through the Möbius map
/// U·(z, iz)/|U|² (z the point shifted by 1; `Moebius`), then the log-polar spiral
/// (½, −½)·ln|U + ½| + (angle, 1)·arg/6.3 (`Log`).
fn dc_moebiuslog(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, _, _, log, moebius, scale, angle, t0, t1, t2, t3, t4] = v.params();
    dc_common(v, [t0, t1, t2, t3, t4], t, acc, rng, 0.5, |x, y| {
        let (mut ux, mut uy) = (x * zoom, y * zoom);
        let (zx, zy) = (ux + 1.0, uy);
        if moebius == 1.0 {
            ux -= 0.5;
            let d = ux * ux + uy * uy;
            (ux, uy) = ((zx * ux + zy * uy) / d, (-zy * ux + zx * uy) / d);
        }
        if log == 1.0 {
            let (ax, ay) = (ux + 0.5, uy + 0.5);
            let l = (ax * ax + ay * ay).sqrt().ln();
            let a = atan2_approx(ay, ax) / 6.3;
            (ux, uy) = (0.5 * l + angle * a, -0.5 * l + a);
        }
        let (fx, fy) = (fract(ux * scale), fract(uy * scale));
        let g = (fx * fx + fy * fy).sqrt();
        [g, g, g]
    })
}
