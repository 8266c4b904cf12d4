//! Attribute names ↔ variations: the names a variation, its `pre_`/`post_` forms and its
//! parameters take in files, the aliases other programs write, the variations of other programs
//! ugnis does not render, and flam3's numeric indices.

use std::collections::HashMap;

use super::VarId;
use super::def::{Dialect, Form, VarDef, flag};
use super::flam3::GAUSSIAN_BLUR;
use super::registry::{REGISTRY, def_in, info};

/// A regular variation by name (case-insensitive).
pub fn by_name(name: &str) -> Option<VarId> {
    let key = name.to_ascii_lowercase();
    let id = *REGISTRY.names.get(&key)?;
    (!info(id).has(flag::POST_ONLY | flag::PRE_ONLY)).then_some(id)
}

/// The variation and form an attribute name denotes: `NAME`, `pre_NAME` or `post_NAME`
/// (case-insensitive). flam3's `pre_blur` is the `pre_` form of `gaussian_blur`.
pub fn parse_name(attr: &str) -> Option<(VarId, Form)> {
    let key = unalias(&attr.to_ascii_lowercase());
    lookup_in(&REGISTRY.names, &REGISTRY.defs, &key)
}

/// The form a variation registered under its own name takes: `pre_`/`post_` for the
/// variations that exist only so (registered under their prefixed names).
fn own_form(d: &VarDef) -> Form {
    if d.has(flag::POST_ONLY) {
        Form::Post
    } else if d.has(flag::PRE_ONLY) {
        Form::Pre
    } else {
        Form::Regular
    }
}

/// [`parse_name`] of a lower-case name without aliases, in the table `names` (lower-case
/// name → id) of the variations `defs`.
pub(super) fn lookup_in(
    names: &HashMap<String, VarId>,
    defs: &[&VarDef],
    key: &str,
) -> Option<(VarId, Form)> {
    if key == "pre_blur" {
        return Some((GAUSSIAN_BLUR, Form::Pre));
    }
    if let Some(&id) = names.get(key) {
        return Some((id, own_form(defs[id as usize])));
    }
    [("pre_", Form::Pre), ("post_", Form::Post)]
        .into_iter()
        .find_map(|(prefix, form)| Some((*names.get(key.strip_prefix(prefix)?)?, form)))
}

/// The attribute name of a variation used in `form`.
pub fn attr_name(id: VarId, form: Form) -> String {
    let d = info(id);
    if form == Form::Pre && id == GAUSSIAN_BLUR {
        return "pre_blur".to_string();
    }
    if d.has(flag::POST_ONLY | flag::PRE_ONLY) {
        return d.name.to_string();
    }
    format!("{}{}", form.prefix(), d.name)
}

/// The attribute name of parameter `k` of a variation used in `form`.
pub fn param_attr_name(id: VarId, form: Form, k: usize) -> String {
    param_attr_name_in(Dialect::Flam3, id, form, k)
}

/// The attribute name of parameter `k` of a variation used in `form` in a flame of
/// `dialect` (JWildfire names some parameters its own way, and has a few more: see
/// [`def_in`](super::def_in)).
pub fn param_attr_name_in(dialect: Dialect, id: VarId, form: Form, k: usize) -> String {
    let name = def_in(dialect, id, form).params[k].name;
    if info(id).has(flag::POST_ONLY | flag::PRE_ONLY) {
        return name.to_string();
    }
    format!("{}{name}", form.prefix())
}

/// The attribute name of text parameter `k` of a variation used in `form`.
pub fn text_attr_name(id: VarId, form: Form, k: usize) -> String {
    let d = info(id);
    let name = d.texts[k].name;
    // A pre- or post-only variation's text is named as its parameters are: as it stands.
    if d.has(flag::POST_ONLY | flag::PRE_ONLY) {
        return name.to_string();
    }
    format!("{}{name}", form.prefix())
}

