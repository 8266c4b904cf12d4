//! Floating windows and the bars around them: Esc closes the window on top, the undo history
//! as a list, a long status line cut at the window's edge and shown whole on a click, no stale
//! status from another Explore topic.

use eframe::egui::accesskit::Role;
use eframe::egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable;
use ugnis::app::Start;

use crate::{harness_sized, open};

#[test]
fn esc_closes_the_window_on_top_then_the_next() {
    let mut h = open("sierpinski.flame");
    h.key_press_modifiers(Modifiers::COMMAND, Key::U);
    h.run_steps(2);
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    h.run_steps(3);
    assert!(h.state().flame.mutations.open && h.state().flame.gradients.open);
    // The gradient window was opened last: it is on top, although the mutations come first
    // in the app's own list.
    h.key_press(Key::Escape);
    h.run_steps(2);
    assert!(!h.state().flame.gradients.open, "the top window closes");
    assert!(h.state().flame.mutations.open, "the one below stays");
    h.key_press(Key::Escape);
    h.run_steps(2);
    assert!(!h.state().flame.mutations.open);
    // F1's shortcuts and the History window close alike.
    h.key_press(Key::F1);
    h.run_steps(2);
    assert!(h.state().help.is_some());
    h.key_press(Key::Escape);
    h.run_steps(2);
    assert!(h.state().help.is_none());
}

#[test]
fn the_history_lists_the_steps_and_goes_back_to_one() {
    let mut h = open("sierpinski.flame");
    let start = h.state().flame.doc().flame().clone();
    h.state_mut().flame.doc_mut().edit(|f| f.gamma = 3.0);
    let after_one = h.state().flame.doc().flame().clone();
    h.state_mut()
        .flame
        .doc_mut()
        .edit(|f| f.xforms[1].coefs.e += 0.1);
    h.state_mut()
        .flame
        .apply_gradient(ugnis::gradient::builtin_named("glacier").unwrap());
    h.key_press_modifiers(Modifiers::COMMAND, Key::H);
    h.run_steps(3);
    for label in ["1. Tone", "2. Transform 2 triangle", "3. Gradient"] {
        assert!(h.query_by_label(label).is_some(), "{label}");
    }
    h.get_by_label("1. Tone").click();
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame(), &after_one);
    // Undone steps stay listed for redoing.
    assert!(h.query_by_label("3. Gradient").is_some());
    h.get_by_label("Start").click();
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame(), &start);
    h.get_by_label("3. Gradient").click();
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().undo_len(), 3);
    h.key_press(Key::Escape);
    h.run_steps(2);
    assert!(!h.state().flame.history_open);
}

#[test]
fn a_long_status_line_ends_at_the_window_and_opens_whole() {
    let mut h = harness_sized(
        Start::File(crate::example("sierpinski.flame")),
        800.0,
        600.0,
    );
    let long = format!(
        "warning: {}",
        "an attribute of another program, ".repeat(12)
    );
    h.state_mut().flame.notices.status(long.clone());
    h.run_steps(2);
    let r = h.get_by_label(long.as_str()).rect();
    assert!(r.right() <= 800.0, "{r:?}");
    h.get_by_label(long.as_str()).click();
    h.run_steps(2);
    assert!(
        h.query_by_label("Status").is_some(),
        "a message box with the whole line"
    );
    h.key_press(Key::Escape);
    h.run_steps(2);
    assert!(h.query_by_label("Status").is_none(), "Esc dismisses it");
}

#[test]
fn the_explore_status_line_is_of_the_topic_shown() {
    let mut h = open("sierpinski.flame");
    h.get_by_role_and_label(Role::Button, "Explore").click();
    h.run_steps(2);
    h.key_press_modifiers(Modifiers::COMMAND, Key::N);
    h.run_steps(2);
    assert!(h.state().status().contains("back to the start"));
    h.get_by_label("Lorenz attractor").click();
    h.run_steps(2);
    assert_eq!(h.state().status(), "", "no line about the topic left");
}
