//! A registry entry ([`VarDef`]: name, parameters, properties, formula) and a variation prepared
//! for evaluation ([`Prepared`]: weight, normalised parameters and derived values), with how a
//! prepared variation is evaluated at one point in each of its three forms.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use super::palette_index::PaletteIndex;
use super::params::{Param, TextParam};
use super::point::{Acc, SoaAcc, SoaIn, VarIn};
use super::shared::{BuildFn, SharedDef};
use super::{V3, VarId};
use crate::flame::affine::Affine;
use crate::flame::rng::FastRng;

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
    /// Exists only as `pre_NAME` (a JWildfire class of its own, named with its prefix).
    pub const PRE_ONLY: u32 = 32768;
    /// Runs twice per iteration, as JWildfire's "prepost" variations do: once before the
    /// regular variations (in its `pre_` form) and once after them (in its `post_` form). The
    /// formula tells the two calls apart by [`Prepared::form`].
    pub const PREPOST: u32 = 65536;
    /// Gives the point the palette position of a colour: needs the flame's palette
    /// ([`Prepared::give_palette`](super::Prepared::give_palette)).
    pub const PALETTE: u32 = 1 << 17;
    /// A `post_` form whose input is the point the regular variations saw (the affine point,
    /// after the `pre_` forms), not the sum; it reads the sum from the running [`Acc`]
    /// (JWildfire's post variations see both, `pAffineTP` and `pVarTP`).
    pub const READS_AFFINE_POINT: u32 = 1 << 18;
    /// Draws an orbit of its own (with [`STATEFUL`]): every call takes the next point of a
    /// map's orbit kept in the state, whatever the input (hopalong, gumowski_mira, …). The
    /// picture is the stretch of that orbit the render draws.
    pub const OWN_ORBIT: u32 = 1 << 19;
}

/// Regular, `pre_` or `post_` use of a variation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Form {
    /// Applied to the affine-transformed point; the outputs of an xform's regular variations
    /// are summed.
    #[default]
    Regular,
    /// `pre_NAME`: applied to the affine-transformed point before the regular variations.
    Pre,
    /// `post_NAME`: applied to the summed result.
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

