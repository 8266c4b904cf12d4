//! Classic constructions step by step — the Cantor set, the Koch curve and snowflake, the
//! Sierpinski triangle and carpet — with the numbers of every step (pieces, their size, total
//! length, area) and the limit's dimension; and the Cantor dust map.

use super::{ExploreError, P2};

/// Largest step whose numbers are reported (8⁴⁰ still fits the piece count).
pub const MAX_STATS_STEP: u32 = 40;

/// A classic construction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Construction {
    /// The middle-thirds Cantor set.
    Cantor,
    /// The Koch curve on a unit segment.
    KochCurve,
    /// Three Koch curves on the sides of an equilateral triangle.
    KochSnowflake,
    /// The Sierpinski triangle (gasket).
    SierpinskiTriangle,
    /// The Sierpinski carpet.
    SierpinskiCarpet,
}

/// The numbers of one step of a construction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stats {
    /// The step these numbers are for (0: the starting figure).
    pub step: u32,
    /// Segments, triangles or squares.
    pub pieces: u128,
    /// Length (or side) of one piece.
    pub piece_size: f64,
    /// Total length (Cantor set, Koch curves: the perimeter of the snowflake).
    pub length: Option<f64>,
    /// Area (snowflake: the enclosed area; triangle and carpet: the area kept), for a starting
    /// figure of side 1.
    pub area: Option<f64>,
    /// Area of the starting figure (side 1).
    pub initial_area: Option<f64>,
    /// The limit's similarity dimension.
    pub dimension: f64,
}

/// The shapes of one step.
#[derive(Clone, Debug, PartialEq)]
pub enum Geometry {
    /// Separate segments (the intervals of the Cantor set, drawn at y = 0).
    Segments(Vec<[P2; 2]>),
    /// One open polyline (Koch curve) or closed polygon (snowflake; first point repeated).
    Polyline(Vec<P2>),
    /// Filled triangles.
    Triangles(Vec<[P2; 3]>),
    /// Filled squares: lower-left corner and side.
    Squares(Vec<(P2, f64)>),
}

impl Geometry {
    /// Number of pieces (segments of a polyline).
    pub fn len(&self) -> usize {
        match self {
            Geometry::Segments(v) => v.len(),
            Geometry::Polyline(v) => v.len().saturating_sub(1),
            Geometry::Triangles(v) => v.len(),
            Geometry::Squares(v) => v.len(),
        }
    }

    /// Whether there are no pieces.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

const SQRT3: f64 = 1.732_050_807_568_877_2;

impl Construction {
    /// Every construction, in menu order.
    pub const ALL: [Construction; 5] = [
        Construction::Cantor,
        Construction::KochCurve,
        Construction::KochSnowflake,
        Construction::SierpinskiTriangle,
        Construction::SierpinskiCarpet,
    ];

    /// The construction's name, as shown.
    pub fn name(self) -> &'static str {
        match self {
            Construction::Cantor => "Cantor set",
            Construction::KochCurve => "Koch curve",
            Construction::KochSnowflake => "Koch snowflake",
            Construction::SierpinskiTriangle => "Sierpinski triangle",
            Construction::SierpinskiCarpet => "Sierpinski carpet",
        }
    }

