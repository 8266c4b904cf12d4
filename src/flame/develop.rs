//! Developing a histogram into an image: log scaling (with density estimation when enabled),
//! the separable spatial filter with downsampling, tone mapping, and 8- or 16-bit samples.

use std::sync::atomic::{AtomicBool, Ordering};

use image::DynamicImage;
use rayon::prelude::*;

use crate::flame::geometry::Geometry;
use crate::flame::histogram::{Bucket, Histogram, scale_bucket};
use crate::flame::model::Flame;
use crate::flame::tonemap::{LogScale, LogTable, OutputFormat, ToneMap};

/// Turn a histogram into an image: log scaling (with density estimation when enabled),
/// spatial filter with downsampling, tone mapping.
pub fn develop(
    flame: &Flame,
    geom: &Geometry,
    hist: &Histogram,
    density: f64,
    format: OutputFormat,
) -> DynamicImage {
    develop_rows(flame, geom, hist, density, format, 0..geom.height)
}

/// As [`develop`] for output rows `out_rows` of the image, from a histogram holding bucket rows
/// `geom.row0 .. geom.row0 + geom.bh` of the whole grid. Those rows must reach the
/// density-estimation radius and the filter beyond the rows used (see
/// [`crate::flame::strips::plan`]); then every pixel is the one of the whole image.
pub fn develop_rows(
    flame: &Flame,
    geom: &Geometry,
    hist: &Histogram,
    density: f64,
    format: OutputFormat,
    out_rows: std::ops::Range<usize>,
) -> DynamicImage {
    let never = AtomicBool::new(false);
    develop_rows_until(flame, geom, hist, density, format, out_rows, &never).expect("not stopped")
}

/// [`develop_rows`], or `None` when `stop` is set before it is done (checked between bands).
pub(super) fn develop_rows_until(
    flame: &Flame,
    geom: &Geometry,
    hist: &Histogram,
    density: f64,
    format: OutputFormat,
    out_rows: std::ops::Range<usize>,
    stop: &AtomicBool,
) -> Option<DynamicImage> {
    if let Some(j) = &geom.jwf {
        return crate::flame::jwf_render::develop::develop(
            flame, geom, j, hist, density, format, out_rows, stop,
        );
    }
    let ls = LogTable::new(LogScale::new(flame, density));
    let mut acc: Vec<Bucket> = Vec::new();
    let acc: &[Bucket] = match &geom.de {
        Some(de) => {
            acc.resize(geom.buckets(), [0.0; 4]);
            de.splat_until(hist, &mut acc, |a| ls.factor(a), stop);
            &acc
        }
        None => {
            acc = hist
                .data
                .par_iter()
                .map(|&b| scale_bucket(b, ls.factor(b[3])))
                .collect();
            &acc
        }
    };
    filter_and_tonemap(flame, geom, &Rows::Acc(acc), format, out_rows, stop)
}

/// A quick development of the thread histograms `hists` as they stand: summed and log-scaled
/// row by row inside the filter's bands (no merged copy, one pass over memory), without density
/// estimation.
pub(super) fn develop_draft(
    flame: &Flame,
    geom: &Geometry,
    hists: &[Histogram],
    density: f64,
    format: OutputFormat,
    out_rows: std::ops::Range<usize>,
) -> DynamicImage {
    if geom.jwf.is_some() {
        let mut sum = hists[0].clone();
        for h in &hists[1..] {
            sum.add(h);
        }
        return develop_rows(flame, geom, &sum, density, format, out_rows);
    }
    let src = Rows::Draft {
        hists,
        ls: LogTable::new(LogScale::new(flame, density)),
    };
    let never = AtomicBool::new(false);
    filter_and_tonemap(flame, geom, &src, format, out_rows, &never).expect("not stopped")
}

