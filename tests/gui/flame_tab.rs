//! The flame tab's panels and windows: gradients and the palette editor as single undo steps,
//! mutations, morphing, random batches and the variations filter, the flame settings, the
//! camera on the preview, the variation list and the first start's flame.

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers, Vec2};
use egui_kittest::kittest::Queryable;
use ugnis::app::Options;
use ugnis::app::{Start, UgnisApp};

use crate::{drag, example, harness, harness_sized, open, section, set_number};

#[test]
fn choosing_a_gradient_recolours_as_one_undo_step() {
    let mut h = open("sierpinski.flame");
    let before = h.state().flame.doc().flame().clone();
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    h.run_steps(2);
    h.get_by_label("glacier").click();
    h.run_steps(2);
    let f = h.state().flame.doc().flame();
    let glacier = ugnis::gradient::builtin_named("glacier").unwrap();
    assert_eq!(f.palette.colors, glacier.colors);
    assert_eq!(f.xforms, before.xforms, "only the colours change");
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame(), &before);
}

#[test]
fn random_batch_is_browsed_beside_the_file_and_kept_into_it() {
    let mut h = open("sierpinski.flame");
    let data = std::env::temp_dir().join(format!("ugnis-gui-data-{}", std::process::id()));
    h.state_mut().flame.data_dir = Some(data.clone());
    let file_flames = h.state().flame.doc().flames.clone();
    h.key_press_modifiers(Modifiers::COMMAND, Key::B);
    let t = std::time::Instant::now();
    while h.state().flame.batch.as_ref().is_none() {
        assert!(t.elapsed().as_secs() < 120, "no batch after 2 minutes");
        std::thread::sleep(std::time::Duration::from_millis(50));
        h.step();
    }
    h.run_steps(2);
    let batch = h.state().flame.batch.as_ref().unwrap().flames.clone();
    assert_eq!(batch.len(), 100);
    assert_eq!(batch[1].name, "random-002");
    // Kept as the last batch in the data directory, and the open file is untouched.
    let saved = ugnis::io::read_flames(&data.join("last-batch.fla"), &Default::default())
        .unwrap()
        .value;
    assert_eq!(saved.len(), 100);
    assert_eq!(h.state().flame.file.flames, file_flames);
    assert!(!h.state().flame.file.dirty);

    // A click loads a batch flame into the editor.
    h.get_by_label("random-002").click();
    h.run_steps(2);
    assert!(h.state().flame.viewing_batch());
    assert_eq!(h.state().flame.doc().flame().name, "random-002");
    // Keep copies it (here the first visible one, random-001) into the open file.
    h.get_all_by_label("Keep").next().unwrap().click();
    h.run_steps(2);
    assert!(!h.state().flame.viewing_batch());
    let f = &h.state().flame.doc();
    assert_eq!(f.flames.len(), file_flames.len() + 1);
    assert_eq!(f.flame().name, "random-001");
    assert!(f.dirty);
    // Undo in the file removes it again.
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flames, file_flames);
    let _ = std::fs::remove_dir_all(&data);
}

#[test]
fn mutation_window_makes_a_mutant_current_and_undo_returns() {
    let mut h = open("sierpinski.flame");
    let before = h.state().flame.doc().flame().clone();
    h.key_press_modifiers(Modifiers::COMMAND, Key::U);
    h.run_steps(2);
    assert!(h.state().flame.mutations.open);
    let mutants = h.state().flame.mutations.mutants.clone();
    assert_eq!(mutants.len(), 8);
    assert!(mutants.iter().all(|m| m.xforms != before.xforms));
    h.get_by_role_and_label(Role::Button, "+ transform").click();
    h.run_steps(2);
    let now = h.state().flame.doc().flame().clone();
    assert_eq!(now.xforms.len(), before.xforms.len() + 1);
    assert_eq!(now, mutants[3]);
    // The grid moves on: new mutants around the new centre.
    assert_ne!(h.state().flame.mutations.mutants, mutants);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame(), &before);
}

