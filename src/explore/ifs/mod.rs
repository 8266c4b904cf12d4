//! Iterated function systems of affine maps for teaching: the textbook tables (Kovács, the Su
//! Xiaohong slides, the Urbonavičius thesis), their fixed points and contraction numbers, the
//! chaos game as an incremental point source, and the conversion to an ugnis flame.

use super::{ExploreError, P2};
use crate::flame::model::{Affine, Flame, FlameKind, NewFlame, Xform};
use crate::flame::rng::FastRng;

/// Most maps an IFS may have (Fractint's own limit is 63 rows).
pub const MAX_MAPS: usize = 1000;
/// Points Kovács' chaos game plots by default.
pub const DEFAULT_POINTS: u64 = 100_000;

/// An IFS: affine maps x′ = a x + b y + e, y′ = c x + d y + f (Fractint's row order
/// `a b c d e f p`, y up) with their probabilities.
#[derive(Clone, Debug, PartialEq)]
pub struct Ifs {
    /// The table's name.
    pub name: String,
    /// The affine maps.
    pub maps: Vec<Affine>,
    /// As given (they need not sum to 1; the chaos game normalises them).
    pub probs: Vec<f64>,
}

impl Ifs {
    /// An IFS from rows `a b c d e f p`.
    pub fn from_rows(name: &str, rows: &[[f64; 7]]) -> Result<Ifs, ExploreError> {
        Self::new(
            name,
            rows.iter()
                .map(|r| Affine::new(r[0], r[1], r[2], r[3], r[4], r[5]))
                .collect(),
            rows.iter().map(|r| r[6]).collect(),
        )
    }

    /// An IFS from maps and probabilities: at least one map, finite coefficients,
    /// probabilities ≥ 0 with a positive sum.
    pub fn new(name: &str, maps: Vec<Affine>, probs: Vec<f64>) -> Result<Ifs, ExploreError> {
        if maps.is_empty() {
            return Err(ExploreError::Invalid(format!(
                "IFS '{name}' has no maps; give at least one"
            )));
        }
        if maps.len() > MAX_MAPS {
            return Err(ExploreError::TooLarge {
                what: format!("IFS '{name}' maps"),
                count: maps.len() as f64,
                limit: MAX_MAPS as f64,
                hint: String::new(),
            });
        }
        if maps.len() != probs.len() {
            return Err(ExploreError::Invalid(format!(
                "IFS '{name}': {} maps but {} probabilities",
                maps.len(),
                probs.len()
            )));
        }
        for (i, m) in maps.iter().enumerate() {
            if ![m.a, m.b, m.c, m.d, m.e, m.f].iter().all(|v| v.is_finite()) {
                return Err(ExploreError::Invalid(format!(
                    "IFS '{name}': map {} has a coefficient that is not a finite number",
                    i + 1
                )));
            }
            if !(probs[i].is_finite() && probs[i] >= 0.0) {
                return Err(ExploreError::Invalid(format!(
                    "IFS '{name}': map {} has probability {}; probabilities must be ≥ 0",
                    i + 1,
                    probs[i]
                )));
            }
        }
        if probs.iter().sum::<f64>() <= 0.0 {
            return Err(ExploreError::Invalid(format!(
                "IFS '{name}': the probabilities sum to 0"
            )));
        }
        Ok(Ifs {
            name: name.to_string(),
            maps,
            probs,
        })
    }

    /// Σp as given.
    pub fn probability_sum(&self) -> f64 {
        self.probs.iter().sum()
    }

    /// The probabilities scaled to sum to 1.
    pub fn normalised_probs(&self) -> Vec<f64> {
        let s = self.probability_sum();
        self.probs.iter().map(|p| p / s).collect()
    }

    /// Probabilities proportional to |det| of each map (a floor of 0.001 keeps degenerate
    /// maps such as a fern's stem in play), as Barnsley suggests for an even density.
    pub fn determinant_probs(&self) -> Vec<f64> {
        Flame::determinant_weights(&self.maps)
    }