/// Where the filter reads its bucket rows from.
enum Rows<'a> {
    /// Log-scaled (density-estimated) buckets.
    Acc(&'a [Bucket]),
    /// Raw thread histograms, summed and log-scaled as they are read.
    Draft {
        hists: &'a [Histogram],
        ls: LogTable,
    },
}

impl<'a> Rows<'a> {
    /// Bucket row `r` (`bw` buckets), in `buf` when it has to be computed.
    #[inline(always)]
    fn row<'b>(&'b self, r: usize, bw: usize, buf: &'b mut Vec<Bucket>) -> &'b [Bucket] {
        match self {
            Rows::Acc(acc) => &acc[r * bw..(r + 1) * bw],
            Rows::Draft { hists, ls } => {
                let scale = |b: Bucket| {
                    if b[3] <= 0.0 {
                        [0.0; 4]
                    } else {
                        scale_bucket(b, ls.factor(b[3]))
                    }
                };
                let sum =
                    |b: &Bucket, o: &Bucket| [b[0] + o[0], b[1] + o[1], b[2] + o[2], b[3] + o[3]];
                let at = |h: &'a Histogram| &h.data[r * bw..(r + 1) * bw];
                // Plain loops (no iterator adaptors) so that they are compiled for the
                // caller's CPU features.
                buf.resize(bw, [0.0; 4]);
                match hists {
                    [h] => {
                        for (d, &b) in buf.iter_mut().zip(at(h)) {
                            *d = scale(b);
                        }
                    }
                    [h0, h1] => {
                        for ((d, b), o) in buf.iter_mut().zip(at(h0)).zip(at(h1)) {
                            *d = scale(sum(b, o));
                        }
                    }
                    _ => {
                        buf.copy_from_slice(at(&hists[0]));
                        for h in &hists[1..] {
                            for (b, o) in buf.iter_mut().zip(at(h)) {
                                *b = sum(b, o);
                            }
                        }
                        for b in buf.iter_mut() {
                            *b = scale(*b);
                        }
                    }
                }
                buf
            }
        }
    }
}

/// Spatial filter (separable, downsampling by os) and tone mapping into the output image, or
/// `None` when `stop` is set before it is done (checked between bands).
fn filter_and_tonemap(
    flame: &Flame,
    geom: &Geometry,
    acc: &Rows,
    format: OutputFormat,
    out_rows: std::ops::Range<usize>,
    stop: &AtomicBool,
) -> Option<DynamicImage> {
    if stop.load(Ordering::Relaxed) {
        return None;
    }
    let band = Band {
        geom,
        acc,
        tm: ToneMap::new(flame, format.transparent),
        channels: if format.transparent { 4 } else { 3 },
        y_first: out_rows.start,
        h: out_rows.len(),
    };
    if format.bits16 {
        encode_image::<u16>(&band, stop)
    } else {
        encode_image::<u8>(&band, stop)
    }
}

/// Filter and tone-map every band of the image into samples of type `S`, or `None` when `stop`
/// is set before it is done.
fn encode_image<S: Sample>(band: &Band, stop: &AtomicBool) -> Option<DynamicImage> {
    let (w, channels, h) = (band.geom.width, band.channels, band.h);
    let row_len = w * channels;
    let mut buf = vec![S::ZERO; row_len * h];
    in_bands(&mut buf, row_len * BAND, |sc, b, chunk| {
        if !stop.load(Ordering::Relaxed) {
            band.encode(sc, b * BAND, chunk)
        }
    });
    if stop.load(Ordering::Relaxed) {
        return None;
    }
    Some(S::image(w as u32, h as u32, channels, buf))
}

/// Run `f(scratch, index, chunk)` over the chunks of `buf` in parallel, with one scratch per
/// worker (reused from band to band).
fn in_bands<T: Send>(
    buf: &mut [T],
    chunk: usize,
    f: impl Fn(&mut Scratch, usize, &mut [T]) + Sync,
) {
    buf.par_chunks_mut(chunk)
        .enumerate()
        .for_each_init(Scratch::default, |sc, (i, c)| f(sc, i, c));
}