/// Why the text parameters `texts` of variation `id` (with parameters `params`) cannot be used
/// as they are (a formula that does not compile, Java code other than the default that ugnis
/// runs instead), for the reader of a file to report; `None` when they can.
pub fn text_problem(id: VarId, params: &[f64], texts: &[String]) -> Option<String> {
    let name = info(id).name;
    if name == "dc_code" {
        return super::jwf_s10_code_dc::code_problem(params.first().copied().unwrap_or(0.0), texts);
    }
    super::jwf_h9a_plots::formula_problem(name, texts)
        .or_else(|| super::jwf_h9a_code::code_problem(name, texts))
        .or_else(|| super::jwf_aa_svg::svg_problem(name, texts))
        .or_else(|| super::jwf_ls_mesh::grammar_problem(name, params, texts))
}

/// If `attr` names a text parameter — `TEXT`, `pre_TEXT` or `post_TEXT` — the variation, form
/// and text index (case-insensitive).
pub fn text_of(attr: &str) -> Option<(VarId, Form, usize)> {
    let key = attr.to_ascii_lowercase();
    if let Some(&(id, k)) = REGISTRY.texts.get(&key) {
        return Some((id, own_form(info(id)), k));
    }
    [("pre_", Form::Pre), ("post_", Form::Post)]
        .into_iter()
        .find_map(|(prefix, form)| {
            let &(id, k) = REGISTRY.texts.get(key.strip_prefix(prefix)?)?;
            Some((id, form, k))
        })
}

