//! Every variation against numeric vectors computed by running Fractorium's renderer
//! (github.com/typpos/fractorium, commit 2ba3764; one point through one variation at a time):
//! for each variation, its default and two other parameter sets, 24 input points, the exact
//! output. Deterministic outputs must agree to 1e-9 relative; random components are compared
//! statistically (20 000 calls per row); stateful variations call by call.
//!
//! The fixtures are trimmed copies of those vectors (tests/fixtures/variations/*.tsv.gz). To
//! check against the full files instead, set UGNIS_VECTORS_DIR to their folder; to check only
//! some variations, set UGNIS_VARS=name,name,… (case-insensitive).

use std::collections::HashMap;
use std::io::Read;

use ugnis::flame::Affine;
use ugnis::flame::rng::FastRng;
use ugnis::flame::variations::{self, Acc, Form, Prepared, VarId};

/// Read a fixture: `NAME.tsv` from UGNIS_VECTORS_DIR, else the committed `NAME.tsv.gz`.
fn fixture(name: &str) -> String {
    if let Ok(dir) = std::env::var("UGNIS_VECTORS_DIR") {
        let p = std::path::Path::new(&dir).join(format!("{name}.tsv"));
        return std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    }
    let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/variations")
        .join(format!("{name}.tsv.gz"));
    let raw = std::fs::read(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    let mut s = String::new();
    flate2::read::GzDecoder::new(&raw[..])
        .read_to_string(&mut s)
        .unwrap();
    s
}

/// Variations selected by UGNIS_VARS (all when unset).
fn selected(name: &str) -> bool {
    match std::env::var("UGNIS_VARS") {
        Ok(list) if !list.trim().is_empty() => {
            list.split(',').any(|n| n.trim().eq_ignore_ascii_case(name))
        }
        _ => true,
    }
}

fn num(s: &str) -> f64 {
    match s.trim() {
        "nan" | "-nan" => f64::NAN,
        "inf" => f64::INFINITY,
        "-inf" => f64::NEG_INFINITY,
        t => t.parse().unwrap_or_else(|_| panic!("bad number {t:?}")),
    }
}

fn nums(s: &str) -> Vec<f64> {
    s.split_whitespace().map(num).collect()
}

/// A table with a header row: rows as maps from column name to cell.
struct Table {
    cols: HashMap<String, usize>,
    rows: Vec<Vec<String>>,
}

impl Table {
    fn parse(text: &str) -> Table {
        let mut lines = text.lines();
        let head: Vec<&str> = lines.next().unwrap().split('\t').collect();
        let cols = head
            .iter()
            .enumerate()
            .map(|(i, h)| (h.to_string(), i))
            .collect();
        let rows = lines
            .filter(|l| !l.is_empty())
            .map(|l| l.split('\t').map(str::to_string).collect())
            .collect();
        Table { cols, rows }
    }
    fn get<'a>(&self, row: &'a [String], col: &str) -> &'a str {
        &row[self.cols[col]]
    }
}

/// The settings of one parameter set of one variation.
#[derive(Clone)]
struct Set {
    id: VarId,
    params: Vec<f64>,
    aff: Affine,
    weight: f64,
    compat: bool,
}

const MAIN_AFFINE: [f64; 6] = [0.75, -0.25, 0.25, 1.25, -0.125, 0.375];

/// Resolve a variation name and its `name=value;…` parameter list.
fn resolve(variation: &str, params: &str) -> Result<(VarId, Vec<f64>), String> {
    let id = match variations::parse_name(variation) {
        Some((id, Form::Regular)) => id,
        // post_-only variations are named with their prefix.
        Some((id, Form::Post)) => id,
        _ => return Err(format!("variation '{variation}' is not in the registry")),
    };
    let mut p = variations::info(id).defaults();
    if params != "-" {
        for kv in params.split(';') {
            let (k, v) = kv.split_once('=').unwrap();
            // Fractorium lists auger's precomputed scale/2 among the values in use.
            if k == "auger_half_scale" {
                continue;
            }
            // Ranges in brackets ("2[int,1,inf]") are documentation.
            let v = v.split('[').next().unwrap();
            // JWildfire's vectors name parameters without the variation's prefix that its
            // flame files (and ugnis) put in front of them.
            let found = variations::param_of(k)
                .filter(|(pid, _, _)| *pid == id)
                .or_else(|| variations::param_of(&format!("{variation}_{k}")))
                .filter(|(pid, _, _)| *pid == id);
            match found {
                Some((_, _, i)) => p[i] = num(v),
                _ => return Err(format!("{variation}: parameter '{k}' is unknown")),
            }
        }
    }
    Ok((id, p))
}

