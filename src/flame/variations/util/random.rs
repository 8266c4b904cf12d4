//! Random draws as Fractorium and JWildfire make them, and the hashes that give cells and
//! lattice points their pseudo-random values.

use super::arith::fract;
use crate::flame::rng::FastRng;

/// Fractorium's bounded draw `Rand(size_t(n))` for a count held in a double: a uniform integer
/// in 0..k (as a double), k being `n` converted to an unsigned integer (truncated; negative
/// and NaN counts give 0). A count of 0 draws a full 32-bit number instead, as Fractorium's
/// generator does for `Rand(0)` — so that, for example, a julian power below 1 picks an
/// arbitrary root.
#[inline(always)]
pub fn rand_size(rng: &mut FastRng, n: f64) -> f64 {
    let k = n as u64;
    if k == 0 {
        rng.u32() as f64
    } else {
        rng.below(k) as f64
    }
}

/// Fractorium's `Crand()`: an integer in 0..=32766 (the range of C's `rand()` on some
/// platforms, minus one), as a double.
#[inline(always)]
pub fn crand(rng: &mut FastRng) -> f64 {
    rng.below(32767) as f64
}

/// George Marsaglia's multiply-with-carry generator pair (two 16-bit lag-1 MWC generators
/// concatenated), seeded and scaled as JWildfire's `MarsagliaRandomGenerator`: the seed is
/// shifted left by 16 bits into a 32-bit state, and each number is |r| / (2³¹ − 1) for the
/// signed 32-bit combination r. All arithmetic wraps as Java's `int` does. Variations that
/// build a structure from a seed (snow crystals, aggregates) use it so that a seed gives
/// JWildfire's shape.
#[derive(Clone, Debug)]
pub struct Mwc {
    u: i32,
    v: i32,
}

impl Mwc {
    pub fn new(seed: i64) -> Mwc {
        let s = seed.wrapping_shl(16) as i32;
        Mwc { u: s, v: s >> 16 }
    }

    /// The generator's state as one number (for the variations that carry it between calls).
    pub fn to_bits(&self) -> u64 {
        ((self.u as u32 as u64) << 32) | self.v as u32 as u64
    }

    /// The generator whose state [`Mwc::to_bits`] gave.
    pub fn from_bits(b: u64) -> Mwc {
        Mwc {
            u: (b >> 32) as u32 as i32,
            v: b as u32 as i32,
        }
    }

    /// The next number, in [0, 1].
    pub fn next_f64(&mut self) -> f64 {
        self.v = 36969i32
            .wrapping_mul(self.v & 65535)
            .wrapping_add(self.v >> 16);
        self.u = 18000i32
            .wrapping_mul(self.u & 65535)
            .wrapping_add(self.u >> 16);
        let bits = (self.v << 16).wrapping_add(self.u);
        (bits as f64 * (1.0 / 2147483647.0)).abs()
    }
}

/// The "shadertoy" hash: fract(sin(12.9898·x + 78.233·y + seed) · 43758.5453), a cheap
/// deterministic pseudo-random value in [0, 1) for a lattice point (x, y), popularised by
/// GPU shader code and used by Chaotica-style variations for random cells. NaN inputs give
/// NaN.
#[inline(always)]
pub fn sine_hash(x: f64, y: f64, seed: f64) -> f64 {
    fract((x * 12.9898 + y * 78.233 + seed).sin() * 43758.5453)
}

/// Thomas Wang's 32-bit integer hash (the `(a ^ 61) ^ (a >> 16)`, `a * 0x27d4eb2d` variant),
/// with C's wrapping 32-bit arithmetic and arithmetic right shifts, divided by `i32::MAX`: a
/// pseudo-random value in about [−1, 1] for an integer seed.
#[inline(always)]
pub fn wang_hash(seed: i32) -> f64 {
    let mut h = (seed ^ 61) ^ (seed >> 16);
    h = h.wrapping_add(h.wrapping_shl(3));
    h ^= h >> 4;
    h = h.wrapping_mul(0x27d4_eb2d);
    h ^= h >> 15;
    h as f64 / i32::MAX as f64
}

/// The classic integer lattice noise of Hugo Elias's "Perlin noise" tutorial: n ^= n << 13,
/// then the polynomial n·(n²·15731 + 789221) + 1376312589, in wrapping 32-bit arithmetic,
/// masked to 31 bits and scaled into [0, 1]. Two-dimensional lattices hash `x + 57·y`.
#[inline(always)]
pub fn lattice_noise(n: i32) -> f64 {
    let n = n ^ n.wrapping_shl(13);
    let h = n
        .wrapping_mul(n.wrapping_mul(n).wrapping_mul(15731).wrapping_add(789221))
        .wrapping_add(1376312589);
    (h & 0x7fff_ffff) as f64 * (1.0 / 2147483647.0)
}

/// [`lattice_noise`] of the 2-D lattice point (x, y), hashed as x + 57·y (wrapping).
#[inline(always)]
pub fn lattice_noise_2d(x: i32, y: i32) -> f64 {
    lattice_noise(x.wrapping_add(y.wrapping_mul(57)))
}

/// Uniform numbers as JWildfire draws them (an index as ⌊u·n⌋), from the chaos game's
/// generator, JWildfire's [`Mwc`] generator, or a scripted sequence in tests.
pub(in crate::flame::variations) trait Draw {
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64;
    /// Uniform index in 0..n (n > 0).
    fn index(&mut self, n: usize) -> usize;
}

impl Draw for FastRng {
    #[inline(always)]
    fn unit(&mut self) -> f64 {
        self.f01()
    }
    #[inline(always)]
    fn index(&mut self, n: usize) -> usize {
        self.below(n as u64) as usize
    }
}

impl Draw for Mwc {
    fn unit(&mut self) -> f64 {
        self.next_f64()
    }
    fn index(&mut self, n: usize) -> usize {
        let i = (self.next_f64() * n as f64) as usize;
        i.min(n - 1)
    }
}
