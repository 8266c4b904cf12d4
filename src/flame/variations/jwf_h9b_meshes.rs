//! JWildfire's mesh variation `obj_mesh_wf`: each call picks one triangle of a mesh at random
//! and returns a uniform random point of it, the mesh's vertices scaled and moved first.
//!
//! The formula follows JWildfire 9.00's (LGPL-2.1) `AbstractOBJMeshWFFunc`, `OBJMeshWFFunc`
//! and `SimpleMesh`, written anew.
//!
//! A JWildfire flame names the mesh, a Wavefront OBJ file, in the text parameter
//! `obj_filename`. The file readers load it and hand it over ([`super::resources`]); a use
//! whose mesh was not handed over takes the mesh JWildfire falls back to, the cube [−1, 1]³ as
//! six squares of two triangles each. A loaded mesh is prepared as JWildfire prepares it:
//! with `subdiv_level` 0, each triangle is picked in proportion to its area (a whole number of
//! times the smallest area, at most 5000 times, 500 for meshes of 5000 triangles or more);
//! above 0, each level splits every triangle into four at its edges' midpoints and smooths
//! the mesh with `subdiv_smooth_passes` passes of Taubin's λ|μ smoothing (G. Taubin, "A signal
//! processing approach to fair surface design", SIGGRAPH 1995), λ = `subdiv_smooth_lambda`,
//! μ = `subdiv_smooth_mu`; the levels stop before the mesh would exceed
//! [`resources::MAX_MESH_FACES`] triangles.
//!
//! The colour and displacement images (`colormap_filename`, `displ_map_filename`) are not
//! read: their parameters are kept for the file's sake, as is `receive_only_shadows`, which
//! concerns JWildfire's solid rendering.

use super::resources::{self, ResourceMesh};
use super::*;

/// JWildfire's default mesh: the cube's corners and its six squares.
const CUBE_VERTICES: [[f32; 3]; 8] = [
    [-1.0, -1.0, 1.0],
    [1.0, -1.0, 1.0],
    [1.0, 1.0, 1.0],
    [-1.0, 1.0, 1.0],
    [-1.0, -1.0, -1.0],
    [1.0, -1.0, -1.0],
    [1.0, 1.0, -1.0],
    [-1.0, 1.0, -1.0],
];
const CUBE_SQUARES: [[u32; 4]; 6] = [
    [0, 1, 2, 3],
    [1, 5, 6, 2],
    [5, 6, 7, 4],
    [4, 7, 3, 0],
    [3, 2, 6, 7],
    [0, 1, 5, 4],
];

/// Most bytes of a mesh file's name.
const MAX_NAME: usize = 4096;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("obj_mesh_wf", obj_mesh_wf)
    .params(&[
        p("obj_mesh_wf_scale_x", 1.0),
        p("obj_mesh_wf_scale_y", 1.0),
        p("obj_mesh_wf_scale_z", 1.0),
        p("obj_mesh_wf_offset_x", 0.0),
        p("obj_mesh_wf_offset_y", 0.0),
        p("obj_mesh_wf_offset_z", 0.0),
        // JWildfire's own bounds (its `limitIntVal`).
        p_int("obj_mesh_wf_subdiv_level", 0.0, 0.0, 6.0).limited(),
        p_int("obj_mesh_wf_subdiv_smooth_passes", 12.0, 0.0, 24.0).limited(),
        p("obj_mesh_wf_subdiv_smooth_lambda", 0.42),
        p("obj_mesh_wf_subdiv_smooth_mu", -0.45),
        p_int("obj_mesh_wf_blend_colormap", 1.0, 0.0, 1.0),
        p("obj_mesh_wf_displ_amount", 0.1),
        p_int("obj_mesh_wf_blend_displ_map", 1.0, 0.0, 1.0),
        p_int("obj_mesh_wf_receive_only_shadows", 0.0, 0.0, 1.0),
    ])
    .texts(&[TextParam {
        name: "obj_mesh_wf_obj_filename",
        default: "",
        max_len: MAX_NAME,
    }])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z)
    .shared(&[6, 7, 8, 9], mesh_data)];

/// The default cube as triangles, each square split along its first diagonal (as JWildfire
/// splits a four-sided face).
fn cube() -> ResourceMesh {
    let faces = CUBE_SQUARES
        .iter()
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect();
    ResourceMesh {
        vertices: CUBE_VERTICES.to_vec(),
        faces,
    }
}

