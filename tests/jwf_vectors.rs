//! Every JWildfire variation against numeric vectors computed by running JWildfire's own classes
//! (github.com/thargor6/JWildfire, release 9.00; one point through one variation at a time):
//! for each of its 884 variations, its default and two other parameter sets (a second affine
//! map, a negative weight, a running sum where they matter), 24 input points, the exact output,
//! direct colour and hidden points; random components as statistics of 20 000 calls,
//! stateful variations call by call. Each variation runs as ugnis runs it in a flame JWildfire
//! wrote: JWildfire's own formulas, in the phase JWildfire runs it (priority -1: before the
//! regular variations, on the affine point; 1: after them, on their sum; ±2: both).
//!
//! The fixtures are trimmed copies of those vectors (tests/fixtures/jwildfire/, see its
//! make_fixtures.py). To check against the full files instead, set UGNIS_JWF_VECTORS_DIR to
//! their folder; to check only some variations, UGNIS_VARS=name,name,…; UGNIS_VEC_ALL=1 prints
//! every mismatch.

mod common;

use std::collections::{BTreeMap, HashMap};

use common::vectors::{
    Finite, Set, SetRows, Table, acc_in, compare_sequence, compare_stats, num, nums, print_all,
    same, selected, sets,
};
use ugnis::flame::rng::FastRng;
use ugnis::flame::variations::{self, Acc, Dialect, Form, Prepared, Rules, VarId};

