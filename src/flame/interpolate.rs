//! In-betweens of flames exactly as flam3 3.1.1 computes them, so that a sequence file renders
//! in ugnis as `flam3-animate` renders it and a loop made here is the one `flam3-genome
//! sequence=` makes:
//!
//! - [`interpolate_at`]: the flame at any time of a sequence of control points (flam3's
//!   `flam3_interpolate`): linear between the two control points around the time (beyond the
//!   ends it extrapolates the first or last segment), or Catmull-Rom through four.
//! - Alignment (`flam3_align`): control points with fewer xforms are padded with weight-0
//!   xforms chosen to match their partners (a spherical partner gets a linear −1 rotated by
//!   180°, a fan or rings partner a swapped identity, …), and a variation's parameters are
//!   carried over where only one side uses it, so that nothing jumps.
//! - Affine maps blend linearly or, with `interpolation_type="log"`, column by column in polar
//!   form (the angle linearly along the shorter turn, the length logarithmically).
//! - Palettes blend in HSV (hue the shorter way round), RGB, a mix of the two, or sweep.
//!
//! flam3-genome's loops and transitions, built on these, are in the `loops` module.

use std::f64::consts::PI;

use crate::flame::model::{Affine, Flame, Var, Xform};
use crate::flame::sequence::{Interpolation, InterpolationType, PaletteInterpolation};
use crate::flame::variations::{self, Form, VarId};
use crate::gradient::{Gradient, hsv_to_rgb, rgb_to_hsv};

/// flam3's tolerance at the ±π seam of angles.
pub(crate) const EPS: f64 = 1e-10;

/// One xform of a control point being blended, with what flam3 keeps beside it.
#[derive(Clone, Debug)]
pub(crate) struct Slot {
    pub(crate) x: Xform,
    /// Added by alignment to match another control point.
    pub(crate) padding: bool,
    /// Reference angle per column for xforms that do not turn on one side of a transition
    /// (0: none).
    pub(crate) wind: [f64; 2],
}

/// A control point: the flame's settings and its xforms, the final one (if any) last.
#[derive(Clone, Debug)]
pub(crate) struct Cp {
    pub(crate) flame: Flame,
    pub(crate) slots: Vec<Slot>,
    pub(crate) has_final: bool,
}

impl Cp {
    pub(crate) fn new(f: &Flame) -> Cp {
        let slot = |x: &Xform| Slot {
            x: x.clone(),
            padding: false,
            wind: [0.0; 2],
        };
        let mut slots: Vec<Slot> = f.xforms.iter().map(slot).collect();
        if let Some(fx) = &f.final_xform {
            slots.push(slot(fx));
        }
        let mut flame = f.clone();
        flame.xforms = Vec::new();
        flame.final_xform = None;
        Cp {
            flame,
            slots,
            has_final: f.final_xform.is_some(),
        }
    }

    fn n_std(&self) -> usize {
        self.slots.len() - self.has_final as usize
    }

    pub(crate) fn into_flame(self) -> Flame {
        let mut f = self.flame;
        let mut xs: Vec<Xform> = self.slots.into_iter().map(|s| s.x).collect();
        f.final_xform = if self.has_final { xs.pop() } else { None };
        f.xforms = xs;
        f
    }
}

/// A new xform as flam3 makes one for padding: weight 0, identity maps, linear 1, colour by
/// the parity of its index.
fn padding_xform(index: usize) -> Xform {
    Xform {
        weight: 0.0,
        color: (index & 1) as f64,
        color_speed: 0.5,
        opacity: 1.0,
        animate: 1.0,
        ..Xform::default()
    }
}

fn var_id(name: &str) -> VarId {
    variations::by_name(name).unwrap_or_else(|| panic!("variation {name} is registered"))
}

fn regular(x: &Xform, id: VarId) -> Option<&Var> {
    x.vars
        .iter()
        .find(|v| v.id == id && v.form == Form::Regular)
}

fn weight_of(x: &Xform, id: VarId) -> f64 {
    regular(x, id).map_or(0.0, |v| v.weight)
}

/// Set a regular variation's weight, adding it with its default parameters when absent.
fn set_weight(x: &mut Xform, id: VarId, w: f64) {
    match x
        .vars
        .iter_mut()
        .find(|v| v.id == id && v.form == Form::Regular)
    {
        Some(v) => v.weight = w,
        None => x.vars.push(Var::new(id, w)),
    }
}

