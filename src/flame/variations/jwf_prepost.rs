//! JWildfire's `pre_`, `post_` and prepost variations that are classes of their own (not the
//! `pre_`/`post_` form of a variation ugnis knows): 3-D affine maps, spins, z moves by colour,
//! waves, symmetries of the complex plane, crops of the summed point, and the prepost maps
//! (`prepost_mobius`, `prepost_affine`, `prepost_circlize`, `prepost_blob`, `ringtile`), which
//! JWildfire calls twice per iteration: once before the regular variations, once after them.
//!
//! A `pre_` variation replaces the affine point, a `post_` one the xform's summed point, as
//! JWildfire's do. The formulas follow JWildfire's (Andreas Maschke and contributors,
//! LGPL-2.1) mathematics, written anew.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::*;

/// The 15 parameters of JWildfire's 3-D affine map, named for variation `$n`.
macro_rules! affine3d_params {
    ($n:literal) => {
        &[
            p(concat!($n, "_translateX"), 0.0),
            p(concat!($n, "_translateY"), 0.0),
            p(concat!($n, "_translateZ"), 0.0),
            p(concat!($n, "_scaleX"), 1.0),
            p(concat!($n, "_scaleY"), 1.0),
            p(concat!($n, "_scaleZ"), 1.0),
            p(concat!($n, "_rotateX"), 0.0),
            p(concat!($n, "_rotateY"), 0.0),
            p(concat!($n, "_rotateZ"), 0.0),
            p(concat!($n, "_shearXY"), 0.0),
            p(concat!($n, "_shearXZ"), 0.0),
            p(concat!($n, "_shearYX"), 0.0),
            p(concat!($n, "_shearYZ"), 0.0),
            p(concat!($n, "_shearZX"), 0.0),
            p(concat!($n, "_shearZY"), 0.0),
        ]
    };
}

/// The parameters of the z moves by colour, named for variation `$n`.
macro_rules! dcztransl_params {
    ($n:literal) => {
        &[
            p_range(concat!($n, "_x0"), 0.0, 0.0, 1.0),
            p_range(concat!($n, "_x1"), 1.0, 0.0, 1.0),
            p(concat!($n, "_factor"), 1.0),
            p_int(concat!($n, "_overwrite"), 1.0, 0.0, 1.0),
            p_int(concat!($n, "_clamp"), 0.0, 0.0, 1.0),
        ]
    };
}

