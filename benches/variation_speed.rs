//! Evaluations per second of the 50 variations real files use most (counted over the flames
//! in the project's test data, `pre_`/`post_` forms included), through each copy of their batch
//! loops — baseline CPU, AVX2 with FMA, AVX-512F — and point by point through the formula's
//! pointer, on 4096 points spread over radii 10⁻³…10³. Best of 5 runs of each; the table is
//! printed as Markdown.
//!
//! Run: `cargo bench --bench variation_speed` (on a CPU without AVX-512 or AVX2 the wider
//! columns repeat the narrower copy); `VARS=julian,juliascope cargo bench …` times only those.

use ugnis::flame::variations::{Affine, Form, Prepared, Simd, VarId, all, by_name, time_batches};
use ugnis::rng::FastRng;

const MOST_USED: [&str; 50] = [
    "linear",
    "blur",
    "spherical",
    "bubble",
    "julian",
    "gaussian_blur",
    "curl",
    "spiral",
    "elliptic",
    "polar",
    "waves2",
    "disc",
    "eyefish",
    "zscale",
    "cylinder",
    "hemisphere",
    "noise",
    "flatten",
    "polar2",
    "rays",
    "swirl",
    "bipolar",
    "boarders",
    "butterfly",
    "diamond",
    "ex",
    "exponential",
    "fan2",
    "fisheye",
    "hypertile1",
    "julia",
    "juliascope",
    "log",
    "loonie",
    "oscilloscope",
    "rectangles",
    "sinusoidal",
    "splits",
    "arch",
    "blade",
    "cosine",
    "handkerchief",
    "hyperbolic",
    "lazysusan",
    "pie",
    "popcorn",
    "radial_blur",
    "secant2",
    "sinh",
    "auger",
];

fn main() {
    let mut rng = FastRng::new(7);
    let pts: Vec<[f64; 3]> = (0..4096)
        .map(|_| {
            let s = 10f64.powf(rng.f01() * 6.0 - 3.0);
            [rng.f11() * s, rng.f11() * s, rng.f11()]
        })
        .collect();
    let aff = Affine {
        a: 0.9,
        b: -0.3,
        c: 0.2,
        d: 0.4,
        e: 1.1,
        f: -0.6,
    };
    let reps = 40;
    let evals = (pts.len() * reps) as f64;
    println!(
        "| variation | point by point | baseline | AVX2+FMA | AVX-512F | AVX-512 / baseline |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    let only = std::env::var("VARS").ok();
    let wanted = |name: &str| {
        only.as_ref()
            .is_none_or(|o| o.split(',').any(|v| v == name))
    };
    for name in MOST_USED.into_iter().filter(|n| wanted(n)) {
        let id: VarId = by_name(name).expect("a registered variation");
        let def = &all()[id as usize];
        // julian and its kin at the powers real files use; the others at their defaults.
        let params: Vec<f64> = def
            .params
            .iter()
            .map(|p| if p.name == "power" { 5.0 } else { p.default })
            .collect();
        let v = Prepared::new(id, Form::Regular, 0.7, &params, aff, true);
        let best = |simd: Simd, batched: bool| {
            (0..5)
                .map(|_| time_batches(&v, &pts, reps, simd, batched))
                .fold(f64::INFINITY, f64::min)
        };
        let per_s = |secs: f64| evals / secs / 1e6;
        let generic = per_s(best(Simd::Baseline, false));
        let [base, avx2, avx512] =
            [Simd::Baseline, Simd::Avx2Fma, Simd::Avx512].map(|s| per_s(best(s, true)));
        println!(
            "| {name} | {generic:.0} M/s | {base:.0} M/s | {avx2:.0} M/s | {avx512:.0} M/s | {:.2}× |",
            avx512 / base
        );
    }
}
