//! JWildfire's `dc_triTile` (after eralex61's "FiveFold" Apophysis example of a finite
//! recurrent system): a random point of a random tile of a triangle substitution tiling, the
//! tile found by subdividing a start triangle `itt` times (choosing each child with the odds of
//! its area), then `itt1` or `itt2` times more by the type reached, with extra steps while the
//! type is not `eq` (`on`, `depth`). The colour is a hash of the path of the last stage plus the
//! last child's colour `col1` or `col2`.
//!
//! Tilings (`type`): 1 the Penrose triangles without rotations, 2 trihex, 3 equithirds, 4 the
//! overlapping Robinson triangles, 5 pinwheel, 6 the golden pinwheel, as the Tilings
//! Encyclopedia (tilings.math.uni-bielefeld.de) describes them; `t` (1 or 2) picks the start
//! triangle. The formulas follow JWildfire 9.00 (`DCTriTileFunc`, LGPL-2.1), written anew, with
//! its corner cases kept: a `t` other than 1 or 2 starts from a triangle collapsed to the origin
//! of type 0, which most tilings leave as it is. JWildfire's loops have no bound; here each
//! stage stops after [`MAX_STEPS`] subdivisions (far below the precision of a double).

use super::util::jwf_math as jm;
use super::util::lattice_noise;
use std::f64::consts::{PI, TAU};

use super::*;

/// Most subdivisions of one stage (0.5^200 is far below a double's resolution).
const MAX_STEPS: i64 = 200;

/// Any 32-bit integer.
const I32: (f64, f64) = (-2147483648.0, 2147483647.0);

pub(super) static DEFS: &[VarDef] = &[VarDef::new("dc_triTile", tri_tile)
    .params(&[
        p_int("dc_triTile_type", 1.0, 1.0, 6.0),
        p_int("dc_triTile_t", 2.0, I32.0, I32.1),
        p("dc_triTile_col1", 0.19),
        p("dc_triTile_col2", 0.83),
        p_int("dc_triTile_on", 1.0, 0.0, 1.0),
        p_int("dc_triTile_itt", 1.0, I32.0, I32.1),
        p_int("dc_triTile_eq", 1.0, 0.0, 2.0),
        p_int("dc_triTile_depth", 2.0, I32.0, I32.1),
        p_int("dc_triTile_on1", 1.0, 0.0, 1.0),
        p_int("dc_triTile_itt1", 0.0, I32.0, I32.1),
        p_int("dc_triTile_eq1", 1.0, 0.0, 2.0),
        p_int("dc_triTile_depth1", 1.0, I32.0, I32.1),
        p_int("dc_triTile_on2", 0.0, 0.0, 1.0),
        p_int("dc_triTile_itt2", 1.0, I32.0, I32.1),
        p_int("dc_triTile_eq2", 1.0, 0.0, 2.0),
        p_int("dc_triTile_depth2", 0.0, I32.0, I32.1),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)];

/// A point of the plane.
type P = [f64; 2];

/// A tile: its type (1 or 2; 0 or 3 only from a collapsed start), corners and colour.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Tri {
    kind: i32,
    v: [P; 3],
    col: f64,
}

/// a + f·(b − a).
fn lerp(a: P, b: P, f: f64) -> P {
    [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])]
}

/// (a + b)/2.
fn mid(a: P, b: P) -> P {
    [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]
}

/// The tiling's settings: its number, the two colours and its ratio `alfa`.
struct Tiling {
    kind: i32,
    col: [f64; 2],
    alfa: f64,
}

impl Tiling {
    /// A tile of type `kind` (1 or 2) with that type's colour.
    fn tile(&self, kind: i32, a: P, b: P, c: P) -> Tri {
        let col = if kind == 1 { self.col[0] } else { self.col[1] };
        Tri {
            kind,
            v: [a, b, c],
            col,
        }
    }

    /// A tile of the parent's type `from` (`same`) or the other one, coloured as JWildfire
    /// colours it (by the parent's type being 1 or not).
    fn follow(&self, from: i32, same: bool, a: P, b: P, c: P) -> Tri {
        let first = (from == 1) == same;
        Tri {
            kind: if same { from } else { 3 - from },
            v: [a, b, c],
            col: if first { self.col[0] } else { self.col[1] },
        }
    }

