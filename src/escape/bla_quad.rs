//! Quadratic (bivariate, second-order) approximation of perturbed orbits of z² + c for the
//! plain-f64 loop. Where the bilinear steps of [`super::bla`] keep only the linear terms, a
//! step here keeps the terms of degree two in δ and δc as well,
//!
//! ```text
//! δ(m + l) = A·δ + B·δc + C·δ² + D·δ·δc + E·δc²,
//! ```
//!
//! so that what it drops is of degree three: its validity radius grows from about ε·|2Z|
//! (bilinear) to about √(ε·|Z|) per step. This is the higher-order approximation of the
//! perturbed orbit (Claude Heiland-Allen, "Deep zoom theory and practice (again)", 2022,
//! after Zhuoran's bilinear approximation; the coefficients compose as truncated power
//! series). One step of z² + c is δ ← 2Z·δ + δ² + δc, exactly of this form (A = 2Z, B = 1,
//! C = 1, D = E = 0), and drops nothing. Step x then step y compose into
//!
//! ```text
//! A = A_y·A_x,  B = A_y·B_x + B_y,  C = A_y·C_x + C_y·A_x²,
//! D = A_y·D_x + 2·C_y·A_x·B_x + D_y·A_x,  E = A_y·E_x + C_y·B_x² + D_y·B_x + E_y,
//! ```
//!
//! dropping C_y·(2·L·Q + Q²) + D_y·δc·Q, where x's linear part is L = A_x·δ + B_x·δc and
//! its quadratic part Q = C_x·δ² + D_x·δ·δc + E_x·δc². The radius R of a merged step bounds
//! the |δ| (with |δc| at most the view's largest offset) at which
//!
//! - x is valid (|δ| < R_x),
//! - y is valid for x's result: |A_x|·|δ| + |B_x|·|δc| + |C_x|·|δ|² + |D_x|·|δ|·|δc| +
//!   |E_x|·|δc|² < R_y,
//! - the dropped terms, bounded through the triangle inequality as a polynomial Σ t_p·|δ|^p,
//!   stay below ε times the linear terms: each of the five powers p = 0…4 gets a quarter of
//!   ε·|A|·|δ| (p ≥ 1) or of ε·|B|·|δc| (p = 0, which then admits every δ or none).
//!
//! The table has the layout of the bilinear one (level k ≥ 1 merges 2^k iterations from
//! m = 1 + j·2^k) and goes straight to f64: a step whose coefficients leave f64's range gets
//! radius 0.

use super::complex::C;
use super::fx::{Cx, Fx};

/// A merged step while the table is built.
#[derive(Clone, Copy, Debug)]
struct Step {
    a: Cx,
    b: Cx,
    c: Cx,
    d: Cx,
    e: Cx,
    /// Validity radius (unused when `exact`).
    r: Fx,
    /// A single step of the map: nothing dropped, valid for any δ.
    exact: bool,
}

/// x^p for x ≥ 0 (0 for 0).
fn pow(x: Fx, p: f64) -> Fx {
    if x.is_zero() {
        return Fx::ZERO;
    }
    let l = x.log2() * p;
    if !l.is_finite() {
        return Fx::ZERO;
    }
    let f = l.floor();
    Fx::new((l - f).exp2(), f.clamp(-1e9, 1e9) as i32)
}

fn min(x: Fx, y: Fx) -> Fx {
    if y.lt(x) { y } else { x }
}

