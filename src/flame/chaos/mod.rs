//! The chaos game: a flame compiled for fast iteration, and the loops that iterate it.
//!
//! [`Chaos`] holds the flame's compiled xforms ([`CompiledXform`]), the tables that draw the
//! next xform (one per xaos row) and the 3-D camera ([`Projection`]). It iterates in two ways:
//!
//! - one orbit at a time, flam3's loop ([`Chaos::run_sub_batch`], here), which automatic
//!   framing and the dimension estimate use;
//! - [`LANES`] orbits at once ([`Chaos::run_lanes`], the renderer's hot loop): every step
//!   draws each orbit's xform, groups the orbits by xform and applies each xform to its group
//!   as arrays. The orbits live in a worker's [`Lanes`] for its whole render.
//!
//! The parts: `xform` compiles one xform and applies it to a point; `batch` applies it to a
//! group of points as arrays; `lanes` holds the orbits of the lane runner and their saved
//! state; `engine` is the lane runner; `projection` is the 3-D camera.

mod batch;
mod engine;
mod lanes;
mod projection;
mod xform;

pub use lanes::{LaneState, Lanes};
pub use projection::Projection;
pub use xform::{BAD_LIMIT_WIDE, CompiledXform};

use crate::flame::jwf_render::colour_type::DistanceColour;
use crate::flame::model::Flame;
use crate::flame::rng::FastRng;
use crate::flame::variations;

/// flam3 `CHOOSE_XFORM_GRAIN`.
pub const CHOOSE_GRAIN: usize = 16384;
/// Fuse iterations at the start of every sub-batch (flam3 `FUSE_27`).
pub const FUSE: i64 = 15;
/// Fuse iterations of an orbit of a flame JWildfire's renderer draws. JWildfire fuses each
/// orbit for 43 steps (`Constants.INITIAL_ITERATIONS`), but it runs one orbit per render
/// thread for the whole render, so the path from an orbit's start towards the attractor is a
/// negligible share of its samples. ugnis runs [`LANES`] orbits per thread, which would draw
/// those paths hundreds of times over (a slowly contracting xform leaves a haze of dots around
/// the attractor that JWildfire's pictures do not have): its orbits of such a flame are fused
/// long enough to reach the attractor (a contraction of 0.97 per step shrinks a start's
/// distance by 10⁻¹³ in 1000 steps), and they live for the whole render.
pub const JWF_FUSE: i64 = 1000;
/// Fuse of the [`LANES`] orbits the lane runner starts with (flam3's flames; JWildfire's take
/// [`JWF_FUSE`]). flam3 3.1.1 (`rect.c`) starts one orbit per sub-batch of [`SUB_BATCH`]
/// samples, fused [`FUSE`] steps, and the lane runner restarts one orbit per sub-batch to
/// match; fused as briefly, its first orbits would draw hundreds more paths towards the
/// attractor per thread, a haze around a slowly converging flame that grows with the thread
/// count (flam3's own test flame render031, a slow xform among two mirrors: mean level
/// 14.28 in flam3, 14.60 / 14.87 / 15.83 / 17.09 in ugnis with 1 / 2 / 4 / 8 threads). They
/// are fused long enough to reach the attractor instead (see [`JWF_FUSE`]).
pub const FIRST_FUSE: i64 = 1000;
/// Fuse of the first orbits of a flame JWildfire's renderer draws when some variation carries
/// an orbit of its own from call to call (`flag::OWN_ORBIT`: hopalong, gumowski_mira,
/// threeply, …). Such a variation takes the next point of its orbit at every call, whatever
/// the input, so the picture is the stretch of that orbit the render draws: JWildfire's render
/// thread fuses its one orbit for 44 steps (`DefaultRenderIterationState.preFuseIter`, see
/// [`JWF_RESTART_FUSE`]) and draws from there, where [`LANES`] orbits fused [`JWF_FUSE`] steps
/// would skip the first 256 000 points of the variation's orbit (hopalong's spiral of inner
/// rings, the chaotic transient of gumowski_mira). One step per orbit skips [`LANES`], the
/// nearest to JWildfire's 44.
pub const JWF_STATEFUL_FUSE: i64 = 1;
/// Samples per sub-batch.
pub const SUB_BATCH: u64 = 10_000;
/// Number of independent orbits iterated together by [`Chaos::run_lanes`].
pub const LANES: usize = 256;
/// A coordinate beyond this magnitude is a bad value.
pub const BAD_LIMIT: f64 = 1e10;