    /// The fixed point of map `i`: the solution of (I − A)x = t, or `None` when I − A is
    /// singular.
    pub fn fixed_point(&self, i: usize) -> Option<P2> {
        fixed_point(self.maps.get(i)?)
    }

    /// The fixed points of all maps, in order.
    pub fn fixed_points(&self) -> Vec<Option<P2>> {
        self.maps.iter().map(fixed_point).collect()
    }

    /// Largest singular value of each map's linear part (below 1: the map is a contraction).
    pub fn contraction(&self) -> Vec<f64> {
        self.maps.iter().map(|m| m.max_singular_value()).collect()
    }

    /// Ratios of the maps if every map is a similarity (a rotation, possibly a reflection,
    /// and a uniform scaling).
    pub fn similarity_ratios(&self) -> Option<Vec<f64>> {
        self.maps
            .iter()
            .map(|m| {
                let tol = 1e-9 * (1.0 + m.a.abs() + m.b.abs());
                let rot = (m.a - m.d).abs() <= tol && (m.b + m.c).abs() <= tol;
                let refl = (m.a + m.d).abs() <= tol && (m.b - m.c).abs() <= tol;
                (rot || refl).then(|| m.det().abs().sqrt())
            })
            .collect()
    }

    /// The similarity dimension, if every map is a similarity with ratio in (0, 1) (exact
    /// when the pieces do not overlap much — the open set condition).
    pub fn similarity_dimension(&self) -> Option<f64> {
        super::dimension::similarity_dimension(&self.similarity_ratios()?).ok()
    }

    /// A chaos game on this IFS from `start`, plotting after `skip` steps.
    pub fn chaos_game(&self, start: P2, skip: u64, seed: u64) -> ChaosGame {
        ChaosGame::new(self, start, skip, seed)
    }

    /// `n` points of the chaos game from the origin after 20 discarded steps.
    pub fn points(&self, n: usize, seed: u64) -> Vec<P2> {
        let mut g = self.chaos_game([0.0, 0.0], 20, seed);
        (0..n).map(|_| g.next_point()).collect()
    }

    /// The IFS as an ugnis flame: one linear xform per map, weights = normalised
    /// probabilities, colours spread over the gradient (see [`linear_flame`]).
    pub fn to_flame(&self, defaults: &NewFlame) -> Flame {
        linear_flame(&self.name, &self.maps, self.normalised_probs(), defaults)
    }
}

/// Fractint (y up) ↔ flame (y down): conjugation with y → −y, its own inverse:
/// (a, b, c, d, e, f) → (a, −b, −c, d, e, −f).
pub fn conjugate_y(m: &Affine) -> Affine {
    Affine::new(m.a, -m.b, -m.c, m.d, m.e, -m.f)
}

/// A flame of affine maps given y up (Fractint's rows): one linear xform per map, conjugated
/// to the flame's y down ([`conjugate_y`]), with the given weights and colours spread evenly
/// over the gradient (0 for a single map). The flame is an IFS with the `defaults`' display
/// settings; the camera is left to automatic framing.
pub fn linear_flame(
    name: &str,
    maps: &[Affine],
    weights: impl IntoIterator<Item = f64>,
    defaults: &NewFlame,
) -> Flame {
    let mut f = defaults.flame();
    f.name = name.to_string();
    f.kind = FlameKind::Ifs;
    f.has_camera = false;
    let n = maps.len();
    f.xforms = maps
        .iter()
        .zip(weights)
        .enumerate()
        .map(|(i, (m, w))| {
            let c = if n > 1 {
                i as f64 / (n - 1) as f64
            } else {
                0.0
            };
            Xform::linear(conjugate_y(m), w, c)
        })
        .collect();
    f
}