/// A variation's formula: weighted output for input `t`; may read or change `acc` (only the
/// variations flagged `READS_ACC`, `WRITES_ACC` or `SETS_COLOR` do).
pub type EvalFn = fn(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3;

/// Fills a prepared variation's derived values (appended to `v.p` after the parameters).
pub type PrepareFn = fn(v: &mut Prepared);

/// A regular variation applied to a batch: adds its outputs to `acc`.
pub type BatchFn = fn(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng);

/// A `pre_`/`post_` form applied to a batch of points in place (`x`, `y`, `z` of one length),
/// giving the bits [`Prepared::apply_pre`] / [`Prepared::apply_post`] give point by point with
/// the same generator: for the variations whose formula reads and writes nothing but the
/// point (no colour, no running sum, no hiding).
pub type FormBatchFn =
    fn(v: &Prepared, x: &mut [f64], y: &mut [f64], z: &mut [f64], rng: &mut FastRng);

/// One registry entry.
#[derive(Clone, Copy)]
pub struct VarDef {
    /// Canonical name (flam3's for flam3's variations, else Fractorium's or JWildfire's).
    pub name: &'static str,
    /// Numeric parameters, with their defaults and ranges.
    pub params: &'static [Param],
    /// Text parameters (few variations have any).
    pub texts: &'static [TextParam],
    /// [`need`](super::need) bits.
    pub needs: u8,
    /// [`flag`] bits.
    pub flags: u32,
    /// How the `pre_`/`post_` forms combine their output.
    pub assign: Assign,
    /// The formula.
    pub eval: EvalFn,
    /// Computes the derived values from the parameters (optional).
    pub prepare: Option<PrepareFn>,
    /// Expensive data built from some parameters, shared between prepared copies
    /// ([`Prepared::data`]).
    pub shared: Option<SharedDef>,
    /// A specialised batch version of a regular use (optional; the generic loop is used
    /// otherwise).
    pub batch: Option<BatchFn>,
    /// A batch loop of the `pre_`/`post_` forms (optional; point by point otherwise).
    pub form_batch: Option<FormBatchFn>,
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
            form_batch: None,
        }
    }
    /// Set the numeric parameters.
    pub const fn params(mut self, params: &'static [Param]) -> VarDef {
        self.params = params;
        self
    }
    /// Set the text parameters.
    pub const fn texts(mut self, texts: &'static [TextParam]) -> VarDef {
        self.texts = texts;
        self
    }
    /// Set the [`need`](super::need) bits: which per-point quantities the formula reads.
    pub const fn needs(mut self, needs: u8) -> VarDef {
        self.needs = needs;
        self
    }
    /// Set the [`flag`] bits.
    pub const fn flags(mut self, flags: u32) -> VarDef {
        self.flags = flags;
        self
    }
    /// Pre/post forms add their output to the point.
    pub const fn sum(mut self) -> VarDef {
        self.assign = Assign::Sum;
        self
    }
    /// Set the function computing the derived values.
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
    /// Set a specialised batch loop for the regular form.
    pub const fn batch(mut self, f: BatchFn) -> VarDef {
        self.batch = Some(f);
        self
    }

    /// Set a batch loop for the `pre_`/`post_` forms.
    pub const fn form_batch(mut self, f: FormBatchFn) -> VarDef {
        self.form_batch = Some(f);
        self
    }

    /// The parameters' default values, in [`VarDef::params`] order.
    pub fn defaults(&self) -> Vec<f64> {
        self.params.iter().map(|p| p.default).collect()
    }

    /// Whether the flags include the [`flag`] bit(s) `f`.
    pub fn has(&self, f: u32) -> bool {
        self.flags & f != 0
    }

    /// Does it act at weight 0 where the writing program runs every variation whatever its
    /// amount (JWildfire)? One that colours or hides points does; one that only moves them
    /// contributes nothing.
    pub fn acts_at_weight_zero(&self) -> bool {
        self.has(flag::SETS_COLOR | flag::HIDES)
    }

    /// Is a 3-D variation (its output depends on z).
    pub fn is_3d(&self) -> bool {
        self.has(flag::USES_Z)
    }
}

/// State carried between calls by the few stateful variations (shared by the threads of a
/// render; relaxed atomics, as the state only decorrelates successive calls).
#[derive(Debug, Default)]
pub struct VarState([AtomicU64; VarState::SLOTS]);

impl VarState {
    /// Number of slots.
    pub const SLOTS: usize = 8;
    /// The value in slot `i` (0–7).
    pub fn get(&self, i: usize) -> f64 {
        f64::from_bits(self.0[i].load(Ordering::Relaxed))
    }
    /// Store `v` in slot `i` (0–7).
    pub fn set(&self, i: usize, v: f64) {
        self.0[i].store(v.to_bits(), Ordering::Relaxed);
    }
}

impl Clone for VarState {
    fn clone(&self) -> Self {
        let s = VarState::default();
        for i in 0..self.0.len() {
            s.set(i, self.get(i));
        }
        s
    }
}

/// Whose formula a variation follows where the programs compute it differently: the program
/// that wrote the flame (flam3's for ugnis' own flames and for Apophysis', which share its
/// formulas).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Dialect {
    /// flam3 (and Apophysis, and ugnis' own flames).
    #[default]
    Flam3,
    /// Fractorium.
    Fractorium,
    /// JWildfire.
    JWildfire,
}

/// The output z of a formula that does not compute one (a 2-D variation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ZRule {
    /// 0: a regular variation (flam3, Fractorium; JWildfire without "preserve Z").
    Zero,
    /// The input z: a `pre_`/`post_` form that replaces the point.
    Input,
    /// The weight times the input z: a regular 2-D variation of a JWildfire flame with
    /// "preserve Z" on.
    Weighted,
}

/// How the program that wrote a flame runs its variations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rules {
    /// Fractorium's flam3-compatibility switch (on by default).
    pub compat: bool,
    /// Whose formulas, where programs differ.
    pub dialect: Dialect,
    /// JWildfire's "preserve Z": its 2-D variations carry the weighted input z along.
    pub preserve_z: bool,
}

