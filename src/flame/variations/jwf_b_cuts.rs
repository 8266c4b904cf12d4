//! JWildfire's cut-outs ported from shaders by Jesus Sosa: `cut_tileillusion`, `cut_sqcir`,
//! `cut_rgrid` and `cut_zigzag`. Each takes the point (`mode` 0) or a uniform point of the unit
//! square (`mode` 1), evaluates a black-and-white pattern there and hides the point where the
//! pattern is off (on, with `invert`); the point replaces the xform's running sum.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. Random numbers are drawn in the order JWildfire draws them.

use std::f64::consts::PI;

use super::jwf_direct_colour::gmod;
use super::util::fract;
use super::*;

const CUT_FLAGS: u32 = flag::JWILDFIRE | flag::RANDOM | flag::HIDES | flag::WRITES_ACC;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("cut_tileillusion", cut_tileillusion)
        .params(&[
            p("cut_tileillusion_time", 0.0),
            p_int("cut_tileillusion_mode", 1.0, 0.0, 1.0),
            p_range("cut_tileillusion_zoom", 15.0, 0.1, 50.0),
            p_int("cut_tileillusion_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT_FLAGS),
    VarDef::new("cut_sqcir", cut_sqcir)
        .params(&[
            p_int("cut_sqcir_mode", 1.0, 0.0, 1.0),
            p_range("cut_sqcir_zoom", 2.0, 0.1, 50.0),
            p_int("cut_sqcir_invert", 0.0, 0.0, 1.0),
            p_range("cut_sqcir_power", 2.0, 0.0, 2.0),
        ])
        .flags(CUT_FLAGS),
    VarDef::new("cut_rgrid", cut_rgrid)
        .params(&[
            p_int("cut_rgrid_mode", 1.0, 0.0, 1.0),
            p_range("cut_rgrid_zoom", 7.0, 0.1, 50.0),
            p_int("cut_rgrid_invert", 0.0, 0.0, 1.0),
            p_int("cut_rgrid_angle", 0.0, 0.0, 90.0),
        ])
        .flags(CUT_FLAGS),
    VarDef::new("cut_zigzag", cut_zigzag)
        .params(&[
            p_int("cut_zigzag_mode", 1.0, 0.0, 1.0),
            p("cut_zigzag_xpar", 1.0),
            p("cut_zigzag_ypar", 2.0),
            p("cut_zigzag_zoom", 2.0),
            p_int("cut_zigzag_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT_FLAGS),
];

/// GLSL's smoothstep.
fn smoothstep(e0: f64, e1: f64, x: f64) -> f64 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// The part the cut-outs share: the point (`mode` 0) or a uniform point of the unit square,
/// `on` the pattern there; hidden where it is off (`invert` 0) or on (1). The result replaces
/// the running sum.
fn cut(
    v: &Prepared,
    t: &VarIn,
    acc: &mut Acc,
    rng: &mut FastRng,
    mode: f64,
    invert: f64,
    on: impl FnOnce(f64, f64) -> bool,
) -> V3 {
    let (x, y) = if mode == 0.0 {
        (t.x, t.y)
    } else {
        let x = rng.f01() - 0.5;
        (x, rng.f01() - 0.5)
    };
    let lit = on(x, y);
    let hide = if invert == 0.0 { !lit } else { lit };
    acc.hide = hide;
    acc.x = 0.0;
    acc.y = 0.0;
    if hide {
        [0.0; 3]
    } else {
        [v.w * x, v.w * y, 0.0]
    }
}

/// x + sin(1.6x)/10, the row warp of cut_tileillusion.
fn tile_warp(x: f64) -> f64 {
    x + 0.1 * (1.6 * x).sin()
}

/// The x where [`tile_warp`] reaches `y` between x0 and x1 (20 steps of false position).
fn tile_solve(mut x0: f64, mut x1: f64, y: f64) -> f64 {
    let (mut y0, mut y1) = (tile_warp(x0), tile_warp(x1));
    if y1 < y0 {
        std::mem::swap(&mut x0, &mut x1);
        std::mem::swap(&mut y0, &mut y1);
    }
    let mut xn = 0.0;
    for _ in 0..20 {
        xn = x0 + (x1 - x0) / (y1 - y0) * (y - y0);
        let yn = tile_warp(xn);
        if yn > y {
            x1 = xn;
            y1 = yn;
        } else {
            x0 = xn;
            y0 = yn;
        }
    }
    xn
}

/// cut_tileillusion: the café-wall illusion: a checkerboard in warped rows of alternating
/// shift (by `time`), with mortar lines between the rows.
fn cut_tileillusion(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [time, mode, zoom, invert] = v.params();
    cut(v, t, acc, rng, mode, invert, |x, y| {
        let (mut ux, uy) = (x * zoom, y * zoom);
        let fy = tile_warp(uy).floor();
        let y0 = tile_solve(uy - 3.0, uy, fy);
        let y1 = tile_solve(uy, uy + 3.0, fy + 1.0);
        let uy = tile_warp(uy);
        ux /= y1 - y0;
        let s = gmod(uy.floor(), 2.0);
        if fract(uy) > 0.05 {
            ux += time * (s - 0.5).signum_or_zero();
            gmod(ux.floor() + uy.floor(), 2.0) != 0.0
        } else {
            false
        }
    })
}

/// GLSL's `sign` (0 at 0).
trait SignOrZero {
    fn signum_or_zero(self) -> f64;
}

impl SignOrZero for f64 {
    fn signum_or_zero(self) -> f64 {
        if self > 0.0 {
            1.0
        } else if self < 0.0 {
            -1.0
        } else {
            0.0
        }
    }
}

/// cut_sqcir: the superellipse |x − y|^p + |x + y|^p ≤ 1 (a square turned by 45° for p → ∞,
/// a circle for p = 2).
fn cut_sqcir(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, invert, power] = v.params();
    let (x, y) = if mode == 0.0 {
        (t.x, t.y)
    } else {
        let x = rng.f01() - 0.5;
        (x, rng.f01() - 0.5)
    };
    let (ux, uy) = (x * zoom, y * zoom);
    let lit = (ux - uy).abs().powf(power) + (uy + ux).abs().powf(power) <= 1.0;
    let hide = if invert == 0.0 { !lit } else { lit };
    acc.hide = hide;
    // With `invert`, JWildfire returns before writing the hidden point.
    if !(hide && invert != 0.0) {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    if hide {
        return [0.0; 3];
    }
    [v.w * x, v.w * y, 0.0]
}

/// cut_rgrid: a grid of squares turned by `angle` degrees, alternate cells mirrored, with the
/// shaded squares of the "rotating grid" illusion.
fn cut_rgrid(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, invert, angle] = v.params();
    cut(v, t, acc, rng, mode, invert, |x, y| {
        let (mut px, mut py) = (x * zoom, y * zoom);
        let th = gmod(angle * PI / 180.0, PI * 2.0);
        let gridsize = (0.5 + (th * 2.0).sin().abs() * (2f64.sqrt() / 2.0 - 0.5)) * 2.0;
        let flip = fract(th / PI + 0.25) > 0.5;
        if flip {
            px -= 0.5;
            py -= 0.5;
        }
        px *= gridsize;
        py *= gridsize;
        let (cx, cy) = ((px / gridsize).floor(), (py / gridsize).floor());
        px = gmod(px, gridsize) - gridsize / 2.0;
        py = gmod(py, gridsize) - gridsize / 2.0;
        px *= gmod(cx, 2.0) * 2.0 - 1.0;
        py *= gmod(cy, 2.0) * 2.0 - 1.0;
        // GLSL's p * mat2(c, s, -s, c): p times the matrix of columns (c, s) and (−s, c).
        let (s, c) = th.sin_cos();
        let (qx, qy) = (px * c + py * s, -px * s + py * c);
        let w = zoom / 2000.0 * 1.5;
        let mut color = smoothstep(-w, w, qx.abs().max(qy.abs()) - 0.5);
        if flip {
            color = 1.0 - color;
        }
        if flip
            && color < 0.5
            && (qx.abs() - qy.abs()) * (fract(th / PI) - 0.5).signum_or_zero() > 0.0
        {
            color = 0.4;
        }
        if !flip && color < 0.5 && gmod(cx + cy, 2.0) - 0.5 > 0.0 {
            color = 0.4;
        }
        color != 0.0
    })
}

/// cut_zigzag: a zigzag band pattern on mirrored tiles (The Book of Shaders).
fn cut_zigzag(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, xpar, ypar, zoom, invert] = v.params();
    cut(v, t, acc, rng, mode, invert, |xp, yp| {
        let (mut sx, mut sy) = (xp * xpar * zoom, yp * ypar * zoom);
        if fract(sy * 0.5) > 0.5 {
            sx += 0.5;
            sy = 1.0 - sy;
        }
        let (sx, sy) = (fract(sx), fract(sy));
        let x = sx * 2.0;
        let a = (1.0 + (x * PI).sin()).floor();
        let b = (1.0 + ((x + 1.0) * PI).sin()).floor();
        let f = fract(x);
        let pct = a + (b - a) * f;
        smoothstep(pct - 0.01, pct, sy) < 0.5
    })
}
