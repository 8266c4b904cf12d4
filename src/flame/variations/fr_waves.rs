//! Wave displacements from Fractorium's catalogue: the `waves2` family (`waves22` … `waves42`,
//! `waves2_3D`, `waves2_radial`, `waves2b`), ripples, pulses, vibrations, interference and the
//! other periodic warps.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, PI, TAU};

use super::util::{bessel_j1, fract, jacobi_sn, mix, sqr, trunc_i32, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("coswrap", coswrap)
        .params(&[
            p_int_nonzero("coswrap_repeat", 1.0, f64::NEG_INFINITY, f64::INFINITY),
            p("coswrap_amount_x", 0.0),
            p("coswrap_amount_y", 0.0),
            p_cyclic("coswrap_phase_x", 0.0, -1.0, 1.0),
            p_cyclic("coswrap_phase_y", 0.0, -1.0, 1.0),
        ])
        .prepare(prep_coswrap),
    super::inlined!("gdoffs", gdoffs)
        .params(&[
            p_range("gdoffs_delta_x", 0.0, 0.0, 16.0),
            p_range("gdoffs_delta_y", 0.0, 0.0, 16.0),
            p("gdoffs_area_x", 2.0),
            p("gdoffs_area_y", 2.0),
            p("gdoffs_center_x", 0.0),
            p("gdoffs_center_y", 0.0),
            p_int("gdoffs_gamma", 1.0, 1.0, 6.0),
            p_int("gdoffs_square", 0.0, 0.0, 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(gdoffs_prepare),
    super::inlined!("interference2", interference2).params(&[
        p("interference2_a1", 1.0),
        p("interference2_b1", 1.0),
        p("interference2_c1", 0.0),
        p("interference2_p1", 1.0),
        p_int("interference2_t1", 0.0, 0.0, 2.0),
        p("interference2_a2", 1.0),
        p("interference2_b2", 1.0),
        p("interference2_c2", 0.0),
        p("interference2_p2", 1.0),
        p_int("interference2_t2", 0.0, 0.0, 2.0),
    ]),
    super::inlined!("oscilloscope2", oscilloscope2)
        .params(&[
            p_range("oscilloscope2_separation", 1.0, 0.0, INF),
            p("oscilloscope2_frequencyx", PI),
            p("oscilloscope2_frequencyy", PI),
            p("oscilloscope2_amplitude", 1.0),
            p("oscilloscope2_perturbation", 1.0),
            p("oscilloscope2_damping", 0.0),
        ])
        .prepare(prep_oscilloscope2),
    super::inlined!("pressure_wave", pressure_wave)
        .params(&[
            p("pressure_wave_x_freq", 1.0),
            p("pressure_wave_y_freq", 1.0),
        ])
        .prepare(pressure_wave_prep),
    super::inlined!("pulse", pulse).params(&[
        p("pulse_freqx", 2.0),
        p("pulse_freqy", 2.0),
        p("pulse_scalex", 1.0),
        p("pulse_scaley", 1.0),
    ]),
    super::inlined!("ripple", ripple)
        .params(&[
            p("ripple_frequency", 2.0),
            p("ripple_velocity", 1.0),
            p("ripple_amplitude", 0.5),
            p("ripple_centerx", 0.0),
            p("ripple_centery", 0.0),
            p("ripple_phase", 0.0),
            p("ripple_scale", 1.0),
        ])
        .prepare(ripple_prep),
    super::inlined!("sinusgrid", sinusgrid)
        .params(&[
            p("sinusgrid_ampx", 0.5),
            p("sinusgrid_ampy", 0.5),
            p("sinusgrid_freqx", 1.0),
            p("sinusgrid_freqy", 1.0),
        ])
        .prepare(sinusgrid_prep),
    super::inlined!("vibration", vibration)
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
    super::inlined!("vibration2", vibration2)
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
    super::inlined!("waves22", waves22).params(&[
        p("waves22_scalex", 0.05),
        p("waves22_scaley", 0.05),
        p("waves22_freqx", 7.0),
        p("waves22_freqy", 13.0),
        p_int("waves22_modex", 0.0, 0.0, 1.0),
        p_int("waves22_modey", 0.0, 0.0, 1.0),
        p("waves22_powerx", 2.0),
        p("waves22_powery", 2.0),
    ]),
    super::inlined!("waves23", waves23)
        .params(&[
            p("waves23_scalex", 0.05),
            p("waves23_scaley", 0.05),
            p("waves23_freqx", 7.0),
            p("waves23_freqy", 13.0),
        ])
        .prepare(waves23_prep),
    super::inlined!("waves2_3D", waves2_3d)
        .params(&[p("waves2_3D_freq", 2.0), p("waves2_3D_scale", 1.0)])
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("waves2_radial", waves2_radial)
        .params(&[
            p("waves2_radial_freqx", 7.0),
            p("waves2_radial_scalex", 0.1),
            p("waves2_radial_freqy", 13.0),
            p("waves2_radial_scaley", 0.1),
            p("waves2_radial_null", 2.0),
            p("waves2_radial_distance", 10.0),
        ])
        .needs(need::SUMSQ | need::SQRT),
    super::inlined!("waves2b", waves2b)
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
    super::inlined!("waves3", waves3)
        .params(&[
            p("waves3_scalex", 0.05),
            p("waves3_scaley", 0.05),
            p("waves3_freqx", 7.0),
            p("waves3_freqy", 13.0),
            p("waves3_sx_freq", 0.0),
            p("waves3_sy_freq", 2.0),
        ])
        .prepare(waves3_prep),
    super::inlined!("waves4", waves4)
        .params(&[
            p("waves4_scalex", 0.05),
            p("waves4_scaley", 0.05),
            p("waves4_freqx", 7.0),
            p("waves4_freqy", 13.0),
            p_int("waves4_cont", 0.0, 0.0, 1.0),
            p("waves4_yfact", 0.1),
        ])
        .prepare(waves4_prep),
    super::inlined!("waves42", waves42)
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
];

/// Derived values: π·phase_x, π·phase_y, |repeat|, 2w and the two blend amounts
/// ½ − ½cos(amount + π·phase).
fn prep_coswrap(v: &mut Prepared) {
    let [repeat, ax, ay, phx, phy] = v.params();
    let (px, py) = (PI * phx, PI * phy);
    v.p.push(px);
    v.p.push(py);
    v.p.push(repeat.abs());
    v.p.push(2.0 * v.w);
    v.p.push(0.5 - (ax + px).fcos() * 0.5);
    v.p.push(0.5 - (ay + py).fcos() * 0.5);
}

/// One coordinate of `coswrap`: u = (c + 1)/2 blended towards a cosine wave of u and of the
/// fractional part of repeat·u.
#[inline(always)]
fn coswrap_axis(c: f64, phase: f64, repeat: f64, blend: f64, w2: f64) -> f64 {
    let u = 0.5 * c + 0.5;
    let b = (repeat * u).fract();
    let wave = |q: f64| 0.5 - (q * 4.0 + phase).fcos() * 0.5;
    let first = u + (wave(u) - u) * blend;
    -1.0 + w2 * (first + (wave(b) - first) * blend)
}

/// Wraps the plane onto cosine waves: each coordinate is blended with a cosine of itself and of
/// its repeated fractional part (phase and amount per axis), mapped back to [−1, −1 + 2w].
#[inline(always)]
fn coswrap(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [px, py, rep, w2, bx, by] = v.derived();
    [
        coswrap_axis(t.x, px, rep, bx, w2),
        coswrap_axis(t.y, py, rep, by, w2),
        0.0,
    ]
}

fn gdoffs_prepare(v: &mut Prepared) {
    let [delta_x, delta_y, area_x, area_y, centre_x, centre_y, gam] = v.params();
    let dx = delta_x * 0.1;
    let dy = delta_y * 0.1;
    let ax = if area_x.abs() < 0.1 {
        0.1
    } else {
        area_x.abs()
    } * 2.0;
    let ay = if area_y.abs() < 0.1 {
        0.1
    } else {
        area_y.abs()
    } * 2.0;
    let b = gam * 2.0 / ax.max(ay);
    v.p.extend_from_slice(&[dx, dy, centre_x, centre_y, b]);
}

/// Signed fractional part of |a| (keeps the sign of `a`).
#[inline(always)]
fn gd_wrap(a: f64) -> f64 {
    let f = a.abs() % 1.0;
    if a < 0.0 { -f } else { f }
}

/// A cosine oscillation of `p·a` mapped into [0, 1).
#[inline(always)]
fn gd_osc(p: f64, a: f64) -> f64 {
    gd_wrap((-(p * a * TAU).fcos() + 1.0) / 2.0)
}

/// Gradient-domain offsets: each coordinate is blended with cosine oscillations of itself,
/// giving a rippled, folded copy of the plane; z is scaled.
#[inline(always)]
fn gdoffs(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, square] = v.params();
    let [dx, dy, cx, cy, b] = v.derived();
    let osc_x = gd_osc(dx, 1.0);
    let osc_y = if square != 0.0 {
        osc_x
    } else {
        gd_osc(dy, 1.0)
    };
    let fold = |a: f64, osc: f64| {
        mix(
            mix(a, gd_osc(a, 4.0), osc),
            gd_osc(gd_wrap(b * a), 4.0),
            osc,
        )
    };
    let ox = fold(t.x + cx, osc_x);
    let oy = fold(t.y + cy, osc_y);
    [v.w * ox, v.w * oy, v.w * t.z]
}

/// One interference wave a·wave(b·x + c)^p: sine (|sin|), triangle or square shape.
#[inline(always)]
fn wave(kind: f64, a: f64, b: f64, c: f64, p_: f64, x: f64) -> f64 {
    if kind == 1.0 {
        a * 2.0 * ((b * x + c - FRAC_PI_2).fcos().asin().abs() * FRAC_1_PI).powf(p_)
    } else if kind == 2.0 {
        let base = if (b * x + c).fsin() < 0.0 {
            f64::EPSILON
        } else {
            1.0
        };
        a * base.powf(p_)
    } else {
        a * (b * x + c).fsin().abs().powf(p_)
    }
}

/// The sum of two periodic waves (sine, triangle or square, each with amplitude, frequency,
/// phase and power) applied to each coordinate.
#[inline(always)]
fn interference2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a1, b1, c1, p1, k1, a2, b2, c2, p2, k2] = v.params();
    let x = wave(k1, a1, b1, c1, p1, t.x) + wave(k2, a2, b2, c2, p2, t.x);
    let y = wave(k1, a1, b1, c1, p1, t.y) + wave(k2, a2, b2, c2, p2, t.y);
    [v.w * x, v.w * y, 0.0]
}

