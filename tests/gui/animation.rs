//! Animation in the editor: the timeline adds, moves and deletes keys (undoably) and the
//! preview shows the flame at the current frame; auto-key; the curve editor; playback; the
//! loop tools; motion-blur settings saved with the flame; the Animation export window writing
//! frames, resuming, and keeping the frames when ffmpeg is missing.

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers, Pos2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::UgnisApp;
use ugnis::app::flame_tab::SourceKind;
use ugnis::flame::keyframes::{FlameParam, Interp, Target, XformParam, XformRef};

use crate::{drag, example, harness_sized, open, section, set_number, wait_until};

const ZOOM: Target = Target::Flame(FlameParam::Zoom);

/// A click (press and release without moving) at `p`.
fn click_at(h: &mut Harness<'_, UgnisApp>, p: Pos2) {
    h.hover_at(p);
    h.step();
    h.drag_at(p);
    h.step();
    h.drop_at(p);
    h.run_steps(2);
}

/// Where the ruler draws frame `f` (on its key row).
fn ruler_at(h: &Harness<'_, UgnisApp>, f: f64) -> Pos2 {
    h.state()
        .flame
        .timeline
        .ruler
        .expect("the ruler is drawn")
        .key_pos(f)
}

/// The keys (frame, value) of `t` in the current flame.
fn keys_of(h: &Harness<'_, UgnisApp>, t: &Target) -> Vec<(f64, f64)> {
    h.state()
        .flame
        .doc()
        .flame()
        .keys
        .curve(t)
        .map_or_else(Vec::new, |c| {
            c.keys().iter().map(|k| (k.frame, k.value)).collect()
        })
}

/// Open the timeline and choose `label` in its parameter list.
fn timeline_with(h: &mut Harness<'_, UgnisApp>, label: &str) {
    h.key_press_modifiers(Modifiers::COMMAND, Key::T);
    h.run_steps(2);
    assert!(h.state().flame.timeline.open, "Ctrl+T shows the timeline");
    h.get_by_role_and_label(Role::ComboBox, "Parameter").click();
    h.run_steps(2);
    h.get_by_label(label).click();
    h.run_steps(2);
}

#[test]
fn the_timeline_keys_moves_and_deletes_and_the_preview_follows_the_frame() {
    let mut h = harness_sized(
        ugnis::app::Start::File(example("sierpinski.flame")),
        1280.0,
        1300.0,
    );
    timeline_with(&mut h, "zoom");
    assert_eq!(h.state().flame.timeline.target, Some(ZOOM));
    let z0 = h.state().flame.doc().flame().zoom;
    // K keys the parameter at frame 0.
    h.key_press(Key::K);
    h.run_steps(2);
    assert_eq!(keys_of(&h, &ZOOM), vec![(0.0, z0)]);
    assert!(h.state().flame.doc().dirty);
    // A click on the ruler goes to frame 40; a new zoom there is keyed (auto-key).
    let p = ruler_at(&h, 40.0);
    click_at(&mut h, p);
    assert_eq!(h.state().flame.timeline.frame, 40.0);
    section(&mut h, "Settings");
    set_number(&mut h, "Zoom", z0 + 1.0);
    h.run_steps(2);
    assert_eq!(keys_of(&h, &ZOOM), vec![(0.0, z0), (40.0, z0 + 1.0)]);
    // The preview shows the flame at the current frame: halfway, a smooth curve between two
    // keys is halfway.
    h.key_press(Key::Home);
    h.run_steps(2);
    assert_eq!(h.state().flame.shown_flame().zoom, z0);
    for _ in 0..20 {
        h.key_press(Key::ArrowRight);
        h.step();
    }
    h.run_steps(2);
    assert_eq!(h.state().flame.timeline.frame, 20.0);
    let shown = h.state().flame.shown_flame();
    assert!((shown.zoom - (z0 + 0.5)).abs() < 1e-9, "{}", shown.zoom);
    // The editor's numbers are those of the frame.
    assert_eq!(h.state().flame.doc().flame().zoom, shown.zoom);
    // Dragging the key at 40 on the ruler moves it to 60.
    let (a, b) = (ruler_at(&h, 40.0), ruler_at(&h, 60.0));
    drag(&mut h, a, b);
    assert_eq!(keys_of(&h, &ZOOM), vec![(0.0, z0), (60.0, z0 + 1.0)]);
    let steps = h.state().flame.doc().undo_len();
    // Select it and delete it with the Delete key.
    let p = ruler_at(&h, 60.0);
    click_at(&mut h, p);
    assert_eq!(h.state().flame.timeline.selected_key, Some(60.0));
    h.key_press(Key::Delete);
    h.run_steps(2);
    assert_eq!(keys_of(&h, &ZOOM), vec![(0.0, z0)]);
    assert_eq!(h.state().flame.doc().undo_len(), steps + 1);
    // Undo brings the key back where it was dragged; again, where it was keyed.
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(keys_of(&h, &ZOOM), vec![(0.0, z0), (60.0, z0 + 1.0)]);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(keys_of(&h, &ZOOM), vec![(0.0, z0), (40.0, z0 + 1.0)]);
    // The interpolation of a key is chosen in the key inspector.
    let p = ruler_at(&h, 0.0);
    click_at(&mut h, p);
    h.get_by_role_and_label(Role::ComboBox, "Interpolation")
        .click();
    h.run_steps(2);
    h.get_by_label("step").click();
    h.run_steps(2);
    let f = h.state().flame.doc().flame().clone();
    assert_eq!(f.keys.curve(&ZOOM).unwrap().keys()[0].interp, Interp::Step);
    assert_eq!(f.keys.apply(&f, 39.0).zoom, z0, "a step holds");
}

