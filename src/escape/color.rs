//! Colouring of escape-time samples: iteration bands, smooth count, distance
//! estimation, histogram colouring and Newton root basins, through the shared gradients.

use super::family::Sample;
use crate::gradient::Gradient;

/// How samples become colours.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Coloring {
    /// palette[n·repeat + offset] (integer bands).
    Bands,
    /// Normalised iteration count, interpolated between palette entries.
    #[default]
    Smooth,
    /// Exterior distance estimate: dark at the boundary, the gradient further out.
    Distance,
    /// Histogram-equalised iteration count (independent of max_iter and repeat).
    Histogram,
    /// Newton: a colour per root, shaded by the iteration count.
    Basins,
}

impl Coloring {
    /// The colouring's name as written in view files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Coloring::Bands => "bands",
            Coloring::Smooth => "smooth",
            Coloring::Distance => "distance",
            Coloring::Histogram => "histogram",
            Coloring::Basins => "basins",
        }
    }

    /// The colouring a name or one of its aliases stands for (any case); None for an unknown name.
    pub fn from_name(s: &str) -> Option<Coloring> {
        Some(match s.trim().to_ascii_lowercase().as_str() {
            "bands" | "iter" | "iterations" => Coloring::Bands,
            "smooth" => Coloring::Smooth,
            "distance" | "de" => Coloring::Distance,
            "histogram" => Coloring::Histogram,
            "basins" | "basin" | "roots" => Coloring::Basins,
            _ => return None,
        })
    }

    /// Every colouring, in menu order.
    pub const ALL: [Coloring; 5] = [
        Coloring::Bands,
        Coloring::Smooth,
        Coloring::Distance,
        Coloring::Histogram,
        Coloring::Basins,
    ];

    /// Whether the colouring needs the large escape radius (smooth values).
    pub fn smooth(self) -> bool {
        matches!(
            self,
            Coloring::Smooth | Coloring::Distance | Coloring::Histogram
        )
    }
}

/// Palette settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Palette {
    /// The gradient the colours are taken from.
    pub gradient: Gradient,
    /// Fraction of the gradient added to every index (0–1).
    pub offset: f64,
    /// Gradient entries per iteration (density).
    pub repeat: f64,
    /// RGB colour of the points that never escape (or, for Newton, never converge).
    pub inside: [u8; 3],
}

impl Default for Palette {
    fn default() -> Self {
        Palette {
            gradient: crate::gradient::default_gradient(),
            offset: 0.0,
            repeat: 1.0,
            inside: [0, 0, 0],
        }
    }
}

fn to8(c: [f64; 4]) -> [u8; 3] {
    [
        (c[0].clamp(0.0, 1.0) * 255.0 + 0.5) as u8,
        (c[1].clamp(0.0, 1.0) * 255.0 + 0.5) as u8,
        (c[2].clamp(0.0, 1.0) * 255.0 + 0.5) as u8,
    ]
}

impl Palette {
    /// The colour at continuous palette position s (wrapping, interpolated).
    pub fn at(&self, s: f64) -> [u8; 3] {
        let k = self.gradient.colors.len();
        let s = s.rem_euclid(k as f64);
        let i = s.floor() as usize % k;
        let t = s - s.floor();
        let (a, b) = (self.gradient.colors[i], self.gradient.colors[(i + 1) % k]);
        to8([
            a[0] + (b[0] - a[0]) * t,
            a[1] + (b[1] - a[1]) * t,
            a[2] + (b[2] - a[2]) * t,
            1.0,
        ])
    }

    /// The entry at integer index n (no interpolation).
    pub fn entry(&self, n: i64) -> [u8; 3] {
        let k = self.gradient.colors.len() as i64;
        to8(self.gradient.colors[n.rem_euclid(k) as usize])
    }

    fn offset_entries(&self) -> f64 {
        self.offset * self.gradient.colors.len() as f64
    }
}

/// Cumulative histogram of integer counts over escaped samples.
pub struct CountHistogram {
    cumulative: Vec<f64>,
}

