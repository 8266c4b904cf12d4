//! Tests of the sound file reader: levels, channels, FLAC and MP3, damaged files.

use super::*;
use crate::sound::{Band, band_levels};

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/sound")
        .join(name)
}

fn rms(s: &[f32]) -> f64 {
    (s.iter().map(|v| (*v as f64).powi(2)).sum::<f64>() / s.len() as f64).sqrt()
}

#[test]
fn a_written_wav_reads_back_with_its_level() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("tone.wav");
    let rate = 8000;
    let tone: Vec<f32> = (0..rate)
        .map(|i| 0.5 * (2.0 * std::f32::consts::PI * 440.0 * i as f32 / rate as f32).sin())
        .collect();
    std::fs::write(&path, wav_bytes(&tone, rate)).unwrap();
    let s = read_sound(&path).unwrap();
    assert_eq!((s.rate, s.samples.len()), (rate, rate as usize));
    // A sine of amplitude ½ has an RMS of ½/√2; 16-bit quantisation is far below 1e-4.
    assert!((rms(&s.samples) - 0.5 / 2f64.sqrt()).abs() < 1e-4);
    let peak = s.samples.iter().fold(0f32, |m, v| m.max(v.abs()));
    assert!((peak - 0.5).abs() < 1e-3, "{peak}");
}

#[test]
fn a_background_decode_reports_its_progress_and_stops_when_cancelled() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("long.wav");
    let rate = 8000;
    let tone: Vec<f32> = (0..20 * rate)
        .map(|i| 0.3 * (i as f32 * 0.05).sin())
        .collect();
    std::fs::write(&path, wav_bytes(&tone, rate)).unwrap();
    let seen = std::sync::Mutex::new(Vec::new());
    let s = read_sound_with(&path, &AtomicBool::new(false), &|f| {
        seen.lock().unwrap().push(f)
    })
    .unwrap();
    assert_eq!(s.samples.len(), tone.len());
    let seen = seen.into_inner().unwrap();
    assert!(seen.len() > 2, "{} progress reports", seen.len());
    assert!(
        seen.windows(2).all(|w| w[0] <= w[1]),
        "progress never goes back"
    );
    assert_eq!(*seen.last().unwrap(), 1.0);
    // Cancelled halfway: an error saying so, not a sound cut short.
    let cancel = AtomicBool::new(false);
    let e = read_sound_with(&path, &cancel, &|f| {
        if f > 0.5 {
            cancel.store(true, Ordering::Relaxed);
        }
    })
    .unwrap_err();
    assert!(e.to_string().contains("cancelled"), "{e}");
}

#[test]
fn stereo_is_averaged_into_one_channel() {
    // Left a tone, right its opposite: the mix is silence; left a tone, right silence: half.
    let dir = tempfile::tempdir().unwrap();
    let rate = 8000u32;
    let n = 800;
    let mut opposite = wav_bytes(&vec![0.0; 2 * n], rate);
    // Make it a two-channel file of n frames (the same byte count).
    opposite[22..24].copy_from_slice(&2u16.to_le_bytes());
    opposite[28..32].copy_from_slice(&(rate * 4).to_le_bytes());
    opposite[32..34].copy_from_slice(&4u16.to_le_bytes());
    let mut half = opposite.clone();
    for i in 0..n {
        let v = ((i as f32 * 0.1).sin() * 16000.0) as i16;
        let at = 44 + 4 * i;
        opposite[at..at + 2].copy_from_slice(&v.to_le_bytes());
        opposite[at + 2..at + 4].copy_from_slice(&(-v).to_le_bytes());
        half[at..at + 2].copy_from_slice(&v.to_le_bytes());
    }
    let (p, q) = (dir.path().join("o.wav"), dir.path().join("h.wav"));
    std::fs::write(&p, opposite).unwrap();
    std::fs::write(&q, half).unwrap();
    let (o, h) = (read_sound(&p).unwrap(), read_sound(&q).unwrap());
    assert_eq!(o.samples.len(), n);
    assert!(o.samples.iter().all(|v| v.abs() < 1e-4));
    let full: Vec<f32> = (0..n)
        .map(|i| ((i as f32 * 0.1).sin() * 16000.0).trunc() / 32768.0)
        .collect();
    assert!((rms(&h.samples) - rms(&full) / 2.0).abs() < 1e-4);
}

#[test]
fn flac_and_mp3_tones_land_in_their_bands() {
    // 60 Hz at 8 kHz (FLAC, amplitude 1/16) and 5 kHz at 22.05 kHz (MP3, stereo), one second
    // each, made with ffmpeg.
    let bass = read_sound(&fixture("bass60.flac")).unwrap();
    assert_eq!(bass.rate, 8000);
    assert!((bass.seconds() - 1.0).abs() < 0.01, "{}", bass.seconds());
    assert!(
        (rms(&bass.samples) - 0.0625 / 2f64.sqrt()).abs() < 2e-3,
        "{}",
        rms(&bass.samples)
    );
    let high = read_sound(&fixture("high5k.mp3")).unwrap();
    assert_eq!(high.rate, 22050);
    assert!((high.seconds() - 1.0).abs() < 0.1, "{}", high.seconds());
    for (s, loud, quiet) in [
        (&bass, Band::BASS, Band::HIGH),
        (&bass, Band::BASS, Band::MIDDLE),
        (&high, Band::HIGH, Band::BASS),
        (&high, Band::HIGH, Band::MIDDLE),
    ] {
        let (l, q) = (
            band_levels(s, loud, 10.0, 10),
            band_levels(s, quiet, 10.0, 10),
        );
        assert!(
            q[5] < 0.02 * l[5],
            "{loud:?} {} vs {quiet:?} {}",
            l[5],
            q[5]
        );
    }
}

#[test]
fn bad_files_give_errors_naming_them() {
    let dir = tempfile::tempdir().unwrap();
    let junk = dir.path().join("junk.wav");
    std::fs::write(&junk, b"RIFF this is not a sound at all, only words").unwrap();
    let empty = dir.path().join("empty.mp3");
    std::fs::write(&empty, b"").unwrap();
    let cut = dir.path().join("cut.flac");
    let flac = std::fs::read(fixture("bass60.flac")).unwrap();
    std::fs::write(&cut, &flac[..40]).unwrap();
    for p in [junk, empty, cut, dir.path().join("missing.wav")] {
        let e = read_sound(&p).unwrap_err().to_string();
        assert!(e.contains(&*p.to_string_lossy()), "{e}");
    }
}
