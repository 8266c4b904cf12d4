//! Helpers of the tests that compare the JWildfire variations with numbers printed by
//! JWildfire's own code (run outside the project, its random draws replayed from the same
//! `FastRng` stream), and the checks every JWildfire variation passes.

use crate::flame::affine::Affine;
use crate::flame::rng::FastRng;
use crate::flame::variations::{
    Acc, Form, Prepared, VarId, all, by_name, eval_prepared, flag, info, param_of, parse_name,
};

pub(super) const PTS: [[f64; 3]; 6] = [
    [0.3, -0.7, 0.2],
    [-1.2, 0.4, -0.5],
    [0.05, 0.9, 1.1],
    [2.5, -1.5, 0.3],
    [-0.4, -0.3, -0.8],
    [0.7, 0.1, -0.25],
];

/// The stream JWildfire's draws were replayed from.
pub(super) const SEED: u64 = 12345;

pub(super) fn make(name: &str, params: &[(&str, f64)], w: f64) -> Prepared {
    // A name `parse_name` does not know is looked up in the registry as a post-only form.
    let (id, form) = parse_name(name)
        .or_else(|| {
            let i = all().iter().position(|d| d.name == name)?;
            Some((i as VarId, Form::Post))
        })
        .unwrap_or_else(|| panic!("{name} not registered"));
    let mut vals = info(id).defaults();
    for (k, val) in params {
        let (pid, _, idx) = param_of(k).unwrap_or_else(|| panic!("{k} unknown"));
        assert_eq!(pid, id, "{k}");
        vals[idx] = *val;
    }
    Prepared::new(id, form, w, &vals, Affine::default(), true)
}

pub(super) fn run(v: &Prepared, pts: &[[f64; 3]], color: f64, rng: &mut FastRng) -> Vec<[f64; 4]> {
    pts.iter()
        .map(|p| {
            let acc = Acc {
                x: 0.0,
                y: 0.0,
                z: 0.0,
                color,
                hide: false,
                rgb: None,
            };
            let a = eval_prepared(v, *p, acc, true, rng);
            [a.x, a.y, a.z, a.color]
        })
        .collect()
}

pub(super) fn matches_jwildfire(a: f64, b: f64) -> bool {
    if a.is_nan() || b.is_nan() {
        return a.is_nan() && b.is_nan();
    }
    a == b || (a - b).abs() <= 1e-9 * a.abs().max(b.abs()) || (a - b).abs() <= 1e-14
}

pub(super) fn check(tag: &str, got: &[[f64; 4]], want: &[[f64; 4]]) {
    assert_eq!(got.len(), want.len(), "{tag}");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        for k in 0..4 {
            assert!(
                matches_jwildfire(g[k], w[k]),
                "{tag} row {i} comp {k}: got {g:?} want {w:?}"
            );
        }
    }
}

/// Runs `cases` (name, params, weight, colour, points, expected) on one random stream.
#[allow(clippy::type_complexity)]
pub(super) fn run_cases(
    rng: &mut FastRng,
    cases: &[(&str, &[(&str, f64)], f64, f64, &[[f64; 3]], &[[f64; 4]])],
) {
    for (i, (name, params, w, color, pts, want)) in cases.iter().enumerate() {
        let v = make(name, params, *w);
        let got = run(&v, pts, *color, rng);
        check(&format!("{name} case {i}"), &got, want);
    }
}

pub(super) fn close(a: f64, b: f64) -> bool {
    if a.is_nan() || b.is_nan() {
        return a.is_nan() && b.is_nan();
    }
    let d = (a - b).abs();
    d <= 1e-9 * a.abs().max(b.abs()) || d <= 1e-12
}

pub(super) fn assert_all_close(what: &str, got: &[f64], want: &[f64]) {
    assert_eq!(got.len(), want.len(), "{what}: length");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(close(*g, *w), "{what}[{i}]: got {g}, want {w}");
    }
}

pub(super) fn prep(name: &str, params: &[f64]) -> Prepared {
    prep_w(name, params, 1.0)
}

pub(super) fn prep_w(name: &str, params: &[f64], w: f64) -> Prepared {
    let id = by_name(name).unwrap_or_else(|| panic!("{name} not registered"));
    Prepared::new(id, Form::Regular, w, params, Affine::default(), true)
}

/// Every JWildfire variation's name and parameters resolve to it (a post-only one by its
/// `post_` name), and its defaults give a finite output at an ordinary point.
#[test]
fn names_and_parameters_resolve() {
    for d in all().iter().filter(|d| d.has(flag::JWILDFIRE)) {
        let (id, form) = parse_name(d.name)
            .or_else(|| {
                Some((
                    all().iter().position(|e| e.name == d.name)? as VarId,
                    Form::Post,
                ))
            })
            .unwrap();
        assert_eq!(info(id).name, d.name);
        if d.has(flag::POST_ONLY) {
            assert_eq!(form, Form::Post);
        } else {
            assert_eq!(by_name(d.name), Some(id), "{}", d.name);
        }
        for (k, p) in d.params.iter().enumerate() {
            assert!(p.name.starts_with(d.name), "{}", p.name);
            let (pid, pform, pk) = param_of(p.name).unwrap();
            assert_eq!((pid, pk), (id, k), "{}", p.name);
            assert_eq!(pform, form, "{}", p.name);
        }
        // Defaults give finite output at an ordinary point.
        let v = make(d.name, &[], 1.0);
        let mut rng = FastRng::new(SEED);
        let a = eval_prepared(&v, [0.3, -0.2, 0.1], Acc::default(), true, &mut rng);
        assert!(
            a.x.is_finite() && a.y.is_finite() && a.z.is_finite(),
            "{} {a:?}",
            d.name
        );
    }
}
