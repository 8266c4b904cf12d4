//! The planar maps of Craig S. Kaplan's Taprats (the Islamic star pattern designer JWildfire
//! 9.00 ships in `csk.taprats` for its `taprats` variation; GPL-3.0): vertices kept in
//! lexicographic order with a tolerance of 1e-7 (close points are one vertex), straight edges
//! kept in order of their least x, merged with the edges split where they cross; the tilings'
//! data types, the affine transforms, the segment intersections and the filling of a window
//! with translation units. Written anew from the algorithms (Kaplan, "Computer Generated
//! Islamic Star Patterns", Bridges 2000), keeping the order of the floating operations.

/// A point or vector.
pub(super) type P = [f64; 2];

/// An affine transform (a b c; d e f): x' = a·x + b·y + c, y' = d·x + e·y + f.
pub(super) type Tr = [f64; 6];

/// Taprats' tolerance for equal coordinates and distances.
pub(super) const TOL: f64 = 1e-7;

/// Most vertices or edges a map gets: merges stop adding beyond them.
pub(super) const MAX_ITEMS: usize = 60_000;

/// A tiling of the plane: a translational unit of placed features and its two translations.
pub(super) struct Tiling {
    /// Taprats' name of the tiling (checked by the tests).
    #[cfg_attr(not(test), allow(dead_code))]
    pub name: &'static str,
    pub t1: P,
    pub t2: P,
    pub features: &'static [TileFeature],
}

/// A tile shape and where the unit places it. `points` empty: the regular polygon of `sides`
/// sides whose edges' midpoints lie on the unit circle, one at (1, 0).
pub(super) struct TileFeature {
    pub sides: usize,
    pub points: &'static [P],
    pub placements: &'static [Tr],
}

impl TileFeature {
    pub fn is_regular(&self) -> bool {
        self.points.is_empty()
    }

    /// The polygon's corners.
    pub fn polygon(&self) -> Vec<P> {
        if !self.is_regular() {
            return self.points.to_vec();
        }
        let n = self.sides as f64;
        let sc = 1.0 / (std::f64::consts::PI / n).cos();
        (0..self.sides)
            .map(|i| {
                let a = (std::f64::consts::PI / n) * (2 * i + 1) as f64;
                [sc * a.cos(), sc * a.sin()]
            })
            .collect()
    }
}

pub(super) fn zero(a: f64) -> bool {
    a.abs() < TOL
}

pub(super) fn sub(a: P, b: P) -> P {
    [a[0] - b[0], a[1] - b[1]]
}

pub(super) fn add(a: P, b: P) -> P {
    [a[0] + b[0], a[1] + b[1]]
}

pub(super) fn scale(a: P, r: f64) -> P {
    [a[0] * r, a[1] * r]
}

pub(super) fn perp(a: P) -> P {
    [-a[1], a[0]]
}

pub(super) fn mag(a: P) -> f64 {
    (a[0] * a[0] + a[1] * a[1]).sqrt()
}

pub(super) fn dist(a: P, b: P) -> f64 {
    let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
    (dx * dx + dy * dy).sqrt()
}

/// The unit vector along `a` (`a` itself when it is 0).
pub(super) fn normalize(a: P) -> P {
    let m = mag(a);
    if m != 0.0 { scale(a, 1.0 / m) } else { a }
}

/// (1 − t)·a + t·b.
pub(super) fn convex_sum(a: P, b: P, t: f64) -> P {
    let mt = 1.0 - t;
    [mt * a[0] + t * b[0], mt * a[1] + t * b[1]]
}

pub(super) fn angle(a: P) -> f64 {
    a[1].atan2(a[0])
}

/// The counter-clockwise angle at `at` from the direction to `from` to that to `to`, in
/// [0, 2π).
pub(super) fn sweep(at: P, from: P, to: P) -> f64 {
    let mut res = angle(sub(to, at)) - angle(sub(from, at));
    for _ in 0..4 {
        if res >= 0.0 {
            break;
        }
        res += 2.0 * std::f64::consts::PI;
    }
    res
}

