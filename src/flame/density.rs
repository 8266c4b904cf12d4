//! Density estimation: a family of Gaussian kernels whose width shrinks as the
//! local hit count grows; each log-scaled bucket is splatted with the kernel chosen by its count.

use rayon::prelude::*;

use crate::flame::filter::gaussian;
use crate::flame::histogram::{Bucket, Histogram};

/// One row of a kernel: weights for dx = dx0, dx0 + 1, … at row offset dy.
#[derive(Clone, Debug, PartialEq)]
pub struct KernelRow {
    pub dy: i32,
    pub dx0: i32,
    pub weights: Vec<f32>,
}

/// The kernel family.
#[derive(Clone, Debug, PartialEq)]
pub struct DeFilters {
    pub kernels: Vec<Vec<KernelRow>>,
    /// Width h_k of every kernel.
    pub widths: Vec<f64>,
    pub kmax: usize,
    pub maxcount: f64,
    pub curve: f64,
    /// Half size of the kernel square, ⌈Hmax⌉ − 1.
    pub half: i32,
    pub os: usize,
}

/// Why a DE setting is unusable.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DeError {
    #[error(
        "density estimation: estimator_radius {0} must be ≥ estimator_minimum {1} ≥ 0 and estimator_curve {2} > 0"
    )]
    Params(f64, f64, f64),
    #[error("density estimation: {0} kernels would be needed (limit 10 000 000)")]
    TooMany(f64),
}

impl DeFilters {
    /// Build the family, or `Ok(None)` when DE is off (radius 0).
    pub fn new(
        radius: f64,
        minimum: f64,
        curve: f64,
        os: u32,
    ) -> Result<Option<DeFilters>, DeError> {
        if radius == 0.0 {
            return Ok(None);
        }
        if !(radius >= minimum
            && minimum >= 0.0
            && curve > 0.0
            && radius.is_finite()
            && curve.is_finite())
        {
            return Err(DeError::Params(radius, minimum, curve));
        }
        let os_f = os as f64;
        let hmax = radius * os_f + 1.0;
        let hmin = minimum * os_f + 1.0;
        let nf = (hmax / hmin).powf(1.0 / curve).ceil();
        if nf > 1e7 {
            return Err(DeError::TooMany(nf));
        }
        let (nk, maxcount) = if nf > 100.0 {
            let nk = (100.0 + (nf - 100.0).powf(curve)).ceil() + 1.0;
            (
                nk as usize,
                ((nk - 100.0).powf(1.0 / curve)).floor() + 100.0,
            )
        } else {
            (nf as usize, nf)
        };
        let half = hmax.ceil() as i32 - 1;
        let mut widths = Vec::with_capacity(nk);
        let mut kmax = nk.saturating_sub(1);
        for k in 0..nk {
            let kf = k as f64;
            let mut h = if k < 100 {
                hmax / (kf + 1.0).powf(curve)
            } else {
                hmax / ((kf - 100.0).powf(1.0 / curve) + 100.0 + 1.0).powf(curve)
            };
            let last = h <= hmin;
            if last {
                h = hmin;
            }
            widths.push(h);
            if last {
                kmax = k;
                break;
            }
        }
        let kernels = widths.iter().map(|&h| Self::kernel(h, half)).collect();
        Ok(Some(DeFilters {
            kernels,
            widths,
            kmax,
            maxcount,
            curve,
            half,
            os: os as usize,
        }))
    }

