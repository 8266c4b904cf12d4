//! JWildfire's formulas for names of Fractorium's catalogue where JWildfire's variation has
//! parameters Fractorium's lacks (after Fractorium's, in JWildfire's names): `henon`'s and
//! `lozi`'s constant term `c` (Fractorium's fixed 1), `hypershift`'s `stretch`, `stwin`'s
//! offsets, `fdisc`'s shifts and terms, `mask`'s shifts and scales (and its hidden origin).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use crate::flame::variations::*;

pub(in crate::flame::variations) const DEFS: &[VarDef] = &[
    VarDef::new("henon", henon).params(&[p("henon_a", 0.5), p("henon_b", 1.0), p("henon_c", 1.0)]),
    VarDef::new("lozi", lozi).params(&[p("lozi_a", 0.5), p("lozi_b", 1.0), p("lozi_c", 1.0)]),
    VarDef::new("hypershift", hypershift)
        .params(&[p("hypershift_shift", 2.0), p("hypershift_stretch", 1.0)]),
    VarDef::new("stwin", stwin).params(&[
        p("stwin_distort", 1.0),
        p("stwin_offset_xy", 0.0),
        p("stwin_offset_x2", 0.0),
        p("stwin_offset_y2", 0.0),
    ]),
    VarDef::new("fdisc", fdisc).params(&[
        p("fdisc_ashift", 1.0),
        p("fdisc_rshift", 1.0),
        p("fdisc_xshift", 0.0),
        p("fdisc_yshift", 0.0),
        p("fdisc_term1", 1.0),
        p("fdisc_term2", 0.0),
        p("fdisc_term3", 0.0),
        p("fdisc_term4", 0.0),
    ]),
    VarDef::new("mask", mask)
        .params(&[
            p("mask_xshift", 0.0),
            p("mask_yshift", 0.0),
            p("mask_ushift", 1.0),
            p("mask_xscale", 1.0),
            p("mask_yscale", 1.0),
        ])
        .flags(flag::HIDES),
];

/// henon: the Hénon map (c − a·x² + y, b·x).
fn henon(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c] = v.params();
    [(c - a * (t.x * t.x) + t.y) * v.w, b * t.x * v.w, 0.0]
}

/// lozi: the Lozi map (c − a·|x| + y, b·x).
fn lozi(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c] = v.params();
    [(c - a * t.x.abs() + t.y) * v.w, b * t.x * v.w, 0.0]
}

/// hypershift: the hyperbolic shift by `shift` along x, its y stretched; added to the sum.
fn hypershift(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [shift, stretch] = v.params();
    let scale = 1.0 - shift * shift;
    let rad = 1.0 / (t.x * t.x + t.y * t.y);
    let (x, y) = (rad * t.x + shift, rad * t.y);
    let rad = v.w * scale / (x * x + y * y);
    [rad * x + shift, rad * y * stretch, 0.0]
}

/// stwin: w·p plus (x² − y²)/(x² + y²)·sin(2π·distort·(x + y + offset_xy/10)) of the point
/// scaled by w/20, with x² and y² offset by offset_x2, offset_y2 over 10 000.
fn stwin(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [distort, offset_xy, offset_x2, offset_y2] = v.params();
    let (x, y) = (t.x * v.w * 0.05, t.y * v.w * 0.05);
    let x2 = x * x + offset_x2 * 0.0001;
    let y2 = y * y + offset_y2 * 0.0001;
    let e = (x2 - y2) * (std::f64::consts::TAU * distort * (x + y + offset_xy * 0.1)).sin();
    let d = x2 + y2;
    let e = e / if d == 0.0 { 1.0 } else { d };
    [v.w * t.x + e, v.w * t.y + e, 0.0]
}

/// fdisc: the disc of angle 2π/(r + ashift) and radius (θ/π + rshift)/2, each coordinate's
/// angle shifted, mixed with the input by four terms.
fn fdisc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [ashift, rshift, xshift, yshift, term1, term2, term3, term4] = v.params();
    let a = std::f64::consts::TAU / (super::jwf_sqrt(t) + ashift);
    let r = (t.y.atan2(t.x) * std::f64::consts::FRAC_1_PI + rshift) * 0.5;
    let pr = v.w * r;
    let (prx, pry) = (pr * (a + xshift).cos(), pr * (a + yshift).sin());
    let mix = |c: f64, pc: f64| term1 * pc + term2 * c * pc + term3 * c * pr + term4 * c;
    [mix(t.x, prx), mix(t.y, pry), 0.0]
}

/// mask: w/r²·sin u·(cosh v + ushift)·sin²u and the same with cos u, u and v the scaled and
/// shifted x and y; the origin is hidden.
fn mask(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [xshift, yshift, ushift, xscale, yscale] = v.params();
    let sumsq = t.x * t.x + t.y * t.y;
    acc.hide = sumsq == 0.0;
    if acc.hide {
        return [0.0; 3];
    }
    let (u, w) = (xscale * t.x + xshift, yscale * t.y + yshift);
    let (su, cu) = u.sin_cos();
    let k = v.w / sumsq * (w.cosh() + ushift) * su * su;
    [k * su, k * cu, 0.0]
}
