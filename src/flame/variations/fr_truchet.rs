//! Truchet tilings from Fractorium's catalogue: square tiles of quarter-circle bands (`Truchet`,
//! `Truchet_fill`, `Truchet_inv`, `Truchet_glyph`, `truchet_knot`) and hexagonal ones
//! (`Truchet_hex_crop`, `Truchet_hex_fill`, `hex_truchet`).
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_1_PI, FRAC_PI_3, FRAC_PI_6, PI, TAU};

use super::util::{floor_f, round_half_out, sine_hash, sqr, trunc_i32, zeps};
use super::*;
use crate::flame::fastmath::FastTrig;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("hex_truchet", hex_truchet)
        .params(&[
            p_range("hex_truchet_size", 1.0, -1.0, 1.0),
            p("hex_truchet_side", 1.0),
            p("hex_truchet_seed", 1.0),
        ])
        .flags(flag::RANDOM)
        .prepare(hex_truchet_prepare),
    super::inlined!("Truchet", truchet)
        .params(&[
            p("Truchet_extended", 1.0),
            p_nonzero("Truchet_exponent", 2.0, f64::EPSILON, 2.0),
            p_nonzero("Truchet_arc_width", 0.5, f64::EPSILON, 1.0),
            p("Truchet_rotation", 0.0),
            p_range("Truchet_size", 1.0, f64::EPSILON, f64::INFINITY),
            p("Truchet_seed", 50.0),
        ])
        .flags(flag::COMPAT)
        .prepare(truchet_prep),
    super::inlined!("Truchet_fill", truchet_fill)
        .params(&[
            p_cyclic("Truchet_fill_exponent", 2.0, 0.001, 2.0),
            p_cyclic("Truchet_fill_arc_width", 0.5, 0.001, 1.0),
            p("Truchet_fill_seed", 0.0),
        ])
        .prepare(truchet_fill_prep),
    super::inlined!("Truchet_glyph", truchet_glyph)
        .params(&[
            p_range("Truchet_glyph_exponent", 2.0, 0.0, 2.0),
            p("Truchet_glyph_arc_width", 0.5),
            p_nonzero("Truchet_glyph_amp", 6.0, f64::EPSILON, f64::INFINITY),
            p_range("Truchet_glyph_max", 0.9, 0.0, f64::INFINITY),
            p("Truchet_glyph_angle", 45.0),
            p("Truchet_glyph_seed", 1.0),
        ])
        .prepare(truchet_glyph_prep),
    super::inlined!("Truchet_hex_crop", truchet_hex_crop)
        .params(&[
            p_range("Truchet_hex_crop_wd", 0.2, 0.0, 5.0),
            p_int("Truchet_hex_crop_mode", 0.0, 0.0, 2.0),
            p_int("Truchet_hex_crop_inv", 0.0, 0.0, 1.0),
            p_int(
                "Truchet_hex_crop_seed",
                0.0,
                f64::NEG_INFINITY,
                f64::INFINITY,
            ),
        ])
        .prepare(truchet_hex_crop_prep),
    super::inlined!("Truchet_hex_fill", truchet_hex_fill)
        .params(&[
            p_int("Truchet_hex_fill_n", 3.0, f64::NEG_INFINITY, f64::INFINITY),
            p_int("Truchet_hex_fill_flipx", 1.0, 0.0, 1.0),
            p_int("Truchet_hex_fill_flipy", 1.0, 0.0, 1.0),
            p("Truchet_hex_fill_spreadx", 1.0),
            p("Truchet_hex_fill_spready", 1.0),
            p_int(
                "Truchet_hex_fill_seed",
                0.0,
                f64::NEG_INFINITY,
                f64::INFINITY,
            ),
        ])
        .flags(flag::RANDOM)
        .prepare(truchet_hex_fill_prep),
    super::inlined!("Truchet_inv", truchet_inv)
        .params(&[
            p_range("Truchet_inv_exponent", 2.0, 0.0, 2.0),
            p("Truchet_inv_arc_width", 0.5),
            p("Truchet_inv_rotation", 0.0),
            p_range("Truchet_inv_size", 1.0, 0.0, f64::INFINITY),
            p("Truchet_inv_seed", 1.0),
        ])
        .prepare(truchet_inv_prep),
    super::inlined!("truchet_knot", truchet_knot).flags(flag::RANDOM),
];

