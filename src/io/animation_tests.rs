//! Tests of animation jobs: frame names, checks, resuming and videos.

use super::*;
use crate::flame::model::{Affine, Xform};

fn cp(time: f64, turn: f64) -> Flame {
    let (s, c) = turn.sin_cos();
    let mut f = Flame {
        width: 32,
        height: 24,
        quality: 5.0,
        scale: 12.0,
        xforms: vec![
            Xform::linear(
                Affine::new(0.5 * c, -0.5 * s, 0.5 * s, 0.5 * c, 0.5, 0.0),
                1.0,
                0.0,
            ),
            Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, -0.5, 0.3), 1.0, 1.0),
        ],
        ..Flame::default()
    };
    f.anim.time = time;
    f.anim.temporal_samples = 4;
    f
}

fn scratch(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ugnis-anim-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn job(dir: &Path) -> Job {
    let source = Source::Sequence(vec![cp(0.0, 0.0), cp(4.0, 1.0)]);
    let (a, b) = source.default_range();
    Job {
        frames: frames_by_time(a, b, 1.0, "").unwrap(),
        source,
        dir: dir.to_path_buf(),
        video: None,
        render: RenderOptions {
            threads: 2,
            ..RenderOptions::default()
        },
        size: None,
        quality: None,
        blur: true,
    }
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn frames_are_named_by_their_time_as_flam3_animate_names_them() {
    let f = frames_by_time(3.0, 5.0, 1.0, "seq-").unwrap();
    let n: Vec<&str> = f.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(n, ["seq-00003.png", "seq-00004.png", "seq-00005.png"]);
    assert_eq!(
        frames_by_time(0.0, 1.0, 0.5, "").unwrap()[1].name,
        "0.5.png"
    );
    assert!(frames_by_time(5.0, 3.0, 1.0, "").is_err());
    assert!(frames_by_time(0.0, 1e12, 1.0, "").is_err());
    assert!(frames_by_time(0.0, 3.0, 0.0, "").is_err());
    assert!(frames_by_time(f64::NAN, 3.0, 1.0, "").is_err());
    // flam3-animate's default range: from the first time to one before the last.
    let s = Source::Sequence(vec![cp(2.0, 0.0), cp(9.0, 0.0)]);
    assert_eq!(s.default_range(), (2.0, 8.0));
}

#[test]
fn times_out_of_order_are_refused_with_the_flame_named() {
    let s = Source::Sequence(vec![cp(0.0, 0.0), cp(5.0, 0.0), cp(5.0, 0.0)]);
    let e = s.check().unwrap_err().to_string();
    assert!(e.contains("flame 3") && e.contains("increase"), "{e}");
    assert!(Source::Sequence(vec![cp(f64::NAN, 0.0)]).check().is_err());
}

#[test]
fn a_rerun_skips_the_frames_on_disk() {
    let d = scratch("resume");
    let j = job(&d);
    let never = AtomicBool::new(false);
    let s = j.run(&never, |_| {}).unwrap();
    assert_eq!((s.rendered, s.skipped), (4, 0));
    assert_eq!(
        names(&d),
        ["00000.png", "00001.png", "00002.png", "00003.png"]
    );
    let before = std::fs::read(d.join("00002.png")).unwrap();
    std::fs::remove_file(d.join("00002.png")).unwrap();
    let s = j.run(&never, |_| {}).unwrap();
    assert_eq!((s.rendered, s.skipped), (1, 3));
    // The same seed renders the same frame.
    assert_eq!(std::fs::read(d.join("00002.png")).unwrap(), before);
}

#[test]
fn a_truncated_or_damaged_frame_is_rendered_again_with_a_note() {
    let d = scratch("truncated");
    let j = job(&d);
    let never = AtomicBool::new(false);
    j.run(&never, |_| {}).unwrap();
    let whole = std::fs::read(d.join("00001.png")).unwrap();
    // Cut short before its end chunk (as a full disk or a crash leaves it), and one with a
    // flipped byte in its image data (a checksum wrong).
    std::fs::write(d.join("00001.png"), &whole[..whole.len() - 20]).unwrap();
    let mut flipped = std::fs::read(d.join("00003.png")).unwrap();
    let k = flipped.len() - 30;
    flipped[k] ^= 0x55;
    std::fs::write(d.join("00003.png"), &flipped).unwrap();
    let s = j.run(&never, |_| {}).unwrap();
    assert_eq!((s.rendered, s.skipped), (2, 2));
    assert_eq!(s.damaged, [d.join("00001.png"), d.join("00003.png")]);
    assert!(s.notes()[0].contains("00001.png") && s.notes()[0].contains("rendered again"));
    assert_eq!(std::fs::read(d.join("00001.png")).unwrap(), whole);
    // Whole again: the next run keeps all four without a note.
    let s = j.run(&never, |_| {}).unwrap();
    assert_eq!((s.rendered, s.skipped, s.damaged.len()), (0, 4, 0));
}

#[test]
fn gif_frames_of_a_transparent_render_lie_on_the_background_and_apng_keeps_alpha() {
    let d = scratch("transparent");
    let bg = [0.2, 0.5, 0.9];
    let mut j = job(&d.join("frames"));
    if let Source::Sequence(cps) = &mut j.source {
        for f in cps {
            f.background = bg;
        }
    }
    j.render.format.transparent = true;
    for name in ["loop.gif", "loop.apng"] {
        j.video = Some((d.join(name), VideoOptions::default()));
        j.run(&AtomicBool::new(false), |_| {}).unwrap();
    }
    let frame = image::open(d.join("frames/00000.png")).unwrap().to_rgba8();
    let empty = (0..frame.width())
        .flat_map(|x| (0..frame.height()).map(move |y| (x, y)))
        .find(|&(x, y)| frame.get_pixel(x, y)[3] == 0)
        .expect("the frame has empty pixels");
    let lit = (0..frame.width())
        .flat_map(|x| (0..frame.height()).map(move |y| (x, y)))
        .find(|&(x, y)| frame.get_pixel(x, y)[3] > 200)
        .expect("the frame has opaque pixels");
    use image::AnimationDecoder;
    let gif = std::fs::File::open(d.join("loop.gif")).unwrap();
    let frames = image::codecs::gif::GifDecoder::new(std::io::BufReader::new(gif))
        .unwrap()
        .into_frames()
        .collect_frames()
        .unwrap();
    let g = frames[0].buffer();
    let want = bg.map(|c| (c * 255.0).round() as i32);
    let p = g.get_pixel(empty.0, empty.1);
    for c in 0..3 {
        assert!((p[c] as i32 - want[c]).abs() <= 12, "{p:?} is not {want:?}");
    }
    let q = frame.get_pixel(lit.0, lit.1);
    let r = g.get_pixel(lit.0, lit.1);
    let a = q[3] as f64 / 255.0;
    for c in 0..3 {
        let over = q[c] as f64 * a + want[c] as f64 * (1.0 - a);
        assert!(
            (r[c] as f64 - over).abs() <= 16.0,
            "{r:?} is not {q:?} over {want:?}"
        );
    }
    // The APNG keeps the alpha of the frames.
    let apng = std::fs::File::open(d.join("loop.apng")).unwrap();
    let mut r = png::Decoder::new(std::io::BufReader::new(apng))
        .read_info()
        .unwrap();
    let mut buf = vec![0; r.output_buffer_size().unwrap()];
    r.next_frame(&mut buf).unwrap();
    assert_eq!(r.info().color_type, png::ColorType::Rgba);
    assert_eq!(buf[(empty.1 * frame.width() + empty.0) as usize * 4 + 3], 0);
}

#[test]
fn a_cancelled_run_leaves_only_whole_frames() {
    let d = scratch("cancel");
    let j = job(&d);
    let stop = AtomicBool::new(true);
    assert!(matches!(j.run(&stop, |_| {}), Err(AnimError::Interrupted)));
    assert!(names(&d).is_empty(), "{:?}", names(&d));
}

#[test]
fn frames_and_a_video_come_out_together() {
    let d = scratch("video");
    let mut j = job(&d.join("frames"));
    j.video = Some((d.join("loop.apng"), VideoOptions::default()));
    let s = j.run(&AtomicBool::new(false), |_| {}).unwrap();
    assert_eq!(s.video, Some(d.join("loop.apng")));
    assert_eq!(names(&d.join("frames")).len(), 4);
    let r = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(d.join("loop.apng")).unwrap(),
    ))
    .read_info()
    .unwrap();
    assert_eq!(r.info().animation_control.unwrap().num_frames, 4);
    // Encoding again from the frames on disk renders nothing.
    std::fs::remove_file(d.join("loop.apng")).unwrap();
    let s = j.run(&AtomicBool::new(false), |_| {}).unwrap();
    assert_eq!((s.rendered, s.skipped), (0, 4));
    assert!(d.join("loop.apng").exists());
}

