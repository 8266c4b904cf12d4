//! Variations: the non-linear functions an xform applies after its affine map.
//!
//! One registry holds every variation ugnis knows: flam3's classic list (ids 0–98 in flam3's
//! order, so that flam3's numeric `var` lists keep working), Fractorium's catalogue and the
//! JWildfire variations that real files use. Each entry ([`VarDef`]) names the variation, its
//! parameters with defaults and ranges, which per-point quantities it reads, and its formula.
//!
//! A variation is used in one of three forms ([`Form`]), as Fractorium and JWildfire do:
//! - regular: the outputs of an xform's regular variations are summed;
//! - `pre_NAME`: applied to the affine-transformed point before the regular variations,
//!   replacing it (or adding to it, for the variations whose [`Assign`] is `Sum`);
//! - `post_NAME`: applied to the summed result, replacing (or adding to) it.
//!
//! A formula receives the point as a [`VarIn`] (with r², r, x/r, y/r and both angles computed
//! once for the xform, as flam3 and Fractorium precompute them), the xform's running output as
//! an [`Acc`] (a few variations read or rewrite what earlier variations summed, or set the
//! colour), and returns its own weighted output `[x, y, z]`.
//!
//! Conventions: angles follow flam3 — `atan_xy` = atan2(x, y), `atan_yx` = atan2(y, x) (the usual
//! polar angle); `ux` = x/r, `uy` = y/r, with r replaced by `f64::EPSILON` when it is 0.
//! Fractorium's affine letters A B C D E F are [`Affine`]'s a b e c d f
//! (x' = A·x + B·y + C, y' = D·x + E·y + F).
//!
//! Helpers the formulas share live in [`util`] (the C/x86 and Java behaviours the source
//! programs rely on, hashes, coordinate systems, complex numbers, special functions) and in
//! `noise` (simplex noise); data that takes long to build (grown aggregates, crystals, meshes,
//! recursive drawings) is built once per parameter values and shared through [`shared`].

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, LazyLock};

pub use crate::flame::affine::Affine;
use crate::flame::rng::FastRng;

mod flam3;
pub use flam3::*;

mod fr_a;
mod fr_b;
mod fr_c;
mod fr_d;
mod fr_e;
mod fr_f;
mod jwf;
mod jwf2;
mod noise;
pub mod shared;
mod text;
pub mod util;

pub use shared::{BuildFn, SharedDef};

/// flam3's `EPS`, the guard its formulas add to denominators.
pub const EPS: f64 = 1e-10;

/// Index of a variation in the registry ([`all`]). Ids 0–98 are flam3's list, in flam3's order.
pub type VarId = u16;

/// An output point `[x, y, z]`.
pub type V3 = [f64; 3];

/// Which per-point quantities a formula reads (bits of [`VarDef::needs`]).
pub mod need {
    /// `sumsq` = x² + y².
    pub const SUMSQ: u8 = 1;
    /// `sqrt` = r.
    pub const SQRT: u8 = 2;
    /// `ux` = x/r and `uy` = y/r.
    pub const ANGLES: u8 = 4;
    /// `atan_xy` = atan2(x, y).
    pub const ATAN_XY: u8 = 8;
    /// `atan_yx` = atan2(y, x).
    pub const ATAN_YX: u8 = 16;
    pub const ALL: u8 = 31;
}

/// Properties of a variation (bits of [`VarDef::flags`]).
pub mod flag {
    /// The formula computes its own z. Without this flag the framework sets the output z
    /// (0 for a regular variation, the input z for a `Set` pre_/post_ form).
    pub const WRITES_Z: u32 = 1;
    /// The formula reads the input z (a 3-D variation).
    pub const USES_Z: u32 = 2;
    /// The output depends on random numbers.
    pub const RANDOM: u32 = 4;
    /// Writes the colour coordinate ("direct colour" variations).
    pub const SETS_COLOR: u32 = 8;
    /// Reads the colour coordinate.
    pub const USES_COLOR: u32 = 16;
    /// Reads the running sum of the xform's earlier variations.
    pub const READS_ACC: u32 = 32;
    /// Rewrites the running sum of the xform's earlier variations.
    pub const WRITES_ACC: u32 = 64;
    /// Carries state from one call to the next.
    pub const STATEFUL: u32 = 128;
    /// One of flam3's classic variations: flam3's semantics (no parameter clamping).
    pub const FLAM3: u32 = 256;
    /// Not offered by name (a placeholder keeping flam3's numbering).
    pub const HIDDEN: u32 = 512;
    /// Exists only as `post_NAME`.
    pub const POST_ONLY: u32 = 1024;
    /// Behaves differently with Fractorium's flam3-compatibility switch off.
    pub const COMPAT: u32 = 2048;
    /// From JWildfire (not in Fractorium).
    pub const JWILDFIRE: u32 = 4096;
    /// Reads the xform's affine coefficients.
    pub const USES_AFFINE: u32 = 8192;
    /// May hide the point: the orbit goes on, the sample is not drawn (JWildfire's crops).
    pub const HIDES: u32 = 16384;
}

