//! The visible rectangle of an escape-time picture: its centre to double-double precision
//! and its half-height, and the maps between pixels and world points (exact at deep zoom).

use super::complex::C;
use super::dd::Dd;

/// The visible rectangle: centre and half-height (the width follows the image's aspect).
/// The centre is the double-double `center + center_lo` (the low parts are zero until a
/// deep zoom needs them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// High part of the centre (x, y) in the complex plane.
    pub center: [f64; 2],
    /// Low part of the centre (zero unless a deep zoom needs it).
    pub center_lo: [f64; 2],
    /// Half the visible height in world units.
    pub half_height: f64,
}

impl View {
    /// A view centred on `center` showing `half_height` above and below it.
    pub fn new(center: [f64; 2], half_height: f64) -> View {
        View {
            center,
            center_lo: [0.0; 2],
            half_height,
        }
    }

    /// A view from Fractint-style corners.
    pub fn from_corners(xmin: f64, xmax: f64, ymin: f64, ymax: f64) -> View {
        View::new(
            [(xmin + xmax) / 2.0, (ymin + ymax) / 2.0],
            (ymax - ymin).abs() / 2.0,
        )
    }

    /// The centre to double-double precision.
    pub fn center_dd(&self) -> [Dd; 2] {
        [
            Dd::new(self.center[0], self.center_lo[0]),
            Dd::new(self.center[1], self.center_lo[1]),
        ]
    }

    /// A view with the given double-double centre.
    pub fn with_center_dd(&self, c: [Dd; 2]) -> View {
        View {
            center: [c[0].hi, c[1].hi],
            center_lo: [c[0].lo, c[1].lo],
            half_height: self.half_height,
        }
    }

    /// The view moved by (dx, dy) world units, exactly to double-double precision.
    pub fn shifted(&self, dx: f64, dy: f64) -> View {
        let [x, y] = self.center_dd();
        self.with_center_dd([x + Dd::from_f64(dx), y + Dd::from_f64(dy)])
    }

    /// Offset of pixel (i, j) from the centre, in world units.
    pub fn offset_from_pixel(&self, i: f64, j: f64, w: u32, h: u32) -> C {
        let (w, h) = (w as f64, h as f64);
        C::new(
            (2.0 * (i + 0.5) / w - 1.0) * self.half_height * w / h,
            -(2.0 * (j + 0.5) / h - 1.0) * self.half_height,
        )
    }

    /// World point of pixel (i, j), rows from the top; the imaginary axis points up.
    pub fn world_from_pixel(&self, i: f64, j: f64, w: u32, h: u32) -> C {
        let o = self.offset_from_pixel(i, j, w, h);
        C::new(self.center[0] + o.re, self.center[1] + o.im)
    }

    /// Where `other`'s centre lies from this view's, in world units (double-double
    /// difference, so it is exact at deep zoom too).
    pub fn offset_to(&self, other: &View) -> C {
        let [a, b] = self.center_dd();
        let [c, d] = other.center_dd();
        C::new((c - a).to_f64(), (d - b).to_f64())
    }

    /// Pixel coordinates (continuous, the pixel's centre at i + 0.5) of a world point.
    pub fn pixel_from_world(&self, p: C, w: u32, h: u32) -> [f64; 2] {
        let (wf, hf) = (w as f64, h as f64);
        let i = ((p.re - self.center[0]) / (self.half_height * wf / hf) + 1.0) * wf / 2.0;
        let j = (1.0 - (p.im - self.center[1]) / self.half_height) * hf / 2.0;
        [i, j]
    }

    /// Pixel coordinates in this view of pixel (i, j) of `other` (same image size), computed
    /// from the double-double difference of the centres (valid at deep zoom).
    pub fn pixel_of(&self, other: &View, i: f64, j: f64, w: u32, h: u32) -> [f64; 2] {
        let o = self.offset_to(other) + other.offset_from_pixel(i, j, w, h);
        let (wf, hf) = (w as f64, h as f64);
        [
            (o.re / (self.half_height * wf / hf) + 1.0) * wf / 2.0,
            (1.0 - o.im / self.half_height) * hf / 2.0,
        ]
    }

    /// World size of one pixel.
    pub fn pixel_size(&self, h: u32) -> f64 {
        2.0 * self.half_height / h.max(1) as f64
    }

    /// The view zoomed by `factor` (> 1 zooms in) keeping the world point under pixel
    /// (i, j) fixed.
    pub fn zoomed_at(&self, i: f64, j: f64, w: u32, h: u32, factor: f64) -> View {
        let o = self.offset_from_pixel(i - 0.5, j - 0.5, w, h);
        let k = 1.0 - 1.0 / factor;
        View {
            half_height: self.half_height / factor,
            ..self.shifted(o.re * k, o.im * k)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deep_views_keep_their_centre_beyond_f64() {
        // Pan by 1e-25 at a 1e-22 zoom: the f64 centre cannot change, the double-double does,
        // and the pixel mapping between the two views sees the exact shift.
        let v = View::new([-0.75, 0.1], 1e-22);
        let p = v.shifted(1e-25, 0.0);
        assert_eq!(p.center, v.center);
        assert_ne!(p.center_lo, v.center_lo);
        let px = v.pixel_of(&p, 0.0, 0.0, 400, 300);
        let one = 2.0 * 1e-22 / 300.0;
        assert!((px[0] - (0.5 + 1e-25 / one)).abs() < 1e-6, "{px:?}");
        // Zooming at a pixel keeps the point under it, to double-double precision.
        let z = v.zoomed_at(100.0, 50.0, 400, 300, 4.0);
        let back = v.pixel_of(&z, 99.5, 49.5, 400, 300);
        assert!((back[0] - 100.0).abs() < 1e-6 && (back[1] - 50.0).abs() < 1e-6);
    }
}
