//! Renders in strips: images larger than memory, band by band.
//!
//! Every strip iterates all the samples of the whole render (the same sub-batches, seeds and
//! orbits) and keeps those that land in its band of bucket rows, as flam3 and Fractorium do
//! for posters. The band reaches beyond the strip's output rows by the spatial filter's
//! footprint plus the density-estimation kernel radius and its hit-count block, so each pixel
//! sees exactly the buckets it sees in the whole render: no seam. The cost is K times the
//! iteration of one render; the memory is one band's histograms.

use std::ops::Range;

use crate::flame::budget::{MemoryEstimate, check_memory, estimate_memory, estimate_memory_rows};
use crate::flame::model::Flame;
use crate::flame::settings::{RenderError, RenderOptions, geometry_of};
use crate::memory::Budget;

/// Most strips a render may be cut into.
pub const MAX_STRIPS: usize = 10_000;

/// One band of a render in strips.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Strip {
    /// Output image rows this strip makes.
    pub out_rows: Range<usize>,
    /// Bucket rows of the whole grid its histogram holds (output rows plus margins).
    pub hist_rows: Range<usize>,
    /// Bucket rows it contributes to a saved state: the strips' core rows tile the grid.
    pub core_rows: Range<usize>,
}

/// Cut a flame's image into `k` strips of nearly equal height.
pub fn plan(flame: &Flame, k: usize) -> Result<Vec<Strip>, RenderError> {
    let h = flame.height as usize;
    if k == 0 || k > MAX_STRIPS.min(h.max(1)) {
        return Err(RenderError::Settings(format!(
            "{k} strips: must be between 1 and {} (the image height, at most {MAX_STRIPS})",
            MAX_STRIPS.min(h.max(1))
        )));
    }
    let geom = geometry_of(flame)?;
    let (os, g, bh) = (geom.os, geom.gutter, geom.full_bh);
    // A bucket's DE kernel reaches `half` rows; its hit count sums a block of os/2 rows more.
    let margin = geom
        .de
        .as_ref()
        .map_or(0, |d| d.half.max(0) as usize + os / 2);
    let cut = |s: usize| s * h / k;
    Ok((0..k)
        .map(|s| {
            let (y0, y1) = (cut(s), cut(s + 1));
            let core_lo = if s == 0 { 0 } else { y0 * os + g };
            let core_hi = if s + 1 == k { bh } else { y1 * os + g };
            let need = geom.source_rows(y0..y1);
            let need_lo = need.start.saturating_sub(margin);
            let need_hi = (need.end + margin).min(bh);
            Strip {
                out_rows: y0..y1,
                hist_rows: core_lo.min(need_lo)..core_hi.max(need_hi),
                core_rows: core_lo..core_hi,
            }
        })
        .collect())
}

