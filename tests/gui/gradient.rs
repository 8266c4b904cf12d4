//! The gradient window: the library and the palette editor in one window, Rotate following
//! the drag and showing its amount, a curve point grabbed by a plain drag, and a 256-colour
//! palette edited as keys without changing a colour.

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use ugnis::app::UgnisApp;

use crate::open;

/// Press at `a`, move to `b` in steps, and hand back before releasing.
fn press_and_move(h: &mut Harness<'_, UgnisApp>, a: Pos2, b: Pos2) {
    h.hover_at(a);
    h.step();
    h.drag_at(a);
    h.step();
    for k in 1..=4 {
        h.hover_at(a + (b - a) * (k as f32 / 4.0));
        h.step();
    }
}

#[test]
fn library_and_editor_are_one_window() {
    let mut h = open("sierpinski.flame");
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    h.run_steps(2);
    assert!(h.query_by_label("glacier").is_some(), "the library page");
    // The window's Editor tab (the toolbar's Editor button comes first).
    h.get_all_by_role_and_label(Role::Button, "Editor")
        .last()
        .unwrap()
        .click();
    h.run_steps(2);
    assert!(h.state().flame.palette_editor.open);
    assert!(h.query_by_label("Saturation").is_some(), "the editor page");
    assert!(h.query_by_label("glacier").is_none(), "in the same window");
    // Ctrl+Shift+G on the editor page closes the window; Ctrl+G opens the library again.
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::G);
    h.run_steps(2);
    assert!(!h.state().flame.gradients.open && !h.state().flame.palette_editor.open);
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    h.run_steps(2);
    assert!(h.query_by_label("glacier").is_some());
}

#[test]
fn rotate_follows_the_drag_shows_its_amount_and_is_one_step() {
    let mut h = open("sierpinski.flame");
    let before = h.state().flame.doc().flame().palette.clone();
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    h.run_steps(2);
    let r = h.get_by_role_and_label(Role::Slider, "Rotate").rect();
    let a = r.center();
    press_and_move(&mut h, a, a + Vec2::new(r.width() * 0.2, 0.0));
    // Still held: the flame's palette is turned already.
    let shift = h.state().flame.gradients.shift;
    assert!(shift > 0, "{shift}");
    assert_eq!(
        h.state().flame.doc().flame().palette.colors,
        before.rotated(shift).colors
    );
    // The amount is shown beside the slider.
    let slider = h.get_by_role_and_label(Role::Slider, "Rotate");
    assert_eq!(slider.accesskit_node().numeric_value(), Some(shift as f64));
    h.drop_at(a + Vec2::new(r.width() * 0.2, 0.0));
    h.run_steps(3);
    assert_eq!(h.state().flame.doc().undo_len(), 1, "one undo step");
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame().palette.colors, before.colors);
}

#[test]
fn a_curve_point_is_grabbed_by_a_plain_drag() {
    let mut h = open("sierpinski.flame");
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::G);
    h.run_steps(3);
    let r = h.get_by_label("colour curve").rect();
    // A click on the straight line adds a point there.
    let p = egui::pos2(r.left() + r.width() * 0.5, r.bottom() - r.height() * 0.5);
    h.hover_at(p);
    h.step();
    h.event(egui::Event::PointerButton {
        pos: p,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    h.step();
    h.event(egui::Event::PointerButton {
        pos: p,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    h.run_steps(2);
    let pts = h.state().flame.palette_editor.curves.all.points().to_vec();
    assert_eq!(pts.len(), 3, "{pts:?}");
    // Dragged up by 40 points with a first step of 14 (past the 8-point hit radius, as a
    // real mouse does before egui sees a drag): the point follows.
    h.hover_at(p);
    h.step();
    h.drag_at(p);
    h.step();
    for dy in [14.0, 28.0, 40.0] {
        h.hover_at(p - Vec2::new(0.0, dy));
        h.step();
    }
    h.drop_at(p - Vec2::new(0.0, 40.0));
    h.run_steps(2);
    let pts = h.state().flame.palette_editor.curves.all.points().to_vec();
    assert_eq!(pts.len(), 3, "moved, not added: {pts:?}");
    let want = 0.5 + 40.0 / r.height() as f64;
    assert!(
        (pts[1][1] - want).abs() < 0.02 && (pts[1][0] - 0.5).abs() < 0.02,
        "{pts:?}, want y {want}"
    );
}

#[test]
fn editing_a_256_colour_palette_as_keys_keeps_its_colours() {
    let mut h = open("sierpinski.flame");
    // A turned palette has no keys left.
    let g = h.state().flame.doc().flame().palette.rotated(37);
    h.state_mut().flame.apply_gradient(g.clone());
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::G);
    h.run_steps(3);
    h.get_by_role_and_label(Role::Button, "Edit as keys")
        .click();
    h.run_steps(3);
    assert!(h.state().flame.palette_editor.keys.is_some());
    let now = &h.state().flame.doc().flame().palette;
    for i in 0..256 {
        assert_eq!(now.rgb8(i), g.rgb8(i), "entry {i}");
    }
}
