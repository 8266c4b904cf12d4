//! Reading sound files (WAV, FLAC, MP3) as one channel of samples, for sound-driven motion: the
//! channels are averaged into one. Files are limited in size and length; a file that is not a
//! sound, or is cut short or damaged, gives an error naming it.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

use symphonia::core::audio::SampleBuffer;
use symphonia::core::codecs::{CODEC_TYPE_NULL, DecoderOptions};
use symphonia::core::errors::Error as SymError;
use symphonia::core::formats::FormatOptions;
use symphonia::core::io::MediaSourceStream;
use symphonia::core::meta::MetadataOptions;
use symphonia::core::probe::Hint;

use crate::sound::Sound;

/// Largest sound file read (bytes).
pub const MAX_FILE_BYTES: u64 = 1 << 30;
/// Most samples (per channel) kept: 24 minutes at 44.1 kHz.
pub const MAX_SAMPLES: usize = 64 << 20;
/// Damaged packets skipped before the file is refused.
const MAX_BAD_PACKETS: usize = 100;

/// Why a sound file could not be read.
#[derive(Debug, thiserror::Error)]
#[error("'{}': {message}", path.display())]
pub struct AudioError {
    /// The sound file.
    pub path: PathBuf,
    /// What is wrong with it.
    pub message: String,
}

/// Read `path` as one channel of samples at the file's rate.
pub fn read_sound(path: &Path) -> Result<Sound, AudioError> {
    read_sound_with(path, &AtomicBool::new(false), &|_| {})
}

/// [`read_sound`] for a background job: `progress` is told the share decoded (when the file
/// says its length), and setting `cancel` stops the decoding with an error saying so.
pub fn read_sound_with(
    path: &Path,
    cancel: &AtomicBool,
    progress: &dyn Fn(f64),
) -> Result<Sound, AudioError> {
    let fail = |message: String| AudioError {
        path: path.to_path_buf(),
        message,
    };
    let file = std::fs::File::open(path).map_err(|e| fail(format!("cannot open: {e}")))?;
    let len = file
        .metadata()
        .map_err(|e| fail(format!("cannot read: {e}")))?
        .len();
    if len > MAX_FILE_BYTES {
        return Err(fail(format!(
            "{} MB; ugnis reads sound files up to {} MB",
            len >> 20,
            MAX_FILE_BYTES >> 20
        )));
    }
    let mut hint = Hint::new();
    if let Some(ext) = path.extension().and_then(|e| e.to_str()) {
        hint.with_extension(ext);
    }
    let stream = MediaSourceStream::new(Box::new(file), Default::default());
    let probed = symphonia::default::get_probe()
        .format(
            &hint,
            stream,
            &FormatOptions::default(),
            &MetadataOptions::default(),
        )
        .map_err(|e| {
            fail(format!(
                "not a sound file ugnis reads (WAV, FLAC, MP3): {e}"
            ))
        })?;
    let mut format = probed.format;
    let track = format
        .tracks()
        .iter()
        .find(|t| t.codec_params.codec != CODEC_TYPE_NULL)
        .ok_or_else(|| fail("holds no sound track".into()))?;
    let (track_id, params) = (track.id, track.codec_params.clone());
    let rate = params
        .sample_rate
        .filter(|r| (1..=768_000).contains(r))
        .ok_or_else(|| fail("its sample rate is missing or out of range".into()))?;
    let mut decoder = symphonia::default::get_codecs()
        .make(&params, &DecoderOptions::default())
        .map_err(|e| fail(format!("cannot decode its sound: {e}")))?;
    let mut samples: Vec<f32> = Vec::new();
    let mut bad = 0;
    let mut buf: Option<SampleBuffer<f32>> = None;
    let length = params.n_frames.filter(|&n| n > 0);
    loop {
        if cancel.load(Ordering::Relaxed) {
            return Err(fail("cancelled".into()));
        }
        let packet = match format.next_packet() {
            Ok(p) => p,
            Err(SymError::IoError(e)) if e.kind() == std::io::ErrorKind::UnexpectedEof => break,
            Err(SymError::ResetRequired) => break,
            Err(e) => return Err(fail(format!("damaged: {e}"))),
        };
        if packet.track_id() != track_id {
            continue;
        }
        let decoded = match decoder.decode(&packet) {
            Ok(d) => d,
            Err(SymError::DecodeError(e)) => {
                bad += 1;
                if bad > MAX_BAD_PACKETS {
                    return Err(fail(format!(
                        "damaged (more than {MAX_BAD_PACKETS} bad packets): {e}"
                    )));
                }
                continue;
            }
            Err(SymError::IoError(e)) if e.kind() == std::io::ErrorKind::UnexpectedEof => break,
            Err(e) => return Err(fail(format!("damaged: {e}"))),
        };
        let spec = *decoded.spec();
        let channels = spec.channels.count().max(1);
        let b = match &mut buf {
            Some(b) if b.capacity() >= decoded.capacity() * channels => b,
            _ => buf.insert(SampleBuffer::new(decoded.capacity() as u64, spec)),
        };
        b.copy_interleaved_ref(decoded);
        if samples.len() + b.samples().len() / channels > MAX_SAMPLES {
            return Err(fail(format!(
                "longer than {:.0} seconds at {rate} Hz; ugnis reads at most {MAX_SAMPLES} samples",
                MAX_SAMPLES as f64 / rate as f64
            )));
        }
        samples.extend(
            b.samples()
                .chunks(channels)
                .map(|c| c.iter().sum::<f32>() / channels as f32),
        );
        if let Some(n) = length {
            progress((samples.len() as f64 / n as f64).min(1.0));
        }
    }
    if samples.is_empty() {
        return Err(fail("holds no sound (no samples could be decoded)".into()));
    }
    Ok(Sound { rate, samples })
}

/// A mono 16-bit PCM WAV file of `samples` (in [−1, 1]) at `rate`, as bytes.
pub fn wav_bytes(samples: &[f32], rate: u32) -> Vec<u8> {
    let data = (samples.len() * 2) as u32;
    let mut v = Vec::with_capacity(44 + data as usize);
    v.extend_from_slice(b"RIFF");
    v.extend_from_slice(&(36 + data).to_le_bytes());
    v.extend_from_slice(b"WAVEfmt ");
    v.extend_from_slice(&16u32.to_le_bytes());
    v.extend_from_slice(&1u16.to_le_bytes()); // PCM
    v.extend_from_slice(&1u16.to_le_bytes()); // one channel
    v.extend_from_slice(&rate.to_le_bytes());
    v.extend_from_slice(&(rate * 2).to_le_bytes());
    v.extend_from_slice(&2u16.to_le_bytes());
    v.extend_from_slice(&16u16.to_le_bytes());
    v.extend_from_slice(b"data");
    v.extend_from_slice(&data.to_le_bytes());
    for s in samples {
        let q = (s.clamp(-1.0, 1.0) * 32767.0).round() as i16;
        v.extend_from_slice(&q.to_le_bytes());
    }
    v
}

#[cfg(test)]
#[path = "audio_tests.rs"]
mod tests;
