//! Objects made of patches, their tessellation into triangle meshes, and the generators the
//! scene files use: surfaces of revolution, tubes along a cubic spine, the reference jug, a
//! teapot-style object and midpoint-displacement mountains.

use glam::DVec3;

use super::patch::Patch;
use super::transform::Transform;
use crate::flame::rng::FastRng;

/// The affine texture map of a patch: (s, t) = origin + u·du + w·dw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexMap {
    /// (s, t) at u = w = 0.
    pub origin: [f64; 2],
    /// Change of (s, t) as u goes from 0 to 1.
    pub du: [f64; 2],
    /// Change of (s, t) as w goes from 0 to 1.
    pub dw: [f64; 2],
}

impl Default for TexMap {
    /// s = u, t = w (the identity map for a single Bézier patch).
    fn default() -> Self {
        TexMap {
            origin: [0.0, 0.0],
            du: [1.0, 0.0],
            dw: [0.0, 1.0],
        }
    }
}

impl TexMap {
    /// The texture coordinates (s, t) of patch parameters (u, w).
    pub fn at(&self, u: f64, w: f64) -> [f64; 2] {
        [
            self.origin[0] + u * self.du[0] + w * self.dw[0],
            self.origin[1] + u * self.du[1] + w * self.dw[1],
        ]
    }

    /// Surface tangents along s and t from Q_u, Q_w (inverting the map's Jacobian).
    pub fn tangents(&self, qu: DVec3, qw: DVec3) -> (DVec3, DVec3) {
        // [Q_u Q_w] = [Q_s Q_t]·J with J = [[du.s, dw.s], [du.t, dw.t]].
        let (a, b, c, d) = (self.du[0], self.dw[0], self.du[1], self.dw[1]);
        let det = a * d - b * c;
        if det.abs() < 1e-15 {
            return (qu, qw);
        }
        // [Q_s Q_t] = [Q_u Q_w]·J⁻¹, J⁻¹ = [[d, −b], [−c, a]]/det.
        ((qu * d - qw * c) / det, (qw * a - qu * b) / det)
    }
}

/// A patch and how the texture lies on it.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfacePatch {
    /// The Bézier patch.
    pub patch: Patch,
    /// Its texture coordinates as a function of the patch parameters.
    pub tex: TexMap,
}

/// A triangle mesh with per-vertex normal, texture coordinate and texture tangents.
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Unit vertex normals, one per position.
    pub normals: Vec<DVec3>,
    /// Texture coordinates (s, t), one per position.
    pub tex: Vec<[f32; 2]>,
    /// ∂P/∂s and ∂P/∂t (for bump mapping).
    pub tangents: Vec<(DVec3, DVec3)>,
    /// Triangles, each as three indices into the vertex lists.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// The mesh mapped through `t`: positions and tangents transformed, normals recomputed so that
    /// non-uniform scaling keeps them perpendicular.
    pub fn transformed(&self, t: &Transform) -> Mesh {
        let normal_of = |n: DVec3, p: DVec3| {
            // Transform the normal through two tangent directions (handles non-uniform scale).
            let a = n.any_orthonormal_vector();
            let b = n.cross(a);
            let pa = t.apply(p + a * 1e-4) - t.apply(p);
            let pb = t.apply(p + b * 1e-4) - t.apply(p);
            let m = pa.cross(pb);
            if m.length_squared() > 0.0 {
                m.normalize()
            } else {
                n
            }
        };
        Mesh {
            positions: self.positions.iter().map(|p| t.apply(*p)).collect(),
            normals: self
                .normals
                .iter()
                .zip(&self.positions)
                .map(|(n, p)| normal_of(*n, *p))
                .collect(),
            tex: self.tex.clone(),
            tangents: self
                .tangents
                .iter()
                .map(|(a, b)| (t.apply_dir(*a), t.apply_dir(*b)))
                .collect(),
            triangles: self.triangles.clone(),
        }
    }

    /// Add the vertices and triangles of `other` (its indices shifted past this mesh's vertices).
    pub fn append(&mut self, other: &Mesh) {
        let base = self.positions.len() as u32;
        self.positions.extend(&other.positions);
        self.normals.extend(&other.normals);
        self.tex.extend(&other.tex);
        self.tangents.extend(&other.tangents);
        self.triangles
            .extend(other.triangles.iter().map(|t| t.map(|i| i + base)));
    }
}

