//! JWildfire's orbit variations: each call takes the next point of a 2-D map's orbit,
//! carried from call to call, whatever the input — `macmillan` (McMillan's map, two steps a
//! call), `hopalong` (Barry Martin's map), `threeply` (Martin's "three-ply" map, replacing
//! the sum so far) and `curliecue2` (a curlicue fractal, its turning rate drawn from Java's
//! generator seeded with `seed`).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1)
//! mathematics, written anew. The orbit lives in the variation's state: the point in slots 0
//! and 1, slot 3 marking it started (curliecue2: point and two angles in slots 0–3, all 0 at
//! the start).

use super::jwf_a_cuts::JavaRandom;
use super::*;

const ORBIT: u32 = flag::JWILDFIRE | flag::STATEFUL | flag::OWN_ORBIT;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("macmillan", macmillan)
        .params(&[
            p("macmillan_a", 1.6),
            p("macmillan_b", 0.4),
            p("macmillan_startx", 0.1),
            p("macmillan_starty", 0.1),
        ])
        .flags(ORBIT),
    VarDef::new("hopalong", hopalong)
        .params(&[
            p_int("hopalong_random", 1.0, 0.0, 10_000_000.0),
            p_range("hopalong_a", 0.75, -1.0, 1.0),
            p_range("hopalong_b", 0.5, -1.0, 1.0),
            p_range("hopalong_c", 0.25, -1.0, 1.0),
            p("hopalong_startx", 0.0),
            p("hopalong_starty", 0.0),
        ])
        .flags(ORBIT),
    VarDef::new("threeply", threeply)
        .params(&[
            p("threeply_a", -55.0),
            p("threeply_b", -1.0),
            p("threeply_c", -42.0),
        ])
        .flags(ORBIT | flag::WRITES_ACC),
    VarDef::new("curliecue2", curliecue2)
        .params(&[p_int("curliecue2_seed", 1000.0, NEG_INF, INF)])
        .flags(ORBIT)
        .prepare(curliecue2_prepare),
];

/// The orbit's point so far (slots 0 and 1), or `start` before the first call.
fn orbit_point(v: &Prepared, start: (f64, f64)) -> (f64, f64) {
    if v.state.get(3) == 1.0 {
        (v.state.get(0), v.state.get(1))
    } else {
        start
    }
}

fn set_orbit_point(v: &Prepared, (x, y): (f64, f64)) {
    v.state.set(0, x);
    v.state.set(1, y);
    v.state.set(3, 1.0);
}

/// McMillan's map y' = −x + 2a·y/(1 + y²) + b·y, x' = y, two steps a call (the state: the
/// previous x and y).
fn macmillan(v: &Prepared, _: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, x0, y0] = v.params();
    let (mut xa, mut y) = orbit_point(v, (x0, y0));
    let step = |xa: f64, y: f64| -xa + 2.0 * a * (y / (1.0 + y * y)) + b * y;
    let x = y;
    y = step(xa, y);
    xa = x;
    let x = y;
    y = step(xa, y);
    set_orbit_point(v, (x, y));
    [v.w * x, v.w * y, 0.0]
}

/// Martin's hopalong map (y − sign x·√|b·x − c|, a − x).
fn hopalong(v: &Prepared, _: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, a, b, c, x0, y0] = v.params();
    let (x0, y0) = orbit_point(v, (x0, y0));
    let sign = if x0 > 0.0 {
        1.0
    } else if x0 < 0.0 {
        -1.0
    } else {
        0.0
    };
    let x1 = y0 - sign * (b * x0 - c).abs().sqrt();
    let y1 = a - x0;
    set_orbit_point(v, (x1, y1));
    [v.w * x1, v.w * y1, 0.0]
}

/// Martin's three-ply map (y − sign x·|sin x·cos b + c − x·sin(a + b + c)|, a − x) from the
/// origin, scaled by 1/1000; replaces the sum so far.
fn threeply(v: &Prepared, _: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c] = v.params();
    let (x0, y0) = orbit_point(v, (0.0, 0.0));
    let sign = if x0 > 0.0 {
        1.0
    } else if x0 < 0.0 {
        -1.0
    } else {
        0.0
    };
    let xn = y0 - sign * (x0.sin() * b.cos() + c - x0 * (a + b + c).sin()).abs();
    let yn = a - x0;
    set_orbit_point(v, (xn, yn));
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [0.001 * xn * v.w, 0.001 * yn * v.w, 0.0]
}

fn curliecue2_prepare(v: &mut Prepared) {
    let [seed] = v.params();
    let s = JavaRandom::new(seed as i64).next_f64();
    v.p.push(s);
}

/// A curlicue: steps of 1/1000 in direction φ, φ turning by θ and θ by 2π·s (both modulo
/// 2π), s the first draw of Java's generator seeded with `seed`. The state (all 0 at the
/// start): the point and the two angles.
fn curliecue2(v: &Prepared, _: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    use std::f64::consts::TAU;
    let [s] = v.derived();
    let st = &v.state;
    let (theta, phi) = (st.get(2), st.get(3));
    let x = st.get(0) + 0.001 * phi.cos();
    let y = st.get(1) + 0.001 * phi.sin();
    st.set(0, x);
    st.set(1, y);
    st.set(3, (theta + phi) % TAU);
    st.set(2, (theta + TAU * s) % TAU);
    [v.w * x, v.w * y, 0.0]
}
