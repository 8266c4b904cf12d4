//! Pictures of Explore's segment and point sources: framing of world coordinates into an
//! image, anti-aliased lines (Xiaolin Wu's algorithm, "An efficient antialiasing technique",
//! SIGGRAPH 1991) and log-density point plots.

use image::RgbImage;

use super::{Bounds, ExploreError, P2};

/// Largest side of an image.
pub const MAX_SIDE: u32 = 16384;
/// Most pixels of an image (3 bytes each).
pub const MAX_PIXELS: u64 = 100_000_000;

/// Refuse image sizes beyond the limits, or beyond the memory the machine has free.
pub fn check_size(width: u32, height: u32) -> Result<(), ExploreError> {
    super::check_range("the image width", width as f64, 1.0, MAX_SIDE as f64)?;
    super::check_range("the image height", height as f64, 1.0, MAX_SIDE as f64)?;
    let px = width as u64 * height as u64;
    if px > MAX_PIXELS {
        return Err(ExploreError::TooLarge {
            what: format!("a {width}x{height} image"),
            count: px as f64,
            limit: MAX_PIXELS as f64,
            hint: " pixels".into(),
        });
    }
    // Lines are drawn straight into an 8-bit RGB image; density plots add 4 bytes of counts.
    let need = px * 7;
    if let Some(avail) = crate::flame::render::available_memory()
        && need > avail
    {
        return Err(ExploreError::Invalid(format!(
            "a {width}x{height} image needs about {} MiB; only {} MiB are free",
            need >> 20,
            avail >> 20
        )));
    }
    Ok(())
}

/// A uniform scaling of world coordinates (y up) into pixel coordinates (y down, pixel
/// centres at integers) that fits given bounds into the image with a margin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Framing {
    /// Pixels per world unit.
    pub scale: f64,
    /// World point shown at the image centre.
    pub center: P2,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

impl Framing {
    /// Fit `bounds` into a width×height image leaving `margin` pixels on every side.
    pub fn fit(bounds: Bounds, width: u32, height: u32, margin: f64) -> Framing {
        let (w, h) = (width as f64, height as f64);
        let aw = (w - 2.0 * margin).max(1.0);
        let ah = (h - 2.0 * margin).max(1.0);
        let (bw, bh) = if bounds.is_empty() {
            (0.0, 0.0)
        } else {
            (bounds.width(), bounds.height())
        };
        let sx = if bw > 0.0 { aw / bw } else { f64::INFINITY };
        let sy = if bh > 0.0 { ah / bh } else { f64::INFINITY };
        let mut scale = sx.min(sy);
        if !scale.is_finite() {
            scale = 1.0;
        }
        let center = if bounds.is_empty() {
            [0.0, 0.0]
        } else {
            [
                0.5 * (bounds.min[0] + bounds.max[0]),
                0.5 * (bounds.min[1] + bounds.max[1]),
            ]
        };
        Framing {
            scale,
            center,
            width,
            height,
        }
    }

    /// The pixel coordinates (pixel centres at integers, y down) of world point `p`.
    #[inline]
    pub fn pixel_from_world(&self, p: P2) -> P2 {
        [
            (p[0] - self.center[0]) * self.scale + 0.5 * self.width as f64 - 0.5,
            0.5 * self.height as f64 - 0.5 - (p[1] - self.center[1]) * self.scale,
        ]
    }

    /// The world point at pixel coordinates `q` (the inverse of
    /// [`Framing::pixel_from_world`]).
    #[inline]
    pub fn world_from_pixel(&self, q: P2) -> P2 {
        [
            (q[0] + 0.5 - 0.5 * self.width as f64) / self.scale + self.center[0],
            (0.5 * self.height as f64 - 0.5 - q[1]) / self.scale + self.center[1],
        ]
    }
}

/// The 16 colours of Fractint's default (EGA) palette; colour indices wrap around it.
pub const EGA: [[u8; 3]; 16] = [
    [0, 0, 0],
    [0, 0, 170],
    [0, 170, 0],
    [0, 170, 170],
    [170, 0, 0],
    [170, 0, 170],
    [170, 85, 0],
    [170, 170, 170],
    [85, 85, 85],
    [85, 85, 255],
    [85, 255, 85],
    [85, 255, 255],
    [255, 85, 85],
    [255, 85, 255],
    [255, 255, 85],
    [255, 255, 255],
];

/// The colour of a turtle colour index.
pub fn palette_color(index: i64) -> [u8; 3] {
    EGA[index.rem_euclid(16) as usize]
}

/// An 8-bit RGB image to draw anti-aliased lines on.
#[derive(Clone, Debug)]
pub struct Canvas {
    /// The picture drawn so far.
    pub image: RgbImage,
}

impl Canvas {
    /// A `width`×`height` canvas filled with `background`; fails for a size the memory or
    /// the pixel limit does not allow.
    pub fn new(width: u32, height: u32, background: [u8; 3]) -> Result<Canvas, ExploreError> {
        check_size(width, height)?;
        Ok(Canvas {
            image: RgbImage::from_pixel(width, height, image::Rgb(background)),
        })
    }