    /// The start triangle for `t`, or `None` (a collapsed one) for other values.
    fn start(&self, t: i64) -> Option<Tri> {
        let o = [0.0, 0.0];
        let k = match t {
            1 => 1,
            2 => 2,
            _ => return None,
        };
        let pair = |a: P, b: P| (self.tile(1, o, a, b), self.tile(2, o, a, b));
        let (one, two) = match self.kind {
            1 => {
                let a1 = [jm::cos(TAU / 5.0), jm::sin(TAU / 5.0)];
                let a2 = [jm::cos(PI / 5.0), jm::sin(PI / 5.0)];
                (
                    self.tile(1, o, a1, [2.0 * a1[0], 0.0]),
                    self.tile(2, o, a2, [2.0 * a2[0], 0.0]),
                )
            }
            2 => pair([jm::cos(PI / 3.0), 0.0], [0.0, jm::sin(PI / 3.0)]),
            3 => {
                let a1 = [jm::cos(PI / 3.0), jm::sin(PI / 3.0)];
                let a2 = [jm::cos(PI / 6.0), jm::sin(PI / 6.0)];
                (
                    self.tile(1, o, a1, [2.0 * a1[0], 0.0]),
                    self.tile(2, o, a2, [2.0 * a2[0], 0.0]),
                )
            }
            4 => {
                let a = [jm::cos(TAU / 5.0), jm::sin(TAU / 5.0)];
                pair(a, [2.0 * a[0], 0.0])
            }
            5 => (
                self.tile(1, o, [0.0, 1.0], [2.0, 0.0]),
                self.tile(2, o, [0.0, 2.0], [1.0, 0.0]),
            ),
            _ => {
                let s = jm::sqrt(M_1_PHI);
                (
                    self.tile(1, o, [M_1_PHI, s], [M_1_PHI, 0.0]),
                    self.tile(2, o, [0.0, s], [1.0, 0.0]),
                )
            }
        };
        Some(if k == 1 { one } else { two })
    }

    /// One child of `t` (drawing one number), or `None` where the tiling has no rule for its
    /// type (the previous child stays).
    fn divide(&self, t: &Tri, rng: &mut FastRng) -> Option<Tri> {
        match self.kind {
            1 => self.five_fold(t, rng),
            2 => Some(self.trihex(t, rng)),
            3 => self.equithirds(t, rng),
            4 => Some(self.robinson(t, rng)),
            5 => self.pinwheel(t, rng),
            _ => self.golden(t, rng),
        }
    }

    /// Penrose triangles without rotations.
    fn five_fold(&self, t: &Tri, rng: &mut FastRng) -> Option<Tri> {
        let [p1, p2, p3] = t.v;
        let a2 = self.alfa * self.alfa;
        match t.kind {
            1 => {
                let p4 = lerp(p2, p3, self.alfa);
                Some(if rng.f01() < a2 {
                    self.tile(1, p3, p1, p4)
                } else {
                    self.tile(2, p2, p4, p1)
                })
            }
            2 => {
                let p4 = lerp(p3, p1, self.alfa);
                let p5 = lerp(p3, p2, self.alfa);
                let w = rng.f01();
                Some(if w < a2 {
                    self.tile(2, p2, p4, p1)
                } else if w < 2.0 * a2 {
                    self.tile(2, p3, p5, p4)
                } else {
                    self.tile(1, p2, p4, p5)
                })
            }
            _ => None,
        }
    }

    /// Trihex: four children, any parent type.
    fn trihex(&self, t: &Tri, rng: &mut FastRng) -> Tri {
        let [p1, p2, p3] = t.v;
        let p4 = mid(p1, p3);
        let p5 = mid(p2, p3);
        let p6 = mid(p1, p5);
        let w = rng.f01();
        let k = t.kind;
        if w < 0.25 {
            self.follow(k, true, p4, p5, p3)
        } else if w < 0.5 {
            self.follow(k, false, p4, p5, p1)
        } else if w < 0.75 {
            self.follow(k, false, p6, p5, p2)
        } else {
            self.follow(k, true, p6, p1, p2)
        }
    }