/// Regular, `pre_` or `post_` use of a variation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Form {
    #[default]
    Regular,
    Pre,
    Post,
}

impl Form {
    /// The attribute prefix: "", "pre_" or "post_".
    pub fn prefix(self) -> &'static str {
        match self {
            Form::Regular => "",
            Form::Pre => "pre_",
            Form::Post => "post_",
        }
    }
}

/// How a `pre_`/`post_` form combines its output with the point it was given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Assign {
    /// The output replaces the point.
    Set,
    /// The output is added to the point (blurs).
    Sum,
}

/// How a parameter's value is normalised before use (Fractorium's parameter types).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamKind {
    /// Clamped to [min, max].
    Real,
    /// Wrapped into [min, max).
    Cyclic,
    /// Clamped; a value within 1e-6 of 0 becomes ±`f64::EPSILON`.
    NonZero,
    /// Rounded (half up) and clamped.
    Int,
    /// Rounded and clamped; 0 becomes ±1.
    IntNonZero,
}

/// A text parameter (JWildfire's "resources": a string, stored in files as the hex digits of
/// its UTF-8 bytes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TextParam {
    pub name: &'static str,
    pub default: &'static str,
    /// Most bytes a value may have (longer ones are cut at a character boundary).
    pub max_len: usize,
}

impl TextParam {
    /// `v` cut to at most [`TextParam::max_len`] bytes at a character boundary.
    pub fn normalise(&self, v: &str) -> String {
        let mut end = v.len().min(self.max_len);
        while !v.is_char_boundary(end) {
            end -= 1;
        }
        v[..end].to_string()
    }
}

/// One parameter of a variation: full attribute name (e.g. `julian_power`), default and range.
#[derive(Clone, Copy, Debug)]
pub struct Param {
    pub name: &'static str,
    pub default: f64,
    pub kind: ParamKind,
    pub min: f64,
    pub max: f64,
}

impl Param {
    /// The value a formula sees for the stored value `v`.
    pub fn normalise(&self, v: f64) -> f64 {
        let (lo, hi) = (self.min, self.max);
        match self.kind {
            ParamKind::Real => v.clamp(lo, hi),
            ParamKind::Cyclic => {
                if v > hi {
                    lo + (v - lo) % (hi - lo)
                } else if v < lo {
                    hi - (hi - v) % (hi - lo)
                } else {
                    v
                }
            }
            ParamKind::NonZero => {
                let c = v.clamp(lo, hi);
                if c.abs() < 1e-6 {
                    if c < 0.0 { -f64::EPSILON } else { f64::EPSILON }
                } else {
                    c
                }
            }
            ParamKind::Int => (v + 0.5)
                .floor()
                .clamp(lo, hi)
                .clamp(-2147483648.0, 2147483647.0),
            ParamKind::IntNonZero => {
                let i = (v + 0.5)
                    .floor()
                    .clamp(lo, hi)
                    .clamp(-2147483648.0, 2147483647.0);
                if i == 0.0 {
                    if v < 0.0 { -1.0 } else { 1.0 }
                } else {
                    i
                }
            }
        }
    }
}

/// A real parameter without bounds.
pub const fn p(name: &'static str, default: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::Real,
        min: f64::MIN,
        max: f64::MAX,
    }
}

/// A real parameter clamped to [min, max].
pub const fn p_range(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::Real,
        min,
        max,
    }
}

/// A real parameter wrapped into [min, max).
pub const fn p_cyclic(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::Cyclic,
        min,
        max,
    }
}

/// A real parameter that must not be 0.
pub const fn p_nonzero(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::NonZero,
        min,
        max,
    }
}

/// An integer parameter.
pub const fn p_int(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::Int,
        min,
        max,
    }
}

/// An integer parameter that must not be 0.
pub const fn p_int_nonzero(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::IntNonZero,
        min,
        max,
    }
}

/// What a variation reads about its input point.
#[derive(Clone, Copy, Debug, Default)]
pub struct VarIn {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// x² + y².
    pub sumsq: f64,
    /// r = √(x² + y²).
    pub sqrt: f64,
    /// x / r (r replaced by `f64::EPSILON` when 0).
    pub ux: f64,
    /// y / r (r replaced by `f64::EPSILON` when 0).
    pub uy: f64,
    /// atan2(x, y).
    pub atan_xy: f64,
    /// atan2(y, x).
    pub atan_yx: f64,
    /// The palette coordinate after the xform's colour blend.
    pub color: f64,
}

