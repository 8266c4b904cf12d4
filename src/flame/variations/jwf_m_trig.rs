//! Whittaker Courtney's `pre_recip` and `post_trig`: sums of complex functions of the point
//! (reciprocal, quotient, roots, logarithm, exponential, the inverse hyperbolic and inverse
//! circular functions, the circular and hyperbolic functions), each with its own power. The
//! first group (reciprocal … logarithm) runs in turn, each on the result of the one before;
//! the second group sums, each on that result; where the second group is all zero, the first
//! group's result is the output.
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew, with DarkBeam's complex
//! arithmetic ([`DbComplex`]: its division by 0 divides by 1, its logarithm adds 1e-20 to
//! |z|²). Random numbers are drawn in the order JWildfire draws them.

use std::f64::consts::{FRAC_2_PI, FRAC_PI_2};

use super::jwf_a_complex::DbComplex;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("pre_recip", pre_recip)
        .params(&[
            p("pre_recip_reciprocalpow", 1.0),
            p("pre_recip_dividepow", 0.0),
            p("pre_recip_sqrtpow", 0.0),
            p("pre_recip_asinhpow", 0.0),
            p("pre_recip_acoshpow", 0.0),
            p("pre_recip_atanhpow", 0.0),
            p("pre_recip_asechpow", 0.0),
            p("pre_recip_acosechpow", 0.0),
            p("pre_recip_acothpow", 0.0),
            p("pre_recip_logpow", 0.0),
            p("pre_recip_exppow", 0.0),
            p("pre_recip_zx_mult", 1.0),
            p("pre_recip_zy_mult", 1.0),
            p("pre_recip_zx_add", 0.0),
            p("pre_recip_zy_add", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::PRE_ONLY | flag::RANDOM),
    VarDef::new("post_trig", post_trig)
        .params(&[
            p("post_trig_reciprocalpow", 1.0),
            p("post_trig_log_dividepow", 0.0),
            p("post_trig_sqrtpow", 0.0),
            p("post_trig_exppow", 0.0),
            p("post_trig_logpow", 0.0),
            p("post_trig_asinhpow", 0.0),
            p("post_trig_acoshpow", 0.0),
            p("post_trig_atanhpow", 0.0),
            p("post_trig_asinpow", 0.0),
            p("post_trig_acospow", 0.0),
            p("post_trig_atanpow", 0.0),
            p("post_trig_sinpow", 0.0),
            p("post_trig_cospow", 0.0),
            p("post_trig_tanpow", 0.0),
            p("post_trig_sinhpow", 0.0),
            p("post_trig_coshpow", 0.0),
            p("post_trig_tanhpow", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::POST_ONLY | flag::RANDOM),
];

/// The complex functions DarkBeam's class adds to [`DbComplex`]'s, as it computes them.
trait DbMore: Sized {
    fn exp(self) -> Self;
    fn sinh(self) -> Self;
    fn cosh(self) -> Self;
    fn sin(self) -> Self;
    fn cos(self) -> Self;
    fn asinh(self) -> Self;
    fn asin(self) -> Self;
    fn acos(self) -> Self;
    fn atan(self) -> Self;
}

impl DbMore for DbComplex {
    fn exp(self) -> DbComplex {
        let e = self.re.exp();
        DbComplex::new(e * self.im.cos(), e * self.im.sin())
    }
    fn sinh(self) -> DbComplex {
        let e = self.re.exp();
        let rr = 0.5 * (e - 1.0 / e);
        let ri = rr + 1.0 / e;
        DbComplex::new(self.im.cos() * rr, self.im.sin() * ri)
    }
    fn cosh(self) -> DbComplex {
        let e = self.re.exp();
        let rr = 0.5 * (e - 1.0 / e);
        let ri = rr + 1.0 / e;
        DbComplex::new(self.im.cos() * ri, self.im.sin() * rr)
    }
    fn sin(self) -> DbComplex {
        self.flip().sinh().flip()
    }
    fn cos(self) -> DbComplex {
        self.flip().cosh().flip()
    }
    /// asinh z = ln(z + √(z² + 1)).
    fn asinh(self) -> DbComplex {
        let s = self.sqr();
        self.add(DbComplex::new(s.re + 1.0, s.im).sqrt()).ln()
    }
    fn asin(self) -> DbComplex {
        self.flip().asinh().flip()
    }
    /// π/2 − asin z.
    fn acos(self) -> DbComplex {
        let a = self.asin();
        DbComplex::new(FRAC_PI_2 - a.re, -a.im)
    }
    fn atan(self) -> DbComplex {
        self.flip().atanh().flip()
    }
}

/// `z`, or −z with probability ½ (one draw).
fn either_sign(z: DbComplex, rng: &mut FastRng) -> DbComplex {
    if rng.f01() < 0.5 { z } else { z.scale(-1.0) }
}

/// The sum of asinh, acosh (on a random branch) and atanh of `z0`, scaled by `k`, with the
/// powers `pw` (a function of power 0 is skipped, drawing nothing).
fn inverse_hyperbolic(z0: DbComplex, k: f64, pw: [f64; 3], rng: &mut FastRng) -> (f64, f64) {
    let (mut xx, mut yy) = (0.0, 0.0);
    let mut add = |pw: f64, z: DbComplex| {
        xx += pw * z.re;
        yy += pw * z.im;
    };
    if pw[0] != 0.0 {
        add(pw[0], z0.asinh().scale(k));
    }
    if pw[1] != 0.0 {
        add(pw[1], either_sign(z0.acosh().scale(k), rng));
    }
    if pw[2] != 0.0 {
        add(pw[2], z0.atanh().scale(k));
    }
    (xx, yy)
}

/// pre_recip: the affine point through the reciprocal, quotient and root group (each on the
/// point scaled by (zx_mult, zy_mult) and shifted by (zx_add, zy_add)), then the sum of the
/// inverse hyperbolic group, the logarithm and the exponential (scaled by 2/π).
fn pre_recip(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        recip,
        divide,
        sqrt,
        asinh,
        acosh,
        atanh,
        asech,
        acosech,
        acoth,
        log,
        exp,
        mx,
        my,
        ax,
        ay,
    ] = v.params();
    let w = v.w;
    let arg = |x: f64, y: f64| DbComplex::new(x * mx + ax, y * my + ay);
    let (mut xr, mut yr) = (t.x, t.y);
    if recip != 0.0 {
        let z = arg(t.x, t.y).recip().scale(w);
        (xr, yr) = (recip * z.re, recip * z.im);
    }
    if divide != 0.0 {
        let z2 = DbComplex::new(xr - 1.0, yr);
        let z = arg(xr, yr);
        let z = DbComplex::new(z.re + 1.0, z.im)
            .div(z2)
            .scale(w * FRAC_2_PI);
        (xr, yr) = (divide * z.re, divide * z.im);
    }
    if sqrt != 0.0 {
        let z = either_sign(arg(xr, yr).sqrt().scale(w), rng);
        (xr, yr) = (sqrt * z.re, sqrt * z.im);
    }
    let k = w * FRAC_2_PI;
    let z0 = arg(xr, yr);
    let (mut xx, mut yy) = inverse_hyperbolic(z0, k, [asinh, acosh, atanh], rng);
    let mut add = |pw: f64, z: DbComplex| {
        xx += pw * z.re;
        yy += pw * z.im;
    };
    if asech != 0.0 {
        add(asech, z0.recip().asinh().scale(k));
    }
    if acosech != 0.0 {
        add(acosech, either_sign(z0.recip().acosh().scale(k), rng));
    }
    if acoth != 0.0 {
        add(acoth, z0.recip().atanh().scale(k));
    }
    if log != 0.0 {
        add(log, z0.ln().scale(k));
    }
    if exp != 0.0 {
        add(exp, z0.exp().scale(k));
    }
    if asinh + acosh + atanh + asech + acosech + acoth + log + exp == 0.0 {
        [xr, yr, t.z]
    } else {
        [xx, yy, t.z]
    }
}

/// post_trig: the xform's sum through the reciprocal, log-quotient, root, exponential and
/// logarithm group, then the sum of the inverse hyperbolic and inverse circular functions
/// (scaled by 2/π) and the circular and hyperbolic ones.
fn post_trig(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        recip,
        divide,
        sqrt,
        exp,
        log,
        asinh,
        acosh,
        atanh,
        asin,
        acos,
        atan,
    ] = v.params();
    let [sin, cos, tan, sinh, cosh, tanh] = v.p[11..17].try_into().expect("17 parameters");
    let w = v.w;
    let (mut xr, mut yr) = (t.x, t.y);
    let set = |pw: f64, z: DbComplex| (pw * z.re, pw * z.im);
    if recip != 0.0 {
        (xr, yr) = set(recip, DbComplex::new(xr, yr).recip().scale(w));
    }
    if divide != 0.0 {
        let z = DbComplex::new(xr + 1.0, yr).div(DbComplex::new(xr - 1.0, yr));
        (xr, yr) = set(divide, z.ln().scale(w * FRAC_2_PI));
    }
    if sqrt != 0.0 {
        let z = either_sign(DbComplex::new(xr, yr).sqrt().scale(w), rng);
        (xr, yr) = set(sqrt, z);
    }
    if exp != 0.0 {
        (xr, yr) = set(exp, DbComplex::new(xr, yr).exp().scale(w));
    }
    if log != 0.0 {
        (xr, yr) = set(log, DbComplex::new(xr, yr).ln().scale(w));
    }
    let z0 = DbComplex::new(xr, yr);
    let k = w * FRAC_2_PI;
    let (mut xx, mut yy) = inverse_hyperbolic(z0, k, [asinh, acosh, atanh], rng);
    let mut add = |pw: f64, z: DbComplex| {
        xx += pw * z.re;
        yy += pw * z.im;
    };
    if asin != 0.0 {
        add(asin, z0.asin().scale(k));
    }
    if acos != 0.0 {
        add(acos, z0.acos().scale(k));
    }
    if atan != 0.0 {
        add(atan, z0.atan().scale(k));
    }
    if sin != 0.0 {
        add(sin, z0.sin().scale(w));
    }
    if cos != 0.0 {
        add(cos, z0.cos().scale(w));
    }
    if tan != 0.0 {
        add(tan, z0.sin().div(z0.cos()).scale(w));
    }
    if sinh != 0.0 {
        add(sinh, z0.sinh().scale(w));
    }
    if cosh != 0.0 {
        add(cosh, z0.cosh().scale(w));
    }
    if tanh != 0.0 {
        add(tanh, z0.sinh().div(z0.cosh()).scale(w));
    }
    let second = asinh + acosh + atanh + sin + cos + tan + sinh + cosh + tanh + asin + acos + atan;
    if second == 0.0 {
        [xr, yr, t.z]
    } else {
        [xx, yy, t.z]
    }
}
