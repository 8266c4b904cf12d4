//! JWildfire's defaults for variation parameters a JWildfire file leaves out. JWildfire
//! writes every parameter of a variation, but its first releases (2011, `version="0.16
//! (06.11.2011)"`) wrote none; JWildfire reading such a file keeps what each variation's
//! constructor sets. Where that differs from ugnis' default (flam3's or Fractorium's, as the
//! registry has it) the table below gives JWildfire's value (JWildfire 9.00, the constructors'
//! field initialisers, e.g. `PDJFunc` a=1 b=2 c=3 d=4, `RectanglesFunc` x=0.3 y=0.2).
//! Variations whose constructor draws random defaults (julia3D's power, …) keep ugnis' value.

use crate::flame::model::Xform;
use crate::flame::variations;

/// Variation name, then (parameter attribute, JWildfire's default) where it differs from the
/// registry's. The values are JWildfire's own numbers (its 1.5708 is not π/2), as written.
#[rustfmt::skip]
#[allow(clippy::approx_constant)]
const DEFAULTS: &[(&str, &[(&str, f64)])] = &[
    ("curl", &[("curl_c1", 0.1)]),
    ("curl3D", &[("curl3D_cy", 0.05), ("curl3D_cz", 0.05)]),
    ("rings2", &[("rings2_val", 0.01)]),
    ("rectangles", &[("rectangles_x", 0.3), ("rectangles_y", 0.2)]),
    ("pdj", &[("pdj_a", 1.0), ("pdj_b", 2.0), ("pdj_c", 3.0), ("pdj_d", 4.0)]),
    ("fan2", &[("fan2_x", 0.5), ("fan2_y", 1.2)]),
    ("radial_blur", &[("radial_blur_angle", 0.5)]),
    ("blob", &[("blob_low", 0.3), ("blob_high", 1.2), ("blob_waves", 6.0)]),
    ("blob3D", &[("blob3D_low", 0.3), ("blob3D_high", 1.2), ("blob3D_waves", 6.0)]),
    ("perspective", &[("perspective_angle", 0.62), ("perspective_dist", 2.2)]),
    ("pie", &[("pie_rotation", 0.0)]),
    ("pie3D", &[("pie3D_slices", 7.0), ("pie3D_rotation", 0.0)]),
    ("wedge", &[("wedge_count", 1.0), ("wedge_swirl", 0.1)]),
    ("waves2", &[("waves2_scalex", 0.25), ("waves2_scaley", 0.5), ("waves2_freqx", 1.5707963267948966), ("waves2_freqy", 0.7853981633974483)]),
    ("popcorn2", &[("popcorn2_x", 1.0), ("popcorn2_y", 0.5), ("popcorn2_c", 1.5)]),
    ("disc2", &[("disc2_rot", 2.0), ("disc2_twist", 0.5)]),
    ("super_shape", &[("super_shape_rnd", 3.0), ("super_shape_m", 1.0)]),
    ("flower", &[("flower_holes", 0.4), ("flower_petals", 7.0)]),
    ("parabola", &[("parabola_width", 1.0), ("parabola_height", 0.5)]),
    ("cell", &[("cell_size", 0.6)]),
    ("cpow", &[("cpow_i", 0.1), ("cpow_power", 1.5)]),
    ("curve", &[("curve_xamp", 0.25), ("curve_yamp", 0.5)]),
    ("escher", &[("escher_beta", 0.3)]),
    ("lazysusan", &[("lazysusan_space", 0.4), ("lazysusan_twist", 0.2), ("lazysusan_spin", 0.1), ("lazysusan_x", 0.1), ("lazysusan_y", 0.2)]),
    ("modulus", &[("modulus_x", 0.2), ("modulus_y", 0.5)]),
    ("separation", &[("separation_x", 0.5), ("separation_xinside", 0.05), ("separation_y", 0.25), ("separation_yinside", 0.025)]),
    ("split", &[("split_xsize", 0.4), ("split_ysize", 0.6)]),
    ("splits", &[("splits_x", 0.4), ("splits_y", 0.6)]),
    ("stripes", &[("stripes_space", 0.2), ("stripes_warp", 0.6)]),
    ("wedge_julia", &[("wedge_julia_power", 7.0), ("wedge_julia_dist", 0.2), ("wedge_julia_count", 2.0), ("wedge_julia_angle", 0.3)]),
    ("wedge_sph", &[("wedge_sph_angle", 0.2), ("wedge_sph_hole", 0.2), ("wedge_sph_swirl", 0.3)]),
    ("whorl", &[("whorl_inside", 0.1), ("whorl_outside", 0.2)]),
    ("auger", &[("auger_freq", 1.0), ("auger_sym", 0.1), ("auger_scale", 0.9)]),
    ("flux", &[("flux_spread", 0.3)]),
    ("mobius", &[("mobius_re_a", 0.1), ("mobius_re_b", 0.2), ("mobius_re_c", -0.15), ("mobius_re_d", 0.21), ("mobius_im_a", 0.2), ("mobius_im_b", -0.12), ("mobius_im_c", -0.15), ("mobius_im_d", 0.1)]),
    ("circlize", &[("circlize_hole", 0.4)]),
    ("eclipse", &[("eclipse_shift", 0.1)]),
    ("linearT", &[("linearT_powX", 1.2), ("linearT_powY", 0.9)]),
    ("linearT3D", &[("linearT3D_powX", 1.35), ("linearT3D_powY", 0.85), ("linearT3D_powZ", 1.15)]),
    ("checks", &[("checks_x", 3.0), ("checks_y", 3.0), ("checks_size", 1.0), ("checks_rnd", 0.5)]),
    ("dc_cube", &[("dc_cube_c1", 0.1), ("dc_cube_c2", 0.2), ("dc_cube_c3", 0.3), ("dc_cube_c4", 0.4), ("dc_cube_c5", 0.5), ("dc_cube_c6", 0.6)]),
    ("collideoscope", &[("collideoscope_a", 0.2)]),
    ("hypertile", &[("hypertile_n", 1.0)]),
    ("cubic3D", &[("cubic3D_style", 1.0)]),
    ("hexnix3D", &[("hexnix3D_3side", 0.67)]),
    ("boarders2", &[("boarders2_c", 0.4), ("boarders2_left", 0.65), ("boarders2_right", 0.35)]),
    ("bTransform", &[("bTransform_power", 1.0)]),
    ("eSwirl", &[("eSwirl_in", 1.2), ("eSwirl_out", 0.2)]),
    ("ovoid3d", &[("ovoid3d_x", 0.92), ("ovoid3d_y", 0.92), ("ovoid3d_z", 0.92)]),
    ("circus", &[("circus_scale", 0.92)]),
    ("lazyTravis", &[("lazyTravis_spin_out", 0.5), ("lazyTravis_space", 1.5707963267948966)]),
    ("mcarpet", &[("mcarpet_x", 1.0), ("mcarpet_y", 0.75), ("mcarpet_twist", 0.5), ("mcarpet_tilt", -0.25)]),
    ("fourth", &[("fourth_space", 0.1), ("fourth_twist", 0.2), ("fourth_x", 0.3), ("fourth_y", 0.12)]),
    ("post_smartcrop", &[("post_smartcrop_static", 2.0)]),
    ("starblur", &[("starblur_range", 0.40162283177245456)]),
    ("blur_zoom", &[("blur_zoom_length", 0.24), ("blur_zoom_x", 0.2), ("blur_zoom_y", -0.1)]),
    ("synth", &[("synth_a", 1.0), ("synth_mix", 1.0)]),
    ("murl", &[("murl_c", 0.1)]),
    ("murl2", &[("murl2_c", 0.1), ("murl2_power", 3.0)]),
    ("waves2b", &[("waves2b_freqx", 1.5), ("waves2b_freqy", 2.5), ("waves2b_pwy", 1.5), ("waves2b_scalex", 2.0), ("waves2b_scaley", 0.75), ("waves2b_scaleinfy", 1.5)]),
    ("loonie2", &[("loonie2_star", 0.15), ("loonie2_circle", 0.25)]),
    ("splits3D", &[("splits3D_x", 0.1), ("splits3D_y", 0.3), ("splits3D_z", 0.2)]),
    ("exblur", &[("exblur_r", 0.25)]),
    ("curl_sp", &[("curl_sp_c1", -0.01), ("curl_sp_c2", 0.03)]),
    ("dc_linear", &[("dc_linear_angle", 0.3), ("dc_linear_scale", 0.8)]),
    ("dc_carpet", &[("dc_carpet_origin", 1.0)]),
    ("mobius_strip", &[("mobius_strip_radius", 1.0)]),
    ("hypershift", &[("hypershift_shift", 2.0)]),
    ("shift", &[("shift_angle", 12.25)]),
    ("crob", &[("crob_ratioBlur", 0.05)]),
    ("blur_linear", &[("blur_linear_length", 1.0), ("blur_linear_angle", 0.5)]),
    ("projective", &[("projective_B", -0.4), ("projective_B1", 0.1), ("projective_B2", 1.2)]),
    ("vibration2", &[("vibration2_angle", 1.5708), ("vibration2_dir2", 1.5708), ("vibration2_angle2", 1.5708), ("vibration2_dmfreq", 0.1), ("vibration2_tmfreq", 0.1), ("vibration2_fmfreq", 0.1), ("vibration2_amfreq", 0.1)]),
    ("dc_mandala", &[("dc_mandala_multiply", 1.0)]),
    ("sinusgrid", &[("sinusgrid_ampy", 0.6), ("sinusgrid_freqx", 1.2)]),
    ("ovoid", &[("ovoid_x", 0.94), ("ovoid_y", 0.94)]),
];

