//! What a render has accumulated, kept so that it can be continued later, on another machine,
//! or summed with other shares of the same render.
//!
//! The histogram of a flame render is a sum over samples, so renders of disjoint sets of
//! samples add up exactly: `--part i/n` iterates the sub-batches whose global index is
//! i, i + n, i + 2n, … (each sub-batch has its own random stream, seeded from the render seed
//! and that index), and the sum of the n parts' histograms holds every sub-batch of the whole
//! render once. A resumed render continues with the next sub-batches of its own share.
//!
//! The file format lives in `io::render_state`; this module holds the settings and the checks
//! that do not depend on files.

use crate::flame::chaos::{LaneState, SUB_BATCH};
use crate::flame::model::Flame;

/// Most parts a render may be split into (a thousand machines is a large farm).
pub const MAX_PARTS: u32 = 100_000;

/// The i-th of n shares of a render's samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Part {
    /// Which share, 0-based (below `count`).
    pub index: u32,
    /// Number of shares.
    pub count: u32,
}

impl Default for Part {
    fn default() -> Self {
        Part { index: 0, count: 1 }
    }
}

impl std::fmt::Display for Part {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl Part {
    /// Check the numbers: 1 ≤ count ≤ `MAX_PARTS` (100 000), index < count.
    pub fn validate(&self) -> Result<(), String> {
        if self.count == 0 || self.count > MAX_PARTS {
            return Err(format!(
                "part count {} must be between 1 and {MAX_PARTS}",
                self.count
            ));
        }
        if self.index >= self.count {
            return Err(format!(
                "part index {} must be below the part count {} (parts are numbered from 0)",
                self.index, self.count
            ));
        }
        Ok(())
    }

    /// Sub-batches of this part among the first `global` sub-batches of the render.
    pub fn local_batches(&self, global: u64) -> u64 {
        let (i, n) = (self.index as u64, self.count as u64);
        if global > i {
            (global - i).div_ceil(n)
        } else {
            0
        }
    }

    /// Global index of the part's k-th sub-batch.
    pub fn global(&self, k: u64) -> u64 {
        k * self.count as u64 + self.index as u64
    }

    /// Samples of this part when the whole render has `total` samples.
    pub fn samples(&self, total: u64) -> u64 {
        let global = total.div_ceil(SUB_BATCH);
        let local = self.local_batches(global);
        if local == 0 {
            return 0;
        }
        let mut s = local * SUB_BATCH;
        if self.global(local - 1) == global - 1 {
            s -= global * SUB_BATCH - total;
        }
        s
    }
}

/// A render's accumulated work, apart from its histogram (which may be larger than memory and
/// is read and written in bands of rows).
#[derive(Clone, Debug, PartialEq)]
pub struct RenderState {
    /// The flame as rendered: framed (`has_camera` set), quality of the whole render.
    pub flame: Flame,
    /// The render's seed.
    pub seed: u64,
    /// Number of parts the render was split into.
    pub part_count: u32,
    /// Indices of the parts this state holds, sorted.
    pub parts: Vec<u32>,
    /// Sub-batches of its part done, for a state of one part; 0 for a merge of several.
    pub batches_done: u64,
    /// Samples plotted so far.
    pub samples_done: u64,
    /// Bad values (orbits that left the plane and were restarted) met so far.
    pub bad_values: u64,
    /// Each worker's orbits (empty after a merge): a resume with as many threads continues
    /// the same orbits, so that it gives the picture of one longer render.
    pub lanes: Vec<LaneState>,
    /// Each worker's state of the flame's stateful variations (the orbit variations such as
    /// gingerbread_man, see `Chaos::variation_state`), for a flame that has some; empty
    /// otherwise and after a merge.
    pub var_states: Vec<Vec<f64>>,
    /// Samples of the render's range that are never drawn (a render in one part that finished
    /// on a partial sub-batch and was then extended goes on with whole sub-batches after it):
    /// the render's sub-batches cover the flame's samples plus these.
    pub gap: u64,
}

impl RenderState {
    /// Rows and columns of the bucket grid of the flame's histogram.
    pub fn grid(&self) -> Result<(usize, usize), String> {
        let de = crate::flame::density::DeFilters::shared(
            self.flame.estimator_radius,
            self.flame.estimator_minimum,
            self.flame.estimator_curve,
            self.flame.supersample.max(1),
        )
        .map_err(|e| e.to_string())?;
        let g = crate::flame::geometry::Geometry::new(&self.flame, de);
        Ok((g.bw, g.bh))
    }

