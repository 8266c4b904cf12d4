//! JWildfire's motion curves: the attribute groups `NAME_enabled`, `NAME_interpolation`,
//! `NAME_point_count`, `NAME_x0`, `NAME_y0` … that JWildfire writes on a `<flame>` for its
//! camera and tone settings (`centreXCurve_…`, `pixelsPerUnitCurve_…`) and on an `<xform>` for
//! its weight, colour, affine coefficients, turns and scales (`xyCoeff20Curve_…`,
//! `xyRotateCurve_…`), a variation's amount (`julian_amountCurve_…`) and its parameters
//! (`julian_power_…`).
//!
//! Reading: the enabled curves whose setting ugnis has become the flame's keyframes, in
//! JWildfire's style ([`CurveStyle::JWildfire`]), with JWildfire's frames (from 1) made
//! ugnis' (from 0); the attributes stay among the kept ones. Writing: those attributes are
//! written back as they were read unless the curve changed in between (then its points and
//! interpolation are written anew, the view settings kept); a curve deleted in ugnis is
//! written disabled, and a JWildfire-style curve made in ugnis gets its attribute group.

use std::collections::HashMap;

use super::context::Ctx;
use crate::flame::jwf_curve::JwfInterp;
use crate::flame::keyframes::{
    Curve, CurveStyle, FlameParam, Key, MAX_CURVES, MAX_FRAMES, MAX_KEYS, Target, VarParam,
    XformParam, XformRef,
};
use crate::flame::model::{Flame, Xform};
use crate::flame::variations::{self, Form};
use crate::io::diag::fmt_num;

type Attrs = Vec<(String, String)>;

/// The flame's settings JWildfire's curves drive, by JWildfire's property name.
const FLAME_CURVES: [(&str, FlameParam); 15] = [
    ("centreXCurve", FlameParam::CenterX),
    ("centreYCurve", FlameParam::CenterY),
    ("pixelsPerUnitCurve", FlameParam::Scale),
    ("camRollCurve", FlameParam::Rotate),
    ("camPitchCurve", FlameParam::CamPitch),
    ("camYawCurve", FlameParam::CamYaw),
    ("camPerspectiveCurve", FlameParam::CamPerspective),
    ("camZoomCurve", FlameParam::CamZoom),
    ("camZCurve", FlameParam::CamZpos),
    ("camDOFCurve", FlameParam::CamDof),
    ("brightnessCurve", FlameParam::Brightness),
    ("contrastCurve", FlameParam::Contrast),
    ("gammaCurve", FlameParam::Gamma),
    ("gammaThresholdCurve", FlameParam::GammaThreshold),
    ("vibrancyCurve", FlameParam::Vibrancy),
];

/// JWildfire's palette shift (whole entries, turning the palette).
const PALETTE_SHIFT: &str = "palette_modShiftCurve";

/// An xform's settings JWildfire's curves drive.
const XFORM_CURVES: [(&str, XformParam); 20] = [
    ("weightCurve", XformParam::Weight),
    ("colorCurve", XformParam::Color),
    ("colorSymmetryCurve", XformParam::ColorSpeed),
    ("opacityCurve", XformParam::Opacity),
    ("xyCoeff00Curve", XformParam::Coef00),
    ("xyCoeff01Curve", XformParam::Coef01),
    ("xyCoeff10Curve", XformParam::Coef10),
    ("xyCoeff11Curve", XformParam::Coef11),
    ("xyCoeff20Curve", XformParam::MoveX),
    ("xyCoeff21Curve", XformParam::MoveY),
    ("xyPostCoeff00Curve", XformParam::PostCoef00),
    ("xyPostCoeff01Curve", XformParam::PostCoef01),
    ("xyPostCoeff10Curve", XformParam::PostCoef10),
    ("xyPostCoeff11Curve", XformParam::PostCoef11),
    ("xyPostCoeff20Curve", XformParam::PostMoveX),
    ("xyPostCoeff21Curve", XformParam::PostMoveY),
    ("xyRotateCurve", XformParam::Rotate),
    ("xyScaleCurve", XformParam::Scale),
    ("xyPostRotateCurve", XformParam::PostRotate),
    ("xyPostScaleCurve", XformParam::PostScale),
];

