//! Developing a histogram as JWildfire does: every bucket log-scaled on its own (with the
//! low-density brightness), the scaled buckets filtered by JWildfire's radial filter (for
//! sharpening kernels only the colour; the density then through a Gaussian of radius 0.75),
//! and JWildfire's tone map: gamma with its threshold, vibrancy, white level, colour balance,
//! the foreground's opacity over the background, and the saturation.
//!
//! The bucket grid is JWildfire's raster: the picture with a border of
//! [`JwfFilter::border`] buckets on every side, points rounded to the nearest bucket.

use std::sync::atomic::{AtomicBool, Ordering};

use image::DynamicImage;
use rayon::prelude::*;

use super::kernel::{JwfFilter, JwfKernel};
use super::{JwfBackground, JwfBackgroundKind, JwfLook};
use crate::flame::geometry::Geometry;
use crate::flame::histogram::{Bucket, COLOR_UNIT, Histogram};
use crate::flame::model::Flame;
use crate::flame::tonemap::OutputFormat;

/// JWildfire's palette colours run to 200 where flam3's run to 255 (a white level of 200
/// shows them at their own brightness).
pub(super) const PALETTE_WHITE: f64 = 200.0;

/// JWildfire's raster of one render: its border, its filters (the kernel at the flame's
/// radius, and for sharpening kernels the Gaussian that takes the density) and the random
/// offsets of its antialiasing.
#[derive(Clone, Debug, PartialEq)]
pub struct JwfRaster {
    pub primary: JwfFilter,
    pub density: Option<JwfFilter>,
    /// Buckets of border around the picture.
    pub border: usize,
    pub os: usize,
    /// The share of the points moved, and the spread of the move (none: `None`).
    pub antialias: Option<(f64, f64)>,
}

impl JwfRaster {
    pub fn new(look: &JwfLook, radius: f64, os: usize) -> JwfRaster {
        let primary = JwfFilter::new(look.kernel, radius, os);
        let density = (look.kernel.is_sharpening() && !primary.is_empty())
            .then(|| JwfFilter::new(JwfKernel::Gaussian, 0.75, os));
        let (amount, radius) = (look.antialias_amount, look.antialias_radius);
        JwfRaster {
            border: primary.border(os),
            primary,
            density,
            os,
            antialias: (amount > 1e-6 && radius > 1e-6).then_some((amount, radius)),
        }
    }

    /// JWildfire's antialiasing offset of one point, in buckets: with probability `amount` a
    /// random direction and a distance e^(radius·√(−ln u)) − 1, u uniform; otherwise none.
    #[inline(always)]
    pub fn jitter(amount: f64, radius: f64, rng: &mut crate::rng::FastRng) -> (f64, f64) {
        if rng.f01() > 1.0 - amount {
            let dr = (radius * (-rng.f01().ln()).sqrt()).exp() - 1.0;
            let (s, c) = (rng.f01() * std::f64::consts::TAU).sin_cos();
            (dr * c, dr * s)
        } else {
            (0.0, 0.0)
        }
    }

    /// The buckets a filter reads for pixel `p` along one axis: the first and the count.
    pub(super) fn window(&self, f: &JwfFilter, p: usize) -> (isize, usize) {
        if f.is_empty() {
            ((p * self.os + self.border) as isize, self.os)
        } else {
            ((p * self.os + self.border) as isize - f.lead(), f.size)
        }
    }

    /// The bucket rows (of the whole grid) that output rows `out` read.
    pub fn source_rows(
        &self,
        out: std::ops::Range<usize>,
        grid_rows: usize,
    ) -> std::ops::Range<usize> {
        if out.is_empty() {
            return 0..0;
        }
        let mut lo = isize::MAX;
        let mut hi = isize::MIN;
        for f in std::iter::once(&self.primary).chain(&self.density) {
            let (a, _) = self.window(f, out.start);
            let (b, n) = self.window(f, out.end - 1);
            lo = lo.min(a);
            hi = hi.max(b + n as isize);
        }
        let clamp = |v: isize| v.clamp(0, grid_rows as isize) as usize;
        clamp(lo)..clamp(hi)
    }
}

