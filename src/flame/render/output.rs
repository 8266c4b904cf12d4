//! What a render shows: the histograms merged and developed into previews, drafts, recoloured
//! pictures and the final image, and the state kept to resume it.

use super::*;

impl Renderer {
    /// Is every sub-batch of the whole render done (one part of one, run to the end)?
    fn complete(&self) -> bool {
        self.part.count == 1 && self.next_batch >= self.batches_total && !self.cancelled
    }

    /// Density used by the log scaling: the flame's quality·4^zoom when done, otherwise the
    /// samples actually done per pixel (so that previews are correctly exposed).
    fn density(&self) -> f64 {
        // A motion-blurred frame's hits are weighted by the temporal filter: on average by its
        // mean weight.
        let weight = self.motion.as_ref().map_or(1.0, |m| m.mean_weight);
        if self.complete() {
            return self.flame.quality * 4f64.powf(self.flame.zoom) * weight;
        }
        if self.geom.jwf.is_some() {
            // JWildfire's samples also cover the border of its raster.
            let done = self.samples_done.max(1) as f64 / self.total_samples() as f64;
            return self.flame.quality * done * 4f64.powf(self.flame.zoom) * weight;
        }
        let px = self.flame.width as f64 * self.flame.height as f64;
        (self.samples_done.max(1) as f64) / px * weight
    }

    /// The picture of a flame JWildfire draws solid, from every worker's buckets; `None` for
    /// the other flames.
    fn solid_image(&self) -> Option<DynamicImage> {
        let mut planes = self.solid.iter().flatten();
        let mut m = planes.next()?.clone();
        for p in planes {
            m.merge(p);
        }
        crate::flame::jwf_render::solid_draw::develop_solid(
            &self.flame,
            &self.geom,
            self.geom.jwf.as_deref()?,
            &m,
            &self.palette,
            self.format,
            self.out_rows.clone(),
        )
    }

    fn merged(&self) -> Histogram {
        let mut m = self.hists[0].clone();
        for h in &self.hists[1..] {
            m.add(h);
        }
        m
    }

    /// The image as it stands (any time during the render).
    pub fn preview(&self) -> DynamicImage {
        self.preview_until(&AtomicBool::new(false))
            .expect("not stopped")
    }

    /// [`Renderer::preview`], or `None` as soon as `stop` is set (density estimation at low
    /// density takes tens of milliseconds; an editor drops a picture that an edit made stale).
    pub fn preview_until(&self, stop: &AtomicBool) -> Option<DynamicImage> {
        if let Some(img) = self.solid_image() {
            return Some(img);
        }
        let m = self.merged();
        develop_rows_until(
            &self.flame,
            &self.geom,
            &m,
            self.density(),
            self.format,
            self.out_rows.clone(),
            stop,
        )
    }

    /// Two pictures of independent halves of the samples so far — the even and the odd
    /// threads' histograms, each exposed for its own samples — with each half's share of the
    /// samples. Their difference measures the noise (grain) left in [`Renderer::preview`], the
    /// two-buffer estimate of Monte Carlo renderers, free of the change density estimation
    /// makes as the density grows. `None` with one thread, or as soon as `stop` is set.
    pub fn preview_halves(&self, stop: &AtomicBool) -> Option<[(DynamicImage, f64); 2]> {
        let t = self.hists.len();
        if t < 2 {
            return None;
        }
        let half = |k: usize| -> Option<(DynamicImage, f64)> {
            let mut it = self.hists.iter().skip(k).step_by(2);
            let mut m = it.next()?.clone();
            for h in it {
                m.add(h);
            }
            // Threads iterate equal numbers of sub-batches (within one).
            let share = (t - k).div_ceil(2) as f64 / t as f64;
            let img = develop_rows_until(
                &self.flame,
                &self.geom,
                &m,
                self.density() * share,
                self.format,
                self.out_rows.clone(),
                stop,
            )?;
            Some((img, share))
        };
        Some([half(0)?, half(1)?])
    }

