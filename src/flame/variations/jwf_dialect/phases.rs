//! JWildfire's own `pre_`/`post_` classes for names that ugnis otherwise runs as the pre or post
//! form of a regular variation: JWildfire gives them formulas of their own (unweighted,
//! changing only some coordinates, or scaling their parameters by it). Each returns the
//! whole point its form replaces.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use super::SMALL_EPSILON;
use crate::flame::variations::*;

/// post_curl: the point divided by 1 + c1·z + c2·z² (c1, c2 scaled by the weight), the point
/// itself not weighted; z kept.
pub(super) fn post_curl(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [c1, c2] = v.params();
    let (c1, c2) = (c1 * v.w, c2 * v.w);
    let (x, y) = (t.x, t.y);
    let re = 1.0 + c1 * x + c2 * (x * x - y * y);
    let im = c1 * y + 2.0 * c2 * x * y;
    let r = re * re + im * im + SMALL_EPSILON;
    [(x * re + y * im) / r, (y * re - x * im) / r, t.z]
}

/// post_flatten: z scaled by 1 − min(|w|, 1); x and y kept.
pub(super) fn post_flatten(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [t.x, t.y, t.z * (1.0 - v.w.abs().min(1.0))]
}

/// pre_zscale: z scaled by the weight; x and y kept.
pub(super) fn pre_zscale(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [t.x, t.y, t.z * v.w]
}

/// post_curl3D: the point divided by 1 + 2c·p (y's term negated, as JWildfire has it) +
/// |c|²·|p|², plus c·|p|² (c scaled by the weight), the point itself not weighted.
pub(super) fn post_curl3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cx, cy, cz] = v.params();
    let (cx, cy, cz) = (cx * v.w, cy * v.w, cz * v.w);
    let c2 = cx * cx + cy * cy + cz * cz;
    let r2 = t.x * t.x + t.y * t.y + t.z * t.z;
    let r = 1.0 / (r2 * c2 + 2.0 * cx * t.x - 2.0 * cy * t.y + 2.0 * cz * t.z + 1.0);
    [
        r * (t.x + cx * r2),
        r * (t.y + cy * r2),
        r * (t.z + cz * r2),
    ]
}

/// pre_sinusoidal3d: sinusoidal3D whose z reads the x and y it has just replaced (the weighted
/// sines), as JWildfire's assignments in order have it.
pub(super) fn pre_sinusoidal3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let x = v.w * t.x.sin();
    let y = v.w * t.y.sin();
    [x, y, v.w * (x * x).atan2(y * y) * t.z.cos()]
}

/// post_heat: heat on the summed point with its true 3-D radius √(x² + y² + z²) (Fractorium's
/// reads √|x² + y² + z|) and no guard at radius 0 (the inclination is then π/2) nor clamp of
/// its cosine. Reads the registry's derived amplitudes, frequencies and phases.
pub(super) fn post_heat(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [at, bt, ct, ap, bp, cp, ar, br, cr] = v.derived();
    let mut r = (t.x * t.x + t.y * t.y + t.z * t.z).sqrt();
    let azimuth = t.y.atan2(t.x);
    r += ar * (br * r + cr).sin();
    let (st, ct_) = (at * (bt * r + ct).sin() + azimuth).sin_cos();
    let cos_incl = if r != 0.0 { t.z / r } else { 0.0 };
    let (sp, cp_) = (ap * (bp * r + cp).sin() + cos_incl.acos()).sin_cos();
    [r * ct_ * sp, r * st * sp, r * cp_]
}
