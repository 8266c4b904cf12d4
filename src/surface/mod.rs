//! Textured Bézier scenes (surfaces.md): patches, row-vector transforms, tessellation,
//! z-buffer rasterising with perspective-correct, mipmapped textures, Phong lighting and bump
//! mapping; procedural fractal textures and midpoint-displacement mountains.

pub mod mesh;
pub mod patch;
pub mod raster;
pub mod scene;
pub mod texture;
pub mod transform;

pub use mesh::{Mesh, SurfacePatch, TexMap};
pub use patch::Patch;
pub use raster::{RenderError, render, try_render};
pub use scene::{Camera, Geometry, Light, Material, Object, Projection, Scene};
pub use texture::Texture;
pub use transform::Transform;
