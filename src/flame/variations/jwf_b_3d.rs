//! JWildfire's 3-D maps of a point: Flamelet's `affine3D`, `tangent3D`, `cylinder_apo`,
//! Larry Berlin's z-lifts `inflateZ_1`/`_3`/`_5`, `onion`, `sphere_nja`, `ztwister`,
//! `post_zscale_wf`, `swirl3D_wf`, `pdj3D`, `log_tile2`, Dini's surface `dinis_surface_wf`, and
//! one step of the Lorenz system (`lorenz_js`) or the gingerbread-man map (`gingerbread_man`),
//! the ball crop `spherecrop` and the shell `seashell3D`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: weights multiply the output linearly,
//! integer parameters are rounded, and random numbers are drawn in the order JWildfire draws
//! them.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("affine3D", affine3d)
        .params(&[
            p("affine3D_translateX", 0.0),
            p("affine3D_translateY", 0.0),
            p("affine3D_translateZ", 0.0),
            p("affine3D_scaleX", 1.0),
            p("affine3D_scaleY", 1.0),
            p("affine3D_scaleZ", 1.0),
            p("affine3D_rotateX", 0.0),
            p("affine3D_rotateY", 0.0),
            p("affine3D_rotateZ", 0.0),
            p("affine3D_shearXY", 0.0),
            p("affine3D_shearXZ", 0.0),
            p("affine3D_shearYX", 0.0),
            p("affine3D_shearYZ", 0.0),
            p("affine3D_shearZX", 0.0),
            p("affine3D_shearZY", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z)
        .prepare(affine3d_prepare),
    VarDef::new("tangent3D", tangent3d).flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("inflateZ_1", inflate_z1).flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("inflateZ_3", inflate_z3).flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("inflateZ_5", inflate_z5).flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("cylinder_apo", cylinder_apo).flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("onion", onion)
        .params(&[p("onion_centre_x", 0.0), p("onion_centre_y", 0.0)])
        .flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("sphere_nja", sphere_nja)
        .params(&[
            p("sphere_nja_circle_a", 1.0),
            p("sphere_nja_circle_b", 1.0),
            p("sphere_nja_shift_x", 0.0),
            p("sphere_nja_shift_y", 0.0),
            p("sphere_nja_shift_z", 0.0),
            p("sphere_nja_stretch", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("ztwister", ztwister)
        .params(&[
            p("ztwister_twist", 4.2),
            p("ztwister_base", std::f64::consts::E),
        ])
        .flags(flag::JWILDFIRE | flag::READS_ACC),
    VarDef::new("post_zscale_wf", post_zscale_wf)
        .params(&[p("post_zscale_wf_ztranslate", 0.0)])
        .flags(flag::JWILDFIRE | flag::READS_ACC | flag::WRITES_ACC | flag::WRITES_Z),
    VarDef::new("swirl3D_wf", swirl3d_wf)
        .params(&[p("swirl3D_wf_n", 0.0)])
        .needs(need::SQRT | need::ATAN_YX)
        .flags(flag::JWILDFIRE | flag::WRITES_Z | flag::SETS_COLOR),
    VarDef::new("pdj3D", pdj3d)
        .params(&[
            p("pdj3D_a", 1.0),
            p("pdj3D_b", 2.0),
            p("pdj3D_c", 3.0),
            p("pdj3D_d", 4.0),
            p("pdj3D_e", 2.0),
            p("pdj3D_f", 0.0),
            p("pdj3D_g", 2.0),
            p("pdj3D_h", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("log_tile2", log_tile2)
        .params(&[
            p("log_tile2_spreadx", 2.0),
            p("log_tile2_spready", 2.0),
            p("log_tile2_spreadz", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("dinis_surface_wf", dinis_surface_wf)
        .params(&[p("dinis_surface_wf_a", 0.8), p("dinis_surface_wf_b", 0.2)])
        .flags(flag::JWILDFIRE | flag::WRITES_Z | flag::HIDES),
    VarDef::new("lorenz_js", lorenz_js)
        .params(&[
            p("lorenz_js_a", 10.0),
            p("lorenz_js_b", 28.0),
            p("lorenz_js_c", 1.66),
            p("lorenz_js_h", 0.00001),
            p("lorenz_js_centerx", 0.0),
            p("lorenz_js_centery", 0.0),
            p("lorenz_js_scale", 1000.0),
        ])
        .flags(
            flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC,
        ),
    VarDef::new("gingerbread_man", gingerbread_man)
        .flags(flag::JWILDFIRE | flag::STATEFUL | flag::OWN_ORBIT | flag::WRITES_ACC)
        .prepare(gingerbread_prepare),
    VarDef::new("spherecrop", spherecrop)
        .params(&[
            p("spherecrop_radius", 1.0),
            p("spherecrop_x", 0.0),
            p("spherecrop_y", 0.0),
            p("spherecrop_z", 0.0),
            p_range("spherecrop_scatter_area", 0.0, -1.0, 1.0),
            p_int("spherecrop_zero", 1.0, NEG_INF, INF),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::HIDES
                | flag::WRITES_ACC,
        ),
    VarDef::new("seashell3D", seashell3d)
        .params(&[
            p("seashell3D_final_radius", 0.25),
            p("seashell3D_height", 3.5),
            p("seashell3D_inner_radius", 0.4),
            p_int("seashell3D_nSpirals", 3.0, NEG_INF, INF),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z),
];

/// The sines and cosines of the three rotation angles (degrees).
fn affine3d_prepare(v: &mut Prepared) {
    let [_, _, _, _, _, _, rx, ry, rz] = v.params();
    for a in [rx, ry, rz] {
        let (s, c) = (a * PI / 180.0).sin_cos();
        v.p.push(s);
        v.p.push(c);
    }
}

/// affine3D: scale, shear, then rotate about x, y and z (in that order), then translate.
fn affine3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        tx,
        ty,
        tz,
        sx,
        sy,
        sz,
        _,
        _,
        _,
        sh_xy,
        sh_xz,
        sh_yx,
        sh_yz,
        sh_zx,
        sh_zy,
    ] = v.params();
    let [sin_x, cos_x, sin_y, cos_y, sin_z, cos_z] = v.derived();
    let (x, y, z) = (t.x, t.y, t.z);
    let px = sh_xy * sy * y + sh_xz * sz * z + sx * x;
    let py = sh_yx * sx * x + sh_yz * sz * z + sy * y;
    let pz = sh_zx * sx * x + sh_zy * sy * y + sz * z;
    let ox = cos_z * (cos_y * px + sin_y * (sin_x * py + cos_x * pz))
        - sin_z * (cos_x * py - sin_x * pz)
        + tx;
    let oy = sin_z * (cos_y * px + sin_y * (sin_x * py + cos_x * pz))
        + cos_z * (cos_x * py - sin_x * pz)
        + ty;
    let oz = -sin_y * px + cos_y * (sin_x * py + cos_x * pz) + tz;
    [v.w * ox, v.w * oy, v.w * oz]
}

/// tangent3D (Z+): sin x / cos y, tan y, and tan x as z.
fn tangent3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [
        v.w * t.x.sin() / t.y.cos(),
        v.w * t.y.tan(),
        v.w * t.x.tan(),
    ]
}

/// inflateZ_1: z = sin(angle) − 2y.
fn inflate_z1(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let ang = t.y.atan2(t.x);
    [0.0, 0.0, v.w * (ang.sin() - t.y * 2.0)]
}

/// inflateZ_3: z = (π − angle)/5 · cos(3·angle + y − x).
fn inflate_z3(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let ang = t.y.atan2(t.x);
    [
        0.0,
        0.0,
        v.w * 0.2 * (PI - ang) * (3.0 * ang + (t.y - t.x)).cos(),
    ]
}

/// inflateZ_5: z = cos(π/2 − angle)/2.
fn inflate_z5(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let ang = t.y.atan2(t.x);
    [0.0, 0.0, v.w * (FRAC_PI_2 - ang).cos() / 2.0]
}

/// cylinder_apo: (sin x, y, cos x), the plane rolled onto a cylinder.
fn cylinder_apo(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w * t.x.sin(), v.w * t.y, v.w * t.x.cos()]
}

/// JWildfire's rounded √2 in onion (two different roundings, kept).
#[allow(clippy::approx_constant)]
const ONION_SQRT2: [f64; 2] = [1.41421356, 1.414213569];

/// onion: a sphere of radius |weight| about a centre: points inside drop to its lower half,
/// points outside are folded back towards the centre and lifted; the weight is the radius,
/// not a factor, and z adds the input z.
fn onion(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cx, cy] = v.params();
    let r0 = if v.w == 0.0 { 1.0 } else { v.w };
    let (x0, y0) = (t.x - cx, t.y - cy);
    let d0 = x0 * x0 + y0 * y0;
    let dr = d0.sqrt();
    let (x1, y1, z1) = if d0 <= r0 * r0 {
        (x0, y0, -(r0 * r0 - d0).sqrt())
    } else {
        let x1 = (2.0 * r0 - dr) * x0 / dr;
        let y1 = (2.0 * r0 - dr) * y0 / dr;
        if 2.0 * r0 - dr > r0 / ONION_SQRT2[0] {
            (x1, y1, (r0 * r0 - (x1 * x1 + y1 * y1)).sqrt())
        } else {
            let z = (dr - r0 - (r0 - r0 / ONION_SQRT2[1])).exp() - 1.0 + r0 / ONION_SQRT2[1];
            (x1, y1, z)
        }
    };
    [x1 + cx, y1 + cy, z1 + t.z]
}

/// sphere_nja: the distance from a centre taken as the parameter of a half circle: the point
/// lands on a sphere (radius |weight|), its z spreading it across the surface.
fn sphere_nja(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [_, _, sx, sy, sz, stretch] = v.params();
    let (x, y, z) = (t.x - sx, t.y - sy, t.z - sz);
    let rr = (x * x + y * y).sqrt() + 1e-300;
    let tt = rr / stretch - FRAC_PI_2;
    let r = tt.cos() * v.w;
    let zz = tt.sin() * v.w;
    let (ux, uy) = (x / rr, y / rr);
    [
        r * ux + r * z * ux + sx,
        r * uy + r * z * uy + sy,
        zz + z * zz / (r * r + zz * zz) + sz,
    ]
}

/// ztwister: the point turned by an angle growing (exponentially, in `base`) with the z the
/// xform's earlier variations produced.
fn ztwister(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [twist, base] = v.params();
    let mut ez = twist * acc.z;
    if base != 1.0 {
        ez = base.powf(ez) - 1.0;
    }
    let (s, c) = ez.sin_cos();
    [v.w * (t.x * c - t.y * s), v.w * (t.x * s + t.y * c), 0.0]
}

/// post_zscale_wf: the z summed so far, scaled by the weight and shifted.
fn post_zscale_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [ztranslate] = v.params();
    acc.z = v.w * acc.z + ztranslate;
    [0.0; 3]
}

/// swirl3D_wf: the point kept, lifted by sin(6·cos r − n·angle), which (absolute) also sets
/// the colour.
fn swirl3d_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [n] = v.params();
    let n = n.trunc();
    let rad = t.sqrt + 1e-300;
    let ang = t.atan_yx;
    let s = (6.0 * rad.cos() - n * ang).sin();
    acc.color = s.abs();
    [v.w * rad * ang.cos(), v.w * rad * ang.sin(), v.w * s]
}

/// pdj3D: Peter de Jong's map with a third coordinate.
fn pdj3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c, d, e, f, g, h] = v.params();
    [
        v.w * ((a * t.y).sin() - (b * t.x).cos()),
        v.w * ((c * t.x).sin() - (d * t.y).cos()),
        v.w * ((e * t.y).sin() - (f * t.z).cos()) * (g * t.x).cos() + (h * t.z).sin(),
    ]
}

/// log_tile2: the point shifted by a whole multiple (rounded log of a uniform draw, so mostly
/// small) of ±spread on each axis.
fn log_tile2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sx, sy, sz] = v.params();
    let mut spread = |s: f64| if rng.f01() < 0.5 { s } else { -s };
    let (sx, sy, sz) = (spread(sx), spread(sy), spread(sz));
    // Java's Math.round: ⌊x + ½⌋.
    let mut jump = || (rng.f01().ln() + 0.5).floor();
    let (jx, jy, jz) = (jump(), jump(), jump());
    [
        v.w * (t.x + sx * jx),
        v.w * (t.y + sy * jy),
        v.w * (t.z + sz * jz),
    ]
}

/// dinis_surface_wf: Dini's surface (a twisted pseudosphere) with (x, y) as its parameters;
/// hidden where |y| ≤ 1e-8 (the surface's pole), where z gets nothing.
fn dinis_surface_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b] = v.params();
    let (u, w) = (t.x, t.y);
    let sinv = w.sin();
    let x = v.w * a * u.cos() * sinv;
    let y = v.w * a * u.sin() * sinv;
    if w.abs() > 1e-8 {
        acc.hide = false;
        let z = -v.w * (a * (w.cos() + (w.abs() / 2.0).tan().ln()) + b * u);
        [x, y, z]
    } else {
        acc.hide = true;
        [x, y, 0.0]
    }
}

