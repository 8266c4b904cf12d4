//! Box counting: the number of grid cells of side 2^−k that meet a point set, an image or a flame
//! attractor, counted for every level at once from 60-bit cell keys, and the dimension fitted
//! to the levels that see the set's structure.

use rayon::prelude::*;

use super::fit::{LineFit, fit_line};
use crate::explore::{Bounds, ExploreError, P2};
use crate::flame::chaos::{Chaos, SUB_BATCH};
use crate::flame::model::Flame;
use crate::flame::rng::FastRng;

/// Finest level counted: cells of side 2⁻³⁰ of the bounding square (two 30-bit cell indices
/// interleaved into one 60-bit key).
pub const MAX_LEVEL: u32 = 30;
/// Coarse levels left out of the fit (the grid is too coarse to see the set's structure).
pub const SKIP_COARSE: u32 = 2;
/// Levels where more than this share of the samples sit in distinct cells are left out of the
/// fit (too few samples per cell to find every cell the set meets).
pub const MAX_FILL: f64 = 0.1;
/// Fewest samples box counting accepts.
pub const MIN_SAMPLES: u64 = 100;
/// Most samples box counting accepts (up to 16 bytes each while counting, see
/// [`box_count_peak_bytes`]).
pub const MAX_SAMPLES: u64 = 50_000_000;

/// The count at one level: cells of side 2^−k of the bounding square.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BoxLevel {
    /// The level k.
    pub k: u32,
    /// Cells of side 2^−k that hold at least one sample.
    pub count: u64,
}

impl BoxLevel {
    /// ln(1/ε) = k·ln 2, the x of the log-log plot.
    pub fn ln_inv_size(&self) -> f64 {
        self.k as f64 * std::f64::consts::LN_2
    }

    /// ln N(ε), the y of the log-log plot.
    pub fn ln_count(&self) -> f64 {
        (self.count as f64).ln()
    }
}

/// The result of box counting: the counts of every level, the fitted line and its range.
#[derive(Clone, Debug, PartialEq)]
pub struct BoxCount {
    /// Points (or set pixels) counted.
    pub samples: u64,
    /// Lower-left corner and side of the bounding square.
    pub origin: P2,
    /// Side of the bounding square.
    pub side: f64,
    /// Levels k = 1, 2, …: up to 13, or up to 30 when the fit reaches past level 13.
    pub levels: Vec<BoxLevel>,
    /// First and last level of the fit (inclusive), if at least two levels qualify.
    pub fit_range: Option<(u32, u32)>,
    /// ln N against k·ln 2 over the fit range; the slope is the dimension estimate.
    pub fit: Option<LineFit>,
}

impl BoxCount {
    /// The estimate: the slope of the fitted line.
    pub fn dimension(&self) -> Option<f64> {
        self.fit.map(|f| f.slope)
    }

    /// The log-log points (ln(1/ε), ln N) of every level.
    pub fn plot_points(&self) -> Vec<(f64, f64)> {
        self.levels
            .iter()
            .map(|l| (l.ln_inv_size(), l.ln_count()))
            .collect()
    }

    /// The levels inside the fit range.
    pub fn fitted_levels(&self) -> &[BoxLevel] {
        match self.fit_range {
            Some((a, b)) => &self.levels[(a - 1) as usize..b as usize],
            None => &[],
        }
    }

    fn from_levels(samples: u64, origin: P2, side: f64, levels: Vec<BoxLevel>) -> BoxCount {
        // Counts grow with k, so the qualifying levels form one run from SKIP_COARSE + 1 on.
        let limit = MAX_FILL * samples as f64;
        let used: Vec<&BoxLevel> = levels
            .iter()
            .filter(|l| l.k > SKIP_COARSE)
            .take_while(|l| l.count as f64 <= limit)
            .collect();
        let (fit_range, fit) = if used.len() >= 2 {
            let pts: Vec<(f64, f64)> = used
                .iter()
                .map(|l| (l.ln_inv_size(), l.ln_count()))
                .collect();
            (Some((used[0].k, used[used.len() - 1].k)), fit_line(&pts))
        } else {
            (None, None)
        };
        BoxCount {
            samples,
            origin,
            side,
            levels,
            fit_range,
            fit,
        }
    }
}

