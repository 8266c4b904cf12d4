//! The convex hull of a set of points in space by the Quickhull algorithm, as John E. Lloyd's
//! QuickHull3D 1.4 (BSD licence: "Copyright John E. Lloyd, 2004", see
//! <https://www.cs.ubc.ca/~lloyd/java/quickhull3d.html>) computes it, followed closely so that
//! the faces come out in QuickHull3D's order, each face's corners in its order (JWildfire's
//! Voronoi diagrams, Lee Byrne's Mesh library, number their regions' corners by it).
//!
//! The algorithm (Barber, Dobkin and Huhdanpaa, "The Quickhull algorithm for convex hulls",
//! ACM TOMS 22(4), 1996): an initial simplex from the extreme points; each point outside the
//! hull is assigned to one face it lies above; repeatedly the farthest point above the first
//! such face is added, the faces it sees are removed and the horizon is joined to it by new
//! triangles, which are merged with their neighbours where the edge between them is not
//! clearly convex (within a distance tolerance derived from the coordinates' size).
//!
//! Faces, half-edges and vertices live in arenas and point at each other by index. Every loop
//! is bounded by a step budget, so that a broken structure (Lloyd's code throws an internal
//! error there) ends the build with `None` instead of looping.

/// No element (a null reference).
const NIL: usize = usize::MAX;
/// Precision of a double, as QuickHull3D writes it.
const DOUBLE_PREC: f64 = 2.220_446_049_250_313e-16;

/// Face marks.
const VISIBLE: u8 = 1;
const NON_CONVEX: u8 = 2;
const DELETED: u8 = 3;

/// The merge rules of the two passes after a point is added.
#[derive(Clone, Copy, PartialEq)]
enum Merge {
    /// Merge where the edge is not convex as seen from the larger face.
    WrtLargerFace,
    /// Merge where the edge is not convex as seen from either face.
    NonConvex,
}

type P3 = [f64; 3];