fn set_param(x: &mut Xform, id: VarId, name: &str, value: f64) {
    let k = variations::info(id)
        .params
        .iter()
        .position(|p| p.name == name)
        .unwrap_or_else(|| panic!("{name} is a parameter"));
    if let Some(v) = x
        .vars
        .iter_mut()
        .find(|v| v.id == id && v.form == Form::Regular)
    {
        v.params[k] = value;
    }
}

/// flam3's `flam3_align`: copies of the control points with equally many xforms (and a final
/// xform in all or none), padding xforms made to match their neighbours, and the parameters of
/// a variation used on one side only carried to the other.
pub(crate) fn align(src: &[&Cp]) -> Vec<Cp> {
    let max_nx = src.iter().map(|c| c.n_std()).max().unwrap_or(0);
    let max_fx = src.iter().any(|c| c.has_final);
    let already_aligned = src
        .iter()
        .all(|c| c.n_std() == src[0].n_std() && c.has_final == src[0].has_final);
    let mut dst: Vec<Cp> = src.iter().map(|c| pad(c, max_nx, max_fx)).collect();
    let reference = dst[(src.len() / 2).saturating_sub(1)]
        .flame
        .anim
        .interpolation_type;
    if matches!(
        reference,
        InterpolationType::Compat | InterpolationType::Older
    ) {
        return dst;
    }
    let n = dst.len();
    for i in 0..n {
        for xf in 0..dst[i].slots.len() {
            carry_parameters(&mut dst, i, xf);
            if dst[i].slots[xf].padding && !already_aligned {
                let log = if i == 0 {
                    dst[0].flame.anim.interpolation_type == InterpolationType::Log
                } else {
                    dst[i - 1].flame.anim.interpolation_type == InterpolationType::Log
                };
                let partners: Vec<Xform> = [i.checked_sub(1), Some(i + 1)]
                    .into_iter()
                    .flatten()
                    .filter(|&k| k < n && !dst[k].slots[xf].padding)
                    .map(|k| dst[k].slots[xf].x.clone())
                    .collect();
                match_padding(&mut dst[i].slots[xf].x, &partners, log);
            }
        }
    }
    dst
}

/// flam3's `flam3_copyx`: the control point with `n_std` standard xforms (new ones are
/// padding) and, when `with_final`, a final xform (an identity that keeps the colour when the
/// control point has none).
fn pad(c: &Cp, n_std: usize, with_final: bool) -> Cp {
    let mut slots: Vec<Slot> = (0..n_std)
        .map(|i| match c.slots.get(i).filter(|_| i < c.n_std()) {
            Some(s) => s.clone(),
            None => Slot {
                x: padding_xform(i),
                padding: true,
                wind: [0.0; 2],
            },
        })
        .collect();
    if with_final {
        let fin = if c.has_final {
            c.slots[c.slots.len() - 1].clone()
        } else {
            Slot {
                x: Xform {
                    animate: 0.0,
                    color_speed: 0.0,
                    ..padding_xform(n_std)
                },
                padding: true,
                wind: [0.0; 2],
            }
        };
        slots.push(fin);
    }
    Cp {
        flame: c.flame.clone(),
        slots,
        has_final: with_final,
    }
}

/// Where control point `i` lacks a variation with parameters that its previous control point
/// uses (for the first, its next), it takes that neighbour's parameters (at weight 0), so the
/// parameters do not move while the weight fades.
fn carry_parameters(dst: &mut [Cp], i: usize, xf: usize) {
    let neighbour = if i > 0 {
        i - 1
    } else if dst.len() > 1 {
        1
    } else {
        return;
    };
    let theirs: Vec<Var> = dst[neighbour].slots[xf]
        .x
        .vars
        .iter()
        .filter(|v| v.weight != 0.0 && !v.params.is_empty())
        .cloned()
        .collect();
    let mine = &mut dst[i].slots[xf].x.vars;
    for v in theirs {
        match mine.iter_mut().find(|w| w.id == v.id && w.form == v.form) {
            Some(w) if w.weight != 0.0 => {}
            Some(w) => w.params = v.params,
            None => mine.push(Var { weight: 0.0, ..v }),
        }
    }
}