fn same(a: f64, b: f64) -> bool {
    if a.is_nan() || b.is_nan() {
        return a.is_nan() && b.is_nan();
    }
    if a.is_infinite() || b.is_infinite() {
        return a == b;
    }
    let d = (a - b).abs();
    d <= 1e-9 * a.abs().max(b.abs()) || d <= 1e-13
}

/// One parameter set of the vectors file: variation, set name, settings, row indices.
type SetRows = (String, String, Result<Set, String>, Vec<usize>);

/// Every set of the vectors file, with its rows.
fn sets(t: &Table) -> Vec<SetRows> {
    let mut out: Vec<SetRows> = Vec::new();
    let mut params_of_set = String::new();
    for (i, r) in t.rows.iter().enumerate() {
        let (var, ps) = (t.get(r, "variation"), t.get(r, "param_set"));
        let params = t.get(r, "params");
        if params != "\"" {
            params_of_set = params.to_string();
        }
        if let Some(last) = out.last_mut()
            && last.0 == var
            && last.1 == ps
        {
            last.3.push(i);
            continue;
        }
        let coefs = t.get(r, "coefs");
        let aff = if coefs == "-" {
            MAIN_AFFINE
        } else {
            nums(coefs).try_into().unwrap()
        };
        let set = resolve(var, &params_of_set).map(|(id, params)| Set {
            id,
            params,
            aff: Affine::from_coefs(aff),
            weight: num(t.get(r, "weight")),
            compat: !ps.starts_with("chaotica"),
        });
        out.push((var.to_string(), ps.to_string(), set, vec![i]));
    }
    out
}

fn prepared(s: &Set) -> Prepared {
    let form = if variations::info(s.id).has(variations::flag::POST_ONLY) {
        Form::Post
    } else {
        Form::Regular
    };
    let mut v = Prepared::new(s.id, form, s.weight, &s.params, s.aff, s.compat);
    // The vectors are Fractorium's: where programs differ, its formulas.
    v.dialect = variations::Dialect::Fractorium;
    v
}

fn input(t: &Table, r: &[String]) -> ([f64; 3], Acc) {
    let tx = [
        num(t.get(r, "t_x")),
        num(t.get(r, "t_y")),
        num(t.get(r, "t_z")),
    ];
    let sum = t.get(r, "sum_in");
    let s = if sum == "-" { vec![0.0; 3] } else { nums(sum) };
    let acc = Acc {
        x: s[0],
        y: s[1],
        z: s[2],
        color: num(t.get(r, "color_in")),
        hide: false,
    };
    (tx, acc)
}