/// Output rows filtered and tone-mapped together (bounded scratch memory per band).
const BAND: usize = 16;

/// An output sample: 8 or 16 bits per channel.
trait Sample: Copy + Send + Sync {
    const ZERO: Self;
    /// A tone-mapped colour value (on the 0..256 scale of 8 bits).
    fn from_tone(v: f64) -> Self;
    /// An alpha in [0, 1].
    fn from_alpha(a: f64) -> Self;
    /// The image of `w`×`h` pixels of `channels` (3 or 4) samples each.
    fn image(w: u32, h: u32, channels: usize, buf: Vec<Self>) -> DynamicImage;
}

impl Sample for u8 {
    const ZERO: u8 = 0;

    #[inline(always)]
    fn from_tone(v: f64) -> u8 {
        v as u8
    }

    #[inline(always)]
    fn from_alpha(a: f64) -> u8 {
        (255.0 * a) as u8
    }

    fn image(w: u32, h: u32, channels: usize, buf: Vec<u8>) -> DynamicImage {
        let img = if channels == 4 {
            image::RgbaImage::from_raw(w, h, buf).map(DynamicImage::ImageRgba8)
        } else {
            image::RgbImage::from_raw(w, h, buf).map(DynamicImage::ImageRgb8)
        };
        img.expect("buffer size")
    }
}

impl Sample for u16 {
    const ZERO: u16 = 0;

    #[inline(always)]
    fn from_tone(v: f64) -> u16 {
        (256.0 * v) as u16
    }

    #[inline(always)]
    fn from_alpha(a: f64) -> u16 {
        (65535.0 * a) as u16
    }

    fn image(w: u32, h: u32, channels: usize, buf: Vec<u16>) -> DynamicImage {
        use image::{ImageBuffer, Rgb, Rgba};
        let img = if channels == 4 {
            ImageBuffer::<Rgba<u16>, _>::from_raw(w, h, buf).map(DynamicImage::ImageRgba16)
        } else {
            ImageBuffer::<Rgb<u16>, _>::from_raw(w, h, buf).map(DynamicImage::ImageRgb16)
        };
        img.expect("buffer size")
    }
}

/// Rows a band works in, kept from band to band (every value is written before it is read).
#[derive(Default)]
struct Scratch {
    /// Horizontally filtered bucket rows.
    tmp: Vec<[f64; 4]>,
    /// A bucket row computed on the fly.
    row: Vec<Bucket>,
    /// One output row, filtered.
    line: Vec<[f64; 4]>,
    alphas: Vec<f64>,
    /// The row tone-mapped: output values and alpha.
    toned: Vec<[f64; 4]>,
}

/// What every band of [`filter_and_tonemap`] shares.
struct Band<'a> {
    geom: &'a Geometry,
    acc: &'a Rows<'a>,
    tm: ToneMap,
    channels: usize,
    /// First output row of the image (of the whole picture's rows).
    y_first: usize,
    /// Output rows.
    h: usize,
}

