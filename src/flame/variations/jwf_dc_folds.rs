//! JWildfire's folding and noise direct-colour stamps (Jesus Sosa's shader ports):
//! `dc_ducks` (the "ducks" log-polar fractal), `dc_mandbrot` (a zoom into the Mandelbrot
//! set through folds), `dc_spacefold` (64 mirror-turn-shift folds under a cosine palette),
//! `dc_warping` (Inigo Quilez's domain-warped value noise, lit) and `dc_fractcolor` (an
//! absolute-value inversion map giving the colour) and `dc_butterflies` (an iterated complex
//! map sin((z + z₀)⁻⁴) − k·z + z₀ coloured by its orbit trap).
//!
//! Each colours its points through `jwf_direct_colour`'s common part. The formulas follow
//! JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics, written anew.

use super::jwf_a_cuts::JavaRandom;
use super::jwf_a_dc::rot;
use super::jwf_dc_maths::{length2, mix3};
use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail};
use super::util::{atan2_approx, fract, smoothstep, trunc_i32};
use super::*;

const DUCKS_TAIL: [Param; 5] = dc_tail!("dc_ducks");
const MANDBROT_TAIL: [Param; 5] = dc_tail!("dc_mandbrot");
const SPACEFOLD_TAIL: [Param; 5] = dc_tail!("dc_spacefold");
const WARPING_TAIL: [Param; 5] = dc_tail!("dc_warping");
const FRACTCOLOR_TAIL: [Param; 5] = dc_tail!("dc_fractcolor");
const BUTTERFLIES_TAIL: [Param; 5] = dc_tail!("dc_butterflies");

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("dc_ducks", dc_ducks)
        .params(&[
            p_int("dc_ducks_seed", 10000.0, NEG_INF, INF),
            p("dc_ducks_time", 10.0),
            p("dc_ducks_zoom", 1.0),
            DUCKS_TAIL[0],
            DUCKS_TAIL[1],
            DUCKS_TAIL[2],
            DUCKS_TAIL[3],
            DUCKS_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_mandbrot", dc_mandbrot)
        .params(&[
            p_int("dc_mandbrot_nIters", 250.0, 10.0, 1000.0).limited(),
            p_int("dc_mandbrot_N", 8.0, 2.0, 10.0),
            p_range("dc_mandbrot_Complexity", 0.995, 0.0, 1.0),
            p_int("dc_mandbrot_seed", 10000.0, NEG_INF, INF),
            p("dc_mandbrot_time", 0.0),
            p("dc_mandbrot_zoom", 4.0),
            p_range("dc_mandbrot_red", 0.0314, 0.0, 1.0),
            p_range("dc_mandbrot_green", 0.02, 0.0, 1.0),
            p_range("dc_mandbrot_blue", 0.011, 0.0, 1.0),
            MANDBROT_TAIL[0],
            MANDBROT_TAIL[1],
            MANDBROT_TAIL[2],
            MANDBROT_TAIL[3],
            MANDBROT_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_spacefold", dc_spacefold)
        .params(&[
            p_int("dc_spacefold_randomize", 1000.0, 0.0, 10000.0),
            p("dc_spacefold_time", 0.0),
            p("dc_spacefold_zoom", 2.5),
            SPACEFOLD_TAIL[0],
            SPACEFOLD_TAIL[1],
            SPACEFOLD_TAIL[2],
            SPACEFOLD_TAIL[3],
            SPACEFOLD_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_warping", dc_warping)
        .params(&[
            p_int("dc_warping_randomize", 0.0, NEG_INF, INF),
            p("dc_warping_zoom", 1.0),
            p("dc_warping_x0", 0.0),
            WARPING_TAIL[0],
            WARPING_TAIL[1],
            WARPING_TAIL[2],
            WARPING_TAIL[3],
            WARPING_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_fractcolor", dc_fractcolor)
        .params(&[
            p_int("dc_fractcolor_randomize", 0.0, NEG_INF, INF),
            p("dc_fractcolor_time", 0.0),
            p_range("dc_fractcolor_xpar", 0.5, 0.0, 1.0),
            p_range("dc_fractcolor_ypar", 0.5, 0.0, 1.0),
            p_int("dc_fractcolor_iters", 88.0, NEG_INF, 2000.0).limited(),
            p("dc_fractcolor_zoom", 1.0),
            FRACTCOLOR_TAIL[0],
            FRACTCOLOR_TAIL[1],
            FRACTCOLOR_TAIL[2],
            FRACTCOLOR_TAIL[3],
            FRACTCOLOR_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_butterflies", dc_butterflies)
        .params(&[
            p_int("dc_butterflies_seed", 1000.0, NEG_INF, INF),
            p("dc_butterflies_time", 0.0),
            p("dc_butterflies_zoom", 1.0),
            p_range("dc_butterflies_red", 1.0, -1.0, 1.0),
            p_range("dc_butterflies_green", 1.0, -1.0, 1.0),
            p_range("dc_butterflies_blue", 1.0, -1.0, 1.0),
            BUTTERFLIES_TAIL[0],
            BUTTERFLIES_TAIL[1],
            BUTTERFLIES_TAIL[2],
            BUTTERFLIES_TAIL[3],
            BUTTERFLIES_TAIL[4],
        ])
        .flags(DC_FLAGS),
];

/// dc_ducks: 50 steps of e ← (ln|e|, arg e − 6.2) + drift (e mirrored into y ≥ 0 first),
/// the summed lengths giving a posterised colour. Over [−1, 1]².
fn dc_ducks(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, zoom, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        let t = time / 65.0 * 30.0;
        let mut e = ((x - 0.0) * zoom, (y - 0.0) * zoom);
        let drift = (0.1 * (t / 3.0).sin() - 0.1, 5.0 + 0.1 * (t / 5.0).cos());
        let mut c = 0.0;
        for _ in 0..50 {
            let (ax, ay) = (e.0, e.1.abs());
            e = (
                length2(ax, ay).ln() + drift.0,
                (atan2_approx(ay, ax) - 6.2) + drift.1,
            );
            c += length2(e.0, e.1);
        }
        let log2 = |v: f64| v.ln() / 2f64.ln();
        let d = log2(log2(c * 0.05)) * 6.0;
        let flori = [
            0.1 + 0.7 * d.sin(),
            0.1 + 0.5 * (d - 0.7).sin(),
            0.7 + 0.7 * (d - 0.7).cos(),
        ];
        let q = flori.map(|f| (0.5 + f * 1.1).floor() / 1.1);
        [q[2], q[0], q[1]]
    })
}

/// dc_mandbrot: the zoomed point scaled, folded N times (p ← |p|/|p|² − s, turned by
/// time, s shrinking by Complexity), shrunk by 1.5^(−31·f) towards a point on the
/// Mandelbrot set's edge; 1 − sin(d·colour) of the escape's summed radii. Over [−½, ½]².
fn dc_mandbrot(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        iters,
        n,
        complexity,
        _,
        time,
        zoom,
        red,
        green,
        blue,
        tail @ ..,
    ] = v.params::<14>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let t = time / 65.0 * 10.0;
        let k = fract(t * 0.0001) * 100.0 + 1.0;
        let (mut px, mut py) = (x * zoom * k, y * zoom * k);
        let mut s = 0.5;
        for _ in 0..n as i64 {
            let d = px * px + py * py;
            (px, py) = rot(px.abs() / d - s, py.abs() / d - s, t);
            s *= complexity;
        }
        let f = (t * 0.10 + 99.0).sin() * 0.5 + 0.5;
        let shrink = 1.5f64.powf(f * (-31.0));
        let (cx, cy) = (px * shrink + -1.002029, py * shrink + 0.303864);
        let (mut sx, mut sy) = (cx, cy);
        let mut d = 0.0;
        for _ in 0..iters as i64 {
            (sx, sy) = (sx * sx - sy * sy + cx, 2.0 * sx * sy + cy);
            let l = length2(sx, sy);
            d += l + 0.5;
            if l > 2.0 {
                return [red, green, blue].map(|c| 1.0 - (d * c).sin());
            }
        }
        [1.0; 3]
    })
}

/// dc_spacefold: 64 folds of the zoomed point (mirror into the first quadrant, turn by
/// time/30, shift by −½, scale 1.03), then |sin uv|^0.3 into a cosine palette. Over
/// [−½, ½]².
fn dc_spacefold(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, zoom, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let (mut ux, mut uy) = (x * zoom, y * zoom);
        for _ in 0..64 {
            (ux, uy) = rot(ux.abs(), uy.abs(), -(time / 30.0));
            ux = (ux - 0.5) * 1.03;
            uy = (uy - 0.5) * 1.03;
        }
        let (ux, uy) = (ux.sin().abs().powf(0.3), uy.sin().abs().powf(0.3));
        let t = ux * uy * 1.9;
        let (c, d) = ([1.0, 1.0, 0.5], [0.8, 0.9, 0.3]);
        [0, 1, 2].map(|k| 0.5 + 0.5 * ((c[k] * t + d[k]) * SHADER_TAU).cos())
    })
}

/// The spacefold shader's rounded 2π (kept).
#[allow(clippy::approx_constant)]
const SHADER_TAU: f64 = 6.28318;

/// The warping's lattice hash in [−1, 1].
fn warp_hash(x: f64, y: f64) -> f64 {
    -1.0 + 2.0 * fract((x * 127.1 + y * 311.7).sin() * 43758.5453123)
}

/// The warping's value noise (JWildfire's fade is f³, the shader's 3 − 2f being written
/// (3 − 2)·f).
fn warp_noise(x: f64, y: f64) -> f64 {
    let (ix, iy) = (x.floor(), y.floor());
    let (fx, fy) = (fract(x), fract(y));
    let (ux, uy) = (fx * fx * (1.0 * fx), fy * fy * (1.0 * fy));
    let mix = |a: f64, b: f64, t: f64| a * (1.0 - t) + b * t;
    mix(
        mix(warp_hash(ix, iy), warp_hash(ix + 1.0, iy), ux),
        mix(warp_hash(ix, iy + 1.0), warp_hash(ix + 1.0, iy + 1.0), ux),
        uy,
    )
}

/// Four octaves of [`warp_noise`], each turned by the matrix (0.8, 0.6; −0.6, 0.8).
fn warp_fbm(mut x: f64, mut y: f64) -> f64 {
    let mut f = 0.0;
    f += 0.5000 * warp_noise(x, y);
    for (gain, scale) in [(0.2500, 2.02), (0.1250, 2.03), (0.0625, 2.01)] {
        let (qx, qy) = (x * scale, y * scale);
        (x, y) = (0.8 * qx + -0.6 * qy, 0.6 * qx + 0.8 * qy);
        f += gain * warp_noise(x, y);
    }
    f / 0.9375
}

fn warp_fbm2(x: f64, y: f64) -> (f64, f64) {
    (warp_fbm(x, y), warp_fbm(y, x))
}

/// The warped noise's colour at p: red to cream by the plain noise, to near black by the
/// twice-warped noise.
fn warp_map(px: f64, py: f64) -> [f64; 3] {
    let (px, py) = (px * 0.7, py * 0.7);
    let a = warp_fbm2(px * 4.0, py * 4.0);
    let b = warp_fbm2((px + a.0) * 2.0, (py + a.1) * 2.0);
    let c = warp_fbm2(px + b.0, py + b.1);
    let f = c.0 - c.1;
    let bl = smoothstep(-0.8, 0.8, f);
    let ti = smoothstep(-1.0, 1.0, warp_fbm(px, py));
    mix3(
        mix3([0.50, 0.00, 0.00], [1.00, 0.75, 0.35], ti),
        [0.00, 0.00, 0.02],
        bl,
    )
}

/// dc_warping's x0 as JWildfire 9.00 sets it when the seed (`dc_warping_randomize`) is set
/// (`DC_WarpingFunc.setParameter`): 2·u − 1, u the first `nextDouble()` of Java's generator
/// seeded with the seed as a Java `int`. Versions before x0 existed wrote only the seed, so
/// JWildfire reads such a flame with this x0.
pub fn dc_warping_x0_of_seed(seed: f64) -> f64 {
    let mut r = JavaRandom::new(i64::from(trunc_i32(seed)));
    2.0 * r.next_f64() - 1.0
}

/// dc_fractcolor's xpar and ypar as JWildfire 9.00 sets them when the seed
/// (`dc_fractcolor_randomize`) is set (`DC_FractColorFunc.setParameter`): the first and the
/// second `nextDouble()` of Java's generator seeded with the seed as a Java `int`. Flames
/// that spell them otherwise (`xPar`, as JWildfire 6 wrote) leave them to the seed in
/// JWildfire 9.00, which reads parameters by their exact names.
pub fn dc_fractcolor_xpar_of_seed(seed: f64) -> f64 {
    JavaRandom::new(i64::from(trunc_i32(seed))).next_f64()
}

/// The second draw: see [`dc_fractcolor_xpar_of_seed`].
pub fn dc_fractcolor_ypar_of_seed(seed: f64) -> f64 {
    let mut r = JavaRandom::new(i64::from(trunc_i32(seed)));
    r.next_f64();
    r.next_f64()
}

/// dc_warping: the warped noise of the zoomed point (shifted by x0), lit by the gradient of
/// its grey and vignetted. Over [−½, ½]².
fn dc_warping(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, zoom, x0, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let (px, py) = (x * zoom + x0, y * zoom + x0);
        let e = 0.0045;
        let grey = |c: [f64; 3]| c[0] * 0.333 + c[1] * 0.333 + c[2] * 0.333;
        let colc = warp_map(px, py);
        let gc = grey(colc);
        let ga = grey(warp_map(px + e, py + 0.0));
        let gb = grey(warp_map(px + 0.0, py + e));
        let n = [ga - gc, e, gb - gc];
        let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let ny = n[1] / l;
        let glow = 8.0 * (2.0 * gc - ga - gb).abs();
        let (qx, qy) = ((x + 1.0) / 2.0, (y + 1.0) / 2.0);
        let vignette = (16.0 * qx * qy * (1.0 - qx) * (1.0 - qy)).powf(0.1);
        let tint = [1.0, 0.7, 0.6];
        [0, 1, 2].map(|k| {
            let c = (colc[k] + tint[k] * glow) * (1.0 + 0.2 * ny * ny);
            (c + 0.05 * ny * ny * ny) * vignette
        })
    })
}

