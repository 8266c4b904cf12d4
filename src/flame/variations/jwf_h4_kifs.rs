//! Brad Stefanov's `kifs3d`: a kaleidoscopic IFS iterated inside one call — fold (absolute
//! values, a diagonal, a custom plane or an edge; or the same as random mirrors), turn, scale
//! about a pivot and shift, in one of three orders, until the point leaves the bailout ball —
//! then random sign flips, and a colour from the escape time or the final point.
//!
//! The formula follows JWildfire 9.00 (`KIFS3DFunc`, LGPL-2.1), written anew.

use std::f64::consts::PI;

use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("kifs3d", kifs3d)
    .params(&[
        // At most 1000 rounds per call (each a few dozen operations).
        p_int("kifs3d_max_iter", 7.0, 0.0, 1000.0).limited(),
        p("kifs3d_bailout_radius", 1.1),
        p("kifs3d_kifs_scale_x", 1.4),
        p("kifs3d_kifs_scale_y", 1.4),
        p("kifs3d_kifs_scale_z", -1.0),
        p_int("kifs3d_scale_pivot", 0.0, 0.0, 1.0),
        p("kifs3d_center_x", 0.0),
        p("kifs3d_center_y", 0.0),
        p("kifs3d_center_z", 0.0),
        p("kifs3d_offset_x", -1.0),
        p("kifs3d_offset_y", -1.0),
        p("kifs3d_offset_z", 1.0),
        p_int("kifs3d_mirror_fold", 0.0, 0.0, 1.0),
        p_int("kifs3d_fold_type", 1.0, 0.0, 4.0),
        p("kifs3d_fold_plane1_nx", 1.0),
        p("kifs3d_fold_plane1_ny", 0.0),
        p("kifs3d_fold_plane1_nz", 0.0),
        p("kifs3d_fold_plane1_dist", 0.0),
        p_range("kifs3d_fold_plane1_intensity", 1.0, 0.0, f64::MAX),
        p("kifs3d_edge_x", 0.0),
        p("kifs3d_edge_y", 0.0),
        p("kifs3d_edge_z", 0.0),
        p("kifs3d_rot_x", 5.0),
        p("kifs3d_rot_y", 5.0),
        p("kifs3d_rot_z", 5.0),
        p_int("kifs3d_rot_order", 0.0, 0.0, 1.0),
        p_int("kifs3d_rot_pivot", 0.0, 0.0, 2.0),
        p_int("kifs3d_transform_order", 0.0, 0.0, 2.0),
        p_int("kifs3d_post_symmetry", 7.0, 0.0, 7.0),
        p_int("kifs3d_color_mode", 0.0, 0.0, 5.0),
        p("kifs3d_color_scale", 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR)
    .prepare(kifs3d_prepare)];

/// Derived values: the squared bailout radius (1e-6 when not positive), the sines and cosines
/// of the three turns (x, y, z), and the squared length of the fold plane's normal.
fn kifs3d_prepare(v: &mut Prepared) {
    let q: [f64; 31] = v.params();
    let bail = q[1] * q[1];
    let bail = if bail <= 0.0 { 1e-6 } else { bail };
    let turns = [q[22], q[23], q[24]].map(f64::to_radians);
    let still = turns.iter().all(|&a| a == 0.0);
    v.p.extend_from_slice(&[bail, f64::from(u8::from(still))]);
    for a in turns {
        v.p.extend_from_slice(&[a.sin(), a.cos()]);
    }
    v.p.push(q[14] * q[14] + q[15] * q[15] + q[16] * q[16]);
}

/// A random sign, −1 or +1 with equal odds.
fn sign(rng: &mut FastRng) -> f64 {
    if rng.f01() < 0.5 { -1.0 } else { 1.0 }
}

/// One fold of the point (with `mirror_fold`, the random mirror form: three signs drawn).
fn fold(q: &[f64; 31], norm2: f64, [x, y, z]: V3, rng: &mut FastRng) -> V3 {
    let (n, dist, intensity) = ([q[14], q[15], q[16]], q[17], q[18]);
    let edge = [q[19], q[20], q[21]];
    let plane = |side: f64| {
        let s = (1.0 + intensity) * side / norm2;
        [x - s * n[0], y - s * n[1], z - s * n[2]]
    };
    let dot = x * n[0] + y * n[1] + z * n[2] - dist;
    let p = [x, y, z];
    if q[12] <= 0.0 {
        match q[13] as i64 {
            1 => [x.abs(), y.abs(), z.abs()],
            2 if x + y < 0.0 => [-y, -x, z],
            3 if norm2 > 1e-9 && dot < 0.0 => plane(dot),
            4 => std::array::from_fn(|k| {
                if edge[k] != 0.0 {
                    edge[k] - (edge[k] - p[k]).abs()
                } else {
                    p[k]
                }
            }),
            _ => p,
        }
    } else {
        let s = [sign(rng), sign(rng), sign(rng)];
        match q[13] as i64 {
            1 => [x * s[0], y * s[1], z * s[2]],
            2 if s[0] < 0.0 => [-y, -x, z],
            3 if norm2 > 1e-9 && s[0] < 0.0 => plane(dot),
            4 => std::array::from_fn(|k| {
                if edge[k] != 0.0 {
                    edge[k] - s[k] * (edge[k] - p[k]).abs()
                } else {
                    p[k]
                }
            }),
            _ => p,
        }
    }
}

/// The turn about a pivot: z, then y, then x (`rot_order` 0), or x, y, z (1).
fn turn(v: &Prepared, q: &[f64; 31], p: V3, pivot: V3) -> V3 {
    let [_, still, sx, cx, sy, cy, sz, cz] = v.derived();
    if still == 1.0 {
        return p;
    }
    let [mut x, mut y, mut z] = [p[0] - pivot[0], p[1] - pivot[1], p[2] - pivot[2]];
    let about_z = |x: f64, y: f64| (x * cz - y * sz, x * sz + y * cz);
    let about_y = |x: f64, z: f64| (x * cy + z * sy, -x * sy + z * cy);
    let about_x = |y: f64, z: f64| (y * cx - z * sx, y * sx + z * cx);
    if q[25] == 0.0 {
        (x, y) = about_z(x, y);
        (x, z) = about_y(x, z);
        (y, z) = about_x(y, z);
    } else {
        (y, z) = about_x(y, z);
        (x, z) = about_y(x, z);
        (x, y) = about_z(x, y);
    }
    [x + pivot[0], y + pivot[1], z + pivot[2]]
}

/// The scaling about the centre (then shifted by the offset), or about the offset
/// (`scale_pivot` 1, unshifted).
fn scale(q: &[f64; 31], p: V3) -> V3 {
    let (centre, offset) = ([q[6], q[7], q[8]], [q[9], q[10], q[11]]);
    let by_offset = q[5] == 1.0;
    let pivot = if by_offset { offset } else { centre };
    std::array::from_fn(|k| {
        let s = q[2 + k] * (p[k] - pivot[k]) + pivot[k];
        if by_offset { s } else { s + offset[k] }
    })
}

/// kifs3d: up to `max_iter` rounds of fold, turn and scale (in `transform_order`), stopping
/// when the point leaves the bailout ball; random sign flips on the axes `post_symmetry`
/// names (bits x 1, y 2, z 4); the colour by `color_mode`.
fn kifs3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 31] = v.params();
    let [bail] = v.derived();
    let norm2 = v.table(0).get(8).copied().unwrap_or(0.0);
    let max_iter = q[0].max(0.0) as usize;
    let pivot = match q[26] as i64 {
        1 => [q[6], q[7], q[8]],
        2 => [q[9], q[10], q[11]],
        _ => [0.0; 3],
    };
    let mut p = [t.x, t.y, t.z];
    let mut iter_color = 1.0;
    for i in 0..max_iter {
        p = match q[27] as i64 {
            0 => scale(&q, turn(v, &q, fold(&q, norm2, p, rng), pivot)),
            1 => {
                let r = turn(v, &q, p, pivot);
                scale(&q, fold(&q, norm2, r, rng))
            }
            _ => {
                let s = scale(&q, p);
                turn(v, &q, fold(&q, norm2, s, rng), pivot)
            }
        };
        if p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > bail {
            iter_color = i as f64 / max_iter as f64;
            break;
        }
    }
    let sym = q[28] as i64;
    if sym > 0 {
        let s = [sign(rng), sign(rng), sign(rng)];
        for k in 0..3 {
            if sym & (1 << k) != 0 {
                p[k] *= s[k];
            }
        }
    }
    let [x, y, z] = p;
    let cs = q[30];
    let frac = |v: f64| v - v.floor();
    acc.color = match q[29] as i64 {
        1 => frac((x * x + y * y + z * z).sqrt() * cs),
        2 => frac((y.atan2(x) + PI) / (2.0 * PI) * cs),
        3 => frac(x * cs),
        4 => frac(y * cs),
        5 => frac(z * cs),
        _ => iter_color,
    };
    [x * v.w, y * v.w, z * v.w]
}