/// JWildfire's log scale of a bucket of `a` hits: (k1·log10(1 + x·k2) + glow/(x + 1))/(white·x)
/// with x = a/m, m the number of flames its motion blur draws (1 without).
#[derive(Clone, Copy, Debug)]
struct LogScale {
    k1: f64,
    k2: f64,
    glow: f64,
    white: f64,
    /// 1/m.
    blur: f64,
}

impl LogScale {
    /// `density` is the samples per pixel the picture is exposed for.
    fn new(flame: &Flame, density: f64, os: usize) -> LogScale {
        let os = os as f64;
        let ppu = flame.ppu();
        let area = flame.width as f64 * flame.height as f64 / (ppu * ppu);
        let k2 = 1.0 / (flame.contrast * area * density);
        let blurred = flame.jwf.motion_blur_length;
        // JWildfire turns the low-density brightness off for motion blur.
        let ldb = if blurred > 0 {
            0.0
        } else {
            flame.jwf.low_density_brightness
        };
        LogScale {
            k1: flame.contrast * 2.0 * flame.brightness / os,
            k2,
            glow: ldb * k2 * area / os,
            white: flame.jwf.white_level,
            blur: 1.0 / (blurred as f64 + 1.0),
        }
    }

    #[inline(always)]
    fn factor(&self, a: f64) -> f64 {
        let x = a * self.blur;
        (self.k1 * (1.0 + x * self.k2).log10() + self.glow / (x + 1.0)) / (self.white * x)
    }
}

/// The scaled buckets: colour ×ls (JWildfire's units, balanced), density ×ls·white.
fn scale_buckets(flame: &Flame, hist: &Histogram, density: f64, os: usize) -> Vec<Bucket> {
    let ls = LogScale::new(flame, density, os);
    let c = PALETTE_WHITE / 256.0 / COLOR_UNIT as f64 * 255.0;
    let bal = flame.jwf.balance.map(|b| b * c);
    hist.data
        .par_iter()
        .map(|b| {
            let a = b[3] as f64;
            if a > 0.0 {
                let s = ls.factor(a);
                [
                    (s * b[0] as f64 * bal[0]) as f32,
                    (s * b[1] as f64 * bal[1]) as f32,
                    (s * b[2] as f64 * bal[2]) as f32,
                    (s * a * ls.white) as f32,
                ]
            } else {
                [0.0; 4]
            }
        })
        .collect()
}

/// JWildfire's tone map of one pixel.
pub(super) struct ToneMap {
    gamma: f64,
    threshold: f64,
    /// threshold^(gamma − 1).
    scl_gamma: f64,
    vib: f64,
    inverse_vib: f64,
    alpha_scale: f64,
    saturation: f64,
    transparent: bool,
}

impl ToneMap {
    pub(super) fn new(flame: &Flame, transparent: bool) -> ToneMap {
        let gamma = if flame.gamma == 0.0 {
            0.0
        } else {
            1.0 / flame.gamma
        };
        let threshold = flame.gamma_threshold;
        let vib = (flame.vibrancy * 256.0 + 0.5).trunc().clamp(0.0, 256.0);
        ToneMap {
            gamma,
            threshold,
            scl_gamma: if threshold != 0.0 {
                threshold.powf(gamma - 1.0)
            } else {
                0.0
            },
            vib,
            inverse_vib: 256.0 - vib,
            alpha_scale: 1.0 - (3.0 * (flame.jwf.foreground_opacity - 1.0)).atan() / 1.25,
            saturation: (flame.jwf.saturation - 1.0).max(-1.0),
            transparent,
        }
    }

