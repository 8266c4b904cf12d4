//! JWildfire's `maurer_lines` (JWildfire 9.00, `MaurerLinesFunc`, by Gregg Helt; after Peter
//! Maurer's rose, "A Rose is a Rose…", Amer. Math. Monthly 94, 1987, and Helt's "A Rose by Any
//! Other Name…", Bridges 2016): the chords joining the points of one of nineteen curves at
//! equal steps of its parameter, drawn in one of 25 render modes. The input's angle (or a
//! random angle) picks the chord, a random fraction the point on it. Cosets (Maurer's and
//! Helt's) start the polyline at a random coset; a "meta" mode draws one of several values of
//! the step, a shape value or a render modifier per call; points and the curve itself can be
//! shown beside the chords. Filters hide points by a measure of their chord (length, angles,
//! the distance along it) and the colour follows such a measure.
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew; random numbers are drawn in
//! the order JWildfire draws them (JWildfire mixes its own generator and Java's
//! `Math.random()`, both ugnis' generator here). The 1,000 chords JWildfire samples at
//! initialisation for its percentile thresholds are sampled from a fixed seed.
//!
//! Limits: JWildfire's filter list grows with `number_of_filters`; ugnis keeps four filters
//! (`filter1_*` … `filter4_*`), more are ignored. The line-thickness strategies other than
//! JWildfire's fixed "random" one are unreachable there and not implemented.

use std::f64::consts::{E, TAU};

use super::jwf_s10_maurer_curves::{Curve, gcd};
use super::jwf_s10_maurer_render::{Chord, Style, draw};
use super::*;

/// Largest integer parameter value (Java's `int`).
const IMAX: f64 = 2147483647.0;
/// Smallest integer parameter value.
const IMIN: f64 = -2147483648.0;
/// How many filters ugnis keeps.
const FILTERS: usize = 4;
/// Chords sampled for the percentile thresholds.
const SAMPLES: usize = 1000;
/// Seed of that sample.
const SAMPLE_SEED: u64 = 0x4d61_7572_6572;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("maurer_lines", maurer_lines)
    .params(&[
        p_int("maurer_lines_curve_mode", 3.0, IMIN, IMAX),
        p("maurer_lines_a", 2.0),
        p("maurer_lines_b", 1.0),
        p("maurer_lines_c", 0.0),
        p("maurer_lines_d", 1.0),
        p("maurer_lines_theta_step_size", 71.0),
        p("maurer_lines_initial_theta", 0.0),
        p("maurer_lines_line_count", 360.0),
        p("maurer_lines_irrationalize", 0.0),
        p_int("maurer_lines_render_mode", 0.0, IMIN, IMAX),
        p_int("maurer_lines_render_submode", 0.0, IMIN, IMAX),
        p_int("maurer_lines_tangent_submode", 0.0, IMIN, IMAX),
        p("maurer_lines_render_modifier1", 1.0),
        p("maurer_lines_render_modifier2", 1.0),
        p("maurer_lines_render_modifier3", 1.0),
        p_int("maurer_lines_cosets_mode", 0.0, IMIN, IMAX),
        p_int("maurer_lines_direct_color_measure", 1.0, IMIN, IMAX),
        p_int("maurer_lines_direct_color_gradient", 0.0, IMIN, IMAX),
        p_int("maurer_lines_direct_color_thresholding", 0.0, IMIN, IMAX),
        p("maurer_lines_color_low_threshold", 0.3),
        p("maurer_lines_color_high_threshold", 2.0),
        p_int("maurer_lines_number_of_filters", 0.0, IMIN, IMAX),
        p_int("maurer_lines_filter1_mode", 1.0, IMIN, IMAX),
        p_int("maurer_lines_filter1_measure", 1.0, IMIN, IMAX),
        p("maurer_lines_filter1_low_threshold", 0.0),
        p("maurer_lines_filter1_high_threshold", 1.0),
        p_int("maurer_lines_filter2_operator", 0.0, IMIN, IMAX),
        p_int("maurer_lines_filter2_mode", 1.0, IMIN, IMAX),
        p_int("maurer_lines_filter2_measure", 1.0, IMIN, IMAX),
        p("maurer_lines_filter2_low_threshold", 0.0),
        p("maurer_lines_filter2_high_threshold", 1.0),
        p_int("maurer_lines_filter3_operator", 0.0, IMIN, IMAX),
        p_int("maurer_lines_filter3_mode", 1.0, IMIN, IMAX),
        p_int("maurer_lines_filter3_measure", 1.0, IMIN, IMAX),
        p("maurer_lines_filter3_low_threshold", 0.0),
        p("maurer_lines_filter3_high_threshold", 1.0),
        p_int("maurer_lines_filter4_operator", 0.0, IMIN, IMAX),
        p_int("maurer_lines_filter4_mode", 1.0, IMIN, IMAX),
        p_int("maurer_lines_filter4_measure", 1.0, IMIN, IMAX),
        p("maurer_lines_filter4_low_threshold", 0.0),
        p("maurer_lines_filter4_high_threshold", 1.0),
        p("maurer_lines_randomize", 0.0),
        p("maurer_lines_diff_mode", 0.0),
        p_int("maurer_lines_meta_mode", 0.0, IMIN, IMAX),
        p("maurer_lines_meta_min_step", 30.0),
        p("maurer_lines_meta_max_step", 45.0),
        p("maurer_lines_meta_step_diff", 1.0),
        p("maurer_lines_show_points", 0.0),
        p("maurer_lines_show_curve", 0.0),
        p("maurer_lines_line_thickness", 0.1),
        p("maurer_lines_point_thickness", 1.0),
        p("maurer_lines_curve_thickness", 0.5),
        p("maurer_lines_e", 1.0),
        p("maurer_lines_f", 1.0),
        p("maurer_lines_g", 1.0),
        p("maurer_lines_h", 1.0),
    ])
    .flags(
        flag::JWILDFIRE
            | flag::RANDOM
            | flag::WRITES_Z
            | flag::USES_Z
            | flag::SETS_COLOR
            | flag::HIDES
            | flag::WRITES_ACC,
    )
    .prepare(maurer_prepare)];

