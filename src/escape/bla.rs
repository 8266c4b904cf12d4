//! Bilinear approximation (BLA) of perturbed orbits (Zhuoran; as described by Claude
//! Heiland-Allen in "Deep zoom theory and practice (again)" and used by Fraktaler-3 and
//! Imagina). Where the non-linear terms of the perturbation are negligible, l iterations from
//! reference index m act on the difference δ as one linear map
//!
//! ```text
//! δ(m + l) = A·δ(m) + B·δc,      valid while |δ(m)| < R.
//! ```
//!
//! One step of z² + c has A = 2Z(m), B = 1 and R = ε·|A| (|δ|² is below ε·|2Zδ|); of z³ + c,
//! A = 3Z², B = 1 and R = ε·|Z| (|3Zδ²| below ε·|3Z²δ|). Two steps x then y merge into
//! A = A_y·A_x, B = A_y·B_x + B_y, R = min(R_x, max(0, (R_y − |B_x|·|δc|max) / |A_x|)), with
//! |δc|max the largest pixel offset of the view. The table holds, for each level k ≥ 1, the
//! merged steps of 2^k iterations starting at m = 1 + j·2^k; a pixel at index m takes the
//! longest one whose radius admits it. Julia sets have no δc term: B = 0.
//!
//! These steps serve the extended-exponent and derivative paths of [`super::deep`]; the
//! plain-f64 loop of z² + c takes quadratic steps instead ([`super::bla_quad`]), whose
//! radius is about √(ε·|Z|) per step rather than ε·|2Z|.

use super::complex::C;
use super::fx::{Cx, Fx};

/// The default relative size ε below which a non-linear term is dropped (by the bilinear
/// steps; by the quadratic ones of [`super::bla_quad`], the terms of degree three). f64's unit
/// round-off (2^-53) drops nothing f64 would keep, but admits few bilinear steps. On a 16×12
/// grid of a seahorse-valley view at 1e-25 (30,000 iterations, the plain loop's quadratic
/// steps) 2^-44 leaves 190 pixels within 0.05 of exact iteration, as do 2^-43, 2^-42 and
/// 1e-12; 1e-10 leaves 188 and Fractalshades' default 1e-6 178, and at 640×480 they take
/// 0.58 and 0.37 times the CPU time. (Fractalshades itself, at its default 1e-6, has 85 % of a grid of
/// that view within 0.05 of exact iteration; it reaches its unapproximated 99 % at 1e-14.)
pub const EPSILON: f64 = 1.0 / (1u64 << 44) as f64;

/// The range a user may choose ε from: f64's unit round-off to a thousandth.
pub const EPSILON_RANGE: std::ops::RangeInclusive<f64> = (1.0 / (1u64 << 53) as f64)..=1e-3;

/// A merged step.
#[derive(Clone, Copy, Debug)]
pub struct Step {
    pub a: Cx,
    pub b: Cx,
    /// Validity radius, and the same as f64 (0 below f64's range).
    pub r: Fx,
    pub r64: f64,
    /// Iterations skipped.
    pub len: u32,
}

/// The bilinear steps of one reference orbit.
#[derive(Clone, Debug, Default)]
pub struct Bla {
    /// levels[k − 1][j]: the step of up to 2^k iterations from m = 1 + j·2^k.
    levels: Vec<Vec<Step>>,
    /// The same steps in f64 for the plain loop: per level the radii (0 where A or B leave
    /// f64's range, so that no difference is admitted) apart from the coefficients, so that
    /// the test most iterations make touches 8 bytes.
    radii: Vec<Vec<f64>>,
    coeffs: Vec<Vec<[C; 2]>>,
    /// z² + c: the plain loop's steps are quadratic ([`super::bla_quad`]): `radii` are
    /// theirs, `coeffs` their A and B, and these their C, D and E (empty for other maps).
    quad: Vec<Vec<[C; 3]>>,
    /// The radius of the first level by starting index (0 at even indices, where no step
    /// starts): one load and comparison turn down the iterations that take no step.
    first: Vec<f64>,
    /// The orbit's last index (steps end there).
    last: usize,
}

fn merge(x: &Step, y: &Step, dc_max: Fx) -> Step {
    let a = y.a.mul(x.a);
    let b = y.a.mul(x.b).add(y.b);
    let ax = x.a.abs();
    let ry = y.r.sub(x.b.abs().mul(dc_max));
    let ry = if ry.m > 0.0 && !ax.is_zero() {
        ry.div(ax)
    } else {
        Fx::ZERO
    };
    let r = if ry.lt(x.r) { ry } else { x.r };
    Step {
        a,
        b,
        r,
        r64: r.to_f64(),
        len: x.len + y.len,
    }
}