/// How JWildfire's value becomes ugnis' value of the same setting.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Conv {
    Same,
    /// JWildfire turns a map the other way round.
    Negate,
    /// JWildfire's colour symmetry s is flam3's colour speed (1 − s) / 2.
    Symmetry,
}

impl Conv {
    fn of(t: &Target) -> Conv {
        match t {
            Target::Xform(_, XformParam::Rotate | XformParam::PostRotate) => Conv::Negate,
            Target::Xform(_, XformParam::ColorSpeed) => Conv::Symmetry,
            _ => Conv::Same,
        }
    }
    fn to_ugnis(self, v: f64) -> f64 {
        match self {
            Conv::Same => v,
            Conv::Negate => -v,
            Conv::Symmetry => (1.0 - v) / 2.0,
        }
    }
    fn to_jwf(self, v: f64) -> f64 {
        match self {
            Conv::Same => v,
            Conv::Negate => -v,
            Conv::Symmetry => 1.0 - 2.0 * v,
        }
    }
}

/// Where a curve's attributes stand.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Scope {
    Flame,
    Xform(XformRef),
}

/// The target of the attribute group `prefix` in `scope` (`x`: the xform, for its
/// variations).
fn target_of(scope: Scope, prefix: &str, x: Option<&Xform>) -> Option<Target> {
    let r = match scope {
        Scope::Flame => {
            if prefix == PALETTE_SHIFT {
                return Some(Target::PaletteRotate);
            }
            return FLAME_CURVES
                .iter()
                .find(|(n, _)| *n == prefix)
                .map(|(_, p)| Target::Flame(*p));
        }
        Scope::Xform(r) => r,
    };
    if let Some((_, p)) = XFORM_CURVES.iter().find(|(n, _)| *n == prefix) {
        return Some(Target::Xform(r, *p));
    }
    // A variation's form as the xform holds it (JWildfire writes pre and post variations
    // under their plain names, with a priority).
    let form_in = |id, form| match (form, x) {
        (Form::Regular, Some(x)) => {
            let mut forms = x.vars.iter().filter(|v| v.id == id).map(|v| v.form);
            match (forms.next(), forms.next()) {
                (Some(f), None) => f,
                _ => form,
            }
        }
        _ => form,
    };
    if let Some(var) = prefix.strip_suffix("_amountCurve") {
        let (id, form) = variations::parse_name(var)?;
        return Some(Target::Var {
            xform: r,
            var: id,
            form: form_in(id, form),
            param: VarParam::Weight,
        });
    }
    let (id, form, k) = variations::param_of(prefix)?;
    Some(Target::Var {
        xform: r,
        var: id,
        form: form_in(id, form),
        param: VarParam::Param(k),
    })
}

/// The attribute prefix JWildfire uses for a target (None: JWildfire has no curve for it).
fn prefix_of(t: &Target) -> Option<(Scope, String)> {
    match t {
        Target::Flame(p) => FLAME_CURVES
            .iter()
            .find(|(_, q)| q == p)
            .map(|(n, _)| (Scope::Flame, n.to_string())),
        Target::PaletteRotate => Some((Scope::Flame, PALETTE_SHIFT.to_string())),
        Target::PaletteHue => None,
        Target::Xform(r, p) => XFORM_CURVES
            .iter()
            .find(|(_, q)| q == p)
            .map(|(n, _)| (Scope::Xform(*r), n.to_string())),
        Target::Var {
            xform,
            var,
            form,
            param,
        } => {
            let name = match param {
                VarParam::Weight => format!("{}_amountCurve", variations::attr_name(*var, *form)),
                VarParam::Param(k) => variations::param_attr_name(*var, *form, *k),
            };
            Some((Scope::Xform(*xform), name))
        }
    }
}

