//! Quaternion Julia objects placed in the world: the world ray taken into object space,
//! distance-estimated ray marching to the first hit, occlusion tests for shadows and the
//! shading data at a hit. Both renderers march them per pixel.

use glam::DVec3;

use super::eye::Eye;
use super::quaternion::{QuaternionJulia, ray_sphere};
use super::scene::{Geometry, Object, Scene};
use super::shading::SurfacePoint;
use super::transform::Transform;

/// A quaternion Julia object placed in the world.
pub(crate) struct Implicit {
    pub(crate) object: usize,
    julia: QuaternionJulia,
    /// object → world, world → object.
    xf: Transform,
    to_object: Transform,
    radius: f64,
}

impl Implicit {
    pub(crate) fn new(object: usize, o: &Object, j: &QuaternionJulia) -> Option<Implicit> {
        Some(Implicit {
            object,
            julia: *j,
            xf: o.transform,
            to_object: o.transform.inverse()?,
            radius: j.escape_radius(),
        })
    }

    /// The ray in object space: origin, unit direction and object units per world unit.
    fn local(&self, o: DVec3, d: DVec3) -> (DVec3, DVec3, f64) {
        let lo = self.to_object.apply(o);
        let ld = self.to_object.apply_dir(d);
        let l = ld.length();
        (lo, ld / l, l)
    }

    /// Surface threshold in object units at ray parameter t: half a pixel.
    fn eps(&self, eye: &Eye, t: f64, l: f64) -> f64 {
        (0.5 * eye.pixel_size(t) * l).max(1e-7 * self.radius)
    }

    /// The first hit in [t_min, t_max] of the world ray o + t·d (unit d).
    pub(crate) fn hit(&self, o: DVec3, d: DVec3, t_min: f64, t_max: f64, eye: &Eye) -> Option<f64> {
        let (lo, ld, l) = self.local(o, d);
        let (s0, s1) = ray_sphere(lo, ld, DVec3::ZERO, self.radius)?;
        let (s0, s1) = (s0.max(t_min * l), s1.min(t_max * l));
        if s0 > s1 {
            return None;
        }
        let s = self
            .julia
            .march(lo, ld, s0, s1, |s| self.eps(eye, s / l, l))?;
        Some(s / l)
    }

    /// Does anything of the set lie on the segment o + t·d, t in (0, t_max)? `eps` is the
    /// surface threshold in world units.
    pub(crate) fn occludes(&self, o: DVec3, d: DVec3, t_max: f64, eps: f64) -> bool {
        let (lo, ld, l) = self.local(o, d);
        let Some((s0, s1)) = ray_sphere(lo, ld, DVec3::ZERO, self.radius) else {
            return false;
        };
        let (s0, s1) = (s0.max(0.0), s1.min(t_max * l));
        s0 <= s1 && self.julia.march(lo, ld, s0, s1, |_| eps * l).is_some()
    }

    /// The shading data at ray parameter t, and the world-space surface threshold there.
    pub(crate) fn surface_point(
        &self,
        o: DVec3,
        d: DVec3,
        t: f64,
        eye: &Eye,
    ) -> (SurfacePoint, f64) {
        let (lo, ld, l) = self.local(o, d);
        let eps = self.eps(eye, t, l);
        let p = lo + ld * (t * l);
        let n = self.julia.normal(p, 0.5 * eps);
        let normal = self.xf.apply_normal(n).normalize_or(n);
        let st = self.julia.tex_coords(p);
        (
            SurfacePoint {
                object: self.object,
                pos: o + d * t,
                normal,
                st,
                footprint: 0.0,
                ts: DVec3::ZERO,
                tt: DVec3::ZERO,
            },
            eps / l,
        )
    }
}

/// The quaternion Julia objects of a scene.
pub(crate) fn implicit_objects(scene: &Scene) -> Vec<Implicit> {
    scene
        .objects
        .iter()
        .enumerate()
        .filter_map(|(k, o)| match &o.geometry {
            Geometry::QuaternionJulia(j) => Implicit::new(k, o, j),
            _ => None,
        })
        .collect()
}