impl VarIn {
    /// The input point with the quantities of `needs` computed. With `poison`, quantities not
    /// asked for are NaN (tests use it to catch formulas that read what they did not declare);
    /// otherwise they are 0.
    #[inline(always)]
    pub fn new(x: f64, y: f64, z: f64, color: f64, needs: u8, poison: bool) -> VarIn {
        let fill = if poison { f64::NAN } else { 0.0 };
        let mut t = VarIn {
            x,
            y,
            z,
            sumsq: fill,
            sqrt: fill,
            ux: fill,
            uy: fill,
            atan_xy: fill,
            atan_yx: fill,
            color,
        };
        if needs & (need::SUMSQ | need::SQRT | need::ANGLES) != 0 {
            t.sumsq = x * x + y * y;
        }
        if needs & (need::SQRT | need::ANGLES) != 0 {
            t.sqrt = (x * x + y * y).sqrt();
        }
        if needs & need::ANGLES != 0 {
            let r = (x * x + y * y).sqrt();
            let r = if r == 0.0 { f64::EPSILON } else { r };
            t.ux = x / r;
            t.uy = y / r;
        }
        if needs & need::ATAN_XY != 0 {
            t.atan_xy = x.atan2(y);
        }
        if needs & need::ATAN_YX != 0 {
            t.atan_yx = y.atan2(x);
        }
        t
    }
}

/// The xform's running output: the sum of its regular variations so far (or, for `pre_` and
/// `post_` forms, the point being transformed) and the colour coordinate.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Acc {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub color: f64,
    /// The sample is not drawn (set by the [`flag::HIDES`] variations).
    pub hide: bool,
}

/// A variation's formula: weighted output for input `t`; may read or change `acc` (only the
/// variations flagged `READS_ACC`, `WRITES_ACC` or `SETS_COLOR` do).
pub type EvalFn = fn(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3;

/// Fills a prepared variation's derived values (appended to `v.p` after the parameters).
pub type PrepareFn = fn(v: &mut Prepared);

/// Per-point quantities of a batch of points, as parallel arrays of one length.
pub struct SoaIn<'a> {
    pub x: &'a [f64],
    pub y: &'a [f64],
    pub z: &'a [f64],
    pub sumsq: &'a [f64],
    pub sqrt: &'a [f64],
    pub ux: &'a [f64],
    pub uy: &'a [f64],
    pub atan_xy: &'a [f64],
    pub atan_yx: &'a [f64],
    pub color: &'a [f64],
}

/// Running outputs of a batch of points.
pub struct SoaAcc<'a> {
    pub x: &'a mut [f64],
    pub y: &'a mut [f64],
    pub z: &'a mut [f64],
    pub color: &'a mut [f64],
    /// Set where a variation hides the point (only formulas called point by point hide).
    pub hide: &'a mut [bool],
}

/// A regular variation applied to a batch: adds its outputs to `acc`.
pub type BatchFn = fn(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng);

/// One registry entry.
#[derive(Clone, Copy)]
pub struct VarDef {
    /// Canonical name (flam3's for flam3's variations, else Fractorium's or JWildfire's).
    pub name: &'static str,
    pub params: &'static [Param],
    /// Text parameters (few variations have any).
    pub texts: &'static [TextParam],
    /// [`need`] bits.
    pub needs: u8,
    /// [`flag`] bits.
    pub flags: u32,
    /// How the `pre_`/`post_` forms combine their output.
    pub assign: Assign,
    pub eval: EvalFn,
    pub prepare: Option<PrepareFn>,
    /// Expensive data built from some parameters, shared between prepared copies
    /// ([`Prepared::data`]).
    pub shared: Option<SharedDef>,
    /// A specialised batch version of a regular use (optional; the generic loop is used
    /// otherwise).
    pub batch: Option<BatchFn>,
}

impl std::fmt::Debug for VarDef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("VarDef").field("name", &self.name).finish()
    }
}

impl VarDef {
    /// A variation without parameters that reads only x and y, with `Set` pre/post forms.
    pub const fn new(name: &'static str, eval: EvalFn) -> VarDef {
        VarDef {
            name,
            params: &[],
            texts: &[],
            needs: 0,
            flags: 0,
            assign: Assign::Set,
            eval,
            prepare: None,
            shared: None,
            batch: None,
        }
    }
    pub const fn params(mut self, params: &'static [Param]) -> VarDef {
        self.params = params;
        self
    }
    pub const fn texts(mut self, texts: &'static [TextParam]) -> VarDef {
        self.texts = texts;
        self
    }
    pub const fn needs(mut self, needs: u8) -> VarDef {
        self.needs = needs;
        self
    }
    pub const fn flags(mut self, flags: u32) -> VarDef {
        self.flags = flags;
        self
    }
    /// Pre/post forms add their output to the point.
    pub const fn sum(mut self) -> VarDef {
        self.assign = Assign::Sum;
        self
    }
    pub const fn prepare(mut self, f: PrepareFn) -> VarDef {
        self.prepare = Some(f);
        self
    }
    /// Data built by `build` from the parameters at the indices `key`, kept in
    /// [`Prepared::data`] and shared between the prepared copies with the same key values.
    pub const fn shared(mut self, key: &'static [usize], build: BuildFn) -> VarDef {
        self.shared = Some(SharedDef { key, build });
        self
    }
    pub const fn batch(mut self, f: BatchFn) -> VarDef {
        self.batch = Some(f);
        self
    }

