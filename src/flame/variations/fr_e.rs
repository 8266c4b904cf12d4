//! Variations (slice fr_e of the registry): Fractorium's catalogue from `pressure_wave` to
//! `SuperShape3D`, written from the formulas (constants, branches and guards) that Fractorium
//! uses, so that they reproduce its numbers.

use std::f64::consts::{FRAC_1_PI, FRAC_2_PI, FRAC_PI_2, PI, TAU};

use super::util::{floor_f, lrint, mix, sine_hash, sqr, square_point, trunc_i32, wang_hash, zeps};
use super::{Acc, Form, Prepared, V3, VarDef, VarIn, flag, need, p, p_int, p_nonzero, p_range};
use crate::flame::rng::FastRng;

const INF: f64 = f64::INFINITY;

// ---------------------------------------------------------------------------------------------
// Numeric guards (Fractorium's semantics at NaN and negative values).
// ---------------------------------------------------------------------------------------------

/// Replaces negatives with 0 (NaN passes through).
#[inline(always)]
fn non_negative(x: f64) -> f64 {
    if x < 0.0 { 0.0 } else { x }
}

/// Replaces negatives and non-finite values with 0 (Fractorium's guard before a square root).
#[inline(always)]
fn finite_non_negative(x: f64) -> f64 {
    if x < 0.0 || !x.is_finite() { 0.0 } else { x }
}

/// Clamps into [lo, hi], sending NaN to `lo` (Fractorium's clamp for doubles).
#[inline(always)]
fn clamp_nan_low(x: f64, lo: f64, hi: f64) -> f64 {
    if x < lo {
        lo
    } else if x > hi {
        hi
    } else if x.is_nan() {
        lo
    } else {
        x
    }
}

/// sin and cos of the angle `deg` given in degrees.
fn degrees_sin_cos(deg: f64) -> (f64, f64) {
    (deg / 180.0 * PI).sin_cos()
}

// ---------------------------------------------------------------------------------------------
// pressure_wave, projective, pRose3D, psphere, pulse, q_ode
// ---------------------------------------------------------------------------------------------

/// Each coordinate is pushed along its own axis by a sine wave of that coordinate: bands of
/// compression and rarefaction, like a sound wave.
fn pressure_wave(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [kx, ky, ikx, iky] = v.derived();
    [
        v.w * (t.x + ikx * (kx * t.x).sin()),
        v.w * (t.y + iky * (ky * t.y).sin()),
        0.0,
    ]
}

fn pressure_wave_prep(v: &mut Prepared) {
    let [x_freq, y_freq] = v.params();
    let (kx, ky) = (x_freq * TAU, y_freq * TAU);
    v.p.extend([kx, ky, 1.0 / zeps(kx), 1.0 / zeps(ky)]);
}

/// A projective (homographic) map of the plane: two affine forms divided by a third.
fn projective(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c, a1, b1, c1, a2, b2, c2] = v.params();
    let s = v.w / zeps(a * t.x + b * t.y + c);
    [
        (a1 * t.x + b1 * t.y + c1) * s,
        (a2 * t.x + b2 * t.y + c2) * s,
        0.0,
    ]
}

/// A polar rose r = l·cos(kθ + c) lifted into 3-D: the height is a blend of radial waves
/// ("wag"), a spiral wiggle and an offset; with a negative option a random half of the points
/// form a scaled, mirrored "ghost" copy below.
fn prose3d(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        l,
        _k,
        c,
        z1,
        z2,
        ref_sc,
        _opt,
        _opt_sc,
        _opt3,
        _transp,
        dist,
        wagsc,
        crvsc,
        _f,
        _wigsc,
        offset,
    ] = v.params();
    let [
        cycle,
        petals,
        dir,
        ghost,
        freq,
        wig_scale,
        s12,
        s3,
        anti,
        abs_opt,
    ] = v.derived();

    let rad = t.sqrt;
    let c1 = rad / l;
    let c2 = c1 * c1;
    let c3 = (rad - l * 0.5) / l;
    let c4 = c2 * c2;
    let th = t.atan_yx;
    let (sth, cth) = th.sin_cos();
    let lower = rng.f01() < 0.5;

    let wig = th / zeps(cycle) * freq * 0.5 + offset * cycle;
    // Radial waves: the sine terms of r/l, (r/l)² and (r/l)⁴, plus linear and curvature terms
    // (which of sin((r/l)²π) and cos((r/l - 1/2)π) goes where depends on the option's sign).
    let curve_a = crvsc * 0.5 * (c2 * PI).sin();
    let curve_b = crvsc * 0.5 * (c3 * PI).cos();
    let (first, last) = if dir < 0.0 {
        (curve_a, curve_b)
    } else {
        (curve_b, curve_a)
    };
    let lin = wagsc * 0.4 * rad;
    let wag = (c1 * PI * abs_opt).sin() + lin + first;
    let wag12 = if s12 <= 1.0 {
        wag
    } else {
        let wag2 = (c2 * PI * abs_opt).sin() + lin + curve_b;
        if s12 <= 2.0 {
            wag2 * (1.0 - anti) + wag * anti
        } else {
            wag2
        }
    };
    let waggle = if s3 == 0.0 {
        wag12
    } else if s3 > 0.0 {
        let wag3 = (c4 * PI * abs_opt).sin() + wagsc * (rad * rad) * 0.4 + last;
        wag12 * (1.0 - s3) + wag3 * s3
    } else {
        0.0
    };

    let petal = l * (petals * th + c).cos();
    let swirl = sqr(rad * 0.5) * wig.sin() * wig_scale;
    let is_ghost = rng.f01() < ghost && lower;
    if is_ghost {
        let k = v.w * 0.5 * ref_sc;
        [
            k * petal * cth,
            k * petal * sth,
            v.w * -0.5 * ((z2 * waggle + swirl) + dist),
        ]
    } else {
        let k = v.w * 0.5;
        [
            k * petal * cth,
            k * petal * sth,
            k * ((z1 * waggle + swirl) + dist),
        ]
    }
}

fn prose3d_prep(v: &mut Prepared) {
    let [
        _l,
        k,
        _c,
        _z1,
        _z2,
        _ref_sc,
        opt,
        opt_sc,
        opt3,
        transp,
        _dist,
        _wagsc,
        _crvsc,
        f,
        wigsc,
    ] = v.params();
    let cycle = TAU / zeps(k);
    let mut petals = k;
    if petals.abs() < 0.0001 {
        petals = 0.0001 * 1f64.copysign(k);
    }
    let s12 = opt.abs().min(2.0);
    let s3 = opt3.abs().min(1.0);
    let mut dir = 1f64.copysign(opt);
    if opt3 < 0.0 {
        dir = -1.0;
    }
    let ghost = if dir > 0.0 { 0.0 } else { transp * transp };
    v.p.extend([
        cycle,
        petals,
        dir,
        ghost,
        f * TAU,
        wigsc * 0.5,
        s12,
        s3,
        2.0 - s12,
        opt_sc.abs(),
    ]);
}

