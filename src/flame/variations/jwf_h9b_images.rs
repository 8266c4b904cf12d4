//! JWildfire's image-driven variations: `colormap_wf` and `post_colormap_wf` (a point takes
//! the colour of the image's pixel under it, and a height from its brightness),
//! `displacemap_wf` and `post_displacemap_wf` (the pixel's brightness turns, scales or shears
//! the point) and `post_bumpmap_wf` (the pixel's brightness raises z).
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `AbstractColorMapWFFunc`,
//! `AbstractDisplacementMapWFFunc` and `PostBumpMapWFFunc`, written anew.
//!
//! A JWildfire flame names the image file in the text parameter `image_filename`, or gives
//! the file's bytes inline (the resource `inlined_image`). The file readers load it and hand
//! it over ([`super::resources`]; an inline image under a name of its own, which they put in
//! `image_filename`); a variation whose image was not handed over (no name, a missing file,
//! an image that cannot be decoded) takes the image JWildfire falls back to, drawn here as
//! JWildfire draws it —
//! * colour and displacement maps: 256 × 256 pixels, a bilinear blend of red (top left),
//!   yellow (top right), cyan (bottom left) and blue (bottom right) in JWildfire's 10-bit
//!   fixed-point steps (`GradientCreator`, see [`corner_gradient`]);
//! * bump map: a blank 320 × 256 image (every pixel black), so only `offset_z` acts, inside
//!   the image's rectangle.
//!
//! Where JWildfire turns a pixel's colour into a palette position (`dc_color` > 0, and
//! `color_mode` 1 of the displacement maps), the point's colour coordinate becomes that of the
//! palette entry nearest to the pixel ([`super::PaletteIndex`], the flame's palette handed over
//! when the xform is compiled); it carries over to the next iterations as any colour
//! coordinate does. The displacement maps compare the pixel's channels in [0, 1] with the
//! palette's bytes, as JWildfire does. Without a palette (a variation evaluated outside a
//! flame) the coordinate is left as it is.

use super::util::jwf_math;
use super::*;

/// JWildfire's `EPSILON`.
const EPS: f64 = 1e-8;

/// Java's `int` range, for the integer switches (JWildfire compares them with 0 or 1).
const IMIN: f64 = -2_147_483_648.0;
const IMAX: f64 = 2_147_483_647.0;

/// An RGB image, rows from the top, pixels as `[r, g, b, a]` bytes.
struct Image {
    w: i32,
    h: i32,
    px: Vec<[u8; 4]>,
}

impl Image {
    /// The image as shared data: width, height, then each pixel packed as 0xAARRGGBB.
    fn to_data(&self) -> Vec<f64> {
        let mut d = Vec::with_capacity(2 + self.px.len());
        d.push(f64::from(self.w));
        d.push(f64::from(self.h));
        d.extend(
            self.px
                .iter()
                .map(|&[r, g, b, a]| f64::from(u32::from_be_bytes([a, r, g, b]))),
        );
        d
    }
}

/// An image kept as shared data ([`Image::to_data`]).
pub(super) struct View<'a> {
    pub(super) w: i32,
    pub(super) h: i32,
    px: &'a [f64],
}

