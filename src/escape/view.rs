//! The visible rectangle of an escape-time picture: its centre to any number of decimal
//! digits and its half-height as an extended-exponent number (so views of 1e-1000 and
//! beyond exist), and the maps between pixels and world points (exact at deep zoom).

use super::centre::Centre;
use super::complex::C;
use super::dd::Dd;
use super::fx::{Cx, Fx};

/// Digits after the decimal point a centre keeps for a half-height: a millionth of a
/// pixel of the largest pictures, and never fewer than f64 shows.
fn digits_for(half: Fx) -> u32 {
    let d = (-half.log10()).ceil() + 12.0;
    if d.is_finite() {
        d.clamp(17.0, super::centre::MAX_DIGITS as f64) as u32
    } else {
        17
    }
}

/// The visible rectangle: centre and half-height (the width follows the image's aspect).
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    /// The centre (x, y) in the complex plane, to any number of digits.
    centre: Centre,
    /// The centre rounded to f64 (what shallow views compute with).
    c64: [f64; 2],
    /// Half the visible height in world units.
    half: Fx,
}

impl View {
    /// A view centred on `center` showing `half_height` above and below it.
    pub fn new(center: [f64; 2], half_height: f64) -> View {
        View::from_centre(Centre::from_f64(center), Fx::from_f64(half_height))
    }

    /// A view with an exact centre and an extended half-height.
    pub fn from_centre(centre: Centre, half: Fx) -> View {
        let centre = centre.with_digits(digits_for(half));
        View {
            c64: centre.to_f64(),
            centre,
            half,
        }
    }

    /// A view from Fractint-style corners.
    pub fn from_corners(xmin: f64, xmax: f64, ymin: f64, ymax: f64) -> View {
        View::new(
            [(xmin + xmax) / 2.0, (ymin + ymax) / 2.0],
            (ymax - ymin).abs() / 2.0,
        )
    }

    /// The centre rounded to f64.
    pub fn center(&self) -> [f64; 2] {
        self.c64
    }

    /// The exact centre.
    pub fn centre(&self) -> &Centre {
        &self.centre
    }

    /// The centre's coordinates as decimal text, with the digits the zoom needs (more
    /// would only repeat what the picture cannot show).
    pub fn centre_text(&self) -> [String; 2] {
        self.centre.rounded(digits_for(self.half)).format()
    }

    /// The same half-height around another centre.
    pub fn with_centre(&self, c: Centre) -> View {
        View::from_centre(c, self.half)
    }

    /// Half the visible height in world units, as f64 (0 below f64's range).
    pub fn half_height(&self) -> f64 {
        self.half.to_f64()
    }

    /// Half the visible height in world units.
    pub fn half_height_fx(&self) -> Fx {
        self.half
    }

    /// Set the half-height (world units).
    pub fn set_half_height(&mut self, h: f64) {
        self.set_half_height_fx(Fx::from_f64(h));
    }

    /// Set the half-height (world units); the centre gains the digits the zoom needs.
    pub fn set_half_height_fx(&mut self, h: Fx) {
        *self = View::from_centre(self.centre.clone(), h);
    }

    /// The half-height multiplied by `factor` (same centre).
    pub fn scaled(&self, factor: f64) -> View {
        View::from_centre(self.centre.clone(), self.half.scale(factor))
    }

    /// The centre to double-double precision.
    pub fn center_dd(&self) -> [Dd; 2] {
        let hi = self.c64;
        let lo = Centre::from_f64_exact(hi).offset_to(&self.centre);
        [
            Dd::new(hi[0], lo[0].to_f64()),
            Dd::new(hi[1], lo[1].to_f64()),
        ]
    }

    /// A view with the given double-double centre.
    pub fn with_center_dd(&self, c: [Dd; 2]) -> View {
        let hi = Centre::from_f64_exact([c[0].hi, c[1].hi]);
        let centre = hi.shifted(Fx::from_f64(c[0].lo), Fx::from_f64(c[1].lo));
        self.with_centre(centre.with_digits(digits_for(self.half).max(40)))
    }

    /// The view moved by (dx, dy) world units.
    pub fn shifted(&self, dx: f64, dy: f64) -> View {
        self.shifted_fx(Fx::from_f64(dx), Fx::from_f64(dy))
    }

    /// The view moved by (dx, dy) world units, exactly to the digits the view keeps.
    pub fn shifted_fx(&self, dx: Fx, dy: Fx) -> View {
        self.with_centre(self.centre.shifted(dx, dy))
    }

    /// Offset of pixel (i, j) from the centre in units of the half-height.
    fn unit_offset(i: f64, j: f64, w: u32, h: u32) -> C {
        let (w, h) = (w as f64, h as f64);
        C::new(
            (2.0 * (i + 0.5) / w - 1.0) * w / h,
            -(2.0 * (j + 0.5) / h - 1.0),
        )
    }

    /// Offset of pixel (i, j) from the centre, in world units.
    pub fn offset_from_pixel(&self, i: f64, j: f64, w: u32, h: u32) -> C {
        View::unit_offset(i, j, w, h) * self.half.to_f64()
    }

