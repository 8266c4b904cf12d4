//! Fractal dimension: the similarity dimension of a set of contractions, box counting of point
//! sets, images and flame attractors (with the log-log points and the fitted line), the divider
//! (coastline) method and Voss's mass distribution with its lacunarity.
//!
//! Box counting estimates D = lim ln N(ε)/ln(1/ε), N(ε) being the number of grid cells of side ε
//! that meet the set; this limit is the box-counting (capacity) dimension, which can differ from
//! the Hausdorff dimension (Falconer, *Fractal Geometry*, ch. 3).

use rayon::prelude::*;

use super::{Bounds, ExploreError, P2};
use crate::flame::chaos::{Chaos, SUB_BATCH};
use crate::flame::model::Flame;
use crate::flame::rng::FastRng;

/// Upper end of the bisection interval of the similarity-dimension solver.
pub const SOLVER_MAX: f64 = 64.0;
/// Most maps the similarity-dimension solver accepts.
pub const MAX_RATIOS: usize = 100_000;

/// The similarity dimension of maps with contraction ratios r₁…r_n: the unique s ≥ 0 with
/// r₁^s + … + r_n^s = 1 (Moran's equation; exact for self-similar sets under the open set
/// condition). Solved by bisection on [0, 64] to 1e-12; the left side decreases strictly in s.
pub fn similarity_dimension(ratios: &[f64]) -> Result<f64, ExploreError> {
    if ratios.is_empty() {
        return Err(ExploreError::Invalid(
            "no contraction ratios given; give at least one ratio between 0 and 1".into(),
        ));
    }
    if ratios.len() > MAX_RATIOS {
        return Err(ExploreError::TooLarge {
            what: "contraction ratios".into(),
            count: ratios.len() as f64,
            limit: MAX_RATIOS as f64,
            hint: String::new(),
        });
    }
    for (i, &r) in ratios.iter().enumerate() {
        if !(r > 0.0 && r < 1.0) {
            return Err(ExploreError::Invalid(format!(
                "ratio {} is {r}; contraction ratios must lie strictly between 0 and 1",
                i + 1
            )));
        }
    }
    let f = |s: f64| ratios.iter().map(|r| r.powf(s)).sum::<f64>() - 1.0;
    if ratios.len() == 1 {
        return Ok(0.0);
    }
    let (mut lo, mut hi) = (0.0, SOLVER_MAX);
    if f(hi) > 0.0 {
        return Err(ExploreError::Invalid(format!(
            "the dimension of these {} ratios exceeds {SOLVER_MAX}",
            ratios.len()
        )));
    }
    while hi - lo > 1e-12 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// Dimension of N copies scaled by r: D = log N / log(1/r).
pub fn equal_ratio_dimension(n: u64, r: f64) -> f64 {
    (n as f64).ln() / (1.0 / r).ln()
}

/// A least-squares line y = slope·x + intercept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineFit {
    pub slope: f64,
    pub intercept: f64,
    /// Coefficient of determination (1 for points exactly on the line).
    pub r2: f64,
    /// Points used.
    pub n: usize,
}

/// Fit a line to (x, y) points by least squares; `None` for fewer than 2 distinct x.
pub fn fit_line(pts: &[(f64, f64)]) -> Option<LineFit> {
    let n = pts.len();
    if n < 2 {
        return None;
    }
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / n as f64;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / n as f64;
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let syy: f64 = pts.iter().map(|p| (p.1 - my) * (p.1 - my)).sum();
    if sxx <= 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let r2 = if syy > 0.0 {
        (sxy * sxy) / (sxx * syy)
    } else {
        1.0
    };
    Some(LineFit {
        slope,
        intercept: my - slope * mx,
        r2,
        n,
    })
}

// ---------------------------------------------------------------------------------------------
// Box counting

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
    pub k: u32,
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
    super::check_range(
        "the number of points",
        points as f64,
        MIN_SAMPLES as f64,
        MAX_SAMPLES as f64,
    )
}

