//! Warped Julia textures (after Borowicz's paper on warped Julia sets for sky textures): texture
//! coordinates, the Möbius (all-pass) warp g(p) = (p − ᾱ)/(1 − αp) and fBm turbulence.

use super::complex::C;
use crate::noise::{Fbm, FbmNoise};

/// How texels sample the start point p.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sampling {
    /// p = s(u − ½) + i·s(v − ½).
    Rect {
        /// Side s of the square sampled, in world units.
        scale: f64,
    },
    /// p = r·v·e^{i2πu}: periodic in u, seamless around a cylinder or dome.
    Polar {
        /// Radius r of the disc sampled, in world units.
        radius: f64,
    },
}

/// A warped-Julia texture.
#[derive(Clone, Debug)]
pub struct Warp {
    /// The Julia constant c of z ← z² + c.
    pub c: C,
    /// The Möbius warp's α (|α| ≠ 1; 0 leaves p unwarped).
    pub alpha: C,
    /// Turbulence amount λ.
    pub lambda: f64,
    /// The fBm turbulence W added to the warped start point.
    pub fbm: Fbm,
    /// How texels sample the start point p.
    pub sampling: Sampling,
    /// Use W − (½ + ½i) so that turbulence does not shift the set.
    pub zero_mean: bool,
    noise: Option<(FbmNoise, FbmNoise)>,
}

impl PartialEq for Warp {
    fn eq(&self, o: &Warp) -> bool {
        self.c == o.c
            && self.alpha == o.alpha
            && self.lambda == o.lambda
            && self.fbm == o.fbm
            && self.sampling == o.sampling
            && self.zero_mean == o.zero_mean
    }
}

/// Why a warp cannot be used.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum WarpError {
    #[error("|α| = {0} is within 1e-9 of 1: the warp degenerates to a constant")]
    Degenerate(f64),
    #[error("the sampling radius or scale must be positive and finite")]
    BadSampling,
}

/// Presets after the figures of Borowicz's paper: polar Julia, warped Julia and the turbulent
/// galaxy.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Preset {
    /// A polar-sampled Julia set, no warp.
    PolarJulia,
    /// A polar-sampled Julia set warped by α = −0.3.
    WarpedJulia,
    /// The warped Julia set with turbulence λ = 0.2 (the galaxy).
    Galaxy,
}

impl Warp {
    /// A warped-Julia texture; fails when |α| is within 1e-9 of 1 or the sampling radius or scale
    /// is not positive and finite.
    pub fn new(
        c: C,
        alpha: C,
        lambda: f64,
        fbm: Fbm,
        sampling: Sampling,
        zero_mean: bool,
    ) -> Result<Warp, WarpError> {
        let a = alpha.abs();
        if (a - 1.0).abs() <= 1e-9 {
            return Err(WarpError::Degenerate(a));
        }
        let ok = match sampling {
            Sampling::Rect { scale } => scale > 0.0 && scale.is_finite(),
            Sampling::Polar { radius } => radius > 0.0 && radius.is_finite(),
        };
        if !ok {
            return Err(WarpError::BadSampling);
        }
        let noise = (lambda != 0.0).then(|| {
            (
                FbmNoise::new(fbm),
                FbmNoise::new(Fbm {
                    seed: fbm.seed.wrapping_add(1),
                    ..fbm
                }),
            )
        });
        Ok(Warp {
            c,
            alpha,
            lambda,
            fbm,
            sampling,
            zero_mean,
            noise,
        })
    }

    /// The texture of a preset (c = −0.8 + 0.156i, polar sampling of radius 1).
    pub fn preset(p: Preset) -> Warp {
        let c = C::new(-0.8, 0.156);
        let polar = Sampling::Polar { radius: 1.0 };
        let (alpha, lambda) = match p {
            Preset::PolarJulia => (C::ZERO, 0.0),
            Preset::WarpedJulia => (C::new(-0.3, 0.0), 0.0),
            Preset::Galaxy => (C::new(-0.3, 0.0), 0.2),
        };
        Warp::new(c, alpha, lambda, Fbm::default(), polar, false).expect("presets are valid")
    }

    /// g(p) = (p − ᾱ)/(1 − αp).
    pub fn g(&self, p: C) -> C {
        (p - self.alpha.conj()) / (C::ONE - self.alpha * p)
    }

    /// |g′(p)| = (1 − |α|²)/|1 − αp|².
    pub fn g_prime_abs(&self, p: C) -> f64 {
        (1.0 - self.alpha.norm2()).abs() / (C::ONE - self.alpha * p).norm2()
    }

