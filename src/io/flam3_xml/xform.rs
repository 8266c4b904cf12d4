//! Reading an `<xform>`'s attributes: weight, colour, affine maps, xaos, variations with their
//! numeric and text parameters (in flam3, Apophysis and JWildfire's spellings); variations
//! ugnis cannot render and other attributes are kept as they stand.

use std::collections::HashSet;

use super::context::{Ctx, R};
use crate::flame::model::{Affine, Var, Xform};
use crate::flame::variations::{self, Form, VarId};
use crate::io::diag::{Diagnostic, parse_number};
use crate::io::xml::Attr;

/// A variation parameter read before its variation is known: it goes to its variation, or is
/// kept as the attribute `name="raw"` if the xform has no such variation.
struct Param<T> {
    id: VarId,
    form: Form,
    index: usize,
    value: T,
    name: String,
    raw: String,
}

/// What an xform's attributes say that is settled only once all of them are read.
struct Pending {
    color_speed: Option<f64>,
    /// flam3's older `symmetry` (colour speed (1 − s) / 2).
    symmetry: Option<f64>,
    params: Vec<Param<f64>>,
    texts: Vec<Param<String>>,
    animate: Option<f64>,
    /// Reading a `<motion>` element: values are changes, so any sign is allowed.
    motion: bool,
}

/// Set the weight of a variation form (replacing an earlier attribute for the same form; weight
/// 0 removes it).
fn set_var(x: &mut Xform, id: VarId, form: Form, w: f64) {
    x.vars.retain(|v| !(v.id == id && v.form == form));
    if w != 0.0 {
        x.vars.push(Var::with_form(id, form, w));
    }
}

/// Read the attributes of an `<xform>` (`fin`: a `<finalxform>`); `parity` is its default colour.
pub(super) fn read_xform(cx: &mut Ctx, attrs: &[Attr], fin: bool, parity: f64) -> R<Xform> {
    read_xform_as(cx, attrs, fin, parity, false)
}

/// Read the attributes of a `<motion>` element as an xform of changes (see
/// `anim::motion_from`, which makes the values it does not name zero).
pub(super) fn read_motion_attrs(cx: &mut Ctx, attrs: &[Attr]) -> R<Xform> {
    read_xform_as(cx, attrs, false, 0.0, true)
}

fn read_xform_as(cx: &mut Ctx, attrs: &[Attr], fin: bool, parity: f64, motion: bool) -> R<Xform> {
    let mut x = Xform {
        weight: 0.0,
        color: parity,
        vars: Vec::new(),
        ..Xform::default()
    };
    let mut st = Pending {
        color_speed: None,
        symmetry: None,
        params: Vec::new(),
        texts: Vec::new(),
        animate: None,
        motion,
    };
    let marked_vars = marked_variations(attrs);
    for a in attrs {
        if !core_attr(cx, &mut x, &mut st, a, fin)? {
            variation_attr(cx, &mut x, &mut st, a, &marked_vars)?;
        }
    }
    x.color_speed = match (st.color_speed, st.symmetry) {
        (Some(s), _) => s,
        (None, Some(sig)) => (1.0 - sig) / 2.0,
        (None, None) => 0.5,
    };
    // flam3's older `symmetry` also keeps symmetry xforms still in loops.
    x.animate = match (st.animate, st.symmetry) {
        (Some(a), _) => a,
        (None, Some(sig)) if sig > 0.0 => 0.0,
        _ => 1.0,
    };
    apply_priorities(attrs, &mut x, &mut st);
    attach_params(&mut x, st);
    Ok(x)
}

/// The names that are taken as variations (to tell a foreign variation from another
/// attribute). JWildfire writes NAME_fx_priority beside every variation it writes; in other
/// programs' files a variation is followed by its NAME_parameters. Both sets are built once, so
/// an xform with very many attributes is still read in linear time.
fn marked_variations<'a>(attrs: &[Attr<'a>]) -> HashSet<&'a str> {
    let fx_marked: HashSet<&str> = attrs
        .iter()
        .filter_map(|b| b.name.strip_suffix("_fx_priority"))
        .collect();
    if !fx_marked.is_empty() {
        return fx_marked;
    }
    attrs
        .iter()
        .flat_map(|b| {
            let n = b.name;
            n.match_indices('_')
                .filter(move |(i, _)| *i > 0 && *i + 1 < n.len())
                .map(move |(i, _)| &n[..i])
        })
        .collect()
}

