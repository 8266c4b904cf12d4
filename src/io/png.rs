//! PNG export with the flame embedded, and reading a flame back from a PNG.

use std::io::{BufWriter, Cursor};
use std::path::Path;

use image::DynamicImage;

use crate::flame::model::Flame;
use crate::io::atomic::write_atomic_with;
use crate::io::diag::{Diagnostic, Pos};

/// Text keyword holding the flame XML.
pub const GENOME_KEYWORD: &str = "flam3_genome";

/// Metadata written with a PNG.
#[derive(Clone, Debug, Default)]
pub struct PngMeta {
    /// The flame, embedded as a `flam3_genome` zTXt chunk.
    pub flame_xml: Option<String>,
    /// Samples rendered, as a `flam3_samples` text chunk.
    pub samples: Option<u64>,
    /// The share of bad values of the render, as a `flam3_error_rate` text chunk.
    pub error_rate: Option<f64>,
    /// Further text chunks (keyword, ASCII text), e.g. an escape-time view.
    pub text: Vec<(String, String)>,
}

impl PngMeta {
    /// The metadata of a flame render: the flame embedded, nothing else.
    pub fn for_flame(f: &Flame) -> Self {
        PngMeta {
            flame_xml: Some(crate::io::flam3_xml::flame_element(f)),
            ..Self::default()
        }
    }
}

/// Replace every non-ASCII character by a numeric character reference so the text is valid
/// Latin-1 (and plain ASCII).
pub fn ascii_xml(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for ch in s.chars() {
        if ch.is_ascii() {
            o.push(ch);
        } else {
            o.push_str(&format!("&#{};", ch as u32));
        }
    }
    o
}

/// Encode an image (8/16-bit, RGB or RGBA) as PNG bytes with metadata.
pub fn encode(img: &DynamicImage, meta: &PngMeta) -> Result<Vec<u8>, png::EncodingError> {
    let mut out = Vec::new();
    encode_to(&mut out, img, meta)?;
    Ok(out)
}

fn encode_to<W: std::io::Write>(
    w: W,
    img: &DynamicImage,
    meta: &PngMeta,
) -> Result<(), png::EncodingError> {
    let (color, depth, bytes): (png::ColorType, png::BitDepth, Vec<u8>) = match img {
        DynamicImage::ImageRgb8(b) => (
            png::ColorType::Rgb,
            png::BitDepth::Eight,
            b.as_raw().clone(),
        ),
        DynamicImage::ImageRgba8(b) => (
            png::ColorType::Rgba,
            png::BitDepth::Eight,
            b.as_raw().clone(),
        ),
        DynamicImage::ImageRgb16(b) => (
            png::ColorType::Rgb,
            png::BitDepth::Sixteen,
            be16(b.as_raw()),
        ),
        DynamicImage::ImageRgba16(b) => (
            png::ColorType::Rgba,
            png::BitDepth::Sixteen,
            be16(b.as_raw()),
        ),
        other => {
            let b = other.to_rgba8();
            (png::ColorType::Rgba, png::BitDepth::Eight, b.into_raw())
        }
    };
    let mut enc = png::Encoder::new(w, img.width(), img.height());
    enc.set_color(color);
    enc.set_depth(depth);
    // fdeflate: several times faster than zlib-style compression, files a little larger.
    enc.set_compression(png::Compression::Fast);
    enc.add_text_chunk("Software".into(), format!("ugnis {}", crate::VERSION))?;
    if let Some(x) = &meta.flame_xml {
        enc.add_ztxt_chunk(GENOME_KEYWORD.into(), ascii_xml(x))?;
    }
    if let Some(s) = meta.samples {
        enc.add_text_chunk("flam3_samples".into(), s.to_string())?;
    }
    if let Some(e) = meta.error_rate {
        enc.add_text_chunk("flam3_error_rate".into(), format!("{e}"))?;
    }
    for (k, t) in &meta.text {
        enc.add_ztxt_chunk(k.clone(), ascii_xml(t))?;
    }
    let mut wr = enc.write_header()?;
    wr.write_image_data(&bytes)?;
    wr.finish()
}

