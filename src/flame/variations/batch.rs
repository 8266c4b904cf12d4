//! Evaluating a regular variation on a batch of points: the generic loop calling the formula
//! point by point, and [`inline_batch!`], which builds a loop with the formula inlined (compiled
//! for AVX2 and FMA where the CPU has them) for every Fractorium variation.

use std::mem::MaybeUninit;

use super::def::Prepared;
use super::point::{Acc, SoaAcc, SoaIn, VarIn};
use super::{Draws, V3, flag};
use crate::flame::fastmath::{self, Simd};
use crate::flame::rng::FastRng;

impl Prepared {
    /// Apply a regular use to a batch (specialised version if the variation has one).
    #[inline]
    pub fn apply_batch(&self, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
        match self.def.batch {
            Some(f) => f(self, s, acc, rng),
            None => generic_batch(self, s, acc, rng),
        }
    }
}

/// The generic batch loop: the formula called point by point.
pub fn generic_batch(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
    batch_with(v, s, acc, rng, v.def.eval)
}

/// Points per pass of [`batch_with`].
const PASS: usize = 256;

/// Copies a pass's outputs to the caller's column. The pass arrays are left uninitialised
/// rather than zeroed (8 KiB per call, a few percent of a cheap flame's time, and calls often
/// hold far fewer than [`PASS`] points); every value of `src` is written by the pass's loop
/// before this copy.
#[inline(always)]
fn copy_written(dst: &mut [f64], src: &[MaybeUninit<f64>]) {
    for (d, s) in dst.iter_mut().zip(src) {
        // SAFETY: the pass's loop writes src[j] for every j below its length, `m`, and
        // cannot leave the loop early (a panic unwinds past this copy).
        *d = unsafe { s.assume_init() };
    }
}

/// Copies a pass's outputs and hide flags (points `r` of the call, every one written by the
/// pass's loop) to the caller's columns.
#[inline(always)]
fn write_pass(
    acc: &mut SoaAcc,
    r: std::ops::Range<usize>,
    out: &[[MaybeUninit<f64>; PASS]; 4],
    hides: &[bool; PASS],
) {
    let m = r.len();
    let [ox, oy, oz, oc] = out;
    copy_written(&mut acc.x[r.clone()], &ox[..m]);
    copy_written(&mut acc.y[r.clone()], &oy[..m]);
    copy_written(&mut acc.z[r.clone()], &oz[..m]);
    copy_written(&mut acc.color[r.clone()], &oc[..m]);
    for (h, &k) in acc.hide[r].iter_mut().zip(&hides[..m]) {
        *h |= k;
    }
}

/// The batch loop calling `f` point by point, as [`Prepared::eval`] does. With `f` a function
/// item (not a pointer) the formula is inlined into the loop: see [`inline_batch!`].
///
/// The loop writes its outputs to arrays of its own (passes of up to [`PASS`] points), copied
/// to `acc` after it: stores to the caller's columns could alias anything the formula reads,
/// and where it reads a table by a computed index (the reduction of huge arguments of sine
/// and cosine) the vectoriser can neither rule that out nor test for it at run time, so the
/// loop stayed scalar.
#[inline(always)]
pub fn batch_with(
    v: &Prepared,
    s: &SoaIn,
    acc: &mut SoaAcc,
    rng: &mut FastRng,
    f: impl Fn(&Prepared, &VarIn, &mut Acc, &mut FastRng) -> V3,
) {
    let n = acc.x.len();
    let own_z = v.def.flags & flag::WRITES_Z != 0;
    let default_z = v.default_z_rule();
    let mut start = 0;
    while start < n {
        let m = (n - start).min(PASS);
        let r = start..start + m;
        let s = s.range(r.clone());
        let mut out = [[MaybeUninit::<f64>::uninit(); PASS]; 4];
        let mut hides = [false; PASS];
        {
            let [ox, oy, oz, oc] = &mut out;
            let (ox, oy, oz, oc) = (&mut ox[..m], &mut oy[..m], &mut oz[..m], &mut oc[..m]);
            let hides = &mut hides[..m];
            let (ax, ay) = (&acc.x[r.clone()], &acc.y[r.clone()]);
            let (az, ac) = (&acc.z[r.clone()], &acc.color[r.clone()]);
            for j in 0..m {
                let t = s.at(j);
                let mut a = Acc {
                    x: ax[j],
                    y: ay[j],
                    z: az[j],
                    color: ac[j],
                    ..Acc::default()
                };
                // [`Prepared::eval_with`], its z rule decided before the loop.
                let mut o = f(v, &t, &mut a, rng);
                if !own_z {
                    o[2] = default_z.of(t.z);
                }
                ox[j] = MaybeUninit::new(a.x + o[0]);
                oy[j] = MaybeUninit::new(a.y + o[1]);
                oz[j] = MaybeUninit::new(a.z + o[2]);
                oc[j] = MaybeUninit::new(a.drawn_color());
                hides[j] = a.hide;
            }
        }
        write_pass(acc, r, &out, &hides);
        start += m;
    }
}

