//! Taprats' inference of a figure for a tile that has none (Craig S. Kaplan, "Computer
//! Generated Islamic Star Patterns", Bridges 2000, §4; as JWildfire 9.00 ships it in
//! `csk.taprats.app.Infer` for its `taprats` variation, GPL-3.0): the neighbouring tiles'
//! figures touch the tile's edges at contacts; each contact's line is continued into the tile
//! and paired greedily with the contact whose line it meets best (collinear first, then met
//! inside at equal distances, then inside at unequal ones, then outside, nearer first); the
//! lines run to their meeting points, and contacts left over are joined pairwise by a bent
//! line. Written anew from the algorithm, keeping the order of the floating operations.

use super::jwf_tp_map::{
    Map, P, TOL, Tiling, Tr, add, apply, compose, dist, dist_to_segment, invert, normalize, scale,
    sub, translate, true_intersection,
};

/// A tile of the 3 × 3 translational units around the origin: its shape (index into the
/// tiling's features), placement and edge midpoints.
struct Placed {
    feature: usize,
    t: Tr,
    mids: Vec<P>,
}

/// A point where a neighbour's figure meets the tile's boundary, coming from `other`.
struct Contact {
    position: P,
    other: P,
    end: P,
    isect: Option<P>,
    partner: Option<usize>,
    master: bool,
    taken: bool,
}

/// The kinds of pairing, best first.
const INSIDE_EVEN: u8 = 0;
const INSIDE_COLINEAR: u8 = 1;
const INSIDE_UNEVEN: u8 = 2;
const OUTSIDE_EVEN: u8 = 3;
const OUTSIDE_UNEVEN: u8 = 4;
const NONE: u8 = 5;

fn loose_eq(a: f64, b: f64) -> bool {
    (a - b).abs() < TOL
}

fn loose_eq_p(a: P, b: P) -> bool {
    let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
    dx * dx + dy * dy < 1e-10
}

/// Whether a lies on the line p–q (within the tolerance, unnormalised).
fn colinear(p: P, q: P, a: P) -> bool {
    loose_eq((q[0] - p[0]) * (a[1] - p[1]), (q[1] - p[1]) * (a[0] - p[0]))
}

/// Whether `p` is inside the polygon (crossings of a ray to the north, Taprats' rule).
fn point_in_poly(pts: &[P], p: P) -> bool {
    let [x, y] = p;
    let mut inside = false;
    let mut a = pts[0];
    for idx in 0..pts.len() {
        let b = pts[(idx + 1) % pts.len()];
        let (lo, hi) = if a[0] < b[0] { (a, b) } else { (b, a) };
        if lo[0] <= x && x < hi[0] && (x - lo[0]) * (hi[1] - lo[1]) > (y - lo[1]) * (hi[0] - lo[0])
        {
            inside = !inside;
        }
        a = b;
    }
    inside
}

fn better(kind: u8, d: f64, best_kind: u8, best_d: f64) -> bool {
    kind < best_kind || (kind == best_kind && !loose_eq(d, best_d) && d < best_d)
}

/// The map `m` moved by `t`, with its vertices' edges in counter-clockwise order starting at
/// each vertex's first edge in `m`'s edge order (as Taprats' copies keep them).
fn moved_with_edges(m: &Map, t: &Tr) -> (Map, Vec<Vec<usize>>) {
    let mut around: Vec<Vec<(f64, usize)>> = vec![Vec::new(); m.pos.len()];
    for &e in &m.eorder {
        let [a, b] = m.edges[e];
        for (v, w) in [(a, b), (b, a)] {
            around[v].push((
                super::jwf_tp_render::pseudo_angle(sub(m.pos[w], m.pos[v])),
                e,
            ));
        }
    }
    let lists = around
        .into_iter()
        .map(|l| {
            let Some(&(_, head)) = l.first() else {
                return Vec::new();
            };
            let mut l = l;
            l.sort_by(|x, y| x.0.total_cmp(&y.0));
            let k = l.iter().position(|x| x.1 == head).unwrap_or(0);
            l.rotate_left(k);
            l.into_iter().map(|(_, e)| e).collect()
        })
        .collect();
    let mut moved = m.clone();
    moved.transform(t);
    (moved, lists)
}