/// Why a flame cannot be iterated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ChaosError {
    #[error("cannot iterate empty flame: it has no transforms")]
    NoXforms,
    #[error("cannot iterate empty flame: all transform weights are 0")]
    ZeroWeights,
    #[error("transform {0} has weight {1}; weights must be finite and non-negative")]
    BadWeight(usize, f64),
    #[error("transform {0}: xaos row has zero total; at least one reachable transform is needed")]
    XaosRowZero(usize),
    #[error("transform {0}: xaos value {1} must be finite and non-negative")]
    BadXaos(usize, f64),
}
/// A point of an orbit: position and colour coordinate.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pt {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub c: f64,
}
/// A flame compiled for the chaos game.
#[derive(Clone, Debug)]
pub struct Chaos {
    /// The flame's xforms, compiled, in the flame's order.
    pub xforms: Vec<CompiledXform>,
    /// The final xform, compiled, if the flame has one.
    pub final_xform: Option<CompiledXform>,
    /// The flame's further final xforms, compiled, applied in order after the first.
    pub more_finals: Vec<CompiledXform>,
    /// The 3-D camera, if the flame has one.
    pub projection: Option<Projection>,
    /// Row 0: plain weights. Rows 1..=n: xaos rows after xform i − 1 (only when xaos is used),
    /// CHOOSE_GRAIN entries each, concatenated.
    tables: Vec<u16>,
    xaos: bool,
    /// Plotted visibility of each xform, and the one of all of them when they agree.
    vis: Vec<f64>,
    same_vis: Option<f64>,
    /// Some xform (or the final one) may hide points: hidden samples count but add nothing.
    hides: bool,
    /// The orbits carry the own colours variations give points (JWildfire's direct colour,
    /// for a flame JWildfire's renderer draws and some variation of which may set one).
    pub rgb: bool,
    /// Every xform is an affine map times `linear` (no post-affine), with no final xform,
    /// camera or xaos: orbits then need no grouping by xform (see [`AffineStep`]).
    affine: Option<Vec<AffineStep>>,
    /// JWildfire's rule for bad values (a flame its renderer draws): only NaN and infinity
    /// (in x, y or z) are bad, and a bad point is kept ([`CompiledXform::keeps_bad`]): the
    /// orbit goes on from it, its samples count and draw nothing while its point is bad, and
    /// the next check (every [`JWF_CHECK_STEPS`] steps) restarts it if it still is; a final
    /// xform's bad value is a sample that draws nothing.
    jwf_bad_values: bool,
    /// JWildfire's rule for hidden points (a flame its renderer draws, some xform of which
    /// may hide points): the hide flag travels with the point, as JWildfire's
    /// `XYZPoint.doHide` does, so the orbit's samples stay hidden through xforms that do not
    /// touch the flag until a hiding variation shows the point again
    /// ([`CompiledXform::hide_passes_on`]); a final xform's hiding variations decide for the
    /// sample in the same way.
    carry_hide: bool,
    /// Some variation gives points the palette position of a colour: the colour coordinates
    /// depend on the palette, so a palette change needs the chaos game run again.
    pub reads_palette: bool,
    /// JWildfire's solid rendering: the samples also report where they were before the
    /// camera ([`Chaos::run_lanes_world`]), and their z is the depth seen by the camera.
    pub solid: bool,
}

/// JWildfire checks each orbit for NaN and infinity once every this many iterations
/// (`DefaultRenderThread`); in between a broken orbit's iterations count but draw nothing.
pub const JWF_CHECK_STEPS: u64 = 1000;

/// The xforms drawn after the first when JWildfire restarts a bad orbit
/// (`Constants.INITIAL_ITERATIONS` + 1: `DefaultRenderIterationState.preFuseIter` transforms
/// the random start by the layer's first xform, then by 43 drawn ones). A restart takes place
/// only where an orbit met a bad value, so its path towards the attractor is drawn as often
/// as in JWildfire (the first orbits of a render are fused [`JWF_FUSE`] steps).
pub const JWF_RESTART_FUSE: usize = 43;

