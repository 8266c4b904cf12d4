//! JWildfire's plane shapes and warps of the plane: the damped waves `waves2_wf` and
//! `waves4_wf`, the outlines `cloverleaf_wf` and `heart_wf`, dark-beam's `yin_yang`,
//! `layered_spiral`, the Fresnel zones of `fresnel`, the vortex street of `vortex` and other
//! small 2-D formulas.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: `atan_xy` is its `getPrecalcAtan`
//! (atan2(x, y)), weights multiply the output linearly, integer parameters are rounded, and
//! random numbers are drawn in the order JWildfire draws them. JWildfire's 2-D variations leave
//! z at 0 (its "preserve z" switch is off by default).

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use super::jwf_direct_colour::gmod;
use super::util::fract;
use super::util::jwf_math as jm;
use super::*;

/// JWildfire's `EPSILON`.
const JEPS: f64 = 1e-8;

/// Parameters of the damped waves (`waves2_wf`, `waves4_wf`), with their JWildfire defaults.
macro_rules! waves_params {
    ($n:literal) => {
        &[
            p(concat!($n, "_scalex"), 0.25),
            p(concat!($n, "_scaley"), 0.5),
            p(concat!($n, "_freqx"), FRAC_PI_2),
            p(concat!($n, "_freqy"), FRAC_PI_4),
            p_int(concat!($n, "_use_cos_x"), 1.0, NEG_INF, INF),
            p_int(concat!($n, "_use_cos_y"), 0.0, NEG_INF, INF),
            p(concat!($n, "_dampx"), 0.0),
            p(concat!($n, "_dampy"), 0.0),
        ]
    };
}

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("waves2_wf", waves2_wf)
        .params(waves_params!("waves2_wf"))
        .flags(flag::JWILDFIRE)
        .prepare(waves_prepare),
    VarDef::new("waves4_wf", waves4_wf)
        .params(waves_params!("waves4_wf"))
        .flags(flag::JWILDFIRE)
        .prepare(waves_prepare),
    VarDef::new("cloverleaf_wf", cloverleaf_wf)
        .params(&[p("cloverleaf_wf_filled", 0.85)])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("yin_yang", yin_yang)
        .params(&[
            p_range("yin_yang_radius", 0.5, 0.0, 1.0),
            p("yin_yang_ang1", 0.0),
            p("yin_yang_ang2", 0.0),
            p_int("yin_yang_dual_t", 1.0, 0.0, 1.0),
            p_int("yin_yang_outside", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .prepare(yin_yang_prepare),
    VarDef::new("heart_wf", heart_wf)
        .params(&[
            p("heart_wf_scale_x", 1.0),
            p("heart_wf_shift_t", 0.0),
            p("heart_wf_scale_r_left", 1.0),
            p("heart_wf_scale_r_right", 1.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("layered_spiral", layered_spiral)
        .params(&[p("layered_spiral_radius", 1.0)])
        .flags(flag::JWILDFIRE),
    VarDef::new("holesq", holesq).flags(flag::JWILDFIRE),
    VarDef::new("stripfit", stripfit)
        .params(&[p("stripfit_dx", 1.0)])
        .flags(flag::JWILDFIRE),
    VarDef::new("squircular", squircular).flags(flag::JWILDFIRE),
    VarDef::new("hole2", hole2)
        .params(&[
            p("hole2_a", 1.0),
            p("hole2_b", 2.0),
            p("hole2_c", 1.0),
            p("hole2_d", 1.0),
            p_int("hole2_inside", 0.0, 0.0, 1.0),
            p_int("hole2_shape", 0.0, 0.0, 9.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::JWILDFIRE),
    VarDef::new("devil_warp", devil_warp)
        .params(&[
            p("devil_warp_a", 2.0),
            p("devil_warp_b", 1.0),
            p("devil_warp_effect", 1.0),
            p("devil_warp_warp", 0.5),
            p("devil_warp_rmin", -0.24),
            p("devil_warp_rmax", 100.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("bsplit", bsplit)
        .params(&[p("bsplit_x", 0.0), p("bsplit_y", 0.0)])
        .flags(flag::JWILDFIRE | flag::HIDES),
    VarDef::new("minkowskope", minkowskope)
        .params(&[
            p("minkowskope_separation", 0.5),
            p("minkowskope_frequencyx", -2.0),
            p("minkowskope_frequencyy", 2.0),
            p("minkowskope_amplitude", 0.5),
            p("minkowskope_perturbation", 1.0),
            p("minkowskope_damping", 0.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("circular2", circular2)
        .params(&[
            p("circular2_angle", 90.0),
            p("circular2_seed", 0.0),
            p("circular2_xx", 12.9898),
            p("circular2_yy", 78.233),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("vogel", vogel)
        .params(&[
            p_int("vogel_n", 20.0, 1.0, 2147483647.0),
            p("vogel_scale", 1.0),
        ])
        .needs(need::SQRT)
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("fresnel", fresnel)
        .params(&[
            p("fresnel_x0", 0.0),
            p("fresnel_y0", 0.0),
            p("fresnel_ring", -2.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_ACC),
    VarDef::new("hyperbolicellipse", hyperbolicellipse)
        .params(&[p("hyperbolicellipse_a", 1.0)])
        .flags(flag::JWILDFIRE | flag::WRITES_ACC),
    VarDef::new("whirligig", whirligig)
        .params(&[p_int("whirligig_Mode", 0.0, 0.0, 15.0)])
        .flags(flag::JWILDFIRE),
    VarDef::new("glynnia3", glynnia3)
        .params(&[
            p("glynnia3_rscale", 1.0),
            p("glynnia3_dscale", 1.0),
            p("glynnia3_rthresh", 0.0),
            p("glynnia3_ythresh", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("vortex", vortex)
        .params(&[
            p_int("vortex_randomize", 0.0, NEG_INF, INF),
            p("vortex_time", 0.0),
            p_int("vortex_flowVel", 20.0, 1.0, 50.0),
            p_range("vortex_zoom", 4.0, 0.0, 9.0),
            p("vortex_UpDown", 0.0),
            p("vortex_vSep", 0.6),
            p("vortex_v_viDistance", 4.0),
            p("vortex_vDiameter", 1.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("oak_leaf", oak_leaf)
        .params(&[p("oak_leaf_filled", 0.25)])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE | flag::RANDOM),
];

/// The damping factors e^damp (1 where |damp| < 1e-8).
fn waves_prepare(v: &mut Prepared) {
    let [_, _, _, _, _, _, dampx, dampy] = v.params();
    let damp = |d: f64| if d.abs() < JEPS { 1.0 } else { d.exp() };
    v.p.push(damp(dampx));
    v.p.push(damp(dampy));
}

/// waves2_wf: x and y displaced by a sine (or cosine) wave of the other coordinate, both
/// scaled by a damping factor.
fn waves2_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scalex, scaley, freqx, freqy, cos_x, cos_y, _, _] = v.params();
    let [dx, dy] = v.derived();
    let wave = |c: f64, use_cos: f64| if use_cos == 1.0 { c.cos() } else { c.sin() };
    let x = (t.x + dx * scalex * wave(t.y * freqx, cos_x)) * dx;
    let y = (t.y + dy * scaley * wave(t.x * freqy, cos_y)) * dy;
    [v.w * x, v.w * y, 0.0]
}

/// waves4_wf: waves2_wf with cos·sin·cos (or sin·cos·sin) in place of the single wave.
fn waves4_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [scalex, scaley, freqx, freqy, cos_x, cos_y, _, _] = v.params();
    let [dx, dy] = v.derived();
    let wave = |c: f64, use_cos: f64| {
        let (s, co) = c.sin_cos();
        if use_cos == 1.0 {
            co * s * co
        } else {
            s * co * s
        }
    };
    let x = (t.x + dx * scalex * wave(t.y * freqx, cos_x)) * dx;
    let y = (t.y + dy * scaley * wave(t.x * freqy, cos_y)) * dy;
    [v.w * x, v.w * y, 0.0]
}

/// cloverleaf_wf: the four-leaf curve r = sin 2a + sin(6a)/4 at the point's angle, filled
/// (radius times a uniform draw) with probability `filled`.
fn cloverleaf_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [filled] = v.params();
    let a = t.atan_xy;
    let mut r = (2.0 * a).sin() + 0.25 * (6.0 * a).sin();
    if filled > 0.0 && filled > rng.f01() {
        r *= rng.f01();
    }
    [v.w * a.sin() * r, v.w * a.cos() * r, 0.0]
}

fn yin_yang_prepare(v: &mut Prepared) {
    let [_, ang1, ang2] = v.params();
    let (sa, ca) = (PI * ang1).sin_cos();
    let (sb, cb) = (PI * ang2).sin_cos();
    v.p.extend_from_slice(&[sa, ca, sb, cb]);
}

/// yin_yang (dark-beam): the unit disc folded into the two halves of a yin-yang symbol (each
/// rotated by its own angle; with `dual_t` half of the points go to the mirrored half at
/// random); points outside the disc pass (`outside`) or go to the origin.
fn yin_yang(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, _, _, dual_t, outside] = v.params();
    let [sa, ca, sb, cb] = v.derived();
    let (mut xx, mut yy) = (t.x, t.y);
    let r2 = xx * xx + yy * yy;
    if r2 >= 1.0 {
        return if outside == 1.0 {
            [v.w * t.x, v.w * t.y, 0.0]
        } else {
            [0.0; 3]
        };
    }
    let mut inv = 1.0;
    let mut rr = radius;
    let mut nx = xx * ca - yy * sa;
    let mut ny = xx * sa + yy * ca;
    if dual_t == 1.0 && rng.f01() > 0.5 {
        inv = -1.0;
        rr = 1.0 - radius;
        nx = xx * cb - yy * sb;
        ny = xx * sb + yy * cb;
    }
    xx = nx;
    yy = ny;
    if yy > 0.0 {
        let t0 = (1.0 - yy * yy).sqrt();
        let k = xx / t0;
        let t1 = (t0 - 0.5) * 2.0;
        let alfa = (1.0 - k) * 0.5;
        let beta = 1.0 - alfa;
        let dx = alfa * (rr - 1.0);
        let k1 = alfa * rr + beta;
        [
            v.w * (t1 * k1 + dx) * inv,
            v.w * (1.0 - t1 * t1).sqrt() * k1 * inv,
            0.0,
        ]
    } else {
        [
            v.w * (xx * (1.0 - rr) + rr) * inv,
            v.w * (yy * (1.0 - rr)) * inv,
            0.0,
        ]
    }
}

/// heart_wf: a heart outline parametrised by the point's angle (left and right halves scaled
/// separately, the parameter capped at 60), times the point's radius.
fn heart_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    const T_MAX: f64 = 60.0;
    let [scale_x, shift_t, left, right] = v.params();
    let a = t.x.atan2(t.y);
    let r = (t.x * t.x + t.y * t.y).sqrt();
    let (side, scale) = if a < 0.0 { (-1.0, left) } else { (1.0, right) };
    let tt = (side * a / PI * T_MAX * scale - shift_t).min(T_MAX);
    let nx = side * 0.001 * (-tt * tt + 40.0 * tt + 1200.0) * (PI * tt / 180.0).sin() * r;
    let ny = -0.001 * (-tt * tt + 40.0 * tt + 400.0) * (PI * tt / 180.0).cos() * r;
    [v.w * nx * scale_x, v.w * ny, 0.0]
}

/// layered_spiral (Will Evans): x·radius turned by the angle x² + y².
fn layered_spiral(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [radius] = v.params();
    let a = t.x * radius;
    let r = t.x * t.x + t.y * t.y + JEPS;
    [v.w * a * r.cos(), v.w * a * r.sin(), 0.0]
}

/// holesq: the square |x| + |y| ≤ 1 (after weighting) opened along its longer axis: the
/// larger coordinate is pushed half-way towards the edge.
fn holesq(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (x, y) = (v.w * t.x, v.w * t.y);
    let (fax, fay) = (x.abs(), y.abs());
    if fax + fay > 1.0 {
        return [x, y, 0.0];
    }
    if fax > fay {
        let tt = if x < 0.0 {
            (x + fay - 1.0) * 0.5
        } else {
            (x - fay + 1.0) * 0.5
        };
        [tt, y, 0.0]
    } else {
        let tt = if y < 0.0 {
            (y + fax - 1.0) * 0.5
        } else {
            (y - fax + 1.0) * 0.5
        };
        [x, tt, 0.0]
    }
}

/// stripfit: the bands of height 2 above and below |y| ≤ 1 folded into it, each shifted in x
/// by dx per band (that shift is not weighted).
fn stripfit(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [dx] = v.params();
    if v.w == 0.0 {
        return [0.0; 3];
    }
    let dxp = -0.5 * dx;
    let mut x = v.w * t.x;
    let y = if t.y > 1.0 {
        let fity = (t.y + 1.0) % 2.0;
        x += (t.y - fity + 1.0) * dxp;
        v.w * (-1.0 + fity)
    } else if t.y < -1.0 {
        let fity = (1.0 - t.y) % 2.0;
        x += (t.y + fity - 1.0) * dxp;
        v.w * (1.0 - fity)
    } else {
        v.w * t.y
    };
    [x, y, 0.0]
}

/// squircular: the FG-squircular map between the disc and the square (the weight enters
/// non-linearly, as the disc's radius).
fn squircular(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (u, w) = (t.x, t.y);
    // JWildfire's table √ (√2 included): near the origin r is a difference of nearly equal
    // numbers.
    let r = u * u + w * w;
    let rs = jm::sqrt(r);
    let xs = if u > 0.0 { 1.0 } else { -1.0 };
    let r = jm::sqrt(v.w * v.w * r - 4.0 * u * u * w * w);
    let r = jm::sqrt(1.0 + u * u / (w * w) - rs / (v.w * w * w) * r);
    let r = r / jm::sqrt(2.0);
    [xs * r, w / u * r, 0.0]
}

/// hole2: a polar hole whose radius grows by a shape function of the angle (ten shapes); with
/// `inside` the radius is inverted.
fn hole2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c, d, inside, shape] = v.params();
    let rhosq = t.sumsq;
    let theta = t.atan_yx * d;
    let delta = (theta / PI + 1.0).powf(a) * c;
    let r1 = match shape as i32 {
        0 => rhosq.sqrt() + delta,
        1 => (rhosq + delta).sqrt(),
        2 => (rhosq + (b * theta).sin() + delta).sqrt(),
        3 => (rhosq + theta.sin() + delta).sqrt(),
        4 => (rhosq + theta * theta - delta + 1.0).sqrt(),
        5 => (rhosq + theta.tan().abs() + delta).sqrt(),
        6 => (rhosq * (1.0 + (b * theta).sin()) + delta).sqrt(),
        7 => (rhosq + (0.5 * b * theta).sin().abs() + delta).sqrt(),
        8 => (rhosq + (PI * (b * theta).sin()).sin() + delta).sqrt(),
        _ => {
            (rhosq + ((b * theta).sin() + (2.0 * b * theta + FRAC_PI_2).sin()) / 2.0 + delta).sqrt()
        }
    };
    let r1 = if inside != 0.0 { v.w / r1 } else { v.w * r1 };
    [r1 * theta.cos(), r1 * theta.sin(), 0.0]
}

/// devil_warp: the point scaled by 1 + effect·r, r the (clamped) difference of two powers of
/// the devil's-curve terms. Not weighted.
fn devil_warp(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, effect, warp, rmin, rmax] = v.params();
    let (xx, yy) = (t.x, t.y);
    let r2 = 1.0 / (xx * xx + yy * yy);
    let mut r = (xx * xx + r2 * b * yy * yy).powf(warp) - (yy * yy + r2 * a * xx * xx).powf(warp);
    if r > rmax {
        r = rmax;
    } else if r < rmin {
        r = rmin;
    }
    let r = effect * r;
    [xx * (1.0 + r), yy * (1.0 + r), 0.0]
}

/// bsplit: cot(x + sx)·cos(y + sy), (sy − y)/sin(x + sx); the point is hidden where
/// x + sx is exactly 0 or π.
fn bsplit(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [sx, sy] = v.params();
    let xs = t.x + sx;
    if xs == 0.0 || xs == PI {
        acc.hide = true;
        return [0.0; 3];
    }
    acc.hide = false;
    [
        v.w / xs.tan() * (t.y + sy).cos(),
        v.w / xs.sin() * (-t.y + sy),
        0.0,
    ]
}

/// Minkowski's question-mark function on [0, 1], by 20 steps of the Stern–Brocot descent.
fn minkowski(x: f64) -> f64 {
    let (mut p, mut q, mut r, mut s) = (0.0, 1.0, 1.0, 1.0);
    let (mut d, mut y) = (1.0, 0.0);
    for _ in 0..20 {
        d *= 0.5;
        let m = p + r;
        let n = q + s;
        if x < m / n {
            r = m;
            s = n;
        } else {
            y += d;
            p = m;
            q = n;
        }
    }
    y + d
}

/// A "sine" of period 4 built from the question-mark function (minus the sawtooth for `alt`).
fn minkosine(x: f64, alt: bool) -> f64 {
    let lp = x.abs() % 4.0;
    let mut p = x.abs() % 2.0;
    if p > 1.0 {
        p = 2.0 - p;
    }
    let mink = if alt { minkowski(p) - p } else { minkowski(p) };
    if (lp < 2.0) ^ (x > 0.0) { mink } else { -mink }
}

/// minkowskope: the point is negated inside a band |y| ≤ t(x), t a (damped) question-mark wave
/// perturbed by another of y.
fn minkowskope(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [separation, fx, fy, amplitude, perturbation, damping] = v.params();
    let alt = fx <= 0.0;
    let pt = perturbation * minkosine(0.5 * fy * t.y, alt);
    let wave = minkosine(0.5 * fx * t.x + pt - 1.0, alt);
    let tt = if damping.abs() <= JEPS {
        amplitude * wave + separation
    } else {
        amplitude * (-t.x.abs() * damping).exp() * wave + separation
    };
    if t.y.abs() <= tt {
        [-v.w * t.x, -v.w * t.y, 0.0]
    } else {
        [v.w * t.x, v.w * t.y, 0.0]
    }
}

/// circular2: the point turned about the origin by a random angle (a uniform draw plus a
/// sine hash of the point) within ±angle degrees.
fn circular2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [angle, seed, xx, yy] = v.params();
    let c_a = angle * PI / 180.0;
    let aux = (t.x * xx + t.y * yy + seed).sin() * 43758.5453;
    let aux = aux - aux.trunc();
    let rnd = (2.0 * (rng.f01() + aux) - 2.0) * c_a;
    let rad = (t.x * t.x + t.y * t.y).sqrt();
    let ang = t.y.atan2(t.x);
    [
        v.w * (ang + rnd).cos() * rad,
        v.w * (ang + rnd).sin() * rad,
        0.0,
    ]
}

/// vogel: one of the first n seeds of Vogel's sunflower spiral (chosen at random), plus the
/// scaled point, times the seed's radius √i plus the point's.
fn vogel(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n, scale] = v.params();
    const PHI: f64 = 1.618_033_988_749_895;
    let i = (rng.f01() * n).trunc().min(n - 1.0) + 1.0;
    let a = i * (2.0 * PI / (PHI * PHI));
    let r = v.w * (t.sqrt + i.sqrt());
    [
        r * (a.cos() + scale * t.x),
        r * (a.sin() + scale * t.y),
        0.0,
    ]
}

/// fresnel: the point scaled by the fractional part of ring·(distance from a centre), Fresnel
/// zones; it replaces the running sum.
fn fresnel(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x0, y0, ring] = v.params();
    let r = ((t.x - x0) * (t.x - x0) + (t.y - y0) * (t.y - y0)).sqrt();
    let r = fract(r * ring);
    acc.x = 0.0;
    acc.y = 0.0;
    [v.w * t.x * r, v.w * t.y * r, 0.0]
}

/// hyperbolicellipse: (sinh x·cos ay, cosh x·sin ay); it replaces the running sum.
fn hyperbolicellipse(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a] = v.params();
    let (ep, em) = (t.x.exp(), (-t.x).exp());
    acc.x = 0.0;
    acc.y = 0.0;
    [
        (ep - em) / 2.0 * (a * t.y).cos() * v.w,
        (ep + em) / 2.0 * (a * t.y).sin() * v.w,
        0.0,
    ]
}

/// whirligig: one of sixteen sign and ratio combinations of sin x, cos x, sinh y and cosh y.
fn whirligig(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [mode] = v.params();
    let (s, c) = t.x.sin_cos();
    let (sh, ch) = (t.y.sinh(), t.y.cosh());
    let m = mode as i32;
    // Mode bits: 0..=3, 4..=7, 8..=11, 12..=15 choose the ratios; the low two bits the signs.
    let (a, b) = match m / 4 {
        0 => (c / ch, s / sh),
        1 => (s / ch, c / sh),
        2 => (s / sh, c / ch),
        _ => (c / sh, s / ch),
    };
    let (sx, sy) = match m % 4 {
        0 => (1.0, -1.0),
        1 => (-1.0, 1.0),
        2 => (1.0, 1.0),
        _ => (-1.0, -1.0),
    };
    [sx * v.w * a, sy * v.w * b, 0.0]
}

/// glynnia3: glynnia with thresholds on the radius and y and scale factors: above both, one of
/// its two inversions at random; below, the same mirrored in x. Nothing where a divisor
/// vanishes.
fn glynnia3(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [rscale, dscale, rthresh, ythresh] = v.params();
    let vvar2 = v.w * 2f64.sqrt() / 2.0;
    let r = rscale * (t.x * t.x + t.y * t.y).sqrt();
    let side = if r > rthresh && t.y > ythresh {
        1.0
    } else {
        -1.0
    };
    if rng.f01() > 0.5 {
        let d = dscale * (r + t.x).sqrt();
        if d == 0.0 {
            return [0.0; 3];
        }
        [side * vvar2 * d, -vvar2 / d * t.y, 0.0]
    } else {
        let d = dscale * (r + t.x);
        let dx = (r * (t.y * t.y + d * d)).sqrt();
        if dx == 0.0 {
            return [0.0; 3];
        }
        let r = v.w / dx;
        [side * r * d, r * t.y, 0.0]
    }
}

/// vortex: the point carried backwards (`flowVel` steps) through a street of alternating
/// vortices (spacing, separation and strength as parameters, sliding with `time`).
fn vortex(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [_, time, strength, zoom, updown, p1, p2, p3] = v.params();
    let (mut px, mut py) = (t.x, t.y + updown);
    for _ in 0..(strength as i64) {
        let (mut cx, mut cy) = (gmod(time, 10.0) - 20.0, p1);
        let (mut vx, mut vy) = (0.0, 0.0);
        let mut dir = 1.0;
        for _ in 0..30 {
            let (dx, dy) = (px * (10.0 - zoom) - cx, py * (10.0 - zoom) - cy);
            let d = dx * dx + dy * dy + 0.05;
            vx += dy / d * p3 * dir;
            vy += -dx / d * p3 * dir;
            cx += p2;
            cy = -cy;
            dir = -dir;
        }
        px -= vx * 0.03;
        py -= vy * 0.03;
    }
    [v.w * px, v.w * py, 0.0]
}

/// oak_leaf: an oak-leaf outline parametrised by the point's angle, filled (radius times a
/// uniform draw) with probability `filled`.
fn oak_leaf(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [filled] = v.params();
    let tt = -t.atan_xy * 0.5 - FRAC_PI_2;
    let r = if filled > 0.0 && filled > rng.f01() {
        v.w * rng.f01() * 2.0
    } else {
        v.w * 2.0
    };
    let s10 = (10.0 * tt).sin().powf(2.0);
    let lx = tt.cos().powf(9.0) / 100.0 * (5.0 * tt).cos().powf(10.0)
        + (2.0 * tt).sin() / 4.0
            * (1.0 - s10 / 2.0)
            * (1.0 - (tt.cos() * (3.0 * tt).cos()).powf(8.0));
    let ly = tt.sin() * (1.0 - s10 / 5.0 * (0.5 + (2.0 * tt).sin().powf(2.0)));
    [r * lx, r * ly, 0.0]
}
