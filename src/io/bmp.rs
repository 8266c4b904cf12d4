//! 24-bit BMP export, the thesis program's image format.

use std::path::Path;

use image::DynamicImage;

use crate::io::atomic::write_atomic;

/// Encode an image as a 24-bit bottom-up BMP (BITMAPINFOHEADER, BI_RGB, 72 dpi).
pub fn encode(img: &DynamicImage) -> Vec<u8> {
    let rgb = img.to_rgb8();
    let (w, h) = (rgb.width() as usize, rgb.height() as usize);
    let stride = (3 * w + 3) & !3;
    let size = 54 + stride * h;
    let mut b = Vec::with_capacity(size);
    b.extend_from_slice(b"BM");
    b.extend_from_slice(&(size as u32).to_le_bytes());
    b.extend_from_slice(&0u32.to_le_bytes());
    b.extend_from_slice(&54u32.to_le_bytes());
    b.extend_from_slice(&40u32.to_le_bytes());
    b.extend_from_slice(&(w as i32).to_le_bytes());
    b.extend_from_slice(&(h as i32).to_le_bytes());
    b.extend_from_slice(&1u16.to_le_bytes());
    b.extend_from_slice(&24u16.to_le_bytes());
    b.extend_from_slice(&0u32.to_le_bytes());
    b.extend_from_slice(&((stride * h) as u32).to_le_bytes());
    b.extend_from_slice(&2835i32.to_le_bytes());
    b.extend_from_slice(&2835i32.to_le_bytes());
    b.extend_from_slice(&0u32.to_le_bytes());
    b.extend_from_slice(&0u32.to_le_bytes());
    let raw = rgb.as_raw();
    for y in (0..h).rev() {
        let row = &raw[y * 3 * w..(y + 1) * 3 * w];
        for p in row.chunks(3) {
            b.extend_from_slice(&[p[2], p[1], p[0]]);
        }
        b.resize(b.len() + stride - 3 * w, 0);
    }
    b
}

/// Save a BMP atomically.
pub fn save(path: &Path, img: &DynamicImage) -> std::io::Result<()> {
    write_atomic(path, &encode(img))
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
            let b = encode(&img);
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
        let b = encode(&DynamicImage::ImageRgb8(img.clone()));
        assert_eq!(&b[54 + 6..54 + 9], &[60, 50, 40]);
        assert_eq!(&b[54 + 12..54 + 15], &[30, 20, 10]);
        let back = image::load_from_memory(&b).unwrap().to_rgb8();
        assert_eq!(back, img);
    }
}
