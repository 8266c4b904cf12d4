//! The palette entry nearest to a colour, for the variations that give a point the palette
//! position of a colour (JWildfire's image variations: `colormap_wf` with `dc_color` > 0,
//! `displacemap_wf` with `color_mode` 1, `kaleidoimg`). The rule follows JWildfire 9.00's
//! `getColorIdx` of `AbstractColorMapWFFunc` and `AbstractDisplacementMapWFFunc`:
//!
//! * the palette is the flame's N entries as its renderer keeps them
//!   (`RGBPalette.createRenderPalette`): each byte times 200/256 (`RenderColor`, whatever the
//!   white level), so a colour given in bytes is compared with palette colours of at most
//!   199.2 per channel;
//! * the distance is Euclidean over red, green and blue; the first of equally near entries
//!   wins;
//! * the point's colour coordinate becomes index / (N − 1).
//!
//! A variation receives the table when its xform is compiled for the chaos game
//! ([`super::Prepared::give_palette`], from the flame's current gradient), so the index persists
//! into the next iterations as any colour coordinate does.
//!
//! The lookup is exact and cheap: the colour cube [0, 256)³ is cut into 16³ cells and each cell
//! keeps, in palette order, only the entries that can be nearest to some colour inside it (an
//! entry whose least distance to the cell exceeds the smallest greatest distance of any entry
//! cannot); repeated palette colours keep their first entry only (a later copy is never
//! strictly nearer). Colours outside the cube (and NaN) scan the whole palette.

/// Cells per channel.
const CELLS: usize = 16;
/// Width of a cell in colour units.
const CELL: f64 = 256.0 / CELLS as f64;

/// JWildfire's palette scale: a palette byte b counts b·200/256.
const RENDER_SCALE: f64 = 200.0 / 256.0;

/// A palette prepared for nearest-colour lookups.
#[derive(Debug, Clone, PartialEq)]
pub struct PaletteIndex {
    /// Number of palette entries (N).
    n: usize,
    /// Distinct colours (render units) with the first entry showing each, in palette order.
    keys: Vec<([f64; 3], u16)>,
    /// Cell c's candidates are `cand[start[c]..start[c + 1]]` (indices into `keys`).
    start: Vec<u32>,
    cand: Vec<u16>,
}

impl PaletteIndex {
    /// The table of a palette given as bytes (at most 65 536 entries are used; an empty
    /// palette acts as one black entry).
    pub fn new(bytes: &[[u8; 3]]) -> PaletteIndex {
        let bytes = &bytes[..bytes.len().min(u16::MAX as usize + 1)];
        let mut keys: Vec<([f64; 3], u16)> = Vec::new();
        let mut seen = std::collections::HashSet::new();
        for (i, b) in bytes.iter().enumerate() {
            if seen.insert(*b) {
                keys.push((b.map(|v| f64::from(v) * RENDER_SCALE), i as u16));
            }
        }
        if keys.is_empty() {
            keys.push(([0.0; 3], 0));
        }
        let mut start = Vec::with_capacity(CELLS * CELLS * CELLS + 1);
        let mut cand = Vec::new();
        let mut reach = vec![(0.0, 0.0); keys.len()];
        for c in 0..CELLS * CELLS * CELLS {
            let lo = [c / (CELLS * CELLS), (c / CELLS) % CELLS, c % CELLS].map(|k| k as f64 * CELL);
            let mut bound = f64::INFINITY;
            for (k, (q, _)) in keys.iter().enumerate() {
                let (mut near, mut far) = (0.0, 0.0);
                for ch in 0..3 {
                    let (a, b) = (lo[ch], lo[ch] + CELL);
                    let d = if q[ch] < a {
                        a - q[ch]
                    } else if q[ch] > b {
                        q[ch] - b
                    } else {
                        0.0
                    };
                    near += d * d;
                    let f = (q[ch] - a).abs().max((q[ch] - b).abs());
                    far += f * f;
                }
                reach[k] = (near, far);
                bound = bound.min(far);
            }
            start.push(cand.len() as u32);
            // A little slack: keeping an extra candidate costs a comparison, never a result.
            let bound = bound * (1.0 + 1e-9) + 1e-9;
            cand.extend(
                (0..keys.len())
                    .filter(|&k| reach[k].0 <= bound)
                    .map(|k| k as u16),
            );
        }
        start.push(cand.len() as u32);
        PaletteIndex {
            n: bytes.len().max(1),
            keys,
            start,
            cand,
        }
    }

    /// JWildfire's palette of a layer whose colours were never set: 256 black entries (what
    /// its variations see outside a loaded flame).
    pub fn unset() -> PaletteIndex {
        PaletteIndex::new(&[[0; 3]; 256])
    }

    /// The palette from colours as a flame keeps them (red, green, blue, alpha in [0, 1]):
    /// each channel times its alpha, as a byte.
    pub fn from_colors(colors: &[[f64; 4]]) -> PaletteIndex {
        let byte = |v: f64, a: f64| {
            let u = (v * a.clamp(0.0, 1.0) * 255.0).round();
            if u.is_nan() {
                0
            } else {
                u.clamp(0.0, 255.0) as u8
            }
        };
        let bytes: Vec<[u8; 3]> = colors
            .iter()
            .map(|c| [byte(c[0], c[3]), byte(c[1], c[3]), byte(c[2], c[3])])
            .collect();
        PaletteIndex::new(&bytes)
    }

