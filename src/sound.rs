//! Sound-driven motion: the loudness of a frequency band of a sound, frame by frame, made into a
//! keyframe curve that moves a flame's setting with the music (as JWildfire's sound-driven
//! animations do). The sound's samples come from the reader in `io`; here they are analysed:
//! for every video frame a Hann-windowed stretch of samples around the frame's time is
//! transformed (FFT), the power of the band's bins summed, and the energies scaled to [0, 1],
//! optionally with a fast attack and slower release so the motion does not flicker.

use crate::flame::Flame;
use crate::flame::keyframes::{self, Curve, Interp, Key, MAX_KEYS, Target};

/// Samples per analysis window (about 46 ms at 44.1 kHz).
pub const WINDOW: usize = 2048;
/// Most frames an analysis may have.
pub const MAX_FRAMES: usize = 10_000_000;

/// A sound as mono samples in [−1, 1].
#[derive(Clone, Debug, PartialEq)]
pub struct Sound {
    /// Samples per second, in hertz (44 100 for a CD); 0 is read as 1.
    pub rate: u32,
    /// The samples in time order, one channel (the reader averages the channels of a file).
    pub samples: Vec<f32>,
}

impl Sound {
    /// Length in seconds.
    pub fn seconds(&self) -> f64 {
        self.samples.len() as f64 / self.rate.max(1) as f64
    }
}

/// A frequency band, in hertz.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    /// The lowest frequency, in hertz (bin 0, the constant part, is always left out).
    pub low: f64,
    /// The highest frequency, in hertz (frequencies above half the sample rate are left
    /// out).
    pub high: f64,
}

impl Band {
    /// The bass (20–150 Hz): kicks and bass lines.
    pub const BASS: Band = Band {
        low: 20.0,
        high: 150.0,
    };
    /// The middle (150–2000 Hz): voices, most instruments.
    pub const MIDDLE: Band = Band {
        low: 150.0,
        high: 2000.0,
    };
    /// The highs (2–16 kHz): cymbals, hi-hats.
    pub const HIGH: Band = Band {
        low: 2000.0,
        high: 16000.0,
    };
}

/// How the energies follow the sound: how fast they may rise and fall, as the fraction of the
/// way to a new value taken per frame (1: at once).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Smoothing {
    /// The fraction of the way taken per frame while the energy rises, in [0, 1]
    /// (default 1: at once).
    pub attack: f64,
    /// The fraction of the way taken per frame while the energy falls, in [0, 1]
    /// (default 0.3: a sound fades out over a few frames).
    pub release: f64,
}

impl Default for Smoothing {
    fn default() -> Self {
        Smoothing {
            attack: 1.0,
            release: 0.3,
        }
    }
}

/// In-place radix-2 FFT of `re`/`im` (length a power of two).
fn fft(re: &mut [f64], im: &mut [f64]) {
    let n = re.len();
    debug_assert!(n.is_power_of_two() && im.len() == n);
    let mut j = 0;
    for i in 1..n {
        let mut bit = n >> 1;
        while j & bit != 0 {
            j ^= bit;
            bit >>= 1;
        }
        j |= bit;
        if i < j {
            re.swap(i, j);
            im.swap(i, j);
        }
    }
    let mut len = 2;
    while len <= n {
        let ang = -2.0 * std::f64::consts::PI / len as f64;
        for start in (0..n).step_by(len) {
            for k in 0..len / 2 {
                let (s, c) = (ang * k as f64).sin_cos();
                let (a, b) = (start + k, start + k + len / 2);
                let (xr, xi) = (re[b] * c - im[b] * s, re[b] * s + im[b] * c);
                re[b] = re[a] - xr;
                im[b] = im[a] - xi;
                re[a] += xr;
                im[a] += xi;
            }
        }
        len <<= 1;
    }
}

