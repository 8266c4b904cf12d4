//! Keyframe animation: any numeric setting of a flame can follow a curve of keys over the
//! frames of an animation. A key holds a value at a frame and how the curve leaves it: linear,
//! smooth (Catmull-Rom through the neighbouring keys), Bézier (with handles, as in most
//! animation programs) or a step, each with optional easing. A timeline can wrap, so that the
//! frame after the last equals the first (a seamless loop).
//!
//! Targets address what a curve drives: flame settings (camera, 3-D camera, tone), an xform's
//! weight, colour, opacity, its position, and its rotation and scale in flam3's log-polar form
//! (the linear part turned by an angle and scaled by a factor, interpolated as angle and
//! logarithm), a variation's weight or any of its parameters, and the palette's rotation and hue.

use crate::flame::jwf_curve::{self, JwfInterp};
#[cfg(feature = "gui")]
pub(crate) use crate::flame::keyframe_target::{FLAME_PARAMS, XFORM_PARAMS};
pub use crate::flame::keyframe_target::{FlameParam, Target, VarParam, XformParam, XformRef};

/// How the curve runs from a key to the next.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Interp {
    /// A straight line to the next key's value.
    Linear,
    /// Catmull-Rom through the keys before and after (tangents from the neighbours).
    #[default]
    Smooth,
    /// A cubic Bézier whose inner control points are the key's out handle and the next key's in
    /// handle.
    Bezier,
    /// The key's value until the next key.
    Step,
}

impl Interp {
    /// Every interpolation, in declaration order (what [`Interp::from_name`] searches).
    pub const ALL: [Interp; 4] = [Interp::Linear, Interp::Smooth, Interp::Bezier, Interp::Step];
    /// The name in files (`<key interp="…">`).
    pub fn name(self) -> &'static str {
        match self {
            Interp::Linear => "linear",
            Interp::Smooth => "smooth",
            Interp::Bezier => "bezier",
            Interp::Step => "step",
        }
    }
    /// The interpolation named `s` (the inverse of [`Interp::name`]); `None` for another word.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|i| i.name() == s)
    }
}

/// Easing of the segment after a key: how the time between two keys is spent.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Ease {
    /// The time runs evenly (u).
    #[default]
    None,
    /// Slow start (u²).
    In,
    /// Slow end (1 − (1 − u)²).
    Out,
    /// Slow start and end (3u² − 2u³).
    InOut,
}

impl Ease {
    /// Every easing, in declaration order (what [`Ease::from_name`] searches).
    pub const ALL: [Ease; 4] = [Ease::None, Ease::In, Ease::Out, Ease::InOut];
    /// The name in files (`<key ease="…">`).
    pub fn name(self) -> &'static str {
        match self {
            Ease::None => "none",
            Ease::In => "in",
            Ease::Out => "out",
            Ease::InOut => "in_out",
        }
    }
    /// The easing named `s` (the inverse of [`Ease::name`]); `None` for another word.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|e| e.name() == s)
    }
    /// The eased fraction of a segment: `u` ∈ [0, 1] (the share of its frames gone) mapped
    /// into [0, 1], 0 and 1 kept.
    pub fn apply(self, u: f64) -> f64 {
        match self {
            Ease::None => u,
            Ease::In => u * u,
            Ease::Out => 1.0 - (1.0 - u) * (1.0 - u),
            Ease::InOut => u * u * (3.0 - 2.0 * u),
        }
    }
}

/// A value at a frame, and how the curve leaves it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Key {
    /// The frame the key sits at (0 is the first frame; fractions allowed; finite).
    pub frame: f64,
    /// The target's value at that frame, in the target's units (degrees for angles; positive
    /// for the scale factors of a curve of [`CurveStyle::Keys`]).
    pub value: f64,
    /// How the curve runs from this key to the next (default smooth).
    pub interp: Interp,
    /// The easing of the segment after this key (default none).
    pub ease: Ease,
    /// Bézier handles as (frames, value) offsets from the key: the one before it and the one
    /// after it. `None`: flat handles a third of the way to the neighbouring keys.
    pub handles: Option<[[f64; 2]; 2]>,
}

impl Key {
    /// A key of `value` at `frame` leaving it the default way: smooth, without easing, with
    /// automatic handles.
    pub fn new(frame: f64, value: f64) -> Key {
        Key {
            frame,
            value,
            interp: Interp::default(),
            ease: Ease::None,
            handles: None,
        }
    }
}

/// Most keys on one curve (a file that says more is refused).
pub const MAX_KEYS: usize = 100_000;
/// Most curves on one flame (a file that says more is refused).
pub const MAX_CURVES: usize = 10_000;
/// Most frames of a timeline.
pub const MAX_FRAMES: u32 = 10_000_000;

