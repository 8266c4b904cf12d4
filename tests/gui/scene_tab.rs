//! The scene tab: orbiting the camera, moving lights and changing textures, ray casting a
//! quaternion Julia set, and a scene saved and read back.

use std::path::Path;

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers, Pos2, Vec2};
use egui_kittest::kittest::Queryable;
use ugnis::app::Start;

use crate::{drag, harness, open};

#[test]
fn scene_tab_orbits_moves_lights_and_changes_textures() {
    let mut h = open("sierpinski.flame");
    h.get_by_role_and_label(Role::Button, "Scene").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Scene);
    let cam0 = h.state().scene.scene.camera;
    let light0 = h.state().scene.scene.lights[0].position;
    let p = Pos2::new(800.0, 400.0);
    drag(&mut h, p, p + Vec2::new(40.0, -20.0));
    let cam1 = h.state().scene.scene.camera;
    assert!(
        (cam1.azimuth_deg - (cam0.azimuth_deg - 12.0)).abs() < 3.0,
        "{cam1:?}"
    );
    assert!(cam1.polar_deg > cam0.polar_deg);
    assert_eq!(h.state().scene.scene.lights[0].position, light0);
    // Ctrl+drag moves the selected light, not the camera.
    let cam_before = h.state().scene.scene.camera;
    h.hover_at(p);
    h.step();
    h.event_modifiers(
        egui::Event::PointerButton {
            pos: p,
            button: egui::PointerButton::Primary,
            pressed: true,
            modifiers: Modifiers::COMMAND,
        },
        Modifiers::COMMAND,
    );
    for k in 1..=4 {
        h.event_modifiers(
            egui::Event::PointerMoved(p + Vec2::new(10.0 * k as f32, 0.0)),
            Modifiers::COMMAND,
        );
        h.step();
    }
    h.event_modifiers(
        egui::Event::PointerButton {
            pos: p + Vec2::new(40.0, 0.0),
            button: egui::PointerButton::Primary,
            pressed: false,
            modifiers: Modifiers::COMMAND,
        },
        Modifiers::COMMAND,
    );
    h.run_steps(2);
    assert_ne!(
        h.state().scene.scene.lights[0].position,
        light0,
        "the light moved"
    );
    assert_eq!(
        h.state().scene.scene.camera,
        cam_before,
        "the camera stayed"
    );
    // A procedural texture replaces the jug's texture (made in the background).
    let flame = h.state().flame.doc().flame().clone();
    let esc = h.state().escape.doc.clone();
    h.state_mut()
        .scene
        .set_source(ugnis::app::TextureSource::Checker, &flame, &esc);
    let t = std::time::Instant::now();
    while h
        .state()
        .scene
        .texture_names
        .iter()
        .all(|n| n != "(checker)")
    {
        assert!(t.elapsed().as_secs() < 30);
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.step();
    }
    let tex = h.state().scene.scene.objects[0].texture.unwrap();
    assert_eq!(h.state().scene.texture_names[tex], "(checker)");
}

#[test]
fn scene_tab_switches_to_ray_casting_and_edits_a_quaternion_julia_set() {
    let mut h = harness(Start::Random(3));
    h.get_by_role_and_label(Role::Button, "Scene").click();
    h.run_steps(3);
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/quaternion-julia.toml");
    assert!(h.state_mut().scene.open(&file));
    h.run_steps(3);
    use ugnis::surface::{Geometry, Renderer};
    let renderer0 = h.state().scene.scene.renderer;
    // The renderer switch.
    h.get_by_role_and_label(Role::ComboBox, "Renderer").click();
    h.run_steps(2);
    let other = if renderer0 == Renderer::RayCast {
        "z-buffer"
    } else {
        "ray casting"
    };
    h.get_by_label(other).click();
    h.run_steps(3);
    assert_ne!(h.state().scene.scene.renderer, renderer0);
    // The quaternion's c, typed into its field.
    let q0 = match &h.state().scene.scene.objects[0].geometry {
        Geometry::QuaternionJulia(q) => *q,
        g => panic!("expected a quaternion Julia set, got {g:?}"),
    };
    h.get_by_label("c (j)").click();
    h.run_steps(1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.get_by_label("c (j)").type_text("0.3");
    h.key_press(Key::Enter);
    h.run_steps(3);
    let Geometry::QuaternionJulia(q1) = &h.state().scene.scene.objects[0].geometry else {
        unreachable!()
    };
    assert_eq!(q1.c[2], 0.3);
    assert_eq!(
        (q1.c[0], q1.c[1], q1.iterations),
        (q0.c[0], q0.c[1], q0.iterations)
    );
    // Both survive a save and reopen.
    let dir = std::env::temp_dir().join(format!("ugnis-gui-q-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("q.toml");
    let text = h.state().scene.scene_file(&out).unwrap();
    std::fs::write(&out, text).unwrap();
    let l = ugnis::io::scene::read(&out).unwrap();
    assert_eq!(l.scene.renderer, h.state().scene.scene.renderer);
    let Geometry::QuaternionJulia(q2) = &l.scene.objects[0].geometry else {
        unreachable!()
    };
    assert_eq!(q2.c[2], 0.3);
}

#[test]
fn a_scene_saves_and_reads_back() {
    let mut h = open("sierpinski.flame");
    h.get_by_role_and_label(Role::Button, "Scene").click();
    h.run_steps(3);
    let flame = h.state().flame.doc().flame().clone();
    let esc = h.state().escape.doc.clone();
    h.state_mut()
        .scene
        .set_source(ugnis::app::TextureSource::Checker, &flame, &esc);
    let t = std::time::Instant::now();
    while !h
        .state()
        .scene
        .texture_names
        .iter()
        .any(|n| n == "(checker)")
    {
        assert!(t.elapsed().as_secs() < 30);
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.step();
    }
    h.state_mut().scene.orbit(Vec2::new(30.0, 10.0));
    let dir = std::env::temp_dir().join(format!("ugnis-scene-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("jug.toml");
    assert!(h.state_mut().scene.save(&path));
    let back = ugnis::io::scene::read(&path).unwrap();
    let s = &h.state().scene.scene;
    assert!((back.scene.camera.azimuth_deg - s.camera.azimuth_deg).abs() < 1e-9);
    assert!((back.scene.camera.polar_deg - s.camera.polar_deg).abs() < 1e-9);
    assert_eq!(back.scene.lights.len(), s.lights.len());
    let i = back.scene.objects[0].texture.unwrap();
    assert_eq!(back.texture_names[i], "(checker)");
    std::fs::remove_dir_all(&dir).unwrap();
}
