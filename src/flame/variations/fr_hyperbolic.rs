//! Hyperbolic geometry from Fractorium's catalogue: the {p, q} tilings of the Poincaré disc
//! (`hypertile*`, `hypershift*`, `hypercrop`), Poincaré maps in 2-D and 3-D and `ortho`.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::util::{crand, floor_f, floor_i64, sqr, trunc_i32, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("hypercrop", hypercrop)
        .params(&[
            p("hypercrop_n", 4.0),
            p("hypercrop_rad", 1.0),
            p("hypercrop_zero", 0.0),
        ])
        .needs(need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(hypercrop_prepare),
    super::inlined!("hypershift", hypershift)
        .params(&[p("hypershift_shift", 0.01)])
        .needs(need::SUMSQ)
        .flags(flag::WRITES_ACC | flag::COMPAT)
        .prepare(hypershift_prepare),
    super::inlined!("hypershift2", hypershift2)
        .params(&[
            p_range("hypershift2_p", 3.0, 2.0, INF),
            p_range("hypershift2_q", 7.0, 2.0, INF),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC | flag::COMPAT)
        .prepare(hypershift2_prepare),
    super::inlined!("hypertile", hypertile)
        .params(&[
            p("hypertile_p", 3.0),
            p("hypertile_q", 7.0),
            p("hypertile_n", 0.0),
        ])
        .prepare(hypertile_prepare),
    super::inlined_drawn!("hypertile1", hypertile1, 1)
        .params(&[p("hypertile1_p", 3.0), p("hypertile1_q", 7.0)])
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(hypertile12_prepare),
    super::inlined!("hypertile2", hypertile2)
        .params(&[p("hypertile2_p", 3.0), p("hypertile2_q", 7.0)])
        .flags(flag::RANDOM)
        .prepare(hypertile12_prepare),
    super::inlined!("hypertile3D", hypertile3d)
        .params(&[
            p_int("hypertile3D_p", 3.0, 3.0, I32_MAX),
            p_int("hypertile3D_q", 7.0, 3.0, I32_MAX),
            p_int("hypertile3D_n", 0.0, NEG_INF, INF),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(hypertile3d_prepare),
    super::inlined!("hypertile3D1", hypertile3d1)
        .params(&[
            p_int("hypertile3D1_p", 3.0, 3.0, I32_MAX),
            p_int("hypertile3D1_q", 7.0, 3.0, I32_MAX),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(hypertile3d12_prepare),
    super::inlined!("hypertile3D2", hypertile3d2)
        .params(&[
            p_int("hypertile3D2_p", 3.0, 3.0, I32_MAX),
            p_int("hypertile3D2_q", 7.0, 3.0, I32_MAX),
        ])
        .needs(need::SUMSQ)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(hypertile3d12_prepare),
    super::inlined!("ortho", ortho)
        .params(&[
            p_cyclic("ortho_in", 0.0, -PI, PI),
            p_cyclic("ortho_out", 0.0, -PI, PI),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES),
    super::inlined!("poincare", poincare)
        .params(&[
            p("poincare_c1r", 1.0),
            p_cyclic("poincare_c1a", -1.0, -PI, PI),
            p("poincare_c2r", 1.0),
            p_cyclic("poincare_c2a", 1.0, -PI, PI),
        ])
        .prepare(prep_poincare),
    super::inlined!("poincare2", poincare2)
        .params(&[p("poincare2_p", 3.0), p("poincare2_q", 7.0)])
        .prepare(prep_poincare2),
    super::inlined!("poincare3D", poincare3d)
        .params(&[
            p("poincare3D_r", 0.0),
            p("poincare3D_a", 0.0),
            p("poincare3D_b", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_poincare3d),
];

/// Largest 32-bit signed integer, the upper bound of some integer parameters.
const I32_MAX: f64 = 2147483647.0;

fn hypercrop_prepare(v: &mut Prepared) {
    let [n, rad] = v.params();
    let n = zeps(n);
    let coeff = zeps(n * 0.5 / PI);
    let a0 = PI / n;
    let len = 1.0 / zeps(a0.fcos());
    let d = rad * a0.fsin() * len;
    v.p.extend_from_slice(&[coeff, a0, len, d]);
}

/// Crops the discs of a hyperbolic n-gon tiling: points inside the disc around one of the n
/// polygon vertices are pushed to its edge (or to the vertex, or to the origin, by `zero`).
#[inline(always)]
fn hypercrop(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, zero] = v.params();
    let [coeff, a0, len, d] = v.derived();
    let ang = floor_f(t.atan_yx * coeff) / coeff + a0;
    let x0 = ang.fcos() * len;
    let y0 = ang.fsin() * len;
    let (mut fx, mut fy, mut fz) = (t.x, t.y, t.z);
    if (sqr(t.x - x0) + sqr(t.y - y0)).sqrt() < d {
        fz = 0.0;
        if zero > 1.5 {
            fx = x0;
            fy = y0;
        } else if zero > 0.5 {
            fx = 0.0;
            fy = 0.0;
        } else {
            let ra = (t.y - y0).atan2(t.x - x0);
            fx = x0 + ra.fcos() * d;
            fy = y0 + ra.fsin() * d;
        }
    }
    [fx * v.w, fy * v.w, fz * v.w]
}

/// A hyperbolic translation of the Poincaré disc by `shift` along x (inversion, shift,
/// inversion); as a regular variation (compat mode) it replaces the xform's running sum.
fn hypershift_prepare(v: &mut Prepared) {
    let [shift] = v.params();
    v.p.push(1.0 - shift * shift);
}

#[inline(always)]
fn hypershift(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [shift] = v.params();
    let [scale] = v.derived();
    let inv = 1.0 / zeps(t.sumsq);
    let x = inv * t.x + shift;
    let y = inv * t.y;
    let k = v.w * scale / zeps(x * x + y * y);
    if v.compat && v.form == Form::Regular {
        *acc = Acc {
            color: acc.color,
            ..Acc::default()
        };
    }
    [k * x + shift, k * y, 0.0]
}

fn hypershift2_prepare(v: &mut Prepared) {
    let [p_, q_] = v.params();
    let pq = PI / q_;
    let pp = PI / p_;
    let spq = pq.fsin();
    let spp = pp.fsin();
    let shift = (PI * 0.5 - pq - pp).fsin() / (1.0 - sqr(spq) - sqr(spp)).sqrt();
    let lean = (PI / 2.0 + pp).fsin();
    let scale2 = 1.0 / (sqr(lean) / sqr(spq) - 1.0).sqrt() * (lean / spq - 1.0);
    let scale = 1.0 - shift * shift;
    v.p.extend_from_slice(&[shift, scale, scale2]);
}

/// A hyperbolic {p, q} tiling step: a hyperbolic shift of the scaled point, then a rotation by
/// a random odd multiple of π/p; z is scaled like the point.
#[inline(always)]
fn hypershift2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [p_] = v.params();
    let [shift, scale, scale2] = v.derived();
    let fx = t.x * scale2;
    let fy = t.y * scale2;
    let inv = 1.0 / zeps(fx * fx + fy * fy);
    let x = inv * fx + shift;
    let y = inv * fy;
    let k = v.w * scale / zeps(x * x + y * y);
    let ang = floor_i64(rng.f01() * p_).wrapping_mul(2).wrapping_add(1) as f64 * PI / p_;
    let bx = k * x + shift;
    let by = k * y;
    let (sa, ca) = ang.fsin_cos();
    if v.compat && v.form == Form::Regular {
        *acc = Acc {
            color: acc.color,
            ..Acc::default()
        };
    }
    [ca * bx - sa * by, sa * bx + ca * by, t.z * k]
}

fn hypertile_prepare(v: &mut Prepared) {
    let [p_, q_, n] = v.params();
    let pa = TAU / zeps(p_);
    let cs = pa.fcos();
    let r2 = (1.0 - cs) / (cs + (TAU / zeps(q_)).fcos()) + 1.0;
    let r = if r2 > 0.0 { 1.0 / r2.sqrt() } else { 1.0 };
    let a = n * pa;
    v.p.extend_from_slice(&[r * a.fcos(), r * a.fsin()]);
}

/// A Möbius map of the Poincaré disc carrying the origin to the n-th vertex of the {p, q}
/// hyperbolic tiling's central polygon.
#[inline(always)]
fn hypertile(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [re, im] = v.derived();
    let a = t.x + re;
    let b = t.y - im;
    let c = re * t.x - im * t.y + 1.0;
    let d = re * t.y + im * t.x;
    let k = v.w / (c * c + d * d);
    [k * (a * c + b * d), k * (b * c - a * d), 0.0]
}

fn hypertile12_prepare(v: &mut Prepared) {
    let [p_, q_] = v.params();
    let pa = TAU / zeps(p_);
    let cs = pa.fcos();
    let r2 = 1.0 - (cs - 1.0) / (cs + (TAU / zeps(q_)).fcos());
    let r = if r2 > 0.0 { 1.0 / r2.sqrt() } else { 1.0 };
    let whole_p = trunc_i32(p_) as f64;
    v.p.extend_from_slice(&[pa, r, whole_p]);
}

/// The {p, q} tiling map of `hypertile` towards a random vertex of the central polygon.
#[inline(always)]
fn hypertile1<R: Draws>(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut R) -> V3 {
    let [pa, r, whole_p] = v.derived();
    // [`crand`] as the draws' own integer below 32767 (exact through i32, which vector units
    // convert).
    let ang = if v.compat {
        rng.below(32767) as i32 as f64 * pa
    } else {
        floor_f(rng.f01() * whole_p) * pa
    };
    let (sa, ca) = ang.fsin_cos();
    let re = r * ca;
    let im = r * sa;
    let a = t.x + re;
    let b = t.y - im;
    let c = re * t.x - im * t.y + 1.0;
    let d = re * t.y + im * t.x;
    let k = v.w / zeps(c * c + d * d);
    [k * (a * c + b * d), k * (b * c - a * d), 0.0]
}

/// The {p, q} tiling map towards the first vertex, followed by a rotation by a random multiple
/// of 2π/p.
#[inline(always)]
fn hypertile2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, r] = v.derived();
    let a = t.x + r;
    let b = t.y;
    let c = r * t.x + 1.0;
    let d = r * t.y;
    let x = a * c + b * d;
    let y = b * c - a * d;
    let k = v.w / zeps(c * c + d * d);
    let (sa, ca) = (crand(rng) * pa).fsin_cos();
    [k * (x * ca + y * sa), k * (y * ca - x * sa), 0.0]
}

/// Radius of the {p, q} tiling's vertex circle (the 3-D hypertiles' shared constant), and 2π/p.
#[inline(always)]
fn tile3d_radius(p_: f64, q_: f64) -> (f64, f64) {
    let pa = TAU / zeps(p_);
    let qa = TAU / zeps(q_);
    let r = -(pa.fcos() - 1.0) / zeps(pa.fcos() + qa.fcos());
    let r = if r > 0.0 {
        1.0 / zeps((1.0 + r).sqrt())
    } else {
        1.0
    };
    (r, pa)
}

fn hypertile3d_prepare(v: &mut Prepared) {
    let [p, q, n] = v.params();
    let (r, pa) = tile3d_radius(p, q);
    let na = n * pa;
    let cx = r * na.fcos();
    let cy = r * na.fsin();
    let (cx2, cy2) = (cx * cx, cy * cy);
    v.p.extend_from_slice(&[
        cx,
        cy,
        cx2 + cy2,
        2.0 * cx,
        2.0 * cy,
        1.0 + cx2 - cy2,
        1.0 + cy2 - cx2,
        1.0 - cy2 - cx2,
    ]);
}

/// The hyperbolic tiling map of `hypertile` extended to 3-D (a Möbius map of the ball).
#[inline(always)]
fn hypertile3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cx, cy, c2, c2x, c2y, s2x, s2y, s2z] = v.derived();
    let r2 = t.sumsq + t.z;
    let x2cx = c2x * t.x;
    let y2cy = c2y * t.y;
    let d = v.w / zeps(c2 * r2 + x2cx - y2cy + 1.0);
    [
        d * (t.x * s2x - cx * (y2cy - r2 - 1.0)),
        d * (t.y * s2y + cy * (-x2cx - r2 - 1.0)),
        d * (t.z * s2z),
    ]
}

fn hypertile3d12_prepare(v: &mut Prepared) {
    let [p, q] = v.params();
    let (r, pa) = tile3d_radius(p, q);
    let c2 = r * r;
    v.p.extend_from_slice(&[pa, r, c2, 1.0 - c2, 2.0 * r, 1.0 + c2]);
}

/// The 3-D hyperbolic tiling map towards a random vertex of the central polygon.
#[inline(always)]
fn hypertile3d1(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, r, c2, s2z] = v.derived();
    let (sa, ca) = (crand(rng) * pa).fsin_cos();
    let cx = r * ca;
    let cy = r * sa;
    let s2x = 1.0 + cx * cx - cy * cy;
    let s2y = 1.0 + cy * cy - cx * cx;
    let r2 = t.sumsq + t.z * t.z;
    let x2cx = 2.0 * cx * t.x;
    let y2cy = 2.0 * cy * t.y;
    let d = v.w / zeps(c2 * r2 + x2cx - y2cy + 1.0);
    [
        d * (t.x * s2x - cx * (y2cy - r2 - 1.0)),
        d * (t.y * s2y + cy * (-x2cx - r2 - 1.0)),
        d * (t.z * s2z),
    ]
}

/// The 3-D hyperbolic tiling map towards the first vertex, then a random rotation by a
/// multiple of 2π/p about the z axis.
#[inline(always)]
fn hypertile3d2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pa, cx, c2, s2z, c2x, s2x] = v.derived();
    let s2y = s2z;
    let r2 = t.sumsq + t.z * t.z;
    let x2cx = c2x * t.x;
    let x = t.x * s2x - cx * (-r2 - 1.0);
    let y = t.y * s2y;
    let k = v.w / (c2 * r2 + x2cx + 1.0);
    let (sa, ca) = (crand(rng) * pa).fsin_cos();
    [
        k * (x * ca + y * sa),
        k * (y * ca - x * sa),
        k * (t.z * s2z),
    ]
}

