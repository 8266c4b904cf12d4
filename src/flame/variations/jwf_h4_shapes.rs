//! Jesus Sosa's `cut_shapes`: a cut (see `jwf_a_cuts`) along one of thirteen of Inigo Quilez's
//! 2-D signed distance functions (https://iquilezles.org/articles/distfunctions2d/): hexagram,
//! equilateral triangle, star, cross, octagon, hexagon, pentagon, vesica, two trapezoids, arc,
//! rhombus, circle and box, some animated by `time`. The point is hidden where cos(120·d) > 0
//! (concentric contours) or, without contours, where it lies within `thick` of the outline.
//!
//! The formulas follow JWildfire 9.00 (`CutShapesFunc`, LGPL-2.1), written anew; its star
//! measures angles with JWildfire's approximate atan2, kept here.

use super::jwf_a_cuts::{CUT, cut_end, cut_point};
use super::util::{atan2_approx, fract, mix, smoothstep};
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("cut_shapes", cut_shapes)
    .params(&[
        p_int("cut_shapes_mode", 1.0, 0.0, 1.0),
        p_int("cut_shapes_type", 0.0, 0.0, 12.0),
        p_int("cut_shapes_contour", 1.0, 0.0, 1.0),
        p_range("cut_shapes_zoom", 1.0, 0.1, 50.0),
        p_int("cut_shapes_invert", 0.0, 0.0, 1.0),
        p_int("cut_shapes_n", 3.0, 3.0, 9.0),
        p("cut_shapes_thick", 0.01),
        p("cut_shapes_time", 0.5),
    ])
    .flags(CUT)];

type P = (f64, f64);

fn dot(a: P, b: P) -> f64 {
    a.0 * b.0 + a.1 * b.1
}

fn len(a: P) -> f64 {
    dot(a, a).sqrt()
}

fn sub(a: P, b: P) -> P {
    (a.0 - b.0, a.1 - b.1)
}

fn scale(a: P, k: f64) -> P {
    (a.0 * k, a.1 * k)
}

fn abs2(a: P) -> P {
    (a.0.abs(), a.1.abs())
}

/// GLSL's `sign` as JWildfire computes it (`Math.signum`: 0 at 0).
fn sgn(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        x
    }
}

/// Reflects `p` across the line through 0 with unit normal `k` when on its negative side.
fn fold(p: P, k: P) -> P {
    sub(p, scale(k, 2.0 * dot(k, p).min(0.0)))
}

/// The signed distance from the top edge (half width w, height r) of a folded polygon.
fn top_edge(p: P, w: f64, r: f64) -> f64 {
    let q = sub(p, (p.0.clamp(-w, w), r));
    len(q) * sgn(q.1)
}

fn hexagram(p: P, r: f64) -> f64 {
    let (kx, ky, kz, kw) = (-0.5, 0.86602540378, 0.57735026919, 1.73205080757);
    let p = fold(fold(abs2(p), (kx, ky)), (ky, kx));
    let q = sub(p, (p.0.clamp(r * kz, r * kw), r));
    len(q) * sgn(q.1)
}

fn triangle(p: P) -> f64 {
    let k = 3f64.sqrt();
    let (mut x, mut y) = (p.0.abs() - 1.0, p.1 + 1.0 / k);
    if x + k * y > 0.0 {
        (x, y) = ((x - k * y) / 2.0, (-k * x - y) / 2.0);
    }
    x -= x.clamp(-2.0, 0.0);
    -len((x, y)) * sgn(y)
}

#[allow(clippy::approx_constant)] // JWildfire's own rounded constants
fn star(p: P, r: f64, n: f64, m: f64) -> f64 {
    let an = 3.141593 / n;
    let en = 6.283185 / m;
    let acs = (an.cos(), an.sin());
    let ecs = (en.cos(), en.sin());
    let a = atan2_approx(p.0, p.1);
    let bn = a - 2.0 * an * (a / (2.0 * an)).floor() - an;
    let q = scale((bn.cos(), bn.sin().abs()), len(p));
    let q = sub(q, scale(acs, r));
    let q = sub(q, scale(ecs, -(-dot(q, ecs)).clamp(0.0, r * acs.1 / ecs.1)));
    len(q) * sgn(q.0)
}

