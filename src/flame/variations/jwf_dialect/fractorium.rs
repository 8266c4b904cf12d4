//! JWildfire's formulas for names of Fractorium's catalogue, where they differ from
//! Fractorium's. Each reads the registry entry's parameters and derived values (the twin is
//! that entry with this formula, see [`super::FORMULAS`]).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{PI, TAU};

use crate::flame::variations::util::mix;
use crate::flame::variations::*;
use crate::flame::variations::{fr_crops, fr_radial};

/// Zueuk's cpow3 as JWildfire computes it: the root of the divisor is ⌊divisor·ξ⌋ (Fractorium
/// draws an integer below 32767), the branch of the logarithm rounds as Java does (⌊x + ½⌋).
/// Reads the registry's derived values.
pub(super) fn cpow3(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, divisor, _] = v.params();
    let [c, d, half_c, half_d, ang, coeff] = v.derived();
    let mut a = t.atan_yx;
    if a < 0.0 {
        a += TAU;
    }
    if (a / 2.0).cos() < rng.f01() * 2.0 - 1.0 {
        a -= TAU;
    }
    let turn = if rng.f01() < 0.5 { TAU } else { -TAU };
    a += turn * (rng.f01().ln() * coeff + 0.5).floor();
    let lnr2 = t.sumsq.ln();
    let r = v.w * (half_c * lnr2 - d * a).exp();
    let th = c * a + half_d * lnr2 + ang * (divisor * rng.f01()).floor();
    let (s, c) = th.sin_cos();
    [r * c, r * s, 0.0]
}

/// JWildfire's `lgamma`: Numerical Recipes' `gammln` series evaluated at x itself (not at
/// x − 1), so it is ln Γ(x + 1), with the series' ~1e-10 accuracy.
fn jwf_lgamma(x: f64) -> f64 {
    let tmp = (x - 0.5) * (x + 4.5).ln() - (x + 4.5);
    let ser = 1.0 + 76.18009173 / x - 86.50532033 / (x + 1.0) + 24.01409822 / (x + 2.0)
        - 1.231739516 / (x + 3.0)
        + 0.00120858003 / (x + 4.0)
        - 0.00000536382 / (x + 5.0);
    tmp + (ser * (2.0 * PI).sqrt()).ln()
}

/// zephyrtronium's gamma as JWildfire computes it: (lgamma(r), θ) with JWildfire's `lgamma`
/// (ln Γ(r + 1), see [`jwf_lgamma`]).
pub(super) fn gamma(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let r = t.y.hypot(t.x);
    [v.w * jwf_lgamma(r), v.w * t.y.atan2(t.x), 0.0]
}

/// Raykoid666's squirrel as JWildfire computes it: 1e-8 added to a and b, and the x and y
/// summed so far replaced (the formula assigns them).
pub(super) fn squirrel(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b] = v.params();
    const EPSILON: f64 = 1e-8;
    let u = ((a + EPSILON) * (t.x * t.x) + (b + EPSILON) * (t.y * t.y)).sqrt();
    replace_sum(v, acc);
    [u.cos() * t.x.tan() * v.w, u.sin() * t.y.tan() * v.w, 0.0]
}

/// Keeps' and Xyrus02's checks as JWildfire computes it: cells of side size + 1e-8, the even
/// cells (of the sum of the rounded cell indices, rounded half to even as Java's `rint`)
/// moved by −(x, y) and a random jitter in x, the odd ones by (x, y) and a jitter in y; no z.
pub(super) fn checks(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ox, oy, size, rnd] = v.params();
    let cs = 1.0 / (size + 1e-8);
    // Java's (int) of rint: saturating, NaN to 0.
    let cell = |c: f64| (c * cs).round_ties_even() as i32;
    let parity = cell(t.x).wrapping_add(cell(t.y));
    let jx = rnd * rng.f01();
    let jy = rnd * rng.f01();
    let (dx, dy) = if parity % 2 == 0 {
        (-ox + jx, -oy)
    } else {
        (ox, oy + jy)
    };
    [v.w * (t.x + dx), v.w * (t.y + dy), 0.0]
}