/// The fixed point of an affine map, if I − A is invertible.
pub fn fixed_point(m: &Affine) -> Option<P2> {
    let (p, q, r, s) = (1.0 - m.a, -m.b, -m.c, 1.0 - m.d);
    let det = p * s - q * r;
    if det.abs() < 1e-14 {
        return None;
    }
    Some([(m.e * s - q * m.f) / det, (p * m.f - r * m.e) / det])
}

/// The chaos game: repeatedly pick a map at random (Fractint's rule: walk the cumulative
/// probabilities until they exceed a uniform r ∈ [0, 1); the last map takes any rounding
/// deficit) and apply it to the current point. A point source for live views: pull as many
/// points per frame as wanted.
#[derive(Clone, Debug)]
pub struct ChaosGame {
    maps: Vec<Affine>,
    cumulative: Vec<f64>,
    rng: FastRng,
    point: P2,
    steps: u64,
    skip: u64,
}

impl ChaosGame {
    /// A chaos game on `ifs` from `start`, its first `skip` points taken but not returned, with
    /// random map choices from `seed`.
    pub fn new(ifs: &Ifs, start: P2, skip: u64, seed: u64) -> ChaosGame {
        let mut acc = 0.0;
        let cumulative = ifs
            .normalised_probs()
            .iter()
            .map(|p| {
                acc += p;
                acc
            })
            .collect();
        ChaosGame {
            maps: ifs.maps.clone(),
            cumulative,
            rng: FastRng::new(seed),
            point: start,
            steps: 0,
            skip,
        }
    }

    /// Kovács' game: corners (0, 0), (1, 0), (½, √3/2), each step moves halfway towards a
    /// corner picked uniformly; starts at the triangle's centre, plots after 10 steps.
    pub fn triangle(seed: u64) -> ChaosGame {
        let ifs = presets::kovacs_sierpinski();
        ChaosGame::new(&ifs, [0.5, 3f64.sqrt() / 6.0], 10, seed)
    }

    /// One step: the new point and the index of the map applied.
    #[inline]
    pub fn step(&mut self) -> (P2, usize) {
        let r = self.rng.f01();
        let n = self.maps.len();
        let i = self.cumulative[..n - 1]
            .iter()
            .position(|&c| r < c)
            .unwrap_or(n - 1);
        let (x, y) = self.maps[i].apply(self.point[0], self.point[1]);
        self.point = [x, y];
        self.steps += 1;
        (self.point, i)
    }

    /// The next point to plot (the first `skip` steps are taken but not returned).
    #[inline]
    pub fn next_point(&mut self) -> P2 {
        while self.steps < self.skip {
            self.step();
        }
        self.step().0
    }

    /// Take `n` plotted steps, handing each point and its map to `plot`.
    pub fn run(&mut self, n: u64, mut plot: impl FnMut(P2, usize)) {
        while self.steps < self.skip {
            self.step();
        }
        for _ in 0..n {
            let (p, i) = self.step();
            plot(p, i);
        }
    }

    /// The current point.
    pub fn point(&self) -> P2 {
        self.point
    }

    /// Steps taken so far (including the skipped ones).
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Points plotted so far.
    pub fn plotted(&self) -> u64 {
        self.steps.saturating_sub(self.skip)
    }
}

impl Iterator for ChaosGame {
    type Item = P2;

    fn next(&mut self) -> Option<P2> {
        Some(self.next_point())
    }
}

pub mod presets;

#[cfg(test)]
mod tests {
    use super::presets::*;
    use super::*;
    use crate::explore::dimension::box_count_points;

    fn near(p: Option<P2>, q: P2, tol: f64) -> bool {
        p.is_some_and(|p| (p[0] - q[0]).abs() <= tol && (p[1] - q[1]).abs() <= tol)
    }

    fn bbox(points: &[P2]) -> [f64; 4] {
        let b = crate::explore::Bounds::of(points.iter().copied());
        [b.min[0], b.max[0], b.min[1], b.max[1]]
    }

