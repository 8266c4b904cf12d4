//! Signals stop a command at once in every phase, remove its temporary files, leave the old
//! outputs as they were and exit with 128 + the signal's number.

use super::*;

/// Start `args` with plain progress lines every moment, wait until a line of stderr contains
/// `wait_for`, send `signal` (by the shell's built-in kill: no procps needed) and return the
/// exit status, the rest of stderr and the time from the signal to the exit.
fn signal_when(args: &[&str], wait_for: &str, signal: &str) -> (Option<i32>, String, Duration) {
    let mut child = Command::new(bin())
        .args(args)
        .args(["--progress", "plain"])
        .env("UGNIS_PROGRESS_SECONDS", "0")
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut err = std::io::BufReader::new(child.stderr.take().unwrap());
    let mut seen = String::new();
    loop {
        let mut line = String::new();
        if err.read_line(&mut line).unwrap() == 0 {
            let status = child.wait().unwrap();
            panic!("ended ({status}) before '{wait_for}': {seen}");
        }
        seen.push_str(&line);
        if line.contains(wait_for) {
            break;
        }
    }
    let sent = Instant::now();
    let ok = Command::new("sh")
        .arg("-c")
        .arg(format!("kill -{signal} {}", child.id()))
        .status()
        .unwrap();
    assert!(ok.success());
    let mut rest = String::new();
    err.read_to_string(&mut rest).unwrap();
    let status = child.wait().unwrap();
    (status.code(), rest, sent.elapsed())
}

/// The files of `dir` with their contents.
fn snapshot(dir: &Path) -> Vec<(String, Vec<u8>)> {
    listing(dir)
        .into_iter()
        .map(|n| {
            let b = std::fs::read(dir.join(&n)).unwrap_or_default();
            (n, b)
        })
        .collect()
}

#[test]
fn term_hup_and_int_stop_the_iteration_at_once() {
    let dir = common::temp_dir("hard-sig-iter");
    let f = small_flame(&dir, "1");
    let out = dir.join("long.png");
    let state = dir.join("long.ugs");
    std::fs::write(&out, b"old picture").unwrap();
    std::fs::write(&state, b"old state").unwrap();
    let before = snapshot(&dir);
    for (signal, status) in [("TERM", 143), ("HUP", 129), ("INT", 130)] {
        let (code, err, took) = signal_when(
            &[
                "render",
                s(&f),
                "-o",
                s(&out),
                "--save-state",
                s(&state),
                "--size",
                "800x600",
                "--quality",
                "10000",
            ],
            "rendering",
            signal,
        );
        assert_eq!(code, Some(status), "SIG{signal}: {err}");
        assert!(
            err.contains(&format!("interrupted by SIG{signal}")),
            "{err}"
        );
        assert!(took < Duration::from_secs(5), "SIG{signal} took {took:?}");
        assert_eq!(snapshot(&dir), before, "SIG{signal} changed the directory");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_signal_after_the_samples_stops_density_estimation_and_the_save() {
    // Iteration is short, density estimation with a wide kernel and the encoding of a large
    // picture are long: the signal arrives after the last progress line.
    let dir = common::temp_dir("hard-sig-de");
    let f = dir.join("de.flame");
    std::fs::write(
        &f,
        "<flame name=\"de\" size=\"4000 3000\" scale=\"800\" quality=\"0.1\" \
         estimator_radius=\"11\" estimator_minimum=\"0\" estimator_curve=\"0.4\">\
         <xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>\
         <xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 1 0\"/>\
         <xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 1\"/></flame>",
    )
    .unwrap();
    let out = dir.join("de.png");
    std::fs::write(&out, b"old picture").unwrap();
    let before = snapshot(&dir);
    let (code, err, took) = signal_when(&["render", s(&f), "-o", s(&out)], "100%", "INT");
    assert_eq!(code, Some(130), "{err}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert_eq!(snapshot(&dir), before);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_signal_during_a_render_in_strips_removes_the_streamed_files() {
    // In strips the PNG and the state are written while the render goes on: their temporary
    // files exist from the start.
    let dir = common::temp_dir("hard-sig-strips");
    let f = small_flame(&dir, "1");
    let out = dir.join("poster.png");
    let state = dir.join("poster.ugs");
    std::fs::write(&out, b"old picture").unwrap();
    let before = snapshot(&dir);
    let (code, err, _) = signal_when(
        &[
            "render",
            s(&f),
            "-o",
            s(&out),
            "--save-state",
            s(&state),
            "--size",
            "400x300",
            "--quality",
            "3000",
            "--strips",
            "3",
        ],
        "rendering",
        "TERM",
    );
    assert_eq!(code, Some(143), "{err}");
    assert_eq!(snapshot(&dir), before);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_signal_while_ffmpeg_encodes_leaves_whole_frames_and_no_video() {
    if Command::new("ffmpeg").arg("-version").output().is_err() {
        println!("skipping: ffmpeg is not installed");
        return;
    }
    let dir = common::temp_dir("hard-sig-video");
    let f = small_flame(&dir, "20");
    let video = dir.join("v.mp4");
    let (code, err, _) = signal_when(
        &[
            "animate",
            s(&f),
            "--frames",
            "400",
            "--size",
            "64x48",
            "-o",
            s(&video),
        ],
        "animating: ",
        "TERM",
    );
    assert_eq!(code, Some(143), "{err}");
    // ffmpeg was stopped with ugnis: nothing appears afterwards.
    std::thread::sleep(Duration::from_millis(500));
    assert_eq!(listing(&dir), ["q.flame", "v.mp4.frames"]);
    for name in listing(&dir.join("v.mp4.frames")) {
        assert!(name.ends_with(".png"), "{name}");
        assert!(image::open(dir.join("v.mp4.frames").join(&name)).is_ok());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// An animation of millions of frames says, after its first frame, how long it will take (and
/// that stopping keeps the frames written); the most frames a command accepts is said too.
#[test]
fn a_huge_animation_says_how_long_it_will_take() {
    let dir = common::temp_dir("hard-anim-long");
    let f = small_flame(&dir, "1");
    let frames = dir.join("frames");
    let (code, err, _) = signal_when(
        &[
            "animate",
            s(&f),
            "--frames",
            "10000000",
            "--size",
            "32x24",
            "-o",
            s(&frames),
        ],
        "will take about",
        "TERM",
    );
    assert_eq!(code, Some(143), "{err}");
    let (code, _, err) = ugnis(&["animate", s(&f), "--frames", "10000001", "-o", s(&frames)]);
    assert_clean_error(code, &err, &["10000001 frames", "between 1 and 10000000"]);
    std::fs::remove_dir_all(&dir).unwrap();
}
