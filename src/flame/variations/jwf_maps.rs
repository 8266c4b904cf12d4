//! JWildfire's maps of the point: `complex` (a weighted sum of complex functions), `rosoni`,
//! Johnny Svensson's attractor `svensson_js`, the crop `crop_stars` and the mirror
//! `post_mirror_wf`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: `atan_xy` is its `getPrecalcAtan`
//! (atan2(x, y)), weights multiply the output linearly, integer parameters are rounded (those it
//! truncates, `(int) value`, are stored as reals and truncated where used), and random numbers
//! are drawn in the order JWildfire draws them, so that the tests can replay JWildfire's own code
//! on the same stream.

use std::f64::consts::{FRAC_1_PI, TAU};

use super::util::jwf_math as jm;
use super::util::{atan2_approx, signum_java, sqr};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("complex", complex)
        .params(COMPLEX_PARAMS)
        .flags(flag::JWILDFIRE),
    VarDef::new("rosoni", rosoni)
        .params(&[
            p_int("rosoni_maxiter", 25.0, 1.0, 1024.0),
            p_int("rosoni_sweetiter", 3.0, 0.0, 1023.0),
            p_int("rosoni_altshapes", 0.0, NEG_INF, INF),
            p("rosoni_cutoff", 1.0),
            p("rosoni_radius", 0.4),
            p("rosoni_dx", 0.6),
            p("rosoni_dy", 0.0),
        ])
        .needs(need::SQRT)
        .flags(flag::JWILDFIRE)
        .prepare(rosoni_prepare),
    VarDef::new("post_mirror_wf", post_mirror_wf)
        .params(&[
            p_int("post_mirror_wf_xaxis", 1.0, NEG_INF, INF),
            p_int("post_mirror_wf_yaxis", 0.0, NEG_INF, INF),
            p_int("post_mirror_wf_zaxis", 0.0, NEG_INF, INF),
            p("post_mirror_wf_xshift", 0.0),
            p("post_mirror_wf_yshift", 0.0),
            p("post_mirror_wf_zshift", 0.0),
            p("post_mirror_wf_xscale", 1.0),
            p("post_mirror_wf_yscale", 1.0),
            p("post_mirror_wf_xcolorshift", 0.0),
            p("post_mirror_wf_ycolorshift", 0.0),
            p("post_mirror_wf_zcolorshift", 0.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::POST_ONLY
                | flag::RANDOM
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::USES_COLOR
                | flag::SETS_COLOR,
        ),
    VarDef::new("crop_stars", crop_stars)
        .params(&[
            p("crop_stars_radius", 0.35),
            p_int("crop_stars_n", 3.0, 3.0, 9.0),
            p_range("crop_stars_r2", 0.333, 0.0, 1.0),
            p_int("crop_stars_invert", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_ACC | flag::HIDES)
        .prepare(crop_stars_prepare),
    VarDef::new("svensson_js", svensson_js)
        .params(P_SVENSSON)
        .flags(flag::JWILDFIRE | flag::WRITES_ACC),
];

/// Parameters of `complex` in JWildfire's order: for each function its weight ("pow") then the
/// factors applied to x and y inside the trigonometric parts.
const COMPLEX_PARAMS: &[super::Param] = &[
    p("complex_cospow", 1.0),
    p("complex_cosx1", 1.0),
    p("complex_cosx2", 1.0),
    p("complex_cosy1", 1.0),
    p("complex_cosy2", 1.0),
    p("complex_coshpow", 0.0),
    p("complex_coshx1", 1.0),
    p("complex_coshx2", 1.0),
    p("complex_coshy1", 1.0),
    p("complex_coshy2", 1.0),
    p("complex_cotpow", 0.0),
    p("complex_cotx1", 2.0),
    p("complex_cotx2", 2.0),
    p("complex_coty1", 2.0),
    p("complex_coty2", 2.0),
    p("complex_cothpow", 0.0),
    p("complex_cothx1", 2.0),
    p("complex_cothx2", 2.0),
    p("complex_cothy1", 2.0),
    p("complex_cothy2", 2.0),
    p("complex_cscpow", 0.0),
    p("complex_cscx1", 1.0),
    p("complex_cscx2", 1.0),
    p("complex_cscy1", 1.0),
    p("complex_cscy2", 1.0),
    p("complex_cschpow", 0.0),
    p("complex_cschx1", 1.0),
    p("complex_cschx2", 1.0),
    p("complex_cschy1", 1.0),
    p("complex_cschy2", 1.0),
    p("complex_exppow", 0.0),
    p("complex_expx1", 1.0),
    p("complex_expy1", 1.0),
    p("complex_expy2", 1.0),
    p("complex_secpow", 0.0),
    p("complex_secx1", 1.0),
    p("complex_secx2", 1.0),
    p("complex_secy1", 1.0),
    p("complex_secy2", 1.0),
    p("complex_sechpow", 0.0),
    p("complex_sechx1", 1.0),
    p("complex_sechx2", 1.0),
    p("complex_sechy1", 1.0),
    p("complex_sechy2", 1.0),
    p("complex_sinpow", 0.0),
    p("complex_sinx1", 1.0),
    p("complex_sinx2", 1.0),
    p("complex_siny1", 1.0),
    p("complex_siny2", 1.0),
    p("complex_sinhpow", 0.0),
    p("complex_sinhx1", 1.0),
    p("complex_sinhx2", 1.0),
    p("complex_sinhy1", 1.0),
    p("complex_sinhy2", 1.0),
    p("complex_tanpow", 0.0),
    p("complex_tanx1", 2.0),
    p("complex_tanx2", 2.0),
    p("complex_tany1", 2.0),
    p("complex_tany2", 2.0),
    p("complex_tanhpow", 0.0),
    p("complex_tanhx1", 2.0),
    p("complex_tanhx2", 2.0),
    p("complex_tanhy1", 2.0),
    p("complex_tanhy2", 2.0),
];

/// complex: a weighted sum of the complex cos, cosh, cot, coth, csc, csch, exp, sec, sech, tan,
/// tanh, sin and sinh of the input, each with factors that detune its real and imaginary
/// parts. A vanishing denominator drops the whole output (the point contributes nothing).
/// JWildfire's table maths throughout: near the origin the poles amplify their last bits.
fn complex(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        cospow,
        cosx1,
        cosx2,
        cosy1,
        cosy2,
        coshpow,
        coshx1,
        coshx2,
        coshy1,
        coshy2,
        cotpow,
        cotx1,
        cotx2,
        coty1,
        coty2,
        cothpow,
        cothx1,
        cothx2,
        cothy1,
        cothy2,
        cscpow,
        cscx1,
        cscx2,
        cscy1,
        cscy2,
        cschpow,
        cschx1,
        cschx2,
        cschy1,
        cschy2,
        exppow,
        expx1,
        expy1,
        expy2,
        secpow,
        secx1,
        secx2,
        secy1,
        secy2,
        sechpow,
        sechx1,
        sechx2,
        sechy1,
        sechy2,
        sinpow,
        sinx1,
        sinx2,
        siny1,
        siny2,
        sinhpow,
        sinhx1,
        sinhx2,
        sinhy1,
        sinhy2,
        tanpow,
        tanx1,
        tanx2,
        tany1,
        tany2,
        tanhpow,
        tanhx1,
        tanhx2,
        tanhy1,
        tanhy2,
    ] = v.params();
    let (x, y) = (t.x, t.y);
    let (mut ox, mut oy) = (0.0, 0.0);
    // cos
    if cospow != 0.0 {
        ox += cospow * jm::cos(x * cosx2) * jm::cosh(y * cosy2);
        oy -= cospow * jm::sin(x * cosx1) * jm::sinh(y * cosy1);
    }
    // cosh
    if coshpow != 0.0 {
        ox += coshpow * jm::cosh(x * coshx2) * jm::cos(y * coshy2);
        oy += coshpow * jm::sinh(x * coshx1) * jm::sin(y * coshy1);
    }
    // cot
    if cotpow != 0.0 {
        let k = 1.0 / (jm::cosh(coty2 * y) - jm::cos(cotx2 * x));
        ox += cotpow * k * jm::sin(cotx1 * x);
        oy -= cotpow * k * jm::sinh(coty1 * y);
    }
    // coth
    if cothpow != 0.0 {
        let d = jm::cosh(cothx2 * x) - jm::cos(cothy2 * y);
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 1.0 / d;
        ox += cothpow * k * jm::sinh(cothx1 * x);
        oy += cothpow * k * jm::sin(cothy1 * y);
    }
    // csc
    if cscpow != 0.0 {
        let d = jm::cosh(2.0 * y) - jm::cos(2.0 * x);
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 2.0 / d;
        ox += cscpow * k * jm::sin(x * cscx1) * jm::cosh(y * cscy2);
        oy -= cscpow * k * jm::cos(x * cscx2) * jm::sinh(y * cscy1);
    }
    // csch
    if cschpow != 0.0 {
        let d = jm::cosh(2.0 * x) - jm::cos(2.0 * y);
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 2.0 / d;
        ox += cschpow * k * jm::sinh(x * cschx1) * jm::cos(y * cschy2);
        oy -= cschpow * k * jm::cosh(x * cschx2) * jm::sin(y * cschy1);
    }
    // exp
    if exppow != 0.0 {
        let e = jm::exp(x * expx1);
        ox += exppow * e * jm::cos(y * expy2);
        oy += exppow * e * jm::sin(y * expy1);
    }
    // sec
    if secpow != 0.0 {
        let d = jm::cos(2.0 * x) + jm::cosh(2.0 * y);
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 2.0 / d;
        ox += secpow * k * jm::cos(x * secx2) * jm::cosh(y * secy2);
        oy += secpow * k * jm::sin(x * secx1) * jm::sinh(y * secy1);
    }
    // sech
    if sechpow != 0.0 {
        let d = jm::cos(2.0 * y) + jm::cosh(2.0 * x);
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 2.0 / d;
        ox += sechpow * k * jm::cosh(x * sechx2) * jm::cos(y * sechy2);
        oy -= sechpow * k * jm::sinh(x * sechx1) * jm::sin(y * sechy1);
    }
    // tan
    if tanpow != 0.0 {
        let d = jm::cos(tanx2 * x) + jm::cosh(tany2 * y);
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 1.0 / d;
        ox += tanpow * k * jm::sin(tanx1 * x);
        oy += tanpow * k * jm::sinh(tany1 * y);
    }
    // tanh
    if tanhpow != 0.0 {
        let d = jm::cos(y * tanhy2) + jm::cosh(x * tanhx2);
        if d == 0.0 {
            return [0.0; 3];
        }
        let k = 1.0 / d;
        ox += tanhpow * k * jm::sinh(x * tanhx1);
        oy += tanhpow * k * jm::sin(y * tanhy1);
    }
    // sin
    if sinpow != 0.0 {
        ox += sinpow * jm::sin(x * sinx1) * jm::cosh(y * siny2);
        oy += sinpow * jm::cos(x * sinx2) * jm::sinh(y * siny1);
    }
    // sinh
    if sinhpow != 0.0 {
        ox += sinhpow * jm::sinh(x * sinhx1) * jm::cos(y * sinhy2);
        oy += sinhpow * jm::cosh(x * sinhx2) * jm::sin(y * sinhy1);
    }
    [v.w * ox, v.w * oy, 0.0]
}

fn rosoni_prepare(v: &mut Prepared) {
    let [maxiter] = v.params();
    let phi = TAU / maxiter;
    v.p.push(phi.sin());
    v.p.push(phi.cos());
}

/// rosoni: inside a cut-off disc (or square), rotates the point through `maxiter` steps around
/// the origin and counts how often it falls into a shape placed at (dx, dy) (a circle, square,
/// lemniscate or wedge); an odd count replaces the point by its rotation at step `sweetiter`.
fn rosoni(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [maxiter, sweetiter, alt, cutoff, radius, dx, dy] = v.params();
    let [sina, cosa] = v.derived();
    let (maxiter, sweetiter) = (maxiter as i32, sweetiter as i32);
    let (x, y) = (t.x, t.y);
    let outside = if cutoff < 0.0 {
        x.abs().max(y.abs()) + cutoff
    } else {
        t.sqrt - cutoff
    };
    if outside > 0.0 {
        return [v.w * x, v.w * y, 0.0];
    }
    let mut odd = dx > 0.0;
    let (mut xr, mut yr) = (x, y);
    let (mut sx, mut sy) = (x, y);
    for i in 0..maxiter {
        let inside_measure = if alt == 0.0 {
            if radius < 0.0 {
                // square (JWildfire measures y from the unrotated point here)
                (xr - dx).abs().max((y - dy).abs()) + radius
            } else {
                sqr(xr - dx) + sqr(yr - dy) - sqr(radius)
            }
        } else if radius < 0.0 {
            // wedge (again with the unrotated y)
            (y - dy).atan2(xr - dx).abs() * FRAC_1_PI + radius
        } else if xr - dx < 0.0 {
            dx - xr
        } else {
            sqr(yr - dy) - sqr(xr - dx) * (sqr(radius) - sqr(xr - dx))
        };
        odd ^= inside_measure <= 0.0;
        if i == sweetiter {
            sx = xr;
            sy = yr;
        }
        let nx = xr * cosa - yr * sina;
        yr = xr * sina + yr * cosa;
        xr = nx;
    }
    if !odd {
        return [v.w * x, v.w * y, 0.0];
    }
    if sweetiter == 0 {
        let ox = if dy != 0.0 { -sx } else { sx };
        [v.w * ox, -v.w * sy, 0.0]
    } else {
        [v.w * sx, v.w * sy, 0.0]
    }
}

/// post_mirror_wf: after the xform's variations, mirrors the point with probability ½ per
/// enabled axis (x: about x = -xshift/2, y: about y = -yshift/2, z: about z = -zshift/2), scaling
/// and shifting the colour on each mirror. The weight is not used.
fn post_mirror_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        xaxis,
        yaxis,
        zaxis,
        xshift,
        yshift,
        zshift,
        xscale,
        yscale,
        xcolorshift,
        ycolorshift,
        zcolorshift,
    ] = v.params();
    // JWildfire 9.00 (`PostMirrorWFFunc`) mirrors nothing, and draws no random number, at a
    // weight within its EPSILON of 0 (the variation still runs there: it sets the colour).
    if v.w.abs() <= 1e-8 {
        return [t.x, t.y, t.z];
    }
    let (mut x, mut y, mut z) = (t.x, t.y, t.z);
    let mut c = acc.color;
    if xaxis > 0.0 && rng.f01() < 0.5 {
        x = xscale * (-x - xshift);
        y *= yscale;
        c = (c + xcolorshift) % 1.0;
    }
    if yaxis > 0.0 && rng.f01() < 0.5 {
        x *= xscale;
        y = yscale * (-y - yshift);
        c = (c + ycolorshift) % 1.0;
    }
    if zaxis > 0.0 && rng.f01() < 0.5 {
        z = -z - zshift;
        c = (c + zcolorshift) % 1.0;
    }
    acc.color = c;
    [x, y, z]
}