#[test]
fn the_curve_editor_drags_a_key_in_value() {
    let mut h = harness_sized(
        ugnis::app::Start::File(example("sierpinski.flame")),
        1280.0,
        1300.0,
    );
    timeline_with(&mut h, "zoom");
    h.key_press(Key::K);
    h.run_steps(2);
    h.state_mut().flame.timeline.frame = 30.0;
    h.run_steps(2);
    h.key_press(Key::K);
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Curve").click();
    h.run_steps(3);
    let g = h
        .state()
        .flame
        .timeline
        .curve
        .expect("the curve editor is drawn");
    let k = keys_of(&h, &ZOOM)[1];
    let from = g.pos(k.0, k.1);
    let to = Pos2::new(from.x, g.y_of(g.hi));
    drag(&mut h, from, to);
    let now = keys_of(&h, &ZOOM);
    assert_eq!(now[1].0, 30.0, "the frame stays");
    assert!(now[1].1 > k.1, "{now:?}");
}

#[test]
fn play_advances_the_frames_and_pause_stops_them() {
    let mut h = open("sierpinski.flame");
    // A rotation loop from the loop tools: keys on every transform, a seamless timeline.
    h.state_mut().flame.make_rotation_loop(1.0, 40);
    h.run_steps(2);
    let f = h.state().flame.doc().flame().clone();
    assert!(f.keys.wrap && f.keys.frames == 40);
    let turn = Target::Xform(XformRef::Index(1), XformParam::Rotate);
    assert_eq!(keys_of(&h, &turn), vec![(0.0, 0.0), (40.0, 360.0)]);
    assert!(h.state().flame.timeline.open);
    h.key_press(Key::Space);
    h.run_steps(1);
    assert!(h.state().flame.timeline.playing());
    wait_until(&mut h, |a| a.flame.timeline.frame >= 3.0);
    h.key_press(Key::Space);
    h.run_steps(1);
    assert!(!h.state().flame.timeline.playing());
    let at = h.state().flame.timeline.frame;
    std::thread::sleep(std::time::Duration::from_millis(200));
    h.run_steps(3);
    assert_eq!(h.state().flame.timeline.frame, at, "paused");
    // The preview's flame is turned as the frame says.
    let shown = h.state().flame.shown_flame();
    assert_eq!(shown, f.keys.apply(&f, at));
    assert_ne!(shown.xforms[1].coefs, f.xforms[1].coefs);
    // Undo removes the loop.
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert!(h.state().flame.doc().flame().keys.is_empty());
}

