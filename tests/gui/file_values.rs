//! Looking at controls changes nothing: values of a file outside the editor's ranges are
//! shown as they are in the flame settings and the escape-time and scene controls, not clamped.

use ugnis::app::Start;

use crate::{example, harness_sized, section};

/// Values of a file outside the editor's ranges (Fractorium files use gamma 9995) are shown,
/// not clamped: looking at the settings changes nothing.
#[test]
fn looking_at_the_settings_does_not_clamp_the_file_values() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("wide.flame");
    let text = std::fs::read_to_string(example("sierpinski.flame"))
        .unwrap()
        .replacen("gamma=\"2.2\"", "gamma=\"9995\" highlight_power=\"250\"", 1);
    std::fs::write(&path, text).unwrap();
    let mut h = harness_sized(Start::File(path), 1280.0, 1600.0);
    let before = h.state().flame.doc().flame().clone();
    assert_eq!(before.gamma, 9995.0);
    for s in ["Settings", "Triangle", "Xaos"] {
        section(&mut h, s);
        h.run_steps(2);
    }
    assert_eq!(h.state().flame.doc().flame(), &before);
    assert!(!h.state().flame.doc().can_undo(), "nothing was edited");
}

/// The same for the escape-time and scene controls: a view's 5 million iterations, an offset
/// past 1 and a repeat past 256, a camera farther, lower and larger than the drag ranges, and
/// a quaternion constant outside ±2 are shown as they are, not clamped by being shown.
#[test]
fn looking_at_escape_and_scene_controls_does_not_clamp_the_file_values() {
    let dir = tempfile::tempdir().unwrap();
    let esc = dir.path().join("wide.esc");
    std::fs::write(
        &esc,
        std::fs::read_to_string(example("seahorse.esc"))
            .unwrap()
            .replace(
                "max_iter = 2000",
                "max_iter = 5000000\noffset = 1.5\nrepeat = 400",
            ),
    )
    .unwrap();
    let mut h = harness_sized(Start::File(esc), 1280.0, 1600.0);
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Escape);
    let p = &h.state().escape.doc.params;
    assert_eq!(
        (p.max_iter, p.palette.offset, p.palette.repeat),
        (5_000_000, 1.5, 400.0)
    );
    let scene = dir.path().join("wide.toml");
    std::fs::write(
        &scene,
        std::fs::read_to_string(example("quaternion-julia.toml"))
            .unwrap()
            .replacen("distance = 6", "distance = 500", 1)
            .replacen("polar = 70", "polar = 0.5", 1)
            .replacen("scale = 150", "scale = 9000", 1)
            .replacen("c = [-0.2, 0.8", "c = [-2.5, 0.8", 1)
            .replacen("slice_value = 0.0", "slice_value = 3.0", 1)
            .replacen("ks = 0.4, n = 30", "ks = 1.5, n = 300", 1),
    )
    .unwrap();
    let mut h = harness_sized(Start::File(scene.clone()), 1280.0, 1600.0);
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Scene);
    let want = ugnis::io::scene::read(&scene).unwrap().scene;
    let c = h.state().scene.scene.camera;
    assert_eq!((c.distance, c.polar_deg, c.scale), (500.0, 0.5, 9000.0));
    assert_eq!(
        h.state().scene.selected_object,
        0,
        "the Julia set's controls are shown"
    );
    let o = &h.state().scene.scene.objects[0];
    let ugnis::surface::Geometry::QuaternionJulia(q) = o.geometry else {
        panic!("the first object is the Julia set");
    };
    let ugnis::surface::Geometry::QuaternionJulia(q0) = want.objects[0].geometry else {
        panic!("read back");
    };
    assert_eq!((q.c[0], q.slice_value), (-2.5, 3.0));
    assert_eq!(q, q0);
    assert_eq!((o.material.ks, o.material.shininess), (1.5, 300.0));
    assert_eq!(h.state().scene.scene.lights, want.lights);
}