/// 16-bit samples are big-endian in PNG.
fn be16(v: &[u16]) -> Vec<u8> {
    v.iter().flat_map(|s| s.to_be_bytes()).collect()
}

/// Save a PNG atomically.
pub fn save(path: &Path, img: &DynamicImage, meta: &PngMeta) -> std::io::Result<()> {
    write_atomic_with(path, |f| {
        encode_to(BufWriter::new(f), img, meta).map_err(std::io::Error::other)
    })
}

/// The `flam3_genome` text of PNG bytes.
pub fn read_genome(bytes: &[u8], file: &str) -> Result<String, Diagnostic> {
    read_genome_from(Cursor::new(bytes), file)
}

/// Largest image ugnis decodes to find a genome written after the image data (ugnis and flam3
/// write it before, where it is found without decoding anything).
pub const MAX_DECODE_FOR_GENOME: usize = 256 << 20;

/// The `flam3_genome` text of a PNG read from a stream: only the chunks before the image data
/// are read when the genome is among them, so PNGs of any size (posters) open as flames.
pub fn read_genome_from<R: std::io::BufRead + std::io::Seek>(
    r: R,
    file: &str,
) -> Result<String, Diagnostic> {
    let err = |code, msg: String| Diagnostic::error(file, Pos::Byte(0), code, msg);
    let mut dec = png::Decoder::new(r);
    dec.set_ignore_text_chunk(false);
    let mut reader = dec
        .read_info()
        .map_err(|e| err("PNG001", format!("not a readable PNG: {e}")))?;
    if let Some(t) = find_text(reader.info(), file)? {
        return Ok(t);
    }
    // Text after the image data: read through it.
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| err("PNG001", "image too large".into()))?;
    if size > MAX_DECODE_FOR_GENOME {
        return Err(err(
            "PNG002",
            "image carries no flame (no flam3_genome chunk before the image data)".into(),
        ));
    }
    let mut buf = vec![0; size];
    reader
        .next_frame(&mut buf)
        .map_err(|e| err("PNG001", format!("not a readable PNG: {e}")))?;
    reader
        .finish()
        .map_err(|e| err("PNG001", format!("not a readable PNG: {e}")))?;
    find_text(reader.info(), file)?.ok_or_else(|| {
        err(
            "PNG002",
            "image carries no flame (no flam3_genome chunk)".into(),
        )
    })
}

fn find_text(info: &png::Info, file: &str) -> Result<Option<String>, Diagnostic> {
    let err = |code, msg: String| Diagnostic::error(file, Pos::Byte(0), code, msg);
    if let Some(t) = info
        .uncompressed_latin1_text
        .iter()
        .find(|t| t.keyword == GENOME_KEYWORD)
    {
        return Ok(Some(t.text.clone()));
    }
    if let Some(t) = info
        .compressed_latin1_text
        .iter()
        .find(|t| t.keyword == GENOME_KEYWORD)
    {
        let mut t = t.clone();
        t.decompress_text_with_limit(64 << 20).map_err(|e| {
            err(
                "PNG003",
                format!("flam3_genome chunk cannot be decompressed: {e}"),
            )
        })?;
        return t
            .get_text()
            .map(Some)
            .map_err(|e| err("PNG003", format!("flam3_genome chunk: {e}")));
    }
    if let Some(t) = info.utf8_text.iter().find(|t| t.keyword == GENOME_KEYWORD) {
        let mut t = t.clone();
        t.decompress_text_with_limit(64 << 20).map_err(|e| {
            err(
                "PNG003",
                format!("flam3_genome chunk cannot be decompressed: {e}"),
            )
        })?;
        return t
            .get_text()
            .map(Some)
            .map_err(|e| err("PNG003", format!("flam3_genome chunk: {e}")));
    }
    Ok(None)
}

/// A PNG written band by band (posters rendered in strips): the header and metadata first,
/// then rows as they are made, never the whole image in memory.
pub struct PngStream<W: std::io::Write + 'static> {
    inner: png::StreamWriter<'static, W>,
    sixteen: bool,
}