    /// Equithirds.
    fn equithirds(&self, t: &Tri, rng: &mut FastRng) -> Option<Tri> {
        let [p1, p2, p3] = t.v;
        let a = self.alfa;
        match t.kind {
            1 => {
                let p4 = lerp(p1, p3, 0.5);
                let p5 = lerp(p4, p2, a);
                let w = rng.f01();
                Some(if w < a {
                    self.tile(2, p2, p5, p1)
                } else if w < 2.0 * a {
                    self.tile(2, p3, p5, p2)
                } else {
                    self.tile(2, p1, p5, p3)
                })
            }
            2 => {
                let p4 = lerp(p1, p3, a);
                let p5 = lerp(p3, p1, a);
                let w = rng.f01();
                Some(if w < a {
                    self.tile(2, p2, p4, p1)
                } else if w < 2.0 * a {
                    self.tile(2, p3, p5, p2)
                } else {
                    self.tile(1, p4, p2, p5)
                })
            }
            _ => None,
        }
    }

    /// Overlapping Robinson triangles: any parent type.
    fn robinson(&self, t: &Tri, rng: &mut FastRng) -> Tri {
        let [p1, p2, p3] = t.v;
        let a = self.alfa;
        let p4 = lerp(p2, p1, a);
        let p5 = lerp(p1, p2, a);
        let p6 = lerp(p2, p3, a);
        let w = rng.f01();
        if w < 0.3 {
            self.tile(2, p4, p2, p6)
        } else if w < 0.63 {
            self.follow(t.kind, false, p6, p1, p5)
        } else {
            self.tile(1, p3, p1, p6)
        }
    }

    /// Pinwheel: five children of equal area.
    fn pinwheel(&self, t: &Tri, rng: &mut FastRng) -> Option<Tri> {
        let [p1, p2, p3] = t.v;
        // The long leg's points at 1/5 and 3/5, the hypotenuse's midpoint, and the midpoint
        // between the right angle and the first.
        let (leg0, leg1, hyp) = match t.kind {
            1 => (p2, p3, p3),
            2 => (p3, p2, p2),
            _ => return None,
        };
        let p4 = lerp(leg0, leg1, 0.2);
        let p5 = lerp(leg0, leg1, 0.6);
        let p6 = lerp(p1, hyp, 0.5);
        let p7 = lerp(p1, p4, 0.5);
        let w = (rng.f01() * 5.0) as i32;
        Some(match (t.kind, w) {
            (1, 0) => self.tile(2, p4, p1, p2),
            (1, 1) => self.tile(2, p7, p6, p1),
            (1, 2) => self.tile(1, p7, p4, p6),
            (1, 3) => self.tile(1, p5, p6, p4),
            (1, _) => self.tile(2, p5, p3, p6),
            (_, 0) => self.tile(1, p4, p3, p1),
            (_, 1) => self.tile(1, p7, p1, p6),
            (_, 2) => self.tile(2, p7, p6, p4),
            (_, 3) => self.tile(2, p5, p4, p6),
            (_, _) => self.tile(1, p5, p6, p2),
        })
    }

    /// Golden pinwheel.
    fn golden(&self, t: &Tri, rng: &mut FastRng) -> Option<Tri> {
        let [p1, p2, p3] = t.v;
        let a = self.alfa;
        match t.kind {
            1 => {
                let p4 = lerp(p1, p2, a);
                let p5 = lerp(p2, p1, a);
                let p6 = lerp(p3, p2, a);
                let p7 = lerp(p1, p3, a);
                let w = rng.f01();
                Some(if w < 0.146 {
                    self.tile(1, p1, p4, p7)
                } else if w < 0.382 {
                    self.tile(2, p4, p7, p6)
                } else if w < 0.618 {
                    self.tile(2, p3, p6, p7)
                } else if w < 0.764 {
                    self.tile(1, p4, p6, p5)
                } else {
                    self.tile(2, p5, p6, p2)
                })
            }
            2 => {
                let p4 = lerp(p2, p1, a);
                let p5 = lerp(p2, p3, a);
                let p6 = lerp(p3, p2, a);
                let p7 = lerp(p1, p3, a);
                let p8 = lerp(p3, p1, a);
                let p9 = lerp(p4, p7, a);
                let p10 = lerp(p7, p4, a);
                let w = rng.f01();
                Some(if w < 0.146 {
                    self.tile(2, p4, p2, p5)
                } else if w < 0.236 {
                    self.tile(1, p4, p5, p9)
                } else if w < 0.382 {
                    self.tile(2, p10, p1, p4)
                } else if w < 0.472 {
                    self.tile(1, p7, p1, p10)
                } else if w < 0.618 {
                    self.tile(2, p9, p5, p7)
                } else if w < 0.764 {
                    self.tile(2, p6, p5, p7)
                } else if w < 0.854 {
                    self.tile(1, p7, p6, p8)
                } else {
                    self.tile(2, p8, p6, p3)
                })
            }
            _ => None,
        }
    }
}

