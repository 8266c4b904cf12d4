//! Animation against flam3, the reference: flam3-genome's sequences, flam3-animate's in-between
//! genomes and flam3-animate's motion-blurred frames (fixtures made by
//! tests/fixtures/animation/make.py; flam3 itself is only needed by the live test at the end).
//!
//! Tolerance for frames: flam3-animate at quality 200 with another seed was measured against
//! its own quality-1000 frame (the flam3 column below); ugnis at quality 200 must come within
//! 1.5 dB of it. Sequence frames rendered without interpreting `time` measured 10–14 dB here, a
//! frame without motion blur about 25 dB.

mod common;

use std::path::Path;

use ugnis::flame::interpolate::interpolate_at;
use ugnis::flame::loops;
use ugnis::flame::model::{Flame, Xform};
use ugnis::flame::render::{RenderOptions, Renderer};
use ugnis::io::animation::{Cursor, Source};
use ugnis::io::flam3_xml::ReadOptions;

fn fixture(name: &str) -> std::path::PathBuf {
    common::fixture(&format!("animation/{name}"))
}

fn read(path: &Path) -> Vec<Flame> {
    ugnis::io::read_flames(path, &ReadOptions::default())
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .value
}

/// Renders `source` at `time` with motion blur at quality 200 and compares it with
/// flam3-animate's quality-1000 frame `golden`.
fn frame_psnr(source: &Source, time: f64, golden: &str) -> f64 {
    let frame = source.frame(time, true, &|_| {}, &mut Cursor::default());
    assert!(!frame.is_still(), "{golden}: the frame should be blurred");
    let opts = RenderOptions {
        seed: 7,
        threads: 2,
        ..RenderOptions::default()
    };
    let mut r = Renderer::motion(&frame, &opts).unwrap();
    r.run_all(10, &Default::default(), |_| {});
    let img = r.finish().to_rgb8();
    common::psnr_blurred(&img, &common::load_rgb(&fixture(golden)))
}

fn check_frames(file: &str, frames: &[(f64, &str, f64)]) {
    let source = Source::Sequence(read(&fixture(file)));
    let mut report = Vec::new();
    let mut worst = f64::INFINITY;
    for &(time, golden, flam3_self) in frames {
        let p = frame_psnr(&source, time, golden);
        report.push(format!(
            "{golden}: {p:.2} dB (flam3 q200: {flam3_self:.2} dB)"
        ));
        worst = worst.min(p - (flam3_self - 1.5));
    }
    eprintln!("{}", report.join("\n"));
    assert!(
        worst >= 0.0,
        "a frame is more than 1.5 dB below flam3's own noise:\n{}",
        report.join("\n")
    );
}

/// flam3-genome's sequence of two flames: frame 3 turns the first flame, frame 14 is in the
/// transition to the second (both motion blurred over 1000 temporal samples).
#[test]
fn sequence_frames_match_flam3_animate() {
    check_frames(
        "seq.flam3",
        &[
            (3.0, "seq-00003.png", 33.94),
            (14.0, "seq-00014.png", 38.73),
        ],
    );
}

/// Four keyed flames (2, 6, 5 and 8 xforms), smooth interpolation, rgb/sweep/hsv_circular
/// palettes and gaussian/box/exp temporal filters.
#[test]
fn keyframe_frames_match_flam3_animate() {
    check_frames(
        "keys.flam3",
        &[
            (5.0, "keys-00005.png", 35.54),
            (13.0, "keys-00013.png", 35.50),
            (24.0, "keys-00024.png", 37.02),
        ],
    );
}

