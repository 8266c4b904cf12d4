//! JWildfire's colour type DISTANCE (an xform's `color_type="DISTANCE"`): the xform leaves the
//! point's gradient position as it is and gives the point the palette colour at the entry
//! ⌊(colour + d·(symmetry + 1))·254 + ½⌋ mod 256, where d is the distance the xform moved the
//! point (from the point before the affine map to the point after the post-affine map, in
//! three dimensions), unless a direct-colour variation of the xform already gave it one. The
//! facts come from JWildfire 9.00's `XForm.initTransform`, `TransformationInitStep` and
//! `TransformationDistanceColorStep`.

use crate::flame::model::Xform;
use crate::flame::variations::{self, flag, own_rgb};

/// An xform of colour type DISTANCE, ready to colour points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DistanceColour {
    /// The xform's colour (its gradient position).
    pub color: f64,
    /// symmetry + 1, symmetry being 1 − 2·(colour speed).
    pub mult: f64,
    /// The xform draws an orbit of its own (a variation carrying its point from call to call, such
    /// as `gingerbread_man`): JWildfire's render thread moves one point, so the point
    /// such a variation is handed is the one it gave a call before; the distance is measured
    /// from there (from the previous point of the same group).
    pub chained: bool,
}

impl DistanceColour {
    /// The distance colouring of `x`, if its file names the colour type DISTANCE.
    pub fn of(x: &Xform) -> Option<DistanceColour> {
        let kind = x.extra_attrs.iter().find(|(k, _)| k == "color_type")?;
        (kind.1.trim() == "DISTANCE").then_some(DistanceColour {
            color: x.color,
            mult: 2.0 - 2.0 * x.color_speed,
            chained: x
                .vars
                .iter()
                .any(|v| variations::info(v.id).has(flag::STATEFUL)),
        })
    }

    /// The packed palette entry ([`own_rgb::INDEX`]) of a point moved by `d`. The index is
    /// converted as Java converts a double to an int (NaN to 0, saturating).
    #[inline]
    pub fn entry(&self, d: f64) -> u32 {
        let i = (((self.color + d * self.mult) * 254.0 + 0.5) as i32).rem_euclid(256);
        own_rgb::INDEX | i as u32
    }

    /// Colour the points `x, y, z` of a group that came in as `old`, where no variation gave
    /// one (`rgb[j]` still 0).
    #[inline]
    pub fn paint(&self, old: [&[f64]; 3], new: [&[f64]; 3], rgb: &mut [u32]) {
        for (j, r) in rgb.iter_mut().enumerate() {
            if *r == 0 {
                let d = (0..3)
                    .map(|k| (old[k][j] - new[k][j]).powi(2))
                    .sum::<f64>()
                    .sqrt();
                *r = self.entry(d);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::model::Affine;

    #[test]
    fn entries_follow_javas_index_rule() {
        let mut x = Xform::linear(Affine::IDENTITY, 1.0, 0.42);
        x.color_speed = 1.0; // symmetry −1: the distance is not used
        assert_eq!(DistanceColour::of(&x), None);
        x.extra_attrs.push(("color_type".into(), "DISTANCE".into()));
        let d = DistanceColour::of(&x).unwrap();
        assert_eq!(d.mult, 0.0);
        assert_eq!(d.entry(5.0), own_rgb::INDEX | 107); // 0.42·254 + ½ = 107.18
        x.color = 0.0;
        x.color_speed = 0.985; // symmetry −0.97
        let d = DistanceColour::of(&x).unwrap();
        assert!((d.mult - 0.03).abs() < 1e-12);
        assert_eq!(d.entry(10.0), own_rgb::INDEX | 76); // 0.3·254 + ½ = 76.7
        assert_eq!(d.entry(100.0), own_rgb::INDEX | (762 % 256)); // wraps
        assert_eq!(d.entry(f64::NAN), own_rgb::INDEX);
        assert_eq!(d.entry(f64::INFINITY), own_rgb::INDEX | 255); // i32::MAX mod 256
    }

    #[test]
    fn paint_keeps_colours_a_variation_gave() {
        let mut x = Xform::linear(Affine::IDENTITY, 1.0, 0.0);
        x.color_speed = 0.0; // symmetry 1: twice the distance
        x.extra_attrs.push(("color_type".into(), "DISTANCE".into()));
        let d = DistanceColour::of(&x).unwrap();
        let old = [&[0.0, 0.0][..], &[0.0, 0.0][..], &[0.0, 0.0][..]];
        let new = [&[0.3, 0.3][..], &[0.4, 0.4][..], &[0.0, 0.0][..]];
        let mut rgb = [0, own_rgb::OWN | 0x123456];
        d.paint(old, new, &mut rgb);
        // d = 0.5: (0 + 0.5·2)·254 + ½ = 254.5.
        assert_eq!(rgb, [own_rgb::INDEX | 254, own_rgb::OWN | 0x123456]);
    }
}
