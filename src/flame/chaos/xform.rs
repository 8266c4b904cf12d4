//! One xform compiled for the chaos game: its variations prepared and sorted by form
//! (`pre_`, regular, `post_`), what they need per point, its colour and opacity, and its
//! application to one point.

use super::{BAD_LIMIT, Pt};
use crate::flame::jwf_render::colour_type::DistanceColour;
use crate::flame::jwf_render::planes::XformPlanes;
use crate::flame::model::{Affine, Xform};
use crate::flame::rng::FastRng;
use crate::flame::variations::{self, Acc, Dialect, Form, Prepared, Rules, VarIn, ZRule};

/// One xform ready for iteration.
#[derive(Clone, Debug)]
pub struct CompiledXform {
    pub coefs: Affine,
    pub post: Option<Affine>,
    /// `pre_` variations, in order: each replaces (or moves) the transformed point.
    pub pre_vars: Vec<Prepared>,
    /// Regular variations: their outputs are summed.
    pub vars: Vec<Prepared>,
    /// `post_` variations, in order: each replaces (or moves) the summed point.
    pub post_vars: Vec<Prepared>,
    /// Per-point quantities the regular variations read ([`variations::need`] bits).
    pub needs: u8,
    pub color: f64,
    pub color_speed: f64,
    /// How much of a colour set by a variation is kept (Fractorium's `direct_color`).
    pub direct_color: f64,
    /// Some variation sets the colour.
    pub sets_color: bool,
    /// Weight of its plotted samples ([`plotted_opacity`]: o^(log2 10) in flam3).
    pub vis: f64,
    pub opacity: f64,
    /// A coordinate of larger magnitude (or NaN) is a bad value: [`BAD_LIMIT`] or
    /// [`BAD_LIMIT_WIDE`].
    pub bad_limit: f64,
    /// JWildfire's rule for bad values (set for a flame its renderer draws): a point with a
    /// NaN or infinite coordinate (z too) is bad, and the lane runner keeps it as it is
    /// instead of starting again from a random point. The orbit goes on from it: NaN
    /// propagates, but an xform whose variations ignore their input (`sineblur`,
    /// `spirograph`, …) brings the orbit back, as in JWildfire 9.00, where
    /// `DefaultRenderIterationState` transforms the point whatever it holds and only its
    /// check every 1000 iterations (`validateState`) starts a bad orbit again.
    pub keeps_bad: bool,
    /// The weight of `linear` when it is the xform's only variation (no `pre_`/`post_`
    /// forms): the lane runner then skips the general variation machinery.
    pub linear_only: Option<f64>,
    /// Some variation may hide the point ([`variations::flag::HIDES`]).
    pub hides: bool,
    /// Under JWildfire's rule the hide flag travels with the point (its `XYZPoint.doHide`,
    /// copied from the point an xform reads to the point it writes): whether this xform
    /// passes a hidden point's flag on. True when no variation here hides (nothing touches
    /// the flag) and when one only ever sets it (JWildfire 9.00's `RhodoneaFunc`); false
    /// when its hiding variations decide afresh for every point (the crops, `cut_fun`, …:
    /// they clear the flag where they draw).
    pub hide_passes_on: bool,
    /// Some variation may give the point a colour of its own (JWildfire's direct colour);
    /// the lane runner carries it only for flames JWildfire's renderer draws.
    pub own_rgb: bool,
    /// A point keeps the own colour it came with unless a variation here sets one (an xform
    /// of JWildfire's colour type NONE: it does not look the palette up).
    pub keeps_rgb: bool,
    /// JWildfire's colour type DISTANCE: the point gets the palette entry of the distance
    /// the xform moved it (set for flames JWildfire's renderer draws).
    pub distance: Option<DistanceColour>,
    /// JWildfire's colour type CYCLIC, with the xform's colour symmetry: the point's gradient
    /// position moves on by the symmetry, modulo 1, instead of blending toward the xform's
    /// colour (JWildfire 9.00's `TransformationInitStep`; set for flames JWildfire's
    /// renderer draws).
    pub cyclic: Option<f64>,
    /// JWildfire's maps of the yz and zx planes, with the affine map and with the post map
    /// (for a flame of JWildfire's variations; see [`XformPlanes`]).
    pub planes: Option<XformPlanes>,
    /// An xform whose only variations are `pre_` forms hands the moved point on (Fractorium
    /// 23.23, `Xform::Apply`: "only pre variations are present"; JWildfire). flam3 3.1.1
    /// (`apply_xform`) and Apophysis (`TXForm.NextPoint`) start the variation sum at 0 and
    /// add nothing to it: the point is the origin (then the post map).
    pub pre_only_passes: bool,
}

