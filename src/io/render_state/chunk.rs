//! The histogram chunks of a render state: a bit per bucket, then the non-empty buckets'
//! alphas and colours as byte planes (whole numbers as integers), deflated.

use std::io::{Read, Write};

use super::err;
use crate::flame::histogram::Bucket;
use crate::io::diag::{Diagnostic, Pos};

/// Byte planes: all the lowest bytes of `words`, then the next…
fn shuffle_into(out: &mut Vec<u8>, words: &[u32]) {
    for k in 0..4 {
        out.extend(words.iter().map(|w| (w >> (8 * k)) as u8));
    }
}

fn unshuffle(bytes: &[u8], n: usize) -> Vec<u32> {
    (0..n)
        .map(|i| u32::from_le_bytes([bytes[i], bytes[n + i], bytes[2 * n + i], bytes[3 * n + i]]))
        .collect()
}

/// Can this accumulator be stored as a whole number (and read back bit for bit)?
fn integral(a: f32) -> bool {
    (0.0..=16_777_216.0).contains(&a) && (a as u32 as f32).to_bits() == a.to_bits()
}

/// Flags of a chunk: its alphas, its colours are whole numbers stored as integers.
const WHOLE_ALPHAS: u8 = 1;
const WHOLE_COLOURS: u8 = 2;

/// The words of accumulators: whole numbers as integers (high bytes mostly zero), else bits.
fn words(values: impl Iterator<Item = f32>, whole: bool) -> Vec<u32> {
    values
        .map(|v| if whole { v as u32 } else { v.to_bits() })
        .collect()
}

fn floats(words: Vec<u32>, whole: bool) -> Vec<f32> {
    words
        .into_iter()
        .map(|w| if whole { w as f32 } else { f32::from_bits(w) })
        .collect()
}

/// A chunk before deflate: a bit per bucket (set: not all zero), flags (whole alphas — hit
/// counts of opaque palettes — and whole colours — sums of 8-bit palette entries — stored as
/// integers), the alphas of the set buckets, then their R, G, B, each as byte planes. Empty
/// buckets cost one bit; the noisy low mantissa bytes are kept apart from the exponents.
pub(super) fn compress(rows: &[Bucket]) -> std::io::Result<Vec<u8>> {
    let n = rows.len();
    let mut mask = vec![0u8; n.div_ceil(8)];
    let mut kept: Vec<&Bucket> = Vec::new();
    for (i, b) in rows.iter().enumerate() {
        if b.iter().any(|v| v.to_bits() != 0) {
            mask[i / 8] |= 1 << (i % 8);
            kept.push(b);
        }
    }
    let whole_a = kept.iter().all(|b| integral(b[3]));
    let whole_c = kept.iter().all(|b| b[..3].iter().all(|&v| integral(v)));
    let mut buf = Vec::with_capacity(mask.len() + 1 + kept.len() * 16);
    buf.extend_from_slice(&mask);
    buf.push(if whole_a { WHOLE_ALPHAS } else { 0 } | if whole_c { WHOLE_COLOURS } else { 0 });
    shuffle_into(&mut buf, &words(kept.iter().map(|b| b[3]), whole_a));
    let rgb = kept.iter().flat_map(|b| [b[0], b[1], b[2]]);
    shuffle_into(&mut buf, &words(rgb, whole_c));
    let mut enc = flate2::write::DeflateEncoder::new(
        Vec::with_capacity(buf.len() / 2),
        flate2::Compression::fast(),
    );
    enc.write_all(&buf)?;
    enc.finish()
}

pub(super) fn decompress(
    file: &str,
    at: u64,
    bytes: &[u8],
    out: &mut [Bucket],
) -> Result<(), Diagnostic> {
    let n = out.len();
    let damaged = |m: String| err(file, Pos::Byte(at), format!("damaged histogram chunk: {m}"));
    let limit = n.div_ceil(8) + 1 + n * 16;
    let mut buf = Vec::with_capacity(limit);
    flate2::read::DeflateDecoder::new(bytes)
        .take(limit as u64 + 1)
        .read_to_end(&mut buf)
        .map_err(|e| damaged(e.to_string()))?;
    let mlen = n.div_ceil(8);
    if buf.len() < mlen + 1 {
        return Err(damaged("too short".into()));
    }
    let m = (0..n).filter(|&i| buf[i / 8] & (1 << (i % 8)) != 0).count();
    if buf.len() != mlen + 1 + 16 * m {
        return Err(damaged(format!(
            "{} bytes where {} were expected",
            buf.len(),
            mlen + 1 + 16 * m
        )));
    }
    let flags = buf[mlen];
    if flags & !(WHOLE_ALPHAS | WHOLE_COLOURS) != 0 {
        return Err(damaged(format!("unknown accumulator encoding {flags}")));
    }
    let alpha = floats(
        unshuffle(&buf[mlen + 1..mlen + 1 + 4 * m], m),
        flags & WHOLE_ALPHAS != 0,
    );
    let rgb = floats(
        unshuffle(&buf[mlen + 1 + 4 * m..], 3 * m),
        flags & WHOLE_COLOURS != 0,
    );
    let mut k = 0;
    for (i, o) in out.iter_mut().enumerate() {
        if buf[i / 8] & (1 << (i % 8)) == 0 {
            *o = [0.0; 4];
            continue;
        }
        *o = [rgb[3 * k], rgb[3 * k + 1], rgb[3 * k + 2], alpha[k]];
        k += 1;
    }
    Ok(())
}