#[test]
fn rotation_frames_step_from_the_start_whatever_the_order() {
    let src = Source::Rotation {
        flame: cp(0.0, 0.3),
        seed: 7,
    };
    let adjust = |_: &mut Flame| {};
    let mut c = Cursor::default();
    let in_order: Vec<Flame> = (0..5)
        .map(|k| src.frame(k as f64, true, &adjust, &mut c).develop)
        .collect();
    let alone = src
        .frame(3.0, true, &adjust, &mut Cursor::default())
        .develop;
    assert_eq!(alone.xforms, in_order[3].xforms);
    // Going back restarts from the first frame.
    assert_eq!(
        src.frame(1.0, true, &adjust, &mut c).develop.xforms,
        in_order[1].xforms
    );
}

#[test]
fn numbered_frames_and_output_paths_follow_the_command_lines_rules() {
    let f = numbered_frames(90, 3, 4).unwrap();
    assert_eq!(
        f,
        vec![
            FrameSpec {
                time: 2.0,
                name: "frame-0003.png".into()
            },
            FrameSpec {
                time: 3.0,
                name: "frame-0004.png".into()
            }
        ]
    );
    assert_eq!(
        numbered_frames(123_456, 1, 1).unwrap()[0].name,
        "frame-000001.png"
    );
    for (total, a, b) in [(0, 1, 1), (10, 0, 3), (10, 4, 3), (10, 9, 11)] {
        assert!(numbered_frames(total, a, b).is_err(), "{total} {a} {b}");
    }
    let dir = scratch("outputs");
    let (frames, video) = output_paths(&dir.join("loop.mp4")).unwrap();
    assert_eq!(frames, dir.join("loop.mp4.frames"));
    assert_eq!(video, Some(dir.join("loop.mp4")));
    assert_eq!(output_paths(&dir).unwrap(), (dir.clone(), None));
    std::fs::write(dir.join("notes.txt"), "x").unwrap();
    assert!(output_paths(&dir.join("notes.txt")).is_err());
}
