//! Gradients: the 256-colour tables that colour flames and escape-time images.
//!
//! One type serves both views. A gradient always has exactly 256 RGBA entries in `[0, 1]`
//! (straight, not pre-multiplied alpha); `stops` keeps the key colours it was built from when the
//! source had them (a `.ugr` key list, a short Fractint `.map`), so that writers can reproduce
//! the source and the escape-time view can cycle a short map.

/// One key colour of a gradient: position in `[0, 1]` and RGB in `[0, 1]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stop {
    pub pos: f64,
    pub rgb: [f64; 3],
}

/// A 256-entry colour table.
#[derive(Clone, Debug, PartialEq)]
pub struct Gradient {
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

/// flam3 RGB → HSV: h in [0, 6), s and v in [0, 1].
pub fn rgb_to_hsv(rgb: [f64; 3]) -> [f64; 3] {
    let [r, g, b] = rgb;
    let max = r.max(g).max(b);
    let min = r.min(g).min(b);
    let del = max - min;
    let v = max;
    let s = if max != 0.0 { del / max } else { 0.0 };
    let mut h = 0.0;
    if s != 0.0 {
        let rc = (max - r) / del;
        let gc = (max - g) / del;
        let bc = (max - b) / del;
        h = if r == max {
            bc - gc
        } else if g == max {
            2.0 + rc - bc
        } else {
            4.0 + gc - rc
        };
        if h < 0.0 {
            h += 6.0;
        }
    }
    [h, s, v]
}

/// flam3 HSV → RGB (h in [0, 6)).
pub fn hsv_to_rgb(hsv: [f64; 3]) -> [f64; 3] {
    let [mut h, s, v] = hsv;
    while h >= 6.0 {
        h -= 6.0;
    }
    while h < 0.0 {
        h += 6.0;
    }
    let j = h.floor();
    let f = h - j;
    let p = v * (1.0 - s);
    let q = v * (1.0 - s * f);
    let t = v * (1.0 - s * (1.0 - f));
    match j as i32 {
        0 => [v, t, p],
        1 => [q, v, p],
        2 => [p, v, t],
        3 => [p, q, v],
        4 => [t, p, v],
        _ => [v, p, q],
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
    fn hsv_round_trip() {
        for rgb in [
            [1.0, 0.5, 0.0],
            [0.2, 0.4, 0.9],
            [0.0, 0.0, 0.0],
            [0.7, 0.7, 0.7],
        ] {
            let back = hsv_to_rgb(rgb_to_hsv(rgb));
            for k in 0..3 {
                assert!((back[k] - rgb[k]).abs() < 1e-12, "{rgb:?} -> {back:?}");
            }
        }
        assert_eq!(rgb_to_hsv([1.0, 0.0, 0.0]), [0.0, 1.0, 1.0]);
        assert_eq!(rgb_to_hsv([0.0, 0.0, 1.0]), [4.0, 1.0, 1.0]);
    }

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

/// ugnis's own gradients: (name, key colours as (position 0..=255, R, G, B)). These are the
/// gradients shipped in `gradients/` and the default library of the editor.
/// A key colour: position 0..=255, R, G, B.
type Key = (u8, u8, u8, u8);

const BUILTIN: &[(&str, &[Key])] = &[
    (
        "ember",
        &[
            (0, 10, 0, 20),
            (77, 140, 20, 10),
            (153, 250, 140, 20),
            (217, 255, 230, 150),
            (255, 255, 255, 255),
        ],
    ),
    (
        "lagoon",
        &[
            (0, 5, 20, 60),
            (89, 0, 120, 160),
            (166, 60, 220, 200),
            (255, 240, 255, 220),
        ],
    ),
    (
        "orchid",
        &[
            (0, 40, 0, 60),
            (102, 180, 40, 160),
            (178, 250, 150, 200),
            (255, 255, 240, 250),
        ],
    ),
    (
        "moss",
        &[
            (0, 20, 30, 10),
            (128, 90, 160, 40),
            (204, 220, 230, 120),
            (255, 255, 250, 220),
        ],
    ),
    (
        "dusk",
        &[
            (0, 250, 200, 90),
            (77, 230, 90, 60),
            (153, 120, 40, 120),
            (255, 20, 30, 90),
        ],
    ),
    (
        "ice",
        &[(0, 255, 255, 255), (128, 120, 190, 255), (255, 20, 40, 120)],
    ),
    (
        "aurora",
        &[
            (0, 0, 10, 30),
            (60, 0, 120, 90),
            (120, 40, 230, 140),
            (180, 120, 90, 220),
            (255, 240, 200, 255),
        ],
    ),
    (
        "copper",
        &[
            (0, 20, 8, 4),
            (90, 120, 50, 20),
            (170, 220, 130, 70),
            (230, 250, 210, 160),
            (255, 255, 250, 235),
        ],
    ),
    (
        "peacock",
        &[
            (0, 10, 30, 40),
            (70, 0, 110, 120),
            (130, 30, 160, 90),
            (190, 200, 170, 40),
            (255, 60, 40, 140),
        ],
    ),
    (
        "sakura",
        &[
            (0, 60, 20, 40),
            (90, 200, 90, 130),
            (170, 255, 190, 210),
            (255, 255, 250, 250),
        ],
    ),
    (
        "volcano",
        &[
            (0, 0, 0, 0),
            (60, 80, 0, 0),
            (130, 230, 40, 0),
            (190, 255, 170, 0),
            (230, 255, 240, 120),
            (255, 255, 255, 255),
        ],
    ),
    (
        "glacier",
        &[
            (0, 0, 20, 40),
            (80, 30, 90, 140),
            (160, 140, 200, 230),
            (220, 220, 245, 255),
            (255, 255, 255, 255),
        ],
    ),
    (
        "meadow",
        &[
            (0, 30, 40, 0),
            (80, 110, 150, 20),
            (150, 230, 210, 60),
            (210, 250, 120, 140),
            (255, 255, 230, 240),
        ],
    ),
    (
        "twilight",
        &[
            (0, 20, 10, 50),
            (70, 90, 30, 120),
            (140, 220, 80, 120),
            (200, 255, 170, 90),
            (255, 255, 240, 200),
        ],
    ),
    (
        "abyss",
        &[
            (0, 0, 0, 10),
            (100, 0, 30, 80),
            (170, 0, 120, 170),
            (230, 90, 220, 240),
            (255, 230, 255, 255),
        ],
    ),
    (
        "amber",
        &[
            (0, 30, 10, 0),
            (100, 160, 80, 0),
            (180, 250, 190, 40),
            (255, 255, 250, 210),
        ],
    ),
    (
        "nebula",
        &[
            (0, 5, 0, 15),
            (60, 70, 10, 90),
            (120, 200, 40, 120),
            (170, 80, 120, 230),
            (220, 180, 220, 255),
            (255, 255, 255, 255),
        ],
    ),
    (
        "jade",
        &[
            (0, 0, 25, 15),
            (90, 20, 110, 70),
            (170, 110, 200, 150),
            (255, 230, 255, 235),
        ],
    ),
    (
        "rust",
        &[
            (0, 40, 20, 10),
            (80, 130, 50, 20),
            (150, 190, 100, 50),
            (210, 140, 60, 40),
            (255, 240, 210, 170),
        ],
    ),
    (
        "citrus",
        &[
            (0, 60, 90, 0),
            (90, 190, 210, 0),
            (170, 255, 200, 0),
            (220, 255, 120, 0),
            (255, 255, 240, 200),
        ],
    ),
    (
        "storm",
        &[
            (0, 10, 12, 20),
            (90, 60, 70, 90),
            (170, 140, 150, 170),
            (220, 220, 225, 240),
            (255, 255, 250, 200),
        ],
    ),
    (
        "coral",
        &[
            (0, 40, 10, 20),
            (80, 200, 70, 70),
            (150, 255, 150, 110),
            (210, 255, 220, 180),
            (255, 120, 220, 230),
        ],
    ),
    (
        "plasma",
        &[
            (0, 13, 8, 135),
            (64, 126, 3, 168),
            (128, 204, 71, 120),
            (192, 248, 149, 64),
            (255, 240, 249, 33),
        ],
    ),
    (
        "ocean-sunset",
        &[
            (0, 0, 30, 70),
            (80, 40, 90, 160),
            (140, 220, 120, 120),
            (200, 255, 180, 80),
            (255, 255, 240, 200),
        ],
    ),
    (
        "lavender",
        &[
            (0, 30, 20, 50),
            (100, 130, 100, 190),
            (190, 210, 190, 245),
            (255, 250, 245, 255),
        ],
    ),
    (
        "forest-fire",
        &[
            (0, 0, 20, 0),
            (70, 20, 90, 20),
            (130, 200, 180, 30),
            (190, 240, 90, 0),
            (255, 255, 240, 200),
        ],
    ),
    (
        "steel",
        &[
            (0, 10, 15, 20),
            (110, 90, 100, 115),
            (200, 190, 200, 210),
            (255, 250, 252, 255),
        ],
    ),
    (
        "candy",
        &[
            (0, 255, 80, 150),
            (64, 255, 200, 80),
            (128, 80, 230, 200),
            (192, 150, 120, 255),
            (255, 255, 80, 150),
        ],
    ),
    (
        "desert",
        &[
            (0, 60, 30, 20),
            (90, 190, 120, 60),
            (170, 240, 200, 130),
            (230, 120, 170, 220),
            (255, 250, 250, 255),
        ],
    ),
    (
        "spectrum",
        &[
            (0, 255, 0, 0),
            (43, 255, 255, 0),
            (85, 0, 255, 0),
            (128, 0, 255, 255),
            (170, 0, 0, 255),
            (213, 255, 0, 255),
            (255, 255, 0, 0),
        ],
    ),
    (
        "bronze-teal",
        &[
            (0, 20, 10, 0),
            (90, 170, 110, 40),
            (150, 240, 220, 160),
            (200, 40, 160, 160),
            (255, 0, 40, 60),
        ],
    ),
    (
        "midnight",
        &[
            (0, 0, 0, 0),
            (100, 10, 20, 70),
            (180, 50, 90, 200),
            (230, 160, 200, 255),
            (255, 255, 255, 255),
        ],
    ),
    (
        "pearl",
        &[
            (0, 60, 55, 70),
            (80, 200, 190, 210),
            (150, 250, 240, 235),
            (210, 210, 230, 250),
            (255, 255, 255, 255),
        ],
    ),
    (
        "magma",
        &[
            (0, 0, 0, 4),
            (64, 80, 18, 123),
            (128, 183, 55, 121),
            (192, 252, 137, 97),
            (255, 252, 253, 191),
        ],
    ),
    (
        "tropic",
        &[
            (0, 0, 40, 50),
            (70, 0, 160, 130),
            (130, 170, 230, 60),
            (190, 255, 200, 40),
            (255, 255, 90, 60),
        ],
    ),
    ("grey", &[(0, 0, 0, 0), (255, 255, 255, 255)]),
];

/// All of ugnis's own gradients, in library order.
pub fn builtin() -> Vec<Gradient> {
    BUILTIN
        .iter()
        .map(|(name, keys)| {
            let stops: Vec<Stop> = keys
                .iter()
                .map(|&(p, r, g, b)| Stop {
                    pos: p as f64 / 255.0,
                    rgb: [r as f64 / 255.0, g as f64 / 255.0, b as f64 / 255.0],
                })
                .collect();
            let mut g = Gradient::from_stops(*name, &stops);
            // Stored with 8 bits per channel, as every file format keeps them.
            for c in &mut g.colors {
                for v in c.iter_mut().take(3) {
                    *v = (*v * 255.0).round() / 255.0;
                }
            }
            g
        })
        .collect()
}

/// A built-in gradient by name.
pub fn builtin_named(name: &str) -> Option<Gradient> {
    builtin().into_iter().find(|g| g.name == name)
}

/// The gradient new flames get when no other is chosen.
pub fn default_gradient() -> Gradient {
    builtin_named("ember").expect("ember is built in")
}

#[cfg(test)]
mod library_tests {
    use super::*;

    #[test]
    fn builtins_are_complete_and_distinct() {
        let b = builtin();
        assert!(b.len() >= 30);
        for g in &b {
            assert_eq!(g.colors.len(), 256, "{}", g.name);
            assert!(
                g.colors
                    .iter()
                    .all(|c| c.iter().all(|v| (0.0..=1.0).contains(v)))
            );
        }
        let mut names: Vec<&str> = b.iter().map(|g| g.name.as_str()).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), b.len());
        assert_eq!(default_gradient().rgb8(0), [10, 0, 20]);
        assert_eq!(default_gradient().rgb8(255), [255, 255, 255]);
    }
}

// ---------------------------------------------------------------------------------------------
// Gradients from images

/// sRGB (0..1) → Oklab.
pub fn srgb_to_oklab(c: [f64; 3]) -> [f64; 3] {
    let lin = |v: f64| {
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    let [r, g, b] = c.map(lin);
    let l = (0.412_221_470_8 * r + 0.536_332_536_3 * g + 0.051_445_992_9 * b).cbrt();
    let m = (0.211_903_498_2 * r + 0.680_699_545_1 * g + 0.107_396_956_6 * b).cbrt();
    let s = (0.088_302_461_9 * r + 0.281_718_837_6 * g + 0.629_978_700_5 * b).cbrt();
    [
        0.210_454_255_3 * l + 0.793_617_785_0 * m - 0.004_072_046_8 * s,
        1.977_998_495_1 * l - 2.428_592_205_0 * m + 0.450_593_709_9 * s,
        0.025_904_037_1 * l + 0.782_771_766_2 * m - 0.808_675_766_0 * s,
    ]
}

/// Oklab → sRGB (0..1, clamped).
pub fn oklab_to_srgb(c: [f64; 3]) -> [f64; 3] {
    let [ll, a, b] = c;
    let l = (ll + 0.396_337_777_4 * a + 0.215_803_757_3 * b).powi(3);
    let m = (ll - 0.105_561_345_8 * a - 0.063_854_172_8 * b).powi(3);
    let s = (ll - 0.089_484_177_5 * a - 1.291_485_548_0 * b).powi(3);
    let lin = [
        4.076_741_662_1 * l - 3.307_711_591_3 * m + 0.230_969_929_2 * s,
        -1.268_438_004_6 * l + 2.609_757_401_1 * m - 0.341_319_396_5 * s,
        -0.004_196_086_3 * l - 0.703_418_614_7 * m + 1.707_614_701_0 * s,
    ];
    lin.map(|v| {
        let v = v.clamp(0.0, 1.0);
        if v <= 0.003_130_8 {
            12.92 * v
        } else {
            1.055 * v.powf(1.0 / 2.4) - 0.055
        }
    })
}

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
    use crate::flame::rng::FastRng;
    if pixels.is_empty() {
        return Gradient::grey_ramp();
    }
    let mut rng = FastRng::new(seed);
    let step = (pixels.len() / 20_000).max(1);
    let samples: Vec<[f64; 3]> = pixels
        .iter()
        .step_by(step)
        .map(|p| {
            srgb_to_oklab([
                p[0] as f64 / 255.0,
                p[1] as f64 / 255.0,
                p[2] as f64 / 255.0,
            ])
        })
        .collect();
    // k-means++ seeding.
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
    let mut counts = vec![0usize; centres.len()];
    for _ in 0..15 {
        let mut sum = vec![[0.0f64; 3]; centres.len()];
        counts.iter_mut().for_each(|c| *c = 0);
        for s in &samples {
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
    let mut cl: Vec<([f64; 3], usize)> = centres
        .into_iter()
        .zip(counts)
        .filter(|c| c.1 > 0)
        .collect();
    // Path: darkest first, nearest neighbour, then 2-opt on the open path.
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
    // Positions by the square root of the cluster sizes.
    let widths: Vec<f64> = cl.iter().map(|c| (c.1 as f64).sqrt()).collect();
    let total: f64 = widths.iter().sum();
    let mut acc = 0.0;
    let keys: Vec<(f64, [f64; 3])> = cl
        .iter()
        .zip(&widths)
        .map(|(c, w)| {
            let p = (acc + w / 2.0) / total;
            acc += w;
            (p, c.0)
        })
        .collect();
    let colors: Vec<[f64; 4]> = (0..256)
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
        .collect();
    Gradient {
        name: name.to_string(),
        colors,
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

#[cfg(test)]
mod image_tests {
    use super::*;

    #[test]
    fn oklab_round_trip() {
        for c in [
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 1.0],
            [0.8, 0.2, 0.1],
            [0.1, 0.5, 0.9],
        ] {
            let back = oklab_to_srgb(srgb_to_oklab(c));
            for k in 0..3 {
                assert!((back[k] - c[k]).abs() < 1e-6, "{c:?} {back:?}");
            }
        }
        assert!((srgb_to_oklab([1.0, 1.0, 1.0])[0] - 1.0).abs() < 1e-6);
    }

    #[test]
    fn photo_like_image_gives_its_colours_in_a_smooth_order() {
        // Sky blue 50 %, sand 30 %, dark green 20 %, with noise.
        let mut rng = crate::flame::rng::FastRng::new(1);
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
