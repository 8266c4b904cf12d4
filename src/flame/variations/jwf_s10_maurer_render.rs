//! How JWildfire's `maurer_lines` (JWildfire 9.00, `MaurerLinesFunc`) draws one chord of its
//! curve: the render modes (the chord itself, circles and ellipses on it, sine waves along it,
//! a quadratic Bézier through a control point, circle splines after Séquin, Lee and Yen,
//! cardinal, Catmull–Rom and Kochanek–Bartels splines through the neighbouring chord ends,
//! cubic Hermite arcs from the curve's tangents) and the render submodes (reflection about the
//! chord, fills towards the chord or the curve, z strokes).

use std::f64::consts::{PI, TAU};

use super::jwf_s10_maurer_curves::Curve;
use crate::flame::rng::FastRng;

/// One chord P1 P2 of the curve, from parameter θ1 to θ2 = θ1 + step, with the quantities the
/// modes measure.
#[derive(Clone, Copy, Debug)]
pub(super) struct Chord {
    pub x1: f64,
    pub y1: f64,
    pub x2: f64,
    pub y2: f64,
    pub theta1: f64,
    pub theta2: f64,
    /// The parameter step between chord ends.
    pub step: f64,
    /// The chord's number ⌊t / step⌋ (odd chords are the alternating submodes' reflected ones).
    pub step_number: f64,
    /// The chord's slope dy/dx and y-intercept (NaN where the slope is NaN).
    pub slope: f64,
    pub intercept: f64,
    /// The chord's direction atan2(dy, dx).
    pub angle: f64,
    pub length: f64,
    /// Half the length.
    pub mid: f64,
    pub xmid: f64,
    pub ymid: f64,
}

/// What a render mode gives: the point, its z and its distance along the chord (which the
/// colour and the filters may measure).
#[derive(Clone, Copy, Debug)]
pub(super) struct Drawn {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub delta: f64,
}

/// The render settings of one call.
#[derive(Clone, Copy, Debug)]
pub(super) struct Style {
    pub mode: i32,
    pub submode: i32,
    pub tangent: i32,
    /// render_modifier1…3.
    pub m: [f64; 3],
}

/// Reflection of (x, y) about the chord's line.
fn reflect(ch: &Chord, x: f64, y: f64) -> (f64, f64) {
    let (dx, dy) = (ch.x2 - ch.x1, ch.y2 - ch.y1);
    let bc = (dx * (x - ch.x1) + dy * (y - ch.y1)) / (dx * dx + dy * dy);
    (2.0 * (ch.x1 + dx * bc) - x, 2.0 * (ch.y1 + dy * bc) - y)
}

/// The Hermite basis h00, h10, h01, h11 at u.
fn hermite(u: f64) -> [f64; 4] {
    let (u2, u3) = (u * u, u * u * u);
    [
        2.0 * u3 - 3.0 * u2 + 1.0,
        u3 - 2.0 * u2 + u,
        -2.0 * u3 + 3.0 * u2,
        u3 - u2,
    ]
}

/// The curve's points one step before the chord and one after (P0, P3), for the splines;
/// `swizzle` 1 swaps x and y of both, 2 swaps the two points, 3 does both.
fn neighbours(curve: &Curve, ch: &Chord, swizzle: i32) -> ((f64, f64), (f64, f64)) {
    let p0 = curve.point(ch.theta1 - ch.step);
    let p3 = curve.point(ch.theta2 + ch.step);
    match swizzle {
        1 => ((p0.1, p0.0), (p3.1, p3.0)),
        2 => (p3, p0),
        3 => ((p3.1, p3.0), (p0.1, p0.0)),
        _ => (p0, p3),
    }
}

/// A cubic Hermite segment from P1 to P2 with tangents m1, m2 scaled by `scale`, at u.
fn hermite_point(ch: &Chord, u: f64, m1: (f64, f64), m2: (f64, f64), scale: f64) -> (f64, f64) {
    let [h00, h10, h01, h11] = hermite(u);
    (
        h00 * ch.x1 + h10 * m1.0 * scale + h01 * ch.x2 + h11 * m2.0 * scale,
        h00 * ch.y1 + h10 * m1.1 * scale + h01 * ch.y2 + h11 * m2.1 * scale,
    )
}

