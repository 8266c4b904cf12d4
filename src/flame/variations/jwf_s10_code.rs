//! JWildfire's escape-time pictures whose formula is Java source in a `code` resource, which
//! JWildfire compiles at run time (Janino): `glsl_code` (a GLSL-style colour function of a
//! pixel), `f_complex` (a complex function iterated from the point, six colourings) and
//! `ducks` (Samuel Monnier's "Ducks" iteration, log(x + i|y|) + c, five colourings). ugnis
//! cannot run Java: each computes what JWildfire's built-in default code computes, written
//! here natively, with every other parameter as JWildfire uses it. A flame whose code differs
//! from the default is still drawn, with the default; its reader reports it
//! ([`super::jwf_h9a_code::code_problem`]).
//!
//! The formulas follow JWildfire 9.00 (LGPL-2.1): `GLSLBaseFunc` with `glslFuncRunner`'s
//! `fractal`, `F_ComplexFunc` with its `ComplexFuncRunner` and the complex class
//! `org.jwildfire.base.mathlib.Complex`, `DucksFunc` with the complex class
//! `js.colordomain.Complex`; the Ducks iteration after Samuel Monnier,
//! algorithmic-worlds.net/blog/blog.php?Post=20110227. Written anew.

use super::jwf_direct_colour::dc_luma;
use super::jwf_h9b_code::domain_rgb as domain_colour;
use super::*;

/// The `code` text parameter: empty for JWildfire's default (a file holding the default's
/// text reads the same).
const fn code(name: &'static str) -> TextParam {
    TextParam {
        name,
        default: "",
        max_len: 1 << 16,
    }
}

/// A short text parameter with a default.
const fn text(name: &'static str, default: &'static str) -> TextParam {
    TextParam {
        name,
        default,
        max_len: 64,
    }
}