/// Wraps the plane around a sphere: x and y become longitude and latitude (scaled by w·π),
/// z the height scaled by `zscale`.
fn psphere(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [zscale] = v.params();
    let [k] = v.derived();
    let (s0, c0) = (t.x * k).sin_cos();
    let (s1, c1) = (t.y * k).sin_cos();
    [c0 * -s1, s0 * c1, c1 * zscale]
}

fn psphere_prep(v: &mut Prepared) {
    let k = v.w * PI;
    v.p.push(k);
}

/// Adds a sine of each coordinate to itself: a regular pulsing of the grid along both axes.
fn pulse(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [freqx, freqy, scalex, scaley] = v.params();
    [
        v.w * (t.x + scalex * (t.x * freqx).sin()),
        v.w * (t.y + scaley * (t.y * freqy).sin()),
        0.0,
    ]
}

/// One step of a quadratic planar ODE: each output coordinate is a general quadratic
/// polynomial of x and y (the weight scales only the x term of x' and the y term of y').
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

// ---------------------------------------------------------------------------------------------
// randCubes, rational3, rays1-3, rblur, ripple, rippled, rotate*
// ---------------------------------------------------------------------------------------------

/// A random city of blocks: points land in random unit cells (spread exponentially around the
/// origin), each cell raised to a hashed height that also picks the colour. Replaces what the
/// xform's earlier variations summed.
fn rand_cubes(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [size, height, spread, seed, density] = v.params();
    let mut cell = || {
        let l = rng.f01().ln();
        floor_f(l * if rng.bit() { spread } else { -spread })
    };
    let bx = cell();
    let by = cell();
    let h = wang_hash(trunc_i32(bx * seed)) + wang_hash(trunc_i32(bx + by * seed));
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    let x = (bx * density + rng.f01()) * size;
    let y = (by * density + rng.f01()) * size;
    let z = height * h * rng.f01().powf(0.125);
    acc.color = h / 2.0;
    [x, y, z]
}

/// A rational function of z = x + iy: (t3 z³ + t2 z² + t1 z + tc) / (b3 z³ + b2 z² + b1 z + bc).
fn rational3(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [t3, t2, t1, tc, b3, b2, b1, bc] = v.params();
    let (x, y) = (t.x, t.y);
    let (xx, yy) = (x * x, y * y);
    let (x3, y3) = (x * x * x, y * y * y);
    // Real and imaginary parts of z³ and z².
    let re3 = x3 - 3.0 * x * yy;
    let im3 = 3.0 * xx * y - y3;
    let re2 = xx - yy;
    let num_re = t3 * re3 + t2 * re2 + t1 * x + tc;
    let num_im = t3 * im3 + t2 * 2.0 * x * y + t1 * y;
    let den_re = b3 * re3 + b2 * re2 + b1 * x + bc;
    let den_im = b3 * im3 + b2 * 2.0 * x * y + b1 * y;
    let inv = 1.0 / zeps(den_re * den_re + den_im * den_im);
    [
        v.w * (num_re * den_re + num_im * den_im) * inv,
        v.w * (num_im * den_re - num_re * den_im) * inv,
        0.0,
    ]
}

/// Rays from the axes: r²/x and r²/y scaled by 1/tan(r) (plus a weight-dependent constant),
/// z scaled by the weight. Replaces the x and y that earlier variations summed.
fn rays1(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let u = 1.0 / zeps(t.sqrt.tan()) + v.w * (FRAC_2_PI * FRAC_2_PI);
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    let k = v.w * u;
    [k * t.sumsq / zeps(t.x), k * t.sumsq / zeps(t.y), v.w * t.z]
}

/// Rays from the axes: r²/x and r²/y scaled by sec(r²·tan(1/r²)) and w/10, z scaled by the
/// weight. Replaces the x and y that earlier variations summed.
fn rays2(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = t.sumsq;
    let u = 1.0 / (r2 * (1.0 / zeps(r2)).tan()).cos();
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    let k = v.w / 10.0 * u;
    [k * r2 / zeps(t.x), k * r2 / zeps(t.y), v.w * t.z]
}

/// Rays from the axes: r²/x and r²/y modulated by cos(r²) and tan(r²) and a factor built from
/// r⁴, z scaled by the weight. Replaces the x and y that earlier variations summed.
fn rays3(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = t.sumsq;
    let r4 = r2 * r2;
    let u = 1.0 / (r4.sin() * (1.0 / zeps(r4)).sin()).cos().sqrt();
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    let k = v.w / 10.0 * u;
    [
        k * r2.cos() * r2 / zeps(t.x),
        k * r2.tan() * r2 / zeps(t.y),
        v.w * t.z,
    ]
}

/// A blur whose size grows with the distance from a centre (beyond an offset): sharp near the
/// centre, smeared further out.
fn rblur(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [strength, offset, center_x, center_y] = v.params();
    let (dx, dy) = (t.x - center_x, t.y - center_y);
    let r = non_negative((dx * dx + dy * dy).sqrt() - offset) * (2.0 * strength);
    let x = v.w * (t.x + (rng.f01() - 0.5) * r);
    let y = v.w * (t.y + (rng.f01() - 0.5) * r);
    [x, y, 0.0]
}

/// Circular ripples around a centre: the distance is displaced by a cosine wave, the two wave
/// offsets (phase and its complement) blended by the phase. (The "distance" is √(x²·y²), as in
/// the original plugin.)
fn ripple(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, cx, cy] = v.params();
    let [f, ph, s, is, vxp, pxa, pixa] = v.derived();
    let x = t.x * s - cx;
    let y = t.y * s + cy;
    let dd = (x * x * (y * y)).sqrt();
    let d = if f64::EPSILON < dd { dd } else { f64::EPSILON };
    let (nx, ny) = (x / d, y / d);
    let wave = (f * d - vxp).cos();
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

/// x scaled by tanh(r²), y by cos(r²): horizontal saturation and vertical rippling.
fn rippled(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let d = zeps(t.sumsq);
    let h = v.w / 2.0;
    [
        h * (d.tanh() * (2.0 * t.x)),
        h * (d.cos() * (2.0 * t.y)),
        0.0,
    ]
}

/// A rotation of the plane by `angle` degrees.
fn rotate(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    [v.w * (t.x * c - t.y * s), v.w * (t.x * s + t.y * c), 0.0]
}

/// sin and cos of rotate's angle (in degrees).
fn rotate_prep(v: &mut Prepared) {
    let [angle] = v.params();
    v.p.extend(<[f64; 2]>::from(degrees_sin_cos(angle)));
}

/// sin and cos of shift's angle (in degrees).
fn shift_prep(v: &mut Prepared) {
    let [_, _, angle] = v.params();
    v.p.extend(<[f64; 2]>::from(degrees_sin_cos(angle)));
}

