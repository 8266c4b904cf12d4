//! Writing flames as flam3 XML: the whole `.fla`/`.flame` document, or one `<flame>` element
//! (as embedded in PNG files). Every attribute and child kept from reading is written back.

use std::collections::HashSet;
use std::fmt::Write as _;

use super::anim::{write_anim_attrs, write_keys, write_motion};
use super::jwf_curves;
use super::{FLA_FORMAT, FlameFile};
use crate::flame::model::{Flame, PaletteIndex, Xform};
use crate::flame::variations::{self, Form, VarId};
use crate::io::diag::fmt_num;
use crate::io::xml::escape_attr;

/// Write a whole `.fla`/`.flame` document.
pub fn write(file: &FlameFile) -> String {
    let mut s = String::new();
    s.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        s,
        "<flames name=\"{}\" ugnis_format=\"{FLA_FORMAT}\">",
        escape_attr(&file.name)
    );
    let mut used: Vec<String> = Vec::new();
    for (i, f) in file.flames.iter().enumerate() {
        // Every flame needs a unique non-empty name.
        let mut name = if f.name.trim().is_empty() {
            format!("flame-{:03}", i + 1)
        } else {
            f.name.clone()
        };
        if used.contains(&name) {
            let base = name.clone();
            let mut k = 2;
            while used.contains(&name) {
                name = format!("{base}-{k}");
                k += 1;
            }
        }
        used.push(name.clone());
        write_flame(&mut s, f, &name, "   ");
    }
    s.push_str("</flames>\n");
    s
}

/// One `<flame>…</flame>` element (no declaration, no root), as embedded in PNG files.
pub fn flame_element(f: &Flame) -> String {
    let mut s = String::new();
    let name = if f.name.is_empty() {
        "ugnis".to_string()
    } else {
        f.name.clone()
    };
    write_flame(&mut s, f, &name, "");
    s
}

