//! Reading and writing a flame's animation settings: flam3's control-point attributes (`time`,
//! the interpolation keywords, motion blur), an xform's `<motion>` elements, and ugnis' own
//! keyframes (`<ugnis_keys>`, a child element flam3, Apophysis and Fractorium skip).

use std::fmt::Write as _;

use super::context::{Ctx, R};
use crate::flame::jwf_curve::JwfInterp;
use crate::flame::keyframes::{
    Curve, CurveStyle, Ease, Interp, Key, Keyframes, MAX_CURVES, MAX_FRAMES,
};
use crate::flame::model::{Affine, Flame, Motion, Xform};
use crate::flame::sequence::{
    Animation, Interpolation, InterpolationType, MAX_TEMPORAL_SAMPLES, MotionFunction,
    PaletteInterpolation, TemporalFilterType,
};
use crate::flame::variations;
use crate::io::diag::fmt_num;
use crate::io::xml::{Attr, escape_attr};

/// A keyword attribute: the value `parse` accepts, or flam3's default with a warning naming the
/// accepted words (flam3 warns and goes on).
fn keyword<T>(cx: &mut Ctx, a: &Attr, parse: fn(&str) -> Option<T>, words: &str, default: T) -> T {
    match parse(a.value.trim()) {
        Some(v) => v,
        None => {
            cx.warn(
                a.offset,
                "XML021",
                format!(
                    "{} '{}' is not one of {words}; the default is used",
                    a.name,
                    a.value.trim()
                ),
            );
            default
        }
    }
}

/// A flame's animation attribute. False if `a` is none of them.
pub(super) fn anim_attr(cx: &mut Ctx, f: &mut Flame, a: &Attr) -> R<bool> {
    let d = Animation::default();
    let an = &mut f.anim;
    match a.name {
        "time" => an.time = cx.num(a)?,
        "interpolation" => {
            an.interpolation = keyword(
                cx,
                a,
                Interpolation::from_name,
                "linear, smooth",
                d.interpolation,
            )
        }
        "interpolation_type" | "interpolation_space" => {
            an.interpolation_type = keyword(
                cx,
                a,
                InterpolationType::from_name,
                "linear, log, old, older",
                d.interpolation_type,
            )
        }
        "palette_interpolation" => {
            an.palette_interpolation = keyword(
                cx,
                a,
                PaletteInterpolation::from_name,
                "hsv, hsv_circular, rgb, sweep",
                d.palette_interpolation,
            )
        }
        "hsv_rgb_palette_blend" => an.hsv_rgb_palette_blend = cx.num(a)?,
        "temporal_samples" => {
            // JWildfire writes it as a real number.
            let n = cx.num(a)?;
            if n < 1.0 {
                return Err(cx.err(
                    a.offset,
                    "XML003",
                    format!("temporal_samples {n} must be at least 1"),
                ));
            }
            if n > MAX_TEMPORAL_SAMPLES as f64 {
                cx.warn(
                    a.offset,
                    "XML021",
                    format!(
                        "temporal_samples {n}: ugnis draws at most {MAX_TEMPORAL_SAMPLES} \
                         sub-frames per frame"
                    ),
                );
            }
            an.temporal_samples = n.min(MAX_TEMPORAL_SAMPLES as f64) as u32;
        }
        "temporal_filter_type" => {
            an.temporal_filter_type = keyword(
                cx,
                a,
                TemporalFilterType::from_name,
                "box, gaussian, exp",
                d.temporal_filter_type,
            )
        }
        "temporal_filter_width" => {
            let w = cx.num(a)?;
            if w < 0.0 {
                return Err(cx.err(
                    a.offset,
                    "XML003",
                    format!("temporal_filter_width {w} must not be negative"),
                ));
            }
            an.temporal_filter_width = w;
        }
        "temporal_filter_exp" => an.temporal_filter_exp = cx.num(a)?,
        _ => return Ok(false),
    }
    Ok(true)
}

