//! Parametric patches: Bézier of any degree, Hermite bicubic, bilinear,
//! ruled and linear Coons patches; derivatives and normals with fallbacks at degenerate points.

use glam::DVec3;

/// Binomial coefficient C(n, k).
pub fn binomial(n: usize, k: usize) -> f64 {
    let mut r = 1.0;
    for i in 0..k.min(n - k.min(n)) {
        r = r * (n - i) as f64 / (i + 1) as f64;
    }
    r
}

/// Bernstein basis J_{n,i}(t) for i = 0..=n.
pub fn bernstein(n: usize, t: f64) -> Vec<f64> {
    (0..=n)
        .map(|i| binomial(n, i) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32))
        .collect()
}

/// Derivatives of the Bernstein basis: J′_{n,i}(t) = n (J_{n−1,i−1} − J_{n−1,i}).
pub fn bernstein_deriv(n: usize, t: f64) -> Vec<f64> {
    if n == 0 {
        return vec![0.0];
    }
    let b = bernstein(n - 1, t);
    (0..=n)
        .map(|i| {
            let a = if i > 0 { b[i - 1] } else { 0.0 };
            let c = if i < n { b[i] } else { 0.0 };
            n as f64 * (a - c)
        })
        .collect()
}

/// Hermite basis [F₁ F₂ F₃ F₄] at t.
pub fn hermite(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        2.0 * t3 - 3.0 * t2 + 1.0,
        -2.0 * t3 + 3.0 * t2,
        t3 - 2.0 * t2 + t,
        t3 - t2,
    ]
}

fn hermite_deriv(t: f64) -> [f64; 4] {
    let t2 = t * t;
    [
        6.0 * t2 - 6.0 * t,
        -6.0 * t2 + 6.0 * t,
        3.0 * t2 - 4.0 * t + 1.0,
        3.0 * t2 - 2.0 * t,
    ]
}

/// A Bézier curve of any degree.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    pub points: Vec<DVec3>,
}

impl Curve {
    pub fn eval(&self, t: f64) -> DVec3 {
        let n = self.points.len() - 1;
        bernstein(n, t)
            .iter()
            .zip(&self.points)
            .map(|(b, p)| *p * *b)
            .sum()
    }
}

/// de Casteljau split of a cubic row at t = ½.
#[cfg(test)]
pub fn split_cubic(p: [DVec3; 4]) -> ([DVec3; 4], [DVec3; 4]) {
    let m = (p[0] + p[1] * 3.0 + p[2] * 3.0 + p[3]) / 8.0;
    (
        [
            p[0],
            (p[0] + p[1]) / 2.0,
            (p[0] + p[1] * 2.0 + p[2]) / 4.0,
            m,
        ],
        [
            m,
            (p[1] + p[2] * 2.0 + p[3]) / 4.0,
            (p[2] + p[3]) / 2.0,
            p[3],
        ],
    )
}

/// Why a patch cannot be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PatchError {
    #[error("a Bézier net of {rows}×{cols} needs {need} points, got {got}")]
    NetSize {
        rows: usize,
        cols: usize,
        need: usize,
        got: usize,
    },
    #[error("Coons boundary curves do not meet at corner {0} (gap {1:.3e} > 1e-9)")]
    CoonsCorners(&'static str, f64),
    #[error("a curve needs at least 2 points")]
    ShortCurve,
}

/// A parametric patch Q(u, w), (u, w) ∈ [0, 1]².
#[derive(Clone, Debug, PartialEq)]
// Patches are few (tens per scene); a boxed Hermite matrix would only add indirection.
#[allow(clippy::large_enum_variant)]
pub enum Patch {
    /// (n + 1)×(m + 1) control net, row i along u: `net[i·(m + 1) + j]`.
    Bezier {
        /// Degree in u.
        n: usize,
        /// Degree in w.
        m: usize,
        /// The control points, (n + 1)·(m + 1) of them.
        net: Vec<DVec3>,
    },
    /// The 4×4 Hermite geometry matrix P: corners, tangents and twists.
    Hermite {
        /// The geometry matrix, row by row.
        g: [[DVec3; 4]; 4],
    },
    /// Corners p₀₀, p₀₁, p₁₀, p₁₁.
    Bilinear {
        /// The four corners, in that order.
        p: [DVec3; 4],
    },
    /// Q(u, w) = c₀(u)(1 − w) + c₁(u)w.
    Ruled {
        /// The curve at w = 0.
        c0: Curve,
        /// The curve at w = 1.
        c1: Curve,
    },
    /// Linear Coons patch from p(u, 0), p(u, 1), p(0, w), p(1, w).
    Coons {
        /// The boundary p(u, 0).
        u0: Curve,
        /// The boundary p(u, 1).
        u1: Curve,
        /// The boundary p(0, w).
        w0: Curve,
        /// The boundary p(1, w).
        w1: Curve,
    },
}