    #[test]
    fn t1_fixed_points_and_probabilities() {
        let t = t1_sierpinski_pixels();
        assert!((t.probability_sum() - 0.99).abs() < 1e-12);
        assert!((t.normalised_probs().iter().sum::<f64>() - 1.0).abs() < 1e-12);
        let fp = t.fixed_points();
        assert!(near(fp[0], [50.0, 2.0], 1e-12));
        assert!(near(fp[1], [2.0, 100.0], 1e-12));
        assert!(near(fp[2], [100.0, 100.0], 1e-12));
        // Apex at the top in y-down pixels: the smallest y belongs to the first map.
        assert!(fp[0].unwrap()[1] < fp[1].unwrap()[1]);
    }

    #[test]
    fn slide_tables_fixed_points() {
        assert!(near(
            t3_fern_leaflet().fixed_point(1),
            [0.7722, 5.7915],
            5e-5
        ));
        let t4 = t4_tree_crown().fixed_points();
        assert!(near(t4[0], [0.0, 0.0], 1e-12));
        assert!(near(t4[1], [0.0, 0.2759], 5e-5));
        assert!(near(t4[2], [-0.3276, 0.4524], 5e-5));
        assert!(near(t4[3], [0.3276, 0.4524], 5e-5));
        let t5 = t5_maple_hexagonal().contraction();
        assert!((t5[2] - 0.9262).abs() < 5e-5 && (t5[3] - 0.9262).abs() < 5e-5);
        let t6 = t6_maple().fixed_points();
        for (p, q) in t6
            .iter()
            .zip([[0.45, 0.9], [0.45, 0.3], [0.6, 0.3], [0.3, 0.3]])
        {
            assert!(near(*p, q, 1e-12), "{p:?} vs {q:?}");
        }
        let t7 = t7_tree().contraction();
        assert!(t7.iter().all(|&s| s < 1.0));
        let m = t7.iter().copied().fold(0.0, f64::max);
        assert!((m - 0.6005).abs() < 5e-5, "{m}");
        let t8 = t8_five_maps().fixed_points();
        let want = [[0.0, 0.0], [-0.5, 1.0], [0.2, 0.8], [0.0, 1.5], [1.0, 1.0]];
        for (p, q) in t8.iter().zip(want) {
            assert!(near(*p, q, 1e-12), "{p:?} vs {q:?}");
        }
    }

    #[test]
    fn durer_pentagon() {
        let t9 = t9_durer_pentagon();
        let fp: Vec<P2> = t9.fixed_points().into_iter().map(Option::unwrap).collect();
        // The apex is the first fixed point; the five lie on one circle, 72° apart.
        assert!(near(Some(fp[0]), [0.4971, 1.0016], 5e-5));
        let cx = fp.iter().map(|p| p[0]).sum::<f64>() / 5.0;
        let cy = fp.iter().map(|p| p[1]).sum::<f64>() / 5.0;
        let r: Vec<f64> = fp.iter().map(|p| (p[0] - cx).hypot(p[1] - cy)).collect();
        for ri in &r {
            assert!((ri / r[0] - 1.0).abs() < 2e-3, "{r:?}");
        }
        assert!(fp[0][1] > fp.iter().skip(1).map(|p| p[1]).fold(0.0, f64::max));
        // 0.382 rounds 1/φ² = 0.381966: the dimension is 1.67228 within the rounding.
        let d = t9.similarity_dimension().unwrap();
        assert!((d - 1.67228).abs() < 1e-3, "{d}");
    }

    #[test]
    fn levy_c_curve() {
        let t = t10_levy_c();
        let fp = t.fixed_points();
        assert!(near(fp[0], [0.0, 0.0], 1e-15));
        assert!(near(fp[1], [1.0, 0.0], 1e-15));
        // Complex form: z → (1 + i)z/2, z → (1 − i)z/2 + (1 + i)/2.
        let z = (0.3, -0.7);
        let (x, y) = t.maps[0].apply(z.0, z.1);
        assert!(
            ((x, y).0 - (z.0 - z.1) / 2.0).abs() < 1e-15 && (y - (z.0 + z.1) / 2.0).abs() < 1e-15
        );
        let (x, y) = t.maps[1].apply(z.0, z.1);
        assert!((x - ((z.0 + z.1) / 2.0 + 0.5)).abs() < 1e-15);
        assert!((y - ((z.1 - z.0) / 2.0 + 0.5)).abs() < 1e-15);
        let r = t.similarity_ratios().unwrap();
        assert!(r.iter().all(|v| (v - 0.5f64.sqrt()).abs() < 1e-15));
        assert!((t.similarity_dimension().unwrap() - 2.0).abs() < 1e-9);
    }

