//! JWildfire's solids filled at random (Jesus Sosa's variations after Inigo Quilez's signed
//! distance functions): `box3D`, `bbox3D` (a box's edges), `ellipsoid3D`, `hexprism3D`,
//! `ocylinder3D`, `pyramid3D`, `solidangle3D`, `cappedtorus3D`, `ocappedcone3D` and
//! `oroundcone3D`.
//!
//! Each call draws up to 50 uniform points of the cube [−½, ½]³ and adds the first that lies
//! inside the solid (negative distance), times the weight; when none does, the point is
//! hidden. The input point is not used. The distance functions follow JWildfire's (LGPL-2.1)
//! code, written anew, quirks included.

use super::util::sign;
use super::*;

/// Flags of a randomly filled solid.
const SOLID: u32 = flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::HIDES;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("box3D", box3d)
        .params(&[p("box3D_dx", 0.5), p("box3D_dy", 0.5), p("box3D_dz", 0.5)])
        .flags(SOLID),
    VarDef::new("bbox3D", bbox3d)
        .params(&[
            p_range("bbox3D_dx", 0.3, 0.0, 0.5),
            p_range("bbox3D_dy", 0.25, 0.0, 0.5),
            p_range("bbox3D_dz", 0.2, 0.0, 0.5),
            p_range("bbox3D_r", 0.05, 0.0, 0.25),
        ])
        .flags(SOLID),
    VarDef::new("ellipsoid3D", ellipsoid3d)
        .params(&[
            p_range("ellipsoid3D_dx", 0.5, 0.0, 0.5),
            p_range("ellipsoid3D_dy", 0.5, 0.0, 0.5),
            p_range("ellipsoid3D_dz", 0.5, 0.0, 0.5),
        ])
        .flags(SOLID),
    VarDef::new("hexprism3D", hexprism3d)
        .params(&[
            p_range("hexprism3D_d", 0.3, 0.0, 0.5),
            p_range("hexprism3D_H", 0.25, 0.0, 0.5),
        ])
        .flags(SOLID),
    VarDef::new("ocylinder3D", ocylinder3d)
        .params(&[
            p_range("ocylinder3D_dx", 1.0, -1.0, 1.0),
            p_range("ocylinder3D_dy", 0.0, -1.0, 1.0),
            p_range("ocylinder3D_dz", 0.0, -1.0, 1.0),
            p_range("ocylinder3D_tx", 0.0, -0.5, 0.5),
            p_range("ocylinder3D_ty", 0.0, -0.5, 0.5),
            p_range("ocylinder3D_tz", 0.0, -0.5, 0.5),
            p_range("ocylinder3D_r", 0.5, 0.0, 0.5),
        ])
        .flags(SOLID),
    VarDef::new("pyramid3D", pyramid3d)
        .params(&[p_range("pyramid3D_h", 0.25, 0.0, 0.5)])
        .flags(SOLID),
    VarDef::new("solidangle3D", solidangle3d)
        .params(&[
            p_range("solidangle3D_p1", 0.25, 0.0, 0.5),
            p_range("solidangle3D_p2", 0.5, 0.0, 0.5),
            p_range("solidangle3D_p3", 0.5, 0.0, 0.5),
        ])
        .flags(SOLID),
    VarDef::new("cappedtorus3D", cappedtorus3d)
        .params(&[
            p_range("cappedtorus3D_dx", 0.866025, 0.0, 1.0),
            p_range("cappedtorus3D_dy", -0.5, -5.0, 5.0),
            p_range("cappedtorus3D_R1", 0.25, 0.0, 0.5),
            p_range("cappedtorus3D_R2", 0.15, 0.0, 0.5),
        ])
        .flags(SOLID),
    VarDef::new("ocappedcone3D", ocappedcone3d)
        .params(&[
            p_range("ocappedcone3D_dx", 0.0, -1.0, 1.0),
            p_range("ocappedcone3D_dy", 0.0, -1.0, 1.0),
            p_range("ocappedcone3D_dz", 0.1, -1.0, 1.0),
            p_range("ocappedcone3D_tx", 0.0, -1.0, 1.0),
            p_range("ocappedcone3D_ty", 0.0, -1.0, 1.0),
            p_range("ocappedcone3D_tz", 0.5, -1.0, 1.0),
            p_range("ocappedcone3D_r1", 0.25, 0.0, 1.0),
            p_range("ocappedcone3D_r2", 0.05, 0.0, 1.0),
        ])
        .flags(SOLID),
    VarDef::new("oroundcone3D", oroundcone3d)
        .params(&[
            p_range("oroundcone3D_dx", 0.1, -1.0, 1.0),
            p_range("oroundcone3D_dy", 0.0, -1.0, 1.0),
            p_range("oroundcone3D_dz", 0.0, -1.0, 1.0),
            p_range("oroundcone3D_tx", -0.1, -0.5, 0.5),
            p_range("oroundcone3D_ty", 0.35, -0.5, 0.5),
            p_range("oroundcone3D_tz", 0.1, -0.5, 0.5),
            p_range("oroundcone3D_r1", 0.15, 0.0, 0.5),
            p_range("oroundcone3D_r2", 0.05, 0.0, 0.5),
        ])
        .flags(SOLID),
];

