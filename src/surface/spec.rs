//! A scene described before its textures and meshes are made: plain data, as a scene file gives
//! it (which texture from which flame, escape-time view, picture or parameters, at which size;
//! which mesh from which parameters), and the step that makes them into a [`Scene`] ready to
//! render.

use glam::Vec3;
use image::RgbImage;

use super::menger;
use super::mesh;
use super::scene::{Geometry, Material, Object, Scene};
use super::texture::{self, MAX_MRF_SIDE, MrfParams, Texture};
use super::transform::Transform;
use crate::escape::EscapeDoc;
use crate::flame::Flame;
use crate::gradient::Gradient;
use crate::noise::Fbm;

/// A scene before its textures and meshes are made.
#[derive(Clone, Debug)]
pub struct SceneSpec {
    /// Camera, lights, image and renderer settings. Its `textures` and `objects` are replaced
    /// by the ones made from the lists below.
    pub scene: Scene,
    /// The textures to make, in the order objects refer to them.
    pub textures: Vec<TextureSpec>,
    /// The objects, their meshes still to make.
    pub objects: Vec<ObjectSpec>,
}

/// A texture to make, `width`×`height` texels (a picture keeps its own size).
#[derive(Clone, Debug)]
pub struct TextureSpec {
    /// Width in texels.
    pub width: usize,
    /// Height in texels.
    pub height: usize,
    /// Where the texels come from.
    pub kind: TextureKind,
}

/// Where a texture's texels come from.
#[derive(Clone, Debug)]
pub enum TextureKind {
    /// A decoded picture.
    Image(RgbImage),
    /// A flame rendered at the texture's size (its framing kept), at `quality` when given.
    Flame {
        /// The flame to render.
        flame: Box<Flame>,
        /// Samples per pixel instead of the flame's own quality.
        quality: Option<f64>,
    },
    /// An escape-time view rendered at the texture's size, its world width kept.
    Escape(Box<EscapeDoc>),
    /// Fractional Brownian motion between two colours.
    Fbm {
        /// The noise: octaves, frequencies, gain and seed.
        fbm: Fbm,
        /// The two colours it blends between (RGB, 0–1).
        colors: [Vec3; 2],
    },
    /// Value noise of `cells` cells across.
    Value {
        /// Seed of the random lattice values.
        seed: u64,
        /// Lattice cells across the texture.
        cells: u32,
        /// The two colours it blends between (RGB, 0–1).
        colors: [Vec3; 2],
    },
    /// A Markov random field (at most `MAX_MRF_SIDE` = 1024 texels on a side).
    Mrf {
        /// The field's interaction weights, sweeps and seed.
        params: MrfParams,
        /// The colours of the two states (RGB, 0–1).
        colors: [Vec3; 2],
    },
    /// A checkerboard of `cells` = [across, down] squares.
    Checker {
        /// Squares [across, down].
        cells: [usize; 2],
        /// The colours of the two kinds of square (RGB, 0–1).
        colors: [Vec3; 2],
    },
    /// Grid lines (first colour) on a background (second colour).
    Grid {
        /// Cells [across, down].
        cells: [usize; 2],
        /// Line colour and background colour (RGB, 0–1).
        colors: [Vec3; 2],
    },
    /// One colour (RGB, 0–1).
    Solid(Vec3),
    /// A gradient along t (e.g. a mountain's height).
    Gradient(Box<Gradient>),
}

/// An object before its mesh is made.
#[derive(Clone, Debug)]
pub struct ObjectSpec {
    /// The object's name in the scene file.
    pub name: String,
    /// Its shape, or how to make it.
    pub geometry: GeometrySpec,
    /// Object space to world space.
    pub transform: Transform,
    /// How it reflects light.
    pub material: Material,
    /// Index into [`SceneSpec::textures`].
    pub texture: Option<usize>,
    /// Index into [`SceneSpec::textures`] of a height texture for bump mapping.
    pub bump_texture: Option<usize>,
}

