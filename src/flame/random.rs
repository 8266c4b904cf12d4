//! Random flames: Fraktalai's RandomIFS with flam3-genome's quality
//! check, reproducible from a seed.

use crate::flame::chaos::{BAD_LIMIT, Chaos, FUSE};
use crate::flame::framing;
use crate::flame::model::{Affine, Flame, FlameKind, NewFlame, Var, Xform};
use crate::flame::render::{RenderOptions, render};
use crate::flame::rng::FastRng;
use crate::flame::symmetry::{add_symmetry, random_symmetry};
use crate::flame::variations::{self, Form, VarId};
use crate::gradient::Gradient;

/// How variations are chosen for a random flame.
#[derive(Clone, Debug, PartialEq)]
pub enum VariationMode {
    /// One variation, weight 1, for every xform (the Variations menu choice).
    Single(VarId),
    /// One of the seven variations of Fraktalai per xform, drawn with these probabilities.
    Random([f64; 7]),
    /// A random mix of 2–3 variations per xform from the 99 (weights normalised to 1).
    Mix,
    /// Variations drawn from a list (the "variations filter" of Fractorium): every xform gets
    /// one or two different entries of the list, weights normalised to 1; an xform whose
    /// entries are all `pre_`/`post_` forms also gets linear, so that it has a main
    /// variation. An empty list gives linear.
    FromList(Vec<(VarId, Form)>),
}

impl Default for VariationMode {
    fn default() -> Self {
        VariationMode::Random([1.0 / 7.0; 7])
    }
}

/// Symmetry requested for random flames.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SymmetryMode {
    /// No symmetry.
    #[default]
    None,
    /// flam3's random order.
    Random,
    /// A fixed order k (k < 0 adds a mirror).
    Order(i32),
}

/// The Random options and generator switches.
#[derive(Clone, Debug, PartialEq)]
pub struct RandomOptions {
    /// Fewest xforms of a flame (at least 1).
    pub min_xforms: usize,
    /// Most xforms of a flame (raised to `min_xforms` if below it).
    pub max_xforms: usize,
    /// Which variations the xforms get.
    pub variations: VariationMode,
    /// Symmetry added to the flame.
    pub symmetry: SymmetryMode,
    /// Probability of a random post transform per xform.
    pub post_probability: f64,
    /// Probability of a final xform.
    pub final_probability: f64,
    /// Gradients to draw from when `random_gradient` is on (the library); empty: built-ins.
    pub gradients: Vec<Gradient>,
    /// Give the flame a random gradient (turned by a random amount); off: keep the default.
    pub random_gradient: bool,
    /// Candidates tried before keeping the last one (flam3-genome uses 10).
    pub max_attempts: usize,
}

impl Default for RandomOptions {
    fn default() -> Self {
        RandomOptions {
            min_xforms: 2,
            max_xforms: 6,
            variations: VariationMode::default(),
            symmetry: SymmetryMode::None,
            post_probability: 0.0,
            final_probability: 0.0,
            gradients: Vec::new(),
            random_gradient: true,
            max_attempts: 10,
        }
    }
}

/// The outcome of generating a flame.
#[derive(Clone, Debug)]
pub struct Generated {
    /// The flame kept, framed for its size.
    pub flame: Flame,
    /// Candidates tried (1 = the first passed).
    pub attempts: usize,
    /// Whether the kept candidate passed the quality check.
    pub passed: bool,
}

fn random_affine(rng: &mut FastRng) -> Affine {
    Affine::new(
        rng.f11(),
        rng.f11(),
        rng.f11(),
        rng.f11(),
        rng.f11(),
        rng.f11(),
    )
}

fn pick_weighted(p: &[f64], rng: &mut FastRng) -> usize {
    let total: f64 = p.iter().sum();
    let mut r = rng.f01() * total;
    for (i, v) in p.iter().enumerate() {
        r -= v;
        if r < 0.0 {
            return i;
        }
    }
    p.len() - 1
}