/// Parameter names other programs write for a variation's parameters.
const PARAM_ALIASES: &[(&str, &str)] = &[
    // Apophysis 7X writes mobius's parameters without the variation prefix.
    ("re_a", "mobius_re_a"),
    ("im_a", "mobius_im_a"),
    ("re_b", "mobius_re_b"),
    ("im_b", "mobius_im_b"),
    ("re_c", "mobius_re_c"),
    ("im_c", "mobius_im_c"),
    ("re_d", "mobius_re_d"),
    ("im_d", "mobius_im_d"),
    // JWildfire writes waves2_radial's parameters with a "w2r" infix.
    ("waves2_radial_w2r_freqx", "waves2_radial_freqx"),
    ("waves2_radial_w2r_scalex", "waves2_radial_scalex"),
    ("waves2_radial_w2r_freqy", "waves2_radial_freqy"),
    ("waves2_radial_w2r_scaley", "waves2_radial_scaley"),
    ("waves2_radial_w2r_null", "waves2_radial_null"),
    ("waves2_radial_w2r_distance", "waves2_radial_distance"),
    // JWildfire 7 wrote the direct-colour variations' z settings the other way round.
    ("dc_mandala_z_scale", "dc_mandala_scale_z"),
    ("dc_mandala_z_offset", "dc_mandala_offset_z"),
    ("dc_inversion_z_scale", "dc_inversion_scale_z"),
    ("dc_inversion_z_offset", "dc_inversion_offset_z"),
    ("dc_poincaredisc_z_scale", "dc_poincaredisc_scale_z"),
    ("dc_poincaredisc_z_offset", "dc_poincaredisc_offset_z"),
    ("dc_circuits_z_scale", "dc_circuits_scale_z"),
    ("dc_circuits_z_offset", "dc_circuits_offset_z"),
    ("dc_turbulence_z_scale", "dc_turbulence_scale_z"),
    ("dc_turbulence_z_offset", "dc_turbulence_offset_z"),
    ("dc_gabornoise_z_scale", "dc_gabornoise_scale_z"),
    ("dc_gabornoise_z_offset", "dc_gabornoise_offset_z"),
    // JWildfire's own spellings of parameters Fractorium names otherwise.
    ("circlesplit_cs_radius", "circlesplit_radius"),
    ("circlesplit_cs_split", "circlesplit_split"),
    ("d_spherical_d_spher_weight", "d_spherical_weight"),
    ("mobiq_qat", "mobiq_at"),
    ("mobiq_qax", "mobiq_ax"),
    ("mobiq_qay", "mobiq_ay"),
    ("mobiq_qaz", "mobiq_az"),
    ("mobiq_qbt", "mobiq_bt"),
    ("mobiq_qbx", "mobiq_bx"),
    ("mobiq_qby", "mobiq_by"),
    ("mobiq_qbz", "mobiq_bz"),
    ("mobiq_qct", "mobiq_ct"),
    ("mobiq_qcx", "mobiq_cx"),
    ("mobiq_qcy", "mobiq_cy"),
    ("mobiq_qcz", "mobiq_cz"),
    ("mobiq_qdt", "mobiq_dt"),
    ("mobiq_qdx", "mobiq_dx"),
    ("mobiq_qdy", "mobiq_dy"),
    ("mobiq_qdz", "mobiq_dz"),
    ("mobiusn_re_a", "mobiusnre_a"),
    ("mobiusn_im_a", "mobiusnim_a"),
    ("mobiusn_re_b", "mobiusnre_b"),
    ("mobiusn_im_b", "mobiusnim_b"),
    ("mobiusn_re_c", "mobiusnre_c"),
    ("mobiusn_im_c", "mobiusnim_c"),
    ("mobiusn_re_d", "mobiusnre_d"),
    ("mobiusn_im_d", "mobiusnim_d"),
    // JWildfire's post_crop_x and post_crop_trapezoid name crop_x's and crop_trapezoid's
    // parameters otherwise.
    ("crop_x_width", "crop_x_w"),
    ("crop_trapezoid_lmay", "crop_trapezoid_base sup."),
    ("crop_trapezoid_lmin", "crop_trapezoid_base inf."),
    // Earlier ugnis releases wrote these sym_ng parameters by other names.
    ("sym_ng4_skewx", "sym_ng4_stepx"),
    ("sym_ng4_skewy", "sym_ng4_stepy"),
    ("sym_ng5_skewx", "sym_ng5_stepx"),
    ("sym_ng6_skewx", "sym_ng6_stepx"),
    ("sym_ng6_skewy", "sym_ng6_stepy"),
    ("sym_ng10_spx", "sym_ng10_spacex"),
    ("sym_ng10_spy", "sym_ng10_spacey"),
    ("sym_ng11_spx", "sym_ng11_spacex"),
    ("sym_ng11_spy", "sym_ng11_spacey"),
    ("sym_ng12_spx", "sym_ng12_spacex"),
    ("sym_ng12_spy", "sym_ng12_spacey"),
    ("sym_ng13_prop_sep", "sym_ng13_radius"),
    ("sym_ng14_prop_sep", "sym_ng14_radius"),
    ("sym_ng15_prop_sep", "sym_ng15_radius"),
    ("sym_ng16_prop_sep", "sym_ng16_radius"),
    ("sym_ng17_prop_sep", "sym_ng17_radius"),
];

