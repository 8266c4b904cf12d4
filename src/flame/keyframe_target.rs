//! What a keyframe curve drives: a flame setting, an xform's setting, a variation's weight or
//! parameter, or the palette; with the names targets have in files and on the command line.

use std::fmt;

use crate::flame::variations::{self, Form, VarId};

/// Flame settings a curve can drive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FlameParam {
    /// The x of the point at the picture's centre, in world units.
    CenterX,
    /// The y of the point at the picture's centre, in world units.
    CenterY,
    /// flam3's zoom (a power of two).
    Zoom,
    /// Pixels per unit at zoom 0; interpolated as a logarithm.
    Scale,
    /// The picture's turn in degrees (positive: clockwise on screen).
    Rotate,
    /// The 3-D camera's pitch (`cam_pitch`), in degrees (the flame keeps radians).
    CamPitch,
    /// The 3-D camera's yaw (`cam_yaw`), in degrees (the flame keeps radians).
    CamYaw,
    /// The 3-D camera's perspective (`cam_perspective`): 1/distance of the eye, 0 for none.
    CamPerspective,
    /// The height of the 3-D camera's focal plane (`cam_zpos`).
    CamZpos,
    /// The 3-D camera's depth-of-field blur (`cam_dof`; 0: none).
    CamDof,
    /// JWildfire's `cam_zoom`, a further factor on the scale (1: none); interpolated as a
    /// logarithm.
    CamZoom,
    /// The tone map's brightness (flam3's `brightness`).
    Brightness,
    /// The tone map's contrast (positive; 1: none).
    Contrast,
    /// The tone map's gamma.
    Gamma,
    /// The density below which gamma is applied linearly (`gamma_threshold`).
    GammaThreshold,
    /// The mix of the two gamma rules, 0–1 (`vibrancy`).
    Vibrancy,
    /// How bright areas move towards white (`highlight_power`; negative: off).
    HighlightPower,
    /// The red of the background, 0–1.
    BackgroundR,
    /// The green of the background, 0–1.
    BackgroundG,
    /// The blue of the background, 0–1.
    BackgroundB,
    /// The largest radius of the density-estimation filter, in pixels (`estimator_radius`;
    /// 0: no density estimation).
    EstimatorRadius,
    /// The smallest radius of the density-estimation filter (`estimator_minimum`).
    EstimatorMinimum,
    /// How fast the density-estimation radius shrinks as the density grows
    /// (`estimator_curve`).
    EstimatorCurve,
    /// The radius of the spatial filter, in pixels (`filter`).
    Filter,
}

pub(crate) const FLAME_PARAMS: [(FlameParam, &str); 24] = [
    (FlameParam::CenterX, "center_x"),
    (FlameParam::CenterY, "center_y"),
    (FlameParam::Zoom, "zoom"),
    (FlameParam::Scale, "scale"),
    (FlameParam::Rotate, "rotate"),
    (FlameParam::CamPitch, "cam_pitch"),
    (FlameParam::CamYaw, "cam_yaw"),
    (FlameParam::CamPerspective, "cam_perspective"),
    (FlameParam::CamZpos, "cam_zpos"),
    (FlameParam::CamDof, "cam_dof"),
    (FlameParam::CamZoom, "cam_zoom"),
    (FlameParam::Brightness, "brightness"),
    (FlameParam::Contrast, "contrast"),
    (FlameParam::Gamma, "gamma"),
    (FlameParam::GammaThreshold, "gamma_threshold"),
    (FlameParam::Vibrancy, "vibrancy"),
    (FlameParam::HighlightPower, "highlight_power"),
    (FlameParam::BackgroundR, "background_r"),
    (FlameParam::BackgroundG, "background_g"),
    (FlameParam::BackgroundB, "background_b"),
    (FlameParam::EstimatorRadius, "estimator_radius"),
    (FlameParam::EstimatorMinimum, "estimator_minimum"),
    (FlameParam::EstimatorCurve, "estimator_curve"),
    (FlameParam::Filter, "filter"),
];

