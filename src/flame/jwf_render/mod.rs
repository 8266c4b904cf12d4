//! JWildfire's renderer, for the flames JWildfire wrote: its picture settings that flam3 lacks
//! ([`JwfLook`]), its spatial filter kernels ([`kernel`]), and its development of the histogram
//! into an image ([`develop`]): per-bucket log scaling with its low-density brightness, a
//! radial 2-D filter over the scaled buckets (sharpening kernels take the colour through the
//! kernel and the density through a small Gaussian), and its tone map (white level, gamma
//! threshold, vibrancy, colour balance, saturation, foreground opacity, gradient backgrounds);
//! the plot of points that carry a colour of their own ([`own_colour`]), and its colour type
//! DISTANCE ([`colour_type`]); the affine maps of the yz and zx planes a JWildfire xform may
//! carry ([`planes`]).
//!
//! Which renderer draws a flame follows the program that wrote it, as the palette rule does
//! ([`crate::flame::PaletteIndex::JWildfire`]). The facts come from JWildfire 9.00's
//! `FlameRenderer`, `LogDensityFilter`, `LogScaleCalculator`, `GammaCorrectionFilter`,
//! `FilterHolder` and its filter kernels.

pub(crate) mod colour_type;
pub(crate) mod develop;
pub mod kernel;
pub(crate) mod own_colour;
pub mod planes;
pub mod solid;
pub(crate) mod solid_draw;

pub(crate) use develop::JwfRaster;
pub use kernel::JwfKernel;
pub use solid::{JwfLight, JwfLightDiff, JwfMaterial, JwfSolid};

/// How JWildfire fills the background (`background_type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum JwfBackgroundKind {
    /// One colour (the flame's `background`; JWildfire's choice for files that name no kind).
    #[default]
    SingleColor,
    /// A bilinear blend of four corner colours.
    Gradient2x2,
    /// Four bilinear quarters meeting in a centre colour.
    Gradient2x2C,
}

impl JwfBackgroundKind {
    /// Every kind, in JWildfire's order.
    pub const ALL: [JwfBackgroundKind; 3] = [
        JwfBackgroundKind::SingleColor,
        JwfBackgroundKind::Gradient2x2,
        JwfBackgroundKind::Gradient2x2C,
    ];

    /// The name JWildfire writes.
    pub fn name(self) -> &'static str {
        match self {
            JwfBackgroundKind::SingleColor => "SINGLE_COLOR",
            JwfBackgroundKind::Gradient2x2 => "GRADIENT_2X2",
            JwfBackgroundKind::Gradient2x2C => "GRADIENT_2X2_C",
        }
    }

    /// The kind JWildfire names `s`.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == s)
    }
}

/// JWildfire's gradient background: corner colours and a centre colour (RGB, 0–1).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct JwfBackground {
    /// How the colours fill the picture.
    pub kind: JwfBackgroundKind,
    /// Upper left corner.
    pub ul: [f64; 3],
    /// Upper right corner.
    pub ur: [f64; 3],
    /// Lower left corner.
    pub ll: [f64; 3],
    /// Lower right corner.
    pub lr: [f64; 3],
    /// Centre (of the four-quarter gradient).
    pub cc: [f64; 3],
}

