//! The z-buffer renderer: adaptive tessellation, near-plane clipping, z-buffer with a top-left
//! fill rule (larger z nearer), perspective-correct attributes, deferred per-pixel shading,
//! parallel bands of rows; quaternion Julia objects are ray-marched per pixel and kept where
//! nearer.

use std::sync::atomic::{AtomicBool, Ordering};

use glam::{DVec3, Vec3};
use image::RgbImage;
use rayon::prelude::*;

use super::eye::Eye;
use super::frame::picture;
use super::implicit::{Implicit, implicit_objects};
use super::mesh::{Mesh, tessellate};
use super::resolution::resolutions;
use super::scene::{Geometry, Scene};
use super::shading::{SurfacePoint, shade};

/// Attribute interpolated perspective-correctly: a/w and 1/w are affine in screen space.
#[cfg(test)]
pub fn perspective_lerp(a0: f64, a1: f64, w0: f64, w1: f64, t: f64) -> f64 {
    let num = (1.0 - t) * a0 / w0 + t * a1 / w1;
    let den = (1.0 - t) / w0 + t / w1;
    num / den
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

/// Bytes per tessellated vertex while rendering: the mesh (position, normal, texture
/// coordinates, tangents) and its transformed copy, the clipped vertex array (with the copy
/// made while it is filled) and the screen positions.
const BYTES_PER_VERTEX: u64 = 2 * (24 + 24 + 8 + 48) + 2 * std::mem::size_of::<Vert>() as u64 + 24;
/// Bytes per triangle: its indices in the mesh, the screen triangle (with the slack of a
/// growing vector) and its entries in the row bins.
const BYTES_PER_TRIANGLE: u64 = 12 + 3 * std::mem::size_of::<Tri>() as u64 / 2 + 16;

/// Bytes of the z-buffer's geometry for a tessellation of `vertices` and `triangles`.
pub(crate) fn geometry_bytes(vertices: u64, triangles: u64) -> u64 {
    vertices
        .saturating_mul(BYTES_PER_VERTEX)
        .saturating_add(triangles.saturating_mul(BYTES_PER_TRIANGLE))
}

/// Rows per band: the unit of parallel work, with its own depth buffer.
const BAND: usize = 16;

/// Render one eye into a w×h buffer (linear RGB); None when cancelled.
fn render_eye(
    scene: &Scene,
    eye: &Eye,
    w: usize,
    h: usize,
    cancel: Option<&AtomicBool>,
) -> Option<Vec<Vec3>> {
    let meshes = build_meshes(scene, eye);
    let (mut verts, bases) = clip_vertices(&meshes, eye);
    let screen: Vec<[f64; 3]> = verts.par_iter().map(|v| eye.screen(v.c)).collect();
    let mut tris = visible_triangles(&meshes, &verts, &screen, &bases, w, h);
    let extra = clip_crossing(&meshes, &verts, &bases, eye, w, h, &mut tris);
    verts.extend(extra);
    let bins = bin_rows(&tris, h);
    let implicit = implicit_objects(scene);
    let mut eye = *eye;
    if !implicit.is_empty() {
        eye.place_ray_start(scene);
    }
    let frame = Frame {
        scene,
        eye: &eye,
        w,
        tris: &tris,
        verts: &verts,
        implicit: &implicit,
    };
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
            frame.band(b * BAND, out, bin);
        });
    if stopped.load(Ordering::Relaxed) {
        return None;
    }
    Some(color)
}

