//! The ray-casting renderer (the optional second hidden-surface method of Köse's 1990 thesis,
//! after Whitted 1980 and Kajiya 1982): one ray per pixel from the eye (or parallel rays for
//! parallel projections), the nearest hit along the ray is the visible one — the same as the
//! z-buffer's "largest z" — and a shadow ray towards every light.
//!
//! Per object, cheap tests come first (75–95 % of a ray caster's time goes into intersection
//! tests): the bounding sphere by the closest approach of the ray to its centre, then the
//! object's bounding box (the root of its hierarchy), then a bounding volume hierarchy over
//! the object's tessellation. A hit on a patch's tessellation is refined by Newton's method on
//! the exact patch (Kajiya's f(u, w) = g(u, w) = 0, here with the ray parameter as the third
//! unknown), so the shading point, normal and texture coordinates are those of the surface.
//! Quaternion Julia sets are found by distance-estimated ray marching.

use std::sync::atomic::{AtomicBool, Ordering};

use glam::{DMat3, DVec3, Vec3};
use image::RgbImage;
use rayon::prelude::*;

use super::bounds::world_sphere;
use super::bvh::{Bvh, TriGeom};
use super::eye::Eye;
use super::frame::picture;
use super::implicit::Implicit;
use super::mesh::{Mesh, SurfacePatch};
use super::patch::Patch;
use super::resolution::resolutions;
use super::scene::{Geometry, Object, Scene};
use super::shading::{SurfacePoint, shade};
use super::transform::Transform;

/// Closest approach of the line P(t) = P₁ + (P₂ − P₁)t to the point P₀: with
/// (a, b, c) = P₂ − P₁, t = −[a(x₁ − x₀) + b(y₁ − y₀) + c(z₁ − z₀)]/(a² + b² + c²), and the
/// squared distance |P(t) − P₀|² there. A bounding sphere of radius R around P₀ is missed when
/// that distance exceeds R². (The minus sign matters: without it t points away from P₀.)
pub fn closest_approach(p1: DVec3, p2: DVec3, p0: DVec3) -> (f64, f64) {
    let d = p2 - p1;
    let t = -d.dot(p1 - p0) / d.length_squared();
    (t, (p1 + d * t - p0).length_squared())
}

/// Does the ray o + t·d (unit d) pass within `r` of `c` somewhere in [t_min, t_max]?
fn sphere_may_hit(c: DVec3, r: f64, o: DVec3, d: DVec3, t_min: f64, t_max: f64) -> bool {
    let (t, d2) = closest_approach(o, o + d, c);
    d2 <= r * r && t + r >= t_min && t - r <= t_max
}

/// Which patch cell a triangle came from: patch, grid cell (i, j) and which half.
#[derive(Clone, Copy, Debug)]
struct PatchTri {
    patch: u32,
    i: u16,
    j: u16,
    upper: bool,
}

impl PatchTri {
    /// (u, w) of the triangle's vertices (the tessellation's winding).
    fn uw(&self, n: usize) -> [[f64; 2]; 3] {
        let f = |i: u16, j: u16| [i as f64 / n as f64, j as f64 / n as f64];
        let (i, j) = (self.i, self.j);
        if self.upper {
            [f(i, j), f(i + 1, j + 1), f(i, j + 1)]
        } else {
            [f(i, j), f(i + 1, j), f(i + 1, j + 1)]
        }
    }
}

enum Kind {
    Patches {
        bvh: Bvh,
        tris: Vec<PatchTri>,
        n: usize,
    },
    Mesh {
        bvh: Bvh,
        mesh: Mesh,
    },
    Implicit(Implicit),
}

struct Prepared {
    object: usize,
    centre: DVec3,
    radius: f64,
    kind: Kind,
}

/// What a ray hit.
#[derive(Clone, Copy, Debug)]
enum Hit {
    Tri {
        obj: usize,
        tri: u32,
        t: f64,
        b1: f64,
        b2: f64,
    },
    Implicit {
        obj: usize,
        t: f64,
    },
}

/// The scene made ready for rays: per object its bounding sphere and hierarchy.
struct World<'a> {
    scene: &'a Scene,
    objs: Vec<Prepared>,
    /// Offset of shadow-ray origins from the surface (world units).
    shadow_eps: f64,
}