thread_local! {
    /// The differences found by `close`, reported together.
    static DIFFS: std::cell::RefCell<Vec<String>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// Relative closeness at the 6 significant digits flam3 prints.
fn close(a: f64, b: f64, what: &str) {
    let tol = 2e-5 * a.abs().max(b.abs()).max(1e-2);
    if (a - b).abs() > tol || a.is_nan() != b.is_nan() {
        DIFFS.with(|d| {
            d.borrow_mut()
                .push(format!("{what}: ugnis {a} vs flam3 {b}"))
        });
    }
}

/// Fails with the differences `close` found.
fn assert_no_diffs() {
    let diffs = DIFFS.with(|d| std::mem::take(&mut *d.borrow_mut()));
    assert!(
        diffs.is_empty(),
        "{} differences:\n{}",
        diffs.len(),
        diffs
            .iter()
            .take(40)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
}

fn check_xform(u: &Xform, f: &Xform, what: &str) {
    close(u.weight, f.weight, &format!("{what} weight"));
    close(u.color, f.color, &format!("{what} color"));
    for (k, (a, b)) in [
        (u.coefs.a, f.coefs.a),
        (u.coefs.b, f.coefs.b),
        (u.coefs.c, f.coefs.c),
        (u.coefs.d, f.coefs.d),
        (u.coefs.e, f.coefs.e),
        (u.coefs.f, f.coefs.f),
    ]
    .into_iter()
    .enumerate()
    {
        close(a, b, &format!("{what} coefficient {k}"));
    }
    for v in &f.vars {
        let mine = u.vars.iter().find(|w| w.id == v.id && w.form == v.form);
        let mine = mine.unwrap_or_else(|| panic!("{what}: variation {:?} missing", v.id));
        close(
            mine.weight,
            v.weight,
            &format!("{what} variation {:?}", v.id),
        );
        for (i, (a, b)) in mine.params.iter().zip(&v.params).enumerate() {
            close(
                *a,
                *b,
                &format!("{what} variation {:?} parameter {i}", v.id),
            );
        }
    }
    for v in &u.vars {
        assert!(
            v.weight == 0.0 || f.vars.iter().any(|w| w.id == v.id),
            "{what}: ugnis has variation {:?} that flam3 has not",
            v.id
        );
    }
}

fn check_flame(u: &Flame, f: &Flame, what: &str) {
    close(u.center[0], f.center[0], &format!("{what} centre x"));
    close(u.center[1], f.center[1], &format!("{what} centre y"));
    close(u.scale, f.scale, &format!("{what} scale"));
    close(u.rotate, f.rotate, &format!("{what} rotate"));
    close(u.brightness, f.brightness, &format!("{what} brightness"));
    close(u.gamma, f.gamma, &format!("{what} gamma"));
    close(
        u.anim.temporal_filter_width,
        f.anim.temporal_filter_width,
        &format!("{what} temporal filter width"),
    );
    let (ux, fx) = (&u.xforms, &f.xforms);
    assert_eq!(ux.len(), fx.len(), "{what}: xform count");
    for (i, (a, b)) in ux.iter().zip(fx).enumerate() {
        check_xform(a, b, &format!("{what} xform {i}"));
    }
    // flam3 writes palette entries as bytes.
    for (i, (a, b)) in u.palette.colors.iter().zip(&f.palette.colors).enumerate() {
        for c in 0..3 {
            assert!(
                (a[c] * 255.0 - b[c] * 255.0).abs() <= 1.0,
                "{what}: palette entry {i} channel {c}: ugnis {} vs flam3 {}",
                a[c] * 255.0,
                b[c] * 255.0
            );
        }
    }
}

/// flam3-animate's in-between genomes (write_genome=1) of the keyed flames: smooth
/// interpolation, padding of unequal xform counts, log-polar coefficients, palette modes.
#[test]
fn in_betweens_match_flam3_animate_genomes() {
    let cps = read(&fixture("keys.flam3"));
    let genomes = read(&fixture("keys-genomes.flam3"));
    assert_eq!(genomes.len(), 3);
    for g in &genomes {
        let t = g.anim.time;
        check_flame(&interpolate_at(&cps, t), g, &format!("time {t}"));
    }
    assert_no_diffs();
}

/// `flam3-genome sequence=` of the pair (its output, trimmed to the times kept): ugnis's
/// sequence holds the same flames at the same times.
#[test]
fn sequence_matches_flam3_genome() {
    let pair = read(&fixture("pair.flam3"));
    let theirs = read(&fixture("seq.flam3"));
    let ours = loops::sequence(&pair, 10, true, 1.0);
    for f in &theirs {
        let t = f.anim.time;
        let mine = ours
            .iter()
            .find(|u| u.anim.time == t)
            .unwrap_or_else(|| panic!("ugnis's sequence has no flame at time {t}"));
        check_flame(mine, f, &format!("sequence time {t}"));
    }
    assert_no_diffs();
}

/// The same against flam3-genome itself, run now, with another frame count (only where
/// flam3-utils is installed; CI installs it, and there the test insists on it).
#[test]
fn sequence_matches_flam3_genome_run_live() {
    let run = std::process::Command::new("flam3-genome")
        .env("sequence", fixture("pair.flam3"))
        .env("nframes", "4")
        .output();
    let out = match run {
        Ok(out) if out.status.success() => out.stdout,
        _ if std::env::var_os("CI").is_some() => panic!("flam3-genome is not installed"),
        _ => {
            eprintln!("flam3-genome not found; skipped");
            return;
        }
    };
    let dir = common::temp_dir("anim-live");
    let path = dir.join("seq.flam3");
    std::fs::write(&path, out).unwrap();
    let theirs = read(&path);
    let ours = loops::sequence(&read(&fixture("pair.flam3")), 4, true, 1.0);
    assert_eq!(ours.len(), theirs.len(), "number of flames");
    for (u, f) in ours.iter().zip(&theirs) {
        assert_eq!(u.anim.time, f.anim.time);
        check_flame(u, f, &format!("live sequence time {}", f.anim.time));
    }
    assert_no_diffs();
    let _ = std::fs::remove_dir_all(dir);
}
