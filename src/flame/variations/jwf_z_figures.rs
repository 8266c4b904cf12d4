//! JWildfire's figures and mirrors of the plane, from the end of its alphabet: the
//! board-game figure `meeple`, Nic Anderson's mirror `tqmirror` and the rose curve `rhodonea`
//! with its inner and outer spreads.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::PI;

use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("meeple", meeple)
        .params(&[
            p("meeple_scale", 2.5),
            p_range("meeple_filled", 1.0, 0.0, 1.0),
            p("meeple_headWidth", 1.0),
            p("meeple_headHeight", 1.0),
            p("meeple_armLength", 2.0),
            p("meeple_armSpread", 1.0),
            p("meeple_bodyWidth", 1.0),
            p("meeple_legHeight", 1.0),
            p("meeple_legSpread", 1.0),
            p("meeple_legSeparationWidth", 0.1),
            p("meeple_legSeparationHeight", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("tqmirror", tqmirror)
        .params(&[
            p_int("tqmirror_preset", 0.0, NEG_INF, INF),
            p("tqmirror_a", 1.0),
            p("tqmirror_b", 1.0),
            p("tqmirror_c", 1.0),
            p("tqmirror_d", 1.0),
            p("tqmirror_e", 1.0),
            p("tqmirror_f", 1.0),
            p("tqmirror_g", 1.0),
            p("tqmirror_h", 1.0),
            p("tqmirror_i", 1.0),
            p("tqmirror_j", 1.0),
            p("tqmirror_k", 1.0),
            p("tqmirror_l", 0.0),
            p("tqmirror_m", 0.0),
            p("tqmirror_n", 0.0),
            p("tqmirror_o", 0.0),
            p("tqmirror_p", 0.0),
            p("tqmirror_q", 0.0),
            p("tqmirror_r", 1.0),
            p("tqmirror_s", 1.0),
            p_int("tqmirror_type", 0.0, 0.0, 1.0),
            p_int("tqmirror_mode", 0.0, 0.0, 2.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("rhodonea", rhodonea)
        .params(&[
            p("rhodonea_knumer", 3.0),
            p("rhodonea_kdenom", 4.0),
            p("rhodonea_inner_mode", 1.0),
            p("rhodonea_outer_mode", 1.0),
            p("rhodonea_inner_spread", 0.0),
            p("rhodonea_outer_spread", 0.0),
            p("rhodonea_inner_spread_ratio", 1.0),
            p("rhodonea_outer_spread_ratio", 1.0),
            p("rhodonea_spread_split", 1.0),
            p("rhodonea_fill", 0.0),
            p("rhodonea_radial_offset", 0.0),
            p("rhodonea_cycles", 0.0),
            p("rhodonea_cycle_offset", 0.0),
            p("rhodonea_metacycles", 1.0),
            p("rhodonea_metacycle_expansion", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::HIDES | flag::WRITES_ACC)
        .prepare(rhodonea_prepare),
];

/// The right half of the meeple's outline (head, arm, body, leg), bottom to top.
const MEEPLE_X: [f64; 14] = [
    0.00, 0.15, 0.28, 0.35, 0.35, 0.40, 0.55, 0.55, 0.45, 0.40, 0.45, 0.40, 0.20, 0.00,
];
const MEEPLE_Y: [f64; 14] = [
    -1.00, -0.99, -0.90, -0.75, -0.60, -0.50, -0.45, -0.25, -0.15, 0.10, 0.80, 0.98, 1.00, 0.85,
];

/// meeple: the outline of a board-game figure (head, arms, body and legs each stretched by
/// their parameters), mirrored at random, filled towards the centre with odds `filled`.
fn meeple(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        scale,
        filled,
        head_w,
        head_h,
        arm_len,
        arm_spread,
        body_w,
        leg_h,
        leg_spread,
        sep_w,
        sep_h,
    ] = v.params();
    let sep_y = MEEPLE_Y[9] - sep_h;
    let vertex = |i: usize| -> (f64, f64) {
        let (bx, by) = (MEEPLE_X[i], MEEPLE_Y[i]);
        match i {
            0..=4 => (bx * head_w, by * head_h),
            5..=8 => (
                MEEPLE_X[4] * body_w + (bx - MEEPLE_X[4]) * arm_len,
                MEEPLE_Y[4] * head_h + (by - MEEPLE_Y[4]) * arm_spread,
            ),
            9 => (bx * body_w, sep_y),
            _ => {
                let off = by - MEEPLE_Y[9];
                let y = if i == 13 { sep_y } else { MEEPLE_Y[9] } + off * leg_h;
                let x = if i <= 12 { bx * leg_spread + sep_w } else { bx };
                (x, y)
            }
        }
    };
    let segments = (MEEPLE_X.len() - 1) as f64;
    let s = rng.f01() * segments;
    let k = (s as usize).min(MEEPLE_X.len() - 2);
    let f = s - k as f64;
    let ((x1, y1), (x2, y2)) = (vertex(k), vertex(k + 1));
    let mut lx = x1 + (x2 - x1) * f;
    let ly = y1 + (y2 - y1) * f;
    if rng.f01() < 0.5 {
        lx = -lx;
    }
    let r = if filled > 0.0 && filled > rng.f01() {
        rng.f01()
    } else {
        1.0
    };
    [r * lx * scale * v.w, r * ly * scale * v.w, 0.0]
}

/// tqmirror: Nic Anderson's mirror: points beyond (l, m) (less the weighted d, e) are
/// swapped (type 0) or scaled by (r, s); those below (n, o) moved by the weighted (f, g); the
/// rest reflected in y = x inside a box the weight spans, else scaled (signs by `mode`). The
/// weight only places the box (JWildfire's `preset` only fills the other parameters).
fn tqmirror(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [
        _,
        a,
        b,
        c,
        d,
        e,
        f,
        g,
        h,
        i,
        j,
        k,
        l,
        m,
        n,
        o,
        p,
        q,
        r,
        s,
        kind,
        mode,
    ] = v.params();
    let (x, y, w) = (t.x, t.y, v.w);
    if w * d + x < l || w * e + y < m {
        return if kind != 0.0 {
            [x * r, y * s, 0.0]
        } else {
            [y * r, x * s, 0.0]
        };
    }
    if x < n && y < o {
        return [x + w * f, y + w * g, 0.0];
    }
    let inside = x + q < w && y < w * a && x + w * b > l && y + w * c > p;
    match (mode as i64, inside) {
        (0, true) | (1, true) => [-y * h, -x * i, 0.0],
        (0, false) => [x * j, y * k, 0.0],
        (1, false) => [-x * j, -y * k, 0.0],
        (2, true) => [y * h, -x * i, 0.0],
        (2, false) => [x * j, -y * k, 0.0],
        _ => [0.0; 3],
    }
}

/// The greatest common divisor of two whole numbers.
fn gcd(a: i64, b: i64) -> i64 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// rhodonea's number of turns: the one that closes the rose kn/kd (or 16 where it does not
/// close), times `metacycles`, unless `cycles` sets it.
fn rhodonea_prepare(v: &mut Prepared) {
    let [
        kn,
        kd,
        _,
        _,
        inner_spread,
        outer_spread,
        _,
        _,
        _,
        fill,
        radial_offset,
        cycles,
        _,
        metacycles,
    ] = v.params();
    let k = kn / kd;
    let to_close = if k % 1.0 == 0.0 {
        let open =
            radial_offset != 0.0 || inner_spread != 0.0 || outer_spread != 0.0 || fill != 0.0;
        if k % 2.0 == 0.0 || open { 1.0 } else { 0.5 }
    } else if kn % 1.0 == 0.0 && kd % 1.0 == 0.0 {
        let g = gcd(kn as i64, kd as i32 as i64) as f64;
        let (kn, kd) = if g != 1.0 { (kn / g, kd / g) } else { (kn, kd) };
        if kn % 2.0 == 0.0 || kd % 2.0 == 0.0 {
            kd
        } else {
            kd / 2.0
        }
    } else {
        16.0
    };
    let turns = if cycles == 0.0 {
        to_close * metacycles
    } else {
        cycles
    };
    v.p.extend_from_slice(&[k, to_close, turns]);
}

/// One side of rhodonea's split: the rose point (x, y) spread by the input as `mode` says
/// (0 none, 1 by the radius, 2 and 3 towards the input's quadrant-matched coordinates, 4 half
/// the radius plus the spread). `toward` is +1 outside the curve and −1 inside.
fn rose_spread(
    mode: i64,
    spread: f64,
    ratio: f64,
    toward: f64,
    rin: f64,
    pt: (f64, f64),
    t: &VarIn,
) -> (f64, f64) {
    let (x, y) = pt;
    let quadrant = || {
        let xin = if x < 0.0 { -t.x.abs() } else { t.x.abs() };
        let yin = if y < 0.0 { -t.y.abs() } else { t.y.abs() };
        (xin, yin)
    };
    match mode {
        1 => {
            let kx = rin * spread * ratio - spread * ratio + 1.0;
            let ky = rin * spread - spread + 1.0;
            (kx * x, ky * y)
        }
        2 => {
            let (xin, yin) = quadrant();
            (x + spread * ratio * (xin - x), y + spread * (yin - y))
        }
        3 => {
            let (xin, yin) = quadrant();
            (x + toward * spread * ratio * xin, y + toward * spread * yin)
        }
        4 => ((0.5 * rin + spread * ratio) * x, (0.5 * rin + spread) * y),
        _ => (x, y),
    }
}

/// rhodonea: the rose curve r = cos(k·θ) (k = knumer/kdenom) along the input's angle, turned
/// `cycles` times round (offset by `cycle_offset` turns), thickened by `fill`; points inside
/// and outside the curve (by the input's radius times `spread_split`) spread towards the input
/// by their own mode, amount and x/y ratio, or masked (modes 5 and 6); each closed turn grows
/// by `metacycle_expansion`.
fn rhodonea(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        inner_mode,
        outer_mode,
        inner_spread,
        outer_spread,
        inner_ratio,
        outer_ratio,
        split,
        fill,
        radial_offset,
        _,
        cycle_offset,
        _,
        expansion,
    ] = v.params();
    let [k, to_close, cycles] = v.derived();
    let mode = |m: f64| {
        let m = m.floor();
        if (0.0..=6.0).contains(&m) {
            m as i64
        } else {
            0
        }
    };
    let rin = split * (t.x * t.x + t.y * t.y).sqrt();
    let tin = t.y.atan2(t.x);
    let a = cycles * (tin + cycle_offset * 2.0 * PI);
    let mut r = (k * a).cos() + radial_offset;
    if fill != 0.0 {
        r += fill * (rng.f01() - 0.5);
    }
    let pt = (r * a.cos(), r * a.sin());
    let amount = v.w + ((cycles * (tin + PI)) / (to_close * 2.0 * PI)).floor() * expansion;
    let outside = rin.abs() > r.abs();
    let (m, spread, ratio, toward, mask_in, mask_out) = if outside {
        (mode(outer_mode), outer_spread, outer_ratio, 1.0, 5, 6)
    } else {
        (mode(inner_mode), inner_spread, inner_ratio, -1.0, 6, 5)
    };
    if m == mask_in {
        return [t.x, t.y, 0.0];
    }
    if m == mask_out {
        acc.hide = true;
        return [0.0; 3];
    }
    let (x, y) = rose_spread(m, spread, ratio, toward, rin, pt, t);
    let (ox, oy) = (amount * x, amount * y);
    if m == 1 && acc.y + oy == 0.0 {
        acc.x = 0.0;
        return [0.0, oy, 0.0];
    }
    [ox, oy, 0.0]
}