/// sin and cos of a quarter turn times the weight (the rotate_x/y/z angle).
fn quarter_turns_prep(v: &mut Prepared) {
    let (s, c) = (v.w * FRAC_PI_2).sin_cos();
    v.p.extend([s, c]);
}

/// A 3-D rotation about the x axis by w quarter turns (the weight is the angle). x passes
/// through unweighted, replacing the x that earlier variations summed.
fn rotate_x(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    if v.form == Form::Regular {
        acc.x = 0.0;
    }
    [t.x, s * t.z + c * t.y, c * t.z - s * t.y]
}

/// A 3-D rotation about the y axis by w quarter turns (the weight is the angle). y passes
/// through unweighted, replacing the y that earlier variations summed.
fn rotate_y(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    let y = if v.form == Form::Regular {
        acc.y = t.y;
        0.0
    } else {
        t.y
    };
    [c * t.x - s * t.z, y, s * t.x + c * t.z]
}

/// A rotation about the z axis by w quarter turns (the weight is the angle). z passes through
/// unweighted, replacing the z that earlier variations summed.
fn rotate_z(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    if v.form == Form::Regular {
        acc.z = 0.0;
    }
    [s * t.y + c * t.x, c * t.y - s * t.x, t.z]
}

// ---------------------------------------------------------------------------------------------
// roundspher, roundspher3D, scry2, scry_3D, sechq, secq, shift, shredlin, shredrad, sigmoid
// ---------------------------------------------------------------------------------------------

/// An inversion softened near the origin: w²·p / (r²·(1/r² + (2/π)²)), i.e. the spherical
/// map with its blow-up at the centre rounded off.
fn roundspher(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let r2 = zeps(t.sumsq);
    let e = 1.0 / r2 + FRAC_2_PI * FRAC_2_PI;
    let k = v.w / r2;
    [v.w * (k * t.x / e), v.w * (k * t.y / e), 0.0]
}

/// The 3-D rounded inversion; a zero z is replaced by cos(r), and the z summed so far (or
/// cos(r) if it is zero) is carried into the output z instead of being added to.
fn roundspher3d(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let other = if v.form == Form::Pre { t.z } else { acc.z };
    let tz = if t.z == 0.0 { t.sqrt.cos() } else { t.z };
    let pz = if other == 0.0 { t.sqrt.cos() } else { other };
    if v.form != Form::Pre {
        acc.z = 0.0;
    }
    let d = t.sumsq + tz * tz;
    let e = 1.0 / d + FRAC_2_PI * FRAC_2_PI;
    let k = v.w / d;
    [
        v.w * (k * t.x / e),
        v.w * (k * t.y / e),
        pz + v.w * (k * tz / e),
    ]
}

/// Shared by scry2 and smartshape: the angular part of a "polygon" map. Splits the angle into
/// `2π/alpha` sectors; returns the folded position in the sector (0 at an edge midpoint, up to
/// 1/2 at a corner) as (sector index rounded to the nearest edge, sign, offset).
#[inline(always)]
fn polygon_sector(dang: f64) -> (f64, f64, f64) {
    let whole = floor_f(dang);
    let frac = dang - whole;
    if frac > 0.5 {
        (whole + 1.0, -1.0, 1.0 - frac)
    } else {
        (whole, 1.0, frac)
    }
}

/// scry's inversion followed by a map that turns circles into regular polygons with `power`
/// sides.
fn scry2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [alpha, half_tan2] = v.derived();
    let r2 = t.sumsq;
    let s = 1.0 / zeps(r2.sqrt() * (r2 + 1.0));
    let (nx, ny) = (t.x * s, t.y * s);
    let dang = (ny.atan2(nx) + PI) / alpha;
    let rad = (nx * nx + ny * ny).sqrt();
    let (sector, sign, off) = polygon_sector(dang);
    let xang = (off * half_tan2).atan() / alpha;
    let coeff = 1.0 / (xang * alpha).cos();
    let ang = (sector + sign * xang) * alpha - PI;
    let k = v.w * coeff * rad;
    [k * ang.cos(), k * ang.sin(), 0.0]
}

fn scry2_prep(v: &mut Prepared) {
    let [power] = v.params();
    let alpha = TAU / zeps(power);
    v.p.extend([alpha, (alpha * 0.5).tan() * 2.0]);
}

/// scry in 3-D: p / (|p|·(|p|² + 1/w)); a zero z is replaced by the polar angle.
fn scry_3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [inv_w] = v.derived();
    let d2 = t.sumsq + t.z * t.z;
    let r = 1.0 / zeps(d2.sqrt() * (d2 + inv_w));
    let z = if t.z == 0.0 { t.atan_yx } else { t.z };
    [t.x * r, t.y * r, z * r]
}

fn inv_weight_prep(v: &mut Prepared) {
    let iw = 1.0 / zeps(v.w);
    v.p.push(iw);
}

/// |(y, z)|, the length of the "imaginary" part of the quaternion (x, y, z).
#[inline(always)]
fn imag_len(t: &VarIn) -> f64 {
    (t.y * t.y + t.z * t.z).sqrt()
}

/// Quaternion hyperbolic secant of (x, y, z, 0): 1/cosh q.
fn sechq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = imag_len(t);
    let ni = v.w / zeps(t.sumsq + t.z * t.z);
    let (s, c) = a.sin_cos();
    let (sh, ch) = (t.x.sinh(), t.x.cosh());
    let d = ni * sh * s / zeps(a);
    [ch * c * ni, -(d * t.y), -(d * t.z)]
}

/// Quaternion secant of (x, y, z, 0): 1/cos q.
fn secq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = imag_len(t);
    let ni = v.w / zeps(t.sumsq + t.z * t.z);
    let (s, c) = (-t.x).sin_cos();
    let (sh, ch) = (a.sinh(), a.cosh());
    let d = ni * s * sh / zeps(a);
    [c * ch * ni, -(d * t.y), -(d * t.z)]
}

/// A translation by (x, y) rotated by `angle` degrees (the y offset mirrored).
fn shift(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [dx, dy] = v.params();
    let [s, c] = v.derived();
    [
        v.w * (t.x + c * dx - s * dy),
        v.w * (t.y - c * dy - s * dx),
        0.0,
    ]
}

/// Shreds the plane into parallel strips: each cell of size `distance` along an axis is
/// squeezed to `width` of itself, leaving gaps between the strips; z is scaled.
fn shredlin(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [xdistance, xwidth, ydistance, ywidth] = v.params();
    let [xw, yw, gx, gy] = v.derived();
    let strip = |c: f64, dist: f64, width: f64, gap: f64| {
        let neg = if c < 0.0 { 1.0 } else { 0.0 };
        let u = c / dist;
        let i = trunc_i32(u) as f64;
        (u - i) * width + i + (0.5 - neg) * gap
    };
    [
        xw * strip(t.x, xdistance, xwidth, gx),
        yw * strip(t.y, ydistance, ywidth, gy),
        v.w * t.z,
    ]
}