/// The tile rotation of hex_truchet: 60° as Fractorium writes it, to four decimals (not π/3).
#[allow(clippy::approx_constant)]
const TRUNCATED_60_DEG: f64 = 1.0471;

fn hex_truchet_prepare(v: &mut Prepared) {
    let [size, side] = v.params();
    let shrink = (1.0 - size) * 0.85;
    let lo = sqr(0.15 + shrink * 0.5);
    let hi = sqr(1.0 - shrink * 0.5);
    v.p.extend_from_slice(&[lo, hi - lo, side * 2.0 + 1.0]);
}

/// Hexagonal Truchet tiles: random points on the three arcs of a random hexagon of the grid,
/// the tile rotated by 60° or not according to a hash of its cell.
#[inline(always)]
fn hex_truchet(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, side, seed] = v.params();
    let [lo, span, cells] = v.derived();
    let ang = rng.f01() * TAU;
    let r = (rng.f01() * span + lo).sqrt();
    let (ox, oy) = if ang < 2.0943 {
        (1.0, 0.5773)
    } else if ang < 4.1887 {
        (-1.0, 0.5773)
    } else {
        (0.0, -1.1547)
    };
    let gx = 2.0 * (floor_f(rng.f01() * cells) - side);
    let gy = 2.0 * (floor_f(rng.f01() * cells) - side);
    let hx = gx + 0.5 * gy;
    let hy = 0.8660 * gy;
    let turn = if sine_hash(gx, gy, seed) < 0.5 {
        0.0
    } else {
        TRUNCATED_60_DEG
    };
    let a = ang + 2.6179 - turn;
    let (st, ct) = turn.fsin_cos();
    let cx = ox * ct + oy * st;
    let cy = -ox * st + oy * ct;
    [
        (a.fcos() * r + cx + hx) * v.w,
        (a.fsin() * r + cy + hy) * v.w,
        0.0,
    ]
}

/// √3, √3/2 and √3/3.
const SQRT3: f64 = 1.7320508075688772;

const SQRT3_2: f64 = 0.8660254037844386;

const SQRT3_3: f64 = 0.5773502691896257;

/// A Truchet tile's pair of quarter-arc distances: the superellipse radii (exponent `n`,
/// 1/n = `inv_n`) of the point (x, y) in the unit cell from the two corners the tile type
/// joins (`straight`: the corners (0, 0) and (1, 1), else the other two).
#[inline(always)]
fn truchet_radii(x: f64, y: f64, straight: bool, n: f64, inv_n: f64) -> (f64, f64) {
    let (a, b) = if straight { (x, x - 1.0) } else { (x - 1.0, x) };
    (
        (a.abs().powf(n) + y.abs().powf(n)).powf(inv_n),
        (b.abs().powf(n) + (y - 1.0).abs().powf(n)).powf(inv_n),
    )
}

/// Position within the unit cell centred on the nearest integer (rounded by `round`), moved
/// to [0, 1).
#[inline(always)]
fn cell_frac(x: f64, rounded: f64) -> f64 {
    let r = x - rounded;
    if r < 0.0 { 1.0 + r } else { r }
}

/// Derived values of Truchet.
fn truchet_prep(v: &mut Prepared) {
    let [_, exponent, _, rotation, _, seed] = v.params();
    let exponent = exponent.clamp(f64::EPSILON, 2.0);
    // Fractorium derives the arc width from the exponent (its arc-width parameter is unused).
    let arc = exponent.clamp(f64::EPSILON, 1.0);
    let inv_ex = 1.0 / exponent;
    let abs_seed = seed.abs();
    let seed2 = zeps(abs_seed * 1.5).sqrt() / zeps(abs_seed * 0.5) * 0.25;
    let inv_rmax = 1.0 / (0.5 * (2f64.powf(inv_ex) - 1.0) * arc);
    let scale = (rotation.fcos() + rotation.fsin()) / v.w;
    v.p.extend_from_slice(&[exponent, inv_ex, abs_seed, seed2, inv_rmax, scale]);
}

