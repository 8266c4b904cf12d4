//! JWildfire's `obj_mesh_primitive_wf`: a random point of a random triangle of one of its
//! built-in meshes, as `obj_mesh_wf` samples a loaded mesh (JWildfire 9.00,
//! `OBJMeshPrimitiveWFFunc` on `AbstractOBJMeshWFFunc`).
//!
//! JWildfire reads its primitives from OBJ files it ships. ugnis builds three of them from
//! their geometry instead:
//! * `primitive` 0, the ball: an icosahedron of radius 1/2 with a vertex on +y and one edge
//!   of its upper ring towards −z, each triangle split three times into four at its edges'
//!   midpoints, the new vertices pushed out to the sphere (642 vertices, 1280 triangles);
//! * 1, the capsule: a cylinder of radius 1/2 along z from −1/2 to 1/2 capped by half
//!   spheres, 24 sectors around, the cylinder cut into 8 bands and each cap into 8 rings of
//!   11.25°, triangles at the poles and quads (split along a diagonal) elsewhere;
//! * 2, the cone: apex (0, 1/2, 0), base circle of radius 1/2 at y = −1/2 through 24 points
//!   (the first at −z, then towards −x), the base cut into a zigzag strip of triangles.
//!
//! The other primitives JWildfire ships (diamond, torus, gears, polyhedra, …), and JWildfire's
//! own cone, are read from the user's JWildfire installation when one is named
//! ([`resources::JWILDFIRE`]); without one they, and indices outside the list, take
//! JWildfire's fallback mesh, the cube [−1, 1]³ (the cone: the one built here).
//! The mesh is then prepared as `obj_mesh_wf` prepares a loaded one: sampled by area with
//! `subdiv_level` 0, else subdivided and smoothed (Taubin's λ|μ smoothing) that many times,
//! stopping before the mesh would exceed [`MAX_FACES`] triangles.
//!
//! The geometry agrees with JWildfire's files to 10⁻⁶. The cone's base triangulation does
//! not: JWildfire's file cuts the base into an irregular set of triangles, and strong
//! smoothing (λ > 1) moves the vertices along that triangulation's edges, so a subdivided,
//! strongly smoothed cone differs from JWildfire's.

use super::jwf_h9b_meshes::{area_counts, mesh_point, subdivide, taubin};
use super::resources::{self, ResourceMesh};
use super::*;

/// JWildfire's primitives by index, each shipped as `<name>.obj` in JWildfire's jar
/// (JWildfire 9.00, `OBJMeshPrimitiveWFFunc`); the mandelbulb has no file and takes the
/// fallback cube.
const PRIMITIVES: [&str; 26] = [
    "ball",
    "capsule",
    "cone",
    "diamond",
    "torus",
    "box",
    "gear15",
    "icosahedron",
    "tetrahedron",
    "octahedron",
    "dodecahedron",
    "wedge",
    "icosidodecahedron",
    "cubeoctahedron",
    "gears6a",
    "gears6s",
    "gears8a",
    "gears8s",
    "gears12a",
    "gears12s",
    "gears16a",
    "gears16s",
    "gears24a",
    "gears24s",
    "mandelbulb",
    "drop",
];

/// Where JWildfire's jar keeps the primitives (read from a JWildfire installation, when the
/// user names one).
const MESH_PATH: &str = "jwildfire:org/jwildfire/create/tina/variation/mesh/";

