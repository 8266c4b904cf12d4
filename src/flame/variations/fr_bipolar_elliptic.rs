//! Fractorium's variations in bipolar coordinates (`bCollide`, `bMod`, `bSwirl`, `bTransform`,
//! `deltaa`) and elliptic coordinates (`eCollide`, `eJulia`, `eMod`, `eMotion`, `ePush`,
//! `eRotate`, `eScale`, `eSwirl`, `block`, `blocky`), and the foci maps (`foci_p`, `foci_3D`).
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_1_PI, FRAC_2_PI, FRAC_PI_2, PI, TAU};

use super::util::{
    acosh, bipolar, elliptic, floor_i64, from_bipolar, from_elliptic, safe_sqrt, sqr, trunc_i32,
    zeps,
};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("bCollide", bcollide)
        .params(&[
            p_cyclic("bCollide_a", 0.0, -1.0, 1.0),
            p_range("bCollide_num", 1.0, f64::EPSILON, 2147483647.0),
        ])
        .prepare(prep_bcollide),
    super::inlined!("block", block).needs(need::SUMSQ),
    super::inlined!("blocky", blocky)
        .params(&[
            p("blocky_x", 1.0),
            p("blocky_y", 1.0),
            p_nonzero("blocky_mp", 4.0, f64::NEG_INFINITY, f64::INFINITY),
        ])
        .needs(need::SUMSQ),
    super::inlined!("bMod", bmod).params(&[
        p_range("bMod_radius", 1.0, 0.0, f64::INFINITY),
        p_cyclic("bMod_distance", 0.0, 0.0, 2.0),
    ]),
    super::inlined!("bSwirl", bswirl).params(&[p("bSwirl_in", 0.0), p("bSwirl_out", 0.0)]),
    super::inlined!("bTransform", btransform).params(&[
        p("bTransform_rotate", 0.0),
        p_nonzero("bTransform_power", 0.0, 1.0, 2147483647.0),
        p("bTransform_move", 0.0),
        p("bTransform_split", 0.0),
    ]),
    super::inlined!("deltaa", deltaa),
    super::inlined!("eCollide", e_collide)
        .params(&[
            p_cyclic("eCollide_a", 0.0, 0.0, 1.0),
            p_int("eCollide_num", 1.0, 1.0, 2147483647.0),
        ])
        .needs(need::SUMSQ)
        .prepare(e_collide_prepare),
    super::inlined!("eJulia", e_julia)
        .params(&[p_int_nonzero("eJulia_power", 2.0, NEG_INF, INF)])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM),
    super::inlined!("eMod", e_mod)
        .params(&[
            p_range("eMod_radius", 1.0, 0.0, INF),
            p_cyclic("eMod_distance", 0.0, 0.0, 2.0),
        ])
        .needs(need::SUMSQ),
    super::inlined!("eMotion", e_motion)
        .params(&[
            p("eMotion_move", 0.0),
            p_cyclic("eMotion_rotate", 0.0, 0.0, TAU),
        ])
        .needs(need::SUMSQ),
    super::inlined!("ePush", e_push)
        .params(&[
            p("ePush_push", 0.0),
            p("ePush_dist", 1.0),
            p_cyclic("ePush_rotate", 0.0, -PI, PI),
        ])
        .needs(need::SUMSQ),
    super::inlined!("eRotate", e_rotate)
        .params(&[p_cyclic("eRotate_rotate", 0.0, -PI, PI)])
        .needs(need::SUMSQ),
    super::inlined!("eScale", e_scale)
        .params(&[
            p_nonzero("eScale_scale", 1.0, 0.0, 1.0),
            p_cyclic("eScale_angle", 0.0, 0.0, TAU),
        ])
        .needs(need::SUMSQ),
    super::inlined!("eSwirl", e_swirl)
        .params(&[p("eSwirl_in", 0.0), p("eSwirl_out", 0.0)])
        .needs(need::SUMSQ),
    super::inlined!("foci_3D", foci_3d)
        .needs(need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("foci_p", foci_p).params(&[p("foci_p_c1", 0.5), p("foci_p_c2", 0.5)]),
];

/// Derived values: num/π, π/num, π·a/num.
fn prep_bcollide(v: &mut Prepared) {
    let [a, num] = v.params();
    let n = zeps(num);
    v.p.push(num * FRAC_1_PI);
    v.p.push(PI / n);
    v.p.push(PI * a / n);
}

