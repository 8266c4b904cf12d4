//! JWildfire's curves drawn at random: `maurer_rose` (Maurer's rose: the chords joining the
//! points of the rose r = cos(k·θ) + c at steps of `line_offset_degrees`, with the points and
//! the rose itself; the input's angle chooses the chord) and `butterfly_fay` (Temple Fay's
//! butterfly curve at the input's angle, spread by the input's radius in one of six ways,
//! separately inside and outside the curve).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew. Random numbers are drawn in
//! the order JWildfire draws them.

use std::f64::consts::{PI, TAU};

use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("maurer_rose", maurer_rose)
        .params(&[
            p("maurer_rose_kn", 2.0),
            p("maurer_rose_kd", 1.0),
            p("maurer_rose_c", 0.0),
            p("maurer_rose_line_offset_degrees", 71.0),
            p("maurer_rose_line_count", 360.0),
            p("maurer_rose_show_lines", 1.0),
            p("maurer_rose_show_points", 0.0),
            p("maurer_rose_show_curve", 0.05),
            p("maurer_rose_line_thickness", 0.5),
            p("maurer_rose_point_thickness", 3.0),
            p("maurer_rose_curve_thickness", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .prepare(maurer_rose_prepare),
    VarDef::new("butterfly_fay", butterfly_fay)
        .params(&[
            p("butterfly_fay_offset", 0.0),
            p("butterfly_fay_unified_inner_outer", 1.0),
            p("butterfly_fay_outer_mode", 1.0),
            p("butterfly_fay_inner_mode", 1.0),
            p("butterfly_fay_outer_spread", 0.0),
            p("butterfly_fay_inner_spread", 0.0),
            p("butterfly_fay_outer_spread_ratio", 1.0),
            p("butterfly_fay_inner_spread_ratio", 1.0),
            p("butterfly_fay_spread_split", 1.0),
            p("butterfly_fay_cycles", 0.0),
            p("butterfly_fay_fill", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
];

/// k, the step, the cycles, the line and point thresholds, half the point band's end.
fn maurer_rose_prepare(v: &mut Prepared) {
    let [kn, kd, _, offset, count, lines, points, curve] = v.params();
    let step = TAU * (offset / 360.0);
    let cycles = (count * step) / TAU;
    let sum = lines + points + curve;
    let (lf, pf) = (lines / sum, points / sum);
    v.p.extend_from_slice(&[kn / kd, step, cycles, lf, lf + pf, lf + pf / 2.0]);
}

/// The rose r = cos(k·θ) + c at θ.
fn rose(k: f64, c: f64, theta: f64) -> (f64, f64) {
    let r = (k * theta).cos() + c;
    (r * theta.cos(), r * theta.sin())
}

/// maurer_rose: a random point of the chord (or of its ends, or of the rose) at the input's
/// angle, blurred by the thicknesses (in hundredths).
fn maurer_rose(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, c, _, _, _, _, _, line_w, point_w, curve_w] = v.params();
    let [k, step, cycles, line_th, point_th, half_th] = v.derived();
    let (line_w, point_w, curve_w) = (line_w / 100.0, point_w / 100.0, curve_w / 100.0);
    let angle = cycles * t.y.atan2(t.x);
    let theta1 = (angle / step).floor() * step;
    let (x1, y1) = rose(k, c, theta1);
    let (x2, y2) = rose(k, c, theta1 + step);
    let (xd, yd) = (x2 - x1, y2 - y1);
    let m = yd / xd;
    let len = (xd * xd + yd * yd).sqrt();
    let rnd = rng.f01();
    let (x, y) = if rnd < line_th {
        let d = rng.f01() * len;
        let mut xo = d / (1.0 + m * m).sqrt();
        if x2 < x1 {
            xo = -xo;
        }
        let mut yo = (m * xo).abs();
        if y2 < y1 {
            yo = -yo;
        }
        if line_w != 0.0 {
            xo += (rng.f01() - 0.5) * line_w;
            yo += (rng.f01() - 0.5) * line_w;
        }
        (x1 + xo, y1 + yo)
    } else if rnd <= point_th {
        let (mut xo, mut yo) = (0.0, 0.0);
        if point_w != 0.0 {
            let ro = rng.f01() * point_w;
            let ra = rng.f01() * TAU;
            (xo, yo) = (ro * ra.cos(), ro * ra.sin());
        }
        if rnd <= half_th {
            (x1 + xo, y1 + yo)
        } else {
            (x2 + xo, y2 + yo)
        }
    } else {
        let (cx, cy) = rose(k, c, angle);
        if curve_w != 0.0 {
            let dx = (rng.f01() - 0.5) * curve_w;
            (cx + dx, cy + (rng.f01() - 0.5) * curve_w)
        } else {
            (cx, cy)
        }
    };
    [v.w * x, v.w * y, 0.0]
}

/// The butterfly's point (x, y) spread by the input (ax, ay) of radius `rin` in `mode` (its
/// integer part; 0 or out of 1–5: no spread) with `spread` and `ratio` (for x); `inner` for
/// the modes' forms inside the curve.
fn butterfly_spread(
    mode: f64,
    (spread, ratio): (f64, f64),
    (x, y): (f64, f64),
    (ax, ay, rin): (f64, f64, f64),
    inner: bool,
) -> (f64, f64) {
    let signed = || {
        let xin = if x < 0.0 { -ax.abs() } else { ax.abs() };
        let yin = if y < 0.0 { -ay.abs() } else { ay.abs() };
        (xin, yin)
    };
    match mode.floor() as i32 {
        1 => {
            let rx = (rin * spread * ratio) - (spread * ratio) + 1.0;
            let ry = (rin * spread) - spread + 1.0;
            (rx * x, ry * y)
        }
        2 => {
            let (xin, yin) = signed();
            if inner {
                (x - spread * ratio * (x - xin), y - spread * (y - yin))
            } else {
                (x + spread * ratio * (xin - x), y + spread * (yin - y))
            }
        }
        3 => {
            let (xin, yin) = signed();
            if inner {
                (x - spread * ratio * xin, y - spread * yin)
            } else {
                (x + spread * ratio * xin, y + spread * yin)
            }
        }
        4 => ((0.5 * rin + spread * ratio) * x, (0.5 * rin + spread) * y),
        5 => (x + spread * ratio * ax, y + spread * ay),
        _ => (x, y),
    }
}

/// butterfly_fay: Fay's butterfly r = ½(e^cos t − 2 cos 4t − |sin(t/12)|⁵ + offset) at
/// t = cycles·angle (π² cycles, closing the curve, for 0), its radius blurred by `fill`.
fn butterfly_fay(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        offset,
        unified,
        outer_mode,
        inner_mode,
        outer,
        inner,
        outer_ratio,
        inner_ratio,
    ] = v.params();
    let [_, _, _, _, _, _, _, _, split, cycles, fill] = v.params();
    let n = if cycles == 0.0 { PI * PI } else { cycles };
    let a = n * t.y.atan2(t.x);
    let rin = split * (t.x * t.x + t.y * t.y).sqrt();
    let mut r =
        0.5 * (a.cos().exp() - 2.0 * (4.0 * a).cos() - (a / 12.0).sin().abs().powi(5) + offset);
    if fill != 0.0 {
        r += fill * (rng.f01() - 0.5);
    }
    let (x, y) = (r * a.sin(), -r * a.cos());
    let input = (t.x, t.y, rin);
    let (ox, oy) = if rin.abs() > r.abs() || unified != 0.0 {
        butterfly_spread(outer_mode, (outer, outer_ratio), (x, y), input, false)
    } else {
        butterfly_spread(inner_mode, (inner, inner_ratio), (x, y), input, true)
    };
    [v.w * ox, v.w * oy, 0.0]
}