fn prep_oscilloscope2(v: &mut Prepared) {
    let [_, fx, fy] = v.params();
    v.p.push(TAU * fx);
    v.p.push(TAU * fy);
}

/// oscilloscope2: points inside a (damped, y-perturbed) cosine band around the x axis are
/// reflected through the origin, the others kept.
#[inline(always)]
fn oscilloscope2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [sep, _, _, amp, pert, damp] = v.params();
    let [kx, ky] = v.derived();
    let wobble = pert * (ky * t.y).fsin();
    let band = if damp == 0.0 {
        amp * (kx * t.x + wobble).fcos() + sep
    } else {
        amp * (-t.x.abs() * damp).exp() * (kx * t.x + wobble).fcos() + sep
    };
    if t.y.abs() <= band {
        [-(v.w * t.x), -(v.w * t.y), 0.0]
    } else {
        [v.w * t.x, v.w * t.y, 0.0]
    }
}

/// Each coordinate is pushed along its own axis by a sine wave of that coordinate: bands of
/// compression and rarefaction, like a sound wave.
#[inline(always)]
fn pressure_wave(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [kx, ky, ikx, iky] = v.derived();
    [
        v.w * (t.x + ikx * (kx * t.x).fsin()),
        v.w * (t.y + iky * (ky * t.y).fsin()),
        0.0,
    ]
}

