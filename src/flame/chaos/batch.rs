//! One compiled xform applied to a group of points as arrays: the colour blend and the affine
//! map over the whole group, the quantities the regular variations read (radius, angles)
//! computed once per point, every regular variation run over the group, then the `post_`
//! forms, the post-affine, the direct colour and the bad-value check.

use super::xform::within;
use super::{CompiledXform, LANES};
use crate::flame::fastmath;
use crate::flame::model::Affine;
use crate::flame::rng::FastRng;
use crate::flame::variations::{self, Acc, Prepared, SoaAcc, SoaIn, need};

/// Per-point scratch arrays of one xform application.
#[derive(Clone, Debug)]
pub(super) struct Scratch {
    pub(super) sumsq: [f64; LANES],
    pub(super) sqrt: [f64; LANES],
    pub(super) atan_xy: [f64; LANES],
    pub(super) atan_yx: [f64; LANES],
    pub(super) ux: [f64; LANES],
    pub(super) uy: [f64; LANES],
    pub(super) px: [f64; LANES],
    pub(super) py: [f64; LANES],
    pub(super) pz: [f64; LANES],
    pub(super) pc: [f64; LANES],
    pub(super) bad: [bool; LANES],
    /// A variation hid the point (see [`crate::flame::variations::flag::HIDES`]).
    pub(super) hide: [bool; LANES],
    /// The points as they came in, for an xform that colours by distance.
    pub(super) old: [[f64; LANES]; 3],
}
impl Scratch {
    pub(super) fn new() -> Scratch {
        Scratch {
            sumsq: [0.0; LANES],
            sqrt: [0.0; LANES],
            atan_xy: [0.0; LANES],
            atan_yx: [0.0; LANES],
            ux: [0.0; LANES],
            uy: [0.0; LANES],
            px: [0.0; LANES],
            py: [0.0; LANES],
            pz: [0.0; LANES],
            pc: [0.0; LANES],
            bad: [false; LANES],
            hide: [false; LANES],
            old: [[0.0; LANES]; 3],
        }
    }
}

/// The colour coordinate a point leaves a variation with. Where own colours are carried
/// (`rgb`), an own colour goes to `rgb[j]` and the coordinate is kept (JWildfire's direct
/// colour leaves the gradient position alone); elsewhere an own colour becomes its
/// luminance ([`Acc::drawn_color`]).
#[inline(always)]
fn own_colour(acc: &Acc, rgb: Option<&mut [u32]>, j: usize) -> f64 {
    match (rgb, acc.packed_rgb()) {
        (Some(r), Some(p)) => {
            r[j] = p;
            acc.color
        }
        _ => acc.drawn_color(),
    }
}

/// A variation that may set an own colour over a group, point by point (the generic batch
/// loop of [`Prepared::eval`], own colours into `rgb`).
fn own_colour_batch(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rgb: &mut [u32], rng: &mut FastRng) {
    let n = acc.x.len().min(rgb.len());
    for j in 0..n {
        let t = s.at(j);
        let mut a = acc.at(j);
        let o = v.eval(&t, &mut a, rng);
        acc.x[j] = a.x + o[0];
        acc.y[j] = a.y + o[1];
        acc.z[j] = a.z + o[2];
        acc.color[j] = own_colour(&a, Some(rgb), j);
        acc.hide[j] |= a.hide;
    }
}

/// Whether every form of `forms` has a batch loop ([`variations::FormBatchFn`]: formulas
/// that touch nothing but the point). They then run one after the other over the whole group
/// instead of point by point: the same points, the random numbers drawn in another order
/// when two of the forms draw any (the same stream, so renders stay reproducible).
#[inline(always)]
fn batched_forms(forms: &[Prepared]) -> bool {
    forms.iter().all(|v| v.def.form_batch.is_some())
}

