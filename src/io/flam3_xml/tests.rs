//! Tests of the flame XML reader and writer: foreign files, round trips, palettes, errors with
//! positions, the `.fla` rules.

use super::*;
use crate::flame::model::{Affine, PaletteMode};
use crate::flame::variations;
use crate::io::diag::Pos;

pub(super) fn opts() -> ReadOptions<'static> {
    ReadOptions {
        file: "t.flame".into(),
        library: LibrarySource::Paths(vec![]),
        ..ReadOptions::default()
    }
}

const SIMPLE: &str = r#"<flames name="test">
<flame name="a" size="64 48" center="0.5 -0.25" scale="20" quality="50" brightness="3" gamma="2.5">
  <xform weight="0.5" color="0" spherical="1" coefs="0.85 -0.04 0.04 0.85 0 1.6"/>
  <xform weight="0.25" color="1" symmetry="1" julian="0.5" julian_power="3" julian_dist="-1" coefs="1 0 0 1 0 0" post="0.5 0 0 0.5 0.1 0.2" chaos="1 0"/>
  <finalxform color="0.5" color_speed="0" linear="1" coefs="1 0 0 1 0 0"/>
  <color index="0" rgb="255 0 0"/>
  <color index="255" rgb="0 0 255"/>
  <edit date="today"><edit nick="x"/></edit>
</flame>
</flames>"#;

/// A flame of other programs: 3-D camera, a 512-colour palette, pre_/post_ forms, JWildfire
/// priorities, Apophysis' mobius names, attributes ugnis does not interpret.
const FOREIGN: &str = r#"<flame name="f" size="64 48" scale="20" cam_pitch="1.0471975511966" cam_yaw="0.25" cam_perspective="0.3" cam_zpos="0.5" cam_dof="0.2" cam_zoom="2" overall_curve="0 0 0.5 0.7 1 1" mod_contrast="1" material="0">
  <xform weight="1" color="0" pre_blur="0.1" spherical3D="0.5" post_curl="0.7" post_curl_c1="0.3" Mobius="0.2" Re_A="2" Im_D="0.5" starblur="0.4" starblur_fx_priority="-1" starblur_power="6" mirror_pre_post_translations="0" xyCoeff00Curve_enabled="false" coefs="1 0 0 1 0 0"/>
  <palette count="512" format="RGB">PALETTE</palette>
</flame>"#;

fn foreign() -> String {
    let mut data = String::new();
    for i in 0..512 {
        data.push_str(&format!("{:02X}00{:02X}", i / 2, 255 - i / 2));
    }
    FOREIGN.replace("PALETTE", &data)
}

#[test]
fn reads_flames_of_other_programs() {
    let p = read(&foreign(), &opts()).unwrap();
    let f = &p.value.flames[0];
    assert!((f.cam.pitch - std::f64::consts::FRAC_PI_3).abs() < 1e-12);
    assert_eq!(
        (f.cam.yaw, f.cam.perspective, f.cam.zpos, f.cam.dof),
        (0.25, 0.3, 0.5, 0.2)
    );
    assert_eq!(f.cam_zoom, 2.0);
    assert_eq!(f.ppu(), 40.0);
    assert_eq!(f.curves.points[0], vec![[0.0, 0.0], [0.5, 0.7], [1.0, 1.0]]);
    assert!(f.curves.points[1..].iter().all(|c| c.len() == 5));
    let x = &f.xforms[0];
    let form = |name: &str| {
        let (id, form) = variations::parse_name(name).unwrap();
        x.vars
            .iter()
            .find(|v| v.id == id && v.form == form)
            .unwrap_or_else(|| panic!("{name} missing"))
    };
    assert_eq!(form("pre_blur").weight, 0.1);
    assert_eq!(form("spherical3D").weight, 0.5);
    let curl = form("post_curl");
    assert_eq!((curl.weight, curl.params[0]), (0.7, 0.3));
    let mobius = form("mobius");
    assert_eq!(mobius.param("mobius_re_a"), Some(2.0));
    assert_eq!(mobius.param("mobius_im_d"), Some(0.5));
    // JWildfire's priority −1: used before the other variations.
    assert_eq!(form("pre_starblur").weight, 0.4);
    assert_eq!(form("pre_starblur").param("starblur_power"), Some(6.0));
    // Attributes of other programs: kept, reported once, never as variations.
    let codes: Vec<&str> = p.warnings.iter().map(|w| w.code).collect();
    assert_eq!(codes, vec!["XML021"], "{:?}", p.warnings);
    assert!(p.warnings[0].to_string().contains("mod_contrast"));
    // The 512 colours render as they are; the editor sees 256.
    assert_eq!(f.render_colors().len(), 512);
    assert_eq!(f.palette.colors.len(), 256);
    assert_eq!(
        crate::flame::histogram::PlotPalette::new(f).colors.len(),
        512
    );
}

