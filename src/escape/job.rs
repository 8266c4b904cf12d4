//! The prepared state of one escape-time render, shared by all rows: the iteration settings,
//! the Newton system or the deep-zoom reference orbit and series, and the computation of one
//! pixel, a row or a list of pixels (by the lane engine for the quadratic families).

use super::color::Coloring;
use super::complex::C;
use super::deep::{self, Map};
use super::family::{
    Family, IterSettings, NewtonSystem, Sample, in_cardioid_or_bulb, iterate_point,
    iterate_quadratic_scalar,
};
use super::lanes::{self, Start};
use super::params::{
    EscapeError, EscapeParams, check_memory, check_params, check_view_for, is_deep,
};
use super::view::View;

/// The prepared per-render state shared by all rows.
pub(super) struct Job {
    pub(super) params: EscapeParams,
    pub(super) view: View,
    pub(super) w: u32,
    pub(super) h: u32,
    pub(super) settings: IterSettings,
    pub(super) newton: Option<NewtonSystem>,
    /// Deep zoom: the reference orbit at the view centre and its bilinear table.
    pub(super) reference: Option<deep::Reference>,
}

impl Job {
    pub(super) fn new(
        params: &EscapeParams,
        view: View,
        w: u32,
        h: u32,
        progress: &deep::OrbitProgress,
    ) -> Result<Job, EscapeError> {
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
        let reference = if deep {
            Some(
                Job::reference(params, &view, w, h, &settings, progress).ok_or_else(|| {
                    EscapeError::Settings("the reference orbit was cancelled".into())
                })?,
            )
        } else {
            None
        };
        Ok(Job {
            reference,
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

    /// The reference orbit and bilinear table of a deep view (None when cancelled).
    pub(super) fn reference(
        params: &EscapeParams,
        view: &View,
        w: u32,
        h: u32,
        settings: &IterSettings,
        progress: &deep::OrbitProgress,
    ) -> Option<deep::Reference> {
        let map = |power| if power == 3 { Map::Cube } else { Map::Square };
        let (map, julia) = match params.family {
            Family::Julia { power, c } => (map(power), Some(c)),
            Family::Mandelbrot { power } => (map(power), None),
            Family::BurningShip => (Map::Ship, None),
            _ => unreachable!("deep zoom only for z^2 + c, z^3 + c and the Burning Ship"),
        };
        // The largest offset of a pixel from the centre: a corner.
        let radius = view.offset_from_pixel_fx(0.0, 0.0, w, h).abs();
        let extent = deep::Extent {
            pixel: view.pixel_size_fx(h),
            radius,
            bla_eps: params.bla_eps,
        };
        deep::Reference::new(map, view.centre(), julia, extent, settings, progress)
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
        if let Some(r) = &self.reference {
            let dc = self
                .view
                .offset_from_pixel_fx(i as f64, j as f64, self.w, self.h);
            return deep::iterate(r, dc, &self.settings, self.view.pixel_size_fx(self.h));
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

    /// Deep zoom: the pixels `pts` (several at once).
    fn deep_pixels(
        &self,
        r: &deep::Reference,
        pts: impl Iterator<Item = (u32, u32)>,
    ) -> Vec<Sample> {
        let dcs: Vec<_> = pts
            .map(|(i, j)| {
                self.view
                    .offset_from_pixel_fx(i as f64, j as f64, self.w, self.h)
            })
            .collect();
        deep::iterate_many(r, &dcs, &self.settings, self.view.pixel_size_fx(self.h))
    }

    /// Compute the listed columns of row j into `row`.
    pub(super) fn compute_row(&self, j: u32, cols: impl Iterator<Item = u32>, row: &mut [Sample]) {
        if let Some(r) = &self.reference {
            let cols: Vec<u32> = cols.collect();
            let samples = self.deep_pixels(r, cols.iter().map(|&i| (i, j)));
            for (i, s) in cols.into_iter().zip(samples) {
                row[i as usize] = s;
            }
        } else if self.uses_lanes() {
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
    pub(super) fn compute_list(&self, pts: &[(u32, u32)]) -> Vec<Sample> {
        if let Some(r) = &self.reference {
            return self.deep_pixels(r, pts.iter().copied());
        }
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
