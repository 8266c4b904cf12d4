//! Memory estimate of a scene render, checked before anything large is allocated, and the
//! render entry point that reports why it stopped.
//!
//! This is a local estimate for the scene renderers; the available memory comes from
//! /proc/meminfo (MemAvailable) and the cgroup limit, the smaller winning. A shared
//! engine-wide helper can replace `available_bytes` without changing the estimate.

use std::sync::atomic::AtomicBool;

use image::RgbImage;

use super::bvh;
use super::raycast;
use super::scene::{Geometry, Renderer, Scene};

/// Why a render produced no picture.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum RenderError {
    #[error("rendering was cancelled")]
    Cancelled,
    #[error(
        "the scene needs about {} MiB to render but only {} MiB are available: reduce the image size or the supersampling",
        .need / (1 << 20),
        .available / (1 << 20)
    )]
    OutOfMemory { need: u64, available: u64 },
}

/// Estimated peak bytes of rendering `scene` with its renderer.
pub fn estimate_bytes(scene: &Scene) -> u64 {
    let ss = scene.supersample.clamp(1, 4) as u64;
    let (w, h) = (scene.width as u64 * ss, scene.height as u64 * ss);
    let pixels = w * h;
    // Linear colour buffer (3 × f32) plus the 8-bit output image.
    let mut bytes = pixels * 12 + scene.width as u64 * scene.height as u64 * 3;
    let tris = raycast::triangle_count(scene, w as usize, h as usize) as u64;
    let verts: u64 = scene
        .objects
        .iter()
        .map(|o| match &o.geometry {
            Geometry::Mesh(m) => m.positions.len() as u64,
            _ => 0,
        })
        .sum::<u64>()
        + tris; // a patch grid has about one vertex per two triangles; generous
    match scene.renderer {
        Renderer::ZBuffer => {
            // Clipped vertices (144 B) with their screen positions (24 B), world meshes
            // (104 B a vertex, 12 B a triangle) and screen triangles (about 200 B); each band
            // of 16 rows holds its depth and hit buffers (32 B a pixel) on every thread.
            bytes += verts * (144 + 24 + 104) + tris * (12 + 200 + 8);
            bytes += w * 16 * 32 * rayon::current_num_threads() as u64;
        }
        Renderer::RayCast => {
            // Per object: the hierarchy, the triangle references and the world mesh.
            bytes += bvh::bytes_for(tris as usize) as u64 + tris * 16 + verts * 104;
        }
    }
    bytes
}

/// Memory this process may still use: the smallest of MemAvailable and the cgroup limit
/// (less what the cgroup already uses). None when neither can be read.
pub fn available_bytes() -> Option<u64> {
    let meminfo = std::fs::read_to_string("/proc/meminfo").ok().and_then(|t| {
        t.lines()
            .find(|l| l.starts_with("MemAvailable:"))
            .and_then(|l| l.split_whitespace().nth(1))
            .and_then(|v| v.parse::<u64>().ok())
            .map(|kib| kib * 1024)
    });
    let read_u64 = |p: &str| {
        std::fs::read_to_string(p)
            .ok()
            .and_then(|t| t.trim().parse::<u64>().ok())
    };
    let cgroup = match (
        read_u64("/sys/fs/cgroup/memory.max"),
        read_u64("/sys/fs/cgroup/memory.current"),
    ) {
        (Some(max), cur) => Some(max.saturating_sub(cur.unwrap_or(0))),
        _ => None,
    };
    match (meminfo, cgroup) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// Refuse a render that needs more than `available` bytes.
pub fn check(scene: &Scene, available: Option<u64>) -> Result<(), RenderError> {
    let need = estimate_bytes(scene);
    match available {
        Some(a) if need > a => Err(RenderError::OutOfMemory { need, available: a }),
        _ => Ok(()),
    }
}

/// Render with the scene's renderer after the memory check.
pub fn try_render(scene: &Scene, cancel: Option<&AtomicBool>) -> Result<RgbImage, RenderError> {
    check(scene, available_bytes())?;
    let img = match scene.renderer {
        Renderer::ZBuffer => super::raster::render_zbuffer(scene, cancel),
        Renderer::RayCast => raycast::render(scene, cancel),
    };
    img.ok_or(RenderError::Cancelled)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::scene::{Material, Object};
    use crate::surface::transform::Transform;

    fn jug_scene(w: u32, h: u32, r: Renderer) -> Scene {
        let mut s = Scene {
            width: w,
            height: h,
            renderer: r,
            ..Scene::default()
        };
        s.objects.push(Object {
            name: "jug".into(),
            geometry: Geometry::Patches(crate::surface::mesh::jug()),
            transform: Transform::IDENTITY,
            material: Material::default(),
            texture: None,
            bump_texture: None,
        });
        s
    }

    #[test]
    fn estimates_grow_with_the_picture_and_refuse_clearly() {
        for r in [Renderer::ZBuffer, Renderer::RayCast] {
            let small = estimate_bytes(&jug_scene(320, 240, r));
            let big = estimate_bytes(&jug_scene(1280, 960, r));
            // At least the colour buffers; 16× the pixels costs more than 10× the memory.
            assert!(small >= 320 * 240 * 15, "{small}");
            assert!(big > 4 * small && big < 40 * small, "{small} {big}");
        }
        // 16384² with 4× supersampling needs tens of GiB: refused with a message that says
        // what to change.
        let mut huge = jug_scene(16384, 16384, Renderer::RayCast);
        huge.supersample = 4;
        let e = check(&huge, Some(8 << 30)).unwrap_err();
        assert!(matches!(e, RenderError::OutOfMemory { .. }));
        let msg = e.to_string();
        assert!(msg.contains("MiB") && msg.contains("image size"), "{msg}");
        assert!(check(&jug_scene(320, 240, Renderer::RayCast), Some(8 << 30)).is_ok());
        // Unknown availability: no refusal.
        assert!(check(&huge, None).is_ok());
    }
}
