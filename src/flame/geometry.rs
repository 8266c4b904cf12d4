//! Camera and bucket geometry of one render: the supersampled bucket grid, its gutter for
//! the spatial filter and density estimation, and the map from world to bucket coordinates.

use crate::flame::density::DeFilters;
use crate::flame::filter::SpatialFilter;
use crate::flame::jwf_render::JwfRaster;
use crate::flame::model::{Affine, Flame};

/// Everything about the sizes of the buffers of one render.
#[derive(Clone, Debug)]
pub struct Geometry {
    pub width: usize,
    pub height: usize,
    pub os: usize,
    /// Total gutter g in buckets (filter gutter, grown for DE).
    pub gutter: usize,
    /// Extra offset δ of the filter window inside the gutter.
    pub delta: usize,
    /// Bucket grid size: os·W + 2g by os·H + 2g (`bh` is the rows held: see `row0`).
    pub bw: usize,
    pub bh: usize,
    /// First bucket row of the whole grid held by this geometry's histograms: 0 for a whole
    /// render, the first row of the band for a render in strips (see [`Geometry::window`]).
    pub row0: usize,
    /// Rows of the whole bucket grid (os·H + 2g).
    pub full_bh: usize,
    /// World → continuous bucket coordinates (rotation, translation and scale in one map).
    pub bucket_from_world: Affine,
    pub filter: SpatialFilter,
    pub de: Option<std::sync::Arc<DeFilters>>,
    /// JWildfire's filters, for flames JWildfire's renderer draws: the bucket grid is then its
    /// raster (the picture and a border, points rounded to the nearest bucket), with no
    /// density estimation.
    pub jwf: Option<std::sync::Arc<JwfRaster>>,
}

impl Geometry {
    /// Build the geometry of a flame. `de` is `None` when DE is disabled (radius 0).
    pub fn new(flame: &Flame, de: Option<std::sync::Arc<DeFilters>>) -> Geometry {
        let os = flame.supersample.max(1) as usize;
        let (w, h) = (flame.width as usize, flame.height as usize);
        if flame.renders_as_jwildfire() {
            return Self::jwildfire(flame, os, w, h);
        }
        let filter = SpatialFilter::new(flame.filter_shape, flame.filter, os as u32);
        let mut gutter = filter.gutter;
        let mut delta = 0;
        if flame.estimator_radius > 0.0 {
            let g_de = flame.estimator_radius.ceil() as usize * os + (os - 1);
            if g_de > gutter {
                delta = g_de - gutter;
                gutter = g_de;
            }
        }
        let bw = os * w + 2 * gutter;
        let bh = os * h + 2 * gutter;
        let bucket_from_world = bucket_from_world(flame, os, w, h, gutter);
        Geometry {
            width: w,
            height: h,
            os,
            gutter,
            delta,
            bw,
            bh,
            row0: 0,
            full_bh: bh,
            bucket_from_world,
            filter,
            de,
            jwf: None,
        }
    }

    /// The geometry of a flame JWildfire's renderer draws: its raster as the bucket grid.
    fn jwildfire(flame: &Flame, os: usize, w: usize, h: usize) -> Geometry {
        let jwf = JwfRaster::new(&flame.jwf, flame.filter, os);
        let gutter = jwf.border;
        let (bw, bh) = (os * w + 2 * gutter, os * h + 2 * gutter);
        let bucket_from_world = jwf_bucket_from_world(flame, os, w, h, gutter);
        Geometry {
            width: w,
            height: h,
            os,
            gutter,
            delta: 0,
            bw,
            bh,
            row0: 0,
            full_bh: bh,
            bucket_from_world,
            filter: SpatialFilter::new(flame.filter_shape, 0.0, os as u32),
            de: None,
            jwf: Some(std::sync::Arc::new(jwf)),
        }
    }

    /// The bucket rows of the whole grid that the output rows `out` are developed from
    /// (without the density estimator's reach).
    pub fn source_rows(&self, out: std::ops::Range<usize>) -> std::ops::Range<usize> {
        if let Some(j) = &self.jwf {
            return j.source_rows(out, self.full_bh);
        }
        if out.is_empty() {
            return 0..0;
        }
        let lo = out.start * self.os + self.delta;
        let hi = ((out.end - 1) * self.os + self.delta + self.filter.taps.len()).min(self.full_bh);
        lo..hi
    }

    /// The same bucket grid (size, supersampling, gutter, filters, rows held) seen through
    /// `flame`'s camera (centre, scale, zoom, rotation): how each sub-frame of a motion-blurred
    /// frame draws into the frame's one histogram.
    pub fn with_camera_of(&self, flame: &Flame) -> Geometry {
        Geometry {
            bucket_from_world: if self.jwf.is_some() {
                jwf_bucket_from_world(flame, self.os, self.width, self.height, self.gutter)
            } else {
                bucket_from_world(flame, self.os, self.width, self.height, self.gutter)
            },
            ..self.clone()
        }
    }