const COLOUR: u32 = flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("glsl_code", glsl_code)
        .params(&[
            // JWildfire's own bounds.
            p_int("glsl_code_ResolutionX", 1_000_000.0, 100.0, 1_000_000.0),
            p_int("glsl_code_ResolutionY", 1_000_000.0, 100.0, 1_000_000.0),
            p_range("glsl_code_zoom", 4.0, 0.0, 100.0),
            p_int("glsl_code_Gradient", 1.0, 0.0, 1.0),
        ])
        .texts(&[code("glsl_code_code")])
        .flags(COLOUR | flag::WRITES_Z),
    VarDef::new("f_complex", f_complex)
        .params(&[
            // The seed of JWildfire's "randomize" (which draws the colour type, escape radius,
            // iteration counts and c when set; a file sets those after it, so it changes
            // nothing when a flame is read).
            p_int("f_complex_randomize", 10000.0, 1.0, 10_000_000.0),
            p_range("f_complex_contrast", 0.5, 0.0, 1.0),
            p("f_complex_zoom", 2.5),
            p("f_complex_Pan_Re", 0.0),
            p("f_complex_Pan_Im", 0.0),
            p("f_complex_escape", 4.0),
            p_int("f_complex_Iters", 50.0, 1.0, 250.0).limited(),
            // At most Iters (JWildfire clamps it to the Iters set before it).
            p_int("f_complex_preIters", 1.0, 1.0, 250.0),
            p_int("f_complex_Julia mode", 1.0, 0.0, 1.0),
            p("f_complex_c-real", 0.32),
            p("f_complex_c-imag", -0.906),
            p_int("f_complex_ColorType", 2.0, 0.0, 5.0),
            p_int("f_complex_ColorOnly", 0.0, 0.0, 1.0),
            p("f_complex_scale_z", 0.0),
            p("f_complex_offset_z", 0.0),
            p_int("f_complex_reset_z", 1.0, 0.0, 1.0),
        ])
        .texts(&[code("f_complex_code")])
        .flags(COLOUR | flag::WRITES_Z | flag::WRITES_ACC),
    VarDef::new("ducks", ducks)
        .params(&[
            p_int("ducks_size", 1500.0, 100.0, 10000.0),
            p("ducks_re_min", -2.0),
            p("ducks_re_max", 2.0),
            p("ducks_im_min", -3.2),
            p("ducks_im_max", 0.8),
            // JWildfire's view buttons: each zooms or pans the rectangle when set; as a file
            // sets all of them, one after the other, the rectangle comes back to itself (up
            // to rounding), and ugnis uses the stored one.
            p_int("ducks_zoomIn", 1.0, 0.0, 1.0),
            p_int("ducks_zoomOut", 1.0, 1.0, 1.0),
            p_int("ducks_Pan -Re", 1.0, 1.0, 1.0),
            p_int("ducks_Pan +Re", 1.0, 1.0, 1.0),
            p_int("ducks_Pan -Im", 1.0, 1.0, 1.0),
            p_int("ducks_Pan +Im", 1.0, 1.0, 1.0),
            p_int("ducks_julia Mode", 0.0, 0.0, 1.0),
            p_range("ducks_c_re", 0.672, -15.0, 8.0),
            p_range("ducks_c_im", -0.378, -15.0, 8.0),
            p_int("ducks_MaxIters", 50.0, 1.0, 50.0).limited(),
            p_int("ducks_MinIters", 1.0, 1.0, 50.0),
            p_int("ducks_ColorType", 4.0, 0.0, 4.0),
            p_range("ducks_ScapeSize", 5.0, 0.0, 11.0),
            p_range("ducks_Contrast", 1.0, 0.0, 2.0),
            p_int("ducks_ColorFactor", 1.0, 0.0, 1.0),
            p_int("ducks_Gradient", 1.0, 0.0, 1.0),
            p_range("ducks_colorScale", 1.0, 0.0, 10.0),
            p_range("ducks_colorCycle", 2.0, 1.0, 10.0),
            p_range("ducks_colorOffset", 0.0, -10.0, 10.0),
            p_int("ducks_colorMirror", 1.0, 0.0, 1.0),
            p_int("ducks_colorRainbow", 0.0, 0.0, 1.0),
        ])
        .texts(&[
            code("ducks_code"),
            text("ducks_Col1 R,G,B", "0,102,178"),
            text("ducks_Col2 R,G,B", "  0,  0,  0"),
        ])
        .prepare(ducks_prepare)
        .flags(COLOUR),
];

/// Java's `(int)` of 256·c kept at most 255 (JWildfire's `dbl2int`), and at least 0.
fn byte(c: f64) -> i64 {
    ((256.0 * c) as i64).clamp(0, 255)
}

fn bytes(c: [f64; 3]) -> [i64; 3] {
    c.map(byte)
}

/// log₂ as JWildfire computes it: ln x / ln 2.
fn log2(x: f64) -> f64 {
    x.ln() / std::f64::consts::LN_2
}

/// JWildfire's own colour (bytes) for the point, or the nearest key of the palette to it.
fn own_colour(acc: &mut Acc, c: [i64; 3], nearest: bool) {
    let lower = if nearest { Acc::NEAREST_KEY } else { 0.0 };
    acc.rgb = Some(c.map(|b| b as f64 - lower));
}

// ---------------------------------------------------------------------------------------
// glsl_code

/// `glslFuncRunner.fractal`: the Mandelbrot set at p, coloured by the escape count i as
/// 0.6 + 0.4·(cos(s + 0.9), cos(s + 0.3), cos(s + 0.2)) with s = 0.125662·i; black inside.
pub(super) fn glsl_fractal(px: f64, py: f64) -> [f64; 3] {
    let (mut x, mut y) = (0.0f64, 0.0f64);
    for i in 0..50 {
        (x, y) = (x * x - y * y + px, 2.0 * x * y + py);
        if x * x + y * y > 4.0 {
            let s = 0.125662 * f64::from(i);
            return [(s + 0.9).cos(), (s + 0.3).cos(), (s + 0.2).cos()].map(|c| c * 0.4 + 0.6);
        }
    }
    [0.0; 3]
}

