//! The 3-D camera of a flame: points turned by the camera's yaw and pitch, seen in
//! perspective, and blurred by depth of field.

use crate::flame::model::{Flame, PaletteIndex};

/// Pixels Fractorium's histogram reaches beyond each side of the image.
const FRACTORIUM_GUTTER: f64 = 10.0;
use crate::flame::rng::FastRng;
use crate::flame::variations;

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
    /// Half the image size in world units, with Fractorium's gutter for its flames (the blur
    /// curve is relative to it).
    half: [f64; 2],
    /// JWildfire's camera (for the flames it draws): z is not moved by the focal plane, the
    /// turn includes the bank (`cam_roll`), a point with 1 − p·z′ below ε is dropped, and depth
    /// of field blurs only the points in front of the focal plane, by its distance times
    /// `cam_dof_scale`.
    jwildfire: bool,
    dof_scale: f64,
}

impl Projection {
    /// The projection of `flame`'s camera, or `None` for the flat view.
    pub fn of(flame: &Flame) -> Option<Projection> {
        if flame.renders_as_jwildfire() {
            return Self::jwildfire(flame);
        }
        let c = &flame.cam;
        if c.is_flat() {
            return None;
        }
        let (sp, cp) = c.pitch.sin_cos();
        let (sy, cy) = (-c.yaw).sin_cos();
        let ppu = flame.ppu();
        // Fractorium measures the blur curve's distance against half its histogram, which is
        // the image with a gutter of 10 pixels on each side (Fractorium 1.0.0.19,
        // `Renderer::ComputeBounds` and `ComputeCamera`; `Ember::ProjectPitchYawDepthBlur`
        // divides by `CarToRas::CachedCarHalfX`).
        let gutter = if flame.palette_index == PaletteIndex::Fractorium {
            FRACTORIUM_GUTTER
        } else {
            0.0
        };
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
                (flame.width as f64 / 2.0 + gutter) / ppu,
                (flame.height as f64 / 2.0 + gutter) / ppu,
            ],
            jwildfire: false,
            dof_scale: 1.0,
        })
    }

    /// Whether JWildfire projects `flame`'s points in 3-D (a turn, a bank, perspective or
    /// depth of field; the focal plane alone does not).
    pub fn is_jwildfire_3d(flame: &Flame) -> bool {
        let c = &flame.cam;
        [c.pitch, c.yaw, flame.jwf.bank, c.perspective, c.dof]
            .iter()
            .any(|v| v.abs() > 1e-6)
    }

    /// JWildfire's camera: the turn by yaw, pitch and bank (the picture's rotation is applied
    /// afterwards, about the origin: see [`crate::flame::geometry::Geometry`]).
    fn jwildfire(flame: &Flame) -> Option<Projection> {
        if !Self::is_jwildfire_3d(flame) {
            return None;
        }
        let c = &flame.cam;
        let (sy, cy) = (-c.yaw).sin_cos();
        let (sp, cp) = c.pitch.sin_cos();
        let (sb, cb) = flame.jwf.bank.sin_cos();
        Some(Projection {
            // JWildfire's matrix at roll 0, rows giving x′, y′, z′.
            m: [
                [cb * cy, -cb * sy, sb],
                [cp * sy + sp * sb * cy, cp * cy - sp * sb * sy, -cb * sp],
                [sp * sy - cp * sb * cy, sp * cy + cp * sb * sy, cp * cb],
            ],
            perspective: c.perspective,
            zpos: c.zpos,
            blur: 0.1 * c.dof,
            blur_curve: 0.0,
            half: [1.0, 1.0],
            jwildfire: true,
            dof_scale: flame.jwf.dof_scale,
        })
    }

    /// [`Projection::project`] by JWildfire's rules.
    #[inline(always)]
    fn project_jwildfire(&self, x: f64, y: f64, z: f64, rng: &mut FastRng) -> (f64, f64) {
        let m = &self.m;
        let px = m[0][0] * x + m[0][1] * y + m[0][2] * z;
        let py = m[1][0] * x + m[1][1] * y + m[1][2] * z;
        let pz = m[2][0] * x + m[2][1] * y + m[2][2] * z;
        let zr = 1.0 - self.perspective * pz;
        if zr < 1e-6 {
            return (f64::NAN, f64::NAN);
        }
        let zdist = self.zpos - pz;
        if self.blur == 0.0 || zdist <= 0.0 {
            return (px / zr, py / zr);
        }
        let dr = rng.f01() * self.blur * zdist * self.dof_scale;
        let (s, c) = (rng.f01() * std::f64::consts::TAU).sin_cos();
        ((px + dr * c) / zr, (py + dr * s) / zr)
    }

    /// The depth of a point seen by the camera (larger: nearer), before perspective.
    #[inline(always)]
    pub fn depth(&self, x: f64, y: f64, z: f64) -> f64 {
        let m = &self.m;
        let z = if self.jwildfire { z } else { z - self.zpos };
        m[2][0] * x + m[2][1] * y + m[2][2] * z
    }

    /// The plotted position of a point.
    #[inline(always)]
    pub fn project(&self, x: f64, y: f64, z: f64, rng: &mut FastRng) -> (f64, f64) {
        if self.jwildfire {
            return self.project_jwildfire(x, y, z, rng);
        }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::chaos::Chaos;
    use crate::flame::model::{Affine, Xform};

    fn projection(cam: crate::flame::model::Camera3d) -> Projection {
        let f = Flame {
            cam,
            ..Flame::default()
        };
        Projection::of(&f).expect("a 3-D camera")
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

    /// The blur curve scales the blur by d²/(4·curve), d ten times the distance from the
    /// origin relative to half the picture: for Fractorium's flames half its histogram, the
    /// picture and a gutter of 10 pixels on each side.
    #[test]
    fn the_blur_curve_is_relative_to_half_the_histogram() {
        use crate::flame::model::Camera3d;
        let cam = Camera3d {
            dof: 1.0,
            blur_curve: 1.0,
            ..Camera3d::default()
        };
        // 100×60 pixels at 10 per unit: half the picture is 5 × 3 units.
        let mut f = Flame {
            cam,
            width: 100,
            height: 60,
            scale: 10.0,
            ..Flame::default()
        };
        // The point (2.5, 0) at depth 1 is moved by 0.1·u·scale, u uniform in [0, 1).
        let mean_move = |f: &Flame| {
            let p = Projection::of(f).expect("a 3-D camera");
            let mut rng = FastRng::new(9);
            let n = 20_000;
            (0..n)
                .map(|_| {
                    let (x, y) = p.project(2.5, 0.0, 1.0, &mut rng);
                    (x - 2.5).hypot(y)
                })
                .sum::<f64>()
                / n as f64
        };
        // flam3's rule: d = 10·2.5/5 = 5, scale 25/4; mean move 0.05·25/4.
        let m = mean_move(&f);
        assert!((m / (0.05 * 6.25) - 1.0).abs() < 0.02, "{m}");
        // Fractorium's: half width (50 + 10)/10 = 6, d = 10·2.5/6, scale d²/4.
        f.palette_index = PaletteIndex::Fractorium;
        let d: f64 = 25.0 / 6.0;
        let m = mean_move(&f);
        assert!((m / (0.05 * d * d / 4.0) - 1.0).abs() < 0.02, "{m}");
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
}