/// Indices of the parameters.
mod ix {
    pub const CURVE: usize = 0;
    pub const A: usize = 1;
    pub const STEP: usize = 5;
    pub const INITIAL: usize = 6;
    pub const COUNT: usize = 7;
    pub const IRRATIONALIZE: usize = 8;
    pub const RENDER: usize = 9;
    pub const MODIFIERS: usize = 12;
    pub const COSETS: usize = 15;
    pub const COLOR_MEASURE: usize = 16;
    pub const GRADIENT: usize = 17;
    pub const THRESHOLDING: usize = 18;
    pub const COLOR_LOW: usize = 19;
    pub const COLOR_HIGH: usize = 20;
    pub const FILTER_COUNT: usize = 21;
    /// filter1: mode, measure, low, high; filter k ≥ 2 at FILTER2 + 5·(k − 2): operator,
    /// mode, measure, low, high.
    pub const FILTER1: usize = 22;
    pub const FILTER2: usize = 26;
    pub const RANDOMIZE: usize = 41;
    pub const DIFF: usize = 42;
    pub const META: usize = 43;
    pub const SHOW_POINTS: usize = 47;
    pub const E: usize = 52;
    pub const COUNT_ALL: usize = 56;
}

/// Derived values (after the parameters): the step, initial angle and turns of the chords;
/// the coset count (gcd), the line count z, the coset step, the turns closing a coset's
/// polyline and the curve; the meta steps; whether the sample follows; then the sorted
/// sample: line lengths, line angles, point angles, speeds, parameters (`SAMPLES` each).
const DERIVED: usize = 10;