const PRE: u32 = flag::JWILDFIRE | flag::PRE_ONLY;
const POST: u32 = flag::JWILDFIRE | flag::POST_ONLY;
const PREPOST: u32 = flag::JWILDFIRE | flag::PREPOST;
const Z3: u32 = flag::USES_Z | flag::WRITES_Z;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("pre_affine3D", affine3d)
        .params(affine3d_params!("pre_affine3D"))
        .flags(PRE | Z3)
        .prepare(prep_affine3d),
    VarDef::new("post_affine3D", affine3d)
        .params(affine3d_params!("post_affine3D"))
        .flags(POST | Z3)
        .prepare(prep_affine3d),
    VarDef::new("pre_spin_z", spin_z)
        .flags(PRE)
        .prepare(prep_spin_z),
    VarDef::new("post_spin_z", spin_z)
        .flags(POST)
        .prepare(prep_spin_z),
    VarDef::new("post_ztranslate_wf", ztranslate).flags(POST | Z3),
    VarDef::new("pre_dcztransl", dcztransl)
        .params(dcztransl_params!("pre_dcztransl"))
        .flags(PRE | Z3 | flag::USES_COLOR)
        .prepare(prep_dcztransl),
    VarDef::new("post_dcztransl", dcztransl)
        .params(dcztransl_params!("post_dcztransl"))
        .flags(POST | Z3 | flag::USES_COLOR)
        .prepare(prep_dcztransl),
    VarDef::new("pre_wave3D_wf", wave3d)
        .params(&[
            p_int("pre_wave3D_wf_axis", 2.0, 0.0, 3.0),
            p("pre_wave3D_wf_wavelen", 0.5),
            p("pre_wave3D_wf_phase", 0.0),
            p("pre_wave3D_wf_damping", 0.01),
            p("pre_wave3D_wf_centre_x", 0.0),
            p("pre_wave3D_wf_centre_y", 0.0),
            p("pre_wave3D_wf_centre_z", 0.0),
        ])
        .flags(PRE | Z3),
    VarDef::new("post_log_tile2", log_tile2)
        .params(&[
            p("post_log_tile2_spreadx", 2.0),
            p("post_log_tile2_spready", 2.0),
            p("post_log_tile2_spreadz", 0.0),
        ])
        .flags(POST | Z3 | flag::RANDOM),
    VarDef::new("pre_c_symmetry", c_symmetry)
        .params(&[p("pre_c_symmetry_p1", 3.0), p("pre_c_symmetry_p2", 3.0)])
        .flags(PRE),
    VarDef::new("post_c_symmetry", c_symmetry)
        .params(&[p("post_c_symmetry_p1", 3.0), p("post_c_symmetry_p2", 3.0)])
        .flags(POST),
    VarDef::new("pre_rect_wf", rect_wf)
        .params(&[
            p("pre_rect_wf_x0", -0.5),
            p("pre_rect_wf_x1", 0.5),
            p("pre_rect_wf_y0", -0.5),
            p("pre_rect_wf_y1", 0.5),
        ])
        .flags(PRE | flag::RANDOM),
    VarDef::new("post_crosscrop", crosscrop)
        .params(&[
            p("post_crosscrop_x", 1.0),
            p("post_crosscrop_y", 1.0),
            p("post_crosscrop_z", 1.0),
            p("post_crosscrop_rotation", 0.0),
            p_int("post_crosscrop_reverse", 0.0, 0.0, 1.0),
        ])
        .flags(POST | Z3 | flag::HIDES),
    VarDef::new("prepost_mobius", prepost_mobius)
        .params(&[
            p("prepost_mobius_re_a", 1.0),
            p("prepost_mobius_re_b", 0.0),
            p("prepost_mobius_re_c", 0.0),
            p("prepost_mobius_re_d", 1.0),
            p("prepost_mobius_im_a", 0.0),
            p("prepost_mobius_im_b", 0.0),
            p("prepost_mobius_im_c", 0.0),
            p("prepost_mobius_im_d", 0.0),
        ])
        .flags(PREPOST),
    VarDef::new("prepost_affine", prepost_affine)
        .params(&[
            p("prepost_affine_scale_x", 1.0),
            p("prepost_affine_scale_y", 1.0),
            p("prepost_affine_scale_z", 1.0),
            p("prepost_affine_yaw", 0.0),
            p("prepost_affine_pitch", 0.0),
            p("prepost_affine_roll", 0.0),
            p("prepost_affine_move_x", 0.0),
            p("prepost_affine_move_y", 0.0),
            p("prepost_affine_move_z", 0.0),
        ])
        .flags(PREPOST | Z3)
        .prepare(prep_prepost_affine),
    VarDef::new("prepost_circlize", prepost_circlize)
        .params(&[
            p_int("prepost_circlize_n", 4.0, 3.0, INF),
            p("prepost_circlize_rotation", 45.0),
            p_int("prepost_circlize_reverse", 0.0, 0.0, 1.0),
        ])
        .flags(PREPOST),
    VarDef::new("prepost_blob", prepost_blob)
        .params(&[
            p("prepost_blob_low", 0.8),
            p("prepost_blob_high", 1.2),
            p("prepost_blob_waves", 6.0),
        ])
        .flags(PREPOST),
    VarDef::new("ringtile", ringtile)
        .params(&[
            p("ringtile_power", 5.0),
            p("ringtile_tilesize", 0.5),
            p("ringtile_width1", 0.5),
            p("ringtile_width2", 0.3),
            p("ringtile_outline", 1e-6),
        ])
        .flags(PREPOST),
];

