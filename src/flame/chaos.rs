//! The chaos game (flame.md §3): a flame compiled for fast iteration.

use crate::flame::fastmath;
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

/// |v| ≤ 1e10; false for NaN (which fails every comparison).
#[inline(always)]
fn within_limit(v: f64) -> bool {
    v.abs() <= BAD_LIMIT
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
        let mut needs = Needs::default();
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
        if !(within_limit(px) && within_limit(py)) {
            return (rng.f11(), rng.f11(), nc, true);
        }
        (px, py, nc, false)
    }
}

/// Number of independent orbits iterated together by [`Chaos::run_lanes`].
pub const LANES: usize = 256;

/// The orbits of the lane runner. They live for the whole render of one worker thread (see
/// [`Chaos::run_lanes`]). Fixed-size arrays: every index is provably in range.
#[derive(Clone, Debug)]
pub struct Lanes {
    x: [f64; LANES],
    y: [f64; LANES],
    c: [f64; LANES],
    /// Xform applied last (xaos row), `u16::MAX` before the first.
    last: [u16; LANES],
    consec: [u8; LANES],
    /// Steps done; an orbit plots once this is ≥ 0 (it starts at −FUSE).
    step: [i32; LANES],
    started: bool,
    // Scratch space.
    choice: [u16; LANES],
    order: [u16; LANES],
    counts: Vec<usize>,
    bounds: Vec<usize>,
    bad: [bool; LANES],
    g: Group,
    fin: Group,
    fin_vis: [f64; LANES],
    chosen: Vec<usize>,
}

/// Structure-of-arrays buffers for one group of points under one xform.
#[derive(Clone, Debug)]
struct Group {
    x: [f64; LANES],
    y: [f64; LANES],
    c: [f64; LANES],
    sumsq: [f64; LANES],
    sqrt: [f64; LANES],
    atan: [f64; LANES],
    atanyx: [f64; LANES],
    sina: [f64; LANES],
    cosa: [f64; LANES],
    px: [f64; LANES],
    py: [f64; LANES],
    bad: [bool; LANES],
}

impl Group {
    fn new() -> Group {
        Group {
            x: [0.0; LANES],
            y: [0.0; LANES],
            c: [0.0; LANES],
            sumsq: [0.0; LANES],
            sqrt: [0.0; LANES],
            atan: [0.0; LANES],
            atanyx: [0.0; LANES],
            sina: [0.0; LANES],
            cosa: [0.0; LANES],
            px: [0.0; LANES],
            py: [0.0; LANES],
            bad: [false; LANES],
        }
    }
}

impl Lanes {
    pub fn new() -> Box<Lanes> {
        Box::new(Lanes {
            x: [0.0; LANES],
            y: [0.0; LANES],
            c: [0.0; LANES],
            last: [u16::MAX; LANES],
            consec: [0; LANES],
            step: [-(FUSE as i32); LANES],
            started: false,
            choice: [0; LANES],
            order: [0; LANES],
            counts: Vec::new(),
            bounds: Vec::new(),
            bad: [false; LANES],
            g: Group::new(),
            fin: Group::new(),
            fin_vis: [0.0; LANES],
            chosen: Vec::with_capacity(LANES),
        })
    }
}

impl CompiledXform {
    /// Apply to the first `n` points of `g` (x, y, c in place; bad flags set; a bad point is
    /// replaced by a random point of [−1, 1]²). The pre-affine points and their derived
    /// quantities are computed as arrays, then every variation runs over the whole group.
    #[inline(always)]
    fn apply_soa(&self, g: &mut Group, n: usize, rng: &mut FastRng) {
        let n = n.min(LANES);
        let a = self.coefs;
        {
            let (x, y) = (&mut g.x[..n], &mut g.y[..n]);
            for j in 0..n {
                let (tx, ty) = a.apply(x[j], y[j]);
                x[j] = tx;
                y[j] = ty;
            }
            if self.pre_blur != 0.0 {
                for j in 0..n {
                    (x[j], y[j]) = variations::pre_blur(self.pre_blur, x[j], y[j], rng);
                }
            }
        }
        let (x, y) = (&g.x[..n], &g.y[..n]);
        let (sumsq, sqrt) = (&mut g.sumsq[..n], &mut g.sqrt[..n]);
        // r² and r for the variations that read them (sin/cos of the angle divide by r).
        if self.needs.sqrt || self.needs.sincos_a {
            for j in 0..n {
                sumsq[j] = x[j] * x[j] + y[j] * y[j];
                sqrt[j] = sumsq[j].sqrt();
            }
        }
        if self.needs.atan {
            let at = &mut g.atan[..n];
            for j in 0..n {
                at[j] = fastmath::atan2(x[j], y[j]);
            }
        }
        if self.needs.atanyx {
            let at = &mut g.atanyx[..n];
            for j in 0..n {
                at[j] = fastmath::atan2(y[j], x[j]);
            }
        }
        if self.needs.sincos_a {
            let (sa, ca) = (&mut g.sina[..n], &mut g.cosa[..n]);
            for j in 0..n {
                sa[j] = x[j] / sqrt[j];
                ca[j] = y[j] / sqrt[j];
            }
        }
        let soa = variations::Soa {
            x,
            y,
            sumsq,
            sqrt,
            atan: &g.atan,
            atanyx: &g.atanyx,
            sina: &g.sina,
            cosa: &g.cosa,
        };
        let (px, py) = (&mut g.px[..n], &mut g.py[..n]);
        px.fill(0.0);
        py.fill(0.0);
        for v in &self.vars {
            (v.batch)(v, &soa, &a, rng, px, py);
        }
        if let Some(post) = &self.post {
            for j in 0..n {
                (px[j], py[j]) = post.apply(px[j], py[j]);
            }
        }
        let (s, col) = (self.color_speed, self.color);
        let (c, bad) = (&mut g.c[..n], &mut g.bad[..n]);
        let mut any_bad = false;
        for j in 0..n {
            c[j] = s * col + (1.0 - s) * c[j];
            // `!(a <= l)` is also true for NaN.
            let b = !within_limit(px[j]) | !within_limit(py[j]);
            bad[j] = b;
            any_bad |= b;
        }
        let (x, y) = (&mut g.x[..n], &mut g.y[..n]);
        x.copy_from_slice(px);
        y.copy_from_slice(py);
        if any_bad {
            for j in 0..n {
                if bad[j] {
                    x[j] = rng.f11();
                    y[j] = rng.f11();
                }
            }
        }
    }
}