/// Tessellate patches uniformly on an (n + 1)² grid each (the same n for all, so shared edges
/// match and there are no cracks); two triangles per cell, diagonal (i, j)–(i + 1, j + 1).
pub fn tessellate(patches: &[SurfacePatch], n: usize) -> Mesh {
    let n = n.max(1);
    let mut mesh = Mesh::default();
    for sp in patches {
        let base = mesh.positions.len() as u32;
        for i in 0..=n {
            for j in 0..=n {
                let (u, w) = (i as f64 / n as f64, j as f64 / n as f64);
                let p = sp.patch.eval(u, w);
                let (qu, qw) = sp.patch.derivs(u, w);
                mesh.positions.push(p);
                mesh.normals.push(sp.patch.normal(u, w));
                let st = sp.tex.at(u, w);
                mesh.tex.push([st[0] as f32, st[1] as f32]);
                mesh.tangents.push(sp.tex.tangents(qu, qw));
            }
        }
        let idx = |i: usize, j: usize| base + (i * (n + 1) + j) as u32;
        for i in 0..n {
            for j in 0..n {
                mesh.triangles
                    .push([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)]);
                mesh.triangles
                    .push([idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)]);
            }
        }
    }
    mesh
}

/// The quarter-circle constant κ = 4(√2 − 1)/3.
pub const KAPPA: f64 = 0.552_284_749_830_793_4;

/// Cubic quarter-circle weights (a_j, c_j): the control points (r·a_j, r·c_j) approximate the
/// quarter circle of radius r from (r, 0) to (0, r).
const ARC_A: [f64; 4] = [1.0, 1.0, KAPPA, 0.0];
const ARC_C: [f64; 4] = [0.0, KAPPA, 1.0, 1.0];

/// A surface of revolution about the y axis: `profile` holds 3k + 1 points (r, y) of k cubic
/// segments; each segment is revolved in four quarter patches. Texture: s = (q + w)/4 around,
/// t = (segment + u)/k along the profile.
pub fn revolve(profile: &[[f64; 2]]) -> Vec<SurfacePatch> {
    let k = (profile.len().saturating_sub(1)) / 3;
    let mut out = Vec::new();
    for seg in 0..k {
        let pts = &profile[seg * 3..seg * 3 + 4];
        for q in 0..4 {
            let net: Vec<DVec3> = (0..4)
                .flat_map(|i| {
                    let (r, y) = (pts[i][0], pts[i][1]);
                    (0..4).map(move |j| DVec3::new(r * ARC_A[j], y, r * ARC_C[j]))
                })
                .map(|p| exact_rotate(p, q))
                .collect();
            out.push(SurfacePatch {
                patch: Patch::Bezier { n: 3, m: 3, net },
                tex: TexMap {
                    origin: [q as f64 / 4.0, seg as f64 / k as f64],
                    du: [0.0, 1.0 / k as f64],
                    dw: [0.25, 0.0],
                },
            });
        }
    }
    out
}

/// Quarter q of the revolution: the base arc (+x towards +z) turned by q quarter turns in the
/// same sense (+x → +z), exactly, so neighbouring patches share boundary control points bit
/// for bit and s = (q + w)/4 runs continuously around.
fn exact_rotate(p: DVec3, q: usize) -> DVec3 {
    match q % 4 {
        0 => p,
        1 => DVec3::new(-p.z, p.y, p.x),
        2 => DVec3::new(-p.x, p.y, -p.z),
        _ => DVec3::new(p.z, p.y, -p.x),
    }
}

/// A tube of `radius` around a cubic spine in the xy plane (as for the jug's handle): four quarter
/// patches. Texture: s = (q + w)/4 around, t = u along.
pub fn tube(spine: [DVec3; 4], radius: f64) -> Vec<SurfacePatch> {
    let sp = super::patch::Curve {
        points: spine.to_vec(),
    };
    let normal_at = |t: f64| {
        let h = 1e-5;
        let (a, b) = ((t - h).max(0.0), (t + h).min(1.0));
        let tan = (sp.eval(b) - sp.eval(a)).normalize();
        DVec3::new(-tan.y, tan.x, 0.0).normalize()
    };
    let z = DVec3::Z;
    (0..4)
        .map(|q| {
            let ang = std::f64::consts::FRAC_PI_2 * q as f64;
            let (s, c) = ang.sin_cos();
            let net: Vec<DVec3> = (0..4)
                .flat_map(|i| {
                    let n = normal_at(i as f64 / 3.0);
                    (0..4).map(move |j| {
                        let (a, cc) = (ARC_A[j], ARC_C[j]);
                        let a2 = a * c - cc * s;
                        let c2 = a * s + cc * c;
                        spine[i] + (n * a2 + z * c2) * radius
                    })
                })
                .collect();
            SurfacePatch {
                patch: Patch::Bezier { n: 3, m: 3, net },
                tex: TexMap {
                    origin: [q as f64 / 4.0, 0.0],
                    du: [0.0, 1.0],
                    dw: [0.25, 0.0],
                },
            }
        })
        .collect()
}