/// Up to 50 uniform draws in [−½, ½]³ until `sd` is negative: that point times the weight,
/// shown; else hidden (nothing added).
pub(super) fn fill_solid(
    v: &Prepared,
    acc: &mut Acc,
    rng: &mut FastRng,
    sd: impl Fn(V3) -> f64,
) -> V3 {
    for _ in 0..50 {
        let x = rng.f01() - 0.5;
        let y = rng.f01() - 0.5;
        let z = rng.f01() - 0.5;
        if sd([x, y, z]) < 0.0 {
            acc.hide = false;
            return [v.w * x, v.w * y, v.w * z];
        }
    }
    acc.hide = true;
    [0.0; 3]
}

pub(super) fn len3(p: V3) -> f64 {
    (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt()
}

pub(super) fn dot3(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(super) fn sub3(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// Distance to a box of half-sides b (negative inside), from |p| − b.
pub(super) fn sd_box_q(q: V3) -> f64 {
    len3(q.map(|c| c.max(0.0))) + q[0].max(q[1].max(q[2])).min(0.0)
}

/// box3D: a box of half-sides dx, dy, dz.
fn box3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let b: [f64; 3] = v.params();
    fill_solid(v, acc, rng, |p| {
        sd_box_q([p[0].abs() - b[0], p[1].abs() - b[1], p[2].abs() - b[2]])
    })
}

/// bbox3D: the edges (thickness r) of a box of half-sides dx, dy, dz.
fn bbox3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [dx, dy, dz, e] = v.params();
    fill_solid(v, acc, rng, |p| {
        let p = [p[0].abs() - dx, p[1].abs() - dy, p[2].abs() - dz];
        let q = p.map(|c| (c + e).abs() - e);
        sd_box_q([p[0], q[1], q[2]])
            .min(sd_box_q([q[0], p[1], q[2]]))
            .min(sd_box_q([q[0], q[1], p[2]]))
    })
}

/// ellipsoid3D: an ellipsoid of semi-axes dx, dy, dz (Quilez's approximate distance).
fn ellipsoid3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let r: [f64; 3] = v.params();
    fill_solid(v, acc, rng, |p| {
        let k0 = len3([p[0] / r[0], p[1] / r[1], p[2] / r[2]]);
        let k1 = len3([
            p[0] / (r[0] * r[0]),
            p[1] / (r[1] * r[1]),
            p[2] / (r[2] * r[2]),
        ]);
        k0 * (k0 - 1.0) / k1
    })
}

/// hexprism3D: a hexagonal prism of inner radius d and half-height H along z.
fn hexprism3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [hx, hy] = v.params();
    let (kx, ky, kz) = (-0.8660254, 0.5, 0.57735);
    fill_solid(v, acc, rng, |p| {
        let (ax, ay, az) = (p[0].abs(), p[1].abs(), p[2].abs());
        let m = 2.0 * (kx * ax + ky * ay).min(0.0);
        let (px, py) = (ax - kx * m, ay - ky * m);
        let cx = px.clamp(-kz * hx, kz * hx);
        let dx = ((px - cx).powi(2) + (py - hx).powi(2)).sqrt() * sign(py - hx);
        let dy = az - hy;
        dx.max(dy).min(0.0) + (dx.max(0.0).powi(2) + dy.max(0.0).powi(2)).sqrt()
    })
}

/// ocylinder3D: a cylinder of radius r between the points (dx, dy, dz) and (tx, ty, tz).
fn ocylinder3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ax, ay, az, bx, by, bz, r] = v.params();
    let (a, b) = ([ax, ay, az], [bx, by, bz]);
    fill_solid(v, acc, rng, |p| {
        let pa = sub3(p, a);
        let ba = sub3(b, a);
        let baba = dot3(ba, ba);
        let paba = dot3(pa, ba);
        let x = len3(sub3(pa.map(|c| c * baba), ba.map(|c| c * paba))) - r * baba;
        let y = (paba - baba * 0.5).abs() - baba * 0.5;
        let (x2, y2) = (x * x, y * y * baba);
        let d = if x.max(y) < 0.0 {
            -x2.min(y2)
        } else {
            (if x > 0.0 { x2 } else { 0.0 }) + (if y > 0.0 { y2 } else { 0.0 })
        };
        sign(d) * d.abs().sqrt() / baba
    })
}

