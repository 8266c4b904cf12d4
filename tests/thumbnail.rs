//! `ugnis thumbnail`, run as a file manager runs it: a small picture of every kind of file it
//! is registered for, quickly, and a clear error (never a panic) for anything else.

mod common;

use std::process::Command;
use std::time::{Duration, Instant};

fn thumbnail(
    input: &std::path::Path,
    out: &std::path::Path,
    size: &str,
) -> (i32, String, Duration) {
    let t = Instant::now();
    let o = Command::new(env!("CARGO_BIN_EXE_ugnis"))
        .args(["thumbnail"])
        .arg(input)
        .arg(out)
        .arg(size)
        .output()
        .expect("run ugnis");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stderr).into_owned(),
        t.elapsed(),
    )
}

#[test]
fn every_registered_kind_gets_a_picture_of_the_asked_size() {
    let dir = common::temp_dir("thumbnail-kinds");
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    // (file, its thumbnail's size when known: at the file's aspect)
    for (file, size) in [
        ("examples/orchid.flame", Some((128, 96))),
        ("examples/gallery.fla", None),
        ("tests/fixtures/library.ifs", None),
        ("tests/fixtures/hand.ugr", Some((128, 64))),
        ("examples/seahorse.esc", Some((128, 96))),
    ] {
        let out = dir.join("t.png");
        let _ = std::fs::remove_file(&out);
        let (code, err, took) = thumbnail(&root.join(file), &out, "128");
        assert_eq!(code, 0, "{file}: {err}");
        assert!(err.is_empty(), "{file}: {err}");
        let img = image::open(&out).unwrap().to_rgb8();
        let (w, h) = (img.width(), img.height());
        assert_eq!(w.max(h), 128, "{file}");
        if let Some(want) = size {
            assert_eq!((w, h), want, "{file}");
        }
        // A picture, not an empty frame.
        let lit = img.pixels().filter(|p| p.0.iter().any(|&c| c > 24)).count();
        assert!(lit * 20 > (w * h) as usize, "{file}: {lit} lit pixels");
        // Bounded time even in a debug build on a busy test machine.
        assert!(took < Duration::from_secs(10), "{file}: {took:?}");
    }
}

#[test]
fn anything_else_is_an_error_message_never_a_panic() {
    let dir = common::temp_dir("thumbnail-bad");
    let out = dir.join("t.png");
    let garbage = dir.join("garbage.flame");
    std::fs::write(&garbage, [0u8, 159, 146, 150, 255, 0, 60, 102, 108]).unwrap();
    let empty = dir.join("empty.fla");
    std::fs::write(&empty, "").unwrap();
    let broken = dir.join("broken.flame");
    std::fs::write(
        &broken,
        "<flames><flame size=\"-3 x\" quality=\"nan\"><xform",
    )
    .unwrap();
    let huge = dir.join("huge.flame");
    std::fs::File::create(&huge)
        .unwrap()
        .set_len(40 << 20)
        .unwrap();
    let scene = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/jug.toml");
    for (input, size, want) in [
        (garbage.as_path(), "64", "garbage.flame"),
        (empty.as_path(), "64", "empty.fla"),
        (broken.as_path(), "64", "broken.flame"),
        (huge.as_path(), "64", "32 MB"),
        (dir.join("missing.flame").as_path(), "64", "missing.flame"),
        (dir.as_path(), "64", ""),
        (scene.as_path(), "64", "thumbnails are made of"),
        (broken.as_path(), "0", "between 1 and 1024"),
        (broken.as_path(), "5000", "between 1 and 1024"),
    ] {
        let (code, err, _) = thumbnail(input, &out, size);
        assert_eq!(code, 1, "{input:?} {size}: {err}");
        assert!(!err.contains("panicked"), "{err}");
        assert!(err.contains(want), "{input:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "one message: {err}");
    }
    assert!(!out.exists(), "nothing written for a failure");
}
