//! Loops and transitions as flam3-genome makes them for `sequence=`: a loop turns every xform
//! about the origin once (its `<motion>` elements applied), a transition turns both flames
//! while blending them with a smooth step, and a sequence strings loops and transitions of a
//! file's flames together, one flame per frame, for `flam3-animate` or ugnis to render.

use std::f64::consts::PI;

use crate::flame::interpolate::{Cp, EPS, align, columns, interpolate_cps, smoother};
use crate::flame::model::{Flame, Var, Xform};
use crate::flame::sequence::{Interpolation, InterpolationType, PaletteInterpolation};

/// Turn every xform's linear part by `degrees` about the origin (flam3's `flam3_rotate`):
/// xforms with `animate` 0 stay, as does the final xform.
pub fn rotate(f: &mut Flame, degrees: f64) {
    let mut cp = Cp::new(f);
    rotate_cp(&mut cp, degrees, f.anim.interpolation_type);
    *f = cp.into_flame();
}

fn rotate_cp(cp: &mut Cp, degrees: f64, kind: InterpolationType) {
    let (s, co) = (degrees * 2.0 * PI / 360.0).sin_cos();
    let last = cp.slots.len().wrapping_sub(1);
    let has_final = cp.has_final;
    for (i, slot) in cp.slots.iter_mut().enumerate() {
        if slot.x.animate == 0.0 || (has_final && i == last) {
            continue;
        }
        if slot.padding && kind != InterpolationType::Log {
            continue;
        }
        let m = &mut slot.x.coefs;
        let (a, c) = (co * m.a - s * m.c, s * m.a + co * m.c);
        let (b, d) = (co * m.b - s * m.d, s * m.b + co * m.d);
        (m.a, m.b, m.c, m.d) = (a, b, c, d);
    }
}

/// Add an xform's `<motion>` changes at `blend` of a loop to `to` (flam3's
/// `apply_motion_parameters`): every value moves by its amount times the element's function
/// of frequency × blend; colour stays in [0, 1] and weight non-negative.
pub fn apply_motion(x: &Xform, to: &mut Xform, blend: f64) {
    for m in &x.motion {
        let k = m.function.eval(m.frequency as f64 * blend);
        let d = &m.delta;
        to.weight += d.weight * k;
        to.color += d.color * k;
        to.opacity += d.opacity * k;
        to.color_speed += d.color_speed * k;
        to.animate += d.animate * k;
        to.direct_color += d.direct_color * k;
        for dv in &d.vars {
            let pos = to
                .vars
                .iter()
                .position(|v| v.id == dv.id && v.form == dv.form);
            let v = match pos {
                Some(p) => &mut to.vars[p],
                // A variation the xform lacks starts at weight 0 with its default parameters.
                None => {
                    to.vars.push(Var::with_form(dv.id, dv.form, 0.0));
                    to.vars.last_mut().expect("just pushed")
                }
            };
            v.weight += dv.weight * k;
            for (p, dp) in v.params.iter_mut().zip(&dv.params) {
                *p += dp * k;
            }
        }
        for (t, dm) in [(&mut to.coefs, &d.coefs), (&mut to.post, &d.post)] {
            t.a += dm.a * k;
            t.b += dm.b * k;
            t.c += dm.c * k;
            t.d += dm.d * k;
            t.e += dm.e * k;
            t.f += dm.f * k;
        }
    }
    to.color = to.color.clamp(0.0, 1.0);
    to.weight = to.weight.max(0.0);
    to.vars.retain(|v| v.weight != 0.0);
}

/// A frame of a flame's loop at `blend` ∈ [0, 1) (flam3-genome's `sheep_loop`): motion
/// elements applied, then every xform turned by blend × 360° × `turns` (flam3: one turn).
pub fn loop_frame(cp: &Flame, blend: f64, turns: f64) -> Flame {
    let mut r = cp.clone();
    for (x, to) in cp.xforms.iter().zip(r.xforms.iter_mut()) {
        apply_motion(x, to, blend);
        to.motion.clear();
    }
    if let (Some(x), Some(to)) = (&cp.final_xform, &mut r.final_xform) {
        apply_motion(x, to, blend);
        to.motion.clear();
    }
    let kind = r.anim.interpolation_type;
    let mut c = Cp::new(&r);
    rotate_cp(&mut c, blend * 360.0 * turns, kind);
    c.into_flame()
}