/// JWildfire's picture settings that flam3's flames do not have, with JWildfire's defaults.
/// They take effect for flames JWildfire wrote; the others keep flam3's renderer.
#[derive(Clone, Debug, PartialEq)]
pub struct JwfLook {
    /// The density a palette colour reaches full brightness at (`white_level`; 200 keeps the
    /// palette's own brightness, more darkens).
    pub white_level: f64,
    /// Brightness added where few samples fell (`low_density_brightness`).
    pub low_density_brightness: f64,
    /// Factors on red, green and blue before the tone map (`balancing_red` …).
    pub balance: [f64; 3],
    /// Saturation of the final colours (`saturation`; 1: unchanged).
    pub saturation: f64,
    /// How opaque the flame is over the background (`fg_opacity`; 1: as the density says).
    pub foreground_opacity: f64,
    /// Share of the samples moved by a random offset (`antialias_amount`).
    pub antialias_amount: f64,
    /// Spread of that offset (`antialias_radius`).
    pub antialias_radius: f64,
    /// The spatial filter's kernel (`filter_kernel`; its radius is the flame's `filter`).
    pub kernel: JwfKernel,
    /// The background.
    pub background: JwfBackground,
    /// The camera's bank, radians (`cam_roll`): a turn about the viewing axis before pitch and
    /// yaw.
    pub bank: f64,
    /// Factor on the depth of field's blur (`cam_dof_scale`).
    pub dof_scale: f64,
    /// The frame of JWildfire's motion curves the picture shows (`frame`, counted from 1).
    pub frame: f64,
    /// Further flames at earlier and later times drawn into the picture (`motion_blur_length`;
    /// 0: none).
    pub motion_blur_length: u32,
    /// Frames between those flames (`motion_blur_timestep`).
    pub motion_blur_timestep: f64,
    /// How fast their colours fade with their distance in time (`motion_blur_decay`).
    pub motion_blur_decay: f64,
    /// Solid rendering (`sld_render_*`).
    pub solid: JwfSolid,
}

impl Default for JwfLook {
    fn default() -> Self {
        JwfLook {
            white_level: 220.0,
            low_density_brightness: 0.24,
            balance: [1.0; 3],
            saturation: 1.0,
            foreground_opacity: 1.0,
            antialias_amount: 0.25,
            antialias_radius: 0.5,
            kernel: JwfKernel::MitchellSmooth,
            background: JwfBackground::default(),
            bank: 0.0,
            dof_scale: 1.0,
            frame: 1.0,
            motion_blur_length: 0,
            motion_blur_timestep: 0.05,
            motion_blur_decay: 0.03,
            solid: JwfSolid::default(),
        }
    }
}

impl crate::flame::model::Flame {
    /// The flame as JWildfire shows it: for a flame JWildfire's renderer draws, its keyframes
    /// (JWildfire's motion curves) played at the frame it shows ([`JwfLook::frame`]); any other
    /// flame as it stands. (With motion blur the renderer plays them at each of its times.)
    pub fn at_jwildfire_frame(&self) -> crate::flame::model::Flame {
        let blurred = self.jwildfire_motion_blur().len() > 1;
        if self.renders_as_jwildfire() && !self.keys.is_empty() && !blurred {
            self.at_jwildfire_time(self.jwf.frame)
        } else {
            self.clone()
        }
    }

    /// The flame JWildfire's final render draws at `time` (counted from 1): its motion curves
    /// played twice. JWildfire's render command (and its batch and command-line renders)
    /// plays the curves at the frame shown on a copy of the flame that keeps its curves, and
    /// its renderer plays them again, at that frame and at each time of the motion blur. A
    /// curve that sets a value (a coefficient, a weight, a variation's parameter) ends at its
    /// value at `time`; a turn or a scale of an affine map turns or scales the map it finds,
    /// so the map ends turned by the curve's value at the frame shown plus its value at
    /// `time` (unless a coefficient curve reset the map in between). Only the maps' curves
    /// are played the first time: every other curve sets its value, which the second time
    /// sets anew (JWildfire's palette shift too, which ugnis' palette turn would add up).
    pub fn at_jwildfire_time(&self, time: f64) -> crate::flame::model::Flame {
        use crate::flame::keyframes::Target;
        let once = self.keys.apply_where(self, self.jwf.frame - 1.0, |t| {
            matches!(t, Target::Xform(..))
        });
        self.keys.apply(&once, time - 1.0)
    }