/// Sectors around the capsule and the cone.
const SECTORS: usize = 24;
/// Rings of each half sphere of the capsule (from the pole to the equator).
const CAP_RINGS: usize = 8;
/// Bands of the capsule's cylinder.
const CYLINDER_BANDS: usize = 8;
/// Most triangles of a subdivided primitive: subdivision stops before the mesh would exceed
/// them (the ball's third level, 81,920 triangles, is the last it reaches).
const MAX_FACES: usize = 100_000;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("obj_mesh_primitive_wf", obj_mesh_primitive_wf)
    .params(&[
        p_int("obj_mesh_primitive_wf_primitive", 0.0, f64::MIN, f64::MAX),
        p("obj_mesh_primitive_wf_scale_x", 1.0),
        p("obj_mesh_primitive_wf_scale_y", 1.0),
        p("obj_mesh_primitive_wf_scale_z", 1.0),
        p("obj_mesh_primitive_wf_offset_x", 0.0),
        p("obj_mesh_primitive_wf_offset_y", 0.0),
        p("obj_mesh_primitive_wf_offset_z", 0.0),
        // JWildfire's own bounds (its `limitIntVal`).
        p_int("obj_mesh_primitive_wf_subdiv_level", 0.0, 0.0, 6.0).limited(),
        p_int(
            "obj_mesh_primitive_wf_subdiv_smooth_passes",
            12.0,
            0.0,
            24.0,
        )
        .limited(),
        p("obj_mesh_primitive_wf_subdiv_smooth_lambda", 0.42),
        p("obj_mesh_primitive_wf_subdiv_smooth_mu", -0.45),
        p_int("obj_mesh_primitive_wf_blend_colormap", 1.0, 0.0, 1.0),
        p("obj_mesh_primitive_wf_displ_amount", 0.1),
        p_int("obj_mesh_primitive_wf_blend_displ_map", 1.0, 0.0, 1.0),
        p_int("obj_mesh_primitive_wf_receive_only_shadows", 0.0, 0.0, 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z)
    .shared(&[0, 7, 8, 9, 10], mesh_data)];

/// A mesh from f64 vertices and triangles.
fn mesh(vertices: &[[f64; 3]], faces: Vec<[u32; 3]>) -> ResourceMesh {
    ResourceMesh {
        vertices: vertices.iter().map(|v| v.map(|c| c as f32)).collect(),
        faces,
    }
}

/// The ball: a thrice-subdivided icosahedron on the sphere of radius 1/2.
fn ball() -> ResourceMesh {
    let h = 1.0 / 5f64.sqrt();
    let rr = 2.0 * h;
    let mut v = vec![[0.0, 1.0, 0.0]];
    for k in 0..2 {
        for i in 0..5 {
            // The lower ring is turned by half a step against the upper one.
            let a = std::f64::consts::TAU * (i as f64 + 0.5 * k as f64) / 5.0;
            let y = if k == 0 { h } else { -h };
            v.push([rr * a.sin(), y, -rr * a.cos()]);
        }
    }
    v.push([0.0, -1.0, 0.0]);
    let mut f: Vec<[u32; 3]> = Vec::with_capacity(20);
    for i in 0..5u32 {
        let j = (i + 1) % 5;
        f.push([0, 1 + j, 1 + i]);
        f.push([1 + i, 1 + j, 6 + i]);
        f.push([1 + j, 6 + j, 6 + i]);
        f.push([11, 6 + i, 6 + j]);
    }
    for _ in 0..3 {
        let mut mids = std::collections::HashMap::new();
        let mut next = Vec::with_capacity(f.len() * 4);
        let mut mid = |a: u32, b: u32, v: &mut Vec<[f64; 3]>| -> u32 {
            *mids.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let (p, q) = (v[a as usize], v[b as usize]);
                let m: [f64; 3] = std::array::from_fn(|k| (p[k] + q[k]) / 2.0);
                let n = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
                v.push(m.map(|c| c / n));
                (v.len() - 1) as u32
            })
        };
        for &[a, b, c] in &f {
            let (ab, bc, ca) = (mid(a, b, &mut v), mid(b, c, &mut v), mid(c, a, &mut v));
            next.extend([[a, ab, ca], [ab, b, bc], [bc, c, ca], [ab, bc, ca]]);
        }
        f = next;
    }
    let v: Vec<[f64; 3]> = v.iter().map(|p| p.map(|c| c * 0.5)).collect();
    mesh(&v, f)
}