/// flam3's choice of a padding xform that starts where its partners (the non-padding xforms
/// of the neighbouring control points in the same slot) are, so a new xform grows out of
/// nothing visible.
fn match_padding(x: &mut Xform, partners: &[Xform], log: bool) {
    let linear = var_id("linear");
    x.vars
        .retain(|v| !(v.id == linear && v.form == Form::Regular));
    let has = |name: &str| partners.iter().any(|p| weight_of(p, var_id(name)) > 0.0);
    // Variations with holes meet a 180°-turned identity of weight −1.
    const HOLES: [&str; 7] = [
        "spherical",
        "ngon",
        "julian",
        "juliascope",
        "polar",
        "wedge_sph",
        "wedge_julia",
    ];
    if log && HOLES.iter().any(|n| has(n)) {
        set_weight(x, linear, -1.0);
        x.coefs = Affine::new(-1.0, 0.0, 0.0, -1.0, 0.0, 0.0);
        return;
    }
    // Parametric variations whose parameters make them the identity.
    let mut found = 0;
    for p in partners {
        let mut take = |name: &str, params: &[(&str, f64)]| {
            let id = var_id(name);
            if weight_of(p, id) > 0.0 {
                set_weight(x, id, 1.0);
                for (k, v) in params {
                    set_param(x, id, k, *v);
                }
                found += 1;
            }
        };
        take(
            "rectangles",
            &[("rectangles_x", 0.0), ("rectangles_y", 0.0)],
        );
        take("rings2", &[("rings2_val", 0.0)]);
        take("fan2", &[("fan2_x", 0.0), ("fan2_y", 0.0)]);
        take(
            "blob",
            &[("blob_low", 1.0), ("blob_high", 1.0), ("blob_waves", 1.0)],
        );
        take("perspective", &[("perspective_angle", 0.0)]);
        take("curl", &[("curl_c1", 0.0), ("curl_c2", 0.0)]);
        take(
            "super_shape",
            &[
                ("super_shape_n1", 2.0),
                ("super_shape_n2", 2.0),
                ("super_shape_n3", 2.0),
                ("super_shape_rnd", 0.0),
                ("super_shape_holes", 0.0),
            ],
        );
    }
    // Fan and rings meet the identity with x and y swapped.
    if found == 0 {
        for p in partners {
            for name in ["fan", "rings"] {
                let id = var_id(name);
                if weight_of(p, id) > 0.0 {
                    set_weight(x, id, 1.0);
                    found += 1;
                }
            }
        }
        if found > 0 {
            x.coefs = Affine::new(0.0, 1.0, 1.0, 0.0, 0.0, 0.0);
        }
    }
    if found == 0 {
        set_weight(x, linear, 1.0);
    } else {
        let total: f64 = x.vars.iter().map(|v| v.weight).sum();
        for v in &mut x.vars {
            v.weight /= total;
        }
    }
}

fn lerp_sum(c: &[f64], vals: impl Iterator<Item = f64>) -> f64 {
    c.iter().zip(vals).map(|(c, v)| c * v).sum()
}

/// flam3's `INTERI`: the weighted sum rounded half to even.
fn lerp_int(c: &[f64], vals: impl Iterator<Item = f64>) -> f64 {
    lerp_sum(c, vals).round_ties_even()
}

