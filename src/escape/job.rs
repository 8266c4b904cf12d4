//! The prepared state of one escape-time render, shared by all rows: the iteration settings,
//! the Newton system or the deep-zoom reference orbit and series, and the computation of one
//! pixel, a row or a list of pixels (by the lane engine for the quadratic families).

use super::color::Coloring;
use super::complex::C;
use super::deep;
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
    /// Deep zoom: the reference orbit at the view centre and the series approximation
    /// that starts every pixel past the iterations they share.
    pub(super) reference: Option<(deep::Reference, deep::Series)>,
}

impl Job {
    pub(super) fn new(
        params: &EscapeParams,
        view: View,
        w: u32,
        h: u32,
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
    pub(super) fn compute_row(&self, j: u32, cols: impl Iterator<Item = u32>, row: &mut [Sample]) {
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
    pub(super) fn compute_list(&self, pts: &[(u32, u32)]) -> Vec<Sample> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::escape::dd::Dd;

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
}
