//! Rendering escape-time views: the view geometry, parallel rows, the lane
//! engine for quadratic families, progressive coarse-to-fine passes, optional Mariani–Silver
//! block filling, and colouring into an image.

use std::sync::atomic::{AtomicBool, Ordering};

use image::RgbImage;
use rayon::prelude::*;

use super::color::{Coloring, Colorizer, CountHistogram, Palette};
use super::complex::C;
use super::dd::Dd;
use super::deep;
use super::family::{
    Family, IterSettings, NewtonSystem, Sample, in_cardioid_or_bulb, iterate_point,
    iterate_quadratic_scalar,
};
use super::lanes::{self, Start};

/// The visible rectangle: centre and half-height (the width follows the image's aspect).
/// The centre is the double-double `center + center_lo` (the low parts are zero until a
/// deep zoom needs them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    pub center: [f64; 2],
    pub center_lo: [f64; 2],
    pub half_height: f64,
}

/// Relative pixel size below which the Mandelbrot set is drawn by perturbation.
pub const DEEP_BELOW: f64 = 1e-12;
/// Relative pixel size limits: f64 arithmetic, and perturbation around a double-double centre.
pub const F64_LIMIT: f64 = 1e-13;
pub const DD_LIMIT: f64 = 1e-28;

impl View {
    pub fn new(center: [f64; 2], half_height: f64) -> View {
        View {
            center,
            center_lo: [0.0; 2],
            half_height,
        }
    }

    /// A view from Fractint-style corners.
    pub fn from_corners(xmin: f64, xmax: f64, ymin: f64, ymax: f64) -> View {
        View::new(
            [(xmin + xmax) / 2.0, (ymin + ymax) / 2.0],
            (ymax - ymin).abs() / 2.0,
        )
    }

    /// The centre to double-double precision.
    pub fn center_dd(&self) -> [Dd; 2] {
        [
            Dd::new(self.center[0], self.center_lo[0]),
            Dd::new(self.center[1], self.center_lo[1]),
        ]
    }

    /// A view with the given double-double centre.
    pub fn with_center_dd(&self, c: [Dd; 2]) -> View {
        View {
            center: [c[0].hi, c[1].hi],
            center_lo: [c[0].lo, c[1].lo],
            half_height: self.half_height,
        }
    }

    /// The view moved by (dx, dy) world units, exactly to double-double precision.
    pub fn shifted(&self, dx: f64, dy: f64) -> View {
        let [x, y] = self.center_dd();
        self.with_center_dd([x + Dd::from_f64(dx), y + Dd::from_f64(dy)])
    }

    /// Offset of pixel (i, j) from the centre, in world units.
    pub fn offset_from_pixel(&self, i: f64, j: f64, w: u32, h: u32) -> C {
        let (w, h) = (w as f64, h as f64);
        C::new(
            (2.0 * (i + 0.5) / w - 1.0) * self.half_height * w / h,
            -(2.0 * (j + 0.5) / h - 1.0) * self.half_height,
        )
    }

    /// World point of pixel (i, j), rows from the top; the imaginary axis points up.
    pub fn world_from_pixel(&self, i: f64, j: f64, w: u32, h: u32) -> C {
        let o = self.offset_from_pixel(i, j, w, h);
        C::new(self.center[0] + o.re, self.center[1] + o.im)
    }

    /// Where `other`'s centre lies from this view's, in world units (double-double
    /// difference, so it is exact at deep zoom too).
    pub fn offset_to(&self, other: &View) -> C {
        let [a, b] = self.center_dd();
        let [c, d] = other.center_dd();
        C::new((c - a).to_f64(), (d - b).to_f64())
    }

    /// Pixel coordinates (continuous, the pixel's centre at i + 0.5) of a world point.
    pub fn pixel_from_world(&self, p: C, w: u32, h: u32) -> [f64; 2] {
        let (wf, hf) = (w as f64, h as f64);
        let i = ((p.re - self.center[0]) / (self.half_height * wf / hf) + 1.0) * wf / 2.0;
        let j = (1.0 - (p.im - self.center[1]) / self.half_height) * hf / 2.0;
        [i, j]
    }