impl<'a> View<'a> {
    pub(super) fn of(d: &'a [f64]) -> View<'a> {
        match d {
            [w, h, px @ ..] if (*w * *h) as usize == px.len() => View {
                w: *w as i32,
                h: *h as i32,
                px,
            },
            _ => View {
                w: 0,
                h: 0,
                px: &[],
            },
        }
    }

    /// The pixel at column `x`, row `y` (both inside the image).
    pub(super) fn at(&self, x: i32, y: i32) -> [u8; 4] {
        let i = y as usize * self.w as usize + x as usize;
        let [a, r, g, b] = (self.px.get(i).copied().unwrap_or(0.0) as u32).to_be_bytes();
        [r, g, b, a]
    }
}

/// The shared data of an image variation: the image handed over under the name in its first
/// text parameter, else `default`.
fn image_data(texts: &[String], default: impl FnOnce() -> Image) -> Vec<f64> {
    let named = texts.first().filter(|t| !t.is_empty());
    match named.and_then(|t| super::resources::image(t)) {
        Some(img) => Image {
            w: img.w as i32,
            h: img.h as i32,
            px: img.rgba.clone(),
        }
        .to_data(),
        None => default().to_data(),
    }
}

/// Shared data of the colour and displacement maps.
pub(super) fn gradient_map(_p: &[f64], texts: &[String]) -> Vec<f64> {
    image_data(texts, || corner_gradient(256, 256))
}

/// The shared data of an image variation whose default image is JWildfire's corner gradient
/// of `w` × `h` pixels (`iflames_wf`'s is 128 × 128).
pub(super) fn gradient_map_of_size(texts: &[String], w: i32, h: i32) -> Vec<f64> {
    image_data(texts, || corner_gradient(w, h))
}

/// Shared data of the bump map: its default is blank.
fn bump_map(_p: &[f64], texts: &[String]) -> Vec<f64> {
    image_data(texts, || Image {
        w: 320,
        h: 256,
        px: vec![[0; 4]; 320 * 256],
    })
}

/// JWildfire's `GradientCreator` with its default corners: each row's ends blend the left
/// and right corners down the image, each row blends its ends across, all in integer steps
/// of 1/1024 (an increment truncated toward zero, positions rounded down), the first and
/// last row and column being the corner colours exactly.
fn corner_gradient(w: i32, h: i32) -> Image {
    const PREC: i32 = 10;
    let (ul, ur, ll, lr) = ([255, 0, 0], [255, 255, 0], [0, 255, 255], [0, 0, 255]);
    let slope = |a: i32, b: i32, n: i32| ((b - a) << PREC) / (n - 1).max(1);
    let mut px = vec![[0u8, 0, 0, 255]; (w.max(0) * h.max(0)) as usize];
    for i in 0..h {
        let (l, r): ([i32; 3], [i32; 3]) = if i == 0 {
            (ul, ur)
        } else if i == h - 1 {
            (ll, lr)
        } else {
            (
                std::array::from_fn(|k| ((i * slope(ul[k], ll[k], h)) >> PREC) + ul[k]),
                std::array::from_fn(|k| ((i * slope(ur[k], lr[k], h)) >> PREC) + ur[k]),
            )
        };
        let step: [i32; 3] = std::array::from_fn(|k| slope(l[k], r[k], w));
        let row = (i * w) as usize;
        let byte = |c: [i32; 3]| [c[0] as u8, c[1] as u8, c[2] as u8, 255];
        px[row] = byte(l);
        for j in 1..w - 1 {
            px[row + j as usize] = byte(std::array::from_fn(|k| ((j * step[k]) >> PREC) + l[k]));
        }
        px[row + (w - 1) as usize] = byte(r);
    }
    Image { w, h, px }
}

/// JWildfire's `Tools.FTOI`: round half away from zero, to Java's `int` (saturating; NaN
/// gives 0).
pub(super) fn ftoi(x: f64) -> i32 {
    if x > 0.0 {
        (x + 0.5) as i32
    } else if x < 0.0 {
        (0.0 - (x.abs() + 0.5)) as i32
    } else {
        0
    }
}

/// Brings a pixel index into `[0, n)` as JWildfire's tiling does: by whole image widths
/// (Java's truncating division, so an index of −n, −2n, … lands on n, outside).
pub(super) fn tile(i: i32, n: i32) -> i32 {
    if i < 0 {
        let k = i / n - 1;
        i.wrapping_sub(k.wrapping_mul(n))
    } else if i >= n {
        i.wrapping_sub((i / n).wrapping_mul(n))
    } else {
        i
    }
}

/// One axis of JWildfire's image lookup (`ColorMapHolder`): the continuous pixel coordinate
/// of `v` in an image of `n` pixels, offset and scaled, and its pixel index (truncated for
/// blending, else rounded as [`ftoi`] does), tiled when `tile_on` is 1.
pub(super) fn image_axis(
    v: f64,
    offset: f64,
    scale: f64,
    n: i32,
    tile_on: f64,
    trunc: bool,
) -> (f64, i32) {
    let x = (v - (offset + 0.5) + 1.0) / scale * f64::from(n - 2);
    let i = if trunc { x.trunc() as i32 } else { ftoi(x) };
    (x, if tile_on == 1.0 { tile(i, n) } else { i })
}

/// JWildfire's brightness weights.
pub(super) fn intensity(r: f64, g: f64, b: f64) -> f64 {
    0.299 * r + 0.588 * g + 0.113 * b
}

// ---------------------------------------------------------------------------------------------
// colormap_wf, post_colormap_wf

/// Most bytes of an image file's name.
const MAX_NAME: usize = 4096;

/// The text parameter naming the image file of variation `$n`.
macro_rules! image_text {
    ($n:literal) => {
        &[TextParam {
            name: concat!($n, "_image_filename"),
            default: "",
            max_len: MAX_NAME,
        }]
    };
}

macro_rules! colormap_params {
    ($n:literal) => {
        &[
            p(concat!($n, "_scale_x"), 1.0),
            p(concat!($n, "_scale_y"), 1.0),
            p(concat!($n, "_scale_z"), 0.0),
            p(concat!($n, "_offset_x"), 0.0),
            p(concat!($n, "_offset_y"), 0.0),
            p(concat!($n, "_offset_z"), 0.0),
            p_int(concat!($n, "_tile_x"), 1.0, IMIN, IMAX),
            p_int(concat!($n, "_tile_y"), 1.0, IMIN, IMAX),
            p_int(concat!($n, "_reset_z"), 1.0, IMIN, IMAX),
            p_int(concat!($n, "_dc_color"), 1.0, IMIN, IMAX),
            p_int(concat!($n, "_blend_colormap"), 0.0, IMIN, IMAX),
            p_int(concat!($n, "_with_alpha"), 0.0, IMIN, IMAX),
            p_int(concat!($n, "_is_sequence"), 0.0, IMIN, IMAX),
            p_int(concat!($n, "_sequence_start"), 1.0, IMIN, IMAX),
            p_int(concat!($n, "_sequence_digits"), 4.0, IMIN, IMAX),
        ]
    };
}

macro_rules! displacemap_params {
    ($n:literal) => {
        &[
            p_int(concat!($n, "_mode"), 0.0, IMIN, IMAX),
            p_int(concat!($n, "_color_mode"), 0.0, IMIN, IMAX),
            p(concat!($n, "_bias"), 0.0),
            p(concat!($n, "_scale_x"), 1.0),
            p(concat!($n, "_scale_y"), 1.0),
            p(concat!($n, "_offset_x"), 0.0),
            p(concat!($n, "_offset_y"), 0.0),
            p_int(concat!($n, "_tile_x"), 1.0, IMIN, IMAX),
            p_int(concat!($n, "_tile_y"), 1.0, IMIN, IMAX),
        ]
    };
}

const MAP_FLAGS: u32 =
    flag::JWILDFIRE | flag::WRITES_Z | flag::SETS_COLOR | flag::HIDES | flag::PALETTE;
const DISPLACE_FLAGS: u32 = flag::JWILDFIRE | flag::WRITES_Z | flag::SETS_COLOR | flag::PALETTE;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("colormap_wf", colormap_wf)
        .params(colormap_params!("colormap_wf"))
        .texts(image_text!("colormap_wf"))
        .flags(MAP_FLAGS | flag::WRITES_ACC)
        .shared(&[], gradient_map),
    VarDef::new("post_colormap_wf", post_colormap_wf)
        .params(colormap_params!("post_colormap_wf"))
        .texts(image_text!("post_colormap_wf"))
        .flags(MAP_FLAGS | flag::POST_ONLY | flag::USES_Z)
        .shared(&[], gradient_map),
    VarDef::new("displacemap_wf", displacemap_wf)
        .params(displacemap_params!("displacemap_wf"))
        .texts(image_text!("displacemap_wf"))
        .flags(DISPLACE_FLAGS | flag::READS_ACC | flag::WRITES_ACC)
        .shared(&[], gradient_map),
    VarDef::new("post_displacemap_wf", post_displacemap_wf)
        .params(displacemap_params!("post_displacemap_wf"))
        .texts(image_text!("post_displacemap_wf"))
        .flags(DISPLACE_FLAGS | flag::POST_ONLY | flag::USES_Z)
        .shared(&[], gradient_map),
    VarDef::new("post_bumpmap_wf", post_bumpmap_wf)
        .params(&[
            p("post_bumpmap_wf_scale_x", 1.0),
            p("post_bumpmap_wf_scale_y", 1.0),
            p("post_bumpmap_wf_scale_z", 0.2),
            p("post_bumpmap_wf_offset_x", 0.0),
            p("post_bumpmap_wf_offset_y", 0.0),
            p("post_bumpmap_wf_offset_z", 0.0),
            p_int("post_bumpmap_wf_reset_z", 0.0, IMIN, IMAX),
        ])
        .texts(image_text!("post_bumpmap_wf"))
        .flags(
            flag::JWILDFIRE
                | flag::POST_ONLY
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::READS_AFFINE_POINT
                | flag::READS_ACC,
        )
        .shared(&[], bump_map),
];