fn pressure_wave_prep(v: &mut Prepared) {
    let [x_freq, y_freq] = v.params();
    let (kx, ky) = (x_freq * TAU, y_freq * TAU);
    v.p.extend([kx, ky, 1.0 / zeps(kx), 1.0 / zeps(ky)]);
}

/// Adds a sine of each coordinate to itself: a regular pulsing of the grid along both axes.
#[inline(always)]
fn pulse(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [freqx, freqy, scalex, scaley] = v.params();
    [
        v.w * (t.x + scalex * (t.x * freqx).fsin()),
        v.w * (t.y + scaley * (t.y * freqy).fsin()),
        0.0,
    ]
}

/// Circular ripples around a centre: the distance is displaced by a cosine wave, the two wave
/// offsets (phase and its complement) blended by the phase. (The "distance" is √(x²·y²), as in
/// the original plugin.)
#[inline(always)]
fn ripple(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, cx, cy] = v.params();
    let [f, ph, s, is, vxp, pxa, pixa] = v.derived();
    let x = t.x * s - cx;
    let y = t.y * s + cy;
    let dd = (x * x * (y * y)).sqrt();
    let d = if f64::EPSILON < dd { dd } else { f64::EPSILON };
    let (nx, ny) = (x / d, y / d);
    let wave = (f * d - vxp).fcos();
    let d1 = wave * pxa + d;
    let d2 = wave * pixa + d;
    let (u1, v1) = (cx + nx * d1, -cy + ny * d1);
    let (u2, v2) = (cx + nx * d2, -cy + ny * d2);
    [v.w * mix(u1, u2, ph) * is, v.w * mix(v1, v2, ph) * is, 0.0]
}

