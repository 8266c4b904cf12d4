//! JWildfire's formulas for variations that flam3 or Fractorium guard at the origin (and a few
//! other singular points) where JWildfire does not, or guards otherwise: its radius is never 0
//! (1e-300 added), its angle there is atan2(0, 0) = 0, and an unguarded 0/0 gives NaN, which the
//! iterator then treats as JWildfire's does. Elsewhere each gives its registry entry's value.
//! Each reads its registry entry's parameters (see [`super::FORMULAS`]).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{FRAC_1_PI, FRAC_2_PI, PI, TAU};

use super::{SMALL_EPSILON, jwf_sqrt};
use crate::flame::variations::*;

/// cardioid: the radius √(r² + sin(a·θ) + 1) along the polar angle θ (θ = 0 at the origin).
pub(super) fn cardioid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a] = v.params();
    let th = t.y.atan2(t.x);
    let r = v.w * (t.x * t.x + t.y * t.y + (th * a).sin() + 1.0).sqrt();
    [r * th.cos(), r * th.sin(), 0.0]
}

/// cot: the complex cotangent, unguarded (NaN at the origin).
pub(super) fn cot(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (s, c) = (2.0 * t.x).sin_cos();
    let den = 1.0 / ((2.0 * t.y).cosh() - c);
    [v.w * den * s, -v.w * den * (2.0 * t.y).sinh(), 0.0]
}

/// SphericalN: the origin (radius at most 1e-300) contributes nothing.
pub(super) fn spherical_n(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, dist] = v.params();
    let r = (t.x * t.x + t.y * t.y).sqrt().powf(dist);
    let n = (power * rng.f01()).floor();
    let alpha = t.y.atan2(t.x) + n * TAU / power.floor();
    if r > SMALL_EPSILON {
        let (s, c) = alpha.sin_cos();
        [v.w * c / r, v.w * s / r, 0.0]
    } else {
        [0.0; 3]
    }
}

/// roundspher: p/(r²·(1/r² + (2/π)²)), weighted twice, unguarded.
pub(super) fn roundspher(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let d = t.x * t.x + t.y * t.y;
    let e = 1.0 / d + FRAC_2_PI * FRAC_2_PI;
    [v.w * (v.w / d * t.x / e), v.w * (v.w / d * t.y / e), 0.0]
}

/// swirl3: the logarithmic twist of JWildfire's radius (never 0).
pub(super) fn swirl3(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [shift] = v.params();
    let rad = jwf_sqrt(t);
    let ang = t.y.atan2(t.x) + rad.ln() * shift;
    [v.w * rad * ang.cos(), v.w * rad * ang.sin(), 0.0]
}

/// wedge_sph: 1/r from JWildfire's radius plus 1e-300 again (5e299 at the origin).
pub(super) fn wedge_sph(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [angle, count, hole, swirl] = v.params();
    let r = 1.0 / (jwf_sqrt(t) + SMALL_EPSILON);
    let a = t.y.atan2(t.x) + swirl * r;
    let c = ((count * a + PI) * FRAC_1_PI * 0.5).floor();
    let comp_fac = 1.0 - angle * count * FRAC_1_PI * 0.5;
    let a = a * comp_fac + c * angle;
    let r = v.w * (r + hole);
    [r * a.cos(), r * a.sin(), 0.0]
}

/// scry_3D: p/(|p|·(|p|² + 1/(w + 1e-300))), unguarded; a zero z is replaced by the polar
/// angle.
pub(super) fn scry_3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let inv = 1.0 / (v.w + SMALL_EPSILON);
    let d2 = t.x * t.x + t.y * t.y + t.z * t.z;
    let r = 1.0 / (d2.sqrt() * (d2 + inv));
    let z = if t.z != 0.0 { t.z } else { t.y.atan2(t.x) };
    [t.x * r, t.y * r, z * r]
}

/// foci_3D: the 3-D foci map, unguarded (NaN at the origin, where the denominator is 0).
pub(super) fn foci_3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let ex = t.x.exp() * 0.5;
    let enx = 0.25 / ex;
    let boot = if t.z == 0.0 { t.y.atan2(t.x) } else { t.z };
    let (sy, cy) = t.y.sin_cos();
    let (sz, cz) = boot.sin_cos();
    let k = v.w / (ex + enx - cy * cz);
    [(ex - enx) * k, sy * k, sz * k]
}

