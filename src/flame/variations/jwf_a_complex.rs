//! JWildfire's functions of the complex plane: the detuned trigonometric family `sin2_bs` …
//! `coth2_bs`, `sec2_bs`, the inverse hyperbolic functions in DarkBeam's complex arithmetic
//! (`acosh`, `acosech`, `sqrt_acosh`, `sqrt_atanh`, `sqrt_acosech`), `log_apo`, `invpolar`,
//! `bi_linear` and the Joukowski airfoil map `joukowski`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: weights multiply the output linearly, and
//! random numbers are drawn in the order JWildfire draws them.

use std::f64::consts::{FRAC_2_PI, PI};

use super::util::jwf_math as jm;
use super::*;

/// The four detuning factors of the `*2_bs` family (JWildfire's defaults differ per function).
macro_rules! bs_params {
    ($n:literal, $d:literal) => {
        &[
            p(concat!($n, "_x1"), $d),
            p(concat!($n, "_x2"), $d),
            p(concat!($n, "_y1"), $d),
            p(concat!($n, "_y2"), $d),
        ]
    };
}

/// Apophysis' 14-digit e, log_apo's default base.
#[allow(clippy::approx_constant)]
const APO_E: f64 = 2.71828182845905;

/// Flags of the variations that pick the sign of their output at random.
const RANDOM_SIGN: u32 = flag::JWILDFIRE | flag::RANDOM;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("sin2_bs", sin2_bs)
        .params(bs_params!("sin2_bs", 1.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("cosh2_bs", cosh2_bs)
        .params(bs_params!("cosh2_bs", 1.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("cot2_bs", cot2_bs)
        .params(bs_params!("cot2_bs", 2.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("tan2_bs", tan2_bs)
        .params(bs_params!("tan2_bs", 2.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("tanh2_bs", tanh2_bs)
        .params(bs_params!("tanh2_bs", 2.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("coth2_bs", coth2_bs)
        .params(bs_params!("coth2_bs", 2.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("sec2_bs", sec2_bs)
        .params(&[
            p("sec2_bs_x1", 1.25),
            p("sec2_bs_x2", 0.75),
            p("sec2_bs_y1", 1.5),
            p("sec2_bs_y2", 0.5),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("acosh", acosh).flags(RANDOM_SIGN),
    VarDef::new("acosech", acosech).flags(RANDOM_SIGN),
    VarDef::new("sqrt_acosh", sqrt_acosh).flags(RANDOM_SIGN),
    VarDef::new("sqrt_atanh", sqrt_atanh).flags(RANDOM_SIGN),
    VarDef::new("sqrt_acosech", sqrt_acosech).flags(RANDOM_SIGN),
    VarDef::new("log_apo", log_apo)
        .params(&[p("log_apo_base", APO_E)])
        .flags(flag::JWILDFIRE)
        .prepare(log_apo_prepare),
    VarDef::new("invpolar", invpolar).flags(flag::JWILDFIRE),
    VarDef::new("bi_linear", bi_linear).flags(flag::JWILDFIRE),
    VarDef::new("joukowski", joukowski)
        .params(&[
            p("joukowski_P1", 2.5),
            p("joukowski_P2", 0.0),
            p_int("joukowski_inverse", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE),
];

/// sin2_bs: the complex sine with its four parts detuned: (sin(x1·x)·cosh(y2·y),
/// cos(x2·x)·sinh(y1·y)).
fn sin2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    let ox = (t.x * x1).sin() * (t.y * y2).cosh();
    let oy = (t.x * x2).cos() * (t.y * y1).sinh();
    [v.w * ox, v.w * oy, 0.0]
}

/// cosh2_bs: the complex hyperbolic cosine, detuned: (cosh(x2·x)·cos(y2·y),
/// sinh(x1·x)·sin(y1·y)).
fn cosh2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    let ox = (t.x * x2).cosh() * (t.y * y2).cos();
    let oy = (t.x * x1).sinh() * (t.y * y1).sin();
    [v.w * ox, v.w * oy, 0.0]
}

/// cot2_bs: the complex cotangent, detuned: (sin(x1·x), −sinh(y1·y)) / (cosh(y2·y) −
/// cos(x2·x)) (no guard: the poles give infinities).
fn cot2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    let den = 1.0 / ((y2 * t.y).cosh() - (x2 * t.x).cos());
    let ox = den * (x1 * t.x).sin();
    let oy = den * -(y1 * t.y).sinh();
    [v.w * ox, v.w * oy, 0.0]
}

/// tan2_bs: the complex tangent, detuned: (sin(x1·x), sinh(y1·y)) / (cos(x2·x) + cosh(y2·y));
/// nothing is added where the denominator vanishes.
fn tan2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    let d = (x2 * t.x).cos() + (y2 * t.y).cosh();
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 1.0 / d;
    [
        v.w * den * (x1 * t.x).sin(),
        v.w * den * (y1 * t.y).sinh(),
        0.0,
    ]
}

/// tanh2_bs: the complex hyperbolic tangent, detuned: (sinh(x1·x), sin(y1·y)) / (cos(y2·y) +
/// cosh(x2·x)); nothing is added where the denominator vanishes.
fn tanh2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    let d = (y2 * t.y).cos() + (x2 * t.x).cosh();
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 1.0 / d;
    [
        v.w * den * (x1 * t.x).sinh(),
        v.w * den * (y1 * t.y).sin(),
        0.0,
    ]
}

/// coth2_bs: the complex hyperbolic cotangent, detuned: (sinh(x1·x), sin(y1·y)) / (cosh(x2·x) −
/// cos(y2·y)); nothing is added where the denominator vanishes.
fn coth2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    // JWildfire's table maths: near the origin d is a difference of nearly equal numbers.
    let d = jm::cosh(x2 * t.x) - jm::cos(y2 * t.y);
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 1.0 / d;
    [
        v.w * den * jm::sinh(x1 * t.x),
        v.w * den * jm::sin(y1 * t.y),
        0.0,
    ]
}

/// sec2_bs: the complex secant, detuned: 2·(cos(x2·x)·cosh(y2·y), sin(x1·x)·sinh(y1·y)) /
/// (cos 2x + cosh 2y); nothing is added where the denominator vanishes.
fn sec2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    let d = (2.0 * t.x).cos() + (2.0 * t.y).cosh();
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 2.0 / d;
    [
        v.w * den * (t.x * x2).cos() * (t.y * y2).cosh(),
        v.w * den * (t.x * x1).sin() * (t.y * y1).sinh(),
        0.0,
    ]
}

/// Complex arithmetic as DarkBeam wrote it for JWildfire (its own guards: a reciprocal of a
/// number below 1e-50 in modulus is the number itself, the logarithm adds 1e-20 to |z|²), so
/// that the inverse functions agree with JWildfire's near their singularities.
#[derive(Clone, Copy, Debug)]
pub(super) struct DbComplex {
    pub re: f64,
    pub im: f64,
}

impl DbComplex {
    pub fn new(re: f64, im: f64) -> DbComplex {
        DbComplex { re, im }
    }
    fn mag2(self) -> f64 {
        self.re * self.re + self.im * self.im
    }
    /// 1/|z|², or 1 for |z|² below 1e-100.
    fn mag_inv(self) -> f64 {
        let m2 = self.mag2();
        if m2 < 1e-100 { 1.0 } else { 1.0 / m2 }
    }
    pub fn sqr(self) -> DbComplex {
        DbComplex::new(
            self.re * self.re - self.im * self.im,
            2.0 * self.re * self.im,
        )
    }
    pub fn recip(self) -> DbComplex {
        let mi = self.mag_inv();
        DbComplex::new(self.re * mi, -self.im * mi)
    }
    pub fn scale(self, k: f64) -> DbComplex {
        DbComplex::new(self.re * k, self.im * k)
    }
    pub fn add(self, o: DbComplex) -> DbComplex {
        DbComplex::new(self.re + o.re, self.im + o.im)
    }
    /// Swaps the real and imaginary parts.
    pub fn flip(self) -> DbComplex {
        DbComplex::new(self.im, self.re)
    }
    /// self / o (o = 0 divides by 1).
    pub fn div(self, o: DbComplex) -> DbComplex {
        let r2 = self.im * o.im + self.re * o.re;
        let i2 = self.im * o.re - self.re * o.im;
        let m = o.mag_inv();
        DbComplex::new(r2 * m, i2 * m)
    }
    /// Principal square root (the sign of the imaginary part follows the input's, +1 at 0).
    pub fn sqrt(self) -> DbComplex {
        let rad = self.re.hypot(self.im);
        let sb = if self.im < 0.0 { -1.0 } else { 1.0 };
        DbComplex::new(
            (0.5 * (rad + self.re)).sqrt(),
            sb * (0.5 * (rad - self.re)).sqrt(),
        )
    }
    /// ln z with |z|² + 1e-20 in place of |z|².
    pub fn ln(self) -> DbComplex {
        DbComplex::new(0.5 * (self.mag2() + 1e-20).ln(), self.im.atan2(self.re))
    }
    /// atanh z = ½·ln((1 + z) / (1 − z)).
    pub fn atanh(self) -> DbComplex {
        let d = DbComplex::new(1.0 - self.re, -self.im);
        DbComplex::new(self.re + 1.0, self.im)
            .div(d)
            .ln()
            .scale(0.5)
    }
    /// acosh z = ln(z + √(z² − 1)).
    pub fn acosh(self) -> DbComplex {
        let s = self.sqr();
        let d = DbComplex::new(s.re - 1.0, s.im).sqrt();
        self.add(d).ln()
    }
}

/// Adds `z` or `−z` (one draw, equal odds), as the random-branch inverse functions do.
fn random_branch(z: DbComplex, rng: &mut FastRng) -> V3 {
    if rng.f01() < 0.5 {
        [z.re, z.im, 0.0]
    } else {
        [-z.re, -z.im, 0.0]
    }
}

/// acosh: the inverse hyperbolic cosine, scaled by 2/π, on a random branch (±).
fn acosh(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let z = DbComplex::new(t.x, t.y).acosh().scale(v.w * FRAC_2_PI);
    random_branch(z, rng)
}

/// acosech: the inverse hyperbolic cosecant (acosh of 1/z, real and imaginary parts swapped),
/// scaled by 2/π, on a random branch.
fn acosech(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let z = DbComplex::new(t.x, t.y)
        .recip()
        .acosh()
        .flip()
        .scale(v.w * FRAC_2_PI);
    random_branch(z, rng)
}

/// sqrt_acosh: acosh of √z, scaled by 2/π, on a random branch.
fn sqrt_acosh(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let z = DbComplex::new(t.x, t.y)
        .sqrt()
        .acosh()
        .scale(v.w * FRAC_2_PI);
    random_branch(z, rng)
}

/// sqrt_atanh: atanh of √z, scaled by 2/π, on a random branch.
fn sqrt_atanh(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let z = DbComplex::new(t.x, t.y)
        .sqrt()
        .atanh()
        .scale(v.w * FRAC_2_PI);
    random_branch(z, rng)
}

/// sqrt_acosech: acosh of 1/√z, scaled by 2/π, on a random branch.
fn sqrt_acosech(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let z = DbComplex::new(t.x, t.y)
        .sqrt()
        .recip()
        .acosh()
        .scale(v.w * FRAC_2_PI);
    random_branch(z, rng)
}

fn log_apo_prepare(v: &mut Prepared) {
    let [base] = v.params();
    v.p.push(0.5 / base.ln());
}

/// log_apo: the complex logarithm in base `base`: (log_base |z|, arg z) (the angle is not
/// divided by ln base, as in Apophysis' plugin).
fn log_apo(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [denom] = v.derived();
    [
        v.w * (t.x * t.x + t.y * t.y).ln() * denom,
        v.w * t.y.atan2(t.x),
        0.0,
    ]
}

/// invpolar: the inverse of polar: x is read as an angle (in units of π), 1 + y as a radius.
fn invpolar(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let ny = 1.0 + t.y;
    let (s, c) = (t.x * PI).sin_cos();
    [v.w * ny * s, v.w * ny * c, 0.0]
}

/// bi_linear: swaps x and y.
fn bi_linear(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w * t.y, v.w * t.x, 0.0]
}

/// joukowski: the Joukowski map w = (z + z0) + P1² / (z + z0) with z0 = (−P2, 0.2), which
/// takes circles to airfoils; `inverse` takes the inverse branch of larger modulus.
fn joukowski(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [p1, p2, inverse] = v.params();
    let (z0x, z0y) = (-p2, 0.2);
    let k = p1 * p1;
    let (ox, oy) = if inverse == 0.0 {
        let (ax, ay) = (t.x + z0x, t.y + z0y);
        let d = ax * ax + ay * ay;
        // (k, 0) / (ax, ay)
        (ax + k * ax / d, ay + (-k * ay) / d)
    } else {
        let (zx, zy) = (t.x, t.y);
        // √(z²/4 − k), with the sign of the imaginary part from its argument (GLSL sign).
        let (wx, wy) = ((zx * zx - zy * zy) / 4.0 - k, (2.0 * zx * zy) / 4.0);
        let m = wx.hypot(wy);
        let sg = if wy > 0.0 {
            1.0
        } else if wy < 0.0 {
            -1.0
        } else {
            0.0
        };
        let (sx, sy) = ((0.5 * (m + wx)).sqrt(), (0.5 * (m - wx)).sqrt() * sg);
        let r1 = (zx / 2.0 + sx - z0x, zy / 2.0 + sy - z0y);
        let r2 = (zx / 2.0 - sx - z0x, zy / 2.0 - sy - z0y);
        if r1.0.hypot(r1.1) > r2.0.hypot(r2.1) {
            r1
        } else {
            r2
        }
    };
    [v.w * ox, v.w * oy, 0.0]
}
