//! The chaos game (flame.md §3): a flame compiled for fast iteration.

use crate::flame::model::{Affine, Flame, Xform};
use crate::flame::rng::FastRng;
use crate::flame::variations::{self, Needs, Pre, Prepared};

/// flam3 `CHOOSE_XFORM_GRAIN`.
pub const CHOOSE_GRAIN: usize = 16384;
/// Fuse iterations at the start of every sub-batch (flam3 `FUSE_27`).
pub const FUSE: i64 = 15;
/// Samples per sub-batch.
pub const SUB_BATCH: u64 = 10_000;
/// A coordinate beyond this magnitude is a bad value.
pub const BAD_LIMIT: f64 = 1e10;

/// Why a flame cannot be iterated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ChaosError {
    #[error("cannot iterate empty flame: it has no transforms")]
    NoXforms,
    #[error("cannot iterate empty flame: all transform weights are 0")]
    ZeroWeights,
    #[error("transform {0} has weight {1}; weights must be finite and non-negative")]
    BadWeight(usize, f64),
    #[error("transform {0}: xaos row has zero total; at least one reachable transform is needed")]
    XaosRowZero(usize),
    #[error("transform {0}: xaos value {1} must be finite and non-negative")]
    BadXaos(usize, f64),
}

/// One xform ready for iteration.
#[derive(Clone, Debug)]
pub struct CompiledXform {
    pub coefs: Affine,
    pub post: Option<Affine>,
    pub vars: Vec<Prepared>,
    pub pre_blur: f64,
    pub needs: Needs,
    pub color: f64,
    pub color_speed: f64,
    /// Plotted visibility o^(log2 10).
    pub vis: f64,
    pub opacity: f64,
}

/// flam3 `adjust_percentage`: vis = o^(log₂10), with 0 ↦ 0.
pub fn adjust_opacity(o: f64) -> f64 {
    if o <= 0.0 {
        0.0
    } else {
        o.powf(std::f64::consts::LOG2_10)
    }
}

impl CompiledXform {
    pub fn new(x: &Xform, opacity: f64) -> Self {
        let mut vars = Vec::with_capacity(x.vars.len());
        let mut needs = Needs {
            sqrt: true,
            ..Needs::default()
        };
        let mut pre_blur = 0.0;
        for v in &x.vars {
            if v.weight == 0.0 || !variations::is_implemented(v.id) {
                continue;
            }
            if v.id == variations::PRE_BLUR {
                pre_blur += v.weight;
                continue;
            }
            needs = needs.union(Needs::of(v.id));
            vars.push(Prepared::new(v.id, v.weight, &v.params));
        }
        CompiledXform {
            coefs: x.coefs,
            post: if x.post.is_identity() {
                None
            } else {
                Some(x.post)
            },
            vars,
            pre_blur,
            needs,
            color: x.color,
            color_speed: x.color_speed,
            vis: adjust_opacity(opacity),
            opacity,
        }
    }

    /// Apply to (x, y, c). Returns the new point and whether it was a bad value (in which case
    /// the point is a uniform random point of [−1, 1]² and the colour is still updated).
    #[inline(always)]
    pub fn apply(&self, x: f64, y: f64, c: f64, rng: &mut FastRng) -> (f64, f64, f64, bool) {
        let nc = self.color_speed * self.color + (1.0 - self.color_speed) * c;
        let (mut tx, mut ty) = self.coefs.apply(x, y);
        if self.pre_blur != 0.0 {
            (tx, ty) = variations::pre_blur(self.pre_blur, tx, ty, rng);
        }
        let pre = Pre::new(tx, ty, self.needs);
        let (mut px, mut py) = (0.0, 0.0);
        for v in &self.vars {
            let (dx, dy) = variations::apply(v, &pre, &self.coefs, rng);
            px += dx;
            py += dy;
        }
        if let Some(post) = &self.post {
            (px, py) = post.apply(px, py);
        }
        // NaN fails every comparison, so `!(|v| <= limit)` catches it too.
        if !(px.abs() <= BAD_LIMIT && py.abs() <= BAD_LIMIT) {
            return (rng.f11(), rng.f11(), nc, true);
        }
        (px, py, nc, false)
    }
}