/// 1/φ, φ the golden ratio.
const M_1_PHI: f64 = 1.0 / 1.618_033_988_749_895;

/// One stage's settings: subdivisions `itt`, extra ones while the type is not `eq` (`on` 0:
/// `depth` more once, at step `itt`; `on` 1: one more at each of the steps itt .. itt+depth−1).
struct Stage {
    itt: i64,
    on: bool,
    eq: i32,
    depth: i64,
}

/// Runs a stage from `t1` (the last child kept in `t2`); returns the path's bits (each child's
/// type − 1, in wrapping 32-bit arithmetic, as JWildfire's `int` computes them).
fn run(tl: &Tiling, s: &Stage, t1: &mut Tri, t2: &mut Tri, rng: &mut FastRng) -> i32 {
    let (mut n, mut k, mut m) = (s.itt, 1i64, 0i32);
    let mut steps = 0;
    while n > 0 && steps < MAX_STEPS {
        if let Some(c) = tl.divide(t1, rng) {
            *t2 = c;
        }
        *t1 = *t2;
        m = m.wrapping_mul(2).wrapping_add(t2.kind - 1);
        let off = t1.kind != s.eq;
        if !s.on {
            if k == s.itt && off {
                n += s.depth;
            }
        } else if k >= s.itt && k < s.itt + s.depth && off {
            n += 1;
        }
        n -= 1;
        k += 1;
        steps += 1;
    }
    m
}

/// A uniform point of the triangle, as JWildfire's `DCTriTileFunc` samples it: the corners
/// sorted by x, the triangle split by its middle corner's vertical into two parts each sampled
/// as a sheared parallelogram half (two draws); degenerate triangles give a point of a side.
fn sample(t: &Tri, rng: &mut FastRng) -> P {
    let [a, b, c] = t.v;
    let [p1, p2, p3] = if a[0] <= b[0] && a[0] <= c[0] {
        if b[0] <= c[0] { [a, b, c] } else { [a, c, b] }
    } else if b[0] <= a[0] && b[0] <= c[0] {
        if a[0] <= c[0] { [b, a, c] } else { [b, c, a] }
    } else if a[0] <= b[0] {
        [c, a, b]
    } else {
        [c, b, a]
    };
    let (r1, r2) = (rng.f01(), rng.f01());
    let mut uv = if p1[0] == p2[0] && p2[0] == p3[0] {
        let (y1, y2, y3) = (p1[1], p2[1], p3[1]);
        let (v1, v2) = if y1 <= y2 && y1 <= y3 {
            (y1, if y3 > y2 { y2 } else { y3 })
        } else if y2 <= y1 && y2 <= y3 {
            (y2, if y3 > y1 { y1 } else { y3 })
        } else {
            (y3, if y2 > y1 { y1 } else { y2 })
        };
        [p1[0], v1 + r1 * (v2 - v1)]
    } else if p1[0] == p2[0] {
        halves(p3, p2, p1, r1, r2)
    } else {
        halves(p1, p2, p3, r1, r2)
    };
    if p1 == p2 {
        uv = lerp(p1, p3, r1);
    }
    if p1 == p3 || p2 == p3 {
        uv = lerp(p1, p2, r1);
    }
    uv
}

/// The two-part sample of [`sample`]: from the end corner `s` (least or greatest x) towards the
/// middle corner `m`; `o` is the other end corner.
fn halves(s: P, m: P, o: P, r1: f64, r2: f64) -> P {
    let h = mid(s, o);
    let d5 = [s[0] + m[0] - h[0], s[1] + m[1] - h[1]];
    let d6 = [o[0] + m[0] - h[0], o[1] + m[1] - h[1]];
    let e = lerp(s, h, r1);
    let e0 = lerp(d5, m, r1);
    let uv = lerp(e, e0, r2);
    let w = s[1] + (m[1] - s[1]) / (m[0] - s[0]) * (uv[0] - s[0]);
    let above = m[1] > s[1] + (o[1] - s[1]) / (o[0] - s[0]) * (m[0] - s[0]);
    if (above && uv[1] > w) || (!above && uv[1] < w) {
        let f = lerp(h, o, r1);
        let f0 = lerp(m, d6, r1);
        lerp(f0, f, r2)
    } else {
        uv
    }
}

