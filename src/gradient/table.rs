//! The gradient table: 256 RGBA entries with the key colours they came from, built from key
//! colours or colour lists, resampled, sampled, rotated, reversed and hue-shifted.

use super::color::{hsv_to_rgb, rgb_to_hsv};

/// One key colour of a gradient: position in `[0, 1]` and RGB in `[0, 1]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stop {
    /// Position along the gradient, 0–1.
    pub pos: f64,
    /// The colour, RGB 0–1.
    pub rgb: [f64; 3],
}

/// A 256-entry colour table.
#[derive(Clone, Debug, PartialEq)]
pub struct Gradient {
    /// The gradient's name.
    pub name: String,
    /// Exactly 256 entries, RGBA in `[0, 1]`.
    pub colors: Vec<[f64; 4]>,
    /// The key colours the table came from, when known (empty otherwise).
    pub stops: Vec<Stop>,
    /// The entries of a Fractint `.map` with fewer than 256 colours: the escape-time view
    /// cycles through these instead of the resampled table.
    pub map_entries: Option<Vec<[f64; 3]>>,
}

/// `colors` resampled to `n` entries by linear interpolation (entry i samples position
/// (i + ½)·N/n − ½ of the N given entries).
pub fn resample_colors(colors: &[[f64; 4]], n: usize) -> Vec<[f64; 4]> {
    let m = colors.len();
    if m == 0 {
        return vec![[0.0, 0.0, 0.0, 1.0]; n];
    }
    (0..n)
        .map(|i| {
            let pos = ((i as f64 + 0.5) * m as f64 / n as f64 - 0.5).clamp(0.0, (m - 1) as f64);
            let k = (pos.floor() as usize).min(m - 1);
            let u = pos - k as f64;
            let (a, b) = (colors[k], colors[(k + 1).min(m - 1)]);
            std::array::from_fn(|c| a[c] + (b[c] - a[c]) * u)
        })
        .collect()
}

impl Default for Gradient {
    fn default() -> Self {
        Self::grey_ramp()
    }
}

impl Gradient {
    /// Number of entries in every gradient.
    pub const LEN: usize = 256;

    /// A gradient from 256 opaque RGB colours.
    pub fn from_rgb(name: impl Into<String>, rgb: &[[f64; 3]]) -> Self {
        assert_eq!(rgb.len(), Self::LEN, "a gradient has 256 colours");
        Self {
            name: name.into(),
            colors: rgb.iter().map(|c| [c[0], c[1], c[2], 1.0]).collect(),
            stops: Vec::new(),
            map_entries: None,
        }
    }

    /// A gradient from 256 colours given as 8-bit RGB.
    pub fn from_rgb8(name: impl Into<String>, rgb: &[[u8; 3]]) -> Self {
        let v: Vec<[f64; 3]> = rgb
            .iter()
            .map(|c| {
                [
                    c[0] as f64 / 255.0,
                    c[1] as f64 / 255.0,
                    c[2] as f64 / 255.0,
                ]
            })
            .collect();
        Self::from_rgb(name, &v)
    }

    /// Black to white.
    pub fn grey_ramp() -> Self {
        let v: Vec<[f64; 3]> = (0..256)
            .map(|i| {
                let g = i as f64 / 255.0;
                [g, g, g]
            })
            .collect();
        Self::from_rgb("grey", &v)
    }

    /// Linear interpolation between key colours (positions in `[0, 1]`, sorted or not).
    /// Outside the first/last key the end colours are held. One key gives a constant gradient.
    pub fn from_stops(name: impl Into<String>, stops: &[Stop]) -> Self {
        let mut s: Vec<Stop> = stops.to_vec();
        s.sort_by(|a, b| a.pos.total_cmp(&b.pos));
        let colors = (0..Self::LEN)
            .map(|i| {
                let t = i as f64 / 255.0;
                let rgb = interpolate_stops(&s, t);
                [rgb[0], rgb[1], rgb[2], 1.0]
            })
            .collect();
        Self {
            name: name.into(),
            colors,
            stops: s,
            map_entries: None,
        }
    }