/// The per-call settings JWildfire's `setValues` makes: step, initial angle, turns, shape
/// values, render modifiers and the meta step drawn.
#[derive(Clone, Copy, Debug)]
struct Call {
    step: f64,
    initial: f64,
    cycles: f64,
    curve: Curve,
    m: [f64; 3],
    meta_step: f64,
}

/// JWildfire's `setValues`: the coset and the meta value of this call (drawn in that order).
fn set_values(p: &[f64], d: &[f64], rng: &mut FastRng) -> Call {
    let mut s = [0.0; 8];
    s[..4].copy_from_slice(&p[ix::A..ix::A + 4]);
    s[4..].copy_from_slice(&p[ix::E..ix::E + 4]);
    let mut call = Call {
        step: d[0],
        initial: d[1],
        cycles: d[2],
        curve: Curve {
            mode: p[ix::CURVE] as i32,
            s,
        },
        m: [p[ix::MODIFIERS], p[ix::MODIFIERS + 1], p[ix::MODIFIERS + 2]],
        meta_step: 0.0,
    };
    let cosets = p[ix::COSETS] as i32;
    let (coset_gcd, coset_z, coset_step, close_polyline, close_curve) =
        (d[3], d[4], d[5], d[6], d[7]);
    if cosets != 0 {
        call.step = coset_step;
        call.cycles = close_polyline;
        if coset_gcd == 1.0 {
            call.initial = 0.0;
        } else if (1..=3).contains(&cosets) {
            let id = (rng.f01() * coset_gcd).floor() as i32 as f64;
            let full = if cosets == 1 { TAU } else { close_curve * TAU };
            call.initial = full * (id / coset_z);
        }
    }
    let meta = p[ix::META] as i32;
    if meta != 0 {
        let [min, _, diff] = [p[ix::META + 1], p[ix::META + 2], p[ix::META + 3]];
        call.meta_step = (rng.f01() * d[8]) as i32 as f64;
        let value = min + call.meta_step * diff;
        match meta {
            1 => {
                let mut offset = value;
                if p[ix::IRRATIONALIZE] != 0.0 {
                    offset += p[ix::IRRATIONALIZE] * 0.01 * E;
                }
                call.step = TAU * (offset / 360.0);
                call.cycles = (p[ix::COUNT] * call.step) / TAU;
            }
            8 => call.initial = TAU * (value / 360.0),
            2..=7 => call.curve.s[(meta - 2) as usize] = value,
            9 => {
                call.curve.s[0] = value;
                call.curve.s[1] = p[ix::A + 1] + call.meta_step * diff;
            }
            10..=12 => call.m[(meta - 10) as usize] = value,
            _ => {}
        }
    }
    call
}

/// Java's `int` remainder and product for the coset arithmetic (0 where Java would throw).
fn idiv(a: i32, b: i32) -> i32 {
    if b == 0 { 0 } else { a.wrapping_div(b) }
}

