//! JWildfire's 3-D figures and solids, from the end of its alphabet: Whittaker Courtney's
//! `mobius_dragon_3D`, the mirrored curl `polySurf`, the simple figures `primitives_wf`
//! (disc, sphere, cube, square, triangle, pyramid, torus) and the GlynnSim in space
//! `glynnSim2B`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: weights multiply the output linearly unless
//! said otherwise; where the order of JWildfire's random draws does not change the
//! distribution, the draws are made in the order that reads best.

use std::f64::consts::{PI, TAU};

use super::jwf_z_3d::{DRAWN_3D, draw_below};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("mobius_dragon_3D", mobius_dragon_3d)
        .params(&[
            p("mobius_dragon_3D_re", 1.0),
            p("mobius_dragon_3D_im", 0.0),
            p("mobius_dragon_3D_x_spread", 1.0),
            p("mobius_dragon_3D_y_spread", 0.0),
            p("mobius_dragon_3D_z_spread", 0.0),
            p("mobius_dragon_3D_x_add", 0.0),
            p("mobius_dragon_3D_y_add", 0.0),
            // JWildfire's default: e to five decimals (not e itself).
            p("mobius_dragon_3D_log_spread", 271_828.0 / 100_000.0),
            p_int("mobius_dragon_3D_line_enable", 1.0, NEG_INF, INF),
            p("mobius_dragon_3D_line_weight", 0.125),
            p("mobius_dragon_3D_line_color_shift", 0.1),
            p_int("mobius_dragon_3D_mag_color", 1.0, NEG_INF, INF),
            p("mobius_dragon_3D_mag_color_scale", 0.5),
            p_int("mobius_dragon_3D_iterations", 1.0, 0.0, 1000.0).limited(),
        ])
        .flags(DRAWN_3D | flag::USES_Z | flag::WRITES_ACC),
    VarDef::new("polySurf", poly_surf)
        .params(&[
            p("polySurf_c", 0.3),
            p_int("polySurf_mirrorX", 1.0, 0.0, 1.0),
            p_int("polySurf_mirrorY", 1.0, 0.0, 1.0),
            p_int("polySurf_mirrorZ", 0.0, 0.0, 1.0),
            p_int("polySurf_julia", 0.0, 0.0, 1.0),
            p("polySurf_juliaX", 0.0),
            p("polySurf_juliaY", 0.0),
            p("polySurf_juliaZ", 0.0),
            p_int("polySurf_enableFold", 0.0, 0.0, 1.0),
            p("polySurf_foldX", 1.0),
            p("polySurf_foldY", 1.0),
            p("polySurf_rotX", 0.0),
            p("polySurf_rotY", 0.0),
            p("polySurf_rotZ", 0.0),
            p_int("polySurf_enableOffset", 1.0, 0.0, 1.0),
            p("polySurf_offsetX", 1.0),
            p("polySurf_offsetY", 1.0),
            p("polySurf_offsetZ", 0.0),
            p_int("polySurf_enableInvert", 0.0, 0.0, 1.0),
            p("polySurf_invertRadius", 1.0),
            p_int("polySurf_colorMode", 0.0, 0.0, 2.0),
            p("polySurf_colorSpeed", 1.0),
        ])
        .flags(DRAWN_3D | flag::USES_Z),
    VarDef::new("primitives_wf", primitives_wf)
        .params(&[
            p_int("primitives_wf_shape", 1.0, NEG_INF, INF),
            p("primitives_wf_a", 1.0),
            p("primitives_wf_b", 1.0),
            p_int("primitives_wf_filled", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z),
    VarDef::new("glynnSim2B", glynn_sim2b)
        .params(&[
            p("glynnSim2B_radius", 1.0),
            p_range("glynnSim2B_thickness", 0.1, 0.0, 1.0),
            p_range("glynnSim2B_contrast", 0.5, 0.0, 1.0),
            p("glynnSim2B_pow", 1.5),
            p("glynnSim2B_phi1", 110.0),
            p("glynnSim2B_phi2", 150.0),
            p("glynnSim2B_rotX", 0.0),
            p("glynnSim2B_rotY", 0.0),
            p("glynnSim2B_rotZ", 0.0),
            p("glynnSim2B_offsetZ", 0.0),
            p("glynnSim2B_scaleX", 1.0),
            p("glynnSim2B_scaleY", 1.0),
            p("glynnSim2B_scaleZ", 1.0),
            p("glynnSim2B_shearXY", 0.0),
            p("glynnSim2B_shearXZ", 0.0),
            p("glynnSim2B_shearYX", 0.0),
            p("glynnSim2B_shearYZ", 0.0),
            p("glynnSim2B_shearZX", 0.0),
            p("glynnSim2B_shearZY", 0.0),
            p("glynnSim2B_circleRotX", 0.0),
            p("glynnSim2B_circleRotY", 0.0),
            p("glynnSim2B_circleThicknessZ", 0.0),
            p("glynnSim2B_colorMode", 0.0),
            p_range("glynnSim2B_fixedHue", 0.0, 0.0, 1.0),
            p("glynnSim2B_zHueScale", 1.0),
            p_range("glynnSim2B_randomHueAmount", 0.0, 0.0, 1.0),
        ])
        .flags(DRAWN_3D | flag::USES_Z),
];

/// mobius_dragon_3D: Whittaker Courtney's dragon: the point (x, y + 1) divided by re + i·im,
/// inverted in space with z, scaled by the weight (`iterations` times, or a point of a random
/// line with odds `line_weight`), then copied by log_tile's rounded logarithmic spreads, either
/// as it is or turned half-way round; the colour grows by tanh of the result's size
/// (`mag_color`). Replaces the sum so far.
fn mobius_dragon_3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        re,
        im,
        xs,
        ys,
        zs,
        x_add,
        y_add,
        log_spread,
        line,
        line_w,
        _,
        mag_color,
        mag_scale,
        iterations,
    ] = v.params();
    let w = v.w;
    let mut zc = acc.color;
    let random = rng.f01();
    let z1 = t.z;
    let (mut sx, mut sy, mut sz) = (-xs, -ys, -zs);
    let (mut ax, mut ay) = (t.x, t.y);
    let (mut zr, mut zi, mut vz) = (t.x, t.y + 1.0, 0.0);
    let inv = {
        let m2 = re * re + im * im;
        if m2 < 1e-100 { 1.0 } else { 1.0 / m2 }
    };
    for _ in 0..iterations as i64 {
        let (a, b) = (ax, ay + 1.0);
        zr = (b * im + a * re) * inv;
        zi = (b * re - a * im) * inv;
        let r1 = w / (zr * zr + zi * zi + z1 * z1);
        zr *= r1;
        zi = -zi * r1;
        vz = -z1 * r1;
        zr *= w;
        zi *= w;
        ax = zr;
        ay = zi + 1.0;
        if line == 1.0 && random < line_w {
            zr = rng.f01() * sx;
            zi = 0.0;
            vz = 0.0;
        }
    }
    if rng.f01() < 0.5 {
        sx = xs;
    }
    if rng.f01() < 0.5 {
        sy = ys;
    }
    if rng.f01() < 0.5 {
        sz = zs;
    }
    let ln_spread = log_spread.ln();
    let step = |rng: &mut FastRng| (rng.f01().ln() / ln_spread + 0.5).floor();
    if random < 0.5 {
        zr = w * x_add + (zr + sx * step(rng));
        zi = w * (y_add + (zi + sy * step(rng))) + 1.0;
        vz = w * (vz + sz * step(rng));
    } else {
        zr = w * (-zr + sx * step(rng));
        zi = w * (-2.0 - (zi + sy * step(rng))) + 1.0;
        vz = w * (-vz + sz * step(rng));
    }
    if mag_color == 1.0 {
        zc += ((zr * zr + zi * zi + z1 * z1).sqrt() * (mag_scale / 6.0)).tanh();
    }
    acc.color = zc;
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    [zr, zi, vz]
}

