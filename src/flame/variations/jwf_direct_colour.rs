//! JWildfire's direct-colour stamps (`dc_mandala`, `dc_inversion`, `dc_poincaredisc`,
//! `dc_circuits`, `dc_turbulence`, `dc_gabornoise`), which colour the points they scatter by a
//! pattern, and `julian2dc` (Georg Kiehne's Apophysis direct-colour plugin).
//!
//! The dc_ variations compute an RGB colour. JWildfire either paints that RGB directly
//! (`Gradient` 0), paints the nearest palette colour (1) or uses the colour's luminance as the
//! palette index (2). The first two give the point its own colour ([`Acc::rgb`]; for 1 marked
//! so that the renderer, which knows the palette, draws the nearest key), the third sets the
//! palette index.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: `atan_xy` is its `getPrecalcAtan`
//! (atan2(x, y)), weights multiply the output linearly, integer parameters are rounded (those it
//! truncates, `(int) value`, are stored as reals and truncated where used), and random numbers
//! are drawn in the order JWildfire draws them, so that the tests can replay JWildfire's own code
//! on the same stream.

use std::f64::consts::{PI, TAU};

use super::util::{atan2_approx, cpp_max, cpp_min, fract, signum_java};
use super::*;

/// Shared trailing parameters of the dc_ variations.
macro_rules! dc_tail {
    ($n:literal) => {
        [
            p_range(concat!($n, "_ColorOnly"), 0.0, 0.0, 1.0),
            p_range(concat!($n, "_Gradient"), 0.0, 0.0, 2.0),
            p(concat!($n, "_scale_z"), 0.0),
            p(concat!($n, "_offset_z"), 0.0),
            p_range(concat!($n, "_reset_z"), 1.0, 0.0, 1.0),
        ]
    };
}
pub(super) use dc_tail;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("julian2dc", julian2dc)
        .params(&[
            p_int_nonzero("julian2dc_power", 2.0, NEG_INF, INF),
            p("julian2dc_dist", 1.0),
            p("julian2dc_col", 0.0),
            p("julian2dc_a", 1.0),
            p("julian2dc_b", 0.0),
            p("julian2dc_c", 0.0),
            p("julian2dc_d", 1.0),
            p("julian2dc_e", 0.0),
            p("julian2dc_f", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR),
    VarDef::new("dc_mandala", dc_mandala)
        .params(P_DC_MANDALA)
        .flags(DC_FLAGS),
    VarDef::new("dc_inversion", dc_inversion)
        .params(P_DC_INVERSION)
        .flags(DC_FLAGS),
    VarDef::new("dc_poincaredisc", dc_poincaredisc)
        .params(P_DC_POINCARE)
        .flags(DC_FLAGS)
        .prepare(prep_poincare),
    VarDef::new("dc_circuits", dc_circuits)
        .params(P_DC_CIRCUITS)
        .flags(DC_FLAGS | flag::STATEFUL),
    VarDef::new("dc_turbulence", dc_turbulence)
        .params(P_DC_TURBULENCE)
        .flags(DC_FLAGS),
    VarDef::new("dc_gabornoise", dc_gabornoise)
        .params(P_DC_GABOR)
        .flags(DC_FLAGS)
        .prepare(prep_gabor),
];

/// julian2dc: julian (the power-th root, one branch at random, radius scaled by
/// |z|^(dist/power)) of an affine image of the point; the colour is set from a blend of the
/// output radius and the branch angle (`col` = 0: angle, 1: radius).
fn julian2dc(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power, dist, col, a, b, c, d, e, f] = v.params();
    let x = a * t.x + b * t.y + e;
    let y = c * t.x + d * t.y + f;
    let branches = power.abs();
    let k = (rng.f01() * branches).floor().min(branches - 1.0);
    let angle = (y.atan2(x) + TAU * k) / power;
    let r = v.w * (x * x + y * y).powf(dist / power / 2.0);
    let (s, c) = angle.sin_cos();
    acc.color = ((r * col + angle / TAU * (1.0 - col)).abs()) % 1.0;
    [r * c, r * s, 0.0]
}

/// Java's `(int) value` on a parameter already clamped to a small range.
#[inline(always)]
fn trunc_i(x: f64) -> i64 {
    x as i64
}

/// GLSL `mod`: x − y·⌊x/y⌋.
#[inline(always)]
pub(super) fn gmod(x: f64, y: f64) -> f64 {
    x - y * (x / y).floor()
}

