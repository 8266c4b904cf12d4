//! `quad`'s sub-variations 25 to 48 (emod to whorl), as JWildfire 9.00 numbers them
//! (`QuadFunc`, LGPL-2.1, written anew); see `jwf_s10_quad` for the quadrants.

use super::jwf_s10_quad::{Out, Sub, acosh};
use super::util::elliptic as to_elliptic;
use super::util::jwf_math as jm;
use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, PI, TAU};

use super::*;

/// Sub-variations 25 to 48 but 34 (lazy sensen, which changes the point: [`lazy_sensen`]).
pub(super) fn second(k: i32, s: &Sub, x: f64, y: f64, rng: &mut FastRng) -> Out {
    let (wa, a, b) = (s.wa, s.a, s.b);
    match k {
        25 => Some(emod(s, x, y)),
        26 => Some(eclipse(s, x, y)),
        27 => Some(elliptic(wa, a, b, x, y, rng)),
        28 => Some(fan2(wa, a, b, x, y)),
        29 => foci(wa, x, y),
        30 => glynnia(wa, x, y, rng),
        // hole
        31 => {
            let alpha = jm::atan2(y, x);
            let delta = jm::pow(alpha / PI + 1.0, a);
            let r = if b != 0.0 {
                wa * delta / (x * x + y * y + delta)
            } else {
                wa * jm::sqrt(x * x + y * y + delta)
            };
            Some((r * jm::cos(alpha), r * jm::sin(alpha)))
        }
        // idisc
        32 => {
            let ang = PI / (jm::sqrt(x * x + y * y) + 1.0);
            let r = jm::atan2(y, x) * (wa * FRAC_1_PI);
            Some((r * jm::cos(ang), r * jm::sin(ang)))
        }
        // julian: power 1a, distance exponent 1b
        33 => {
            // JWildfire's random(n): ⌊u·n⌋ below n, else n − 1 (−1 for n = 0).
            let n = i64::from(ftoi(a)).abs();
            let branch = ((rng.f01() * n as f64) as i64).min(n - 1);
            let ang = (jm::atan2(y, x) + 2.0 * PI * branch as f64) / a;
            let r = wa * jm::pow(x * x + y * y, b / a * 0.5);
            Some((r * jm::cos(ang), r * jm::sin(ang)))
        }
        35 => Some(lazy_susan(s, x, y)),
        36 => Some(murl2(wa, a, b, x, y)),
        37 => Some(ortho(wa, a, b, x, y)),
        // rectangles
        38 => {
            let fold = |v: f64, size: f64| {
                if size.abs() < 1e-8 {
                    v
                } else {
                    (2.0 * (v / size).floor() + 1.0) * size - v
                }
            };
            Some((wa * fold(x, a), wa * fold(y, b)))
        }
        // sinusoidal
        39 => Some((wa * jm::sin(x), wa * jm::sin(y))),
        // sphericaln
        40 => {
            let r = jm::pow(jm::sqrt(x * x + y * y), b);
            let n = (a * rng.f01()).floor() as i32;
            let alpha = jm::atan2(y, x) + f64::from(n) * TAU / a.floor();
            if r > 1e-300 {
                Some((wa * jm::cos(alpha) / r, wa * jm::sin(alpha) / r))
            } else {
                Some((0.0, 0.0))
            }
        }
        // waves2
        41 => Some((wa * (x + a * jm::sin(y * b)), wa * (y + a * jm::sin(x * b)))),
        // waves22: the sines squared
        42 => Some((
            wa * (x + jm::pow(jm::sin(y * b), 2.0) * a),
            wa * (y + jm::pow(jm::sin(x * b), 2.0) * a),
        )),
        // waves23: saw-tooth waves
        43 => {
            let saw = |v: f64| {
                let m = v * b * (1.0 / TAU);
                let f = m - m.floor();
                if f > 0.5 { 0.5 - f } else { f }
            };
            Some((wa * (x + saw(y) * a), wa * (y + saw(x) * a)))
        }
        // waves3
        44 => {
            let scale_x = 0.5 * a * (1.0 + jm::sin(y * 0.0));
            let scale_y = 0.5 * a * (1.0 + jm::sin(x * 2.0));
            Some((
                wa * (x + jm::sin(y * b) * scale_x),
                wa * (y + jm::sin(x * b) * scale_y),
            ))
        }
        // waves4 and waves42: the x wave's height hashed per band of y
        45 | 46 => {
            let band = if k == 45 {
                (y * b / TAU).floor()
            } else {
                (y * b).floor()
            };
            let h = jm::sin(band * 12.9898 + band * 78.233 + 1.0 + y * 0.001 * 0.1) * 43758.5453;
            let h = h - f64::from(h as i32);
            Some((
                wa * (x + jm::sin(y * b) * h * h * a),
                wa * (y + jm::sin(x * b) * a),
            ))
        }
        // wdisc
        47 => {
            let mut ang = PI / (jm::sqrt(x * x + y * y) + a);
            let r = jm::atan2(y, x) * FRAC_1_PI;
            if r > 0.0 {
                ang = PI - ang;
            }
            Some((wa * r * jm::cos(ang), wa * r * jm::sin(ang)))
        }
        // whorl
        48 => {
            let r = jm::sqrt(x * x + y * y) + 1e-300;
            let turn = if r < s.w { a } else { b };
            let ang = jm::atan2(y, x) + turn / (s.w - r);
            Some((wa * r * jm::cos(ang), wa * r * jm::sin(ang)))
        }
        _ => Some((0.0, 0.0)),
    }
}

