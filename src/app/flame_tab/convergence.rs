//! When the live preview is clean enough to stop: an estimate of the grain left in a picture
//! (8-bit levels, root mean square over the channels of the pixels that show the flame).
//!
//! The renderer's threads fill histograms of their own from independent random streams, so
//! the even and the odd threads' histograms are two independent renders of about half the
//! samples each. Developed apart, each is the picture plus noise of variance σ²/nₖ (σ² the
//! variance one sample adds to a pixel); their difference has variance σ²·(1/n₁ + 1/n₂),
//! while the whole picture's noise is σ²/(n₁ + n₂). So the whole picture's noise is the root
//! mean square of the difference times √(s₁·s₂), sₖ the halves' shares — for equal halves,
//! half the difference: the two-buffer estimate of Monte Carlo renderers.
//!
//! Grain is not all that changes as samples are added: density estimation blurs sparse areas
//! with kernels that narrow as the density grows, so a picture keeps sharpening long after its
//! grain is gone (and a blurred early picture has little grain). The preview therefore also
//! has a least quality before it may stop. With one thread there are no halves: the picture
//! is compared with an earlier one of the same render instead ([`noise_between`]), which
//! counts that sharpening as noise too and so refines longer.
//!
//! Only pixels that show the flame in either picture count: a small flame on a wide
//! background would otherwise look clean long before it is.

/// Root mean square difference of two RGB8 pictures over the pixels that are not background
/// in either; `None` when the sizes differ, 0 when every pixel is background.
fn rms_difference(a: &[u8], b: &[u8], background: [u8; 3]) -> Option<f64> {
    if a.len() != b.len() || !a.len().is_multiple_of(3) {
        return None;
    }
    let is_background = |p: &[u8]| {
        p.iter()
            .zip(background)
            .all(|(x, y)| x.abs_diff(y) <= BACKGROUND_SLACK)
    };
    let (mut sum, mut count) = (0.0f64, 0u64);
    for (p, q) in a.chunks_exact(3).zip(b.chunks_exact(3)) {
        if is_background(p) && is_background(q) {
            continue;
        }
        for k in 0..3 {
            let d = p[k] as f64 - q[k] as f64;
            sum += d * d;
        }
        count += 1;
    }
    if count == 0 {
        return Some(0.0);
    }
    Some((sum / (3 * count) as f64).sqrt())
}

/// The noise of the whole picture from pictures of two independent parts of its samples
/// (RGB8, same size) and their shares of the samples.
pub fn noise_of_halves(a: &[u8], b: &[u8], shares: [f64; 2], background: [u8; 3]) -> Option<f64> {
    let [s1, s2] = shares;
    if !(s1 > 0.0 && s2 > 0.0) {
        return None;
    }
    Some(rms_difference(a, b, background)? * (s1 * s2).sqrt())
}

/// The noise of `now` estimated from the difference to an earlier picture `before` of the
/// same render; `n_before` and `n_now` are their sample counts. A picture of `m` samples is
/// the average of that of its first `n` and that of the `m − n` after them: the difference
/// has variance σ²·(m − n)/(m·n) and the newer picture's noise is σ²/m, so the noise is the
/// root mean square of the difference times √(n/(m − n)). `None` when the counts do not grow
/// or the sizes differ.
pub fn noise_between(
    before: &[u8],
    now: &[u8],
    n_before: u64,
    n_now: u64,
    background: [u8; 3],
) -> Option<f64> {
    if n_now <= n_before {
        return None;
    }
    let rms = rms_difference(before, now, background)?;
    Some(rms * (n_before as f64 / (n_now - n_before) as f64).sqrt())
}

/// Levels a pixel may differ from the background colour and still count as background (the
/// tone map's rounding).
const BACKGROUND_SLACK: u8 = 1;

