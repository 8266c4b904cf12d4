//! Gradients from pictures: the dominant colours of an image found by k-means in Oklab, put in
//! the order of a short path and spread over the table by their share of the picture.

use super::color::{oklab_to_srgb, srgb_to_oklab};
use super::table::{Gradient, Stop};
use crate::rng::FastRng;

/// Squared distance of two colours.
fn dist2(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)
}

/// A gradient from the colours of an image.
///
/// Method: up to 20 000 pixels are sampled; k-means (k ≤ 16, k-means++ seeding, seeded
/// generator) finds the dominant colours in the perceptual Oklab space; the colours are put in
/// the order of a short path (start at the darkest, nearest neighbour, then 2-opt), so that
/// neighbours on the gradient look alike; each colour gets a share of the gradient growing with
/// the square root of its pixel count, and the 256 entries interpolate between them in Oklab.
/// The result is smooth, keeps the photograph's main colours and their proportions, and is the
/// same for the same image and seed.
pub fn from_pixels(name: &str, pixels: &[[u8; 3]], seed: u64) -> Gradient {
    if pixels.is_empty() {
        return Gradient::grey_ramp();
    }
    let mut rng = FastRng::new(seed);
    let samples = oklab_samples(pixels);
    let centres = seed_centres(&samples, &mut rng);
    let mut clusters = k_means(&samples, centres);
    order_as_path(&mut clusters);
    let keys = keys_by_share(&clusters);
    Gradient {
        name: name.to_string(),
        colors: interpolate_keys(&keys),
        stops: keys
            .iter()
            .map(|(p, c)| Stop {
                pos: *p,
                rgb: oklab_to_srgb(*c),
            })
            .collect(),
        map_entries: None,
    }
}

/// Up to about 20 000 of the pixels (every n-th), in Oklab.
fn oklab_samples(pixels: &[[u8; 3]]) -> Vec<[f64; 3]> {
    let step = (pixels.len() / 20_000).max(1);
    pixels
        .iter()
        .step_by(step)
        .map(|p| {
            srgb_to_oklab([
                p[0] as f64 / 255.0,
                p[1] as f64 / 255.0,
                p[2] as f64 / 255.0,
            ])
        })
        .collect()
}

/// k-means++ seeding: up to 16 starting centres, each further one drawn with a probability
/// growing with its squared distance to the nearest centre so far.
fn seed_centres(samples: &[[f64; 3]], rng: &mut FastRng) -> Vec<[f64; 3]> {
    let k = 16.min(samples.len());
    let mut centres: Vec<[f64; 3]> = vec![samples[rng.below(samples.len() as u64) as usize]];
    let mut d2: Vec<f64> = samples.iter().map(|s| dist2(s, &centres[0])).collect();
    while centres.len() < k {
        let total: f64 = d2.iter().sum();
        if total <= 1e-12 {
            break;
        }
        let mut r = rng.f01() * total;
        let mut pick = samples.len() - 1;
        for (i, d) in d2.iter().enumerate() {
            r -= d;
            if r <= 0.0 {
                pick = i;
                break;
            }
        }
        centres.push(samples[pick]);
        for (i, s) in samples.iter().enumerate() {
            d2[i] = d2[i].min(dist2(s, &centres[centres.len() - 1]));
        }
    }
    centres
}

/// 15 rounds of Lloyd's k-means from `centres`: the clusters that kept samples, as (centre,
/// number of samples).
fn k_means(samples: &[[f64; 3]], mut centres: Vec<[f64; 3]>) -> Vec<([f64; 3], usize)> {
    let mut counts = vec![0usize; centres.len()];
    for _ in 0..15 {
        let mut sum = vec![[0.0f64; 3]; centres.len()];
        counts.iter_mut().for_each(|c| *c = 0);
        for s in samples {
            let (best, _) = centres
                .iter()
                .enumerate()
                .map(|(i, c)| (i, dist2(s, c)))
                .fold((0, f64::MAX), |a, b| if b.1 < a.1 { b } else { a });
            counts[best] += 1;
            for j in 0..3 {
                sum[best][j] += s[j];
            }
        }
        for (i, c) in centres.iter_mut().enumerate() {
            if counts[i] > 0 {
                *c = sum[i].map(|v| v / counts[i] as f64);
            }
        }
    }
    centres
        .into_iter()
        .zip(counts)
        .filter(|c| c.1 > 0)
        .collect()
}