/// How a curve runs through its keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CurveStyle {
    /// Each key says how the curve leaves it (its [`Interp`] and [`Ease`]).
    #[default]
    Keys,
    /// A JWildfire motion curve: the whole curve is one spline, Bézier or polyline through the
    /// keys, evaluated as JWildfire evaluates it (the keys' own interpolation and easing are
    /// not used, values are not taken as logarithms). JWildfire numbers frames from 1: a key at
    /// frame k is JWildfire's frame k + 1.
    JWildfire(JwfInterp),
}

/// A curve of keys driving one target. Keys are kept sorted by frame, one per frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    /// What the curve drives.
    pub target: Target,
    keys: Vec<Key>,
    style: CurveStyle,
}

impl Curve {
    /// An empty curve for `target` whose keys say how it runs ([`CurveStyle::Keys`]).
    pub fn new(target: Target) -> Curve {
        Curve {
            target,
            keys: Vec::new(),
            style: CurveStyle::Keys,
        }
    }

    /// An empty curve of the given style.
    pub fn with_style(target: Target, style: CurveStyle) -> Curve {
        Curve {
            style,
            ..Curve::new(target)
        }
    }

    /// The keys, sorted by frame, one per frame.
    pub fn keys(&self) -> &[Key] {
        &self.keys
    }

    /// How the curve runs through its keys.
    pub fn style(&self) -> CurveStyle {
        self.style
    }

    /// Change how the curve runs through its keys (the keys stay). A scale factor's keys
    /// must be positive to be interpolated as logarithms ([`CurveStyle::Keys`]).
    pub fn set_style(&mut self, style: CurveStyle) -> Result<(), String> {
        if style == CurveStyle::Keys
            && self.target.is_logarithmic()
            && let Some(k) = self.keys.iter().find(|k| k.value <= 0.0)
        {
            return Err(format!(
                "'{}' is a scale factor: its keys must be positive, not {}",
                self.target, k.value
            ));
        }
        self.style = style;
        Ok(())
    }

    /// Add a key (replacing one at the same frame). Keys at frames that are not finite, or
    /// with values that are not, are refused.
    pub fn insert(&mut self, key: Key) -> Result<(), String> {
        if !key.frame.is_finite() || !key.value.is_finite() {
            return Err(format!(
                "a key needs a finite frame and value, not {} = {}",
                key.frame, key.value
            ));
        }
        if self.target.is_logarithmic() && self.style == CurveStyle::Keys && key.value <= 0.0 {
            return Err(format!(
                "'{}' is a scale factor: its keys must be positive, not {}",
                self.target, key.value
            ));
        }
        match self
            .keys
            .binary_search_by(|k| k.frame.total_cmp(&key.frame))
        {
            Ok(i) => self.keys[i] = key,
            Err(i) => {
                if self.keys.len() >= MAX_KEYS {
                    return Err(format!("a curve holds at most {MAX_KEYS} keys"));
                }
                self.keys.insert(i, key)
            }
        }
        Ok(())
    }

    /// Remove the key at index `i` (if any).
    pub fn remove(&mut self, i: usize) -> Option<Key> {
        (i < self.keys.len()).then(|| self.keys.remove(i))
    }

    /// Move key `i` to another frame and value; returns its new index. A key already at
    /// that frame is replaced; on an error (no key `i`, a value [`Curve::insert`] refuses) the
    /// curve is unchanged.
    pub fn move_key(&mut self, i: usize, frame: f64, value: f64) -> Result<usize, String> {
        let mut k = *self.keys.get(i).ok_or("no such key")?;
        k.frame = frame;
        k.value = value;
        let old = self.keys.remove(i);
        if let Err(e) = self.insert(k) {
            self.keys.insert(i, old);
            return Err(e);
        }
        Ok(self
            .keys
            .binary_search_by(|q| q.frame.total_cmp(&frame))
            .unwrap_or(0))
    }