/// The distance from `x` to the segment p–q.
pub(super) fn dist_to_segment(x: P, p: P, q: P) -> f64 {
    let qmp = sub(q, p);
    let d = sub(x, p);
    let t = (d[0] * qmp[0] + d[1] * qmp[1]) / (qmp[0] * qmp[0] + qmp[1] * qmp[1]);
    if (0.0..=1.0).contains(&t) {
        let ox = p[0] + t * (q[0] - p[0]);
        let oy = p[1] + t * (q[1] - p[1]);
        ((x[0] - ox) * (x[0] - ox) + (x[1] - oy) * (x[1] - oy)).sqrt()
    } else if t < 0.0 {
        dist(p, x)
    } else {
        dist(q, x)
    }
}

pub(super) fn apply(t: &Tr, p: P) -> P {
    [
        t[0] * p[0] + t[1] * p[1] + t[2],
        t[3] * p[0] + t[4] * p[1] + t[5],
    ]
}

/// s ∘ t (t first).
pub(super) fn compose(s: &Tr, t: &Tr) -> Tr {
    [
        s[0] * t[0] + s[1] * t[3],
        s[0] * t[1] + s[1] * t[4],
        s[0] * t[2] + s[1] * t[5] + s[2],
        s[3] * t[0] + s[4] * t[3],
        s[3] * t[1] + s[4] * t[4],
        s[3] * t[2] + s[4] * t[5] + s[5],
    ]
}

pub(super) fn invert(t: &Tr) -> Option<Tr> {
    let [a, b, c, d, e, f] = *t;
    let det = a * e - b * d;
    (det != 0.0).then(|| {
        [
            e / det,
            -b / det,
            (b * f - c * e) / det,
            -d / det,
            a / det,
            (c * d - a * f) / det,
        ]
    })
}

pub(super) fn rotate(t: f64) -> Tr {
    [t.cos(), -t.sin(), 0.0, t.sin(), t.cos(), 0.0]
}

pub(super) fn translate(p: P) -> Tr {
    [1.0, 0.0, p[0], 0.0, 1.0, p[1]]
}

/// Where segments p1–q1 and p2–q2 cross, as the fractions (s, t) along each (within the
/// tolerance of their ends); `None` for parallel segments or no crossing.
fn intersection_params(p1: P, q1: P, p2: P, q2: P) -> Option<(f64, f64)> {
    let [p1x, p1y] = p1;
    let [q1x, q1y] = q1;
    let [p2x, p2y] = p2;
    let [q2x, q2y] = q2;
    let (d1x, d1y) = (q1x - p1x, q1y - p1y);
    let (d2x, d2y) = (q2x - p2x, q2y - p2y);
    let det = (d1x * d2y) - (d1y * d2x);
    if zero(det) {
        return None;
    }
    // O'Rourke, "Computational Geometry in C", segment–segment intersection.
    let s = -((p1x * d2y) + p2x * (p1y - q2y) + q2x * (p2y - p1y)) / det;
    let t = ((p1x * (p2y - q1y)) + q1x * (p1y - p2y) + p2x * d1y) / det;
    let inside = |u: f64| (-TOL..=1.0 + TOL).contains(&u);
    (inside(s) && inside(t)).then_some((s, t))
}

/// The crossing point of two segments.
pub(super) fn intersection(p1: P, q1: P, p2: P, q2: P) -> Option<P> {
    intersection_params(p1, q1, p2, q2).map(|(s, _)| convex_sum(p1, q1, s))
}

/// The crossing point of two segments unless it is an end of both.
pub(super) fn true_intersection(p1: P, q1: P, p2: P, q2: P) -> Option<P> {
    let (s, t) = intersection_params(p1, q1, p2, q2)?;
    let end = |u: f64| u < TOL || (1.0 - u) < TOL;
    if end(s) && end(t) {
        return None;
    }
    Some(convex_sum(p1, q1, s))
}

fn cmp_loose(d: f64) -> i8 {
    if zero(d) {
        0
    } else if d < 0.0 {
        -1
    } else {
        1
    }
}

/// Lexicographic order of points, with the tolerance.
fn cmp_points(a: P, b: P) -> i8 {
    match cmp_loose(a[0] - b[0]) {
        0 => cmp_loose(a[1] - b[1]),
        c => c,
    }
}

/// A planar map: vertex positions (by id) with their ids in lexicographic order, and edges
/// (ends by vertex id, oriented) with their ids in order of least x.
#[derive(Clone, Default, Debug)]
pub(super) struct Map {
    pub pos: Vec<P>,
    pub vorder: Vec<usize>,
    pub edges: Vec<[usize; 2]>,
    pub eorder: Vec<usize>,
}

