//! Log-density scaling and tone mapping.

use crate::flame::model::{Flame, PaletteIndex};
use crate::gradient::{hsv_to_rgb, rgb_to_hsv};

/// The tone scale of the program that wrote a flame: (the factor of brightness in k1 beyond
/// the accumulators' 255 per hit, the output value of full intensity). flam3 (and Apophysis,
/// which copies it) multiplies brightness by 268/256 and scales its output to 256 before
/// clamping at 255; Fractorium does neither (brightness as given, output to 255), which draws
/// its pictures about 1.5 % darker — 4–7 % in the faint parts.
fn writer_scale(flame: &Flame) -> (f64, f64) {
    match flame.palette_index {
        PaletteIndex::Fractorium => (1.0, 255.0),
        _ => (268.0 / 256.0, 256.0),
    }
}

/// ls(A) = k1·ln(1 + A·k2)/A, with A in hits (flam3's A/255).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogScale {
    pub k1: f64,
    pub k2: f64,
}

impl LogScale {
    /// `density` is quality·4^zoom for a finished render, or samples done / (W·H) for a preview.
    pub fn new(flame: &Flame, density: f64) -> LogScale {
        let os = flame.supersample.max(1) as f64;
        let contrast = flame.contrast;
        let ppu = flame.ppu();
        let area = flame.width as f64 * flame.height as f64 / (ppu * ppu);
        LogScale {
            k1: contrast * flame.brightness * 255.0 * writer_scale(flame).0,
            k2: os * os / (contrast * area * density),
        }
    }

    #[inline(always)]
    pub fn factor(&self, a: f64) -> f64 {
        if a > 0.0 {
            self.k1 * (a * self.k2).ln_1p() / a
        } else {
            0.0
        }
    }
}

/// [`LogScale::factor`] of a bucket's f32 count, with the factors of the small whole counts (the
/// usual buckets of a preview: every sample adds 1) read from a table: same values, no log.
#[derive(Clone, Debug)]
pub struct LogTable {
    pub ls: LogScale,
    small: Vec<f32>,
}

impl LogTable {
    /// Counts below this are looked up when whole.
    const SMALL: u32 = 1024;

    pub fn new(ls: LogScale) -> LogTable {
        LogTable {
            ls,
            small: (0..Self::SMALL)
                .map(|n| ls.factor(n as f64) as f32)
                .collect(),
        }
    }

    /// `ls.factor(a as f64) as f32`, bit for bit.
    #[inline(always)]
    pub fn factor(&self, a: f32) -> f32 {
        // Saturating cast: negative and NaN give 0, which `a` then does not equal (NaN) or
        // whose factor is 0 like a negative count's.
        let n = a as u32;
        if n < Self::SMALL && n as f32 == a {
            self.small[n as usize]
        } else {
            self.ls.factor(a as f64) as f32
        }
    }
}

/// Output encoding of the tone-mapped image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct OutputFormat {
    /// 8 or 16 bits per channel.
    pub bits16: bool,
    /// Alpha channel from density instead of blending over the background.
    pub transparent: bool,
}

/// Per-pixel tone mapping constants.
#[derive(Clone, Debug)]
pub struct ToneMap {
    /// Colour curves, when the flame has any other than the identity.
    pub curves: Option<std::sync::Arc<crate::flame::curves::CurveLut>>,
    pub g: f64,
    pub threshold: f64,
    pub vibrancy: f64,
    pub highlight_power: f64,
    pub background: [f64; 3],
    pub transparent: bool,
    /// The output value of full intensity before the clamp at 255 (256 for flam3).
    pub white: f64,
    /// t^g / t, precomputed for the threshold blend.
    thresh_factor: f64,
}