/// Parameter names Apophysis' plugins write that Fractorium reads as other parameters in the
/// files it did not write (Fractorium 1.0.0.19, `XmlToEmber`'s table of bad parameter names,
/// the entries whose target ugnis has). Applied to Apophysis' flames only: Fractorium's own
/// files keep their names.
const APOPHYSIS_PARAM_NAMES: &[(&str, &str)] = &[
    ("rx_sin", "rotate_x_sin"),
    ("rx_cos", "rotate_x_cos"),
    ("ry_sin", "rotate_y_sin"),
    ("ry_cos", "rotate_y_cos"),
    ("intrfr2_a1", "interference2_a1"),
    ("intrfr2_b1", "interference2_b1"),
    ("intrfr2_c1", "interference2_c1"),
    ("intrfr2_p1", "interference2_p1"),
    ("intrfr2_t1", "interference2_t1"),
    ("intrfr2_a2", "interference2_a2"),
    ("intrfr2_b2", "interference2_b2"),
    ("intrfr2_c2", "interference2_c2"),
    ("intrfr2_p2", "interference2_p2"),
    ("intrfr2_t2", "interference2_t2"),
    ("octa_x", "octagon_x"),
    ("octa_y", "octagon_y"),
    ("octa_z", "octagon_z"),
    ("bubble_x", "bubble2_x"),
    ("bubble_y", "bubble2_y"),
    ("bubble_z", "bubble2_z"),
    ("cubic3d_xpand", "cubiclattice_3d_xpand"),
    ("cubic3d_style", "cubiclattice_3d_style"),
    ("splitb_x", "splitbrdr_x"),
    ("splitb_y", "splitbrdr_y"),
    ("splitb_px", "splitbrdr_px"),
    ("splitb_py", "splitbrdr_py"),
    ("dc_cyl_offset", "dc_cylinder_offset"),
    ("dc_cyl_angle", "dc_cylinder_angle"),
    ("dc_cyl_scale", "dc_cylinder_scale"),
    ("cyl_x", "dc_cylinder_x"),
    ("cyl_y", "dc_cylinder_y"),
    ("cyl_blur", "dc_cylinder_blur"),
    ("mobius_radius", "mobius_strip_radius"),
    ("mobius_width", "mobius_strip_width"),
    ("mobius_rect_x", "mobius_strip_rect_x"),
    ("mobius_rect_y", "mobius_strip_rect_y"),
    ("mobius_rotate_x", "mobius_strip_rotate_x"),
    ("mobius_rotate_y", "mobius_strip_rotate_y"),
    ("hexa3d_majp", "hexaplay3d_majp"),
    ("hexa3d_scale", "hexaplay3d_scale"),
    ("hexa3d_zlift", "hexaplay3d_zlift"),
    ("nb_numedges", "nblur_numedges"),
    ("nb_numstripes", "nblur_numstripes"),
    ("nb_ratiostripes", "nblur_ratiostripes"),
    ("nb_ratiohole", "nblur_ratiohole"),
    ("nb_circumcircle", "nblur_circumcircle"),
    ("nb_adjusttolinear", "nblur_adjusttolinear"),
    ("nb_equalblur", "nblur_equalblur"),
    ("nb_exactcalc", "nblur_exactcalc"),
    ("nb_highlightedges", "nblur_highlightedges"),
    ("octapol_r", "octapol_radius"),
    ("post_scrop_power", "post_smartcrop_power"),
    ("post_scrop_radius", "post_smartcrop_radius"),
    ("post_scrop_roundstr", "post_smartcrop_roundstr"),
    ("post_scrop_roundwidth", "post_smartcrop_roundwidth"),
    ("post_scrop_distortion", "post_smartcrop_distortion"),
    ("post_scrop_edge", "post_smartcrop_edge"),
    ("post_scrop_scatter", "post_smartcrop_scatter"),
    ("post_scrop_offset", "post_smartcrop_offset"),
    ("post_scrop_rotation", "post_smartcrop_rotation"),
    ("post_scrop_cropmode", "post_smartcrop_cropmode"),
    ("post_scrop_static", "post_smartcrop_static"),
    ("cs_radius", "circlesplit_radius"),
    ("cs_split", "circlesplit_split"),
    ("w2r_freqx", "waves2_radial_freqx"),
    ("w2r_scalex", "waves2_radial_scalex"),
    ("w2r_freqy", "waves2_radial_freqy"),
    ("w2r_scaley", "waves2_radial_scaley"),
    ("w2r_null", "waves2_radial_null"),
    ("w2r_distance", "waves2_radial_distance"),
    ("tf_exponent", "truchet_fill_exponent"),
    ("tf_arc_width", "truchet_fill_arc_width"),
    ("tf_seed", "truchet_fill_seed"),
    ("radial_gaussian_angle", "radial_blur_angle"),
    ("pr_a", "projective_a"),
    ("pr_b", "projective_b"),
    ("pr_c", "projective_c"),
    ("pr_a1", "projective_a1"),
    ("pr_b1", "projective_b1"),
    ("pr_c1", "projective_c1"),
    ("pr_a2", "projective_a2"),
    ("pr_b2", "projective_b2"),
    ("pr_c2", "projective_c2"),
    ("db_power", "depth_blur_power"),
    ("db_range", "depth_blur_range"),
    ("db_blur", "depth_blur_blur"),
    ("db_radius", "depth_blur_radius"),
    ("osco2_separation", "oscilloscope2_separation"),
    ("osco2_frequencyx", "oscilloscope2_frequencyx"),
    ("osco2_frequencyy", "oscilloscope2_frequencyy"),
    ("osco2_amplitude", "oscilloscope2_amplitude"),
    ("osco2_perturbation", "oscilloscope2_perturbation"),
    ("osco2_damping", "oscilloscope2_damping"),
    ("oscope_separation", "oscilloscope_separation"),
    ("oscope_frequency", "oscilloscope_frequency"),
    ("oscope_amplitude", "oscilloscope_amplitude"),
    ("oscope_damping", "oscilloscope_damping"),
    ("sshape_power", "smartshape_power"),
    ("sshape_roundstr", "smartshape_roundstr"),
    ("sshape_roundwidth", "smartshape_roundwidth"),
    ("sshape_distortion", "smartshape_distortion"),
    ("sshape_compensation", "smartshape_compensation"),
    ("post_sshape_power", "post_smartshape_power"),
    ("post_sshape_roundstr", "post_smartshape_roundstr"),
    ("post_sshape_roundwidth", "post_smartshape_roundwidth"),
    ("post_sshape_distortion", "post_smartshape_distortion"),
    ("post_sshape_compensation", "post_smartshape_compensation"),
    ("d_spher_weight", "d_spherical_weight"),
    ("poincare_p", "poincare2_p"),
    ("poincare_q", "poincare2_q"),
    ("phoenix_power", "phoenix_julia_power"),
    ("phoenix_dist", "phoenix_julia_dist"),
    ("phoenixjulia_power", "phoenix_julia_power"),
    ("phoenixjulia_dist", "phoenix_julia_dist"),
    ("phoenixjulia_x_distort", "phoenix_julia_x_distort"),
    ("phoenixjulia_y_distort", "phoenix_julia_y_distort"),
];