impl Map {
    fn min_x(&self, e: usize) -> f64 {
        let [a, b] = self.edges[e];
        self.pos[a][0].min(self.pos[b][0])
    }

    pub fn full(&self) -> bool {
        self.pos.len() >= MAX_ITEMS || self.edges.len() >= MAX_ITEMS
    }

    /// The vertex at `pt` (within the tolerance), added when there is none.
    pub fn vertex_simple(&mut self, pt: P) -> usize {
        // Vertices more than the tolerance left of `pt` come first: skip them at once.
        let start = self
            .vorder
            .partition_point(|&v| self.pos[v][0] < pt[0] - 4.0 * TOL);
        for k in start..self.vorder.len() {
            let v = self.vorder[k];
            match cmp_points(pt, self.pos[v]) {
                0 => return v,
                c if c < 0 => {
                    self.pos.push(pt);
                    self.vorder.insert(k, self.pos.len() - 1);
                    return self.pos.len() - 1;
                }
                _ => {}
            }
        }
        self.pos.push(pt);
        self.vorder.push(self.pos.len() - 1);
        self.pos.len() - 1
    }

    fn place_edge(&mut self, e: usize) {
        let xm = self.min_x(e);
        let k = self
            .eorder
            .iter()
            .position(|&o| cmp_loose(xm - self.min_x(o)) < 0)
            .unwrap_or(self.eorder.len());
        self.eorder.insert(k, e);
    }

    /// Adds the edge v1–v2 (no check for crossings).
    pub fn insert_edge(&mut self, v1: usize, v2: usize) {
        self.edges.push([v1, v2]);
        self.place_edge(self.edges.len() - 1);
    }

    /// Splits the first edge passing through vertex `v` (not at its ends) there.
    fn split_edges_by(&mut self, v: usize) {
        let vp = self.pos[v];
        for k in 0..self.eorder.len() {
            let e = self.eorder[k];
            if cmp_loose(self.min_x(e) - vp[0]) > 0 {
                return;
            }
            let [v1, v2] = self.edges[e];
            let (p1, p2) = (self.pos[v1], self.pos[v2]);
            if zero(dist_to_segment(vp, p1, p2)) {
                if zero(dist(vp, p1)) || zero(dist(vp, p2)) {
                    continue;
                }
                self.edges.push([v, v2]);
                self.edges[e][1] = v;
                self.eorder.remove(k);
                self.place_edge(self.edges.len() - 1);
                self.place_edge(e);
                return;
            }
        }
    }

    /// The vertex at `pt`, splitting an edge through it.
    pub fn insert_vertex(&mut self, pt: P) -> usize {
        let v = self.vertex_simple(pt);
        self.split_edges_by(v);
        v
    }

    /// Moves every vertex by `t` and restores the orders.
    pub fn transform(&mut self, t: &Tr) {
        for p in &mut self.pos {
            *p = apply(t, *p);
        }
        let mut order = std::mem::take(&mut self.vorder);
        order.sort_by(|&a, &b| {
            let (p, q) = (self.pos[a], self.pos[b]);
            p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
        });
        // Points within the tolerance in x go by y: an insertion pass (never more than a few
        // swaps) with the loose order.
        for i in 1..order.len() {
            let mut j = i;
            while j > 0 && cmp_points(self.pos[order[j - 1]], self.pos[order[j]]) > 0 {
                order.swap(j - 1, j);
                j -= 1;
            }
        }
        self.vorder = order;
        self.sort_edges();
    }

    fn sort_edges(&mut self) {
        let mut order = std::mem::take(&mut self.eorder);
        order.sort_by(|&a, &b| self.min_x(a).total_cmp(&self.min_x(b)));
        self.eorder = order;
    }

    /// Adds copies of `other` moved by each transform, merging coincident vertices (the copies
    /// must meet at vertices only).
    pub fn merge_simple_many(&mut self, other: &Map, transforms: &[Tr]) {
        let mut copy = vec![0; other.pos.len()];
        for t in transforms {
            if self.full() {
                break;
            }
            for &v in &other.vorder {
                copy[v] = self.vertex_simple(apply(t, other.pos[v]));
            }
            for &e in &other.eorder {
                let [a, b] = other.edges[e];
                self.edges.push([copy[a], copy[b]]);
                self.eorder.push(self.edges.len() - 1);
            }
        }
        self.sort_edges();
    }

