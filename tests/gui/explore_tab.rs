//! The Explore tab: every topic's numbers, the Koch curve, the L-system editor and files, the
//! chaos game, fractal interpolation, box counting (of the flame, an image and the
//! escape-time boundary), typed limits, and what opens in the flame and scene tabs.

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::Options;
use ugnis::app::{Start, UgnisApp};

use crate::{drag, example, harness, open, wait_until};

fn explore_tab() -> Harness<'static, UgnisApp> {
    let mut h = open("sierpinski.flame");
    h.get_by_role_and_label(Role::Button, "Explore").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Explore);
    h
}

/// Choose a topic in the list at the left (the first widget with its name: the list is drawn
/// before the topic's heading).
fn explore_topic(h: &mut Harness<'_, UgnisApp>, name: &str) {
    h.get_all_by_label(name).next().unwrap().click();
    h.run_steps(3);
}

#[test]
fn explore_every_topic_shows_its_numbers() {
    use ugnis::app::Topic;
    let mut h = explore_tab();
    // The default topic: the Koch curve at step 3.
    assert_eq!(h.state().explore.topic, Topic::Classic);
    assert!(h.query_by_label("Similarity dimension: 1.26186").is_some());
    explore_topic(&mut h, "Chaos game");
    assert_eq!(h.state().explore.topic, Topic::ChaosGame);
    assert!(h.query_by_label_contains("Points plotted: ").is_some());
    assert!(h.query_by_label("Similarity dimension: 1.58496").is_some());
    explore_topic(&mut h, "L-systems");
    assert_eq!(h.state().explore.topic, Topic::LSystems);
    // The first preset: the Koch curve at order 4, 4⁴ segments.
    assert!(h.query_by_label("Segments: 256").is_some());
    assert!(h.query_by_label("Segments drawn here: 256").is_some());
    explore_topic(&mut h, "Fractal interpolation");
    // Equal spacing: D = 1 + log Σ|d| / log N with d = (0.5, −0.5, 0.5).
    let d = 1.0 + 1.5f64.ln() / 3f64.ln();
    assert!(
        h.query_by_label(&format!("Dimension D = {d:.5}")).is_some(),
        "{d}"
    );
    explore_topic(&mut h, "Julia by inverse iteration");
    assert!(
        h.query_by_label("c is in the Mandelbrot set: J_c is connected")
            .is_some()
    );
    assert!(h.state().explore.julia.covered > 1000, "no preimages drawn");
    explore_topic(&mut h, "Lorenz attractor");
    assert!(
        h.query_by_label("Equilibrium (8.4853, 8.4853, 27.0000)")
            .is_some()
    );
    // Two starts 1e-9 apart are more than 1 apart by t = 40.
    let l = &h.state().explore.lorenz;
    assert!(l.distance > 1.0 && l.apart_at.is_some_and(|t| t > 20.0 && t < 40.0));
    explore_topic(&mut h, "Dimension");
    assert!(h.query_by_label("Similarity dimension: 1.26186").is_some());
    assert!(
        h.query_by_label_contains("D = 1 − slope = 1.3712")
            .is_some()
    );
    // Box counting of the Sierpinski preset runs in the background.
    let t = std::time::Instant::now();
    while h.state().explore.dimension.result.is_none() {
        assert!(t.elapsed() < std::time::Duration::from_secs(60));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    let dim = h.state().explore.dimension.result.as_ref().unwrap();
    let d = dim.count.dimension().unwrap();
    assert!((d - 1.585).abs() < 0.05, "{d}");
    assert!(
        h.query_by_label_contains("Box-counting dimension ≈ ")
            .is_some()
    );
}

#[test]
fn explore_koch_step_3_has_64_segments_of_total_length_four_thirds_cubed() {
    use ugnis::explore::classic::Construction;
    let mut h = explore_tab();
    h.state_mut().explore.classic.construction = Construction::Cantor;
    h.get_by_label("Koch curve").click();
    h.run_steps(2);
    h.state_mut().explore.classic.step = 3;
    h.run_steps(2);
    assert_eq!(
        h.state().explore.classic.construction,
        Construction::KochCurve
    );
    assert!(h.query_by_label("Segments: 64 = 4^n").is_some());
    let len = (4.0f64 / 3.0).powi(3);
    assert!(
        h.query_by_label(&format!("Length: {len:.6} = (4/3)^n"))
            .is_some()
    );
    assert_eq!(format!("{len:.6}"), "2.370370");
    // Another construction, same step.
    h.get_by_label("Sierpinski carpet").click();
    h.run_steps(2);
    assert!(h.query_by_label("Squares: 512 = 8^n").is_some());
    assert!(h.query_by_label("Similarity dimension: 1.89279").is_some());
}

#[test]
fn explore_lsystem_editor_shows_a_bad_rule_with_its_line() {
    let mut h = explore_tab();
    explore_topic(&mut h, "L-systems");
    h.state_mut()
        .explore
        .lsystem
        .set_text("Bad {\n  Angle 6\n  Axiom F\n  +=F+F\n}\n");
    h.run_steps(2);
    let e = h.state().explore.lsystem.error.clone().unwrap();
    assert!(
        e.starts_with("Line 4, column 3: '+' is a turtle command"),
        "{e}"
    );
    assert!(h.query_by_label(&e).is_some());
    assert!(h.query_by_label("(nothing drawn)").is_some());
    // What Fractint would ignore is drawn without, and shown with its line.
    h.state_mut()
        .explore
        .lsystem
        .set_text("Stray {\n  Angle 6\n  Axiom F\n  F=F+@F\n}\n");
    h.run_steps(2);
    let e = h.state().explore.lsystem.error.clone().unwrap();
    assert!(
        e.starts_with("Line 4, column 5: in 'Stray', ignored"),
        "{e}"
    );
    assert!(h.query_by_label("Segments: 16").is_some());
    // Typing in the editor redraws: a good rule again.
    h.state_mut()
        .explore
        .lsystem
        .set_text("Good {\n  Angle 6\n  Axiom F\n  F=F+F--F+F\n}\n");
    h.run_steps(2);
    assert!(h.state().explore.lsystem.error.is_none());
    assert!(h.query_by_label("Segments: 256").is_some());
    let node = h.get_by_label("L-system text");
    node.focus();
    h.run_steps(1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.run_steps(1);
    h.get_by_label("L-system text")
        .type_text("T {\n Angle 4\n Axiom F\n F=F+F-F-FF+F+F-F\n}");
    h.run_steps(2);
    // 8 segments per F: 8⁴ at order 4.
    assert!(
        h.query_by_label("Segments: 4096").is_some(),
        "{:?} {:?}",
        h.state().explore.lsystem.text,
        h.state().explore.lsystem.error
    );
}

#[test]
fn explore_lsystem_over_the_live_cap_says_so_and_exports() {
    let mut h = explore_tab();
    explore_topic(&mut h, "L-systems");
    h.state_mut()
        .explore
        .lsystem
        .set_text("Koch {\n  Angle 6\n  Axiom F\n  F=F+F--F+F\n}\n");
    h.state_mut().explore.lsystem.order = 10;
    h.run_steps(3);
    let note = h.state().explore.lsystem.note.clone().unwrap();
    assert!(note.contains("1048576 segments"), "{note}");
    assert_eq!(h.state().explore.lsystem.drawn, 0);
    // Order 3 is drawn; its SVG export has one path point per segment.
    h.state_mut().explore.lsystem.order = 3;
    h.run_steps(2);
    assert!(h.state().explore.lsystem.note.is_none());
    assert_eq!(h.state().explore.lsystem.drawn, 64);
    let out = example("sierpinski.flame").with_file_name("koch.svg");
    h.state_mut().explore.lsystem.export(out.clone());
    let t = std::time::Instant::now();
    while !h.state().status().starts_with("Exported") {
        assert!(t.elapsed() < std::time::Duration::from_secs(30));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(
        svg.starts_with("<?xml") || svg.starts_with("<svg"),
        "{}",
        &svg[..40]
    );
}

#[test]
fn explore_chaos_game_adds_points_over_frames_and_stops_when_paused() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Chaos game");
    let a = h.state().explore.chaos.plotted;
    h.run_steps(5);
    let b = h.state().explore.chaos.plotted;
    assert!(b > a, "{a} -> {b}");
    let speed = h.state().explore.chaos.speed as u64;
    assert_eq!(speed, 20);
    assert_eq!((b - a) % speed, 0);
    assert!(h.query_by_label(&format!("Points plotted: {b}")).is_some());
    h.get_by_label("Pause").click();
    h.run_steps(2);
    let c = h.state().explore.chaos.plotted;
    h.run_steps(5);
    assert_eq!(
        h.state().explore.chaos.plotted,
        c,
        "paused, yet points were added"
    );
    h.get_by_label("Resume").click();
    h.run_steps(3);
    assert!(h.state().explore.chaos.plotted > c);
    h.get_by_label("Reset").click();
    h.run_steps(1);
    assert!(h.state().explore.chaos.plotted <= 2 * speed);
}

#[test]
fn explore_chaos_preset_opens_in_the_flame_tab_asking_about_unsaved_changes() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Chaos game");
    h.state_mut().flame.file.dirty = true;
    h.get_by_label("Open in Flame tab").click();
    h.run_steps(3);
    // The question comes first; Cancel keeps everything.
    h.get_by_label("Cancel").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Explore);
    assert_eq!(h.state().flame.doc().name, "sierpinski");
    h.get_by_label("Open in Flame tab").click();
    h.run_steps(3);
    h.get_by_label("Discard").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Flame);
    let f = h.state().flame.doc().flame();
    assert_eq!(f.xforms.len(), 3);
    assert!((f.xforms[0].coefs.a - 0.5).abs() < 1e-12);
}

