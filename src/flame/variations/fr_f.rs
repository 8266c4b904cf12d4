//! Variations (slice fr_f of the registry): Fractorium's catalogue from `svf` to `ztranslate`
//! (spiral/target warps, Truchet tilings, wave displacements, the hypergon/star/lituus/super
//! shape family `w`/`x`/`y`/`z`, and the z-only helpers).
//!
//! Every formula returns the weighted output; where Fractorium does not scale by the weight
//! (the Truchet tilings, `target`, `Truchet_glyph`'s pass-through), the weight enters elsewhere
//! (as a scale of the input) or not at all, and the entry is noted as such.

use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, FRAC_PI_3, FRAC_PI_4, FRAC_PI_6, PI, TAU};

use super::util::{
    bessel_j1, erf, fract, jacobi_sn, lattice_noise, quat_mul_conj, rand_size, sine_hash, sqr,
    trunc_i32, zeps,
};
use super::*;

/// √3, √3/2 and √3/3.
const SQRT3: f64 = 1.7320508075688772;
const SQRT3_2: f64 = 0.8660254037844386;
const SQRT3_3: f64 = 0.5773502691896257;
/// 1/(2π).
const INV_TAU: f64 = FRAC_1_PI * 0.5;

// ---------------------------------------------------------------------------------------------
// Shared helpers.

/// Fractorium's rounding: half away from zero, computed as floor(x + ½) for positive values
/// and ceil(x − ½) otherwise (differs from `f64::round` just below the halves).
#[inline(always)]
fn round_half_out(x: f64) -> f64 {
    if x > 0.0 {
        (x + 0.5).floor()
    } else {
        (x - 0.5).ceil()
    }
}

/// 1/r when r is below machine epsilon (a pole), else q/r.
#[inline(always)]
fn div_or_inverse(q: f64, r: f64) -> f64 {
    if r < f64::EPSILON { 1.0 / r } else { q / r }
}

// ---------------------------------------------------------------------------------------------
// svf … taurus.

/// svf: the plane wrapped onto a sphere-like surface whose latitude bands are modulated by
/// cos(n·y) (a 3-D output).
fn svf(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [n] = v.params();
    let cn = (n * t.y).cos();
    let (sx, cx) = t.x.sin_cos();
    let (sy, cy) = t.y.sin_cos();
    [
        v.w * (cy * (cn * cx)),
        v.w * (cy * (cn * sx)),
        v.w * (sy * cn),
    ]
}

/// swirl3: a logarithmic spiral twist — each point turns by `shift`·ln r.
fn swirl3(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [shift] = v.params();
    let r = t.sqrt;
    let ang = t.atan_yx + r.ln() * shift;
    [v.w * r * ang.cos(), v.w * r * ang.sin(), 0.0]
}

/// Derived values of swirl3r: the ordered radius band and the twists at its two edges.
fn swirl3r_prep(v: &mut Prepared) {
    let [shift, a, b] = v.params();
    let lo = a.min(b);
    let hi = a.max(b);
    let twist_lo = if lo > 0.0 { lo.ln() * shift } else { 0.0 };
    let twist_hi = if hi > 0.0 { hi.ln() * shift } else { 0.0 };
    v.p.extend_from_slice(&[lo, hi, twist_lo, twist_hi]);
}

/// swirl3r: swirl3's logarithmic twist restricted to a radius band; inside and outside the
/// band the twist stays at its value on the nearer edge (rigid rotation).
fn swirl3r(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [shift] = v.params();
    let [lo, hi, twist_lo, twist_hi] = v.derived();
    let r = t.sqrt;
    let ang = if r < lo {
        t.atan_yx + twist_lo
    } else if r > hi {
        t.atan_yx + twist_hi
    } else {
        t.atan_yx + r.ln() * shift
    };
    [v.w * r * ang.cos(), v.w * r * ang.sin(), 0.0]
}

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
            0 => (u * TAU).sin(),
            1 => (u * TAU).cos(),
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
                1.0 / zeps(ang.cos()) - 1.0
            }
            _ => {
                // Inverted polygon.
                let ang = (u - 0.5) * (TAU / frq);
                let c = ang.cos();
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
fn bezier_quad_map(x: f64, m: f64) -> f64 {
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
    let end = if im < m * 2.0 { m * 2.0 } else { im };
    if x > end || m == 1.0 {
        return sign * x;
    }
    if m < 1.0 && x <= 1.0 {
        // Control points (0,0), (m,m), (1,m).
        let mut t = x;
        if (m - 0.5).abs() > 1e-10 {
            t = (-m + (m * m + (1.0 - 2.0 * m) * x).sqrt()) / (1.0 - 2.0 * m);
        }
        return sign * (x + (m - 1.0) * t * t);
    }
    if 1.0 < m && x <= 1.0 {
        // Control points (0,0), (1/m,1/m), (1,m).
        let mut t = x;
        if (m - 2.0).abs() > 1e-10 {
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

/// Apply the shaping factor m to x: linearly, or by the Bézier map when `smooth` is 1.
#[inline]
fn synth_lerp(x: f64, m: f64, smooth: i32) -> f64 {
    if smooth == 0 {
        x * m
    } else {
        bezier_quad_map(x, m)
    }
}

/// sin and cos of theta, reshaped by the synth function: multiplied by it (smooth 0) or with
/// its deviation from 1 added (otherwise).
fn synth_sin_cos(v: &Prepared, theta: f64, smooth: i32) -> (f64, f64) {
    let [_, _, _, mix] = v.params();
    let (s, c) = theta.sin_cos();
    if smooth == 0 {
        (
            s * synth_value(v, theta),
            c * synth_value(v, theta + FRAC_PI_2),
        )
    } else {
        let k = 1.0 - mix;
        (
            k * s + (synth_value(v, theta) - 1.0),
            k * c + (synth_value(v, theta + FRAC_PI_2) - 1.0),
        )
    }
}

/// synth: one of 27 classic shapes (spherical, bubble, blurs, shifts, swirl, julia, …) whose
/// radius or angle is reshaped by a configurable sum of periodic waves.
fn synth(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, power, mix, smooth] = v.params();
    let smooth = smooth as i32;
    let w = v.w;
    let (x, y) = (t.x, t.y);
    let polar = |radius: f64, theta: f64| -> V3 {
        let (s, c) = theta.sin_cos();
        [w * radius * s, w * radius * c, 0.0]
    };
    match mode as i32 {
        0 => {
            // spherical
            let radius = zeps(t.sumsq).powf((power + 1.0) / 2.0);
            let theta = t.atan_xy;
            let radius = synth_lerp(radius, synth_value(v, theta), smooth);
            polar(radius, theta)
        }
        1 => {
            // bubble
            let radius = t.sqrt / (t.sumsq / 4.0 + 1.0);
            let theta = t.atan_xy;
            let radius = synth_lerp(radius, synth_value(v, theta), smooth);
            polar(radius, theta)
        }
        2 => {
            // legacy blur
            let radius = (rng.f01() + rng.f01() + 0.002 * rng.f01()) / 2.002;
            let theta = TAU * rng.f01() - PI;
            let vx = radius * theta.sin();
            let vy = radius * theta.cos();
            let radius = zeps(radius * radius).powf(power / 2.0);
            let radius = w * synth_lerp(radius, synth_value(v, theta), smooth);
            [vx * radius, vy * radius, 0.0]
        }
        3 => {
            // blur
            let radius = 0.5 * (rng.f01() + rng.f01());
            let theta = TAU * rng.f01() - PI;
            let radius = zeps(sqr(radius)).powf(-power / 2.0);
            let radius = synth_lerp(radius, synth_value(v, theta), smooth);
            polar(radius, theta)
        }
        4 => {
            // zigzag blur along a segment
            let vy = 1.0 + 0.1 * (rng.f01() + rng.f01() - 1.0) * power;
            let theta = 2.0 * ((rng.f01() - 0.5) * 2.0).asin();
            let vy = synth_lerp(vy, synth_value(v, theta), smooth);
            [w * (theta / PI), w * (vy - 1.0), 0.0]
        }
        5 => {
            // raw circle
            let theta = t.atan_xy;
            let radius = synth_lerp(t.sqrt, synth_value(v, theta), smooth);
            polar(radius, theta)
        }
        6 => [w * synth_lerp(x, synth_value(v, y), smooth), w * y, 0.0],
        7 => [w * x, w * synth_lerp(y, synth_value(v, x), smooth), 0.0],
        8 => [
            w * synth_lerp(x, synth_value(v, y), smooth),
            w * synth_lerp(y, synth_value(v, x), smooth),
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
                w * (synth_value(v, x) - 1.0 + k * x.sin()),
                w * (synth_value(v, y) - 1.0 + k * y.sin()),
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
            let radius = synth_lerp(radius, synth_value(v, theta), smooth);
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
            let (s, c) = t.atan_xy.sin_cos();
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
            let radius = synth_lerp(t.sqrt, synth_value(v, theta), smooth);
            let radius = radius.powf(power);
            polar(radius, theta)
        }
    }
}

/// tancos: x scaled by tanh(r²)/r² and y by cos(r²)/r² (doubled).
fn tancos(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let d = zeps(t.sumsq);
    let k = v.w / d;
    [
        k * (d.tanh() * (2.0 * t.x)),
        k * (d.cos() * (2.0 * t.y)),
        0.0,
    ]
}

/// tanh_spiral: a random point on the curve (sinh t, sin(a·t)) / (cos(a·t) + cosh t),
/// t uniform in [−π, π] — a spiral-armed figure independent of the input.
fn tanh_spiral(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a] = v.params();
    let s = (rng.f01() - 0.5) * TAU;
    let den = zeps((a * s).cos() + s.cosh());
    [v.w * (s.sinh() / den), v.w * ((a * s).sin() / den), 0.0]
}

/// tanhq: the hyperbolic tangent of the quaternion (x, y, z, 0).
fn tanhq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (x, y, z) = (t.x, t.y, t.z);
    let yz_sq = sqr(y) + sqr(z);
    let yz_len = yz_sq.sqrt();
    let k = v.w / zeps(sqr(x) + yz_sq);
    let (s, c) = yz_len.sin_cos();
    let sh = x.sinh();
    let ch = x.cosh();
    let d = ch * s / zeps(yz_len);
    let b = sh * s / zeps(yz_len);
    quat_mul_conj(sh * c, d, c * ch, b, y, z, k)
}

/// tanq: the tangent of the quaternion (x, y, z, 0).
fn tanq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (x, y, z) = (t.x, t.y, t.z);
    let yz_sq = sqr(y) + sqr(z);
    let yz_len = yz_sq.sqrt();
    let k = v.w / zeps(sqr(x) + yz_sq);
    let (s, c) = x.sin_cos();
    let sh = yz_len.sinh();
    let ch = yz_len.cosh();
    let d = c * sh / zeps(yz_len);
    let b = -s * sh / zeps(yz_len);
    quat_mul_conj(s * ch, d, c * ch, b, y, z, k)
}

