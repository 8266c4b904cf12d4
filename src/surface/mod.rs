//! Textured Bézier scenes: patches, row-vector transforms, tessellation, z-buffer rasterising
//! with perspective-correct, mipmapped textures, Phong lighting and bump mapping; ray casting
//! with shadows as a second renderer; procedural fractal textures, midpoint-displacement
//! mountains, the Menger sponge and ray-marched quaternion Julia sets.

mod bounds;
mod bvh;
mod eye;
mod frame;
mod implicit;
pub mod menger;
pub(crate) mod mesh;
mod patch;
mod quaternion;
mod raster;
mod raycast;
mod renderer;
mod resolution;
mod scene;
mod shading;
mod spec;
pub(crate) mod texture;
pub(crate) mod transform;

pub use eye::project;
pub use mesh::{Mesh, SurfacePatch, TexMap};
pub use patch::Patch;
pub use quaternion::{QuaternionJulia, SliceAxis};
pub use renderer::{
    MAX_SIDE, MemoryEstimate, RenderError, check, estimate_memory, render, try_render,
};
pub use resolution::MAX_TRIANGLES;
pub use scene::{Camera, Geometry, Light, Material, Object, Projection, Renderer, Scene};
pub use spec::{GeometrySpec, ObjectSpec, SceneSpec, TextureError, TextureKind, TextureSpec};
pub use texture::Texture;
pub use transform::Transform;
