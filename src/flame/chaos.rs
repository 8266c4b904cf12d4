//! The chaos game: a flame compiled for fast iteration.

use crate::flame::fastmath;
use crate::flame::model::{Affine, Flame, Xform};
use crate::flame::rng::FastRng;
use crate::flame::variations::{self, Acc, Form, Prepared, SoaAcc, SoaIn, VarIn, need};

/// flam3 `CHOOSE_XFORM_GRAIN`.
pub const CHOOSE_GRAIN: usize = 16384;
/// Fuse iterations at the start of every sub-batch (flam3 `FUSE_27`).
pub const FUSE: i64 = 15;
/// Samples per sub-batch.
pub const SUB_BATCH: u64 = 10_000;
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
    /// Plotted visibility o^(log2 10).
    pub vis: f64,
    pub opacity: f64,
    /// A coordinate of larger magnitude (or NaN) is a bad value: [`BAD_LIMIT`] or
    /// [`BAD_LIMIT_WIDE`].
    pub bad_limit: f64,
    /// The weight of `linear` when it is the xform's only variation (no `pre_`/`post_`
    /// forms): the lane runner then skips the general variation machinery.
    pub linear_only: Option<f64>,
    /// Some variation may hide the point ([`variations::flag::HIDES`]).
    pub hides: bool,
}

/// |v| ≤ limit; false for NaN (which fails every comparison).
#[inline(always)]
fn within(v: f64, limit: f64) -> bool {
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

/// A point of an orbit: position and colour coordinate.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pt {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub c: f64,
}

impl CompiledXform {
    pub fn new(x: &Xform, opacity: f64, compat: bool) -> Self {
        let mut pre_vars = Vec::new();
        let mut vars = Vec::new();
        let mut post_vars = Vec::new();
        let mut needs = 0u8;
        let mut sets_color = false;
        for v in &x.vars {
            if v.weight == 0.0 {
                continue;
            }
            let p =
                Prepared::with_texts(v.id, v.form, v.weight, &v.params, &v.texts, x.coefs, compat);
            sets_color |= p.def.has(variations::flag::SETS_COLOR);
            match v.form {
                Form::Pre => pre_vars.push(p),
                Form::Regular => {
                    needs |= p.def.needs;
                    vars.push(p);
                }
                Form::Post => post_vars.push(p),
            }
        }
        let linear_only = match (&pre_vars[..], &vars[..], &post_vars[..]) {
            ([], [v], []) if v.id == variations::LINEAR && !sets_color => Some(v.w),
            _ => None,
        };
        let hides = pre_vars
            .iter()
            .chain(&vars)
            .chain(&post_vars)
            .any(|v| v.def.has(variations::flag::HIDES));
        CompiledXform {
            linear_only,
            hides,
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
            vis: adjust_opacity(opacity),
            opacity,
            bad_limit: BAD_LIMIT,
        }
    }

    /// Apply to a point. Returns the new point and whether it was a bad value (in which case
    /// the point is a uniform random point of [−1, 1]² and the colour is still updated).
    #[inline(always)]
    pub fn apply(&self, p: Pt, rng: &mut FastRng) -> (Pt, bool) {
        let (q, bad, _) = self.apply_hiding(p, rng);
        (q, bad)
    }

    /// [`CompiledXform::apply`], also saying whether a variation hid the point (the orbit
    /// goes on from it, the sample is not drawn).
    #[inline(always)]
    pub fn apply_hiding(&self, p: Pt, rng: &mut FastRng) -> (Pt, bool, bool) {
        let blended = self.color_speed * self.color + (1.0 - self.color_speed) * p.c;
        let (tx, ty) = self.coefs.apply(p.x, p.y);
        let mut acc = Acc {
            color: blended,
            ..Acc::default()
        };
        let mut tr = [tx, ty, p.z];
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
        } else if !self.pre_vars.is_empty() {
            (acc.x, acc.y, acc.z) = (tr[0], tr[1], tr[2]);
        }
        for v in &self.post_vars {
            v.apply_post(&mut acc, blended, rng);
        }
        if let Some(post) = &self.post {
            (acc.x, acc.y) = post.apply(acc.x, acc.y);
        }
        let mut nc = blended;
        if self.sets_color {
            nc = blended + self.direct_color * (acc.color - blended);
            if nc.is_nan() {
                nc = 0.0;
            }
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

/// Number of independent orbits iterated together by [`Chaos::run_lanes`].
pub const LANES: usize = 256;

/// The state of [`LANES`] orbits: position, colour coordinate, the xform applied last (xaos
/// row; `u16::MAX` before the first), consecutive bad values, and steps done (an orbit plots
/// once this is ≥ 0; it starts at −FUSE).
#[derive(Clone, Debug)]
struct Orbits {
    x: [f64; LANES],
    y: [f64; LANES],
    z: [f64; LANES],
    c: [f64; LANES],
    last: [u16; LANES],
    consec: [u8; LANES],
    step: [i32; LANES],
}

impl Orbits {
    fn new() -> Orbits {
        Orbits {
            x: [0.0; LANES],
            y: [0.0; LANES],
            z: [0.0; LANES],
            c: [0.0; LANES],
            last: [u16::MAX; LANES],
            consec: [0; LANES],
            step: [-(FUSE as i32); LANES],
        }
    }
}

/// The orbits of the lane runner. They live for the whole render of one worker thread (see
/// [`Chaos::run_lanes`]). Fixed-size arrays: every index is provably in range.
///
/// Orbits are interchangeable, so they need not keep their places: every step reads one set
/// of orbits and writes the other, grouped by the xform each orbit drew, so that each xform
/// works on a contiguous run and nothing is scattered back.
#[derive(Clone, Debug)]
pub struct Lanes {
    sets: [Orbits; 2],
    /// Which of `sets` holds the orbits as they stand.
    cur: usize,
    started: bool,
    /// Every orbit is past its fuse and none is retrying a bad value, in both sets: a step
    /// then needs neither the retry counters nor the step counters.
    clean: bool,
    // Scratch space.
    choice: [u16; LANES],
    order: [u16; LANES],
    /// Xform applied at each place of the set just written.
    group: [u16; LANES],
    counts: Vec<usize>,
    bounds: Vec<usize>,
    bad: [bool; LANES],
    /// Hidden by a variation, at each place of the set just written.
    hide: [bool; LANES],
    /// Visibility of each place of the set just written; negative: not a sample.
    vis: [f64; LANES],
    g: Scratch,
    fin: Group,
    fin_vis: [f64; LANES],
    chosen: Vec<usize>,
    tmp: Group,
}

/// Per-point scratch arrays of one xform application.
#[derive(Clone, Debug)]
struct Scratch {
    sumsq: [f64; LANES],
    sqrt: [f64; LANES],
    atan_xy: [f64; LANES],
    atan_yx: [f64; LANES],
    ux: [f64; LANES],
    uy: [f64; LANES],
    px: [f64; LANES],
    py: [f64; LANES],
    pz: [f64; LANES],
    pc: [f64; LANES],
    bad: [bool; LANES],
    /// A variation hid the point (see [`variations::flag::HIDES`]).
    hide: [bool; LANES],
}

/// Points as a structure of arrays, for the final xform.
#[derive(Clone, Debug)]
struct Group {
    x: [f64; LANES],
    y: [f64; LANES],
    z: [f64; LANES],
    c: [f64; LANES],
}

impl Group {
    fn new() -> Group {
        Group {
            x: [0.0; LANES],
            y: [0.0; LANES],
            z: [0.0; LANES],
            c: [0.0; LANES],
        }
    }
}

impl Scratch {
    fn new() -> Scratch {
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
        }
    }
}

/// The orbits of one worker's [`Lanes`], without the scratch space: what a saved render state
/// keeps so that a resumed render continues the same orbits.
#[derive(Clone, Debug, PartialEq)]
pub struct LaneState {
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub z: Vec<f64>,
    pub c: Vec<f64>,
    pub last: Vec<u16>,
    pub consec: Vec<u8>,
    pub step: Vec<i32>,
    pub started: bool,
}

impl Lanes {
    /// The orbits as they stand.
    pub fn state(&self) -> LaneState {
        let o = &self.sets[self.cur];
        LaneState {
            x: o.x.to_vec(),
            y: o.y.to_vec(),
            z: o.z.to_vec(),
            c: o.c.to_vec(),
            last: o.last.to_vec(),
            consec: o.consec.to_vec(),
            step: o.step.to_vec(),
            started: self.started,
        }
    }