/// polySurf: a 3-D curl of (|x|, |y|, z) by c (after an optional julia shift, box fold and
/// offset), turned about the axes by rotX, rotY, rotZ degrees, optionally inverted in a sphere,
/// put back in the input's quadrant and mirrored at random per axis; the colour moves towards
/// the distance, angle or height of the result by the weight.
fn poly_surf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 22] = v.params();
    let [c, mx, my, mz, julia, jx, jy, jz, fold, fx, fy, rx, ry, rz] =
        <[f64; 14]>::try_from(&q[..14]).expect("14 values");
    let [offset, ox, oy, oz, invert, inv_r, cmode, cspeed] =
        <[f64; 8]>::try_from(&q[14..]).expect("8 values");
    let sign_x = if t.x >= 0.0 { 1.0 } else { -1.0 };
    let sign_y = if t.y >= 0.0 { 1.0 } else { -1.0 };
    let (mut x, mut y, mut z) = (t.x, t.y, t.z);
    if julia > 0.0 {
        (x, y, z) = (x + jx, y + jy, z + jz);
    }
    if fold > 0.0 {
        x = (x + fx).abs() - (x - fx).abs() - x;
        y = (y + fy).abs() - (y - fy).abs() - y;
    }
    if offset > 0.0 {
        (x, y, z) = (x + ox, y + oy, z + oz);
    }
    let (xa, ya) = (x.abs(), y.abs());
    let r2 = xa * xa + ya * ya + z * z;
    let r = v.w / (r2 * c * c + 2.0 * c * z + 1.0);
    let (mut dx, mut dy, mut dz) = (r * xa, r * ya, r * (z + c * r2));
    if rx != 0.0 || ry != 0.0 || rz != 0.0 {
        let (sx, cx) = rx.to_radians().sin_cos();
        let (sy, cy) = ry.to_radians().sin_cos();
        let (sz, cz) = rz.to_radians().sin_cos();
        (dy, dz) = (dy * cx - dz * sx, dy * sx + dz * cx);
        (dx, dz) = (dx * cy + dz * sy, -dx * sy + dz * cy);
        (dx, dy) = (dx * cz - dy * sz, dx * sz + dy * cz);
    }
    if invert > 0.0 {
        let d2 = dx * dx + dy * dy + dz * dz;
        if d2 > 1e-9 {
            let k = inv_r * inv_r / d2;
            (dx, dy, dz) = (dx * k, dy * k, dz * k);
        }
    }
    let flip = |on: f64, rng: &mut FastRng| {
        if on > 0.0 && rng.f01() < 0.5 {
            -1.0
        } else {
            1.0
        }
    };
    let ox = flip(mx, rng) * sign_x * dx;
    let oy = flip(my, rng) * sign_y * dy;
    let oz = flip(mz, rng) * dz;
    if cmode > 0.0 {
        let value = match cmode as i64 {
            1 => (dx * dx + dy * dy + dz * dz).sqrt(),
            2 => dy.atan2(dx) / TAU + 0.5,
            _ => dz,
        } * cspeed;
        let value = ((value % 1.0) + 1.0) % 1.0;
        acc.color += (value - acc.color) * v.w;
    }
    [ox, oy, oz]
}

