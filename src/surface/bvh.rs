//! A bounding volume hierarchy over triangles (axis-aligned boxes, binned surface-area
//! heuristic; Goldsmith & Salmon 1987, Wald 2007) and the ray–triangle test of Möller and
//! Trumbore (1997). The ray caster keeps one per object, inside the object's bounding sphere.

use glam::DVec3;

/// An axis-aligned box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: DVec3,
    pub max: DVec3,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };

    pub fn grow(&mut self, p: DVec3) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    pub fn union(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }

    fn area(&self) -> f64 {
        let d = (self.max - self.min).max(DVec3::ZERO);
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }

    /// Slab test: the parameter interval [t_in, t_out] of o + t·d inside the box, if it
    /// overlaps [0, t_max]. `inv_d` = 1/d per component. (Equivalent to moving the ray onto
    /// the z axis and checking that the box's x and y ranges straddle 0.)
    #[inline]
    pub fn hit(&self, o: DVec3, inv_d: DVec3, t_max: f64) -> Option<f64> {
        let t0 = (self.min - o) * inv_d;
        let t1 = (self.max - o) * inv_d;
        let tn = t0.min(t1);
        let tf = t0.max(t1);
        let t_in = tn.max_element().max(0.0);
        let t_out = tf.min_element().min(t_max);
        // NaN (0·∞ for a ray in a slab's plane) compares false: counted as a hit, safely.
        if t_in <= t_out || t_in.is_nan() || t_out.is_nan() {
            Some(t_in)
        } else {
            None
        }
    }
}

/// A triangle prepared for intersection: v0 and the edges v1 − v0, v2 − v0.
#[derive(Clone, Copy, Debug)]
pub struct TriGeom {
    pub v0: DVec3,
    pub e1: DVec3,
    pub e2: DVec3,
}

impl TriGeom {
    pub fn new(a: DVec3, b: DVec3, c: DVec3) -> TriGeom {
        TriGeom {
            v0: a,
            e1: b - a,
            e2: c - a,
        }
    }

    /// Möller–Trumbore: (t, b1, b2) with the hit at v0 + b1·e1 + b2·e2, for t in (t_min, t_max).
    #[inline]
    pub fn intersect(&self, o: DVec3, d: DVec3, t_min: f64, t_max: f64) -> Option<(f64, f64, f64)> {
        let p = d.cross(self.e2);
        let det = self.e1.dot(p);
        if det.abs() < 1e-300 {
            return None;
        }
        let inv = 1.0 / det;
        let s = o - self.v0;
        let b1 = s.dot(p) * inv;
        if !(0.0..=1.0).contains(&b1) {
            return None;
        }
        let q = s.cross(self.e1);
        let b2 = d.dot(q) * inv;
        if b2 < 0.0 || b1 + b2 > 1.0 {
            return None;
        }
        let t = self.e2.dot(q) * inv;
        (t > t_min && t < t_max).then_some((t, b1, b2))
    }

    /// Barycentrics (b1, b2) of the point where the line o + t·d meets the triangle's plane
    /// (not clipped to the triangle), for texture footprints.
    pub fn plane_barycentrics(&self, o: DVec3, d: DVec3) -> Option<(f64, f64)> {
        let p = d.cross(self.e2);
        let det = self.e1.dot(p);
        if det.abs() < 1e-300 {
            return None;
        }
        let s = o - self.v0;
        let q = s.cross(self.e1);
        Some((s.dot(p) / det, d.dot(q) / det))
    }

    pub fn normal(&self) -> DVec3 {
        self.e1.cross(self.e2)
    }

    /// The triangle's box, padded by a relative 1e-9 so that rays grazing an edge that lies
    /// on the box's face are not lost to rounding in the slab test.
    pub fn bounds(&self) -> Aabb {
        let mut b = Aabb::EMPTY;
        b.grow(self.v0);
        b.grow(self.v0 + self.e1);
        b.grow(self.v0 + self.e2);
        let pad = (b.max - b.min + b.min.abs() + b.max.abs()) * 1e-9 + DVec3::splat(1e-300);
        Aabb {
            min: b.min - pad,
            max: b.max + pad,
        }
    }
}

#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    /// Leaf: first index into `order`; inner: index of the left child (right = left + 1).
    first: u32,
    /// Triangles in a leaf (0 for inner nodes).
    count: u32,
}

/// The hierarchy over a triangle list.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    /// Triangle indices, leaves referring to ranges.
    order: Vec<u32>,
    pub tris: Vec<TriGeom>,
}

const LEAF: usize = 4;
const BINS: usize = 12;

/// Bytes a hierarchy over n triangles needs at most (for memory estimates).
pub fn bytes_for(n: usize) -> usize {
    n * (std::mem::size_of::<TriGeom>() + 4 + 2 * std::mem::size_of::<Node>())
}

