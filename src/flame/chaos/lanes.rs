//! The orbits of the lane runner: [`LANES`] orbits as arrays, two sets that a step reads and
//! writes in turn, the scratch space of a step, and the state a saved render keeps of them.

use super::batch::Scratch;
use super::{FUSE, LANES};

/// The state of [`LANES`] orbits: position, colour coordinate, own colour (see
/// [`crate::flame::variations::own_rgb`]; carried only for flames that have them), the xform
/// applied last (xaos row; `u16::MAX` before the first), consecutive bad values, and steps
/// done (an orbit plots once this is ≥ 0; it starts at minus the fuse, [`Chaos::fuse`](super::Chaos::fuse)). Under JWildfire's rule for bad
/// values an orbit waiting for its restart has [`WAITING`] consecutive bad values.
#[derive(Clone, Debug)]
pub(super) struct Orbits {
    pub(super) x: [f64; LANES],
    pub(super) y: [f64; LANES],
    pub(super) z: [f64; LANES],
    pub(super) c: [f64; LANES],
    pub(super) rgb: [u32; LANES],
    pub(super) last: [u16; LANES],
    pub(super) consec: [u8; LANES],
    pub(super) step: [i32; LANES],
    /// The point is hidden (carried only for a flame JWildfire's renderer draws,
    /// whose points keep their hide flag from xform to xform).
    pub(super) hid: [bool; LANES],
}

/// The consecutive bad values of an orbit whose point is bad under JWildfire's rule: it waits for
/// the next check, which restarts it unless an xform brings it back first (its steps count as
/// samples that draw nothing).
pub(super) const WAITING: u8 = u8::MAX;

impl Orbits {
    fn new() -> Orbits {
        Orbits {
            x: [0.0; LANES],
            y: [0.0; LANES],
            z: [0.0; LANES],
            c: [0.0; LANES],
            rgb: [0; LANES],
            last: [u16::MAX; LANES],
            consec: [0; LANES],
            step: [-(FUSE as i32); LANES],
            hid: [false; LANES],
        }
    }
}

/// The orbits of the lane runner. They live for the whole render of one worker thread (see
/// [`Chaos::run_lanes`](super::Chaos::run_lanes)). Fixed-size arrays: every index is provably
/// in range.
///
/// Orbits are interchangeable, so they need not keep their places: every step reads one set
/// of orbits and writes the other, grouped by the xform each orbit drew, so that each xform
/// works on a contiguous run and nothing is scattered back.
#[derive(Clone, Debug)]
pub struct Lanes {
    pub(super) sets: [Orbits; 2],
    /// Which of `sets` holds the orbits as they stand.
    pub(super) cur: usize,
    pub(super) started: bool,
    /// Every orbit is past its fuse and none is retrying a bad value, in both sets: a step
    /// then needs neither the retry counters nor the step counters.
    pub(super) clean: bool,
    /// Steps taken since the orbits were made (the clock of JWildfire's checks for bad
    /// values; a saved render state keeps it, so a resumed render restarts its waiting orbits
    /// when the uninterrupted one does).
    pub(super) steps: u64,
    // Scratch space.
    pub(super) choice: [u16; LANES],
    pub(super) order: [u16; LANES],
    /// Xform applied at each place of the set just written.
    pub(super) group: [u16; LANES],
    pub(super) counts: Vec<usize>,
    pub(super) bounds: Vec<usize>,
    pub(super) bad: [bool; LANES],
    /// Hidden by a variation, at each place of the set just written.
    pub(super) hide: [bool; LANES],
    /// Visibility of each place of the set just written; negative: not a sample.
    pub(super) vis: [f64; LANES],
    pub(super) g: Scratch,
    pub(super) fin: Group,
    pub(super) fin_vis: [f64; LANES],
    /// Under JWildfire's rule: the sample in `fin` at each place is hidden (the final xforms
    /// may hide it or show it again).
    pub(super) fin_hide: [bool; LANES],
    pub(super) chosen: Vec<usize>,
    pub(super) tmp: Group,
    /// For solid rendering: the samples in `fin` before the camera.
    pub(super) world: Group,
}

/// Points as a structure of arrays, for the final xform.
#[derive(Clone, Debug)]
pub(super) struct Group {
    pub(super) x: [f64; LANES],
    pub(super) y: [f64; LANES],
    pub(super) z: [f64; LANES],
    pub(super) c: [f64; LANES],
    pub(super) rgb: [u32; LANES],
}

impl Group {
    fn new() -> Group {
        Group {
            x: [0.0; LANES],
            y: [0.0; LANES],
            z: [0.0; LANES],
            c: [0.0; LANES],
            rgb: [0; LANES],
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
    /// Each orbit's own colour (see [`crate::flame::variations::own_rgb`]; 0 for flames
    /// without them).
    pub rgb: Vec<u32>,
    /// Each orbit's point is hidden (JWildfire's renderer: the flag travels with the point).
    pub hid: Vec<bool>,
    /// Steps taken (the clock of JWildfire's checks for bad values).
    pub steps: u64,
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
            rgb: o.rgb.to_vec(),
            hid: o.hid.to_vec(),
            steps: self.steps,
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
        o.rgb = st.rgb.as_slice().try_into().ok()?;
        o.hid = st.hid.as_slice().try_into().ok()?;
        l.steps = st.steps;
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

    /// Forget which xform each orbit applied last, so that the next step draws from the flame's
    /// plain weights (for orbits handed to a flame whose xforms are not the ones they ran
    /// with: the sub-frames of a motion-blurred frame).
    pub fn forget_last_xforms(&mut self) {
        for set in &mut self.sets {
            set.last = [u16::MAX; LANES];
        }
    }

    pub fn new() -> Box<Lanes> {
        Box::new(Lanes {
            sets: [Orbits::new(), Orbits::new()],
            cur: 0,
            started: false,
            clean: false,
            steps: 0,
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
            fin_hide: [false; LANES],
            chosen: Vec::with_capacity(LANES),
            tmp: Group::new(),
            world: Group::new(),
        })
    }
}
