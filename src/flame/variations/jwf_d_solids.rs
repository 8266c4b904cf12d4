//! More of JWildfire's solids filled at random (Jesus Sosa's variations after Inigo Quilez's
//! signed distance functions): `cone3D`, `torus3D`, `cylinder3D`, `capsule3D`,
//! `cappedcone3D`, `rhombus3D`, `triprism3D`, `octahedron3D`, `octogonprism3D` and `rbox3D`
//! (a box with rounded edges); and two surfaces of the input point: `hourglass3D` (a
//! hyperboloid of one sheet, after Apophysis AV's) and `gridout3D` (the plane shifted by the
//! octant of its rounded point).
//!
//! The solids draw up to 50 points of the cube [−½, ½]³ as `box3D` does (see `jwf_a_sdf3d`).
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew.

use super::jwf_a_sdf3d::{dot3, fill_solid, len3, sd_box_q, sub3};
use super::util::sign;
use super::*;

/// Flags of a randomly filled solid.
const SOLID: u32 = flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::HIDES;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("cone3D", cone3d)
        .params(&[
            p_range("cone3D_w", 0.25, 0.0, 1.0),
            p_range("cone3D_h", 0.25, 0.0, 1.0),
            p_range("cone3D_Ty", 0.1, -1.0, 1.0),
        ])
        .flags(SOLID),
    VarDef::new("torus3D", torus3d)
        .params(&[
            p_range("torus3D_r1", 0.5, 0.0, 0.5),
            p_range("torus3D_r2", 0.5, 0.0, 0.5),
        ])
        .flags(SOLID),
    VarDef::new("cylinder3D", cylinder3d)
        .params(&[
            p_range("cylinder3D_d", 0.3, 0.0, 0.5),
            p_range("cylinder3D_H", 0.25, 0.0, 0.5),
        ])
        .flags(SOLID),
    VarDef::new("capsule3D", capsule3d)
        .params(&[
            p_range("capsule3D_dx", 0.1, -1.0, 1.0),
            p_range("capsule3D_dy", 0.0, -1.0, 1.0),
            p_range("capsule3D_dz", 0.0, -1.0, 1.0),
            p_range("capsule3D_tx", 0.0, -1.0, 1.0),
            p_range("capsule3D_ty", 0.0, -1.0, 1.0),
            p_range("capsule3D_tz", 0.0, -1.0, 1.0),
            p_range("capsule3D_R", 0.05, -1.0, 1.0),
        ])
        .flags(SOLID),
    VarDef::new("cappedcone3D", cappedcone3d)
        .params(&[
            p_range("cappedcone3D_h", 0.5, -1.0, 1.0),
            p_range("cappedcone3D_r1", 0.1, -1.0, 1.0),
            p_range("cappedcone3D_r2", 0.3, -1.0, 1.0),
        ])
        .flags(SOLID),
    VarDef::new("rhombus3D", rhombus3d)
        .params(&[
            p_range("rhombus3D_la", 0.5, 0.0, 0.5),
            p_range("rhombus3D_lb", 0.5, 0.0, 0.5),
            p_range("rhombus3D_h", 0.5, 0.0, 0.5),
            p_range("rhombus3D_r", 0.05, 0.0, 0.25),
        ])
        .flags(SOLID),
    VarDef::new("triprism3D", triprism3d)
        .params(&[
            p_range("triprism3D_d", 0.25, 0.0, 0.5),
            p_range("triprism3D_h", 0.5, 0.0, 0.5),
        ])
        .flags(SOLID),
    VarDef::new("octahedron3D", octahedron3d)
        .params(&[p_range("octahedron3D_h", 0.25, 0.0, 0.5)])
        .flags(SOLID),
    VarDef::new("octogonprism3D", octogonprism3d)
        .params(&[
            p_range("octogonprism3D_R", 0.25, 0.0, 0.5),
            p_range("octogonprism3D_H", 0.5, 0.0, 0.5),
        ])
        .flags(SOLID),
    VarDef::new("rbox3D", rbox3d)
        .params(&[
            p_range("rbox3D_dx", 0.5, 0.0, 0.5),
            p_range("rbox3D_dy", 0.5, 0.0, 0.5),
            p_range("rbox3D_dz", 0.5, 0.0, 0.5),
            p_range("rbox3D_r", 0.05, 0.0, 0.25),
        ])
        .flags(SOLID),
    VarDef::new("hourglass3D", hourglass3d)
        .params(&[
            p_range("hourglass3D_kx", 1.0, 1e-8, INF),
            p_range("hourglass3D_ky", 1.0, 1e-8, INF),
            p_range("hourglass3D_kz", 1.0, 1e-8, INF),
            p_range("hourglass3D_maxheight", 4.5, 0.1, INF),
            p_int("hourglass3D_limit", 1.0, 0.0, 1.0),
            p_int("hourglass3D_zero", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_Z)
        .prepare(hourglass3d_prepare),
    VarDef::new("gridout3D", gridout3d)
        .params(&[
            p("gridout3D_xx", 1.0),
            p("gridout3D_yy", 1.0),
            p("gridout3D_xa", 1.0),
            p("gridout3D_xb", 0.0),
            p("gridout3D_xc", 1.0),
            p("gridout3D_xd", 0.0),
            p("gridout3D_xe", 1.0),
            p("gridout3D_xf", 0.0),
            p("gridout3D_xg", 1.0),
            p("gridout3D_xh", 0.0),
            p("gridout3D_ya", 0.0),
            p("gridout3D_yb", 1.0),
            p("gridout3D_yc", 0.0),
            p("gridout3D_yd", 1.0),
            p("gridout3D_ye", 0.0),
            p("gridout3D_yf", 1.0),
            p("gridout3D_yg", 0.0),
            p("gridout3D_yh", 1.0),
            p("gridout3D_za", 0.0),
            p("gridout3D_zb", 0.0),
            p("gridout3D_zc", 0.0),
            p("gridout3D_zd", 0.0),
            p("gridout3D_ze", 1.0),
            p("gridout3D_zf", 1.0),
            p("gridout3D_zg", 1.0),
            p("gridout3D_zh", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z),
];

fn len2(x: f64, y: f64) -> f64 {
    (x * x + y * y).sqrt()
}

/// min(max(x, y), 0) + |max((x, y), 0)|: the distance of a 2-D box step.
fn box2(x: f64, y: f64) -> f64 {
    x.max(y).min(0.0) + len2(x.max(0.0), y.max(0.0))
}

/// cone3D: a cone of apex angle (w, h) and height Ty about the y axis.
fn cone3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [cx, cy, h] = v.params();
    let (qx, qy) = (cx * (h / cy), -cy * (h / cy));
    fill_solid(v, acc, rng, |p| {
        let (wx, wy) = (len2(p[0], p[2]), p[1]);
        let s = ((wx * qx + wy * qy) / (qx * qx + qy * qy)).clamp(0.0, 1.0);
        let (ax, ay) = (wx - qx * s, wy - qy * s);
        let (bx, by) = (wx - qx * (wx / qx).clamp(0.0, 1.0), wy - qy);
        let k = sign(qy);
        let d = (ax * ax + ay * ay).min(bx * bx + by * by);
        let s = (k * (wx * qy - wy * qx)).max(k * (wy - qy));
        d.sqrt() * sign(s)
    })
}

/// torus3D: a torus of radii r1, r2 about the y axis.
fn torus3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [r1, r2] = v.params();
    fill_solid(v, acc, rng, |p| len2(len2(p[0], p[2]) - r1, p[1]) - r2)
}

/// cylinder3D: a cylinder of radius d and half-height H about the y axis.
fn cylinder3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [d, h] = v.params();
    fill_solid(v, acc, rng, |p| {
        box2(len2(p[0], p[2]).abs() - d, p[1].abs() - h)
    })
}

