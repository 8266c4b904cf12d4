//! JWildfire's escape-time fractals drawn as point sets: `mandelbrot` (Jed Kelsey's Apophysis
//! plugin), which samples the Mandelbrot set's boundary with its own seeded generator and a
//! random walk carried from call to call; and the 2-D Mandelbox `mandelbox2D`.
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew.

use super::util::Mwc;
use super::*;

/// Most iterations of the escape-time variations (each evaluation may run them all; beyond a
/// thousand the set's boundary no longer changes at any useful zoom).
const FRACTAL_MAX_ITER: f64 = 1000.0;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("mandelbrot", mandelbrot)
        .params(&[
            p_int("mandelbrot_iter", 100.0, NEG_INF, FRACTAL_MAX_ITER).limited(),
            p("mandelbrot_xmin", -1.6),
            p("mandelbrot_xmax", 1.6),
            p("mandelbrot_ymin", -1.2),
            p("mandelbrot_ymax", 1.2),
            p_int("mandelbrot_invert", 0.0, NEG_INF, INF),
            p("mandelbrot_skin", 0.012),
            p("mandelbrot_cx", 0.0),
            p("mandelbrot_cy", 0.0),
            p_int("mandelbrot_max_points", -1.0, NEG_INF, INF),
            p_int("mandelbrot_seed", 1234.0, NEG_INF, INF),
            p("mandelbrot_rnd_z_range", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::STATEFUL | flag::WRITES_Z)
        .prepare(mandelbrot_prepare),
    VarDef::new("mandelbox2D", mandelbox2d)
        .params(&[
            p_int("mandelbox2D_mandelboxMode", 0.0, 0.0, 2.0),
            p_range("mandelbox2D_iterations", 10.0, 0.0, FRACTAL_MAX_ITER).limited(),
            p("mandelbox2D_scale", -1.5),
            p("mandelbox2D_foldLimit", 1.0),
            p("mandelbox2D_minRadius", 0.5),
            p("mandelbox2D_fixedRadius", 1.0),
            p("mandelbox2D_rotation", 0.0),
            p_int("mandelbox2D_juliaMode", 0.0, 0.0, 1.0),
            p("mandelbox2D_juliaX", 0.4),
            p("mandelbox2D_juliaY", 0.6),
            p_int("mandelbox2D_coloringMode", 0.0, 0.0, 2.0),
            p("mandelbox2D_colorSpeed", 0.5),
        ])
        .flags(flag::JWILDFIRE | flag::SETS_COLOR | flag::USES_COLOR),
];

/// The carried state: the current c = (x0, y0), its z, and the variation's own generator
/// (JWildfire's Marsaglia generator seeded with `seed`).
fn mandelbrot_prepare(v: &mut Prepared) {
    let [_, _, _, _, _, _, _, _, _, _, seed] = v.params();
    v.state.set(0, 0.0);
    v.state.set(1, 0.0);
    v.state.set(2, 0.0);
    v.state
        .set(3, f64::from_bits(Mwc::new(seed as i64).to_bits()));
}

/// mandelbrot: looks for a c near the set's boundary (escaping after more than
/// 0.1·iter·(1 − skin) steps but not staying inside; `invert` looks inside instead), by a
/// random walk of step (skin + 0.001) from the last c found, or afresh uniformly in the
/// window; at most 10 tries, then a far point. Adds c + (cx, cy)·(last orbit point), and the
/// random z of the last fresh start. (JWildfire's `max_points`, a fixed pool of starts, is
/// not kept: every fresh start is new.)
fn mandelbrot(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        iter,
        xmin,
        xmax,
        ymin,
        ymax,
        invert,
        skin,
        cx,
        cy,
        _,
        _,
        rnd_z_range,
    ] = v.params();
    let iter = iter as i64;
    let (mut x0, mut y0, mut z0) = (v.state.get(0), v.state.get(1), v.state.get(2));
    let mut g = Mwc::from_bits(v.state.get(3).to_bits());
    let (mut x1, mut y1, mut x, mut y) = (x0, y0, x0, y0);
    let inverted = g.next_f64() < invert;
    let mut curr = if inverted { 0 } else { iter };
    let low = |c: i64| (c as f64) < 0.1 * iter as f64 * (1.0 - skin);
    let mut k = 0;
    loop {
        let go =
            (inverted && curr < iter) || (!inverted && (curr >= iter || (skin < 1.0 && low(curr))));
        let again = k < 10;
        k += 1;
        if !(again && go) {
            break;
        }
        if x0 == 0.0 && y0 == 0.0 {
            x0 = (xmax - xmin) * g.next_f64() + xmin;
            y0 = (ymax - ymin) * g.next_f64() + ymin;
            z0 = g.next_f64() * rnd_z_range;
        } else {
            x0 += (skin + 0.001) * (g.next_f64() - 0.5);
            y0 += (skin + 0.001) * (g.next_f64() - 0.5);
        }
        (x1, y1, x, y) = (x0, y0, x0, y0);
        curr = 0;
        while x * x + y * y < 4.0 && curr < iter {
            let xt = x * x - y * y + x0;
            y = 2.0 * x * y + y0;
            x = xt;
            curr += 1;
        }
        if curr >= iter || skin == 1.0 || (curr as f64) < 0.1 * (iter as f64 * (1.0 - skin)) {
            x0 = 0.0;
            y0 = 0.0;
        }
    }
    if k >= 10 {
        let far = 50000.0 - rng.f01() * 100000.0;
        x1 = far;
        y1 = far;
    }
    v.state.set(0, x0);
    v.state.set(1, y0);
    v.state.set(2, z0);
    v.state.set(3, f64::from_bits(g.to_bits()));
    [v.w * (x1 + cx * x), v.w * (y1 + cy * y), z0]
}