impl CompiledXform {
    /// Apply to the points `idx` of the lane arrays (x, y, c), in place. `bad[i]` is set for
    /// every lane whose result was a bad value (then replaced by a random point of [−1, 1]²).
    #[inline(always)]
    fn apply_group(&self, idx: &[u16], lanes: &mut Lanes, sc: &mut Scratch, rng: &mut FastRng) {
        let n = idx.len();
        sc.pre.clear();
        for &l in idx {
            let l = l as usize;
            let (mut tx, mut ty) = self.coefs.apply(lanes.x[l], lanes.y[l]);
            if self.pre_blur != 0.0 {
                (tx, ty) = variations::pre_blur(self.pre_blur, tx, ty, rng);
            }
            sc.pre.push(Pre::new(tx, ty, self.needs));
        }
        let (px, py) = (&mut sc.px[..n], &mut sc.py[..n]);
        px.fill(0.0);
        py.fill(0.0);
        for v in &self.vars {
            (v.batch)(v, &sc.pre, &self.coefs, rng, px, py);
        }
        for (j, &l) in idx.iter().enumerate() {
            let l = l as usize;
            let (mut nx, mut ny) = (px[j], py[j]);
            if let Some(post) = &self.post {
                (nx, ny) = post.apply(nx, ny);
            }
            lanes.c[l] = self.color_speed * self.color + (1.0 - self.color_speed) * lanes.c[l];
            if nx.abs() <= BAD_LIMIT && ny.abs() <= BAD_LIMIT {
                lanes.x[l] = nx;
                lanes.y[l] = ny;
                lanes.bad[l] = false;
            } else {
                lanes.x[l] = rng.f11();
                lanes.y[l] = rng.f11();
                lanes.bad[l] = true;
            }
        }
    }
}

/// Number of independent orbits iterated together by [`Chaos::run_lanes`].
pub const LANES: usize = 64;

/// Per-orbit state of the lane runner.
#[derive(Clone, Debug)]
pub struct Lanes {
    x: [f64; LANES],
    y: [f64; LANES],
    c: [f64; LANES],
    bad: [bool; LANES],
}

impl Default for Lanes {
    fn default() -> Self {
        Lanes {
            x: [0.0; LANES],
            y: [0.0; LANES],
            c: [0.0; LANES],
            bad: [false; LANES],
        }
    }
}

/// Reusable buffers of the lane runner (one per worker thread).
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    pre: Vec<Pre>,
    px: Vec<f64>,
    py: Vec<f64>,
}

impl Scratch {
    pub fn new() -> Self {
        Scratch {
            pre: Vec::with_capacity(LANES),
            px: vec![0.0; LANES],
            py: vec![0.0; LANES],
        }
    }
}

/// A flame compiled for the chaos game.
#[derive(Clone, Debug)]
pub struct Chaos {
    pub xforms: Vec<CompiledXform>,
    pub final_xform: Option<CompiledXform>,
    /// Row 0: plain weights. Rows 1..=n: xaos rows after xform i − 1 (only when xaos is used).
    tables: Vec<Box<[u16]>>,
    xaos: bool,
}

/// Build the 16 384-entry selection table for weights `w` (flame.md §3.1).
pub fn selection_table(w: &[f64]) -> Box<[u16]> {
    let n = w.len();
    let total: f64 = w.iter().sum();
    let delta = total / CHOOSE_GRAIN as f64;
    let mut t = vec![0u16; CHOOSE_GRAIN].into_boxed_slice();
    let mut j = 0usize;
    let mut acc = w[0];
    let mut r = 0.0;
    for slot in t.iter_mut() {
        while r >= acc && j < n - 1 {
            j += 1;
            acc += w[j];
        }
        *slot = j as u16;
        r += delta;
    }
    t
}

