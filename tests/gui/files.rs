//! Opening and saving flames: Save then Open, the unsaved-changes question on closing, a
//! failed save, the file chooser from a relative folder, files given at start, and attributes
//! of other programs told in the status line.

use std::path::{Path, PathBuf};

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable;
use ugnis::app::Start;

use crate::{example, harness, open};

#[test]
fn save_then_open_round_trips() {
    let dir = std::env::temp_dir().join(format!("ugnis-gui-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("saved.fla");
    let _ = std::fs::remove_file(&path);

    let mut h = open("orchid.flame");
    // An edit, so that the saved file differs from the example.
    h.state_mut()
        .flame
        .doc_mut()
        .edit(|f| f.xforms[0].color = 0.25);
    let edited = h.state().flame.doc().flame().clone();
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::S);
    h.run_steps(2);
    let field = h.get_by_role_and_label(Role::TextInput, "File name");
    field.focus();
    h.run_steps(1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.get_by_role_and_label(Role::TextInput, "File name")
        .type_text(path.to_str().unwrap());
    h.run_steps(2);
    // The dialog's Save button (the toolbar has one too; the dialog is drawn last).
    h.get_all_by_role_and_label(Role::Button, "Save")
        .last()
        .unwrap()
        .click();
    h.run_steps(3);
    assert!(path.is_file(), "Save As wrote nothing");
    assert!(!h.state().flame.doc().dirty);
    assert_eq!(h.state().flame.doc().path.as_deref(), Some(path.as_path()));

    // Open it in a fresh app: the same flame comes back.
    let h2 = harness(Start::File(path.clone()));
    let back = h2.state().flame.doc().flame();
    assert_eq!(back.xforms.len(), edited.xforms.len());
    for (a, b) in back.xforms.iter().zip(&edited.xforms) {
        assert_eq!(a.coefs, b.coefs);
        assert_eq!(a.color, b.color);
        assert_eq!(a.vars, b.vars);
    }
    assert_eq!(back.center, edited.center);
    assert_eq!(back.scale, edited.scale);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn closing_with_unsaved_changes_asks() {
    let mut h = open("sierpinski.flame");
    h.state_mut()
        .flame
        .doc_mut()
        .edit(|f| f.xforms[0].color = 0.5);
    h.input_mut()
        .viewports
        .entry(egui::ViewportId::ROOT)
        .or_default()
        .events
        .push(egui::ViewportEvent::Close);
    h.run_steps(2);
    assert!(
        h.query_by_label("Unsaved changes").is_some(),
        "no question asked"
    );
    // Cancel keeps the program and the edit.
    h.get_by_role_and_label(Role::Button, "Cancel").click();
    h.run_steps(2);
    assert!(h.query_by_label("Unsaved changes").is_none());
    assert!(h.state().flame.doc().dirty);
    assert_eq!(h.state().flame.doc().flame().xforms[0].color, 0.5);
}

#[test]
fn a_failed_save_says_so_and_keeps_the_changes() {
    let mut h = open("sierpinski.flame");
    h.state_mut()
        .flame
        .doc_mut()
        .edit(|f| f.xforms[0].color = 0.75);
    let target = Path::new("/nonexistent-ugnis-dir/out.fla");
    assert!(!h.state_mut().save_to(target));
    h.run_steps(2);
    assert!(h.query_by_label("Cannot save").is_some());
    assert!(h.state().flame.doc().dirty);
    assert_ne!(h.state().flame.doc().path.as_deref(), Some(target));
}

#[test]
fn the_file_chooser_works_from_a_relative_folder() {
    // As after `ugnis examples/orchid.flame` in the repository.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::env::set_current_dir(root).unwrap();
    let mut h = harness(Start::File(PathBuf::from("examples/orchid.flame")));
    assert!(h.query_by_label("Warnings").is_none());
    h.key_press_modifiers(Modifiers::COMMAND, Key::E);
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Choose…").click();
    h.run_steps(2);
    let dir = h.state().file_browser().unwrap().dir.clone();
    assert!(dir.is_absolute(), "{dir:?}");
    assert!(dir.ends_with("examples"), "{dir:?}");
    h.get_by_role_and_label(Role::Button, "Up").click();
    h.run_steps(2);
    let up = h.state().file_browser().unwrap().dir.clone();
    assert_eq!(up, std::fs::canonicalize(root).unwrap());
    assert!(h.query_by_label_contains("No such file").is_none());
}

#[test]
fn a_scene_or_lsystem_file_given_at_start_opens_in_its_tab() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let h = harness(Start::File(root.join("examples/jug.toml")));
    assert_eq!(h.state().tab, ugnis::app::Tab::Scene);
    assert!(
        h.state().status().contains("jug.toml"),
        "{}",
        h.state().status()
    );
    let h = harness(Start::File(root.join("tests/fixtures/explore.l")));
    assert_eq!(h.state().tab, ugnis::app::Tab::Explore);
    assert!(h.state().explore.lsystem.file.is_some());
}

#[test]
fn attributes_of_other_programs_are_told_in_the_status_line() {
    // Kept and written back; told in the status line, not in a message box in the way.
    let dir = std::env::temp_dir().join(format!("ugnis-gui-foreign-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(example("orchid.flame"))
        .unwrap()
        .replacen("<flame ", "<flame mod_contrast=\"1\" material=\"0\" ", 1);
    let path = dir.join("foreign.flame");
    std::fs::write(&path, text).unwrap();
    let h = harness(Start::File(path));
    let status = h.state().status().to_string();
    std::fs::remove_dir_all(&dir).ok();
    assert!(
        status.contains("attribute names of other programs"),
        "{status}"
    );
    assert!(h.query_by_label("Warnings").is_none());
}

#[test]
fn a_folder_typed_into_the_chooser_is_kept_and_opened() {
    let dir = std::env::temp_dir().join(format!("ugnis-gui-folder-{}", std::process::id()));
    let sub = dir.join("flames here");
    std::fs::create_dir_all(&sub).unwrap();
    std::fs::copy(example("sierpinski.flame"), sub.join("tri.flame")).unwrap();
    let mut h = harness(Start::File(example("sierpinski.flame")));
    h.key_press_modifiers(Modifiers::COMMAND, Key::O);
    h.run_steps(2);
    let field = h.get_by_role_and_label(Role::TextInput, "Folder");
    field.focus();
    h.run_steps(1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.run_steps(1);
    // Typed a key at a time, with frames between: nothing is lost.
    let text = sub.display().to_string();
    for c in text.chars() {
        h.get_by_role_and_label(Role::TextInput, "Folder")
            .type_text(&c.to_string());
        h.run_steps(1);
    }
    assert_eq!(h.state().file_browser().unwrap().folder, text);
    h.key_press(Key::Enter);
    h.run_steps(2);
    let b = h.state().file_browser().unwrap();
    assert_eq!(b.dir, std::fs::canonicalize(&sub).unwrap());
    assert!(
        h.query_by_label("tri.flame").is_some(),
        "the folder's file is listed"
    );
    // A name that is no folder is told, and the text stays for correcting.
    let field = h.get_by_role_and_label(Role::TextInput, "Folder");
    field.focus();
    h.run_steps(1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.get_by_role_and_label(Role::TextInput, "Folder")
        .type_text("no-such-folder");
    h.run_steps(1);
    h.key_press(Key::Enter);
    h.run_steps(2);
    assert!(h.query_by_label_contains("not a folder").is_some());
    assert_eq!(h.state().file_browser().unwrap().folder, "no-such-folder");
    let _ = std::fs::remove_dir_all(&dir);
}
