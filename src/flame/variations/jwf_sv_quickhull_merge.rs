//! QuickHull3D's merging of faces (John E. Lloyd, BSD licence, see the parent module): two
//! neighbouring faces whose common edge is not clearly convex become one face, dropping the
//! edges they share and any face left with a redundant edge.

use super::{DELETED, Hull, Merge, NIL, NON_CONVEX, tick};

impl Hull {
    /// The distance of the centroid of the face across `e` above the plane of `e`'s face.
    fn opp_face_distance(&self, e: usize) -> f64 {
        let opp = self.he[self.he[e].opposite].face;
        self.distance_to_plane(self.he[e].face, self.f[opp].centroid)
    }

    /// Merges `face` with the first neighbour the rule says to (then true); otherwise marks
    /// it non-convex where the first pass found a doubtful edge.
    pub(super) fn adjacent_merge(&mut self, face: usize, rule: Merge) -> Option<bool> {
        let he0 = self.f[face].he0;
        let mut e = he0;
        let mut convex = true;
        loop {
            tick(&mut self.budget)?;
            let opp_e = self.he[e].opposite;
            if opp_e == NIL {
                return None;
            }
            let opp_face = self.he[opp_e].face;
            let tol = -self.tolerance;
            let merge = match rule {
                Merge::NonConvex => {
                    self.opp_face_distance(e) > tol || self.opp_face_distance(opp_e) > tol
                }
                Merge::WrtLargerFace => {
                    let (first, second) = if self.f[face].area > self.f[opp_face].area {
                        (e, opp_e)
                    } else {
                        (opp_e, e)
                    };
                    if self.opp_face_distance(first) > tol {
                        true
                    } else {
                        if self.opp_face_distance(second) > tol {
                            convex = false;
                        }
                        false
                    }
                }
            };
            if merge {
                let mut discarded = [NIL; 3];
                let count = self.merge_adjacent_face(face, e, &mut discarded)?;
                for &d in &discarded[..count] {
                    self.delete_face_points(d, face)?;
                }
                return Some(true);
            }
            e = self.he[e].next;
            if e == he0 {
                break;
            }
        }
        if !convex {
            self.f[face].mark = NON_CONVEX;
        }
        Some(false)
    }

    /// Absorbs the face across `adj` into `face` (with the run of edges they share), and a
    /// face left with a redundant edge; returns how many faces were discarded.
    fn merge_adjacent_face(
        &mut self,
        face: usize,
        adj: usize,
        discarded: &mut [usize; 3],
    ) -> Option<usize> {
        let opp_face = self.opposite_face(adj);
        let mut count = 0;
        discarded[count] = opp_face;
        count += 1;
        self.f[opp_face].mark = DELETED;
        let opp = self.he[adj].opposite;
        let mut adj_prev = self.he[adj].prev;
        let mut adj_next = self.he[adj].next;
        let mut opp_prev = self.he[opp].prev;
        let mut opp_next = self.he[opp].next;
        while self.opposite_face(adj_prev) == opp_face {
            tick(&mut self.budget)?;
            adj_prev = self.he[adj_prev].prev;
            opp_next = self.he[opp_next].next;
        }
        while self.opposite_face(adj_next) == opp_face {
            tick(&mut self.budget)?;
            opp_prev = self.he[opp_prev].prev;
            adj_next = self.he[adj_next].next;
        }
        let stop = self.he[opp_prev].next;
        let mut e = opp_next;
        while e != stop {
            tick(&mut self.budget)?;
            self.he[e].face = face;
            e = self.he[e].next;
        }
        if adj == self.f[face].he0 {
            self.f[face].he0 = adj_next;
        }
        if let Some(d) = self.connect_half_edges(face, opp_prev, adj_next)? {
            discarded[count] = d;
            count += 1;
        }
        if let Some(d) = self.connect_half_edges(face, adj_prev, opp_next)? {
            discarded[count] = d;
            count += 1;
        }
        self.normal_and_centroid(face)?;
        Some(count)
    }

    /// Joins `prev` to `e` in `face`'s ring; where both border the same other face, the
    /// redundant edge is removed (and that face, if a triangle, discarded and returned).
    fn connect_half_edges(&mut self, face: usize, prev: usize, e: usize) -> Option<Option<usize>> {
        if self.opposite_face(prev) != self.opposite_face(e) {
            self.he[prev].next = e;
            self.he[e].prev = prev;
            return Some(None);
        }
        let opp_face = self.opposite_face(e);
        if opp_face == NIL {
            return None;
        }
        let mut discarded = None;
        if prev == self.f[face].he0 {
            self.f[face].he0 = e;
        }
        let e_opp = self.he[e].opposite;
        let opp_edge = if self.f[opp_face].num_verts == 3 {
            let o = self.he[self.he[e_opp].prev].opposite;
            self.f[opp_face].mark = DELETED;
            discarded = Some(opp_face);
            o
        } else {
            let o = self.he[e_opp].next;
            if self.f[opp_face].he0 == self.he[o].prev {
                self.f[opp_face].he0 = o;
            }
            let pp = self.he[self.he[o].prev].prev;
            self.he[o].prev = pp;
            self.he[pp].next = o;
            o
        };
        if opp_edge == NIL {
            return None;
        }
        let pp = self.he[prev].prev;
        self.he[e].prev = pp;
        self.he[pp].next = e;
        self.he[e].opposite = opp_edge;
        self.he[opp_edge].opposite = e;
        self.normal_and_centroid(opp_face)?;
        Some(discarded)
    }
}