/// Truchet: the plane (scaled by 1/weight) kept only on Truchet tiles — two quarter-circle
/// (superellipse) bands per unit cell, with the tile orientation chosen per cell by a
/// seeded hash (`extended` 0 or flam3-compatibility off: a slower iterated hash).
#[inline(always)]
fn truchet(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [extended, _, _, _, size] = v.params();
    let [exponent, inv_ex, abs_seed, seed2, inv_rmax, scale] = v.derived();
    let extended = trunc_i32(extended) == 0 || !v.compat;
    let x0 = t.x * scale;
    let y0 = t.y * scale;
    let x = cell_frac(x0, trunc_i32(round_half_out(x0)) as f64);
    let y = cell_frac(y0, trunc_i32(round_half_out(y0)) as f64);
    let tile = if abs_seed == 0.0 {
        0.0
    } else if abs_seed == 1.0 {
        1.0
    } else if extended {
        let xr = round_half_out(t.x) * seed2;
        let yr = round_half_out(t.y) * seed2;
        let mix = xr + yr + xr * yr;
        let h = (mix + abs_seed) * seed2 * 0.5;
        let h = (h * 32747.0 + 12345.0) % 65535.0;
        h % 2.0
    } else {
        let xi = trunc_i32(round_half_out(t.x));
        let yi = trunc_i32(round_half_out(t.y));
        let mix = xi
            .wrapping_add(yi)
            .wrapping_add(xi.wrapping_mul(yi))
            .wrapping_abs();
        let mut h = abs_seed.floor() + mix as f64;
        let mut k = 0;
        while k < mix && k < 20 {
            k += 1;
            h = (h * 32747.0 + 12345.0) % 65535.0;
        }
        h % 2.0
    };
    // The two drawing modes read the tile type with opposite orientations.
    let straight = if extended { tile < 1.0 } else { tile == 1.0 };
    let (r0, r1) = truchet_radii(x, y, straight, exponent, inv_ex);
    let cx = size * (x + t.x.floor());
    let cy = size * (y + t.y.floor());
    let mut out = [0.0; 3];
    if (r0 - 0.5).abs() * inv_rmax < 1.0 {
        out[0] = cx;
        out[1] = cy;
    }
    if (r1 - 0.5).abs() * inv_rmax < 1.0 {
        out[0] += cx;
        out[1] += cy;
    }
    out
}

/// Derived values of Truchet_fill.
pub(super) fn truchet_fill_prep(v: &mut Prepared) {
    let [exponent, arc_width, seed] = v.params();
    let ex = exponent.clamp(0.001, 2.0);
    let inv_ex = 1.0 / ex;
    let width = arc_width.clamp(0.001, 1.0);
    let seed2 = (seed * 1.5).sqrt() / zeps(seed * 0.5) * 0.25;
    let rmax = zeps(0.5 * (2f64.powf(inv_ex) - 1.0) * width);
    v.p.extend_from_slice(&[ex, inv_ex, seed2, rmax, 1.0 / v.w]);
}

/// Truchet_fill: the complement-style Truchet map — points of the (1/weight-scaled) plane
/// are sent to twice their cell position on each arc band they lie in, minus the input,
/// filling the tile pattern.
#[inline(always)]
pub(super) fn truchet_fill(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, seed] = v.params();
    let [ex, inv_ex, seed2, rmax, scale] = v.derived();
    let x0 = t.x * scale;
    let y0 = t.y * scale;
    let x = cell_frac(x0, round_half_out(x0));
    let y = cell_frac(y0, round_half_out(y0));
    let tile = if seed == 0.0 {
        0.0
    } else if seed == 1.0 {
        seed
    } else {
        let xr = round_half_out(t.x.abs()) * seed2;
        let yr = round_half_out(t.y.abs()) * seed2;
        let mix = xr + yr + xr * yr;
        let h = (seed + mix) * seed2 * 0.5;
        let h = (h * 32747.0 + 12345.0) % 65535.0;
        h % 2.0
    };
    let (r0, r1) = truchet_radii(x, y, tile < 1.0, ex, inv_ex);
    let cx = 2.0 * (x + t.x.floor());
    let cy = 2.0 * (y + t.y.floor());
    let (x1, y1) = if (r0 - 0.5).abs() / rmax < 1.0 {
        (cx, cy)
    } else {
        (0.0, 0.0)
    };
    if (r1 - 0.5).abs() / rmax < 1.0 {
        [x1 + cx - t.x, y1 + cy - t.y, 0.0]
    } else {
        [x1 - t.x, y1 - t.y, 0.0]
    }
}

