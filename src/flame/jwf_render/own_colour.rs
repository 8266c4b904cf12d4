//! Points with a colour of their own in JWildfire's renderer (its direct colour): the colour a
//! variation gave the point is plotted instead of the palette's, as its bytes stand, or the
//! palette colour nearest to it (JWildfire's Gradient = 1, nearest by squared distance over
//! red, green and blue, the first of equals winning). The facts come from JWildfire 9.00's
//! `DefaultRenderIterationState` (the plotted colour is the point's red, green and blue,
//! whichever set them), `RenderColor` (palette colours scaled to 200 for 255) and the
//! `findKey` of its `dc_` variations. A point may also carry a palette entry of its own
//! (JWildfire's colour type DISTANCE, [`super::colour_type`]), drawn as the palette draws it.

use super::develop::PALETTE_WHITE;
use crate::flame::histogram::{Histogram, PlotPalette};
use crate::flame::variations::own_rgb;

/// A sample with an own colour: bucket, packed colour ([`own_rgb`]), visibility.
pub(crate) type OwnSample = (u32, u32, f32);

/// JWildfire adds an own colour's bytes as they are, a palette colour at 200/256 of its
/// bytes; the histogram counts a palette byte k as k, so an own byte b counts b·256/200.
const OWN_GAIN: f32 = (256.0 / PALETTE_WHITE) as f32;

/// Slots of the nearest-colour cache (a power of two).
const CACHE: usize = 4096;

/// The palette colour nearest to a colour, with a small direct-mapped cache (a pattern
/// repeats its colours).
pub(super) struct NearestKey {
    keys: Vec<[i32; 3]>,
    cache: Vec<(u32, [u8; 3])>,
}

impl NearestKey {
    pub(super) fn new(pal: &PlotPalette) -> NearestKey {
        let keys = pal
            .colors
            .iter()
            .map(|c| [c[0], c[1], c[2]].map(|v| v.round().clamp(0.0, 255.0) as i32))
            .collect();
        NearestKey {
            keys,
            cache: vec![(u32::MAX, [0; 3]); CACHE],
        }
    }

    /// The palette colour nearest to the packed colour `p`.
    pub(super) fn find(&mut self, p: u32) -> [u8; 3] {
        let rgb = p & 0xff_ffff;
        let slot = ((rgb ^ (rgb >> 12)) as usize) & (CACHE - 1);
        if self.cache[slot].0 == rgb {
            return self.cache[slot].1;
        }
        let c = own_rgb::channels(p).map(|v| v as i32);
        let mut best = (i32::MAX, [0u8; 3]);
        for k in &self.keys {
            let d: i32 = (0..3).map(|i| (c[i] - k[i]) * (c[i] - k[i])).sum();
            if d < best.0 {
                best = (d, k.map(|v| v as u8));
            }
        }
        self.cache[slot] = (rgb, best.1);
        best.1
    }
}

/// Add samples with own colours to a histogram (alpha: the visibility, as a palette colour
/// of full opacity).
pub(crate) fn accumulate_own(pal: &PlotPalette, hist: &mut Histogram, buf: &[OwnSample]) {
    if buf.is_empty() {
        return;
    }
    let mut near = NearestKey::new(pal);
    let top = pal.colors.len().saturating_sub(1);
    for &(idx, p, v) in buf {
        if p & own_rgb::INDEX != 0 {
            // A palette entry, added as the palette's colours are.
            let c = pal.colors[(p as usize & 0xff).min(top)];
            let b = &mut hist.data[idx as usize];
            for k in 0..4 {
                b[k] += c[k] * v;
            }
            continue;
        }
        let rgb = if p & own_rgb::NEAREST != 0 {
            near.find(p)
        } else {
            own_rgb::channels(p)
        };
        let g = OWN_GAIN * v;
        let b = &mut hist.data[idx as usize];
        b[0] += rgb[0] as f32 * g;
        b[1] += rgb[1] as f32 * g;
        b[2] += rgb[2] as f32 * g;
        b[3] += v;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::model::Flame;

    #[test]
    fn nearest_key_is_the_first_closest_palette_colour() {
        let rgb: Vec<[u8; 3]> = (0..=255).map(|i| [i, 0, 255]).collect();
        let f = Flame {
            palette: crate::gradient::Gradient::from_rgb8("ramp", &rgb),
            ..Flame::default()
        };
        let pal = PlotPalette::new(&f);
        let mut n = NearestKey::new(&pal);
        let pack = |r: u32, g: u32, b: u32| own_rgb::NEAREST | r << 16 | g << 8 | b;
        assert_eq!(n.find(pack(100, 3, 250)), [100, 0, 255]);
        // Twice, from the cache.
        assert_eq!(n.find(pack(100, 3, 250)), [100, 0, 255]);
        assert_eq!(n.find(pack(255, 255, 255)), [255, 0, 255]);
    }
}
