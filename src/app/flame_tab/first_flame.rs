//! The first picture a new user sees: a random flame in a colourful gradient of the library
//! that passes the quality check and fills a good part of the picture with colour — the best
//! of a few tries, reproducible from the start seed.

use crate::app::options::Options;
use crate::flame::Flame;
use crate::flame::random::{self, VariationMode};
use crate::flame::render::{RenderOptions, render};
use crate::gradient::{self, Gradient, rgb_to_hsv};
use crate::rng::FastRng;

/// Candidates tried before keeping the most colourful one.
const TRIES: u64 = 8;
/// A candidate with this share of coloured pixels is kept at once.
pub const GOOD_SHARE: f64 = 0.5;

/// Mean HSV saturation of a gradient's entries, weighted by their brightness (a dark
/// saturated colour hardly shows).
pub fn colourfulness(g: &Gradient) -> f64 {
    let (mut s, mut w) = (0.0, 0.0);
    for c in &g.colors {
        let [_, sat, v] = rgb_to_hsv([c[0], c[1], c[2]]);
        s += sat * v;
        w += v;
    }
    if w > 0.0 { s / w } else { 0.0 }
}

/// The library gradients with clear colours (no greys, no pale pastels).
pub fn colourful_gradients() -> Vec<Gradient> {
    gradient::builtin()
        .into_iter()
        .filter(|g| colourfulness(g) >= 0.45)
        .collect()
}

/// Share of the lit pixels of a small render that are clearly coloured (channels differ by
/// at least 48 of 255); 0 when less than 5 % of the picture is lit.
pub fn colour_share(f: &Flame) -> f64 {
    let mut t = f.clone();
    t.resize_keep_framing(96, 72);
    t.quality = 5.0;
    let o = RenderOptions {
        seed: 1,
        threads: 1,
        ..RenderOptions::default()
    };
    let Ok(img) = render(&t, &o) else {
        return 0.0;
    };
    let img = img.to_rgb8();
    let (mut lit, mut coloured) = (0u32, 0u32);
    for p in img.pixels() {
        let [r, g, b] = p.0;
        let (hi, lo) = (r.max(g).max(b), r.min(g).min(b));
        if hi >= 24 {
            lit += 1;
            if hi - lo >= 48 {
                coloured += 1;
            }
        }
    }
    let n = img.width() * img.height();
    if lit * 20 < n {
        return 0.0;
    }
    coloured as f64 / lit as f64
}

/// The start flame for `seed`.
pub fn striking_flame(seed: u64, options: &Options) -> Flame {
    let mut opts = options.random_options(VariationMode::Random(options.probabilities));
    opts.random_gradient = true;
    opts.gradients = colourful_gradients();
    let defaults = options.new_flame();
    let mut best: Option<(f64, Flame)> = None;
    for k in 0..TRIES {
        let g = random::generate(FastRng::for_stream(seed, k).u64(), &opts, &defaults);
        if !g.passed {
            continue;
        }
        let share = colour_share(&g.flame);
        if share >= GOOD_SHARE {
            return g.flame;
        }
        if best.as_ref().is_none_or(|(s, _)| share > *s) {
            best = Some((share, g.flame));
        }
    }
    match best {
        Some((_, f)) => f,
        None => random::generate(seed, &opts, &defaults).flame,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grey_gradients_are_left_out_of_the_first_start() {
        let names: Vec<String> = colourful_gradients().into_iter().map(|g| g.name).collect();
        assert!(names.len() >= 8, "{names:?}");
        for grey in ["grey", "steel"] {
            assert!(!names.iter().any(|n| n == grey), "{grey} is not colourful");
        }
        assert!(colourfulness(&Gradient::grey_ramp()) < 1e-12);
    }
}
