//! Rendering escape-time views: progressive coarse-to-fine passes over parallel rows (or one
//! pass of Mariani–Silver block filling), and colouring the samples into an image. The view,
//! the parameters and their checks are re-exported here from the modules that hold them.

use std::sync::atomic::{AtomicBool, Ordering};

use image::RgbImage;
use rayon::prelude::*;

use super::color::{Coloring, Colorizer, CountHistogram};
use super::family::Sample;
use super::guess::mariani_silver;
use super::job::Job;

pub use super::params::{
    DEEP_LIMIT_EXP10, EscapeError, EscapeParams, Fill, check_memory, check_view_for,
    estimate_memory, is_deep,
};
pub use super::view::View;

/// Progressive passes: pixel steps 8, 4, 2, 1 (each pass adds the pixels of its grid that the
/// coarser ones did not compute).
const STEPS: [u32; 4] = [8, 4, 2, 1];

/// A progressive escape-time render.
pub struct EscapeRenderer {
    job: Job,
    samples: Vec<Sample>,
    pass: usize,
    cancelled: bool,
}

impl EscapeRenderer {
    /// Check the view, the settings and the memory and prepare a render of `w`×`h` pixels (nothing
    /// computed yet).
    pub fn new(params: &EscapeParams, view: View, w: u32, h: u32) -> Result<Self, EscapeError> {
        let job = Job::new(params, view, w, h)?;
        Ok(EscapeRenderer {
            samples: vec![Sample::default(); w as usize * h as usize],
            job,
            pass: 0,
            cancelled: false,
        })
    }

    /// Number of passes the render takes (4 coarse-to-fine passes, 1 with block filling).
    pub fn passes(&self) -> usize {
        if self.job.params.fill == Fill::Guess {
            1
        } else {
            STEPS.len()
        }
    }

    /// Whether every pass has run, or the render was cancelled.
    pub fn is_done(&self) -> bool {
        self.pass >= self.passes() || self.cancelled
    }

    /// Fraction of the passes done (0–1).
    pub fn fraction(&self) -> f64 {
        self.pass as f64 / self.passes() as f64
    }

    /// The samples computed so far, row by row from the top.
    pub fn samples(&self) -> &[Sample] {
        &self.samples
    }

    /// Picture size (width, height) in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.job.w, self.job.h)
    }

    /// Run the next pass on the rayon pool. Returns false when cancelled (checked per row).
    pub fn run_pass(&mut self, cancel: &AtomicBool) -> bool {
        if self.is_done() {
            return !self.cancelled;
        }
        let (w, h) = (self.job.w, self.job.h);
        let job = &self.job;
        if job.params.fill == Fill::Guess && job.newton.is_none() {
            self.cancelled = !mariani_silver(job, &mut self.samples, cancel);
            self.pass = self.passes();
            return !self.cancelled;
        }
        let step = if job.params.fill == Fill::Guess {
            1
        } else {
            STEPS[self.pass]
        };
        let first = self.pass == 0 || job.params.fill == Fill::Guess;
        let stopped = AtomicBool::new(false);
        self.samples
            .par_chunks_mut(w as usize)
            .enumerate()
            .for_each(|(j, row)| {
                let j = j as u32;
                if !j.is_multiple_of(step) || stopped.load(Ordering::Relaxed) {
                    return;
                }
                if cancel.load(Ordering::Relaxed) {
                    stopped.store(true, Ordering::Relaxed);
                    return;
                }
                let coarse_row = j.is_multiple_of(2 * step);
                let cols = (0..w)
                    .step_by(step as usize)
                    .filter(move |i| first || !(coarse_row && i % (2 * step) == 0));
                job.compute_row(j, cols, row);
            });
        let _ = h;
        if stopped.load(Ordering::Relaxed) {
            self.cancelled = true;
            return false;
        }
        self.pass += 1;
        true
    }

    /// Compute every pixel not computed yet in one pass at full resolution (no coarse
    /// preview), calling `on_pixels(n)` as rows of n pixels finish (from worker threads).
    /// Returns false when cancelled (checked per row). Mariani–Silver filling runs its own
    /// single pass.
    pub fn run_exact(&mut self, cancel: &AtomicBool, on_pixels: &(dyn Fn(u64) + Sync)) -> bool {
        if self.is_done() {
            return !self.cancelled;
        }
        if self.job.params.fill == Fill::Guess {
            return self.run_pass(cancel);
        }
        let w = self.job.w;
        let job = &self.job;
        let stopped = AtomicBool::new(false);
        self.samples
            .par_chunks_mut(w as usize)
            .enumerate()
            .for_each(|(j, row)| {
                if stopped.load(Ordering::Relaxed) {
                    return;
                }
                if cancel.load(Ordering::Relaxed) {
                    stopped.store(true, Ordering::Relaxed);
                    return;
                }
                job.compute_row(j as u32, 0..w, row);
                on_pixels(w as u64);
            });
        if stopped.load(Ordering::Relaxed) {
            self.cancelled = true;
            return false;
        }
        self.pass = STEPS.len();
        true
    }

    /// Run every remaining pass.
    pub fn run_all(&mut self, cancel: &AtomicBool) -> bool {
        while !self.is_done() {
            if !self.run_pass(cancel) {
                return false;
            }
        }
        true
    }

    /// The picture as it stands: pixels not computed yet take the colour of their pass's
    /// block leader.
    pub fn image(&self) -> RgbImage {
        let (w, h) = (self.job.w, self.job.h);
        let step = if self.pass == 0 || self.job.params.fill == Fill::Guess {
            if self.pass == 0 { STEPS[0] } else { 1 }
        } else {
            STEPS[self.pass - 1]
        };
        colorize(&self.job, &self.samples, step).unwrap_or_else(|| RgbImage::new(w, h))
    }
}