/// The random numbers of one point, drawn before its batch's loop, read in order: what a
/// formula generic over [`Draws`] takes in [`batch_with_draws`]. A formula that reads more than
/// `K` gets 0 for the rest (its batch loop then differs from its point-by-point version, which
/// the bit-for-bit test of every loop shows).
pub struct Row<const K: usize> {
    d: [u64; K],
    pos: usize,
}

impl<const K: usize> Draws for Row<K> {
    #[inline(always)]
    fn u64(&mut self) -> u64 {
        let u = self.d.get(self.pos).copied().unwrap_or(0);
        self.pos += 1;
        u
    }
}

/// A formula generic over [`Draws`] at [`Row`]`<K>`, for [`batch_with_draws`]: a trait with an
/// always-inlined method rather than a function passed as a value, whose call the compiler may
/// leave out of line (and a call in the loop stops it from vectorising).
pub trait DrawnFormula<const K: usize> {
    fn at(&self, v: &Prepared, t: &VarIn, a: &mut Acc, row: &mut Row<K>) -> V3;
}

/// [`batch_with`] for a formula that draws exactly `K` random numbers per point whatever the
/// point: the numbers of a pass are drawn first, point after point in the order the formula
/// draws them (the same stream and the same bits as the formula drawing them itself), and the
/// formula reads them from its point's [`Row`]: nothing then carries from point to point, so
/// the loop vectorises where the formula does.
#[inline(always)]
pub fn batch_with_draws<const K: usize>(
    v: &Prepared,
    s: &SoaIn,
    acc: &mut SoaAcc,
    rng: &mut FastRng,
    f: impl DrawnFormula<K>,
) {
    let n = acc.x.len();
    let own_z = v.def.flags & flag::WRITES_Z != 0;
    let default_z = v.default_z_rule();
    // Uninitialised as the outputs are (see [`copy_written`]): rows 0..m are drawn first.
    let mut drawn = [MaybeUninit::<[u64; K]>::uninit(); PASS];
    let mut start = 0;
    while start < n {
        let m = (n - start).min(PASS);
        for row in drawn[..m].iter_mut() {
            let mut d = [0u64; K];
            for u in d.iter_mut() {
                *u = rng.u64();
            }
            *row = MaybeUninit::new(d);
        }
        let r = start..start + m;
        let s = s.range(r.clone());
        let mut out = [[MaybeUninit::<f64>::uninit(); PASS]; 4];
        let mut hides = [false; PASS];
        {
            let [ox, oy, oz, oc] = &mut out;
            let (ox, oy, oz, oc) = (&mut ox[..m], &mut oy[..m], &mut oz[..m], &mut oc[..m]);
            let hides = &mut hides[..m];
            let drawn = &drawn[..m];
            let (ax, ay) = (&acc.x[r.clone()], &acc.y[r.clone()]);
            let (az, ac) = (&acc.z[r.clone()], &acc.color[r.clone()]);
            for j in 0..m {
                let t = s.at(j);
                let mut a = Acc {
                    x: ax[j],
                    y: ay[j],
                    z: az[j],
                    color: ac[j],
                    ..Acc::default()
                };
                let mut row = Row {
                    // SAFETY: rows 0..m were drawn above, and j < m.
                    d: unsafe { drawn[j].assume_init() },
                    pos: 0,
                };
                let mut o = f.at(v, &t, &mut a, &mut row);
                if !own_z {
                    o[2] = default_z.of(t.z);
                }
                ox[j] = MaybeUninit::new(a.x + o[0]);
                oy[j] = MaybeUninit::new(a.y + o[1]);
                oz[j] = MaybeUninit::new(a.z + o[2]);
                oc[j] = MaybeUninit::new(a.drawn_color());
                hides[j] = a.hide;
            }
        }
        write_pass(acc, r, &out, &hides);
        start += m;
    }
}