impl Default for Rules {
    fn default() -> Self {
        Rules {
            compat: true,
            dialect: Dialect::Flam3,
            preserve_z: false,
        }
    }
}

/// A variation ready to evaluate: its weight, normalised parameters followed by derived values,
/// and the xform's affine map.
#[derive(Clone, Debug)]
pub struct Prepared {
    /// The variation's registry id.
    pub id: VarId,
    /// Its registry entry.
    pub def: &'static VarDef,
    /// Regular, `pre_` or `post_`: the phase it runs in (a variation JWildfire runs before or
    /// after the others whatever its name says — `flatten` — runs there).
    pub form: Form,
    /// The weight.
    pub w: f64,
    /// Parameters in [`VarDef::params`] order, then values derived by [`VarDef::prepare`].
    pub p: Vec<f64>,
    /// Where the derived values start in `p`: the number of parameters (kept here so that a
    /// formula reaches its derived values without going through [`Prepared::def`]).
    pub(super) derived_at: usize,
    /// The xform's pre-affine map.
    pub aff: Affine,
    /// Fractorium's flam3-compatibility switch (on by default).
    pub compat: bool,
    /// The program whose formula to follow where programs differ (flam3's by default).
    pub dialect: Dialect,
    /// The output z when the formula computes none.
    pub zrule: ZRule,
    /// How a `pre_`/`post_` form joins its output to the point: the variation's own
    /// [`VarDef::assign`], or [`Assign::Sum`] for a regular variation JWildfire's priority moved
    /// before or after the others ([`Prepared::moved_by_priority`]).
    pub assign: Assign,
    /// State carried from one call to the next (used by the stateful variations only). Boxed:
    /// its atomics inline would make `&Prepared` a reference to interior-mutable memory, and
    /// the compiler could then keep no parameter in a register across a batch loop's stores
    /// (every read of a parameter would be repeated per point, and such loops do not
    /// vectorise).
    pub state: Box<VarState>,
    /// The data of [`VarDef::shared`] for these parameters (built once per distinct value and
    /// shared through a process-wide cache); `None` for the variations without.
    pub data: Option<Arc<[f64]>>,
    /// Text parameters in [`VarDef::texts`] order.
    pub texts: Vec<String>,
    /// The flame's palette for nearest-colour lookups, for the variations flagged
    /// [`flag::PALETTE`] once their xform is compiled for a flame (`None` before).
    pub palette: Option<Arc<PaletteIndex>>,
}

impl Prepared {
    /// The first `N` parameters (normalised, in [`VarDef::params`] order), to bind by name:
    /// `let [power, dist] = v.params();` (`_` for those not read). With [`Prepared::derived`],
    /// the one way formulas and `prepare` functions read their values.
    #[inline(always)]
    pub fn params<const N: usize>(&self) -> [f64; N] {
        debug_assert!(
            N <= self.def.params.len(),
            "{} has fewer parameters",
            self.def.name
        );
        match self.p.first_chunk() {
            Some(a) => *a,
            None => too_few_values(N, self.p.len()),
        }
    }

    /// The first `N` values [`VarDef::prepare`] derived from the parameters (appended to
    /// [`Prepared::p`] after them), to bind by name: `let [abs_power, cn] = v.derived();`.
    #[inline(always)]
    pub fn derived<const N: usize>(&self) -> [f64; N] {
        let values = &self.p[self.derived_at..];
        match values.first_chunk() {
            Some(a) => *a,
            None => too_few_values(N, values.len()),
        }
    }

    /// The derived values from index `from` on (0 being the first value after the parameters):
    /// a table [`VarDef::prepare`] appended (cell sites, symmetry maps, drawing segments), read
    /// by position.
    #[inline(always)]
    pub fn table(&self, from: usize) -> &[f64] {
        &self.p[self.derived_at + from..]
    }

    /// The shared data ([`Prepared::data`]); empty for a variation without.
    #[inline(always)]
    pub fn data(&self) -> &[f64] {
        self.data.as_deref().unwrap_or(&[])
    }

