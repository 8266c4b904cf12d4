//! The histogram: buckets of accumulated colour and hits, and the palette prepared for
//! plotting into it. The camera and bucket geometry are in `geometry.rs`.

use crate::flame::model::{Flame, PaletteMode};

/// One histogram bucket: R, G, B accumulated in [`COLOR_UNIT`]s, A in "hits" (palette alpha ×
/// visibility). A doubles as the hit count for density estimation.
pub type Bucket = [f32; 4];

/// Colours are accumulated in palette units, 1/255 of full intensity: an 8-bit palette entry
/// of value k adds the whole number k, whose f32 sums are exact up to 2^24 — independent of the
/// order of the adds, and with the low mantissa bits zero, so saved render states compress to
/// a third of their raw size. The log scaling divides them out ([`scale_bucket`]).
pub const COLOR_UNIT: f32 = 255.0;

/// A bucket's colour in palette units times `s`/[`COLOR_UNIT`], its alpha times `s`: the
/// log-density scaling of a bucket whose factor is `s`.
#[inline(always)]
pub fn scale_bucket(b: Bucket, s: f32) -> Bucket {
    let c = s / COLOR_UNIT;
    [b[0] * c, b[1] * c, b[2] * c, b[3] * s]
}

/// The palette prepared for plotting: RGB pre-multiplied by alpha in [`COLOR_UNIT`]s, as f32.
#[derive(Clone, Debug)]
pub struct PlotPalette {
    /// Premultiplied RGBA entries (256 for most flames; files may carry other counts).
    pub colors: Vec<[f32; 4]>,
    pub mode: PaletteMode,
    /// Entry ⌊c·scale + offset⌋ (step) or position c·scale (linear): the rule of
    /// [`crate::flame::PaletteIndex`] for this many entries.
    pub scale: f64,
    pub offset: f64,
}

impl PlotPalette {
    pub fn new(flame: &Flame) -> PlotPalette {
        let colors = flame
            .render_colors()
            .iter()
            .map(|c| {
                let a = c[3].clamp(0.0, 1.0);
                let unit = |v: f64| {
                    // 8-bit values (k/255 read from a file) become the whole number k.
                    let u = v * a * COLOR_UNIT as f64;
                    if (u - u.round()).abs() < 1e-9 {
                        u.round() as f32
                    } else {
                        u as f32
                    }
                };
                [unit(c[0]), unit(c[1]), unit(c[2]), a as f32]
            })
            .collect::<Vec<_>>();
        let colors = if colors.is_empty() {
            vec![[0.0; 4]; 2]
        } else if colors.len() == 1 {
            vec![colors[0]; 2]
        } else {
            colors
        };
        let (scale, offset) = flame
            .palette_index
            .scale_offset(colors.len(), flame.palette_mode);
        PlotPalette {
            colors,
            mode: flame.palette_mode,
            scale,
            offset,
        }
    }

    /// Palette colour of colour coordinate `c`: entry ⌊c·scale + offset⌋ of the N entries
    /// (step; flam3's ⌊c·N⌋), or linear interpolation between neighbouring entries at c·scale.
    #[inline(always)]
    pub fn lookup(&self, c: f64) -> [f32; 4] {
        let n = self.colors.len();
        let nf = n as f64;
        match self.mode {
            PaletteMode::Step => {
                let k = (c * self.scale + self.offset) as i64; // saturating cast; NaN → 0
                self.colors[k.clamp(0, n as i64 - 1) as usize]
            }
            PaletteMode::Linear => {
                let f = c * self.scale;
                let mut k = f.floor();
                let mut u = f - k;
                if k.is_nan() || k < 0.0 {
                    k = 0.0;
                    u = 0.0;
                }
                if k >= nf - 1.0 {
                    k = nf - 2.0;
                    u = 1.0;
                }
                let k = k as usize;
                let (a, b) = (self.colors[k], self.colors[k + 1]);
                let u = u as f32;
                [
                    a[0] + (b[0] - a[0]) * u,
                    a[1] + (b[1] - a[1]) * u,
                    a[2] + (b[2] - a[2]) * u,
                    a[3] + (b[3] - a[3]) * u,
                ]
            }
        }
    }
}

/// A bucket grid of accumulators.
#[derive(Clone, Debug)]
pub struct Histogram {
    /// Width in buckets.
    pub bw: usize,
    /// Height in buckets.
    pub bh: usize,
    /// The buckets, row by row, `bw` to a row.
    pub data: Vec<Bucket>,
}

impl Histogram {
    /// An empty (all zero) histogram of `bw`×`bh` buckets.
    pub fn new(bw: usize, bh: usize) -> Histogram {
        Histogram {
            bw,
            bh,
            data: vec![[0.0; 4]; bw * bh],
        }
    }