/// glsl_code: a random pixel of a `ResolutionX` × `ResolutionY` grid over the unit square,
/// centred on the origin, coloured by the default code: the pixel centre mapped to
/// [−1, 1]², times `zoom`, moved by −½ along x, through [`glsl_fractal`]. With Gradient 0 the
/// colour is the point's own; else the palette coordinate is its red times its green.
fn glsl_code(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [res_x, res_y, zoom, gradient] = v.params();
    let i = (rng.f01() * res_x).trunc();
    let j = (rng.f01() * res_y).trunc();
    let sx = 2.0 * (i + 0.5) / res_x - 1.0;
    let sy = 2.0 * (j + 0.5) / res_y - 1.0;
    let c = glsl_fractal(sx * zoom - 0.5, sy * zoom);
    if gradient as i64 == 0 {
        own_colour(acc, bytes(c), false);
    } else {
        acc.color = c[0] * c[1];
    }
    [v.w * (i / res_x - 0.5), v.w * (j / res_y - 0.5), 0.0]
}

// ---------------------------------------------------------------------------------------
// f_complex

/// The rounded 2π of JWildfire's cosine palette (`ComplexFuncRunner.palette`; kept: it is
/// not the nearest double to 2π).
#[allow(clippy::approx_constant)]
const ROUGH_TAU: f64 = 6.28318;

/// The default code's function: log(x + i|y|) + c, the logarithm of
/// `org.jwildfire.base.mathlib.Complex` (which adds 1e-20 to |z|² against the singularity).
#[inline]
fn f_complex_f((x, y): (f64, f64), (cx, cy): (f64, f64)) -> (f64, f64) {
    let ay = y.abs();
    (0.5 * (x * x + ay * ay + 1e-20).ln() + cx, ay.atan2(x) + cy)
}

/// f_complex: the point (random in [−1, 1]², or the input with ColorOnly = 1) times `zoom`,
/// less (Pan_Re, Pan_Im), is z₀ (and c, unless Julia mode takes c = (c-real, c-imag)); the
/// default function iterated from it gives the colour, by ColorType: 0 the domain colouring
/// after `Iters` steps; 1 the palette coordinate from the grey of a cosine colour of the sum
/// d of |z|² past `preIters` steps (to the escape, |z|² > `escape`); 2 a cosine palette of
/// the smooth escape count; 3 the palette colour nearest to a cosine colour of d; 4 the
/// smooth escape count as the palette coordinate; 5 the default code's `rgbColor`, |z|²
/// scaled by `contrast`. Its grey (the coordinate for type 4), scaled and offset, is z.
fn f_complex(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        contrast,
        zoom,
        pan_re,
        pan_im,
        escape,
        iters,
        pre_iters,
        julia,
        c_re,
        c_im,
        colour_type,
        colour_only,
        scale_z,
        offset_z,
        reset_z,
    ] = v.params();
    let (ux, uy) = if colour_only as i64 == 0 {
        let x = 2.0 * rng.f01() - 1.0;
        (x, 2.0 * rng.f01() - 1.0)
    } else {
        (t.x, t.y)
    };
    let max_iters = iters as i64;
    let n_iters = (pre_iters as i64).min(max_iters);
    let z0 = (ux * zoom - pan_re, uy * zoom - pan_im);
    let c = if julia as i64 == 1 { (c_re, c_im) } else { z0 };
    let mag2 = |z: (f64, f64)| z.0 * z.0 + z.1 * z.1;
    // The iteration to the escape: the last z, the step it escaped at (0 if none) and the sum
    // of |z|² past the first n_iters + 1 steps.
    let escaping = || {
        let mut z = z0;
        let (mut it, mut d) = (0, 0.0);
        for k in 0..max_iters {
            z = f_complex_f(z, c);
            if k > n_iters {
                d += mag2(z);
                if mag2(z) > escape {
                    it = k;
                    break;
                }
            }
        }
        (z, it as f64, d)
    };
    let cosine = |s: f64, phases: [f64; 3]| phases.map(|ph| (s + ph).cos() * 0.4 + 0.6);
    let smooth = |z: (f64, f64), it: f64| it - log2(log2(mag2(z))) + 4.0;
    let mut rgb = [0i64; 3];
    let mut grey_of_rgb = true;
    match colour_type as i64 {
        0 => {
            let mut z = z0;
            for _ in 0..max_iters {
                z = f_complex_f(z, c);
            }
            rgb = bytes(domain_colour(z.0, z.1));
            own_colour(acc, rgb, false);
        }
        1 => {
            let (_, _, d) = escaping();
            rgb = bytes(cosine(0.125662 * d, [0.2, 0.3, 0.6]));
            acc.color = dc_luma(rgb);
        }
        2 => {
            let (z, it, _) = escaping();
            let s = smooth(z, it) / max_iters as f64;
            let g = 0.5 + 0.5 * (ROUGH_TAU * (s + 1.0)).cos();
            rgb = bytes([g; 3]);
            own_colour(acc, rgb, false);
        }
        3 => {
            let (_, _, d) = escaping();
            rgb = bytes(cosine(0.125662 * d, [0.9, 0.3, 0.2]));
            own_colour(acc, rgb, true);
        }
        4 => {
            let (z, it, _) = escaping();
            acc.color = smooth(z, it) / max_iters as f64;
            grey_of_rgb = false;
        }
        _ => {
            let (z, _, _) = escaping();
            let m = mag2(z);
            rgb = bytes([m / 64.0, m / 32.0, m / 24.0].map(|c| c * m * contrast));
            own_colour(acc, rgb, false);
        }
    }
    let cz = if grey_of_rgb { dc_luma(rgb) } else { acc.color };
    let dz = cz * scale_z + offset_z;
    let z = if reset_z as i64 == 1 {
        if v.form == Form::Regular {
            acc.z = 0.0;
        }
        dz
    } else if v.form == Form::Regular {
        dz
    } else {
        t.z + dz
    };
    [v.w * ux, v.w * uy, z]
}