/// One ortho step: the circle through the point orthogonal to the unit circle (centre `xo` on
/// the x axis, radius `ro`), on which the point is moved by the angle `turn`·θ, wrapped into
/// (−θ, θ]. Works on x ≥ 0 (callers mirror). Returns the new point.
#[inline(always)]
fn ortho_step(x: f64, y: f64, xo: f64, turn: f64) -> (f64, f64) {
    let ro = ((x - xo) * (x - xo) + y * y).sqrt();
    let theta = 1.0f64.atan2(ro);
    let a = (turn * theta + y.atan2(xo - x) + theta) % (2.0 * theta) - theta;
    (xo - a.fcos() * ro, a.fsin() * ro)
}

/// ortho: moves points along circles orthogonal to the unit circle (by `in` inside the disc,
/// by `out` for the inverted image of outside points).
#[inline(always)]
fn ortho(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [turn_in, turn_out] = v.params();
    let w = v.w;
    let r = t.sumsq;
    if r < 1.0 {
        if t.x >= 0.0 {
            let xo = (r + 1.0) / zeps(2.0 * t.x);
            let ro = ((t.x - xo) * (t.x - xo) + t.y * t.y).sqrt();
            let theta = 1.0f64.atan2(ro);
            let a = (turn_in * theta + t.y.atan2(xo - t.x) + theta) % (2.0 * theta) - theta;
            [w * (xo - a.fcos() * ro), w * a.fsin() * ro, 0.0]
        } else {
            let xo = -(r + 1.0) / (2.0 * t.x);
            let ro = ((-t.x - xo) * (-t.x - xo) + t.y * t.y).sqrt();
            let theta = 1.0f64.atan2(ro);
            let a = (turn_in * theta + t.y.atan2(xo + t.x) + theta) % (2.0 * theta) - theta;
            [-(w * (xo - a.fcos() * ro)), w * a.fsin() * ro, 0.0]
        }
    } else {
        let inv = 1.0 / r.sqrt();
        let x = inv * t.ux;
        let y = inv * t.uy;
        let mirrored = x < 0.0;
        let (nx, ny) = if !mirrored {
            let xo = (x * x + y * y + 1.0) / zeps(2.0 * x);
            ortho_step(x, y, xo, turn_out)
        } else {
            let xo = -(x * x + y * y + 1.0) / (2.0 * x);
            ortho_step(-x, y, xo, turn_out)
        };
        let ang = ny.atan2(nx);
        let k = 1.0 / (nx * nx + ny * ny).sqrt();
        let ox = w * k * ang.fcos();
        [if mirrored { -ox } else { ox }, w * k * ang.fsin(), 0.0]
    }
}

