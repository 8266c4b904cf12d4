//! Brad Stefanov's `cell3D`: space cut into cubes of side `size`/`a`, the cells moved apart by
//! quadrant (their indices spaced and shifted as `cell` does in the plane, optionally with a
//! second set of spacings on a checkerboard), the cell contents scaled, bent by powers and
//! turned; optional random mirrors and a colour from the cell index.
//!
//! The formula follows JWildfire 9.00 (`Cell3DFunc`, LGPL-2.1), written anew. JWildfire clamps
//! `color_mode` to 0 or 1, so only the cell-index colouring is reachable there and here.

use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("cell3D", cell3d)
    .params(&[
        p("cell3D_size", 0.6),
        p("cell3D_a", 1.0),
        p("cell3D_grid_rot_x", 0.0),
        p("cell3D_grid_rot_y", 0.0),
        p("cell3D_grid_rot_z", 0.0),
        p("cell3D_cell_idx_power_x", 1.0),
        p("cell3D_cell_idx_power_y", 1.0),
        p("cell3D_cell_idx_power_z", 1.0),
        p_int("cell3D_dxdydz_mode", 0.0, 0.0, 1.0),
        p("cell3D_cell_scale_x", 1.0),
        p("cell3D_cell_scale_y", 1.0),
        p("cell3D_cell_scale_z", 1.0),
        p("cell3D_cell_power_x", 1.0),
        p("cell3D_cell_power_y", 1.0),
        p("cell3D_cell_power_z", 1.0),
        p("cell3D_cell_rot_x", 0.0),
        p("cell3D_cell_rot_y", 0.0),
        p("cell3D_cell_rot_z", 0.0),
        p("cell3D_space_xa", 2.0),
        p("cell3D_space_ya", 2.0),
        p("cell3D_space_xb", 2.0),
        p("cell3D_space_yb", 2.0),
        p("cell3D_move_xa", 1.0),
        p("cell3D_space_xc", 2.0),
        p("cell3D_space_yc", 2.0),
        p("cell3D_move_ya", 1.0),
        p("cell3D_space_xd", 2.0),
        p("cell3D_space_yd", 2.0),
        p("cell3D_move_xb", 1.0),
        p("cell3D_move_yb", 1.0),
        p("cell3D_move_tr_x", 0.0),
        p("cell3D_move_tr_y", 0.0),
        p("cell3D_move_br_x", 0.0),
        p("cell3D_space_z", 1.0),
        p("cell3D_move_z", 0.0),
        p_int("cell3D_checker_mode", 0.0, 0.0, 1.0),
        p_int("cell3D_checker_invert", 0.0, 0.0, 1.0),
        p("cell3D_space_xa2", 2.0),
        p("cell3D_space_ya2", 2.0),
        p("cell3D_space_xb2", 2.0),
        p("cell3D_space_yb2", 2.0),
        p("cell3D_move_xa2", 1.0),
        p("cell3D_space_xc2", 2.0),
        p("cell3D_space_yc2", 2.0),
        p("cell3D_move_ya2", 1.0),
        p("cell3D_space_xd2", 2.0),
        p("cell3D_space_yd2", 2.0),
        p("cell3D_move_xb2", 1.0),
        p("cell3D_move_yb2", 1.0),
        p("cell3D_move_tr_x2", 0.0),
        p("cell3D_move_tr_y2", 0.0),
        p("cell3D_move_br_x2", 0.0),
        p("cell3D_space_z2", 1.0),
        p("cell3D_move_z2", 0.0),
        p_int("cell3D_mirror_x", 0.0, 0.0, 1.0),
        p_int("cell3D_mirror_y", 0.0, 0.0, 1.0),
        p_int("cell3D_mirror_z", 0.0, 0.0, 1.0),
        p_int("cell3D_invert_y", 1.0, 0.0, 1.0),
        p_int("cell3D_invert_z", 0.0, 0.0, 1.0),
        p("cell3D_offset_x", 0.0),
        p("cell3D_offset_y", 0.0),
        p("cell3D_offset_z", 0.0),
        p_int("cell3D_color_mode", 0.0, 0.0, 1.0),
        p("cell3D_cidx_scale_x", 0.05),
        p("cell3D_cidx_scale_y", 0.05),
        p("cell3D_cidx_scale_z", 0.05),
        p("cell3D_cidx_offset", 0.0),
        p("cell3D_cdist_scale", 1.0),
        p("cell3D_color_q1", 0.0),
        p("cell3D_color_q2", 0.25),
        p("cell3D_color_q3", 0.5),
        p("cell3D_color_q4", 0.75),
        p_int("cell3D_color_use_z_sign", 0.0, 0.0, 1.0),
        p("cell3D_color_z_neg_offset", 0.1),
        p("cell3D_cz_scale", 0.05),
        p("cell3D_cz_offset", 0.0),
    ])
    .flags(
        flag::JWILDFIRE
            | flag::RANDOM
            | flag::USES_Z
            | flag::WRITES_Z
            | flag::READS_ACC
            | flag::WRITES_ACC
            | flag::SETS_COLOR,
    )];

// Positions of the parameters read by name.
const GRID_ROT: usize = 2;
const CELL_IDX_POWER: usize = 5;
const DXDYDZ_MODE: usize = 8;
const CELL_SCALE: usize = 9;
const CELL_POWER: usize = 12;
const CELL_ROT: usize = 15;
/// The first of the 17 spacings and moves (`space_xa` … `move_z`); the alternate set
/// (`space_xa2` …) follows the two checkerboard switches.
const SPACING: usize = 18;
const CHECKER_MODE: usize = 35;
const CHECKER_INVERT: usize = 36;
const SPACING2: usize = 37;
const MIRROR: usize = 54;
const INVERT_Y: usize = 57;
const INVERT_Z: usize = 58;
const OFFSET: usize = 59;
const COLOR_MODE: usize = 62;
const CIDX_SCALE: usize = 63;
const CIDX_OFFSET: usize = 66;

