//! The drawing styles of Craig S. Kaplan's Taprats (as JWildfire 9.00 ships them in
//! `csk.taprats.ui1` for its `taprats` variation; GPL-3.0), turned into the figures JWildfire's
//! drawing base samples: each style makes segments (kind 2) and, when filling, triangles
//! (kind 3) from a design's planar map. Written anew from the algorithms, keeping the order of
//! the floating operations:
//! * plain (0): each edge, colour 0;
//! * outline (1): each edge as a band `width` wide (its outline, colour 1), mitred at bends and
//!   crossings, with its two long sides again in colour 0;
//! * interlace (2): the bands woven over and under at crossings (an edge's under end cut back
//!   by `gap`);
//! * emboss (3): the outline's bands with their two halves shaded by their facing (colour from
//!   0 to 1 for a light at 45°) and their middle line;
//! * filled (4): the regions between the lines, two-coloured (0 and 1);
//! * sketch (5): each edge drawn 8 times, its ends jittered by Java's generator (seed 279401),
//!   with a random colour.
//!
//! With `fill` a band or region is its triangles (ear clipping) instead of its sides.

use super::jwf_a_cuts::JavaRandom;
use super::jwf_sv_sunvoroni::ear_clip;
use super::jwf_tp_map::{Map, P, add, convex_sum, normalize, perp, scale, sub, sweep};

/// The values one figure takes: its kind (2 segment, 3 triangle), three points, its colour.
pub(super) const FIG: usize = 8;

/// Most figures a drawing gets.
pub(super) const MAX_FIGURES: usize = 400_000;

/// The figures being drawn.
#[derive(Default)]
pub(super) struct Figures(pub Vec<f64>);

impl Figures {
    fn full(&self) -> bool {
        self.0.len() >= MAX_FIGURES * FIG
    }

    /// Adds a segment; one with a non-finite end (a mitre of two edges lying on each other,
    /// infinitely long in Taprats) is left out.
    fn line(&mut self, a: P, b: P, color: f64) {
        if !self.full() && a.iter().chain(&b).all(|v| v.is_finite()) {
            self.0
                .extend_from_slice(&[2.0, a[0], a[1], b[0], b[1], 0.0, 0.0, color]);
        }
    }

    fn triangle(&mut self, a: P, b: P, c: P, color: f64) {
        if !self.full() && a.iter().chain(&b).chain(&c).all(|v| v.is_finite()) {
            self.0
                .extend_from_slice(&[3.0, a[0], a[1], b[0], b[1], c[0], c[1], color]);
        }
    }

    /// A closed polygon: its sides, or its triangles with `fill`.
    fn polygon(&mut self, pts: &[P], fill: bool, color: f64) {
        if fill {
            for [a, b, c] in triangulate(pts) {
                self.triangle(a, b, c, color);
            }
        } else {
            for (i, &a) in pts.iter().enumerate() {
                self.line(a, pts[(i + 1) % pts.len()], color);
            }
        }
    }
}

/// A simple polygon's triangles by ear clipping (John W. Ratcliff's `Triangulate`, which
/// Taprats has too; a polygon that finds no ear for a while, not simple, keeps the triangles
/// found).
pub(super) fn triangulate(contour: &[P]) -> Vec<[P; 3]> {
    ear_clip(contour)
        .into_iter()
        .map(|t| t.map(|k| contour[k]))
        .collect()
}

/// A map's vertices' edges in counter-clockwise order (Taprats' order by a monotone stand-in
/// for the angle).
struct Around(Vec<Vec<usize>>);

/// A monotone function of the direction's angle, in [0, 1) (Taprats' `pseudoAtan2`).
pub(super) fn pseudo_angle(d: P) -> f64 {
    let [x, y] = normalize(d);
    if x > 0.0 {
        if y >= 0.0 { y * 0.25 } else { 1.0 + y * 0.25 }
    } else if y > 0.0 {
        0.25 * (2.0 - y)
    } else {
        0.5 - y * 0.25
    }
}

