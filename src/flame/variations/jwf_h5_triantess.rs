//! JWildfire's `dc_triantess` (Jesus Sosa's port of knighty's shader of the tessellations by
//! the triangle group (p, q, r) of the sphere, the plane or the hyperbolic plane): the point,
//! lifted onto the space of the group's curvature, is turned, folded into the fundamental
//! triangle by its mirrors, and coloured by the face of the uniform tiling it lies in (the
//! tiling's vertex set by the barycentric U, V, W), its edges and vertices drawn over.
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `DC_TrianTessFunc`, written anew. Its six
//! colours are texts of six hexadecimal digits (RRGGBB), as JWildfire stores them.

use std::f64::consts::PI;

use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail};
use super::util::{signum_java, smoothstep};
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("dc_triantess", dc_triantess)
    .params(P_DC_TRIANTESS)
    .texts(TRIANTESS_TEXTS)
    .flags(DC_FLAGS)
    .prepare(triantess_prepare)];

const P_DC_TRIANTESS: &[Param] = &{
    let tail = dc_tail!("dc_triantess");
    [
        p("dc_triantess_zoom", 0.5),
        p("dc_triantess_CenterX", 0.0),
        p("dc_triantess_CenterY", 0.0),
        // JWildfire's bound: at most 20 folds.
        p_int("dc_triantess_Iterations", 13.0, 0.0, 20.0),
        p_int("dc_triantess_pParam", 2.0, 2.0, 20.0),
        p_int("dc_triantess_qParam", 3.0, 2.0, 20.0),
        p_int("dc_triantess_rParam", 7.0, 2.0, 20.0),
        p_range("dc_triantess_U", 1.0, 0.0, 1.0),
        p_range("dc_triantess_V", 1.0, 0.0, 1.0),
        p_range("dc_triantess_W", 0.0, 0.0, 1.0),
        p_range("dc_triantess_VRadius", 0.0, 0.0, 0.25),
        p_range("dc_triantess_SRadius", 0.02528, 0.0, 0.05),
        p_range("dc_triantess_RotAngle", 0.0, -3.0, 3.0),
        p_int("dc_triantess_Vertex", 1.0, 0.0, 1.0),
        p_int("dc_triantess_Segments", 1.0, 0.0, 1.0),
        p_int("dc_triantess_Faces", 1.0, 0.0, 1.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// The six colours: faces A, B, C, edges, vertices, background.
const TRIANTESS_TEXTS: &[TextParam] = &[
    TextParam {
        name: "dc_triantess_FaceA_-RGB",
        default: "FFFFFF",
        max_len: 64,
    },
    TextParam {
        name: "dc_triantess_FaceB_-RGB",
        default: "000000",
        max_len: 64,
    },
    TextParam {
        name: "dc_triantess_FaceC_-RGB",
        default: "000000",
        max_len: 64,
    },
    TextParam {
        name: "dc_triantess_Segment_-RGB",
        default: "FFFFFF",
        max_len: 64,
    },
    TextParam {
        name: "dc_triantess_Vertex_-RGB",
        default: "000000",
        max_len: 64,
    },
    TextParam {
        name: "dc_triantess_Background_-RGB",
        default: "000000",
        max_len: 64,
    },
];

type V = [f64; 3];

/// The colour a text RRGGBB gives (channels / 255), `fallback` when its first six characters
/// are not hexadecimal digits.
fn hex_colour(s: &str, fallback: V) -> V {
    let h: Vec<u32> = s.chars().take(6).map_while(|c| c.to_digit(16)).collect();
    if h.len() < 6 {
        return fallback;
    }
    [0, 1, 2].map(|k| f64::from(h[2 * k] * 16 + h[2 * k + 1]) / 255.0)
}

/// The product of "vectors" in the space of curvature sign `st`.
fn hdotd(st: f64, a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + st * a[2] * b[2]
}

/// The product of "duals".
fn hdotv(st: f64, a: V, b: V) -> f64 {
    st * (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2]
}

fn comb(a: V, x: f64, b: V, y: f64) -> V {
    [0, 1, 2].map(|k| a[k] * x + b[k] * y)
}

/// Derived values, in order: st, nb, nc, p, gA, gB, gC (3 each), tan of the half vertex and
/// edge radii, cos and sin of the turn (in the space's own trigonometry), then the six colours
/// (3 each).
fn triantess_prepare(v: &mut Prepared) {
    let [_, _, _, _, pp, qq, rr, u, vv, w, vr, sr, rot] = v.params();
    let st = signum_java(qq * rr + pp * rr + pp * qq - pp * qq * rr);
    let (sp, cp) = (PI / pp).sin_cos();
    let cq = (PI / qq).cos();
    let (spr, cpr) = (PI / rr).sin_cos();
    let k = (cq + cp * cpr) / sp;
    let nb = [-cp, sp, 0.0];
    let mut nc = [-cpr, -k, ((k + spr) * (-k + spr)).abs().sqrt()];
    if st == 0.0 {
        nc[2] = 0.25;
    }
    let pa = [nb[1] * nc[2], -nb[0] * nc[2], nb[0] * nc[1] - nb[1] * nc[0]];
    let pb = [0.0, nc[2], -nc[1]];
    let pc = [0.0, 0.0, nb[1]];
    let q: V = [0, 1, 2].map(|i| pa[i] * u + pb[i] * vv + pc[i] * w);
    let qlen = hdotv(st, q, q).abs().sqrt();
    let g = |pv: V| comb(pv, qlen / hdotv(st, pv, q), q, -1.0);
    let (ga, gb, gc) = (g(pa), g(pb), g(pc));
    let p = q.map(|c| c * (1.0 / qlen));
    let (tvr, tsr, cra, sra) = if st == -1.0 {
        ((0.5 * vr).tanh(), (0.5 * sr).tanh(), rot.cosh(), rot.sinh())
    } else if st == 1.0 {
        (
            (0.5 * vr).sin() / (0.5 * vr).cos(),
            (0.5 * sr).sin() / (0.5 * sr).cos(),
            rot.cos(),
            rot.sin(),
        )
    } else {
        (0.5 * vr, 0.5 * sr, 1.0, rot)
    };
    v.p.push(st);
    for x in [nb, nc, p, ga, gb, gc] {
        v.p.extend_from_slice(&x);
    }
    v.p.extend_from_slice(&[tvr, tsr, cra, sra]);
    let colours: Vec<V> = TRIANTESS_TEXTS
        .iter()
        .enumerate()
        .map(|(i, d)| {
            let fallback = hex_colour(d.default, [0.0; 3]);
            hex_colour(v.texts.get(i).map_or(d.default, |s| s.as_str()), fallback)
        })
        .collect();
    for c in colours {
        v.p.extend_from_slice(&c);
    }
}

/// The tessellation's colour at (x, y).
fn triantess_rgb(v: &Prepared, x: f64, y: f64) -> V {
    let [zoom, cx, cy, iters] = v.params();
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        show_v,
        show_s,
        show_f,
    ] = v.params();
    let d = v.table(0);
    let st = d[0];
    let at = |i: usize| [d[i], d[i + 1], d[i + 2]];
    let (nb, nc, p, ga, gb, gc) = (at(1), at(4), at(7), at(10), at(13), at(16));
    let (tvr, tsr, cra, sra) = (d[19], d[20], d[21], d[22]);
    let (face_a, face_b, face_c, seg, vert, back) =
        (at(23), at(26), at(29), at(32), at(35), at(38));
    let aa = 0.0005;
    let (px, py) = (x / zoom + cx, y / zoom + cy);
    let r = (px * px + py * py).sqrt();
    let k = 1.0 / (1.0 + st * r * r);
    let mut z = [2.0 * px * k, 2.0 * py * k, (1.0 - st * r * r) * k];
    if st == -1.0 && r >= 1.0 {
        return back;
    }
    // The turn about the axis (0, 1) in the space's own geometry.
    let vp = z[1];
    z[1] += vp * (cra - 1.0) - z[2] * sra;
    z[2] += vp * st * sra + z[2] * (cra - 1.0);
    let reflect = |z: &mut V, n: V| {
        let t = -2.0 * (n[0] * z[0] + n[1] * z[1] + n[2] * z[2]).min(0.0);
        z[0] += n[0] * t;
        z[1] += n[1] * t;
        z[2] += n[2] * st * t;
    };
    // At most 20 folds (the parameter's bound); once a fold changes nothing the rest do not.
    for _ in 0..(iters as i32).clamp(0, 20) {
        z[0] = z[0].abs();
        reflect(&mut z, nb);
        reflect(&mut z, nc);
    }
    let dd = |tha: f64| tha * (1.0 + st * r * r) / (1.0 + st * st * r * tha);
    let mut color = back;
    if show_f == 1.0 {
        let (fa, fb, fc) = (hdotd(st, ga, z), hdotd(st, gb, z), hdotd(st, gc, z));
        let f = fa.max(fb.max(fc));
        let c = [fa, fb, fc].map(|x| if x == f { 1.0 } else { 0.0 });
        let kk = 1.0 / (c[0] + c[1] + c[2]);
        color = [0, 1, 2]
            .map(|i| face_a[i] * (c[0] * kk) + face_b[i] * (c[1] * kk) + face_c[i] * (c[2] * kk));
    }
    let mix = |a: V, b: V, t: f64| [0, 1, 2].map(|i| a[i] * (1.0 - t) + b[i] * t);
    if show_s == 1.0 {
        let segment = |n: V| {
            let (pn, nn, pp) = (hdotv(st, p, n), hdotv(st, n, n), hdotv(st, p, p));
            let (zn, zp) = (hdotv(st, z, n), hdotv(st, z, p));
            let det = 1.0 / (pn * pn - pp * nn);
            let alpha = det * (pn * zn - zp * nn);
            let beta = det * (-pp * zn + pn * zp);
            let m = comb(p, alpha, n, beta.min(0.0));
            let m = m.map(|c| c * (1.0 / hdotv(st, m, m).abs().sqrt()));
            let (dm, sm) = (comb(m, 1.0, z, -1.0), comb(m, 1.0, z, 1.0));
            let tha = hdotd(st, dm, dm).abs().sqrt() / hdotv(st, sm, sm).abs().sqrt();
            dd((tha - tsr) / (1.0 + st * tha * tsr))
        };
        let ds = segment([1.0, 0.0, 0.0])
            .min(segment(nb))
            .min(segment([nc[0], nc[1], nc[2] * st]));
        color = mix(seg, color, smoothstep(-1.0, 1.0, ds * 0.5 / aa));
    }
    if show_v == 1.0 {
        let (dm, sm) = (comb(p, 1.0, z, -1.0), comb(p, 1.0, z, 1.0));
        let tha = hdotd(st, dm, dm).abs().sqrt() / hdotv(st, sm, sm).abs().sqrt();
        let dv = dd((tha - tvr) / (1.0 + st * tha * tvr));
        color = mix(vert, color, smoothstep(-1.0, 1.0, dv * 0.5 / aa));
    }
    if st == -1.0 {
        color = mix(back, color, smoothstep(0.0, 1.0, (1.0 - r) * 0.5 / aa));
    }
    color
}

/// dc_triantess: the tessellation's colour at the point (uniform in [−½, ½]², or the input
/// with ColorOnly).
fn dc_triantess(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [.., c0, c1, c2, c3, c4] = v.params::<21>();
    dc_common(v, [c0, c1, c2, c3, c4], t, acc, rng, 0.5, |x, y| {
        triantess_rgb(v, x, y)
    })
}