/// The levels of a step table over an orbit whose last index is `last`: level 0 holds the
/// steps of two iterations from m = 1, 3, 5, … (each made by `merge` of the single steps
/// `single(m)` and `single(m + 1)`; a single step alone where m + 1 would land on the last
/// point), and each further level merges the steps of the one below in pairs (a lone last
/// step is carried up as it is), up to one step.
pub(super) fn levels<S: Copy>(
    last: usize,
    single: impl Fn(usize) -> S,
    merge: impl Fn(&S, &S) -> S,
) -> Vec<Vec<S>> {
    let mut levels = Vec::new();
    let mut prev: Vec<S> = (1..last)
        .step_by(2)
        .map(|m| {
            let x = single(m);
            if m + 1 < last {
                merge(&x, &single(m + 1))
            } else {
                x
            }
        })
        .collect();
    while prev.len() > 1 {
        let next: Vec<S> = prev
            .chunks(2)
            .filter_map(|p| match p {
                [x, y] => Some(merge(x, y)),
                [x] => Some(*x),
                _ => None,
            })
            .collect();
        levels.push(prev);
        prev = next;
    }
    if !prev.is_empty() {
        levels.push(prev);
    }
    levels
}

/// The longest step of `levels` (as [`levels`] builds them) from reference index m that
/// `admits`: a merged radius is at most the radius of its first half, which starts at the same
/// index one level down, and its length is larger, so the search climbs from the single steps
/// and stops at the first that does not admit the difference.
#[inline(always)]
pub(super) fn climb<S>(levels: &[Vec<S>], m: usize, admits: impl Fn(&S) -> bool) -> Option<&S> {
    if m == 0 {
        return None;
    }
    let k0 = (m - 1).trailing_zeros() as usize;
    let mut best = None;
    for (k, level) in levels.iter().enumerate().take(k0) {
        match level.get((m - 1) >> (k + 1)) {
            Some(st) if admits(st) => best = Some(st),
            _ => break,
        }
    }
    best
}

/// [`climb`] over the plain loop's radii (|re| + |im|, 0 where a step is not used) of an
/// orbit whose last index is `last`: the level, place and length of the longest step from
/// odd m admitting `d1` (|re| + |im| of the difference) and at most `room` iterations.
#[inline(always)]
pub(super) fn climb_plain(
    radii: &[Vec<f64>],
    last: usize,
    m: usize,
    d1: f64,
    room: u32,
) -> Option<(usize, usize, u32)> {
    let k0 = (m - 1).trailing_zeros() as usize;
    let mut found = None;
    for (k, level) in radii.iter().enumerate().take(k0) {
        let j = (m - 1) >> (k + 1);
        let admits = matches!(level.get(j), Some(&r) if d1 < r);
        let len = (2usize << k).min(last - m) as u32;
        if !admits || len > room {
            break;
        }
        found = Some((k, j, len));
    }
    found
}

/// The first level's radius at every reference index up to `last` (0 where no step starts):
/// one load turns most iterations down before the level search.
pub(super) fn first_radii(last: usize, radii: &[Vec<f64>]) -> Vec<f64> {
    let mut first = vec![0.0; last + 1];
    for (j, &r) in radii.first().into_iter().flatten().enumerate() {
        if let Some(f) = first.get_mut(1 + 2 * j) {
            *f = r;
        }
    }
    first
}

/// Bytes the table of an orbit of `len` points takes (about one merged step per point, its
/// f64 copy with the quadratic coefficients and the first level's radii by index).
pub fn table_bytes(len: u64) -> u64 {
    len * (std::mem::size_of::<Step>() + std::mem::size_of::<[C; 5]>() + 16) as u64
}