/// The JWildfire variations that do not match their vectors yet, each with why. The test fails
/// when one of them passes (take it off the list) and when a variation off the list fails.
/// Sorted, one name per line.
const NOT_YET: &[(&str, &str)] = &[
    (
        "arcsech2",
        "x, y differ at the points (0, 0), (0, 1) or (-1, 0)",
    ),
    (
        "arctanh",
        "x differs at the points (0, 0), (0, 1) or (-1, 0)",
    ),
    (
        "asteria",
        "weight2 points 11, 13, 15 are random in JWildfire (a draw above 0.35 keeps the point) but recorded as exact: every seed the vectors tried drew above 0.35",
    ),
    ("blade3D", "statistics differ"),
    ("brush_stroke_wf", "not implemented"),
    (
        "bubbleT3D",
        "the vectors record angle_of_hole as JWildfire's init rewrote it (the hole's half angle in radians), not as it was set",
    ),
    ("cactusGlobe", "not implemented"),
    (
        "capsule3D",
        "statistics differ (alt2, where the capsule fills the cube's corner)",
    ),
    ("cell3D", "not implemented"),
    (
        "chaosCubes",
        "x, y, z differ in alt2 (scales above 1 and twists amplify JWildfire's table-based sin and cos)",
    ),
    (
        "circlecrop",
        "z differs; hide flag differs; statistics differ",
    ),
    ("colordomain", "not implemented"),
    ("colormap_wf", "not implemented"),
    (
        "complex",
        "x, y differ at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "coth2_bs",
        "x, y differ at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    ("curliecue", "not implemented"),
    ("custom_wf", "not implemented"),
    ("custom_wf_full", "not implemented"),
    ("cut_shapes", "not implemented"),
    (
        "d_spherical",
        "x, y differ at the origin; statistics differ",
    ),
    ("dc_carpet", "statistics differ"),
    ("dc_code", "not implemented"),
    (
        "dc_dmodulus",
        "statistics differ at one point (its colour is a slowly mixing chain: the quantiles of \
         20000 correlated draws vary more than the tolerance allows)",
    ),
    (
        "dc_fingerprint",
        "colour differs (a chain of 50 sine hashes amplifies the last bits of JWildfire's \
         table-based sin)",
    ),
    ("dc_randomoctree", "not implemented"),
    ("dc_triTile", "not implemented"),
    ("dc_triangle", "x, y, z, color differ; statistics differ"),
    ("dc_triantess", "not implemented"),
    ("displacemap_wf", "not implemented"),
    ("dla3d_wf", "x, y, z, color differ; call sequence differs"),
    ("dla_wf", "not implemented"),
    ("ducks", "not implemented"),
    (
        "eCollide",
        "y differs at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "eMod",
        "y differs at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "eMotion",
        "x, y differ at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "ePush",
        "x, y differ at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "eRotate",
        "y differs at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "eScale",
        "y differs at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "eSwirl",
        "x, y differ at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "edisc",
        "y differs at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "elliptic",
        "statistics differ at the near-zero point 17 (JWildfire's table-based maths: the mean radius, or its last digits)",
    ),
    (
        "elliptic2",
        "statistics differ at the near-zero point 17 (JWildfire's table-based maths: the mean radius, or its last digits)",
    ),
    ("f_complex", "not implemented"),
    ("flame_bulb", "not implemented"),
    ("fract_formula_julia_wf", "not implemented"),
    ("fract_formula_mand_wf", "not implemented"),
    (
        "fract_mandelbrot_wf",
        "statistics differ in buddhabrot mode",
    ),
    ("fract_meteors_wf", "statistics differ in buddhabrot mode"),
    ("glsl_circuits", "not implemented"),
    ("glsl_code", "not implemented"),
    ("glsl_mandala", "statistics differ (alt)"),
    ("glsl_randomoctree", "not implemented"),
    (
        "glynnSim1",
        "statistics differ: the registry's parameter ranges (Fractorium's: pow clamped to [0, 1]) clamp JWildfire's pow 1.5",
    ),
    ("glynns3subfl", "not implemented"),
    ("gpattern", "not implemented"),
    ("grid3d_wf", "not implemented"),
    ("hamid_js", "not implemented"),
    ("hexnix3D", "statistics differ"),
    ("hypershift2", "x, y, z differ at the origin"),
    ("iflames_wf", "not implemented"),
    ("inversion", "not implemented"),
    ("isosfplot3d_wf", "not implemented"),
    ("kaleidoimg", "not implemented"),
    ("kifs3d", "not implemented"),
    ("klein_group", "not implemented"),
    ("lazyjess", "x, y differ at the origin"),
    ("lsystem3D_js", "not implemented"),
    ("lsystem_js", "not implemented"),
    ("mandala", "not implemented"),
    ("mandala2", "not implemented"),
    ("maurer_lines", "not implemented"),
    ("metaballs3d_wf", "not implemented"),
    ("msTruchet", "not implemented"),
    ("multi_ifs", "not implemented"),
    (
        "npolar",
        "y differs at the points (0, 0), (0, 1) or (-1, 0)",
    ),
    ("obj_mesh_primitive_wf", "not implemented"),
    ("obj_mesh_wf", "not implemented"),
    ("ocappedcone3D", "statistics differ"),
    ("ocylinder3D", "statistics differ"),
    ("oroundcone3D", "statistics differ"),
    ("ortho", "x, y differ at the origin"),
    ("parplot2d_wf", "not implemented"),
    ("pie3D", "statistics differ"),
    ("pixel_flow", "statistics differ"),
    ("point_mirror_symmetry", "not implemented"),
    ("polarplot2d_wf", "not implemented"),
    (
        "polarplot3d_wf",
        "statistics differ in the alt sets, whose formula text (drawn from a random preset by JWildfire's constructor) the vectors do not record",
    ),
    ("post_brush_stroke_wf", "not implemented"),
    ("post_bumpmap_wf", "not implemented"),
    ("post_circlecrop", "hide flag differs; statistics differ"),
    ("post_colormap_wf", "not implemented"),
    ("post_custom_wf", "not implemented"),
    (
        "post_depth",
        "x, y, z differ: JWildfire's adds the affine point (not the sum) to the sum, and ugnis' post phase does not see the affine point",
    ),
    ("post_displacemap_wf", "not implemented"),
    ("post_point_crop", "not implemented"),
    ("post_smartcrop", "color differs; statistics differ"),
    ("pre_circlecrop", "hide flag differs; statistics differ"),
    ("pre_custom_wf", "not implemented"),
    ("pre_subflame_wf", "not implemented"),
    ("quad", "not implemented"),
    (
        "quaternion",
        "y differs at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    (
        "rays",
        "statistics differ at the origin (point 16): JWildfire divides by r² + 1e-300, the registry's formula guards r² otherwise",
    ),
    (
        "rays3",
        "x, y differ at the points (0, 0), (0, 1) or (-1, 0) (JWildfire's table-based tan)",
    ),
    ("recurrenceplot", "not implemented"),
    ("ringer", "not implemented"),
    ("ringsubflame", "not implemented"),
    ("sattractor3D", "not implemented"),
    (
        "spliptic_bs",
        "statistics differ at the near-zero point 17 (JWildfire's table-based maths: the mean radius, or its last digits)",
    ),
    ("splitbrdr", "statistics differ"),
    (
        "sqrt_asinh",
        "statistics differ at the near-zero point 17 (JWildfire's table-based maths: the mean radius, or its last digits)",
    ),
    (
        "squircular",
        "x, y differ at the near-zero point 17 (JWildfire's table-based maths)",
    ),
    ("squish", "statistics differ"),
    ("subflame_wf", "not implemented"),
    ("sunvoroni", "not implemented"),
    ("superShape3d", "statistics differ"),
    ("svg_wf", "not implemented"),
    ("synth", "x, y differ; statistics differ"),
    ("taprats", "not implemented"),
    ("terrain3D", "not implemented"),
    ("tess_shape", "not implemented"),
    ("text_wf", "statistics differ"),
    ("triantruchet", "not implemented"),
    ("truchet_ae", "not implemented"),
    ("truchet_hex_fill", "statistics differ"),
    ("wallpaper_js", "x differs at the origin"),
    ("wangtiles", "not implemented"),
    (
        "x",
        "x, y differ at the points (0, 0), (0, 1) or (-1, 0) (JWildfire's table-based tan)",
    ),
    (
        "y",
        "x, y differ at the points (0, 0), (0, 1) or (-1, 0) (JWildfire's table-based tan)",
    ),
    ("yplot2d_wf", "not implemented"),
    ("yplot3d_wf", "not implemented"),
    (
        "z",
        "x, y differ at the points (0, 0), (0, 1) or (-1, 0) (JWildfire's table-based tan)",
    ),
];

/// A table of the vectors: from UGNIS_JWF_VECTORS_DIR, else the committed fixture.
fn fixture(name: &str) -> String {
    common::vectors::fixture("jwildfire", "UGNIS_JWF_VECTORS_DIR", name)
}

/// What the vectors say about one variation.
struct JwfVar {
    /// -1 pre, 0 regular, 1 post, ±2 prepost.
    priority: i32,
    /// Its direct colour or hide flag varies from call to call.
    random_rgb_or_hide: bool,
    /// Its output depends on random numbers (its call sequences then depend on JWildfire's
    /// generator: the statistics test them).
    random: bool,
}

/// Every JWildfire variation, by name.
fn jwildfire_variations() -> BTreeMap<String, JwfVar> {
    let t = Table::parse(&fixture("variations"));
    t.rows
        .iter()
        .map(|r| {
            let flags = t.get(r, "flags");
            let v = JwfVar {
                priority: t.get(r, "priority").parse().expect("a priority"),
                random_rgb_or_hide: flags.split(',').any(|f| f == "random_rgb_or_hide"),
                random: flags.split(',').any(|f| f == "random"),
            };
            (t.get(r, "variation").to_string(), v)
        })
        .collect()
}

/// The images of the 24 points under the main affine map (the trimmed vectors write `-` for
/// them).
fn main_points() -> HashMap<String, [f64; 3]> {
    let p = common::fixture("jwildfire").join("points.tsv");
    let t = Table::parse(&std::fs::read_to_string(&p).expect("points.tsv"));
    t.rows
        .iter()
        .map(|r| {
            let v = nums(t.get(r, "t"));
            (t.get(r, "point").to_string(), [v[0], v[1], v[2]])
        })
        .collect()
}

/// The input point of a row.
fn t_in(t: &Table, r: &[String], points: &HashMap<String, [f64; 3]>) -> [f64; 3] {
    match t.opt(r, "t") {
        Some("-") => points[t.get(r, "point")],
        Some(s) => nums(s).try_into().expect("three coordinates"),
        None => [
            num(t.get(r, "t_x")),
            num(t.get(r, "t_y")),
            num(t.get(r, "t_z")),
        ],
    }
}

/// The input point and running sum of every row of the vectors, by (variation, set, point):
/// the statistics and sequences are of the same inputs.
type Inputs = HashMap<(String, String, String), ([f64; 3], Acc)>;

fn inputs(t: &Table) -> Inputs {
    let points = main_points();
    t.rows
        .iter()
        .map(|r| {
            let key = ["variation", "param_set", "point"].map(|c| t.get(r, c).to_string());
            (key.into(), (t_in(t, r, &points), acc_in(t, r)))
        })
        .collect()
}

/// The inputs of row `r` of a statistics or sequence table.
fn input_of(inputs: &Inputs, t: &Table, r: &[String]) -> ([f64; 3], Acc) {
    let key = ["variation", "param_set", "point"].map(|c| t.get(r, c).to_string());
    inputs[&key.into()]
}

/// The variation a name denotes and the form a set of it runs in: a prepost variation's
/// `SET` rows are its call before the regular variations, `SET_post` its call after them.
fn resolve(variation: &str, set: &str) -> Result<(VarId, Form), String> {
    let (id, form) = variations::parse_name(variation)
        .ok_or_else(|| format!("variation '{variation}' is not in the registry"))?;
    if variations::info(id).has(variations::flag::PREPOST) {
        let phase = if set.ends_with("_post") {
            Form::Post
        } else {
            Form::Pre
        };
        return Ok((id, phase));
    }
    Ok((id, form))
}

/// A JWildfire flame's rules: JWildfire's formulas, "preserve Z" off (a new flame's default).
const RULES: Rules = Rules {
    compat: true,
    dialect: Dialect::JWildfire,
    preserve_z: false,
};

fn prepared(s: &Set) -> Prepared {
    Prepared::for_flame(s.id, s.form, s.weight, &s.params, &[], s.aff, RULES)
}

/// The phase JWildfire runs a variation of `priority` in, against the one ugnis runs it in.
fn phase_error(var: &str, priority: i32) -> Option<String> {
    let (id, form) = variations::parse_name(var)?;
    let v = Prepared::for_flame(id, form, 1.0, &[], &[], Default::default(), RULES);
    let prepost = v.def.has(variations::flag::PREPOST);
    let want = match priority {
        -1 => "pre",
        0 => "regular",
        1 => "post",
        _ => "prepost",
    };
    let got = match v.form {
        _ if prepost => "prepost",
        Form::Pre => "pre",
        Form::Regular => "regular",
        Form::Post => "post",
    };
    (want != got).then(|| format!("runs as a {got} variation, JWildfire's is {want}"))
}

/// Failures, by variation (the first few of each).
#[derive(Default)]
struct Failures(BTreeMap<String, Vec<String>>);

impl Failures {
    fn add(&mut self, var: &str, msg: String) {
        let v = self.0.entry(var.to_string()).or_default();
        if v.len() < 8 || print_all() {
            v.push(msg);
        }
    }
    fn merge(&mut self, other: Failures) {
        for (k, v) in other.0 {
            for m in v {
                self.add(&k, m);
            }
        }
    }
}

/// The colour JWildfire's harness reads from a point's own colour. A colour asking for the
/// palette's nearest key (channels lowered by [`Acc::NEAREST_KEY`], JWildfire's Gradient = 1)
/// becomes that key in the harness' palette: a new layer's `RGBPalette`, which holds no colour,
/// so each of its 256 entries reads black. The search is JWildfire's `findKey`: least squared
/// distance over red, green and blue, the first of equals winning.
fn harness_rgb(c: [f64; 3]) -> [f64; 3] {
    if c.iter().all(|&v| v >= 0.0) {
        return c;
    }
    let asked = c.map(|v| (v + Acc::NEAREST_KEY).clamp(0.0, 255.0) as i64);
    let palette = [[0i64; 3]; 256];
    let dist = |k: &[i64; 3]| (0..3).map(|i| (asked[i] - k[i]).pow(2)).sum::<i64>();
    let mut best = palette[0];
    for k in &palette[1..] {
        if dist(k) < dist(&best) {
            best = *k;
        }
    }
    best.map(|v| v as f64)
}

/// The exact cells of every row: position, colour, direct colour, hide flag.
fn check_deterministic(
    t: &Table,
    all: &[SetRows],
    vars: &BTreeMap<String, JwfVar>,
    fails: &mut Failures,
) -> usize {
    let points = main_points();
    let mut checked = 0;
    for (var, ps, set, rows) in all {
        if !selected(var) {
            continue;
        }
        let set = match set {
            Ok(s) => s,
            Err(e) => {
                fails.add(var, e.clone());
                continue;
            }
        };
        let rgb_may_vary = vars.get(var).is_some_and(|v| v.random_rgb_or_hide);
        for &i in rows {
            let r = &t.rows[i];
            let tx = t_in(t, r, &points);
            let v = prepared(set);
            let mut rng = FastRng::new(i as u64);
            let o = variations::eval_prepared(&v, tx, acc_in(t, r), true, &mut rng);
            let color_in = acc_in(t, r).color;
            let want = [
                t.get(r, "out_x"),
                t.get(r, "out_y"),
                t.get(r, "out_z"),
                t.get(r, "color_out"),
            ];
            let got = [o.x, o.y, o.z, o.color];
            let random_row = want.iter().any(|w| w.is_empty());
            let point = t.get(r, "point");
            for k in 0..4 {
                let w = match want[k] {
                    "" => continue, // a random component: see the statistical test
                    "=" => color_in,
                    w => num(w),
                };
                checked += 1;
                if !same(got[k], w) {
                    let c = ["x", "y", "z", "color"][k];
                    let msg = format!("[{ps}] point {point}: {c} = {:e}, want {w:e}", got[k]);
                    fails.add(var, format!("{msg} (t = {tx:?})"));
                }
            }
            if random_row && rgb_may_vary {
                continue;
            }
            let want_hide = t.get(r, "hide_out") == "1";
            if o.hide != want_hide {
                fails.add(
                    var,
                    format!("[{ps}] point {point}: hide {}, want {want_hide}", o.hide),
                );
            }
            let want_rgb = match t.get(r, "rgb_out") {
                "-" => None,
                s => Some(nums(s)),
            };
            let rgb_ok = match (&want_rgb, o.rgb.map(harness_rgb)) {
                (None, None) => true,
                (Some(w), Some(g)) => (0..3).all(|k| same(g[k], w[k])),
                _ => false,
            };
            if !rgb_ok {
                let msg = format!("[{ps}] point {point}: rgb {:?}, want {want_rgb:?}", o.rgb);
                fails.add(var, msg);
            }
        }
    }
    checked
}

/// The random components, against their statistics (rows split between threads).
fn check_random(
    by_set: &HashMap<(String, String), &Set>,
    inputs: &Inputs,
    fails: &mut Failures,
) -> usize {
    let t = Table::parse(&fixture("random_stats"));
    let rows: Vec<(usize, &Vec<String>)> = t
        .rows
        .iter()
        .enumerate()
        .filter(|(_, r)| selected(t.get(r, "variation")))
        .collect();
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let chunk = rows.len().div_ceil(threads).max(1);
    let parts: Vec<Failures> = std::thread::scope(|s| {
        let handles: Vec<_> = rows
            .chunks(chunk)
            .map(|part| {
                let t = &t;
                s.spawn(move || {
                    let mut f = Failures::default();
                    for &(i, r) in part {
                        let (var, ps) = (t.get(r, "variation"), t.get(r, "param_set"));
                        // Each failing variation needs one failing row only.
                        if f.0.contains_key(var) && !print_all() {
                            continue;
                        }
                        let Some(set) = by_set.get(&(var.to_string(), ps.to_string())) else {
                            continue;
                        };
                        let (tx, acc) = input_of(inputs, t, r);
                        let v = prepared(set);
                        let mut rng = FastRng::new(1000 + i as u64);
                        let draw = || variations::eval_prepared(&v, tx, acc, false, &mut rng);
                        if let Err(e) = compare_stats(t, r, Finite::PerCoordinate, draw) {
                            f.add(var, format!("[{ps}] point {}: {e}", t.get(r, "point")));
                        }
                    }
                    f
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for p in parts {
        fails.merge(p);
    }
    rows.len()
}

/// The stateful variations without random numbers, six calls in a row on one object.
fn check_stateful(
    by_set: &HashMap<(String, String), &Set>,
    inputs: &Inputs,
    vars: &BTreeMap<String, JwfVar>,
    fails: &mut Failures,
) {
    let t = Table::parse(&fixture("state_sequences"));
    for r in &t.rows {
        let (var, ps) = (t.get(r, "variation"), t.get(r, "param_set"));
        if !selected(var) || vars.get(var).is_none_or(|v| v.random) {
            continue;
        }
        let Some(set) = by_set.get(&(var.to_string(), ps.to_string())) else {
            continue;
        };
        let v = prepared(set);
        let (tx, _) = input_of(inputs, &t, r);
        let mut rng = FastRng::new(7);
        let acc = Acc {
            color: 0.35,
            ..Acc::default()
        };
        let run = || variations::eval_prepared(&v, tx, acc, false, &mut rng);
        if let Err(e) = compare_sequence(&t, r, run) {
            fails.add(var, format!("[{ps}] point {}: {e}", t.get(r, "point")));
        }
    }
}

#[test]
fn jwildfire_variations_match_their_vectors() {
    let vars = jwildfire_variations();
    let listed: BTreeMap<&str, &str> = NOT_YET.iter().copied().collect();
    let names: Vec<&str> = NOT_YET.iter().map(|(n, _)| *n).collect();
    assert!(names.is_sorted(), "NOT_YET must be sorted");
    assert_eq!(
        listed.len(),
        NOT_YET.len(),
        "NOT_YET names a variation twice"
    );
    for n in &names {
        assert!(
            vars.contains_key(*n),
            "{n} (in NOT_YET) is not a JWildfire variation"
        );
    }

    let t = Table::parse(&fixture("vectors"));
    let all = sets(&t, resolve);
    let mut fails = Failures::default();
    for (name, v) in &vars {
        if !selected(name) {
            continue;
        }
        if let Some(e) = phase_error(name, v.priority) {
            fails.add(name, e);
        }
    }
    let checked = check_deterministic(&t, &all, &vars, &mut fails);
    let by_set: HashMap<(String, String), &Set> = all
        .iter()
        .filter_map(|(v, p, s, _)| Some(((v.clone(), p.clone()), s.as_ref().ok()?)))
        .collect();
    let inputs = inputs(&t);
    let rows = check_random(&by_set, &inputs, &mut fails);
    check_stateful(&by_set, &inputs, &vars, &mut fails);

    let considered: Vec<&String> = vars.keys().filter(|n| selected(n)).collect();
    let mut problems = Vec::new();
    let mut passing = 0;
    for name in &considered {
        match (fails.0.get(*name), listed.get(name.as_str())) {
            (None, None) => passing += 1,
            (None, Some(_)) => problems.push(format!("{name} passes: take it off NOT_YET")),
            (Some(_), Some(_)) => {}
            (Some(f), None) => problems.push(format!("{name}:\n    {}", f.join("\n    "))),
        }
    }
    let listed_here = considered
        .iter()
        .filter(|n| listed.contains_key(n.as_str()))
        .count();
    eprintln!(
        "JWildfire variations: {passing} of {} pass, {listed_here} listed as not yet \
         ({checked} exact values, {rows} statistics rows)",
        considered.len()
    );
    if print_all() {
        for (name, f) in &fails.0 {
            eprintln!("{name}:\n    {}", f.join("\n    "));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// Every JWildfire variation ugnis renders goes by JWildfire's own name where names are listed
/// (`ugnis info --variations`, the editor's variation list: a variation's name in each form
/// reads back as that variation and form), so typing JWildfire's name finds it.
#[test]
fn jwildfire_names_are_listed_as_jwildfire_writes_them() {
    let mut unlisted = Vec::new();
    let mut known = 0;
    for name in jwildfire_variations().keys() {
        let Some((id, form)) = variations::parse_name(name) else {
            continue;
        };
        known += 1;
        let listed = variations::attr_name(id, form);
        if !listed.eq_ignore_ascii_case(name) || variations::info(id).has(variations::flag::HIDDEN)
        {
            unlisted.push(format!("{name} (listed as {listed})"));
        }
    }
    eprintln!("{known} of JWildfire's names are known");
    assert!(
        unlisted.is_empty(),
        "not listed by their name: {unlisted:?}"
    );
}
