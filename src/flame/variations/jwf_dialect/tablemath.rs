//! JWildfire's formulas for names of flam3's and Fractorium's catalogues whose JWildfire
//! results depend on JWildfire's own maths: its table-based sin, cos, acos, √, sinh, cosh, …
//! (`util::jwf_math`, `FAST_MATH`), its `java.lang.Math.atan2` (fdlibm's, as the `libm` crate gives it),
//! and its unguarded singular points. Near the foci of elliptic coordinates, or at the origin,
//! a few ulps of those functions change the result in its leading digits, so these twins use
//! exactly JWildfire's functions. Each reads its registry entry's parameters (see
//! [`super::FORMULAS`]).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{FRAC_1_PI, PI, TAU};

use crate::flame::variations::util::jwf_math as jm;
use crate::flame::variations::util::rand_size;
use crate::flame::variations::*;

/// √x, 0 for x ≤ 0 (the `sqrt_safe` of JWildfire's e-series).
fn sqrt_safe(x: f64) -> f64 {
    if x <= 0.0 { 0.0 } else { jm::sqrt(x) }
}

/// JWildfire's `MathLib.acosh`: ln(√(d² − 1) + d).
fn acosh(d: f64) -> f64 {
    (jm::sqrt(jm::pow(d, 2.0) - 1.0) + d).ln()
}

/// Elliptic coordinates as JWildfire's e-series computes them: the half sum of the distances
/// to the foci (at least 1), and the angle ν = acos(x/that) (in [0, π]).
fn elliptic(x: f64, y: f64) -> (f64, f64) {
    let s = y * y + x * x + 1.0;
    let d = 2.0 * x;
    let mut xmax = (sqrt_safe(s + d) + sqrt_safe(s - d)) * 0.5;
    if xmax < 1.0 {
        xmax = 1.0;
    }
    (xmax, jm::acos((x / xmax).clamp(-1.0, 1.0)))
}

/// The point of elliptic coordinates (μ, ν), weighted.
fn from_elliptic(w: f64, mu: f64, nu: f64) -> V3 {
    [
        w * jm::cosh(mu) * jm::cos(nu),
        w * jm::sinh(mu) * jm::sin(nu),
        0.0,
    ]
}

/// eCollide: ν cut into `num` sectors and shifted within each, alternately forwards and
/// backwards. Derived values: num/π, π/num, π·a/num.
pub(super) fn e_collide(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cn_pi, pi_cn, ca_cn] = v.derived();
    let (xmax, mut nu) = elliptic(t.x, t.y);
    let sector = (nu * cn_pi) as i32;
    nu = if sector % 2 == 0 {
        f64::from(sector) * pi_cn + (nu + ca_cn) % pi_cn
    } else {
        f64::from(sector) * pi_cn + (nu - ca_cn) % pi_cn
    };
    if t.y <= 0.0 {
        nu = -nu;
    }
    [
        v.w * xmax * jm::cos(nu),
        v.w * jm::sqrt(xmax - 1.0) * jm::sqrt(xmax + 1.0) * jm::sin(nu),
        0.0,
    ]
}

/// eMod: μ wrapped into [−radius, radius) after a shift of `distance`·radius.
pub(super) fn e_mod(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [radius, distance] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.y);
    let mut mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    if mu < radius && -mu < radius {
        mu = if nu > 0.0 {
            (mu + radius + distance * radius) % (2.0 * radius) - radius
        } else {
            (mu - radius - distance * radius) % (2.0 * radius) + radius
        };
    }
    from_elliptic(v.w, mu, nu)
}

/// eMotion: μ moved by `move` (with the side of ν), reflected through the focal segment when
/// it crosses it, then ν rotated.
pub(super) fn e_motion(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [mv, rot] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.y);
    let mut mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    if nu < 0.0 {
        mu += mv;
    } else {
        mu -= mv;
    }
    if mu <= 0.0 {
        mu = -mu;
        nu = -nu;
    }
    from_elliptic(v.w, mu, nu + rot)
}

/// ePush: μ scaled by `dist` and pushed by `push`, ν rotated.
pub(super) fn e_push(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [push, dist, rot] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.y);
    let mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    from_elliptic(v.w, mu * dist + push, nu + rot)
}

