//! Reading an `<xform>`'s attributes: weight, colour, affine maps, xaos, variations with their
//! numeric and text parameters (in flam3, Apophysis and JWildfire's spellings); variations
//! ugnis cannot render and other attributes are kept as they stand.

use std::collections::HashSet;

use super::context::{Ctx, R};
use crate::flame::model::{Affine, Var, Xform};
use crate::flame::variations::{self, Form, VarId};
use crate::io::diag::{Diagnostic, parse_number};
use crate::io::xml::{Attr, split_jwf_index};

/// A variation parameter read before its variation is known: it goes to its variation, or is
/// kept as the attribute `name="raw"` if the xform has no such variation.
struct Param<T> {
    id: VarId,
    form: Form,
    /// Which use of the variation in the xform (JWildfire's `NAME#k#`; 0: the first).
    instance: u32,
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
    /// Which use of its variation each of the xform's variations is (in `x.vars` order).
    instances: Vec<u32>,
}

/// Set the weight of use `instance` of a variation form (replacing an earlier attribute for
/// the same use; weight 0 removes it). JWildfire writes a variation used twice in an xform as
/// `NAME` and `NAME#1#`: both stay, and their outputs are summed as in JWildfire.
fn set_var(x: &mut Xform, st: &mut Pending, id: VarId, form: Form, instance: u32, w: f64) {
    if let Some(i) = (0..x.vars.len())
        .find(|&i| x.vars[i].id == id && x.vars[i].form == form && st.instances[i] == instance)
    {
        x.vars.remove(i);
        st.instances.remove(i);
    }
    if w != 0.0 {
        x.vars.push(Var::with_form(id, form, w));
        st.instances.push(instance);
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
        instances: Vec::new(),
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
    if cx.apophysis_names && !motion {
        unprefixed_params(cx, &mut x, &mut st);
    }
    apply_priorities(attrs, &mut x, &mut st, cx.jwildfire_flame);
    let mut derived = Vec::new();
    if cx.jwildfire_flame && !motion {
        let given = |id: VarId, index: usize, k: u32| {
            st.params
                .iter()
                .any(|p| p.id == id && p.index == index && p.instance == k)
        };
        super::jwf_defaults::apply(&mut x, &st.instances, given);
        derived = super::jwf_defaults::derived_missing(&x, &st.instances, given);
    }
    let has_texts = !st.texts.is_empty();
    attach_params(&mut x, st);
    super::jwf_defaults::apply_derived(&mut x, &derived);
    if cx.jwildfire_flame && !motion {
        super::jwf_defaults::apply_rendered(&mut x);
    }
    if has_texts {
        let at = attrs.first().map_or(0, |a| a.offset);
        for v in &x.vars {
            if let Some(msg) = variations::text_problem(v.id, &v.params, &v.texts) {
                cx.warn(at, "XML030", msg);
            }
        }
    }
    Ok(x)
}

/// Apophysis plugins may name their parameters without the variation's prefix (pixel_flow's
/// `angle`, `len`, `width`, `seed` for `pixel_flow_angle` …), and Apophysis writes them so;
/// Fractorium reads such an attribute as the parameter `VAR_name` of a variation VAR of the
/// xform (`XmlToEmber`, for files it did not write). Some plugins spell a parameter otherwise
/// (octagon's `octa_x` for `octagon_x`), which Fractorium's table of such names corrects
/// ([`variations::apophysis_param_of`]). The kept attributes that name such a parameter of a
/// variation of the xform become it; a prefixed attribute of the same parameter wins.
fn unprefixed_params(cx: &mut Ctx, x: &mut Xform, st: &mut Pending) {
    let mut k = 0;
    while k < x.extra_attrs.len() {
        let (name, raw) = x.extra_attrs[k].clone();
        let found = parse_number(raw.trim()).ok().and_then(|value| {
            x.vars.iter().find_map(|v| {
                let full = format!("{}_{}", variations::info(v.id).name, name);
                let (id, _, index) = variations::param_of(&full)
                    .filter(|p| p.0 == v.id)
                    .or_else(|| variations::apophysis_param_of(&name))?;
                (id == v.id).then_some((id, v.form, index, value))
            })
        });
        let Some((id, form, index, value)) = found else {
            k += 1;
            continue;
        };
        let given = st
            .params
            .iter()
            .any(|p| p.id == id && p.index == index && p.instance == 0);
        if !given {
            st.params.push(Param {
                id,
                form,
                instance: 0,
                index,
                value,
                name: name.clone(),
                raw,
            });
        }
        cx.interpreted(&name);
        x.extra_attrs.remove(k);
    }
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
        "var" | "var1" => flam3_var_list(cx, x, st, a)?,
        _ => return Ok(false),
    }
    Ok(true)
}