/// Xyrus02's julian3Dx as JWildfire computes it: its "z" is the input x over |power| (not the
/// input z). Reads the registry's derived |power| and exponent.
pub(super) fn julian3dx(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, power, a, b, c, d, e, f] = v.params();
    let [abs_n, exponent] = v.derived();
    let z = t.x / abs_n;
    let r2 = t.x * t.x + t.y * t.y;
    let radius = v.w * (r2 + z * z).powf(exponent);
    let x = a * t.x + b * t.y + e;
    let y = c * t.x + d * t.y + f;
    let branch = ((rng.f01() * abs_n) as i32) as f64;
    let ang = (y.atan2(x) + TAU * branch) / power;
    let planar = radius * r2.sqrt();
    [planar * ang.cos(), planar * ang.sin(), radius * z]
}

/// JWildfire's `random(Integer.MAX_VALUE)`: a whole number below 2³¹ − 1.
fn jwf_random_int(rng: &mut FastRng) -> f64 {
    const MAX: f64 = i32::MAX as f64;
    (rng.f01() * MAX).trunc().min(MAX - 1.0)
}

/// The hyperbolic tiling map of the ball towards (cx, cy), as Zueuk's hypertile3D family
/// computes it in JWildfire: r² of the three coordinates (Fractorium's hypertile3D adds z, not
/// z²), no guard on the denominator.
#[inline(always)]
fn hypertile3d_map(w: f64, t: &VarIn, c: [f64; 2], c2: f64, s2: [f64; 3]) -> V3 {
    let [cx, cy] = c;
    let r2 = t.x * t.x + t.y * t.y + t.z * t.z;
    let x2cx = 2.0 * cx * t.x;
    let y2cy = 2.0 * cy * t.y;
    let d = w / (c2 * r2 + x2cx - y2cy + 1.0);
    [
        d * (t.x * s2[0] - cx * (y2cy - r2 - 1.0)),
        d * (t.y * s2[1] + cy * (-x2cx - r2 - 1.0)),
        d * (t.z * s2[2]),
    ]
}

/// hypertile3D as JWildfire computes it (see [`hypertile3d_map`]). Reads the registry's
/// derived centre and factors.
pub(super) fn hypertile3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cx, cy, c2, _, _, s2x, s2y, s2z] = v.derived();
    hypertile3d_map(v.w, t, [cx, cy], c2, [s2x, s2y, s2z])
}

/// hypertile3D1 as JWildfire computes it: towards the vertex at angle k·2π/p for a whole k
/// below 2³¹ − 1, as JWildfire draws it (so the angle carries the rounding of a large k).
pub(super) fn hypertile3d1(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, r, c2, s2z] = v.derived();
    let (sa, ca) = (jwf_random_int(rng) * pa).sin_cos();
    let (cx, cy) = (r * ca, r * sa);
    let s2x = 1.0 + cx * cx - cy * cy;
    let s2y = 1.0 + cy * cy - cx * cx;
    hypertile3d_map(v.w, t, [cx, cy], c2, [s2x, s2y, s2z])
}

/// hypertile3D2 as JWildfire computes it: towards the first vertex, then turned by k·2π/p for
/// a whole k below 2³¹ − 1 (drawn after the map, as JWildfire does).
pub(super) fn hypertile3d2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, cx, c2, s2z, c2x, s2x] = v.derived();
    let r2 = t.x * t.x + t.y * t.y + t.z * t.z;
    let x = t.x * s2x - cx * (-r2 - 1.0);
    let y = t.y * s2z;
    let k = v.w / (c2 * r2 + c2x * t.x + 1.0);
    let (sa, ca) = (jwf_random_int(rng) * pa).sin_cos();
    [
        k * (x * ca + y * sa),
        k * (y * ca - x * sa),
        k * (t.z * s2z),
    ]
}

/// Xyrus02's crop as JWildfire computes it: the point replaces the sum so far (rather than
/// adding to it); outside the rectangle with `zero` the point is hidden, else it is shown.
/// Reads the registry's derived corners and sizes.
pub(super) fn crop(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, zero] = v.params();
    let [x0, y0, x1, y1, w, h] = v.derived();
    let (x, y) = (t.x, t.y);
    acc.x = 0.0;
    acc.y = 0.0;
    if (x < x0 || x > x1 || y < y0 || y > y1) && zero != 0.0 {
        acc.hide = true;
        return [0.0; 3];
    }
    acc.hide = false;
    let (x, y) = fr_crops::pull_inside(x, y, [x0, y0, x1, y1, w, h], rng);
    [v.w * x, v.w * y, 0.0]
}

