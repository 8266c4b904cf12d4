//! In-betweens of flames exactly as flam3 3.1.1 computes them, so that a sequence file renders
//! in ugnis as `flam3-animate` renders it and a loop made here is the one `flam3-genome
//! sequence=` makes:
//!
//! - [`interpolate_at`]: the flame at any time of a sequence of control points (flam3's
//!   `flam3_interpolate`): linear between the two control points around the time (beyond the
//!   ends it extrapolates the first or last segment), or Catmull-Rom through four.
//! - Alignment (`flam3_align`): control points with fewer xforms are padded with weight-0
//!   xforms chosen to match their partners (a spherical partner gets a linear −1 rotated by
//!   180°, a fan or rings partner a swapped identity, …), and a variation's parameters are
//!   carried over where only one side uses it, so that nothing jumps.
//! - Affine maps blend linearly or, with `interpolation_type="log"`, column by column in polar
//!   form (the angle linearly along the shorter turn, the length logarithmically).
//! - Palettes blend in HSV (hue the shorter way round), RGB, a mix of the two, or sweep.
//!
//! flam3-genome's loops and transitions, built on these, are in the `loops` module.

use crate::flame::model::{Affine, Flame, Var, Xform};
use crate::flame::sequence::{Interpolation, InterpolationType};
use crate::flame::variations::{self, Form, VarId};

/// flam3's tolerance at the ±π seam of angles.
pub(crate) const EPS: f64 = 1e-10;

/// One xform of a control point being blended, with what flam3 keeps beside it.
#[derive(Clone, Debug)]
pub(crate) struct Slot {
    pub(crate) x: Xform,
    /// Added by alignment to match another control point.
    pub(crate) padding: bool,
    /// Reference angle per column for xforms that do not turn on one side of a transition
    /// (0: none).
    pub(crate) wind: [f64; 2],
}

/// A control point: the flame's settings and its xforms, the final one (if any) last.
#[derive(Clone, Debug)]
pub(crate) struct Cp {
    pub(crate) flame: Flame,
    pub(crate) slots: Vec<Slot>,
    pub(crate) has_final: bool,
}

impl Cp {
    pub(crate) fn new(f: &Flame) -> Cp {
        let slot = |x: &Xform| Slot {
            x: x.clone(),
            padding: false,
            wind: [0.0; 2],
        };
        let mut slots: Vec<Slot> = f.xforms.iter().map(slot).collect();
        if let Some(fx) = &f.final_xform {
            slots.push(slot(fx));
        }
        let mut flame = f.clone();
        flame.xforms = Vec::new();
        flame.final_xform = None;
        Cp {
            flame,
            slots,
            has_final: f.final_xform.is_some(),
        }
    }

    fn n_std(&self) -> usize {
        self.slots.len() - self.has_final as usize
    }

    pub(crate) fn into_flame(self) -> Flame {
        let mut f = self.flame;
        let mut xs: Vec<Xform> = self.slots.into_iter().map(|s| s.x).collect();
        f.final_xform = if self.has_final { xs.pop() } else { None };
        f.xforms = xs;
        f
    }
}

/// A new xform as flam3 makes one for padding: weight 0, identity maps, linear 1, colour by
/// the parity of its index.
mod align;
mod blend;

pub(crate) use align::align;
#[cfg(test)]
use align::weight_of;
use blend::blend;
pub(crate) use blend::columns;

/// flam3's smooth step 3t² − 2t³.
pub fn smoother(t: f64) -> f64 {
    3.0 * t * t - 2.0 * t * t * t
}

/// flam3's `get_stagger_coef`: with stagger, xform `i` of `n` blends within its own part of the
/// transition, the last xform first.
fn stagger_coef(t: f64, stagger: f64, n: usize, i: usize) -> f64 {
    if n <= 1 {
        return t;
    }
    let max_stag = (n - 1) as f64 / n as f64;
    let scaled = stagger * max_stag;
    let st = scaled * (n - 1 - i.min(n - 1)) as f64 / (n - 1) as f64;
    let et = st + (1.0 - scaled);
    if t <= st {
        0.0
    } else if t >= et {
        1.0
    } else {
        smoother((t - st) / (1.0 - scaled))
    }
}

/// Are a sequence's control points in strictly increasing time order? Returns the index of the
/// first one that is not (or whose time is not a number).
pub fn check_times(cps: &[Flame]) -> Result<(), usize> {
    for (i, f) in cps.iter().enumerate() {
        if !f.anim.time.is_finite() || (i > 0 && f.anim.time <= cps[i - 1].anim.time) {
            return Err(i);
        }
    }
    Ok(())
}

