//! JWildfire's random shapes and curves: `meeple` (the board-game figure, outlined or
//! filled), `waveblur_wf` (a blur of concentric waves, with an optional z ripple and direct
//! colour), `conicalSpiral` (a spiral on a cone driven by one coordinate) and
//! `intersection` (two crossing bands of tiles, the weight unused as in JWildfire) and
//! `spirograph3D` (a random point of a hypotrochoid lifted into 3-D, widened by `mode`).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew.

use std::f64::consts::{PI, TAU};

use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("meeple", meeple)
        .params(&[
            p("meeple_scale", 2.5),
            p_range("meeple_filled", 1.0, 0.0, 1.0),
            p("meeple_headWidth", 1.0),
            p("meeple_headHeight", 1.0),
            p("meeple_armLength", 2.0),
            p("meeple_armSpread", 1.0),
            p("meeple_bodyWidth", 1.0),
            p("meeple_legHeight", 1.0),
            p("meeple_legSpread", 1.0),
            p("meeple_legSeparationWidth", 0.1),
            p("meeple_legSeparationHeight", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .prepare(meeple_prepare),
    VarDef::new("waveblur_wf", waveblur_wf)
        .params(&[
            p_int("waveblur_wf_count", 5.0, 1.0, INF),
            p("waveblur_wf_phase", 0.0),
            p("waveblur_wf_amplitude_z", 0.5),
            p_range("waveblur_wf_damping_z", 0.0, 0.0, INF),
            p_int("waveblur_wf_direct_color", 0.0, 0.0, 1.0),
            p("waveblur_wf_color_scale", 0.5),
            p("waveblur_wf_color_offset", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR),
    VarDef::new("conicalSpiral", conical_spiral)
        .params(&[
            p("conicalSpiral_turns", 8.0),
            p("conicalSpiral_radius", 1.2),
            p("conicalSpiral_height", 1.0),
            p_int("conicalSpiral_mode", 0.0, 0.0, 3.0),
            p("conicalSpiral_z_wave_freq", 0.0),
            p("conicalSpiral_z_wave_amp", 0.0),
            p("conicalSpiral_twist", 0.0),
            p("conicalSpiral_thickness", 0.0),
            p_int("conicalSpiral_solid", 0.0, 0.0, 1.0),
            p_int("conicalSpiral_colorize", 0.0, 0.0, 1.0),
            p_int("conicalSpiral_colorMode", 0.0, 0.0, 4.0),
            p("conicalSpiral_colorSpeed", 1.0),
            p("conicalSpiral_colorOffset", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR),
    VarDef::new("intersection", intersection)
        .params(&[
            p("intersection_xwidth", 5.0),
            p("intersection_xtilesize", 0.5),
            p("intersection_xmod1", 0.3),
            p("intersection_xmod2", 1.0),
            p("intersection_xheight", 0.5),
            p("intersection_yheight", 5.0),
            p("intersection_ytilesize", 0.5),
            p("intersection_ymod1", 0.3),
            p("intersection_ymod2", 1.0),
            p("intersection_ywidth", 0.5),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("spirograph3D", spirograph3d)
        .params(&[
            p("spirograph3D_a", 1.0),
            p("spirograph3D_b", -0.3),
            p("spirograph3D_c", 0.4),
            p("spirograph3D_tmin", 0.0),
            p("spirograph3D_tmax", 1000.0),
            p("spirograph3D_width", 0.0),
            p_int("spirograph3D_mode", 0.0, 0.0, 4.0),
            p_int("spirograph3D_direct_color", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR),
];

/// The meeple's outline (its right half, from the foot up to the head's top).
const MEEPLE_X: [f64; 14] = [
    0.00, 0.15, 0.28, 0.35, 0.35, 0.40, 0.55, 0.55, 0.45, 0.40, 0.45, 0.40, 0.20, 0.00,
];
const MEEPLE_Y: [f64; 14] = [
    -1.00, -0.99, -0.90, -0.75, -0.60, -0.50, -0.45, -0.25, -0.15, 0.10, 0.80, 0.98, 1.00, 0.85,
];

/// The outline's 14 points shaped by the parameters (x then y), appended to the parameters.
fn meeple_prepare(v: &mut Prepared) {
    let [
        _,
        _,
        hw,
        hh,
        arm_len,
        arm_spread,
        body,
        leg_h,
        leg_spread,
        sep_w,
        sep_h,
    ] = v.params();
    let sep_y = MEEPLE_Y[9] - sep_h;
    let mut xs = MEEPLE_X;
    let mut ys = MEEPLE_Y;
    for i in 0..14 {
        match i {
            0..=4 => {
                xs[i] *= hw;
                ys[i] *= hh;
            }
            5..=8 => {
                xs[i] = MEEPLE_X[4] * body + (MEEPLE_X[i] - MEEPLE_X[4]) * arm_len;
                ys[i] = MEEPLE_Y[4] * hh + (MEEPLE_Y[i] - MEEPLE_Y[4]) * arm_spread;
            }
            9 => {
                xs[i] *= body;
                ys[i] = sep_y;
            }
            _ => {
                let off = MEEPLE_Y[i] - MEEPLE_Y[9];
                ys[i] = if i == 13 {
                    sep_y + off * leg_h
                } else {
                    MEEPLE_Y[9] + off * leg_h
                };
                if i <= 12 {
                    xs[i] = MEEPLE_X[i] * leg_spread + sep_w;
                }
            }
        }
    }
    v.p.extend_from_slice(&xs);
    v.p.extend_from_slice(&ys);
}

/// meeple: a uniform point of the outline (mirrored at random), pulled towards the centre
/// by a uniform factor with probability `filled`.
fn meeple(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scale, filled, ..] = v.params::<11>();
    let d: [f64; 28] = v.derived();
    let (xs, ys) = d.split_at(14);
    let scaled = rng.f01() * 13.0;
    let k = (scaled as usize).min(12);
    let f = scaled - k as f64;
    let mut lx = xs[k] + f * (xs[k + 1] - xs[k]);
    let ly = ys[k] + f * (ys[k + 1] - ys[k]);
    if rng.f01() < 0.5 {
        lx = -lx;
    }
    let r = if filled > 0.0 && filled > rng.f01() {
        rng.f01()
    } else {
        1.0
    };
    [r * lx * scale * v.w, r * ly * scale * v.w, 0.0]
}

/// JWildfire's `random(n)`: ⌊u·n⌋ for a uniform u, at most n − 1.
fn index_below(rng: &mut FastRng, n: i32) -> f64 {
    let k = (rng.f01() * n as f64) as i32;
    (if k < n { k } else { n - 1 }) as f64
}

/// waveblur_wf: a point at a random angle whose radius is an arc cosine less a random
/// multiple of π (the `count` rings), plus z = (cos u − ½)·amplitude.
fn waveblur_wf(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [count, phase, amp_z, damping, direct, cscale, coffset] = v.params();
    let ang = rng.f01() * TAU;
    let rnd = 1.0 - 2.0 * rng.f01();
    let side = if rng.f01() < 0.5 { rnd } else { -rnd };
    let ring = index_below(rng, count as i32) + 1.0;
    let r = (side.acos() - ring * PI + phase) * (v.w / (count * PI));
    if direct == 1.0 {
        acc.color = (rnd.acos() * cscale + coffset).clamp(0.0, 1.0);
    }
    let z = if amp_z != 0.0 {
        let mut zamp = (rnd.cos() - 0.5) * amp_z;
        if damping.abs() > 1e-300 {
            zamp *= (r * damping).exp();
        }
        v.w * zamp
    } else {
        0.0
    };
    let (s, c) = ang.sin_cos();
    [r * c, r * s, z]
}

/// conicalSpiral: the fractional part t of |x| (|y|, |z| by `mode`) placed on a spiral of
/// `turns` turns on a cone of `radius` and `height`, optionally rippled, twisted, thickened
/// and coloured by t, radius, angle or height.
fn conical_spiral(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        turns,
        radius,
        height,
        mode,
        wave_freq,
        wave_amp,
        twist,
        thickness,
        solid,
        colorize,
        color_mode,
        color_speed,
        color_offset,
    ] = v.params();
    let s = match mode as i32 {
        1 => t.y.abs() % 1.0,
        2 => t.z.abs() % 1.0,
        _ => t.x.abs() % 1.0,
    };
    let angle = s * TAU * turns;
    let cur_r = s * radius;
    let mut z = s * height;
    if wave_amp != 0.0 {
        z += (s * TAU * wave_freq).sin() * wave_amp;
    }
    let fa = if twist != 0.0 {
        angle + z * twist
    } else {
        angle
    };
    let mut x = cur_r * fa.cos();
    let mut y = cur_r * fa.sin();
    if thickness > 0.0 {
        if solid > 0.0 {
            x += rng.f01() * thickness;
            y += rng.f01() * thickness;
            z += rng.f01() * thickness;
        } else {
            x += t.x * thickness;
            y += t.y * thickness;
            z += t.z * thickness;
        }
    }
    if colorize > 0.0 {
        let driver = match color_mode as i32 {
            0 => s,
            1 => cur_r,
            2 => angle % TAU / TAU,
            _ => z,
        };
        acc.color = (driver * color_speed + color_offset).abs() % 1.0;
    }
    [x * v.w, y * v.w, z * v.w]
}

/// One coordinate folded into the band |c| ≤ m1 (period m1·m2 beyond it), times `k`.
fn fold_band(c: f64, m1: f64, period: f64, k: f64) -> f64 {
    if c > m1 {
        k * (-m1 + (c + m1) % period)
    } else if c < -m1 {
        k * (m1 - (m1 - c) % period)
    } else {
        k * c
    }
}

/// intersection: with even odds, a horizontal band (x moved by a random whole number of
/// tiles, exponentially distributed, y folded) or a vertical one (the same with x and y
/// swapped). JWildfire ignores the weight here.
fn intersection(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [xw, xtile, xm1, xm2, xh, yh, ytile, ym1, ym2, yw] = v.params();
    // Java's Math.round: halves rounded up.
    let jround = |a: f64| (a + 0.5).floor();
    if rng.f01() < 0.5 {
        let w = if rng.f01() < 0.5 { xw } else { -xw };
        let x = xtile * (t.x + jround(w * rng.f01().ln()));
        [x, fold_band(t.y, xm1, xm2 * xm1, xh), 0.0]
    } else {
        let h = if rng.f01() < 0.5 { yh } else { -yh };
        let y = ytile * (t.y + jround(h * rng.f01().ln()));
        [fold_band(t.x, ym1, ym2 * ym1, yw), y, 0.0]
    }
}

/// spirograph3D: the hypotrochoid ((a+b)cos t − c·cos((a+b)t/b), (a+b)sin t −
/// c·sin((a+b)t/b), c·sin((a+b)t/b)) at a uniform t in [tmin, tmax], widened by `width`: one
/// offset on every axis (mode 0), one turning with t (1), three (2), three of a bell shape
/// (3) or ±width on x (4); coloured by t/2π with `direct_color`.
fn spirograph3d(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a, b, c, tmin, tmax, width, mode, direct] = v.params();
    let t = (tmax - tmin) * rng.f01() + tmin;
    let mut uniform = || width * rng.f01() - width / 2.0;
    let (w1, w2, w3) = match mode as i32 {
        0 => {
            let w = uniform();
            (w, w, w)
        }
        1 => {
            let w = uniform();
            let turn = |k: f64| w * (36.0 * t + k * TAU / 3.0).sin();
            (turn(0.0), turn(1.0), turn(2.0))
        }
        2 => (uniform(), uniform(), uniform()),
        3 => {
            let mut bell = || {
                let s = rng.f01() + rng.f01() + rng.f01() + rng.f01();
                width * (s - 2.0) / 2.0
            };
            (bell(), bell(), bell())
        }
        _ => {
            let w = if rng.f01() < 0.5 { width } else { -width };
            (w, 0.0, 0.0)
        }
    };
    let k = (a + b) / b * t;
    let x1 = (a + b) * t.cos() - c * k.cos();
    let y1 = (a + b) * t.sin() - c * k.sin();
    let z1 = c * k.sin();
    if direct != 0.0 {
        acc.color = (t / TAU) % 1.0;
    }
    [v.w * (x1 + w1), v.w * (y1 + w2), v.w * (z1 + w3)]
}