/// Colour the samples (block leaders of `step`-sized blocks stand in for the others).
fn colorize(job: &Job, samples: &[Sample], step: u32) -> Option<RgbImage> {
    let (w, h) = (job.w, job.h);
    let histogram = (job.params.coloring == Coloring::Histogram).then(|| {
        if step == 1 {
            CountHistogram::new(samples, job.params.max_iter)
        } else {
            let leaders: Vec<Sample> = (0..h)
                .step_by(step as usize)
                .flat_map(|j| (0..w).step_by(step as usize).map(move |i| (i, j)))
                .map(|(i, j)| samples[(j * w + i) as usize])
                .collect();
            CountHistogram::new(&leaders, job.params.max_iter)
        }
    });
    let roots = job.newton.as_ref().map_or(0, |n| n.roots.len());
    let cz = Colorizer {
        coloring: job.params.coloring,
        palette: &job.params.palette,
        // Deep views estimate distances in pixels.
        pixel: if job.reference.is_some() {
            1.0
        } else {
            job.view.pixel_size(h)
        },
        roots,
        histogram,
    };
    let mut buf = vec![0u8; w as usize * h as usize * 3];
    buf.par_chunks_mut(w as usize * 3)
        .enumerate()
        .for_each(|(j, row)| {
            let jl = j as u32 - j as u32 % step;
            for i in 0..w {
                let il = i - i % step;
                let c = cz.color(&samples[(jl * w + il) as usize]);
                row[i as usize * 3..i as usize * 3 + 3].copy_from_slice(&c);
            }
        });
    RgbImage::from_raw(w, h, buf)
}