/// The shared vertex array of all meshes in clip coordinates, and where each mesh's vertices
/// start in it.
fn clip_vertices(meshes: &[Mesh], eye: &Eye) -> (Vec<Vert>, Vec<u32>) {
    let mut verts: Vec<Vert> = Vec::with_capacity(meshes.iter().map(|m| m.positions.len()).sum());
    let mut bases = Vec::with_capacity(meshes.len());
    for m in meshes {
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
    (verts, bases)
}

/// The screen triangle of vertices `idx` at screen points `s`, with its edge equations, rows
/// and texture footprint; None when degenerate or outside the w×h picture.
fn screen_triangle(
    idx: [u32; 3],
    s: [[f64; 3]; 3],
    object: u32,
    vv: [&Vert; 3],
    w: usize,
    h: usize,
) -> Option<Tri> {
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
}

/// The screen triangles of every mesh triangle wholly in front of the near plane.
fn visible_triangles(
    meshes: &[Mesh],
    verts: &[Vert],
    screen: &[[f64; 3]],
    bases: &[u32],
    w: usize,
    h: usize,
) -> Vec<Tri> {
    meshes
        .par_iter()
        .enumerate()
        .flat_map_iter(|(oi, m)| {
            let base = bases[oi];
            m.triangles.iter().filter_map(move |t| {
                let idx = t.map(|i| i + base);
                let vv = idx.map(|i| &verts[i as usize]);
                if vv.iter().all(|v| v.c[3] >= 1e-3) {
                    screen_triangle(idx, idx.map(|i| screen[i as usize]), oi as u32, vv, w, h)
                } else {
                    None
                }
            })
        })
        .collect()
}

/// Triangles crossing the near plane: clipped (rare; sequential), their pieces added to
/// `tris`. Returns the vertices made by clipping, which follow `verts`.
fn clip_crossing(
    meshes: &[Mesh],
    verts: &[Vert],
    bases: &[u32],
    eye: &Eye,
    w: usize,
    h: usize,
    tris: &mut Vec<Tri>,
) -> Vec<Vert> {
    let mut extra: Vec<Vert> = Vec::new();
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
                if let Some(t) = screen_triangle(
                    [first, first + 1, first + 2],
                    s3,
                    oi as u32,
                    [&tri_v[0], &tri_v[1], &tri_v[2]],
                    w,
                    h,
                ) {
                    extra.extend(tri_v);
                    tris.push(t);
                }
            }
        }
    }
    extra
}

/// The triangles of every band of rows, by index.
fn bin_rows(tris: &[Tri], h: usize) -> Vec<Vec<u32>> {
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
    bins
}

/// What every band of rows reads: the scene, the eye, the picture width, the screen triangles
/// with their vertices and the ray-marched objects.
struct Frame<'a> {
    scene: &'a Scene,
    eye: &'a Eye,
    w: usize,
    tris: &'a [Tri],
    verts: &'a [Vert],
    implicit: &'a [Implicit],
}

/// No triangle: the background, or a ray-marched object.
const NO_TRIANGLE: u32 = u32::MAX;

