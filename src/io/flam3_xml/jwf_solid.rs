//! JWildfire's solid rendering settings on a `<flame>`: `sld_render_enabled`, the ambient
//! occlusion and shadow settings, and the numbered materials (`sld_render_material_*N`, their
//! count in `sld_render_material_count`) and lights (`sld_render_light_*N`, their count in
//! JWildfire's misspelt `sld_render_ligtht_count`). Read as JWildfire 9.00's
//! `AbstractFlameReader` reads them (the rest only when solid rendering is on), written back as
//! its writer writes them.

use std::fmt::Write as _;

use super::context::Ctx;
use crate::flame::jwf_render::solid::MAX_SOLID_ITEMS;
use crate::flame::jwf_render::{JwfLight, JwfLightDiff, JwfMaterial, JwfSolid};
use crate::io::diag::fmt_num;

/// Whether `name` is one of the solid rendering attributes.
pub(super) fn is_solid_attr(name: &str) -> bool {
    name.starts_with("sld_render_")
}

/// The settings of the attributes `attrs` (name, value, offset), read in any order.
pub(super) fn read(cx: &mut Ctx, attrs: &[(String, String, usize)]) -> JwfSolid {
    let mut r = Reader {
        attrs,
        bad: Vec::new(),
    };
    let mut s = JwfSolid {
        enabled: r.flag("sld_render_enabled").unwrap_or(false),
        ..JwfSolid::default()
    };
    if !s.enabled {
        return s;
    }
    if let Some(b) = r.flag("sld_render_ao_enabled") {
        s.ao_enabled = b;
    }
    r.num("sld_render_ao_intensity", &mut s.ao_intensity);
    r.num("sld_render_ao_search_radius", &mut s.ao_search_radius);
    r.num("sld_render_ao_blur_radius", &mut s.ao_blur_radius);
    r.num("sld_render_ao_falloff", &mut s.ao_falloff);
    r.num("sld_render_ao_affect_diffuse", &mut s.ao_affect_diffuse);
    r.num(
        "sld_render_shadow_smooth_radius",
        &mut s.shadow_smooth_radius,
    );
    r.num("sld_render_shadowmap_bias", &mut s.shadowmap_bias);
    r.count(
        "sld_render_ao_radius_samples",
        &mut s.ao_radius_samples,
        1e6,
    );
    r.count(
        "sld_render_ao_azimuth_samples",
        &mut s.ao_azimuth_samples,
        1e6,
    );
    r.count("sld_render_shadowmap_size", &mut s.shadowmap_size, 1e6);
    if let Some(v) = r.text("sld_render_shadow_type") {
        s.shadow_type = v.trim().to_string();
    }
    if r.text("sld_render_material_count").is_some() {
        let mut n_materials = 0;
        r.count(
            "sld_render_material_count",
            &mut n_materials,
            MAX_SOLID_ITEMS as f64,
        );
        s.materials = (0..n_materials)
            .map(|i| {
                let mut m = JwfMaterial::default();
                let p = |k: &str| format!("sld_render_material_{k}{i}");
                r.num(&p("diffuse"), &mut m.diffuse);
                r.num(&p("ambient"), &mut m.ambient);
                r.num(&p("phong"), &mut m.phong);
                r.num(&p("phong_size"), &mut m.phong_size);
                r.num(&p("phong_red"), &mut m.phong_color[0]);
                r.num(&p("phong_green"), &mut m.phong_color[1]);
                r.num(&p("phong_blue"), &mut m.phong_color[2]);
                r.num(&p("refl_map_intensity"), &mut m.refl_map_intensity);
                if let Some(f) = r
                    .text(&p("light_diif_func"))
                    .and_then(|v| JwfLightDiff::from_name(v.trim()))
                {
                    m.light_diff = f;
                }
                if let Some(v) = r.text(&p("refl_map_filename")) {
                    m.refl_map_filename = v.to_string();
                }
                if let Some(v) = r.text(&p("refl_mappping")) {
                    m.refl_mapping = v.trim().to_string();
                }
                m
            })
            .collect();
    }
    if r.text("sld_render_ligtht_count").is_some() {
        let mut n_lights = 0;
        r.count(
            "sld_render_ligtht_count",
            &mut n_lights,
            MAX_SOLID_ITEMS as f64,
        );
        s.lights = (0..n_lights)
            .map(|i| {
                let mut l = JwfLight::default();
                let p = |k: &str| format!("sld_render_light_{k}{i}");
                r.num(&p("altitude"), &mut l.altitude);
                r.num(&p("azimuth"), &mut l.azimuth);
                r.num(&p("intensity"), &mut l.intensity);
                r.num(&p("shadow_intensity"), &mut l.shadow_intensity);
                r.num(&p("red"), &mut l.color[0]);
                r.num(&p("green"), &mut l.color[1]);
                r.num(&p("blue"), &mut l.color[2]);
                if let Some(b) = r.flag(&p("shadows")) {
                    l.cast_shadows = b;
                }
                l
            })
            .collect();
    }
    for (off, n) in r.bad {
        cx.warn(
            off,
            "XML014",
            format!("{n} is not a number; JWildfire's default is used"),
        );
    }
    if s.materials
        .iter()
        .any(|m| m.refl_map_intensity > 1e-6 && !m.refl_map_filename.is_empty())
    {
        cx.warn(
            0,
            "XML014",
            "solid rendering: reflection maps are not drawn".to_string(),
        );
    }
    if s.shadow_type != "OFF" {
        cx.warn(
            0,
            "XML014",
            format!("solid rendering: shadows ({}) are not drawn", s.shadow_type),
        );
    }
    s
}