/// Turns `p` about z, then y, then x, by angles in degrees (an angle within 1e-9 of 0 is
/// skipped).
fn rotate(p: [f64; 3], [ax, ay, az]: [f64; 3]) -> [f64; 3] {
    let [mut x, mut y, mut z] = p;
    if az.abs() > 1e-9 {
        let (s, c) = az.to_radians().sin_cos();
        (x, y) = (x * c - y * s, x * s + y * c);
    }
    if ay.abs() > 1e-9 {
        let (s, c) = ay.to_radians().sin_cos();
        (x, z) = (x * c + z * s, -x * s + z * c);
    }
    if ax.abs() > 1e-9 {
        let (s, c) = ax.to_radians().sin_cos();
        (y, z) = (y * c - z * s, y * s + z * c);
    }
    [x, y, z]
}

/// Java's `Math.signum`.
fn signum(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        x
    }
}

/// cell3D: the cell index of the point (after the grid turn), powered and moved by quadrant;
/// the offset within the cell bent, scaled and turned; the sum weighted, then mirrored at
/// random and offset.
fn cell3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 76] = v.params();
    let three = |i: usize| [q[i], q[i + 1], q[i + 2]];
    let p = if three(GRID_ROT).iter().any(|a| a.abs() > 1e-9) {
        rotate([t.x, t.y, t.z], three(GRID_ROT))
    } else {
        [t.x, t.y, t.z]
    };
    let (size, a) = (q[0], q[1]);
    let cell = if a.abs() < 1e-9 {
        if size.abs() < 1e-9 { 1.0 } else { size }
    } else {
        size / a
    };
    if cell.abs() < 1e-9 {
        acc.x += v.w * p[0];
        acc.y += v.w * p[1];
        acc.z += v.w * p[2];
        return [0.0; 3];
    }
    let inv = 1.0 / cell;
    let raw = p.map(|c| (c * inv).floor());
    let mut idx = raw;
    for k in 0..3 {
        let power = q[CELL_IDX_POWER + k];
        if (power - 1.0).abs() > 1e-9 {
            idx[k] = signum(raw[k]) * raw[k].abs().powf(power);
        }
    }
    let mut d = [0.0; 3];
    for k in 0..3 {
        d[k] = p[k] - raw[k] * cell;
        if q[DXDYDZ_MODE] == 1.0 {
            d[k] = cell / 2.0 - (d[k] - cell / 2.0).abs();
        }
    }
    if q[COLOR_MODE] == 1.0 {
        let c = idx[0] * q[CIDX_SCALE]
            + idx[1] * q[CIDX_SCALE + 1]
            + idx[2] * q[CIDX_SCALE + 2]
            + q[CIDX_OFFSET];
        acc.color = c.abs().fract();
    }
    for k in 0..3 {
        let power = q[CELL_POWER + k];
        if (power - 1.0).abs() > 1e-9 {
            d[k] = if d[k].abs() < 1e-9 {
                0.0
            } else {
                signum(d[k]) * (d[k] * inv).abs().powf(power) * cell
            };
        }
        d[k] *= q[CELL_SCALE + k];
    }
    if three(CELL_ROT).iter().any(|a| a.abs() > 1e-9) {
        let h = cell / 2.0;
        d = rotate(d.map(|c| c - h), three(CELL_ROT)).map(|c| c + h);
    }
    let odd = (raw[0] + raw[1]) % 2.0 != 0.0;
    let alt = q[CHECKER_MODE] == 1.0 && (odd == (q[CHECKER_INVERT] == 0.0));
    let s = if alt { SPACING2 } else { SPACING };
    let [
        xa,
        ya,
        xb,
        yb,
        mxa,
        xc,
        yc,
        mya,
        xd,
        yd,
        mxb,
        myb,
        trx,
        try_,
        brx,
        sz,
        mz,
    ]: [f64; 17] = q[s..s + 17].try_into().unwrap_or([0.0; 17]);
    let (ix, iy) = (idx[0], idx[1]);
    let (mx, my) = match (ix >= 0.0, iy >= 0.0) {
        (true, true) => (xa * ix + trx, ya * iy + try_),
        (false, true) => (-(xb * ix + mxa), yb * iy),
        (true, false) => (xc * ix + brx, -(yc * iy + mya)),
        (false, false) => (-(xd * ix + mxb), -(yd * iy + myb)),
    };
    let mzi = idx[2] * sz + mz;
    let fx = d[0] + mx * cell;
    let fy = d[1] + my * cell;
    let fz = d[2] + mzi * cell;
    acc.x += v.w * fx;
    acc.y += v.w * if q[INVERT_Y] == 1.0 { -fy } else { fy };
    acc.z += v.w * if q[INVERT_Z] == 1.0 { -fz } else { fz };
    if q[MIRROR] > 0.0 && rng.f01() < 0.5 {
        acc.x = -acc.x;
    }
    if q[MIRROR + 1] > 0.0 && rng.f01() < 0.5 {
        acc.y = -acc.y;
    }
    if q[MIRROR + 2] > 0.0 && rng.f01() < 0.5 {
        acc.z = -acc.z;
    }
    acc.x += q[OFFSET];
    acc.y += q[OFFSET + 1];
    acc.z += q[OFFSET + 2];
    [0.0; 3]
}