    /// One step of the construction in a sentence.
    pub fn rule(self) -> &'static str {
        match self {
            Construction::Cantor => "Remove the open middle third of every segment.",
            Construction::KochCurve => {
                "Replace the middle third of every segment by the two other sides of an \
                 equilateral triangle standing on it: each segment becomes four."
            }
            Construction::KochSnowflake => {
                "Start from an equilateral triangle and apply the Koch step to all three sides."
            }
            Construction::SierpinskiTriangle => {
                "Split every triangle into four by joining the midpoints of its sides and remove \
                 the middle one."
            }
            Construction::SierpinskiCarpet => {
                "Split every square into nine and remove the middle one."
            }
        }
    }

    /// The limit's similarity dimension (log of the number of copies over log of the inverse
    /// scale factor).
    pub fn dimension(self) -> f64 {
        match self {
            Construction::Cantor => 2f64.ln() / 3f64.ln(),
            Construction::KochCurve | Construction::KochSnowflake => 4f64.ln() / 3f64.ln(),
            Construction::SierpinskiTriangle => 3f64.ln() / 2f64.ln(),
            Construction::SierpinskiCarpet => 8f64.ln() / 3f64.ln(),
        }
    }

    /// Largest step [`Self::geometry`] builds (about a million pieces at most).
    pub fn max_geometry_step(self) -> u32 {
        match self {
            Construction::Cantor => 20,
            Construction::KochCurve => 10,
            Construction::KochSnowflake => 9,
            Construction::SierpinskiTriangle => 12,
            Construction::SierpinskiCarpet => 6,
        }
    }

    /// The numbers after `n` steps (n ≤ [`MAX_STATS_STEP`]).
    pub fn stats(self, n: u32) -> Result<Stats, ExploreError> {
        super::check_range("the step", n as f64, 0.0, MAX_STATS_STEP as f64)?;
        let ni = n as i32;
        let third = 3f64.powi(-ni);
        let tri_area = SQRT3 / 4.0;
        let s = match self {
            Construction::Cantor => Stats {
                step: n,
                pieces: 1u128 << n,
                piece_size: third,
                length: Some((2.0f64 / 3.0).powi(ni)),
                area: None,
                initial_area: None,
                dimension: self.dimension(),
            },
            Construction::KochCurve => Stats {
                step: n,
                pieces: 4u128.pow(n),
                piece_size: third,
                length: Some((4.0f64 / 3.0).powi(ni)),
                area: None,
                initial_area: None,
                dimension: self.dimension(),
            },
            Construction::KochSnowflake => Stats {
                step: n,
                pieces: 3 * 4u128.pow(n),
                piece_size: third,
                length: Some(3.0 * (4.0f64 / 3.0).powi(ni)),
                // Step k adds 3·4^(k−1) triangles of area A₀/9^k: the sum is
                // A₀·(1 + 3/5·(1 − (4/9)^n)), tending to 8/5·A₀ = 2√3/5.
                area: Some(tri_area * (1.0 + 0.6 * (1.0 - (4.0f64 / 9.0).powi(ni)))),
                initial_area: Some(tri_area),
                dimension: self.dimension(),
            },
            Construction::SierpinskiTriangle => Stats {
                step: n,
                pieces: 3u128.pow(n),
                piece_size: 2f64.powi(-ni),
                length: None,
                area: Some(tri_area * 0.75f64.powi(ni)),
                initial_area: Some(tri_area),
                dimension: self.dimension(),
            },
            Construction::SierpinskiCarpet => Stats {
                step: n,
                pieces: 8u128.pow(n),
                piece_size: third,
                length: None,
                area: Some((8.0f64 / 9.0).powi(ni)),
                initial_area: Some(1.0),
                dimension: self.dimension(),
            },
        };
        Ok(s)
    }

    /// The limit of the area as the steps go on, where it is finite and non-zero.
    pub fn limit_area(self) -> Option<f64> {
        match self {
            Construction::KochSnowflake => Some(2.0 * SQRT3 / 5.0),
            _ => None,
        }
    }

    /// The shapes after `n` steps, starting from the unit segment [0, 1], the triangle
    /// (0, 0), (1, 0), (½, √3/2) or the unit square.
    pub fn geometry(self, n: u32) -> Result<Geometry, ExploreError> {
        super::check_range("the step", n as f64, 0.0, self.max_geometry_step() as f64)?;
        Ok(match self {
            Construction::Cantor => {
                let mut v = vec![(0.0, 1.0)];
                for _ in 0..n {
                    v = v
                        .iter()
                        .flat_map(|&(a, b)| {
                            let t = (b - a) / 3.0;
                            [(a, a + t), (b - t, b)]
                        })
                        .collect();
                }
                Geometry::Segments(v.into_iter().map(|(a, b)| [[a, 0.0], [b, 0.0]]).collect())
            }
            Construction::KochCurve => Geometry::Polyline(koch_curve_points(n)),
            Construction::KochSnowflake => {
                // Clockwise, so every bump (on the left of its side) points outwards.
                let corners = [[0.0, 0.0], [0.5, SQRT3 / 2.0], [1.0, 0.0], [0.0, 0.0]];
                let mut pts = vec![corners[0]];
                for w in corners.windows(2) {
                    koch_between(w[0], w[1], n, &mut pts);
                }
                Geometry::Polyline(pts)
            }
            Construction::SierpinskiTriangle => {
                let mut v = vec![[[0.0, 0.0], [1.0, 0.0], [0.5, SQRT3 / 2.0]]];
                for _ in 0..n {
                    v = v
                        .iter()
                        .flat_map(|&[a, b, c]| {
                            let ab = mid(a, b);
                            let bc = mid(b, c);
                            let ca = mid(c, a);
                            [[a, ab, ca], [ab, b, bc], [ca, bc, c]]
                        })
                        .collect();
                }
                Geometry::Triangles(v)
            }
            Construction::SierpinskiCarpet => {
                let mut v = vec![([0.0, 0.0], 1.0)];
                for _ in 0..n {
                    v = v
                        .iter()
                        .flat_map(|&(o, s): &(P2, f64)| {
                            let t = s / 3.0;
                            (0..9).filter(|&i| i != 4).map(move |i| {
                                ([o[0] + (i % 3) as f64 * t, o[1] + (i / 3) as f64 * t], t)
                            })
                        })
                        .collect();
                }
                Geometry::Squares(v)
            }
        })
    }
}