fn shredlin_prep(v: &mut Prepared) {
    let [xd, xwid, yd, ywid] = v.params();
    v.p.extend([v.w * xd, v.w * yd, 1.0 - xwid, 1.0 - ywid]);
}

/// Shreds the plane into `n` angular wedges, each squeezed to `width` of its angle, leaving
/// empty spokes between them; z is scaled.
fn shredrad(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, width] = v.params();
    let [alpha] = v.derived();
    let a = (t.atan_yx + 3.0 * PI + alpha / 2.0) / alpha;
    let i = trunc_i32(a) as f64;
    let ang = ((a - i) * width + i) * alpha - PI - alpha / 2.0 * width;
    let k = v.w * t.sqrt;
    [k * ang.cos(), k * ang.sin(), v.w * t.z]
}

fn shredrad_prep(v: &mut Prepared) {
    let [n] = v.params();
    let alpha = TAU / n;
    v.p.push(alpha);
}

/// A logistic squashing of each axis into (-|w|, |w|); |shift| < 1 uses the reciprocal
/// steepness and flips by the shift's sign.
fn sigmoid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sx, sy, ax, ay, vv] = v.derived();
    let c0 = ax / zeps(1.0 + (sx * t.x).exp());
    let c1 = ay / zeps(1.0 + (sy * t.y).exp());
    [vv * (2.0 * (c0 - 0.5)), vv * (2.0 * (c1 - 0.5)), 0.0]
}

fn sigmoid_prep(v: &mut Prepared) {
    let [shiftx, shifty] = v.params();
    let steep = |shift: f64| -> (f64, f64) {
        if shift < 1.0 && shift > -1.0 {
            if shift == 0.0 {
                (f64::EPSILON, 1.0)
            } else {
                (1.0 / shift, if shift < 0.0 { -1.0 } else { 1.0 })
            }
        } else {
            (shift, 1.0)
        }
    };
    let (sx, ax) = steep(shiftx);
    let (sy, ay) = steep(shifty);
    let vv = v.w.abs();
    v.p.extend([sx * -5.0, sy * -5.0, ax, ay, vv]);
}

// ---------------------------------------------------------------------------------------------
// sineblur, sinhq, sinq, sintrange, sinusgrid, sinusoidal3D, smartshape, spher, sphereblur,
// Spherical3D, SphericalN, spherivoid, sphyp3D, spiralwing, Spirograph, SplitBrdr
// ---------------------------------------------------------------------------------------------

/// A uniform number in [0, 1) raised to the power `pw` (drawn as e^(pw·ln u); u itself when
/// pw = 1): the radial profile of sineblur and sphereblur.
#[inline(always)]
fn powered_unit(rng: &mut FastRng, pw: f64) -> f64 {
    if pw == 1.0 {
        rng.f01()
    } else {
        (rng.f01().ln() * pw).exp()
    }
}

/// A disc of radius w filled with a density that follows acos (denser at the rim); `power`
/// reshapes the radial profile.
fn sineblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let (s, c) = (rng.f01() * TAU).sin_cos();
    let u = powered_unit(rng, power);
    let r = v.w * ((u * 2.0 - 1.0).acos() / PI);
    [r * c, r * s, 0.0]
}

/// Quaternion hyperbolic sine of (x, y, z, 0).
fn sinhq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = imag_len(t);
    let (s, c) = a.sin_cos();
    let (sh, ch) = (t.x.sinh(), t.x.cosh());
    let d = v.w * ch * s / zeps(a);
    [v.w * sh * c, d * t.y, d * t.z]
}

/// Quaternion sine of (x, y, z, 0).
fn sinq(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = imag_len(t);
    let (s, c) = t.x.sin_cos();
    let (sh, ch) = (a.sinh(), a.cosh());
    let d = v.w * c * sh / zeps(a);
    [v.w * s * ch, d * t.y, d * t.z]
}

/// sin of each coordinate times a quadratic "range" factor (its square plus w, minus w·r²).
fn sintrange(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.params();
    let (xx, yy) = (t.x * t.x, t.y * t.y);
    let m = (xx + yy) * k;
    [
        v.w * t.x.sin() * (xx + k - m),
        v.w * t.y.sin() * (yy + k - m),
        0.0,
    ]
}

/// Blends each coordinate toward -cos(2π·freq·coordinate): a grid of sine-shaped cells.
fn sinusgrid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [ax, ay] = v.params();
    let [fx, fy] = v.derived();
    let sx = -(t.x * fx).cos();
    let sy = -(t.y * fy).cos();
    [v.w * mix(t.x, sx, ax), v.w * mix(t.y, sy, ay), 0.0]
}

fn sinusgrid_prep(v: &mut Prepared) {
    let [_, _, freqx, freqy] = v.params();
    let (fx, fy) = (zeps(freqx * TAU), zeps(freqy * TAU));
    v.p.extend([fx, fy]);
}

/// sinusoidal in 3-D: sin x, sin y, and z from the angle of (x², y²) times cos z.
fn sinusoidal3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [
        v.w * t.x.sin(),
        v.w * t.y.sin(),
        v.w * ((t.x * t.x).atan2(t.y * t.y) * t.z.cos()),
    ]
}

/// Turns circles around the origin into regular polygons with `power` sides; corners can be
/// rounded (`roundstr`, `roundwidth`), the effect strengthened or inverted (`distortion`), and
/// the angular spacing compensated.
fn smartshape(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, roundstr, roundwidth, distortion] = v.params();
    let [alpha, alpha_coeff, round_coeff, comp] = v.derived();
    let dang = (t.atan_yx + PI) / alpha;
    let (sector, sign, off) = polygon_sector(dang);
    let xang = if comp == 1.0 && distortion >= 1.0 {
        (off * alpha_coeff).atan() / alpha
    } else {
        off
    };
    let base = if distortion == 0.0 {
        1.0
    } else {
        let c0 = 1.0 / (xang * alpha).cos();
        if roundstr != 0.0 {
            let ww = if roundwidth != 1.0 {
                ((xang * 2.0).ln() * roundwidth).exp() * round_coeff
            } else {
                xang * 2.0 * round_coeff
            };
            ((1.0 - ww) * c0 + ww).abs()
        } else {
            c0
        }
    };
    let coeff = if distortion != 1.0 {
        (base.ln() * distortion).exp()
    } else {
        base
    };
    let ang = (sector + sign * xang) * alpha - PI;
    let k = v.w * coeff * t.sqrt;
    [ang.cos() * k, ang.sin() * k, 0.0]
}

fn smartshape_prep(v: &mut Prepared) {
    let [power, roundstr, _, _, compensation] = v.params();
    let power = power.max(2.0);
    v.p[0] = power;
    let alpha = TAU / power;
    let alpha_coeff = (alpha * 0.5).tan() * 2.0;
    let round_coeff = roundstr / (alpha * 0.5).sin() / power * 2.0;
    let comp = if compensation <= 0.0 { 0.0 } else { 1.0 };
    v.p.extend([alpha, alpha_coeff, round_coeff, comp]);
}

