//! JWildfire's `sunvoroni` (Jesus Sosa, after a mandala in R by fronkonstin.com): the Voronoi
//! diagram of a sunflower's seeds, its cells filled and/or its edges drawn; each call draws one
//! figure (a triangle of a cell or an edge) at random and returns a random point of it, with
//! the figure's colour.
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `SunflowerVoroniFunc` and `DrawFunc`,
//! written anew. The diagram is made as Lee Byrne's Mesh library (`megamu.mesh.Voronoi`, which
//! JWildfire uses) makes it: the seeds lifted to the paraboloid z = −(x² + y²) with three far
//! points around them, the convex hull of all of them by QuickHull3D ([`hull_faces`]), each
//! hull face's circumcentre a corner of the diagram. A seed's cell lists the corners of the
//! faces around it, starting from its first face (in the hull's order) and going on each time
//! to the first neighbouring face (in the same order) not yet listed; the direction round the
//! cell, and so the sign of its area, follows the hull's face order, which is why the hull is
//! computed exactly as QuickHull3D computes it. The seeds next to the far points get cells
//! reaching thousands of units out. Cells are cut into triangles by ear clipping as John W.
//! Ratcliff's public-domain `Triangulate` (flipcode, 2000; in JWildfire through Craig
//! Kaplan's Taprats) does it, and coloured by colour mode 0: the cell's signed area plus 1,
//! mod 1 (keeping the sign, so huge clockwise cells give negative colours); 1: the cell's
//! number / the number of cells; 2: a `java.util.Random` seeded with the area's integer part,
//! one draw per triangle. Edges have the outline colour and no thickness (`SunflowerVoroniFunc`
//! does not run `DrawFunc`'s `init`, which would set one).
//!
//! JWildfire's `init` fails for a seed that is no corner of the hull (a seed that lies within
//! QuickHull3D's tolerance of a face); ugnis leaves that seed's cell out.

use std::collections::HashMap;
use std::f64::consts::PI;