/// One linear-only xform as a table row, for stepping orbits in place: the chosen row of each
/// orbit is read, no orbit moves. The arithmetic is the general path's, in its order.
#[derive(Clone, Copy, Debug)]
struct AffineStep {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    e: f64,
    f: f64,
    /// Weight of `linear`.
    w: f64,
    /// Colour blend c' = sc + keep·c: sc = speed·colour, keep = 1 − speed.
    sc: f64,
    keep: f64,
    bad_limit: f64,
}

/// Build the 16 384-entry selection table for weights `w`.
pub fn selection_table(w: &[f64]) -> Box<[u16]> {
    let n = w.len();
    let total: f64 = w.iter().sum();
    let delta = total / CHOOSE_GRAIN as f64;
    let mut t = vec![0u16; CHOOSE_GRAIN].into_boxed_slice();
    let mut j = 0usize;
    let mut acc = w[0];
    let mut r = 0.0;
    for slot in t.iter_mut() {
        while r >= acc && j < n - 1 {
            j += 1;
            acc += w[j];
        }
        *slot = j as u16;
        r += delta;
    }
    t
}

/// Whether JWildfire's xform `x` keeps the colour a point comes with: its colour type is NONE
/// (no palette look-up), which a final xform that names no colour type has too.
fn keeps_own_colour(x: &crate::flame::model::Xform, is_final: bool) -> bool {
    let kind = x.extra_attrs.iter().find(|(k, _)| k == "color_type");
    match kind {
        Some((_, v)) => v.trim() == "NONE",
        None => is_final,
    }
}

/// The xforms of JWildfire's colour types DISTANCE and CYCLIC, which take the general path
/// (which colours them): DISTANCE keeps the gradient position and carries own colours;
/// CYCLIC moves the gradient position on by the colour symmetry (1 − 2·colour speed).
fn jwildfire_colour_types(
    flame: &Flame,
    xforms: &mut [CompiledXform],
    final_xform: &mut Option<CompiledXform>,
    more_finals: &mut [CompiledXform],
) {
    let compiled = xforms.iter_mut().chain(final_xform).chain(more_finals);
    for (c, x) in compiled.zip(flame.xforms.iter().chain(flame.finals())) {
        if let Some(d) = DistanceColour::of(x) {
            c.distance = Some(d);
            c.color_speed = 0.0;
            c.own_rgb = true;
            c.linear_only = None;
        }
        let kind = x.extra_attrs.iter().find(|(k, _)| k == "color_type");
        if kind.is_some_and(|(_, v)| v.trim() == "CYCLIC") {
            c.cyclic = Some(1.0 - 2.0 * x.color_speed);
            c.linear_only = None;
        }
    }
}

/// Hand the flame's palette (as its renderer colours the picture) to the variations that look
/// colours up in it ([`variations::flag::PALETTE`]); the table is built only when one does.
/// Returns whether one does.
fn give_palette(
    flame: &Flame,
    xforms: &mut [CompiledXform],
    final_xform: &mut Option<CompiledXform>,
    more_finals: &mut [CompiledXform],
) -> bool {
    let mut vars = xforms
        .iter_mut()
        .chain(final_xform)
        .chain(more_finals)
        .flat_map(|x| {
            x.pre_vars
                .iter_mut()
                .chain(&mut x.vars)
                .chain(&mut x.post_vars)
        })
        .filter(|v| v.def.has(variations::flag::PALETTE))
        .peekable();
    if vars.peek().is_none() {
        return false;
    }
    let table = std::sync::Arc::new(variations::PaletteIndex::from_colors(flame.render_colors()));
    for v in vars {
        v.give_palette(&table);
    }
    true
}

impl Chaos {
    /// Some variation carries its own state from call to call (`flag::STATEFUL`: the orbit
    /// variations such as gingerbread_man or hopalong). Each worker thread then needs its own
    /// copy of the compiled flame, as each of JWildfire's render threads has its own copy of
    /// the flame: threads sharing one state would tear its steps apart.
    pub(crate) fn has_variation_state(&self) -> bool {
        let stateful = |x: &CompiledXform| {
            x.pre_vars
                .iter()
                .chain(&x.vars)
                .chain(&x.post_vars)
                .any(|v| v.def.has(crate::flame::variations::flag::STATEFUL))
        };
        self.xforms
            .iter()
            .chain(&self.final_xform)
            .chain(&self.more_finals)
            .any(stateful)
    }

