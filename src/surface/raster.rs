//! The software renderer: adaptive tessellation, near-plane clipping,
//! z-buffer with a top-left fill rule (larger z nearer), perspective-correct attributes,
//! deferred per-pixel Phong shading with mipmapped textures and Blinn bump mapping, parallel
//! bands of rows, optional supersampling, stereo pairs.

use std::sync::atomic::{AtomicBool, Ordering};

use glam::{DVec3, Vec3};
use image::RgbImage;
use rayon::prelude::*;

use super::mesh::SurfacePatch;
use super::mesh::{Mesh, projected_extent, resolution_for, tessellate};
use super::scene::{Geometry, Object, Projection, Renderer, Scene, illuminate_visible};
use super::transform::Transform;

/// Attribute interpolated perspective-correctly: a/w and 1/w are affine in screen space.
pub fn perspective_lerp(a0: f64, a1: f64, w0: f64, w1: f64, t: f64) -> f64 {
    let num = (1.0 - t) * a0 / w0 + t * a1 / w1;
    let den = (1.0 - t) / w0 + t / w1;
    num / den
}

/// Blinn's perturbed normal n′ = N + [P_s (N × Q_t) + P_t (Q_s × N)]/|N| with N = Q_s × Q_t.
pub fn bump_normal(qs: DVec3, qt: DVec3, ps: f64, pt: f64) -> DVec3 {
    let n = qs.cross(qt);
    let len = n.length();
    if len == 0.0 {
        return n;
    }
    n + (n.cross(qt) * ps + qs.cross(n) * pt) / len
}

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
    pub(crate) fn clip(&self, p: DVec3) -> [f64; 4] {
        let v = self.view.apply(p);
        let w = match self.k {
            Some(k) => 1.0 - v.z / k,
            None => 1.0,
        };
        [v.x + self.dx, v.y, v.z, w]
    }

    pub(crate) fn screen(&self, c: [f64; 4]) -> [f64; 3] {
        [
            self.cx + self.scale * c[0] / c[3],
            self.cy - self.scale * c[1] / c[3],
            c[2] / c[3],
        ]
    }

    /// The ray through screen point (px, py) in world space: origin, unit direction and the
    /// smallest t the z-buffer would draw (its near plane w ≥ 1e-3).
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
    pub(crate) fn pixel_size(&self, t: f64) -> f64 {
        match self.k {
            Some(k) => t / (self.scale * k),
            None => 1.0 / self.scale,
        }
    }
}

/// A vertex after clipping: clip coordinates and world-space attributes.
#[derive(Clone, Copy, Debug)]
struct Vert {
    c: [f64; 4],
    pos: DVec3,
    normal: DVec3,
    tex: [f64; 2],
    ts: DVec3,
    tt: DVec3,
}

impl Vert {
    fn lerp(&self, o: &Vert, t: f64) -> Vert {
        let l = |a: f64, b: f64| a + (b - a) * t;
        Vert {
            c: [
                l(self.c[0], o.c[0]),
                l(self.c[1], o.c[1]),
                l(self.c[2], o.c[2]),
                l(self.c[3], o.c[3]),
            ],
            pos: self.pos.lerp(o.pos, t),
            normal: self.normal.lerp(o.normal, t),
            tex: [l(self.tex[0], o.tex[0]), l(self.tex[1], o.tex[1])],
            ts: self.ts.lerp(o.ts, t),
            tt: self.tt.lerp(o.tt, t),
        }
    }
}