    pub fn defaults(&self) -> Vec<f64> {
        self.params.iter().map(|p| p.default).collect()
    }

    pub fn has(&self, f: u32) -> bool {
        self.flags & f != 0
    }

    /// Is a 3-D variation (its output depends on z).
    pub fn is_3d(&self) -> bool {
        self.has(flag::USES_Z)
    }
}

/// State carried between calls by the few stateful variations (shared by the threads of a
/// render; relaxed atomics, as the state only decorrelates successive calls).
#[derive(Debug, Default)]
pub struct VarState([AtomicU64; 4]);

impl VarState {
    pub fn get(&self, i: usize) -> f64 {
        f64::from_bits(self.0[i].load(Ordering::Relaxed))
    }
    pub fn set(&self, i: usize, v: f64) {
        self.0[i].store(v.to_bits(), Ordering::Relaxed);
    }
}

impl Clone for VarState {
    fn clone(&self) -> Self {
        let s = VarState::default();
        for i in 0..4 {
            s.set(i, self.get(i));
        }
        s
    }
}

/// A variation ready to evaluate: its weight, normalised parameters followed by derived values,
/// and the xform's affine map.
#[derive(Clone, Debug)]
pub struct Prepared {
    pub id: VarId,
    pub def: &'static VarDef,
    pub form: Form,
    pub w: f64,
    /// Parameters in [`VarDef::params`] order, then values derived by [`VarDef::prepare`].
    pub p: Vec<f64>,
    /// The xform's pre-affine map.
    pub aff: Affine,
    /// Fractorium's flam3-compatibility switch (on by default).
    pub compat: bool,
    pub state: VarState,
    /// The data of [`VarDef::shared`] for these parameters (built once per distinct value and
    /// shared through a process-wide cache); `None` for the variations without.
    pub data: Option<Arc<[f64]>>,
    /// Text parameters in [`VarDef::texts`] order.
    pub texts: Vec<String>,
}

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
        let def = info(id);
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
            aff,
            compat,
            state: VarState::default(),
            data: None,
            texts,
        };
        if let Some(sd) = &def.shared {
            v.data = Some(shared::data(id, sd, &v.p, &v.texts));
        }
        if let Some(f) = def.prepare {
            f(&mut v);
        }
        v
    }

    /// The shared data ([`Prepared::data`]); empty for a variation without.
    #[inline(always)]
    pub fn data(&self) -> &[f64] {
        self.data.as_deref().unwrap_or(&[])
    }

    /// The output z of a formula that does not compute one: 0 for a regular variation, the
    /// input z for a `pre_`/`post_` form that replaces the point, 0 for one that adds to it.
    #[inline(always)]
    pub fn default_z(&self, t: &VarIn) -> f64 {
        if self.form != Form::Regular && self.def.assign == Assign::Set {
            t.z
        } else {
            0.0
        }
    }

    /// Evaluate the formula: the weighted output for input `t`.
    #[inline(always)]
    pub fn eval(&self, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
        self.eval_with(self.def.eval, t, acc, rng)
    }

    /// [`Prepared::eval`] with the formula `f` (the variation's own: a function item inlines).
    #[inline(always)]
    fn eval_with(
        &self,
        f: impl Fn(&Prepared, &VarIn, &mut Acc, &mut FastRng) -> V3,
        t: &VarIn,
        acc: &mut Acc,
        rng: &mut FastRng,
    ) -> V3 {
        let mut o = f(self, t, acc, rng);
        if self.def.flags & flag::WRITES_Z == 0 {
            o[2] = self.default_z(t);
        }
        o
    }

    /// Apply as a `pre_` form to the transformed point `tr` (colour `color`).
    #[inline]
    pub fn apply_pre(&self, tr: &mut V3, acc: &mut Acc, color: f64, rng: &mut FastRng) {
        let t = VarIn::new(tr[0], tr[1], tr[2], color, self.def.needs, false);
        let o = self.eval(&t, acc, rng);
        self.assign(tr, o);
    }

    /// Apply as a `post_` form to the xform's summed output `acc`.
    #[inline]
    pub fn apply_post(&self, acc: &mut Acc, color: f64, rng: &mut FastRng) {
        let t = VarIn::new(acc.x, acc.y, acc.z, color, self.def.needs, false);
        let o = self.eval(&t, acc, rng);
        self.assign_acc(acc, o);
    }

    /// Combines the output `o` of a `pre_`/`post_` form with the point `p` it transformed:
    /// replaces it or adds to it, as [`VarDef::assign`] says.
    #[inline(always)]
    fn assign(&self, p: &mut V3, o: V3) {
        match self.def.assign {
            Assign::Set => *p = o,
            Assign::Sum => {
                p[0] += o[0];
                p[1] += o[1];
                p[2] += o[2];
            }
        }
    }

    /// [`Prepared::assign`] to the point held in `acc`.
    #[inline(always)]
    fn assign_acc(&self, acc: &mut Acc, o: V3) {
        let mut p = [acc.x, acc.y, acc.z];
        self.assign(&mut p, o);
        [acc.x, acc.y, acc.z] = p;
    }

    /// Apply a regular use to a batch (specialised version if the variation has one).
    #[inline]
    pub fn apply_batch(&self, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
        match self.def.batch {
            Some(f) => f(self, s, acc, rng),
            None => generic_batch(self, s, acc, rng),
        }
    }
}