/// Folds a point into the wedge [0, k] of a kaleidoscope with mirror angle k.
fn kaleido(x: f64, y: f64, k: f64) -> (f64, f64) {
    let ang = (gmod(atan2_approx(y, x), 2.0 * k) - k).abs();
    let len = (x * x + y * y).sqrt();
    (len * ang.cos(), len * ang.sin())
}

/// Colour channels in 0..=255 as JWildfire quantises them.
pub(super) fn dc_bytes(rgb: [f64; 3]) -> [i64; 3] {
    rgb.map(|c| ((c * 256.0).floor() as i64).clamp(0, 255))
}

/// Luminance of quantised channels, in [0, 1].
pub(super) fn dc_luma(c: [i64; 3]) -> f64 {
    let r = (c[0] as f64 * 0.299) as i64;
    let g = (c[1] as f64 * 0.587) as i64;
    let b = (c[2] as f64 * 0.114) as i64;
    (r + g + b) as f64 / 255.0
}

/// The part all dc_ variations share. The point is the input (ColorOnly = 1) or uniform in a
/// square of half-side `half` (1 or 0.5); its pattern colour, quantised to bytes, is the
/// point's own colour (Gradient = 0, JWildfire's default), the gradient's colour nearest to
/// it (1: marked for the renderer, which knows the gradient, see [`Acc::rgb`]) or, by its
/// luminance, the palette index (Gradient = 2); the luminance, scaled and offset, gives z (which replaces the running
/// z when reset_z is 1). `tail` holds the five shared parameters, which come last (see
/// `dc_tail!`).
#[inline(always)]
pub(super) fn dc_common(
    v: &Prepared,
    tail: [f64; 5],
    t: &VarIn,
    acc: &mut Acc,
    rng: &mut FastRng,
    half: f64,
    pattern: impl FnOnce(f64, f64) -> [f64; 3],
) -> V3 {
    let [color_only, gradient, scale_z, offset_z, reset_z] = tail;
    let (x, y) = if trunc_i(color_only) == 1 {
        (t.x, t.y)
    } else if half == 1.0 {
        let x = 2.0 * rng.f01() - 1.0;
        (x, 2.0 * rng.f01() - 1.0)
    } else {
        let x = rng.f01() - 0.5;
        (x, rng.f01() - 0.5)
    };
    let bytes = dc_bytes(pattern(x, y));
    let luma = dc_luma(bytes);
    let gradient = trunc_i(gradient);
    if gradient < 2 {
        // Gradient 1 asks the renderer for the palette colour nearest to the pattern's.
        let lower = if gradient == 1 { Acc::NEAREST_KEY } else { 0.0 };
        acc.rgb = Some(bytes.map(|c| c as f64 - lower));
    } else {
        acc.color = luma;
    }
    let dz = luma * scale_z + offset_z;
    let z = if trunc_i(reset_z) == 1 {
        if v.form == Form::Regular {
            acc.z = 0.0;
        }
        dz
    } else if v.form == Form::Regular {
        dz
    } else {
        t.z + dz
    };
    [v.w * x, v.w * y, z]
}

pub(super) const DC_FLAGS: u32 =
    flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::WRITES_ACC;

/// JWildfire's rounded 1/π in dc_mandala (kept: it is not the nearest double to 1/π).
#[allow(clippy::approx_constant)]
const MANDALA_INV_PI: f64 = 0.318309886183791;