#[test]
fn morph_plays_in_betweens_to_the_next_flame_without_editing() {
    let mut h = harness(Start::File(example("gallery.fla")));
    assert_eq!(h.state().flame.doc().flames.len(), 4);
    let before = h.state().flame.doc().flame().clone();
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::M);
    h.run_steps(2);
    let m = h
        .state()
        .flame
        .morph
        .as_ref()
        .expect("Ctrl+Shift+M starts the morph");
    assert_eq!(m.frames.len(), ugnis::app::MORPH_FRAMES);
    // The first frame is the current flame: its xforms, then the next flame's extra ones
    // faded out to weight 0.
    let n0 = before.xforms.len();
    assert!(m.frames[0].xforms[..n0] == before.xforms[..]);
    assert!(m.frames[0].xforms[n0..].iter().all(|x| x.weight == 0.0));
    let next = &h.state().flame.doc().flames[1];
    let last = &m.frames[m.frames.len() - 1];
    assert_eq!(
        last.xforms.len(),
        next.xforms.len().max(before.xforms.len())
    );
    assert_eq!(last.palette, next.palette);
    // The preview plays the frames (each waits for the previous one to be shown).
    let mut seen = 0;
    for _ in 0..400 {
        h.run_steps(1);
        seen = seen.max(h.state().flame.morph.as_ref().unwrap().index);
        if seen >= 3 {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(25));
    }
    assert!(seen >= 3, "the morph did not advance");
    assert!(h.state().status().contains("orchid -> ember-swirl"));
    // The document is untouched; any edit stops the morph.
    assert!(h.state().flame.doc().flame() == &before);
    assert!(!h.state().flame.doc().dirty);
    h.key_press_modifiers(Modifiers::COMMAND, Key::R);
    h.run_steps(3);
    assert!(h.state().flame.morph.is_none());
    // A single flame has nothing to morph to.
    let mut h = open("sierpinski.flame");
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::M);
    h.run_steps(2);
    assert!(h.state().flame.morph.is_none());
    assert!(h.state().status().contains("two or more flames"));
}

#[test]
fn one_drag_of_the_colour_slider_is_one_undo_step() {
    let mut h = open("sierpinski.flame");
    let before = h.state().flame.doc().undo_len();
    let c0 = h.state().flame.doc().flame().xforms[0].color;
    let r = h.get_by_role_and_label(Role::Slider, "Colour").rect();
    let a = r.left_center() + Vec2::new(4.0, 0.0);
    let b = r.right_center() - Vec2::new(4.0, 0.0);
    drag(&mut h, a, b);
    h.run_steps(2);
    let c1 = h.state().flame.doc().flame().xforms[0].color;
    assert!(c1 > c0 + 0.5, "{c0} → {c1}");
    assert_eq!(h.state().flame.doc().undo_len(), before + 1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame().xforms[0].color, c0);
}

#[test]
fn find_narrows_the_variation_list_with_all_ticked() {
    let mut h = open("sierpinski.flame");
    section(&mut h, "Variations");
    h.get_by_role_and_label(Role::CheckBox, "all").click();
    h.run_steps(2);
    assert!(
        h.query_by_label("spherical").is_some(),
        "all lists every name"
    );
    h.get_by_role_and_label(Role::TextInput, "Find").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "Find")
        .type_text("julian");
    h.run_steps(3);
    assert!(
        h.query_by_role_and_label(Role::SpinButton, "julian")
            .is_some()
    );
    assert!(h.query_by_label("pre_julian").is_some());
    assert!(h.query_by_label("spherical").is_none(), "Find narrows");
    // A weight typed into a listed name adds it.
    set_number(&mut h, "julian", 0.5);
    let x = &h.state().flame.doc().flame().xforms[0];
    let j = ugnis::flame::variations::by_name("julian").unwrap();
    assert!(x.vars.iter().any(|v| v.id == j && v.weight == 0.5));
}

