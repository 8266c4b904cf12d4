//! The blend of aligned control points: settings, xforms, variations, affine maps (linear or
//! polar) and palettes, each as flam3 mixes it.

use std::f64::consts::PI;

use super::*;
use crate::flame::sequence::PaletteInterpolation;
use crate::gradient::{Gradient, hsv_to_rgb, rgb_to_hsv};

fn lerp_sum(c: &[f64], vals: impl Iterator<Item = f64>) -> f64 {
    c.iter().zip(vals).map(|(c, v)| c * v).sum()
}

/// flam3's `INTERI`: the weighted sum rounded half to even.
fn lerp_int(c: &[f64], vals: impl Iterator<Item = f64>) -> f64 {
    lerp_sum(c, vals).round_ties_even()
}

/// flam3's `interpolate_n`: the blend of aligned control points with weights `c`.
pub(super) fn blend(cpi: &[Cp], c: &[f64], stagger: f64) -> Cp {
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
        let moved = found.iter().flatten().any(|v| v.moved);
        out.push(Var {
            id,
            form,
            weight,
            params,
            texts,
            moved,
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
