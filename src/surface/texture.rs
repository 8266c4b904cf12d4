//! Textures: RGB images with a mipmap pyramid, bilinear and trilinear
//! sampling (wrap in s, clamp in t), and procedural sources: fBm and value noise, the Markov
//! random field texture, checker and grid patterns.

use glam::Vec3;

use crate::flame::rng::FastRng;
use crate::noise::{Fbm, FbmNoise};

/// One level of a texture.
#[derive(Clone, Debug)]
struct Level {
    w: usize,
    h: usize,
    texels: Vec<Vec3>,
}

impl Level {
    fn get(&self, x: i64, y: i64) -> Vec3 {
        let xi = x.rem_euclid(self.w as i64) as usize;
        let yi = y.clamp(0, self.h as i64 - 1) as usize;
        self.texels[yi * self.w + xi]
    }

    /// Bilinear sample at texel coordinates (centres at i + 0.5).
    fn bilinear(&self, s: f32, t: f32) -> Vec3 {
        let x = s * self.w as f32 - 0.5;
        let y = t * self.h as f32 - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let xa = (x0 as i64).rem_euclid(self.w as i64) as usize;
        let xb = if xa + 1 == self.w { 0 } else { xa + 1 };
        let ya = (y0 as i64).clamp(0, self.h as i64 - 1) as usize;
        let yb = (y0 as i64 + 1).clamp(0, self.h as i64 - 1) as usize;
        let (ra, rb) = (ya * self.w, yb * self.w);
        let a = self.texels[ra + xa].lerp(self.texels[ra + xb], fx);
        let b = self.texels[rb + xa].lerp(self.texels[rb + xb], fx);
        a.lerp(b, fy)
    }

    /// The next mip level: 2×2 box filter.
    fn half(&self) -> Level {
        let (w, h) = ((self.w / 2).max(1), (self.h / 2).max(1));
        let mut texels = Vec::with_capacity(w * h);
        for y in 0..h {
            for x in 0..w {
                let (x0, y0) = ((2 * x) as i64, (2 * y) as i64);
                texels.push(
                    (self.get(x0, y0)
                        + self.get(x0 + 1, y0)
                        + self.get(x0, y0 + 1)
                        + self.get(x0 + 1, y0 + 1))
                        * 0.25,
                );
            }
        }
        Level { w, h, texels }
    }
}

/// A mipmapped RGB texture; s wraps (around a revolved object), t clamps.
#[derive(Clone, Debug)]
pub struct Texture {
    levels: Vec<Level>,
}

impl Texture {
    /// From linear RGB texels in [0, 1], rows from the top (t = 0 is the first row).
    pub fn from_texels(w: usize, h: usize, texels: Vec<Vec3>) -> Texture {
        assert_eq!(texels.len(), w * h);
        let mut levels = vec![Level { w, h, texels }];
        while levels.last().is_some_and(|l| l.w > 1 || l.h > 1) {
            let next = levels.last().unwrap().half();
            levels.push(next);
        }
        Texture { levels }
    }

    /// From an 8-bit RGB picture, rows from the top.
    pub fn from_image(img: &image::RgbImage) -> Texture {
        let texels = img
            .pixels()
            .map(|p| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32) / 255.0)
            .collect();
        Texture::from_texels(img.width() as usize, img.height() as usize, texels)
    }

    /// A single colour.
    pub fn solid(c: Vec3) -> Texture {
        Texture::from_texels(1, 1, vec![c])
    }

    /// Width and height in texels of the finest level.
    pub fn size(&self) -> (usize, usize) {
        (self.levels[0].w, self.levels[0].h)
    }

    /// Trilinear sample: `footprint` is the larger screen derivative of (s, t) per pixel (in
    /// texture units); 0 samples the finest level bilinearly.
    pub fn sample(&self, s: f32, t: f32, footprint: f32) -> Vec3 {
        let base = &self.levels[0];
        let rho = footprint * base.w.max(base.h) as f32;
        if rho <= 1.0 || self.levels.len() == 1 {
            return base.bilinear(s, t);
        }
        let lod = rho.log2().min((self.levels.len() - 1) as f32);
        let l0 = lod.floor() as usize;
        let l1 = (l0 + 1).min(self.levels.len() - 1);
        let f = lod - l0 as f32;
        self.levels[l0]
            .bilinear(s, t)
            .lerp(self.levels[l1].bilinear(s, t), f)
    }

    /// The scalar height (mean of R, G, B) at (s, t), finest level.
    pub fn height(&self, s: f32, t: f32) -> f32 {
        let c = self.levels[0].bilinear(s, t);
        (c.x + c.y + c.z) / 3.0
    }

    /// One texel step in s and t (for bump-map differences).
    pub fn texel_step(&self) -> (f32, f32) {
        (1.0 / self.levels[0].w as f32, 1.0 / self.levels[0].h as f32)
    }
}

