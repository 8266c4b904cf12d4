//! The memory budget of a flame render: what its buffers will need, part by part, estimated
//! before anything is allocated, and the check that refuses a render that does not fit.

use crate::flame::chaos::{Lanes, SUB_BATCH};
use crate::flame::histogram::Bucket;
use crate::flame::model::Flame;
use crate::flame::plot::Pending;
use crate::flame::settings::{MAX_KEPT_SAMPLES, RenderError, RenderOptions};
use crate::threads::Threads;

/// Bucket rows of one compressed chunk of a saved render state.
pub const SAVE_CHUNK_ROWS: u64 = 32;

/// Most bytes the chunks of a render state being saved hold at once. The writer compresses
/// [`save_chunks_in_flight`] chunks in parallel; each holds up to twice its size (its packed
/// copy and the compressor's output) until it is written.
pub const SAVE_BUFFER_BYTES: u64 = 64 << 20;

/// The PNG compressor's own state and output buffer (the fast deflate ugnis writes with),
/// besides the rows it filters and, for a whole picture, its compressed data.
pub const PNG_ENCODER_BYTES: u64 = 64 << 10;

/// How many chunks of `chunk_bytes` the state writer compresses at once on `threads`
/// threads: two per thread, as far as [`SAVE_BUFFER_BYTES`] allows, and at least one.
pub fn save_chunks_in_flight(chunk_bytes: u64, threads: usize) -> usize {
    let fit = SAVE_BUFFER_BYTES / (2 * chunk_bytes).max(1);
    (2 * threads.max(1)).min(fit.max(1) as usize)
}

/// Memory the buffers of a render will need, in bytes, part by part.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MemoryEstimate {
    /// Threads the estimate is for (resolved and clamped).
    pub threads: usize,
    /// One histogram (os·W + 2g by os·H + 2g buckets of 16 bytes).
    pub histogram: u64,
    /// Every thread's histogram, orbit lanes and plot buffer.
    pub workers: u64,
    /// Developing: the density-estimation accumulator and the merged copy a preview makes.
    pub develop: u64,
    /// The output image and the copy made while encoding it.
    pub image: u64,
    /// The encoders' working memory: the PNG compressor with the rows it filters (a whole
    /// picture is compressed into memory before it is written: up to its own size) and, when
    /// a render state is saved, the chunks being compressed ([`save_chunks_in_flight`] on the
    /// pool the save runs on: at most [`SAVE_BUFFER_BYTES`] unless one chunk is larger).
    pub encoder: u64,
    /// Kept samples for recolouring (0 unless asked for).
    pub kept_samples: u64,
    /// Bytes in all.
    pub total: u64,
}

impl MemoryEstimate {
    /// What to change when the estimate does not fit: the largest part first.
    pub fn hint(&self, flame: &Flame) -> String {
        let mut h = String::from("reduce the image size");
        if flame.supersample > 1 {
            h.push_str(&format!(" or the supersample ({})", flame.supersample));
        }
        if self.threads > 1 {
            h.push_str(&format!(
                ", or use fewer threads ({} histograms of {} each)",
                self.threads,
                crate::memory::fmt_bytes(self.histogram)
            ));
        }
        if self.kept_samples > 0 {
            h.push_str(", or do not keep samples for recolouring");
        }
        h
    }
}

/// Estimate the buffers of a render before allocating anything. The threads are resolved
/// as the renderer resolves them. A render in strips estimates one strip with
/// [`estimate_memory_rows`].
pub fn estimate_memory(flame: &Flame, opts: &RenderOptions) -> MemoryEstimate {
    estimate_memory_rows(flame, opts, None)
}

