//! Jesus Sosa's small iterated-function maps after Paul Bourke's pages: the inverse tree
//! `invtree_js`, the wallpaper map `wallpaper_js` and the woggle `woggle_js` (each picks one
//! of its maps at random per call), the random curve point of `crown_js` and the uniform
//! triangle `triangle`, and the interleaved cells of `cell2`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. Random numbers are drawn in the order JWildfire draws them.

use std::f64::consts::TAU;

use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("invtree_js", invtree_js).flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("wallpaper_js", wallpaper_js)
        .params(&[
            p("wallpaper_js_a", 1.156),
            p("wallpaper_js_b", -0.28),
            p("wallpaper_js_c", 21.288),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_ACC),
    VarDef::new("woggle_js", woggle_js)
        .params(&[p_int("woggle_js_m", 2.0, 2.0, 12.0)])
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("crown_js", crown_js)
        .params(&[
            p("crown_js_a", 5.0),
            p("crown_js_b", 0.630_929_753_571_457_4),
        ])
        .flags(
            flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::READS_ACC,
        ),
    VarDef::new("triangle", triangle)
        .params(&[
            p("triangle_x1", -0.2),
            p("triangle_y1", -0.1),
            p("triangle_z1", 0.0),
            p("triangle_x2", 0.2),
            p("triangle_y2", -0.1),
            p("triangle_z2", 0.0),
            p("triangle_x3", 0.2),
            p("triangle_y3", 0.1),
            p("triangle_z3", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::WRITES_ACC),
    VarDef::new("cell2", cell2)
        .params(&[
            p("cell2_size", 0.6),
            p_int("cell2_mirror_x", 0.0, NEG_INF, INF),
            p_int("cell2_mirror_y", 0.0, NEG_INF, INF),
            p("cell2_a", 1.0),
            p("cell2_space_ya", 2.0),
            p("cell2_space_xa", 2.0),
            p("cell2_space_yb", 2.0),
            p("cell2_space_xb", 2.0),
            p("cell2_move_xa", 1.0),
            p("cell2_space_yc", 2.0),
            p("cell2_move_ya", 1.0),
            p("cell2_space_xc", 2.0),
            p("cell2_space_yd", 2.0),
            p("cell2_move_yb", 1.0),
            p("cell2_space_xd", 2.0),
            p("cell2_move_xb", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::READS_ACC | flag::WRITES_ACC),
];

/// invtree_js: one of three maps at random (x/2, y/2), (1/(x+1), y/(y+1)),
/// (x/(x+1), 1/(y+1)); the second draw decides between the last two.
fn invtree_js(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = if rng.f01() < 0.333 {
        (t.x / 2.0, t.y / 2.0)
    } else if rng.f01() < 0.666 {
        (1.0 / (t.x + 1.0), t.y / (t.y + 1.0))
    } else {
        (t.x / (t.x + 1.0), 1.0 / (t.y + 1.0))
    };
    [x * v.w, y * v.w, 0.0]
}

/// wallpaper_js: Hopalong's step (y − sign(x)·√|bx − c|, a − x) added unweighted, or (half
/// the time) the point itself replacing the running sum.
fn wallpaper_js(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a, b, c] = v.params();
    if rng.f01() < 0.5 {
        // Java's Integer.signum((int) x).
        let s = if t.x.trunc() == 0.0 {
            0.0
        } else {
            t.x.signum()
        };
        [t.y - s * (b * t.x - c).abs().sqrt(), a - t.x, 0.0]
    } else {
        acc.x = 0.0;
        acc.y = 0.0;
        [t.x, t.y, 0.0]
    }
}

/// woggle_js: one of m rotations-with-inversion about the m-th roots of unity, at random.
fn woggle_js(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [m] = v.params();
    let r = 1.25f64.sqrt() * m.sqrt();
    let c = (m * rng.f01()).trunc();
    let (bc, ac) = (TAU * c / m).sin_cos();
    let ra = 1.0 / (3f64.sqrt() * (t.x * t.x + t.y * t.y).sqrt());
    let (x, y) = if c as i64 % 2 == 0 {
        (-t.x / r + ra * t.y / r + ac, -ra * t.x / r - t.y / r + bc)
    } else {
        (t.x / r + ra * t.y / r + ac, -ra * t.x / r + t.y / r + bc)
    };
    [x * v.w, y * v.w, 0.0]
}

/// crown_js: a point of a Weierstrass-like curve Σ (sin, cos)(±aᵏ·t)/a^(bk), k = 1…14, at a
/// uniform t in [−π, π); z is |w|⁴ and the colour the squared radius of the sum, modulo 1.
fn crown_js(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [a, b] = v.params();
    let t = -std::f64::consts::PI + TAU * rng.f01();
    let (mut wx, mut wy) = (0.0, 0.0);
    for k in 1..15 {
        let denom = a.powf(b * k as f64);
        let sign = if k % 2 == 0 { -1.0 } else { 1.0 };
        let th = a.powf(k as f64) * t * sign;
        wx += th.sin() / denom;
        wy += th.cos() / denom;
    }
    let z = (wx * wx + wy * wy).powi(2);
    let o = [wx * v.w, wy * v.w, z * v.w];
    let (sx, sy) = (acc.x + o[0], acc.y + o[1]);
    acc.color = (sx * sx + sy * sy).abs() % 1.0;
    o
}

/// triangle: a uniform point of the triangle with the three given corners (3-D); it replaces
/// the running sum.
fn triangle(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [x1, y1, z1, x2, y2, z2, x3, y3, z3] = v.params();
    let s1 = rng.f01().sqrt();
    let r2 = rng.f01();
    let (a, b, c) = (1.0 - s1, s1 * (1.0 - r2), r2 * s1);
    acc.x = 0.0;
    acc.y = 0.0;
    acc.z = 0.0;
    [
        v.w * (a * x1 + b * x2 + c * x3),
        v.w * (a * y1 + b * y2 + c * y3),
        v.w * (a * z1 + b * z2 + c * z3),
    ]
}

/// cell2: the Apophysis plugin pack's `cell` with every spacing and shift exposed: square cells
/// moved apart differently in each quadrant (y flipped), then the whole running sum mirrored in
/// x and in y at random when asked.
fn cell2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        size,
        mirror_x,
        mirror_y,
        a,
        s_ya,
        s_xa,
        s_yb,
        s_xb,
        m_xa,
        s_yc,
        m_ya,
        s_xc,
        s_yd,
        m_yb,
        s_xd,
        m_xb,
    ] = v.params();
    let inv = a / size;
    let mut x = (t.x * inv).floor();
    let mut y = (t.y * inv).floor();
    let dx = t.x - x * size;
    let dy = t.y - y * size;
    if y >= 0.0 {
        if x >= 0.0 {
            y *= s_ya;
            x *= s_xa;
        } else {
            y *= s_yb;
            x = -(s_xb * x + m_xa);
        }
    } else if x >= 0.0 {
        y = -(s_yc * y + m_ya);
        x *= s_xc;
    } else {
        y = -(s_yd * y + m_yb);
        x = -(s_xd * x + m_xb);
    }
    let mut o = [v.w * (dx + x * size), -v.w * (dy + y * size), 0.0];
    if mirror_x > 0.0 && rng.f01() < 0.5 {
        o[0] = -(acc.x + o[0]);
        acc.x = 0.0;
    }
    if mirror_y > 0.0 && rng.f01() < 0.5 {
        o[1] = -(acc.y + o[1]);
        acc.y = 0.0;
    }
    o
}