#[test]
fn the_palette_rule_is_chosen_in_the_flame_settings() {
    use ugnis::flame::PaletteIndex;
    // Tall enough for the whole Settings grid to be on screen.
    let mut h = harness_sized(Start::File(example("sierpinski.flame")), 1280.0, 1600.0);
    section(&mut h, "Settings");
    assert_eq!(
        h.state().flame.doc().flame().palette_index,
        PaletteIndex::Flam3
    );
    // The rule has a row of its own, its label at the left of its control.
    let label = h.get_by_role_and_label(Role::Label, "Rule").rect();
    let combo = h.get_by_role_and_label(Role::ComboBox, "Rule").rect();
    assert!((label.center().y - combo.center().y).abs() < 4.0);
    assert!(label.right() < combo.left());
    h.get_by_role_and_label(Role::ComboBox, "Rule").click();
    h.run_steps(3);
    h.get_by_label("as Fractorium").click();
    h.run_steps(2);
    assert_eq!(
        h.state().flame.doc().flame().palette_index,
        PaletteIndex::Fractorium
    );
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(
        h.state().flame.doc().flame().palette_index,
        PaletteIndex::Flam3
    );
}

#[test]
fn the_palette_editor_adjusts_the_gradient_as_one_undo_step() {
    let mut h = open("sierpinski.flame");
    let before = h.state().flame.doc().flame().palette.clone();
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::G);
    h.run_steps(3);
    assert!(h.state().flame.palette_editor.open);
    set_number(&mut h, "Saturation", -1.0);
    let g = &h.state().flame.doc().flame().palette;
    assert!(
        g.colors
            .iter()
            .all(|c| (c[0] - c[1]).abs() < 1e-9 && (c[1] - c[2]).abs() < 1e-9)
    );
    assert_ne!(g.colors, before.colors);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(3);
    assert_eq!(h.state().flame.doc().flame().palette.colors, before.colors);
}

#[test]
fn the_camera_moves_with_the_mouse_on_the_preview() {
    let mut h = open("sierpinski.flame");
    let f0 = h.state().flame.doc().flame().clone();
    let r = h.state().flame.preview_rect.unwrap();
    let k = f0.ppu() * r.width() as f64 / f0.width as f64;
    // Drag: the centre moves against the pointer by the dragged distance in world units.
    let a = r.center();
    drag(&mut h, a, a + Vec2::new(40.0, 0.0));
    let f1 = h.state().flame.doc().flame().clone();
    let (s, c) = f0.rotate.to_radians().sin_cos();
    let dx = 40.0 / k;
    assert!(
        (f1.center[0] - (f0.center[0] - c * dx)).abs() < 1e-6,
        "{:?}",
        f1.center
    );
    assert!((f1.center[1] - (f0.center[1] + s * dx)).abs() < 1e-6);
    assert_eq!(h.state().flame.doc().undo_len(), 1);
    // Wheel: zooms in at the pointer, one undo step.
    h.hover_at(a);
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: Vec2::new(0.0, 60.0),
        modifiers: Modifiers::NONE,
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
    });
    h.run_steps(30);
    let f2 = h.state().flame.doc().flame().clone();
    assert!(f2.zoom > f1.zoom, "{} → {}", f1.zoom, f2.zoom);
    assert_eq!(h.state().flame.doc().undo_len(), 2);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame(), &f0);
}

#[test]
fn the_first_start_shows_a_colourful_flame() {
    use ugnis::app::{colour_share, colourfulness};
    for seed in 1..=3u64 {
        let app = UgnisApp::new(Options::default(), Start::Random(seed), None);
        let f = app.flame.doc().flame();
        assert!(colourfulness(&f.palette) >= 0.45, "{}", f.palette.name);
        assert!(ugnis::flame::random::passes_render_test(f));
        let share = colour_share(f);
        assert!(share >= 0.3, "seed {seed}: {share}");
    }
}