/// Draw the chord in `style.mode` at the fraction `u` (drawn by the caller) of the way; the
/// input point (xin, yin) is the answer of the Hermite modes where the curve's tangent is
/// unknown. Then apply the submode (`curve_at` is the curve's own point at the input's angle,
/// which the fills to the curve reach).
pub(super) fn draw(
    style: &Style,
    curve: &Curve,
    ch: &Chord,
    u: f64,
    input: (f64, f64),
    curve_at: (f64, f64),
    rng: &mut FastRng,
) -> Drawn {
    let m = (ch.x1 * (1.0 - u) + ch.x2 * u, ch.y1 * (1.0 - u) + ch.y2 * u);
    let mut d = mode_point(style, curve, ch, u, m, input, rng);
    let (x, y) = submode_point(style.submode, ch, (d.x, d.y), m, curve_at, rng);
    d.x = x;
    d.y = y;
    d
}

/// The render mode's point (before the submode).
fn mode_point(
    style: &Style,
    curve: &Curve,
    ch: &Chord,
    u: f64,
    m: (f64, f64),
    input: (f64, f64),
    rng: &mut FastRng,
) -> Drawn {
    let [m1, m2, m3] = style.m;
    let sub = style.submode;
    let mut out = Drawn {
        x: m.0,
        y: m.1,
        z: 0.0,
        delta: u * ch.length,
    };
    let from_p1 = |x: f64, y: f64| ((ch.x1 - x) * (ch.x1 - x) + (ch.y1 - y) * (ch.y1 - y)).sqrt();
    match style.mode {
        // Circles on the chord as diameter (z stroke: the circle stood up along z).
        2 => {
            let ang = u * TAU;
            if sub == 15 {
                let along = ch.mid * ang.cos();
                out.z = ch.mid * ang.sin();
                out.x = ch.xmid + along * ch.angle.cos();
                out.y = ch.ymid + along * ch.angle.sin();
            } else {
                out.x = ch.xmid + ch.mid * ang.sin();
                out.y = ch.ymid + ch.mid * ang.cos();
            }
            out.delta = from_p1(out.x, out.y);
        }
        // Ellipses on the chord: half-axes mid·m1 along it, mid·m2/2 across.
        3 => {
            let ang = u * TAU;
            let across = ch.mid * (m2 / 2.0) * ang.sin();
            let back = ch.angle + PI;
            if sub == 15 {
                let along = ch.mid * m1 * ang.cos();
                out.delta = ch.mid - along;
                let off = along - ch.mid;
                out.x = ch.x1 + off * back.cos();
                out.y = ch.y1 + off * back.sin();
                out.z = across;
            } else {
                let along = ch.mid * m1 * ang.cos();
                out.delta = ch.mid * ang.cos();
                let off = along - ch.mid;
                out.x = ch.x1 + off * back.cos() - across * back.sin();
                out.y = ch.y1 + off * back.sin() + across * back.cos();
            }
        }
        // A sine wave along the chord (amplitude length/4·m1, frequency m2), its ends on the
        // chord's ends.
        4 => {
            let amp = ch.length / 4.0 * m1;
            let ang = u * TAU;
            let along = ang * (ch.length / TAU);
            out.delta = along;
            let end = amp * (PI * m2).cos();
            let across = amp * ((ang - PI) * m2).cos() - end;
            if sub == 15 || sub == 17 {
                out.x = ch.x1 + along * ch.angle.cos();
                out.y = ch.slope * out.x + ch.intercept;
                out.z = if sub == 15 || rng.f01() < 0.5 {
                    across
                } else {
                    -across
                };
            } else {
                let (c, s) = (ch.angle.cos(), ch.angle.sin());
                out.x = ch.x1 + along * c - across * s;
                out.y = ch.y1 + along * s + across * c;
            }
        }
        // A quadratic Bézier from P1 to P2; its control point the origin, or (m1, m2 ≠ 1) on
        // the line from the chord's midpoint to the origin at (1 − m1) of the midpoint's
        // radius, turned by (1 − m2) turns.
        5 => {
            let b = u;
            let (ax, ay) = if m1 != 1.0 || m2 != 1.0 {
                let mr = (ch.xmid * ch.xmid + ch.ymid * ch.ymid).sqrt();
                let ma = ch.ymid.atan2(ch.xmid);
                let cr = (1.0 - m1) * mr;
                let ca = ma + (TAU - m2 * TAU);
                let (cx, cy) = (cr * ca.cos(), cr * ca.sin());
                (
                    (1.0 - b) * (1.0 - b) * ch.x1 + 2.0 * (1.0 - b) * b * cx + b * b * ch.x2,
                    (1.0 - b) * (1.0 - b) * ch.y1 + 2.0 * (1.0 - b) * b * cy + b * b * ch.y2,
                )
            } else {
                (
                    (1.0 - b) * (1.0 - b) * ch.x1 + b * b * ch.x2,
                    (1.0 - b) * (1.0 - b) * ch.y1 + b * b * ch.y2,
                )
            };
            if sub == 15 {
                out.z = ay;
                let mut xo = out.delta / (1.0 + ch.slope * ch.slope).sqrt();
                if ch.x2 < ch.x1 {
                    xo = -xo;
                }
                let mut yo = (ch.slope * xo).abs();
                if ch.y2 < ch.y1 {
                    yo = -yo;
                }
                out.x = ch.x1 + xo;
                out.y = ch.y1 + yo;
            } else if sub == 17 {
                out.x = ax;
                out.y = ch.slope * ax + ch.intercept;
                let r = -ch.angle;
                out.z = (ax - ch.x1) * r.sin() + (ay - ch.y1) * r.cos();
            } else {
                out.x = ax;
                out.y = ay;
            }
        }
        9 => (out.x, out.y) = sequin(curve, ch, u),
        6..=8 | 11 | 12 => {
            let swizzle = if (6..=8).contains(&style.mode) {
                style.mode - 5
            } else {
                0
            };
            let (p0, p3) = neighbours(curve, ch, swizzle);
            let t1 = (0.5 * (ch.x2 - p0.0), 0.5 * (ch.y2 - p0.1));
            let t2 = (0.5 * (p3.0 - ch.x1), 0.5 * (p3.1 - ch.y1));
            let scale = if style.mode == 12 { 1.0 } else { 1.0 - m1 };
            (out.x, out.y) = hermite_point(ch, u, t1, t2, scale);
        }
        13..=15 => {
            let alpha = match style.mode {
                15 => 0.5,
                14 => 1.0,
                _ => m2,
            };
            let (p0, p3) = neighbours(curve, ch, 0);
            let (p1, p2) = ((ch.x1, ch.y1), (ch.x2, ch.y2));
            let knot = |a: (f64, f64), b: (f64, f64)| {
                ((b.0 - a.0) * (b.0 - a.0) + (b.1 - a.1) * (b.1 - a.1)).powf(alpha / 2.0)
            };
            let (d0, d1, d2) = (knot(p0, p1), knot(p1, p2), knot(p2, p3));
            let tangent = |k: usize| {
                let (pa, pb, pc, da, db) = if k == 0 {
                    (p0, p1, p2, d0, d1)
                } else {
                    (p1, p2, p3, d1, d2)
                };
                let c = |i: usize| {
                    let g = |p: (f64, f64)| if i == 0 { p.0 } else { p.1 };
                    (g(pb) - g(pa)) / da - (g(pc) - g(pa)) / (da + db) + (g(pc) - g(pb)) / db
                };
                (c(0), c(1))
            };
            (out.x, out.y) = hermite_point(ch, u, tangent(0), tangent(1), d1 * (1.0 - m1));
        }
        16 | 22..=24 => {
            let swizzle = if style.mode == 16 { 0 } else { style.mode - 21 };
            let (p0, p3) = neighbours(curve, ch, swizzle);
            let (tension, continuity, bias) = (m1, m2, m3);
            let c110 = (1.0 - tension) * (1.0 + bias) * (1.0 + continuity) / 2.0;
            let c121 = (1.0 - tension) * (1.0 - bias) * (1.0 - continuity) / 2.0;
            let c221 = (1.0 - tension) * (1.0 + bias) * (1.0 - continuity) / 2.0;
            let c232 = (1.0 - tension) * (1.0 - bias) * (1.0 + continuity) / 2.0;
            let t1 = (
                c110 * (ch.x1 - p0.0) + c121 * (ch.x2 - ch.x1),
                c110 * (ch.y1 - p0.1) + c121 * (ch.y2 - ch.y1),
            );
            let t2 = (
                c221 * (ch.x2 - ch.x1) + c232 * (p3.0 - ch.x2),
                c221 * (ch.y2 - ch.y1) + c232 * (p3.1 - ch.y2),
            );
            (out.x, out.y) = hermite_point(ch, u, t1, t2, 1.0);
        }
        10 | 17..=21 => (out.x, out.y) = tangent_hermite(style, curve, ch, u, input),
        25 => (out.x, out.y) = hermite_form2(curve, ch, u, input),
        // 0, 1 and unknown modes: the chord.
        _ => {}
    }
    out
}