    /// Pixel coordinates in this view of pixel (i, j) of `other` (same image size), computed
    /// from the double-double difference of the centres (valid at deep zoom).
    pub fn pixel_of(&self, other: &View, i: f64, j: f64, w: u32, h: u32) -> [f64; 2] {
        let o = self.offset_to(other) + other.offset_from_pixel(i, j, w, h);
        let (wf, hf) = (w as f64, h as f64);
        [
            (o.re / (self.half_height * wf / hf) + 1.0) * wf / 2.0,
            (1.0 - o.im / self.half_height) * hf / 2.0,
        ]
    }

    /// World size of one pixel.
    pub fn pixel_size(&self, h: u32) -> f64 {
        2.0 * self.half_height / h.max(1) as f64
    }

    /// The view zoomed by `factor` (> 1 zooms in) keeping the world point under pixel
    /// (i, j) fixed.
    pub fn zoomed_at(&self, i: f64, j: f64, w: u32, h: u32, factor: f64) -> View {
        let o = self.offset_from_pixel(i - 0.5, j - 0.5, w, h);
        let k = 1.0 - 1.0 / factor;
        View {
            half_height: self.half_height / factor,
            ..self.shifted(o.re * k, o.im * k)
        }
    }
}

/// Block filling.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Fill {
    /// Every pixel computed (the default).
    #[default]
    Exact,
    /// Mariani–Silver rectangles: filled when their whole border agrees (not for Newton).
    Guess,
}

/// Everything that defines an escape-time picture except its size and view.
#[derive(Clone, Debug, PartialEq)]
pub struct EscapeParams {
    pub family: Family,
    pub max_iter: u32,
    pub coloring: Coloring,
    /// Escape radius; None: the family's default for the colouring.
    pub bailout: Option<f64>,
    pub periodicity: bool,
    pub fill: Fill,
    pub palette: Palette,
}

impl EscapeParams {
    pub fn new(family: Family) -> EscapeParams {
        let coloring = if matches!(family, Family::Newton { .. }) {
            Coloring::Basins
        } else if matches!(family, Family::WarpedJulia(_)) {
            Coloring::Bands
        } else {
            Coloring::Smooth
        };
        // Four gradient entries per iteration spread the outside over the whole gradient
        // (with one, the first few dozen iterations use a fifth of it).
        let repeat = if coloring == Coloring::Basins {
            1.0
        } else {
            4.0
        };
        EscapeParams {
            family,
            max_iter: 256,
            coloring,
            bailout: None,
            periodicity: true,
            fill: Fill::Exact,
            palette: Palette {
                repeat,
                ..Palette::default()
            },
        }
    }

    pub fn bailout(&self) -> f64 {
        self.bailout
            .unwrap_or_else(|| self.family.default_bailout(self.coloring.smooth()))
    }
}

/// Why a view cannot be rendered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EscapeError {
    #[error(
        "zoomed in to the limit of 64-bit floating point (pixel {pixel:.3e} at |centre| {scale:.3e}); \
         zoom out (deep zoom is available for z² + c: the Mandelbrot set and its Julia sets)"
    )]
    PrecisionLimit { pixel: f64, scale: f64 },
    #[error(
        "zoomed in to the deep-zoom limit (pixel {pixel:.3e} at |centre| {scale:.3e}, \
         double-double precision); zoom out"
    )]
    DeepLimit { pixel: f64, scale: f64 },
    #[error("image size {0}x{1} must be between 1x1 and 30000x30000")]
    BadSize(u32, u32),
    #[error("{0}")]
    Settings(String),
    #[error(transparent)]
    OutOfMemory(#[from] crate::memory::MemoryError),
}

