//! The Menger sponge (Karl Menger, 1926): split the cube into 27 sub-cubes, remove the centre
//! cube and the six face centres, keep 20, and repeat on each. After n steps: 20ⁿ cubes of
//! side 3⁻ⁿ, volume (20/27)ⁿ, similarity dimension ln 20/ln 3 = 2.72683.
//!
//! The generator lists the kept cells on the 3ⁿ grid (a cell is kept unless, at some digit
//! position of the base-3 expansions of its coordinates, two or more of them are 1 — that is
//! the middle cross removed at that scale), and builds a mesh of the exposed faces only, with
//! neighbouring coplanar faces merged into rectangles so that step 4 stays small.

use std::collections::HashMap;

use glam::DVec3;

use super::mesh::Mesh;

/// Highest step a scene may ask for (step 4: 160 000 cubes).
pub const MAX_STEP: u32 = 4;

/// The numbers of the sponge after `step` steps, for a unit cube.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MengerNumbers {
    /// Number n of construction steps.
    pub step: u32,
    /// 20ⁿ.
    pub cubes: u64,
    /// Edge of one cube: 3⁻ⁿ.
    pub side: f64,
    /// (20/27)ⁿ.
    pub volume: f64,
    /// Surface area 2(20/9)ⁿ + 4(8/9)ⁿ (6 for the cube; the count of exposed unit faces of
    /// the grid, see `exposed_faces`, divided by 9ⁿ).
    pub area: f64,
    /// Similarity dimension ln 20/ln 3.
    pub dimension: f64,
}

/// The numbers of the sponge after `step` steps.
pub fn numbers(step: u32) -> MengerNumbers {
    let n = step as i32;
    MengerNumbers {
        step,
        cubes: 20u64.pow(step),
        side: 3f64.powi(-n),
        volume: (20.0f64 / 27.0).powi(n),
        area: 2.0 * (20.0f64 / 9.0).powi(n) + 4.0 * (8.0f64 / 9.0).powi(n),
        dimension: 20f64.ln() / 3f64.ln(),
    }
}

/// Is cell (x, y, z) of the 3ⁿ grid part of the sponge?
pub fn is_kept(mut x: u32, mut y: u32, mut z: u32, step: u32) -> bool {
    for _ in 0..step {
        let ones = (x % 3 == 1) as u32 + (y % 3 == 1) as u32 + (z % 3 == 1) as u32;
        if ones >= 2 {
            return false;
        }
        (x, y, z) = (x / 3, y / 3, z / 3);
    }
    true
}

/// The kept cells of the 3ⁿ grid (20ⁿ of them), x fastest.
pub fn cells(step: u32) -> Vec<[u32; 3]> {
    let step = step.min(MAX_STEP);
    let n = 3u32.pow(step);
    let mut out = Vec::with_capacity(20usize.pow(step));
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                if is_kept(x, y, z, step) {
                    out.push([x, y, z]);
                }
            }
        }
    }
    out
}

/// The cubes as boxes (min, max) for a sponge of edge `size` centred on the origin.
pub fn boxes(step: u32, size: f64) -> Vec<(DVec3, DVec3)> {
    let step = step.min(MAX_STEP);
    let s = size / 3f64.powi(step as i32);
    let o = DVec3::splat(-0.5 * size);
    cells(step)
        .into_iter()
        .map(|[x, y, z]| {
            let lo = o + DVec3::new(x as f64, y as f64, z as f64) * s;
            (lo, lo + DVec3::splat(s))
        })
        .collect()
}