impl Around {
    fn new(map: &Map) -> Around {
        let mut around: Vec<Vec<(f64, usize)>> = vec![Vec::new(); map.pos.len()];
        for &e in &map.eorder {
            let [a, b] = map.edges[e];
            around[a].push((pseudo_angle(sub(map.pos[b], map.pos[a])), e));
            around[b].push((pseudo_angle(sub(map.pos[a], map.pos[b])), e));
        }
        // Each list starts at the vertex's first edge in the map's order.
        Around(
            around
                .into_iter()
                .map(|mut l| {
                    let head = l.first().map(|x| x.1);
                    l.sort_by(|x, y| x.0.total_cmp(&y.0));
                    let k = l.iter().position(|x| Some(x.1) == head).unwrap_or(0);
                    l.rotate_left(k);
                    l.into_iter().map(|(_, e)| e).collect()
                })
                .collect(),
        )
    }

    /// The edges before and after `e` around `v`.
    fn before_after(&self, v: usize, e: usize) -> (usize, usize) {
        let l = &self.0[v];
        let k = l.iter().position(|&x| x == e).unwrap_or(0);
        (l[(k + l.len() - 1) % l.len()], l[(k + 1) % l.len()])
    }
}

fn other(map: &Map, e: usize, v: usize) -> usize {
    let [a, b] = map.edges[e];
    if a == v { b } else { a }
}

/// The mitre point of two bands `width` wide meeting at `joint` from `a` and `b` (on the
/// side swept counter-clockwise from a to b); `None` when they are straight on.
fn join_point(joint: P, a: P, b: P, width: f64) -> Option<P> {
    let th = sweep(joint, a, b);
    if (th - std::f64::consts::PI).abs() < 1e-7 {
        return None;
    }
    let d1 = normalize(sub(joint, a));
    let d2 = normalize(sub(joint, b));
    let l = width / th.sin();
    Some([
        joint[0] - (d1[0] + d2[0]) * l,
        joint[1] - (d1[1] + d2[1]) * l,
    ])
}

/// The band's two corners at the `to` end of edge `e` (below and above its direction).
fn outline_end(map: &Map, around: &Around, e: usize, from: usize, to: usize, w: f64) -> [P; 2] {
    let (pfrom, pto) = (map.pos[from], map.pos[to]);
    let side = scale(perp(normalize(sub(pto, pfrom))), w);
    let square = [sub(pto, side), add(pto, side)];
    match around.0[to].len() {
        1 => square,
        2 => {
            let (before, _) = around.before_after(to, e);
            match join_point(pto, pfrom, map.pos[other(map, before, to)], w) {
                Some(jp) => [jp, convex_sum(jp, pto, 2.0)],
                None => square,
            }
        }
        _ => {
            let (before, after) = around.before_after(to, e);
            let before_pt = map.pos[other(map, before, to)];
            let after_pt = map.pos[other(map, after, to)];
            // Taprats fails on a straight-on neighbour here; the square end stands in.
            [
                join_point(pto, pfrom, after_pt, w).unwrap_or(square[0]),
                join_point(pto, before_pt, pfrom, w).unwrap_or(square[1]),
            ]
        }
    }
}

/// Each edge's band as six points: the two corners and the middle at either end (the middle
/// being the vertex for the outline), in the map's edge order.
fn outline_bands(map: &Map, w: f64) -> Vec<[P; 6]> {
    let around = Around::new(map);
    map.eorder
        .iter()
        .map(|&e| {
            let [v1, v2] = map.edges[e];
            let top = outline_end(map, &around, e, v1, v2, w);
            let back = outline_end(map, &around, e, v2, v1, w);
            [top[0], map.pos[v2], top[1], back[0], map.pos[v1], back[1]]
        })
        .collect()
}

