//! `synth`, Fractorium's configurable shape: one of 27 classic maps whose radius or angle is
//! reshaped by a sum of up to five periodic waves.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::util::{sqr, trunc_i32, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

/// synth's parameters: five global ones, then six per wave layer (`synth_L`, `_type`, `_skew`,
/// `_frq`, `_phs`, `_layer`) for the layers named.
/// `$modes` and `$smooth` are the largest shape number and smoothing type the writer knows.
macro_rules! synth_params {
    ($modes:literal, $smooth:literal; $($layer:literal),*) => {
        &[
            p("synth_a", 0.0),
            p_int("synth_mode", 3.0, 0.0, $modes),
            p("synth_power", -2.0),
            p("synth_mix", 0.0),
            p_int("synth_smooth", 0.0, 0.0, $smooth),
            $(
                p(concat!("synth_", $layer), 0.0),
                p_int(concat!("synth_", $layer, "_type"), 0.0, 0.0, 8.0),
                p(concat!("synth_", $layer, "_skew"), 0.0),
                p(concat!("synth_", $layer, "_frq"), 1.0),
                p(concat!("synth_", $layer, "_phs"), 0.0),
                p_int(concat!("synth_", $layer, "_layer"), 0.0, 0.0, 3.0),
            )*
        ]
    };
}

pub(super) static DEFS: &[VarDef] = &[super::inlined!("synth", synth)
    .params(SYNTH_PARAMS)
    .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
    .flags(flag::RANDOM)];

/// synth's shaping function of an angle (or coordinate): the constant `synth_a` combined
/// with up to five periodic waves, then mixed with 1 by `synth_mix`.
fn synth_value(v: &Prepared, theta: f64) -> f64 {
    // The five wave layers (b … f) follow the first five parameters, six parameters each:
    // amplitude, wave type, skew, frequency, phase, layer combination.
    let [base, _mode, _power, mix, _smooth, layers @ ..] = v.params::<35>();
    let mut f = base;
    for &[amp, kind, skew, frq, phs, comb] in layers.as_chunks::<6>().0 {
        if amp == 0.0 {
            continue;
        }
        let (kind, comb) = (kind as i32, comb as i32);
        // Position within the period, in [0, 1).
        let mut u = (phs + theta * frq) / TAU;
        u -= u.floor();
        if skew != 0.0 {
            // Move the mid-point of the period to (1 + skew)/2.
            let mid = 0.5 + 0.5 * skew;
            u = if u > mid {
                0.5 + 0.5 * (u - mid) / zeps(1.0 - mid)
            } else {
                0.5 - 0.5 * (mid - u) / zeps(mid)
            };
        }
        let wave = match kind {
            0 => (u * TAU).fsin(),
            1 => (u * TAU).fcos(),
            2 => {
                if u > 0.5 {
                    1.0
                } else {
                    -1.0
                }
            }
            3 => 1.0 - 2.0 * u,
            4 => {
                if u > 0.5 {
                    3.0 - 4.0 * u
                } else {
                    2.0 * u - 1.0
                }
            }
            5 => 8.0 * (u - 0.5) * (u - 0.5) - 1.0,
            6 => 2.0 * u.sqrt() - 1.0,
            7 => {
                // Polygon with `frq` sides.
                let ang = (u - 0.5) * (TAU / frq);
                1.0 / zeps(ang.fcos()) - 1.0
            }
            _ => {
                // Inverted polygon.
                let ang = (u - 0.5) * (TAU / frq);
                let c = ang.fcos();
                c / zeps(1.0 - c)
            }
        };
        match comb {
            0 => f += amp * wave,
            1 => f *= 1.0 + amp * wave,
            2 => {
                let g = base + amp * wave;
                f = if f > g { f } else { g };
            }
            _ => {
                let g = base + amp * wave;
                f = if f < g { f } else { g };
            }
        }
    }
    f * mix + (1.0 - mix)
}