impl Patch {
    /// A Bézier patch of degrees n×m; fails unless the net holds (n + 1)·(m + 1) points and
    /// both degrees are at least 1.
    pub fn bezier(n: usize, m: usize, net: Vec<DVec3>) -> Result<Patch, PatchError> {
        let need = (n + 1) * (m + 1);
        if net.len() != need || n == 0 || m == 0 {
            return Err(PatchError::NetSize {
                rows: n + 1,
                cols: m + 1,
                need,
                got: net.len(),
            });
        }
        Ok(Patch::Bezier { n, m, net })
    }

    /// A Coons patch; fails when a curve has fewer than 2 points or the boundaries do not meet
    /// at the corners (within 1e-9).
    pub fn coons(u0: Curve, u1: Curve, w0: Curve, w1: Curve) -> Result<Patch, PatchError> {
        for c in [&u0, &u1, &w0, &w1] {
            if c.points.len() < 2 {
                return Err(PatchError::ShortCurve);
            }
        }
        for (name, a, b) in [
            ("(0,0)", u0.eval(0.0), w0.eval(0.0)),
            ("(1,0)", u0.eval(1.0), w1.eval(0.0)),
            ("(0,1)", u1.eval(0.0), w0.eval(1.0)),
            ("(1,1)", u1.eval(1.0), w1.eval(1.0)),
        ] {
            let gap = (a - b).length();
            if gap > 1e-9 {
                return Err(PatchError::CoonsCorners(name, gap));
            }
        }
        Ok(Patch::Coons { u0, u1, w0, w1 })
    }

    /// The point Q(u, w).
    pub fn eval(&self, u: f64, w: f64) -> DVec3 {
        match self {
            Patch::Bezier { n, m, net } => {
                let (bu, bw) = (bernstein(*n, u), bernstein(*m, w));
                let mut q = DVec3::ZERO;
                for i in 0..=*n {
                    for j in 0..=*m {
                        q += net[i * (m + 1) + j] * (bu[i] * bw[j]);
                    }
                }
                q
            }
            Patch::Hermite { g } => {
                let (fu, fw) = (hermite(u), hermite(w));
                let mut q = DVec3::ZERO;
                for i in 0..4 {
                    for j in 0..4 {
                        q += g[i][j] * (fu[i] * fw[j]);
                    }
                }
                q
            }
            Patch::Bilinear { p } => {
                p[0] * ((1.0 - u) * (1.0 - w))
                    + p[1] * ((1.0 - u) * w)
                    + p[2] * (u * (1.0 - w))
                    + p[3] * (u * w)
            }
            Patch::Ruled { c0, c1 } => c0.eval(u) * (1.0 - w) + c1.eval(u) * w,
            Patch::Coons { u0, u1, w0, w1 } => {
                let (p00, p01, p10, p11) = (u0.eval(0.0), u1.eval(0.0), u0.eval(1.0), u1.eval(1.0));
                u0.eval(u) * (1.0 - w) + u1.eval(u) * w + w0.eval(w) * (1.0 - u) + w1.eval(w) * u
                    - p00 * ((1.0 - u) * (1.0 - w))
                    - p01 * ((1.0 - u) * w)
                    - p10 * (u * (1.0 - w))
                    - p11 * (u * w)
            }
        }
    }