/// The radius from (r² + δ) rather than (r + δ), δ = (θ/π + 1)^a, along the polar angle.
pub(super) fn hole(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, inside] = v.params();
    let alpha = t.y.atan2(t.x);
    let delta = (alpha / PI + 1.0).powf(a);
    let r2 = t.x * t.x + t.y * t.y;
    let r = if inside != 0.0 {
        v.w * delta / (r2 + delta)
    } else {
        v.w * (r2 + delta).sqrt()
    };
    let (s, c) = alpha.sin_cos();
    [r * c, r * s, 0.0]
}

/// Will Evans's kaleidoscope with JWildfire's angle: 45 radians (not degrees).
pub(super) fn kaleidoscope(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (s45, c45) = 45f64.sin_cos();
    fr_radial::kaleidoscope_turned(v, t, s45, c45)
}

/// Zy0rg's tile_log with Java's rounding (⌊x + ½⌋) and the weighted z carried along.
pub(super) fn tile_log(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [spread] = v.params();
    let s = if rng.f01() < 0.5 { spread } else { -spread };
    let shift = (s * rng.f01().ln() + 0.5).floor();
    [v.w * (t.x + shift), v.w * t.y, v.w * t.z]
}

/// The Apophysis plug-in's boarders with Java's rounding (half to even); at a cell centre the
/// slope 0/0 gives NaN, as in JWildfire.
pub(super) fn boarders(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let (rx, ry) = (t.x.round_ties_even(), t.y.round_ties_even());
    let (ox, oy) = (t.x - rx, t.y - ry);
    let w = v.w;
    if rng.f01() >= 0.75 {
        return [w * (ox * 0.5 + rx), w * (oy * 0.5 + ry), 0.0];
    }
    if ox.abs() >= oy.abs() {
        let q = if ox >= 0.0 { 0.25 } else { -0.25 };
        [
            w * (ox * 0.5 + rx + q),
            w * (oy * 0.5 + ry + q * oy / ox),
            0.0,
        ]
    } else {
        let q = if oy >= 0.0 { 0.25 } else { -0.25 };
        [
            w * (ox * 0.5 + rx + ox / oy * q),
            w * (oy * 0.5 + ry + q),
            0.0,
        ]
    }
}

/// sintrange: Fractorium's formula, but it replaces the x and y summed so far (JWildfire
/// assigns them) in the regular form.
pub(super) fn sintrange(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.params();
    let (xx, yy) = (t.x * t.x, t.y * t.y);
    let m = (xx + yy) * k;
    replace_sum(v, acc);
    [
        v.w * t.x.sin() * (xx + k - m),
        v.w * t.y.sin() * (yy + k - m),
        0.0,
    ]
}

/// ennepers: Fractorium's formula, replacing the x and y summed so far in the regular form.
pub(super) fn ennepers(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let (x2, y2) = (t.x * t.x, t.y * t.y);
    replace_sum(v, acc);
    [
        v.w * (t.x - ((x2 * t.x) / 3.0)) + t.x * y2,
        v.w * (t.y - ((y2 * t.y) / 3.0)) + t.y * x2,
        0.0,
    ]
}

/// shredlin: Fractorium's strips (reading the registry's derived w·distances and gaps),
/// replacing the x and y summed so far in the regular form; no z.
pub(super) fn shredlin(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [xdistance, xwidth, ydistance, ywidth] = v.params();
    let [xw, yw, gx, gy] = v.derived();
    let strip = |c: f64, dist: f64, width: f64, gap: f64| {
        let neg = if c < 0.0 { 1.0 } else { 0.0 };
        let u = c / dist;
        let i = u.trunc();
        (u - i) * width + i + (0.5 - neg) * gap
    };
    replace_sum(v, acc);
    [
        xw * strip(t.x, xdistance, xwidth, gx),
        yw * strip(t.y, ydistance, ywidth, gy),
        0.0,
    ]
}