/// Bipolar coordinates: the angle σ is cut into `num` sectors, alternately rotated by ±πa/num
/// (modulo the sector), which makes the circles through the foci collide and interleave.
#[inline(always)]
fn bcollide(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [n_pi, pi_n, a_n] = v.derived();
    let (tau, sigma) = bipolar(t.x, t.y);
    let sector = trunc_i32(sigma * n_pi);
    let shift = if sector & 1 == 0 { a_n } else { -a_n };
    let sigma = sector as f64 * pi_n + (sigma + shift) % pi_n;
    let (x, y) = from_bipolar(v.w, tau, sigma);
    [x, y, 0.0]
}

/// The coordinate a/m mapped through arcsin, where m is half the sum of the distances to
/// (±1, 0) along that axis: squares the plane into the block [−w, w]².
#[inline(always)]
fn block_axis(c: f64, sumsq: f64) -> f64 {
    let base = sumsq + 1.0;
    let m = 0.5 * ((base + 2.0 * c).sqrt() + (base - 2.0 * c).sqrt());
    let a = c / zeps(m);
    a.atan2(safe_sqrt(1.0 - a * a))
}

/// Maps the plane into a square: each coordinate becomes the arcsine of its elliptic
/// coordinate, scaled by 2w/π.
#[inline(always)]
fn block(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let k = v.w * FRAC_2_PI;
    [
        k * block_axis(t.x, t.sumsq),
        k * block_axis(t.y, t.sumsq),
        0.0,
    ]
}

/// `block` with independent x/y scales, divided by 1 + (cos x + cos y)/mp, which bulges the
/// square into rounded blocks.
#[inline(always)]
fn blocky(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sx, sy, mp] = v.params();
    let r = v.w / zeps((t.x.fcos() + t.y.fcos()) / mp + 1.0);
    let k = v.w / FRAC_PI_2;
    [
        k * sx * block_axis(t.x, t.sumsq) * r,
        k * sy * block_axis(t.y, t.sumsq) * r,
        0.0,
    ]
}

/// Bipolar coordinates: inside the band |τ| < radius, τ is shifted by distance·radius and
/// wrapped back into the band, sliding the circles around the foci.
#[inline(always)]
fn bmod(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [radius, dist] = v.params();
    let (mut tau, sigma) = bipolar(t.x, t.y);
    if tau < radius && -tau < radius {
        tau = (tau + radius + dist * radius) % (2.0 * radius) - radius;
    }
    let (x, y) = from_bipolar(v.w, tau, sigma);
    [x, y, 0.0]
}

/// Bipolar swirl: the angle σ turns by out·τ + in/τ, twisting near the foci and far away.
#[inline(always)]
fn bswirl(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [in_, out] = v.params();
    let (tau, sigma) = bipolar(t.x, t.y);
    let sigma = sigma + tau * out + in_ / zeps(tau);
    let (x, y) = from_bipolar(v.w, tau, sigma);
    [x, y, 0.0]
}

/// Bipolar transform: τ is divided by `power` and moved, σ rotated and divided by `power`
/// (one of `power` random copies), and the two half-planes are split apart along τ.
#[inline(always)]
fn btransform(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [rotate, power, mv, split] = v.params();
    let (tau, sigma) = bipolar(t.x, t.y);
    let mut tau = tau / power + mv;
    let copy = floor_i64(rng.f01() * power) as f64;
    let sigma = (sigma + rotate) / power + TAU / power * copy;
    if t.x >= 0.0 {
        tau += split;
    } else {
        tau -= split;
    }
    let (x, y) = from_bipolar(v.w, tau, sigma);
    [x, y, 0.0]
}

/// Half the angle and the ratio of distances as seen from the points (−1, 0) and (1, 0):
/// a bipolar-coordinate map.
#[inline(always)]
fn deltaa(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let y2 = t.y * t.y;
    let r = v.w * ((y2 + sqr(t.x + 1.0)).sqrt() / (y2 + sqr(t.x - 1.0)).sqrt());
    let a = (t.y.atan2(t.x - 1.0) - t.y.atan2(t.x + 1.0)) / 2.0;
    let (s, c) = a.fsin_cos();
    [r * c, r * s, 0.0]
}