/// eRotate: ν rotated (wrapped to [−π, π)), the confocal ellipse kept.
pub(super) fn e_rotate(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [rot] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.y);
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = (nu + rot + PI) % TAU - PI;
    [
        v.w * xmax * jm::cos(nu),
        v.w * jm::sqrt(xmax - 1.0) * jm::sqrt(xmax + 1.0) * jm::sin(nu),
        0.0,
    ]
}

/// eScale: μ and ν scaled by `scale` (ν about `angle`, wrapped).
pub(super) fn e_scale(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scale, angle] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.y);
    let mu = acosh(xmax) * scale;
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = ((scale * (nu + PI + angle)) % (TAU * scale) - angle - scale * PI) % TAU;
    if nu > PI {
        nu -= TAU;
    }
    if nu < -PI {
        nu += TAU;
    }
    from_elliptic(v.w, mu, nu)
}

/// eSwirl: ν twisted by `out`·μ + `in`/μ (JWildfire keeps the half sum of distances ≥ 1).
pub(super) fn e_swirl(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [win, wout] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.y);
    let mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = nu + mu * wout + win / mu;
    from_elliptic(v.w, mu, nu)
}

/// edisc: the elliptic coordinates read as the angle and the hyperbolic angle of a disc, with
/// JWildfire's weight divisor 11.57034632 and no guard at the foci.
pub(super) fn edisc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let s = t.x * t.x + t.y * t.y + 1.0;
    let d = 2.0 * t.x;
    let xmax = (jm::sqrt(s + d) + jm::sqrt(s - d)) * 0.5;
    let a1 = (xmax + jm::sqrt(xmax - 1.0)).ln();
    let a2 = -jm::acos(t.x / xmax);
    let w = v.w / 11.57034632;
    let mut snv = jm::sin(a1);
    if t.y > 0.0 {
        snv = -snv;
    }
    [w * jm::cosh(a2) * jm::cos(a1), w * jm::sinh(a2) * snv, 0.0]
}

/// 2/π as JWildfire's `M_2_PI` (2.0/Math.PI).
const M_2_PI: f64 = 2.0 / PI;

/// JWildfire's `Complex.MagInv`: 1/|z|², or 1 when |z|² < 1e-100.
fn mag_inv(re: f64, im: f64) -> f64 {
    let m2 = re * re + im * im;
    if m2 < 1e-100 { 1.0 } else { 1.0 / m2 }
}

/// JWildfire's `Complex.Log`: ½·ln(|z|² + 1e-20) and the argument (Java's atan2, plus a zero
/// period term, so that −0 reads +0).
fn c_log(re: f64, im: f64) -> (f64, f64) {
    let arg = libm::atan2(im, re);
    (
        0.5 * (re * re + im * im + 1e-20).ln(),
        if arg == 0.0 { 0.0 } else { arg },
    )
}

/// JWildfire's `Complex.Sqrt`: the principal root, from Jafama's hypot and Java's √.
fn c_sqrt(re: f64, im: f64) -> (f64, f64) {
    let rad = jm::hypot(re, im);
    let sb = if im < 0.0 { -1.0 } else { 1.0 };
    ((0.5 * (rad + re)).sqrt(), sb * (0.5 * (rad - re)).sqrt())
}

/// JWildfire's `Complex.Mul` (a real factor scales).
fn c_mul(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    if b.1 == 0.0 {
        (a.0 * b.0, a.1 * b.0)
    } else {
        (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0)
    }
}

/// arcsech2: the inverse hyperbolic secant ln(1/z + √(1/z − 1)·√(1/z + 1)), scaled by 2/π, its
/// two branches shifted by ∓1 (JWildfire's guarded reciprocal and logarithm).
pub(super) fn arcsech2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let mi = mag_inv(t.x, t.y);
    let z = (t.x * mi, -t.y * mi);
    let dec = c_sqrt(z.0 - 1.0, z.1);
    let inc = c_sqrt(z.0 + 1.0, z.1);
    let m = c_mul(inc, dec);
    let (lr, li) = c_log(z.0 + m.0, z.1 + m.1);
    let k = v.w * 2.0 * FRAC_1_PI;
    let (re, im) = (lr * k, li * k);
    if im < 0.0 {
        [re, im + 1.0, 0.0]
    } else {
        [-re, im - 1.0, 0.0]
    }
}

