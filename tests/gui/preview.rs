//! The preview as the main thing on screen: it fills the room the panels leave at the flame's
//! aspect, goes over the whole window (F11, a button, Esc back) and into a window of its own,
//! stays usable at 800×600 with the selected triangle in sight, and refines a still picture
//! until it is clean, then idles.

use eframe::egui::Key;
use eframe::egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::{Start, UgnisApp};

use crate::{example, harness_sized, wait_until};

fn aspect(h: &Harness<'_, UgnisApp>) -> (f32, f32) {
    let f = h.state().flame.doc().flame();
    let r = h.state().flame.preview_rect.expect("a preview");
    (r.width() / r.height(), f.width as f32 / f.height as f32)
}

/// Hover the picture and click one of the buttons it then shows.
fn picture_button(h: &mut Harness<'_, UgnisApp>, label: &str) {
    let r = h.state().flame.preview_rect.unwrap();
    h.hover_at(r.center());
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, label).click();
    h.run_steps(3);
}

#[test]
fn the_preview_fills_its_area_at_the_flames_aspect() {
    let h = harness_sized(Start::File(example("orchid.flame")), 1280.0, 800.0);
    let r = h.state().flame.preview_rect.unwrap();
    let (got, want) = aspect(&h);
    assert!((got - want).abs() < 0.01, "{got} vs {want}");
    // The room between the panels: about 630 points wide, and the picture takes all of it.
    assert!(r.width() >= 580.0, "{r:?}");
}

#[test]
fn the_preview_goes_full_window_by_key_and_button_and_comes_back() {
    let mut h = harness_sized(Start::File(example("orchid.flame")), 1280.0, 800.0);
    let small = h.state().flame.preview_rect.unwrap();
    h.key_press(Key::F11);
    h.run_steps(3);
    assert!(h.state().flame.full_view);
    let big = h.state().flame.preview_rect.unwrap();
    // No bars and no panels: the whole height of the window.
    assert!(big.height() >= 770.0, "{big:?}");
    assert!(h.query_by_label("Undo").is_none(), "no toolbar");
    let (got, want) = aspect(&h);
    assert!((got - want).abs() < 0.01);
    h.key_press(Key::Escape);
    h.run_steps(3);
    assert!(!h.state().flame.full_view, "Esc leaves it");
    assert_eq!(h.state().flame.preview_rect.unwrap(), small);
    picture_button(&mut h, "Full window");
    assert!(h.state().flame.full_view);
    picture_button(&mut h, "Leave full window");
    assert!(!h.state().flame.full_view);
}

#[test]
fn the_preview_gets_a_window_of_its_own_and_the_editor_its_room() {
    let mut h = harness_sized(Start::File(example("orchid.flame")), 1280.0, 800.0);
    let canvas = h.state().flame.editor.canvas;
    picture_button(&mut h, "Own window");
    assert!(h.state().flame.preview_window);
    // Here there is no second native window: a floating one of the main window.
    assert!(h.query_by_label("ugnis — preview").is_some());
    let (got, want) = aspect(&h);
    assert!((got - want).abs() < 0.01);
    assert!(
        h.state().flame.editor.canvas.width() > canvas.width() + 100.0,
        "the editor takes the middle"
    );
    h.get_by_role_and_label(Role::Button, "Back to the main window")
        .click();
    h.run_steps(3);
    assert!(!h.state().flame.preview_window);
    assert!(h.query_by_label("ugnis — preview").is_none());
}

#[test]
fn at_800_by_600_the_preview_is_usable_and_the_triangle_in_sight() {
    let h = harness_sized(Start::File(example("orchid.flame")), 800.0, 600.0);
    let r = h.state().flame.preview_rect.unwrap();
    assert!(r.width() >= 320.0, "{r:?}");
    let (got, want) = aspect(&h);
    assert!((got - want).abs() < 0.01);
    let st = &h.state().flame.editor;
    let f = h.state().flame.doc().flame();
    for x in &f.xforms {
        for p in x.coefs.triangle() {
            assert!(
                st.canvas.expand(1.0).contains(st.screen_from_world(p)),
                "{p:?} outside {:?}",
                st.canvas
            );
        }
    }
}

#[test]
fn a_still_preview_refines_until_clean_then_idles() {
    let mut h = harness_sized(Start::File(example("sierpinski.flame")), 800.0, 600.0);
    {
        let app = h.state_mut();
        // Small and quick for the test machine.
        app.options.preview_size = 200;
        app.options.preview_least_quality = 20.0;
        app.options.preview_noise = 4.0;
        app.options.preview_max_quality = 200.0;
    }
    let ctx = h.ctx.clone();
    h.state_mut().flame.start_preview(&ctx);
    h.run_steps(2);
    wait_until(&mut h, |a| {
        a.flame.preview_progress().is_some_and(|(_, done)| done)
    });
    h.run_steps(2);
    assert!(
        h.query_by_label_contains("preview clean").is_some(),
        "the status bar says so"
    );
    // Clean: no more frames are asked for.
    h.run();
}
