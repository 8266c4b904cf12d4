//! JWildfire's `kaleidoimg`: a point drawn at random in a square takes the colour of an image
//! seen through one of 14 kaleidoscopes and warps (or of a hue pattern), as its own colour or
//! as the palette position nearest to it, and a height from its brightness.
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `KaleidoImgFunc` (Jesus Sosa, after
//! shadertoy.com shaders tsSXzt, Ms2XRc, 4lsGWj, 4tlGD2, MdyBW3, Ws33Wl, 3dVczK, ldd3Wn,
//! Ms2SWW, 4sS3Wc, XtKSDm, tsKXDh) and the GLSL helpers of its `js.glsl.G` class, written
//! anew. The image is the one the colour maps use ([`super::jwf_h9b_images`]): the file named
//! in `image_filename`, else JWildfire's default 256 × 256 corner gradient. Sampling is
//! JWildfire's `G.texture`: the image spans [0, 1]², tiled, blended bilinearly, the last row
//! and column black.

// JWildfire's shaders write π and 2π rounded (3.14159, 3.1415, 6.28, …): kept as written.
#![allow(clippy::approx_constant)]

use super::jwf_h9b_images::{View, ftoi, gradient_map, tile};
use super::util::jwf_math;
use super::*;

/// JWildfire's `EPSILON`.
const EPS: f64 = 1e-8;

/// Most bytes of an image file's name.
const MAX_NAME: usize = 4096;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("kaleidoimg", kaleidoimg)
    .params(&[
        p("kaleidoimg_zoom", 2.0),
        p("kaleidoimg_time", 0.0),
        p_int("kaleidoimg_blendcolor", 0.0, 0.0, 1.0),
        p_int("kaleidoimg_dc_color", 0.0, 0.0, 1.0),
        p("kaleidoimg_Angle", 0.0),
        p("kaleidoimg_scaleX", 1.0),
        p("kaleidoimg_scaleY", 1.0),
        p("kaleidoimg_scale_z", 0.0),
        p("kaleidoimg_offsetX", 0.0),
        p("kaleidoimg_offsetY", 0.0),
        p("kaleidoimg_offset_z", 0.0),
        p_int("kaleidoimg_tile_x", 1.0, 0.0, 1.0),
        p_int("kaleidoimg_tile_y", 1.0, 0.0, 1.0),
        p_int("kaleidoimg_reset_z", 1.0, 0.0, 1.0),
        p_int("kaleidoimg_type", 0.0, -1.0, 13.0),
        p_int("kaleidoimg_nr", 12.0, 1.0, 50.0),
        p("kaleidoimg_a", 1.0),
        p("kaleidoimg_b", 0.0),
    ])
    .texts(&[TextParam {
        name: "kaleidoimg_image_filename",
        default: "",
        max_len: MAX_NAME,
    }])
    .flags(
        flag::JWILDFIRE
            | flag::RANDOM
            | flag::WRITES_Z
            | flag::SETS_COLOR
            | flag::WRITES_ACC
            | flag::PALETTE,
    )
    .shared(&[], gradient_map)];

type V2 = [f64; 2];

/// Java's `Math.max` (NaN wins).
fn jmax(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else if a >= b {
        a
    } else {
        b
    }
}

/// Java's `Math.min` (NaN wins).
fn jmin(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else if a <= b {
        a
    } else {
        b
    }
}

/// GLSL's `mod`: x − y·⌊x/y⌋.
fn gmod(x: f64, y: f64) -> f64 {
    x - y * (x / y).floor()
}

/// GLSL's `fract`.
fn fract(x: f64) -> f64 {
    x - x.floor()
}

/// `G.length`, with JWildfire's square root.
fn length(p: V2) -> f64 {
    jwf_math::sqrt(p[0] * p[0] + p[1] * p[1])
}

