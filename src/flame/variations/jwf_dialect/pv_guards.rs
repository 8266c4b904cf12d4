//! JWildfire's complex trigonometric functions (cothe's `csc`, `csch`, `sec`, `sech`, `tan`,
//! `tanh`, `coth`): flam3 (and Fractorium in its compatibility mode) replaces a vanishing
//! denominator by the machine epsilon and sends the point far away; JWildfire 9.00
//! (`CscFunc`, `CschFunc`, … : `if (d == 0) return;`) leaves the point as it was, so the
//! variation adds nothing there. Elsewhere each gives the compatibility formula's value; z is
//! the framework's (0, or the weighted input z when the flame preserves z; at a pole JWildfire
//! adds no z, ugnis still does). The formulas are JWildfire's (LGPL-2.1), written anew.
//!
//! A point can land exactly on such a pole after an underflow: `julian` then `csc` near the
//! origin (cosh 2y and cos 2x both round to 1) sends a JWildfire orbit to the origin, which
//! both variations then keep (sidwellr's `complex_csc` examples).

use crate::flame::fastmath as fm;
use crate::flame::variations::*;

/// csc z = 2 (sin x cosh y − i cos x sinh y) / (cosh 2y − cos 2x).
pub(super) fn csc(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let d = fm::cosh(2.0 * t.y) - fm::cos(2.0 * t.x);
    if d == 0.0 {
        return [0.0; 3];
    }
    let (s, c) = fm::sin_cos(t.x);
    let den = 2.0 / d;
    [
        v.w * den * s * fm::cosh(t.y),
        -(v.w * den * c * fm::sinh(t.y)),
        0.0,
    ]
}

/// csch z = 2 (sinh x cos y − i cosh x sin y) / (cosh 2x − cos 2y).
pub(super) fn csch(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let d = fm::cosh(2.0 * t.x) - fm::cos(2.0 * t.y);
    if d == 0.0 {
        return [0.0; 3];
    }
    let (s, c) = fm::sin_cos(t.y);
    let den = 2.0 / d;
    [
        v.w * den * fm::sinh(t.x) * c,
        -(v.w * den * fm::cosh(t.x) * s),
        0.0,
    ]
}

/// sec z = 2 (cos x cosh y + i sin x sinh y) / (cos 2x + cosh 2y).
pub(super) fn sec(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let d = fm::cos(2.0 * t.x) + fm::cosh(2.0 * t.y);
    if d == 0.0 {
        return [0.0; 3];
    }
    let (s, c) = fm::sin_cos(t.x);
    let den = v.w * (2.0 / d);
    [den * c * fm::cosh(t.y), den * s * fm::sinh(t.y), 0.0]
}

/// sech z = 2 (cos y cosh x − i sin y sinh x) / (cos 2y + cosh 2x).
pub(super) fn sech(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let d = fm::cos(2.0 * t.y) + fm::cosh(2.0 * t.x);
    if d == 0.0 {
        return [0.0; 3];
    }
    let (s, c) = fm::sin_cos(t.y);
    let den = 2.0 / d;
    [
        v.w * den * c * fm::cosh(t.x),
        -(v.w * den * s * fm::sinh(t.x)),
        0.0,
    ]
}

/// tan z = (sin 2x + i sinh 2y) / (cos 2x + cosh 2y).
pub(super) fn tan(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (s, c) = fm::sin_cos(2.0 * t.x);
    let d = c + fm::cosh(2.0 * t.y);
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 1.0 / d;
    [v.w * den * s, v.w * den * fm::sinh(2.0 * t.y), 0.0]
}

/// tanh z = (sinh 2x + i sin 2y) / (cos 2y + cosh 2x).
pub(super) fn tanh(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (s, c) = fm::sin_cos(2.0 * t.y);
    let d = c + fm::cosh(2.0 * t.x);
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 1.0 / d;
    [v.w * den * fm::sinh(2.0 * t.x), v.w * den * s, 0.0]
}

/// coth z = (sinh 2x + i sin 2y) / (cosh 2x − cos 2y).
pub(super) fn coth(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let (s, c) = fm::sin_cos(2.0 * t.y);
    let d = fm::cosh(2.0 * t.x) - c;
    if d == 0.0 {
        return [0.0; 3];
    }
    let den = 1.0 / d;
    [v.w * den * fm::sinh(2.0 * t.x), v.w * den * s, 0.0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::variations::jwf_testing::run;

    /// The variation as a flame JWildfire wrote gets it (weight 1, default parameters).
    fn make(name: &str) -> Prepared {
        let (id, form) = parse_name(name).expect("registered");
        let rules = Rules {
            dialect: Dialect::JWildfire,
            ..Rules::default()
        };
        Prepared::for_flame(
            id,
            form,
            1.0,
            &info(id).defaults(),
            &[],
            Affine::default(),
            rules,
        )
    }

    /// JWildfire 9.00's own classes (`CscFunc` … `CothFunc`, weight 1, colour 0.5): at their
    /// poles, where the denominator rounds to 0 exactly, the point gets nothing; the values
    /// printed elsewhere are matched (csc at (1.0670477503916913, −3.7379572548006076e-10):
    /// JWildfire's orbit step of sidwellr's `complex_csc-1`).
    #[test]
    fn a_pole_adds_nothing_as_jwildfire_computes() {
        let mut rng = FastRng::new(1);
        let tiny = [1.0336191e-9, 1.8766248e-10, 0.0];
        for name in ["csc", "csch", "coth"] {
            let v = make(name);
            let o = run(&v, &[tiny], 0.5, &mut rng)[0];
            assert_eq!(o, [0.0, 0.0, 0.0, 0.5], "{name}");
        }
        let half_pi = std::f64::consts::FRAC_PI_2;
        for (name, p) in [
            ("tan", [half_pi, 0.0, 0.0]),
            ("sec", [half_pi, 0.0, 0.0]),
            ("tanh", [0.0, half_pi, 0.0]),
            ("sech", [0.0, half_pi, 0.0]),
        ] {
            let v = make(name);
            let o = run(&v, &[p], 0.5, &mut rng)[0];
            // cos π rounds to −1 and cosh 0 is 1: the denominator is 0.
            assert_eq!(o, [0.0, 0.0, 0.0, 0.5], "{name}");
        }
        let v = make("csc");
        let o = run(
            &v,
            &[[1.0670477503916913, -3.7379572548006076E-10, 0.0]],
            0.5,
            &mut rng,
        )[0];
        assert!((o[0] - 1.1418402694663168).abs() < 1e-12, "{o:?}");
        assert!((o[1] - 2.3525182414663633E-10).abs() < 1e-15, "{o:?}");
    }
}
