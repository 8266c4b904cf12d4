//! JWildfire's formulas for julia-like variations that pick a random root or tile vertex: where
//! flam3 and Fractorium draw the branch below its count (or below 32767), JWildfire multiplies
//! its step angle by a whole number below 2³¹ − 1 (`random(Integer.MAX_VALUE)`). The product
//! is some 10⁹ radians, so the branch angle carries a rounding error of about 10⁻⁷ that grows
//! with the number drawn: each root is smeared along a short arc, and the smear is part of
//! JWildfire's picture. Each reads its registry entry's parameters and derived values (see
//! [`super::FORMULAS`]).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{FRAC_1_PI, PI};

use crate::flame::fastmath::FastTrig;
use crate::flame::variations::*;

/// JWildfire's `random(Integer.MAX_VALUE)`: a whole number below 2³¹ − 1, as a double.
#[inline(always)]
fn whole_below_int_max(rng: &mut FastRng) -> f64 {
    const MAX: f64 = i32::MAX as f64;
    (rng.f01() * MAX).trunc().min(MAX - 1.0)
}

/// juliaq (and post_juliaq, on the sum): z^(divisor/power) turned by k·2π/power, k a whole
/// number below 2³¹ − 1 (JWildfire 9.00, `JuliaQFunc`).
pub(super) fn juliaq(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [half_ratio, ratio, step] = v.derived();
    let a = t.y.atan2(t.x) * ratio + whole_below_int_max(rng) * step;
    let (s, c) = a.fsin_cos();
    let r = v.w * (t.x * t.x + t.y * t.y).powf(half_ratio);
    [r * c, r * s, v.default_z(t)]
}

/// julia3Dq (and post_julia3Dq, on the sum): juliaq in the plane, z scaled by |divisor/power|
/// and the point by its 3-D length to the power (divisor/power − 1)/2 (JWildfire 9.00,
/// `Julia3DQFunc`).
pub(super) fn julia3dq(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [inv, abs_inv, half_inv, step] = v.derived();
    let a = t.y.atan2(t.x) * inv + whole_below_int_max(rng) * step;
    let (s, c) = a.fsin_cos();
    let z = t.z * abs_inv;
    let r2d = t.x * t.x + t.y * t.y;
    let r = v.w * (r2d + z * z).powf(half_inv);
    let k = r * r2d.sqrt();
    [k * c, k * s, r * z]
}

/// juliac: z^(1/(re + i·im/100)) with a winding of fmod(k, re) turns, k a whole number below
/// 2³¹ − 1 (JWildfire 9.00, `JuliaCFunc`: the remainder is taken by `re` itself, not by the
/// reciprocal of its reciprocal).
pub(super) fn juliac(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [re, im, dist] = v.params();
    let re_inv = 1.0 / (re + 1e-300);
    let im = im / 100.0;
    let arg = t.y.atan2(t.x) + (whole_below_int_max(rng) % re) * 2.0 * PI;
    let lnmod = dist * 0.5 * (t.x * t.x + t.y * t.y).ln();
    let a = arg * re_inv + lnmod * im;
    let (s, c) = a.fsin_cos();
    let m = (lnmod * re_inv - arg * im).exp();
    [v.w * m * c, v.w * m * s, v.default_z(t)]
}

/// phoenix_julia: the power-th root of the point, its angle taken from the point stretched by
/// (1 + x_distort, 1 + y_distort), turned by k·2π/power (JWildfire 9.00, `PhoenixJuliaFunc`).
pub(super) fn phoenix_julia(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, xd, yd] = v.params();
    let [inv_n, step, exponent] = v.derived();
    let px = t.x * (xd + 1.0);
    let py = t.y * (yd + 1.0);
    let a = py.atan2(px) * inv_n + whole_below_int_max(rng) * step;
    let (s, c) = a.fsin_cos();
    let r = v.w * (t.x * t.x + t.y * t.y).powf(exponent);
    [r * c, r * s, v.default_z(t)]
}

/// wedge_julia: julian's root, the branch ⌊|power|·ξ⌋ (a fractional power keeps its partial
/// last branch), then wedged (JWildfire 9.00, `WedgeJuliaFunc`).
pub(super) fn wedge_julia(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [angle, count, power, dist] = v.params();
    let cf = 1.0 - angle * count * FRAC_1_PI * 0.5;
    let cn = dist / power / 2.0;
    let r = v.w * (t.x * t.x + t.y * t.y).powf(cn);
    let k = ((power.abs() * rng.f01()) as i32) as f64;
    let a = (t.y.atan2(t.x) + 2.0 * PI * k) / power;
    let c = ((count * a + PI) * FRAC_1_PI * 0.5).floor();
    let a = a * cf + c * angle;
    let (s, co) = a.fsin_cos();
    [r * co, r * s, v.default_z(t)]
}

/// hypertile1: the {p, q} tiling map towards the vertex at angle k·2π/p, k a whole number
/// below 2³¹ − 1 (JWildfire 9.00, `Hypertile1Func`; no guard on the denominator).
pub(super) fn hypertile1(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, r, _] = v.derived();
    let (sa, ca) = (whole_below_int_max(rng) * pa).fsin_cos();
    let (re, im) = (r * ca, r * sa);
    let a = t.x + re;
    let b = t.y - im;
    let c = re * t.x - im * t.y + 1.0;
    let d = re * t.y + im * t.x;
    let k = v.w / (c * c + d * d);
    [k * (a * c + b * d), k * (b * c - a * d), v.default_z(t)]
}

/// hypertile2: the {p, q} tiling map towards the first vertex, turned by k·2π/p, k a whole
/// number below 2³¹ − 1 (JWildfire 9.00, `Hypertile2Func`; no guard on the denominator).
pub(super) fn hypertile2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, r] = v.derived();
    let a = t.x + r;
    let b = t.y;
    let c = r * t.x + 1.0;
    let d = r * t.y;
    let x = a * c + b * d;
    let y = b * c - a * d;
    let k = v.w / (c * c + d * d);
    let (sa, ca) = (pa * whole_below_int_max(rng)).fsin_cos();
    [k * (x * ca + y * sa), k * (y * ca - x * sa), v.default_z(t)]
}

#[cfg(test)]
mod tests {
    use std::f64::consts::TAU;

    use super::*;

    /// The whole numbers reach past 2³⁰ (the smear of a branch grows with them) and stay below
    /// 2³¹ − 1.
    #[test]
    fn whole_numbers_span_javas_int_range() {
        let mut rng = FastRng::new(3);
        let draws: Vec<f64> = (0..4000).map(|_| whole_below_int_max(&mut rng)).collect();
        let in_range = |k: f64| (0.0..2147483647.0).contains(&k) && k.fract() == 0.0;
        assert!(draws.iter().all(|&k| in_range(k)));
        assert!(draws.iter().any(|&k| k > 1073741824.0));
        assert!(draws.iter().any(|&k| k < 1073741824.0));
    }

    /// A smeared root stays within 1e-6 of the exact one (the branch is right) and is not
    /// always exactly on it (the smear is there).
    #[test]
    fn roots_are_smeared_by_rounding_only() {
        let mut rng = FastRng::new(5);
        let step = TAU / 7.0;
        let mut off_exact = 0;
        for _ in 0..1000 {
            let k = whole_below_int_max(&mut rng);
            let a = k * step;
            let exact = (k % 7.0) * step;
            let d = (a.fsin() - exact.sin()).abs() + (a.fcos() - exact.cos()).abs();
            assert!(d < 1e-6, "k = {k}: {d}");
            off_exact += usize::from(d > 1e-12);
        }
        assert!(off_exact > 500);
    }
}
