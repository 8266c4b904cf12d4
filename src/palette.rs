//! Palette editing: key colours, adjustments (hue, saturation, brightness, contrast,
//! frequency, blur) and colour curves, as a flame artist edits a gradient in Fractorium's
//! palette editor. Every function returns a new 256-entry [`Gradient`]; alpha is kept.

use crate::gradient::{Gradient, Stop, hsv_to_rgb, rgb_to_hsv};

/// Adjustments of a palette. They apply in this order: frequency, hue, saturation,
/// brightness, contrast, blur.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Adjust {
    /// Hue rotation in turns (1 = a full turn of the colour wheel).
    pub hue: f64,
    /// −1 (grey) … 0 (unchanged) … 1 (twice the saturation, clamped).
    pub saturation: f64,
    /// Added to every channel: −1 (black) … 1 (white).
    pub brightness: f64,
    /// −1 (flat mid grey) … 0 (unchanged) … towards 1 (hard steps).
    pub contrast: f64,
    /// The palette repeated this many times over the 256 entries (1 = unchanged).
    pub frequency: u32,
    /// Box blur radius in entries (0 = none); the ends are not wrapped.
    pub blur: u32,
}

impl Default for Adjust {
    fn default() -> Self {
        Adjust {
            hue: 0.0,
            saturation: 0.0,
            brightness: 0.0,
            contrast: 0.0,
            frequency: 1,
            blur: 0,
        }
    }
}

/// Largest frequency the editor offers.
pub const MAX_FREQUENCY: u32 = 16;
/// Largest blur radius the editor offers, in entries.
pub const MAX_BLUR: u32 = 64;

fn set_rgb(c: &mut [f64; 4], rgb: [f64; 3]) {
    c[0] = rgb[0].clamp(0.0, 1.0);
    c[1] = rgb[1].clamp(0.0, 1.0);
    c[2] = rgb[2].clamp(0.0, 1.0);
}

/// The palette with the adjustments applied.
pub fn adjust(g: &Gradient, a: &Adjust) -> Gradient {
    let mut out = g.clone();
    out.stops.clear();
    out.map_entries = None;
    let n = g.colors.len();
    let freq = a.frequency.clamp(1, MAX_FREQUENCY) as usize;
    if freq > 1 {
        for i in 0..n {
            out.colors[i] = g.colors[(i * freq) % n];
        }
    }
    // Contrast about mid grey with slope tan((k + 1)·π/4): 0 at k = −1, 1 at k = 0.
    let k = a.contrast.clamp(-1.0, 0.98);
    let slope = ((k + 1.0) * std::f64::consts::FRAC_PI_4).tan();
    let turns = a.hue.rem_euclid(1.0);
    let colour = turns != 0.0 || a.saturation != 0.0;
    for c in &mut out.colors {
        let mut rgb = [c[0], c[1], c[2]];
        if colour {
            let mut hsv = rgb_to_hsv(rgb);
            hsv[0] += 6.0 * turns;
            hsv[1] = (hsv[1] * (1.0 + a.saturation.clamp(-1.0, 1.0))).clamp(0.0, 1.0);
            rgb = hsv_to_rgb(hsv);
        }
        let rgb = rgb.map(|v| {
            let v = (v + a.brightness.clamp(-1.0, 1.0)).clamp(0.0, 1.0);
            if k == 0.0 { v } else { (v - 0.5) * slope + 0.5 }
        });
        set_rgb(c, rgb);
    }
    let r = a.blur.min(MAX_BLUR) as usize;
    if r > 0 {
        let src = out.colors.clone();
        for (i, c) in out.colors.iter_mut().enumerate() {
            let lo = i.saturating_sub(r);
            let hi = (i + r).min(n - 1);
            let mut sum = [0.0; 3];
            for s in &src[lo..=hi] {
                for k in 0..3 {
                    sum[k] += s[k];
                }
            }
            let m = (hi - lo + 1) as f64;
            set_rgb(c, sum.map(|v| v / m));
        }
    }
    out
}

/// A palette from key colours (at least one), keeping the keys for later editing.
pub fn from_keys(name: &str, keys: &[Stop]) -> Gradient {
    Gradient::from_stops(name, keys)
}

/// `n` keys sampled evenly from a palette (for editing a palette that has none).
pub fn sample_keys(g: &Gradient, n: usize) -> Vec<Stop> {
    let n = n.max(2);
    (0..n)
        .map(|k| {
            let pos = k as f64 / (n - 1) as f64;
            let c = g.colors[((pos * 255.0).round() as usize).min(255)];
            Stop {
                pos,
                rgb: [c[0], c[1], c[2]],
            }
        })
        .collect()
}

/// A colour curve: control points (x, y) in [0, 1] through which the curve passes,
/// interpolated by the monotone cubic of Fritsch and Carlson ("Monotone piecewise cubic
/// interpolation", SIAM J. Numer. Anal. 17, 1980), so a rising set of points never
/// overshoots. Outside the first and last point the curve is flat.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    points: Vec<[f64; 2]>,
}