/// The derived values, and the sample where a percentile threshold needs it.
fn maurer_prepare(v: &mut Prepared) {
    let p: Vec<f64> = v.p[..ix::COUNT_ALL].to_vec();
    let mut s = [0.0; 8];
    s[..4].copy_from_slice(&p[ix::A..ix::A + 4]);
    s[4..].copy_from_slice(&p[ix::E..ix::E + 4]);
    let curve = Curve {
        mode: p[ix::CURVE] as i32,
        s,
    };
    let (step_deg, count, irr) = (p[ix::STEP], p[ix::COUNT], p[ix::IRRATIONALIZE]);
    let mut step = TAU * (step_deg / 360.0);
    if irr != 0.0 {
        step += (irr * 0.01 * E) / 360.0;
    }
    let initial = TAU * (p[ix::INITIAL] / 360.0);
    let cycles = (count * step) / TAU;
    let coset_d = step_deg.floor() as i32;
    let mut coset_z = count.floor() as i32;
    let mut close_curve = curve.cycles_to_close();
    if close_curve.is_nan() {
        close_curve = 1.0;
    }
    let cosets = p[ix::COSETS] as i32;
    if cosets == 3 {
        coset_z = (f64::from(coset_z) * close_curve) as i32;
    }
    let coset_gcd = gcd(i64::from(coset_d), i64::from(coset_z)) as i32;
    let coset_lcm = coset_d
        .wrapping_abs()
        .wrapping_mul(idiv(coset_z.wrapping_abs(), coset_gcd));
    let (mut close_polyline, mut coset_step) = (0.0, 0.0);
    let ratio = f64::from(coset_d) / f64::from(coset_z);
    if cosets == 1 {
        close_polyline = f64::from(idiv(coset_lcm, coset_z));
        coset_step = TAU * ratio;
    } else if cosets == 2 || cosets == 3 {
        close_polyline = close_curve * f64::from(idiv(coset_lcm, coset_z));
        coset_step = close_curve * TAU * ratio;
    }
    let meta = p[ix::META] as i32;
    let meta_steps = ((p[ix::META + 2] - p[ix::META + 1]) / p[ix::META + 3]) as i32 as f64;
    let color_on = p[ix::COLOR_MEASURE] as i32 != 0 && p[ix::GRADIENT] as i32 != 0;
    let color_percent = color_on
        && p[ix::THRESHOLDING] as i32 == 0
        && !(p[ix::COLOR_MEASURE] as i32 == 4 && meta != 0);
    let filter_percent = (0..filter_count(&p)).any(|k| {
        let (_, mode, _, _, _) = filter(&p, k);
        mode == 3 || mode == 4
    });
    let sampled = color_percent || filter_percent;
    let d = [
        step,
        initial,
        cycles,
        f64::from(coset_gcd),
        f64::from(coset_z),
        coset_step,
        close_polyline,
        close_curve,
        meta_steps,
        if sampled { 1.0 } else { 0.0 },
    ];
    v.p.extend_from_slice(&d);
    if sampled {
        let mut rng = FastRng::new(SAMPLE_SEED);
        let mut cols: [Vec<f64>; 5] = Default::default();
        for _ in 0..SAMPLES {
            let call = set_values(&p, &d, &mut rng);
            let theta1 = rng.f01() * call.cycles * TAU;
            let theta2 = theta1 + call.step;
            let (x1, y1) = call.curve.point(theta1);
            let (x2, y2) = call.curve.point(theta2);
            let ch = measures(x1, y1, x2, y2);
            cols[0].push(ch.0);
            cols[1].push(ch.1);
            cols[2].push(ch.2);
            cols[3].push(call.curve.speed(theta1));
            cols[4].push(theta1 / TAU);
        }
        for c in &mut cols {
            // Java's order for doubles: NaN after everything.
            c.sort_by(|a, b| a.is_nan().cmp(&b.is_nan()).then(a.total_cmp(b)));
            v.p.extend_from_slice(c);
        }
    }
}

/// A chord's length, line angle (0 along y … 1 along x) and point angle (the angle between
/// its ends seen from the origin, 0…π).
fn measures(x1: f64, y1: f64, x2: f64, y2: f64) -> (f64, f64, f64) {
    let (xd, yd) = (x2 - x1, y2 - y1);
    let raw = yd.atan2(xd);
    let line_angle = (raw.abs() - TAU / 4.0).abs() / (TAU / 4.0);
    let length = (xd * xd + yd * yd).sqrt();
    let turn = |a: f64| if a < 0.0 { a + TAU } else { a };
    let mut pa = (turn(y2.atan2(x2)) - turn(y1.atan2(x1))).abs();
    if pa > TAU / 2.0 {
        pa = TAU - pa;
    }
    (length, line_angle, pa)
}

/// How many filters are in use (at most [`FILTERS`]).
fn filter_count(p: &[f64]) -> usize {
    (p[ix::FILTER_COUNT].max(0.0) as usize).min(FILTERS)
}

