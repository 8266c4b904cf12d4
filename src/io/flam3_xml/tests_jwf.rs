//! Tests of how JWildfire's variation uses are read and written: a variation used twice
//! (`NAME#1#`), and the priorities that move a variation before or after the others.

use super::tests::opts;
use super::*;
use crate::flame::variations::Form;

/// JWildfire writes a variation used twice in an xform as `NAME` and `NAME#1#` (its
/// parameters `NAME#1#_param`, its priority `NAME#1#_fx_priority`): two uses, written back
/// the same way; a dropped use's parameters are not written twice.
#[test]
fn jwildfire_variation_used_twice() {
    let text = r#"<flame version="JWildfire V7.30"><xform weight="1" julian="0.5" julian_power="3" julian#1#="0.25" julian#1#_power="5" julian#1#_fx_priority="1" julian#2#="0" julian#2#_power="7" coefs="1 0 0 1 0 0"/></flame>"#;
    let f = read(text, &opts()).unwrap().value.flames.remove(0);
    let vars: Vec<(Form, f64, f64)> = f.xforms[0]
        .vars
        .iter()
        .map(|v| (v.form, v.weight, v.params[0]))
        .collect();
    assert_eq!(vars, [(Form::Regular, 0.5, 3.0), (Form::Post, 0.25, 5.0)]);
    let out = write(&FlameFile {
        name: String::new(),
        flames: vec![f.clone()],
    });
    // The use moved after the others keeps its name and priority; the dropped third use keeps
    // its parameter.
    assert!(
        out.contains("julian=\"0.5\" julian#1#=\"0.25\" julian#1#_fx_priority=\"1\""),
        "{out}"
    );
    assert!(out.contains("julian#2#_power=\"7\""), "{out}");
    let mut x = f.xforms[0].clone();
    x.vars[1].form = Form::Regular;
    x.vars[1].moved = false;
    x.extra_attrs.clear();
    let g = Flame {
        xforms: vec![x.clone()],
        ..f
    };
    let out = write(&FlameFile {
        name: String::new(),
        flames: vec![g],
    });
    assert!(
        out.contains("julian=\"0.5\" julian#1#=\"0.25\" julian_power=\"3\""),
        "{out}"
    );
    assert!(out.contains("julian#1#_power=\"5\""), "{out}");
    let back = read(&out, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(back.xforms[0].vars, x.vars);
}

/// A `pre_` variation JWildfire's file marks with priority 0 runs among the regular ones on a
/// copy JWildfire then throws away: it draws nothing, so it is no variation here, and it is
/// written back as it was read. Marked -1, it stays a pre_ variation.
#[test]
fn jwildfire_pre_variation_of_priority_zero_does_nothing() {
    let text = r#"<flame version="JWildfire V7.30"><xform weight="1" pre_blur="1.18" pre_blur_fx_priority="0" bubble="0.2" bubble_fx_priority="0" coefs="1 0 0 1 0 0"/><xform weight="1" pre_blur="0.5" pre_blur_fx_priority="-1" coefs="1 0 0 1 0 0"/></flame>"#;
    let f = read(text, &opts()).unwrap().value.flames.remove(0);
    let forms = |i: usize| -> Vec<(Form, f64)> {
        f.xforms[i]
            .vars
            .iter()
            .map(|v| (v.form, v.weight))
            .collect()
    };
    assert_eq!(forms(0), [(Form::Regular, 0.2)]);
    assert_eq!(forms(1), [(Form::Pre, 0.5)]);
    let out = write(&FlameFile {
        name: String::new(),
        flames: vec![f.clone()],
    });
    assert!(out.contains("pre_blur=\"1.18\""), "{out}");
    assert!(out.contains("pre_blur_fx_priority=\"0\""), "{out}");
    let back = read(&out, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(back.xforms[0].vars, f.xforms[0].vars);
}

/// A regular variation JWildfire's priority moves before (-1) or after (1) the others is
/// marked as moved in JWildfire's flames (it then adds to the point), written back as the plain
/// name with its priority, and read back the same; in other programs' flames the mark only
/// changes the phase.
#[test]
fn jwildfire_priority_moves_a_regular_variation() {
    let xform = r#"<xform weight="1" loonie="0.25" loonie_fx_priority="-1" julian="0.5" julian_fx_priority="1" spherical="1" coefs="1 0 0 1 0 0"/>"#;
    let jwf = format!(r#"<flame version="JWildfire V7.30">{xform}</flame>"#);
    let f = read(&jwf, &opts()).unwrap().value.flames.remove(0);
    let marks = |f: &Flame| -> Vec<(Form, bool)> {
        f.xforms[0].vars.iter().map(|v| (v.form, v.moved)).collect()
    };
    assert_eq!(
        marks(&f),
        [
            (Form::Pre, true),
            (Form::Post, true),
            (Form::Regular, false)
        ]
    );
    let out = write(&FlameFile {
        name: String::new(),
        flames: vec![f.clone()],
    });
    assert!(out.contains("loonie_fx_priority=\"-1\""), "{out}");
    assert!(out.contains("julian_fx_priority=\"1\""), "{out}");
    assert!(
        !out.contains("pre_loonie") && !out.contains("post_julian"),
        "{out}"
    );
    let back = read(&out, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(back.xforms[0].vars, f.xforms[0].vars);
    let other = format!(r#"<flame>{xform}</flame>"#);
    let g = read(&other, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(
        marks(&g),
        [
            (Form::Pre, false),
            (Form::Post, false),
            (Form::Regular, false)
        ]
    );
}

/// Older JWildfire versions wrote parameter names that are not XML names
/// (`dc_booleans_^/&/|`, its operator): JWildfire reads a name as all that stands before
/// `="`, and so does ugnis, with one warning; the name is kept and written back as it stands,
/// and what follows it is read as usual.
#[test]
fn jwildfire_names_that_are_not_xml() {
    let text = r#"<flame version="JWildfire V5.60"><xform weight="0.5" dc_booleans="1" dc_booleans_^/&/|="2" dc_booleans_a|b="3" dc_booleans_zoom="500" coefs="1 0 0 1 0 0.5"/></flame>"#;
    let p = read(text, &opts()).unwrap();
    let notes: Vec<_> = p.warnings.iter().filter(|w| w.code == "XML024").collect();
    assert_eq!(notes.len(), 1, "{:?}", p.warnings);
    assert!(
        notes[0].message.contains("'dc_booleans_^/&/|'"),
        "{notes:?}"
    );
    let f = &p.value.flames[0];
    let x = &f.xforms[0];
    assert_eq!(x.coefs.to_coefs()[5], 0.5);
    // zoom is read after the odd names; the operator JWildfire 9.00 calls `type` keeps its
    // default, as in JWildfire 9.00 (which no longer knows the old name).
    assert_eq!(x.vars.len(), 1);
    assert_eq!(x.vars[0].params[1], 1.0);
    assert_eq!(x.vars[0].params[2], 500.0);
    let kept: Vec<&str> = x.extra_attrs.iter().map(|(k, _)| k.as_str()).collect();
    assert_eq!(kept, ["dc_booleans_^/&/|", "dc_booleans_a|b"]);
    let out = write(&p.value);
    assert!(out.contains(r#" dc_booleans_^/&/|="2""#), "{out}");
    let back = read(&out, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(back.xforms, f.xforms);
    // A self-closing tag still ends at its `/`; a quote or `<` in a name is refused.
    let closed = r#"<flame version="JWildfire V5.60"><xform weight="1" a_b/c="1" coefs="1 0 0 1 0 0" /></flame>"#;
    let f = read(closed, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(
        f.xforms[0].extra_attrs,
        [("a_b/c".to_string(), "1".to_string())]
    );
    for bad in [r#"a'b="1""#, r#"a<b="1""#] {
        let t = format!(r#"<flame version="JWildfire V5.60"><xform weight="1" {bad}/></flame>"#);
        assert!(read(&t, &opts()).is_err(), "{bad}");
    }
}

/// A prepost variation's own priority (2, which JWildfire writes beside it) does not move it:
/// it stays one variation called before and after the others, its parameters attached, and
/// the mark is written back as read.
#[test]
fn jwildfire_prepost_variation_keeps_its_own_priority() {
    let text = r#"<flame version="JWildfire V5.60"><xform weight="1" spherical="1" spherical_fx_priority="0" prepost_circlize="0.5" prepost_circlize_fx_priority="2" prepost_circlize_n="8" coefs="1 0 0 1 0 0"/></flame>"#;
    let f = read(text, &opts()).unwrap().value.flames.remove(0);
    let vars = &f.xforms[0].vars;
    assert_eq!(vars.len(), 2);
    assert_eq!((vars[1].form, vars[1].moved), (Form::Regular, false));
    assert_eq!(vars[1].weight, 0.5);
    assert_eq!(vars[1].params[0], 8.0);
    let out = write(&FlameFile {
        name: String::new(),
        flames: vec![f.clone()],
    });
    assert!(out.contains("prepost_circlize_fx_priority=\"2\""), "{out}");
    let back = read(&out, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(back.xforms[0].vars, f.xforms[0].vars);
}

/// dc_warping's x0, which JWildfire sets from the seed when the seed is set: a flame written
/// before x0 existed gets the seed's (Java's `new Random(6239).nextDouble()` is
/// 0.27607020393605808, so x0 = −0.44785959212788384); a written x0 wins.
#[test]
fn jwildfire_dc_warping_x0_follows_the_seed_when_left_out() {
    let x0_of = |attrs: &str| {
        let text = format!(
            r#"<flame version="JWildfire V5.50"><xform weight="1" dc_warping="1" dc_warping_randomize="6239" {attrs} coefs="1 0 0 1 0 0"/></flame>"#
        );
        let f = read(&text, &opts()).unwrap().value.flames.remove(0);
        f.xforms[0].vars[0].params[2]
    };
    assert_eq!(x0_of(""), -0.44785959212788384);
    assert_eq!(x0_of(r#"dc_warping_x0="0.25""#), 0.25);
    // Other programs' flames keep the registry's default.
    let text = r#"<flame><xform weight="1" dc_warping="1" dc_warping_randomize="6239" coefs="1 0 0 1 0 0"/></flame>"#;
    let f = read(text, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(f.xforms[0].vars[0].params[2], 0.0);
}

/// dc_fractcolor's xpar and ypar spelt `xPar`, `yPar` (JWildfire 6) are not read, as JWildfire
/// 9.00 does not read them: they come from the seed (`new Random(5)` draws 0.730519863614471
/// and 0.08825840967622589).
#[test]
fn jwildfire_dc_fractcolor_pars_follow_the_seed() {
    let text = r#"<flame version="JWildfire V6.00"><xform weight="1" dc_fractcolor="1" dc_fractcolor_randomize="5" dc_fractcolor_xPar="0.1" dc_fractcolor_yPar="0.2" coefs="1 0 0 1 0 0"/></flame>"#;
    let f = read(text, &opts()).unwrap().value.flames.remove(0);
    let p = &f.xforms[0].vars[0].params;
    assert_eq!((p[2], p[3]), (0.730519863614471, 0.08825840967622589));
}

/// JWildfire's solid rendering settings are read (materials and lights by number, their
/// counts in attributes that may come after them), written back under JWildfire's names and
/// read again to the same settings; a flame without them keeps solid rendering off.
#[test]
fn jwildfire_solid_settings_round_trip() {
    use crate::flame::jwf_render::JwfLightDiff;
    let text = r#"<flame version="JWildfire V7.30" sld_render_material_diffuse1="0.1" sld_render_enabled="1" sld_render_ao_enabled="0" sld_render_ao_intensity="0.8" sld_render_ao_azimuth_samples="3" sld_render_shadow_type="OFF" sld_render_material_count="2" sld_render_material_ambient0="0.6" sld_render_material_phong_size0="12.0" sld_render_material_light_diif_func1="COSA_SQUARE" sld_render_ligtht_count="1" sld_render_light_altitude0="-20.5" sld_render_light_red0="0.8" sld_render_light_shadows0="0"><xform weight="1" linear="1" coefs="1 0 0 1 0 0"/></flame>"#;
    let f = read(text, &opts()).unwrap().value.flames.remove(0);
    let s = &f.jwf.solid;
    assert!(s.enabled && !s.ao_enabled);
    assert_eq!((s.ao_intensity, s.ao_azimuth_samples), (0.8, 3));
    assert_eq!(s.ao_radius_samples, 6, "JWildfire's default");
    assert_eq!(s.materials.len(), 2);
    assert_eq!(
        (s.materials[0].ambient, s.materials[0].phong_size),
        (0.6, 12.0)
    );
    assert_eq!(s.materials[1].diffuse, 0.1);
    assert_eq!(s.materials[1].light_diff, JwfLightDiff::CosaSquare);
    assert_eq!(s.lights.len(), 1);
    let l = &s.lights[0];
    assert_eq!(
        (l.altitude, l.color[0], l.cast_shadows),
        (-20.5, 0.8, false)
    );
    assert!(f.extra_attrs.iter().all(|(k, _)| !k.starts_with("sld_")));
    let out = write(&FlameFile {
        name: String::new(),
        flames: vec![f.clone()],
    });
    assert!(out.contains("sld_render_ligtht_count=\"1\""), "{out}");
    assert_eq!(out.matches("sld_render_enabled").count(), 1, "{out}");
    let back = read(&out, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(back.jwf.solid, f.jwf.solid);
    let plain = r#"<flame version="JWildfire V7.30"><xform weight="1" linear="1" coefs="1 0 0 1 0 0"/></flame>"#;
    let g = read(plain, &opts()).unwrap().value.flames.remove(0);
    assert!(!g.jwf.solid.enabled);
}

/// JWildfire 9.00's `flatten` only clears z (`FlattenFunc`: `pVarTP.z = 0`), before the other
/// variations (priority -1) or after them (+1, its own). JWildfire itself maps (0.3, -0.7,
/// 0.2) by these xforms (linear3D 0.5, preserve_z) to (0.15, -0.35, 0) both ways.
#[test]
fn jwildfire_flatten_moved_by_its_priority_only_clears_z() {
    let text = r#"<flame version="JWildfire 9.00" preserve_z="1"><xform weight="1" linear3D="0.5" flatten="1" flatten_fx_priority="1" coefs="1 0 0 1 0 0"/><xform weight="1" linear3D="0.5" flatten="1" flatten_fx_priority="-1" coefs="1 0 0 1 0 0"/></flame>"#;
    let f = read(text, &opts()).unwrap().value.flames.remove(0);
    let ch = crate::flame::Chaos::new(&f).unwrap();
    let mut rng = crate::flame::rng::FastRng::new(1);
    for x in &ch.xforms {
        let mut p = crate::flame::Chaos::start_point(&mut rng);
        (p.x, p.y, p.z) = (0.3, -0.7, 0.2);
        let (q, bad) = x.apply(p, &mut rng);
        assert!(!bad);
        assert_eq!((q.x, q.y, q.z), (0.15, -0.35, 0.0));
    }
}

/// Given priority 0, `flatten` runs among the regular variations, in the xform's order
/// (JWildfire 9.00 runs each variation in the phase its stored priority names): JWildfire
/// itself maps (0.3, -0.7, 0.2) by `linear3D, flatten, zscale 0.5` to z = 0.1 and by
/// `zscale 0.5, flatten, linear3D` to z = 0.2. Without a priority it runs after the others,
/// its own +1; the priority is written back as read.
#[test]
fn jwildfire_flatten_of_priority_zero_runs_in_its_place() {
    let text = r#"<flame version="JWildfire 9.00"><xform weight="1" linear3D="1" linear3D_fx_priority="0" flatten="1" flatten_fx_priority="0" zscale="0.5" zscale_fx_priority="0" coefs="1 0 0 1 0 0"/><xform weight="1" zscale="0.5" flatten="1" flatten_fx_priority="0" linear3D="1" coefs="1 0 0 1 0 0"/><xform weight="1" zscale="0.5" flatten="1" linear3D="1" coefs="1 0 0 1 0 0"/></flame>"#;
    let f = read(text, &opts()).unwrap().value.flames.remove(0);
    let ch = crate::flame::Chaos::new(&f).unwrap();
    let mut rng = crate::flame::rng::FastRng::new(1);
    let z: Vec<f64> = ch
        .xforms
        .iter()
        .map(|x| {
            let mut p = crate::flame::Chaos::start_point(&mut rng);
            (p.x, p.y, p.z) = (0.3, -0.7, 0.2);
            let (q, _) = x.apply(p, &mut rng);
            assert_eq!((q.x, q.y), (0.3, -0.7));
            q.z
        })
        .collect();
    assert_eq!(z, [0.1, 0.2, 0.0]);
    let out = write(&FlameFile {
        name: String::new(),
        flames: vec![f],
    });
    assert_eq!(out.matches("flatten_fx_priority=\"0\"").count(), 2, "{out}");
}

/// gumowski_mira's `a` as JWildfire 9.00's command-line renderer draws it: its threads' copies
/// hold a = 10⁻⁶ + (10⁻⁶ − 10⁻⁸)·u, u drawn by Java's generator seeded with the file's seed + 2,
/// whatever `a` the file gives, and seed + 3 (the numbers printed by an instrumented
/// `GumowskiMiraFunc` in JWildfire's own render of these flames).
#[test]
fn jwildfire_gumowski_mira_draws_a_from_its_seed() {
    let read_a = |seed: &str| {
        let text = format!(
            r#"<flame version="JWildfire V5.60"><xform weight="1" gumowski_mira="1" gumowski_mira_random="{seed}" gumowski_mira_step="0.001" gumowski_mira_a="1.7235694087962579E-6" gumowski_mira_b="0.05" coefs="1 0 0 1 0 0"/></flame>"#
        );
        let f = read(&text, &opts()).unwrap().value.flames.remove(0);
        let p = &f.xforms[0].vars[0].params;
        (p[0], p[2])
    };
    assert_eq!(read_a("2"), (5.0, 1.7233033656849586e-6));
    assert_eq!(read_a("7"), (10.0, 1.7228599359125443e-6));
    // Other programs' flames keep what they say.
    let text = r#"<flame><xform weight="1" gumowski_mira="1" gumowski_mira_random="2" gumowski_mira_a="2e-6" coefs="1 0 0 1 0 0"/></flame>"#;
    let f = read(text, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(f.xforms[0].vars[0].params[2], 2e-6);
}