/// The reference jug's profile: four G1 cubic segments (r, y).
pub const JUG_PROFILE: [[f64; 2]; 13] = [
    [0.0, 0.0],
    [0.3, 0.0],
    [0.5, 0.0],
    [0.7, 0.0],
    [1.0, 0.0],
    [1.25, 0.35],
    [1.2, 0.9],
    [1.15, 1.35],
    [0.7, 1.55],
    [0.5, 1.8],
    [0.42, 1.9],
    [0.42, 2.25],
    [0.6, 2.4],
];

/// The jug's handle spine.
pub const JUG_HANDLE: [[f64; 3]; 4] = [
    [1.12, 0.6, 0.0],
    [1.85, 0.55, 0.0],
    [1.75, 1.75, 0.0],
    [0.78, 1.5, 0.0],
];

/// The reference jug: 16 body patches and 4 handle patches.
pub fn jug() -> Vec<SurfacePatch> {
    let mut p = revolve(&JUG_PROFILE);
    p.extend(tube(JUG_HANDLE.map(DVec3::from_array), 0.07));
    p
}

/// A teapot-style test object: body, lid and knob of revolution, a spout and a handle.
pub fn teapot() -> Vec<SurfacePatch> {
    let body = [
        [0.0, 0.0],
        [0.5, 0.0],
        [0.9, 0.0],
        [1.1, 0.05],
        [1.45, 0.15],
        [1.5, 0.7],
        [1.4, 1.0],
        [1.3, 1.3],
        [1.1, 1.45],
        [0.9, 1.5],
    ];
    let lid = [
        [0.9, 1.5],
        [0.85, 1.6],
        [0.5, 1.7],
        [0.25, 1.75],
        [0.15, 1.78],
        [0.12, 1.85],
        [0.18, 1.95],
        [0.22, 2.02],
        [0.1, 2.08],
        [0.0, 2.08],
    ];
    let mut p = revolve(&body);
    p.extend(revolve(&lid));
    p.extend(tube(
        [
            DVec3::new(1.35, 0.5, 0.0),
            DVec3::new(2.0, 0.6, 0.0),
            DVec3::new(1.9, 1.3, 0.0),
            DVec3::new(2.5, 1.55, 0.0),
        ],
        0.12,
    ));
    p.extend(tube(
        [
            DVec3::new(-1.4, 1.15, 0.0),
            DVec3::new(-2.2, 1.3, 0.0),
            DVec3::new(-2.1, 0.3, 0.0),
            DVec3::new(-1.35, 0.45, 0.0),
        ],
        0.08,
    ));
    p
}

