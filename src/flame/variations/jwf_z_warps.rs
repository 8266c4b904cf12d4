//! JWildfire's shape-driven warps, from the end of its alphabet: `shape_warp` (a rotation,
//! scaling, swirl, fisheye or shear whose strength grows with the distance from a shape's
//! centre measured in that shape's own units: square, rectangle, ellipse, diamond, regular
//! polygons, flower, star or cloud) and `drunken_tiles` (lazyjess-like tiles, each cell's
//! centre moved by its own seeded draws, twisted inside a boundary of twelve shapes) and dark-beam's `bwrands` (bubble wraps whose
//! cells each draw, from a hash of the cell, their size, turn and kind: bubble, loonie or
//! flower) and `glitchy2` (a Möbius map and a turn per quadrant about its own centre, the
//! quadrants' results averaged).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{PI, TAU};

use super::jwf_a_cuts::JavaRandom;

use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("shape_warp", shape_warp)
        .params(&[
            p_range("shape_warp_shape", 0.0, 0.0, 9.0),
            p_range("shape_warp_size", 1.0, 1e-9, INF),
            p_range("shape_warp_aspect", 1.0, 1e-9, INF),
            p("shape_warp_centerX", 0.0),
            p("shape_warp_centerY", 0.0),
            p_range("shape_warp_innerRadius", 0.0, 0.0, INF),
            p("shape_warp_outerRadius", 1.0),
            p_range("shape_warp_warpMode", 0.0, 0.0, 5.0),
            p("shape_warp_warpAmount", PI),
            p("shape_warp_warpAmountX", 1.0),
            p("shape_warp_warpAmountY", 1.0),
            p("shape_warp_warpCenterX", 0.0),
            p("shape_warp_warpCenterY", 0.0),
            p_range("shape_warp_warpCurve", 1.0, 1e-6, INF),
            p("shape_warp_warpInvert", 0.0),
            p_range("shape_warp_flowerPetals", 5.0, 2.0, INF),
            p_range("shape_warp_starPoints", 5.0, 3.0, INF),
            p_range("shape_warp_starDepth", 0.5, 0.0, 1.0),
            p_range("shape_warp_cloudAmplitude", 0.2, 0.0, INF),
            p("shape_warp_cloudFrequency", 5.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_ACC),
    VarDef::new("drunken_tiles", drunken_tiles)
        .params(&[
            p_int("drunken_tiles_seed", 1.0, NEG_INF, INF),
            p_range("drunken_tiles_cellsize", 0.5, 1e-9, INF),
            p_range("drunken_tiles_radius_factor", 1.0, 1e-9, INF),
            p("drunken_tiles_offset_strength", 0.25),
            p_range("drunken_tiles_shape_boundary_type", 0.0, 0.0, 11.0),
            p("drunken_tiles_aspect_ratio", 1.0),
            p_range("drunken_tiles_inner_radius_factor", 0.5, 0.0, 1.0),
            p_range("drunken_tiles_arm_width_factor", 0.3, 0.0, 1.0),
            p("drunken_tiles_spacing", 0.1),
            p("drunken_tiles_inner_twist", 0.0),
            p("drunken_tiles_outer_twist", PI),
            p_range("drunken_tiles_flowerPetals", 5.0, 2.0, INF),
            p_range("drunken_tiles_starPoints", 5.0, 3.0, INF),
            p_range("drunken_tiles_cloudAmplitude", 0.2, 0.0, INF),
            p_range("drunken_tiles_cloudFrequency", 5.0, 1e-6, INF),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("bwrands", bwrands)
        .params(&[
            p("bwrands_cellsize", 1.0),
            p("bwrands_space", 0.0),
            p("bwrands_gain", 1.25),
            p("bwrands_inner_twist", 0.0),
            p("bwrands_outer_twist", 0.0),
            p_int("bwrands_seed", 3210.0, NEG_INF, INF),
            p_range("bwrands_rrot", 1.0, 0.0, 1.0),
            p_range("bwrands_rmin", 0.25, 0.0, 1.0),
            p_range("bwrands_loonie_chance", 0.5, 0.0, 1.0),
            p_range("bwrands_petals_chance", 0.5, 0.0, 1.0),
            p_int("bwrands_minpetals", 3.0, 1.0, 1000.0),
            p_int("bwrands_maxpetals", 20.0, 1.0, 1000.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .prepare(bwrands_prepare),
    VarDef::new("glitchy2", glitchy2)
        .params(&[
            p_int("glitchy2_mode", 0.0, 0.0, 1.0),
            p("glitchy2_lr_spin", 1.0),
            p("glitchy2_lr_x", 0.0),
            p("glitchy2_lr_shiftx", 0.0),
            p("glitchy2_lr_y", 0.0),
            p("glitchy2_lr_shifty", 0.0),
            p("glitchy2_lr_re_a", 0.0),
            p("glitchy2_lr_re_b", 0.0),
            p("glitchy2_lr_re_c", 0.0),
            p("glitchy2_lr_re_d", 1.0),
            p("glitchy2_lr_im_a", 0.0),
            p("glitchy2_lr_im_b", 0.0),
            p("glitchy2_lr_im_c", 0.0),
            p("glitchy2_lr_im_d", 0.0),
            p("glitchy2_ur_spin", -1.0),
            p("glitchy2_ur_x", 0.0),
            p("glitchy2_ur_shiftx", 0.0),
            p("glitchy2_ur_y", 0.0),
            p("glitchy2_ur_shifty", 0.0),
            p("glitchy2_ur_re_a", 0.0),
            p("glitchy2_ur_re_b", 0.0),
            p("glitchy2_ur_re_c", 0.0),
            p("glitchy2_ur_re_d", 1.0),
            p("glitchy2_ur_im_a", 0.0),
            p("glitchy2_ur_im_b", 0.0),
            p("glitchy2_ur_im_c", 0.0),
            p("glitchy2_ur_im_d", 0.0),
            p("glitchy2_ll_spin", -1.0),
            p("glitchy2_ll_x", 0.0),
            p("glitchy2_ll_shiftx", 0.0),
            p("glitchy2_ll_y", 0.0),
            p("glitchy2_ll_shifty", 0.0),
            p("glitchy2_ll_re_a", 0.0),
            p("glitchy2_ll_re_b", 0.0),
            p("glitchy2_ll_re_c", 0.0),
            p("glitchy2_ll_re_d", 1.0),
            p("glitchy2_ll_im_a", 0.0),
            p("glitchy2_ll_im_b", 0.0),
            p("glitchy2_ll_im_c", 0.0),
            p("glitchy2_ll_im_d", 0.0),
            p("glitchy2_ul_spin", 1.0),
            p("glitchy2_ul_x", 0.0),
            p("glitchy2_ul_shiftx", 0.0),
            p("glitchy2_ul_y", 0.0),
            p("glitchy2_ul_shifty", 0.0),
            p("glitchy2_ul_re_a", 0.0),
            p("glitchy2_ul_re_b", 0.0),
            p("glitchy2_ul_re_c", 0.0),
            p("glitchy2_ul_re_d", 1.0),
            p("glitchy2_ul_im_a", 0.0),
            p("glitchy2_ul_im_b", 0.0),
            p("glitchy2_ul_im_c", 0.0),
            p("glitchy2_ul_im_d", 0.0),
        ])
        .flags(flag::JWILDFIRE),
];

/// The distance of a point at radius r, angle a to the edge of a regular polygon of `n`
/// sides and circumradius `big_r`, in units of the edge distance along that angle.
fn polygon_dist(radius: f64, angle: f64, n: f64, big_r: f64) -> f64 {
    if radius < 1e-9 {
        return 0.0;
    }
    let sector = TAU / n;
    let diff = angle % sector - PI / n;
    let edge = big_r * (PI / n).cos() / diff.cos().abs().max(1e-9);
    radius / edge.max(1e-9)
}

/// The normalised distance of (x, y) from the shape's centre (1 on its outline).
fn shape_dist(q: &[f64; 20], x: f64, y: f64) -> f64 {
    let shape = q[0] as i64;
    let size = q[1];
    let aspect = if matches!(shape, 1..=3) { q[2] } else { 1.0 };
    let hw = (size * aspect * 0.5).max(1e-9);
    let hh = (size * 0.5).max(1e-9);
    let big_r = (size * 0.5).max(1e-9);
    let radius = (x * x + y * y).sqrt();
    let mut angle = 0.0;
    if radius > 1e-9 {
        angle = y.atan2(x);
        while angle < 0.0 {
            angle += TAU;
        }
    }
    match shape {
        2 => ((x / hw).powi(2) + (y / hh).powi(2)).sqrt(),
        3 => (x / hw).abs() + (y / hh).abs(),
        4 => polygon_dist(radius, angle, 3.0, big_r),
        5 => polygon_dist(radius, angle, 5.0, big_r),
        6 => polygon_dist(radius, angle, 6.0, big_r),
        7 if radius >= 1e-9 => {
            let petals = q[15].trunc();
            radius / (big_r * (petals * angle).cos().abs()).max(1e-9)
        }
        8 if radius >= 1e-9 => {
            let (k, depth) = (q[16].trunc(), q[17]);
            let inner = big_r * depth;
            let per = PI / k;
            let sector = (angle / per).floor();
            let tn = 2.0 * ((angle - sector * per) / per - 0.5).abs();
            let edge = if (sector as i64) % 2 == 0 {
                inner + (big_r - inner) * (1.0 - tn)
            } else {
                inner + (big_r - inner) * tn
            };
            radius / edge.max(1e-9)
        }
        9 if radius >= 1e-9 => {
            let (amp, freq) = (q[18], q[19]);
            let noise = 0.6 * (freq * angle).sin()
                + 0.3 * (2.1 * freq * angle + 1.23).sin()
                + 0.1 * (4.3 * freq * angle + 4.56).sin();
            radius / (big_r * (1.0 + amp * noise)).max(big_r * 0.1)
        }
        7..=9 => 0.0,
        _ => (x / hw).abs().max((y / hh).abs()),
    }
}

/// shape_warp: the point warped about (warpCenterX, warpCenterY) by `warpMode` (rotation,
/// radial scaling, swirl, x/y scaling, fisheye, shear), the strength growing from 0 at
/// `innerRadius` to full at `outerRadius` of the shape's distance (to the power `warpCurve`,
/// reversed by `warpInvert`); replaces the sum so far.
fn shape_warp(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let q: [f64; 20] = v.params();
    let q = {
        let mut q = q;
        q[0] = q[0].trunc();
        q[7] = q[7].trunc();
        q
    };
    let dist = shape_dist(&q, t.x - q[3], t.y - q[4]);
    let inner = q[5].max(0.0);
    let outer = (inner + 1e-9).max(q[6].max(q[5]));
    let range = outer - inner;
    let mut f = if dist <= inner {
        0.0
    } else if dist >= outer {
        1.0
    } else if range > 1e-9 {
        (dist - inner) / range
    } else {
        1.0
    };
    f = f.powf(q[13].max(1e-6));
    if q[14] >= 0.5 {
        f = 1.0 - f;
    }
    let (ew, ewx, ewy) = (f * q[8], f * q[9], f * q[10]);
    let (cx, cy) = (q[11], q[12]);
    let (rx, ry) = (t.x - cx, t.y - cy);
    let (wx, wy) = match q[7] as i64 {
        0 => {
            let (s, c) = ew.sin_cos();
            (rx * c - ry * s, rx * s + ry * c)
        }
        1 => {
            let k = (1.0 + ew).max(1e-9);
            (rx * k, ry * k)
        }
        2 => {
            let a = ry.atan2(rx) + ew;
            let r = (rx * rx + ry * ry).sqrt();
            (r * a.cos(), r * a.sin())
        }
        3 => (rx * (1.0 + ewx).max(1e-9), ry * (1.0 + ewy).max(1e-9)),
        4 => {
            let a = ry.atan2(rx);
            let r = (rx * rx + ry * ry).sqrt();
            let power = (1.0 - ew).clamp(-5.0, 5.0);
            if r > 1e-9 && (power - 1.0).abs() > 1e-9 {
                let nr = r.powf(power);
                (nr * a.cos(), nr * a.sin())
            } else {
                (rx, ry)
            }
        }
        5 => (rx + ewx * ry, ry + ewy * rx),
        _ => (rx, ry),
    };
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [(wx + cx) * v.w, (wy + cy) * v.w, 0.0]
}

/// Which side of the line through b and c the point a is on (the sign of the cross product).
fn side(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> f64 {
    (a.0 - c.0) * (b.1 - c.1) - (b.0 - c.0) * (a.1 - c.1)
}

/// Is (x, y) inside the polygon of `n` vertices from the top anticlockwise, at radius `ro` on
/// even and `ri` on odd vertices (all edges turning left)?
fn in_star_polygon(x: f64, y: f64, n: usize, ro: f64, ri: f64) -> bool {
    let step = TAU / n as f64;
    let mut v2 = (0.0, ro);
    for i in 0..n {
        let v1 = v2;
        let a = PI / 2.0 + (i + 1) as f64 * step;
        let r = if (i + 1) % 2 == 0 { ro } else { ri };
        v2 = (r * a.cos(), r * a.sin());
        if (v2.0 - v1.0) * (y - v1.1) - (v2.1 - v1.1) * (x - v1.0) < 0.0 {
            return false;
        }
    }
    true
}

/// (x, y) turned by −π/4.
fn rhombus_frame(x: f64, y: f64) -> (f64, f64) {
    let (s, c) = (-PI / 4.0).sin_cos();
    (c * x - s * y, s * x + c * y)
}

/// Is the cell-local point (lx, ly) inside drunken_tiles' boundary of radius r?
fn in_tile(q: &[f64; 15], lx: f64, ly: f64, r: f64) -> bool {
    let d2 = lx * lx + ly * ly;
    let d = d2.sqrt();
    let radial = |edge: &dyn Fn(f64) -> f64, reach: f64| {
        if d > reach {
            false
        } else if d < 1e-9 {
            true
        } else {
            d <= edge(ly.atan2(lx)) + 1e-9
        }
    };
    match q[4].trunc() as i64 {
        1 => lx.abs() <= r && ly.abs() <= r,
        2 => {
            let ry = r / q[5].abs().max(1e-9);
            let (rx2, ry2) = (r * r, ry * ry);
            rx2 > 1e-12 && ry2 > 1e-12 && lx * lx / rx2 + ly * ly / ry2 <= 1.0
        }
        3 => {
            let s32 = 3f64.sqrt() / 2.0;
            let (v1, v2, v3) = ((0.0, r), (r * s32, -r / 2.0), (-r * s32, -r / 2.0));
            let p = (lx, ly);
            let ds = [side(p, v1, v2), side(p, v2, v3), side(p, v3, v1)];
            !(ds.iter().any(|&d| d < 0.0) && ds.iter().any(|&d| d > 0.0))
        }
        4 => {
            let (rx, ry) = rhombus_frame(lx, ly);
            rx.abs() <= r && ry.abs() <= r
        }
        5 => in_star_polygon(lx, ly, 6, r, r),
        6 => in_star_polygon(lx, ly, 10, r, r * q[6].clamp(0.01, 1.0)),
        7 => {
            let arm = r * q[7].clamp(0.01, 1.0);
            (lx.abs() <= arm && ly.abs() <= r) || (lx.abs() <= r && ly.abs() <= arm)
        }
        8 => {
            let ri = r * q[6].clamp(0.0, 0.99);
            d2 >= ri * ri && d2 <= r * r
        }
        9 => {
            let k = q[11].trunc().max(2.0);
            radial(&|a| r * (k * a).cos().abs(), r)
        }
        10 => {
            let k = q[12].trunc().max(3.0);
            let inner = r * q[6].clamp(0.0, 1.0);
            let edge = |a: f64| {
                let a = if a < 0.0 { a + TAU } else { a };
                let per = PI / k;
                let sector = (a / per).floor();
                let tn = 2.0 * ((a - sector * per) / per - 0.5).abs();
                let f = if (sector as i64) % 2 == 0 {
                    1.0 - tn
                } else {
                    tn
                };
                inner + (r - inner) * f
            };
            radial(&edge, r)
        }
        11 => {
            let (amp, freq) = (q[13].max(0.0), q[14].max(1e-6));
            let edge = |a: f64| {
                let noise = 0.6 * (freq * a).sin()
                    + 0.3 * (2.1 * freq * a + 1.23).sin()
                    + 0.1 * (4.3 * freq * a + 4.56).sin();
                r * (1.0 + amp * noise)
            };
            radial(&edge, r * (1.0 + q[13].abs()))
        }
        _ => d2 <= r * r,
    }
}

/// drunken_tiles: the plane cut into square cells of `cellsize`, each cell's centre moved
/// by up to `offset_strength` cells (Java's generator seeded from the seed and the cell);
/// points inside the boundary shape around it are wrapped as lazyjess does, spaced by
/// 1 + `spacing` and twisted from `inner_twist` at the centre to `outer_twist` at the edge.
fn drunken_tiles(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let q: [f64; 15] = v.params();
    let (seed, cs, rf, offset) = (q[0], q[1], q[2], q[3]);
    let r = (cs * 0.5 * rf).abs().max(1e-9);
    let ix = (t.x * (1.0 / cs)).floor() as i32;
    let iy = (t.y * (1.0 / cs)).floor() as i32;
    let cell_seed = (seed as i32) ^ ix.wrapping_mul(31) ^ iy;
    let mut g = JavaRandom::new(cell_seed as i64);
    let ox = (g.next_f64() * 2.0 - 1.0) * offset * cs;
    let oy = (g.next_f64() * 2.0 - 1.0) * offset * cs;
    let cx = (ix as f64 + 0.5) * cs + ox;
    let cy = (iy as f64 + 0.5) * cs + oy;
    let (lx, ly) = (t.x - cx, t.y - cy);
    if !in_tile(&q, lx, ly, r) {
        return [v.w * t.x, v.w * t.y, 0.0];
    }
    let wrap = |u: f64| {
        let u = if u > 1.0 { u - 2.0 } else { u };
        if u < -1.0 { u + 2.0 } else { u }
    };
    let k = 1.0 + q[8];
    let (jx, jy) = (wrap(lx / r) * k * r, wrap(ly / r) * k * r);
    let norm = match q[4].trunc() as i64 {
        1 => (lx.abs().max(ly.abs()) / r).min(1.0),
        4 => {
            let (rx, ry) = rhombus_frame(lx, ly);
            (rx.abs().max(ry.abs()) / r).min(1.0)
        }
        _ => ((lx * lx + ly * ly).sqrt() / r).min(1.0),
    };
    let theta = q[9] * (1.0 - norm) + q[10] * norm;
    let (s, c) = theta.sin_cos();
    [
        v.w * (cx + c * jx - s * jy),
        v.w * (cy + s * jx + c * jy),
        0.0,
    ]
}

/// bwrands' constants: [g2, r², rfactor, the fewest petals, the spread of petals].
fn bwrands_prepare(v: &mut Prepared) {
    let [cellsize, space, gain, _, _, _, _, _, _, _, minp, maxp] = v.params();
    let radius = 0.5 * (cellsize / (1.0 + space * space));
    let g2 = gain * gain / radius + 1.0e-6;
    let mut max_bubble = g2 * radius;
    max_bubble = if max_bubble > 2.0 {
        1.0
    } else {
        max_bubble / (max_bubble * max_bubble / 4.0 + 1.0)
    };
    let derived = [
        g2,
        radius * radius,
        radius / max_bubble,
        minp.min(maxp),
        (maxp - minp).abs(),
    ];
    v.p.extend_from_slice(&derived);
}

/// dark-beam's 16-bit mixes of two cell numbers.
fn bytemix(a: i32, b: i32) -> i32 {
    (a & 0x5A5A) ^ (b & 0xA5A5)
}
fn bytexim(a: i32, b: i32) -> i32 {
    (a & 0xAAAA) ^ (b & 0x5555)
}
fn byteshf(a: i32, b: i32) -> i32 {
    ((a << 8) ^ (b >> 8)) & 0xFFFF
}
fn byteprimes(a: i32, b: i32) -> i32 {
    (a.wrapping_mul(857).wrapping_sub(4) & 0xFF00)
        ^ (b.wrapping_neg().wrapping_mul(977).wrapping_add(8) & 0x00FF)
}

/// bwrands: bubble wraps with a bubble per cell of `cellsize`, each cell's size (down to
/// `rmin`), turn (up to `rrot` turns) and kind drawn from a hash of the cell and the seed: a
/// loonie (odds `loonie_chance`), a flower of minpetals–maxpetals petals (`petals_chance`;
/// filled at random) or a bubble; points outside the bubbles stay where they are.
fn bwrands(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    use std::f64::consts::TAU;
    let [
        cellsize,
        _,
        _,
        inner_twist,
        outer_twist,
        seed,
        rrot,
        rmin,
        loonie,
        petals,
    ] = v.params();
    let [g2, r2, rfactor, petx, pety] = v.derived();
    let (vx, vy) = (t.x, t.y);
    if cellsize.abs() < 1e-300 {
        return [v.w * vx, v.w * vy, 0.0];
    }
    let ix = (vx / cellsize).floor() as i32;
    let iy = (vy / cellsize).floor() as i32;
    let cx = (ix as f64 + 0.5) * cellsize;
    let cy = (iy as f64 + 0.5) * cellsize;
    let mut xx = ix ^ 0xB641;
    let mut yy = iy ^ 0x9D81;
    let mut xy = xx.wrapping_mul(yy).wrapping_add(seed as i32);
    xx &= 0xFFFF;
    yy &= 0xFFFF;
    xy &= 0xFFFF;
    (xx, yy) = (bytemix(xx, yy), bytemix(yy, xx));
    (xx, yy) = (byteshf(xx, xy), byteshf(xy, yy));
    (xx, yy) = (bytexim(xx, yy), bytexim(yy, xx));
    let ssz = rmin + xx as f64 / 65535.0 * (1.0 - rmin);
    let aan = rrot * TAU * yy as f64 / 65535.0;
    (xx, yy) = (byteprimes(xx, yy), byteprimes(yy, xx));
    let mut loonie_chance = -(xx as f64) / 65535.0 + loonie;
    let petals_chance = if loonie_chance < 0.0 {
        loonie_chance + petals
    } else {
        0.0
    };
    let n_petals = if pety == 0.0 {
        petx
    } else {
        petx + ((yy >> 3) % (1 + pety as i32)) as f64
    };
    if loonie_chance <= petals_chance {
        loonie_chance = -1.0;
    }
    let (mut lx, mut ly) = (vx - cx, vy - cy);
    let mut vv2 = ssz * r2;
    let d2 = lx * lx + ly * ly;
    if d2 > vv2 {
        return [v.w * vx, v.w * vy, 0.0];
    }
    if loonie_chance > 0.0 {
        let r = (vv2 / d2 - 1.0).sqrt();
        lx *= r;
        ly *= r;
        vv2 = 1.0;
    } else if petals_chance > 0.0 {
        let f = n_petals / TAU * (PI + ly.atan2(lx));
        let f = ((f - f.trunc()) - 0.5).abs() * 2.0;
        let r = d2.sqrt();
        let k = if rng.f01() < 0.5 * (f + 0.5) {
            (1.0 - r) * (f * 1.1)
        } else {
            (vv2.sqrt() - r * (1.0 - f)) / (r + 1e-300)
        };
        lx *= k;
        ly *= k;
        vv2 = 1.0;
    } else {
        lx *= g2;
        ly *= g2;
        let r = rfactor / ((lx * lx + ly * ly) / (4.0 * ssz) + 1.0);
        lx *= r;
        ly *= r;
        vv2 = ssz.sqrt();
    }
    let r = vv2 * (lx * lx + ly * ly) / r2;
    let theta = inner_twist * (1.0 - r) + outer_twist * r;
    let (s, c) = (theta + aan).sin_cos();
    [
        v.w * (cx + c * lx + s * ly),
        v.w * (cy - s * lx + c * ly),
        0.0,
    ]
}

/// One quadrant of glitchy2 (`q`: spin, x, shiftx, y, shifty, re_a … re_d, im_a … im_d):
/// the weighted turn by spin·π/2 plus (x, y) plus |v|²·u·conj(v) of the Möbius parts u = a·z + b,
/// v = c·z + d; `None` where v is 0 (JWildfire then adds nothing at all).
fn glitchy_quadrant(q: &[f64], t: &VarIn, w: f64) -> Option<(f64, f64)> {
    let (sin, cos) = (q[0] * std::f64::consts::FRAC_PI_2).sin_cos();
    let [re_a, re_b, re_c, re_d, im_a, im_b, im_c, im_d] = q[5..13].try_into().expect("8 values");
    let re_u = re_a * t.x - im_a * t.y + re_b;
    let im_u = re_a * t.y + im_a * t.x + im_b;
    let re_v = re_c * t.x - im_c * t.y + re_d;
    let im_v = re_c * t.y + im_c * t.x + im_d;
    let d = re_v * re_v + im_v * im_v;
    if d == 0.0 {
        return None;
    }
    Some((
        w * (sin * t.y + cos * t.x) + q[1] + d * (re_u * re_v + im_u * im_v),
        w * (cos * t.y - sin * t.x) + q[3] + d * (im_u * re_v - re_u * im_v),
    ))
}

/// glitchy2 (Brad Stefanov and Rick Sidwell, after guagapunyaimel's "fourth"): each of the
/// four quadrants about its own (shiftx, shifty) that holds the point adds its map
/// ([`glitchy_quadrant`]); the average is the output (mode 0) or its swapped reciprocal
/// (mode 1); a point in no quadrant passes (or is inverted) unchanged.
fn glitchy2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let q: [f64; 53] = v.params();
    let (mode, w) = (q[0], v.w);
    let (mut x, mut y, mut count) = (0.0, 0.0, 0.0);
    for (k, (right, below)) in [(true, true), (true, false), (false, true), (false, false)]
        .into_iter()
        .enumerate()
    {
        let qq = &q[1 + 13 * k..14 + 13 * k];
        let (sx, sy) = (qq[2], qq[4]);
        let in_x = if right { t.x > sx } else { t.x < sx };
        let in_y = if below { t.y > sy } else { t.y < sy };
        if in_x && in_y {
            let Some((dx, dy)) = glitchy_quadrant(qq, t, w) else {
                return [0.0; 3];
            };
            x += dx;
            y += dy;
            count += 1.0;
        }
    }
    match (mode != 0.0, count == 0.0) {
        (true, true) => [w / t.y, w / t.x, 0.0],
        (true, false) => [w / y / count, w / x / count, 0.0],
        (false, true) => [w * t.x, w * t.y, 0.0],
        (false, false) => [w * x / count, w * y / count, 0.0],
    }
}
