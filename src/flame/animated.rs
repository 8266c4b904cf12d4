//! Keyframes applied to a flame: what each target reads and sets in the flame model, and the
//! flame at a frame of its animation.

use crate::flame::keyframes::{
    Curve, FlameParam, Key, Keyframes, Target, VarParam, XformParam, XformRef,
};
use crate::flame::model::{Affine, Flame, Var, Xform};
use crate::flame::variations;
use crate::gradient::{hsv_to_rgb, rgb_to_hsv};

/// The field of a flame setting, borrowed as `&` or `&mut`.
macro_rules! flame_field {
    ($f:expr, $p:expr, $($m:tt)*) => {
        match $p {
            FlameParam::CenterX => & $($m)* $f.center[0],
            FlameParam::CenterY => & $($m)* $f.center[1],
            FlameParam::Zoom => & $($m)* $f.zoom,
            FlameParam::Scale => & $($m)* $f.scale,
            FlameParam::Rotate => & $($m)* $f.rotate,
            FlameParam::CamPitch => & $($m)* $f.cam.pitch,
            FlameParam::CamYaw => & $($m)* $f.cam.yaw,
            FlameParam::CamPerspective => & $($m)* $f.cam.perspective,
            FlameParam::CamZpos => & $($m)* $f.cam.zpos,
            FlameParam::CamDof => & $($m)* $f.cam.dof,
            FlameParam::CamZoom => & $($m)* $f.cam_zoom,
            FlameParam::Brightness => & $($m)* $f.brightness,
            FlameParam::Contrast => & $($m)* $f.contrast,
            FlameParam::Gamma => & $($m)* $f.gamma,
            FlameParam::GammaThreshold => & $($m)* $f.gamma_threshold,
            FlameParam::Vibrancy => & $($m)* $f.vibrancy,
            FlameParam::HighlightPower => & $($m)* $f.highlight_power,
            FlameParam::BackgroundR => & $($m)* $f.background[0],
            FlameParam::BackgroundG => & $($m)* $f.background[1],
            FlameParam::BackgroundB => & $($m)* $f.background[2],
            FlameParam::EstimatorRadius => & $($m)* $f.estimator_radius,
            FlameParam::EstimatorMinimum => & $($m)* $f.estimator_minimum,
            FlameParam::EstimatorCurve => & $($m)* $f.estimator_curve,
            FlameParam::Filter => & $($m)* $f.filter,
        }
    };
}

/// The field of an xform setting kept as a number (not the turn and scale of its maps).
macro_rules! xform_field {
    ($x:expr, $p:expr, $($m:tt)*) => {
        match $p {
            XformParam::Weight => Some(& $($m)* $x.weight),
            XformParam::Color => Some(& $($m)* $x.color),
            XformParam::ColorSpeed => Some(& $($m)* $x.color_speed),
            XformParam::Opacity => Some(& $($m)* $x.opacity),
            XformParam::MoveX => Some(& $($m)* $x.coefs.e),
            XformParam::MoveY => Some(& $($m)* $x.coefs.f),
            XformParam::PostMoveX => Some(& $($m)* $x.post.e),
            XformParam::PostMoveY => Some(& $($m)* $x.post.f),
            XformParam::Coef00 => Some(& $($m)* $x.coefs.a),
            XformParam::Coef01 => Some(& $($m)* $x.coefs.c),
            XformParam::Coef10 => Some(& $($m)* $x.coefs.b),
            XformParam::Coef11 => Some(& $($m)* $x.coefs.d),
            XformParam::PostCoef00 => Some(& $($m)* $x.post.a),
            XformParam::PostCoef01 => Some(& $($m)* $x.post.c),
            XformParam::PostCoef10 => Some(& $($m)* $x.post.b),
            XformParam::PostCoef11 => Some(& $($m)* $x.post.d),
            _ => None,
        }
    };
}