/// sin and cos of the rotations (degrees) about x, y and z, and whether there is a shear.
fn prep_affine3d(v: &mut Prepared) {
    let [_, _, _, _, _, _, rx, ry, rz, s1, s2, s3, s4, s5, s6] = v.params();
    let (sx, cx) = (rx * PI / 180.0).sin_cos();
    let (sy, cy) = (ry * PI / 180.0).sin_cos();
    let (sz, cz) = (rz * PI / 180.0).sin_cos();
    let shear = [s1, s2, s3, s4, s5, s6].iter().any(|s| s.abs() > 1e-8);
    v.p.extend_from_slice(&[sx, cx, sy, cy, sz, cz, f64::from(u8::from(shear))]);
}

/// Flamelet's 3-D affine map: scale and shear, then rotations about x, y and z, then the
/// translation; weighted; replaces the point.
fn affine3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [tx, ty, tz, kx, ky, kz, _, _, _, xy, xz, yx, yz, zx, zy] = v.params();
    let [sx, cx, sy, cy, sz, cz, shear] = v.derived();
    let (x, y, z) = (t.x, t.y, t.z);
    let w = v.w;
    if shear != 0.0 {
        let a = xy * ky * y + xz * kz * z + kx * x;
        let b = yx * kx * x + yz * kz * z + ky * y;
        let c = zx * kx * x + zy * ky * y + kz * z;
        [
            w * (cz * (cy * a + sy * (sx * b + cx * c)) - sz * (cx * b - sx * c) + tx),
            w * (sz * (cy * a + sy * (sx * b + cx * c)) + cz * (cx * b - sx * c) + ty),
            w * (-sy * a + cy * (sx * b + cx * c) + tz),
        ]
    } else {
        [
            w * (cz * (cy * kx * x + sy * (cx * kz * z + sx * ky * y))
                - sz * (cx * ky * y - sx * kz * z)
                + tx),
            w * (sz * (cy * kx * x + sy * (cx * kz * z + sx * ky * y))
                + cz * (cx * ky * y - sx * kz * z)
                + ty),
            w * (-sy * kx * x + cy * (cx * kz * z + sx * ky * y) + tz),
        ]
    }
}

/// sin and cos of weight·π/2.
fn prep_spin_z(v: &mut Prepared) {
    let (s, c) = (v.w * FRAC_PI_2).sin_cos();
    v.p.extend_from_slice(&[s, c]);
}

/// Larry Berlin's spin about z by weight·90°.
fn spin_z(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [s, c] = v.derived();
    [s * t.y + c * t.x, c * t.y - s * t.x, t.z]
}

/// z moved by the weight.
fn ztranslate(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [t.x, t.y, t.z + v.w]
}

/// The colour range x0..x1 in order, and its width (1e-300 for none).
fn prep_dcztransl(v: &mut Prepared) {
    let [x0, x1] = v.params();
    let (lo, hi) = (x0.min(x1), x0.max(x1));
    let width = if hi - lo == 0.0 { 1e-300 } else { hi - lo };
    v.p.extend_from_slice(&[lo, width]);
}

/// Xyrus02's z by colour: x and y weighted, z the colour's place in the range (times z
/// unless `overwrite`).
fn dcztransl(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    super::fr_direct_colour::ztransl_by(v, t, t.color)
}