/// Xform settings a curve can drive. `Rotate` and `Scale` act on the linear part of the map
/// (or of the post map) kept in the file: it is turned by the angle (degrees) and scaled by
/// the factor; `MoveX`/`MoveY` set the translation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum XformParam {
    /// The relative probability of choosing the xform (≥ 0).
    Weight,
    /// The colour coordinate the xform moves points towards, 0–1.
    Color,
    /// How far a step moves the colour coordinate towards `color`, 0–1 (`color_speed`).
    ColorSpeed,
    /// How visible the xform's points are, 0–1.
    Opacity,
    /// The x of the map's translation (`e`; flam3's fifth `coefs` number).
    MoveX,
    /// The y of the map's translation (`f`; flam3's sixth `coefs` number).
    MoveY,
    /// The map's linear part turned by this many degrees (0: as in the file; positive turns
    /// from the x axis towards the y axis).
    Rotate,
    /// The map's linear part multiplied by this factor (1: as in the file); interpolated as
    /// a logarithm.
    Scale,
    /// The x of the post map's translation.
    PostMoveX,
    /// The y of the post map's translation.
    PostMoveY,
    /// The post map's linear part turned by this many degrees (0: as in the file).
    PostRotate,
    /// The post map's linear part multiplied by this factor (1: as in the file);
    /// interpolated as a logarithm.
    PostScale,
    /// The map's coefficient of x in x′, the first of flam3's `coefs` (the coefficients are
    /// set as they stand, as JWildfire's curves set them).
    Coef00,
    /// The map's coefficient of x in y′, the second of flam3's `coefs`.
    Coef01,
    /// The map's coefficient of y in x′, the third of flam3's `coefs`.
    Coef10,
    /// The map's coefficient of y in y′, the fourth of flam3's `coefs`.
    Coef11,
    /// The post map's coefficient of x in x′ (the first of flam3's `post`).
    PostCoef00,
    /// The post map's coefficient of x in y′ (the second of flam3's `post`).
    PostCoef01,
    /// The post map's coefficient of y in x′ (the third of flam3's `post`).
    PostCoef10,
    /// The post map's coefficient of y in y′ (the fourth of flam3's `post`).
    PostCoef11,
}

pub(crate) const XFORM_PARAMS: [(XformParam, &str); 20] = [
    (XformParam::Weight, "weight"),
    (XformParam::Color, "color"),
    (XformParam::ColorSpeed, "color_speed"),
    (XformParam::Opacity, "opacity"),
    (XformParam::MoveX, "move_x"),
    (XformParam::MoveY, "move_y"),
    (XformParam::Rotate, "rotate"),
    (XformParam::Scale, "scale"),
    (XformParam::PostMoveX, "post_move_x"),
    (XformParam::PostMoveY, "post_move_y"),
    (XformParam::PostRotate, "post_rotate"),
    (XformParam::PostScale, "post_scale"),
    (XformParam::Coef00, "coef_00"),
    (XformParam::Coef01, "coef_01"),
    (XformParam::Coef10, "coef_10"),
    (XformParam::Coef11, "coef_11"),
    (XformParam::PostCoef00, "post_coef_00"),
    (XformParam::PostCoef01, "post_coef_01"),
    (XformParam::PostCoef10, "post_coef_10"),
    (XformParam::PostCoef11, "post_coef_11"),
];

/// Which xform: a standard one by index, or the final one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum XformRef {
    /// The standard xform at this index (0-based, in the flame's order).
    Index(usize),
    /// The final xform.
    Final,
}

/// A variation's weight, or its k-th parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarParam {
    /// The variation's weight; 0 takes it out of the xform at that frame.
    Weight,
    /// The parameter at this index of the variation's parameter list (0-based, in the order
    /// of its table entry and of its attributes in flame XML).
    Param(usize),
}