fn ripple_prep(v: &mut Prepared) {
    let [freq, vel, amp, _, _, phase, scale] = v.params();
    let a = amp * 0.01;
    let ph = phase * TAU - PI;
    let s = zeps(scale);
    v.p.extend([freq * 5.0, ph, s, 1.0 / s, vel * ph, ph * a, (PI - ph) * a]);
}

/// Blends each coordinate toward -cos(2π·freq·coordinate): a grid of sine-shaped cells.
#[inline(always)]
fn sinusgrid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [ax, ay] = v.params();
    let [fx, fy] = v.derived();
    let sx = -(t.x * fx).fcos();
    let sy = -(t.y * fy).fcos();
    [v.w * mix(t.x, sx, ax), v.w * mix(t.y, sy, ay), 0.0]
}

fn sinusgrid_prep(v: &mut Prepared) {
    let [_, _, freqx, freqy] = v.params();
    let (fx, fy) = (zeps(freqx * TAU), zeps(freqy * TAU));
    v.p.extend([fx, fy]);
}

/// 1/(2π).
const INV_TAU: f64 = FRAC_1_PI * 0.5;

/// 1/r when r is below machine epsilon (a pole), else q/r.
#[inline(always)]
fn div_or_inverse(q: f64, r: f64) -> f64 {
    if r < f64::EPSILON { 1.0 / r } else { q / r }
}

/// Derived values of vibration: for each of the two waves, cos/sin of its direction and of
/// direction + displacement angle, the angular frequency and the phase shift.
fn vibration_prep(v: &mut Prepared) {
    let [dir, angle, freq, _, phase, dir2, angle2, freq2, _, phase2] = v.params();
    for (dir, angle, freq, phase) in [(dir, angle, freq, phase), (dir2, angle2, freq2, phase2)] {
        let tot = angle + dir;
        v.p.extend_from_slice(&[
            dir.fcos(),
            dir.fsin(),
            tot.fcos(),
            tot.fsin(),
            freq * TAU,
            TAU * phase / zeps(freq),
        ]);
    }
}

/// vibration: two superposed plane waves, each displacing points by amp·sin(phase along its
/// direction) along its own displacement angle.
#[inline(always)]
fn vibration(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, amp, _, _, _, _, amp2] = v.params();
    let waves = v.table(0);
    let (mut x, mut y) = (t.x, t.y);
    for (amp, d) in [(amp, &waves[..6]), (amp2, &waves[6..12])] {
        let along = t.x * d[0] + t.y * d[1];
        let a = amp * ((along * d[4]) + d[5]).fsin();
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
        v.p.extend_from_slice(&[dir.fcos(), dir.fsin(), freq * TAU, TAU * phase / zeps(freq)]);
    }
}

