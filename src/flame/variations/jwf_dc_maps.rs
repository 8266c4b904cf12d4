//! JWildfire's direct-colour maps of the plane: `dc_cylinder2` (FracFx's blurred cylinder,
//! coloured by a linear gradient across the running sum), `dc_dmodulus` (a modulus map whose
//! two turned copies are chosen at random) and `dc_kaleidotile` (Will Evans' kaleidoscope as
//! Brad Stefanov's two mirrored tiles); the last two blend the colour carried from the
//! previous call towards the chosen copy's own; `dc_carpet3D` (Xyrus02's carpet with Brad
//! Stefanov's colour, stretch, scale and z controls: the point moved to one of four quadrant
//! copies through the xform's own affine map) and `dc_gnarly` (Brad Stefanov's and Rick
//! Sidwell's blurred gnarly maps, coloured by their sines).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's dc_cylinder2 keeps its four blur draws from call to call,
//! replacing one per call; each call here draws four afresh, which gives the blur the same
//! distribution.

use std::f64::consts::{PI, TAU};

use super::util::Mwc;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("dc_cylinder2", dc_cylinder2)
        .params(&[
            p("dc_cylinder2_offset", 0.0),
            p("dc_cylinder2_angle", 0.0),
            p("dc_cylinder2_scale", 0.5),
            p("dc_cylinder2_x", 0.125),
            p("dc_cylinder2_y", 0.125),
            p("dc_cylinder2_blur", 1.0),
        ])
        .flags(
            flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC,
        ),
    VarDef::new("dc_dmodulus", dc_dmodulus)
        .params(&[
            p("dc_dmodulus_x", 2.0),
            p("dc_dmodulus_y", 2.0),
            p("dc_dmodulus_angle", 45.0),
            p("dc_dmodulus_shiftx", 0.0),
            p("dc_dmodulus_shifty", 0.0),
            p("dc_dmodulus_color1", 0.0),
            p("dc_dmodulus_speed1", 0.0),
            p("dc_dmodulus_color2", 1.0),
            p("dc_dmodulus_speed2", 0.0),
            p_int("dc_dmodulus_square", 1.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR | flag::STATEFUL)
        .prepare(dmodulus_prepare),
    VarDef::new("dc_kaleidotile", dc_kaleidotile)
        .params(&[
            p("dc_kaleidotile_pull", -1.5),
            p("dc_kaleidotile_rotate", 0.0),
            p("dc_kaleidotile_line_up", 1.0),
            p("dc_kaleidotile_x", 0.0),
            p("dc_kaleidotile_y", 0.0),
            p("dc_kaleidotile_color1", 0.0),
            p("dc_kaleidotile_speed1", 0.0),
            p("dc_kaleidotile_color2", 1.0),
            p("dc_kaleidotile_speed2", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR | flag::STATEFUL),
    VarDef::new("dc_carpet3D", dc_carpet3d)
        .params(&[
            p("dc_carpet3D_origin", 0.5),
            p("dc_carpet3D_color_a", 0.5),
            p("dc_carpet3D_color_b", 1.0),
            p("dc_carpet3D_color_c", 1.0),
            p("dc_carpet3D_color_d", 1.0),
            p("dc_carpet3D_color_e", 0.5),
            p("dc_carpet3D_color_f", 1.0),
            p("dc_carpet3D_stretch_x", 1.0),
            p("dc_carpet3D_stretch_y", 1.0),
            p("dc_carpet3D_scale_x", 1.0),
            p("dc_carpet3D_scale_y", 1.0),
            p("dc_carpet3D_scale_z", 1.0),
            p("dc_carpet3D_offset_z", 0.0),
            p("dc_carpet3D_reset_z", 0.0),
            p("dc_carpet3D_sides", 0.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::USES_AFFINE
                | flag::USES_COLOR
                | flag::SETS_COLOR
                | flag::WRITES_Z
                | flag::WRITES_ACC,
        ),
    VarDef::new("dc_gnarly", dc_gnarly)
        .params(&[
            p_int("dc_gnarly_mode", 1.0, 0.0, 8.0),
            p("dc_gnarly_scalex", 0.05),
            p("dc_gnarly_scaley", 0.05),
            p("dc_gnarly_freqx1", 3.5),
            p("dc_gnarly_freqy1", 3.5),
            p("dc_gnarly_freqx2", 2.0),
            p("dc_gnarly_freqy2", 2.0),
            p("dc_gnarly_freqx3", 5.0),
            p("dc_gnarly_freqy3", 5.0),
            p_int("dc_gnarly_dc", 1.0, 0.0, 1.0),
            p("dc_gnarly_color1", 5.0),
            p("dc_gnarly_color2", 5.0),
            p("dc_gnarly_fmag", 1.0),
            p("dc_gnarly_distort", 0.0),
            p("dc_gnarly_blur", 5.0),
            p("dc_gnarly_scale_z", 0.0),
            p("dc_gnarly_offset_z", 0.0),
            p_int("dc_gnarly_reset_z", 0.0, 0.0, 1.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::STATEFUL
                | flag::USES_COLOR
                | flag::SETS_COLOR
                | flag::WRITES_Z
                | flag::WRITES_ACC,
        ),
];

/// dc_carpet3D: the point shifted by (±stretch_x, ±stretch_y) (signs at random) and mapped
/// by the xform's affine map, scaled per axis; the colour the carried colour blended by the
/// quadrant's XOR (modulo color_f); z the colour scaled and offset, replacing z (reset_z > 0)
/// or added twice (the second time times a random number with `sides` > 0).
fn dc_carpet3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        origin,
        ca,
        cb,
        cc,
        cd,
        ce,
        cf,
        stx,
        sty,
        scx,
        scy,
        scz,
        offz,
        reset,
        sides,
    ] = v.params();
    let x0: i32 = if rng.f01() < 0.5 { -1 } else { 1 };
    let y0: i32 = if rng.f01() > 0.5 { -1 } else { 1 };
    let (x, y) = (t.x + x0 as f64 * stx, t.y + y0 as f64 * sty);
    let xor = (x0 ^ y0) as f64;
    let h = 0.1 * origin;
    let hh = -h + (cb - xor) * h;
    let a = &v.aff;
    let ox = v.w * (a.a * x + a.b * y + a.e) * scx;
    let oy = v.w * (a.c * x + a.d * y + a.f) * scy;
    acc.color = (acc.color * ca * (cc + hh) + xor * (cd - hh) * ce).abs() % cf;
    let dz = acc.color * scz + offz;
    let z = if reset > 0.0 {
        if v.form == Form::Regular {
            acc.z = 0.0;
        }
        dz
    } else {
        let extra = if sides > 0.0 { dz * rng.f01() } else { dz };
        let base = if v.form == Form::Regular { 0.0 } else { t.z };
        base + dz + extra
    };
    [ox, oy, z]
}

/// The colour carried from call to call (0.5 at first) moved towards `colour` at `speed`:
/// c·(1 + speed)/2 + colour·(1 − speed)/2; stored for the next call, returned modulo 1.
fn carry_colour(v: &Prepared, colour: f64, speed: f64) -> f64 {
    let old = if v.state.get(1) == 1.0 {
        v.state.get(0)
    } else {
        0.5
    };
    let new = old * ((1.0 + speed) / 2.0) + colour * (1.0 - speed) / 2.0;
    v.state.set(0, new);
    v.state.set(1, 1.0);
    new % 1.0
}

/// dc_kaleidotile: the point scaled by 0.831 and turned by 45 radians into one of two
/// mirrored halves picked at random (pull, rotate, line_up, x, y negated in the second),
/// each split at y = 0; the weight is not applied.
fn dc_kaleidotile(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pull, rotate, line_up, x, y, color1, speed1, color2, speed2] = v.params();
    let (xin, yin) = (t.x * 0.831, t.y * 0.831);
    let (s45, c45) = (45f64.sin(), 45f64.cos());
    let half = |q: f64, w: f64, e: f64, r: f64, tt: f64| {
        let ox = (w * xin) * c45 - yin * s45 + e + r;
        let oy = if yin > 0.0 {
            (w * yin) * c45 + xin * s45 + q + e + tt
        } else {
            (w * yin) * c45 + xin * s45 - q - e
        };
        (ox, oy)
    };
    let (ox, oy) = if rng.f01() < 0.5 {
        acc.color = carry_colour(v, color1, speed1);
        half(pull, rotate, line_up, x, y)
    } else {
        acc.color = carry_colour(v, color2, speed2);
        half(-pull, -rotate, -line_up, -x, -y)
    };
    [ox, oy, 0.0]
}

/// dc_cylinder2: x wrapped around a cylinder (sin into x, cos into z) with a random radial
/// blur, y scaled by the blur (not by the weight); the colour a gradient along `angle`
/// across the new running sum, 1/scale wide.
fn dc_cylinder2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [offset, angle, scale, sx, sy, blur] = v.params();
    let (sr, cr) = (rng.f01() * TAU).sin_cos();
    let rr = blur * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
    let o = [
        v.w * (t.x + rr * sr).sin() * sx,
        rr * t.y * sy,
        v.w * (t.x + rr * cr).cos(),
    ];
    let (px, py, _) = sum_or_input(v, t, acc);
    let (tx, ty) = (o[0] + px, o[1] + py);
    let ldcs = 1.0 / if scale == 0.0 { 10e-6 } else { scale };
    acc.color = (0.5 * (ldcs * (angle.cos() * tx + angle.sin() * ty + offset) + 1.0)).abs() % 1.0;
    o
}

/// Derived values of dc_dmodulus: cos², sin·cos and sin² of the angle (degrees).
fn dmodulus_prepare(v: &mut Prepared) {
    let [_, _, angle] = v.params();
    let a = PI * angle / 180.0;
    let (s, c) = (a.sin(), a.cos());
    v.p.extend_from_slice(&[c * c, s * c, s * s]);
}

/// Wraps `u` into [−m, m] (from outside that range only), as dc_dmodulus does.
fn wrap(u: f64, m: f64) -> f64 {
    if u > m {
        -m + (u + m) % (2.0 * m)
    } else if u < -m {
        m - (m - u) % (2.0 * m)
    } else {
        u
    }
}

/// dc_dmodulus: the point wrapped into [−x, x] × [−y, y], then one of two turned copies
/// (picked with probabilities cos² : sin² of the angle), shifted and (with `square`) wrapped
/// again; each copy moves the colour carried from the previous call towards its own colour.
fn dc_dmodulus(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        x,
        y,
        angle,
        shiftx,
        shifty,
        color1,
        speed1,
        color2,
        speed2,
        square,
    ] = v.params();
    let [coscos, sincos, sinsin] = v.derived();
    let p2 = coscos / (coscos + sinsin);
    let p1 = sinsin / (coscos + sinsin);
    let (xn, yn) = (wrap(t.x, x), wrap(t.y, y));
    let p = rng.f01();
    let first = if angle <= 45.0 { p < p2 } else { p >= p1 };
    let (xt, yt) = if first {
        acc.color = carry_colour(v, color1, speed1);
        (
            xn * coscos + yn * sincos + x,
            -xn * sincos + yn * coscos - y,
        )
    } else {
        acc.color = carry_colour(v, color2, speed2);
        (xn * sincos + yn * sinsin, -xn * sinsin + yn * sincos)
    };
    let (xt, yt) = (xt + shiftx, yt + shifty);
    let (ox, oy) = if square as i64 == 0 {
        (xt, yt)
    } else {
        (wrap(xt, x), wrap(yt, y))
    };
    [v.w * ox, v.w * oy, 0.0]
}

/// One gnarly map of (x, y) by mode: a wave of y for x and of x for y, each the sine or
/// cosine of a frequency times the coordinate plus a nested sine, cosine, root, asinh, tan or
/// square (mode 0: a plain sine).
fn gnarly_wave(mode: i64, x0: f64, y0: f64, q: &[f64; 8]) -> (f64, f64) {
    let [sx, sy, fx1, fy1, fx2, fy2, fx3, fy3] = *q;
    let asinh = |u: f64| (u + (u * u + 1.0).sqrt()).ln();
    // One axis: a = own coordinate's partner (the wave's variable), b the coordinate the
    // middle term reads.
    let wave = |f1: f64, f2: f64, f3: f64, a: f64, b: f64| -> f64 {
        match mode {
            1 => (f1 * a + (f2 * (a + (f3 * a).sin())).sin()).cos(),
            2 => (f1 * a + (f2 * (a + (f3 * a).cos())).sin()).sin(),
            3 => (f1 * a + (f2 * (b + (f3 * a).sin())).sin()).cos(),
            4 => (f1 * a + (f2 * (a + (f3 * a).cos())).abs().sqrt().sin()).sin(),
            5 => (f1 * a + asinh(f2 * (a + (f3 * a).sin()))).cos(),
            6 => (f1 * a + (f2 * (a + (f3 * a).sin())).tan()).cos(),
            7 => (f1 * a + (f2 * (a + (f3 * a).cos())).powi(2).sin()).sin(),
            8 => (f1 * a + (f2 * (b + (f3 * a).cos())).powi(2).sin()).sin(),
            _ => (f1 * a).sin(),
        }
    };
    (
        wave(fx1, fx2, fx3, y0, x0) * sx,
        wave(fy1, fy2, fy3, x0, y0) * sy,
    )
}

/// dc_gnarly: the point blurred (a Gaussian-like radius from six draws with `blur` > 0, a
/// square with `blur` < 0), moved halfway to its gnarly wave; the colour |cos + sin| of the
/// point and the wave (modulo fmag), z from the colour. JWildfire's blur sums two draws
/// replaced in turn from call to call and four it drew once, at the start of the render;
/// those four are the four after the first two of JWildfire's generator seeded with 1.
fn dc_gnarly(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        mode,
        sx,
        sy,
        fx1,
        fy1,
        fx2,
        fy2,
        fx3,
        fy3,
        dc,
        c1,
        c2,
        fmag,
        distort,
        blur,
        scz,
        offz,
        reset,
    ] = v.params();
    let (mut x0, mut y0) = (t.x, t.y);
    if blur > 0.0 {
        let (sina, cosa) = (rng.f01() * 2.0 * PI).sin_cos();
        let mut init = Mwc::new(1);
        let g: [f64; 6] = std::array::from_fn(|_| init.next_f64());
        if v.state.get(3) != 1.0 {
            v.state.set(0, g[0]);
            v.state.set(1, g[1]);
            v.state.set(2, 0.0);
            v.state.set(3, 1.0);
        }
        let (g0, g1) = (v.state.get(0), v.state.get(1));
        let r = blur * (g0 + g1 + g[2] + g[3] + g[4] + g[5] - 3.0);
        let n = v.state.get(2) as usize;
        v.state.set(n, rng.f01());
        v.state.set(2, ((n + 1) & 5) as f64);
        x0 += r * cosa;
        y0 += r * sina;
    } else if blur < 0.0 {
        x0 += rng.f01() * blur * 2.0 - blur;
        y0 += rng.f01() * blur * 2.0 - blur;
    }
    let q = [sx, sy, fx1, fy1, fx2, fy2, fx3, fy3];
    let (x1, y1) = gnarly_wave(mode as i64, x0, y0, &q);
    let s1 = (x1 * x1 + y1 * y1).sqrt().ln() * distort;
    if dc as i64 != 0 {
        acc.color = ((x0 + x1 * c1 + s1).cos() + (y0 + y1 * c2 + s1).sin()).abs() % fmag;
    }
    let dz = acc.color * scz + offz;
    let z = if reset as i64 > 0 {
        if v.form == Form::Regular {
            acc.z = 0.0;
        }
        dz
    } else if v.form == Form::Regular {
        dz
    } else {
        t.z + dz
    };
    [v.w * (x0 + x1) / 2.0, v.w * (y0 + y1) / 2.0, z]
}
