//! JWildfire's maps and point sets of the plane, from the end of its alphabet: Jacobi's
//! elliptic integrals after dark-beam (`jac_elk`, the incomplete integral of the first kind by
//! Carlson's R_F; `jac_asn`, its complex form by Landen's transformation), Brad Stefanov's
//! crossing bands `intersection`, the GlynnSim of a spirograph `glynnspiro` and
//! `juliascopePlus`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: weights multiply the output linearly unless
//! said otherwise, and random numbers are drawn in the order JWildfire draws them.

use super::util::{signum_java, sqr};
use std::f64::consts::PI;

use super::jwf_a_shapes::glynn_common;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("jac_elk", jac_elk)
        .params(&[p("jac_elk_k", 0.5)])
        .flags(flag::JWILDFIRE),
    VarDef::new("jac_asn", jac_asn)
        .params(&[
            p("jac_asn_kr", 0.5),
            p("jac_asn_ki", 0.0),
            p_int("jac_asn_type", 1.0, NEG_INF, INF),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("intersection", intersection)
        .params(&[
            p("intersection_xwidth", 5.0),
            p("intersection_xtilesize", 0.5),
            p("intersection_xmod1", 0.3),
            p("intersection_xmod2", 1.0),
            p("intersection_xheight", 0.5),
            p("intersection_yheight", 5.0),
            p("intersection_ytilesize", 0.5),
            p("intersection_ymod1", 0.3),
            p("intersection_ymod2", 1.0),
            p("intersection_ywidth", 0.5),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("glynnspiro", glynnspiro)
        .params(&[
            p("glynnspiro_radius", 1.0),
            p("glynnspiro_radius1", 0.5),
            p("glynnspiro_thickness", 1.0),
            p("glynnspiro_phi1", 0.0),
            p("glynnspiro_a", 1.0),
            p("glynnspiro_b", -0.3),
            p("glynnspiro_c", 0.4),
            p("glynnspiro_time", 1000.0),
            p_range("glynnspiro_mode", 0.0, 0.0, 4.0),
            p("glynnspiro_width", 0.0),
            p("glynnspiro_scale", 0.71),
            p("glynnspiro_pow", 1.5),
            p_range("glynnspiro_contrast", 0.5, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("juliascopePlus", juliascope_plus)
        .params(&[
            // JWildfire draws this default at random; the value of its test vectors.
            p_int("juliascopePlus_power", -5.0, NEG_INF, INF),
            p("juliascopePlus_dist", 1.0),
            p("juliascopePlus_cx", 0.0),
            p("juliascopePlus_cy", 0.0),
            p("juliascopePlus_mixPowerSign", 0.0),
            p_int("juliascopePlus_colorMode", 0.0, 0.0, 5.0),
            p("juliascopePlus_colorSpeed", 1.0),
            p_int("juliascopePlus_thetaSignMode", 0.0, 0.0, 3.0),
            p("juliascopePlus_angularOffset", 0.0),
            p("juliascopePlus_swirlFactor", 0.0),
            p("juliascopePlus_fixedBranch", -1.0),
            p("juliascopePlus_radialOffset", 0.0),
            p("juliascopePlus_altPowerScale", 1.0),
            p("juliascopePlus_altPowerRotate", 0.0),
            p_int("juliascopePlus_rndTermMode", 0.0, 0.0, 3.0),
            p_int("juliascopePlus_mandelbrotLike", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR),
];

/// dark-beam's guard against a zero divisor: values within 1e-20 of 0 become ±1e-20.
fn nonz(x: f64) -> f64 {
    const E: f64 = 1e-20;
    if x.abs() <= E { E * signum_java(x) } else { x }
}

/// Carlson's symmetric elliptic integral R_F(x, y, z) by its duplication theorem (stopping at
/// a relative spread of 1e-5 or after 25 steps) and the series of DLMF 19.36.1.
fn carlson_rf(mut x: f64, mut y: f64, mut z: f64) -> f64 {
    let (mut a, mut dx, mut dy, mut dz);
    let mut steps = 0;
    loop {
        let lambda = (x * y).sqrt() + (y * z).sqrt() + (z * x).sqrt();
        x = (x + lambda) / 4.0;
        y = (y + lambda) / 4.0;
        z = (z + lambda) / 4.0;
        a = (x + y + z) / 3.0;
        dx = 1.0 - x / a;
        dy = 1.0 - y / a;
        dz = 1.0 - z / a;
        steps += 1;
        if steps >= 25 || dx.abs().max(dy.abs()).max(dz.abs()) <= 1e-5 {
            break;
        }
    }
    let e2 = dx * dy + dy * dz + dz * dx;
    let e3 = dy * dx * dz;
    let s = 1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0
        - 3.0 / 44.0 * e2 * e3
        - 5.0 / 208.0 * (e2 * e2 * e2)
        + 3.0 / 104.0 * (e3 * e3)
        + (e2 * e2) / 16.0 * e3;
    s * (1.0 / a.sqrt())
}

/// jac_elk: the incomplete elliptic integral of the first kind F(φ + iψ | k) of the point as
/// a complex amplitude, by its real and imaginary parts (dark-beam's expansion).
fn jac_elk(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.params();
    let (phi, psi) = (t.x, t.y);
    let cotphi = phi.cos() / nonz(phi.sin());
    let cotphi2 = cotphi * cotphi;
    let b = -(cotphi2 + k * sqr(psi.sinh() / (1e-20 + phi.sin())) - 1.0 + k) / 2.0;
    let c = -(1.0 - k) * cotphi2;
    let c = (b * b - c).abs().sqrt();
    let x1 = (-b + c).max(-b - c);
    let mu = signum_java(psi) * ((x1 / nonz(cotphi2) - 1.0) / nonz(k)).abs().sqrt();
    let lambda = signum_java(phi) * x1.abs().sqrt();
    let sin_a = signum_java(lambda) / (lambda * lambda + 1.0).sqrt();
    let cos_a = lambda * sin_a;
    let e_phi = sin_a * carlson_rf(cos_a * cos_a, 1.0 - k * sin_a * sin_a, 1.0);
    let cos_a = 1.0 / (mu * mu + 1.0).sqrt();
    let sin_a = mu * cos_a;
    let e_psi = sin_a * carlson_rf(cos_a * cos_a, 1.0 - (1.0 - k) * sin_a * sin_a, 1.0);
    [v.w * e_phi, v.w * e_psi, 0.0]
}

/// A complex number with the plain textbook formulas of the small complex class dark-beam's
/// variations use in JWildfire (square root and logarithm through modulus and argument).
#[derive(Clone, Copy, Debug)]
struct Hc(f64, f64);

impl Hc {
    fn add(self, o: Hc) -> Hc {
        Hc(self.0 + o.0, self.1 + o.1)
    }
    fn sub(self, o: Hc) -> Hc {
        Hc(self.0 - o.0, self.1 - o.1)
    }
    fn mul(self, o: Hc) -> Hc {
        Hc(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    fn scale(self, k: f64) -> Hc {
        Hc(self.0 * k, self.1 * k)
    }
    fn mag(self) -> f64 {
        (self.0 * self.0 + self.1 * self.1).sqrt()
    }
    fn arg(self) -> f64 {
        self.1.atan2(self.0)
    }
    /// self / o, or `None` where |o| < 1e-12 (the class refuses).
    fn div(self, o: Hc) -> Option<Hc> {
        let r = o.mag();
        if r.abs() < 1e-12 {
            return None;
        }
        let d = r * r;
        Some(Hc(
            (self.0 * o.0 + self.1 * o.1) / d,
            (self.1 * o.0 - self.0 * o.1) / d,
        ))
    }
    fn sqrt(self) -> Hc {
        let r = self.mag().sqrt();
        let phi = self.arg() / 2.0;
        Hc(r * phi.cos(), r * phi.sin())
    }
    fn ln(self) -> Hc {
        Hc(self.mag().ln() / std::f64::consts::E.ln(), self.arg())
    }
    fn sin(self) -> Hc {
        Hc(self.0.sin() * self.1.cosh(), self.0.cos() * self.1.sinh())
    }
    fn tan(self) -> Hc {
        let d = (2.0 * self.0).cos() + (2.0 * self.1).cosh();
        Hc((2.0 * self.0).sin() / d, (2.0 * self.1).sinh() / d)
    }
    /// i·z.
    fn times_i(self) -> Hc {
        Hc(-self.1, self.0)
    }
    /// asin z = −i·ln(√(1 − z²) + i·z).
    fn asin(self) -> Hc {
        let s = Hc(1.0, 0.0).sub(self.mul(self)).sqrt().add(self.times_i());
        s.ln().times_i().scale(-1.0)
    }
    /// acos z = −i·ln(z + √(z² − 1)).
    fn acos(self) -> Hc {
        let s = self.add(self.mul(self).sub(Hc(1.0, 0.0)).sqrt());
        s.ln().times_i().scale(-1.0)
    }
    /// asinh z = ln(z + √(1 + z²)).
    fn asinh(self) -> Hc {
        self.add(Hc(1.0, 0.0).add(self.mul(self)).sqrt()).ln()
    }
}

/// jac_asn: dark-beam's Jacobi amplitude-like map: a first half-angle step chosen by `type`
/// (0–3; 4–7 swap the modulus and the amplitude), then Landen's descending transformation
/// (at most 10 steps) and the integral ln tan(φ/2 + π/4) scaled by the accumulated factor.
fn jac_asn(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [kr, ki, kind] = v.params();
    let one = Hc(1.0, 0.0);
    let mut phi = Hc(t.x, t.y);
    let mut modul = Hc(kr, ki);
    let kind = kind as i64;
    phi = match kind {
        0 | 4 => phi.add(modul.mul(phi.sin()).asin()).scale(0.5),
        1 | 5 => phi.asin().add(modul.mul(phi).asin()).scale(0.5),
        2 | 6 => phi
            .acos()
            .add(modul.mul(one.sub(phi.mul(phi)).sqrt()).asin())
            .scale(0.5),
        3 | 7 => {
            let p = phi.asinh().times_i();
            p.add(modul.mul(p.sin()).asin()).scale(0.5)
        }
        _ => phi,
    };
    if kind > 3 {
        std::mem::swap(&mut phi, &mut modul);
    }
    let mut geo = Hc(v.w, 0.0);
    let mut geo1 = Hc(0.0, 0.0);
    for jj in 0..10 {
        let d = one.sub(modul);
        if d.0 * d.0 + d.1 * d.1 < 1e-300 {
            break;
        }
        if jj > 0 {
            phi = phi.add(modul.mul(phi.sin()).asin()).scale(0.5);
        }
        if let Some(g) = Hc(2.0, 0.0).div(one.add(modul)) {
            geo1 = g;
        }
        geo = geo.mul(geo1);
        modul = geo1.mul(modul.sqrt());
    }
    let q = Hc(std::f64::consts::FRAC_PI_4, 0.0);
    let out = geo.mul(phi.scale(0.5).add(q).tan().ln());
    [out.0, out.1, 0.0]
}

/// One band of [`intersection`]: tiles along `a` (spread by `width`·ln u, rounded), the
/// other coordinate `b` folded into bands of height `mod1`·`mod2`.
fn crossing_band(a: f64, b: f64, q: [f64; 5], rng: &mut FastRng) -> (f64, f64) {
    let [width, tilesize, mod1, mod2, height] = q;
    let r1 = mod2 * mod1;
    let w = if rng.f01() < 0.5 { width } else { -width };
    let oa = tilesize * (a + (w * rng.f01().ln() + 0.5).floor());
    let ob = if b > mod1 {
        height * (-mod1 + (b + mod1) % r1)
    } else if b < -mod1 {
        height * (mod1 - (mod1 - b) % r1)
    } else {
        height * b
    };
    (oa, ob)
}

/// intersection: horizontal or vertical bands of tiles, chosen at random; the weight is not
/// applied (JWildfire's formula ignores it).
fn intersection(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [xw, xts, xm1, xm2, xh, yh, yts, ym1, ym2, yw] = v.params();
    if rng.f01() < 0.5 {
        let (x, y) = crossing_band(t.x, t.y, [-xw, xts, xm1, xm2, xh], rng);
        [x, y, 0.0]
    } else {
        let (y, x) = crossing_band(t.y, t.x, [-yh, yts, ym1, ym2, yw], rng);
        [x, y, 0.0]
    }
}

/// glynnspiro: GlynnSim whose inner disc holds a spirograph (the epitrochoid of a, b, c at a
/// uniform t in [0, time], scaled by `scale` and widened by `width`).
fn glynnspiro(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        radius,
        radius1,
        thickness,
        phi1,
        a,
        b,
        c,
        time,
        _,
        width,
        scale,
        pw,
        contrast,
    ] = v.params();
    let s = rng.f01() * time;
    let k = (a + b) / b * s;
    let px = (a + b) * s.cos() - c * k.cos();
    let py = (a + b) * s.sin() - c * k.sin();
    let y = rng.f01() - 0.5;
    let figure = (
        (px * scale + width * y) * radius1,
        (py * scale + width * y) * radius1,
    );
    let q = [radius, radius1, thickness, phi1, pw, contrast];
    glynn_common(v, t, rng, q, figure)
}

/// A sign drawn as JWildfire draws it: + when `random(2)` gives 0.
fn coin_sign(rng: &mut FastRng) -> f64 {
    if rng.f01() < 0.5 { 1.0 } else { -1.0 }
}

/// juliascopePlus: juliascope with every sign a choice: the power's sign mixed at random
/// (the flipped branch scaled and turned by altPowerScale, altPowerRotate), the branch fixed or
/// drawn, the signs of the angle and of the branch term by mode, a swirl ln(1 + r), angular
/// and radial offsets, a constant (cx, cy) or the point itself added; colour by angle,
/// radius, input angle, branch or sign (`colorMode` 1–5).
fn juliascope_plus(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        power,
        dist,
        cx,
        cy,
        mix,
        cmode,
        cspeed,
        tsm,
        ang_off,
        swirl,
        fixed,
        rad_off,
        alt_scale,
        alt_rot,
        rtm,
        mandel,
    ] = v.params();
    let abs_branches = if power == 0.0 {
        2.0
    } else {
        power.abs().max(1.0)
    };
    let sign = if power == 0.0 { 1.0 } else { power.signum() };
    let (add_x, add_y) = if mandel >= 1.0 { (t.x, t.y) } else { (cx, cy) };
    let (mut eff, mut alt) = (power, false);
    if power != 0.0 && mix >= 0.5 {
        if rng.f01() < 0.5 {
            eff = abs_branches * sign;
        } else {
            eff = -abs_branches * sign;
            alt = true;
        }
    }
    if eff == 0.0 {
        return [v.w * (t.x + add_x), v.w * (t.y + add_y), 0.0];
    }
    let c_power = dist / eff * 0.5;
    let fixed = (fixed + 0.5).floor();
    let rnd = if fixed >= 0.0 && fixed < abs_branches {
        fixed
    } else {
        ((rng.f01() * abs_branches) as i64 as f64).min(abs_branches - 1.0)
    };
    let odd = rnd as i64 & 1 != 0;
    let theta = t.y.atan2(t.x);
    let theta_sign = match tsm as i64 {
        0 if odd => -1.0,
        2 => -1.0,
        3 => coin_sign(rng),
        _ => 1.0,
    };
    let rnd_sign = match rtm as i64 {
        1 => -1.0,
        2 if odd => -1.0,
        3 => coin_sign(rng),
        _ => 1.0,
    };
    let mut a = (rnd_sign * 2.0 * PI * rnd + theta_sign * theta) / eff;
    if swirl != 0.0 {
        let r0 = (t.x * t.x + t.y * t.y).sqrt();
        if r0 > 0.00001 {
            a += swirl * (1.0 + r0).ln();
        }
    }
    a += ang_off;
    let mag = (t.x * t.x + t.y * t.y).max(0.0).powf(c_power) + rad_off;
    let (mut dx, mut dy) = (mag * a.cos(), mag * a.sin());
    if alt {
        dx *= alt_scale;
        dy *= alt_scale;
        if alt_rot != 0.0 {
            let (s, c) = alt_rot.sin_cos();
            (dx, dy) = (dx * c - dy * s, dx * s + dy * c);
        }
    }
    if cmode != 0.0 {
        let value = match cmode as i64 {
            1 => a / (2.0 * PI),
            2 => (1.00001 + mag.max(0.0)).ln(),
            3 => (theta + PI) / (2.0 * PI),
            4 => rnd / abs_branches,
            _ if mix >= 0.5 && power != 0.0 => {
                if eff < 0.0 {
                    0.75
                } else {
                    0.25
                }
            }
            _ => {
                if power >= 0.0 {
                    0.25
                } else {
                    0.75
                }
            }
        };
        let c = value * cspeed;
        acc.color = c - c.trunc();
    }
    [v.w * (dx + add_x), v.w * (dy + add_y), 0.0]
}
