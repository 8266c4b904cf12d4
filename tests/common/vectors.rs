//! What the tests against other programs' variation vectors share: reading the tables
//! (tab-separated cells, numbers as C's `%.17g` prints them, `nan`/`inf` spelled out), resolving
//! a variation and its parameter list, and the three comparisons — exact values to 1e-9
//! relative, random components by their statistics, stateful variations call by call.

use std::collections::HashMap;
use std::io::Read;

use ugnis::flame::Affine;
use ugnis::flame::variations::{self, Acc, Form, VarId};

/// A table of `folder`: `NAME.tsv` from the folder the environment variable `env` names, else
/// the committed `tests/fixtures/FOLDER/NAME.tsv.gz`.
pub fn fixture(folder: &str, env: &str, name: &str) -> String {
    if let Ok(dir) = std::env::var(env) {
        let p = std::path::Path::new(&dir).join(format!("{name}.tsv"));
        return std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    }
    let p = super::fixture(folder).join(format!("{name}.tsv.gz"));
    let raw = std::fs::read(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    let mut s = String::new();
    flate2::read::GzDecoder::new(&raw[..])
        .read_to_string(&mut s)
        .unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    s
}

/// Variations selected by UGNIS_VARS (a comma-separated list, case-insensitive; all when
/// unset).
pub fn selected(name: &str) -> bool {
    match std::env::var("UGNIS_VARS") {
        Ok(list) if !list.trim().is_empty() => {
            list.split(',').any(|n| n.trim().eq_ignore_ascii_case(name))
        }
        _ => true,
    }
}

/// Every failure is printed (not only the first ones) when UGNIS_VEC_ALL is set.
pub fn print_all() -> bool {
    std::env::var_os("UGNIS_VEC_ALL").is_some()
}

/// A number of the tables (`nan`, `inf`, `-inf` included).
pub fn num(s: &str) -> f64 {
    match s.trim() {
        "nan" | "-nan" => f64::NAN,
        "inf" => f64::INFINITY,
        "-inf" => f64::NEG_INFINITY,
        t => t.parse().unwrap_or_else(|_| panic!("bad number {t:?}")),
    }
}

/// Space-separated numbers.
pub fn nums(s: &str) -> Vec<f64> {
    s.split_whitespace().map(num).collect()
}

/// A table with a header row.
pub struct Table {
    cols: HashMap<String, usize>,
    pub rows: Vec<Vec<String>>,
}

impl Table {
    pub fn parse(text: &str) -> Table {
        let mut lines = text.lines();
        let head: Vec<&str> = lines.next().expect("a header row").split('\t').collect();
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
    /// The cell of column `col` (which must exist).
    pub fn get<'a>(&self, row: &'a [String], col: &str) -> &'a str {
        &row[self.cols[col]]
    }
    /// The cell of column `col`, `None` when the table has no such column.
    pub fn opt<'a>(&self, row: &'a [String], col: &str) -> Option<&'a str> {
        self.cols.get(col).map(|&i| row[i].as_str())
    }
}

/// Equal to 1e-9 relative (or 1e-13 absolute near 0); NaN equals NaN, infinities themselves.
pub fn same(a: f64, b: f64) -> bool {
    if a.is_nan() || b.is_nan() {
        return a.is_nan() && b.is_nan();
    }
    if a.is_infinite() || b.is_infinite() {
        return a == b;
    }
    let d = (a - b).abs();
    d <= 1e-9 * a.abs().max(b.abs()) || d <= 1e-13
}

/// The main affine of the vectors (flam3's coefficient order a b c d e f).
pub const MAIN_AFFINE: [f64; 6] = [0.75, -0.25, 0.25, 1.25, -0.125, 0.375];

/// The parameters of variation `id` (named `variation` in the table) with the `name=value;…`
/// list `params` applied (`-`: the defaults). Parameters may be named with or without the
/// variation's prefix; ranges in brackets ("2[int,1,inf]") are documentation.
pub fn resolve_params(id: VarId, variation: &str, params: &str) -> Result<Vec<f64>, String> {
    let mut p = variations::param_defaults(id);
    if params == "-" {
        return Ok(p);
    }
    let base = variation
        .strip_prefix("pre_")
        .or_else(|| variation.strip_prefix("post_"))
        .unwrap_or(variation);
    for kv in params.split(';') {
        let (k, v) = kv
            .split_once('=')
            .ok_or_else(|| format!("{variation}: bad parameter '{kv}'"))?;
        // Fractorium lists auger's precomputed scale/2 among the values in use.
        if k == "auger_half_scale" {
            continue;
        }
        let v = v.split('[').next().unwrap_or(v);
        let mine = |name: &str| variations::param_of(name).filter(|(pid, _, _)| *pid == id);
        let found = mine(k)
            .or_else(|| mine(&format!("{variation}_{k}")))
            .or_else(|| mine(&format!("{base}_{k}")));
        match found {
            Some((_, _, i)) => p[i] = num(v),
            None => return Err(format!("{variation}: parameter '{k}' is unknown")),
        }
    }
    Ok(p)
}

/// The settings of one parameter set of one variation.
#[derive(Clone)]
pub struct Set {
    pub id: VarId,
    pub form: Form,
    pub params: Vec<f64>,
    pub aff: Affine,
    pub weight: f64,
    /// Fractorium's flam3-compatibility switch.
    pub compat: bool,
}

/// One parameter set of a vectors table: variation, set name, settings, row indices.
pub type SetRows = (String, String, Result<Set, String>, Vec<usize>);

