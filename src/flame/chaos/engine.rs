//! The lane runner, the renderer's hot loop: [`LANES`] orbits advanced together. At every
//! step each orbit draws its xform; an affine IFS past its fuse then steps every orbit in place
//! by its drawn row, any other flame groups the orbits by xform (a counting sort) and applies
//! each xform to its group as one array computation. Then bad values are retried, fused orbits
//! counted, and the samples go through the final xform and the camera to the plot callback.

use super::lanes::{Lanes, Orbits, WAITING};
use super::xform::within;
use super::{
    AffineStep, CHOOSE_GRAIN, Chaos, CompiledXform, JWF_CHECK_STEPS, JWF_RESTART_FUSE, LANES, Pt,
};
use crate::flame::rng::FastRng;

/// Mask of a lane index: indices masked by it are provably in range.
const M: usize = LANES - 1;
/// Mask of a 14-bit table index: four 16-bit draws per random word, 14 bits used (flam3's
/// table grain).
const G: usize = CHOOSE_GRAIN - 1;

/// The two sets of orbits as (`sets[first]`, the other one).
#[inline(always)]
fn split_sets(sets: &mut [Orbits; 2], first: usize) -> (&mut Orbits, &mut Orbits) {
    let [s0, s1] = sets;
    if first & 1 == 0 { (s0, s1) } else { (s1, s0) }
}

impl Chaos {
    /// Iterate until `n` more samples are plotted, with [`LANES`] orbits advanced together:
    /// at every step each orbit draws its xform, and each xform is applied to all the orbits
    /// that drew it as one array computation. The orbits persist between calls (a worker keeps
    /// one [`Lanes`] for its whole render): every orbit starts at a random point, is fused for
    /// 15 steps (see [`Chaos::fuse`]) and retries bad values up to 4 times, as in [`Chaos::run_sub_batch`]; one
    /// orbit, chosen at random, restarts (fused) at every call, so that orbits live about as
    /// long as flam3's (one per sub-batch of 10 000 samples).
    ///
    /// `plot(xs, ys, zs, cs, vis, rgb)` receives the points of a step (final xform and camera
    /// applied) with their visibilities and, for a flame whose points carry own colours
    /// ([`Chaos::rgb`]; otherwise empty), those colours; an entry with a negative visibility
    /// is not a sample (an orbit still in its fuse or retrying a bad value, or beyond the `n`
    /// asked for) and must be skipped. Returns the number of bad values.
    #[inline(always)]
    pub(crate) fn run_lanes<F: FnMut(&[f64], &[f64], &[f64], &[f64], &[f64], &[u32])>(
        &self,
        n: u64,
        rng: &mut FastRng,
        ln: &mut Lanes,
        mut plot: F,
    ) -> u64 {
        self.run_lanes_world(n, rng, ln, |xs, ys, zs, cs, vs, rgb, _| {
            plot(xs, ys, zs, cs, vs, rgb)
        })
    }

