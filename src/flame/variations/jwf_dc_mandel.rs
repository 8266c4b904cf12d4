//! JWildfire's `dc_gmandelbroot` (Jesus Sosa): a generalised Mandelbrot set z ← z^(d + ik)
//! (with the branch n and a log offset m) + c, as a burning ship, conjugate or Julia set,
//! coloured in one of six ways; points coloured pure black are hidden.
//!
//! The formula follows JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew; its quirks are kept (the channel bases of colour modes 2 and 3 are only set
//! by mode 1, so they are 0 there).

use std::cell::Cell;
use std::f64::consts::PI;

use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail};
use super::util::fract;
use super::*;

const TAIL: [Param; 5] = dc_tail!("dc_gmandelbroot");

pub(super) static DEFS: &[VarDef] = &[VarDef::new("dc_gmandelbroot", dc_gmandelbroot)
    .params(&[
        p_int("dc_gmandelbroot_randomize", 10000.0, 0.0, 10000000.0),
        p_int("dc_gmandelbroot_colormode", 0.0, 0.0, 5.0),
        p_int("dc_gmandelbroot_iters", 128.0, 1.0, 255.0),
        p("dc_gmandelbroot_exp_re", 2.0),
        p("dc_gmandelbroot_exp_im", 0.0),
        p("dc_gmandelbroot_n", 0.0),
        p("dc_gmandelbroot_m", 0.0),
        p_int("dc_gmandelbroot_burnigship", 0.0, 0.0, 1.0),
        p_int("dc_gmandelbroot_conjugate", 0.0, 0.0, 1.0),
        p_int("dc_gmandelbroot_julia", 0.0, 0.0, 1.0),
        p("dc_gmandelbroot_jre", 0.0),
        p("dc_gmandelbroot_jim", 0.0),
        p_range("dc_gmandelbroot_panX", 0.5, -2.0, 2.0),
        p_range("dc_gmandelbroot_panY", 0.0, -2.0, 2.0),
        p_range("dc_gmandelbroot_zoom", 4.0, 0.0, 100.0),
        TAIL[0],
        TAIL[1],
        TAIL[2],
        TAIL[3],
        TAIL[4],
    ])
    .flags(DC_FLAGS | flag::HIDES)];

/// The generalised Mandelbrot set's colour at c (see the module documentation); `q` holds
/// colormode, iters, exp_re, exp_im, n, m, burning ship, conjugate, julia, jre, jim.
fn gmandel_rgb(cx: f64, cy: f64, q: [f64; 11]) -> [f64; 3] {
    let [mode, iters, d, k, n, m, ship, conj, julia, jre, jim] = q;
    let julia = julia as i64 == 1;
    let (mut zx, mut zy) = (cx, cy);
    let (mut ii, mut r) = (0.0, 0.0);
    for i in 0..iters as i64 {
        if ship as i64 == 1 {
            (zx, zy) = (zx.abs(), zy.abs());
        }
        if conj as i64 == 1 {
            zy = -zy;
        }
        let q1 = zy.atan2(zx);
        r = zx * zx + zy * zy;
        let q2 = q1 * d + (k / 2.0) * (r + m).ln() + 2.0 * PI * n;
        let q3 = r.powf(d / 2.0) / (k * q1).exp();
        let (bx, by) = if julia { (jre, jim) } else { (cx, cy) };
        (zx, zy) = (q3 * q2.cos() + bx, q3 * q2.sin() + by);
        if m == 0.0 && !julia && i == 0 {
            r = 0.0;
        }
        if r > iters {
            ii = i as f64;
            break;
        }
    }
    let q = if d == 0.0 {
        ii * r.powf(0.5) * ii.powf(0.75) / 255.0
    } else {
        ii * r.powf(d.abs() / d * 0.5) * ii.powf(0.75) / 255.0
    };
    let base = 0.0;
    match mode as i64 {
        0 => {
            let s = 0.125662 * ii;
            [0.9, 0.3, 0.2].map(|o: f64| (s + o).cos() * 0.4 + 0.6)
        }
        1 => {
            let h = (255.0 * ii / iters).floor() / 255.0;
            [3.0, 2.0, 1.0]
                .map(|o: f64| ((fract((o + h) / 3.0) * 6.0 - 3.0).abs() - 1.0).clamp(0.0, 1.0))
        }
        2 => [
            (base * q + zx * zx * ii / 255.0) / 255.0,
            (base * q - zy * zy * ii / 255.0) / 255.0,
            (base * q - ii * ii * ii / 255.0) / 255.0,
        ],
        3 => [
            (base * q + (zx * zx * ii).powf(0.5) / 255.0) / 255.0,
            (base * q + (zy * zy * ii).powf(0.5) / 255.0) / 255.0,
            base * q + (ii * ii * ii).powf(3.0) / 255.0,
        ],
        4 => [0.45, 0.35, 0.25].map(|e| ii * (r * ii / iters).powf(e) / 255.0),
        _ => {
            let f = 1e20f64.min(zx * zx + zy * zy);
            let f = 1.0 + (f.log10() / 2f64.log10()) / 16.0;
            [f, f * f, f * f * f]
        }
    }
}

/// dc_gmandelbroot: the set over [−1, 1]² zoomed and panned; hidden where the colour is
/// black.
fn dc_gmandelbroot(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, q @ .., pan_x, pan_y, zoom, t0, t1, t2, t3, t4] = v.params::<20>();
    let q: [f64; 11] = q;
    let black = Cell::new(false);
    let o = dc_common(v, [t0, t1, t2, t3, t4], t, acc, rng, 1.0, |x, y| {
        let c = gmandel_rgb(x * zoom - pan_x, y * zoom - pan_y, q);
        black.set(c == [0.0; 3]);
        c
    });
    acc.hide = black.get();
    o
}