/// What a curve drives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// A setting of the flame.
    Flame(FlameParam),
    /// A setting of an xform (skipped at frames of a flame that lacks the xform).
    Xform(XformRef, XformParam),
    /// A variation of an xform: its weight (a variation the xform lacks is added, with its
    /// default parameters) or one of its parameters.
    Var {
        /// The xform holding the variation.
        xform: XformRef,
        /// The variation.
        var: VarId,
        /// Which of its forms (regular, `pre_` or `post_`): an xform may hold each.
        form: Form,
        /// The weight or a parameter.
        param: VarParam,
    },
    /// The palette turned by this many entries (of 256; rounded to whole entries, positive
    /// moves each colour to a higher index).
    PaletteRotate,
    /// The palette's hue turned by this many degrees.
    PaletteHue,
}

impl Target {
    /// Values that interpolate as logarithms (scale factors): a zoom from 1 to 4 passes 2 at
    /// the middle.
    pub fn is_logarithmic(&self) -> bool {
        matches!(
            self,
            Target::Xform(_, XformParam::Scale | XformParam::PostScale)
                | Target::Flame(FlameParam::Scale | FlameParam::CamZoom)
        )
    }
}

impl fmt::Display for Target {
    /// The target's name in files: `zoom`, `xform 2 rotate`, `final weight`,
    /// `xform 0 var julian weight`, `xform 0 var pre_blur pre_blur` … `palette rotate`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let xf = |r: &XformRef| match r {
            XformRef::Index(i) => format!("xform {i}"),
            XformRef::Final => "final".to_string(),
        };
        match self {
            Target::Flame(p) => {
                let name = FLAME_PARAMS.iter().find(|(q, _)| q == p).map(|(_, n)| *n);
                write!(f, "{}", name.unwrap_or("?"))
            }
            Target::Xform(r, p) => {
                let name = XFORM_PARAMS.iter().find(|(q, _)| q == p).map(|(_, n)| *n);
                write!(f, "{} {}", xf(r), name.unwrap_or("?"))
            }
            Target::Var {
                xform: r,
                var,
                form,
                param,
            } => {
                let p = match param {
                    VarParam::Weight => "weight".to_string(),
                    VarParam::Param(k) => variations::param_attr_name(*var, *form, *k),
                };
                write!(
                    f,
                    "{} var {} {}",
                    xf(r),
                    variations::attr_name(*var, *form),
                    p
                )
            }
            Target::PaletteRotate => write!(f, "palette rotate"),
            Target::PaletteHue => write!(f, "palette hue"),
        }
    }
}

impl std::str::FromStr for Target {
    type Err = String;
    fn from_str(s: &str) -> Result<Target, String> {
        let words: Vec<&str> = s.split_whitespace().collect();
        let bad = || format!("'{s}' is not a keyframe target");
        match words.as_slice() {
            ["palette", "rotate"] => return Ok(Target::PaletteRotate),
            ["palette", "hue"] => return Ok(Target::PaletteHue),
            [name] => {
                return FLAME_PARAMS
                    .iter()
                    .find(|(_, n)| n == name)
                    .map(|(p, _)| Target::Flame(*p))
                    .ok_or_else(bad);
            }
            _ => {}
        }
        let (r, rest) = match words.as_slice() {
            ["xform", i, rest @ ..] => (XformRef::Index(i.parse().map_err(|_| bad())?), rest),
            ["final", rest @ ..] => (XformRef::Final, rest),
            _ => return Err(bad()),
        };
        match rest {
            [name] => XFORM_PARAMS
                .iter()
                .find(|(_, n)| n == name)
                .map(|(p, _)| Target::Xform(r, *p))
                .ok_or_else(bad),
            ["var", attr, param] => {
                let (var, form) = variations::parse_name(attr)
                    .ok_or_else(|| format!("'{s}': '{attr}' is not a variation ugnis knows"))?;
                let param = if *param == "weight" {
                    VarParam::Weight
                } else {
                    let k = (0..variations::info(var).params.len())
                        .find(|&k| variations::param_attr_name(var, form, k) == *param)
                        .ok_or_else(|| format!("'{s}': {attr} has no parameter '{param}'"))?;
                    VarParam::Param(k)
                };
                Ok(Target::Var {
                    xform: r,
                    var,
                    form,
                    param,
                })
            }
            _ => Err(bad()),
        }
    }
}