// JWildfire rounds π to 6 decimals here; kept so that the star's edges agree.
#[allow(clippy::approx_constant)]
fn crop_stars_prepare(v: &mut Prepared) {
    let [radius, n, r2] = v.params();
    // Inner angle of a sector and the star's external angle; JWildfire uses 6-digit π here.
    let an = 3.141593 / n;
    let m = 4.0 + r2 * r2 * (n * 2.0 - 4.0);
    let en = 6.283185 / m;
    let (asin, acos) = an.sin_cos();
    let (esin, ecos) = en.sin_cos();
    v.p.extend_from_slice(&[an, acos, asin, ecos, esin, radius * asin / esin]);
}

/// crop_stars: keeps the points inside a star (n points, outer radius `radius`, inner angle set
/// by r2) and sends the others to the origin (`invert` swaps inside and outside). It replaces
/// the xform's sum so far, as JWildfire's crop variations do.
fn crop_stars(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [radius, _, _, invert] = v.params();
    let [an, acos, asin, ecos, esin, kmax] = v.derived();
    // Signed distance to the star, computed in its first sector.
    let a = atan2_approx(t.x, t.y);
    let period = 2.0 * an;
    let bn = a - period * (a / period).floor() - an;
    let len = (t.x * t.x + t.y * t.y).sqrt();
    let (sb, cb) = bn.sin_cos();
    let mut px = cb * len - acos * radius;
    let mut py = sb.abs() * len - asin * radius;
    let k = (-(px * ecos + py * esin)).max(0.0).min(kmax);
    px += ecos * k;
    py += esin * k;
    let d = (px * px + py * py).sqrt() * signum_java(px);
    // Hidden (d > 0) outside, or (d <= 0) inside when inverted; NaN is kept.
    let keep = if invert == 0.0 {
        d.is_nan() || d <= 0.0
    } else {
        d.is_nan() || d > 0.0
    };
    acc.x = 0.0;
    acc.y = 0.0;
    if keep {
        [v.w * t.x, v.w * t.y, 0.0]
    } else {
        // The orbit goes on from the origin; the sample is not drawn.
        acc.hide = true;
        [0.0, 0.0, 0.0]
    }
}

/// svensson_js: one step of Johnny Svensson's attractor map,
/// (d·sin(a·x) − sin(b·y), c·cos(a·x) + cos(b·y)). Like JWildfire it replaces (rather than
/// adds to) the x and y its xform's earlier variations summed.
fn svensson_js(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c, d] = v.params();
    let x = d * (a * t.x).sin() - (b * t.y).sin();
    let y = c * (a * t.x).cos() + (b * t.y).cos();
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [x * v.w, y * v.w, 0.0]
}

const P_SVENSSON: &[Param] = &[
    p("svensson_js_a", 1.4),
    p("svensson_js_b", 1.56),
    p("svensson_js_c", 1.4),
    p("svensson_js_d", -6.56),
];

#[cfg(test)]
mod tests;