/// arctanh: ½·ln((1 + z)/(1 − z)) scaled by 2/π, with JWildfire's guarded division and
/// logarithm.
pub(super) fn arctanh(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (x, y) = (t.x, t.y);
    let (dr, di) = (-x + 1.0, -y);
    let (nr, ni) = (x + 1.0, y);
    let m = mag_inv(dr, di);
    let q = ((ni * di + nr * dr) * m, (ni * dr - nr * di) * m);
    let (lr, li) = c_log(q.0, q.1);
    let k = v.w * M_2_PI;
    [lr * k, li * k, 0.0]
}

/// Derived values of JWildfire's x, y and z: √(1 + hypergon_r²), tan(star_slope), −lituus_a,
/// super_m/4, −1/(super_n1 + 1e-300).
pub(super) fn shape_prep(v: &mut Prepared) {
    let [
        _,
        _,
        hypergon_r,
        _,
        _,
        slope,
        _,
        lituus_a,
        _,
        super_m,
        super_n1,
        _,
        _,
    ] = v.params::<13>();
    v.p.extend_from_slice(&[
        jm::sqrt(1.0 + hypergon_r * hypergon_r),
        jm::tan(slope),
        -lituus_a,
        super_m / 4.0,
        -1.0 / (super_n1 + 1e-300),
    ]);
}

/// The shape profile of JWildfire's x, y and z at the angle `a`: the sum of the hypergon,
/// star, lituus and superformula radii that are switched on.
fn shape_total(v: &Prepared, a: f64) -> f64 {
    let [
        hypergon,
        hypergon_n,
        _,
        star,
        star_n,
        _,
        lituus,
        _,
        super_,
        _,
        _,
        n2,
        n3,
    ] = v.params::<13>();
    let [hyper_d, tan_slope, lituus_exp, super_m4, super_exp] = v.derived();
    let mut total = 0.0;
    if hypergon != 0.0 {
        let t1 = a.abs() % (TAU / hypergon_n) - PI / hypergon_n;
        let tn = jm::tan(t1);
        let t2 = tn * tn + 1.0;
        if t2 >= hyper_d * hyper_d {
            total += hypergon;
        } else {
            total += hypergon * (hyper_d - jm::sqrt(hyper_d * hyper_d - t2)) / jm::sqrt(t2);
        }
    }
    if star != 0.0 {
        let t1 = jm::tan((a.abs() % (TAU / star_n) - PI / star_n).abs());
        let s2 = tan_slope * tan_slope;
        total += star * jm::sqrt(s2 * (1.0 + t1 * t1) / ((t1 + tan_slope) * (t1 + tan_slope)));
    }
    if lituus != 0.0 {
        total += lituus * jm::pow(a / PI + 1.0, lituus_exp);
    }
    if super_ != 0.0 {
        let ang = a * super_m4;
        let (s, c) = (jm::sin(ang), jm::cos(ang));
        total += super_ * jm::pow(jm::pow(c.abs(), n2) + jm::pow(s.abs(), n3), super_exp);
    }
    total
}

/// The radius `r` along the angle of (x, y) (JWildfire's atan2, so the origin has angle 0).
fn along(t: &VarIn, r: impl Fn(f64) -> f64) -> V3 {
    let a = jm::atan2(t.y, t.x);
    let r = r(a);
    [r * jm::cos(a), r * jm::sin(a), 0.0]
}

/// x: the radius pushed out to √(r² + profile²) along each ray.
pub(super) fn x_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    along(t, |a| {
        let total = shape_total(v, a);
        v.w * jm::sqrt(t.x * t.x + t.y * t.y + total * total)
    })
}

/// y: the shape profile squared over the radius, along each ray.
pub(super) fn y_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    along(t, |a| {
        let total = shape_total(v, a);
        v.w * (total * total) / jm::sqrt(t.x * t.x + t.y * t.y)
    })
}

/// z: the radius increased by the shape profile, along each ray.
pub(super) fn z_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    along(t, |a| {
        v.w * (jm::sqrt(t.x * t.x + t.y * t.y) + shape_total(v, a))
    })
}