/// Spread the low 32 bits of `v` to the even bits of a u64.
#[inline(always)]
fn spread(v: u64) -> u64 {
    let mut x = v & 0xFFFF_FFFF;
    x = (x | (x << 16)) & 0x0000_FFFF_0000_FFFF;
    x = (x | (x << 8)) & 0x00FF_00FF_00FF_00FF;
    x = (x | (x << 4)) & 0x0F0F_0F0F_0F0F_0F0F;
    x = (x | (x << 2)) & 0x3333_3333_3333_3333;
    x = (x | (x << 1)) & 0x5555_5555_5555_5555;
    x
}

/// Level counted with a bitmap (4¹³ bits = 8 MiB); finer levels need the sorted cell keys.
const COARSE: u32 = 13;
/// Shift from a level-30 key to its level-COARSE cell.
const COARSE_SHIFT: u32 = 2 * (MAX_LEVEL - COARSE);

/// The grid of cells over the bounding square. Cell keys interleave the bits of the two cell
/// indices (Morton order), so the cells of a coarser level are runs of consecutive keys: two
/// keys lie in different cells of level k exactly when they differ in their top 2k bits.
#[derive(Clone, Copy, Debug)]
struct Grid {
    origin: P2,
    side: f64,
    scale: f64,
}

impl Grid {
    /// The bounding square of `bounds` (sharing the lower-left corner).
    fn new(bounds: Bounds) -> Result<Grid, ExploreError> {
        if bounds.is_empty() {
            return Err(ExploreError::Invalid(
                "no points to count (the set is empty)".into(),
            ));
        }
        let side = bounds.width().max(bounds.height());
        if side.is_nan() || side <= 0.0 || !side.is_finite() {
            return Err(ExploreError::Invalid(
                "all points coincide; box counting needs a set that extends in some direction"
                    .into(),
            ));
        }
        Ok(Grid {
            origin: bounds.min,
            side,
            scale: (1u64 << MAX_LEVEL) as f64 / side,
        })
    }

    /// The level-30 key of the cell holding `p` (points on the far edge belong to the last
    /// cell); `None` outside the square.
    #[inline(always)]
    fn key(&self, p: P2) -> Option<u64> {
        let fx = (p[0] - self.origin[0]) * self.scale;
        let fy = (p[1] - self.origin[1]) * self.scale;
        let top = (1u64 << MAX_LEVEL) as f64;
        if !(fx >= 0.0 && fy >= 0.0 && fx <= top && fy <= top) {
            return None;
        }
        let max = (1u64 << MAX_LEVEL) - 1;
        let ix = (fx as u64).min(max);
        let iy = (fy as u64).min(max);
        Some(spread(ix) | (spread(iy) << 1))
    }
}

/// Most bytes box counting of `samples` points allocates: the level-13 bitmap (8 MiB) and its
/// per-word summary (1 MiB), and, when the fit reaches past level 13, a cell key and a sorted
/// copy per point (16 bytes) with two bucket tables (8 MiB). The points themselves are not
/// included.
pub fn box_count_peak_bytes(samples: u64) -> u64 {
    let words = 1u64 << (2 * COARSE - 6);
    (8 * words + words).max(16 * samples + 8 * (1 << (2 * BUCKET_LEVEL)))
}

/// The occupied cells of level [`COARSE`], one bit each, in Morton order.
struct Bitmap(Vec<u64>);

impl Bitmap {
    fn new() -> Bitmap {
        Bitmap(vec![0u64; 1 << (2 * COARSE - 6)])
    }

    #[inline(always)]
    fn mark(&mut self, key: u64) {
        let c = key >> COARSE_SHIFT;
        self.0[(c >> 6) as usize] |= 1 << (c & 63);
    }