    /// Offset of pixel (i, j) from the centre, in world units, at any depth.
    pub fn offset_from_pixel_fx(&self, i: f64, j: f64, w: u32, h: u32) -> Cx {
        let u = View::unit_offset(i, j, w, h);
        Cx::new(u.re * self.half.m, u.im * self.half.m, self.half.e)
    }

    /// World point of pixel (i, j), rows from the top; the imaginary axis points up.
    pub fn world_from_pixel(&self, i: f64, j: f64, w: u32, h: u32) -> C {
        let o = self.offset_from_pixel(i, j, w, h);
        C::new(self.c64[0] + o.re, self.c64[1] + o.im)
    }

    /// Where `other`'s centre lies from this view's, in world units (exact difference of the
    /// centres, so it is right at deep zoom too).
    pub fn offset_to(&self, other: &View) -> C {
        self.offset_to_fx(other).to_c()
    }

    /// Where `other`'s centre lies from this view's, at any depth.
    pub fn offset_to_fx(&self, other: &View) -> Cx {
        let [x, y] = self.centre.offset_to(&other.centre);
        Cx::from_parts(x, y)
    }

    /// Pixel coordinates (continuous, the pixel's centre at i + 0.5) of a world point.
    pub fn pixel_from_world(&self, p: C, w: u32, h: u32) -> [f64; 2] {
        let (wf, hf) = (w as f64, h as f64);
        let hh = self.half.to_f64();
        let i = ((p.re - self.c64[0]) / (hh * wf / hf) + 1.0) * wf / 2.0;
        let j = (1.0 - (p.im - self.c64[1]) / hh) * hf / 2.0;
        [i, j]
    }

    /// Pixel coordinates in this view of pixel (i, j) of `other` (same image size), computed
    /// from the exact difference of the centres (valid at any depth).
    pub fn pixel_of(&self, other: &View, i: f64, j: f64, w: u32, h: u32) -> [f64; 2] {
        let o = self
            .offset_to_fx(other)
            .add(other.offset_from_pixel_fx(i, j, w, h));
        // In units of this view's half-height.
        let u = Cx::new(o.re, o.im, o.e.saturating_sub(self.half.e)).scale(1.0 / self.half.m);
        let u = u.to_c();
        let (wf, hf) = (w as f64, h as f64);
        [(u.re / (wf / hf) + 1.0) * wf / 2.0, (1.0 - u.im) * hf / 2.0]
    }

    /// World size of one pixel (0 below f64's range).
    pub fn pixel_size(&self, h: u32) -> f64 {
        self.pixel_size_fx(h).to_f64()
    }

    /// World size of one pixel.
    pub fn pixel_size_fx(&self, h: u32) -> Fx {
        self.half.scale(2.0 / h.max(1) as f64)
    }

    /// The view zoomed by `factor` (> 1 zooms in) keeping the world point under pixel
    /// (i, j) fixed.
    pub fn zoomed_at(&self, i: f64, j: f64, w: u32, h: u32, factor: f64) -> View {
        let o = self
            .offset_from_pixel_fx(i - 0.5, j - 0.5, w, h)
            .scale(1.0 - 1.0 / factor);
        let moved = self
            .centre
            .with_digits(digits_for(self.half.scale(1.0 / factor)));
        let x = Fx::new(o.re, o.e);
        let y = Fx::new(o.im, o.e);
        View::from_centre(moved.shifted(x, y), self.half.scale(1.0 / factor))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deep_views_keep_their_centre_beyond_f64() {
        // Pan by 1e-25 at a 1e-22 zoom: the f64 centre cannot change, the exact one does,
        // and the pixel mapping between the two views sees the exact shift.
        let v = View::new([-0.75, 0.1], 1e-22);
        let p = v.shifted(1e-25, 0.0);
        assert_eq!(p.center(), v.center());
        assert_ne!(p.centre(), v.centre());
        let px = v.pixel_of(&p, 0.0, 0.0, 400, 300);
        let one = 2.0 * 1e-22 / 300.0;
        assert!((px[0] - (0.5 + 1e-25 / one)).abs() < 1e-6, "{px:?}");
        // Zooming at a pixel keeps the point under it.
        let z = v.zoomed_at(100.0, 50.0, 400, 300, 4.0);
        let back = v.pixel_of(&z, 99.5, 49.5, 400, 300);
        assert!((back[0] - 100.0).abs() < 1e-6 && (back[1] - 50.0).abs() < 1e-6);
    }

    #[test]
    fn views_far_below_f64_zoom_pan_and_map_pixels() {
        let mut v = View::new([-1.75, 0.0], 1.0);
        v.set_half_height_fx(Fx::parse("1e-1000").unwrap());
        assert!(v.centre().digits() >= 1012);
        assert_eq!(v.half_height(), 0.0);
        let z = v.zoomed_at(10.0, 20.0, 64, 48, 1e5);
        assert!((z.half_height_fx().log10() + 1005.0).abs() < 1e-9);
        let back = v.pixel_of(&z, 9.5, 19.5, 64, 48);
        assert!(
            (back[0] - 10.0).abs() < 1e-6 && (back[1] - 20.0).abs() < 1e-6,
            "{back:?}"
        );
        let o = v.offset_from_pixel_fx(0.0, 0.0, 64, 48);
        assert!((o.abs().log10() + 1000.0).abs() < 0.3);
    }
}