/// Derived values of Truchet_glyph.
fn truchet_glyph_prep(v: &mut Prepared) {
    let [exponent, arc_width, amp, max, angle] = v.params();
    let n = exponent.clamp(0.001, 2.0);
    let width = arc_width.clamp(0.001, 1.0);
    let inv_n = 1.0 / zeps(n);
    let rmax = zeps(0.5 * (2f64.powf(inv_n) - 1.0) * width);
    let rads = angle * (PI / 180.0);
    let half_amp_max = amp * 0.5 * max;
    let amp = zeps(amp);
    let scale = 1.0 / v.w;
    v.p.extend_from_slice(&[
        n,
        inv_n,
        rmax,
        scale,
        rads.fcos(),
        rads.fsin(),
        half_amp_max,
        amp,
    ]);
}

/// Truchet_glyph: Truchet_fill (hash-chosen tiles) applied only inside rotated squares
/// ("glyphs") centred on an `amp`-spaced grid; elsewhere the input passes unchanged.
#[inline(always)]
fn truchet_glyph(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, _, _, seed] = v.params();
    let [n, inv_n, rmax, scale, cost, sint, half_amp_max, amp] = v.derived();
    let x1 = t.x * scale;
    let y1 = t.y * scale;
    let x = cell_frac(x1, (x1 + 0.5).floor());
    let y = cell_frac(y1, (y1 + 0.5).floor());
    let tile = if seed == 0.0 {
        0.0
    } else if seed == 1.0 {
        1.0
    } else {
        let xr = (t.x.abs() + 0.5).floor();
        let yr = (t.y.abs() + 0.5).floor();
        let h = sine_hash(xr, yr, seed);
        let h = (h * 32747.0 + 12345.0) % 65535.0;
        h % 2.0
    };
    let (r0, r1) = truchet_radii(x, y, tile < 1.0, n, inv_n);
    let cx = (x + t.x.floor()) * 2.0;
    let cy = (y + t.y.floor()) * 2.0;
    let (ax, ay) = if (r0 - 0.5).abs() / rmax < 1.0 {
        (cx, cy)
    } else {
        (0.0, 0.0)
    };
    let gx = t.x - ((t.x / amp).floor() + 0.5) * amp;
    let gy = t.y - ((t.y / amp).floor() + 0.5) * amp;
    let rx = cost * gx + sint * gy;
    let ry = -sint * gx + cost * gy;
    if rx.abs() + ry.abs() < half_amp_max {
        if (r1 - 0.5).abs() / rmax < 1.0 {
            [ax + cx - t.x, ay + cy - t.y, 0.0]
        } else {
            [ax - t.x, ay - t.y, 0.0]
        }
    } else {
        [t.x, t.y, 0.0]
    }
}

/// Derived values of Truchet_hex_crop: the outer and inner radii of the arc band.
fn truchet_hex_crop_prep(v: &mut Prepared) {
    let [wd] = v.params();
    v.p.extend_from_slice(&[0.5 + wd, 0.5 - wd]);
}

/// The nearest hexagon centre of (x, y) (unit hexagons, pointy side up) and its cube
/// coordinates (rx, rz), by rounding cube coordinates.
#[inline(always)]
fn hex_centre(x: f64, y: f64) -> (f64, f64, f64, f64) {
    let y3 = y / 3.0;
    let cx = SQRT3_3 * x - y3;
    let cz = 2.0 * y3;
    let cy = -cx - cz;
    let (rx, ry, rz) = (cx.round(), cy.round(), cz.round());
    let dx = (rx - cx).abs();
    let dy = (ry - cy).abs();
    let dz = (rz - cz).abs();
    // The coordinate that rounded worst is rebuilt from the other two (x + y + z = 0); the
    // y coordinate itself is not needed.
    let (rx, rz) = if dx > dy && dx > dz {
        (-ry - rz, rz)
    } else if dy > dz {
        (rx, rz)
    } else {
        (rx, -rx - ry)
    };
    (SQRT3 * rx + SQRT3_2 * rz, 1.5 * rz, rx, rz)
}