    /// [`Chaos::run_lanes`], the plot also given the samples' x, y and z before the camera
    /// when the flame is drawn solid ([`Chaos::solid`]; empty otherwise). The z of a solid
    /// flame's samples is then their depth seen by the camera.
    #[inline(always)]
    pub(crate) fn run_lanes_world<
        F: FnMut(&[f64], &[f64], &[f64], &[f64], &[f64], &[u32], [&[f64]; 3]),
    >(
        &self,
        n: u64,
        rng: &mut FastRng,
        ln: &mut Lanes,
        mut plot: F,
    ) -> u64 {
        let nx = self.xforms.len();
        self.start_orbits(ln, rng);
        ln.counts.resize(4 * (nx + 1), 0);
        ln.bounds.resize(nx + 1, 0);
        let mut plotted = 0u64;
        let mut bad = 0u64;
        let direct = self.final_xform.is_none() && self.projection.is_none();
        while plotted < n {
            if self.jwf_bad_values {
                if ln.steps.is_multiple_of(JWF_CHECK_STEPS) {
                    self.restart_waiting(ln, rng);
                }
                ln.steps += 1;
            }
            match (&self.affine, ln.clean) {
                (Some(rows), true) => self.step_in_place(rows, ln, rng),
                _ => self.step_grouped(ln, rng),
            }
            // The common step: no bad value, every orbit a sample.
            if ln.clean && direct && !ln.bad.iter().any(|&b| b) && plotted + LANES as u64 <= n {
                self.all_samples(ln);
                plotted += LANES as u64;
                let o = &ln.sets[ln.cur & 1];
                let rgb: &[u32] = if self.rgb { &o.rgb } else { &[] };
                let world: [&[f64]; 3] = if self.solid {
                    [&o.x, &o.y, &o.z]
                } else {
                    [&[], &[], &[]]
                };
                plot(&o.x, &o.y, &o.z, &o.c, &ln.vis, rgb, world);
                continue;
            }
            let (nf, took, bad_values) = self.samples_of_step(ln, n - plotted, direct);
            plotted += took;
            bad += bad_values;
            if direct {
                let o = &ln.sets[ln.cur & 1];
                let rgb: &[u32] = if self.rgb { &o.rgb } else { &[] };
                let world: [&[f64]; 3] = if self.solid {
                    [&o.x, &o.y, &o.z]
                } else {
                    [&[], &[], &[]]
                };
                plot(&o.x, &o.y, &o.z, &o.c, &ln.vis, rgb, world);
                continue;
            }
            let m = nf.min(LANES);
            self.finish_samples(ln, m, rng);
            let fin = &ln.fin;
            let rgb: &[u32] = if self.rgb { &fin.rgb[..m] } else { &[] };
            let w = &ln.world;
            let world: [&[f64]; 3] = if self.solid {
                [&w.x[..m], &w.y[..m], &w.z[..m]]
            } else {
                [&[], &[], &[]]
            };
            plot(
                &fin.x[..m],
                &fin.y[..m],
                &fin.z[..m],
                &fin.c[..m],
                &ln.fin_vis[..m],
                rgb,
                world,
            );
        }
        bad
    }

    /// Start every orbit at a random point on the first call, fused
    /// [`Chaos::first_fuse`] steps; at every call restart one orbit, chosen at random,
    /// fused as flam3 fuses (not for a flame JWildfire's renderer draws, whose orbits live for
    /// the whole render).
    #[inline(always)]
    fn start_orbits(&self, ln: &mut Lanes, rng: &mut FastRng) {
        if !ln.started {
            let fuse = -(self.first_fuse() as i32);
            let o = &mut ln.sets[ln.cur & 1];
            for l in 0..LANES {
                let p = Self::start_point(rng);
                (o.x[l], o.y[l], o.z[l], o.c[l]) = (p.x, p.y, p.z, p.c);
                o.rgb[l] = 0;
                o.hid[l] = false;
                o.step[l] = fuse;
            }
            ln.started = true;
        }
        if !self.jwf_bad_values {
            // flam3 starts a new orbit for every sub-batch of 10 000 samples; a flame that
            // converges slowly (one contracting xform, say) shows the path towards its
            // attractor from each start. Restart one orbit per call, chosen at random: every
            // orbit then lives for ~LANES calls, about 10 000 of its own samples, the same
            // share of fresh starts.
            let l = rng.u32() as usize % LANES;
            let (p, last, hid) = self.fused_start(rng);
            let o = &mut ln.sets[ln.cur & 1];
            (o.x[l], o.y[l], o.z[l], o.c[l]) = (p.x, p.y, p.z, p.c);
            (o.last[l], o.consec[l], o.step[l]) = (last as u16, 0, 0);
            o.rgb[l] = 0;
            o.hid[l] = hid;
        }
    }

