//! JWildfire's picture settings on a `<flame>` (`white_level`, `low_density_brightness`,
//! `balancing_red` …, `saturation`, `fg_opacity`, `antialias_amount`, `antialias_radius`,
//! `filter_kernel`, `background_type` and the gradient background's colours, the camera's
//! `cam_roll` and `cam_dof_scale`, the `frame` shown and its motion blur): read into
//! [`JwfLook`] for flames JWildfire wrote, kept verbatim for the others, and written back for
//! flames JWildfire's renderer draws; and the colour types of a JWildfire file's xforms.

use std::fmt::Write as _;

use super::context::{Ctx, R};
use crate::flame::jwf_render::{JwfBackgroundKind, JwfKernel, JwfLook};
use crate::flame::model::Flame;
use crate::io::diag::fmt_num;
use crate::io::xml::Attr;

/// Most flames JWildfire's motion blur may add.
const MAX_MOTION_BLUR: i64 = 1000;

/// The settings read so far, and the names they were read from.
#[derive(Default)]
pub(super) struct Pending {
    look: JwfLook,
    names: Vec<String>,
    /// The solid rendering attributes (name, value, offset), read when the writer is known.
    solid: Vec<(String, String, usize)>,
}

/// Read `a` if it is one of JWildfire's picture settings (kept among the flame's attributes
/// until the writer is known). False if it is none of them.
pub(super) fn attr(cx: &mut Ctx, f: &mut Flame, st: &mut Pending, a: &Attr) -> R<bool> {
    if super::jwf_solid::is_solid_attr(a.name) {
        st.solid
            .push((a.name.to_string(), a.value.to_string(), a.offset));
        st.names.push(a.name.to_string());
        f.extra_attrs
            .push((a.name.to_string(), a.value.to_string()));
        return Ok(true);
    }
    let l = &mut st.look;
    let v = a.value.trim();
    let colour = |cx: &mut Ctx| -> R<[f64; 3]> { cx.fixed(a, "XML003", "numbers") };
    match a.name {
        "white_level" => l.white_level = positive(cx, a)?,
        "low_density_brightness" => l.low_density_brightness = cx.num(a)?,
        "balancing_red" => l.balance[0] = cx.num(a)?,
        "balancing_green" => l.balance[1] = cx.num(a)?,
        "balancing_blue" => l.balance[2] = cx.num(a)?,
        "saturation" => l.saturation = cx.num(a)?,
        "fg_opacity" => l.foreground_opacity = cx.num(a)?,
        "antialias_amount" => l.antialias_amount = cx.num(a)?,
        "antialias_radius" => l.antialias_radius = cx.num(a)?,
        "filter_kernel" => match JwfKernel::from_name(v) {
            Some(k) => l.kernel = k,
            None => cx.warn(
                a.offset,
                "XML014",
                format!(
                    "unknown filter_kernel '{v}'; JWildfire's renderer uses {}",
                    l.kernel.name()
                ),
            ),
        },
        "background_type" => match JwfBackgroundKind::from_name(v) {
            Some(k) => l.background.kind = k,
            None => cx.warn(
                a.offset,
                "XML014",
                format!("unknown background_type '{v}'; using one colour"),
            ),
        },
        "background_ul" => l.background.ul = colour(cx)?,
        "background_ur" => l.background.ur = colour(cx)?,
        "background_ll" => l.background.ll = colour(cx)?,
        "background_lr" => l.background.lr = colour(cx)?,
        "background_cc" => l.background.cc = colour(cx)?,
        "cam_roll" => l.bank = cx.num(a)?,
        "cam_dof_scale" => l.dof_scale = cx.num(a)?,
        "frame" => l.frame = cx.num(a)?,
        "motion_blur_length" => {
            let n = cx.int(a)?;
            if !(0..=MAX_MOTION_BLUR).contains(&n) {
                return Err(cx.err(
                    a.offset,
                    "XML013",
                    format!("motion_blur_length {n} must be between 0 and {MAX_MOTION_BLUR}"),
                ));
            }
            l.motion_blur_length = n as u32;
        }
        "motion_blur_timestep" => l.motion_blur_timestep = cx.num(a)?,
        "motion_blur_decay" => l.motion_blur_decay = cx.num(a)?,
        _ => return Ok(false),
    }
    st.names.push(a.name.to_string());
    f.extra_attrs
        .push((a.name.to_string(), a.value.to_string()));
    Ok(true)
}

