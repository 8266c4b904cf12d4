//! JWildfire's `sattractor3D`: a tube around the orbit of a three-dimensional strange
//! attractor, sampled as a mesh (JWildfire 9.00, `Strange3DFunc` on `AbstractOBJMeshWFFunc`,
//! after Mikael Hvidtfeldt Christensen's "Strange Attractors",
//! <https://syntopia.github.io/StrangeAttractors/>).
//!
//! The orbit: each of the formulas x′, y′, z′ (Java expressions over x, y, z, `param_a` …
//! `param_h` and `pi`) advances its coordinate by Euler's method, `x ← x + x′·dt`, the three in
//! turn, each seeing the coordinates already advanced. From (`start_x`, `start_y`, `start_z`)
//! `warmup` steps of dt = `stepTime`/2 are taken first, then `steps`·1000 points, each two
//! such steps on from the last. Each point carries a frame: its tangent (the direction from
//! the last point), a normal (at the first point the x axis made perpendicular to the
//! tangent; after that the direction one whole `stepTime` step of the formulas would move the
//! point, made perpendicular to the tangent) and their cross product. Around each point lie
//! `facets` vertices on the circle of radius `radius` in the normal's and binormal's plane,
//! joined to the next point's by two triangles per side; a triangle from each end to the
//! orbit's first and last point closes the tube. A point of the variation is a uniform random
//! point of one triangle picked uniformly, scaled and moved per axis, times the weight.
//!
//! As JWildfire, the mesh merges vertices at the same place to 10⁻⁴ but numbers the
//! triangles' corners as if none had merged; a triangle whose corner then lies past the
//! vertices is left out (JWildfire fails on it).
//!
//! `presetId` picks one of JWildfire's 21 formula triples (0 Aizawa, 1 Anishchenko–Astakhov,
//! 2 Arneodo, 3 Bouali, 4 Bourke–Shaw, 5 Chen–Celikovsky, 6 Chen–Lee, 7 Chua, 8 Chen,
//! 9 Lotka–Volterra, 10 Rikitake, 11 TSUCS 1, 12 Dequan Li, 13 Halvorsen, 14 finance,
//! 15 Newton–Leipnik, 16 Nosé–Hoover, 17 Sprott–Linz, 18 Thomas, 19 TSUCS 2, 20 Dadras); a
//! formula given as text (`xformula`, …, as JWildfire's flame files carry them) replaces the
//! preset's. Unlike JWildfire's editor, picking a preset here does not also set the start,
//! step and `param_*` values the preset suggests. The subdivision, colour-map and
//! displacement parameters are kept for the file's sake: JWildfire does not use them here.

use super::jwf_h9b_meshes::{place, point_in_triangle};
use super::params::TextParam;
use super::resources;
use super::util::formula;
use super::*;

/// The formulas' variable names, in the order their values are passed.
const VARS: &[&str] = &[
    "x", "y", "z", "param_a", "param_b", "param_c", "param_d", "param_e", "param_f", "param_g",
    "param_h", "pi",
];