/// Weight, colour, opacity, the affine maps, xaos and flam3's variation lists. False if `a` is
/// none of them.
fn core_attr(cx: &mut Ctx, x: &mut Xform, st: &mut Pending, a: &Attr, fin: bool) -> R<bool> {
    let v = a.value.trim();
    match a.name {
        "weight" => {
            let w = cx.num(a).map_err(|d| Diagnostic {
                code: "XML005",
                ..d
            })?;
            if w < 0.0 && !st.motion {
                return Err(cx.err(
                    a.offset,
                    "XML005",
                    format!("weight {w} must not be negative"),
                ));
            }
            if fin && w != 0.0 {
                return Err(cx.err(a.offset, "XML005", "a <finalxform> has no weight"));
            }
            x.weight = w;
        }
        "color" => {
            let c = cx.nums(a, "XML003")?;
            if c.is_empty() || c.len() > 2 {
                return Err(cx.err(
                    a.offset,
                    "XML003",
                    "color must be one number (or two, legacy)",
                ));
            }
            x.color = c[0];
        }
        "color_speed" => st.color_speed = Some(cx.num(a)?),
        "symmetry" => st.symmetry = Some(cx.num(a)?),
        "animate" => st.animate = Some(cx.num(a)?),
        "opacity" => {
            let o = cx.num(a)?;
            if !(0.0..=1.0).contains(&o) && !st.motion {
                return Err(cx.err(a.offset, "XML003", format!("opacity {o} must be in 0..1")));
            }
            x.opacity = o;
        }
        "plotmode" => {
            if v == "off" {
                x.opacity = 0.0;
            }
        }
        "coefs" | "post" => {
            let c: [f64; 6] = cx.fixed(a, "XML004", "numbers").map_err(|d| Diagnostic {
                code: "XML004",
                ..d
            })?;
            let m = Affine::from_coefs(c);
            if a.name == "coefs" {
                x.coefs = m;
            } else {
                x.post = m;
            }
        }
        "chaos" => {
            let c = cx.nums(a, "XML008")?;
            if let Some(bad) = c.iter().find(|v| **v < 0.0) {
                return Err(cx.err(
                    a.offset,
                    "XML008",
                    format!("xaos value {bad} must not be negative"),
                ));
            }
            x.chaos = c;
        }
        "direct_color" => x.direct_color = cx.num(a)?,
        "var" | "var1" => flam3_var_list(cx, x, a)?,
        _ => return Ok(false),
    }
    Ok(true)
}

/// flam3's `var="w0 w1 …"` (weights by flam3 index) and `var1="i"` (one variation of weight 1).
fn flam3_var_list(cx: &mut Ctx, x: &mut Xform, a: &Attr) -> R<()> {
    if a.name == "var" {
        let ws = cx.nums(a, "XML003")?;
        if ws.len() > variations::FLAM3_COUNT {
            return Err(cx.err(
                a.offset,
                "XML003",
                format!("var holds {} weights; at most 99", ws.len()),
            ));
        }
        for (i, w) in ws.iter().enumerate() {
            if *w != 0.0
                && let Some((id, form)) = variations::from_flam3_index(i)
            {
                set_var(x, id, form, *w);
            }
        }
        return Ok(());
    }
    let i = cx.int(a)?;
    let Some((id, form)) = usize::try_from(i)
        .ok()
        .and_then(variations::from_flam3_index)
    else {
        return Err(cx.err(
            a.offset,
            "XML003",
            format!("var1 index {i} is outside 0..98"),
        ));
    };
    x.vars.clear();
    set_var(x, id, form, 1.0);
    Ok(())
}

