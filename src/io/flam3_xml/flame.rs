//! Reading one `<flame>`: its attributes by group (camera, tone and filter, palette, ugnis'
//! own and foreign ones), then the rules that need all of them, then its children.

use quick_xml::events::BytesStart;

use super::MAX_SIDE;
use super::anim::anim_attr;
use super::children::read_flame_children;
use super::context::{Ctx, R};
use super::palette::{PaletteData, resolve_palette};
use crate::flame::curves::{self, Curves};
use crate::flame::model::{FilterShape, Flame, FlameKind, PaletteIndex, PaletteMode};
use crate::io::diag::parse_int;
use crate::io::xml::{Attr, XmlCursor};

/// What a flame's attributes say that is settled only once all of them are read.
struct Pending {
    /// `palette="N"` of flam3's library, with its offset.
    library_palette: Option<(usize, usize)>,
    /// Hue rotation of a library palette.
    hue: f64,
    rotate_seen: bool,
    /// Apophysis' `angle` (radians), used when there is no `rotate`.
    angle: Option<f64>,
    contrast: Option<f64>,
    /// Density estimator radius, minimum and curve, and the offset to report them at.
    est: (f64, f64, f64, usize),
    /// The palette rule: ugnis' own attribute, else the writing program's (`version`).
    palette_index: Option<PaletteIndex>,
    version_index: PaletteIndex,
    palette_mode_seen: bool,
    highlight_power_seen: bool,
    smooth_gradient: Option<(String, usize)>,
    /// JWildfire's picture settings.
    jwf: super::jwf_look::Pending,
    /// JWildfire's `preserve_z` and `new_linear` (which JWildfire reads as "preserve Z" too,
    /// after `preserve_z`).
    preserve_z: Option<bool>,
    new_linear: Option<bool>,
}

/// Read a `<flame>` element whose start tag `e` is at `start`.
pub(super) fn read_flame(
    cx: &mut Ctx,
    cur: &mut XmlCursor,
    text: &str,
    e: &BytesStart,
    start: usize,
    is_empty: bool,
) -> R<Flame> {
    let attrs = cx.attrs(e, start + 1)?;
    let mut f = Flame {
        // flam3 defaults for absent attributes.
        width: 100,
        height: 100,
        scale: 50.0,
        quality: cx.opts.default_quality,
        gamma: 4.0,
        has_camera: false,
        ..Flame::default()
    };
    f.palette.name.clear();
    let mut st = Pending {
        library_palette: None,
        hue: 0.0,
        rotate_seen: false,
        angle: None,
        contrast: None,
        est: (9.0, 0.0, 0.4, start),
        palette_index: None,
        version_index: PaletteIndex::Flam3,
        palette_mode_seen: false,
        highlight_power_seen: false,
        smooth_gradient: None,
        jwf: Default::default(),
        preserve_z: None,
        new_linear: None,
    };
    for a in &attrs {
        let handled = camera_attr(cx, &mut f, &mut st, a)?
            || tone_attr(cx, &mut f, &mut st, a)?
            || palette_attr(cx, &mut f, &mut st, a)?
            || anim_attr(cx, &mut f, a)?
            || super::jwf_look::attr(cx, &mut f, &mut st.jwf, a)?;
        if !handled {
            match a.name {
                "preserve_z" => st.preserve_z = Some(a.value.trim() == "1"),
                "new_linear" => st.new_linear = Some(a.value.trim() == "1"),
                _ => other_attr(cx, &mut f, a)?,
            }
        }
    }
    settle_attrs(cx, &mut f, &mut st, start)?;
    let mut pal = PaletteData::new();
    let gradient_name = std::mem::take(&mut f.palette.name);
    if !is_empty {
        cx.jwildfire_names = st.version_index == PaletteIndex::JWildfire;
        cx.apophysis_names = st.version_index == PaletteIndex::Apophysis;
        cx.jwildfire_flame =
            st.palette_index.unwrap_or(st.version_index) == PaletteIndex::JWildfire;
        let read = read_flame_children(cx, cur, text, &mut f, &mut pal);
        cx.jwildfire_names = false;
        cx.apophysis_names = false;
        cx.jwildfire_flame = false;
        read?;
    }
    cut_xaos_rows(cx, &mut f, start);
    if st.version_index == PaletteIndex::JWildfire && st.palette_index.is_none() {
        super::jwf_look::settle_color_types(&mut f);
    }
    super::jwf_curves::read(cx, &mut f, start);
    // A template (render settings, no xform) needs no colours and no xform.
    let template = cx.opts.templates && f.xforms.is_empty();
    if !template || st.library_palette.is_some() || pal.any() {
        resolve_palette(
            cx,
            &mut f,
            pal,
            gradient_name,
            st.library_palette,
            st.hue,
            start,
        )?;
    }
    if !template {
        check_iterable(cx, &f, start)?;
    }
    Ok(f)
}