/// A screen triangle ready for rasterising: vertex indices into the shared vertex array,
/// screen positions, edge equations and the texture footprint.
struct Tri {
    idx: [u32; 3],
    s: [[f64; 3]; 3],
    /// Edge equations e_k(x, y) = a·x + b·y + c (canonical vertex order, sign folded in so
    /// that the interior is e > 0), and whether pixels exactly on the edge belong here.
    e: [[f64; 3]; 3],
    on_edge: [bool; 3],
    inv_area: f64,
    object: u32,
    footprint: f32,
    y0: i64,
    y1: i64,
}
/// Near-plane clipping (Sutherland–Hodgman against w ≥ ε).
fn clip_near(poly: &[Vert], eps: f64) -> Vec<Vert> {
    let mut out = Vec::with_capacity(poly.len() + 2);
    for i in 0..poly.len() {
        let (a, b) = (&poly[i], &poly[(i + 1) % poly.len()]);
        let (ia, ib) = (a.c[3] >= eps, b.c[3] >= eps);
        if ia {
            out.push(*a);
        }
        if ia != ib {
            let t = (eps - a.c[3]) / (b.c[3] - a.c[3]);
            out.push(a.lerp(b, t));
        }
    }
    out
}

fn edge_raw(a: [f64; 3], b: [f64; 3], x: f64, y: f64) -> f64 {
    (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
}

/// Edge function evaluated in a canonical vertex order, so that two triangles sharing an edge
/// get exactly opposite values (and the fill rule leaves no holes).
fn edge(a: [f64; 3], b: [f64; 3], x: f64, y: f64) -> f64 {
    if (a[0], a[1]) <= (b[0], b[1]) {
        edge_raw(a, b, x, y)
    } else {
        -edge_raw(b, a, x, y)
    }
}

/// The edge a→b as coefficients (A, B, C) with e(x, y) = A·x + B·y + C, computed in a
/// canonical vertex order so that two triangles sharing the edge get exactly opposite
/// coefficients.
fn edge_eq(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    let (p, q, sign) = if (a[0], a[1]) <= (b[0], b[1]) {
        (a, b, 1.0)
    } else {
        (b, a, -1.0)
    };
    let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
    // (q − p) × (P − p) = dx·(y − py) − dy·(x − px)
    [-dy * sign, dx * sign, (dy * p[0] - dx * p[1]) * sign]
}

/// Top-left rule for an edge a→b of a triangle with positive area in this orientation.
fn top_left(a: [f64; 3], b: [f64; 3], positive: bool) -> bool {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    // In screen space (y down), with the triangle oriented so interior edge values are
    // positive: a "top" edge is horizontal with the interior below, a "left" edge goes up.
    if positive {
        (dy == 0.0 && dx < 0.0) || dy > 0.0
    } else {
        (dy == 0.0 && dx > 0.0) || dy < 0.0
    }
}

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

/// World-space meshes of all objects for one eye (tessellation adapted to projected size).
fn build_meshes(scene: &Scene, eye: &Eye) -> Vec<Mesh> {
    let n = resolutions(scene, eye);
    scene
        .objects
        .par_iter()
        .zip(n.par_iter())
        .map(|(o, &k)| match &o.geometry {
            Geometry::Patches(p) => tessellate(p, k).transformed(&o.transform),
            Geometry::Mesh(m) => m.transformed(&o.transform),
            // Ray-marched per pixel instead.
            Geometry::QuaternionJulia(_) => Mesh::default(),
        })
        .collect()
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

/// A visible surface point, ready for shading (both renderers).
pub(crate) struct SurfacePoint {
    pub(crate) object: usize,
    pub(crate) pos: DVec3,
    pub(crate) normal: DVec3,
    pub(crate) st: [f64; 2],
    /// Largest change of (s, t) per pixel (mipmap level).
    pub(crate) footprint: f32,
    /// Texture tangents ∂P/∂s and ∂P/∂t (zero: no bump mapping).
    pub(crate) ts: DVec3,
    pub(crate) tt: DVec3,
}

/// Texture, Blinn bump mapping and the lighting model at one surface point; `visible(j)`
/// says whether light j reaches it (shadows).
pub(crate) fn shade(
    scene: &Scene,
    eye_pos: DVec3,
    p: &SurfacePoint,
    visible: &dyn Fn(usize) -> bool,
) -> Vec3 {
    let obj = &scene.objects[p.object];
    let st = p.st;
    let mut normal = p.normal;
    let tex = obj
        .texture
        .and_then(|i| scene.textures.get(i))
        .map_or(Vec3::ONE, |tx| {
            tx.sample(st[0] as f32, st[1] as f32, p.footprint)
        });
    if obj.material.bump != 0.0
        && let Some(bt) = obj
            .bump_texture
            .or(obj.texture)
            .and_then(|i| scene.textures.get(i))
    {
        let (ds, dt) = bt.texel_step();
        let (s0, t0) = (st[0] as f32, st[1] as f32);
        let ps = (bt.height(s0 + ds, t0) - bt.height(s0 - ds, t0)) as f64 / (2.0 * ds as f64);
        let pt = (bt.height(s0, t0 + dt) - bt.height(s0, t0 - dt)) as f64 / (2.0 * dt as f64);
        let (qs, qt) = (p.ts, p.tt);
        let mut nb = bump_normal(qs, qt, ps * obj.material.bump, pt * obj.material.bump);
        let n0 = qs.cross(qt);
        if n0.dot(normal) < 0.0 {
            // The tangent frame is left-handed relative to the shading normal.
            nb = -bump_normal(qt, qs, pt * obj.material.bump, ps * obj.material.bump);
        }
        if nb.length_squared() > 0.0 {
            normal = nb;
        }
    }
    illuminate_visible(
        &obj.material,
        tex,
        normal,
        p.pos,
        eye_pos,
        &scene.lights,
        scene.ambient,
        scene.attenuation_k,
        scene.blinn,
        visible,
    )
}

/// Bytes per tessellated vertex while rendering: the mesh (position, normal, texture
/// coordinates, tangents) and its transformed copy, the clipped vertex array (with the copy
/// made while it is filled) and the screen positions.
const BYTES_PER_VERTEX: u64 = 2 * (24 + 24 + 8 + 48) + 2 * std::mem::size_of::<Vert>() as u64 + 24;
/// Bytes per triangle: its indices in the mesh, the screen triangle (with the slack of a
/// growing vector) and its entries in the row bins.
const BYTES_PER_TRIANGLE: u64 = 12 + 3 * std::mem::size_of::<Tri>() as u64 / 2 + 16;

/// Memory a scene render needs, part by part, estimated before tessellating.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MemoryEstimate {
    /// Vertices and triangles after tessellation (all eyes).
    pub vertices: u64,
    pub triangles: u64,
    /// Meshes, clipped vertices, screen triangles and their bins.
    pub geometry: u64,
    /// Colour buffers at the supersampled size and the output image.
    pub pixels: u64,
    pub total: u64,
}

/// The pixel size a scene renders at (supersampled), and the eyes with their widths.
fn eyes(scene: &Scene) -> (usize, usize, Vec<(Eye, usize)>) {
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
        Renderer::ZBuffer => vertices
            .saturating_mul(BYTES_PER_VERTEX)
            .saturating_add(triangles.saturating_mul(BYTES_PER_TRIANGLE)),
        // The ray caster keeps the world meshes, a bounding volume hierarchy and one
        // reference (16 bytes) per triangle.
        Renderer::RayCast => vertices
            .saturating_mul(104)
            .saturating_add(super::bvh::bytes_for(triangles as usize) as u64)
            .saturating_add(triangles.saturating_mul(16)),
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
    #[error("{0}")]
    Settings(String),
    #[error(transparent)]
    OutOfMemory(#[from] crate::memory::MemoryError),
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

const BAND: usize = 16;

/// Render one eye into a w×h buffer (linear RGB).
fn render_eye(
    scene: &Scene,
    eye: &Eye,
    w: usize,
    h: usize,
    cancel: Option<&AtomicBool>,
) -> Option<Vec<Vec3>> {
    let meshes = build_meshes(scene, eye);
    // Shared vertex array: every mesh's vertices, then the vertices made by clipping.
    let mut verts: Vec<Vert> = Vec::with_capacity(meshes.iter().map(|m| m.positions.len()).sum());
    let mut bases = Vec::with_capacity(meshes.len());
    for m in &meshes {
        bases.push(verts.len() as u32);
        verts.par_extend((0..m.positions.len()).into_par_iter().map(|i| Vert {
            c: eye.clip(m.positions[i]),
            pos: m.positions[i],
            normal: m.normals[i],
            tex: [m.tex[i][0] as f64, m.tex[i][1] as f64],
            ts: m.tangents.get(i).map_or(DVec3::X, |t| t.0),
            tt: m.tangents.get(i).map_or(DVec3::Y, |t| t.1),
        }));
    }
    let screen: Vec<[f64; 3]> = verts.par_iter().map(|v| eye.screen(v.c)).collect();
    let make_tri = |idx: [u32; 3], s: [[f64; 3]; 3], object: u32, vv: [&Vert; 3]| -> Option<Tri> {
        let area = edge(s[0], s[1], s[2][0], s[2][1]);
        if area == 0.0 || !area.is_finite() {
            return None;
        }
        let ymin = s.iter().map(|p| p[1]).fold(f64::MAX, f64::min);
        let ymax = s.iter().map(|p| p[1]).fold(f64::MIN, f64::max);
        let xmin = s.iter().map(|p| p[0]).fold(f64::MAX, f64::min);
        let xmax = s.iter().map(|p| p[0]).fold(f64::MIN, f64::max);
        if ymax < 0.0 || ymin > h as f64 || xmax < 0.0 || xmin > w as f64 {
            return None;
        }
        let pos = area > 0.0;
        let sg = if pos { 1.0 } else { -1.0 };
        let e = [
            edge_eq(s[1], s[2]),
            edge_eq(s[2], s[0]),
            edge_eq(s[0], s[1]),
        ]
        .map(|q| q.map(|v| v * sg));
        let on_edge = [
            top_left(s[1], s[2], pos),
            top_left(s[2], s[0], pos),
            top_left(s[0], s[1], pos),
        ];
        let c = [
            (s[0][0] + s[1][0] + s[2][0]) / 3.0,
            (s[0][1] + s[1][1] + s[2][1]) / 3.0,
        ];
        let mut t = Tri {
            idx,
            s,
            e,
            on_edge,
            inv_area: 1.0 / area.abs(),
            object,
            footprint: 0.0,
            y0: (ymin - 0.5).ceil().max(0.0) as i64,
            y1: ((ymax - 0.5).floor() as i64).min(h as i64 - 1),
        };
        t.footprint = footprint(&t, vv, c) as f32;
        Some(t)
    };
    let mut extra: Vec<Vert> = Vec::new();
    let (vref, sref, bref, mk) = (&verts, &screen, &bases, &make_tri);
    let mut tris: Vec<Tri> = meshes
        .par_iter()
        .enumerate()
        .flat_map_iter(|(oi, m)| {
            let base = bref[oi];
            m.triangles.iter().filter_map(move |t| {
                let idx = t.map(|i| i + base);
                let vv = idx.map(|i| &vref[i as usize]);
                if vv.iter().all(|v| v.c[3] >= 1e-3) {
                    mk(idx, idx.map(|i| sref[i as usize]), oi as u32, vv)
                } else {
                    None
                }
            })
        })
        .collect();
    // Triangles crossing the near plane: clip (rare; sequential).
    for (oi, m) in meshes.iter().enumerate() {
        let base = bases[oi];
        for t in &m.triangles {
            let idx = t.map(|i| i + base);
            let poly = idx.map(|i| verts[i as usize]);
            if poly.iter().all(|v| v.c[3] >= 1e-3) {
                continue;
            }
            let clipped = clip_near(&poly, 1e-3);
            for k in 1..clipped.len().saturating_sub(1) {
                let first = (verts.len() + extra.len()) as u32;
                let tri_v = [clipped[0], clipped[k], clipped[k + 1]];
                let s3 = tri_v.map(|v| eye.screen(v.c));
                if let Some(t) = make_tri(
                    [first, first + 1, first + 2],
                    s3,
                    oi as u32,
                    [&tri_v[0], &tri_v[1], &tri_v[2]],
                ) {
                    extra.extend(tri_v);
                    tris.push(t);
                }
            }
        }
    }
    verts.extend(extra);
    // Bin triangles into bands of rows.
    let nb = h.div_ceil(BAND);
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); nb];
    for (i, t) in tris.iter().enumerate() {
        if t.y1 < t.y0 {
            continue;
        }
        let (b0, b1) = (t.y0 as usize / BAND, ((t.y1 as usize) / BAND).min(nb - 1));
        for bin in &mut bins[b0..=b1] {
            bin.push(i as u32);
        }
    }
    let implicit = super::raycast::implicit_objects(scene);
    let mut eye = *eye;
    if !implicit.is_empty() {
        eye.place_ray_start(scene);
    }
    let eye = &eye;
    let mut color = vec![scene.background; w * h];
    let stopped = AtomicBool::new(false);
    color
        .par_chunks_mut(w * BAND)
        .zip(bins.par_iter())
        .enumerate()
        .for_each(|(b, (out, bin))| {
            if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
                stopped.store(true, Ordering::Relaxed);
                return;
            }
            let rows = out.len() / w;
            let y_base = b * BAND;
            // Visibility pass: depth, triangle and barycentrics per pixel.
            let mut depth = vec![f64::NEG_INFINITY; w * rows];
            let mut hit = vec![(u32::MAX, 0.0f64, 0.0f64); w * rows];
            for &ti in bin {
                let t = &tris[ti as usize];
                let s = t.s;
                let xmin = s.iter().map(|p| p[0]).fold(f64::MAX, f64::min);
                let xmax = s.iter().map(|p| p[0]).fold(f64::MIN, f64::max);
                let x0 = (xmin - 0.5).ceil().max(0.0) as usize;
                let x1 = ((xmax - 0.5).floor() as i64).min(w as i64 - 1);
                if x1 < x0 as i64 {
                    continue;
                }
                let ya = t.y0.max(y_base as i64);
                let yb = t.y1.min((y_base + rows) as i64 - 1);
                let [e0, e1, e2] = t.e;
                for y in ya..=yb {
                    let py = y as f64 + 0.5;
                    let row = (y as usize - y_base) * w;
                    for x in x0..=x1 as usize {
                        let px = x as f64 + 0.5;
                        let v0 = e0[0] * px + e0[1] * py + e0[2];
                        let v1 = e1[0] * px + e1[1] * py + e1[2];
                        let v2 = e2[0] * px + e2[1] * py + e2[2];
                        if v0 < 0.0 || v1 < 0.0 || v2 < 0.0 {
                            continue;
                        }
                        if (v0 == 0.0 && !t.on_edge[0])
                            || (v1 == 0.0 && !t.on_edge[1])
                            || (v2 == 0.0 && !t.on_edge[2])
                        {
                            continue;
                        }
                        let (b0, b1, b2) = (v0 * t.inv_area, v1 * t.inv_area, v2 * t.inv_area);
                        // z* = z/w is affine in screen space.
                        let z = b0 * s[0][2] + b1 * s[1][2] + b2 * s[2][2];
                        let k = row + x;
                        if z > depth[k] {
                            depth[k] = z;
                            hit[k] = (ti, b1, b2);
                        }
                    }
                }
            }
            // Quaternion Julia objects: ray-marched per pixel, kept where nearer.
            let mut marched: Vec<(u32, f64)> = Vec::new();
            if !implicit.is_empty() {
                marched = vec![(u32::MAX, 0.0); w * rows];
                for r in 0..rows {
                    let py = (y_base + r) as f64 + 0.5;
                    for x in 0..w {
                        let (o, d, t_min) = eye.ray(x as f64 + 0.5, py);
                        let k = r * w + x;
                        for (ii, im) in implicit.iter().enumerate() {
                            let Some(t) = im.hit(o, d, t_min, f64::INFINITY, eye) else {
                                continue;
                            };
                            let c = eye.clip(o + d * t);
                            let z = c[2] / c[3];
                            if z > depth[k] {
                                depth[k] = z;
                                hit[k].0 = u32::MAX;
                                marched[k] = (ii as u32, t);
                            }
                        }
                    }
                }
            }
            // Shading pass: each visible pixel once.
            for (k, &(ti, b1, b2)) in hit.iter().enumerate() {
                if let Some(&(ii, t)) = marched.get(k).filter(|m| m.0 != u32::MAX) {
                    let (x, r) = (k % w, k / w);
                    let (o, d, _) = eye.ray(x as f64 + 0.5, (y_base + r) as f64 + 0.5);
                    let (p, _) = implicit[ii as usize].surface_point(o, d, t, eye);
                    out[k] = shade(scene, eye.pos, &p, &|_| true);
                    continue;
                }
                if ti == u32::MAX {
                    continue;
                }
                let t = &tris[ti as usize];
                let v = t.idx.map(|i| &verts[i as usize]);
                let b0 = 1.0 - b1 - b2;
                // Perspective-correct weights.
                let iw = [b0 / v[0].c[3], b1 / v[1].c[3], b2 / v[2].c[3]];
                let sum = iw[0] + iw[1] + iw[2];
                let wt = [iw[0] / sum, iw[1] / sum, iw[2] / sum];
                let mix3 = |f: &dyn Fn(&Vert) -> DVec3| {
                    f(v[0]) * wt[0] + f(v[1]) * wt[1] + f(v[2]) * wt[2]
                };
                let pos = mix3(&|v| v.pos);
                let normal = mix3(&|v| v.normal);
                let st = [
                    v[0].tex[0] * wt[0] + v[1].tex[0] * wt[1] + v[2].tex[0] * wt[2],
                    v[0].tex[1] * wt[0] + v[1].tex[1] * wt[1] + v[2].tex[1] * wt[2],
                ];
                let p = SurfacePoint {
                    object: t.object as usize,
                    pos,
                    normal,
                    st,
                    footprint: t.footprint,
                    ts: mix3(&|v| v.ts),
                    tt: mix3(&|v| v.tt),
                };
                out[k] = shade(scene, eye.pos, &p, &|_| true);
            }
        });
    if stopped.load(Ordering::Relaxed) {
        return None;
    }
    Some(color)
}