/// Whether each edge (by id) starts under at its first vertex: the over–under alternation
/// spread from each unvisited edge in order (taken to start under), along bends unchanged and
/// across crossings alternating, depth first as Taprats recurses.
fn interlacing(map: &Map, around: &Around) -> Vec<bool> {
    enum Task {
        Build(usize, bool),
        Spread(usize, usize, bool),
    }
    let mut edge_seen = vec![false; map.edges.len()];
    let mut start_under = vec![false; map.edges.len()];
    let mut vert_seen = vec![false; map.pos.len()];
    let mut stack = Vec::new();
    for &first in &map.eorder {
        if edge_seen[first] {
            continue;
        }
        stack.push(Task::Build(first, true));
        while let Some(task) = stack.pop() {
            match task {
                Task::Build(e, under) => {
                    if edge_seen[e] {
                        continue;
                    }
                    edge_seen[e] = true;
                    start_under[e] = under;
                    let [v1, v2] = map.edges[e];
                    stack.push(Task::Spread(v2, e, !under));
                    stack.push(Task::Spread(v1, e, under));
                }
                Task::Spread(v, e, under) => {
                    if vert_seen[v] {
                        continue;
                    }
                    vert_seen[v] = true;
                    let l = &around.0[v];
                    let nn = l.len();
                    let starts_here = |oe: usize| map.edges[oe][0] == v;
                    if nn == 2 {
                        let (oe, _) = around.before_after(v, e);
                        stack.push(Task::Build(oe, under != starts_here(oe)));
                    } else if nn > 2 {
                        let k = l.iter().rposition(|&x| x == e).unwrap_or(0);
                        let mut cur = under;
                        let mut next = Vec::with_capacity(nn);
                        for idx in 1..nn {
                            let oe = l[(k + idx) % nn];
                            next.push(Task::Build(oe, cur != starts_here(oe)));
                            cur = !cur;
                        }
                        stack.extend(next.into_iter().rev());
                    }
                }
            }
        }
    }
    start_under
}

/// The woven band's below, middle and above points at the `to` end of edge `e`.
#[allow(clippy::too_many_arguments)]
fn interlace_end(
    map: &Map,
    around: &Around,
    under: &[bool],
    e: usize,
    from: usize,
    to: usize,
    width: f64,
    gap: f64,
) -> [P; 3] {
    let from_under = (map.edges[e][0] == from) == under[e];
    let (pfrom, pto) = (map.pos[from], map.pos[to]);
    let dir = normalize(sub(pto, pfrom));
    let side = perp(dir);
    let l = &around.0[to];
    let nn = l.len();
    if nn == 1 {
        let (s, d) = (scale(side, width), scale(dir, width));
        return [add(sub(pto, s), d), add(pto, d), add(add(pto, s), d)];
    }
    if nn == 2 {
        let [below, above] = outline_end(map, around, e, from, to, width);
        return [below, pto, above];
    }
    if from_under {
        let k = l.iter().rposition(|&x| x == e).unwrap_or(0);
        let op = map.pos[other(map, l[(k + 2) % nn], to)];
        let below =
            join_point(pto, pfrom, op, width).unwrap_or_else(|| sub(pto, scale(side, width)));
        return [below, pto, convex_sum(below, pto, 2.0)];
    }
    let (before, after) = around.before_after(to, e);
    let before_pt = map.pos[other(map, before, to)];
    let after_pt = map.pos[other(map, after, to)];
    let below =
        join_point(pto, pfrom, after_pt, width).unwrap_or_else(|| sub(pto, scale(side, width)));
    let above =
        join_point(pto, before_pt, pfrom, width).unwrap_or_else(|| add(pto, scale(side, width)));
    let cen = join_point(pto, before_pt, after_pt, width).unwrap_or_else(|| {
        let ab = scale(perp(normalize(sub(after_pt, before_pt))), width);
        sub(pto, ab)
    });
    let back = scale(dir, gap);
    [sub(below, back), sub(cen, back), sub(above, back)]
}

