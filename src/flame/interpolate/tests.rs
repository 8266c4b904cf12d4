//! Unit tests of flam3's in-betweens on hand-made flames (the comparisons with flam3's own
//! output are in tests/animation.rs).

use std::f64::consts::PI;

use super::*;
use crate::flame::loops::{loop_frame, rotate, sequence};
use crate::flame::model::Motion;
use crate::flame::sequence::MotionFunction;
use crate::flame::sequence::PaletteInterpolation;

fn flame_at(time: f64, xforms: Vec<Xform>) -> Flame {
    let mut f = Flame {
        xforms,
        ..Flame::default()
    };
    f.anim.time = time;
    f
}

fn xf(weight: f64, coefs: Affine, vars: &[(&str, f64)]) -> Xform {
    Xform {
        weight,
        coefs,
        vars: vars
            .iter()
            .map(|(n, w)| Var::new(variations::by_name(n).unwrap(), *w))
            .collect(),
        ..Xform::default()
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-12
}

fn affine_close(a: &Affine, b: &Affine) -> bool {
    close(a.a, b.a)
        && close(a.b, b.b)
        && close(a.c, b.c)
        && close(a.d, b.d)
        && close(a.e, b.e)
        && close(a.f, b.f)
}

fn weight(x: &Xform, name: &str) -> f64 {
    weight_of(x, variations::by_name(name).unwrap())
}

#[test]
fn control_points_come_back_at_their_times_and_the_middle_is_blended() {
    let sq = Affine::new(0.5, 0.0, 0.0, 0.5, 0.2, -0.1);
    let a = flame_at(0.0, vec![xf(1.0, sq, &[("linear", 1.0)])]);
    let mut b = flame_at(10.0, vec![xf(3.0, sq, &[("linear", 0.5), ("swirl", 0.5)])]);
    b.center = [1.0, -2.0];
    b.brightness = 8.0;
    let cps = [a.clone(), b.clone()];
    let at0 = interpolate_at(&cps, 0.0);
    assert!(close(at0.xforms[0].weight, 1.0));
    assert!(affine_close(&at0.xforms[0].coefs, &sq));
    assert_eq!(at0.xforms[0].vars.len(), 1, "swirl at weight 0 is dropped");
    let mid = interpolate_at(&cps, 5.0);
    assert!(close(mid.xforms[0].weight, 2.0));
    assert!(close(weight(&mid.xforms[0], "linear"), 0.75));
    assert!(close(weight(&mid.xforms[0], "swirl"), 0.25));
    assert_eq!(mid.center, [0.5, -1.0]);
    assert!(close(mid.brightness, 6.0));
    assert_eq!(mid.anim.time, 5.0);
    // Outside the sequence the segment is extrapolated (c0 = 1.5 at time −5).
    let before = interpolate_at(&cps, -5.0);
    assert!(close(before.center[0], -0.5));
    assert!(close(before.brightness, 2.0));
}

#[test]
fn log_interpolation_turns_columns_and_scales_lengths_geometrically() {
    // Column (a, c) turns from 0° to 90° and grows from 1 to 4.
    let a = flame_at(
        0.0,
        vec![xf(1.0, Affine::new(1.0, 0.0, 0.0, 1.0, 0.0, 0.0), &[])],
    );
    let b = flame_at(
        1.0,
        vec![xf(1.0, Affine::new(0.0, 0.0, 4.0, 1.0, 2.0, 0.0), &[])],
    );
    let mid = interpolate_at(&[a.clone(), b.clone()], 0.5);
    let m = mid.xforms[0].coefs;
    let s = 2.0 * (PI / 4.0).sin();
    assert!(close(m.a, s) && close(m.c, s), "{m:?}");
    assert!(close(m.b, 0.0) && close(m.d, 1.0) && close(m.e, 1.0));
    // Linear interpolation averages the coefficients.
    let (mut a, mut b) = (a, b);
    a.anim.interpolation_type = InterpolationType::Linear;
    b.anim.interpolation_type = InterpolationType::Linear;
    let mid = interpolate_at(&[a, b], 0.5);
    assert!(affine_close(
        &mid.xforms[0].coefs,
        &Affine::new(0.5, 0.0, 2.0, 1.0, 1.0, 0.0)
    ));
}

#[test]
fn a_half_turn_goes_clockwise_and_a_zero_column_takes_the_other_angle() {
    let a = flame_at(
        0.0,
        vec![xf(1.0, Affine::new(1.0, 0.0, 0.0, 1.0, 0.0, 0.0), &[])],
    );
    let b = flame_at(
        1.0,
        vec![xf(1.0, Affine::new(-1.0, 0.0, 0.0, -1.0, 0.0, 0.0), &[])],
    );
    let m = interpolate_at(&[a.clone(), b], 0.5).xforms[0].coefs;
    // Exactly π apart, both columns turn the positive way: +90° at the middle.
    assert!(close(m.a, 0.0) && close(m.c, 1.0), "{m:?}");
    assert!(close(m.b, -1.0) && close(m.d, 0.0), "{m:?}");
    // A tiny column blends its length linearly (its logarithm is below −10).
    let c = flame_at(
        1.0,
        vec![xf(1.0, Affine::new(1e-6, 0.0, 0.0, 1.0, 0.0, 0.0), &[])],
    );
    let m = interpolate_at(&[a, c], 0.5).xforms[0].coefs;
    assert!(close(m.a, 0.5 + 0.5e-6), "{m:?}");
}

#[test]
fn padding_xforms_match_their_partners() {
    let id = Affine::IDENTITY;
    let sq = Affine::new(0.5, 0.1, -0.2, 0.4, 0.3, 0.0);
    let a = flame_at(0.0, vec![xf(1.0, id, &[("linear", 1.0)])]);
    let with = |name: &str| {
        flame_at(
            1.0,
            vec![xf(1.0, id, &[("linear", 1.0)]), xf(2.0, sq, &[(name, 1.0)])],
        )
    };
    // A spherical partner: linear −1 with the map turned 180°.
    let mid = interpolate_at(&[a.clone(), with("spherical")], 0.25);
    let x = &mid.xforms[1];
    assert!(close(x.weight, 0.5));
    assert!(close(weight(x, "linear"), -0.75));
    assert!(close(weight(x, "spherical"), 0.25));
    // A fan partner: fan 1 on the swapped identity.
    let cps = [a.clone(), with("fan")];
    let start = interpolate_at(&cps, 0.0);
    let x = &start.xforms[1];
    assert!(close(x.weight, 0.0) && close(weight(x, "fan"), 1.0));
    assert!(close(weight(x, "linear"), 0.0));
    assert!(affine_close(
        &x.coefs,
        &Affine::new(0.0, 1.0, 1.0, 0.0, 0.0, 0.0)
    ));
    // A blob partner: blob 1 with the parameters that make it the identity.
    let start = interpolate_at(&[a.clone(), with("blob")], 0.0);
    let blob = start.xforms[1]
        .vars
        .iter()
        .find(|v| v.name() == "blob")
        .unwrap();
    assert_eq!(blob.params, vec![1.0, 1.0, 1.0]);
    // No special partner: linear 1 on the identity; colour by the slot's parity.
    let start = interpolate_at(&[a.clone(), with("swirl")], 0.0);
    let x = &start.xforms[1];
    assert!(close(weight(x, "linear"), 1.0) && affine_close(&x.coefs, &Affine::IDENTITY));
    assert_eq!(x.color, 1.0);
    // Compat interpolation pads with plain linear xforms.
    let mut old = a;
    old.anim.interpolation_type = InterpolationType::Compat;
    let start = interpolate_at(&[old, with("spherical")], 0.0);
    assert!(close(weight(&start.xforms[1], "linear"), 1.0));
}

#[test]
fn parameters_of_a_variation_used_on_one_side_are_carried_over() {
    let id = Affine::IDENTITY;
    let mut julian = xf(1.0, id, &[("julian", 1.0)]);
    julian.vars[0].params = vec![5.0, 2.0];
    let a = flame_at(0.0, vec![xf(1.0, id, &[("linear", 1.0)])]);
    let b = flame_at(1.0, vec![julian]);
    let mid = interpolate_at(&[a, b], 0.5);
    let j = mid.xforms[0]
        .vars
        .iter()
        .find(|v| v.name() == "julian")
        .unwrap();
    assert!(close(j.weight, 0.5));
    assert_eq!(
        j.params,
        vec![5.0, 2.0],
        "the power does not move while fading in"
    );
}

#[test]
fn final_xforms_fade_against_an_identity_that_keeps_the_colour() {
    let id = Affine::IDENTITY;
    let a = flame_at(0.0, vec![xf(1.0, id, &[("linear", 1.0)])]);
    let mut b = a.clone();
    b.anim.time = 1.0;
    b.final_xform = Some(xf(
        1.0,
        Affine::new(2.0, 0.0, 0.0, 2.0, 0.0, 0.0),
        &[("swirl", 1.0)],
    ));
    let start = interpolate_at(&[a, b], 0.0);
    let fx = start.final_xform.expect("a final xform on both sides");
    assert_eq!(fx.color_speed, 0.0);
    assert!(close(weight(&fx, "linear"), 1.0) && affine_close(&fx.coefs, &Affine::IDENTITY));
}

#[test]
fn palettes_take_the_shorter_way_round_the_hue_circle() {
    let mut a = flame_at(0.0, vec![xf(1.0, Affine::IDENTITY, &[])]);
    let mut b = a.clone();
    b.anim.time = 1.0;
    a.palette.colors = vec![[1.0, 0.0, 0.0, 1.0]; 256]; // red, hue 0
    b.palette.colors = vec![[0.0, 0.0, 1.0, 1.0]; 256]; // blue, hue 4
    let mid = interpolate_at(&[a.clone(), b.clone()], 0.5);
    // Hue 0 → 4 the short way is 6 → 4: the middle is hue 5, magenta.
    assert_eq!(mid.palette.colors[0], [1.0, 0.0, 1.0, 1.0]);
    a.anim.palette_interpolation = PaletteInterpolation::Rgb;
    let mid = interpolate_at(&[a.clone(), b.clone()], 0.5);
    assert_eq!(mid.palette.colors[0], [0.5, 0.0, 0.5, 1.0]);
    a.anim.palette_interpolation = PaletteInterpolation::Sweep;
    let q = interpolate_at(&[a, b], 0.25);
    // A quarter of the way, the first three quarters of the entries are still the first's.
    assert_eq!(q.palette.colors[191], [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(q.palette.colors[192], [0.0, 0.0, 1.0, 1.0]);
}

#[test]
fn smooth_interpolation_runs_through_four_points_except_at_the_ends() {
    let w = catmull_rom(0.3);
    assert!(close(w.iter().sum::<f64>(), 1.0));
    let cps: Vec<Flame> = (0..4)
        .map(|k| {
            let mut f = flame_at(k as f64, vec![xf(1.0, Affine::IDENTITY, &[])]);
            f.center = [(k * k) as f64, 0.0];
            f.anim.interpolation = Interpolation::Smooth;
            f
        })
        .collect();
    // Catmull-Rom reproduces a quadratic's values at the middle segment: x(1.5) = 2.25.
    assert!(close(interpolate_at(&cps, 1.5).center[0], 2.25));
    // The first segment falls back to linear: x(0.5) = 0.5.
    assert!(close(interpolate_at(&cps, 0.5).center[0], 0.5));
}

#[test]
fn rotation_spares_symmetry_and_final_xforms() {
    let sq = Affine::new(0.5, 0.0, 0.0, 0.5, 0.1, 0.2);
    let mut f = flame_at(0.0, vec![xf(1.0, sq, &[]), xf(1.0, sq, &[])]);
    f.xforms[1].animate = 0.0;
    f.final_xform = Some(xf(1.0, sq, &[]));
    rotate(&mut f, 90.0);
    let m = f.xforms[0].coefs;
    assert!(close(m.a, 0.0) && close(m.c, 0.5) && close(m.b, -0.5) && close(m.d, 0.0));
    assert_eq!((m.e, m.f), (0.1, 0.2), "translation stays");
    assert_eq!(f.xforms[1].coefs, sq);
    assert_eq!(f.final_xform.unwrap().coefs, sq);
}

#[test]
fn motion_elements_move_values_by_their_function() {
    let mut x = xf(1.0, Affine::IDENTITY, &[("linear", 1.0)]);
    let mut m = Motion::new(2, MotionFunction::Sin);
    m.delta.weight = 0.5;
    m.delta.coefs.e = 1.0;
    m.delta.vars.push(Var {
        weight: 0.25,
        ..Var::new(variations::by_name("swirl").unwrap(), 0.0)
    });
    x.motion.push(m);
    let f = flame_at(0.0, vec![x]);
    // sin(2π · 2 · 0.125) = 1.
    let g = loop_frame(&f, 0.125, 1.0);
    assert!(close(g.xforms[0].weight, 1.5));
    assert!(close(g.xforms[0].coefs.e, 1.0));
    assert!(close(weight(&g.xforms[0], "swirl"), 0.25));
    assert!(g.xforms[0].motion.is_empty());
    // A loop of 45° turns the xform.
    assert!(close(g.xforms[0].coefs.a, (PI / 4.0).cos()));
}

#[test]
fn sequences_hold_loops_and_transitions_named_by_their_time() {
    let a = flame_at(0.0, vec![xf(1.0, Affine::IDENTITY, &[("linear", 1.0)])]);
    let b = flame_at(0.0, vec![xf(1.0, Affine::IDENTITY, &[("swirl", 1.0)])]);
    let s = sequence(&[a.clone(), b], 4, true, 1.0);
    assert_eq!(s.len(), 4 + 4 + 4 + 1);
    for (k, f) in s.iter().enumerate() {
        assert_eq!(f.anim.time, k as f64);
        assert_eq!(f.name, format!("{k}.000000"));
    }
    // The transition's first frame is the first flame itself.
    assert_eq!(s[4].xforms, a.xforms);
    assert_eq!(sequence(&[a.clone(), a], 3, false, 1.0).len(), 3 + 1);
    assert!(close(smoother(0.5), 0.5) && close(stagger_coef(0.3, 0.0, 3, 1), smoother(0.3)));
}

#[test]
fn times_must_increase() {
    let f = |t: f64| flame_at(t, Vec::new());
    assert_eq!(check_times(&[f(0.0), f(1.0), f(5.0)]), Ok(()));
    assert_eq!(check_times(&[f(0.0), f(0.0)]), Err(1));
    assert_eq!(check_times(&[f(2.0), f(1.0)]), Err(1));
    assert_eq!(check_times(&[f(f64::NAN)]), Err(0));
}

#[test]
fn consecutive_rotations_are_brought_within_half_a_turn_as_flam3_reads_them() {
    let at = |t: f64, rotate: f64| {
        let mut f = flame_at(t, vec![xf(1.0, Affine::default(), &[("linear", 1.0)])]);
        f.rotate = rotate;
        f
    };
    let cps = vec![
        at(0.0, 10.0),
        at(1.0, 350.0),
        at(2.0, -700.0),
        at(3.0, 1e12),
    ];
    // 350° after 10° is −10°; −700° after −10° is 20°; a nonsense angle stays as written.
    assert_eq!(unwrapped_rotations(&cps), vec![10.0, -10.0, 20.0, 1e12]);
    // Half a turn exactly stays on the side it was written (flam3's loops stop there).
    let half = vec![at(0.0, 0.0), at(1.0, 180.0), at(2.0, -180.0)];
    assert_eq!(unwrapped_rotations(&half), vec![0.0, 180.0, 180.0]);
    // The blend between 10° and 350° passes 0°, not 180°.
    assert!(close(interpolate_at(&cps, 0.5).rotate, 0.0));
    // Not after a control point of the compat type.
    let mut compat = cps.clone();
    compat[0].anim.interpolation_type = InterpolationType::Compat;
    assert_eq!(unwrapped_rotations(&compat)[1], 350.0);
}