fn prep_poincare(v: &mut Prepared) {
    let [c1r, c1a, c2r, c2a] = v.params();
    let d1 = (1.0 + c1r * c1r).sqrt();
    let d2 = (1.0 + c2r * c2r).sqrt();
    let (a1, a2) = (c1a % PI, c2a % PI);
    v.p.extend_from_slice(&[
        d1 * a1.fcos(),
        d1 * a1.fsin(),
        d2 * a2.fcos(),
        d2 * a2.fsin(),
    ]);
}

/// poincare: two successive inversions in circles of radii c1r, c2r orthogonal to the unit
/// circle, centred in the directions c1a, c2a (weight not used).
#[inline(always)]
fn poincare(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [c1r, _, c2r] = v.params();
    let [c1x, c1y, c2x, c2y] = v.derived();
    let invert = |x: f64, y: f64, cx: f64, cy: f64, rr: f64| {
        let (dx, dy) = (x - cx, y - cy);
        let den = zeps(dx * dx + dy * dy);
        (cx + (rr * dx) / den, cy + (rr * dy) / den)
    };
    let (x, y) = invert(t.x, t.y, c1x, c1y, c1r * c1r);
    let (x, y) = invert(x, y, c2x, c2y, c2r * c2r);
    [x, y, 0.0]
}