/// A quadratic Bézier reshaping of x by the factor m: it bends the line y = x so that it
/// passes through (1, m), rejoining y = x beyond max(1/m, 2m); odd in x and in m.
fn bezier_quad_map<const JWF: bool>(x: f64, m: f64) -> f64 {
    let mut sign = 1.0;
    let (mut x, mut m) = (x, m);
    if m < 0.0 {
        m = -m;
        sign = -1.0;
    }
    if x < 0.0 {
        x = -x;
        sign = -sign;
    }
    let im = if m > 1.0e-10 { 1.0 / m } else { 1e10 };
    // Where the curve rejoins the diagonal: Fractorium takes the larger of 1/m and 2m,
    // JWildfire the larger of 2 − m and 2m. JWildfire also takes the special cases m = ½ and
    // m = 2 within 1e-5 (a squared distance below 1e-10), Fractorium within 1e-10.
    let other = if JWF { 2.0 - m } else { im };
    let end = if other < m * 2.0 { m * 2.0 } else { other };
    let near = |a: f64, b: f64| {
        if JWF {
            (a - b) * (a - b) <= 1e-10
        } else {
            (a - b).abs() <= 1e-10
        }
    };
    if x > end || m == 1.0 {
        return sign * x;
    }
    if m < 1.0 && x <= 1.0 {
        // Control points (0,0), (m,m), (1,m).
        let mut t = x;
        if !near(m, 0.5) {
            t = (-m + (m * m + (1.0 - 2.0 * m) * x).sqrt()) / (1.0 - 2.0 * m);
        }
        return sign * (x + (m - 1.0) * t * t);
    }
    if 1.0 < m && x <= 1.0 {
        // Control points (0,0), (1/m,1/m), (1,m).
        let mut t = x;
        if !near(m, 2.0) {
            t = (-im + (im * im + (1.0 - 2.0 * im) * x).sqrt()) / (1.0 - 2.0 * im);
        }
        return sign * (x + (m - 1.0) * t * t);
    }
    if m < 1.0 {
        // From (1,m) back to the diagonal at `end`, via (1,1).
        let t = ((x - 1.0) / (end - 1.0)).sqrt();
        return sign * (x + (m - 1.0) * t * t + 2.0 * (1.0 - m) * t + (m - 1.0));
    }
    // From (1,m) back to the diagonal at `end`, via (m,m).
    let t = (1.0 - m) + ((m - 1.0) * (m - 1.0) + (x - 1.0)).sqrt();
    sign * (x + (m - 1.0) * t * t - 2.0 * (m - 1.0) * t + (m - 1.0))
}

/// Apply the shaping factor m to x: by the Bézier map when `smooth` is 1, else linearly.
#[inline]
fn synth_lerp<const JWF: bool>(x: f64, m: f64, smooth: i32) -> f64 {
    if smooth == 1 {
        bezier_quad_map::<JWF>(x, m)
    } else {
        x * m
    }
}

/// sin and cos of theta, reshaped by the synth function: multiplied by it (smooth 0), with
/// its deviation from 1 added (smooth 1), or as they are (another type, in JWildfire's files).
fn synth_sin_cos(v: &Prepared, theta: f64, smooth: i32) -> (f64, f64) {
    let [_, _, _, mix] = v.params();
    let (s, c) = theta.fsin_cos();
    match smooth {
        0 => (
            s * synth_value(v, theta),
            c * synth_value(v, theta + FRAC_PI_2),
        ),
        1 => {
            let k = 1.0 - mix;
            (
                k * s + (synth_value(v, theta) - 1.0),
                k * c + (synth_value(v, theta + FRAC_PI_2) - 1.0),
            )
        }
        _ => (s, c),
    }
}

/// synth: one of 27 classic shapes (spherical, bubble, blurs, shifts, swirl, julia, …) whose
/// radius or angle is reshaped by a configurable sum of periodic waves.
#[inline(always)]
fn synth(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode] = v.params();
    synth_shape::<false>(v, t, rng, mode as i32)
}

/// synth in a flame JWildfire wrote: JWildfire numbers the shapes from 12 on otherwise
/// (blurred ring 12, thin ring 13, shift-and-stretch 14, tangent shift 15, angle shift 16 (the
/// radius as it was), the mirrors 17 and 18, powered spherical 19; the sinusoidal to cylinder
/// shapes as 1001–1007) and draws nothing for a number it does not know (JWildfire 9.00's
/// `SynthFunc`).
fn synth_jwildfire(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, power] = v.params();
    let shape = match mode as i32 {
        m @ 0..=11 => m,
        12 => 19,
        13 => 20,
        14 => 22,
        15 => 23,
        16 => {
            let radius = zeps(t.sumsq).powf(power / 2.0);
            let theta = t.atan_xy - 1.0 + synth_value(v, radius);
            let (s, c) = theta.fsin_cos();
            return [v.w * t.sqrt * s, v.w * t.sqrt * c, 0.0];
        }
        17 => 24,
        18 => 25,
        19 => 26,
        m @ 1001..=1007 => m - 989,
        _ => return [0.0; 3],
    };
    synth_shape::<true>(v, t, rng, shape)
}