/// Tessellate an object's patches in world space (the z-buffer's grid for this eye).
fn patch_triangles(o: &Object, p: &[SurfacePatch], n: usize) -> (Vec<TriGeom>, Vec<PatchTri>) {
    let mut geo = Vec::with_capacity(p.len() * n * n * 2);
    let mut refs = Vec::with_capacity(p.len() * n * n * 2);
    for (k, sp) in p.iter().enumerate() {
        let grid: Vec<DVec3> = (0..=n)
            .flat_map(|i| (0..=n).map(move |j| (i, j)))
            .map(|(i, j)| {
                o.transform
                    .apply(sp.patch.eval(i as f64 / n as f64, j as f64 / n as f64))
            })
            .collect();
        let at = |i: usize, j: usize| grid[i * (n + 1) + j];
        for i in 0..n {
            for j in 0..n {
                for upper in [false, true] {
                    let t = if upper {
                        TriGeom::new(at(i, j), at(i + 1, j + 1), at(i, j + 1))
                    } else {
                        TriGeom::new(at(i, j), at(i + 1, j), at(i + 1, j + 1))
                    };
                    if t.normal().length_squared() == 0.0 {
                        continue; // collapsed at a pole
                    }
                    geo.push(t);
                    refs.push(PatchTri {
                        patch: k as u32,
                        i: i as u16,
                        j: j as u16,
                        upper,
                    });
                }
            }
        }
    }
    (geo, refs)
}

fn prepare<'a>(scene: &'a Scene, eye: &Eye) -> World<'a> {
    // The same tessellation as the z-buffer's, within its triangle budget.
    let res = resolutions(scene, eye);
    let objs: Vec<Prepared> = scene
        .objects
        .par_iter()
        .enumerate()
        .filter_map(|(k, o)| {
            let (centre, radius) = world_sphere(o)?;
            let kind = match &o.geometry {
                Geometry::Patches(p) => {
                    let n = res[k].max(1);
                    let (geo, tris) = patch_triangles(o, p, n);
                    Kind::Patches {
                        bvh: Bvh::build(geo),
                        tris,
                        n,
                    }
                }
                Geometry::Mesh(m) => {
                    let mesh = m.transformed(&o.transform);
                    let geo = mesh
                        .triangles
                        .iter()
                        .map(|t| {
                            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
                            TriGeom::new(a, b, c)
                        })
                        .collect();
                    Kind::Mesh {
                        bvh: Bvh::build(geo),
                        mesh,
                    }
                }
                Geometry::QuaternionJulia(j) => Kind::Implicit(Implicit::new(k, o, j)?),
            };
            Some(Prepared {
                object: k,
                centre,
                radius,
                kind,
            })
        })
        .collect();
    let extent = objs
        .iter()
        .map(|p| p.centre.length() + p.radius)
        .fold(1.0, f64::max);
    World {
        scene,
        objs,
        shadow_eps: 1e-6 * extent,
    }
}

/// Newton's method on P(u, w) − (o + t·d) = 0 from a tessellation hit (u₀, w₀, t₀): the exact
/// patch point, or None when it does not converge nearby.
fn refine(
    patch: &Patch,
    xf: &Transform,
    o: DVec3,
    d: DVec3,
    start: (f64, f64, f64),
    max_dt: f64,
) -> Option<(f64, f64, f64)> {
    let (mut u, mut w, mut t) = start;
    for _ in 0..6 {
        let (q, qu, qw) = patch.eval_with_derivs(u, w);
        let (p, pu, pw) = (xf.apply(q), xf.apply_dir(qu), xf.apply_dir(qw));
        let f = p - (o + d * t);
        if f.length_squared() < 1e-26 * (1.0 + p.length_squared()) {
            break;
        }
        let j = DMat3::from_cols(pu, pw, -d);
        let det = j.determinant();
        if det.abs() < 1e-300 {
            return None;
        }
        let delta = j.inverse() * f;
        u -= delta.x;
        w -= delta.y;
        t -= delta.z;
        if !(u.is_finite() && w.is_finite() && t.is_finite()) {
            return None;
        }
    }
    let tol = 1e-7;
    let inside = (-tol..=1.0 + tol).contains(&u) && (-tol..=1.0 + tol).contains(&w);
    (inside && (t - start.2).abs() <= max_dt).then_some((u.clamp(0.0, 1.0), w.clamp(0.0, 1.0), t))
}