/// The hiding variations that, in JWildfire 9.00, set the point's hide flag and never clear
/// it: a point they hide stays hidden through the next xforms until some variation clears the
/// flag (see [`CompiledXform::hide_passes_on`]).
const ONLY_SET_HIDE: &[&str] = &["rhodonea"];

/// |v| ≤ limit; false for NaN (which fails every comparison).
#[inline(always)]
pub(super) fn within(v: f64, limit: f64) -> bool {
    v.abs() <= limit
}

/// Largest magnitude of a good coordinate for flames of Fractorium's variations: Fractorium
/// only treats NaN as a bad value (its trig and quaternion variations bring far-away points
/// back), so only NaN and infinity are bad there.
pub const BAD_LIMIT_WIDE: f64 = f64::MAX;

/// flam3 `adjust_percentage`: vis = o^(log₂10), with 0 ↦ 0.
pub fn adjust_opacity(o: f64) -> f64 {
    if o <= 0.0 {
        0.0
    } else {
        o.powf(std::f64::consts::LOG2_10)
    }
}

/// The weight a sample of an xform of opacity `o` is plotted with, by the rule of the program
/// whose formulas the flame follows. flam3 plots it with [`adjust_opacity`]; Fractorium with
/// the opacity itself, clamped to [0, 1] (Fractorium 1.0.0.19, `Xform::Apply` gives the point
/// `m_Opacity` and `Renderer::Accumulate` scales the palette colour by it): an xform of
/// opacity 0.4 draws 40 % of its points' weight there, 4.8 % in flam3.
pub fn plotted_opacity(o: f64, dialect: Dialect) -> f64 {
    match dialect {
        Dialect::Fractorium if o > 0.0 => o.min(1.0),
        Dialect::Fractorium => 0.0,
        _ => adjust_opacity(o),
    }
}
impl CompiledXform {
    /// Compile `x` with plotted opacity `opacity`; its variations run as `rules` say (the
    /// rules of the program that wrote the flame).
    pub fn new(x: &Xform, opacity: f64, rules: Rules) -> Self {
        let mut pre_vars = Vec::new();
        let mut vars = Vec::new();
        let mut post_vars = Vec::new();
        let mut needs = 0u8;
        let mut sets_color = false;
        for v in &x.vars {
            // JWildfire runs every variation whatever its amount: one that colours or hides
            // points acts at 0 too; flam3 and Fractorium skip it.
            let runs_at_zero =
                rules.dialect == Dialect::JWildfire && variations::info(v.id).acts_at_weight_zero();
            if v.weight == 0.0 && !runs_at_zero {
                continue;
            }
            let prepare = |form| {
                let (w, p, t) = (v.weight, &v.params, &v.texts);
                if v.moved && form == Form::Regular {
                    Prepared::for_flame(v.id, form, w, p, t, x.coefs, rules)
                        .kept_among_regular(rules)
                } else if v.moved {
                    // The regular variation's formula, run in the phase `form` names.
                    Prepared::for_flame(v.id, Form::Regular, w, p, t, x.coefs, rules)
                        .moved_by_priority(form, rules)
                } else {
                    Prepared::for_flame(v.id, form, w, p, t, x.coefs, rules)
                }
            };
            let p = prepare(v.form);
            sets_color |= p.def.has(variations::flag::SETS_COLOR);
            if p.def.has(variations::flag::PREPOST) {
                // Called before the regular variations and again after them.
                pre_vars.push(prepare(Form::Pre));
                post_vars.push(prepare(Form::Post));
                continue;
            }
            // The phase, which a JWildfire flame's variation may have whatever its name says.
            match p.form {
                Form::Pre => pre_vars.push(p),
                Form::Regular => {
                    needs |= p.def.needs;
                    vars.push(p);
                }
                Form::Post => post_vars.push(p),
            }
        }
        let planes = if rules.dialect == Dialect::JWildfire {
            XformPlanes::of(x)
        } else {
            None
        };
        // The short path computes flam3's linear, z carried along.
        let linear_only = match (&pre_vars[..], &vars[..], &post_vars[..]) {
            ([], [v], [])
                if v.id == variations::LINEAR
                    && planes.is_none()
                    && !sets_color
                    && (v.def.has(variations::flag::WRITES_Z) || v.zrule == ZRule::Weighted) =>
            {
                Some(v.w)
            }
            _ => None,
        };
        let hides = pre_vars
            .iter()
            .chain(&vars)
            .chain(&post_vars)
            .any(|v| v.def.has(variations::flag::HIDES));
        let hide_passes_on = !hides
            || pre_vars
                .iter()
                .chain(&vars)
                .chain(&post_vars)
                .any(|v| ONLY_SET_HIDE.contains(&v.def.name));
        let own_rgb = pre_vars.iter().chain(&vars).chain(&post_vars).any(|v| {
            v.def.has(variations::flag::JWILDFIRE) && v.def.has(variations::flag::SETS_COLOR)
        });
        CompiledXform {
            linear_only,
            hides,
            hide_passes_on,
            own_rgb,
            keeps_rgb: false,
            distance: None,
            cyclic: None,
            planes,
            coefs: x.coefs,
            post: if x.post.is_identity() {
                None
            } else {
                Some(x.post)
            },
            pre_vars,
            vars,
            post_vars,
            needs,
            color: x.color,
            color_speed: x.color_speed,
            direct_color: x.direct_color,
            sets_color,
            vis: plotted_opacity(opacity, rules.dialect),
            opacity,
            bad_limit: BAD_LIMIT,
            keeps_bad: false,
            pre_only_passes: rules.dialect != Dialect::Flam3,
        }
    }