#[test]
fn a_morph_plays_on_the_timeline_as_a_flam3_sequence() {
    let mut h = crate::harness(ugnis::app::Start::File(example("gallery.fla")));
    h.state_mut().flame.play_morph(10, 0.0);
    h.run_steps(2);
    assert!(h.state().flame.timeline.plays_sequence());
    assert_eq!(
        h.state()
            .flame
            .timeline
            .frames(h.state().flame.doc().flame()),
        10
    );
    // Frame 0 is the first flame, padded with resting transforms to match the second.
    let first = h.state().flame.shown_flame();
    let own = &h.state().flame.doc().flames[0].xforms;
    assert_eq!(&first.xforms[..own.len()], &own[..]);
    assert!(first.xforms[own.len()..].iter().all(|x| x.weight == 0.0));
    h.state_mut().flame.timeline.frame = 5.0;
    h.run_steps(2);
    assert_ne!(h.state().flame.shown_flame().xforms, first.xforms);
    assert!(!h.state().flame.doc().dirty, "the file is not changed");
    h.get_by_role_and_label(Role::Button, "Back to the keys")
        .click();
    h.run_steps(2);
    assert!(!h.state().flame.timeline.plays_sequence());
}

#[test]
fn motion_blur_settings_are_kept_in_the_flame_and_saved() {
    let mut h = harness_sized(
        ugnis::app::Start::File(example("sierpinski.flame")),
        1280.0,
        1600.0,
    );
    section(&mut h, "Settings");
    set_number(&mut h, "Sub-frames", 12.0);
    set_number(&mut h, "Exposure (frames)", 0.5);
    h.get_by_role_and_label(Role::ComboBox, "Shape").click();
    h.run_steps(2);
    h.get_by_label("exp").click();
    h.run_steps(2);
    set_number(&mut h, "Exponent", 2.0);
    let a = h.state().flame.doc().flame().anim;
    assert_eq!(a.temporal_samples, 12);
    assert_eq!(a.temporal_filter_width, 0.5);
    assert_eq!(a.temporal_filter_type.name(), "exp");
    assert_eq!(a.temporal_filter_exp, 2.0);
    let path = example("sierpinski.flame").with_file_name("blurred.flame");
    assert!(h.state_mut().flame.save_to(&path));
    let back = ugnis::io::read_flames(&path, &Default::default())
        .unwrap()
        .value
        .remove(0);
    assert_eq!(back.anim, a);
}

/// Start the export the window describes (its button says Render or Resume) and wait for it
/// to end; the status line.
fn run_export(h: &mut Harness<'_, UgnisApp>, button: &str) -> String {
    h.get_by_role_and_label(Role::Button, button).click();
    h.run_steps(2);
    assert!(h.state().flame.anim_export.is_none(), "the export started");
    wait_until(h, |a| a.flame.anim_job.is_none());
    h.run_steps(1);
    h.state().status().to_string()
}

/// Open the Animation export window for 32×24 frames 0–2 of the keys, written to `out`.
fn export_window(h: &mut Harness<'_, UgnisApp>, out: &std::path::Path) {
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::E);
    h.run_steps(2);
    let d = h
        .state_mut()
        .flame
        .anim_export
        .as_mut()
        .expect("the window");
    let s = &mut d.settings;
    assert_eq!(s.source, SourceKind::Keys);
    assert_eq!((s.first, s.last), (0.0, 39.0), "the whole timeline");
    s.width = 32;
    s.height = 24;
    s.quality = 2.0;
    s.last = 2.0;
    s.output = out.to_path_buf();
    h.run_steps(2);
}