/// Séquin, Lee and Yen's circle spline ("Fair, G2- and C2-continuous circle splines for the
/// interpolation of sparse data points", 2005) as JWildfire blends it: the angle between the
/// chord and the arc at P1 and at P2 from the neighbouring chord ends, blended by cos²/sin².
fn sequin(curve: &Curve, ch: &Chord, u: f64) -> (f64, f64) {
    let (p0, p3) = neighbours(curve, ch, 0);
    let (p1, p2) = ((ch.x1, ch.y1), (ch.x2, ch.y2));
    let unit = |a: (f64, f64), b: (f64, f64)| {
        let n = ((b.0 - a.0) * (b.0 - a.0) + (b.1 - a.1) * (b.1 - a.1)).sqrt();
        ((b.0 - a.0) / n, (b.1 - a.1) / n, n)
    };
    let va = unit(p0, p1);
    let vb = unit(p1, p2);
    let vc = unit(p0, p2);
    let vd = unit(p2, p3);
    let ve = unit(p1, p3);
    let a1 = (va.0 * vc.0 + va.1 * vc.1).acos();
    let a2 = (ve.0 * vd.0 + ve.1 * vd.1).acos();
    let (cu, su) = ((u * PI / 2.0).cos(), (u * PI / 2.0).sin());
    let au = a1 * cu * cu + a2 * su * su;
    let norm21 = vb.2;
    let pd = norm21 * (u * au).sin() / au.sin();
    let pa = -((1.0 - u) * au);
    let lx = ch.x1 + (ch.x2 - ch.x1) * pd / norm21;
    let ly = ch.y1 + (ch.y2 - ch.y1) * pd / norm21;
    (
        ch.x1 + (lx - ch.x1) * pa.cos() - (ly - ch.y1) * pa.sin(),
        ch.y1 + (lx - ch.x1) * pa.sin() + (ly - ch.y1) * pa.cos(),
    )
}