/// A two-colour ramp for procedural textures.
fn ramp(a: Vec3, b: Vec3, v: f32) -> Vec3 {
    a.lerp(b, v.clamp(0.0, 1.0))
}

/// fBm texture: colour ramp over F(p) mapped to [0, 1]; `tiles` repeats of the noise period
/// across s (the noise is sampled on a cylinder so that s wraps without a seam).
pub fn fbm_texture(w: usize, h: usize, fbm: Fbm, a: Vec3, b: Vec3) -> Texture {
    let noise = FbmNoise::new(fbm);
    let mut tex = Vec::with_capacity(w * h);
    let r = 1.0 / (2.0 * std::f64::consts::PI);
    for y in 0..h {
        let t = (y as f64 + 0.5) / h as f64;
        for x in 0..w {
            let ang = 2.0 * std::f64::consts::PI * (x as f64 + 0.5) / w as f64;
            // Seamless in s: walk a circle in the noise's plane, offset by t along a third
            // direction folded into the two coordinates.
            let (px, py) = (r * ang.cos() + 3.1 * t, r * ang.sin() + 1.7 * t);
            let v = (noise.sample(px, py) + 1.0) * 0.5;
            tex.push(ramp(a, b, v as f32));
        }
    }
    Texture::from_texels(w, h, tex)
}

/// Value noise (Kovács): lattice values in [−1, 1] from a seeded 256-entry
/// permutation, smoothstep fade.
#[derive(Clone, Debug)]
pub struct ValueNoise {
    perm: [u8; 256],
    values: [f32; 256],
}

impl ValueNoise {
    pub fn new(seed: u64) -> ValueNoise {
        let mut rng = FastRng::new(seed ^ 0x76616c75);
        let mut perm: [u8; 256] = std::array::from_fn(|i| i as u8);
        for i in (1..256).rev() {
            perm.swap(i, rng.below(i as u64 + 1) as usize);
        }
        let values = std::array::from_fn(|_| rng.f11() as f32);
        ValueNoise { perm, values }
    }

    fn node(&self, i: i64, j: i64) -> f32 {
        let h = self.perm[(self.perm[(i & 255) as usize] as i64 + j).rem_euclid(256) as usize];
        self.values[h as usize]
    }

    pub fn sample(&self, x: f32, y: f32) -> f32 {
        let (fx, fy) = (x.floor(), y.floor());
        let (i, j) = (fx as i64, fy as i64);
        let fade = |t: f32| t * t * (3.0 - 2.0 * t);
        let (u, v) = (fade(x - fx), fade(y - fy));
        let a = self.node(i, j) + u * (self.node(i + 1, j) - self.node(i, j));
        let b = self.node(i, j + 1) + u * (self.node(i + 1, j + 1) - self.node(i, j + 1));
        a + v * (b - a)
    }
}

/// Value-noise fBm texture (periodic in s with period `cells`).
pub fn value_noise_texture(w: usize, h: usize, seed: u64, cells: u32, a: Vec3, b: Vec3) -> Texture {
    let n = ValueNoise::new(seed);
    let mut tex = Vec::with_capacity(w * h);
    for y in 0..h {
        for x in 0..w {
            let mut v = 0.0;
            let mut amp = 1.0;
            let mut norm = 0.0;
            let mut f = cells as f32;
            for _ in 0..5 {
                let sx = (x as f32 + 0.5) / w as f32 * f;
                let sy = (y as f32 + 0.5) / h as f32 * f;
                v += amp * n.sample(sx, sy);
                norm += amp;
                amp *= 0.5;
                f *= 2.0;
            }
            tex.push(ramp(a, b, (v / norm + 1.0) * 0.5));
        }
    }
    Texture::from_texels(w, h, tex)
}