fn mid(a: P2, b: P2) -> P2 {
    [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]
}

/// Köse's Koch generator: the segment a→b split into thirds with a fifth point at the apex of
/// the equilateral triangle over the middle third, on the left of a→b.
pub fn koch_generator(a: P2, b: P2) -> [P2; 5] {
    let d = [(b[0] - a[0]) / 3.0, (b[1] - a[1]) / 3.0];
    let p1 = [a[0] + d[0], a[1] + d[1]];
    let p3 = [a[0] + 2.0 * d[0], a[1] + 2.0 * d[1]];
    // Rotate the third by +60°.
    let (s, c) = (SQRT3 / 2.0, 0.5);
    let apex = [p1[0] + c * d[0] - s * d[1], p1[1] + s * d[0] + c * d[1]];
    [a, p1, apex, p3, b]
}

/// Append the points of a Koch curve of order `n` from a to b, a excluded.
fn koch_between(a: P2, b: P2, n: u32, out: &mut Vec<P2>) {
    if n == 0 {
        out.push(b);
        return;
    }
    let g = koch_generator(a, b);
    for w in g.windows(2) {
        koch_between(w[0], w[1], n - 1, out);
    }
}

/// The 4ⁿ + 1 points of the Koch curve of order n from (0, 0) to (1, 0), bumps upwards.
pub fn koch_curve_points(n: u32) -> Vec<P2> {
    let n = n.min(Construction::KochCurve.max_geometry_step());
    let mut pts = Vec::with_capacity(4usize.pow(n) + 1);
    pts.push([0.0, 0.0]);
    koch_between([0.0, 0.0], [1.0, 0.0], n, &mut pts);
    pts
}

/// The Cantor dust map f(x) = (½ − |x − ½|)/r with r = ⅓, i.e. 3·min(x, 1 − x) (Köse 1990):
/// the points whose orbit stays in [0, 1] form the Cantor set.
pub fn cantor_map(x: f64) -> f64 {
    3.0 * x.min(1.0 - x)
}

