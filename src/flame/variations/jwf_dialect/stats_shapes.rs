//! JWildfire's formulas for random shapes of Fractorium's catalogue, where they differ from
//! Fractorium's: `blade3D`'s z (from y, not z), `pie3D`'s z (r·sin r, not weight·sin r) and its
//! real-valued slice count, `superShape3d`'s radii (the powers −1/n1, not n1), `squish`'s last
//! edge (y mirrored), `splitbrdr`'s unguarded slopes (0/0 is NaN at a cell centre) and
//! `hexnix3D`'s walker (six nodes two times in three) and z (lifted twice on one plane).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::TAU;

use crate::flame::variations::fr_hexagons::{ST_SIX_STEP, ST_SIXFOLD, ST_THREE_STEP};
use crate::flame::variations::util::{square_point, trunc_i32};
use crate::flame::variations::*;

pub(in crate::flame::variations) const DEFS: &[VarDef] = &[VarDef::new("pie3D", pie3d)
    // JWildfire keeps all three as they are set (a fractional slice count included).
    .params(&[
        p("pie3D_slices", 6.0),
        p("pie3D_rotation", 0.5),
        p("pie3D_thickness", 0.5),
    ])
    .flags(flag::RANDOM | flag::WRITES_Z)
    .sum()];

/// Zueuk's blade3D as JWildfire computes it: the angle r·ξ·weight, x and y from x, z from y
/// (Fractorium's takes z from z).
pub(super) fn blade3d(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let r = rng.f01() * v.w * (t.x * t.x + t.y * t.y).sqrt();
    let (s, c) = r.sin_cos();
    let wx = v.w * t.x;
    [wx * (c + s), wx * (c - s), v.w * t.y * (s - c)]
}

/// pie3D as JWildfire computes it: slice ⌊ξ·slices + ½⌋ of a real slice count, the slice's
/// wedge filled up to radius r = weight·ξ, lifted to z = r·sin r.
fn pie3d(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [slices, rotation, thickness] = v.params();
    let slice = trunc_i32(rng.f01() * slices + 0.5) as f64;
    let a = rotation + TAU * (slice + rng.f01() * thickness) / slices;
    let r = v.w * rng.f01();
    let (s, c) = a.sin_cos();
    [r * c, r * s, r * r.sin()]
}

/// David Young's superShape3d as JWildfire computes it: the two superformula radii raised to
/// −1/n1 (Fractorium's raise them to n1). Reads the registry's derived values.
pub(super) fn super_shape3d(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    crate::flame::variations::fr_curves::super_shape3d_as::<true>(v, rng)
}

/// Michael Faber's squish as JWildfire computes it: the arc length along the square of
/// half-side max(|x|, |y|), divided by `power` and moved by a random number of turns, back
/// onto the square; on the last edge y is mirrored (Fractorium's keeps it).
pub(super) fn squish(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let (ax, ay) = (t.x.abs(), t.y.abs());
    let (s, p) = if ax > ay {
        (ax, if t.x > 0.0 { t.y } else { 4.0 * ax - t.y })
    } else if t.y > 0.0 {
        (ay, 2.0 * ay - t.x)
    } else {
        (ay, 6.0 * ay + t.x)
    };
    let p = (p + 8.0 * s * (power * rng.f01()).floor()) / power;
    square_point(v.w, s, p, true)
}

/// FracFx's splitbrdr as JWildfire computes it: Fractorium's formula without its guard on the
/// slopes, so a point on a cell's centre line gets 0/0 (NaN) in three draws of four.
pub(super) fn split_brdr(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [bx, by, px, py] = v.params();
    let w = v.w;
    let b = w / ((t.x * t.x + t.y * t.y) / 4.0 + 1.0);
    let (rx, ry) = (t.x.round_ties_even(), t.y.round_ties_even());
    let (ox, oy) = (t.x - rx, t.y - ry);
    let mut x = t.x * b;
    let mut y = t.y * b;
    if rng.f01() >= 0.75 {
        x += w * (ox * 0.5 + rx);
        y += w * (oy * 0.5 + ry);
    } else if ox.abs() >= oy.abs() {
        if ox >= 0.0 {
            x += w * (ox * 0.5 + rx + bx);
            y += w * (oy * 0.5 + ry + by * oy / ox);
        } else {
            x += w * (ox * 0.5 + rx - by);
            y += w * (oy * 0.5 + ry - by * oy / ox);
        }
    } else if oy >= 0.0 {
        y += w * (oy * 0.5 + ry + by);
        x += w * (ox * 0.5 + rx + ox / oy * by);
    } else {
        y += w * (oy * 0.5 + ry - by);
        x += w * (ox * 0.5 + rx - ox / oy * bx);
    }
    [x + t.x * px, y + t.y * py, 0.0]
}

