//! JWildfire's functions of the complex plane: Brad Stefanov's detuned `cos2_bs`, `csc2_bs`,
//! `csch2_bs`, `exp2_bs`, `sech2_bs` and `sinh2_bs`, the inverse hyperbolic maps `acoth`,
//! `sqrt_acoth`, `sqrt_asech`, `sqrt_asinh` and `exp_multi`, Whittaker Courtney's
//! `inverted_julia` and `julia_outside`, DarkBeam's `plusrecip`, and `atan`, `csin`, `cpow3_wf`,
//! `csc_squared`, `bipolar2` and `bulge`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. Several use DarkBeam's complex-number class, whose operations are not C's: its
//! square root takes the sign of the imaginary part from the input (+ for 0), division by 0
//! divides by 1, and its logarithm adds 1e-20 to |z|² ([`Jc`] keeps these rules). Weights
//! multiply the output linearly, integer parameters are rounded, and random numbers are drawn in
//! the order JWildfire draws them.

use super::util::jwf_math as jm;
use std::f64::consts::{FRAC_2_PI, FRAC_PI_2, PI, TAU};

use super::*;

/// JWildfire's default centre of inverted_julia (3.14, not π).
#[allow(clippy::approx_constant)]
const INV_JULIA_CENTER: f64 = 3.14;

