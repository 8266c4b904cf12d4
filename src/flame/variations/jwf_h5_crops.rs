//! JWildfire's crops and mirrors that remember points: `ringer` (Glynn's circle inversion
//! with a ring drawn inside, then a circular crop of the whole sum), `post_point_crop` (hides
//! points at a given place or within bands, putting them back at the last point it kept) and
//! `point_mirror_symmetry` (a wedge of the plane copied round by a random turn and mirror,
//! points outside the wedge replaced by a kept one).
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `RingerFunc`, `PostPointCropFunc` and
//! `PointMirrorSymmetryFunc`, written anew; random numbers are drawn in the order JWildfire
//! draws them.

use std::f64::consts::PI;

use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("ringer", ringer)
        .params(&[
            p_int("ringer_hide_inner", 0.0, 0.0, 1.0),
            p("ringer_innerradius", 0.5),
            p("ringer_outerradius", 1.0),
            p_range("ringer_thickness", 0.0, 0.0, 1.0),
            p_range("ringer_contrast", 0.0, 0.0, 1.0),
            p("ringer_pow", 1.0),
            p("ringer_scatter_area", 0.0),
            p_int("ringer_hide_outer", 1.0, 0.0, 1.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::STATEFUL
                | flag::READS_ACC
                | flag::WRITES_ACC
                | flag::HIDES,
        )
        .prepare(ringer_prepare),
    VarDef::new("post_point_crop", post_point_crop)
        .params(&[
            p("post_point_crop_x_offset", 0.0),
            p("post_point_crop_y_offset", 0.0),
            p("post_point_crop_z_offset", 0.0),
            p_int("post_point_crop_point_hide_enable", 1.0, 0.0, 1.0),
            p_int("post_point_crop_point_crop_enable", 1.0, 0.0, 1.0),
            p("post_point_crop_x_width", 0.0),
            p("post_point_crop_y_width", 0.0),
            p("post_point_crop_z_width", 0.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::POST_ONLY
                | flag::STATEFUL
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::USES_COLOR
                | flag::SETS_COLOR
                | flag::HIDES,
        ),
    VarDef::new("point_mirror_symmetry", point_mirror_symmetry)
        .params(&[
            p_int("point_mirror_symmetry_symmetry", 3.0, 1.0, 99.0),
            p_int("point_mirror_symmetry_side crop enable", 1.0, 0.0, 1.0),
            p_int("point_mirror_symmetry_crop end enable", 1.0, 0.0, 1.0),
            p("point_mirror_symmetry_crop end distance", 1.0),
            p("point_mirror_symmetry_zx Multiply", 1.0),
            p("point_mirror_symmetry_zy Multiply", 0.0),
            p_int("point_mirror_symmetry_collidoscopic", 1.0, 0.0, 1.0),
            p_int("point_mirror_symmetry_color_preserve", 0.0, 0.0, 1.0),
            p_int("point_mirror_symmetry_buffer_size", 12.0, 1.0, 1000.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::STATEFUL
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::USES_COLOR
                | flag::SETS_COLOR
                | flag::WRITES_ACC,
        ),
];

/// Derived: the ring's outer and inner radii, the chance of the outer one, |pow|, the
/// scatter clamped to ±1.
fn ringer_prepare(v: &mut Prepared) {
    let [_, radius, _, thickness, _, pow, scatter] = v.params();
    let r1 = radius + thickness;
    let r2 = radius * radius / r1;
    v.p.extend_from_slice(&[r1, r2, r1 / (r1 + r2), pow.abs(), scatter.clamp(-1.0, 1.0)]);
}

/// ringer: Glynn's inversion added to the sum (inside the ring's outer radius a random point of
/// its two circles, or with `hide_inner` the sum the last call left; outside, the input or,
/// with chance `contrast`·(radius/r)^|pow|, its inversion in the circle); then the whole sum,
/// remembered for the next call, is cropped to `outerradius`: weighted inside, hidden at the
/// origin outside (with `hide_outer`) or put on a random ring beyond the radius `scatter_area`
/// wide. Replaces the sum.
fn ringer(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [hide_inner, radius, crop_r, _, contrast, _, _, hide_outer] = v.params();
    let [r1, r2, gamma, abs_pow, scatter] = v.derived();
    let (mut sx, mut sy) = if v.form == Form::Regular {
        (acc.x, acc.y)
    } else {
        (0.0, 0.0)
    };
    let r = (t.x * t.x + t.y * t.y).sqrt();
    let alpha = radius / r;
    if r < r1 {
        if hide_inner == 0.0 {
            let phi = 2.0 * PI * rng.f01();
            let rr = if rng.f01() < gamma { r1 } else { r2 };
            sx += v.w * rr * phi.cos();
            sy += v.w * rr * phi.sin();
        } else {
            (sx, sy) = (v.state.get(0), v.state.get(1));
        }
    } else if rng.f01() > contrast * alpha.powf(abs_pow) {
        sx += v.w * t.x;
        sy += v.w * t.y;
    } else {
        sx += v.w * alpha * alpha * t.x;
        sy += v.w * alpha * alpha * t.y;
    }
    v.state.set(0, sx);
    v.state.set(1, sy);
    let rad = (sx * sx + sy * sy).sqrt();
    let ang = sy.atan2(sx);
    let rdc = crop_r + rng.f01() * 0.5 * scatter;
    let outside = rad > crop_r;
    acc.hide = false;
    let out = if hide_outer == 1.0 && outside {
        acc.hide = true;
        [0.0; 3]
    } else if outside {
        [v.w * rdc * ang.cos(), v.w * rdc * ang.sin(), 0.0]
    } else {
        [v.w * sx, v.w * sy, 0.0]
    };
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    out
}

/// post_point_crop: a point exactly at the offset (or, when a width is set, within `x_width`
/// of the offset's x, or `y_width` of its y, or `z_width` of its z with z ≠ 0) is hidden
/// (`point_hide_enable`) and replaced by the last point and colour kept
/// (`point_crop_enable`); any other point is kept (remembered, shown).
fn post_point_crop(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [xo, yo, zo, hide, crop, xw, yw, zw] = v.params();
    let (x, y, z) = (t.x, t.y, t.z);
    let hit = if xw + yw + zw != 0.0 {
        let (dx, dy, dz) = (x - xo, y - yo, z - zo);
        (-xw..=xw).contains(&dx)
            || (-yw..=yw).contains(&dy)
            || ((-zw..=zw).contains(&dz) && z != 0.0)
    } else {
        x == xo && y == yo && z == zo
    };
    if hit {
        if hide == 1.0 {
            acc.hide = true;
        }
        if crop == 1.0 {
            acc.color = v.state.get(3);
            return [v.state.get(0), v.state.get(1), v.state.get(2)];
        }
        return [x, y, z];
    }
    if hide == 1.0 {
        acc.hide = false;
    }
    if crop == 1.0 {
        v.state.set(0, x);
        v.state.set(1, y);
        v.state.set(2, z);
        v.state.set(3, acc.color);
    }
    [x, y, z]
}

/// point_mirror_symmetry: the input times the complex number (zx, zy), kept when it lies in
/// the wedge of half angle π/symmetry about the x axis (its upper half with `collidoscopic`)
/// and within `crop end distance` along both edges (with the crops enabled); a point outside
/// is replaced by the last one kept (with its colour unless `color_preserve`), or left at the
/// origin before any was kept. The point is then mirrored at random (`collidoscopic`), and
/// turned by a random multiple of 2π/symmetry, mirrored on the even ones; weighted, it
/// replaces the sum.
///
/// JWildfire keeps the last `buffer_size` points and draws one of them; ugnis keeps the last
/// one only (a variation's carried state is a few numbers).
fn point_mirror_symmetry(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        sym,
        side_crop,
        crop_end,
        end_dist,
        zx,
        zy,
        collido,
        preserve,
        buffer,
    ] = v.params();
    let k = rng.below(sym.max(1.0) as u64) as f64;
    let wedge = PI / sym;
    let turn = wedge * k * 2.0;
    let mut x = t.x * zx - t.y * zy;
    let mut y = t.x * zy + t.y * zx;
    let mut z = t.z;
    if side_crop == 1.0 {
        let r = (x * x + y * y).sqrt();
        let (sw, cw) = wedge.sin_cos();
        if collido == 1.0 && y < 0.0 {
            (x, y) = (0.0, 0.0);
        }
        if x < r * cw {
            (x, y) = (0.0, 0.0);
        }
        if crop_end == 1.0 && x * cw + y * sw > end_dist {
            (x, y) = (0.0, 0.0);
        }
        if crop_end == 1.0 && x * cw - y * sw > end_dist {
            (x, y) = (0.0, 0.0);
        }
        if x == 0.0 && y == 0.0 {
            if v.state.get(4) == 1.0 {
                // JWildfire draws which of its kept points to take.
                rng.below(buffer.max(1.0) as u64);
                (x, y, z) = (v.state.get(0), v.state.get(1), v.state.get(2));
                if preserve == 0.0 {
                    acc.color = v.state.get(3);
                }
            }
        } else {
            v.state.set(0, x);
            v.state.set(1, y);
            v.state.set(2, z);
            v.state.set(3, acc.color);
            v.state.set(4, 1.0);
        }
    }
    if collido == 1.0 && rng.f01() < 0.5 {
        y = -y;
    }
    if k % 2.0 == 0.0 {
        y = -y;
    }
    let (s, c) = turn.sin_cos();
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    [v.w * (x * c - y * s), v.w * (y * c + x * s), v.w * z]
}