impl Target {
    /// The value this target has in `f` (with no curve applied).
    pub fn get(&self, f: &Flame) -> Option<f64> {
        Some(match *self {
            Target::Flame(p) => *flame_field!(f, p,),
            Target::Xform(r, p) => {
                let x = xform(f, r)?;
                match p {
                    XformParam::Rotate | XformParam::PostRotate => 0.0,
                    XformParam::Scale | XformParam::PostScale => 1.0,
                    _ => *xform_field!(x, p,)?,
                }
            }
            Target::Var {
                xform: r,
                var,
                form,
                param,
            } => {
                let v = xform(f, r)?
                    .vars
                    .iter()
                    .find(|v| v.id == var && v.form == form);
                match (v, param) {
                    (Some(v), VarParam::Weight) => v.weight,
                    (None, VarParam::Weight) => 0.0,
                    (Some(v), VarParam::Param(k)) => *v.params.get(k)?,
                    (None, VarParam::Param(k)) => *variations::param_defaults(var).get(k)?,
                }
            }
            Target::PaletteRotate | Target::PaletteHue => 0.0,
        })
    }

    /// Set this target in `f` to `value`. Returns false when the target does not exist in the
    /// flame (an xform index past its end).
    pub fn set(&self, f: &mut Flame, value: f64) -> bool {
        match *self {
            Target::Flame(p) => *flame_field!(f, p, mut) = value,
            Target::Xform(r, p) => {
                let Some(x) = xform_mut(f, r) else {
                    return false;
                };
                match p {
                    XformParam::Rotate => x.coefs = turn(&x.coefs, value),
                    XformParam::PostRotate => x.post = turn(&x.post, value),
                    XformParam::Scale => x.coefs = scale(&x.coefs, value),
                    XformParam::PostScale => x.post = scale(&x.post, value),
                    _ => match xform_field!(x, p, mut) {
                        Some(v) => *v = value,
                        None => return false,
                    },
                }
            }
            Target::Var {
                xform: r,
                var,
                form,
                param,
            } => {
                let Some(x) = xform_mut(f, r) else {
                    return false;
                };
                let pos = x.vars.iter().position(|v| v.id == var && v.form == form);
                let v = match pos {
                    Some(p) => &mut x.vars[p],
                    None => {
                        x.vars.push(Var::with_form(var, form, 0.0));
                        x.vars.last_mut().expect("just pushed")
                    }
                };
                match param {
                    VarParam::Weight => v.weight = value,
                    VarParam::Param(k) => match v.params.get_mut(k) {
                        Some(p) => *p = value,
                        None => return false,
                    },
                }
            }
            Target::PaletteRotate => {
                let n = f.palette.colors.len();
                if n > 0 {
                    let k = value.round().rem_euclid(n as f64) as usize;
                    f.palette.colors.rotate_right(k);
                    f.palette_hires = None;
                }
            }
            Target::PaletteHue => {
                for c in &mut f.palette.colors {
                    let mut hsv = rgb_to_hsv([c[0], c[1], c[2]]);
                    hsv[0] += value / 60.0;
                    let rgb = hsv_to_rgb(hsv);
                    c[..3].copy_from_slice(&rgb);
                }
                f.palette_hires = None;
            }
        }
        true
    }
}

fn xform(f: &Flame, r: XformRef) -> Option<&Xform> {
    match r {
        XformRef::Index(i) => f.xforms.get(i),
        XformRef::Final => f.final_xform.as_ref(),
    }
}

fn xform_mut(f: &mut Flame, r: XformRef) -> Option<&mut Xform> {
    match r {
        XformRef::Index(i) => f.xforms.get_mut(i),
        XformRef::Final => f.final_xform.as_mut(),
    }
}

/// The linear part turned by `degrees` (both columns, as flam3 turns xforms in a loop).
fn turn(m: &Affine, degrees: f64) -> Affine {
    let (s, c) = degrees.to_radians().sin_cos();
    Affine {
        a: c * m.a - s * m.c,
        c: s * m.a + c * m.c,
        b: c * m.b - s * m.d,
        d: s * m.b + c * m.d,
        ..*m
    }
}

fn scale(m: &Affine, k: f64) -> Affine {
    Affine {
        a: m.a * k,
        b: m.b * k,
        c: m.c * k,
        d: m.d * k,
        ..*m
    }
}