/// The figure inferred for tile shape `feature` of `tiling`, given the current figures of
/// all shapes (in the shape's own frame); empty when a neighbour cannot be found.
pub(super) fn infer(tiling: &Tiling, figures: &[Map], feature: usize) -> Map {
    // Every placed tile of the 3 × 3 units, unit by unit (rows of t2, then t1).
    let mut placed = Vec::new();
    for y in -1..=1 {
        for x in -1..=1 {
            let shift = translate(add(
                scale(tiling.t1, f64::from(x)),
                scale(tiling.t2, f64::from(y)),
            ));
            for (f, feat) in tiling.features.iter().enumerate() {
                let poly = feat.polygon();
                for pl in feat.placements {
                    let t = compose(&shift, pl);
                    let pts: Vec<P> = poly.iter().map(|&p| apply(&t, p)).collect();
                    let n = pts.len();
                    let mids = (0..n)
                        .map(|i| super::jwf_tp_map::convex_sum(pts[i], pts[(i + 1) % n], 0.5))
                        .collect();
                    placed.push(Placed {
                        feature: f,
                        t,
                        mids,
                    });
                }
            }
        }
    }
    let per_unit = placed.len() / 9;
    let Some(cur) = (4 * per_unit..5 * per_unit).find(|&i| placed[i].feature == feature) else {
        return Map::default();
    };
    let main = &placed[cur];
    let fpts: Vec<P> = tiling.features[feature]
        .polygon()
        .iter()
        .map(|&p| apply(&main.t, p))
        .collect();
    // The neighbour across each edge.
    let mut adjacent = Vec::with_capacity(main.mids.len());
    for &pv in &main.mids {
        let found = placed.iter().enumerate().find_map(|(i, pc)| {
            (i != cur && pc.mids.iter().any(|&m| loose_eq_p(m, pv))).then_some((pc.feature, pc.t))
        });
        match found {
            Some(a) => adjacent.push(a),
            None => return Map::default(),
        }
    }
    // The contacts: vertices of the neighbours' figures on the shared edges (not at the
    // edge's first corner), once for each of their edges.
    let mut cons: Vec<Contact> = Vec::new();
    for (idx, &(f, t)) in adjacent.iter().enumerate() {
        let (a, b) = (fpts[idx], fpts[(idx + 1) % fpts.len()]);
        let (m, around) = moved_with_edges(&figures[f], &t);
        for &v in &m.vorder {
            let pos = m.pos[v];
            let (dx, dy) = (pos[0] - a[0], pos[1] - a[1]);
            if dist_to_segment(pos, a, b).abs() < TOL && dx * dx + dy * dy > 1e-10 {
                for &e in &around[v] {
                    let [e1, e2] = m.edges[e];
                    let other = m.pos[if e1 == v { e2 } else { e1 }];
                    cons.push(Contact {
                        position: pos,
                        other,
                        end: add(pos, scale(normalize(sub(pos, other)), 100.0)),
                        isect: None,
                        partner: None,
                        master: false,
                        taken: false,
                    });
                }
            }
        }
        if cons.len() > 4096 {
            return Map::default();
        }
    }
    pair_contacts(&mut cons, &fpts);
    let mut ret = Map::default();
    for con in &cons {
        let to = match (con.isect, con.partner) {
            (Some(p), _) => p,
            (None, Some(j)) if con.master => cons[j].position,
            _ => continue,
        };
        let mut t = Map::default();
        let v1 = t.insert_vertex(con.position);
        let v2 = t.insert_vertex(to);
        t.insert_edge(v1, v2);
        ret.merge(t);
    }
    let n = fpts.len();
    let minlen = (1..n).fold(dist(fpts[0], fpts[n - 1]), |m, i| {
        m.min(dist(fpts[i - 1], fpts[i]))
    });
    for idx in 0..cons.len() {
        if cons[idx].partner.is_some() {
            continue;
        }
        for jdx in 0..cons.len() {
            if jdx == idx || cons[jdx].partner.is_some() {
                continue;
            }
            let reach = |c: &Contact| {
                add(
                    c.position,
                    scale(normalize(sub(c.position, c.other)), minlen * 0.5),
                )
            };
            let (ex1, ex2) = (reach(&cons[idx]), reach(&cons[jdx]));
            let mut t = Map::default();
            let vx1 = t.insert_vertex(ex1);
            let vx2 = t.insert_vertex(ex2);
            let c = t.insert_vertex(cons[idx].position);
            let oc = t.insert_vertex(cons[jdx].position);
            t.insert_edge(c, vx1);
            t.insert_edge(vx1, vx2);
            t.insert_edge(vx2, oc);
            ret.merge(t);
            cons[idx].partner = Some(jdx);
            cons[jdx].partner = Some(idx);
        }
    }
    if let Some(back) = invert(&main.t) {
        ret.transform(&back);
    }
    ret
}