impl ToneMap {
    pub fn new(flame: &Flame, transparent: bool) -> ToneMap {
        let g = 1.0 / flame.gamma;
        let t = flame.gamma_threshold;
        ToneMap {
            curves: (!flame.curves.is_identity()).then(|| std::sync::Arc::new(flame.curves.lut())),
            g,
            threshold: t,
            vibrancy: flame.vibrancy,
            highlight_power: flame.highlight_power,
            background: flame.background,
            transparent,
            white: writer_scale(flame).1,
            thresh_factor: if t > 0.0 { t.powf(g) / t } else { 0.0 },
        }
    }

    /// alpha = a^g above the threshold, a linear blend below (flam3's gamma threshold), for
    /// a > 0. Branch-free, so that a loop over a row of pixels vectorises.
    #[inline(always)]
    pub fn gamma_alpha(&self, a: f64) -> f64 {
        let p = crate::flame::fastmath::pow_pos(a, self.g);
        if a >= self.threshold {
            p
        } else {
            let f = a / self.threshold;
            (1.0 - f) * a * self.thresh_factor + f * p
        }
    }

    /// The unclamped alpha of a filtered density `a_raw` (flam3 units): 0 where nothing was
    /// drawn. Branch-free.
    #[inline(always)]
    pub fn alpha(&self, a_raw: f64) -> f64 {
        let alpha = self.gamma_alpha(a_raw / 255.0);
        if a_raw <= 0.0 { 0.0 } else { alpha }
    }

    /// Map filtered accumulators (flam3 units, channel/255 = density) to output values in
    /// 0..=255 (not yet truncated) and the alpha in [0, 1].
    #[cfg(test)]
    pub fn pixel(&self, acc: [f64; 4]) -> ([f64; 3], f64) {
        self.pixel_with_alpha(acc, self.alpha(acc[3]))
    }

    /// The output values and alpha of filtered accumulators (flam3 units, channel/255 =
    /// density), given `alpha` = [`ToneMap::alpha`]`(acc[3])` (computed for a whole row at once).
    #[inline(always)]
    pub fn pixel_with_alpha(&self, acc: [f64; 4], alpha: f64) -> ([f64; 3], f64) {
        let a_raw = acc[3];
        let (alpha, ls) = if a_raw <= 0.0 {
            (0.0, 0.0)
        } else {
            let a = a_raw / 255.0;
            let ls = self.vibrancy * self.white * alpha / a;
            (alpha.clamp(0.0, 1.0), ls)
        };
        let c = [
            acc[0].max(0.0) / 255.0,
            acc[1].max(0.0) / 255.0,
            acc[2].max(0.0) / 255.0,
        ];
        let newrgb = highlight(c, ls, self.highlight_power);
        let mut out = [0.0; 3];
        for k in 0..3 {
            let mut v = newrgb[k];
            if self.vibrancy != 1.0 {
                v += (1.0 - self.vibrancy) * self.white * c[k].powf(self.g);
            }
            if !self.transparent {
                v += (1.0 - alpha) * self.white * self.background[k];
            } else if alpha > 0.0 {
                v /= alpha;
            } else {
                v = 0.0;
            }
            if let Some(c) = &self.curves {
                v = self.white * c.apply(v / self.white, k);
            }
            out[k] = v.clamp(0.0, 255.0);
        }
        (out, alpha)
    }
}

impl ToneMap {
    /// Tone-map a row of filtered accumulators: `out[i]` = ([`ToneMap::pixel_with_alpha`]'s
    /// three values, then the alpha), `alphas[i]` = [`ToneMap::alpha`]`(line[i][3])`. The usual
    /// pixels (no curves, vibrancy 1, nothing saturating) take a branch-free loop that
    /// vectorises; the others are then redone one by one. Same values as pixel by pixel.
    #[inline(always)]
    pub fn row(&self, line: &[[f64; 4]], alphas: &[f64], out: &mut [[f64; 4]]) {
        let scalar = |s: [f64; 4], a: f64| {
            let (rgb, alpha) = self.pixel_with_alpha(s, a);
            [rgb[0], rgb[1], rgb[2], alpha]
        };
        if self.curves.is_some() || self.vibrancy != 1.0 {
            for ((o, &s), &a) in out.iter_mut().zip(line).zip(alphas) {
                *o = scalar(s, a);
            }
            return;
        }
        let bg = self.background.map(|b| self.white * b);
        let mut any_slow = false;
        for ((o, &s), &au) in out.iter_mut().zip(line).zip(alphas) {
            let (n, alpha, slow) = self.usual(s, au);
            any_slow |= slow;
            let mut v = [0.0; 4];
            for k in 0..3 {
                v[k] = if !self.transparent {
                    n[k] + (1.0 - alpha) * bg[k]
                } else if alpha > 0.0 {
                    n[k] / alpha
                } else {
                    0.0
                };
                v[k] = v[k].clamp(0.0, 255.0);
            }
            v[3] = alpha;
            *o = v;
        }
        if any_slow {
            for ((o, &s), &au) in out.iter_mut().zip(line).zip(alphas) {
                if self.usual(s, au).2 {
                    *o = scalar(s, au);
                }
            }
        }
    }

