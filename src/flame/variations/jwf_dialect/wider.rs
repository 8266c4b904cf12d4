//! JWildfire's formulas for names of Fractorium's catalogue where JWildfire's variation has
//! parameters Fractorium's lacks (after Fractorium's, in JWildfire's names): `henon`'s and
//! `lozi`'s constant term `c` (Fractorium's fixed 1), `hypershift`'s `stretch`, `stwin`'s
//! offsets, `fdisc`'s shifts and terms, `mask`'s shifts and scales (and its hidden origin);
//! and those whose parameters JWildfire names or counts its own way: `cpow2`'s `range`,
//! `rational3`'s coefficients `a`…`h`, `scry2`'s `sides`, `star` and `circle`, `vibration2`'s
//! second modulations `d2m`…`a2mfreq`, `ripple`'s `fixed_dist_calc`, `octagon`'s `mode`, `truchet`'s `direct_color` (and its defaults, clamps and
//! unweighted tiles), `dc_bubble`'s `invert`, `murl`'s power (any whole number, 1 by
//! default, where Fractorium's is at least 2); and Michael Faber's `x`, `y`, `z` and `w`, whose
//! star slope JWildfire takes as it stands (Fractorium keeps it below π/2).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::SMALL_EPSILON;
use crate::flame::variations::fr_radial;
use crate::flame::variations::*;

/// vibration2's default angles: JWildfire's rounded π/2 (kept).
#[allow(clippy::approx_constant)]
const ROUNDED_HALF_PI: f64 = 1.5708;