impl World<'_> {
    fn nearest(&self, o: DVec3, d: DVec3, t_min: f64, eye: &Eye) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut t_best = f64::INFINITY;
        for (k, p) in self.objs.iter().enumerate() {
            if !sphere_may_hit(p.centre, p.radius, o, d, t_min, t_best) {
                continue;
            }
            match &p.kind {
                Kind::Patches { bvh, .. } | Kind::Mesh { bvh, .. } => {
                    if let Some((tri, t, b1, b2)) = bvh.nearest(o, d, t_min, t_best) {
                        t_best = t;
                        best = Some(Hit::Tri {
                            obj: k,
                            tri,
                            t,
                            b1,
                            b2,
                        });
                    }
                }
                Kind::Implicit(im) => {
                    if let Some(t) = im.hit(o, d, t_min, t_best, eye) {
                        t_best = t;
                        best = Some(Hit::Implicit { obj: k, t });
                    }
                }
            }
        }
        best
    }

    /// Is the segment o + t·d, t in (0, t_max), blocked? `skip`: (object, triangle) the ray
    /// starts on; `eps`: surface threshold for ray-marched objects.
    fn occluded(
        &self,
        o: DVec3,
        d: DVec3,
        t_max: f64,
        skip: Option<(usize, u32)>,
        eps: f64,
    ) -> bool {
        self.objs.iter().enumerate().any(|(k, p)| {
            if !sphere_may_hit(p.centre, p.radius, o, d, 0.0, t_max) {
                return false;
            }
            match &p.kind {
                Kind::Patches { bvh, .. } | Kind::Mesh { bvh, .. } => {
                    let skip_tri = skip.filter(|s| s.0 == k).map(|s| s.1);
                    bvh.any(o, d, 0.0, t_max, skip_tri)
                }
                Kind::Implicit(im) => im.occludes(o, d, t_max, eps),
            }
        })
    }

    /// Shade the ray's hit; `next` holds the rays of the neighbouring pixels to the right
    /// and below, for the texture footprint.
    fn shade_hit(
        &self,
        hit: Hit,
        o: DVec3,
        d: DVec3,
        eye: &Eye,
        next: [(DVec3, DVec3); 2],
    ) -> Vec3 {
        let scene = self.scene;
        match hit {
            Hit::Implicit { obj, t } => {
                let Kind::Implicit(im) = &self.objs[obj].kind else {
                    unreachable!()
                };
                let (sp, eps) = im.surface_point(o, d, t, eye);
                let n = sp.normal;
                let visible = |j: usize| {
                    let lp = scene.lights[j].position;
                    let side = if n.dot(lp - sp.pos) >= 0.0 { n } else { -n };
                    let from = sp.pos + side * (8.0 * eps);
                    let to = lp - from;
                    let dist = to.length();
                    dist <= 0.0 || !self.occluded(from, to / dist, dist, None, 0.5 * eps)
                };
                self.finish(&sp, eye, &visible)
            }
            Hit::Tri {
                obj,
                tri,
                t,
                b1,
                b2,
            } => {
                let p = &self.objs[obj];
                let h = TriHit {
                    o,
                    d,
                    tri,
                    t,
                    b1,
                    b2,
                    next,
                };
                let (bvh, sp) = match &p.kind {
                    Kind::Patches { bvh, tris, n } => (
                        bvh,
                        self.patch_point(p.object, bvh, tris[tri as usize], *n, &h),
                    ),
                    Kind::Mesh { bvh, mesh } => (bvh, mesh_point(p.object, bvh, mesh, &h)),
                    Kind::Implicit(_) => unreachable!(),
                };
                // Shadow rays start on the tessellation (so neighbouring triangles of a
                // smooth surface do not shadow it), nudged off the triangle's plane.
                let g = &bvh.tris[tri as usize];
                let on_tri = g.v0 + g.e1 * b1 + g.e2 * b2;
                let face = g.normal().normalize_or_zero();
                let visible = |j: usize| {
                    let lp = scene.lights[j].position;
                    let side = if face.dot(lp - on_tri) >= 0.0 {
                        face
                    } else {
                        -face
                    };
                    let from = on_tri + side * self.shadow_eps;
                    let to = lp - from;
                    let dist = to.length();
                    dist <= 0.0
                        || !self.occluded(
                            from,
                            to / dist,
                            dist,
                            Some((obj, tri)),
                            eye.pixel_size(t),
                        )
                };
                self.finish(&sp, eye, &visible)
            }
        }
    }

    /// The surface point of a hit on a patch's tessellation: refined by Newton's method onto
    /// the exact patch (affine transforms), with the patch's normal, texture coordinates and
    /// tangents there.
    fn patch_point(
        &self,
        object: usize,
        bvh: &Bvh,
        pt: PatchTri,
        n: usize,
        h: &TriHit,
    ) -> SurfacePoint {
        let o_ref = &self.scene.objects[object];
        let Geometry::Patches(patches) = &o_ref.geometry else {
            unreachable!()
        };
        let (o, d, t, b1, b2) = (h.o, h.d, h.t, h.b1, h.b2);
        let spatch = &patches[pt.patch as usize];
        let uw = pt.uw(n);
        let b0 = 1.0 - b1 - b2;
        let mix = |k: usize| uw[0][k] * b0 + uw[1][k] * b1 + uw[2][k] * b2;
        let (u0, w0) = (mix(0), mix(1));
        let cell = bvh.tris[h.tri as usize].e1.length() + bvh.tris[h.tri as usize].e2.length();
        let xf = &o_ref.transform;
        let exact = if xf.is_affine() {
            refine(&spatch.patch, xf, o, d, (u0, w0, t), cell)
        } else {
            None
        };
        let (u, w) = exact.map_or((u0, w0), |(u, w, _)| (u, w));
        let (q, qu, qw) = spatch.patch.eval_with_derivs(u, w);
        let (pu, pw) = (xf.apply_dir(qu), xf.apply_dir(qw));
        let mut normal = pu.cross(pw);
        if normal.length_squared() <= 1e-24 {
            normal = xf.apply_normal(spatch.patch.normal(u, w));
        }
        // The exact patch point, or the tessellation's where Newton failed.
        let pos = if exact.is_some() {
            xf.apply(q)
        } else {
            o + d * t
        };
        let (tan_s, tan_t) = spatch.tex.tangents(pu, pw);
        let st_v = uw.map(|c| spatch.tex.at(c[0], c[1]));
        let footprint = footprint(&bvh.tris[h.tri as usize], st_v, h.next, (b1, b2));
        SurfacePoint {
            object,
            pos,
            normal: normal.normalize_or(DVec3::Y),
            st: spatch.tex.at(u, w),
            footprint,
            ts: tan_s,
            tt: tan_t,
        }
    }

    fn finish(&self, sp: &SurfacePoint, eye: &Eye, visible: &dyn Fn(usize) -> bool) -> Vec3 {
        if self.scene.shadows {
            shade(self.scene, eye.pos, sp, visible)
        } else {
            shade(self.scene, eye.pos, sp, &|_| true)
        }
    }
}