/// The flame at `time` of a sequence of control points sorted by time (flam3's
/// `flam3_interpolate`). Outside the sequence the first or last segment is extrapolated, as
/// flam3 does for the sub-frames of a motion-blurred first or last frame.
pub fn interpolate_at(cps: &[Flame], time: f64) -> Flame {
    assert!(!cps.is_empty(), "a sequence has at least one flame");
    if cps.len() == 1 {
        let mut one = cps[0].clone();
        one.anim.time = time;
        return one;
    }
    // Only the control points the blend reads are prepared.
    let (i1, i2) = segment(cps.len(), |i| cps[i].anim.time, time);
    let lo = i1.saturating_sub(1);
    let hi = (i2 + 1).min(cps.len() - 1);
    let turns = unwrapped_rotations(&cps[..=hi]);
    let window: Vec<Cp> = cps[lo..=hi]
        .iter()
        .zip(&turns[lo..])
        .map(|(f, &rotate)| {
            let mut cp = Cp::new(f);
            cp.flame.rotate = rotate;
            cp
        })
        .collect();
    interpolate_cps(&window, time, 0.0).into_flame()
}

/// The control points' camera rotations as flam3 reads a sequence: each shifted by whole turns
/// to lie within 180° of the one before (so 350° after 10° turns back by 20°, not forward by
/// 340°), except after a control point of the `compat` or `older` interpolation types.
pub fn unwrapped_rotations(cps: &[Flame]) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::with_capacity(cps.len());
    for (i, f) in cps.iter().enumerate() {
        let mut r = f.rotate;
        if let Some(&prev) = out.last()
            && !matches!(
                cps[i - 1].anim.interpolation_type,
                InterpolationType::Compat | InterpolationType::Older
            )
            // Beyond a billion degrees whole turns are lost to rounding: left as written.
            && (r - prev).abs() < 1e9
        {
            // flam3 adds or takes 360° until within range; whole turns toward the previous
            // angle first (truncated, as those loops would stop), so huge angles cost no time.
            r -= 360.0 * ((r - prev) / 360.0).trunc();
            while r < prev - 180.0 {
                r += 360.0;
            }
            while r > prev + 180.0 {
                r -= 360.0;
            }
        }
        out.push(r);
    }
    out
}

/// The control points (i1, i2) around `time` (the first or last segment outside the sequence).
fn segment(n: usize, t: impl Fn(usize) -> f64, time: f64) -> (usize, usize) {
    if t(0) >= time {
        (0, 1)
    } else if t(n - 1) <= time {
        (n - 2, n - 1)
    } else {
        let mut i = 0;
        while t(i) < time {
            i += 1;
        }
        (i - 1, i)
    }
}

pub(crate) fn interpolate_cps(cps: &[Cp], time: f64, stagger: f64) -> Cp {
    assert!(!cps.is_empty(), "a sequence has at least one flame");
    if cps.len() == 1 {
        let mut one = cps[0].clone();
        // A copy keeps its padding flags only while being blended.
        for s in &mut one.slots {
            s.padding = false;
        }
        return one;
    }
    let n = cps.len();
    let t = |i: usize| cps[i].flame.anim.time;
    let (i1, i2) = segment(n, t, time);
    let c0 = (t(i2) - time) / (t(i2) - t(i1));
    let c = [c0, 1.0 - c0];
    let smooth = cps[i1].flame.anim.interpolation == Interpolation::Smooth && i1 > 0 && i2 < n - 1;
    let mut out = if smooth {
        let cpi = align(&[&cps[i1 - 1], &cps[i1], &cps[i2], &cps[i2 + 1]]);
        blend(&cpi, &catmull_rom(c[1]), 0.0)
    } else {
        let cpi = align(&[&cps[i1], &cps[i2]]);
        blend(&cpi, &c, stagger)
    };
    out.flame.anim.time = time;
    out.flame.anim.interpolation = Interpolation::Linear;
    out
}

/// Catmull-Rom weights of four control points at `t` of the middle segment.
fn catmull_rom(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        (2.0 * t2 - t - t3) / 2.0,
        (3.0 * t3 - 5.0 * t2 + 2.0) / 2.0,
        (4.0 * t2 - 3.0 * t3 + t) / 2.0,
        (t3 - t2) / 2.0,
    ]
}

#[cfg(test)]
mod tests;