    /// N(2^−k) for k = 1..=COARSE. Within a word, OR-ing shifted copies gathers groups of 4
    /// and 16 bits (the cells of the next two coarser levels); a word is one cell three levels
    /// up, and groups of 4 of those make each further level.
    fn counts(&self) -> Vec<u64> {
        let mut counts = vec![0u64; COARSE as usize];
        let (mut c0, mut c1, mut c2) = (0u64, 0u64, 0u64);
        let mut cur: Vec<bool> = Vec::with_capacity(self.0.len());
        for &w in &self.0 {
            c0 += w.count_ones() as u64;
            let t2 = {
                let t1 = w | (w >> 1);
                t1 | (t1 >> 2)
            };
            c1 += (t2 & 0x1111_1111_1111_1111).count_ones() as u64;
            let t4 = {
                let t3 = t2 | (t2 >> 4);
                t3 | (t3 >> 8)
            };
            c2 += (t4 & 0x0001_0001_0001_0001).count_ones() as u64;
            cur.push(w != 0);
        }
        let top = COARSE as usize;
        counts[top - 1] = c0;
        counts[top - 2] = c1;
        counts[top - 3] = c2;
        let mut level = top - 3;
        loop {
            counts[level - 1] = cur.iter().filter(|b| **b).count() as u64;
            if level == 1 {
                break;
            }
            cur = cur.chunks(4).map(|c| c.iter().any(|b| *b)).collect();
            level -= 1;
        }
        counts
    }
}

/// Level whose cells split the keys into buckets before sorting (4¹⁰ buckets).
const BUCKET_LEVEL: u32 = 10;
/// Buckets sorted by one task.
const BUCKETS_PER_TASK: usize = 1024;

/// Sort cell keys: one counting pass distributes them by their level-10 cell (the top 20 bits,
/// so the buckets follow each other in key order), then the buckets are sorted in parallel.
/// A set whose fit reaches past level 13 meets few level-10 cells, so the buckets are long and
/// few; sorting them costs n·log(n/buckets) instead of n·log n. Extra memory: 8 bytes per key
/// and two bucket tables of 4 MiB.
fn sort_keys(keys: Vec<u64>) -> Vec<u64> {
    let n = keys.len();
    let shift = 2 * (MAX_LEVEL - BUCKET_LEVEL);
    let buckets = 1usize << (2 * BUCKET_LEVEL);
    // Keys are at most MAX_SAMPLES < 2³², so u32 offsets suffice.
    let mut start = vec![0u32; buckets + 1];
    for &k in &keys {
        start[(k >> shift) as usize + 1] += 1;
    }
    for i in 0..buckets {
        start[i + 1] += start[i];
    }
    let mut pos = start.clone();
    let mut out = vec![0u64; n];
    for &k in &keys {
        let b = (k >> shift) as usize;
        out[pos[b] as usize] = k;
        pos[b] += 1;
    }
    drop(keys);
    drop(pos);
    let mut tasks = Vec::with_capacity(buckets / BUCKETS_PER_TASK);
    let mut rest: &mut [u64] = &mut out;
    for first in (0..buckets).step_by(BUCKETS_PER_TASK) {
        let len = (start[first + BUCKETS_PER_TASK] - start[first]) as usize;
        let (mine, tail) = rest.split_at_mut(len);
        tasks.push((first, mine));
        rest = tail;
    }
    tasks.into_par_iter().for_each(|(first, slice)| {
        let base = start[first];
        for b in first..first + BUCKETS_PER_TASK {
            let (lo, hi) = ((start[b] - base) as usize, (start[b + 1] - base) as usize);
            if hi - lo > 1 {
                slice[lo..hi].sort_unstable();
            }
        }
    });
    out
}

/// N(2^−k) for k = 1..=MAX_LEVEL from the keys of all points (sorted here).
fn fine_counts(keys: Vec<u64>) -> Vec<u64> {
    let keys = sort_keys(keys);
    // hist[j]: neighbouring keys whose first difference is in bit pair j (0 = finest).
    let hist = keys
        .par_windows(2)
        .fold(
            || [0u64; MAX_LEVEL as usize],
            |mut h, w| {
                let x = w[0] ^ w[1];
                if x != 0 {
                    let bit = 63 - x.leading_zeros();
                    h[(bit / 2) as usize] += 1;
                }
                h
            },
        )
        .reduce(
            || [0u64; MAX_LEVEL as usize],
            |mut a, b| {
                for (x, y) in a.iter_mut().zip(b) {
                    *x += y;
                }
                a
            },
        );
    // A new cell at level k starts wherever the first difference lies in bit pair
    // j ≥ MAX_LEVEL − k.
    (1..=MAX_LEVEL)
        .map(|k| 1 + hist[(MAX_LEVEL - k) as usize..].iter().sum::<u64>())
        .collect()
}

