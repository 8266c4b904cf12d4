//! Jesus Sosa's `recurrenceplot`, after Jürgen Meier's recurrence plots
//! (http://www.3d-meier.de/tut19/Seite0.html): of a signal y(i), i = 0 … N − 1 (one of 30
//! functions: sums of sines, chirps, a sigmoid, tanh, tan, sec, Gaussians, damped waves,
//! Fourier series of square, sawtooth, rectified-sine and parabola waves, sinc, a Gabor
//! wavelet, Legendre and Chebyshev polynomials), each call draws a random pair (i, j) and plots
//! (i/N − ½, j/N − ½) when |y(i) − y(j)| < `tolerance`; otherwise the point plotted last is
//! repeated (the variation remembers it from call to call).
//!
//! The formulas follow JWildfire 9.00 (`RecurrencePlotFunc`, LGPL-2.1), written anew.

use std::f64::consts::PI;

use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("recurrenceplot", recurrenceplot)
    .params(&[
        p_int("recurrenceplot_func_id", 0.0, 0.0, 29.0),
        p("recurrenceplot_a", 0.5),
        p("recurrenceplot_b", 10.0),
        // At most 10000 terms of a Fourier series per call.
        p_int("recurrenceplot_k", 5.0, -10000.0, 10000.0).limited(),
        p("recurrenceplot_Density", 700.0),
        p_int("recurrenceplot_dc", 0.0, -2147483648.0, 2147483647.0),
        p("recurrenceplot_scale", 1.0),
        p("recurrenceplot_angle", 0.0),
        p("recurrenceplot_offset", 0.0),
        p("recurrenceplot_tolerance", 5.0),
    ])
    .flags(
        flag::JWILDFIRE
            | flag::RANDOM
            | flag::STATEFUL
            | flag::SETS_COLOR
            | flag::READS_ACC
            | flag::WRITES_ACC,
    )];

/// The Legendre polynomial P_n(x) (0 for n outside 0 … 10, as JWildfire's table).
fn legendre(n: i64, x: f64) -> f64 {
    if !(0..=10).contains(&n) {
        return 0.0;
    }
    let (mut p0, mut p1) = (1.0, x);
    if n == 0 {
        return p0;
    }
    for k in 1..n {
        let k = k as f64;
        (p0, p1) = (p1, ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0));
    }
    p1
}

/// The Chebyshev polynomial T_n(x) (0 for n outside 0 … 12, as JWildfire's table).
fn chebyshev(n: i64, x: f64) -> f64 {
    if !(0..=12).contains(&n) {
        return 0.0;
    }
    let (mut t0, mut t1) = (1.0, x);
    if n == 0 {
        return t0;
    }
    for _ in 1..n {
        (t0, t1) = (t1, 2.0 * x * t1 - t0);
    }
    t1
}