    /// Colour (0..=255, unrounded) and alpha (0..=1) of filtered colour `c` and density `i`
    /// over background `bg` (whole numbers 0..=255).
    fn pixel(&self, c: [f64; 3], i: f64, bg: [f64; 3]) -> ([f64; 3], f64) {
        if i.is_nan() || i <= 0.0 {
            return if self.transparent {
                ([0.0; 3], 0.0)
            } else if self.saturation != 0.0 {
                // JWildfire changes the saturation of the background too.
                (saturate(bg, self.saturation), 1.0)
            } else {
                (bg, 1.0)
            };
        }
        let alpha = if i <= self.threshold {
            let frac = i / self.threshold;
            (1.0 - frac) * i * self.scl_gamma + frac * i.powf(self.gamma)
        } else {
            i.powf(self.gamma)
        };
        let ls = self.vib * alpha / i;
        let alpha_int = java_int(alpha * 255.0 * self.alpha_scale + 0.5).clamp(0.0, 255.0);
        let inverse = 255.0 - alpha_int;
        let mut out = [0.0; 3];
        for k in 0..3 {
            let mut v = ls * c[k];
            if self.inverse_vib > 0.0 {
                v += self.inverse_vib * c[k].powf(self.gamma);
            }
            out[k] = if self.transparent {
                v
            } else {
                java_int(v + 0.5) + ((inverse * bg[k]) as i64 >> 8) as f64
            };
        }
        if self.transparent {
            let a = alpha_int / 255.0;
            if a <= 0.0 {
                return ([0.0; 3], 0.0);
            }
            return (out.map(|v| (v / a).clamp(0.0, 255.0)), a);
        }
        let mut out = out.map(|v| v.clamp(0.0, 255.0));
        if self.saturation != 0.0 {
            out = saturate(out, self.saturation);
        }
        (out, 1.0)
    }
}

impl ToneMap {
    /// Colour (0..=255, unrounded) and alpha (0..=1) of a pixel of a solid flame: lit colour
    /// `c` (0..=255 units) covering share `i` of the pixel, over background `bg`. As
    /// JWildfire's `GammaCorrectionFilter` composes solid colours: the coverage to the power
    /// 1 + 1/gamma is the opacity, and the colour is added to the background the rest of the
    /// opacity lets through (no vibrancy, no gamma on the colour).
    pub(super) fn solid_pixel(&self, c: [f64; 3], i: f64, bg: [f64; 3]) -> ([f64; 3], f64) {
        if i.is_nan() || i <= 0.0 {
            return self.pixel([0.0; 3], 0.0, bg);
        }
        let alpha = i.powf(1.0 + self.gamma);
        let alpha_int = java_int(alpha * 255.0 * self.alpha_scale + 0.5).clamp(0.0, 255.0);
        if self.transparent {
            let a = alpha_int / 255.0;
            if a <= 0.0 {
                return ([0.0; 3], 0.0);
            }
            return (c.map(|v| (v / a).clamp(0.0, 255.0)), a);
        }
        let inverse = 255.0 - alpha_int;
        let mut out =
            [0, 1, 2].map(|k| java_int(c[k] + 0.5) + ((inverse * bg[k]) as i64 >> 8) as f64);
        out = out.map(|v| v.clamp(0.0, 255.0));
        if self.saturation != 0.0 {
            out = saturate(out, self.saturation);
        }
        (out, 1.0)
    }
}

/// Java's conversion of a double to an int (towards zero, NaN to 0), as a double.
pub(super) fn java_int(v: f64) -> f64 {
    if v.is_nan() {
        0.0
    } else {
        v.trunc().clamp(i32::MIN as f64, i32::MAX as f64)
    }
}

/// JWildfire's saturation change: the colour to HSL, `add` added to the saturation, back to
/// RGB, each channel rounded.
fn saturate(c: [f64; 3], add: f64) -> [f64; 3] {
    let (h, s, l) = rgb_to_hsl(c.map(|v| v / 255.0));
    let rgb = hsl_to_rgb(h, s + add, l);
    rgb.map(|v| java_int(v * 255.0 + 0.5).clamp(0.0, 255.0))
}

/// RGB (0..=1) to hue, saturation and luminosity (0..=1), as JWildfire converts.
fn rgb_to_hsl(c: [f64; 3]) -> (f64, f64, f64) {
    const EPS: f64 = 1e-6;
    let [r, g, b] = c.map(|v| v.clamp(0.0, 1.0));
    let max = r.max(g).max(b);
    let min = r.min(g).min(b);
    let l = (min + max) / 2.0;
    if l.abs() <= EPS {
        return (1.0, 0.0, l);
    }
    let d = max - min;
    if d.abs() <= EPS {
        return (1.0, d, l);
    }
    let s = d / if l <= 0.5 { min + max } else { 2.0 - max - min };
    let h = if (r - max).abs() < EPS {
        if g == min {
            5.0 + (max - b) / d
        } else {
            1.0 - (max - g) / d
        }
    } else if (g - max).abs() < EPS {
        if b == min {
            1.0 + (max - r) / d
        } else {
            3.0 - (max - b) / d
        }
    } else if r == min {
        3.0 + (max - g) / d
    } else {
        5.0 - (max - r) / d
    };
    (h / 6.0, s, l)
}

