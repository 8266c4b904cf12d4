//! Julia-like variations from Fractorium's catalogue: roots of the point with a random branch
//! (`julia3D`, `julia3Dq`, `julia3Dz`, `Juliac`, `julian2`, `julian3Dx`, `juliaNab`, `juliaq`,
//! `npolar`, `phoenix_julia`, `pow_block`, `SphericalN`, `wavesn`).
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{PI, TAU};

use super::util::{crand, floor_f, rand_size, trunc_i32, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("julia3D", julia3d)
        .params(&[p_int_nonzero("julia3D_power", 2.0, NEG_INF, INF)])
        .needs(need::SQRT | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(julia3d_prepare),
    super::inlined!("julia3Dq", julia3dq)
        .params(&[
            p_int_nonzero("julia3Dq_power", 3.0, NEG_INF, INF),
            p_int_nonzero("julia3Dq_divisor", 2.0, NEG_INF, INF),
        ])
        .needs(need::SQRT | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(julia3dq_prepare),
    super::inlined!("julia3Dz", julia3dz)
        .params(&[p_int_nonzero("julia3Dz_power", 2.0, NEG_INF, INF)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_julia3dz),
    super::inlined!("Juliac", juliac)
        .params(&[
            p("Juliac_re", 2.0),
            p("Juliac_im", 1.0),
            p("Juliac_dist", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_juliac),
    super::inlined!("julian2", julian2)
        .params(&[
            p("julian2_a", 1.0),
            p("julian2_b", 0.0),
            p("julian2_c", 0.0),
            p("julian2_d", 1.0),
            p("julian2_e", 0.0),
            p("julian2_f", 0.0),
            p_nonzero("julian2_power", 2.0, NEG_INF, INF),
            p("julian2_dist", 1.0),
        ])
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(prep_julian2),
    super::inlined!("julian3Dx", julian3dx)
        .params(&[
            p("julian3Dx_dist", 1.0),
            p_int_nonzero("julian3Dx_power", 2.0, NEG_INF, INF),
            p("julian3Dx_a", 1.0),
            p("julian3Dx_b", 0.0),
            p("julian3Dx_c", 0.0),
            p("julian3Dx_d", 1.0),
            p("julian3Dx_e", 0.0),
            p("julian3Dx_f", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_julian3dx),
    super::inlined!("juliaNab", julianab)
        .params(&[
            p("juliaNab_n", 1.0),
            p("juliaNab_a", 1.0),
            p("juliaNab_b", 1.0),
            p("juliaNab_separ", 1.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(prep_julianab),
    super::inlined!("juliaq", juliaq)
        .params(&[
            p_nonzero("juliaq_power", 3.0, NEG_INF, INF),
            p_nonzero("juliaq_divisor", 2.0, NEG_INF, INF),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_juliaq),
    super::inlined!("npolar", npolar)
        .params(&[p("npolar_parity", 0.0), p("npolar_n", 1.0)])
        .needs(need::SUMSQ | need::ATAN_XY | need::ATAN_YX)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(prep_npolar),
    super::inlined!("phoenix_julia", phoenix_julia)
        .params(&[
            p("phoenix_julia_power", 2.0),
            p("phoenix_julia_dist", 1.0),
            p("phoenix_julia_x_distort", -0.5),
            p("phoenix_julia_y_distort", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::COMPAT)
        .prepare(prep_phoenix_julia),
    super::inlined!("pow_block", pow_block)
        .params(&[
            p("pow_block_numerator", 3.0),
            p("pow_block_denominator", 2.0),
            p("pow_block_root", 1.0),
            p("pow_block_correctn", 1.0),
            p("pow_block_correctd", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(prep_pow_block),
    super::inlined!("SphericalN", spherical_n)
        .params(&[p("SphericalN_Power", 1.0), p("SphericalN_Dist", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(spherical_n_prep),
    super::inlined!("wavesn", wavesn)
        .params(&[
            p("wavesn_freqx", 2.0),
            p("wavesn_freqy", 2.0),
            p("wavesn_scalex", 1.0),
            p("wavesn_scaley", 1.0),
            p("wavesn_incx", 0.0),
            p("wavesn_incy", 0.0),
            p("wavesn_power", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(wavesn_prep),
];

/// julia in 3-D: a random |power|-th root of the point in the plane, z divided by |power| and
/// the whole point scaled by its 3-D length to the power (1/power − 1)/2.
fn julia3d_prepare(v: &mut Prepared) {
    let [n] = v.params();
    v.p.extend_from_slice(&[n.abs(), (1.0 / n - 1.0) / 2.0]);
}

#[inline(always)]
fn julia3d(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n] = v.params();
    let [abs_n, expo] = v.derived();
    let z = t.z / abs_n;
    let r = v.w * (t.sumsq + z * z).powf(expo);
    let k = r * t.sqrt;
    let branch = rng.below(abs_n as u64) as f64;
    let (sa, ca) = ((t.atan_yx + TAU * branch) / n).fsin_cos();
    [k * ca, k * sa, r * z]
}

fn julia3dq_prepare(v: &mut Prepared) {
    let [power, divisor] = v.params();
    let inv = divisor / power;
    v.p.extend_from_slice(&[inv, inv.abs(), 0.5 * inv - 0.5, TAU / power]);
}

/// julia3D with a rational power divisor/power and Fractorium's wide random branch choice
/// (any multiple of 2π/power).
#[inline(always)]
fn julia3dq(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [inv, abs_inv, half_inv, step] = v.derived();
    let ang = t.atan_yx * inv + crand(rng) * step;
    let (sa, ca) = ang.fsin_cos();
    let z = t.z * abs_inv;
    let r = v.w * (t.sumsq + z * z).powf(half_inv);
    let k = r * t.sqrt;
    [k * ca, k * sa, r * z]
}

fn prep_julia3dz(v: &mut Prepared) {
    let [n] = v.params();
    v.p.push(n.abs());
    v.p.push(1.0 / n / 2.0);
}

/// julia3Dz: the n-th root julia map in the plane (one of |n| branches at random); z is scaled by
/// the same radial factor over the input radius, making a 3-D cone of julia sheets.
#[inline(always)]
fn julia3dz(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n] = v.params();
    let [abs_n, exponent] = v.derived();
    let radius = v.w * t.sumsq.powf(exponent);
    let branch = TAU * rand_size(rng, abs_n as u32 as f64);
    let ang = (t.atan_yx + branch) / n;
    [
        radius * ang.fcos(),
        radius * ang.fsin(),
        radius * t.z / zeps(t.sqrt * abs_n),
    ]
}

fn prep_juliac(v: &mut Prepared) {
    let [re, im, dist] = v.params();
    let re_inv = 1.0 / zeps(re);
    v.p.extend_from_slice(&[dist * 0.5, re_inv, 1.0 / re_inv, im * 0.01]);
}

/// Juliac: a complex power z^(1/(re + i·im/100)) with a random integer winding; the imaginary
/// part of the exponent spirals the branches.
#[inline(always)]
fn juliac(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [half_dist, re_inv, period, im_scaled] = v.derived();
    let turn = (rng.u32() as f64) % period;
    let arg = t.atan_yx + turn * TAU;
    let log_mod = half_dist * t.sumsq.ln();
    let ang = arg * re_inv + log_mod * im_scaled;
    let magnitude = (log_mod * re_inv - arg * im_scaled).exp();
    [
        v.w * magnitude * ang.fcos(),
        v.w * magnitude * ang.fsin(),
        0.0,
    ]
}

fn prep_julian2(v: &mut Prepared) {
    let [_, _, _, _, _, _, power, dist] = v.params();
    let power = if power == 0.0 { 2.0 } else { power };
    let abs_n = if v.compat {
        power.abs().trunc()
    } else {
        power.abs()
    };
    let exponent = dist / power / 2.0;
    v.p.extend_from_slice(&[power, abs_n, exponent]);
}

/// julian2: julian (the power-th root with a random branch) applied after its own affine map
/// (a b c d e f) of the input point.
#[inline(always)]
fn julian2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a, b, c, d, e, f] = v.params();
    let [power, abs_n, exponent] = v.derived();
    let x = a * t.x + b * t.y + e;
    let y = c * t.x + d * t.y + f;
    let radius = v.w * (x * x + y * y).powf(exponent);
    let ang = if v.compat {
        (y.atan2(x) + TAU * rand_size(rng, abs_n)) / power
    } else {
        let branch = trunc_i32(abs_n * rng.f01()) as f64;
        (y.atan2(x) + branch * TAU) / power
    };
    [radius * ang.fcos(), radius * ang.fsin(), 0.0]
}

fn prep_julian3dx(v: &mut Prepared) {
    let [dist, power] = v.params();
    v.p.push(power.abs());
    v.p.push((dist / power - 1.0) / 2.0);
}

/// julian3Dx: a 3-D julian whose planar angle comes from an affine-transformed copy of the
/// point; the radius combines the planar radius and z scaled by 1/|power|.
#[inline(always)]
fn julian3dx(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, power, a, b, c, d, e, f] = v.params();
    let [abs_n, exponent] = v.derived();
    let z = t.z / abs_n;
    let radius = v.w * (t.sumsq + z * z).powf(exponent);
    let x = a * t.x + b * t.y + e;
    let y = c * t.x + d * t.y + f;
    let branch = trunc_i32(rng.f01() * abs_n) as f64;
    let ang = (y.atan2(x) + TAU * branch) / power;
    let planar = radius * t.sqrt;
    [planar * ang.fcos(), planar * ang.fsin(), radius * z]
}

fn prep_julianab(v: &mut Prepared) {
    let [n] = v.params();
    let div = zeps(n.abs());
    v.p.push(n.abs());
    v.p.push(1.0 / div / 2.0);
}

/// juliaNab: a julia-like root whose angle is taken from (|x|^separ, y), with an exponent scaled
/// by `a` and both outputs shifted by `b`; z passes through (and the running z is reset).
#[inline(always)]
fn julianab(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n, a, b, separ] = v.params();
    let [abs_n, exponent] = v.derived();
    let div = zeps(n.abs());
    let branch = (rng.f01() * abs_n).floor();
    let ang = (t.y.atan2(t.x.abs().powf(separ)) + TAU * branch) / div;
    let radius = v.w * t.sumsq.powf(exponent * a);
    if v.form == Form::Regular {
        acc.z = 0.0;
    }
    [radius * ang.fcos() + b, radius * ang.fsin() + b, t.z]
}

fn prep_juliaq(v: &mut Prepared) {
    let [power, divisor] = v.params();
    let pz = zeps(power);
    v.p.extend_from_slice(&[0.5 * (divisor / pz), divisor / pz, TAU / pz]);
}

/// juliaq: the rational power z^(divisor/power), with a random multiple of 2π/power added to
/// the angle.
#[inline(always)]
fn juliaq(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [half_ratio, ratio, step] = v.derived();
    let ang = t.atan_yx * ratio + crand(rng) * step;
    let radius = v.w * t.sumsq.powf(half_ratio);
    [radius * ang.fcos(), radius * ang.fsin(), 0.0]
}

fn prep_npolar(v: &mut Prepared) {
    let [parity, n] = v.params();
    let nnz = if n == 0.0 { 1.0 } else { n };
    let vvar = v.w / PI;
    v.p.extend_from_slice(&[
        nnz,
        vvar,
        vvar * 0.5,
        nnz.abs(),
        1.0 / nnz / 2.0,
        parity.abs() % 2.0,
    ]);
}

/// npolar: with odd parity a julian-style n-th root; with even parity the same root taken of
/// the point's log-polar image, the result mapped back through the log-polar map.
#[inline(always)]
fn npolar(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [parity] = v.params();
    let [nnz, vvar, vvar2, abs_n, exponent, odd] = v.derived();
    let (x, y) = if odd != 0.0 {
        let ang = (t.atan_yx + TAU * rand_size(rng, abs_n)) / nnz;
        let mut r = v.w * t.sumsq.powf(exponent);
        if v.compat {
            r *= parity;
        }
        (ang.fcos() * r, ang.fsin() * r)
    } else {
        let lx = vvar * t.atan_xy;
        let ly = vvar2 * t.sumsq.ln();
        let ang = (ly.atan2(lx) + TAU * rand_size(rng, abs_n)) / nnz;
        let mut r = v.w * (lx * lx + ly * ly).powf(exponent);
        if !v.compat {
            r *= parity;
        }
        let (s, c) = (ang.fsin() * r, ang.fcos() * r);
        let x = if v.compat {
            vvar2 * (c * c + s * s).ln()
        } else {
            vvar2 * 2.0 * r.ln()
        };
        (x, vvar * c.atan2(s))
    };
    [x, y, 0.0]
}

fn prep_phoenix_julia(v: &mut Prepared) {
    let [power, dist] = v.params();
    let pz = zeps(power);
    let inv_n = dist / pz;
    v.p.extend_from_slice(&[inv_n, TAU / pz, inv_n / 2.0]);
}

/// phoenix_julia: a julia-style root whose angle is taken from the point stretched by
/// (1 + x_distort, 1 + y_distort); z is scaled in compatible mode.
#[inline(always)]
fn phoenix_julia(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, _, xd, yd] = v.params();
    let [inv_n, step, exponent] = v.derived();
    let px = t.x * (xd + 1.0);
    let py = t.y * (yd + 1.0);
    let r = v.w * t.sumsq.powf(exponent);
    if v.compat {
        let ang = py.atan2(px) * inv_n + crand(rng) * step;
        [r * ang.fcos(), r * ang.fsin(), v.w * t.z]
    } else {
        let root = trunc_i32(rng.f01() * power) as f64;
        let ang = py.atan2(px) * inv_n + root * step;
        [r * ang.fcos(), r * ang.fsin(), v.default_z(t)]
    }
}

fn prep_pow_block(v: &mut Prepared) {
    let [num, den, _, cn, cd] = v.params();
    v.p.push(num / zeps(den * cn * (1.0 / cd)));
}

/// pow_block: the power z^(numerator/denominator·corrections) with a random root branch
/// (scaled by `root`), the angle taken as numerator·(θ + 2π·k·root)/denominator.
#[inline(always)]
fn pow_block(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [num, den, root] = v.params();
    let [power] = v.derived();
    let r = t.sumsq.powf(power * 0.5) * v.w;
    let dz = zeps(den);
    let ang = (t.atan_yx / dz + (root * TAU * (rng.f01() * den).floor() / dz)) * num;
    [r * ang.fcos(), r * ang.fsin(), 0.0]
}

/// An inversion r → 1/r^dist copied into `power` random rotated sectors (x and y swapped with
/// flam3 compatibility off).
#[inline(always)]
fn spherical_n(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, dist] = v.params();
    let [step] = v.derived();
    let r = zeps(t.sqrt.powf(dist));
    let n = floor_f(power * rng.f01());
    let alpha = t.atan_yx + n * TAU / step;
    let (s, c) = alpha.fsin_cos();
    if v.compat {
        [v.w * c / r, v.w * s / r, 0.0]
    } else {
        [v.w * s / r, v.w * c / r, 0.0]
    }
}

fn spherical_n_prep(v: &mut Prepared) {
    let [power] = v.params();
    let step = zeps(floor_f(power));
    v.p.push(step);
}

/// Derived values of wavesn: the power actually used (0 becomes 2), the number of roots and
/// the radius exponent.
fn wavesn_prep(v: &mut Prepared) {
    let [_, _, _, _, _, _, mut power] = v.params();
    if power == 0.0 {
        power = 2.0;
    }
    let roots = trunc_i32(power.abs()) as f64;
    v.p.extend_from_slice(&[power, roots, 1.0 / power / 2.0]);
}

/// wavesn: a random n-th root (julian-like, n = `power`) followed by waves whose amplitude
/// can grow with distance (`incx`, `incy`).
#[inline(always)]
fn wavesn(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [freqx, freqy, scalex, scaley, incx, incy] = v.params();
    let [power, roots, cn] = v.derived();
    let angle = (t.atan_yx + TAU * rand_size(rng, roots)) / power;
    let r = v.w * t.sumsq.powf(cn);
    let (sa, ca) = angle.fsin_cos();
    let ux = r * ca;
    let uy = r * sa;
    let sy = (freqx * uy).fsin();
    let sx = (freqy * ux).fsin();
    let dx = ux + 0.5 * (scalex * sy + ux.abs() * incx * sy);
    let dy = uy + 0.5 * (scaley * sx + uy.abs() * incy * sx);
    [v.w * dx, v.w * dy, 0.0]
}