pub(in crate::flame::variations) const DEFS: &[VarDef] = &[
    VarDef::new("murl", murl)
        .params(&[p("murl_c", 0.0), p_int("murl_power", 1.0, NEG_INF, INF)])
        .needs(need::SUMSQ | need::ATAN_YX),
    VarDef::new("henon", henon).params(&[p("henon_a", 0.5), p("henon_b", 1.0), p("henon_c", 1.0)]),
    VarDef::new("lozi", lozi).params(&[p("lozi_a", 0.5), p("lozi_b", 1.0), p("lozi_c", 1.0)]),
    VarDef::new("hypershift", hypershift)
        .params(&[p("hypershift_shift", 2.0), p("hypershift_stretch", 1.0)]),
    VarDef::new("stwin", stwin).params(&[
        p("stwin_distort", 1.0),
        p("stwin_offset_xy", 0.0),
        p("stwin_offset_x2", 0.0),
        p("stwin_offset_y2", 0.0),
    ]),
    VarDef::new("fdisc", fdisc).params(&[
        p("fdisc_ashift", 1.0),
        p("fdisc_rshift", 1.0),
        p("fdisc_xshift", 0.0),
        p("fdisc_yshift", 0.0),
        p("fdisc_term1", 1.0),
        p("fdisc_term2", 0.0),
        p("fdisc_term3", 0.0),
        p("fdisc_term4", 0.0),
    ]),
    VarDef::new("mask", mask)
        .params(&[
            p("mask_xshift", 0.0),
            p("mask_yshift", 0.0),
            p("mask_ushift", 1.0),
            p("mask_xscale", 1.0),
            p("mask_yscale", 1.0),
        ])
        .flags(flag::HIDES),
    VarDef::new("cpow2", cpow2)
        .params(&[
            p("cpow2_r", 1.0),
            p("cpow2_a", 0.0),
            p("cpow2_divisor", 1.0),
            p("cpow2_range", 1.0),
        ])
        .flags(flag::RANDOM),
    VarDef::new("rational3", rational3).params(&[
        p("rational3_a", 0.5),
        p("rational3_b", 0.0),
        p("rational3_c", 0.25),
        p("rational3_d", 1.0),
        p("rational3_e", 0.0),
        p("rational3_f", 0.9),
        p("rational3_g", 0.0),
        p("rational3_h", 1.0),
    ]),
    VarDef::new("scry2", scry2)
        .params(&[
            p_int("scry2_sides", 4.0, 1.0, 50.0),
            p_range("scry2_star", 0.0, -1.0, 1.0),
            p_range("scry2_circle", 0.0, -1.0, 1.0),
        ])
        .prepare(scry2_prep),
    VarDef::new("vibration2", vibration2).params(&[
        p("vibration2_dir", 0.0),
        p("vibration2_angle", ROUNDED_HALF_PI),
        p("vibration2_freq", 1.0),
        p("vibration2_amp", 0.25),
        p("vibration2_phase", 0.0),
        p("vibration2_dir2", ROUNDED_HALF_PI),
        p("vibration2_angle2", ROUNDED_HALF_PI),
        p("vibration2_freq2", 1.0),
        p("vibration2_amp2", 0.25),
        p("vibration2_phase2", 0.0),
        p("vibration2_dm", 0.0),
        p("vibration2_dmfreq", 0.1),
        p("vibration2_tm", 0.0),
        p("vibration2_tmfreq", 0.1),
        p("vibration2_fm", 0.0),
        p("vibration2_fmfreq", 0.1),
        p("vibration2_am", 0.0),
        p("vibration2_amfreq", 0.1),
        p("vibration2_d2m", 0.0),
        p("vibration2_d2mfreq", 0.1),
        p("vibration2_t2m", 0.0),
        p("vibration2_t2mfreq", 0.1),
        p("vibration2_f2m", 0.0),
        p("vibration2_f2mfreq", 0.1),
        p("vibration2_a2m", 0.0),
        p("vibration2_a2mfreq", 0.1),
    ]),
    VarDef::new("ripple", ripple)
        .params(&[
            p("ripple_frequency", 2.0),
            p("ripple_velocity", 1.0),
            p("ripple_amplitude", 0.5),
            p("ripple_centerx", 0.0),
            p("ripple_centery", 0.0),
            p("ripple_phase", 0.0),
            p("ripple_scale", 1.0),
            p_int(
                "ripple_fixed_dist_calc",
                0.0,
                f64::NEG_INFINITY,
                f64::INFINITY,
            ),
        ])
        .flags(flag::WRITES_ACC),
    VarDef::new("octagon", octagon)
        .params(&[
            p("octagon_x", 0.0),
            p("octagon_y", 0.0),
            p("octagon_z", 0.0),
            p_int("octagon_mode", 1.0, 0.0, 6.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("Truchet", truchet)
        .params(&[
            p_int("truchet_extended", 0.0, 0.0, 1.0),
            p_range("truchet_exponent", 2.0, 0.001, 2.0),
            p_range("truchet_arc_width", 0.5, 0.001, 1.0),
            p("truchet_rotation", 0.0),
            p_range("truchet_size", 1.0, 0.001, 10.0),
            p("truchet_seed", 50.0),
            p_int("truchet_direct_color", 0.0, 0.0, 1.0),
        ])
        .flags(flag::SETS_COLOR),
    VarDef::new("dc_bubble", dc_bubble)
        .params(&[
            p("dc_bubble_centerx", 0.0),
            p("dc_bubble_centery", 0.0),
            p("dc_bubble_scale", 1.0),
            p_int("dc_bubble_invert", 1.0, 0.0, 1.0),
        ])
        .flags(flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC),
    VarDef::new("x", super::tablemath::x_var)
        .params(fr_radial::shape_params!(jwildfire "x"))
        .needs(need::SUMSQ | need::ATAN_YX)
        .prepare(super::tablemath::shape_prep),
    VarDef::new("y", super::tablemath::y_var)
        .params(fr_radial::shape_params!(jwildfire "y"))
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(super::tablemath::shape_prep),
    VarDef::new("z", super::tablemath::z_var)
        .params(fr_radial::shape_params!(jwildfire "z"))
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(super::tablemath::shape_prep),
    VarDef::new("w", fr_radial::w_var)
        .params(fr_radial::shape_params!(jwildfire "w", p("w_angle", 0.0)))
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(fr_radial::shape_prep_w),
];

/// JWildfire's `random(n)`: a uniform integer below n (n − 1 where rounding reaches n).
fn random_below(rng: &mut FastRng, n: i64) -> i64 {
    let k = (rng.f01() * n as f64) as i64;
    if k < n { k } else { n - 1 }
}

/// cpow2: z to the complex power (r·cos(πa/2) + i·r·sin(πa/2))/divisor on a random branch of
/// the logarithm among `range` (Peter Sdobnov's), and a random one of the divisor's roots.
fn cpow2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [r, a, divisor, range] = v.params();
    let divisor = if divisor == 0.0 { 1.0 } else { divisor };
    let range = if range < 1.0 { 1 } else { range.round() as i64 };
    let ang = TAU / divisor;
    let (sa, ca) = (PI / 2.0 * a).sin_cos();
    let (c, d) = (r * ca / divisor, r * sa / divisor);
    let mut theta = t.y.atan2(t.x);
    let mut n = random_below(rng, range);
    if theta < 0.0 {
        n += 1;
    }
    theta += TAU * n as f64;
    if (theta * (0.5 / range as f64)).cos() < rng.f01() * 2.0 - 1.0 {
        theta -= TAU * range as f64;
    }
    let lnr2 = (t.x * t.x + t.y * t.y).ln();
    let rr = v.w * (c / 2.0 * lnr2 - d * theta).exp();
    let th = c * theta + d / 2.0 * lnr2 + ang * (divisor * rng.f01()).floor();
    let (s, co) = th.sin_cos();
    [rr * co, rr * s, 0.0]
}

/// rational3: (a·z³ + b·z² + c·z + d) / (e·z³ + f·z² + g·z + h) with real coefficients.
fn rational3(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c, d, e, f, g, h] = v.params();
    let (x, y) = (t.x, t.y);
    let (xx, yy) = (x * x, y * y);
    let (re3, im3) = (xx * x - 3.0 * x * yy, 3.0 * xx * y - yy * y);
    let (re2, im2) = (xx - yy, 2.0 * x * y);
    let (tr, ti) = (a * re3 + b * re2 + c * x + d, a * im3 + b * im2 + c * y);
    let (br, bi) = (e * re3 + f * re2 + g * x + h, e * im3 + f * im2 + g * y);
    let den = 1.0 / (br * br + bi * bi);
    [
        v.w * (tr * br + ti * bi) * den,
        v.w * (ti * br - tr * bi) * den,
        0.0,
    ]
}

fn scry2_prep(v: &mut Prepared) {
    let [sides, star, circle] = v.params();
    let (sa, ca) = (TAU / sides).sin_cos();
    let (ss, cs) = (-FRAC_PI_2 * star).sin_cos();
    let (sc, cc) = (FRAC_PI_2 * circle).sin_cos();
    v.p.extend([sa, ca, ss, cs, sc, cc]);
}

/// scry2 (dark-beam's): scry's inversion by the distance to a regular polygon of `sides`
/// (its edges bent into a star by `star`, blended with a circle by `circle`).
fn scry2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sides] = v.params();
    let [sa, ca, ss, cs, sc, cc] = v.derived();
    let (mut x, mut y) = (t.x, t.y);
    let mut r2 = x * cs + y.abs() * ss;
    let circle = (x * x + y * y).sqrt();
    let turns = (sides as i64 - 1).max(0);
    for _ in 0..turns {
        (x, y) = (x * ca - y * sa, x * sa + y * ca);
        r2 = r2.max(x * cs + y.abs() * ss);
    }
    r2 = r2 * cc + circle * sc;
    let r1 = r2;
    r2 = if turns > 1 { r2 * r2 } else { r2.abs() * r2 };
    let d = r1 * (r2 + 1.0 / v.w);
    if d == 0.0 {
        return [0.0; 3];
    }
    [t.x / d, t.y / d, 0.0]
}

