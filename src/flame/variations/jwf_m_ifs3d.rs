//! JWildfire's `chaosCubes`: the chaos game of 3-D cube fractals (the Menger sponge and its
//! relatives: the sub-cubes kept are chosen by how many of a cell's coordinates are 0, or
//! their complement with `invert`; mode 6 the Sierpinski pyramid; mode 7 two modes at
//! random), run `depth` steps from the input, with twists, a turn of the start, an inversion
//! in a sphere and a colour by the walk; and `romanesco` (a Romanesco broccoli: florets on a
//! golden-angle spiral on a cone, each carrying a smaller cone, `recursion_depth` levels down,
//! optionally on several arms).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew. Random numbers are drawn
//! in the order JWildfire draws them; the redraw of an excluded cell stops after 1000 tries,
//! and romanesco's depth is limited to 100 levels (JWildfire's is unbounded; each level is
//! 0.28 times smaller by default).

use std::f64::consts::PI;

use super::util::jwf_math as jm;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("chaosCubes", chaos_cubes)
        .params(&[
            p_int("chaosCubes_mode", 0.0, 0.0, 7.0),
            p_int("chaosCubes_mode7_A", 0.0, 0.0, 5.0),
            p_int("chaosCubes_mode7_B", 1.0, 0.0, 5.0),
            p_int("chaosCubes_depth", 5.0, 1.0, 15.0),
            p("chaosCubes_twistX", 0.0),
            p("chaosCubes_twistY", 0.0),
            p("chaosCubes_twistZ", 0.0),
            p("chaosCubes_scaleX", 0.3333333),
            p("chaosCubes_scaleY", 0.3333333),
            p("chaosCubes_scaleZ", 0.3333333),
            p("chaosCubes_offset", 1.0),
            p("chaosCubes_rotX", 0.0),
            p("chaosCubes_rotY", 0.0),
            p("chaosCubes_rotZ", 0.0),
            p_int("chaosCubes_invert", 0.0, 0.0, 1.0),
            p_int("chaosCubes_julia", 0.0, 0.0, 1.0),
            p_int("chaosCubes_colorMode", 0.0, 0.0, 5.0),
            p("chaosCubes_colorSpeed", 1.0),
            p_int("chaosCubes_sphereInvert", 0.0, 0.0, 1.0),
            p("chaosCubes_sphereRadius", 1.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::SETS_COLOR
                | flag::USES_COLOR,
        ),
    VarDef::new("romanesco", romanesco)
        .params(&[
            p("romanesco_size", 0.5),
            p_int("romanesco_recursion_depth", 7.0, -2147483648.0, 100.0),
            p_int("romanesco_num_arms", 1.0, -2147483648.0, 2147483647.0),
            p("romanesco_arm_spread", 1.0),
            p("romanesco_arm_elevation", 45.0),
            p("romanesco_arm_twist", 0.0),
            p_int("romanesco_floret_count", 100.0, -2147483648.0, 2147483647.0),
            p("romanesco_floret_scale", 0.28),
            p("romanesco_pattern_spread", 0.4),
            p("romanesco_spiral_twist", 1.0),
            p("romanesco_cone_steepness", 1.0),
            p("romanesco_floret_detail_size", 0.1),
            p_int("romanesco_floret_shape", 0.0, 0.0, 3.0),
            p("romanesco_pitch", 180.0),
            p("romanesco_yaw", 0.0),
            p("romanesco_roll", 0.0),
            p_int("romanesco_color_mode", 0.0, 0.0, 3.0),
            p("romanesco_solid_color_idx", 0.5),
            p("romanesco_color_range_min", 0.0),
            p("romanesco_color_range_max", 9.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR),
];

// The rotations take JWildfire's table sin and cos: the twists feed each step's angle with
// the previous step's point, so the last bits of sin and cos grow along the chain.
fn rotate_x(p: &mut [f64; 3], a: f64) {
    let (y, z) = (p[1], p[2]);
    let (s, c) = (jm::sin(a), jm::cos(a));
    p[1] = c * y - s * z;
    p[2] = s * y + c * z;
}

fn rotate_y(p: &mut [f64; 3], a: f64) {
    let (x, z) = (p[0], p[2]);
    let (s, c) = (jm::sin(a), jm::cos(a));
    p[0] = c * x + s * z;
    p[2] = -s * x + c * z;
}

fn rotate_z(p: &mut [f64; 3], a: f64) {
    let (x, y) = (p[0], p[1]);
    let (s, c) = (jm::sin(a), jm::cos(a));
    p[0] = c * x - s * y;
    p[1] = s * x + c * y;
}

/// Whether sub-cube (i, j, k) of {−1, 0, 1}³ is kept in `mode` (0–5).
fn cube_kept(mode: i32, [i, j, k]: [i32; 3], invert: bool) -> bool {
    let zeros = i32::from(i == 0) + i32::from(j == 0) + i32::from(k == 0);
    let sum = i.abs() + j.abs() + k.abs();
    let centre = i == 0 && j == 0 && k == 0;
    let kept = match mode {
        0 => zeros < 2,
        1 => return if invert { sum > 1 } else { sum <= 1 },
        2 => !centre,
        3 => {
            return if invert {
                zeros >= 2 && !centre
            } else {
                zeros < 2 || centre
            };
        }
        4 => sum == 3,
        _ => 3 - zeros == 2,
    };
    kept != invert
}

/// A random kept sub-cube of `mode` (JWildfire redraws until one is kept).
fn pick_cube(rng: &mut FastRng, mode: i32, invert: bool) -> Option<[i32; 3]> {
    for _ in 0..1000 {
        let c = [0; 3].map(|_| (rng.f01() * 3.0) as i32 - 1);
        if cube_kept(mode, c, invert) {
            return Some(c);
        }
    }
    None
}

/// chaosCubes: `depth` steps of the cube fractal's chaos game from the input.
fn chaos_cubes(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        mode,
        mode_a,
        mode_b,
        depth,
        tx,
        ty,
        tz,
        sx,
        sy,
        sz,
        offset,
        rx,
        ry,
        rz,
    ] = v.params();
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        invert,
        julia,
        color_mode,
        speed,
        sphere,
        radius,
    ] = v.params();
    let mut p = [t.x, t.y, t.z];
    for (r, rot) in [
        (rx, rotate_x as fn(&mut [f64; 3], f64)),
        (ry, rotate_y),
        (rz, rotate_z),
    ] {
        if r != 0.0 {
            rot(&mut p, r.to_radians());
        }
    }
    let c = p;
    let (mut last, mut last_v, mut path) = ([0; 3], 0, 0.0);
    let scale = [sx, sy, sz];
    for _ in 0..depth as i32 {
        let mut m = mode as i32;
        if m == 7 {
            m = if rng.f01() < 0.5 {
                mode_a as i32
            } else {
                mode_b as i32
            };
        }
        if m == 6 {
            let verts = [
                [offset, offset, 0.0],
                [offset, -offset, 0.0],
                [-offset, -offset, 0.0],
                [-offset, offset, 0.0],
                [0.0, 0.0, offset * sy * 0.5],
            ];
            last_v = ((rng.f01() * 5.0) as usize).min(4);
            p = [0, 1, 2].map(|k| (p[k] + verts[last_v][k]) * 0.5);
        } else if let Some(cube) = pick_cube(rng, m, invert == 1.0) {
            last = cube;
            p = [0, 1, 2].map(|k| p[k] * scale[k] - f64::from(cube[k]) * offset * (1.0 - scale[k]));
            if julia > 0.0 {
                p = [0, 1, 2].map(|k| p[k] + c[k]);
            }
        }
        if tx != 0.0 {
            let a = p[0] * tx;
            rotate_x(&mut p, a);
        }
        if ty != 0.0 {
            let a = p[1] * ty;
            rotate_y(&mut p, a);
        }
        if tz != 0.0 {
            let a = p[2] * tz;
            rotate_z(&mut p, a);
        }
        path += (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    }
    if sphere > 0.0 {
        let r2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        if r2 > 1e-6 {
            p = p.map(|a| a * (radius * radius / r2));
        }
    }
    if color_mode > 0.0 {
        let col = match color_mode as i32 {
            1 => (p[0] / offset + p[1] / offset + p[2] / offset) / 3.0,
            2 if mode == 6.0 => last_v as f64 / 4.0,
            2 => f64::from(last[0] + 1 + (last[1] + 1) * 3 + (last[2] + 1) * 9) / 26.0,
            3 => (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt() / offset,
            4 => path / (depth * offset),
            _ => (libm::atan2(p[1], p[0]) + libm::atan2(p[2], p[0]) + 2.0 * PI) / (4.0 * PI),
        } * speed;
        let col = ((col % 1.0) + 1.0) % 1.0;
        acc.color += (col - acc.color) * v.w;
    }
    p.map(|a| a * v.w)
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `v` scaled to length 1 (unchanged when shorter than 1e-9).
fn normalized(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if l > 1e-9 { v.map(|c| c / l) } else { v }
}

/// `base` plus the local point `l` in the frame (ax, ay, az).
fn in_frame(base: [f64; 3], [ax, ay, az]: [[f64; 3]; 3], l: [f64; 3], k: f64) -> [f64; 3] {
    [0, 1, 2].map(|i| base[i] + (ax[i] * l[0] + ay[i] * l[1] + az[i] * l[2]) * k)
}

/// The floret's own shape about its centre: a ball, a cube, a spike or a ring of `size`.
fn floret_point(rng: &mut FastRng, shape: f64, size: f64) -> [f64; 3] {
    match shape as i32 {
        0 => {
            let r = [0; 3].map(|_| rng.f01() - 0.5);
            let len = (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).sqrt();
            if len > 1e-6 {
                let bump = size * rng.f01();
                r.map(|c| c / len * bump)
            } else {
                [0.0; 3]
            }
        }
        1 => [0; 3].map(|_| (rng.f01() - 0.5) * size),
        2 => [0.0, 0.0, size * rng.f01()],
        _ => {
            let a = rng.f01() * 2.0 * PI;
            [size * a.cos(), size * a.sin(), 0.0]
        }
    }
}

/// romanesco: a random point of a random floret `recursion_depth` levels down the spirals.
fn romanesco(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        size,
        depth,
        arms,
        spread,
        elevation,
        twist,
        count,
        fscale,
        pspread,
        stwist,
    ] = v.params();
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        steep,
        detail,
        shape,
        pitch,
        yaw,
        roll,
        cmode,
    ] = v.params();
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        solid,
        cmin,
        cmax,
    ] = v.params();
    let golden = PI * (3.0 - 5f64.sqrt());
    let mut scale = size;
    let mut pos = [0.0; 3];
    let (mut ax, mut ay, mut az) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    if arms > 1.0 {
        let i = (rng.f01() * arms) as i32;
        let base = f64::from(i) / arms * 2.0 * PI;
        pos = [spread * base.cos(), spread * base.sin(), 0.0];
        let el = elevation * PI / 180.0;
        let a = base + pos[1] * twist;
        az = [a.cos() * el.cos(), a.sin() * el.cos(), el.sin()];
        let up = if az[2].abs() > 0.999 {
            [1.0, 0.0, 0.0]
        } else {
            [0.0, 0.0, 1.0]
        };
        ax = normalized(cross(az, up));
        ay = cross(az, ax);
    }
    for _ in 0..depth.max(0.0) as i32 {
        let floret = (rng.f01().powf(1.5) * count) as i32;
        let sa = f64::from(floret) * golden * stwist;
        let r = pspread * f64::from(floret).sqrt();
        let local = [r * sa.cos(), r * sa.sin(), r * steep];
        pos = in_frame(pos, [ax, ay, az], local, scale);
        let n = normalized([-steep * sa.cos(), -steep * sa.sin(), 1.0]);
        az = normalized(in_frame([0.0; 3], [ax, ay, az], n, 1.0));
        let up = if az[1].abs() > 0.999 {
            [1.0, 0.0, 0.0]
        } else {
            [0.0, 1.0, 0.0]
        };
        ax = normalized(cross(up, az));
        ay = cross(az, ax);
        scale *= fscale;
    }
    let local = floret_point(rng, shape, detail * scale);
    let [mut x, mut y, mut z] = in_frame(pos, [ax, ay, az], local, 1.0);
    if pitch != 0.0 || yaw != 0.0 || roll != 0.0 {
        let (sp, cp) = pitch.to_radians().sin_cos();
        let (sy, cy) = yaw.to_radians().sin_cos();
        let (sr, cr) = roll.to_radians().sin_cos();
        (x, z) = (x * cy - z * sy, x * sy + z * cy);
        (y, z) = (y * cp - z * sp, y * sp + z * cp);
        (x, y) = (x * cr - y * sr, x * sr + y * cr);
    }
    let range = cmax - cmin;
    let index = match cmode as i32 {
        0 => solid,
        1 if range > 1e-6 => ((x * x + y * y + z * z).sqrt() - cmin) / range,
        2 if range > 1e-6 => ((x * x + y * y).sqrt() - cmin) / range,
        3 if range > 1e-6 => (z - cmin) / range,
        _ => 0.5,
    };
    acc.color = index.clamp(0.0, 1.0);
    [x * v.w, y * v.w, z * v.w]
}
