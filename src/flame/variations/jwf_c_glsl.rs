//! JWildfire's `glsl_*` stamps (Jesus Sosa's shader ports): each draws a random pixel of a
//! square grid, places the point there (the unit square centred on the origin) and colours
//! it by a shader pattern, with the pattern's colour as the point's own (`Gradient` 0) or an
//! index into the palette computed from it (1). Here the shared frame; `glsl_acrilic` and
//! `glsl_starsfield`, whose patterns are those of `dc_acrilic` and `dc_starsfield` on other
//! coordinates; `glsl_mandelbox2D` (the distance estimate of a 2-D Mandelbox) and
//! `glsl_apollonian` (an Apollonian-like 3-D fold of the plane); Kali's circle inversions
//! `glsl_kaliset` and `glsl_kaliset2`; `glsl_squares` (a Sierpiński carpet over a colour
//! flipped where the carpet is set); `glsl_circlesblue` (rising bubbles), `glsl_grid3D` (a
//! flight through a 3-D grid, grey) and `glsl_hyperbolictile` (a two-colour tiling of the
//! Poincaré disc), `glsl_mandala` (dc_mandala's kaleidoscope), `glsl_kaleidoscopic` (an
//! inversion fractal, optionally folded into a kaleidoscope) and `glsl_kaleidocomplex` (an
//! escape-time orbit of complex folds), `glsl_fractaldots` (dots of a folded, turned
//! lattice).
//!
//! JWildfire's grid has `Density Pixels` columns but always 1 000 000 rows (the parameter
//! sets the columns only), which these keep. The formulas follow JWildfire's (Andreas
//! Maschke and contributors, LGPL-2.1) mathematics, written anew; random numbers are drawn in
//! the order JWildfire draws them.

use super::jwf_a_dc::starsfield_grey;
use super::jwf_b_dc::acrilic_rgb;
use super::jwf_direct_colour::{dc_bytes, mandala_rgb};
use super::util::{atan2_approx, smoothstep};
use super::*;

/// The grid's rows (JWildfire's `resolutionY`, which no parameter sets).
pub(super) const GLSL_RES_Y: f64 = 1_000_000.0;

/// Flags of the glsl_ stamps.
const GLSL: u32 = flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR;