use super::jwf_a_cuts::JavaRandom;
use super::jwf_h5_draw::line_point;
use super::jwf_h9b_meshes::point_in_triangle;
use super::jwf_sv_quickhull::hull_faces;
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("sunvoroni", sunvoroni)
    .params(&[
        // JWildfire's bounds.
        p_int("sunvoroni_nPoints", 50.0, 10.0, 1000.0),
        p_int("sunvoroni_Iters", 3.0, 2.0, 4.0),
        p_range("sunvoroni_angle", 180.0, 0.0, 360.0),
        p_int("sunvoroni_color mode", 0.0, 0.0, 2.0),
        p_int("sunvoroni_outline", 0.0, 0.0, 1.0),
        p_int("sunvoroni_fill", 1.0, 0.0, 1.0),
        p_range("sunvoroni_outline color", 0.5, 0.0, 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
    // `Iters` (index 1) changes nothing.
    .shared(&[0, 2, 3, 4, 5, 6], sunvoroni_figures)];

/// The values one figure takes in the figure table: its kind (2 an edge, 3 a triangle), three
/// corners (an edge's third unused) and its colour.
const FIG: usize = 8;

/// Ratcliff's `Triangulate` threshold on twice a corner's signed area, a `float` 1e-10.
const SNIP_EPSILON: f64 = 1e-10f32 as f64;

/// The far points megamu adds around the seeds (on the paraboloid too): x, y, z.
const FAR: [[f64; 3]; 3] = [
    [-8000.0, 0.0, -64_000_000.0],
    [8000.0, 8000.0, -128_000_000.0],
    [8000.0, -8000.0, -128_000_000.0],
];

type P2 = [f64; 2];

/// A Voronoi diagram as megamu returns it: its edges (x1, y1, x2, y2) and each seed's cell
/// (its corners in megamu's order; empty for a seed that is no corner of the hull), all in
/// single precision.
pub(super) struct Diagram {
    pub edges: Vec<[f32; 4]>,
    pub regions: Vec<Vec<[f32; 2]>>,
}

/// The `n` seeds of the sunflower turning by `angle`·(3 − √5) degrees per seed, seed i at
/// radius √(i + 1)/√(n + 1), in single precision as JWildfire stores them.
pub(super) fn sunflower_seeds(n: usize, angle: f64) -> Vec<[f32; 2]> {
    let ang = angle * (3.0 - 5f64.sqrt());
    let rmax = ((n + 1) as f64).sqrt() / 30.0;
    (0..n)
        .map(|i| {
            let r = ((i + 1) as f64).sqrt() / 30.0;
            let t = (i + 1) as f64 * ang * PI / 180.0;
            [(r * t.cos() / rmax) as f32, (r * t.sin() / rmax) as f32]
        })
        .collect()
}

/// The Voronoi diagram of `seeds` as megamu computes it (see the module documentation);
/// `None` when the hull cannot be made.
pub(super) fn voronoi(seeds: &[[f32; 2]]) -> Option<Diagram> {
    let n = seeds.len();
    let mut q: Vec<[f64; 3]> = seeds
        .iter()
        .map(|&[x, y]| [f64::from(x), f64::from(y), f64::from(-(x * x + y * y))])
        .collect();
    q.extend_from_slice(&FAR);
    let faces = hull_faces(&q)?;
    if faces.iter().any(|f| f.len() < 3) {
        return None;
    }
    // The face of the three far points (the last face of far points only; the first face
    // when there is none).
    let artifact = faces
        .iter()
        .rposition(|f| f.len() >= 3 && f[..3].iter().all(|&k| k >= n))
        .unwrap_or(0);
    // Each face's circumcentre, from its first three corners.
    let dual: Vec<P2> = faces
        .iter()
        .map(|f| {
            let [x0, y0] = [q[f[0]][0], q[f[0]][1]];
            let [x1, y1] = [q[f[1]][0], q[f[1]][1]];
            let [x2, y2] = [q[f[2]][0], q[f[2]][1]];
            let (v1x, v1y) = (2.0 * (x1 - x0), 2.0 * (y1 - y0));
            let v1z = x0 * x0 - x1 * x1 + y0 * y0 - y1 * y1;
            let (v2x, v2y) = (2.0 * (x2 - x0), 2.0 * (y2 - y0));
            let v2z = x0 * x0 - x2 * x2 + y0 * y0 - y2 * y2;
            let tx = v1y * v2z - v1z * v2y;
            let ty = v1z * v2x - v1x * v2z;
            let tz = v1x * v2y - v1y * v2x;
            [tx / tz, ty / tz]
        })
        .collect();
    // The faces along each edge of the hull.
    let mut by_edge: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        for k in 0..f.len() {
            let (a, b) = (f[k], f[(k + 1) % f.len()]);
            by_edge.entry((a.min(b), a.max(b))).or_default().push(i);
        }
    }
    // megamu pairs the faces (i, then each earlier j) that share an edge, the artifact left
    // out: each pair an edge of the diagram, and each face's neighbours listed in the order
    // of the pairs (ascending).
    let mut links: Vec<Vec<usize>> = vec![Vec::new(); faces.len()];
    let mut edges = Vec::new();
    let mut buckets: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (i, f) in faces.iter().enumerate() {
        for &k in f {
            if k < n {
                buckets[k].push(i);
            }
        }
        let mut earlier: Vec<usize> = (0..f.len())
            .flat_map(|k| {
                let (a, b) = (f[k], f[(k + 1) % f.len()]);
                by_edge
                    .get(&(a.min(b), a.max(b)))
                    .into_iter()
                    .flatten()
                    .copied()
            })
            .filter(|&j| j < i)
            .collect();
        earlier.sort_unstable();
        earlier.dedup();
        if i == artifact {
            continue;
        }
        for j in earlier.into_iter().filter(|&j| j != artifact) {
            links[i].push(j);
            links[j].push(i);
            let ([x1, y1], [x2, y2]) = (dual[i], dual[j]);
            edges.push([x1 as f32, y1 as f32, x2 as f32, y2 as f32]);
        }
    }
    let regions = buckets
        .iter()
        .map(|bucket| {
            let Some(&first) = bucket.first() else {
                return Vec::new();
            };
            let mut order = vec![first];
            while let Some(&next) = links[order[order.len() - 1]]
                .iter()
                .find(|&&j| !order.contains(&j) && bucket.contains(&j))
            {
                order.push(next);
            }
            // megamu's polygon has room for every face of the bucket: corners the walk did
            // not reach stay at the origin.
            let mut cell: Vec<[f32; 2]> = order
                .iter()
                .map(|&f| [dual[f][0] as f32, dual[f][1] as f32])
                .collect();
            cell.resize(bucket.len(), [0.0, 0.0]);
            cell
        })
        .collect();
    Some(Diagram { edges, regions })
}

/// The signed area of a polygon (positive counter-clockwise).
pub(super) fn signed_area(c: &[P2]) -> f64 {
    let mut a = 0.0;
    let mut p = c.len().wrapping_sub(1);
    for q in 0..c.len() {
        a += c[p][0] * c[q][1] - c[q][0] * c[p][1];
        p = q;
    }
    a * 0.5
}

/// Whether `p` lies in the triangle (a, b, c) or on its edges (for a counter-clockwise one).
fn inside_triangle(a: P2, b: P2, c: P2, p: P2) -> bool {
    let (ax, ay) = (c[0] - b[0], c[1] - b[1]);
    let (bx, by) = (a[0] - c[0], a[1] - c[1]);
    let (cx, cy) = (b[0] - a[0], b[1] - a[1]);
    let (apx, apy) = (p[0] - a[0], p[1] - a[1]);
    let (bpx, bpy) = (p[0] - b[0], p[1] - b[1]);
    let (cpx, cpy) = (p[0] - c[0], p[1] - c[1]);
    let a_bp = ax * bpy - ay * bpx;
    let c_ap = cx * apy - cy * apx;
    let b_cp = bx * cpy - by * cpx;
    a_bp >= 0.0 && b_cp >= 0.0 && c_ap >= 0.0
}

/// Whether corners u, v, w of the remaining polygon `vv` (of `nv` corners) make an ear: a
/// counter-clockwise corner no other corner lies in.
fn snip(c: &[P2], [u, v, w]: [usize; 3], nv: usize, vv: &[usize]) -> bool {
    let (a, b, cc) = (c[vv[u]], c[vv[v]], c[vv[w]]);
    if SNIP_EPSILON > (b[0] - a[0]) * (cc[1] - a[1]) - (b[1] - a[1]) * (cc[0] - a[0]) {
        return false;
    }
    (0..nv)
        .filter(|&p| p != u && p != v && p != w)
        .all(|p| !inside_triangle(a, b, cc, c[vv[p]]))
}

/// The triangles (corner indices) ear clipping cuts polygon `c` into, as Ratcliff's
/// `Triangulate.Process` finds them: the corners taken counter-clockwise, an ear cut off at
/// the first corner that is one, going round from the last cut. Where no ear is found in two
/// rounds (a polygon that is not simple) it stops, keeping the triangles cut so far.
pub(super) fn ear_clip(c: &[P2]) -> Vec<[usize; 3]> {
    let n = c.len();
    let mut out = Vec::new();
    if n < 3 {
        return out;
    }
    let mut vv: Vec<usize> = if 0.0 < signed_area(c) {
        (0..n).collect()
    } else {
        (0..n).rev().collect()
    };
    let mut nv = n;
    let mut count = 2 * nv;
    let mut v = nv - 1;
    while nv > 2 {
        if count == 0 {
            break;
        }
        count -= 1;
        let u = if nv <= v { 0 } else { v };
        v = if nv <= u + 1 { 0 } else { u + 1 };
        let w = if nv <= v + 1 { 0 } else { v + 1 };
        if snip(c, [u, v, w], nv, &vv) {
            out.push([vv[u], vv[v], vv[w]]);
            vv.remove(v);
            nv -= 1;
            count = 2 * nv;
        }
    }
    out
}

/// sunvoroni's figures (see the module documentation): the edges (with `outline`, or when
/// neither `outline` nor `fill` is on), then the triangles of each cell in turn (with `fill`).
fn sunvoroni_figures(p: &[f64], _texts: &[String]) -> Vec<f64> {
    let [n, _, angle, mode, outline, fill, outline_color] = params_of(p);
    let n = if n.is_finite() {
        n.clamp(10.0, 1000.0) as usize
    } else {
        50
    };
    let fill = fill == 1.0;
    let outline = outline == 1.0 || !fill;
    let Some(diagram) = voronoi(&sunflower_seeds(n, angle)) else {
        return Vec::new();
    };
    let mut t = Vec::new();
    if outline {
        for &[x1, y1, x2, y2] in &diagram.edges {
            let e = [x1, y1, x2, y2].map(f64::from);
            t.extend_from_slice(&[2.0, e[0], e[1], e[2], e[3], 0.0, 0.0, outline_color]);
        }
    }
    if fill {
        let count = diagram.regions.len() as f64;
        for (i, region) in diagram.regions.iter().enumerate() {
            let c: Vec<P2> = region
                .iter()
                .map(|&[x, y]| [f64::from(x), f64::from(y)])
                .collect();
            let area = signed_area(&c);
            let mut random = JavaRandom::new(area as i64);
            let mut color = match mode as i32 {
                0 => (1.0 + area) % 1.0,
                1 => i as f64 / count,
                _ => 0.0,
            };
            for [a, b, d] in ear_clip(&c) {
                if mode as i32 == 2 {
                    color = random.next_f64();
                }
                let [a, b, d] = [c[a], c[b], c[d]];
                t.extend_from_slice(&[3.0, a[0], a[1], b[0], b[1], d[0], d[1], color]);
            }
        }
    }
    t
}

/// sunvoroni: a random point of a random figure, times the weight, with its colour.
fn sunvoroni(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let table = v.data();
    let count = table.len() / FIG;
    if count == 0 {
        return [0.0; 3];
    }
    let i = ((rng.f01() * count as f64) as usize).min(count - 1);
    let f = &table[i * FIG..(i + 1) * FIG];
    let (x, y) = if f[0] == 2.0 {
        line_point(rng, f[1], f[2], f[3], f[4])
    } else {
        let q = point_in_triangle(
            [[f[1], f[2], 0.0], [f[3], f[4], 0.0], [f[5], f[6], 0.0]],
            rng,
        );
        (q[0], q[1])
    };
    acc.color = f[7];
    [v.w * x, v.w * y, 0.0]
}

#[cfg(test)]
#[path = "jwf_sv_tests.rs"]
mod tests;
