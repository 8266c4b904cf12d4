//! Gregg Helt's (CozyG) `klein_group`: limit sets of Kleinian groups, each call applying one
//! of two Möbius maps or their inverses, chosen at random; the generators come from the
//! recipes of Mumford, Series and Wright's "Indra's Pearls" (Grandma's special parabolic
//! commutator groups, Maskit's, Jørgensen's, Riley's, and modified forms, one after Jos Leys'
//! "A fast algorithm for limit sets of Kleinian groups with the Maskit parametrisation", §4.1).
//!
//! The formulas follow JWildfire 9.00 (`KleinGroupFunc`, LGPL-2.1), written anew; the complex
//! arithmetic follows JEP 2.4.1's `Complex` (its division after Numerical Recipes, its square
//! root and its power by polar form).

use std::f64::consts::PI;

use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("klein_group", klein_group)
    .params(&[
        p("klein_group_a_re", 2.0),
        p("klein_group_a_im", 0.0),
        p("klein_group_b_re", 2.0),
        p("klein_group_b_im", 0.0),
        p("klein_group_recipe", 0.0),
        p("klein_group_avoid_reversal", 0.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::STATEFUL)
    .prepare(klein_prepare)];

/// A complex number, with JEP's operations.
#[derive(Clone, Copy, Debug, PartialEq)]
struct C(f64, f64);

impl C {
    fn add(self, o: C) -> C {
        C(self.0 + o.0, self.1 + o.1)
    }
    fn sub(self, o: C) -> C {
        C(self.0 - o.0, self.1 - o.1)
    }
    fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.1 * o.0 + self.0 * o.1)
    }
    fn scale(self, k: f64) -> C {
        C(self.0 * k, self.1 * k)
    }
    /// Division as Numerical Recipes in C (§5.4) does it, avoiding overflow.
    fn div(self, o: C) -> C {
        let C(re, im) = self;
        if o.0.abs() >= o.1.abs() {
            let r = o.1 / o.0;
            let den = o.0 + r * o.1;
            C((re + r * im) / den, (im - r * re) / den)
        } else {
            let r = o.0 / o.1;
            let den = o.1 + r * o.0;
            C((re * r + im) / den, (im * r - re) / den)
        }
    }
    /// The principal square root (Numerical Recipes in C, §5.4).
    fn sqrt(self) -> C {
        let C(re, im) = self;
        if re == 0.0 && im == 0.0 {
            return C(0.0, 0.0);
        }
        let (ar, ai) = (re.abs(), im.abs());
        let mut w = if ar >= ai {
            let r = ai / ar;
            ar.sqrt() * (0.5 * (1.0 + (1.0 + r * r).sqrt())).sqrt()
        } else {
            let r = ar / ai;
            ai.sqrt() * (0.5 * (r + (1.0 + r * r).sqrt())).sqrt()
        };
        if re >= 0.0 {
            C(w, im / (2.0 * w))
        } else {
            if im < 0.0 {
                w = -w;
            }
            C(im / (2.0 * w), w)
        }
    }
    /// The modulus, scaled against overflow.
    fn abs(self) -> f64 {
        let (ar, ai) = (self.0.abs(), self.1.abs());
        if ar == 0.0 && ai == 0.0 {
            0.0
        } else if ar > ai {
            let t = ai / ar;
            ar * (1.0 + t * t).sqrt()
        } else {
            let t = ar / ai;
            ai * (1.0 + t * t).sqrt()
        }
    }
    /// The square, in polar form as JEP's `power(2)` computes it (exactly on the negative
    /// real and the imaginary axes).
    fn square(self) -> C {
        let s = self.abs().powi(2);
        let C(re, im) = self;
        if (im == 0.0 && re < 0.0) || (re == 0.0 && im != 0.0) {
            // 2·arg is a multiple of π: cos ±1, sin 0.
            let c = if im == 0.0 { 1.0 } else { -1.0 };
            return C(s * c, 0.0);
        }
        let a = 2.0 * im.atan2(re);
        C(s * a.cos(), s * a.sin())
    }
}

const ZERO: C = C(0.0, 0.0);
const ONE: C = C(1.0, 0.0);
const TWO: C = C(2.0, 0.0);
const I: C = C(0.0, 1.0);

/// The trace of the product of the generators from their traces (the root of
/// t² − ta·tb·t + ta² + tb² = 0 with the minus sign, as the recipes in "Indra's Pearls" take).
fn trace_ab(ta: C, tb: C) -> C {
    let b = ta.mul(tb).scale(-1.0);
    let c = ta.square().add(tb.square());
    let disc = b.square().sub(c.scale(4.0)).sqrt();
    b.scale(-1.0).sub(disc).div(TWO)
}

