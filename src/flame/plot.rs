//! Plotting samples into a histogram: one sub-batch of the lane runner turned into bucket
//! indices and kept points, the scattered adds of their palette colours (with prefetching and
//! a block-wise palette lookup), and the sub-batch of a 3-D IFS.

use crate::flame::chaos::{Chaos, LANES, Lanes};
use crate::flame::geometry::Geometry;
use crate::flame::histogram::{Bucket, Histogram, PlotPalette};
use crate::flame::ifs3d::Ifs3dSystem;
use crate::flame::jwf_render::JwfRaster;
use crate::flame::jwf_render::own_colour::{OwnSample, accumulate_own};
use crate::flame::model::PaletteMode;
use crate::flame::rng::FastRng;

/// A plotted point waiting to be accumulated: bucket, colour coordinate, visibility.
pub(super) type Pending = (u32, f32, f32);

/// Iterate one sub-batch into a histogram. The plotted points are first collected in `buf`
/// and then added in a tight loop, so the cache misses of the scattered adds overlap.
///
/// The loop is compiled twice: for the baseline CPU and with AVX2 and FMA, chosen at run
/// time. Rust never fuses a multiply and an add on its own, so both give the same bits.
#[allow(clippy::too_many_arguments)]
pub(super) fn iterate_into(
    chaos: &Chaos,
    geom: &Geometry,
    pal: &PlotPalette,
    hist: &mut Histogram,
    buf: &mut Vec<Pending>,
    lanes: &mut Lanes,
    n: u64,
    rng: &mut FastRng,
) -> u64 {
    #[cfg(target_arch = "x86_64")]
    if crate::flame::fastmath::has_avx2_fma() {
        // SAFETY: the CPU has just reported AVX2 and FMA.
        return unsafe { iterate_into_avx2(chaos, geom, pal, hist, buf, lanes, n, rng) };
    }
    iterate_into_generic(chaos, geom, pal, hist, buf, lanes, n, rng)
}

/// [`iterate_into`] for CPUs with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[allow(clippy::too_many_arguments)]
fn iterate_into_avx2(
    chaos: &Chaos,
    geom: &Geometry,
    pal: &PlotPalette,
    hist: &mut Histogram,
    buf: &mut Vec<Pending>,
    lanes: &mut Lanes,
    n: u64,
    rng: &mut FastRng,
) -> u64 {
    iterate_into_generic(chaos, geom, pal, hist, buf, lanes, n, rng)
}

#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn iterate_into_generic(
    chaos: &Chaos,
    geom: &Geometry,
    pal: &PlotPalette,
    hist: &mut Histogram,
    buf: &mut Vec<Pending>,
    lanes: &mut Lanes,
    n: u64,
    rng: &mut FastRng,
) -> u64 {
    const L: usize = LANES;
    buf.clear();
    // At most n samples are kept, and each step writes up to L places beyond the kept ones.
    buf.reserve(n as usize + L);
    let map = geom.bucket_map();
    let (mut idx, mut keep) = ([0u32; L], [0u32; L]);
    // JWildfire's raster, and its antialiasing: points moved by random offsets, from a
    // stream of their own.
    let jwf = geom.jwf.is_some();
    let antialias = geom.jwf.as_ref().and_then(|j| j.antialias);
    let mut aa_rng = FastRng::new(if antialias.is_some() { rng.u64() } else { 0 });
    // Samples with colours of their own, added apart (only flames whose points carry them).
    let mut own: Vec<OwnSample> = Vec::new();
    let bad = chaos.run_lanes(n, rng, lanes, |xs, ys, _zs, cs, vs, rgbs| {
        // Buckets as arrays (vectorised), then a branch-free compaction of the visible
        // points that land in the histogram.
        let m = xs.len().min(ys.len()).min(cs.len()).min(vs.len()).min(L);
        if jwf {
            for j in 0..m {
                let d = match antialias {
                    Some((amount, radius)) => JwfRaster::jitter(amount, radius, &mut aa_rng),
                    None => (0.0, 0.0),
                };
                let (i, inside) = map.index_jwildfire(xs[j], ys[j], d);
                idx[j] = i;
                keep[j] = (inside & (vs[j] > 0.0)) as u32;
            }
        } else {
            for j in 0..m {
                let (i, inside) = map.index(xs[j], ys[j]);
                idx[j] = i;
                keep[j] = (inside & (vs[j] > 0.0)) as u32;
            }
        }
        if !rgbs.is_empty() {
            for j in 0..m.min(rgbs.len()) {
                if keep[j] != 0 && rgbs[j] != 0 {
                    own.push((idx[j], rgbs[j], vs[j] as f32));
                    keep[j] = 0;
                }
            }
        }
        // Written straight into the spare capacity of `buf`: every place is written before
        // it is counted, only the kept ones are counted.
        let len = buf.len();
        assert!(buf.capacity() - len >= L);
        let spare = buf.as_mut_ptr().wrapping_add(len);
        let mut k = 0;
        for j in 0..m {
            // SAFETY: k ≤ j < m ≤ L places after `len`, within the capacity just checked.
            unsafe {
                spare
                    .add(k & (L - 1))
                    .write((idx[j], cs[j] as f32, vs[j] as f32))
            };
            k += keep[j] as usize;
        }
        // SAFETY: places len..len + k were initialised just above (k ≤ m ≤ L).
        unsafe { buf.set_len(len + k.min(m)) };
    });
    accumulate(pal, hist, buf);
    accumulate_own(pal, hist, &own);
    bad
}