    /// JWildfire's check for bad values: every orbit whose point is bad starts again at a
    /// random point, fused as JWildfire fuses (see [`Chaos::jwf_restart`]).
    fn restart_waiting(&self, ln: &mut Lanes, rng: &mut FastRng) {
        let o = &mut ln.sets[ln.cur & 1];
        for l in 0..LANES {
            if o.consec[l] == WAITING {
                let (p, last, hid, bad) = self.jwf_restart(rng);
                (o.x[l], o.y[l], o.z[l], o.c[l]) = (p.x, p.y, p.z, p.c);
                let consec = if bad { WAITING } else { 0 };
                (o.last[l], o.consec[l], o.step[l]) = (last as u16, consec, 0);
                o.rgb[l] = 0;
                o.hid[l] = hid;
            }
        }
    }

    /// A restarted orbit of a flame JWildfire's renderer draws, as JWildfire 9.00 starts one
    /// (`DefaultRenderIterationState.preFuseIter`): a random point, transformed by the first
    /// xform, then by [`JWF_RESTART_FUSE`] xforms drawn in turn, bad values kept. Returns
    /// the point, the xform applied last, whether the point is hidden and whether it is bad
    /// (then it waits for the next check).
    fn jwf_restart(&self, rng: &mut FastRng) -> (Pt, usize, bool, bool) {
        let mut p = Self::start_point(rng);
        let (mut i, mut hidden, mut bad) = (0usize, false, false);
        for k in 0..=JWF_RESTART_FUSE {
            if k > 0 {
                i = self.choose(Some(i), rng);
            }
            let Some(x) = self.xforms.get(i) else { break };
            let (q, b, here) = x.apply_keeping(p, rng);
            p = q;
            bad = b;
            hidden = self.carry_hide && x.hidden_after(here, hidden);
        }
        (p, i, hidden, bad)
    }

    /// One step of an affine IFS past the fuse: every orbit steps in place by its drawn row
    /// into the other set, which becomes the current one.
    #[inline(always)]
    fn step_in_place(&self, rows: &[AffineStep], ln: &mut Lanes, rng: &mut FastRng) {
        let (src, dst) = split_sets(&mut ln.sets, ln.cur);
        let table = &self.tables[..CHOOSE_GRAIN];
        for q in 0..LANES / 4 {
            let mut u = rng.u64();
            for r in 0..4 {
                ln.choice[4 * q + r] = table[u as usize & G];
                u >>= 16;
            }
        }
        let mut any_bad = false;
        for l in 0..LANES {
            let i = ln.choice[l];
            let t = &rows[i as usize];
            let (x, y) = (src.x[l], src.y[l]);
            let (tx, ty) = (t.a * x + t.b * y + t.e, t.c * x + t.d * y + t.f);
            let (x, y) = (0.0 + t.w * tx, 0.0 + t.w * ty);
            let z = 0.0 + t.w * src.z[l];
            dst.x[l] = x;
            dst.y[l] = y;
            dst.z[l] = z;
            dst.c[l] = t.sc + t.keep * src.c[l];
            let b = !within(x, t.bad_limit)
                | !within(y, t.bad_limit)
                | (self.jwf_bad_values & !z.is_finite());
            ln.bad[l] = b;
            any_bad |= b;
            ln.group[l] = i;
        }
        // Under JWildfire's rule a bad point stays as it is (`CompiledXform::keeps_bad`).
        if any_bad && !self.jwf_bad_values {
            for l in 0..LANES {
                if ln.bad[l] {
                    dst.x[l] = rng.f11();
                    dst.y[l] = rng.f11();
                    dst.z[l] = 0.0;
                }
            }
        }
        ln.cur ^= 1;
    }

    /// One step of any other flame: draw each orbit's xform, gather the orbits into the other
    /// set grouped by xform (which becomes the current one), and apply each xform to its group.
    #[inline(always)]
    fn step_grouped(&self, ln: &mut Lanes, rng: &mut FastRng) {
        self.draw_xforms(ln, rng);
        self.order_by_xform(ln);
        self.gather(ln);
        self.apply_groups(ln, rng);
    }