/// Hue, saturation and luminosity (each clamped to 0..=1) to RGB, as JWildfire converts.
fn hsl_to_rgb(h: f64, s: f64, l: f64) -> [f64; 3] {
    let (h, s, l) = (h.clamp(0.0, 1.0), s.clamp(0.0, 1.0), l.clamp(0.0, 1.0));
    let v = if l <= 0.5 {
        l * (1.0 + s)
    } else {
        l + s - l * s
    };
    if v <= 0.0 {
        return [0.0; 3];
    }
    let h = (h * 6.0).clamp(0.0, 6.0);
    let y = l + l - v;
    let f = h - h.trunc();
    let x = y + (v - y) * f;
    let z = v - (v - y) * f;
    match h as u32 {
        1 => [z, v, y],
        2 => [y, v, x],
        3 => [y, z, v],
        4 => [x, y, v],
        5 => [v, y, z],
        _ => [v, x, y],
    }
}

/// The background of pixel (x, y) of a `w`×`h` picture, whole numbers 0..=255.
pub(super) fn background(
    bg: &JwfBackground,
    single: [f64; 3],
    x: usize,
    y: usize,
    w: usize,
    h: usize,
) -> [f64; 3] {
    let round = |v: f64| java_int(v * 255.0 + 0.5).clamp(0.0, 255.0);
    let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
    let blerp = |c: [[f64; 3]; 4], tx: f64, ty: f64| {
        [0, 1, 2].map(|k| {
            let v = lerp(lerp(c[0][k], c[1][k], tx), lerp(c[2][k], c[3][k], tx), ty);
            java_int(v + 0.5).clamp(0.0, 255.0)
        })
    };
    let ints = |c: [f64; 3]| c.map(round);
    match bg.kind {
        JwfBackgroundKind::SingleColor => ints(single),
        JwfBackgroundKind::Gradient2x2 => {
            let tx = x as f64 / (w as f64 - 1.0);
            let ty = y as f64 / (h as f64 - 1.0);
            blerp([ints(bg.ul), ints(bg.ur), ints(bg.ll), ints(bg.lr)], tx, ty)
        }
        JwfBackgroundKind::Gradient2x2C => {
            let (ul, ur, ll, lr, cc) = (
                ints(bg.ul),
                ints(bg.ur),
                ints(bg.ll),
                ints(bg.lr),
                ints(bg.cc),
            );
            let mid = |a: [f64; 3], b: [f64; 3]| [0, 1, 2].map(|k| lerp(a[k], b[k], 0.5));
            let (w2, h2) = ((w / 2) as f64 - 1.0, (h / 2) as f64 - 1.0);
            let (left, top) = (x as f64 <= w2, y as f64 <= h2);
            let tx = if left {
                x as f64 / w2
            } else {
                (x as f64 - w2) / w2
            };
            let ty = if top {
                y as f64 / h2
            } else {
                (y as f64 - h2) / h2
            };
            let corners = match (left, top) {
                (true, true) => [ul, mid(ul, ur), mid(ll, ul), cc],
                (true, false) => [mid(ul, ll), cc, ll, mid(ll, lr)],
                (false, true) => [mid(ul, ur), ur, cc, mid(ur, lr)],
                (false, false) => [cc, mid(ur, lr), mid(ll, lr), lr],
            };
            blerp(corners, tx, ty)
        }
    }
}

