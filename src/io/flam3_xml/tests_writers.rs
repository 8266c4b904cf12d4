//! Tests of what a flame's writer changes in how its attributes are read: JWildfire's defaults
//! for the parameters its first releases left out, Apophysis' plugin parameters written
//! without their variation's prefix.

use super::tests::opts;
use super::*;
use crate::flame::PaletteIndex;

fn first(text: &str) -> Flame {
    read(text, &opts()).unwrap().value.flames.remove(0)
}

/// A file of JWildfire's first releases (version "0.16 (06.11.2011)") is JWildfire's: a
/// parameter it leaves out takes JWildfire's default (pdj a=1 b=2 c=3 d=4, rectangles
/// x=0.3 y=0.2), one it gives is kept; flam3's and Apophysis' files keep the registry's
/// defaults.
#[test]
fn jwildfire_defaults_for_left_out_parameters() {
    let xf = r#"<xform weight="1" pdj="0.3" pdj_b="7" rectangles="0.2" coefs="1 0 0 1 0 0"/>"#;
    let f = first(&format!(
        r#"<flame version="0.16 (06.11.2011)" size="64 48" scale="20">{xf}</flame>"#
    ));
    assert_eq!(f.palette_index, PaletteIndex::JWildfire);
    assert!(f.renders_as_jwildfire());
    let vars = &f.xforms[0].vars;
    assert_eq!(&vars[0].params[..4], &[1.0, 7.0, 3.0, 4.0]);
    assert_eq!(&vars[1].params[..2], &[0.3, 0.2]);
    for version in ["Apophysis 2.09", "FLAM3-LNX-3.1.1"] {
        let f = first(&format!(
            r#"<flame version="{version}" size="64 48" scale="20">{xf}</flame>"#
        ));
        let vars = &f.xforms[0].vars;
        assert_eq!(&vars[0].params[..4], &[0.0, 7.0, 0.0, 0.0], "{version}");
        assert_eq!(&vars[1].params[..2], &[1.0, 1.0], "{version}");
    }
}

/// Apophysis writes pixel_flow's parameters as `angle`, `len`, `width`, `seed` (the plugin's
/// names): in its files they are pixel_flow's parameters (a prefixed one wins), written back
/// with their prefix; in other programs' files they stay attributes ugnis does not interpret.
#[test]
fn apophysis_plugin_parameters_without_prefix() {
    let xf = r#"<xform weight="1" linear="1" pixel_flow="0.1" angle="130" len="1.2" width="100" pixel_flow_width="50" seed="7" coefs="1 0 0 1 0 0"/>"#;
    let f = first(&format!(
        r#"<flame version="Apophysis 7x" size="64 48" scale="20">{xf}</flame>"#
    ));
    let x = &f.xforms[0];
    let pf = x.vars.iter().find(|v| v.params.len() >= 4).unwrap();
    assert_eq!(&pf.params[..4], &[130.0, 1.2, 50.0, 7.0]);
    assert!(
        x.extra_attrs
            .iter()
            .all(|(k, _)| k != "angle" && k != "len")
    );
    let out = write(&FlameFile {
        name: String::new(),
        flames: vec![f.clone()],
    });
    assert!(out.contains("pixel_flow_angle=\"130\""), "{out}");
    let f = first(&format!(
        r#"<flame version="EMBER-WIN-1.0.0.19" size="64 48" scale="20">{xf}</flame>"#
    ));
    let x = &f.xforms[0];
    let pf = x.vars.iter().find(|v| v.params.len() >= 4).unwrap();
    assert_eq!(&pf.params[..4], &[90.0, 0.1, 50.0, 42.0]);
    assert!(
        x.extra_attrs
            .iter()
            .any(|(k, v)| k == "angle" && v == "130")
    );
}

/// Apophysis' octagon plugin writes its parameters as `octa_x`, `octa_y`, `octa_z`, which
/// Fractorium reads as `octagon_x` … in the files it did not write (its table of bad parameter
/// names); in Fractorium's own files they stay attributes ugnis does not interpret.
#[test]
fn apophysis_plugin_parameters_of_other_names() {
    let xf = r#"<xform weight="1" octagon="0.3" octa_x="0.164" octa_y="0.04" octa_z="0" coefs="1 0 0 1 0 0"/>"#;
    let f = first(&format!(
        r#"<flame version="Apophysis 7x" size="64 48" scale="20">{xf}</flame>"#
    ));
    let x = &f.xforms[0];
    assert_eq!(&x.vars[0].params[..3], &[0.164, 0.04, 0.0]);
    assert!(x.extra_attrs.iter().all(|(k, _)| !k.starts_with("octa_")));
    let f = first(&format!(
        r#"<flame version="EMBER-WIN-1.0.0.19" size="64 48" scale="20">{xf}</flame>"#
    ));
    let x = &f.xforms[0];
    assert_eq!(&x.vars[0].params[..3], &[0.0, 0.0, 0.0]);
    assert!(
        x.extra_attrs
            .iter()
            .any(|(k, v)| k == "octa_x" && v == "0.164")
    );
}