    /// Sub-batches of the whole render at the flame's quality (with its gap).
    pub fn global_batches(&self) -> u64 {
        self.flame
            .total_samples()
            .max(1)
            .saturating_add(self.gap)
            .div_ceil(SUB_BATCH)
    }

    /// Has every sub-batch of the parts held been done?
    pub fn is_finished(&self) -> bool {
        match self.parts.as_slice() {
            [i] => {
                let p = Part {
                    index: *i,
                    count: self.part_count,
                };
                self.batches_done >= p.local_batches(self.global_batches())
            }
            _ => true,
        }
    }

    /// Finished, with every part.
    pub fn is_complete(&self) -> bool {
        self.is_finished() && self.parts.len() == self.part_count as usize
    }

    /// Samples per pixel for the log scale: the flame's quality·4^zoom when complete, else
    /// the samples actually done per pixel.
    pub fn density(&self) -> f64 {
        if self.is_complete() {
            self.flame.quality * 4f64.powf(self.flame.zoom)
        } else {
            let px = self.flame.width as f64 * self.flame.height as f64;
            self.samples_done.max(1) as f64 / px
        }
    }

    /// The part a resumed render works on and its next sub-batch: a state of one part goes on
    /// with that part; a complete state goes on as one render after the last sub-batch.
    pub fn continuation(&self) -> Result<(Part, u64), String> {
        match self.parts.as_slice() {
            [i] => Ok((
                Part {
                    index: *i,
                    count: self.part_count,
                },
                self.batches_done,
            )),
            _ if self.is_complete() => Ok((Part::default(), self.global_batches())),
            _ => Err(format!(
                "the state holds parts {} of {}; merge all the parts before resuming",
                list(&self.parts),
                self.part_count
            )),
        }
    }

    /// What makes `other` a different render (None: the same flame and settings, so the two
    /// can be summed). Parts and samples done are not compared.
    pub fn difference(&self, other: &RenderState) -> Option<String> {
        let (a, b) = (&self.flame, &other.flame);
        let d = |what: &str, x: String, y: String| Some(format!("{what} {x} vs {y}"));
        if (a.width, a.height) != (b.width, b.height) {
            return d(
                "image size",
                format!("{}x{}", a.width, a.height),
                format!("{}x{}", b.width, b.height),
            );
        }
        if a.supersample != b.supersample {
            return d(
                "supersample",
                a.supersample.to_string(),
                b.supersample.to_string(),
            );
        }
        if a.quality != b.quality {
            return d("quality", a.quality.to_string(), b.quality.to_string());
        }
        if self.seed != other.seed {
            return d("seed", self.seed.to_string(), other.seed.to_string());
        }
        if self.part_count != other.part_count {
            return d(
                "part count",
                self.part_count.to_string(),
                other.part_count.to_string(),
            );
        }
        if (a.filter, a.filter_shape) != (b.filter, b.filter_shape) {
            return d(
                "spatial filter",
                format!("{} {}", a.filter_shape.name(), a.filter),
                format!("{} {}", b.filter_shape.name(), b.filter),
            );
        }
        let de = |f: &Flame| (f.estimator_radius, f.estimator_minimum, f.estimator_curve);
        if de(a) != de(b) {
            return d(
                "density estimation (radius, minimum, curve)",
                format!("{:?}", de(a)),
                format!("{:?}", de(b)),
            );
        }
        if (a.center, a.scale, a.rotate, a.zoom) != (b.center, b.scale, b.rotate, b.zoom) {
            return d(
                "camera (center, scale, rotate, zoom)",
                format!("{:?}", (a.center, a.scale, a.rotate, a.zoom)),
                format!("{:?}", (b.center, b.scale, b.rotate, b.zoom)),
            );
        }
        if a.xforms.len() != b.xforms.len() {
            return d(
                "number of xforms",
                a.xforms.len().to_string(),
                b.xforms.len().to_string(),
            );
        }
        if let Some(k) = (0..a.xforms.len()).find(|&k| a.xforms[k] != b.xforms[k]) {
            return Some(format!("xform {} differs", k + 1));
        }
        if a.final_xform != b.final_xform || a.more_finals != b.more_finals {
            return Some("the final xform differs".into());
        }
        if a.palette != b.palette || a.palette_mode != b.palette_mode {
            return Some("the palette differs".into());
        }
        if a != b {
            return Some("the flames differ (colouring or tone settings)".into());
        }
        None
    }

