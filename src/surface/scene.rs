//! The scene model: objects (patches or meshes) with materials and textures, lights, camera
//! and projection.

use glam::{DVec3, Vec3};

use super::mesh::{Mesh, SurfacePatch};
use super::quaternion::QuaternionJulia;
use super::texture::Texture;
use super::transform::Transform;

/// Material of the Phong illumination model (see `illuminate`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Ambient reflection coefficient K_a.
    pub ka: f64,
    /// Diffuse reflection coefficient K_d.
    pub kd: f64,
    /// Specular reflection coefficient k_s.
    pub ks: f64,
    /// Specular exponent n.
    pub shininess: f64,
    /// Multiplies the texture colour.
    pub color: Vec3,
    /// Light both sides: a normal facing away from the eye is flipped before shading.
    pub two_sided: bool,
    /// Blinn bump mapping amplitude (0: off) from the texture's heights.
    pub bump: f64,
}

impl Default for Material {
    /// The jug's material: K_a = 0.25, K_d = 0.75, k_s = 0.35, n = 24.
    fn default() -> Self {
        Material {
            ka: 0.25,
            kd: 0.75,
            ks: 0.35,
            shininess: 24.0,
            color: Vec3::ONE,
            two_sided: true,
            bump: 0.0,
        }
    }
}

/// Geometry of an object.
#[derive(Clone, Debug)]
pub enum Geometry {
    /// Parametric patches, tessellated by the renderer at a resolution fitting the view.
    Patches(Vec<SurfacePatch>),
    /// A ready triangle mesh.
    Mesh(Mesh),
    /// A 3-D slice of a quaternion Julia set, ray-marched by both renderers (the z-buffer
    /// renderer marches it per pixel and compares depths).
    QuaternionJulia(QuaternionJulia),
}

/// Which hidden-surface method renders a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Renderer {
    /// Catmull's z-buffer over a tessellation (the default).
    #[default]
    ZBuffer,
    /// Ray casting: bounding spheres and boxes, exact patch intersection, shadows.
    RayCast,
}

/// One object.
#[derive(Clone, Debug)]
pub struct Object {
    /// The object's name in the scene file.
    pub name: String,
    /// Its shape, in object space.
    pub geometry: Geometry,
    /// Object space to world space.
    pub transform: Transform,
    /// How it reflects light.
    pub material: Material,
    /// Index into `Scene::textures` (None: untextured, the material colour).
    pub texture: Option<usize>,
    /// Optional height texture for bump mapping (defaults to the colour texture).
    pub bump_texture: Option<usize>,
}

/// A point light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Position in world space.
    pub position: DVec3,
    /// I_l per channel.
    pub intensity: Vec3,
}

/// How the view is projected.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Centre of projection at the eye (k = ρ).
    Perspective,
    /// Parallel projection along the viewing direction.
    Orthographic,
    /// Axonometric: rotate about y by φ, about x by θ, project along z.
    Axonometric {
        /// φ in radians.
        phi: f64,
        /// θ in radians.
        theta: f64,
    },
    /// A left/right perspective pair side by side (Köse's 1990 matrices A and B).
    Stereo,
}

/// An orbit camera: target T, distance ρ, azimuth θ (from +z towards +x) and polar
/// angle φ (from +y).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The point looked at, T.
    pub target: DVec3,
    /// Distance ρ of the eye from the target.
    pub distance: f64,
    /// Azimuth θ in degrees, from +z towards +x.
    pub azimuth_deg: f64,
    /// Polar angle φ in degrees, from +y.
    pub polar_deg: f64,
    /// How the view is projected.
    pub projection: Projection,
    /// Pixels per world unit at the target plane, for a 480-pixel-high image (scaled with
    /// the image height).
    pub scale: f64,
}