/// flam3's `var="w0 w1 …"` (weights by flam3 index) and `var1="i"` (one variation of weight 1).
fn flam3_var_list(cx: &mut Ctx, x: &mut Xform, st: &mut Pending, a: &Attr) -> R<()> {
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
                set_var(x, st, id, form, 0, *w);
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
    st.instances.clear();
    set_var(x, st, id, form, 0, 1.0);
    Ok(())
}

/// A variation's weight, one of its parameters, or another attribute (kept as it stands; a
/// variation ugnis cannot render is reported once per file). JWildfire's `NAME#k#` (and
/// `NAME#k#_param`) are the k-th further use of variation NAME in the xform.
fn variation_attr(
    cx: &mut Ctx,
    x: &mut Xform,
    st: &mut Pending,
    a: &Attr,
    marked_vars: &HashSet<&str>,
) -> R<()> {
    let name = a.name;
    let v = a.value.trim();
    let indexed = split_jwf_index(name);
    let (base, instance) = indexed
        .as_ref()
        .map_or((name, 0), |(b, k)| (b.as_str(), *k));
    if let Some((id, form)) = variations::parse_name(base) {
        let w = cx.num(a)?;
        set_var(x, st, id, form, instance, w);
        if w == 0.0 && cx.jwildfire_flame && variations::info(id).acts_at_weight_zero() {
            // JWildfire runs every variation whatever its amount: one that colours or hides
            // points acts at amount 0 too, so it is kept (it moves nothing).
            x.vars.push(Var::with_form(id, form, 0.0));
            st.instances.push(instance);
        }
    } else if let Some((id, form, index)) = variations::param_of(base)
        && !(cx.jwildfire_names && case_differs(base, id, form, index))
    {
        let value = cx.num(a)?;
        // A parameter only the variation's JWildfire formula has lies beyond the registry's
        // list: it has no limit to check here.
        let def = variations::info(id).params.get(index);
        if let Some(def) = def.filter(|d| d.beyond_limit(value))
            && cx.reported_vars.insert(base.to_string())
        {
            let bound = if value > def.max { def.max } else { def.min };
            cx.warn(
                a.offset,
                "XML026",
                format!("{base}=\"{v}\" is outside what the variation can use; {bound} is used"),
            );
        }
        st.params.push(Param {
            id,
            form,
            instance,
            index,
            value,
            name: name.to_string(),
            raw: a.value.to_string(),
        });
    } else if let Some((id, form, index)) = variations::text_of(base) {
        st.texts.push(Param {
            id,
            form,
            instance,
            index,
            value: text_from_hex(v),
            name: name.to_string(),
            raw: v.to_string(),
        });
    } else {
        let numeric = parse_number(v).is_ok();
        let marked = marked_vars.contains(name);
        if numeric && (marked || variations::is_foreign_variation_name(base)) {
            if cx.reported_vars.insert(base.to_string()) {
                cx.warn(
                    a.offset,
                    "XML020",
                    format!("variation '{base}' (weight {v}) not supported; ignored"),
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

/// Whether attribute `base`, found as parameter `index` of variation `id` used in `form`,
/// spells that parameter with other letter case than JWildfire does (`dc_starsfield_Glow` for
/// `dc_starsfield_glow`, as older JWildfire versions wrote): JWildfire, which looks parameters
/// up by their exact names, does not read it (JWildfire 9.00 reads `dc_inversion_Iterations`
/// and `_ScaleX` of its 6.x files as nothing, and draws its defaults). Only the part after the
/// variation's name counts: for JWildfire's own variations the registry spells it as
/// JWildfire does; for the others only where the registry spells it in lower case, which is
/// JWildfire's spelling of every such name (names with capitals there follow Fractorium's or
/// Apophysis' spelling). Names reached through an alias match in any case.
fn case_differs(base: &str, id: VarId, form: Form, index: usize) -> bool {
    let def = variations::def_in(variations::Dialect::JWildfire, id, form);
    let exact = variations::info(id).has(variations::flag::JWILDFIRE);
    let Some(p) = def
        .params
        .get(index)
        .or(variations::info(id).params.get(index))
    else {
        return false;
    };
    let var = variations::info(id).name;
    let part = match p.name.get(..var.len()) {
        Some(head) if head.eq_ignore_ascii_case(var) => p.name[var.len()..].strip_prefix('_'),
        _ => None,
    };
    let Some(part) = part.filter(|q| exact || !q.bytes().any(|b| b.is_ascii_uppercase())) else {
        return false;
    };
    let tail = base
        .len()
        .checked_sub(part.len())
        .and_then(|cut| base.get(cut..));
    tail.is_some_and(|t| t != part && t.eq_ignore_ascii_case(part))
}

/// JWildfire marks a variation used before (< 0) or after (> 0) the others with
/// NAME_fx_priority (NAME#k#_fx_priority for a further use): the variation and its
/// parameters change form. A `pre_` variation marked 0 runs among the regular ones, where
/// JWildfire hands it a copy of the sum so far as the point to change and keeps nothing of
/// what it changes there: it draws nothing, so it is kept as an attribute, not a variation
/// (and written back as it was read). In JWildfire's flames a regular variation moved before
/// or after the others adds its output to the point there ([`Var::moved`]).
fn apply_priorities(attrs: &[Attr], x: &mut Xform, st: &mut Pending, jwildfire: bool) {
    for a in attrs {
        let (base, instance) = split_jwf_index(a.name).unwrap_or((a.name.to_string(), 0));
        if let Some(name) = base.strip_suffix("_fx_priority")
            && let Ok(p) = parse_number(a.value.trim())
            && p == 0.0
            && let Some((id, Form::Pre)) = variations::parse_name(name)
        {
            let weight_name = a.name.strip_suffix("_fx_priority").unwrap_or(name);
            let at = (0..x.vars.len()).find(|&i| {
                x.vars[i].id == id && x.vars[i].form == Form::Pre && st.instances[i] == instance
            });
            if let Some(i) = at
                && let Some(w) = attrs.iter().find(|b| b.name == weight_name)
            {
                x.vars.remove(i);
                st.instances.remove(i);
                x.extra_attrs
                    .push((weight_name.to_string(), w.value.to_string()));
            }
        } else if let Some(name) = base.strip_suffix("_fx_priority")
            && jwildfire
            && let Ok(p) = parse_number(a.value.trim())
            && p == 0.0
            && let Some((id, Form::Regular)) = variations::parse_name(name)
            && variations::jwildfire_runs_after(id)
        {
            // A variation JWildfire runs after the others by default, put among the regular
            // ones by the file: it runs there (the priority is written back as read).
            for (var, &k) in x.vars.iter_mut().zip(&st.instances) {
                if var.id == id && var.form == Form::Regular && k == instance {
                    var.moved = true;
                }
            }
        } else if let Some(name) = base.strip_suffix("_fx_priority")
            && let Ok(p) = parse_number(a.value.trim())
            && p != 0.0
            && let Some((id, Form::Regular)) = variations::parse_name(name)
            && !native_prepost(id, p)
        {
            let form = if p < 0.0 { Form::Pre } else { Form::Post };
            let this = |vid: VarId, vform: Form, k: u32| {
                vid == id && vform == Form::Regular && k == instance
            };
            let mut moved = false;
            for (var, &k) in x.vars.iter_mut().zip(&st.instances) {
                if this(var.id, var.form, k) {
                    var.form = form;
                    var.moved = jwildfire;
                    moved |= jwildfire;
                }
            }
            if moved {
                // Written again with the variation itself.
                x.extra_attrs.retain(|(k, _)| k != a.name);
            }
            for p in st.params.iter_mut() {
                if this(p.id, p.form, p.instance) {
                    p.form = form;
                }
            }
            for t in st.texts.iter_mut() {
                if this(t.id, t.form, t.instance) {
                    t.form = form;
                }
            }
        }
    }
}

/// Whether priority `p` is a prepost variation's own (2 or −2; JWildfire 9.00's
/// `XForm.createTransformations` runs such a variation both before and after the others for
/// either sign): it stays where it is, called in both phases, not moved.
fn native_prepost(id: VarId, p: f64) -> bool {
    p.abs() == 2.0 && variations::info(id).has(variations::flag::PREPOST)
}

/// Parameters go to their variation; parameters of absent variations are kept as-is.
fn attach_params(x: &mut Xform, st: Pending) {
    let find = |x: &Xform, id: VarId, form: Form, k: u32| {
        (0..x.vars.len())
            .find(|&i| x.vars[i].id == id && x.vars[i].form == form && st.instances[i] == k)
    };
    for p in &st.params {
        match find(x, p.id, p.form, p.instance) {
            Some(i) => x.vars[i].params[p.index] = p.value,
            None => x.extra_attrs.push((p.name.clone(), p.raw.clone())),
        }
    }
    for t in &st.texts {
        match find(x, t.id, t.form, t.instance) {
            Some(i) => {
                x.vars[i].texts[t.index] = variations::info(t.id).texts[t.index].normalise(&t.value)
            }
            None => x.extra_attrs.push((t.name.clone(), t.raw.clone())),
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