/// flam3's `interpolate_n`: the blend of aligned control points with weights `c`.
fn blend(cpi: &[Cp], c: &[f64], stagger: f64) -> Cp {
    let first = &cpi[0].flame;
    let mut f = first.clone();
    macro_rules! mix {
        ($($field:tt)+) => {
            lerp_sum(c, cpi.iter().map(|k| k.flame.$($field)+))
        };
    }
    f.palette = blend_palettes(cpi, c);
    f.palette_hires = None;
    f.brightness = mix!(brightness);
    f.contrast = mix!(contrast);
    f.highlight_power = mix!(highlight_power);
    f.gamma = mix!(gamma);
    f.vibrancy = mix!(vibrancy);
    f.width = lerp_int(c, cpi.iter().map(|k| k.flame.width as f64)).max(1.0) as u32;
    f.height = lerp_int(c, cpi.iter().map(|k| k.flame.height as f64)).max(1.0) as u32;
    f.supersample = lerp_int(c, cpi.iter().map(|k| k.flame.supersample as f64)).max(1.0) as u32;
    f.center = [mix!(center[0]), mix!(center[1])];
    f.background = [
        mix!(background[0]),
        mix!(background[1]),
        mix!(background[2]),
    ];
    f.scale = mix!(scale);
    f.filter = mix!(filter);
    f.anim.temporal_filter_exp = mix!(anim.temporal_filter_exp);
    f.anim.temporal_filter_width = mix!(anim.temporal_filter_width);
    f.quality = mix!(quality);
    f.zoom = mix!(zoom);
    f.rotate = mix!(rotate);
    f.anim.temporal_samples =
        lerp_int(c, cpi.iter().map(|k| k.flame.anim.temporal_samples as f64)).max(1.0) as u32;
    f.estimator_radius = mix!(estimator_radius);
    f.estimator_minimum = mix!(estimator_minimum);
    f.estimator_curve = mix!(estimator_curve);
    f.gamma_threshold = mix!(gamma_threshold);
    // Beyond flam3: the 3-D camera and JWildfire's zoom blend linearly too.
    f.cam_zoom = mix!(cam_zoom);
    f.cam.pitch = mix!(cam.pitch);
    f.cam.yaw = mix!(cam.yaw);
    f.cam.perspective = mix!(cam.perspective);
    f.cam.zpos = mix!(cam.zpos);
    f.cam.dof = mix!(cam.dof);
    f.cam.blur_curve = mix!(cam.blur_curve);

    let n_std = cpi[0].n_std();
    let mut slots = Vec::with_capacity(cpi[0].slots.len());
    for i in 0..cpi[0].slots.len() {
        let is_final = cpi[0].has_final && i == cpi[0].slots.len() - 1;
        let staggered;
        let ci: &[f64] = if cpi.len() == 2 && stagger > 0.0 && !is_final {
            let c0 = stagger_coef(c[0], stagger, n_std, i);
            staggered = [c0, 1.0 - c0];
            &staggered
        } else {
            c
        };
        let mut x = blend_xform(cpi, ci, i);
        if !is_final {
            // The xaos matrix blends with the flame's weights, never staggered ones.
            x.chaos = (0..n_std)
                .map(|j| lerp_sum(c, cpi.iter().map(|k| k.slots[i].x.chaos_to(j))).max(0.0))
                .collect();
            // Missing entries are 1.
            while x.chaos.last() == Some(&1.0) {
                x.chaos.pop();
            }
        }
        slots.push(Slot {
            x,
            padding: false,
            wind: [0.0; 2],
        });
    }
    Cp {
        flame: f,
        slots,
        has_final: cpi[0].has_final,
    }
}

/// One xform of the blend.
fn blend_xform(cpi: &[Cp], c: &[f64], i: usize) -> Xform {
    let xs: Vec<&Xform> = cpi.iter().map(|k| &k.slots[i].x).collect();
    let mix = |get: &dyn Fn(&Xform) -> f64| lerp_sum(c, xs.iter().map(|x| get(x)));
    let mut x = xs[0].clone();
    x.weight = mix(&|x| x.weight).max(0.0);
    x.color = mix(&|x| x.color).clamp(0.0, 1.0);
    x.color_speed = mix(&|x| x.color_speed).clamp(0.0, 1.0);
    x.opacity = mix(&|x| x.opacity);
    x.animate = mix(&|x| x.animate);
    x.direct_color = mix(&|x| x.direct_color);
    x.motion = Vec::new();
    x.vars = blend_vars(&xs, c);
    let log = cpi[0].flame.anim.interpolation_type == InterpolationType::Log;
    let winds: Vec<[f64; 2]> = cpi.iter().map(|k| k.slots[i].wind).collect();
    let coefs: Vec<Affine> = xs.iter().map(|x| x.coefs).collect();
    let posts: Vec<Affine> = xs.iter().map(|x| x.post).collect();
    x.coefs = if log {
        blend_polar(&coefs, &winds, c)
    } else {
        blend_linear(&coefs, c)
    };
    x.post = if posts.iter().all(Affine::is_identity) {
        Affine::IDENTITY
    } else if log {
        // Reference angles steer only the pre-affine maps.
        blend_polar(&posts, &vec![[0.0; 2]; posts.len()], c)
    } else {
        blend_linear(&posts, c)
    };
    x
}