/// Derived value of the target family: half the ring width.
fn target_prep(v: &mut Prepared) {
    let [_, _, size] = v.params();
    let half = size * 0.5;
    v.p.push(half);
}

/// The angle of a target variation: alternate rings (of width `size`/2 in log r or in the
/// given ring coordinate `t`) are rotated by `even` and `odd`.
#[inline(always)]
fn target_angle(a: f64, t: f64, v: &Prepared) -> f64 {
    let [even, odd, size] = v.params();
    let [half] = v.derived();
    let mut s = t;
    if s < 0.0 {
        s -= half;
    }
    s = s.abs() % size;
    if s < half { a + even } else { a + odd }
}

/// target: concentric rings of equal width in log r, alternately rotated by two angles
/// (Fractorium's version ignores the weight).
fn target(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = target_angle(t.atan_yx, t.sqrt.ln(), v);
    [t.sqrt * a.cos(), t.sqrt * a.sin(), 0.0]
}

/// target0: target, weighted.
fn target0(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = target_angle(t.atan_yx, t.sqrt.ln(), v);
    [t.sqrt * a.cos() * v.w, t.sqrt * a.sin() * v.w, 0.0]
}

/// target2: target with spiral rings — the ring coordinate also grows with the angle, and
/// `thightness` scales log r.
fn target2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, tightness] = v.params();
    let a = t.atan_yx;
    let ring = tightness * t.sqrt.ln() + FRAC_1_PI * (a + PI);
    let a = target_angle(a, ring, v);
    [t.sqrt * a.cos() * v.w, t.sqrt * a.sin() * v.w, 0.0]
}

/// Derived values of taurus: inv·r, 1 − inv, 1 − sor.
fn taurus_prep(v: &mut Prepared) {
    let [r, _, inv, sor] = v.params();
    v.p.extend_from_slice(&[inv * r, 1.0 - inv, 1.0 - sor]);
}

/// taurus: the plane wrapped onto a torus-like surface whose tube radius ripples n times
/// around (`inv` blends toward a plain torus, `sor` toward a surface of revolution).
fn taurus(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [r, n, _, sor] = v.params();
    let [inv_r, one_minus_inv, one_minus_sor] = v.derived();
    let (sx, cx) = t.x.sin_cos();
    let (sy, cy) = t.y.sin_cos();
    let ir = inv_r + (one_minus_inv * (r * (n * t.x).cos()));
    [
        v.w * (cx * (ir + sy)),
        v.w * (sx * (ir + sy)),
        v.w * (sor * cy) + (one_minus_sor * t.y),
    ]
}

/// Derived value of tile_hlp: the weighted tile width.
fn tile_hlp_prep(v: &mut Prepared) {
    let [width] = v.params();
    let vw = width * v.w;
    v.p.push(vw);
}

/// tile_hlp: copies the plane and randomly shifts points by one tile width along x, with a
/// probability that fades smoothly across each tile (a soft half-plane tiling).
fn tile_hlp(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [width] = v.params();
    let [width_w] = v.derived();
    let x = t.x / width;
    let pos = x > 0.0;
    let k = trunc_i32(x) as f64;
    let frac = if pos { x - k } else { x + k };
    let shift = if (frac * PI).cos() < rng.f11() {
        if pos { -width_w } else { width_w }
    } else {
        0.0
    };
    [v.w * t.x + shift, v.w * t.y, 0.0]
}

/// tile_log: copies the plane at integer x offsets drawn from a two-sided, geometrically
/// decaying distribution (`spread` its scale).
fn tile_log(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [spread] = v.params();
    let l = rng.f01().ln();
    let shift = round_half_out(l * if rng.bit() { spread } else { -spread });
    [v.w * (t.x + shift), v.w * t.y, 0.0]
}

/// Derived values of trade: the two disc centres' distances from the origin.
fn trade_prep(v: &mut Prepared) {
    let [r1, d1, r2, d2] = v.params();
    v.p.extend_from_slice(&[r1 + d1, r2 + d2]);
}

/// trade: swaps two discs — points inside the disc right of the y axis (radius r1) move,
/// rescaled and mirrored, into the disc left of it (radius r2), and vice versa.
fn trade(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [r1, _, r2] = v.params();
    let [c1, c2] = v.derived();
    let w = v.w;
    if t.x > 0.0 {
        let dx = c1 - t.x;
        let mut r = (sqr(dx) + sqr(t.y)).sqrt();
        if r <= r1 {
            r *= r2 / r1;
            let a = t.y.atan2(dx);
            return [w * (r * a.cos() - c2), w * r * a.sin(), 0.0];
        }
    } else {
        let dx = -c2 - t.x;
        let mut r = (sqr(dx) + sqr(t.y)).sqrt();
        if r <= r2 {
            r *= r1 / r2;
            let a = t.y.atan2(dx);
            return [w * (r * a.cos() + c1), w * r * a.sin(), 0.0];
        }
    }
    [w * t.x, w * t.y, 0.0]
}

// ---------------------------------------------------------------------------------------------
// The Truchet tilings.

/// A Truchet tile's pair of quarter-arc distances: the superellipse radii (exponent `n`,
/// 1/n = `inv_n`) of the point (x, y) in the unit cell from the two corners the tile type
/// joins (`straight`: the corners (0, 0) and (1, 1), else the other two).
#[inline(always)]
fn truchet_radii(x: f64, y: f64, straight: bool, n: f64, inv_n: f64) -> (f64, f64) {
    let (a, b) = if straight { (x, x - 1.0) } else { (x - 1.0, x) };
    (
        (a.abs().powf(n) + y.abs().powf(n)).powf(inv_n),
        (b.abs().powf(n) + (y - 1.0).abs().powf(n)).powf(inv_n),
    )
}

/// Position within the unit cell centred on the nearest integer (rounded by `round`), moved
/// to [0, 1).
#[inline(always)]
fn cell_frac(x: f64, rounded: f64) -> f64 {
    let r = x - rounded;
    if r < 0.0 { 1.0 + r } else { r }
}

/// Derived values of Truchet.
fn truchet_prep(v: &mut Prepared) {
    let [_, exponent, _, rotation, _, seed] = v.params();
    let exponent = exponent.clamp(f64::EPSILON, 2.0);
    // Fractorium derives the arc width from the exponent (its arc-width parameter is unused).
    let arc = exponent.clamp(f64::EPSILON, 1.0);
    let inv_ex = 1.0 / exponent;
    let abs_seed = seed.abs();
    let seed2 = zeps(abs_seed * 1.5).sqrt() / zeps(abs_seed * 0.5) * 0.25;
    let inv_rmax = 1.0 / (0.5 * (2f64.powf(inv_ex) - 1.0) * arc);
    let scale = (rotation.cos() + rotation.sin()) / v.w;
    v.p.extend_from_slice(&[exponent, inv_ex, abs_seed, seed2, inv_rmax, scale]);
}

/// Truchet: the plane (scaled by 1/weight) kept only on Truchet tiles — two quarter-circle
/// (superellipse) bands per unit cell, with the tile orientation chosen per cell by a
/// seeded hash (`extended` 0 or flam3-compatibility off: a slower iterated hash).
fn truchet(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [extended, _, _, _, size] = v.params();
    let [exponent, inv_ex, abs_seed, seed2, inv_rmax, scale] = v.derived();
    let extended = trunc_i32(extended) == 0 || !v.compat;
    let x0 = t.x * scale;
    let y0 = t.y * scale;
    let x = cell_frac(x0, trunc_i32(round_half_out(x0)) as f64);
    let y = cell_frac(y0, trunc_i32(round_half_out(y0)) as f64);
    let tile = if abs_seed == 0.0 {
        0.0
    } else if abs_seed == 1.0 {
        1.0
    } else if extended {
        let xr = round_half_out(t.x) * seed2;
        let yr = round_half_out(t.y) * seed2;
        let mix = xr + yr + xr * yr;
        let h = (mix + abs_seed) * seed2 * 0.5;
        let h = (h * 32747.0 + 12345.0) % 65535.0;
        h % 2.0
    } else {
        let xi = trunc_i32(round_half_out(t.x));
        let yi = trunc_i32(round_half_out(t.y));
        let mix = xi
            .wrapping_add(yi)
            .wrapping_add(xi.wrapping_mul(yi))
            .wrapping_abs();
        let mut h = abs_seed.floor() + mix as f64;
        let mut k = 0;
        while k < mix && k < 20 {
            k += 1;
            h = (h * 32747.0 + 12345.0) % 65535.0;
        }
        h % 2.0
    };
    // The two drawing modes read the tile type with opposite orientations.
    let straight = if extended { tile < 1.0 } else { tile == 1.0 };
    let (r0, r1) = truchet_radii(x, y, straight, exponent, inv_ex);
    let cx = size * (x + t.x.floor());
    let cy = size * (y + t.y.floor());
    let mut out = [0.0; 3];
    if (r0 - 0.5).abs() * inv_rmax < 1.0 {
        out[0] = cx;
        out[1] = cy;
    }
    if (r1 - 0.5).abs() * inv_rmax < 1.0 {
        out[0] += cx;
        out[1] += cy;
    }
    out
}

/// Derived values of Truchet_fill.
fn truchet_fill_prep(v: &mut Prepared) {
    let [exponent, arc_width, seed] = v.params();
    let ex = exponent.clamp(0.001, 2.0);
    let inv_ex = 1.0 / ex;
    let width = arc_width.clamp(0.001, 1.0);
    let seed2 = (seed * 1.5).sqrt() / zeps(seed * 0.5) * 0.25;
    let rmax = zeps(0.5 * (2f64.powf(inv_ex) - 1.0) * width);
    v.p.extend_from_slice(&[ex, inv_ex, seed2, rmax, 1.0 / v.w]);
}