/// A binary image: which pixels belong to the set.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mask {
    pub width: u32,
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

// ---------------------------------------------------------------------------------------------
// Divider (coastline) method

/// Ruler lengths and measured lengths (km) of the coastline example of the Su Xiaohong slides
/// (after Mandelbrot, "How long is the coast of Britain?", Science 1967).
pub const COASTLINE_DATA: [(f64, f64); 4] = [
    (500.0, 2500.0),
    (100.0, 3800.0),
    (50.0, 5700.0),
    (17.0, 8640.0),
];

/// The divider method: measured length u ∝ s^{1−D}. Returns the least-squares line of ln u
/// against ln s and D = 1 − slope.
pub fn divider_dimension(data: &[(f64, f64)]) -> Result<(LineFit, f64), ExploreError> {
    for &(s, u) in data {
        if !(s > 0.0 && u > 0.0 && s.is_finite() && u.is_finite()) {
            return Err(ExploreError::Invalid(format!(
                "ruler {s} and length {u}: both must be positive"
            )));
        }
    }
    let pts: Vec<(f64, f64)> = data.iter().map(|&(s, u)| (s.ln(), u.ln())).collect();
    let fit = fit_line(&pts).ok_or_else(|| {
        ExploreError::Invalid("the divider fit needs at least two different rulers".into())
    })?;
    Ok((fit, 1.0 - fit.slope))
}

