//! flam3's alignment of control points: padding xforms made to match their partners, and the
//! parameters of a variation used on one side only carried to the other.

use super::*;

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

pub(super) fn weight_of(x: &Xform, id: VarId) -> f64 {
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