/// The band's level (the root of its power) at each of `frames` video frames at `fps`.
pub fn band_levels(sound: &Sound, band: Band, fps: f64, frames: usize) -> Vec<f64> {
    let frames = frames.min(MAX_FRAMES);
    let rate = sound.rate.max(1) as f64;
    let hann: Vec<f64> = (0..WINDOW)
        .map(|i| 0.5 - 0.5 * (2.0 * std::f64::consts::PI * i as f64 / WINDOW as f64).cos())
        .collect();
    let bin_hz = rate / WINDOW as f64;
    let lo = ((band.low / bin_hz).floor().max(1.0)) as usize;
    let hi = ((band.high / bin_hz).ceil() as usize).clamp(lo, WINDOW / 2);
    let (mut re, mut im) = (vec![0.0; WINDOW], vec![0.0; WINDOW]);
    (0..frames)
        .map(|f| {
            let centre = (f as f64 / fps.max(1e-9) * rate) as i64;
            for (i, (r, m)) in re.iter_mut().zip(im.iter_mut()).enumerate() {
                let k = centre - (WINDOW / 2) as i64 + i as i64;
                let s = if k >= 0 {
                    sound.samples.get(k as usize).copied().unwrap_or(0.0)
                } else {
                    0.0
                };
                *r = s as f64 * hann[i];
                *m = 0.0;
            }
            fft(&mut re, &mut im);
            (lo..hi)
                .map(|b| re[b] * re[b] + im[b] * im[b])
                .sum::<f64>()
                .sqrt()
        })
        .collect()
}

/// The band's levels at each of `frames` video frames at `fps`, scaled so the loudest frame is
/// 1 (all 0 for silence), smoothed by `smooth`.
pub fn band_energy(
    sound: &Sound,
    band: Band,
    fps: f64,
    frames: usize,
    smooth: Smoothing,
) -> Vec<f64> {
    let mut energy = band_levels(sound, band, fps, frames);
    let max = energy.iter().cloned().fold(0.0, f64::max);
    if max > 0.0 {
        for e in &mut energy {
            *e /= max;
        }
    }
    let mut level = 0.0;
    for e in &mut energy {
        let k = if *e > level {
            smooth.attack
        } else {
            smooth.release
        };
        level += (*e - level) * k.clamp(0.0, 1.0);
        *e = level;
    }
    energy
}

/// A curve for `target` with a key at every frame (`low` at silence, `high` at the loudest),
/// linear between them; past [`MAX_KEYS`] frames, a key every few frames and at the last.
pub fn curve_from_energy(energy: &[f64], target: Target, low: f64, high: f64) -> Curve {
    let mut c = Curve::new(target);
    let step = energy.len().div_ceil(MAX_KEYS - 1).max(1);
    let last = energy.len().saturating_sub(1);
    for (f, e) in energy.iter().enumerate() {
        if f % step != 0 && f != last {
            continue;
        }
        let v = low + (high - low) * e;
        let key = Key {
            interp: Interp::Linear,
            ..Key::new(f as f64, v)
        };
        // Values are finite and frames distinct; a scale factor's low end must be positive,
        // which the caller chose.
        let _ = c.insert(key);
    }
    c
}

/// What a sound moves: a target from `low` (silence) to `high` (the loudest frame), the band
/// that drives it and how fast it follows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drive {
    /// The setting the sound moves.
    pub target: Target,
    /// The frequency band listened to.
    pub band: Band,
    /// The value at silence.
    pub low: f64,
    /// The value at the loudest frame.
    pub high: f64,
    /// How fast the value follows the sound.
    pub smooth: Smoothing,
}

