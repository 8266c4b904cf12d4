//! Polar and radial warps from Fractorium's catalogue: spiral twists (`swirl3`, `swirl3r`),
//! target rings, disc and wedge maps, kaleidoscopes, the square-to-circle maps, polygon
//! reshaping (`smartshape`, `scry2`), the shape-profile family `w`, `x`, `y`, `z`, and
//! panoramas.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, FRAC_PI_4, PI, SQRT_2, TAU};

use super::util::{floor_f, sqr, square_arc, square_point, trunc_i32, zeps};
use super::*;
use crate::flame::fastmath;
use crate::flame::fastmath::FastTrig;

/// The thirteen shape parameters of the w/x/y/z family, `PREFIX_hypergon` … `PREFIX_super_n3`,
/// after any leading ones given. Fractorium keeps the star slope below π/2 and n3 at 1 by
/// default; the `jwildfire` form takes the slope as it stands and n3 at 0, as JWildfire does.
macro_rules! shape_params {
    (jwildfire $pre:literal $(, $lead:expr)*) => {
        $crate::flame::variations::fr_radial::shape_params!(@ $pre, p(concat!($pre, "_star_slope"), 2.0), 0.0 $(, $lead)*)
    };
    ($pre:literal $(, $lead:expr)*) => {
        $crate::flame::variations::fr_radial::shape_params!(
            @ $pre,
            p_range(concat!($pre, "_star_slope"), 2.0, f64::EPSILON, ::std::f64::consts::FRAC_PI_2),
            1.0
            $(, $lead)*
        )
    };
    (@ $pre:literal, $slope:expr, $n3:expr $(, $lead:expr)*) => {
        &[
            $($lead,)*
            p(concat!($pre, "_hypergon"), 0.0),
            p_int(concat!($pre, "_hypergon_n"), 4.0, 3.0, f64::INFINITY),
            p(concat!($pre, "_hypergon_r"), 1.0),
            p(concat!($pre, "_star"), 0.0),
            p_int(concat!($pre, "_star_n"), 5.0, 3.0, f64::INFINITY),
            $slope,
            p(concat!($pre, "_lituus"), 0.0),
            p(concat!($pre, "_lituus_a"), 1.0),
            p(concat!($pre, "_super"), 0.0),
            p(concat!($pre, "_super_m"), 1.0),
            p(concat!($pre, "_super_n1"), 1.0),
            p(concat!($pre, "_super_n2"), 1.0),
            p(concat!($pre, "_super_n3"), $n3),
        ]
    };
}
pub(super) use shape_params;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("cardioid", cardioid)
        .params(&[p("cardioid_a", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES | need::ATAN_YX),
    super::inlined!("circlize", circlize).params(&[p("circlize_hole", 0.0)]),
    super::inlined!("circlize2", circlize2).params(&[p("circlize2_hole", 0.0)]),
    super::inlined!("circus", circus)
        .params(&[p("circus_scale", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES),
    super::inlined!("collideoscope", collideoscope)
        .params(&[p("collideoscope_a", 0.0), p("collideoscope_num", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(prep_collideoscope),
    super::inlined!("curvature", curvature).needs(need::SUMSQ | need::SQRT | need::ATAN_YX),
    super::inlined!("epispiral", epispiral)
        .params(&[
            p("epispiral_n", 6.0),
            p("epispiral_thickness", 0.0),
            p("epispiral_holes", 1.0),
        ])
        .needs(need::ATAN_YX)
        .flags(flag::RANDOM)
        .prepare(epispiral_prepare),
    super::inlined!("fdisc", fdisc).needs(need::SQRT | need::ATAN_YX),
    super::inlined!("flowerdb", flowerdb)
        .params(&[
            p("flowerdb_petals", 6.0),
            p("flowerdb_petal_split", 0.0),
            p("flowerdb_petal_spread", 1.0),
        ])
        .needs(need::SQRT | need::ATAN_YX)
        .prepare(flowerdb_prepare),
    super::inlined!("hole", hole)
        .params(&[p("hole_a", 1.0), p_int("hole_inside", 0.0, 0.0, 1.0)])
        .needs(need::SQRT | need::ANGLES | need::ATAN_YX),
    super::inlined!("idisc", idisc).needs(need::SQRT | need::ATAN_YX),
    super::inlined!("Kaleidoscope", kaleidoscope)
        .params(&[
            p("Kaleidoscope_pull", 0.0),
            p("Kaleidoscope_rotate", 1.0),
            p("Kaleidoscope_line_up", 1.0),
            p("Kaleidoscope_x", 0.0),
            p("Kaleidoscope_y", 0.0),
        ])
        .prepare(prep_kaleidoscope),
    super::inlined!("lazyjess", lazyjess)
        .params(&[
            p_nonzero("lazyjess_n", 4.0, 2.0, INF),
            p("lazyjess_spin", PI),
            p("lazyjess_space", 0.0),
            p("lazyjess_corner", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .prepare(prep_lazyjess),
    super::inlined!("lazyTravis", lazytravis)
        .params(&[
            p_cyclic("lazyTravis_spin_in", 1.0, 0.0, 2.0),
            p_cyclic("lazyTravis_spin_out", 0.0, 0.0, 2.0),
            p("lazyTravis_space", 0.0),
        ])
        .prepare(prep_lazytravis),
    VarDef::new("panorama1", panorama::<false>).needs(need::SUMSQ),
    VarDef::new("panorama2", panorama::<true>).needs(need::SUMSQ | need::SQRT),
    super::inlined!("scry2", scry2)
        .params(&[p("scry2_power", 4.0)])
        .needs(need::SUMSQ)
        .prepare(scry2_prep),
    super::inlined!("shredrad", shredrad)
        .params(&[
            p_nonzero("shredrad_n", 4.0, -INF, INF),
            p_range("shredrad_width", 0.5, -1.0, 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(shredrad_prep),
    super::inlined!("smartshape", smartshape)
        .params(&[
            p_range("smartshape_power", 4.0, 2.0, INF),
            p("smartshape_roundstr", 0.0),
            p("smartshape_roundwidth", 1.0),
            p("smartshape_distortion", 1.0),
            p_range("smartshape_compensation", 0.0, 0.0, 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(smartshape_prep),
    super::inlined!("squarize", squarize).needs(need::SUMSQ | need::SQRT | need::ATAN_YX),
    super::inlined!("squish", squish)
        .params(&[p_nonzero("squish_power", 2.0, 2.0, INF)])
        .flags(flag::RANDOM)
        .prepare(squish_prep),
    super::inlined!("swirl3", swirl3)
        .params(&[p("swirl3_shift", 0.5)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX),
    super::inlined!("swirl3r", swirl3r)
        .params(&[
            p("swirl3r_shift", 0.5),
            p_range("swirl3r_min", 0.5, 0.0, f64::INFINITY),
            p_range("swirl3r_max", 1.0, 0.0, f64::INFINITY),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(swirl3r_prep),
    super::inlined!("target", target)
        .params(&[
            p_cyclic("target_even", 0.0, 0.0, TAU),
            p_cyclic("target_odd", 0.0, 0.0, TAU),
            p_range("target_size", 1.0, f64::EPSILON, f64::INFINITY),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(target_prep),
    super::inlined!("target0", target0)
        .params(&[
            p_cyclic("target0_even", 0.0, 0.0, TAU),
            p_cyclic("target0_odd", 0.0, 0.0, TAU),
            p_range("target0_size", 0.0, 0.0, f64::INFINITY),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(target_prep),
    super::inlined!("target2", target2)
        .params(&[
            p_cyclic("target2_even", 0.0, 0.0, TAU),
            p_cyclic("target2_odd", 0.0, 0.0, TAU),
            p_range("target2_size", 1.0, f64::EPSILON, f64::INFINITY),
            p("target2_thightness", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(target_prep),
    super::inlined!("unpolar", unpolar).prepare(unpolar_prep),
    super::inlined!("w", w_var)
        .params(SHAPE_W)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(shape_prep_w),
    super::inlined!("wdisc", wdisc).needs(need::SUMSQ | need::SQRT | need::ATAN_YX),
    super::inlined!("x", x_var)
        .params(SHAPE_X)
        .needs(need::SUMSQ | need::ATAN_YX)
        .prepare(shape_prep),
    super::inlined!("y", y_var)
        .params(SHAPE_Y)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(shape_prep),
    super::inlined!("z", z_var)
        .params(SHAPE_Z)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .prepare(shape_prep),
];

/// Cardioid-like radial warp: r ← √(r² + sin(a·θ) + 1), angle kept.
#[inline(always)]
fn cardioid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a] = v.params();
    let r = v.w * (t.sumsq + (t.atan_yx * a).fsin() + 1.0).sqrt();
    [r * t.ux, r * t.uy, 0.0]
}

/// Squares to circles: the square of half-side s becomes the circle of radius (4w/π)·s + hole,
/// the position along the square's perimeter becoming the angle.
#[inline(always)]
fn circlize(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [hole] = v.params();
    let (side, per) = square_arc(t.x, t.y);
    let r = v.w / FRAC_PI_4 * side + hole;
    let (s, c) = (FRAC_PI_4 * per / side - FRAC_PI_4).fsin_cos();
    [r * c, r * s, 0.0]
}

/// `circlize` with the hole inside the weight: radius w·(s + hole).
#[inline(always)]
fn circlize2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [hole] = v.params();
    let (side, per) = square_arc(t.x, t.y);
    let r = v.w * (side + hole);
    let (s, c) = (FRAC_PI_4 * per / side - FRAC_PI_4).fsin_cos();
    [r * c, r * s, 0.0]
}

/// Radial scaling by `scale` inside the unit circle and by 1/scale outside it.
#[inline(always)]
fn circus(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [scale] = v.params();
    let r = if t.sqrt <= 1.0 {
        t.sqrt * scale
    } else {
        t.sqrt * (1.0 / scale)
    };
    [v.w * r * t.ux, v.w * r * t.uy, 0.0]
}

/// Derived values: num/π, π/num, π·a/num (num replaced by ε when 0).
fn prep_collideoscope(v: &mut Prepared) {
    let [a, num] = v.params();
    let num = zeps(num);
    v.p.push(num * FRAC_1_PI);
    v.p.push(PI / num);
    v.p.push(PI * a / num);
}

/// Kaleidoscope of `num` sectors per half-turn: alternate sectors are rotated by ±πa/num
/// (modulo the sector), mirrored between the upper and lower half-planes.
#[inline(always)]
fn collideoscope(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [n_pi, pi_n, a_n] = v.derived();
    let a = t.atan_yx;
    let r = v.w * t.sqrt;
    let a = if a >= 0.0 {
        let sector = trunc_i32(a * n_pi);
        let shift = if sector & 1 == 0 { a_n } else { -a_n };
        sector as f64 * pi_n + (shift + a) % pi_n
    } else {
        let sector = trunc_i32(-a * n_pi);
        let shift = if sector & 1 == 1 { -a_n } else { a_n };
        -(sector as f64 * pi_n + (shift - a) % pi_n)
    };
    [r * a.fcos(), r * a.fsin(), 0.0]
}

/// Maps the point to (weight / r, angle): unweighted polar angle on y.
#[inline(always)]
fn curvature(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w / zeps(t.sqrt), t.atan_yx, 0.0]
}

fn epispiral_prepare(v: &mut Prepared) {
    let [_, thick, holes] = v.params();
    v.p.extend_from_slice(&[thick * v.w, holes * v.w]);
}

/// Maps the point's direction θ onto the epispiral r = 1/cos(nθ), shifted by `holes` and
/// randomly thickened.
#[inline(always)]
fn epispiral(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n] = v.params();
    let [thick_w, holes_w] = v.derived();
    let theta = t.atan_yx;
    let num = if thick_w == 0.0 {
        v.w
    } else {
        thick_w * rng.f01()
    };
    let r = num / (n * theta).fcos() - holes_w;
    if r.abs() != 0.0 {
        let (s, c) = theta.fsin_cos();
        [r * c, r * s, 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// A disc folded the other way: the distance from the origin picks the angle 2π/(r+1) and the
/// polar angle picks the radius (from 0 at angle −π to 1 at π).
#[inline(always)]
fn fdisc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let ang = TAU / (t.sqrt + 1.0);
    let rad = (t.atan_yx * FRAC_1_PI + 1.0) * 0.5;
    let (s, c) = ang.fsin_cos();
    [v.w * rad * c, v.w * rad * s, 0.0]
}

fn flowerdb_prepare(v: &mut Prepared) {
    let [petals, petal_split] = v.params();
    let split_petals = petals * petal_split;
    v.p.push(split_petals);
}

/// A rose: the radius is scaled by |(spread + sin(petals·θ))·cos(petals·split·θ)|, giving
/// `petals` lobes, each split in two when `split` is non-zero.
#[inline(always)]
fn flowerdb(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [petals, _, spread] = v.params();
    let [split_petals] = v.derived();
    let th = t.atan_yx;
    let rad = v.w * t.sqrt;
    let petal = fastmath::sin_cos_any(petals * th).0;
    let split = fastmath::sin_cos_any(split_petals * th).1;
    let r2 = rad * ((spread + petal) * split).abs();
    let (s, c) = fastmath::sin_cos(th);
    [r2 * c, r2 * s, 0.0]
}

/// Opens a hole at the origin whose size varies with the polar angle (power `a`); with
/// `inside` the plane is squeezed into the hole instead.
#[inline(always)]
fn hole(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, inside] = v.params();
    let delta = (t.atan_yx / PI + 1.0).powf(a);
    let r = if inside != 0.0 {
        v.w * delta / (t.sqrt + delta)
    } else {
        v.w * t.sqrt + delta
    };
    [r * t.ux, r * t.uy, 0.0]
}

/// An inverted disc: the angle is π/(r + 1), the radius the polar angle over π.
#[inline(always)]
fn idisc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (s, c) = (PI / (t.sqrt + 1.0)).fsin_cos();
    let r = t.atan_yx * (v.w * FRAC_1_PI);
    [r * c, r * s, 0.0]
}

fn prep_kaleidoscope(v: &mut Prepared) {
    // 45° in radians as Fractorium forms it; its sine and cosine differ in the last bit.
    let quarter = 45.0 * (PI / 180.0);
    v.p.push(quarter.fsin());
    v.p.push(quarter.fcos());
}

/// Kaleidoscope: rotates the plane by 45° (scaling by `rotate`) and splits it along y = 0, the
/// two halves being pushed apart by `pull` and shifted by `line_up`; the weight is not used.
#[inline(always)]
fn kaleidoscope(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [s45, c45] = v.derived();
    kaleidoscope_turned(v, t, s45, c45)
}

/// [`kaleidoscope`] with the sine and cosine of its turn given (the programs form the angle
/// differently).
pub(super) fn kaleidoscope_turned(v: &Prepared, t: &VarIn, s45: f64, c45: f64) -> V3 {
    let [pull, rotate, line_up, sx, sy] = v.params();
    let x = ((rotate * t.x) * c45 - t.y * s45 + line_up) + sx;
    let y = if t.y > 0.0 {
        ((rotate * t.y) * c45 + t.x * s45 + pull + line_up) + sy
    } else {
        (rotate * t.y) * c45 + t.x * s45 - pull - line_up
    };
    [x, y, 0.0]
}

fn prep_lazyjess(v: &mut Prepared) {
    let [n, _, _, corner] = v.params();
    let vertex = PI * (n - 2.0) / zeps(2.0 * n);
    let slice = TAU / zeps(n);
    v.p.extend_from_slice(&[
        vertex,
        vertex.fsin(),
        slice,
        slice / 2.0,
        (corner - 1.0) * slice,
    ]);
}

/// lazyjess: inside a regular n-gon (of circumradius tied to the weight) points are spun by
/// `spin`; spun corners that leave the polygon are mirrored back; outside points are pushed out
/// by `space`.
#[inline(always)]
fn lazyjess(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [n, spin, space] = v.params();
    let [vertex, sin_vertex, slice, half_slice, corner_turn] = v.derived();
    let w = v.w;
    let (x, y) = (t.x, t.y);
    let m = t.sqrt;
    let push_out = || {
        let k = 1.0 + space / zeps(m);
        [w * k * x, w * k * y, 0.0]
    };
    // Distance from the centre to the polygon's edge in direction `ang` (ang includes +2π).
    let edge_at = |ang: f64| {
        let off = (ang + half_slice) % slice;
        w * SQRT_2 * sin_vertex / zeps((PI - off - vertex).fsin())
    };
    if n == 2.0 {
        if x.abs() < w {
            let ang = y.atan2(x) + spin;
            let (rx, ry) = (w * m * ang.fcos(), w * m * ang.fsin());
            if rx.abs() < w {
                return [rx, ry, 0.0];
            }
            // A spun corner that left the band is mirrored back into place.
            let back = ry.atan2(rx) - spin + corner_turn;
            return [w * m * back.fcos(), -(w * m * back.fsin()), 0.0];
        }
        return push_out();
    }
    if m < edge_at(y.atan2(x) + TAU) {
        let ang = y.atan2(x) + spin + TAU;
        let (rx, ry) = (w * m * ang.fcos(), w * m * ang.fsin());
        let m2 = (rx * rx + ry * ry).sqrt();
        if m2 < edge_at(ang) {
            return [rx, ry, 0.0];
        }
        let back = ry.atan2(rx) - spin + corner_turn + TAU;
        return [w * m2 * back.fcos(), -(w * m2 * back.fsin()), 0.0];
    }
    push_out()
}

fn prep_lazytravis(v: &mut Prepared) {
    let [spin_in, spin_out] = v.params();
    v.p.push(4.0 * spin_in);
    v.p.push(4.0 * spin_out);
}

/// lazyTravis: each point's square ring (max(|x|, |y|)) is treated as a loop of perimeter 8s
/// and the point is slid along it (by `spin_in` inside the weight square, `spin_out` outside,
/// where the rings are also spaced out by `space`).
#[inline(always)]
fn lazytravis(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [_, _, space] = v.params();
    let [turn_in, turn_out] = v.derived();
    let w = v.w;
    let (ax, ay) = (t.x.abs(), t.y.abs());
    let outside = ax > w || ay > w;
    let turn = if outside { turn_out } else { turn_in };
    let (s, pos) = if ax > ay {
        let base = if t.x > 0.0 { ax + t.y } else { 5.0 * ax - t.y };
        (ax, base + ax * turn)
    } else {
        let base = if t.y > 0.0 {
            3.0 * ay - t.x
        } else {
            7.0 * ay + t.x
        };
        (ay, base + ay * turn)
    };
    let pos = pos % (s * 8.0);
    if outside {
        let widen = |u: f64| u + u / s * space;
        let (x2, y2) = if pos <= 2.0 * s {
            (s + space, widen(-(s - pos)))
        } else if pos <= 4.0 * s {
            (widen(3.0 * s - pos), s + space)
        } else if pos <= 6.0 * s {
            (-(s + space), widen(5.0 * s - pos))
        } else {
            (widen(-(7.0 * s - pos)), -(s + space))
        };
        [w * x2, w * y2, 0.0]
    } else if pos <= 2.0 * s {
        [w * s, -(w * (s - pos)), 0.0]
    } else if pos <= 4.0 * s {
        [w * (3.0 * s - pos), w * s, 0.0]
    } else if pos <= 6.0 * s {
        [-(w * s), w * (5.0 * s - pos), 0.0]
    } else {
        [-(w * (7.0 * s - pos)), -(w * s), 0.0]
    }
}

/// panorama1 / panorama2: squeeze the plane into the unit disc (by 1/√(r² + 1), or 1/(r + 1)
/// for panorama2) and unroll the disc into a strip: angle along x, radius along y.
fn panorama<const LINEAR: bool>(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let k = if LINEAR {
        1.0 / (t.sqrt + 1.0)
    } else {
        1.0 / (t.sumsq + 1.0).sqrt()
    };
    let (x1, y1) = (t.x * k, t.y * k);
    let rr = (x1 * x1 + y1 * y1).sqrt();
    [v.w * x1.atan2(y1) * FRAC_1_PI, v.w * (rr - 0.5), 0.0]
}

/// Shared by scry2 and smartshape: the angular part of a "polygon" map. Splits the angle into
/// `2π/alpha` sectors; returns the folded position in the sector (0 at an edge midpoint, up to
/// 1/2 at a corner) as (sector index rounded to the nearest edge, sign, offset).
#[inline(always)]
fn polygon_sector(dang: f64) -> (f64, f64, f64) {
    let whole = floor_f(dang);
    let frac = dang - whole;
    if frac > 0.5 {
        (whole + 1.0, -1.0, 1.0 - frac)
    } else {
        (whole, 1.0, frac)
    }
}

/// scry's inversion followed by a map that turns circles into regular polygons with `power`
/// sides.
#[inline(always)]
fn scry2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [alpha, half_tan2] = v.derived();
    let r2 = t.sumsq;
    let s = 1.0 / zeps(r2.sqrt() * (r2 + 1.0));
    let (nx, ny) = (t.x * s, t.y * s);
    let dang = (ny.atan2(nx) + PI) / alpha;
    let rad = (nx * nx + ny * ny).sqrt();
    let (sector, sign, off) = polygon_sector(dang);
    let xang = (off * half_tan2).atan() / alpha;
    let coeff = 1.0 / (xang * alpha).fcos();
    let ang = (sector + sign * xang) * alpha - PI;
    let k = v.w * coeff * rad;
    [k * ang.fcos(), k * ang.fsin(), 0.0]
}

fn scry2_prep(v: &mut Prepared) {
    let [power] = v.params();
    let alpha = TAU / zeps(power);
    v.p.extend([alpha, (alpha * 0.5).tan() * 2.0]);
}

/// Shreds the plane into `n` angular wedges, each squeezed to `width` of its angle, leaving
/// empty spokes between them; z is scaled.
#[inline(always)]
fn shredrad(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, width] = v.params();
    let [alpha] = v.derived();
    let a = (t.atan_yx + 3.0 * PI + alpha / 2.0) / alpha;
    let i = trunc_i32(a) as f64;
    let ang = ((a - i) * width + i) * alpha - PI - alpha / 2.0 * width;
    let k = v.w * t.sqrt;
    [k * ang.fcos(), k * ang.fsin(), v.w * t.z]
}

fn shredrad_prep(v: &mut Prepared) {
    let [n] = v.params();
    let alpha = TAU / n;
    v.p.push(alpha);
}

/// Turns circles around the origin into regular polygons with `power` sides; corners can be
/// rounded (`roundstr`, `roundwidth`), the effect strengthened or inverted (`distortion`), and
/// the angular spacing compensated.
#[inline(always)]
fn smartshape(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, roundstr, roundwidth, distortion] = v.params();
    let [alpha, alpha_coeff, round_coeff, comp] = v.derived();
    let dang = (t.atan_yx + PI) / alpha;
    let (sector, sign, off) = polygon_sector(dang);
    let xang = if comp == 1.0 && distortion >= 1.0 {
        (off * alpha_coeff).atan() / alpha
    } else {
        off
    };
    let base = if distortion == 0.0 {
        1.0
    } else {
        let c0 = 1.0 / (xang * alpha).fcos();
        if roundstr != 0.0 {
            let ww = if roundwidth != 1.0 {
                ((xang * 2.0).ln() * roundwidth).exp() * round_coeff
            } else {
                xang * 2.0 * round_coeff
            };
            ((1.0 - ww) * c0 + ww).abs()
        } else {
            c0
        }
    };
    let coeff = if distortion != 1.0 {
        (base.ln() * distortion).exp()
    } else {
        base
    };
    let ang = (sector + sign * xang) * alpha - PI;
    let k = v.w * coeff * t.sqrt;
    [ang.fcos() * k, ang.fsin() * k, 0.0]
}

fn smartshape_prep(v: &mut Prepared) {
    let [power, roundstr, _, _, compensation] = v.params();
    let power = power.max(2.0);
    v.p[0] = power;
    let alpha = TAU / power;
    let alpha_coeff = (alpha * 0.5).tan() * 2.0;
    let round_coeff = roundstr / (alpha * 0.5).fsin() / power * 2.0;
    let comp = if compensation <= 0.0 { 0.0 } else { 1.0 };
    v.p.extend([alpha, alpha_coeff, round_coeff, comp]);
}

/// Maps the plane onto squares: the circle of radius r becomes the square of half-side r, the
/// angle becoming the arc length along its boundary.
#[inline(always)]
fn squarize(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let r = t.sqrt;
    let a = if t.atan_yx < 0.0 {
        t.atan_yx + TAU
    } else {
        t.atan_yx
    };
    let p = 4.0 * r * a * FRAC_1_PI;
    square_point(v.w, r, p, true)
}

/// Squares are squished into a random one of `power` portions of the square ring they lie on:
/// the arc length along the square boundary is divided by `power` and shifted by a random
/// number of full turns.
#[inline(always)]
fn squish(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let [inv] = v.derived();
    let (ax, ay) = (t.x.abs(), t.y.abs());
    let (s, p) = if ax > ay {
        (ax, if t.x > 0.0 { t.y } else { 4.0 * ax - t.y })
    } else {
        (
            ay,
            if t.y > 0.0 {
                2.0 * ay - t.x
            } else {
                6.0 * ay + t.x
            },
        )
    };
    let p = inv * (p + 8.0 * s * floor_f(power * rng.f01()));
    square_point(v.w, s, p, false)
}

fn squish_prep(v: &mut Prepared) {
    let [power] = v.params();
    let inv = 1.0 / power;
    v.p.push(inv);
}

/// swirl3: a logarithmic spiral twist — each point turns by `shift`·ln r.
#[inline(always)]
fn swirl3(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [shift] = v.params();
    let r = t.sqrt;
    let ang = t.atan_yx + r.ln() * shift;
    [v.w * r * ang.fcos(), v.w * r * ang.fsin(), 0.0]
}

/// Derived values of swirl3r: the ordered radius band and the twists at its two edges.
fn swirl3r_prep(v: &mut Prepared) {
    let [shift, a, b] = v.params();
    let lo = a.min(b);
    let hi = a.max(b);
    let twist_lo = if lo > 0.0 { lo.ln() * shift } else { 0.0 };
    let twist_hi = if hi > 0.0 { hi.ln() * shift } else { 0.0 };
    v.p.extend_from_slice(&[lo, hi, twist_lo, twist_hi]);
}

/// swirl3r: swirl3's logarithmic twist restricted to a radius band; inside and outside the
/// band the twist stays at its value on the nearer edge (rigid rotation).
#[inline(always)]
fn swirl3r(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [shift] = v.params();
    let [lo, hi, twist_lo, twist_hi] = v.derived();
    let r = t.sqrt;
    let ang = if r < lo {
        t.atan_yx + twist_lo
    } else if r > hi {
        t.atan_yx + twist_hi
    } else {
        t.atan_yx + r.ln() * shift
    };
    [v.w * r * ang.fcos(), v.w * r * ang.fsin(), 0.0]
}

/// Derived value of the target family: half the ring width.
fn target_prep(v: &mut Prepared) {
    let [_, _, size] = v.params();
    let half = size * 0.5;
    v.p.push(half);
}

/// The angle of a target variation: alternate rings (of width `size`/2 in log r or in the
/// given ring coordinate `t`) are rotated by `even` and `odd`.
#[inline(always)]
fn target_angle(a: f64, t: f64, v: &Prepared) -> f64 {
    let [even, odd, size] = v.params();
    let [half] = v.derived();
    let mut s = t;
    if s < 0.0 {
        s -= half;
    }
    s = s.abs() % size;
    if s < half { a + even } else { a + odd }
}

/// target: concentric rings of equal width in log r, alternately rotated by two angles
/// (Fractorium's version ignores the weight).
#[inline(always)]
fn target(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = target_angle(t.atan_yx, t.sqrt.ln(), v);
    [t.sqrt * a.fcos(), t.sqrt * a.fsin(), 0.0]
}

/// target0: target, weighted.
#[inline(always)]
fn target0(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = target_angle(t.atan_yx, t.sqrt.ln(), v);
    [t.sqrt * a.fcos() * v.w, t.sqrt * a.fsin() * v.w, 0.0]
}

/// target2: target with spiral rings — the ring coordinate also grows with the angle, and
/// `thightness` scales log r.
#[inline(always)]
fn target2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, tightness] = v.params();
    let a = t.atan_yx;
    let ring = tightness * t.sqrt.ln() + FRAC_1_PI * (a + PI);
    let a = target_angle(a, ring, v);
    [t.sqrt * a.fcos() * v.w, t.sqrt * a.fsin() * v.w, 0.0]
}

/// Derived value of unpolar: weight/(2π).
fn unpolar_prep(v: &mut Prepared) {
    let k = (v.w / PI) * 0.5;
    v.p.push(k);
}

/// unpolar: the inverse of polar — x read as an angle and y as log-radius.
#[inline(always)]
fn unpolar(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [k] = v.derived();
    let r = t.y.exp();
    let (s, c) = t.x.fsin_cos();
    [k * r * s, k * r * c, 0.0]
}

/// The 13 parameters of a shape profile: for the hypergon, the star, the lituus and the
/// superformula curve, each curve's amount and settings.
type ShapeParams = [f64; 13];

/// The values derived from a shape profile's parameters: hypergon D, −a of the lituus, tan of
/// the star slope, m/4 and −1/n1 of the superformula.
fn shape_derived(shape: &ShapeParams) -> [f64; 5] {
    let [
        _,
        _,
        hypergon_r,
        _,
        _,
        slope,
        _,
        lituus_a,
        _,
        super_m,
        super_n1,
        _,
        _,
    ] = *shape;
    let hyper_d = (1.0 + sqr(hypergon_r)).sqrt();
    let lituus_exp = -lituus_a;
    // tan(π/2) is infinite: an almost-vertical slope backs off by 0.05 rad.
    let tan_slope = if (slope - FRAC_PI_2).abs() < 1e-6 {
        (slope - 0.05).tan()
    } else {
        slope.tan()
    };
    let super_m4 = super_m / 4.0;
    let super_exp = -1.0 / zeps(super_n1);
    [hyper_d, lituus_exp, tan_slope, super_m4, super_exp]
}

/// Derived values of x, y and z (see [`shape_derived`]).
pub(super) fn shape_prep(v: &mut Prepared) {
    let shape = v.params();
    v.p.extend(shape_derived(&shape));
}

/// Derived values of w, whose shape parameters follow its angle (see [`shape_derived`]).
pub(super) fn shape_prep_w(v: &mut Prepared) {
    let [_angle, shape @ ..] = v.params::<14>();
    v.p.extend(shape_derived(&shape));
}

/// The radius profile at angle `a` of the shape with parameters `shape` and derived values
/// `derived`.
fn shape_total(shape: &ShapeParams, derived: [f64; 5], a: f64) -> f64 {
    let [
        hypergon,
        hypergon_n,
        _,
        star,
        star_n,
        _,
        lituus,
        _,
        super_,
        _,
        _,
        super_n2,
        super_n3,
    ] = *shape;
    let [hyper_d, lituus_exp, tan_slope, super_m4, super_exp] = derived;
    let mut sum = 0.0;
    if hypergon != 0.0 {
        let n = hypergon_n;
        let s = (a.abs() % (TAU / n)) - PI / n;
        let sec2 = sqr(s.tan()) + 1.0;
        let d2 = sqr(hyper_d);
        if sec2 >= d2 {
            sum += hypergon;
        } else {
            sum += hypergon * (hyper_d - (d2 - sec2).sqrt()) / sec2.sqrt();
        }
    }
    if star != 0.0 {
        let n = star_n;
        let tn = ((a.abs() % (TAU / n)) - PI / n).abs().tan();
        sum += star * (sqr(tan_slope) * (1.0 + sqr(tn)) / sqr(tn + tan_slope)).sqrt();
    }
    if lituus != 0.0 {
        sum += lituus * (a / PI + 1.0).abs().powf(lituus_exp);
    }
    if super_ != 0.0 {
        let (s, c) = (a * super_m4).fsin_cos();
        sum += super_ * (c.abs().powf(super_n2) + s.abs().powf(super_n3)).powf(super_exp);
    }
    sum
}

/// w: points inside the shape profile (the profile at their own angle) are rotated by
/// `w_angle` and rescaled to the profile at the new angle; points outside pass through.
#[inline(always)]
pub(super) fn w_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [angle, shape @ ..] = v.params::<14>();
    let d = v.derived();
    let a = t.atan_yx;
    let r = t.sqrt;
    let mut turned = a + angle;
    if turned < -PI {
        turned += TAU;
    }
    if turned > PI {
        turned -= TAU;
    }
    let reach = shape_total(&shape, d, a);
    if r <= reach {
        let reach2 = shape_total(&shape, d, turned);
        let r = v.w * reach2 * r / reach;
        let (s, c) = turned.fsin_cos();
        [r * c, r * s, 0.0]
    } else {
        [v.w * t.x, v.w * t.y, 0.0]
    }
}

/// x: the radius pushed out to √(r² + profile²) along each ray.
#[inline(always)]
pub(super) fn x_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = t.atan_yx;
    let reach = shape_total(&v.params(), v.derived(), a);
    let r = v.w * (t.sumsq + sqr(reach)).sqrt();
    let (s, c) = a.fsin_cos();
    [r * c, r * s, 0.0]
}

/// y: inversion in the shape profile — radius profile²/r along each ray.
#[inline(always)]
pub(super) fn y_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = t.atan_yx;
    let reach = shape_total(&v.params(), v.derived(), a);
    let r = v.w * sqr(reach) / t.sqrt;
    let (s, c) = a.fsin_cos();
    [r * c, r * s, 0.0]
}

/// z: the radius increased by the shape profile along each ray.
#[inline(always)]
pub(super) fn z_var(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let a = t.atan_yx;
    let reach = shape_total(&v.params(), v.derived(), a);
    let r = v.w * (t.sqrt + reach);
    let (s, c) = a.fsin_cos();
    [r * c, r * s, 0.0]
}

/// wdisc: a disc-like map — the angle/π becomes the radius and the radius bends the
/// direction (mirrored for positive angles).
#[inline(always)]
fn wdisc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let mut a = PI / (t.sqrt + 1.0);
    let r = t.atan_yx * FRAC_1_PI;
    if r > 0.0 {
        a = PI - a;
    }
    [v.w * r * a.fcos(), v.w * r * a.fsin(), 0.0]
}

const SHAPE_X: &[Param] = shape_params!("x");

const SHAPE_Y: &[Param] = shape_params!("y");

const SHAPE_Z: &[Param] = shape_params!("z");

const SHAPE_W: &[Param] = shape_params!("w", p_cyclic("w_angle", 0.0, -PI, PI));