    /// The texel's start point p for column i of W and row j of H counted from the top.
    pub fn point(&self, i: u32, j: u32, w: u32, h: u32) -> C {
        let u = ((i % w.max(1)) as f64 + 0.5) / w as f64;
        // v counts rows from the bottom.
        let v = ((h - 1 - j.min(h - 1)) as f64 + 0.5) / h as f64;
        self.point_uv(u, v)
    }

    /// The start point p at texture coordinates (u, v), both 0–1, v counted from the bottom.
    pub fn point_uv(&self, u: f64, v: f64) -> C {
        match self.sampling {
            Sampling::Rect { scale } => C::new(scale * (u - 0.5), scale * (v - 0.5)),
            Sampling::Polar { radius } => C::from_polar(radius * v, 2.0 * std::f64::consts::PI * u),
        }
    }

    /// ẑ₀ = g(p) + λ·W(p) (Borowicz, eq. 13).
    pub fn start(&self, p: C) -> C {
        let g = self.g(p);
        match &self.noise {
            Some((n1, n2)) => {
                let w1 = (n1.sample(p.re, p.im) + 1.0) * 0.5;
                let w2 = (n2.sample(p.re, p.im) + 1.0) * 0.5;
                let (mut wr, mut wi) = (w1, w2);
                if self.zero_mean {
                    wr -= 0.5;
                    wi -= 0.5;
                }
                g + C::new(wr, wi) * self.lambda
            }
            None => g,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn warp(alpha: C) -> Warp {
        Warp::new(
            C::new(-0.8, 0.156),
            alpha,
            0.0,
            Fbm::default(),
            Sampling::Polar { radius: 1.0 },
            false,
        )
        .unwrap()
    }

    #[test]
    fn warp_identities_7_6() {
        let w = warp(C::new(0.5, 0.25));
        // A(1/p) = (p − ᾱ)/(1 − αp) for p = 0.3 + 0.2i.
        let p = C::new(0.3, 0.2);
        // The all-pass A(z) = (z⁻¹ − ᾱ)/(1 − α z⁻¹) at z = 1/p.
        let z = C::ONE / p;
        let a = (C::ONE / z - w.alpha.conj()) / (C::ONE - w.alpha / z);
        let g = w.g(p);
        assert!((a - g).abs() < 1e-12);
        assert!((g - C::new(-0.307807, 0.440149)).abs() < 1e-6, "{g:?}");
        assert!((w.g(C::ZERO) - C::new(-0.5, 0.25)).abs() < 1e-15);
        assert!(w.g(C::new(0.5, -0.25)).abs() < 1e-15);
        // Pole 1/α = 1.6 − 0.8i; the image of ∞ is −1/α = −1.6 + 0.8i.
        let pole = C::ONE / w.alpha;
        assert!((pole - C::new(1.6, -0.8)).abs() < 1e-12);
        assert!(!w.g(pole).is_finite() || w.g(pole).abs() > 1e12);
        assert!((w.g(C::new(1e9, 0.0)) - C::new(-1.6, 0.8)).abs() < 1e-8);
        assert!((w.g(C::from_polar(1.0, 0.7)).abs() - 1.0).abs() < 1e-12);
        let v = warp(C::new(-0.3, 0.0));
        assert!((v.g(C::ONE) - C::ONE).abs() < 1e-15);
        assert!((v.g(-C::ONE) + C::ONE).abs() < 1e-15);
        assert!((v.g(C::ZERO) - C::new(0.3, 0.0)).abs() < 1e-15);
        assert!((v.g_prime_abs(C::ONE) - 0.538462).abs() < 1e-6);
        assert!((v.g_prime_abs(-C::ONE) - 1.857143).abs() < 1e-6);
        // The unit disc maps into itself for |α| < 1.
        for k in 0..50 {
            let p = C::from_polar(0.99 * (k as f64 / 50.0), k as f64 * 1.3);
            assert!(v.g(p).abs() < 1.0);
        }
        assert!(matches!(
            Warp::new(
                C::ZERO,
                C::new(0.6, 0.8),
                0.0,
                Fbm::default(),
                Sampling::Polar { radius: 1.0 },
                false
            ),
            Err(WarpError::Degenerate(_))
        ));
        // α = 0 is the identity; λ = 0 adds nothing.
        let id = warp(C::ZERO);
        assert_eq!(id.start(p), p);
    }

    #[test]
    fn polar_sampling_is_periodic_in_u() {
        let w = Warp::preset(Preset::Galaxy);
        for j in [0u32, 5, 63] {
            let a = w.start(w.point(0, j, 64, 64));
            let b = w.start(w.point(64, j, 64, 64));
            assert_eq!(a, b, "column W wraps to column 0");
        }
        // Bottom-left texel has v = 0.5/H.
        let p = w.point(0, 63, 64, 64);
        assert!((p.abs() - 0.5 / 64.0).abs() < 1e-12);
    }
}