impl Frame<'_> {
    /// Render the rows from `y_base` into `out` (whole rows): the band's triangles `bin` by
    /// depth, the ray-marched objects where nearer, then each visible pixel shaded once.
    fn band(&self, y_base: usize, out: &mut [Vec3], bin: &[u32]) {
        let w = self.w;
        let rows = out.len() / w;
        // Visibility pass: depth, triangle and barycentrics per pixel.
        let mut depth = vec![f64::NEG_INFINITY; w * rows];
        let mut hit = vec![(NO_TRIANGLE, 0.0f64, 0.0f64); w * rows];
        for &ti in bin {
            self.rasterise(ti, y_base, rows, &mut depth, &mut hit);
        }
        // Quaternion Julia objects: ray-marched per pixel, kept where nearer.
        let mut marched: Vec<(u32, f64)> = Vec::new();
        if !self.implicit.is_empty() {
            marched = self.march(y_base, rows, &mut depth, &mut hit);
        }
        // Shading pass: each visible pixel once.
        for (k, &(ti, b1, b2)) in hit.iter().enumerate() {
            if let Some(&(ii, t)) = marched.get(k).filter(|m| m.0 != u32::MAX) {
                let (x, r) = (k % w, k / w);
                let (o, d, _) = self.eye.ray(x as f64 + 0.5, (y_base + r) as f64 + 0.5);
                let (p, _) = self.implicit[ii as usize].surface_point(o, d, t, self.eye);
                out[k] = shade(self.scene, self.eye.pos, &p, &|_| true);
                continue;
            }
            if ti == NO_TRIANGLE {
                continue;
            }
            let p = self.surface_point(&self.tris[ti as usize], b1, b2);
            out[k] = shade(self.scene, self.eye.pos, &p, &|_| true);
        }
    }

    /// Draw triangle `ti` into the band's depth buffer: each covered pixel centre (top-left
    /// rule on shared edges) keeps the nearest triangle and its barycentrics.
    fn rasterise(
        &self,
        ti: u32,
        y_base: usize,
        rows: usize,
        depth: &mut [f64],
        hit: &mut [(u32, f64, f64)],
    ) {
        let w = self.w;
        let t = &self.tris[ti as usize];
        let s = t.s;
        let xmin = s.iter().map(|p| p[0]).fold(f64::MAX, f64::min);
        let xmax = s.iter().map(|p| p[0]).fold(f64::MIN, f64::max);
        let x0 = (xmin - 0.5).ceil().max(0.0) as usize;
        let x1 = ((xmax - 0.5).floor() as i64).min(w as i64 - 1);
        if x1 < x0 as i64 {
            return;
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

    /// March every pixel's ray into the quaternion Julia objects: per pixel (object, ray
    /// parameter) where one is nearer than the triangles (`u32::MAX`: none).
    fn march(
        &self,
        y_base: usize,
        rows: usize,
        depth: &mut [f64],
        hit: &mut [(u32, f64, f64)],
    ) -> Vec<(u32, f64)> {
        let (w, eye) = (self.w, self.eye);
        let mut marched = vec![(u32::MAX, 0.0); w * rows];
        for r in 0..rows {
            let py = (y_base + r) as f64 + 0.5;
            for x in 0..w {
                let (o, d, t_min) = eye.ray(x as f64 + 0.5, py);
                let k = r * w + x;
                for (ii, im) in self.implicit.iter().enumerate() {
                    let Some(t) = im.hit(o, d, t_min, f64::INFINITY, eye) else {
                        continue;
                    };
                    let c = eye.clip(o + d * t);
                    let z = c[2] / c[3];
                    if z > depth[k] {
                        depth[k] = z;
                        hit[k].0 = NO_TRIANGLE;
                        marched[k] = (ii as u32, t);
                    }
                }
            }
        }
        marched
    }

    /// The surface point at barycentrics (b1, b2) of a screen triangle, its attributes
    /// interpolated perspective-correctly.
    fn surface_point(&self, t: &Tri, b1: f64, b2: f64) -> SurfacePoint {
        let v = t.idx.map(|i| &self.verts[i as usize]);
        let b0 = 1.0 - b1 - b2;
        // Perspective-correct weights.
        let iw = [b0 / v[0].c[3], b1 / v[1].c[3], b2 / v[2].c[3]];
        let sum = iw[0] + iw[1] + iw[2];
        let wt = [iw[0] / sum, iw[1] / sum, iw[2] / sum];
        let mix3 = |f: &dyn Fn(&Vert) -> DVec3| f(v[0]) * wt[0] + f(v[1]) * wt[1] + f(v[2]) * wt[2];
        let pos = mix3(&|v| v.pos);
        let normal = mix3(&|v| v.normal);
        let st = [
            v[0].tex[0] * wt[0] + v[1].tex[0] * wt[1] + v[2].tex[0] * wt[2],
            v[0].tex[1] * wt[0] + v[1].tex[1] * wt[1] + v[2].tex[1] * wt[2],
        ];
        SurfacePoint {
            object: t.object as usize,
            pos,
            normal,
            st,
            footprint: t.footprint,
            ts: mix3(&|v| v.ts),
            tt: mix3(&|v| v.tt),
        }
    }
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

/// Render the scene with the z-buffer (width×height; a stereo pair puts the left eye on the
/// left half), without the size and memory check of [`super::try_render`]. None when
/// cancelled.
pub fn render_zbuffer(scene: &Scene, cancel: Option<&AtomicBool>) -> Option<RgbImage> {
    picture(scene, |eye, w, h| render_eye(scene, eye, w, h, cancel))
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::surface::mesh::{SurfacePatch, TexMap};
    use crate::surface::patch::Patch;
    use crate::surface::scene::{Light, Material, Object, Projection};
    use crate::surface::transform::Transform;

    #[test]
    fn perspective_correct_oracle() {
        assert!((perspective_lerp(0.0, 1.0, 1.0, 3.0, 0.5) - 0.25).abs() < 1e-15);
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