    /// Apply to a point. Returns the new point and whether it was a bad value (in which case
    /// the point is a uniform random point of [−1, 1]² and the colour is still updated).
    #[inline(always)]
    pub fn apply(&self, p: Pt, rng: &mut FastRng) -> (Pt, bool) {
        let (q, bad, _) = self.apply_hiding(p, rng);
        (q, bad)
    }

    /// Under JWildfire's rule, whether the point this xform wrote is hidden: `here`, a
    /// variation of this xform hid it; `carried`, the point it read was hidden.
    #[inline(always)]
    pub fn hidden_after(&self, here: bool, carried: bool) -> bool {
        here || (carried && self.hide_passes_on)
    }

    /// [`CompiledXform::apply`], also saying whether a variation hid the point (the orbit
    /// goes on from it, the sample is not drawn).
    #[inline(always)]
    pub fn apply_hiding(&self, p: Pt, rng: &mut FastRng) -> (Pt, bool, bool) {
        self.apply_with(p, false, rng)
    }

    /// [`CompiledXform::apply_hiding`] that, under JWildfire's rule ([`Self::keeps_bad`]),
    /// returns a bad point as it is (still flagged bad).
    #[inline(always)]
    pub(super) fn apply_keeping(&self, p: Pt, rng: &mut FastRng) -> (Pt, bool, bool) {
        self.apply_with(p, self.keeps_bad, rng)
    }

    /// The application to one point; `keep`: a bad point is returned as it is.
    #[inline(always)]
    fn apply_with(&self, p: Pt, keep: bool, rng: &mut FastRng) -> (Pt, bool, bool) {
        let blended = match self.cyclic {
            Some(sym) => cycle_colour(p.c, sym),
            None => self.color_speed * self.color + (1.0 - self.color_speed) * p.c,
        };
        let mut tr = match self.planes.as_ref().and_then(|m| m.pre.as_ref()) {
            Some(m) => {
                let (tx, ty, tz) = m.apply(&self.coefs, p.x, p.y, p.z);
                [tx, ty, tz]
            }
            None => {
                let (tx, ty) = self.coefs.apply(p.x, p.y);
                [tx, ty, p.z]
            }
        };
        let mut acc = Acc {
            color: blended,
            ..Acc::default()
        };
        for v in &self.pre_vars {
            v.apply_pre(&mut tr, &mut acc, blended, rng);
        }
        if !self.vars.is_empty() {
            let t = VarIn::new(tr[0], tr[1], tr[2], blended, self.needs, false);
            acc.x = 0.0;
            acc.y = 0.0;
            acc.z = 0.0;
            for v in &self.vars {
                let o = v.eval(&t, &mut acc, rng);
                acc.x += o[0];
                acc.y += o[1];
                acc.z += o[2];
            }
        } else if self.pre_only_passes && !self.pre_vars.is_empty() {
            (acc.x, acc.y, acc.z) = (tr[0], tr[1], tr[2]);
        }
        for v in &self.post_vars {
            v.apply_post_after(&tr, &mut acc, blended, rng);
        }
        if let Some(m) = self.planes.as_ref().and_then(|m| m.post.as_ref()) {
            let post = self.post.unwrap_or(Affine::IDENTITY);
            (acc.x, acc.y, acc.z) = m.apply(&post, acc.x, acc.y, acc.z);
        } else if let Some(post) = &self.post {
            (acc.x, acc.y) = post.apply(acc.x, acc.y);
        }
        let mut nc = blended;
        if self.sets_color {
            nc = blended + self.direct_color * (acc.drawn_color() - blended);
            if nc.is_nan() {
                nc = 0.0;
            }
        }
        if keep {
            let bad = !(acc.x.is_finite() && acc.y.is_finite() && acc.z.is_finite());
            let q = Pt {
                x: acc.x,
                y: acc.y,
                z: acc.z,
                c: nc,
            };
            return (q, bad, acc.hide);
        }
        if !(within(acc.x, self.bad_limit) && within(acc.y, self.bad_limit)) {
            let q = Pt {
                x: rng.f11(),
                y: rng.f11(),
                z: 0.0,
                c: nc,
            };
            return (q, true, acc.hide);
        }
        (
            Pt {
                x: acc.x,
                y: acc.y,
                z: acc.z,
                c: nc,
            },
            false,
            acc.hide,
        )
    }
}

