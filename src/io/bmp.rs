//! 24-bit BMP export, Fraktalai's image format.

use std::path::Path;

use image::codecs::bmp::BmpEncoder;
use image::{DynamicImage, ExtendedColorType};

use crate::io::atomic::write_atomic;

/// Encode an image as a 24-bit bottom-up BMP (BITMAPINFOHEADER, BI_RGB, 72 dpi) with the
/// `image` crate's encoder. Fails when the picture is too large for the format (its size must
/// fit in 32 bits).
pub fn encode(img: &DynamicImage) -> std::io::Result<Vec<u8>> {
    let rgb = img.to_rgb8();
    let mut b = Vec::new();
    BmpEncoder::new(&mut b)
        .encode(
            rgb.as_raw(),
            rgb.width(),
            rgb.height(),
            ExtendedColorType::Rgb8,
        )
        .map_err(std::io::Error::other)?;
    // The encoder leaves the resolution unset (0); ugnis' BMP files have always said 72 dpi
    // (2835 pixels per metre), which is kept so that they stay the same byte for byte.
    for field in [RESOLUTION_X, RESOLUTION_Y] {
        b[field..field + 4].copy_from_slice(&PIXELS_PER_METRE.to_le_bytes());
    }
    Ok(b)
}

/// Offsets of the horizontal and vertical resolution in the BITMAPINFOHEADER.
const RESOLUTION_X: usize = 38;
const RESOLUTION_Y: usize = 42;
/// 72 dpi.
const PIXELS_PER_METRE: i32 = 2835;

/// Save a BMP atomically.
pub fn save(path: &Path, img: &DynamicImage) -> std::io::Result<()> {
    write_atomic(path, &encode(img)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_and_layout() {
        let sizes = [
            ((1, 1), 58),
            ((2, 2), 70),
            ((3, 2), 78),
            ((640, 480), 921_654),
        ];
        for ((w, h), want) in sizes {
            let img = DynamicImage::ImageRgb8(image::RgbImage::new(w, h));
            let b = encode(&img).unwrap();
            assert_eq!(b.len(), want);
            assert_eq!(&b[0..2], b"BM");
            assert_eq!(
                u32::from_le_bytes(b[2..6].try_into().unwrap()) as usize,
                want
            );
        }
        // Bottom row first, BGR order; decodes back to the same picture.
        let mut img = image::RgbImage::new(3, 2);
        img.put_pixel(0, 0, image::Rgb([10, 20, 30]));
        img.put_pixel(2, 1, image::Rgb([40, 50, 60]));
        let b = encode(&DynamicImage::ImageRgb8(img.clone())).unwrap();
        assert_eq!(&b[54 + 6..54 + 9], &[60, 50, 40]);
        assert_eq!(&b[54 + 12..54 + 15], &[30, 20, 10]);
        let back = image::load_from_memory(&b).unwrap().to_rgb8();
        assert_eq!(back, img);
    }
}