/// [`inline_batch!`] for a formula `$f` generic over [`Draws`] that draws exactly `$k` random
/// numbers per point: [`batch_with_draws`] with `$f` at [`Row`]`<$k>`, compiled for AVX2 and
/// FMA where the CPU has them; elsewhere [`generic_batch`] (the formula drawing the same
/// numbers itself, point by point).
macro_rules! inline_batch_drawn {
    ($f:ident, $k:expr) => {{
        fn batch(
            v: &$crate::flame::variations::Prepared,
            s: &$crate::flame::variations::SoaIn,
            acc: &mut $crate::flame::variations::SoaAcc,
            rng: &mut $crate::flame::rng::FastRng,
        ) {
            #[cfg(target_arch = "x86_64")]
            {
                use $crate::flame::fastmath::{Simd, simd};
                use $crate::flame::rng::FastRng;
                use $crate::flame::variations::{
                    Acc, DrawnFormula, Prepared, Row, SoaAcc, SoaIn, V3, VarIn, batch_with_draws,
                };
                struct Formula;
                impl DrawnFormula<{ $k }> for Formula {
                    #[inline(always)]
                    fn at(
                        &self,
                        v: &Prepared,
                        t: &VarIn,
                        a: &mut Acc,
                        row: &mut Row<{ $k }>,
                    ) -> V3 {
                        $f(v, t, a, row)
                    }
                }
                #[target_feature(enable = "avx2,fma")]
                fn avx2(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
                    batch_with_draws::<{ $k }>(v, s, acc, rng, Formula)
                }
                match simd() {
                    // SAFETY: the CPU has reported AVX2 and FMA (AVX-512F implies them here).
                    Simd::Avx512 | Simd::Avx2Fma => return unsafe { avx2(v, s, acc, rng) },
                    Simd::Baseline => {}
                }
            }
            // The same numbers in the same order, drawn point by point: the same bits.
            $crate::flame::variations::generic_batch(v, s, acc, rng)
        }
        batch as $crate::flame::variations::BatchFn
    }};
}
pub(crate) use inline_batch_drawn;

/// `VarDef::new(name, f)` for a formula `f` generic over [`Draws`] drawing exactly `k` random
/// numbers per point, with [`inline_batch_drawn!`]`(f, k)` as its batch loop.
macro_rules! inlined_drawn {
    ($name:expr, $f:ident, $k:expr) => {
        $crate::flame::variations::VarDef::new($name, $f::<$crate::flame::rng::FastRng>)
            .batch($crate::flame::variations::inline_batch_drawn!($f, $k))
    };
}
pub(crate) use inlined_drawn;

/// A [`BatchFn`] for the formula `$f` (an [`EvalFn`]-shaped function): on CPUs with AVX2 and
/// FMA, [`batch_with`] with the formula inlined and compiled for them — no call through a
/// pointer and no input record in memory per point; elsewhere [`generic_batch`] (one copy of
/// the loop each keeps the build short; an AVX-512 copy measured no faster for these
/// variations, benches/variation_speed.md). Every copy gives the same bits: Rust never
/// fuses a multiply and an add on its own. Every Fractorium variation has one: besides the
/// call through a pointer per point, the loop saves the baseline CPU's library calls for
/// floor and round where the formula is inlined.
macro_rules! inline_batch {
    ($f:path) => {{
        fn batch(
            v: &$crate::flame::variations::Prepared,
            s: &$crate::flame::variations::SoaIn,
            acc: &mut $crate::flame::variations::SoaAcc,
            rng: &mut $crate::flame::rng::FastRng,
        ) {
            #[cfg(target_arch = "x86_64")]
            {
                use $crate::flame::fastmath::{Simd, simd};
                use $crate::flame::rng::FastRng;
                use $crate::flame::variations::{Prepared, SoaAcc, SoaIn, batch_with};
                #[target_feature(enable = "avx2,fma")]
                fn avx2(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
                    batch_with(v, s, acc, rng, $f)
                }
                match simd() {
                    // SAFETY: the CPU has reported AVX2 and FMA (AVX-512F implies them here).
                    Simd::Avx512 | Simd::Avx2Fma => return unsafe { avx2(v, s, acc, rng) },
                    Simd::Baseline => {}
                }
            }
            $crate::flame::variations::generic_batch(v, s, acc, rng)
        }
        batch as $crate::flame::variations::BatchFn
    }};
}
pub(crate) use inline_batch;