fn prep_poincare2(v: &mut Prepared) {
    let [pp, qq] = v.params();
    let a0 = TAU / pp;
    let dist2 = 1.0 - (a0.fcos() - 1.0) / (a0.fcos() + (TAU / qq).fcos());
    let dist = if dist2 > 0.0 { 1.0 / dist2.sqrt() } else { 1.0 };
    let (cx, cy) = if 1.0 / pp + 1.0 / qq < 0.5 {
        (a0.fcos() * dist, a0.fsin() * dist)
    } else {
        (0.0, 0.0)
    };
    v.p.push(cx);
    v.p.push(cy);
}

/// poincare2: the hyperbolic translation of the Poincaré disc (z − c)/(1 − c̄·z) that moves the
/// centre c of a neighbouring tile of the {p, q} tiling to the origin.
#[inline(always)]
fn poincare2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cx, cy] = v.derived();
    let a = t.x - cx;
    let b = t.y - cy;
    let c = 1.0 - cx * t.x - cy * t.y;
    let d = cy * t.x - cx * t.y;
    let k = v.w / zeps(c * c + d * d);
    [(a * c + b * d) * k, (b * c - a * d) * k, 0.0]
}

fn prep_poincare3d(v: &mut Prepared) {
    let [r, a, b] = v.params();
    let cx = -r * (a * FRAC_PI_2).fcos() * (b * FRAC_PI_2).fcos();
    let cy = r * (a * FRAC_PI_2).fsin() * (b * FRAC_PI_2).fcos();
    let cz = -r * (b * FRAC_PI_2).fsin();
    let (sx, sy, sz) = (cx * cx, cy * cy, cz * cz);
    v.p.extend_from_slice(&[
        cx,
        cy,
        cz,
        sx + sy + sz,
        2.0 * cx,
        2.0 * cy,
        2.0 * cz,
        sx - sy - sz + 1.0,
        sy - sx - sz + 1.0,
        sz - sy - sx + 1.0,
    ]);
}

/// poincare3D: the 3-D Möbius translation of the unit ball moving the point c (of length r,
/// direction given by the angles a and b) to the origin.
#[inline(always)]
fn poincare3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cx, cy, cz, c2, c2x, c2y, c2z, s2x, s2y, s2z] = v.derived();
    let r2 = t.sumsq + t.z * t.z;
    let px = c2x * t.x;
    let py = c2y * t.y;
    let pz = c2z * t.z;
    let d = v.w / zeps(c2 * r2 - px - py - pz + 1.0);
    [
        d * (t.x * s2x + cx * (py + pz - r2 - 1.0)),
        d * (t.y * s2y + cy * (px + pz - r2 - 1.0)),
        d * (t.z * s2z + cz * (py + px - r2 - 1.0)),
    ]
}