// ---------------------------------------------------------------------------------------
// ducks

/// JWildfire's `convColor`: "r,g,b" as integers over 255; a text it cannot read (fewer than
/// three parts, or a part not an integer: spaces count) gives `fallback`.
fn parse_colour(s: &str, fallback: [f64; 3]) -> [f64; 3] {
    let parts: Vec<&str> = s.split(',').take(3).collect();
    if parts.len() < 3 {
        return fallback;
    }
    let mut c = [0.0; 3];
    for (k, part) in parts.iter().enumerate() {
        match part.parse::<i32>() {
            Ok(n) => c[k] = f64::from(n) / 255.0,
            Err(_) => return fallback,
        }
    }
    c
}

/// The two colours of the FractalLab colouring, from the texts (white and black when
/// unreadable).
fn ducks_prepare(v: &mut Prepared) {
    let text = |k: usize| v.texts.get(k).map_or("", String::as_str);
    let c1 = parse_colour(text(1), [1.0; 3]);
    let c2 = parse_colour(text(2), [0.0; 3]);
    v.p.extend_from_slice(&c1);
    v.p.extend_from_slice(&c2);
}

/// The default code's function: log(x + i|y|) + c with `js.colordomain.Complex`'s logarithm
/// (ln of the modulus, 0 for z = 0, so −∞ there).
#[inline]
fn ducks_f((x, y): (f64, f64), (cx, cy): (f64, f64)) -> (f64, f64) {
    let ay = y.abs();
    let m = if x != 0.0 || ay != 0.0 {
        (x * x + ay * ay).sqrt()
    } else {
        0.0
    };
    (m.ln() + cx, ay.atan2(x) + cy)
}

/// JWildfire's `hsv2rgb` (which ducks applies to a mix of two red-green-blue colours: its
/// `rgb2hsv` returns the colour it was given).
fn hsv2rgb([h, s, v]: [f64; 3]) -> [f64; 3] {
    let h = if h == 1.0 { 0.0 } else { h };
    if v == 0.0 {
        return [0.0; 3];
    }
    if s == 0.0 {
        return [v; 3];
    }
    let h = h * 6.0;
    let i = h.floor();
    let j = h - i;
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - s * j), v * (1.0 - s * (1.0 - j)));
    match i as i64 {
        0 => [v, t, p],
        1 => [q, v, p],
        2 => [p, v, t],
        3 => [p, q, v],
        4 => [t, p, v],
        5 => [v, p, q],
        _ => [0.0; 3],
    }
}

