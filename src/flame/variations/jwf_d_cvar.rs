//! JWildfire's variations of a complex function given as code, with the function JWildfire
//! ships as their default, f(z) = 1/z + exp(1/z) + 1: `c_var` (the point replaced by f of it,
//! zoomed and shifted; or f of a uniform point of [−1, 1]² with `mode` 1), its own `pre_c_var`
//! and `post_c_var` classes, and `cut_c` (hides the points where f lies ½ or more from the
//! nearest point of the integer lattice; the others with `invert`).
//!
//! ugnis evaluates the default function only; a flame whose `code` resource holds another
//! function is drawn with the default.
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew.

use super::jwf_a_cuts::{CUT, cut_end};
use super::*;

/// The parameters of the c_var variations, named for variation `$n`.
macro_rules! cvar_params {
    ($n:literal) => {
        &[
            p(concat!($n, "_shiftX"), 0.0),
            p(concat!($n, "_shiftY"), 0.0),
            p_int(concat!($n, "_mode"), 0.0, 0.0, 1.0),
            p(concat!($n, "_zoom"), 1.0),
        ]
    };
}

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("c_var", c_var)
        .params(cvar_params!("c_var"))
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_ACC),
    VarDef::new("pre_c_var", c_var)
        .params(cvar_params!("pre_c_var"))
        .flags(flag::JWILDFIRE | flag::PRE_ONLY | flag::RANDOM),
    VarDef::new("post_c_var", c_var)
        .params(cvar_params!("post_c_var"))
        .flags(flag::JWILDFIRE | flag::POST_ONLY | flag::RANDOM),
    VarDef::new("cut_c", cut_c)
        .params(&[
            p("cut_c_shiftX", 0.0),
            p("cut_c_shiftY", 0.0),
            p_int("cut_c_mode", 1.0, 0.0, 1.0),
            p("cut_c_zoom", 2.5),
            p_int("cut_c_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
];

/// JWildfire's default function: 1/z + exp(1/z) + exp(0).
fn default_f(x: f64, y: f64) -> (f64, f64) {
    let norm = (x * x + y * y).sqrt();
    let (ix, iy) = (x / (norm * norm), -y / (norm * norm));
    let e = ix.exp();
    (ix + e * iy.cos() + 1.0, iy + e * iy.sin() + 0.0)
}

/// The point a c_var variation evaluates: the input (`mode` 0) or a uniform point of
/// [−1, 1]², zoomed and shifted.
fn cvar_point(t: &VarIn, rng: &mut FastRng, [x0, y0, mode, zoom]: [f64; 4]) -> (f64, f64) {
    let (x, y) = if mode == 0.0 {
        (t.x, t.y)
    } else {
        let x = 2.0 * rng.f01() - 1.0;
        (x, 2.0 * rng.f01() - 1.0)
    };
    (x * zoom + x0, y * zoom + y0)
}

/// c_var (and its pre_/post_ classes): f of the point, times the weight, in place of the
/// point (the regular form replaces the xform's sum so far); z is kept.
fn c_var(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (zx, zy) = cvar_point(t, rng, v.params());
    let (fx, fy) = default_f(zx, zy);
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        return [v.w * fx, v.w * fy, 0.0];
    }
    [v.w * fx, v.w * fy, t.z]
}

/// cut_c: hides the points whose f lies at least ½ from the nearest lattice point.
fn cut_c(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [x0, y0, mode, zoom, invert] = v.params();
    let (x, y) = if mode == 0.0 {
        (t.x, t.y)
    } else {
        let x = 2.0 * rng.f01() - 1.0;
        (x, 2.0 * rng.f01() - 1.0)
    };
    let (fx, fy) = default_f(x * zoom + x0, y * zoom + y0);
    // Java's Math.round: halves rounded up.
    let (dx, dy) = (fx - (fx + 0.5).floor(), fy - (fy + 0.5).floor());
    let far = (dx * dx + dy * dy).sqrt() >= 0.5;
    cut_end(v, acc, far, invert, (x, y), 0.0)
}