fn positive(cx: &Ctx, a: &Attr) -> R<f64> {
    let v = cx.num(a)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(cx.err(
            a.offset,
            "XML013",
            format!("{} {v} must be positive", a.name),
        ))
    }
}

/// Once the writer is known: a flame JWildfire's renderer draws takes the settings (they leave
/// its kept attributes); for the others they stay kept, uninterpreted.
pub(super) fn settle(cx: &mut Ctx, f: &mut Flame, st: Pending) {
    if f.renders_as_jwildfire() {
        f.jwf = st.look;
        f.jwf.solid = super::jwf_solid::read(cx, &st.solid);
        f.extra_attrs.retain(|(k, _)| !st.names.contains(k));
    } else {
        for n in &st.names {
            cx.ignore(n);
        }
    }
}

/// The settings as attributes, for a flame JWildfire's renderer draws (nothing otherwise).
pub(super) fn write(s: &mut String, f: &Flame) {
    if !f.renders_as_jwildfire() {
        return;
    }
    let n = fmt_num;
    let l = &f.jwf;
    let rgb = |c: [f64; 3]| format!("{} {} {}", n(c[0]), n(c[1]), n(c[2]));
    let b = &l.background;
    let _ = write!(
        s,
        " white_level=\"{}\" low_density_brightness=\"{}\" balancing_red=\"{}\" \
         balancing_green=\"{}\" balancing_blue=\"{}\" saturation=\"{}\" fg_opacity=\"{}\" \
         antialias_amount=\"{}\" antialias_radius=\"{}\" filter_kernel=\"{}\" \
         background_type=\"{}\" background_ul=\"{}\" background_ur=\"{}\" background_ll=\"{}\" \
         background_lr=\"{}\" background_cc=\"{}\" cam_roll=\"{}\" cam_dof_scale=\"{}\" frame=\"{}\" \
         motion_blur_length=\"{}\" motion_blur_timestep=\"{}\" motion_blur_decay=\"{}\"",
        n(l.white_level),
        n(l.low_density_brightness),
        n(l.balance[0]),
        n(l.balance[1]),
        n(l.balance[2]),
        n(l.saturation),
        n(l.foreground_opacity),
        n(l.antialias_amount),
        n(l.antialias_radius),
        l.kernel.name(),
        b.kind.name(),
        rgb(b.ul),
        rgb(b.ur),
        rgb(b.ll),
        rgb(b.lr),
        rgb(b.cc),
        n(l.bank),
        n(l.dof_scale),
        n(l.frame),
        l.motion_blur_length,
        n(l.motion_blur_timestep),
        n(l.motion_blur_decay),
    );
    super::jwf_solid::write(s, &l.solid);
}

/// JWildfire's colour types, for a flame JWildfire wrote: an xform of `color_type="NONE"`
/// leaves the colour as it is, and so does a final xform that names no colour type (JWildfire
/// gives final xforms the type NONE unless the file says otherwise). Both become xforms of
/// colour speed 0; the other types keep flam3's mixing.
pub(super) fn settle_color_types(f: &mut Flame) {
    let kind = |x: &crate::flame::model::Xform| {
        x.extra_attrs
            .iter()
            .find(|(k, _)| k == "color_type")
            .map(|(_, v)| v.trim().to_string())
    };
    for x in &mut f.xforms {
        if kind(x).as_deref() == Some("NONE") {
            x.color_speed = 0.0;
        }
    }
    let finals = f.final_xform.iter_mut().chain(f.more_finals.iter_mut());
    for x in finals {
        if matches!(kind(x).as_deref(), None | Some("NONE")) {
            x.color_speed = 0.0;
        }
    }
}