/// One of vibration2's two waves: the point moved along `angle` (from `dir`) by a sine of its
/// distance along `dir`, each of direction, angle, phase and amplitude modulated by a cosine of
/// that distance.
fn vibration_wave(x: f64, y: f64, w: [f64; 13]) -> (f64, f64) {
    let [
        dir,
        angle,
        freq,
        amp,
        phase,
        dm,
        dmf,
        tm,
        tmf,
        fm,
        fmf,
        am,
        amf,
    ] = w;
    let modulate = |a: f64, f: f64, d: f64| a * (d * f * TAU).cos();
    let d0 = x * dir.cos() + y * dir.sin();
    let dir_l = dir + modulate(dm, dmf, d0);
    let angle_l = angle + modulate(tm, tmf, d0);
    let freq_l = modulate(fm, fmf, d0) / freq;
    let amp_l = amp + amp * modulate(am, amf, d0);
    let total = angle_l + dir_l;
    let d = x * dir_l.cos() + y * dir_l.sin();
    let local = amp_l * (d * freq * TAU + freq_l + TAU * phase / freq).sin();
    (local * total.cos(), local * total.sin())
}

/// vibration2 (FarDareisMai's): two modulated waves added to the point.
fn vibration2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let q: [f64; 26] = v.params();
    let first = [
        q[0], q[1], q[2], q[3], q[4], q[10], q[11], q[12], q[13], q[14], q[15], q[16], q[17],
    ];
    let second = [
        q[5], q[6], q[7], q[8], q[9], q[18], q[19], q[20], q[21], q[22], q[23], q[24], q[25],
    ];
    let (dx, dy) = vibration_wave(t.x, t.y, first);
    let (ex, ey) = vibration_wave(t.x, t.y, second);
    [v.w * (t.x + dx + ex), v.w * (t.y + dy + ey), 0.0]
}