    /// Adds `other`, splitting both maps' edges where they cross.
    pub fn merge(&mut self, mut other: Map) {
        if self.full() {
            return;
        }
        let mut crossings = Vec::new();
        for &e in &other.eorder {
            let [a, b] = other.edges[e];
            let (ep, eq) = (other.pos[a], other.pos[b]);
            let exm = ep[0].max(eq[0]);
            for &c in &self.eorder {
                if cmp_loose(self.min_x(c) - exm) > 0 {
                    break;
                }
                let [ca, cb] = self.edges[c];
                if let Some(p) = true_intersection(ep, eq, self.pos[ca], self.pos[cb]) {
                    crossings.push(p);
                }
            }
            if crossings.len() > MAX_ITEMS {
                break;
            }
        }
        for p in crossings {
            self.insert_vertex(p);
            other.insert_vertex(p);
        }
        let copy = self.merge_vertices(&other);
        for &e in &other.eorder {
            let [a, b] = other.edges[e];
            self.edges.push([copy[a], copy[b]]);
            self.eorder.push(self.edges.len() - 1);
        }
        self.sort_edges();
    }

    /// Merges the vertices of `other` into this map's order, coincident ones becoming one;
    /// gives the id here of each vertex of `other`.
    fn merge_vertices(&mut self, other: &Map) -> Vec<usize> {
        let mut copy = vec![0; other.pos.len()];
        let mine = std::mem::take(&mut self.vorder);
        let mut order = Vec::with_capacity(mine.len() + other.vorder.len());
        let (mut i, mut j) = (0, 0);
        loop {
            let take_other = match (mine.get(i), other.vorder.get(j)) {
                (None, None) => break,
                (Some(&m), None) => {
                    order.push(m);
                    i += 1;
                    continue;
                }
                (None, Some(_)) => true,
                (Some(&m), Some(&o)) => match cmp_points(self.pos[m], other.pos[o]) {
                    c if c < 0 => {
                        order.push(m);
                        i += 1;
                        continue;
                    }
                    0 => {
                        order.push(m);
                        copy[o] = m;
                        i += 1;
                        j += 1;
                        continue;
                    }
                    _ => true,
                },
            };
            if take_other {
                let o = other.vorder[j];
                self.pos.push(other.pos[o]);
                copy[o] = self.pos.len() - 1;
                order.push(self.pos.len() - 1);
                j += 1;
            }
        }
        self.vorder = order;
        copy
    }
}