/// JWildfire's `Tools.FTOI`: rounds half away from 0 (saturating).
fn ftoi(v: f64) -> i32 {
    if v > 0.0 {
        (v + 0.5) as i32
    } else if v < 0.0 {
        -((-v + 0.5) as i32)
    } else {
        0
    }
}

/// lazy sensen: x flipped in every other band of width 1/1a (1a ≠ 0), y likewise with 1b; the
/// point itself is flipped.
pub(super) fn lazy_sensen(s: &Sub, x: &mut f64, y: &mut f64) -> (f64, f64) {
    let flip = |v: &mut f64, k: f64| {
        if k != 0.0 {
            // The band number as Java's (int) cast leaves it.
            let nr = f64::from((*v * k).floor() as i32);
            let odd = if nr >= 0.0 {
                nr % 2.0 == 1.0
            } else {
                nr % 2.0 == 0.0
            };
            if odd {
                *v = -*v;
            }
        }
    };
    flip(x, s.a);
    flip(y, s.b);
    (s.wa * *x, s.wa * *y)
}

/// emod: the elliptic μ wrapped into (−1a, 1a) with offset 1b (see the module documentation of
/// `jwf_s10_quad` for the bound).
fn emod(s: &Sub, x: f64, y: f64) -> (f64, f64) {
    let (xmax, nu) = to_elliptic(x, y * y + x * x, true);
    let nu = if y < 0.0 { -nu } else { nu };
    let mut mu = acosh(xmax);
    let a = s.a;
    if mu < s.emod_a && -mu < s.emod_a {
        mu = if nu > 0.0 {
            (mu + a + s.b * a) % (2.0 * a) - a
        } else {
            (mu - a - s.b * a) % (2.0 * a) + a
        };
    }
    (
        s.wa * jm::cosh(mu) * jm::cos(nu),
        s.wa * jm::sinh(mu) * jm::sin(nu),
    )
}