/// lorenz_js: one Euler step (h) of the Lorenz system from the point; the colour is the
/// scaled squared distance of the summed point from a centre, modulo 1.
fn lorenz_js(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c, h, cx, cy, scale] = v.params();
    let bdcs = 1.0 / if scale == 0.0 { 10e-6 } else { scale };
    let x = t.x + h * a * (t.y - t.x);
    let y = t.y + h * (t.x * (b - t.z) - t.y);
    let z = t.z + h * (t.x * t.y - c * t.z);
    let o = [x * v.w, y * v.w, z * v.w];
    let (sx, sy) = (acc.x + o[0] + cx, acc.y + o[1] + cy);
    acc.color = (bdcs * (sx * sx + sy * sy)).abs() % 1.0;
    o
}

/// The gingerbread man's starting point (−0.1, 0).
fn gingerbread_prepare(v: &mut Prepared) {
    v.state.set(0, -0.1);
    v.state.set(1, 0.0);
}

/// gingerbread_man: one step of the gingerbread-man map (x, y) → (1 − y + |x|, x) per call,
/// from the variation's own point (the input is ignored); the point replaces the running sum.
fn gingerbread_man(v: &Prepared, _t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (x0, y0) = (v.state.get(0), v.state.get(1));
    let (xn, yn) = (1.0 - y0 + x0.abs(), x0);
    v.state.set(0, xn);
    v.state.set(1, yn);
    acc.x = 0.0;
    acc.y = 0.0;
    [xn * v.w, yn * v.w, 0.0]
}