/// What a colour map gives a point: the height to set or add, and the colour and hiding it
/// writes into `acc`.
fn colormap(v: &Prepared, x_in: f64, y_in: f64, acc: &mut Acc) -> (f64, bool) {
    let [
        scale_x,
        scale_y,
        scale_z,
        offset_x,
        offset_y,
        offset_z,
        tile_x,
        tile_y,
        reset_z,
        dc_color,
        blend,
        with_alpha,
    ] = v.params();
    let img = View::of(v.data());
    let (w, h) = (img.w, img.h);
    let blend = blend > 0.0;
    let (x, ix) = image_axis(x_in, offset_x, scale_x, w, tile_x, blend);
    let (y, iy) = image_axis(y_in, offset_y, scale_y, h, tile_y, blend);
    let [r, g, b, a] = if (0..w).contains(&ix) && (0..h).contains(&iy) {
        let px = |dx: i32, dy: i32| {
            let (cx, cy) = (ix + dx, iy + dy);
            // Beyond the last column or row: black, opaque.
            if cx < w && cy < h {
                img.at(cx, cy).map(f64::from)
            } else {
                [0.0, 0.0, 0.0, 255.0]
            }
        };
        if blend {
            let (fx, fy) = (x - x.trunc(), y - y.trunc());
            let (c00, c10, c01, c11) = (px(0, 0), px(1, 0), px(0, 1), px(1, 1));
            let lerp = |s: f64, e: f64, t: f64| s + (e - s) * t;
            std::array::from_fn(|k| lerp(lerp(c00[k], c10[k], fx), lerp(c01[k], c11[k], fx), fy))
        } else {
            px(0, 0)
        }
    } else {
        [0.0; 4]
    };
    if dc_color == 0.0 {
        acc.rgb = Some([r, g, b]);
    } else if dc_color > 0.0 {
        // The palette entry nearest to the pixel (see the module documentation).
        let [r, g, b] = [r, g, b].map(|c| f64::from(ftoi(c)));
        if let Some(c) = v.palette_coordinate(r, g, b) {
            acc.color = c;
        }
    }
    acc.hide = with_alpha > 0.0 && a <= 0.1;
    let mut dz = offset_z;
    if scale_z.abs() > EPS {
        dz += scale_z * intensity(r, g, b) / 255.0;
    }
    (dz, reset_z != 0.0)
}