    /// The stateful variations of the compiled flame, in a fixed order (xforms, final xform,
    /// further finals; in each the `pre_`, regular and `post_` forms).
    fn stateful_vars(&self) -> impl Iterator<Item = &variations::Prepared> {
        self.xforms
            .iter()
            .chain(&self.final_xform)
            .chain(&self.more_finals)
            .flat_map(|x| x.pre_vars.iter().chain(&x.vars).chain(&x.post_vars))
            .filter(|v| v.def.has(variations::flag::STATEFUL))
    }

    /// The state the stateful variations carry from call to call (their orbits), every slot
    /// of each in [`Chaos::stateful_vars`] order: what a saved render keeps so that a resumed
    /// one continues those orbits. Empty when no variation is stateful.
    pub fn variation_state(&self) -> Vec<f64> {
        self.stateful_vars()
            .flat_map(|v| (0..variations::VarState::SLOTS).map(|i| v.state.get(i)))
            .collect()
    }

    /// Give the stateful variations the state [`Chaos::variation_state`] took (of a copy of
    /// the same flame). Returns false, changing nothing, when `values` does not fit this
    /// flame's stateful variations.
    pub fn restore_variation_state(&self, values: &[f64]) -> bool {
        let n = variations::VarState::SLOTS;
        if values.len() != self.stateful_vars().count() * n {
            return false;
        }
        for (v, vals) in self.stateful_vars().zip(values.chunks_exact(n)) {
            for (i, &x) in vals.iter().enumerate() {
                v.state.set(i, x);
            }
        }
        true
    }

    /// Compile `flame`; fails when it has no xforms, no positive weight, a weight or xaos
    /// value that is negative or not finite, or an xaos row that reaches no xform.
    pub fn new(flame: &Flame) -> Result<Self, ChaosError> {
        let n = flame.xforms.len();
        if n == 0 {
            return Err(ChaosError::NoXforms);
        }
        for (i, x) in flame.xforms.iter().enumerate() {
            if !(x.weight.is_finite() && x.weight >= 0.0) {
                return Err(ChaosError::BadWeight(i, x.weight));
            }
        }
        let weights: Vec<f64> = flame.xforms.iter().map(|x| x.weight).collect();
        if weights.iter().sum::<f64>() <= 0.0 {
            return Err(ChaosError::ZeroWeights);
        }
        let rules = flame.rules();
        let xforms: Vec<CompiledXform> = flame
            .xforms
            .iter()
            .enumerate()
            .map(|(i, x)| {
                let o = match flame.solo_xform {
                    Some(s) if s < n && s != i => 0.0,
                    _ => x.opacity,
                };
                CompiledXform::new(x, o, rules)
            })
            .collect();
        let xaos = flame
            .xforms
            .iter()
            .any(|x| (0..n).any(|j| x.chaos_to(j) != 1.0));
        let mut tables = selection_table(&weights).into_vec();
        if xaos {
            for (i, x) in flame.xforms.iter().enumerate() {
                let row: Vec<f64> = (0..n)
                    .map(|j| {
                        let c = x.chaos_to(j);
                        if !(c.is_finite() && c >= 0.0) {
                            return Err(ChaosError::BadXaos(i, c));
                        }
                        Ok(weights[j] * c)
                    })
                    .collect::<Result<_, _>>()?;
                if row.iter().sum::<f64>() <= 0.0 {
                    // Fractorium 23.23 (`Iterator::InitDistributions`) allows a row of zero
                    // total: its table is left all zeros, so the first xform always follows.
                    // flam3 refuses the flame (`flam3_create_xform_distrib`).
                    if rules.dialect != variations::Dialect::Fractorium {
                        return Err(ChaosError::XaosRowZero(i));
                    }
                    tables.extend(std::iter::repeat_n(0u16, CHOOSE_GRAIN));
                    continue;
                }
                tables.extend_from_slice(&selection_table(&row));
            }
        }
        let mut finals = flame
            .finals()
            .map(|f| CompiledXform::new(f, f.opacity, rules));
        let final_xform = finals.next();
        let more_finals: Vec<CompiledXform> = finals.collect();
        // flam3 resets points beyond 1e10; Fractorium and JWildfire only NaN (and infinity).
        // Flames that use a variation flam3 does not have follow Fractorium.
        let fractorium = flame
            .xforms
            .iter()
            .chain(flame.finals())
            .flat_map(|x| &x.vars)
            .any(|v| v.weight != 0.0 && !variations::info(v.id).has(variations::flag::FLAM3));
        let mut xforms = xforms;
        let mut final_xform = final_xform;
        let mut more_finals = more_finals;
        let jwf_bad_values = flame.renders_as_jwildfire();
        if fractorium || jwf_bad_values {
            for x in xforms
                .iter_mut()
                .chain(final_xform.as_mut())
                .chain(&mut more_finals)
            {
                x.bad_limit = BAD_LIMIT_WIDE;
                x.keeps_bad = jwf_bad_values;
            }
        }
        if flame.renders_as_jwildfire() {
            jwildfire_colour_types(flame, &mut xforms, &mut final_xform, &mut more_finals);
        }
        let reads_palette = give_palette(flame, &mut xforms, &mut final_xform, &mut more_finals);
        let vis: Vec<f64> = xforms.iter().map(|x| x.vis).collect();
        let affine = (final_xform.is_none() && !xaos && Projection::of(flame).is_none())
            .then(|| {
                xforms
                    .iter()
                    .map(|x| {
                        let w = x.linear_only.filter(|_| x.post.is_none())?;
                        let a = x.coefs;
                        Some(AffineStep {
                            a: a.a,
                            b: a.b,
                            c: a.c,
                            d: a.d,
                            e: a.e,
                            f: a.f,
                            w,
                            sc: x.color_speed * x.color,
                            keep: 1.0 - x.color_speed,
                            bad_limit: x.bad_limit,
                        })
                    })
                    .collect::<Option<Vec<_>>>()
            })
            .flatten();
        let hides = xforms
            .iter()
            .chain(final_xform.as_ref())
            .chain(&more_finals)
            .any(|x| x.hides);
        let rgb = flame.renders_as_jwildfire()
            && xforms
                .iter()
                .chain(final_xform.as_ref())
                .chain(&more_finals)
                .any(|x| x.own_rgb);
        if rgb {
            for (c, x) in xforms.iter_mut().zip(&flame.xforms) {
                c.keeps_rgb = keeps_own_colour(x, false);
            }
            let finals = final_xform.iter_mut().chain(&mut more_finals);
            for (c, x) in finals.zip(flame.finals()) {
                c.keeps_rgb = keeps_own_colour(x, true);
            }
        }
        Ok(Chaos {
            affine,
            hides,
            rgb,
            same_vis: vis.iter().all(|&v| v == vis[0]).then_some(vis[0]),
            vis,
            xforms,
            final_xform,
            more_finals,
            projection: Projection::of(flame),
            tables,
            xaos,
            jwf_bad_values,
            carry_hide: jwf_bad_values && hides,
            reads_palette,
            solid: flame.renders_as_jwildfire() && flame.jwf.solid.enabled,
        })
    }