/// Rings of `SECTORS` vertices (radius, z) joined into bands of quads, closed by a pole
/// at each end: the capsule.
fn capsule() -> ResourceMesh {
    let quarter = std::f64::consts::FRAC_PI_2;
    let mut rings: Vec<(f64, f64)> = Vec::new();
    for k in 1..=CAP_RINGS {
        let t = quarter * k as f64 / CAP_RINGS as f64;
        rings.push((0.5 * t.sin(), -0.5 - 0.5 * t.cos()));
    }
    for k in 1..CYLINDER_BANDS {
        rings.push((0.5, -0.5 + k as f64 / CYLINDER_BANDS as f64));
    }
    for k in (1..=CAP_RINGS).rev() {
        let t = quarter * k as f64 / CAP_RINGS as f64;
        rings.push((0.5 * t.sin(), 0.5 + 0.5 * t.cos()));
    }
    let n = SECTORS as u32;
    let mut v = vec![[0.0, 0.0, -1.0]];
    for &(r, z) in &rings {
        for i in 0..SECTORS {
            let a = std::f64::consts::TAU * i as f64 / SECTORS as f64;
            v.push([r * a.cos(), r * a.sin(), z]);
        }
    }
    let top = v.len() as u32;
    v.push([0.0, 0.0, 1.0]);
    let mut f = Vec::new();
    for i in 0..n {
        f.push([0, 1 + (i + 1) % n, 1 + i]);
    }
    for k in 0..rings.len() as u32 - 1 {
        for i in 0..n {
            let a = 1 + k * n + i;
            let b = 1 + k * n + (i + 1) % n;
            // The quad (a, b, b + n, a + n) split along its diagonal from a.
            f.push([a, b, b + n]);
            f.push([a, b + n, a + n]);
        }
    }
    let last = 1 + (rings.len() as u32 - 1) * n;
    for i in 0..n {
        f.push([top, last + i, last + (i + 1) % n]);
    }
    mesh(&v, f)
}

/// The cone: its side from the apex to each base edge, its base a zigzag strip.
fn cone() -> ResourceMesh {
    let n = SECTORS as u32;
    let mut v: Vec<[f64; 3]> = (0..SECTORS)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / SECTORS as f64;
            [-0.5 * a.sin(), -0.5, -0.5 * a.cos()]
        })
        .collect();
    v.push([0.0, 0.5, 0.0]);
    let mut f: Vec<[u32; 3]> = (0..n).map(|i| [n, i, (i + 1) % n]).collect();
    // The base's corners taken alternately from both sides of corner 0.
    let mut order = vec![0u32];
    let (mut i, mut j) = (1, n - 1);
    while i <= j {
        order.push(i);
        i += 1;
        if i <= j {
            order.push(j);
            j -= 1;
        }
    }
    f.extend(order.windows(3).map(|w| [w[0], w[1], w[2]]));
    mesh(&v, f)
}

/// JWildfire's fallback: the cube [−1, 1]³, each square split along its first diagonal.
fn cube() -> ResourceMesh {
    let v = [
        [-1.0, -1.0, 1.0],
        [1.0, -1.0, 1.0],
        [1.0, 1.0, 1.0],
        [-1.0, 1.0, 1.0],
        [-1.0, -1.0, -1.0],
        [1.0, -1.0, -1.0],
        [1.0, 1.0, -1.0],
        [-1.0, 1.0, -1.0],
    ];
    let squares: [[u32; 4]; 6] = [
        [0, 1, 2, 3],
        [1, 5, 6, 2],
        [5, 6, 7, 4],
        [4, 7, 3, 0],
        [3, 2, 6, 7],
        [0, 1, 5, 4],
    ];
    let f = squares
        .iter()
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect();
    mesh(&v, f)
}

/// The shared data, laid out as `obj_mesh_wf`'s: the number n of triangles, the running
/// totals of how often each is picked (n values), then each triangle's corners (9 values).
fn mesh_data(p: &[f64], _texts: &[String]) -> Vec<f64> {
    let [primitive, _, _, _, _, _, _, level, passes, lambda, mu] = params_of(p);
    let shipped = PRIMITIVES
        .get(primitive as usize)
        .filter(|_| primitive >= 0.0)
        .and_then(|name| resources::mesh(&format!("{MESH_PATH}{name}.obj")));
    let (m, fallback) = if primitive == 0.0 {
        (ball(), false)
    } else if primitive == 1.0 {
        (capsule(), false)
    } else if let Some(m) = shipped {
        (m.as_ref().clone(), false)
    } else if primitive == 2.0 {
        (cone(), false)
    } else {
        (cube(), true)
    };
    let (m, counts) = if fallback {
        // JWildfire's fallback mesh is neither subdivided nor weighted.
        let n = m.faces.len();
        (m, vec![1.0; n])
    } else if level >= 1.0 {
        let mut m = m;
        for _ in 0..level as usize {
            if m.faces.len() * 4 > MAX_FACES {
                break;
            }
            m = subdivide(&m);
            taubin(&mut m, passes as usize, lambda, mu);
        }
        let n = m.faces.len();
        (m, vec![1.0; n])
    } else {
        let c = area_counts(&m);
        (m, c)
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
            d.extend(m.vertices[i as usize].map(f64::from));
        }
    }
    d
}