/// The animation attributes that differ from flam3's defaults, as ` name="value"` pairs.
pub(super) fn write_anim_attrs(s: &mut String, a: &Animation) {
    let d = Animation::default();
    let n = fmt_num;
    if a.time != d.time {
        let _ = write!(s, " time=\"{}\"", n(a.time));
    }
    if a.interpolation != d.interpolation {
        let _ = write!(s, " interpolation=\"{}\"", a.interpolation.name());
    }
    if a.interpolation_type != d.interpolation_type {
        let _ = write!(s, " interpolation_type=\"{}\"", a.interpolation_type.name());
    }
    if a.palette_interpolation != d.palette_interpolation {
        let _ = write!(
            s,
            " palette_interpolation=\"{}\"",
            a.palette_interpolation.name()
        );
    }
    if a.hsv_rgb_palette_blend != d.hsv_rgb_palette_blend {
        let _ = write!(
            s,
            " hsv_rgb_palette_blend=\"{}\"",
            n(a.hsv_rgb_palette_blend)
        );
    }
    if a.temporal_samples != d.temporal_samples {
        let _ = write!(s, " temporal_samples=\"{}\"", a.temporal_samples);
    }
    if a.temporal_filter_type != d.temporal_filter_type {
        let _ = write!(
            s,
            " temporal_filter_type=\"{}\"",
            a.temporal_filter_type.name()
        );
    }
    if a.temporal_filter_width != d.temporal_filter_width {
        let _ = write!(
            s,
            " temporal_filter_width=\"{}\"",
            n(a.temporal_filter_width)
        );
    }
    if a.temporal_filter_exp != d.temporal_filter_exp {
        let _ = write!(s, " temporal_filter_exp=\"{}\"", n(a.temporal_filter_exp));
    }
}

/// A `<motion>` element read as an xform (`x`, from the same attribute reader): its frequency
/// and function, and every value it does not name made zero, so that it holds only changes.
pub(super) fn motion_from(cx: &mut Ctx, attrs: &[Attr], mut x: Xform, start: usize) -> R<Motion> {
    let has = |name: &str| attrs.iter().any(|a| a.name == name);
    let mut m = Motion::new(0, MotionFunction::Hill);
    for a in attrs {
        match a.name {
            "motion_frequency" => {
                let k = cx.int(a)?;
                if k.abs() > 1_000_000 {
                    return Err(cx.err(
                        a.offset,
                        "XML003",
                        format!("motion_frequency {k} is out of range"),
                    ));
                }
                m.frequency = k as i32;
            }
            "motion_function" => {
                m.function = MotionFunction::from_name(a.value.trim()).ok_or_else(|| {
                    cx.err(
                        a.offset,
                        "XML003",
                        format!(
                            "motion_function '{}' must be sin, triangle or hill",
                            a.value.trim()
                        ),
                    )
                })?
            }
            "chaos" | "plotmode" => {
                return Err(cx.err(
                    a.offset,
                    "XML003",
                    format!("a <motion> element cannot have a {} attribute", a.name),
                ));
            }
            _ => {}
        }
    }
    let zero = Affine::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    if !has("color") {
        x.color = 0.0;
    }
    if !has("color_speed") && !has("symmetry") {
        x.color_speed = 0.0;
    }
    if !has("opacity") {
        x.opacity = 0.0;
    }
    if !has("animate") {
        x.animate = 0.0;
    }
    if !has("direct_color") {
        x.direct_color = 0.0;
    }
    if !has("coefs") {
        x.coefs = zero;
    }
    if !has("post") {
        x.post = zero;
    }
    // Parameters: only those named change; one named for a variation the element gives no
    // weight to changes that variation's parameter.
    for v in &mut x.vars {
        for (k, p) in v.params.iter_mut().enumerate() {
            if !has(&variations::param_attr_name(v.id, v.form, k)) {
                *p = 0.0;
            }
        }
    }
    let mut rest = Vec::new();
    for (name, raw) in std::mem::take(&mut x.extra_attrs) {
        if matches!(name.as_str(), "motion_frequency" | "motion_function") {
            continue;
        }
        match variations::param_of(&name) {
            Some((id, form, k)) => {
                let value = raw.trim().parse::<f64>().map_err(|_| {
                    cx.err(
                        start,
                        "XML003",
                        format!("<motion> {name}: '{raw}' is not a number"),
                    )
                })?;
                let pos = x.vars.iter().position(|v| v.id == id && v.form == form);
                let v = match pos {
                    Some(p) => &mut x.vars[p],
                    None => {
                        let mut v = crate::flame::model::Var::with_form(id, form, 0.0);
                        v.params.iter_mut().for_each(|p| *p = 0.0);
                        x.vars.push(v);
                        x.vars.last_mut().expect("just pushed")
                    }
                };
                v.params[k] = value;
            }
            None => rest.push((name, raw)),
        }
    }
    x.extra_attrs = rest;
    m.delta = x;
    Ok(m)
}