/// A damped sine wave along the distance from the centre in a plane (axis 0: xy, moving z;
/// 1: yz, moving x; 2: zx, moving y) or in space (3: along the radius).
fn wave3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [axis, wavelen, phase, damping, cx, cy, cz] = v.params();
    let (dx, dy, dz) = (t.x - cx, t.y - cy, t.z - cz);
    let r = match axis as i32 {
        3 => (dx * dx + dy * dy + dz * dz).sqrt(),
        1 => (dy * dy + dz * dz).sqrt(),
        2 => (dz * dz + dx * dx).sqrt(),
        _ => (dx * dx + dy * dy).sqrt(),
    };
    let dl = r / wavelen;
    let mut amplitude = v.w;
    if damping.abs() > 1e-300 {
        amplitude *= (-dl * damping).exp();
    }
    let amp = amplitude * (TAU * dl + phase).sin();
    let [mut x, mut y, mut z] = [t.x, t.y, t.z];
    match axis as i32 {
        3 => {
            let len = (dx * dx + dy * dy + dz * dz).sqrt();
            if len != 0.0 {
                x += dx / len * amp;
                y += dy / len * amp;
                z += dz / len * amp;
            }
        }
        1 => x += amp,
        2 => y += amp,
        _ => z += amp,
    }
    [x, y, z]
}

/// Tiles at random: each coordinate moves by its spread times a rounded logarithm of a
/// random number, in a random direction; the point is then weighted.
fn log_tile2(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sx, sy, sz] = v.params();
    let mut spread = |s: f64| if rng.f01() < 0.5 { s } else { -s };
    let (sx, sy, sz) = (spread(sx), spread(sy), spread(sz));
    // Java's Math.round: ⌊x + ½⌋.
    let mut step = |s: f64| s * (rng.f01().ln() + 0.5).floor();
    let x = v.w * (t.x + step(sx));
    let y = v.w * (t.y + step(sy));
    let z = v.w * (t.z + step(sz));
    [x, y, z]
}

/// Jesus Sosa's complex symmetry: angle times p1, radius to the power p2.
fn c_symmetry(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [p1, p2] = v.params();
    let a = p1 * t.y.atan2(t.x);
    let r = (t.x * t.x + t.y * t.y).sqrt().powf(p2);
    let (s, c) = a.sin_cos();
    [v.w * c * r, v.w * s * r, t.z]
}

/// pre_rect_wf: a uniform point of the rectangle [x0, x1] × [y0, y1] (times the weight) in
/// place of the affine point; z is kept.
fn rect_wf(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [x0, x1, y0, y1] = v.params();
    let x = v.w * (x0 + (x1 - x0) * rng.f01());
    let y = v.w * (y0 + (y1 - y0) * rng.f01());
    [x, y, t.z]
}

/// Whittaker Courtney's cross: keeps (weighted) the points within the cross of half-widths x
/// and y (turned by `rotation` degrees) and the slab |z| ≤ z, hides the others (the other way
/// round with `reverse`).
fn crosscrop(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [x, y, z, rotation, reverse] = v.params();
    let (s, c) = (rotation * PI / 180.0).sin_cos();
    let rx = t.x * c - t.y * s;
    let ry = t.y * c + t.x * s;
    let inside = (rx <= x && rx >= -x || ry <= y && ry >= -y) && t.z <= z && t.z >= -z;
    if inside == (reverse != 0.0) {
        acc.hide = true;
        return [0.0; 3];
    }
    acc.hide = false;
    [v.w * t.x, v.w * t.y, v.w * t.z]
}

/// A Möbius map: before the regular variations its inverse (divided by the weight), after
/// them the map itself (times the weight). Nothing for weight 0 or a pole.
fn prepost_mobius(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [re_a, re_b, re_c, re_d, im_a, im_b, im_c, im_d] = v.params();
    let (x, y) = (t.x, t.y);
    let w = v.w;
    if w == 0.0 {
        return [x, y, t.z];
    }
    let (re_u, im_u, re_v, im_v, k) = if v.form == Form::Pre {
        (
            re_d * x - im_d * y - re_b,
            re_d * y + im_d * x - im_b,
            -re_c * x + im_c * y + re_a,
            -re_c * y - im_c * x + im_a,
            0.0,
        )
    } else {
        (
            re_a * x - im_a * y + re_b,
            re_a * y + im_a * x + im_b,
            re_c * x - im_c * y + re_d,
            re_c * y + im_c * x + im_d,
            1.0,
        )
    };
    let d = re_v * re_v + im_v * im_v;
    if d == 0.0 {
        return [x, y, t.z];
    }
    let rad = if k == 1.0 { w / d } else { 1.0 / (w * d) };
    [
        rad * (re_u * re_v + im_u * im_v),
        rad * (im_u * re_v - re_u * im_v),
        t.z,
    ]
}