#[test]
fn explore_fif_dimension_follows_the_vertical_scalings() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Fractal interpolation");
    let label = |d: f64| format!("Dimension D = {d:.5}");
    assert!(
        h.query_by_label(&label(1.0 + 1.5f64.ln() / 3f64.ln()))
            .is_some()
    );
    h.state_mut().explore.fif.set_scaling(1, 0.9);
    h.run_steps(2);
    let d = 1.0 + 1.9f64.ln() / 3f64.ln();
    assert!(h.query_by_label(&label(d)).is_some(), "{d}");
    assert!((h.state().explore.fif.fif.dimension() - d).abs() < 1e-9);
    h.get_by_label("All d = 0").click();
    h.run_steps(2);
    assert!(h.query_by_label(&label(1.0)).is_some());
    // A scaling of 1 is refused with the engine's reason.
    h.state_mut().explore.fif.set_scaling(2, 1.0);
    h.run_steps(2);
    assert!(
        h.query_by_label_contains("must lie strictly between")
            .is_some()
    );
}

#[test]
fn explore_lsystem_file_entries_are_all_selectable() {
    let mut h = explore_tab();
    explore_topic(&mut h, "L-systems");
    let path = example("sierpinski.flame").with_file_name("two.l");
    std::fs::write(
        &path,
        "Koch {\r\n  Angle 6\r\n  Axiom F\r\n  F=F+F--F+F\r\n}\r\n\
         Square { ; quadratic Koch island\r\n  Angle 4\r\n  Axiom F+F+F+F\r\n  F=F+F-F-FF+F+F-F\r\n}\r\n",
    )
    .unwrap();
    let n = h.state_mut().explore.lsystem.open(&path);
    assert!(format!("{n:?}").contains("2 entries"), "{n:?}");
    h.state_mut().explore.lsystem.order = 1;
    h.run_steps(3);
    assert_eq!(h.state().explore.lsystem.entries.len(), 2);
    assert!(h.query_by_label("Segments: 4").is_some());
    h.state_mut().explore.lsystem.choose_entry(1);
    h.run_steps(3);
    assert_eq!(h.state().explore.lsystem.system().unwrap().name, "Square");
    // Four sides of eight segments each.
    assert!(h.query_by_label("Segments: 32").is_some());
    assert_eq!(h.state().explore.lsystem.drawn, 32);
}