/// Random parameters for parametric variations, in ranges that tend to give pictures.
fn random_params(id: VarId, rng: &mut FastRng) -> Vec<f64> {
    let info = variations::info(id);
    let mut p = info.defaults();
    match id {
        variations::BLOB => {
            p = vec![
                0.2 + 0.5 * rng.f01(),
                0.8 + 0.6 * rng.f01(),
                (2.0 + 5.0 * rng.f01()).floor(),
            ]
        }
        variations::PDJ => p = (0..4).map(|_| 3.0 * rng.f11()).collect(),
        variations::FAN2 => p = vec![rng.f11(), rng.f11()],
        variations::RINGS2 => p = vec![rng.f01()],
        variations::PERSPECTIVE => p = vec![rng.f01(), 1.0 + 2.0 * rng.f01()],
        variations::JULIAN | variations::JULIASCOPE => {
            p = vec![
                (2.0 + 5.0 * rng.f01()).floor() * if rng.bit() { 1.0 } else { -1.0 },
                rng.f11(),
            ]
        }
        variations::CURL => p = vec![rng.f11(), 0.5 * rng.f11()],
        variations::RECTANGLES => p = vec![rng.f01() + 0.1, rng.f01() + 0.1],
        variations::NGON => {
            p = vec![
                (3.0 + 5.0 * rng.f01()).floor(),
                2.0 * rng.f11(),
                rng.f01(),
                rng.f01(),
            ]
        }
        variations::DISC2 => p = vec![rng.f11(), 3.0 * rng.f11()],
        variations::BENT2 => p = vec![2.0 * rng.f11(), 2.0 * rng.f11()],
        variations::PIE => {
            p = vec![
                (3.0 + 8.0 * rng.f01()).floor(),
                2.0 * rng.f01(),
                0.2 + 0.8 * rng.f01(),
            ]
        }
        _ => {}
    }
    p
}

/// The variation terms of one random xform in the given mode.
pub fn random_variations(mode: &VariationMode, rng: &mut FastRng) -> Vec<Var> {
    match mode {
        VariationMode::Single(id) => vec![Var {
            params: random_params(*id, rng),
            ..Var::new(*id, 1.0)
        }],
        VariationMode::Random(p) => {
            let id = variations::THESIS_SEVEN[pick_weighted(p, rng)];
            vec![Var::new(id, 1.0)]
        }
        VariationMode::Mix => {
            let k = 2 + rng.below(2) as usize;
            let mut vs: Vec<Var> = Vec::new();
            while vs.len() < k {
                let id = rng.below(variations::FLAM3_COUNT as u64) as VarId;
                // pre_blur alone gives no picture; keep it out of mixes.
                if id == variations::PRE_BLUR || vs.iter().any(|v| v.id == id) {
                    continue;
                }
                vs.push(Var {
                    params: random_params(id, rng),
                    ..Var::new(id, rng.f01() + 0.05)
                });
            }
            let s: f64 = vs.iter().map(|v| v.weight).sum();
            vs.iter_mut().for_each(|v| v.weight /= s);
            vs
        }
        VariationMode::FromList(list) => {
            let mut distinct: Vec<(VarId, Form)> = Vec::new();
            for e in list {
                if !distinct.contains(e) {
                    distinct.push(*e);
                }
            }
            if distinct.is_empty() {
                return vec![Var::new(variations::LINEAR, 1.0)];
            }
            let k = if distinct.len() > 1 && rng.bit() {
                2
            } else {
                1
            };
            let mut vs: Vec<Var> = Vec::new();
            while vs.len() < k {
                let (id, form) = distinct[rng.below(distinct.len() as u64) as usize];
                if vs.iter().any(|v| v.id == id && v.form == form) {
                    continue;
                }
                vs.push(Var {
                    params: random_params(id, rng),
                    ..Var::with_form(id, form, rng.f01() + 0.05)
                });
            }
            if vs.iter().all(|v| v.form != Form::Regular) {
                vs.push(Var::new(variations::LINEAR, 1.0));
            }
            let s: f64 = vs.iter().map(|v| v.weight).sum();
            vs.iter_mut().for_each(|v| v.weight /= s);
            vs
        }
    }
}

/// One random candidate (coefficients, variations, colours, weights, gradient, symmetry), not
/// yet tested or framed.
pub fn candidate(n: usize, opts: &RandomOptions, defaults: &NewFlame, rng: &mut FastRng) -> Flame {
    let mut f = defaults.flame();
    f.kind = FlameKind::Flame;
    for i in 0..n {
        let color = if n > 1 {
            i as f64 / (n - 1) as f64
        } else {
            0.0
        };
        let mut x = Xform::linear(random_affine(rng), 1.0, color);
        x.vars = random_variations(&opts.variations, rng);
        if rng.f01() < opts.post_probability {
            x.post = random_affine(rng);
        }
        f.xforms.push(x);
    }
    f.set_determinant_weights();
    if rng.f01() < opts.final_probability {
        let mut fx = Xform::linear(random_affine(rng), 0.0, rng.f01());
        fx.color_speed = 0.0;
        let id = variations::THESIS_SEVEN[rng.below(7) as usize];
        fx.vars = vec![Var::new(id, 1.0)];
        f.final_xform = Some(fx);
    }
    if opts.random_gradient {
        let lib = if opts.gradients.is_empty() {
            crate::gradient::builtin()
        } else {
            opts.gradients.clone()
        };
        let g = &lib[rng.below(lib.len() as u64) as usize];
        f.palette = g.clone();
        // A random rotation makes the library go further.
        let k = rng.below(256) as i32;
        f.palette = f.palette.rotated(k);
        f.palette.name = g.name.clone();
    }
    match opts.symmetry {
        SymmetryMode::None => {}
        SymmetryMode::Random => add_symmetry(&mut f, random_symmetry(rng)),
        SymmetryMode::Order(k) => add_symmetry(&mut f, k),
    }
    f
}