/// `VarDef::new(name, f)` with [`inline_batch!`]`(f)` as its batch loop.
macro_rules! inlined {
    ($name:expr, $f:ident) => {
        $crate::flame::variations::VarDef::new($name, $f)
            .batch($crate::flame::variations::inline_batch!($f))
    };
}
pub(crate) use inlined;

/// The batch inputs of the points `pts` (their derived quantities computed as the chaos loop
/// computes them), as owned columns: x, y, z, r², r, x/r, y/r, atan2(x, y), atan2(y, x),
/// colour.
fn columns(pts: &[V3], color: f64) -> [Vec<f64>; 10] {
    let ts: Vec<VarIn> = pts
        .iter()
        .map(|p| VarIn::new(p[0], p[1], p[2], color, 0xff, false))
        .collect();
    let col = |f: fn(&VarIn) -> f64| ts.iter().map(f).collect::<Vec<f64>>();
    [
        col(|t| t.x),
        col(|t| t.y),
        col(|t| t.z),
        col(|t| t.sumsq),
        col(|t| t.sqrt),
        col(|t| t.ux),
        col(|t| t.uy),
        col(|t| t.atan_xy),
        col(|t| t.atan_yx),
        col(|t| t.color),
    ]
}

/// Run `v` over the points `pts` (in groups of 256, as the chaos loop does) `reps` times, the
/// batch loops of this thread limited to `simd`, through its batch loop (`batched`) or point by
/// point through its formula's pointer; the seconds it took. For benches.
pub fn time_batches(v: &Prepared, pts: &[V3], reps: usize, simd: Simd, batched: bool) -> f64 {
    let [x, y, z, sumsq, sqrt, ux, uy, atan_xy, atan_yx, color] = columns(pts, 0.25);
    let n = pts.len();
    let (mut ax, mut ay, mut az) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let (mut ac, mut hide) = (color.clone(), vec![false; n]);
    let mut rng = FastRng::new(1);
    fastmath::limit_simd(simd);
    let start = std::time::Instant::now();
    for _ in 0..reps {
        for g in (0..n).step_by(256) {
            let r = g..n.min(g + 256);
            let soa = SoaIn {
                x: &x[r.clone()],
                y: &y[r.clone()],
                z: &z[r.clone()],
                sumsq: &sumsq[r.clone()],
                sqrt: &sqrt[r.clone()],
                ux: &ux[r.clone()],
                uy: &uy[r.clone()],
                atan_xy: &atan_xy[r.clone()],
                atan_yx: &atan_yx[r.clone()],
                color: &color[r.clone()],
            };
            let mut acc = SoaAcc {
                x: &mut ax[r.clone()],
                y: &mut ay[r.clone()],
                z: &mut az[r.clone()],
                color: &mut ac[r.clone()],
                hide: &mut hide[r],
            };
            if batched {
                v.apply_batch(&soa, &mut acc, &mut rng);
            } else {
                generic_batch(v, &soa, &mut acc, &mut rng);
            }
        }
    }
    let secs = start.elapsed().as_secs_f64();
    fastmath::limit_simd(Simd::Avx512);
    std::hint::black_box((&ax, &ay, &az));
    secs
}

#[cfg(test)]
mod tests {
    use super::super::{VarId, all};
    use super::*;
    use crate::flame::affine::Affine;
    use crate::flame::variations::def::Form;