/// The parameter an attribute of an Apophysis flame names by an Apophysis plugin's spelling
/// that is not the registry's (`octa_x` for `octagon_x`): the variation, form and parameter
/// index, as [`param_of`] gives them for the registry's spelling.
pub fn apophysis_param_of(attr: &str) -> Option<(VarId, Form, usize)> {
    let key = attr.to_ascii_lowercase();
    let target = APOPHYSIS_PARAM_NAMES.iter().find(|a| a.0 == key)?.1;
    param_of(target)
}

/// Variation names other programs use for a variation of the registry (lower case), also as
/// the prefix of its parameters.
/// (JWildfire's `flower_db` is its own variation, not Fractorium's `flowerdb`.)
const NAME_ALIASES: &[(&str, &str)] = &[];

/// `key` (lower case) with an alias prefix replaced by the registry's name.
fn unalias(key: &str) -> String {
    for (alias, name) in NAME_ALIASES {
        for prefix in ["", "pre_", "post_"] {
            if let Some(rest) = key.strip_prefix(prefix).and_then(|k| k.strip_prefix(alias))
                && (rest.is_empty() || rest.starts_with('_'))
            {
                return format!("{prefix}{name}{rest}");
            }
        }
    }
    key.to_string()
}

/// If `attr` names a parameter — `PARAM`, `pre_PARAM` or `post_PARAM` — the variation, form
/// and parameter index (case-insensitive; known aliases accepted).
pub fn param_of(attr: &str) -> Option<(VarId, Form, usize)> {
    let key = unalias(&attr.to_ascii_lowercase());
    let lookup = |k: &str| -> Option<(VarId, usize)> {
        if let Some(&r) = REGISTRY.params.get(k) {
            return Some(r);
        }
        let alias = PARAM_ALIASES.iter().find(|a| a.0 == k)?.1;
        REGISTRY.params.get(alias).copied()
    };
    if let Some((id, k)) = lookup(&key) {
        return Some((id, own_form(info(id)), k));
    }
    for (prefix, form) in [("pre_", Form::Pre), ("post_", Form::Post)] {
        if let Some(rest) = key.strip_prefix(prefix)
            && let Some((id, k)) = lookup(rest)
        {
            if form == Form::Pre && id == GAUSSIAN_BLUR {
                continue;
            }
            return Some((id, form, k));
        }
    }
    None
}

