//! JWildfire's "cut" variations (Jesus Sosa's ports of shader patterns): a point of the plane
//! (the input with `mode` 0, a uniform point of the unit square with `mode` 1) is kept where
//! the pattern is empty and hidden where it is set (`invert` swaps them). Here: `cut_fun` (a
//! field of random cells with rounded corners), `cut_triskel` (three spirals), `cut_yuebing`
//! (a moiré of sin(x·y)), `cut_hexdots` (dots on a hexagonal lattice), `cut_x` (an X),
//! `cut_sincos` (a wave of stripes), `cut_sqsplits` (squares split by turning edges),
//! `cut_chains` (interlocking waves), `cut_fractal` (an abs-inversion fractal) and
//! `cut_btruchet` (Truchet tiles of crosses and arcs), `cut_btree` (a binary tree of bands)
//! `cut_spiralcb` (a twisted spiral), `cut_snowflake` (a Kali-style 3-D fold) and
//! `cut_booleans` (the bits of x XOR/AND/OR y), `cut_web` (a log-polar spider web) and
//! `cut_glypho` (rings of glyph-like blobs) and `cut_bricks` (a brick wall).
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew. Like JWildfire, the cut
//! variations replace the xform's sum so far.

use super::util::{atan2_approx, fract, mix, sign, signum_java, smoothstep};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("cut_fun", cut_fun)
        .params(&[
            p_int("cut_fun_seed", 1000.0, NEG_INF, INF),
            p_int("cut_fun_mode", 1.0, 0.0, 1.0),
            p("cut_fun_zoom", 10.0),
            p_int("cut_fun_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(cut_fun_prepare),
    VarDef::new("cut_triskel", cut_triskel)
        .params(&[
            p_int("cut_triskel_mode", 1.0, 0.0, 1.0),
            p("cut_triskel_zoom", 1.0),
            p_int("cut_triskel_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_yuebing", cut_yuebing)
        .params(&[
            p_int("cut_yuebing_mode", 1.0, 0.0, 1.0),
            p("cut_yuebing_zoom", 0.25),
            p_int("cut_yuebing_invert", 0.0, 0.0, 1.0),
            p("cut_yuebing_p1", 2.0),
            p("cut_yuebing_p2", 25.0),
        ])
        .flags(CUT),
    VarDef::new("cut_hexdots", cut_hexdots)
        .params(&[
            p_int("cut_hexdots_mode", 1.0, 0.0, 1.0),
            p_range("cut_hexdots_size", 0.5, 0.01, 1.0),
            p_range("cut_hexdots_zoom", 4.0, 0.1, 50.0),
            p_int("cut_hexdots_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_x", cut_x)
        .params(&[
            p_int("cut_x_mode", 1.0, 0.0, 1.0),
            p("cut_x_zoom", 1.0),
            p_int("cut_x_invert", 0.0, 0.0, 1.0),
            p("cut_x_size", 0.1),
        ])
        .flags(CUT),
    VarDef::new("cut_sincos", cut_sincos)
        .params(&[
            p_int("cut_sincos_seed", 1000.0, NEG_INF, INF),
            p_int("cut_sincos_mode", 1.0, 0.0, 1.0),
            p("cut_sincos_time", 0.9),
            p("cut_sincos_zoom", 0.5),
            p_int("cut_sincos_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_sqsplits", cut_sqsplits)
        .params(&[
            p_int("cut_sqsplits_seed", 1000.0, NEG_INF, INF),
            p_int("cut_sqsplits_mode", 1.0, 0.0, 1.0),
            p("cut_sqsplits_time", 0.9),
            p("cut_sqsplits_zoom", 2.0),
            p_int("cut_sqsplits_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_chains", cut_chains)
        .params(&[
            p("cut_chains_shiftX", 0.0),
            p("cut_chains_shiftY", 0.0),
            p_int("cut_chains_mode", 1.0, 0.0, 1.0),
            p("cut_chains_zoom", 2.5),
            p_int("cut_chains_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_fractal", cut_fractal)
        .params(&[
            p_int("cut_fractal_seed", 0.0, NEG_INF, INF),
            p_int("cut_fractal_mode", 1.0, 0.0, 1.0),
            p("cut_fractal_time", 0.0),
            p_int("cut_fractal_iters", 30.0, 1.0, 100.0),
            p("cut_fractal_zoom", 1.0),
            p_int("cut_fractal_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_btruchet", cut_btruchet)
        .params(&[
            p_int("cut_btruchet_mode", 1.0, 0.0, 1.0),
            p_range("cut_btruchet_width", 2.0, 0.5, 5.0),
            p_int("cut_btruchet_seed", 1000.0, NEG_INF, INF),
            p("cut_btruchet_zoom", 10.0),
            p_int("cut_btruchet_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(cut_btruchet_prepare),
    VarDef::new("cut_btree", cut_btree)
        .params(&[
            p_int("cut_btree_randomize", 0.0, NEG_INF, INF),
            p("cut_btree_time", 1.0),
            p_range("cut_btree_thickness", 5.0, 1.0, 10.0),
            p("cut_btree_zoom", 1.0),
            p_int("cut_btree_mode", 1.0, 0.0, 1.0),
            p_int("cut_btree_invert", 1.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_spiralcb", cut_spiralcb)
        .params(&[
            p("cut_spiralcb_time", 0.0),
            p_int("cut_spiralcb_mode", 1.0, 0.0, 1.0),
            p("cut_spiralcb_zoom", 1.0),
            p_int("cut_spiralcb_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_snowflake", cut_snowflake)
        .params(&[
            p_int("cut_snowflake_seed", 1000.0, NEG_INF, INF),
            p_int("cut_snowflake_mode", 1.0, 0.0, 1.0),
            p("cut_snowflake_time", 0.0),
            p_int("cut_snowflake_level", 10.0, 1.0, 15.0),
            p("cut_snowflake_zoom", 10.0),
            p_int("cut_snowflake_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_booleans", cut_booleans)
        .params(&[
            p_int("cut_booleans_seed", 1000.0, NEG_INF, INF),
            p_int("cut_booleans_mode", 1.0, 0.0, 1.0),
            p_int("cut_booleans_type", 0.0, 0.0, 2.0),
            p("cut_booleans_zoom", 250.0),
            p_int("cut_booleans_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(cut_booleans_prepare),
    VarDef::new("cut_web", cut_web)
        .params(&[
            p_int("cut_web_seed", 1000.0, NEG_INF, INF),
            p("cut_web_time", 0.0),
            p_int("cut_web_mode", 1.0, 0.0, 1.0),
            p_range("cut_web_thick", 0.05, 0.0, 0.9),
            p_int("cut_web_invert", 1.0, 0.0, 1.0),
        ])
        .flags(CUT),
    VarDef::new("cut_glypho", cut_glypho)
        .params(&[
            p_int("cut_glypho_mode", 1.0, 0.0, 1.0),
            p_range("cut_glypho_zoom", 1.0, 0.1, 50.0),
            p_int("cut_glypho_invert", 0.0, 0.0, 1.0),
            p("cut_glypho_f1", 0.115),
            p("cut_glypho_f2", 0.75),
            p("cut_glypho_f3", 1.5),
        ])
        .flags(CUT),
    VarDef::new("cut_bricks", cut_bricks)
        .params(&[
            p_int("cut_bricks_seed", 1000.0, NEG_INF, INF),
            p_int("cut_bricks_mode", 1.0, 0.0, 1.0),
            p_range("cut_bricks_size", 0.9, 0.1, 0.9999),
            p("cut_bricks_zoom", 3.0),
            p_int("cut_bricks_invert", 0.0, 0.0, 1.0),
        ])
        .flags(CUT)
        .prepare(cut_bricks_prepare),
];

/// Java's `java.util.Random`: the 48-bit linear congruential generator, seeded and drawn as
/// Java does, so that a seed gives JWildfire's pattern.
pub(super) struct JavaRandom(pub(super) u64);

impl JavaRandom {
    const MULT: u64 = 0x5_DEEC_E66D;
    const MASK: u64 = (1 << 48) - 1;

    pub fn new(seed: i64) -> JavaRandom {
        JavaRandom((seed as u64 ^ Self::MULT) & Self::MASK)
    }

    fn next(&mut self, bits: u32) -> u64 {
        self.0 = (self.0.wrapping_mul(Self::MULT).wrapping_add(0xB)) & Self::MASK;
        self.0 >> (48 - bits)
    }

    /// `nextDouble()`: 53 random bits in [0, 1).
    pub fn next_f64(&mut self) -> f64 {
        ((self.next(26) << 27) + self.next(27)) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// The shader hash fract(sin(12.9898·x + 78.233·y)·43758.5453).
fn hash2(x: f64, y: f64) -> f64 {
    let v = (x * 12.9898 + y * 78.233).sin() * 43758.5453;
    v - v.floor()
}

/// The common end of the cut variations: the point (x, y), shifted by −centre, kept or hidden
/// (then at −centre) by `set` and `invert`; replaces the sum so far.
pub(super) fn cut_end(
    v: &Prepared,
    acc: &mut Acc,
    set: bool,
    invert: f64,
    pt: (f64, f64),
    c: f64,
) -> V3 {
    let hide = if invert == 0.0 { set } else { !set };
    let (x, y) = if hide { (0.0, 0.0) } else { pt };
    acc.hide = hide;
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [v.w * (x - c), v.w * (y - c), 0.0]
}

/// The point a cut variation tests: the input (mode 0, centre 0) or a uniform point of
/// [lo, lo + span]² (mode 1; two draws) with the centre `c` the variation subtracts then.
pub(super) fn cut_point(
    mode: f64,
    t: &VarIn,
    rng: &mut FastRng,
    lo: f64,
    span: f64,
    c: f64,
) -> (f64, f64, f64) {
    if mode == 0.0 {
        (t.x, t.y, 0.0)
    } else {
        let x = span * rng.f01() + lo;
        let y = span * rng.f01() + lo;
        (x, y, c)
    }
}

/// Flags of the cut variations.
pub(super) const CUT: u32 = flag::JWILDFIRE | flag::RANDOM | flag::WRITES_ACC | flag::HIDES;

/// A pattern's offset (x0, y0) = seed × two draws of Java's generator seeded with `seed`.
pub(super) fn seed_offset(v: &mut Prepared, seed: f64) {
    let mut r = JavaRandom::new(seed as i64);
    let x0 = seed * r.next_f64();
    let y0 = seed * r.next_f64();
    v.p.extend_from_slice(&[x0, y0]);
}

fn cut_fun_prepare(v: &mut Prepared) {
    let [seed] = v.params();
    seed_offset(v, seed);
}

fn cut_booleans_prepare(v: &mut Prepared) {
    let [seed] = v.params();
    seed_offset(v, seed);
}

fn cut_bricks_prepare(v: &mut Prepared) {
    let [seed] = v.params();
    seed_offset(v, seed);
}

fn cut_btruchet_prepare(v: &mut Prepared) {
    let [_, _, seed] = v.params();
    seed_offset(v, seed);
}

/// Whether the cell at ⌊(x, y)⌋ is set (hash ≥ ½).
fn fun_pix(x: f64, y: f64) -> f64 {
    if hash2(x.floor(), y.floor()) < 0.5 {
        0.0
    } else {
        1.0
    }
}

/// cut_fun's pattern at (x, y): random cells whose corners are rounded into their
/// neighbours.
fn fun_pattern(x: f64, y: f64) -> f64 {
    let nx = (x - x.floor()) * 2.0 - 1.0;
    let ny = (y - y.floor()) * 2.0 - 1.0;
    let (px, py) = (sign(nx) * 0.9, sign(ny) * 0.9);
    let d = (nx * nx + ny * ny).sqrt();
    let mut c = fun_pix(x, y);
    if d < 1.0 {
        return c;
    }
    let v0 = c;
    let v1 = fun_pix(px + x, y);
    let v2 = fun_pix(x, py + y);
    if v1 == v2 {
        c = if c == fun_pix(x + px, y + py) && c != v1 {
            0.0
        } else {
            v1
        };
    }
    let s = ((1.01 - d) / (1.0 - d)).clamp(0.0, 1.0);
    let s = s * s * (3.0 - 2.0 * s);
    v0 * (1.0 - s) + c * s
}

/// cut_fun: cuts along a field of random cells (`zoom` cells per unit) with rounded corners.
fn cut_fun(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, zoom, invert] = v.params();
    let [x0, y0] = v.derived();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let set = fun_pattern(x * zoom + x0, y * zoom + y0) > 0.0;
    cut_end(v, acc, set, invert, (x, y), c)
}

/// cut_triskel: three interlaced spiral arms turned by 120°.
fn cut_triskel(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -1.0, 2.0, 0.0);
    let (mut ux, mut uy) = (x * zoom, y * zoom + 0.1);
    let mut color: f64 = 0.0;
    for _ in 0..3 {
        (ux, uy) = (-0.5 * ux - 0.866 * uy, 0.866 * ux - 0.5 * uy);
        let (ax, ay) = (ux + 0.03, uy - 0.577);
        let l = 3.0 * (ax * ax + ay * ay).sqrt();
        let b = atan2_approx(ay, ax);
        let arm = if l + fract(b / 7.0 + 0.3) < 2.0 {
            0.5 + 0.5 * (b + 6.24 * l).sin()
        } else {
            0.0
        };
        color = color.max(arm);
    }
    let color = smoothstep(0.0, 0.1, (color - 0.5).abs()) - smoothstep(0.8, 0.9, color);
    cut_end(v, acc, color > 0.5, invert, (x, y), 0.0)
}

/// cut_yuebing: the moiré sin(10000·x·y·sin(p1/2)·p2), cut below 0.3.
fn cut_yuebing(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, invert, p1, p2] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let duration = (p1 / 2.0).sin() * p2;
    let color = (x * zoom * y * zoom * 10000.0 * duration).sin();
    cut_end(v, acc, color < 0.3, invert, (x, y), 0.0)
}

/// cut_hexdots: round dots on a hexagonal lattice (0.8 times the smaller squared distance to
/// the two interleaved rectangular lattices), of size `size`.
fn cut_hexdots(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, size, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (ux, uy) = (x * zoom, y * zoom);
    let (sx, sy) = (1.0, 1.732);
    let gm = |a: f64, m: f64| a - m * (a / m).floor();
    let (ax, ay) = (gm(ux, sx) * 2.0 - sx, gm(uy, sy) * 2.0 - sy);
    let (bx, by) = (
        gm(ux + sx * 0.5, sx) * 2.0 - sx,
        gm(uy + sy * 0.5, sy) * 2.0 - sy,
    );
    let col = 0.8 * (ax * ax + ay * ay).min(bx * bx + by * by);
    cut_end(v, acc, col > size, invert, (x, y), 0.0)
}

/// cut_x: an X of two bars of half-width `size` through the origin (the cut keeps the bars).
fn cut_x(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, invert, size] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (ax, ay) = ((x * zoom).abs(), (y * zoom).abs());
    let (s, c) = (std::f64::consts::FRAC_PI_4).sin_cos();
    let sy = (-s * ax + c * ay).abs() - size;
    let color = smoothstep(0.0, 0.009, sy);
    cut_end(v, acc, color < 0.1, invert, (x, y), 0.0)
}

/// cut_sincos: stripes along a cosine wave, their width varying along x (`time` shifts
/// them).
fn cut_sincos(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, time, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let ux = x * zoom + 1.5;
    let uy = (y * zoom + (ux * 10.0).cos() * 0.15) * 1.5;
    let e = ux - time * 0.5;
    let tt = e + uy.abs();
    let f = (1.0 + (ux * 3.0).sin()) * 0.4 + 0.1;
    let d = f - (fract(tt * 7.3) - 0.5).abs() * 2.0;
    let s = smoothstep(0.0, 0.05 / (d + 0.5).max(0.0), d + 0.1);
    cut_end(v, acc, s.sqrt() > 0.0, invert, (x, y), 0.0)
}

/// cut_sqsplits: a checkerboard of squares, each cut by an edge turning with `time` (the two
/// colours of squares turning opposite ways).
fn cut_sqsplits(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, time, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (ux, uy) = (x * zoom, y * zoom);
    let (fx, fy) = (fract(ux) - 0.5, fract(uy) - 0.5);
    let gm = |a: f64| (a - 2.0 * (a / 2.0).floor()).floor();
    let (ix, iy) = (gm(ux), gm(uy));
    let tt = time * 0.35;
    let a = atan2_approx(fx, fy) / 6.3;
    let r = fract(tt + tt + 2.0 * if ix != iy { a } else { 1.0 - a });
    let sharp = 180.0 * (fx * fx + fy * fy).sqrt();
    let k = ((r - 0.5) * sharp).clamp(0.0, 1.0) + (1.0 - r * sharp).clamp(0.0, 1.0);
    cut_end(v, acc, 1.0 - k > 0.0, invert, (x, y), 0.0)
}

/// cut_chains: chains of interlocking waves, smoothstep(−¼, ¼, mix(cos 12y + sin 15x,
/// 1.4·sin 15x, 3·cos 30x)).
fn cut_chains(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [shift_x, shift_y, mode, zoom, invert] = v.params();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let (ux, uy) = (x * zoom + shift_x, y * zoom + shift_y);
    let wy = (uy * 12.0).cos();
    let wx = (ux * 15.0).sin();
    let w = (ux * 30.0).cos();
    let color = smoothstep(-0.25, 0.25, mix(wy + wx, wx * 1.4, w * 3.0));
    cut_end(v, acc, color > 0.0, invert, (x, y), c)
}

/// cut_fractal: `iters` steps of U ↦ |U|/(2|U|²) + c (c turning with `time`) from the
/// transposed point; cut where |U|² is more than ¼ away from 0.01.
fn cut_fractal(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, time, iters, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let cx = (time + 1.5).cos() * 0.15 - 0.25;
    let cy = (time + 1.8).sin() * 0.15 - 0.25;
    let (mut ux, mut uy) = (y * zoom, x * zoom);
    for _ in 0..iters as i32 {
        let k = 0.5 / (ux * ux + uy * uy);
        (ux, uy) = (ux.abs() * k + cx, uy.abs() * k + cy);
    }
    let color = (ux * ux + uy * uy - 0.01).abs() * 2.0;
    cut_end(v, acc, color > 0.5, invert, (x, y), 0.0)
}

/// Hugo Elias' integer hash (Java's wrapping 32-bit arithmetic) over i32::MAX.
fn elias_hash(n: i32) -> f64 {
    let n = (n << 13) ^ n;
    let n = n
        .wrapping_mul(n.wrapping_mul(n).wrapping_mul(15731).wrapping_add(789221))
        .wrapping_add(1376312589);
    n as f64 / 2147483647.0
}

/// Distance to the two quarter circles of radius 1 about (1, 1) and (−1, −1) in a tile
/// [−1, 1]².
fn truchet_arcs(x: f64, y: f64) -> f64 {
    let (x, y) = if y < -x { (-x, -y) } else { (x, y) };
    (((x - 1.0).powi(2) + (y - 1.0).powi(2)).sqrt() - 1.0).abs()
}

/// cut_btruchet: Truchet tiles chosen by a hash of the cell: a cross, or quarter arcs in one of
/// two orientations, of line width `width`; the cut keeps the lines.
fn cut_btruchet(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, width, _, zoom, invert] = v.params();
    let [x0, y0] = v.derived();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let (ux, uy) = (x * zoom + x0, y * zoom + y0);
    let e = zoom * width / 1000.0;
    let (tx, ty) = (ux.floor(), uy.floor());
    let id = tx * 10000.0 + ty;
    let (lx, ly) = ((ux - tx - 0.5) * 2.0, (uy - ty - 0.5) * 2.0);
    let h = elias_hash(id as i32);
    let d = if h < 0.33 {
        lx.abs().min(ly.abs())
    } else if h < 0.67 {
        truchet_arcs(lx, ly)
    } else {
        truchet_arcs(-lx, ly)
    };
    let color = smoothstep(e * 5.0, e, d);
    cut_end(v, acc, color == 0.0, invert, (x, y), 0.0)
}

/// cut_btree: bands that double in number as y² grows (a binary tree), line width set by
/// `thickness`; only the y part of the shader's vector pattern decides.
fn cut_btree(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, thickness, zoom, mode, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -1.0, 2.0, 0.0);
    let (wx, wy) = (x * zoom, y * zoom);
    // The shader's w/w: 1, or NaN at 0 (the cut then keeps nothing there).
    let unit = if wy != 0.0 && wy.is_finite() {
        1.0
    } else {
        f64::NAN
    };
    let ty = unit * fract(time);
    let ly = wy * wy * 5.0 - ty;
    let my = 2.0_f64.powf(ly.ceil()) * (ty + 1.0);
    let w2 = fract(my * wx) - 0.5;
    let t0 = signum_java(w2) / 4.0;
    let t1 = (smoothstep(0.0, 1.0, fract(ly)) * t0 - w2).abs();
    let color = my / t1 / (100.0 * thickness);
    cut_end(v, acc, color > 0.5, invert, (x, y), 0.0)
}

/// (x, y) times the shader's mat2(−sin a, cos a, cos a, sin a) (a reflection-rotation).
fn spiral_turn(x: f64, y: f64, a: f64) -> (f64, f64) {
    let (s, c) = a.sin_cos();
    (-s * x + c * y, c * x + s * y)
}

/// cut_spiralcb: a spiral of arms twisted by the radius and modulated by sin 15θ; `time`
/// turns it.
fn cut_spiralcb(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [time, mode, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -1.0, 2.0, 0.0);
    let (ux, uy) = (x * zoom, y * zoom);
    let fi = (ux * ux + uy * uy).sqrt() * 50.0;
    let g = atan2_approx(uy, ux);
    let (ux, uy) = spiral_turn(ux, uy, time * 7.0);
    let k = (g * 15.0).sin();
    let (ux, uy) = spiral_turn(ux * k, uy * k, fi);
    let step = |lim: f64, p: f64| -> f64 { if p < lim { 0.0 } else { 1.0 } };
    let w = fi / 25.0;
    let hill = step(-w / 2.0, uy).min(1.0 - step(w / 2.0, uy));
    let color = 1.0 - step(0.0, ux).min(hill);
    cut_end(v, acc, color > 0.0, invert, (x, y), 0.0)
}

/// cut_snowflake: `level` folds p ↦ |p|/|p|² − 1.65, then p·|p| + |p|, of (x, y, z(time))
/// scaled by ¼; cut where ¼|p|² exceeds ½.
fn cut_snowflake(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, time, level, zoom, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let s = 0.25;
    let mut p = [
        x * zoom * s,
        y * zoom * s,
        ((time * 0.4).sin() * 0.5 - 0.5) * s,
    ];
    for _ in 0..level as i32 {
        let d = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        p = p.map(|c| c.abs() / d - 1.65);
        let k = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        p = p.map(|c| c * k + k);
    }
    let f = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) * s;
    cut_end(v, acc, f > 0.5, invert, (x, y), 0.0)
}

/// cut_booleans: sin of (int x) XOR, AND or OR (int y) on a grid shifted by the seed.
fn cut_booleans(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, kind, zoom, invert] = v.params();
    let [x0, y0] = v.derived();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let (ix, iy) = ((x * zoom + x0) as i32, (y * zoom + y0) as i32);
    let bits = match kind as i32 {
        0 => ix ^ iy,
        1 => ix & iy,
        _ => ix | iy,
    };
    cut_end(v, acc, (bits as f64).sin() > 0.0, invert, (x, y), c)
}

/// cut_web: a grid in log-polar coordinates, sheared into spirals (a spider's web), lines of
/// width `thick`.
fn cut_web(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, mode, thick, invert] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -1.0, 2.0, 0.0);
    let (px, py) = (x * 0.5, y * 0.5);
    let fac = 10.0 / (2.0 * std::f64::consts::PI);
    let (l, ang) = ((px * px + py * py).sqrt().ln(), atan2_approx(py, px));
    let d = l * 0.05 * fac;
    let (ex, ey) = (l - ang * 4.0, ang + l * 4.0);
    let band = |e: f64| {
        let m = e * fac + time;
        let m = m - 2.0 * (m / 2.0).floor();
        smoothstep(-0.5 * d, 0.5 * d, (m - 1.0).abs() - thick)
    };
    let color = 1.0 - (1.0 - (band(ex) + band(ey)));
    cut_end(v, acc, color > 0.0, invert, (x, y), 0.0)
}

/// cut_glypho: three rings of ten blobs (radii f1·n, n = 1, 1.5, 2) summed and banded by
/// step(f2, fract(m·f3)); the cut keeps the bands.
fn cut_glypho(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [mode, zoom, invert, f1, f2, f3] = v.params();
    let (x, y, _) = cut_point(mode, t, rng, -0.5, 1.0, 0.0);
    let m = glypho_pattern(x * zoom, y * zoom, [f1, f2, f3], 0.0);
    cut_end(v, acc, m == 0.0, invert, (x, y), 0.0)
}

/// The glypho pattern at (x, y): three rings of ten blobs (radii f1·n, n = 1, 1.5, 2; the
/// rings turn with `time`, alternately) summed and banded by step(f2, fract(m·f3)): 0 or 1.
pub(super) fn glypho_pattern(ux: f64, uy: f64, [f1, f2, f3]: [f64; 3], time: f64) -> f64 {
    let stp = std::f64::consts::PI / 5.0;
    let mut m = 0.0;
    let mut n = 1.0;
    let mut odd = -1.0;
    while n < 2.5 {
        odd = -odd;
        let tt = time * odd * 0.3;
        let mut i = 0.0001;
        while i < 2.0 * std::f64::consts::PI {
            let a = i + n * stp * 0.5 + tt;
            let (bx, by) = (ux * n + a.cos() * 0.4, uy * n + a.sin() * 0.4);
            m += smoothstep(f1 * n, 0.0, (bx * bx + by * by).sqrt()) * f3;
            i += stp;
        }
        n += 0.5;
    }
    if fract(m * f3) < f2 { 0.0 } else { 1.0 }
}

/// cut_bricks: a wall of bricks (every other row shifted by half a brick), each brick a
/// box of relative size `size`; the cut keeps the bricks.
fn cut_bricks(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, mode, size, zoom, invert] = v.params();
    let [x0, y0] = v.derived();
    let (x, y, c) = cut_point(mode, t, rng, 0.0, 1.0, 0.5);
    let (mut ux, uy) = (x * zoom + x0, y * zoom + y0);
    if uy - 2.0 * (uy / 2.0).floor() >= 1.0 {
        ux += 0.5;
    }
    let (ux, uy) = (fract(ux), fract(uy));
    let e = 0.5 - size * 0.5;
    let edge = |a: f64| smoothstep(e, e + 1e-4, a) * smoothstep(e, e + 1e-4, 1.0 - a);
    let color = edge(ux) * edge(uy);
    cut_end(v, acc, color > 0.0, invert, (x, y), c)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Java's `new Random(42).nextDouble()` twice (values from the JDK).
    #[test]
    fn java_random_matches_the_jdk() {
        let mut r = JavaRandom::new(42);
        assert_eq!(r.next_f64(), 0.7275636800328681);
        assert_eq!(r.next_f64(), 0.6832234717598454);
    }
}