/// One attribute group as read: enabled, interpolation, points.
struct Group {
    enabled: bool,
    interp: Option<JwfInterp>,
    /// The interpolation's text when JWildfire would not know it.
    bad_interp: Option<String>,
    points: Vec<(i64, f64)>,
    parent: bool,
}

fn get<'a>(attrs: &'a HashMap<&str, &str>, prefix: &str, field: &str) -> Option<&'a str> {
    attrs.get(format!("{prefix}_{field}").as_str()).copied()
}

/// The group `prefix` among `attrs`, or why it cannot be read.
fn read_group(attrs: &HashMap<&str, &str>, prefix: &str) -> Result<Group, String> {
    let enabled =
        get(attrs, prefix, "enabled").is_some_and(|v| v.trim().eq_ignore_ascii_case("true"));
    let raw_interp = get(attrs, prefix, "interpolation").map(str::trim);
    let interp = match raw_interp {
        None => Some(JwfInterp::Spline),
        Some(s) => JwfInterp::from_name(s),
    };
    let count = get(attrs, prefix, "point_count").unwrap_or("0").trim();
    let n: usize = count
        .parse()
        .map_err(|_| format!("point_count '{count}' is not a whole number"))?;
    if n > MAX_KEYS {
        return Err(format!("{n} points; a curve holds at most {MAX_KEYS}"));
    }
    let mut points = Vec::with_capacity(n);
    for i in 0..n {
        let x = match get(attrs, prefix, &format!("x{i}")) {
            None => 0,
            Some(v) => v
                .trim()
                .parse::<i64>()
                .map_err(|_| format!("x{i} '{v}' is not a whole frame number"))?,
        };
        if x.unsigned_abs() > MAX_FRAMES as u64 {
            return Err(format!("x{i} {x} is past frame {MAX_FRAMES}"));
        }
        let y = match get(attrs, prefix, &format!("y{i}")) {
            None => 0.0,
            Some(v) => v
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|y| y.is_finite())
                .ok_or_else(|| format!("y{i} '{v}' is not a number"))?,
        };
        points.push((x, y));
    }
    Ok(Group {
        enabled,
        interp,
        bad_interp: raw_interp
            .filter(|_| interp.is_none())
            .map(|s| s.to_string()),
        points,
        parent: get(attrs, prefix, "parent_curve").is_some(),
    })
}

/// The prefixes of the attribute groups among `attrs`, in file order.
fn group_prefixes(attrs: &[(String, String)]) -> Vec<&str> {
    attrs
        .iter()
        .filter_map(|(k, _)| k.strip_suffix("_point_count"))
        .collect()
}

/// Whether any attribute of `attrs` starts a curve group.
fn has_groups(attrs: &[(String, String)]) -> bool {
    attrs.iter().any(|(k, _)| k.ends_with("_point_count"))
}

/// Attributes by name.
fn attr_map(attrs: &[(String, String)]) -> HashMap<&str, &str> {
    attrs
        .iter()
        .map(|(k, v)| (k.as_str(), v.as_str()))
        .collect()
}

/// Whether `rest` (an attribute name past its group's prefix and `_`) names a point: `x3`, `y3`.
fn is_point(rest: &str) -> bool {
    rest.len() > 1
        && (rest.starts_with('x') || rest.starts_with('y'))
        && rest[1..].bytes().all(|b| b.is_ascii_digit())
}

/// The names of a group's attributes (to count them as interpreted).
fn group_names<'a>(attrs: &'a [(String, String)], prefix: &str) -> Vec<&'a str> {
    attrs
        .iter()
        .map(|(k, _)| k.as_str())
        .filter(|k| {
            k.strip_prefix(prefix)
                .and_then(|r| r.strip_prefix('_'))
                .is_some_and(|r| {
                    matches!(
                        r,
                        "enabled"
                            | "interpolation"
                            | "point_count"
                            | "view_xmin"
                            | "view_xmax"
                            | "view_ymin"
                            | "view_ymax"
                            | "selected_idx"
                            | "locked"
                    ) || is_point(r)
                })
        })
        .collect()
}