/// JWildfire's colour type CYCLIC: the gradient position `c` moved on by `sym`, as Java's
/// `%` takes it modulo 1, then into [0, 1).
#[inline(always)]
pub(crate) fn cycle_colour(c: f64, sym: f64) -> f64 {
    let m = (c + sym) % 1.0;
    if m < 0.0 { m + 1.0 } else { m }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::model::Var;

    /// A regular variation JWildfire's priority moved before the others adds its output to
    /// the point (T + w·f(T)); a `pre_` form replaces it (w·f(T)). Moved after the others, it
    /// adds to the sum.
    #[test]
    fn a_variation_moved_by_priority_adds_to_the_point() {
        let spherical = crate::flame::variations::by_name("spherical").unwrap();
        let (w, x, y) = (0.25, 0.6, -0.8);
        let run = |form: Form, moved: bool, rules: Rules| {
            let mut xf = Xform::linear(Affine::IDENTITY, 1.0, 0.0);
            if form == Form::Post {
                xf.vars[0].weight = 1.0;
            } else {
                xf.vars.clear();
            }
            xf.vars.push(Var {
                moved,
                ..Var::with_form(spherical, form, w)
            });
            let c = CompiledXform::new(&xf, 1.0, rules);
            let p = Pt {
                x,
                y,
                z: 0.0,
                c: 0.0,
            };
            let (q, bad) = c.apply(p, &mut FastRng::new(1));
            assert!(!bad);
            (q.x, q.y)
        };
        let jwf = Rules {
            dialect: Dialect::JWildfire,
            ..Rules::default()
        };
        let r2 = x * x + y * y;
        let (sx, sy) = (w * x / r2, w * y / r2);
        let close = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).abs() + (a.1 - b.1).abs() < 1e-12;
        assert!(close(run(Form::Pre, true, jwf), (x + sx, y + sy)));
        assert!(close(run(Form::Pre, false, jwf), (sx, sy)));
        assert!(close(run(Form::Post, true, jwf), (x + sx, y + sy)));
        assert!(close(run(Form::Post, false, jwf), (sx, sy)));
    }

    #[test]
    fn opacity_adjustment_oracles() {
        assert!((adjust_opacity(0.5) - 0.1).abs() < 1e-12);
        assert!((adjust_opacity(0.25) - 0.01).abs() < 1e-12);
        assert_eq!(adjust_opacity(1.0), 1.0);
        assert_eq!(adjust_opacity(0.0), 0.0);
        // Fractorium plots the opacity itself.
        assert_eq!(plotted_opacity(0.4, Dialect::Fractorium), 0.4);
        assert_eq!(plotted_opacity(1.5, Dialect::Fractorium), 1.0);
        assert_eq!(plotted_opacity(-0.2, Dialect::Fractorium), 0.0);
        assert_eq!(plotted_opacity(f64::NAN, Dialect::Fractorium), 0.0);
        assert!((plotted_opacity(0.5, Dialect::Flam3) - 0.1).abs() < 1e-12);
    }
}