/// The coordinate across a face of the cube of side `size`: ±size/2 (filled: with odds 0.05,
/// else uniform between; the order of JWildfire's draws does not change the distribution).
fn face(size: f64, filled: bool, rng: &mut FastRng) -> f64 {
    let near = rng.f01() < 0.5;
    if !filled || rng.f01() < 0.05 {
        size * if near { -0.5 } else { 0.5 }
    } else {
        size * (rng.f01() - 0.5)
    }
}

/// Is (x, y) in the triangle (0, 0), (1, 0), (0, 1) (its long side open)?
fn in_unit_triangle(x: f64, y: f64) -> bool {
    x >= 0.0 && y >= 0.0 && x + y < 1.0
}

/// A radius of `r`, or with `filled` a uniform fraction of it (odds 0.95).
fn shell_radius(r: f64, filled: bool, rng: &mut FastRng) -> f64 {
    if !filled || rng.f01() < 0.05 {
        r
    } else {
        r * rng.f01()
    }
}

/// primitives_wf: a random point of a simple figure the size of the weight: disc (0), sphere
/// (1), cube (2), square (3), triangle (4), pyramid (5) or torus of radii a, 2b (6); outlines,
/// or filled with `filled`.
fn primitives_wf(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [shape, a, b, filled] = v.params();
    let (w, filled) = (v.w, filled == 1.0);
    let centred = |rng: &mut FastRng| w * (rng.f01() - 0.5);
    match shape as i64 {
        0 => {
            let r = shell_radius(w, filled, rng);
            let ang = rng.f01() * TAU;
            [r * ang.cos(), r * ang.sin(), 0.0]
        }
        2 => match draw_below(rng, 3) {
            0 => [face(w, filled, rng), centred(rng), centred(rng)],
            1 => [centred(rng), face(w, filled, rng), centred(rng)],
            _ => [centred(rng), centred(rng), face(w, filled, rng)],
        },
        3 => {
            if filled && rng.f01() < 0.5 {
                [centred(rng), centred(rng), 0.0]
            } else if draw_below(rng, 2) == 0 {
                [face(w, filled, rng), centred(rng), 0.0]
            } else {
                [centred(rng), face(w, filled, rng), 0.0]
            }
        }
        4 => {
            let (x, y) = (rng.f01(), rng.f01());
            if !in_unit_triangle(x, y) {
                return [0.0; 3];
            }
            let x = if rng.f01() < 0.5 { x } else { -x };
            [x, -y, 0.0]
        }
        5 => pyramid_point(w, rng),
        6 => {
            let r = shell_radius(a, filled, rng);
            let alpha = rng.f01() * TAU;
            let (x, y) = (r * alpha.cos(), r * alpha.sin());
            let beta = rng.f01() * TAU;
            [
                (y + b + b) * beta.sin() * w,
                x * w,
                (y + b + b) * beta.cos() * w,
            ]
        }
        _ => {
            let r = shell_radius(w, filled, rng);
            let (sa, ca) = (rng.f01() * TAU).sin_cos();
            let (sb, cb) = (rng.f01() * TAU).sin_cos();
            [r * sa * cb, r * sa * sb, r * ca]
        }
    }
}