/// dc_fractcolor: `iters` steps of O ← swizzle(|O/|O|² − (1, 1, 0.3·ypar)|·(1.3, 1, 0.777))
/// from (zoomed point, 1.5 − xpar + 0.04·sin time). Over [−½, ½]².
fn dc_fractcolor(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, xpar, ypar, iters, zoom, tail @ ..] = v.params::<11>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let mut o = [x * zoom, y * zoom, 1.5 - xpar + 0.04 * time.sin()];
        let shift = [1.0, 1.0, ypar * 0.3];
        let gain = [1.3, 1.0, 0.777];
        for _ in 0..iters as i64 {
            let d = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
            let w: [f64; 3] = std::array::from_fn(|k| (o[k] / d - shift[k]).abs() * gain[k]);
            o = [w[0], w[2], w[1]];
        }
        o
    })
}

/// dc_butterflies: up to 100 steps of z ← sin((z + z₀)⁻⁴) − 0.9·(1 + 2·sin(time/10))·z + z₀
/// from the zoomed point z₀ (stopping, blended back, when a step is tiny or huge); the colour
/// sines of the closest approach to 1 + i and the last z. The point replaces the running sum.
fn dc_butterflies(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, zoom, red, green, blue, tail @ ..] = v.params::<11>();
    acc.x = 0.0;
    acc.y = 0.0;
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let z0 = (x * zoom, y * zoom);
        let pull = 0.9 * (1.0 + 2.0 * (0.1 * time).sin());
        let step = |(zx, zy): (f64, f64)| {
            // (z + z0)^-4 in polar form, then its complex sine.
            let (ax, ay) = (zx + z0.0, zy + z0.1);
            let (r, a) = (length2(ax, ay), atan2_approx(ay, ax));
            let m = r.powf(-4.0);
            let (px, py) = ((a * -4.0).cos() * m, (a * -4.0).sin() * m);
            let e = py.exp();
            let (sx, sy) = (
                (e + 1.0 / e) * px.sin() * 0.5,
                (e - 1.0 / e) * px.cos() * 0.5,
            );
            (sx - zx * pull + z0.0, sy - zy * pull + z0.1)
        };
        let mut z = z0;
        let mut g: f64 = 1e10;
        for _ in 0..100 {
            let prev = z;
            z = step(z);
            g = g.min((z.0 - 1.0) * (z.0 - 1.0) + (z.1 - 1.0) * (z.1 - 1.0));
            let dz = (z.0 - prev.0) * (z.0 - prev.0) + (z.1 - prev.1) * (z.1 - prev.1);
            let k = if dz < 0.00001 {
                dz / 0.00001
            } else if dz > 10000.0 {
                10000.0 / dz
            } else {
                continue;
            };
            z = (z.0 * k + prev.0 * (1.0 - k), z.1 * k + prev.1 * (1.0 - k));
            break;
        }
        let shift = 2.3 + (g * (z.1 * z.0).abs()).ln();
        [red, green, blue].map(|c| (c + shift).sin() * 0.5 + 0.5)
    })
}