impl Bvh {
    pub fn build(tris: Vec<TriGeom>) -> Bvh {
        let n = tris.len();
        let bounds: Vec<Aabb> = tris.iter().map(|t| t.bounds()).collect();
        let centres: Vec<DVec3> = bounds.iter().map(|b| (b.min + b.max) * 0.5).collect();
        let mut bvh = Bvh {
            nodes: Vec::with_capacity(2 * n / LEAF + 1),
            order: (0..n as u32).collect(),
            tris,
        };
        if n == 0 {
            return bvh;
        }
        bvh.nodes.push(Node {
            bounds: Aabb::EMPTY,
            first: 0,
            count: n as u32,
        });
        // Explicit stack of nodes to split.
        let mut todo = vec![0usize];
        while let Some(ni) = todo.pop() {
            let (first, count) = (bvh.nodes[ni].first as usize, bvh.nodes[ni].count as usize);
            let range = &mut bvh.order[first..first + count];
            let mut bb = Aabb::EMPTY;
            let mut cb = Aabb::EMPTY;
            for &i in range.iter() {
                bb = bb.union(&bounds[i as usize]);
                cb.grow(centres[i as usize]);
            }
            bvh.nodes[ni].bounds = bb;
            if count <= LEAF {
                continue;
            }
            // Binned SAH along the widest centroid axis.
            let ext = cb.max - cb.min;
            let axis = if ext.x >= ext.y && ext.x >= ext.z {
                0
            } else if ext.y >= ext.z {
                1
            } else {
                2
            };
            if ext[axis] <= 0.0 {
                continue; // all centres coincide: keep as a (large) leaf
            }
            let bin_of = |i: u32| {
                let f = (centres[i as usize][axis] - cb.min[axis]) / ext[axis];
                ((f * BINS as f64) as usize).min(BINS - 1)
            };
            let mut bin_box = [Aabb::EMPTY; BINS];
            let mut bin_n = [0usize; BINS];
            for &i in range.iter() {
                let b = bin_of(i);
                bin_box[b] = bin_box[b].union(&bounds[i as usize]);
                bin_n[b] += 1;
            }
            let (mut best, mut best_cost) = (0, f64::INFINITY);
            for split in 1..BINS {
                let side = |bins: std::ops::Range<usize>| {
                    bins.fold((Aabb::EMPTY, 0), |(b, n), k| {
                        (b.union(&bin_box[k]), n + bin_n[k])
                    })
                };
                let ((lb, ln), (rb, rn)) = (side(0..split), side(split..BINS));
                if ln == 0 || rn == 0 {
                    continue;
                }
                let cost = lb.area() * ln as f64 + rb.area() * rn as f64;
                if cost < best_cost {
                    (best, best_cost) = (split, cost);
                }
            }
            if best == 0 {
                continue;
            }
            // Partition in place.
            let mut l = 0;
            for k in 0..count {
                if bin_of(range[k]) < best {
                    range.swap(l, k);
                    l += 1;
                }
            }
            let left = bvh.nodes.len();
            bvh.nodes.push(Node {
                bounds: Aabb::EMPTY,
                first: first as u32,
                count: l as u32,
            });
            bvh.nodes.push(Node {
                bounds: Aabb::EMPTY,
                first: (first + l) as u32,
                count: (count - l) as u32,
            });
            bvh.nodes[ni].first = left as u32;
            bvh.nodes[ni].count = 0;
            todo.push(left);
            todo.push(left + 1);
        }
        bvh
    }

