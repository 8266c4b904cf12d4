//! JWildfire's `glsl_circuits` (Jesus Sosa's port of a "circuits" shader: a folded, turned
//! plane of glowing traces), on the frame of the other `glsl_*` stamps.
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `GLSLCircuitsFunc`, written anew. Its
//! brightness sum `S` carries over from pixel to pixel (JWildfire keeps it in the variation
//! and never resets it), as here.

use std::f64::consts::PI;

use super::jwf_c_glsl::{GLSL_RES_Y, GlslIndex, glsl_frame};
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("glsl_circuits", glsl_circuits)
    .params(&[
        p_int("glsl_circuits_Density Pixels", 1e6, 100.0, 1e7),
        p("glsl_circuits_time", 0.0),
        p("glsl_circuits_rate", 0.8),
        p("glsl_circuits_intensity", 0.9),
        p("glsl_circuits_focus", 1.5),
        p("glsl_circuits_pulse", 10.0),
        p("glsl_circuits_glow", 2.0),
        p("glsl_circuits_loops", 15.0),
        p("glsl_circuits_zoom", 1.0),
        p_int("glsl_circuits_Gradient", 0.0, 0.0, 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR | flag::STATEFUL)
    .prepare(circuits_prepare)];

/// The brightness sum's start: JWildfire computes it from the default glow (2) and intensity
/// (0.9) when it makes the variation, before any parameter is set.
fn circuits_prepare(v: &mut Prepared) {
    v.state.set(0, (101.0 + 2.0) * 0.9);
}

/// GLSL's mod: a − b·⌊a/b⌋.
fn glsl_mod(a: f64, b: f64) -> f64 {
    a - b * (a / b).floor()
}

/// GLSL's sign.
fn glsl_sign(a: f64) -> f64 {
    if a == 0.0 || a.is_nan() {
        a
    } else {
        a.signum()
    }
}

/// One sample of the traces at `z` and time `t`: its colour, adding its brightness to `s`.
fn circuits_sample(mut z: (f64, f64), t: f64, q: [f64; 4], s: &mut f64) -> [f64; 3] {
    let [intensity, pulse, loops, zoom] = q;
    let mut m = 0.0f64;
    let (mut ot, mut ot2) = (1000.0f64, 1000.0f64);
    let mut k = (loops / 4.0 + (5.0 * zoom).floor()).floor();
    for i in 0..11 {
        let d = (z.0 * z.0 + z.1 * z.1).clamp(0.1, 0.5);
        z = (z.0.abs() / d - t, z.1.abs() / d - t);
        let l = (z.0 * z.0 + z.1 * z.1).sqrt();
        let o = z.0.min(z.1).abs().max(-l + 0.25).min((l - 0.25).abs());
        ot = ot.min(o);
        ot2 = (l * 0.1).min(ot2);
        m = m.max(f64::from(i) * (1.0 - glsl_sign(ot - o).abs()));
        if k <= 0.0 {
            break;
        }
        k -= 1.0;
    }
    m += 1.0;
    let w = intensity * zoom * m;
    let circ = ((w - ot2).max(0.0) / w).powf(6.0);
    *s += ((w - ot).max(0.0) / w).powf(0.25).max(circ);
    let c = [0.1 + 0.45, 0.1 + 0.75, 0.1 + m * 0.1];
    let n = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    let t2 = 0.4 + glsl_mod(m / 9.0 - t * pulse + ot2 * 2.0, 1.0);
    let f = circ * (10.0 - m) * 3.0;
    [
        c[0] / n * t2 + f,
        c[1] / n * t2 + 0.7 * f,
        c[2] / n * t2 + 0.3 * f,
    ]
}

/// glsl_circuits: the pixel's centre turned and moved by the time, sampled up to 24 times
/// (⌊loops⌋ + 1) in a small defocused pattern, the last sample's colour mixed with grey by the
/// carried brightness and darkened towards the edge.
fn glsl_circuits(v: &Prepared, _: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        res,
        time,
        rate,
        intensity,
        focus,
        pulse,
        _,
        loops,
        zoom,
        gradient,
    ] = v.params();
    let mut s = v.state.get(0);
    let out = glsl_frame(v, res, gradient, acc, rng, GlslIndex::RedGreen, |i, j| {
        let pos = ((i + 0.5) / res - 0.5, (j + 0.5) / GLSL_RES_Y - 0.5);
        let mut n = time * 0.01 * rate;
        let mut tt = 2.0 * rate;
        if n > 6.0 * rate {
            n -= 8.0 * rate;
        }
        if n < 4.0 * rate {
            tt += n;
        } else {
            tt = 8.0 * rate - n;
        }
        let zf = 1.05 - zoom;
        let sph = (pos.0 * pos.0 + pos.1 * pos.1).sqrt() * 0.1;
        let sph = (1.0 - sph * sph).sqrt() * 2.0;
        let a = tt * PI;
        let b = a + tt;
        let c = a.cos() + b.sin();
        let (sb, cb) = b.sin_cos();
        let mut uv = (cb * pos.0 + sb * pos.1, -sb * pos.0 + cb * pos.1);
        let (sa, ca) = a.sin_cos();
        uv = (ca * uv.0 - sa * uv.1, sa * uv.0 + ca * uv.1);
        uv = ((uv.0 - c.sin() / PI) * zf, (uv.1 - c.cos() / PI) * zf);
        let pix = 0.5 / res * zf / sph;
        let dof = zoom * focus + tt * 0.25;
        let mut l = loops.floor();
        let mut color = [0.0; 3];
        let q = [intensity, pulse, loops, zoom];
        for aa in 0..24 {
            let (ax, ay) = ((f64::from(aa) / 6.0).floor(), f64::from(aa % 6));
            let z = (uv.0 + ax * pix * dof, uv.1 + ay * pix * dof);
            color = circuits_sample(z, tt, q, &mut s);
            if l <= 0.0 {
                break;
            }
            l -= 1.0;
        }
        s /= loops.floor();
        let fade = 1.0 - (pos.0 * pos.0 + pos.1 * pos.1).sqrt();
        let tint = [1.2, 1.1, 1.0];
        let lf = loops.floor();
        std::array::from_fn(|k| (0.15 * (1.0 - s) + color[k] / lf * s) * fade * tint[k])
    });
    v.state.set(0, s);
    out
}