/// capsule3D: a capsule of radius R between the points (dx, dy, dz) and (tx, ty, tz).
fn capsule3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ax, ay, az, bx, by, bz, r] = v.params();
    let (a, b) = ([ax, ay, az], [bx, by, bz]);
    fill_solid(v, acc, rng, |p| {
        let (pa, ba) = (sub3(p, a), sub3(b, a));
        let h = (dot3(pa, ba) / dot3(ba, ba)).clamp(0.0, 1.0);
        len3(sub3(pa, ba.map(|c| c * h))) - r
    })
}

/// cappedcone3D: a cone of half-height h cut at radii r1 (below) and r2 (above).
fn cappedcone3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [h, r1, r2] = v.params();
    fill_solid(v, acc, rng, |p| {
        let (qx, qy) = (len2(p[0], p[2]), p[1]);
        let (k2x, k2y) = (r2 - r1, 2.0 * h);
        let cax = qx - qx.min(if qy < 0.0 { r1 } else { r2 });
        let cay = qy.abs() - h;
        let f = (((r2 - qx) * k2x + (h - qy) * k2y) / (k2x * k2x + k2y * k2y)).clamp(0.0, 1.0);
        let (cbx, cby) = (qx - r2 + k2x * f, qy - h + k2y * f);
        let s = if cbx < 0.0 && cay < 0.0 { -1.0 } else { 1.0 };
        s * (cax * cax + cay * cay).min(cbx * cbx + cby * cby).sqrt()
    })
}

/// rhombus3D: a rhombus of diagonals la, lb and half-height h, its edges rounded by r.
fn rhombus3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [la, lb, h, ra] = v.params();
    fill_solid(v, acc, rng, |p| {
        let p = p.map(f64::abs);
        let (nx, nz) = (la - 2.0 * p[0], lb - 2.0 * p[2]);
        let f = ((la * nx - lb * nz) / (la * la + lb * lb)).clamp(-1.0, 1.0);
        let dx = p[0] - la * (1.0 - f) * 0.5;
        let dz = p[2] - lb * (1.0 + f) * 0.5;
        let qx = len2(dx, dz) * sign(p[0] * lb + p[2] * la - la * lb) - ra;
        box2(qx, p[1] - h)
    })
}