/// dc_triTile: see the module documentation.
fn tri_tile(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 16] = v.params();
    let kind = q[0] as i32;
    let alfa = match kind {
        1 | 4 => 2.0 * jm::cos(TAU / 5.0),
        3 => 1.0 / 3.0,
        6 => M_1_PHI * M_1_PHI,
        _ => 0.0,
    };
    let tl = Tiling {
        kind,
        col: [q[2], q[3]],
        alfa,
    };
    let stage = |i: usize| Stage {
        on: q[i] != 0.0,
        itt: q[i + 1] as i64,
        eq: q[i + 2] as i32,
        depth: q[i + 3] as i64,
    };
    let orig = tl.start(q[1] as i64).unwrap_or_default();
    let mut t1 = Tri { col: 0.25, ..orig };
    let mut t2 = Tri { col: 0.0, ..orig };
    run(&tl, &stage(4), &mut t1, &mut t2, rng);
    // The second stage by the type reached, its path hashed (salted by the type) for colour.
    let second = match t1.kind {
        1 => Some((stage(8), 43)),
        2 => Some((stage(12), 31)),
        _ => None,
    };
    if let Some((st, salt)) = second {
        let m = run(&tl, &st, &mut t1, &mut t2, rng);
        t1.col = lattice_noise(m.wrapping_add(salt));
    }
    let [x, y] = sample(&t2, rng);
    acc.color = (t1.col + t2.col) % 1.0;
    [v.w * x, v.w * y, 0.0]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Twice the signed area of a triangle.
    fn area2(t: &Tri) -> f64 {
        let [a, b, c] = t.v;
        (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
    }

    /// Is `p` inside `t` (with a little slack)?
    fn inside(t: &Tri, p: P) -> bool {
        let [a, b, c] = t.v;
        let s = |u: P, w: P| (w[0] - u[0]) * (p[1] - u[1]) - (p[0] - u[0]) * (w[1] - u[1]);
        let (d1, d2, d3) = (s(a, b), s(b, c), s(c, a));
        let eps = 1e-12;
        (d1 >= -eps && d2 >= -eps && d3 >= -eps) || (d1 <= eps && d2 <= eps && d3 <= eps)
    }

    #[test]
    fn children_cover_the_parent_area() {
        // Every tiling's children, over many draws, have areas summing (by their odds) to the
        // parent's: check that each child lies inside its parent and is smaller.
        let mut rng = FastRng::new(7);
        for kind in 1..=6 {
            let tl = Tiling {
                kind,
                col: [0.2, 0.8],
                alfa: match kind {
                    1 | 4 => 2.0 * jm::cos(TAU / 5.0),
                    3 => 1.0 / 3.0,
                    6 => M_1_PHI * M_1_PHI,
                    _ => 0.0,
                },
            };
            for t in 1..=2 {
                let start = tl.start(t).expect("t 1 and 2 have start triangles");
                for _ in 0..200 {
                    let c = tl
                        .divide(&start, &mut rng)
                        .expect("types 1 and 2 have rules");
                    assert!(area2(&c).abs() < area2(&start).abs(), "tiling {kind}");
                    for p in c.v {
                        assert!(inside(&start, p), "tiling {kind} t {t}: {p:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn samples_lie_in_the_triangle() {
        let mut rng = FastRng::new(3);
        let t = Tri {
            kind: 1,
            v: [[0.0, 0.0], [0.3, 0.9], [1.0, 0.1]],
            col: 0.0,
        };
        let t2 = Tri {
            v: [[0.0, 0.0], [0.0, 1.0], [2.0, 0.0]],
            ..t
        };
        for tri in [t, t2] {
            for _ in 0..1000 {
                let p = sample(&tri, &mut rng);
                assert!(inside(&tri, p), "{p:?}");
            }
        }
    }

    /// Means and standard deviations of x, y and the colour over 200 000 calls of JWildfire
    /// 9.00's `DCTriTileFunc` (run outside the project) for each tiling and start triangle,
    /// with col1 0.2, col2 0.7, on 1, itt 3, eq 1, depth 2, on1 0, itt1 2, eq1 2, depth1 1,
    /// on2 1, itt2 2, eq2 1, depth2 1.
    #[rustfmt::skip]
    const STATS: &[(i32, i32, [f64; 3], [f64; 3])] = &[
        (1, 1, [0.3086725215897584, 0.3176622773149059, 0.5113217438235934], [0.1261134494853762, 0.22444111417623575, 0.2734887512173016]),
        (1, 2, [0.8076126970687314, 0.19663758001069442, 0.5107832923207903], [0.3300871222260972, 0.13895523077010968, 0.27328504526371167]),
        (2, 1, [0.16690432113916082, 0.28819137250479726, 0.5785031493855406], [0.11773221898856129, 0.20451800178215404, 0.29266551902331533]),
        (2, 2, [0.16685512664433375, 0.2885351178790662, 0.5799067819206122], [0.1178063811940045, 0.2040447993158371, 0.29244831377896646]),
        (3, 1, [0.49903251515080627, 0.2875838823573505, 0.38057714368327694], [0.204090822406588, 0.2041307348135739, 0.21296795629479817]),
        (3, 2, [0.8636712215181589, 0.16676510731175354, 0.3801185264557077], [0.3534525434964057, 0.11791911824684946, 0.20908708218424601]),
        (4, 1, [0.30669260521918484, 0.31648208989735366, 0.5604966650804314], [0.11598264352971047, 0.20929715820617772, 0.28870665661261025]),
        (4, 2, [0.30715678415015724, 0.3164777325987581, 0.5601315527293734], [0.11607168091848429, 0.209258004248653, 0.2885904768322655]),
        (5, 1, [0.6677310663349507, 0.33170623200879495, 0.5704364493298871], [0.471455102909919, 0.2348833719651049, 0.2861932741135078]),
        (5, 2, [0.33242907485081064, 0.6680187913315558, 0.5693367020637241], [0.23535779873319215, 0.47134665386501917, 0.2862690216345086]),
        (6, 1, [0.4118262401971706, 0.262443471579375, 0.4973611881245105], [0.1454983690763172, 0.1851783819246713, 0.2688445093723873]),
        (6, 2, [0.33430793292167177, 0.2623695330757997, 0.49785753971978836], [0.2359233064878433, 0.18536741805159024, 0.26972687267231527]),
    ];

    #[test]
    fn every_tiling_matches_jwildfire_statistics() {
        let names = [
            "type", "t", "col1", "col2", "on", "itt", "eq", "depth", "on1", "itt1", "eq1",
            "depth1", "on2", "itt2", "eq2", "depth2",
        ];
        let n = 100_000;
        let mut rng = FastRng::new(5);
        for &(kind, t, mean, std) in STATS {
            let vals = [
                f64::from(kind),
                f64::from(t),
                0.2,
                0.7,
                1.0,
                3.0,
                1.0,
                2.0,
                0.0,
                2.0,
                2.0,
                1.0,
                1.0,
                2.0,
                1.0,
                1.0,
            ];
            let full: Vec<String> = names.iter().map(|p| format!("dc_triTile_{p}")).collect();
            let params: Vec<(&str, f64)> = full.iter().map(String::as_str).zip(vals).collect();
            let v = super::super::jwf_testing::make("dc_triTile", &params, 1.0);
            let (mut s, mut ss) = ([0.0; 3], [0.0; 3]);
            for _ in 0..n {
                let o = super::super::jwf_testing::run(&v, &[[0.1, 0.2, 0.0]], 0.5, &mut rng)[0];
                for (k, c) in [o[0], o[1], o[3]].into_iter().enumerate() {
                    s[k] += c;
                    ss[k] += c * c;
                }
            }
            for k in 0..3 {
                let m = s[k] / f64::from(n);
                let sd = (ss[k] / f64::from(n) - m * m).max(0.0).sqrt();
                let se = (std[k] * std[k] / 200_000.0 + sd * sd / f64::from(n)).sqrt();
                assert!(
                    (m - mean[k]).abs() < 6.0 * se,
                    "tiling {kind} t {t} comp {k}: mean {m} want {}",
                    mean[k]
                );
                assert!(
                    (sd - std[k]).abs() < 0.03 * std[k],
                    "tiling {kind} t {t} comp {k}: std {sd} want {}",
                    std[k]
                );
            }
        }
    }
}
