//! Functions of the complex plane from Fractorium's catalogue: inverse hyperbolic functions,
//! exponentials and powers, logarithms, the error and Γ functions, Jacobi's elliptic
//! functions, Fibonacci's closed form, rational and Möbius maps.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{E, FRAC_1_PI, FRAC_2_PI, PI, TAU};

use super::util::{Cplx, crand, erf, jacobi_elliptic, ln_gamma, sqr, zeps};
use super::*;
use crate::flame::fastmath::{self as fm, FastTrig};

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("arcsech", arcsech).prepare(prep_arcsech),
    super::inlined!("arcsech2", arcsech2).prepare(prep_arcsech2),
    super::inlined!("arcsinh", arcsinh).prepare(prep_arcsinh),
    super::inlined!("arctanh", arctanh).prepare(prep_arcsech),
    super::inlined!("cpow2", cpow2)
        .params(&[
            p("cpow2_r", 1.0),
            p("cpow2_a", 0.0),
            p("cpow2_divisor", 1.0),
            p("cpow2_spread", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_cpow2),
    super::inlined_drawn!("cpow3", cpow3, 4)
        .params(&[
            p("cpow3_r", 1.0),
            p_nonzero("cpow3_d", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p_nonzero("cpow3_divisor", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p("cpow3_spread", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_cpow3),
    super::inlined!("dragonfire", dragonfire)
        .params(&[
            p("dragonfire_c1", 0.5),
            p("dragonfire_c2", 0.25),
            p_range("dragonfire_fuzzyMode", 0.0, 0.0, 7.0),
            p("dragonfire_fuzzyRadius", 1.0),
            p_range("dragonfire_fuzzyInterpolationMode", 0.0, 0.0, 6.0),
            p("dragonfire_fuzzyInterpolationPosition", 1.0),
            p("dragonfire_logScalarFuzzy", TAU),
            p("dragonfire_adjustedFuzzyScalar", 0.5),
        ])
        .prepare(dragonfire_prepare),
    super::inlined!("erf", erf_var),
    super::inlined!("excinis", excinis)
        .params(&[
            p("excinis_lengthscalar", 1.0),
            p_range("excinis_radiusFunc", 0.0, 0.0, 5.0),
            p("excinis_eps", 0.1),
        ])
        .needs(need::SUMSQ | need::SQRT),
    super::inlined!("exp2", exp2),
    super::inlined!("expo", expo)
        .params(&[p("expo_real", -1.0), p("expo_imaginary", 1.0)])
        .prepare(expo_prepare),
    super::inlined!("fibonacci", fibonacci).prepare(fib_prepare),
    super::inlined!("fibonacci2", fibonacci2)
        .params(&[p("fibonacci2_sc", 1.0), p("fibonacci2_sc2", 1.0)])
        .prepare(fib_prepare),
    super::inlined!("gamma", gamma).needs(need::SQRT | need::ATAN_YX),
    super::inlined!("jac_cn", jac_cn).params(&[p_range("jac_cn_k", 0.5, -1.0, 1.0)]),
    super::inlined!("jac_dn", jac_dn).params(&[p_range("jac_dn_k", 0.5, -1.0, 1.0)]),
    super::inlined!("jac_sn", jac_sn).params(&[p_range("jac_sn_k", 0.5, -1.0, 1.0)]),
    super::inlined!("lens", lens),
    super::inlined!("log_db", log_db)
        .params(&[p("log_db_base", 1.0), p("log_db_fix_period", 1.0)])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_log_db),
    super::inlined_drawn!("MobiusN", mobius_n, 1)
        .params(&[
            p("MobiusNRe_A", 1.0),
            p("MobiusNIm_A", 0.0),
            p("MobiusNRe_B", 0.0),
            p("MobiusNIm_B", 0.0),
            p("MobiusNRe_C", 0.0),
            p("MobiusNIm_C", 0.0),
            p("MobiusNRe_D", 1.0),
            p("MobiusNIm_D", 0.0),
            p("MobiusN_Power", 2.0),
            p("MobiusN_Dist", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_mobius_n),
    super::inlined!("murl", murl)
        .params(&[p("murl_c", 0.0), p_range("murl_power", 2.0, 2.0, INF)])
        .needs(need::SUMSQ | need::ATAN_YX)
        .prepare(prep_murl),
    super::inlined!("murl2", murl2)
        .params(&[p_range("murl2_c", 0.0, -1.0, 1.0), p("murl2_power", 1.0)])
        .needs(need::SUMSQ | need::ATAN_YX)
        .prepare(prep_murl2),
    super::inlined!("rational3", rational3).params(&[
        p("rational3_t3", 1.0),
        p("rational3_t2", 0.0),
        p("rational3_t1", 0.0),
        p("rational3_tc", 1.0),
        p("rational3_b3", 0.0),
        p("rational3_b2", 1.0),
        p("rational3_b1", 0.0),
        p("rational3_bc", 1.0),
    ]),
    super::inlined!("xerf", xerf)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
];

/// Derived value: w/π.
fn prep_arcsech(v: &mut Prepared) {
    let k = v.w * FRAC_1_PI;
    v.p.push(k);
}

/// Derived value: 2w/π.
fn prep_arcsech2(v: &mut Prepared) {
    let k = v.w * FRAC_1_PI * 2.0;
    v.p.push(k);
}

/// Derived value: 2w/π.
fn prep_arcsinh(v: &mut Prepared) {
    let k = v.w * FRAC_2_PI;
    v.p.push(k);
}

/// arcsech(1/z) = ln(1/z + √(1/z + 1)·√(1/z − 1)) scaled by w/π: the plane folds into a
/// horizontal strip.
fn arcsech_raw(t: &VarIn) -> Cplx {
    let z = Cplx::new(t.x, t.y).recip();
    let root = z.add_re(1.0).sqrt() * z.add_re(-1.0).sqrt();
    (z + root).ln()
}

/// Inverse hyperbolic secant, scaled by w/π: the plane maps into the strip |y| ≤ w.
#[inline(always)]
fn arcsech(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let r = arcsech_raw(t).scale(k);
    [r.re, r.im, 0.0]
}

/// Inverse hyperbolic secant scaled by 2w/π, with the two halves of the strip swapped and
/// mirrored so that they tile around the real axis.
#[inline(always)]
fn arcsech2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let r = arcsech_raw(t).scale(k);
    if r.im < 0.0 {
        [r.re, r.im + 1.0, 0.0]
    } else {
        [-r.re, r.im - 1.0, 0.0]
    }
}

/// Inverse hyperbolic sine ln(z + √(z² + 1)), scaled by 2w/π: a strip again.
#[inline(always)]
fn arcsinh(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let z = Cplx::new(t.x, t.y);
    let r = (z + (z * z).add_re(1.0).sqrt()).ln().scale(k);
    [r.re, r.im, 0.0]
}

/// Twice the inverse hyperbolic tangent, ln((1 + z)/(1 − z)), scaled by w/π.
#[inline(always)]
fn arctanh(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let z = Cplx::new(t.x, t.y);
    let r = (z.add_re(1.0) / (-z).add_re(1.0)).ln().scale(k);
    [r.re, r.im, 0.0]
}

fn prep_cpow2(v: &mut Prepared) {
    let [r, a, div, spread] = v.params();
    let spread = zeps(spread);
    let c = r * (PI / 2.0 * a).fcos() / div;
    let d = r * (PI / 2.0 * a).fsin() / div;
    v.p.extend_from_slice(&[
        c,
        d,
        c / 2.0,
        d / 2.0,
        TAU / div,
        0.5 / spread,
        TAU * spread,
        // C's conversion to unsigned: negative spreads give 0 branches.
        spread.clamp(0.0, 4294967295.0).trunc(),
    ]);
}

/// Complex power z^((r/divisor)·e^(iπa/2)) with a random choice among the branches of the
/// logarithm (about `spread` of them, favouring the principal one) and of the divisor's roots.
#[inline(always)]
fn cpow2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [c, d, half_c, half_d, ang, inv_spread, full_spread, branches] = v.derived();
    let mut a = t.atan_yx;
    let branches = branches as u64;
    let mut n = if branches == 0 {
        rng.u32() as i32
    } else {
        rng.below(branches) as i32
    };
    if a < 0.0 {
        n = n.wrapping_add(1);
    }
    a += TAU * n as f64;
    if (a * inv_spread).fcos() < rng.f11() {
        a -= full_spread;
    }
    let lnr2 = t.sumsq.ln();
    let r = v.w * (half_c * lnr2 - d * a).exp();
    let th = c * a + half_d * lnr2 + ang * crand(rng);
    let (s, c) = th.fsin_cos();
    [r * c, r * s, 0.0]
}

fn prep_cpow3(v: &mut Prepared) {
    let [r, d, div, spread] = v.params();
    let div = zeps(div);
    let ld = if d < 0.0 { -(-d).ln() } else { d.ln() };
    let a = (ld * r).atan2(TAU);
    let (sa, ca) = (a.fsin(), a.fcos());
    let pc = ca * r * ca / div;
    let pd = ca * r * sa / div;
    let coeff = if pd == 0.0 { 0.0 } else { -0.095 * spread / pd };
    v.p.extend_from_slice(&[pc, pd, pc / 2.0, pd / 2.0, TAU / div, coeff]);
}

/// Complex power along a logarithmic spiral (exponent set by r and d), with random branches of
/// the logarithm drawn from a geometric-like law whose width is `spread`, and random roots of
/// the divisor.
#[inline(always)]
fn cpow3<R: Draws>(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut R) -> V3 {
    let [c, d, half_c, half_d, ang, coeff] = v.derived();
    let mut a = t.atan_yx;
    if a < 0.0 {
        a += TAU;
    }
    if (a / 2.0).fcos() < rng.f11() {
        a -= TAU;
    }
    let turn = if rng.bit() { TAU } else { -TAU };
    a += turn * (rng.f01().fln() * coeff).round();
    let lnr2 = t.sumsq.fln();
    let r = v.w * (half_c * lnr2 - d * a).fexp();
    // [`crand`]: an integer below 32767 (exact through i32, which vector units convert).
    let th = c * a + half_d * lnr2 + ang * (rng.below(32767) as i32 as f64);
    let (s, c) = th.fsin_cos();
    [r * c, r * s, 0.0]
}

fn dragonfire_prepare(v: &mut Prepared) {
    let [_, _, _, _, mode, pos, _, adj] = v.params();
    let val = if mode < 2.0 {
        pos
    } else {
        let a = pos * PI;
        let trig = if mode < 3.0 {
            a.fcos()
        } else if mode < 4.0 {
            a.tan()
        } else if mode < 5.0 {
            fm::sinh(a)
        } else {
            a.asinh()
        };
        (1.0 - trig) * adj
    };
    v.p.extend_from_slice(&[val, 1.0 - val]);
}

/// With u = c1·eˣ and v = c2/u: (u − v, sin y)/(u + v − cos y), a coth-like map, with optional
/// "fuzzy" perturbations driven by the logarithm of the result, blended in by a chosen curve.
#[inline(always)]
fn dragonfire(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [c1, c2, mode, radius, interp, _, scalar] = v.params();
    let [val, one_m_val] = v.derived();
    let ex = t.x.exp() * c1;
    let enx = c2 / zeps(ex);
    let (sy, cy) = t.y.fsin_cos();
    let r = v.w / zeps(ex + enx - cy);
    let fx = (ex - enx) * r;
    let fy = sy * r;
    if mode < 1.0 {
        return [fx, fy, 0.0];
    }
    let zx = (scalar / zeps(fx.abs().ln())).fcos();
    let zy = (scalar / zeps(fy.abs().ln())).fcos();
    let dir = |a: f64| if a < 0.0 { -radius } else { radius };
    let (nx, ny) = if mode < 2.0 {
        (fx + zx, fy + zy)
    } else if mode < 3.0 {
        (fx * zx.fsin(), fy * zy.fsin())
    } else if mode < 4.0 {
        (fx * zx.fsin().exp(), fy * zy.fsin().exp())
    } else if mode < 5.0 {
        (fx + dir(zx), fy + dir(zy))
    } else if mode < 6.0 {
        (fx + dir(zx).exp(), fy + dir(zy).exp())
    } else {
        (fx + dir(zx).fsin().exp(), fy + dir(zy).fcos().exp())
    };
    if interp < 1.0 {
        [nx, ny, 0.0]
    } else {
        [fx * one_m_val + nx * val, fy * one_m_val + ny * val, 0.0]
    }
}

/// The error function applied to each coordinate.
#[inline(always)]
fn erf_var(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w * erf(t.x), v.w * erf(t.y), 0.0]
}

/// Squares the point as a complex number and scales by a function of 1/r (kept away from the
/// pole by `eps`): identity, cos, exp, log or reciprocal by `radiusFunc`.
#[inline(always)]
fn excinis(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [ls, func, eps] = v.params();
    let rp = t.sqrt * ls;
    let sign = if rp >= 0.0 { 1.0 } else { -1.0 };
    let reps = if rp.abs() > eps { 0.0 } else { sign * eps };
    let r = v.w / zeps(rp + reps);
    let f = if func < 1.0 {
        r
    } else if func < 2.0 {
        r.fcos()
    } else if func < 3.0 {
        r.exp()
    } else if func < 4.0 {
        (r.abs() + reps.abs()).ln()
    } else {
        1.0 / zeps(r + reps)
    };
    [(t.x - t.y) * (t.x + t.y) * f, 2.0 * t.x * t.y * f, 0.0]
}

/// The complex exponential of π·z.
#[inline(always)]
fn exp2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let k = v.w * (t.x * PI).exp();
    let (s, c) = (t.y * PI).fsin_cos();
    [k * c, k * s, 0.0]
}

fn expo_prepare(v: &mut Prepared) {
    let [re, im] = v.params();
    let k = 0.5 * zeps(re * re + im * im).ln();
    let th = im.atan2(re);
    v.p.extend_from_slice(&[k, th]);
}

/// The complex power c^z for a fixed complex base c = real + i·imaginary.
#[inline(always)]
fn expo(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [k, th] = v.derived();
    let m = (t.x * k - t.y * th).exp();
    let (s, c) = (t.x * th + t.y * k).fsin_cos();
    [v.w * m * c, v.w * m * s, 0.0]
}

/// Appends ln φ (φ the golden ratio), the growth rate of the Fibonacci numbers.
fn fib_prepare(v: &mut Prepared) {
    v.p.push(1.618_033_988_749_895_f64.ln());
}

/// 1/√5.
const INV_SQRT5: f64 = 1.0 / 2.236_067_977_499_79;

/// Binet's formula for the Fibonacci numbers extended to the complex plane:
/// (φ^z − φ^(−z)·e^(iπz)) / √5 with z = x + iy.
#[inline(always)]
fn fibonacci(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [ln_phi] = v.derived();
    fib_common(v.w, 1.0, 1.0, ln_phi, t)
}

/// [`fibonacci`] with both powers scaled by `sc` and their exponents by `sc2`.
#[inline(always)]
fn fibonacci2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sc, sc2] = v.params();
    let [ln_phi] = v.derived();
    fib_common(v.w, sc, sc2, ln_phi, t)
}