impl<W: std::io::Write + 'static> PngStream<W> {
    /// Start a `width`×`height` PNG (RGB or RGBA, 8 or 16 bits) with metadata.
    pub fn new(
        w: W,
        width: u32,
        height: u32,
        format: crate::flame::OutputFormat,
        meta: &PngMeta,
    ) -> Result<PngStream<W>, png::EncodingError> {
        let mut enc = png::Encoder::new(w, width, height);
        enc.set_color(if format.transparent {
            png::ColorType::Rgba
        } else {
            png::ColorType::Rgb
        });
        enc.set_depth(if format.bits16 {
            png::BitDepth::Sixteen
        } else {
            png::BitDepth::Eight
        });
        enc.set_compression(png::Compression::Fast);
        enc.add_text_chunk("Software".into(), format!("ugnis {}", crate::VERSION))?;
        if let Some(x) = &meta.flame_xml {
            enc.add_ztxt_chunk(GENOME_KEYWORD.into(), ascii_xml(x))?;
        }
        for (k, t) in &meta.text {
            enc.add_ztxt_chunk(k.clone(), ascii_xml(t))?;
        }
        let inner = enc.write_header()?.into_stream_writer()?;
        Ok(PngStream {
            inner,
            sixteen: format.bits16,
        })
    }

    /// Append the rows of a band (as the renderer made them, in the stream's format).
    pub fn write_rows(&mut self, img: &DynamicImage) -> std::io::Result<()> {
        use std::io::Write as _;
        if self.sixteen {
            let raw: &[u16] = match img {
                DynamicImage::ImageRgb16(b) => b.as_raw(),
                DynamicImage::ImageRgba16(b) => b.as_raw(),
                _ => return Err(std::io::Error::other("a band of the wrong pixel format")),
            };
            self.inner.write_all(&be16(raw))
        } else {
            let raw: &[u8] = match img {
                DynamicImage::ImageRgb8(b) => b.as_raw(),
                DynamicImage::ImageRgba8(b) => b.as_raw(),
                _ => return Err(std::io::Error::other("a band of the wrong pixel format")),
            };
            self.inner.write_all(raw)
        }
    }

    /// End the image (every row must have been written).
    pub fn finish(self) -> std::io::Result<()> {
        self.inner.finish().map_err(std::io::Error::other)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn genome_round_trip_and_bit_depths() {
        let img = DynamicImage::ImageRgb8(image::RgbImage::from_pixel(3, 2, image::Rgb([1, 2, 3])));
        let meta = PngMeta {
            flame_xml: Some("<flame name=\"žvaigždė\"/>".into()),
            samples: Some(12),
            error_rate: None,
            text: vec![("ugnis_escape_view".into(), "kind = julia".into())],
        };
        let bytes = encode(&img, &meta).unwrap();
        let g = read_genome(&bytes, "x.png").unwrap();
        assert_eq!(
            g,
            "<flame name=\"&#382;vaigžd&#279;\"/>".replace('ž', "&#382;")
        );
        let back = image::load_from_memory(&bytes).unwrap();
        assert_eq!(back.to_rgb8().get_pixel(2, 1).0, [1, 2, 3]);
        // 16-bit samples come back exactly (big-endian on disk).
        let img16 = DynamicImage::ImageRgba16(image::ImageBuffer::from_pixel(
            2,
            2,
            image::Rgba([65280u16, 256, 1, 65535]),
        ));
        let bytes = encode(&img16, &PngMeta::default()).unwrap();
        let back = image::load_from_memory(&bytes).unwrap();
        assert_eq!(back.to_rgba16().get_pixel(0, 0).0, [65280, 256, 1, 65535]);
        assert_eq!(read_genome(&bytes, "y.png").unwrap_err().code, "PNG002");
        assert_eq!(
            read_genome(b"not a png", "z.png").unwrap_err().code,
            "PNG001"
        );
    }
}