/// The first step n ≥ 1 at which the orbit of x₀ under [`cantor_map`] is negative (from there
/// it runs off to −∞), or `None` if it stays in [0, 1] for `max_steps` steps.
pub fn cantor_exit_step(x0: f64, max_steps: u32) -> Option<u32> {
    let mut x = x0;
    for n in 1..=max_steps {
        x = cantor_map(x);
        if x < 0.0 {
            return Some(n);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + b.abs())
    }

    fn polyline_length(p: &[P2]) -> f64 {
        p.windows(2)
            .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
            .sum()
    }

    #[test]
    fn numbers_per_step() {
        for n in 0..=6u32 {
            let ni = n as i32;
            let c = Construction::Cantor.stats(n).unwrap();
            assert_eq!(c.pieces, 2u128.pow(n));
            assert!(close(c.piece_size, 3f64.powi(-ni), 1e-15));
            assert!(close(c.length.unwrap(), (2.0f64 / 3.0).powi(ni), 1e-15));
            let k = Construction::KochCurve.stats(n).unwrap();
            assert_eq!(k.pieces, 4u128.pow(n));
            assert!(close(k.length.unwrap(), (4.0f64 / 3.0).powi(ni), 1e-15));
            let s = Construction::KochSnowflake.stats(n).unwrap();
            assert_eq!(s.pieces, 3 * 4u128.pow(n));
            assert!(close(
                s.length.unwrap(),
                3.0 * (4.0f64 / 3.0).powi(ni),
                1e-15
            ));
            let t = Construction::SierpinskiTriangle.stats(n).unwrap();
            assert_eq!(t.pieces, 3u128.pow(n));
            assert!(close(t.piece_size, 2f64.powi(-ni), 1e-15));
            assert!(close(
                t.area.unwrap() / t.initial_area.unwrap(),
                0.75f64.powi(ni),
                1e-15
            ));
            let q = Construction::SierpinskiCarpet.stats(n).unwrap();
            assert_eq!(q.pieces, 8u128.pow(n));
            assert!(close(q.piece_size, 3f64.powi(-ni), 1e-15));
        }
        let dims = [0.63093, 1.26186, 1.26186, 1.58496, 1.89279];
        for (c, d) in Construction::ALL.iter().zip(dims) {
            assert!((c.dimension() - d).abs() < 5e-6, "{}", c.name());
        }
        // The snowflake's area tends to 2√3/5 = 0.692820 (8/5 of the triangle).
        let lim = Construction::KochSnowflake.limit_area().unwrap();
        assert!((lim - 0.692820).abs() < 5e-7);
        let a40 = Construction::KochSnowflake.stats(40).unwrap().area.unwrap();
        assert!((a40 - lim).abs() < 1e-12);
        assert!((lim / (SQRT3 / 4.0) - 1.6).abs() < 1e-15);
        assert_eq!(
            Construction::SierpinskiCarpet.stats(40).unwrap().pieces,
            1u128 << 120
        );
        assert!(Construction::Cantor.stats(41).is_err());
    }

    #[test]
    fn geometry_matches_the_numbers() {
        for c in Construction::ALL {
            for n in 0..=c.max_geometry_step().min(5) {
                let g = c.geometry(n).unwrap();
                let s = c.stats(n).unwrap();
                assert_eq!(g.len() as u128, s.pieces, "{} step {n}", c.name());
                match &g {
                    Geometry::Segments(v) => {
                        let len: f64 = v.iter().map(|s| s[1][0] - s[0][0]).sum();
                        assert!(close(len, s.length.unwrap(), 1e-12));
                    }
                    Geometry::Polyline(p) => {
                        assert!(close(polyline_length(p), s.length.unwrap(), 1e-12));
                        for w in p.windows(2) {
                            let l = (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
                            assert!(close(l, s.piece_size, 1e-12));
                        }
                    }
                    Geometry::Triangles(v) => {
                        let area: f64 = v
                            .iter()
                            .map(|[a, b, c]| {
                                ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))
                                    .abs()
                                    / 2.0
                            })
                            .sum();
                        assert!(close(area, s.area.unwrap(), 1e-12));
                    }
                    Geometry::Squares(v) => {
                        let area: f64 = v.iter().map(|q| q.1 * q.1).sum();
                        assert!(close(area, s.area.unwrap(), 1e-12));
                    }
                }
            }
        }
        // The snowflake polygon encloses the area of the formula (shoelace).
        for n in 0..=5 {
            let Geometry::Polyline(p) = Construction::KochSnowflake.geometry(n).unwrap() else {
                panic!()
            };
            let a: f64 = p
                .windows(2)
                .map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1])
                .sum::<f64>()
                .abs()
                / 2.0;
            let s = Construction::KochSnowflake.stats(n).unwrap();
            assert!(close(a, s.area.unwrap(), 1e-12), "step {n}: {a}");
            assert_eq!(p.first(), p.last());
        }
        assert!(Construction::SierpinskiCarpet.geometry(7).is_err());
        assert_eq!(
            Construction::KochCurve.geometry(10).unwrap().len(),
            1_048_576
        );
    }

    #[test]
    fn koch_generator_points() {
        let g = koch_generator([0.0, 0.0], [3.0, 0.0]);
        assert_eq!(g[1], [1.0, 0.0]);
        assert!((g[2][0] - 1.5).abs() < 1e-15 && (g[2][1] - SQRT3 / 2.0).abs() < 1e-15);
        assert_eq!(g[3], [2.0, 0.0]);
    }

    #[test]
    fn cantor_dust_map() {
        // x₀ < 0 runs off to −∞.
        let mut x = -0.01;
        for _ in 0..30 {
            x = cantor_map(x);
        }
        assert!(x < -1e12);
        assert_eq!(cantor_exit_step(-0.01, 10), Some(1));
        // x₀ > 1 is negative after one step.
        assert!(cantor_map(1.2) < 0.0);
        // 3/4 (0.2020…₃) is a fixed point, 0 belongs to C.
        assert_eq!(cantor_map(0.75), 0.75);
        assert_eq!(cantor_exit_step(0.75, 1000), None);
        assert_eq!(cantor_exit_step(0.0, 1000), None);
        // 0.5 → 1.5 → −1.5; 0.15 → 0.45 → 1.35 → −1.05.
        assert_eq!(cantor_map(0.5), 1.5);
        assert_eq!(cantor_map(1.5), -1.5);
        assert_eq!(cantor_exit_step(0.5, 10), Some(2));
        let o: Vec<f64> = std::iter::successors(Some(0.15), |&x| Some(cantor_map(x)))
            .skip(1)
            .take(3)
            .collect();
        for (a, b) in o.iter().zip([0.45, 1.35, -1.05]) {
            assert!((a - b).abs() < 1e-12);
        }
        assert_eq!(cantor_exit_step(0.15, 10), Some(3));
        // The removed thirds leave by step 2, the removed ninths by step 3.
        for i in 1..100 {
            let t = i as f64 / 100.0;
            assert_eq!(cantor_exit_step(1.0 / 3.0 + t / 3.0, 10), Some(2));
            assert_eq!(cantor_exit_step(1.0 / 9.0 + t / 9.0, 10), Some(3));
            assert_eq!(cantor_exit_step(7.0 / 9.0 + t / 9.0, 10), Some(3));
        }
    }
}
