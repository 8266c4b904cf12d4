//! `ugnis animate --sound`: sound-driven motion. The loudness of a frequency band of a sound
//! file, frame by frame, becomes a keyframe curve of the flame (linear between keys, one key
//! per frame), which the animation then plays; the curve can be saved with the flame
//! (`--save-keys`) to edit it in the editor.

use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use clap::Args;

use ugnis::flame::Flame;
use ugnis::flame::keyframes::Target;
use ugnis::io::audio::read_sound;
use ugnis::sound::{Band, Drive, Smoothing, drive_flame};

#[derive(Args, Debug)]
pub struct SoundArgs {
    /// Sound-driven motion: a WAV, FLAC or MP3 file whose loudness in --sound-band moves
    /// --sound-target over --sound-range. It also goes into the video (unless --no-audio or
    /// --audio names another)
    #[arg(long, requires_all = ["sound_target", "sound_range"])]
    pub sound: Option<PathBuf>,
    /// The frequency band: bass (20–150 Hz), middle (150–2000 Hz), high (2–16 kHz) or LOW-HIGHhz
    /// (e.g. 60-250hz)
    #[arg(long, default_value = "bass", value_parser = parse_band)]
    pub sound_band: Band,
    /// What the sound moves, named as keyframe targets are: "xform 0 rotate", "zoom",
    /// "brightness", "xform 1 var julian weight", "palette hue" …
    #[arg(long, requires = "sound")]
    pub sound_target: Option<String>,
    /// The target's value at silence and at the loudest frame: LOW..HIGH (e.g. 0..90)
    #[arg(long, requires = "sound", value_parser = parse_range)]
    pub sound_range: Option<(f64, f64)>,
    /// How fast the motion follows the sound, ATTACK,RELEASE: the part of the way to a louder
    /// (a quieter) level taken in one frame, from 0 (never) to 1 (at once)
    #[arg(long, requires = "sound", default_value = "1,0.3", value_parser = parse_smooth)]
    pub sound_smooth: Smoothing,
    /// Save the flame with the curve made from the sound (to open and edit it in the editor)
    #[arg(long, requires = "sound")]
    pub save_keys: Option<PathBuf>,
    /// Do not put the sound of --sound into the video
    #[arg(long, requires = "sound")]
    pub no_audio: bool,
}

fn parse_band(s: &str) -> Result<Band, String> {
    match s.to_ascii_lowercase().as_str() {
        "bass" => return Ok(Band::BASS),
        "middle" | "mid" => return Ok(Band::MIDDLE),
        "high" | "highs" | "treble" => return Ok(Band::HIGH),
        _ => {}
    }
    let bad = || format!("band '{s}' must be bass, middle, high or LOW-HIGHhz (e.g. 60-250hz)");
    let t = s.to_ascii_lowercase();
    let (lo, hi) = t
        .strip_suffix("hz")
        .and_then(|r| r.split_once('-'))
        .ok_or_else(bad)?;
    let num = |v: &str| v.trim().parse::<f64>().ok().filter(|v| v.is_finite());
    let (low, high) = (num(lo).ok_or_else(bad)?, num(hi).ok_or_else(bad)?);
    if !(0.0 <= low && low < high && high <= 400_000.0) {
        return Err(format!(
            "band {s}: LOW must be below HIGH, both from 0 to 400000 Hz"
        ));
    }
    Ok(Band { low, high })
}

fn parse_range(s: &str) -> Result<(f64, f64), String> {
    let (a, b) = s
        .split_once("..")
        .ok_or_else(|| format!("range '{s}' must be LOW..HIGH (e.g. 0..90)"))?;
    let num = |v: &str| {
        v.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("range '{s}': '{v}' is not a number"))
    };
    Ok((num(a)?, num(b)?))
}

fn parse_smooth(s: &str) -> Result<Smoothing, String> {
    let bad =
        || format!("smoothing '{s}' must be ATTACK,RELEASE with both from 0 to 1 (e.g. 1,0.3)");
    let (a, r) = s.split_once(',').ok_or_else(bad)?;
    let num = |v: &str| {
        v.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| (0.0..=1.0).contains(v))
    };
    Ok(Smoothing {
        attack: num(a).ok_or_else(bad)?,
        release: num(r).ok_or_else(bad)?,
    })
}

/// Give `flame` the curve the sound makes (its timeline the sound's length at `fps`, or the
/// flame's frame rate, when it has no keyframes yet), and save it if asked.
pub fn drive(s: &SoundArgs, flame: &mut Flame, fps: Option<f64>, input: &Path) -> Result<()> {
    let Some(path) = &s.sound else {
        return Ok(());
    };
    let (Some(name), Some((low, high))) = (&s.sound_target, s.sound_range) else {
        bail!("--sound needs --sound-target and --sound-range");
    };
    let target: Target = name
        .parse()
        .map_err(|e| anyhow::anyhow!("--sound-target: {e}"))?;
    let sound = read_sound(path)?;
    if let Some(fps) = fps {
        flame.keys.fps = fps;
    }
    let d = Drive {
        target,
        band: s.sound_band,
        low,
        high,
        smooth: s.sound_smooth,
    };
    let replaced = drive_flame(flame, &sound, &d)
        .map_err(|e| anyhow::anyhow!("--sound {}: {e} ({})", path.display(), input.display()))?;
    if replaced {
        stderr!("'{target}' had keyframes; the sound's curve replaces them");
    }
    if let Some(out) = &s.save_keys {
        super::check_outputs(&[input, path.as_path()], &[out.as_path()])?;
        let name = flame.name.clone();
        ugnis::io::write_flames(out, &name, std::slice::from_ref(flame))
            .map_err(|e| anyhow::anyhow!("'{}': {e}", out.display()))?;
        stderr!(
            "saved the flame with the sound's curve ({} keys) to '{}'",
            flame.keys.frames,
            out.display()
        );
    }
    Ok(())
}

/// The sound to put into the video: --audio, else --sound (unless --no-audio).
pub fn audio(s: &SoundArgs, audio: &Option<PathBuf>) -> Option<PathBuf> {
    audio
        .clone()
        .or_else(|| s.sound.clone().filter(|_| !s.no_audio))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_ranges_and_smoothing_parse() {
        assert_eq!(parse_band("BASS"), Ok(Band::BASS));
        assert_eq!(
            parse_band("60-250hz"),
            Ok(Band {
                low: 60.0,
                high: 250.0
            })
        );
        for bad in ["250-60hz", "60-250", "x-9hz", "loud"] {
            assert!(parse_band(bad).is_err(), "{bad}");
        }
        assert_eq!(parse_range("-1.5..90"), Ok((-1.5, 90.0)));
        assert!(parse_range("1-2").is_err());
        assert_eq!(
            parse_smooth("1,0.5"),
            Ok(Smoothing {
                attack: 1.0,
                release: 0.5
            })
        );
        assert!(parse_smooth("2,0.5").is_err() && parse_smooth("1").is_err());
    }
}
