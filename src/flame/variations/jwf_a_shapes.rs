//! JWildfire's figures drawn from the point's angle, outlined or filled at random
//! (`cannabiscurve_wf`, Hamid Naderi Yeganeh's `maple_leaf` and `japanese_maple_leaf`), the
//! random cone `cone`, the dotted grid `r_circleblur`, `spliptic_bs`, `tile_reverse` and the
//! spiral target `target_sp`, elliptic with every constant a parameter (`elliptic2`) and the
//! two sets of parallel bands `parallel`, and `glynnlissa` and `glynnSShape` (GlynnSim with a Lissajous figure or a superformula shape).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: `atan_xy` is its `getPrecalcAtan`
//! (atan2(x, y)), weights multiply the output linearly, and random numbers are drawn in the
//! order JWildfire draws them.

use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, PI, TAU};

use super::util::jwf_math as jm;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("cannabiscurve_wf", cannabiscurve_wf)
        .params(&[p("cannabiscurve_wf_filled", 0.85)])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("maple_leaf", maple_leaf)
        .params(&[p("maple_leaf_filled", 0.5)])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("japanese_maple_leaf", japanese_maple_leaf)
        .params(&[p("japanese_maple_leaf_filled", 0.15)])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("cone", cone)
        .params(&[
            p("cone_radius1", 0.5),
            p("cone_radius2", 1.0),
            p("cone_size1", 0.5),
            p("cone_size2", 2.0),
            p("cone_ywave", 1.0),
            p("cone_xwave", 1.0),
            p("cone_height", 1.0),
            p("cone_warp", 1.0),
            p("cone_weight", 2.0),
        ])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z),
    VarDef::new("r_circleblur", r_circleblur)
        .params(&[
            p("r_circleblur_n", 1.0),
            p("r_circleblur_seed", 0.0),
            p("r_circleblur_dist", 0.5),
            p("r_circleblur_min", 0.1),
            p("r_circleblur_max", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("spliptic_bs", spliptic_bs)
        .params(&[p("spliptic_bs_x", 0.05), p("spliptic_bs_y", 0.05)])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("tile_reverse", tile_reverse)
        .params(&[
            p("tile_reverse_space", 1.0),
            p("tile_reverse_reversal", 1.0),
            p_int("tile_reverse_vertical", 0.0, NEG_INF, INF),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_ACC),
    VarDef::new("target_sp", target_sp)
        .params(&[
            p("target_sp_twist", 0.0),
            p("target_sp_n_of_sp", 1.0),
            // JWildfire draws these two defaults at random; the values of its test vectors.
            p("target_sp_size", 1.2782142051432566),
            p("target_sp_tightness", 0.728_271_834_281_289),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("elliptic2", elliptic2)
        .params(&[
            p("elliptic2_a1", 1.0),
            p("elliptic2_a2", 1.0),
            p("elliptic2_a3", 0.0),
            p("elliptic2_b1", 2.0),
            p("elliptic2_b2", 1.0),
            p("elliptic2_c", 0.5),
            p("elliptic2_d", 1.0),
            p("elliptic2_e", 0.5),
            p("elliptic2_f", 1.0),
            p("elliptic2_g", 1.0),
            p("elliptic2_h", 2.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("parallel", parallel)
        .params(&[
            p("parallel_x1width", 5.0),
            p("parallel_x1tilesize", 0.5),
            p("parallel_x1mod1", 0.3),
            p("parallel_x1mod2", 1.0),
            p("parallel_x1height", 0.5),
            p("parallel_x1move", 1.0),
            p("parallel_x2width", 5.0),
            p("parallel_x2tilesize", 0.5),
            p("parallel_x2mod1", 0.3),
            p("parallel_x2mod2", 1.0),
            p("parallel_x2height", 0.5),
            p("parallel_x2move", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("glynnlissa", glynnlissa)
        .params(&[
            p("glynnlissa_radius", 1.0),
            p("glynnlissa_radius1", 0.5),
            p("glynnlissa_thickness", 1.0),
            p("glynnlissa_phi1", 0.0),
            p("glynnlissa_a", 3.0),
            p("glynnlissa_b", 2.0),
            p("glynnlissa_width", 0.0),
            p("glynnlissa_phase", 0.0),
            p("glynnlissa_scale", 0.71),
            p("glynnlissa_pow", 1.5),
            p_range("glynnlissa_contrast", 0.5, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("glynnSShape", glynn_sshape)
        .params(&[
            p("glynnSShape_radius", 1.0),
            p("glynnSShape_radius1", 0.5),
            p("glynnSShape_thickness", 1.0),
            p("glynnSShape_phi1", 0.0),
            p("glynnSShape_m", 5.0),
            p("glynnSShape_n1", 1.7),
            p("glynnSShape_n2", 1.7),
            p("glynnSShape_n3", 1.7),
            p("glynnSShape_scale", 0.71),
            p("glynnSShape_pow", 1.5),
            p_range("glynnSShape_contrast", 0.5, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
];

/// A radius of `r` on the outline, or with odds `filled` a uniform fraction of it (two draws).
fn fill(filled: f64, r: f64, rng: &mut FastRng) -> f64 {
    if filled > 0.0 && filled > rng.f01() {
        r * rng.f01()
    } else {
        r
    }
}

/// cannabiscurve_wf: the cannabis curve r(a) = (1 + 0.9 cos 8a)(1 + 0.1 cos 24a)(0.9 +
/// 0.1 cos 200a)(1 + sin a), drawn at the point's angle, filled with odds `filled`.
fn cannabiscurve_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [filled] = v.params();
    let a = t.atan_xy;
    let r = (1.0 + 0.9 * (8.0 * a).cos())
        * (1.0 + 0.1 * (24.0 * a).cos())
        * (0.9 + 0.1 * (200.0 * a).cos())
        * (1.0 + a.sin());
    let a = a + PI / 2.0;
    let r = fill(filled, r, rng);
    [v.w * a.sin() * r, v.w * a.cos() * r, 0.0]
}

/// maple_leaf: Hamid Naderi Yeganeh's maple leaf, drawn at the point's angle, filled with
/// odds `filled`. (One term carries Java's integer 1/4, which is 0, as JWildfire has it.)
fn maple_leaf(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [filled] = v.params();
    let t = t.atan_xy - FRAC_PI_2;
    let r = fill(filled, v.w, rng);
    let c = |k: f64| (k * t).cos();
    let s6 = (6.0 * t).sin();
    let lx = (1.0
        + c(6.0).powi(2)
        + 0.2 * (c(6.0) * c(24.0)).powi(10)
        + (c(30.0).powi(12) / 9.0) * (1.0 - s6.powi(10)))
        * (2.0 * t).sin()
        * (1.0 - c(1.0).powi(4))
        * (1.0 - c(1.0).powi(10) * c(3.0).powi(2));
    let ly = 21.0 / 20.0
        * c(2.0)
        * (1.0 - c(1.0).powi(4) + 0.5 * (c(1.0) * c(3.0)).powi(10))
        * (1.0
            + c(6.0).powi(2)
            + 0.2 * (c(6.0) * c(18.0)).powi(10)
            + (0.25 * c(30.0).powi(4) + 0.1 * c(30.0).powi(12))
                * (1.0 - c(1.0).powi(10) * c(3.0).powi(2))
                * (1.0 - s6.powi(10)));
    [r * lx, r * ly, 0.0]
}

/// japanese_maple_leaf: Hamid Naderi Yeganeh's Japanese maple leaf at half the point's angle,
/// scaled by 0.667, filled with odds `filled`.
fn japanese_maple_leaf(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [filled] = v.params();
    let t = t.atan_xy * 0.5 + FRAC_PI_2;
    let r = fill(filled, v.w, rng) * 0.667;
    let c = |k: f64| (k * t).cos();
    let s8 = (8.0 * t).sin();
    let lx = (4.0 / 15.0
        + c(8.0).powi(2)
        + 0.2 * (c(8.0) * c(24.0)).powi(10)
        + (c(80.0).powi(2) / 6.0 + c(80.0).powi(10) / 15.0))
        * (1.0 - s8.powi(10))
        * (2.0 * t).sin()
        * (1.0 + t.sin())
        * (1.0 - c(1.0).powi(10) * c(3.0).powi(2) + c(1.0).powi(9) * c(5.0).powi(10) / 30.0);
    let ly = (8.0 / 30.0
        + c(8.0).powi(2)
        + 0.2 * (c(8.0) * c(24.0)).powi(10)
        + (c(80.0).powi(2) / 6.0 + c(80.0).powi(10) / 15.0)
            * (1.0 - c(1.0).powi(10) * c(3.0).powi(2))
            * (1.0 - s8.powi(10)))
        * c(2.0)
        * (1.0 + t.sin() + (c(1.0) * c(3.0)).powi(10));
    [r * lx, r * ly, 0.0]
}

/// cone (Brad Stefanov): julia and hemisphere mixed: radius size2/√(warp·x² + y² + size1), the
/// angle atan2(x, y)·radius1 plus π·radius2 times a random integer below `weight`, lifted to
/// z by `height`.
fn cone(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        radius1,
        radius2,
        size1,
        size2,
        ywave,
        xwave,
        height,
        warp,
        weight,
    ] = v.params();
    let r = v.w / (t.x * t.x * warp + t.y * t.y + size1).sqrt() * size2;
    let k = (weight * rng.f01()).trunc();
    let xx = t.atan_xy * radius1 + PI * k * radius2;
    [r * (xx * xwave).cos(), r * (xx * ywave).sin(), r * height]
}

/// Java's `x - trunc(x)` of a sine hash.
fn hash_frac(a: f64) -> f64 {
    a - a.trunc()
}

/// r_circleblur (Tatyana Zabanova): the plane wound into rings (radius taken modulo n),
/// rounded to a grid, and each grid point replaced by a random disc whose size and offset
/// come from hashes of the point.
fn r_circleblur(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n, seed, dist, min, max] = v.params();
    let angle = t.y.atan2(t.x);
    let rad = (t.x * t.x + t.y * t.y).sqrt() % n.abs();
    let by = ((angle + rad).sin() * rad + 0.5).floor();
    let bx = ((angle + rad).cos() * rad + 0.5).floor();
    let rad2 = rng.f01().sqrt() * 0.5;
    let angle2 = rng.f01() * TAU;
    let a1 = hash_frac((bx * 127.1 + by * 311.7 + seed).sin() * 43758.5453);
    let a2 = hash_frac((bx * 269.5 + by * 183.3 + seed).sin() * 43758.5453);
    let a3 = hash_frac((by * 12.9898 + bx * 78.233 + seed).sin() * 43758.5453);
    let rad2 = rad2 * (a3 * (max - min) + min);
    let oy = by + rad2 * angle2.sin() + a1 * dist;
    let ox = bx + rad2 * angle2.cos() + a2 * dist;
    [v.w * ox, v.w * oy, 0.0]
}

/// √x, 0 below 1e-300, with JWildfire's table-based square root (`FAST_MATH`): the elliptic
/// family needs its last ulps near the origin, where xmax is 1 plus a few ulps.
fn jm_sqrt_safe(x: f64) -> f64 {
    if x < 1e-300 { 0.0 } else { jm::sqrt(x) }
}

/// spliptic_bs (Brad Stefanov): elliptic with its halves split apart by ±x and ±y, the y
/// half chosen at random.
fn spliptic_bs(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [px, py] = v.params();
    let k = v.w / FRAC_PI_2;
    let tmp = t.y * t.y + t.x * t.x + 1.0;
    let x2 = 2.0 * t.x;
    let xmax = 0.5 * (jm::sqrt(tmp + x2) + jm::sqrt(tmp - x2));
    let a = t.x / xmax;
    let b = jm_sqrt_safe(1.0 - a * a);
    let ox = if t.x >= 0.0 {
        k * jm::atan2(a, b) + px
    } else {
        k * jm::atan2(a, b) - px
    };
    let l = k * (xmax + jm_sqrt_safe(xmax - 1.0)).ln() + py;
    let oy = if rng.f01() < 0.5 { l } else { -l };
    [ox, oy, 0.0]
}

/// tile_reverse (Whittaker Courtney): the point mirrored (`reversal` 1) and moved by ±space
/// along x (or y with `vertical` 1), the side at random; replaces the xform's sum so far.
fn tile_reverse(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [space, reversal, vertical] = v.params();
    let n = rng.f01();
    let rev = if reversal == 1.0 { -1.0 } else { 1.0 };
    if n == 0.5 {
        return [0.0; 3];
    }
    let sh = if n < 0.5 { space } else { -space };
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    if vertical != 1.0 {
        [v.w * rev * t.x + sh, v.w * t.y, 0.0]
    } else {
        [v.w * t.x, v.w * rev * t.y + sh, 0.0]
    }
}

/// target_sp: `n_of_sp` spiral arms of width size/2 alternately rotated by π·twist and by
/// π·twist − π. The weight is not used.
fn target_sp(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [twist, n_of_sp, size, tightness] = v.params();
    let n = n_of_sp.trunc();
    let half = 0.5 * size;
    let rota = PI * twist;
    let mut a = t.y.atan2(t.x);
    let r = (t.x * t.x + t.y * t.y).sqrt();
    let mut s = tightness * r.ln() + n * FRAC_1_PI * (a + PI);
    if s < 0.0 {
        s -= half;
    }
    s = s.abs() % size;
    a += if s < half { rota } else { -PI + rota };
    [r * a.cos(), r * a.sin(), 0.0]
}

/// elliptic2: elliptic with every constant a parameter; the lower or upper half at random
/// (odds e).
fn elliptic2(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a1, a2, a3, b1, b2, c, d, e, f, g, h] = v.params();
    let k = v.w / (PI / h);
    let tmp = t.y * t.y + t.x * t.x + a1;
    let x2 = b1 * t.x;
    let xmax = c * (jm::sqrt(tmp + x2) + jm::sqrt(tmp - x2));
    let a = t.x / xmax * a2;
    let b = jm_sqrt_safe(d - a * a) * b2;
    let ox = k * jm::atan2(a, b) - FRAC_PI_2 * a3;
    let oy = if rng.f01() < e {
        k * (xmax + jm_sqrt_safe(xmax - f)).ln()
    } else {
        -(k * (xmax + jm_sqrt_safe(xmax - g)).ln())
    };
    [ox, oy, 0.0]
}

/// One of parallel's two band sets: x spread to a random tile (an exponential draw of scale
/// `width` with a random sign, rounded), y folded into bands and moved by ±move.
fn parallel_band(t: &VarIn, q: &[f64], sign: f64, w: f64, rng: &mut FastRng) -> V3 {
    let (width, tilesize, mod1, mod2, height, mv) = (q[0], q[1], q[2], q[3], q[4], q[5]);
    let xr = mod2 * mod1;
    let x1 = if rng.f01() < 0.5 { width } else { -width };
    let ox = tilesize * (t.x + (x1 * rng.f01().ln() + 0.5).floor());
    let oy = if t.y > mod1 {
        height * (-mod1 + (t.y + mod1) % xr)
    } else if t.y < -mod1 {
        height * (mod1 - (mod1 - t.y) % xr)
    } else {
        height * t.y
    };
    [ox, oy + sign * w * mv, 0.0]
}

/// parallel: two sets of horizontal bands of tiles, one above (moved by +x1move) and one
/// below (−x2move), the set chosen at random. The weight only moves the bands.
fn parallel(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 12] = v.params();
    if rng.f01() < 0.5 {
        parallel_band(t, &q[0..6], 1.0, v.w, rng)
    } else {
        parallel_band(t, &q[6..12], -1.0, v.w, rng)
    }
}

/// GlynnSim's common part (an inversion in the circle of radius `radius`, partial by
/// `contrast`, whose inner disc of radius radius1 at angle phi1 holds `figure`, a point of the
/// disc's figure already scaled into it; a negative radius1 draws a random ring instead).
/// `q` = [radius, radius1, thickness, phi1, pow, contrast].
pub(super) fn glynn_common(
    v: &Prepared,
    t: &VarIn,
    rng: &mut FastRng,
    q: [f64; 6],
    figure: (f64, f64),
) -> V3 {
    let [radius, radius1, thickness, phi1, pw, contrast] = q;
    let (s1, c1) = (PI * phi1 / 180.0).sin_cos();
    let (x1, y1) = (radius * c1, radius * s1);
    let fig = [v.w * (figure.0 + x1), v.w * (figure.1 + y1), 0.0];
    let r = (t.x * t.x + t.y * t.y).sqrt();
    if r < radius.abs() {
        if radius1 >= 0.0 {
            return fig;
        }
        let rr = radius1 * (thickness + (1.0 - thickness) * rng.f01());
        let phi = TAU * rng.f01();
        return [
            v.w * (rr * phi.cos() + x1),
            v.w * (rr * phi.sin() + y1),
            0.0,
        ];
    }
    let alpha = radius.abs() / r;
    let (xi, yi) = if rng.f01() > contrast * alpha.powf(pw.abs()) {
        (t.x, t.y)
    } else {
        (alpha * alpha * t.x, alpha * alpha * t.y)
    };
    if (xi - x1).powi(2) + (yi - y1).powi(2) < radius1 * radius1 {
        fig
    } else {
        [v.w * xi, v.w * yi, 0.0]
    }
}

/// glynnlissa: GlynnSim whose inner disc holds the Lissajous figure sin(a·t + phase),
/// sin(b·t), widened by `width`.
fn glynnlissa(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        radius,
        radius1,
        thickness,
        phi1,
        a,
        b,
        width,
        phase,
        scale,
        pw,
        contrast,
    ] = v.params();
    let tt = rng.f01() * TAU;
    let (px, py) = ((a * tt + phase).sin(), (b * tt).sin());
    let yj = rng.f01() - 0.5;
    let fig = (
        (px * scale + width * yj) * radius1,
        (py * scale + width * yj) * radius1,
    );
    glynn_common(
        v,
        t,
        rng,
        [radius, radius1, thickness, phi1, pw, contrast],
        fig,
    )
}

/// The superformula's point at angle phi (a = b = 1): r(phi)⁻¹·(cos phi, sin phi), the origin
/// where r is 0.
fn supershape(m: f64, n1: f64, n2: f64, n3: f64, phi: f64) -> (f64, f64) {
    let t1 = (m * phi / 4.0).cos().abs().powf(n2);
    let t2 = (m * phi / 4.0).sin().abs().powf(n3);
    let r = (t1 + t2).powf(1.0 / n1);
    if r.abs() == 0.0 {
        (0.0, 0.0)
    } else {
        (phi.cos() / r, phi.sin() / r)
    }
}

/// glynnSShape: GlynnSim whose inner disc holds Gielis' superformula shape (m, n1, n2, n3).
fn glynn_sshape(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        radius,
        radius1,
        thickness,
        phi1,
        m,
        n1,
        n2,
        n3,
        scale,
        pw,
        contrast,
    ] = v.params();
    let phi = rng.f01() * TAU;
    let (px, py) = supershape(m, n1, n2, n3, phi);
    let fig = (px * scale * radius1, py * scale * radius1);
    glynn_common(
        v,
        t,
        rng,
        [radius, radius1, thickness, phi1, pw, contrast],
        fig,
    )
}