/// The generic batch loop: the formula called point by point.
pub fn generic_batch(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
    batch_with(v, s, acc, rng, v.def.eval)
}

/// The batch loop calling `f` point by point, as [`Prepared::eval`] does. With `f` a function
/// item (not a pointer) the formula is inlined into the loop: see [`inline_batch!`].
#[inline(always)]
pub fn batch_with(
    v: &Prepared,
    s: &SoaIn,
    acc: &mut SoaAcc,
    rng: &mut FastRng,
    f: impl Fn(&Prepared, &VarIn, &mut Acc, &mut FastRng) -> V3,
) {
    let n = acc.x.len();
    for j in 0..n {
        let t = VarIn {
            x: s.x[j],
            y: s.y[j],
            z: s.z[j],
            sumsq: s.sumsq[j],
            sqrt: s.sqrt[j],
            ux: s.ux[j],
            uy: s.uy[j],
            atan_xy: s.atan_xy[j],
            atan_yx: s.atan_yx[j],
            color: s.color[j],
        };
        let mut a = Acc {
            x: acc.x[j],
            y: acc.y[j],
            z: acc.z[j],
            color: acc.color[j],
            hide: false,
        };
        let o = v.eval_with(&f, &t, &mut a, rng);
        acc.x[j] = a.x + o[0];
        acc.y[j] = a.y + o[1];
        acc.z[j] = a.z + o[2];
        acc.color[j] = a.color;
        acc.hide[j] |= a.hide;
    }
}

/// A [`BatchFn`] for the formula `$f` (an [`EvalFn`]-shaped function): on CPUs with AVX2 and
/// FMA, [`batch_with`] with the formula inlined — no call through a pointer and no input
/// record in memory per point; elsewhere [`generic_batch`] (one copy of the loop each keeps the
/// build short). Both give the same bits: Rust never fuses a multiply and an add on its own.
/// For the variations real files use most.
macro_rules! inline_batch {
    ($f:path) => {{
        fn batch(
            v: &$crate::flame::variations::Prepared,
            s: &$crate::flame::variations::SoaIn,
            acc: &mut $crate::flame::variations::SoaAcc,
            rng: &mut $crate::flame::rng::FastRng,
        ) {
            #[cfg(target_arch = "x86_64")]
            if $crate::flame::fastmath::has_avx2_fma() {
                #[target_feature(enable = "avx2,fma")]
                fn avx2(
                    v: &$crate::flame::variations::Prepared,
                    s: &$crate::flame::variations::SoaIn,
                    acc: &mut $crate::flame::variations::SoaAcc,
                    rng: &mut $crate::flame::rng::FastRng,
                ) {
                    $crate::flame::variations::batch_with(v, s, acc, rng, $f)
                }
                // SAFETY: the CPU has reported AVX2 and FMA.
                return unsafe { avx2(v, s, acc, rng) };
            }
            $crate::flame::variations::generic_batch(v, s, acc, rng)
        }
        batch as $crate::flame::variations::BatchFn
    }};
}
pub(crate) use inline_batch;

/// Every variation, by id.
pub fn all() -> &'static [&'static VarDef] {
    &REGISTRY.defs
}

/// Number of variations in the registry.
pub fn count() -> usize {
    REGISTRY.defs.len()
}

pub fn info(id: VarId) -> &'static VarDef {
    REGISTRY.defs[id as usize]
}

struct Registry {
    defs: Vec<&'static VarDef>,
    /// Lower-case name → id (hidden entries excluded).
    names: HashMap<String, VarId>,
    /// Lower-case full parameter name → (id, parameter index).
    params: HashMap<String, (VarId, usize)>,
    /// Lower-case full text parameter name → (id, text index).
    texts: HashMap<String, (VarId, usize)>,
}