    /// The scaled colour and clamped alpha of a pixel when [`highlight`] leaves the colour as
    /// it is (vibrancy 1), and whether it does not: a channel above 255 or NaN — except with a
    /// highlight power of −1 or below (flam3's default), whose blend weight λ = 1 keeps the
    /// scale ls exactly (0·newls + ls) whenever the channels are finite.
    #[inline(always)]
    fn usual(&self, s: [f64; 4], au: f64) -> ([f64; 3], f64, bool) {
        let empty = s[3] <= 0.0;
        let ls = self.vibrancy * self.white * au / (s[3] / 255.0);
        let ls = if empty { 0.0 } else { ls };
        let alpha = if empty { 0.0 } else { au.clamp(0.0, 1.0) };
        let n = [
            ls * (s[0].max(0.0) / 255.0),
            ls * (s[1].max(0.0) / 255.0),
            ls * (s[2].max(0.0) / 255.0),
        ];
        let saturating = !(n[0] <= 255.0 && n[1] <= 255.0 && n[2] <= 255.0);
        let kept = self.highlight_power <= -1.0 && n.iter().all(|v| v.is_finite());
        (n, alpha, saturating && !kept)
    }
}

/// flam3 `flam3_calc_newrgb`: scale a colour by ls with highlight handling.
#[inline(always)]
pub fn highlight(c: [f64; 3], ls: f64, hp: f64) -> [f64; 3] {
    if ls == 0.0 || (c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0) {
        return [0.0; 3];
    }
    let mut m = 0;
    for k in 1..3 {
        if ls * c[k] > ls * c[m] {
            m = k;
        }
    }
    let maxa = ls * c[m];
    if maxa <= 255.0 || maxa.is_nan() {
        // λ = 1: (1 − λ)·newls + λ·ls is ls exactly (newls is finite, c[m] > 0).
        return [ls * c[0], ls * c[1], ls * c[2]];
    }
    let newls = 255.0 / c[m];
    if hp >= 0.0 {
        let col = [
            newls * c[0] / 255.0,
            newls * c[1] / 255.0,
            newls * c[2] / 255.0,
        ];
        let mut hsv = rgb_to_hsv(col);
        hsv[1] *= (newls / ls).powf(hp);
        let col = hsv_to_rgb(hsv);
        [255.0 * col[0], 255.0 * col[1], 255.0 * col[2]]
    } else {
        let lambda = (-hp).min(1.0);
        let s = (1.0 - lambda) * newls + lambda * ls;
        [s * c[0], s * c[1], s * c[2]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn oracle_flame() -> Flame {
        Flame {
            width: 100,
            height: 100,
            scale: 50.0,
            quality: 10.0,
            brightness: 4.0,
            contrast: 1.0,
            supersample: 1,
            ..Flame::default()
        }
    }

    #[test]
    fn the_log_table_gives_the_factor_bit_for_bit() {
        let t = LogTable::new(LogScale::new(&oracle_flame(), 3.7));
        for a in [
            0.0f32,
            1.0,
            2.0,
            7.0,
            1023.0,
            1024.0,
            1e6,
            0.5,
            2.25,
            -1.0,
            -0.0,
            f32::NAN,
        ] {
            let want = t.ls.factor(a as f64) as f32;
            assert_eq!(t.factor(a).to_bits(), want.to_bits(), "{a}");
        }
    }

    /// The row-at-once tone map gives what the pixel-by-pixel one gives, bit for bit: empty,
    /// faint, saturating (both highlight modes), negative and NaN accumulators, opaque and
    /// transparent, with and without vibrancy and curves.
    #[test]
    fn a_row_is_tone_mapped_as_its_pixels() {
        let mut rng = crate::flame::rng::FastRng::new(9);
        let mut line: Vec<[f64; 4]> = (0..400)
            .map(|i| {
                let a = [0.0, 1e-3, 0.7, 40.0, 3000.0, 1e6][i % 6] * rng.f01();
                let c = |r: f64| a * r * [0.2, 1.0, 3.0][i % 3];
                [c(rng.f01()), c(rng.f01()), c(rng.f01()), a]
            })
            .collect();
        line.extend([
            [0.0; 4],
            [-1.0, 2.0, 3.0, 5.0],
            [f64::NAN, 1.0, 1.0, 2.0],
            [1.0, 1.0, 1.0, f64::NAN],
            [f64::INFINITY, 0.0, 0.0, 4.0],
            [0.0, 0.0, 0.0, 7.0],
            [5.0, 5.0, 5.0, -2.0],
        ]);
        let mut seen_slow = false;
        for (transparent, hp, vibrancy, curves) in [
            (false, 1.0, 1.0, false),
            (true, 1.0, 1.0, false),
            (false, -1.0, 1.0, false),
            (true, -1.0, 1.0, false),
            (false, -3.0, 1.0, false),
            (false, -0.5, 1.0, false),
            (true, -0.5, 0.6, false),
            (false, 2.0, 1.0, true),
        ] {
            let mut f = Flame {
                gamma: 2.5,
                gamma_threshold: 0.05,
                highlight_power: hp,
                vibrancy,
                background: [0.1, 0.5, 0.9],
                ..Flame::default()
            };
            if curves {
                f.curves.points[1][1] = [0.3, 0.6];
            }
            let tm = ToneMap::new(&f, transparent);
            let alphas: Vec<f64> = line.iter().map(|s| tm.alpha(s[3])).collect();
            let mut out = vec![[0.0; 4]; line.len()];
            tm.row(&line, &alphas, &mut out);
            for (s, o) in line.iter().zip(&out) {
                let (rgb, alpha) = tm.pixel(*s);
                let want = [rgb[0], rgb[1], rgb[2], alpha];
                assert_eq!(o.map(f64::to_bits), want.map(f64::to_bits), "{s:?}");
                seen_slow |= tm.usual(*s, tm.alpha(s[3])).2;
            }
        }
        assert!(seen_slow);
    }

    #[test]
    fn log_density_oracles() {
        let f = oracle_flame();
        let ls = LogScale::new(&f, 10.0);
        for (hits, want) in [(1.0, 0.103400), (10.0, 0.934414), (100.0, 5.245945)] {
            let a = ls.factor(hits) * hits / 255.0;
            assert!((a - want).abs() < 1e-6, "{hits}: {a}");
        }
    }

    #[test]
    fn gamma_threshold_oracles() {
        let f = Flame {
            gamma: 4.0,
            gamma_threshold: 0.01,
            ..Flame::default()
        };
        let tm = ToneMap::new(&f, false);
        for (a, want) in [
            (0.001, 0.046243),
            (0.005, 0.212014),
            (0.01, 0.316228),
            (0.1, 0.562341),
        ] {
            assert!((tm.gamma_alpha(a) - want).abs() < 1e-6, "{a}");
        }
    }

    #[test]
    fn single_hit_pixel_oracle() {
        let f = Flame {
            gamma: 4.0,
            vibrancy: 1.0,
            gamma_threshold: 0.01,
            highlight_power: -1.0,
            ..oracle_flame()
        };
        let ls = LogScale::new(&f, 10.0);
        let s = ls.factor(1.0);
        let acc = [s * 1.0, s * 0.5, 0.0, s * 1.0];
        let tm = ToneMap::new(&f, false);
        let (rgb, alpha) = tm.pixel(acc);
        assert!((alpha - 0.567062).abs() < 1e-6);
        assert_eq!([rgb[0] as u8, rgb[1] as u8, rgb[2] as u8], [145, 72, 0]);
        // With the 0.5 Gaussian filter's centre weight the bytes are unchanged.
        let w = 0.998659;
        let (rgb, _) = tm.pixel([acc[0] * w, acc[1] * w, 0.0, acc[3] * w]);
        assert_eq!([rgb[0] as u8, rgb[1] as u8, rgb[2] as u8], [145, 72, 0]);
    }

    #[test]
    fn fractorium_files_take_fractoriums_tone_scale() {
        // Fractorium's log scale and gamma in its own units (colours in [0, 1], one per hit,
        // k1 = brightness, output ×255), written out for a grey pixel of n hits.
        let f = Flame {
            gamma: 4.0,
            vibrancy: 1.0,
            gamma_threshold: 0.01,
            highlight_power: -1.0,
            palette_index: PaletteIndex::Fractorium,
            ..oracle_flame()
        };
        let k2 = 1.0 / (4.0 * 10.0); // area 100·100/50², quality 10
        let ls = LogScale::new(&f, 10.0);
        let tm = ToneMap::new(&f, false);
        for n in [1.0f64, 7.0, 300.0] {
            let scaled = 4.0 * (1.0 + n * k2).ln(); // the alpha channel after log scaling
            let alpha = if scaled < 0.01 {
                let frac = scaled / 0.01;
                (1.0 - frac) * scaled * 0.01f64.powf(0.25) / 0.01 + frac * scaled.powf(0.25)
            } else {
                scaled.powf(0.25)
            };
            let want = 255.0 * alpha * 0.5;
            let s = ls.factor(n);
            let (rgb, _) = tm.pixel([s * n * 0.5, s * n * 0.5, 0.0, s * n]);
            assert!((rgb[0] - want).abs() < 1e-9, "{n}: {} vs {want}", rgb[0]);
        }
        // flam3's scale is 268/256 brighter before the gamma and outputs to 256: not the same.
        let flam3 = Flame {
            palette_index: PaletteIndex::Flam3,
            ..f.clone()
        };
        let s = LogScale::new(&flam3, 10.0).factor(1.0);
        let (rgb, _) = ToneMap::new(&flam3, false).pixel([s * 0.5, s * 0.5, 0.0, s]);
        let s = ls.factor(1.0);
        let (fr, _) = tm.pixel([s * 0.5, s * 0.5, 0.0, s]);
        assert!(rgb[0] / fr[0] > 1.01, "{} vs {}", rgb[0], fr[0]);
    }

    #[test]
    fn highlight_power_keeps_hue_when_saturating() {
        // Very bright orange: with hp ≥ 0 the largest channel is 255 and no channel exceeds it.
        let c = [0.8, 0.4, 0.1];
        let out = highlight(c, 10_000.0, 1.0);
        assert!((out[0] - 255.0).abs() < 1e-9);
        assert!(out.iter().all(|v| *v <= 255.0 + 1e-9));
        // hp = −1 is plain scaling.
        let out = highlight(c, 100.0, -1.0);
        assert_eq!(out, [80.0, 40.0, 10.0]);
    }

    #[test]
    fn background_shows_through_empty_pixels() {
        let f = Flame {
            background: [1.0, 0.5, 0.0],
            ..Flame::default()
        };
        let tm = ToneMap::new(&f, false);
        let (rgb, a) = tm.pixel([0.0; 4]);
        assert_eq!(a, 0.0);
        assert_eq!(rgb, [255.0, 128.0, 0.0]);
    }
}
