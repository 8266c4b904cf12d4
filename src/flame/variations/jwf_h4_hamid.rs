//! Jesus Sosa's `hamid_js`: twenty of Hamid Naderi Yeganeh's "Math Art" figures
//! (https://mathematics.culturalspot.org/browse), each the k-th of `number_lines/circles`
//! segments (presets 0–9) or circles (10–19) whose ends, centres and radii are trigonometric
//! functions of k; a call draws a random k and a random point of that segment or circle
//! (filled discs with `filled circles` 1). The parameters `a` … `p` scale the frequencies and
//! terms (1 gives the published figures).
//!
//! The formulas follow JWildfire 9.00 (`HamidFunc`, LGPL-2.1), written anew.

use std::f64::consts::PI;

use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("hamid_js", hamid)
    .params(&[
        p_int("hamid_js_presetId", 0.0, 0.0, 19.0),
        p_int(
            "hamid_js_number_lines/circles",
            2000.0,
            -2147483648.0,
            2147483647.0,
        ),
        p_int("hamid_js_filled circles", 1.0, -2147483648.0, 2147483647.0),
        p("hamid_js_a", 1.0),
        p("hamid_js_b", 1.0),
        p("hamid_js_c", 1.0),
        p("hamid_js_d", 1.0),
        p("hamid_js_e", 1.0),
        p("hamid_js_f", 1.0),
        p("hamid_js_g", 1.0),
        p("hamid_js_h", 1.0),
        p("hamid_js_i", 1.0),
        p("hamid_js_j", 1.0),
        p("hamid_js_k", 1.0),
        p("hamid_js_l", 1.0),
        p("hamid_js_m", 1.0),
        p("hamid_js_n", 1.0),
        p("hamid_js_o", 1.0),
        p("hamid_js_p", 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM)];

/// A point of the outline of the unit square walked from (0, 0) in 400 steps of 1/100
/// (preset 9's segment ends).
fn square_walk(mut n: i64) -> (f64, f64) {
    if n >= 400 {
        n %= 400;
    }
    let f = |v: i64| v as f64 / 100.0;
    match n {
        _ if n < 100 => (f(n), 0.0),
        _ if n < 200 => (1.0, f(n - 100)),
        _ if n < 300 => (f(300 - n), 1.0),
        _ => (0.0, f(400 - n)),
    }
}

/// A random point of the segment from (x1, y1) to (x2, y2), placed along it by slope as
/// JWildfire's line drawing does (a vertical segment takes slope 10000).
fn on_segment(rng: &mut FastRng, (x1, y1): (f64, f64), (x2, y2): (f64, f64)) -> (f64, f64) {
    let (dx, dy) = (x2 - x1, y2 - y1);
    let m = if dx == 0.0 { 10000.0 } else { dy / dx };
    let len = (dx * dx + dy * dy).sqrt();
    let d = rng.f01() * len;
    let mut xo = d / (1.0 + m * m).sqrt();
    if x2 < x1 {
        xo = -xo;
    }
    let mut yo = (m * xo).abs();
    if y2 < y1 {
        yo = -yo;
    }
    (x1 + xo, y1 + yo)
}

/// The ends of segment `i` of `n` for presets 0 to 9.
fn segment(preset: i64, q: &[f64; 19], i: i64, n: f64) -> ((f64, f64), (f64, f64)) {
    let [_, _, _, a, b, c, d, e, f, g, h, ii, j, k, ..] = *q;
    let fi = i as f64;
    // sin and cos of k·π·i/n.
    let s = |k: f64| (k * PI * fi / n).sin();
    let co = |k: f64| (k * PI * fi / n).cos();
    match preset {
        0 => (
            (-s(4.0 * a), -co(2.0 * b)),
            (-0.5 * e * s(8.0 * c), -0.5 * f * co(4.0 * d)),
        ),
        1 => (
            (-s(2.0 * a), -co(2.0 * b)),
            (-0.5 * e * s(8.0 * c), -0.5 * f * co(12.0 * d)),
        ),
        2 => (
            (-s(8.0 * a), -co(2.0 * b)),
            (-0.5 * e * s(6.0 * c), -0.5 * f * co(2.0 * d)),
        ),
        3 => (
            (-s(10.0 * a), -co(2.0 * b)),
            (-0.5 * e * s(12.0 * c), -0.5 * f * co(2.0 * d)),
        ),
        4 => {
            let t = |k: f64| k * PI * (fi + 699.0) / n;
            (
                (t(10.0 * a).sin(), t(8.0 * b).cos()),
                (t(12.0 * c).sin(), t(10.0 * d).cos()),
            )
        }
        5 => (
            (
                -2.0 * a * (4.0 * b * PI * fi / 1000.0).cos(),
                0.5 * c * co(6.0 * d).powf(3.0 * ii),
            ),
            (
                -2.0 * e * s(6.0 * f) / 15.0 * j,
                4.0 * g * s(2.0 * h) / 15.0 * k,
            ),
        ),
        6 => (
            (3.0 * a * s(2.0 * b).powf(3.0 * h), -co(8.0 * c)),
            (1.5 * d * s(2.0 * e).powf(3.0 * ii), -0.5 * f * co(6.0 * g)),
        ),
        7 => (
            (co(6.0 * a), -co(8.0 * b)),
            (1.5 * c * s(2.0).powf(3.0 * f), -0.5 * d * co(6.0 * e)),
        ),
        8 => (
            (s(20.0 * a).powi(3), co(18.0 * b).powf(3.0 * e)),
            (s(16.0 * c).powi(3), co(14.0 * d).powf(3.0 * f)),
        ),
        _ => (square_walk(i), square_walk(i + 199)),
    }
}

/// The centre and radius of circle `i` of `n` for presets 10 to 19.
fn circle(preset: i64, q: &[f64; 19], i: i64, n: f64) -> (f64, f64, f64) {
    let [_, _, _, a, b, c, d, e, f, g, h, ii, j, k, l, m, nn, o, p] = *q;
    let fi = i as f64;
    let s = |k: f64| (k * PI * fi / n).sin();
    let co = |k: f64| (k * PI * fi / n).cos();
    match preset {
        10 => (
            2.0 * a * s(2.0 * b) / 3.0
                + s(36.0 * c) * co(30.0 * d) / 3.0 * k
                + s(14.0).powf(3.0 * l) / 3.0 * m,
            2.0 * e * co(2.0 * f) / 3.0 * nn
                + co(36.0 * g) * co(30.0 * h) / 3.0 * o
                + co(14.0 * ii).powi(3) / 5.0 * p,
            1.0 / 150.0 + s(36.0 * j).powi(4) / 9.0,
        ),
        11 => (s(14.0 * a), co(32.0 * b), s(20.0 * c).powi(2) / 3.0 * d),
        12 => (
            2.0 * a * s(6.0 * b) / 3.0
                + s(36.0 * c) * co(30.0 * d) / 4.0
                + s(14.0 * e).powf(3.0 * k) / 4.0 * l,
            2.0 * f * co(6.0 * g) / 3.0
                + co(28.0 * h) * co(30.0 * ii) / 3.0
                + co(14.0).powf(3.0 * m) / 5.0 * nn,
            1.0 / 150.0 + s(36.0 * j).powf(4.0 * o) / 20.0 * p,
        ),
        13 => (
            s(10.0 * a),
            co(28.0 * b).powf(3.0 * e),
            s(18.0 * c).powi(2) / 3.0 * d,
        ),
        14 => (
            2.0 * a * s(18.0 * b) / 3.0
                + s(40.0 * c).powi(3) * co(30.0 * d) / 3.0
                + s(34.0 * e).powf(3.0 * k) / 4.0 * l,
            2.0 * f * co(18.0 * g) / 3.0
                + co(28.0 * h).powi(3) * co(40.0) / 3.0
                + co(34.0 * ii).powf(3.0 * m) / 3.0 * nn,
            1.0 / 150.0 + s(56.0 * j).powf(4.0 * o) / 8.0 * p,
        ),
        15 => (
            2.0 * a * s(14.0 * b) / 3.0
                + s(10.0 * c).powi(3) * co(28.0 * d) / 3.0
                + s(46.0 * e).powf(3.0 * m) / 3.0 * nn,
            2.0 * co(14.0 * f) / 3.0
                + co(10.0 * g).powi(3) * co(28.0 * h) / 3.0
                + co(34.0 * j).powf(3.0 * o) / 3.0,
            1.0 / 150.0 + s(72.0 * k).powi(6) / 9.0 + s(12.0 * l).powi(4) / 20.0 * p,
        ),
        16 => (
            s(38.0 * a) * co(26.0 * b) / 2.0 + s(18.0 * c).powf(3.0 * l) / 2.0 * m,
            2.0 * co(18.0 * d) / 3.0
                + co(38.0 * e) * co(36.0 * f) / 3.0
                + co(18.0 * g).powf(3.0 * nn) / 4.0 * o,
            1.0 / 150.0
                + s(18.0 * h).powi(10) * s(100.0 * ii).powi(6) / 100.0
                + s(72.0 * j).powi(8) * co(18.0 * k).powi(6) / 20.0 * p,
        ),
        17 => (
            2.0 * a * s(10.0 * b)
                + s(6.0 * c).powi(3) * co(28.0 * d) / 3.0
                + s(126.0 * e) / 10.0 * l,
            2.0 * co(6.0 * f) / 3.0
                + co(18.0 * g).powi(3) * co(36.0 * h) / 3.0
                + co(126.0 * ii) / 10.0 * m,
            1.0 / 150.0 + s(48.0 * j).powi(4) * (1.0 + s(12.0 * k).powf(2.0 * nn)) / 18.0 * o,
        ),
        18 => (
            2.0 * a * s(18.0 * b) / 5.0
                + s(34.0 * c).powf(3.0 * j) / 3.0 * k
                + s(50.0 * d).powf(3.0 * l) / 3.0 * m,
            2.0 * co(18.0 * e) / 3.0
                + co(34.0 * f).powi(3) / 3.0
                + co(50.0 * g).powf(3.0 * nn) / 10.0 * o,
            1.0 / 150.0 + s(58.0 * ii).powi(4) / 10.0 * p,
        ),
        _ => (
            co(10.0 * a) * (c - s(16.0 * b).powf(2.0 * h) / 2.0 * ii),
            s(10.0 * d) * (f - co(34.0 * e).powf(2.0 * j) / 2.0 * k),
            1.0 / 200.0 + s(52.0 * g).powf(4.0 * l) / 10.0 * m,
        ),
    }
}

/// hamid_js: a random point of a random segment or circle of the preset's figure.
fn hamid(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 19] = v.params();
    let (preset, n, filled) = (q[0] as i64, q[1], q[2]);
    let i = (rng.f01() * n + 1.0) as i64;
    let (x, y) = if preset < 10 {
        let (p1, p2) = segment(preset, &q, i, n);
        on_segment(rng, p1, p2)
    } else {
        let (x, y, mut radius) = circle(preset, &q, i, n);
        if filled == 1.0 && rng.f01() > 0.05 {
            radius *= rng.f01();
        }
        let (s, c) = (rng.f01() * 2.0 * PI).sin_cos();
        (x + radius * c, y + radius * s)
    };
    [v.w * x, v.w * y, 0.0]
}
