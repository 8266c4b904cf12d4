//! The image operations of JWildfire's brush strokes ([`super::jwf_br_brush`]): a brush turned
//! and zoomed about its centre as JWildfire's `RotateTransformer` does it (JWildfire 9.00,
//! LGPL-2.1; `Mesh2DTransformer` for the pixel reads and the edge smoothing), written anew,
//! and a plain bilinear down-scaling.

/// An image: `w` × `h` pixels, rows from the top, each `[r, g, b, a]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Raster {
    /// Width in pixels.
    pub w: i32,
    /// Height in pixels.
    pub h: i32,
    /// The pixels.
    pub px: Vec<[u8; 4]>,
}

impl Raster {
    /// The pixel at column `x`, row `y`, or `None` outside.
    fn get(&self, x: i32, y: i32) -> Option<[u8; 4]> {
        if (0..self.w).contains(&x) && (0..self.h).contains(&y) {
            self.px.get((y * self.w + x) as usize).copied()
        } else {
            None
        }
    }
}

/// The four pixels JWildfire blends for the position (x, y): the pixel nearest to it (coordinates
/// rounded half up), its right, lower and lower-right neighbours (the pixel itself, or the right
/// one, at the last column or row); all black outside the image.
fn quad(src: &Raster, x: f64, y: f64) -> [[f64; 3]; 4] {
    let (ix, iy) = ((x + 0.5) as i32, (y + 0.5) as i32);
    let rgb = |p: [u8; 4]| [f64::from(p[0]), f64::from(p[1]), f64::from(p[2])];
    let Some(p) = src.get(ix, iy) else {
        return [[0.0; 3]; 4];
    };
    let right = ix < src.w - 1;
    let q = if right {
        src.get(ix + 1, iy).unwrap_or(p)
    } else {
        p
    };
    let (r, s) = if iy < src.h - 1 {
        let r = src.get(ix, iy + 1).unwrap_or(p);
        let s = if right {
            src.get(ix + 1, iy + 1).unwrap_or(q)
        } else {
            q
        };
        (r, s)
    } else {
        (p, q)
    };
    [rgb(p), rgb(q), rgb(r), rgb(s)]
}

/// A channel value rounded half up into a byte.
fn round_color(v: f64) -> u8 {
    (v + 0.5).clamp(0.0, 255.0) as i32 as u8
}

/// `img` turned by `degrees` (clockwise on screen) and zoomed by `zoom` about its centre pixel
/// (width/2, height/2, integer halves), as JWildfire's `RotateTransformer` with a radius
/// covering the whole image and smoothing 1: each pixel takes the source position its
/// centre maps back to; inside the source it blends the 2 × 2 pixels from the nearest one by
/// the position's fractional parts, outside it takes the colour of the source pixel (1, 1).
/// Every pixel becomes opaque. Then [`smooth`].
pub fn rotate(img: &Raster, zoom: f64, degrees: f64) -> Raster {
    let (w, h) = (img.w, img.h);
    let alpha = -degrees * std::f64::consts::PI / 180.0;
    let (sina, cosa) = alpha.sin_cos();
    let cx = f64::from(w / 2) - 0.5;
    let cy = f64::from(h / 2) - 0.5;
    let inv = 1.0 / zoom.max(0.01);
    let (w1, h1) = (f64::from(w) - 1.0, f64::from(h) - 1.0);
    let bg = quad(img, 1.0, 1.0)[0];
    let mut out = img.clone();
    for i in 0..h {
        let y0 = (f64::from(i) - cy) * inv;
        for j in 0..w {
            let x0 = (f64::from(j) - cx) * inv;
            let x = cosa * x0 + sina * y0 + cx;
            let y = -sina * x0 + cosa * y0 + cy;
            let c = if x < 0.0 || x > w1 || y < 0.0 || y > h1 || x.is_nan() || y.is_nan() {
                bg
            } else {
                let (xi, yi) = (x - x.trunc(), y - y.trunc());
                let [p, q, r, s] = quad(img, x, y);
                std::array::from_fn(|k| {
                    (1.0 - yi) * ((1.0 - xi) * p[k] + xi * q[k])
                        + yi * ((1.0 - xi) * r[k] + xi * s[k])
                })
            };
            out.px[(i * w + j) as usize] =
                [round_color(c[0]), round_color(c[1]), round_color(c[2]), 255];
        }
    }
    smooth(&mut out);
    out
}

