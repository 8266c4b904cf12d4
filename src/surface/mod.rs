//! Textured Bézier scenes: patches, row-vector transforms, tessellation, z-buffer rasterising
//! with perspective-correct, mipmapped textures, Phong lighting and bump mapping; ray casting
//! with shadows as a second renderer; procedural fractal textures, midpoint-displacement
//! mountains, the Menger sponge and ray-marched quaternion Julia sets.

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

pub use mesh::{Mesh, SurfacePatch, TexMap};
pub use patch::Patch;
pub use quaternion::{QuaternionJulia, SliceAxis};
pub use raster::{RenderError, render, try_render};
pub use scene::{Camera, Geometry, Light, Material, Object, Projection, Renderer, Scene};
pub use texture::Texture;
pub use transform::Transform;
