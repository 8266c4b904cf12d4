//! JWildfire's direct-colour stamps ported from shaders by Jesus Sosa: `dc_acrilic`,
//! `dc_vortex`, `dc_portal` and `glsl_hoshi`. Each scatters points over a square and colours
//! them by a pattern.
//!
//! JWildfire paints the pattern's RGB directly (`Gradient` 0), the nearest palette colour (1)
//! or uses the colour's luminance as the palette index (2), as `jwf_direct_colour` describes;
//! glsl_hoshi paints the RGB (0) or takes red·green as the palette index (1).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. Random numbers are drawn in the order JWildfire draws them.

use super::jwf_c_glsl::{GLSL_RES_Y, GlslIndex, glsl_frame};
use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail, gmod};
use super::util::{atan2_approx, fract};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("dc_acrilic", dc_acrilic)
        .params(P_ACRILIC)
        .flags(DC_FLAGS),
    VarDef::new("dc_vortex", dc_vortex)
        .params(P_VORTEX)
        .flags(DC_FLAGS),
    VarDef::new("dc_portal", dc_portal)
        .params(P_PORTAL)
        .flags(DC_FLAGS),
    VarDef::new("glsl_hoshi", glsl_hoshi)
        .params(&[
            p_int("glsl_hoshi_Density Pixels", 1000000.0, 100.0, 10000000.0),
            p_int("glsl_hoshi_Seed", 100000.0, 0.0, 10000.0),
            p("glsl_hoshi_time", 10.0),
            p_int("glsl_hoshi_Steps", 28.0, 1.0, 60.0),
            p_range("glsl_hoshi_Scale", 1.25, 1.0, 5.0),
            p_range("glsl_hoshi_Translate", 1.5, 0.0, 5.0),
            p_int("glsl_hoshi_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR),
];

/// GLSL's smoothstep.
fn smoothstep(e0: f64, e1: f64, x: f64) -> f64 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

const P_ACRILIC: &[Param] = &{
    let tail = dc_tail!("dc_acrilic");
    [
        p_int("dc_acrilic_seed", 10000.0, NEG_INF, INF),
        p("dc_acrilic_time", 0.0),
        p("dc_acrilic_zoom", 0.7),
        p_int("dc_acrilic_steps", 10.0, 3.0, 100.0),
        p_range("dc_acrilic_p1", 12.0, 1.0, 100.0),
        p_range("dc_acrilic_p2", 12.0, 1.0, 100.0),
        p_range("dc_acrilic_p3", 12.0, 1.0, 100.0),
        p_range("dc_acrilic_p4", 12.0, 1.0, 100.0),
        p_range("dc_acrilic_p5", 75.0, 1.0, 100.0),
        p_range("dc_acrilic_p6", 75.0, 1.0, 100.0),
        p_range("dc_acrilic_redf", 1.0, 0.0, 5.0),
        p_range("dc_acrilic_greenf", 1.0, 0.0, 5.0),
        p_range("dc_acrilic_bluef", 1.0, 0.0, 5.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// dc_acrilic: three passes of a sine/cosine flow of the point, each giving one channel as
/// cos((sin(p5·x²) + sin(p6·y²))·factor).
fn dc_acrilic(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        time,
        zoom,
        steps,
        p1,
        p2,
        p3,
        p4,
        p5,
        p6,
        fr,
        fg,
        fb,
        tail @ ..,
    ] = v.params::<18>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let p = [p1, p2, p3, p4, p5, p6];
        acrilic_rgb(zoom * x, zoom * y, time, steps, p, [fr, fg, fb])
    })
}

/// The acrylic pattern's colour at (px, py): the point pushed along sine waves `steps` times
/// per channel (p1…p4 their frequencies), each channel cos(f·(sin(p5·x²) + sin(p6·y²))).
pub(super) fn acrilic_rgb(
    mut px: f64,
    mut py: f64,
    time: f64,
    steps: f64,
    [p1, p2, p3, p4, p5, p6]: [f64; 6],
    f: [f64; 3],
) -> [f64; 3] {
    let mut col = [0.0; 3];
    for (j, c) in col.iter_mut().enumerate() {
        let jf = j as f64;
        for i in 1..(steps as i64) {
            let i = i as f64;
            px += 0.1 / (i + jf) * (i * p1 * py + time + ((time / (p2 * i)) * i + jf).cos()).sin();
            py += 0.1 / (i + jf) * (i * p3 * px + time + ((time / (p4 * i)) * i + jf).sin()).cos();
        }
        *c = (p5 * px * px).sin() + (p6 * py * py).sin();
    }
    [0, 1, 2].map(|k| (col[k] * f[k]).cos())
}

const P_VORTEX: &[Param] = &{
    let tail = dc_tail!("dc_vortex");
    [
        p_int("dc_vortex_randomize", 0.0, NEG_INF, INF),
        p("dc_vortex_time", 0.0),
        p_int("dc_vortex_flowStrength", 10.0, 1.0, 15.0),
        p_range("dc_vortex_Blending", 5.0, 1.0, 5.0),
        p("dc_vortex_zoom", 1.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// Value noise of the shaders: a smooth blend of sine hashes at the cell's corners.
fn noise_fv2(x: f64, y: f64) -> f64 {
    let (ix, iy) = (x.floor(), y.floor());
    let (fx, fy) = (fract(x), fract(y));
    let (fx, fy) = (fx * fx * (3.0 - 2.0 * fx), fy * fy * (3.0 - 2.0 * fy));
    let p = ix + iy * 57.0;
    let h = [0.0, 1.0, 57.0, 58.0].map(|a: f64| fract((a + p).sin() * 43758.54));
    let a = h[0] + (h[1] - h[0]) * fx;
    let b = h[2] + (h[3] - h[2]) * fx;
    a + (b - a) * fy
}

/// Six octaves of [`noise_fv2`].
fn fbm2(mut x: f64, mut y: f64) -> f64 {
    let (mut s, mut a) = (0.0, 1.0);
    for _ in 0..6 {
        s += a * noise_fv2(x, y);
        a *= 0.5;
        x *= 2.0;
        y *= 2.0;
    }
    s
}

/// The velocity of a row of 30 alternating vortices (strength `k`, spacing `dx`, rows at
/// ±`sep`, the row sliding with `time`) at the point `scale`·q.
fn flow_field(qx: f64, qy: f64, time: f64, scale: f64, sep: f64, dx: f64, k: f64) -> (f64, f64) {
    let (mut cx, mut cy) = (gmod(time, 10.0) - 20.0, sep);
    let (mut vx, mut vy) = (0.0, 0.0);
    let mut dir = 1.0;
    for _ in 0..30 {
        let (dx_, dy_) = (qx * scale - cx, qy * scale - cy);
        let d = dx_ * dx_ + dy_ * dy_ + 0.05;
        vx += dy_ / d * k * dir;
        vy += -dx_ / d * k * dir;
        cx += dx;
        cy = -cy;
        dir = -dir;
    }
    (vx, vy)
}

/// dc_vortex: the point carried backwards through a vortex street, coloured by fractal noise.
fn dc_vortex(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, strength, softness, zoom, tail @ ..] = v.params::<10>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let (mut px, mut py) = (x * zoom, y * zoom);
        for _ in 0..(strength as i64) {
            let (fx, fy) = flow_field(px, py, time, 4.0, 0.6, 1.0, -0.25);
            px -= fx * 0.03;
            py -= fy * 0.03;
        }
        let c = 0.5 * fbm2(px * softness - 0.1 * time, py * softness);
        [c, c, c]
    })
}

const P_PORTAL: &[Param] = &{
    let tail = dc_tail!("dc_portal");
    [
        p_int("dc_portal_seed", 1000.0, NEG_INF, INF),
        p("dc_portal_time", 0.0),
        p("dc_portal_waves", 5.0),
        p("dc_portal_zoom", 15.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// dc_portal: rings of sin((1 + √|uv|/waves)·t + t/8·cos u·cos v), a metallic ramp of it. The
/// point replaces the running sum.
fn dc_portal(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, waves, zoom, tail @ ..] = v.params::<9>();
    acc.x = 0.0;
    acc.y = 0.0;
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let (ux, uy) = (x * zoom, y * zoom);
        let d = 1.0 + (ux * ux + uy * uy).sqrt().sqrt() / waves;
        let tt = 1000.0 + time;
        let value = d * tt + (tt * 0.125) * ux.cos() * uy.cos();
        let color = value.sin() * 3.0;
        let med = color.abs() - 1.0;
        let med_high = color.abs() - 1.5;
        let high = color.abs() - 2.0;
        if color > 0.0 {
            [med, med_high, high]
        } else {
            [med_high, med_high, med_high]
        }
    })
}

/// The shader's rounded π in glsl_hoshi (kept).
#[allow(clippy::approx_constant)]
const HOSHI_PI: f64 = 3.14159;

/// glsl_hoshi: a star-like folding fractal (iterated fold, scale, translate and rotate), its
/// colour a hue from the final angle, drawn on a random pixel (see [`glsl_frame`]).
fn glsl_hoshi(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, steps, scale, translate, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedGreen, |i, j| {
        let (px, py) = (2.0 * i / res - 1.0, 2.0 * j / GLSL_RES_Y - 1.0);
        hoshi_rgb(px, py, time, steps, scale, translate)
    })
}

/// glsl_hoshi's colour at (px, py) of [-1, 1]².
pub(super) fn hoshi_rgb(
    px: f64,
    py: f64,
    time: f64,
    steps: f64,
    scale: f64,
    translate: f64,
) -> [f64; 3] {
    let (mut px, mut py) = (px * 0.182, py * 0.182);
    let x = py;
    px = (gmod(px, 4.0) - 2.0).abs();
    py = (gmod(py, 4.0) - 2.0).abs();
    let mut k = steps as i64;
    while k > 0 {
        px = (px + 0.5).abs() - 0.5;
        py = (py + 0.5).abs() - 0.5;
        px = px * scale - translate;
        py = py * scale - translate;
        let a = HOSHI_PI
            / (0.10
                + (time * 0.0005 + k as f64 * 0.5000001).sin() * 0.4999
                + 0.5
                + (10.0 / time)
                + time.sin() / 100.0);
        let (s, c) = a.sin_cos();
        (px, py) = (px * c - py * s, px * s + py * c);
        k -= 1;
    }
    let ii = x * x + atan2_approx(py, px) + time * 0.02;
    let mut h = (ii * 4.0).floor() / 8.0 + 1.107;
    h += smoothstep(-0.1, 0.8, gmod(ii * 2.0 / 5.0, 1.0 / 4.0) * 900.0) / 0.010 - 0.5;
    let val = smoothstep(-3.0, 3.0, (px * px + py * py).sqrt());
    [3.0, 2.0, 1.0].map(|o: f64| {
        let c = (fract((o + h) / 3.0) * 6.0 - 3.0).abs() - 1.0;
        c.clamp(0.0, 1.0) * val
    })
}