/// Pairs the contacts greedily, in order, each with its best free partner.
fn pair_contacts(cons: &mut [Contact], fpts: &[P]) {
    for idx in 0..cons.len() {
        if cons[idx].taken {
            continue;
        }
        let mut best: Option<(usize, Option<P>)> = None;
        let (mut best_kind, mut best_d) = (NONE, 0.0);
        let con = &cons[idx];
        for (jdx, ocon) in cons.iter().enumerate() {
            if jdx == idx || ocon.taken || loose_eq_p(con.position, ocon.position) {
                continue;
            }
            let (kind, d, isect);
            if colinear(con.other, con.position, ocon.position)
                && colinear(con.position, ocon.position, ocon.other)
            {
                let d1 = sub(con.position, con.other);
                let d2 = sub(ocon.position, ocon.other);
                let dc = sub(con.position, ocon.position);
                let dot = |a: P, b: P| a[0] * b[0] + a[1] * b[1];
                if dot(d1, d2) > 0.0 || dot(d1, dc) > 0.0 || dot(d2, dc) < 0.0 {
                    continue;
                }
                kind = INSIDE_COLINEAR;
                d = dist(con.position, ocon.position);
                isect = None;
            } else {
                let Some(p) = true_intersection(con.position, con.end, ocon.position, ocon.end)
                else {
                    continue;
                };
                if loose_eq_p(p, con.position) || loose_eq_p(p, ocon.position) {
                    continue;
                }
                let (d_me, d_other) = (dist(con.position, p), dist(ocon.position, p));
                let inside = point_in_poly(fpts, p);
                if !loose_eq(d_me, d_other) {
                    kind = if inside {
                        INSIDE_UNEVEN
                    } else {
                        OUTSIDE_UNEVEN
                    };
                    d = (d_me - d_other).abs();
                } else {
                    kind = if inside { INSIDE_EVEN } else { OUTSIDE_EVEN };
                    d = d_me;
                }
                isect = Some(p);
            }
            if better(kind, d, best_kind, best_d) {
                best = Some((jdx, isect));
                best_kind = kind;
                best_d = d;
            }
        }
        let Some((j, isect)) = best else {
            continue;
        };
        cons[idx].taken = true;
        cons[j].taken = true;
        if best_kind == INSIDE_COLINEAR {
            cons[idx].master = true;
        } else {
            cons[idx].isect = isect;
            cons[j].isect = isect;
        }
        cons[idx].partner = Some(j);
        cons[j].partner = Some(idx);
    }
}

#[cfg(test)]
mod tests {
    use super::super::jwf_tp_figures::Figure;
    use super::super::jwf_tp_tiling::TILINGS;
    use super::*;

    /// The square of the 4.8² tiling between four octagons' rosettes: its inferred figure
    /// has the square's 4-fold symmetry (turning it a quarter maps its vertices onto
    /// themselves) and lies within the square.
    #[test]
    fn square_between_rosettes() {
        let t = &TILINGS[1];
        assert_eq!(t.name, "4.8^2");
        let figures = [Map::default(), Figure::Rosette { n: 8, q: 0.3, s: 2 }.map()];
        let m = infer(t, &figures, 0);
        assert!(!m.edges.is_empty());
        let quarter = super::super::jwf_tp_map::rotate(std::f64::consts::FRAC_PI_2);
        let r = 1.0 / (std::f64::consts::PI / 4.0).cos();
        for &p in &m.pos {
            let q = apply(&quarter, p);
            assert!(m.pos.iter().any(|&o| dist(o, q) < 1e-6), "{p:?}");
            assert!(p[0].abs() <= r + 1e-9 && p[1].abs() <= r + 1e-9, "{p:?}");
        }
    }
}