/// ripple (Xyrus02's): waves around a centre, the distance the product |x·y| unless
/// `fixed_dist_calc` (then the Euclidean one); replaces the sum so far.
fn ripple(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [freq, vel, amp, cx, cy, phase, scale, fixed] = v.params();
    let f = freq * 5.0;
    let a = amp * 0.01;
    let ph = phase * TAU - PI;
    let s = if scale == 0.0 { SMALL_EPSILON } else { scale };
    let (x, y) = (t.x * s - cx, t.y * s + cy);
    let d = if fixed as i64 != 0 {
        (x * x + y * y).sqrt()
    } else {
        (x * x * y * y).sqrt()
    };
    let d = d.max(SMALL_EPSILON);
    let (nx, ny) = (x / d, y / d);
    let wave = (f * d - vel * ph).cos();
    let (d1, d2) = (wave * ph * a + d, wave * (PI - ph) * a + d);
    let lerp = |p: f64, q: f64| p + (q - p) * ph;
    let (u1, v1) = (cx + nx * d1, -cy + ny * d1);
    let (u2, v2) = (cx + nx * d2, -cy + ny * d2);
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    let is = 1.0 / s;
    [v.w * lerp(u1, u2) * is, v.w * lerp(v1, v2) * is, 0.0]
}

/// henon: the Hénon map (c − a·x² + y, b·x).
fn henon(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c] = v.params();
    [(c - a * (t.x * t.x) + t.y) * v.w, b * t.x * v.w, 0.0]
}

/// lozi: the Lozi map (c − a·|x| + y, b·x).
fn lozi(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c] = v.params();
    [(c - a * t.x.abs() + t.y) * v.w, b * t.x * v.w, 0.0]
}

/// hypershift: the hyperbolic shift by `shift` along x, its y stretched; added to the sum.
fn hypershift(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [shift, stretch] = v.params();
    let scale = 1.0 - shift * shift;
    let rad = 1.0 / (t.x * t.x + t.y * t.y);
    let (x, y) = (rad * t.x + shift, rad * t.y);
    let rad = v.w * scale / (x * x + y * y);
    [rad * x + shift, rad * y * stretch, 0.0]
}

/// stwin: w·p plus (x² − y²)/(x² + y²)·sin(2π·distort·(x + y + offset_xy/10)) of the point
/// scaled by w/20, with x² and y² offset by offset_x2, offset_y2 over 10 000.
fn stwin(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [distort, offset_xy, offset_x2, offset_y2] = v.params();
    let (x, y) = (t.x * v.w * 0.05, t.y * v.w * 0.05);
    let x2 = x * x + offset_x2 * 0.0001;
    let y2 = y * y + offset_y2 * 0.0001;
    let e = (x2 - y2) * (std::f64::consts::TAU * distort * (x + y + offset_xy * 0.1)).sin();
    let d = x2 + y2;
    let e = e / if d == 0.0 { 1.0 } else { d };
    [v.w * t.x + e, v.w * t.y + e, 0.0]
}