/// The rotation matrix (yaw, pitch, roll in degrees) and its transpose.
fn prep_prepost_affine(v: &mut Prepared) {
    let [_, _, _, yaw, pitch, roll] = v.params();
    let d2r = PI / 180.0;
    let (sy, cy) = (yaw * d2r).sin_cos();
    let (sp, cp) = (pitch * d2r).sin_cos();
    let (sr, cr) = (roll * d2r).sin_cos();
    let m = [
        cy * cr - sy * sp * sr,
        -sy * cr - cy * sp * sr,
        -cp * sr,
        sy * cp,
        cy * cp,
        -sp,
        cy * sr + sy * sp * cr,
        cy * sp * cr - sy * sr,
        cp * cr,
    ];
    v.p.extend_from_slice(&m);
}

/// A scaled, rotated and moved 3-D map: before the regular variations its inverse, after them
/// the map. Nothing for weight 0.
fn prepost_affine(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [kx, ky, kz, _, _, _, mx, my, mz] = v.params();
    let m: [f64; 9] = v.derived();
    let w = v.w;
    if w == 0.0 {
        return [t.x, t.y, t.z];
    }
    if v.form == Form::Pre {
        let (x, y, z) = (t.x - mx, t.y - my, t.z - mz);
        [
            (m[0] * x + m[3] * y + m[6] * z) / (w * kx),
            (m[1] * x + m[4] * y + m[7] * z) / (w * ky),
            (m[2] * x + m[5] * y + m[8] * z) / (w * kz),
        ]
    } else {
        let (x, y, z) = (w * kx * t.x, w * ky * t.y, w * kz * t.z);
        [
            m[0] * x + m[1] * y + m[2] * z + mx,
            m[3] * x + m[4] * y + m[5] * z + my,
            m[6] * x + m[7] * y + m[8] * z + mz,
        ]
    }
}

/// Regular n-gons to circles and back: before the regular variations towards circles, after
/// them back to n-gons (the other way round with `reverse`); the weight blends.
fn prepost_circlize(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [n, rotation, reverse] = v.params();
    let rot = rotation * PI / 180.0;
    let pi_n = PI / n;
    let theta = t.y.atan2(t.x);
    let r = (t.x * t.x + t.y * t.y).sqrt() + 1e-300;
    let factor =
        pi_n.cos() / ((theta - rot) - pi_n * (2.0 * (n * (theta - rot) / TAU).floor() + 1.0)).cos();
    let to_circle = (v.form == Form::Pre) == (reverse == 0.0);
    let target = if to_circle { r / factor } else { r * factor };
    let rr = r + (target - r) * v.w;
    [rr * theta.cos(), rr * theta.sin(), t.z]
}

/// A wavy blob: before the regular variations the radius divided by the wave, after them
/// multiplied.
fn prepost_blob(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [low, high, waves] = v.params();
    let alow = 1.0 - v.w * (1.0 - low);
    let ahigh = 1.0 - v.w * (1.0 - high);
    let a = t.x.atan2(t.y);
    let r = (t.x * t.x + t.y * t.y).sqrt();
    let k = alow + (ahigh - alow) * (0.5 + 0.5 * (waves * a).sin());
    let r = if v.form == Form::Pre { r / k } else { r * k };
    [a.sin() * r, a.cos() * r, t.z]
}

/// Brad Stefanov's and Whittaker Courtney's ring tiles: after the regular variations the
/// complex exponential of the point. (Before them JWildfire adds the tiles to the running sum,
/// leaving the affine point as it is.)
fn ringtile(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    if v.form == Form::Pre {
        return [t.x, t.y, t.z];
    }
    let e = t.x.exp();
    let (s, c) = t.y.sin_cos();
    [v.w * e * c, v.w * e * s, t.z]
}