/// colormap_wf: the colour of the image under the affine point; the height replaces or adds
/// to the running z; x and y are left as they are.
fn colormap_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (dz, reset) = colormap(v, t.x, t.y, acc);
    if reset {
        acc.z = 0.0;
    }
    [0.0, 0.0, dz]
}

/// post_colormap_wf: colormap_wf on the xform's summed point.
fn post_colormap_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (dz, reset) = colormap(v, t.x, t.y, acc);
    [t.x, t.y, if reset { dz } else { t.z + dz }]
}

// ---------------------------------------------------------------------------------------------
// displacemap_wf, post_displacemap_wf

/// A displacement map applied to the point (px, py) at the image position of (x_in, y_in):
/// the moved point (the point itself outside the image).
fn displace(v: &Prepared, x_in: f64, y_in: f64, px: f64, py: f64, acc: &mut Acc) -> (f64, f64) {
    let [
        mode,
        color_mode,
        bias,
        scale_x,
        scale_y,
        offset_x,
        offset_y,
        tile_x,
        tile_y,
    ] = v.params();
    let img = View::of(v.data());
    let (w, h) = (img.w, img.h);
    let x = (x_in - (offset_x + 0.5) + 1.0) / scale_x * f64::from(w - 1);
    let y = (y_in - (offset_y + 0.5) + 1.0) / scale_y * f64::from(h - 1);
    let (mut ix, mut iy) = (ftoi(x), ftoi(y));
    if tile_x == 1.0 {
        ix = tile(ix, w);
    }
    if tile_y == 1.0 {
        iy = tile(iy, h);
    }
    if !((0..w).contains(&ix) && (0..h).contains(&iy)) {
        return (px, py);
    }
    let [r, g, b, _] = img.at(ix, iy).map(|c| f64::from(c) / 255.0);
    let amount = v.w;
    let out = match mode as i64 {
        // Translate by the red and green channels.
        1 => (px + (r - 0.5) * amount, py + (g - 0.5) * amount),
        // Scale about the origin by the brightness.
        2 => {
            let i = intensity(r, g, b) - bias;
            if i > 0.0 {
                let s = 1.0 + (i - 0.5) * amount;
                (px * s, py * s)
            } else {
                (px, py)
            }
        }
        // Shear.
        3 => {
            let (ax, ay) = ((r - 0.5) * amount, (g - 0.5) * amount);
            (px * ax * ay + py * ay, px * ay - py * ax * ay)
        }
        // Turn about the origin by the brightness (0 and any other mode).
        _ => {
            let i = intensity(r, g, b) - bias;
            if i > 0.0 {
                let angle = i * std::f64::consts::TAU * amount;
                let (s, c) = (jwf_math::sin(angle), jwf_math::cos(angle));
                (px * c - py * s, px * s + py * c)
            } else {
                (px, py)
            }
        }
    };
    if color_mode == 1.0 {
        // The pixel's own colour, and the palette entry nearest to it (see the module
        // documentation).
        acc.rgb = Some([r * 255.0, g * 255.0, b * 255.0]);
        if let Some(c) = v.palette_coordinate(r, g, b) {
            acc.color = c;
        }
    }
    out
}