fn cross(p: P, b: P, r: f64) -> f64 {
    let p = abs2(p);
    let p = if p.1 > p.0 { (p.1, p.0) } else { p };
    let q = sub(p, b);
    let k = q.1.max(q.0);
    let w = if k > 0.0 { q } else { (b.1 - p.0, -k) };
    sgn(k) * len((w.0.max(0.0), w.1.max(0.0))) + r
}

fn octagon(p: P, r: f64) -> f64 {
    let (kx, ky, kz) = (-0.9238795325, 0.3826834323, 0.4142135623);
    let p = fold(fold(abs2(p), (kx, ky)), (-kx, ky));
    top_edge(p, kz * r, r)
}

fn hexagon(p: P, r: f64) -> f64 {
    let (kx, ky, kz) = (-0.866025404, 0.5, 0.577350269);
    top_edge(fold(abs2(p), (kx, ky)), kz * r, r)
}

fn pentagon(p: P, r: f64) -> f64 {
    let (kx, ky, kz) = (0.809016994, 0.587785252, 0.726542528);
    let p = fold(fold((p.0.abs(), -p.1), (-kx, ky)), (kx, ky));
    top_edge(p, r * kz, r)
}

fn vesica(p: P, r: f64, d: f64) -> f64 {
    let p = abs2(p);
    let b = (r * r - d * d).sqrt();
    if (p.1 - b) * d > p.0 * b {
        len(sub(p, (0.0, b)))
    } else {
        len(sub(p, (-d, 0.0))) - r
    }
}

/// The isosceles trapezoid of half widths r1 (bottom) and r2 (top) and half height he.
fn trapezoid(p: P, r1: f64, r2: f64, he: f64) -> f64 {
    let k1 = (r2, he);
    let k2 = (r2 - r1, 2.0 * he);
    let p = (p.0.abs(), p.1);
    let ca = (
        (p.0 - if p.1 < 0.0 { r1 } else { r2 }).max(0.0),
        p.1.abs() - he,
    );
    let t = (dot(sub(k1, p), k2) / dot(k2, k2)).clamp(0.0, 1.0);
    let cb = sub(sub(p, k1), scale(k2, -t));
    let s = if cb.0 < 0.0 && ca.1 < 0.0 { -1.0 } else { 1.0 };
    s * dot(ca, ca).min(dot(cb, cb)).sqrt()
}

/// The trapezoid between the segment ends a and b with half widths ra and rb.
fn trapezoid_ab(p: P, a: P, b: P, ra: f64, rb: f64) -> f64 {
    let rba = rb - ra;
    let ba = sub(b, a);
    let pa = sub(p, a);
    let baba = dot(ba, ba);
    let papa = dot(pa, pa);
    let paba = dot(pa, ba) / baba;
    let x = (papa - paba * paba * baba).sqrt();
    let cax = (x - if paba < 0.5 { ra } else { rb }).max(0.0);
    let cay = (paba - 0.5).abs() - 0.5;
    let k = rba * rba + baba;
    let f = ((rba * (x - ra) + paba * baba) / k).clamp(0.0, 1.0);
    let cbx = x - ra - f * rba;
    let cby = paba - f;
    let s = if cbx < 0.0 && cay < 0.0 { -1.0 } else { 1.0 };
    s * (cax * cax + cay * cay * baba)
        .min(cbx * cbx + cby * cby * baba)
        .sqrt()
}

fn arc(p: P, sca: P, scb: P, ra: f64, rb: f64) -> f64 {
    let p = (sca.0 * p.0 - sca.1 * p.1, sca.1 * p.0 + sca.0 * p.1);
    let p = (p.0.abs(), p.1);
    let k = if scb.1 * p.0 > scb.0 * p.1 {
        dot(p, scb)
    } else {
        len(p)
    };
    (dot(p, p) + ra * ra - 2.0 * ra * k).sqrt() - rb
}

fn rhombus(p: P, b: P) -> f64 {
    let q = abs2(p);
    let ndot = |a: P, c: P| a.0 * c.0 - a.1 * c.1;
    let h = ((-2.0 * ndot(q, b) + ndot(b, b)) / dot(b, b)).clamp(-1.0, 1.0);
    let d = len(sub(q, scale((b.0 * (1.0 - h), b.1 * (1.0 + h)), 0.5)));
    d * sgn(q.0 * b.1 + q.1 * b.0 - b.0 * b.1)
}