/// The walker of JWildfire's hexnix3D: when a cycle of six (or three) nodes is complete the
/// next kind is drawn, six nodes when ⌊3ξ⌋ ≤ 1 (two times in three). Returns whether this
/// step is on the six-node walk and counts it.
fn hexnix_walk(v: &Prepared, rng: &mut FastRng) -> bool {
    let mut six = v.state.get(ST_SIXFOLD);
    let mut i6 = v.state.get(ST_SIX_STEP);
    let mut i3 = v.state.get(ST_THREE_STEP);
    let draw = |rng: &mut FastRng| {
        if (rng.f01() * 3.0).trunc() <= 1.0 {
            1.0
        } else {
            0.0
        }
    };
    if i6 > 5.0 {
        i6 = 0.0;
        six = draw(rng);
    }
    if i3 > 2.0 {
        i3 = 0.0;
        six = draw(rng);
    }
    if six != 0.0 {
        i6 += 1.0;
    } else {
        i3 += 1.0;
    }
    v.state.set(ST_SIXFOLD, six);
    v.state.set(ST_SIX_STEP, i6);
    v.state.set(ST_THREE_STEP, i3);
    six != 0.0
}

/// Larry Berlin's hexnix3D as JWildfire computes it: the walker above; the sum so far and
/// the point rotated and scaled about a random node of a hexagon (or of a triangle) and
/// moved towards it; z lifted by zlift, and on a single plane (|majp| ≤ 1) lifted twice (its
/// single-plane step and its general step both run). Reads the registry's derived values.
pub(super) fn hexnix3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [majp, scale, zlift, side3] = v.params();
    let [smooth, plane, boost, gentle, lift, c7, c11] = v.derived();
    let six = hexnix_walk(v, rng);
    let (sx, sy, sz) = if v.form == Form::Regular {
        let s = (acc.x, acc.y, acc.z);
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
        s
    } else {
        (t.x, t.y, t.z)
    };
    let updown = if rng.f01() < 0.5 { -1.0 } else { 1.0 };
    let lifted = t.z * scale * zlift;
    let mut z = sz;
    if plane == 0.0 {
        z += smooth * lifted;
    } else if plane == 1.0 && majp < 0.0 && updown < 0.0 {
        z += -2.0 * (z * gentle);
    }
    if plane == 2.0 && majp < 0.0 {
        if updown > 0.0 {
            z += smooth * (lifted + boost);
        } else {
            z = (z - 2.0 * smooth * z) + smooth * updown * (lifted + boost);
        }
    } else {
        z += smooth * (lifted + updown * boost);
    }
    let (vx, vy, reach) = if six {
        const X6: [f64; 6] = [1.0, 0.5, -0.5, -1.0, -0.5, 0.5];
        const Y6: [f64; 6] = [0.0, -1.0, -1.0, 0.0, 1.0, 1.0];
        let n = ((rng.f01() * 6.0) as usize).min(5);
        (X6[n], Y6[n] * lift, 1.0)
    } else {
        let n = ((rng.f01() * 3.0) as usize).min(2);
        ([0.0, c7, c11][n], [-1.0, 0.5, 0.5][n], side3)
    };
    let ss = smooth * scale;
    let pull = smooth * v.w * reach;
    [
        sx * (1.0 - smooth) + ss * (sx * vx - sy * vy) + ss * (t.x * vx - t.y * vy) + pull * vx,
        sy * (1.0 - smooth) + ss * (sy * vx + sx * vy) + ss * (t.y * vx + t.x * vy) + pull * vy,
        z,
    ]
}