/// displacemap_wf: the running sum moved by the image under the affine point.
fn displacemap_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (x, y) = displace(v, t.x, t.y, acc.x, acc.y, acc);
    acc.x = x;
    acc.y = y;
    [0.0, 0.0, 0.0]
}

/// post_displacemap_wf: the summed point moved by the image under itself.
fn post_displacemap_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (x, y) = displace(v, t.x, t.y, t.x, t.y, acc);
    [x, y, t.z]
}

// ---------------------------------------------------------------------------------------------
// post_bumpmap_wf

/// post_bumpmap_wf: inside the image's rectangle, z is raised by `offset_z` plus `scale_z`
/// times the pixel's brightness (0 everywhere in the blank default image), or set to that
/// with `reset_z`. As in JWildfire, the pixel is the one under the xform's affine point (the
/// input `t`, [`flag::READS_AFFINE_POINT`]); the summed point, read from `acc`, is moved.
fn post_bumpmap_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        scale_x,
        scale_y,
        scale_z,
        offset_x,
        offset_y,
        offset_z,
        reset_z,
    ] = v.params();
    let img = View::of(v.data());
    let x = (t.x - offset_x + 1.0) / scale_x * 0.5 * f64::from(img.w - 1);
    let y = (t.y - offset_y + 1.0) / scale_y * 0.5 * f64::from(img.h - 1);
    let (ix, iy) = (ftoi(x), ftoi(y));
    if !((0..img.w).contains(&ix) && (0..img.h).contains(&iy)) {
        return [acc.x, acc.y, acc.z];
    }
    let [r, g, b, _] = img.at(ix, iy).map(f64::from);
    let dz = offset_z + scale_z * (intensity(r, g, b) / 255.0);
    [acc.x, acc.y, if reset_z != 0.0 { dz } else { acc.z + dz }]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_gradient_has_its_corners_and_blends_between_them() {
        let d = corner_gradient(256, 256).to_data();
        let g = View::of(&d);
        assert_eq!((g.w, g.h), (256, 256));
        assert_eq!(g.at(0, 0), [255, 0, 0, 255]);
        assert_eq!(g.at(255, 0), [255, 255, 0, 255]);
        assert_eq!(g.at(0, 255), [0, 255, 255, 255]);
        assert_eq!(g.at(255, 255), [0, 0, 255, 255]);
        // Row 1: left end 255 + ((1·((0−255)·1024/255)) >> 10) = 255 − 1024/1024 = 254.
        assert_eq!(g.at(0, 1), [254, 1, 1, 255]);
        // Top row, column 128: green (128·1024) >> 10 = 128.
        assert_eq!(g.at(128, 0), [255, 128, 0, 255]);
    }

    #[test]
    fn a_handed_over_image_replaces_the_default() {
        let img = super::super::resources::ResourceImage {
            w: 2,
            h: 2,
            rgba: vec![[10, 20, 30, 255]; 4],
        };
        assert!(super::super::resources::put_image(
            "h9b-images-test.png",
            img
        ));
        let id = super::super::by_name("colormap_wf").unwrap();
        let mut p = DEFS[0].defaults();
        p[9] = 0.0; // dc_color 0: the pixel's own colour
        let named = ["h9b-images-test.png".to_string()];
        let v = Prepared::with_texts(id, Form::Regular, 1.0, &p, &named, Default::default(), true);
        let t = VarIn {
            x: 0.5,
            y: 0.5,
            ..Default::default()
        };
        let mut acc = Acc::default();
        colormap_wf(&v, &t, &mut acc, &mut FastRng::new(1));
        assert_eq!(acc.rgb, Some([10.0, 20.0, 30.0]));
        // Without a name: the default gradient's top-left quarter at the same point.
        let v = Prepared::with_texts(id, Form::Regular, 1.0, &p, &[], Default::default(), true);
        colormap_wf(&v, &t, &mut acc, &mut FastRng::new(1));
        assert_ne!(acc.rgb, Some([10.0, 20.0, 30.0]));
    }

    /// JWildfire's `getColorIdx`, entry by entry: palette bytes × 200/256, Euclidean
    /// distance, the first of equals, index / (N − 1).
    fn jwildfire_index(pal: &[[u8; 3]], c: [f64; 3]) -> f64 {
        let mut best = (f64::INFINITY, 0);
        for (i, p) in pal.iter().enumerate() {
            let q = p.map(|v| f64::from(v) * 200.0 / 256.0);
            let d = (0..3).map(|k| (q[k] - c[k]).powi(2)).sum::<f64>().sqrt();
            if d < best.0 {
                best = (d, i);
            }
        }
        best.1 as f64 / (pal.len() - 1) as f64
    }

    #[test]
    fn the_flames_gradient_gives_the_nearest_index_which_persists() {
        use crate::flame::Chaos;
        use crate::flame::chaos::Pt;
        use crate::flame::model::{Flame, PaletteIndex as Rule, Var, Xform};
        // A gradient whose entries repeat (the first of equals must win).
        let rgb: Vec<[u8; 3]> = (0..256)
            .map(|i| [(i % 128 * 2) as u8, (255 - i % 128 * 2) as u8, 90])
            .collect();
        let cm = super::super::by_name("colormap_wf").unwrap();
        let dm = super::super::by_name("displacemap_wf").unwrap();
        let mut x = Xform::linear(crate::flame::model::Affine::IDENTITY, 1.0, 0.3);
        x.direct_color = 1.0;
        x.vars.push(Var::new(cm, 1.0));
        let mut d = Var::new(dm, 0.0);
        d.params[1] = 1.0; // color_mode 1
        x.vars.push(d);
        let f = Flame {
            xforms: vec![x],
            palette: crate::gradient::Gradient::from_rgb8("repeats", &rgb),
            palette_index: Rule::JWildfire,
            ..Flame::default()
        };
        let ch = Chaos::new(&f).unwrap();
        assert!(ch.reads_palette);
        let xf = &ch.xforms[0];
        let v = xf.vars.iter().find(|v| v.id == cm).unwrap();
        let dv = xf.vars.iter().find(|v| v.id == dm).unwrap();
        assert!(v.palette.is_some() && dv.palette.is_some());
        for (px, py) in [(0.3, -0.2), (-0.45, 0.1), (0.05, 0.4)] {
            let t = VarIn {
                x: px,
                y: py,
                ..Default::default()
            };
            // The pixel under the point, as its own colour (dc_color 0).
            let mut own = v.clone();
            own.p[9] = 0.0;
            let mut a = Acc::default();
            colormap_wf(&own, &t, &mut a, &mut FastRng::new(1));
            let pixel = a.rgb.unwrap();
            let want = jwildfire_index(&rgb, pixel);
            let mut a = Acc::default();
            colormap_wf(v, &t, &mut a, &mut FastRng::new(1));
            assert_eq!((a.color, a.rgb), (want, None), "({px}, {py})");
            // The displacement map compares the channels in [0, 1].
            let mut a = Acc::default();
            displacemap_wf(dv, &t, &mut a, &mut FastRng::new(1));
            let unit = a.rgb.unwrap().map(|c| c / 255.0);
            assert_eq!(a.color, jwildfire_index(&rgb, unit));
        }
        // Through an xform of the colour map alone: the map sets the point's colour
        // coordinate, which the next iteration blends from.
        let mut one = f.clone();
        one.xforms[0].vars.truncate(2);
        let ch = Chaos::new(&one).unwrap();
        assert!(ch.reads_palette);
        let p = Pt {
            x: 0.3,
            y: -0.2,
            z: 0.0,
            c: 0.9,
        };
        let (q, bad, _) = ch.xforms[0].apply_hiding(p, &mut FastRng::new(3));
        assert!(!bad);
        let mut a = Acc::default();
        let t = VarIn {
            x: 0.3,
            y: -0.2,
            ..Default::default()
        };
        colormap_wf(v, &t, &mut a, &mut FastRng::new(1));
        assert_eq!(q.c, a.color);
        let xf = &ch.xforms[0];
        assert_ne!(
            q.c,
            xf.color_speed * xf.color + (1.0 - xf.color_speed) * 0.9
        );
        // Without these variations no table is built.
        let mut plain = f.clone();
        plain.xforms[0].vars.truncate(1);
        assert!(!Chaos::new(&plain).unwrap().reads_palette);
    }

    #[test]
    fn tiling_follows_java_division() {
        assert_eq!(tile(-1, 256), 255);
        assert_eq!(tile(-256, 256), 256);
        assert_eq!(tile(300, 256), 44);
        assert_eq!(tile(5, 256), 5);
        assert_eq!(ftoi(-2.5), -3);
        assert_eq!(ftoi(2.5), 3);
        assert_eq!(ftoi(f64::NAN), 0);
    }
}