    #[cfg(test)]
    pub fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::EMPTY, |n| n.bounds)
    }

    /// The nearest hit in (t_min, t_max): (triangle, t, b1, b2).
    pub fn nearest(
        &self,
        o: DVec3,
        d: DVec3,
        t_min: f64,
        t_max: f64,
    ) -> Option<(u32, f64, f64, f64)> {
        if self.nodes.is_empty() {
            return None;
        }
        let inv = d.recip();
        let mut best: Option<(u32, f64, f64, f64)> = None;
        let mut t_far = t_max;
        let mut stack = [0u32; 64];
        let mut sp = 0;
        let mut ni = 0usize;
        self.nodes[0].bounds.hit(o, inv, t_far)?;
        loop {
            let node = &self.nodes[ni];
            if node.count > 0 {
                for &ti in &self.order[node.first as usize..(node.first + node.count) as usize] {
                    if let Some((t, b1, b2)) = self.tris[ti as usize].intersect(o, d, t_min, t_far)
                    {
                        t_far = t;
                        best = Some((ti, t, b1, b2));
                    }
                }
            } else {
                let (l, r) = (node.first as usize, node.first as usize + 1);
                let hl = self.nodes[l].bounds.hit(o, inv, t_far);
                let hr = self.nodes[r].bounds.hit(o, inv, t_far);
                match (hl, hr) {
                    (Some(a), Some(b)) => {
                        // Nearer child first.
                        let (near, far) = if a <= b { (l, r) } else { (r, l) };
                        if sp < stack.len() {
                            stack[sp] = far as u32;
                            sp += 1;
                        }
                        ni = near;
                        continue;
                    }
                    (Some(_), None) => {
                        ni = l;
                        continue;
                    }
                    (None, Some(_)) => {
                        ni = r;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            // Pop, skipping nodes now beyond the nearest hit.
            loop {
                if sp == 0 {
                    return best;
                }
                sp -= 1;
                let cand = stack[sp] as usize;
                if self.nodes[cand].bounds.hit(o, inv, t_far).is_some() {
                    ni = cand;
                    break;
                }
            }
        }
    }

    /// Is anything hit in (t_min, t_max)? Triangle `skip` is ignored (the one a shadow ray
    /// starts on).
    pub fn any(&self, o: DVec3, d: DVec3, t_min: f64, t_max: f64, skip: Option<u32>) -> bool {
        if self.nodes.is_empty() {
            return false;
        }
        let inv = d.recip();
        let mut stack = [0u32; 64];
        let mut sp = 1;
        while sp > 0 {
            sp -= 1;
            let node = &self.nodes[stack[sp] as usize];
            if node.bounds.hit(o, inv, t_max).is_none() {
                continue;
            }
            if node.count > 0 {
                for &ti in &self.order[node.first as usize..(node.first + node.count) as usize] {
                    if Some(ti) != skip
                        && self.tris[ti as usize]
                            .intersect(o, d, t_min, t_max)
                            .is_some()
                    {
                        return true;
                    }
                }
            } else if sp + 2 <= stack.len() {
                stack[sp] = node.first;
                stack[sp + 1] = node.first + 1;
                sp += 2;
            }
        }
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(n: usize) -> Vec<TriGeom> {
        // A wavy height field of 2n² triangles.
        let h = |i: usize, j: usize| ((i as f64 * 0.7).sin() * (j as f64 * 0.3).cos()) * 0.2;
        let p = |i: usize, j: usize| DVec3::new(i as f64 / n as f64, h(i, j), j as f64 / n as f64);
        let mut t = Vec::new();
        for i in 0..n {
            for j in 0..n {
                t.push(TriGeom::new(p(i, j), p(i + 1, j), p(i + 1, j + 1)));
                t.push(TriGeom::new(p(i, j), p(i + 1, j + 1), p(i, j + 1)));
            }
        }
        t
    }

    #[test]
    fn moller_trumbore_basics() {
        let t = TriGeom::new(DVec3::ZERO, DVec3::X, DVec3::Y);
        let (tt, b1, b2) = t
            .intersect(DVec3::new(0.25, 0.5, 2.0), -DVec3::Z, 0.0, 10.0)
            .unwrap();
        assert!((tt - 2.0).abs() < 1e-15 && (b1 - 0.25).abs() < 1e-15 && (b2 - 0.5).abs() < 1e-15);
        assert!(
            t.intersect(DVec3::new(0.8, 0.8, 2.0), -DVec3::Z, 0.0, 10.0)
                .is_none()
        );
        assert!(
            t.intersect(DVec3::new(0.2, 0.2, 2.0), DVec3::Z, 0.0, 10.0)
                .is_none()
        );
        assert_eq!(
            t.plane_barycentrics(DVec3::new(2.0, 3.0, 1.0), -DVec3::Z),
            Some((2.0, 3.0))
        );
    }

    #[test]
    fn hierarchy_agrees_with_brute_force() {
        let tris = grid(30);
        let bvh = Bvh::build(tris.clone());
        let mut hits = 0;
        for k in 0..400 {
            let a = k as f64 * 0.618;
            let o = DVec3::new(
                0.5 + 0.8 * a.cos(),
                1.0 + 0.3 * (a * 1.7).sin(),
                0.5 + 0.8 * a.sin(),
            );
            let target = DVec3::new((k % 20) as f64 / 19.0, 0.0, (k / 20) as f64 / 19.0);
            let d = (target - o).normalize();
            let brute = tris
                .iter()
                .enumerate()
                .filter_map(|(i, t)| {
                    t.intersect(o, d, 1e-9, f64::INFINITY)
                        .map(|h| (i as u32, h.0))
                })
                .min_by(|a, b| a.1.total_cmp(&b.1));
            let fast = bvh.nearest(o, d, 1e-9, f64::INFINITY).map(|h| (h.0, h.1));
            // The same nearest distance (rays through a shared edge may report either
            // triangle).
            match (fast, brute) {
                (Some(f), Some(b)) => assert!((f.1 - b.1).abs() < 1e-12, "ray {k}: {f:?} {b:?}"),
                (f, b) => assert_eq!(f.is_some(), b.is_some(), "ray {k}: {f:?} {b:?}"),
            }
            assert_eq!(bvh.any(o, d, 1e-9, f64::INFINITY, None), brute.is_some());
            hits += brute.is_some() as usize;
        }
        assert!(hits > 300, "{hits}");
        // The root box holds every triangle.
        let b = bvh.bounds();
        for t in &tris {
            let tb = t.bounds();
            assert!(tb.min.cmpge(b.min).all() && tb.max.cmple(b.max).all());
        }
    }
}