    /// Draw the next xform; `last` is the previously applied xform (None at the start).
    #[inline(always)]
    pub fn choose(&self, last: Option<usize>, rng: &mut FastRng) -> usize {
        let row = match (self.xaos, last) {
            (true, Some(i)) => i + 1,
            _ => 0,
        };
        let u = rng.u32() as usize & (CHOOSE_GRAIN - 1);
        self.tables[row * CHOOSE_GRAIN + u] as usize
    }

    /// Apply the final xforms (if any, in order, each with its opacity as a probability) to a
    /// copy of a point.
    #[inline(always)]
    pub fn finalise(&self, p: Pt, rng: &mut FastRng) -> Pt {
        self.finalise_hiding(p, rng).0
    }

    /// [`Chaos::finalise`], also saying whether a final xform hid the point.
    #[inline(always)]
    pub fn finalise_hiding(&self, p: Pt, rng: &mut FastRng) -> (Pt, bool) {
        self.finalise_carrying(p, false, rng)
    }

    /// [`Chaos::finalise_hiding`] of a point that comes `hidden` or not: under JWildfire's
    /// rule ([`Chaos::carry_hide`]) the final xforms pass the flag on or decide afresh,
    /// otherwise any hiding (the point's or a final xform's) hides the sample.
    #[inline(always)]
    fn finalise_carrying(&self, p: Pt, hidden: bool, rng: &mut FastRng) -> (Pt, bool) {
        let (mut p, mut hidden) = (p, hidden);
        for f in self.final_xform.iter().chain(&self.more_finals) {
            if f.opacity >= 1.0 || rng.f01() < f.opacity {
                let (q, _, hide) = f.apply_hiding(p, rng);
                p = q;
                hidden = if self.carry_hide {
                    f.hidden_after(hide, hidden)
                } else {
                    hidden | hide
                };
            }
        }
        (p, hidden)
    }