/// Put the clusters in the order of a short open path: darkest first, nearest neighbour,
/// then 2-opt.
fn order_as_path(cl: &mut [([f64; 3], usize)]) {
    let start = (0..cl.len())
        .min_by(|&a, &b| cl[a].0[0].total_cmp(&cl[b].0[0]))
        .unwrap_or(0);
    cl.swap(0, start);
    for i in 1..cl.len() {
        let prev = cl[i - 1].0;
        let j = (i..cl.len())
            .min_by(|&a, &b| dist2(&cl[a].0, &prev).total_cmp(&dist2(&cl[b].0, &prev)))
            .unwrap_or(i);
        cl.swap(i, j);
    }
    let d = |a: &[f64; 3], b: &[f64; 3]| dist2(a, b).sqrt();
    let mut improved = true;
    while improved {
        improved = false;
        for i in 1..cl.len().saturating_sub(1) {
            for j in i + 1..cl.len() {
                // Reverse cl[i..=j]: edges (i−1, i) and (j, j+1) become (i−1, j) and (i, j+1).
                let before = d(&cl[i - 1].0, &cl[i].0)
                    + if j + 1 < cl.len() {
                        d(&cl[j].0, &cl[j + 1].0)
                    } else {
                        0.0
                    };
                let after = d(&cl[i - 1].0, &cl[j].0)
                    + if j + 1 < cl.len() {
                        d(&cl[i].0, &cl[j + 1].0)
                    } else {
                        0.0
                    };
                if after + 1e-12 < before {
                    cl[i..=j].reverse();
                    improved = true;
                }
            }
        }
    }
}

/// Key colours (position in [0, 1], Oklab): each cluster in the middle of a share of the
/// gradient growing with the square root of its size.
fn keys_by_share(cl: &[([f64; 3], usize)]) -> Vec<(f64, [f64; 3])> {
    let widths: Vec<f64> = cl.iter().map(|c| (c.1 as f64).sqrt()).collect();
    let total: f64 = widths.iter().sum();
    let mut acc = 0.0;
    cl.iter()
        .zip(&widths)
        .map(|(c, w)| {
            let p = (acc + w / 2.0) / total;
            acc += w;
            (p, c.0)
        })
        .collect()
}

/// The 256 entries between the keys, interpolated in Oklab (the end colours held outside
/// them) and stored with 8 bits per channel.
fn interpolate_keys(keys: &[(f64, [f64; 3])]) -> Vec<[f64; 4]> {
    (0..256)
        .map(|i| {
            let t = i as f64 / 255.0;
            let lab = if t <= keys[0].0 {
                keys[0].1
            } else if t >= keys[keys.len() - 1].0 {
                keys[keys.len() - 1].1
            } else {
                let j = keys
                    .iter()
                    .rposition(|k| k.0 <= t)
                    .unwrap_or(0)
                    .min(keys.len() - 2);
                let (p0, c0) = keys[j];
                let (p1, c1) = keys[j + 1];
                let u = (t - p0) / (p1 - p0);
                [0, 1, 2].map(|k| c0[k] + (c1[k] - c0[k]) * u)
            };
            let rgb = oklab_to_srgb(lab).map(|v| (v * 255.0).round() / 255.0);
            [rgb[0], rgb[1], rgb[2], 1.0]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn photo_like_image_gives_its_colours_in_a_smooth_order() {
        // Sky blue 50 %, sand 30 %, dark green 20 %, with noise.
        let mut rng = crate::rng::FastRng::new(1);
        let mut px = Vec::new();
        for i in 0..10_000 {
            let base: [f64; 3] = if i % 10 < 5 {
                [110.0, 170.0, 230.0]
            } else if i % 10 < 8 {
                [220.0, 200.0, 150.0]
            } else {
                [30.0, 70.0, 30.0]
            };
            px.push(base.map(|v| (v + rng.f11() * 12.0).clamp(0.0, 255.0) as u8));
        }
        let g = from_pixels("photo", &px, 7);
        assert_eq!(g.colors.len(), 256);
        // Starts with the darkest colour (the green), contains blue and sand.
        let first = g.rgb8(0);
        assert!(first[1] > first[0] && first[1] < 110, "{first:?}");
        let has = |t: [u8; 3]| {
            (0..256).any(|i| {
                let c = g.rgb8(i);
                (0..3).all(|k| (c[k] as i32 - t[k] as i32).abs() < 25)
            })
        };
        assert!(has([110, 170, 230]) && has([220, 200, 150]));
        // Smooth: no jump between neighbours larger than a fifth of the colour range.
        for i in 1..256 {
            let (a, b) = (g.rgb8(i - 1), g.rgb8(i));
            assert!(
                (0..3).all(|k| (a[k] as i32 - b[k] as i32).abs() < 50),
                "{i}: {a:?} {b:?}"
            );
        }
        // Deterministic.
        assert_eq!(from_pixels("photo", &px, 7), g);
    }
}
