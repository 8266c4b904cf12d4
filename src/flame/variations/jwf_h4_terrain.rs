//! Jesus Sosa's `terrain3D`: a fractal landscape made by the diamond-square algorithm (Fournier,
//! Fussell and Carpenter, "Computer rendering of stochastic models", CACM 1982) on a grid of
//! 2ⁿ × 2ⁿ cells, its heights from Java's generator seeded with `seed`, triangulated, optionally
//! subdivided (each triangle into four, up to twice) and smoothed by Taubin's λ|μ filter
//! (G. Taubin, "A signal processing approach to fair surface design", SIGGRAPH 1995); each call
//! returns a uniform random point of a random triangle, coloured by its height.
//!
//! The formulas follow JWildfire 9.00 (`FracTerrain3DFunc`, `SimpleMesh`,
//! `AbstractOBJMeshWFFunc`, LGPL-2.1), written anew. Vertices are kept in single precision as
//! JWildfire keeps them. The colour-map and displacement-map parameters JWildfire lists take
//! effect only with image files, which this variation never has; they are kept for the files.

use std::collections::HashMap;

use super::jwf_a_cuts::JavaRandom;
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("terrain3D", terrain3d)
    .params(&[
        p("terrain3D_roughness", 0.5),
        p("terrain3D_z_exaggeration", 0.7),
        // A grid of at most 256 × 256 cells.
        p_int("terrain3D_Size (N PowersOf 2)", 5.0, 1.0, 8.0).limited(),
        p_int("terrain3D_seed", 347.0, -2147483648.0, 2147483647.0),
        p_int("terrain3D_dc", 1.0, 0.0, 1.0),
        p("terrain3D_scale_x", 1.0),
        p("terrain3D_scale_y", 1.0),
        p("terrain3D_scale_z", 1.0),
        p("terrain3D_offset_x", 0.0),
        p("terrain3D_offset_y", 0.0),
        p("terrain3D_offset_z", 0.0),
        // JWildfire subdivides at most twice whatever the level.
        p_int("terrain3D_subdiv_level", 0.0, 0.0, 6.0),
        p_int("terrain3D_subdiv_smooth_passes", 12.0, 0.0, 24.0).limited(),
        p("terrain3D_subdiv_smooth_lambda", 0.42),
        p("terrain3D_subdiv_smooth_mu", -0.45),
        p_int("terrain3D_blend_colormap", 1.0, 0.0, 1.0),
        p("terrain3D_displ_amount", 0.1),
        p_int("terrain3D_blend_displ_map", 1.0, 0.0, 1.0),
        p_int("terrain3D_receive_only_shadows", 0.0, 0.0, 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR | flag::WRITES_Z | flag::READS_ACC)
    .shared(&[0, 1, 2, 3, 11, 12, 13, 14], terrain_mesh)];

/// A triangle mesh whose vertices are merged when they agree to 1e-4 (JWildfire's
/// `SimpleMesh`).
#[derive(Default)]
struct Mesh {
    verts: Vec<[f32; 3]>,
    faces: Vec<[usize; 3]>,
    index: HashMap<[i64; 3], usize>,
}

/// JWildfire's `Tools.FTOI`: rounded half away from zero.
fn ftoi(v: f64) -> i64 {
    if v > 0.0 {
        (v + 0.5) as i64
    } else if v < 0.0 {
        (v - 0.5) as i64
    } else {
        0
    }
}

impl Mesh {
    fn vertex(&mut self, [x, y, z]: [f64; 3]) -> usize {
        let key = [ftoi(x * 1e4), ftoi(y * 1e4), ftoi(z * 1e4)];
        if let Some(&i) = self.index.get(&key) {
            return i;
        }
        self.verts.push([x as f32, y as f32, z as f32]);
        self.index.insert(key, self.verts.len() - 1);
        self.verts.len() - 1
    }

    /// Each triangle split into four at its edges' midpoints.
    fn subdivided(&self) -> Mesh {
        let mut m = Mesh::default();
        let f64s = |v: [f32; 3]| v.map(f64::from);
        let mid = |a: [f32; 3], b: [f32; 3]| -> [f64; 3] {
            std::array::from_fn(|k| {
                f64::from((f64::from(a[k]) + f64::from(b[k] - a[k]) * 0.5) as f32)
            })
        };
        for &[a, b, c] in &self.faces {
            let (va, vb, vc) = (self.verts[a], self.verts[b], self.verts[c]);
            let n1 = m.vertex(f64s(va));
            let n2 = m.vertex(f64s(vb));
            let n3 = m.vertex(f64s(vc));
            let n4 = m.vertex(mid(va, vb));
            let n5 = m.vertex(mid(vb, vc));
            let n6 = m.vertex(mid(vc, va));
            m.faces
                .extend([[n1, n4, n6], [n4, n2, n5], [n5, n3, n6], [n4, n5, n6]]);
        }
        m
    }

    /// `passes` rounds of Taubin's smoothing: a Laplacian step by `lambda`, then by `mu`.
    fn taubin(&mut self, passes: usize, lambda: f64, mu: f64) {
        let mut nb: Vec<Vec<usize>> = vec![Vec::new(); self.verts.len()];
        for &[a, b, c] in &self.faces {
            for (from, to) in [(a, b), (a, c), (b, a), (b, c), (c, a), (c, b)] {
                if !nb[from].contains(&to) {
                    nb[from].push(to);
                }
            }
        }
        for _ in 0..passes {
            for strength in [lambda, mu] {
                let moves: Vec<[f32; 3]> = (0..self.verts.len())
                    .map(|i| {
                        let mut d = [0f32; 3];
                        if nb[i].len() > 1 {
                            let w = 1.0 / nb[i].len() as f64;
                            let v = self.verts[i];
                            for &n in &nb[i] {
                                let u = self.verts[n];
                                for k in 0..3 {
                                    d[k] = (f64::from(d[k]) + f64::from(u[k] - v[k]) * w) as f32;
                                }
                            }
                        }
                        d
                    })
                    .collect();
                for (v, d) in self.verts.iter_mut().zip(moves) {
                    for k in 0..3 {
                        v[k] = (f64::from(v[k]) + f64::from(d[k]) * strength) as f32;
                    }
                }
            }
        }
    }
}

/// The diamond-square heights of a (2^lod + 1)² grid, normalised to [0, 1].
fn heights(lod: u32, roughness: f64, seed: i64) -> Vec<Vec<f64>> {
    let div = 1usize << lod;
    let mut t = vec![vec![0.0; div + 1]; div + 1];
    let mut rng = JavaRandom::new(seed);
    let mut rnd = move || 2.0 * rng.next_f64() - 1.0;
    t[0][0] = rnd();
    t[0][div] = rnd();
    t[div][div] = rnd();
    t[div][0] = rnd();
    let mut rough = roughness;
    for i in 0..lod {
        let r = 1usize << (lod - i);
        let s = r >> 1;
        for j in (0..div).step_by(r) {
            for k in (0..div).step_by(r) {
                if r > 1 {
                    let avg = (t[j][k] + t[j + r][k] + t[j + r][k + r] + t[j][k + r]) * 0.25;
                    t[j + s][k + s] = avg + rnd() * rough;
                }
            }
        }
        if s > 0 {
            for j in (0..=div).step_by(s) {
                let mut k = (j + s) % r;
                while k <= div {
                    // The square step about (j, k): the cell from (j − s, k − s) of side r.
                    let (x, y) = (j as i64 - s as i64, k as i64 - s as i64);
                    let (h, side, d) = (s as i64, r as i64, div as i64);
                    let mut avg = 0.0;
                    let mut sum = 0.0;
                    let at = |a: i64, b: i64| t[a as usize][b as usize];
                    if x >= 0 {
                        avg += at(x, y + h);
                        sum += 1.0;
                    }
                    if y >= 0 {
                        avg += at(x + h, y);
                        sum += 1.0;
                    }
                    if x + side <= d {
                        avg += at(x + side, y + h);
                        sum += 1.0;
                    }
                    if y + side <= d {
                        avg += at(x + h, y + side);
                        sum += 1.0;
                    }
                    t[j][k] = avg / sum + rnd() * rough;
                    k += r;
                }
            }
        }
        rough *= roughness;
    }
    let (mut min, mut max) = (t[0][0], t[0][0]);
    for row in &t {
        for &v in row {
            if v < min {
                min = v;
            } else if v > max {
                max = v;
            }
        }
    }
    for row in &mut t {
        for v in row.iter_mut() {
            *v = (*v - min) / (max - min);
        }
    }
    t
}

/// The landscape's mesh: the vertex count, the vertices (x, y, z; y up) and the triangles
/// (vertex indices).
fn terrain_mesh(q: &[f64], _: &[String]) -> Vec<f64> {
    let [roughness, exaggeration, n, seed] = params_of(q);
    let [subdiv, passes, lambda, mu] = [q[11], q[12], q[13], q[14]];
    let lod = n.clamp(1.0, 8.0) as u32;
    let t = heights(lod, roughness, seed as i64);
    let steps = 1usize << lod;
    let mut m = Mesh::default();
    for (i, row) in t.iter().enumerate() {
        for (j, &h) in row.iter().enumerate() {
            let (x, z) = (i as f64 / steps as f64, j as f64 / steps as f64);
            m.vertex([x - 0.5, h * exaggeration, z - 0.5]);
        }
    }
    for i in 0..steps {
        for j in 0..steps {
            let at = |a: usize, b: usize| (steps + 1) * a + b;
            m.faces.push([at(i, j), at(i + 1, j), at(i, j + 1)]);
            m.faces.push([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    for _ in 0..(subdiv.max(0.0) as usize).min(2) {
        m = m.subdivided();
        m.taubin(passes.clamp(0.0, 24.0) as usize, lambda, mu);
    }
    let mut out = Vec::with_capacity(1 + 3 * (m.verts.len() + m.faces.len()));
    out.push(m.verts.len() as f64);
    out.extend(m.verts.iter().flat_map(|v| v.map(f64::from)));
    out.extend(m.faces.iter().flat_map(|f| f.map(|i| i as f64)));
    out
}

/// terrain3D: a uniform random point of a random triangle of the landscape (scaled and
/// offset per axis in single precision), coloured by the output's height modulo 1 with `dc`.
fn terrain3d(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 19] = v.params();
    let data = v.data();
    let Some(&nv) = data.first() else {
        return [0.0; 3];
    };
    let nv = nv as usize;
    let faces = data.get(1 + 3 * nv..).unwrap_or(&[]);
    let count = faces.len() / 3;
    if count == 0 {
        return [0.0; 3];
    }
    let f = ((rng.f01() * count as f64) as usize).min(count - 1);
    let corner = |k: usize| -> [f64; 3] {
        let i = faces[3 * f + k] as usize;
        let p = &data[1 + 3 * i..4 + 3 * i];
        std::array::from_fn(|a| f64::from((p[a] * q[5 + a] + q[8 + a]) as f32))
    };
    let (p1, p2, p3) = (corner(0), corner(1), corner(2));
    let s = rng.f01().sqrt();
    let r2 = rng.f01();
    let (a, b, c) = (1.0 - s, s * (1.0 - r2), r2 * s);
    let out: V3 = std::array::from_fn(|k| v.w * (a * p1[k] + b * p2[k] + c * p3[k]));
    if q[4] == 1.0 {
        acc.color = (acc.y + out[1]) % 1.0;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn landscape_mesh_has_the_grid_and_subdivides() {
        let mut q = vec![0.5, 0.7, 2.0, 347.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0];
        q.extend([12.0, 0.42, -0.45, 1.0, 0.1, 1.0, 0.0]);
        let m = terrain_mesh(&q, &[]);
        // 5 × 5 vertices, 2 × 16 triangles; heights normalised to [0, 0.7].
        assert_eq!(m[0], 25.0);
        assert_eq!(m.len(), 1 + 75 + 96);
        let ys: Vec<f64> = (0..25).map(|i| m[1 + 3 * i + 1]).collect();
        let top = ys.iter().cloned().fold(f64::MIN, f64::max);
        let bottom = ys.iter().cloned().fold(f64::MAX, f64::min);
        assert!((top - 0.7).abs() < 1e-6 && bottom == 0.0);
        q[11] = 1.0;
        let m = terrain_mesh(&q, &[]);
        // Each triangle in four; the 81 points of the finer grid.
        assert_eq!(m[0], 81.0);
        assert_eq!(m.len(), 1 + 243 + 4 * 96);
    }
}