/// A `<motion>` element's text: only what it changes.
pub(super) fn write_motion(s: &mut String, m: &Motion, ind: &str) {
    let n = fmt_num;
    let d = &m.delta;
    let _ = write!(
        s,
        "{ind}<motion motion_frequency=\"{}\" motion_function=\"{}\"",
        m.frequency,
        m.function.name()
    );
    for (name, v) in [
        ("weight", d.weight),
        ("color", d.color),
        ("color_speed", d.color_speed),
        ("opacity", d.opacity),
        ("animate", d.animate),
        ("direct_color", d.direct_color),
    ] {
        if v != 0.0 {
            let _ = write!(s, " {name}=\"{}\"", n(v));
        }
    }
    for v in &d.vars {
        if v.weight != 0.0 {
            let _ = write!(s, " {}=\"{}\"", v.attr_name(), n(v.weight));
        }
        for (k, p) in v.params.iter().enumerate() {
            if *p != 0.0 {
                let _ = write!(
                    s,
                    " {}=\"{}\"",
                    variations::param_attr_name(v.id, v.form, k),
                    n(*p)
                );
            }
        }
    }
    let zero = Affine::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for (name, m) in [("coefs", d.coefs), ("post", d.post)] {
        if m != zero {
            let c: Vec<String> = m.to_coefs().iter().map(|v| n(*v)).collect();
            let _ = write!(s, " {name}=\"{}\"", c.join(" "));
        }
    }
    s.push_str("/>\n");
}

/// The attributes of `<ugnis_keys>`: the timeline.
pub(super) fn keys_timeline(cx: &mut Ctx, attrs: &[Attr], k: &mut Keyframes) -> R<()> {
    for a in attrs {
        match a.name {
            "frames" => {
                let v = cx.int(a)?;
                if !(1..=MAX_FRAMES as i64).contains(&v) {
                    return Err(cx.err(
                        a.offset,
                        "XML003",
                        format!("frames {v} must be between 1 and {MAX_FRAMES}"),
                    ));
                }
                k.frames = v as u32;
            }
            "fps" => {
                let v = cx.num(a)?;
                if !(0.01..=1000.0).contains(&v) {
                    return Err(cx.err(
                        a.offset,
                        "XML003",
                        format!("fps {v} must be between 0.01 and 1000"),
                    ));
                }
                k.fps = v;
            }
            "wrap" => k.wrap = a.value.trim() == "1",
            _ => cx.ignore(a.name),
        }
    }
    Ok(())
}

/// A `<curve target="…">`: None (with a warning) when the target is unknown here, so a file of
/// a later version still opens.
pub(super) fn keys_curve(
    cx: &mut Ctx,
    attrs: &[Attr],
    start: usize,
    k: &Keyframes,
) -> R<Option<Curve>> {
    if k.curves.len() >= MAX_CURVES {
        return Err(cx.err(
            start,
            "XML003",
            format!("more than {MAX_CURVES} keyframe curves"),
        ));
    }
    let Some(t) = attrs.iter().find(|a| a.name == "target") else {
        return Err(cx.err(start, "XML003", "<curve> needs a 'target' attribute"));
    };
    let mut style = CurveStyle::Keys;
    if let Some(a) = attrs.iter().find(|a| a.name == "style") {
        let v = a.value.trim();
        style = match v.strip_prefix("jwildfire_") {
            None if v == "keys" => CurveStyle::Keys,
            Some(i) => match JwfInterp::from_name(&i.to_ascii_uppercase()) {
                Some(i) => CurveStyle::JWildfire(i),
                None => return Err(bad_style(cx, a)),
            },
            None => return Err(bad_style(cx, a)),
        };
    }
    match t.value.parse() {
        Ok(target) if k.curve(&target).is_some() => {
            cx.warn(
                t.offset,
                "XML021",
                format!("a second curve for '{target}': the first is played, this one skipped"),
            );
            Ok(None)
        }
        Ok(target) => Ok(Some(Curve::with_style(target, style))),
        Err(e) => {
            cx.warn(t.offset, "XML021", format!("{e}; the curve is skipped"));
            Ok(None)
        }
    }
}