impl Default for Curve {
    fn default() -> Self {
        Curve::identity()
    }
}

impl Curve {
    /// y = x.
    pub fn identity() -> Curve {
        Curve {
            points: vec![[0.0, 0.0], [1.0, 1.0]],
        }
    }

    /// A curve through `points` (clamped to [0, 1], sorted by x; points with the same x
    /// keep the last one; fewer than two points give the identity).
    pub fn new(points: &[[f64; 2]]) -> Curve {
        let mut p: Vec<[f64; 2]> = points
            .iter()
            .map(|q| [q[0].clamp(0.0, 1.0), q[1].clamp(0.0, 1.0)])
            .filter(|q| q[0].is_finite() && q[1].is_finite())
            .collect();
        p.sort_by(|a, b| a[0].total_cmp(&b[0]));
        let mut out: Vec<[f64; 2]> = Vec::with_capacity(p.len());
        for q in p {
            match out.last_mut() {
                Some(l) if (l[0] - q[0]).abs() < 1e-9 => *l = q,
                _ => out.push(q),
            }
        }
        if out.len() < 2 {
            return Curve::identity();
        }
        Curve { points: out }
    }

    /// The control points (x, y), x increasing.
    pub fn points(&self) -> &[[f64; 2]] {
        &self.points
    }

    /// Whether the curve maps every value to itself.
    pub fn is_identity(&self) -> bool {
        self.points.iter().all(|p| (p[0] - p[1]).abs() < 1e-12)
    }

    /// Tangents of the monotone cubic at each point.
    fn tangents(&self) -> Vec<f64> {
        let p = &self.points;
        let n = p.len();
        let d: Vec<f64> = p
            .windows(2)
            .map(|w| (w[1][1] - w[0][1]) / (w[1][0] - w[0][0]))
            .collect();
        let mut m = vec![0.0; n];
        m[0] = d[0];
        m[n - 1] = d[n - 2];
        for i in 1..n - 1 {
            m[i] = if d[i - 1] * d[i] <= 0.0 {
                0.0
            } else {
                (d[i - 1] + d[i]) / 2.0
            };
        }
        // Limit the tangents so that each piece stays monotone.
        for i in 0..n - 1 {
            if d[i] == 0.0 {
                m[i] = 0.0;
                m[i + 1] = 0.0;
                continue;
            }
            let (a, b) = (m[i] / d[i], m[i + 1] / d[i]);
            let s = a * a + b * b;
            if s > 9.0 {
                let t = 3.0 / s.sqrt();
                m[i] = t * a * d[i];
                m[i + 1] = t * b * d[i];
            }
        }
        m
    }

    /// The curve at x (clamped to [0, 1]).
    pub fn eval(&self, x: f64) -> f64 {
        self.eval_with(&self.tangents(), x)
    }

    fn eval_with(&self, m: &[f64], x: f64) -> f64 {
        let p = &self.points;
        let n = p.len();
        if x <= p[0][0] {
            return p[0][1];
        }
        if x >= p[n - 1][0] {
            return p[n - 1][1];
        }
        let i = p
            .partition_point(|q| q[0] <= x)
            .saturating_sub(1)
            .min(n - 2);
        let h = p[i + 1][0] - p[i][0];
        let t = (x - p[i][0]) / h;
        let (t2, t3) = (t * t, t * t * t);
        let y = (2.0 * t3 - 3.0 * t2 + 1.0) * p[i][1]
            + (t3 - 2.0 * t2 + t) * h * m[i]
            + (-2.0 * t3 + 3.0 * t2) * p[i + 1][1]
            + (t3 - t2) * h * m[i + 1];
        y.clamp(0.0, 1.0)
    }

    /// 256 samples of the curve (for drawing and applying).
    pub fn table(&self) -> Vec<f64> {
        let m = self.tangents();
        (0..256)
            .map(|i| self.eval_with(&m, i as f64 / 255.0))
            .collect()
    }
}

/// The four curves of the editor: one for all channels, then one per channel.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Curves {
    /// Applied to each channel first.
    pub all: Curve,
    /// Applied to the red channel after `all`.
    pub red: Curve,
    /// Applied to the green channel after `all`.
    pub green: Curve,
    /// Applied to the blue channel after `all`.
    pub blue: Curve,
}

impl Curves {
    /// Whether all four curves are the identity.
    pub fn is_identity(&self) -> bool {
        [&self.all, &self.red, &self.green, &self.blue]
            .iter()
            .all(|c| c.is_identity())
    }
}