    /// Orbits restored from [`Lanes::state`]; `None` when the arrays do not have [`LANES`]
    /// entries each.
    pub fn restore(st: &LaneState) -> Option<Box<Lanes>> {
        let mut l = Lanes::new();
        let o = &mut l.sets[0];
        o.x = st.x.as_slice().try_into().ok()?;
        o.y = st.y.as_slice().try_into().ok()?;
        o.z = st.z.as_slice().try_into().ok()?;
        o.c = st.c.as_slice().try_into().ok()?;
        o.last = st.last.as_slice().try_into().ok()?;
        o.consec = st.consec.as_slice().try_into().ok()?;
        o.step = st.step.as_slice().try_into().ok()?;
        l.started = st.started;
        // At the end of every step `clean` says whether the counters are all clear; both sets
        // then read as clean (the other one's counters are not gathered). Restored the same
        // way, a resumed render takes the same paths (and so the same orbits) as one run on.
        l.clean = l.started
            && l.sets[0].consec.iter().all(|&c| c == 0)
            && l.sets[0].step.iter().all(|&s| s >= 0);
        if l.clean {
            l.sets[1].consec = [0; LANES];
            l.sets[1].step = [0; LANES];
        }
        Some(l)
    }

    pub fn new() -> Box<Lanes> {
        Box::new(Lanes {
            sets: [Orbits::new(), Orbits::new()],
            cur: 0,
            started: false,
            clean: false,
            choice: [0; LANES],
            order: [0; LANES],
            group: [0; LANES],
            counts: Vec::new(),
            bounds: Vec::new(),
            bad: [false; LANES],
            hide: [false; LANES],
            vis: [0.0; LANES],
            g: Scratch::new(),
            fin: Group::new(),
            fin_vis: [0.0; LANES],
            chosen: Vec::with_capacity(LANES),
            tmp: Group::new(),
        })
    }
}

impl CompiledXform {
    /// Apply to the points `x, y, z, c` (at most [`LANES`]; in place; `g.bad` flags set; a
    /// bad point is replaced by a random point of [−1, 1]²). The pre-affine points and their
    /// derived quantities are computed as arrays, then every regular variation runs over the
    /// whole group.
    #[inline(always)]
    fn apply_soa(
        &self,
        x: &mut [f64],
        y: &mut [f64],
        z: &mut [f64],
        c: &mut [f64],
        g: &mut Scratch,
        rng: &mut FastRng,
    ) {
        let n = x.len().min(y.len()).min(z.len()).min(c.len()).min(LANES);
        let (x, y, z, c) = (&mut x[..n], &mut y[..n], &mut z[..n], &mut c[..n]);
        if self.hides {
            g.hide[..n].fill(false);
        }
        let a = self.coefs;
        let (s, col) = (self.color_speed, self.color);
        for cj in c.iter_mut() {
            *cj = s * col + (1.0 - s) * *cj;
        }
        for j in 0..n {
            let (tx, ty) = a.apply(x[j], y[j]);
            x[j] = tx;
            y[j] = ty;
        }
        if let Some(w) = self.linear_only {
            // Only `linear`: the sum of the variations is w times the point (written as the
            // general path computes it, 0 + w·v, so both give the same bits).
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
            self.mark_bad(x, y, z, &mut g.bad[..n], rng);
            return;
        }
        if !self.pre_vars.is_empty() {
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
                g.pc[j] = acc.color;
                g.hide[j] |= acc.hide;
            }
        } else {
            g.pc[..n].copy_from_slice(c);
        }
        if !self.vars.is_empty() {
            let needs = self.needs;
            let (xs, ys) = (&*x, &*y);
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
            let soa = SoaIn {
                x: xs,
                y: ys,
                z: &*z,
                sumsq,
                sqrt,
                ux: &g.ux[..n],
                uy: &g.uy[..n],
                atan_xy: &g.atan_xy[..n],
                atan_yx: &g.atan_yx[..n],
                color: &*c,
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
                v.apply_batch(&soa, &mut acc, rng);
            }
        } else if !self.pre_vars.is_empty() {
            g.px[..n].copy_from_slice(x);
            g.py[..n].copy_from_slice(y);
            g.pz[..n].copy_from_slice(z);
        } else {
            g.px[..n].fill(0.0);
            g.py[..n].fill(0.0);
            g.pz[..n].fill(0.0);
        }
        if !self.post_vars.is_empty() {
            for (j, &cj) in c.iter().enumerate() {
                let mut acc = Acc {
                    x: g.px[j],
                    y: g.py[j],
                    z: g.pz[j],
                    color: g.pc[j],
                    hide: false,
                };
                for v in &self.post_vars {
                    v.apply_post(&mut acc, cj, rng);
                }
                (g.px[j], g.py[j], g.pz[j], g.pc[j]) = (acc.x, acc.y, acc.z, acc.color);
                g.hide[j] |= acc.hide;
            }
        }
        let (px, py) = (&mut g.px[..n], &mut g.py[..n]);
        if let Some(post) = &self.post {
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
        x.copy_from_slice(px);
        y.copy_from_slice(py);
        z.copy_from_slice(&g.pz[..n]);
        self.mark_bad(x, y, z, &mut g.bad[..n], rng);
    }