/// The curve a group makes, or why it makes none (None: nothing to say).
fn curve_of(target: Target, g: &Group, x: Option<&Xform>) -> Result<Option<Curve>, String> {
    if !g.enabled {
        return Ok(None);
    }
    let Some(interp) = g.interp else {
        return Err(format!(
            "interpolation '{}' is not SPLINE, BEZIER or LINEAR",
            g.bad_interp.as_deref().unwrap_or("")
        ));
    };
    if g.parent {
        return Err("a curve added to a parent curve (parent_curve) is not played".into());
    }
    if g.points.is_empty() {
        return Err("enabled without points (JWildfire would set the value to 0)".into());
    }
    if let (Target::Xform(_, XformParam::Opacity), Some(x)) = (target, x)
        && (x.opacity.abs() <= 1e-6 || (x.opacity - 1.0).abs() <= 1e-6)
    {
        // JWildfire plays opacity only for xforms drawn with their own opacity.
        return Ok(None);
    }
    if g.points.windows(2).any(|w| w[1].0 <= w[0].0) {
        return Err("its points are not in increasing frame order".into());
    }
    let conv = Conv::of(&target);
    let mut c = Curve::with_style(target, CurveStyle::JWildfire(interp));
    for (px, py) in &g.points {
        c.insert(Key::new((*px - 1) as f64, conv.to_ugnis(*py)))?;
    }
    Ok(Some(c))
}

/// Read the enabled JWildfire curves of `f` (its attributes and its xforms') into its
/// keyframes. Problems are warnings at `start` (the flame element): the curve is not played
/// but its attributes stay.
pub(super) fn read(cx: &mut Ctx, f: &mut Flame, start: usize) {
    let had_keys = !f.keys.curves.is_empty();
    let mut scopes: Vec<(Scope, &Attrs, Option<&Xform>)> =
        vec![(Scope::Flame, &f.extra_attrs, None)];
    for (i, x) in f.xforms.iter().enumerate() {
        scopes.push((Scope::Xform(XformRef::Index(i)), &x.extra_attrs, Some(x)));
    }
    if let Some(x) = &f.final_xform {
        scopes.push((Scope::Xform(XformRef::Final), &x.extra_attrs, Some(x)));
    }
    if !scopes.iter().any(|(_, a, _)| has_groups(a)) {
        return;
    }
    let mut curves = Vec::new();
    let mut interpreted: Vec<String> = Vec::new();
    for (scope, attrs, x) in scopes {
        let map = attr_map(attrs);
        for prefix in group_prefixes(attrs) {
            let Some(target) = target_of(scope, prefix, x) else {
                if get(&map, prefix, "enabled").is_some_and(|v| v.trim() == "true") {
                    cx.warn(
                        start,
                        "XML021",
                        format!(
                            "JWildfire curve {prefix} is kept but not played: ugnis has no such setting"
                        ),
                    );
                }
                continue;
            };
            let made = read_group(&map, prefix).and_then(|g| curve_of(target, &g, x));
            match made {
                Ok(Some(c)) => {
                    if f.keys.curve(&target).is_some() {
                        cx.warn(
                            start,
                            "XML021",
                            format!(
                                "JWildfire curve {prefix}: '{target}' already has keyframes; \
                                 the JWildfire curve is not played"
                            ),
                        );
                        continue;
                    }
                    interpreted.extend(group_names(attrs, prefix).iter().map(|s| s.to_string()));
                    curves.push(c);
                }
                Ok(None) => {
                    interpreted.extend(group_names(attrs, prefix).iter().map(|s| s.to_string()))
                }
                Err(e) => cx.warn(
                    start,
                    "XML021",
                    format!("JWildfire curve {prefix} is kept but not played: {e}"),
                ),
            }
        }
    }
    for name in &interpreted {
        cx.interpreted(name);
    }
    if curves.is_empty() {
        return;
    }
    if f.keys.curves.len() + curves.len() > MAX_CURVES {
        cx.warn(
            start,
            "XML021",
            format!("more than {MAX_CURVES} keyframe curves; JWildfire's curves are not played"),
        );
        return;
    }
    f.keys.curves.extend(curves);
    if !had_keys {
        // The timeline: JWildfire's frame count and frame rate.
        let attr = |name: &str| {
            f.extra_attrs
                .iter()
                .find(|(k, _)| k == name)
                .and_then(|(_, v)| v.trim().parse::<f64>().ok())
        };
        if let Some(n) = attr("frame_count").filter(|n| (1.0..=MAX_FRAMES as f64).contains(n)) {
            f.keys.frames = n as u32;
        }
        if let Some(fps) = attr("fps").filter(|v| (0.01..=1000.0).contains(v)) {
            f.keys.fps = fps;
        }
    }
}