/// The cubic Hermite modes (10 and JWildfire's "happy accidents" 17–21): tangents from the
/// curve's derivative (the rhodonea's only; other curves give the input point back), or from
/// the accidents' mistaken derivative of the rose; the tangent submode picks where they are
/// taken, how they are turned, scaled and normalised.
fn tangent_hermite(
    style: &Style,
    curve: &Curve,
    ch: &Chord,
    u: f64,
    input: (f64, f64),
) -> (f64, f64) {
    let [m1, m2, m3] = style.m;
    let sub = style.tangent;
    let (w1, w2) = match sub {
        10 => (ch.theta1 - m2 / 360.0 * TAU, ch.theta2 + m2 / 360.0 * TAU),
        11 => (ch.theta1 - m2 * ch.step, ch.theta2 + m2 * ch.step),
        _ => (ch.theta1, ch.theta2),
    };
    let tangents = if style.mode == 10 {
        curve.derivative(w1).zip(curve.derivative(w2))
    } else {
        let [a, b, c, ..] = curve.s;
        let k = a / b;
        let wrong = |w: f64| {
            let r = (k * w).cos() + c;
            (-r * w.sin(), r * w.cos())
        };
        let (mut d1, mut d2) = (wrong(w1), wrong(w2));
        match style.mode {
            18 => (d1.0, d2.0) = (-d1.0, -d2.0),
            19 => (d1.1, d2.1) = (-d1.1, -d2.1),
            20 => (d1, d2) = ((-d1.0, -d1.1), (-d2.0, -d2.1)),
            21 => (d1, d2) = (d2, d1),
            _ => {}
        }
        Some((d1, d2))
    };
    let Some((t1, t2)) = tangents else {
        return input;
    };
    if t1.0.is_nan() || t1.1.is_nan() || t2.0.is_nan() || t2.1.is_nan() {
        return input;
    }
    let unscaled = matches!(sub, 3 | 4 | 7 | 8);
    let mut scale = if unscaled { 1.0 } else { ch.theta2 - ch.theta1 };
    let turn = |p: (f64, f64), t: (f64, f64), a: f64| {
        (
            p.0 + (t.0 - p.0) * a.cos() - (t.1 - p.1) * a.sin(),
            p.1 + (t.0 - p.0) * a.sin() + (t.1 - p.1) * a.cos(),
        )
    };
    let (p1, p2) = ((ch.x1, ch.y1), (ch.x2, ch.y2));
    let (mut d1, mut d2) = match sub {
        5..=8 => (turn(p1, t1, -PI / 2.0), turn(p2, t2, -PI / 2.0)),
        9 => (
            turn(p1, t1, m2 / 360.0 * TAU),
            turn(p2, t2, m3 / 360.0 * TAU),
        ),
        12 => ((t1.0 * m2, t1.1 * m3), (t2.0 * m2, t2.1 * m3)),
        _ => (t1, t2),
    };
    if matches!(sub, 2 | 4 | 6 | 8) {
        let n1 = (d1.0 * d1.0 + d1.1 * d1.1).sqrt();
        let n2 = (d2.0 * d2.0 + d2.1 * d2.1).sqrt();
        d1 = (d1.0 / n1, d1.1 / n1);
        d2 = (d2.0 / n2, d2.1 / n2);
    }
    scale *= 1.0 - m1;
    hermite_point(ch, u, d1, d2, scale)
}