impl CountHistogram {
    pub fn new(samples: &[Sample], max_iter: u32) -> CountHistogram {
        let mut h = vec![0u64; max_iter as usize + 2];
        let mut total = 0u64;
        for s in samples {
            if !s.inside {
                h[(s.n as usize).min(max_iter as usize + 1)] += 1;
                total += 1;
            }
        }
        let mut cumulative = Vec::with_capacity(h.len());
        let mut acc = 0u64;
        for v in h {
            acc += v;
            cumulative.push(if total > 0 {
                acc as f64 / total as f64
            } else {
                0.0
            });
        }
        CountHistogram { cumulative }
    }

    /// hue(ν) in (0, 1], interpolated between hue(⌊ν⌋) and hue(⌊ν⌋ + 1).
    pub fn hue(&self, nu: f64) -> f64 {
        let last = self.cumulative.len() - 1;
        let k = (nu.floor().max(0.0) as usize).min(last);
        let t = (nu - nu.floor()).clamp(0.0, 1.0);
        let a = self.cumulative[k];
        let b = self.cumulative[(k + 1).min(last)];
        a + (b - a) * t
    }
}

/// Everything needed to colour one sample.
pub struct Colorizer<'a> {
    pub coloring: Coloring,
    pub palette: &'a Palette,
    /// World size of a pixel (for distance colouring).
    pub pixel: f64,
    pub roots: usize,
    pub histogram: Option<CountHistogram>,
}

impl Colorizer<'_> {
    pub fn color(&self, s: &Sample) -> [u8; 3] {
        let p = self.palette;
        if s.inside {
            return p.inside;
        }
        let k = p.gradient.colors.len() as f64;
        match self.coloring {
            Coloring::Bands => p.entry((s.n as f64 * p.repeat + p.offset_entries()).floor() as i64),
            Coloring::Smooth => p.at(s.nu * p.repeat + p.offset_entries()),
            Coloring::Histogram => {
                let h = self.histogram.as_ref().map_or(0.0, |h| h.hue(s.nu));
                p.at(h * (k - 1.0) * p.repeat.max(1e-9) + p.offset_entries())
            }
            Coloring::Distance => {
                // Boundary (b below a pixel) at the start of the gradient, then outwards on a
                // log scale: eight doublings of the distance cover the gradient.
                let d = (s.de as f64 / self.pixel.max(1e-300)).max(0.0);
                let t = ((1.0 + d).log2() / 8.0).min(1.0);
                p.at(t * (k - 1.0) * p.repeat + p.offset_entries())
            }
            Coloring::Basins => {
                if s.root == 255 {
                    return p.inside;
                }
                let m = self.roots.max(1) as f64;
                let base = p.at(((s.root as f64 + 0.5) / m) * k + p.offset_entries());
                // Shade by the number of Newton steps: fast convergence is bright.
                let shade = 0.25 + 0.75 * (-(s.n as f64) / (12.0 * p.repeat.max(0.05))).exp();
                base.map(|v| (v as f64 * shade).round() as u8)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(n: u32, nu: f64) -> Sample {
        Sample {
            n,
            inside: false,
            nu,
            de: 0.0,
            root: 255,
        }
    }

    #[test]
    fn histogram_colouring_is_independent_of_max_iter_and_monotone() {
        let s: Vec<Sample> = (1..=50)
            .map(|n| sample(n % 10 + 1, (n % 10 + 1) as f64))
            .collect();
        let a = CountHistogram::new(&s, 100);
        let b = CountHistogram::new(&s, 5000);
        for k in 0..12 {
            assert_eq!(a.hue(k as f64), b.hue(k as f64));
        }
        assert!((a.hue(10.0) - 1.0).abs() < 1e-12);
        let mut prev = 0.0;
        for k in 0..40 {
            let h = a.hue(k as f64 * 0.3);
            assert!(h >= prev);
            prev = h;
        }
    }

    #[test]
    fn palette_wraps_and_interpolates() {
        let p = Palette::default();
        assert_eq!(p.at(0.0), p.entry(0));
        assert_eq!(p.at(256.0), p.entry(0));
        assert_eq!(p.entry(-1), p.entry(255));
        let c = Colorizer {
            coloring: Coloring::Bands,
            palette: &p,
            pixel: 1.0,
            roots: 0,
            histogram: None,
        };
        assert_eq!(c.color(&Sample::inside(10)), [0, 0, 0]);
        assert_eq!(c.color(&sample(3, 3.5)), p.entry(3));
    }
}
