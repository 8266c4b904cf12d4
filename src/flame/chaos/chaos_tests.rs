//! Tests of the chaos game's compiled flame and flam3's one-orbit loop.

use super::*;
use crate::flame::model::{Affine, Xform};

#[test]
fn selection_table_matches_weights() {
    let t = selection_table(&[1.0, 3.0]);
    let ones = t.iter().filter(|&&v| v == 1).count();
    assert_eq!(ones, 16384 * 3 / 4);
    assert_eq!(t[0], 0);
    assert_eq!(t[16383], 1);
    // A tiny weight may get no entry (flam3 quantisation); never out of range.
    let t = selection_table(&[1.0, 1e-9, 1.0]);
    assert!(t.iter().all(|&v| v < 3));
}

#[test]
fn empty_and_bad_flames_are_rejected() {
    let mut f = Flame::default();
    assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::NoXforms);
    f.xforms.push(Xform::linear(Affine::IDENTITY, 0.0, 0.0));
    assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::ZeroWeights);
    f.xforms[0].weight = -1.0;
    assert!(matches!(Chaos::new(&f), Err(ChaosError::BadWeight(0, _))));
    f.xforms[0].weight = 1.0;
    f.xforms[0].chaos = vec![0.0];
    assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::XaosRowZero(0));
}

#[test]
fn a_fractorium_xaos_row_of_zero_total_picks_the_first_xform() {
    // Fractorium draws the first xform after one whose xaos row sums to 0; flam3 refuses.
    let mut f = Flame::default();
    for e in [0.0, 0.5, 0.25] {
        f.xforms.push(Xform::linear(
            Affine::new(0.5, 0.0, 0.0, 0.5, e, 0.0),
            1.0,
            0.0,
        ));
    }
    f.xforms[2].chaos = vec![0.0, 0.0, 0.0];
    assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::XaosRowZero(2));
    f.palette_index = crate::flame::model::PaletteIndex::Fractorium;
    let ch = Chaos::new(&f).unwrap();
    let mut rng = FastRng::new(5);
    for _ in 0..1000 {
        assert_eq!(ch.choose(Some(2), &mut rng), 0);
    }
    assert!((0..1000).any(|_| ch.choose(Some(0), &mut rng) == 2));
}

#[test]
fn sierpinski_points_stay_on_the_attractor() {
    let mut f = Flame::default();
    for (e, ff) in [(0.0, 0.0), (0.5, 0.0), (0.25, 0.5)] {
        f.xforms.push(Xform::linear(
            Affine::new(0.5, 0.0, 0.0, 0.5, e, ff),
            1.0,
            0.0,
        ));
    }
    let ch = Chaos::new(&f).unwrap();
    let mut rng = FastRng::new(5);
    let mut count = 0;
    let bad = ch.run_sub_batch(10_000, &mut rng, |p, vis| {
        let (x, y) = (p.x, p.y);
        assert!((-1e-6..=1.0 + 1e-6).contains(&x) && (-1e-6..=1.0 + 1e-6).contains(&y));
        assert_eq!(vis, 1.0);
        count += 1;
    });
    assert_eq!(count, 10_000);
    assert_eq!(bad, 0);
}

#[test]
fn xaos_restricts_transitions() {
    // Xform 0 may only go to 1, 1 only to 0: colours alternate exactly.
    let mut f = Flame::default();
    let mut a = Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0), 1.0, 0.0);
    a.color_speed = 1.0;
    a.chaos = vec![0.0, 1.0];
    let mut b = Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 0.5, 0.0), 1.0, 1.0);
    b.color_speed = 1.0;
    b.chaos = vec![1.0, 0.0];
    f.xforms = vec![a, b];
    let ch = Chaos::new(&f).unwrap();
    let mut rng = FastRng::new(9);
    let mut prev: Option<f64> = None;
    ch.run_sub_batch(1000, &mut rng, |p, _| {
        let c = p.c;
        if let Some(p) = prev {
            assert_ne!(p, c);
        }
        prev = Some(c);
    });
}