/// Size, centre, scale, rotation and the 3-D camera. False if `a` is none of them.
fn camera_attr(cx: &mut Ctx, f: &mut Flame, st: &mut Pending, a: &Attr) -> R<bool> {
    let v = &a.value;
    match a.name {
        "size" => {
            let parts: Vec<&str> = v.split_whitespace().collect();
            let ok = parts.len() == 2
                && parts
                    .iter()
                    .all(|p| parse_int(p).is_ok_and(|n| (1..=MAX_SIDE).contains(&n)));
            if !ok {
                return Err(cx.err(
                    a.offset,
                    "XML003",
                    format!("size '{v}' must be two integers between 1 and {MAX_SIDE}"),
                ));
            }
            f.width = parts[0].parse().unwrap_or(1);
            f.height = parts[1].parse().unwrap_or(1);
            f.has_camera = true;
        }
        "center" => {
            let c: [f64; 2] = cx.fixed(a, "XML003", "numbers")?;
            f.center = c;
            f.has_camera = true;
        }
        "scale" => {
            f.scale = cx.num(a)?;
            if f.scale <= 0.0 {
                return Err(cx.err(
                    a.offset,
                    "XML013",
                    format!("scale {} must be positive", f.scale),
                ));
            }
            f.has_camera = true;
        }
        "rotate" => {
            f.rotate = cx.num(a)?;
            st.rotate_seen = true;
        }
        "angle" => st.angle = Some(cx.num(a)?),
        "zoom" => f.zoom = cx.num(a)?,
        "cam_zoom" => {
            let z = cx.num(a)?;
            if !(z > 0.0 && z.is_finite()) {
                return Err(cx.err(a.offset, "XML013", format!("cam_zoom {z} must be positive")));
            }
            f.cam_zoom = z;
        }
        "cam_pitch" => f.cam.pitch = cx.num(a)?,
        "cam_yaw" => f.cam.yaw = cx.num(a)?,
        "cam_perspective" | "cam_persp" => f.cam.perspective = cx.num(a)?,
        "cam_zpos" => f.cam.zpos = cx.num(a)?,
        "cam_dof" => f.cam.dof = cx.num(a)?,
        "blur_curve" => f.cam.blur_curve = cx.num(a)?,
        _ => return Ok(false),
    }
    Ok(true)
}

/// Quality, filter, curves, background and the tone map. False if `a` is none of them.
fn tone_attr(cx: &mut Ctx, f: &mut Flame, st: &mut Pending, a: &Attr) -> R<bool> {
    let v = &a.value;
    match a.name {
        "curves" | "overall_curve" | "red_curve" | "green_curve" | "blue_curve" => {
            curve_attr(cx, f, a)?
        }
        "supersample" | "oversample" => {
            let n = cx.int(a)?;
            if !(1..=16).contains(&n) {
                return Err(cx.err(
                    a.offset,
                    "XML013",
                    format!("{} {n} must be between 1 and 16", a.name),
                ));
            }
            f.supersample = n as u32;
        }
        "filter" => {
            f.filter = cx.num(a)?;
            if f.filter < 0.0 {
                return Err(cx.err(a.offset, "XML013", "filter radius must not be negative"));
            }
        }
        "filter_shape" => match FilterShape::from_name(v.trim()) {
            Some(s) => f.filter_shape = s,
            None => cx.warn(
                a.offset,
                "XML014",
                format!("unknown filter_shape '{v}'; using gaussian"),
            ),
        },
        "quality" => {
            f.quality = cx.num(a)?;
            if f.quality <= 0.0 {
                return Err(cx.err(
                    a.offset,
                    "XML013",
                    format!("quality {} must be positive", f.quality),
                ));
            }
        }
        "background" => {
            let b: [f64; 3] = cx.fixed(a, "XML003", "numbers")?;
            f.background = b;
        }
        "brightness" => f.brightness = cx.num(a)?,
        "gamma" => {
            f.gamma = cx.num(a)?;
            if f.gamma <= 0.0 {
                return Err(cx.err(
                    a.offset,
                    "XML013",
                    format!("gamma {} must be positive", f.gamma),
                ));
            }
        }
        "gamma_threshold" => f.gamma_threshold = cx.num(a)?,
        "vibrancy" => f.vibrancy = cx.num(a)?,
        "highlight_power" => {
            f.highlight_power = cx.num(a)?;
            st.highlight_power_seen = true;
        }
        "estimator_radius" => st.est.0 = cx.num(a)?,
        "estimator_minimum" => st.est.1 = cx.num(a)?,
        "estimator_curve" => {
            st.est.2 = cx.num(a)?;
            st.est.3 = a.offset;
        }
        "contrast" => {
            if st.contrast.is_none() {
                st.contrast = Some(cx.num(a)?);
            }
        }
        "ugnis_contrast" => st.contrast = Some(cx.num(a)?),
        _ => return Ok(false),
    }
    Ok(true)
}