fn write_flame(s: &mut String, f: &Flame, name: &str, ind: &str) {
    let n = fmt_num;
    // A flame of layers is written as JWildfire writes it.
    let tag = if f.has_layers() { "jwf-flame" } else { "flame" };
    let _ = write!(
        s,
        "{ind}<{tag} name=\"{}\" version=\"ugnis-{}\" size=\"{} {}\" center=\"{} {}\" scale=\"{}\" rotate=\"{}\" zoom=\"{}\" \
         supersample=\"{}\" filter=\"{}\" filter_shape=\"{}\" quality=\"{}\" background=\"{} {} {}\" brightness=\"{}\" \
         gamma=\"{}\" gamma_threshold=\"{}\" vibrancy=\"{}\" highlight_power=\"{}\" estimator_radius=\"{}\" \
         estimator_minimum=\"{}\" estimator_curve=\"{}\" palette_mode=\"{}\"{} ugnis_contrast=\"{}\"",
        escape_attr(name),
        crate::VERSION,
        f.width,
        f.height,
        n(f.center[0]),
        n(f.center[1]),
        n(f.scale),
        n(f.rotate),
        n(f.zoom),
        f.supersample,
        n(f.filter),
        f.filter_shape.name(),
        n(f.quality),
        n(f.background[0]),
        n(f.background[1]),
        n(f.background[2]),
        n(f.brightness),
        n(f.gamma),
        n(f.gamma_threshold),
        n(f.vibrancy),
        n(f.highlight_power),
        n(f.estimator_radius),
        n(f.estimator_minimum),
        n(f.estimator_curve),
        f.palette_mode.name(),
        // flam3's "linear is 2-D" switch; JWildfire reads it as its "preserve Z" instead.
        if f.palette_index == PaletteIndex::JWildfire {
            ""
        } else {
            " new_linear=\"1\""
        },
        n(f.contrast),
    );
    if f.preserve_z {
        s.push_str(" preserve_z=\"1\"");
    }
    if let Some(seed) = f.seed {
        let _ = write!(s, " ugnis_seed=\"{seed}\"");
    }
    let _ = write!(s, " ugnis_kind=\"{}\"", f.kind.name());
    if f.palette_index != PaletteIndex::Flam3 {
        let _ = write!(s, " ugnis_palette_index=\"{}\"", f.palette_index.name());
    }
    if let Some(aw) = f.auto_weights {
        let _ = write!(s, " ugnis_auto_weights=\"{}\"", aw as u8);
    }
    if !f.palette.name.is_empty() {
        let _ = write!(s, " ugnis_gradient=\"{}\"", escape_attr(&f.palette.name));
    }
    if let Some(solo) = f.solo_xform {
        let _ = write!(s, " soloxform=\"{solo}\"");
    }
    if !f.curves.is_identity() {
        for (ci, name) in ["overall_curve", "red_curve", "green_curve", "blue_curve"]
            .iter()
            .enumerate()
        {
            let v: Vec<String> = f.curves.points[ci]
                .iter()
                .flat_map(|p| [n(p[0]), n(p[1])])
                .collect();
            let _ = write!(s, " {name}=\"{}\"", v.join(" "));
        }
    }
    if f.cam_zoom != 1.0 {
        let _ = write!(s, " cam_zoom=\"{}\"", n(f.cam_zoom));
    }
    let c = &f.cam;
    if !c.is_flat() || c.blur_curve != 0.0 {
        let _ = write!(
            s,
            " cam_pitch=\"{}\" cam_yaw=\"{}\" cam_perspective=\"{}\" cam_zpos=\"{}\" cam_dof=\"{}\"",
            n(c.pitch),
            n(c.yaw),
            n(c.perspective),
            n(c.zpos),
            n(c.dof)
        );
        if c.blur_curve != 0.0 {
            let _ = write!(s, " blur_curve=\"{}\"", n(c.blur_curve));
        }
    }
    write_anim_attrs(s, &f.anim);
    super::jwf_look::write(s, f);
    let jwf = jwf_curves::for_writing(f);
    for (k, v) in jwf.as_ref().map_or(&f.extra_attrs, |w| &w.flame) {
        let _ = write!(s, " {k}=\"{}\"", escape_attr(v));
    }
    s.push_str(">\n");
    let inner = format!("{ind}   ");
    let own = |s: &mut String, inner: &str| {
        for (i, x) in f.xforms.iter().enumerate() {
            let extra = jwf.as_ref().and_then(|w| w.xforms.get(i));
            let extra = extra.unwrap_or(&x.extra_attrs);
            write_xform(s, x, extra, "xform", inner, f.dialect());
        }
        for (k, fx) in f.finals().enumerate() {
            let extra = jwf
                .as_ref()
                .and_then(|w| w.final_xform.as_ref())
                .filter(|_| k == 0);
            let extra = extra.unwrap_or(&fx.extra_attrs);
            write_xform(s, fx, extra, "finalxform", inner, f.dialect());
        }
        write_palette(s, f.render_colors(), inner);
    };
    if f.has_layers() {
        let other = |s: &mut String, l: &crate::flame::layers::Layer, inner: &str| {
            for x in &l.xforms {
                write_xform(s, x, &x.extra_attrs, "xform", inner, f.dialect());
            }
            for x in &l.finals {
                write_xform(s, x, &x.extra_attrs, "finalxform", inner, f.dialect());
            }
            write_palette(s, &l.palette.colors, inner);
        };
        super::layers::write_layers(s, f, &inner, own, other);
    } else {
        own(s, &inner);
    }
    let written = jwf.as_ref().map_or(&[][..], |w| &w.curves[..]);
    write_keys(s, &f.keys, written, &inner);
    for c in &f.extra_children {
        let _ = writeln!(s, "{inner}{}", c.trim());
    }
    let _ = writeln!(s, "{ind}</{tag}>");
}