/// Outside the unit circle, randomly either the spherical inversion p/r² or the identity;
/// inside it, the origin.
fn spher(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let r2 = zeps(t.sumsq);
    if r2 > 1.0 {
        let k = if rng.f01() < 0.5 { v.w / r2 } else { v.w };
        [k * t.x, k * t.y, 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// A solid ball of radius w in 3-D, random direction, with an acos radial profile shaped by
/// `power`.
fn sphereblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let ang = rng.f01() * TAU;
    let polar = (rng.f01() * 2.0 - 1.0).acos();
    let u = powered_unit(rng, power);
    let r = v.w * (((u * 2.0 - 1.0).acos() / PI).ln() / 1.5).exp();
    let (s, c) = ang.sin_cos();
    let (sz, cz) = polar.sin_cos();
    [r * c * sz, r * s * sz, r * cz]
}

/// Spherical inversion in 3-D: p / |p|².
fn spherical3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let k = v.w / zeps(t.sumsq + t.z * t.z);
    [k * t.x, k * t.y, k * t.z]
}

/// An inversion r → 1/r^dist copied into `power` random rotated sectors (x and y swapped with
/// flam3 compatibility off).
fn spherical_n(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, dist] = v.params();
    let [step] = v.derived();
    let r = zeps(t.sqrt.powf(dist));
    let n = floor_f(power * rng.f01());
    let alpha = t.atan_yx + n * TAU / step;
    let (s, c) = alpha.sin_cos();
    if v.compat {
        [v.w * c / r, v.w * s / r, 0.0]
    } else {
        [v.w * s / r, v.w * c / r, 0.0]
    }
}

fn spherical_n_prep(v: &mut Prepared) {
    let [power] = v.params();
    let step = zeps(floor_f(power));
    v.p.push(step);
}

/// Pushes every point of 3-D space `radius` further from the origin (along its direction),
/// hollowing out a spherical void.
fn spherivoid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [radius] = v.params();
    let zr = (t.z * t.z + t.sqrt * t.sqrt).sqrt();
    let phi = clamp_nan_low(t.z / zr, -1.0, 1.0).acos();
    let (ps, pc) = phi.sin_cos();
    let grow = zr + radius;
    [
        v.w * t.ux * ps * grow,
        v.w * t.uy * ps * grow,
        v.w * pc * grow,
    ]
}

/// A 3-D spherical inversion with a separate power of |p|² per axis; z only when `zOn` is 1
/// (otherwise 0).
fn sphyp3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [stretch_x, stretch_y, stretch_z, z_on] = v.params();
    let d = zeps(t.sumsq + t.z * t.z);
    let z = if z_on == 1.0 {
        t.z * (v.w / d.powf(stretch_z))
    } else {
        0.0
    };
    [
        t.x * (v.w / d.powf(stretch_x)),
        t.y * (v.w / d.powf(stretch_y)),
        z,
    ]
}

/// Wing-like spirals: (cos x², sin x²)·sin y² / r².
fn spiralwing(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let inv = 1.0 / zeps(t.sumsq);
    let a = zeps(t.x * t.x);
    let b = zeps(t.y * t.y);
    let (sa, ca) = a.sin_cos();
    let sb = b.sin();
    [v.w * (inv * ca * sb), v.w * (inv * sa * sb), 0.0]
}

/// Draws a spirograph (epitrochoid) curve independently of the input: a random curve
/// parameter in [tmin, tmax) and a random offset in [ymin, ymax) added to both coordinates.
fn spirograph(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a, b, d, tmin, ymin, tmax, ymax, c1, c2] = v.params();
    let tt = (tmax - tmin) * rng.f01() + tmin;
    let off = (ymax - ymin) * rng.f01() + ymin;
    let ab = a + b;
    let inner = ab / b * tt;
    let (st, ct) = tt.sin_cos();
    let x1 = ab * ct - c1 * inner.cos();
    let y1 = ab * st - c2 * inner.sin();
    [v.w * (x1 + d * ct + off), v.w * (y1 + d * st + off), 0.0]
}

/// A bubble-like contraction plus a grid of unit cells, each cell's content halved toward its
/// centre and, three times in four, pushed out toward the nearest cell border.
fn split_brdr(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [bx, by, px, py] = v.params();
    let w = v.w;
    let b = w / (t.sumsq * 0.25 + 1.0);
    let (rx, ry) = (t.x.round_ties_even(), t.y.round_ties_even());
    let (ox, oy) = (t.x - rx, t.y - ry);
    let mut x = t.x * b;
    let mut y = t.y * b;
    if rng.f01() >= 0.75 {
        x += w * (ox * 0.5 + rx);
        y += w * (oy * 0.5 + ry);
    } else if ox.abs() >= oy.abs() {
        if ox >= 0.0 {
            x += w * (ox * 0.5 + rx + bx);
            y += w * (oy * 0.5 + ry + by * oy / zeps(ox));
        } else {
            x += w * (ox * 0.5 + rx - by);
            y += w * (oy * 0.5 + ry - by * oy / zeps(ox));
        }
    } else if oy >= 0.0 {
        y += w * (oy * 0.5 + ry + by);
        x += w * (ox * 0.5 + rx + ox / zeps(oy) * by);
    } else {
        y += w * (oy * 0.5 + ry - by);
        x += w * (ox * 0.5 + rx - ox / zeps(oy) * bx);
    }
    x += t.x * px;
    y += t.y * py;
    [x, y, 0.0]
}

// ---------------------------------------------------------------------------------------------
// splits3D, square3D, squares, squarize, squirrel, squish, sschecks, starblur, starblur2,
// stwin, SuperShape3D
// ---------------------------------------------------------------------------------------------

/// splits in 3-D: each octant is moved away from the coordinate planes by (x, y, z).
fn splits3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [dx, dy, dz] = v.params();
    let away = |c: f64, d: f64| if c >= 0.0 { c + d } else { c - d };
    [
        v.w * away(t.x, dx),
        v.w * away(t.y, dy),
        v.w * away(t.z, dz),
    ]
}

/// A uniformly filled cube of side w centred on the origin.
fn square3d(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let x = v.w * (rng.f01() - 0.5);
    let y = v.w * (rng.f01() - 0.5);
    let z = v.w * (rng.f01() - 0.5);
    [x, y, z]
}