    /// Flag the bad points of a group and restart them at a random point of the plane (a NaN
    /// or infinite z must not carry over).
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

/// The 3-D camera of a flame, ready to project points (Apophysis 7X's model, as Fractorium and
/// JWildfire use it): turn by the yaw about z, then by the pitch about x, divide by the
/// perspective factor 1 − p·z′, and with depth of field move each point by a random offset
/// proportional to its depth.
#[derive(Clone, Debug)]
pub struct Projection {
    /// Rows: x′, y′, z′ as combinations of (x, y, z − zpos).
    m: [[f64; 3]; 3],
    perspective: f64,
    zpos: f64,
    /// 0.1 · cam_dof.
    blur: f64,
    blur_curve: f64,
    /// Half the image size in world units (the blur curve is relative to it).
    half: [f64; 2],
}

impl Projection {
    /// The projection of `flame`'s camera, or `None` for the flat view.
    pub fn of(flame: &Flame) -> Option<Projection> {
        let c = &flame.cam;
        if c.is_flat() {
            return None;
        }
        let (sp, cp) = c.pitch.sin_cos();
        let (sy, cy) = (-c.yaw).sin_cos();
        let ppu = flame.ppu();
        Some(Projection {
            m: [
                [cy, -sy, 0.0],
                [cp * sy, cp * cy, -sp],
                [sp * sy, sp * cy, cp],
            ],
            perspective: c.perspective,
            zpos: c.zpos,
            blur: 0.1 * c.dof,
            blur_curve: c.blur_curve,
            half: [
                flame.width as f64 / 2.0 / ppu,
                flame.height as f64 / 2.0 / ppu,
            ],
        })
    }