/// The signal y(i) of function `id` over `n` samples.
fn signal(id: i64, a: f64, b: f64, k: i64, n: f64, i: f64) -> f64 {
    let s = |f: f64| (i * f * PI / n).sin();
    let half = |f: f64| (i * f * PI / (0.5 * n)).sin();
    let terms = 1..=k.max(0);
    match id {
        0 => 50.0 * s(4.0) + 25.0 * s(40.0),
        1 => 10.0 * s(5.0) * 5.0 * s(15.0),
        2 => 50.0 * (i * 24.0 * PI / n + 5.0 * s(6.0)).cos(),
        3 => 50.0 * s(20.0) + 50.0 * (i * 22.0 * PI / n + PI).sin(),
        4 => 50.0 * s(20.0) + 10.0 * s(22.0),
        5 => 50.0 * (i * a * PI / n + s(a)).sin(),
        6 => a / (1.0 + (-b * (i - n / 2.0) / n).exp()),
        7 => 400.0 / PI * (half(1.0) + half(3.0) / 3.0 + half(5.0) / 5.0 + half(7.0) / 7.0),
        8 => 400.0 / PI * PI * (half(1.0) - half(3.0) / 9.0 + half(5.0) / 25.0 - half(7.0) / 49.0),
        9 => (a * i * PI / n).tanh(),
        10 => (a * i * PI / n).tan(),
        11 => {
            -200.0 / PI
                * (1..=8)
                    .map(|m| half(f64::from(m)) / f64::from(m))
                    .sum::<f64>()
        }
        12 => 50.0 * s(40.0) + 50.0 * s(44.0),
        13 => 50.0 * s(40.0) + 50.0 * (i * 44.0 * PI / n + PI).sin(),
        14 => 100.0 * s(16.0) - 500.0 + i * 0.25,
        15 => 100.0 * s(16.0),
        16 => 1.0 / (i * a * PI / n).cos(),
        17 => 50.0 * (i * 2.0 * PI * 25.0 / n + 25.0 * (i * 2.0 * PI * 0.5 / n).sin()).cos(),
        18 => {
            let u = 2.0 * a * i / n - a;
            a * (-b * u * u).exp()
        }
        19 => 500.0 * s(10.0) * (-5.0 * i / n).exp(),
        20 => 500.0 * s(20.0) * (-3.0 * i / n).exp(),
        21 => 50.0 * (i * 2.0 * PI / n).tan(),
        22 => a * legendre(b as i64, 2.0 * i / n - 1.0),
        23 => {
            // A square wave.
            let sum: f64 = terms
                .map(|j| {
                    let m = 2.0 * j as f64 - 1.0;
                    (i * m * b * 2.0 * PI / n).sin() / m
                })
                .sum();
            sum * (4.0 * a / PI)
        }
        24 => {
            // A sawtooth.
            let sum: f64 = terms
                .map(|j| (i * j as f64 * b * 2.0 * PI / n).sin() / j as f64)
                .sum();
            sum * (-2.0 * a / PI)
        }
        25 => {
            // A rectified sine.
            let sum: f64 = terms
                .map(|j| {
                    let j = j as f64;
                    (i * 2.0 * j * b * 2.0 * PI / n).cos() / ((2.0 * j - 1.0) * (2.0 * j + 1.0))
                })
                .sum();
            4.0 * a / PI * (0.5 - sum)
        }
        26 => {
            // A parabola.
            let sum: f64 = terms
                .map(|j| {
                    let sign = if j % 2 == 0 { 1.0 } else { -1.0 };
                    let j = j as f64;
                    sign * (i * 2.0 * j * b * PI / n).cos() / (j * j)
                })
                .sum();
            a * PI * PI / 3.0 + 4.0 * a * sum
        }
        27 => {
            let u = b * PI * (i - 0.5 * n) / n;
            a * u.sin() / u
        }
        28 => {
            let u = (i - 0.5 * n) / n;
            a * (-b * (u * u)).exp() * (2.0 * k as f64 * PI * i / n).cos()
        }
        29 => a * chebyshev(k, 2.0 * i / n - 1.0),
        _ => 0.0,
    }
}

/// State slots: the point plotted last (x, y), the colour `dc` gave it and whether a point
/// was plotted yet (1).
const ST_X: usize = 0;
const ST_Y: usize = 1;
const ST_C: usize = 2;
const ST_HIT: usize = 3;