    /// Add another histogram of the same size (in parallel bands; each bucket's sum is the
    /// same whatever the banding).
    pub fn add(&mut self, other: &Histogram) {
        use rayon::prelude::*;
        self.data
            .par_chunks_mut(1 << 16)
            .zip(other.data.par_chunks(1 << 16))
            .for_each(|(a, b)| {
                for (a, b) in a.iter_mut().zip(b) {
                    for k in 0..4 {
                        a[k] += b[k];
                    }
                }
            });
    }

    /// Set every bucket to zero.
    pub fn clear(&mut self) {
        self.data.fill([0.0; 4]);
    }

    /// Total hits (sum of A).
    pub fn total(&self) -> f64 {
        self.data.iter().map(|b| b[3] as f64).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gradient::Gradient;

    #[test]
    fn palette_lookup_modes() {
        let mut f = Flame {
            palette: Gradient::grey_ramp(),
            ..Flame::default()
        };
        let p = PlotPalette::new(&f);
        assert_eq!(p.lookup(0.0)[0], 0.0);
        // In palette units: the 8-bit grey k adds exactly k.
        assert_eq!(p.lookup(1.0)[0], 255.0);
        assert_eq!(p.lookup(-3.0)[0], 0.0);
        assert_eq!(p.lookup(0.5)[0], 128.0);
        assert_eq!(p.lookup(0.5)[3], 1.0);
        f.palette_mode = PaletteMode::Linear;
        let p = PlotPalette::new(&f);
        let v = p.lookup(0.5 + 0.5 / 256.0)[0];
        assert!((v - 128.5).abs() < 1e-4);
        assert_eq!(p.lookup(1.0)[0], 255.0);
    }

    /// The programs' rules on a 256-entry grey ramp (entry k has grey k/255, k palette units).
    #[test]
    fn palette_index_rules() {
        use crate::flame::PaletteIndex::*;
        let grey = |k: f64| k as f32;
        let at = |index, mode, c: f64| {
            let f = Flame {
                palette: Gradient::grey_ramp(),
                palette_mode: mode,
                palette_index: index,
                ..Flame::default()
            };
            PlotPalette::new(&f).lookup(c)[0]
        };
        let step = PaletteMode::Step;
        // flam3 ⌊256c⌋, Apophysis ⌊255c + ½⌋, Fractorium ⌊255c⌋, JWildfire ⌊254c + ½⌋.
        assert_eq!(at(Apophysis, step, 0.5), grey(128.0)); // 127.5 + ½
        assert_eq!(at(Apophysis, step, 0.498), grey(127.0)); // 126.99 + ½
        assert_eq!(at(Apophysis, step, 1.0), grey(255.0));
        assert_eq!(at(Flam3, step, 0.5), grey(128.0));
        assert_eq!(at(Fractorium, step, 0.5), grey(127.0));
        assert_eq!(at(JWildfire, step, 0.5), grey(127.0));
        assert_eq!(at(JWildfire, step, 0.503), grey(128.0)); // 127.762 + ½
        assert_eq!(at(Flam3, step, 0.1), grey(25.0));
        assert_eq!(at(Fractorium, step, 0.1), grey(25.0));
        assert_eq!(at(JWildfire, step, 0.1), grey(25.0)); // 25.4 + ½
        assert_eq!(at(Flam3, step, 1.0), grey(255.0));
        assert_eq!(at(Fractorium, step, 1.0), grey(255.0));
        assert_eq!(at(JWildfire, step, 1.0), grey(254.0));
        // Linear: positions 256c, 255c, 254c.
        let lin = PaletteMode::Linear;
        let close = |a: f32, k: f64| assert!((a - grey(k)).abs() < 1e-4, "{a} vs {k}");
        close(at(Flam3, lin, 0.25), 64.0);
        close(at(Fractorium, lin, 0.25), 63.75);
        close(at(JWildfire, lin, 0.25), 63.5);
        close(at(Fractorium, lin, 1.0), 255.0);
        close(at(JWildfire, lin, 1.0), 254.0);
    }

    #[test]
    fn palette_index_from_version() {
        use crate::flame::PaletteIndex::{self, *};
        for (v, want) in [
            ("EMBER-LNX-1.0.0.19", Fractorium),
            ("EMBER-WIN-1.0.0.7", Fractorium),
            ("JWildfire V5.60 (07.05.2020)", JWildfire),
            ("JWildfire V7.00 (07.08.2021)", JWildfire),
            ("0.16 (06.11.2011)", JWildfire),
            ("Apophysis 7x 2010 (R12)", Apophysis),
            ("Apophysis 2.09", Apophysis),
            ("FLAM3-LNX-3.1.1", Flam3),
            ("FLAM3H-WIN-1.1.0", Fractorium),
            ("FLAM3H-LNX-1.9.5", Fractorium),
            ("ugnis-0.1.0", Flam3),
            ("1.0 (beta)", Flam3),
            ("", Flam3),
        ] {
            assert_eq!(PaletteIndex::from_version(v), want, "{v}");
        }
    }
}