/// An object's geometry: given (patches, a quaternion Julia set), or a mesh to make.
#[derive(Clone, Debug)]
pub enum GeometrySpec {
    /// Geometry given as it is.
    Given(Geometry),
    /// A midpoint-displacement mountain (`mesh::mountain`).
    Mountain {
        /// Subdivision levels K (2·4^K triangles).
        levels: u32,
        /// Side of the square base in world units.
        size: f64,
        /// Standard deviation σ₀ of the first displacement.
        sigma: f64,
        /// The roughness exponent H: σ_k = σ₀·2^(−kH).
        h: f64,
        /// Seed of the displacements.
        seed: u64,
    },
    /// The Menger sponge at construction step `step` with edge `size` ([`menger::mesh`]).
    Menger {
        /// Construction step (at most [`menger::MAX_STEP`]).
        step: u32,
        /// Edge of the whole cube in world units.
        size: f64,
    },
}

/// A texture that could not be made: its index in [`SceneSpec::textures`] and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TextureError {
    /// Index of the texture in [`SceneSpec::textures`].
    pub index: usize,
    /// Why it could not be made.
    pub message: String,
}

impl SceneSpec {
    /// Make the textures (rendering flames and escape-time views) and the meshes: the scene
    /// ready to render.
    pub fn build(self) -> Result<Scene, TextureError> {
        let mut scene = self.scene;
        scene.textures = self
            .textures
            .iter()
            .enumerate()
            .map(|(index, t)| t.make().map_err(|message| TextureError { index, message }))
            .collect::<Result<_, _>>()?;
        scene.objects = self.objects.into_iter().map(ObjectSpec::make).collect();
        Ok(scene)
    }
}

impl TextureSpec {
    /// Make the texture.
    pub fn make(&self) -> Result<Texture, String> {
        let (w, h) = (self.width, self.height);
        Ok(match &self.kind {
            TextureKind::Image(img) => Texture::from_image(img),
            TextureKind::Flame { flame, quality } => {
                let mut f = (**flame).clone();
                f.resize_keep_framing(w as u32, h as u32);
                if let Some(q) = quality {
                    f.quality = *q;
                }
                // A fixed thread count keeps the texture (and the scene) identical on every
                // machine.
                let opts = crate::flame::RenderOptions {
                    threads: 2,
                    ..Default::default()
                };
                let img = crate::flame::render(&f, &opts).map_err(|e| e.to_string())?;
                Texture::from_image(&img.to_rgb8())
            }
            TextureKind::Escape(d) => {
                // Keep the view's world width at the texture's size.
                let mut d = d.clone();
                d.resize(w as u32, h as u32);
                let (img, _) = crate::escape::render(&d.params, d.view.clone(), w as u32, h as u32)
                    .map_err(|e| e.to_string())?;
                Texture::from_image(&img)
            }
            TextureKind::Fbm {
                fbm,
                colors: [a, b],
            } => texture::fbm_texture(w, h, *fbm, *a, *b),
            TextureKind::Value {
                seed,
                cells,
                colors: [a, b],
            } => texture::value_noise_texture(w, h, *seed, *cells, *a, *b),
            TextureKind::Mrf {
                params,
                colors: [a, b],
            } => texture::mrf_texture(w.min(MAX_MRF_SIDE), h.min(MAX_MRF_SIDE), params, *a, *b),
            TextureKind::Checker {
                cells: [n, m],
                colors: [a, b],
            } => texture::checker(w, h, *n, *m, *a, *b),
            TextureKind::Grid {
                cells: [n, m],
                colors: [a, b],
            } => texture::grid(w, h, *n, *m, *a, *b),
            TextureKind::Solid(c) => Texture::solid(*c),
            TextureKind::Gradient(g) => {
                // t runs along the gradient: 4 texels across, 256 down.
                let rows: Vec<Vec3> = (0..256)
                    .flat_map(|k| {
                        let c = g.colors[k];
                        std::iter::repeat_n(Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32), 4)
                    })
                    .collect();
                Texture::from_texels(4, 256, rows)
            }
        })
    }
}

impl ObjectSpec {
    /// Make the object (its mesh, when it has one to make).
    pub fn make(self) -> Object {
        let geometry = match self.geometry {
            GeometrySpec::Given(g) => g,
            GeometrySpec::Mountain {
                levels,
                size,
                sigma,
                h,
                seed,
            } => Geometry::Mesh(mesh::mountain(levels, size, sigma, h, seed)),
            GeometrySpec::Menger { step, size } => Geometry::Mesh(menger::mesh(step, size)),
        };
        Object {
            name: self.name,
            geometry,
            transform: self.transform,
            material: self.material,
            texture: self.texture,
            bump_texture: self.bump_texture,
        }
    }
}