#[inline(always)]
fn fib_common(w: f64, sc: f64, sc2: f64, lp: f64, t: &VarIn) -> V3 {
    let (s1, c1) = (t.y * lp).fsin_cos();
    let (s2, c2) = (-(t.x * PI + t.y * lp)).fsin_cos();
    let e1 = sc * (sc2 * (t.x * lp)).exp();
    let e2 = sc * (sc2 * -(t.x * lp - t.y * PI)).exp();
    [
        w * (e1 * c1 - e2 * c2) * INV_SQRT5,
        w * (e1 * s1 - e2 * s2) * INV_SQRT5,
        0.0,
    ]
}

/// Polar coordinates remapped: x = ln Γ(r), y = θ.
#[inline(always)]
fn gamma(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [v.w * ln_gamma(t.sqrt), v.w * t.atan_yx, 0.0]
}

/// The Jacobi functions at x (parameter k) and at y (parameter 1 − k), and the common
/// denominator sn²(x)·sn²(y)·k + cn²(y) of the complex-argument addition formulas.
#[inline(always)]
fn jac_parts(t: &VarIn, k: f64) -> ((f64, f64, f64), (f64, f64, f64), f64) {
    let jx = jacobi_elliptic(t.x, k);
    let jy = jacobi_elliptic(t.y, 1.0 - k);
    let den = jx.0 * jx.0 * (jy.0 * jy.0) * k + jy.1 * jy.1;
    (jx, jy, den)
}