/// dc_mandala's colour: a doubly folded kaleidoscope, an optional modular tiling, then an
/// absolute-value inversion map iterated up to 73 times on a 3-vector that becomes RGB.
pub(super) fn mandala_rgb(q: [f64; 9], x: f64, y: f64) -> [f64; 3] {
    let [mx, my, scale, sides, multiply, loops, inv_r, inv_g, inv_b] = q;
    let zoom = 5.5 - scale;
    let k = PI / sides.floor();
    let s = kaleido(zoom * x, zoom * y, k);
    let t = kaleido(s.0, s.1, k);
    let dot = t.0 * s.0 + t.1 * s.1;
    let c = dot.cos();
    let mut u = (s.0 * (1.0 - c) + t.0 * c, s.1 * (1.0 - c) + t.1 * c);
    if multiply > 0.001 {
        let m = multiply.floor();
        let ux = u.0 + gmod(gmod(u.0, m), -u.1);
        let uy = u.1 + gmod(gmod(u.1, m), -u.0);
        u = (ux, uy);
    }
    let mut p = [u.0, u.1, mx * dot];
    let shift = [1.0, 1.02, my * MANDALA_INV_PI];
    let gain = [1.3, 0.999, 0.678];
    let limit = loops.floor();
    for l in 0..73 {
        if l as f64 > limit {
            break;
        }
        let d = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        let w: [f64; 3] = std::array::from_fn(|i| gain[i] * (p[i].abs() / d - shift[i]).abs());
        p = [w[0], w[2], w[1]];
    }
    let flips = [inv_r, inv_g, inv_b];
    for i in 0..3 {
        if trunc_i(flips[i]) == 1 {
            p[i] = 1.0 - p[i];
        }
    }
    p
}

/// dc_mandala: a kaleidoscopic fractal stamp over [−1, 1]² (after a GLSL shader of the same
/// name).
fn dc_mandala(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, _, _, tail @ ..] = v.params::<14>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        mandala_rgb(v.params(), x, y)
    })
}