/// fdisc: the disc of angle 2π/(r + ashift) and radius (θ/π + rshift)/2, each coordinate's
/// angle shifted, mixed with the input by four terms.
fn fdisc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [ashift, rshift, xshift, yshift, term1, term2, term3, term4] = v.params();
    let a = std::f64::consts::TAU / (super::jwf_sqrt(t) + ashift);
    let r = (t.y.atan2(t.x) * std::f64::consts::FRAC_1_PI + rshift) * 0.5;
    let pr = v.w * r;
    let (prx, pry) = (pr * (a + xshift).cos(), pr * (a + yshift).sin());
    let mix = |c: f64, pc: f64| term1 * pc + term2 * c * pc + term3 * c * pr + term4 * c;
    [mix(t.x, prx), mix(t.y, pry), 0.0]
}

/// mask: w/r²·sin u·(cosh v + ushift)·sin²u and the same with cos u, u and v the scaled and
/// shifted x and y; the origin is hidden.
fn mask(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [xshift, yshift, ushift, xscale, yscale] = v.params();
    let sumsq = t.x * t.x + t.y * t.y;
    acc.hide = sumsq == 0.0;
    if acc.hide {
        return [0.0; 3];
    }
    let (u, w) = (xscale * t.x + xshift, yscale * t.y + yshift);
    let (su, cu) = u.sin_cos();
    let k = v.w / sumsq * (w.cosh() + ushift) * su * su;
    [k * su, k * cu, 0.0]
}

/// octagon (FracFx's): the point scaled by m and, where it "splits", pushed away from the
/// axes by (x, y, z); m and the split from the quartic r = x⁴ + y⁴ + 2z² and the sum
/// t = |x| + |y| + 2√z (√|z| in modes above 1) against w/2, by `mode` (0–6).
fn octagon(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [ox, oy, oz, mode] = v.params();
    let w = v.w;
    let (x2, y2) = (t.x * t.x, t.y * t.y);
    let r = x2 * x2 + y2 * y2 + 2.0 * t.z * t.z;
    let r = if r == 0.0 { SMALL_EPSILON } else { r };
    let mode = mode as i64;
    let zz = if mode > 1 { t.z.abs() } else { t.z };
    let tt = t.x.abs() + t.y.abs() + 2.0 * zz.sqrt();
    let tt = if tt == 0.0 { SMALL_EPSILON } else { tt };
    let near = r <= w / 2.0;
    let (m, splits) = match mode {
        0 if near => (1.0 + 1.0 / tt, true),
        0 => (1.0 / r, false),
        1 if near => (1.0 + 1.0 / tt, true),
        1 if w >= 0.0 => (1.0 / r + 1.0 / tt, true),
        1 => (1.0 + 1.0 / r, true),
        2 if near => (1.0 + 1.0 / tt, true),
        2 => (1.0 + 1.0 / r, false),
        3 if near => (1.0 / tt, true),
        3 => (1.0 / r, false),
        4 => (1.0 / r, near),
        5 if tt <= w / 2.0 => (1.0 / tt, true),
        5 => (1.0 / r, false),
        6 if tt <= w / 2.0 => (1.0 + 1.0 / tt, true),
        6 => (1.0 + 1.0 / r, false),
        _ => (1.0, false),
    };
    let away = |u: f64, off: f64| {
        let base = w * m * u;
        match splits {
            false => base,
            true if u >= 0.0 => base + w * (u + off),
            true => base + w * (u - off),
        }
    };
    [away(t.x, ox), away(t.y, oy), away(t.z, oz)]
}

/// Java's `Math.round` as a double: halves round up.
fn round_half_up(x: f64) -> f64 {
    (x + 0.5).floor()
}