/// `G.atan2`: JWildfire's shader helpers use a coarse rational approximation of the angle
/// (exact at multiples of π/4 only).
fn g_atan2(y: f64, x: f64) -> f64 {
    const C1: f64 = std::f64::consts::PI / 4.0;
    const C2: f64 = 3.0 * C1;
    let ay = y.abs();
    let angle = if x >= 0.0 {
        C1 - C1 * ((x - ay) / (x + ay))
    } else {
        C2 - C1 * ((x + ay) / (ay - x))
    };
    if y < 0.0 { -angle } else { angle }
}

/// `G.atan(n, d)`: the arc tangent of n/d.
fn g_atan(n: f64, d: f64) -> f64 {
    jwf_math::atan(n / d)
}

/// GLSL's `smoothstep` (NaN passes through, as Java's `min`/`max` pass it).
fn smoothstep(e0: f64, e1: f64, x: f64) -> f64 {
    let t = jmin(jmax((x - e0) / (e1 - e0), 0.0), 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// `G.texture`: the colour (0–255 per channel) of the image at (u, v), the image spanning the
/// unit square (less its last row and column), tiled, blended between the four pixels around.
fn texture(img: &View, uv: V2) -> [f64; 3] {
    let (w, h) = (img.w, img.h);
    if w < 2 || h < 2 {
        return [0.0; 3];
    }
    let x = (uv[0] - 0.5) * f64::from(w - 2);
    let y = (uv[1] - 0.5) * f64::from(h - 2);
    let (ix, iy) = (tile(x.trunc() as i32, w), tile(y.trunc() as i32, h));
    if !((0..w - 1).contains(&ix) && (0..h - 1).contains(&iy)) {
        return [0.0; 3];
    }
    // The fractions of the untiled position (negative left of 0, as JWildfire takes them).
    let (fx, fy) = (x - x.trunc(), y - y.trunc());
    let px = |dx: i32, dy: i32| img.at(ix + dx, iy + dy).map(f64::from);
    let (c00, c10, c01, c11) = (px(0, 0), px(1, 0), px(0, 1), px(1, 1));
    let lerp = |s: f64, e: f64, t: f64| s + (e - s) * t;
    std::array::from_fn(|k| lerp(lerp(c00[k], c10[k], fx), lerp(c01[k], c11[k], fx), fy))
}

/// Turned by angle `a` (Java's sine and cosine).
fn rotate(p: V2, a: f64) -> V2 {
    let (s, c) = a.sin_cos();
    [p[0] * c - p[1] * s, p[0] * s + p[1] * c]
}

/// A point of the (x, y) plane times the z-rotation by `a`, as `vec3 * mat3` computes it.
fn times_rotation(p: [f64; 3], a: f64) -> [f64; 3] {
    let (s, c) = (a.sin(), a.cos());
    [
        p[0] * c + p[1] * -s + p[2] * 0.0,
        p[0] * s + p[1] * c + p[2] * 0.0,
        p[0] * 0.0 + p[1] * 0.0 + p[2],
    ]
}

/// The shared quantities of one evaluation.
struct Scene<'a> {
    img: View<'a>,
    time: f64,
    nr: i32,
    a: f64,
    b: f64,
}

impl Scene<'_> {
    /// Hue of an iterated fold-and-turn (shadertoy Ms2XRc).
    fn mode0(&self, p: V2) -> f64 {
        let (fold, translate, scale) = (-0.15, 1.5, 1.25);
        let mut p = p.map(|c| c * 0.182);
        let x = p[1];
        p = p.map(|c| (gmod(c, 4.0) - 2.0).abs());
        let t = self.time;
        for i in (1..=self.nr).rev() {
            p = p.map(|c| (c - fold).abs() + fold);
            p = p.map(|c| c * scale - translate);
            let wobble = jwf_math::sin(t * 0.0005 + f64::from(i) * 0.5000001) * 0.4999;
            let d = 0.10 + wobble + 0.5 + (10.0 / t) + jwf_math::sin(t) / 100.0;
            p = rotate(p, 3.14159 / d);
        }
        let i = x * x + g_atan2(p[1], p[0]) + t * 0.02;
        let mut h = (i * 4.0).floor() / 8.0 + 1.107;
        h += smoothstep(-0.1, 0.8, gmod(i * 2.0 / 5.0, 1.0 / 4.0) * 900.0) / 0.010 - 0.5;
        h
    }

    /// 32 folds and turns (shadertoy 4lsGWj).
    fn mode1(&self, mut uv: V2) -> V2 {
        let (s, c) = (self.time * 0.1).sin_cos();
        for _ in 0..32 {
            uv = uv.map(|v| v.abs() - 0.25);
            uv = [uv[0] * c + uv[1] * s, uv[1] * c + -(uv[0] * s)];
        }
        uv
    }

    /// 30 angular foldings (shadertoy 4tlGD2).
    fn mode2(&self, mut uv: V2) -> V2 {
        let tt = self.time * 0.3 + 10.0;
        let (s, c) = (tt * 0.1).sin_cos();
        let q = tt * 0.2 / 6.2831853;
        for _ in 0..30 {
            let mut t = g_atan(uv[0], uv[1]);
            t *= q;
            t = (fract(t * 0.5 + 0.5) * 2.0 - 1.0).abs();
            t /= q;
            let r = length(uv);
            uv = [t.sin() * r - 0.7, t.cos() * r - 0.7];
            uv = [uv[0] * c + uv[1] * s, uv[1] * c + -uv[0] * s];
        }
        uv
    }

    /// A rose of `nr` petals (shadertoy MdyBW3).
    fn mode3(&self, uv: V2) -> V2 {
        let t = f64::from(self.nr) * g_atan(uv[1], uv[0]);
        let r3 = jwf_math::pow(length(uv), 3.0);
        [(1.0 + t.cos() * r3) / 2.0, (1.0 + t.sin() * r3) / 2.0]
    }

    /// Mirrors about `nr` axes through (0, 0, 1) (shadertoy Ws33Wl).
    fn mode4(&self, uv: V2) -> V2 {
        let mut huv = times_rotation([uv[0], uv[1], 0.0], self.time * 0.2);
        let origin = [0.0, 0.0, 1.0];
        for i in 0..self.nr {
            let turn = (3.1415 * 2.0 / f64::from(self.nr)) * f64::from(i);
            let rel = [huv[0] - origin[0], huv[1] - origin[1], huv[2] - origin[2]];
            let t = times_rotation(rel, -turn);
            if t[1] < 0.0 {
                let back = times_rotation([t[0], -t[1], t[2]], turn);
                huv = [
                    back[0] + origin[0],
                    back[1] + origin[1],
                    back[2] + origin[2],
                ];
            }
        }
        [huv[0], huv[1]]
    }

    /// A Koch-snowflake folding (shadertoy 3dVczK).
    fn mode5(&self, mut uv: V2) -> V2 {
        let dir = |a: f64| [a.sin(), a.cos()];
        let a: f64 = 5.0 / 6.0 * 3.1415;
        uv[0] = uv[0].abs();
        uv[1] += a.tan() * 0.5;
        let n = dir(a);
        let d = (uv[0] - 0.5) * n[0] + (uv[1] - 0.0) * n[1];
        let k = jmax(0.0, d) * 2.0;
        uv = [uv[0] - n[0] * k, uv[1] - n[1] * k];
        let mut scale = 1.0;
        let n = dir(2.0 / 3.0 * 3.1415);
        uv[0] += 1.5 / 3.0;
        for _ in 0..4 {
            uv = uv.map(|c| c * 3.0);
            scale *= 3.0;
            uv[0] -= 1.5;
            uv[0] = uv[0].abs();
            uv[0] -= 0.5;
            let k = 2.0 * jmin(uv[0] * n[0] + uv[1] * n[1], 0.0);
            uv = [uv[0] - n[0] * k, uv[1] - n[1] * k];
        }
        uv.map(|c| c / scale)
    }

    /// A log-polar spiral (shadertoy ldd3Wn).
    fn mode6(&self, uv: V2) -> V2 {
        let t1 = [g_atan2(uv[0], uv[1]) / 6.28, g_atan2(uv[1], uv[0]) / 6.28];
        let t2 = 2f64.powf(-length(uv));
        [5.0 * (t1[0] + t2), 8.0 * (t1[1] + t2)]
    }

    /// A tunnel (Inigo Quilez): the image by inverse radius and angle, darkened to the
    /// centre.
    fn mode7(&self, p: V2) -> [f64; 3] {
        let a = g_atan2(p[1], p[0]);
        let r = length(p);
        let uv = [0.3 / r + 0.2 * self.time, a / 3.1415927];
        texture(&self.img, uv).map(|c| c * r)
    }

    /// The image's own red and green as a noise moving the point, 19 times.
    fn mode8(&self, n0: V2) -> V2 {
        let drift = self.time * 0.25;
        let nudge = |uv: V2, at: V2| {
            let t = texture(&self.img, at.map(|c| c * 0.01));
            [
                uv[0] + (t[0] * 2.0 - 1.0) * 0.01,
                uv[1] + (t[1] * 2.0 - 1.0) * 0.01,
            ]
        };
        let mut uv = nudge(n0, n0);
        for k in [
            0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.15, 0.25, 0.35, 0.45, 0.55, 0.65, 0.75,
            0.85, 0.95,
        ] {
            uv = nudge(uv, [n0[0] + k + drift, n0[1] + k + drift]);
        }
        uv
    }

    /// A bulge: the point moved along its direction by 0.7·ln r.
    fn mode9(&self, p: V2) -> V2 {
        let r = length(p);
        let k = 0.7 * length(p).ln();
        [p[0] + p[0] / r * k, p[1] + p[1] / r * k]
    }

    /// The radius raised to b, times a (y divided by the new radius, as JWildfire does).
    fn mode10(&self, p: V2) -> V2 {
        let r = length(p);
        let rn = self.a * r.powf(self.b);
        [rn * p[0] / r, rn * p[1] / rn]
    }

    /// A Hermite warp of the unit square (shadertoy 4sS3Wc).
    fn mode11(&self, uv: V2) -> V2 {
        let t = self.time;
        let wave = |f: f64| jwf_math::sin(t * f) * 0.5 + 0.5;
        let (a, b, c, d) = (wave(1.0), wave(1.5), wave(2.0), wave(2.5));
        let mix = |x: f64, y: f64, k: f64| x * (1.0 - k) + y * k;
        let (y0, y1) = (mix(a, b, uv[0]), mix(c, d, uv[0]));
        let (x0, x1) = (mix(a, c, uv[1]), mix(b, d, uv[1]));
        let hermite = |m0: f64, m1: f64, x: f64| {
            let h00 = 2.0 * x * x * x - 3.0 * x * x + 1.0;
            let h10 = x * x * x - 2.0 * x * x + x;
            let h01 = 3.0 * x * x - 2.0 * x * x * x;
            let h11 = x * x * x - x * x;
            0.0 * h00 + m0 * h10 + 1.0 * h01 + m1 * h11
        };
        let u = hermite(3.0 * x0, 3.0 * x1, uv[0]);
        let v = hermite(3.0 * y0, 3.0 * y1, uv[1]);
        [u, 1.0 - v]
    }

    /// Fresnel rings (shadertoy XtKSDm).
    fn mode12(&self, uv: V2) -> V2 {
        let r = length([uv[0] - 0.0, uv[1] - 0.0]) - self.time * 0.05;
        let r = fract(r * self.a) / self.b;
        uv.map(|c| ((c * 2.0 - 1.0) * r) * 0.5 + 0.5)
    }

    /// Two interfering ring waves (shadertoy tsKXDh).
    fn mode13(&self, uv: V2) -> V2 {
        let da = length([uv[0] - -self.a / 2.0, uv[1] - 0.0]);
        let db = length([uv[0] - self.a / 2.0, uv[1] - 0.0]);
        let wave = |d: f64| (((d - self.time / 20.0) * 10.0).sin() + 1.0) / 2.0;
        [wave(da), wave(db)]
    }
}