/// The two generators (matrices a b c d of z ↦ (az + b)/(cz + d)) of recipe `recipe`.
fn generators(recipe: f64, a: C, b: C) -> [[C; 4]; 2] {
    let maskit = |mu: C, k: C| {
        [
            [mu.scale(-1.0).mul(I), I.scale(-1.0), I.scale(-1.0), ZERO],
            [ONE, k, ZERO, ONE],
        ]
    };
    match recipe as i64 {
        1 => maskit(a, TWO),
        5 => maskit(a, b),
        6 => maskit(a, C(2.0 * (PI / b.0).cos(), b.1)),
        2 => {
            // Jørgensen's groups.
            let t = trace_ab(a, b);
            [
                [a.sub(b.div(t)), a.div(t.square()), a, b.div(t)],
                [
                    b.sub(a.div(t)),
                    b.scale(-1.0).div(t.square()),
                    b.scale(-1.0),
                    a.div(t),
                ],
            ]
        }
        3 => [[ONE, ZERO, a, ONE], [ONE, TWO, ZERO, ONE]],
        4 => [[ONE, ZERO, a, ONE], [ONE, b, ZERO, ONE]],
        _ => {
            // Grandma's special parabolic commutator groups.
            let t = trace_ab(a, b);
            let (i2, i4, four) = (C(0.0, 2.0), C(0.0, 4.0), C(4.0, 0.0));
            let z0 = t
                .sub(TWO)
                .mul(b)
                .div(b.mul(t).sub(a.mul(TWO)).add(t.mul(i2)));
            let a1 = a
                .mul(t)
                .sub(b.mul(TWO))
                .add(i4)
                .div(t.mul(TWO).add(four).mul(z0));
            let a2 = a
                .mul(t)
                .sub(b.mul(TWO))
                .sub(i4)
                .mul(z0)
                .div(t.mul(TWO).sub(four));
            [
                [a.div(TWO), a1, a2, a.div(TWO)],
                [
                    b.sub(i2).div(TWO),
                    b.div(TWO),
                    b.div(TWO),
                    b.add(i2).div(TWO),
                ],
            ]
        }
    }
}

/// Derived values: the four maps a, a⁻¹, b, b⁻¹, each as 8 numbers (a b c d, re and im).
fn klein_prepare(v: &mut Prepared) {
    let [a_re, a_im, b_re, b_im, recipe] = v.params();
    let [ga, gb] = generators(recipe.floor(), C(a_re, a_im), C(b_re, b_im));
    let inv = |m: [C; 4]| [m[3], m[1].scale(-1.0), m[2].scale(-1.0), m[0]];
    for m in [ga, inv(ga), gb, inv(gb)] {
        for c in m {
            v.p.extend_from_slice(&[c.0, c.1]);
        }
    }
}

/// State slot: the map used last (0 a, 1 a⁻¹, 2 b, 3 b⁻¹; a new object starts at a).
const ST_PREV: usize = 0;

/// klein_group: one of the four maps at random applied to the point divided by the weight
/// (with `avoid_reversal` 1, never the inverse of the map used last).
fn klein_group(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, avoid] = v.params();
    let maps = v.table(0);
    if maps.len() < 32 {
        return [0.0; 3];
    }
    let k = if avoid == 1.0 {
        let prev = (v.state.get(ST_PREV) as usize).min(3);
        // The inverse of map m is m ^ 1; the three others in their order.
        let pick = ((rng.f01() * 3.0) as usize).min(2);
        pick + usize::from(pick >= prev ^ 1)
    } else {
        ((rng.f01() * 4.0) as usize).min(3)
    };
    v.state.set(ST_PREV, k as f64);
    let m = &maps[8 * k..8 * k + 8];
    let (a, b, c, d) = (C(m[0], m[1]), C(m[2], m[3]), C(m[4], m[5]), C(m[6], m[7]));
    let z = C(t.x / v.w, t.y / v.w);
    let o = z.mul(a).add(b).div(z.mul(c).add(d));
    [v.w * o.0, v.w * o.1, 0.0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generators_have_determinant_one_and_the_asked_traces() {
        // Grandma's recipe: tr a = ta, tr b = tb, det 1 for both.
        let (ta, tb) = (C(2.0, 0.0), C(2.0, 0.0));
        let [ga, gb] = generators(0.0, ta, tb);
        for (g, tr) in [(ga, ta), (gb, tb)] {
            let det = g[0].mul(g[3]).sub(g[1].mul(g[2]));
            assert!(
                (det.0 - 1.0).abs() < 1e-12 && det.1.abs() < 1e-12,
                "{det:?}"
            );
            let trace = g[0].add(g[3]);
            assert!((trace.0 - tr.0).abs() < 1e-12 && (trace.1 - tr.1).abs() < 1e-12);
        }
        assert_eq!(C(0.0, 3.0).square(), C(-9.0, 0.0));
        let r = C(-3.0, 4.0).sqrt();
        assert!((r.0 - 1.0).abs() < 1e-15 && (r.1 - 2.0).abs() < 1e-15);
    }
}
