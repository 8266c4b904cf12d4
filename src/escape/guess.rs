//! Mariani–Silver block filling: a rectangle whose border agrees is filled without computing
//! its inside; any other splits in four, down to small blocks computed pixel by pixel.

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use super::family::Sample;
use super::job::Job;

/// Mariani–Silver: rectangles whose border has one integer count (or is all inside; with
/// smooth colourings only all-inside borders) are filled; others split in four down to 4×4.
pub(super) fn mariani_silver(job: &Job, samples: &mut [Sample], cancel: &AtomicBool) -> bool {
    const TILE: u32 = 64;
    let (w, h) = (job.w, job.h);
    let tiles: Vec<(u32, u32)> = (0..h)
        .step_by(TILE as usize)
        .flat_map(|y| (0..w).step_by(TILE as usize).map(move |x| (x, y)))
        .collect();
    let results: Vec<Option<Vec<(u32, Sample)>>> = tiles
        .par_iter()
        .map(|&(x0, y0)| {
            if cancel.load(Ordering::Relaxed) {
                return None;
            }
            let (x1, y1) = ((x0 + TILE).min(w), (y0 + TILE).min(h));
            let tw = x1 - x0;
            let mut local: Vec<Option<Sample>> = vec![None; (tw * (y1 - y0)) as usize];
            let smooth = job.params.coloring.smooth();
            let mut stack = vec![(x0, y0, x1, y1)];
            while let Some((a, b, c, d)) = stack.pop() {
                // The border pixels not known yet.
                let mut border = Vec::new();
                for i in a..c {
                    border.push((i, b));
                    if d - 1 > b {
                        border.push((i, d - 1));
                    }
                }
                for j in b + 1..d.saturating_sub(1) {
                    border.push((a, j));
                    if c - 1 > a {
                        border.push((c - 1, j));
                    }
                }
                let todo: Vec<(u32, u32)> = border
                    .iter()
                    .copied()
                    .filter(|&(i, j)| local[((j - y0) * tw + i - x0) as usize].is_none())
                    .collect();
                for (k, s) in job.compute_list(&todo).into_iter().enumerate() {
                    let (i, j) = todo[k];
                    local[((j - y0) * tw + i - x0) as usize] = Some(s);
                }
                let first = local[((b - y0) * tw + a - x0) as usize].unwrap_or_default();
                let same = border.iter().all(|&(i, j)| {
                    let s = local[((j - y0) * tw + i - x0) as usize].unwrap_or_default();
                    if smooth {
                        s.inside && first.inside
                    } else {
                        s.inside == first.inside && s.n == first.n
                    }
                });
                if same && c - a > 2 && d - b > 2 {
                    for j in b + 1..d - 1 {
                        for i in a + 1..c - 1 {
                            let slot = &mut local[((j - y0) * tw + i - x0) as usize];
                            if slot.is_none() {
                                *slot = Some(first);
                            }
                        }
                    }
                } else if c - a <= 4 || d - b <= 4 {
                    let rest: Vec<(u32, u32)> = (b..d)
                        .flat_map(|j| (a..c).map(move |i| (i, j)))
                        .filter(|&(i, j)| local[((j - y0) * tw + i - x0) as usize].is_none())
                        .collect();
                    for (k, s) in job.compute_list(&rest).into_iter().enumerate() {
                        let (i, j) = rest[k];
                        local[((j - y0) * tw + i - x0) as usize] = Some(s);
                    }
                } else {
                    let (mx, my) = ((a + c) / 2, (b + d) / 2);
                    stack.push((a, b, mx + 1, my + 1));
                    stack.push((mx, b, c, my + 1));
                    stack.push((a, my, mx + 1, d));
                    stack.push((mx, my, c, d));
                }
            }
            Some(
                local
                    .into_iter()
                    .enumerate()
                    .map(|(k, s)| {
                        let (i, j) = (x0 + k as u32 % tw, y0 + k as u32 / tw);
                        (j * w + i, s.unwrap_or_default())
                    })
                    .collect(),
            )
        })
        .collect();
    for r in results {
        let Some(v) = r else { return false };
        for (k, s) in v {
            samples[k as usize] = s;
        }
    }
    true
}
