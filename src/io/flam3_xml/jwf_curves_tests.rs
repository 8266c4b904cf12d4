//! Tests of JWildfire's curve attributes: reading, what is not played and why, writing back.

use super::*;
use crate::io::flam3_xml::{ReadOptions, flame_element, read as read_xml};

fn group(name: &str, interp: &str, pts: &[(i64, f64)]) -> String {
    let mut s = format!(
        "{name}_enabled=\"true\" {name}_view_xmin=\"-10\" {name}_interpolation=\"{interp}\" \
         {name}_point_count=\"{}\"",
        pts.len()
    );
    for (i, (x, y)) in pts.iter().enumerate() {
        s += &format!(" {name}_x{i}=\"{x}\" {name}_y{i}=\"{y:?}\"");
    }
    s
}

fn flame(flame_attrs: &str, xform_attrs: &str) -> String {
    format!(
        "<flame version=\"JWildfire V9.00\" size=\"40 30\" scale=\"10\" frame_count=\"60\" fps=\"30\" \
         {flame_attrs}><xform weight=\"1\" linear3D=\"1\" julian=\"0.5\" julian_dist=\"1\" \
         coefs=\"1 0 0 1 0 0\" {xform_attrs}/></flame>"
    )
}

fn parse(text: &str) -> (Flame, Vec<String>) {
    let p = read_xml(text, &ReadOptions::default()).unwrap();
    let w = p.warnings.iter().map(|d| d.to_string()).collect();
    (p.value.flames.into_iter().next().unwrap(), w)
}

#[test]
fn curves_become_keyframes_with_ugnis_frames_and_values() {
    let text = flame(
        &group("centreXCurve", "BEZIER", &[(1, 0.5), (30, -0.5), (60, 0.0)]),
        &(group("xyRotateCurve", "SPLINE", &[(1, 0.0), (61, 90.0)])
            + " "
            + &group("colorSymmetryCurve", "LINEAR", &[(1, 1.0), (10, -1.0)])
            + " "
            + &group("julian_dist", "SPLINE", &[(5, 2.0), (9, 3.0)])
            + " "
            + &group("julian_amountCurve", "SPLINE", &[(5, 0.25)])),
    );
    let (f, warnings) = parse(&text);
    // The curves' attributes count as read, not as kept and ignored.
    assert!(
        warnings.iter().all(|w| !w.contains("Curve")),
        "{warnings:?}"
    );
    assert_eq!((f.keys.frames, f.keys.fps), (60, 30.0));
    let cx = f.keys.curve(&Target::Flame(FlameParam::CenterX)).unwrap();
    assert_eq!(cx.style(), CurveStyle::JWildfire(JwfInterp::Bezier));
    assert_eq!(cx.keys()[1].frame, 29.0);
    let x = XformRef::Index(0);
    let rot = f.keys.curve(&Target::Xform(x, XformParam::Rotate)).unwrap();
    assert_eq!(rot.keys()[1].value, -90.0);
    // A straight line over 60 frames: JWildfire's frame 31 is a quarter turn's half.
    assert!((rot.eval(30.0, None).unwrap() + 45.0).abs() < 1e-9);
    let speed = f
        .keys
        .curve(&Target::Xform(x, XformParam::ColorSpeed))
        .unwrap();
    assert_eq!((speed.keys()[0].value, speed.keys()[1].value), (0.0, 1.0));
    let julian = variations::parse_name("julian").unwrap().0;
    let dist = Target::Var {
        xform: x,
        var: julian,
        form: Form::Regular,
        param: VarParam::Param(variations::param_of("julian_dist").unwrap().2),
    };
    assert_eq!(f.keys.curve(&dist).unwrap().keys()[0].frame, 4.0);
    let played = f.keys.apply(&f, 100.0);
    let v = played.xforms[0]
        .vars
        .iter()
        .find(|v| v.id == julian)
        .unwrap();
    assert_eq!((v.weight, v.params[dist_index()]), (0.25, 3.0));
    assert_eq!(played.center[0], 0.0);
}

fn dist_index() -> usize {
    variations::param_of("julian_dist").unwrap().2
}