/// The Jacobi elliptic function cn of the complex number x + iy.
#[inline(always)]
fn jac_cn(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [m] = v.params();
    let ((snx, cnx, dnx), (sny, cny, dny), den) = jac_parts(t, m);
    let k = v.w / zeps(den);
    [k * (cnx * cny), k * (-dnx * snx * dny * sny), 0.0]
}

/// The Jacobi elliptic function dn of the complex number x + iy.
#[inline(always)]
fn jac_dn(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [m] = v.params();
    let ((snx, cnx, dnx), (sny, cny, dny), den) = jac_parts(t, m);
    let k = v.w / zeps(den);
    [k * (dnx * cny * dny), k * (-cnx * snx * sny * m), 0.0]
}

/// The Jacobi elliptic function sn of the complex number x + iy.
#[inline(always)]
fn jac_sn(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [m] = v.params();
    let ((snx, cnx, dnx), (sny, cny, dny), den) = jac_parts(t, m);
    let k = v.w / zeps(den);
    [k * (snx * dny), k * (cnx * dnx * cny * sny), 0.0]
}

/// lens: half the complex square, ((x² − y²)/2, x·y).
#[inline(always)]
fn lens(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [0.5 * (t.x * t.x - t.y * t.y) * v.w, t.x * t.y * v.w, 0.0]
}