    /// Every copy of every batch loop (baseline, AVX2 and FMA, AVX-512 as far as the CPU has
    /// them) gives the same bits as the formula called point by point (compiled for the
    /// baseline CPU; a NaN may differ in sign), random variations included (their numbers
    /// drawn beforehand in the same order): the chaos game's pictures do not depend on the CPU.
    #[test]
    fn batch_loops_match_the_formula_bit_for_bit() {
        let mut gen_rng = FastRng::new(3);
        let n = 256;
        let mut pts: Vec<V3> = (0..n)
            .map(|_| {
                let s = 10f64.powf(gen_rng.f01() * 6.0 - 3.0);
                [
                    (gen_rng.f01() - 0.5) * s,
                    (gen_rng.f01() - 0.5) * s,
                    gen_rng.f01() - 0.5,
                ]
            })
            .collect();
        pts[0] = [0.0, 0.0, 0.0];
        pts[1] = [1e-300, -1e-300, 0.0];
        let aff = Affine {
            a: 0.9,
            b: -0.3,
            c: 0.2,
            d: 0.4,
            e: 1.1,
            f: -0.6,
        };
        let mut checked = 0;
        // Each loop with Fractorium's compatibility switch on and off (loops are compiled for
        // one setting each).
        let loops = all().iter().enumerate().filter(|(_, d)| d.batch.is_some());
        for ((id, def), compat) in loops.flat_map(|l| [(l, true), (l, false)]) {
            let params: Vec<f64> = def.params.iter().map(|p| p.default + 0.37).collect();
            // A fresh copy per run: some variations walk a state from point to point.
            let fresh = || Prepared::new(id as VarId, Form::Regular, 0.7, &params, aff, compat);
            let ts: Vec<VarIn> = pts
                .iter()
                .map(|p| VarIn::new(p[0], p[1], p[2], 0.25, 0xff, false))
                .collect();
            let col = |f: fn(&VarIn) -> f64| ts.iter().map(f).collect::<Vec<f64>>();
            let (x, y, z) = (col(|t| t.x), col(|t| t.y), col(|t| t.z));
            let (sumsq, sqrt) = (col(|t| t.sumsq), col(|t| t.sqrt));
            let (ux, uy) = (col(|t| t.ux), col(|t| t.uy));
            let (atan_xy, atan_yx, color) =
                (col(|t| t.atan_xy), col(|t| t.atan_yx), col(|t| t.color));
            let soa = SoaIn {
                x: &x,
                y: &y,
                z: &z,
                sumsq: &sumsq,
                sqrt: &sqrt,
                ux: &ux,
                uy: &uy,
                atan_xy: &atan_xy,
                atan_yx: &atan_yx,
                color: &color,
            };
            let run = |batched: bool| {
                let (mut ax, mut ay, mut az) = (vec![0.5; n], vec![-0.5; n], vec![0.125; n]);
                let (mut ac, mut hide) = (color.clone(), vec![false; n]);
                let mut acc = SoaAcc {
                    x: &mut ax,
                    y: &mut ay,
                    z: &mut az,
                    color: &mut ac,
                    hide: &mut hide,
                };
                let mut rng = FastRng::new(9);
                let v = fresh();
                if batched {
                    v.apply_batch(&soa, &mut acc, &mut rng);
                } else {
                    generic_batch(&v, &soa, &mut acc, &mut rng);
                }
                (ax, ay, az)
            };
            // NaN as one value: a loop compiled for vector units may give a NaN of the other
            // sign (the hardware's default NaN where the scalar code folded a constant), and
            // the chaos game discards a NaN point whatever its bits.
            let bits = |v: &[f64]| {
                v.iter()
                    .map(|x| {
                        if x.is_nan() {
                            f64::NAN.to_bits()
                        } else {
                            x.to_bits()
                        }
                    })
                    .collect::<Vec<u64>>()
            };
            let g = run(false);
            for simd in [Simd::Baseline, Simd::Avx2Fma, Simd::Avx512] {
                fastmath::limit_simd(simd);
                let b = run(true);
                fastmath::limit_simd(Simd::Avx512);
                let name = format!("{} (compat {compat}) {simd:?}", def.name);
                assert_eq!(bits(&b.0), bits(&g.0), "{name} x");
                assert_eq!(bits(&b.1), bits(&g.1), "{name} y");
                assert_eq!(bits(&b.2), bits(&g.2), "{name} z");
            }
            checked += 1;
        }
        // flam3's 99 and the 319 inlined loops of Fractorium's variations, twice.
        assert!(checked >= 2 * 418, "{checked} batch loops");
    }
}