/// A point of the square pyramid of side `size` (its base or one of its four faces), or the
/// origin where JWildfire's draw misses its triangle.
fn pyramid_point(size: f64, rng: &mut FastRng) -> V3 {
    let (sin_a, cos_a) = (3f64.sqrt() / 2.0, 0.5);
    let (tx, ty) = (rng.f01(), rng.f01());
    if !in_unit_triangle(tx, ty) {
        return [0.0; 3];
    }
    let (tx, ty) = (tx * size, ty * size);
    let half = size * 0.5;
    let signed = |rng: &mut FastRng| (if rng.f01() < 0.5 { tx } else { -tx }) * 0.5;
    match draw_below(rng, 5) {
        0 => [size * (rng.f01() - 0.5), half, size * (rng.f01() - 0.5)],
        1 => [-half + cos_a * ty, half - sin_a * ty, signed(rng)],
        2 => [half - cos_a * ty, half - sin_a * ty, signed(rng)],
        3 => [signed(rng), half - sin_a * ty, -half + cos_a * ty],
        _ => [signed(rng), half - sin_a * ty, half - cos_a * ty],
    }
}

/// (y, z) turned by `a` about x, then (x, z) by `b` about y.
fn turn_xy(p: [f64; 3], a: f64, b: f64) -> [f64; 3] {
    let [x, y, z] = p;
    let (sa, ca) = a.sin_cos();
    let (y, z) = (y * ca - z * sa, y * sa + z * ca);
    let (sb, cb) = b.sin_cos();
    [x * cb + z * sb, y, -x * sb + z * cb]
}

/// glynnSim2B: eralex61's GlynnSim2 in space: inside `radius` a point of the arc from phi1 to
/// phi2 (degrees) `thickness` wide, thickened in z and turned by circleRotX, circleRotY;
/// outside, the point or (odds contrast·(radius/r)^|pow|) its inversion; then scaled,
/// sheared, turned by rotX, rotY, rotZ and lifted by offsetZ; colour by depth, at random or
/// fixed (`colorMode` 1–4).
fn glynn_sim2b(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 26] = v.params();
    let [radius, thick, contrast, pw, phi1, phi2, rx, ry, rz, off_z] =
        <[f64; 10]>::try_from(&q[..10]).expect("10 values");
    let [sx, sy, sz, sxy, sxz, syx, syz, szx, szy, crx, cry, ctz] =
        <[f64; 12]>::try_from(&q[10..22]).expect("12 values");
    let [cmode, fixed_hue, z_hue, rnd_hue] = <[f64; 4]>::try_from(&q[22..]).expect("4 values");
    let deg = PI / 180.0;
    let r = (t.x * t.x + t.y * t.y).sqrt();
    let alpha = radius / r;
    let [x, y, z] = if r < radius {
        let gamma = thick * (2.0 * radius + thick) / (radius + thick);
        let rr = radius + thick - gamma * rng.f01();
        let phi = phi1 * deg + (phi2 - phi1) * deg * rng.f01();
        let cz = (rng.f01() - 0.5) * 2.0 * ctz;
        turn_xy([rr * phi.cos(), rr * phi.sin(), cz], crx * deg, cry * deg)
    } else if rng.f01() > contrast * alpha.powf(pw.abs()) {
        [t.x, t.y, t.z]
    } else {
        [alpha * alpha * t.x, alpha * alpha * t.y, t.z]
    };
    let (x, y, z) = (x * sx, y * sy, z * sz);
    let p = [
        x + syx * y + szx * z,
        y + sxy * x + szy * z,
        z + sxz * x + syz * y,
    ];
    let [x, y, z] = turn_xy(p, rx * deg, ry * deg);
    let (s, c) = (rz * deg).sin_cos();
    let (x, y, z) = (x * c - y * s, x * s + y * c, z + off_z);
    let mode = cmode.trunc();
    if mode != 0.0 {
        let mut hue = 0.0;
        if mode == 1.0 || mode == 3.0 {
            hue = (z * z_hue) % 1.0;
            if hue < 0.0 {
                hue += 1.0;
            }
        }
        if mode == 2.0 || mode == 3.0 {
            hue = (hue + (rng.f01() - 0.5) * 2.0 * rnd_hue) % 1.0;
            if hue < 0.0 {
                hue += 1.0;
            }
        }
        if mode == 4.0 {
            hue = fixed_hue;
        }
        acc.color = hue;
    }
    [v.w * x, v.w * y, v.w * z]
}