/// triprism3D: a triangular prism of side d and half-length h along z.
fn triprism3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [d, h] = v.params();
    let k = 3f64.sqrt();
    let hx = d * 0.5 * k;
    fill_solid(v, acc, rng, |p| {
        let mut px = (p[0] / hx).abs() - 1.0;
        let mut py = p[1] / hx + 1.0 / k;
        if px + k * py > 0.0 {
            (px, py) = ((px - k * py) / 2.0, (-k * px - py) / 2.0);
        }
        px -= px.clamp(-2.0, 0.0);
        let d1 = len2(px, py) * sign(-py) * hx;
        let d2 = p[2].abs() - h;
        len2(d1.max(0.0), d2.max(0.0)) + d1.max(d2).min(0.0)
    })
}

/// octahedron3D: a regular octahedron of radius h.
fn octahedron3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [s] = v.params();
    fill_solid(v, acc, rng, |p| {
        let [x, y, z] = p.map(f64::abs);
        let m = x + y + z - s;
        let q = if 3.0 * x < m {
            [x, y, z]
        } else if 3.0 * y < m {
            [y, z, x]
        } else if 3.0 * z < m {
            [z, x, y]
        } else {
            return m * 0.57735027;
        };
        let k = (0.5 * (q[2] - q[1] + s)).clamp(0.0, s);
        len3([q[0], q[1] - s + k, q[2] - k])
    })
}

/// octogonprism3D: an octagonal prism of inner radius R and half-length H along z.
fn octogonprism3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [r, h] = v.params();
    let (kx, ky, kz) = (-0.9238795325, 0.3826834323, 0.4142135623);
    fill_solid(v, acc, rng, |p| {
        let (mut x, mut y) = (p[0].abs(), p[1].abs());
        let m = 2.0 * (kx * x + ky * y).min(0.0);
        (x, y) = (x - kx * m, y - ky * m);
        let m = 2.0 * (-kx * x + ky * y).min(0.0);
        (x, y) = (x + kx * m, y - ky * m);
        x -= x.clamp(-kz * r, kz * r);
        y -= r;
        box2(len2(x, y) * sign(y), p[2].abs() - h)
    })
}

/// rbox3D: a box of half-sides dx, dy, dz with edges rounded by r.
fn rbox3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [dx, dy, dz, r] = v.params();
    fill_solid(v, acc, rng, |p| {
        sd_box_q([p[0].abs() - dx, p[1].abs() - dy, p[2].abs() - dz]) - r
    })
}

fn hourglass3d_prepare(v: &mut Prepared) {
    let [kx, ky, kz, maxheight, _, _] = v.params();
    let h = (1.0 + (maxheight / ky).powi(2)).sqrt();
    let hb = (h * h - 1.0).sqrt();
    let w = v.w;
    v.p.extend_from_slice(&[w * kx, w * ky, w * kz, h, hb]);
}

/// hourglass3D: the hyperboloid (cosh y·sin x, sinh y, cosh y·cos x) scaled by (kx, ky, kz);
/// with `limit`, cut where cosh y exceeds the height's (points beyond dropped with `zero`,
/// else put on the rim).
fn hourglass3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, _, limit, zero] = v.params();
    let [vkx, vky, vkz, h, hb] = v.derived();
    let (sn, cn) = t.x.sin_cos();
    let (sh, ch) = (t.y.sinh(), t.y.cosh());
    if limit == 0.0 || ch <= h {
        [vkx * ch * sn, vky * sh, vkz * ch * cn]
    } else if zero == 0.0 {
        [vkx * h * sn, vky * sign(sh) * hb, vkz * h * cn]
    } else {
        [0.0; 3]
    }
}

/// gridout3D: the point moved by one of eight offsets (z scaled in the upper half) chosen by
/// the octant of its rounded coordinates.
fn gridout3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [
        xx,
        yy,
        xa,
        xb,
        xc,
        xd,
        xe,
        xf,
        xg,
        xh,
        ya,
        yb,
        yc,
        yd,
        ye,
        yf,
        yg,
        yh,
        za,
        zb,
        zc,
        zd,
        ze,
        zf,
        zg,
        zh,
    ] = v.params();
    let x = t.x.round_ties_even() * xx;
    let y = t.y.round_ties_even() * yy;
    let (dx, dy, z) = if y <= 0.0 {
        if x > 0.0 {
            if -y >= x {
                (xa, ya, t.z + za)
            } else {
                (xb, yb, t.z + zb)
            }
        } else if y <= x {
            (xc, yc, t.z + zc)
        } else {
            (xd, -yd, t.z + zd)
        }
    } else if x > 0.0 {
        if y >= x {
            (-xe, ye, t.z * ze)
        } else {
            (xf, yf, t.z * zf)
        }
    } else if y > -x {
        (-xg, yg, t.z * zg)
    } else {
        (xh, -yh, t.z * zh)
    };
    [v.w * (t.x + dx), v.w * (t.y + dy), v.w * z]
}