/// Markov random field parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MrfParams {
    pub alpha: f64,
    pub beta: f64,
    pub delta: f64,
    pub phi: f64,
    pub omega: f64,
    pub sweeps: u32,
    pub seed: u64,
}

impl Default for MrfParams {
    fn default() -> Self {
        MrfParams {
            alpha: -1.0,
            beta: 0.5,
            delta: 0.25,
            phi: 0.0,
            omega: 0.0,
            sweeps: 40,
            seed: 1,
        }
    }
}

/// T for a site X given its 8 neighbours (t, t′, u, u′, v, v′, w, w′), laid out in rows from the
/// top as v u w′ / t X t′ / w u′ v′.
#[allow(clippy::too_many_arguments)]
pub fn mrf_t(
    p: &MrfParams,
    t: f64,
    t2: f64,
    u: f64,
    u2: f64,
    v: f64,
    v2: f64,
    w: f64,
    w2: f64,
) -> f64 {
    let pairs = t * u
        + t * v
        + u * v
        + u * t2
        + u * w2
        + t2 * w2
        + t * w
        + t * u2
        + w * u2
        + t2 * u2
        + t2 * v2
        + u2 * v2;
    let triples = t * u * v + t2 * u * w2 + t * u2 * w + t2 * u2 * v2;
    p.alpha
        + p.beta * (t + t2 + u + u2)
        + p.delta * (v + v2 + w + w2)
        + p.phi * pairs
        + p.omega * triples
}

/// P(X = 1 | neighbours) = e^T/(1 + e^T).
pub fn mrf_probability(tt: f64) -> f64 {
    1.0 / (1.0 + (-tt).exp())
}

/// Largest side of a Markov random field texture (larger sizes are made at this side).
pub const MAX_MRF_SIDE: usize = 1024;

/// A binary MRF texture by Gibbs sampling on a torus (raster order), coloured a/b.
pub fn mrf_texture(w: usize, h: usize, p: &MrfParams, a: Vec3, b: Vec3) -> Texture {
    let mut rng = FastRng::new(p.seed);
    let mut x: Vec<f64> = (0..w * h).map(|_| rng.below(2) as f64).collect();
    let at = |x: &[f64], i: i64, j: i64| {
        x[(j.rem_euclid(h as i64) as usize) * w + i.rem_euclid(w as i64) as usize]
    };
    for _ in 0..p.sweeps {
        for j in 0..h as i64 {
            for i in 0..w as i64 {
                // Layout:  v u w′ / t X t′ / w u′ v′
                let tt = mrf_t(
                    p,
                    at(&x, i - 1, j),
                    at(&x, i + 1, j),
                    at(&x, i, j - 1),
                    at(&x, i, j + 1),
                    at(&x, i - 1, j - 1),
                    at(&x, i + 1, j + 1),
                    at(&x, i - 1, j + 1),
                    at(&x, i + 1, j - 1),
                );
                let one = rng.f01() < mrf_probability(tt);
                x[j as usize * w + i as usize] = if one { 1.0 } else { 0.0 };
            }
        }
    }
    Texture::from_texels(
        w,
        h,
        x.iter().map(|&v| if v > 0.5 { b } else { a }).collect(),
    )
}

/// Checkerboard of n×m squares.
pub fn checker(w: usize, h: usize, n: usize, m: usize, a: Vec3, b: Vec3) -> Texture {
    let tex = (0..h)
        .flat_map(|y| (0..w).map(move |x| ((x * n / w) + (y * m / h)).is_multiple_of(2)))
        .map(|even| if even { a } else { b })
        .collect();
    Texture::from_texels(w, h, tex)
}