fn dot(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Scaled to length 1 unless it is within two ulps of that already (QuickHull3D's
/// `Vector3d.normalize`).
fn normalize(v: P3) -> P3 {
    let len_sqr = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    let err = len_sqr - 1.0;
    if err.abs() > 2.0 * DOUBLE_PREC {
        let len = len_sqr.sqrt();
        [v[0] / len, v[1] / len, v[2] / len]
    } else {
        v
    }
}

struct Vertex {
    pnt: P3,
    prev: usize,
    next: usize,
    /// The face the point is assigned to (lies above).
    face: usize,
}

struct HalfEdge {
    /// The vertex at the head.
    vertex: usize,
    face: usize,
    next: usize,
    prev: usize,
    opposite: usize,
}

struct Face {
    he0: usize,
    normal: P3,
    area: f64,
    centroid: P3,
    plane_offset: f64,
    num_verts: usize,
    mark: u8,
    /// The first of the points assigned to this face (they follow each other in `claimed`).
    outside: usize,
}

/// A doubly linked list of vertices through their `prev`/`next`.
#[derive(Clone, Copy)]
struct VertexList {
    head: usize,
    tail: usize,
}

impl VertexList {
    const EMPTY: VertexList = VertexList {
        head: NIL,
        tail: NIL,
    };

    fn add(&mut self, v: &mut [Vertex], x: usize) {
        if self.head == NIL {
            self.head = x;
        } else {
            v[self.tail].next = x;
        }
        v[x].prev = self.tail;
        v[x].next = NIL;
        self.tail = x;
    }

    /// Appends the chain starting at `x` (to its end).
    fn add_all(&mut self, v: &mut [Vertex], mut x: usize, budget: &mut usize) -> Option<()> {
        if self.head == NIL {
            self.head = x;
        } else {
            v[self.tail].next = x;
        }
        v[x].prev = self.tail;
        while v[x].next != NIL {
            tick(budget)?;
            x = v[x].next;
        }
        self.tail = x;
        Some(())
    }

    fn delete(&mut self, v: &mut [Vertex], x: usize) {
        self.delete_range(v, x, x);
    }

    /// Unlinks the run from `a` to `b`.
    fn delete_range(&mut self, v: &mut [Vertex], a: usize, b: usize) {
        let (prev, next) = (v[a].prev, v[b].next);
        if prev == NIL {
            self.head = next;
        } else {
            v[prev].next = next;
        }
        if next == NIL {
            self.tail = prev;
        } else {
            v[next].prev = prev;
        }
    }

    fn insert_before(&mut self, v: &mut [Vertex], x: usize, next: usize) {
        let prev = v[next].prev;
        v[x].prev = prev;
        if prev == NIL {
            self.head = x;
        } else {
            v[prev].next = x;
        }
        v[x].next = next;
        v[next].prev = x;
    }
}

/// Spends one step of the budget; `None` once it is spent.
fn tick(budget: &mut usize) -> Option<()> {
    *budget = budget.checked_sub(1)?;
    Some(())
}

struct Hull {
    v: Vec<Vertex>,
    he: Vec<HalfEdge>,
    f: Vec<Face>,
    /// Every face in the order it was made (deleted ones included until the end).
    faces: Vec<usize>,
    claimed: VertexList,
    unclaimed: VertexList,
    tolerance: f64,
    budget: usize,
}

/// The faces of the convex hull of `points`, in QuickHull3D's order, each as the indices of
/// its corners listed clockwise seen from outside (QuickHull3D's `getFaces(POINT_RELATIVE |
/// CLOCKWISE)`); `None` where QuickHull3D would refuse the points (fewer than four, all
/// coincident, collinear or coplanar within its tolerance, or not finite) or its structure
/// broke.
pub(super) fn hull_faces(points: &[P3]) -> Option<Vec<Vec<usize>>> {
    if points.len() < 4 || points.iter().flatten().any(|c| !c.is_finite()) {
        return None;
    }
    let n = points.len();
    let mut h = Hull {
        v: points
            .iter()
            .map(|&pnt| Vertex {
                pnt,
                prev: NIL,
                next: NIL,
                face: NIL,
            })
            .collect(),
        he: Vec::with_capacity(12 * n),
        f: Vec::with_capacity(4 * n),
        faces: Vec::with_capacity(4 * n),
        claimed: VertexList::EMPTY,
        unclaimed: VertexList::EMPTY,
        tolerance: 0.0,
        // Far more than the hull of a few thousand points takes.
        budget: 200_000 * n + 1_000_000,
    };
    let (max_v, min_v) = h.max_and_min();
    h.initial_simplex(max_v, min_v)?;
    let mut horizon = Vec::new();
    let mut new_faces = Vec::new();
    while let Some(eye) = h.next_point_to_add() {
        tick(&mut h.budget)?;
        h.add_point_to_hull(eye, &mut horizon, &mut new_faces)?;
    }
    let mut out = Vec::new();
    for &face in &h.faces {
        if h.f[face].mark != VISIBLE {
            continue;
        }
        // Clockwise: from the first edge's head backwards.
        let he0 = h.f[face].he0;
        let mut corners = Vec::with_capacity(h.f[face].num_verts);
        let mut e = he0;
        loop {
            tick(&mut h.budget)?;
            corners.push(h.he[e].vertex);
            e = h.he[e].prev;
            if e == he0 {
                break;
            }
        }
        out.push(corners);
    }
    Some(out)
}

impl Hull {
    fn head(&self, e: usize) -> usize {
        self.he[e].vertex
    }

    fn tail(&self, e: usize) -> usize {
        self.he[self.he[e].prev].vertex
    }

    fn opposite_face(&self, e: usize) -> usize {
        match self.he[e].opposite {
            NIL => NIL,
            o => self.he[o].face,
        }
    }

    fn set_opposite(&mut self, a: usize, b: usize) {
        self.he[a].opposite = b;
        self.he[b].opposite = a;
    }

    fn distance_to_plane(&self, face: usize, p: P3) -> f64 {
        let f = &self.f[face];
        f.normal[0] * p[0] + f.normal[1] * p[1] + f.normal[2] * p[2] - f.plane_offset
    }

    /// The `i`th edge from the face's first (backwards for negative `i`).
    fn edge(&self, face: usize, i: i32) -> usize {
        let mut e = self.f[face].he0;
        if i >= 0 {
            for _ in 0..i {
                e = self.he[e].next;
            }
        } else {
            for _ in 0..-i {
                e = self.he[e].prev;
            }
        }
        e
    }

    /// The extreme vertices along each axis, and the distance tolerance from the extents.
    fn max_and_min(&mut self) -> ([usize; 3], [usize; 3]) {
        let mut max_v = [0usize; 3];
        let mut min_v = [0usize; 3];
        let mut max = self.v[0].pnt;
        let mut min = self.v[0].pnt;
        for i in 1..self.v.len() {
            let p = self.v[i].pnt;
            for k in 0..3 {
                if p[k] > max[k] {
                    max[k] = p[k];
                    max_v[k] = i;
                } else if p[k] < min[k] {
                    min[k] = p[k];
                    // QuickHull3D 1.4 records a new least z as the greatest z's vertex
                    // (fixed in later releases); kept, as it picks the initial simplex.
                    if k == 2 {
                        max_v[k] = i;
                    } else {
                        min_v[k] = i;
                    }
                }
            }
        }
        self.tolerance = 3.0
            * DOUBLE_PREC
            * (max[0].abs().max(min[0].abs())
                + max[1].abs().max(min[1].abs())
                + max[2].abs().max(min[2].abs()));
        (max_v, min_v)
    }

    /// A new triangle face (v0, v1, v2), its half-edges linked in a ring (not yet to others).
    fn create_triangle(&mut self, v0: usize, v1: usize, v2: usize) -> usize {
        let face = self.f.len();
        let e0 = self.he.len();
        for (k, vertex) in [v0, v1, v2].into_iter().enumerate() {
            self.he.push(HalfEdge {
                vertex,
                face,
                next: e0 + (k + 1) % 3,
                prev: e0 + (k + 2) % 3,
                opposite: NIL,
            });
        }
        self.f.push(Face {
            he0: e0,
            normal: [0.0; 3],
            area: 0.0,
            centroid: [0.0; 3],
            plane_offset: 0.0,
            num_verts: 3,
            mark: VISIBLE,
            outside: NIL,
        });
        // A triangle's ring is whole, so the count cannot fail.
        let _ = self.normal_and_centroid(face);
        face
    }

    /// The face's normal (the sum of its fan's cross products, normalised), area, corner
    /// count, centroid and plane offset.
    fn normal_and_centroid(&mut self, face: usize) -> Option<()> {
        let he0 = self.f[face].he0;
        let e1 = self.he[he0].next;
        let mut e2 = self.he[e1].next;
        let p0 = self.v[self.head(he0)].pnt;
        let mut d2 = sub(self.v[self.head(e1)].pnt, p0);
        let mut normal = [0.0; 3];
        let mut num_verts = 2;
        while e2 != he0 {
            tick(&mut self.budget)?;
            let d1 = d2;
            d2 = sub(self.v[self.head(e2)].pnt, p0);
            normal[0] += d1[1] * d2[2] - d1[2] * d2[1];
            normal[1] += d1[2] * d2[0] - d1[0] * d2[2];
            normal[2] += d1[0] * d2[1] - d1[1] * d2[0];
            e2 = self.he[e2].next;
            num_verts += 1;
        }
        let area = dot(normal, normal).sqrt();
        let s = 1.0 / area;
        let normal = [s * normal[0], s * normal[1], s * normal[2]];
        let mut c = [0.0; 3];
        let mut e = he0;
        loop {
            tick(&mut self.budget)?;
            let p = self.v[self.head(e)].pnt;
            c = [c[0] + p[0], c[1] + p[1], c[2] + p[2]];
            e = self.he[e].next;
            if e == he0 {
                break;
            }
        }
        let s = 1.0 / num_verts as f64;
        let centroid = [s * c[0], s * c[1], s * c[2]];
        let f = &mut self.f[face];
        f.normal = normal;
        f.area = area;
        f.num_verts = num_verts;
        f.centroid = centroid;
        f.plane_offset = dot(normal, centroid);
        Some(())
    }

    fn add_point_to_face(&mut self, x: usize, face: usize) {
        self.v[x].face = face;
        match self.f[face].outside {
            NIL => self.claimed.add(&mut self.v, x),
            o => self.claimed.insert_before(&mut self.v, x, o),
        }
        self.f[face].outside = x;
    }

    fn remove_point_from_face(&mut self, x: usize, face: usize) {
        if x == self.f[face].outside {
            let next = self.v[x].next;
            self.f[face].outside = if next != NIL && self.v[next].face == face {
                next
            } else {
                NIL
            };
        }
        self.claimed.delete(&mut self.v, x);
    }

    /// Unlinks the face's points from `claimed`: the first of them (their chain ends after
    /// the last), or NIL.
    fn remove_all_points_from_face(&mut self, face: usize) -> Option<usize> {
        let first = self.f[face].outside;
        if first == NIL {
            return Some(NIL);
        }
        let mut end = first;
        while self.v[end].next != NIL && self.v[self.v[end].next].face == face {
            tick(&mut self.budget)?;
            end = self.v[end].next;
        }
        self.claimed.delete_range(&mut self.v, first, end);
        self.v[end].next = NIL;
        Some(first)
    }

    /// Hands the points of a removed face to `absorbing` (those above it) or to `unclaimed`.
    fn delete_face_points(&mut self, face: usize, absorbing: usize) -> Option<()> {
        let first = self.remove_all_points_from_face(face)?;
        if first == NIL {
            return Some(());
        }
        if absorbing == NIL {
            return self.unclaimed.add_all(&mut self.v, first, &mut self.budget);
        }
        let mut x = first;
        while x != NIL {
            tick(&mut self.budget)?;
            let next = self.v[x].next;
            if self.distance_to_plane(absorbing, self.v[x].pnt) > self.tolerance {
                self.add_point_to_face(x, absorbing);
            } else {
                self.unclaimed.add(&mut self.v, x);
            }
            x = next;
        }
        Some(())
    }

    /// The tetrahedron of the two points farthest apart along an axis, the point farthest
    /// from their line and the point farthest from the plane of the three; every other point
    /// assigned to the face it lies farthest above (beyond the tolerance).
    fn initial_simplex(&mut self, max_v: [usize; 3], min_v: [usize; 3]) -> Option<()> {
        let mut max = 0.0;
        let mut imax = 0;
        for i in 0..3 {
            let diff = self.v[max_v[i]].pnt[i] - self.v[min_v[i]].pnt[i];
            if diff > max {
                max = diff;
                imax = i;
            }
        }
        if max <= self.tolerance {
            return None;
        }
        let v0 = max_v[imax];
        let v1 = min_v[imax];
        let u01 = normalize(sub(self.v[v1].pnt, self.v[v0].pnt));
        let mut max_sqr = 0.0;
        let mut v2 = NIL;
        let mut nrml = [0.0; 3];
        for i in 0..self.v.len() {
            let xprod = cross(u01, sub(self.v[i].pnt, self.v[v0].pnt));
            let len_sqr = dot(xprod, xprod);
            if len_sqr > max_sqr && i != v0 && i != v1 {
                max_sqr = len_sqr;
                v2 = i;
                nrml = xprod;
            }
        }
        if v2 == NIL || max_sqr.sqrt() <= 100.0 * self.tolerance {
            return None;
        }
        let nrml = normalize(nrml);
        let d0 = dot(self.v[v2].pnt, nrml);
        let mut max_dist = 0.0;
        let mut v3 = NIL;
        for i in 0..self.v.len() {
            let dist = (dot(self.v[i].pnt, nrml) - d0).abs();
            if dist > max_dist && i != v0 && i != v1 && i != v2 {
                max_dist = dist;
                v3 = i;
            }
        }
        if v3 == NIL || max_dist.abs() <= 100.0 * self.tolerance {
            return None;
        }
        let tris = if dot(self.v[v3].pnt, nrml) - d0 < 0.0 {
            let tris = [
                self.create_triangle(v0, v1, v2),
                self.create_triangle(v3, v1, v0),
                self.create_triangle(v3, v2, v1),
                self.create_triangle(v3, v0, v2),
            ];
            for i in 0..3 {
                let k = (i + 1) % 3;
                let (a, b) = (self.edge(tris[i + 1], 1), self.edge(tris[k + 1], 0));
                self.set_opposite(a, b);
                let (a, b) = (self.edge(tris[i + 1], 2), self.edge(tris[0], k as i32));
                self.set_opposite(a, b);
            }
            tris
        } else {
            let tris = [
                self.create_triangle(v0, v2, v1),
                self.create_triangle(v3, v0, v1),
                self.create_triangle(v3, v1, v2),
                self.create_triangle(v3, v2, v0),
            ];
            for i in 0..3 {
                let k = (i + 1) % 3;
                let (a, b) = (self.edge(tris[i + 1], 0), self.edge(tris[k + 1], 1));
                self.set_opposite(a, b);
                let (a, b) = (
                    self.edge(tris[i + 1], 2),
                    self.edge(tris[0], ((3 - i) % 3) as i32),
                );
                self.set_opposite(a, b);
            }
            tris
        };
        self.faces.extend_from_slice(&tris);
        for i in 0..self.v.len() {
            if i == v0 || i == v1 || i == v2 || i == v3 {
                continue;
            }
            let mut max_dist = self.tolerance;
            let mut max_face = NIL;
            for &t in &tris {
                let dist = self.distance_to_plane(t, self.v[i].pnt);
                if dist > max_dist {
                    max_face = t;
                    max_dist = dist;
                }
            }
            if max_face != NIL {
                self.add_point_to_face(i, max_face);
            }
        }
        Some(())
    }

    /// The point farthest above the face of the first claimed point (none when no point is
    /// claimed, or none of that face's is above it).
    fn next_point_to_add(&self) -> Option<usize> {
        let head = self.claimed.head;
        if head == NIL {
            return None;
        }
        let eye_face = self.v[head].face;
        let mut eye = None;
        let mut max_dist = 0.0;
        let mut x = self.f[eye_face].outside;
        while x != NIL && self.v[x].face == eye_face {
            let dist = self.distance_to_plane(eye_face, self.v[x].pnt);
            if dist > max_dist {
                max_dist = dist;
                eye = Some(x);
            }
            x = self.v[x].next;
        }
        eye
    }

    fn add_point_to_hull(
        &mut self,
        eye: usize,
        horizon: &mut Vec<usize>,
        new_faces: &mut Vec<usize>,
    ) -> Option<()> {
        horizon.clear();
        self.unclaimed = VertexList::EMPTY;
        let eye_face = self.v[eye].face;
        self.remove_point_from_face(eye, eye_face);
        self.calculate_horizon(self.v[eye].pnt, eye_face, horizon)?;
        self.add_new_faces(new_faces, eye, horizon)?;
        // First pass: merge the faces that are not convex seen from the larger face.
        for &face in new_faces.iter() {
            if self.f[face].mark == VISIBLE {
                while self.adjacent_merge(face, Merge::WrtLargerFace)? {}
            }
        }
        // Second pass: merge those that are not convex seen from either face.
        for &face in new_faces.iter() {
            if self.f[face].mark == NON_CONVEX {
                self.f[face].mark = VISIBLE;
                while self.adjacent_merge(face, Merge::NonConvex)? {}
            }
        }
        self.resolve_unclaimed_points(new_faces)
    }

    /// Removes the faces the eye sees, starting from `face`, depth first across their edges
    /// (each face's edges in order, from the one it was entered by), and collects the edges
    /// between them and the faces it does not see: the horizon, in order around the eye. An
    /// explicit stack replaces QuickHull3D's recursion, in the same order.
    fn calculate_horizon(&mut self, eye: P3, face: usize, horizon: &mut Vec<usize>) -> Option<()> {
        // Per visited face: the edge it was entered by, the edge to look across next,
        // whether its ring is done.
        let mut stack: Vec<(usize, usize, bool)> = Vec::new();
        self.delete_face_points(face, NIL)?;
        self.f[face].mark = DELETED;
        let e0 = self.edge(face, 0);
        stack.push((e0, e0, false));
        while let Some(&(edge0, edge, done)) = stack.last() {
            tick(&mut self.budget)?;
            if done {
                stack.pop();
                continue;
            }
            let next = self.he[edge].next;
            if let Some(top) = stack.last_mut() {
                *top = (edge0, next, next == edge0);
            }
            let opp = self.opposite_face(edge);
            if opp == NIL {
                return None;
            }
            if self.f[opp].mark == VISIBLE {
                if self.distance_to_plane(opp, eye) > self.tolerance {
                    let entry = self.he[edge].opposite;
                    self.delete_face_points(opp, NIL)?;
                    self.f[opp].mark = DELETED;
                    stack.push((entry, self.he[entry].next, false));
                } else {
                    horizon.push(edge);
                }
            }
        }
        Some(())
    }

    /// A triangle from the eye to each horizon edge, in the horizon's order, linked to the
    /// face beyond the edge and to its neighbours.
    fn add_new_faces(
        &mut self,
        new_faces: &mut Vec<usize>,
        eye: usize,
        horizon: &[usize],
    ) -> Option<()> {
        new_faces.clear();
        let mut side_prev = NIL;
        let mut side_begin = NIL;
        for &h in horizon {
            let face = self.create_triangle(eye, self.tail(h), self.head(h));
            self.faces.push(face);
            let last = self.edge(face, -1);
            let beyond = self.he[h].opposite;
            if beyond == NIL {
                return None;
            }
            self.set_opposite(last, beyond);
            let side = self.edge(face, 0);
            if side_prev != NIL {
                let a = self.he[side].next;
                self.set_opposite(a, side_prev);
            } else {
                side_begin = side;
            }
            new_faces.push(face);
            side_prev = side;
        }
        if side_begin == NIL {
            return None;
        }
        let a = self.he[side_begin].next;
        self.set_opposite(a, side_prev);
        Some(())
    }

    /// Assigns each unclaimed point to the new face it lies farthest above (beyond the
    /// tolerance; the search stops at a face it lies 1000 tolerances above).
    fn resolve_unclaimed_points(&mut self, new_faces: &[usize]) -> Option<()> {
        let mut x = self.unclaimed.head;
        while x != NIL {
            tick(&mut self.budget)?;
            let next = self.v[x].next;
            let mut max_dist = self.tolerance;
            let mut max_face = NIL;
            for &face in new_faces {
                if self.f[face].mark == VISIBLE {
                    let dist = self.distance_to_plane(face, self.v[x].pnt);
                    if dist > max_dist {
                        max_dist = dist;
                        max_face = face;
                    }
                    if max_dist > 1000.0 * self.tolerance {
                        break;
                    }
                }
            }
            if max_face != NIL {
                self.add_point_to_face(x, max_face);
            }
            x = next;
        }
        Some(())
    }
}

// The merging of faces after a point is added.
#[path = "jwf_sv_quickhull_merge.rs"]
mod merge;