/// A frame of the transition from `pair[0]` to `pair[1]` at `blend` ∈ [0, 1) (flam3-genome's
/// `sheep_edge`): both flames get their motion at `blend` and are turned by blend × 360° ×
/// `turns`, then blended with the smooth step of `blend` (`stagger` > 0 lets the xforms change
/// one after another). `first_or_last`: at blend 0 the first flame is returned as it is.
pub fn edge_frame(
    pair: [&Flame; 2],
    blend: f64,
    first_or_last: bool,
    stagger: f64,
    turns: f64,
) -> Flame {
    let prealign: Vec<Cp> = pair
        .iter()
        .map(|f| {
            let mut g = (*f).clone();
            for (x, to) in f.xforms.iter().zip(g.xforms.iter_mut()) {
                apply_motion(x, to, blend);
            }
            if let (Some(x), Some(to)) = (&f.final_xform, &mut g.final_xform) {
                apply_motion(x, to, blend);
            }
            Cp::new(&g)
        })
        .collect();
    let mut out = if first_or_last && blend == 0.0 {
        prealign[0].clone().into_flame()
    } else {
        let mut spun = align(&[&prealign[0], &prealign[1]]);
        spun[0].flame.anim.time = 0.0;
        spun[1].flame.anim.time = 1.0;
        reference_angles(&mut spun);
        let kind = spun[0].flame.anim.interpolation_type;
        for s in &mut spun {
            rotate_cp(s, blend * 360.0 * turns, kind);
        }
        interpolate_cps(&spun, smoother(blend), stagger).into_flame()
    };
    for x in out.xforms.iter_mut().chain(out.final_xform.as_mut()) {
        x.motion.clear();
    }
    out
}

/// flam3's `establish_asymmetric_refangles`: where an xform turns on one side of a transition
/// and not on the other, the side that does not turn remembers the other's angle so that the
/// blend takes the matching way round.
fn reference_angles(cps: &mut [Cp]) {
    let n_slots = cps[0].slots.len();
    for xf in 0..n_slots {
        if cps[0].has_final && xf == n_slots - 1 {
            continue;
        }
        let mut ang: Vec<[f64; 2]> = cps
            .iter()
            .map(|c| {
                let cols = columns(&c.slots[xf].x.coefs);
                [cols[0][1].atan2(cols[0][0]), cols[1][1].atan2(cols[1][0])]
            })
            .collect();
        for k in 1..cps.len() {
            let prev = ang[k - 1];
            let sym0 = cps[k - 1].slots[xf].x.animate == 0.0;
            let sym1 = cps[k].slots[xf].x.animate == 0.0;
            for (col, a) in ang[k].iter_mut().enumerate() {
                let d = *a - prev[col];
                if d > PI + EPS {
                    *a -= 2.0 * PI;
                } else if d < -(PI - EPS) {
                    *a += 2.0 * PI;
                }
                if sym1 && !sym0 {
                    cps[k].slots[xf].wind[col] = prev[col] + 2.0 * PI;
                } else if sym0 && !sym1 {
                    cps[k].slots[xf].wind[col] = *a + 2.0 * PI;
                }
            }
        }
    }
}

/// The flames of flam3-genome's `sequence=`: for each flame a loop of `frames` frames (when
/// `loops`), and a transition of `frames` frames to the next flame; then the last flame once.
/// Frame k has time k and is named by its time. `turns`: whole turns per loop (flam3: 1); the
/// sequence is seamless for whole numbers.
pub fn sequence(cps: &[Flame], frames: usize, loops: bool, turns: f64) -> Vec<Flame> {
    let mut out = Vec::new();
    let nf = frames.max(1);
    let mut push = |mut f: Flame, interp_defaults: bool| {
        let k = out.len();
        f.anim.time = k as f64;
        f.name = format!("{:.6}", k as f64);
        if interp_defaults {
            f.anim.interpolation = Interpolation::Linear;
            f.anim.palette_interpolation = PaletteInterpolation::HsvCircular;
            f.anim.hsv_rgb_palette_blend = 0.0;
        }
        out.push(f);
    };
    for (i, cp) in cps.iter().enumerate() {
        if loops {
            for frame in 0..nf {
                push(loop_frame(cp, frame as f64 / nf as f64, turns), true);
            }
        }
        if let Some(next) = cps.get(i + 1) {
            for frame in 0..nf {
                let ends = frame == 0 || frame == nf - 1;
                push(
                    edge_frame([cp, next], frame as f64 / nf as f64, ends, 0.0, turns),
                    false,
                );
            }
        }
    }
    if let Some(last) = cps.last() {
        push(loop_frame(last, 0.0, turns), true);
    }
    out
}