/// A grid of square cells; inside each cell, concentric square rings are rotated by quarter
/// turns according to their level, with hashed per-cell limits and hashed cells left still.
fn squares(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [cell, lo, hi, num, seed, zero, zero_seed] = v.params();
    if cell == 0.0 {
        return [t.x * v.w, t.y * v.w, 0.0];
    }
    let cx = (floor_f(t.x / cell) + 0.5) * cell;
    let cy = (floor_f(t.y / cell) + 0.5) * cell;
    let (lx, ly) = (t.x - cx, t.y - cy);
    let ring_x = floor_f(lx * num * 2.0 / cell + 0.5).abs();
    let ring_y = floor_f(ly * num * 2.0 / cell + 0.5).abs();
    let m = ring_x.max(ring_y);
    let (hx, hy) = (cx * cx, cy * cy);
    let top = hi + floor_f(sine_hash(hx, hy, seed) * (num - hi));
    let level = if m > top || m < lo { 0.0 } else { m - lo };
    let angle = if sine_hash(hx, hy, zero_seed) < zero {
        0.0
    } else {
        level * FRAC_PI_2
    };
    let (s, c) = angle.sin_cos();
    [
        (cx + lx * c - ly * s) * v.w,
        (cy + lx * s + ly * c) * v.w,
        0.0,
    ]
}

/// Maps the plane onto squares: the circle of radius r becomes the square of half-side r, the
/// angle becoming the arc length along its boundary.
fn squarize(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let r = t.sqrt;
    let a = if t.atan_yx < 0.0 {
        t.atan_yx + TAU
    } else {
        t.atan_yx
    };
    let p = 4.0 * r * a * FRAC_1_PI;
    square_point(v.w, r, p, true)
}

/// (cos u·tan x, sin u·tan y) with u = √(a x² + b y²).
fn squirrel(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b] = v.params();
    let u = finite_non_negative(zeps(a) * (t.x * t.x) + zeps(b) * (t.y * t.y)).sqrt();
    let (s, c) = u.sin_cos();
    [c * t.x.tan() * v.w, s * t.y.tan() * v.w, 0.0]
}

/// Squares are squished into a random one of `power` portions of the square ring they lie on:
/// the arc length along the square boundary is divided by `power` and shifted by a random
/// number of full turns.
fn squish(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let [inv] = v.derived();
    let (ax, ay) = (t.x.abs(), t.y.abs());
    let (s, p) = if ax > ay {
        (ax, if t.x > 0.0 { t.y } else { 4.0 * ax - t.y })
    } else {
        (
            ay,
            if t.y > 0.0 {
                2.0 * ay - t.x
            } else {
                6.0 * ay + t.x
            },
        )
    };
    let p = inv * (p + 8.0 * s * floor_f(power * rng.f01()));
    square_point(v.w, s, p, false)
}

fn squish_prep(v: &mut Prepared) {
    let [power] = v.params();
    let inv = 1.0 / power;
    v.p.push(inv);
}

/// Checkerboard-shifted spherical sines: sin(p)/r² plus an offset that depends on the colour
/// of the checkerboard square the point falls in, with optional random jitter.
fn sschecks(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ox, oy, _, jitter] = v.params();
    let [inv_size] = v.derived();
    let r = v.w / zeps(t.sumsq);
    let parity = trunc_i32(lrint(t.x * inv_size) + lrint(t.y * inv_size));
    let (dx, dy) = if parity & 1 != 0 {
        (-ox + jitter * rng.f01(), -oy)
    } else {
        (ox, oy + jitter * rng.f01())
    };
    [v.w * (t.x.sin() * r + dx), v.w * (t.y.sin() * r + dy), 0.0]
}

fn sschecks_prep(v: &mut Prepared) {
    let [_, _, size] = v.params();
    let inv = 1.0 / zeps(size);
    v.p.push(inv);
}

/// A filled star with `power` points (`range` sets how deep the notches are), drawn
/// independently of the input.
fn starblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let [len, step, sin_a, cos_a] = v.derived();
    let f = rng.f01() * power * 2.0;
    let i = trunc_i32(f);
    let x = (f - i as f64) * len;
    let mut z = (1.0 + x * x - 2.0 * x * cos_a).sqrt();
    let turn = sin_a * x / z;
    let base = step * (i / 2) as f64;
    let angle = if i & 1 != 0 {
        base + turn.asin()
    } else {
        base - turn.asin()
    };
    z *= rng.f01().sqrt();
    let a = angle - FRAC_PI_2;
    [v.w * z * a.cos(), v.w * z * a.sin(), 0.0]
}

fn starblur_prep(v: &mut Prepared) {
    let [power, range] = v.params();
    let half = PI / power;
    let len = (1.0 + range * range - 2.0 * range * half.cos()).sqrt();
    let alpha = (half.sin() * range / len).asin();
    v.p.extend([len, TAU / power, alpha.sin(), alpha.cos()]);
}

/// starblur with a hole in the middle (`hole`) and each point's edge split into `stripes`
/// stripes of relative `width`.
fn starblur2(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, width] = v.params();
    let [len, hole2, fill2, step, power2, sin_a, cos_a2, stripes] = v.derived();
    let k = rng.f01() * power2;
    let whole = floor_f(k);
    let f = k - whole;
    let ff = if stripes > 0.0 {
        let g = f * stripes;
        let fs = g.trunc();
        let dif = if whole % 2.0 == 0.0 {
            width * (g - fs)
        } else {
            1.0 - width * (g - fs)
        };
        (dif + fs) / stripes
    } else {
        f
    };
    let x = ff * len;
    let z = zeps((1.0 + x * x - x * cos_a2).sqrt());
    // The parity and half of the sector index, in 64-bit integer arithmetic.
    let wi = whole as i64;
    let odd = wi.wrapping_sub((floor_f(k / 2.0) as i64).wrapping_mul(2)) == 1;
    let sign = if odd { 1.0 } else { -1.0 };
    let angle = step * (wi / 2) as f64 + sign * (sin_a * x / z).asin() - FRAC_PI_2;
    let r = v.w * (z * (rng.f01() * fill2 + hole2).sqrt());
    [angle.cos() * r, angle.sin() * r, 0.0]
}

fn starblur2_prep(v: &mut Prepared) {
    let [power, range, hole, stripes] = v.params();
    let pz = zeps(power);
    let half = PI / pz;
    let len = (1.0 + range * range - 2.0 * range * half.cos()).sqrt();
    let alpha = (half.sin() * range / zeps(len)).asin();
    let hole2 = sqr(hole.abs().min(1.0));
    v.p.extend([
        len,
        hole2,
        1.0 - hole2,
        TAU / pz,
        power * 2.0,
        alpha.sin(),
        alpha.cos() * 2.0,
        zeps(stripes.abs()),
    ]);
}

/// Twin interference: w·p plus (x² − y²)/(x² + y²)·sin(2π·distort·(x + y)) of the scaled
/// point, added to both coordinates.
fn stwin(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [distort] = v.params();
    let x = t.x * v.w * 0.05;
    let y = t.y * v.w * 0.05;
    let (xx, yy) = (x * x, y * y);
    let sum2 = xx + yy;
    let mut e = (xx - yy) * (TAU * distort * (x + y)).sin();
    e /= if sum2 != 0.0 { sum2 } else { 1.0 };
    [v.w * t.x + e, v.w * t.y + e, 0.0]
}

