//! JWildfire's motion curves played by ugnis, against JWildfire itself: the settings of a flame
//! after its curves are played at several frames, as JWildfire 9.00 computes them
//! (`tests/fixtures/jwf_curves/NAME.values`, written by `make_vectors.sh` beside them).

mod common;

use std::collections::BTreeMap;

use ugnis::flame::Flame;
use ugnis::flame::variations;
use ugnis::io::flam3_xml;

fn read(name: &str) -> Flame {
    let path = common::fixture(&format!("jwf_curves/{name}"));
    let text = std::fs::read_to_string(&path).unwrap();
    let opts = flam3_xml::ReadOptions {
        file: name.to_string(),
        ..Default::default()
    };
    let mut file = flam3_xml::read(&text, &opts).unwrap().value;
    file.flames.remove(0)
}

/// ugnis' value of what JWildfire calls `name` in `scope` (None: not compared).
fn value(f: &Flame, base: &Flame, scope: &str, name: &str, jwf: f64) -> Option<f64> {
    if scope == "flame" {
        return Some(match name {
            "centreX" => f.center[0],
            "centreY" => f.center[1],
            "pixelsPerUnit" => f.scale,
            "camRoll" => f.rotate,
            "camPitch" => f.cam.pitch.to_degrees(),
            "camYaw" => f.cam.yaw.to_degrees(),
            "camPerspective" => f.cam.perspective,
            "camZoom" => f.cam_zoom,
            "camZ" => f.cam.zpos,
            "camDOF" => f.cam.dof,
            "brightness" => f.brightness,
            "contrast" => f.contrast,
            "gamma" => f.gamma,
            "gammaThreshold" => f.gamma_threshold,
            "vibrancy" => f.vibrancy,
            "modShift" => {
                // The palette turned by JWildfire's shift.
                let mut turned = base.palette.colors.clone();
                let n = turned.len();
                turned.rotate_right(jwf as usize % n);
                return Some(if turned == f.palette.colors {
                    jwf
                } else {
                    f64::NAN
                });
            }
            _ => panic!("unknown flame setting {name}"),
        });
    }
    let (x, bx) = match scope.strip_prefix("xform ") {
        Some(i) => {
            let i: usize = i.parse().unwrap();
            (&f.xforms[i], &base.xforms[i])
        }
        None => (
            f.final_xform.as_ref().unwrap(),
            base.final_xform.as_ref().unwrap(),
        ),
    };
    let coef = |m: &ugnis::flame::model::Affine, k: &str| {
        let i = ["00", "01", "10", "11", "20", "21"]
            .iter()
            .position(|n| *n == k)
            .unwrap();
        m.to_coefs()[i]
    };
    Some(match name {
        "weight" if scope == "final" => return None,
        "weight" => x.weight,
        "color" => x.color,
        "colorSymmetry" => 1.0 - 2.0 * x.color_speed,
        // JWildfire's xforms drawn normally have opacity 0 and ignore it.
        "opacity" if bx.opacity == 1.0 && jwf == 0.0 => return None,
        "opacity" => x.opacity,
        _ => {
            if let Some(k) = name.strip_prefix("xyPostCoeff") {
                coef(&x.post, k)
            } else if let Some(k) = name.strip_prefix("xyCoeff") {
                coef(&x.coefs, k)
            } else if let Some((id, _)) = variations::parse_name(name) {
                x.vars.iter().find(|v| v.id == id).map_or(0.0, |v| v.weight)
            } else {
                let (id, _, k) = variations::param_of(name).expect(name);
                x.vars.iter().find(|v| v.id == id).map(|v| v.params[k])?
            }
        }
    })
}

/// Compares every value of NAME.values; returns the largest relative difference.
fn check(name: &str) -> f64 {
    let base = read(&format!("{name}.flame"));
    assert!(!base.keys.is_empty(), "{name}: no curves read");
    let path = common::fixture(&format!("jwf_curves/{name}.values"));
    let text = std::fs::read_to_string(path).unwrap();
    let mut frames: BTreeMap<String, Flame> = BTreeMap::new();
    let (mut worst, mut compared) = (0.0f64, 0);
    for line in text.lines() {
        let p: Vec<&str> = line.split('|').collect();
        let (frame, scope, setting, jwf) = (p[0], p[1], p[2], p[3].parse::<f64>().unwrap());
        // JWildfire numbers frames from 1, ugnis from 0.
        let f = frames.entry(frame.to_string()).or_insert_with(|| {
            let t: f64 = frame.parse().unwrap();
            base.keys.apply(&base, t - 1.0)
        });
        let Some(got) = value(f, &base, scope, setting, jwf) else {
            continue;
        };
        let diff = (got - jwf).abs() / jwf.abs().max(1e-3);
        assert!(
            diff <= 1e-9,
            "{name} frame {frame}, {scope} {setting}: ugnis {got}, JWildfire {jwf}"
        );
        worst = worst.max(diff);
        compared += 1;
    }
    assert!(compared > 500, "{name}: only {compared} values compared");
    worst
}

#[test]
fn curves_of_every_kind_play_as_in_jwildfire() {
    let worst = check("curves");
    eprintln!("curves.flame: largest relative difference {worst:e}");
}

#[test]
fn a_long_animation_plays_as_in_jwildfire() {
    let worst = check("long");
    eprintln!("long.flame: largest relative difference {worst:e}");
}

#[test]
fn jwildfire_curves_survive_a_round_trip_unchanged() {
    let text = std::fs::read_to_string(common::fixture("jwf_curves/curves.flame")).unwrap();
    let f = read("curves.flame");
    let again = flam3_xml::flame_element(&f);
    // Every curve attribute is written back as it was read, and no keyframes of ugnis' own are
    // added for them.
    let attrs = |s: &str| -> Vec<String> {
        s.split_whitespace()
            .filter(|w| w.contains("Curve_") || w.starts_with("julian_dist_"))
            .map(|w| w.trim_end_matches("/>").trim_end_matches('>').to_string())
            .collect()
    };
    let (before, after) = (attrs(&text), attrs(&again));
    assert!(before.len() > 200);
    assert_eq!(before, after);
    assert!(!again.contains("<ugnis_keys"), "{again}");
    let back = flam3_xml::read(&again, &Default::default())
        .unwrap()
        .value
        .flames
        .remove(0);
    assert_eq!(back.keys, f.keys);
}