#[test]
fn the_animation_export_writes_frames_and_a_second_run_resumes() {
    let mut h = open("sierpinski.flame");
    h.state_mut().flame.make_rotation_loop(1.0, 40);
    h.run_steps(2);
    let dir = example("sierpinski.flame").with_file_name("anim-frames");
    let _ = std::fs::remove_dir_all(&dir);
    export_window(&mut h, &dir);
    let status = run_export(&mut h, "Render");
    assert!(
        status.contains("3 frames rendered, 0 on disk kept"),
        "{status}"
    );
    for n in ["00000.png", "00001.png", "00002.png"] {
        let img = image::open(dir.join(n)).unwrap().to_rgb8();
        assert_eq!(img.dimensions(), (32, 24));
        assert!(img.pixels().any(|p| p.0 != [0, 0, 0]), "{n} is not black");
    }
    // The frames turn: the first and second differ.
    let (a, b) = (
        image::open(dir.join("00000.png")).unwrap().to_rgb8(),
        image::open(dir.join("00001.png")).unwrap().to_rgb8(),
    );
    assert_ne!(a.as_raw(), b.as_raw());
    // Again: the window says the frames are there, and the run keeps them.
    export_window(&mut h, &dir);
    assert!(
        h.query_by_label_contains("3 of them are in the folder already")
            .is_some()
    );
    let status = run_export(&mut h, "Resume");
    assert!(
        status.contains("0 frames rendered, 3 on disk kept"),
        "{status}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_gif_is_made_and_a_video_without_ffmpeg_keeps_its_frames() {
    let mut h = open("sierpinski.flame");
    h.state_mut().flame.make_rotation_loop(1.0, 40);
    h.run_steps(2);
    let gif = example("sierpinski.flame").with_file_name("loop.gif");
    export_window(&mut h, &gif);
    let status = run_export(&mut h, "Render");
    assert!(status.contains("video"), "{status}");
    let decoder = image::codecs::gif::GifDecoder::new(std::io::BufReader::new(
        std::fs::File::open(&gif).unwrap(),
    ))
    .unwrap();
    use image::AnimationDecoder;
    assert_eq!(decoder.into_frames().count(), 3);
    // An .mp4 with an ffmpeg that is not there: the frames are written and kept, and the
    // message names what to install.
    let mp4 = gif.with_file_name("loop.mp4");
    export_window(&mut h, &mp4);
    h.state_mut()
        .flame
        .anim_export
        .as_mut()
        .unwrap()
        .settings
        .ffmpeg = "/nonexistent/ffmpeg".into();
    h.run_steps(2);
    run_export(&mut h, "Render");
    assert!(
        h.query_by_label_contains("needs ffmpeg").is_some(),
        "the message box says why"
    );
    let frames = mp4.with_file_name("loop.mp4.frames");
    assert_eq!(std::fs::read_dir(&frames).unwrap().count(), 3);
    assert!(!mp4.exists());
}

#[test]
fn a_cancelled_export_keeps_its_frames_and_the_next_one_renders_the_rest() {
    let mut h = open("sierpinski.flame");
    h.state_mut().flame.make_rotation_loop(1.0, 40);
    h.run_steps(2);
    let dir = example("sierpinski.flame").with_file_name("anim-cancelled");
    let _ = std::fs::remove_dir_all(&dir);
    export_window(&mut h, &dir);
    {
        let s = &mut h.state_mut().flame.anim_export.as_mut().unwrap().settings;
        s.last = 39.0;
        s.width = 96;
        s.height = 72;
        s.quality = 200.0;
    }
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Render").click();
    h.run_steps(2);
    wait_until(&mut h, |a| {
        a.flame
            .anim_job
            .as_ref()
            .is_none_or(|j| j.progress().done >= 2)
    });
    assert!(h.state().flame.anim_job.is_some(), "40 frames take longer");
    h.get_by_role_and_label(Role::Button, "Cancel").click();
    h.run_steps(2);
    wait_until(&mut h, |a| a.flame.anim_job.is_none());
    h.run_steps(1);
    let status = h.state().status().to_string();
    assert!(status.contains("cancelled"), "{status}");
    let kept = std::fs::read_dir(&dir).unwrap().count();
    assert!((2..40).contains(&kept), "{kept} frames kept");
    // Only whole frames: every file on disk is a complete picture.
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        assert_eq!(image::image_dimensions(&p).unwrap(), (96, 72), "{p:?}");
    }
    // The next export says what it keeps and renders only the rest (here: the first ten).
    export_window(&mut h, &dir);
    {
        let s = &mut h.state_mut().flame.anim_export.as_mut().unwrap().settings;
        s.width = 96;
        s.height = 72;
        s.last = (kept as f64 - 1.0).max(9.0);
    }
    h.run_steps(2);
    let status = run_export(&mut h, "Resume");
    let total = kept.max(10);
    assert!(
        status.contains(&format!(
            "{} frames rendered, {kept} on disk kept",
            total - kept
        )),
        "{status}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_mp4_is_made_through_ffmpeg_when_it_is_there() {
    if !ugnis::io::video::ffmpeg_available(std::path::Path::new("ffmpeg")) {
        eprintln!("ffmpeg is not on PATH: the .mp4 export is not tried");
        return;
    }
    let mut h = open("sierpinski.flame");
    h.state_mut().flame.make_rotation_loop(1.0, 40);
    h.run_steps(2);
    let mp4 = example("sierpinski.flame").with_file_name("loop-ffmpeg.mp4");
    let _ = std::fs::remove_file(&mp4);
    export_window(&mut h, &mp4);
    let status = run_export(&mut h, "Render");
    assert!(status.contains("video"), "{status}");
    let bytes = std::fs::read(&mp4).unwrap();
    assert!(bytes.len() > 100 && &bytes[4..8] == b"ftyp", "an MP4 file");
    assert_eq!(
        std::fs::read_dir(mp4.with_file_name("loop-ffmpeg.mp4.frames"))
            .unwrap()
            .count(),
        3
    );
}

#[test]
fn a_sound_decodes_in_the_background_then_its_curve_is_made() {
    let mut h = harness_sized(
        ugnis::app::Start::File(example("sierpinski.flame")),
        1280.0,
        1300.0,
    );
    timeline_with(&mut h, "zoom");
    // Eight seconds of a 60 Hz tone, louder in the second half.
    let rate = 22_050;
    let tone: Vec<f32> = (0..8 * rate)
        .map(|i| {
            let t = i as f32 / rate as f32;
            let a = if t < 4.0 { 0.05 } else { 0.8 };
            a * (2.0 * std::f32::consts::PI * 60.0 * t).sin()
        })
        .collect();
    let path = example("sierpinski.flame").with_file_name("beat.wav");
    std::fs::write(&path, ugnis::io::audio::wav_bytes(&tone, rate as u32)).unwrap();
    h.get_by_label("Sound…").click();
    h.run_steps(2);
    h.state_mut()
        .flame
        .timeline
        .sound_dialog
        .as_mut()
        .expect("Sound… opens its window")
        .path = Some(path);
    h.run_steps(1);
    h.get_by_label("Make curve").click();
    h.step();
    h.step();
    // The window says it is decoding (the file is read in the background) …
    assert!(h.state().flame.timeline.sound_job.is_some());
    assert!(h.query_by_label_contains("decoding").is_some());
    assert!(h.query_by_label("Cancel").is_some());
    // … then what follows the sound.
    wait_until(&mut h, |s| s.flame.timeline.sound_job.is_none());
    h.run_steps(2);
    // In the window (and the status bar).
    let said = |h: &Harness<'_, UgnisApp>| {
        h.state()
            .flame
            .timeline
            .sound_dialog
            .as_ref()
            .unwrap()
            .result
            .clone()
    };
    assert!(matches!(said(&h), Some(Ok(t)) if t.contains("follows beat.wav")));
    assert_eq!(h.query_all_by_label_contains("follows beat.wav").count(), 2);
    assert!(h.query_by_label_contains("decoding").is_none());
    assert!(!keys_of(&h, &ZOOM).is_empty(), "the curve is made");
    // A file that is no sound: the error is shown in the window.
    let bad = example("sierpinski.flame").with_file_name("noise.wav");
    std::fs::write(&bad, b"not a sound at all").unwrap();
    h.state_mut()
        .flame
        .timeline
        .sound_dialog
        .as_mut()
        .unwrap()
        .path = Some(bad);
    h.run_steps(1);
    h.get_by_label("Make curve").click();
    h.run_steps(2);
    wait_until(&mut h, |s| s.flame.timeline.sound_job.is_none());
    h.run_steps(2);
    assert!(h.query_by_label_contains("not a sound file").is_some());
    assert!(matches!(said(&h), Some(Err(_))));
}