    #[inline]
    fn blend(&mut self, x: i64, y: i64, c: [u8; 3], a: f64) {
        if x < 0 || y < 0 || x >= self.image.width() as i64 || y >= self.image.height() as i64 {
            return;
        }
        let a = a.clamp(0.0, 1.0);
        let p = self.image.get_pixel_mut(x as u32, y as u32);
        for (pv, cv) in p.0.iter_mut().zip(c) {
            let v = *pv as f64 * (1.0 - a) + cv as f64 * a;
            *pv = (v + 0.5) as u8;
        }
    }

    /// A one-pixel anti-aliased line between pixel coordinates (Wu's algorithm).
    pub fn line(&mut self, p0: P2, p1: P2, c: [u8; 3]) {
        if !(p0[0].is_finite() && p0[1].is_finite() && p1[0].is_finite() && p1[1].is_finite()) {
            return;
        }
        // Clip trivially: lines wholly off the image are skipped.
        let (w, h) = (self.image.width() as f64, self.image.height() as f64);
        if (p0[0] < -1.0 && p1[0] < -1.0)
            || (p0[1] < -1.0 && p1[1] < -1.0)
            || (p0[0] > w && p1[0] > w)
            || (p0[1] > h && p1[1] > h)
        {
            return;
        }
        let (mut x0, mut y0, mut x1, mut y1) = (p0[0], p0[1], p1[0], p1[1]);
        let steep = (y1 - y0).abs() > (x1 - x0).abs();
        if steep {
            std::mem::swap(&mut x0, &mut y0);
            std::mem::swap(&mut x1, &mut y1);
        }
        if x0 > x1 {
            std::mem::swap(&mut x0, &mut x1);
            std::mem::swap(&mut y0, &mut y1);
        }
        let dx = x1 - x0;
        let grad = if dx == 0.0 { 0.0 } else { (y1 - y0) / dx };
        let mut put = |x: i64, y: i64, a: f64| {
            if steep {
                self.blend(y, x, c, a);
            } else {
                self.blend(x, y, c, a);
            }
        };
        // A line shorter than a pixel: one dot weighted by its length.
        if dx < 1.0 {
            let xm = 0.5 * (x0 + x1);
            let ym = 0.5 * (y0 + y1);
            let fy = ym - ym.floor();
            let cover = dx.max(0.25);
            put(xm.round() as i64, ym.floor() as i64, cover * (1.0 - fy));
            put(xm.round() as i64, ym.floor() as i64 + 1, cover * fy);
            return;
        }
        // End points.
        let xe0 = x0.round();
        let ye0 = y0 + grad * (xe0 - x0);
        let gap0 = 1.0 - (x0 + 0.5 - (x0 + 0.5).floor());
        let xp0 = xe0 as i64;
        put(xp0, ye0.floor() as i64, (1.0 - ye0.fract_pos()) * gap0);
        put(xp0, ye0.floor() as i64 + 1, ye0.fract_pos() * gap0);
        let xe1 = x1.round();
        let ye1 = y1 + grad * (xe1 - x1);
        let gap1 = x1 + 0.5 - (x1 + 0.5).floor();
        let xp1 = xe1 as i64;
        put(xp1, ye1.floor() as i64, (1.0 - ye1.fract_pos()) * gap1);
        put(xp1, ye1.floor() as i64 + 1, ye1.fract_pos() * gap1);
        // Between them, limited to the image.
        let lim = if steep { h } else { w } as i64;
        let from = (xp0 + 1).max(0);
        let to = (xp1 - 1).min(lim);
        let mut y = ye0 + grad * (from - xp0) as f64;
        for x in from..=to {
            put(x, y.floor() as i64, 1.0 - y.fract_pos());
            put(x, y.floor() as i64 + 1, y.fract_pos());
            y += grad;
        }
    }
}

trait FractPos {
    fn fract_pos(self) -> f64;
}

impl FractPos for f64 {
    /// The fractional part in [0, 1) (also for negative numbers).
    #[inline]
    fn fract_pos(self) -> f64 {
        self - self.floor()
    }
}

/// Hit counts per pixel, shown with a logarithmic scale.
#[derive(Clone, Debug)]
pub struct Density {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Hits per pixel, row by row from the top.
    pub counts: Vec<u32>,
}

impl Density {
    /// A `width`×`height` grid of zero counts; fails for a size the memory or the pixel limit
    /// does not allow.
    pub fn new(width: u32, height: u32) -> Result<Density, ExploreError> {
        check_size(width, height)?;
        Ok(Density {
            width,
            height,
            counts: vec![0; width as usize * height as usize],
        })
    }