/// In the regular form, clears the x and y summed so far (the formula assigns them).
fn replace_sum(v: &Prepared, acc: &mut Acc) {
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
}

/// sinusgrid: Fractorium's grid (reading the registry's derived 2π·frequencies), with z
/// weighted as JWildfire always carries it.
pub(super) fn sinusgrid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [ax, ay] = v.params();
    let [fx, fy] = v.derived();
    let sx = -(t.x * fx).cos();
    let sy = -(t.y * fy).cos();
    [v.w * mix(t.x, sx, ax), v.w * mix(t.y, sy, ay), v.w * t.z]
}

/// erf: the error function of x and y in JWildfire's approximation (Numerical Recipes').
pub(super) fn erf(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    use crate::flame::variations::jwf_a_surfaces::erf_nr;
    [erf_nr(t.x) * v.w, erf_nr(t.y) * v.w, 0.0]
}

/// xerf: each coordinate's error function (JWildfire's approximation) below 2 in size, the
/// coordinate over r² (r² at least 1e-300) from 2 on.
pub(super) fn xerf(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    use crate::flame::variations::jwf_a_surfaces::erf_nr;
    let r2 = (t.x * t.x + t.y * t.y + t.z * t.z).max(super::SMALL_EPSILON);
    let f = |c: f64| if c.abs() >= 2.0 { c / r2 } else { erf_nr(c) };
    [f(t.x) * v.w, f(t.y) * v.w, f(t.z) * v.w]
}

/// waves2b: Fractorium's waves2b with JWildfire's numbers: the power taken of |u| + 1e-10
/// (sign +1 at 0), the fall-off's quotient inverted below 1e-10, and its faster Jacobi sn
/// (at most 8 Landen steps, tolerance 3e-4).
pub(super) fn waves2b(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [freqx, freqy, pwx, pwy, _, sinfx, _, sinfy, unity, jacok] = v.params();
    let [six, siy] = v.derived();
    let safediv = |q: f64, r: f64| if r < 1e-10 { 1.0 / r } else { q / r };
    let csx = safediv(unity, unity + t.x * t.x) * six + sinfx;
    let csy = safediv(unity, unity + t.y * t.y) * siy + sinfy;
    let wave = |u: f64, pw: f64, freq: f64| -> f64 {
        if (0.0..1e-4).contains(&pw) {
            jacobi_sn_fast(u * freq, jacok)
        } else if pw < 0.0 && pw > -1e-4 {
            crate::flame::variations::util::bessel_j1(u * freq)
        } else {
            let sgn = if u < 0.0 { -1.0 } else { 1.0 };
            (sgn * (u.abs() + 1e-10).powf(pw) * freq).sin()
        }
    };
    [
        v.w * (t.x + csx * wave(t.y, pwx, freqx)),
        v.w * (t.y + csy * wave(t.x, pwy, freqy)),
        0.0,
    ]
}

/// The Jacobi elliptic function sn(u | 1 − emc) by descending Landen transformations, cut
/// short as JWildfire's waves2b does (8 steps, relative tolerance 3e-4); tanh u for emc = 0.
fn jacobi_sn_fast(u: f64, emc: f64) -> f64 {
    const CA: f64 = 0.0003;
    if emc == 0.0 {
        return u.tanh();
    }
    let (mut emc, mut u) = (emc, u);
    let neg = emc < 0.0;
    let mut d = 0.0;
    if neg {
        d = 1.0 - emc;
        emc = -emc / d;
        d = d.sqrt();
        u *= d;
    }
    let (mut em, mut en) = ([0.0; 8], [0.0; 8]);
    let (mut a, mut c, mut dn) = (1.0, 0.0, 1.0);
    let mut l = 0;
    for i in 0..8 {
        l = i;
        em[i] = a;
        emc = emc.sqrt();
        en[i] = emc;
        c = 0.5 * (a + emc);
        if (a - emc).abs() <= CA * a {
            break;
        }
        emc *= a;
        a = c;
    }
    u *= c;
    let mut sn = u.sin();
    if sn != 0.0 {
        let mut a = u.cos() / sn;
        c *= a;
        for ii in (0..=l).rev() {
            let b = em[ii];
            a *= c;
            c *= dn;
            dn = (en[ii] + a) / (b + a);
            a = c / b;
        }
        let a = 1.0 / (c * c + 1.0).sqrt();
        sn = if sn < 0.0 { -a } else { a };
    }
    if neg { sn / d } else { sn }
}