    /// Draw every orbit's xform into `ln.choice` (from its xaos row, if any) and count the
    /// draws of each xform in `ln.counts`. Four interleaved streams of counters and positions
    /// avoid store-to-load chains on a single counter.
    #[inline(always)]
    fn draw_xforms(&self, ln: &mut Lanes, rng: &mut FastRng) {
        let w = self.xforms.len() + 1;
        ln.counts.fill(0);
        if self.xaos {
            let src = &ln.sets[ln.cur & 1];
            for q in 0..LANES / 4 {
                let mut u = rng.u64();
                for r in 0..4 {
                    let l = 4 * q + r;
                    let prev = src.last[l];
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
    }

    /// A counting sort of the orbits by drawn xform: `ln.bounds[i]` is where group i starts,
    /// `ln.order` lists the orbits group by group.
    #[inline(always)]
    fn order_by_xform(&self, ln: &mut Lanes) {
        let nx = self.xforms.len();
        let w = nx + 1;
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
    }

    /// Gather the orbits into the other set in group order; it becomes the current one.
    #[inline(always)]
    fn gather(&self, ln: &mut Lanes) {
        let (src, dst) = split_sets(&mut ln.sets, ln.cur);
        for (p, &l) in ln.order.iter().enumerate() {
            let l = l as usize & M;
            dst.x[p] = src.x[l];
            dst.y[p] = src.y[l];
            dst.z[p] = src.z[l];
            dst.c[p] = src.c[l];
        }
        if self.xaos {
            for (p, &l) in ln.order.iter().enumerate() {
                dst.last[p] = src.last[l as usize & M];
            }
        }
        if self.rgb {
            for (p, &l) in ln.order.iter().enumerate() {
                dst.rgb[p] = src.rgb[l as usize & M];
            }
        }
        if self.carry_hide {
            for (p, &l) in ln.order.iter().enumerate() {
                dst.hid[p] = src.hid[l as usize & M];
            }
        }
        if !ln.clean {
            for (p, &l) in ln.order.iter().enumerate() {
                let l = l as usize & M;
                dst.consec[p] = src.consec[l];
                dst.step[p] = src.step[l];
                dst.last[p] = src.last[l];
            }
        }
        ln.cur ^= 1;
    }

    /// Apply each xform to its group of the current set, noting bad values, hidden points and
    /// the xform of each place.
    #[inline(always)]
    fn apply_groups(&self, ln: &mut Lanes, rng: &mut FastRng) {
        let dst = &mut ln.sets[ln.cur & 1];
        for i in 0..self.xforms.len() {
            let (start, end) = (ln.bounds[i].min(LANES), ln.bounds[i + 1].min(LANES));
            if end > start {
                let r = start..end;
                let rgb = self.rgb.then(|| &mut dst.rgb[r.clone()]);
                self.xforms[i].apply_soa(
                    &mut dst.x[r.clone()],
                    &mut dst.y[r.clone()],
                    &mut dst.z[r.clone()],
                    &mut dst.c[r.clone()],
                    rgb,
                    &mut ln.g,
                    rng,
                );
                ln.bad[r.clone()].copy_from_slice(&ln.g.bad[..end - start]);
                if self.carry_hide {
                    // JWildfire's rule: the flag travels with the point.
                    let x = &self.xforms[i];
                    let here = &ln.g.hide[..end - start];
                    for ((h, c), &hh) in ln.hide[r.clone()]
                        .iter_mut()
                        .zip(&mut dst.hid[r.clone()])
                        .zip(here)
                    {
                        *h = x.hidden_after(x.hides && hh, *c);
                        *c = *h;
                    }
                } else if self.hides {
                    if self.xforms[i].hides {
                        ln.hide[r.clone()].copy_from_slice(&ln.g.hide[..end - start]);
                    } else {
                        ln.hide[r.clone()].fill(false);
                    }
                }
                ln.group[r].fill(i as u16);
            }
        }
    }

    /// A step where every orbit is a sample: note the xforms applied and the visibilities.
    #[inline(always)]
    fn all_samples(&self, ln: &mut Lanes) {
        ln.sets[ln.cur & 1].last = ln.group;
        match self.same_vis {
            Some(v) => ln.vis = [v; LANES],
            None => {
                for (v, &g) in ln.vis.iter_mut().zip(&ln.group) {
                    *v = self.vis.get(g as usize).copied().unwrap_or(0.0);
                }
            }
        }
        if self.hides {
            // A hidden sample counts, and adds nothing.
            for (v, &h) in ln.vis.iter_mut().zip(&ln.hide) {
                if h {
                    *v = 0.0;
                }
            }
        }
    }

    /// Bad-value retries, step counting, and which points of the step are samples (at most
    /// `left`). With `direct` the samples get their visibility in `ln.vis` (−1: not a sample);
    /// otherwise they are copied to `ln.fin` for the final xform and the camera. Returns how
    /// many were copied, how many samples the step gave and how many bad values it met.
    #[inline(always)]
    fn samples_of_step(&self, ln: &mut Lanes, left: u64, direct: bool) -> (usize, u64, u64) {
        let (dst, src) = split_sets(&mut ln.sets, ln.cur);
        let (mut nf, mut took, mut bad) = (0usize, 0u64, 0u64);
        for p in 0..LANES {
            ln.vis[p] = -1.0;
            if self.jwf_bad_values && ln.bad[p] {
                // JWildfire's rule: a bad point's step counts and draws nothing; the orbit
                // goes on from it (an xform that ignores its input brings it back) and the
                // next check restarts it if it is still bad.
                if dst.consec[p] != WAITING {
                    dst.consec[p] = WAITING;
                    bad += 1;
                }
                if dst.step[p] >= 0 && took < left {
                    took += 1;
                }
                continue;
            }
            if ln.bad[p] {
                dst.consec[p] += 1;
                bad += 1;
                if dst.consec[p] < 5 {
                    continue;
                }
            }
            dst.consec[p] = 0;
            let ch = ln.group[p];
            dst.last[p] = ch;
            if dst.step[p] >= 0 {
                if took < left {
                    // Under JWildfire's rule the final xforms may show a hidden point again:
                    // its visibility waits for them (`fin_hide`).
                    let v = if self.hides && ln.hide[p] && (direct || !self.carry_hide) {
                        0.0
                    } else {
                        self.xforms[ch as usize].vis
                    };
                    took += 1;
                    if direct {
                        ln.vis[p] = v;
                    } else {
                        let k = nf & M;
                        ln.fin.x[k] = dst.x[p];
                        ln.fin.y[k] = dst.y[p];
                        ln.fin.z[k] = dst.z[p];
                        ln.fin.c[k] = dst.c[p];
                        ln.fin.rgb[k] = dst.rgb[p];
                        ln.fin_vis[k] = v;
                        ln.fin_hide[k] = self.carry_hide && ln.hide[p];
                        nf += 1;
                    }
                }
            } else {
                dst.step[p] += 1;
            }
        }
        if !ln.clean && dst.consec.iter().all(|&c| c == 0) && dst.step.iter().all(|&s| s >= 0) {
            // From now on the counters are not gathered: both sets must read as clean.
            ln.clean = true;
            src.consec = [0; LANES];
            src.step = [0; LANES];
        } else if ln.clean && dst.consec.iter().any(|&c| c != 0) {
            ln.clean = false;
        }
        (nf, took, bad)
    }

    /// The first `m` samples of `ln.fin` through the final xforms in order (hidden ones get
    /// visibility 0) and the camera.
    #[inline(always)]
    fn finish_samples(&self, ln: &mut Lanes, m: usize, rng: &mut FastRng) {
        for f in self.final_xform.iter().chain(&self.more_finals) {
            if f.opacity >= 1.0 {
                let fin = &mut ln.fin;
                let rgb = self.rgb.then(|| &mut fin.rgb[..m]);
                f.apply_soa(
                    &mut fin.x[..m],
                    &mut fin.y[..m],
                    &mut fin.z[..m],
                    &mut fin.c[..m],
                    rgb,
                    &mut ln.g,
                    rng,
                );
                if self.carry_hide {
                    for (c, &h) in ln.fin_hide[..m].iter_mut().zip(&ln.g.hide[..m]) {
                        *c = f.hidden_after(f.hides && h, *c);
                    }
                } else if f.hides {
                    for (v, &h) in ln.fin_vis[..m].iter_mut().zip(&ln.g.hide[..m]) {
                        if h {
                            *v = 0.0;
                        }
                    }
                }
                if self.jwf_bad_values {
                    // JWildfire draws nothing of a sample its final xform makes bad.
                    for (v, &b) in ln.fin_vis[..m].iter_mut().zip(&ln.g.bad[..m]) {
                        if b {
                            *v = -1.0;
                        }
                    }
                }
            } else {
                let rules = (self.jwf_bad_values, self.carry_hide);
                Self::final_by_opacity(f, ln, m, self.rgb, rules, rng);
            }
        }
        if self.carry_hide {
            // A hidden sample counts, and adds nothing.
            for (v, &h) in ln.fin_vis[..m].iter_mut().zip(&ln.fin_hide[..m]) {
                if h && *v > 0.0 {
                    *v = 0.0;
                }
            }
        }
        if self.solid {
            let (fin, w) = (&ln.fin, &mut ln.world);
            w.x[..m].copy_from_slice(&fin.x[..m]);
            w.y[..m].copy_from_slice(&fin.y[..m]);
            w.z[..m].copy_from_slice(&fin.z[..m]);
        }
        if let Some(pr) = &self.projection {
            let fin = &mut ln.fin;
            for j in 0..m {
                (fin.x[j], fin.y[j]) = pr.project(fin.x[j], fin.y[j], fin.z[j], rng);
            }
            if self.solid {
                let w = &ln.world;
                for j in 0..m {
                    fin.z[j] = pr.depth(w.x[j], w.y[j], w.z[j]);
                }
            }
        }
    }

    /// The final xform `f` applied to each of the first `m` samples of `ln.fin` with
    /// probability = its opacity: the chosen points are compacted, transformed and put back.
    /// `(drop_bad, carry_hide)`: JWildfire's rules for bad values and hidden points.
    #[inline(always)]
    fn final_by_opacity(
        f: &CompiledXform,
        ln: &mut Lanes,
        m: usize,
        own_rgb: bool,
        (drop_bad, carry_hide): (bool, bool),
        rng: &mut FastRng,
    ) {
        ln.chosen.clear();
        for j in 0..m {
            if rng.f01() < f.opacity {
                ln.chosen.push(j);
            }
        }
        let (fin, t) = (&mut ln.fin, &mut ln.tmp);
        for (k, &j) in ln.chosen.iter().enumerate() {
            let (k, j) = (k & M, j & M);
            t.x[k] = fin.x[j];
            t.y[k] = fin.y[j];
            t.z[k] = fin.z[j];
            t.c[k] = fin.c[j];
            t.rgb[k] = fin.rgb[j];
        }
        let k = ln.chosen.len().min(LANES);
        f.apply_soa(
            &mut t.x[..k],
            &mut t.y[..k],
            &mut t.z[..k],
            &mut t.c[..k],
            own_rgb.then(|| &mut t.rgb[..k]),
            &mut ln.g,
            rng,
        );
        for (k, &j) in ln.chosen.iter().enumerate() {
            if carry_hide {
                let c = &mut ln.fin_hide[j & M];
                *c = f.hidden_after(f.hides && ln.g.hide[k & M], *c);
            } else if f.hides && ln.g.hide[k & M] {
                ln.fin_vis[j & M] = 0.0;
            }
            if drop_bad && ln.g.bad[k & M] {
                ln.fin_vis[j & M] = -1.0;
            }
        }
        for (k, &j) in ln.chosen.iter().enumerate() {
            let (k, j) = (k & M, j & M);
            fin.x[j] = t.x[k];
            fin.y[j] = t.y[k];
            fin.z[j] = t.z[k];
            fin.c[j] = t.c[k];
            fin.rgb[j] = t.rgb[k];
        }
    }
}

#[cfg(test)]
#[path = "engine_tests.rs"]
mod tests;