#[test]
fn flames_of_other_programs_round_trip() {
    let f = read(&foreign(), &opts()).unwrap().value.flames[0].clone();
    let text = flame_element(&f);
    assert!(text.contains("<palette count=\"512\""), "{text}");
    for attr in [
        "cam_pitch=\"1.0471975511966\"",
        "cam_zoom=\"2\"",
        "pre_blur=\"0.1\"",
        "post_curl_c1=\"0.3\"",
        "mod_contrast=\"1\"",
        "xyCoeff00Curve_enabled=\"false\"",
    ] {
        assert!(text.contains(attr), "{attr} missing in {text}");
    }
    let back = read(&text, &opts()).unwrap().value.flames[0].clone();
    assert_eq!(back.cam, f.cam);
    assert_eq!(back.cam_zoom, f.cam_zoom);
    assert_eq!(back.curves, f.curves);
    assert_eq!(back.xforms[0].vars, f.xforms[0].vars);
    assert_eq!(back.render_colors(), f.render_colors());
    // An edited gradient replaces the file's 512 colours.
    let mut edited = f.clone();
    edited.palette.colors[0] = [1.0, 1.0, 1.0, 1.0];
    assert_eq!(edited.render_colors().len(), 256);
    assert!(flame_element(&edited).contains("<palette count=\"256\""));
}

/// Each file keeps the palette rule of the program that wrote it, through ugnis' own files.
#[test]
fn palette_rule_follows_the_writing_program() {
    use crate::flame::PaletteIndex;
    let flame = |head: &str| {
        format!(
            "<flame name=\"p\" {head} size=\"8 8\" center=\"0 0\" scale=\"4\">\
                 <xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/></flame>"
        )
    };
    let one = |head: &str| read(&flame(head), &opts()).unwrap().value.flames[0].clone();
    for (head, index, mode) in [
        (
            "version=\"EMBER-LNX-1.0.0.19\" palette_mode=\"linear\"",
            PaletteIndex::Fractorium,
            PaletteMode::Linear,
        ),
        // Fractorium's own defaults where its file is silent.
        (
            "version=\"EMBER-25.25.12.1\"",
            PaletteIndex::Fractorium,
            PaletteMode::Linear,
        ),
        (
            "version=\"EMBER-25.25.12.1\" palette_mode=\"step\"",
            PaletteIndex::Fractorium,
            PaletteMode::Step,
        ),
        (
            "version=\"JWildfire V5.60 (07.05.2020)\" smooth_gradient=\"0\"",
            PaletteIndex::JWildfire,
            PaletteMode::Step,
        ),
        (
            "version=\"JWildfire V5.60 (07.05.2020)\" smooth_gradient=\"1\"",
            PaletteIndex::JWildfire,
            PaletteMode::Linear,
        ),
        (
            "version=\"Apophysis 7x\"",
            PaletteIndex::Apophysis,
            PaletteMode::Step,
        ),
        (
            "version=\"FLAM3-LNX-3.1.1\"",
            PaletteIndex::Flam3,
            PaletteMode::Step,
        ),
        (
            "smooth_gradient=\"1\"",
            PaletteIndex::Flam3,
            PaletteMode::Step,
        ),
        (
            "version=\"ugnis-0.1.0\" ugnis_palette_index=\"jwildfire\"",
            PaletteIndex::JWildfire,
            PaletteMode::Step,
        ),
    ] {
        let f = one(head);
        assert_eq!((f.palette_index, f.palette_mode), (index, mode), "{head}");
        let text = flame_element(&f);
        assert_eq!(
            text.contains("ugnis_palette_index="),
            index != PaletteIndex::Flam3,
            "{text}"
        );
        let back = read(&text, &opts()).unwrap().value.flames[0].clone();
        assert_eq!(back, f, "{head}");
    }
    // Highlight power: Fractorium's default 1, flam3's −1, a written value kept.
    assert_eq!(one("version=\"EMBER-25.25.12.1\"").highlight_power, 1.0);
    assert_eq!(
        one("version=\"EMBER-25.25.12.1\" highlight_power=\"-1\"").highlight_power,
        -1.0
    );
    assert_eq!(one("version=\"FLAM3-LNX-3.1.1\"").highlight_power, -1.0);
    let e = read(&flame("ugnis_palette_index=\"xaos\""), &opts()).unwrap_err();
    assert!(
        e.to_string()
            .contains("must be 'flam3', 'apophysis', 'fractorium' or 'jwildfire'"),
        "{e}"
    );
}

