//! Gregg Helt's (CozyG) `inversion`: inversion of the plane in a shape — circle, ellipse,
//! hyperbola, regular polygon, rhodonea, superellipse or Gielis supershape — generalising
//! circle inversion: a point at angle θ and radius r goes to radius R(θ)²/r, R(θ) being the
//! shape's radius along the ray (its farthest crossing for a rhodonea), with p-norms in place
//! of Euclid's optionally. Inversion can be limited to the inside or outside of the shape or of
//! a ring; the points left alone pass unweighted (or are hidden); a share of the calls can draw
//! the shape's outline instead, or pass the point through. The colour can measure distances.
//!
//! The formulas follow JWildfire 9.00 (`InversionFunc`, LGPL-2.1), written anew. JWildfire's
//! editor guides are not drawn in renders and are left out.

use std::f64::consts::PI;

use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("inversion", inversion)
    .params(&[
        p("inversion_scale", 1.0),
        p("inversion_rotation", 0.0),
        p_int("inversion_shape", 0.0, -2147483648.0, 2147483647.0),
        p_int("inversion_imode", 0.0, -2147483648.0, 2147483647.0),
        p("inversion_hide_uninverted", 0.0),
        p("inversion_a", 1.0),
        // For a rhodonea `b` is the denominator of the petal ratio a/b: its outline is followed
        // over b half-turns, at most 10000 (see `MAX_TURNS`).
        p("inversion_b", 1.0),
        p("inversion_c", 0.0),
        p("inversion_d", 0.0),
        p("inversion_e", 0.0),
        p("inversion_f", 0.0),
        p_int("inversion_ring_mode", 0.0, -2147483648.0, 2147483647.0),
        p("inversion_ring_scale", 1.0),
        p("inversion_pnorm_point", 2.0),
        p("inversion_pnorm_shape", 2.0),
        p("inversion_pnorm_pmod", 1.0),
        p("inversion_pnorm_smod", 1.0),
        p("inversion_draw_shape", 0.0),
        p("inversion_shape_thickness", 0.0),
        p("inversion_passthrough", 0.0),
        p("inversion_guides_enabled", 1.0),
        p_int("inversion_color_measure", 0.0, -2147483648.0, 2147483647.0),
        p_int("inversion_color_gradient", 1.0, -2147483648.0, 2147483647.0),
        p("inversion_color_low_threshold", 0.0),
        p("inversion_color_high_threshold", 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR | flag::HIDES | flag::READS_ACC)
    .prepare(inversion_prepare)];

/// Most half-turns over which a rhodonea's farthest crossing of a ray is sought.
const MAX_TURNS: f64 = 10000.0;

/// Derived values: the shape's turn (radians), its period (radians) and the ring's radii.
fn inversion_prepare(v: &mut Prepared) {
    let q: [f64; 25] = v.params();
    let (scale, rotation, shape, a, b, c) = (q[0], q[1], q[2], q[5], q[6], q[7]);
    let ring_scale = q[12];
    let period = if shape == 4.0 {
        rhodonea_period(a, b, c)
    } else {
        2.0 * PI
    };
    let (rmin, rmax) = if ring_scale <= scale {
        let rmin = ring_scale * scale;
        (rmin, scale * scale / rmin)
    } else {
        let rmax = ring_scale * scale;
        (scale * scale / rmax, rmax)
    };
    v.p.extend_from_slice(&[PI * rotation, period, rmin, rmax]);
}

/// Greatest common divisor of |a| and |b| (0 when both are 0).
fn gcd(a: i64, b: i64) -> i64 {
    let (mut a, mut b) = (a.unsigned_abs(), b.unsigned_abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a as i64
}

/// The angle over which the rhodonea r = cos((a/b)·t) + c closes.
fn rhodonea_period(a: f64, b: f64, c: f64) -> f64 {
    let k = a / b;
    if k % 1.0 == 0.0 {
        if k % 2.0 == 0.0 || c != 0.0 {
            2.0 * PI
        } else {
            PI
        }
    } else if a % 1.0 == 0.0 && b % 1.0 == 0.0 {
        let g = gcd(a as i64, b as i32 as i64) as f64;
        let (kn, kd) = if g != 1.0 { (a / g, b / g) } else { (a, b) };
        if kn % 2.0 == 0.0 || kd % 2.0 == 0.0 {
            kd * 2.0 * PI
        } else {
            kd * PI
        }
    } else {
        2.0 * PI
    }
}

/// The point of the shape's outline at angle `t`: (x, y, radius).
fn curve_point(q: &[f64; 25], rot: f64, t: f64) -> (f64, f64, f64) {
    let [scale, _, shape, _, _, a, b, c, d, e, f, ..] = *q;
    let u = t - rot;
    let r = match shape as i64 {
        1 => a * b / ((b * u.cos()).powi(2) + (a * u.sin()).powi(2)).sqrt(),
        2 => {
            let (cu, su) = (u.cos(), u.sin());
            (a * a * b * b / (b * b * cu * cu - a * a * su * su)).sqrt()
        }
        3 => {
            let theta = (u % (2.0 * PI)).abs();
            let n = a.floor();
            (PI / n).cos() / (theta % (2.0 * PI / n) - PI / n).cos()
        }
        4 => (a / b * u).cos() + c,
        5 => {
            let s = (a * u.sin()).abs().powf(c);
            let co = (b * u.cos()).abs().powf(c);
            a * b / (s + co).powf(1.0 / c)
        }
        6 => {
            // Gielis' supershape with m = c, n1 = d, n2 = e, n3 = f.
            let (cm, sm) = ((c * u / 4.0).cos(), (c * u / 4.0).sin());
            ((cm / a).abs().powf(e) + (sm / b).abs().powf(f)).powf(-1.0 / d)
        }
        _ => 1.0,
    } * scale;
    (r * t.cos(), r * t.sin(), r)
}

/// The outline's point along the ray at angle `t`; for a rhodonea (whose rays cross it several
/// times) the farthest of its crossings over the half-turns of its period.
fn max_curve_point(q: &[f64; 25], rot: f64, period: f64, t: f64) -> (f64, f64, f64) {
    if q[2] != 4.0 {
        return curve_point(q, rot, t);
    }
    let turns = (period / (2.0 * PI)).clamp(0.0, MAX_TURNS) as i64;
    let mut best = (0.0, 0.0, -0.0001);
    for i in 0..turns {
        let (x, y, r) = curve_point(q, rot, t + i as f64 * PI);
        if r.abs() > best.2 {
            best = (x, y, r.abs());
        }
    }
    best
}

/// The colour from the measure `color_measure` of the inverted point (1: its distance from the
/// outline, 2: the input's, 3: from the input, 4: its radius over the circle inversion's),
/// mapped from [low, high] to [0, 1] (clamped, or wrapped with `color_gradient` 2).
fn measure_colour(
    q: &[f64; 25],
    w: f64,
    src: (f64, f64),
    dst: (f64, f64),
    curve: (f64, f64),
) -> Option<f64> {
    let dist = |a: (f64, f64), b: (f64, f64)| ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt();
    let val = match q[21] as i64 {
        1 => dist(dst, curve),
        2 => dist(src, curve),
        3 => dist(dst, src),
        4 => {
            let r_shape = (dst.0 * dst.0 + dst.1 * dst.1).sqrt();
            let iscale = q[0] * q[0] / (src.0 * src.0 + src.1 * src.1);
            let (cx, cy) = (iscale * src.0 * w, iscale * src.1 * w);
            r_shape / (cx * cx + cy * cy).sqrt()
        }
        _ => return None,
    };
    let (mut low, mut high) = (q[23], q[24]);
    if low > high {
        (low, high) = (high, low);
    }
    let base = if q[22] == 2.0 {
        let val = if val < low {
            high - (low - val) % (high - low)
        } else if val > high {
            low + (val - low) % (high - low)
        } else {
            val
        };
        (val - low) / (high - low) * 255.0
    } else if val < low {
        0.0
    } else if val >= high {
        255.0
    } else {
        (val - low) / (high - low) * 255.0
    };
    Some((base / 255.0).clamp(0.0, 1.0))
}

/// inversion: the outline (a share `draw_shape` of the calls), the input (a share
/// `passthrough`), or the input inverted in the shape when the mode and ring allow, else the
/// input unweighted (hidden with `hide_uninverted` 1).
fn inversion(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 25] = v.params();
    let [rot, period, rmin, rmax] = v.derived();
    let (draw_shape, thickness, passthrough) = (q[17], q[18], q[19]);
    let (xin, yin) = (t.x, t.y);
    if draw_shape > 0.0 && rng.f01() < draw_shape {
        let (x, y, _) = curve_point(&q, rot, rng.f01() * period);
        let (mut x, mut y) = (x, y);
        if thickness != 0.0 {
            x += 0.01 * (rng.f01() - 0.5) * thickness;
            y += 0.01 * (rng.f01() - 0.5) * thickness;
        }
        return [x, y, 0.0];
    }
    if passthrough > 0.0 && rng.f01() < passthrough {
        return [xin, yin, 0.0];
    }
    let tin = yin.atan2(xin);
    let rin = (xin * xin + yin * yin).sqrt();
    let (xc, yc, rc) = max_curve_point(&q, rot, period, tin);
    let mut invert = match q[3] as i64 {
        1 => rin > rc,
        2 => rin < rc,
        _ => true,
    };
    let (ring_mode, ring_scale) = (q[11], q[12]);
    if invert && ring_mode != 0.0 && ring_scale != 1.0 {
        if ring_mode == 1.0 {
            invert = rin >= rmin && rin <= rmax;
        } else if ring_mode == 2.0 {
            invert = rin <= rmin || rin >= rmax;
        }
    }
    if !invert {
        acc.hide = q[4] == 1.0;
        return [xin, yin, 0.0];
    }
    let (pnorm_point, pnorm_shape, pnorm_pmod, pnorm_smod) = (q[13], q[14], q[15], q[16]);
    let num = if pnorm_shape == 2.0 && pnorm_smod == 1.0 {
        rc * rc
    } else {
        (xc.abs().powf(pnorm_shape) + yc.abs().powf(pnorm_shape))
            .powf(2.0 / (pnorm_shape * pnorm_smod))
    };
    let den = if pnorm_point == 2.0 && pnorm_pmod == 1.0 {
        xin * xin + yin * yin
    } else {
        (xin.abs().powf(pnorm_point) + yin.abs().powf(pnorm_point))
            .powf(2.0 / (pnorm_point * pnorm_pmod))
    };
    let s = num / den;
    let out = [v.w * s * xin, v.w * s * yin, 0.0];
    acc.hide = false;
    let dst = (acc.x + out[0], acc.y + out[1]);
    if let Some(c) = measure_colour(&q, v.w, (xin, yin), dst, (xc, yc)) {
        acc.color = c;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rhodonea_periods() {
        assert_eq!(rhodonea_period(2.0, 1.0, 0.0), 2.0 * PI);
        assert_eq!(rhodonea_period(3.0, 1.0, 0.0), PI);
        assert_eq!(rhodonea_period(3.0, 1.0, 0.5), 2.0 * PI);
        // 3/2: numerator odd, denominator even: 2 turns.
        assert_eq!(rhodonea_period(3.0, 2.0, 0.0), 4.0 * PI);
        // 6/4 = 3/2 after the common factor.
        assert_eq!(rhodonea_period(6.0, 4.0, 0.0), 4.0 * PI);
        assert_eq!(gcd(-6, 4), 2);
    }
}