static REGISTRY: LazyLock<Registry> = LazyLock::new(|| {
    let groups: [&'static [VarDef]; 9] = [
        flam3::DEFS,
        fr_a::DEFS,
        fr_b::DEFS,
        fr_c::DEFS,
        fr_d::DEFS,
        fr_e::DEFS,
        fr_f::DEFS,
        jwf::DEFS,
        jwf2::DEFS,
    ];
    let defs: Vec<&'static VarDef> = groups.iter().flat_map(|g| g.iter()).collect();
    let mut names = HashMap::new();
    let mut params = HashMap::new();
    let mut texts = HashMap::new();
    for (i, d) in defs.iter().enumerate() {
        if d.has(flag::HIDDEN) {
            continue;
        }
        let prev = names.insert(d.name.to_ascii_lowercase(), i as VarId);
        debug_assert!(prev.is_none(), "variation {} registered twice", d.name);
        for (k, pa) in d.params.iter().enumerate() {
            params.insert(pa.name.to_ascii_lowercase(), (i as VarId, k));
        }
        for (k, t) in d.texts.iter().enumerate() {
            texts.insert(t.name.to_ascii_lowercase(), (i as VarId, k));
        }
    }
    Registry {
        defs,
        names,
        params,
        texts,
    }
});

/// A regular variation by name (case-insensitive).
pub fn by_name(name: &str) -> Option<VarId> {
    let key = name.to_ascii_lowercase();
    let id = *REGISTRY.names.get(&key)?;
    (!info(id).has(flag::POST_ONLY)).then_some(id)
}

/// The variation and form an attribute name denotes: `NAME`, `pre_NAME` or `post_NAME`
/// (case-insensitive). flam3's `pre_blur` is the `pre_` form of `gaussian_blur`.
pub fn parse_name(attr: &str) -> Option<(VarId, Form)> {
    let key = unalias(&attr.to_ascii_lowercase());
    if key == "pre_blur" {
        return Some((GAUSSIAN_BLUR, Form::Pre));
    }
    if let Some(&id) = REGISTRY.names.get(&key) {
        // Post-only variations are registered under their `post_` name.
        let form = if info(id).has(flag::POST_ONLY) {
            Form::Post
        } else {
            Form::Regular
        };
        return Some((id, form));
    }
    for (prefix, form) in [("pre_", Form::Pre), ("post_", Form::Post)] {
        if let Some(rest) = key.strip_prefix(prefix)
            && let Some(&id) = REGISTRY.names.get(rest)
        {
            return Some((id, form));
        }
    }
    None
}

/// The attribute name of a variation used in `form`.
pub fn attr_name(id: VarId, form: Form) -> String {
    let d = info(id);
    if form == Form::Pre && id == GAUSSIAN_BLUR {
        return "pre_blur".to_string();
    }
    if d.has(flag::POST_ONLY) {
        return d.name.to_string();
    }
    format!("{}{}", form.prefix(), d.name)
}

/// The attribute name of parameter `k` of a variation used in `form`.
pub fn param_attr_name(id: VarId, form: Form, k: usize) -> String {
    let d = info(id);
    if d.has(flag::POST_ONLY) {
        return d.params[k].name.to_string();
    }
    format!("{}{}", form.prefix(), d.params[k].name)
}

/// The attribute name of text parameter `k` of a variation used in `form`.
pub fn text_attr_name(id: VarId, form: Form, k: usize) -> String {
    format!("{}{}", form.prefix(), info(id).texts[k].name)
}

/// If `attr` names a text parameter — `TEXT`, `pre_TEXT` or `post_TEXT` — the variation, form
/// and text index (case-insensitive).
pub fn text_of(attr: &str) -> Option<(VarId, Form, usize)> {
    let key = attr.to_ascii_lowercase();
    if let Some(&(id, k)) = REGISTRY.texts.get(&key) {
        return Some((id, Form::Regular, k));
    }
    [("pre_", Form::Pre), ("post_", Form::Post)]
        .into_iter()
        .find_map(|(prefix, form)| {
            let &(id, k) = REGISTRY.texts.get(key.strip_prefix(prefix)?)?;
            Some((id, form, k))
        })
}

/// Parameter names other programs write for a variation's parameters.
const PARAM_ALIASES: &[(&str, &str)] = &[
    // Apophysis 7X writes mobius's parameters without the variation prefix.
    ("re_a", "mobius_re_a"),
    ("im_a", "mobius_im_a"),
    ("re_b", "mobius_re_b"),
    ("im_b", "mobius_im_b"),
    ("re_c", "mobius_re_c"),
    ("im_c", "mobius_im_c"),
    ("re_d", "mobius_re_d"),
    ("im_d", "mobius_im_d"),
    // JWildfire writes waves2_radial's parameters with a "w2r" infix.
    ("waves2_radial_w2r_freqx", "waves2_radial_freqx"),
    ("waves2_radial_w2r_scalex", "waves2_radial_scalex"),
    ("waves2_radial_w2r_freqy", "waves2_radial_freqy"),
    ("waves2_radial_w2r_scaley", "waves2_radial_scaley"),
    ("waves2_radial_w2r_null", "waves2_radial_null"),
    ("waves2_radial_w2r_distance", "waves2_radial_distance"),
    // JWildfire 7 wrote the direct-colour variations' z settings the other way round.
    ("dc_mandala_z_scale", "dc_mandala_scale_z"),
    ("dc_mandala_z_offset", "dc_mandala_offset_z"),
    ("dc_inversion_z_scale", "dc_inversion_scale_z"),
    ("dc_inversion_z_offset", "dc_inversion_offset_z"),
    ("dc_poincaredisc_z_scale", "dc_poincaredisc_scale_z"),
    ("dc_poincaredisc_z_offset", "dc_poincaredisc_offset_z"),
    ("dc_circuits_z_scale", "dc_circuits_scale_z"),
    ("dc_circuits_z_offset", "dc_circuits_offset_z"),
    ("dc_turbulence_z_scale", "dc_turbulence_scale_z"),
    ("dc_turbulence_z_offset", "dc_turbulence_offset_z"),
    ("dc_gabornoise_z_scale", "dc_gabornoise_scale_z"),
    ("dc_gabornoise_z_offset", "dc_gabornoise_offset_z"),
];