/// A hit on a triangle: the ray, the triangle, the ray parameter and barycentrics, and the
/// rays of the neighbouring pixels (right, below) for the texture footprint.
struct TriHit {
    o: DVec3,
    d: DVec3,
    tri: u32,
    t: f64,
    b1: f64,
    b2: f64,
    next: [(DVec3, DVec3); 2],
}

/// The surface point of a hit on a mesh triangle: normals, texture coordinates and tangents
/// interpolated from its vertices.
fn mesh_point(object: usize, bvh: &Bvh, mesh: &Mesh, h: &TriHit) -> SurfacePoint {
    let (b1, b2) = (h.b1, h.b2);
    let idx = mesh.triangles[h.tri as usize].map(|i| i as usize);
    let wt = [1.0 - b1 - b2, b1, b2];
    let mix3 =
        |f: &dyn Fn(usize) -> DVec3| f(idx[0]) * wt[0] + f(idx[1]) * wt[1] + f(idx[2]) * wt[2];
    let st_v = idx.map(|i| [mesh.tex[i][0] as f64, mesh.tex[i][1] as f64]);
    let st = [0, 1].map(|c| st_v[0][c] * wt[0] + st_v[1][c] * wt[1] + st_v[2][c] * wt[2]);
    let (tan_s, tan_t) = if mesh.tangents.len() == mesh.positions.len() {
        (mix3(&|i| mesh.tangents[i].0), mix3(&|i| mesh.tangents[i].1))
    } else {
        (DVec3::X, DVec3::Y)
    };
    let footprint = footprint(&bvh.tris[h.tri as usize], st_v, h.next, (b1, b2));
    SurfacePoint {
        object,
        pos: h.o + h.d * h.t,
        normal: mix3(&|i| mesh.normals[i]).normalize_or(DVec3::Y),
        st,
        footprint,
        ts: tan_s,
        tt: tan_t,
    }
}