/// Truchet_fill: the complement-style Truchet map — points of the (1/weight-scaled) plane
/// are sent to twice their cell position on each arc band they lie in, minus the input,
/// filling the tile pattern.
fn truchet_fill(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, seed] = v.params();
    let [ex, inv_ex, seed2, rmax, scale] = v.derived();
    let x0 = t.x * scale;
    let y0 = t.y * scale;
    let x = cell_frac(x0, round_half_out(x0));
    let y = cell_frac(y0, round_half_out(y0));
    let tile = if seed == 0.0 {
        0.0
    } else if seed == 1.0 {
        seed
    } else {
        let xr = round_half_out(t.x.abs()) * seed2;
        let yr = round_half_out(t.y.abs()) * seed2;
        let mix = xr + yr + xr * yr;
        let h = (seed + mix) * seed2 * 0.5;
        let h = (h * 32747.0 + 12345.0) % 65535.0;
        h % 2.0
    };
    let (r0, r1) = truchet_radii(x, y, tile < 1.0, ex, inv_ex);
    let cx = 2.0 * (x + t.x.floor());
    let cy = 2.0 * (y + t.y.floor());
    let (x1, y1) = if (r0 - 0.5).abs() / rmax < 1.0 {
        (cx, cy)
    } else {
        (0.0, 0.0)
    };
    if (r1 - 0.5).abs() / rmax < 1.0 {
        [x1 + cx - t.x, y1 + cy - t.y, 0.0]
    } else {
        [x1 - t.x, y1 - t.y, 0.0]
    }
}

/// Derived values of Truchet_glyph.
fn truchet_glyph_prep(v: &mut Prepared) {
    let [exponent, arc_width, amp, max, angle] = v.params();
    let n = exponent.clamp(0.001, 2.0);
    let width = arc_width.clamp(0.001, 1.0);
    let inv_n = 1.0 / zeps(n);
    let rmax = zeps(0.5 * (2f64.powf(inv_n) - 1.0) * width);
    let rads = angle * (PI / 180.0);
    let half_amp_max = amp * 0.5 * max;
    let amp = zeps(amp);
    let scale = 1.0 / v.w;
    v.p.extend_from_slice(&[
        n,
        inv_n,
        rmax,
        scale,
        rads.cos(),
        rads.sin(),
        half_amp_max,
        amp,
    ]);
}

/// Truchet_glyph: Truchet_fill (hash-chosen tiles) applied only inside rotated squares
/// ("glyphs") centred on an `amp`-spaced grid; elsewhere the input passes unchanged.
fn truchet_glyph(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, _, _, seed] = v.params();
    let [n, inv_n, rmax, scale, cost, sint, half_amp_max, amp] = v.derived();
    let x1 = t.x * scale;
    let y1 = t.y * scale;
    let x = cell_frac(x1, (x1 + 0.5).floor());
    let y = cell_frac(y1, (y1 + 0.5).floor());
    let tile = if seed == 0.0 {
        0.0
    } else if seed == 1.0 {
        1.0
    } else {
        let xr = (t.x.abs() + 0.5).floor();
        let yr = (t.y.abs() + 0.5).floor();
        let h = sine_hash(xr, yr, seed);
        let h = (h * 32747.0 + 12345.0) % 65535.0;
        h % 2.0
    };
    let (r0, r1) = truchet_radii(x, y, tile < 1.0, n, inv_n);
    let cx = (x + t.x.floor()) * 2.0;
    let cy = (y + t.y.floor()) * 2.0;
    let (ax, ay) = if (r0 - 0.5).abs() / rmax < 1.0 {
        (cx, cy)
    } else {
        (0.0, 0.0)
    };
    let gx = t.x - ((t.x / amp).floor() + 0.5) * amp;
    let gy = t.y - ((t.y / amp).floor() + 0.5) * amp;
    let rx = cost * gx + sint * gy;
    let ry = -sint * gx + cost * gy;
    if rx.abs() + ry.abs() < half_amp_max {
        if (r1 - 0.5).abs() / rmax < 1.0 {
            [ax + cx - t.x, ay + cy - t.y, 0.0]
        } else {
            [ax - t.x, ay - t.y, 0.0]
        }
    } else {
        [t.x, t.y, 0.0]
    }
}

/// Derived values of Truchet_hex_crop: the outer and inner radii of the arc band.
fn truchet_hex_crop_prep(v: &mut Prepared) {
    let [wd] = v.params();
    v.p.extend_from_slice(&[0.5 + wd, 0.5 - wd]);
}

/// The nearest hexagon centre of (x, y) (unit hexagons, pointy side up) and its cube
/// coordinates (rx, rz), by rounding cube coordinates.
#[inline(always)]
fn hex_centre(x: f64, y: f64) -> (f64, f64, f64, f64) {
    let y3 = y / 3.0;
    let cx = SQRT3_3 * x - y3;
    let cz = 2.0 * y3;
    let cy = -cx - cz;
    let (rx, ry, rz) = (cx.round(), cy.round(), cz.round());
    let dx = (rx - cx).abs();
    let dy = (ry - cy).abs();
    let dz = (rz - cz).abs();
    // The coordinate that rounded worst is rebuilt from the other two (x + y + z = 0); the
    // y coordinate itself is not needed.
    let (rx, rz) = if dx > dy && dx > dz {
        (-ry - rz, rz)
    } else if dy > dz {
        (rx, rz)
    } else {
        (rx, -rx - ry)
    };
    (SQRT3 * rx + SQRT3_2 * rz, 1.5 * rz, rx, rz)
}

/// Truchet_hex_crop: hexagonal Truchet tiles of three arcs each — points on the arc bands
/// (width 2·`wd`) are removed (collapsed to the origin, to the arc's corner, or pushed to the
/// band's edges, by `mode`), or, with `inv`, the points off the bands are.
fn truchet_hex_crop(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, inv, seed] = v.params();
    let [d1, d2] = v.derived();
    let (hx, hy, rx, rz) = hex_centre(t.x, t.y);
    let mut fx = t.x - hx;
    let mut fy = t.y - hy;
    let mut add = 0.0;
    if seed == 1.0 {
        if trunc_i32(rx) & 1 == 0 && trunc_i32(rz) & 1 == 0 {
            add = FRAC_PI_3;
        }
    } else if seed >= 2.0 && sine_hash(hx, hy, seed) < 0.5 {
        add = FRAC_PI_3;
    }
    // The corner of the hexagon nearest in angle: the centre of this arc.
    let coef = 0.477464829275686; // 1.5/π
    let angle = fy.atan2(fx) + FRAC_PI_6 - add;
    let corner = (angle * coef).floor() / coef + FRAC_PI_6 + add;
    let (y0, x0) = corner.sin_cos();
    let dist = (sqr(fx - x0) + sqr(fy - y0)).sqrt();
    let hit = if inv != 0.0 {
        dist > d1 || dist < d2
    } else {
        dist < d1 && dist > d2
    };
    if hit {
        if mode < 0.5 {
            fx = 0.0;
            fy = 0.0;
        } else if mode < 1.5 {
            fx = x0;
            fy = y0;
        } else {
            let a = (fy - y0).atan2(fx - x0);
            let d = if rng.f01() < 0.5 { d1 } else { d2 };
            fx = x0 + a.cos() * d;
            fy = y0 + a.sin() * d;
        }
    }
    [(fx + hx) * v.w, (fy + hy) * v.w, 0.0]
}

/// Derived values of Truchet_hex_fill: 3n and 1/(3n).
fn truchet_hex_fill_prep(v: &mut Prepared) {
    let [n] = v.params();
    let n3 = 3.0 * n;
    v.p.extend_from_slice(&[n3, 1.0 / zeps(n3)]);
}

/// Truchet_hex_fill: fills random hexagons (geometrically spread around the origin) with
/// three-arc Truchet tiles — the input, wrapped around a ring in one of 3n sectors, is
/// split into the three arcs of a hexagon.
fn truchet_hex_fill(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, flipx, flipy, sx, sy, seed] = v.params();
    let [n3, inv_n3] = v.derived();
    let l = rng.f01().ln();
    let rx = (l * if rng.f01() < 0.5 { sx } else { -sx }).floor();
    let l = rng.f01().ln();
    let rz = (l * if rng.f01() < 0.5 { sy } else { -sy }).floor();
    let hx = SQRT3 * rx + SQRT3_2 * if rng.f01() < 0.5 { rz } else { -rz };
    let hy = 1.5 * rz;
    let mut add = true;
    if seed == 1.0 {
        if trunc_i32(rx) & 1 == 0 && trunc_i32(rz) & 1 == 0 {
            add = false;
        }
    } else if seed >= 2.0 && sine_hash(hx, hy, seed) < 0.5 {
        add = false;
    }
    let sector = (rng.f01() * n3).floor() * TAU * inv_n3;
    let ya = if flipy != 0.0 && !add { -t.y } else { t.y };
    let xa = if flipx != 0.0 && !add { -t.x } else { t.x };
    let ang = ya * inv_n3 * PI + sector;
    let a = 1.0 + xa * inv_n3 * PI;
    let fx = a * ang.cos();
    let fy = a * ang.sin();
    // Which third of the circle: move that arc's centre to the origin.
    let mut th = fy.atan2(fx);
    if th < 0.0 {
        th += TAU;
    }
    let third = (1.5 * th * FRAC_1_PI).floor();
    let ang = (PI + third * TAU) / 3.0;
    let nx = fx - ang.cos() * 2.0;
    let ny = fy - ang.sin() * 2.0;
    // Rotate by ±30° into the hexagon.
    let (fx, fy) = if add {
        (SQRT3_2 * nx - 0.5 * ny, 0.5 * nx + SQRT3_2 * ny)
    } else {
        (SQRT3_2 * nx + 0.5 * ny, -0.5 * nx + SQRT3_2 * ny)
    };
    [v.w * (fx * 0.5 + hx), v.w * (fy * 0.5 + hy), 0.0]
}