/// Walk a polyline with dividers of opening `ruler`: from the start, each step goes to the
/// first later point of the curve at distance `ruler`. Returns the number of full steps and the
/// measured length (steps·ruler plus the last, shorter piece to the end point).
pub fn divider_length(curve: &[P2], ruler: f64) -> Result<(u64, f64), ExploreError> {
    if !(ruler > 0.0 && ruler.is_finite()) {
        return Err(ExploreError::Invalid(format!(
            "ruler length {ruler} must be positive"
        )));
    }
    if curve.len() < 2 {
        return Err(ExploreError::Invalid(
            "the divider method needs a curve of at least two points".into(),
        ));
    }
    let total: f64 = curve.windows(2).map(|w| dist(w[0], w[1])).sum();
    if total / ruler > 1e8 {
        return Err(ExploreError::TooLarge {
            what: "divider steps".into(),
            count: total / ruler,
            limit: 1e8,
            hint: "; use a longer ruler".into(),
        });
    }
    let mut c = curve[0];
    let mut seg = 0usize;
    let mut t0 = 0.0;
    let mut steps = 0u64;
    let r2 = ruler * ruler;
    while seg + 1 < curve.len() {
        let (a, b) = (curve[seg], curve[seg + 1]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let f = [a[0] - c[0], a[1] - c[1]];
        // |f + t d|² = r²; the curve leaves the circle at the larger root.
        let qa = d[0] * d[0] + d[1] * d[1];
        let qb = 2.0 * (f[0] * d[0] + f[1] * d[1]);
        let qc = f[0] * f[0] + f[1] * f[1] - r2;
        let disc = qb * qb - 4.0 * qa * qc;
        if qa > 0.0 && disc >= 0.0 {
            let t = (-qb + disc.sqrt()) / (2.0 * qa);
            // A step ending exactly on a vertex may round to just past it.
            if t >= t0 && t <= 1.0 + 1e-12 {
                let t = t.min(1.0);
                c = [a[0] + t * d[0], a[1] + t * d[1]];
                t0 = t;
                steps += 1;
                continue;
            }
        }
        seg += 1;
        t0 = 0.0;
    }
    let rest = dist(c, curve[curve.len() - 1]);
    Ok((steps, steps as f64 * ruler + rest))
}

fn dist(a: P2, b: P2) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

// ---------------------------------------------------------------------------------------------
// Voss mass distribution and lacunarity

/// Most box centres sampled per box size by [`voss`].
pub const VOSS_MAX_CENTRES: usize = 20_000;
/// Most points [`voss`] accepts.
pub const VOSS_MAX_POINTS: usize = 2_000_000;

/// Voss's mass distribution at one box size Γ: p(m, Γ) is the probability that a box of side Γ
/// centred on a point of the set holds m points (R. F. Voss, "Random fractals: characterization
/// and measurement", 1986).
#[derive(Clone, Debug, PartialEq)]
pub struct VossLevel {
    pub gamma: f64,
    /// Boxes counted (centred on points whose box lies inside the bounding square).
    pub centres: usize,
    /// (m, p(m, Γ)) for every m that occurs, m ascending.
    pub distribution: Vec<(u64, f64)>,
    /// N(Γ) = Σ p(m, Γ)/m.
    pub n: f64,
    /// M(Γ) = Σ m·p(m, Γ).
    pub m1: f64,
    /// M₂(Γ) = Σ m²·p(m, Γ).
    pub m2: f64,
    /// Λ(Γ) = (M₂ − M²)/M².
    pub lacunarity: f64,
}

impl VossLevel {
    /// Moments of a distribution given as (m, p) pairs.
    pub fn from_distribution(gamma: f64, centres: usize, distribution: Vec<(u64, f64)>) -> Self {
        let n = distribution.iter().map(|&(m, p)| p / m as f64).sum();
        let m1: f64 = distribution.iter().map(|&(m, p)| m as f64 * p).sum();
        let m2: f64 = distribution
            .iter()
            .map(|&(m, p)| (m as f64) * (m as f64) * p)
            .sum();
        VossLevel {
            gamma,
            centres,
            distribution,
            n,
            m1,
            m2,
            lacunarity: (m2 - m1 * m1) / (m1 * m1),
        }
    }
}

/// Mandelbrot's lacunarity of box masses: E[(M/E(M) − 1)²].
pub fn lacunarity_of_masses(masses: &[u64]) -> f64 {
    let n = masses.len() as f64;
    let mean = masses.iter().map(|&m| m as f64).sum::<f64>() / n;
    masses
        .iter()
        .map(|&m| (m as f64 / mean - 1.0).powi(2))
        .sum::<f64>()
        / n
}

/// The mass distribution of a point set at each box size. Boxes are closed squares of side Γ
/// centred on points of the set; only boxes lying inside the set's bounding square are counted
/// (so the edge of a finite sample does not pose as a gap), and at most
/// [`VOSS_MAX_CENTRES`] centres, evenly spread over the points, are used per size. Sizes
/// without any such box are left out.
pub fn voss(points: &[P2], gammas: &[f64]) -> Result<Vec<VossLevel>, ExploreError> {
    if points.len() < 2 {
        return Err(ExploreError::Invalid(
            "the mass distribution needs at least two points".into(),
        ));
    }
    if points.len() > VOSS_MAX_POINTS {
        return Err(ExploreError::TooLarge {
            what: "points for the mass distribution".into(),
            count: points.len() as f64,
            limit: VOSS_MAX_POINTS as f64,
            hint: String::new(),
        });
    }
    if gammas.is_empty() || gammas.len() > 64 {
        return Err(ExploreError::Invalid(format!(
            "{} box sizes given; give 1 to 64",
            gammas.len()
        )));
    }
    let b = Bounds::of(points.iter().copied());
    let side = b.width().max(b.height());
    if side.is_nan() || side <= 0.0 {
        return Err(ExploreError::Invalid("all points coincide".into()));
    }
    // The bounding square, centred on the bounding box.
    let cx = 0.5 * (b.min[0] + b.max[0]);
    let cy = 0.5 * (b.min[1] + b.max[1]);
    let sq = [
        cx - side / 2.0,
        cy - side / 2.0,
        cx + side / 2.0,
        cy + side / 2.0,
    ];
    let mut out = Vec::new();
    for &g in gammas {
        if !(g > 0.0 && g.is_finite() && g >= side * 1e-6) {
            return Err(ExploreError::Invalid(format!(
                "box size {g} must be positive and at least a millionth of the set's extent {side}"
            )));
        }
        // Points sorted into cells of side Γ.
        let cell = |p: P2| -> (i64, i64) {
            (
                ((p[0] - sq[0]) / g).floor() as i64,
                ((p[1] - sq[1]) / g).floor() as i64,
            )
        };
        let mut idx: Vec<((i64, i64), u32)> = points
            .iter()
            .enumerate()
            .map(|(i, p)| (cell(*p), i as u32))
            .collect();
        idx.sort_unstable();
        let cells: Vec<(i64, i64)> = idx.iter().map(|e| e.0).collect();
        let h = g / 2.0;
        let centres: Vec<usize> = (0..points.len())
            .filter(|&i| {
                let p = points[i];
                p[0] - h >= sq[0] && p[0] + h <= sq[2] && p[1] - h >= sq[1] && p[1] + h <= sq[3]
            })
            .collect();
        if centres.is_empty() {
            continue;
        }
        let stride = centres.len().div_ceil(VOSS_MAX_CENTRES);
        let chosen: Vec<usize> = centres.iter().step_by(stride).copied().collect();
        let masses: Vec<u64> = chosen
            .par_iter()
            .map(|&i| {
                let p = points[i];
                let (x0, y0) = cell([p[0] - h, p[1] - h]);
                let (x1, y1) = cell([p[0] + h, p[1] + h]);
                let mut m = 0u64;
                for cxi in x0..=x1 {
                    for cyi in y0..=y1 {
                        let lo = cells.partition_point(|c| *c < (cxi, cyi));
                        let hi = cells.partition_point(|c| *c <= (cxi, cyi));
                        for e in &idx[lo..hi] {
                            let q = points[e.1 as usize];
                            if (q[0] - p[0]).abs() <= h && (q[1] - p[1]).abs() <= h {
                                m += 1;
                            }
                        }
                    }
                }
                m
            })
            .collect();
        let mut sorted = masses.clone();
        sorted.sort_unstable();
        let total = sorted.len() as f64;
        let mut dist: Vec<(u64, f64)> = Vec::new();
        for m in sorted {
            match dist.last_mut() {
                Some((lm, c)) if *lm == m => *c += 1.0,
                _ => dist.push((m, 1.0)),
            }
        }
        for d in &mut dist {
            d.1 /= total;
        }
        out.push(VossLevel::from_distribution(g, chosen.len(), dist));
    }
    Ok(out)
}

/// Voss's dimension estimate: N(Γ) ∝ Γ^−D, so D is the slope of −ln N(Γ) against ln Γ.
pub fn voss_dimension(levels: &[VossLevel]) -> Option<LineFit> {
    let pts: Vec<(f64, f64)> = levels.iter().map(|l| (l.gamma.ln(), -l.n.ln())).collect();
    fit_line(&pts)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    #[test]
    fn similarity_dimension_table() {
        let phi2 = 2.0 / (3.0 + 5f64.sqrt());
        let cases: Vec<(Vec<f64>, f64)> = vec![
            (vec![1.0 / 3.0; 2], 0.63093),
            (vec![1.0 / 3.0; 4], 1.26186),
            (vec![1.0 / 3.0; 5], 1.46497),
            (vec![0.25; 8], 1.5),
            (vec![0.5; 3], 1.58496),
            (vec![phi2; 5], 1.67228),
            (vec![1.0 / 3.0; 8], 1.89279),
            (vec![1.0 / 3.0; 9], 2.0),
            (vec![0.5; 4], 2.0),
            (vec![1.0 / 3.0; 20], 2.72683),
            (vec![0.5, 0.25, 0.25], 1.0),
            (vec![0.5, 0.5, 0.25], 1.27155),
        ];
        for (r, d) in cases {
            let s = similarity_dimension(&r).unwrap();
            assert!(close(s, d, 5e-6), "{r:?}: {s} vs {d}");
        }
        // Exact forms.
        let s = similarity_dimension(&[1.0 / 3.0; 2]).unwrap();
        assert!(close(s, 2f64.ln() / 3f64.ln(), 1e-11));
        assert!(close(
            similarity_dimension(&[0.5, 0.25, 0.25]).unwrap(),
            1.0,
            1e-11
        ));
        let x = 2f64.sqrt() - 1.0;
        assert!(close(
            similarity_dimension(&[0.5, 0.5, 0.25]).unwrap(),
            -x.log2(),
            1e-11
        ));
        // Dürer pentagon: ln 5 / ln((3 + √5)/2), not the slides' misprint log 5/log(3 + √5/2).
        let durer = 5f64.ln() / ((3.0 + 5f64.sqrt()) / 2.0).ln();
        assert!(close(
            similarity_dimension(&[phi2; 5]).unwrap(),
            durer,
            1e-11
        ));
        assert!(!close(
            durer,
            5f64.ln() / (3.0 + 5f64.sqrt() / 2.0).ln(),
            0.1
        ));
        assert!(close(equal_ratio_dimension(20, 1.0 / 3.0), 2.72683, 5e-6));
        // Scaling by B = 3 gives M = 3, 9, 27 copies of a segment, square, cube: d = 1, 2, 3.
        for (m, d) in [(3, 1.0), (9, 2.0), (27, 3.0)] {
            assert!(close(equal_ratio_dimension(m, 1.0 / 3.0), d, 1e-12));
        }
    }

    #[test]
    fn similarity_dimension_refuses_bad_ratios() {
        assert!(similarity_dimension(&[]).is_err());
        assert!(similarity_dimension(&[0.5, 1.0]).is_err());
        assert!(similarity_dimension(&[0.5, 0.0]).is_err());
        assert!(similarity_dimension(&[0.5, f64::NAN]).is_err());
        assert_eq!(similarity_dimension(&[0.5]).unwrap(), 0.0);
    }

    fn random_points(n: usize, seed: u64, f: impl Fn(f64, f64) -> P2) -> Vec<P2> {
        let mut r = FastRng::new(seed);
        (0..n).map(|_| f(r.f01(), r.f01())).collect()
    }

    #[test]
    fn box_counting_of_a_segment_and_a_square() {
        let seg = random_points(1_000_000, 1, |u, _| [u, 0.3 * u]);
        let b = box_count_points(&seg).unwrap();
        let d = b.dimension().unwrap();
        assert!(close(d, 1.0, 0.02), "segment {d}");
        assert_eq!(b.fit_range.unwrap().0, 3);
        let sq = random_points(1_000_000, 2, |u, v| [u, v]);
        let b = box_count_points(&sq).unwrap();
        let d = b.dimension().unwrap();
        assert!(close(d, 2.0, 0.02), "square {d}");
        // Counts at the fit range: every cell of a filled square is met; the fit stops where
        // N would exceed 10 % of the points.
        let (k0, k1) = b.fit_range.unwrap();
        assert_eq!((k0, k1), (3, 8));
        assert_eq!(b.levels[7].count, 4u64.pow(8));
        assert!(b.levels[8].count as f64 > 0.1e6);
    }

    #[test]
    fn counting_matches_a_direct_count() {
        let pts = random_points(5000, 3, |u, v| [u * u, v * u]);
        let b = box_count_points(&pts).unwrap();
        for lvl in [1u32, 4, 7, 12] {
            let n = 1u64 << lvl;
            let mut cells: Vec<(u64, u64)> = pts
                .iter()
                .map(|p| {
                    let ix = (((p[0] - b.origin[0]) / b.side * n as f64) as u64).min(n - 1);
                    let iy = (((p[1] - b.origin[1]) / b.side * n as f64) as u64).min(n - 1);
                    (ix, iy)
                })
                .collect();
            cells.sort_unstable();
            cells.dedup();
            assert_eq!(
                b.levels[lvl as usize - 1].count,
                cells.len() as u64,
                "k={lvl}"
            );
        }
    }

    #[test]
    fn bitmap_and_sorted_keys_agree() {
        // A parabola arc of 500 000 points stays under the 10 % rule past level 13 (about
        // 1.5·2^k cells at level k), so the finer levels are counted from sorted keys; both
        // ways give the same counts up to 13.
        let pts = random_points(500_000, 4, |u, _| [u, 0.5 * u * u]);
        let b = box_count_points(&pts).unwrap();
        assert_eq!(b.levels.len(), MAX_LEVEL as usize);
        let g = Grid::new(Bounds::of(pts.iter().copied())).unwrap();
        let mut bm = Bitmap::new();
        for p in &pts {
            bm.mark(g.key(*p).unwrap());
        }
        let coarse = bm.counts();
        for (k, c) in coarse.iter().enumerate() {
            assert_eq!(b.levels[k].count, *c, "k={}", k + 1);
        }
        for lvl in [14u32, 16, 18] {
            let n = 1u64 << lvl;
            let mut cells: Vec<(u64, u64)> = pts
                .iter()
                .map(|p| {
                    let ix = (((p[0] - b.origin[0]) / b.side * n as f64) as u64).min(n - 1);
                    let iy = (((p[1] - b.origin[1]) / b.side * n as f64) as u64).min(n - 1);
                    (ix, iy)
                })
                .collect();
            cells.sort_unstable();
            cells.dedup();
            assert_eq!(
                b.levels[lvl as usize - 1].count,
                cells.len() as u64,
                "k={lvl}"
            );
        }
        assert!(b.fit_range.unwrap().1 > COARSE);
        // The stream gives the same result as the slice.
        let s = box_count_stream(|sink| pts.iter().for_each(|p| sink(*p))).unwrap();
        assert_eq!(s, b);
        // Spread keys, and keys crowded into one bucket, come out sorted.
        for spread in [4u32, 40] {
            let keys: Vec<u64> = (0..50_000u64)
                .map(|i| i.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> spread)
                .collect();
            let mut want = keys.clone();
            want.sort_unstable();
            assert_eq!(sort_keys(keys), want);
        }
    }

    #[test]
    fn box_counting_refuses_degenerate_sets() {
        assert!(box_count_points(&[[1.0, 1.0]; 500]).is_err());
        assert!(box_count_points(&[[0.0, 0.0], [1.0, 1.0]]).is_err());
        assert!(box_count_points(&[]).is_err());
        assert!(check_samples(10).is_err());
        assert!(check_samples(MAX_SAMPLES + 1).is_err());
    }

    #[test]
    fn box_counting_of_images() {
        // A filled disc: D = 2; a one-pixel circle outline: D = 1.
        let n = 1024u32;
        let disc = image::GrayImage::from_fn(n, n, |x, y| {
            let (dx, dy) = (x as f64 - 512.0, y as f64 - 512.0);
            image::Luma([if dx.hypot(dy) < 500.0 { 255 } else { 0 }])
        });
        let m = Mask::from_luma(&disc, 128, Ink::Auto);
        let d = box_count_mask(&m).unwrap().dimension().unwrap();
        assert!(close(d, 2.0, 0.05), "disc {d}");
        // Dark ink on white: the mask picks the dark pixels automatically.
        let line =
            image::GrayImage::from_fn(n, n, |x, y| image::Luma([if x == y { 0 } else { 255 }]));
        let m = Mask::from_luma(&line, 128, Ink::Auto);
        assert_eq!(m.count(), n as u64);
        let b = box_count_mask(&m).unwrap();
        assert!(close(b.dimension().unwrap(), 1.0, 0.02), "{b:?}");
        let m = Mask::from_luma(&line, 128, Ink::Light);
        assert_eq!(m.count(), (n * n - n) as u64);
        let empty = image::GrayImage::new(8, 8);
        assert!(box_count_mask(&Mask::from_luma(&empty, 128, Ink::Light)).is_err());
    }

    #[test]
    fn divider_on_the_coastline_data() {
        let (fit, d) = divider_dimension(&COASTLINE_DATA).unwrap();
        assert!(close(fit.slope, -0.371221, 1e-6), "{}", fit.slope);
        assert!(close(d, 1.371, 5e-4), "{d}");
        assert!(divider_dimension(&[(1.0, 2.0)]).is_err());
        assert!(divider_dimension(&[(1.0, 2.0), (-1.0, 3.0)]).is_err());
    }

    #[test]
    fn divider_walk_on_curves() {
        // A straight line measures its own length with any ruler.
        let line = [[0.0, 0.0], [3.0, 4.0], [6.0, 8.0]];
        let (steps, len) = divider_length(&line, 2.0).unwrap();
        assert_eq!(steps, 5);
        assert!(close(len, 10.0, 1e-12));
        // On a Koch curve (order 7), rulers 3^−2..3^−5 step exactly along the segments of
        // the corresponding level: lengths (4/3)^k, D = log 4 / log 3.
        let pts = crate::explore::classic::koch_curve_points(7);
        let data: Vec<(f64, f64)> = (2..=5)
            .map(|k| {
                let s = 3f64.powi(-k);
                (s, divider_length(&pts, s).unwrap().1)
            })
            .collect();
        for (k, &(_, u)) in (2..=5).zip(&data) {
            assert!(close(u, (4.0f64 / 3.0).powi(k), 1e-6), "k={k}: {u}");
        }
        let (_, d) = divider_dimension(&data).unwrap();
        assert!(close(d, 1.26186, 1e-5), "{d}");
        assert!(divider_length(&line, 0.0).is_err());
        assert!(divider_length(&line[..1], 1.0).is_err());
    }

    #[test]
    fn lacunarity_of_a_regular_lattice_is_zero() {
        // A 60×60 lattice: every box of side 3 centred on an interior point holds 9 points.
        let pts: Vec<P2> = (0..3600)
            .map(|i| [(i % 60) as f64, (i / 60) as f64])
            .collect();
        let lv = voss(&pts, &[3.0, 5.0]).unwrap();
        assert_eq!(lv[0].distribution, vec![(9, 1.0)]);
        assert_eq!(lv[0].m1, 9.0);
        assert_eq!(lv[0].m2, 81.0);
        assert_eq!(lv[0].lacunarity, 0.0);
        assert_eq!(lv[1].distribution, vec![(25, 1.0)]);
        // N(Γ) = 1/m: for the lattice (a filled square) D = 2 from these two sizes.
        let fit = voss_dimension(&lv).unwrap();
        assert!(close(fit.slope, 2.0, 1e-12));
        assert_eq!(lacunarity_of_masses(&[9; 10]), 0.0);
    }

    #[test]
    fn lacunarity_definitions_agree() {
        // Voss's (M₂ − M²)/M² and Mandelbrot's E[(M/E(M) − 1)²] on the same masses.
        let masses = [1u64, 1, 2, 3, 3, 3, 7, 12];
        let mut dist: Vec<(u64, f64)> = Vec::new();
        for &m in &masses {
            match dist.iter_mut().find(|d| d.0 == m) {
                Some(d) => d.1 += 1.0 / 8.0,
                None => dist.push((m, 1.0 / 8.0)),
            }
        }
        let v = VossLevel::from_distribution(1.0, 8, dist);
        assert!(close(v.lacunarity, lacunarity_of_masses(&masses), 1e-12));
        assert!(v.lacunarity > 0.5);
        // A set with a dense clump and sparse surroundings is far more lacunar (its box
        // masses vary more) than a uniform set at the same box size.
        let uniform = random_points(20_000, 5, |u, v| [u, v]);
        let clumpy = random_points(20_000, 6, |u, v| {
            if u < 0.5 {
                [2.0 * u, v]
            } else {
                [0.5 + 0.06 * (u - 0.5), 0.5 + 0.03 * v]
            }
        });
        let lu = voss(&uniform, &[0.1]).unwrap()[0].lacunarity;
        let lc = voss(&clumpy, &[0.1]).unwrap()[0].lacunarity;
        assert!(lc > 2.0 * lu, "{lc} vs {lu}");
    }
}