/// Bytes an escape-time render of `w`×`h` needs, before anything is allocated: one sample per
/// pixel, the RGB image and the copy made while encoding it, the reference orbit of a deep
/// zoom (up to `max_iter` points, twice with a critical orbit) and the iteration-count table
/// of histogram colouring.
pub fn estimate_memory(params: &EscapeParams, view: &View, w: u32, h: u32) -> u64 {
    let px = w as u64 * h as u64;
    let samples = px * std::mem::size_of::<Sample>() as u64;
    let image = px * 3 * 2;
    let iters = params.max_iter as u64 + 2;
    let orbit = if is_deep(&params.family, view, h) {
        2 * iters * std::mem::size_of::<C>() as u64
    } else {
        0
    };
    let histogram = if params.coloring == Coloring::Histogram {
        iters * 16
    } else {
        0
    };
    samples + image + orbit + histogram
}

/// Refuse an escape-time render that does not fit in memory (see [`crate::memory`]).
pub fn check_memory(
    params: &EscapeParams,
    view: &View,
    w: u32,
    h: u32,
    configured: Option<u64>,
) -> Result<u64, EscapeError> {
    let need = estimate_memory(params, view, w, h);
    crate::memory::check(
        need,
        configured,
        || format!("a {w}×{h} escape-time render"),
        || {
            let mut hint = String::from("reduce the image size");
            if params.coloring == Coloring::Histogram || is_deep(&params.family, view, h) {
                hint.push_str(&format!(" or the maximum iterations ({})", params.max_iter));
            }
            hint
        },
    )?;
    Ok(need)
}

/// Check a view against the f64 precision limit.
pub fn check_view(view: &View, w: u32, h: u32) -> Result<(), EscapeError> {
    if w == 0 || h == 0 || w > 30_000 || h > 30_000 {
        return Err(EscapeError::BadSize(w, h));
    }
    let (pixel, scale) = (view.pixel_size(h), view_scale(view));
    if !(pixel >= F64_LIMIT * scale) || !pixel.is_finite() {
        return Err(EscapeError::PrecisionLimit { pixel, scale });
    }
    Ok(())
}

/// Families that zoom past the f64 limit by perturbation.
pub fn supports_deep_zoom(family: &Family) -> bool {
    matches!(
        family,
        Family::Mandelbrot { power: 2 } | Family::Julia { power: 2, .. }
    )
}

/// Check a view for a family: the f64 limit, or the deep-zoom limit where it applies.
pub fn check_view_for(family: &Family, view: &View, w: u32, h: u32) -> Result<(), EscapeError> {
    if !supports_deep_zoom(family) {
        return check_view(view, w, h);
    }
    if w == 0 || h == 0 || w > 30_000 || h > 30_000 {
        return Err(EscapeError::BadSize(w, h));
    }
    let (pixel, scale) = (view.pixel_size(h), view_scale(view));
    if !(pixel >= DD_LIMIT * scale) || !pixel.is_finite() {
        return Err(EscapeError::DeepLimit { pixel, scale });
    }
    Ok(())
}

/// True when the view is drawn by perturbation (deep zoom).
pub fn is_deep(family: &Family, view: &View, h: u32) -> bool {
    supports_deep_zoom(family) && view.pixel_size(h) < DEEP_BELOW * view_scale(view)
}

fn view_scale(view: &View) -> f64 {
    view.center[0].abs().max(view.center[1].abs()).max(1.0)
}

