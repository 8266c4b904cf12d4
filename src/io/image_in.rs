//! Reading images (JPEG, PNG, BMP, GIF) for gradients from images, with size limits and BMP
//! header checks that report byte offsets.

use std::path::Path;

use image::{ImageReader, Limits, RgbImage};

use crate::gradient::{Gradient, from_pixels};
use crate::io::diag::{Diagnostic, Pos};

/// Largest image (pixels) accepted.
pub const MAX_PIXELS: u64 = 100_000_000;

fn rd16(b: &[u8], o: usize) -> Option<u16> {
    Some(u16::from_le_bytes(b.get(o..o + 2)?.try_into().ok()?))
}
fn rd32(b: &[u8], o: usize) -> Option<u32> {
    Some(u32::from_le_bytes(b.get(o..o + 4)?.try_into().ok()?))
}

/// Validate a BMP header before decoding: the decoder's own messages do not say where.
pub fn check_bmp(b: &[u8], file: &str) -> Result<(), Diagnostic> {
    let e = |off: u64, code, msg: String| Diagnostic::error(file, Pos::Byte(off), code, msg);
    if b.len() < 2 || &b[..2] != b"BM" {
        return Err(e(
            0,
            "BMP001",
            "not a BMP file: the signature is not 'BM'".into(),
        ));
    }
    let trunc = |off: u64| e(off, "BMP002", "truncated header".into());
    let offset = rd32(b, 10).ok_or_else(|| trunc(10))? as u64;
    let hsize = rd32(b, 14).ok_or_else(|| trunc(14))?;
    let (w, h, planes, bpp, comp, clr_used): (i64, i64, u16, u16, u32, u32) = if hsize == 12 {
        (
            rd16(b, 18).ok_or_else(|| trunc(18))? as i64,
            rd16(b, 20).ok_or_else(|| trunc(20))? as i64,
            rd16(b, 22).ok_or_else(|| trunc(22))?,
            rd16(b, 24).ok_or_else(|| trunc(24))?,
            0,
            0,
        )
    } else if [40, 52, 56, 64, 108, 124].contains(&hsize) {
        (
            rd32(b, 18).ok_or_else(|| trunc(18))? as i32 as i64,
            rd32(b, 22).ok_or_else(|| trunc(22))? as i32 as i64,
            rd16(b, 26).ok_or_else(|| trunc(26))?,
            rd16(b, 28).ok_or_else(|| trunc(28))?,
            rd32(b, 30).ok_or_else(|| trunc(30))?,
            rd32(b, 46).ok_or_else(|| trunc(46))?,
        )
    } else {
        return Err(e(
            14,
            "BMP004",
            format!("unsupported BMP header size {hsize}"),
        ));
    };
    if w <= 0 || h == 0 {
        return Err(e(18, "BMP003", format!("image size {w}×{h} is invalid")));
    }
    if (w as u64) * h.unsigned_abs() > MAX_PIXELS {
        return Err(e(
            18,
            "BMP003",
            format!(
                "image of {w}×{} pixels exceeds the limit of {MAX_PIXELS}",
                h.abs()
            ),
        ));
    }
    let plane_off = if hsize == 12 { 22 } else { 26 };
    if planes != 1 {
        return Err(e(
            plane_off,
            "BMP004",
            format!("planes = {planes}; must be 1"),
        ));
    }
    let ok = matches!(
        (bpp, comp),
        (1 | 4 | 8 | 24, 0) | (16 | 32, 0 | 3) | (8, 1) | (4, 2)
    );
    if !ok {
        return Err(e(
            plane_off + 2,
            "BMP004",
            format!("unsupported {bpp}-bit BMP with compression {comp}"),
        ));
    }
    if bpp <= 8 && clr_used as u64 > 1u64 << bpp {
        return Err(e(
            46,
            "BMP006",
            format!(
                "palette of {clr_used} colours for a {bpp}-bit image (max {})",
                1u64 << bpp
            ),
        ));
    }
    if offset >= b.len() as u64 {
        return Err(e(
            10,
            "BMP005",
            format!(
                "pixel data offset {offset} is outside the file ({} bytes)",
                b.len()
            ),
        ));
    }
    if comp == 0 {
        let stride = (w as u64 * bpp as u64).div_ceil(32) * 4;
        let need = stride * h.unsigned_abs();
        if offset + need > b.len() as u64 {
            return Err(e(
                offset,
                "BMP002",
                format!(
                    "truncated pixel data: {need} bytes expected, {} present",
                    b.len() as u64 - offset
                ),
            ));
        }
    }
    Ok(())
}

/// Decode an image file to RGB with the size limit.
pub fn read_rgb(path: &Path) -> Result<RgbImage, Diagnostic> {
    let name = path.display().to_string();
    let bytes = crate::io::read_bytes(path)?;
    decode_rgb(&bytes, &name)
}

