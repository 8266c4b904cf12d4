//! JWildfire's iterated-field direct-colour stamps (Jesus Sosa's shader ports): `dc_layers`
//! (shells of a sine field seen along turned rays), `dc_tree` (a swaying fractal tree of
//! polar folds), `dc_tesla` (Kali's "field" of absolute-value inversions, glowing) and
//! `dc_rotations` (folds turned with time, coloured by a smooth hue).
//!
//! Each colours its points through `jwf_direct_colour`'s common part. The formulas follow
//! JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics, written anew.

use super::jwf_a_dc::rot;
use super::jwf_dc_maths::{length2, mix3, row_times_mat3};
use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail, gmod};
use super::util::{atan2_approx, fract, smoothstep};
use super::*;

const LAYERS_TAIL: [Param; 5] = dc_tail!("dc_layers");
const TREE_TAIL: [Param; 5] = dc_tail!("dc_tree");
const TESLA_TAIL: [Param; 5] = dc_tail!("dc_tesla");
const ROTATIONS_TAIL: [Param; 5] = dc_tail!("dc_rotations");

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("dc_layers", dc_layers)
        .params(&[
            p_int("dc_layers_N", 8.0, 1.0, 10.0),
            p_range("dc_layers_Amplitude", 0.995, 0.0, 10.0),
            p_int("dc_layers_seed", 10000.0, NEG_INF, INF),
            p("dc_layers_time", 0.0),
            p("dc_layers_zoom", 8.0),
            LAYERS_TAIL[0],
            LAYERS_TAIL[1],
            LAYERS_TAIL[2],
            LAYERS_TAIL[3],
            LAYERS_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_tree", dc_tree)
        .params(&[
            p_int("dc_tree_levels", 20.0, 1.0, 25.0),
            p_range("dc_tree_thicknes", 1000.0, -1500.0, 1500.0),
            p_range("dc_tree_style", 50.0, 1.0, 100.0),
            p_range("dc_tree_shift", 1.5, -100.0, 100.0),
            p_int("dc_tree_seed", 10000.0, NEG_INF, INF),
            p("dc_tree_time", 0.0),
            p("dc_tree_zoom", 4.0),
            TREE_TAIL[0],
            TREE_TAIL[1],
            TREE_TAIL[2],
            TREE_TAIL[3],
            TREE_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_tesla", dc_tesla)
        .params(&[
            p_int("dc_tesla_levels", 20.0, 1.0, 25.0),
            p_range("dc_tesla_style", 10.0, 5.0, 100.0),
            p_int("dc_tesla_seed", 10000.0, NEG_INF, INF),
            p("dc_tesla_time", 0.0),
            p("dc_tesla_zoom", 4.0),
            TESLA_TAIL[0],
            TESLA_TAIL[1],
            TESLA_TAIL[2],
            TESLA_TAIL[3],
            TESLA_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_rotations", dc_rotations)
        .params(&[
            p_int("dc_rotations_levels", 20.0, 1.0, 50.0),
            p_int("dc_rotations_seed", 10000.0, NEG_INF, INF),
            p("dc_rotations_time", 0.0),
            p("dc_rotations_zoom", 4.0),
            ROTATIONS_TAIL[0],
            ROTATIONS_TAIL[1],
            ROTATIONS_TAIL[2],
            ROTATIONS_TAIL[3],
            ROTATIONS_TAIL[4],
        ])
        .flags(DC_FLAGS),
];

/// dc_layers: the ray (zoomed point, 1) turned about x by Amplitude·π and about y by
/// 2·Amplitude·π, then N shells |sin 4x·cos 4y − sin 4z| of its multiples (shifted by
/// 0.13·time), the nearest shell (fading with depth) white on black. Over [−1, 1]².
fn dc_layers(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n, amplitude, _, time, zoom, tail @ ..] = v.params::<10>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        let m = (
            2.0 * (amplitude * std::f64::consts::PI),
            amplitude * std::f64::consts::PI,
        );
        let (sy, cy) = (m.1.sin(), m.1.cos());
        let (sx, cx) = (m.0.sin(), m.0.cos());
        let p = [x * zoom, y * zoom, 1.0];
        let p = row_times_mat3(p, [1.0, 0.0, 0.0, 0.0, cy, -sy, 0.0, sy, cy]);
        let p = row_times_mat3(p, [cx, 0.0, -sx, 0.0, 1.0, 0.0, sx, 0.0, cx]);
        let l = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        let pos = p.map(|c| c / l);
        let mut dist: f64 = 0.0;
        for k in 1..=n as i64 {
            let k = k as f64;
            let q = [pos[0] * k + time * 0.13, pos[1] * k + 0.0, pos[2] * k + 0.0];
            let shell = ((q[0] * 4.0).sin() * (q[1] * 4.0).cos() - (q[2] * 4.0).sin()).abs();
            let shell = smoothstep(0.25, 0.2, shell);
            dist = dist.max(shell * (1.0 - k / 8.0));
        }
        mix3([1.0; 3], [0.0; 3], 1.0 - dist)
    })
}

/// The shaders' polar form (|u|, angle) and back.
fn to_polar((x, y): (f64, f64)) -> (f64, f64) {
    (length2(x, y), atan2_approx(y, x))
}

fn from_polar((r, a): (f64, f64)) -> (f64, f64) {
    (a.cos() * r, a.sin() * r)
}

/// dc_tree: `levels` − 1 steps of a polar fold (turn, mirror in x, scale, turn again) of the
/// zoomed point shifted up, the distance to a wobbling unit stem kept (the stem's wobble
/// also moves the point, as JWildfire's does); the grey sin(e^(−thickness·d²)·style) summed.
/// Over [−½, ½]².
fn dc_tree(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [levels, thickness, style, shift, _, time, zoom, tail @ ..] = v.params::<12>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let mut u = (x * zoom, y * zoom + shift);
        let mut r: f64 = 1e9;
        let mut col = 0.0;
        for k in 1..levels as i64 {
            let k = k as f64;
            let s1 =
                0.3 * ((2.0 * time).sin() + 0.5 * (4.53 * time).sin() + 0.1 * (12.2 * time).cos());
            let pu = to_polar(u);
            u = from_polar((pu.0 + 0.0 * s1, pu.1 + 1.0 * s1));
            r = r.min(stem_distance(&mut u, time));
            u.1 -= 1.0;
            u.0 = u.0.abs();
            let f = 1.4 + 0.1 * time.sin() + 0.05 * (0.2455 * time).sin() * k;
            u = to_polar((u.0 * f, u.1 * f));
            u.1 += 1.0
                + 0.5 * (0.553 * time).sin() * (time.sin() * k).sin()
                + 0.1 * (0.4 * time).sin()
                + 0.05 * (0.554 * time).sin();
            u = from_polar(u);
            let s0 = (-thickness.trunc() * r * r).exp() * style;
            col += s0.sin();
        }
        [col; 3]
    })
}

