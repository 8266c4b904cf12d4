//! Rendering a scene with its renderer: the size and memory check before anything is made, and
//! the choice between the z-buffer and the ray caster.

use std::sync::atomic::AtomicBool;

use glam::Vec3;
use image::RgbImage;

use super::eye::eyes;
use super::resolution::resolutions;
use super::scene::{Geometry, Projection, Renderer, Scene};
use super::{raster, raycast};

/// Memory a scene render needs, part by part, estimated before tessellating.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MemoryEstimate {
    /// Vertices and triangles after tessellation (all eyes).
    pub vertices: u64,
    /// Triangles after tessellation (the larger eye's, for a stereo pair).
    pub triangles: u64,
    /// Meshes, clipped vertices, screen triangles and their bins.
    pub geometry: u64,
    /// Colour buffers at the supersampled size and the output image.
    pub pixels: u64,
    /// Bytes in all: geometry plus pixels.
    pub total: u64,
}

/// Estimate the memory of a render (the textures, already made, are not counted): the
/// tessellation the renderer will choose, every triangle visible, colour buffers per eye.
pub fn estimate_memory(scene: &Scene) -> MemoryEstimate {
    let (w, h, eyes) = eyes(scene);
    // Eyes render one after the other: the larger tessellation counts.
    let (mut vertices, mut triangles) = (0u64, 0u64);
    for (eye, _) in &eyes {
        let (mut v, mut t) = (0u64, 0u64);
        for (o, k) in scene.objects.iter().zip(resolutions(scene, eye)) {
            let (dv, dt) = match &o.geometry {
                Geometry::Patches(p) => {
                    let n = k.max(1) as u64;
                    (
                        p.len() as u64 * (n + 1) * (n + 1),
                        p.len() as u64 * 2 * n * n,
                    )
                }
                Geometry::Mesh(m) => (m.positions.len() as u64, m.triangles.len() as u64),
                // Ray-marched per pixel: no geometry.
                Geometry::QuaternionJulia(_) => (0, 0),
            };
            v = v.saturating_add(dv);
            t = t.saturating_add(dt);
        }
        vertices = vertices.max(v);
        triangles = triangles.max(t);
    }
    let geometry = match scene.renderer {
        Renderer::ZBuffer => raster::geometry_bytes(vertices, triangles),
        Renderer::RayCast => raycast::geometry_bytes(vertices, triangles),
    };
    let px = (w * h) as u64;
    let colour = std::mem::size_of::<Vec3>() as u64;
    // A stereo pair keeps the left picture while the right one is made, then joins them.
    let pixels = px * colour * if eyes.len() > 1 { 2 } else { 1 }
        + (scene.width as u64 * scene.height as u64) * 3 * 2;
    MemoryEstimate {
        vertices,
        triangles,
        geometry,
        pixels,
        total: geometry.saturating_add(pixels),
    }
}

/// Largest scene image side.
pub const MAX_SIDE: u32 = 16_384;

/// Why a scene cannot be rendered.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RenderError {
    /// The image size or a setting is out of range (the message says which).
    #[error("{0}")]
    Settings(String),
    /// The render would not fit in the memory allowed.
    #[error(transparent)]
    OutOfMemory(#[from] crate::memory::MemoryError),
    /// The cancel flag was raised while rendering.
    #[error("rendering was cancelled")]
    Cancelled,
}

/// Check a scene's size and memory before rendering it (`configured`: a memory limit instead
/// of the system's budget).
pub fn check(scene: &Scene, configured: Option<u64>) -> Result<MemoryEstimate, RenderError> {
    let (w, h) = (scene.width, scene.height);
    if w == 0 || h == 0 || w > MAX_SIDE || h > MAX_SIDE {
        return Err(RenderError::Settings(format!(
            "image size {w}x{h} must be between 1x1 and {MAX_SIDE}x{MAX_SIDE}"
        )));
    }
    if !(1..=4).contains(&scene.supersample) {
        return Err(RenderError::Settings(format!(
            "supersample {} must be between 1 and 4",
            scene.supersample
        )));
    }
    if let Projection::Stereo = scene.camera.projection
        && w < 2
    {
        return Err(RenderError::Settings(format!(
            "a stereo pair puts two pictures side by side: the width ({w}) must be at least 2"
        )));
    }
    let est = estimate_memory(scene);
    crate::memory::check(
        est.total,
        configured,
        || {
            format!(
                "a {w}×{h} scene at supersample {} with {} object{} ({} triangles)",
                scene.supersample,
                scene.objects.len(),
                if scene.objects.len() == 1 { "" } else { "s" },
                est.triangles
            )
        },
        || {
            let mut h = String::from("reduce the image size");
            if scene.supersample > 1 {
                h.push_str(&format!(" or the supersample ({})", scene.supersample));
            }
            h.push_str(", or use fewer objects or profile segments");
            h
        },
    )?;
    Ok(est)
}

