//! Brad Stefanov's, Andreas Maschke's and Rick Sidwell's `quad` (after guagapunyaimel's "fourth"
//! plugin): the plane is cut into four quadrants around each quadrant's own shift point, and a
//! point in a quadrant goes through the sub-variation chosen for it (one of 49 classic
//! variations, numbered as JWildfire numbers them, each with an amount and two parameters `1a`
//! and `1b`). A point in several quadrants (the shifts differ) gets the mean of their results, a
//! point in none passes unchanged (linear); mode 1 swaps and inverts the result (x' = w/y,
//! y' = w/x). The sub-variations already scale by the weight, and the mean is scaled by it once
//! more, as JWildfire does.
//!
//! The formulas follow JWildfire 9.00 (`QuadFunc`, LGPL-2.1), written anew, with JWildfire's
//! quirks kept: a sub-variation that meets its pole (bipolar, foci, glynnia, the b-* maps) ends
//! the whole call with nothing added; "lazy sensen" flips the point it reads, which the later
//! quadrants' tests see; the upper-left quadrant's "emod" tests its bound with the lower-left
//! quadrant's `1a`. JWildfire's `seed` parameters only draw new `1a`/`1b` values in its editor;
//! they are kept for files and change nothing here.

use super::jwf_s10_quad_subs as more;
use super::util::jwf_math as jm;
use super::util::{bipolar as to_bipolar, elliptic as to_elliptic};
use std::f64::consts::{FRAC_2_PI, FRAC_PI_2, PI, TAU};

use super::jwf_a_complex::DbComplex;
use super::*;

/// One quadrant's parameters, in the order of the file's attributes.
macro_rules! quadrant {
    ($q:literal, $kind:expr) => {
        [
            p_int(concat!("quad_", $q, "_quad"), $kind, 0.0, 50.0),
            p(concat!("quad_", $q, "_amount"), 1.0),
            p(concat!("quad_", $q, "_shiftx"), 0.0),
            p(concat!("quad_", $q, "_shifty"), 0.0),
            p_int(
                concat!("quad_", $q, "_seed"),
                0.0,
                -2147483648.0,
                2147483647.0,
            ),
            p(concat!("quad_", $q, "_1a"), 1.0),
            p(concat!("quad_", $q, "_1b"), 1.0),
        ]
    };
}

/// The parameters: the mode, then the upper-left, upper-right, lower-left and lower-right
/// quadrants.
const QUAD_PARAMS: [Param; 29] = {
    let ul = quadrant!("ul", 0.0);
    let ur = quadrant!("ur", 0.0);
    let ll = quadrant!("ll", 1.0);
    let lr = quadrant!("lr", 1.0);
    let mut all = [p_int("quad_mode", 0.0, 0.0, 1.0); 29];
    let mut i = 0;
    while i < 7 {
        all[1 + i] = ul[i];
        all[8 + i] = ur[i];
        all[15 + i] = ll[i];
        all[22 + i] = lr[i];
        i += 1;
    }
    all
};

pub(super) static DEFS: &[VarDef] = &[VarDef::new("quad", quad)
    .params(&QUAD_PARAMS)
    .flags(flag::JWILDFIRE | flag::RANDOM)];

/// A sub-variation's settings in one call: the variation's weight `w`, the quadrant's amount
/// (`wa` = w·amount) and its parameters `a` (1a) and `b` (1b); `emod_a` is the bound emod
/// tests (see the module documentation).
pub(super) struct Sub {
    pub w: f64,
    pub amount: f64,
    pub wa: f64,
    pub a: f64,
    pub b: f64,
    pub emod_a: f64,
}

/// What a sub-variation gives: a displacement, or `None` to end the whole call unchanged.
pub(super) type Out = Option<(f64, f64)>;

/// First offset of each quadrant's parameters, in the order JWildfire visits them (lower
/// right, upper right, lower left, upper left), with which sides of its shift x and y must lie
/// (+1 above, −1 below).
const VISIT: [(usize, f64, f64); 4] = [
    (22, 1.0, 1.0),
    (8, 1.0, -1.0),
    (15, -1.0, 1.0),
    (1, -1.0, -1.0),
];

/// Does `v` lie strictly on side `s` (+1 above, −1 below) of `shift`?
fn beyond(v: f64, shift: f64, s: f64) -> bool {
    if s > 0.0 { v > shift } else { v < shift }
}