impl Default for Camera {
    /// The jug's camera: T = (0, 1.2, 0), ρ = 7, θ = 35°, φ = 75°, S = 150.
    fn default() -> Self {
        Camera {
            target: DVec3::new(0.0, 1.2, 0.0),
            distance: 7.0,
            azimuth_deg: 35.0,
            polar_deg: 75.0,
            projection: Projection::Perspective,
            scale: 150.0,
        }
    }
}

impl Camera {
    /// The eye position E = T + ρ·(sinφ sinθ, cosφ, sinφ cosθ).
    pub fn eye(&self) -> DVec3 {
        let (th, ph) = (self.azimuth_deg.to_radians(), self.polar_deg.to_radians());
        self.target + DVec3::new(ph.sin() * th.sin(), ph.cos(), ph.sin() * th.cos()) * self.distance
    }

    /// The viewing transform V (world → view space, eye on +z at distance ρ).
    pub fn view(&self) -> Transform {
        let (th, ph) = (self.azimuth_deg.to_radians(), self.polar_deg.to_radians());
        let x = DVec3::new(th.cos(), 0.0, -th.sin());
        let y = DVec3::new(-ph.cos() * th.sin(), ph.sin(), -ph.cos() * th.cos());
        let z = DVec3::new(ph.sin() * th.sin(), ph.cos(), ph.sin() * th.cos());
        let t = self.target;
        Transform([
            [x.x, y.x, z.x, 0.0],
            [x.y, y.y, z.y, 0.0],
            [x.z, y.z, z.z, 0.0],
            [-t.dot(x), -t.dot(y), -t.dot(z), 1.0],
        ])
    }
}

/// A complete scene.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The objects drawn.
    pub objects: Vec<Object>,
    /// The textures the objects refer to by index.
    pub textures: Vec<Texture>,
    /// The point lights.
    pub lights: Vec<Light>,
    /// I_a.
    pub ambient: f64,
    /// The attenuation constant K in I_l/(d + K).
    pub attenuation_k: f64,
    /// Where the scene is seen from and how it is projected.
    pub camera: Camera,
    /// Colour of pixels no object covers (RGB, 0–1).
    pub background: Vec3,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Supersampling factor per axis (1 = none).
    pub supersample: u32,
    /// Blinn–Phong (n·H) instead of Phong (R·S) highlights.
    pub blinn: bool,
    /// The hidden-surface method.
    pub renderer: Renderer,
    /// Cast shadow rays towards each light (ray casting only).
    pub shadows: bool,
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            objects: Vec::new(),
            textures: Vec::new(),
            lights: vec![Light {
                position: DVec3::new(-5.0, 8.0, 6.0),
                intensity: Vec3::splat(8.0),
            }],
            ambient: 1.0,
            attenuation_k: 1.0,
            camera: Camera::default(),
            background: Vec3::ZERO,
            width: 640,
            height: 480,
            supersample: 1,
            blinn: false,
            renderer: Renderer::ZBuffer,
            shadows: true,
        }
    }
}

/// The Phong illumination model for one surface point (all vectors in one space):
/// I = I_a·K_a·c + Σ I_l/(d + K)·(K_d·c·(n̂·L̂) + k_s·(R̂·Ŝ)ⁿ), clamped to [0, 1].
#[allow(clippy::too_many_arguments)]
#[cfg(test)]
pub fn illuminate(
    m: &Material,
    tex: Vec3,
    normal: DVec3,
    point: DVec3,
    eye: DVec3,
    lights: &[Light],
    ambient: f64,
    k: f64,
    blinn: bool,
) -> Vec3 {
    illuminate_visible(
        m,
        tex,
        normal,
        point,
        eye,
        lights,
        ambient,
        k,
        blinn,
        &|_| true,
    )
}