/// The colour curves: Fractorium's older `curves` (four curves of four x, y, weight points) or
/// one curve of x y pairs per attribute.
fn curve_attr(cx: &mut Ctx, f: &mut Flame, a: &Attr) -> R<()> {
    let v = cx.nums(a, "XML003")?;
    if a.name == "curves" {
        if v.len() != 48 {
            return Err(cx.err(
                a.offset,
                "XML003",
                format!(
                    "curves must hold 48 numbers (4 curves of 4 x y weight points), found {}",
                    v.len()
                ),
            ));
        }
        for (ci, c) in v.chunks(12).enumerate() {
            let pts = c.chunks(3).map(|p| [p[0], p[1]]).collect();
            f.curves.points[ci] = Curves::normalised(pts);
        }
        return Ok(());
    }
    if v.len() % 2 != 0 || v.len() < 4 || v.len() > 2 * curves::MAX_POINTS {
        return Err(cx.err(
            a.offset,
            "XML003",
            format!(
                "{} must hold 2 to {} x y pairs, found {} numbers",
                a.name,
                curves::MAX_POINTS,
                v.len()
            ),
        ));
    }
    let ci = ["overall_curve", "red_curve", "green_curve", "blue_curve"]
        .iter()
        .position(|n| *n == a.name)
        .unwrap_or(0);
    f.curves.points[ci] = Curves::normalised(v.chunks(2).map(|p| [p[0], p[1]]).collect());
    Ok(())
}

/// The palette: flam3's library number and hue, the palette mode and index rule, the writing
/// program, the gradient's name. False if `a` is none of them.
fn palette_attr(cx: &mut Ctx, f: &mut Flame, st: &mut Pending, a: &Attr) -> R<bool> {
    let v = &a.value;
    match a.name {
        "version" => st.version_index = PaletteIndex::from_version(v),
        "ugnis_palette_index" => match PaletteIndex::from_name(v.trim()) {
            Some(m) => st.palette_index = Some(m),
            None => {
                return Err(cx.err(
                    a.offset,
                    "FLA004",
                    format!(
                        "ugnis_palette_index '{v}' must be 'flam3', 'apophysis', 'fractorium' or 'jwildfire'"
                    ),
                ));
            }
        },
        // JWildfire's interpolated gradient; honoured for JWildfire's files (below) and
        // written back either way.
        "smooth_gradient" => {
            st.smooth_gradient = Some((v.trim().to_string(), a.offset));
            f.extra_attrs.push((a.name.to_string(), v.to_string()));
        }
        "hue" => st.hue = cx.num(a)?.rem_euclid(1.0),
        "palette_mode" => match PaletteMode::from_name(v.trim()) {
            Some(m) => {
                f.palette_mode = m;
                st.palette_mode_seen = true;
            }
            None => cx.warn(
                a.offset,
                "XML014",
                format!("unknown palette_mode '{v}'; using step"),
            ),
        },
        "palette" => {
            let n = cx.int(a)?;
            if !(0..=700).contains(&n) {
                return Err(cx.err(
                    a.offset,
                    "XML011",
                    format!("palette number {n} is outside 0..700"),
                ));
            }
            st.library_palette = Some((n as usize, a.offset));
        }
        "ugnis_gradient" => f.palette.name = v.to_string(),
        _ => return Ok(false),
    }
    Ok(true)
}