/// rays3: rays from the axes, r²/x and r²/y modulated by cos(r²) and tan(r²) and a factor built
/// from r⁴; replaces the x and y summed so far. Unguarded (NaN or ±∞ at the origin and on the
/// axes, as JWildfire's).
pub(super) fn rays3(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = t.x * t.x + t.y * t.y;
    let r4 = r2 * r2;
    let u = 1.0 / jm::sqrt(jm::cos(jm::sin(r4 + 1e-300) * jm::sin(1.0 / r4 + 1e-300)));
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    let k = v.w / 10.0;
    [
        k * u * jm::cos(r2) * r2 / t.x,
        k * u * jm::tan(r2) * r2 / t.y,
        0.0,
    ]
}

/// d_spherical: spherical (unguarded: NaN at the origin) with probability `weight`, else
/// linear.
pub(super) fn d_spherical(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [weight] = v.params();
    if rng.f01() < weight {
        let r = v.w / (t.x * t.x + t.y * t.y);
        [t.x * r, t.y * r, 0.0]
    } else {
        [t.x * v.w, t.y * v.w, 0.0]
    }
}

/// hypershift2: a hyperbolic {p, q} tiling step (a shift of the inverted, scaled point, then
/// a rotation by a random odd multiple of π/p), unguarded: NaN at the origin.
pub(super) fn hypershift2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [p_, q_] = v.params();
    let pq = PI / q_;
    let pp = PI / p_;
    let spq = jm::sin(pq);
    let spp = jm::sin(pp);
    let shift = jm::sin(PI * 0.5 - pq - pp) / jm::sqrt(1.0 - spq * spq - spp * spp);
    let lean = jm::sin(PI / 2.0 + pp);
    let scale2 = (1.0 / jm::sqrt(lean * lean / (spq * spq) - 1.0)) * (lean / spq - 1.0);
    let scale = 1.0 - shift * shift;
    let fx = t.x * scale2;
    let fy = t.y * scale2;
    let inv = 1.0 / (fx * fx + fy * fy);
    let x = inv * fx + shift;
    let y = inv * fy;
    let k = v.w * scale / (x * x + y * y);
    let ang = (rng.f01() * p_).floor() * 2.0 + 1.0;
    let ang = ang * PI / p_;
    let bx = k * x + shift;
    let by = k * y;
    let (ca, sa) = (jm::cos(ang), jm::sin(ang));
    if v.compat && v.form == Form::Regular {
        *acc = Acc {
            color: acc.color,
            ..Acc::default()
        };
    }
    [ca * bx - sa * by, sa * bx + ca * by, t.z * k]
}

/// lazyjess: inside the regular n-gon of radius w the point is spun by `spin` (corners that
/// leave it folded back, turned by `corner`); outside it moves out by `space`.
pub(super) fn lazyjess(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [n, spin, space, corner] = v.params();
    let n = n.max(2.0);
    let vertex = PI * (n - 2.0) / (2.0 * n);
    let sin_vertex = jm::sin(vertex);
    let slice = TAU / n;
    let half_slice = slice / 2.0;
    let corner_turn = (corner - 1.0) * slice;
    let w = v.w;
    let (x, y) = (t.x, t.y);
    let m = jm::sqrt(x * x + y * y);
    let push_out = || {
        let k = 1.0 + space / m;
        [w * k * x, w * k * y, 0.0]
    };
    let edge_at = |ang: f64| {
        let off = (ang + half_slice) % slice;
        w * std::f64::consts::SQRT_2 * sin_vertex / jm::sin(PI - off - vertex)
    };
    if n == 2.0 {
        if x.abs() < w {
            let ang = jm::atan2(y, x) + spin;
            let (rx, ry) = (w * m * jm::cos(ang), w * m * jm::sin(ang));
            if rx.abs() < w {
                return [rx, ry, 0.0];
            }
            let back = jm::atan2(ry, rx) - spin + corner_turn;
            return [w * m * jm::cos(back), -(w * m * jm::sin(back)), 0.0];
        }
        return push_out();
    }
    if m < edge_at(jm::atan2(y, x) + TAU) {
        let ang = jm::atan2(y, x) + spin + TAU;
        let (rx, ry) = (w * m * jm::cos(ang), w * m * jm::sin(ang));
        let m2 = jm::sqrt(rx * rx + ry * ry);
        if m2 < edge_at(ang) {
            return [rx, ry, 0.0];
        }
        let back = jm::atan2(ry, rx) - spin + corner_turn + TAU;
        return [w * m2 * jm::cos(back), -(w * m2 * jm::sin(back)), 0.0];
    }
    push_out()
}