/// Variation weights and parameters blended over the union of the variations used (a
/// variation used twice in an xform, as JWildfire allows, pairs its first uses, then its
/// second ones); a control point without a variation counts weight 0 and the variation's
/// default parameters.
fn blend_vars(xs: &[&Xform], c: &[f64]) -> Vec<Var> {
    // (variation, form, which use of it in the xform).
    let mut keys: Vec<(VarId, Form, usize)> = Vec::new();
    for x in xs {
        for (i, v) in x.vars.iter().enumerate() {
            let k = x.vars[..i]
                .iter()
                .filter(|u| u.id == v.id && u.form == v.form)
                .count();
            if !keys.contains(&(v.id, v.form, k)) {
                keys.push((v.id, v.form, k));
            }
        }
    }
    let mut out = Vec::with_capacity(keys.len());
    for (id, form, k) in keys {
        let found: Vec<Option<&Var>> = xs
            .iter()
            .map(|x| {
                x.vars
                    .iter()
                    .filter(|v| v.id == id && v.form == form)
                    .nth(k)
            })
            .collect();
        let weight = lerp_sum(c, found.iter().map(|v| v.map_or(0.0, |v| v.weight)));
        if weight == 0.0 {
            continue;
        }
        let defaults = variations::absent_params(id);
        let params = (0..defaults.len())
            .map(|k| {
                lerp_sum(
                    c,
                    found.iter().map(|v| {
                        v.and_then(|v| v.params.get(k).copied())
                            .unwrap_or(defaults[k])
                    }),
                )
            })
            .collect();
        let texts = found
            .iter()
            .flatten()
            .next()
            .map(|v| v.texts.clone())
            .unwrap_or_default();
        out.push(Var {
            id,
            form,
            weight,
            params,
            texts,
        });
    }
    out
}

fn blend_linear(m: &[Affine], c: &[f64]) -> Affine {
    let mix = |get: fn(&Affine) -> f64| lerp_sum(c, m.iter().map(get));
    Affine {
        a: mix(|m| m.a),
        b: mix(|m| m.b),
        c: mix(|m| m.c),
        d: mix(|m| m.d),
        e: mix(|m| m.e),
        f: mix(|m| m.f),
    }
}

/// The columns of an affine map's linear part, flam3's `c[0]` = (a, c) and `c[1]` = (b, d).
pub(crate) fn columns(m: &Affine) -> [[f64; 2]; 2] {
    [[m.a, m.c], [m.b, m.d]]
}

/// flam3's log interpolation (`convert_linear_to_polar` and `interp_and_convert_back`): each
/// column as angle and length; angles made continuous along the sequence (within a reference
/// window for xforms that turn on one side only); lengths blended as logarithms unless one is
/// below e^−10; translation linearly.
fn blend_polar(m: &[Affine], wind: &[[f64; 2]], c: &[f64]) -> Affine {
    if let Some(k) = unit_weight(c) {
        return m[k];
    }
    let n = m.len();
    let mut ang = vec![[0.0f64; 2]; n];
    let mut mag = vec![[0.0f64; 2]; n];
    for k in 0..n {
        let cols = columns(&m[k]);
        let mut zero = [false; 2];
        for col in 0..2 {
            ang[k][col] = cols[col][1].atan2(cols[col][0]);
            mag[k][col] = (cols[col][0] * cols[col][0] + cols[col][1] * cols[col][1]).sqrt();
            zero[col] = mag[k][col] == 0.0;
        }
        if zero[0] && !zero[1] {
            ang[k][0] = ang[k][1];
        } else if !zero[0] && zero[1] {
            ang[k][1] = ang[k][0];
        }
    }
    for col in 0..2 {
        for k in 1..n {
            if wind[k][col] > 0.0 {
                let refang = wind[k][col] - 2.0 * PI;
                for a in [k - 1, k] {
                    while ang[a][col] < refang {
                        ang[a][col] += 2.0 * PI;
                    }
                    while ang[a][col] > refang + 2.0 * PI {
                        ang[a][col] -= 2.0 * PI;
                    }
                }
            } else {
                let d = ang[k][col] - ang[k - 1][col];
                if d > PI + EPS {
                    ang[k][col] -= 2.0 * PI;
                } else if d < -(PI - EPS) {
                    ang[k][col] += 2.0 * PI;
                }
            }
        }
    }
    let mut out = [[0.0f64; 2]; 2];
    for col in 0..2 {
        let linear = mag.iter().any(|mg| mg[col].ln() < -10.0);
        let a = lerp_sum(c, ang.iter().map(|a| a[col]));
        let r = if linear {
            lerp_sum(c, mag.iter().map(|mg| mg[col]))
        } else {
            lerp_sum(c, mag.iter().map(|mg| mg[col].ln())).exp()
        };
        out[col] = [r * a.cos(), r * a.sin()];
    }
    Affine {
        a: out[0][0],
        c: out[0][1],
        b: out[1][0],
        d: out[1][1],
        e: lerp_sum(c, m.iter().map(|m| m.e)),
        f: lerp_sum(c, m.iter().map(|m| m.f)),
    }
}