/// Give `flame` the curve `sound` makes for `d.target`: on the flame's timeline, or, when the
/// flame has no keyframes yet, on a new one as long as the sound at the flame's frame rate.
/// A curve the target had is replaced (the result says so: `Ok(true)`). Refused with a
/// message: a target the flame lacks, a scale factor with an end not above 0, a sound longer
/// than an animation may be.
pub fn drive_flame(flame: &mut Flame, sound: &Sound, d: &Drive) -> Result<bool, String> {
    let target = d.target;
    if target.get(flame).is_none() {
        return Err(format!(
            "'{target}' is not in this flame ({} xforms, {})",
            flame.xforms.len(),
            if flame.final_xform.is_some() {
                "and a final one"
            } else {
                "no final one"
            }
        ));
    }
    if !(d.low.is_finite() && d.high.is_finite()) {
        return Err(format!("the range {}..{} must be numbers", d.low, d.high));
    }
    if target.is_logarithmic() && (d.low <= 0.0 || d.high <= 0.0) {
        return Err(format!(
            "'{target}' is a scale factor: both ends of {}..{} must be above 0",
            d.low, d.high
        ));
    }
    if flame.keys.is_empty() {
        let frames = (sound.seconds() * flame.keys.fps).ceil().max(1.0);
        if frames > keyframes::MAX_FRAMES as f64 {
            return Err(format!(
                "the sound lasts {frames} frames at {} fps; an animation has at most {}",
                flame.keys.fps,
                keyframes::MAX_FRAMES
            ));
        }
        flame.keys.frames = frames as u32;
    }
    let k = &flame.keys;
    let energy = band_energy(sound, d.band, k.fps, k.frames as usize, d.smooth);
    let curve = curve_from_energy(&energy, target, d.low, d.high);
    let replaced = k.curve(&target).is_some();
    flame.keys.curves.retain(|c| c.target != target);
    flame.keys.curves.push(curve);
    Ok(replaced)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::keyframes::FlameParam;

    fn tone(hz: f64, rate: u32, seconds: f64, amp: impl Fn(f64) -> f64) -> Sound {
        let n = (rate as f64 * seconds) as usize;
        Sound {
            rate,
            samples: (0..n)
                .map(|i| {
                    let t = i as f64 / rate as f64;
                    (amp(t) * (2.0 * std::f64::consts::PI * hz * t).sin()) as f32
                })
                .collect(),
        }
    }

    #[test]
    fn fft_finds_a_sine() {
        let n = 64;
        let mut re: Vec<f64> = (0..n)
            .map(|i| (2.0 * std::f64::consts::PI * 5.0 * i as f64 / n as f64).cos())
            .collect();
        let mut im = vec![0.0; n];
        fft(&mut re, &mut im);
        assert!((re[5] - 32.0).abs() < 1e-9 && (re[59] - 32.0).abs() < 1e-9);
        assert!(re[6].abs() < 1e-9 && im[5].abs() < 1e-9);
    }

    #[test]
    fn a_bass_tone_that_swells_drives_the_bass_band_only() {
        // 80 Hz growing from silence over two seconds.
        let s = tone(80.0, 22050, 2.0, |t| t / 2.0);
        let bass = band_energy(
            &s,
            Band::BASS,
            10.0,
            20,
            Smoothing {
                attack: 1.0,
                release: 1.0,
            },
        );
        assert_eq!(bass.len(), 20);
        assert!(bass[2] < bass[10] && bass[10] < bass[18], "{bass:?}");
        let max = bass.iter().cloned().fold(0.0, f64::max);
        assert!((max - 1.0).abs() < 1e-12);
        // The tone's level in the highs is a leak of the window, far below its bass level; a
        // 5 kHz tone is the other way round.
        let (b, h) = (
            band_levels(&s, Band::BASS, 10.0, 20),
            band_levels(&s, Band::HIGH, 10.0, 20),
        );
        assert!(h[15] < 1e-3 * b[15], "{} {}", h[15], b[15]);
        let t = tone(5000.0, 22050, 2.0, |_| 1.0);
        let (b, h) = (
            band_levels(&t, Band::BASS, 10.0, 20),
            band_levels(&t, Band::HIGH, 10.0, 20),
        );
        assert!(b[10] < 1e-3 * h[10], "{} {}", b[10], h[10]);
        let silent = Sound {
            rate: 8000,
            samples: vec![0.0; 8000],
        };
        assert!(
            band_energy(&silent, Band::BASS, 25.0, 10, Smoothing::default())
                .iter()
                .all(|e| *e == 0.0)
        );
    }

    #[test]
    fn release_smooths_the_fall() {
        // A burst in the first half second, then silence.
        let s = tone(100.0, 8000, 2.0, |t| if t < 0.5 { 1.0 } else { 0.0 });
        let fast = band_energy(
            &s,
            Band::BASS,
            10.0,
            20,
            Smoothing {
                attack: 1.0,
                release: 1.0,
            },
        );
        let slow = band_energy(
            &s,
            Band::BASS,
            10.0,
            20,
            Smoothing {
                attack: 1.0,
                release: 0.3,
            },
        );
        assert!(fast[9] < 0.01, "{fast:?}");
        assert!(slow[9] > fast[9]);
        let c = curve_from_energy(&slow, Target::Flame(FlameParam::Brightness), 2.0, 6.0);
        assert_eq!(c.keys().len(), 20);
        assert!((c.eval(3.0, None).unwrap() - (2.0 + 4.0 * slow[3])).abs() < 1e-12);
    }
}
