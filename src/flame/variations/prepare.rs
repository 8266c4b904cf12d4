//! Preparing a variation for evaluation — its stored parameters normalised, its shared data
//! fetched, its derived values computed — and evaluating one variation at one point, as an
//! xform with only that variation would.

use super::def::{Assign, Dialect, Form, Prepared, Rules, ZRule, flag};
use super::point::{Acc, VarIn};
use super::registry::{info, jwildfire_runs_after, jwildfire_twin};
use super::{V3, VarId, shared};
use crate::flame::affine::Affine;
use crate::flame::rng::FastRng;

impl Prepared {
    /// Prepare variation `id` used in `form` with weight `w` and stored parameters `params`
    /// (missing ones take their defaults).
    pub fn new(id: VarId, form: Form, w: f64, params: &[f64], aff: Affine, compat: bool) -> Self {
        Self::with_texts(id, form, w, params, &[], aff, compat)
    }

    /// [`Prepared::new`] with stored text parameters `texts` (missing ones take their
    /// defaults).
    pub fn with_texts(
        id: VarId,
        form: Form,
        w: f64,
        params: &[f64],
        texts: &[String],
        aff: Affine,
        compat: bool,
    ) -> Self {
        let rules = Rules {
            compat,
            ..Rules::default()
        };
        Self::for_flame(id, form, w, params, texts, aff, rules)
    }

    /// Prepare variation `id` used in `form` as the program that wrote the flame runs it
    /// (`rules`): in a JWildfire flame, JWildfire's own formula where it differs from the
    /// others' (chosen here, once, so that the others pay nothing per point), in the phase
    /// JWildfire runs it, and with JWildfire's z for 2-D variations.
    pub fn for_flame(
        id: VarId,
        form: Form,
        w: f64,
        params: &[f64],
        texts: &[String],
        aff: Affine,
        rules: Rules,
    ) -> Self {
        let jwildfire = rules.dialect == Dialect::JWildfire;
        let def = jwildfire
            .then(|| jwildfire_twin(id, form))
            .flatten()
            .unwrap_or_else(|| info(id));
        let form = if def.has(flag::PRE_ONLY) {
            Form::Pre
        } else if def.has(flag::POST_ONLY) {
            Form::Post
        } else {
            form
        };
        let zrule = match form {
            Form::Regular if jwildfire && rules.preserve_z => ZRule::Weighted,
            Form::Regular => ZRule::Zero,
            _ if def.assign == Assign::Set => ZRule::Input,
            _ => ZRule::Zero,
        };
        let texts = def
            .texts
            .iter()
            .enumerate()
            .map(|(i, d)| d.normalise(texts.get(i).map_or(d.default, |t| t.as_str())))
            .collect();
        let flam3 = def.has(flag::FLAM3);
        let p = def
            .params
            .iter()
            .enumerate()
            .map(|(i, d)| {
                let v = params.get(i).copied().unwrap_or(d.default);
                if flam3 { v } else { d.normalise(v) }
            })
            .collect();
        let mut v = Prepared {
            id,
            def,
            form,
            w,
            p,
            derived_at: def.params.len(),
            aff,
            compat: rules.compat,
            dialect: rules.dialect,
            zrule,
            assign: def.assign,
            state: Box::default(),
            data: None,
            texts,
            palette: None,
        };
        if let Some(sd) = &def.shared {
            v.data = Some(shared::data(id, sd, &v.p, &v.texts));
        }
        if let Some(f) = def.prepare {
            f(&mut v);
        }
        v
    }

    /// A variation JWildfire runs after the others by default ([`jwildfire_runs_after`]:
    /// `flatten`) that the flame's priority 0 puts among the regular ones: its own formula,
    /// in its place among them (JWildfire 9.00 runs each variation in the phase its stored
    /// priority names, in the xform's order).
    pub fn kept_among_regular(mut self, rules: Rules) -> Self {
        if rules.dialect == Dialect::JWildfire && jwildfire_runs_after(self.id) {
            self.def = info(self.id);
            self.form = Form::Regular;
            self.assign = self.def.assign;
            self.zrule = if rules.preserve_z {
                ZRule::Weighted
            } else {
                ZRule::Zero
            };
        }
        self
    }

    /// The variation as JWildfire runs a regular variation its priority moved before
    /// (`NAME_fx_priority` −1, `form` pre) or after (1, post) the others (JWildfire 9.00's
    /// `EnforcedPreVariationTransformationStep` and `…PostVariationTransformationStep`):
    /// `self`, prepared as the regular variation (its formula, not that of a `pre_`/`post_`
    /// variation of the same name), is given a copy of the point and adds its output to the
    /// point, as it adds to the sum among the regular ones, where a `pre_`/`post_` form
    /// replaces the point. The output z follows the regular rule (0, or the weighted input z
    /// with "preserve Z").
    pub fn moved_by_priority(mut self, form: Form, rules: Rules) -> Self {
        let own_phase = self.def.has(flag::PRE_ONLY | flag::POST_ONLY);
        if form == Form::Regular || (own_phase && !jwildfire_runs_after(self.id)) {
            return self;
        }
        self.form = form;
        self.assign = Assign::Sum;
        self.zrule = if rules.dialect == Dialect::JWildfire && rules.preserve_z {
            ZRule::Weighted
        } else {
            ZRule::Zero
        };
        self
    }
}

/// Evaluate one variation at one point, as an xform would with only this variation: the running
/// output starts at `acc` (zero for a fresh xform). Returns the running output after the
/// variation (for `pre_` forms, the new transformed point in x, y, z and the colour).
#[allow(clippy::too_many_arguments)]
pub fn eval_point(
    id: VarId,
    form: Form,
    weight: f64,
    params: &[f64],
    aff: Affine,
    compat: bool,
    t: V3,
    acc: Acc,
    rng: &mut FastRng,
) -> Acc {
    let v = Prepared::new(id, form, weight, params, aff, compat);
    eval_prepared(&v, t, acc, false, rng)
}

/// [`eval_point`] with a prepared variation (stateful variations keep their state between
/// calls). With `poison`, quantities the variation did not declare are NaN.
pub fn eval_prepared(v: &Prepared, t: V3, mut acc: Acc, poison: bool, rng: &mut FastRng) -> Acc {
    let color = acc.color;
    match v.form {
        Form::Regular => {
            let tin = VarIn::new(t[0], t[1], t[2], color, v.def.needs, poison);
            let o = v.eval(&tin, &mut acc, rng);
            acc.x += o[0];
            acc.y += o[1];
            acc.z += o[2];
            acc
        }
        Form::Pre => {
            let mut tr = t;
            let tin = VarIn::new(t[0], t[1], t[2], color, v.def.needs, poison);
            let o = v.eval(&tin, &mut acc, rng);
            v.assign(&mut tr, o);
            Acc {
                x: tr[0],
                y: tr[1],
                z: tr[2],
                color: acc.color,
                hide: acc.hide,
                rgb: acc.rgb,
            }
        }
        Form::Post => {
            acc.x = t[0];
            acc.y = t[1];
            acc.z = t[2];
            let tin = VarIn::new(t[0], t[1], t[2], color, v.def.needs, poison);
            let o = v.eval(&tin, &mut acc, rng);
            v.assign_acc(&mut acc, o);
            acc
        }
    }
}