/// eclipse: inside the band |y| ≤ w, points within the disc of radius w shift by 1a·w·amount
/// along x, mirrored where they would leave it.
fn eclipse(s: &Sub, x: f64, y: f64) -> (f64, f64) {
    let wa = s.wa;
    if y.abs() > s.w {
        return (wa * x, wa * y);
    }
    let c2 = jm::sqrt(s.w * s.w - y * y);
    let dx = if x.abs() <= c2 {
        let moved = x + s.a * s.w * s.amount;
        if moved.abs() >= c2 {
            -(wa * x)
        } else {
            wa * moved
        }
    } else {
        wa * x
    };
    (dx, wa * y)
}

/// √x, or 0 below 1e-300.
fn sqrt_e(v: f64) -> f64 {
    if v < 1e-300 { 0.0 } else { jm::sqrt(v) }
}

/// elliptic, 1a added to the radius and 1b in place of 1; either sign of y.
fn elliptic(wa: f64, a: f64, b: f64, x: f64, y: f64, rng: &mut FastRng) -> (f64, f64) {
    let v = wa / FRAC_PI_2;
    let tmp = y * y + x * x + a;
    let x2 = 2.0 * x;
    let xmax = 0.5 * (jm::sqrt(tmp + x2) + jm::sqrt(tmp - x2));
    let q = x / xmax;
    let w = sqrt_e(b - q * q);
    let ny = v * (xmax + sqrt_e(xmax - 1.0)).ln();
    let ny = if rng.f01() < 0.5 { ny } else { -ny };
    (v * jm::atan2(q, w), ny)
}

/// fan2: 1a sets the fan's width (π·1a²), 1b its offset.
fn fan2(wa: f64, a: f64, b: f64, x: f64, y: f64) -> (f64, f64) {
    let r = jm::sqrt(x * x + y * y);
    let tiny = |v: f64| (-1e-300..=1e-300).contains(&v);
    let angle = if tiny(x) && tiny(y) {
        0.0
    } else {
        jm::atan2(x, y)
    };
    let dx = PI * (a * a) + 1e-300;
    let dx2 = dx * 0.5;
    let t = angle + b - f64::from(((angle + b) / dx) as i32) * dx;
    let ang = if t > dx2 { angle - dx2 } else { angle + dx2 };
    (wa * r * jm::sin(ang), wa * r * jm::cos(ang))
}

/// foci; `None` where exp(x) under- or overflows or the denominator is 0.
fn foci(wa: f64, x: f64, y: f64) -> Out {
    let expx = jm::exp(x) * 0.5;
    let expnx = 0.25 / expx;
    if expx <= 1e-300 || expnx <= 1e-300 {
        return None;
    }
    let tmp = expx + expnx - jm::cos(y);
    if tmp == 0.0 {
        return None;
    }
    let tmp = wa / tmp;
    Some(((expx - expnx) * tmp, jm::sin(y) * tmp))
}

/// glynnia; `None` where its denominators vanish.
fn glynnia(wa: f64, x: f64, y: f64, rng: &mut FastRng) -> Out {
    let vvar2 = wa * jm::sqrt(2.0) / 2.0;
    let r = jm::sqrt(x * x + y * y);
    let outside = r >= 1.0;
    let sx = if outside { 1.0 } else { -1.0 };
    if rng.f01() > 0.5 {
        let d = jm::sqrt(r + x);
        if d == 0.0 {
            return None;
        }
        Some((sx * (vvar2 * d), -(vvar2 / d * y)))
    } else {
        let d = r + x;
        let dx = jm::sqrt(r * (y * y + d * d));
        if dx == 0.0 {
            return None;
        }
        let r = wa / dx;
        Some((sx * (r * d), r * y))
    }
}

/// lazysusan: inside the circle of radius w the point turns by 1b + 1a·(w·amount − r).
fn lazy_susan(s: &Sub, x: f64, y: f64) -> (f64, f64) {
    let rr = jm::sqrt(x * x + y * y);
    if rr < s.w {
        let ang = jm::atan2(y, x) + s.b + s.a * (s.wa - rr);
        let rr = s.wa * rr;
        (rr * jm::cos(ang), rr * jm::sin(ang))
    } else {
        // JWildfire's 1 + 0/r (NaN at r = 0).
        let rr = s.wa * (1.0 + 0.0 / rr);
        (rr * x, rr * y)
    }
}