fn mix(a: [f64; 3], b: [f64; 3], t: f64) -> [f64; 3] {
    [0, 1, 2].map(|k| a[k] * (1.0 - t) + b[k] * t)
}

/// ducks: a random node (i, j) of a `size` × `size` grid over the unit square, centred on the
/// origin, coloured by the default function iterated from the matching point c of the
/// rectangle [re_min, re_max] × [im_min, im_max] (with "julia Mode" c is (c_re, c_im) and the
/// point only the start). ColorType 4 (FractalLab) blends the two colours by the root mean
/// |z|² past `MinIters` steps (scaled, cycled, offset, mirrored; through `hsv2rgb` with
/// colorRainbow); 0 is the domain colouring of the last z; 1–3 are Fragmentarium's smooth
/// colourings (the mean modulus, a running blend of it, the escape count), their own colour
/// with Gradient 0, else their count over `MaxIters` as the palette coordinate. JWildfire
/// switches Gradient off for types 0 and 4.
fn ducks(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        size,
        re_min,
        re_max,
        im_min,
        im_max,
        _,
        _,
        _,
        _,
        _,
        _,
        julia,
        c_re,
        c_im,
        max_iters,
        n_iters,
        colour_type,
        escape,
        contrast,
        colour_factor,
        gradient,
        colour_scale,
        colour_cycle,
        colour_offset,
        mirror,
        rainbow,
    ] = v.params();
    let [r1, g1, b1, r2, g2, b2] = v.derived();
    let (c1, c2) = ([r1, g1, b1], [r2, g2, b2]);
    let j = (rng.f01() * size).trunc();
    let i = (rng.f01() * size).trunc();
    let im = im_max - ((im_max - im_min) * j) / (size - 1.0);
    let re = re_min - ((re_min - re_max) * i) / (size - 1.0);
    let mut z = (re, im);
    let c = if julia as i64 == 1 { (c_re, c_im) } else { z };
    let max_iters = max_iters as i64;
    let n_iters = n_iters as i64;
    let norm = |z: (f64, f64)| z.0 * z.0 + z.1 * z.1;
    let modulus = |z: (f64, f64)| {
        if z.0 != 0.0 || z.1 != 0.0 {
            norm(z).sqrt()
        } else {
            0.0
        }
    };
    let cosine = |ci: f64| [r1, g1, b1].map(|ph| 0.5 + 0.5 * (6.0 * ci + ph).cos());
    // Colour and whether Gradient may give the palette coordinate instead.
    let mut col = 0.5;
    let (colour, gradient_allowed) = match colour_type as i64 {
        0 => {
            for _ in 0..max_iters {
                z = ducks_f(z, c);
            }
            (domain_colour(z.0, z.1), false)
        }
        1 => {
            let (mut mean, mut it) = (0.0, 0);
            for k in 0..max_iters {
                z = ducks_f(z, c);
                if k > n_iters {
                    mean += modulus(z);
                    if norm(z) > escape {
                        it = k;
                        break;
                    }
                }
            }
            mean /= (it - n_iters) as f64;
            let ci = 1.0 - log2(0.5 * log2(mean / contrast));
            col = ci / max_iters as f64;
            (cosine(ci), true)
        }
        2 => {
            let mut m = 0.0;
            for k in 0..max_iters {
                z = ducks_f(z, c);
                if k > n_iters {
                    m = m * (1.0 - colour_factor) + modulus(z) * colour_factor;
                    if norm(z) > escape {
                        break;
                    }
                }
            }
            let ci = 1.0 - log2(0.5 * log2(m / contrast));
            col = ci / max_iters as f64;
            (cosine(ci), true)
        }
        3 => {
            let mut m = 0;
            for k in 0..max_iters {
                z = ducks_f(z, c);
                if norm(z) > escape && k > n_iters {
                    m = k;
                    break;
                }
            }
            let ci = m as f64 + 1.0 - log2(0.5 * log2(norm(z)));
            col = ci / max_iters as f64;
            (cosine(ci), true)
        }
        _ => {
            let mut d = 0.0;
            for k in 1..=max_iters {
                z = ducks_f(z, c);
                if k >= n_iters {
                    d += norm(z);
                }
            }
            let mut x = (d / max_iters as f64).sqrt().powf(colour_scale);
            x = x * colour_cycle + colour_offset;
            x = if mirror as i64 == 1 && x % 2.0 >= 1.0 {
                x % 1.0
            } else {
                1.0 - x % 1.0
            };
            let a = x.clamp(0.0, 1.0);
            let colour = if rainbow as i64 == 1 {
                hsv2rgb(mix(c1, c2, a))
            } else {
                mix(c1, c2, a)
            };
            (colour, false)
        }
    };
    if gradient_allowed && gradient as i64 != 0 {
        acc.color = col;
    } else {
        own_colour(acc, bytes(colour), false);
    }
    [
        v.w * (i / size - 0.5),
        v.w * (j / size - 0.5),
        v.default_z(t),
    ]
}