    /// Partial derivatives (Q_u, Q_w).
    pub fn derivs(&self, u: f64, w: f64) -> (DVec3, DVec3) {
        match self {
            Patch::Bezier { n, m, net } => {
                let (bu, bw) = (bernstein(*n, u), bernstein(*m, w));
                let (du, dw) = (bernstein_deriv(*n, u), bernstein_deriv(*m, w));
                let (mut qu, mut qw) = (DVec3::ZERO, DVec3::ZERO);
                for i in 0..=*n {
                    for j in 0..=*m {
                        let p = net[i * (m + 1) + j];
                        qu += p * (du[i] * bw[j]);
                        qw += p * (bu[i] * dw[j]);
                    }
                }
                (qu, qw)
            }
            Patch::Hermite { g } => {
                let (fu, fw, du, dw) = (hermite(u), hermite(w), hermite_deriv(u), hermite_deriv(w));
                let (mut qu, mut qw) = (DVec3::ZERO, DVec3::ZERO);
                for i in 0..4 {
                    for j in 0..4 {
                        qu += g[i][j] * (du[i] * fw[j]);
                        qw += g[i][j] * (fu[i] * dw[j]);
                    }
                }
                (qu, qw)
            }
            _ => {
                let h = 1e-6;
                let (u0, u1) = ((u - h).max(0.0), (u + h).min(1.0));
                let (w0, w1) = ((w - h).max(0.0), (w + h).min(1.0));
                (
                    (self.eval(u1, w) - self.eval(u0, w)) / (u1 - u0),
                    (self.eval(u, w1) - self.eval(u, w0)) / (w1 - w0),
                )
            }
        }
    }

    /// Q(u, w) with (Q_u, Q_w) in one pass, without allocating for bicubic Bézier patches
    /// (the ray caster's Newton iteration calls this per pixel).
    pub fn eval_with_derivs(&self, u: f64, w: f64) -> (DVec3, DVec3, DVec3) {
        if let Patch::Bezier { n: 3, m: 3, net } = self {
            let cubic = |t: f64| {
                let s = 1.0 - t;
                (
                    [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t],
                    [
                        -3.0 * s * s,
                        3.0 * s * s - 6.0 * t * s,
                        6.0 * t * s - 3.0 * t * t,
                        3.0 * t * t,
                    ],
                )
            };
            let ((bu, du), (bw, dw)) = (cubic(u), cubic(w));
            let (mut q, mut qu, mut qw) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
            for i in 0..4 {
                let (mut row, mut rowd) = (DVec3::ZERO, DVec3::ZERO);
                for j in 0..4 {
                    let p = net[i * 4 + j];
                    row += p * bw[j];
                    rowd += p * dw[j];
                }
                q += row * bu[i];
                qu += row * du[i];
                qw += rowd * bu[i];
            }
            return (q, qu, qw);
        }
        let (qu, qw) = self.derivs(u, w);
        (self.eval(u, w), qu, qw)
    }

    /// Unit normal Q_u × Q_w; where it vanishes, the normal a step inside the patch.
    pub fn normal(&self, u: f64, w: f64) -> DVec3 {
        let (qu, qw) = self.derivs(u, w);
        let n = qu.cross(qw);
        if n.length_squared() > 1e-24 {
            return n.normalize();
        }
        for d in [1e-4, 1e-3, 1e-2] {
            let uu = if u < 0.5 { u + d } else { u - d };
            let ww = if w < 0.5 { w + d } else { w - d };
            let (a, b) = self.derivs(uu, ww);
            let n = a.cross(b);
            if n.length_squared() > 1e-24 {
                return n.normalize();
            }
        }
        DVec3::Y
    }