/// The shared data: the number n of triangles, the running totals of how often each is
/// picked (n values), then each triangle's three corners (9 values each).
fn mesh_data(p: &[f64], texts: &[String]) -> Vec<f64> {
    let [_, _, _, _, _, _, level, passes, lambda, mu] = params_of(p);
    let named = texts.first().filter(|t| !t.is_empty());
    let (m, counts) = match named.and_then(|t| resources::mesh(t)) {
        Some(m) if level >= 1.0 => {
            let mut m = (*m).clone();
            for _ in 0..level as usize {
                if m.faces.len() * 4 > resources::MAX_MESH_FACES {
                    break;
                }
                m = subdivide(&m);
                taubin(&mut m, passes as usize, lambda, mu);
            }
            let n = m.faces.len();
            (m, vec![1.0; n])
        }
        Some(m) => {
            let c = area_counts(&m);
            ((*m).clone(), c)
        }
        None => {
            let m = cube();
            let n = m.faces.len();
            (m, vec![1.0; n])
        }
    };
    let n = m.faces.len();
    let mut d = Vec::with_capacity(1 + 10 * n);
    d.push(n as f64);
    let mut total = 0.0;
    for c in &counts {
        total += c;
        d.push(total);
    }
    for f in &m.faces {
        for &i in f {
            let v = m.vertices[i as usize];
            d.extend(v.map(f64::from));
        }
    }
    d
}

/// How often JWildfire lists each triangle of a loaded mesh: its area over the smallest area,
/// rounded, at most 5000 (500 for a mesh of 5000 triangles or more); every triangle once
/// when all have the same area (within 10⁻⁸). A triangle of no area is not listed.
pub(super) fn area_counts(m: &ResourceMesh) -> Vec<f64> {
    let area = |f: &[u32; 3]| {
        let [a, b, c] = f.map(|i| m.vertices[i as usize].map(f64::from));
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let x = [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ];
        (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt()
    };
    let areas: Vec<f64> = m.faces.iter().map(area).collect();
    let lo = areas.iter().copied().fold(f64::MAX, f64::min);
    let hi = areas.iter().copied().fold(0.0, f64::max);
    if (lo - hi).abs() <= 1e-8 {
        return vec![1.0; areas.len()];
    }
    let most = if areas.len() < 5000 { 5000.0 } else { 500.0 };
    areas
        .iter()
        .map(|a| {
            let k = a / lo;
            // Java's rounding of a double to an int: NaN gives 0, ∞ the largest int.
            let k = if k.is_nan() { 0.0 } else { (k + 0.5).floor() };
            k.min(most)
        })
        .collect()
}

/// The key JWildfire merges vertices by: each coordinate times 10⁴, rounded half away from 0.
fn vertex_key(v: [f32; 3]) -> [i64; 3] {
    v.map(|c| {
        let x = f64::from(c) * 1e4;
        (x.abs() + 0.5).trunc().copysign(x) as i64
    })
}

/// Every triangle split into four at its edges' midpoints, vertices at the same place
/// (to 10⁻⁴) merged.
pub(super) fn subdivide(m: &ResourceMesh) -> ResourceMesh {
    let mut out = ResourceMesh {
        vertices: Vec::new(),
        faces: Vec::with_capacity(m.faces.len() * 4),
    };
    let mut index = std::collections::HashMap::new();
    let mut add = |v: [f32; 3], out: &mut ResourceMesh| -> u32 {
        *index.entry(vertex_key(v)).or_insert_with(|| {
            out.vertices.push(v);
            (out.vertices.len() - 1) as u32
        })
    };
    let mid = |a: [f32; 3], b: [f32; 3]| -> [f32; 3] {
        std::array::from_fn(|k| {
            (f64::from(a[k]) + (f64::from(b[k]) - f64::from(a[k])) * 0.5) as f32
        })
    };
    for f in &m.faces {
        let [a, b, c] = f.map(|i| m.vertices[i as usize]);
        let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
        let [n1, n2, n3, n4, n5, n6] = [a, b, c, ab, bc, ca].map(|v| add(v, &mut out));
        out.faces
            .extend([[n1, n4, n6], [n4, n2, n5], [n5, n3, n6], [n4, n5, n6]]);
    }
    out
}

/// Taubin smoothing: `passes` times, each vertex moved by λ, then by μ, times the mean of the
/// vectors to its neighbours (a vertex with fewer than two neighbours stays).
pub(super) fn taubin(m: &mut ResourceMesh, passes: usize, lambda: f64, mu: f64) {
    let mut nb: Vec<Vec<u32>> = vec![Vec::new(); m.vertices.len()];
    for f in &m.faces {
        for (a, b) in [(0, 1), (0, 2), (1, 0), (1, 2), (2, 0), (2, 1)] {
            let list = &mut nb[f[a] as usize];
            if !list.contains(&f[b]) {
                list.push(f[b]);
            }
        }
    }
    let step = |m: &mut ResourceMesh, strength: f64| {
        let moves: Vec<[f32; 3]> = (0..m.vertices.len())
            .map(|i| {
                let mut d = [0.0f32; 3];
                let list = &nb[i];
                if list.len() > 1 {
                    let w = 1.0 / list.len() as f64;
                    let v = m.vertices[i];
                    for &j in list {
                        let u = m.vertices[j as usize];
                        d = std::array::from_fn(|k| {
                            (f64::from(d[k]) + f64::from(u[k] - v[k]) * w) as f32
                        });
                    }
                }
                d
            })
            .collect();
        for (v, d) in m.vertices.iter_mut().zip(moves) {
            *v = std::array::from_fn(|k| (f64::from(v[k]) + f64::from(d[k]) * strength) as f32);
        }
    };
    for _ in 0..passes {
        step(m, lambda);
        step(m, mu);
    }
}

/// A vertex scaled and moved as JWildfire does it: each coordinate rounded to a `float`.
pub(super) fn place(v: [f64; 3], scale: [f64; 3], offset: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|k| (v[k] * scale[k] + offset[k]) as f32 as f64)
}