    /// The same camera restricted to bucket rows `rows` of the whole grid: a point lands in
    /// exactly the bucket it lands in for the whole grid, shifted up by `rows.start` rows, or
    /// outside. (The row is found in whole-grid coordinates first, so rounding is the same.)
    pub fn window(&self, rows: std::ops::Range<usize>) -> Geometry {
        let end = rows.end.min(self.full_bh);
        let start = rows.start.min(end);
        Geometry {
            row0: start,
            bh: end - start,
            ..self.clone()
        }
    }

    pub fn buckets(&self) -> usize {
        self.bw * self.bh
    }

    /// World area of the image: W·H/ppu².
    pub fn area(flame: &Flame) -> f64 {
        let ppu = flame.ppu();
        flame.width as f64 * flame.height as f64 / (ppu * ppu)
    }

    /// As [`Geometry::bucket_of`] without a branch: the index (meaningless when outside)
    /// and whether the point falls inside the bucket grid.
    #[inline(always)]
    pub fn bucket_index(&self, x: f64, y: f64) -> (usize, bool) {
        let (bx, by) = self.bucket_from_world.apply(x, y);
        // floor(v) = trunc(v + 1) − 1 for v > −1, and anything ≤ −1 maps to a negative
        // value: one saturating conversion per axis (NaN → −1), then unsigned range checks.
        let ix = ((bx + 1.0) as i64).wrapping_sub(1);
        let iy = ((by + 1.0) as i64).wrapping_sub(1 + self.row0 as i64);
        let inside = ((ix as u64) < self.bw as u64) & ((iy as u64) < self.bh as u64);
        (
            (iy as usize)
                .wrapping_mul(self.bw)
                .wrapping_add(ix as usize),
            inside,
        )
    }

    /// The bucket map of the plotting loop (see [`BucketMap`]).
    pub fn bucket_map(&self) -> BucketMap {
        BucketMap {
            m: self.bucket_from_world,
            row0: self.row0 as f64,
            // Grids are far narrower than 2³¹ buckets; a wider one would only lose points.
            bw: self.bw.min(i32::MAX as usize) as f64,
            bh: self.bh.min(i32::MAX as usize) as f64,
            stride: self.bw as u32,
        }
    }

    /// Bucket index of a world point, if it falls inside the bucket grid.
    #[inline(always)]
    pub fn bucket_of(&self, x: f64, y: f64) -> Option<usize> {
        let (i, inside) = self.bucket_index(x, y);
        inside.then_some(i)
    }
}

/// As [`Geometry::bucket_index`], with float comparisons instead of saturating integer
/// conversions and everything the loop needs by value (the same buckets; cheaper in the
/// plotting loop). Grids hold fewer than 2³² buckets, and rows and columns fewer than 2³¹.
#[derive(Clone, Copy, Debug)]
pub struct BucketMap {
    m: Affine,
    row0: f64,
    bw: f64,
    bh: f64,
    stride: u32,
}

impl BucketMap {
    /// The bucket index (0 when outside) and whether the point falls inside the grid.
    #[inline(always)]
    pub fn index(&self, x: f64, y: f64) -> (u32, bool) {
        let (bx, by) = self.m.apply(x, y);
        self.index_of(bx, by)
    }

    /// [`BucketMap::index`] of a point moved by `d` buckets once mapped.
    #[inline(always)]
    pub fn index_moved(&self, x: f64, y: f64, d: (f64, f64)) -> (u32, bool) {
        let (bx, by) = self.m.apply(x, y);
        self.index_of(bx + d.0, by + d.1)
    }

    /// The bucket index of continuous bucket coordinates (0 when outside the grid) and
    /// whether they fall inside.
    #[inline(always)]
    fn index_of(&self, bx: f64, by: f64) -> (u32, bool) {
        // Exact: row0 is a whole number no larger than the grid, and a difference of a
        // double and a smaller whole number below 2⁵² is representable.
        let by = by - self.row0;
        let inside = (bx >= 0.0) & (bx < self.bw) & (by >= 0.0) & (by < self.bh);
        let (bx, by) = if inside { (bx, by) } else { (0.0, 0.0) };
        // SAFETY: both values are in [0, 2³¹): inside the grid, or 0.
        let (ix, iy) = unsafe { (bx.to_int_unchecked::<i32>(), by.to_int_unchecked::<i32>()) };
        (
            (iy as u32)
                .wrapping_mul(self.stride)
                .wrapping_add(ix as u32),
            inside,
        )
    }
}