/// Variation names other programs use for a variation of the registry (lower case), also as
/// the prefix of its parameters.
const NAME_ALIASES: &[(&str, &str)] = &[("flower_db", "flowerdb")];

/// `key` (lower case) with an alias prefix replaced by the registry's name.
fn unalias(key: &str) -> String {
    for (alias, name) in NAME_ALIASES {
        for prefix in ["", "pre_", "post_"] {
            if let Some(rest) = key.strip_prefix(prefix).and_then(|k| k.strip_prefix(alias))
                && (rest.is_empty() || rest.starts_with('_'))
            {
                return format!("{prefix}{name}{rest}");
            }
        }
    }
    key.to_string()
}

/// If `attr` names a parameter — `PARAM`, `pre_PARAM` or `post_PARAM` — the variation, form
/// and parameter index (case-insensitive; known aliases accepted).
pub fn param_of(attr: &str) -> Option<(VarId, Form, usize)> {
    let key = unalias(&attr.to_ascii_lowercase());
    let lookup = |k: &str| -> Option<(VarId, usize)> {
        if let Some(&r) = REGISTRY.params.get(k) {
            return Some(r);
        }
        let alias = PARAM_ALIASES.iter().find(|a| a.0 == k)?.1;
        REGISTRY.params.get(alias).copied()
    };
    if let Some((id, k)) = lookup(&key) {
        let form = if info(id).has(flag::POST_ONLY) {
            Form::Post
        } else {
            Form::Regular
        };
        return Some((id, form, k));
    }
    for (prefix, form) in [("pre_", Form::Pre), ("post_", Form::Post)] {
        if let Some(rest) = key.strip_prefix(prefix)
            && let Some((id, k)) = lookup(rest)
        {
            if form == Form::Pre && id == GAUSSIAN_BLUR {
                continue;
            }
            return Some((id, form, k));
        }
    }
    None
}

/// Names of variations of other programs (JWildfire, Apophysis plugins) that ugnis does not
/// render: an attribute with one of these names is an unsupported variation rather than some
/// other program's setting.
const FOREIGN_VARIATIONS: &[&str] = &[
    "bwraps7",
    "cross2",
    "mandelbrot",
    "oscope",
    "pdj3d",
    "perspective2",
    "wedge_julia_3D",
    "whorl3D",
];

/// True for names (optionally `pre_`/`post_`) of variations of other programs that ugnis does not
/// know: attributes that describe a variation weight rather than a setting.
pub fn is_foreign_variation_name(name: &str) -> bool {
    if parse_name(name).is_some() {
        return false;
    }
    let key = name.to_ascii_lowercase();
    let base = key
        .strip_prefix("pre_")
        .or_else(|| key.strip_prefix("post_"))
        .unwrap_or(&key);
    FOREIGN_VARIATIONS
        .iter()
        .any(|f| f.eq_ignore_ascii_case(&key) || f.eq_ignore_ascii_case(base))
}