/// A flame compiled for the chaos game.
#[derive(Clone, Debug)]
pub struct Chaos {
    pub xforms: Vec<CompiledXform>,
    pub final_xform: Option<CompiledXform>,
    /// Row 0: plain weights. Rows 1..=n: xaos rows after xform i − 1 (only when xaos is used),
    /// CHOOSE_GRAIN entries each, concatenated.
    tables: Vec<u16>,
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
        let mut tables = selection_table(&weights).into_vec();
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
                tables.extend_from_slice(&selection_table(&row));
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
        self.tables[row * CHOOSE_GRAIN + u] as usize
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
    /// Iterate until `n` more samples are plotted, with [`LANES`] orbits advanced together:
    /// at every step each orbit draws its xform, and each xform is applied to all the orbits
    /// that drew it as one array computation. The orbits persist between calls (a worker keeps
    /// one [`Lanes`] for its whole render): every orbit starts at a random point, is fused for
    /// 15 steps and retries bad values up to 4 times, as in [`Chaos::run_sub_batch`]; only the
    /// orbit restarts every 10 000 samples are replaced by 256 long orbits per worker.
    /// Returns the number of bad values.
    pub fn run_lanes<F: FnMut(&[f64], &[f64], &[f64], &[f64])>(
        &self,
        n: u64,
        rng: &mut FastRng,
        ln: &mut Lanes,
        mut plot: F,
    ) -> u64 {
        let nx = self.xforms.len();
        if !ln.started {
            for l in 0..LANES {
                ln.x[l] = rng.f11();
                ln.y[l] = rng.f11();
                ln.c[l] = rng.f01();
            }
            ln.started = true;
        }
        ln.counts.resize(4 * (nx + 1), 0);
        ln.bounds.resize(nx + 1, 0);
        let mut plotted = 0u64;
        let mut bad = 0u64;
        const M: usize = LANES - 1;
        while plotted < n {
            // Draw every orbit's xform; group the orbits by xform (counting sort).
            // Four interleaved streams of counters and positions avoid store-to-load chains on
            // a single counter.
            let w = nx + 1;
            ln.counts.fill(0);
            // Four 16-bit draws per random word (14 bits are used, as flam3's table grain).
            const G: usize = CHOOSE_GRAIN - 1;
            if self.xaos {
                for q in 0..LANES / 4 {
                    let mut u = rng.u64();
                    for r in 0..4 {
                        let l = 4 * q + r;
                        let prev = ln.last[l];
                        let row = if prev == u16::MAX {
                            0
                        } else {
                            prev as usize + 1
                        };
                        let i = self.tables[row * CHOOSE_GRAIN + (u as usize & G)] as usize;
                        u >>= 16;
                        ln.choice[l] = i as u16;
                        ln.counts[r * w + i] += 1;
                    }
                }
            } else {
                let table = &self.tables[..CHOOSE_GRAIN];
                for q in 0..LANES / 4 {
                    let mut u = rng.u64();
                    for r in 0..4 {
                        let i = table[u as usize & G] as usize;
                        u >>= 16;
                        ln.choice[4 * q + r] = i as u16;
                        ln.counts[r * w + i] += 1;
                    }
                }
            }
            // bounds[i]: start of group i; positions of stream s inside group i follow.
            let mut acc = 0usize;
            for i in 0..nx {
                ln.bounds[i] = acc;
                for st in 0..4 {
                    let c = ln.counts[st * w + i];
                    ln.counts[st * w + i] = acc;
                    acc += c;
                }
            }
            ln.bounds[nx] = acc;
            for l in 0..LANES {
                let k = (l & 3) * w + ln.choice[l] as usize;
                ln.order[ln.counts[k] & M] = l as u16;
                ln.counts[k] += 1;
            }
            for i in 0..nx {
                let (start, end) = (ln.bounds[i], ln.bounds[i + 1]);
                let m = end - start;
                if m > 0 {
                    let idx = &ln.order[start..end];
                    let g = &mut ln.g;
                    for (j, &l) in idx.iter().enumerate() {
                        let (l, j) = (l as usize & M, j & M);
                        g.x[j] = ln.x[l];
                        g.y[j] = ln.y[l];
                        g.c[j] = ln.c[l];
                    }
                    self.xforms[i].apply_soa(g, m, rng);
                    for (j, &l) in idx.iter().enumerate() {
                        let (l, j) = (l as usize & M, j & M);
                        ln.x[l] = g.x[j];
                        ln.y[l] = g.y[j];
                        ln.c[l] = g.c[j];
                        ln.bad[l] = g.bad[j];
                    }
                }
            }
            // Bad-value retries, step counting, and the points to plot.
            let mut nf = 0usize;
            for l in 0..LANES {
                if ln.bad[l] {
                    ln.consec[l] += 1;
                    bad += 1;
                    if ln.consec[l] < 5 {
                        continue;
                    }
                }
                ln.consec[l] = 0;
                let ch = ln.choice[l];
                ln.last[l] = ch;
                if ln.step[l] >= 0 {
                    if plotted < n {
                        let k = nf & M;
                        ln.fin.x[k] = ln.x[l];
                        ln.fin.y[k] = ln.y[l];
                        ln.fin.c[k] = ln.c[l];
                        ln.fin_vis[k] = self.xforms[ch as usize].vis;
                        nf += 1;
                        plotted += 1;
                    }
                } else {
                    ln.step[l] += 1;
                }
            }
            if let Some(f) = &self.final_xform {
                if f.opacity >= 1.0 {
                    f.apply_soa(&mut ln.fin, nf, rng);
                } else {
                    // Apply with probability = opacity: compact the chosen points, apply, put back.
                    ln.chosen.clear();
                    for j in 0..nf {
                        if rng.f01() < f.opacity {
                            ln.chosen.push(j);
                        }
                    }
                    for (k, &j) in ln.chosen.iter().enumerate() {
                        let (k, j) = (k & M, j & M);
                        ln.g.x[k] = ln.fin.x[j];
                        ln.g.y[k] = ln.fin.y[j];
                        ln.g.c[k] = ln.fin.c[j];
                    }
                    f.apply_soa(&mut ln.g, ln.chosen.len(), rng);
                    for (k, &j) in ln.chosen.iter().enumerate() {
                        let (k, j) = (k & M, j & M);
                        ln.fin.x[j] = ln.g.x[k];
                        ln.fin.y[j] = ln.g.y[k];
                        ln.fin.c[j] = ln.g.c[k];
                    }
                }
            }
            let (fin, m) = (&ln.fin, nf.min(LANES));
            plot(&fin.x[..m], &fin.y[..m], &fin.c[..m], &ln.fin_vis[..m]);
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
            f.xforms.push(Xform::linear(
                Affine::new(0.5, 0.0, 0.0, 0.5, e, ff),
                1.0,
                0.0,
            ));
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
            let mut sc = Lanes::new();
            let (mut n, mut sx, mut sy, mut sc2, mut sxx) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for _ in 0..40 {
                // Bounded statistics: the spherical xform gives heavy tails.
                let mut plot = |x: f64, y: f64, c: f64, _v: f64| {
                    n += 1.0;
                    sx += x.clamp(-3.0, 3.0);
                    sy += y.clamp(-3.0, 3.0);
                    sc2 += c;
                    sxx += (x.abs() < 0.5) as u8 as f64;
                };
                if lanes {
                    ch.run_lanes(10_000, &mut rng, &mut sc, |xs, ys, cs, vs| {
                        for j in 0..xs.len() {
                            plot(xs[j], ys[j], cs[j], vs[j]);
                        }
                    });
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
        let f = Flame {
            xforms: vec![Xform::linear(
                Affine::new(1e6, 0.0, 0.0, 1e6, 0.0, 0.0),
                1.0,
                0.0,
            )],
            ..Flame::default()
        };
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(1);
        let bad = ch.run_sub_batch(100, &mut rng, |x, y, _, _| {
            assert!(x.abs() <= BAD_LIMIT && y.abs() <= BAD_LIMIT);
        });
        assert!(bad > 0);
    }
}