fn to_levels(counts: &[u64]) -> Vec<BoxLevel> {
    counts
        .iter()
        .enumerate()
        .map(|(i, &count)| BoxLevel {
            k: i as u32 + 1,
            count,
        })
        .collect()
}

/// Whether the fit may reach past the bitmap level (the counts there are still within the
/// 10 % rule), so the finer levels must be counted too.
fn needs_fine(coarse: &[u64], samples: u64) -> bool {
    coarse[COARSE as usize - 1] as f64 <= MAX_FILL * samples as f64
}

fn check_count(n: u64) -> Result<(), ExploreError> {
    if n < MIN_SAMPLES {
        return Err(ExploreError::Invalid(format!(
            "{n} points are too few for box counting; give at least {MIN_SAMPLES}"
        )));
    }
    if n > MAX_SAMPLES {
        return Err(ExploreError::TooLarge {
            what: "box counting samples".into(),
            count: n as f64,
            limit: MAX_SAMPLES as f64,
            hint: String::new(),
        });
    }
    Ok(())
}

/// Box counting of a point set: normalised to its bounding square, cells of side 2^−k, a
/// least-squares fit of ln N against k·ln 2 from level 3 up to the last level where N is at
/// most 10 % of the number of points. Levels 1–13 are always counted; finer ones (up to 30)
/// when the fit reaches them.
pub fn box_count_points(points: &[P2]) -> Result<BoxCount, ExploreError> {
    check_count(points.len() as u64)?;
    let bounds = points
        .par_iter()
        .fold(
            || Bounds::EMPTY,
            |mut b, p| {
                b.add(*p);
                b
            },
        )
        .reduce(
            || Bounds::EMPTY,
            |mut a, b| {
                if !b.is_empty() {
                    a.add(b.min);
                    a.add(b.max);
                }
                a
            },
        );
    let g = Grid::new(bounds)?;
    let mut bm = Bitmap::new();
    let mut n = 0u64;
    for p in points {
        if let Some(k) = g.key(*p) {
            bm.mark(k);
            n += 1;
        }
    }
    check_count(n)?;
    let coarse = bm.counts();
    drop(bm);
    let counts = if needs_fine(&coarse, n) {
        fine_counts(points.par_iter().filter_map(|p| g.key(*p)).collect())
    } else {
        coarse
    };
    Ok(BoxCount::from_levels(
        n,
        g.origin,
        g.side,
        to_levels(&counts),
    ))
}

/// Box counting of a deterministic point stream: `run` is called with a sink two or three
/// times (bounds, coarse counts, and the finer levels when the fit reaches them) and must
/// produce the same points every time, as a seeded chaos game does. Memory: at most
/// [`box_count_peak_bytes`].
pub fn box_count_stream(mut run: impl FnMut(&mut dyn FnMut(P2))) -> Result<BoxCount, ExploreError> {
    let mut bounds = Bounds::EMPTY;
    let mut total = 0u64;
    run(&mut |p| {
        bounds.add(p);
        total += 1;
    });
    check_count(total)?;
    let g = Grid::new(bounds)?;
    let mut bm = Bitmap::new();
    let mut n = 0u64;
    run(&mut |p| {
        if let Some(k) = g.key(p) {
            bm.mark(k);
            n += 1;
        }
    });
    check_count(n)?;
    let coarse = bm.counts();
    drop(bm);
    let counts = if needs_fine(&coarse, n) {
        let mut keys = Vec::with_capacity(n as usize);
        run(&mut |p| {
            if let Some(k) = g.key(p)
                && keys.len() < n as usize
            {
                keys.push(k);
            }
        });
        fine_counts(keys)
    } else {
        coarse
    };
    Ok(BoxCount::from_levels(
        n,
        g.origin,
        g.side,
        to_levels(&counts),
    ))
}