/// Decode image bytes to RGB with the size limit.
pub fn decode_rgb(bytes: &[u8], name: &str) -> Result<RgbImage, Diagnostic> {
    if bytes.starts_with(b"BM") {
        check_bmp(bytes, name)?;
    }
    let mut r = ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| {
            Diagnostic::error(name, Pos::Byte(0), "IMG001", format!("cannot read: {e}"))
        })?;
    let mut limits = Limits::default();
    limits.max_alloc = Some(1 << 30);
    r.limits(limits);
    let img = r.decode().map_err(|e| {
        Diagnostic::error(
            name,
            Pos::Byte(0),
            "IMG001",
            format!("cannot decode the image: {e}"),
        )
    })?;
    if img.width() as u64 * img.height() as u64 > MAX_PIXELS {
        return Err(Diagnostic::error(
            name,
            Pos::Byte(0),
            "IMG002",
            "image too large",
        ));
    }
    Ok(img.to_rgb8())
}

/// A gradient from an image file (see [`from_pixels`] for the method).
pub fn gradient_from_image(path: &Path, seed: u64) -> Result<Gradient, Diagnostic> {
    let img = read_rgb(path)?;
    let name = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "image".into());
    Ok(gradient_from_rgb(&name, &img, seed))
}

/// The size a large image is reduced to before its colours are clustered: the longer side
/// [`GRADIENT_SIDE`] pixels, the aspect ratio kept, never less than one pixel a side (a
/// 1×1 100 000 strip stays a strip). Images of at most 2^20 pixels are used as they are.
pub fn gradient_sample_size(w: u32, h: u32) -> (u32, u32) {
    if w as u64 * h as u64 <= 1 << 20 {
        return (w, h);
    }
    let long = w.max(h) as f64;
    let k = GRADIENT_SIDE as f64 / long;
    (
        ((w as f64 * k).round() as u32).clamp(1, GRADIENT_SIDE),
        ((h as f64 * k).round() as u32).clamp(1, GRADIENT_SIDE),
    )
}

/// Longer side of the downsampled image a gradient is made from.
pub const GRADIENT_SIDE: u32 = 1024;

/// A gradient from decoded pixels (see [`from_pixels`]); large images are downsampled first
/// (the clustering samples 20 000 pixels anyway).
pub fn gradient_from_rgb(name: &str, img: &RgbImage, seed: u64) -> Gradient {
    let (tw, th) = gradient_sample_size(img.width(), img.height());
    let small;
    let img = if (tw, th) != img.dimensions() {
        small = image::imageops::thumbnail(img, tw, th);
        &small
    } else {
        img
    };
    let pixels: Vec<[u8; 3]> = img.pixels().map(|p| p.0).collect();
    from_pixels(name, &pixels, seed)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bmp(w: i32, h: i32) -> Vec<u8> {
        crate::io::bmp::encode(&image::DynamicImage::ImageRgb8(RgbImage::from_pixel(
            w as u32,
            h as u32,
            image::Rgb([200, 100, 50]),
        )))
        .unwrap()
    }

    #[test]
    fn bmp_checks_have_codes_and_offsets() {
        let good = bmp(3, 2);
        assert!(check_bmp(&good, "g.bmp").is_ok());
        assert_eq!(
            decode_rgb(&good, "g.bmp").unwrap().get_pixel(2, 1).0,
            [200, 100, 50]
        );
        let mut b = good.clone();
        b[0] = b'X';
        assert_eq!(check_bmp(&b, "x").unwrap_err().code, "BMP001");
        assert_eq!(check_bmp(&good[..20], "x").unwrap_err().code, "BMP002");
        let mut b = good.clone();
        b[18..22].copy_from_slice(&0i32.to_le_bytes());
        assert_eq!(check_bmp(&b, "x").unwrap_err().code, "BMP003");
        let mut b = good.clone();
        b[26] = 2;
        let e = check_bmp(&b, "x").unwrap_err();
        assert_eq!((e.code, e.pos), ("BMP004", Pos::Byte(26)));
        let mut b = good.clone();
        b[10..14].copy_from_slice(&9999u32.to_le_bytes());
        assert_eq!(check_bmp(&b, "x").unwrap_err().code, "BMP005");
        assert_eq!(
            check_bmp(&good[..good.len() - 3], "x").unwrap_err().code,
            "BMP002"
        );
        let mut b = good.clone();
        b[18..22].copy_from_slice(&100_000i32.to_le_bytes());
        b[22..26].copy_from_slice(&100_000i32.to_le_bytes());
        assert_eq!(check_bmp(&b, "x").unwrap_err().code, "BMP003");
        // Top-down (negative height) files are accepted.
        let mut b = good.clone();
        b[22..26].copy_from_slice(&(-2i32).to_le_bytes());
        assert!(check_bmp(&b, "x").is_ok());
        assert_eq!(decode_rgb(b"not an image", "n").unwrap_err().code, "IMG001");
    }

    #[test]
    fn long_strips_keep_their_colour() {
        // The downsampled size never reaches zero and keeps the aspect ratio.
        assert_eq!(gradient_sample_size(1, 1_100_000), (1, 1024));
        assert_eq!(gradient_sample_size(1_100_000, 1), (1024, 1));
        assert_eq!(gradient_sample_size(4000, 3000), (1024, 768));
        assert_eq!(gradient_sample_size(640, 480), (640, 480));
        for (w, h) in [(1_100_000, 1), (1, 1_100_000)] {
            let img = RgbImage::from_pixel(w, h, image::Rgb([255, 0, 0]));
            let g = gradient_from_rgb("red", &img, 1);
            for i in [0, 128, 255] {
                assert_eq!(g.rgb8(i), [255, 0, 0], "{w}x{h} entry {i}");
            }
        }
    }
}