/// JWildfire's preset formulas (x′, y′, z′), by `presetId`.
const PRESETS: [[&str; 3]; 21] = [
    [
        "(z-param_b)*x-param_d*y",
        "param_d*x + (z-param_b)*y",
        "param_c + param_a*z - z*z*z/3 - (x*x+y*y)*(1+param_e*z)+ param_f*z*x*x*x",
    ],
    [
        "param_a*x + y - x*z",
        "-x",
        "-param_b*z + param_b*((x>0)?1:0)*x*x",
    ],
    ["y", "z", "-(param_a)*x - param_b*y -z + (param_c)* x*x*x"],
    [
        "x*(4-y) + param_a*z",
        "-y*(1-x*x)",
        "-x*(1.5-param_b*z)-0.5*z",
    ],
    [
        "-param_a *(x+y)",
        "-y - param_a*x*z",
        "param_a *x*y + param_b",
    ],
    ["param_a*(y-x)", "-x*z + param_c*y", "x*y-param_b*z"],
    ["param_a*x - y*z", "param_b*y+x*z", "param_c*z+x*y/3.0"],
    [
        "param_a*(y - x - (param_e*x + (param_d + param_e)*(fabs(x + 1) - fabs(x-1))))",
        "param_b *(x  - y + z)",
        "-param_c* y",
    ],
    [
        "param_a*(y-x)",
        "(param_c-param_a)*x -x*z + param_c*y",
        "x*y - param_b*z",
    ],
    [
        "x -x*y + param_c*x*x - param_a*z * x*x",
        "-y + x*y",
        "-param_b*z + param_a*z*x*x",
    ],
    [
        "-param_b*x + z*y",
        "-param_b *y + (z-param_a)*x",
        "1.0 -x*y",
    ],
    [
        "param_a*(y-x) + param_d*x*z",
        "param_f* y -x*z",
        "param_c*z +x*y -param_e*x*x",
    ],
    [
        "param_a*(y-x) + param_d*x*z",
        "param_b*x + param_f*y -x*z",
        "param_c*z + x*y - param_e*x*x",
    ],
    [
        "-param_a*x - 4*y - 4*z -y*y",
        "-param_a*y - 4*z - 4*x -z*z",
        "-param_a*z - 4*x - 4*y -x*x",
    ],
    [
        "(1/param_b - param_a)*x +z + x*y",
        "-param_b*y -x*x",
        "-x -param_c*z",
    ],
    [
        "-param_a*x + y + 10*y*z",
        "-x - 0.4*y + 5*x*z",
        "param_b* z - 5*x*y",
    ],
    ["y", "-x + y*z", "param_a - y*y"],
    ["y", "-x + y*z", "1.0 - y*y"],
    [
        "-param_b*x + sin(y)",
        "-param_b*y + sin(z)",
        "-param_b*z + sin(x)",
    ],
    [
        "param_a*(y-x)+ param_d*x*z",
        "param_b*x - x*z + param_f*y",
        "param_c*z + x*y - param_e*x*x",
    ],
    [
        "y - param_a*x + param_b*y*z",
        "param_c*y -x *z + z",
        "param_d*x*y - param_e*z",
    ],
];

/// Most bytes of a formula text.
const MAX_TEXT: usize = 4096;
/// Most warm-up steps.
const MAX_WARMUP: f64 = 1.0e6;
/// Most vertices around the tube.
const MAX_FACETS: f64 = 64.0;

const fn text(name: &'static str) -> TextParam {
    TextParam {
        name,
        default: "",
        max_len: MAX_TEXT,
    }
}