/// (variation, derived parameter, parameter it derives from, rule).
type DerivedRule = (&'static str, &'static str, &'static str, fn(f64) -> f64);

/// Parameters JWildfire 9.00 sets as a side effect of setting another one (in the variation's
/// `setParameter`), which flames written before the parameter existed leave out: variation,
/// the parameter so set, the one that sets it, and how.
const DERIVED: &[DerivedRule] = &[
    (
        "dc_warping",
        "dc_warping_x0",
        "dc_warping_randomize",
        variations::dc_warping_x0_of_seed,
    ),
    (
        "dc_fractcolor",
        "dc_fractcolor_xpar",
        "dc_fractcolor_randomize",
        variations::dc_fractcolor_xpar_of_seed,
    ),
    (
        "dc_fractcolor",
        "dc_fractcolor_ypar",
        "dc_fractcolor_randomize",
        variations::dc_fractcolor_ypar_of_seed,
    ),
];

/// A derived parameter the file left out while it set the one it derives from: which of the
/// xform's variations, the two parameters' indices, and the rule.
pub(super) struct Derived {
    var: usize,
    target: usize,
    source: usize,
    rule: fn(f64) -> f64,
}

/// The derived parameters of `x`'s variations to compute once the file's values are attached
/// ([`apply_derived`]); arguments as for [`apply`].
pub(super) fn derived_missing(
    x: &Xform,
    instances: &[u32],
    given: impl Fn(variations::VarId, usize, u32) -> bool,
) -> Vec<Derived> {
    let mut out = Vec::new();
    for (name, target, source, rule) in DERIVED {
        let Some((id, _)) = variations::parse_name(name) else {
            continue;
        };
        let (Some((tid, _, t)), Some((sid, _, s))) =
            (variations::param_of(target), variations::param_of(source))
        else {
            continue;
        };
        if tid != id || sid != id {
            continue;
        }
        for (i, v) in x.vars.iter().enumerate() {
            let k = instances.get(i).copied().unwrap_or(0);
            if v.id == id && !given(id, t, k) && given(id, s, k) {
                out.push(Derived {
                    var: i,
                    target: t,
                    source: s,
                    rule: *rule,
                });
            }
        }
    }
    out
}

/// Set the parameters [`derived_missing`] found from the values the file gave.
pub(super) fn apply_derived(x: &mut Xform, derived: &[Derived]) {
    for d in derived {
        if let Some(v) = x.vars.get_mut(d.var)
            && d.target < v.params.len()
            && d.source < v.params.len()
        {
            v.params[d.target] = (d.rule)(v.params[d.source]);
        }
    }
}

/// The parameters JWildfire 9.00 draws anew whenever it reads or copies a flame, as its
/// command-line renderer's threads hold them (variations whose `setParameter` draws from a
/// generator it reseeds): gumowski_mira's seed and `a`
/// ([`variations::gumowski_mira_rendered`]).
pub(super) fn apply_rendered(x: &mut Xform) {
    let Some((id, _)) = variations::parse_name("gumowski_mira") else {
        return;
    };
    let (Some((_, _, seed)), Some((_, _, a))) = (
        variations::param_of("gumowski_mira_random"),
        variations::param_of("gumowski_mira_a"),
    ) else {
        return;
    };
    for v in x.vars.iter_mut().filter(|v| v.id == id) {
        if seed < v.params.len() && a < v.params.len() {
            (v.params[seed], v.params[a]) = variations::gumowski_mira_rendered(v.params[seed]);
        }
    }
}

/// Give each of `x`'s variations that JWildfire defaults differently its JWildfire default for
/// every parameter the file did not set. `given(id, index, k)`: whether the file set parameter
/// `index` of use `k` of variation `id`; `instances[i]`: which use `x.vars[i]` is.
pub(super) fn apply(
    x: &mut Xform,
    instances: &[u32],
    given: impl Fn(variations::VarId, usize, u32) -> bool,
) {
    for (name, params) in DEFAULTS {
        let Some((id, _)) = variations::parse_name(name) else {
            continue;
        };
        if !x.vars.iter().any(|v| v.id == id) {
            continue;
        }
        for (pname, value) in params.iter() {
            let Some((pid, _, index)) = variations::param_of(pname) else {
                continue;
            };
            if pid != id {
                continue;
            }
            for (i, v) in x.vars.iter_mut().enumerate() {
                let k = instances.get(i).copied().unwrap_or(0);
                if v.id == id && index < v.params.len() && !given(id, index, k) {
                    v.params[index] = *value;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every entry names a variation ugnis has and parameters of that variation; the values
    /// that repeat ugnis' own default are listed (the table is meant to hold differences).
    #[test]
    fn entries_resolve() {
        let mut same = Vec::new();
        for (name, params) in DEFAULTS {
            let (id, form) = variations::parse_name(name).unwrap_or_else(|| panic!("{name}"));
            let fresh = crate::flame::model::Var::with_form(id, form, 1.0);
            for (pname, value) in params.iter() {
                let (pid, _, index) =
                    variations::param_of(pname).unwrap_or_else(|| panic!("{pname}"));
                assert_eq!(pid, id, "{pname} is not a parameter of {name}");
                assert!(index < fresh.params.len(), "{pname}");
                if fresh.params[index] == *value {
                    same.push(*pname);
                }
            }
        }
        eprintln!("entries equal to ugnis' default: {same:?}");
    }

    /// Every derived parameter names parameters of its variation.
    #[test]
    fn derived_entries_resolve() {
        for (name, target, source, _) in DERIVED {
            let (id, _) = variations::parse_name(name).unwrap_or_else(|| panic!("{name}"));
            for p in [target, source] {
                let (pid, _, _) = variations::param_of(p).unwrap_or_else(|| panic!("{p}"));
                assert_eq!(pid, id, "{p}");
            }
        }
    }
}