/// spiralwing: w/(r² + 1e-300)·(cos x², sin x²)·sin y², unguarded otherwise (0 at the origin).
pub(super) fn spiralwing(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (c1, c2) = (t.x * t.x, t.y * t.y);
    let d = v.w / (c1 + c2 + SMALL_EPSILON);
    let s2 = c2.sin();
    [d * c1.cos() * s2, d * c1.sin() * s2, 0.0]
}

/// loonie_3D: a point within 1e-8 of the origin (a zero z taken as the polar angle)
/// contributes nothing.
pub(super) fn loonie_3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let w2 = v.w * v.w;
    let z = if t.z == 0.0 { t.y.atan2(t.x) } else { t.z };
    let r2 = t.x * t.x + t.y * t.y + z * z;
    if r2 < 1e-8 {
        return [0.0; 3];
    }
    let k = if r2 < w2 {
        v.w * (w2 / r2 - 1.0).sqrt()
    } else {
        v.w
    };
    [k * t.x, k * t.y, k * z * 0.5]
}

/// bSwirl: the bipolar swirl σ + τ·out + in/τ, unguarded (NaN where τ = 0, on the y axis).
/// A point whose denominator is exactly 0 contributes nothing.
pub(super) fn bswirl(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [in_, out] = v.params();
    let (x, y) = (t.x, t.y);
    let y2 = y * y;
    let tau = 0.5 * (((x + 1.0) * (x + 1.0) + y2).ln() - ((x - 1.0) * (x - 1.0) + y2).ln());
    let sigma = PI - y.atan2(x + 1.0) - y.atan2(1.0 - x);
    let sigma = sigma + tau * out + in_ / tau;
    let temp = tau.cosh() - sigma.cos();
    if temp == 0.0 {
        return [0.0; 3];
    }
    [v.w * tau.sinh() / temp, v.w * sigma.sin() / temp, 0.0]
}

/// glynnia: the outer maps from radius 1 on (the unit circle included), and a point at a pole
/// of the inner maps contributes nothing. Reads the registry's derived w·√2/2.
pub(super) fn glynnia(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [v2] = v.derived();
    let r = (t.x * t.x + t.y * t.y).sqrt();
    let sign = if r >= 1.0 { 1.0 } else { -1.0 };
    if rng.f01() > 0.5 {
        let d = (r + t.x).sqrt();
        if d == 0.0 {
            return [0.0; 3];
        }
        [sign * v2 * d, -(v2 / d * t.y), 0.0]
    } else {
        let d = r + t.x;
        let dx = (r * (t.y * t.y + d * d)).sqrt();
        if dx == 0.0 {
            return [0.0; 3];
        }
        let k = v.w / dx;
        [sign * k * d, k * t.y, 0.0]
    }
}

/// rays1: r²/x and r²/y scaled by w·(cot r + w·(2/π)²), unguarded (infinite on the axes);
/// replaces the x and y summed so far.
pub(super) fn rays1(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = t.x * t.x + t.y * t.y;
    let u = 1.0 / r2.sqrt().tan() + v.w * (FRAC_2_PI * FRAC_2_PI);
    replace_xy(v, acc, v.w * u * r2, t)
}

/// rays2: r²/x and r²/y scaled by w/10·sec((r² + 1e-300)·tan(1/r² + 1e-300)), unguarded;
/// replaces the x and y summed so far.
pub(super) fn rays2(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = t.x * t.x + t.y * t.y;
    let u = 1.0 / ((r2 + SMALL_EPSILON) * (1.0 / r2 + SMALL_EPSILON).tan()).cos();
    replace_xy(v, acc, v.w / 10.0 * u * r2, t)
}

/// (k/x, k/y), replacing the sum's x and y in the regular form.
fn replace_xy(v: &Prepared, acc: &mut Acc, k: f64, t: &VarIn) -> V3 {
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [k / t.x, k / t.y, 0.0]
}