    /// A quick look at the image as it stands: like [`Renderer::preview`] but without density
    /// estimation (a few milliseconds instead of tens at low densities, where DE kernels are
    /// widest). Same exposure; noisier. The GUI shows it first after an edit and while
    /// dragging.
    pub fn preview_draft(&self) -> DynamicImage {
        if let Some(img) = self.solid_image() {
            return img;
        }
        develop_draft(
            &self.flame,
            &self.geom,
            &self.hists,
            self.density(),
            self.format,
            self.out_rows.clone(),
        )
    }

    /// True when the samples are kept and [`Renderer::recolor`] can be used.
    pub fn can_recolor(&self) -> bool {
        self.logs.is_some()
            && self.ifs3d.is_none()
            && self.motion.is_none()
            && !self.chaos.reads_palette
    }

    /// Change the palette (and palette mode) by re-accumulating the kept samples: no iteration.
    /// Returns false when the samples were not kept (the caller must render again).
    pub fn recolor(
        &mut self,
        palette: &crate::gradient::Gradient,
        mode: crate::flame::PaletteMode,
    ) -> bool {
        let Some(logs) = &self.logs else { return false };
        // Colour coordinates taken from the palette change with it.
        if self.ifs3d.is_some() || self.chaos.reads_palette {
            return false;
        }
        self.flame.palette = palette.clone();
        self.flame.palette_mode = mode;
        self.palette = PlotPalette::new(&self.flame);
        let pal = &self.palette;
        self.hists
            .par_iter_mut()
            .zip(logs.par_iter())
            .for_each(|(h, log)| {
                h.clear();
                accumulate(pal, h, log);
            });
        true
    }

    /// The state to save (a copy: the render can go on). `None` after a cancel, whose
    /// bookkeeping of finished sub-batches is not exact.
    pub fn snapshot(&self) -> Option<(RenderState, Histogram)> {
        Some((self.state()?, self.merged()))
    }

    /// Finish into the state to save: merges the thread histograms in place. `None` after a
    /// cancel.
    pub fn into_state(mut self) -> Option<(RenderState, Histogram)> {
        let st = self.state()?;
        Some((st, self.take_merged()))
    }

    /// The bucket geometry (with the strip's window of rows, if any).
    pub fn geometry(&self) -> &Geometry {
        &self.geom
    }

    fn state(&self) -> Option<RenderState> {
        // A solid flame's buckets are not part of a render state.
        let solid = self.solid.iter().any(Option::is_some);
        if self.cancelled || solid || self.motion.as_ref().is_some_and(|m| !m.layers) {
            return None;
        }
        let mut flame = self.flame.clone();
        flame.has_camera = true;
        Some(RenderState {
            flame,
            seed: self.seed,
            part_count: self.part.count,
            parts: vec![self.part.index],
            batches_done: self.next_batch,
            samples_done: self.samples_done,
            bad_values: self.badvals,
            lanes: self.lanes.iter().map(|l| l.state()).collect(),
            var_states: self
                .thread_chaos
                .iter()
                .map(|c| c.variation_state())
                .collect(),
            gap: self.gap,
        })
    }

    fn take_merged(&mut self) -> Histogram {
        let mut hists = std::mem::take(&mut self.hists);
        let mut first = hists.swap_remove(0);
        for h in hists.drain(..) {
            first.add(&h);
        }
        first
    }

    /// Finish: merge the thread histograms in place (freeing them) and develop the image
    /// (the strip's rows for a render in strips).
    pub fn finish(mut self) -> DynamicImage {
        if let Some(img) = self.solid_image() {
            return img;
        }
        let density = self.density();
        let first = self.take_merged();
        develop_rows(
            &self.flame,
            &self.geom,
            &first,
            density,
            self.format,
            self.out_rows.clone(),
        )
    }

    /// As [`Renderer::finish`], also returning the state to save (`None` after a cancel).
    pub fn finish_with_state(mut self) -> (DynamicImage, Option<(RenderState, Histogram)>) {
        if let Some(img) = self.solid_image() {
            return (img, None);
        }
        let density = self.density();
        let st = self.state();
        let first = self.take_merged();
        let img = develop_rows(
            &self.flame,
            &self.geom,
            &first,
            density,
            self.format,
            self.out_rows.clone(),
        );
        (img, st.map(|s| (s, first)))
    }
}