/// The fewest strips whose largest strip fits in `budget` bytes (`None`: not even strips one
/// output row high fit).
pub fn strips_for_budget(
    flame: &Flame,
    opts: &RenderOptions,
    budget: u64,
) -> Result<Option<usize>, RenderError> {
    let h = (flame.height as usize).clamp(1, MAX_STRIPS);
    let fits = |k: usize| -> Result<bool, RenderError> {
        if k == 1 {
            // One strip is the whole render, checked as such (its picture is encoded whole).
            return Ok(estimate_memory(flame, opts).total <= budget);
        }
        let strips = plan(flame, k)?;
        let worst = strips
            .iter()
            .map(|s| (s.hist_rows.len() as u64, s.out_rows.len() as u64))
            .max()
            .unwrap_or((0, 0));
        Ok(estimate_memory_rows(flame, opts, Some(worst)).total <= budget)
    };
    if !fits(h)? {
        return Ok(None);
    }
    // Fitting is monotone in k (more strips, smaller bands): bisect.
    let (mut lo, mut hi) = (1usize, h);
    if fits(1)? {
        return Ok(Some(1));
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if fits(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok(Some(hi))
}

/// As [`check_memory`] for one strip of a render in strips.
pub fn check_memory_rows(
    flame: &Flame,
    opts: &RenderOptions,
    strip: &Strip,
) -> Result<MemoryEstimate, RenderError> {
    let rows = (strip.hist_rows.len() as u64, strip.out_rows.len() as u64);
    let est = estimate_memory_rows(flame, opts, Some(rows));
    crate::memory::check(
        est.total,
        opts.memory_limit,
        || {
            format!(
                "a strip of {} rows of a {}×{} flame render at supersample {} with {} thread(s)",
                rows.1, flame.width, flame.height, flame.supersample, est.threads
            )
        },
        || format!("use more strips, or {}", est.hint(flame)),
    )?;
    Ok(est)
}

/// How a render fits in memory.
#[derive(Clone, Debug)]
pub struct Fit {
    /// 1: the whole image at once; more: in this many strips.
    pub strips: usize,
    /// The estimate of the whole render at once, in bytes.
    pub needed: u64,
    /// The memory it may use.
    pub budget: Budget,
}

impl Fit {
    /// The options to render with: the budget the strips were chosen for. Each strip's check
    /// ([`check_memory_rows`]) then compares the same estimate with the same budget as the
    /// choice did, instead of measuring again once the render's threads run — the address
    /// space their stacks and allocator arenas take is what the budget's headroom allowed
    /// for (see [`crate::memory::ADDRESS_SPACE_HEADROOM`]), and taking it twice refused
    /// strips that fit.
    pub fn options(&self, opts: &RenderOptions) -> RenderOptions {
        RenderOptions {
            memory_limit: Some(self.budget.bytes),
            ..opts.clone()
        }
    }

    /// "needs about 3.1 GiB at once, 2 GiB available (memory limit)".
    pub fn describe(&self) -> String {
        format!(
            "needs about {} at once, {} available ({})",
            crate::memory::fmt_bytes(self.needed),
            crate::memory::fmt_bytes(self.budget.bytes),
            self.budget.source
        )
    }
}

/// The fewest strips a render needs within its memory budget (`opts.memory_limit`, or what
/// the system allows). The whole render's memory error when not even strips one output row
/// high fit.
pub fn fit(flame: &Flame, opts: &RenderOptions) -> Result<Fit, RenderError> {
    let budget = crate::memory::budget_or(opts.memory_limit);
    let needed = estimate_memory(flame, opts).total;
    let strips = if needed <= budget.bytes {
        1
    } else {
        match strips_for_budget(flame, opts, budget.bytes)? {
            Some(k) => k,
            None => {
                check_memory(flame, opts)?;
                1
            }
        }
    };
    Ok(Fit {
        strips,
        needed,
        budget,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::geometry::Geometry;

    #[test]
    fn strips_cover_the_image_and_tile_the_grid() {
        let f = Flame {
            width: 64,
            height: 48,
            supersample: 2,
            estimator_radius: 5.0,
            ..Flame::default()
        };
        let strips = plan(&f, 5).unwrap();
        assert_eq!(strips[0].out_rows.start, 0);
        assert_eq!(strips[4].out_rows.end, 48);
        assert_eq!(strips[0].core_rows.start, 0);
        let geom = Geometry::new(&f, None);
        assert_eq!(strips[4].core_rows.end, geom.full_bh);
        for w in strips.windows(2) {
            assert_eq!(w[0].out_rows.end, w[1].out_rows.start);
            assert_eq!(w[0].core_rows.end, w[1].core_rows.start);
        }
        for s in &strips {
            assert!(s.hist_rows.start <= s.core_rows.start && s.core_rows.end <= s.hist_rows.end);
        }
        assert!(plan(&f, 0).is_err());
        assert!(plan(&f, 49).is_err());
    }

    #[test]
    fn the_chosen_strips_pass_their_own_check_and_are_the_fewest() {
        let f = Flame {
            width: 800,
            height: 600,
            supersample: 2,
            estimator_radius: 9.0,
            ..Flame::default()
        };
        let whole = estimate_memory(&f, &RenderOptions::default()).total;
        for (share, save_state) in [(0.9, false), (0.5, true), (0.3, false), (0.2, true)] {
            let opts = RenderOptions {
                threads: 2,
                memory_limit: Some((whole as f64 * share) as u64),
                save_state,
                ..RenderOptions::default()
            };
            let fit = fit(&f, &opts).unwrap();
            assert!(fit.strips > 1, "{share}");
            let strip_opts = fit.options(&opts);
            for s in plan(&f, fit.strips).unwrap() {
                check_memory_rows(&f, &strip_opts, &s).unwrap();
            }
            // One strip fewer does not fit (one strip is the whole render, checked whole).
            let fewer = plan(&f, fit.strips - 1).unwrap();
            assert!(
                if fit.strips == 2 {
                    check_memory(&f, &strip_opts).is_err()
                } else {
                    fewer
                        .iter()
                        .any(|s| check_memory_rows(&f, &strip_opts, s).is_err())
                },
                "{share}: {} strips would have fitted",
                fit.strips - 1
            );
        }
    }
}