fn prep_log_db(v: &mut Prepared) {
    let [base, fix_period] = v.params();
    let mut scale = 0.5;
    if base > f64::EPSILON {
        scale /= (E * base).ln();
    }
    scale *= v.w;
    let mut period = PI;
    if fix_period > f64::EPSILON {
        period *= fix_period;
    }
    v.p.push(scale);
    v.p.push(period);
}

/// log_db: the complex logarithm in base e·base, with the angle shifted by a random small
/// multiple of π·fix_period (the sum of seven draws in −2..=2); z is scaled.
#[inline(always)]
fn log_db(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scale, period] = v.derived();
    let mut turns = 0i32;
    for _ in 0..7 {
        let d = rng.below(10) as i32 - 5;
        if d.abs() < 3 {
            turns += d;
        }
    }
    let shift = turns as f64 * period;
    [scale * t.sumsq.ln(), v.w * (t.atan_yx + shift), v.w * t.z]
}

fn prep_mobius_n(v: &mut Prepared) {
    let [_, _, _, _, _, _, _, _, power] = v.params();
    let power = if power.abs() < 1.0 { 1.0 } else { power };
    v.p.push(power);
    v.p.push(power.floor());
}

/// MobiusN: conjugates a Möbius map (A·z + B)/(C·z + D) by z ↦ z^power: the input is raised to
/// the power, mapped, then one of the power-th roots is taken at random.
#[inline(always)]
fn mobius_n<R: Draws>(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut R) -> V3 {
    let [re_a, im_a, re_b, im_b, re_c, im_c, re_d, im_d, _, dist] = v.params();
    let [power, whole_power] = v.derived();
    let e = 4.0 * dist / power;
    let r = t.sqrt.fpowf(e);
    let ang = t.atan_yx * power;
    let (x, y) = (r * ang.fcos(), r * ang.fsin());
    let re_u = re_a * x - im_a * y + re_b;
    let im_u = re_a * y + im_a * x + im_b;
    let re_v = re_c * x - im_c * y + re_d;
    let im_v = re_c * y + im_c * x + im_d;
    let den = re_v * re_v + im_v * im_v;
    let x = (re_u * re_v + im_u * im_v) / den;
    let y = (im_u * re_v - re_u * im_v) / den;
    let r = (x * x + y * y).sqrt().fpowf(1.0 / e);
    let branch = (power * rng.f01()).floor();
    let ang = (y.fatan2(x) + branch * TAU) / whole_power;
    [v.w * r * ang.fcos(), v.w * r * ang.fsin(), 0.0]
}