/// spherecrop: a ball about a centre: with `zero` the points outside are hidden (and the
/// running sum cleared), else they are scattered onto a shell just outside it.
fn spherecrop(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [cr, x0, y0, z0, ca, zero] = v.params();
    let (x, y, z) = (t.x - x0, t.y - y0, t.z - z0);
    let rad = (x * x + y * y + z * z).sqrt();
    let ang = y.atan2(x);
    let az = (z / rad).acos();
    let rdc = cr + rng.f01() * 0.5 * ca;
    let esc = rad > cr;
    acc.hide = false;
    if zero == 1.0 && esc {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
        acc.hide = true;
        return [0.0; 3];
    }
    if zero != 1.0 && esc {
        let (s, c) = ang.sin_cos();
        let (saz, caz) = az.sin_cos();
        return [
            v.w * rdc * c * saz + x0,
            v.w * rdc * s * saz + y0,
            v.w * rdc * caz + z0,
        ];
    }
    [v.w * x + x0, v.w * y + y0, v.w * z + z0]
}

/// seashell3D: a uniform parameter point of a conical spiral shell (nSpirals turns, a tube
/// shrinking towards the tip).
fn seashell3d(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [fr, height, inner, n] = v.params();
    let n = n.trunc();
    let tt = TAU * rng.f01();
    let s = TAU * rng.f01();
    let k = fr * (1.0 - tt / TAU);
    let x = k * (n * tt).cos() * (1.0 + s.cos()) + inner * (n * tt).cos();
    let y = k * (n * tt).sin() * (1.0 + s.cos()) + inner * (n * tt).sin();
    let z = height * tt / TAU + k * s.sin();
    [x * v.w, y * v.w, z * v.w]
}