    /// [`DeFilters::new`], shared with the renders made recently with the same settings (the
    /// editor starts a render at every edit; building the kernels took a fifth of that).
    pub fn shared(
        radius: f64,
        minimum: f64,
        curve: f64,
        os: u32,
    ) -> Result<Option<std::sync::Arc<DeFilters>>, DeError> {
        use std::sync::{Arc, Mutex};
        type Key = (u64, u64, u64, u32);
        // The last few families of at most 2^20 taps (4 MB) each.
        static RECENT: Mutex<Vec<(Key, Arc<DeFilters>)>> = Mutex::new(Vec::new());
        let key = (radius.to_bits(), minimum.to_bits(), curve.to_bits(), os);
        let found = {
            let recent = RECENT.lock().unwrap_or_else(|e| e.into_inner());
            recent
                .iter()
                .find(|(k, _)| *k == key)
                .map(|(_, d)| d.clone())
        };
        if let Some(d) = found {
            return Ok(Some(d));
        }
        let Some(d) = Self::new(radius, minimum, curve, os)? else {
            return Ok(None);
        };
        let d = Arc::new(d);
        // Only small families are kept (wide estimators on big supersamples reach hundreds of
        // megabytes, which must go with their render).
        let taps: usize = d.kernels.iter().flatten().map(|r| r.weights.len()).sum();
        if taps > 1 << 20 {
            return Ok(Some(d));
        }
        let mut recent = RECENT.lock().unwrap_or_else(|e| e.into_inner());
        if recent.len() >= 4 {
            recent.remove(0);
        }
        recent.push((key, d.clone()));
        Ok(Some(d))
    }

    /// Kernel of width h: coefficients G(1.5·d) for d = dist/h ≤ 1, normalised over the
    /// square of half-size `half`; but, as flam3 splats them, only the taps within
    /// ⌈h⌉ − 1 of the centre in both directions are kept (so the narrowest kernels lose a
    /// little of their mass — flam3's behaviour, which the reference text does not mention).
    fn kernel(h: f64, half: i32) -> Vec<KernelRow> {
        let reach = (h.ceil() as i32 - 1).clamp(0, half);
        let mut raw: Vec<(i32, i32, f64)> = Vec::new();
        let mut sum = 0.0;
        for dy in -half..=half {
            for dx in -half..=half {
                let d = ((dx * dx + dy * dy) as f64).sqrt() / h;
                if d <= 1.0 {
                    let v = gaussian(1.5 * d);
                    sum += v;
                    if dx.abs() <= reach && dy.abs() <= reach {
                        raw.push((dy, dx, v));
                    }
                }
            }
        }
        let mut rows: Vec<KernelRow> = Vec::new();
        for (dy, dx, v) in raw {
            let w = (v / sum) as f32;
            match rows.last_mut() {
                Some(r) if r.dy == dy && r.dx0 + r.weights.len() as i32 == dx => r.weights.push(w),
                _ => rows.push(KernelRow {
                    dy,
                    dx0: dx,
                    weights: vec![w],
                }),
            }
        }
        rows
    }

    /// Kernel index for a (block) hit count n > 0.
    pub fn select(&self, n: f64) -> usize {
        let k = if n > self.maxcount {
            self.kmax
        } else if n <= 100.0 {
            (n.ceil() as usize).saturating_sub(1)
        } else {
            100 + ((n - 100.0).powf(self.curve)).floor() as usize
        };
        k.min(self.kmax)
    }

    /// Splat every log-scaled bucket of `hist` into `acc` (same size), in parallel bands.
    /// `ls(A)` gives the log-scale factor of a bucket with alpha accumulator A.
    pub fn splat<F: Fn(f32) -> f32 + Sync>(&self, hist: &Histogram, acc: &mut [Bucket], ls: F) {
        self.splat_until(hist, acc, ls, &std::sync::atomic::AtomicBool::new(false));
    }

