//! `ugnis animate --sound`: a sound's loudness moves a flame, run as a user would.

mod common;

use std::process::Command;

use ugnis::flame::keyframes::Target;

fn ugnis(args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ugnis"))
        .args(args)
        .output()
        .expect("run ugnis");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// 0.3 s of 80 Hz swelling from silence (22.05 kHz, mono).
fn swelling_bass(path: &std::path::Path) {
    let rate = 22050;
    let n = rate * 3 / 10;
    let s: Vec<f32> = (0..n)
        .map(|i| {
            let t = i as f32 / rate as f32;
            0.9 * (t / 0.3) * (2.0 * std::f32::consts::PI * 80.0 * t).sin()
        })
        .collect();
    std::fs::write(path, ugnis::io::audio::wav_bytes(&s, rate as u32)).unwrap();
}

/// `ugnis animate` of the Sierpiński example at 10 fps, 32×24, driven by `wav`, into `out`.
fn animate_to_sound(wav: &std::path::Path, out: &std::path::Path, extra: &[&str]) -> (i32, String) {
    let ex = common::example("sierpinski.flame");
    let mut args = vec![
        "animate",
        ex.to_str().unwrap(),
        "--sound",
        wav.to_str().unwrap(),
        "--fps",
        "10",
        "--size",
        "32x24",
        "--quality",
        "2",
        "-o",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    ugnis(&args)
}

fn turn_of(a: &ugnis::flame::model::Affine) -> f64 {
    a.c.atan2(a.a).to_degrees()
}

#[test]
fn a_sound_turns_an_xform_and_its_curve_is_saved() {
    let dir = common::temp_dir("cli-sound");
    let _cleanup = common::Cleanup(dir.clone());
    let wav = dir.join("bass.wav");
    swelling_bass(&wav);
    let (frames, keys) = (dir.join("frames"), dir.join("keys.flame"));
    let (code, err) = animate_to_sound(
        &wav,
        &frames,
        &[
            "--sound-target",
            "xform 0 rotate",
            "--sound-range",
            "0..90",
            "--sound-smooth",
            "1,1",
            "--save-keys",
            keys.to_str().unwrap(),
        ],
    );
    assert_eq!(code, 0, "{err}");
    // 0.3 s at 10 fps: three frames, a key each, louder and louder, the last the loudest.
    let mut names: Vec<String> = std::fs::read_dir(&frames)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["00000.png", "00001.png", "00002.png"]);
    let saved = ugnis::io::read_flames(&keys, &Default::default())
        .unwrap()
        .value
        .remove(0);
    assert_eq!((saved.keys.frames, saved.keys.fps), (3, 10.0));
    let target: Target = "xform 0 rotate".parse().unwrap();
    let k = saved.keys.curve(&target).unwrap().keys();
    assert_eq!(k.len(), 3);
    assert!(k[0].value < k[1].value && k[1].value < k[2].value, "{k:?}");
    assert_eq!(k[2].value, 90.0);
    // The last frame's flame (embedded in its PNG) has xform 0 turned by 90°.
    let last = ugnis::io::read_flames(&frames.join("00002.png"), &Default::default())
        .unwrap()
        .value
        .remove(0);
    let turn = turn_of(&last.xforms[0].coefs) - turn_of(&saved.xforms[0].coefs);
    assert!(((turn + 360.0) % 360.0 - 90.0).abs() < 1e-6, "{turn}");
}

#[test]
fn the_sound_goes_into_the_video() {
    if Command::new("ffmpeg").arg("-version").output().is_err() {
        eprintln!("ffmpeg is not installed; the video part is not tested");
        return;
    }
    let dir = common::temp_dir("cli-sound-video");
    let _cleanup = common::Cleanup(dir.clone());
    let wav = dir.join("bass.wav");
    swelling_bass(&wav);
    let mp4 = dir.join("movie.mp4");
    let (code, err) = animate_to_sound(
        &wav,
        &mp4,
        &["--sound-target", "brightness", "--sound-range", "2..6"],
    );
    assert_eq!(code, 0, "{err}");
    let probe = Command::new("ffprobe")
        .args([
            "-v",
            "error",
            "-show_entries",
            "stream=codec_type",
            "-of",
            "csv=p=0",
        ])
        .arg(&mp4)
        .output()
        .unwrap();
    let streams = String::from_utf8_lossy(&probe.stdout);
    assert!(
        streams.contains("video") && streams.contains("audio"),
        "{streams}"
    );
}

#[test]
fn bad_sound_options_are_refused_clearly() {
    let dir = common::temp_dir("cli-sound-bad");
    let _cleanup = common::Cleanup(dir.clone());
    let wav = dir.join("bass.wav");
    swelling_bass(&wav);
    let junk = dir.join("junk.mp3");
    std::fs::write(&junk, b"not a sound").unwrap();
    let ex = common::example("sierpinski.flame");
    let out = dir.join("out");
    let (ex, wav, junk, out) = (
        ex.to_str().unwrap(),
        wav.to_str().unwrap(),
        junk.to_str().unwrap(),
        out.to_str().unwrap(),
    );
    let base = [
        "animate",
        ex,
        "-o",
        out,
        "--size",
        "16x12",
        "--quality",
        "1",
    ];
    for (extra, want) in [
        (
            vec![
                "--sound",
                junk,
                "--sound-target",
                "zoom",
                "--sound-range",
                "0..1",
            ],
            "junk.mp3",
        ),
        (
            vec![
                "--sound",
                wav,
                "--sound-target",
                "xform 9 rotate",
                "--sound-range",
                "0..1",
            ],
            "xform 9 rotate",
        ),
        (
            vec![
                "--sound",
                wav,
                "--sound-target",
                "wobble",
                "--sound-range",
                "0..1",
            ],
            "'wobble' is not a keyframe target",
        ),
        (
            vec![
                "--sound",
                wav,
                "--sound-target",
                "scale",
                "--sound-range",
                "0..9",
            ],
            "scale factor",
        ),
        (
            vec![
                "--sound",
                wav,
                "--sound-target",
                "zoom",
                "--sound-range",
                "0..1",
                "--mode",
                "rotate",
            ],
            "--mode keys",
        ),
        (vec!["--sound", wav], "--sound-target"),
        (
            vec![
                "--sound",
                wav,
                "--sound-target",
                "zoom",
                "--sound-range",
                "0..1",
                "--sound-band",
                "loud",
            ],
            "band 'loud'",
        ),
    ] {
        let args: Vec<&str> = base.iter().copied().chain(extra.iter().copied()).collect();
        let (code, err) = ugnis(&args);
        assert_ne!(code, 0, "{extra:?}");
        assert!(err.contains(want), "{extra:?}: {err}");
    }
}