/// Render the scene with its renderer (z-buffer or ray casting) after checking its size and
/// memory ([`check`]). Cancelling returns [`RenderError::Cancelled`].
pub fn try_render(scene: &Scene, cancel: Option<&AtomicBool>) -> Result<RgbImage, RenderError> {
    check(scene, None)?;
    match scene.renderer {
        Renderer::ZBuffer => raster::render_zbuffer(scene, cancel),
        Renderer::RayCast => raycast::render(scene, cancel),
    }
    .ok_or(RenderError::Cancelled)
}

/// As [`try_render`], None for every failure (cancelled, too large, invalid size); kept for
/// callers that only show a picture when there is one.
pub fn render(scene: &Scene, cancel: Option<&AtomicBool>) -> Option<RgbImage> {
    try_render(scene, cancel).ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::mesh;
    use crate::surface::scene::{Material, Object};
    use crate::surface::transform::{self, Transform};

    #[test]
    fn estimates_of_both_renderers_grow_with_the_picture_and_refuse_clearly() {
        let jug_scene = |w: u32, h: u32, r: Renderer| {
            let mut s = Scene {
                width: w,
                height: h,
                renderer: r,
                ..Scene::default()
            };
            s.objects.push(Object {
                name: "jug".into(),
                geometry: Geometry::Patches(mesh::jug()),
                transform: Transform::IDENTITY,
                material: Material::default(),
                texture: None,
                bump_texture: None,
            });
            s
        };
        for r in [Renderer::ZBuffer, Renderer::RayCast] {
            let small = estimate_memory(&jug_scene(320, 240, r)).total;
            let big = estimate_memory(&jug_scene(1280, 960, r)).total;
            // At least the colour buffers; 16× the pixels costs more than 4× the memory.
            assert!(small >= 320 * 240 * 12, "{small}");
            assert!(big > 4 * small && big < 40 * small, "{small} {big}");
        }
        // 16384² with 4× supersampling needs tens of GiB: refused with a message that says
        // what to change.
        let mut huge = jug_scene(16384, 16384, Renderer::RayCast);
        huge.supersample = 4;
        let e = check(&huge, Some(8 << 30)).unwrap_err();
        assert!(matches!(e, RenderError::OutOfMemory(_)));
        let msg = e.to_string();
        assert!(msg.contains("image size"), "{msg}");
        assert!(check(&jug_scene(320, 240, Renderer::RayCast), Some(8 << 30)).is_ok());
    }
    #[test]
    fn every_projection_casts_the_rays_the_z_buffer_projects() {
        // The untextured jug under each projection: the ray caster (no shadows) and the
        // z-buffer agree pixel for pixel within 12/255 almost everywhere, so the rays go
        // through the same points the z-buffer projects to.
        let mut base = Scene {
            width: 96,
            height: 72,
            shadows: false,
            ..Scene::default()
        };
        base.objects.push(Object {
            name: "jug".into(),
            geometry: Geometry::Patches(mesh::jug()),
            transform: Transform::rot_y(0.4),
            material: Material::default(),
            texture: None,
            bump_texture: None,
        });
        let (phi, theta) = transform::isometric_angles();
        for (name, p, w) in [
            ("perspective", Projection::Perspective, 96),
            ("orthographic", Projection::Orthographic, 96),
            ("isometric", Projection::Axonometric { phi, theta }, 96),
            ("stereo", Projection::Stereo, 192),
        ] {
            let mut s = base.clone();
            s.camera.projection = p;
            s.width = w;
            let z = raster::render_zbuffer(&s, None).unwrap();
            s.renderer = Renderer::RayCast;
            let r = raycast::render(&s, None).unwrap();
            let close = z
                .pixels()
                .zip(r.pixels())
                .filter(|(a, b)| (0..3).all(|c| a.0[c].abs_diff(b.0[c]) <= 12))
                .count() as f64
                / (w * 72) as f64;
            let drawn = r.pixels().filter(|p| p.0 != [0, 0, 0]).count();
            assert!(
                close >= 0.98 && drawn > 1000,
                "{name}: {close} ({drawn} drawn)"
            );
        }
    }
}