#[test]
fn curves_not_played_say_why_and_stay() {
    let mut off = group("gammaCurve", "SPLINE", &[(1, 2.0), (9, 3.0)]);
    off = off.replace(
        "gammaCurve_enabled=\"true\"",
        "gammaCurve_enabled=\"false\"",
    );
    let text = flame(
        &(off
            + " "
            + &group("whiteLevelCurve", "SPLINE", &[(1, 200.0), (9, 250.0)])
            + " "
            + &group("brightnessCurve", "CUBIC", &[(1, 2.0), (9, 3.0)])
            + " "
            + &group("contrastCurve", "LINEAR", &[(9, 2.0), (1, 3.0)])),
        &group("opacityCurve", "LINEAR", &[(1, 0.2), (9, 0.3)]),
    );
    let (f, warnings) = parse(&text);
    assert!(f.keys.curves.is_empty(), "{:?}", f.keys.curves);
    let all = warnings.join("\n");
    for what in [
        "whiteLevelCurve is kept but not played: ugnis has no such setting",
        "brightnessCurve is kept but not played: interpolation 'CUBIC'",
        "contrastCurve is kept but not played: its points are not in increasing frame order",
    ] {
        assert!(all.contains(what), "{what}\n{all}");
    }
    // Written back as they were.
    let again = flame_element(&f);
    for a in [
        "gammaCurve_enabled=\"false\"",
        "whiteLevelCurve_x1=\"9\"",
        "opacityCurve_y1=\"0.3\"",
    ] {
        assert!(again.contains(a), "{a}\n{again}");
    }
}

#[test]
fn edited_curves_are_written_anew_and_deleted_ones_disabled() {
    let text = flame(
        &(group("centreXCurve", "SPLINE", &[(1, 0.5), (30, -0.5), (60, 0.0)])
            + " "
            + &group("gammaCurve", "SPLINE", &[(1, 2.0), (60, 3.0)])),
        &group("xyRotateCurve", "SPLINE", &[(1, 0.0), (61, 90.0)]),
    );
    let (mut f, _) = parse(&text);
    let unchanged = flame_element(&f);
    assert!(unchanged.contains("centreXCurve_y0=\"0.5\" centreXCurve_x1=\"30\""));
    // Move a key, delete a curve, add a JWildfire curve, another timeline.
    let cx = f.keys.curve_mut(Target::Flame(FlameParam::CenterX));
    cx.move_key(1, 19.0, 0.75).unwrap();
    cx.set_style(CurveStyle::JWildfire(JwfInterp::Linear))
        .unwrap();
    f.keys
        .curves
        .retain(|c| c.target != Target::Flame(FlameParam::Gamma));
    let mut w = Curve::with_style(
        Target::Xform(XformRef::Index(0), XformParam::Weight),
        CurveStyle::JWildfire(JwfInterp::Spline),
    );
    w.insert(Key::new(0.0, 1.0)).unwrap();
    w.insert(Key::new(9.0, 2.0)).unwrap();
    f.keys.curves.push(w);
    // A curve of ugnis' own stays among ugnis' keyframes.
    f.keys
        .curve_mut(Target::Flame(FlameParam::Vibrancy))
        .insert(Key::new(3.0, 0.5))
        .unwrap();
    f.keys.frames = 90;
    let s = flame_element(&f);
    for a in [
        "centreXCurve_interpolation=\"LINEAR\"",
        "centreXCurve_point_count=\"3\" centreXCurve_x0=\"1\" centreXCurve_y0=\"0.5\" \
         centreXCurve_x1=\"20\" centreXCurve_y1=\"0.75\"",
        "centreXCurve_view_xmin=\"-10\"",
        "gammaCurve_enabled=\"false\"",
        "weightCurve_enabled=\"true\" weightCurve_interpolation=\"SPLINE\" \
         weightCurve_point_count=\"2\" weightCurve_x0=\"1\" weightCurve_y0=\"1.0\" \
         weightCurve_x1=\"10\" weightCurve_y1=\"2.0\"",
        "frame_count=\"90\"",
        "<curve target=\"vibrancy\">",
    ] {
        assert!(s.contains(a), "{a}\n{s}");
    }
    assert_eq!(s.matches("<curve ").count(), 1, "{s}");
    let (back, _) = parse(&s);
    assert_eq!(back.keys.frames, 90);
    for c in &f.keys.curves {
        assert_eq!(back.keys.curve(&c.target), Some(c), "{}", c.target);
    }
    assert!(back.keys.curve(&Target::Flame(FlameParam::Gamma)).is_none());
}

#[test]
fn a_jwildfire_curve_without_a_jwildfire_name_stays_in_ugnis_keys() {
    let mut f = parse(&flame("", "")).0;
    let mut c = Curve::with_style(Target::PaletteHue, CurveStyle::JWildfire(JwfInterp::Bezier));
    for (k, v) in [(0.0, 0.0), (5.0, 90.0), (9.0, 10.0)] {
        c.insert(Key::new(k, v)).unwrap();
    }
    f.keys.curves.push(c.clone());
    let s = flame_element(&f);
    assert!(
        s.contains("<curve target=\"palette hue\" style=\"jwildfire_bezier\">"),
        "{s}"
    );
    assert_eq!(parse(&s).0.keys.curve(&Target::PaletteHue), Some(&c));
}