    /// Entry `i` as 8-bit RGB (rounded).
    pub fn rgb8(&self, i: usize) -> [u8; 3] {
        let c = self.colors[i];
        [to8(c[0]), to8(c[1]), to8(c[2])]
    }

    /// True when every entry is fully opaque.
    pub fn is_opaque(&self) -> bool {
        self.colors.iter().all(|c| c[3] >= 1.0)
    }

    /// Colour at a continuous position `t` (wrapping into `[0, 1)`), linearly interpolated,
    /// used by the escape-time view.
    pub fn sample(&self, t: f64) -> [f64; 3] {
        let n = self.colors.len();
        let f = t.rem_euclid(1.0) * n as f64;
        let i = (f.floor() as usize).min(n - 1);
        let u = f - i as f64;
        let a = self.colors[i];
        let b = self.colors[(i + 1) % n];
        [
            a[0] + (b[0] - a[0]) * u,
            a[1] + (b[1] - a[1]) * u,
            a[2] + (b[2] - a[2]) * u,
        ]
    }

    /// Rotate the entries by `k` places (positive: entry i moves to i + k).
    pub fn rotated(&self, k: i32) -> Self {
        let n = self.colors.len() as i32;
        let mut g = self.clone();
        for i in 0..n {
            g.colors[((i + k).rem_euclid(n)) as usize] = self.colors[i as usize];
        }
        g.stops.clear();
        g
    }

    /// The entries in reverse order.
    pub fn reversed(&self) -> Self {
        let mut g = self.clone();
        g.colors.reverse();
        for s in &mut g.stops {
            s.pos = 1.0 - s.pos;
        }
        g.stops.reverse();
        g
    }
}

fn to8(v: f64) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

fn interpolate_stops(s: &[Stop], t: f64) -> [f64; 3] {
    match s.len() {
        0 => [t, t, t],
        1 => s[0].rgb,
        _ => {
            if t <= s[0].pos {
                return s[0].rgb;
            }
            for w in s.windows(2) {
                if t <= w[1].pos {
                    let span = w[1].pos - w[0].pos;
                    let u = if span > 0.0 {
                        (t - w[0].pos) / span
                    } else {
                        1.0
                    };
                    return [
                        w[0].rgb[0] + (w[1].rgb[0] - w[0].rgb[0]) * u,
                        w[0].rgb[1] + (w[1].rgb[1] - w[0].rgb[1]) * u,
                        w[0].rgb[2] + (w[1].rgb[2] - w[0].rgb[2]) * u,
                    ];
                }
            }
            s[s.len() - 1].rgb
        }
    }
}

/// Rotate the hue of every colour by `turns` of a full turn (flam3 `hue` attribute).
pub fn hue_rotate(g: &Gradient, turns: f64) -> Gradient {
    let mut out = g.clone();
    if turns == 0.0 {
        return out;
    }
    for c in &mut out.colors {
        let mut hsv = rgb_to_hsv([c[0], c[1], c[2]]);
        hsv[0] += 6.0 * turns.rem_euclid(1.0);
        let rgb = hsv_to_rgb(hsv);
        c[0] = rgb[0];
        c[1] = rgb[1];
        c[2] = rgb[2];
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stops_interpolate_and_rotate() {
        let g = Gradient::from_stops(
            "bw",
            &[
                Stop {
                    pos: 0.0,
                    rgb: [0.0, 0.0, 0.0],
                },
                Stop {
                    pos: 1.0,
                    rgb: [1.0, 1.0, 1.0],
                },
            ],
        );
        assert_eq!(g.colors[0][0], 0.0);
        assert_eq!(g.colors[255][0], 1.0);
        assert!((g.colors[51][1] - 0.2).abs() < 1e-12);
        let r = g.rotated(1);
        assert_eq!(r.colors[1], g.colors[0]);
        assert_eq!(r.colors[0], g.colors[255]);
        assert_eq!(g.reversed().colors[0], g.colors[255]);
    }
}
