//! Random flames: symmetry shows in the picture, the quality check's pass rate over
//! 1000 seeds, batches are reproducible, transform counts stay in range.

use rayon::prelude::*;
use ugnis::flame::Chaos;
use ugnis::flame::random::{self, RandomOptions, SymmetryMode, VariationMode};
use ugnis::flame::rng::FastRng;
use ugnis::flame::{Flame, NewFlame, variations};

const BINS: usize = 48;

/// Histogram of the attractor on a BINS×BINS grid over [−r, r]², whose bin edges are symmetric
/// about the origin (so quarter turns and mirrors about the origin permute bins exactly).
fn histogram(f: &Flame, seed: u64, samples: usize) -> Vec<f64> {
    let chaos = Chaos::new(f).unwrap();
    let mut rng = FastRng::new(seed);
    let mut p = Chaos::start_point(&mut rng);
    let mut last = None;
    let mut pts = Vec::with_capacity(samples);
    for k in 0..samples as i64 + 20 {
        let i = chaos.choose(last, &mut rng);
        let (np, bad) = chaos.xforms[i].apply(p, &mut rng);
        if bad {
            (p.x, p.y) = (rng.f11(), rng.f11());
            continue;
        }
        (p, last) = (np, Some(i));
        if k >= 20 {
            pts.push((p.x, p.y));
        }
    }
    // r: the 99th percentile of |x|, |y| (ignore far outliers).
    let mut ext: Vec<f64> = pts.iter().map(|p| p.0.abs().max(p.1.abs())).collect();
    ext.sort_by(f64::total_cmp);
    let r = ext[ext.len() * 99 / 100].max(1e-9);
    let mut h = vec![0.0; BINS * BINS];
    for (x, y) in pts {
        let i = ((x + r) / (2.0 * r) * BINS as f64).floor();
        let j = ((y + r) / (2.0 * r) * BINS as f64).floor();
        if (0.0..BINS as f64).contains(&i) && (0.0..BINS as f64).contains(&j) {
            h[j as usize * BINS + i as usize] += 1.0;
        }
    }
    h
}

/// Bin (i, j) → its image under a map of the grid.
fn permuted(h: &[f64], map: impl Fn(usize, usize) -> (usize, usize)) -> Vec<f64> {
    let mut out = vec![0.0; h.len()];
    for j in 0..BINS {
        for i in 0..BINS {
            let (a, b) = map(i, j);
            out[b * BINS + a] = h[j * BINS + i];
        }
    }
    out
}

/// Relative L1 distance of the log densities (what the log-density renderer shows): 0 for
/// equal histograms, 1 for disjoint ones.
fn distance(a: &[f64], b: &[f64]) -> f64 {
    let (a, b): (Vec<f64>, Vec<f64>) = (
        a.iter().map(|v| v.ln_1p()).collect(),
        b.iter().map(|v| v.ln_1p()).collect(),
    );
    let d: f64 = a.iter().zip(&b).map(|(p, q)| (p - q).abs()).sum();
    let s: f64 = a.iter().zip(&b).map(|(p, q)| p + q).sum();
    d / s
}

fn quarter(i: usize, j: usize) -> (usize, usize) {
    (BINS - 1 - j, i)
}
fn half(i: usize, j: usize) -> (usize, usize) {
    (BINS - 1 - i, BINS - 1 - j)
}
fn mirror(i: usize, j: usize) -> (usize, usize) {
    (BINS - 1 - i, j)
}

fn symmetric(k: i32, seed: u64) -> Flame {
    let opts = RandomOptions {
        symmetry: SymmetryMode::Order(k),
        ..RandomOptions::default()
    };
    random::generate(seed, &opts, &NewFlame::default()).flame
}

#[test]
fn symmetry_n_is_invariant_under_rotation_by_360_over_n() {
    const N: usize = 1_000_000;
    for seed in 1u64..=4 {
        let mut line = format!("seed {seed}:");
        for (k, map, name) in [
            (
                4,
                quarter as fn(usize, usize) -> (usize, usize),
                "quarter turn",
            ),
            (2, half, "half turn"),
            (-1, mirror, "mirror"),
            (-4, mirror, "mirror"),
        ] {
            let f = symmetric(k, seed);
            let h = histogram(&f, 1, N);
            let turned = distance(&h, &permuted(&h, map));
            // The chaos game's own noise: the same flame from another starting seed.
            let noise = distance(&h, &histogram(&f, 2, N));
            // Control: the flame without its symmetry transforms is not invariant.
            let mut plain = f.clone();
            plain
                .xforms
                .retain(|x| x.color_speed != 0.0 || x.vars.len() != 1);
            let hp = histogram(&plain, 1, N);
            let control = distance(&hp, &permuted(&hp, map));
            line += &format!(
                "  order {k}: {name} {turned:.3} (noise {noise:.3}, without symmetry {control:.3})"
            );
            // flam3's symmetry transforms make the support exactly symmetric; the density only
            // nearly (the last map of the chaos game is not always one of the group's), so
            // allow a few per cent beyond the noise (measured 0.013–0.06 over 12 seeds, noise
            // 0.01–0.05; without the symmetry transforms 0.12–0.99).
            assert!(
                turned <= 0.08,
                "seed {seed}, order {k}: {name} moves the log histogram by {turned:.3} (noise {noise:.3})"
            );
            assert!(
                control >= 2.0 * turned,
                "seed {seed}, order {k}: without symmetry {control:.3}, with {turned:.3}"
            );
        }
        eprintln!("{line}");
    }
}

#[test]
fn thousand_seeds_mostly_pass_the_quality_check() {
    let opts = RandomOptions::default();
    let defaults = NewFlame::default();
    let results: Vec<(bool, usize)> = (0..1000u64)
        .into_par_iter()
        .map(|s| {
            let g = random::generate(random::batch_seed(77, s as usize), &opts, &defaults);
            (g.passed, g.attempts)
        })
        .collect();
    let passed = results.iter().filter(|r| r.0).count();
    let first_try = results.iter().filter(|r| r.0 && r.1 == 1).count();
    eprintln!("{passed}/1000 passed within 10 attempts, {first_try} at the first attempt");
    assert!(passed >= 900, "only {passed} of 1000 seeds passed");
}

#[test]
fn batches_are_identical_for_a_seed_and_counts_stay_in_range() {
    let opts = RandomOptions {
        min_xforms: 3,
        max_xforms: 4,
        variations: VariationMode::Single(variations::SWIRL),
        ..RandomOptions::default()
    };
    let d = NewFlame::default();
    let a = random::generate_batch(12, 99, &opts, &d);
    let b = random::generate_batch(12, 99, &opts, &d);
    assert_eq!(a, b);
    assert_ne!(a, random::generate_batch(12, 100, &opts, &d));
    let mut seen = std::collections::HashSet::new();
    for f in &a {
        assert!((3..=4).contains(&f.xforms.len()), "{}", f.xforms.len());
        seen.insert(f.xforms.len());
        for x in &f.xforms {
            assert_eq!(x.vars.len(), 1);
            assert_eq!(x.vars[0].id, variations::SWIRL);
        }
        assert!(f.seed.is_some(), "each flame keeps its seed");
        // Regenerating from the stored seed gives the same flame.
        let again = random::generate(f.seed.unwrap(), &opts, &d).flame;
        assert_eq!(again.xforms, f.xforms);
    }
    assert_eq!(seen.len(), 2, "both 3 and 4 transforms occur");
    let names: Vec<&str> = a.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(names[0], "random-001");
    assert_eq!(names[11], "random-012");
}
