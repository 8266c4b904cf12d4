//! JWildfire's shape crops by Jesus Sosa: `crop_box`, `crop_x`, `crop_trapezoid` and
//! `crop_polygon` (hexagram, octagon, hexagon, pentagon or circle). Each measures the signed
//! distance of the point to the shape (Inigo Quilez's distance functions) and hides the points
//! outside (inside, with `invert`), which go to the origin; the point replaces the xform's
//! running sum.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use super::*;

const CROP_FLAGS: u32 = flag::JWILDFIRE | flag::HIDES | flag::WRITES_ACC;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("crop_box", crop_box)
        .params(&[
            p("crop_box_width", 0.5),
            p("crop_box_height", 0.5),
            p_int("crop_box_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CROP_FLAGS),
    VarDef::new("crop_x", crop_x)
        .params(&[
            p("crop_x_radius", 0.1),
            p_range("crop_x_w", 0.5, 0.0, 1.0),
            p_int("crop_x_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CROP_FLAGS),
    VarDef::new("crop_trapezoid", crop_trapezoid)
        .params(&[
            p("crop_trapezoid_Base Sup.", 0.5),
            p("crop_trapezoid_Base Inf.", 0.2),
            p("crop_trapezoid_height", 0.5),
            p_int("crop_trapezoid_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CROP_FLAGS),
    VarDef::new("crop_polygon", crop_polygon)
        .params(&[
            p_int("crop_polygon_type", 4.0, 0.0, 4.0),
            p("crop_polygon_radius", 0.35),
            p_int("crop_polygon_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CROP_FLAGS),
];

/// The shared part: hidden (and moved to the origin) where the distance `d` is positive
/// (`invert` 0) or not (1); the point replaces the running sum.
fn crop(v: &Prepared, t: &VarIn, acc: &mut Acc, d: f64, invert: f64) -> V3 {
    let hide = if invert == 0.0 { d > 0.0 } else { d <= 0.0 };
    acc.hide = hide;
    acc.x = 0.0;
    acc.y = 0.0;
    if hide {
        [0.0; 3]
    } else {
        [v.w * t.x, v.w * t.y, 0.0]
    }
}

/// GLSL's `sign` (0 at 0).
fn gsign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// crop_box: the rectangle |x| ≤ width, |y| ≤ height.
fn crop_box(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [width, height, invert] = v.params();
    let (dx, dy) = (t.x.abs() - width, t.y.abs() - height);
    let d = (dx.max(0.0).powi(2) + dy.max(0.0).powi(2)).sqrt() + dx.max(dy).min(0.0);
    crop(v, t, acc, d, invert)
}

/// crop_x: JWildfire hides every point here (its test for the inside is not in an `else`), and
/// does not move the hidden points.
fn crop_x(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [radius, w, invert] = v.params();
    let (px, py) = (t.x.abs(), t.y.abs());
    let m = (px + py).min(w) * 0.5;
    let d = ((px - m).powi(2) + (py - m).powi(2)).sqrt() - radius;
    let hide = if invert == 0.0 { d > 0.0 } else { d <= 0.0 };
    acc.hide = hide;
    if v.form == Form::Post {
        // JWildfire's post_crop_x moves a hidden point to the origin and keeps z.
        let k = if hide { 0.0 } else { v.w };
        return [k * t.x, k * t.y, t.z];
    }
    acc.x = 0.0;
    acc.y = 0.0;
    [v.w * t.x, v.w * t.y, 0.0]
}

/// crop_trapezoid: the isosceles trapezoid of half-widths `Base Sup.` (bottom) and
/// `Base Inf.` (top) and half-height `height`.
fn crop_trapezoid(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [r1, r2, he, invert] = v.params();
    let (k1x, k1y) = (r2, he);
    let (k2x, k2y) = (r2 - r1, 2.0 * he);
    let (px, py) = (t.x.abs(), t.y);
    let cax = (px - if py < 0.0 { r1 } else { r2 }).max(0.0);
    let cay = py.abs() - he;
    let t0 = ((k1x - px) * k2x + (k1y - py) * k2y) / (k2x * k2x + k2y * k2y);
    let t0 = t0.clamp(0.0, 1.0);
    let (cbx, cby) = (px - k1x + k2x * t0, py - k1y + k2y * t0);
    let s = if cbx < 0.0 && cay < 0.0 { -1.0 } else { 1.0 };
    let d = s * (cax * cax + cay * cay).min(cbx * cbx + cby * cby).sqrt();
    crop(v, t, acc, d, invert)
}

/// Folds `p` across the line through the origin of normal `k` where it lies on its negative
/// side.
fn fold(p: (f64, f64), k: (f64, f64)) -> (f64, f64) {
    let m = 2.0 * (k.0 * p.0 + k.1 * p.1).min(0.0);
    (p.0 - k.0 * m, p.1 - k.1 * m)
}

/// The signed distance to the edge segment |x| ≤ half at height r of a folded point.
fn edge(p: (f64, f64), lo: f64, hi: f64, r: f64) -> f64 {
    let (x, y) = (p.0 - p.0.max(lo).min(hi), p.1 - r);
    (x * x + y * y).sqrt() * gsign(y)
}

/// crop_polygon: a hexagram (type 4), octagon (3), hexagon (2), pentagon (1) or circle (0) of
/// inner radius `radius`.
fn crop_polygon(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [kind, r, invert] = v.params();
    let a = (t.x.abs(), t.y.abs());
    let d = match kind as i32 {
        4 => {
            let (kx, ky, kz, kw) = (-0.5, 0.86602540378, 0.57735026919, 1.73205080757);
            let p = fold(fold(a, (kx, ky)), (ky, kx));
            edge(p, r * kz, r * kw, r)
        }
        3 => {
            let (kx, ky, kz) = (-0.9238795325, 0.3826834323, 0.4142135623);
            let p = fold(fold(a, (kx, ky)), (-kx, ky));
            edge(p, -kz * r, kz * r, r)
        }
        2 => {
            let (kx, ky, kz) = (-0.866025404, 0.5, 0.577350269);
            edge(fold(a, (kx, ky)), -kz * r, kz * r, r)
        }
        1 => {
            let (kx, ky, kz) = (0.809016994, 0.587785252, 0.726542528);
            let p = fold(fold((t.x.abs(), -t.y), (-kx, ky)), (kx, ky));
            edge(p, -r * kz, r * kz, r)
        }
        _ => (t.x * t.x + t.y * t.y).sqrt() - r,
    };
    crop(v, t, acc, d, invert)
}

#[cfg(test)]
mod tests;
