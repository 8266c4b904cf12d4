//! JWildfire's crops by shape: `crop_triangle`, `crop_rhombus`, `crop_cross`, `crop_vesica`
//! (signed-distance shapes from Inigo Quilez's catalogue) and the box crop `crop3D`. A cropped
//! point is hidden (the orbit goes on, the sample is not drawn).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. Like JWildfire, the shape crops replace the xform's sum so far and send a
//! hidden point to the origin.

use super::util::sign;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("crop_triangle", crop_triangle)
        .params(&[
            p("crop_triangle_x1", 0.0),
            p("crop_triangle_y1", 0.5),
            p("crop_triangle_x2", 0.5),
            p("crop_triangle_y2", 0.5),
            p("crop_triangle_x3", 0.0),
            p("crop_triangle_y3", -0.5),
        ])
        .flags(flag::JWILDFIRE | flag::HIDES),
    VarDef::new("crop_rhombus", crop_rhombus)
        .params(&[
            p("crop_rhombus_width", 0.5),
            p("crop_rhombus_height", 0.5),
            p_int("crop_rhombus_invert", 0.0, 0.0, 1.0),
        ])
        .flags(SHAPE_CROP),
    VarDef::new("crop_cross", crop_cross)
        .params(&[
            p("crop_cross_width", 0.5),
            p("crop_cross_Size", 0.5),
            p("crop_cross_round", 0.001),
            p_int("crop_cross_invert", 0.0, 0.0, 1.0),
        ])
        .flags(SHAPE_CROP),
    VarDef::new("crop_vesica", crop_vesica)
        .params(&[
            p("crop_vesica_width", 0.2),
            p("crop_vesica_height", 0.1),
            p_int("crop_vesica_invert", 0.0, 0.0, 1.0),
        ])
        .flags(SHAPE_CROP),
    VarDef::new("crop3D", crop3d)
        .params(&[
            p("crop3D_left", -1.0),
            p("crop3D_right", 1.0),
            p("crop3D_top", -1.0),
            p("crop3D_bottom", 1.0),
            p("crop3D_floor", -1.0),
            p("crop3D_ceiling", 1.0),
            p_range("crop3D_scatter_area", 0.0, -1.0, 1.0),
            p_int("crop3D_zero", 0.0, 0.0, 1.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::WRITES_ACC
                | flag::HIDES,
        ),
];

/// Flags of the shape crops that replace the sum so far.
const SHAPE_CROP: u32 = flag::JWILDFIRE | flag::WRITES_ACC | flag::HIDES;

/// Twice the area of a triangle, unsigned, halved as JWildfire computes it.
fn triangle_area(x1: f64, y1: f64, x2: f64, y2: f64, x3: f64, y3: f64) -> f64 {
    ((x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2)) / 2.0).abs()
}

/// crop_triangle: keeps the point where it is when it lies in the triangle (the three
/// sub-triangles' areas add up exactly to the whole, a test that floating point makes strict),
/// else hides it (still adding the point).
fn crop_triangle(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [x1, y1, x2, y2, x3, y3] = v.params();
    let (x, y) = (t.x, t.y);
    let a = triangle_area(x1, y1, x2, y2, x3, y3);
    let a1 = triangle_area(x, y, x2, y2, x3, y3);
    let a2 = triangle_area(x1, y1, x, y, x3, y3);
    let a3 = triangle_area(x1, y1, x2, y2, x, y);
    acc.hide = a != a1 + a2 + a3;
    [v.w * x, v.w * y, 0.0]
}

/// The shape crops' common end: keeps the point where the signed distance `d` says it is
/// inside (outside with `invert`), else hides it at the origin; replaces the sum so far.
fn shape_crop(v: &Prepared, t: &VarIn, acc: &mut Acc, d: f64, invert: f64) -> V3 {
    let cut = if invert == 0.0 { d > 0.0 } else { d <= 0.0 };
    acc.hide = cut;
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    if cut {
        [0.0; 3]
    } else {
        [v.w * t.x, v.w * t.y, 0.0]
    }
}

/// crop_rhombus: keeps the rhombus with half-diagonals width and height.
fn crop_rhombus(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [bx, by, invert] = v.params();
    let (qx, qy) = (t.x.abs(), t.y.abs());
    let ndot = |ax: f64, ay: f64, cx: f64, cy: f64| ax * cx - ay * cy;
    let h = ((-2.0 * ndot(qx, qy, bx, by) + ndot(bx, by, bx, by)) / (bx * bx + by * by))
        .clamp(-1.0, 1.0);
    let (dx, dy) = (qx - 0.5 * bx * (1.0 - h), qy - 0.5 * by * (1.0 + h));
    let d = (dx * dx + dy * dy).sqrt() * sign(qx * by + qy * bx - bx * by);
    shape_crop(v, t, acc, d, invert)
}