/// As [`estimate_memory`] for a band of the image: `rows` = (bucket rows held, output rows
/// made) of one strip; `None` for the whole image.
pub fn estimate_memory_rows(
    flame: &Flame,
    opts: &RenderOptions,
    rows: Option<(u64, u64)>,
) -> MemoryEstimate {
    let threads = Threads::resolve(opts.threads).count as u64;
    let os = flame.supersample.max(1) as u64;
    let g = {
        let f =
            crate::flame::filter::SpatialFilter::new(flame.filter_shape, flame.filter, os as u32);
        let de = if flame.estimator_radius > 0.0 {
            flame.estimator_radius.ceil() as u64 * os + (os - 1)
        } else {
            0
        };
        (f.gutter as u64).max(de)
    };
    let bw = os * flame.width as u64 + 2 * g;
    let bh = match rows {
        Some((hist_rows, _)) => hist_rows,
        None => os * flame.height as u64 + 2 * g,
    };
    let bucket = std::mem::size_of::<Bucket>() as u64;
    let hist = bw.saturating_mul(bh).saturating_mul(bucket);
    let per_worker =
        std::mem::size_of::<Lanes>() as u64 + SUB_BATCH * std::mem::size_of::<Pending>() as u64;
    let mut workers = (hist + per_worker).saturating_mul(threads);
    let mut develop = hist.saturating_mul(2);
    if flame.renders_as_jwildfire() && flame.jwf.solid.enabled && rows.is_none() {
        // JWildfire's solid rendering: each worker's nearest points, and the planes of their
        // development.
        use crate::flame::jwf_render::solid_draw::{SOLID_CELL_BYTES, SOLID_DEVELOP_BYTES};
        let buckets = bw.saturating_mul(bh);
        workers = workers.saturating_add(
            buckets
                .saturating_mul(SOLID_CELL_BYTES)
                .saturating_mul(threads),
        );
        develop = develop.saturating_add(buckets.saturating_mul(SOLID_DEVELOP_BYTES));
    }
    let px = flame.width as u64
        * match rows {
            Some((_, out_rows)) => out_rows,
            None => flame.height as u64,
        };
    let channels = if opts.format.transparent { 4 } else { 3 };
    let depth = if opts.format.bits16 { 2 } else { 1 };
    let image = px.saturating_mul(channels * depth * 2);
    let png = PNG_ENCODER_BYTES
        + match rows {
            Some(_) => 4 * flame.width as u64 * channels * depth,
            None => px.saturating_mul(channels * depth),
        };
    let encoder = if opts.save_state {
        // The pool a save compresses on (the global one: as many threads as cores).
        let chunk = SAVE_CHUNK_ROWS.saturating_mul(bw).saturating_mul(bucket);
        let in_flight = save_chunks_in_flight(chunk, rayon::current_num_threads()) as u64;
        (2 * chunk).saturating_mul(in_flight).saturating_add(png)
    } else {
        png
    };
    let samples = flame.total_samples();
    let kept_samples = if opts.keep_samples && samples <= MAX_KEPT_SAMPLES {
        samples * std::mem::size_of::<Pending>() as u64
    } else {
        0
    };
    MemoryEstimate {
        threads: threads as usize,
        histogram: hist,
        workers,
        develop,
        image,
        encoder,
        kept_samples,
        total: workers
            .saturating_add(develop)
            .saturating_add(image)
            .saturating_add(encoder)
            .saturating_add(kept_samples),
    }
}

/// Refuse a render whose estimate exceeds the memory budget (`opts.memory_limit`, or what
/// the system allows: see [`crate::memory`]).
pub fn check_memory(flame: &Flame, opts: &RenderOptions) -> Result<MemoryEstimate, RenderError> {
    let est = estimate_memory(flame, opts);
    crate::memory::check(
        est.total,
        opts.memory_limit,
        || {
            format!(
                "a {}×{} flame render at supersample {} with {} thread(s)",
                flame.width, flame.height, flame.supersample, est.threads
            )
        },
        || est.hint(flame),
    )?;
    Ok(est)
}

/// Memory available to this process (Linux `MemAvailable`), if known.
pub fn available_memory() -> Option<u64> {
    crate::memory::available_memory()
}