/// The quality a clean picture needs: at least `least`; noise falls as 1/√samples, so noise
/// `noise` measured at quality `measured_at` needs `measured_at·(noise/target)²`; at most
/// `most`.
pub fn quality_needed(least: f64, most: f64, measured: Option<(f64, f64)>, target: f64) -> f64 {
    let by_noise = match measured {
        Some((q, n)) if n > target && target > 0.0 => q * (n / target).powi(2),
        _ => 0.0,
    };
    least.max(by_noise).min(most)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::rng::FastRng;

    /// A picture of a grey disc on black: each pixel of the disc the mean of `n` noisy draws.
    fn picture(n: u64, rng: &mut FastRng, sigma: f64) -> Vec<u8> {
        let mut out = Vec::new();
        for y in 0..64 {
            for x in 0..64 {
                let inside = (x as f64 - 32.0).hypot(y as f64 - 32.0) < 20.0;
                for _ in 0..3 {
                    if !inside {
                        out.push(0);
                        continue;
                    }
                    // The mean of n draws of variance sigma²: variance sigma²/n.
                    let mut s = 0.0;
                    for _ in 0..n {
                        // Uniform on [−√3, √3]: variance 1.
                        s += (rng.f01() * 2.0 - 1.0) * 3f64.sqrt();
                    }
                    let v = 128.0 + sigma * s / n as f64;
                    out.push(v.round().clamp(0.0, 255.0) as u8);
                }
            }
        }
        out
    }

    #[test]
    fn the_estimate_follows_the_true_noise() {
        let mut rng = FastRng::new(3);
        let sigma = 40.0;
        // Independent pictures stand for the first half and the whole render: the whole is
        // the average of the halves.
        let a = picture(16, &mut rng, sigma);
        let b = picture(16, &mut rng, sigma);
        let whole: Vec<u8> = a
            .iter()
            .zip(&b)
            .map(|(x, y)| ((*x as f64 + *y as f64) / 2.0).round() as u8)
            .collect();
        let est = noise_between(&a, &whole, 16, 32, [0, 0, 0]).unwrap();
        let truth = sigma / 32f64.sqrt();
        assert!(
            (est / truth - 1.0).abs() < 0.15,
            "estimate {est:.3}, truth {truth:.3}"
        );
        // The black background does not dilute it: a picture twice as wide with the same disc
        // gives the same estimate.
        let pad = |p: &[u8]| {
            p.chunks(64 * 3)
                .flat_map(|row| row.iter().copied().chain(std::iter::repeat_n(0, 64 * 3)))
                .collect::<Vec<u8>>()
        };
        let est2 = noise_between(&pad(&a), &pad(&whole), 16, 32, [0, 0, 0]).unwrap();
        assert!((est2 - est).abs() < 1e-9);
    }

    #[test]
    fn unequal_steps_and_degenerate_input() {
        let mut rng = FastRng::new(9);
        let sigma = 40.0;
        // n = 8 samples, then 24 more: the whole is (8·a + 24·b)/32.
        let a = picture(8, &mut rng, sigma);
        let b = picture(24, &mut rng, sigma);
        let whole: Vec<u8> = a
            .iter()
            .zip(&b)
            .map(|(x, y)| ((8.0 * *x as f64 + 24.0 * *y as f64) / 32.0).round() as u8)
            .collect();
        let est = noise_between(&a, &whole, 8, 32, [0, 0, 0]).unwrap();
        let truth = sigma / 32f64.sqrt();
        assert!((est / truth - 1.0).abs() < 0.15, "{est} vs {truth}");
        assert_eq!(noise_between(&a, &whole, 32, 32, [0, 0, 0]), None);
        assert_eq!(noise_between(&a, &whole[3..], 8, 32, [0, 0, 0]), None);
        let black = vec![0u8; 30];
        assert_eq!(noise_between(&black, &black, 1, 2, [0, 0, 0]), Some(0.0));
    }

    #[test]
    fn the_quality_needed_follows_the_square_root_law() {
        // Clean already: the least quality decides.
        assert_eq!(quality_needed(100.0, 2000.0, Some((50.0, 0.5)), 1.0), 100.0);
        // Twice the target's noise: four times the samples.
        assert_eq!(
            quality_needed(100.0, 2000.0, Some((200.0, 2.0)), 1.0),
            800.0
        );
        assert_eq!(
            quality_needed(100.0, 2000.0, Some((1000.0, 4.0)), 1.0),
            2000.0
        );
        assert_eq!(quality_needed(100.0, 2000.0, None, 1.0), 100.0);
    }

    #[test]
    fn halves_give_the_noise_of_their_sum() {
        let mut rng = FastRng::new(5);
        let sigma = 40.0;
        let a = picture(16, &mut rng, sigma);
        let b = picture(16, &mut rng, sigma);
        let est = noise_of_halves(&a, &b, [0.5, 0.5], [0, 0, 0]).unwrap();
        let truth = sigma / 32f64.sqrt();
        assert!((est / truth - 1.0).abs() < 0.15, "{est} vs {truth}");
        assert_eq!(noise_of_halves(&a, &b, [0.0, 1.0], [0, 0, 0]), None);
    }

    /// The renderer's halves on a real flame: without density estimation the grain falls as
    /// 1/√samples, so four times the samples halve it.
    #[test]
    fn the_renderers_halves_follow_the_square_root_law() {
        use crate::flame::render::{RenderOptions, Renderer};
        use std::sync::atomic::AtomicBool;
        let mut f = crate::io::read_flames(
            std::path::Path::new(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/examples/orchid.flame"
            )),
            &Default::default(),
        )
        .unwrap()
        .value
        .remove(0);
        f.resize_keep_framing(96, 72);
        f.estimator_radius = 0.0;
        f.quality = 64.0;
        let opts = RenderOptions {
            seed: 3,
            threads: 2,
            ..RenderOptions::default()
        };
        let mut r = Renderer::new(&f, &opts).unwrap();
        let never = AtomicBool::new(false);
        let noise = |r: &Renderer| {
            let [(a, sa), (b, sb)] = r.preview_halves(&never).unwrap();
            let bg = [0, 0, 0];
            noise_of_halves(a.to_rgb8().as_raw(), b.to_rgb8().as_raw(), [sa, sb], bg).unwrap()
        };
        r.run(r.total_samples() / 4, &never);
        let early = noise(&r);
        r.run(r.total_samples(), &never);
        let late = noise(&r);
        let ratio = late / early;
        assert!(
            (0.38..0.65).contains(&ratio),
            "{early:.2} → {late:.2}: {ratio:.2}"
        );
        let one = Renderer::new(&f, &RenderOptions { threads: 1, ..opts }).unwrap();
        assert!(one.preview_halves(&never).is_none());
    }
}