#[test]
fn random_flames_use_the_variations_filter() {
    let mut h = open("sierpinski.flame");
    h.state_mut().options.variation_filter = vec!["julia".into(), "bubble".into()];
    h.get_by_role_and_label(Role::Button, "Tools").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Random variations")
        .click();
    h.run_steps(2);
    h.get_by_label("From the variations filter").click();
    h.run_steps(2);
    assert!(h.state().options.use_variation_filter);
    h.key_press_modifiers(Modifiers::COMMAND, Key::R);
    h.run_steps(2);
    use ugnis::flame::variations;
    let ok = [
        variations::by_name("julia").unwrap(),
        variations::by_name("bubble").unwrap(),
        variations::LINEAR,
    ];
    for x in &h.state().flame.doc().flame().xforms {
        for v in &x.vars {
            assert!(ok.contains(&v.id), "{}", variations::info(v.id).name);
        }
    }
    // The filter window ticks and unticks names.
    h.state_mut().flame.variation_filter.open = true;
    h.run_steps(2);
    h.get_by_role_and_label(Role::TextInput, "Find").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "Find")
        .type_text("swirl");
    h.run_steps(3);
    h.get_by_role_and_label(Role::CheckBox, "swirl").click();
    h.run_steps(2);
    assert!(
        h.state()
            .options
            .variation_filter
            .contains(&"swirl".to_string())
    );
}

#[test]
fn every_flame_setting_has_a_control_including_the_3d_camera() {
    let mut h = harness_sized(Start::File(example("sierpinski.flame")), 1280.0, 1800.0);
    section(&mut h, "Settings");
    h.get_by_label("3-D camera").click();
    h.run_steps(2);
    set_number(&mut h, "Pitch (°)", 30.0);
    set_number(&mut h, "Yaw (°)", -45.0);
    set_number(&mut h, "Perspective", 0.2);
    set_number(&mut h, "Z position", 0.5);
    set_number(&mut h, "Depth of field", 0.1);
    set_number(&mut h, "Blur curve", 0.3);
    set_number(&mut h, "Supersample", 2.0);
    set_number(&mut h, "Filter radius", 1.2);
    set_number(&mut h, "DE radius", 6.0);
    set_number(&mut h, "DE minimum", 0.5);
    set_number(&mut h, "DE curve", 0.6);
    h.get_by_role_and_label(Role::ComboBox, "Filter shape")
        .click();
    h.run_steps(2);
    h.get_by_label("mitchell").click();
    h.run_steps(2);
    let f = h.state().flame.doc().flame().clone();
    let c = f.cam;
    assert!((c.pitch - 30f64.to_radians()).abs() < 1e-12);
    assert!((c.yaw + 45f64.to_radians()).abs() < 1e-12);
    assert_eq!(
        (c.perspective, c.zpos, c.dof, c.blur_curve),
        (0.2, 0.5, 0.1, 0.3)
    );
    assert_eq!(f.supersample, 2);
    assert_eq!(f.filter, 1.2);
    assert_eq!(f.filter_shape.name(), "mitchell");
    assert_eq!(
        (f.estimator_radius, f.estimator_minimum, f.estimator_curve),
        (6.0, 0.5, 0.6)
    );
    // Saved and read back as they are.
    let path = example("sierpinski.flame").with_file_name("settings.flame");
    assert!(h.state_mut().flame.save_to(&path));
    let back = ugnis::io::read_flames(&path, &Default::default())
        .unwrap()
        .value
        .remove(0);
    assert!((back.cam.pitch - c.pitch).abs() < 1e-9);
    assert_eq!(back.filter_shape, f.filter_shape);
    assert_eq!(back.estimator_minimum, 0.5);
    // Each change is one undo step.
    for _ in 0..12 {
        h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
        h.run_steps(1);
    }
    assert!(h.state().flame.doc().flame().cam.is_flat());
}
