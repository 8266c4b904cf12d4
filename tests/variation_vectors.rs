//! Every variation against numeric vectors computed by running Fractorium's renderer
//! (github.com/typpos/fractorium, commit 2ba3764; one point through one variation at a time):
//! for each variation, its default and two other parameter sets, 24 input points, the exact
//! output. Deterministic outputs must agree to 1e-9 relative; random components are compared
//! statistically (20 000 calls per row); stateful variations call by call.
//!
//! The fixtures are trimmed copies of those vectors (tests/fixtures/variations/*.tsv.gz). To
//! check against the full files instead, set UGNIS_VECTORS_DIR to their folder; to check only
//! some variations, set UGNIS_VARS=name,name,… (case-insensitive).

mod common;

use common::vectors::{
    Finite, Set, Table, acc_in, compare_sequence, compare_stats, num, print_all, same, selected,
    sets, sets_by_name,
};
use ugnis::flame::rng::FastRng;
use ugnis::flame::variations::{self, Acc, Form, Prepared, VarId};

/// A table of the vectors: from UGNIS_VECTORS_DIR, else the committed fixture.
fn fixture(name: &str) -> String {
    common::vectors::fixture("variations", "UGNIS_VECTORS_DIR", name)
}

/// The variation a name denotes (post_-only variations are named with their prefix).
fn resolve(variation: &str, _set: &str) -> Result<(VarId, Form), String> {
    match variations::parse_name(variation) {
        Some((id, form @ (Form::Regular | Form::Post))) => Ok((id, form)),
        _ => Err(format!("variation '{variation}' is not in the registry")),
    }
}

fn prepared(s: &Set) -> Prepared {
    let mut v = Prepared::new(s.id, s.form, s.weight, &s.params, s.aff, s.compat);
    // The vectors are Fractorium's: where programs differ, its formulas.
    v.dialect = variations::Dialect::Fractorium;
    v
}

/// The variation's input point of a row.
fn t_in(t: &Table, r: &[String]) -> [f64; 3] {
    [
        num(t.get(r, "t_x")),
        num(t.get(r, "t_y")),
        num(t.get(r, "t_z")),
    ]
}

#[test]
fn deterministic_outputs_match_fractorium() {
    let t = Table::parse(&fixture("vectors"));
    let mut failures: Vec<String> = Vec::new();
    let mut checked = 0usize;
    let mut failed_vars: Vec<String> = Vec::new();
    for (var, ps, set, rows) in sets(&t, resolve) {
        if !selected(&var) {
            continue;
        }
        let set = match set {
            Ok(s) => s,
            Err(e) => {
                if !failed_vars.contains(&var) {
                    failures.push(e);
                    failed_vars.push(var.clone());
                }
                continue;
            }
        };
        for &i in &rows {
            let r = &t.rows[i];
            let tx = t_in(&t, r);
            let v = prepared(&set);
            let mut rng = FastRng::new(i as u64);
            let got = variations::eval_prepared(&v, tx, acc_in(&t, r), true, &mut rng);
            let want = [
                t.get(r, "out_x"),
                t.get(r, "out_y"),
                t.get(r, "out_z"),
                t.get(r, "color_out"),
            ];
            let got = [got.x, got.y, got.z, got.color];
            for k in 0..4 {
                if want[k].is_empty() {
                    continue; // a random component: see the statistical test
                }
                checked += 1;
                if !same(got[k], num(want[k])) {
                    failures.push(format!(
                        "{var} [{ps}] point {}: {} = {:e}, want {} (t = {tx:?})",
                        t.get(r, "point"),
                        ["x", "y", "z", "color"][k],
                        got[k],
                        want[k],
                    ));
                }
            }
        }
    }
    let n = failures.len();
    if print_all() {
        eprintln!("{}", failures.join("\n"));
    }
    failures.truncate(60);
    assert!(
        n == 0,
        "{n} mismatches of {checked} values:\n{}",
        failures.join("\n")
    );
    assert!(checked > 0, "no vector selected");
}

#[test]
fn random_outputs_match_fractorium_statistically() {
    let by_set = sets_by_name(sets(&Table::parse(&fixture("vectors")), resolve));
    let t = Table::parse(&fixture("random_stats"));
    let mut failures: Vec<String> = Vec::new();
    let mut checked = 0usize;
    for (i, r) in t.rows.iter().enumerate() {
        let (var, ps) = (t.get(r, "variation"), t.get(r, "param_set"));
        if !selected(var) {
            continue;
        }
        let Some(Ok(set)) = by_set.get(&(var.to_string(), ps.to_string())) else {
            if !failures.iter().any(|f| f.starts_with(&format!("{var}:"))) {
                failures.push(format!("{var}: not in the registry"));
            }
            continue;
        };
        let (tx, acc) = (t_in(&t, r), acc_in(&t, r));
        let v = prepared(set);
        let mut rng = FastRng::new(1000 + i as u64);
        checked += 1;
        let draw = || variations::eval_prepared(&v, tx, acc, false, &mut rng);
        if let Err(e) = compare_stats(&t, r, Finite::Whole, draw) {
            failures.push(format!("{var} [{ps}] point {}: {e}", t.get(r, "point")));
        }
    }
    let nf = failures.len();
    if print_all() {
        eprintln!("{}", failures.join("\n"));
    }
    failures.truncate(60);
    assert!(
        nf == 0,
        "{nf} statistical mismatches of {checked} rows:\n{}",
        failures.join("\n")
    );
}

#[test]
fn stateful_variations_follow_their_sequences() {
    let by_set = sets_by_name(sets(&Table::parse(&fixture("vectors")), resolve));
    let t = Table::parse(&fixture("state_sequences"));
    let mut failures: Vec<String> = Vec::new();
    for r in &t.rows {
        let (var, ps) = (t.get(r, "variation"), t.get(r, "param_set"));
        if !selected(var) {
            continue;
        }
        let Some(Ok(set)) = by_set.get(&(var.to_string(), ps.to_string())) else {
            failures.push(format!("{var}: not in the registry"));
            continue;
        };
        // hexaplay3D's first walk (six nodes or three) comes from Fractorium's global
        // generator, not from the inputs: either start is right (state slot 0 says which).
        let starts: &[Option<f64>] = if var == "hexaplay3D" {
            &[None, Some(0.0)]
        } else {
            &[None]
        };
        let mut errs = Vec::new();
        for start in starts {
            let v = prepared(set);
            if let Some(s0) = start {
                v.state.set(0, *s0);
            }
            let tx = t_in(&t, r);
            let mut rng = FastRng::new(7);
            let acc = Acc {
                color: 0.35,
                ..Acc::default()
            };
            match compare_sequence(&t, r, || {
                variations::eval_prepared(&v, tx, acc, false, &mut rng)
            }) {
                Ok(()) => {
                    errs.clear();
                    break;
                }
                Err(e) => errs.push(format!("{var} [{ps}] point {}: {e}", t.get(r, "point"))),
            }
        }
        failures.extend(errs.into_iter().take(1));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