const P_DC_MANDALA: &[Param] = &{
    let tail = dc_tail!("dc_mandala");
    [
        p("dc_mandala_mX", 0.025),
        p("dc_mandala_mY", -0.001245675),
        p("dc_mandala_scale", 2.0),
        p("dc_mandala_sides", 12.0),
        p("dc_mandala_multiply", 1.5),
        p("dc_mandala_loops", 64.0),
        p_range("dc_mandala_iR", 0.0, 0.0, 1.0),
        p_range("dc_mandala_iG", 0.0, 0.0, 1.0),
        p_range("dc_mandala_iB", 1.0, 0.0, 1.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// dc_inversion's colour: the point folded (|x|), scaled, shifted and inverted in a circle,
/// repeatedly; brightness from the last and the smallest size reached.
fn inversion_rgb(v: &Prepared, x: f64, y: f64) -> [f64; 3] {
    let [_, time, iterations, sx, sy] = v.params();
    let iters = trunc_i(iterations);
    let (ox, oy) = ((time * 0.123).sin(), (time * 0.0567).atan());
    let (mut vx, mut vy) = (x, y);
    let mut l = 0.0;
    let mut l_min = 10000.0;
    for _ in 0..iters {
        vx = vx.abs();
        vx = vx * sx + ox;
        vy = vy * sy + oy;
        // Inversion in the circle of radius 0.9 around (0.5, 0.5), plus a faint warp.
        let (dx, dy) = (vx - 0.5, vy - 0.5);
        let f = 0.9 / (dx * dx + dy * dy);
        let mut ix = 0.5 - dx * 0.9 * f;
        let mut iy = 0.5 - dy * 0.9 * f;
        ix += (ix * 0.001).sin() / (iy * 0.001).cos();
        iy += (ix * 0.001).sin() * (iy * 0.001).cos();
        vx = ix;
        vy = iy;
        let (qx, qy) = (vx * vx, vy * vy);
        l = (qx * qx + qy * qy).sqrt();
        l_min = cpp_min(l, l_min);
    }
    let tt = 2.1 + time * 0.025;
    let base = [
        (tt * 1.790).sin() * 0.5 + 0.5,
        (tt * 1.345).sin() * 0.5 + 0.5,
        (tt * 1.123).sin() * 0.5 + 0.5,
    ];
    let norm = (base[0] * base[0] + base[1] * base[1] + base[2] * base[2]).sqrt();
    let bright = l * l * 11.0;
    let m = (3.0 * l_min * (1.0 - l_min)).powf(5.0) + 0.14;
    base.map(|c| 1.0 - (-((c / norm * bright) * m)).exp())
}

/// dc_inversion: an iterated circle-inversion fractal stamp over [−1, 1]².
fn dc_inversion(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, tail @ ..] = v.params::<10>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| inversion_rgb(v, x, y))
}

const P_DC_INVERSION: &[Param] = &{
    let tail = dc_tail!("dc_inversion");
    [
        p("dc_inversion_seed", 10000.0),
        p("dc_inversion_time", 0.0),
        p_range("dc_inversion_iterations", 50.0, 0.0, 100.0),
        p_range("dc_inversion_scaleX", 1.5, 1.1, 3.0),
        p_range("dc_inversion_scaleY", 1.5, 1.1, 3.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// Derived values of dc_poincaredisc (after its parameters): the centre and radius of the
/// third folding circle and the normal of the second fold line.
fn prep_poincare(v: &mut Prepared) {
    let [_, _, n, p] = v.params();
    let n = trunc_i(n) as f64;
    let m = trunc_i(p) as f64;
    let a = PI / n;
    let mut b = PI / m;
    if a + b >= 0.5 * PI {
        b = 0.5 * PI - a - 0.01;
    }
    let (sa, ca) = a.sin_cos();
    let sb = b.sin();
    let s = (a + b).cos() / (1.0 - sa * sa - sb * sb).sqrt();
    let cx = (s * s + 1.0) / (2.0 * s * ca);
    let cr = (cx * cx - 1.0).sqrt();
    v.p.extend_from_slice(&[cx, cr, sa, -ca]);
}

/// dc_poincaredisc's colour: a hyperbolic (n, p) tiling of the unit disc by repeated folds
/// (a mirror, a line and a circle), shaded by the distance to the circle and checkered by the
/// parity of the line and circle folds.
fn poincare_rgb(v: &Prepared, x: f64, y: f64) -> [f64; 3] {
    let [zoom, max_iter, _, _, _, checkers1, checkers2] = v.params();
    let [cx, cr, nx, ny] = v.derived();
    let (mut zx, mut zy) = (x * zoom, y * zoom);
    if zx * zx + zy * zy > 1.0 {
        return [0.0; 3];
    }
    // JWildfire's mirror-fold counter never counts (it compares a point with itself), so
    // only the line and circle folds are counted.
    let mut line_folds = 0.0;
    let mut circle_folds = 0.0;
    for _ in 0..trunc_i(max_iter) {
        zy = zy.abs();
        let t = 2.0 * cpp_min(0.0, zx * nx + zy * ny);
        if t < 0.0 {
            line_folds += 1.0;
        }
        zx -= nx * t;
        zy -= ny * t;
        zx -= cx;
        let k = cpp_max(cr * cr / (zx * zx + zy * zy), 1.0);
        if k != 1.0 {
            circle_folds += 1.0;
        }
        zx *= k;
        zy *= k;
        zx += cx;
    }
    let dx = zx - cx;
    let r = ((dx * dx + zy * zy).sqrt() - cr).abs().powf(0.25);
    let c1 = if trunc_i(checkers1) == 1 { 1.0 } else { 0.0 };
    let c2 = if trunc_i(checkers2) == 1 { 1.0 } else { 0.0 };
    let k = gmod(c1 * line_folds + c2 * circle_folds, 2.0);
    [r * (0.5 * k + 0.5); 3]
}

/// dc_poincaredisc: a hyperbolic tiling of the Poincaré disc over [−0.5, 0.5]².
fn dc_poincaredisc(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, tail @ ..] = v.params::<12>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| poincare_rgb(v, x, y))
}

const P_DC_POINCARE: &[Param] = &{
    let tail = dc_tail!("dc_poincaredisc");
    [
        p("dc_poincaredisc_zoom", 2.0),
        p_range("dc_poincaredisc_MaxIter", 10.0, 0.0, 20.0),
        p_range("dc_poincaredisc_N", 4.0, 3.0, 20.0),
        p_range("dc_poincaredisc_P", 5.0, 3.0, 20.0),
        p_range("dc_poincaredisc_checkers0", 1.0, 0.0, 1.0),
        p_range("dc_poincaredisc_checkers1", 1.0, 0.0, 1.0),
        p_range("dc_poincaredisc_checkers2", 1.0, 0.0, 1.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// dc_circuits' running glow: JWildfire seeds it with (101 + 2)·0.9 from the default glow
/// and intensity (whatever the parameters say) and carries it from call to call.
const CIRCUITS_GLOW0: f64 = (101.0 + 2.0) * 0.9;

/// One orbit of dc_circuits' fold map: colour, and the glow it adds.
fn circuits_orbit(v: &Prepared, zx0: f64, zy0: f64, t: f64) -> ([f64; 3], f64) {
    let [_, _, _, intensity, _, pulse, _, loops, zoom] = v.params();
    let (mut zx, mut zy) = (zx0, zy0);
    let mut m = 0.0;
    let mut ot = 1000.0;
    let mut ot2 = 1000.0;
    let mut budget = (loops / 4.0 + (5.0 * zoom).floor()).floor();
    for i in 0..11 {
        let d = (zx * zx + zy * zy).clamp(0.1, 0.5);
        zx = zx.abs() / d - t;
        zy = zy.abs() / d - t;
        let l = (zx * zx + zy * zy).sqrt();
        let o = cpp_min(cpp_max(cpp_min(zx, zy).abs(), -l + 0.25), (l - 0.25).abs());
        ot = cpp_min(ot, o);
        ot2 = cpp_min(l * 0.1, ot2);
        m = cpp_max(m, i as f64 * (1.0 - signum_java(ot - o).abs()));
        if budget <= 0.0 {
            break;
        }
        budget -= 1.0;
    }
    m += 1.0;
    let w = intensity * zoom * m;
    let circ = (cpp_max(0.0, w - ot2) / w).powf(6.0);
    let glow = cpp_max((cpp_max(0.0, w - ot) / w).powf(0.25), circ);
    let base = [0.1 + 0.45, 0.1 + 0.75, 0.1 + m * 0.1];
    let len = (base[0] * base[0] + base[1] * base[1] + base[2] * base[2]).sqrt();
    let shade = 0.4 + gmod(m / 9.0 - t * pulse + ot2 * 2.0, 1.0);
    let hot = circ * (10.0 - m) * 3.0;
    let tint = [1.0, 0.7, 0.3];
    let col = std::array::from_fn(|i| base[i] / len * shade + tint[i] * hot);
    (col, glow)
}

/// dc_circuits' colour at (x, y), given the running glow; returns the colour and the new
/// glow.
fn circuits_rgb(v: &Prepared, x: f64, y: f64, glow0: f64) -> ([f64; 3], f64) {
    let [_, time, rate, _, focus, _, _, loops, zoom] = v.params();
    let mut n = time * 0.01 * rate;
    let mut tt = 2.0 * rate;
    if n > 6.0 * rate {
        n -= 8.0 * rate;
    }
    if n < 4.0 * rate {
        tt += n;
    } else {
        tt = 8.0 * rate - n;
    }
    let zz = 1.05 - zoom;
    let sph = (x * x + y * y).sqrt() * 0.1;
    let sph = (1.0 - sph * sph).sqrt() * 2.0;
    let a = tt * PI;
    let b = a + tt;
    let c = a.cos() + b.sin();
    let (sb, cb) = b.sin_cos();
    let (sa, ca) = a.sin_cos();
    let (ux, uy) = (cb * x + sb * y, x * -sb + y * cb);
    let (ux, uy) = (ca * ux + -sa * uy, ux * sa + uy * ca);
    let ux = (ux - c.sin() / PI) * zz;
    let uy = (uy - c.cos() / PI) * zz;
    let pix = 0.5 / 1000.0 * zz / sph;
    let dof = zoom * focus + tt * 0.25;
    let mut left = loops.floor();
    let mut glow = glow0;
    let mut col = [0.0; 3];
    for aa in 0..24 {
        let ax = (aa as f64 / 6.0).floor();
        let ay = gmod(aa as f64, 6.0).floor();
        let (c, g) = circuits_orbit(v, ux + ax * pix * dof, uy + ay * pix * dof, tt);
        col = c;
        glow += g;
        if left <= 0.0 {
            break;
        }
        left -= 1.0;
    }
    let fl = loops.floor();
    glow /= fl;
    let fade = 1.0 - (x * x + y * y).sqrt();
    let gain = [1.2, 1.1, 1.0];
    let rgb = std::array::from_fn(|i| (0.15 * (1.0 - glow) + col[i] / fl * glow) * fade * gain[i]);
    (rgb, glow)
}

/// dc_circuits: glowing circuit-like traces over [−1, 1]² (a kaliset-style fold fractal). The
/// glow level carries over from one point to the next, as in JWildfire (its state is shared
/// by the render threads).
fn dc_circuits(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, _, _, tail @ ..] = v.params::<14>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        let glow0 = if v.state.get(1) == 1.0 {
            v.state.get(0)
        } else {
            CIRCUITS_GLOW0
        };
        let (rgb, glow) = circuits_rgb(v, x, y, glow0);
        v.state.set(0, glow);
        v.state.set(1, 1.0);
        rgb
    })
}

const P_DC_CIRCUITS: &[Param] = &{
    let tail = dc_tail!("dc_circuits");
    [
        p("dc_circuits_Seed", 1000000.0),
        p("dc_circuits_time", 0.0),
        p("dc_circuits_rate", 0.8),
        p("dc_circuits_intensity", 0.9),
        p("dc_circuits_focus", 1.5),
        p("dc_circuits_pulse", 10.0),
        p("dc_circuits_glow", 2.0),
        p("dc_circuits_loops", 15.0),
        p("dc_circuits_zoom", 1.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// dc_turbulence's grey level: a few rounds of a sin/cos displacement of the zoomed point
/// (shifted by −20), accumulating inverse distances ("water caustics").
fn turbulence_rgb(v: &Prepared, x: f64, y: f64) -> [f64; 3] {
    let [_, time, zoom, level] = v.params();
    let level = trunc_i(level);
    let (px, py) = (x * zoom - 20.0, y * zoom - 20.0);
    let (mut ix, mut iy) = (px, py);
    let mut c = 1.0;
    let inten = 0.05;
    for n in 0..level {
        let t = time * (1.0 - 3.0 / (n + 1) as f64);
        let nx = px + ((t - ix).cos() + (t + iy).sin());
        let ny = py + ((t - iy).sin() + (t + ix).cos());
        ix = nx;
        iy = ny;
        let a = px / ((ix + t).sin() / inten);
        let b = py / ((iy + t).cos() / inten);
        c += 1.0 / (a * a + b * b).sqrt();
    }
    c /= level as f64;
    c = 1.5 - c.sqrt();
    [c * c * c * c; 3]
}

/// dc_turbulence: a grey caustic pattern over [−0.5, 0.5]².
fn dc_turbulence(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, tail @ ..] = v.params::<9>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| turbulence_rgb(v, x, y))
}

const P_DC_TURBULENCE: &[Param] = &{
    let tail = dc_tail!("dc_turbulence");
    [
        p("dc_turbulence_seed", 10000.0),
        p_range("dc_turbulence_time", 0.0, 1.0, 1000.0),
        p("dc_turbulence_zoom", 8.0),
        p_range("dc_turbulence_level", 3.0, 1.0, 5.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// Number of kernel centres of dc_gabornoise.
const GABOR_N: usize = 100;

/// Derived values of dc_gabornoise: its 100 pseudo-random centres (a hash of the index,
/// turned by a time-dependent shear), as (x, y) pairs.
fn prep_gabor(v: &mut Prepared) {
    let [_, time] = v.params();
    let hash = |p: f64, k: f64| (fract((k * p).sin() * 43141.59265) * 2.0 - 1.0) * 30.0;
    for i in 0..GABOR_N {
        let i = i as f64;
        let (hx, hy, hz) = (hash(i, 63.31), hash(i, 395.467), hash(i, 1.0));
        let c = (hz / 1e2 * time).cos();
        v.p.push(c * hx + (33.0 + c) * hy);
        v.p.push(hx * (11.0 + c) + hy * c);
    }
}

/// dc_gabornoise's colour: the summed (approximate) angles from the mirrored, zoomed point to
/// the centres, through a cosine palette.
fn gabor_rgb(v: &Prepared, x: f64, y: f64) -> [f64; 3] {
    let [_, _, zoom] = v.params();
    let centres = v.table(0);
    let ux = (x * zoom).abs() * 45.0;
    let uy = (y * zoom) * 45.0;
    let mut a = 0.0;
    for c in centres.chunks_exact(2) {
        a += atan2_approx(ux - c[0], uy - c[1]);
    }
    [
        a.cos() * 0.6 + 0.6,
        (23.0 + a).cos() * 0.6 + 0.6,
        (21.0 + a).cos() * 0.6 + 0.6,
    ]
}

/// dc_gabornoise: a fingerprint-like angular pattern over [−0.5, 0.5]².
fn dc_gabornoise(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| gabor_rgb(v, x, y))
}

const P_DC_GABOR: &[Param] = &{
    let tail = dc_tail!("dc_gabornoise");
    [
        p_range("dc_gabornoise_seed", 10000.0, 0.0, 10000.0),
        p("dc_gabornoise_time", 0.0),
        p_range("dc_gabornoise_zoom", 20.0, 1.0, 100.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

#[cfg(test)]
mod tests;