/// quad: see the module documentation.
fn quad(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 29] = v.params();
    let (mut x, mut y) = (t.x, t.y);
    let (mut sx, mut sy, mut count) = (0.0, 0.0, 0u32);
    for (o, side_x, side_y) in VISIT {
        if !(beyond(x, q[o + 2], side_x) && beyond(y, q[o + 3], side_y)) {
            continue;
        }
        let s = Sub {
            w: v.w,
            amount: q[o + 1],
            wa: v.w * q[o + 1],
            a: q[o + 5],
            b: q[o + 6],
            // The upper-left quadrant's emod reads the lower-left quadrant's 1a.
            emod_a: if o == 1 { q[20] } else { q[o + 5] },
        };
        match sub(q[o] as i32, &s, &mut x, &mut y, rng) {
            Some((dx, dy)) => {
                sx += dx;
                sy += dy;
            }
            None => return [0.0; 3],
        }
        count += 1;
    }
    let n = f64::from(count);
    match (q[0] != 0.0, count) {
        (true, 0) => [v.w / y, v.w / x, 0.0],
        (true, _) => [v.w / sy / n, v.w / sx / n, 0.0],
        (false, 0) => [v.w * x, v.w * y, 0.0],
        (false, _) => [v.w * sx / n, v.w * sy / n, 0.0],
    }
}

/// Sub-variation `k` at (x, y) (lazy sensen may flip the point); numbers above 48 add nothing.
fn sub(k: i32, s: &Sub, x: &mut f64, y: &mut f64, rng: &mut FastRng) -> Out {
    let (px, py) = (*x, *y);
    match k {
        0..=24 => first(k, s, px, py, rng),
        34 => Some(more::lazy_sensen(s, x, y)),
        25..=48 => more::second(k, s, px, py, rng),
        _ => Some((0.0, 0.0)),
    }
}

/// `z` or −z, with equal odds (one draw).
fn either_sign(z: DbComplex, rng: &mut FastRng) -> Out {
    if rng.f01() < 0.5 {
        Some((z.re, z.im))
    } else {
        Some((-z.re, -z.im))
    }
}

/// w·(sinh τ, sin σ)/(cosh τ − cos σ), or `None` where the denominator is 0 and `stop_at_pole`.
fn from_bipolar(wa: f64, tau: f64, sigma: f64, stop_at_pole: bool) -> Out {
    let den = jm::cosh(tau) - jm::cos(sigma);
    if stop_at_pole && den == 0.0 {
        return None;
    }
    Some((wa * jm::sinh(tau) / den, wa * jm::sin(sigma) / den))
}

/// The angle `a` folded as the "collide" maps fold it: in the slice `alt` = ⌊a·n/π⌋ of width
/// π/n, shifted by `shift` forwards in even slices and backwards in odd ones (C's `fmod`).
fn collide_fold(a: f64, n: f64, shift: f64) -> f64 {
    let (n_pi, pi_n) = (n * (1.0 / PI), PI / n);
    let alt = (a * n_pi) as i32;
    if alt % 2 == 0 {
        f64::from(alt) * pi_n + (a + shift) % pi_n
    } else {
        f64::from(alt) * pi_n + (a - shift) % pi_n
    }
}