/// A fractal mountain by midpoint displacement on a square of two triangles: K levels
/// give 2·4^K triangles on a (2^K + 1)² lattice. Each new midpoint is displaced once by a
/// Gaussian N(0, σ_k²), σ_k = σ₀·2^(−kH), from a hash of its lattice position (crack-free,
/// reproducible). The square spans [−size/2, size/2]² in x and z; heights along y. Texture:
/// s = x across, t = height from the top (1 at the lowest point).
pub fn mountain(levels: u32, size: f64, sigma: f64, h: f64, seed: u64) -> Mesh {
    let k = levels.clamp(1, 10);
    let n = 1usize << k;
    let side = n + 1;
    let mut hgt = vec![0.0f64; side * side];
    let gauss = |i: usize, j: usize| {
        let mut r = FastRng::new(seed ^ ((i as u64) << 32) ^ (j as u64) ^ 0x6d6f_756e);
        // Box–Muller.
        let (u1, u2) = (r.f01().max(1e-300), r.f01());
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    };
    for level in 1..=k {
        let s = n >> level; // half step of this level
        let sd = sigma * 2f64.powf(-(level as f64) * h);
        for i in (0..side).step_by(s) {
            for j in (0..side).step_by(s) {
                let (oi, oj) = ((i / s) % 2 == 1, (j / s) % 2 == 1);
                let ends = match (oi, oj) {
                    (false, false) => continue,
                    (true, false) => ((i - s, j), (i + s, j)),
                    (false, true) => ((i, j - s), (i, j + s)),
                    (true, true) => ((i - s, j - s), (i + s, j + s)),
                };
                let (a, b) = (
                    hgt[ends.0.0 * side + ends.0.1],
                    hgt[ends.1.0 * side + ends.1.1],
                );
                hgt[i * side + j] = 0.5 * (a + b) + sd * gauss(i, j);
            }
        }
    }
    let (lo, hi) = hgt
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
    let span = (hi - lo).max(1e-12);
    let pos = |i: usize, j: usize| {
        DVec3::new(
            (i as f64 / n as f64 - 0.5) * size,
            hgt[i * side + j],
            (j as f64 / n as f64 - 0.5) * size,
        )
    };
    let mut m = Mesh::default();
    for i in 0..side {
        for j in 0..side {
            m.positions.push(pos(i, j));
            let t = ((hi - hgt[i * side + j]) / span) as f32;
            m.tex.push([i as f32 / n as f32, t]);
        }
    }
    // Normals from central differences of the height field.
    let step = size / n as f64;
    for i in 0..side {
        for j in 0..side {
            let dx = (hgt[(i + 1).min(n) * side + j] - hgt[i.saturating_sub(1) * side + j])
                / (step * ((i + 1).min(n) - i.saturating_sub(1)) as f64);
            let dz = (hgt[i * side + (j + 1).min(n)] - hgt[i * side + j.saturating_sub(1)])
                / (step * ((j + 1).min(n) - j.saturating_sub(1)) as f64);
            m.normals.push(DVec3::new(-dx, 1.0, -dz).normalize());
            m.tangents
                .push((DVec3::X * size, DVec3::new(0.0, -span, 0.0)));
        }
    }
    let idx = |i: usize, j: usize| (i * side + j) as u32;
    for i in 0..n {
        for j in 0..n {
            // Split along the (i, j)–(i + 1, j + 1) diagonal (the lattice's diagonal edges);
            // wound so the normals point up (+y).
            m.triangles
                .push([idx(i, j), idx(i + 1, j + 1), idx(i + 1, j)]);
            m.triangles
                .push([idx(i, j), idx(i, j + 1), idx(i + 1, j + 1)]);
        }
    }
    m
}

/// Largest projected extent (pixels) of a set of patches' control points under `to_screen`.
pub fn projected_extent(
    patches: &[SurfacePatch],
    to_screen: impl Fn(DVec3) -> Option<[f64; 2]>,
) -> f64 {
    let mut ext: f64 = 0.0;
    for p in patches {
        let pts: Vec<[f64; 2]> = p
            .patch
            .control_points()
            .into_iter()
            .filter_map(&to_screen)
            .collect();
        if pts.is_empty() {
            continue;
        }
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for q in pts {
            x0 = x0.min(q[0]);
            x1 = x1.max(q[0]);
            y0 = y0.min(q[1]);
            y1 = y1.max(q[1]);
        }
        ext = ext.max((x1 - x0).max(y1 - y0));
    }
    ext
}