/// murl2: 1a the strength, 1b the power.
fn murl2(wa: f64, a: f64, b: f64, x: f64, y: f64) -> (f64, f64) {
    let p2 = b / 2.0;
    let (invp, vp) = if b != 0.0 {
        let vp = if a == -1.0 {
            0.0
        } else {
            wa * jm::pow(a + 1.0, 2.0 / b)
        };
        (1.0 / b, vp)
    } else {
        (100000000000.0, wa * jm::pow(a + 1.0, 4.0))
    };
    let ang = jm::atan2(y, x) * b;
    let r = a * jm::pow(x * x + y * y, p2);
    let re = r * jm::cos(ang) + 1.0;
    let im = r * jm::sin(ang);
    let r = jm::pow(re * re + im * im, invp);
    let ang = jm::atan2(im, re) * 2.0 * invp;
    let (re, im) = (r * jm::cos(ang), r * jm::sin(ang));
    let rl = vp / (r * r);
    (rl * (x * re + y * im), rl * (y * re - x * im))
}

/// One ortho arc: the point (u ≥ 0, y) with |u, y|² + 1 = `r1`, moved along the circle through
/// it orthogonal to the unit circle by `k` times the arc's half-angle.
fn ortho_arc(u: f64, y: f64, r1: f64, k: f64) -> (f64, f64) {
    let xo = r1 / (2.0 * u);
    let ro = jm::sqrt((u - xo) * (u - xo) + y * y);
    let theta = jm::atan2(1.0, ro);
    let ang = (k * theta + jm::atan2(y, xo - u) + theta) % (2.0 * theta) - theta;
    (xo - jm::cos(ang) * ro, jm::sin(ang) * ro)
}

/// ortho: inside the unit circle by 1a, outside (inverted, moved by 1b, inverted back).
fn ortho(wa: f64, a: f64, b: f64, x: f64, y: f64) -> (f64, f64) {
    let r = x * x + y * y;
    if r < 1.0 {
        let sx = if x >= 0.0 { 1.0 } else { -1.0 };
        let (px, py) = ortho_arc(sx * x, y, r + 1.0, a);
        return (sx * (wa * px), wa * py);
    }
    let r = 1.0 / jm::sqrt(r);
    let ta = jm::atan2(y, x);
    let (ix, iy) = (r * jm::cos(ta), r * jm::sin(ta));
    let sx = if ix >= 0.0 { 1.0 } else { -1.0 };
    let (px, py) = ortho_arc(sx * ix, iy, ix * ix + iy * iy + 1.0, b);
    let ta = jm::atan2(py, px);
    let r = 1.0 / jm::sqrt(px * px + py * py);
    (sx * (wa * r * jm::cos(ta)), wa * r * jm::sin(ta))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ftoi_rounds_half_away_from_zero() {
        assert_eq!(ftoi(2.5), 3);
        assert_eq!(ftoi(-2.5), -3);
        assert_eq!(ftoi(-2.4), -2);
        assert_eq!(ftoi(0.0), 0);
    }

    #[test]
    fn lazy_sensen_flips_odd_bands() {
        let s = Sub {
            w: 1.0,
            amount: 1.0,
            wa: 1.0,
            a: 1.0,
            b: 1.0,
            emod_a: 1.0,
        };
        let (mut x, mut y) = (1.5, -0.5);
        // x in band 1 (odd) flips; y in band −1 (odd, nr % 2 = −1) stays.
        let out = lazy_sensen(&s, &mut x, &mut y);
        assert_eq!((x, y), (-1.5, -0.5));
        assert_eq!(out, (-1.5, -0.5));
    }
}