/// JWildfire's text parameters: the hex digits of their bytes, read into the variation and
/// written back the same way.
#[test]
fn text_parameters_round_trip_as_hex() {
    let src = r#"<flame name="t" size="8 8" center="0 0" scale="4">
<xform weight="1" color="0" text_wf="1" text_wf_font_size="100" text_wf_text="53594D20C3A9" text_wf_font_name="417269616C" coefs="1 0 0 1 0 0"/>
<xform weight="1" color="1" linear="1" text_wf_text="4142" coefs="1 0 0 1 0 0"/></flame>"#;
    let p = read(src, &opts()).unwrap();
    assert!(
        p.warnings.iter().all(|w| w.code == "XML018"), // no palette in this snippet
        "{:?}",
        p.warnings
    );
    let x = &p.value.flames[0].xforms;
    let v = &x[0].vars[0];
    assert_eq!(v.texts, ["SYM é", "Arial"]);
    assert_eq!(v.params[0], 100.0);
    // A text of an absent variation is kept as it was.
    assert!(
        x[1].extra_attrs
            .contains(&("text_wf_text".into(), "4142".into()))
    );
    let text = write(&p.value);
    assert!(text.contains("text_wf_text=\"53594D20C3A9\""), "{text}");
    assert!(text.contains("text_wf_font_name=\"417269616C\""), "{text}");
    let back = read(&text, &opts()).unwrap().value;
    assert_eq!(back.flames, p.value.flames);
    // Not hex digits: taken as written.
    let plain = src.replace("53594D20C3A9", "hello!");
    let q = read(&plain, &opts()).unwrap().value;
    assert_eq!(q.flames[0].xforms[0].vars[0].texts[0], "hello!");
}

#[test]
fn reads_attributes_and_palette() {
    let p = read(SIMPLE, &opts()).unwrap();
    let ff = p.value;
    assert_eq!(ff.name, "test");
    let f = &ff.flames[0];
    assert_eq!((f.width, f.height), (64, 48));
    assert_eq!(f.center, [0.5, -0.25]);
    assert_eq!(f.quality, 50.0);
    assert_eq!(f.gamma, 2.5);
    assert_eq!(f.gamma_threshold, 0.01);
    assert_eq!(f.xforms.len(), 2);
    let x0 = &f.xforms[0];
    // coefs are "a c b d e f".
    assert_eq!(x0.coefs, Affine::new(0.85, 0.04, -0.04, 0.85, 0.0, 1.6));
    assert_eq!(x0.var_weight(variations::SPHERICAL), 0.5 * 2.0);
    let x1 = &f.xforms[1];
    assert_eq!(x1.color_speed, 0.0);
    let j = x1.var(variations::JULIAN).unwrap();
    assert_eq!(j.params, vec![3.0, -1.0]);
    assert_eq!(x1.chaos, vec![1.0, 0.0]);
    assert_eq!(x1.post.e, 0.1);
    let fx = f.final_xform.as_ref().unwrap();
    assert_eq!(fx.color_speed, 0.0);
    // Undefined palette entries are interpolated.
    assert_eq!(f.palette.colors[0][0], 1.0);
    assert_eq!(f.palette.colors[255][2], 1.0);
    assert!((f.palette.colors[128][0] - (127.0 / 255.0)).abs() < 1e-12);
    assert_eq!(f.extra_children.len(), 1);
    assert!(f.extra_children[0].starts_with("<edit date=\"today\">"));
}