/// The tile type (0 or 1) of the cell of (x, y): a linear congruential hash of its rounded
/// coordinates and the seed (iterated in the extended mode), fixed for seeds 0 and 1.
fn truchet_tile(x: f64, y: f64, seed: f64, extended: bool) -> f64 {
    let (modbase, mult, offset) = (65535.0, 32747.0, 12345.0);
    if seed == 0.0 || seed == 1.0 {
        return seed;
    }
    let seed2 = (seed + seed / 2.0 + SMALL_EPSILON).sqrt() / (seed * 0.5 + SMALL_EPSILON) * 0.25;
    let randint = if extended {
        let (xr, yr) = (round_half_up(x) as i64, round_half_up(y) as i64);
        let niter = ((xr + yr + xr * yr).abs() as f64).min(1000.0) as i64;
        let mut r = seed.floor() + niter as f64;
        for _ in 0..niter {
            r = (r * mult + offset) % modbase;
        }
        r
    } else {
        let (xr, yr) = (round_half_up(x) * seed2, round_half_up(y) * seed2);
        let niter = xr + yr + xr * yr;
        ((niter + seed) * seed2 / 2.0 * mult + offset) % modbase
    };
    randint % 2.0
}

/// truchet (Apophysis' plugin as JWildfire has it): quarter-circle arcs of width `arc_width`
/// (in the `exponent`-norm) in tiles turned by a hash of the cell; a point near an arc is
/// added at its place in the tile (unweighted, by `size`), once per arc it is near; with
/// `direct_color` its colour is its place across the arc.
fn truchet(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [extended, n, width, rotation, size, seed, direct] = v.params();
    let extended = extended.clamp(0.0, 1.0) as i64 == 1;
    let n = n.clamp(0.001, 2.0);
    let width = width.clamp(0.001, 1.0);
    let size = size.clamp(0.001, 10.0);
    let seed = seed.abs();
    let rmax = 0.5 * (2f64.powf(1.0 / n) - 1.0) * width;
    let r = -rotation;
    let scale = (r.cos() - r.sin()) / v.w;
    let cell = |u: f64| {
        let f = u - round_half_up(u);
        if f < 0.0 { 1.0 + f } else { f }
    };
    let (x, y) = (cell(t.x * scale), cell(t.y * scale));
    let tile = truchet_tile(t.x, t.y, seed, extended);
    let norm = |a: f64, b: f64| (a.abs().powf(n) + b.abs().powf(n)).powf(1.0 / n);
    let flipped = if extended { tile != 1.0 } else { tile >= 1.0 };
    let (r0, r1) = if flipped {
        (norm(x - 1.0, y), norm(x, y - 1.0))
    } else {
        (norm(x, y), norm(x - 1.0, y - 1.0))
    };
    let place = [size * (x + t.x.floor()), size * (y + t.y.floor())];
    let mut out = [0.0; 3];
    for (rr, colour) in [(r0, r0), (r1, 1.0 - r1)] {
        if (rr - 0.5).abs() / rmax < 1.0 {
            if direct as i64 == 1 {
                acc.color = colour.clamp(0.0, 1.0);
            }
            out[0] += place[0];
            out[1] += place[1];
        }
    }
    out
}

/// dc_bubble (Xyrus02's corrected one): bubble, its height 2/k − 1 of k = w/r (`invert` 1) or
/// of r = |p|²/4 + 1 (0); the colour the squared distance of the new sum from −centre, scaled
/// by 1/scale, modulo 1.
fn dc_bubble(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [cx, cy, scale, invert] = v.params();
    let r = (t.x * t.x + t.y * t.y) / 4.0 + 1.0;
    let k = v.w / r;
    let o = [
        k * t.x,
        k * t.y,
        v.w * (2.0 / if invert as i64 == 1 { k } else { r } - 1.0),
    ];
    let bdcs = 1.0 / if scale == 0.0 { 10e-6 } else { scale };
    let (sx, sy, _) = sum_or_input(v, t, acc);
    let (x, y) = (sx + o[0] + cx, sy + o[1] + cy);
    acc.color = (bdcs * (x * x + y * y)).abs() % 1.0;
    o
}

/// murl: the point divided by 1 + c'·z^power (c' = c/(power − 1), c itself for power 1),
/// scaled by weight·(c' + 1).
fn murl(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [c, power] = v.params();
    let cp = if power != 1.0 { c / (power - 1.0) } else { c };
    let vp = v.w * (cp + 1.0);
    let a = t.atan_yx * power;
    let r = cp * t.sumsq.powf(power / 2.0);
    let re = r * a.cos() + 1.0;
    let im = r * a.sin();
    let rl = vp / (re * re + im * im);
    [rl * (t.x * re + t.y * im), rl * (t.y * re - t.x * im), 0.0]
}