/// JWildfire's edge smoothing of a rotated image (`Mesh2DTransformer.applySmoothing`, one
/// pass, in place, rows top to bottom): an inner pixel whose brightness (r + g + b) differs by
/// more than 64 from both its upper and right neighbours (else from both its right and lower
/// neighbours) becomes the mean of itself and those two neighbours weighted by their
/// differences, in integer steps.
pub fn smooth(img: &mut Raster) {
    let (w, h) = (img.w, img.h);
    let at = |img: &Raster, x: i32, y: i32| img.px[(y * w + x) as usize].map(i32::from);
    for i in 1..h - 1 {
        for j in 1..w - 1 {
            let up = at(img, j, i - 1);
            let right = at(img, j + 1, i);
            let down = at(img, j, i + 1);
            let me = at(img, j, i);
            let sum = |p: [i32; 4]| p[0] + p[1] + p[2];
            let av = sum(me);
            let (d1, d2, d3) = (
                (sum(up) - av).abs(),
                (sum(right) - av).abs(),
                (sum(down) - av).abs(),
            );
            let mix = |a: [i32; 4], da: i32, b: [i32; 4], db: i32| -> [u8; 4] {
                let c = |k: usize| ((((a[k] * da + b[k] * db) / (da + db)) + me[k]) / 2) as u8;
                [c(0), c(1), c(2), 255]
            };
            if d1 > 64 && d2 > 64 {
                img.px[(i * w + j) as usize] = mix(up, d1, right, d2);
            } else if d2 > 64 && d3 > 64 {
                img.px[(i * w + j) as usize] = mix(right, d2, down, d3);
            }
        }
    }
}

/// `img` scaled so that its larger side is `size` pixels (the other side in proportion,
/// rounded, at least 1), sampling bilinearly at pixel centres.
pub fn scale_to(img: &Raster, size: i32) -> Raster {
    let size = size.max(1);
    let (w, h) = (img.w.max(1), img.h.max(1));
    let (nw, nh) = if w >= h {
        (
            size,
            ((f64::from(h) * f64::from(size) / f64::from(w)).round() as i32).max(1),
        )
    } else {
        (
            ((f64::from(w) * f64::from(size) / f64::from(h)).round() as i32).max(1),
            size,
        )
    };
    let (sx, sy) = (f64::from(w) / f64::from(nw), f64::from(h) / f64::from(nh));
    let mut px = Vec::with_capacity((nw * nh) as usize);
    for y in 0..nh {
        let fy = ((f64::from(y) + 0.5) * sy - 0.5).clamp(0.0, f64::from(h - 1));
        for x in 0..nw {
            let fx = ((f64::from(x) + 0.5) * sx - 0.5).clamp(0.0, f64::from(w - 1));
            let (x0, y0) = (fx as i32, fy as i32);
            let (x1, y1) = ((x0 + 1).min(w - 1), (y0 + 1).min(h - 1));
            let (tx, ty) = (fx - f64::from(x0), fy - f64::from(y0));
            let g = |x: i32, y: i32| img.get(x, y).unwrap_or([0, 0, 0, 255]).map(f64::from);
            let (a, b, c, d) = (g(x0, y0), g(x1, y0), g(x0, y1), g(x1, y1));
            px.push(std::array::from_fn(|k| {
                round_color(
                    (1.0 - ty) * ((1.0 - tx) * a[k] + tx * b[k])
                        + ty * ((1.0 - tx) * c[k] + tx * d[k]),
                )
            }));
        }
    }
    Raster { w: nw, h: nh, px }
}