fn boxed(p: P, b: P) -> f64 {
    let d = sub(abs2(p), b);
    len((d.0.max(0.0), d.1.max(0.0))) + d.0.max(d.1).min(0.0)
}

/// The signed distance of shape `kind` (animated by `time`; `n` points for the star).
#[allow(clippy::approx_constant)] // JWildfire's own rounded constants
fn shape(kind: f64, p: P, n: f64, time: f64) -> f64 {
    // The half sizes cos((0, 1.57) + time)·0.3 + c of the cross, rhombus and box.
    let wobble = |c: f64| ((time).cos() * 0.3 + c, (1.57 + time).cos() * 0.3 + c);
    match kind as i64 {
        0 => hexagram(p, 0.35),
        1 => triangle(p),
        2 => {
            let a = fract(time / 3.0);
            star(p, 0.7, n, 4.0 + a * a * (n * 2.0 - 4.0))
        }
        3 => {
            let si = wobble(0.8);
            let si = if si.0 < si.1 { (si.1, si.0) } else { si };
            cross(p, si, 0.1 * (time * 1.2).sin())
        }
        4 => octagon(p, 0.5),
        5 => hexagon(p, 0.5),
        6 => pentagon(p, 0.5),
        7 => vesica(p, 1.1, 0.8 + 0.2 * time.sin()),
        8 => {
            let ra = 0.2 + 0.15 * (time * 1.3).sin();
            let rb = 0.2 + 0.15 * (time * 1.4 + 0.1).sin();
            let t1 = time * 1.1;
            let t2 = time * 1.2;
            let pa = (-0.6 + t1.sin() * 0.4, (2.0 + t1).sin() * 0.4);
            let pb = (-0.6 + (1.0 + t2).sin() * 0.4, (2.5 + t2).sin() * 0.4);
            let d = trapezoid(sub(p, (0.8, 0.0)), ra, rb, 0.5 + 0.2 * (1.3 * time).sin());
            d.min(trapezoid_ab(p, pa, pb, ra, rb))
        }
        9 => {
            let ta = 3.14 * (0.5 + 0.5 * (time * 0.52 + 2.0).cos());
            let tb = 3.14 * (0.5 + 0.5 * (time * 0.31 + 2.0).cos());
            let rb = 0.15 * (0.5 + 0.5 * (time * 0.41 + 3.0).cos());
            arc(p, (ta.sin(), ta.cos()), (tb.sin(), tb.cos()), 0.5, rb)
        }
        10 => rhombus(p, wobble(0.4)),
        11 => len(p) - 0.5,
        _ => boxed(p, wobble(0.4)),
    }
}

/// cut_shapes: the point (the input, or a uniform point of [−½, ½]² with `mode` 1) zoomed and
/// measured against the shape; hidden on the contours' positive half (or near the outline
/// without contours), the other points kept (`invert` swaps them).
fn cut_shapes(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, kind, contour, zoom, invert, n, thick, time] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let d = shape(kind, (x * zoom, y * zoom), n, time);
    let color = if contour == 1.0 {
        (120.0 * d).cos()
    } else {
        mix(0.0, 1.0, 1.0 - smoothstep(0.0, thick.abs(), d.abs()))
    };
    cut_end(v, acc, color > 0.0, invert, (x, y), 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_vanish_on_the_outlines_and_are_negative_inside() {
        // Points on the outlines of the circle, box, hexagon and equilateral triangle.
        assert!((shape(11.0, (0.5, 0.0), 3.0, 0.0)).abs() < 1e-12);
        assert!(hexagon((0.0, 0.5), 0.5).abs() < 1e-12);
        assert!(triangle((0.0, -1.0 / 3f64.sqrt())).abs() < 1e-12);
        assert!(boxed((0.3, 0.1), (0.3, 0.2)).abs() < 1e-12);
        for kind in 0..13 {
            let d = shape(f64::from(kind), (0.0, 0.05), 5.0, 0.5);
            assert!(d.is_finite(), "shape {kind}");
        }
        assert!(hexagon((0.0, 0.0), 0.5) < 0.0 && octagon((0.0, 0.0), 0.5) < 0.0);
        assert!(pentagon((0.0, 0.0), 0.5) < 0.0 && hexagram((0.0, 0.0), 0.35) < 0.0);
    }
}