/// recurrenceplot: a random pair of samples, plotted when their values are close (coloured
/// by x·y with `dc` 1, along the direction `angle` with `dc` 2); else the last plotted point.
///
/// JWildfire draws each render thread's one orbit through its own copy of the variation, so a
/// repeated point comes with the colour the orbit had when the variation plotted it (exactly
/// so when the xform keeps colours, colour symmetry 1). ugnis advances many orbits through one
/// shared state, so a repeated point may be another orbit's: with `dc` on, it takes the colour
/// stored with it; without, colour and position were never tied.
fn recurrenceplot(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [id, a, b, k, density, dc, scale, angle, offset, tolerance] = v.params();
    let n = density.trunc();
    let i = (n * rng.f01()).trunc();
    let j = (n * rng.f01()).trunc();
    let (id, k) = (id as i64, k as i64);
    let y1 = signal(id, a, b, k, n, i);
    let y2 = signal(id, a, b, k, n, j);
    let dist = ((y1 - y2) * (y1 - y2)).sqrt();
    if dist < tolerance {
        acc.x += v.w * (i / n - 0.5);
        acc.y += v.w * (j / n - 0.5);
        v.state.set(ST_X, acc.x);
        v.state.set(ST_Y, acc.y);
        let ldcs = 1.0 / if scale == 0.0 { 10e-6 } else { scale };
        if dc == 1.0 {
            acc.color = (0.5 * ldcs * acc.x * acc.y + offset).abs() % 1.0;
        } else if dc == 2.0 {
            let (s, c) = angle.sin_cos();
            acc.color = (0.5 * (ldcs * (c * acc.x + s * acc.y + offset) + 1.0)).abs() % 1.0;
        }
        v.state.set(ST_C, acc.color);
        v.state.set(ST_HIT, 1.0);
    } else {
        acc.x = v.state.get(ST_X);
        acc.y = v.state.get(ST_Y);
        if (dc == 1.0 || dc == 2.0) && v.state.get(ST_HIT) == 1.0 {
            acc.color = v.state.get(ST_C);
        }
    }
    [0.0; 3]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polynomials_match_their_closed_forms() {
        for x in [-0.9f64, -0.3, 0.0, 0.4, 1.0] {
            let p4 = (35.0 * x.powi(4) - 30.0 * x * x + 3.0) / 8.0;
            assert!((legendre(4, x) - p4).abs() < 1e-12);
            let t5 = 16.0 * x.powi(5) - 20.0 * x.powi(3) + 5.0 * x;
            assert!((chebyshev(5, x) - t5).abs() < 1e-12);
        }
        assert_eq!(legendre(11, 0.5), 0.0);
        assert_eq!(chebyshev(0, 0.5), 1.0);
    }

    /// JWildfire 9.00's classes on the corpus flame's settings (func 0, a 0.5, b 10, k 5, N
    /// 700, dc 1, scale 0.124, angle 1, offset 0.272, tolerance 5), one orbit from colour 0.5
    /// under colour symmetry 1: the plotted point (i, j) = (422, 397) is
    /// (0.10285714285714287, 0.06714285714285717) with colour 0.2998472679394339, and the
    /// next (missed) pair repeats it with that colour.
    #[test]
    fn a_repeated_point_keeps_the_colour_it_was_plotted_with() {
        use crate::flame::variations::jwf_testing::{make, run};
        let v = make(
            "recurrenceplot",
            &[
                ("recurrenceplot_func_id", 0.0),
                ("recurrenceplot_a", 0.5),
                ("recurrenceplot_b", 10.0),
                ("recurrenceplot_k", 5.0),
                ("recurrenceplot_Density", 700.0),
                ("recurrenceplot_dc", 1.0),
                ("recurrenceplot_scale", 0.12399999999999997),
                ("recurrenceplot_angle", 1.0),
                ("recurrenceplot_offset", 0.272),
                ("recurrenceplot_tolerance", 5.0),
            ],
            1.0,
        );
        let mut rng = FastRng::new(7);
        let (mut hits, mut repeats) = (0, 0);
        let mut last: Option<[f64; 4]> = None;
        for _ in 0..4000 {
            let o = run(&v, &[[0.1, 0.2, 0.0]], 0.5, &mut rng)[0];
            if hits == 0 && o[..2] == [0.0, 0.0] {
                // Nothing plotted yet: the origin, with the colour the point came with.
                assert_eq!(o[3], 0.5);
                continue;
            }
            let expect = (0.5 / 0.12399999999999997 * o[0] * o[1] + 0.272).abs() % 1.0;
            if let Some(l) = last.filter(|l| l[0] == o[0] && l[1] == o[1]) {
                // A repeat (or the same pair drawn again): the colour of the plotted point.
                assert_eq!(o[3], l[3]);
                repeats += 1;
            } else {
                assert!((o[3] - expect).abs() < 1e-12, "{o:?}");
                hits += 1;
            }
            last = Some(o);
        }
        assert!(hits > 50 && repeats > 1000, "{hits} {repeats}");
        // JWildfire's point and colour for the pair (422, 397).
        let (x, y) = (422.0 / 700.0 - 0.5, 397.0 / 700.0 - 0.5);
        assert!((x - 0.10285714285714287f64).abs() < 1e-15);
        assert!((y - 0.06714285714285717f64).abs() < 1e-15);
        let c = (0.5 / 0.12399999999999997 * x * y + 0.272f64).abs() % 1.0;
        assert!((c - 0.2998472679394339).abs() < 1e-15);
    }
}