/// Truchet_hex_crop: hexagonal Truchet tiles of three arcs each — points on the arc bands
/// (width 2·`wd`) are removed (collapsed to the origin, to the arc's corner, or pushed to the
/// band's edges, by `mode`), or, with `inv`, the points off the bands are.
#[inline(always)]
fn truchet_hex_crop(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, inv, seed] = v.params();
    let [d1, d2] = v.derived();
    let (hx, hy, rx, rz) = hex_centre(t.x, t.y);
    let mut fx = t.x - hx;
    let mut fy = t.y - hy;
    let mut add = 0.0;
    if seed == 1.0 {
        if trunc_i32(rx) & 1 == 0 && trunc_i32(rz) & 1 == 0 {
            add = FRAC_PI_3;
        }
    } else if seed >= 2.0 && sine_hash(hx, hy, seed) < 0.5 {
        add = FRAC_PI_3;
    }
    // The corner of the hexagon nearest in angle: the centre of this arc.
    let coef = 0.477464829275686; // 1.5/π
    let angle = fy.atan2(fx) + FRAC_PI_6 - add;
    let corner = (angle * coef).floor() / coef + FRAC_PI_6 + add;
    let (y0, x0) = corner.fsin_cos();
    let dist = (sqr(fx - x0) + sqr(fy - y0)).sqrt();
    let hit = if inv != 0.0 {
        dist > d1 || dist < d2
    } else {
        dist < d1 && dist > d2
    };
    if hit {
        if mode < 0.5 {
            fx = 0.0;
            fy = 0.0;
        } else if mode < 1.5 {
            fx = x0;
            fy = y0;
        } else {
            let a = (fy - y0).atan2(fx - x0);
            let d = if rng.f01() < 0.5 { d1 } else { d2 };
            fx = x0 + a.fcos() * d;
            fy = y0 + a.fsin() * d;
        }
    }
    [(fx + hx) * v.w, (fy + hy) * v.w, 0.0]
}

/// Derived values of Truchet_hex_fill: 3n and 1/(3n).
fn truchet_hex_fill_prep(v: &mut Prepared) {
    let [n] = v.params();
    let n3 = 3.0 * n;
    v.p.extend_from_slice(&[n3, 1.0 / zeps(n3)]);
}

/// Truchet_hex_fill: fills random hexagons (geometrically spread around the origin) with
/// three-arc Truchet tiles — the input, wrapped around a ring in one of 3n sectors, is
/// split into the three arcs of a hexagon.
#[inline(always)]
fn truchet_hex_fill(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    truchet_hex_fill_as::<false>(v, t, rng)
}

/// Truchet_hex_fill as JWildfire 9.00 computes it (`TruchetHexFillFunc`): the ring is
/// exponential in x (scaled by 2 / (e^(π/3n) + e^(−π/3n)) so that the tiles meet), where
/// Fractorium's is linear, and the input is mirrored for the other tile orientation when the
/// flip is 0 (Fractorium: when it is 1).
pub(super) fn truchet_hex_fill_jwildfire(
    v: &Prepared,
    t: &VarIn,
    _: &mut Acc,
    rng: &mut FastRng,
) -> V3 {
    truchet_hex_fill_as::<true>(v, t, rng)
}

