//! The window around the tabs: every menu item with its shortcut, shortcuts reaching their
//! commands, New, Recent and Help, the toolbar of each tab, tooltips, idle frames, a small
//! window, and the Options dialog.

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::{MENU, Start, UgnisApp};

use crate::{example, harness_sized, open};

#[test]
fn every_menu_item_exists_with_its_shortcut() {
    let mut h = open("sierpinski.flame");
    for menu in ugnis::app::MENUS {
        h.get_by_role_and_label(Role::Button, menu).click();
        h.run_steps(2);
        for item in MENU.iter().filter(|m| m.menu == menu) {
            // A menu button's accessible label is its text followed by its shortcut.
            let want = match &item.shortcut {
                Some(s) => format!("{} {}", item.label, h.ctx.format_shortcut(s)),
                None => item.label.to_string(),
            };
            assert!(
                h.query_by_role_and_label(Role::Button, &want).is_some(),
                "{menu} › {want:?} is missing"
            );
        }
        h.key_press(Key::Escape);
        h.run_steps(2);
    }
    // The Variations submenu names the seven variations and Random.
    h.get_by_role_and_label(Role::Button, "Tools").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Random variations")
        .click();
    h.run_steps(3);
    assert!(
        h.query_all_by_label("Random").count() >= 2,
        "Random variations › Random missing"
    );
    for v in [
        "Linear",
        "Sinusoidal",
        "Spherical",
        "Swirl",
        "Horseshoe",
        "Polar",
        "Bent",
    ] {
        assert!(
            h.query_by_label(v).is_some(),
            "Random variations › {v} missing"
        );
    }
}

#[test]
fn shortcuts_reach_their_commands() {
    let mut h = open("sierpinski.flame");
    assert!(h.state().flame.show_editor);
    h.key_press(Key::F4);
    h.run_steps(2);
    assert!(!h.state().flame.show_editor, "F4 toggles the editor");
    assert!(!h.state().flame.gradients.open);
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    h.run_steps(2);
    assert!(
        h.state().flame.gradients.open,
        "Ctrl+G opens the gradient window"
    );
    let before = h.state().flame.doc().flame().clone();
    h.key_press_modifiers(Modifiers::COMMAND, Key::R);
    h.run_steps(2);
    assert_ne!(
        h.state().flame.doc().flame(),
        &before,
        "Ctrl+R makes a random flame"
    );
    // Tools › Random variations › Swirl sets every transform to swirl, as one undo step.
    h.get_by_role_and_label(Role::Button, "Tools").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Random variations")
        .click();
    h.run_steps(3);
    h.get_by_label("Swirl").click();
    h.run_steps(2);
    let swirl = ugnis::flame::variations::by_name("swirl").unwrap();
    for x in &h.state().flame.doc().flame().xforms {
        assert_eq!(x.vars.len(), 1);
        assert_eq!(x.vars[0].id, swirl);
    }
    assert!(h.state().status().to_lowercase().contains("swirl"));
}

#[test]
fn idle_is_idle_in_every_tab() {
    let mut h = open("sierpinski.flame");
    // `run` fails when the app keeps asking for frames.
    h.run();
    for tab in ["Escape-time", "Scene", "Flame"] {
        h.get_by_role_and_label(Role::Button, tab).click();
        h.run();
    }
}

#[test]
fn a_small_window_keeps_the_preview_and_the_tabs() {
    let mut h = harness_sized(Start::File(example("sierpinski.flame")), 800.0, 600.0);
    let scene = h.get_by_role_and_label(Role::Button, "Scene").rect();
    assert!(scene.max.x <= 800.0 && scene.max.y <= 600.0, "{scene:?}");
    let preview = h.state().flame.preview_rect.expect("a preview area");
    assert!(preview.width() >= 250.0, "preview {preview:?}");
    h.get_by_role_and_label(Role::Button, "Scene").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Scene);
}

#[test]
fn the_options_dialog_stays_put_when_its_tab_changes() {
    let mut h = open("sierpinski.flame");
    h.key_press_modifiers(Modifiers::COMMAND, Key::Comma);
    h.run_steps(3);
    // The dialog's "Random" tab (the toolbar has a Random button too; the dialog is last).
    let tab = |h: &Harness<'_, UgnisApp>| {
        h.get_all_by_role_and_label(Role::Button, "Random")
            .last()
            .unwrap()
            .rect()
    };
    let r0 = tab(&h);
    h.get_all_by_role_and_label(Role::Button, "Random")
        .last()
        .unwrap()
        .click();
    h.run_steps(3);
    assert_eq!(tab(&h), r0);
    h.get_by_role_and_label(Role::Button, "General").click();
    h.run_steps(3);
    assert_eq!(tab(&h), r0);
}

#[test]
fn new_recent_help_and_the_per_tab_toolbar() {
    let mut h = open("sierpinski.flame");
    let path = h.state().flame.doc().path.clone().unwrap();
    // Saving puts the file first in File › Recent.
    assert!(h.state_mut().save_to(&path));
    assert_eq!(
        h.state().options.recent_files.first(),
        Some(&std::fs::canonicalize(&path).unwrap_or(path.clone()))
            .filter(|_| true)
            .or(h.state().options.recent_files.first())
    );
    assert!(h.state().options.recent_files[0].ends_with("sierpinski.flame"));
    // File › New: three transforms, a new untitled file.
    h.key_press_modifiers(Modifiers::COMMAND, Key::N);
    h.run_steps(2);
    assert_eq!(h.state().flame.file.flames.len(), 1);
    assert_eq!(h.state().flame.doc().flame().xforms.len(), 3);
    assert!(h.state().flame.file.path.is_none());
    // Help › Keyboard shortcuts lists the menu's shortcuts.
    h.key_press(Key::F1);
    h.run_steps(4);
    assert_eq!(
        h.state().help,
        Some(ugnis::app::HelpPage::Shortcuts),
        "F1 opens the shortcuts"
    );
    assert!(h.query_by_label("Keyboard shortcuts").is_some());
    assert!(h.query_by_label("File › New").is_some());
    // The toolbar shows the current tab's commands.
    assert!(h.query_by_role_and_label(Role::Button, "Random").is_some());
    h.get_by_role_and_label(Role::Button, "Escape-time").click();
    h.run_steps(2);
    assert!(h.query_by_role_and_label(Role::Button, "Random").is_none());
    assert!(h.query_by_role_and_label(Role::Button, "Export").is_some());
}

#[test]
fn controls_have_tooltips() {
    let mut h = open("sierpinski.flame");
    h.ctx.all_styles_mut(|s| s.interaction.tooltip_delay = 0.0);
    for (button, tip) in [
        ("Move", "drag inside a triangle"),
        ("Rotate", "turn it about the pivot"),
        ("Scale", "grow or shrink"),
        ("Local pivot", "triangle's centre"),
        ("Post", "post transforms"),
        ("Final", "final transform"),
        ("Auto zoom", "fit every triangle"),
    ] {
        let p = h
            .get_by_role_and_label(Role::Button, button)
            .rect()
            .center();
        h.hover_at(p);
        h.run_steps(3);
        assert!(
            h.query_by_label_contains(tip).is_some(),
            "{button} has no tooltip"
        );
    }
    let p = h
        .get_by_role_and_label(Role::Slider, "Colour speed")
        .rect()
        .center();
    h.hover_at(p);
    h.run_steps(3);
    assert!(
        h.query_by_label_contains("take on this transform's colour")
            .is_some()
    );
}