impl Chaos {
    pub fn new(flame: &Flame) -> Result<Self, ChaosError> {
        let n = flame.xforms.len();
        if n == 0 {
            return Err(ChaosError::NoXforms);
        }
        for (i, x) in flame.xforms.iter().enumerate() {
            if !(x.weight.is_finite() && x.weight >= 0.0) {
                return Err(ChaosError::BadWeight(i, x.weight));
            }
        }
        let weights: Vec<f64> = flame.xforms.iter().map(|x| x.weight).collect();
        if weights.iter().sum::<f64>() <= 0.0 {
            return Err(ChaosError::ZeroWeights);
        }
        let xforms: Vec<CompiledXform> = flame
            .xforms
            .iter()
            .enumerate()
            .map(|(i, x)| {
                let o = match flame.solo_xform {
                    Some(s) if s < n && s != i => 0.0,
                    _ => x.opacity,
                };
                CompiledXform::new(x, o)
            })
            .collect();
        let xaos = flame
            .xforms
            .iter()
            .any(|x| (0..n).any(|j| x.chaos_to(j) != 1.0));
        let mut tables = vec![selection_table(&weights)];
        if xaos {
            for (i, x) in flame.xforms.iter().enumerate() {
                let row: Vec<f64> = (0..n)
                    .map(|j| {
                        let c = x.chaos_to(j);
                        if !(c.is_finite() && c >= 0.0) {
                            return Err(ChaosError::BadXaos(i, c));
                        }
                        Ok(weights[j] * c)
                    })
                    .collect::<Result<_, _>>()?;
                if row.iter().sum::<f64>() <= 0.0 {
                    return Err(ChaosError::XaosRowZero(i));
                }
                tables.push(selection_table(&row));
            }
        }
        let final_xform = flame
            .final_xform
            .as_ref()
            .map(|f| CompiledXform::new(f, f.opacity));
        Ok(Chaos {
            xforms,
            final_xform,
            tables,
            xaos,
        })
    }

    /// Draw the next xform; `last` is the previously applied xform (None at the start).
    #[inline(always)]
    pub fn choose(&self, last: Option<usize>, rng: &mut FastRng) -> usize {
        let row = match (self.xaos, last) {
            (true, Some(i)) => i + 1,
            _ => 0,
        };
        let u = rng.u32() as usize & (CHOOSE_GRAIN - 1);
        // SAFETY-free: tables have exactly CHOOSE_GRAIN entries and u is masked.
        self.tables[row][u] as usize
    }

    /// Apply the final xform (if any, with its opacity as a probability) to a copy of a point.
    #[inline(always)]
    pub fn finalise(&self, x: f64, y: f64, c: f64, rng: &mut FastRng) -> (f64, f64, f64) {
        match &self.final_xform {
            Some(f) if f.opacity >= 1.0 || rng.f01() < f.opacity => {
                let (fx, fy, fc, _) = f.apply(x, y, c, rng);
                (fx, fy, fc)
            }
            _ => (x, y, c),
        }
    }

    /// Run one sub-batch of `n` plotted samples (flame.md §3.3). `plot(x, y, c, vis)` receives
    /// every point after the fuse, final xform applied. Returns the number of bad values.
    #[inline(always)]
    pub fn run_sub_batch<F: FnMut(f64, f64, f64, f64)>(
        &self,
        n: u64,
        rng: &mut FastRng,
        mut plot: F,
    ) -> u64 {
        let mut x = rng.f11();
        let mut y = rng.f11();
        let mut c = rng.f01();
        let mut k: i64 = -FUSE;
        let mut consec = 0u32;
        let mut bad = 0u64;
        let mut last = None;
        let n = n as i64;
        while k < n {
            let i = self.choose(last, rng);
            let xf = &self.xforms[i];
            let (nx, ny, nc, is_bad) = xf.apply(x, y, c, rng);
            if is_bad {
                consec += 1;
                bad += 1;
                if consec < 5 {
                    x = nx;
                    y = ny;
                    c = nc;
                    continue;
                }
                consec = 0;
            } else {
                consec = 0;
            }
            x = nx;
            y = ny;
            c = nc;
            last = Some(i);
            if k >= 0 {
                let (px, py, pc) = self.finalise(x, y, c, rng);
                plot(px, py, pc, xf.vis);
            }
            k += 1;
        }
        bad
    }
}