/// Pre-check after Apophysis `BlowsUp`: 15 fuse + 5000 iterations from a
/// random point; reject on a bad value or a span above 1000 world units.
pub fn blows_up(f: &Flame, rng: &mut FastRng) -> bool {
    let Ok(chaos) = Chaos::new(f) else {
        return true;
    };
    let mut p = Chaos::start_point(rng);
    let (mut xmin, mut xmax, mut ymin, mut ymax) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    let mut last = None;
    for k in -FUSE..5000 {
        let i = chaos.choose(last, rng);
        let (np, bad) = chaos.xforms[i].apply(p, rng);
        if bad || !(np.x.abs() <= BAD_LIMIT && np.y.abs() <= BAD_LIMIT) {
            return true;
        }
        (p, last) = (np, Some(i));
        let (x, y) = (p.x, p.y);
        if k >= 0 {
            xmin = xmin.min(x);
            xmax = xmax.max(x);
            ymin = ymin.min(y);
            ymax = ymax.max(y);
        }
    }
    xmax - xmin > 1000.0 || ymax - ymin > 1000.0
}

/// The flam3-genome render test on an already framed 128×128 copy: accept iff
/// avg ≥ 20, black ≥ 1 % and white ≤ 5 %.
pub fn passes_render_test(f: &Flame) -> bool {
    let mut t = f.clone();
    t.width = 128;
    t.height = 128;
    framing::apply_auto_frame(&mut t);
    t.quality = 1.0;
    t.supersample = 1;
    t.filter = 0.5;
    t.filter_shape = crate::flame::FilterShape::Gaussian;
    t.estimator_radius = 0.0;
    t.brightness = 4.0;
    t.gamma = 4.0;
    t.vibrancy = 1.0;
    t.gamma_threshold = 0.01;
    t.highlight_power = 1.0;
    t.background = [0.0; 3];
    t.contrast = 1.0;
    let o = RenderOptions {
        seed: 1,
        threads: 1,
        ..RenderOptions::default()
    };
    let Ok(img) = render(&t, &o) else {
        return false;
    };
    let img = img.to_rgb8();
    let n = (128 * 128) as f64;
    let (mut sum, mut black, mut white) = (0.0, 0.0, 0.0);
    for p in img.pixels() {
        let [r, g, b] = p.0;
        sum += (r as f64 + g as f64 + b as f64) / 3.0;
        if r == 0 && g == 0 && b == 0 {
            black += 1.0;
        }
        if r == 255 && g == 255 && b == 255 {
            white += 1.0;
        }
    }
    sum / n >= 20.0 && black / n >= 0.01 && white / n <= 0.05
}

/// Generate one random flame from a seed: the xform count stays fixed over the
/// retries, up to `max_attempts` candidates; the survivor is framed for its size.
pub fn generate(seed: u64, opts: &RandomOptions, defaults: &NewFlame) -> Generated {
    let mut rng = FastRng::new(seed);
    let lo = opts.min_xforms.max(1);
    let hi = opts.max_xforms.max(lo);
    let n = lo + rng.below((hi - lo + 1) as u64) as usize;
    let mut last = None;
    for attempt in 1..=opts.max_attempts.max(1) {
        let f = candidate(n, opts, defaults, &mut rng);
        let ok = !blows_up(&f, &mut rng) && passes_render_test(&f);
        if ok || attempt == opts.max_attempts.max(1) {
            last = Some((f, attempt, ok));
            if ok {
                break;
            }
        }
    }
    let (mut flame, attempts, passed) = last.expect("at least one attempt");
    framing::apply_auto_frame(&mut flame);
    flame.seed = Some(seed);
    Generated {
        flame,
        attempts,
        passed,
    }
}

/// Seed of flame `i` of a batch with master seed `seed`.
pub fn batch_seed(seed: u64, i: usize) -> u64 {
    FastRng::for_stream(seed, i as u64).u64()
}