/// The control point whose weight is 1 when all others are 0: the blend is that control point
/// itself, exactly (round trips through HSV or polar form would change the last bits).
fn unit_weight(c: &[f64]) -> Option<usize> {
    let k = c.iter().position(|&w| w == 1.0)?;
    c.iter()
        .enumerate()
        .all(|(i, &w)| i == k || w == 0.0)
        .then_some(k)
}

/// flam3's palette blend, entry by entry.
fn blend_palettes(cpi: &[Cp], c: &[f64]) -> Gradient {
    if let Some(k) = unit_weight(c) {
        return cpi[k].flame.palette.clone();
    }
    let mode = cpi[0].flame.anim.palette_interpolation;
    let entry = |k: usize, i: usize| -> [f64; 4] {
        cpi[k]
            .flame
            .palette
            .colors
            .get(i)
            .copied()
            .unwrap_or([0.0, 0.0, 0.0, 1.0])
    };
    let mut colors = Vec::with_capacity(256);
    if mode == PaletteInterpolation::Sweep {
        for i in 0..256 {
            let k = if (i as f64) < 256.0 * c[0] { 0 } else { 1 };
            colors.push(entry(k.min(cpi.len() - 1), i));
        }
    } else {
        let rgb_fraction = match mode {
            PaletteInterpolation::Rgb => 1.0,
            PaletteInterpolation::HsvCircular => cpi[0].flame.anim.hsv_rgb_palette_blend,
            _ => 0.0,
        };
        for i in 0..256 {
            let mut rgb = [0.0; 3];
            let mut hsv = [0.0; 3];
            let mut alpha = 0.0;
            let mut all_opaque = true;
            for (k, ck) in c.iter().enumerate() {
                let col = entry(k, i);
                let mut h = rgb_to_hsv([col[0], col[1], col[2]]);
                if cpi.len() == 2 && k == 0 && mode == PaletteInterpolation::HsvCircular {
                    let other = entry(1, i);
                    let second = rgb_to_hsv([other[0], other[1], other[2]]);
                    if second[0] - h[0] > 3.0 {
                        h[0] += 6.0;
                    } else if second[0] - h[0] < -3.0 {
                        h[0] -= 6.0;
                    }
                }
                for j in 0..3 {
                    rgb[j] += ck * col[j];
                    hsv[j] += ck * h[j];
                }
                alpha += ck * col[3];
                all_opaque &= col[3] == 1.0;
            }
            if all_opaque {
                alpha = 1.0;
            }
            let back = hsv_to_rgb(hsv);
            let mut out = [0.0; 4];
            for j in 0..3 {
                out[j] = rgb_fraction * rgb[j] + (1.0 - rgb_fraction) * back[j];
            }
            out[3] = alpha;
            colors.push(out.map(|v| v.clamp(0.0, 1.0)));
        }
    }
    Gradient {
        name: cpi[0].flame.palette.name.clone(),
        colors,
        stops: Vec::new(),
        map_entries: None,
    }
}

/// flam3's smooth step 3t² − 2t³.
pub fn smoother(t: f64) -> f64 {
    3.0 * t * t - 2.0 * t * t * t
}

/// flam3's `get_stagger_coef`: with stagger, xform `i` of `n` blends within its own part of the
/// transition, the last xform first.
fn stagger_coef(t: f64, stagger: f64, n: usize, i: usize) -> f64 {
    if n <= 1 {
        return t;
    }
    let max_stag = (n - 1) as f64 / n as f64;
    let scaled = stagger * max_stag;
    let st = scaled * (n - 1 - i.min(n - 1)) as f64 / (n - 1) as f64;
    let et = st + (1.0 - scaled);
    if t <= st {
        0.0
    } else if t >= et {
        1.0
    } else {
        smoother((t - st) / (1.0 - scaled))
    }
}

/// Are a sequence's control points in strictly increasing time order? Returns the index of the
/// first one that is not (or whose time is not a number).
pub fn check_times(cps: &[Flame]) -> Result<(), usize> {
    for (i, f) in cps.iter().enumerate() {
        if !f.anim.time.is_finite() || (i > 0 && f.anim.time <= cps[i - 1].anim.time) {
            return Err(i);
        }
    }
    Ok(())
}

