//! Crops from Fractorium's catalogue: keep the points inside a rectangle, polygon, disc, annulus,
//! hexagon or octagon and remove, push back or scatter the others (`crob`, `crop`, `cropn`,
//! `circlecrop*`, `hexcrop`, `post_smartcrop`, `vignette`, `octapol`, `bcircle`, `circlesplit`).
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{PI, TAU};

use super::util::{mix, sqr, trunc_i32, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("bcircle", bcircle)
        .params(&[p("bcircle_scale", 1.0), p("bcircle_borderwidth", 0.0)])
        .flags(flag::RANDOM)
        .prepare(prep_bcircle),
    super::inlined!("circlecrop", circlecrop)
        .params(&[
            p("circlecrop_radius", 1.0),
            p("circlecrop_x", 0.0),
            p("circlecrop_y", 0.0),
            p("circlecrop_scatter_area", 0.0),
            p_range("circlecrop_zero", 1.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC | flag::COMPAT),
    super::inlined!("circlecrop2", circlecrop2)
        .params(&[
            p("circlecrop2_inner", 0.5),
            p("circlecrop2_outer", 1.0),
            p_range("circlecrop2_zero", 1.0, 0.0, 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(prep_circlecrop2),
    super::inlined!("circlesplit", circlesplit)
        .params(&[p("circlesplit_radius", 1.0), p("circlesplit_split", 0.5)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX),
    super::inlined!("crob", crob)
        .params(&[
            p("crob_top", -1.0),
            p("crob_bottom", 1.0),
            p("crob_left", -1.0),
            p("crob_right", 1.0),
            p_int("crob_blur", 1.0, NEG_INF, INF),
            p_range("crob_ratioBlur", 0.5, 0.0, 1.0),
            p("crob_directBlur", 2.0),
        ])
        .flags(flag::RANDOM)
        .prepare(crob_prepare),
    super::inlined!("crop", crop)
        .params(&[
            p("crop_left", -1.0),
            p("crop_top", -1.0),
            p("crop_right", 1.0),
            p("crop_bottom", 1.0),
            p("crop_scatter_area", 0.0),
            p_int("crop_zero", 0.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(crop_prepare),
    super::inlined!("cropn", cropn)
        .params(&[
            p("cropn_power", 5.0),
            p("cropn_radius", 1.0),
            p("cropn_scatterdist", 0.0),
            p("cropn_zero", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES | need::ATAN_YX)
        .flags(flag::RANDOM | flag::COMPAT)
        .prepare(cropn_prepare),
    super::inlined!("hexcrop", hexcrop)
        .params(&[
            p("hexcrop_scale_x", 1.0),
            p("hexcrop_scale_y", 1.0),
            p("hexcrop_center_x", 0.0),
            p("hexcrop_center_y", 0.0),
            p("hexcrop_dropoff", 1e10),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::READS_ACC | flag::WRITES_ACC)
        .prepare(hexcrop_prepare),
    super::inlined!("octapol", octapol)
        .params(&[
            p("octapol_polarweight", 0.0),
            p("octapol_radius", 1.0),
            p("octapol_s", 0.5),
            p("octapol_t", 0.5),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::WRITES_ACC)
        .prepare(prep_octapol),
    super::inlined!("post_smartcrop", post_smartcrop)
        .params(&[
            p("post_smartcrop_power", 4.0),
            p("post_smartcrop_radius", 1.0),
            p("post_smartcrop_roundstr", 0.0),
            p("post_smartcrop_roundwidth", 1.0),
            p("post_smartcrop_distortion", 1.0),
            p("post_smartcrop_edge", 0.0),
            p("post_smartcrop_scatter", 0.0),
            p("post_smartcrop_offset", 0.0),
            p("post_smartcrop_rotation", 0.0),
            p_range("post_smartcrop_cropmode", 1.0, -1.0, 2.0),
            p_range("post_smartcrop_static", 1.0, -1.0, 3.0),
        ])
        .flags(
            flag::POST_ONLY
                | flag::RANDOM
                | flag::STATEFUL
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::SETS_COLOR
                | flag::USES_COLOR
                | flag::READS_AFFINE_POINT
                | flag::READS_ACC,
        )
        .prepare(prep_post_smartcrop),
    super::inlined!("vignette", vignette)
        .params(&[
            p("vignette_posx", 0.0),
            p("vignette_posy", 0.0),
            p("vignette_inner_radius", 0.5),
            p_nonzero(
                "vignette_fade_radius",
                0.5,
                f64::NEG_INFINITY,
                f64::INFINITY,
            ),
            p_nonzero("vignette_power", 4.0, f64::NEG_INFINITY, f64::INFINITY),
            p("vignette_blur", 1.0),
        ])
        .flags(flag::RANDOM)
        .prepare(vignette_prep),
];

/// Derived values: |border width|, |border width| / 5.
fn prep_bcircle(v: &mut Prepared) {
    let [_, borderwidth] = v.params();
    let bw = borderwidth.abs();
    v.p.push(bw);
    v.p.push(0.2 * bw);
}

/// Keeps the scaled point inside the unit disc; outside it, the point goes to a random radius
/// in a thin ring just beyond the circle (or to the origin when the ring has no width).
#[inline(always)]
fn bcircle(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scale] = v.params();
    let [bw, bw_fifth] = v.derived();
    let (x, y) = (t.x * scale, t.y * scale);
    if (x * x + y * y).sqrt() <= 1.0 {
        return [v.w * x, v.w * y, 0.0];
    }
    if bw == 0.0 {
        return [0.0, 0.0, 0.0];
    }
    let (s, c) = y.atan2(x).fsin_cos();
    let rad = v.w * (bw_fifth * rng.f01() + 1.0);
    [rad * c, rad * s, 0.0]
}

/// Crops to the disc of `radius` about (x₀, y₀): points outside go to the origin (`zero` = 1)
/// or onto a thin random ring just outside the rim.
#[inline(always)]
fn circlecrop(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, cx, cy, scatter, zero] = v.params();
    let (xi, yi) = (t.x - cx, t.y - cy);
    // flam3-compatible regular use: z is weighted (and, as in Fractorium, the crop also clears
    // what earlier variations summed); otherwise z passes through.
    let legacy = v.compat && v.form == Form::Regular;
    let z = if legacy { v.w * t.z } else { t.z };
    let rad = (xi * xi + yi * yi).sqrt();
    let rdc = radius + rng.f01() * 0.5 * scatter.clamp(-1.0, 1.0);
    if rad > radius {
        if zero as i32 != 0 {
            if legacy {
                acc.x = 0.0;
                acc.y = 0.0;
            }
            [0.0, 0.0, z]
        } else {
            let (s, c) = yi.atan2(xi).fsin_cos();
            [v.w * rdc * c + cx, v.w * rdc * s + cy, z]
        }
    } else {
        [v.w * xi + cx, v.w * yi + cy, z]
    }
}

/// Derived values: inner and outer radii in order, outer radius · w.
fn prep_circlecrop2(v: &mut Prepared) {
    let [a, b] = v.params();
    let (lo, hi) = (a.min(b), a.max(b));
    v.p.push(lo);
    v.p.push(hi);
    v.p.push(hi * v.w);
}

/// Keeps the annulus between the two radii; points outside it go to the origin, or
/// (zero = 0) onto the outer circle, mirrored across the diagonal (sine of their angle in x,
/// cosine in y).
#[inline(always)]
fn circlecrop2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, zero] = v.params();
    let [lo, hi, hi_w] = v.derived();
    let r = t.sqrt;
    if r > hi || r < lo {
        if zero == 0.0 {
            let (s, c) = (t.atan_yx.fsin(), t.atan_yx.fcos());
            [s * hi_w, c * hi_w, 0.0]
        } else {
            [0.0, 0.0, 0.0]
        }
    } else {
        [t.x * v.w, t.y * v.w, 0.0]
    }
}

/// Splits the disc of `radius − split` from the rest of the plane, pushing outer points out by
/// `split`.
#[inline(always)]
fn circlesplit(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [radius, split] = v.params();
    if t.sqrt < radius - split {
        return [v.w * t.x, v.w * t.y, 0.0];
    }
    let len = t.sqrt + split;
    let (s, c) = (t.atan_yx.fsin(), t.atan_yx.fcos());
    [v.w * (c * len), v.w * (s * len), 0.0]
}

/// Derived values: the edges of the kept region (top, bottom, left, right), the sorted edges of
/// the rectangle, blur (0 or 1), the direct-blur exponent, the half sizes, the smaller half size,
/// the corner (x0c, y0c) the bands are cut from and the probability of the vertical bands.
fn crob_prepare(v: &mut Prepared) {
    let [top0, bottom0, left0, right0, blur0, ratio, direct0] = v.params();
    let (mut top, mut bottom) = if top0 > bottom0 {
        (bottom0, top0)
    } else {
        (top0, bottom0)
    };
    if top == bottom {
        (top, bottom) = (-1.0, 1.0);
    }
    let (mut left, mut right) = if left0 > right0 {
        (right0, left0)
    } else {
        (left0, right0)
    };
    if left == right {
        (left, right) = (-1.0, 1.0);
    }
    let direct = if direct0 < 0.0 { 0.0 } else { direct0 };
    let blur = if blur0 != 0.0 { 1.0 } else { 0.0 };
    let xint = right.abs() - left;
    let yint = bottom.abs() - top;
    let (xint2, yint2) = (xint / 2.0, yint / 2.0);
    let minint2 = if xint2 > yint2 { yint2 } else { xint2 };
    let x0 = right - xint2;
    let y0 = top + yint2;
    let (x0c, y0c) = if xint2 > yint2 {
        (right - minint2, y0)
    } else if xint2 < yint2 {
        (x0, top + minint2)
    } else {
        (x0, y0)
    };
    let prob = yint / (xint + yint);
    let border = if blur == 0.0 {
        [top, bottom, left, right]
    } else {
        let m = minint2 * ratio;
        [top + m, bottom - m, left + m, right - m]
    };
    v.p.extend_from_slice(&border);
    v.p.extend_from_slice(&[
        top, bottom, left, right, blur, direct, xint2, yint2, minint2, x0c, y0c, prob,
    ]);
}

/// Crops to a rectangle: points inside vanish (0), points outside are thrown back onto a band
/// along the rectangle's inner edge (or to 0 without blur). Unweighted.
#[inline(always)]
fn crob(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, ratio] = v.params();
    let [
        b_top,
        b_bottom,
        b_left,
        b_right,
        top,
        bottom,
        left,
        right,
        blur,
        direct,
        xint2,
        yint2,
        minint2,
        x0c,
        y0c,
        prob,
    ] = v.derived();
    let outside = t.x < b_left || t.x > b_right || t.y < b_top || t.y > b_bottom;
    if !outside || blur == 0.0 {
        return [0.0, 0.0, 0.0];
    }
    let sec = rng.f01();
    let (mut x, mut y);
    // The rejection loops accept well over half of their draws for any sensible rectangle; the
    // cap only guards against degenerate parameters.
    let mut tries = 0;
    if sec < prob {
        loop {
            y = top + rng.f01() * yint2;
            x = right - rng.f01().powf(direct) * ratio * minint2;
            tries += 1;
            if (y - y0c) / zeps(x - x0c) >= -1.0 || tries > 100_000 {
                break;
            }
        }
        if sec < 0.5 * prob {
            x = left + right - x;
        }
        if sec > 0.25 * prob && sec < 0.75 * prob {
            y = bottom + top - y;
        }
    } else {
        loop {
            x = right - rng.f01() * xint2;
            y = top + rng.f01().powf(direct) * ratio * minint2;
            let grad = (y - y0c) / zeps(x - x0c);
            tries += 1;
            if !(grad <= 0.0 && grad > -1.0) || tries > 100_000 {
                break;
            }
        }
        if sec > 0.5 * prob {
            y = bottom + top - y;
        }
        if sec > 0.25 * prob && sec < 0.75 * prob {
            x = left + right - x;
        }
    }
    [x, y, 0.0]
}

fn crop_prepare(v: &mut Prepared) {
    let [left, top, right, bottom, s] = v.params();
    let (x0, x1) = if left < right {
        (left, right)
    } else {
        (right, left)
    };
    let (y0, y1) = if top < bottom {
        (top, bottom)
    } else {
        (bottom, top)
    };
    let w = (x1 - x0) * 0.5 * s;
    let h = (y1 - y0) * 0.5 * s;
    v.p.extend_from_slice(&[x0, y0, x1, y1, w, h]);
}

/// Crops to a rectangle: outside points are zeroed (`crop_zero`) or pulled back inside, scattered
/// over a band of relative width `crop_scatter_area` along the violated edge.
#[inline(always)]
fn crop(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, zero] = v.params();
    let [x0, y0, x1, y1, w, h] = v.derived();
    let (x, y) = (t.x, t.y);
    let outside = x < x0 || x > x1 || y < y0 || y > y1;
    let (x, y) = if outside && zero != 0.0 {
        (0.0, 0.0)
    } else {
        pull_inside(x, y, [x0, y0, x1, y1, w, h], rng)
    };
    [v.w * x, v.w * y, v.w * t.z]
}

/// A point outside the rectangle `[x0, y0, x1, y1]` pulled back inside, scattered over a band
/// of width `w` (x) or `h` (y) along each violated edge; x's draw comes before y's.
pub(super) fn pull_inside(
    mut x: f64,
    mut y: f64,
    [x0, y0, x1, y1, w, h]: [f64; 6],
    rng: &mut FastRng,
) -> (f64, f64) {
    if x < x0 {
        x = x0 + rng.f01() * w;
    } else if x > x1 {
        x = x1 - rng.f01() * w;
    }
    if y < y0 {
        y = y0 + rng.f01() * h;
    } else if y > y1 {
        y = y1 - rng.f01() * h;
    }
    (x, y)
}

fn cropn_prepare(v: &mut Prepared) {
    let [power] = v.params();
    let alpha = TAU / power.abs().max(2.0);
    v.p.extend_from_slice(&[alpha, alpha / 2.0]);
}

/// Crops to a regular polygon of `cropn_power` sides (outside it for a negative power): points
/// beyond the edge go to the edge (optionally scattered outwards) or to 0.
#[inline(always)]
fn cropn(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, radius, scatter, zero] = v.params();
    let [alpha, half] = v.derived();
    let w = v.w;
    if v.compat {
        let mut a = (t.atan_yx + PI) / alpha;
        a = (a - a.trunc()) * alpha;
        let c = (if a < half { a } else { alpha - a }).fcos();
        let edge = if c > 0.0 { radius / c } else { 1.0 };
        if (t.sqrt > edge) == (power > 0.0) {
            if zero == 1.0 {
                [0.0, 0.0, 0.0]
            } else {
                let rd = edge + rng.f01() * 0.5 * scatter;
                [w * rd * t.ux, w * rd * t.uy, 0.0]
            }
        } else {
            [w * t.x, w * t.y, 0.0]
        }
    } else {
        let r2 = t.sumsq;
        let a = (t.atan_yx + PI) % alpha;
        let c = (if a < half { a } else { alpha - a }).fcos();
        let edge = if c > 0.0 { radius / zeps(c) } else { 1.0 };
        if (r2 > edge * edge) == (power > 0.0) {
            if zero == 0.0 {
                [0.0, 0.0, 0.0]
            } else {
                let k = (edge + rng.f01() * scatter) * w / zeps(r2.sqrt());
                [k * t.x, k * t.y, 0.0]
            }
        } else {
            [w * t.x, w * t.y, 0.0]
        }
    }
}

fn hexcrop_prepare(v: &mut Prepared) {
    let [sx, sy] = v.params();
    const H: f64 = 1.060_660_171_779_821_2;
    const S2: f64 = std::f64::consts::SQRT_2;
    let xs = [-0.5 * sx, 0.5 * sx, S2 * sx, 0.5 * sx, -0.5 * sx, -S2 * sx];
    let ys = [H * sy, H * sy, 0.0 * sy, -H * sy, -H * sy, 0.0 * sy];
    v.p.extend_from_slice(&xs);
    v.p.extend_from_slice(&ys);
}

/// Crops to a hexagon (scaled by scale_x/scale_y, shifted by the centre): points inside are
/// kept, the others sent to the far `dropoff` point. As a regular variation the xform's running
/// sum is carried along inside the hexagon and dropped outside.
#[inline(always)]
fn hexcrop(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, cx, cy, drop] = v.params();
    let (xs, ys) = v.table(0).split_at(6);
    let ix = t.x + cx;
    let iy = t.y + cy;
    let mut inside = false;
    let mut prev = 5;
    for cur in 0..6 {
        let (ya, yb) = (ys[cur], ys[prev]);
        if ((ya <= iy && iy < yb) || (yb <= iy && iy < ya))
            && ix < (xs[prev] - xs[cur]) * (iy - ya) / zeps(yb - ya) + xs[cur]
        {
            inside = !inside;
        }
        prev = cur;
    }
    let z = v.w * t.z;
    if v.form == Form::Regular {
        let (sx, sy) = (acc.x, acc.y);
        acc.x = 0.0;
        acc.y = 0.0;
        if inside {
            [sx + ix * v.w, sy + iy * v.w, z]
        } else {
            [drop, drop, z]
        }
    } else if inside {
        [ix * v.w, iy * v.w, z]
    } else {
        [drop, drop, z]
    }
}

/// Fractorium's rounded 1/√2 for octapol's disc radius (kept rounded to reproduce it).
#[allow(clippy::approx_constant)]
const OCTAPOL_HALF_SQRT2: f64 = 0.707_106_781;

/// Derived values: the disc radius, the half-size of the shape, then the corner points A..L as
/// x, y pairs.
fn prep_octapol(v: &mut Prepared) {
    let [_, radius, s, t] = v.params();
    let (s, t) = (s.abs(), t.abs());
    let h = 0.5 * s;
    let rad = OCTAPOL_HALF_SQRT2 * s * radius.abs();
    v.p.extend_from_slice(&[
        rad,
        h + t,
        // A B C D
        -h,
        h + t,
        h,
        h + t,
        t,
        h,
        t,
        -h,
        // E F G H
        h,
        -h - t,
        -h,
        -h - t,
        -t,
        -h,
        -t,
        h,
        // I J K L
        -h,
        h,
        h,
        h,
        -h,
        -h,
        h,
        -h,
    ]);
}

/// octapol: keeps the points of an octagon-like shape built from rectangles and triangles
/// (sizes s and t), with a polar-warped disc in its centre; points elsewhere are removed from
/// the running sum. The output adds a scaled copy of the (shrunken) input.
#[inline(always)]
fn octapol(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [pw] = v.params();
    let [rad, st] = v.derived();
    let corners = v.table(2);
    let w = v.w;
    let pt = |i: usize| (corners[2 * i], corners[2 * i + 1]);
    let (a, b, c, d, e, f) = (pt(0), pt(1), pt(2), pt(3), pt(4), pt(5));
    let (g, h, i, j, k, l) = (pt(6), pt(7), pt(8), pt(9), pt(10), pt(11));
    let x = t.x * 0.15;
    let y = t.y * 0.15;
    let in_rect = |tl: (f64, f64), br: (f64, f64)| x >= tl.0 && y >= tl.1 && x <= br.0 && y <= br.1;
    let in_tri = |a: (f64, f64), b: (f64, f64), c: (f64, f64)| {
        let (v0x, v0y) = (c.0 - a.0, c.1 - a.1);
        let (v1x, v1y) = (b.0 - a.0, b.1 - a.1);
        let (v2x, v2y) = (x - a.0, y - a.1);
        let d00 = v0x * v0x + v0y * v0y;
        let d01 = v0x * v1x + v0y * v1y;
        let d02 = v0x * v2x + v0y * v2y;
        let d11 = v1x * v1x + v1y * v1y;
        let d12 = v1x * v2x + v1y * v2y;
        let den = d00 * d11 - d01 * d01;
        let (u, vv) = if den != 0.0 {
            ((d11 * d02 - d01 * d12) / den, (d00 * d12 - d01 * d02) / den)
        } else {
            (0.0, 0.0)
        };
        (u + vv) < 1.0 && u > 0.0 && vv > 0.0
    };
    let mut extra = (0.0, 0.0);
    let mut keep = true;
    let r = if rad > 0.0 {
        (x * x + y * y).sqrt()
    } else {
        0.0
    };
    if rad > 0.0 && r <= rad {
        let rd = (sqr(r / rad)).ln();
        let phi = y.atan2(x);
        extra = (w * mix(x, phi, rd * pw), w * mix(y, r, rd * pw));
    } else if x.abs() <= st && y.abs() <= st {
        if in_rect(h, k)
            || in_rect(j, d)
            || in_rect(a, j)
            || in_rect(k, e)
            || in_tri(i, a, h)
            || in_tri(j, b, c)
            || in_tri(l, d, e)
            || in_tri(k, f, g)
        {
            extra = (w * x, w * y);
        } else {
            keep = false;
        }
    } else {
        keep = false;
    }
    if !keep && v.form != Form::Pre {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [extra.0 + w * x, extra.1 + w * y, w * t.z]
}

/// post_smartcrop's state slots: the last kept point (x, y, z) and its colour.
mod sc {
    pub const SX: usize = 0;
    pub const SY: usize = 1;
    pub const SZ: usize = 2;
    pub const SC: usize = 3;
}

/// Derived values: the crop mode (1 keeps the inside), radial (1 for a sector), |radius|, the
/// working power, the polygon's angle, the rounding factor and the rotation.
fn prep_post_smartcrop(v: &mut Prepared) {
    let [power, radius, roundstr, _, _, _, _, _, rotation] = v.params();
    let mode = if (power > 0.0) == (radius > 0.0) {
        1.0
    } else {
        0.0
    };
    let mut work_power = zeps(power).abs();
    let (radial, mut alpha, mut round, mut work_rot) = (work_power < 2.0, 0.0, 0.0, 0.0);
    if radial {
        work_power *= PI;
    } else {
        alpha = TAU / work_power;
        round = roundstr / zeps((alpha / 2.0).fsin()) / work_power * 2.0;
        work_rot = rotation * alpha;
    }
    v.p.extend_from_slice(&[
        mode,
        if radial { 1.0 } else { 0.0 },
        radius.abs(),
        work_power,
        alpha,
        round,
        work_rot,
    ]);
    for i in 0..4 {
        v.state.set(i, 0.0);
    }
}

/// post_smartcrop: crops the summed point to a polygon (power ≥ 2 sides, optionally rounded
/// and distorted) or to an angular sector (power < 2); cropped points are removed, pushed onto
/// the crop edge (scattered), or replaced by the last kept point. The `static` modes above 1
/// crop the summed point (`acc`); the others crop the point the xform's regular variations saw
/// (the input `t`, [`flag::READS_AFFINE_POINT`]) and add the result to the sum, as Fractorium
/// (`PostSmartcropVariation`) and JWildfire 9.00 (`PostSmartCropFunc`) both do.
#[inline(always)]
fn post_smartcrop(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _power,
        _radius,
        roundstr,
        roundwidth,
        distortion,
        edge_p,
        scatter,
        offset,
        _rotation,
        cropmode,
        stat,
    ] = v.params();
    let [mode, radial, radius, power, alpha, round, rotation] = v.derived();
    let w = v.w;
    let mode = mode as i32;
    let absolute = stat > 1.0 || stat == -1.0;
    // The sum so far, which a relative mode adds to.
    let sum = [acc.x, acc.y, acc.z];
    let (xi, yi, zi) = if stat > 1.0 {
        (sum[0], sum[1], sum[2])
    } else {
        (t.x, t.y, t.z)
    };
    let ang = yi.atan2(xi);
    let rad = (xi * xi + yi * yi).sqrt();
    let st = &v.state;
    let last_kept = |acc: &mut Acc| -> V3 {
        acc.color = st.get(sc::SC);
        let s = [st.get(sc::SX), st.get(sc::SY), st.get(sc::SZ)];
        if absolute {
            s
        } else {
            [sum[0] + s[0], sum[1] + s[1], sum[2] + s[2]]
        }
    };
    let placed = |r: f64, a: f64| -> V3 {
        let o = [w * r * a.fcos(), w * r * a.fsin(), w * zi];
        if absolute {
            o
        } else {
            [sum[0] + o[0], sum[1] + o[1], sum[2] + o[2]]
        }
    };
    if radial != 0.0 {
        let edge = edge_p * (rng.f01() - 0.5);
        let mut xang = ang / TAU + 1.0 + edge;
        xang = (xang - xang.trunc()) * TAU;
        if ((xang > power) as i32) == mode {
            if cropmode == 2.0 {
                return last_kept(acc);
            }
            let a = if trunc_i32(rng.f01() * 2.0) != 0 {
                power + (rng.f01() * scatter + offset + edge) * PI
            } else {
                -(rng.f01() * scatter + offset + edge) * PI
            };
            return placed(rad, a);
        }
    } else {
        let coeff = if distortion == 0.0 {
            1.0
        } else {
            let mut xang = (ang + PI) / alpha;
            xang -= xang.trunc();
            xang = if xang < 0.5 { xang } else { 1.0 - xang };
            let mut k = 1.0 / (xang * alpha).fcos();
            if roundstr != 0.0 {
                let ww = if roundwidth != 1.0 {
                    ((xang * 2.0).ln() * roundwidth).exp()
                } else {
                    xang * 2.0
                } * round;
                k = ((1.0 - ww) * k + ww).abs();
            }
            if distortion != 1.0 {
                k = (k.ln() * distortion).exp();
            }
            k
        };
        let xr = coeff
            * if edge_p != 0.0 {
                radius + edge_p * (rng.f01() - 0.5)
            } else {
                radius
            };
        if ((rad > xr) as i32) == mode {
            if cropmode == 2.0 {
                return last_kept(acc);
            }
            if cropmode != 0.0 {
                let rdc = if cropmode == -1.0 {
                    rad
                } else {
                    xr + coeff * (rng.f01() * scatter + offset)
                };
                return placed(rdc, ang + rotation);
            }
            // Removed: the origin in the absolute modes; otherwise the point is left as is.
            return if absolute { [0.0, 0.0, 0.0] } else { sum };
        }
    }
    // Kept: remember it (scaled by the weight) for the "last kept point" crop mode.
    let s = [w * xi, w * yi, w * zi];
    st.set(sc::SX, s[0]);
    st.set(sc::SY, s[1]);
    st.set(sc::SZ, s[2]);
    if cropmode == 2.0 {
        st.set(sc::SC, acc.color);
    }
    if stat > 0.0 {
        s
    } else {
        [sum[0] + s[0], sum[1] + s[1], sum[2] + s[2]]
    }
}

/// Derived values of vignette: |inner radius|, |fade radius|, 1/|power|.
fn vignette_prep(v: &mut Prepared) {
    let [_, _, inner, fade, power] = v.params();
    v.p.extend_from_slice(&[inner.abs(), fade.abs(), 1.0 / power.abs()]);
}

/// vignette: keeps the disc around (posx, posy) and randomly thins and blurs the points
/// beyond it over the fade distance (a negative fade radius inverts the fade; a negative
/// inner radius empties the disc).
#[inline(always)]
fn vignette(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [posx, posy, inner, fade_r, _, blur] = v.params();
    let [inner_abs, fade_abs, pow_inv] = v.derived();
    let (mut px, mut py) = (t.x, t.y);
    let dist = ((px - posx) * (px - posx) + (py - posy) * (py - posy)).sqrt();
    if dist < inner_abs {
        if inner < 0.0 {
            return [0.0; 3];
        }
        return [px * v.w, py * v.w, 0.0];
    }
    let dist = (dist - inner_abs) / fade_abs;
    let fade = 1.0 - rng.f01().powf(pow_inv);
    let blur_r = blur * (dist * rng.f01()).powf(2.0);
    let blur_a = rng.f01() * TAU;
    let dropped = if fade_r > 0.0 {
        fade < dist
    } else {
        1.0 - fade > dist
    };
    if dropped {
        px = 0.0;
        py = 0.0;
    } else {
        px += blur_r * blur_a.fcos();
        py += blur_r * blur_a.fsin();
    }
    [px * v.w, py * v.w, 0.0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::affine::Affine;

    /// post_smartcrop with `static` set, power 4 (a square of radius 1), keeping the inside.
    fn smartcrop(stat: f64) -> Prepared {
        let (id, form) = parse_name("post_smartcrop").expect("registered");
        let mut vals = info(id).defaults();
        let (_, _, k) = param_of("post_smartcrop_static").expect("a parameter");
        vals[k] = stat;
        Prepared::new(id, form, 1.0, &vals, Affine::default(), true)
    }

    fn sum_at(x: f64, y: f64) -> Acc {
        Acc {
            x,
            y,
            z: 0.0,
            color: 0.5,
            hide: false,
            rgb: None,
        }
    }

    #[test]
    fn smartcrop_reads_the_affine_point_unless_static_is_above_1() {
        let mut rng = FastRng::new(7);
        let affine = [0.1, 0.2, 0.0];
        // static 0: the affine point (inside) is kept and added to the sum (outside).
        let mut acc = sum_at(5.0, 5.0);
        smartcrop(0.0).apply_post_after(&affine, &mut acc, 0.5, &mut rng);
        assert!((acc.x - 5.1).abs() < 1e-12 && (acc.y - 5.2).abs() < 1e-12);
        // static 1: a kept affine point replaces the sum.
        let mut acc = sum_at(5.0, 5.0);
        smartcrop(1.0).apply_post_after(&affine, &mut acc, 0.5, &mut rng);
        assert!((acc.x - 0.1).abs() < 1e-12 && (acc.y - 0.2).abs() < 1e-12);
        // An affine point outside is pushed onto the crop's edge, and that is added.
        let mut acc = sum_at(5.0, 5.0);
        smartcrop(1.0).apply_post_after(&[3.0, 0.0, 0.0], &mut acc, 0.5, &mut rng);
        assert!((acc.x - 6.0).abs() < 1e-9 && (acc.y - 5.0).abs() < 1e-9);
        // static 2: the sum itself is cropped (onto the edge, replacing it).
        let mut acc = sum_at(3.0, 0.0);
        smartcrop(2.0).apply_post_after(&affine, &mut acc, 0.5, &mut rng);
        assert!((acc.x - 1.0).abs() < 1e-9 && acc.y.abs() < 1e-9);
    }
}