/// The translations (i, j) of a tiling's unit (by t1 and t2) that meet the convex
/// quadrilateral `region` (a scan of its rows in the lattice's own coordinates, as Taprats'
/// `FillRegion` does), at most `cap` of them; none for a degenerate lattice or more than
/// 1000 rows (where Taprats gives up).
pub(super) fn fill_region(region: &[P; 4], t1: P, t2: P, cap: usize) -> Vec<(i32, i32)> {
    let det = 1.0 / (t1[0] * t2[1] - t2[0] * t1[1]);
    let basis = [t2[1] * det, -t2[0] * det, -t1[1] * det, t1[0] * det];
    let ps = region.map(|[x, y]| [basis[0] * x + basis[1] * y, basis[2] * x + basis[3] * y]);
    if ps.iter().flatten().any(|v| !v.is_finite()) {
        return Vec::new();
    }
    let ymin = ps.iter().map(|p| p[1]).fold(ps[0][1], f64::min);
    let ymax = ps.iter().map(|p| p[1]).fold(ps[0][1], f64::max);
    let (iymin, iymax) = (ymin.floor() as i64, ymax.floor() as i64);
    if iymax - iymin > 999 {
        return Vec::new();
    }
    let rows = (iymax - iymin + 1) as usize;
    let mut xmins = vec![f64::MAX; rows];
    let mut xmaxs = vec![-f64::MAX; rows];
    let mut widen = |row: i64, x: f64| {
        if let Some(k) = usize::try_from(row - iymin).ok().filter(|&k| k < rows) {
            xmins[k] = xmins[k].min(x);
            xmaxs[k] = xmaxs[k].max(x);
        }
    };
    for lc in 0..4 {
        let (mut from, mut to) = (ps[lc], ps[(lc + 1) % 4]);
        if from[1] == to[1] {
            let row = from[1].floor() as i64;
            widen(row, from[0]);
            widen(row, to[0]);
            continue;
        }
        if from[1] > to[1] {
            std::mem::swap(&mut from, &mut to);
        }
        let [fx, fy] = from;
        let [tx, ty] = to;
        let mut y = fy.floor();
        let mut iy = y as i64;
        let iym = ty.floor() as i64;
        let m = (tx - fx) / (ty - fy);
        let mut x = fx + (y - fy) * m;
        while iy <= iym {
            let (nx, ny) = (x + m, y + 1.0);
            widen(iy, if y <= fy { fx } else { x });
            widen(iy, if ny > ty { tx } else { nx });
            iy += 1;
            y = ny;
            x = nx;
        }
    }
    let mut out = Vec::new();
    for (k, (&lo, &hi)) in xmins.iter().zip(&xmaxs).enumerate() {
        let y = iymin + k as i64;
        if lo > hi {
            continue;
        }
        let (start, end) = (lo.floor() as i64, hi.floor() as i64);
        for x in start..=end {
            if out.len() >= cap {
                return out;
            }
            out.push((x as i32, y as i32));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two crossing segments merged: both split at the crossing, five vertices, four edges.
    #[test]
    fn merge_splits_crossing_edges() {
        let mut a = Map::default();
        let (p, q) = (a.insert_vertex([-1.0, 0.0]), a.insert_vertex([1.0, 0.0]));
        a.insert_edge(p, q);
        let mut b = Map::default();
        let (p, q) = (b.insert_vertex([0.0, -1.0]), b.insert_vertex([0.0, 1.0]));
        b.insert_edge(p, q);
        a.merge(b);
        assert_eq!(a.vorder.len(), 5);
        assert_eq!(a.eorder.len(), 4);
        let centre = a.vorder.iter().find(|&&v| a.pos[v] == [0.0, 0.0]).copied();
        let centre = centre.expect("a vertex at the crossing");
        assert_eq!(a.edges.iter().filter(|e| e.contains(&centre)).count(), 4);
    }

    /// Close points are one vertex; vertices stay sorted; edges stay sorted by least x.
    #[test]
    fn vertices_merge_and_stay_sorted() {
        let mut m = Map::default();
        let pts = [
            [0.5, 0.1],
            [-0.2, 3.0],
            [0.5, 0.1 + 1e-9],
            [2.0, -1.0],
            [-0.2, -3.0],
        ];
        let ids: Vec<usize> = pts.iter().map(|&p| m.insert_vertex(p)).collect();
        assert_eq!(ids[0], ids[2]);
        assert_eq!(m.vorder.len(), 4);
        for w in m.vorder.windows(2) {
            assert!(cmp_points(m.pos[w[0]], m.pos[w[1]]) < 0);
        }
        m.insert_edge(ids[0], ids[3]);
        m.insert_edge(ids[1], ids[4]);
        let xs: Vec<f64> = m.eorder.iter().map(|&e| m.min_x(e)).collect();
        assert_eq!(xs, [-0.2, 0.5]);
        // A vertex in the middle of an edge splits it.
        let mid = m.insert_vertex([-0.2, 0.0]);
        assert_eq!(m.edges.len(), 3);
        assert_eq!(m.edges.iter().filter(|e| e.contains(&mid)).count(), 2);
    }

    /// The translations filling a window cover it: every point of the window lies in some
    /// translated unit cell.
    #[test]
    fn fill_region_covers_the_window() {
        let (t1, t2) = ([1.0, 0.2], [0.3, 0.9]);
        let region = [[-1.5, 1.5], [1.5, 1.5], [1.5, -1.5], [-1.5, -1.5]];
        let cells = fill_region(&region, t1, t2, 10_000);
        assert!(!cells.is_empty());
        for k in 0..=20 {
            for l in 0..=20 {
                let p = [-1.5 + 0.15 * k as f64, -1.5 + 0.15 * l as f64];
                // The lattice coordinates of p.
                let det = t1[0] * t2[1] - t2[0] * t1[1];
                let a = (p[0] * t2[1] - p[1] * t2[0]) / det;
                let b = (t1[0] * p[1] - t1[1] * p[0]) / det;
                let cell = (a.floor() as i32, b.floor() as i32);
                assert!(cells.contains(&cell), "{p:?} in {cell:?}");
            }
        }
    }
}