// The steps of `apply_soa` take the group as slices of one length (at most `LANES`).
impl CompiledXform {
    /// Apply to the points `x, y, z, c` (at most [`LANES`]; in place; `g.bad` flags set; a
    /// bad point is replaced by a random point of [−1, 1]², or kept under JWildfire's rule). The pre-affine points and their
    /// derived quantities are computed as arrays, then every regular variation runs over the
    /// whole group. With `rgb` (the points' own colours, [`variations::own_rgb`]) the own
    /// colours the variations set are written there, and the colour coordinate keeps its
    /// blend; a point no variation gives one draws the palette's again unless the xform keeps
    /// colours.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn apply_soa(
        &self,
        x: &mut [f64],
        y: &mut [f64],
        z: &mut [f64],
        c: &mut [f64],
        rgb: Option<&mut [u32]>,
        g: &mut Scratch,
        rng: &mut FastRng,
    ) {
        let n = x.len().min(y.len()).min(z.len()).min(c.len()).min(LANES);
        let (x, y, z, c) = (&mut x[..n], &mut y[..n], &mut z[..n], &mut c[..n]);
        let mut rgb = rgb.map(|r| &mut r[..n]);
        if let Some(r) = rgb.as_deref_mut()
            && !self.keeps_rgb
        {
            r.fill(0);
        }
        // Only variations that may set an own colour write one.
        let mut rgb = rgb.filter(|_| self.own_rgb);
        if self.hides {
            g.hide[..n].fill(false);
        }
        let distance = self.distance.filter(|_| rgb.is_some());
        if distance.is_some() {
            g.old[0][..n].copy_from_slice(x);
            g.old[1][..n].copy_from_slice(y);
            g.old[2][..n].copy_from_slice(z);
        }
        self.blend_and_map(x, y, z, c);
        if let Some(w) = self.linear_only {
            self.linear_and_post(w, x, y, z);
            self.mark_bad(x, y, z, &mut g.bad[..n], rng);
            return;
        }
        self.pre_forms(x, y, z, c, rgb.as_deref_mut(), g, rng);
        if !self.vars.is_empty() {
            self.regular_forms(x, y, z, c, rgb.as_deref_mut(), g, rng);
        } else if self.pre_only_passes && !self.pre_vars.is_empty() {
            g.px[..n].copy_from_slice(x);
            g.py[..n].copy_from_slice(y);
            g.pz[..n].copy_from_slice(z);
        } else {
            g.px[..n].fill(0.0);
            g.py[..n].fill(0.0);
            g.pz[..n].fill(0.0);
        }
        self.post_forms(x, y, z, c, rgb.as_deref_mut(), g, rng);
        self.finish_group(x, y, z, c, g, rng);
        if let (Some(d), Some(r)) = (distance, rgb) {
            if d.chained && n > 1 {
                // Each point from the one before it in the group (the first from its own).
                g.old[0][1..n].copy_from_slice(&x[..n - 1]);
                g.old[1][1..n].copy_from_slice(&y[..n - 1]);
                g.old[2][1..n].copy_from_slice(&z[..n - 1]);
            }
            let old = [&g.old[0][..n], &g.old[1][..n], &g.old[2][..n]];
            d.paint(old, [x, y, z], r);
        }
    }

    /// Blend the colours towards the xform's colour and apply the affine map to the points.
    #[inline(always)]
    fn blend_and_map(&self, x: &mut [f64], y: &mut [f64], z: &mut [f64], c: &mut [f64]) {
        let n = x.len();
        let a = self.coefs;
        let (s, col) = (self.color_speed, self.color);
        if let Some(sym) = self.cyclic {
            for cj in c[..n].iter_mut() {
                *cj = super::xform::cycle_colour(*cj, sym);
            }
        } else {
            for cj in c[..n].iter_mut() {
                *cj = s * col + (1.0 - s) * *cj;
            }
        }
        if let Some(m) = self.planes.as_ref().and_then(|m| m.pre.as_ref()) {
            let z = &mut z[..n];
            for j in 0..n {
                (x[j], y[j], z[j]) = m.apply(&a, x[j], y[j], z[j]);
            }
            return;
        }
        for j in 0..n {
            let (tx, ty) = a.apply(x[j], y[j]);
            x[j] = tx;
            y[j] = ty;
        }
    }

    /// Only `linear`, of weight `w`: the sum of the variations is w times the point (written
    /// as the general path computes it, 0 + w·v, so both give the same bits), then the
    /// post-affine map.
    #[inline(always)]
    fn linear_and_post(&self, w: f64, x: &mut [f64], y: &mut [f64], z: &mut [f64]) {
        let n = x.len();
        for j in 0..n {
            x[j] = 0.0 + w * x[j];
            y[j] = 0.0 + w * y[j];
            z[j] = 0.0 + w * z[j];
        }
        if let Some(post) = &self.post {
            for j in 0..n {
                (x[j], y[j]) = post.apply(x[j], y[j]);
            }
        }
    }

    /// The `pre_` forms: each replaces (or moves) the point; the colour they set goes to
    /// `g.pc` (the blended colour when there are none), an own colour to `rgb`. When every
    /// form has a batch loop ([`batched_forms`]) each runs over the whole group in turn,
    /// otherwise the forms run point by point.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn pre_forms(
        &self,
        x: &mut [f64],
        y: &mut [f64],
        z: &mut [f64],
        c: &[f64],
        mut rgb: Option<&mut [u32]>,
        g: &mut Scratch,
        rng: &mut FastRng,
    ) {
        let n = x.len();
        if self.pre_vars.is_empty() || batched_forms(&self.pre_vars) {
            let (y, z) = (&mut y[..n], &mut z[..n]);
            for v in &self.pre_vars {
                if let Some(f) = v.def.form_batch {
                    f(v, x, y, z, rng);
                }
            }
            g.pc[..n].copy_from_slice(&c[..n]);
            return;
        }
        for j in 0..n {
            let mut acc = Acc {
                color: c[j],
                ..Acc::default()
            };
            let mut tr = [x[j], y[j], z[j]];
            for v in &self.pre_vars {
                v.apply_pre(&mut tr, &mut acc, c[j], rng);
            }
            (x[j], y[j], z[j]) = (tr[0], tr[1], tr[2]);
            g.pc[j] = own_colour(&acc, rgb.as_deref_mut(), j);
            g.hide[j] |= acc.hide;
        }
    }

    /// The quantities of the points that the regular variations read (the [`need`] bits of
    /// the xform): r², r, the two atan2 orders, the unit vector.
    #[inline(always)]
    fn derived(&self, xs: &[f64], ys: &[f64], g: &mut Scratch) {
        let n = xs.len();
        let needs = self.needs;
        let (sumsq, sqrt) = (&mut g.sumsq[..n], &mut g.sqrt[..n]);
        if needs & (need::SUMSQ | need::SQRT | need::ANGLES) != 0 {
            for j in 0..n {
                sumsq[j] = xs[j] * xs[j] + ys[j] * ys[j];
                sqrt[j] = sumsq[j].sqrt();
            }
        }
        if needs & need::ATAN_XY != 0 {
            let at = &mut g.atan_xy[..n];
            for j in 0..n {
                at[j] = fastmath::atan2(xs[j], ys[j]);
            }
        }
        if needs & need::ATAN_YX != 0 {
            let at = &mut g.atan_yx[..n];
            for j in 0..n {
                at[j] = fastmath::atan2(ys[j], xs[j]);
            }
        }
        if needs & need::ANGLES != 0 {
            let (ux, uy) = (&mut g.ux[..n], &mut g.uy[..n]);
            for j in 0..n {
                let r = if sqrt[j] == 0.0 {
                    f64::EPSILON
                } else {
                    sqrt[j]
                };
                ux[j] = xs[j] / r;
                uy[j] = ys[j] / r;
            }
        }
    }

    /// Every regular variation over the whole group, their outputs summed into `g.px`,
    /// `g.py`, `g.pz` (and their colours into `g.pc`, own colours into `rgb`).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn regular_forms(
        &self,
        x: &[f64],
        y: &[f64],
        z: &[f64],
        c: &[f64],
        mut rgb: Option<&mut [u32]>,
        g: &mut Scratch,
        rng: &mut FastRng,
    ) {
        let n = x.len();
        let (xs, ys) = (&x[..n], &y[..n]);
        self.derived(xs, ys, g);
        let soa = SoaIn {
            x: xs,
            y: ys,
            z: &z[..n],
            sumsq: &g.sumsq[..n],
            sqrt: &g.sqrt[..n],
            ux: &g.ux[..n],
            uy: &g.uy[..n],
            atan_xy: &g.atan_xy[..n],
            atan_yx: &g.atan_yx[..n],
            color: &c[..n],
        };
        g.px[..n].fill(0.0);
        g.py[..n].fill(0.0);
        g.pz[..n].fill(0.0);
        let mut acc = SoaAcc {
            x: &mut g.px[..n],
            y: &mut g.py[..n],
            z: &mut g.pz[..n],
            color: &mut g.pc[..n],
            hide: &mut g.hide[..n],
        };
        for v in &self.vars {
            match rgb.as_deref_mut() {
                Some(r) if v.def.has(variations::flag::SETS_COLOR) => {
                    own_colour_batch(v, &soa, &mut acc, r, rng)
                }
                _ => v.apply_batch(&soa, &mut acc, rng),
            }
        }
    }

    /// The `post_` forms on the summed points in `g` (own colours into `rgb`): each over the
    /// whole group when all have batch loops ([`batched_forms`]), else point by point (a form
    /// reading the affine point gets it from `x`, `y`, `z`).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn post_forms(
        &self,
        x: &[f64],
        y: &[f64],
        z: &[f64],
        c: &[f64],
        mut rgb: Option<&mut [u32]>,
        g: &mut Scratch,
        rng: &mut FastRng,
    ) {
        let n = c.len();
        if self.post_vars.is_empty() {
            return;
        }
        if batched_forms(&self.post_vars) {
            let (px, py, pz) = (&mut g.px[..n], &mut g.py[..n], &mut g.pz[..n]);
            for v in &self.post_vars {
                if let Some(f) = v.def.form_batch {
                    f(v, px, py, pz, rng);
                }
            }
            return;
        }
        for (j, &cj) in c[..n].iter().enumerate() {
            let mut acc = Acc {
                x: g.px[j],
                y: g.py[j],
                z: g.pz[j],
                color: g.pc[j],
                hide: false,
                rgb: None,
            };
            let affine = [x[j], y[j], z[j]];
            for v in &self.post_vars {
                v.apply_post_after(&affine, &mut acc, cj, rng);
            }
            let pc = own_colour(&acc, rgb.as_deref_mut(), j);
            (g.px[j], g.py[j], g.pz[j], g.pc[j]) = (acc.x, acc.y, acc.z, pc);
            g.hide[j] |= acc.hide;
        }
    }

    /// The post-affine map and the direct colour, then the points of `g` back into `x, y,
    /// z` and their bad values flagged.
    #[inline(always)]
    fn finish_group(
        &self,
        x: &mut [f64],
        y: &mut [f64],
        z: &mut [f64],
        c: &mut [f64],
        g: &mut Scratch,
        rng: &mut FastRng,
    ) {
        let n = x.len();
        let (px, py, pz) = (&mut g.px[..n], &mut g.py[..n], &mut g.pz[..n]);
        if let Some(m) = self.planes.as_ref().and_then(|m| m.post.as_ref()) {
            let post = self.post.unwrap_or(Affine::IDENTITY);
            for j in 0..n {
                (px[j], py[j], pz[j]) = m.apply(&post, px[j], py[j], pz[j]);
            }
        } else if let Some(post) = &self.post {
            for j in 0..n {
                (px[j], py[j]) = post.apply(px[j], py[j]);
            }
        }
        if self.sets_color {
            let dc = self.direct_color;
            let pc = &g.pc[..n];
            for j in 0..n {
                let v = c[j] + dc * (pc[j] - c[j]);
                c[j] = if v.is_nan() { 0.0 } else { v };
            }
        }
        x[..n].copy_from_slice(px);
        y[..n].copy_from_slice(py);
        z[..n].copy_from_slice(pz);
        self.mark_bad(&mut x[..n], &mut y[..n], &mut z[..n], &mut g.bad[..n], rng);
    }

    /// Flag the bad points of a group and restart them at a random point of the plane (a NaN
    /// or infinite z must not carry over); under JWildfire's rule ([`CompiledXform::keeps_bad`])
    /// flag them only.
    #[inline(always)]
    fn mark_bad(
        &self,
        x: &mut [f64],
        y: &mut [f64],
        z: &mut [f64],
        bad: &mut [bool],
        rng: &mut FastRng,
    ) {
        let n = bad.len().min(x.len()).min(y.len()).min(z.len());
        if self.keeps_bad {
            // JWildfire's rule: the point stays as it is (see `keeps_bad`).
            for j in 0..n {
                bad[j] = !(x[j].is_finite() & y[j].is_finite() & z[j].is_finite());
            }
            return;
        }
        let mut any_bad = false;
        for j in 0..n {
            let b = !within(x[j], self.bad_limit) | !within(y[j], self.bad_limit);
            bad[j] = b;
            any_bad |= b;
        }
        if any_bad {
            for j in 0..n {
                if bad[j] {
                    x[j] = rng.f11();
                    y[j] = rng.f11();
                    z[j] = 0.0;
                }
            }
        }
    }
}

#[cfg(test)]
#[path = "batch_tests.rs"]
mod tests;