    /// Count a hit at pixel coordinates (pixel centres at integers).
    #[inline]
    pub fn plot(&mut self, q: P2) {
        let x = (q[0] + 0.5).floor();
        let y = (q[1] + 0.5).floor();
        if x >= 0.0 && y >= 0.0 && x < self.width as f64 && y < self.height as f64 {
            let i = y as usize * self.width as usize + x as usize;
            self.counts[i] = self.counts[i].saturating_add(1);
        }
    }

    /// Count hits along the segment from `a` to `b` (pixel coordinates), about one per pixel
    /// of its length, `b` included and `a` left to the previous segment.
    pub fn line(&mut self, a: P2, b: P2) {
        let len = (b[0] - a[0]).abs().max((b[1] - a[1]).abs());
        if !len.is_finite() {
            return;
        }
        let n = (len.ceil() as usize).clamp(1, 4 * (self.width + self.height) as usize);
        for i in 1..=n {
            let t = i as f64 / n as f64;
            self.plot([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
        }
    }

    /// Pixels hit at least once.
    pub fn covered(&self) -> usize {
        self.counts.iter().filter(|c| **c > 0).count()
    }

    /// Colour by log(1 + count)/log(1 + max) between `background` and `color`.
    pub fn to_image(&self, color: [u8; 3], background: [u8; 3]) -> RgbImage {
        let max = self.counts.iter().copied().max().unwrap_or(0).max(1) as f64;
        let lmax = (1.0 + max).ln();
        RgbImage::from_fn(self.width, self.height, |x, y| {
            let c = self.counts[(y * self.width + x) as usize] as f64;
            let t = ((1.0 + c).ln() / lmax).powf(0.6);
            let mut p = [0u8; 3];
            for i in 0..3 {
                p[i] = (background[i] as f64 * (1.0 - t) + color[i] as f64 * t).round() as u8;
            }
            image::Rgb(p)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn framing_round_trips_and_fits() {
        let b = Bounds {
            min: [-1.0, 0.0],
            max: [3.0, 1.0],
        };
        let f = Framing::fit(b, 200, 100, 10.0);
        assert_eq!(f.scale, 45.0);
        let q = f.pixel_from_world([-1.0, 0.0]);
        assert!((q[0] - 9.5).abs() < 1e-12);
        let p = f.world_from_pixel(q);
        assert!((p[0] + 1.0).abs() < 1e-12 && p[1].abs() < 1e-12);
        // y up in the world is y down on screen.
        assert!(f.pixel_from_world([0.0, 1.0])[1] < f.pixel_from_world([0.0, 0.0])[1]);
        // A flat set is scaled by its one extent.
        let flat = Bounds {
            min: [0.0, 2.0],
            max: [4.0, 2.0],
        };
        assert_eq!(Framing::fit(flat, 100, 100, 0.0).scale, 25.0);
    }

    #[test]
    fn lines_cover_their_length() {
        let mut c = Canvas::new(64, 64, [0, 0, 0]).unwrap();
        c.line([5.0, 10.0], [50.0, 10.0], [255, 255, 255]);
        // A horizontal line on pixel centres lights exactly its row.
        let lit: Vec<(u32, u32)> = c
            .image
            .enumerate_pixels()
            .filter(|p| p.2.0[0] > 0)
            .map(|p| (p.0, p.1))
            .collect();
        assert!(lit.iter().all(|p| p.1 == 10));
        assert!(lit.len() >= 45 && lit.len() <= 47, "{}", lit.len());
        // A diagonal line's total intensity is about its length in pixels along x.
        let mut c = Canvas::new(64, 64, [0, 0, 0]).unwrap();
        c.line([3.2, 4.7], [40.2, 30.1], [255, 255, 255]);
        let sum: f64 = c.image.pixels().map(|p| p.0[0] as f64 / 255.0).sum();
        assert!((sum - 37.0).abs() < 2.0, "{sum}");
        // Off-image and non-finite lines are harmless.
        c.line([-100.0, -5.0], [-50.0, -80.0], [255, 0, 0]);
        c.line([f64::NAN, 0.0], [1.0, 1.0], [255, 0, 0]);
        c.line([-1e9, 10.0], [1e9, 12.0], [255, 0, 0]);
    }

    #[test]
    fn sizes_are_limited() {
        assert!(check_size(0, 10).is_err());
        assert!(check_size(MAX_SIDE + 1, 10).is_err());
        assert!(check_size(12000, 12000).is_err());
        assert!(check_size(640, 480).is_ok());
    }

    #[test]
    fn density() {
        let mut d = Density::new(4, 4).unwrap();
        d.plot([0.0, 0.0]);
        d.plot([0.4, -0.4]);
        d.plot([3.0, 3.0]);
        d.plot([9.0, 3.0]);
        assert_eq!(d.counts[0], 2);
        assert_eq!(d.covered(), 2);
        let img = d.to_image([255, 255, 255], [0, 0, 0]);
        assert_eq!(img.get_pixel(0, 0).0, [255, 255, 255]);
        assert_eq!(img.get_pixel(1, 1).0, [0, 0, 0]);
        assert!(img.get_pixel(3, 3).0[0] > 100);
    }
}