    #[test]
    fn dragon_preset() {
        // T11: Fractint's dragon rows with p = 0.8 / 0.2; fixed points as Fractint's entry.
        let t = t11_dragon();
        assert_eq!(t.probs, vec![0.8, 0.2]);
        let fp = t.fixed_points();
        assert!(near(fp[0], [-3.4275, 4.5449], 5e-5));
        assert!(near(fp[1], [3.5383, 4.6846], 5e-5));
    }

    #[test]
    fn thesis_systems() {
        let a = thesis_a();
        assert!((a.probability_sum() - 0.99).abs() < 1e-12);
        let p = a.determinant_probs();
        for (x, y) in p.iter().zip([0.261015, 0.255580, 0.483405]) {
            assert!((x - y).abs() < 1e-6, "{p:?}");
        }
        assert!((a.contraction()[2] - 1.0035).abs() < 5e-5);
        // Not every map contracts, yet the chaos game is stable.
        let pts = a.points(300_000, 1);
        let b = bbox(&pts);
        for (x, y) in b.iter().zip([-1.91, 1.52, -1.39, 1.87]) {
            assert!((x - y).abs() < 0.02, "{b:?}");
        }
        let bsys = thesis_b();
        let p = bsys.determinant_probs();
        assert!((p[0] - 0.601491).abs() < 1e-6 && (p[1] - 0.398509).abs() < 1e-6);
        let b = bbox(&bsys.points(300_000, 1));
        for (x, y) in b.iter().zip([-2.00, 1.56, -1.57, 1.36]) {
            assert!((x - y).abs() < 0.02, "{b:?}");
        }
    }

    #[test]
    fn fern() {
        let f = fractint_fern();
        assert!(near(f.fixed_point(1), [2.6556, 9.9585], 5e-5));
        // 300 000 points from the origin stay in x ∈ [−2.19, 2.66], y ∈ [0, 10].
        let mut g = f.chaos_game([0.0, 0.0], 0, 7);
        let mut b = crate::explore::Bounds::EMPTY;
        g.run(300_000, |p, _| b.add(p));
        assert!(b.min[0] >= -2.19 && b.max[0] <= 2.66, "{b:?}");
        assert!(b.min[1] >= 0.0 && b.max[1] <= 10.0, "{b:?}");
        // …and reach close to the frond tip.
        assert!(b.max[1] > 9.9);
    }

    #[test]
    fn triangle_game() {
        let mut g = ChaosGame::triangle(3);
        let s3 = 3f64.sqrt();
        // Every iterate after step 1 avoids the open central triangle (¼, √3/4), (¾, √3/4),
        // (½, 0): inside it means y < √3/4 and above both lines through (½, 0).
        let in_central = |p: P2| {
            p[1] < s3 / 4.0 - 1e-12
                && p[1] > s3 * (p[0] - 0.5) + 1e-12
                && p[1] > -s3 * (p[0] - 0.5) + 1e-12
        };
        let mut level = vec![];
        if let crate::explore::classic::Geometry::Triangles(t) =
            crate::explore::classic::Construction::SierpinskiTriangle
                .geometry(6)
                .unwrap()
        {
            level = t;
        }
        let inside = |p: P2, t: &[P2; 3]| {
            let s = |a: P2, b: P2| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
            s(t[0], t[1]) >= -1e-12 && s(t[1], t[2]) >= -1e-12 && s(t[2], t[0]) >= -1e-12
        };
        for k in 1..=2000u64 {
            let (p, _) = g.step();
            assert!(!in_central(p), "step {k}: {p:?}");
            if k >= 6 {
                // After k ≥ 6 steps the point lies in one of the 3⁶ level-6 triangles.
                assert!(level.iter().any(|t| inside(p, t)), "step {k}: {p:?}");
            }
        }
        // The box dimension of 10⁶ points is 1.585 ± 0.05.
        let mut g = ChaosGame::triangle(4);
        let pts: Vec<P2> = (0..1_000_000).map(|_| g.next_point()).collect();
        let d = box_count_points(&pts).unwrap().dimension().unwrap();
        assert!((d - 1.585).abs() < 0.05, "{d}");
        assert_eq!(g.plotted(), 1_000_000);
        assert_eq!(g.steps(), 1_000_010);
    }

