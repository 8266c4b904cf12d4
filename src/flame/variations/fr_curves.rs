//! Fractorium's variations that draw a curve or a figure independently of the input point:
//! Lissajous and spirograph curves, a line, spirals, the 3-D superformula, pie slices, waffles,
//! concentric rings and random cubes.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_2_PI, PI, TAU};

use super::util::{floor_f, floor_i64, rand_size, trunc_i32, wang_hash, zeps};
use super::*;
use crate::flame::fastmath::{self as fm, FastTrig};

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("concentric", concentric)
        .params(&[
            p("concentric_radius", 1.0),
            p_nonzero("concentric_density", 10.0, f64::NEG_INFINITY, f64::INFINITY),
            p("concentric_R_blur", 0.0),
            p("concentric_Z_blur", 0.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::WRITES_ACC)
        .sum(),
    super::inlined!("coth_spiral", coth_spiral)
        .params(&[p("coth_spiral_a", 4.0)])
        .flags(flag::RANDOM),
    super::inlined!("line", line)
        .params(&[p("line_delta", 0.0), p("line_phi", 0.0)])
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum()
        .prepare(prep_line),
    super::inlined!("Lissajous", lissajous)
        .params(&[
            p("Lissajous_tmin", -PI),
            p("Lissajous_tmax", PI),
            p("Lissajous_a", 3.0),
            p("Lissajous_b", 2.0),
            p("Lissajous_c", 0.0),
            p("Lissajous_d", 0.0),
            p("Lissajous_e", 0.0),
        ])
        .flags(flag::RANDOM)
        .sum(),
    super::inlined!("pie3D", pie3d)
        .params(&[
            p_int_nonzero("pie3D_slices", 6.0, 1.0, INF),
            p_cyclic("pie3D_rotation", 0.5, 0.0, TAU),
            p_range("pie3D_thickness", 0.5, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
    super::inlined!("randCubes", rand_cubes)
        .params(&[
            p("randCubes_blockSize", 1.0),
            p("randCubes_blockHeight", 1.0),
            p("randCubes_spread", 3.0),
            p_int("randCubes_seed", 1.0, -INF, INF),
            p("randCubes_density", 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::WRITES_ACC)
        .sum(),
    super::inlined!("Spirograph", spirograph)
        .params(&[
            p("Spirograph_a", 3.0),
            p("Spirograph_b", 2.0),
            p("Spirograph_d", 1.0),
            p("Spirograph_tmin", -1.0),
            p("Spirograph_ymin", -1.0),
            p("Spirograph_tmax", 1.0),
            p("Spirograph_ymax", 1.0),
            p("Spirograph_c1", 0.0),
            p("Spirograph_c2", 0.0),
        ])
        .flags(flag::RANDOM)
        .sum(),
    super::inlined!("SuperShape3D", super_shape3d)
        .params(&[
            p("SuperShape3D_rho", 9.9),
            p("SuperShape3D_phi", 2.5),
            p("SuperShape3D_m1", 6.0),
            p("SuperShape3D_m2", 3.0),
            p("SuperShape3D_a1", 1.0),
            p("SuperShape3D_a2", 1.0),
            p("SuperShape3D_b1", 1.0),
            p("SuperShape3D_b2", 1.0),
            p("SuperShape3D_n1_1", 1.0),
            p("SuperShape3D_n1_2", 1.0),
            p("SuperShape3D_n2_1", 1.0),
            p("SuperShape3D_n2_2", 1.0),
            p("SuperShape3D_n3_1", 1.0),
            p("SuperShape3D_n3_2", 1.0),
            p("SuperShape3D_spiral", 0.0),
            p_int("SuperShape3D_toroidmap", 0.0, 0.0, 1.0),
        ])
        .flags(flag::RANDOM | flag::WRITES_Z)
        .prepare(super_shape3d_prep)
        .sum(),
    super::inlined!("tanh_spiral", tanh_spiral)
        .params(&[p("tanh_spiral_a", 4.0)])
        .flags(flag::RANDOM),
    super::inlined!("waffle", waffle)
        .params(&[
            p_nonzero("waffle_slices", 6.0, f64::NEG_INFINITY, f64::INFINITY),
            p("waffle_xthickness", 0.5),
            p("waffle_ythickness", 0.5),
            p("waffle_rotation", 0.0),
        ])
        .flags(flag::RANDOM)
        .sum()
        .prepare(waffle_prep),
];

/// Random concentric rings: a random ring index k < density sets the radius k/density·radius
/// (optionally blurred) and the depth −k/density (optionally blurred); in regular use it
/// replaces what earlier variations summed.
#[inline(always)]
fn concentric(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [radius, density, r_blur, z_blur] = v.params();
    let level = floor_i64(rng.f01() * density) as f64 / zeps(density);
    let angle = rng.f01() * TAU;
    let mut r = level * radius;
    if r_blur != 0.0 {
        r += (rng.f01().sqrt() * 2.0 - 1.0) * r_blur;
    }
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    let zb = if z_blur != 0.0 {
        (rng.f01() * 2.0 - 1.0) * z_blur
    } else {
        0.0
    };
    let (s, c) = angle.fsin_cos();
    [r * c * v.w, r * s * v.w, (-level + zb) * v.w]
}

/// A random point of the spiral curve (−sinh s, sin(a·s)) / (cos(a·s) − cosh s), s uniform in
/// [−π, π): the hyperbolic cotangent of a line through the origin.
#[inline(always)]
fn coth_spiral(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a] = v.params();
    let s = (rng.f01() - 0.5) * TAU;
    let den = zeps((a * s).fcos() - fm::cosh(s));
    [
        v.w * (-fm::sinh(s) / den),
        v.w * ((a * s).fsin() / den),
        0.0,
    ]
}

fn prep_line(v: &mut Prepared) {
    let [delta, phi] = v.params();
    let (delta, phi) = (delta * PI, phi * PI);
    let ux = delta.fcos() * phi.fcos();
    let uy = delta.fsin() * phi.fcos();
    let uz = phi.fsin();
    let len = (ux * ux + uy * uy + uz * uz).sqrt();
    v.p.extend_from_slice(&[ux / len, uy / len, uz / len]);
}

/// line: a random point on a segment of length `weight` from the origin, in the 3-D direction
/// given by the angles `delta` (azimuth) and `phi` (elevation), in half turns.
#[inline(always)]
fn line(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ux, uy, uz] = v.derived();
    let r = rng.f01() * v.w;
    [ux * r, uy * r, uz * r]
}

/// Lissajous: a random point of the Lissajous curve (sin(a·s + d), sin(b·s)) for s in
/// [tmin, tmax], drifted along the diagonal by c·s and thickened by e.
#[inline(always)]
fn lissajous(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [tmin, tmax, a, b, c, d, e] = v.params();
    let s = (tmax - tmin) * rng.f01() + tmin;
    let thick = rng.f01() - 0.5;
    let cx = (a * s + d).fsin();
    let cy = (b * s).fsin();
    [
        v.w * (cx + c * s + e * thick),
        v.w * (cy + c * s + e * thick),
        0.0,
    ]
}

/// pie3D: a random point in one of `slices` pie wedges (rotated, of angular `thickness`), of
/// radius r up to the weight, lifted to z = weight·sin r.
#[inline(always)]
fn pie3d(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [slices, rotation, thickness] = v.params();
    let slice = trunc_i32(rng.f01() * slices + 0.5) as f64;
    let ang = rotation + TAU * (slice + rng.f01() * thickness) / slices;
    let r = v.w * rng.f01();
    [r * ang.fcos(), r * ang.fsin(), v.w * r.fsin()]
}

/// A random city of blocks: points land in random unit cells (spread exponentially around the
/// origin), each cell raised to a hashed height that also picks the colour. Replaces what the
/// xform's earlier variations summed.
#[inline(always)]
fn rand_cubes(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [size, height, spread, seed, density] = v.params();
    let mut cell = || {
        let l = rng.f01().ln();
        floor_f(l * if rng.bit() { spread } else { -spread })
    };
    let bx = cell();
    let by = cell();
    let h = wang_hash(trunc_i32(bx * seed)) + wang_hash(trunc_i32(bx + by * seed));
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
    }
    let x = (bx * density + rng.f01()) * size;
    let y = (by * density + rng.f01()) * size;
    let z = height * h * rng.f01().powf(0.125);
    acc.color = h / 2.0;
    [x, y, z]
}

/// Draws a spirograph (epitrochoid) curve independently of the input: a random curve
/// parameter in [tmin, tmax) and a random offset in [ymin, ymax) added to both coordinates.
#[inline(always)]
fn spirograph(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a, b, d, tmin, ymin, tmax, ymax, c1, c2] = v.params();
    let tt = (tmax - tmin) * rng.f01() + tmin;
    let off = (ymax - ymin) * rng.f01() + ymin;
    let ab = a + b;
    let inner = ab / b * tt;
    let (st, ct) = tt.fsin_cos();
    let x1 = ab * ct - c1 * inner.fcos();
    let y1 = ab * st - c2 * inner.fsin();
    [v.w * (x1 + d * ct + off), v.w * (y1 + d * st + off), 0.0]
}

/// A random point on a 3-D superformula surface (Gielis): two superformula radii for the
/// latitude and longitude, spherical or toroidal, with an optional spiral; independent of the
/// input.
#[inline(always)]
fn super_shape3d(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    super_shape3d_as::<false>(v, rng)
}

/// superShape3d as Fractorium computes it, or with `JWILDFIRE` as JWildfire 9.00 does: the two
/// superformula radii raised to −1/n1 (Fractorium: |·| raised to n1), the sign of φ from a
/// uniform draw below 0.5 and the standard library's sine and cosine.
#[inline(always)]
pub(super) fn super_shape3d_as<const JWILDFIRE: bool>(v: &Prepared, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        n1_1,
        n1_2,
        n2_1,
        n2_2,
        n3_1,
        n3_2,
        spiral,
        toroid,
    ] = v.params();
    let [an2_1, an2_2, bn3_1, bn3_2, m4_1, m4_2, rho_k, phi_k] = v.derived();
    let rho = rng.f01() * rho_k;
    let mut phi = rng.f01() * phi_k;
    let flip = if JWILDFIRE {
        rng.f01() < 0.5
    } else {
        rng.bit()
    };
    if flip {
        phi = -phi;
    }
    let sin_cos = |a: f64| if JWILDFIRE { a.sin_cos() } else { a.fsin_cos() };
    let (sr, cr) = sin_cos(rho);
    let (sp, cp) = sin_cos(phi);
    let (msr, mcr) = sin_cos(m4_1 * rho);
    let (msp, mcp) = sin_cos(m4_2 * phi);
    let pr1 = an2_1 * mcr.abs().powf(n2_1) + bn3_1 * msr.abs().powf(n3_1);
    let pr2 = an2_2 * mcp.abs().powf(n2_2) + bn3_2 * msp.abs().powf(n3_2);
    let (r1, r2) = if JWILDFIRE {
        (pr1.powf(-1.0 / n1_1), pr2.powf(-1.0 / n1_2))
    } else {
        (pr1.abs().powf(n1_1), pr2.abs().powf(n1_2))
    };
    let r1 = r1 + spiral * rho;
    if toroid == 1.0 {
        let ring = r1 + r2 * cp;
        [v.w * cr * ring, v.w * sr * ring, v.w * r2 * sp]
    } else {
        [
            v.w * r1 * cr * r2 * cp,
            v.w * r1 * sr * r2 * cp,
            v.w * r2 * sp,
        ]
    }
}

fn super_shape3d_prep(v: &mut Prepared) {
    let [rho, phi, m1, m2, a1, a2, b1, b2] = v.params();
    let [_, _, _, _, _, _, _, _, _, _, n2_1, n2_2, n3_1, n3_2] = v.params();
    v.p.extend([
        (1.0 / a1).abs().powf(n2_1),
        (1.0 / a2).abs().powf(n2_2),
        (1.0 / b1).abs().powf(n3_1),
        (1.0 / b2).abs().powf(n3_2),
        m1 / 4.0,
        m2 / 4.0,
        rho * FRAC_2_PI,
        phi * FRAC_2_PI,
    ]);
}

/// tanh_spiral: a random point on the curve (sinh t, sin(a·t)) / (cos(a·t) + cosh t),
/// t uniform in [−π, π] — a spiral-armed figure independent of the input.
#[inline(always)]
fn tanh_spiral(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a] = v.params();
    let s = (rng.f01() - 0.5) * TAU;
    let den = zeps((a * s).fcos() + fm::cosh(s));
    [v.w * (fm::sinh(s) / den), v.w * ((a * s).fsin() / den), 0.0]
}