/// Sub-variations 0 to 24.
fn first(k: i32, s: &Sub, x: f64, y: f64, rng: &mut FastRng) -> Out {
    let wa = s.wa;
    let (a, b) = (s.a, s.b);
    match k {
        // linear
        0 => Some((wa * x, wa * y)),
        // spherical, x² and y² weighted by 1a and 1b
        1 => {
            let r = wa / (x * x * a + y * y * b + 1e-300);
            Some((x * r, y * r))
        }
        // acosech: acosh(1/z), parts swapped, either sign
        2 => {
            let z = DbComplex::new(x, y).recip().acosh().flip();
            either_sign(z.scale(wa * FRAC_2_PI), rng)
        }
        // acosh, either sign
        3 => either_sign(DbComplex::new(x, y).acosh().scale(wa * FRAC_2_PI), rng),
        // acoth: atanh(1/z), parts swapped
        4 => {
            let z = DbComplex::new(x, y).recip().atanh().flip();
            let z = z.scale(wa * FRAC_2_PI);
            Some((z.re, z.im))
        }
        5 => Some(apollony(wa, x, y, rng)),
        // arcsinh: ln(z + √(z² + 1))
        6 => {
            let z = DbComplex::new(x, y);
            let d = z.sqr().add(DbComplex::new(1.0, 0.0)).sqrt();
            let z = z.add(d).ln().scale(wa * FRAC_2_PI);
            Some((z.re, z.im))
        }
        // arctanh: ln((1 + z)/(1 − z)), without the ½
        7 => {
            let q = DbComplex::new(x + 1.0, y).div(DbComplex::new(1.0 - x, -y));
            let z = q.ln().scale(wa * FRAC_2_PI);
            Some((z.re, z.im))
        }
        // atan, both axes, stretched by 1a and 1b
        8 => {
            let norm = 1.0 / FRAC_PI_2 * wa;
            Some((norm * jm::atan(a * x), norm * jm::atan(b * y)))
        }
        // bcollide
        9 => {
            let (tau, sigma) = to_bipolar(x, y);
            let sigma = collide_fold(sigma, a, PI * b / a);
            from_bipolar(wa, tau, sigma, false)
        }
        // bmod
        10 => {
            let (mut tau, sigma) = to_bipolar(x, y);
            if tau < a && -tau < a {
                tau = (tau + a + b * a) % (2.0 * a) - a;
            }
            from_bipolar(wa, tau, sigma, true)
        }
        // bswirl
        11 => {
            let (tau, sigma) = to_bipolar(x, y);
            from_bipolar(wa, tau, sigma + tau * b + a / tau, true)
        }
        // btransform
        12 => {
            let (tau, sigma) = to_bipolar(x, y);
            let mut tau = tau / a;
            let sigma = sigma / a + TAU / a * (rng.f01() * a).floor();
            tau += if x >= 0.0 { b } else { -b };
            from_bipolar(wa, tau, sigma, false)
        }
        // bent
        13 => {
            let nx = if x < 0.0 { x * a } else { x };
            let ny = if y < 0.0 { y * b } else { y };
            Some((wa * nx, wa * ny))
        }
        14 => bipolar(wa, a, b, x, y),
        // blob
        15 => {
            let ang = jm::atan2(x, y);
            let r = jm::sqrt(x * x + y * y);
            let r = r * (a + (b - a) * (0.5 + 0.5 * jm::sin(6.0 * ang)));
            Some((wa * (jm::sin(ang) * r), wa * (jm::cos(ang) * r)))
        }
        // butterfly
        16 => {
            let y2 = y * b;
            let r = wa * a * jm::sqrt((y * x).abs() / (1e-300 + x * x + y2 * y2));
            Some((r * x, r * y2))
        }
        17 => Some(collideoscope(wa, a, b, x, y)),
        // cpow, two branches
        18 => {
            let ang0 = jm::atan2(y, x);
            let lnr = 0.5 * (x * x + y * y).ln();
            let (vc, vd) = (a / 2.0, b / 2.0);
            let ang = vc * ang0 + vd * lnr + PI * (2.0 * rng.f01()).floor();
            let m = wa * jm::exp(vc * lnr - vd * ang0);
            Some((m * jm::cos(ang), m * jm::sin(ang)))
        }
        // curl
        19 => {
            let re = 1.0 + a * x + b * (x * x - y * y);
            let im = a * y + b * 2.0 * x * y;
            let r = wa / (re * re + im * im);
            Some(((x * re + y * im) * r, (y * re - x * im) * r))
        }
        // devil warp (scaled by the amount only)
        20 => {
            let r2 = 1.0 / (x * x + y * y);
            let r = jm::pow(x * x + r2 * y * y, b) - jm::pow(y * y + r2 * 2.0 * x * x, b);
            let r = a * r.clamp(-0.24, 100.0);
            Some((s.amount * x * (1.0 + r), s.amount * y * (1.0 + r)))
        }
        // disc, the radius scaled by 1a
        21 => {
            let rpi = PI * jm::sqrt(x * x + y * y) * a;
            let r = wa * jm::atan2(x, y) / PI;
            Some((jm::sin(rpi) * r, jm::cos(rpi) * r))
        }
        22 => Some(ecollide(wa, a, b, x, y)),
        23 => Some(edisc(wa, x, y)),
        24 => Some(ejulia(wa, a, x, y, rng)),
        _ => Some((0.0, 0.0)),
    }
}

/// apollony: one of the three Möbius maps of the Apollonian gasket (the first with odds ½).
fn apollony(wa: f64, x: f64, y: f64, rng: &mut FastRng) -> (f64, f64) {
    let r = jm::sqrt(3.0);
    let den = jm::pow(1.0 + r - x, 2.0) + y * y;
    let a0 = 3.0 * (1.0 + r - x) / den - (1.0 + r) / (2.0 + r);
    let b0 = 3.0 * y / den;
    let m = a0 * a0 + b0 * b0;
    let (f1x, f1y) = (a0 / m, -b0 / m);
    let (xx, yy) = match ((4.0 * rng.f01()) as i32) % 3 {
        0 => (a0, b0),
        1 => (-f1x / 2.0 - f1y * r / 2.0, f1x * r / 2.0 - f1y / 2.0),
        _ => (-f1x / 2.0 + f1y * r / 2.0, -f1x * r / 2.0 - f1y / 2.0),
    };
    (xx * wa, yy * wa)
}

