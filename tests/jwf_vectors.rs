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
        "grid3d_wf",
        "implemented; alt sets differ: JWildfire keeps a cell's spreads in a map shared by the whole session (its RessourceManager, keyed by the spread's value), filled from a java.util.Random(123) per object in the order cells are first reached anywhere in the session (for the vectors, by the harness' earlier calls); ugnis draws a cell's spreads from a hash of the cell, the same in every thread and every render",
    ),
    (
        "recurrenceplot",
        "implemented; alt set (dc 1) differs by choice: on a missed pair JWildfire repeats its instance's last plotted point with the colour the call came with (the harness' fixed colour; in a render, its one orbit's own colour); ugnis's orbits share one state, so a missed pair there takes the colour stored with the repeated point, which keeps dc's colouring in pictures (sidwellr patterns_recurrenceplot-1: 20.9 -> 29.0 dB, JWildfire's noise 29.3)",
    ),
];

/// The JWildfire variations that match their vectors only with JWildfire's own resources
/// (its brush images, tiles, meshes, default drawing), which ugnis reads from a JWildfire
/// installation named by `UGNIS_JWILDFIRE` (its j-wildfire.jar, or its resource and class
/// folders). With it set they are checked like the others; without it they are not checked.
/// Sorted, one name per line.
const NEEDS_JWILDFIRE: &[(&str, &str)] = &[
    (
        "brush_stroke_wf",
        "its default brushes, JWildfire's brush images (brush001.png, …); a round brush without them",
    ),
    (
        "obj_mesh_primitive_wf",
        "alt2's cone: the irregular triangulation of the base in JWildfire's cone.obj",
    ),
    (
        "post_brush_stroke_wf",
        "its default brushes, JWildfire's brush images (brush001.png, …); a round brush without them",
    ),
    (
        "svg_wf",
        "the default drawing, a string in SVGWFFunc's class",
    ),
    (
        "wangtiles",
        "alt and alt2: the heights are the brightness of JWildfire's tile images (GIFs under org/jwildfire/icons/); without them it draws grey stand-in tiles",
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

fn prepared(var: &str, ps: &str, s: &Set) -> Prepared {
    let mut params = s.params.clone();
    if var == "bubbleT3D" {
        undo_bubble_t3d_init(&mut params);
    }
    let texts: Vec<String> = harness_texts(var, ps)
        .iter()
        .map(|t| t.to_string())
        .collect();
    let mut v = Prepared::for_flame(s.id, s.form, s.weight, &params, &texts, s.aff, RULES);
    v.give_palette(&UNSET_PALETTE);
    v
}

/// The palette the vectors' variations see: a fresh layer's, every entry black (handed over
/// as the chaos game hands a flame's palette over).
static UNSET_PALETTE: std::sync::LazyLock<std::sync::Arc<variations::PaletteIndex>> =
    std::sync::LazyLock::new(|| std::sync::Arc::new(variations::PaletteIndex::unset()));

/// bubbleT3D's `init` rewrites its field `angle_of_hole` (a, in degrees) to the hole's angle
/// π − a·π/360 (for a ≥ 0, as in every set of the vectors), and the vectors' `params` column
/// reads the fields back after `init`: the value set is (π − A)·360/π of the value A listed.
fn undo_bubble_t3d_init(params: &mut [f64]) {
    let (_, _, k) = variations::param_of("bubbleT3D_angle_of_hole").expect("bubbleT3D's hole");
    params[k] = (std::f64::consts::PI - params[k]) * 360.0 / std::f64::consts::PI;
}

/// The formula texts a set ran with where the vectors do not record them. polarplot3d_wf's
/// harness set `preset_id` (an integer: 8 + 1 = 9 in `alt`, 8 + 2 = 10 in `alt2`) first,
/// which loads that preset's formula (JWildfire's presets file; an id it lacks, as 10, gives
/// the default preset, formula `1.0`); the ranges set next differ from the preset's, so
/// `preset_id` reads back as −1 while the formula stays.
fn harness_texts(var: &str, ps: &str) -> &'static [&'static str] {
    match (var, ps) {
        ("polarplot3d_wf", "alt") => &["cos(param_a*t + sin(param_b*u)) + param_c"],
        ("polarplot3d_wf", "alt2") => &["1.0"],
        // The other plots likewise: the preset id pinned for `default` (preset_id in the
        // `params` column), that id + 1 for `alt` and + 2 for `alt2` (polarplot2d_wf has no
        // preset 16: its default preset's formula `1.0`).
        ("parplot2d_wf", "default") => &[
            "(6.0+2.0*cos(u*v))*cos(u)",
            "(6.0+2.0*cos(u*v))*sin(u)",
            "(2.0*u+2.0*sin(u*v))",
        ],
        ("parplot2d_wf", "alt") => &[
            "(1.0+0.25*cos(75.0*u))*cos(u)",
            "(1.0+0.25*cos(75.0*u))*sin(u)",
            "u+sin(75.0*u)",
        ],
        ("parplot2d_wf", "alt2") => &[
            "7.83*cos((v-pi)/2.0)*(cos(16.4*v))",
            "7.83*cos((v-pi)/2.0)*(sin(16.4*v))",
            "7.83*sin((v-pi)/2.0)",
        ],
        ("polarplot2d_wf", "default") => &["param_a * sin(t) / t"],
        ("polarplot2d_wf", "alt") => &["param_a + tanh(param_b * sin(param_c*t))/param_b"],
        ("polarplot2d_wf", "alt2") => &["1.0"],
        ("yplot2d_wf", "default") => &["log(fabs(x))"],
        ("yplot2d_wf", "alt") => &["fabs(sin(x)*param_a) + fabs(cos(x)*param_b)"],
        ("yplot2d_wf", "alt2") => &["x>0?pow(x,param_a):-pow(-x,param_a)"],
        ("yplot3d_wf", "default") => &["(sin(x)*sin(x)+cos(z)*cos(z))/(5+x*x+z*z)"],
        ("yplot3d_wf", "alt") => &["cos(2*pi*(x+z))*(1-sqrt(x*x+z*z))"],
        ("yplot3d_wf", "alt2") => &["sin(x*x+z*z)"],
        ("isosfplot3d_wf", "default") => &[
            "pow(4*(-fabs(fabs(x)-1)*cos(pi/10)+y*sin(pi/10)+1),2)+pow((2*z),200)+pow((y/3),200)-1",
        ],
        ("isosfplot3d_wf", "alt") => &[
            "cos(param_a*floor(x * param_e)) + sin(param_b*floor(y * param_f)) + cos(param_c*floor(z))-param_d",
        ],
        ("isosfplot3d_wf", "alt2") => &[
            "cos(floor(param_a*floor(x))* param_e) + sin(floor(param_b*floor(y)) * param_f) + cos(floor(param_c*floor(z)) * param_d)",
        ],
        _ => &[],
    }
}

/// Cells the vectors record as exact that are random in JWildfire: the harness looks for
/// random cells at the default weight and affine map only and reuses that finding for the
/// `weight2`, `affine2` and `acc` sets. asteria draws only for points inside both the unit
/// circle and the circle of radius 1 about (±1, ±1); at weight −1.3 points 11, 13 and 15 are
/// there (at 0.7 they are not), and the value recorded is the one the draw of seed
/// 1000 + point gave (above 0.35: the point kept). Such a row must equal ugnis' output for
/// one of [`UNMARKED_SEEDS`] seeds. wallpaper_js either adds its map to the sum or replaces
/// the sum by the point, at random: at the origin both give x = 0 from a zero sum, so the
/// default set finds that cell exact (y, a or 0, is marked random), but from the `acc` set's
/// sum (0.3, −0.2) the first keeps x = 0.3 and the second gives 0.
///
/// post_smartcrop with `cropmode` 2 replaces a cropped point by the last point it kept (with
/// its colour); a fresh object that crops before it has kept any gives the origin with colour
/// 0. At `alt2` point 10 the random edge crops the point some of the time, so a fresh object's
/// first call is random, but JWildfire's own call kept it (colour 0.35 recorded as exact).
const UNMARKED_RANDOM: &[(&str, &str, &[&str])] = &[
    ("asteria", "weight2", &["11", "13", "15"]),
    ("post_smartcrop", "alt2", &["10"]),
    ("wallpaper_js", "acc", &["16"]),
];

/// Variations whose statistics stream in JWildfire began with a kept point, where ugnis'
/// stream may begin with a crop: post_smartcrop gives the origin with colour 0 for a crop
/// before any point was kept (see [`UNMARKED_RANDOM`]), once per object; the statistics of
/// `alt2` point 10 (all 20,000 outputs the point itself) count from the first kept point
/// (within the first 64 calls).
const STARTS_KEPT: &[&str] = &["post_smartcrop"];

/// How many seeds an [`UNMARKED_RANDOM`] row is tried with.
const UNMARKED_SEEDS: u64 = 64;

/// JWildfire's generator (`MarsagliaRandomGenerator`: two 16-bit multiply-with-carry
/// generators in Java's signed `int`; the overflow of the one multiplied by 36969 breaks it
/// into short cycles) enters a cycle of 2331 steps from the statistics' seeds 4242 + 11 and
/// 4242 + 23 (after 34416 and 27665 draws; from the other 22 seeds it enters one of 100638
/// steps), and the part it adds to every later draw repeats with that period: successive
/// triples of draws are then far from uniform in the unit cube (seed 4253: 3.41 % of 300000
/// triples in [0.7, 1]³, where 2.70 % are expected and seed 4242 gives 2.80 %). Variations
/// that fill a solid by drawing points of the cube until one falls inside accept at a rate
/// that differs accordingly (capsule3D `alt2`: 6.1 % of the draws from seed 4253, 5.4 % from
/// 4265, 4.9 to 5.1 % from the others), so their statistics at these two points are not
/// those of uniform draws. Their other 22 points are compared.
const SHORT_CYCLE_POINTS: &[&str] = &["11", "23"];

/// The variations whose statistics at [`SHORT_CYCLE_POINTS`] are left out: those that draw
/// points of the cube until one falls inside a solid (chaosCubes: a sub-cube of the kept
/// pattern), and dc_dmodulus, whose colour halves
/// the last colour and adds one of two values picked by a draw at every call (the colour
/// reads the last draws as binary digits).
const JOINT_DRAWS: &[&str] = &[
    "capsule3D",
    "chaosCubes",
    "dc_dmodulus",
    "ocappedcone3D",
    "ocylinder3D",
    "oroundcone3D",
];

/// Variations whose successive outputs are strongly correlated, so that the quantiles of one
/// stream of 20,000 calls scatter far more than those of independent draws: the buddhabrot
/// modes of fract_mandelbrot_wf and fract_meteors_wf give every point of an escaping orbit in
/// turn (a run of up to `max_iter` related points, the last ones far out), and recurrenceplot
/// repeats the last point plotted for every rejected draw. (A Python replica of JWildfire's
/// `transformBuddhabrot` with its Marsaglia generator from seed 4242 reproduces the recorded
/// p10/p50/p90 of fract_mandelbrot_wf's `alt` point 0 exactly, 1.26232, 3.20302, 205.670,
/// while two other seeds of a good generator give p90 343.8 and 177.4.) Their rows are
/// compared with [`compare_correlated`].
const CORRELATED: &[&str] = &["fract_mandelbrot_wf", "fract_meteors_wf", "recurrenceplot"];

/// How many independent streams [`compare_correlated`] draws.
const CORRELATED_STREAMS: u64 = 16;

/// A row of a [`CORRELATED`] variation: `stream(k)` gives the row's count of successive
/// outputs of a fresh object from the k-th seed. For each component and each recorded
/// quantile q (probability p), the share of each stream's finite values below (at most) q is
/// found; the recorded stream is one more stream of the same kind, so p must lie within five
/// standard deviations of those shares (their spread between the streams, allowing for the
/// recorded stream's own) of their mean, plus 0.01. (With the spread estimated from 16 streams
/// a share is that far off by chance about once in 6,000 comparisons; the seeds are fixed.)
/// The recorded rows are themselves that scattered: the same Python replica of recurrenceplot
/// gives JWildfire's p10 of y at all 24 points exactly, from −0.300 to −0.252.
fn compare_correlated(
    t: &Table,
    r: &[String],
    mut stream: impl FnMut(u64) -> Vec<Acc>,
) -> Result<(), String> {
    let cell = |c: &str| match t.get(r, c) {
        "" => f64::NAN,
        s => num(s),
    };
    let streams: Vec<[Vec<f64>; 5]> = (0..CORRELATED_STREAMS)
        .map(|k| {
            let mut comp: [Vec<f64>; 5] = Default::default();
            for o in stream(k) {
                let values = [o.x, o.y, o.z, o.x.hypot(o.y), o.color];
                for (c, v) in comp.iter_mut().zip(values) {
                    if v.is_finite() {
                        c.push(v);
                    }
                }
            }
            for c in &mut comp {
                c.sort_by(f64::total_cmp);
            }
            comp
        })
        .collect();
    let mut bad = Vec::new();
    for (k, name) in ["x", "y", "z", "r", "color"].iter().enumerate() {
        if streams.iter().any(|c| c[k].len() < 100) {
            continue;
        }
        for (p, col) in [(0.1, "p10"), (0.5, "p50"), (0.9, "p90")] {
            let q = cell(&format!("{col}_{name}"));
            if q.is_nan() {
                continue;
            }
            let shares: Vec<(f64, f64)> = streams
                .iter()
                .map(|c| {
                    let v = &c[k];
                    let m = v.len() as f64;
                    let below = v.partition_point(|&x| x < q - 1e-9 * q.abs()) as f64 / m;
                    let upto = v.partition_point(|&x| x <= q + 1e-9 * q.abs()) as f64 / m;
                    (below, upto)
                })
                .collect();
            let s = shares.len() as f64;
            let mid: Vec<f64> = shares.iter().map(|(b, u)| (b + u) / 2.0).collect();
            let mean_mid = mid.iter().sum::<f64>() / s;
            let sd = (mid.iter().map(|x| (x - mean_mid).powi(2)).sum::<f64>() / (s - 1.0)).sqrt();
            let below = shares.iter().map(|x| x.0).sum::<f64>() / s;
            let upto = shares.iter().map(|x| x.1).sum::<f64>() / s;
            let tol = 5.0 * sd * (1.0 + 1.0 / s).sqrt() + 0.01;
            if below > p + tol || upto < p - tol {
                bad.push(format!(
                    "{name}: {:.3} of the values below their {col} {q:.6e} (at most {:.3}; \
                     spread between streams {sd:.3})",
                    below, upto
                ));
            }
        }
    }
    if bad.is_empty() {
        Ok(())
    } else {
        Err(bad.join("; "))
    }
}

fn unmarked_random(var: &str, ps: &str, point: &str) -> bool {
    UNMARKED_RANDOM
        .iter()
        .any(|(v, s, pts)| *v == var && *s == ps && pts.contains(&point))
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
/// Parameter sets whose recorded values come from a race in JWildfire, left out: dla3d_wf
/// with `single_thread` 0 (its `default` set) grows its aggregate with two walker threads per
/// render thread drawing from one shared generator, so the shape depends on the threads'
/// timing (JWildfire caches the first shape it grew for the session). ugnis grows it as
/// JWildfire's single-threaded path does; the `alt` and `alt2` sets (`single_thread` 1 and 2)
/// are compared exactly.
const RACED_SETS: &[(&str, &str)] = &[("dla3d_wf", "default")];

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
        if RACED_SETS.contains(&(var.as_str(), ps.as_str())) {
            continue;
        }
        let rgb_may_vary = vars.get(var).is_some_and(|v| v.random_rgb_or_hide);
        // JWildfire's harness evaluates a set on one object, point after point, unless the set
        // is flagged stateful (then each point on a fresh object): a variation that remembers
        // points (post_point_crop) sees the points before it.
        let shared = prepared(var, ps, set);
        for &i in rows {
            let r = &t.rows[i];
            let tx = t_in(t, r, &points);
            let fresh;
            let v = if t.get(r, "fresh") == "1" {
                fresh = prepared(var, ps, set);
                &fresh
            } else {
                &shared
            };
            let color_in = acc_in(t, r).color;
            let want = [
                t.get(r, "out_x"),
                t.get(r, "out_y"),
                t.get(r, "out_z"),
                t.get(r, "color_out"),
            ];
            let random_row = want.iter().any(|w| w.is_empty());
            let point = t.get(r, "point");
            let run = |seed: u64| {
                let mut rng = FastRng::new(seed);
                variations::eval_prepared(v, tx, acc_in(t, r), true, &mut rng)
            };
            let matches = |o: &Acc| {
                let got = [o.x, o.y, o.z, o.color];
                (0..4).all(|k| match want[k] {
                    "" => true,
                    "=" => same(got[k], color_in),
                    w => same(got[k], num(w)),
                })
            };
            let mut o = run(i as u64);
            if unmarked_random(var, ps, point) && !matches(&o) {
                let seeds = (1..UNMARKED_SEEDS).map(|k| i as u64 + k * 7919);
                if let Some(hit) = seeds.map(run).find(matches) {
                    o = hit;
                }
            }
            let got = [o.x, o.y, o.z, o.color];
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
                        let point = t.get(r, "point");
                        if JOINT_DRAWS.contains(&var) && SHORT_CYCLE_POINTS.contains(&point) {
                            continue;
                        }
                        let (tx, acc) = input_of(inputs, t, r);
                        if CORRELATED.contains(&var) {
                            let n: usize = t.get(r, "n").parse().expect("a count");
                            let stream = |k: u64| {
                                let v = prepared(var, ps, set);
                                let mut rng = FastRng::new(1000 + i as u64 + 7919 * k);
                                (0..n)
                                    .map(|_| {
                                        variations::eval_prepared(&v, tx, acc, false, &mut rng)
                                    })
                                    .collect()
                            };
                            if let Err(e) = compare_correlated(t, r, stream) {
                                f.add(var, format!("[{ps}] point {}: {e}", t.get(r, "point")));
                            }
                            continue;
                        }
                        let v = prepared(var, ps, set);
                        let mut rng = FastRng::new(1000 + i as u64);
                        // Leading initial outputs skipped (at most 64: a point never kept
                        // gives the initial state throughout).
                        let mut skip = if STARTS_KEPT.contains(&var) { 64 } else { 0 };
                        let draw = || loop {
                            let o = variations::eval_prepared(&v, tx, acc, false, &mut rng);
                            let initial = o.x == 0.0 && o.y == 0.0 && o.z == 0.0 && o.color == 0.0;
                            if skip == 0 || !initial {
                                skip = 0;
                                return o;
                            }
                            skip -= 1;
                        };
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
        if !selected(var)
            || vars.get(var).is_none_or(|v| v.random)
            || RACED_SETS.contains(&(var, ps))
        {
            continue;
        }
        let Some(set) = by_set.get(&(var.to_string(), ps.to_string())) else {
            continue;
        };
        let v = prepared(var, ps, set);
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
    let installed = match ugnis::io::jwf_install::install_from_env() {
        Some(r) => {
            r.expect("UGNIS_JWILDFIRE names a JWildfire installation that opens");
            true
        }
        None => false,
    };
    let listed: BTreeMap<&str, &str> = NOT_YET.iter().copied().collect();
    let mut names: Vec<&str> = NOT_YET.iter().map(|(n, _)| *n).collect();
    assert!(names.is_sorted(), "NOT_YET must be sorted");
    assert_eq!(
        listed.len(),
        NOT_YET.len(),
        "NOT_YET names a variation twice"
    );
    let needs: Vec<&str> = NEEDS_JWILDFIRE.iter().map(|(n, _)| *n).collect();
    assert!(needs.is_sorted(), "NEEDS_JWILDFIRE must be sorted");
    for n in &needs {
        assert!(!listed.contains_key(n), "{n} is on both lists");
    }
    if !installed {
        eprintln!(
            "{} variations need JWildfire's own resources and are not checked: {} \
             (set UGNIS_JWILDFIRE to JWildfire's jar or resource folders)",
            needs.len(),
            needs.join(", ")
        );
    }
    let skipped: Vec<&str> = if installed { Vec::new() } else { needs };
    names.extend(&skipped);
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

    let considered: Vec<&String> = vars
        .keys()
        .filter(|n| selected(n) && !skipped.contains(&n.as_str()))
        .collect();
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

/// JWildfire looks a parameter up by its exact name, so ugnis spells the parameters of
/// JWildfire's own variations in JWildfire 9.00's letter case (that of the vectors' sets); variations shared with Fractorium keep Fractorium's spelling and are read in
/// any case.
#[test]
fn jwildfire_variations_spell_parameters_as_jwildfire() {
    let t = Table::parse(&fixture("vectors"));
    let mut wrong = std::collections::BTreeSet::new();
    for r in &t.rows {
        let (var, ps) = (t.get(r, "variation"), t.get(r, "params"));
        let Some((id, form)) = variations::parse_name(var) else {
            continue;
        };
        if ps == "\"" || ps == "-" || !variations::info(id).has(variations::flag::JWILDFIRE) {
            continue;
        }
        let def = variations::def_in(variations::Dialect::JWildfire, id, form);
        for k in ps
            .split(';')
            .filter_map(|kv| kv.split_once('='))
            .map(|kv| kv.0)
        {
            let want = format!("{}_{k}", variations::info(id).name);
            let Some((pid, _, i)) = variations::param_of(&want) else {
                continue;
            };
            let p = def.params.get(i).or(variations::info(id).params.get(i));
            if pid == id && p.is_some_and(|p| p.name != want && p.name.eq_ignore_ascii_case(&want))
            {
                wrong.insert(format!("{} (JWildfire: {want})", p.map_or("", |p| p.name)));
            }
        }
    }
    assert!(wrong.is_empty(), "spelled otherwise: {wrong:?}");
}