    /// [`DeFilters::splat`], giving up (leaving `acc` incomplete) once `stop` is set: checked
    /// before each band.
    pub fn splat_until<F: Fn(f32) -> f32 + Sync>(
        &self,
        hist: &Histogram,
        acc: &mut [Bucket],
        ls: F,
        stop: &std::sync::atomic::AtomicBool,
    ) {
        let (bw, bh) = (hist.bw, hist.bh);
        assert_eq!(acc.len(), bw * bh);
        let half = self.half.max(0) as usize;
        let threads = rayon::current_num_threads().max(1);
        let band = (2 * half + 1).max(bh.div_ceil(4 * threads)).max(1);
        let nbands = bh.div_ceil(band);
        for phase in 0..2 {
            // Disjoint write windows: rows [b0 − half, b1 + half) of the bands of this phase.
            let mut jobs: Vec<(usize, usize, usize, &mut [Bucket])> = Vec::new();
            let mut rest: &mut [Bucket] = acc;
            let mut consumed = 0usize; // rows already split off
            for b in (phase..nbands).step_by(2) {
                let b0 = b * band;
                let b1 = ((b + 1) * band).min(bh);
                let lo = b0.saturating_sub(half);
                let hi = (b1 + half).min(bh);
                let (_, tail) = rest.split_at_mut((lo - consumed) * bw);
                let (win, tail) = tail.split_at_mut((hi - lo) * bw);
                rest = tail;
                consumed = hi;
                jobs.push((b0, b1, lo, win));
            }
            jobs.into_par_iter().for_each(|(b0, b1, lo, win)| {
                if stop.load(std::sync::atomic::Ordering::Relaxed) {
                    return;
                }
                let rows_in_win = win.len() / bw;
                for y in b0..b1 {
                    for x in 0..bw {
                        let b = hist.data[y * bw + x];
                        if b[3] <= 0.0 {
                            continue;
                        }
                        let n = self.block_count(hist, x, y);
                        let k = self.select(n as f64);
                        let v = crate::flame::histogram::scale_bucket(b, ls(b[3]));
                        for row in &self.kernels[k] {
                            let yy = y as i64 + row.dy as i64;
                            if yy < lo as i64 || yy >= (lo + rows_in_win) as i64 {
                                continue;
                            }
                            let base = (yy as usize - lo) * bw;
                            let x0 = x as i64 + row.dx0 as i64;
                            let (mut i0, mut x_start) = (0usize, x0);
                            if x_start < 0 {
                                i0 = (-x_start) as usize;
                                x_start = 0;
                            }
                            if i0 >= row.weights.len() {
                                continue;
                            }
                            let len =
                                (row.weights.len() - i0).min(bw.saturating_sub(x_start as usize));
                            let dst =
                                &mut win[base + x_start as usize..base + x_start as usize + len];
                            for (d, &wgt) in dst.iter_mut().zip(&row.weights[i0..i0 + len]) {
                                d[0] += v[0] * wgt;
                                d[1] += v[1] * wgt;
                                d[2] += v[2] * wgt;
                                d[3] += v[3] * wgt;
                            }
                        }
                    }
                }
            });
        }
    }