pub(super) static DEFS: &[VarDef] = &[VarDef::new("sattractor3D", sattractor3d)
    .params(&[
        p_int("sattractor3D_presetId", 0.0, -1.0, 20.0),
        p_int("sattractor3D_steps", 5.0, 0.0, 1000.0).limited(),
        p("sattractor3D_radius", 0.05),
        p("sattractor3D_stepTime", 0.02),
        p_int("sattractor3D_facets", 3.0, 0.0, MAX_FACETS).limited(),
        p("sattractor3D_start_x", 0.1),
        p("sattractor3D_start_y", 0.0),
        p("sattractor3D_start_z", 0.0),
        p_int("sattractor3D_warmup", 1000.0, 0.0, MAX_WARMUP).limited(),
        p("sattractor3D_param_a", 0.95),
        p("sattractor3D_param_b", 0.7),
        p("sattractor3D_param_c", 0.6),
        p("sattractor3D_param_d", 3.5),
        p("sattractor3D_param_e", 0.25),
        p("sattractor3D_param_f", 0.1),
        p("sattractor3D_param_g", 0.0),
        p("sattractor3D_param_h", 0.0),
        p("sattractor3D_scale_x", 1.0),
        p("sattractor3D_scale_y", 1.0),
        p("sattractor3D_scale_z", 1.0),
        p("sattractor3D_offset_x", 0.0),
        p("sattractor3D_offset_y", 0.0),
        p("sattractor3D_offset_z", 0.0),
        p_int("sattractor3D_subdiv_level", 0.0, 0.0, 6.0).limited(),
        p_int("sattractor3D_subdiv_smooth_passes", 12.0, 0.0, 24.0).limited(),
        p("sattractor3D_subdiv_smooth_lambda", 0.42),
        p("sattractor3D_subdiv_smooth_mu", -0.45),
        p_int("sattractor3D_blend_colormap", 1.0, 0.0, 1.0),
        p("sattractor3D_displ_amount", 0.1),
        p_int("sattractor3D_blend_displ_map", 1.0, 0.0, 1.0),
        p_int("sattractor3D_receive_only_shadows", 0.0, 0.0, 1.0),
    ])
    .texts(&[
        text("sattractor3D_xformula"),
        text("sattractor3D_yformula"),
        text("sattractor3D_zformula"),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z)
    .shared(
        &[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16],
        mesh_data,
    )];

/// Three-vectors as JWildfire's `Vector3` computes them.
type Vec3 = [f64; 3];

fn dot(a: Vec3, b: Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The vector times 1/|v| (a zero vector gives NaNs, as in JWildfire).
fn normalize(v: Vec3) -> Vec3 {
    let s = 1.0 / dot(v, v).sqrt();
    v.map(|c| c * s)
}

/// v less its part along n.
fn project_on_plane(v: Vec3, n: Vec3) -> Vec3 {
    let s = dot(n, v) / dot(n, n);
    [v[0] - n[0] * s, v[1] - n[1] * s, v[2] - n[2] * s]
}

fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The three compiled formulas and the parameters' values.
struct System {
    code: [Vec<f64>; 3],
    params: [f64; 8],
}

impl System {
    /// The formula k's value at p plus p[k], as JWildfire's `evaluateX` … return it:
    /// `p[k] + f(p)·dt`.
    fn advance(&self, k: usize, p: Vec3, dt: f64) -> f64 {
        let mut vars = [0.0; 12];
        vars[..3].copy_from_slice(&p);
        vars[3..11].copy_from_slice(&self.params);
        vars[11] = std::f64::consts::PI;
        p[k] + formula::run(&self.code[k], &vars) * dt
    }

    /// One Euler step, the coordinates in turn.
    fn step(&self, p: &mut Vec3, dt: f64) {
        for k in 0..3 {
            p[k] = self.advance(k, *p, dt);
        }
    }
}

/// JWildfire's `Tools.FTOI`: rounded half away from zero to a Java `int` (NaN gives 0).
fn ftoi(x: f64) -> i64 {
    let r = if x > 0.0 {
        x + 0.5
    } else if x < 0.0 {
        x - 0.5
    } else {
        0.0
    };
    // Java's cast saturates and maps NaN to 0.
    if r.is_nan() {
        0
    } else {
        r.clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i64
    }
}

/// The shared data: the number n of triangles, then each triangle's corners (9 values).
fn mesh_data(p: &[f64], texts: &[String]) -> Vec<f64> {
    let [
        preset,
        steps,
        radius,
        step_time,
        facets,
        sx,
        sy,
        sz,
        warmup,
        a,
        b,
        c,
        d,
        e,
        f,
        g,
        h,
    ] = params_of(p);
    let preset_formulas = (0.0..=20.0)
        .contains(&preset)
        .then(|| PRESETS[preset as usize]);
    let mut code: [Vec<f64>; 3] = Default::default();
    for k in 0..3 {
        let own = texts.get(k).map(|t| t.trim()).filter(|t| !t.is_empty());
        let Some(src) = own.or(preset_formulas.map(|f| f[k])) else {
            return vec![0.0];
        };
        match formula::compile(src, VARS) {
            Ok(c) => code[k] = c,
            Err(_) => return vec![0.0],
        }
    }
    let sys = System {
        code,
        params: [a, b, c, d, e, f, g, h],
    };
    let shape = facets as usize;
    // At most MAX_MESH_FACES triangles: 2·shape per ring.
    let most = resources::MAX_MESH_FACES / (2 * shape.max(1));
    let count = ((steps as usize) * 1000).min(most);
    if count == 0 || shape == 0 {
        return vec![0.0];
    }
    // The orbit and its frames.
    let half = step_time / 2.0;
    let mut at = [sx, sy, sz];
    for _ in 0..warmup as usize {
        sys.step(&mut at, half);
    }
    let mut pos = Vec::with_capacity(count);
    let mut tangents = Vec::with_capacity(count);
    let mut normals: Vec<Vec3> = Vec::with_capacity(count);
    for i in 0..count {
        let old = at;
        for _ in 0..2 {
            sys.step(&mut at, half);
        }
        let tangent = normalize([at[0] - old[0], at[1] - old[1], at[2] - old[2]]);
        let normal = if i == 0 {
            normalize(project_on_plane([1.0, 0.0, 0.0], tangent))
        } else {
            let moved: Vec3 = std::array::from_fn(|k| sys.advance(k, at, step_time));
            normalize(project_on_plane(
                [moved[0] - at[0], moved[1] - at[1], moved[2] - at[2]],
                tangent,
            ))
        };
        pos.push(at);
        tangents.push(tangent);
        normals.push(normal);
    }
    // The circle around each point.
    let circle: Vec<[f64; 2]> = (0..shape)
        .map(|i| {
            let t = i as f64 / (shape as f64 / 2.0) * std::f64::consts::PI;
            [t.cos() * radius, t.sin() * radius]
        })
        .collect();
    let mut vertices: Vec<[f32; 3]> = Vec::with_capacity(count * shape + 2);
    let mut index = std::collections::HashMap::new();
    let mut add = |v: Vec3| {
        let key = v.map(|c| ftoi(c * 1e4));
        if let std::collections::hash_map::Entry::Vacant(e) = index.entry(key) {
            e.insert(vertices.len());
            vertices.push(v.map(|c| c as f32));
        }
    };
    for i in 0..count {
        let (n, o) = (normals[i], pos[i]);
        let bn = normalize(cross(tangents[i], n));
        for s in &circle {
            add(std::array::from_fn(|k| o[k] + s[0] * n[k] + s[1] * bn[k]));
        }
    }
    add(pos[0]);
    add(pos[count - 1]);
    // The triangles, numbered as if no vertex had merged.
    let mut faces: Vec<[usize; 3]> = Vec::with_capacity(2 * count * shape + 2 * shape);
    let next = |j: usize, p: usize| if j == shape - 1 { p + 1 - shape } else { p + 1 };
    for i in 0..count - 1 {
        for j in 0..shape {
            let p1 = i * shape + j;
            let p2 = next(j, p1);
            let (p1n, p2n) = (p1 + shape, next(j, p1 + shape));
            faces.push([p1, p2, p1n]);
            faces.push([p1n, p2, p2n]);
        }
    }
    let (first, last) = (count * shape, count * shape + 1);
    for j in 0..shape {
        faces.push([next(j, j), j, first]);
        let p1 = (count - 1) * shape + j;
        faces.push([p1, next(j, p1), last]);
    }
    faces.retain(|f| f.iter().all(|&i| i < vertices.len()));
    let mut out = Vec::with_capacity(1 + 9 * faces.len());
    out.push(faces.len() as f64);
    for f in &faces {
        for &i in f {
            out.extend(vertices[i].map(f64::from));
        }
    }
    out
}

/// sattractor3D: a random point of a random triangle of the tube, times the weight.
fn sattractor3d(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let p: [f64; 23] = v.params();
    let [sx, sy, sz, ox, oy, oz] = params_of(&p[17..]);
    let d = v.data();
    let n = d.first().map_or(0, |&n| n as usize);
    if n == 0 || d.len() < 1 + 9 * n {
        return [0.0; 3];
    }
    let k = (rng.below(n as u64) as usize).min(n - 1);
    let c = &d[1 + 9 * k..1 + 9 * k + 9];
    let corner = |i: usize| {
        place(
            [c[3 * i], c[3 * i + 1], c[3 * i + 2]],
            [sx, sy, sz],
            [ox, oy, oz],
        )
    };
    let q = point_in_triangle([corner(0), corner(1), corner(2)], rng);
    q.map(|c| v.w * c)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data(preset: f64, steps: f64) -> Vec<f64> {
        let mut p = DEFS[0].defaults();
        p[0] = preset;
        p[1] = steps;
        mesh_data(&p, &[])
    }

    #[test]
    fn every_preset_compiles_and_gives_a_closed_tube() {
        for (k, preset) in PRESETS.iter().enumerate() {
            for f in preset {
                assert!(formula::compile(f, VARS).is_ok(), "{k}: {f}");
            }
        }
        // Aizawa with its own parameters (the defaults): 1000 rings of three vertices.
        let d = data(0.0, 1.0);
        assert_eq!(d[0], (2 * 999 * 3 + 2 * 3) as f64);
        // Every corner near the attractor (|x|, |y| < 2, −1 < z < 2.5).
        for c in d[1..].chunks(3) {
            assert!(c[0].abs() < 2.0 && c[1].abs() < 2.0 && c[2] > -1.0 && c[2] < 2.5);
        }
    }

    #[test]
    fn the_tube_keeps_its_radius() {
        // Each ring's three vertices lie at `radius` from their centre, 120° apart: the
        // side of the triangle they form is radius·√3.
        let d = data(0.0, 1.0);
        let side = 0.05 * 3f64.sqrt();
        // The first triangle's corners are ring 0's vertices 0 and 1 and ring 1's vertex 0.
        let c = &d[1..10];
        let dist = ((c[0] - c[3]).powi(2) + (c[1] - c[4]).powi(2) + (c[2] - c[5]).powi(2)).sqrt();
        assert!((dist - side).abs() < 1e-6, "{dist}");
    }

    #[test]
    fn no_formula_or_a_broken_one_gives_no_mesh() {
        assert_eq!(data(-1.0, 5.0), vec![0.0]);
        let p = DEFS[0].defaults();
        let t = ["x*(".to_string(), String::new(), String::new()];
        assert_eq!(mesh_data(&p, &t), vec![0.0]);
    }
}
