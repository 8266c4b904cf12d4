//! Polynomial and rational maps of the plane from Fractorium's catalogue: the Hénon and Lozi
//! maps, a quadratic ODE step, `mcarpet`, `polynomial`, `unicorngaloshen`, `fourth`, `xheart`
//! and `projective`.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_PI_4, PI, TAU};

use super::util::{sign, sqr, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("fourth", fourth)
        .params(&[
            p_cyclic("fourth_spin", PI, 0.0, TAU),
            p("fourth_space", 0.0),
            p("fourth_twist", 0.0),
            p("fourth_x", 0.0),
            p("fourth_y", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES),
    super::inlined!("henon", henon).params(&[p("henon_a", 0.5), p("henon_b", 1.0)]),
    super::inlined!("lozi", lozi).params(&[p("lozi_a", 0.5), p("lozi_b", 1.0)]),
    super::inlined!("mcarpet", mcarpet)
        .params(&[
            p("mcarpet_x", 0.0),
            p("mcarpet_y", 0.0),
            p("mcarpet_twist", 0.0),
            p("mcarpet_tilt", 0.0),
        ])
        .needs(need::SUMSQ),
    super::inlined!("polynomial", polynomial)
        .params(&[
            p("polynomial_powx", 1.0),
            p("polynomial_powy", 1.0),
            p("polynomial_lcx", 0.0),
            p("polynomial_lcy", 0.0),
            p("polynomial_scx", 0.0),
            p("polynomial_scy", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("projective", projective).params(&[
        p("projective_A", 0.0),
        p("projective_B", 0.0),
        p("projective_C", 1.0),
        p("projective_A1", 1.0),
        p("projective_B1", 0.0),
        p("projective_C1", 0.0),
        p("projective_A2", 0.0),
        p("projective_B2", 1.0),
        p("projective_C2", 0.0),
    ]),
    super::inlined!("q_ode", q_ode).params(&[
        p("q_ode01", 1.0),
        p("q_ode02", -1.0),
        p("q_ode03", 0.0),
        p("q_ode04", 0.0),
        p("q_ode05", 0.0),
        p("q_ode06", 0.0),
        p("q_ode07", 1.0),
        p("q_ode08", 0.0),
        p("q_ode09", 0.0),
        p("q_ode10", 0.0),
        p("q_ode11", 0.0),
        p("q_ode12", 0.0),
    ]),
    super::inlined!("unicorngaloshen", unicorngaloshen)
        .params(&[
            p("unicorngaloshen_mult_x", 1.0),
            p("unicorngaloshen_mult_y", 1.0),
            p("unicorngaloshen_sine", 0.0),
            p("unicorngaloshen_sin_x_amplitude", 1.0),
            p("unicorngaloshen_sin_x_freq", 0.1),
            p("unicorngaloshen_sin_y_amplitude", 2.0),
            p("unicorngaloshen_sin_y_freq", 0.2),
            p_range("unicorngaloshen_mode", 0.0, 0.0, 4.0),
        ])
        .prepare(unicorngaloshen_prep),
    super::inlined!("xheart", xheart)
        .params(&[p("xheart_angle", 0.0), p("xheart_ratio", 0.0)])
        .needs(need::SUMSQ)
        .prepare(xheart_prep),
];

/// A different map in each quadrant: spherical where x, y > 0, loonie where x > 0 > y,
/// a lazysusan-like swirl (centre (x, −y) params, `spin`, `twist`, `space`) where x < 0 < y,
/// linear elsewhere.
#[inline(always)]
fn fourth(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [spin, space, twist, cx, cy] = v.params();
    let w = v.w;
    let (x, y) = (t.x, t.y);
    if x > 0.0 && y > 0.0 {
        let inv = 1.0 / t.sqrt;
        [w * inv * t.ux, w * inv * t.uy, 0.0]
    } else if x > 0.0 && y < 0.0 {
        let w2 = w * w;
        if t.sumsq < w2 {
            let k = w * (w2 / t.sumsq - 1.0).sqrt();
            [k * x, k * y, 0.0]
        } else {
            [w * x, w * y, 0.0]
        }
    } else if x < 0.0 && y > 0.0 {
        let dx = x - cx;
        let dy = y + cy;
        let r = (dx * dx + dy * dy).sqrt();
        if r < w {
            let a = dy.atan2(dx) + spin + twist * (w - r);
            let rr = r * w;
            [rr * a.fcos() + cx, rr * a.fsin() - cy, 0.0]
        } else {
            let k = w * (1.0 + space / zeps(r));
            [k * dx + cx, k * dy - cy, 0.0]
        }
    } else {
        [w * x, w * y, 0.0]
    }
}

/// One step of the Hénon map: (1 − a·x² + y, b·x).
#[inline(always)]
fn henon(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b] = v.params();
    [(1.0 - a * (t.x * t.x) + t.y) * v.w, b * t.x * v.w, 0.0]
}

/// lozi: the Lozi map (1 − a·|x| + y, b·x).
#[inline(always)]
fn lozi(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b] = v.params();
    [(1.0 - (a * t.x.abs()) + t.y) * v.w, b * t.x * v.w, 0.0]
}

/// mcarpet: a damped scaling x·r·(x, y)/(1 + r²/4) plus a Lozi/Hénon-like term
/// (1 − twist·x² + y, tilt·x).
#[inline(always)]
fn mcarpet(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [sx, sy, twist, tilt] = v.params();
    let k = v.w / (t.sumsq * 0.25 + 1.0);
    let x = t.x * k * sx + (1.0 - (twist * (t.x * t.x)) + t.y) * v.w;
    let y = t.y * k * sy + tilt * t.x * v.w;
    [x, y, 0.0]
}

/// polynomial: per coordinate a signed power of |weight·u| plus a linear term lc·u and a
/// constant sc; z is scaled by the weight.
#[inline(always)]
fn polynomial(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [powx, powy, lcx, lcy, scx, scy] = v.params();
    let aw = v.w.abs();
    let xp = (aw * t.x.abs()).powf(powx);
    let yp = (aw * t.y.abs()).powf(powy);
    [
        xp * sign(t.x) + lcx * t.x + scx,
        yp * sign(t.y) + lcy * t.y + scy,
        v.w * t.z,
    ]
}

/// A projective (homographic) map of the plane: two affine forms divided by a third.
#[inline(always)]
fn projective(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c, a1, b1, c1, a2, b2, c2] = v.params();
    let s = v.w / zeps(a * t.x + b * t.y + c);
    [
        (a1 * t.x + b1 * t.y + c1) * s,
        (a2 * t.x + b2 * t.y + c2) * s,
        0.0,
    ]
}

/// One step of a quadratic planar ODE: each output coordinate is a general quadratic
/// polynomial of x and y (the weight scales only the x term of x' and the y term of y').
#[inline(always)]
fn q_ode(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [
        q_ode01,
        q_ode02,
        q_ode03,
        q_ode04,
        q_ode05,
        q_ode06,
        q_ode07,
        q_ode08,
        q_ode09,
        q_ode10,
        q_ode11,
        q_ode12,
    ] = v.params();
    let (x, y) = (t.x, t.y);
    let (xx, yy, xy) = (x * x, y * y, x * y);
    [
        (q_ode01 + v.w * q_ode02 * x + q_ode03 * xx) + (q_ode04 * xy + q_ode05 * y + q_ode06 * yy),
        (q_ode07 + q_ode08 * x + q_ode09 * xx) + (q_ode10 * xy + v.w * q_ode11 * y + q_ode12 * yy),
        0.0,
    ]
}

/// Derived values of unicorngaloshen: the sine frequencies times π.
fn unicorngaloshen_prep(v: &mut Prepared) {
    let [_, _, _, _, fx, _, fy] = v.params();
    v.p.extend_from_slice(&[PI * fx, PI * fy]);
}

/// unicorngaloshen: a quadratic map (x − y)(x + m_y·y), x·y divided by an elliptic radius,
/// with optional sine modulation of its two factors (by x, y, e⁻ˣ, 1/x, log|x| or angles).
#[inline(always)]
fn unicorngaloshen(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [mx, my, sine, ax, _, ay, _, mode] = v.params();
    let [pi_fx, pi_fy] = v.derived();
    let (x, y) = (t.x, t.y);
    let r = v.w / zeps(((sqr(y) * my) + (mx * sqr(x))).sqrt());
    let (fx, fy) = if sine <= 0.0 {
        (ax, ay)
    } else {
        let (u, w) = if mode <= 0.0 {
            (x, y)
        } else if mode <= 1.0 {
            ((-x).exp(), (-y).exp())
        } else if mode <= 2.0 {
            (1.0 / zeps(x), 1.0 / zeps(y))
        } else if mode <= 3.0 {
            (x.abs().ln(), ay * y.abs().ln())
        } else {
            (x.atan2(y), y.atan2(x))
        };
        (1.0 + ax * (u * pi_fx).fsin(), 2.0 + ay * (w * pi_fy).fsin())
    };
    [fx * (x - y) * (x + my * y) * r, fy * x * y * r, 0.0]
}

/// Derived values of xheart: cos and sin of the rotation π/4 + angle·π/8, and the stretch
/// 6 + 2·ratio.
fn xheart_prep(v: &mut Prepared) {
    let [angle, ratio] = v.params();
    let ang = FRAC_PI_4 + (0.5 * FRAC_PI_4 * angle);
    let (s, c) = ang.fsin_cos();
    let rat = 6.0 + 2.0 * ratio;
    v.p.extend_from_slice(&[c, s, rat]);
}

/// xheart: a heart shape — the point is shrunk by 1/(r² + 4), stretched, rotated by 45°
/// (adjustable), and its left half mirrored in x.
#[inline(always)]
fn xheart(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [c, s, rat] = v.derived();
    let mut den = t.sumsq + 4.0;
    if den == 0.0 {
        den = 1.0;
    }
    let kx = 4.0 / den;
    let ky = rat / den;
    let x = c * (kx * t.x) - s * (ky * t.y);
    let y = s * (kx * t.x) + c * (ky * t.y);
    if x > 0.0 {
        [v.w * x, v.w * y, 0.0]
    } else {
        [v.w * x, -v.w * y, 0.0]
    }
}