/// Every parameter set of a vectors table, with its rows; `resolve` names the variation and
/// form a set runs (from the variation's name and the set's name).
pub fn sets(
    t: &Table,
    resolve: impl Fn(&str, &str) -> Result<(VarId, Form), String>,
) -> Vec<SetRows> {
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
            nums(coefs).try_into().expect("six coefficients")
        };
        let set = resolve(var, ps).and_then(|(id, form)| {
            Ok(Set {
                id,
                form,
                params: resolve_params(id, var, &params_of_set)?,
                aff: Affine::from_coefs(aff),
                weight: num(t.get(r, "weight")),
                compat: !ps.starts_with("chaotica"),
            })
        });
        out.push((var.to_string(), ps.to_string(), set, vec![i]));
    }
    out
}

/// The sets by (variation, set name).
pub fn sets_by_name(sets: Vec<SetRows>) -> HashMap<(String, String), Result<Set, String>> {
    sets.into_iter().map(|(v, p, s, _)| ((v, p), s)).collect()
}

/// The running output a row starts from: `sum_in` (`-` or absent: 0 0 0) and `color_in`
/// (`-`: 0.35).
pub fn acc_in(t: &Table, r: &[String]) -> Acc {
    let s = match t.opt(r, "sum_in") {
        None | Some("-") => vec![0.0; 3],
        Some(s) => nums(s),
    };
    let color = match t.opt(r, "color_in") {
        None | Some("-") => 0.35,
        Some(c) => num(c),
    };
    Acc {
        x: s[0],
        y: s[1],
        z: s[2],
        color,
        hide: false,
        rgb: None,
    }
}

/// Sample statistics of one component.
pub struct Stats {
    pub mean: f64,
    pub std: f64,
    pub min: f64,
    pub max: f64,
    pub q: [f64; 3],
}

pub fn stats(v: &mut [f64]) -> Stats {
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

/// A statistic of a random-stats row (`STAT_COMPONENT`; an empty cell — a statistic the
/// trimmed fixtures leave out — is NaN).
fn stat(t: &Table, r: &[String], col: &str) -> f64 {
    match t.get(r, col) {
        "" => f64::NAN,
        s => num(s),
    }
}

/// How a random-stats table leaves out non-finite outputs.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Finite {
    /// An output with a non-finite x, y or z is left out of every statistic (Fractorium's
    /// vectors).
    Whole,
    /// Each statistic skips only its own non-finite values, and an output counts as
    /// non-finite when x, y, z or the colour is (JWildfire's vectors).
    PerCoordinate,
}

/// Compare `n` outputs drawn from `draw` with the statistics of row `r` of a random-stats
/// table: the share of non-finite outputs; a constant output exactly; the mean of an output
/// taking few values; the deciles and median of any other.
pub fn compare_stats(
    t: &Table,
    r: &[String],
    finite: Finite,
    mut draw: impl FnMut() -> Acc,
) -> Result<(), String> {
    let n: usize = t.get(r, "n").parse().expect("a count");
    let mut comp: [Vec<f64>; 5] = Default::default();
    let mut nonfinite = 0usize;
    for _ in 0..n {
        let o = draw();
        let values = [o.x, o.y, o.z, o.x.hypot(o.y), o.color];
        let whole = o.x.is_finite() && o.y.is_finite() && o.z.is_finite();
        match finite {
            Finite::Whole if !whole => nonfinite += 1,
            Finite::Whole => {
                for (c, v) in comp.iter_mut().zip(values) {
                    c.push(v);
                }
            }
            Finite::PerCoordinate => {
                nonfinite += usize::from(!(whole && o.color.is_finite()));
                for (c, v) in comp.iter_mut().zip(values) {
                    if v.is_finite() {
                        c.push(v);
                    }
                }
            }
        }
    }
    let their_nonfinite: f64 = num(t.get(r, "n_nonfinite"));
    let nf = nonfinite as f64;
    if (nf - their_nonfinite).abs()
        > 6.0 * (their_nonfinite.max(nf) + 1.0).sqrt() + 0.002 * n as f64
    {
        return Err(format!(
            "{nonfinite} non-finite outputs of {n}, want {their_nonfinite}"
        ));
    }
    let their_distinct: f64 = num(t.get(r, "n_distinct"));
    let discrete = their_distinct <= 64.0;
    let mut bad = Vec::new();
    for (k, name) in ["x", "y", "z", "r", "color"].iter().enumerate() {
        // Too few finite values to compare.
        if comp[k].len() < 100 {
            continue;
        }
        let s = stats(&mut comp[k]);
        let g = |c: &str| stat(t, r, &format!("{c}_{name}"));
        let (mean, std) = (g("mean"), g("std"));
        let want_q = [g("p10"), g("p50"), g("p90")];
        let wrong = if their_distinct == 1.0 {
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
        if wrong {
            bad.push(format!(
                "{name}: mean {:.6e} std {:.3e} min {:.6e} max {:.6e} p10/50/90 {:.6e} {:.6e} \
                 {:.6e}; want mean {mean:.6e} std {std:.3e} min {:.6e} max {:.6e} p10/50/90 \
                 {:.6e} {:.6e} {:.6e}",
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
    if bad.is_empty() {
        Ok(())
    } else {
        Err(bad.join("; "))
    }
}

/// Compare six successive outputs of `call` with the `call1` … `call6` cells ("x y z color")
/// of row `r` of a state-sequences table.
pub fn compare_sequence(
    t: &Table,
    r: &[String],
    mut call: impl FnMut() -> Acc,
) -> Result<(), String> {
    for k in 1..=6 {
        let want = nums(t.get(r, &format!("call{k}")));
        let o = call();
        let got = [o.x, o.y, o.z, o.color];
        if !(0..4).all(|i| same(got[i], want[i])) {
            return Err(format!("call {k}: {got:?}, want {want:?}"));
        }
    }
    Ok(())
}