fn check_params(p: &EscapeParams) -> Result<(), EscapeError> {
    if p.max_iter == 0 || p.max_iter > 100_000_000 {
        return Err(EscapeError::Settings(format!(
            "max iterations {} must be between 1 and 100000000",
            p.max_iter
        )));
    }
    match &p.family {
        Family::Mandelbrot { power } | Family::Julia { power, .. } if !(2..=9).contains(power) => {
            return Err(EscapeError::Settings(format!(
                "power {power} must be between 2 and 9"
            )));
        }
        Family::Newton { coeffs }
            if coeffs.iter().filter(|c| c.norm2() > 0.0).count() < 2 || coeffs.len() < 2 =>
        {
            return Err(EscapeError::Settings(
                "Newton needs a polynomial of degree 1 or more with a non-zero constant or linear term"
                    .into(),
            ));
        }
        _ => {}
    }
    let b = p.bailout();
    if !(b > 0.0 && b.is_finite()) {
        return Err(EscapeError::Settings(format!(
            "escape radius {b} must be positive"
        )));
    }
    Ok(())
}

/// The prepared per-render state shared by all rows.
struct Job {
    params: EscapeParams,
    view: View,
    w: u32,
    h: u32,
    settings: IterSettings,
    newton: Option<NewtonSystem>,
    /// Deep zoom: the reference orbit at the view centre and the series approximation
    /// that starts every pixel past the iterations they share.
    reference: Option<(deep::Reference, deep::Series)>,
}

impl Job {
    fn new(params: &EscapeParams, view: View, w: u32, h: u32) -> Result<Job, EscapeError> {
        check_params(params)?;
        if !matches!(params.family, Family::WarpedJulia(_)) {
            check_view_for(&params.family, &view, w, h)?;
        } else if w == 0 || h == 0 || w > 30_000 || h > 30_000 {
            return Err(EscapeError::BadSize(w, h));
        }
        check_memory(params, &view, w, h, None)?;
        let bail = params.bailout();
        let warped = matches!(params.family, Family::WarpedJulia(_));
        // Periodicity: a small fraction of a pixel (never for Newton or warped textures).
        let deep = is_deep(&params.family, &view, h);
        let period_tol = if params.periodicity
            && !deep
            && !warped
            && !matches!(params.family, Family::Newton { .. })
            && params.coloring != Coloring::Distance
        {
            view.pixel_size(h) * 1e-3
        } else {
            0.0
        };
        let settings = IterSettings {
            max_iter: params.max_iter,
            bailout2: if warped && params.bailout.is_none() {
                4.0
            } else {
                bail * bail
            },
            strict: !warped,
            period_tol,
            want_de: params.coloring == Coloring::Distance,
        };
        Ok(Job {
            reference: deep.then(|| {
                let orbit = match params.family {
                    Family::Julia { c, .. } => {
                        deep::Reference::julia(view.center_dd(), c, &settings)
                    }
                    _ => deep::Reference::mandelbrot(view.center_dd(), &settings),
                };
                // Probes on the border, where the series is least accurate.
                let (wf, hf) = ((w - 1) as f64, (h - 1) as f64);
                let probes: Vec<C> = [0.0, 0.5, 1.0]
                    .iter()
                    .flat_map(|&u| [0.0, 0.5, 1.0].map(|v| (u, v)))
                    .filter(|&(u, v)| (u, v) != (0.5, 0.5))
                    .map(|(u, v)| view.offset_from_pixel(u * wf, v * hf, w, h))
                    .collect();
                let series = deep::Series::for_view(&orbit, &probes, &settings);
                (orbit, series)
            }),
            newton: match &params.family {
                Family::Newton { coeffs } => Some(NewtonSystem::new(coeffs)),
                _ => None,
            },
            settings,
            params: params.clone(),
            view,
            w,
            h,
        })
    }

    fn point(&self, i: u32, j: u32) -> C {
        self.view
            .world_from_pixel(i as f64, j as f64, self.w, self.h)
    }