/// The kept attributes of a flame and its xforms as they are to be written, with its
/// JWildfire-style curves in them; and which curves were written so (they are not written
/// again among ugnis' keyframes).
pub(super) struct Written {
    pub(super) flame: Attrs,
    pub(super) xforms: Vec<Attrs>,
    pub(super) final_xform: Option<Attrs>,
    /// Indices into the flame's keyframe curves.
    pub(super) curves: Vec<usize>,
}

/// The attributes to write for `f`; None when it has no JWildfire curve (its kept attributes
/// are written as they stand).
pub(super) fn for_writing(f: &Flame) -> Option<Written> {
    let jwf_style = |c: &Curve| matches!(c.style(), CurveStyle::JWildfire(_));
    let any = f.keys.curves.iter().any(jwf_style)
        || has_groups(&f.extra_attrs)
        || f.xforms.iter().any(|x| has_groups(&x.extra_attrs))
        || f.final_xform
            .as_ref()
            .is_some_and(|x| has_groups(&x.extra_attrs));
    if !any {
        return None;
    }
    let mut w = Written {
        flame: f.extra_attrs.clone(),
        xforms: f.xforms.iter().map(|x| x.extra_attrs.clone()).collect(),
        final_xform: f.final_xform.as_ref().map(|x| x.extra_attrs.clone()),
        curves: Vec::new(),
    };
    let mut jwf_curves: Vec<(usize, Scope, String)> = Vec::new();
    for (i, c) in f.keys.curves.iter().enumerate() {
        if jwf_style(c)
            && !c.keys().is_empty()
            && let Some((scope, prefix)) = prefix_of(&c.target)
        {
            jwf_curves.push((i, scope, prefix));
        }
    }
    let mut scopes: Vec<(Scope, &mut Attrs, Option<&Xform>)> =
        vec![(Scope::Flame, &mut w.flame, None)];
    for (i, (a, x)) in w.xforms.iter_mut().zip(&f.xforms).enumerate() {
        scopes.push((Scope::Xform(XformRef::Index(i)), a, Some(x)));
    }
    if let (Some(a), Some(x)) = (w.final_xform.as_mut(), f.final_xform.as_ref()) {
        scopes.push((Scope::Xform(XformRef::Final), a, Some(x)));
    }
    for (scope, attrs, x) in scopes {
        let prefixes: Vec<String> = group_prefixes(attrs)
            .iter()
            .map(|s| s.to_string())
            .collect();
        for prefix in prefixes {
            let Some(target) = target_of(scope, &prefix, x) else {
                continue;
            };
            let curve = f
                .keys
                .curves
                .iter()
                .position(|c| c.target == target && jwf_style(c) && !c.keys().is_empty());
            match curve {
                Some(i) => {
                    put_group(attrs, &prefix, &f.keys.curves[i]);
                    w.curves.push(i);
                    jwf_curves.retain(|(j, ..)| *j != i);
                }
                None => {
                    let map = attr_map(attrs);
                    // A curve ugnis played and no longer has: JWildfire must not play it.
                    let played = read_group(&map, &prefix)
                        .ok()
                        .and_then(|g| curve_of(target, &g, x).ok().flatten())
                        .is_some();
                    if played {
                        set(attrs, &format!("{prefix}_enabled"), "false".into());
                    }
                }
            }
        }
        for (i, _, prefix) in jwf_curves.iter().filter(|(_, s, _)| *s == scope) {
            put_group(attrs, prefix, &f.keys.curves[*i]);
            w.curves.push(*i);
        }
        jwf_curves.retain(|(_, s, _)| *s != scope);
    }
    if !w.curves.is_empty() {
        sync_timeline(&mut w.flame, f);
    }
    Some(w)
}

