//! How finely each object's patches are tessellated for one eye: about 6 pixels a cell, every
//! grid coarsened alike when the scene would exceed its triangle budget. Both renderers use the
//! same tessellation.

use glam::DVec3;

use super::eye::Eye;
use super::mesh::{SurfacePatch, projected_extent, resolution_for};
use super::scene::{Geometry, Object, Scene};

/// Most triangles the patches of a scene are tessellated into (for one eye). Each object's
/// grid follows its projected size (about 6 pixels a cell); when the sum would exceed this,
/// every grid is coarsened by the same factor, so that memory and time stay bounded for
/// scenes of thousands of patches, whose cells are then a few pixels larger.
pub const MAX_TRIANGLES: u64 = 1_500_000;

/// The tessellation grid of every object for one eye (0 for meshes), within
/// [`MAX_TRIANGLES`].
pub(crate) fn resolutions(scene: &Scene, eye: &Eye) -> Vec<usize> {
    let mut n: Vec<usize> = scene
        .objects
        .iter()
        .map(|o| match &o.geometry {
            Geometry::Patches(p) => patch_resolution(o, p, eye),
            Geometry::Mesh(_) | Geometry::QuaternionJulia(_) => 0,
        })
        .collect();
    let patch_triangles = |n: &[usize]| -> u64 {
        scene
            .objects
            .iter()
            .zip(n)
            .map(|(o, &k)| match &o.geometry {
                Geometry::Patches(p) => p.len() as u64 * 2 * (k * k) as u64,
                Geometry::Mesh(_) | Geometry::QuaternionJulia(_) => 0,
            })
            .sum()
    };
    let total = patch_triangles(&n);
    if total > MAX_TRIANGLES {
        let k = (MAX_TRIANGLES as f64 / total as f64).sqrt();
        for v in n.iter_mut().filter(|v| **v > 0) {
            *v = ((*v as f64 * k).floor() as usize).max(1);
        }
    }
    n
}

/// Tessellation grid of an object's patches for one eye: about 6 pixels per cell.
pub(crate) fn patch_resolution(o: &Object, p: &[SurfacePatch], eye: &Eye) -> usize {
    let to_screen = |q: DVec3| {
        let c = eye.clip(o.transform.apply(q));
        (c[3] > 1e-3).then(|| {
            let s = eye.screen(c);
            [s[0], s[1]]
        })
    };
    resolution_for(projected_extent(p, to_screen))
}