#[test]
fn bad_values_are_retried() {
    // A map that expands by 10⁶ escapes past 1e10 within two steps: the point is
    // replaced by a random point and nothing non-finite or huge is ever plotted.
    let f = Flame {
        xforms: vec![Xform::linear(
            Affine::new(1e6, 0.0, 0.0, 1e6, 0.0, 0.0),
            1.0,
            0.0,
        )],
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    let mut rng = FastRng::new(1);
    let bad = ch.run_sub_batch(100, &mut rng, |p, _| {
        assert!(p.x.abs() <= BAD_LIMIT && p.y.abs() <= BAD_LIMIT);
    });
    assert!(bad > 0);
}

#[test]
fn a_bad_value_restarts_in_the_plane() {
    // A 3-D point that escapes is replaced by a random point with z = 0: a NaN or huge z
    // carried over would poison every later step of 3-D variations (tanq, sinhq …).
    let mut x = Xform::linear(Affine::new(1e11, 0.0, 0.0, 1e11, 0.0, 0.0), 1.0, 0.0);
    x.vars = vec![crate::flame::model::Var::new(
        variations::by_name("linear3D").unwrap(),
        1.0,
    )];
    let f = Flame {
        xforms: vec![x],
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    let mut rng = FastRng::new(3);
    // An infinite x is bad for every flame (linear3D is not flam3's, so 1e10 is not).
    let p = Pt {
        x: f64::INFINITY,
        y: 0.5,
        z: f64::NAN,
        c: 0.0,
    };
    let (q, bad) = ch.xforms[0].apply(p, &mut rng);
    assert!(bad);
    assert_eq!(q.z, 0.0);
    assert!(q.x.abs() <= 1.0 && q.y.abs() <= 1.0);
    // Lanes: plotted points after restarts stay finite.
    let mut seen = 0;
    let mut ln = Lanes::new();
    ch.run_lanes(
        2000,
        &mut rng,
        &mut ln,
        |xs: &[f64], ys: &[f64], zs: &[f64], _, vs: &[f64], _: &[u32]| {
            for k in (0..xs.len()).filter(|&k| vs[k] >= 0.0) {
                assert!(xs[k].is_finite() && ys[k].is_finite() && zs[k].is_finite());
                seen += 1;
            }
        },
    );
    assert!(seen > 0);
}

#[test]
fn flames_of_fractorium_variations_only_reset_nan() {
    // flam3 resets coordinates beyond 1e10; Fractorium only NaN (and ugnis infinity).
    let mut f = Flame {
        xforms: vec![Xform::linear(Affine::IDENTITY, 1.0, 0.0)],
        ..Flame::default()
    };
    assert_eq!(Chaos::new(&f).unwrap().xforms[0].bad_limit, BAD_LIMIT);
    f.xforms[0].vars.push(crate::flame::model::Var::new(
        variations::by_name("tanq").unwrap(),
        0.5,
    ));
    assert_eq!(Chaos::new(&f).unwrap().xforms[0].bad_limit, BAD_LIMIT_WIDE);
}

/// Several final xforms apply in order, in both runners (JWildfire chains them): scale
/// by ½ about the origin, then move by (1, 0).
#[test]
fn final_xforms_chain_in_order() {
    let mut f = Flame {
        xforms: vec![Xform::linear(
            Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0),
            1.0,
            0.0,
        )],
        final_xform: Some(Xform::linear(
            Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0),
            0.0,
            0.0,
        )),
        more_finals: vec![Xform::linear(
            Affine::new(1.0, 0.0, 0.0, 1.0, 1.0, 0.0),
            0.0,
            0.0,
        )],
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    let mut rng = FastRng::new(3);
    let p = Pt {
        x: 0.5,
        y: -0.25,
        z: 0.0,
        c: 0.0,
    };
    let q = ch.finalise(p, &mut rng);
    assert_eq!((q.x, q.y), (1.25, -0.125));
    // The lane runner: every sample of an orbit shrinking to the origin ends near (1, 0).
    let mut ln = Lanes::new();
    let mut seen = 0;
    ch.run_lanes(
        1000,
        &mut rng,
        &mut ln,
        |xs: &[f64], ys: &[f64], _: &[f64], _, vs: &[f64], _: &[u32]| {
            for k in (0..xs.len()).filter(|&k| vs[k] >= 0.0) {
                assert!((xs[k] - 1.0).abs() < 1e-3 && ys[k].abs() < 1e-3);
                seen += 1;
            }
        },
    );
    assert!(seen > 0);
    // Without a first final xform the others do not apply.
    f.final_xform = None;
    let q = Chaos::new(&f).unwrap().finalise(p, &mut rng);
    assert_eq!((q.x, q.y), (0.5, -0.25));
}

/// A variation used twice in an xform (JWildfire's `linear3D` and `linear3D#1#`) adds both
/// outputs: weights 0.3 and 0.2 move a point as weight 0.5 does.
#[test]
fn a_variation_used_twice_sums() {
    let lin = variations::by_name("linear3D").unwrap();
    let mut two = Xform::linear(Affine::new(0.9, 0.1, -0.2, 0.8, 0.1, 0.2), 1.0, 0.0);
    two.vars = vec![
        crate::flame::model::Var::new(lin, 0.3),
        crate::flame::model::Var::new(lin, 0.2),
    ];
    let mut one = two.clone();
    one.vars = vec![crate::flame::model::Var::new(lin, 0.5)];
    let p = Pt {
        x: 0.3,
        y: -0.7,
        z: 0.25,
        c: 0.5,
    };
    let run = |x: &Xform| {
        let f = Flame {
            xforms: vec![x.clone()],
            ..Flame::default()
        };
        Chaos::new(&f).unwrap().xforms[0]
            .apply(p, &mut FastRng::new(1))
            .0
    };
    let (a, b) = (run(&two), run(&one));
    for (u, v) in [(a.x, b.x), (a.y, b.y), (a.z, b.z)] {
        assert!((u - v).abs() < 1e-12, "{a:?} {b:?}");
    }
}

/// JWildfire's colour type CYCLIC moves the gradient position on by the colour symmetry,
/// modulo 1 as Java's `%` (keeping the sign), then into [0, 1).
#[test]
fn cyclic_colour_moves_on_by_the_symmetry() {
    use super::xform::cycle_colour;
    assert!((cycle_colour(0.9, 0.125) - 0.025).abs() < 1e-15);
    assert!((cycle_colour(0.25, 0.125) - 0.375).abs() < 1e-15);
    assert!((cycle_colour(0.1, -0.3) - 0.8).abs() < 1e-15);
    assert_eq!(cycle_colour(0.5, 0.5), 0.0);
    assert!(cycle_colour(f64::NAN, 0.1).is_nan());
}