/// Develop the output rows `out_rows` of a JWildfire flame's histogram (which holds bucket rows
/// `geom.row0 .. geom.row0 + geom.bh` of the whole grid), or `None` when `stop` is set first.
#[allow(clippy::too_many_arguments)] // the parts of one develop step; bundling them buys nothing
pub(crate) fn develop(
    flame: &Flame,
    geom: &Geometry,
    filters: &JwfRaster,
    hist: &Histogram,
    density: f64,
    format: OutputFormat,
    out_rows: std::ops::Range<usize>,
    stop: &AtomicBool,
) -> Option<DynamicImage> {
    let os = filters.os;
    let scaled = scale_buckets(flame, hist, density, os);
    if stop.load(Ordering::Relaxed) {
        return None;
    }
    let (w, h) = (geom.width, geom.height);
    let (bw, full_bh) = (geom.bw as isize, geom.full_bh as isize);
    let (row0, bh) = (geom.row0 as isize, geom.bh as isize);
    // The scaled bucket at whole-grid column x, row y (empty outside the grid or the rows held).
    let at = |x: isize, y: isize| -> Option<&Bucket> {
        if x < 0 || x >= bw || y < 0 || y >= full_bh || y < row0 || y >= row0 + bh {
            return None;
        }
        scaled.get(((y - row0) * bw + x) as usize)
    };
    let sum = |f: &JwfFilter, px: usize, py: usize, density_only: bool| -> [f64; 4] {
        let (x0, nx) = filters.window(f, px);
        let (y0, ny) = filters.window(f, py);
        let mut s = [0.0; 4];
        for i in 0..ny {
            for j in 0..nx {
                let Some(b) = at(x0 + j as isize, y0 + i as isize) else {
                    continue;
                };
                let t = if f.is_empty() {
                    1.0
                } else {
                    f.taps[i * f.size + j]
                };
                if !density_only {
                    s[0] += t * b[0] as f64;
                    s[1] += t * b[1] as f64;
                    s[2] += t * b[2] as f64;
                }
                s[3] += t * b[3] as f64;
            }
        }
        s
    };
    let tm = ToneMap::new(flame, format.transparent);
    let rows: Vec<usize> = out_rows.collect();
    let pixels: Vec<Vec<([f64; 3], f64)>> = rows
        .par_iter()
        .map(|&py| {
            if stop.load(Ordering::Relaxed) {
                return Vec::new();
            }
            (0..w)
                .map(|px| {
                    let mut s = sum(&filters.primary, px, py, false);
                    if let Some(d) = &filters.density {
                        s[3] = sum(d, px, py, true)[3];
                    }
                    let c = [s[0].max(0.0), s[1].max(0.0), s[2].max(0.0)];
                    let bg = background(&flame.jwf.background, flame.background, px, py, w, h);
                    tm.pixel(c, s[3].max(0.0), bg)
                })
                .collect()
        })
        .collect();
    if stop.load(Ordering::Relaxed) {
        return None;
    }
    to_image(&pixels, w, rows.len(), format)
}

/// Rows of pixels (colour 0..=255 unrounded, alpha 0..=1) as an image of `w` columns.
pub(super) fn to_image(
    pixels: &[Vec<([f64; 3], f64)>],
    w: usize,
    n: usize,
    format: OutputFormat,
) -> Option<DynamicImage> {
    let channels = if format.transparent { 4 } else { 3 };
    let n = n as u32;
    let values = pixels.iter().flatten();
    Some(if format.bits16 {
        let buf: Vec<u16> = values
            .flat_map(|(c, a)| {
                let mut v = c.map(|v| (v * 257.0).round() as u16).to_vec();
                if channels == 4 {
                    v.push((a * 65535.0).round() as u16);
                }
                v
            })
            .collect();
        if channels == 4 {
            DynamicImage::ImageRgba16(image::ImageBuffer::from_raw(w as u32, n, buf)?)
        } else {
            DynamicImage::ImageRgb16(image::ImageBuffer::from_raw(w as u32, n, buf)?)
        }
    } else {
        let buf: Vec<u8> = values
            .flat_map(|(c, a)| {
                let mut v = c.map(|v| v as u8).to_vec();
                if channels == 4 {
                    v.push((a * 255.0).round() as u8);
                }
                v
            })
            .collect();
        if channels == 4 {
            DynamicImage::ImageRgba8(image::RgbaImage::from_raw(w as u32, n, buf)?)
        } else {
            DynamicImage::ImageRgb8(image::RgbImage::from_raw(w as u32, n, buf)?)
        }
    })
}