    /// The state of a sum of disjoint finished states of the same render (see
    /// [`RenderState::difference`]): the parts united, samples added. Errors name the
    /// offending state by its position in `states`.
    pub fn merged(states: &[&RenderState]) -> Result<RenderState, MergeError> {
        let Some(first) = states.first() else {
            return Err(MergeError {
                index: 0,
                message: "nothing to merge".into(),
            });
        };
        let mut parts: Vec<(u32, usize)> = Vec::new();
        let (mut samples, mut bad) = (0u64, 0u64);
        for (k, s) in states.iter().enumerate() {
            if let Some(diff) = first.difference(s) {
                return Err(MergeError {
                    index: k,
                    message: format!("is a different render: {diff}"),
                });
            }
            if !s.is_finished() {
                return Err(MergeError {
                    index: k,
                    message: format!(
                        "is unfinished ({} samples done); resume it to the end first",
                        s.samples_done
                    ),
                });
            }
            for &p in &s.parts {
                if let Some(&(_, other)) = parts.iter().find(|(q, _)| *q == p) {
                    return Err(MergeError {
                        index: k,
                        message: format!(
                            "holds part {p}/{}, as input {} does",
                            s.part_count,
                            other + 1
                        ),
                    });
                }
                parts.push((p, k));
            }
            samples += s.samples_done;
            bad += s.bad_values;
        }
        let mut parts: Vec<u32> = parts.into_iter().map(|(p, _)| p).collect();
        parts.sort_unstable();
        let mut out = RenderState {
            flame: first.flame.clone(),
            seed: first.seed,
            part_count: first.part_count,
            parts,
            batches_done: 0,
            samples_done: samples,
            bad_values: bad,
            lanes: Vec::new(),
            var_states: Vec::new(),
            // Only a render in one part has a gap, and its one state is the whole render.
            gap: if states.len() == 1 { first.gap } else { 0 },
        };
        if out.parts.len() == out.part_count as usize {
            // Every sub-batch is done: from now on one render of one part.
            out.batches_done = out.global_batches();
            out.part_count = 1;
            out.parts = vec![0];
        }
        Ok(out)
    }
}

/// Why states cannot be merged: `index` is the position of the offending state.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MergeError {
    pub index: usize,
    pub message: String,
}

/// "0, 1, 3".
fn list(v: &[u32]) -> String {
    v.iter()
        .map(|p| p.to_string())
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parts_share_every_sub_batch_once() {
        for total in [1u64, 9_999, 10_000, 10_001, 123_456, 1_000_000] {
            for n in [1u32, 2, 3, 4, 7] {
                let sum: u64 = (0..n)
                    .map(|i| Part { index: i, count: n }.samples(total))
                    .sum();
                assert_eq!(sum, total, "total {total}, {n} parts");
                let global = total.div_ceil(SUB_BATCH);
                let batches: u64 = (0..n)
                    .map(|i| Part { index: i, count: n }.local_batches(global))
                    .sum();
                assert_eq!(batches, global);
            }
        }
        assert!(Part { index: 4, count: 4 }.validate().is_err());
        assert!(Part { index: 0, count: 0 }.validate().is_err());
        assert_eq!(Part { index: 2, count: 4 }.global(3), 14);
    }
}