/// Derived values of Truchet_inv.
fn truchet_inv_prep(v: &mut Prepared) {
    let [exponent, arc_width, rotation, _, seed] = v.params();
    let n = exponent.clamp(0.001, 2.0);
    let width = arc_width.clamp(0.001, 1.0);
    let seed2 = (seed * 1.5).sqrt() / zeps(seed * 0.5) * 0.25;
    let inv_n = 1.0 / zeps(n);
    let rmax = zeps(0.5 * (2f64.powf(inv_n) - 1.0) * width);
    let scale = (rotation.cos() + rotation.sin()) / v.w;
    v.p.extend_from_slice(&[n, inv_n, rmax, seed2, seed2 * 0.5, scale]);
}

/// Truchet_inv: the negative of Truchet — the (1/weight-scaled) plane kept only off both arc
/// bands of each tile.
fn truchet_inv(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, size, seed] = v.params();
    let [n, inv_n, rmax, seed2, seed2_half, scale] = v.derived();
    let x1 = t.x * scale;
    let y1 = t.y * scale;
    let x = cell_frac(x1, (x1 + 0.5).floor());
    let y = cell_frac(y1, (y1 + 0.5).floor());
    let tile = if seed == 0.0 {
        0.0
    } else if seed == 1.0 {
        1.0
    } else {
        let xr = (t.x + 0.5).floor() * seed2;
        let yr = (t.y + 0.5).floor() * seed2;
        let mix = xr + yr + xr * yr;
        let h = (mix + seed) * seed2_half;
        let h = (h * 32747.0 + 12345.0) % 65535.0;
        h % 2.0
    };
    let (r0, r1) = truchet_radii(x, y, tile < 1.0, n, inv_n);
    if (r0 - 0.5).abs() / rmax > 1.0 && (r1 - 0.5).abs() / rmax > 1.0 {
        [(x + t.x.floor()) * size, (y + t.y.floor()) * size, 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// truchet_knot: random points on short strokes centred in each unit cell, horizontal or
/// vertical in a checkerboard pattern (a woven-knot look).
fn truchet_knot(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    const WIDTH: f64 = 0.5;
    const SPACE: f64 = 0.1;
    let cx = t.x.floor();
    let cy = t.y.floor();
    let along = (rng.f01() - 0.5) * WIDTH;
    let across = (rng.f01() * 2.0 - 1.0) * (1.0 - SPACE - WIDTH * 0.5);
    let parity = (cx + cy).abs();
    let parity = parity - 2.0 * (parity * 0.5).floor();
    let (dx, dy) = if parity < 0.5 {
        (along, across)
    } else {
        (-across, along)
    };
    [v.w * (cx + dx), v.w * (cy + dy), 0.0]
}

/// twoface: the right half-plane inverted (divided by r²), the left half passed through.
fn twoface(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let mut r = v.w;
    if t.x > 0.0 {
        r /= t.sumsq;
    }
    [r * t.x, r * t.y, 0.0]
}

/// Derived values of unicorngaloshen: the sine frequencies times π.
fn unicorngaloshen_prep(v: &mut Prepared) {
    let [_, _, _, _, fx, _, fy] = v.params();
    v.p.extend_from_slice(&[PI * fx, PI * fy]);
}

/// unicorngaloshen: a quadratic map (x − y)(x + m_y·y), x·y divided by an elliptic radius,
/// with optional sine modulation of its two factors (by x, y, e⁻ˣ, 1/x, log|x| or angles).
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
        (1.0 + ax * (u * pi_fx).sin(), 2.0 + ay * (w * pi_fy).sin())
    };
    [fx * (x - y) * (x + my * y) * r, fy * x * y * r, 0.0]
}

/// Derived value of unpolar: weight/(2π).
fn unpolar_prep(v: &mut Prepared) {
    let k = (v.w / PI) * 0.5;
    v.p.push(k);
}

/// unpolar: the inverse of polar — x read as an angle and y as log-radius.
fn unpolar(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let r = t.y.exp();
    let (s, c) = t.x.sin_cos();
    [k * r * s, k * r * c, 0.0]
}

/// Derived values of vibration: for each of the two waves, cos/sin of its direction and of
/// direction + displacement angle, the angular frequency and the phase shift.
fn vibration_prep(v: &mut Prepared) {
    let [dir, angle, freq, _, phase, dir2, angle2, freq2, _, phase2] = v.params();
    for (dir, angle, freq, phase) in [(dir, angle, freq, phase), (dir2, angle2, freq2, phase2)] {
        let tot = angle + dir;
        v.p.extend_from_slice(&[
            dir.cos(),
            dir.sin(),
            tot.cos(),
            tot.sin(),
            freq * TAU,
            TAU * phase / zeps(freq),
        ]);
    }
}

/// vibration: two superposed plane waves, each displacing points by amp·sin(phase along its
/// direction) along its own displacement angle.
fn vibration(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, amp, _, _, _, _, amp2] = v.params();
    let waves = v.table(0);
    let (mut x, mut y) = (t.x, t.y);
    for (amp, d) in [(amp, &waves[..6]), (amp2, &waves[6..12])] {
        let along = t.x * d[0] + t.y * d[1];
        let a = amp * ((along * d[4]) + d[5]).sin();
        x += a * d[2];
        y += a * d[3];
    }
    [v.w * x, v.w * y, 0.0]
}

/// Derived values of vibration2: for each wave, cos/sin of its direction, its angular
/// frequency and phase shift.
fn vibration2_prep(v: &mut Prepared) {
    let [dir, _, freq, _, phase, dir2, _, freq2, _, phase2] = v.params();
    for (dir, freq, phase) in [(dir, freq, phase), (dir2, freq2, phase2)] {
        v.p.extend_from_slice(&[dir.cos(), dir.sin(), freq * TAU, TAU * phase / zeps(freq)]);
    }
}

/// amp·cos(2π·freq·x): vibration2's modulation of a wave parameter along the wave.
#[inline(always)]
fn modulate(amp: f64, freq: f64, x: f64) -> f64 {
    amp * (x * freq * TAU).cos()
}

/// vibration2: vibration whose direction, displacement angle, frequency and amplitude are
/// themselves modulated along each wave.
fn vibration2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [
        dir,
        angle,
        freq,
        amp,
        _phase,
        dir2,
        angle2,
        freq2,
        amp2,
        _phase2,
        dm,
        dmfreq,
        tm,
        tmfreq,
        fm,
        fmfreq,
        am,
        amfreq,
        dm2,
        dmfreq2,
        tm2,
        tmfreq2,
        fm2,
        fmfreq2,
        am2,
        amfreq2,
    ] = v.params();
    let [
        cos_dir,
        sin_dir,
        omega,
        shift,
        cos_dir2,
        sin_dir2,
        omega2,
        shift2,
    ] = v.derived();
    let (mut x, mut y) = (t.x, t.y);
    // Per wave: base parameters, modulation parameters (amount and frequency of the direction,
    // tilt, frequency and amplitude modulations), derived values.
    for ([dir, angle, freq, amp], m, d) in [
        (
            [dir, angle, freq, amp],
            [dm, dmfreq, tm, tmfreq, fm, fmfreq, am, amfreq],
            [cos_dir, sin_dir, omega, shift],
        ),
        (
            [dir2, angle2, freq2, amp2],
            [dm2, dmfreq2, tm2, tmfreq2, fm2, fmfreq2, am2, amfreq2],
            [cos_dir2, sin_dir2, omega2, shift2],
        ),
    ] {
        let along = t.x * d[0] + t.y * d[1];
        let dir_m = dir + modulate(m[0], m[1], along);
        let tilt_m = angle + modulate(m[2], m[3], along);
        let phase_m = modulate(m[4], m[5], along) / zeps(freq);
        let amp_m = amp + amp * modulate(m[6], m[7], along);
        let tilt_dir = tilt_m + dir_m;
        let (sd, cd) = dir_m.sin_cos();
        let along = t.x * cd + t.y * sd;
        let a = amp_m * ((along * d[2]) + phase_m + d[3]).sin();
        x += a * tilt_dir.cos();
        y += a * tilt_dir.sin();
    }
    [v.w * x, v.w * y, 0.0]
}

/// Derived values of vignette: |inner radius|, |fade radius|, 1/|power|.
fn vignette_prep(v: &mut Prepared) {
    let [_, _, inner, fade, power] = v.params();
    v.p.extend_from_slice(&[inner.abs(), fade.abs(), 1.0 / power.abs()]);
}

/// vignette: keeps the disc around (posx, posy) and randomly thins and blurs the points
/// beyond it over the fade distance (a negative fade radius inverts the fade; a negative
/// inner radius empties the disc).
fn vignette(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [posx, posy, inner, fade_r, _, blur] = v.params();
    let [inner_abs, fade_abs, pow_inv] = v.derived();
    let (mut px, mut py) = (t.x, t.y);
    let dist = ((px - posx) * (px - posx) + (py - posy) * (py - posy)).sqrt();
    if dist < inner_abs {
        if inner < 0.0 {
            return [0.0; 3];
        }
        return [px * v.w, py * v.w, 0.0];
    }
    let dist = (dist - inner_abs) / fade_abs;
    let fade = 1.0 - rng.f01().powf(pow_inv);
    let blur_r = blur * (dist * rng.f01()).powf(2.0);
    let blur_a = rng.f01() * TAU;
    let dropped = if fade_r > 0.0 {
        fade < dist
    } else {
        1.0 - fade > dist
    };
    if dropped {
        px = 0.0;
        py = 0.0;
    } else {
        px += blur_r * blur_a.cos();
        py += blur_r * blur_a.sin();
    }
    [px * v.w, py * v.w, 0.0]
}

/// Voron: Voronoi cells of hashed seed points (1 … `Num` per grid square of side `Step`);
/// each point is pulled toward its cell's seed, keeping the fraction K of its offset.
fn voron(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k, step, num, xseed, yseed] = v.params();
    let m = trunc_i32((t.x / step).floor());
    let n = trunc_i32((t.y / step).floor());
    let mut nearest = 20.0;
    let (mut x0, mut y0) = (0.0, 0.0);
    for i in -1..2 {
        let ci = m.wrapping_add(i);
        for j in -1..2 {
            let cj = n.wrapping_add(j);
            let cell = 19i32.wrapping_mul(ci).wrapping_add(257i32.wrapping_mul(cj));
            let count = 1.0 + (num * lattice_noise(trunc_i32(cell as f64 + xseed))).floor();
            let kx = 64 * ci as i64 + 15 * cj as i64;
            let ky = 21 * ci as i64 + 33 * cj as i64;
            let mut l = 0.0;
            while l < count {
                let li = l as i64;
                let sx = (lattice_noise(trunc_i32((li + kx) as f64 + xseed)) + ci as f64) * step;
                let sy = (lattice_noise(trunc_i32((li + ky) as f64 + yseed)) + cj as f64) * step;
                let r = (sqr(t.x - sx) + sqr(t.y - sy)).sqrt();
                if r < nearest {
                    nearest = r;
                    x0 = sx;
                    y0 = sy;
                }
                l += 1.0;
            }
        }
    }
    [
        v.w * (k * (t.x - x0) + x0),
        v.w * (k * (t.y - y0) + y0),
        0.0,
    ]
}