impl Band<'_> {
    /// Filter and tone-map the output rows `y0..y0 + BAND` into `out`.
    fn encode<S: Sample>(&self, sc: &mut Scratch, y0: usize, out: &mut [S]) {
        #[cfg(target_arch = "x86_64")]
        if crate::flame::fastmath::has_avx2_fma() {
            // SAFETY: the CPU has just reported AVX2 and FMA.
            return unsafe { self.encode_avx2(sc, y0, out) };
        }
        self.encode_generic(sc, y0, out)
    }

    /// [`Band::encode`] for CPUs with AVX2 and FMA (the compiler contracts nothing into FMA, so
    /// the values are the same as the generic copy's).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn encode_avx2<S: Sample>(&self, sc: &mut Scratch, y0: usize, out: &mut [S]) {
        self.encode_generic(sc, y0, out)
    }

    #[inline(always)]
    fn encode_generic<S: Sample>(&self, sc: &mut Scratch, y0: usize, out: &mut [S]) {
        let geom = self.geom;
        let (w, os, bw, delta) = (geom.width, geom.os, geom.bw, geom.delta);
        let taps = &geom.filter.taps;
        let fw = geom.filter.width;
        let channels = self.channels;
        let row_len = w * channels;
        let rows = BAND.min(self.h - y0);
        // Horizontally filtered acc rows needed by this band (rows of `acc`, which starts at
        // row `geom.row0` of the whole grid).
        let r0 = (self.y_first + y0) * os + delta - geom.row0;
        let nr = (rows - 1) * os + fw;
        // Loops run along a row (tap by tap) so that they vectorise; each sum still adds its
        // terms in tap order, starting from 0 as a plain dot product would.
        // (Plain loops, no iterator adaptors: they are compiled for the caller's CPU features.)
        let Scratch {
            tmp,
            row,
            line,
            alphas,
            toned,
        } = sc;
        tmp.resize(nr * w, [0.0; 4]);
        line.resize(w, [0.0; 4]);
        alphas.resize(w, 0.0);
        toned.resize(w, [0.0; 4]);
        let t0 = taps[0];
        let first = |b: &Bucket| {
            [
                0.0 + t0 * b[0] as f64,
                0.0 + t0 * b[1] as f64,
                0.0 + t0 * b[2] as f64,
                0.0 + t0 * b[3] as f64,
            ]
        };
        for (r, dst) in tmp[..nr * w].chunks_exact_mut(w).enumerate() {
            let src = self.acc.row(r0 + r, bw, row);
            if os == 1 {
                for (d, b) in dst.iter_mut().zip(&src[delta..delta + w]) {
                    *d = first(b);
                }
            } else {
                for (x, d) in dst.iter_mut().enumerate() {
                    *d = first(&src[x * os + delta]);
                }
            }
            for (i, &t) in taps.iter().enumerate().skip(1) {
                let add = |d: &mut [f64; 4], b: &Bucket| {
                    d[0] += t * b[0] as f64;
                    d[1] += t * b[1] as f64;
                    d[2] += t * b[2] as f64;
                    d[3] += t * b[3] as f64;
                };
                if os == 1 {
                    for (d, b) in dst.iter_mut().zip(&src[delta + i..delta + i + w]) {
                        add(d, b);
                    }
                } else {
                    for (x, d) in dst.iter_mut().enumerate() {
                        add(d, &src[x * os + delta + i]);
                    }
                }
            }
        }
        for yy in 0..rows {
            let tmp_row = |j: usize| &tmp[(yy * os + j) * w..(yy * os + j + 1) * w];
            for (d, b) in line.iter_mut().zip(tmp_row(0)) {
                *d = [
                    0.0 + t0 * b[0],
                    0.0 + t0 * b[1],
                    0.0 + t0 * b[2],
                    0.0 + t0 * b[3],
                ];
            }
            for (j, &t) in taps.iter().enumerate().skip(1) {
                for (d, b) in line.iter_mut().zip(tmp_row(j)) {
                    d[0] += t * b[0];
                    d[1] += t * b[1];
                    d[2] += t * b[2];
                    d[3] += t * b[3];
                }
            }
            for (al, s) in alphas.iter_mut().zip(line.iter()) {
                *al = self.tm.alpha(s[3]);
            }
            self.tm.row(line, alphas, toned);
            let o = yy * row_len;
            let dst = out[o..o + row_len].chunks_exact_mut(channels);
            for (px, t) in dst.zip(toned.iter()) {
                px[0] = S::from_tone(t[0]);
                px[1] = S::from_tone(t[1]);
                px[2] = S::from_tone(t[2]);
                if channels == 4 {
                    px[3] = S::from_alpha(t[3]);
                }
            }
        }
    }
}