    /// JWildfire's motion blur: the times of the flames drawn for the frame shown (from 1),
    /// with the factors on their colours. The frame itself comes first; without motion blur it
    /// is the only one.
    pub fn jwildfire_motion_blur(&self) -> Vec<(f64, f64)> {
        let l = &self.jwf;
        let n = l.motion_blur_length;
        if !self.renders_as_jwildfire() || n == 0 {
            return vec![(l.frame, 1.0)];
        }
        let half = n as f64 * l.motion_blur_timestep / 2.0;
        let mut out = vec![(l.frame, 1.0)];
        for p in 1..=n {
            let p = p as f64;
            let fade = 1.0 - p * p * l.motion_blur_decay * 0.07 / n as f64;
            out.push((l.frame + half - p * l.motion_blur_timestep, fade.max(0.01)));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use crate::flame::PaletteIndex;
    use crate::flame::jwf_curve::JwfInterp;
    use crate::flame::keyframes::{CurveStyle, Key, Target, XformParam, XformRef};
    use crate::flame::model::{Affine, Flame, Xform};

    /// A JWildfire flame of one map, shown at frame 31, whose turn runs linearly from 0° at
    /// frame 1 to 100° at frame 101 (so its value at frame t is t − 1), whose x move runs
    /// from 0 to 1 over the same frames, and whose palette is shifted by 3 entries.
    fn turning() -> Flame {
        let mut f = Flame {
            xforms: vec![Xform::linear(
                Affine::new(0.5, 0.1, -0.2, 0.7, 0.3, 0.0),
                1.0,
                0.0,
            )],
            palette_index: PaletteIndex::JWildfire,
            ..Flame::default()
        };
        f.jwf.frame = 31.0;
        let linear = |f: &mut Flame, t: Target, keys: [(f64, f64); 2]| {
            let c = f.keys.curve_mut(t);
            c.set_style(CurveStyle::JWildfire(JwfInterp::Linear))
                .unwrap();
            for (frame, value) in keys {
                c.insert(Key::new(frame, value)).unwrap();
            }
        };
        let rotate = Target::Xform(XformRef::Index(0), XformParam::Rotate);
        linear(&mut f, rotate, [(0.0, 0.0), (100.0, 100.0)]);
        let move_x = Target::Xform(XformRef::Index(0), XformParam::MoveX);
        linear(&mut f, move_x, [(0.0, 0.0), (100.0, 1.0)]);
        linear(&mut f, Target::PaletteRotate, [(0.0, 3.0), (100.0, 3.0)]);
        f
    }

    /// JWildfire's final render plays the curves at the frame shown and again at the time
    /// drawn: a turn adds up, a set value and the palette shift do not.
    #[test]
    fn a_turn_curve_counts_the_frame_shown_and_the_time_drawn() {
        let f = turning();
        let base = f.xforms[0].coefs;
        for (time, turn) in [(31.0, 60.0), (21.0, 50.0), (31.5, 60.5)] {
            let g = f.at_jwildfire_time(time);
            let m = g.xforms[0].coefs;
            let (s, c) = f64::to_radians(turn).sin_cos();
            let want = [
                c * base.a - s * base.c,
                c * base.b - s * base.d,
                s * base.a + c * base.c,
                s * base.b + c * base.d,
            ];
            for (got, want) in [m.a, m.b, m.c, m.d].into_iter().zip(want) {
                assert!((got - want).abs() < 1e-12, "{time}: {m:?}");
            }
            assert!((m.e - (time - 1.0) / 100.0).abs() < 1e-12, "{time}: {m:?}");
            assert_eq!(m.f, base.f);
            let mut shifted = f.palette.colors.clone();
            shifted.rotate_right(3);
            assert_ne!(shifted, f.palette.colors, "the palette shift shows");
            assert_eq!(g.palette.colors, shifted, "{time}");
        }
        // Without motion blur the picture shows the flame at the frame shown.
        assert_eq!(f.at_jwildfire_frame(), f.at_jwildfire_time(31.0));
    }
}