#[test]
fn round_trip_is_lossless() {
    let src = r#"<flame name="r" size="10 10" center="0 0" scale="5" foo="bar">
<xform weight="1" color="0.3" linear="0.7" waves="0.3" coefs="1 2 3 4 5 6" animate="0" my_plugin="2" my_plugin_amount="0.5"/>
<palette count="2" format="RGB">FF000000FF00</palette></flame>"#;
    let a = read(src, &opts()).unwrap();
    assert!(a.warnings.iter().any(|w| w.message.contains("my_plugin")));
    let text = write(&a.value);
    let b = read(&text, &opts()).unwrap().value;
    assert_eq!(a.value.flames, b.flames);
    let x = &b.flames[0].xforms[0];
    assert!(x.extra_attrs.contains(&("my_plugin".into(), "2".into())));
    assert!(
        b.flames[0]
            .extra_attrs
            .contains(&("foo".into(), "bar".into()))
    );
    // Writing again gives the same text.
    assert_eq!(write(&b), text);
}

#[test]
fn hex_palette_and_errors_have_positions() {
    let bad = "<flame size=\"1 x\"><xform weight=\"1\" coefs=\"1 0 0 1 0 0\"/></flame>";
    let e = read(bad, &opts()).unwrap_err();
    assert_eq!(e.code, "XML003");
    assert_eq!(e.line(), Some(1));
    let e = read(
        "<flame><xform weight=\"-1\" coefs=\"1 0 0 1 0 0\"/></flame>",
        &opts(),
    )
    .unwrap_err();
    assert_eq!(e.code, "XML005");
    let e = read(
        "<flame>\n<xform weight=\"1\" coefs=\"1 0 0 1 0\"/></flame>",
        &opts(),
    )
    .unwrap_err();
    assert_eq!(e.code, "XML004");
    assert_eq!(e.pos, Pos::LineCol(2, 26));
    let e = read(
        "<flame><xform weight=\"0\" coefs=\"1 0 0 1 0 0\"/></flame>",
        &opts(),
    )
    .unwrap_err();
    assert_eq!(e.code, "XML007");
    let e = read("<flames/>", &opts()).unwrap_err();
    assert_eq!(e.code, "XML002");
    let e = read("<flame><xform weight='1'/>", &opts()).unwrap_err();
    assert_eq!(e.code, "XML001");
    let e = read("<flame palette=\"3\"><xform weight='1'/></flame>", &opts()).unwrap_err();
    assert_eq!(e.code, "XML011");
    assert!(e.message.contains("flam3-palettes.xml"), "{e}");
    let e = read(
            "<flame><xform weight='1'/><palette count=\"2\" format=\"RGB\">FF00 00FF0000</palette></flame>",
            &opts(),
        )
        .unwrap_err();
    assert_eq!(e.code, "XML010");
    let e = read(
        "<flame estimator_radius=\"1\" estimator_minimum=\"2\"><xform weight='1'/></flame>",
        &opts(),
    )
    .unwrap_err();
    assert_eq!(e.code, "XML012");
    let e = read("<flame quality=\"0\"><xform weight='1'/></flame>", &opts()).unwrap_err();
    assert_eq!(e.code, "XML013");
    let e = read("<flame><xform weight='1' chaos='1 -1'/></flame>", &opts()).unwrap_err();
    assert_eq!(e.code, "XML008");
    let e = read(
        "<flame><xform weight='1'/><color index='256' rgb='1 2 3'/></flame>",
        &opts(),
    )
    .unwrap_err();
    assert_eq!(e.code, "XML009");
    let e = read("<flame><xform weight='1' color='0,5'/></flame>", &opts()).unwrap_err();
    assert!(e.message.contains("decimal separator"), "{e}");
}

#[test]
fn fla_rules() {
    let o = ReadOptions {
        fla: true,
        ..opts()
    };
    let e = read(
        "<pick><flame name='a'><xform weight='1'/></flame></pick>",
        &o,
    )
    .unwrap_err();
    assert_eq!(e.code, "FLA001");
    let e = read(
            "<flames>\n<flame name='a'><xform weight='1'/></flame>\n<flame name='a'><xform weight='1'/></flame></flames>",
            &o,
        )
        .unwrap_err();
    assert_eq!(e.code, "FLA002");
    assert!(e.message.contains("2:1"), "{e}");
    let e = read(
        "<flames><flame name='a' ugnis_kind='x'><xform weight='1'/></flame></flames>",
        &o,
    )
    .unwrap_err();
    assert_eq!(e.code, "FLA004");
}