/// Mirrors `c` back inside [−limit, limit] (the Mandelbox's box fold).
fn box_fold(c: f64, limit: f64) -> f64 {
    if c > limit {
        2.0 * limit - c
    } else if c < -limit {
        -2.0 * limit - c
    } else {
        c
    }
}

/// mandelbox2D: `iterations` steps of the Mandelbox map in the plane (box fold, ball fold,
/// scale, rotation, add c = the point or the Julia constant), in one of three orders
/// (`mandelboxMode`); the colour from the final angle (coloringMode 1) or blended towards
/// the angle at each step (2).
fn mandelbox2d(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        mode,
        iterations,
        scale,
        fold,
        min_radius,
        fixed_radius,
        rotation,
        julia,
        jx,
        jy,
        coloring,
        speed,
    ] = v.params();
    let (mut x, mut y) = (t.x, t.y);
    let (cx, cy) = if julia == 1.0 { (jx, jy) } else { (x, y) };
    let (min2, fixed2) = (min_radius * min_radius, fixed_radius * fixed_radius);
    let (sin_r, cos_r) = rotation.to_radians().sin_cos();
    let rotate = |x: f64, y: f64| {
        if rotation != 0.0 {
            (x * cos_r - y * sin_r, x * sin_r + y * cos_r)
        } else {
            (x, y)
        }
    };
    let angle_colour = |x: f64, y: f64| y.atan2(x) / (2.0 * std::f64::consts::PI) + 0.5;
    let mut blended = t.color;
    for _ in 0..iterations as i64 {
        if coloring == 2.0 {
            blended += (angle_colour(x, y) - blended) * speed;
        }
        if mode == 0.0 {
            (x, y) = (box_fold(x, fold), box_fold(y, fold));
            if x * x + y * y < min2 {
                let f = fixed2 / min2;
                (x, y) = (x * f, y * f);
            }
            (x, y) = rotate(x * scale, y * scale);
            (x, y) = (x + cx, y + cy);
        } else if mode == 1.0 {
            (x, y) = rotate(x * scale + cx, y * scale + cy);
            (x, y) = (box_fold(x, fold), box_fold(y, fold));
            let r2 = x * x + y * y;
            if r2 < min2 {
                (x, y) = (x * fixed2 / r2, y * fixed2 / r2);
            }
        } else {
            (x, y) = (box_fold(x, fold) + cx, box_fold(y, fold) + cy);
            (x, y) = rotate(x * scale, y * scale);
            let r2 = x * x + y * y;
            if r2 < min2 {
                (x, y) = (x * fixed2 / r2, y * fixed2 / r2);
            }
        }
    }
    if coloring == 1.0 {
        acc.color = angle_colour(x, y);
    } else if coloring == 2.0 {
        acc.color = blended;
    }
    [x * v.w, y * v.w, 0.0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::variations::{by_name, eval_prepared, info};

    /// JWildfire's six successive calls of a fresh mandelbrot (default parameters, weight 0.7,
    /// seed 1234): three walks that fail ten times (a far point drawn from the render's
    /// generator, so only its shape is compared), then three boundary points exactly.
    #[test]
    fn mandelbrot_follows_jwildfires_sequence() {
        let id = by_name("mandelbrot").unwrap();
        let v = Prepared::new(
            id,
            Form::Regular,
            0.7,
            &info(id).defaults(),
            Affine::IDENTITY,
            true,
        );
        let mut rng = FastRng::new(7);
        let want = [
            [-0.4052165484080168, -0.36423292760003023],
            [-0.4064390125477635, -0.36409758201090037],
            [-0.4069960482459962, -0.3672343747467894],
        ];
        for call in 0..6 {
            let acc = Acc {
                color: 0.35,
                ..Acc::default()
            };
            let o = eval_prepared(&v, [-0.1125, 0.3975, 0.0], acc, true, &mut rng);
            if call < 3 {
                assert!(o.x == o.y && o.x.abs() > 100.0, "call {call}: {o:?}");
            } else {
                let w = want[call - 3];
                assert!(
                    (o.x - w[0]).abs() < 1e-12 && (o.y - w[1]).abs() < 1e-12,
                    "call {call}: {o:?}, want {w:?}"
                );
            }
        }
    }
}