    /// The curve's value at `frame`. With `wrap` = Some(n), the timeline is a loop of n frames:
    /// keys repeat every n frames, so the curve after the last key runs into the first.
    /// Before the first key and after the last the value holds. None without keys.
    pub fn eval(&self, frame: f64, wrap: Option<f64>) -> Option<f64> {
        if let CurveStyle::JWildfire(interp) = self.style {
            let t = match wrap {
                Some(len) if len > 0.0 => frame.rem_euclid(len),
                _ => frame,
            };
            let x: Vec<f64> = self.keys.iter().map(|k| k.frame + 1.0).collect();
            let y: Vec<f64> = self.keys.iter().map(|k| k.value).collect();
            return jwf_curve::eval(&x, &y, interp, t + 1.0);
        }
        let log = self.target.is_logarithmic();
        let to = |v: f64| if log { v.ln() } else { v };
        let from = |v: f64| if log { v.exp() } else { v };
        let keys = &self.keys;
        let (first, last) = (keys.first()?, keys.last()?);
        if keys.len() == 1 {
            return Some(first.value);
        }
        // The key sequence the segment is taken from, with the neighbours Catmull-Rom needs.
        let key = |i: isize| -> Key {
            let n = keys.len() as isize;
            match wrap {
                Some(len) => {
                    let k = i.rem_euclid(n) as usize;
                    let turns = i.div_euclid(n) as f64;
                    Key {
                        frame: keys[k].frame + turns * len,
                        ..keys[k]
                    }
                }
                None => keys[i.clamp(0, n - 1) as usize],
            }
        };
        let t = match wrap {
            Some(len) if len > 0.0 => {
                // Bring the frame into [first, first + len).
                first.frame + (frame - first.frame).rem_euclid(len)
            }
            _ => {
                if frame <= first.frame {
                    return Some(first.value);
                }
                if frame >= last.frame {
                    return Some(last.value);
                }
                frame
            }
        };
        // The segment [i, i + 1] holding t.
        let mut i = keys.partition_point(|k| k.frame <= t) as isize - 1;
        if i < 0 {
            i = 0;
        }
        let (k0, k1) = (key(i), key(i + 1));
        let span = k1.frame - k0.frame;
        if span <= 0.0 {
            return Some(k0.value);
        }
        let u = k0.ease.apply(((t - k0.frame) / span).clamp(0.0, 1.0));
        let (v0, v1) = (to(k0.value), to(k1.value));
        let v = match k0.interp {
            Interp::Step => v0,
            Interp::Linear => v0 + (v1 - v0) * u,
            Interp::Smooth => {
                let (km, k2) = (key(i - 1), key(i + 2));
                // Tangents from the neighbours (finite differences over uneven spacing);
                // an end key without a neighbour gets the segment's slope.
                let slope = |a: &Key, b: &Key| {
                    if b.frame > a.frame {
                        (to(b.value) - to(a.value)) / (b.frame - a.frame)
                    } else {
                        (v1 - v0) / span
                    }
                };
                let m0 = slope(&km, &k1) * span;
                let m1 = slope(&k0, &k2) * span;
                hermite(v0, m0, v1, m1, u)
            }
            Interp::Bezier => {
                let out = k0.handles.map_or([span / 3.0, 0.0], |h| h[1]);
                let inn = k1.handles.map_or([-span / 3.0, 0.0], |h| h[0]);
                let p = [
                    [k0.frame, v0],
                    [k0.frame + out[0].clamp(0.0, span), v0 + out[1]],
                    [k1.frame + inn[0].clamp(-span, 0.0), v1 + inn[1]],
                    [k1.frame, v1],
                ];
                // The eased frame within the segment, then the curve's value there.
                bezier_at(&p, k0.frame + u * span)
            }
        };
        Some(from(v))
    }
}

/// The cubic Hermite spline from (0, v0) with slope m0 to (1, v1) with slope m1, at u.
fn hermite(v0: f64, m0: f64, v1: f64, m1: f64, u: f64) -> f64 {
    let (u2, u3) = (u * u, u * u * u);
    (2.0 * u3 - 3.0 * u2 + 1.0) * v0
        + (u3 - 2.0 * u2 + u) * m0
        + (-2.0 * u3 + 3.0 * u2) * v1
        + (u3 - u2) * m1
}

/// The value of a cubic Bézier in (frame, value) at frame `x` (its frames increase along the
/// curve, so the parameter is found by bisection).
fn bezier_at(p: &[[f64; 2]; 4], x: f64) -> f64 {
    let at = |s: f64, c: usize| {
        let r = 1.0 - s;
        r * r * r * p[0][c]
            + 3.0 * r * r * s * p[1][c]
            + 3.0 * r * s * s * p[2][c]
            + s * s * s * p[3][c]
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if at(mid, 0) < x {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    at(0.5 * (lo + hi), 1)
}

/// A flame's keyframe animation: the timeline and the curves.
#[derive(Clone, Debug, PartialEq)]
pub struct Keyframes {
    /// Frames of the animation (frames 0 … frames − 1).
    pub frames: u32,
    /// Frames per second of the video.
    pub fps: f64,
    /// A seamless loop: frame `frames` equals frame 0 (Chaotica's "wrap").
    pub wrap: bool,
    /// The curves, one per target as [`Keyframes::curve_mut`] makes them. [`Keyframes::apply`]
    /// sets values first, then scales, then turns, each group in this order.
    pub curves: Vec<Curve>,
}

impl Default for Keyframes {
    fn default() -> Self {
        Keyframes {
            frames: 100,
            fps: 25.0,
            wrap: false,
            curves: Vec::new(),
        }
    }
}

impl Keyframes {
    /// True when no curve has a key: nothing moves.
    pub fn is_empty(&self) -> bool {
        self.curves.iter().all(|c| c.keys.is_empty())
    }

    /// The curve of a target, if any.
    pub fn curve(&self, t: &Target) -> Option<&Curve> {
        self.curves.iter().find(|c| c.target == *t)
    }

    /// The curve of a target, made when missing.
    pub fn curve_mut(&mut self, t: Target) -> &mut Curve {
        match self.curves.iter().position(|c| c.target == t) {
            Some(i) => &mut self.curves[i],
            None => {
                self.curves.push(Curve::new(t));
                self.curves.last_mut().expect("just pushed")
            }
        }
    }
}
