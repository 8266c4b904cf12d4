//! JWildfire's shapes filled at random: `cactusGlobe` (a ribbed globe cactus with areoles,
//! spikes and a cluster of smaller pups), `tess_shape` (a point of a square, rectangle,
//! triangle, hexagon, profiled rectangle or star, blended with the input, or a crop to that
//! shape), `flame_bulb` (two random complex-root steps of Inigo Quilez's spherical bulb) and
//! `grid3d_wf` (the surface of the grid cube the input lies in, cubes sized and turned at
//! random per cell).
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `CactusGlobeFunc`, `TessShapeFunc`,
//! `FlameBulbFunc` and `Grid3DWFFunc`, written anew; random numbers are drawn in the order
//! JWildfire draws them.

use std::f64::consts::{PI, TAU};

use super::jwf_a_cuts::JavaRandom;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("cactusGlobe", cactus_globe)
        .params(&[
            p_int("cactusGlobe_pattern_mode", 0.0, 0.0, 1.0),
            p_int("cactusGlobe_generator_mode", 1.0, 0.0, 1.0),
            p("cactusGlobe_size", 1.0),
            p("cactusGlobe_ribs_1", 12.0),
            p("cactusGlobe_ribDepth_1", 0.1),
            p("cactusGlobe_spiral_1", 0.5),
            p("cactusGlobe_ribs_2", 0.0),
            p("cactusGlobe_ribDepth_2", 0.0),
            p("cactusGlobe_spiral_2", 0.0),
            p("cactusGlobe_areoles_per_rib", 10.0),
            p_range("cactusGlobe_areole_density", 1.0, 0.0, 1.0),
            p("cactusGlobe_areole_focus", 16.0),
            p("cactusGlobe_areole_size", 0.05),
            p("cactusGlobe_spike_length", 0.1),
            p("cactusGlobe_spike_angle_rand", 0.0),
            p("cactusGlobe_spike_droop", 0.0),
            // JWildfire clamps the depth of the pup cluster to 0..8.
            p_int("cactusGlobe_recursion_depth", 3.0, 0.0, 8.0),
            p_range("cactusGlobe_pup_chance", 0.3, 0.0, 1.0),
            p_int("cactusGlobe_pups_count", 3.0, -2147483648.0, 2147483647.0),
            p("cactusGlobe_pup_size", 0.5),
            p("cactusGlobe_pups_spread", 1.0),
            p("cactusGlobe_pups_vertical_offset", -0.5),
            p_range("cactusGlobe_feature_color", 1.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR),
    VarDef::new("tess_shape", tess_shape)
        .params(&[
            p("tess_shape_strength", 1.0),
            p("tess_shape_shapeSize", 0.8),
            p_int("tess_shape_shapeType", 0.0, 0.0, 7.0),
            p("tess_shape_shapeAspectRatio", 1.0),
            p("tess_shape_lrRadialAmp", 0.2),
            p("tess_shape_lrRadialWidthFreq", 0.6),
            p("tess_shape_tbAmp", 0.2),
            p("tess_shape_tbWidthFreq", 0.6),
            p("tess_shape_lrRadialPosPhaseDuty", 0.0),
            p("tess_shape_tbPosPhaseDuty", 0.0),
            p_int("tess_shape_lrRadialProfileType", 0.0, 0.0, 4.0),
            p_int("tess_shape_tbProfileType", 0.0, 0.0, 4.0),
            p_int("tess_shape_operationMode", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_ACC | flag::HIDES),
    VarDef::new("flame_bulb", flame_bulb)
        .params(&[
            p("flame_bulb_root_power", 8.0),
            p("flame_bulb_radius_pow", 1.0),
            p("flame_bulb_add C", 1.0),
            p_int("flame_bulb_color mode 1-4", 1.0, 0.0, 6.0),
            p("flame_bulb_color scale", 1.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::SETS_COLOR
                | flag::USES_COLOR
                | flag::WRITES_ACC,
        ),
    VarDef::new("grid3d_wf", grid3d_wf)
        .params(&[
            p("grid3d_wf_size", 0.1),
            p("grid3d_wf_size_spread", 0.0),
            p("grid3d_wf_spacing", 0.75),
            p("grid3d_wf_alpha", 0.0),
            p("grid3d_wf_alpha_spread", 0.0),
            p("grid3d_wf_beta", 0.0),
            p("grid3d_wf_beta_spread", 0.0),
            p("grid3d_wf_gamma", 0.0),
            p("grid3d_wf_gamma_spread", 0.0),
            p_range("grid3d_wf_c1", 0.1, 0.0, 1.0),
            p_range("grid3d_wf_c2", 0.2, 0.0, 1.0),
            p_range("grid3d_wf_c3", 0.3, 0.0, 1.0),
            p_range("grid3d_wf_c4", 0.4, 0.0, 1.0),
            p_range("grid3d_wf_c5", 0.5, 0.0, 1.0),
            p_range("grid3d_wf_c6", 0.6, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR),
];

/// Java's `Math.round` (as a double): ⌊x + ½⌋.
fn java_round(x: f64) -> f64 {
    (x + 0.5).floor()
}

/// A spike on the point (x, y, z) of the cactus' surface: along the outward normal, of a
/// random length up to `length`, drooping by `droop` and splayed by `splay` in a random
/// direction.
fn cactus_spike(
    rng: &mut FastRng,
    (x, y, z): (f64, f64, f64),
    length: f64,
    splay: f64,
    droop: f64,
) -> V3 {
    let len = length * rng.f01();
    let body = (x * x + y * y + z * z).sqrt();
    if body < 1e-6 {
        return [0.0; 3];
    }
    let mut s = [x / body * len, y / body * len, z / body * len - droop * len];
    if splay > 0.0 {
        let r = [rng.f01() - 0.5, rng.f01() - 0.5, rng.f01() - 0.5];
        let rl = (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).sqrt();
        if rl > 1e-6 {
            let m = splay * len * rng.f01();
            for (sk, rk) in s.iter_mut().zip(r) {
                *sk += rk / rl * m;
            }
        }
    }
    s
}

/// One point of a cactus of size `size` (random, or the input's direction and distance scaled
/// to it): (point, whether it lies on an areole or spike).
fn cactus_point(v: &Prepared, t: &VarIn, rng: &mut FastRng, size: f64) -> (V3, bool) {
    let [
        mode,
        generator,
        base_size,
        ribs1,
        depth1,
        spiral1,
        ribs2,
        depth2,
        spiral2,
        areoles,
        density,
        focus,
        areole_size,
        spike_len,
        splay,
        droop,
    ] = v.params();
    let (rho, theta, phi) = if generator == 1.0 {
        let rho = size * rng.f01().powf(1.0 / 3.0);
        let theta = rng.f01() * TAU;
        (rho, theta, (2.0 * rng.f01() - 1.0).acos())
    } else {
        let s = if base_size > 0.0 {
            size / base_size
        } else {
            size
        };
        let (x, y, z) = (t.x * s, t.y * s, t.z * s);
        let rho = (x * x + y * y + z * z).sqrt();
        if rho == 0.0 {
            return ([0.0; 3], false);
        }
        (rho, y.atan2(x), (z / rho).acos())
    };
    let (sin_phi, cos_phi) = phi.sin_cos();
    let mut feature = false;
    let mut p;
    if mode == 0.0 {
        // One spiral of ribs, areoles on a grid along them.
        let r = rho + depth1 * sin_phi * (theta * ribs1).cos();
        let ct = theta + phi * spiral1;
        p = [r * sin_phi * ct.cos(), r * sin_phi * ct.sin(), r * cos_phi];
        if areoles > 0.0 {
            let rib_width = TAU / ribs1;
            let rib_centre = java_round(theta / rib_width) * rib_width;
            let cell = PI / areoles;
            let centre = (phi / cell).floor() * cell + cell * 0.5;
            let d = (phi.sin() * centre.sin() * (theta - rib_centre).cos()
                + phi.cos() * centre.cos())
            .acos();
            if d < areole_size {
                feature = true;
            }
        }
    } else {
        // Two spirals of ribs; areoles where they cross.
        let c1 = ((theta + phi * spiral1) * ribs1).cos();
        let c2 = ((theta + phi * spiral2) * ribs2).cos();
        let r = rho + depth1 * sin_phi * c1 + depth2 * sin_phi * c2;
        p = [
            r * sin_phi * theta.cos(),
            r * sin_phi * theta.sin(),
            r * cos_phi,
        ];
        if density > 0.0 && rng.f01() < density {
            let f = ((c1 + 1.0) / 2.0 * ((c2 + 1.0) / 2.0)).powf(focus);
            if rng.f01() < f {
                feature = true;
            }
        }
    }
    if feature {
        let s = cactus_spike(rng, (p[0], p[1], p[2]), spike_len, splay, droop);
        for (pk, sk) in p.iter_mut().zip(s) {
            *pk += sk;
        }
    }
    (p, feature)
}

/// cactusGlobe: a random point of a ribbed cactus; with chance `pup_chance` per level (up to
/// `recursion_depth` levels) one of `pups_count` smaller pups around it instead. Areoles and
/// spikes take the colour `feature_color`.
fn cactus_globe(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let p = &v.p;
    let (size, depth, chance, count, pup_size, spread, lift, colour) =
        (p[2], p[16], p[17], p[18], p[19], p[20], p[21], p[22]);
    let mut current = size;
    let mut off = [0.0; 3];
    // At most 8 levels (the parameter's bound).
    for _ in 0..(depth as i32).clamp(0, 8) {
        if rng.f01() >= chance {
            break;
        }
        let pup = (rng.f01() * count) as i32;
        let angle = f64::from(pup) / count * 2.0 * PI;
        off[0] += current * spread * angle.cos();
        off[1] += current * spread * angle.sin();
        off[2] += current * lift;
        current *= pup_size;
    }
    let (q, feature) = cactus_point(v, t, rng, current);
    if feature {
        acc.color = colour;
    }
    [
        (q[0] + off[0]) * v.w,
        (q[1] + off[1]) * v.w,
        (q[2] + off[2]) * v.w,
    ]
}

/// The offset of one edge of tess_shape's profiled shapes at `u`: a cosine bump (0) of width
/// `wf` centred at `ppd`, or a sine (1), triangle (2), square (3, duty |ppd|) or sawtooth (4)
/// wave of frequency `wf` and phase `ppd`, of amplitude `amp`.
fn profile(u: f64, kind: f64, amp: f64, wf: f64, ppd: f64) -> f64 {
    if amp == 0.0 || (kind != 0.0 && wf.abs() <= 1e-6) {
        return 0.0;
    }
    let frac = |s: f64| s - s.floor();
    match kind as i32 {
        0 => {
            if wf <= 1e-6 {
                return 0.0;
            }
            let e = u - ppd;
            let half = wf / 2.0;
            if e.abs() < half {
                amp * (1.0 + (e / half * PI).cos()) / 2.0
            } else {
                0.0
            }
        }
        1 => amp * (u * wf * TAU + ppd * TAU).sin(),
        2 => {
            let f = frac(u * wf + ppd);
            let tri = if f < 0.5 { 2.0 * f } else { 2.0 * (1.0 - f) };
            amp * (tri * 2.0 - 1.0)
        }
        3 => {
            let duty = ppd.abs().clamp(0.01, 0.99);
            if frac(u * wf) < duty { amp } else { -amp }
        }
        4 => amp * (2.0 * frac(u * wf + ppd) - 1.0),
        _ => 0.0,
    }
}

/// Whether (px, py) lies in the triangle (v1, v2, v3), edges included (JWildfire's sign test).
fn in_triangle(px: f64, py: f64, v: [f64; 6]) -> bool {
    let [x1, y1, x2, y2, x3, y3] = v;
    let d1 = (px - x2) * (y1 - y2) - (x1 - x2) * (py - y2);
    let d2 = (px - x3) * (y2 - y3) - (x2 - x3) * (py - y3);
    let d3 = (px - x1) * (y3 - y1) - (x3 - x1) * (py - y1);
    !((d1 < 0.0 || d2 < 0.0 || d3 < 0.0) && (d1 > 0.0 || d2 > 0.0 || d3 > 0.0))
}

/// How many points tess_shape draws (at most) to find one inside a profiled rectangle
/// (JWildfire's bound); the centre when none is.
const MAX_REJECTION_SAMPLES: usize = 100;

/// tess_shape's two edge profiles at the point (px, py) of a shape of half sizes (hw, hh):
/// (left/right offset, top/bottom offset). `clamp` clamps the normalised coordinates to ±1.
fn tess_offsets(v: &Prepared, px: f64, py: f64, hw: f64, hh: f64, clamp: bool) -> (f64, f64) {
    let [
        _,
        _,
        _,
        _,
        lr_amp,
        lr_wf,
        tb_amp,
        tb_wf,
        lr_ppd,
        tb_ppd,
        lr_kind,
        tb_kind,
    ] = v.params();
    let norm = |a: f64, h: f64| {
        if h == 0.0 {
            0.0
        } else if clamp {
            (a / h).clamp(-1.0, 1.0)
        } else {
            a / h
        }
    };
    let (yn, xn) = (norm(py, hh), norm(px, hw));
    let ulr = if lr_kind == 0.0 { yn } else { (yn + 1.0) / 2.0 };
    let utb = if tb_kind == 0.0 { xn } else { (xn + 1.0) / 2.0 };
    (
        profile(ulr, lr_kind, lr_amp, lr_wf, lr_ppd),
        profile(utb, tb_kind, tb_amp, tb_wf, tb_ppd),
    )
}

/// The triangle tess_shape fills (side `s`, centred on its centroid).
fn tess_triangle(s: f64) -> [f64; 6] {
    let h = s * 3f64.sqrt() / 2.0;
    [0.0, 2.0 / 3.0 * h, -s / 2.0, -h / 3.0, s / 2.0, -h / 3.0]
}

/// tess_shape's star/circle radius at the normalised angle `a01` (0..1).
fn tess_star_radius(v: &Prepared, a01: f64) -> f64 {
    let [_, size, _, _, amp, wf, _, _, ppd, _, kind] = v.params();
    let u = if kind == 0.0 { a01 * 2.0 - 1.0 } else { a01 };
    (size + profile(u, kind, amp, wf, ppd)).max(0.0)
}

/// Whether tess_shape's crop keeps (px, py).
fn tess_inside(v: &Prepared, px: f64, py: f64, hw: f64, hh: f64) -> bool {
    let [_, size, kind] = v.params();
    match kind as i32 {
        0 => px.abs() <= size / 2.0 && py.abs() <= size / 2.0,
        1 => px.abs() <= hw && py.abs() <= hh,
        2 => in_triangle(px, py, tess_triangle(size)),
        3 => (0..6).any(|i| {
            let (a1, a2) = (f64::from(i) * PI / 3.0, f64::from(i + 1) * PI / 3.0);
            let tri = [
                0.0,
                0.0,
                size * a1.cos(),
                size * a1.sin(),
                size * a2.cos(),
                size * a2.sin(),
            ];
            in_triangle(px, py, tri)
        }),
        4 => {
            let (lr, tb) = tess_offsets(v, px, py, hw, hh, true);
            (-hw + lr..=hw - lr).contains(&px) && (-hh + tb..=hh - tb).contains(&py)
        }
        5 => {
            let (dx, dy) = tess_offsets(v, px, py, hw, hh, true);
            (px - dx).abs() <= hw + 1e-7 && (py - dy).abs() <= hh + 1e-7
        }
        6 => {
            let (r, t) = tess_offsets(v, px, py, hw, hh, true);
            (-hw..=hw + r).contains(&px) && (-hh..=hh + t).contains(&py)
        }
        7 => {
            let a = py.atan2(px);
            let a01 = (a / TAU + 1.0) % 1.0;
            (px * px + py * py).sqrt() <= tess_star_radius(v, a01)
        }
        _ => false,
    }
}

/// A random point of tess_shape's shape.
fn tess_fill(v: &Prepared, rng: &mut FastRng, hw: f64, hh: f64) -> (f64, f64) {
    let [_, size, kind, _, lr_amp, _, tb_amp] = v.params();
    let sym = |rng: &mut FastRng| rng.f01() * 2.0 - 1.0;
    match kind as i32 {
        0 => {
            let x = sym(rng) * (size / 2.0);
            (x, sym(rng) * (size / 2.0))
        }
        1 => {
            let x = sym(rng) * hw;
            (x, sym(rng) * hh)
        }
        2 => {
            let [x1, y1, x2, y2, x3, y3] = tess_triangle(size);
            let (mut r1, mut r2) = (rng.f01(), rng.f01());
            if r1 + r2 > 1.0 {
                (r1, r2) = (1.0 - r1, 1.0 - r2);
            }
            let r3 = 1.0 - r1 - r2;
            (r1 * x1 + r2 * x2 + r3 * x3, r1 * y1 + r2 * y2 + r3 * y3)
        }
        3 => {
            let a = (rng.f01() * 6.0).floor() * PI / 3.0;
            let (s1, c1) = a.sin_cos();
            let (s2, c2) = (a + PI / 3.0).sin_cos();
            let (mut r1, mut r2) = (rng.f01(), rng.f01());
            if r1 + r2 > 1.0 {
                (r1, r2) = (1.0 - r1, 1.0 - r2);
            }
            (
                r1 * size * c1 + r2 * size * c2,
                r1 * size * s1 + r2 * size * s2,
            )
        }
        4 => {
            let (sx, sy) = (hw + lr_amp.abs(), hh + tb_amp.abs());
            for _ in 0..MAX_REJECTION_SAMPLES {
                let px = (rng.f01() * 2.0 - 1.0) * sx;
                let py = (rng.f01() * 2.0 - 1.0) * sy;
                let (lr, tb) = tess_offsets(v, px, py, hw, hh, true);
                if (-hw + lr..=hw - lr).contains(&px) && (-hh + tb..=hh - tb).contains(&py) {
                    return (px, py);
                }
            }
            (0.0, 0.0)
        }
        5 => {
            let px = (rng.f01() * 2.0 - 1.0) * hw;
            let py = (rng.f01() * 2.0 - 1.0) * hh;
            let (dx, dy) = tess_offsets(v, px, py, hw, hh, false);
            (px + dx, py + dy)
        }
        6 => {
            let (xa, ya) = (hw + lr_amp.abs(), hh + tb_amp.abs());
            for _ in 0..MAX_REJECTION_SAMPLES {
                let px = -hw + rng.f01() * (xa + hw);
                let py = -hh + rng.f01() * (ya + hh);
                if px < -hw || py < -hh {
                    continue;
                }
                let (r, t) = tess_offsets(v, px, py, hw, hh, true);
                if px > hw + r || py > hh + t {
                    continue;
                }
                return (px, py);
            }
            (0.0, 0.0)
        }
        7 => {
            let a = rng.f01() * TAU;
            let r = rng.f01().sqrt() * tess_star_radius(v, a / TAU);
            (r * a.cos(), r * a.sin())
        }
        _ => (0.0, 0.0),
    }
}

/// tess_shape: the input moved towards a random point of the shape by weight·strength
/// (clamped to 0..1), replacing the sum so far; with `operationMode` 1, the input itself
/// (unweighted) where it lies in the shape, hidden elsewhere.
fn tess_shape(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [strength, size, _, aspect] = v.params();
    let mode = v.p[12];
    let (bh, bw) = (size, size * aspect);
    let hh = if bh == 0.0 { 1e-9 } else { bh / 2.0 };
    let hw = if bw == 0.0 { 1e-9 } else { bw / 2.0 };
    let (x, y) = if mode == 1.0 {
        let inside = tess_inside(v, t.x, t.y, hw, hh);
        acc.hide = !inside;
        if !inside {
            return [0.0; 3];
        }
        (t.x, t.y)
    } else {
        let (sx, sy) = tess_fill(v, rng, hw, hh);
        let a = (v.w * strength).clamp(0.0, 1.0);
        ((1.0 - a) * t.x + a * sx, (1.0 - a) * t.y + a * sy)
    };
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [x, y, 0.0]
}

/// flame_bulb (Whittaker Courtney, after Mandelbulb3D's IQ bulb): the weighted input, pushed
/// out by half its length times `add C` along the diagonal, then twice a random spherical root
/// of order `root_power` (its radius raised to `radius_pow`) of its difference from the
/// weighted input. Replaces the sum so far; colours by the push (modes 1–6).
fn flame_bulb(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, rpow, add_c, mode, scale] = v.params();
    let inv = 1.0 / power;
    let o = [v.w * t.x, v.w * t.y, v.w * t.z];
    let mag = (o[0] * o[0] + o[1] * o[1] + o[2] * o[2]).sqrt() / 2.0 * add_c;
    let mut p = o;
    if add_c != 0.0 {
        p = o.map(|c| c + mag);
    }
    // Java's Random.nextInt(⌊power⌋ + 1); JWildfire fails on a bound below 1.
    let bound = ((power as i32).saturating_add(1)).max(1) as u64;
    let k = rng.below(bound) as f64;
    let k2 = rng.below(bound) as f64;
    for i in 0..2 {
        let (x, y, z) = (p[0] - o[0], p[1] - o[1], p[2] - o[2]);
        let sq = (x * x + y * y + z * z).sqrt();
        let r = sq.powf(inv).powf(rpow);
        let theta = ((z / sq).acos() + 2.0 * k * PI) * inv;
        let zangle = (y.atan2(x) + f64::from(i) * 2.0 * k2 * PI) * inv;
        p = [
            theta.sin() * zangle.cos() * r,
            theta.sin() * zangle.sin() * r,
            theta.cos() * r,
        ];
    }
    let mag2 = mag / scale;
    let len = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    match mode as i32 {
        1 => acc.color = mag2,
        2 => acc.color += mag2,
        3 => acc.color = (len + mag2 * 2.0).sin(),
        4 => acc.color += (len + mag2 * 2.0).sin(),
        5 => acc.color = (len + mag2 * 2.0).ln(),
        6 => acc.color += (len + mag2 * 2.0).ln(),
        _ => {}
    }
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    p
}

/// A grid cell's random number in [0, 1): JWildfire gives each cell the next number of a
/// generator seeded 123 when the render first reaches it (so a cell's value depends on the
/// order the cells are reached); here the first number of Java's generator seeded with 123
/// mixed with the cell's indices, the same in every render.
fn grid_cell_random(x: i32, y: i32, z: i32) -> f64 {
    let h = (i64::from(x).wrapping_mul(73_856_093))
        ^ (i64::from(y).wrapping_mul(19_349_663))
        ^ (i64::from(z).wrapping_mul(83_492_791));
    JavaRandom::new(123 ^ h).next_f64()
}

/// grid3d_wf (thargor6, after Xyrus02's dc_cube): a random point of one of the six faces
/// (chosen at random, each with its colour c1–c6) of the cube of side spacing·(size + spread/10)
/// centred on the corner of the `size` grid cell the input lies in (indices truncated
/// towards 0), turned by alpha, beta, gamma; each cell's spreads (up to `size_spread`,
/// `alpha_spread`, …) are random. Added unweighted.
fn grid3d_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        size,
        size_sp,
        spacing,
        alpha,
        alpha_sp,
        beta,
        beta_sp,
        gamma,
        gamma_sp,
        c1,
        c2,
        c3,
        c4,
        c5,
        c6,
    ] = v.params();
    let (cx, cy, cz) = (
        (t.x / size) as i32,
        (t.y / size) as i32,
        (t.z / size) as i32,
    );
    let cell = grid_cell_random(cx, cy, cz);
    let spread = |s: f64| if s > 1e-8 { -cell * s + s } else { 0.0 };
    let scl = spacing * (size + spread(size_sp) * 0.1);
    let side = |r: f64| scl * (r - 0.5);
    let (mut dx, mut dy, mut dz);
    match ((rng.f01() * 3.0) as i32).min(2) {
        0 => {
            let left = rng.f01() < 0.5;
            dx = scl * if left { -0.5 } else { 0.5 };
            dy = side(rng.f01());
            dz = side(rng.f01());
            acc.color = if left { c1 } else { c2 };
        }
        1 => {
            let top = rng.f01() < 0.5;
            dx = side(rng.f01());
            dy = scl * if top { -0.5 } else { 0.5 };
            dz = side(rng.f01());
            acc.color = if top { c3 } else { c4 };
        }
        _ => {
            let front = rng.f01() < 0.5;
            dx = side(rng.f01());
            dy = side(rng.f01());
            dz = scl * if front { -0.5 } else { 0.5 };
            acc.color = if front { c5 } else { c6 };
        }
    }
    let rotate = [alpha, beta, gamma, alpha_sp, beta_sp, gamma_sp]
        .iter()
        .any(|a| a.abs() > 1e-8);
    if rotate {
        let (sa, ca) = (alpha + spread(alpha_sp)).sin_cos();
        let (sb, cb) = (beta + spread(beta_sp)).sin_cos();
        let (sg, cg) = (gamma + spread(gamma_sp)).sin_cos();
        let rx = dx * (cb * cg) + dy * (cg * sa * sb - ca * sg) + dz * (ca * cg * sb + sa * sg);
        let ry = dx * (cb * sg) + dy * (ca * cg + sa * sb * sg) + dz * (-cg * sa + ca * sb * sg);
        let rz = dx * -sb + dy * (cb * sa) + dz * (ca * cb);
        (dx, dy, dz) = (rx, ry, rz);
    }
    [
        f64::from(cx) * size + dx,
        f64::from(cy) * size + dy,
        f64::from(cz) * size + dz,
    ]
}