    #[test]
    fn fractint_triangle_fills_its_triangle() {
        let pts = fractint_triangle().points(200_000, 5);
        let b = bbox(&pts);
        for (x, y) in b.iter().zip([0.0, 2.0, 0.0, 2.0]) {
            assert!((x - y).abs() < 0.01, "{b:?}");
        }
        // The triangle (0, 0), (0, 2), (2, 2) is 0 ≤ x ≤ y ≤ 2.
        assert!(pts.iter().all(|p| p[0] >= -1e-9 && p[0] <= p[1] + 1e-9));
        let d = box_count_points(&pts).unwrap().dimension().unwrap();
        assert!((d - 1.585).abs() < 0.05, "{d}");
    }

    #[test]
    fn box_dimension_of_presets() {
        for (ifs, want, n) in [
            (kovacs_carpet(), 1.893, 10_000_000),
            (koch_curve(), 1.262, 1_000_000),
            (kovacs_cantor(), 0.631, 1_000_000),
        ] {
            let pts = ifs.points(n, 11);
            let d = box_count_points(&pts).unwrap().dimension().unwrap();
            assert!((d - want).abs() < 0.05, "{}: {d}", ifs.name);
            let s = ifs.similarity_dimension().unwrap();
            assert!((s - want).abs() < 1e-3, "{}: {s}", ifs.name);
        }
    }

    #[test]
    fn flame_conversion_flips_y() {
        let f = fractint_fern().to_flame(&NewFlame::default());
        assert_eq!(f.kind, FlameKind::Ifs);
        assert_eq!(f.xforms.len(), 4);
        let c = f.xforms[1].coefs;
        assert_eq!(
            c.to_coefs(),
            [0.85, 0.04, -0.04, 0.85, 0.0, -1.6],
            "flam3 coefs order a c b d e f"
        );
        // The conjugated map's fixed point is the tip mirrored: (2.6556, −9.9585).
        assert!(near(fixed_point(&c), [2.6556, -9.9585], 5e-5));
        let w: f64 = f.xforms.iter().map(|x| x.weight).sum();
        assert!((w - 1.0).abs() < 1e-12);
        // The flame iterates: its attractor has the fern's dimension region (about 1.7–1.9).
        let b = crate::explore::dimension::box_count_flame(&f, 1_000_000, 1).unwrap();
        let d = b.dimension().unwrap();
        assert!(d > 1.5 && d < 2.0, "{d}");
    }

    #[test]
    fn invalid_tables_are_refused() {
        assert!(Ifs::from_rows("x", &[]).is_err());
        assert!(Ifs::from_rows("x", &[[0.5, 0.0, 0.0, 0.5, 0.0, 0.0, -1.0]]).is_err());
        assert!(Ifs::from_rows("x", &[[0.5, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0]]).is_err());
        assert!(Ifs::from_rows("x", &[[f64::NAN, 0.0, 0.0, 0.5, 0.0, 0.0, 1.0]]).is_err());
        assert!(Ifs::new("x", vec![Affine::IDENTITY], vec![]).is_err());
    }
}