// ---------------------------------------------------------------------------------------------
// The shape family w, x, y, z: a radius profile summed from a hypergon, a star, a lituus
// spiral and a superformula curve, each weighted by its amount.

/// The 13 parameters of a shape profile: for the hypergon, the star, the lituus and the
/// superformula curve, each curve's amount and settings.
type ShapeParams = [f64; 13];

/// The values derived from a shape profile's parameters: hypergon D, −a of the lituus, tan of
/// the star slope, m/4 and −1/n1 of the superformula.
fn shape_derived(shape: &ShapeParams) -> [f64; 5] {
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
    ] = *shape;
    let hyper_d = (1.0 + sqr(hypergon_r)).sqrt();
    let lituus_exp = -lituus_a;
    // tan(π/2) is infinite: an almost-vertical slope backs off by 0.05 rad.
    let tan_slope = if (slope - FRAC_PI_2).abs() < 1e-6 {
        (slope - 0.05).tan()
    } else {
        slope.tan()
    };
    let super_m4 = super_m / 4.0;
    let super_exp = -1.0 / zeps(super_n1);
    [hyper_d, lituus_exp, tan_slope, super_m4, super_exp]
}

/// Derived values of x, y and z (see [`shape_derived`]).
fn shape_prep(v: &mut Prepared) {
    let shape = v.params();
    v.p.extend(shape_derived(&shape));
}

/// Derived values of w, whose shape parameters follow its angle (see [`shape_derived`]).
fn shape_prep_w(v: &mut Prepared) {
    let [_angle, shape @ ..] = v.params::<14>();
    v.p.extend(shape_derived(&shape));
}

/// The radius profile at angle `a` of the shape with parameters `shape` and derived values
/// `derived`.
fn shape_total(shape: &ShapeParams, derived: [f64; 5], a: f64) -> f64 {
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
        super_n2,
        super_n3,
    ] = *shape;
    let [hyper_d, lituus_exp, tan_slope, super_m4, super_exp] = derived;
    let mut sum = 0.0;
    if hypergon != 0.0 {
        let n = hypergon_n;
        let s = (a.abs() % (TAU / n)) - PI / n;
        let sec2 = sqr(s.tan()) + 1.0;
        let d2 = sqr(hyper_d);
        if sec2 >= d2 {
            sum += hypergon;
        } else {
            sum += hypergon * (hyper_d - (d2 - sec2).sqrt()) / sec2.sqrt();
        }
    }
    if star != 0.0 {
        let n = star_n;
        let tn = ((a.abs() % (TAU / n)) - PI / n).abs().tan();
        sum += star * (sqr(tan_slope) * (1.0 + sqr(tn)) / sqr(tn + tan_slope)).sqrt();
    }
    if lituus != 0.0 {
        sum += lituus * (a / PI + 1.0).abs().powf(lituus_exp);
    }
    if super_ != 0.0 {
        let (s, c) = (a * super_m4).sin_cos();
        sum += super_ * (c.abs().powf(super_n2) + s.abs().powf(super_n3)).powf(super_exp);
    }
    sum
}

/// w: points inside the shape profile (the profile at their own angle) are rotated by
/// `w_angle` and rescaled to the profile at the new angle; points outside pass through.
fn w_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [angle, shape @ ..] = v.params::<14>();
    let d = v.derived();
    let a = t.atan_yx;
    let r = t.sqrt;
    let mut turned = a + angle;
    if turned < -PI {
        turned += TAU;
    }
    if turned > PI {
        turned -= TAU;
    }
    let reach = shape_total(&shape, d, a);
    if r <= reach {
        let reach2 = shape_total(&shape, d, turned);
        let r = v.w * reach2 * r / reach;
        let (s, c) = turned.sin_cos();
        [r * c, r * s, 0.0]
    } else {
        [v.w * t.x, v.w * t.y, 0.0]
    }
}

/// x: the radius pushed out to √(r² + profile²) along each ray.
fn x_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = t.atan_yx;
    let reach = shape_total(&v.params(), v.derived(), a);
    let r = v.w * (t.sumsq + sqr(reach)).sqrt();
    let (s, c) = a.sin_cos();
    [r * c, r * s, 0.0]
}

/// y: inversion in the shape profile — radius profile²/r along each ray.
fn y_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = t.atan_yx;
    let reach = shape_total(&v.params(), v.derived(), a);
    let r = v.w * sqr(reach) / t.sqrt;
    let (s, c) = a.sin_cos();
    [r * c, r * s, 0.0]
}

/// z: the radius increased by the shape profile along each ray.
fn z_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = t.atan_yx;
    let reach = shape_total(&v.params(), v.derived(), a);
    let r = v.w * (t.sqrt + reach);
    let (s, c) = a.sin_cos();
    [r * c, r * s, 0.0]
}

// ---------------------------------------------------------------------------------------------
// waffle … wdisc.

/// Derived values of waffle: weight·sin and weight·cos of the rotation.
fn waffle_prep(v: &mut Prepared) {
    let [_, _, _, rotation] = v.params();
    let (s, c) = rotation.sin_cos();
    let w = v.w;
    v.p.extend_from_slice(&[w * s, w * c]);
}

/// waffle: random points on a rotated grid of `slices`×`slices` bars in the unit square
/// (bar thickness `xthickness`, `ythickness`), independent of the input.
fn waffle(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [slices, xt, yt] = v.params();
    let [sinr, cosr] = v.derived();
    let (a, r) = match rng.below(5) {
        0 => {
            let a = (rand_size(rng, slices) + rng.f01() * xt) / slices;
            let r = (rand_size(rng, slices) + rng.f01() * yt) / slices;
            (a, r)
        }
        1 => {
            let a = (rand_size(rng, slices) + rng.f01()) / slices;
            let r = (rand_size(rng, slices) + yt) / slices;
            (a, r)
        }
        2 => {
            let a = (rand_size(rng, slices) + xt) / slices;
            let r = (rand_size(rng, slices) + rng.f01()) / slices;
            (a, r)
        }
        3 => {
            let a = rng.f01();
            let r = (rand_size(rng, slices) + yt + rng.f01() * (1.0 - yt)) / slices;
            (a, r)
        }
        _ => {
            let a = (rand_size(rng, slices) + xt + rng.f01() * (1.0 - xt)) / slices;
            (a, rng.f01())
        }
    };
    [cosr * a + sinr * r, -sinr * a + cosr * r, 0.0]
}

/// waves22: each coordinate displaced by a power of a sine wave of the other (or of a
/// raised sine, by mode).
fn waves22(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scx, scy, fx, fy, modex, modey, powerx, powery] = v.params();
    let px = trunc_i32(powerx) as f64;
    let py = trunc_i32(powery) as f64;
    let sx = if modex < 0.5 {
        (t.y * fx).sin()
    } else {
        0.5 * (1.0 + (t.y * fx).sin())
    };
    let sy = if modey < 0.5 {
        (t.x * fy).sin()
    } else {
        0.5 * (1.0 + (t.x * fy).sin())
    };
    [
        v.w * (t.x + sx.powf(px) * scx),
        v.w * (t.y + sy.powf(py) * scy),
        0.0,
    ]
}

/// Derived values of waves23: the frequencies divided by 2π.
fn waves23_prep(v: &mut Prepared) {
    let [_, _, fx, fy] = v.params();
    v.p.extend_from_slice(&[fx * INV_TAU, fy * INV_TAU]);
}

/// waves23: each coordinate displaced by a sawtooth-like wave of the other.
fn waves23(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scalex, scaley] = v.params();
    let [freqx, freqy] = v.derived();
    let saw = |u: f64| {
        let f = fract(u);
        if f > 0.5 { 0.5 - f } else { f }
    };
    let fx = saw(t.y * freqx);
    let fy = saw(t.x * freqy);
    [v.w * (t.x + fx * scalex), v.w * (t.y + fy * scaley), 0.0]
}

/// waves2_3D: waves2 in 3-D — x and y displaced by sines of each other, z by a sine of
/// their mean.
fn waves2_3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [freq, scale] = v.params();
    let avg = (t.x + t.y) * 0.5;
    [
        v.w * (t.x + scale * (t.y * freq).sin()),
        v.w * (t.y + scale * (t.x * freq).sin()),
        v.w * (t.z + scale * (avg * freq).sin()),
    ]
}

/// waves2_radial: waves2 whose amplitude grows linearly with r from 0 at `null` to full at
/// `distance`.
fn waves2_radial(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [fx, sx, fy, sy, null, dist] = v.params();
    let r = t.sqrt;
    let mut k = if r < dist {
        (r - null) / zeps(dist - null)
    } else {
        1.0
    };
    if r < null {
        k = 0.0;
    }
    [
        v.w * (t.x + k * (t.y * fx).sin() * sx),
        v.w * (t.y + k * (t.x * fy).sin() * sy),
        0.0,
    ]
}

/// Derived values of waves2b: scale − scaleinf for x and y.
fn waves2b_prep(v: &mut Prepared) {
    let [_, _, _, _, sx, sinfx, sy, sinfy] = v.params();
    v.p.extend_from_slice(&[sx - sinfx, sy - sinfy]);
}