/// pyramid3D: a square pyramid of height h on the unit square (JWildfire's symmetry step
/// sets both x and z to z when z > x, as kept here).
fn pyramid3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [h] = v.params();
    fill_solid(v, acc, rng, |p| {
        let m2 = h * h + 0.25;
        let (mut px, py, mut pz) = (p[0].abs(), p[1], p[2].abs());
        if pz > px {
            px = pz;
        }
        px -= 0.5;
        pz -= 0.5;
        let (qx, qy, qz) = (pz, h * py - 0.5 * px, h * px + 0.5 * py);
        let s = (-qx).max(0.0);
        let tt = ((qy - 0.5 * pz) / (m2 + 0.25)).clamp(0.0, 1.0);
        let a = m2 * (qx + s) * (qx + s) + qy * qy;
        let b = m2 * (qx + 0.5 * tt) * (qx + 0.5 * tt) + (qy - m2 * tt) * (qy - m2 * tt);
        let d2 = if qy.min(-qx * m2 - qy * 0.5) > 0.0 {
            0.0
        } else {
            a.min(b)
        };
        ((d2 + qz * qz) / m2).sqrt() * sign(qz.max(-py))
    })
}

/// solidangle3D: a spherical sector of radius p3 whose cone has sine and cosine (p1, p2).
fn solidangle3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [cx, cy, ra] = v.params();
    fill_solid(v, acc, rng, |p| {
        let (qx, qy) = ((p[0] * p[0] + p[2] * p[2]).sqrt(), p[1]);
        let l = (qx * qx + qy * qy).sqrt() - ra;
        let k = (qx * cx + qy * cy).clamp(0.0, ra);
        let m = ((qx - cx * k).powi(2) + (qy - cy * k).powi(2)).sqrt();
        l.max(m * sign(cy * qx - cx * qy))
    })
}

/// cappedtorus3D: a torus (radii R1, R2) cut to the arc given by the sine/cosine (dx, dy).
fn cappedtorus3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scx, scy, ra, rb] = v.params();
    fill_solid(v, acc, rng, |p| {
        let px = p[0].abs();
        let k = if scy * px > scx * p[1] {
            px * scx + p[1] * scy
        } else {
            (px * px + p[1] * p[1]).sqrt()
        };
        (px * px + p[1] * p[1] + p[2] * p[2] + ra * ra - 2.0 * ra * k).sqrt() - rb
    })
}

/// ocappedcone3D: a cone cut at both ends, radius r1 at (dx, dy, dz) and r2 at (tx, ty, tz).
fn ocappedcone3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ax, ay, az, bx, by, bz, ra, rb] = v.params();
    let (a, b) = ([ax, ay, az], [bx, by, bz]);
    fill_solid(v, acc, rng, |p| {
        let rba = rb - ra;
        let ba = sub3(b, a);
        let pa = sub3(p, a);
        let baba = dot3(ba, ba);
        let papa = dot3(pa, pa);
        let paba = dot3(pa, ba) / baba;
        let x = (papa - paba * paba * baba).sqrt();
        let cax = 0.0_f64.max(x - if paba < 0.5 { ra } else { rb });
        let cay = (paba - 0.5).abs() - 0.5;
        let k = rba * rba + baba;
        let f = ((rba * (x - ra) + paba * baba) / k).clamp(0.0, 1.0);
        let cbx = x - ra - f * rba;
        let cby = paba - f;
        let s = if cbx < 0.0 && cay < 0.0 { -1.0 } else { 1.0 };
        s * (cax * cax + cay * cay * baba)
            .min(cbx * cbx + cby * cby * baba)
            .sqrt()
    })
}

/// oroundcone3D: a cone with rounded ends, radius r1 at (dx, dy, dz) and r2 at (tx, ty, tz).
fn oroundcone3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ax, ay, az, bx, by, bz, r1, r2] = v.params();
    let (a, b) = ([ax, ay, az], [bx, by, bz]);
    fill_solid(v, acc, rng, |p| {
        let ba = sub3(b, a);
        let l2 = dot3(ba, ba);
        let rr = r1 - r2;
        let a2 = l2 - rr * rr;
        let il2 = 1.0 / l2;
        let pa = sub3(p, a);
        let y = dot3(pa, ba);
        let z = y - l2;
        let w = sub3(pa.map(|c| c * l2), ba.map(|c| c * y));
        let x2 = dot3(w, w);
        let y2 = y * y * l2;
        let z2 = z * z * l2;
        let k = sign(rr) * rr * rr * x2;
        if sign(z) * a2 * z2 > k {
            return (x2 + z2).sqrt() * il2 - r2;
        }
        if sign(y) * a2 * y2 < k {
            return (x2 + y2).sqrt() * il2 - r1;
        }
        ((x2 * a2 * il2).sqrt() + y * rr) * il2 - r1
    })
}