/// The palette through the curves: each channel v becomes channel_curve(all(v)).
pub fn apply_curves(g: &Gradient, c: &Curves) -> Gradient {
    let mut out = g.clone();
    if c.is_identity() {
        return out;
    }
    out.stops.clear();
    out.map_entries = None;
    let (all, m_all) = (&c.all, c.all.tangents());
    let chans = [&c.red, &c.green, &c.blue];
    let ms: Vec<Vec<f64>> = chans.iter().map(|k| k.tangents()).collect();
    // Straight curves are skipped, so that untouched channels keep their exact values.
    let all_straight = all.is_identity();
    for col in &mut out.colors {
        for k in 0..3 {
            let mut v = col[k];
            if !all_straight {
                v = all.eval_with(&m_all, v);
            }
            if !chans[k].is_identity() {
                v = chans[k].eval_with(&ms[k], v);
            }
            col[k] = v;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ramp() -> Gradient {
        crate::gradient::builtin_named("ember").unwrap()
    }

    #[test]
    fn neutral_adjustments_and_identity_curves_change_nothing() {
        let g = ramp();
        assert_eq!(adjust(&g, &Adjust::default()).colors, g.colors);
        assert_eq!(apply_curves(&g, &Curves::default()).colors, g.colors);
    }

    #[test]
    fn adjustment_oracles() {
        let red = Gradient::from_rgb("red", &[[1.0, 0.0, 0.0]; 256]);
        // A third of a turn takes pure red to pure green.
        let a = adjust(
            &red,
            &Adjust {
                hue: 1.0 / 3.0,
                ..Adjust::default()
            },
        );
        let c = a.colors[0];
        assert!(c[0].abs() < 1e-12 && (c[1] - 1.0).abs() < 1e-12 && c[2].abs() < 1e-12);
        // No saturation: grey; full brightness: white; no contrast: mid grey.
        let g = ramp();
        for c in adjust(
            &g,
            &Adjust {
                saturation: -1.0,
                ..Adjust::default()
            },
        )
        .colors
        {
            assert!((c[0] - c[1]).abs() < 1e-12 && (c[1] - c[2]).abs() < 1e-12);
        }
        let white = adjust(
            &g,
            &Adjust {
                brightness: 1.0,
                ..Adjust::default()
            },
        );
        assert!(white.colors.iter().all(|c| c[..3] == [1.0, 1.0, 1.0]));
        let flat = adjust(
            &g,
            &Adjust {
                contrast: -1.0,
                ..Adjust::default()
            },
        );
        assert!(
            flat.colors
                .iter()
                .all(|c| c[..3].iter().all(|v| (v - 0.5).abs() < 1e-12))
        );
        // Twice the frequency: entry i shows entry 2i of the original.
        let f2 = adjust(
            &g,
            &Adjust {
                frequency: 2,
                ..Adjust::default()
            },
        );
        for i in 0..256 {
            assert_eq!(f2.colors[i], g.colors[(2 * i) % 256]);
        }
        // Blur turns a black/white step into a ramp 2r + 1 entries wide.
        let mut step = vec![[0.0; 3]; 128];
        step.extend(vec![[1.0; 3]; 128]);
        let b = adjust(
            &Gradient::from_rgb("step", &step),
            &Adjust {
                blur: 2,
                ..Adjust::default()
            },
        );
        let v: Vec<f64> = (125..=130).map(|i| b.colors[i][0]).collect();
        assert_eq!(v, vec![0.0, 0.2, 0.4, 0.6, 0.8, 1.0]);
    }

    #[test]
    fn curves_pass_through_their_points_and_stay_monotone() {
        let c = Curve::new(&[[0.0, 0.0], [0.5, 0.2], [0.8, 0.9], [1.0, 1.0]]);
        for p in c.points() {
            assert!((c.eval(p[0]) - p[1]).abs() < 1e-12);
        }
        let t = c.table();
        assert!(t.windows(2).all(|w| w[1] >= w[0] - 1e-12), "monotone");
        // Points out of order, out of range or repeated are tidied.
        let d = Curve::new(&[[1.2, 1.0], [0.5, 0.5], [0.0, -1.0], [0.5, 0.4]]);
        assert_eq!(d.points(), &[[0.0, 0.0], [0.5, 0.4], [1.0, 1.0]]);
        // An inverting curve on the red channel only.
        let curves = Curves {
            red: Curve::new(&[[0.0, 1.0], [1.0, 0.0]]),
            ..Curves::default()
        };
        let g = ramp();
        let out = apply_curves(&g, &curves);
        for (a, b) in out.colors.iter().zip(&g.colors) {
            assert!((a[0] - (1.0 - b[0])).abs() < 1e-12);
            assert_eq!(a[1], b[1]);
        }
    }

    #[test]
    fn keys_round_trip_through_a_palette() {
        let keys = vec![
            Stop {
                pos: 0.0,
                rgb: [0.0, 0.0, 0.0],
            },
            Stop {
                pos: 1.0,
                rgb: [1.0, 0.5, 0.0],
            },
        ];
        let g = from_keys("k", &keys);
        assert_eq!(g.stops, keys);
        let back = sample_keys(&g, 2);
        assert_eq!(back, keys);
    }
}