fn bad_style(cx: &Ctx, a: &Attr) -> crate::io::diag::Diagnostic {
    cx.err(
        a.offset,
        "XML003",
        format!(
            "curve style '{}' must be keys, jwildfire_spline, jwildfire_bezier or jwildfire_linear",
            a.value.trim()
        ),
    )
}

/// A `<key>` of a curve.
pub(super) fn keys_key(cx: &mut Ctx, attrs: &[Attr], start: usize, c: &mut Curve) -> R<()> {
    let mut key = Key::new(f64::NAN, f64::NAN);
    for a in attrs {
        match a.name {
            "frame" => key.frame = cx.num(a)?,
            "value" => key.value = cx.num(a)?,
            "interp" => {
                key.interp = Interp::from_name(a.value.trim()).ok_or_else(|| {
                    cx.err(
                        a.offset,
                        "XML003",
                        format!(
                            "interp '{}' must be linear, smooth, bezier or step",
                            a.value.trim()
                        ),
                    )
                })?
            }
            "ease" => {
                key.ease = Ease::from_name(a.value.trim()).ok_or_else(|| {
                    cx.err(
                        a.offset,
                        "XML003",
                        format!("ease '{}' must be none, in, out or in_out", a.value.trim()),
                    )
                })?
            }
            "handles" => {
                let h: [f64; 4] = cx.fixed(a, "XML003", "numbers")?;
                key.handles = Some([[h[0], h[1]], [h[2], h[3]]]);
            }
            _ => cx.ignore(a.name),
        }
    }
    c.insert(key)
        .map_err(|e| cx.err(start, "XML003", format!("<key>: {e}")))
}

/// The `<ugnis_keys>` element of a flame's keyframes (nothing when it has none), less the
/// curves at the indices `skip` (written as JWildfire's attributes).
pub(super) fn write_keys(s: &mut String, k: &Keyframes, skip: &[usize], ind: &str) {
    let shown = |(i, c): &(usize, &Curve)| !c.keys().is_empty() && !skip.contains(i);
    if !k.curves.iter().enumerate().any(|ic| shown(&ic)) {
        return;
    }
    let n = fmt_num;
    let _ = writeln!(
        s,
        "{ind}<ugnis_keys frames=\"{}\" fps=\"{}\" wrap=\"{}\">",
        k.frames,
        n(k.fps),
        k.wrap as u8
    );
    for (_, c) in k.curves.iter().enumerate().filter(shown) {
        let _ = write!(
            s,
            "{ind}   <curve target=\"{}\"",
            escape_attr(&c.target.to_string())
        );
        if let CurveStyle::JWildfire(i) = c.style() {
            let _ = write!(s, " style=\"jwildfire_{}\"", i.name().to_ascii_lowercase());
        }
        s.push_str(">\n");
        for key in c.keys() {
            let _ = write!(
                s,
                "{ind}      <key frame=\"{}\" value=\"{}\"",
                n(key.frame),
                n(key.value)
            );
            if key.interp != Interp::default() {
                let _ = write!(s, " interp=\"{}\"", key.interp.name());
            }
            if key.ease != Ease::None {
                let _ = write!(s, " ease=\"{}\"", key.ease.name());
            }
            if let Some(h) = key.handles {
                let _ = write!(
                    s,
                    " handles=\"{} {} {} {}\"",
                    n(h[0][0]),
                    n(h[0][1]),
                    n(h[1][0]),
                    n(h[1][1])
                );
            }
            s.push_str("/>\n");
        }
        let _ = writeln!(s, "{ind}   </curve>");
    }
    let _ = writeln!(s, "{ind}</ugnis_keys>");
}
