//! The quadratic lane engine: z ← z² + c for 8 points at a time, 8 unchecked iterations per
//! block (plain f64 arrays the compiler vectorises; AVX2 when the CPU has it, without FMA so
//! results equal the scalar code bit for bit). A lane that escaped inside a block is replayed
//! in scalar code from the block's start to find its exact count and z; a finished lane is
//! refilled with the next point at once. Periodicity is checked at block boundaries.

use super::complex::C;
use super::family::{IterSettings, Sample, smooth_count};

const L: usize = 8;
const BLOCK: u32 = 8;
const NONE: u32 = u32::MAX;

/// How a point starts.
pub enum Start {
    Iterate {
        z: C,
        c: C,
    },
    /// Known inside (cardioid, bulb).
    Inside,
    /// Escaped before the first iteration (e.g. a warp pole).
    Escaped0,
}

#[inline(always)]
fn block_generic(zx: &mut [f64; L], zy: &mut [f64; L], cx: &[f64; L], cy: &[f64; L]) {
    for _ in 0..BLOCK {
        for l in 0..L {
            let (x, y) = (zx[l], zy[l]);
            let x2 = x * x;
            let y2 = y * y;
            zy[l] = (x + x) * y + cy[l];
            zx[l] = x2 - y2 + cx[l];
        }
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn block_avx2(zx: &mut [f64; L], zy: &mut [f64; L], cx: &[f64; L], cy: &[f64; L]) {
    block_generic(zx, zy, cx, cy)
}

fn block(avx2: bool, zx: &mut [f64; L], zy: &mut [f64; L], cx: &[f64; L], cy: &[f64; L]) {
    #[cfg(target_arch = "x86_64")]
    if avx2 {
        // SAFETY: `avx2` is true only when the CPU reports AVX2 (see `has_avx2`).
        unsafe { block_avx2(zx, zy, cx, cy) };
        return;
    }
    let _ = avx2;
    block_generic(zx, zy, cx, cy)
}

/// Whether the AVX2 block can be used on this CPU.
pub fn has_avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Iterate every point of `points` (opaque ids) and report each sample through `out`.
/// Smooth counts use degree 2. Distance estimation is not computed here (use the scalar path).
pub fn run(
    s: &IterSettings,
    points: impl IntoIterator<Item = u32>,
    start: impl Fn(u32) -> Start,
    mut out: impl FnMut(u32, Sample),
) {
    let avx2 = has_avx2();
    let escaped = |r2: f64| {
        if s.strict {
            !(r2 <= s.bailout2)
        } else {
            !(r2 < s.bailout2)
        }
    };
    let mut it = points.into_iter();
    let mut exhausted = false;
    let (mut zx, mut zy, mut cx, mut cy) = ([0.0f64; L], [0.0f64; L], [0.0f64; L], [0.0f64; L]);
    let (mut sx, mut sy) = ([0.0f64; L], [0.0f64; L]);
    let mut n = [0u32; L];
    let mut next_save = [0u32; L];
    let mut id = [NONE; L];
    loop {
        // Refill empty lanes.
        for l in 0..L {
            while id[l] == NONE && !exhausted {
                let Some(p) = it.next() else {
                    exhausted = true;
                    break;
                };
                match start(p) {
                    Start::Inside => out(p, Sample::inside(s.max_iter)),
                    Start::Escaped0 => out(p, Sample::escaped_at_zero()),
                    Start::Iterate { z, c } => {
                        (zx[l], zy[l], cx[l], cy[l]) = (z.re, z.im, c.re, c.im);
                        (sx[l], sy[l]) = (z.re, z.im);
                        n[l] = 0;
                        next_save[l] = BLOCK * 2;
                        id[l] = p;
                    }
                }
            }
        }
        if id.iter().all(|&i| i == NONE) {
            return;
        }
        let (bx, by) = (zx, zy);
        block(avx2, &mut zx, &mut zy, &cx, &cy);
        for l in 0..L {
            if id[l] == NONE {
                continue;
            }
            let r2 = zx[l] * zx[l] + zy[l] * zy[l];
            let mut finished = None;
            if escaped(r2) {
                // Replay the block in scalar code for the exact escape iteration and z.
                let (mut x, mut y) = (bx[l], by[l]);
                let mut k = 0;
                let mut rr = x * x + y * y;
                while k < BLOCK {
                    let x2 = x * x;
                    let y2 = y * y;
                    y = (x + x) * y + cy[l];
                    x = x2 - y2 + cx[l];
                    k += 1;
                    rr = x * x + y * y;
                    if escaped(rr) {
                        break;
                    }
                }
                let total = n[l] + k;
                finished = Some(if total > s.max_iter {
                    Sample::inside(s.max_iter)
                } else {
                    Sample {
                        n: total,
                        inside: false,
                        nu: smooth_count(total, rr, 2.0),
                        de: 0.0,
                        root: 255,
                    }
                });
            } else {
                n[l] += BLOCK;
                if n[l] >= s.max_iter {
                    finished = Some(Sample::inside(s.max_iter));
                } else if s.period_tol > 0.0 {
                    if n[l] >= next_save[l] {
                        (sx[l], sy[l]) = (zx[l], zy[l]);
                        next_save[l] = next_save[l].saturating_mul(2);
                    } else if (zx[l] - sx[l]).abs() < s.period_tol
                        && (zy[l] - sy[l]).abs() < s.period_tol
                    {
                        finished = Some(Sample::inside(s.max_iter));
                    }
                }
            }
            if let Some(sample) = finished {
                out(id[l], sample);
                id[l] = NONE;
                (zx[l], zy[l], cx[l], cy[l]) = (0.0, 0.0, 0.0, 0.0);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::escape::family::{Family, iterate_point};

    #[test]
    fn lanes_equal_the_scalar_iteration() {
        let s = IterSettings {
            max_iter: 301,
            bailout2: 256.0 * 256.0,
            strict: true,
            period_tol: 0.0,
            want_de: false,
        };
        let m = Family::Mandelbrot { power: 2 };
        let pts: Vec<C> = (0..4000)
            .map(|k| {
                C::new(
                    -2.2 + (k % 80) as f64 * 0.035,
                    -1.3 + (k / 80) as f64 * 0.052,
                )
            })
            .collect();
        let mut got = vec![Sample::default(); pts.len()];
        run(
            &s,
            0..pts.len() as u32,
            |i| Start::Iterate {
                z: C::ZERO,
                c: pts[i as usize],
            },
            |i, smp| got[i as usize] = smp,
        );
        for (p, g) in pts.iter().zip(&got) {
            let mut w = iterate_point(&m, *p, &s);
            if crate::escape::family::in_cardioid_or_bulb(p.re, p.im) {
                w = Sample::inside(s.max_iter);
            }
            assert_eq!((g.n, g.inside), (w.n, w.inside), "{p:?}");
            if !g.inside {
                assert_eq!(g.nu, w.nu, "{p:?}");
            }
        }
    }
}