/// Names of variations of other programs (JWildfire, Apophysis plugins) that ugnis does not
/// render: an attribute with one of these names is an unsupported variation rather than some
/// other program's setting.
const FOREIGN_VARIATIONS: &[&str] = &[
    "cross2",
    "oscope",
    "perspective2",
    "wedge_julia_3D",
    "whorl3D",
];

/// True for names (optionally `pre_`/`post_`) of variations of other programs that ugnis does not
/// know: attributes that describe a variation weight rather than a setting.
pub fn is_foreign_variation_name(name: &str) -> bool {
    if parse_name(name).is_some() {
        return false;
    }
    let key = name.to_ascii_lowercase();
    let base = key
        .strip_prefix("pre_")
        .or_else(|| key.strip_prefix("post_"))
        .unwrap_or(&key);
    FOREIGN_VARIATIONS
        .iter()
        .any(|f| f.eq_ignore_ascii_case(&key) || f.eq_ignore_ascii_case(base))
}

/// The flam3 index (0–98) of a variation form, for flam3's numeric `var` lists.
pub fn from_flam3_index(i: usize) -> Option<(VarId, Form)> {
    match i {
        67 => Some((GAUSSIAN_BLUR, Form::Pre)),
        0..=98 => Some((i as VarId, Form::Regular)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Assign, GAUSSIAN_BLUR};
    use super::*;

    /// The `pre_`/`post_` forms that add their output to the point in Fractorium (the blurs
    /// and the random shapes); every other form replaces it. flam3's `pre_blur` adds too.
    #[test]
    fn blur_forms_add_to_the_point() {
        let sum = [
            "arch",
            "blur",
            "blur3D",
            "blur_circle",
            "blur_heart",
            "blur_square",
            "circleblur",
            "CircleRand",
            "concentric",
            "dc_cube",
            "gaussian_blur",
            "line",
            "Lissajous",
            "pie",
            "pie3D",
            "randCubes",
            "sineblur",
            "sphereblur",
            "Spirograph",
            "square",
            "square3D",
            "starblur",
            "SuperShape3D",
            "waffle",
            "zblur",
            "ztranslate",
        ];
        for name in sum {
            let (id, form) = parse_name(&format!("pre_{name}")).expect(name);
            assert_eq!(form, Form::Pre);
            assert_eq!(info(id).assign, Assign::Sum, "{name}");
        }
        for name in ["linear", "spherical", "julia", "stripes", "hexes"] {
            let (id, _) = parse_name(&format!("pre_{name}")).expect(name);
            assert_eq!(info(id).assign, Assign::Set, "{name}");
        }
        let (id, form) = parse_name("pre_blur").unwrap();
        assert_eq!(
            (id, form, info(id).assign),
            (GAUSSIAN_BLUR, Form::Pre, Assign::Sum)
        );
    }

    /// The list of foreign names holds only names the registry does not know (an implemented
    /// variation is recognised by the registry, so its entry would be dead).
    #[test]
    fn foreign_names_are_unknown_to_the_registry() {
        for name in FOREIGN_VARIATIONS {
            assert!(parse_name(name).is_none(), "{name} is implemented");
            assert!(is_foreign_variation_name(name));
            assert!(is_foreign_variation_name(&format!("pre_{name}")));
        }
        for known in ["linear3D", "post_mirror_wf", "rose_wf", "julia3Dz"] {
            assert!(!is_foreign_variation_name(known), "{known}");
        }
        assert!(!is_foreign_variation_name("weight"));
    }
}