/// The flame at `time` of a sequence of control points sorted by time (flam3's
/// `flam3_interpolate`). Outside the sequence the first or last segment is extrapolated, as
/// flam3 does for the sub-frames of a motion-blurred first or last frame.
pub fn interpolate_at(cps: &[Flame], time: f64) -> Flame {
    assert!(!cps.is_empty(), "a sequence has at least one flame");
    if cps.len() == 1 {
        let mut one = cps[0].clone();
        one.anim.time = time;
        return one;
    }
    // Only the control points the blend reads are prepared.
    let (i1, i2) = segment(cps.len(), |i| cps[i].anim.time, time);
    let lo = i1.saturating_sub(1);
    let hi = (i2 + 1).min(cps.len() - 1);
    let turns = unwrapped_rotations(&cps[..=hi]);
    let window: Vec<Cp> = cps[lo..=hi]
        .iter()
        .zip(&turns[lo..])
        .map(|(f, &rotate)| {
            let mut cp = Cp::new(f);
            cp.flame.rotate = rotate;
            cp
        })
        .collect();
    interpolate_cps(&window, time, 0.0).into_flame()
}

/// The control points' camera rotations as flam3 reads a sequence: each shifted by whole turns
/// to lie within 180° of the one before (so 350° after 10° turns back by 20°, not forward by
/// 340°), except after a control point of the `compat` or `older` interpolation types.
pub fn unwrapped_rotations(cps: &[Flame]) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::with_capacity(cps.len());
    for (i, f) in cps.iter().enumerate() {
        let mut r = f.rotate;
        if let Some(&prev) = out.last()
            && !matches!(
                cps[i - 1].anim.interpolation_type,
                InterpolationType::Compat | InterpolationType::Older
            )
            // Beyond a billion degrees whole turns are lost to rounding: left as written.
            && (r - prev).abs() < 1e9
        {
            // flam3 adds or takes 360° until within range; whole turns toward the previous
            // angle first (truncated, as those loops would stop), so huge angles cost no time.
            r -= 360.0 * ((r - prev) / 360.0).trunc();
            while r < prev - 180.0 {
                r += 360.0;
            }
            while r > prev + 180.0 {
                r -= 360.0;
            }
        }
        out.push(r);
    }
    out
}

/// The control points (i1, i2) around `time` (the first or last segment outside the sequence).
fn segment(n: usize, t: impl Fn(usize) -> f64, time: f64) -> (usize, usize) {
    if t(0) >= time {
        (0, 1)
    } else if t(n - 1) <= time {
        (n - 2, n - 1)
    } else {
        let mut i = 0;
        while t(i) < time {
            i += 1;
        }
        (i - 1, i)
    }
}

pub(crate) fn interpolate_cps(cps: &[Cp], time: f64, stagger: f64) -> Cp {
    assert!(!cps.is_empty(), "a sequence has at least one flame");
    if cps.len() == 1 {
        let mut one = cps[0].clone();
        // A copy keeps its padding flags only while being blended.
        for s in &mut one.slots {
            s.padding = false;
        }
        return one;
    }
    let n = cps.len();
    let t = |i: usize| cps[i].flame.anim.time;
    let (i1, i2) = segment(n, t, time);
    let c0 = (t(i2) - time) / (t(i2) - t(i1));
    let c = [c0, 1.0 - c0];
    let smooth = cps[i1].flame.anim.interpolation == Interpolation::Smooth && i1 > 0 && i2 < n - 1;
    let mut out = if smooth {
        let cpi = align(&[&cps[i1 - 1], &cps[i1], &cps[i2], &cps[i2 + 1]]);
        blend(&cpi, &catmull_rom(c[1]), 0.0)
    } else {
        let cpi = align(&[&cps[i1], &cps[i2]]);
        blend(&cpi, &c, stagger)
    };
    out.flame.anim.time = time;
    out.flame.anim.interpolation = Interpolation::Linear;
    out
}

/// Catmull-Rom weights of four control points at `t` of the middle segment.
fn catmull_rom(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        (2.0 * t2 - t - t3) / 2.0,
        (3.0 * t3 - 5.0 * t2 + 2.0) / 2.0,
        (4.0 * t2 - 3.0 * t3 + t) / 2.0,
        (t3 - t2) / 2.0,
    ]
}

#[cfg(test)]
#[path = "interpolate_tests.rs"]
mod tests;