/// Grid lines on a background.
pub fn grid(w: usize, h: usize, n: usize, m: usize, line: Vec3, back: Vec3) -> Texture {
    let tex = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x * n) % w < n.max(1) * 2 || (y * m) % h < m.max(1) * 2))
        .map(|on| if on { line } else { back })
        .collect();
    Texture::from_texels(w, h, tex)
}

/// The pyramidal filters of Köse's (1990) table 6.1: 3×3 and 7×7 weights (sum 16 and 256).
#[cfg(test)]
pub fn pyramid_filter(size: usize) -> Vec<Vec<u32>> {
    let row: Vec<u32> = match size {
        3 => vec![1, 2, 1],
        7 => vec![1, 2, 3, 4, 3, 2, 1],
        _ => vec![1],
    };
    row.iter()
        .map(|a| row.iter().map(|b| a * b).collect())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mrf_oracles() {
        let p = MrfParams {
            alpha: -1.0,
            beta: 0.5,
            delta: 0.25,
            phi: 0.0,
            omega: 0.0,
            ..Default::default()
        };
        let all1 = mrf_t(&p, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0);
        assert!((all1 - 2.0).abs() < 1e-15);
        assert!((mrf_probability(all1) - 0.880797).abs() < 1e-6);
        let all0 = mrf_t(&p, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        assert!((mrf_probability(all0) - 0.268941).abs() < 1e-6);
        // With φ and Ω each neighbourhood block counts: all ones give 12 pairs and 4 triples.
        let q = MrfParams {
            phi: 1.0,
            omega: 1.0,
            ..p
        };
        assert!(
            (mrf_t(&q, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0) - (2.0 + 12.0 + 4.0)).abs() < 1e-12
        );
        // β > 0 clusters: neighbours agree more often than chance.
        let tex = mrf_texture(
            64,
            64,
            &MrfParams {
                alpha: -2.0,
                beta: 1.0,
                delta: 0.0,
                ..Default::default()
            },
            Vec3::ZERO,
            Vec3::ONE,
        );
        let l = &tex.levels[0];
        let mut agree = 0;
        for y in 0..64 {
            for x in 0..63 {
                agree += (l.texels[y * 64 + x] == l.texels[y * 64 + x + 1]) as u32;
            }
        }
        assert!(agree as f64 / (64.0 * 63.0) > 0.6, "{agree}");
    }

    #[test]
    fn sampling_wraps_in_s_and_mipmaps_average() {
        let t = checker(64, 64, 8, 8, Vec3::ZERO, Vec3::ONE);
        // Wrap: s and s + 1 sample the same.
        let a = t.sample(0.01, 0.5, 0.0);
        let b = t.sample(1.01, 0.5, 0.0);
        assert!((a - b).length() < 1e-6);
        // A footprint covering many squares averages to grey.
        let g = t.sample(0.3, 0.3, 0.5);
        assert!((g.x - 0.5).abs() < 0.05, "{g:?}");
        assert_eq!(pyramid_filter(3).iter().flatten().sum::<u32>(), 16);
        assert_eq!(pyramid_filter(7).iter().flatten().sum::<u32>(), 256);
        // Value noise equals its node values on the lattice and fades are exact at ends.
        let n = ValueNoise::new(3);
        assert_eq!(n.sample(2.0, 5.0), n.node(2, 5));
        let fade = |t: f32| t * t * (3.0 - 2.0 * t);
        assert_eq!((fade(0.0), fade(0.5), fade(1.0)), (0.0, 0.5, 1.0));
        // fBm texture is seamless in s: first and last columns are neighbours.
        let f = fbm_texture(128, 32, Fbm::default(), Vec3::ZERO, Vec3::ONE);
        let l = &f.levels[0];
        let seam: f32 = (0..32)
            .map(|y| (l.texels[y * 128] - l.texels[y * 128 + 127]).length())
            .sum();
        let inner: f32 = (0..32)
            .map(|y| (l.texels[y * 128 + 60] - l.texels[y * 128 + 61]).length())
            .sum();
        assert!(seam < 3.0 * inner + 0.05, "{seam} vs {inner}");
    }
}
