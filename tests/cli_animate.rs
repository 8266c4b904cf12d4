//! `ugnis animate` run as a user runs it: sequences named by time, resume, videos, export as a
//! flam3 sequence, and bad input (times out of order, too many frames, a full disk mid-way).

mod common;

use std::path::Path;
use std::process::Command;

use ugnis::flame::Flame;
use ugnis::flame::keyframes::{Key, Target};

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

fn seq() -> String {
    common::fixture("animation/seq.flam3")
        .to_string_lossy()
        .into_owned()
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn read(path: &Path) -> Vec<Flame> {
    ugnis::io::read_flames(path, &Default::default())
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .value
}

#[test]
fn a_sequence_renders_the_times_asked_for_and_a_rerun_skips_them() {
    let dir = common::temp_dir("cli-anim-seq");
    let out = dir.join("frames");
    let o = out.to_str().unwrap();
    let args = [
        "animate",
        &seq(),
        "--frames",
        "3..4",
        "-o",
        o,
        "--size",
        "32x24",
        "--quality",
        "2",
    ];
    let (code, err) = ugnis(&args);
    assert_eq!(code, 0, "{err}");
    assert_eq!(names(&out), ["00003.png", "00004.png"]);
    let (w, h) = image::image_dimensions(out.join("00003.png")).unwrap();
    assert_eq!((w, h), (32, 24));
    let before = std::fs::metadata(out.join("00003.png"))
        .unwrap()
        .modified()
        .unwrap();
    let (code, err) = ugnis(&args);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("2 frames were already on disk"), "{err}");
    let after = std::fs::metadata(out.join("00003.png"))
        .unwrap()
        .modified()
        .unwrap();
    assert_eq!(before, after);
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_gif_is_made_without_other_tools_and_keeps_its_frames() {
    let dir = common::temp_dir("cli-anim-gif");
    let gif = dir.join("loop.gif");
    let (code, err) = ugnis(&[
        "animate",
        &seq(),
        "--frames",
        "2..4",
        "-o",
        gif.to_str().unwrap(),
        "--size",
        "24x18",
        "--quality",
        "2",
        "--no-blur",
    ]);
    assert_eq!(code, 0, "{err}");
    let frames = image::codecs::gif::GifDecoder::new(std::io::BufReader::new(
        std::fs::File::open(&gif).unwrap(),
    ))
    .unwrap();
    use image::AnimationDecoder;
    assert_eq!(frames.into_frames().count(), 3);
    assert_eq!(names(&dir.join("loop.gif.frames")).len(), 3);
    let _ = std::fs::remove_dir_all(dir);
}

/// A flame whose zoom is keyed 0 → 1 over frames 0..4.
fn keyed_flame(dir: &Path) -> std::path::PathBuf {
    let mut f = read(&common::example("sierpinski.flame")).remove(0);
    f.keys.frames = 5;
    let zoom: Target = "zoom".parse().unwrap();
    zoom_curve(&mut f, &zoom);
    let path = dir.join("keyed.flame");
    ugnis::io::write_flames(&path, "keyed", &[f]).unwrap();
    path
}

fn zoom_curve(f: &mut Flame, zoom: &Target) {
    let c = f.keys.curve_mut(*zoom);
    c.insert(Key::new(0.0, 0.0)).unwrap();
    c.insert(Key::new(4.0, 1.0)).unwrap();
}

#[test]
fn keyframes_export_as_a_flam3_sequence_of_one_flame_per_frame() {
    let dir = common::temp_dir("cli-anim-export");
    let keyed = keyed_flame(&dir);
    let out = dir.join("seq.flam3");
    let (code, err) = ugnis(&[
        "animate",
        keyed.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--size",
        "40x30",
    ]);
    assert_eq!(code, 0, "{err}");
    let flames = read(&out);
    let base = read(&keyed).remove(0);
    assert_eq!(flames.len(), 5);
    for (k, f) in flames.iter().enumerate() {
        assert_eq!(f.anim.time, k as f64);
        assert!(f.keys.is_empty(), "exported flames carry no ugnis keys");
        assert_eq!((f.width, f.height), (40, 30));
        let want = base.keys.apply(&base, k as f64).zoom;
        assert!(
            (f.zoom - want).abs() < 1e-9,
            "frame {k}: {} vs {want}",
            f.zoom
        );
    }
    assert!((flames[4].zoom - 1.0).abs() < 1e-9);
    // flam3 reads it as a sequence (when installed).
    if let Ok(o) = Command::new("flam3-genome").env("clone_all", &out).output() {
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let text = String::from_utf8_lossy(&o.stdout);
        assert_eq!(text.matches("<flame ").count(), 5);
    }
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn bad_animations_are_refused_with_a_reason() {
    let dir = common::temp_dir("cli-anim-bad");
    // Times out of order.
    let text = std::fs::read_to_string(common::fixture("animation/seq.flam3")).unwrap();
    let swapped = text.replacen("time=\"1\"", "time=\"9\"", 1);
    let bad = dir.join("bad.flam3");
    std::fs::write(&bad, swapped).unwrap();
    let o = dir.join("o");
    let (code, err) = ugnis(&["animate", bad.to_str().unwrap(), "-o", o.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.contains("times of a sequence must be numbers"), "{err}");
    // A billion frames.
    let (code, err) = ugnis(&[
        "animate",
        &seq(),
        "--frames",
        "0..1000000000",
        "-o",
        o.to_str().unwrap(),
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("at most"), "{err}");
    // No temporal samples.
    let (code, err) = ugnis(&[
        "animate",
        &seq(),
        "--temporal-samples",
        "0",
        "-o",
        o.to_str().unwrap(),
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("--temporal-samples"), "{err}");
    let _ = std::fs::remove_dir_all(dir);
}

/// A disk that fills up in the middle of a sequence (a file-size limit smaller than a frame
/// makes writes fail with EFBIG, as a full disk makes them fail with ENOSPC): the command fails
/// with a message, the frames written before stay whole, nothing half-written is left, and the
/// same command afterwards renders only the rest.
#[test]
fn a_full_disk_mid_sequence_keeps_whole_frames_and_a_rerun_finishes() {
    let dir = common::temp_dir("cli-anim-full");
    let out = dir.join("frames");
    let args = |range: &str| {
        format!(
            "animate '{}' --frames {range} -o '{}' --size 160x120 --quality 1 --no-blur",
            seq(),
            out.display()
        )
    };
    let bin = env!("CARGO_BIN_EXE_ugnis");
    let sh = |script: String| Command::new("sh").arg("-c").arg(script).output().unwrap();
    // Frames 1 to 3 fit; then the disk is "full" (no file over 8 KiB) while 4 to 6 are made.
    let first = sh(format!("exec '{bin}' {}", args("1..3")));
    assert!(first.status.success());
    let full = sh(format!(
        "ulimit -f 16; trap '' XFSZ; exec '{bin}' {}",
        args("1..6")
    ));
    let err = String::from_utf8_lossy(&full.stderr);
    assert!(!full.status.success(), "the limit should have stopped it");
    assert!(err.contains("File too large"), "{err}");
    let written = names(&out);
    assert_eq!(written, ["00001.png", "00002.png", "00003.png"], "{err}");
    for p in &written {
        image::open(out.join(p)).unwrap_or_else(|e| panic!("{p} is not whole: {e}"));
    }
    let last = sh(format!("exec '{bin}' {}", args("1..6")));
    let err = String::from_utf8_lossy(&last.stderr);
    assert!(last.status.success(), "{err}");
    assert!(err.contains("3 frames were already on disk"), "{err}");
    assert_eq!(names(&out).len(), 6);
    let _ = std::fs::remove_dir_all(dir);
}

/// `--mode loop` through two flames: a loop of each and the transitions there and back, so the
/// frame after the last is the first.
#[test]
fn a_loop_through_two_flames_comes_back_to_the_first() {
    let dir = common::temp_dir("cli-anim-loop");
    let out = dir.join("loop.flam3");
    let pair = common::fixture("animation/pair.flam3");
    let (code, err) = ugnis(&[
        "animate",
        pair.to_str().unwrap(),
        "--mode",
        "loop",
        "--loop-frames",
        "3",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let frames = read(&out);
    let keys = read(&pair);
    // Loop A (0–2), A → B (3–5), loop B (6–8), B → A (9–11); frame 12 would be frame 0.
    assert_eq!(frames.len(), 12);
    let coefs =
        |f: &Flame| -> Vec<[f64; 6]> { f.xforms.iter().map(|x| x.coefs.to_coefs()).collect() };
    let close = |a: &Flame, b: &Flame| {
        coefs(a)
            .iter()
            .zip(coefs(b))
            .all(|(p, q)| p.iter().zip(q).all(|(x, y)| (x - y).abs() < 1e-6))
    };
    assert!(close(&frames[0], &keys[0]));
    assert!(close(&frames[6], &keys[1]));
    assert!(
        !close(&frames[11], &keys[0]),
        "the last frame is one step before the first"
    );
    let _ = std::fs::remove_dir_all(dir);
}