/// Filter `k` (0-based): operator, mode, measure, low and high threshold.
fn filter(p: &[f64], k: usize) -> (i32, i32, i32, f64, f64) {
    if k == 0 {
        let f = &p[ix::FILTER1..ix::FILTER1 + 4];
        (0, f[0] as i32, f[1] as i32, f[2], f[3])
    } else {
        let at = ix::FILTER2 + 5 * (k - 1);
        let f = &p[at..at + 5];
        (f[0] as i32, f[1] as i32, f[2] as i32, f[3], f[4])
    }
}

/// The sorted sample of measure column `col` (empty when none was taken).
fn sample(v: &Prepared, col: usize) -> &[f64] {
    if v.derived::<DERIVED>()[9] == 0.0 {
        return &[];
    }
    let t = v.table(DERIVED);
    t.get(col * SAMPLES..(col + 1) * SAMPLES).unwrap_or(&[])
}

/// Entry `i` of a sample (NaN without one).
fn at(s: &[f64], i: usize) -> f64 {
    s.get(i).copied().unwrap_or(f64::NAN)
}

/// What the filters and the colour measure of a drawn point.
struct Measured {
    length: f64,
    line_angle: f64,
    point_angle: f64,
    delta: f64,
    mid: f64,
    z: f64,
}

/// The value of filter measure `measure` and its sample column (None: the distance measures,
/// whose percentiles are fractions of the chord).
fn filter_value(m: &Measured, measure: i32) -> (f64, Option<usize>) {
    match measure {
        2 => (m.line_angle, Some(1)),
        3 => (m.point_angle, Some(2)),
        7 => (m.delta, None),
        8 => ((m.delta - m.mid).abs(), None),
        9 => (m.delta.min(m.length - m.delta), None),
        5 => (m.z + m.length / 2.0, Some(0)),
        6 => (m.z.abs() * 2.0, Some(0)),
        _ => (m.length, Some(0)),
    }
}

/// Whether the filters pass the point (JWildfire hides it otherwise).
fn filters_pass(v: &Prepared, p: &[f64], m: &Measured) -> bool {
    let mut pass = true;
    for k in 0..filter_count(p) {
        let (op, mode, measure, low, high) = filter(p, k);
        if mode == 0 {
            continue;
        }
        let (val, col) = filter_value(m, measure);
        let (lo, hi) = if mode == 3 || mode == 4 {
            match (measure, col) {
                (7, _) => (low * m.length, high * m.length),
                (8 | 9, _) => (low * m.mid, high * m.mid),
                (_, Some(c)) => {
                    let s = sample(v, c);
                    let li = if low <= 0.0 || low >= 1.0 {
                        0
                    } else {
                        (low * SAMPLES as f64) as usize
                    };
                    let hi = if high >= 1.0 || high <= 0.0 {
                        SAMPLES - 1
                    } else {
                        (high * SAMPLES as f64) as usize
                    };
                    (at(s, li), at(s, hi))
                }
                _ => (low, high),
            }
        } else {
            (low, high)
        };
        let inband = val >= lo && val <= hi;
        let current = if mode == 2 || mode == 4 {
            !inband
        } else {
            inband
        };
        pass = if k == 0 {
            current
        } else {
            match op {
                1 => pass || current,
                2 => pass != current,
                3 => pass && !current,
                4 => !pass && current,
                _ => pass && current,
            }
        };
    }
    pass
}