/// The map from world coordinates to the whole bucket grid of `os`·`w` by `os`·`h` buckets plus a
/// `gutter` on every side, through `flame`'s camera: bx = k·(cos θ·(x − cx) − sin θ·(y − cy)) +
/// os·W/2 + g (by likewise), k = os·ppu.
fn bucket_from_world(flame: &Flame, os: usize, w: usize, h: usize, gutter: usize) -> Affine {
    let ppu = flame.ppu();
    let k = os as f64 * ppu;
    let th = flame.rotate.to_radians();
    let (s, c) = th.sin_cos();
    let [cx, cy] = flame.center;
    // bx = k·(cos θ·(x − cx) − sin θ·(y − cy)) + os·W/2 + g, by likewise.
    let ox = (os * w) as f64 / 2.0 + gutter as f64;
    let oy = (os * h) as f64 / 2.0 + gutter as f64;
    Affine {
        a: k * c,
        b: -k * s,
        c: k * s,
        d: k * c,
        e: ox - k * (c * cx - s * cy),
        f: oy - k * (s * cx + c * cy),
    }
}

/// [`bucket_from_world`] as JWildfire maps: rounding to the nearest bucket, and for a 3-D
/// camera the rotation about the origin rather than the centre (JWildfire turns the projected
/// point, then moves the centre to the middle of the picture).
fn jwf_bucket_from_world(flame: &Flame, os: usize, w: usize, h: usize, gutter: usize) -> Affine {
    let mut m = bucket_from_world(flame, os, w, h, gutter);
    if crate::flame::chaos::Projection::is_jwildfire_3d(flame) {
        let k = os as f64 * flame.ppu();
        m.e = (os * w) as f64 / 2.0 + gutter as f64 - k * flame.center[0];
        m.f = (os * h) as f64 / 2.0 + gutter as f64 - k * flame.center[1];
    }
    m.e += 0.5;
    m.f += 0.5;
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn camera_maps_center_to_image_centre_and_y_down() {
        let f = Flame {
            width: 100,
            height: 50,
            scale: 10.0,
            center: [1.0, 2.0],
            estimator_radius: 0.0,
            ..Flame::default()
        };
        let g = Geometry::new(&f, None);
        assert_eq!(g.gutter, 1);
        let (bx, by) = g.bucket_from_world.apply(1.0, 2.0);
        assert_eq!((bx, by), (51.0, 26.0));
        // One world unit right is 10 buckets right; one unit down (+y) is 10 rows down.
        let (bx, by) = g.bucket_from_world.apply(2.0, 3.0);
        assert_eq!((bx, by), (61.0, 36.0));
        // Top-left image corner (x0, y0) is bucket (g, g).
        let (bx, by) = g.bucket_from_world.apply(1.0 - 5.0, 2.0 - 2.5);
        assert!((bx - 1.0).abs() < 1e-12 && (by - 1.0).abs() < 1e-12);
    }

    #[test]
    fn positive_rotate_turns_clockwise_on_screen() {
        let f = Flame {
            width: 100,
            height: 100,
            scale: 10.0,
            rotate: 90.0,
            estimator_radius: 0.0,
            ..Flame::default()
        };
        let g = Geometry::new(&f, None);
        // A point to the right of the centre (+x) ends up below it on screen (+row).
        let (bx, by) = g.bucket_from_world.apply(1.0, 0.0);
        assert!(
            (bx - 51.0).abs() < 1e-9 && (by - 61.0).abs() < 1e-9,
            "{bx} {by}"
        );
    }

    #[test]
    fn bucket_edges_are_half_open() {
        let f = Flame {
            width: 10,
            height: 10,
            scale: 1.0,
            estimator_radius: 0.0,
            filter: 0.0,
            ..Flame::default()
        };
        let g = Geometry::new(&f, None);
        assert_eq!(g.gutter, 0);
        // World x = −5 is the left edge (bucket 0); −5 − ε is outside; +5 is outside.
        assert_eq!(g.bucket_of(-5.0, -5.0), Some(0));
        assert_eq!(g.bucket_of(-5.000001, -5.0), None);
        assert_eq!(g.bucket_of(-5.5, -5.0), None);
        assert_eq!(g.bucket_of(4.999, 4.999), Some(99));
        assert_eq!(g.bucket_of(5.0, 0.0), None);
        assert_eq!(g.bucket_of(f64::NAN, 0.0), None);
        assert_eq!(g.bucket_of(1e300, 0.0), None);
        assert_eq!(g.bucket_of(-1e300, 0.0), None);
        assert_eq!(g.bucket_of(0.5, 1.5), Some(6 * 10 + 5));
    }

    #[test]
    fn de_grows_the_gutter() {
        let f = Flame {
            width: 10,
            height: 10,
            estimator_radius: 9.0,
            ..Flame::default()
        };
        let g = Geometry::new(&f, None);
        assert_eq!(g.gutter, 9);
        assert_eq!(g.delta, 8);
        assert_eq!(g.bw, 28);
    }
}