/// The tree shader's rounded π (kept).
#[allow(clippy::approx_constant)]
const SHADER_PI: f64 = 3.14159;

/// Distance from p to the stem from (0, 0) to (0, 1), wobbling with time (wider towards
/// its top); the wobble is added to p's x.
fn stem_distance(p: &mut (f64, f64), time: f64) -> f64 {
    let (ax, ay, bx, by) = (0.0, 0.0, 0.0, 1.0);
    let (dx, dy) = (bx - ax, by - ay);
    let r = ((p.0 - ax) * dx + (p.1 - ay) * dy) / (dx * dx + dy * dy);
    let r = r.clamp(0.0, 1.0);
    p.0 += (0.7 + 0.5 * (0.1 * time).sin())
        * 0.2
        * smoothstep(1.0, 0.0, (r * 2.0 - 1.0).abs())
        * (SHADER_PI * (r - 4.0 * time)).sin();
    let (t0x, t0y) = (p.0 - ax, p.1 - ay);
    (1.0 + 0.5 * r) * length2(t0x - dx * r, t0y - dy * r)
}

/// dc_tesla: Kali's field at (zoomed point, 1): `levels` steps of p ← |p|/m + offset
/// (m = |p|²·½^|sin(time/8)|), weighting how sharply m changes; grey. Over [−½, ½]².
fn dc_tesla(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [levels, style, _, time, zoom, tail @ ..] = v.params::<10>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let s: f64 = 0.5;
        let mut p = [x * zoom, y * zoom, 1.0];
        let strength = 20.0 + 0.03 * (1.0e-6 + fract((time * 10.0).sin() * 4500.0)).ln();
        let mut accum = s * 3.0;
        let (mut prev, mut tw) = (0.0, 0.0);
        let offset = [-0.9, -0.234560 * time.sin().abs(), -1.0];
        for i in 0..levels as i64 {
            let mag =
                (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) * s.powf(1.0 * (time / 8.0).sin().abs());
            p = [0, 1, 2].map(|k| p[k].abs() / mag + offset[k]);
            let w = (-(i as f64) / style).exp();
            accum += w * (-strength * (mag / prev).abs().powf(1.2)).exp();
            tw += w * w;
            prev = mag;
        }
        [(6.0 * accum / tw - 2.0).max(0.0); 3]
    })
}

/// dc_rotations: `levels` folds uv ← |uv|/|uv|² − s (s shrinking by 0.955), each turned by
/// time/10, a final turn by time + x/20; the colour a smooth hue of 0.4·time + y/10. Over
/// [−½, ½]².
fn dc_rotations(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [levels, _, time, zoom, tail @ ..] = v.params::<9>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let mut uv = (x * zoom, y * zoom);
        let d = 1.0 - length2(uv.0, uv.1);
        let mut s = 0.5;
        for _ in 0..levels as i64 {
            let dd = uv.0 * uv.0 + uv.1 * uv.1;
            uv = (uv.0.abs() / dd - s, uv.1.abs() / dd - s);
            uv = rot(uv.0, uv.1, -(time * 0.1));
            s *= 0.955;
        }
        uv = rot(uv.0, uv.1, time + uv.0 * 0.05);
        let h = time * 0.4 + uv.1 * 0.1;
        let rgb = [0.0, 4.0, 2.0].map(|o: f64| {
            let c = ((gmod(o + h * 6.0, 6.0) - 3.0).abs() - 1.0).clamp(0.0, 1.0);
            c * c * (3.0 - c * 2.0)
        });
        let hue = mix3([1.0; 3], rgb, 1.0);
        mix3(hue, [d * 0.1, d * 0.2, d * 0.1], 0.0)
    })
}
