//! Mutations (the Apophysis mutation window): variants of a flame that differ by a chosen
//! amount in one respect — coefficients, variations, colours, the set of transforms, symmetry.

use crate::flame::framing;
use crate::flame::model::{Affine, Flame, Var, Xform};
use crate::flame::random::{RandomOptions, VariationMode, blows_up, random_variations};
use crate::flame::rng::FastRng;
use crate::flame::symmetry::{add_symmetry, random_symmetry};

/// What a mutant changes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mutation {
    /// Every affine coefficient moves by up to ±distance.
    Coefficients,
    /// One transform gets new variations (blended in by distance).
    Variations,
    /// Transform colours move by up to ±distance/2 and the gradient turns by up to distance·128.
    Colours,
    /// A random transform is added.
    AddTransform,
    /// A transform is removed (never below 2).
    RemoveTransform,
    /// Rotational or mirror symmetry is added.
    Symmetry,
    /// Coefficients and one variation.
    Mixed,
}

/// The eight mutants of the 3×3 grid, in reading order around the centre.
pub const GRID: [Mutation; 8] = [
    Mutation::Coefficients,
    Mutation::Variations,
    Mutation::Colours,
    Mutation::AddTransform,
    Mutation::Mixed,
    Mutation::RemoveTransform,
    Mutation::Symmetry,
    Mutation::Coefficients,
];

fn jitter(m: &Affine, d: f64, rng: &mut FastRng) -> Affine {
    Affine {
        a: m.a + d * rng.f11(),
        b: m.b + d * rng.f11(),
        c: m.c + d * rng.f11(),
        d: m.d + d * rng.f11(),
        e: m.e + d * rng.f11(),
        f: m.f + d * rng.f11(),
    }
}

/// One mutant of `flame`. `distance` in (0, 1]: how far it may move. Deterministic for a seed;
/// a mutant that would blow up is retried a few times and otherwise falls back to a smaller
/// coefficient change. The mutant is framed anew.
pub fn mutate(
    flame: &Flame,
    kind: Mutation,
    distance: f64,
    seed: u64,
    opts: &RandomOptions,
) -> Flame {
    let d = distance.clamp(0.01, 1.0);
    let mut rng = FastRng::new(seed);
    let mut out = None;
    for _ in 0..6 {
        let m = mutate_once(flame, kind, d, &mut rng, opts);
        if !blows_up(&m, &mut rng) {
            out = Some(m);
            break;
        }
    }
    let mut m =
        out.unwrap_or_else(|| mutate_once(flame, Mutation::Coefficients, d * 0.2, &mut rng, opts));
    if m.xforms.is_empty() {
        m = flame.clone();
    }
    if kind != Mutation::Colours {
        framing::apply_auto_frame(&mut m);
    }
    m.seed = None;
    m
}