    /// Control points (for bounds; the surface lies in their convex hull for Bézier patches).
    pub fn control_points(&self) -> Vec<DVec3> {
        match self {
            Patch::Bezier { net, .. } => net.clone(),
            Patch::Hermite { g } => (0..4)
                .flat_map(|i| (0..2).map(move |j| g[i][j]))
                .take(4)
                .collect(),
            Patch::Bilinear { p } => p.to_vec(),
            Patch::Ruled { c0, c1 } => c0.points.iter().chain(&c1.points).copied().collect(),
            Patch::Coons { u0, u1, w0, w1 } => u0
                .points
                .iter()
                .chain(&u1.points)
                .chain(&w0.points)
                .chain(&w1.points)
                .copied()
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fast_cubic_evaluation_matches_the_general_one() {
        // The oracle net B_ij = (i, j, 1 if i, j ∈ {1, 2} else 0).
        let net: Vec<DVec3> = (0..4)
            .flat_map(|i| {
                (0..4).map(move |j| {
                    let inner = (1..=2).contains(&i) && (1..=2).contains(&j);
                    DVec3::new(i as f64, j as f64, if inner { 1.0 } else { 0.0 })
                })
            })
            .collect();
        let p = Patch::Bezier { n: 3, m: 3, net };
        let (q, _, _) = p.eval_with_derivs(0.5, 0.5);
        assert!((q - DVec3::new(1.5, 1.5, 0.5625)).length() < 1e-15);
        let (q, _, _) = p.eval_with_derivs(0.25, 0.5);
        assert!((q - DVec3::new(0.75, 1.5, 0.421875)).length() < 1e-15);
        for k in 0..25 {
            let (u, w) = ((k % 5) as f64 / 4.0, (k / 5) as f64 / 4.0 * 0.9 + 0.03);
            let (q, qu, qw) = p.eval_with_derivs(u, w);
            let (gu, gw) = p.derivs(u, w);
            assert!((q - p.eval(u, w)).length() < 1e-12);
            assert!((qu - gu).length() < 1e-12 && (qw - gw).length() < 1e-12);
        }
    }

    #[test]
    fn basis_oracles() {
        let h = hermite(0.5);
        assert_eq!(h, [0.5, 0.5, 0.125, -0.125]);
        let h = hermite(0.25);
        for (a, b) in h.iter().zip([0.84375, 0.15625, 0.140625, -0.046875]) {
            assert!((a - b).abs() < 1e-15);
        }
        assert_eq!(bernstein(3, 0.5), vec![0.125, 0.375, 0.375, 0.125]);
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            for n in 1..7 {
                assert!((bernstein(n, t).iter().sum::<f64>() - 1.0).abs() < 1e-12);
            }
        }
        // The cubic Bernstein derivative formulas.
        let t: f64 = 0.3;
        let d = bernstein_deriv(3, t);
        let want = [
            -3.0 * (1.0 - t).powi(2),
            3.0 * (1.0 - t).powi(2) - 6.0 * t * (1.0 - t),
            6.0 * t * (1.0 - t) - 3.0 * t * t,
            3.0 * t * t,
        ];
        for (a, b) in d.iter().zip(want) {
            assert!((a - b).abs() < 1e-12);
        }
    }

    fn net(f: impl Fn(usize, usize) -> DVec3) -> Patch {
        Patch::bezier(
            3,
            3,
            (0..4)
                .flat_map(|i| (0..4).map(move |j| (i, j)))
                .map(|(i, j)| f(i, j))
                .collect(),
        )
        .unwrap()
    }

    #[test]
    fn bezier_patch_oracles() {
        let p = net(|i, j| {
            let inner = (1..=2).contains(&i) && (1..=2).contains(&j);
            DVec3::new(i as f64, j as f64, if inner { 1.0 } else { 0.0 })
        });
        assert!((p.eval(0.5, 0.5) - DVec3::new(1.5, 1.5, 0.5625)).length() < 1e-15);
        assert!((p.eval(0.25, 0.5) - DVec3::new(0.75, 1.5, 0.421875)).length() < 1e-15);
        for (u, w, i, j) in [
            (0.0, 0.0, 0, 0),
            (1.0, 0.0, 3, 0),
            (0.0, 1.0, 0, 3),
            (1.0, 1.0, 3, 3),
        ] {
            let Patch::Bezier { net, .. } = &p else {
                unreachable!()
            };
            assert_eq!(p.eval(u, w), net[i * 4 + j]);
        }
        let plane = net(|i, j| DVec3::new(i as f64, j as f64, 0.0));
        for (u, w) in [(0.1, 0.7), (0.5, 0.5), (0.93, 0.2)] {
            assert!((plane.eval(u, w) - DVec3::new(3.0 * u, 3.0 * w, 0.0)).length() < 1e-14);
            assert!((plane.normal(u, w) - DVec3::Z).length() < 1e-12);
        }
        // Edge slope: ∂Q/∂u(0, w) = n Σ (B₁ⱼ − B₀ⱼ) K(w).
        let (qu, _) = p.derivs(0.0, 0.3);
        let k = bernstein(3, 0.3);
        let want = DVec3::new(3.0, 0.0, 3.0 * (k[1] + k[2]));
        assert!((qu - want).length() < 1e-12, "{qu:?}");
        // Subdivision: the halves meet at Q(½) of the row.
        let row = [
            DVec3::ZERO,
            DVec3::new(1.0, 2.0, 0.0),
            DVec3::new(3.0, 2.0, 1.0),
            DVec3::new(4.0, 0.0, 0.0),
        ];
        let (l, r) = split_cubic(row);
        let c = Curve {
            points: row.to_vec(),
        };
        assert!((l[3] - c.eval(0.5)).length() < 1e-15 && l[3] == r[0]);
        let cl = Curve { points: l.to_vec() };
        assert!((cl.eval(0.5) - c.eval(0.25)).length() < 1e-14);
    }

    #[test]
    fn bilinear_ruled_coons_reproduce_their_boundaries() {
        let c = [
            DVec3::ZERO,
            DVec3::new(0.0, 1.0, 0.3),
            DVec3::new(1.0, 0.0, 0.2),
            DVec3::new(1.0, 1.0, 1.0),
        ];
        let b = Patch::Bilinear { p: c };
        assert_eq!(b.eval(0.0, 0.0), c[0]);
        assert_eq!(b.eval(0.0, 1.0), c[1]);
        assert_eq!(b.eval(1.0, 0.0), c[2]);
        assert_eq!(b.eval(1.0, 1.0), c[3]);
        let curve = |pts: &[[f64; 3]]| Curve {
            points: pts.iter().map(|p| DVec3::from_array(*p)).collect(),
        };
        let u0 = curve(&[[0.0, 0.0, 0.0], [0.5, 0.0, 0.4], [1.0, 0.0, 0.0]]);
        let u1 = curve(&[[0.0, 1.0, 0.0], [0.5, 1.0, -0.3], [1.0, 1.0, 0.0]]);
        let w0 = curve(&[[0.0, 0.0, 0.0], [0.0, 0.5, 0.2], [0.0, 1.0, 0.0]]);
        let w1 = curve(&[[1.0, 0.0, 0.0], [1.0, 0.5, 0.1], [1.0, 1.0, 0.0]]);
        let coons = Patch::coons(u0.clone(), u1.clone(), w0.clone(), w1.clone()).unwrap();
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            assert!((coons.eval(t, 0.0) - u0.eval(t)).length() < 1e-14);
            assert!((coons.eval(t, 1.0) - u1.eval(t)).length() < 1e-14);
            assert!((coons.eval(0.0, t) - w0.eval(t)).length() < 1e-14);
            assert!((coons.eval(1.0, t) - w1.eval(t)).length() < 1e-14);
        }
        let ruled = Patch::Ruled {
            c0: u0.clone(),
            c1: u1.clone(),
        };
        assert!((ruled.eval(0.3, 0.0) - u0.eval(0.3)).length() < 1e-15);
        assert!((ruled.eval(0.3, 1.0) - u1.eval(0.3)).length() < 1e-15);
        let bad = curve(&[[0.5, 0.0, 0.0], [0.0, 1.0, 0.0]]);
        assert!(matches!(
            Patch::coons(u0, u1, bad, w1),
            Err(PatchError::CoonsCorners(..))
        ));
        // Hermite: corners from the geometry matrix.
        let mut g = [[DVec3::ZERO; 4]; 4];
        g[0][0] = DVec3::new(0.0, 0.0, 0.0);
        g[0][1] = DVec3::new(0.0, 1.0, 0.0);
        g[1][0] = DVec3::new(1.0, 0.0, 0.0);
        g[1][1] = DVec3::new(1.0, 1.0, 0.5);
        let h = Patch::Hermite { g };
        assert_eq!(h.eval(1.0, 1.0), g[1][1]);
        assert_eq!(h.eval(0.0, 1.0), g[0][1]);
    }
}