#[test]
fn several_roots_and_pick() {
    let src = "<pick><flame name='a'><xform weight='1' linear='1'/></flame><flame name='b'><xform weight='1'/></flame></pick>";
    let f = read(src, &opts()).unwrap().value;
    assert_eq!(f.flames.len(), 2);
    assert_eq!(f.flames[1].name, "b");
    // No colour data → default gradient with a warning.
    let p = read(src, &opts()).unwrap();
    assert!(p.warnings.iter().any(|w| w.code == "XML018"));
}

#[test]
fn legacy_forms() {
    let src = "<flame angle=\"0.5\" oversample=\"2\" contrast=\"2\"><xform weight='1' var='0 0 1' coefs='1 0 0 1 0 0' plotmode='off'/><xform weight='1' var1='14'/><symmetry kind='3'/></flame>";
    let f = &read(src, &opts()).unwrap().value.flames[0];
    assert!((f.rotate + 0.5f64.to_degrees()).abs() < 1e-12);
    assert_eq!(f.supersample, 2);
    assert_eq!(f.contrast, 2.0);
    assert_eq!(f.xforms[0].var_weight(variations::SPHERICAL), 1.0);
    assert_eq!(f.xforms[0].opacity, 0.0);
    assert_eq!(f.xforms[1].var_weight(variations::BENT), 1.0);
    assert_eq!(f.xforms.len(), 4);
}

#[test]
fn writer_follows_apophysis_line_rules() {
    let f = read(SIMPLE, &opts()).unwrap().value;
    let t = write(&f);
    for line in t.lines() {
        if line.contains("<flame ") {
            assert!(line.trim_start().starts_with("<flame ") && line.ends_with('>'));
        }
    }
    assert!(t.lines().any(|l| l.trim() == "</flame>"));
    assert!(t.contains("new_linear=\"1\""));
    // symmetry written before color_speed when s ≠ 0.5
    assert!(t.contains("symmetry=\"1\" color_speed=\"0\""));
    // Palette as zero-padded upper-case hex, 8 colours per line.
    assert!(t.contains("FF0000FE0001"), "{t}");
    assert!(!t.contains("ugnis_kind") || t.contains("ugnis_kind=\"flame\""));
}

#[test]
fn a_second_curve_for_one_target_is_skipped_with_a_warning() {
    use crate::flame::keyframes::{FlameParam, Key, Target};
    let mut f = read(SIMPLE, &opts()).unwrap().value.flames.remove(0);
    let zoom = Target::Flame(FlameParam::Zoom);
    f.keys.frames = 10;
    let c = f.keys.curve_mut(zoom);
    c.insert(Key::new(0.0, 1.0)).unwrap();
    c.insert(Key::new(9.0, 2.0)).unwrap();
    let text = flame_element(&f);
    let (a, b) = (
        text.find("<curve").unwrap(),
        text.find("</curve>").unwrap() + 8,
    );
    let curve = &text[a..b];
    let doubled = text.replacen(
        curve,
        &format!("{curve}{}", curve.replace("\"2\"", "\"5\"")),
        1,
    );
    let p = read(&doubled, &opts()).unwrap();
    let back = &p.value.flames[0];
    assert_eq!(back.keys.curves.len(), 1);
    assert_eq!(back.keys, f.keys, "the first curve is played");
    assert!(
        p.warnings
            .iter()
            .any(|w| w.to_string().contains("second curve for 'zoom'")),
        "{:?}",
        p.warnings
    );
}