#[test]
fn explore_menger_sponge_opens_in_the_scene_tab() {
    let mut h = explore_tab();
    h.get_by_label("Open in Scene tab").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Scene);
    assert_eq!(h.state().scene.scene.objects.len(), 1);
    assert!(h.state().status().contains("Menger sponge, step 2"));
}

#[test]
fn explore_a_typed_number_out_of_range_is_refused_with_its_limits() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Julia by inverse iteration");
    h.get_by_label("c real part").click();
    h.run_steps(1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.get_by_label("c real part").type_text("5");
    h.key_press(Key::Enter);
    h.run_steps(3);
    assert_eq!(
        h.state().explore.julia.c[0],
        2.0,
        "brought back to the limit"
    );
    assert!(
        h.query_by_label("Re c is 5; it must be between -2 and 2")
            .is_some()
    );
}

#[test]
fn explore_fif_points_are_dragged_and_added_with_the_mouse() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Fractal interpolation");
    let p1 = h.state().explore.fif.fif.points()[1];
    let from = h.state().explore.fif.screen_of(p1).unwrap();
    let target = [p1[0], p1[1] + 0.5];
    let to = h.state().explore.fif.screen_of(target).unwrap();
    drag(&mut h, from, to);
    let q = h.state().explore.fif.fif.points()[1];
    assert!(
        (q[0] - target[0]).abs() < 0.01 && (q[1] - target[1]).abs() < 0.01,
        "{q:?}"
    );
    // A click away from the points adds one between its neighbours along x.
    let at = h.state().explore.fif.screen_of([0.5, -0.5]).unwrap();
    h.hover_at(at);
    h.step();
    h.get_by_label("Data points: 4");
    h.drag_at(at);
    h.step();
    h.drop_at(at);
    h.run_steps(3);
    let pts = h.state().explore.fif.fif.points().to_vec();
    assert_eq!(pts.len(), 5);
    assert!(
        (pts[2][0] - 0.5).abs() < 0.01 && (pts[2][1] + 0.5).abs() < 0.01,
        "{pts:?}"
    );
    assert_eq!(h.state().explore.fif.fif.scalings().len(), 4);
    assert!(h.query_by_label("Data points: 5").is_some());
}