impl Chaos {
    /// Like [`Chaos::run_sub_batch`] with `N` independent orbits advanced in turn, so that
    /// the processor overlaps their dependency chains (sqrt, division, trigonometry).
    /// Every orbit starts at its own random point and is fused; samples are counted over all
    /// orbits. Returns the number of bad values.
    #[inline(always)]
    pub fn run_interleaved<const N: usize, F: FnMut(f64, f64, f64, f64)>(
        &self,
        n: u64,
        rng: &mut FastRng,
        mut plot: F,
    ) -> u64 {
        let mut x = [0.0; N];
        let mut y = [0.0; N];
        let mut c = [0.0; N];
        for o in 0..N {
            x[o] = rng.f11();
            y[o] = rng.f11();
            c[o] = rng.f01();
        }
        let mut k = [-FUSE; N];
        let mut consec = [0u32; N];
        let mut last: [Option<usize>; N] = [None; N];
        let mut bad = 0u64;
        let mut plotted = 0u64;
        while plotted < n {
            for o in 0..N {
                let i = self.choose(last[o], rng);
                let xf = &self.xforms[i];
                let (nx, ny, nc, is_bad) = xf.apply(x[o], y[o], c[o], rng);
                x[o] = nx;
                y[o] = ny;
                c[o] = nc;
                if is_bad {
                    consec[o] += 1;
                    bad += 1;
                    if consec[o] < 5 {
                        continue;
                    }
                }
                consec[o] = 0;
                last[o] = Some(i);
                if k[o] >= 0 && plotted < n {
                    let (px, py, pc) = self.finalise(nx, ny, nc, rng);
                    plot(px, py, pc, xf.vis);
                    plotted += 1;
                }
                k[o] += 1;
            }
        }
        bad
    }
}