/// Largest change of (s, t) to the neighbouring pixels: their rays meet the hit triangle's
/// plane at other barycentrics (the ray-differential form of the z-buffer's per-triangle
/// footprint).
fn footprint(g: &TriGeom, st: [[f64; 2]; 3], next: [(DVec3, DVec3); 2], here: (f64, f64)) -> f32 {
    let at = |(b1, b2): (f64, f64)| {
        let b0 = 1.0 - b1 - b2;
        [0, 1].map(|c| st[0][c] * b0 + st[1][c] * b1 + st[2][c] * b2)
    };
    let c = at(here);
    let mut f: f64 = 0.0;
    for (o, d) in next {
        if let Some(b) = g.plane_barycentrics(o, d) {
            let s = at(b);
            f = f.max((s[0] - c[0]).abs()).max((s[1] - c[1]).abs());
        }
    }
    f as f32
}

/// Render one eye into a w×h buffer (linear RGB); None when cancelled.
fn render_eye(
    scene: &Scene,
    eye: &Eye,
    w: usize,
    h: usize,
    cancel: Option<&AtomicBool>,
) -> Option<Vec<Vec3>> {
    let mut eye = *eye;
    eye.place_ray_start(scene);
    let eye = &eye;
    let world = prepare(scene, eye);
    let mut color = vec![scene.background; w * h];
    let stopped = AtomicBool::new(false);
    color.par_chunks_mut(w).enumerate().for_each(|(y, row)| {
        if stopped.load(Ordering::Relaxed) || cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
            stopped.store(true, Ordering::Relaxed);
            return;
        }
        let py = y as f64 + 0.5;
        for (x, out) in row.iter_mut().enumerate() {
            let px = x as f64 + 0.5;
            let (o, d, t_min) = eye.ray(px, py);
            if let Some(hit) = world.nearest(o, d, t_min, eye) {
                let rx = eye.ray(px + 1.0, py);
                let ry = eye.ray(px, py + 1.0);
                *out = world.shade_hit(hit, o, d, eye, [(rx.0, rx.1), (ry.0, ry.1)]);
            }
        }
    });
    (!stopped.load(Ordering::Relaxed)).then_some(color)
}

/// Ray-cast the scene (width×height; a stereo pair puts the left eye on the left half).
/// Returns None when cancelled.
pub fn render(scene: &Scene, cancel: Option<&AtomicBool>) -> Option<RgbImage> {
    picture(scene, |eye, w, h| render_eye(scene, eye, w, h, cancel))
}