/// waves2b: waves2 with a wave amplitude falling off with distance (from `scale` near the
/// axis to `scaleinf` far away) and a power-warped wave argument; an exponent near 0 uses
/// a Jacobi sn wave (≥ 0) or the Bessel function J1 (< 0) instead of the sine.
fn waves2b(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [freqx, freqy, pwx, pwy, _, sinfx, _, sinfy, unity, jacok] = v.params();
    let [six, siy] = v.derived();
    let csx = div_or_inverse(unity, unity + sqr(t.x)) * six + sinfx;
    let csy = div_or_inverse(unity, unity + sqr(t.y)) * siy + sinfy;
    let wave = |u: f64, pw: f64, freq: f64| -> f64 {
        if (0.0..1e-4).contains(&pw) {
            jacobi_sn(u * freq, jacok)
        } else if pw < 0.0 && pw > -1e-4 {
            bessel_j1(u * freq)
        } else {
            (util::sign_nz(u) * zeps(u.abs()).powf(pw) * freq).sin()
        }
    };
    [
        v.w * (t.x + csx * wave(t.y, pwx, freqx)),
        v.w * (t.y + csy * wave(t.x, pwy, freqy)),
        0.0,
    ]
}

/// Derived values of waves3: half scales.
fn waves3_prep(v: &mut Prepared) {
    let [sx, sy] = v.params();
    v.p.extend_from_slice(&[sx * 0.5, sy * 0.5]);
}

/// waves3: waves2 whose amplitudes are themselves sine-modulated (frequencies `sx_freq`,
/// `sy_freq`).
fn waves3(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, freqx, freqy, sx_freq, sy_freq] = v.params();
    let [half_sx, half_sy] = v.derived();
    let scx = half_sx * (1.0 + (t.y * sx_freq).sin());
    let scy = half_sy * (1.0 + (t.x * sy_freq).sin());
    [
        v.w * (t.x + (t.y * freqx).sin() * scx),
        v.w * (t.y + (t.x * freqy).sin() * scy),
        0.0,
    ]
}

/// Derived value of waves4 and waves42: yfact/1000.
fn waves4_prep(v: &mut Prepared) {
    let [_, _, _, _, _, yfact] = v.params();
    let k = yfact * 0.001;
    v.p.push(k);
}

/// The pseudo-random band amplitude of waves4/waves42 for band index `band` at height y
/// (binarised when `cont` is 1).
#[inline(always)]
fn band_amp(band: f64, y: f64, yfact: f64, cont: f64) -> f64 {
    let h = (band * 12.9898 + band * 78.233 + 1.0 + y * yfact).sin() * 43758.5453;
    let h = h - trunc_i32(h) as f64;
    if cont == 1.0 {
        if h > 0.5 { 1.0 } else { 0.0 }
    } else {
        h
    }
}

/// waves4: waves2 whose x amplitude is random per wave period (horizontal bands).
fn waves4(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scalex, scaley, freqx, freqy, cont] = v.params();
    let [yfact] = v.derived();
    let band = (t.y * freqx / TAU).floor();
    let ax = band_amp(band, t.y, yfact, cont);
    [
        v.w * (t.x + (t.y * freqx).sin() * ax * ax * scalex),
        v.w * (t.y + (t.x * freqy).sin() * scaley),
        0.0,
    ]
}

/// waves42: waves4 with the band width set independently (`freqx2`).
fn waves42(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scalex, scaley, freqx, freqy, cont, _, freqx2] = v.params();
    let [yfact] = v.derived();
    let band = (t.y * freqx2).floor();
    let ax = band_amp(band, t.y, yfact, cont);
    [
        v.w * (t.x + (t.y * freqx).sin() * ax * ax * scalex),
        v.w * (t.y + (t.x * freqy).sin() * scaley),
        0.0,
    ]
}

/// Derived values of wavesn: the power actually used (0 becomes 2), the number of roots and
/// the radius exponent.
fn wavesn_prep(v: &mut Prepared) {
    let [_, _, _, _, _, _, mut power] = v.params();
    if power == 0.0 {
        power = 2.0;
    }
    let roots = trunc_i32(power.abs()) as f64;
    v.p.extend_from_slice(&[power, roots, 1.0 / power / 2.0]);
}

/// wavesn: a random n-th root (julian-like, n = `power`) followed by waves whose amplitude
/// can grow with distance (`incx`, `incy`).
fn wavesn(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [freqx, freqy, scalex, scaley, incx, incy] = v.params();
    let [power, roots, cn] = v.derived();
    let angle = (t.atan_yx + TAU * rand_size(rng, roots)) / power;
    let r = v.w * t.sumsq.powf(cn);
    let (sa, ca) = angle.sin_cos();
    let ux = r * ca;
    let uy = r * sa;
    let sy = (freqx * uy).sin();
    let sx = (freqy * ux).sin();
    let dx = ux + 0.5 * (scalex * sy + ux.abs() * incx * sy);
    let dy = uy + 0.5 * (scaley * sx + uy.abs() * incy * sx);
    [v.w * dx, v.w * dy, 0.0]
}

/// wdisc: a disc-like map — the angle/π becomes the radius and the radius bends the
/// direction (mirrored for positive angles).
fn wdisc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let mut a = PI / (t.sqrt + 1.0);
    let r = t.atan_yx * FRAC_1_PI;
    if r > 0.0 {
        a = PI - a;
    }
    [v.w * r * a.cos(), v.w * r * a.sin(), 0.0]
}

/// xerf: the error function applied to each coordinate (3-D); coordinates of magnitude ≥ 2
/// are inverted in the unit sphere instead.
fn xerf(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = sqr((t.sumsq + sqr(t.z)).sqrt());
    let f = |u: f64| if u.abs() >= 2.0 { u / r2 } else { erf(u) };
    [v.w * f(t.x), v.w * f(t.y), v.w * f(t.z)]
}

/// Derived values of xheart: cos and sin of the rotation π/4 + angle·π/8, and the stretch
/// 6 + 2·ratio.
fn xheart_prep(v: &mut Prepared) {
    let [angle, ratio] = v.params();
    let ang = FRAC_PI_4 + (0.5 * FRAC_PI_4 * angle);
    let (s, c) = ang.sin_cos();
    let rat = 6.0 + 2.0 * ratio;
    v.p.extend_from_slice(&[c, s, rat]);
}

/// xheart: a heart shape — the point is shrunk by 1/(r² + 4), stretched, rotated by 45°
/// (adjustable), and its left half mirrored in x.
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

/// Derived values of xtrb: the triangle (angles 0.047 + a, 0.047 + b and the rest, inradius
/// `radius`) — its side lengths, heights and their ratios, the band widths, and the root
/// count and radius exponent of the final power map.
fn xtrb_prep(v: &mut Prepared) {
    let [power, radius, width, dist, a, b] = v.params();
    let br = 0.047 + a;
    let cr = 0.047 + b;
    let ar = PI - br - cr;
    let (sa2, ca2) = (ar / 2.0).sin_cos();
    let (sb2, cb2) = (br / 2.0).sin_cos();
    let (sc2, cc2) = (cr / 2.0).sin_cos();
    let (sinc, cosc) = cr.sin_cos();
    let la = radius * (sc2 / cc2 + sb2 / cb2);
    let lb = radius * (sc2 / cc2 + sa2 / ca2);
    let lc = radius * (sb2 / cb2 + sa2 / ca2);
    let s2 = radius * (la + lb + lc);
    let ha = s2 / la / 6.0;
    let hb = s2 / lb / 6.0;
    let hc = s2 / lc / 6.0;
    let power = if power == 0.0 { 2.0 } else { power };
    v.p.extend_from_slice(&[
        sinc,
        cosc,
        ha,
        hb,
        hc,
        la / lb,
        la / lc,
        lb / la,
        lb / lc,
        lc / la,
        lc / lb,
        6.0 * ha,
        6.0 * hb,
        6.0 * hc,
        s2 / (la + lb) / 6.0,
        s2 / (la + lc) / 6.0,
        s2 / (lb + lc) / 6.0,
        1.0 - width,
        2.0 * width,
        1.0 - width * width,
        power,
        trunc_i32(power.abs()) as f64,
        dist / power / 2.0,
    ]);
}

/// xtrb's per-triangle map in trilinear coordinates (al, be, ga): points are pulled into a
/// hexagonal band pattern inside the triangle, randomly (with probability 1 − width²) or
/// scaled by `width` toward the nearest vertex.
fn xtrb_hex(hex: &[f64; 16], al: f64, be: f64, ga: f64, rng: &mut FastRng) -> (f64, f64) {
    let [
        width,
        ha,
        hb,
        hc,
        ab,
        ba,
        ca,
        cb,
        s2a,
        s2b,
        s2ab,
        s2ac,
        s2bc,
        w1,
        w2,
        w3,
    ] = *hex;
    let r = rng.f01();
    if be < al {
        if ga < be {
            let (side, gam) = if r >= w3 {
                (width * be, width * ga)
            } else {
                (
                    w1 * be + w2 * s2ab * (3.0 - ga / be),
                    w1 * ga + w2 * hc * ga / be,
                )
            };
            (s2a - ba * side - ca * gam, side)
        } else if ga < al {
            let (side, gam) = if r >= w3 {
                (width * be, width * ga)
            } else {
                (
                    w1 * be + w2 * hb * be / ga,
                    w1 * ga + w2 * s2ac * (3.0 - be / ga),
                )
            };
            (s2a - ba * side - ca * gam, side)
        } else if r >= w3 {
            (width * al, width * be)
        } else {
            (
                w1 * al + w2 * s2ac * (3.0 - be / al),
                w1 * be + w2 * hb * be / al,
            )
        }
    } else if ga < al {
        let (side, gam) = if r >= w3 {
            (width * al, width * ga)
        } else {
            (
                w1 * al + w2 * s2ab * (3.0 - ga / al),
                w1 * ga + w2 * hc * ga / al,
            )
        };
        (side, s2b - ab * side - cb * gam)
    } else if ga < be {
        let (side, gam) = if r >= w3 {
            (width * al, width * ga)
        } else {
            (
                w1 * al + w2 * ha * al / ga,
                w1 * ga + w2 * s2bc * (3.0 - al / ga),
            )
        };
        (side, s2b - ab * side - cb * gam)
    } else if r >= w3 {
        (width * al, width * be)
    } else {
        (
            w1 * al + w2 * ha * al / be,
            w1 * be + w2 * s2bc * (3.0 - al / be),
        )
    }
}