/// crop_cross: keeps a cross of arm lengths width and Size (the larger first); the corner
/// rounding JWildfire applies is the fixed 0.1·sin(0.0012), whatever `round` says.
fn crop_cross(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [width, size, _, invert] = v.params();
    let (bx, by) = if width < size {
        (size, width)
    } else {
        (width, size)
    };
    let rr = 0.1 * (0.001_f64 * 1.2).sin();
    let (ax, ay) = (t.x.abs(), t.y.abs());
    let (px, py) = if ay > ax { (ay, ax) } else { (ax, ay) };
    let (qx, qy) = (px - bx, py - by);
    let k = qy.max(qx);
    let (wx, wy) = if k > 0.0 { (qx, qy) } else { (by - px, -k) };
    let (wx, wy) = (wx.max(0.0), wy.max(0.0));
    let d = sign(k) * (wx * wx + wy * wy).sqrt() + rr;
    shape_crop(v, t, acc, d, invert)
}

/// crop_vesica: keeps a vesica (the lens between two circles of radius 1 + height whose
/// centres are 0.8 + width from the middle).
fn crop_vesica(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [width, height, invert] = v.params();
    let (r, dd) = (1.0 + height, 0.8 + width);
    let (px, py) = (t.x.abs(), t.y.abs());
    let b = (r * r - dd * dd).sqrt();
    let d = if (py - b) * dd > px * b {
        (px * px + (py - b) * (py - b)).sqrt()
    } else {
        ((px + dd) * (px + dd) + py * py).sqrt() - r
    };
    shape_crop(v, t, acc, d, invert)
}

/// crop3D (Xyrus02's crop in 3-D): a point outside the box is hidden at the origin (`zero`)
/// or moved inside, into a band of relative width `scatter_area` along the crossed faces (one
/// draw per crossed axis, in x, y, z order). Replaces the xform's sum so far.
fn crop3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [left, right, top, bottom, floor, ceiling, scatter, zero] = v.params();
    let (xmin, xmax) = (left.min(right), left.max(right));
    let (ymin, ymax) = (top.min(bottom), top.max(bottom));
    let (zmin, zmax) = (floor.min(ceiling), floor.max(ceiling));
    let w = (xmax - xmin) * 0.5 * scatter;
    let h = (ymax - ymin) * 0.5 * scatter;
    let l = (zmax - zmin) * 0.5 * scatter;
    let (mut x, mut y, mut z) = (t.x, t.y, t.z);
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    let outside = x < xmin || x > xmax || y < ymin || y > ymax || z < zmin || z > zmax;
    if outside && zero != 0.0 {
        acc.hide = true;
        return [0.0; 3];
    }
    acc.hide = false;
    let mut pull = |c: &mut f64, lo: f64, hi: f64, band: f64| {
        if *c < lo {
            *c = lo + rng.f01() * band;
        } else if *c > hi {
            *c = hi - rng.f01() * band;
        }
    };
    pull(&mut x, xmin, xmax, w);
    pull(&mut y, ymin, ymax, h);
    pull(&mut z, zmin, zmax, l);
    [v.w * x, v.w * y, v.w * z]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::variations::{by_name, eval_prepared, info};

    /// JWildfire's output and hide flag at points of its vectors (default parameters, weight
    /// 0.7): one kept and one hidden point per crop.
    #[test]
    fn hide_flags_follow_jwildfire() {
        let rows: &[(&str, [f64; 2], [f64; 2], bool)] = &[
            (
                "crop_triangle",
                [-0.1125, 0.3975],
                [-0.07875, 0.27825],
                true,
            ),
            ("crop_triangle", [0.0, 0.0], [0.0, 0.0], false),
            ("crop_rhombus", [-0.1125, 0.3975], [0.0, 0.0], true),
            (
                "crop_rhombus",
                [-0.124999975, 0.374999725],
                [-0.0874999825, 0.2624998075],
                false,
            ),
            ("crop_cross", [-0.1125, 0.3975], [-0.07875, 0.27825], false),
            ("crop_cross", [0.625, 0.125], [0.0, 0.0], true),
            ("crop_vesica", [-0.1125, 0.3975], [0.0, 0.0], true),
            ("crop_vesica", [0.0, 0.0], [0.0, 0.0], false),
        ];
        for &(name, t, want, hide) in rows {
            let id = by_name(name).unwrap();
            let v = Prepared::new(
                id,
                Form::Regular,
                0.7,
                &info(id).defaults(),
                Affine::IDENTITY,
                true,
            );
            let mut rng = FastRng::new(1);
            let acc = Acc {
                color: 0.35,
                ..Acc::default()
            };
            let o = eval_prepared(&v, [t[0], t[1], 0.0], acc, true, &mut rng);
            assert_eq!(o.hide, hide, "{name} at {t:?}");
            assert!(
                (o.x - want[0]).abs() < 1e-12 && (o.y - want[1]).abs() < 1e-12,
                "{name} at {t:?}: {o:?}"
            );
        }
    }
}