/// Largest change of (s, t) per pixel at screen point p (perspective-correct derivative),
/// used once per triangle (at its centroid) to choose the mipmap level.
fn footprint(t: &Tri, v: [&Vert; 3], p: [f64; 2]) -> f64 {
    let s = t.s;
    let area = edge(s[0], s[1], s[2][0], s[2][1]);
    let at = |x: f64, y: f64| {
        let b = [
            edge(s[1], s[2], x, y) / area,
            edge(s[2], s[0], x, y) / area,
            edge(s[0], s[1], x, y) / area,
        ];
        let iw = [b[0] / v[0].c[3], b[1] / v[1].c[3], b[2] / v[2].c[3]];
        let sum = iw[0] + iw[1] + iw[2];
        let wt = [iw[0] / sum, iw[1] / sum, iw[2] / sum];
        [
            v[0].tex[0] * wt[0] + v[1].tex[0] * wt[1] + v[2].tex[0] * wt[2],
            v[0].tex[1] * wt[0] + v[1].tex[1] * wt[1] + v[2].tex[1] * wt[2],
        ]
    };
    let c = at(p[0], p[1]);
    let dx = at(p[0] + 1.0, p[1]);
    let dy = at(p[0], p[1] + 1.0);
    let fx = (dx[0] - c[0]).abs().max((dx[1] - c[1]).abs());
    let fy = (dy[0] - c[0]).abs().max((dy[1] - c[1]).abs());
    fx.max(fy)
}

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