/// amp·cos(2π·freq·x): vibration2's modulation of a wave parameter along the wave.
#[inline(always)]
fn modulate(amp: f64, freq: f64, x: f64) -> f64 {
    amp * (x * freq * TAU).fcos()
}

/// vibration2: vibration whose direction, displacement angle, frequency and amplitude are
/// themselves modulated along each wave.
#[inline(always)]
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
        let (sd, cd) = dir_m.fsin_cos();
        let along = t.x * cd + t.y * sd;
        let a = amp_m * ((along * d[2]) + phase_m + d[3]).fsin();
        x += a * tilt_dir.fcos();
        y += a * tilt_dir.fsin();
    }
    [v.w * x, v.w * y, 0.0]
}

/// waves22: each coordinate displaced by a power of a sine wave of the other (or of a
/// raised sine, by mode).
#[inline(always)]
fn waves22(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scx, scy, fx, fy, modex, modey, powerx, powery] = v.params();
    let px = trunc_i32(powerx) as f64;
    let py = trunc_i32(powery) as f64;
    let sx = if modex < 0.5 {
        (t.y * fx).fsin()
    } else {
        0.5 * (1.0 + (t.y * fx).fsin())
    };
    let sy = if modey < 0.5 {
        (t.x * fy).fsin()
    } else {
        0.5 * (1.0 + (t.x * fy).fsin())
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
#[inline(always)]
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
#[inline(always)]
fn waves2_3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [freq, scale] = v.params();
    let avg = (t.x + t.y) * 0.5;
    [
        v.w * (t.x + scale * (t.y * freq).fsin()),
        v.w * (t.y + scale * (t.x * freq).fsin()),
        v.w * (t.z + scale * (avg * freq).fsin()),
    ]
}

/// waves2_radial: waves2 whose amplitude grows linearly with r from 0 at `null` to full at
/// `distance`.
#[inline(always)]
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
        v.w * (t.x + k * (t.y * fx).fsin() * sx),
        v.w * (t.y + k * (t.x * fy).fsin() * sy),
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
#[inline(always)]
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
            (util::sign_nz(u) * zeps(u.abs()).powf(pw) * freq).fsin()
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
#[inline(always)]
fn waves3(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, freqx, freqy, sx_freq, sy_freq] = v.params();
    let [half_sx, half_sy] = v.derived();
    let scx = half_sx * (1.0 + (t.y * sx_freq).fsin());
    let scy = half_sy * (1.0 + (t.x * sy_freq).fsin());
    [
        v.w * (t.x + (t.y * freqx).fsin() * scx),
        v.w * (t.y + (t.x * freqy).fsin() * scy),
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
    let h = (band * 12.9898 + band * 78.233 + 1.0 + y * yfact).fsin() * 43758.5453;
    let h = h - trunc_i32(h) as f64;
    if cont == 1.0 {
        if h > 0.5 { 1.0 } else { 0.0 }
    } else {
        h
    }
}

/// waves4: waves2 whose x amplitude is random per wave period (horizontal bands).
#[inline(always)]
fn waves4(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scalex, scaley, freqx, freqy, cont] = v.params();
    let [yfact] = v.derived();
    let band = (t.y * freqx / TAU).floor();
    let ax = band_amp(band, t.y, yfact, cont);
    [
        v.w * (t.x + (t.y * freqx).fsin() * ax * ax * scalex),
        v.w * (t.y + (t.x * freqy).fsin() * scaley),
        0.0,
    ]
}

/// waves42: waves4 with the band width set independently (`freqx2`).
#[inline(always)]
fn waves42(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scalex, scaley, freqx, freqy, cont, _, freqx2] = v.params();
    let [yfact] = v.derived();
    let band = (t.y * freqx2).floor();
    let ax = band_amp(band, t.y, yfact, cont);
    [
        v.w * (t.x + (t.y * freqx).fsin() * ax * ax * scalex),
        v.w * (t.y + (t.x * freqy).fsin() * scaley),
        0.0,
    ]
}