/// npolar: with odd parity a julian-style n-th root; with even parity the same root of the
/// point's log-polar image, mapped back through the log-polar map. Derived values: n (1 for
/// 0), w/π, w/2π, |n|, 1/2n, |parity| mod 2.
pub(super) fn npolar(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [parity] = v.params();
    let [nnz, vvar, vvar2, abs_n, cn, odd] = v.derived();
    let odd = odd != 0.0;
    let (x, y) = if odd {
        (t.x, t.y)
    } else {
        (
            vvar * jm::atan2(t.x, t.y),
            vvar2 * (t.x * t.x + t.y * t.y).ln(),
        )
    };
    let angle = (jm::atan2(y, x) + TAU * rand_size(rng, abs_n)) / nnz;
    let r = v.w * jm::pow(x * x + y * y, cn) * if odd { parity } else { 1.0 };
    let s = jm::sin(angle) * r;
    let c = jm::cos(angle) * r;
    if odd {
        [c, s, 0.0]
    } else {
        [vvar2 * (c * c + s * s).ln(), vvar * jm::atan2(c, s), 0.0]
    }
}

/// One ortho step: (x, y) moved by `turn` along the circle of centre (xo, 0) orthogonal to the
/// unit circle.
fn ortho_step(x: f64, y: f64, xo: f64, turn: f64) -> (f64, f64) {
    let ro = jm::sqrt((x - xo) * (x - xo) + y * y);
    let theta = jm::atan2(1.0, ro);
    let a = (turn * theta + jm::atan2(y, xo - x) + theta) % (2.0 * theta) - theta;
    (xo - jm::cos(a) * ro, jm::sin(a) * ro)
}

/// ortho: moves points along circles orthogonal to the unit circle (by `in` inside the disc,
/// by `out` for the inverted image of outside points), unguarded: NaN at the origin.
pub(super) fn ortho(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [turn_in, turn_out] = v.params();
    let w = v.w;
    let r = t.x * t.x + t.y * t.y;
    if r < 1.0 {
        if t.x >= 0.0 {
            let xo = (r + 1.0) / (2.0 * t.x);
            let (nx, ny) = ortho_step(t.x, t.y, xo, turn_in);
            [w * nx, w * ny, 0.0]
        } else {
            let xo = -(r + 1.0) / (2.0 * t.x);
            let (nx, ny) = ortho_step(-t.x, t.y, xo, turn_in);
            [-(w * nx), w * ny, 0.0]
        }
    } else {
        let inv = 1.0 / jm::sqrt(r);
        let ta = jm::atan2(t.y, t.x);
        let x = inv * jm::cos(ta);
        let y = inv * jm::sin(ta);
        let mirrored = x < 0.0;
        let xo = (x * x + y * y + 1.0) / (2.0 * x);
        let (nx, ny) = if mirrored {
            ortho_step(-x, y, -xo, turn_out)
        } else {
            ortho_step(x, y, xo, turn_out)
        };
        let ang = jm::atan2(ny, nx);
        let k = 1.0 / jm::sqrt(nx * nx + ny * ny);
        let ox = w * k * jm::cos(ang);
        [if mirrored { -ox } else { ox }, w * k * jm::sin(ang), 0.0]
    }
}

/// rays: the point thrown along a random tangent, scaled by the inverse of its squared
/// distance, where JWildfire adds only `SMALL_EPSILON` (1e-300) to that distance (flam3 adds
/// 1e-10), so near the origin its rays reach much further (JWildfire 9.00, `RaysFunc`).
pub(super) fn rays(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let w = v.w;
    let ang = w * rng.f01() * PI;
    let r = w / (t.x * t.x + t.y * t.y + super::SMALL_EPSILON);
    let tanr = w * jm::tan(ang) * r;
    [tanr * jm::cos(t.x), tanr * jm::sin(t.y), 0.0]
}