/// bipolar: 1a turns the angle, 1b shifts the foci's distance; `None` off its domain.
fn bipolar(wa: f64, a: f64, b: f64, x: f64, y: f64) -> Out {
    let x2y2 = x * x + y * y;
    let t = x2y2 + b;
    let x2 = 2.0 * x;
    let mut yb = 0.5 * jm::atan2(2.0 * y, x2y2 - 1.0) + -FRAC_PI_2 * a;
    if yb > FRAC_PI_2 {
        yb = -FRAC_PI_2 + (yb + FRAC_PI_2) % PI;
    } else if yb < -FRAC_PI_2 {
        yb = FRAC_PI_2 - (FRAC_PI_2 - yb) % PI;
    }
    let (f, g) = (t + x2, t - x2);
    if g == 0.0 || f / g <= 0.0 {
        return None;
    }
    Some((
        wa * 0.25 * FRAC_2_PI * ((t + x2) / (t - x2)).ln(),
        wa * FRAC_2_PI * yb,
    ))
}

/// collideoscope: the angle folded into slices of π/1b, shifted by π·1a/1b.
fn collideoscope(wa: f64, a: f64, b: f64, x: f64, y: f64) -> (f64, f64) {
    let ang = jm::atan2(y, x);
    let r = wa * jm::sqrt(x * x + y * y);
    let (pi_kn, ka_kn) = (PI / b, PI * a / b);
    let kn_pi = b * (1.0 / PI);
    let ang = if ang >= 0.0 {
        collide_fold(ang, b, ka_kn)
    } else {
        let alt = (-ang * kn_pi) as i32;
        let base = f64::from(alt) * pi_kn;
        if alt % 2 != 0 {
            -(base + (-ka_kn - ang) % pi_kn)
        } else {
            -(base + (ka_kn - ang) % pi_kn)
        }
    };
    (r * jm::cos(ang), r * jm::sin(ang))
}

/// ecollide: the elliptic angle folded as the collide maps fold it.
fn ecollide(wa: f64, a: f64, b: f64, x: f64, y: f64) -> (f64, f64) {
    let (xmax, nu) = to_elliptic(x, x * x + y * y, true);
    let mut nu = collide_fold(nu, a, PI * b / a);
    if y <= 0.0 {
        nu = -nu;
    }
    (
        wa * xmax * jm::cos(nu),
        wa * jm::sqrt(xmax - 1.0) * jm::sqrt(xmax + 1.0) * jm::sin(nu),
    )
}

/// edisc.
fn edisc(wa: f64, x: f64, y: f64) -> (f64, f64) {
    let tmp = x * x + y * y + 1.0;
    let tmp2 = 2.0 * x;
    let xmax = (jm::sqrt(tmp + tmp2) + jm::sqrt(tmp - tmp2)) * 0.5;
    let a1 = (xmax + jm::sqrt(xmax - 1.0)).ln();
    let a2 = -jm::acos(x / xmax);
    let w = wa / 11.57034632;
    let snv = if y > 0.0 { -jm::sin(a1) } else { jm::sin(a1) };
    (w * jm::cosh(a2) * jm::cos(a1), w * jm::sinh(a2) * snv)
}

/// JWildfire's acosh: ln(√(d² − 1) + d).
pub(super) fn acosh(d: f64) -> f64 {
    (jm::sqrt(jm::pow(d, 2.0) - 1.0) + d).ln()
}

/// ejulia: the 1a-th root in elliptic coordinates (inverted first for a negative 1a).
fn ejulia(wa: f64, a: f64, x: f64, y: f64, rng: &mut FastRng) -> (f64, f64) {
    let r2 = y * y + x * x;
    let (r2, x) = if a < 0.0 {
        (1.0 / r2, x * (1.0 / r2))
    } else {
        (r2, x)
    };
    let (xmax, nu) = to_elliptic(x, r2, true);
    let nu = if y < 0.0 { -nu } else { nu };
    let nu = nu / a + TAU / a * (rng.f01() * a).floor();
    let mu = acosh(xmax) / a;
    (
        wa * jm::cosh(mu) * jm::cos(nu),
        wa * jm::sinh(mu) * jm::sin(nu),
    )
}
