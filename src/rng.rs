//! The seeded random generator of ugnis: Xoshiro256++ from `rand`, with the draws the chaos
//! game, random flames, gradients from images and procedural textures need.

use rand::rngs::Xoshiro256PlusPlus;
use rand::{Rng, SeedableRng};

/// A seeded Xoshiro256++ with the draws the chaos game needs.
#[derive(Clone, Debug)]
pub struct FastRng(Xoshiro256PlusPlus);

impl FastRng {
    /// The generator seeded from `seed`.
    pub fn new(seed: u64) -> Self {
        Self(Xoshiro256PlusPlus::seed_from_u64(seed))
    }

    /// A generator for stream `stream` of master seed `seed` (decorrelated by SplitMix64).
    pub fn for_stream(seed: u64, stream: u64) -> Self {
        let mut z = seed ^ stream.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        Self::new(z ^ (z >> 31))
    }

    /// 64 random bits.
    #[inline(always)]
    pub fn u64(&mut self) -> u64 {
        self.0.next_u64()
    }

    /// 32 random bits.
    #[inline(always)]
    pub fn u32(&mut self) -> u32 {
        (self.0.next_u64() >> 32) as u32
    }

    /// Uniform in [0, 1) with 53 random bits.
    #[inline(always)]
    pub fn f01(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [-1, 1).
    #[inline(always)]
    pub fn f11(&mut self) -> f64 {
        self.f01() * 2.0 - 1.0
    }

    /// A fair coin.
    #[inline(always)]
    pub fn bit(&mut self) -> bool {
        (self.0.next_u64() >> 63) != 0
    }

    /// Uniform integer in 0..n (n > 0).
    #[inline(always)]
    pub fn below(&mut self, n: u64) -> u64 {
        ((self.u64() as u128 * n as u128) >> 64) as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeded_streams_are_reproducible_and_distinct() {
        let mut a = FastRng::for_stream(7, 3);
        let mut b = FastRng::for_stream(7, 3);
        let mut c = FastRng::for_stream(7, 4);
        let va: Vec<u64> = (0..8).map(|_| a.u64()).collect();
        let vb: Vec<u64> = (0..8).map(|_| b.u64()).collect();
        let vc: Vec<u64> = (0..8).map(|_| c.u64()).collect();
        assert_eq!(va, vb);
        assert_ne!(va, vc);
    }

    #[test]
    fn uniform_ranges() {
        let mut r = FastRng::new(1);
        let mut sum = 0.0;
        for _ in 0..100_000 {
            let v = r.f01();
            assert!((0.0..1.0).contains(&v));
            sum += v;
            assert!(r.below(7) < 7);
        }
        assert!((sum / 100_000.0 - 0.5).abs() < 0.01);
    }
}