/// Set attribute `name` (in place, or added at the end).
fn set(attrs: &mut Attrs, name: &str, value: String) {
    match attrs.iter_mut().find(|(k, _)| k == name) {
        Some((_, v)) => *v = value,
        None => attrs.push((name.to_string(), value)),
    }
}

/// JWildfire's frame count and rate, where they differ from the keyframes' timeline.
fn sync_timeline(attrs: &mut Attrs, f: &Flame) {
    let read = |attrs: &Attrs, name: &str| {
        attrs
            .iter()
            .find(|(k, _)| k == name)
            .and_then(|(_, v)| v.trim().parse::<f64>().ok())
    };
    if read(attrs, "frame_count") != Some(f.keys.frames as f64) {
        set(attrs, "frame_count", f.keys.frames.to_string());
    }
    if read(attrs, "fps") != Some(f.keys.fps) {
        let fps = if f.keys.fps.fract() == 0.0 {
            format!("{}", f.keys.fps as i64)
        } else {
            fmt_num(f.keys.fps)
        };
        set(attrs, "fps", fps);
    }
}

/// Write curve `c` as the group `prefix`: the attributes stand as they are when they already
/// say the same, else its points and interpolation are written anew.
fn put_group(attrs: &mut Attrs, prefix: &str, c: &Curve) {
    let CurveStyle::JWildfire(interp) = c.style() else {
        return;
    };
    let conv = Conv::of(&c.target);
    let points: Vec<(i64, f64)> = c
        .keys()
        .iter()
        .map(|k| ((k.frame + 1.0).round() as i64, conv.to_jwf(k.value)))
        .collect();
    let map = attr_map(attrs);
    if let Ok(g) = read_group(&map, prefix) {
        let same = g.enabled
            && g.interp == Some(interp)
            && !g.parent
            && g.points.len() == points.len()
            && g.points
                .iter()
                .zip(&points)
                .all(|(a, b)| a.0 == b.0 && (a.1 - b.1).abs() <= 1e-12 * a.1.abs().max(1.0));
        if same {
            return;
        }
    }
    // Drop the old points, then write the group.
    let is_point = |k: &str| {
        k.strip_prefix(prefix)
            .and_then(|r| r.strip_prefix('_'))
            .is_some_and(is_point)
    };
    attrs.retain(|(k, _)| !is_point(k));
    set(attrs, &format!("{prefix}_enabled"), "true".into());
    set(
        attrs,
        &format!("{prefix}_interpolation"),
        interp.name().into(),
    );
    set(
        attrs,
        &format!("{prefix}_point_count"),
        points.len().to_string(),
    );
    let at = attrs
        .iter()
        .position(|(k, _)| *k == format!("{prefix}_point_count"))
        .map_or(attrs.len(), |p| p + 1);
    let new: Attrs = points
        .iter()
        .enumerate()
        .flat_map(|(i, (x, y))| {
            [
                (format!("{prefix}_x{i}"), x.to_string()),
                (format!("{prefix}_y{i}"), java_double(*y)),
            ]
        })
        .collect();
    attrs.splice(at..at, new);
}

/// A number as Java writes a double when it is a whole number (`2.0`), else the shortest
/// decimal that reads back the same.
fn java_double(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e7 {
        format!("{v:.1}")
    } else {
        fmt_num(v)
    }
}

#[cfg(test)]
#[path = "jwf_curves_tests.rs"]
mod tests;