    fn lane_start(&self, i: u32, j: u32) -> Start {
        match &self.params.family {
            Family::Mandelbrot { .. } => {
                let c = self.point(i, j);
                if in_cardioid_or_bulb(c.re, c.im) {
                    Start::Inside
                } else {
                    Start::Iterate { z: C::ZERO, c }
                }
            }
            Family::Julia { c, .. } => Start::Iterate {
                z: self.point(i, j),
                c: *c,
            },
            Family::WarpedJulia(w) => {
                let z = w.start(w.point(i, j, self.w, self.h));
                if z.is_finite() {
                    Start::Iterate { z, c: w.c }
                } else {
                    Start::Escaped0
                }
            }
            _ => unreachable!("lane engine only for quadratic families"),
        }
    }

    /// One pixel in scalar code.
    fn pixel(&self, i: u32, j: u32) -> Sample {
        if let Some((orbit, series)) = &self.reference {
            let dc = self
                .view
                .offset_from_pixel(i as f64, j as f64, self.w, self.h);
            return deep::iterate_perturbed_from(orbit, series, dc, &self.settings);
        }
        match (&self.params.family, &self.newton) {
            (Family::Newton { .. }, Some(sys)) => {
                sys.iterate(self.point(i, j), self.settings.max_iter)
            }
            (Family::WarpedJulia(w), _) => {
                let z = w.start(w.point(i, j, self.w, self.h));
                if !z.is_finite() {
                    return Sample::escaped_at_zero();
                }
                iterate_quadratic_scalar(z, w.c, &self.settings)
            }
            (f, _) => iterate_point(f, self.point(i, j), &self.settings),
        }
    }

    fn uses_lanes(&self) -> bool {
        self.params.family.is_quadratic() && !self.settings.want_de && self.reference.is_none()
    }

    /// Compute the listed columns of row j into `row`.
    fn compute_row(&self, j: u32, cols: impl Iterator<Item = u32>, row: &mut [Sample]) {
        if self.uses_lanes() {
            lanes::run(
                &self.settings,
                cols,
                |i| self.lane_start(i, j),
                |i, s| row[i as usize] = s,
            );
        } else {
            for i in cols {
                row[i as usize] = self.pixel(i, j);
            }
        }
    }

    /// Compute a list of (i, j) pixels, returning their samples in order.
    fn compute_list(&self, pts: &[(u32, u32)]) -> Vec<Sample> {
        let mut out = vec![Sample::default(); pts.len()];
        if self.uses_lanes() {
            lanes::run(
                &self.settings,
                0..pts.len() as u32,
                |k| {
                    let (i, j) = pts[k as usize];
                    self.lane_start(i, j)
                },
                |k, s| out[k as usize] = s,
            );
        } else {
            for (k, &(i, j)) in pts.iter().enumerate() {
                out[k] = self.pixel(i, j);
            }
        }
        out
    }
}

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
    pub fn new(params: &EscapeParams, view: View, w: u32, h: u32) -> Result<Self, EscapeError> {
        let job = Job::new(params, view, w, h)?;
        Ok(EscapeRenderer {
            samples: vec![Sample::default(); w as usize * h as usize],
            job,
            pass: 0,
            cancelled: false,
        })
    }

    pub fn passes(&self) -> usize {
        if self.job.params.fill == Fill::Guess {
            1
        } else {
            STEPS.len()
        }
    }

    pub fn is_done(&self) -> bool {
        self.pass >= self.passes() || self.cancelled
    }

    pub fn fraction(&self) -> f64 {
        self.pass as f64 / self.passes() as f64
    }

    pub fn samples(&self) -> &[Sample] {
        &self.samples
    }

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
        pixel: job.view.pixel_size(h),
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