/// The exposed faces as bitmaps: for each axis a (0..3), each side (0: facing −a, 1: +a) and
/// each grid plane p (0..=N), an N×N mask over the other two axes (in the order
/// (a + 1) % 3, (a + 2) % 3) of unit faces on the sponge's surface.
fn exposed_masks(step: u32) -> Vec<(usize, usize, usize, Vec<bool>)> {
    let n = 3usize.pow(step);
    let filled = |c: [i64; 3]| {
        c.iter().all(|&v| (0..n as i64).contains(&v))
            && is_kept(c[0] as u32, c[1] as u32, c[2] as u32, step)
    };
    let mut out = Vec::new();
    for a in 0..3 {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        for side in 0..2 {
            for p in 0..=n {
                let mut mask = vec![false; n * n];
                let mut any = false;
                for v in 0..n {
                    for u in 0..n {
                        // The face between cells p − 1 and p along a.
                        let mut lo = [0i64; 3];
                        lo[a] = p as i64 - 1;
                        lo[b] = u as i64;
                        lo[c] = v as i64;
                        let mut hi = lo;
                        hi[a] = p as i64;
                        // side 1 (normal +a): the lower cell is solid and the upper empty.
                        let (solid, empty) = if side == 1 { (lo, hi) } else { (hi, lo) };
                        if filled(solid) && !filled(empty) {
                            mask[v * n + u] = true;
                            any = true;
                        }
                    }
                }
                if any {
                    out.push((a, side, p, mask));
                }
            }
        }
    }
    out
}

/// Number of exposed unit faces (of side 3⁻ⁿ): the area of a unit sponge times 9ⁿ.
pub fn exposed_faces(step: u32) -> u64 {
    exposed_masks(step.min(MAX_STEP))
        .iter()
        .map(|(_, _, _, m)| m.iter().filter(|&&b| b).count() as u64)
        .sum()
}

/// Merge the set cells of an N×N mask into rectangles (u, v, width, height), greedily: grow
/// each rectangle along u, then along v while whole rows match.
fn rectangles(mask: &[bool], n: usize) -> Vec<[usize; 4]> {
    let mut used = vec![false; n * n];
    let mut out = Vec::new();
    for v in 0..n {
        let mut u = 0;
        while u < n {
            if !mask[v * n + u] || used[v * n + u] {
                u += 1;
                continue;
            }
            let mut w = 1;
            while u + w < n && mask[v * n + u + w] && !used[v * n + u + w] {
                w += 1;
            }
            let mut h = 1;
            'grow: while v + h < n {
                for k in u..u + w {
                    let i = (v + h) * n + k;
                    if !mask[i] || used[i] {
                        break 'grow;
                    }
                }
                h += 1;
            }
            for vv in v..v + h {
                for k in u..u + w {
                    used[vv * n + k] = true;
                }
            }
            out.push([u, v, w, h]);
            u += w;
        }
    }
    out
}