/// The colour: the measure mapped between its thresholds (values or percentiles) to the
/// palette, clamped or wrapped, or to a red–green, red–blue or blue–green colour.
fn colour(
    v: &Prepared,
    p: &[f64],
    m: &Measured,
    speed: f64,
    theta1: f64,
    call: &Call,
    acc: &mut Acc,
) {
    let measure = p[ix::COLOR_MEASURE] as i32;
    let gradient = p[ix::GRADIENT] as i32;
    let meta = p[ix::META] as i32 != 0;
    let meta_index = measure == 4 && meta;
    let (mut val, col) = match measure {
        10 => (speed, Some(3)),
        11 => (theta1 / TAU, Some(4)),
        _ if meta_index => (call.meta_step, None),
        7..=9 | 2 | 3 | 5 | 6 => filter_value(m, measure),
        _ => (m.length, Some(0)),
    };
    let (low, high) = (p[ix::COLOR_LOW], p[ix::COLOR_HIGH]);
    let (lo, hi) = if meta_index {
        (0.0, v.derived::<DERIVED>()[8])
    } else {
        let (mut lo, mut hi) = if p[ix::THRESHOLDING] as i32 == 0 {
            match (measure, col) {
                (7, _) => (low * m.length, high * m.length),
                (8 | 9, _) => (low * m.mid, high * m.mid),
                (_, Some(c)) => {
                    let s = sample(v, c);
                    let li = if !(0.0..1.0).contains(&low) {
                        0
                    } else {
                        (low * SAMPLES as f64) as usize
                    };
                    let hi = if !(0.0..1.0).contains(&high) {
                        SAMPLES - 1
                    } else {
                        (high * (SAMPLES - 1) as f64) as usize
                    };
                    (at(s, li), at(s, hi))
                }
                _ => (low, high),
            }
        } else {
            (low, high)
        };
        if lo > hi {
            (lo, hi) = (hi, lo);
        }
        (lo, hi)
    };
    let base = if val < lo {
        0.0
    } else if val >= hi {
        255.0
    } else {
        (val - lo) / (hi - lo) * 255.0
    };
    // NaN stays NaN, as in JWildfire.
    let clamp01 = |c: f64| c.clamp(0.0, 1.0);
    match gradient {
        1 => {
            acc.rgb = None;
            acc.color = clamp01(base / 255.0);
        }
        2 => {
            acc.rgb = None;
            let range = hi - lo;
            if val < lo {
                val = hi - ((lo - val) % range);
            } else if val > hi {
                val = lo + ((val - lo) % range);
            }
            acc.color = clamp01((val - lo) / range * 255.0 / 255.0);
        }
        3 => acc.rgb = Some([base, 255.0 - base, 0.0]),
        4 => acc.rgb = Some([base, 0.0, 255.0 - base]),
        5 => acc.rgb = Some([0.0, 255.0 - base, base]),
        _ => {}
    }
}