/// JWildfire's crob: points inside the rectangle (less the blur band) are kept as they are,
/// those outside vanish (no blur) or are thrown onto the band along the rectangle's inner
/// edge; the sides are chosen by JWildfire's probabilities and intervals (|right − left|).
/// Unweighted, as in JWildfire.
pub(super) fn crob(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, ratio] = v.params();
    let [_, _, _, _, top, bottom, left, right, blur, direct] = v.derived();
    let (xint, yint) = ((right - left).abs(), (bottom - top).abs());
    let (xint2, yint2) = (xint / 2.0, yint / 2.0);
    let minint2 = if xint2 > yint2 { yint2 } else { xint2 };
    let (x0, y0) = (right - xint2, top + yint2);
    let (x0c, y0c) = if xint2 > yint2 {
        (right - minint2, y0)
    } else if xint2 < yint2 {
        (x0, top + minint2)
    } else {
        (x0, y0)
    };
    let m = if blur == 0.0 { 0.0 } else { minint2 * ratio };
    if !(t.x < left + m || t.x > right - m || t.y < top + m || t.y > bottom - m) {
        return [t.x, t.y, 0.0];
    }
    if blur == 0.0 {
        return [0.0; 3];
    }
    let prob = yint / (xint + yint);
    let comp = 1.0 - prob;
    let sec = rng.f01();
    let (mut x, mut y);
    // The cap only guards against degenerate rectangles.
    let mut tries = 0;
    if sec < prob {
        loop {
            y = top + rng.f01() * yint2;
            x = right - rng.f01().powf(direct) * ratio * minint2;
            tries += 1;
            if (y - y0c) / (x - x0c) >= -1.0 || tries > 100_000 {
                break;
            }
        }
        if sec < 0.5 * prob {
            x = left + right - x;
        }
        if sec > 0.25 * prob && sec < 0.75 * prob {
            y = bottom + top - y;
        }
    } else {
        loop {
            x = right - rng.f01() * xint2;
            y = top + rng.f01().powf(direct) * ratio * minint2;
            let grad = (y - y0c) / (x - x0c);
            tries += 1;
            if !(grad <= 0.0 && grad > -1.0) || tries > 100_000 {
                break;
            }
        }
        if sec > prob + 0.5 * comp {
            y = bottom + top - y;
        }
        if sec > prob + 0.25 * comp && sec < prob + 0.75 * comp {
            x = left + right - x;
        }
    }
    [x, y, 0.0]
}

/// JWildfire's funnel: each coordinate c through tanh(c)·(1/cos c + effect·π) — its own
/// cosine for each (Fractorium's uses cos y for both), unguarded.
pub(super) fn funnel(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [effect] = v.params();
    let f = |c: f64| c.tanh() * (1.0 / c.cos() + effect * PI);
    [v.w * f(t.x), v.w * f(t.y), 0.0]
}

/// JWildfire's ho: the powers of cos u·cos v, sin u·cos v and sin v taken as they stand
/// (negative bases keep their sign for whole exponents, NaN otherwise), where Fractorium's
/// take them of the absolute values.
pub(super) fn ho(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [px, py, pz] = v.params();
    let om_x = (t.y * t.y).atan2(t.z * t.z);
    let om_y = (t.x * t.x).atan2(t.z * t.z);
    let (su, cu) = t.x.sin_cos();
    let (sv, cv) = t.y.sin_cos();
    let (cucv, sucv) = (cu * cv, su * cv);
    let x = cucv.powf(px) + cucv * px + 0.25 * om_x;
    let y = sucv.powf(py) + sucv * py + 0.25 * om_y;
    let z = sv.powf(pz) + sv * pz;
    [v.w * x, v.w * y, v.w * z]
}