impl Bla {
    /// The table for orbit `z` of z^degree + c, pixels within `dc_max` of the reference,
    /// with (`with_c`, the Mandelbrot kind) or without a δc term, dropping non-linear terms
    /// below `eps` relative to the linear ones.
    pub fn new(z: &[C], degree: u32, dc_max: Fx, with_c: bool, eps: f64) -> Bla {
        let last = z.len().saturating_sub(1);
        if last < 3 {
            return Bla::default();
        }
        let single = |m: usize| {
            let zm = z[m];
            let (a, r) = if degree == 3 {
                (zm * zm * 3.0, Fx::from_f64(zm.abs() * eps))
            } else {
                (zm * 2.0, Fx::from_f64(zm.abs() * 2.0 * eps))
            };
            Step {
                a: Cx::from_c(a),
                b: Cx::new(if with_c { 1.0 } else { 0.0 }, 0.0, 0),
                r,
                r64: r.to_f64(),
                len: 1,
            }
        };
        // Single steps from m = 1 to last − 1 (the last lands on the final point).
        let levels = levels(last, single, |x, y| merge(x, y, dc_max));
        let in_f64 = |c: &Cx| c.is_zero() || (-1000..1000).contains(&c.e);
        let (radii, coeffs, quad) = if degree == 2 {
            super::bla_quad::table(z, dc_max, with_c, eps)
        } else {
            let radii: Vec<Vec<f64>> = levels
                .iter()
                .map(|l| {
                    l.iter()
                        .map(|st| {
                            if in_f64(&st.a) && in_f64(&st.b) {
                                st.r64
                            } else {
                                0.0
                            }
                        })
                        .collect()
                })
                .collect();
            let coeffs = levels
                .iter()
                .map(|l| l.iter().map(|st| [st.a.to_c(), st.b.to_c()]).collect())
                .collect();
            (radii, coeffs, Vec::new())
        };
        let first = first_radii(last, &radii);
        Bla {
            levels,
            first,
            radii,
            coeffs,
            quad,
            last,
        }
    }

    /// The longest step from reference index m admitting |δ| = `d` and at most `room`
    /// iterations.
    ///
    /// A merged radius is at most the radius of its first half, which starts at the same
    /// index one level down, and its length is larger: the steps from m grow shorter-lived
    /// level by level, so the search climbs from the single steps and stops at the first
    /// that does not admit δ (most iterations that take no step cost one comparison).
    #[inline]
    pub fn find(&self, m: usize, d: Fx, room: u32) -> Option<&Step> {
        climb(&self.levels, m, |st| st.len <= room && d.lt(st.r))
    }

    /// As [`Bla::find`] for a difference `d` in f64's range, measured by |re| + |im| (at most
    /// √2 times |d|: no square root, and no underflow of |d|² for the smallest differences).
    #[inline]
    pub fn find_f64(&self, m: usize, d: C, room: u32) -> Option<&Step> {
        let d = d.re.abs() + d.im.abs();
        climb(&self.levels, m, |st| d < st.r64 && st.len <= room)
    }

    /// The plain loop's step from reference index m admitting |re| + |im| = `d1` of the
    /// difference and at most `room` iterations, as its level, place and length. `m` must be
    /// odd (the steps start at m = 1 + j·2^k). For z² + c these are the quadratic steps, for
    /// z³ + c the bilinear ones of [`Bla::find_f64`].
    #[inline(always)]
    pub fn find_plain(&self, m: usize, d1: f64, room: u32) -> Option<(usize, usize, u32)> {
        climb_plain(&self.radii, self.last, m, d1, room)
    }

    /// The coefficients A and B of the plain loop's step at level k, place j (0 past the table).
    #[inline(always)]
    pub fn plain_linear(&self, k: usize, j: usize) -> [C; 2] {
        self.coeffs
            .get(k)
            .and_then(|l| l.get(j))
            .copied()
            .unwrap_or([C::ZERO; 2])
    }

    /// The radius (|re| + |im|) of the plain loop's step at level k, place j (0 past the table).
    #[cfg(test)]
    pub fn plain_radius(&self, k: usize, j: usize) -> f64 {
        self.radii
            .get(k)
            .and_then(|l| l.get(j))
            .copied()
            .unwrap_or(0.0)
    }

    /// The quadratic coefficients C, D and E of the same step (0 but for z² + c).
    #[inline(always)]
    pub fn plain_quad(&self, k: usize, j: usize) -> [C; 3] {
        self.quad
            .get(k)
            .and_then(|l| l.get(j))
            .copied()
            .unwrap_or([C::ZERO; 3])
    }

    /// The radius of the first level's step from reference index m (0 where none starts:
    /// at even m, and past the orbit), compared with |re| + |im| of the difference before
    /// [`Bla::find_plain`] is called.
    #[inline(always)]
    pub fn first_radius(&self, m: usize) -> f64 {
        self.first.get(m).copied().unwrap_or(0.0)
    }

    /// Number of steps stored.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.levels.iter().map(Vec::len).sum()
    }
}