    /// The plotted position of a point.
    #[inline(always)]
    pub fn project(&self, x: f64, y: f64, z: f64, rng: &mut FastRng) -> (f64, f64) {
        let m = &self.m;
        let z = z - self.zpos;
        let px = m[0][0] * x + m[0][1] * y;
        let py = m[1][0] * x + m[1][1] * y + m[1][2] * z;
        let pz = m[2][0] * x + m[2][1] * y + m[2][2] * z;
        let zr = variations::util::zeps(1.0 - self.perspective * pz);
        if self.blur == 0.0 {
            return (px / zr, py / zr);
        }
        let t = rng.f01() * std::f64::consts::TAU;
        let scale = if self.blur_curve != 0.0 {
            let d = (px / self.half[0]).hypot(py / self.half[1]) * 10.0;
            d * d / (4.0 * self.blur_curve)
        } else {
            1.0
        };
        let dr = rng.f01() * self.blur * scale * pz;
        let (s, c) = t.sin_cos();
        ((px + dr * c) / zr, (py + dr * s) / zr)
    }
}

/// A flame compiled for the chaos game.
#[derive(Clone, Debug)]
pub struct Chaos {
    pub xforms: Vec<CompiledXform>,
    pub final_xform: Option<CompiledXform>,
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
    /// Every xform is an affine map times `linear` (no post-affine), with no final xform,
    /// camera or xaos: orbits then need no grouping by xform (see [`AffineStep`]).
    affine: Option<Vec<AffineStep>>,
}

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

impl Chaos {
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
        let xforms: Vec<CompiledXform> = flame
            .xforms
            .iter()
            .enumerate()
            .map(|(i, x)| {
                let o = match flame.solo_xform {
                    Some(s) if s < n && s != i => 0.0,
                    _ => x.opacity,
                };
                CompiledXform::new(x, o, true)
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
                    return Err(ChaosError::XaosRowZero(i));
                }
                tables.extend_from_slice(&selection_table(&row));
            }
        }
        let final_xform = flame
            .final_xform
            .as_ref()
            .map(|f| CompiledXform::new(f, f.opacity, true));
        // flam3 resets points beyond 1e10; Fractorium only NaN. Flames that use a variation
        // flam3 does not have follow Fractorium.
        let fractorium = flame
            .xforms
            .iter()
            .chain(flame.final_xform.as_ref())
            .flat_map(|x| &x.vars)
            .any(|v| v.weight != 0.0 && !variations::info(v.id).has(variations::flag::FLAM3));
        let mut xforms = xforms;
        let mut final_xform = final_xform;
        if fractorium {
            for x in xforms.iter_mut().chain(final_xform.as_mut()) {
                x.bad_limit = BAD_LIMIT_WIDE;
            }
        }
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
        let hides = xforms.iter().chain(final_xform.as_ref()).any(|x| x.hides);
        Ok(Chaos {
            affine,
            hides,
            same_vis: vis.iter().all(|&v| v == vis[0]).then_some(vis[0]),
            vis,
            xforms,
            final_xform,
            projection: Projection::of(flame),
            tables,
            xaos,
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

    /// Apply the final xform (if any, with its opacity as a probability) to a copy of a point.
    #[inline(always)]
    pub fn finalise(&self, p: Pt, rng: &mut FastRng) -> Pt {
        self.finalise_hiding(p, rng).0
    }

    /// [`Chaos::finalise`], also saying whether the final xform hid the point.
    #[inline(always)]
    pub fn finalise_hiding(&self, p: Pt, rng: &mut FastRng) -> (Pt, bool) {
        match &self.final_xform {
            Some(f) if f.opacity >= 1.0 || rng.f01() < f.opacity => {
                let (q, _, hide) = f.apply_hiding(p, rng);
                (q, hide)
            }
            _ => (p, false),
        }
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

    /// A random start point iterated through the fuse, and the xform applied last.
    fn fused_start(&self, rng: &mut FastRng) -> (Pt, usize) {
        let mut p = Self::start_point(rng);
        let mut last = None;
        for _ in 0..FUSE {
            let i = self.choose(last, rng);
            p = self.xforms[i].apply(p, rng).0;
            last = Some(i);
        }
        (p, last.unwrap_or(0))
    }

    /// Run one sub-batch of `n` plotted samples. `plot(p, vis)` receives
    /// every point after the fuse, final xform applied. Returns the number of bad values.
    #[inline(always)]
    pub fn run_sub_batch<F: FnMut(Pt, f64)>(&self, n: u64, rng: &mut FastRng, mut plot: F) -> u64 {
        let mut p = Self::start_point(rng);
        let mut k: i64 = -FUSE;
        let mut consec = 0u32;
        let mut bad = 0u64;
        let mut last = None;
        let n = n as i64;
        while k < n {
            let i = self.choose(last, rng);
            let xf = &self.xforms[i];
            let (np, is_bad, hidden) = xf.apply_hiding(p, rng);
            p = np;
            if is_bad {
                consec += 1;
                bad += 1;
                if consec < 5 {
                    continue;
                }
            }
            consec = 0;
            last = Some(i);
            if k >= 0 {
                // A hidden sample counts, and adds nothing.
                let (q, fin_hidden) = self.finalise_hiding(p, rng);
                let v = if hidden || fin_hidden { 0.0 } else { xf.vis };
                plot(self.project(q, rng), v);
            }
            k += 1;
        }
        bad
    }
}

impl Chaos {
    /// Iterate until `n` more samples are plotted, with [`LANES`] orbits advanced together:
    /// at every step each orbit draws its xform, and each xform is applied to all the orbits
    /// that drew it as one array computation. The orbits persist between calls (a worker keeps
    /// one [`Lanes`] for its whole render): every orbit starts at a random point, is fused for
    /// 15 steps and retries bad values up to 4 times, as in [`Chaos::run_sub_batch`]; one
    /// orbit, chosen at random, restarts (fused) at every call, so that orbits live about as
    /// long as flam3's (one per sub-batch of 10 000 samples).
    ///
    /// `plot(xs, ys, zs, cs, vis)` receives the points of a step (final xform and camera
    /// applied) with their visibilities; an entry with a negative visibility is not a sample
    /// (an orbit still in its fuse or retrying a bad value, or beyond the `n` asked for) and
    /// must be skipped. Returns the number of bad values.
    #[inline(always)]
    pub fn run_lanes<F: FnMut(&[f64], &[f64], &[f64], &[f64], &[f64])>(
        &self,
        n: u64,
        rng: &mut FastRng,
        ln: &mut Lanes,
        mut plot: F,
    ) -> u64 {
        let nx = self.xforms.len();
        if !ln.started {
            let o = &mut ln.sets[ln.cur & 1];
            for l in 0..LANES {
                let p = Self::start_point(rng);
                (o.x[l], o.y[l], o.z[l], o.c[l]) = (p.x, p.y, p.z, p.c);
            }
            ln.started = true;
        } else {
            // flam3 starts a new orbit for every sub-batch of 10 000 samples; a flame that
            // converges slowly (one contracting xform, say) shows the path towards its
            // attractor from each start. Restart one orbit per call, chosen at random: every
            // orbit then lives for ~LANES calls, about 10 000 of its own samples, the same
            // share of fresh starts.
            let l = rng.u32() as usize % LANES;
            let (p, last) = self.fused_start(rng);
            let o = &mut ln.sets[ln.cur & 1];
            (o.x[l], o.y[l], o.z[l], o.c[l]) = (p.x, p.y, p.z, p.c);
            (o.last[l], o.consec[l], o.step[l]) = (last as u16, 0, 0);
        }
        ln.counts.resize(4 * (nx + 1), 0);
        ln.bounds.resize(nx + 1, 0);
        let mut plotted = 0u64;
        let mut bad = 0u64;
        const M: usize = LANES - 1;
        let direct = self.final_xform.is_none() && self.projection.is_none();
        while plotted < n {
            let [s0, s1] = &mut ln.sets;
            let (src, dst) = if ln.cur & 1 == 0 { (s0, s1) } else { (s1, s0) };
            // Draw every orbit's xform; group the orbits by xform (counting sort).
            // Four interleaved streams of counters and positions avoid store-to-load chains on
            // a single counter.
            let w = nx + 1;
            // Four 16-bit draws per random word (14 bits are used, as flam3's table grain).
            const G: usize = CHOOSE_GRAIN - 1;
            if let (Some(rows), true) = (&self.affine, ln.clean) {
                // Affine IFS past the fuse: every orbit steps in place by its drawn row.
                let table = &self.tables[..CHOOSE_GRAIN];
                for q in 0..LANES / 4 {
                    let mut u = rng.u64();
                    for r in 0..4 {
                        ln.choice[4 * q + r] = table[u as usize & G];
                        u >>= 16;
                    }
                }
                let mut any_bad = false;
                for l in 0..LANES {
                    let i = ln.choice[l];
                    let t = &rows[i as usize];
                    let (x, y) = (src.x[l], src.y[l]);
                    let (tx, ty) = (t.a * x + t.b * y + t.e, t.c * x + t.d * y + t.f);
                    let (x, y) = (0.0 + t.w * tx, 0.0 + t.w * ty);
                    dst.x[l] = x;
                    dst.y[l] = y;
                    dst.z[l] = 0.0 + t.w * src.z[l];
                    dst.c[l] = t.sc + t.keep * src.c[l];
                    let b = !within(x, t.bad_limit) | !within(y, t.bad_limit);
                    ln.bad[l] = b;
                    any_bad |= b;
                    ln.group[l] = i;
                }
                if any_bad {
                    for l in 0..LANES {
                        if ln.bad[l] {
                            dst.x[l] = rng.f11();
                            dst.y[l] = rng.f11();
                            dst.z[l] = 0.0;
                        }
                    }
                }
                ln.cur ^= 1;
            } else {
                ln.counts.fill(0);
                if self.xaos {
                    for q in 0..LANES / 4 {
                        let mut u = rng.u64();
                        for r in 0..4 {
                            let l = 4 * q + r;
                            let prev = src.last[l];
                            let row = if prev == u16::MAX {
                                0
                            } else {
                                prev as usize + 1
                            };
                            let i = self.tables[row * CHOOSE_GRAIN + (u as usize & G)] as usize;
                            u >>= 16;
                            ln.choice[l] = i as u16;
                            ln.counts[r * w + i] += 1;
                        }
                    }
                } else {
                    let table = &self.tables[..CHOOSE_GRAIN];
                    for q in 0..LANES / 4 {
                        let mut u = rng.u64();
                        for r in 0..4 {
                            let i = table[u as usize & G] as usize;
                            u >>= 16;
                            ln.choice[4 * q + r] = i as u16;
                            ln.counts[r * w + i] += 1;
                        }
                    }
                }
                // bounds[i]: start of group i; positions of stream s inside group i follow.
                let mut acc = 0usize;
                for i in 0..nx {
                    ln.bounds[i] = acc;
                    for st in 0..4 {
                        let c = ln.counts[st * w + i];
                        ln.counts[st * w + i] = acc;
                        acc += c;
                    }
                }
                ln.bounds[nx] = acc;
                for l in 0..LANES {
                    let k = (l & 3) * w + ln.choice[l] as usize;
                    ln.order[ln.counts[k] & M] = l as u16;
                    ln.counts[k] += 1;
                }
                // Gather the orbits into `dst` in group order.
                for (p, &l) in ln.order.iter().enumerate() {
                    let l = l as usize & M;
                    dst.x[p] = src.x[l];
                    dst.y[p] = src.y[l];
                    dst.z[p] = src.z[l];
                    dst.c[p] = src.c[l];
                }
                if self.xaos {
                    for (p, &l) in ln.order.iter().enumerate() {
                        dst.last[p] = src.last[l as usize & M];
                    }
                }
                if !ln.clean {
                    for (p, &l) in ln.order.iter().enumerate() {
                        let l = l as usize & M;
                        dst.consec[p] = src.consec[l];
                        dst.step[p] = src.step[l];
                        dst.last[p] = src.last[l];
                    }
                }
                ln.cur ^= 1;
                for i in 0..nx {
                    let (start, end) = (ln.bounds[i].min(LANES), ln.bounds[i + 1].min(LANES));
                    if end > start {
                        let r = start..end;
                        self.xforms[i].apply_soa(
                            &mut dst.x[r.clone()],
                            &mut dst.y[r.clone()],
                            &mut dst.z[r.clone()],
                            &mut dst.c[r.clone()],
                            &mut ln.g,
                            rng,
                        );
                        ln.bad[r.clone()].copy_from_slice(&ln.g.bad[..end - start]);
                        if self.hides {
                            if self.xforms[i].hides {
                                ln.hide[r.clone()].copy_from_slice(&ln.g.hide[..end - start]);
                            } else {
                                ln.hide[r.clone()].fill(false);
                            }
                        }
                        ln.group[r].fill(i as u16);
                    }
                }
            }
            // The common step: no bad value, every orbit a sample.
            if ln.clean && direct && !ln.bad.iter().any(|&b| b) && plotted + LANES as u64 <= n {
                dst.last = ln.group;
                match self.same_vis {
                    Some(v) => ln.vis = [v; LANES],
                    None => {
                        for (v, &g) in ln.vis.iter_mut().zip(&ln.group) {
                            *v = self.vis.get(g as usize).copied().unwrap_or(0.0);
                        }
                    }
                }
                if self.hides {
                    // A hidden sample counts, and adds nothing.
                    for (v, &h) in ln.vis.iter_mut().zip(&ln.hide) {
                        if h {
                            *v = 0.0;
                        }
                    }
                }
                plotted += LANES as u64;
                plot(&dst.x, &dst.y, &dst.z, &dst.c, &ln.vis);
                continue;
            }
            // Bad-value retries, step counting, and which points are samples.
            let mut nf = 0usize;
            for p in 0..LANES {
                ln.vis[p] = -1.0;
                if ln.bad[p] {
                    dst.consec[p] += 1;
                    bad += 1;
                    if dst.consec[p] < 5 {
                        continue;
                    }
                }
                dst.consec[p] = 0;
                let ch = ln.group[p];
                dst.last[p] = ch;
                if dst.step[p] >= 0 {
                    if plotted < n {
                        let v = if self.hides && ln.hide[p] {
                            0.0
                        } else {
                            self.xforms[ch as usize].vis
                        };
                        plotted += 1;
                        if direct {
                            ln.vis[p] = v;
                        } else {
                            let k = nf & M;
                            ln.fin.x[k] = dst.x[p];
                            ln.fin.y[k] = dst.y[p];
                            ln.fin.z[k] = dst.z[p];
                            ln.fin.c[k] = dst.c[p];
                            ln.fin_vis[k] = v;
                            nf += 1;
                        }
                    }
                } else {
                    dst.step[p] += 1;
                }
            }
            if !ln.clean && dst.consec.iter().all(|&c| c == 0) && dst.step.iter().all(|&s| s >= 0) {
                // From now on the counters are not gathered: both sets must read as clean.
                ln.clean = true;
                src.consec = [0; LANES];
                src.step = [0; LANES];
            } else if ln.clean && dst.consec.iter().any(|&c| c != 0) {
                ln.clean = false;
            }
            if direct {
                plot(&dst.x, &dst.y, &dst.z, &dst.c, &ln.vis);
                continue;
            }
            let m = nf.min(LANES);
            if let Some(f) = &self.final_xform {
                let fin = &mut ln.fin;
                if f.opacity >= 1.0 {
                    f.apply_soa(
                        &mut fin.x[..m],
                        &mut fin.y[..m],
                        &mut fin.z[..m],
                        &mut fin.c[..m],
                        &mut ln.g,
                        rng,
                    );
                    if f.hides {
                        for (v, &h) in ln.fin_vis[..m].iter_mut().zip(&ln.g.hide[..m]) {
                            if h {
                                *v = 0.0;
                            }
                        }
                    }
                } else {
                    // Apply with probability = opacity: compact the chosen points, apply, put back.
                    ln.chosen.clear();
                    for j in 0..m {
                        if rng.f01() < f.opacity {
                            ln.chosen.push(j);
                        }
                    }
                    let t = &mut ln.tmp;
                    for (k, &j) in ln.chosen.iter().enumerate() {
                        let (k, j) = (k & M, j & M);
                        t.x[k] = fin.x[j];
                        t.y[k] = fin.y[j];
                        t.z[k] = fin.z[j];
                        t.c[k] = fin.c[j];
                    }
                    let k = ln.chosen.len().min(LANES);
                    f.apply_soa(
                        &mut t.x[..k],
                        &mut t.y[..k],
                        &mut t.z[..k],
                        &mut t.c[..k],
                        &mut ln.g,
                        rng,
                    );
                    if f.hides {
                        for (k, &j) in ln.chosen.iter().enumerate() {
                            if ln.g.hide[k & M] {
                                ln.fin_vis[j & M] = 0.0;
                            }
                        }
                    }
                    for (k, &j) in ln.chosen.iter().enumerate() {
                        let (k, j) = (k & M, j & M);
                        fin.x[j] = t.x[k];
                        fin.y[j] = t.y[k];
                        fin.z[j] = t.z[k];
                        fin.c[j] = t.c[k];
                    }
                }
            }
            if let Some(pr) = &self.projection {
                let fin = &mut ln.fin;
                for j in 0..m {
                    (fin.x[j], fin.y[j]) = pr.project(fin.x[j], fin.y[j], fin.z[j], rng);
                }
            }
            let fin = &ln.fin;
            plot(
                &fin.x[..m],
                &fin.y[..m],
                &fin.z[..m],
                &fin.c[..m],
                &ln.fin_vis[..m],
            );
        }
        bad
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn selection_table_matches_weights() {
        let t = selection_table(&[1.0, 3.0]);
        let ones = t.iter().filter(|&&v| v == 1).count();
        assert_eq!(ones, 16384 * 3 / 4);
        assert_eq!(t[0], 0);
        assert_eq!(t[16383], 1);
        // A tiny weight may get no entry (flam3 quantisation); never out of range.
        let t = selection_table(&[1.0, 1e-9, 1.0]);
        assert!(t.iter().all(|&v| v < 3));
    }

    #[test]
    fn opacity_adjustment_oracles() {
        assert!((adjust_opacity(0.5) - 0.1).abs() < 1e-12);
        assert!((adjust_opacity(0.25) - 0.01).abs() < 1e-12);
        assert_eq!(adjust_opacity(1.0), 1.0);
        assert_eq!(adjust_opacity(0.0), 0.0);
    }

    #[test]
    fn empty_and_bad_flames_are_rejected() {
        let mut f = Flame::default();
        assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::NoXforms);
        f.xforms.push(Xform::linear(Affine::IDENTITY, 0.0, 0.0));
        assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::ZeroWeights);
        f.xforms[0].weight = -1.0;
        assert!(matches!(Chaos::new(&f), Err(ChaosError::BadWeight(0, _))));
        f.xforms[0].weight = 1.0;
        f.xforms[0].chaos = vec![0.0];
        assert_eq!(Chaos::new(&f).unwrap_err(), ChaosError::XaosRowZero(0));
    }

    #[test]
    fn sierpinski_points_stay_on_the_attractor() {
        let mut f = Flame::default();
        for (e, ff) in [(0.0, 0.0), (0.5, 0.0), (0.25, 0.5)] {
            f.xforms.push(Xform::linear(
                Affine::new(0.5, 0.0, 0.0, 0.5, e, ff),
                1.0,
                0.0,
            ));
        }
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(5);
        let mut count = 0;
        let bad = ch.run_sub_batch(10_000, &mut rng, |p, vis| {
            let (x, y) = (p.x, p.y);
            assert!((-1e-6..=1.0 + 1e-6).contains(&x) && (-1e-6..=1.0 + 1e-6).contains(&y));
            assert_eq!(vis, 1.0);
            count += 1;
        });
        assert_eq!(count, 10_000);
        assert_eq!(bad, 0);
    }

    #[test]
    fn lanes_match_the_scalar_statistics() {
        // A flame with a non-trivial variation mix: the mean and spread of the plotted points
        // and colours agree between the scalar and the lane runner.
        let mut f = Flame::default();
        let mut a = Xform::linear(Affine::new(0.6, -0.3, 0.4, 0.5, 0.2, -0.1), 1.0, 0.0);
        a.vars = vec![
            crate::flame::model::Var::new(variations::SWIRL, 0.6),
            crate::flame::model::Var::new(variations::POLAR, 0.4),
        ];
        let mut b = Xform::linear(Affine::new(-0.5, 0.2, 0.1, 0.7, -0.3, 0.4), 2.0, 1.0);
        b.vars = vec![crate::flame::model::Var::new(variations::SPHERICAL, 0.8)];
        b.post = Affine::new(0.9, 0.0, 0.0, 0.9, 0.1, 0.0);
        f.xforms = vec![a, b];
        let mut fx = Xform::linear(Affine::new(1.0, 0.1, 0.0, 1.0, 0.0, 0.0), 0.0, 0.5);
        fx.vars = vec![crate::flame::model::Var::new(variations::SINUSOIDAL, 1.0)];
        fx.opacity = 0.7;
        f.final_xform = Some(fx);
        let ch = Chaos::new(&f).unwrap();
        let stats = |lanes: bool| {
            let mut rng = FastRng::new(11);
            let mut sc = Lanes::new();
            let (mut n, mut sx, mut sy, mut sc2, mut sxx) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for _ in 0..40 {
                // Bounded statistics: the spherical xform gives heavy tails.
                let mut plot = |x: f64, y: f64, c: f64, _v: f64| {
                    n += 1.0;
                    sx += x.clamp(-3.0, 3.0);
                    sy += y.clamp(-3.0, 3.0);
                    sc2 += c;
                    sxx += (x.abs() < 0.5) as u8 as f64;
                };
                if lanes {
                    ch.run_lanes(10_000, &mut rng, &mut sc, |xs, ys, _zs, cs, vs| {
                        for j in 0..xs.len() {
                            if vs[j] >= 0.0 {
                                plot(xs[j], ys[j], cs[j], vs[j]);
                            }
                        }
                    });
                } else {
                    ch.run_sub_batch(10_000, &mut rng, |p, v| plot(p.x, p.y, p.c, v));
                }
            }
            (n, sx / n, sy / n, sc2 / n, sxx / n)
        };
        let a = stats(false);
        let b = stats(true);
        assert_eq!(a.0, 400_000.0);
        assert_eq!(b.0, 400_000.0);
        for (p, q) in [(a.1, b.1), (a.2, b.2), (a.3, b.3), (a.4, b.4)] {
            assert!((p - q).abs() < 0.01, "{a:?} vs {b:?}");
        }
    }

    /// Run the lane runner and bin the plotted points on an 8×8 grid over [−1, 2]²; also the
    /// mean colour, the number of samples and of bad values.
    fn lane_grid(ch: &Chaos, seed: u64) -> ([f64; 64], f64, f64, u64) {
        let mut rng = FastRng::new(seed);
        let mut ln = Lanes::new();
        let (mut grid, mut n, mut c) = ([0.0; 64], 0.0, 0.0);
        let mut bad = 0;
        for _ in 0..30 {
            bad += ch.run_lanes(10_000, &mut rng, &mut ln, |xs, ys, _zs, cs, vs| {
                for j in 0..xs.len() {
                    if vs[j] >= 0.0 {
                        assert!(xs[j].is_finite() && ys[j].is_finite());
                        let cell = |v: f64| (((v + 1.0) / 3.0 * 8.0).clamp(0.0, 7.0)) as usize;
                        grid[cell(ys[j]) * 8 + cell(xs[j])] += 1.0;
                        n += 1.0;
                        c += cs[j];
                    }
                }
            });
        }
        (grid.map(|g| g / n), n, c / n, bad)
    }

    #[test]
    fn affine_ifs_steps_orbits_in_place_with_the_same_statistics() {
        // Unequal weights, a colour blend and a linear weight other than 1: the in-place rows
        // and the grouped general path plot the same distribution.
        let mut f = Flame::default();
        for (i, (e, ff, w)) in [(0.0, 0.0, 1.0), (0.5, 0.0, 2.0), (0.25, 0.5, 0.5)]
            .into_iter()
            .enumerate()
        {
            let mut x = Xform::linear(Affine::new(0.5, 0.1, -0.1, 0.5, e, ff), w, i as f64 / 2.0);
            x.vars[0].weight = 0.9;
            x.color_speed = 0.3;
            f.xforms.push(x);
        }
        let ch = Chaos::new(&f).unwrap();
        assert!(ch.affine.is_some());
        let general = Chaos {
            affine: None,
            ..Chaos::new(&f).unwrap()
        };
        let (a, na, ca, _) = lane_grid(&ch, 3);
        let (b, nb, cb, _) = lane_grid(&general, 3);
        assert_eq!((na, nb), (300_000.0, 300_000.0));
        assert!((ca - cb).abs() < 0.01, "{ca} vs {cb}");
        let l1: f64 = a.iter().zip(&b).map(|(p, q)| (p - q).abs()).sum();
        assert!(l1 < 0.02, "cell frequencies differ by {l1}");
        // A post-affine, a final xform or xaos take the general path.
        let mut g = f.clone();
        g.xforms[1].post = Affine::new(0.9, 0.0, 0.0, 0.9, 0.0, 0.0);
        assert!(Chaos::new(&g).unwrap().affine.is_none());
    }

    #[test]
    fn orbits_restart_as_often_as_flam3s() {
        // One xform contracting slowly to the origin: only fresh orbits plot points away from
        // it. flam3 starts one orbit per sub-batch; the lane runner restarts one orbit per call,
        // so the share of such points is about the same (long-lived orbits alone: ~20× fewer).
        let mut f = Flame::default();
        f.xforms.push(Xform::linear(
            Affine::new(0.9, 0.0, 0.0, 0.9, 0.0, 0.0),
            1.0,
            0.0,
        ));
        let ch = Chaos::new(&f).unwrap();
        let (calls, n) = (5000, 200);
        let mut rng = FastRng::new(8);
        let (mut far, mut total) = (0.0, 0.0);
        for _ in 0..calls {
            ch.run_sub_batch(n, &mut rng, |p, _| {
                far += (p.x.abs() > 0.01) as u8 as f64;
                total += 1.0;
            });
        }
        let scalar = far / total;
        let mut ln = Lanes::new();
        let (mut far, mut total) = (0.0, 0.0);
        for _ in 0..calls {
            ch.run_lanes(n, &mut rng, &mut ln, |xs, _ys, _zs, _cs, vs| {
                for (x, v) in xs.iter().zip(vs) {
                    if *v >= 0.0 {
                        far += (x.abs() > 0.01) as u8 as f64;
                        total += 1.0;
                    }
                }
            });
        }
        let lanes = far / total;
        assert!(scalar > 0.05, "{scalar}");
        assert!(
            (0.5..1.5).contains(&(lanes / scalar)),
            "{lanes} vs {scalar}"
        );
    }

    #[test]
    fn hidden_samples_count_and_add_nothing() {
        // crop_stars hides what falls outside its star: those samples come to the origin,
        // count as samples, and are plotted with visibility 0, in the lanes and the scalar
        // loop alike.
        let crop = variations::by_name("crop_stars").unwrap();
        let mut a = Xform::linear(Affine::new(0.9, 0.3, -0.3, 0.9, 0.2, 0.1), 1.0, 0.0);
        a.vars = vec![crate::flame::model::Var::new(crop, 1.0)];
        let mut b = Xform::linear(Affine::new(0.6, 0.0, 0.0, 0.6, -0.3, 0.2), 1.0, 1.0);
        b.vars = vec![crate::flame::model::Var::new(variations::SPHERICAL, 0.5)];
        let f = Flame {
            xforms: vec![a, b],
            ..Flame::default()
        };
        let ch = Chaos::new(&f).unwrap();
        assert!(ch.hides && ch.xforms[0].hides && !ch.xforms[1].hides);
        let at_origin = |x: f64, y: f64| x == 0.0 && y == 0.0;
        let mut rng = FastRng::new(2);
        let mut ln = Lanes::new();
        let (mut n, mut hidden) = (0u64, 0u64);
        for _ in 0..20 {
            ch.run_lanes(10_000, &mut rng, &mut ln, |xs, ys, _zs, _cs, vs| {
                for j in 0..xs.len() {
                    if vs[j] < 0.0 {
                        continue;
                    }
                    n += 1;
                    if vs[j] == 0.0 {
                        hidden += 1;
                        assert!(at_origin(xs[j], ys[j]));
                    } else {
                        assert!(!at_origin(xs[j], ys[j]), "a hidden point was drawn");
                    }
                }
            });
        }
        assert_eq!(n, 200_000);
        let (mut m, mut hidden_scalar) = (0u64, 0u64);
        for _ in 0..20 {
            ch.run_sub_batch(10_000, &mut rng, |p, v| {
                m += 1;
                if v == 0.0 {
                    hidden_scalar += 1;
                    assert!(at_origin(p.x, p.y));
                }
            });
        }
        assert_eq!(m, 200_000);
        let (fl, fs) = (hidden as f64 / 2e5, hidden_scalar as f64 / 2e5);
        assert!(fl > 0.05 && (fl - fs).abs() < 0.02, "{fl} vs {fs}");
    }

    #[test]
    fn affine_ifs_replaces_bad_values_and_keeps_plotting() {
        // An expanding map sends orbits past the bad-value limit: they restart at random
        // points, are counted, and every plotted point is finite.
        let mut f = Flame::default();
        f.xforms.push(Xform::linear(
            Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0),
            1.0,
            0.0,
        ));
        f.xforms.push(Xform::linear(
            Affine::new(1e30, 0.0, 0.0, 1e30, 0.0, 0.0),
            1.0,
            1.0,
        ));
        let ch = Chaos::new(&f).unwrap();
        assert!(ch.affine.is_some());
        let (_, n, _, bad) = lane_grid(&ch, 4);
        assert_eq!(n, 300_000.0);
        assert!(bad > 1000, "{bad} bad values");
    }

    fn projection(cam: crate::flame::model::Camera3d) -> Projection {
        let f = Flame {
            cam,
            ..Flame::default()
        };
        Projection::of(&f).expect("a 3-D camera")
    }

    #[test]
    fn pre_and_post_forms_wrap_the_regular_variations() {
        use crate::flame::model::Var;
        use crate::flame::variations::{Form, LINEAR, SINUSOIDAL, SPHERICAL};
        let mut x = Xform::linear(Affine::new(0.8, 0.2, -0.3, 0.9, 0.1, -0.2), 1.0, 0.0);
        x.vars = vec![
            Var::with_form(SINUSOIDAL, Form::Pre, 1.0),
            Var::new(LINEAR, 0.5),
            Var::with_form(SPHERICAL, Form::Post, 1.0),
        ];
        let f = Flame {
            xforms: vec![x.clone()],
            ..Flame::default()
        };
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(2);
        let p = Pt {
            x: 0.4,
            y: -0.7,
            z: 0.0,
            c: 0.5,
        };
        let (q, bad) = ch.xforms[0].apply(p, &mut rng);
        assert!(!bad);
        // affine → sin (replaces the point) → 0.5·linear → spherical of the sum.
        let (tx, ty) = x.coefs.apply(p.x, p.y);
        let (sx, sy) = (0.5 * tx.sin(), 0.5 * ty.sin());
        let r2 = sx * sx + sy * sy;
        assert!(
            (q.x - sx / r2).abs() < 1e-12 && (q.y - sy / r2).abs() < 1e-12,
            "{q:?}"
        );
        // The same through the batched lanes.
        let (mut gx, mut gy, mut gz, mut gc) = ([p.x], [p.y], [p.z], [p.c]);
        let mut s = Scratch::new();
        ch.xforms[0].apply_soa(&mut gx, &mut gy, &mut gz, &mut gc, &mut s, &mut rng);
        assert!((gx[0] - q.x).abs() < 1e-12 && (gy[0] - q.y).abs() < 1e-12);
    }

    #[test]
    fn linear_only_xforms_take_the_short_path_with_the_same_bits() {
        let mut x = Xform::linear(Affine::new(0.5, -0.3, 0.2, 0.7, 0.1, -0.4), 1.0, 0.25);
        x.vars[0].weight = 0.8;
        x.post = Affine::new(0.9, 0.1, -0.2, 1.1, 0.05, 0.3);
        x.color_speed = 0.4;
        let f = Flame {
            xforms: vec![x],
            ..Flame::default()
        };
        let ch = Chaos::new(&f).unwrap();
        assert_eq!(ch.xforms[0].linear_only, Some(0.8));
        let mut rng = FastRng::new(5);
        let pts: Vec<Pt> = (0..16).map(|_| Chaos::start_point(&mut rng)).collect();
        let mut gx: Vec<f64> = pts.iter().map(|p| p.x).collect();
        let mut gy: Vec<f64> = pts.iter().map(|p| p.y).collect();
        let mut gz: Vec<f64> = pts.iter().map(|p| p.z + 0.5).collect();
        let mut gc: Vec<f64> = pts.iter().map(|p| p.c).collect();
        let mut s = Scratch::new();
        ch.xforms[0].apply_soa(&mut gx, &mut gy, &mut gz, &mut gc, &mut s, &mut rng);
        for (j, p) in pts.iter().enumerate() {
            let (q, bad) = ch.xforms[0].apply(Pt { z: p.z + 0.5, ..*p }, &mut rng);
            assert!(!bad && !s.bad[j]);
            assert_eq!((q.x, q.y, q.z, q.c), (gx[j], gy[j], gz[j], gc[j]));
        }
        // Any other variation, or a pre_/post_ form, takes the general path.
        let mut f2 = f.clone();
        f2.xforms[0]
            .vars
            .push(crate::flame::model::Var::new(variations::SPHERICAL, 0.1));
        assert_eq!(Chaos::new(&f2).unwrap().xforms[0].linear_only, None);
    }

    #[test]
    fn camera_projection_oracles() {
        use crate::flame::model::Camera3d;
        use std::f64::consts::FRAC_PI_2;
        let mut rng = FastRng::new(1);
        let close = |a: (f64, f64), b: (f64, f64)| {
            assert!(
                (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-12,
                "{a:?} vs {b:?}"
            )
        };
        assert!(Projection::of(&Flame::default()).is_none());
        // Perspective only: divide by 1 − p·z.
        let p = projection(Camera3d {
            perspective: 0.5,
            ..Camera3d::default()
        });
        close(p.project(1.0, 1.0, 1.0, &mut rng), (2.0, 2.0));
        // The focal plane moves z.
        let p = projection(Camera3d {
            perspective: 0.5,
            zpos: 1.0,
            ..Camera3d::default()
        });
        close(p.project(1.0, 1.0, 1.0, &mut rng), (1.0, 1.0));
        // Pitch a quarter turn: the view from the side, y′ = −z.
        let p = projection(Camera3d {
            pitch: FRAC_PI_2,
            ..Camera3d::default()
        });
        close(p.project(1.0, 2.0, 3.0, &mut rng), (1.0, -3.0));
        // Yaw a quarter turn about z: (x, y) → (y, −x).
        let p = projection(Camera3d {
            yaw: FRAC_PI_2,
            ..Camera3d::default()
        });
        close(p.project(1.0, 2.0, 0.0, &mut rng), (2.0, -1.0));
    }

    #[test]
    fn depth_of_field_blurs_by_depth() {
        use crate::flame::model::Camera3d;
        let p = projection(Camera3d {
            dof: 2.0,
            ..Camera3d::default()
        });
        let mut rng = FastRng::new(3);
        // In the focal plane: sharp.
        assert_eq!(p.project(0.3, 0.4, 0.0, &mut rng), (0.3, 0.4));
        // At depth 1: moved by 0.1·dof·u, u uniform in [0, 1): mean distance 0.1.
        let n = 20_000;
        let mean = (0..n)
            .map(|_| {
                let (x, y) = p.project(0.3, 0.4, 1.0, &mut rng);
                (x - 0.3).hypot(y - 0.4)
            })
            .sum::<f64>()
            / n as f64;
        assert!((mean - 0.1).abs() < 0.003, "{mean}");
    }

    #[test]
    fn a_flat_attractor_seen_edge_on_is_a_line() {
        let mut f = Flame::default();
        for (e, ff) in [(0.0, 0.0), (0.5, 0.0), (0.25, 0.5)] {
            f.xforms.push(Xform::linear(
                Affine::new(0.5, 0.0, 0.0, 0.5, e, ff),
                1.0,
                0.0,
            ));
        }
        f.cam.pitch = std::f64::consts::FRAC_PI_2;
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(5);
        let (mut xmin, mut xmax) = (f64::MAX, f64::MIN);
        ch.run_sub_batch(5_000, &mut rng, |p, _| {
            assert!(p.y.abs() < 1e-12, "{p:?}");
            xmin = xmin.min(p.x);
            xmax = xmax.max(p.x);
        });
        assert!(xmax - xmin > 0.9);
    }

    #[test]
    fn xaos_restricts_transitions() {
        // Xform 0 may only go to 1, 1 only to 0: colours alternate exactly.
        let mut f = Flame::default();
        let mut a = Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0), 1.0, 0.0);
        a.color_speed = 1.0;
        a.chaos = vec![0.0, 1.0];
        let mut b = Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 0.5, 0.0), 1.0, 1.0);
        b.color_speed = 1.0;
        b.chaos = vec![1.0, 0.0];
        f.xforms = vec![a, b];
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(9);
        let mut prev: Option<f64> = None;
        ch.run_sub_batch(1000, &mut rng, |p, _| {
            let c = p.c;
            if let Some(p) = prev {
                assert_ne!(p, c);
            }
            prev = Some(c);
        });
    }

    #[test]
    fn bad_values_are_retried() {
        // A map that expands by 10⁶ escapes past 1e10 within two steps: the point is
        // replaced by a random point and nothing non-finite or huge is ever plotted.
        let f = Flame {
            xforms: vec![Xform::linear(
                Affine::new(1e6, 0.0, 0.0, 1e6, 0.0, 0.0),
                1.0,
                0.0,
            )],
            ..Flame::default()
        };
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(1);
        let bad = ch.run_sub_batch(100, &mut rng, |p, _| {
            assert!(p.x.abs() <= BAD_LIMIT && p.y.abs() <= BAD_LIMIT);
        });
        assert!(bad > 0);
    }

    #[test]
    fn a_bad_value_restarts_in_the_plane() {
        // A 3-D point that escapes is replaced by a random point with z = 0: a NaN or huge z
        // carried over would poison every later step of 3-D variations (tanq, sinhq …).
        let mut x = Xform::linear(Affine::new(1e11, 0.0, 0.0, 1e11, 0.0, 0.0), 1.0, 0.0);
        x.vars = vec![crate::flame::model::Var::new(
            variations::by_name("linear3D").unwrap(),
            1.0,
        )];
        let f = Flame {
            xforms: vec![x],
            ..Flame::default()
        };
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(3);
        // An infinite x is bad for every flame (linear3D is not flam3's, so 1e10 is not).
        let p = Pt {
            x: f64::INFINITY,
            y: 0.5,
            z: f64::NAN,
            c: 0.0,
        };
        let (q, bad) = ch.xforms[0].apply(p, &mut rng);
        assert!(bad);
        assert_eq!(q.z, 0.0);
        assert!(q.x.abs() <= 1.0 && q.y.abs() <= 1.0);
        // Lanes: plotted points after restarts stay finite.
        let mut seen = 0;
        let mut ln = Lanes::new();
        ch.run_lanes(
            2000,
            &mut rng,
            &mut ln,
            |xs: &[f64], ys: &[f64], zs: &[f64], _, vs: &[f64]| {
                for k in (0..xs.len()).filter(|&k| vs[k] >= 0.0) {
                    assert!(xs[k].is_finite() && ys[k].is_finite() && zs[k].is_finite());
                    seen += 1;
                }
            },
        );
        assert!(seen > 0);
    }

    #[test]
    fn flames_of_fractorium_variations_only_reset_nan() {
        // flam3 resets coordinates beyond 1e10; Fractorium only NaN (and ugnis infinity).
        let mut f = Flame {
            xforms: vec![Xform::linear(Affine::IDENTITY, 1.0, 0.0)],
            ..Flame::default()
        };
        assert_eq!(Chaos::new(&f).unwrap().xforms[0].bad_limit, BAD_LIMIT);
        f.xforms[0].vars.push(crate::flame::model::Var::new(
            variations::by_name("tanq").unwrap(),
            0.5,
        ));
        assert_eq!(Chaos::new(&f).unwrap().xforms[0].bad_limit, BAD_LIMIT_WIDE);
    }
}