/// The sponge's surface as a mesh (edge `size`, centred on the origin): one flat rectangle
/// (two triangles) per merged group of exposed faces. Texture coordinates are the planar
/// projection onto the face's plane, (0, 0)–(1, 1) across the whole sponge.
pub fn mesh(step: u32, size: f64) -> Mesh {
    let step = step.min(MAX_STEP);
    let n = 3usize.pow(step);
    let cell = size / n as f64;
    let half = 0.5 * size;
    let mut m = Mesh::default();
    for (a, side, p, mask) in exposed_masks(step) {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        let mut normal = DVec3::ZERO;
        normal[a] = if side == 1 { 1.0 } else { -1.0 };
        let (mut eb, mut ec) = (DVec3::ZERO, DVec3::ZERO);
        eb[b] = 1.0;
        ec[c] = 1.0;
        // Rectangles of one plane share their corner vertices.
        let mut index: HashMap<(usize, usize), u32> = HashMap::new();
        for [u, v, w, h] in rectangles(&mask, n) {
            let q = [(0, 0), (w, 0), (w, h), (0, h)].map(|(du, dv)| {
                let (gu, gv) = (u + du, v + dv);
                *index.entry((gu, gv)).or_insert_with(|| {
                    let mut pos = DVec3::ZERO;
                    pos[a] = p as f64 * cell - half;
                    pos[b] = gu as f64 * cell - half;
                    pos[c] = gv as f64 * cell - half;
                    m.positions.push(pos);
                    m.normals.push(normal);
                    m.tex
                        .push([(gu as f64 / n as f64) as f32, (gv as f64 / n as f64) as f32]);
                    m.tangents.push((eb * size, ec * size));
                    m.positions.len() as u32 - 1
                })
            });
            // eb × ec = +a: counter-clockwise seen from outside for side 1.
            if side == 1 {
                m.triangles.push([q[0], q[1], q[2]]);
                m.triangles.push([q[0], q[2], q[3]]);
            } else {
                m.triangles.push([q[0], q[2], q[1]]);
                m.triangles.push([q[0], q[3], q[2]]);
            }
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_volume_area_and_dimension() {
        let d = numbers(0);
        assert_eq!((d.cubes, d.side, d.volume, d.area), (1, 1.0, 1.0, 6.0));
        assert!((d.dimension - 2.72683).abs() < 5e-6);
        assert!((numbers(1).area - 8.0).abs() < 1e-12);
        assert_eq!(numbers(4).cubes, 160_000);
        assert!((numbers(2).volume - 400.0 / 729.0).abs() < 1e-15);
        for step in 0..=MAX_STEP {
            let k = numbers(step);
            let c = cells(step);
            // 20ⁿ distinct cells.
            assert_eq!(c.len() as u64, k.cubes);
            let mut sorted = c.clone();
            sorted.sort_unstable();
            sorted.dedup();
            assert_eq!(sorted.len(), c.len());
            // The volume is the cubes times the side cubed.
            assert!((k.cubes as f64 * k.side.powi(3) - k.volume).abs() < 1e-12);
            // The area formula against a count of the exposed faces.
            let faces = exposed_faces(step);
            assert!(
                (faces as f64 / 9f64.powi(step as i32) - k.area).abs() < 1e-9,
                "step {step}: {faces} faces, area {}",
                k.area
            );
        }
        assert_eq!(exposed_faces(1), 72);
    }

    #[test]
    fn structure_of_step_one() {
        // The centre and the six face centres are gone; the corners and edges stay.
        let c = cells(1);
        assert!(!c.contains(&[1, 1, 1]));
        for f in [
            [1, 1, 0],
            [1, 0, 1],
            [0, 1, 1],
            [1, 1, 2],
            [1, 2, 1],
            [2, 1, 1],
        ] {
            assert!(!c.contains(&f));
        }
        assert!(c.contains(&[0, 0, 0]) && c.contains(&[1, 0, 0]) && c.contains(&[2, 2, 2]));
        // Self-similarity: step 2 is step 1 of step-1 blocks.
        let c2 = cells(2);
        for &[x, y, z] in &c2 {
            assert!(c.contains(&[x / 3, y / 3, z / 3]) && c.contains(&[x % 3, y % 3, z % 3]));
        }
        let b = boxes(1, 3.0);
        assert_eq!(b[0], (DVec3::splat(-1.5), DVec3::splat(-0.5)));
    }

    #[test]
    fn mesh_covers_the_exposed_area_with_few_rectangles() {
        for step in 0..=3 {
            let m = mesh(step, 2.0);
            let area: f64 = m
                .triangles
                .iter()
                .map(|t| {
                    let [a, b, c] = t.map(|i| m.positions[i as usize]);
                    0.5 * (b - a).cross(c - a).length()
                })
                .sum();
            assert!(
                (area - numbers(step).area * 4.0).abs() < 1e-9,
                "step {step}: {area}"
            );
            // Triangles wind so that their face normal is the vertex normal (outwards).
            for t in &m.triangles {
                let [a, b, c] = t.map(|i| m.positions[i as usize]);
                let n = (b - a).cross(c - a).normalize();
                assert!((n - m.normals[t[0] as usize]).length() < 1e-9);
            }
            assert!(
                m.positions
                    .iter()
                    .all(|p| p.abs().max_element() <= 1.0 + 1e-12)
            );
        }
        // Step 0 is the cube: six squares.
        assert_eq!(mesh(0, 1.0).triangles.len(), 12);
        // Merging and shared corners keep step 4 well below two triangles and four vertices
        // per exposed face (336 384 faces: 359 448 triangles).
        let m4 = mesh(4, 1.0);
        let faces = exposed_faces(4) as usize;
        assert_eq!(faces, 336_384);
        assert!(
            m4.triangles.len() < faces * 2 * 6 / 10,
            "{} triangles",
            m4.triangles.len()
        );
        assert!(
            m4.positions.len() < faces * 2,
            "{} vertices",
            m4.positions.len()
        );
    }
}