/// A random batch: `count` flames named random-001…, generated in parallel;
/// each stores its own seed (`ugnis_seed`) so that it can be regenerated.
pub fn generate_batch(
    count: usize,
    seed: u64,
    opts: &RandomOptions,
    defaults: &NewFlame,
) -> Vec<Flame> {
    use rayon::prelude::*;
    (0..count)
        .into_par_iter()
        .map(|i| {
            let mut f = generate(batch_seed(seed, i), opts, defaults).flame;
            f.name = format!("random-{:03}", i + 1);
            f
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_flame() {
        let o = RandomOptions::default();
        let d = NewFlame {
            width: 64,
            height: 48,
            ..NewFlame::default()
        };
        let a = generate(42, &o, &d);
        let b = generate(42, &o, &d);
        assert_eq!(a.flame, b.flame);
        assert_ne!(a.flame, generate(43, &o, &d).flame);
        assert_eq!(a.flame.seed, Some(42));
        assert!(a.flame.has_camera);
    }

    #[test]
    fn xform_counts_and_variation_modes() {
        let d = NewFlame::default();
        for seed in 0..30 {
            let o = RandomOptions {
                min_xforms: 3,
                max_xforms: 4,
                variations: VariationMode::Single(variations::SWIRL),
                max_attempts: 1,
                ..RandomOptions::default()
            };
            let mut rng = FastRng::new(seed);
            let f = candidate(3 + rng.below(2) as usize, &o, &d, &mut rng);
            assert!((3..=4).contains(&f.xforms.len()));
            assert!(
                f.xforms
                    .iter()
                    .all(|x| x.vars.len() == 1 && x.vars[0].id == variations::SWIRL)
            );
            let ws: f64 = f.xforms.iter().map(|x| x.weight).sum();
            assert!((ws - 1.0).abs() < 1e-12);
        }
        let o = RandomOptions {
            variations: VariationMode::Mix,
            ..RandomOptions::default()
        };
        let mut rng = FastRng::new(5);
        let f = candidate(4, &o, &d, &mut rng);
        for x in &f.xforms {
            assert!((2..=3).contains(&x.vars.len()));
            let s: f64 = x.vars.iter().map(|v| v.weight).sum();
            assert!((s - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn a_variation_list_is_all_random_flames_use() {
        let list = vec![
            (variations::SWIRL, Form::Regular),
            (variations::JULIA, Form::Regular),
            (variations::by_name("spherical").unwrap(), Form::Pre),
        ];
        let o = RandomOptions {
            variations: VariationMode::FromList(list.clone()),
            ..RandomOptions::default()
        };
        let mut seen = std::collections::HashSet::new();
        let mut rng = FastRng::new(9);
        for _ in 0..40 {
            let f = candidate(4, &o, &NewFlame::default(), &mut rng);
            for x in &f.xforms {
                assert!(x.vars.iter().any(|v| v.form == Form::Regular));
                for v in &x.vars {
                    let e = (v.id, v.form);
                    assert!(
                        list.contains(&e) || e == (variations::LINEAR, Form::Regular),
                        "{e:?}"
                    );
                    seen.insert(e);
                }
                let s: f64 = x.vars.iter().map(|v| v.weight).sum();
                assert!((s - 1.0).abs() < 1e-12);
            }
        }
        assert!(list.iter().all(|e| seen.contains(e)), "every entry is used");
        let empty = VariationMode::FromList(Vec::new());
        let v = random_variations(&empty, &mut rng);
        assert_eq!((v.len(), v[0].id), (1, variations::LINEAR));
    }

    #[test]
    fn quality_check_rejects_empty_and_blown_out() {
        // A flame that collapses to one point is nearly empty.
        let mut f = NewFlame::default().flame();
        f.xforms = vec![
            Xform::linear(Affine::new(0.1, 0.0, 0.0, 0.1, 0.0, 0.0), 1.0, 0.0),
            Xform::linear(Affine::new(0.1, 0.0, 0.0, 0.1, 0.0, 0.0), 1.0, 1.0),
        ];
        assert!(!passes_render_test(&f));
        // An expanding map blows up.
        let mut g = NewFlame::default().flame();
        g.xforms = vec![Xform::linear(
            Affine::new(3.0, 0.0, 0.0, 3.0, 1.0, 0.0),
            1.0,
            0.0,
        )];
        assert!(blows_up(&g, &mut FastRng::new(1)));
        // A Sierpinski triangle in a light gradient passes.
        let mut s = NewFlame::default().flame();
        s.palette = crate::gradient::builtin_named("ice").unwrap().reversed();
        for (e, ff) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)] {
            s.xforms.push(Xform::linear(
                Affine::new(0.5, 0.0, 0.0, 0.5, e, ff),
                1.0,
                e,
            ));
        }
        assert!(!blows_up(&s, &mut FastRng::new(1)));
        assert!(passes_render_test(&s));
    }
}