    /// The output z of a formula that does not compute one ([`Prepared::zrule`]): 0 for a
    /// regular variation (the weighted input z in a JWildfire flame with "preserve Z" on), the
    /// input z for a `pre_`/`post_` form that replaces the point, 0 for one that adds to it.
    #[inline(always)]
    pub fn default_z(&self, t: &VarIn) -> f64 {
        match self.zrule {
            ZRule::Zero => 0.0,
            ZRule::Input => t.z,
            ZRule::Weighted => self.w * t.z,
        }
    }

    /// [`Prepared::default_z`] decided once, for a loop over points: a `match` inside the loop
    /// is a switch the vectoriser cannot take.
    #[inline(always)]
    pub fn default_z_rule(&self) -> DefaultZ {
        DefaultZ {
            zero: self.zrule == ZRule::Zero,
            factor: if self.zrule == ZRule::Weighted {
                self.w
            } else {
                1.0
            },
        }
    }

    /// Hand the flame's palette to a variation that looks colours up in it
    /// ([`flag::PALETTE`]; the others ignore it).
    pub fn give_palette(&mut self, palette: &Arc<PaletteIndex>) {
        if self.def.has(flag::PALETTE) {
            self.palette = Some(palette.clone());
        }
    }

    /// The colour coordinate of the palette entry nearest to the colour (r, g, b) (see
    /// [`PaletteIndex::coordinate`]); `None` while no palette was handed over.
    #[inline]
    pub fn palette_coordinate(&self, r: f64, g: f64, b: f64) -> Option<f64> {
        Some(self.palette.as_deref()?.coordinate(r, g, b))
    }

    /// Evaluate the formula: the weighted output for input `t`.
    #[inline(always)]
    pub fn eval(&self, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
        self.eval_with(self.def.eval, t, acc, rng)
    }

    /// [`Prepared::eval`] with the formula `f` (the variation's own: a function item inlines).
    #[inline(always)]
    pub(super) fn eval_with(
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

    /// [`Prepared::apply_post`] for a form that may read the point the regular variations saw,
    /// `affine`: a form with [`flag::READS_AFFINE_POINT`] gets it as its input (and the sum
    /// in `acc`), any other the sum.
    #[inline]
    pub fn apply_post_after(&self, affine: &V3, acc: &mut Acc, color: f64, rng: &mut FastRng) {
        if self.def.flags & flag::READS_AFFINE_POINT == 0 {
            self.apply_post(acc, color, rng);
            return;
        }
        let t = VarIn::new(
            affine[0],
            affine[1],
            affine[2],
            color,
            self.def.needs,
            false,
        );
        let o = self.eval(&t, acc, rng);
        self.assign_acc(acc, o);
    }

    /// Combines the output `o` of a `pre_`/`post_` form with the point `p` it transformed:
    /// replaces it or adds to it, as [`VarDef::assign`] says.
    #[inline(always)]
    pub(super) fn assign(&self, p: &mut V3, o: V3) {
        match self.assign {
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
    pub(super) fn assign_acc(&self, acc: &mut Acc, o: V3) {
        let mut p = [acc.x, acc.y, acc.z];
        self.assign(&mut p, o);
        [acc.x, acc.y, acc.z] = p;
    }
}

/// [`Prepared::default_z`] as a rule fixed for a loop: 0, or a factor times the input z (1 for
/// the input z itself: the same bits).
#[derive(Clone, Copy, Debug)]
pub struct DefaultZ {
    zero: bool,
    factor: f64,
}

impl DefaultZ {
    /// The output z for the input z `z`.
    #[inline(always)]
    pub fn of(self, z: f64) -> f64 {
        if self.zero { 0.0 } else { self.factor * z }
    }
}

/// The point (x, y, z) of a `pre_` form, else the xform's running sum: what the variations that
/// look at "the sum so far" read.
#[inline(always)]
pub(super) fn sum_or_input(v: &Prepared, t: &VarIn, acc: &Acc) -> (f64, f64, f64) {
    if v.form == Form::Pre {
        (t.x, t.y, t.z)
    } else {
        (acc.x, acc.y, acc.z)
    }
}

/// The panic of [`Prepared::params`] asked for more values than the variation has.
#[cold]
#[inline(never)]
fn too_few_values(wanted: usize, have: usize) -> ! {
    panic!("a formula read {wanted} values of a variation that has {have}")
}