/// The four detuning factors x1, x2, y1, y2 of the `*2_bs` functions.
macro_rules! bs_params {
    ($n:literal, $x1:expr, $x2:expr, $y1:expr, $y2:expr) => {
        [
            p(concat!($n, "_x1"), $x1),
            p(concat!($n, "_x2"), $x2),
            p(concat!($n, "_y1"), $y1),
            p(concat!($n, "_y2"), $y2),
        ]
    };
}

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("cos2_bs", cos2_bs)
        .params(&bs_params!("cos2_bs", 1.0, 1.0, 1.0, 1.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("csc2_bs", csc2_bs)
        .params(&bs_params!("csc2_bs", 1.0, 1.0, 1.0, 1.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("csch2_bs", csch2_bs)
        .params(&bs_params!("csch2_bs", 1.0, 1.0, 1.0, 1.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("sech2_bs", sech2_bs)
        .params(&bs_params!("sech2_bs", 1.25, 0.75, 1.5, 0.75))
        .flags(flag::JWILDFIRE),
    VarDef::new("sinh2_bs", sinh2_bs)
        .params(&bs_params!("sinh2_bs", 1.0, 1.0, 1.0, 1.0))
        .flags(flag::JWILDFIRE),
    VarDef::new("exp2_bs", exp2_bs)
        .params(&[
            p("exp2_bs_x1", 1.0),
            p("exp2_bs_y1", 1.0),
            p("exp2_bs_y2", 1.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("atan", atan)
        .params(&[p_int("atan_Mode", 0.0, 0.0, 2.0), p("atan_Stretch", 1.0)])
        .flags(flag::JWILDFIRE),
    VarDef::new("acoth", acoth).flags(flag::JWILDFIRE),
    VarDef::new("sqrt_acoth", sqrt_acoth).flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("sqrt_asech", sqrt_asech).flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("sqrt_asinh", sqrt_asinh).flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("exp_multi", exp_multi)
        .params(&[
            p("exp_multi_re", 1.0),
            p("exp_multi_im", 0.0),
            p("exp_multi_re_add", 0.0),
            p("exp_multi_im_add", 0.0),
            p("exp_multi_sqr", 0.0),
            p("exp_multi_asech", 0.0),
            p("exp_multi_acosech", 0.0),
            p("exp_multi_acoth", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("csin", csin)
        .params(&[p("csin_stretch", 1.5)])
        .flags(flag::JWILDFIRE),
    VarDef::new("plusrecip", plusrecip)
        .params(&[p("plusrecip_ar", 4.0), p("plusrecip_ai", 0.0)])
        .flags(flag::JWILDFIRE),
    VarDef::new("inverted_julia", inverted_julia)
        .params(&[
            p("inverted_julia_power", 0.25),
            p("inverted_julia_y2_mult", 1.0),
            p("inverted_julia_a2x_mult", 1.0),
            p("inverted_julia_a2y_mult", 1.0),
            p("inverted_julia_a2y_add", 0.0),
            p("inverted_julia_cos_mult", 0.0),
            p("inverted_julia_y_mult", 1.0),
            p("inverted_julia_center", INV_JULIA_CENTER),
            p("inverted_julia_x2y2_add", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("julia_outside", julia_outside)
        .params(&[
            p("julia_outside_re_div", 1.0),
            p("julia_outside_im_div", 0.0),
            p_int("julia_outside_mode", 0.0, 0.0, 2.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("cpow3_wf", cpow3_wf)
        .params(&[
            p("cpow3_wf_r", 1.0),
            p("cpow3_wf_a", 0.1),
            p("cpow3_wf_divisor", 1.0),
            p("cpow3_wf_spread", 1.0),
            p("cpow3_wf_discrete_spread", 1.0),
            p("cpow3_wf_spread2", 0.0),
            p("cpow3_wf_offset2", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .prepare(cpow3_prepare),
    VarDef::new("csc_squared", csc_squared)
        .params(&[
            p("csc_squared_csc_div", 1.0),
            p("csc_squared_cos_div", 1.0),
            p("csc_squared_tan_div", 1.0),
            p("csc_squared_csc_pow", 0.5),
            p("csc_squared_pi_mult", 0.5),
            p("csc_squared_csc_add", 0.25),
            p("csc_squared_scale_y", 1.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("bipolar2", bipolar2)
        .params(&[
            p("bipolar2_shift", 0.0),
            p("bipolar2_a", 1.0),
            p("bipolar2_b", 2.0),
            p("bipolar2_c", 0.5),
            p("bipolar2_d", 1.0),
            p("bipolar2_e", 2.0),
            p("bipolar2_f1", 0.25),
            p("bipolar2_g1", 1.0),
            p("bipolar2_h", 1.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("bulge", bulge)
        .params(&[p("bulge_N", 2.0)])
        .flags(flag::JWILDFIRE),
];

/// DarkBeam's complex numbers as JWildfire computes them.
#[derive(Clone, Copy, Debug)]
struct Jc {
    re: f64,
    im: f64,
}

impl Jc {
    fn new(re: f64, im: f64) -> Jc {
        Jc { re, im }
    }
    fn flip(self) -> Jc {
        Jc::new(self.im, self.re)
    }
    fn neg(self) -> Jc {
        Jc::new(-self.re, -self.im)
    }
    fn scale(self, k: f64) -> Jc {
        Jc::new(self.re * k, self.im * k)
    }
    fn add(self, o: Jc) -> Jc {
        Jc::new(self.re + o.re, self.im + o.im)
    }
    fn mag2(self) -> f64 {
        self.re * self.re + self.im * self.im
    }
    fn mag2eps(self) -> f64 {
        self.re * self.re + self.im * self.im + 1e-20
    }
    /// 1/|z|², or 1 where |z|² < 1e-100.
    fn mag_inv(self) -> f64 {
        let m = self.mag2();
        if m < 1e-100 { 1.0 } else { 1.0 / m }
    }
    fn sqr(self) -> Jc {
        Jc::new(
            self.re * self.re - self.im * self.im,
            2.0 * self.re * self.im,
        )
    }
    fn recip(self) -> Jc {
        let mi = self.mag_inv();
        Jc::new(self.re * mi, -self.im * mi)
    }
    fn mul(self, o: Jc) -> Jc {
        if o.im == 0.0 {
            return self.scale(o.re);
        }
        Jc::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
    fn div(self, o: Jc) -> Jc {
        let r2 = self.im * o.im + self.re * o.re;
        let i2 = self.im * o.re - self.re * o.im;
        let m = o.mag_inv();
        Jc::new(r2 * m, i2 * m)
    }
    /// The principal root, the radius from Jafama's `hypot` as JWildfire's `Complex.Radius`.
    fn sqrt(self) -> Jc {
        let rad = jm::hypot(self.re, self.im);
        let sb = if self.im < 0.0 { -1.0 } else { 1.0 };
        Jc::new(
            (0.5 * (rad + self.re)).sqrt(),
            sb * (0.5 * (rad - self.re)).sqrt(),
        )
    }
    fn ln(self) -> Jc {
        // java.lang.Math.atan2 is fdlibm's.
        Jc::new(0.5 * self.mag2eps().ln(), libm::atan2(self.im, self.re))
    }
    fn exp(self) -> Jc {
        let e = self.re.exp();
        Jc::new(e * self.im.cos(), e * self.im.sin())
    }
    fn sinh(self) -> Jc {
        let e = self.re.exp();
        let er = 1.0 / e;
        let rr = 0.5 * (e - er);
        let ri = rr + er;
        Jc::new(self.im.cos() * rr, self.im.sin() * ri)
    }
    fn sin(self) -> Jc {
        self.flip().sinh().flip()
    }
    fn atanh(self) -> Jc {
        let d = Jc::new(-(self.re - 1.0), -self.im);
        Jc::new(self.re + 1.0, self.im).div(d).ln().scale(0.5)
    }
    fn asinh(self) -> Jc {
        let d = self.sqr();
        let d = Jc::new(d.re + 1.0, d.im).sqrt();
        self.add(d).ln()
    }
    fn acosh(self) -> Jc {
        let d = self.sqr();
        let d = Jc::new(d.re - 1.0, d.im).sqrt();
        self.add(d).ln()
    }
    fn acoth(self) -> Jc {
        self.recip().atanh()
    }
    fn asech(self) -> Jc {
        self.recip().asinh()
    }
    fn acosech(self) -> Jc {
        self.recip().acosh()
    }
}

/// `z`, or −z with probability ½ (one draw): both roots.
fn either_root(z: Jc, rng: &mut FastRng) -> V3 {
    if rng.f01() < 0.5 {
        [z.re, z.im, 0.0]
    } else {
        [-z.re, -z.im, 0.0]
    }
}

/// cos2_bs: cos z with the factors x1, x2, y1, y2 detuning its parts.
fn cos2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    [
        v.w * (t.x * x2).cos() * (t.y * y2).cosh(),
        -v.w * (t.x * x1).sin() * (t.y * y1).sinh(),
        0.0,
    ]
}

/// csc2_bs: csc z, detuned; nothing where the denominator vanishes.
fn csc2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    let d = (2.0 * t.y).cosh() - (2.0 * t.x).cos();
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 2.0 / d;
    [
        v.w * den * (t.x * x1).sin() * (t.y * y2).cosh(),
        -v.w * den * (t.x * x2).cos() * (t.y * y1).sinh(),
        0.0,
    ]
}

/// csch2_bs: csch z, detuned; nothing where the denominator vanishes.
fn csch2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    let d = (2.0 * t.x).cosh() - (2.0 * t.y).cos();
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 2.0 / d;
    [
        v.w * den * (t.x * x1).sinh() * (t.y * y2).cos(),
        -v.w * den * (t.x * x2).cosh() * (t.y * y1).sin(),
        0.0,
    ]
}

/// sech2_bs: sech z, detuned; nothing where the denominator vanishes.
fn sech2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    let d = (2.0 * t.y).cos() + (2.0 * t.x).cosh();
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 2.0 / d;
    [
        v.w * den * (t.y * y2).cos() * (t.x * x2).cosh(),
        -v.w * den * (t.y * y1).sin() * (t.x * x1).sinh(),
        0.0,
    ]
}

/// sinh2_bs: sinh z, detuned.
fn sinh2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, x2, y1, y2] = v.params();
    [
        v.w * (t.x * x1).sinh() * (t.y * y2).cos(),
        v.w * (t.x * x2).cosh() * (t.y * y1).sin(),
        0.0,
    ]
}

/// exp2_bs: exp z, detuned.
fn exp2_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, y1, y2] = v.params();
    let e = (t.x * x1).exp();
    [v.w * e * (t.y * y2).cos(), v.w * e * (t.y * y1).sin(), 0.0]
}

/// atan: the arctangent (scaled to ±1) of y (mode 0), x (1) or both (2).
fn atan(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [mode, stretch] = v.params();
    let norm = 1.0 / FRAC_PI_2 * v.w;
    match mode as i32 {
        0 => [v.w * t.x, norm * (stretch * t.y).atan(), 0.0],
        1 => [norm * (stretch * t.x).atan(), v.w * t.y, 0.0],
        _ => [
            norm * (stretch * t.x).atan(),
            norm * (stretch * t.y).atan(),
            0.0,
        ],
    }
}

/// acoth: the inverse hyperbolic cotangent, real and imaginary parts swapped, times 2/π.
fn acoth(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let z = Jc::new(t.x, t.y).acoth().flip().scale(v.w * FRAC_2_PI);
    [z.re, z.im, 0.0]
}

/// sqrt_acoth: acoth of √z times 2/π, either sign.
fn sqrt_acoth(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let z = Jc::new(t.x, t.y).sqrt().acoth().scale(v.w * FRAC_2_PI);
    either_root(z, rng)
}

/// sqrt_asech: asech of √z times 2/π, either sign.
fn sqrt_asech(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let z = Jc::new(t.x, t.y).sqrt().asech().scale(v.w * FRAC_2_PI);
    either_root(z, rng)
}

/// sqrt_asinh: asinh of √z times 2/π, either sign.
fn sqrt_asinh(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let z = Jc::new(t.x, t.y).sqrt().asinh().scale(v.w * FRAC_2_PI);
    either_root(z, rng)
}

/// exp_multi (Whittaker Courtney): e^z / (re + i·im), optionally squared and scaled, shifted,
/// square-rooted, then passed through the inverse hyperbolic functions whose factors are not 0;
/// times 2/π, either sign.
fn exp_multi(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [re, im, re_add, im_add, sqr, asech, acosech, acoth] = v.params();
    let mut z = Jc::new(t.x, t.y).exp().div(Jc::new(re, im));
    if sqr != 0.0 {
        z = z.sqr().scale(sqr);
    }
    z = z.add(Jc::new(re_add, im_add)).sqrt();
    if asech != 0.0 {
        z = z.asech().scale(asech);
    }
    if acosech != 0.0 {
        z = z.acosech().scale(acosech);
    }
    if acoth != 0.0 {
        z = z.acoth().scale(acoth);
    }
    either_root(z.scale(v.w * FRAC_2_PI), rng)
}

/// csin: sin of the stretched point.
fn csin(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [stretch] = v.params();
    let z = Jc::new(t.x * stretch, t.y * stretch).sin();
    [v.w * z.re, v.w * z.im, 0.0]
}

/// plusrecip (DarkBeam): z + √(z² − a), kept in the right half-plane (inside |..| < |a| it is
/// reflected through a's direction).
fn plusrecip(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [ar, ai] = v.params();
    let z = Jc::new(t.x, t.y);
    let a = Jc::new(ar, ai);
    let aa = a.mag2eps().sqrt();
    let zs = z.sqr();
    let mut k = Jc::new(zs.re - a.re, zs.im - a.im).sqrt().add(z);
    if k.sqr().mag2eps().sqrt() < aa {
        k = Jc::new(k.re, -k.im).mul(a.scale(-1.0 / aa));
    }
    if k.re < 0.0 {
        k = k.neg();
    }
    [v.w * k.re, v.w * k.im, 0.0]
}

/// inverted_julia (Whittaker Courtney): a julia root of the inverted point, with factors on
/// its parts and a cosine modulation of the radius.
fn inverted_julia(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        power,
        y2_mult,
        a2x_mult,
        a2y_mult,
        a2y_add,
        cos_mult,
        y_mult,
        center,
        x2y2_add,
    ] = v.params();
    let (x, y) = (t.x, t.y);
    let z = (x * x + y * y * y2_mult).powf(power) + x2y2_add;
    let q = (x * a2x_mult).atan2(y * a2y_mult + a2y_add) * 0.5 + PI * (2.0 * rng.f01()).trunc();
    let c = (z * cos_mult).cos();
    [
        v.w * c * (q.sin() / z / center),
        v.w * c * (q.cos() / z / center) * y_mult,
        0.0,
    ]
}

/// julia_outside (Whittaker Courtney): ((√z + 1)² / (√z − 1)²), its root (modes 0, 1: either
/// sign) divided by re_div + i·im_div; mode 1 skips the inner roots and squares, mode 2 the
/// outer root.
fn julia_outside(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [re_div, im_div, mode] = v.params();
    let inner = mode == 0.0 || mode == 2.0;
    let outer = mode == 0.0 || mode == 1.0;
    let mut z = Jc::new(t.x, t.y);
    let mut z2 = z;
    if inner {
        z = z.sqrt();
    }
    z.re += 1.0;
    if inner {
        z = z.sqr();
        z2 = z2.sqrt();
    }
    z2.re -= 1.0;
    if inner {
        z2 = z2.sqr();
    }
    z = z.div(z2);
    if outer {
        z = z.sqrt();
    }
    z = z.div(Jc::new(re_div, im_div)).scale(v.w);
    if outer {
        either_root(z, rng)
    } else {
        [z.re, z.im, 0.0]
    }
}

/// cpow3_wf's derived values: angle step, c, d, their halves, 1/(2·spread), 2π·spread.
fn cpow3_prepare(v: &mut Prepared) {
    let [r, a, divisor, spread] = v.params();
    let ang = TAU / divisor;
    let c = r * (FRAC_PI_2 * a).cos() / divisor;
    let d = r * (FRAC_PI_2 * a).sin() / divisor;
    v.p.extend_from_slice(&[ang, c, d, c / 2.0, d / 2.0, 0.5 / spread, TAU * spread]);
}

/// cpow3_wf: a complex power z^(c + i·d) on a random branch (discrete or not), with JWildfire's
/// angle (the product c·θ·(d/2)·ln r²·step·(random spread), as it computes it).
fn cpow3_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, spread, discrete, spread2, offset2] = v.params();
    let [ang, c, d, half_c, half_d, inv_spread, full_spread] = v.derived();
    let mut ai = t.atan_yx;
    let mut n = rng.f01() * spread;
    if discrete >= 1.0 {
        n = n.trunc();
    }
    if ai < 0.0 {
        n += 1.0;
    }
    ai += TAU * n;
    if (ai * inv_spread).cos() < rng.f01() * 2.0 - 1.0 {
        ai -= full_spread;
    }
    let lnr2 = t.sumsq.ln();
    let ri = v.w * (half_c * lnr2 - d * ai).exp();
    let ang2 = c * ai * half_d * lnr2 * ang * (rng.f01() * spread2 + offset2);
    [ri * ang2.cos(), ri * ang2.sin(), 0.0]
}

/// csc_squared: both coordinates scaled by (csc² + π·pi_mult)^csc_pow + csc_add, where
/// csc = csc_div / cos(x/cos_div) / tan(x/tan_div).
fn csc_squared(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        csc_div,
        cos_div,
        tan_div,
        csc_pow,
        pi_mult,
        csc_add,
        scale_y,
    ] = v.params();
    let csc = csc_div / (t.x / cos_div).cos() / (t.x / tan_div).tan();
    let fx = (csc * csc + PI * pi_mult).powf(csc_pow) + csc_add;
    [v.w * t.x * fx, v.w * t.y * fx * scale_y, 0.0]
}

/// bipolar2: bipolar coordinates with every constant exposed; nothing where the logarithm's
/// argument is not positive.
fn bipolar2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [shift, a, b, c, d, e, f1, g1, h] = v.params();
    let x2y2 = (t.x * t.x + t.y * t.y) * g1;
    let tt = x2y2 + a;
    let x2 = b * t.x;
    let mut y = c * (e * t.y).atan2(x2y2 - d) - FRAC_PI_2 * shift;
    if y > FRAC_PI_2 {
        y = -FRAC_PI_2 + (y + FRAC_PI_2) % PI;
    } else if y < -FRAC_PI_2 {
        y = FRAC_PI_2 - (FRAC_PI_2 - y) % PI;
    }
    let (f, g) = (tt + x2, tt - x2);
    if g == 0.0 || f / g <= 0.0 {
        return [0.0; 3];
    }
    [
        v.w * f1 * FRAC_2_PI * ((tt + x2) / (tt - x2)).ln(),
        v.w * FRAC_2_PI * y * h,
        0.0,
    ]
}

/// bulge: the radius raised to the power N, direction kept.
fn bulge(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [n] = v.params();
    let r = (t.x * t.x + t.y * t.y).sqrt();
    let rn = r.powf(n);
    [v.w * (rn * t.x / r), v.w * (rn * t.y / r), 0.0]
}