fn e_collide_prepare(v: &mut Prepared) {
    let [a, num] = v.params();
    let ca = PI * a;
    v.p.extend_from_slice(&[num * FRAC_1_PI, PI / num, ca / num]);
}

/// Elliptic coordinates: the angle ν is cut into `num` sectors and shifted within each,
/// alternately forwards and backwards, like balls colliding.
#[inline(always)]
fn e_collide(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cn_pi, pi_cn, ca_cn] = v.derived();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
    let sector = (nu * cn_pi) as i32;
    nu = if sector & 1 == 0 {
        sector as f64 * pi_cn + (nu + ca_cn) % pi_cn
    } else {
        sector as f64 * pi_cn + (nu - ca_cn) % pi_cn
    };
    if t.y <= 0.0 {
        nu = -nu;
    }
    let (s, c) = nu.fsin_cos();
    [
        v.w * xmax * c,
        v.w * (xmax - 1.0).sqrt() * (xmax + 1.0).sqrt() * s,
        0.0,
    ]
}

/// An elliptic-coordinate analogue of julian: μ divided by the power, ν divided and rotated to a
/// random one of `power` branches (inverted first for negative powers).
#[inline(always)]
fn e_julia(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let mut r2 = t.sumsq;
    let x = if power >= 0.0 {
        t.x
    } else {
        r2 = 1.0 / zeps(r2);
        t.x * r2
    };
    let (xmax, mut nu) = elliptic(x, r2, true);
    let mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = nu / power + TAU / power * (rng.f01() * power).floor();
    from_elliptic(v.w, mu / power, nu)
}

/// Elliptic coordinates with μ wrapped into [−radius, radius) after a shift of `distance`·radius.
#[inline(always)]
fn e_mod(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [radius, distance] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
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

/// Elliptic coordinates: μ moved by `move` (towards or away from the focal segment depending
/// on the side), reflected through the segment when it crosses it, then ν rotated.
#[inline(always)]
fn e_motion(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [mv, rot] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
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

/// Elliptic coordinates: μ scaled by `dist` and pushed by `push`, ν rotated.
#[inline(always)]
fn e_push(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [push, dist, rot] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
    let mu = acosh(xmax);
    if t.y < 0.0 {
        nu = -nu;
    }
    from_elliptic(v.w, mu * dist + push, nu + rot)
}

/// Elliptic coordinates: rotates ν (wrapped to [−π, π)), keeping the confocal ellipse.
#[inline(always)]
fn e_rotate(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [rot] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = (nu + rot + PI) % TAU - PI;
    let (s, c) = nu.fsin_cos();
    [v.w * xmax * c, v.w * (xmax * xmax - 1.0).sqrt() * s, 0.0]
}

/// Elliptic coordinates: μ and ν scaled by `scale` (ν about the angle `angle`, wrapped).
#[inline(always)]
fn e_scale(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scale, angle] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, true);
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

/// Elliptic coordinates: ν twisted by `out`·μ + `in`/μ (a swirl about the focal segment).
#[inline(always)]
fn e_swirl(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [win, wout] = v.params();
    let (xmax, mut nu) = elliptic(t.x, t.sumsq, false);
    let mu = acosh(if xmax < -1.0 { -1.0 } else { xmax });
    if t.y < 0.0 {
        nu = -nu;
    }
    nu = nu + mu * wout + win / mu;
    from_elliptic(v.w, mu, nu)
}

/// 3-D foci: elliptic-like coordinates where the input z (or the polar angle when z is 0)
/// plays the role of a second angle.
#[inline(always)]
fn foci_3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let ex = t.x.exp() * 0.5;
    let enx = 0.25 / zeps(ex);
    let second = if t.z == 0.0 { t.atan_yx } else { t.z };
    let k = v.w / zeps(ex + enx - t.y.fcos() * second.fcos());
    [(ex - enx) * k, t.y.fsin() * k, second.fsin() * k]
}

/// foci with adjustable weights `c1`, `c2` on eˣ and e⁻ˣ.
#[inline(always)]
fn foci_p(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [c1, c2] = v.params();
    let ex = zeps(t.x.exp());
    let a = ex * c1;
    let b = c2 / ex;
    let (sy, cy) = t.y.fsin_cos();
    let k = v.w / zeps(a + b - cy);
    [(a - b) * k, sy * k, 0.0]
}