#[test]
fn deterministic_outputs_match_fractorium() {
    let t = Table::parse(&fixture("vectors"));
    let mut failures: Vec<String> = Vec::new();
    let mut checked = 0usize;
    let mut failed_vars: Vec<String> = Vec::new();
    for (var, ps, set, rows) in sets(&t) {
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
            let (tx, acc) = input(&t, r);
            let v = prepared(&set);
            let mut rng = FastRng::new(i as u64);
            let got = variations::eval_prepared(&v, tx, acc, true, &mut rng);
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
    if std::env::var_os("UGNIS_VEC_ALL").is_some() {
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

/// Sample statistics of one component.
struct Stats {
    mean: f64,
    std: f64,
    min: f64,
    max: f64,
    q: [f64; 3],
}

fn stats(v: &mut [f64]) -> Stats {
    v.sort_by(f64::total_cmp);
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / n;
    let q = |p: f64| v[((p * (n - 1.0)).round() as usize).min(v.len() - 1)];
    Stats {
        mean,
        std: var.sqrt(),
        min: v[0],
        max: v[v.len() - 1],
        q: [q(0.1), q(0.5), q(0.9)],
    }
}

#[test]
fn random_outputs_match_fractorium_statistically() {
    let vt = Table::parse(&fixture("vectors"));
    let by_set: HashMap<(String, String), Result<Set, String>> = sets(&vt)
        .into_iter()
        .map(|(v, p, s, _)| ((v, p), s))
        .collect();
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
        let (tx, acc) = input(&t, r);
        let v = prepared(set);
        let n: usize = t.get(r, "n").parse().unwrap();
        let mut rng = FastRng::new(1000 + i as u64);
        let mut comp: [Vec<f64>; 5] = Default::default();
        let mut nonfinite = 0usize;
        let mut distinct = std::collections::HashSet::new();
        for _ in 0..n {
            let o = variations::eval_prepared(&v, tx, acc, false, &mut rng);
            if !(o.x.is_finite() && o.y.is_finite() && o.z.is_finite()) {
                nonfinite += 1;
                continue;
            }
            if distinct.len() <= 1000 {
                distinct.insert((o.x.to_bits(), o.y.to_bits(), o.z.to_bits()));
            }
            comp[0].push(o.x);
            comp[1].push(o.y);
            comp[2].push(o.z);
            comp[3].push(o.x.hypot(o.y));
            comp[4].push(o.color);
        }
        checked += 1;
        let their_nonfinite: f64 = num(t.get(r, "n_nonfinite"));
        let nf = nonfinite as f64;
        if (nf - their_nonfinite).abs()
            > 6.0 * (their_nonfinite.max(nf) + 1.0).sqrt() + 0.002 * n as f64
        {
            failures.push(format!(
                "{var} [{ps}] point {}: {nonfinite} non-finite outputs of {n}, want {their_nonfinite}",
                t.get(r, "point")
            ));
            continue;
        }
        if comp[0].len() < 100 {
            continue;
        }
        let their_distinct: f64 = num(t.get(r, "n_distinct"));
        let discrete = their_distinct <= 64.0;
        for (k, name) in ["x", "y", "z", "r", "color"].iter().enumerate() {
            let s = stats(&mut comp[k]);
            let g = |c: &str| num(t.get(r, &format!("{c}_{name}")));
            let (mean, std) = (g("mean"), g("std"));
            let want_q = [g("p10"), g("p50"), g("p90")];
            let bad = if their_distinct == 1.0 {
                // Always the same value.
                !(same(s.min, g("min")) && same(s.max, g("max")))
            } else if discrete {
                // A few values (or rare events): the means agree. Extremes are not compared:
                // unbounded integer offsets and rare outliers reach farther in one sample than
                // in another.
                let se = 6.0 * ((std * std + s.std * s.std) / n as f64).sqrt();
                (s.mean - mean).abs() > se + 1e-9 * mean.abs() + 1e-12
            } else {
                // Distribution-free: the share of our samples below each of their quantiles
                // (an atom at the quantile may fall on either side).
                let v = &comp[k];
                let m = v.len() as f64;
                [0.1, 0.5, 0.9].iter().zip(want_q).any(|(&p, q)| {
                    let below = v.partition_point(|&x| x < q - 1e-9 * q.abs()) as f64 / m;
                    let upto = v.partition_point(|&x| x <= q + 1e-9 * q.abs()) as f64 / m;
                    let tol = 8.0 * (p * (1.0 - p) / m).sqrt() + 0.005;
                    below > p + tol || upto < p - tol
                })
            };
            if bad {
                failures.push(format!(
                    "{var} [{ps}] point {} {name}: mean {:.6e} std {:.3e} min {:.6e} max {:.6e} \
                     p10/50/90 {:.6e} {:.6e} {:.6e}; want mean {mean:.6e} std {std:.3e} \
                     min {:.6e} max {:.6e} p10/50/90 {:.6e} {:.6e} {:.6e}",
                    t.get(r, "point"),
                    s.mean,
                    s.std,
                    s.min,
                    s.max,
                    s.q[0],
                    s.q[1],
                    s.q[2],
                    g("min"),
                    g("max"),
                    want_q[0],
                    want_q[1],
                    want_q[2],
                ));
            }
        }
    }
    let nf = failures.len();
    if std::env::var_os("UGNIS_VEC_ALL").is_some() {
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
    let vt = Table::parse(&fixture("vectors"));
    let by_set: HashMap<(String, String), Result<Set, String>> = sets(&vt)
        .into_iter()
        .map(|(v, p, s, _)| ((v, p), s))
        .collect();
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
            match sequence(set, &t, r, *start) {
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

/// Six successive calls of one prepared variation on one input, against the recorded outputs.
fn sequence(set: &Set, t: &Table, r: &[String], start: Option<f64>) -> Result<(), String> {
    let tx = [
        num(t.get(r, "t_x")),
        num(t.get(r, "t_y")),
        num(t.get(r, "t_z")),
    ];
    let v = prepared(set);
    if let Some(s0) = start {
        v.state.set(0, s0);
    }
    let mut rng = FastRng::new(7);
    for call in 1..=6 {
        let want = nums(t.get(r, &format!("call{call}")));
        let acc = Acc {
            color: 0.35,
            ..Acc::default()
        };
        let o = variations::eval_prepared(&v, tx, acc, false, &mut rng);
        let got = [o.x, o.y, o.z, o.color];
        if !(0..4).all(|k| same(got[k], want[k])) {
            return Err(format!("call {call}: {got:?}, want {want:?}"));
        }
    }
    Ok(())
}