/// The name, the solo xform, ugnis' own attributes, and anything else (kept as it stands).
fn other_attr(cx: &mut Ctx, f: &mut Flame, a: &Attr) -> R<()> {
    let v = &a.value;
    match a.name {
        "name" => {
            if v.len() > 64 {
                cx.warn(
                    a.offset,
                    "XML016",
                    "flame name longer than 64 bytes (flam3 truncates it)",
                );
            }
            f.name = v.to_string();
        }
        "soloxform" => {
            let n = cx.num(a)?;
            f.solo_xform = if n >= 0.0 { Some(n as usize) } else { None };
        }
        "ugnis_seed" => {
            f.seed = Some(v.trim().parse::<u64>().map_err(|_| {
                cx.err(
                    a.offset,
                    "FLA004",
                    format!("ugnis_seed '{v}' must be an unsigned 64-bit integer"),
                )
            })?)
        }
        "ugnis_kind" => {
            f.kind = match v.trim() {
                "flame" => FlameKind::Flame,
                "ifs" => FlameKind::Ifs,
                other => {
                    return Err(cx.err(
                        a.offset,
                        "FLA004",
                        format!("ugnis_kind '{other}' must be 'flame' or 'ifs'"),
                    ));
                }
            }
        }
        "ugnis_auto_weights" => {
            f.auto_weights = match v.trim() {
                "0" => Some(false),
                "1" => Some(true),
                other => {
                    return Err(cx.err(
                        a.offset,
                        "FLA004",
                        format!("ugnis_auto_weights '{other}' must be 0 or 1"),
                    ));
                }
            }
        }
        other => {
            if other.starts_with("ugnis_") {
                cx.warn(
                    a.offset,
                    "FLA005",
                    format!("unknown attribute '{other}' kept"),
                );
            } else {
                cx.ignore(other);
            }
            f.extra_attrs.push((other.to_string(), v.to_string()));
        }
    }
    Ok(())
}

/// The rules that need all attributes: `angle` without `rotate`, the palette index rule,
/// JWildfire's picture settings and smooth gradient, the contrast and the density estimator.
fn settle_attrs(cx: &mut Ctx, f: &mut Flame, st: &mut Pending, start: usize) -> R<()> {
    if !st.rotate_seen
        && let Some(ang) = st.angle
    {
        f.rotate = -ang.to_degrees();
    }
    f.palette_index = st.palette_index.unwrap_or(st.version_index);
    // Fractorium's defaults for what its file leaves out differ from flam3's: a linear
    // palette and highlight power 1.
    if f.palette_index == PaletteIndex::Fractorium {
        if !st.palette_mode_seen {
            f.palette_mode = PaletteMode::Linear;
        }
        if !st.highlight_power_seen {
            f.highlight_power = 1.0;
        }
    }
    super::jwf_look::settle(cx, f, std::mem::take(&mut st.jwf));
    // JWildfire reads `new_linear` as its "preserve Z" (after `preserve_z`); for flam3 it says
    // that linear is 2-D, as ugnis' linear is.
    f.preserve_z = st.preserve_z.unwrap_or(false);
    if f.palette_index == PaletteIndex::JWildfire
        && let Some(on) = st.new_linear
    {
        f.preserve_z = on;
    }
    if let Some((v, _)) = &st.smooth_gradient {
        if f.palette_index == PaletteIndex::JWildfire {
            if !st.palette_mode_seen && matches!(v.as_str(), "1" | "true") {
                f.palette_mode = PaletteMode::Linear;
            }
        } else {
            cx.ignore("smooth_gradient");
        }
    }
    if let Some(c) = st.contrast {
        if c <= 0.0 {
            return Err(cx.err(start, "XML013", format!("contrast {c} must be positive")));
        }
        f.contrast = c;
    }
    let (r, m, k, koff) = st.est;
    if !(r >= m && m >= 0.0 && k > 0.0) {
        return Err(cx.err(
            koff,
            "XML012",
            format!("estimator_radius {r} must be ≥ estimator_minimum {m} ≥ 0, and estimator_curve {k} > 0"),
        ));
    }
    (f.estimator_radius, f.estimator_minimum, f.estimator_curve) = (r, m, k);
    Ok(())
}

/// A xaos row has one multiplier per xform; longer rows (written for a flame that had more
/// xforms) are cut, with a word.
fn cut_xaos_rows(cx: &mut Ctx, f: &mut Flame, start: usize) {
    let n = f.xforms.len();
    for (k, x) in f.xforms.iter_mut().enumerate() {
        if x.chaos.len() > n {
            let extra = x.chaos.len() - n;
            x.chaos.truncate(n);
            cx.warn(
                start,
                "XML022",
                format!(
                    "xaos row of xform {} has {} values for {n} xforms; the last {extra} are ignored",
                    k + 1,
                    n + extra
                ),
            );
        }
    }
}

/// A flame needs an xform with a positive weight.
fn check_iterable(cx: &Ctx, f: &Flame, start: usize) -> R<()> {
    if f.xforms.is_empty() {
        return Err(cx.err(
            start,
            "XML007",
            "cannot iterate empty flame: it has no <xform>",
        ));
    }
    if f.xforms.iter().all(|x| x.weight == 0.0) {
        return Err(cx.err(
            start,
            "XML007",
            "cannot iterate empty flame: all xform weights are 0",
        ));
    }
    Ok(())
}