/// A random point on a 3-D superformula surface (Gielis): two superformula radii for the
/// latitude and longitude, spherical or toroidal, with an optional spiral; independent of the
/// input.
fn super_shape3d(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        n1_1,
        n1_2,
        n2_1,
        n2_2,
        n3_1,
        n3_2,
        spiral,
        toroid,
    ] = v.params();
    let [an2_1, an2_2, bn3_1, bn3_2, m4_1, m4_2, rho_k, phi_k] = v.derived();
    let rho = rng.f01() * rho_k;
    let mut phi = rng.f01() * phi_k;
    if rng.bit() {
        phi = -phi;
    }
    let (sr, cr) = rho.sin_cos();
    let (sp, cp) = phi.sin_cos();
    let (msr, mcr) = (m4_1 * rho).sin_cos();
    let (msp, mcp) = (m4_2 * phi).sin_cos();
    let pr1 = an2_1 * mcr.abs().powf(n2_1) + bn3_1 * msr.abs().powf(n3_1);
    let pr2 = an2_2 * mcp.abs().powf(n2_2) + bn3_2 * msp.abs().powf(n3_2);
    let r1 = pr1.abs().powf(n1_1) + spiral * rho;
    let r2 = pr2.abs().powf(n1_2);
    if toroid == 1.0 {
        let ring = r1 + r2 * cp;
        [v.w * cr * ring, v.w * sr * ring, v.w * r2 * sp]
    } else {
        [
            v.w * r1 * cr * r2 * cp,
            v.w * r1 * sr * r2 * cp,
            v.w * r2 * sp,
        ]
    }
}

fn super_shape3d_prep(v: &mut Prepared) {
    let [rho, phi, m1, m2, a1, a2, b1, b2] = v.params();
    let [_, _, _, _, _, _, _, _, _, _, n2_1, n2_2, n3_1, n3_2] = v.params();
    v.p.extend([
        (1.0 / a1).abs().powf(n2_1),
        (1.0 / a2).abs().powf(n2_2),
        (1.0 / b1).abs().powf(n3_1),
        (1.0 / b2).abs().powf(n3_2),
        m1 / 4.0,
        m2 / 4.0,
        rho * FRAC_2_PI,
        phi * FRAC_2_PI,
    ]);
}

// ---------------------------------------------------------------------------------------------
// The table.
// ---------------------------------------------------------------------------------------------