impl Eye {
    /// Let parallel rays start in front of every object's bounding sphere (perspective rays
    /// start at the eye and need nothing).
    pub(crate) fn place_ray_start(&mut self, scene: &Scene) {
        if self.k.is_some() {
            return;
        }
        let mut z = scene.camera.distance;
        for o in &scene.objects {
            if let Some((c, r)) = super::raycast::world_sphere(o) {
                z = z.max(self.view.apply(c).z + r);
            }
        }
        self.ray_z = z + 1.0;
    }
}

pub(crate) fn to_image(buf: &[Vec3], w: usize, h: usize, ss: usize) -> RgbImage {
    let (ow, oh) = (w / ss, h / ss);
    let mut img = RgbImage::new(ow as u32, oh as u32);
    let n = (ss * ss) as f32;
    for y in 0..oh {
        for x in 0..ow {
            let mut c = Vec3::ZERO;
            for dy in 0..ss {
                for dx in 0..ss {
                    c += buf[(y * ss + dy) * w + x * ss + dx];
                }
            }
            let c = (c / n).clamp(Vec3::ZERO, Vec3::ONE) * 255.0 + Vec3::splat(0.5);
            img.put_pixel(
                x as u32,
                y as u32,
                image::Rgb([c.x as u8, c.y as u8, c.z as u8]),
            );
        }
    }
    img
}