/// A variation's weight, one of its parameters, or another attribute (kept as it stands; a
/// variation ugnis cannot render is reported once per file).
fn variation_attr(
    cx: &mut Ctx,
    x: &mut Xform,
    st: &mut Pending,
    a: &Attr,
    marked_vars: &HashSet<&str>,
) -> R<()> {
    let name = a.name;
    let v = a.value.trim();
    if let Some((id, form)) = variations::parse_name(name) {
        let w = cx.num(a)?;
        set_var(x, id, form, w);
    } else if let Some((id, form, index)) = variations::param_of(name) {
        let value = cx.num(a)?;
        st.params.push(Param {
            id,
            form,
            index,
            value,
            name: name.to_string(),
            raw: a.value.to_string(),
        });
    } else if let Some((id, form, index)) = variations::text_of(name) {
        st.texts.push(Param {
            id,
            form,
            index,
            value: text_from_hex(v),
            name: name.to_string(),
            raw: v.to_string(),
        });
    } else {
        let numeric = parse_number(v).is_ok();
        let marked = marked_vars.contains(name);
        if numeric && (marked || variations::is_foreign_variation_name(name)) {
            if cx.reported_vars.insert(name.to_string()) {
                cx.warn(
                    a.offset,
                    "XML020",
                    format!("variation '{name}' (weight {v}) not supported; ignored"),
                );
            }
        } else if !matches!(
            name,
            "var_color" | "name" | "motion_frequency" | "motion_function"
        ) {
            cx.ignore(name);
        }
        x.extra_attrs.push((name.to_string(), a.value.to_string()));
    }
    Ok(())
}

/// JWildfire marks a variation used before (< 0) or after (> 0) the others with
/// NAME_fx_priority: the variation and its parameters change form.
fn apply_priorities(attrs: &[Attr], x: &mut Xform, st: &mut Pending) {
    for a in attrs {
        if let Some(name) = a.name.strip_suffix("_fx_priority")
            && let Ok(p) = parse_number(a.value.trim())
            && p != 0.0
            && let Some((id, Form::Regular)) = variations::parse_name(name)
        {
            let form = if p < 0.0 { Form::Pre } else { Form::Post };
            for var in x
                .vars
                .iter_mut()
                .filter(|v| v.id == id && v.form == Form::Regular)
            {
                var.form = form;
            }
            for p in st
                .params
                .iter_mut()
                .filter(|p| p.id == id && p.form == Form::Regular)
            {
                p.form = form;
            }
            for t in st
                .texts
                .iter_mut()
                .filter(|t| t.id == id && t.form == Form::Regular)
            {
                t.form = form;
            }
        }
    }
}

/// Parameters go to their variation; parameters of absent variations are kept as-is.
fn attach_params(x: &mut Xform, st: Pending) {
    for p in st.params {
        if let Some(var) = x.vars.iter_mut().find(|v| v.id == p.id && v.form == p.form) {
            var.params[p.index] = p.value;
        } else {
            x.extra_attrs.push((p.name, p.raw));
        }
    }
    for t in st.texts {
        if let Some(var) = x.vars.iter_mut().find(|v| v.id == t.id && v.form == t.form) {
            var.texts[t.index] = variations::info(t.id).texts[t.index].normalise(&t.value);
        } else {
            x.extra_attrs.push((t.name, t.raw));
        }
    }
}

/// A text parameter's value: JWildfire writes the hex digits of its bytes ("53594D" for
/// "SYM"); a value that is not an even number of hex digits is taken as it stands.
fn text_from_hex(v: &str) -> String {
    let v = v.trim();
    let hex = v.len().is_multiple_of(2) && v.bytes().all(|b| b.is_ascii_hexdigit());
    if !hex {
        return v.to_string();
    }
    let bytes: Vec<u8> = (0..v.len())
        .step_by(2)
        .filter_map(|i| u8::from_str_radix(&v[i..i + 2], 16).ok())
        .collect();
    String::from_utf8_lossy(&bytes).into_owned()
}