/// Mode 25: the Hermite cubic in its long form over [θ1, θ2], with the curve's derivatives at
/// the ends (the input point back where they are unknown).
fn hermite_form2(curve: &Curve, ch: &Chord, u: f64, input: (f64, f64)) -> (f64, f64) {
    let (w0, w1) = (ch.theta1, ch.theta2);
    let (Some(f0), Some(f1)) = (curve.derivative(w0), curve.derivative(w1)) else {
        return input;
    };
    if f0.0.is_nan() || f0.1.is_nan() || f1.0.is_nan() || f1.1.is_nan() {
        return input;
    }
    let w = w0 + u * (w1 - w0);
    let tw = (w - w0) / (w1 - w0);
    let tw1 = (w1 - w) / (w1 - w0);
    let tw0 = (w0 - w) / (w0 - w1);
    let form = |p0: f64, d0: f64, p1: f64, d1: f64| {
        (1.0 + 2.0 * tw) * tw1 * tw1 * p0
            + (w - w0) * tw1 * tw1 * d0
            + (1.0 + 2.0 * tw1) * tw0 * tw0 * p1
            + (w - w1) * tw0 * tw0 * d1
    };
    (
        form(ch.x1, f0.0, ch.x2, f1.0),
        form(ch.y1, f0.1, ch.y2, f1.1),
    )
}

/// The render submode applied to the mode's point `p`: 2 reflected about the chord, 3 half of
/// the points reflected, 4 the odd chords reflected; 5–12 the same followed by a fill towards
/// the chord's point `m` (5–8) or the curve's point `c` (9–12); 13 and 14 fill between the
/// chord and the curve (14 with the curve's x and y swapped). 0, 1 and the z strokes (15–18,
/// handled by the modes) leave it.
fn submode_point(
    sub: i32,
    ch: &Chord,
    p: (f64, f64),
    m: (f64, f64),
    c: (f64, f64),
    rng: &mut FastRng,
) -> (f64, f64) {
    let fill = |p: (f64, f64), o: (f64, f64), r: f64| {
        (p.0 * (1.0 - r) + o.0 * r, p.1 * (1.0 - r) + o.1 * r)
    };
    let odd = ch.step_number % 2.0 != 0.0;
    match sub {
        2 => reflect(ch, p.0, p.1),
        3 => {
            if rng.f01() < 0.5 {
                reflect(ch, p.0, p.1)
            } else {
                p
            }
        }
        4 => {
            if odd {
                reflect(ch, p.0, p.1)
            } else {
                p
            }
        }
        5..=12 => {
            let target = if sub >= 9 { c } else { m };
            let kind = (sub - 5) % 4;
            let q = match kind {
                1 => reflect(ch, p.0, p.1),
                2 if rng.f01() < 0.5 => reflect(ch, p.0, p.1),
                3 if odd => reflect(ch, p.0, p.1),
                _ => p,
            };
            fill(q, target, rng.f01())
        }
        13 => fill(m, c, rng.f01()),
        14 => fill(m, (c.1, c.0), rng.f01()),
        _ => p,
    }
}