    /// The index of the palette entry nearest to the colour (r, g, b), compared with the
    /// palette in its render units (bytes × 200/256).
    #[inline]
    pub fn nearest(&self, r: f64, g: f64, b: f64) -> usize {
        let cell = |v: f64| {
            if (0.0..256.0).contains(&v) {
                Some((v / CELL) as usize)
            } else {
                None
            }
        };
        let best = match (cell(r), cell(g), cell(b)) {
            (Some(i), Some(j), Some(k)) => {
                let c = (i * CELLS + j) * CELLS + k;
                let (s, e) = (self.start[c] as usize, self.start[c + 1] as usize);
                let keys = self.cand[s..e].iter().map(|&k| &self.keys[k as usize]);
                Self::scan(keys, r, g, b)
            }
            _ => Self::scan(self.keys.iter(), r, g, b),
        };
        best as usize
    }

    /// The first entry of least distance among `keys` (in palette order); the first entry
    /// when every distance is NaN, as JWildfire's strict comparison leaves it.
    #[inline]
    fn scan<'a>(keys: impl Iterator<Item = &'a ([f64; 3], u16)>, r: f64, g: f64, b: f64) -> u16 {
        let mut best = (f64::NAN, 0u16);
        let mut first = true;
        for (q, i) in keys {
            let (dr, dg, db) = (q[0] - r, q[1] - g, q[2] - b);
            let d = (dr * dr + dg * dg + db * db).sqrt();
            if first || d < best.0 {
                best = (d, *i);
                first = false;
            }
        }
        best.1
    }

    /// The colour coordinate of the entry nearest to (r, g, b): index / (N − 1) (0 for a
    /// palette of one entry).
    #[inline]
    pub fn coordinate(&self, r: f64, g: f64, b: f64) -> f64 {
        if self.n < 2 {
            return 0.0;
        }
        self.nearest(r, g, b) as f64 / (self.n - 1) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::rng::FastRng;

    /// JWildfire's rule, entry by entry.
    fn slow(pal: &[[u8; 3]], r: f64, g: f64, b: f64) -> usize {
        let mut best = (f64::INFINITY, 0);
        for (i, p) in pal.iter().enumerate() {
            let q = p.map(|v| f64::from(v) * 200.0 / 256.0);
            let d = ((q[0] - r).powi(2) + (q[1] - g).powi(2) + (q[2] - b).powi(2)).sqrt();
            if i == 0 || d < best.0 {
                best = (d, i);
            }
        }
        best.1
    }

    #[test]
    fn nearest_entry_is_jwildfires_first_of_equals() {
        // A ramp of red with repeats: entries 0–127 red 2k, then 128–255 the same again.
        let pal: Vec<[u8; 3]> = (0..256).map(|i| [((i % 128) * 2) as u8, 0, 40]).collect();
        let t = PaletteIndex::new(&pal);
        // Byte 100 scaled is 78.125; red 100 is nearest to the entry whose scaled red is
        // nearest 100: 2k·0.78125 ≈ 100 → k = 64 (100.0 exactly): entry 64, not its copy 192.
        assert_eq!(t.nearest(100.0, 0.0, 31.25), 64);
        assert_eq!(t.coordinate(100.0, 0.0, 31.25), 64.0 / 255.0);
        // Halfway between two entries (scaled reds 1.5625 and 3.125): the first wins.
        assert_eq!(t.nearest(2.34375, 0.0, 31.25), 1);
        // Outside the cube and NaN: the whole palette, NaN giving entry 0.
        assert_eq!(t.nearest(500.0, 0.0, 31.25), 127);
        assert_eq!(t.nearest(f64::NAN, 0.0, 0.0), 0);
        // Against the entry-by-entry rule on random palettes and colours.
        let mut rng = FastRng::new(7);
        for _ in 0..20 {
            let pal: Vec<[u8; 3]> = (0..256)
                .map(|_| [0; 3].map(|_: u8| (rng.f01() * 256.0) as u8 & 0xf8))
                .collect();
            let t = PaletteIndex::new(&pal);
            for _ in 0..500 {
                let c = [0; 3].map(|_: u8| (rng.f01() * 256.0).floor());
                assert_eq!(t.nearest(c[0], c[1], c[2]), slow(&pal, c[0], c[1], c[2]));
                let u = [0; 3].map(|_: u8| rng.f01());
                assert_eq!(t.nearest(u[0], u[1], u[2]), slow(&pal, u[0], u[1], u[2]));
            }
        }
        // A black palette: always entry 0.
        assert_eq!(PaletteIndex::unset().coordinate(255.0, 10.0, 3.0), 0.0);
    }

    #[test]
    fn flame_colours_become_bytes() {
        let t = PaletteIndex::from_colors(&[[1.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0]]);
        assert_eq!(t.nearest(0.0, 0.0, 200.0), 1);
        assert_eq!(t.coordinate(199.0, 0.0, 0.0), 0.0);
        assert_eq!(t.coordinate(0.0, 0.0, 199.0), 1.0);
    }
}