#[inline(always)]
fn truchet_hex_fill_as<const JWF: bool>(v: &Prepared, t: &VarIn, rng: &mut FastRng) -> V3 {
    let [_, flipx, flipy, sx, sy, seed] = v.params();
    let [n3, inv_n3] = v.derived();
    let l = rng.f01().ln();
    let rx = (l * if rng.f01() < 0.5 { sx } else { -sx }).floor();
    let l = rng.f01().ln();
    let rz = (l * if rng.f01() < 0.5 { sy } else { -sy }).floor();
    let hx = SQRT3 * rx + SQRT3_2 * if rng.f01() < 0.5 { rz } else { -rz };
    let hy = 1.5 * rz;
    let mut add = true;
    if seed == 1.0 {
        if trunc_i32(rx) & 1 == 0 && trunc_i32(rz) & 1 == 0 {
            add = false;
        }
    } else if seed >= 2.0 && sine_hash(hx, hy, seed) < 0.5 {
        add = false;
    }
    let sector = (rng.f01() * n3).floor() * TAU * inv_n3;
    let mirror = |flip: f64| !add && (flip == 0.0) == JWF;
    let ya = if mirror(flipy) { -t.y } else { t.y };
    let xa = if mirror(flipx) { -t.x } else { t.x };
    let ang = ya * inv_n3 * PI + sector;
    let a = if JWF {
        let s1 = (PI * inv_n3).exp();
        2.0 / (s1 + 1.0 / s1) * (xa * inv_n3 * PI).exp()
    } else {
        1.0 + xa * inv_n3 * PI
    };
    let fx = a * ang.fcos();
    let fy = a * ang.fsin();
    // Which third of the circle: move that arc's centre to the origin.
    let mut th = fy.atan2(fx);
    if th < 0.0 {
        th += TAU;
    }
    let third = (1.5 * th * FRAC_1_PI).floor();
    let ang = (PI + third * TAU) / 3.0;
    let nx = fx - ang.fcos() * 2.0;
    let ny = fy - ang.fsin() * 2.0;
    // Rotate by ±30° into the hexagon.
    let (fx, fy) = if add {
        (SQRT3_2 * nx - 0.5 * ny, 0.5 * nx + SQRT3_2 * ny)
    } else {
        (SQRT3_2 * nx + 0.5 * ny, -0.5 * nx + SQRT3_2 * ny)
    };
    [v.w * (fx * 0.5 + hx), v.w * (fy * 0.5 + hy), 0.0]
}

/// Derived values of Truchet_inv.
fn truchet_inv_prep(v: &mut Prepared) {
    let [exponent, arc_width, rotation, _, seed] = v.params();
    let n = exponent.clamp(0.001, 2.0);
    let width = arc_width.clamp(0.001, 1.0);
    let seed2 = (seed * 1.5).sqrt() / zeps(seed * 0.5) * 0.25;
    let inv_n = 1.0 / zeps(n);
    let rmax = zeps(0.5 * (2f64.powf(inv_n) - 1.0) * width);
    let scale = (rotation.fcos() + rotation.fsin()) / v.w;
    v.p.extend_from_slice(&[n, inv_n, rmax, seed2, seed2 * 0.5, scale]);
}

/// Truchet_inv: the negative of Truchet — the (1/weight-scaled) plane kept only off both arc
/// bands of each tile.
#[inline(always)]
fn truchet_inv(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, size, seed] = v.params();
    let [n, inv_n, rmax, seed2, seed2_half, scale] = v.derived();
    let x1 = t.x * scale;
    let y1 = t.y * scale;
    let x = cell_frac(x1, (x1 + 0.5).floor());
    let y = cell_frac(y1, (y1 + 0.5).floor());
    let tile = if seed == 0.0 {
        0.0
    } else if seed == 1.0 {
        1.0
    } else {
        let xr = (t.x + 0.5).floor() * seed2;
        let yr = (t.y + 0.5).floor() * seed2;
        let mix = xr + yr + xr * yr;
        let h = (mix + seed) * seed2_half;
        let h = (h * 32747.0 + 12345.0) % 65535.0;
        h % 2.0
    };
    let (r0, r1) = truchet_radii(x, y, tile < 1.0, n, inv_n);
    if (r0 - 0.5).abs() / rmax > 1.0 && (r1 - 0.5).abs() / rmax > 1.0 {
        [(x + t.x.floor()) * size, (y + t.y.floor()) * size, 0.0]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// truchet_knot: random points on short strokes centred in each unit cell, horizontal or
/// vertical in a checkerboard pattern (a woven-knot look).
#[inline(always)]
fn truchet_knot(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    const WIDTH: f64 = 0.5;
    const SPACE: f64 = 0.1;
    let cx = t.x.floor();
    let cy = t.y.floor();
    let along = (rng.f01() - 0.5) * WIDTH;
    let across = (rng.f01() * 2.0 - 1.0) * (1.0 - SPACE - WIDTH * 0.5);
    let parity = (cx + cy).abs();
    let parity = parity - 2.0 * (parity * 0.5).floor();
    let (dx, dy) = if parity < 0.5 {
        (along, across)
    } else {
        (-across, along)
    };
    [v.w * (cx + dx), v.w * (cy + dy), 0.0]
}