fn prep_murl(v: &mut Prepared) {
    let [c, power] = v.params();
    let cp = if power != 1.0 { c / (power - 1.0) } else { c };
    v.p.extend_from_slice(&[cp, power / 2.0, v.w * (cp + 1.0)]);
}

/// murl: divides the point by 1 + c'·z^power (c' = c/(power − 1)), normalised so that the
/// map is the identity scaled by the weight at c = 0.
#[inline(always)]
fn murl(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [_, power] = v.params();
    let [cp, half_power, scale] = v.derived();
    let ang = t.atan_yx * power;
    let r = cp * t.sumsq.fpowf(half_power);
    let re = r * ang.fcos() + 1.0;
    let im = r * ang.fsin();
    let k = scale / (re * re + im * im);
    [k * (t.x * re + t.y * im), k * (t.y * re - t.x * im), 0.0]
}

fn prep_murl2(v: &mut Prepared) {
    let [c, power] = v.params();
    let scale = if c == -1.0 {
        0.0
    } else {
        v.w * (c + 1.0).powf(2.0 / power)
    };
    v.p.extend_from_slice(&[power / 2.0, 1.0 / power, 2.0 / power, scale]);
}

/// murl2: like murl but divides by the (2/power)-th power of 1 + c·z^power.
#[inline(always)]
fn murl2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [c, power] = v.params();
    let [half_power, inv_p, two_inv_p, scale] = v.derived();
    let ang = t.atan_yx * power;
    let r = c * t.sumsq.powf(half_power);
    let re = r * ang.fcos() + 1.0;
    let im = r * ang.fsin();
    let rr = (re * re + im * im).powf(inv_p);
    let ang2 = im.atan2(re) * two_inv_p;
    let (re, im) = (rr * ang2.fcos(), rr * ang2.fsin());
    let k = scale / (rr * rr);
    [k * (t.x * re + t.y * im), k * (t.y * re - t.x * im), 0.0]
}