/// xtrb: a triangular tiling (in trilinear coordinates) with hexagonal bands in each
/// triangle, followed by a random root of a power map (as julian, n = `power`).
fn xtrb(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, radius, width] = v.params();
    let [
        sinc,
        cosc,
        ha,
        hb,
        hc,
        ab,
        ac,
        ba,
        bc,
        ca,
        cb,
        s2a,
        s2b,
        s2c,
        s2ab,
        s2ac,
        s2bc,
        w1,
        w2,
        w3,
        power,
        roots,
        cn,
    ] = v.derived();
    let hex = [
        width, ha, hb, hc, ab, ba, ca, cb, s2a, s2b, s2ab, s2ac, s2bc, w1, w2, w3,
    ];
    // To trilinear coordinates (distances from two sides of the triangle).
    let al = t.y + radius;
    let be = t.x * sinc - t.y * cosc + radius;
    let m = (al / s2a).floor();
    let n = (be / s2b).floor();
    let mut oa = al - m * s2a;
    let mut ob = be - n * s2b;
    let og = s2c - ac * oa - bc * ob;
    let (mut al, mut be);
    if og > 0.0 {
        (al, be) = xtrb_hex(&hex, oa, ob, og, rng);
    } else {
        oa = s2a - oa;
        ob = s2b - ob;
        (al, be) = xtrb_hex(&hex, oa, ob, -og, rng);
        al = s2a - al;
        be = s2b - be;
    }
    al += m * s2a;
    be += n * s2b;
    // Back to the plane, then the power map.
    let ix = (be - radius + (al - radius) * cosc) / sinc;
    let iy = al - radius;
    let angle = (iy.atan2(ix) + TAU * rand_size(rng, roots)) / power;
    let r = v.w * (sqr(ix) + sqr(iy)).powf(cn);
    let (s, c) = angle.sin_cos();
    [v.w * (r * c), v.w * (r * s), 0.0]
}

// ---------------------------------------------------------------------------------------------
// The z helpers.

/// zblur: a random z offset (sum of four uniforms, bell-shaped in [−2, 2]·weight).
fn zblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let s = rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0;
    [0.0, 0.0, v.w * s]
}

/// zcone: z set to the distance from the z axis (a cone); as a pre_/post_ form x and y pass
/// through.
fn zcone(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let z = v.w * t.sqrt;
    if v.form == Form::Regular {
        [0.0, 0.0, z]
    } else {
        [t.x, t.y, z]
    }
}

/// zscale: z scaled by the weight (x, y contribute nothing).
fn zscale(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [0.0, 0.0, v.w * t.z]
}

/// ztranslate: z shifted by the weight.
fn ztranslate(v: &Prepared, _: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [0.0, 0.0, v.w]
}

// ---------------------------------------------------------------------------------------------
// Registry entries.

/// The thirteen shape parameters of the w/x/y/z family, `PREFIX_hypergon` … `PREFIX_super_n3`,
/// after any leading ones given.
macro_rules! shape_params {
    ($pre:literal $(, $lead:expr)*) => {
        &[
            $($lead,)*
            p(concat!($pre, "_hypergon"), 0.0),
            p_int(concat!($pre, "_hypergon_n"), 4.0, 3.0, f64::INFINITY),
            p(concat!($pre, "_hypergon_r"), 1.0),
            p(concat!($pre, "_star"), 0.0),
            p_int(concat!($pre, "_star_n"), 5.0, 3.0, f64::INFINITY),
            p_range(concat!($pre, "_star_slope"), 2.0, f64::EPSILON, FRAC_PI_2),
            p(concat!($pre, "_lituus"), 0.0),
            p(concat!($pre, "_lituus_a"), 1.0),
            p(concat!($pre, "_super"), 0.0),
            p(concat!($pre, "_super_m"), 1.0),
            p(concat!($pre, "_super_n1"), 1.0),
            p(concat!($pre, "_super_n2"), 1.0),
            p(concat!($pre, "_super_n3"), 1.0),
        ]
    };
}

const SHAPE_X: &[Param] = shape_params!("x");
const SHAPE_Y: &[Param] = shape_params!("y");
const SHAPE_Z: &[Param] = shape_params!("z");
const SHAPE_W: &[Param] = shape_params!("w", p_cyclic("w_angle", 0.0, -PI, PI));