/// JWildfire's `hsv` of the shader: full saturation, value `v`.
fn hsv(h: f64, v: f64) -> [f64; 3] {
    [3.0, 2.0, 1.0].map(|k| {
        let t = fract((k + h) / 3.0) * 6.0 - 3.0;
        let t = jmin(jmax(t.abs() - 1.0, 0.0), 1.0);
        // The shader's mix(3.1, t, 1): t.
        t * v
    })
}

/// kaleidoimg: a uniform point of the square of side `weight` (replacing the running sum),
/// coloured by the image seen through kaleidoscope `type`.
fn kaleidoimg(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        zoom,
        time,
        _blend,
        dc_color,
        angle,
        scale_x,
        scale_y,
        scale_z,
        offset_x,
        offset_y,
        offset_z,
        _tile_x,
        _tile_y,
        reset_z,
        kind,
        nr,
        a,
        b,
    ] = v.params();
    let x = rng.f01() - 0.5;
    let y = rng.f01() - 0.5;
    let sc = Scene {
        img: View::of(v.data()),
        time,
        nr: nr as i32,
        a,
        b,
    };
    let (s, c) = (angle.sin(), angle.cos());
    // Turned, scaled and moved (the shader's `uv * mat2(c, s, −s, c)`).
    let place = |p: V2| {
        let r = [c * p[0] + s * p[1], p[0] * -s + p[1] * c];
        [r[0] * scale_x + offset_x, r[1] * scale_y + offset_y]
    };
    let uv = [x * zoom, y * zoom];
    let img = &sc.img;
    let pixel = match kind as i32 {
        -1 => texture(img, place(uv)),
        0 => {
            let rgb = hsv(sc.mode0(uv), smoothstep(-3.0, 3.0, length(uv)));
            rgb.map(|c| f64::from(((c * 256.0).floor() as i32).clamp(0, 255)))
        }
        1 => texture(img, place(sc.mode1(uv))),
        2 => texture(img, place(sc.mode2(uv))),
        3 => texture(img, place(sc.mode3(uv))),
        4 => texture(img, place(sc.mode4(uv))),
        5 => {
            let p = place(sc.mode5(uv));
            texture(img, p.map(|c| c * 2.0 + time * 0.05))
        }
        6 => texture(img, place(sc.mode6(uv))),
        7 => sc.mode7(place(uv)),
        8 => {
            // The shader moves its point by the drift before adding the warp to it.
            let p = place(uv).map(|c| c + time * 0.25);
            let w = sc.mode8(p);
            texture(img, [p[0] + w[0], p[1] + w[1]])
        }
        9 => texture(img, sc.mode9(place(uv))),
        10 => texture(img, sc.mode10(place(uv))),
        11 => texture(img, sc.mode11(place(uv))),
        12 => texture(img, sc.mode12(place(uv))),
        _ => texture(img, sc.mode13(place(uv))),
    };
    let mut dz = offset_z;
    if scale_z.abs() > EPS {
        dz += scale_z * ((0.299 * pixel[0] + 0.588 * pixel[1] + 0.113 * pixel[2]) / 255.0);
    }
    let regular = v.form == Form::Regular;
    let z = if reset_z != 0.0 {
        if regular {
            acc.z = 0.0;
        }
        dz
    } else if regular {
        v.default_z(t) + dz
    } else {
        t.z + dz
    };
    if regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    if dc_color == 0.0 {
        // A negative channel (a blend reaching outside its pixels) or NaN counts as 0.
        acc.rgb = Some(pixel.map(|c| c.max(0.0)));
    } else {
        acc.rgb = None;
        let [r, g, b] = pixel.map(|c| f64::from(ftoi(c)));
        if let Some(k) = v.palette_coordinate(r, g, b) {
            acc.color = k;
        }
    }
    [v.w * x, v.w * y, z]
}
