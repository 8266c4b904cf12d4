//! How an eye sees a scene: the viewing transform and projection of the camera, the mapping to
//! screen pixels, the ray through a pixel (both renderers), and the eyes of a picture (one, or
//! the two of a stereo pair).

use glam::DVec3;

use super::bounds::world_sphere;
use super::scene::{Projection, Scene};
use super::transform::Transform;

/// How one eye sees: world → view transform, projection and screen placement.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Eye {
    pub(crate) view: Transform,
    /// View → world (for rays).
    pub(crate) world_from_view: Transform,
    /// Horizontal shift of view space (stereo).
    pub(crate) dx: f64,
    /// Perspective distance k (None: parallel projection).
    pub(crate) k: Option<f64>,
    pub(crate) cx: f64,
    pub(crate) cy: f64,
    pub(crate) scale: f64,
    /// Eye position in world space (lighting).
    pub(crate) pos: DVec3,
    /// View-space z where parallel rays start (in front of everything).
    pub(crate) ray_z: f64,
}

impl Eye {
    /// View-space point → (x, y, z, w).
    #[inline]
    pub(crate) fn clip(&self, p: DVec3) -> [f64; 4] {
        let v = self.view.apply(p);
        let w = match self.k {
            Some(k) => 1.0 - v.z / k,
            None => 1.0,
        };
        [v.x + self.dx, v.y, v.z, w]
    }

    #[inline]
    pub(crate) fn screen(&self, c: [f64; 4]) -> [f64; 3] {
        [
            self.cx + self.scale * c[0] / c[3],
            self.cy - self.scale * c[1] / c[3],
            c[2] / c[3],
        ]
    }

    /// The ray through screen point (px, py) in world space: origin, unit direction and the
    /// smallest t the z-buffer would draw (its near plane w ≥ 1e-3).
    #[inline]
    pub(crate) fn ray(&self, px: f64, py: f64) -> (DVec3, DVec3, f64) {
        let sx = (px - self.cx) / self.scale;
        let sy = (self.cy - py) / self.scale;
        // Perspective: x* = (x + dx)/w with w = 1 − z/k, so the points of the pixel are
        // (−dx, 0, k) + λ·(sx, sy, −k) for λ = w > 0.
        let (o, d) = match self.k {
            Some(k) => (DVec3::new(-self.dx, 0.0, k), DVec3::new(sx, sy, -k)),
            None => (DVec3::new(sx - self.dx, sy, self.ray_z), DVec3::NEG_Z),
        };
        let len = d.length();
        let t_min = if self.k.is_some() { 1e-3 * len } else { 0.0 };
        let ow = self.world_from_view.apply(o);
        let dw = self.world_from_view.apply_dir(d / len);
        let dl = dw.length();
        (ow, dw / dl, t_min * dl)
    }

    /// World-space size of one pixel at distance t along a ray (perspective grows with t).
    #[inline]
    pub(crate) fn pixel_size(&self, t: f64) -> f64 {
        match self.k {
            Some(k) => t / (self.scale * k),
            None => 1.0 / self.scale,
        }
    }

    /// Let parallel rays start in front of every object's bounding sphere (perspective rays
    /// start at the eye and need nothing).
    pub(crate) fn place_ray_start(&mut self, scene: &Scene) {
        if self.k.is_some() {
            return;
        }
        let mut z = scene.camera.distance;
        for o in &scene.objects {
            if let Some((c, r)) = world_sphere(o) {
                z = z.max(self.view.apply(c).z + r);
            }
        }
        self.ray_z = z + 1.0;
    }
}

/// The eye of a `w`×`h` picture of the scene's camera, shifted by `dx` in view space (stereo).
pub(crate) fn eye_for(scene: &Scene, w: usize, h: usize, dx: f64) -> Eye {
    let cam = &scene.camera;
    let scale = cam.scale * h as f64 / 480.0;
    let (view, k) = match cam.projection {
        Projection::Perspective | Projection::Stereo => (cam.view(), Some(cam.distance)),
        Projection::Orthographic => (cam.view(), None),
        Projection::Axonometric { phi, theta } => (
            Transform::translate(-cam.target.x, -cam.target.y, -cam.target.z)
                .then(&Transform::axonometric(phi, theta)),
            None,
        ),
    };
    let world_from_view = view.inverse().unwrap_or(Transform::IDENTITY);
    Eye {
        view,
        world_from_view,
        dx,
        k,
        cx: w as f64 / 2.0,
        cy: h as f64 / 2.0,
        scale,
        pos: cam.eye(),
        ray_z: cam.distance,
    }
}

/// The pixel size a scene renders at (supersampled), and the eyes with their widths.
pub(crate) fn eyes(scene: &Scene) -> (usize, usize, Vec<(Eye, usize)>) {
    let ss = scene.supersample.clamp(1, 4) as usize;
    let (w, h) = (scene.width as usize * ss, scene.height as usize * ss);
    let eyes = if let Projection::Stereo = scene.camera.projection {
        let half = w / 2;
        let k = scene.camera.distance;
        vec![
            (eye_for(scene, half, h, k / 20.0), half),
            (eye_for(scene, half, h, -k / 20.0), half),
        ]
    } else {
        vec![(eye_for(scene, w, h, 0.0), w)]
    };
    (w, h, eyes)
}

/// The screen position (pixels) of a world point under the scene's camera (None behind the
/// eye), e.g. for drawing light handles in the GUI.
pub fn project(scene: &Scene, p: DVec3) -> Option<[f64; 2]> {
    let (w, h) = (scene.width as usize, scene.height as usize);
    let eye = eye_for(scene, w, h, 0.0);
    let c = eye.clip(p);
    (c[3] > 1e-3).then(|| {
        let s = eye.screen(c);
        [s[0], s[1]]
    })
}
