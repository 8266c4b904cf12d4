//! Posters and render farms: saved render states (resume, version check), parts and merge,
//! strips, animation frame ranges, and the farm recipes (GNU parallel, SLURM, Kubernetes).

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use ugnis::flame::Flame;
use ugnis::flame::Histogram;
use ugnis::flame::render::{Plan, Renderer, develop, geometry_of};
use ugnis::flame::strips;
use ugnis::flame::{Part, RenderState};
use ugnis::io::render_state::{self, StateReader};

use common::{opts, run};

fn ugnis(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ugnis"))
        .args(args)
        .arg("--progress=none")
        .output()
        .expect("run ugnis");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn ok(args: &[&str]) -> String {
    let (code, out, err) = ugnis(args);
    assert_eq!(code, 0, "ugnis {args:?} failed: {err}");
    out
}

fn scratch(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ugnis-farm-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The orchid example at a test size.
fn flame(w: u32, h: u32, quality: f64) -> Flame {
    let f = ugnis::io::read_flames(&common::example("orchid.flame"), &Default::default())
        .unwrap()
        .value;
    let mut f = f.into_iter().next().unwrap();
    f.resize_keep_framing(w, h);
    f.quality = quality;
    f
}

fn rgb(img: &image::DynamicImage) -> Vec<i32> {
    img.to_rgb8().as_raw().iter().map(|&v| v as i32).collect()
}

fn max_diff(a: &[i32], b: &[i32]) -> i32 {
    assert_eq!(a.len(), b.len());
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).max().unwrap()
}

fn psnr(a: &[i32], b: &[i32]) -> f64 {
    let mse: f64 = a
        .iter()
        .zip(b)
        .map(|(x, y)| ((x - y) as f64).powi(2))
        .sum::<f64>()
        / a.len() as f64;
    10.0 * (255.0f64 * 255.0 / mse).log10()
}

#[test]
fn resume_continues_the_same_render() {
    // 80×50 at quality 5 is exactly two sub-batches, so the first render ends on a sub-batch
    // boundary and the resumed one iterates the very sub-batches (and orbits) of a render at
    // quality 10.
    let f = flame(80, 50, 5.0);
    let mut r = Renderer::new(&f, &opts(7, 2)).unwrap();
    run(&mut r);
    let (st, hist) = r.into_state().unwrap();
    assert_eq!(st.samples_done, 20_000);
    assert!(st.is_complete());
    // Through a file, as the command line does it.
    let dir = scratch("resume");
    let path = dir.join("a.ugnis-state");
    render_state::save(&path, &st, &hist).unwrap();
    let mut rd = StateReader::open(&path).unwrap();
    assert_eq!(rd.state, st, "the state reads back as written");
    let back = rd.read_all().unwrap();
    assert_eq!(back.data, hist.data, "the histogram reads back bit for bit");
    let mut r2 = Renderer::resume(&rd.state, back, 5.0, &opts(7, 2), None).unwrap();
    run(&mut r2);
    assert_eq!(r2.samples_done(), 40_000);
    let resumed = r2.finish();
    let mut whole = Renderer::new(&flame(80, 50, 10.0), &opts(7, 2)).unwrap();
    run(&mut whole);
    let whole = whole.finish();
    // Equal up to the rounding of the sums (added in another order).
    let d = max_diff(&rgb(&resumed), &rgb(&whole));
    assert!(
        d <= 1,
        "resumed render differs from the longer render by {d}"
    );
    // And it really did add samples: the state alone is a different picture.
    let geom = geometry_of(&st.flame).unwrap();
    let before = develop(&st.flame, &geom, &hist, st.density(), Default::default());
    assert!(max_diff(&rgb(&before), &rgb(&whole)) > 10);
}

#[test]
fn a_resumed_affine_ifs_continues_the_same_orbits() {
    // Affine IFS orbits step in place once they are all past the fuse; a resumed render must
    // take that path at the same steps as the render run on (else its orbits differ).
    let ifs = |q: f64| {
        let mut f =
            ugnis::io::read_flames(&common::example("sierpinski.flame"), &Default::default())
                .unwrap()
                .value
                .remove(0);
        f.resize_keep_framing(80, 50);
        f.quality = q;
        f
    };
    let mut r = Renderer::new(&ifs(5.0), &opts(3, 2)).unwrap();
    run(&mut r);
    let (st, hist) = r.into_state().unwrap();
    let mut r2 = Renderer::resume(&st, hist, 5.0, &opts(3, 2), None).unwrap();
    run(&mut r2);
    let resumed = r2.finish();
    let mut whole = Renderer::new(&ifs(10.0), &opts(3, 2)).unwrap();
    run(&mut whole);
    let d = max_diff(&rgb(&resumed), &rgb(&whole.finish()));
    assert!(
        d <= 1,
        "resumed render differs from the longer render by {d}"
    );
}

#[test]
fn a_render_resumed_after_a_partial_sub_batch_draws_every_sample() {
    // 81×50 at quality 5 is 20 250 samples: the last of its three sub-batches holds 250. The
    // added quality's samples come in whole sub-batches after it, none lost.
    let f = |q: f64| {
        let mut f = flame(80, 50, q);
        f.resize_keep_framing(81, 50);
        f
    };
    let mut r = Renderer::new(&f(5.0), &opts(7, 2)).unwrap();
    run(&mut r);
    let (st, hist) = r.into_state().unwrap();
    assert_eq!((st.samples_done, st.batches_done), (20_250, 3));
    let mut r2 = Renderer::resume(&st, hist, 5.0, &opts(7, 2), None).unwrap();
    assert_eq!(r2.total_samples(), 40_500);
    run(&mut r2);
    assert_eq!(r2.samples_done(), 40_500);
    assert!((r2.fraction() - 1.0).abs() < 1e-12);
    // Extended again, in a running renderer.
    r2.extend(5.0).unwrap();
    run(&mut r2);
    assert_eq!(r2.samples_done(), 60_750);
    assert!((r2.quality_done() - 15.0).abs() < 1e-9);
    let (st2, _) = r2.snapshot().unwrap();
    let mut whole = Renderer::new(&f(15.0), &opts(7, 2)).unwrap();
    run(&mut whole);
    let resumed = r2.finish();
    let p = psnr(&rgb(&resumed), &rgb(&whole.finish()));
    assert!(p > 25.0, "resumed render is {p:.1} dB from one run on");
    // A state saved after the extensions resumes after its last sub-batch too.
    assert!(st2.is_finished());
    assert_eq!(st2.samples_done, 60_750);
}

/// The JWildfire fixture whose crop hides points, at a test size.
fn hidden(quality: f64) -> Flame {
    let path = common::fixture("jwildfire_render/hidden.flame");
    let mut f = ugnis::io::read_flames(&path, &Default::default())
        .unwrap()
        .value
        .remove(0);
    // JWildfire's renderer draws a border of 2 pixels around the image (its filter's reach),
    // so 96×46 at quality 4 is (96 + 4)·(46 + 4)·4 samples, two whole sub-batches (see
    // resume_continues_the_same_render).
    f.resize_keep_framing(96, 46);
    f.quality = quality;
    f
}

#[test]
fn a_resumed_jwildfire_render_keeps_its_hidden_points_hidden() {
    // Under JWildfire's rule a point's hide flag travels with it from xform to xform: the
    // state keeps it, so the resumed render draws what one run on draws.
    let mut r = Renderer::new(&hidden(4.0), &opts(5, 2)).unwrap();
    run(&mut r);
    let (st, hist) = r.into_state().unwrap();
    assert_eq!(st.samples_done, 20_000);
    assert!(
        st.lanes.iter().any(|l| l.hid.iter().any(|&h| h)),
        "some orbits are hidden when the render stops"
    );
    let dir = scratch("hidden");
    let path = dir.join("h.ugnis-state");
    render_state::save(&path, &st, &hist).unwrap();
    let mut rd = StateReader::open(&path).unwrap();
    assert_eq!(rd.state, st, "the hide flags read back as written");
    let back = rd.read_all().unwrap();
    let mut r2 = Renderer::resume(&rd.state, back, 4.0, &opts(5, 2), None).unwrap();
    run(&mut r2);
    let mut whole = Renderer::new(&hidden(8.0), &opts(5, 2)).unwrap();
    run(&mut whole);
    let resumed = r2.finish();
    let whole = whole.finish();
    let d = max_diff(&rgb(&resumed), &rgb(&whole));
    assert!(
        d <= 1,
        "resumed render differs from the longer render by {d}"
    );
}

#[test]
fn version_2_states_read_with_no_hidden_points() {
    // Version 2 kept no own colours, hide flags and steps: its orbit sets are 5 bytes per
    // orbit and 8 bytes shorter and read as all shown.
    let mut r = Renderer::new(&hidden(2.0), &opts(1, 1)).unwrap();
    run(&mut r);
    let (st, hist) = r.into_state().unwrap();
    let dir = scratch("v2");
    let v3 = dir.join("v3.ugnis-state");
    render_state::save(&v3, &st, &hist).unwrap();
    let b = std::fs::read(&v3).unwrap();
    let lanes = st.lanes[0].x.len();
    let hlen = u32::from_le_bytes(b[12..16].try_into().unwrap()) as usize;
    let at = 16 + hlen;
    let sets = u32::from_le_bytes(b[at..at + 4].try_into().unwrap()) as usize;
    let v2_set = lanes * (4 * 8 + 2 + 1 + 4) + 1;
    let v3_set = v2_set + 5 * lanes + 8;
    // Version 4's header line "gap" and its variation states are not in version 2.
    let header = std::str::from_utf8(&b[16..at]).unwrap();
    let header = header.replacen("gap 0\n", "", 1);
    assert_eq!(header.len() + 6, hlen, "the header has a gap line");
    let mut old = b[..8].to_vec();
    old.extend_from_slice(&2u32.to_le_bytes());
    old.extend_from_slice(&(header.len() as u32).to_le_bytes());
    old.extend_from_slice(header.as_bytes());
    old.extend_from_slice(&b[at..at + 4]);
    for k in 0..sets {
        let o = at + 4 + k * v3_set;
        old.extend_from_slice(&b[o..o + v2_set]);
    }
    let var_states: usize = st.var_states.iter().map(|v| 4 + 8 * v.len()).sum();
    old.extend_from_slice(&b[at + 4 + sets * v3_set + 4 + var_states..]);
    let v2 = dir.join("v2.ugnis-state");
    std::fs::write(&v2, &old).unwrap();
    let mut rd = StateReader::open(&v2).unwrap();
    assert_eq!(rd.state.lanes.len(), sets);
    for (a, b) in rd.state.lanes.iter().zip(&st.lanes) {
        assert_eq!((&a.x, &a.step, a.started), (&b.x, &b.step, b.started));
        assert!(a.hid.iter().all(|&h| !h) && a.rgb.iter().all(|&c| c == 0));
    }
    assert_eq!(rd.read_all().unwrap().data, hist.data);
}

#[test]
fn states_of_other_versions_and_damaged_states_are_refused() {
    let f = flame(32, 24, 2.0);
    let mut r = Renderer::new(&f, &opts(1, 1)).unwrap();
    run(&mut r);
    let (st, hist) = r.into_state().unwrap();
    let dir = scratch("version");
    let good = dir.join("good.ugnis-state");
    render_state::save(&good, &st, &hist).unwrap();
    let bytes = std::fs::read(&good).unwrap();
    for v in [0u32, 1, 5] {
        let mut b = bytes.clone();
        b[8..12].copy_from_slice(&v.to_le_bytes());
        let p = dir.join(format!("v{v}.ugnis-state"));
        std::fs::write(&p, &b).unwrap();
        let e = StateReader::open(&p).err().expect("refused").to_string();
        assert!(
            e.contains(&format!("format version {v}")) && e.contains("v0.ugnis-state") == (v == 0),
            "{e}"
        );
        let (code, _, err) = ugnis(&["info", s(&p)]);
        assert_eq!(code, 1);
        assert!(err.contains("reads versions 2 to 4 only"), "{err}");
    }
    // Truncated: the end marker is missing.
    let p = dir.join("cut.ugnis-state");
    std::fs::write(&p, &bytes[..bytes.len() - 30]).unwrap();
    let e = StateReader::open(&p).err().expect("refused").to_string();
    assert!(
        e.contains("cut.ugnis-state") && e.contains("truncated"),
        "{e}"
    );
    // Not a state at all.
    let p = dir.join("png.ugnis-state");
    std::fs::write(&p, b"\x89PNG\r\n\x1a\nrest").unwrap();
    let e = StateReader::open(&p).err().expect("refused").to_string();
    assert!(e.contains("not a ugnis render state"), "{e}");
    // A damaged chunk is an error, never garbage.
    let mut b = bytes.clone();
    let at = b.windows(4).position(|w| w == b"ROWS").unwrap() + 24;
    for x in &mut b[at..at + 16] {
        *x ^= 0x5a;
    }
    let p = dir.join("bad.ugnis-state");
    std::fs::write(&p, &b).unwrap();
    let mut rd = StateReader::open(&p).unwrap();
    assert!(rd.read_all().is_err());
}

/// Parts rendered one by one (as on separate machines), summed in part order.
fn merged_parts(f: &Flame, n: u32, seed: u64) -> (RenderState, Histogram) {
    let mut states = Vec::new();
    for i in 0..n {
        let plan = Plan {
            part: Part { index: i, count: n },
            strip: None,
        };
        let mut r = Renderer::with_plan(f, &opts(seed, 1), &plan).unwrap();
        run(&mut r);
        states.push(r.into_state().unwrap());
    }
    let refs: Vec<&RenderState> = states.iter().map(|s| &s.0).collect();
    let st = RenderState::merged(&refs).unwrap();
    let mut sum = states[0].1.clone();
    for s in &states[1..] {
        sum.add(&s.1);
    }
    (st, sum)
}

#[test]
fn a_merge_of_parts_is_as_good_as_one_render() {
    let (w, h) = (64, 48);
    let reference = {
        let mut r = Renderer::new(&flame(w, h, 1000.0), &opts(99, 0)).unwrap();
        run(&mut r);
        rgb(&r.finish())
    };
    let q = 40.0;
    let (mut whole_db, mut merged_db) = (0.0, 0.0);
    let seeds = [1u64, 2, 3];
    for &seed in &seeds {
        let mut r = Renderer::new(&flame(w, h, q), &opts(seed, 1)).unwrap();
        run(&mut r);
        whole_db += psnr(&rgb(&r.finish()), &reference);
        let (st, sum) = merged_parts(&flame(w, h, q), 4, seed);
        assert!(st.is_complete());
        assert_eq!(st.samples_done, flame(w, h, q).total_samples());
        let geom = geometry_of(&st.flame).unwrap();
        let img = develop(&st.flame, &geom, &sum, st.density(), Default::default());
        merged_db += psnr(&rgb(&img), &reference);
    }
    let (whole_db, merged_db) = (
        whole_db / seeds.len() as f64,
        merged_db / seeds.len() as f64,
    );
    eprintln!(
        "PSNR vs quality 1000: one render {whole_db:.2} dB, merge of 4 parts {merged_db:.2} dB"
    );
    assert!(
        (whole_db - merged_db).abs() <= 0.3,
        "one render {whole_db:.2} dB, merge {merged_db:.2} dB"
    );
}

#[test]
fn merge_is_order_independent_and_names_mismatched_parts() {
    let dir = scratch("merge");
    let flame_file = common::example("orchid.flame");
    let part = |i: u32, q: &str, seed: &str| {
        let p = dir.join(format!("p{i}-{q}-{seed}.ugnis-state"));
        ok(&[
            "render",
            s(&flame_file),
            "--size",
            "64x48",
            "--quality",
            q,
            "--seed",
            seed,
            "--threads",
            "1",
            "--part",
            &format!("{i}/3"),
            "--save-state",
            s(&p),
        ]);
        p
    };
    let p: Vec<PathBuf> = (0..3).map(|i| part(i, "30", "5")).collect();
    let a = dir.join("a.png");
    let b = dir.join("b.png");
    let all = dir.join("all.ugnis-state");
    ok(&[
        "merge",
        s(&p[0]),
        s(&p[1]),
        s(&p[2]),
        "-o",
        s(&a),
        "--save-state",
        s(&all),
    ]);
    ok(&["merge", s(&p[2]), s(&p[0]), s(&p[1]), "-o", s(&b)]);
    let (ia, ib) = (image::open(&a).unwrap(), image::open(&b).unwrap());
    assert_eq!(
        rgb(&ia),
        rgb(&ib),
        "the merge depends on the order of the files"
    );
    // The merged state develops to the same picture, and says it is complete.
    let info = ok(&["info", s(&all)]);
    assert!(
        info.contains("complete") && info.contains("quality 30"),
        "{info}"
    );
    let c = dir.join("c.png");
    ok(&["render", "--resume", s(&all), "-o", s(&c)]);
    assert_eq!(rgb(&image::open(&c).unwrap()), rgb(&ia));
    // A part of another quality or seed: the error names the file and the difference.
    let odd = part(1, "31", "5");
    let (code, _, err) = ugnis(&["merge", s(&p[0]), s(&odd), "-o", s(&b)]);
    assert_eq!(code, 1);
    assert!(
        err.contains("p1-31-5.ugnis-state") && err.contains("quality 30 vs 31"),
        "{err}"
    );
    let odd = part(2, "30", "6");
    let (code, _, err) = ugnis(&["merge", s(&p[0]), s(&odd), "-o", s(&b)]);
    assert_eq!(code, 1);
    assert!(
        err.contains("p2-30-6.ugnis-state") && err.contains("seed 5 vs 6"),
        "{err}"
    );
    // The same part twice.
    let (code, _, err) = ugnis(&["merge", s(&p[0]), s(&p[0]), "-o", s(&b)]);
    assert_eq!(code, 1);
    assert!(err.contains("holds part 0/3"), "{err}");
    // Missing parts: merged with a warning.
    let (code, _, err) = ugnis(&["merge", s(&p[0]), s(&p[1]), "-o", s(&b)]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("2 of 3 shares"), "{err}");
}

#[test]
fn strips_give_the_whole_render() {
    // Supersample 2 and wide density estimation: the margins must cover both.
    let mut f = flame(64, 48, 20.0);
    f.supersample = 2;
    f.estimator_radius = 6.0;
    let mut r = Renderer::new(&f, &opts(3, 2)).unwrap();
    run(&mut r);
    let (whole_img, st) = r.finish_with_state();
    let (_, whole_hist) = st.unwrap();
    let whole = rgb(&whole_img);
    let plan = strips::plan(&f, 5).unwrap();
    let mut rows = Vec::new();
    let mut tiled = Vec::new();
    for strip in &plan {
        let mut r = Renderer::with_plan(
            &f,
            &opts(3, 2),
            &Plan {
                part: Part::default(),
                strip: Some(strip.clone()),
            },
        )
        .unwrap();
        run(&mut r);
        let g = r.geometry().clone();
        let (img, st) = r.finish_with_state();
        rows.extend(rgb(&img));
        let (_, h) = st.unwrap();
        let c = &strip.core_rows;
        tiled.extend_from_slice(&h.data[(c.start - g.row0) * g.bw..(c.end - g.row0) * g.bw]);
    }
    // The strips' histograms are the whole histogram's rows, bit for bit (same samples, same
    // order); the pictures differ at most by the rounding of density estimation's sums.
    assert_eq!(tiled, whole_hist.data);
    let d = max_diff(&rows, &whole);
    assert!(d <= 1, "strips differ from the whole render by {d}");
}

#[test]
fn cli_strips_parts_and_automatic_strips() {
    let dir = scratch("strips");
    let fl = common::example("orchid.flame");
    let base = ["--size", "96x64", "--quality", "20", "--threads", "2"];
    let whole = dir.join("whole.png");
    let mut args = vec!["render", s(&fl), "-o", s(&whole)];
    args.extend(base);
    ok(&args);
    let striped = dir.join("striped.png");
    let mut args = vec!["render", s(&fl), "-o", s(&striped), "--strips", "4"];
    args.extend(base);
    ok(&args);
    let w = rgb(&image::open(&whole).unwrap());
    assert!(max_diff(&rgb(&image::open(&striped).unwrap()), &w) <= 1);
    // A memory limit too small for the whole render: strips chosen automatically.
    let auto = dir.join("auto.png");
    let mut args = vec!["render", s(&fl), "-o", s(&auto), "--memory-limit", "700K"];
    args.extend(base);
    let (code, _, err) = ugnis(&args);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("strips"), "{err}");
    assert!(max_diff(&rgb(&image::open(&auto).unwrap()), &w) <= 1);
    // Parts in strips: the same states as parts rendered whole.
    for (tag, strips) in [("whole", None), ("strips", Some("3"))] {
        for i in 0..2 {
            let p = dir.join(format!("{tag}-{i}.ugnis-state"));
            let part = format!("{i}/2");
            let mut args = vec!["render", s(&fl), "--part", &part, "--save-state", s(&p)];
            args.extend(base);
            if let Some(k) = strips {
                args.extend(["--strips", k]);
            }
            ok(&args);
        }
    }
    for i in 0..2 {
        let mut a = StateReader::open(&dir.join(format!("whole-{i}.ugnis-state"))).unwrap();
        let mut b = StateReader::open(&dir.join(format!("strips-{i}.ugnis-state"))).unwrap();
        assert_eq!(a.state, b.state);
        assert_eq!(a.read_all().unwrap().data, b.read_all().unwrap().data);
    }
    // Merged in strips, too.
    let m = dir.join("merged.png");
    ok(&[
        "merge",
        s(&dir.join("strips-1.ugnis-state")),
        s(&dir.join("strips-0.ugnis-state")),
        "-o",
        s(&m),
        "--strips",
        "3",
    ]);
    let m1 = dir.join("merged1.png");
    ok(&[
        "merge",
        s(&dir.join("whole-0.ugnis-state")),
        s(&dir.join("whole-1.ugnis-state")),
        "-o",
        s(&m1),
    ]);
    assert!(
        max_diff(
            &rgb(&image::open(&m).unwrap()),
            &rgb(&image::open(&m1).unwrap())
        ) <= 1
    );
    // Bad numbers get clear errors.
    let (code, _, err) = ugnis(&[
        "render",
        s(&fl),
        "--part",
        "4/4",
        "--save-state",
        "x.ugnis-state",
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("below the part count"), "{err}");
    let (code, _, err) = ugnis(&["render", s(&fl), "--part", "1/4"]);
    assert_eq!(code, 1);
    assert!(err.contains("--save-state"), "{err}");
    let (code, _, err) = ugnis(&["render", s(&fl), "--strips", "0", "-o", s(&auto)]);
    assert_eq!(code, 1);
    assert!(err.contains("strips"), "{err}");
}

#[test]
fn animation_ranges_name_frames_as_the_whole_animation() {
    let dir = scratch("anim");
    let fl = common::example("orchid.flame");
    let (all, part) = (dir.join("all"), dir.join("part"));
    let common = ["--size", "32x24", "--quality", "5", "--threads", "1"];
    let mut a = vec!["animate", s(&fl), "--frames", "5", "-o", s(&all)];
    a.extend(common);
    ok(&a);
    let mut a = vec![
        "animate",
        s(&fl),
        "--frames",
        "3..4",
        "--total",
        "5",
        "-o",
        s(&part),
    ];
    a.extend(common);
    ok(&a);
    let mut names: Vec<String> = std::fs::read_dir(&part)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, ["frame-0003.png", "frame-0004.png"]);
    for n in &names {
        assert_eq!(
            std::fs::read(all.join(n)).unwrap(),
            std::fs::read(part.join(n)).unwrap(),
            "{n}"
        );
    }
    let (code, _, err) = ugnis(&[
        "animate",
        s(&fl),
        "--frames",
        "3..9",
        "--total",
        "5",
        "-o",
        s(&part),
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("past the last frame"), "{err}");
    let (code, _, err) = ugnis(&["animate", s(&fl), "--frames", "3..4", "-o", s(&part)]);
    assert_eq!(code, 1);
    assert!(err.contains("--total"), "{err}");
}

/// Parts 0..n rendered directly and merged: what every farm recipe must reproduce.
fn direct_merge(dir: &Path, fl: &Path, n: u32, size: &str, q: &str) -> Vec<i32> {
    let mut parts = Vec::new();
    for i in 0..n {
        let p = dir.join(format!("direct-{i}.ugnis-state"));
        let part = format!("{i}/{n}");
        ok(&[
            "render",
            s(fl),
            "--size",
            size,
            "--quality",
            q,
            "--seed",
            "1",
            "--threads",
            "1",
            "--part",
            &part,
            "--save-state",
            s(&p),
        ]);
        parts.push(p);
    }
    let out = dir.join("direct.png");
    let mut a = vec!["merge"];
    a.extend(parts.iter().map(|p| s(p)));
    a.extend(["-o", s(&out)]);
    ok(&a);
    rgb(&image::open(&out).unwrap())
}

#[test]
fn gnu_parallel_recipe_renders_four_parts_and_merges() {
    if Command::new("parallel").arg("--version").output().is_err() {
        println!(
            "NOTICE: GNU parallel is not installed; skipping the GNU parallel recipe test (CI installs it)"
        );
        return;
    }
    let dir = scratch("parallel");
    let fl = common::example("orchid.flame");
    let bin = env!("CARGO_BIN_EXE_ugnis");
    // The README's recipe, with the test's size and quality.
    let script = format!(
        "set -e\ncd '{d}'\nparallel --will-cite -j4 '{bin}' render '{fl}' --size 64x48 --quality 40 --seed 1 --threads 1 --part {{}}/4 --save-state part-{{}}.ugnis-state --progress none ::: 0 1 2 3\n'{bin}' merge part-*.ugnis-state -o poster.png --progress none\n",
        d = dir.display(),
        fl = fl.display()
    );
    let st = Command::new("sh").arg("-c").arg(&script).status().unwrap();
    assert!(st.success());
    let got = rgb(&image::open(dir.join("poster.png")).unwrap());
    assert_eq!(got, direct_merge(&dir, &fl, 4, "64x48", "40"));
}

/// The text between two marker lines of a file, dedented.
fn block(text: &str, begin: &str, end: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let a = lines.iter().position(|l| l.trim() == begin).expect(begin);
    let b = lines.iter().position(|l| l.trim() == end).expect(end);
    let indent = lines[a].len() - lines[a].trim_start().len();
    lines[a..=b]
        .iter()
        .map(|l| l.get(indent..).unwrap_or("").to_string() + "\n")
        .collect()
}

#[test]
fn slurm_and_kubernetes_recipes_run_locally() {
    let fl = common::example("orchid.flame");
    let bin = env!("CARGO_BIN_EXE_ugnis");
    let env = |c: &mut Command, out: &Path| {
        c.env("UGNIS", bin)
            .env("FLAME", &fl)
            .env("OUT", out)
            .env("SIZE", "64x48")
            .env("QUALITY", "40")
            .env("SEED", "1")
            .env("PARTS", "3");
    };
    // SLURM: one task per index, then the merge step.
    let dir = scratch("slurm");
    let script = common::root().join("contrib/slurm/ugnis-array.sh");
    let out = dir.join("out");
    for i in 0..3 {
        let mut c = Command::new("bash");
        c.arg(&script)
            .env("SLURM_ARRAY_TASK_ID", i.to_string())
            .env("SLURM_CPUS_PER_TASK", "1");
        env(&mut c, &out);
        assert!(c.status().unwrap().success(), "array task {i}");
    }
    let mut c = Command::new("bash");
    c.arg(&script).arg("merge");
    env(&mut c, &out);
    assert!(c.status().unwrap().success());
    let want = direct_merge(&dir, &fl, 3, "64x48", "40");
    assert_eq!(rgb(&image::open(out.join("poster.png")).unwrap()), want);
    // The merge step refuses to run with a part missing.
    std::fs::remove_file(out.join("part-1.ugnis-state")).unwrap();
    let mut c = Command::new("bash");
    c.arg(&script).arg("merge");
    env(&mut c, &out);
    assert!(!c.status().unwrap().success());

    // Kubernetes: the worker and merge scripts of the manifest, with JOB_COMPLETION_INDEX.
    let yaml =
        std::fs::read_to_string(common::root().join("contrib/k8s/ugnis-indexed-job.yaml")).unwrap();
    let worker = block(&yaml, "# ugnis-worker-begin", "# ugnis-worker-end");
    let merge = block(&yaml, "# ugnis-merge-begin", "# ugnis-merge-end");
    let dir = scratch("k8s");
    let out = dir.join("out");
    // The merge job starts first and waits for the parts.
    let mut m = Command::new("sh");
    m.arg("-c").arg(&merge).env("POLL_SECONDS", "0.2");
    env(&mut m, &out);
    let mut merging = m.spawn().unwrap();
    for i in 0..3 {
        let mut c = Command::new("sh");
        c.arg("-c")
            .arg(&worker)
            .env("JOB_COMPLETION_INDEX", i.to_string());
        env(&mut c, &out);
        assert!(c.status().unwrap().success(), "index {i}");
    }
    assert!(merging.wait().unwrap().success());
    // The workers use all cores; the picture is the same as with one thread per part only up
    // to the orbits each thread follows, so compare with the SLURM run's quality instead.
    let got = rgb(&image::open(out.join("poster.png")).unwrap());
    assert!(psnr(&got, &want) > 25.0, "{}", psnr(&got, &want));
}

#[test]
fn a_solid_flame_keeps_no_state_and_is_not_cut_into_strips() {
    // JWildfire's solid rendering keeps its depth buffers in memory only: a state or strips
    // would give another picture, so both are refused before rendering, with the reason.
    let dir = scratch("solid");
    let fl = common::fixture("jwildfire_render/solid.flame");
    let st = dir.join("solid.ugnis-state");
    let png = dir.join("solid.png");
    let base = ["--size", "40x30", "--quality", "2", "--threads", "1"];
    let mut args = vec!["render", s(&fl), "-o", s(&png), "--save-state", s(&st)];
    args.extend(base);
    let (code, _, err) = ugnis(&args);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("solid") && err.contains("state"), "{err}");
    assert!(!st.exists() && !png.exists());
    let mut args = vec!["render", s(&fl), "-o", s(&png), "--strips", "2"];
    args.extend(base);
    let (code, _, err) = ugnis(&args);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("solid") && err.contains("strips"), "{err}");
    // Whole, it renders.
    let mut args = vec!["render", s(&fl), "-o", s(&png)];
    args.extend(base);
    ok(&args);
    assert!(png.exists());
}