const S: u8 = need::SUMSQ;
const R: u8 = need::SQRT;
const YX: u8 = need::ATAN_YX;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("pressure_wave", pressure_wave)
        .params(&[
            p("pressure_wave_x_freq", 1.0),
            p("pressure_wave_y_freq", 1.0),
        ])
        .prepare(pressure_wave_prep),
    VarDef::new("projective", projective).params(&[
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
    VarDef::new("pRose3D", prose3d)
        .params(&[
            p_nonzero("pRose3D_l", 1.0, -INF, INF),
            p("pRose3D_k", 3.0),
            p("pRose3D_c", 0.0),
            p("pRose3D_z1", 1.0),
            p("pRose3D_z2", 1.0),
            p("pRose3D_refSc", 1.0),
            p("pRose3D_opt", 1.0),
            p("pRose3D_optSc", 1.0),
            p("pRose3D_opt3", 0.0),
            p("pRose3D_transp", 0.5),
            p("pRose3D_dist", 1.0),
            p("pRose3D_wagsc", 0.0),
            p("pRose3D_crvsc", 0.0),
            p("pRose3D_f", 3.0),
            p("pRose3D_wigsc", 0.0),
            p("pRose3D_offset", 0.0),
        ])
        .needs(S | R | YX)
        .flags(flag::WRITES_Z)
        .prepare(prose3d_prep),
    VarDef::new("psphere", psphere)
        .params(&[p("psphere_zscale", 0.0)])
        .flags(flag::WRITES_Z)
        .prepare(psphere_prep),
    VarDef::new("pulse", pulse).params(&[
        p("pulse_freqx", 2.0),
        p("pulse_freqy", 2.0),
        p("pulse_scalex", 1.0),
        p("pulse_scaley", 1.0),
    ]),
    VarDef::new("q_ode", q_ode).params(&[
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
    VarDef::new("randCubes", rand_cubes)
        .params(&[
            p("randCubes_blockSize", 1.0),
            p("randCubes_blockHeight", 1.0),
            p("randCubes_spread", 3.0),
            p_int("randCubes_seed", 1.0, -INF, INF),
            p("randCubes_density", 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::WRITES_ACC)
        .sum(),
    VarDef::new("rational3", rational3).params(&[
        p("rational3_t3", 1.0),
        p("rational3_t2", 0.0),
        p("rational3_t1", 0.0),
        p("rational3_tc", 1.0),
        p("rational3_b3", 0.0),
        p("rational3_b2", 1.0),
        p("rational3_b1", 0.0),
        p("rational3_bc", 1.0),
    ]),
    VarDef::new("rays1", rays1)
        .needs(S | R)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC),
    VarDef::new("rays2", rays2)
        .needs(S)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC),
    VarDef::new("rays3", rays3)
        .needs(S)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC),
    VarDef::new("rblur", rblur)
        .params(&[
            p("rblur_strength", 1.0),
            p("rblur_offset", 1.0),
            p("rblur_center_x", 0.0),
            p("rblur_center_y", 0.0),
        ])
        .flags(flag::RANDOM),
    VarDef::new("ripple", ripple)
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
    VarDef::new("rippled", rippled).needs(S),
    VarDef::new("rotate", rotate)
        .params(&[p("rotate_angle", 0.0)])
        .prepare(rotate_prep),
    VarDef::new("rotate_x", rotate_x)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(quarter_turns_prep),
    VarDef::new("rotate_y", rotate_y)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(quarter_turns_prep),
    VarDef::new("rotate_z", rotate_z)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(quarter_turns_prep),
    VarDef::new("roundspher", roundspher).needs(S),
    VarDef::new("roundspher3D", roundspher3d)
        .needs(S | R)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::READS_ACC | flag::WRITES_ACC),
    VarDef::new("scry2", scry2)
        .params(&[p("scry2_power", 4.0)])
        .needs(S)
        .prepare(scry2_prep),
    VarDef::new("scry_3D", scry_3d)
        .needs(S | YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(inv_weight_prep),
    VarDef::new("sechq", sechq)
        .needs(S)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("secq", secq)
        .needs(S)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("shift", shift)
        .params(&[p("shift_x", 0.0), p("shift_y", 0.0), p("shift_angle", 0.0)])
        .prepare(shift_prep),
    VarDef::new("shredlin", shredlin)
        .batch(super::inline_batch!(shredlin))
        .params(&[
            p_nonzero("shredlin_xdistance", 1.0, -INF, INF),
            p_range("shredlin_xwidth", 0.5, -1.0, 1.0),
            p_nonzero("shredlin_ydistance", 1.0, -INF, INF),
            p_range("shredlin_ywidth", 0.5, -1.0, 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(shredlin_prep),
    VarDef::new("shredrad", shredrad)
        .params(&[
            p_nonzero("shredrad_n", 4.0, -INF, INF),
            p_range("shredrad_width", 0.5, -1.0, 1.0),
        ])
        .needs(S | R | YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(shredrad_prep),
    VarDef::new("sigmoid", sigmoid)
        .params(&[p("sigmoid_shiftx", 1.0), p("sigmoid_shifty", 1.0)])
        .prepare(sigmoid_prep),
    VarDef::new("sineblur", sineblur)
        .batch(super::inline_batch!(sineblur))
        .params(&[p_range("sineblur_power", 1.0, 0.0, INF)])
        .flags(flag::RANDOM)
        .sum(),
    VarDef::new("sinhq", sinhq).flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("sinq", sinq).flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("sintrange", sintrange).params(&[p("sintrange_w", 1.0)]),
    VarDef::new("sinusgrid", sinusgrid)
        .params(&[
            p("sinusgrid_ampx", 0.5),
            p("sinusgrid_ampy", 0.5),
            p("sinusgrid_freqx", 1.0),
            p("sinusgrid_freqy", 1.0),
        ])
        .prepare(sinusgrid_prep),
    VarDef::new("sinusoidal3D", sinusoidal3d)
        .batch(super::inline_batch!(sinusoidal3d))
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("smartshape", smartshape)
        .params(&[
            p_range("smartshape_power", 4.0, 2.0, INF),
            p("smartshape_roundstr", 0.0),
            p("smartshape_roundwidth", 1.0),
            p("smartshape_distortion", 1.0),
            p_range("smartshape_compensation", 0.0, 0.0, 1.0),
        ])
        .needs(S | R | YX)
        .prepare(smartshape_prep),
    VarDef::new("spher", spher).needs(S).flags(flag::RANDOM),
    VarDef::new("sphereblur", sphereblur)
        .params(&[p_range("sphereblur_power", 1.0, 0.0, INF)])
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
    VarDef::new("Spherical3D", spherical3d)
        .batch(super::inline_batch!(spherical3d))
        .needs(S)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("SphericalN", spherical_n)
        .params(&[p("SphericalN_Power", 1.0), p("SphericalN_Dist", 1.0)])
        .needs(S | R | YX)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(spherical_n_prep),
    VarDef::new("spherivoid", spherivoid)
        .params(&[p("spherivoid_radius", 0.0)])
        .needs(S | R | need::ANGLES)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("sphyp3D", sphyp3d)
        .params(&[
            p("sphyp3D_stretchX", 1.0),
            p("sphyp3D_stretchY", 1.0),
            p("sphyp3D_stretchZ", 1.0),
            p_int("sphyp3D_zOn", 1.0, 0.0, 1.0),
        ])
        .needs(S)
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("spiralwing", spiralwing).needs(S),
    VarDef::new("Spirograph", spirograph)
        .params(&[
            p("Spirograph_a", 3.0),
            p("Spirograph_b", 2.0),
            p("Spirograph_d", 1.0),
            p("Spirograph_tmin", -1.0),
            p("Spirograph_ymin", -1.0),
            p("Spirograph_tmax", 1.0),
            p("Spirograph_ymax", 1.0),
            p("Spirograph_c1", 0.0),
            p("Spirograph_c2", 0.0),
        ])
        .flags(flag::RANDOM)
        .sum(),
    VarDef::new("SplitBrdr", split_brdr)
        .params(&[
            p("SplitBrdr_x", 0.25),
            p("SplitBrdr_y", 0.25),
            p("SplitBrdr_px", 0.0),
            p("SplitBrdr_py", 0.0),
        ])
        .needs(S)
        .flags(flag::RANDOM),
    VarDef::new("splits3D", splits3d)
        .batch(super::inline_batch!(splits3d))
        .params(&[
            p("splits3D_x", 0.0),
            p("splits3D_y", 0.0),
            p("splits3D_z", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    VarDef::new("square3D", square3d)
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
    VarDef::new("squares", squares).params(&[
        p("squares_cellsize", 0.0),
        p_range("squares_min", 0.0, 0.0, INF),
        p_range("squares_max", 10.0, 0.0, INF),
        p("squares_num", 10.0),
        p("squares_seed", 1.0),
        p("squares_zero", 0.5),
        p("squares_zero_seed", 1.0),
    ]),
    VarDef::new("squarize", squarize).needs(S | R | YX),
    VarDef::new("squirrel", squirrel).params(&[p("squirrel_a", 1.0), p("squirrel_b", 1.0)]),
    VarDef::new("squish", squish)
        .params(&[p_nonzero("squish_power", 2.0, 2.0, INF)])
        .flags(flag::RANDOM)
        .prepare(squish_prep),
    VarDef::new("sschecks", sschecks)
        .params(&[
            p("sschecks_x", 0.5),
            p("sschecks_y", 0.5),
            p("sschecks_size", 0.5),
            p("sschecks_rnd", 0.0),
        ])
        .needs(S)
        .flags(flag::RANDOM)
        .prepare(sschecks_prep),
    VarDef::new("starblur", starblur)
        .batch(super::inline_batch!(starblur))
        .params(&[
            p("starblur_power", 5.0),
            p("starblur_range", 0.401_622_831_7),
        ])
        .flags(flag::RANDOM)
        .prepare(starblur_prep)
        .sum(),
    VarDef::new("starblur2", starblur2)
        .params(&[
            p("starblur2_power", 5.0),
            p("starblur2_range", 0.401_622_831_772_454_56),
            p("starblur2_hole", 0.5),
            p("starblur2_stripes", 5.0),
            p("starblur2_width", 0.2),
        ])
        .flags(flag::RANDOM)
        .prepare(starblur2_prep),
    VarDef::new("stwin", stwin).params(&[p("stwin_distort", 1.0)]),
    VarDef::new("SuperShape3D", super_shape3d)
        .params(&[
            p("SuperShape3D_rho", 9.9),
            p("SuperShape3D_phi", 2.5),
            p("SuperShape3D_m1", 6.0),
            p("SuperShape3D_m2", 3.0),
            p("SuperShape3D_a1", 1.0),
            p("SuperShape3D_a2", 1.0),
            p("SuperShape3D_b1", 1.0),
            p("SuperShape3D_b2", 1.0),
            p("SuperShape3D_n1_1", 1.0),
            p("SuperShape3D_n1_2", 1.0),
            p("SuperShape3D_n2_1", 1.0),
            p("SuperShape3D_n2_2", 1.0),
            p("SuperShape3D_n3_1", 1.0),
            p("SuperShape3D_n3_2", 1.0),
            p("SuperShape3D_spiral", 0.0),
            p_int("SuperShape3D_toroidmap", 0.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z)
        .prepare(super_shape3d_prep)
        .sum(),
];