/// Grid resolution for a projected extent: about 6 pixels per cell, 4–48 cells per patch.
pub fn resolution_for(extent_px: f64) -> usize {
    ((extent_px / 6.0).ceil() as usize).clamp(4, 48)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jug_scene_checks() {
        let j = jug();
        assert_eq!(j.len(), 20);
        assert_eq!(tessellate(&j, 16).triangles.len(), 10_240);
        // κ and the quarter circle's radial error.
        assert!((KAPPA - 0.5522847498).abs() < 1e-10);
        let arc = super::super::patch::Curve {
            points: (0..4)
                .map(|k| DVec3::new(ARC_A[k], ARC_C[k], 0.0))
                .collect(),
        };
        let err = (0..=1000)
            .map(|k| (arc.eval(k as f64 / 1000.0).length() - 1.0).abs())
            .fold(0.0, f64::max);
        assert!((err - 2.7253e-4).abs() < 2e-7, "{err}");
        // Widest radius 1.2064 at y = 0.762 (segment 1 profile).
        let seg = super::super::patch::Curve {
            points: JUG_PROFILE[3..7]
                .iter()
                .map(|p| DVec3::new(p[0], p[1], 0.0))
                .collect(),
        };
        let (mut best, mut at) = (0.0, 0.0);
        for k in 0..=20000 {
            let p = seg.eval(k as f64 / 20000.0);
            if p.x > best {
                (best, at) = (p.x, p.y);
            }
        }
        assert!(
            (best - 1.2064).abs() < 1e-4 && (at - 0.762).abs() < 1e-3,
            "{best} at {at}"
        );
        // Adjacent body patches share boundary control points bit for bit.
        let net = |k: usize| match &j[k].patch {
            Patch::Bezier { net, .. } => net.clone(),
            _ => unreachable!(),
        };
        for seg in 0..4 {
            for q in 0..4 {
                let a = net(seg * 4 + q);
                let b = net(seg * 4 + (q + 1) % 4);
                for i in 0..4 {
                    assert_eq!(a[i * 4 + 3], b[i * 4], "seg {seg} quarter {q} row {i}");
                }
                if seg < 3 {
                    let c = net((seg + 1) * 4 + q);
                    for jj in 0..4 {
                        assert_eq!(a[12 + jj], c[jj]);
                    }
                }
            }
        }
        // N(½, ½) points away from the y axis on every body patch.
        for sp in &j[..16] {
            let p = sp.patch.eval(0.5, 0.5);
            let n = sp.patch.normal(0.5, 0.5);
            let radial = DVec3::new(p.x, 0.0, p.z).normalize();
            assert!(
                n.dot(radial) > 0.0 || (sp.tex.origin[1] == 0.0 && n.y < 0.0),
                "{p:?} {n:?}"
            );
        }
        // The base centre (a pole) still has a finite normal.
        let n = j[0].patch.normal(0.0, 0.3);
        assert!(n.is_finite() && (n.length() - 1.0).abs() < 1e-9);
    }

    #[test]
    fn sphere_patch_texture_mapping_example() {
        // s = θ/(π/2), t = (π/2 − φ)/(π/4): (0.5, 0.5) → θ = π/4, φ = 3π/8.
        let (s, t) = (0.5f64, 0.5f64);
        let th = std::f64::consts::FRAC_PI_2 * s;
        let ph = std::f64::consts::FRAC_PI_2 - std::f64::consts::FRAC_PI_4 * t;
        assert!((th - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert!((ph - 3.0 * std::f64::consts::PI / 8.0).abs() < 1e-15);
        let p = DVec3::new(th.sin() * ph.sin(), ph.cos(), th.cos() * ph.sin());
        assert!((p - DVec3::new(0.653281, 0.382683, 0.653281)).length() < 1e-6);
        // Tangents from a texture map invert its Jacobian.
        let m = TexMap {
            origin: [0.25, 0.5],
            du: [0.0, 0.25],
            dw: [0.25, 0.0],
        };
        let (qs, qt) = m.tangents(DVec3::Y, DVec3::X);
        assert!((qs - DVec3::X * 4.0).length() < 1e-12 && (qt - DVec3::Y * 4.0).length() < 1e-12);
    }

    #[test]
    fn mountain_counts_and_crack_free_reproducibility() {
        let m = mountain(8, 10.0, 1.0, 0.8, 5);
        assert_eq!(m.triangles.len(), 2 * 65_536);
        assert_eq!(m.positions.len(), 257 * 257);
        let again = mountain(8, 10.0, 1.0, 0.8, 5);
        assert_eq!(m.positions, again.positions);
        // K levels on one triangle give 4^K triangles and (2^K + 1)(2^K + 2)/2 vertices.
        let k = 8u32;
        assert_eq!(4usize.pow(k), 65_536);
        assert_eq!((2usize.pow(k) + 1) * (2usize.pow(k) + 2) / 2, 33_153);
        // Every lattice vertex is displaced once, so two triangles sharing an edge share its
        // midpoint height (no cracks by construction): heights vary and are finite.
        assert!(m.positions.iter().all(|p| p.is_finite()));
        assert!(m.normals.iter().all(|n| n.y > 0.0));
    }
}