/// synth's shape `mode` in Fractorium's numbering.
fn synth_shape<const JWF: bool>(v: &Prepared, t: &VarIn, rng: &mut FastRng, mode: i32) -> V3 {
    let [_, _, power, mix, smooth] = v.params();
    let smooth = smooth as i32;
    let w = v.w;
    let (x, y) = (t.x, t.y);
    let polar = |radius: f64, theta: f64| -> V3 {
        let (s, c) = theta.fsin_cos();
        [w * radius * s, w * radius * c, 0.0]
    };
    match mode {
        0 => {
            // spherical
            let radius = zeps(t.sumsq).powf((power + 1.0) / 2.0);
            let theta = t.atan_xy;
            let radius = synth_lerp::<JWF>(radius, synth_value(v, theta), smooth);
            polar(radius, theta)
        }
        1 => {
            // bubble
            let radius = t.sqrt / (t.sumsq / 4.0 + 1.0);
            let theta = t.atan_xy;
            let radius = synth_lerp::<JWF>(radius, synth_value(v, theta), smooth);
            polar(radius, theta)
        }
        2 => {
            // legacy blur
            let radius = (rng.f01() + rng.f01() + 0.002 * rng.f01()) / 2.002;
            let theta = TAU * rng.f01() - PI;
            let vx = radius * theta.fsin();
            let vy = radius * theta.fcos();
            let radius = zeps(radius * radius).powf(power / 2.0);
            let radius = w * synth_lerp::<JWF>(radius, synth_value(v, theta), smooth);
            [vx * radius, vy * radius, 0.0]
        }
        3 => {
            // blur
            let radius = 0.5 * (rng.f01() + rng.f01());
            let theta = TAU * rng.f01() - PI;
            let radius = zeps(sqr(radius)).powf(-power / 2.0);
            let radius = synth_lerp::<JWF>(radius, synth_value(v, theta), smooth);
            polar(radius, theta)
        }
        4 => {
            // zigzag blur along a segment
            let vy = 1.0 + 0.1 * (rng.f01() + rng.f01() - 1.0) * power;
            let theta = 2.0 * ((rng.f01() - 0.5) * 2.0).asin();
            let vy = synth_lerp::<JWF>(vy, synth_value(v, theta), smooth);
            [w * (theta / PI), w * (vy - 1.0), 0.0]
        }
        5 => {
            // raw circle
            let theta = t.atan_xy;
            let radius = synth_lerp::<JWF>(t.sqrt, synth_value(v, theta), smooth);
            polar(radius, theta)
        }
        6 => [
            w * synth_lerp::<JWF>(x, synth_value(v, y), smooth),
            w * y,
            0.0,
        ],
        7 => [
            w * x,
            w * synth_lerp::<JWF>(y, synth_value(v, x), smooth),
            0.0,
        ],
        8 => [
            w * synth_lerp::<JWF>(x, synth_value(v, y), smooth),
            w * synth_lerp::<JWF>(y, synth_value(v, x), smooth),
            0.0,
        ],
        9 => [w * (x + synth_value(v, y) - 1.0), w * y, 0.0],
        10 => [w * x, w * (y + synth_value(v, x) - 1.0), 0.0],
        11 => [
            w * (x + synth_value(v, y) - 1.0),
            w * (y + synth_value(v, x) - 1.0),
            0.0,
        ],
        12 => {
            // sinusoidal
            let k = 1.0 - mix;
            [
                w * (synth_value(v, x) - 1.0 + k * x.fsin()),
                w * (synth_value(v, y) - 1.0 + k * y.fsin()),
                0.0,
            ]
        }
        13 => {
            // swirl
            let radius = zeps(t.sumsq).powf(power / 2.0);
            let (s, c) = synth_sin_cos(v, radius, smooth);
            [w * (s * x - c * y), w * (c * x + s * y), 0.0]
        }
        14 => {
            // hyperbolic
            let radius = zeps(t.sumsq).powf(power / 2.0);
            let (s, c) = synth_sin_cos(v, t.atan_xy, smooth);
            [w * s / radius, w * c * radius, 0.0]
        }
        15 => {
            // julia
            let radius = zeps(t.sumsq).powf(power / 4.0);
            let mut theta = t.atan_xy / 2.0;
            if rng.f01() < 0.5 {
                theta += PI;
            }
            let (s, c) = synth_sin_cos(v, theta, smooth);
            [w * radius * c, w * radius * s, 0.0]
        }
        16 => {
            // disc
            let theta = t.atan_xy / PI;
            let radius = PI * zeps(t.sumsq).powf(power / 2.0);
            let (s, c) = synth_sin_cos(v, radius, smooth);
            [w * s * theta, w * c * theta, 0.0]
        }
        17 if JWF => {
            // rings as JWildfire 9.00 computes them (`SynthFunc`, MODE_RINGS): the folded
            // radius times the waved sine and cosine of the angle.
            let mu = sqr(power) + 1e-300;
            let mut radius = t.sumsq.sqrt();
            radius += -2.0 * mu * ((radius + mu) / (2.0 * mu)) as i32 as f64 + radius * (1.0 - mu);
            let (s, c) = synth_sin_cos(v, t.atan_xy, smooth);
            [w * s * radius, w * c * radius, 0.0]
        }
        17 => {
            // rings
            let mut radius = t.sqrt;
            let theta = t.atan_xy;
            let mu = zeps(sqr(power));
            radius +=
                -2.0 * mu * trunc_i32((radius + mu) / (2.0 * mu)) as f64 + radius * (1.0 - mu);
            let (s, c) = synth_sin_cos(v, radius, smooth);
            [w * s * theta, w * c * theta, 0.0]
        }
        18 => {
            // cylinder
            let radius = zeps(t.sumsq).powf(power / 2.0);
            let (s, _) = synth_sin_cos(v, x, smooth);
            [w * radius * s, w * radius * y, 0.0]
        }
        19 => {
            // blurred ring
            let radius = 1.0 + 0.1 * (rng.f01() + rng.f01() - 1.0) * power;
            let theta = TAU * rng.f01() - PI;
            let radius = synth_lerp::<JWF>(radius, synth_value(v, theta), smooth);
            polar(radius, theta)
        }
        20 => {
            // thin ring
            let theta = TAU * rng.f01() - PI;
            let radius = zeps(rng.f01()).powf(power);
            let radius = synth_value(v, theta) + 0.1 * radius;
            polar(radius, theta)
        }
        21 | 22 => {
            // angle shifted by the synth value of the radius
            let radius = zeps(t.sumsq).powf(power / 2.0);
            let theta = t.atan_xy - 1.0 + synth_value(v, radius);
            polar(radius, theta)
        }
        23 => {
            // tangential shift
            let radius = zeps(t.sumsq).powf(power / 2.0);
            let (s, c) = t.atan_xy.fsin_cos();
            let mu = synth_value(v, radius) - 1.0;
            [w * (x + mu * c), w * (y - mu * s), 0.0]
        }
        24 => {
            let mu = synth_value(v, x) - 1.0;
            [w * x, w * (2.0 * mu - y), 0.0]
        }
        25 => {
            let mu = synth_value(v, x) - 1.0;
            let nu = synth_value(v, y) - 1.0;
            [w * (2.0 * nu - x), w * (2.0 * mu - y), 0.0]
        }
        _ => {
            // spherical, power applied after the shaping
            let theta = t.atan_xy;
            let radius = synth_lerp::<JWF>(t.sqrt, synth_value(v, theta), smooth);
            let radius = radius.powf(power);
            polar(radius, theta)
        }
    }
}

const SYNTH_PARAMS: &[Param] = synth_params!(26.0, 1.0; "b", "c", "d", "e", "f");

/// JWildfire's synth: its own shape numbers (up to 1007; others draw nothing) and smoothing
/// types (0 and 1 as Fractorium's; any other number interpolates linearly and leaves the sine
/// and cosine unshaped), not clamped to Fractorium's ranges.
pub(super) static JWF_DEFS: &[VarDef] = &[VarDef::new("synth", synth_jwildfire)
    .params(synth_params!(2147483647.0, 2147483647.0; "b", "c", "d", "e", "f"))
    .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
    .flags(flag::RANDOM)];