fn mutate_once(
    flame: &Flame,
    kind: Mutation,
    d: f64,
    rng: &mut FastRng,
    opts: &RandomOptions,
) -> Flame {
    let mut f = flame.clone();
    let n = f.xforms.len();
    match kind {
        Mutation::Coefficients => {
            for x in &mut f.xforms {
                x.coefs = jitter(&x.coefs, d * 0.5, rng);
            }
        }
        Mutation::Variations if n > 0 => {
            let i = rng.below(n as u64) as usize;
            let mode = match &opts.variations {
                VariationMode::Single(_) => VariationMode::Mix,
                m => m.clone(),
            };
            let x = &mut f.xforms[i];
            // New terms: at least one the transform does not have yet.
            let mut new = random_variations(&mode, rng);
            for _ in 0..20 {
                if new.iter().any(|v| x.var(v.id).is_none()) {
                    break;
                }
                new = random_variations(&VariationMode::Mix, rng);
            }
            // Blend: the old terms shrink by d, the new ones come in with weight d.
            for v in &mut x.vars {
                v.weight *= 1.0 - d;
            }
            for v in new {
                match x.vars.iter_mut().find(|w| w.id == v.id) {
                    Some(w) => w.weight += d * v.weight,
                    None => x.vars.push(Var {
                        weight: d * v.weight,
                        ..v
                    }),
                }
            }
            x.vars.retain(|v| v.weight.abs() > 1e-9);
        }
        Mutation::Colours => {
            for x in &mut f.xforms {
                x.color = (x.color + 0.5 * d * rng.f11()).rem_euclid(1.0);
            }
            let k = (d * 128.0 * rng.f11()).round() as i32;
            let name = f.palette.name.clone();
            f.palette = f.palette.rotated(k);
            f.palette.name = name;
        }
        Mutation::AddTransform => {
            let mut x = Xform::linear(
                Affine::new(
                    d * rng.f11(),
                    d * rng.f11(),
                    d * rng.f11(),
                    d * rng.f11(),
                    rng.f11(),
                    rng.f11(),
                ),
                0.0,
                rng.f01(),
            );
            x.vars = random_variations(&opts.variations, rng);
            let avg = if n > 0 {
                f.xforms.iter().map(|x| x.weight).sum::<f64>() / n as f64
            } else {
                1.0
            };
            x.weight = avg.max(1e-3);
            f.xforms.push(x);
        }
        Mutation::RemoveTransform if n > 2 => {
            let i = rng.below(n as u64) as usize;
            f.xforms.remove(i);
            for x in &mut f.xforms {
                if i < x.chaos.len() {
                    x.chaos.remove(i);
                }
            }
        }
        Mutation::RemoveTransform => {
            // Two left: change one of them a lot instead.
            let i = rng.below(n.max(1) as u64) as usize;
            if let Some(x) = f.xforms.get_mut(i) {
                x.coefs = jitter(&x.coefs, d, rng);
            }
        }
        Mutation::Symmetry => {
            let mut k = random_symmetry(rng);
            if (-1..=1).contains(&k) && k != -1 {
                k = 2 + rng.below(3) as i32;
            }
            add_symmetry(&mut f, k);
        }
        Mutation::Mixed => {
            f = mutate_once(&f, Mutation::Coefficients, d * 0.5, rng, opts);
            f = mutate_once(&f, Mutation::Variations, d, rng, opts);
        }
        Mutation::Variations => {}
    }
    f
}

/// The eight mutants of the grid for a seed.
pub fn grid(flame: &Flame, distance: f64, seed: u64, opts: &RandomOptions) -> Vec<Flame> {
    GRID.iter()
        .enumerate()
        .map(|(i, k)| {
            mutate(
                flame,
                *k,
                distance,
                FastRng::for_stream(seed, i as u64).u64(),
                opts,
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::random::generate;

    fn base() -> Flame {
        generate(5, &RandomOptions::default(), &Default::default()).flame
    }

    #[test]
    fn mutants_are_deterministic_and_change_what_they_say() {
        let f = base();
        let opts = RandomOptions::default();
        let a = grid(&f, 0.3, 9, &opts);
        let b = grid(&f, 0.3, 9, &opts);
        assert_eq!(a.len(), 8);
        assert_eq!(a, b, "same seed, same mutants");
        for (m, k) in a.iter().zip(GRID) {
            assert_ne!(m.xforms, f.xforms, "{k:?} changed nothing");
        }
        let c = mutate(&f, Mutation::Colours, 0.5, 1, &opts);
        for (x, y) in c.xforms.iter().zip(&f.xforms) {
            assert_eq!(x.coefs, y.coefs, "colours leave the triangles");
        }
        let add = mutate(&f, Mutation::AddTransform, 0.5, 1, &opts);
        assert_eq!(add.xforms.len(), f.xforms.len() + 1);
        let mut two = f.clone();
        two.xforms.truncate(2);
        assert_eq!(
            mutate(&two, Mutation::RemoveTransform, 0.5, 1, &opts)
                .xforms
                .len(),
            2
        );
    }

    #[test]
    fn distance_scales_the_change() {
        let f = base();
        let opts = RandomOptions::default();
        let change = |d: f64| -> f64 {
            let m = mutate(&f, Mutation::Coefficients, d, 3, &opts);
            m.xforms
                .iter()
                .zip(&f.xforms)
                .map(|(x, y)| {
                    x.coefs
                        .to_coefs()
                        .iter()
                        .zip(y.coefs.to_coefs())
                        .map(|(p, q)| (p - q).abs())
                        .fold(0.0, f64::max)
                })
                .fold(0.0, f64::max)
        };
        let (small, large) = (change(0.05), change(1.0));
        assert!(small <= 0.025 + 1e-12, "{small}");
        assert!(large > small, "{large} vs {small}");
    }
}
