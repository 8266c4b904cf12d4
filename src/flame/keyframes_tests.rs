//! Unit tests of keyframe curves and targets.

use super::*;
use crate::flame::keyframes::{Ease, Interp};
use crate::flame::variations::Form;

fn curve(keys: &[(f64, f64, Interp)]) -> Curve {
    let mut c = Curve::new(Target::Flame(FlameParam::CenterX));
    for &(f, v, i) in keys {
        c.insert(Key {
            interp: i,
            ..Key::new(f, v)
        })
        .unwrap();
    }
    c
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

#[test]
fn linear_step_and_holding_ends() {
    let c = curve(&[
        (0.0, 0.0, Interp::Linear),
        (10.0, 5.0, Interp::Step),
        (20.0, 1.0, Interp::Linear),
    ]);
    assert_eq!(c.eval(-3.0, None), Some(0.0));
    assert!(close(c.eval(4.0, None).unwrap(), 2.0));
    assert_eq!(
        c.eval(15.0, None),
        Some(5.0),
        "a step holds until the next key"
    );
    assert_eq!(c.eval(20.0, None), Some(1.0));
    assert_eq!(c.eval(99.0, None), Some(1.0));
    assert_eq!(Curve::new(Target::PaletteHue).eval(1.0, None), None);
}

#[test]
fn smooth_curves_pass_through_keys_and_follow_a_line() {
    // Keys on a line: Catmull-Rom reproduces it, also with uneven spacing.
    let c = curve(&[
        (0.0, 0.0, Interp::Smooth),
        (3.0, 6.0, Interp::Smooth),
        (10.0, 20.0, Interp::Smooth),
        (11.0, 22.0, Interp::Smooth),
    ]);
    for f in [0.0, 1.5, 3.0, 7.0, 10.5, 11.0] {
        assert!(close(c.eval(f, None).unwrap(), 2.0 * f), "{f}");
    }
    // Through the keys of a bump, and smooth across them (equal slopes either side).
    let b = curve(&[
        (0.0, 0.0, Interp::Smooth),
        (5.0, 1.0, Interp::Smooth),
        (10.0, 0.0, Interp::Smooth),
    ]);
    assert!(close(b.eval(5.0, None).unwrap(), 1.0));
    let h = 1e-6;
    let left = (b.eval(5.0, None).unwrap() - b.eval(5.0 - h, None).unwrap()) / h;
    let right = (b.eval(5.0 + h, None).unwrap() - b.eval(5.0, None).unwrap()) / h;
    assert!((left - right).abs() < 1e-4, "{left} {right}");
}

#[test]
fn bezier_handles_shape_the_segment() {
    let mut c = curve(&[(0.0, 0.0, Interp::Bezier), (10.0, 1.0, Interp::Bezier)]);
    // Default flat handles: symmetric ease, half way at the middle.
    assert!(close(c.eval(5.0, None).unwrap(), 0.5));
    assert!(c.eval(1.0, None).unwrap() < 0.1);
    // Steep handles rise faster.
    let mut k = c.keys()[0];
    k.handles = Some([[0.0, 0.0], [3.0, 1.0]]);
    c.insert(k).unwrap();
    assert!(c.eval(2.0, None).unwrap() > 0.3);
}

#[test]
fn easing_changes_the_pace_not_the_ends() {
    let mut c = curve(&[(0.0, 0.0, Interp::Linear), (10.0, 10.0, Interp::Linear)]);
    let mut k = c.keys()[0];
    k.ease = Ease::In;
    c.insert(k).unwrap();
    assert!(close(c.eval(5.0, None).unwrap(), 2.5));
    assert!(close(c.eval(10.0, None).unwrap(), 10.0));
    assert!(close(Ease::InOut.apply(0.5), 0.5) && close(Ease::Out.apply(0.5), 0.75));
}

#[test]
fn a_wrapped_timeline_loops_seamlessly() {
    let c = curve(&[(0.0, 0.0, Interp::Smooth), (50.0, 10.0, Interp::Smooth)]);
    let wrap = Some(100.0);
    // The frame after the last is the first, and the curve runs back to the first key.
    assert!(close(
        c.eval(100.0, wrap).unwrap(),
        c.eval(0.0, wrap).unwrap()
    ));
    assert!(close(c.eval(75.0, wrap).unwrap(), 5.0));
    assert!(close(c.eval(-25.0, wrap).unwrap(), 5.0));
    // Slopes match across the seam.
    let h = 1e-5;
    let before = (c.eval(100.0, wrap).unwrap() - c.eval(100.0 - h, wrap).unwrap()) / h;
    let after = (c.eval(h, wrap).unwrap() - c.eval(0.0, wrap).unwrap()) / h;
    assert!((before - after).abs() < 1e-3, "{before} {after}");
}

#[test]
fn scale_keys_interpolate_geometrically_and_must_be_positive() {
    let t = Target::Xform(XformRef::Index(0), XformParam::Scale);
    let mut c = Curve::new(t);
    c.insert(Key {
        interp: Interp::Linear,
        ..Key::new(0.0, 1.0)
    })
    .unwrap();
    c.insert(Key::new(10.0, 4.0)).unwrap();
    assert!(close(c.eval(5.0, None).unwrap(), 2.0));
    assert!(c.insert(Key::new(3.0, 0.0)).is_err());
    assert!(c.insert(Key::new(f64::NAN, 1.0)).is_err());
}

#[test]
fn targets_round_trip_through_their_names_and_set_the_flame() {
    let blur = variations::by_name("julian").unwrap();
    let targets = [
        Target::Flame(FlameParam::Zoom),
        Target::Flame(FlameParam::CamPitch),
        Target::Xform(XformRef::Index(3), XformParam::Rotate),
        Target::Xform(XformRef::Final, XformParam::Weight),
        Target::Var {
            xform: XformRef::Index(0),
            var: blur,
            form: Form::Regular,
            param: VarParam::Weight,
        },
        Target::Var {
            xform: XformRef::Index(1),
            var: blur,
            form: Form::Pre,
            param: VarParam::Param(1),
        },
        Target::PaletteRotate,
        Target::PaletteHue,
    ];
    for t in targets {
        let name = t.to_string();
        assert_eq!(name.parse::<Target>(), Ok(t), "{name}");
    }
    assert!("xform x weight".parse::<Target>().is_err());
    assert!(
        "xform 0 var nosuchvariation weight"
            .parse::<Target>()
            .is_err()
    );

    let mut f = Flame {
        xforms: vec![Xform {
            coefs: Affine::new(1.0, 0.0, 0.0, 1.0, 0.5, 0.0),
            ..Xform::default()
        }],
        ..Flame::default()
    };
    f.palette.colors = (0..256)
        .map(|i| [i as f64 / 255.0, 0.0, 0.0, 1.0])
        .collect();
    let mut k = Keyframes::default();
    let rot = Target::Xform(XformRef::Index(0), XformParam::Rotate);
    k.curve_mut(rot).insert(Key::new(0.0, 0.0)).unwrap();
    k.curve_mut(rot).insert(Key::new(10.0, 90.0)).unwrap();
    let jw = Target::Var {
        xform: XformRef::Index(0),
        var: blur,
        form: Form::Regular,
        param: VarParam::Weight,
    };
    k.curve_mut(jw).insert(Key::new(10.0, 0.5)).unwrap();
    k.curve_mut(Target::PaletteRotate)
        .insert(Key::new(0.0, 1.0))
        .unwrap();
    k.key_current(&f, Target::Flame(FlameParam::CenterX), 0.0)
        .unwrap();
    let g = k.apply(&f, 10.0);
    let m = g.xforms[0].coefs;
    assert!(close(m.a, 0.0) && close(m.c, 1.0) && close(m.b, -1.0) && close(m.d, 0.0));
    assert_eq!(m.e, 0.5);
    assert_eq!(g.xforms[0].var(blur).map(|v| v.weight), Some(0.5));
    assert_eq!(g.palette.colors[1][0], 0.0, "turned by one entry");
    // A target past the end of the flame is skipped.
    assert!(!Target::Xform(XformRef::Index(5), XformParam::Weight).set(&mut f.clone(), 1.0));
    // Camera angles are keyed in degrees.
    let mut p = Keyframes::default();
    p.curve_mut(Target::Flame(FlameParam::CamPitch))
        .insert(Key::new(0.0, 90.0))
        .unwrap();
    assert!(close(
        p.apply(&f, 0.0).cam.pitch,
        std::f64::consts::FRAC_PI_2
    ));
}

#[test]
fn holding_a_frame_sets_values_and_leaves_offsets_to_apply() {
    use crate::flame::model::{Affine, Flame, Var, Xform};
    let julia = variations::parse_name("julian").unwrap();
    let mut x = Xform::linear(Affine::new(0.5, 0.1, -0.2, 0.7, 0.3, 0.0), 1.0, 0.0);
    let mut v = Var::with_form(julia.0, julia.1, 0.5);
    v.params[0] = 5.0;
    x.vars.push(v);
    let base = Flame {
        xforms: vec![x],
        ..Flame::default()
    };
    let mut k = Keyframes::default();
    let zoom = Target::Flame(FlameParam::Zoom);
    let turn = Target::Xform(XformRef::Index(0), XformParam::Rotate);
    let weight = Target::Var {
        xform: XformRef::Index(0),
        var: julia.0,
        form: julia.1,
        param: VarParam::Weight,
    };
    for (t, a, b) in [(zoom, 0.0, 2.0), (turn, 0.0, 90.0), (weight, 0.5, 0.0)] {
        let c = k.curve_mut(t);
        c.insert(Key {
            interp: Interp::Linear,
            ..Key::new(0.0, a)
        })
        .unwrap();
        c.insert(Key::new(10.0, b)).unwrap();
    }
    let mut held = base.clone();
    k.hold_at(&mut held, 5.0);
    assert!(close(held.zoom, 1.0));
    assert_eq!(
        held.xforms[0].coefs, base.xforms[0].coefs,
        "turns stay offsets"
    );
    assert!(turn.is_offset() && !zoom.is_offset() && !weight.is_offset());
    for f in [0.0, 5.0, 10.0] {
        assert_eq!(k.apply(&held, f), k.apply(&base, f), "frame {f}");
    }
    // At weight 0 the variation stays in the base with its parameters.
    k.hold_at(&mut held, 10.0);
    let w = &held.xforms[0].vars[1];
    assert_eq!((w.weight, w.params[0]), (0.0, 5.0));
    k.hold_at(&mut held, 0.0);
    assert_eq!(held.xforms[0].vars[1].params[0], 5.0);
    assert_eq!(k.apply(&held, 3.0), k.apply(&base, 3.0));
}

#[test]
fn a_parameter_curve_stored_before_its_weight_curve_is_kept() {
    use crate::flame::model::{Affine, Flame, Xform};
    let julia = variations::parse_name("julian").unwrap();
    // The variation is not in the base: both its weight and its power come from curves.
    let base = Flame {
        xforms: vec![Xform::linear(Affine::default(), 1.0, 0.0)],
        ..Flame::default()
    };
    let target = |param| Target::Var {
        xform: XformRef::Index(0),
        var: julia.0,
        form: julia.1,
        param,
    };
    let (power, weight) = (target(VarParam::Param(0)), target(VarParam::Weight));
    let mut k = Keyframes::default();
    k.curve_mut(power).insert(Key::new(0.0, 4.0)).unwrap();
    k.curve_mut(weight).insert(Key::new(0.0, 0.5)).unwrap();
    let at = k.apply(&base, 0.0);
    let v = at.xforms[0].vars.iter().find(|v| v.id == julia.0).unwrap();
    assert_eq!((v.weight, v.params[0]), (0.5, 4.0));
    // At weight 0 the variation is not rendered at all.
    k.curve_mut(weight).insert(Key::new(0.0, 0.0)).unwrap();
    let off = k.apply(&base, 0.0);
    assert!(off.xforms[0].vars.iter().all(|v| v.id != julia.0));
}