/// A parameter only the JWildfire formula of a variation has (`splits`' shears, beyond the
/// registry's `splits_x` and `splits_y`) is read, kept and rendered, not refused.
#[test]
fn parameters_only_jwildfires_formula_has_are_read() {
    let xml = r#"<flame name="s" version="JWildfire V9.00" size="16 12" scale="10" quality="2">
  <xform weight="1" color="0" splits="1" splits_x="0.1" splits_y="0.2" splits_lshear="0.3" splits_rshear="0.4" coefs="0.5 0 0 0.5 0 0"/>
</flame>"#;
    let f = read(xml, &opts()).unwrap().value.flames.remove(0);
    let v = &f.xforms[0].vars[0];
    assert!(v.params.len() > 2 && v.params.contains(&0.3) && v.params.contains(&0.4));
    crate::flame::render(&f, &crate::flame::RenderOptions::default()).unwrap();
}

/// JWildfire reads a variation's parameters by their exact names: a name written with other
/// letter case (as older JWildfire versions wrote `dc_starsfield_Glow`) keeps the default and
/// is kept as an attribute; flam3-style files still match names in any case, and so do names
/// the registry spells with capitals.
#[test]
fn jwildfire_parameter_names_are_case_sensitive() {
    let xform =
        r#"<xform weight="1" julian="0.5" julian_Power="5" julian_dist="2" coefs="1 0 0 1 0 0"/>"#;
    let jwf = format!(r#"<flame version="JWildfire V9.00">{xform}</flame>"#);
    let f = read(&jwf, &opts()).unwrap().value.flames.remove(0);
    let x = &f.xforms[0];
    let julian = variations::parse_name("julian").unwrap().0;
    let power = variations::info(julian).params[0].default;
    assert_eq!(x.vars[0].params[..2], [power, 2.0]);
    assert!(x.extra_attrs.contains(&("julian_Power".into(), "5".into())));
    let out = write(&FlameFile {
        name: String::new(),
        flames: vec![f.clone()],
    });
    assert!(out.contains("julian_Power=\"5\""), "{out}");
    let flam3 = format!(r#"<flame>{xform}</flame>"#);
    let f = read(&flam3, &opts()).unwrap().value.flames.remove(0);
    assert_eq!(f.xforms[0].vars[0].params[..2], [5.0, 2.0]);
    // JWildfire's own spelling is read; another letter case is not, as JWildfire 9.00 reads
    // neither sym_bg5_StepX nor dc_inversion_Iterations (its 6.x spelling).
    let sym = |attrs: &str| {
        let src = format!(
            r#"<flame version="JWildfire V9.00"><xform weight="1" {attrs} coefs="1 0 0 1 0 0"/></flame>"#
        );
        read(&src, &opts()).unwrap().value.flames.remove(0).xforms[0].vars[0]
            .params
            .clone()
    };
    assert!(sym(r#"sym_bg5="1" sym_bg5_stepx="0.375""#).contains(&0.375));
    assert!(!sym(r#"sym_bg5="1" sym_bg5_StepX="0.375""#).contains(&0.375));
    assert!(sym(r#"dc_inversion="1" dc_inversion_iterations="37""#).contains(&37.0));
    assert!(!sym(r#"dc_inversion="1" dc_inversion_Iterations="37""#).contains(&37.0));
    assert!(sym(r#"dc_inversion="1" dc_inversion_scaleX="2.25""#).contains(&2.25));
}

/// JWildfire runs a variation of amount 0 too: one that colours or hides points is kept from
/// JWildfire's files (and through ugnis' own copy of them), one that only moves points is not,
/// and flam3's files keep neither.
#[test]
fn jwildfire_keeps_colouring_variations_of_amount_zero() {
    let src = |version: &str| {
        format!(
            r#"<flame name="z" {version} size="64 48" scale="20">
  <xform weight="1" color="0" cpow3="1" dc_linear="0" dc_linear_scale="0.85" spherical="0" coefs="1 0 0 1 0 0"/>
</flame>"#
        )
    };
    let names = |f: &crate::flame::model::Flame| -> Vec<(String, f64)> {
        f.xforms[0]
            .vars
            .iter()
            .map(|v| (variations::info(v.id).name.to_string(), v.weight))
            .collect()
    };
    let jwf = read(&src(r#"version="JWildfire V5.50 (21.12.2019)""#), &opts()).unwrap();
    let f = jwf.value.flames[0].clone();
    let want = [("cpow3".to_string(), 1.0), ("dc_linear".to_string(), 0.0)];
    assert_eq!(names(&f), want);
    let back = read(&flame_element(&f), &opts()).unwrap().value.flames[0].clone();
    assert_eq!(names(&back), want);
    let flam3 = read(&src(""), &opts()).unwrap().value.flames[0].clone();
    assert_eq!(names(&flam3), [("cpow3".to_string(), 1.0)]);
}

/// ducks' code other than its default is reported; dc_code's code is checked against the
/// source its `randomize` seed writes (JWildfire 9.00's `randomizeCode`, seed 10002).
#[test]
fn code_of_the_escape_time_pictures_is_checked() {
    let hex = |s: &str| s.bytes().map(|b| format!("{b:02X}")).collect::<String>();
    let seed_10002 = "public vec3 getRGBColor(double xp,double yp)\n{\n  vec2 p=new vec2(xp,yp);\n  \
        p=p.multiply(zoom).minus(new vec2(stepX,stepY));\n  double t=26.52197521717507;\n  \
        vec3 color=new vec3(0.0);\n  vec2 z = new vec2(0.0);\n   vec2 c=p;\n   \
        for(int k = 0; k < 32; ++k) {\n      if (length(z) > 2.) break;\n          \
        z = c_add(c_mul(z,z),c);\n      t = (double)k;\n   }\n   \
        double t1=length(c_tanh(z));\n   \
        color =  new vec3(t/32., t/64., t/24.).multiply(t1);\n   return color;\n}\n";
    let flame = |seed: u32| {
        format!(
            r#"<flame name="c" version="JWildfire V9.00" size="16 12" scale="10" quality="2">
  <xform weight="1" color="0" ducks="1" ducks_code="{}" coefs="1 0 0 1 0 0"/>
  <xform weight="1" color="0" dc_code="1" dc_code_randomize="{seed}" dc_code_code="{}" coefs="1 0 0 1 0 0"/>
</flame>"#,
            hex("public Complex f(Complex z, Complex c) { return z; }"),
            hex(seed_10002)
        )
    };
    let msgs = |seed| {
        let p = read(&flame(seed), &opts()).unwrap();
        p.warnings.iter().map(|w| w.to_string()).collect::<Vec<_>>()
    };
    let (right, wrong) = (msgs(10002), msgs(10001));
    let has = |m: &[String], s: &str| m.iter().any(|w| w.contains(s));
    assert!(
        has(&right, "ducks: custom code is not supported"),
        "{right:?}"
    );
    assert!(!has(&right, "dc_code"), "{right:?}");
    assert!(
        has(&wrong, "dc_code: edited code is not supported"),
        "{wrong:?}"
    );
}

/// Java code other than a variation's default (which ugnis runs instead) and a plot formula
/// that does not compile are read, and each is reported by name; the default code and a
/// formula that compiles are not.
#[test]
fn unsupported_code_and_bad_formulas_are_reported() {
    let hex = |s: &str| s.bytes().map(|b| format!("{b:02X}")).collect::<String>();
    let xml = format!(
        r#"<flame name="c" version="JWildfire V9.00" size="16 12" scale="10" quality="2">
  <xform weight="1" color="0" custom_wf="1" custom_wf_code="{}" coefs="1 0 0 1 0 0"/>
  <xform weight="1" color="0" yplot2d_wf="1" yplot2d_wf_formula="{}" coefs="1 0 0 1 0 0"/>
  <xform weight="1" color="0" yplot3d_wf="1" yplot3d_wf_formula="{}" coefs="1 0 0 1 0 0"/>
</flame>"#,
        hex("pVarTP.x += pAmount;"),
        hex("sin(x) +"),
        hex("x > 0 ? sin(x*z) : -pi")
    );
    let p = read(&xml, &opts()).unwrap();
    let msgs: Vec<String> = p.warnings.iter().map(|w| w.to_string()).collect();
    let has = |s: &str| msgs.iter().any(|m| m.contains(s));
    assert!(
        has("custom_wf: custom code is not supported; the default code is used"),
        "{msgs:?}"
    );
    assert!(
        has("yplot2d_wf_formula: the formula does not compile"),
        "{msgs:?}"
    );
    assert!(!has("yplot3d_wf"), "{msgs:?}");
    let f = &p.value.flames[0];
    assert_eq!(f.xforms[1].vars[0].texts[0], "sin(x) +");
    crate::flame::render(f, &crate::flame::RenderOptions::default()).unwrap();
}