/// The figures of `map` in style `style` (0–5).
pub(super) fn draw(map: &Map, style: i32, width: f64, gap: f64, fill: bool) -> Vec<f64> {
    let mut f = Figures::default();
    match style {
        4 => {
            let (black, white) = faces(map);
            for face in &white {
                f.polygon(face, fill, 0.0);
            }
            for face in &black {
                f.polygon(face, fill, 1.0);
            }
        }
        1 | 3 => {
            for b in outline_bands(map, width) {
                if style == 1 {
                    f.polygon(&b, fill, 1.0);
                    f.line(b[2], b[3], 0.0);
                    f.line(b[5], b[0], 0.0);
                } else {
                    emboss_half(&mut f, [b[1], b[2], b[3], b[4]], fill);
                    emboss_half(&mut f, [b[4], b[5], b[0], b[1]], fill);
                    f.polygon(&b, fill, 1.0);
                    f.line(b[1], b[4], 0.0);
                }
            }
        }
        2 => {
            let around = Around::new(map);
            let under = interlacing(map, &around);
            let bands: Vec<[P; 6]> = map
                .eorder
                .iter()
                .map(|&e| {
                    let [v1, v2] = map.edges[e];
                    let [a, b, c] = interlace_end(map, &around, &under, e, v1, v2, width, gap);
                    let [d, e2, g] = interlace_end(map, &around, &under, e, v2, v1, width, gap);
                    [a, b, c, d, e2, g]
                })
                .collect();
            for b in &bands {
                f.polygon(b, fill, 1.0);
            }
            for b in &bands {
                f.line(b[2], b[3], 0.0);
                f.line(b[5], b[0], 0.0);
            }
        }
        5 => {
            let mut rand = JavaRandom::new(279_401);
            for &e in &map.eorder {
                let [a, b] = map.edges[e].map(|v| map.pos[v]);
                let (mut p, mut q) = (a, b);
                for _ in 0..8 {
                    let mut jitter = |x: f64| x + (rand.next_f64() * 0.05) - 0.025;
                    p = [jitter(p[0]), jitter(p[1])];
                    q = [jitter(q[0]), jitter(q[1])];
                    let c = rand.next_f64();
                    f.line(p, q, c);
                }
            }
        }
        _ => {
            for &e in &map.eorder {
                let [a, b] = map.edges[e];
                f.line(map.pos[a], map.pos[b], 0.0);
            }
        }
    }
    f.0
}

/// The face on the left of edge `e` walked from vertex `from`: its corners, turning to the
/// next edge clockwise at each vertex; `None` at a dead end.
fn face_from(map: &Map, around: &Around, from: usize, e: usize) -> Option<Vec<usize>> {
    let mut face = Vec::new();
    let (mut cur, mut ecur) = (from, e);
    for _ in 0..=map.edges.len() {
        face.push(cur);
        let n = other(map, ecur, cur);
        if around.0[n].len() < 2 {
            return None;
        }
        ecur = around.before_after(n, ecur).0;
        cur = n;
        if cur == from {
            return Some(face);
        }
    }
    None
}

/// Whether a face runs clockwise (the turn at its rightmost corner).
fn clockwise(map: &Map, face: &[usize]) -> bool {
    let sz = face.len();
    let mut imax = 0;
    for (i, &v) in face.iter().enumerate() {
        if map.pos[v][0] > map.pos[face[imax]][0] {
            imax = i;
        }
    }
    let pmax = map.pos[face[imax]];
    let pnext = map.pos[face[(imax + 1) % sz]];
    let pprev = map.pos[face[(imax + sz - 1) % sz]];
    let (dp, dn) = (sub(pmax, pprev), sub(pnext, pmax));
    dp[0] * dn[1] - dp[1] * dn[0] < 0.0
}