impl Chaos {
    /// Run one sub-batch of `n` plotted samples with [`LANES`] independent orbits iterated
    /// together: at every step each orbit draws its xform, and each xform is applied to all the
    /// orbits that drew it in one tight loop. The statistics are those of
    /// [`Chaos::run_sub_batch`] (every orbit starts at a random point, is fused for 15 steps,
    /// retries bad values up to 4 times); the work is several times faster because the
    /// variation dispatch and its branches are per group instead of per point.
    /// Returns the number of bad values.
    pub fn run_lanes<F: FnMut(f64, f64, f64, f64)>(
        &self,
        n: u64,
        rng: &mut FastRng,
        sc: &mut Scratch,
        mut plot: F,
    ) -> u64 {
        let nx = self.xforms.len();
        let mut lanes = Lanes::default();
        let mut last = [u16::MAX; LANES];
        let mut consec = [0u8; LANES];
        let mut step = [-FUSE; LANES];
        for l in 0..LANES {
            lanes.x[l] = rng.f11();
            lanes.y[l] = rng.f11();
            lanes.c[l] = rng.f01();
        }
        let mut choice = [0u16; LANES];
        let mut counts = vec![0usize; nx + 1];
        let mut order = [0u16; LANES];
        let mut plotted = 0u64;
        let mut bad = 0u64;
        let mut fin = Lanes::default();
        let mut fin_vis = [0f64; LANES];
        let mut fin_idx: Vec<u16> = Vec::with_capacity(LANES);
        while plotted < n {
            // Draw every lane's xform and group the lanes by xform (counting sort).
            counts.fill(0);
            for l in 0..LANES {
                let prev = if last[l] == u16::MAX { None } else { Some(last[l] as usize) };
                let i = self.choose(prev, rng);
                choice[l] = i as u16;
                counts[i + 1] += 1;
            }
            for i in 0..nx {
                counts[i + 1] += counts[i];
            }
            {
                let mut pos = counts.clone();
                for l in 0..LANES {
                    let i = choice[l] as usize;
                    order[pos[i]] = l as u16;
                    pos[i] += 1;
                }
            }
            for i in 0..nx {
                let (a, b) = (counts[i], counts[i + 1]);
                if a < b {
                    self.xforms[i].apply_group(&order[a..b], &mut lanes, sc, rng);
                }
            }
            // Bad-value retries, step counting and plotting.
            let mut nf = 0usize;
            for l in 0..LANES {
                if lanes.bad[l] {
                    consec[l] += 1;
                    bad += 1;
                    if consec[l] < 5 {
                        continue;
                    }
                }
                consec[l] = 0;
                last[l] = choice[l];
                if step[l] >= 0 && plotted < n {
                    fin.x[nf] = lanes.x[l];
                    fin.y[nf] = lanes.y[l];
                    fin.c[nf] = lanes.c[l];
                    fin_vis[nf] = self.xforms[choice[l] as usize].vis;
                    nf += 1;
                    plotted += 1;
                }
                step[l] += 1;
            }
            if let Some(f) = &self.final_xform {
                fin_idx.clear();
                for j in 0..nf {
                    if f.opacity >= 1.0 || rng.f01() < f.opacity {
                        fin_idx.push(j as u16);
                    }
                }
                if !fin_idx.is_empty() {
                    let idx = std::mem::take(&mut fin_idx);
                    f.apply_group(&idx, &mut fin, sc, rng);
                    fin_idx = idx;
                }
            }
            for j in 0..nf {
                plot(fin.x[j], fin.y[j], fin.c[j], fin_vis[j]);
            }
        }
        bad
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn selection_table_matches_weights() {
        let t = selection_table(&[1.0, 3.0]);
        let ones = t.iter().filter(|&&v| v == 1).count();
        assert_eq!(ones, 16384 * 3 / 4);
        assert_eq!(t[0], 0);
        assert_eq!(t[16383], 1);
        // A tiny weight may get no entry (flam3 quantisation); never out of range.
        let t = selection_table(&[1.0, 1e-9, 1.0]);
        assert!(t.iter().all(|&v| v < 3));
    }

    #[test]
    fn opacity_adjustment_oracles() {
        assert!((adjust_opacity(0.5) - 0.1).abs() < 1e-12);
        assert!((adjust_opacity(0.25) - 0.01).abs() < 1e-12);
        assert_eq!(adjust_opacity(1.0), 1.0);
        assert_eq!(adjust_opacity(0.0), 0.0);
    }

    #[test]
    fn empty_and_bad_flames_are_rejected() {
        let mut f = Flame::default();
        assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::NoXforms);
        f.xforms.push(Xform::linear(Affine::IDENTITY, 0.0, 0.0));
        assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::ZeroWeights);
        f.xforms[0].weight = -1.0;
        assert!(matches!(Chaos::new(&f), Err(ChaosError::BadWeight(0, _))));
        f.xforms[0].weight = 1.0;
        f.xforms[0].chaos = vec![0.0];
        assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::XaosRowZero(0));
    }

    #[test]
    fn sierpinski_points_stay_on_the_attractor() {
        let mut f = Flame::default();
        for (e, ff) in [(0.0, 0.0), (0.5, 0.0), (0.25, 0.5)] {
            f.xforms
                .push(Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, e, ff), 1.0, 0.0));
        }
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(5);
        let mut count = 0;
        let bad = ch.run_sub_batch(10_000, &mut rng, |x, y, _, vis| {
            assert!((-1e-6..=1.0 + 1e-6).contains(&x) && (-1e-6..=1.0 + 1e-6).contains(&y));
            assert_eq!(vis, 1.0);
            count += 1;
        });
        assert_eq!(count, 10_000);
        assert_eq!(bad, 0);
    }

    #[test]
    fn lanes_match_the_scalar_statistics() {
        // A flame with a non-trivial variation mix: the mean and spread of the plotted points
        // and colours agree between the scalar and the lane runner.
        let mut f = Flame::default();
        let mut a = Xform::linear(Affine::new(0.6, -0.3, 0.4, 0.5, 0.2, -0.1), 1.0, 0.0);
        a.vars = vec![
            crate::flame::model::Var::new(variations::SWIRL, 0.6),
            crate::flame::model::Var::new(variations::POLAR, 0.4),
        ];
        let mut b = Xform::linear(Affine::new(-0.5, 0.2, 0.1, 0.7, -0.3, 0.4), 2.0, 1.0);
        b.vars = vec![crate::flame::model::Var::new(variations::SPHERICAL, 0.8)];
        b.post = Affine::new(0.9, 0.0, 0.0, 0.9, 0.1, 0.0);
        f.xforms = vec![a, b];
        let mut fx = Xform::linear(Affine::new(1.0, 0.1, 0.0, 1.0, 0.0, 0.0), 0.0, 0.5);
        fx.vars = vec![crate::flame::model::Var::new(variations::SINUSOIDAL, 1.0)];
        fx.opacity = 0.7;
        f.final_xform = Some(fx);
        let ch = Chaos::new(&f).unwrap();
        let stats = |lanes: bool| {
            let mut rng = FastRng::new(11);
            let mut sc = Scratch::new();
            let (mut n, mut sx, mut sy, mut sc2, mut sxx) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for _ in 0..40 {
                let mut plot = |x: f64, y: f64, c: f64, _v: f64| {
                    n += 1.0;
                    sx += x;
                    sy += y;
                    sc2 += c;
                    sxx += x * x;
                };
                if lanes {
                    ch.run_lanes(10_000, &mut rng, &mut sc, &mut plot);
                } else {
                    ch.run_sub_batch(10_000, &mut rng, &mut plot);
                }
            }
            (n, sx / n, sy / n, sc2 / n, sxx / n)
        };
        let a = stats(false);
        let b = stats(true);
        assert_eq!(a.0, 400_000.0);
        assert_eq!(b.0, 400_000.0);
        for (p, q) in [(a.1, b.1), (a.2, b.2), (a.3, b.3), (a.4, b.4)] {
            assert!((p - q).abs() < 0.01, "{a:?} vs {b:?}");
        }
    }

    #[test]
    fn xaos_restricts_transitions() {
        // Xform 0 may only go to 1, 1 only to 0: colours alternate exactly.
        let mut f = Flame::default();
        let mut a = Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0), 1.0, 0.0);
        a.color_speed = 1.0;
        a.chaos = vec![0.0, 1.0];
        let mut b = Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 0.5, 0.0), 1.0, 1.0);
        b.color_speed = 1.0;
        b.chaos = vec![1.0, 0.0];
        f.xforms = vec![a, b];
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(9);
        let mut prev: Option<f64> = None;
        ch.run_sub_batch(1000, &mut rng, |_, _, c, _| {
            if let Some(p) = prev {
                assert_ne!(p, c);
            }
            prev = Some(c);
        });
    }

    #[test]
    fn bad_values_are_retried() {
        // A map that expands by 10⁶ escapes past 1e10 within two steps: the point is
        // replaced by a random point and nothing non-finite or huge is ever plotted.
        let mut f = Flame::default();
        f.xforms = vec![Xform::linear(Affine::new(1e6, 0.0, 0.0, 1e6, 0.0, 0.0), 1.0, 0.0)];
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(1);
        let bad = ch.run_sub_batch(100, &mut rng, |x, y, _, _| {
            assert!(x.abs() <= BAD_LIMIT && y.abs() <= BAD_LIMIT);
        });
        assert!(bad > 0);
    }
}