/// An xform element; `extra` are the kept attributes to write (the xform's own, or with its
/// JWildfire curves brought up to date). Parameters are named and counted as in flames of
/// `dialect` (the program that wrote the flame).
fn write_xform(
    s: &mut String,
    x: &Xform,
    extra: &[(String, String)],
    tag: &str,
    ind: &str,
    dialect: variations::Dialect,
) {
    let n = fmt_num;
    let _ = write!(s, "{ind}<{tag}");
    if tag == "xform" {
        let _ = write!(s, " weight=\"{}\"", n(x.weight));
    }
    let _ = write!(s, " color=\"{}\"", n(x.color));
    if x.color_speed != 0.5 {
        let _ = write!(s, " symmetry=\"{}\"", n(1.0 - 2.0 * x.color_speed));
    }
    let _ = write!(s, " color_speed=\"{}\"", n(x.color_speed));
    // After `symmetry`, which flam3 also reads as `animate`.
    if x.animate != 1.0 || (x.color_speed != 0.5 && tag == "xform") {
        let _ = write!(s, " animate=\"{}\"", n(x.animate));
    }
    if x.opacity != 1.0 {
        let _ = write!(s, " opacity=\"{}\"", n(x.opacity));
    }
    if x.direct_color != 1.0 {
        let _ = write!(s, " direct_color=\"{}\"", n(x.direct_color));
    }
    // Names written so far: a kept attribute of the same name (the parameter of a variation
    // of weight 0 that was dropped on reading) is not written again.
    let mut written: HashSet<String> = HashSet::new();
    let names = var_names(x);
    for (v, name) in x.vars.iter().zip(&names) {
        let _ = write!(s, " {}=\"{}\"", name.weight, n(v.weight));
        if let Some(p) = name.priority {
            let pn = format!("{}_fx_priority", name.weight);
            let _ = write!(s, " {pn}=\"{p}\"");
            written.insert(pn);
        }
    }
    for (v, name) in x.vars.iter().zip(names) {
        let def = variations::def_in(dialect, v.id, v.form);
        for (i, p) in def.params.iter().enumerate() {
            let pn = name.of(variations::param_attr_name_in(dialect, v.id, name.form, i));
            let value = v.params.get(i).copied().unwrap_or(p.default);
            let _ = write!(s, " {pn}=\"{}\"", n(value));
            written.insert(pn);
        }
        for (i, t) in v.texts.iter().enumerate() {
            let tn = name.of(variations::text_attr_name(v.id, name.form, i));
            // An image JWildfire gave inline is named so while loaded; the file name stays
            // empty, the image itself is written back with the xform's other attributes.
            let t = if t.starts_with(crate::io::var_images::INLINED_IMAGE) {
                ""
            } else {
                t
            };
            let _ = write!(s, " {tn}=\"{}\"", text_to_hex(t));
            written.insert(tn);
        }
        written.insert(name.weight);
    }
    let c = x.coefs.to_coefs();
    let _ = write!(
        s,
        " coefs=\"{} {} {} {} {} {}\"",
        n(c[0]),
        n(c[1]),
        n(c[2]),
        n(c[3]),
        n(c[4]),
        n(c[5])
    );
    if !x.post.is_identity() {
        let p = x.post.to_coefs();
        let _ = write!(
            s,
            " post=\"{} {} {} {} {} {}\"",
            n(p[0]),
            n(p[1]),
            n(p[2]),
            n(p[3]),
            n(p[4]),
            n(p[5])
        );
    }
    let mut chaos = x.chaos.clone();
    while chaos.last() == Some(&1.0) {
        chaos.pop();
    }
    if !chaos.is_empty() {
        let v: Vec<String> = chaos.iter().map(|c| n(*c)).collect();
        let _ = write!(s, " chaos=\"{}\"", v.join(" "));
    }
    for (k, v) in extra.iter().filter(|(k, _)| !written.contains(k)) {
        let _ = write!(s, " {k}=\"{}\"", escape_attr(v));
    }
    if x.extra_children.is_empty() && x.motion.is_empty() {
        s.push_str("/>\n");
    } else {
        s.push_str(">\n");
        let inner = format!("{ind}   ");
        for m in &x.motion {
            write_motion(s, m, &inner);
        }
        for c in &x.extra_children {
            let _ = writeln!(s, "{inner}{}", c.trim());
        }
        let _ = writeln!(s, "{ind}</{tag}>");
    }
}