/// synth's parameters: five global ones, then six per wave layer (`synth_L`, `_type`, `_skew`,
/// `_frq`, `_phs`, `_layer`) for the layers named.
macro_rules! synth_params {
    ($($layer:literal),*) => {
        &[
            p("synth_a", 0.0),
            p_int("synth_mode", 3.0, 0.0, 26.0),
            p("synth_power", -2.0),
            p("synth_mix", 0.0),
            p_int("synth_smooth", 0.0, 0.0, 1.0),
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

const SYNTH_PARAMS: &[Param] = synth_params!("b", "c", "d", "e", "f");

const POLAR_NEEDS: u8 = need::SUMSQ | need::SQRT | need::ATAN_YX;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("svf", svf)
        .params(&[p("svf_n", 2.0)])
        .flags(flag::WRITES_Z),
    VarDef::new("swirl3", swirl3)
        .params(&[p("swirl3_shift", 0.5)])
        .needs(POLAR_NEEDS),
    VarDef::new("swirl3r", swirl3r)
        .params(&[
            p("swirl3r_shift", 0.5),
            p_range("swirl3r_min", 0.5, 0.0, f64::INFINITY),
            p_range("swirl3r_max", 1.0, 0.0, f64::INFINITY),
        ])
        .needs(POLAR_NEEDS)
        .prepare(swirl3r_prep),
    VarDef::new("synth", synth)
        .batch(super::inline_batch!(synth))
        .params(SYNTH_PARAMS)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(flag::RANDOM),
    VarDef::new("tancos", tancos).needs(need::SUMSQ),
    VarDef::new("tanh_spiral", tanh_spiral)
        .params(&[p("tanh_spiral_a", 4.0)])
        .flags(flag::RANDOM),
    VarDef::new("tanhq", tanhq).flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("tanq", tanq).flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("target", target)
        .params(&[
            p_cyclic("target_even", 0.0, 0.0, TAU),
            p_cyclic("target_odd", 0.0, 0.0, TAU),
            p_range("target_size", 1.0, f64::EPSILON, f64::INFINITY),
        ])
        .needs(POLAR_NEEDS)
        .prepare(target_prep),
    VarDef::new("target0", target0)
        .params(&[
            p_cyclic("target0_even", 0.0, 0.0, TAU),
            p_cyclic("target0_odd", 0.0, 0.0, TAU),
            p_range("target0_size", 0.0, 0.0, f64::INFINITY),
        ])
        .needs(POLAR_NEEDS)
        .prepare(target_prep),
    VarDef::new("target2", target2)
        .params(&[
            p_cyclic("target2_even", 0.0, 0.0, TAU),
            p_cyclic("target2_odd", 0.0, 0.0, TAU),
            p_range("target2_size", 1.0, f64::EPSILON, f64::INFINITY),
            p("target2_thightness", 0.0),
        ])
        .needs(POLAR_NEEDS)
        .prepare(target_prep),
    VarDef::new("taurus", taurus)
        .params(&[
            p("taurus_r", 3.0),
            p("taurus_n", 5.0),
            p("taurus_inv", 1.5),
            p("taurus_sor", 1.0),
        ])
        .flags(flag::WRITES_Z)
        .prepare(taurus_prep),
    VarDef::new("tile_hlp", tile_hlp)
        .batch(super::inline_batch!(tile_hlp))
        .params(&[p_nonzero(
            "tile_hlp_width",
            1.0,
            f64::NEG_INFINITY,
            f64::INFINITY,
        )])
        .flags(flag::RANDOM)
        .prepare(tile_hlp_prep),
    VarDef::new("tile_log", tile_log)
        .batch(super::inline_batch!(tile_log))
        .params(&[p("tile_log_spread", 1.0)])
        .flags(flag::RANDOM),
    VarDef::new("trade", trade)
        .params(&[
            p_range("trade_r1", 1.0, f64::EPSILON, f64::INFINITY),
            p_range("trade_d1", 1.0, 0.0, f64::INFINITY),
            p_range("trade_r2", 1.0, f64::EPSILON, f64::INFINITY),
            p_range("trade_d2", 1.0, 0.0, f64::INFINITY),
        ])
        .prepare(trade_prep),
    VarDef::new("Truchet", truchet)
        .params(&[
            p("Truchet_extended", 1.0),
            p_nonzero("Truchet_exponent", 2.0, f64::EPSILON, 2.0),
            p_nonzero("Truchet_arc_width", 0.5, f64::EPSILON, 1.0),
            p("Truchet_rotation", 0.0),
            p_range("Truchet_size", 1.0, f64::EPSILON, f64::INFINITY),
            p("Truchet_seed", 50.0),
        ])
        .flags(flag::COMPAT)
        .prepare(truchet_prep),
    VarDef::new("Truchet_fill", truchet_fill)
        .params(&[
            p_cyclic("Truchet_fill_exponent", 2.0, 0.001, 2.0),
            p_cyclic("Truchet_fill_arc_width", 0.5, 0.001, 1.0),
            p("Truchet_fill_seed", 0.0),
        ])
        .prepare(truchet_fill_prep),
    VarDef::new("Truchet_glyph", truchet_glyph)
        .params(&[
            p_range("Truchet_glyph_exponent", 2.0, 0.0, 2.0),
            p("Truchet_glyph_arc_width", 0.5),
            p_nonzero("Truchet_glyph_amp", 6.0, f64::EPSILON, f64::INFINITY),
            p_range("Truchet_glyph_max", 0.9, 0.0, f64::INFINITY),
            p("Truchet_glyph_angle", 45.0),
            p("Truchet_glyph_seed", 1.0),
        ])
        .prepare(truchet_glyph_prep),
    VarDef::new("Truchet_hex_crop", truchet_hex_crop)
        .params(&[
            p_range("Truchet_hex_crop_wd", 0.2, 0.0, 5.0),
            p_int("Truchet_hex_crop_mode", 0.0, 0.0, 2.0),
            p_int("Truchet_hex_crop_inv", 0.0, 0.0, 1.0),
            p_int(
                "Truchet_hex_crop_seed",
                0.0,
                f64::NEG_INFINITY,
                f64::INFINITY,
            ),
        ])
        .prepare(truchet_hex_crop_prep),
    VarDef::new("Truchet_hex_fill", truchet_hex_fill)
        .params(&[
            p_int("Truchet_hex_fill_n", 3.0, f64::NEG_INFINITY, f64::INFINITY),
            p_int("Truchet_hex_fill_flipx", 1.0, 0.0, 1.0),
            p_int("Truchet_hex_fill_flipy", 1.0, 0.0, 1.0),
            p("Truchet_hex_fill_spreadx", 1.0),
            p("Truchet_hex_fill_spready", 1.0),
            p_int(
                "Truchet_hex_fill_seed",
                0.0,
                f64::NEG_INFINITY,
                f64::INFINITY,
            ),
        ])
        .flags(flag::RANDOM)
        .prepare(truchet_hex_fill_prep),
    VarDef::new("Truchet_inv", truchet_inv)
        .params(&[
            p_range("Truchet_inv_exponent", 2.0, 0.0, 2.0),
            p("Truchet_inv_arc_width", 0.5),
            p("Truchet_inv_rotation", 0.0),
            p_range("Truchet_inv_size", 1.0, 0.0, f64::INFINITY),
            p("Truchet_inv_seed", 1.0),
        ])
        .prepare(truchet_inv_prep),
    VarDef::new("truchet_knot", truchet_knot).flags(flag::RANDOM),
    VarDef::new("twoface", twoface).needs(need::SUMSQ),
    VarDef::new("unicorngaloshen", unicorngaloshen)
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
    VarDef::new("unpolar", unpolar).prepare(unpolar_prep),
    VarDef::new("vibration", vibration)
        .params(&[
            p_cyclic("vibration_dir", 0.0, 0.0, TAU),
            p_cyclic("vibration_angle", FRAC_PI_2, 0.0, TAU),
            p("vibration_freq", 1.0),
            p("vibration_amp", 0.25),
            p_cyclic("vibration_phase", 0.0, 0.0, 1.0),
            p_cyclic("vibration_dir2", FRAC_PI_2, 0.0, TAU),
            p_cyclic("vibration_angle2", FRAC_PI_2, 0.0, TAU),
            p("vibration_freq2", 1.0),
            p("vibration_amp2", 0.25),
            p_cyclic("vibration_phase2", 0.0, 0.0, 1.0),
        ])
        .prepare(vibration_prep),
    VarDef::new("vibration2", vibration2)
        .params(&[
            p("vibration2_dir", 0.0),
            p("vibration2_angle", FRAC_PI_2),
            p("vibration2_freq", 1.0),
            p("vibration2_amp", 0.25),
            p("vibration2_phase", 0.0),
            p("vibration2_dir2", FRAC_PI_2),
            p("vibration2_angle2", FRAC_PI_2),
            p("vibration2_freq2", 1.0),
            p("vibration2_amp2", 0.25),
            p("vibration2_phase2", 0.0),
            p("vibration2_dm", 0.0),
            p("vibration2_dmfreq", 0.0),
            p("vibration2_tm", 0.0),
            p("vibration2_tmfreq", 0.0),
            p("vibration2_fm", 0.0),
            p("vibration2_fmfreq", 0.0),
            p("vibration2_am", 0.0),
            p("vibration2_amfreq", 0.0),
            p("vibration2_dm2", 0.0),
            p("vibration2_dmfreq2", 0.0),
            p("vibration2_tm2", 0.0),
            p("vibration2_tmfreq2", 0.0),
            p("vibration2_fm2", 0.0),
            p("vibration2_fmfreq2", 0.0),
            p("vibration2_am2", 0.0),
            p("vibration2_amfreq2", 0.0),
        ])
        .prepare(vibration2_prep),
    VarDef::new("vignette", vignette)
        .params(&[
            p("vignette_posx", 0.0),
            p("vignette_posy", 0.0),
            p("vignette_inner_radius", 0.5),
            p_nonzero(
                "vignette_fade_radius",
                0.5,
                f64::NEG_INFINITY,
                f64::INFINITY,
            ),
            p_nonzero("vignette_power", 4.0, f64::NEG_INFINITY, f64::INFINITY),
            p("vignette_blur", 1.0),
        ])
        .flags(flag::RANDOM)
        .prepare(vignette_prep),
    VarDef::new("Voron", voron).params(&[
        p("Voron_K", 0.99),
        p_nonzero("Voron_Step", 0.25, f64::NEG_INFINITY, f64::INFINITY),
        p_int("Voron_Num", 1.0, 1.0, 25.0),
        p_int("Voron_XSeed", 3.0, f64::NEG_INFINITY, f64::INFINITY),
        p_int("Voron_YSeed", 7.0, f64::NEG_INFINITY, f64::INFINITY),
    ]),
    VarDef::new("w", w_var)
        .params(SHAPE_W)
        .needs(POLAR_NEEDS)
        .prepare(shape_prep_w),
    VarDef::new("waffle", waffle)
        .params(&[
            p_nonzero("waffle_slices", 6.0, f64::NEG_INFINITY, f64::INFINITY),
            p("waffle_xthickness", 0.5),
            p("waffle_ythickness", 0.5),
            p("waffle_rotation", 0.0),
        ])
        .flags(flag::RANDOM)
        .sum()
        .prepare(waffle_prep),
    VarDef::new("waves22", waves22).params(&[
        p("waves22_scalex", 0.05),
        p("waves22_scaley", 0.05),
        p("waves22_freqx", 7.0),
        p("waves22_freqy", 13.0),
        p_int("waves22_modex", 0.0, 0.0, 1.0),
        p_int("waves22_modey", 0.0, 0.0, 1.0),
        p("waves22_powerx", 2.0),
        p("waves22_powery", 2.0),
    ]),
    VarDef::new("waves23", waves23)
        .params(&[
            p("waves23_scalex", 0.05),
            p("waves23_scaley", 0.05),
            p("waves23_freqx", 7.0),
            p("waves23_freqy", 13.0),
        ])
        .prepare(waves23_prep),
    VarDef::new("waves2_3D", waves2_3d)
        .params(&[p("waves2_3D_freq", 2.0), p("waves2_3D_scale", 1.0)])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("waves2_radial", waves2_radial)
        .params(&[
            p("waves2_radial_freqx", 7.0),
            p("waves2_radial_scalex", 0.1),
            p("waves2_radial_freqy", 13.0),
            p("waves2_radial_scaley", 0.1),
            p("waves2_radial_null", 2.0),
            p("waves2_radial_distance", 10.0),
        ])
        .needs(need::SUMSQ | need::SQRT),
    VarDef::new("waves2b", waves2b)
        .params(&[
            p("waves2b_freqx", 2.0),
            p("waves2b_freqy", 2.0),
            p_range("waves2b_pwx", 1.0, -10.0, 10.0),
            p_range("waves2b_pwy", 1.0, -10.0, 10.0),
            p("waves2b_scalex", 1.0),
            p("waves2b_scaleinfx", 1.0),
            p("waves2b_scaley", 1.0),
            p("waves2b_scaleinfy", 1.0),
            p("waves2b_unity", 1.0),
            p_range("waves2b_jacok", 0.25, -1.0, 1.0),
        ])
        .prepare(waves2b_prep),
    VarDef::new("waves3", waves3)
        .params(&[
            p("waves3_scalex", 0.05),
            p("waves3_scaley", 0.05),
            p("waves3_freqx", 7.0),
            p("waves3_freqy", 13.0),
            p("waves3_sx_freq", 0.0),
            p("waves3_sy_freq", 2.0),
        ])
        .prepare(waves3_prep),
    VarDef::new("waves4", waves4)
        .params(&[
            p("waves4_scalex", 0.05),
            p("waves4_scaley", 0.05),
            p("waves4_freqx", 7.0),
            p("waves4_freqy", 13.0),
            p_int("waves4_cont", 0.0, 0.0, 1.0),
            p("waves4_yfact", 0.1),
        ])
        .prepare(waves4_prep),
    VarDef::new("waves42", waves42)
        .params(&[
            p("waves42_scalex", 0.05),
            p("waves42_scaley", 0.05),
            p("waves42_freqx", 7.0),
            p("waves42_freqy", 13.0),
            p_int("waves42_cont", 0.0, 0.0, 1.0),
            p("waves42_yfact", 0.1),
            p("waves42_freqx2", 1.0),
        ])
        .prepare(waves4_prep),
    VarDef::new("wavesn", wavesn)
        .params(&[
            p("wavesn_freqx", 2.0),
            p("wavesn_freqy", 2.0),
            p("wavesn_scalex", 1.0),
            p("wavesn_scaley", 1.0),
            p("wavesn_incx", 0.0),
            p("wavesn_incy", 0.0),
            p("wavesn_power", 1.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(wavesn_prep),
    VarDef::new("wdisc", wdisc).needs(POLAR_NEEDS),
    VarDef::new("x", x_var)
        .params(SHAPE_X)
        .needs(need::SUMSQ | need::ATAN_YX)
        .prepare(shape_prep),
    VarDef::new("xerf", xerf)
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("xheart", xheart)
        .params(&[p("xheart_angle", 0.0), p("xheart_ratio", 0.0)])
        .needs(need::SUMSQ)
        .prepare(xheart_prep),
    VarDef::new("xtrb", xtrb)
        .params(&[
            p_int_nonzero("xtrb_power", 2.0, f64::NEG_INFINITY, f64::INFINITY),
            p("xtrb_radius", 1.0),
            p("xtrb_width", 0.5),
            p("xtrb_dist", 1.0),
            p("xtrb_a", 1.0),
            p("xtrb_b", 1.0),
        ])
        .flags(flag::RANDOM)
        .prepare(xtrb_prep),
    VarDef::new("y", y_var)
        .params(SHAPE_Y)
        .needs(POLAR_NEEDS)
        .prepare(shape_prep),
    VarDef::new("z", z_var)
        .params(SHAPE_Z)
        .needs(POLAR_NEEDS)
        .prepare(shape_prep),
    VarDef::new("zblur", zblur)
        .batch(super::inline_batch!(zblur))
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
    VarDef::new("zcone", zcone)
        .batch(super::inline_batch!(zcone))
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::WRITES_Z),
    VarDef::new("zscale", zscale)
        .batch(super::inline_batch!(zscale))
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("ztranslate", ztranslate)
        .batch(super::inline_batch!(ztranslate))
        .flags(flag::WRITES_Z)
        .sum(),
];