/// Add pending samples to a histogram.
#[inline(always)]
pub(super) fn accumulate(pal: &PlotPalette, hist: &mut Histogram, buf: &[Pending]) {
    // The adds scatter over a histogram larger than the caches: ask for the bucket a few
    // samples ahead so its cache miss overlaps the adds in between.
    const AHEAD: usize = 40;
    // With a stepped palette the entries are looked up for a block of samples first, in a
    // loop of conversions the compiler vectorises (the same entry as `PlotPalette::lookup`).
    const BLOCK: usize = 64;
    let data = &mut hist.data;
    let colors = &pal.colors[..];
    let step = pal.mode == PaletteMode::Step && !colors.is_empty();
    let (scale, offset) = (pal.scale, pal.offset);
    let top = colors.len().saturating_sub(1) as f64;
    let add = |data: &mut [Bucket], i: usize, idx: u32, p: [f32; 4], v: f32| {
        if let Some(&(ahead, _, _)) = buf.get(i + AHEAD) {
            prefetch(data.as_ptr().wrapping_add(ahead as usize));
        }
        let b = &mut data[idx as usize];
        b[0] += p[0] * v;
        b[1] += p[1] * v;
        b[2] += p[2] * v;
        b[3] += p[3] * v;
    };
    if !step {
        for (i, &(idx, c, v)) in buf.iter().enumerate() {
            add(data, i, idx, pal.lookup(c as f64), v);
        }
        return;
    }
    let mut entry = [0u32; BLOCK];
    for (b, block) in buf.chunks(BLOCK).enumerate() {
        for (e, &(_, c, _)) in entry.iter_mut().zip(block) {
            // max/min also send NaN to 0, as the saturating cast of `lookup` does.
            let f = (c as f64 * scale + offset).max(0.0).min(top);
            // SAFETY: f is finite and within 0..=top, which fits a u32.
            *e = unsafe { f.to_int_unchecked::<u32>() };
        }
        for (j, (&(idx, _, v), &e)) in block.iter().zip(&entry).enumerate() {
            // SAFETY: e ≤ top = colors.len() - 1.
            let p = unsafe { *colors.get_unchecked(e as usize) };
            add(data, b * BLOCK + j, idx, p, v);
        }
    }
}

/// Hint the CPU to fetch the cache line at `p` (no effect on other targets).
#[inline(always)]
fn prefetch<T>(p: *const T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch never faults and does not read memory into the program; any
    // address, valid or not, is allowed.
    unsafe {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        _mm_prefetch::<_MM_HINT_T0>(p.cast::<i8>());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = p;
}

/// Iterate a 3-D IFS sub-batch into a histogram.
pub(super) fn iterate_3d(
    sys: &Ifs3dSystem,
    geom: &Geometry,
    pal: &PlotPalette,
    hist: &mut Histogram,
    n: u64,
    rng: &mut FastRng,
) -> u64 {
    let data = &mut hist.data;
    sys.run_sub_batch(n, rng, |x, y, c, _| {
        if let Some(idx) = geom.bucket_of(x, y) {
            let p = pal.lookup(c);
            let b = &mut data[idx];
            b[0] += p[0];
            b[1] += p[1];
            b[2] += p[2];
            b[3] += p[3];
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::model::Flame;
    use crate::gradient::Gradient;

    /// The block-wise palette lookup of `accumulate` adds what `PlotPalette::lookup` gives,
    /// bit for bit, at the edges too (NaN, negative, 1 and beyond), in both palette modes.
    #[test]
    fn accumulate_adds_the_entries_lookup_gives() {
        let edge = [
            f32::NAN,
            -1.0,
            -0.0,
            0.0,
            1e-9,
            0.5,
            0.999_999,
            1.0,
            1.5,
            f32::INFINITY,
        ];
        let buf: Vec<Pending> = (0..300u32)
            .map(|i| {
                let c = match edge.get(i as usize % 13) {
                    Some(&e) => e,
                    None => (i as f32 * 0.618_034).fract(),
                };
                (i % 7, c, 0.25 + (i % 3) as f32)
            })
            .collect();
        for (mode, index) in [PaletteMode::Step, PaletteMode::Linear]
            .into_iter()
            .flat_map(|m| crate::flame::PaletteIndex::ALL.map(|r| (m, r)))
        {
            let flame = Flame {
                palette: Gradient::grey_ramp(),
                palette_mode: mode,
                palette_index: index,
                ..Flame::default()
            };
            let pal = PlotPalette::new(&flame);
            let mut got = Histogram::new(7, 1);
            accumulate(&pal, &mut got, &buf);
            let mut want = Histogram::new(7, 1);
            for &(idx, c, v) in &buf {
                let p = pal.lookup(c as f64);
                for (w, p) in want.data[idx as usize].iter_mut().zip(p) {
                    *w += p * v;
                }
            }
            let bits = |h: &Histogram| -> Vec<u32> {
                h.data.iter().flatten().map(|v| v.to_bits()).collect()
            };
            assert_eq!(bits(&got), bits(&want), "{mode:?} {index:?}");
        }
    }
}