/// A uniform random point of the triangle (p1, p2, p3): the square root of one draw and a
/// second draw give its barycentric weights (Osada et al., "Shape distributions", 2002).
pub(super) fn point_in_triangle(p: [[f64; 3]; 3], rng: &mut FastRng) -> [f64; 3] {
    let s = rng.f01().sqrt();
    let r2 = rng.f01();
    let (a, b, c) = (1.0 - s, s * (1.0 - r2), r2 * s);
    std::array::from_fn(|k| a * p[0][k] + b * p[1][k] + c * p[2][k])
}

/// obj_mesh_wf: a random point of a random triangle of the mesh, times the weight.
fn obj_mesh_wf(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sx, sy, sz, ox, oy, oz] = v.params();
    mesh_point(v, [sx, sy, sz], [ox, oy, oz], rng)
}

/// A random point of a random triangle (picked by area) of the mesh in the variation's
/// shared data (count, running area totals, then nine corner coordinates per triangle),
/// scaled by `scale`, moved by `offset`, times the weight; the origin for an empty mesh.
pub(super) fn mesh_point(v: &Prepared, scale: V3, offset: V3, rng: &mut FastRng) -> V3 {
    let d = v.data();
    let n = d.first().map_or(0, |&n| n as usize);
    if n == 0 || d.len() < 1 + 10 * n {
        return [0.0; 3];
    }
    let totals = &d[1..1 + n];
    let total = totals[n - 1];
    // The triangle whose running total first exceeds a uniform pick below the total.
    let pick = rng.below(total as u64) as f64;
    let k = totals.partition_point(|&c| c <= pick).min(n - 1);
    let c = &d[1 + n + 9 * k..1 + n + 9 * k + 9];
    let corner = |i: usize| place([c[3 * i], c[3 * i + 1], c[3 * i + 2]], scale, offset);
    let p = point_in_triangle([corner(0), corner(1), corner(2)], rng);
    p.map(|c| v.w * c)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn prepared(texts: &[String], level: f64) -> Prepared {
        let mut p = DEFS[0].defaults();
        p[6] = level;
        Prepared::with_texts(
            super::super::by_name("obj_mesh_wf").unwrap(),
            Form::Regular,
            0.5,
            &p,
            texts,
            Default::default(),
            true,
        )
    }

    #[test]
    fn points_lie_on_the_cube_surface() {
        let v = prepared(&[], 0.0);
        let mut rng = FastRng::new(3);
        let t = VarIn::default();
        for _ in 0..1000 {
            let o = obj_mesh_wf(&v, &t, &mut Acc::default(), &mut rng);
            let m = o.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            assert!((m - 0.5).abs() < 1e-12, "{o:?}");
        }
    }

    #[test]
    fn a_handed_over_mesh_is_sampled_by_area() {
        // Two triangles in the plane z = 0: one of area 1/2, one of area 3/2 (three times).
        let m = ResourceMesh {
            vertices: vec![
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [-3.0, 0.0, 0.0],
                [0.0, -1.0, 0.0],
            ],
            faces: vec![[0, 1, 2], [0, 3, 4]],
        };
        assert!(resources::put_mesh("h9b-meshes-test.obj", m));
        let v = prepared(&["h9b-meshes-test.obj".to_string()], 0.0);
        let mut rng = FastRng::new(5);
        let t = VarIn::default();
        let n = 40_000;
        let mut first = 0;
        for _ in 0..n {
            let o = obj_mesh_wf(&v, &t, &mut Acc::default(), &mut rng);
            assert_eq!(o[2], 0.0);
            if o[0] > 0.0 || o[1] > 0.0 {
                first += 1;
            }
        }
        let share = first as f64 / n as f64;
        assert!((share - 0.25).abs() < 0.02, "{share}");
        // Subdivided: four times as many triangles, each picked alike; smoothing with no
        // passes keeps the points in the plane.
        let mut p = DEFS[0].defaults();
        p[6] = 1.0;
        p[7] = 0.0;
        let data = mesh_data(&params_normalised(&p), &["h9b-meshes-test.obj".to_string()]);
        assert_eq!(data[0], 8.0);
    }

    fn params_normalised(p: &[f64]) -> Vec<f64> {
        DEFS[0]
            .params
            .iter()
            .zip(p)
            .map(|(d, &v)| d.normalise(v))
            .collect()
    }
}