/// The selected transform's map as the preview shows it at the timeline's frame.
fn shown_map(h: &Harness<'_, UgnisApp>) -> ugnis::flame::Affine {
    h.state().flame.shown_flame().xforms[0].coefs
}

/// Drag the first transform's triangle as shown at the frame from its centre by `by` points.
fn drag_shown(h: &mut Harness<'_, UgnisApp>, by: egui::Vec2) {
    let t = shown_map(h).triangle();
    let c = [
        (t[0][0] + t[1][0] + t[2][0]) / 3.0,
        (t[0][1] + t[1][1] + t[2][1]) / 3.0,
    ];
    let from = h.state().flame.editor.screen_from_world(c);
    drag(h, from, from + by);
}

#[test]
fn the_triangles_are_the_frames_and_a_drag_keys_the_turn_there() {
    let mut h = harness_sized(
        ugnis::app::Start::File(example("sierpinski.flame")),
        1280.0,
        1300.0,
    );
    // A rotation loop: every transform turns once over 40 frames.
    h.state_mut().flame.make_rotation_loop(1.0, 40);
    h.state_mut().flame.editor.selected = ugnis::app::Selected::Xform(0);
    h.state_mut().flame.timeline.frame = 10.0;
    h.run_steps(3);
    let turn = Target::Xform(XformRef::Index(0), XformParam::Rotate);
    let base = h.state().flame.doc().flame().xforms[0].coefs;
    let at10 = shown_map(&h);
    assert_ne!(at10.a, base.a, "turned a quarter at frame 10");
    // A move of the triangle drawn (the turned one: grabbing the base one's centre would
    // miss it) moves the base; the turn stays as keyed.
    let steps = h.state().flame.doc().undo_len();
    drag_shown(&mut h, egui::Vec2::new(20.0, 10.0));
    let moved = shown_map(&h);
    assert!(moved.e != at10.e, "the triangle at the frame moved");
    assert_eq!(
        (moved.a, moved.b, moved.c, moved.d),
        (at10.a, at10.b, at10.c, at10.d)
    );
    assert_eq!(keys_of(&h, &turn), vec![(0.0, 0.0), (40.0, 360.0)]);
    assert_eq!(h.state().flame.doc().undo_len(), steps + 1);
    // Rotate mode with Auto-key: the turn is keyed at the frame, the base map's shape kept.
    h.get_by_role_and_label(Role::Button, "Rotate").click();
    h.run_steps(2);
    drag_shown(&mut h, egui::Vec2::new(0.0, 40.0));
    let k = keys_of(&h, &turn);
    assert_eq!(k.len(), 3, "{k:?}");
    assert_eq!(k[1].0, 10.0);
    assert!(
        (k[1].1 - 90.0).abs() > 1.0,
        "the key at 10 turned on: {k:?}"
    );
    let b = h.state().flame.doc().flame().xforms[0].coefs;
    assert!(
        (b.a - base.a).abs() < 1e-9 && (b.d - base.d).abs() < 1e-9,
        "{b:?}"
    );
    // One undo step takes the key away.
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(keys_of(&h, &turn), vec![(0.0, 0.0), (40.0, 360.0)]);
    // Without Auto-key the base map turns, no key is made, and the triangle drawn is the
    // one dragged.
    h.state_mut().flame.timeline.auto_key = false;
    h.run_steps(1);
    drag_shown(&mut h, egui::Vec2::new(0.0, 40.0));
    assert_eq!(keys_of(&h, &turn), vec![(0.0, 0.0), (40.0, 360.0)]);
    let b = h.state().flame.doc().flame().xforms[0].coefs;
    assert!((b.a - base.a).abs() > 1e-3, "the base turned: {b:?}");
    // An edit while playing pauses playback at the frame shown.
    h.state_mut().flame.timeline.auto_key = true;
    h.key_press(Key::Space);
    h.run_steps(1);
    assert!(h.state().flame.timeline.playing());
    wait_until(&mut h, |a| a.flame.timeline.frame != 10.0);
    section(&mut h, "Settings");
    let z = h.state().flame.doc().flame().zoom;
    set_number(&mut h, "Zoom", z + 0.5);
    h.run_steps(2);
    assert!(
        !h.state().flame.timeline.playing(),
        "the edit paused playback"
    );
    let at = h.state().flame.timeline.frame;
    assert_eq!(h.state().flame.doc().flame().zoom, z + 0.5);
    std::thread::sleep(std::time::Duration::from_millis(100));
    h.run_steps(2);
    assert_eq!(h.state().flame.timeline.frame, at, "paused");
}