/// The attribute names of one variation of an xform: its weight's name, and the JWildfire
/// index `#k#` that its parameters' names carry after the variation's name.
struct VarName {
    weight: String,
    /// `(variation name, index)` for a further use of the variation (JWildfire's `NAME#k#`).
    index: Option<(String, String)>,
    /// The form the names are written in.
    form: Form,
    /// JWildfire's `NAME_fx_priority` (−1: `pre_`, 1: `post_`) when the prefixed name would
    /// be read as another variation.
    priority: Option<&'static str>,
}

impl VarName {
    /// A parameter's attribute name for this use of the variation.
    fn of(&self, param: String) -> String {
        match &self.index {
            Some((var, idx)) if param.starts_with(var.as_str()) => {
                format!("{var}{idx}{}", &param[var.len()..])
            }
            _ => param,
        }
    }
}

/// The names of an xform's variations: a variation used more than once is written as
/// JWildfire writes it, `NAME`, `NAME#1#`, `NAME#2#`, … (with `NAME#1#_param` for its
/// parameters), which JWildfire reads back as further uses of NAME.
fn var_names(x: &Xform) -> Vec<VarName> {
    let mut seen: Vec<String> = Vec::new();
    x.vars
        .iter()
        .map(|v| {
            let (name, form, priority) = names_of(v.id, v.form, v.moved);
            let k = seen.iter().filter(|s| **s == name).count();
            seen.push(name.clone());
            if k == 0 {
                VarName {
                    weight: name,
                    index: None,
                    form,
                    priority,
                }
            } else {
                let idx = format!("#{k}#");
                VarName {
                    weight: format!("{name}{idx}"),
                    index: Some((name, idx)),
                    form,
                    priority,
                }
            }
        })
        .collect()
}

/// The name variation `id` used in `form` is written under, the form of its parameters' names
/// and its JWildfire priority mark. The prefixed name unless it means another variation
/// (flam3's `pre_blur` is `gaussian_blur`'s `pre_` form, not `blur`'s): then the plain name,
/// marked as JWildfire marks a variation run before or after the others; so too a variation
/// JWildfire's priority `moved` there.
fn names_of(id: VarId, form: Form, moved: bool) -> (String, Form, Option<&'static str>) {
    let own = variations::attr_name(id, form);
    let plain = variations::attr_name(id, Form::Regular);
    let mark = match form {
        Form::Pre => "-1",
        Form::Post => "1",
        Form::Regular => "0",
    };
    if !(moved && form != Form::Regular) && variations::parse_name(&own) == Some((id, form))
        || variations::parse_name(&plain) != Some((id, Form::Regular))
    {
        (own, form, None)
    } else {
        (plain, Form::Regular, Some(mark))
    }
}

fn to8(v: f64) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

fn write_palette(s: &mut String, colors: &[[f64; 4]], ind: &str) {
    let rgba = colors.iter().any(|c| c[3] < 1.0);
    let fmt = if rgba { "RGBA" } else { "RGB" };
    let _ = writeln!(
        s,
        "{ind}<palette count=\"{}\" format=\"{fmt}\">",
        colors.len()
    );
    for line in colors.chunks(8) {
        s.push_str(ind);
        s.push_str("   ");
        for c in line {
            let _ = write!(s, "{:02X}{:02X}{:02X}", to8(c[0]), to8(c[1]), to8(c[2]));
            if rgba {
                let _ = write!(s, "{:02X}", to8(c[3]));
            }
        }
        s.push('\n');
    }
    let _ = writeln!(s, "{ind}</palette>");
}

/// The hex digits of a text parameter's bytes, as JWildfire writes them.
fn text_to_hex(t: &str) -> String {
    t.bytes().map(|b| format!("{b:02X}")).collect()
}