/// Bytes of the ray caster's geometry for a tessellation of `vertices` and `triangles`: the
/// world meshes, a bounding volume hierarchy and one reference (16 bytes) per triangle.
pub(crate) fn geometry_bytes(vertices: u64, triangles: u64) -> u64 {
    vertices
        .saturating_mul(104)
        .saturating_add(super::bvh::bytes_for(triangles as usize) as u64)
        .saturating_add(triangles.saturating_mul(16))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::mesh::TexMap;
    use crate::surface::quaternion::ray_sphere;
    use crate::surface::scene::{Light, Material, Renderer};

    #[test]
    fn closest_approach_oracle() {
        // P₁ = (0, 0, 10), P₂ = (1, 1, 9), P₀ = (2, 2, 0): t = 14/3, d² = 128/3.
        let (t, d2) = closest_approach(
            DVec3::new(0.0, 0.0, 10.0),
            DVec3::new(1.0, 1.0, 9.0),
            DVec3::new(2.0, 2.0, 0.0),
        );
        assert!((t - 14.0 / 3.0).abs() < 1e-14 && (d2 - 128.0 / 3.0).abs() < 1e-12);
        // Sphere x² + y² + z² = 4 seen along the z axis from z = 10: the visible hit has the
        // largest z, z = 2 (t = 8); the far one z = −2.
        let (t0, t1) = ray_sphere(DVec3::new(0.0, 0.0, 10.0), -DVec3::Z, DVec3::ZERO, 2.0).unwrap();
        assert_eq!((10.0 - t0, 10.0 - t1), (2.0, -2.0));
        assert!(sphere_may_hit(
            DVec3::ZERO,
            2.0,
            DVec3::new(1.9, 0.0, 10.0),
            -DVec3::Z,
            0.0,
            100.0
        ));
        assert!(!sphere_may_hit(
            DVec3::ZERO,
            2.0,
            DVec3::new(2.1, 0.0, 10.0),
            -DVec3::Z,
            0.0,
            100.0
        ));
        // Behind the ray's start, or beyond the nearest hit so far: skipped.
        assert!(!sphere_may_hit(
            DVec3::ZERO,
            2.0,
            DVec3::new(0.0, 0.0, 10.0),
            DVec3::Z,
            0.0,
            100.0
        ));
        assert!(!sphere_may_hit(
            DVec3::ZERO,
            2.0,
            DVec3::new(0.0, 0.0, 10.0),
            -DVec3::Z,
            0.0,
            5.0
        ));
    }

    fn plane(y: f64, half: f64) -> SurfacePatch {
        SurfacePatch {
            patch: Patch::Bilinear {
                p: [
                    DVec3::new(-half, y, -half),
                    DVec3::new(-half, y, half),
                    DVec3::new(half, y, -half),
                    DVec3::new(half, y, half),
                ],
            },
            tex: TexMap::default(),
        }
    }

    #[test]
    fn newton_refinement_lands_on_the_exact_patch() {
        let jug = crate::surface::mesh::jug();
        let xf = Transform::rot_y(0.3).then(&Transform::translate(0.2, -0.1, 0.4));
        let sp = &jug[5]; // lower body
        for (u, w) in [(0.3, 0.6), (0.8, 0.1), (0.5, 0.5)] {
            let target = xf.apply(sp.patch.eval(u, w));
            let o = target + DVec3::new(3.0, 1.0, 4.0);
            let d = (target - o).normalize();
            let t_true = (target - o).length();
            let (ru, rw, rt) = refine(
                &sp.patch,
                &xf,
                o,
                d,
                (u + 0.02, w - 0.02, t_true + 0.01),
                1.0,
            )
            .expect("converges");
            assert!((ru - u).abs() < 1e-9 && (rw - w).abs() < 1e-9 && (rt - t_true).abs() < 1e-9);
        }
    }

    #[test]
    fn shadows_fall_where_the_light_is_blocked() {
        // A small square above a floor, light straight above: the floor under the square is
        // dark (ambient only), the floor beside it is lit; without shadows both are lit.
        let mut s = Scene {
            width: 80,
            height: 60,
            renderer: Renderer::RayCast,
            ..Scene::default()
        };
        s.camera.target = DVec3::ZERO;
        s.camera.distance = 10.0;
        s.camera.azimuth_deg = 0.0;
        s.camera.polar_deg = 1.0; // looking straight down
        s.lights = vec![Light {
            position: DVec3::new(0.0, 20.0, 0.0),
            intensity: Vec3::splat(21.0),
        }];
        let obj = |name: &str, p: SurfacePatch, color: Vec3| Object {
            name: name.into(),
            geometry: Geometry::Patches(vec![p]),
            transform: Transform::IDENTITY,
            material: Material {
                color,
                ks: 0.0,
                ..Material::default()
            },
            texture: None,
            bump_texture: None,
        };
        s.objects.push(obj("floor", plane(0.0, 3.0), Vec3::ONE));
        // A red square one unit above the floor; the light comes from +x at 45°, so the
        // shadow lies one unit towards −x, beside the square as seen from above.
        s.objects
            .push(obj("blocker", plane(1.0, 0.5), Vec3::new(1.0, 0.0, 0.0)));
        s.lights[0].position = DVec3::new(20.0, 20.0, 0.0);
        let img = render(&s, None).unwrap();
        let mut no = s.clone();
        no.shadows = false;
        let plain = render(&no, None).unwrap();
        let px = |img: &RgbImage, wx: f64, wz: f64| {
            let q = crate::surface::eye::project(&s, DVec3::new(wx, 0.0, wz)).unwrap();
            img.get_pixel(q[0] as u32, q[1] as u32).0
        };
        let (shadow, lit) = (px(&img, -1.0, 0.0), px(&img, -2.5, 0.0));
        assert!(
            (shadow[1] as i32) < lit[1] as i32 - 60,
            "shadow {shadow:?} lit {lit:?}"
        );
        // Without shadows the same floor point is lit like its neighbours.
        assert!((px(&plain, -1.0, 0.0)[1] as i32 - px(&plain, -2.5, 0.0)[1] as i32).abs() < 12);
        assert!(px(&plain, -1.0, 0.0)[1] > shadow[1] + 60);
    }
}