/// Derived values of waffle: weight·sin and weight·cos of the rotation.
fn waffle_prep(v: &mut Prepared) {
    let [_, _, _, rotation] = v.params();
    let (s, c) = rotation.fsin_cos();
    let w = v.w;
    v.p.extend_from_slice(&[w * s, w * c]);
}

/// waffle: random points on a rotated grid of `slices`×`slices` bars in the unit square
/// (bar thickness `xthickness`, `ythickness`), independent of the input.
#[inline(always)]
fn waffle(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [slices, xt, yt] = v.params();
    let [sinr, cosr] = v.derived();
    let (a, r) = match rng.below(5) {
        0 => {
            let a = (rand_size(rng, slices) + rng.f01() * xt) / slices;
            let r = (rand_size(rng, slices) + rng.f01() * yt) / slices;
            (a, r)
        }
        1 => {
            let a = (rand_size(rng, slices) + rng.f01()) / slices;
            let r = (rand_size(rng, slices) + yt) / slices;
            (a, r)
        }
        2 => {
            let a = (rand_size(rng, slices) + xt) / slices;
            let r = (rand_size(rng, slices) + rng.f01()) / slices;
            (a, r)
        }
        3 => {
            let a = rng.f01();
            let r = (rand_size(rng, slices) + yt + rng.f01() * (1.0 - yt)) / slices;
            (a, r)
        }
        _ => {
            let a = (rand_size(rng, slices) + xt + rng.f01() * (1.0 - xt)) / slices;
            (a, rng.f01())
        }
    };
    [cosr * a + sinr * r, -sinr * a + cosr * r, 0.0]
}
