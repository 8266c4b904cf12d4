//! World-space bounding spheres of objects: where parallel rays start, and the first test of
//! every ray against an object.

use glam::DVec3;

use super::scene::{Geometry, Object};
use super::transform::Transform;

/// A world-space bounding sphere of an object (centre, radius); None for an empty object.
pub(crate) fn world_sphere(o: &Object) -> Option<(DVec3, f64)> {
    let pts: Vec<DVec3> = match &o.geometry {
        // The convex hull of the nets holds the surfaces.
        Geometry::Patches(p) => p
            .iter()
            .flat_map(|sp| sp.patch.control_points())
            .map(|q| o.transform.apply(q))
            .collect(),
        Geometry::Mesh(m) => m.positions.iter().map(|q| o.transform.apply(*q)).collect(),
        Geometry::QuaternionJulia(j) => {
            let r = j.escape_radius();
            return Some((
                o.transform.apply(DVec3::ZERO),
                r * linear_stretch(&o.transform),
            ));
        }
    };
    if pts.is_empty() {
        return None;
    }
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for p in &pts {
        lo = lo.min(*p);
        hi = hi.max(*p);
    }
    let c = (lo + hi) * 0.5;
    let r = pts.iter().map(|p| (*p - c).length()).fold(0.0, f64::max);
    Some((c, r))
}

/// An upper bound of how much the linear block stretches a vector (its Frobenius norm).
fn linear_stretch(t: &Transform) -> f64 {
    let m = &t.0;
    (0..3)
        .flat_map(|r| (0..3).map(move |c| m[r][c] * m[r][c]))
        .sum::<f64>()
        .sqrt()
}