/// The attributes being read, and the names of those that were not numbers.
struct Reader<'a> {
    attrs: &'a [(String, String, usize)],
    bad: Vec<(usize, String)>,
}

impl<'a> Reader<'a> {
    fn get(&self, n: &str) -> Option<&'a (String, String, usize)> {
        self.attrs.iter().find(|(k, _, _)| k == n)
    }

    fn text(&self, n: &str) -> Option<&'a str> {
        self.get(n).map(|(_, v, _)| v.as_str())
    }

    /// JWildfire's flags: "1" is on, anything else off.
    fn flag(&self, n: &str) -> Option<bool> {
        self.text(n).map(|v| v.trim() == "1")
    }

    fn num(&mut self, n: &str, dst: &mut f64) {
        if let Some((_, v, off)) = self.get(n) {
            match v.trim().parse::<f64>() {
                Ok(x) if x.is_finite() => *dst = x,
                _ => self.bad.push((*off, n.to_string())),
            }
        }
    }

    /// A whole number, clamped to 0..=max.
    fn count(&mut self, n: &str, dst: &mut u32, max: f64) {
        let mut v = *dst as f64;
        self.num(n, &mut v);
        *dst = v.clamp(0.0, max) as u32;
    }
}

/// The settings as attributes (JWildfire's writer's names).
pub(super) fn write(s: &mut String, l: &JwfSolid) {
    let n = fmt_num;
    let b = |v: bool| if v { "1" } else { "0" };
    let _ = write!(s, " sld_render_enabled=\"{}\"", b(l.enabled));
    if !l.enabled {
        return;
    }
    let _ = write!(
        s,
        " sld_render_ao_enabled=\"{}\" sld_render_ao_intensity=\"{}\" \
         sld_render_ao_search_radius=\"{}\" sld_render_ao_blur_radius=\"{}\" \
         sld_render_ao_radius_samples=\"{}\" sld_render_ao_azimuth_samples=\"{}\" \
         sld_render_ao_falloff=\"{}\" sld_render_ao_affect_diffuse=\"{}\" \
         sld_render_shadow_type=\"{}\" sld_render_shadow_smooth_radius=\"{}\" \
         sld_render_shadowmap_size=\"{}\" sld_render_shadowmap_bias=\"{}\" \
         sld_render_material_count=\"{}\"",
        b(l.ao_enabled),
        n(l.ao_intensity),
        n(l.ao_search_radius),
        n(l.ao_blur_radius),
        l.ao_radius_samples,
        l.ao_azimuth_samples,
        n(l.ao_falloff),
        n(l.ao_affect_diffuse),
        crate::io::xml::escape_attr(&l.shadow_type),
        n(l.shadow_smooth_radius),
        l.shadowmap_size,
        n(l.shadowmap_bias),
        l.materials.len(),
    );
    for (i, m) in l.materials.iter().enumerate() {
        let _ = write!(
            s,
            " sld_render_material_diffuse{i}=\"{}\" sld_render_material_ambient{i}=\"{}\" \
             sld_render_material_phong{i}=\"{}\" sld_render_material_phong_size{i}=\"{}\" \
             sld_render_material_phong_red{i}=\"{}\" sld_render_material_phong_green{i}=\"{}\" \
             sld_render_material_phong_blue{i}=\"{}\" \
             sld_render_material_refl_map_intensity{i}=\"{}\" \
             sld_render_material_refl_map_filename{i}=\"{}\" \
             sld_render_material_refl_mappping{i}=\"{}\" \
             sld_render_material_light_diif_func{i}=\"{}\"",
            n(m.diffuse),
            n(m.ambient),
            n(m.phong),
            n(m.phong_size),
            n(m.phong_color[0]),
            n(m.phong_color[1]),
            n(m.phong_color[2]),
            n(m.refl_map_intensity),
            crate::io::xml::escape_attr(&m.refl_map_filename),
            crate::io::xml::escape_attr(&m.refl_mapping),
            m.light_diff.name(),
        );
    }
    let _ = write!(s, " sld_render_ligtht_count=\"{}\"", l.lights.len());
    for (i, x) in l.lights.iter().enumerate() {
        let _ = write!(
            s,
            " sld_render_light_altitude{i}=\"{}\" sld_render_light_azimuth{i}=\"{}\" \
             sld_render_light_intensity{i}=\"{}\" sld_render_light_red{i}=\"{}\" \
             sld_render_light_green{i}=\"{}\" sld_render_light_blue{i}=\"{}\" \
             sld_render_light_shadows{i}=\"{}\" sld_render_light_shadow_intensity{i}=\"{}\"",
            n(x.altitude),
            n(x.azimuth),
            n(x.intensity),
            n(x.color[0]),
            n(x.color[1]),
            n(x.color[2]),
            b(x.cast_shadows),
            n(x.shadow_intensity),
        );
    }
}