#[test]
fn explore_box_counting_of_the_current_flame() {
    use ugnis::app::BoxSource;
    // The flame tab holds the Sierpinski triangle as a flame (no symmetry transforms).
    let ifs = ugnis::explore::ifs::presets::kovacs_sierpinski();
    let flame = ifs.to_flame(&Options::default().new_flame());
    let mut h = harness(Start::Flames(vec![flame]));
    h.get_by_role_and_label(Role::Button, "Explore").click();
    h.run_steps(3);
    explore_topic(&mut h, "Dimension");
    // Wait for the automatic count of the first preset, then count the flame tab's flame.
    wait_until(&mut h, |a| {
        !a.explore.dimension.busy() && a.explore.dimension.result.is_some()
    });
    h.state_mut().explore.dimension.source = BoxSource::Flame;
    h.state_mut().explore.dimension.points = 300_000.0;
    h.run_steps(1);
    h.get_by_label("Count boxes").click();
    h.run_steps(1);
    wait_until(&mut h, |a| {
        a.explore
            .dimension
            .result
            .as_ref()
            .is_some_and(|r| r.source.contains("flame"))
    });
    let r = h.state().explore.dimension.result.clone().unwrap();
    assert_eq!(r.count.samples, 300_000);
    // log 3 / log 2.
    let d = r.count.dimension().unwrap();
    assert!((d - 1.585).abs() < 0.06, "{d}");
    assert!(h.state().status().contains("Box counting of the flame"));
}

#[test]
fn explore_box_counting_of_an_image_file() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Dimension");
    // A white square on black: dimension 2.
    let path = example("sierpinski.flame").with_file_name("square.png");
    let img = image::RgbImage::from_fn(512, 512, |x, y| {
        let inside = (64..448).contains(&x) && (64..448).contains(&y);
        image::Rgb(if inside { [255; 3] } else { [0; 3] })
    });
    img.save(&path).unwrap();
    h.state_mut().explore.dimension.count_image(&path);
    let t = std::time::Instant::now();
    while h
        .state()
        .explore
        .dimension
        .result
        .as_ref()
        .is_none_or(|r| r.source != "square.png")
    {
        assert!(t.elapsed() < std::time::Duration::from_secs(60));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    let r = h.state().explore.dimension.result.clone().unwrap();
    assert_eq!(r.count.samples, 384 * 384);
    let d = r.count.dimension().unwrap();
    assert!((d - 2.0).abs() < 0.05, "{d}");
    assert!(h.query_by_label("square.png: 147456 samples").is_some());
}

#[test]
fn explore_box_counting_of_the_escape_time_boundary() {
    use ugnis::app::BoxSource;
    use ugnis::escape::{C, EscapeDoc, Family};
    let mut h = explore_tab();
    // The Julia set of z² + 0 is the unit circle: its boundary has dimension 1.
    let mut doc = EscapeDoc::new(Family::Julia {
        power: 2,
        c: C { re: 0.0, im: 0.0 },
    });
    doc.view = ugnis::escape::View::new([0.0, 0.0], 1.2);
    h.state_mut().escape.doc = doc;
    explore_topic(&mut h, "Dimension");
    wait_until(&mut h, |a| {
        !a.explore.dimension.busy() && a.explore.dimension.result.is_some()
    });
    h.state_mut().explore.dimension.source = BoxSource::Escape;
    h.run_steps(1);
    h.get_by_label("Count boxes").click();
    h.run_steps(1);
    wait_until(&mut h, |a| {
        a.explore
            .dimension
            .result
            .as_ref()
            .is_some_and(|r| r.source.contains("escape-time"))
    });
    let d = h
        .state()
        .explore
        .dimension
        .result
        .as_ref()
        .unwrap()
        .count
        .dimension()
        .unwrap();
    assert!((d - 1.0).abs() < 0.1, "{d}");
}