/// The flam3 index (0–98) of a variation form, for flam3's numeric `var` lists.
pub fn from_flam3_index(i: usize) -> Option<(VarId, Form)> {
    match i {
        67 => Some((GAUSSIAN_BLUR, Form::Pre)),
        0..=98 => Some((i as VarId, Form::Regular)),
        _ => None,
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The `pre_`/`post_` forms that add their output to the point in Fractorium (the blurs
    /// and the random shapes); every other form replaces it. flam3's `pre_blur` adds too.
    #[test]
    fn blur_forms_add_to_the_point() {
        let sum = [
            "arch",
            "blur",
            "blur3D",
            "blur_circle",
            "blur_heart",
            "blur_square",
            "circleblur",
            "CircleRand",
            "concentric",
            "dc_cube",
            "gaussian_blur",
            "line",
            "Lissajous",
            "pie",
            "pie3D",
            "randCubes",
            "sineblur",
            "sphereblur",
            "Spirograph",
            "square",
            "square3D",
            "starblur",
            "SuperShape3D",
            "waffle",
            "zblur",
            "ztranslate",
        ];
        for name in sum {
            let (id, form) = parse_name(&format!("pre_{name}")).expect(name);
            assert_eq!(form, Form::Pre);
            assert_eq!(info(id).assign, Assign::Sum, "{name}");
        }
        for name in ["linear", "spherical", "julia", "stripes", "hexes"] {
            let (id, _) = parse_name(&format!("pre_{name}")).expect(name);
            assert_eq!(info(id).assign, Assign::Set, "{name}");
        }
        let (id, form) = parse_name("pre_blur").unwrap();
        assert_eq!(
            (id, form, info(id).assign),
            (GAUSSIAN_BLUR, Form::Pre, Assign::Sum)
        );
    }

    /// Every batch loop (compiled for AVX2 and FMA where the CPU has them) gives the same bits
    /// as the formula called point by point (compiled for the baseline CPU), random
    /// variations included: the chaos game's pictures do not depend on the CPU.
    #[test]
    fn batch_loops_match_the_formula_bit_for_bit() {
        let mut gen_rng = FastRng::new(3);
        let n = 256;
        let mut pts: Vec<V3> = (0..n)
            .map(|_| {
                let s = 10f64.powf(gen_rng.f01() * 6.0 - 3.0);
                [
                    (gen_rng.f01() - 0.5) * s,
                    (gen_rng.f01() - 0.5) * s,
                    gen_rng.f01() - 0.5,
                ]
            })
            .collect();
        pts[0] = [0.0, 0.0, 0.0];
        pts[1] = [1e-300, -1e-300, 0.0];
        let aff = Affine {
            a: 0.9,
            b: -0.3,
            c: 0.2,
            d: 0.4,
            e: 1.1,
            f: -0.6,
        };
        let mut checked = 0;
        for (id, def) in all().iter().enumerate() {
            if def.batch.is_none() {
                continue;
            }
            let params: Vec<f64> = def.params.iter().map(|p| p.default + 0.37).collect();
            let v = Prepared::new(id as VarId, Form::Regular, 0.7, &params, aff, true);
            let ts: Vec<VarIn> = pts
                .iter()
                .map(|p| VarIn::new(p[0], p[1], p[2], 0.25, 0xff, false))
                .collect();
            let col = |f: fn(&VarIn) -> f64| ts.iter().map(f).collect::<Vec<f64>>();
            let (x, y, z) = (col(|t| t.x), col(|t| t.y), col(|t| t.z));
            let (sumsq, sqrt) = (col(|t| t.sumsq), col(|t| t.sqrt));
            let (ux, uy) = (col(|t| t.ux), col(|t| t.uy));
            let (atan_xy, atan_yx, color) =
                (col(|t| t.atan_xy), col(|t| t.atan_yx), col(|t| t.color));
            let soa = SoaIn {
                x: &x,
                y: &y,
                z: &z,
                sumsq: &sumsq,
                sqrt: &sqrt,
                ux: &ux,
                uy: &uy,
                atan_xy: &atan_xy,
                atan_yx: &atan_yx,
                color: &color,
            };
            let run = |batched: bool| {
                let (mut ax, mut ay, mut az) = (vec![0.5; n], vec![-0.5; n], vec![0.125; n]);
                let (mut ac, mut hide) = (color.clone(), vec![false; n]);
                let mut acc = SoaAcc {
                    x: &mut ax,
                    y: &mut ay,
                    z: &mut az,
                    color: &mut ac,
                    hide: &mut hide,
                };
                let mut rng = FastRng::new(9);
                if batched {
                    v.apply_batch(&soa, &mut acc, &mut rng);
                } else {
                    generic_batch(&v, &soa, &mut acc, &mut rng);
                }
                (ax, ay, az)
            };
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
            let (b, g) = (run(true), run(false));
            assert_eq!(bits(&b.0), bits(&g.0), "{} x", def.name);
            assert_eq!(bits(&b.1), bits(&g.1), "{} y", def.name);
            assert_eq!(bits(&b.2), bits(&g.2), "{} z", def.name);
            checked += 1;
        }
        // flam3's 99 and the 41 inlined loops of the variations real files use most.
        assert!(checked >= 139, "{checked} batch loops");
    }

    /// The list of foreign names holds only names the registry does not know (an implemented
    /// variation is recognised by the registry, so its entry would be dead).
    #[test]
    fn foreign_names_are_unknown_to_the_registry() {
        for name in FOREIGN_VARIATIONS {
            assert!(parse_name(name).is_none(), "{name} is implemented");
            assert!(is_foreign_variation_name(name));
            assert!(is_foreign_variation_name(&format!("pre_{name}")));
        }
        for known in ["linear3D", "post_mirror_wf", "rose_wf", "julia3Dz"] {
            assert!(!is_foreign_variation_name(known), "{known}");
        }
        assert!(!is_foreign_variation_name("weight"));
    }
}