/// Box counting of a flame's attractor: `points` samples of the seeded chaos game (post and
/// final transforms applied, invisible transforms left out), counted in the flame's own
/// coordinates (before the camera).
pub fn box_count_flame(flame: &Flame, points: u64, seed: u64) -> Result<BoxCount, ExploreError> {
    if flame.ifs3d.is_some() {
        return Err(ExploreError::Invalid(
            "box counting works on plane sets; this is a 3-D IFS".into(),
        ));
    }
    check_samples(points)?;
    let chaos = Chaos::new(flame).map_err(|e| ExploreError::Invalid(e.to_string()))?;
    box_count_stream(|sink| {
        let mut rng = FastRng::new(seed);
        let mut left = points;
        while left > 0 {
            let b = left.min(SUB_BATCH);
            chaos.run_sub_batch(b, &mut rng, |p, vis| {
                if vis > 0.0 && p.x.is_finite() && p.y.is_finite() {
                    sink([p.x, p.y]);
                }
            });
            left -= b;
        }
    })
}

/// Refuse a sample count outside [MIN_SAMPLES, MAX_SAMPLES].
pub fn check_samples(points: u64) -> Result<(), ExploreError> {
    crate::explore::check_range(
        "the number of points",
        points as f64,
        MIN_SAMPLES as f64,
        MAX_SAMPLES as f64,
    )
}

/// A binary image: which pixels belong to the set.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mask {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Row-major, row 0 at the top.
    pub bits: Vec<bool>,
}

/// Which side of the threshold is the set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Ink {
    /// The class that is rarer along the image border (the border is mostly background).
    #[default]
    Auto,
    /// Pixels darker than the threshold (a drawing on white paper).
    Dark,
    /// Pixels at least as bright as the threshold (a render on black).
    Light,
}

impl Mask {
    /// Threshold a greyscale image: light pixels are those with value ≥ `threshold`.
    pub fn from_luma(img: &image::GrayImage, threshold: u8, ink: Ink) -> Mask {
        let (w, h) = img.dimensions();
        let light: Vec<bool> = img.pixels().map(|p| p.0[0] >= threshold).collect();
        let ink_is_light = match ink {
            Ink::Light => true,
            Ink::Dark => false,
            Ink::Auto => {
                let (mut border, mut border_light) = (0u64, 0u64);
                for y in 0..h {
                    for x in 0..w {
                        if x == 0 || y == 0 || x + 1 == w || y + 1 == h {
                            border += 1;
                            border_light += light[(y * w + x) as usize] as u64;
                        }
                    }
                }
                2 * border_light <= border
            }
        };
        Mask {
            width: w,
            height: h,
            bits: light.into_iter().map(|l| l == ink_is_light).collect(),
        }
    }

    /// Threshold any image by its luminance (Rec. 601 weights, as `image` converts to grey).
    pub fn from_image(img: &image::DynamicImage, threshold: u8, ink: Ink) -> Mask {
        Self::from_luma(&img.to_luma8(), threshold, ink)
    }

    /// Pixels in the set.
    pub fn count(&self) -> u64 {
        self.bits.iter().filter(|b| **b).count() as u64
    }
}

/// Box counting of a binary image: every set pixel is a point at its centre (y up); the
/// 10 % rule uses the number of set pixels.
pub fn box_count_mask(m: &Mask) -> Result<BoxCount, ExploreError> {
    let w = m.width as usize;
    let h = m.height as usize;
    let pts: Vec<P2> = m
        .bits
        .iter()
        .enumerate()
        .filter(|(_, b)| **b)
        .map(|(i, _)| [(i % w) as f64 + 0.5, (h - 1 - i / w) as f64 + 0.5])
        .collect();
    if pts.is_empty() {
        return Err(ExploreError::Invalid(
            "no pixel belongs to the set (try another --threshold or --ink)".into(),
        ));
    }
    box_count_points(&pts)
}

#[cfg(test)]
#[path = "box_count_tests.rs"]
mod tests;
