//! Textured Bézier scenes: patches, row-vector transforms, tessellation, z-buffer rasterising
//! with perspective-correct, mipmapped textures, Phong lighting and bump mapping; ray casting
//! with shadows as a second renderer; procedural fractal textures, midpoint-displacement
//! mountains, the Menger sponge and ray-marched quaternion Julia sets.

pub mod budget;
pub mod bvh;
pub mod menger;
pub mod mesh;
pub mod patch;
pub mod quaternion;
pub mod raster;
pub mod raycast;
pub mod scene;
pub mod texture;
pub mod transform;

pub use budget::{RenderError, try_render};
pub use mesh::{Mesh, SurfacePatch, TexMap};
pub use patch::Patch;
pub use quaternion::{QuaternionJulia, SliceAxis};
pub use scene::{Camera, Geometry, Light, Material, Object, Projection, Renderer, Scene};
pub use texture::Texture;
pub use transform::Transform;

use std::sync::atomic::AtomicBool;

/// Render the scene with its renderer (z-buffer or ray casting). Returns None when cancelled.
/// `try_render` also checks the memory estimate first.
pub fn render(scene: &Scene, cancel: Option<&AtomicBool>) -> Option<image::RgbImage> {
    match scene.renderer {
        Renderer::ZBuffer => raster::render_zbuffer(scene, cancel),
        Renderer::RayCast => raycast::render(scene, cancel),
    }
}