/// obj_mesh_primitive_wf: a random point of a random triangle of the primitive, times the
/// weight.
fn obj_mesh_primitive_wf(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, sx, sy, sz, ox, oy, oz] = v.params();
    mesh_point(v, [sx, sy, sz], [ox, oy, oz], rng)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn radius(v: [f32; 3]) -> f64 {
        v.iter()
            .map(|&c| f64::from(c) * f64::from(c))
            .sum::<f64>()
            .sqrt()
    }

    #[test]
    fn the_ball_is_a_closed_sphere_of_1280_triangles() {
        let m = ball();
        assert_eq!((m.vertices.len(), m.faces.len()), (642, 1280));
        for &v in &m.vertices {
            assert!((radius(v) - 0.5).abs() < 1e-6, "{v:?}");
        }
        // Closed: every edge is shared by exactly two triangles, once each way round.
        let mut edges = std::collections::HashMap::new();
        for f in &m.faces {
            for k in 0..3 {
                *edges.entry((f[k], f[(k + 1) % 3])).or_insert(0) += 1;
            }
        }
        for (&(a, b), &c) in &edges {
            assert_eq!((c, edges.get(&(b, a))), (1, Some(&1)));
        }
    }

    #[test]
    fn the_capsule_and_cone_have_their_shape() {
        let m = capsule();
        assert_eq!((m.vertices.len(), m.faces.len()), (554, 1104));
        for &v in &m.vertices {
            let z = f64::from(v[2]);
            // Distance from the axis segment z ∈ [−1/2, 1/2].
            let c = z.clamp(-0.5, 0.5);
            let d = (f64::from(v[0]).powi(2) + f64::from(v[1]).powi(2) + (z - c).powi(2)).sqrt();
            assert!((d - 0.5).abs() < 1e-6, "{v:?}");
        }
        let m = cone();
        assert_eq!((m.vertices.len(), m.faces.len()), (25, 46));
        // The base's triangles cover the 24-gon once: their areas add up to its area.
        let base: f64 = m.faces[SECTORS..]
            .iter()
            .map(|f| {
                let [a, b, c] = f.map(|i| m.vertices[i as usize].map(f64::from));
                ((b[0] - a[0]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[0] - a[0])).abs() / 2.0
            })
            .sum();
        let polygon = 0.5 * SECTORS as f64 * 0.25 * (std::f64::consts::TAU / 24.0).sin();
        assert!((base - polygon).abs() < 1e-6, "{base} {polygon}");
    }

    #[test]
    fn points_lie_on_the_ball() {
        let mut p = DEFS[0].defaults();
        p[1] = 2.0;
        let v = Prepared::with_texts(
            super::super::by_name("obj_mesh_primitive_wf").unwrap(),
            Form::Regular,
            0.5,
            &p,
            &[],
            Default::default(),
            true,
        );
        let mut rng = FastRng::new(9);
        for _ in 0..1000 {
            let o = obj_mesh_primitive_wf(&v, &VarIn::default(), &mut Acc::default(), &mut rng);
            // Scaled by 2 along x, times the weight 1/2: the ellipsoid (x/0.5)² + (y/0.25)²
            // + (z/0.25)² = 1, up to the flat triangles' sag.
            let e = (o[0] / 0.5).powi(2) + (o[1] / 0.25).powi(2) + (o[2] / 0.25).powi(2);
            assert!(e <= 1.0 + 1e-9 && e > 0.98, "{o:?} {e}");
        }
    }
}