    /// Hit count of the os×os block around a bucket.
    fn block_count(&self, hist: &Histogram, x: usize, y: usize) -> f32 {
        let os = self.os;
        if os == 1 {
            return hist.data[y * hist.bw + x][3];
        }
        let r = (os / 2) as i64;
        let mut n = 0.0f32;
        for dy in -r..=r {
            let yy = y as i64 + dy;
            if yy < 0 || yy >= hist.bh as i64 {
                continue;
            }
            for dx in -r..=r {
                let xx = x as i64 + dx;
                if xx < 0 || xx >= hist.bw as i64 {
                    continue;
                }
                n += hist.data[yy as usize * hist.bw + xx as usize][3];
            }
        }
        if os.is_multiple_of(2) {
            let f = os as f32 / (os as f32 + 1.0);
            n *= f * f;
        }
        n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kernel_family_oracle() {
        let de = DeFilters::new(9.0, 0.0, 0.4, 1).unwrap().unwrap();
        assert_eq!(de.maxcount, 416.0);
        assert_eq!(de.kmax, 109);
        assert_eq!(de.half, 9);
        let w = |n: f64| de.widths[de.select(n)];
        for (n, want) in [
            (1.0, 10.0),
            (2.0, 7.5786),
            (3.0, 6.4439),
            (10.0, 3.9811),
            (50.0, 2.0913),
            (100.0, 1.5849),
        ] {
            assert!((w(n) - want).abs() < 1e-4, "n={n}: {} vs {want}", w(n));
        }
        for (n, k) in [
            (1.0, 0),
            (1.5, 1),
            (100.0, 99),
            (101.0, 101),
            (150.0, 104),
            (416.0, 109),
            (500.0, 109),
        ] {
            assert_eq!(de.select(n), k, "n={n}");
        }
    }

    #[test]
    fn kernels_are_normalised_and_truncated_like_flam3() {
        let de = DeFilters::new(9.0, 0.0, 0.4, 1).unwrap().unwrap();
        let sum = |k: &Vec<KernelRow>| -> f64 {
            k.iter()
                .flat_map(|r| r.weights.iter())
                .map(|&w| w as f64)
                .sum()
        };
        // The widest kernel (h = 10) keeps every tap of the 19×19 square: sum 1.
        assert!((sum(&de.kernels[0]) - 1.0).abs() < 1e-5);
        // h = 7.58: taps up to 7 away; the d ≤ 1 taps 8 away are normalised but not
        // splatted, so the kernel sums to a little under 1.
        let s1 = sum(&de.kernels[1]);
        assert!(s1 < 1.0 && s1 > 0.95, "{s1}");
        assert!(de.kernels[1].iter().all(|r| r.dy.abs() <= 7 && r.dx0 >= -7));
        // The narrowest (h = 1) is the centre tap only: G(0) / (G(0) + 4 G(1.5)).
        let last = &de.kernels[de.kmax];
        assert_eq!(last.len(), 1);
        assert_eq!(last[0].weights.len(), 1);
        let g0 = gaussian(0.0);
        let want = g0 / (g0 + 4.0 * gaussian(1.5));
        assert!((last[0].weights[0] as f64 - want).abs() < 1e-6);
        assert!(DeFilters::new(0.0, 0.0, 0.4, 1).unwrap().is_none());
        assert!(DeFilters::new(1.0, 2.0, 0.4, 1).is_err());
        assert!(DeFilters::new(1.0, 0.0, 0.0, 1).is_err());
    }

    #[test]
    fn small_families_are_shared_and_wide_ones_are_not_kept() {
        use std::sync::Arc;
        let a = DeFilters::shared(3.25, 0.0, 0.4, 1).unwrap().unwrap();
        let b = DeFilters::shared(3.25, 0.0, 0.4, 1).unwrap().unwrap();
        assert!(Arc::ptr_eq(&a, &b));
        assert_eq!(*a, DeFilters::new(3.25, 0.0, 0.4, 1).unwrap().unwrap());
        let c = DeFilters::shared(3.25, 0.0, 0.4, 2).unwrap().unwrap();
        assert!(!Arc::ptr_eq(&a, &c));
        assert!(DeFilters::shared(0.0, 0.0, 0.4, 1).unwrap().is_none());
        // 40 × supersample 6: several million taps, built anew each time.
        let w1 = DeFilters::shared(40.0, 0.0, 0.4, 6).unwrap().unwrap();
        let w2 = DeFilters::shared(40.0, 0.0, 0.4, 6).unwrap().unwrap();
        assert!(!Arc::ptr_eq(&w1, &w2));
    }

    #[test]
    fn splat_spreads_each_bucket_with_its_kernel() {
        let de = DeFilters::new(4.0, 0.0, 0.4, 1).unwrap().unwrap();
        let mut h = Histogram::new(40, 40);
        h.data[20 * 40 + 20] = [1.0, 0.5, 0.25, 1.0];
        h.data[10 * 40 + 12] = [3.0, 3.0, 3.0, 3.0];
        let mut acc = vec![[0.0f32; 4]; 1600];
        de.splat(&h, &mut acc, |_| 2.0);
        let kernel_sum = |n: f64| -> f64 {
            de.kernels[de.select(n)]
                .iter()
                .flat_map(|r| r.weights.iter())
                .map(|&w| w as f64)
                .sum()
        };
        let want = 2.0 * kernel_sum(1.0) + 2.0 * 3.0 * kernel_sum(3.0);
        let sum: f64 = acc.iter().map(|b| b[3] as f64).sum();
        assert!((sum - want).abs() < 1e-4, "{sum} vs {want}");
        // The single hit spread over several buckets.
        assert!(acc[20 * 40 + 20][3] < 2.0 && acc[20 * 40 + 21][3] > 0.0);
    }
}