/// maurer_lines: the chord the input's angle (or a random angle) falls on, a random point of it
/// drawn in the render mode (or, at random, a chord end or the curve), thickened; hidden by
/// the filters, coloured by the colour measure; added to the sum, or (diff_mode) moving the
/// input point towards it by the weight.
fn maurer_lines(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let p = &v.p[..ix::COUNT_ALL];
    let d: [f64; DERIVED] = v.derived();
    let call = set_values(p, &d, rng);
    let curve = call.curve;
    let tin = if p[ix::RANDOMIZE] >= 1.0 {
        rng.f01() * TAU
    } else {
        t.y.atan2(t.x)
    };
    let tc = call.cycles * tin;
    let curve_at = curve.point(tc);
    let step_number = (tc / call.step).floor();
    let theta1 = step_number * call.step + call.initial;
    let theta2 = theta1 + call.step;
    let (x1, y1) = curve.point(theta1);
    let (x2, y2) = curve.point(theta2);
    let (xd, yd) = (x2 - x1, y2 - y1);
    let slope = yd / xd;
    let intercept = if slope.is_nan() {
        f64::NAN
    } else {
        y1 - slope * x1
    };
    let (length, line_angle, point_angle) = measures(x1, y1, x2, y2);
    let ch = Chord {
        x1,
        y1,
        x2,
        y2,
        theta1,
        theta2,
        step: call.step,
        step_number,
        slope,
        intercept,
        angle: yd.atan2(xd),
        length,
        mid: length / 2.0,
        xmid: (x1 + x2) / 2.0,
        ymid: (y1 + y2) / 2.0,
    };
    let [show_points, show_curve, line_w, point_w, curve_w] =
        [0, 1, 2, 3, 4].map(|k| p[ix::SHOW_POINTS + k]);
    let (line_w, point_w, curve_w) = (line_w / 100.0, point_w / 100.0, curve_w / 100.0);
    let (mut xo, mut yo, mut zo, mut delta) = (0.0, 0.0, 0.0, 0.0);
    let mut render = true;
    if show_points > 0.0 || show_curve > 0.0 {
        let rnd = rng.f01();
        let which = rng.f01();
        if which <= show_points {
            render = false;
            let (mut ox, mut oy) = (0.0, 0.0);
            if point_w != 0.0 {
                let r = rng.f01() * point_w;
                let a = rng.f01() * TAU;
                (ox, oy) = (r * a.cos(), r * a.sin());
            }
            (xo, yo) = if rnd <= show_points / 2.0 {
                (x1 + ox, y1 + oy)
            } else {
                (x2 + ox, y2 + oy)
            };
        } else if which <= show_points + show_curve {
            render = false;
            (xo, yo) = curve_at;
            if curve_w != 0.0 {
                xo += (rng.f01() - 0.5) * curve_w;
                yo += (rng.f01() - 0.5) * curve_w;
            }
        }
    }
    if render {
        let u = rng.f01();
        let style = Style {
            mode: p[ix::RENDER] as i32,
            submode: p[ix::RENDER + 1] as i32,
            tangent: p[ix::RENDER + 2] as i32,
            m: call.m,
        };
        let dr = draw(&style, &curve, &ch, u, (t.x, t.y), curve_at, rng);
        (xo, yo, zo, delta) = (dr.x, dr.y, dr.z, dr.delta);
        if line_w != 0.0 {
            xo += (rng.f01() - 0.5) * line_w;
            yo += (rng.f01() - 0.5) * line_w;
        }
    }
    let m = Measured {
        length,
        line_angle,
        point_angle,
        delta,
        mid: ch.mid,
        z: zo,
    };
    acc.hide = !filters_pass(v, p, &m);
    let w = v.w;
    let out = if p[ix::DIFF] >= 1.0 {
        let moved = [
            t.x + w * (xo - t.x),
            t.y + w * (yo - t.y),
            t.z + w * (zo - t.z),
        ];
        if v.form == Form::Regular {
            (acc.x, acc.y, acc.z) = (moved[0], moved[1], moved[2]);
            [0.0; 3]
        } else {
            moved
        }
    } else {
        [w * xo, w * yo, w * zo]
    };
    if p[ix::COLOR_MEASURE] as i32 != 0 && p[ix::GRADIENT] as i32 != 0 {
        let speed = if p[ix::COLOR_MEASURE] as i32 == 10 {
            curve.speed(theta1)
        } else {
            0.0
        };
        colour(v, p, &m, speed, theta1, &call, acc);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::variations::{Form, Prepared};

    fn prepared(set: &[(&str, f64)]) -> Prepared {
        let (id, _) = crate::flame::variations::parse_name("maurer_lines").expect("registered");
        let mut params = crate::flame::variations::param_defaults(id);
        for (name, value) in set {
            if let Some((_, _, k)) =
                crate::flame::variations::param_of(&format!("maurer_lines_{name}"))
            {
                params[k] = *value;
            }
        }
        Prepared::new(id, Form::Regular, 1.0, &params, Default::default(), true)
    }

    fn call(v: &Prepared, x: f64, y: f64, rng: &mut FastRng) -> Acc {
        crate::flame::variations::eval_prepared(v, [x, y, 0.0], Acc::default(), false, rng)
    }

    /// The default rose's chords: every point lies on the chord (within the thickness) whose
    /// ends are the rose r = cos 2θ at ⌊θ·360/2π⌋ steps of 71° (the input's angle θ times 71
    /// turns).
    #[test]
    fn default_points_lie_on_their_chord() {
        let v = prepared(&[("line_thickness", 0.0)]);
        let mut rng = FastRng::new(3);
        for k in 0..50 {
            let a = -3.0 + 0.12 * k as f64;
            let o = call(&v, a.cos(), a.sin(), &mut rng);
            let step = TAU * 71.0 / 360.0;
            let t1 = (71.0 * a / step).floor() * step;
            let rose = |t: f64| {
                let r = (2.0 * t).cos();
                (r * t.cos(), r * t.sin())
            };
            let (p1, p2) = (rose(t1), rose(t1 + step));
            let cross = (p2.0 - p1.0) * (o.y - p1.1) - (p2.1 - p1.1) * (o.x - p1.0);
            assert!(cross.abs() < 1e-9, "off the chord at angle {a}: {cross}");
            let dot = (p2.0 - p1.0) * (o.x - p1.0) + (p2.1 - p1.1) * (o.y - p1.1);
            let len2 = (p2.0 - p1.0).powi(2) + (p2.1 - p1.1).powi(2);
            assert!((-1e-12..=len2 + 1e-12).contains(&dot));
            assert!(!o.hide);
        }
    }

    /// The circle mode puts every point on the circle over the chord; a band-pass filter on
    /// the length hides exactly the chords outside the band; the clamped line-angle colour
    /// lies in [0, 1].
    #[test]
    fn circles_filters_and_colour() {
        let v = prepared(&[
            ("render_mode", 2.0),
            ("line_thickness", 0.0),
            ("number_of_filters", 1.0),
            ("filter1_low_threshold", 0.5),
            ("filter1_high_threshold", 1.5),
            ("direct_color_gradient", 1.0),
            ("direct_color_measure", 2.0),
            ("direct_color_thresholding", 1.0),
            ("color_low_threshold", 0.0),
            ("color_high_threshold", 1.0),
        ]);
        let mut rng = FastRng::new(5);
        let (mut shown, mut hidden) = (0, 0);
        for k in 0..200 {
            let a = -3.1 + 0.031 * k as f64;
            let o = call(&v, a.cos(), a.sin(), &mut rng);
            let step = TAU * 71.0 / 360.0;
            let t1 = (71.0 * a / step).floor() * step;
            let rose = |t: f64| {
                let r = (2.0 * t).cos();
                (r * t.cos(), r * t.sin())
            };
            let (p1, p2) = (rose(t1), rose(t1 + step));
            let mid = ((p1.0 + p2.0) / 2.0, (p1.1 + p2.1) / 2.0);
            let len = (p2.0 - p1.0).hypot(p2.1 - p1.1);
            assert!(((o.x - mid.0).hypot(o.y - mid.1) - len / 2.0).abs() < 1e-9);
            assert_eq!(o.hide, !(0.5..=1.5).contains(&len));
            if o.hide {
                hidden += 1;
            } else {
                shown += 1;
            }
            assert!((0.0..=1.0).contains(&o.color));
        }
        assert!(shown > 0 && hidden > 0);
    }

    /// diff_mode moves the input towards the drawn point by the weight: weight 0 leaves the
    /// input point, including z.
    #[test]
    fn diff_mode_at_weight_zero_keeps_the_point() {
        let (id, _) = crate::flame::variations::parse_name("maurer_lines").expect("registered");
        let mut params = crate::flame::variations::param_defaults(id);
        if let Some((_, _, k)) = crate::flame::variations::param_of("maurer_lines_diff_mode") {
            params[k] = 1.0;
        }
        let v = Prepared::new(id, Form::Regular, 0.0, &params, Default::default(), true);
        let mut rng = FastRng::new(1);
        let o = crate::flame::variations::eval_prepared(
            &v,
            [0.3, -0.4, 0.7],
            Acc::default(),
            false,
            &mut rng,
        );
        assert_eq!((o.x, o.y, o.z), (0.3, -0.4, 0.7));
    }
}