fn merge(x: &Step, y: &Step, g: Fx, eps: f64) -> Step {
    let a = y.a.mul(x.a);
    let b = y.a.mul(x.b).add(y.b);
    let c = y.a.mul(x.c).add(y.c.mul(x.a).mul(x.a));
    let d =
        y.a.mul(x.d)
            .add(y.c.mul(x.a).mul(x.b).scale(2.0))
            .add(y.d.mul(x.a));
    let e =
        y.a.mul(x.e)
            .add(y.c.mul(x.b).mul(x.b))
            .add(y.d.mul(x.b))
            .add(y.e);
    let (ax, bx, cx, dx, ex) = (x.a.abs(), x.b.abs(), x.c.abs(), x.d.abs(), x.e.abs());
    let (cy, dy) = (y.c.abs(), y.d.abs());
    let g2 = g.mul(g);
    let g3 = g2.mul(g);
    let two = |v: Fx| v.scale(2.0);
    // The dropped terms' bound by power of |δ|.
    let t4 = cy.mul(cx).mul(cx);
    let t3 = two(cy.mul(cx).mul(ax.add(dx.mul(g))));
    let t2 = two(cy.mul(g).mul(ax.mul(dx).add(bx.mul(cx))))
        .add(cy.mul(dx.mul(dx).add(two(cx.mul(ex)))).mul(g2))
        .add(dy.mul(cx).mul(g));
    let t1 = two(cy.mul(g2).mul(ax.mul(ex).add(bx.mul(dx))))
        .add(two(cy.mul(dx).mul(ex).mul(g3)))
        .add(dy.mul(dx).mul(g2));
    let t0 = two(cy.mul(bx).mul(ex).mul(g3))
        .add(cy.mul(ex).mul(ex).mul(g2).mul(g2))
        .add(dy.mul(ex).mul(g3));
    let share = eps / 4.0;
    let linear = a.abs().scale(share);
    let fails = linear.lt(t1) || b.abs().mul(g).scale(share).lt(t0);
    let mut r = if fails {
        Fx::ZERO
    } else if x.exact {
        Fx::new(1.0, 1 << 20)
    } else {
        x.r
    };
    for (p, t) in [(1.0, t2), (0.5, t3), (1.0 / 3.0, t4)] {
        if !t.is_zero() {
            r = min(r, pow(linear.div(t), p));
        }
    }
    if !y.exact {
        // y admits x's result: (|A_x| + |D_x|·g)·|δ| + |C_x|·|δ|² < R_y − |B_x|·g − |E_x|·g²,
        // solved for |δ| as 2q / (s + √(s² + 4·|C_x|·q)).
        let q = y.r.sub(bx.mul(g)).sub(ex.mul(g2));
        if q.m > 0.0 {
            let s = ax.add(dx.mul(g));
            let root = s.mul(s).add(cx.mul(q).scale(4.0)).sqrt();
            let den = s.add(root);
            if !den.is_zero() {
                r = min(r, q.scale(2.0).div(den));
            }
        } else {
            r = Fx::ZERO;
        }
    }
    let finite = [a, b, c, d, e].iter().all(|v| v.is_finite());
    Step {
        a,
        b,
        c,
        d,
        e,
        r: if finite && r.is_finite() { r } else { Fx::ZERO },
        exact: false,
    }
}

/// The plain loop's table for orbit `z` of z² + c, pixels within `dc_max` of the reference,
/// with (`with_c`) or without a δc term: per level the radii in f64 (0 where a coefficient
/// leaves f64's range) and the coefficients (A, B) and (C, D, E).
#[allow(clippy::type_complexity)]
pub fn table(
    z: &[C],
    dc_max: Fx,
    with_c: bool,
    eps: f64,
) -> (Vec<Vec<f64>>, Vec<Vec<[C; 2]>>, Vec<Vec<[C; 3]>>) {
    let last = z.len().saturating_sub(1);
    let g = if with_c { dc_max } else { Fx::ZERO };
    let single = |m: usize| Step {
        a: Cx::from_c(z[m] * 2.0),
        b: Cx::new(if with_c { 1.0 } else { 0.0 }, 0.0, 0),
        c: Cx::new(1.0, 0.0, 0),
        d: Cx::ZERO,
        e: Cx::ZERO,
        r: Fx::ZERO,
        exact: true,
    };
    let levels = super::bla::levels(last, single, |x, y| merge(x, y, g, eps));
    let in_f64 = |c: &Cx| c.is_zero() || (-1000..1000).contains(&c.e);
    let mut radii = Vec::with_capacity(levels.len());
    let mut lin = Vec::with_capacity(levels.len());
    let mut quad = Vec::with_capacity(levels.len());
    for l in &levels {
        radii.push(
            l.iter()
                .map(|st| {
                    let ok = [st.a, st.b, st.c, st.d, st.e].iter().all(in_f64);
                    // A lone single step at the end of a level (exact) is taken as a single
                    // step by the loop itself.
                    if ok && !st.exact { st.r.to_f64() } else { 0.0 }
                })
                .collect(),
        );
        lin.push(l.iter().map(|st| [st.a.to_c(), st.b.to_c()]).collect());
        quad.push(
            l.iter()
                .map(|st| [st.c.to_c(), st.d.to_c(), st.e.to_c()])
                .collect(),
        );
    }
    (radii, lin, quad)
}