/// Render to the end: the image and the samples.
pub fn render(
    params: &EscapeParams,
    view: View,
    w: u32,
    h: u32,
) -> Result<(RgbImage, Vec<Sample>), EscapeError> {
    let mut r = EscapeRenderer::new(params, view, w, h)?;
    let never = AtomicBool::new(false);
    if params.fill == Fill::Exact {
        // One full pass (no coarse grid needed).
        r.run_exact(&never, &|_| {});
    } else {
        r.run_all(&never);
    }
    let img = colorize(&r.job, &r.samples, 1).expect("image size");
    Ok((img, r.samples))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::escape::complex::C;
    use crate::escape::dd::Dd;
    use crate::escape::family::{Family, IterSettings, iterate_point};
    use crate::escape::warp::{Preset, Warp};

    #[test]
    fn perturbation_render_agrees_with_f64_where_both_work() {
        // Pixel 4e-13: below the perturbation threshold, above the f64 limit.
        let mut p = EscapeParams::new(Family::Mandelbrot { power: 2 });
        p.max_iter = 3000;
        p.periodicity = false;
        let view = View::new([-0.743643887037151, 0.131825904205330], 8e-12);
        let (w, h) = (48, 36);
        assert!(is_deep(&p.family, &view, h));
        let (_, samples) = render(&p, view.clone(), w, h).unwrap();
        let s = IterSettings {
            max_iter: p.max_iter,
            bailout2: p.bailout() * p.bailout(),
            strict: true,
            period_tol: 0.0,
            want_de: false,
        };
        // The truth: every pixel iterated directly in double-double arithmetic. (Plain f64
        // iteration is already unreliable here: thousands of iterations amplify its rounding.)
        let direct_dd = |c: [Dd; 2]| -> u32 {
            let (mut x, mut y) = (Dd::ZERO, Dd::ZERO);
            for n in 1..=s.max_iter {
                let (xx, yy, xy) = (x * x, y * y, x * y);
                x = xx - yy + c[0];
                y = xy + xy + c[1];
                if !(x.to_f64().powi(2) + y.to_f64().powi(2) <= s.bailout2) {
                    return n;
                }
            }
            s.max_iter
        };
        let (mut same, mut same_f64) = (0, 0);
        let [cx, cy] = view.center_dd();
        for j in 0..h {
            for i in 0..w {
                let o = view.offset_from_pixel(i as f64, j as f64, w, h);
                let truth = direct_dd([cx + Dd::from_f64(o.re), cy + Dd::from_f64(o.im)]);
                let got = samples[(j * w + i) as usize];
                same += (got.n == truth) as u32;
                let c = view.world_from_pixel(i as f64, j as f64, w, h);
                same_f64 += (iterate_point(&p.family, c, &s).n == truth) as u32;
            }
        }
        assert!(same * 100 >= w * h * 99, "{same} of {}", w * h);
        assert!(
            same >= same_f64,
            "perturbation {same}, plain f64 {same_f64}"
        );
    }

    fn count_grid(params: &EscapeParams, w: u32, h: u32) -> Vec<(u32, bool)> {
        let (view_c, hh) = params.family.default_view();
        let view = View::new(view_c, hh);
        render(params, view, w, h)
            .unwrap()
            .1
            .iter()
            .map(|s| (s.n, s.inside))
            .collect()
    }

    #[test]
    fn progressive_passes_and_full_render_agree() {
        let mut p = EscapeParams::new(Family::Mandelbrot { power: 2 });
        p.coloring = Coloring::Bands;
        let view = View::new([-0.7, 0.0], 1.25);
        let (img, samples) = render(&p, view.clone(), 97, 61).unwrap();
        let mut r = EscapeRenderer::new(&p, view.clone(), 97, 61).unwrap();
        let never = AtomicBool::new(false);
        let mut frames = 0;
        while !r.is_done() {
            assert!(r.run_pass(&never));
            let _ = r.image();
            frames += 1;
        }
        assert_eq!(frames, 4);
        assert_eq!(r.samples(), &samples[..]);
        assert_eq!(r.image(), img);
        // Cancelling stops at once.
        let mut r2 = EscapeRenderer::new(&p, view, 97, 61).unwrap();
        assert!(!r2.run_pass(&AtomicBool::new(true)));
        assert!(r2.is_done());
    }

    #[test]
    fn block_filling_agrees_with_the_full_computation() {
        // Default view, 256×256, n_max 256, integer colouring: ≥ 99.9 % of pixels agree.
        let mut p = EscapeParams::new(Family::Mandelbrot { power: 2 });
        p.coloring = Coloring::Bands;
        p.max_iter = 256;
        let exact = count_grid(&p, 256, 256);
        p.fill = Fill::Guess;
        let guessed = count_grid(&p, 256, 256);
        let same = exact.iter().zip(&guessed).filter(|(a, b)| a == b).count();
        let frac = same as f64 / exact.len() as f64;
        assert!(frac >= 0.999, "{frac}");
        // Periodicity checking does not change the picture either.
        p.fill = Fill::Exact;
        p.periodicity = false;
        let slow = count_grid(&p, 256, 256);
        let same = exact.iter().zip(&slow).filter(|(a, b)| a == b).count();
        assert!(same as f64 / exact.len() as f64 >= 0.999);
    }

    #[test]
    fn warped_texture_seam_symmetry_and_pole() {
        let (w, h) = (256u32, 128u32);
        let texture = |warp: Warp| {
            let mut p = EscapeParams::new(Family::WarpedJulia(warp));
            p.max_iter = 256;
            render(&p, View::new([0.5, 0.5], 0.5), w, h).unwrap().1
        };
        let plain = texture(Warp::preset(Preset::PolarJulia));
        let pairs = |t: &[Sample]| {
            let mut eq = 0;
            for j in 0..h {
                for i in 0..w / 2 {
                    let a = t[(j * w + i) as usize];
                    let b = t[(j * w + i + w / 2) as usize];
                    eq += (a.n == b.n && a.inside == b.inside) as u32;
                }
            }
            eq as f64 / (w * h / 2) as f64
        };
        let sym = pairs(&plain);
        assert!(
            sym >= 0.999,
            "unwarped polar texture: t(u, v) = t(u + ½, v) for {sym}"
        );
        let warped = texture(Warp::preset(Preset::WarpedJulia));
        let broken = pairs(&warped);
        assert!(broken < 0.5, "the warp breaks the symmetry: {broken}");
        // Seam: the last column continues into the first like any two neighbours.
        for t in [&plain, &warped, &texture(Warp::preset(Preset::Galaxy))] {
            let diff = |a: u32, b: u32| {
                (0..h)
                    .map(|j| {
                        (t[(j * w + a) as usize].n as f64 - t[(j * w + b) as usize].n as f64).abs()
                    })
                    .sum::<f64>()
            };
            let seam = diff(w - 1, 0);
            let typical = (1..w).map(|i| diff(i - 1, i)).sum::<f64>() / (w - 1) as f64;
            assert!(
                seam <= 3.0 * typical + 1.0,
                "seam {seam} vs typical {typical}"
            );
        }
        // A pole inside the image: finite output, those texels escape at 0.
        let pole = Warp::new(
            C::new(-0.8, 0.156),
            C::new(2.0, 0.0),
            0.0,
            Default::default(),
            crate::escape::warp::Sampling::Rect { scale: 3.0 },
            false,
        )
        .unwrap();
        let mut p = EscapeParams::new(Family::WarpedJulia(pole));
        p.max_iter = 64;
        let (img, s) = render(&p, View::new([0.5, 0.5], 0.5), 64, 64).unwrap();
        assert_eq!(img.width(), 64);
        assert!(s.iter().all(|s| s.nu.is_finite()));
    }
}