/// Degrees for the camera angles, which the model keeps in radians.
fn to_model_units(t: &Target, v: f64) -> f64 {
    match t {
        Target::Flame(FlameParam::CamPitch | FlameParam::CamYaw) => v.to_radians(),
        _ => v,
    }
}

fn from_model_units(t: &Target, v: f64) -> f64 {
    match t {
        Target::Flame(FlameParam::CamPitch | FlameParam::CamYaw) => v.to_degrees(),
        _ => v,
    }
}

impl Target {
    /// True for targets whose values move the base flame rather than replace one of its
    /// values: an xform's turn and scale, the palette's rotation and hue. Their curves are
    /// offsets from the base; every other curve sets its value outright.
    pub fn is_offset(&self) -> bool {
        matches!(
            self,
            Target::Xform(
                _,
                XformParam::Rotate
                    | XformParam::Scale
                    | XformParam::PostRotate
                    | XformParam::PostScale
            ) | Target::PaletteRotate
                | Target::PaletteHue
        )
    }
}

impl Keyframes {
    /// Set in `base` the values its curves have at `frame`, for every target that is not an
    /// offset ([`Target::is_offset`]): what an editor shows as the flame's values at that
    /// frame. Offsets stay with [`Keyframes::apply`], so `apply(base, frame)` is the same
    /// before and after. A variation whose weight curve passes 0 stays (weight 0) with its
    /// parameters.
    pub fn hold_at(&self, base: &mut Flame, frame: f64) {
        let wrap = self.wrap.then_some(self.frames as f64);
        for c in self.curves.iter().filter(|c| !c.target.is_offset()) {
            let Some(v) = c.eval(frame, wrap) else {
                continue;
            };
            let v = to_model_units(&c.target, v);
            c.target.set(base, v);
        }
    }

    /// Key the target's current value in `flame` at `frame` (as in most editors' "set key").
    pub fn key_current(&mut self, flame: &Flame, t: Target, frame: f64) -> Result<(), String> {
        let v = t
            .get(flame)
            .ok_or_else(|| format!("'{t}' is not in this flame"))?;
        self.curve_mut(t)
            .insert(Key::new(frame, from_model_units(&t, v)))
    }

    /// The flame at `frame` (fractional frames for motion blur): `base` with every curve's value
    /// at that frame set. Targets the flame lacks are skipped.
    pub fn apply(&self, base: &Flame, frame: f64) -> Flame {
        self.apply_where(base, frame, |_| true)
    }

    /// As [`Keyframes::apply`], playing only the curves whose target `keep` accepts.
    pub fn apply_where(&self, base: &Flame, frame: f64, keep: impl Fn(&Target) -> bool) -> Flame {
        let mut f = base.clone();
        let wrap = self.wrap.then_some(self.frames as f64);
        // Values set as they stand first (position, coefficients), then scales, then turns,
        // so a turned and scaled map is the same whatever order the curves are stored in (and
        // as JWildfire applies its curves).
        let order = |c: &&Curve| match c.target {
            Target::Xform(_, XformParam::Scale | XformParam::PostScale) => 1,
            Target::Xform(_, XformParam::Rotate | XformParam::PostRotate) => 2,
            _ => 0,
        };
        let mut curves: Vec<&Curve> = self.curves.iter().filter(|c| keep(&c.target)).collect();
        curves.sort_by_key(order);
        for c in &curves {
            if let Some(v) = c.eval(frame, wrap) {
                c.target.set(&mut f, to_model_units(&c.target, v));
            }
        }
        // A keyed variation whose weight is 0 at this frame is not rendered; dropped only
        // now, so its parameter curves are kept whatever order the curves are stored in.
        for c in &curves {
            if let Target::Var {
                xform: r,
                var,
                form,
                ..
            } = c.target
                && let Some(x) = xform_mut(&mut f, r)
            {
                x.vars
                    .retain(|v| !(v.id == var && v.form == form && v.weight == 0.0));
            }
        }
        f
    }
}

#[cfg(test)]
#[path = "keyframes_tests.rs"]
mod tests;
