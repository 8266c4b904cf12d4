//! Seeded gradient (Perlin) noise and fBm, shared by the warped-Julia turbulence and the scene
//! textures.

use crate::flame::rng::FastRng;

/// 2-D gradient noise with a seeded permutation table.
#[derive(Clone, Debug)]
pub struct Perlin {
    perm: [u8; 512],
}

/// Twelve unit gradient directions, evenly spread.
const GRADS: [[f64; 2]; 12] = {
    let mut g = [[0.0; 2]; 12];
    let mut k = 0;
    while k < 12 {
        // cos/sin of k·30° without const trig: a table.
        let t = [
            (1.0, 0.0),
            (0.866_025_403_784_438_6, 0.5),
            (0.5, 0.866_025_403_784_438_6),
            (0.0, 1.0),
            (-0.5, 0.866_025_403_784_438_6),
            (-0.866_025_403_784_438_6, 0.5),
            (-1.0, 0.0),
            (-0.866_025_403_784_438_6, -0.5),
            (-0.5, -0.866_025_403_784_438_6),
            (0.0, -1.0),
            (0.5, -0.866_025_403_784_438_6),
            (0.866_025_403_784_438_6, -0.5),
        ][k];
        g[k] = [t.0, t.1];
        k += 1;
    }
    g
};

fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

impl Perlin {
    /// Perlin noise whose permutation table is shuffled from `seed`.
    pub fn new(seed: u64) -> Perlin {
        let mut rng = FastRng::new(seed ^ 0x6e6f_6973_6521);
        let mut p: [u8; 256] = std::array::from_fn(|i| i as u8);
        for i in (1..256).rev() {
            let j = rng.below(i as u64 + 1) as usize;
            p.swap(i, j);
        }
        let mut perm = [0u8; 512];
        for i in 0..512 {
            perm[i] = p[i & 255];
        }
        Perlin { perm }
    }

    fn grad(&self, ix: i64, iy: i64, dx: f64, dy: f64) -> f64 {
        let h = self.perm[(self.perm[(ix & 255) as usize] as usize + (iy & 255) as usize) & 511];
        let g = GRADS[h as usize % 12];
        g[0] * dx + g[1] * dy
    }

    /// Noise in [−1, 1]; 0 at every lattice point.
    pub fn noise(&self, x: f64, y: f64) -> f64 {
        let (fx, fy) = (x.floor(), y.floor());
        let (ix, iy) = (fx as i64, fy as i64);
        let (dx, dy) = (x - fx, y - fy);
        let (u, v) = (fade(dx), fade(dy));
        let n00 = self.grad(ix, iy, dx, dy);
        let n10 = self.grad(ix + 1, iy, dx - 1.0, dy);
        let n01 = self.grad(ix, iy + 1, dx, dy - 1.0);
        let n11 = self.grad(ix + 1, iy + 1, dx - 1.0, dy - 1.0);
        let a = n00 + u * (n10 - n00);
        let b = n01 + u * (n11 - n01);
        // The 2-D gradient-noise range is ±√2/2 for unit gradients: scale to [−1, 1].
        ((a + v * (b - a)) * std::f64::consts::SQRT_2).clamp(-1.0, 1.0)
    }
}

/// Fractional Brownian motion settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fbm {
    /// Octaves summed (at least 1 is used).
    pub octaves: u32,
    /// Frequency factor ℓ from one octave to the next.
    pub lacunarity: f64,
    /// Amplitude factor γ from one octave to the next.
    pub gain: f64,
    /// Base frequency f.
    pub frequency: f64,
    /// Seed of the noise.
    pub seed: u64,
}

impl Default for Fbm {
    fn default() -> Self {
        Fbm {
            octaves: 6,
            lacunarity: 2.0,
            gain: 0.5,
            frequency: 4.0,
            seed: 1,
        }
    }
}

/// fBm sampler: F(p) = Σ γ^o N(ℓ^o f p) / Σ γ^o, in [−1, 1].
#[derive(Clone, Debug)]
pub struct FbmNoise {
    /// The settings.
    pub params: Fbm,
    perlin: Perlin,
}

impl FbmNoise {
    /// A sampler for these settings.
    pub fn new(params: Fbm) -> FbmNoise {
        FbmNoise {
            perlin: Perlin::new(params.seed),
            params,
        }
    }

    /// F at (x, y), in [−1, 1].
    pub fn sample(&self, x: f64, y: f64) -> f64 {
        let p = &self.params;
        let (mut amp, mut freq, mut sum, mut norm) = (1.0, p.frequency, 0.0, 0.0);
        for _ in 0..p.octaves.max(1) {
            sum += amp * self.perlin.noise(x * freq, y * freq);
            norm += amp;
            amp *= p.gain;
            freq *= p.lacunarity;
        }
        sum / norm
    }

    /// Turbulence: Σ γ^o |N| / Σ γ^o, in [0, 1].
    pub fn turbulence(&self, x: f64, y: f64) -> f64 {
        let p = &self.params;
        let (mut amp, mut freq, mut sum, mut norm) = (1.0, p.frequency, 0.0, 0.0);
        for _ in 0..p.octaves.max(1) {
            sum += amp * self.perlin.noise(x * freq, y * freq).abs();
            norm += amp;
            amp *= p.gain;
            freq *= p.lacunarity;
        }
        sum / norm
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noise_is_zero_on_the_lattice_bounded_and_seeded() {
        let a = Perlin::new(3);
        let b = Perlin::new(3);
        let c = Perlin::new(4);
        let mut differs = false;
        for i in -5..5 {
            for j in -5..5 {
                assert_eq!(a.noise(i as f64, j as f64), 0.0);
                let (x, y) = (i as f64 * 0.37 + 0.11, j as f64 * 0.53 + 0.07);
                let v = a.noise(x, y);
                assert!((-1.0..=1.0).contains(&v));
                assert_eq!(v, b.noise(x, y));
                differs |= v != c.noise(x, y);
            }
        }
        assert!(differs, "another seed gives other noise");
    }

    #[test]
    fn fbm_is_continuous_and_in_range() {
        let f = FbmNoise::new(Fbm::default());
        let mut prev = f.sample(0.0, 0.3);
        let mut spread = (f64::MAX, f64::MIN);
        for k in 1..2000 {
            let x = k as f64 * 1e-4;
            let v = f.sample(x, 0.3);
            assert!((v - prev).abs() < 0.05, "jump at {x}");
            assert!((-1.0..=1.0).contains(&v));
            spread = (spread.0.min(v), spread.1.max(v));
            prev = v;
        }
        assert!(spread.1 - spread.0 > 0.1, "fBm varies: {spread:?}");
        let t = f.turbulence(0.3, 0.7);
        assert!((0.0..=1.0).contains(&t));
    }
}