/// The map's bounded faces two-coloured (Taprats' `Faces`): (black, white) corner lists.
/// The colouring spreads from the first face found to the faces across its edges; faces it
/// does not reach are left out.
fn faces(map: &Map) -> (Vec<Vec<P>>, Vec<Vec<P>>) {
    #[derive(Clone, Copy, PartialEq)]
    enum State {
        Undone,
        Processing,
        Black,
        White,
    }
    let around = Around::new(map);
    // The face on each side of each edge: walked from its first or its second vertex.
    let mut side = vec![[None::<usize>; 2]; map.edges.len()];
    let mut all: Vec<(Vec<usize>, State)> = Vec::new();
    let mut listed = Vec::new();
    let link = |from: usize, to: usize| {
        around.0[from]
            .iter()
            .copied()
            .find(|&e| other(map, e, from) == to)
    };
    for &e in &map.eorder {
        for end in 0..2 {
            if side[e][end].is_some() || all.len() > MAX_FIGURES {
                continue;
            }
            let Some(face) = face_from(map, &around, map.edges[e][end], e) else {
                continue;
            };
            let id = all.len();
            if !clockwise(map, &face) {
                listed.push(id);
            }
            for k in 0..face.len() {
                let (from, to) = (face[k], face[(k + 1) % face.len()]);
                if let Some(c) = link(from, to) {
                    side[c][usize::from(map.edges[c][0] != from)] = Some(id);
                }
            }
            all.push((face, State::Undone));
        }
    }
    let Some(&first) = listed.first() else {
        return (Vec::new(), Vec::new());
    };
    let twin = |face: &[usize], k: usize| {
        let (from, to) = (face[k], face[(k + 1) % face.len()]);
        let c = link(from, to)?;
        side[c][usize::from(map.edges[c][0] == from)]
    };
    all[first].1 = State::Processing;
    let mut stack = vec![first];
    while let Some(fi) = stack.pop() {
        let mut col = -1;
        for k in 0..all[fi].0.len() {
            let Some(n) = twin(&all[fi].0, k) else {
                continue;
            };
            match all[n].1 {
                State::Undone => {
                    all[n].1 = State::Processing;
                    stack.push(n);
                }
                State::Processing => {}
                State::Black => col = 1,
                State::White => col = 0,
            }
        }
        all[fi].1 = if col == 1 { State::White } else { State::Black };
    }
    let (mut black, mut white) = (Vec::new(), Vec::new());
    for id in listed {
        let pts = all[id].0.iter().map(|&v| map.pos[v]).collect();
        match all[id].1 {
            State::White => white.push(pts),
            State::Black => black.push(pts),
            _ => {}
        }
    }
    (black, white)
}

/// One half of an embossed band, shaded by how its side a–d faces the light at 45°.
fn emboss_half(f: &mut Figures, [a, b, c, d]: [P; 4], fill: bool) {
    let n = normalize(perp(sub(a, d)));
    let light = std::f64::consts::FRAC_PI_4;
    let shade = 0.5 * (n[0] * light.cos() + n[1] * light.sin() + 1.0);
    f.polygon(&[a, b, c, d], fill, shade);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::variations::jwf_sv_sunvoroni::signed_area;

    /// Ear clipping covers the polygon: the triangles' areas add up to its area, for convex
    /// and non-convex polygons either way round.
    #[test]
    fn triangles_cover_the_polygon() {
        let star: Vec<P> = (0..10)
            .map(|k| {
                let a = std::f64::consts::PI * k as f64 / 5.0;
                let r = if k % 2 == 0 { 1.0 } else { 0.4 };
                [r * a.cos(), r * a.sin()]
            })
            .collect();
        let square = vec![[0.0, 0.0], [0.0, 2.0], [2.0, 2.0], [2.0, 0.0]];
        for poly in [star, square] {
            let tris = triangulate(&poly);
            assert_eq!(tris.len(), poly.len() - 2);
            let sum: f64 = tris.iter().map(|t| signed_area(t).abs()).sum();
            assert!((sum - signed_area(&poly).abs()).abs() < 1e-12, "{sum}");
        }
    }

    /// Two crossing edges interlaced: the crossing is over for one strand and under for the
    /// other, so of the four edge ends there the under ones are cut back by the gap.
    #[test]
    fn crossing_alternates() {
        let mut m = Map::default();
        let c = m.insert_vertex([0.0, 0.0]);
        for p in [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]] {
            let v = m.insert_vertex(p);
            m.insert_edge(c, v);
        }
        let around = Around::new(&m);
        let under = interlacing(&m, &around);
        // At the centre, opposite edges share their state, neighbours differ.
        let at_centre = |e: usize| (m.edges[e][0] == c) == under[e];
        let l = &around.0[c];
        assert_eq!(at_centre(l[0]), at_centre(l[2]));
        assert_eq!(at_centre(l[1]), at_centre(l[3]));
        assert_ne!(at_centre(l[0]), at_centre(l[1]));
    }
}