/// Render the scene with the z-buffer (width×height; a stereo pair puts the left eye on the
/// left half), without the size and memory check of [`try_render`]. None when cancelled.
pub fn render_zbuffer(scene: &Scene, cancel: Option<&AtomicBool>) -> Option<RgbImage> {
    zbuffer(scene, cancel).ok()
}

/// Render the scene with its renderer (z-buffer or ray casting) after checking its size and
/// memory ([`check`]). Cancelling returns [`RenderError::Cancelled`].
pub fn try_render(scene: &Scene, cancel: Option<&AtomicBool>) -> Result<RgbImage, RenderError> {
    check(scene, None)?;
    match scene.renderer {
        Renderer::ZBuffer => zbuffer(scene, cancel),
        Renderer::RayCast => super::raycast::render(scene, cancel).ok_or(RenderError::Cancelled),
    }
}

fn zbuffer(scene: &Scene, cancel: Option<&AtomicBool>) -> Result<RgbImage, RenderError> {
    let ss = scene.supersample.clamp(1, 4) as usize;
    let (w, h, eyes) = eyes(scene);
    if let [(left_eye, half), (right_eye, _)] = eyes.as_slice() {
        let half = *half;
        let left = render_eye(scene, left_eye, half, h, cancel).ok_or(RenderError::Cancelled)?;
        let right = render_eye(scene, right_eye, half, h, cancel).ok_or(RenderError::Cancelled)?;
        let mut buf = vec![scene.background; w * h];
        for y in 0..h {
            buf[y * w..y * w + half].copy_from_slice(&left[y * half..(y + 1) * half]);
            buf[y * w + half..y * w + 2 * half].copy_from_slice(&right[y * half..(y + 1) * half]);
        }
        return Ok(to_image(&buf, w, h, ss));
    }
    let (eye, _) = &eyes[0];
    let buf = render_eye(scene, eye, w, h, cancel).ok_or(RenderError::Cancelled)?;
    Ok(to_image(&buf, w, h, ss))
}