/// A rational function of z = x + iy: (t3 z³ + t2 z² + t1 z + tc) / (b3 z³ + b2 z² + b1 z + bc).
#[inline(always)]
fn rational3(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [t3, t2, t1, tc, b3, b2, b1, bc] = v.params();
    let (x, y) = (t.x, t.y);
    let (xx, yy) = (x * x, y * y);
    let (x3, y3) = (x * x * x, y * y * y);
    // Real and imaginary parts of z³ and z².
    let re3 = x3 - 3.0 * x * yy;
    let im3 = 3.0 * xx * y - y3;
    let re2 = xx - yy;
    let num_re = t3 * re3 + t2 * re2 + t1 * x + tc;
    let num_im = t3 * im3 + t2 * 2.0 * x * y + t1 * y;
    let den_re = b3 * re3 + b2 * re2 + b1 * x + bc;
    let den_im = b3 * im3 + b2 * 2.0 * x * y + b1 * y;
    let inv = 1.0 / zeps(den_re * den_re + den_im * den_im);
    [
        v.w * (num_re * den_re + num_im * den_im) * inv,
        v.w * (num_im * den_re - num_re * den_im) * inv,
        0.0,
    ]
}

/// xerf: the error function applied to each coordinate (3-D); coordinates of magnitude ≥ 2
/// are inverted in the unit sphere instead.
#[inline(always)]
fn xerf(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = sqr((t.sumsq + sqr(t.z)).sqrt());
    let f = |u: f64| if u.abs() >= 2.0 { u / r2 } else { erf(u) };
    [v.w * f(t.x), v.w * f(t.y), v.w * f(t.z)]
}