/// The grid's columns, the first parameter of each stamp.
macro_rules! density {
    ($n:literal) => {
        p_int(concat!($n, "_Density Pixels"), 1e6, 100.0, 1e7)
    };
}

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("glsl_acrilic", glsl_acrilic)
        .params(&[
            density!("glsl_acrilic"),
            p_int("glsl_acrilic_Seed", 10000.0, 0.0, 10000.0),
            p("glsl_acrilic_time", 0.0),
            p_int("glsl_acrilic_Steps", 10.0, 3.0, 100.0),
            p("glsl_acrilic_p1", 12.0),
            p("glsl_acrilic_p2", 12.0),
            p("glsl_acrilic_p3", 12.0),
            p("glsl_acrilic_p4", 12.0),
            p("glsl_acrilic_p5", 75.0),
            p("glsl_acrilic_p6", 75.0),
            p("glsl_acrilic_Red Fac.", 1.0),
            p("glsl_acrilic_Green Fac.", 1.0),
            p("glsl_acrilic_Blue Fac.", 1.0),
            p_int("glsl_acrilic_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_starsfield", glsl_starsfield)
        .params(&[
            density!("glsl_starsfield"),
            p_int("glsl_starsfield_Seed", 10000.0, 0.0, 10000.0),
            p("glsl_starsfield_time", 0.0),
            p("glsl_starsfield_Z distance", 2.0),
            p("glsl_starsfield_Glow", 2.0),
            p_int("glsl_starsfield_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_mandelbox2D", glsl_mandelbox2d)
        .params(&[
            density!("glsl_mandelbox2D"),
            p_int("glsl_mandelbox2D_seed", 10000.0, 0.0, 10000.0),
            p("glsl_mandelbox2D_time", 0.0),
            p_int("glsl_mandelbox2D_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_kaliset", glsl_kaliset)
        .params(&[
            density!("glsl_kaliset"),
            p_int("glsl_kaliset_Seed", 10000.0, NEG_INF, INF),
            p_range("glsl_kaliset_time", 200.0, 1.0, 1000.0),
            p_int("glsl_kaliset_N", 60.0, 1.0, 100.0),
            p_range("glsl_kaliset_ShiftX", -0.22, -5.0, 5.0),
            p_range("glsl_kaliset_ShiftY", -0.21, -5.0, 5.0),
            p_int("glsl_kaliset_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_kaliset2", glsl_kaliset2)
        .params(&[
            density!("glsl_kaliset2"),
            p_int("glsl_kaliset2_Seed", 5000.0, NEG_INF, INF),
            p_range("glsl_kaliset2_time", 85.5, 1.0, 1000.0),
            p_int("glsl_kaliset2_N", 100.0, 1.0, 100.0),
            p_range("glsl_kaliset2_radio", 1.0, 0.1, 10.0),
            p("glsl_kaliset2_ShiftX", -0.356),
            p("glsl_kaliset2_ShiftY", 0.686),
            p("glsl_kaliset2_Red Fac.", 1.8),
            p("glsl_kaliset2_Green Fac.", 1.9),
            p("glsl_kaliset2_Blue Fac.", 2.2),
            p_int("glsl_kaliset2_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_squares", glsl_squares)
        .params(&[
            density!("glsl_squares"),
            p_int("glsl_squares_Seed", 5000.0, NEG_INF, INF),
            p_range("glsl_squares_time", 85.5, 0.0, 1000.0),
            p_int("glsl_squares_N", 3.0, 1.0, 20.0),
            p_int("glsl_squares_Direction", 1.0, 0.0, 1.0),
            p_range("glsl_squares_Red Fac.", 1.8, 0.0, 5.0),
            p_range("glsl_squares_Green Fac.", 1.9, 0.0, 5.0),
            p_range("glsl_squares_Blue Fac.", 2.2, 0.0, 5.0),
            p_int("glsl_squares_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_circlesblue", glsl_circlesblue)
        .params(&[
            density!("glsl_circlesblue"),
            p_int("glsl_circlesblue_Seed", 10000.0, NEG_INF, INF),
            p_range("glsl_circlesblue_time", 1.0, 1.0, 1000.0),
            p_range("glsl_circlesblue_Radiusy", 0.04, 0.0, 1.0),
            p_int("glsl_circlesblue_Bubles", 40.0, 1.0, 100.0),
            p_int("glsl_circlesblue_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_grid3D", glsl_grid3d)
        .params(&[
            density!("glsl_grid3D"),
            p_int("glsl_grid3D_Seed", 10000.0, NEG_INF, INF),
            p_range("glsl_grid3D_time", 200.0, 1.0, 1000.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_hyperbolictile", glsl_hyperbolictile)
        .params(&[
            density!("glsl_hyperbolictile"),
            p_int("glsl_hyperbolictile_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_mandala", glsl_mandala)
        .params(&[
            density!("glsl_mandala"),
            p("glsl_mandala_mX", 0.025),
            p("glsl_mandala_mY", -0.001245675),
            p("glsl_mandala_scale", 2.0),
            p("glsl_mandala_sides", 12.0),
            p("glsl_mandala_multiply", 1.5),
            p("glsl_mandala_loops", 64.0),
            p_int("glsl_mandala_iR", 0.0, 0.0, 1.0),
            p_int("glsl_mandala_iG", 0.0, 0.0, 1.0),
            p_int("glsl_mandala_iB", 1.0, 0.0, 1.0),
            p_int("glsl_mandala_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_kaleidoscopic", glsl_kaleidoscopic)
        .params(&[
            density!("glsl_kaleidoscopic"),
            p_int("glsl_kaleidoscopic_Seed", 10000.0, NEG_INF, INF),
            p("glsl_kaleidoscopic_time", 0.0),
            p_int("glsl_kaleidoscopic_Sides", 8.0, 2.0, 20.0),
            p_range("glsl_kaleidoscopic_zoom", 0.0, 0.0, 1.0),
            p_range("glsl_kaleidoscopic_P1", 0.0, 0.0, 1.0),
            p_int("glsl_kaleidoscopic_Radial", 0.0, 0.0, 1.0),
            p_int("glsl_kaleidoscopic_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_kaleidocomplex", glsl_kaleidocomplex)
        .params(&[
            density!("glsl_kaleidocomplex"),
            p_int("glsl_kaleidocomplex_Seed", 10000.0, 0.0, 10000.0),
            p("glsl_kaleidocomplex_time", 0.0),
            p_int("glsl_kaleidocomplex_iMax", 12.0, 1.0, 50.0),
            p("glsl_kaleidocomplex_Color", 2.0),
            p_range("glsl_kaleidocomplex_Red Fac.", 1.0, 0.0, 5.0),
            p_range("glsl_kaleidocomplex_Green Fac.", 1.0, 0.0, 5.0),
            p_range("glsl_kaleidocomplex_Blue Fac.", 1.0, 0.0, 5.0),
            p_int("glsl_kaleidocomplex_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_fractaldots", glsl_fractaldots)
        .params(&[
            density!("glsl_fractaldots"),
            p_int("glsl_fractaldots_iterations", 9.0, 1.0, 100.0),
            p("glsl_fractaldots_DotSize", 400.0),
            p("glsl_fractaldots_MaxIterations", 10.0),
            p("glsl_fractaldots_complexity", 0.001245675),
            p("glsl_fractaldots_pattern", 2.5),
            p("glsl_fractaldots_spacing", 12.0),
            p("glsl_fractaldots_rotate1", 1.5),
            p("glsl_fractaldots_rotate2", 64.0),
            p("glsl_fractaldots_zoom", 64.0),
            p_int("glsl_fractaldots_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
    VarDef::new("glsl_apollonian", glsl_apollonian)
        .params(&[
            density!("glsl_apollonian"),
            p_int("glsl_apollonian_seed", 10000.0, 0.0, 10000.0),
            p("glsl_apollonian_time", 0.0),
            p_int("glsl_apollonian_Gradient", 0.0, 0.0, 1.0),
        ])
        .flags(GLSL),
];

/// The palette index a stamp computes from its colour with `Gradient` 1.
#[derive(Clone, Copy)]
pub(super) enum GlslIndex {
    /// red·green.
    RedGreen,
    /// sin of red's share of red + green + blue.
    RedShare,
}

/// The frame of the glsl_ stamps: a random pixel (i, j) of the grid (`res` columns), its
/// colour `pattern(i, j)` the point's own (`gradient` 0) or turned into a palette index;
/// the point is the pixel's corner in the unit square centred on the origin.
pub(super) fn glsl_frame(
    v: &Prepared,
    res: f64,
    gradient: f64,
    acc: &mut Acc,
    rng: &mut FastRng,
    index: GlslIndex,
    pattern: impl FnOnce(f64, f64) -> [f64; 3],
) -> V3 {
    let i = (rng.f01() * res).trunc();
    let j = (rng.f01() * GLSL_RES_Y).trunc();
    let c = pattern(i, j);
    if gradient == 0.0 {
        acc.rgb = Some(dc_bytes(c).map(|b| b as f64));
    } else {
        acc.color = match index {
            GlslIndex::RedGreen => c[0] * c[1],
            GlslIndex::RedShare => (c[0] / (c[0] + c[1] + c[2])).sin(),
        };
    }
    [v.w * (i / res - 0.5), v.w * (j / GLSL_RES_Y - 0.5), 0.0]
}

/// glsl_acrilic: dc_acrilic's waves on the pixel's centre scaled into [0, 0.7]².
fn glsl_acrilic(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        res,
        _,
        time,
        steps,
        p1,
        p2,
        p3,
        p4,
        p5,
        p6,
        fr,
        fg,
        fb,
        gradient,
    ] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let (x, y) = (0.7 * (i + 0.5) / res, 0.7 * (j + 0.5) / GLSL_RES_Y);
        acrilic_rgb(x, y, time, steps, [p1, p2, p3, p4, p5, p6], [fr, fg, fb])
    })
}

/// glsl_starsfield: dc_starsfield's stars on the pixel's centre in [-0.5, 0.5]².
fn glsl_starsfield(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, zdistance, glow, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let (x, y) = ((i + 0.5) / res - 0.5, (j + 0.5) / GLSL_RES_Y - 0.5);
        let g = starsfield_grey(x, y, time, zdistance, glow);
        [g, g, g]
    })
}

/// glsl_mandelbox2D: 20 box and ball folds of the pixel's centre in [-7, 7]² (scale
/// −5·cos(time/10)), the colour three cosines of the distance estimate's tenth root.
fn glsl_mandelbox2d(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedGreen, |i, j| {
        let (x, y) = (i + 0.5, j + 0.5);
        mandelbox2d_rgb(
            7.0 * (x + x - res) / res,
            7.0 * (y + y - GLSL_RES_Y) / GLSL_RES_Y,
            time,
        )
    })
}

/// The 2-D Mandelbox's colour at c: 20 box and ball folds (scale −5·cos(time/10)), three
/// cosines of the distance estimate's tenth root.
pub(super) fn mandelbox2d_rgb(cx: f64, cy: f64, time: f64) -> [f64; 3] {
    let scale = -5.0 * (time * 0.1).cos();
    let (mut ix, mut iy, mut d) = (cx, cy, 1.0);
    for _ in 0..20 {
        ix = ix.clamp(-1.0, 1.0) * 2.0 - ix;
        iy = iy.clamp(-1.0, 1.0) * 2.0 - iy;
        let l = (ix * ix + iy * iy).sqrt();
        let b = if l < 0.5 {
            4.0
        } else if l < 1.0 {
            1.0 / l
        } else {
            1.0
        };
        ix = ix * scale * b + cx;
        iy = iy * scale * b + cy;
        d = b * d * scale.abs() + 1.0;
    }
    let d = ((ix * ix + iy * iy).sqrt() / d).powf(0.1) * 5.0;
    [d.cos(), (10.0 * d + 1.0).sin(), (3.0 * d + 1.0).cos()].map(|c| c * 0.5 + 0.5)
}

/// A 3 × 3 matrix times a vector (rows of `m`).
fn mat_vec(m: &[[f64; 3]; 3], p: [f64; 3]) -> [f64; 3] {
    m.map(|r| r[0] * p[0] + r[1] * p[1] + r[2] * p[2])
}

/// The shader's rotation by the angles (a, b, c) about x, y and z.
fn rotation([a, b, c]: [f64; 3]) -> [[f64; 3]; 3] {
    let ((sa, ca), (sb, cb), (sc, cc)) = (a.sin_cos(), b.sin_cos(), c.sin_cos());
    [
        [cb * cc, sa * sb * cc + ca * sc, -ca * sb * cc + sa * sc],
        [-cb * sc, -sa * sb * sc + ca * cc, ca * sb * sc + sa * cc],
        [sb, -sa * cb, ca * cb],
    ]
}

/// glsl_apollonian: the pixel's centre in [-1, 1]², doubled, turned and scaled into space,
/// then folded 50 times (v ← |k·M·v/(2|v|²) − ½|·2 − 1); the colour 0.6·sin v + 0.5.
fn glsl_apollonian(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedGreen, |i, j| {
        apollonian_rgb(
            2.0 * (i + 0.5) / res - 1.0,
            2.0 * (j + 0.5) / GLSL_RES_Y - 1.0,
            time,
        )
    })
}

/// The Apollonian fold's colour at (ux, uy): the point doubled, turned and scaled into
/// space, folded 50 times (v ← |k·M·v/(2|v|²) − ½|·2 − 1), then 0.6·sin v + 0.5.
pub(super) fn apollonian_rgb(ux: f64, uy: f64, time: f64) -> [f64; 3] {
    let t = 0.05 * time;
    let m = rotation([t + 1.0, t + 2.0, t + 3.0]);
    let k = 1.2 + 0.1 * (0.1 * time).sin();
    let f1 = 2.0 + 0.25 * (0.3 * time).sin();
    let mut p = mat_vec(&m.map(|r| r.map(|e| e * f1)), [2.0 * ux, 2.0 * uy, 0.0]);
    let mk = m.map(|r| r.map(|e| e * k));
    for _ in 0..50 {
        let q = mat_vec(&mk, p);
        let d = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        p = q.map(|c| (c / d * 0.5 - 0.5).abs() * 2.0 - 1.0);
    }
    p.map(|c| c.sin() * 0.6 + 0.5)
}

/// The pixel's centre in [-10, 10]² (Kali's sets start there).
fn kali_start(i: f64, j: f64, res: f64) -> (f64, f64) {
    (
        ((i + 0.5) / res - 0.5) * 20.0,
        ((j + 0.5) / GLSL_RES_Y - 0.5) * 20.0,
    )
}

/// glsl_kaliset: N steps of inversion in the unit circle (outside it), turn, zoom and shift,
/// the decaying sum of the squared radii giving three cosines.
fn glsl_kaliset(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, n, shiftx, shifty, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let (x, y) = kali_start(i, j, res);
        kaliset_rgb((x, y), time, [n, shiftx, shifty])
    })
}

/// Kali's set at (x, y): N steps of inversion in the unit circle (outside it), turn, zoom
/// and shift; the decaying sum of the squared radii gives three cosines.
pub(super) fn kaliset_rgb(
    (mut x, mut y): (f64, f64),
    time: f64,
    [n, sx, sy]: [f64; 3],
) -> [f64; 3] {
    let pi2 = 3.6 * 2.0;
    let (c, s) = ((time / 603.0 * pi2).cos(), (time / 407.4 * pi2).sin());
    let zoom = time / 184.0 + 1.0;
    let mut rsum = 0.0;
    for _ in 0..n as i64 {
        let mut rr = x * x + y * y;
        if rr > 1.0 {
            rr = 1.0 / rr;
            x *= rr;
            y *= rr;
        }
        rsum = rsum * 0.99 + rr;
        (x, y) = ((c * x - s * y) * zoom + sx, (s * x + c * y) * zoom + sy);
    }
    let col = rsum * 0.5;
    [col.cos(), (col * 2.0).cos(), (col * 4.0).cos()]
}

/// glsl_kaliset2's 2π as the shader writes it (kept).
#[allow(clippy::approx_constant)]
const KALI_TAU: f64 = 6.2831853070;

/// glsl_kaliset2: N steps of inversion in the circle of squared radius `radio` (outside it),
/// turn by 2π·ShiftX, zoom 2 + 5·ShiftY and shift up by 2 + 2·sin(0.03·time); the colour
/// cosines of the largest squared radius.
fn glsl_kaliset2(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, n, rad2, shiftx, shifty, fr, fg, fb, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let (x, y) = kali_start(i, j, res);
        kaliset2_rgb(x, y, time, [n, rad2, shiftx, shifty], [fr, fg, fb])
    })
}

/// Kali's second set at (x, y): N steps of inversion in the circle of squared radius
/// `radio` (outside it), turn by 2π·ShiftX, zoom 2 + 5·ShiftY and shift up by
/// 2 + 2·sin(0.03·time); the colour cosines of the largest squared radius.
pub(super) fn kaliset2_rgb(
    mut x: f64,
    mut y: f64,
    time: f64,
    [n, rad2, shiftx, shifty]: [f64; 4],
    [fr, fg, fb]: [f64; 3],
) -> [f64; 3] {
    let angle = KALI_TAU * shiftx;
    let (c, s) = (angle.cos(), angle.sin());
    let up = 2.0 + 2.0 * (0.03 * time).sin();
    let zoom = 2.0 + 5.0 * shifty;
    let mut rmax: f64 = 0.0;
    for _ in 0..n as i64 {
        let mut rr = x * x + y * y;
        if rr > rad2 {
            rr = rad2 / rr;
            x *= rr;
            y *= rr;
        }
        rmax = rmax.max(rr);
        (x, y) = ((c * x - s * y) * zoom, (s * x + c * y) * zoom + up);
    }
    let col = rmax * rmax * (500.0 / n / rad2);
    [(col * fr).cos(), (col * fg).cos(), (col * fb).cos()]
}

/// Whether (x, y) is set in the Sierpiński carpet of `levels` levels zoomed by
/// 2^(frac(direction·time)) (direction 0.1 with `dir` 1, else −1).
fn carpet_hit(x: f64, y: f64, levels: i64, dir: f64, time: f64) -> bool {
    let direction = if dir as i64 == 1 { 0.1 } else { -1.0 };
    let m = direction * time;
    let zoom = 0.5f64.powf(m - m.floor());
    let (mut cx, mut cy) = (x / zoom, y / zoom);
    for _ in 0..levels {
        let (sx, sy) = ((cx * 3.0).floor(), (cy * 3.0).floor());
        if sx == 1.0 && sy == 1.0 {
            return false;
        }
        cx = cx * 3.0 - sx;
        cy = cy * 3.0 - sy;
    }
    true
}

/// glsl_squares: the colour (cos t, tan t, sin t) flipped (1 − c) by each of four carpets
/// shifted along the diagonal that hits the pixel's centre (folded into the first quadrant).
fn glsl_squares(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, n, dir, fr, fg, fb, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let (x, y) = ((i + 0.5) / res - 0.5, (j + 0.5) / GLSL_RES_Y - 0.5);
        squares_rgb(x, y, time, n, dir, [fr, fg, fb])
    })
}

/// The squares' colour at (x, y) (folded into the first unit square): (cos t, tan t, sin t)
/// flipped (1 − c) by each of four carpets shifted along the diagonal that hits the point.
pub(super) fn squares_rgb(x: f64, y: f64, time: f64, n: f64, dir: f64, f: [f64; 3]) -> [f64; 3] {
    let fold = |u: f64| {
        let a = u.abs();
        a - a.floor()
    };
    let (x, y) = (fold(x), fold(y));
    let mut color = [time.cos(), time.tan(), time.sin()];
    for k in 0..4 {
        let d = k as f64 * 0.1;
        if carpet_hit(x + d, y + d, n as i64, dir, time) {
            color = color.map(|c| 1.0 - c);
        }
    }
    [0, 1, 2].map(|k| (color[k] * f[k]).cos())
}

/// glsl_circlesblue: `Bubles` discs rising and swaying with time, each a mix of two blues
/// by its index, summed (×0.3) over the pixel's centre in [-1, 1]².
fn glsl_circlesblue(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, radius, bubbles, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let (ux, uy) = (
            2.0 * (i + 0.5) / res - 1.0,
            2.0 * (j + 0.5) / GLSL_RES_Y - 1.0,
        );
        circlesblue_rgb(ux, uy, time, radius, bubbles)
    })
}

/// The bubbles' colour at (ux, uy): `bubbles` discs rising and swaying with time, each a mix
/// of two blues by its index, summed (×0.3).
pub(super) fn circlesblue_rgb(ux: f64, uy: f64, time: f64, radius: f64, bubbles: f64) -> [f64; 3] {
    let mut color = [0.0; 3];
    for k in 0..bubbles as i64 {
        let k = k as f64;
        let pha = (k * 6.0 + 1.0).tan() * 0.5 + 0.5;
        let siz = ((k * 2.4 + 5.0).cos() * 0.5 + 0.5).powf(4.0);
        let pox = (k * 3.55 + 4.1).cos();
        let rad = radius + k.sin() * 0.12 + 0.08;
        let m = pha + 0.1 * (time / 5.0) * (0.2 + 0.8 * siz);
        let px = pox + (time / 15.0 + pha + siz).sin();
        let py = -1.0 - rad + (2.0 + 2.0 * rad) * (m - m.floor());
        let dis = ((ux - px).powi(2) + (uy - py).powi(2)).sqrt();
        let f = 0.5 + 0.5 * (k * (time * pox * 0.03).sin() + 1.9).sin();
        let col = [0.1 + 0.1 * f, 0.2 + 0.6 * f, 0.8 - 0.2 * f];
        let edge = 1.0 - smoothstep(rad * (0.65 + 0.20 * (pox * time).sin()), rad, dis);
        let w = edge * (1.0 - (pox * time).cos());
        for c in 0..3 {
            color[c] += col[c] * w;
        }
    }
    color.map(|c| c * 0.3)
}

/// glsl_grid3D's distance field of three folded grids.
fn grid_field(p: [f64; 3]) -> [f64; 3] {
    let mut p = p.map(|c| c * 0.1);
    let mut f = 0.1;
    for _ in 0..3 {
        p = [p[1], p[2], p[0]];
        p = p.map(|c| (c - c.floor() - 0.5).abs() * 2.0);
        f *= 2.0;
    }
    let q = p.map(|c| c * c);
    [0, 1, 2].map(|k| (q[k] + q[(k + 1) % 3]).sqrt() / f - 0.05)
}

/// glsl_grid3D: 30 steps of a ray (turned by time·0.021 about x, then y) through the grid
/// field, its glow summed into a grey level.
fn glsl_grid3d(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time] = v.params();
    glsl_frame(v, res, 0.0, acc, rng, GlslIndex::RedShare, |i, j| {
        let g = grid3d_grey((i + 0.5) / res - 0.5, (j + 0.5) / GLSL_RES_Y - 0.5, time);
        [g, g, g]
    })
}

/// The 3-D grid's grey level seen along the ray through (px, py, 1): 30 steps (the ray
/// turned by time·0.021 about x, then y) through the grid field, its glow summed.
pub(super) fn grid3d_grey(px: f64, py: f64, time: f64) -> f64 {
    const STEPS: usize = 30;
    let d = [px, py, 1.0];
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let d = d.map(|c| c / l);
    let a = time * 0.021;
    let (s, c) = (a.sin(), a.cos());
    // The row vector times the shader's column-major matrices.
    let d = [d[0], d[1] * c - d[2] * s, d[1] * s + d[2] * c];
    let d = [d[0] * c - d[2] * s, d[1], d[0] * s + d[2] * c];
    let mut pos = [0.0, time * 0.1, 0.0];
    let mut glow = [0.0; 3];
    for k in 0..STEPS {
        let f2 = grid_field(pos);
        let f = f2[0].min(f2[1]).min(f2[2]);
        pos = [0, 1, 2].map(|q| pos[q] + d[q] * f);
        for q in 0..3 {
            glow[q] += (STEPS - k) as f64 / (f2[q] + 0.1);
        }
    }
    glow.iter()
        .map(|c| 1.0 - 1.0 / (1.0 + c * (0.09 / (STEPS * STEPS) as f64)))
        .sum()
}

/// A point in polar form (r, angle) reflected in a line of the hyperbolic tiling given in
/// polar form: a circle orthogonal to the unit circle (r < 100) or a diameter.
fn hyperbolic_mirror(line: (f64, f64), p: (f64, f64)) -> (f64, f64) {
    if line.0 < 100.0 {
        let (cx, cy) = (line.0 * line.1.cos(), line.0 * line.1.sin());
        let (px, py) = (p.0 * p.1.cos(), p.0 * p.1.sin());
        let (dx, dy) = (px - cx, py - cy);
        let rr = (line.0 * line.0 - 1.0) / (dx * dx + dy * dy);
        let (x, y) = (cx + dx * rr, cy + dy * rr);
        ((x * x + y * y).sqrt(), atan2_approx(y, x))
    } else {
        (p.0, -p.1 + 2.0 * line.1 + std::f64::consts::PI)
    }
}

/// glsl_hyperbolictile: the pixel's centre in [-1, 1]² folded into one triangle of an
/// octagonal tiling of the Poincaré disc; white where an odd number of folds was needed,
/// black there and outside the disc.
fn glsl_hyperbolictile(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let c = hyperbolic_grey(
            2.0 * (i + 0.5) / res - 1.0,
            2.0 * (j + 0.5) / GLSL_RES_Y - 1.0,
        );
        [c, c, c]
    })
}

/// The octagonal tiling of the Poincaré disc at (x, y): 1 where an odd number of folds took
/// the point into the fundamental triangle, 0 there and outside the disc.
pub(super) fn hyperbolic_grey(x: f64, y: f64) -> f64 {
    use std::f64::consts::PI;
    let mut p = ((x * x + y * y).sqrt(), atan2_approx(y, x));
    if p.0 > 1.0 {
        return 0.0;
    }
    let (l1, l2) = ((1000.0, 0.0), (1000.0, PI / 8.0));
    let l3 = ((2f64.sqrt() + 1.0).sqrt(), PI / 2.0);
    let inside = |a: f64| (PI / 2.0..PI * 0.75).contains(&a);
    let mut folds = 0;
    for _ in 0..7 {
        for _ in 1..8 {
            if inside(p.1) {
                break;
            }
            folds += 1;
            p = hyperbolic_mirror(l2, hyperbolic_mirror(l1, p));
        }
        p = hyperbolic_mirror(l3, p);
        if inside(p.1) {
            break;
        }
    }
    (folds % 2) as f64
}

/// glsl_mandala: dc_mandala's kaleidoscopic fractal on the pixel's centre in [-1, 1]².
fn glsl_mandala(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, mut q @ .., gradient] = v.params::<11>();
    if gradient != 0.0 {
        // JWildfire's GLSL vectors keep their r, g, b as constructed: the channel inversions
        // (iR, iG, iB) change x, y, z after that, so the gradient index r·g never sees them.
        q[6..].fill(0.0);
    }
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedGreen, |i, j| {
        let (x, y) = (
            2.0 * (i + 0.5) / res - 1.0,
            2.0 * (j + 0.5) / GLSL_RES_Y - 1.0,
        );
        mandala_rgb(q, x, y)
    })
}

/// glsl_kaleidoscopic: the pixel's centre in [-12, 12]² scaled by 0.1 + zoom (folded into a
/// wedge of π/Sides turned by time/10 with `Radial`), then 44 steps of
/// p ← swizzle((1.3, 0.999, 0.678)·|p/|p|² − (1, 1.02, 0.4·P1)|) from (uv, zoom).
fn glsl_kaleidoscopic(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, sides, zoom, p1, radial, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let f = 12.0 * (0.1 + zoom);
        let uv = (
            (2.0 * (i + 0.5) / res - 1.0) * f,
            (2.0 * (j + 0.5) / GLSL_RES_Y - 1.0) * f,
        );
        kaleidoscopic_rgb(uv, zoom, time, sides, p1, radial)
    })
}

/// The kaleidoscopic inversion fractal at uv (folded into a wedge of π/sides turned by
/// time/10 with `radial`), 44 steps of p ← swizzle((1.3, 0.999, 0.678)·|p/|p|² − (1, 1.02,
/// 0.4·p1)|) from (uv, zoom).
pub(super) fn kaleidoscopic_rgb(
    mut uv: (f64, f64),
    zoom: f64,
    time: f64,
    sides: f64,
    p1: f64,
    radial: f64,
) -> [f64; 3] {
    let k = std::f64::consts::PI / sides.trunc();
    if radial as i64 == 1 {
        let a = atan2_approx(uv.1, uv.0);
        let a = ((a - 2.0 * k * (a / (2.0 * k)).floor()) - k).abs() + 0.1 * time;
        let d = (uv.0 * uv.0 + uv.1 * uv.1).sqrt();
        uv = (a.cos() * d, a.sin() * d);
    }
    let mut p = [uv.0, uv.1, zoom];
    let shift = [1.0, 1.02, p1 * 0.4];
    let gain = [1.3, 0.999, 0.678];
    for _ in 0..44 {
        let d = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        let w: [f64; 3] = std::array::from_fn(|q| gain[q] * (p[q].abs() / d - shift[q]).abs());
        p = [w[0], w[2], w[1]];
    }
    p
}

/// glsl_kaleidocomplex: z = |pixel's centre|·8 turned, folded (|z| + ±1 − 10.5) and turned
/// by time up to iMax + 1 times; the colour sums of exponentials of z, or a final one where
/// a coordinate of z comes within 0.51 of 0; cosines of the sums.
fn glsl_kaleidocomplex(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, _, time, imax, fc, fr, fg, fb, gradient] = v.params();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedShare, |i, j| {
        let (ux, uy) = ((i + 0.5) / res - 0.5, (j + 0.5) / GLSL_RES_Y - 0.5);
        kaleidocomplex_rgb(ux, uy, time, imax, fc, [fr, fg, fb])
    })
}

/// The complex folds' colour at (ux, uy): z = |uv|·8 turned, folded (|z| + ±1 − 10.5) and
/// turned by time up to iMax + 1 times; the colour sums of exponentials of z, or a final one
/// where a coordinate of z comes within 0.51 of 0; cosines of the sums.
pub(super) fn kaleidocomplex_rgb(
    ux: f64,
    uy: f64,
    time: f64,
    imax: f64,
    fc: f64,
    f: [f64; 3],
) -> [f64; 3] {
    let (mut zx, mut zy) = (ux.abs() / 0.125, uy.abs() / 0.125);
    let (st, ct) = (time.sin(), time.cos());
    let mut col = [0.0; 3];
    let mut r = 1.0;
    for ii in 0..=imax as i64 {
        r = -r;
        (zx, zy) = (zx - zy, zx + zy);
        (zx, zy) = (zx.abs() + r - 10.5, zy.abs() + r - 10.5);
        (zx, zy) = (zx * st - zy * ct, zx * ct + zy * st);
        let iif = ii as f64;
        if ii > 0 && (zx.abs() < 0.51 || zy.abs() < 0.51) {
            col = [
                (-(zx * zx * zy).abs()).exp(),
                (-(zy * zx * zy).abs()).exp(),
                (-zx.min(zy).abs()).exp(),
            ];
            break;
        }
        col[0] += fc * (-(-zx / iif + iif / zx).abs()).exp();
        col[1] += fc * (-(-zy / iif + iif / zy).abs()).exp();
        col[2] += fc * (-((-zx - zy) / iif + iif / (zx + zy)).abs()).exp();
        if zx * zx + zy * zy > 1e7 {
            break;
        }
    }
    [0, 1, 2].map(|k| (col[k] * f[k]).cos())
}

/// glsl_fractaldots' dot radius: JWildfire computes it once from the default DotSize and
/// MaxIterations (400 / (3·2¹⁰)), whatever the parameters say.
const FRACTALDOTS_RADIUS: f64 = 400.0 / (3.0 * 1024.0);

/// glsl_fractaldots: the pixel's centre in [-½, ½]² turned by rotate1 and zoomed, then folded
/// (|uv| − s − complexity, turned by rotate2, s divided by `pattern`) while the step count is
/// below MaxIterations and at most iterations + 1; white within the dot radius of the origin.
fn glsl_fractaldots(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res, q @ .., gradient] = v.params::<11>();
    glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedGreen, |i, j| {
        let uv = ((i + 0.5) / res - 0.5, (j + 0.5) / GLSL_RES_Y - 0.5);
        let c = fractaldots_grey(uv, q);
        [c, c, c]
    })
}

/// The fractal dots at uv (turned by rotate1 and zoomed), folded (|uv| − s − complexity,
/// turned by rotate2, s divided by `pattern`) while the step count is below MaxIterations
/// and at most iterations + 1: 1 within the dot radius of the origin, else 0. `q` holds
/// iterations, DotSize (unused: see [`FRACTALDOTS_RADIUS`]), MaxIterations, complexity,
/// pattern, spacing, rotate1, rotate2 and zoom.
pub(super) fn fractaldots_grey(uv: (f64, f64), q: [f64; 9]) -> f64 {
    let [
        iterations,
        _,
        max_iter,
        complexity,
        pattern,
        spacing,
        rot1,
        rot2,
        zoom,
    ] = q;
    let rot = |(x, y): (f64, f64), a: f64| {
        let (s, c) = a.sin_cos();
        (x * c - y * s, y * c + x * s)
    };
    let uv = rot(uv, rot1);
    let mut uv = (uv.0 * zoom, uv.1 * zoom);
    let mut s = spacing;
    let mut k = 0;
    while (k as f64) < max_iter {
        uv = (uv.0.abs() - s - complexity, uv.1.abs() - s - complexity);
        uv = rot(uv, rot2);
        s /= pattern;
        if iterations < k as f64 {
            break;
        }
        k += 1;
    }
    if (uv.0 * uv.0 + uv.1 * uv.1).sqrt() > FRACTALDOTS_RADIUS {
        0.0
    } else {
        1.0
    }
}