/// `illuminate` with a visibility test per light (shadows): `visible(j)` is asked only for
/// lights the surface faces, and a light it denies adds nothing (the ambient term stays).
#[allow(clippy::too_many_arguments)]
pub fn illuminate_visible(
    m: &Material,
    tex: Vec3,
    normal: DVec3,
    point: DVec3,
    eye: DVec3,
    lights: &[Light],
    ambient: f64,
    k: f64,
    blinn: bool,
    visible: &dyn Fn(usize) -> bool,
) -> Vec3 {
    let base = tex * m.color;
    let mut n = normal.normalize_or_zero();
    let s = (eye - point).normalize_or_zero();
    if m.two_sided && n.dot(s) < 0.0 {
        n = -n;
    }
    let d = (eye - point).length();
    let mut c = base * (ambient * m.ka) as f32;
    for (j, l) in lights.iter().enumerate() {
        let lv = (l.position - point).normalize_or_zero();
        let ndl = n.dot(lv).max(0.0);
        if ndl <= 0.0 || !visible(j) {
            continue;
        }
        let spec = if blinn {
            n.dot((lv + s).normalize_or_zero()).max(0.0)
        } else {
            let r = n * (2.0 * n.dot(lv)) - lv;
            r.dot(s).max(0.0)
        };
        let att = 1.0 / (d + k);
        let diffuse = base * (m.kd * ndl) as f32;
        let specular = Vec3::splat((m.ks * spec.powf(m.shininess)) as f32);
        c += l.intensity * att as f32 * (diffuse + specular);
    }
    c.clamp(Vec3::ZERO, Vec3::ONE)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lighting_oracle() {
        // I_a = 1, K_a = 0.2, I_l = 1, K_d = 0.7, k_s = 0.3, n = 10, d = 4, K = 1, θ = 60°,
        // α = 30° → I = 0.28423828125.
        let m = Material {
            ka: 0.2,
            kd: 0.7,
            ks: 0.3,
            shininess: 10.0,
            color: Vec3::ONE,
            two_sided: false,
            bump: 0.0,
        };
        let n = DVec3::Y;
        // Light at 60° from the normal; viewer so that the mirror direction is 30° from S.
        let th = 60f64.to_radians();
        let lv = DVec3::new(-th.sin(), th.cos(), 0.0);
        let r = n * (2.0 * n.dot(lv)) - lv; // at +60° on the other side
        let a = 30f64.to_radians();
        // Rotate r by 30° towards the normal to get S.
        let rot = |v: DVec3, ang: f64| {
            DVec3::new(
                v.x * ang.cos() - v.y * ang.sin(),
                v.x * ang.sin() + v.y * ang.cos(),
                0.0,
            )
        };
        let s = rot(r, a);
        assert!((r.dot(s) - a.cos()).abs() < 1e-12);
        let point = DVec3::ZERO;
        let eye = s * 4.0;
        let light = Light {
            position: lv * 1000.0,
            intensity: Vec3::ONE,
        };
        let i = illuminate(&m, Vec3::ONE, n, point, eye, &[light], 1.0, 1.0, false);
        assert!((i.x as f64 - 0.28423828125).abs() < 1e-6, "{i:?}");
        assert!((30f64.to_radians().cos().powi(10) - 0.2373046875).abs() < 1e-12);
    }

    #[test]
    fn viewing_transform_oracles() {
        let c = Camera {
            target: DVec3::ZERO,
            distance: 5.0,
            azimuth_deg: 0.0,
            polar_deg: 90.0,
            ..Camera::default()
        };
        let v = c.view();
        for (a, b) in
            v.0.iter()
                .flatten()
                .zip(Transform::IDENTITY.0.iter().flatten())
        {
            assert!((a - b).abs() < 1e-12);
        }
        let c2 = Camera {
            azimuth_deg: 90.0,
            ..c
        };
        let p = c2.view().apply(DVec3::new(0.0, 0.0, -1.0));
        assert!((p - DVec3::X).length() < 1e-12, "{p:?}");
        // The eye maps to (0, 0, ρ).
        let j = Camera::default();
        assert!((j.view().apply(j.eye()) - DVec3::new(0.0, 0.0, 7.0)).length() < 1e-12);
    }
}