/// Mariani–Silver: rectangles whose border has one integer count (or is all inside; with
/// smooth colourings only all-inside borders) are filled; others split in four down to 4×4.
fn mariani_silver(job: &Job, samples: &mut [Sample], cancel: &AtomicBool) -> bool {
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
    use crate::escape::warp::{Preset, Warp};

    #[test]
    fn view_maps_pixels_both_ways_with_y_up() {
        let v = View::new([-0.7, 0.2], 1.5);
        let p = v.world_from_pixel(0.0, 0.0, 400, 300);
        assert!(p.re < -0.7 && p.im > 0.2, "top-left is up and left");
        let q = v.pixel_from_world(p, 400, 300);
        assert!((q[0] - 0.5).abs() < 1e-9 && (q[1] - 0.5).abs() < 1e-9);
        let z = v.zoomed_at(100.0, 50.0, 400, 300, 2.0);
        let before = v.world_from_pixel(99.5, 49.5, 400, 300);
        let after = z.world_from_pixel(99.5, 49.5, 400, 300);
        assert!(
            (before - after).abs() < 1e-12,
            "the point under the cursor stays"
        );
        assert!(check_view(&v, 400, 300).is_ok());
        let deep = View::new([-0.7, 0.2], 1e-12);
        assert!(matches!(
            check_view(&deep, 400, 300),
            Err(EscapeError::PrecisionLimit { .. })
        ));
        // The Mandelbrot set z² + c zooms on by perturbation, to the double-double limit.
        let m2 = Family::Mandelbrot { power: 2 };
        assert!(check_view_for(&m2, &deep, 400, 300).is_ok());
        assert!(is_deep(&m2, &deep, 300));
        assert!(!is_deep(&m2, &v, 300));
        let m3 = Family::Mandelbrot { power: 3 };
        assert!(check_view_for(&m3, &deep, 400, 300).is_err());
        let too_deep = View::new([-0.7, 0.2], 1e-27);
        assert!(matches!(
            check_view_for(&m2, &too_deep, 400, 300),
            Err(EscapeError::DeepLimit { .. })
        ));
    }

    /// Escape counts by direct double-double iteration (slow; the truth for deep tests).
    fn dd_counts(view: &View, w: u32, h: u32, s: &IterSettings) -> Vec<u32> {
        let [cx, cy] = view.center_dd();
        let mut out = Vec::new();
        for j in 0..h {
            for i in 0..w {
                let o = view.offset_from_pixel(i as f64, j as f64, w, h);
                let c = [cx + Dd::from_f64(o.re), cy + Dd::from_f64(o.im)];
                let (mut x, mut y) = (Dd::ZERO, Dd::ZERO);
                let mut n = s.max_iter;
                for k in 1..=s.max_iter {
                    let (xx, yy, xy) = (x * x, y * y, x * y);
                    x = xx - yy + c[0];
                    y = xy + xy + c[1];
                    if !(x.to_f64().powi(2) + y.to_f64().powi(2) <= s.bailout2) {
                        n = k;
                        break;
                    }
                }
                out.push(n);
            }
        }
        out
    }

    #[test]
    fn series_approximation_skips_shared_iterations_and_agrees_with_the_truth() {
        let mut p = EscapeParams::new(Family::Mandelbrot { power: 2 });
        p.max_iter = 12_000;
        let c = crate::io::escape_view::parse_center(
            "-0.743643887037158704752191506114774, 0.131825904205311970493132056385139",
        )
        .unwrap();
        let view = View::new([0.0; 2], 2e-19).with_center_dd(c);
        let (w, h) = (40, 30);
        let job = Job::new(&p, view, w, h).unwrap();
        let (orbit, series) = job.reference.as_ref().unwrap();
        assert!(series.skip > 1000, "skip {}", series.skip);
        let truth = dd_counts(&view, w, h, &job.settings);
        let (mut with_sa, mut without) = (0, 0);
        for j in 0..h {
            for i in 0..w {
                let t = truth[(j * w + i) as usize];
                with_sa += (job.pixel(i, j).n == t) as u32;
                let dc = view.offset_from_pixel(i as f64, j as f64, w, h);
                let no_series = deep::iterate_perturbed(orbit, dc, &job.settings);
                without += (no_series.n == t) as u32;
            }
        }
        // Both agree with the truth on all but a few chaotic boundary pixels, and the series
        // adds no errors of its own beyond that noise.
        assert!(with_sa * 100 >= w * h * 99, "{with_sa} of {}", w * h);
        assert!(without * 100 >= w * h * 99, "{without} of {}", w * h);
        assert!(with_sa + 3 >= without, "with {with_sa}, without {without}");
    }

    #[test]
    fn julia_sets_zoom_deep_too() {
        // Around the β fixed point (1 + √(1 − 4c))/2, which lies on the Julia set, 1e-14 wide.
        let c = C::new(-0.8, 0.156);
        let disc = C::ONE - c * 4.0;
        let root = C::from_polar(disc.abs().sqrt(), disc.im.atan2(disc.re) / 2.0);
        let beta = (C::ONE + root) * 0.5;
        let mut p = EscapeParams::new(Family::Julia { power: 2, c });
        p.max_iter = 4000;
        let view = View::new([beta.re, beta.im], 1e-14);
        let (w, h) = (40, 30);
        assert!(is_deep(&p.family, &view, h));
        let job = Job::new(&p, view, w, h).unwrap();
        let [cx, cy] = view.center_dd();
        let (mut same, mut counts) = (0, Vec::new());
        for j in 0..h {
            for i in 0..w {
                let o = view.offset_from_pixel(i as f64, j as f64, w, h);
                let (mut x, mut y) = (cx + Dd::from_f64(o.re), cy + Dd::from_f64(o.im));
                let mut truth = p.max_iter;
                for k in 1..=p.max_iter {
                    let (xx, yy, xy) = (x * x, y * y, x * y);
                    x = xx - yy + Dd::from_f64(c.re);
                    y = xy + xy + Dd::from_f64(c.im);
                    if !(x.to_f64().powi(2) + y.to_f64().powi(2) <= job.settings.bailout2) {
                        truth = k;
                        break;
                    }
                }
                let got = job.pixel(i, j).n;
                same += (got == truth) as u32;
                counts.push(truth);
            }
        }
        counts.sort();
        counts.dedup();
        assert!(
            counts.len() > 20,
            "the view shows structure: {} counts",
            counts.len()
        );
        assert!(same * 100 >= w * h * 99, "{same} of {}", w * h);
    }

    #[test]
    fn deep_views_keep_their_centre_beyond_f64() {
        // Pan by 1e-25 at a 1e-22 zoom: the f64 centre cannot change, the double-double does,
        // and the pixel mapping between the two views sees the exact shift.
        let v = View::new([-0.75, 0.1], 1e-22);
        let p = v.shifted(1e-25, 0.0);
        assert_eq!(p.center, v.center);
        assert_ne!(p.center_lo, v.center_lo);
        let px = v.pixel_of(&p, 0.0, 0.0, 400, 300);
        let one = 2.0 * 1e-22 / 300.0;
        assert!((px[0] - (0.5 + 1e-25 / one)).abs() < 1e-6, "{px:?}");
        // Zooming at a pixel keeps the point under it, to double-double precision.
        let z = v.zoomed_at(100.0, 50.0, 400, 300, 4.0);
        let back = v.pixel_of(&z, 99.5, 49.5, 400, 300);
        assert!((back[0] - 100.0).abs() < 1e-6 && (back[1] - 50.0).abs() < 1e-6);
    }

    #[test]
    fn perturbation_render_agrees_with_f64_where_both_work() {
        // Pixel 4e-13: below the perturbation threshold, above the f64 limit.
        let mut p = EscapeParams::new(Family::Mandelbrot { power: 2 });
        p.max_iter = 3000;
        p.periodicity = false;
        let view = View::new([-0.743643887037151, 0.131825904205330], 8e-12);
        let (w, h) = (48, 36);
        assert!(is_deep(&p.family, &view, h));
        let (_, samples) = render(&p, view, w, h).unwrap();
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
        let (img, samples) = render(&p, view, 97, 61).unwrap();
        let mut r = EscapeRenderer::new(&p, view, 97, 61).unwrap();
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