/// As [`try_render`], None for every failure (cancelled, too large, invalid size); kept for
/// callers that only show a picture when there is one.
pub fn render(scene: &Scene, cancel: Option<&AtomicBool>) -> Option<RgbImage> {
    try_render(scene, cancel).ok()
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

#[cfg(test)]
mod tests {
    use super::*;

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
                geometry: Geometry::Patches(crate::surface::mesh::jug()),
                transform: Transform::IDENTITY,
                material: crate::surface::scene::Material::default(),
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
    use crate::surface::mesh::{SurfacePatch, TexMap};
    use crate::surface::patch::Patch;
    use crate::surface::scene::{Light, Material, Object};

    #[test]
    fn perspective_correct_and_bump_oracles() {
        assert!((perspective_lerp(0.0, 1.0, 1.0, 3.0, 0.5) - 0.25).abs() < 1e-15);
        // Q = (u, w, 0), P = 0.1u → n′ = (−0.1, 0, 1).
        let n = bump_normal(DVec3::X, DVec3::Y, 0.1, 0.0);
        assert!((n - DVec3::new(-0.1, 0.0, 1.0)).length() < 1e-15);
    }

    fn quad_scene(z: f64) -> Scene {
        let p = Patch::Bilinear {
            p: [
                DVec3::new(-1.0, -1.0, z),
                DVec3::new(-1.0, 1.0, z),
                DVec3::new(1.0, -1.0, z),
                DVec3::new(1.0, 1.0, z),
            ],
        };
        let mut s = Scene {
            width: 64,
            height: 48,
            ..Scene::default()
        };
        s.camera.target = DVec3::ZERO;
        s.camera.azimuth_deg = 0.0;
        s.camera.polar_deg = 90.0;
        s.camera.distance = 5.0;
        s.lights = vec![Light {
            position: DVec3::new(0.0, 0.0, 10.0),
            intensity: Vec3::splat(6.0),
        }];
        s.objects.push(Object {
            name: "quad".into(),
            geometry: Geometry::Patches(vec![SurfacePatch {
                patch: p,
                tex: TexMap::default(),
            }]),
            transform: Transform::IDENTITY,
            material: Material::default(),
            texture: None,
            bump_texture: None,
        });
        s
    }

    #[test]
    fn z_buffer_keeps_the_nearest_and_pixels_are_covered_once() {
        // A red quad in front of a green one: only red is visible where they overlap.
        let mut s = quad_scene(0.5);
        let back = quad_scene(-0.5).objects.remove(0);
        s.objects[0].material.color = Vec3::new(1.0, 0.0, 0.0);
        let mut b = back;
        b.material.color = Vec3::new(0.0, 1.0, 0.0);
        s.objects.push(b);
        let img = render_zbuffer(&s, None).unwrap();
        let c = img.get_pixel(32, 24).0;
        // Red diffuse plus a white highlight: red dominates, no green surface shows.
        assert!(c[0] as i32 > c[1] as i32 + 100 && c[1] == c[2], "{c:?}");
        // Reverse the order: same picture (depth, not drawing order, decides).
        s.objects.swap(0, 1);
        assert_eq!(render_zbuffer(&s, None).unwrap(), img);
        // The quad's two triangles share a diagonal: no pixel is left out along it (the
        // top-left rule covers each once), so the covered area is one solid rectangle.
        let single = render_zbuffer(&quad_scene(0.0), None).unwrap();
        let lit: Vec<(u32, u32)> = single
            .enumerate_pixels()
            .filter(|(_, _, p)| p.0 != [0, 0, 0])
            .map(|(x, y, _)| (x, y))
            .collect();
        let (x0, x1) = (
            lit.iter().map(|p| p.0).min().unwrap(),
            lit.iter().map(|p| p.0).max().unwrap(),
        );
        let (y0, y1) = (
            lit.iter().map(|p| p.1).min().unwrap(),
            lit.iter().map(|p| p.1).max().unwrap(),
        );
        assert_eq!(lit.len() as u32, (x1 - x0 + 1) * (y1 - y0 + 1));
    }

    #[test]
    fn near_plane_clipping_keeps_output_finite() {
        // The quad passes through the eye plane: clipped, no panic, something drawn.
        let mut s = quad_scene(0.0);
        s.objects[0].transform = Transform::rot_x(1.4).then(&Transform::translate(0.0, 0.0, 4.5));
        let img = render_zbuffer(&s, None).unwrap();
        assert!(img.pixels().any(|p| p.0 != [0, 0, 0]));
    }

    #[test]
    fn stereo_pair_shifts_the_eyes() {
        let mut s = quad_scene(0.0);
        s.width = 128;
        s.camera.projection = Projection::Stereo;
        let img = render_zbuffer(&s, None).unwrap();
        assert_eq!(img.width(), 128);
        let centroid = |x0: u32, x1: u32| {
            let mut sum = 0.0;
            let mut n = 0.0;
            for y in 0..48 {
                for x in x0..x1 {
                    if img.get_pixel(x, y).0 != [0, 0, 0] {
                        sum += (x - x0) as f64;
                        n += 1.0;
                    }
                }
            }
            sum / n
        };
        // An object at z = 0 shifts right in the left image (A) and left in the right one.
        assert!(centroid(0, 64) > 32.0 && centroid(64, 128) < 32.0);
    }
}