#[cfg(test)]
mod tests {
    use super::super::jwf_h9a_code::code_problem;
    use super::super::jwf_h9b_code::set_hsv;
    use super::*;

    #[test]
    fn code_other_than_the_default_is_reported() {
        let t = |s: &str| vec![s.to_string()];
        assert_eq!(code_problem("ducks", &t("")), None);
        let default = "import js.colordomain.Complex;\r\npublic Complex f(Complex z, Complex c)\r\n\
             {\r\n Complex tmp = new Complex(z.re(),Math.abs(z.im()));\r\n \
             return tmp.Log().plus(new Complex(c.re(),c.im()));\r\n }";
        assert_eq!(code_problem("ducks", &t(default)), None);
        let w = code_problem("f_complex", &t("public Complex f() {}")).unwrap();
        assert!(w.contains("f_complex") && w.contains("default code is used"));
    }

    #[test]
    fn colours_read_as_java_reads_them() {
        assert_eq!(
            parse_colour("0,102,178", [1.0; 3]),
            [0.0, 0.4, 178.0 / 255.0]
        );
        // Java's parseInt takes no spaces: the default second colour falls back to black.
        assert_eq!(parse_colour("  0,  0,  0", [0.0; 3]), [0.0; 3]);
        assert_eq!(parse_colour("1,2", [1.0; 3]), [1.0; 3]);
    }

    #[test]
    fn escape_colours_and_functions() {
        // The Mandelbrot set's inside is black; c = 1 escapes at the third step (i = 2).
        assert_eq!(glsl_fractal(0.0, 0.0), [0.0; 3]);
        let s: f64 = 0.125662 * 2.0;
        let want = [(s + 0.9).cos(), (s + 0.3).cos(), (s + 0.2).cos()].map(|c| c * 0.4 + 0.6);
        assert_eq!(glsl_fractal(1.0, 0.0), want);
        // log(e + 0i) + 0 = 1; log(−1 + 0i) has argument π; |y| taken first.
        let (x, y) = ducks_f((std::f64::consts::E, -0.0), (0.0, 0.0));
        assert!((x - 1.0).abs() < 1e-15 && y == 0.0);
        let (_, y) = ducks_f((-1.0, 0.0), (0.0, 0.0));
        assert_eq!(y, std::f64::consts::PI);
        let (x, _) = f_complex_f((0.0, 0.0), (0.25, 0.0));
        assert!((x - (0.5 * 1e-20f64.ln() + 0.25)).abs() < 1e-12);
        // Hue 0, full saturation and value: red.
        assert_eq!(set_hsv(0.0, 1.0, 1.0), [1.0, 0.0, 0.0]);
        assert_eq!(hsv2rgb([0.5, 1.0, 1.0]), [0.0, 1.0, 1.0]);
    }
}