    /// Where a point is plotted: through the 3-D camera, if any (z is kept).
    #[inline(always)]
    pub fn project(&self, p: Pt, rng: &mut FastRng) -> Pt {
        match &self.projection {
            Some(pr) => {
                let (x, y) = pr.project(p.x, p.y, p.z, rng);
                Pt { x, y, ..p }
            }
            None => p,
        }
    }

    /// A random starting point of an orbit: x, y uniform in [−1, 1], z = 0, colour in [0, 1).
    #[inline(always)]
    pub fn start_point(rng: &mut FastRng) -> Pt {
        let x = rng.f11();
        let y = rng.f11();
        let c = rng.f01();
        Pt { x, y, z: 0.0, c }
    }

    /// The fuse of an orbit: [`JWF_FUSE`] for a flame JWildfire's renderer draws, else
    /// flam3's [`FUSE`].
    pub fn fuse(&self) -> i64 {
        if self.jwf_bad_values { JWF_FUSE } else { FUSE }
    }

    /// The fuse of the first orbits of a render: [`JWF_STATEFUL_FUSE`] for a flame
    /// JWildfire's renderer draws with a variation carrying its own orbit
    /// (`flag::OWN_ORBIT`), else at least [`FIRST_FUSE`]. Other stateful variations (a
    /// stabiliser or crop keeping a few points, say) transform their input: their orbits
    /// still need the long fuse.
    pub(crate) fn first_fuse(&self) -> i64 {
        let own_orbit = || {
            self.xforms
                .iter()
                .chain(&self.final_xform)
                .chain(&self.more_finals)
                .flat_map(|x| x.pre_vars.iter().chain(&x.vars).chain(&x.post_vars))
                .any(|v| v.def.has(variations::flag::OWN_ORBIT))
        };
        if self.jwf_bad_values && own_orbit() {
            JWF_STATEFUL_FUSE
        } else {
            self.fuse().max(FIRST_FUSE)
        }
    }

    /// A random start point iterated through the fuse, the xform applied last, and whether
    /// the point is hidden at the end (under JWildfire's rule, [`Chaos::carry_hide`]: its
    /// fuse carries the flag as its render does).
    fn fused_start(&self, rng: &mut FastRng) -> (Pt, usize, bool) {
        let mut p = Self::start_point(rng);
        let mut last = None;
        let mut hidden = false;
        for _ in 0..self.fuse() {
            let i = self.choose(last, rng);
            let x = &self.xforms[i];
            let (q, bad, here) = x.apply_hiding(p, rng);
            p = q;
            hidden = self.carry_hide && !bad && x.hidden_after(here, hidden);
            last = Some(i);
        }
        (p, last.unwrap_or(0), hidden)
    }

    /// Run one sub-batch of `n` plotted samples. `plot(p, vis)` receives
    /// every point after the fuse, final xform applied. Returns the number of bad values.
    #[inline(always)]
    pub fn run_sub_batch<F: FnMut(Pt, f64)>(&self, n: u64, rng: &mut FastRng, mut plot: F) -> u64 {
        let mut p = Self::start_point(rng);
        let mut k: i64 = -self.fuse();
        let mut consec = 0u32;
        let mut bad = 0u64;
        let mut last = None;
        // The point's hide flag, under JWildfire's rule (see `carry_hide`).
        let mut carried = false;
        let n = n as i64;
        while k < n {
            let i = self.choose(last, rng);
            let xf = &self.xforms[i];
            let (np, is_bad, mut hidden) = xf.apply_hiding(p, rng);
            p = np;
            if self.carry_hide {
                hidden = xf.hidden_after(hidden, carried);
                carried = hidden;
            }
            if is_bad {
                consec += 1;
                bad += 1;
                // The point starts again (in the plane, shown).
                carried = false;
                if consec < 5 {
                    continue;
                }
            }
            consec = 0;
            last = Some(i);
            if k >= 0 {
                // A hidden sample counts, and adds nothing.
                let (q, hidden) = self.finalise_carrying(p, hidden, rng);
                let v = if hidden { 0.0 } else { xf.vis };
                plot(self.project(q, rng), v);
            }
            k += 1;
        }
        bad
    }
}

#[cfg(test)]
#[path = "chaos_tests.rs"]
mod tests;
