//! The flame tab's Export: refining until stopped with the render state saved, resuming a
//! saved state, a corrupt state file refused, and Cancel writing nothing.

use std::path::Path;

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::UgnisApp;

use crate::{example, open};

/// Wait (stepping the UI) until the flame tab's export has finished; its status line.
fn wait_for_export(h: &mut Harness<'_, UgnisApp>) -> String {
    let t = std::time::Instant::now();
    while h.state().flame.export_job.is_some() {
        assert!(
            t.elapsed() < std::time::Duration::from_secs(60),
            "the export does not end: {:?}",
            h.state().flame.export_job.as_ref().map(|j| j.status())
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    h.run_steps(1);
    h.state().status().to_string()
}

/// Open the export dialog for a small picture written to `out`.
fn export_dialog_for(h: &mut Harness<'_, UgnisApp>, out: &Path, quality: f64) {
    h.key_press_modifiers(Modifiers::COMMAND, Key::E);
    h.run_steps(2);
    let s = h
        .state_mut()
        .flame
        .export_dialog
        .as_mut()
        .expect("the dialog");
    s.width = 64;
    s.height = 48;
    s.lock_aspect = false;
    s.quality = quality;
    s.path = out.to_path_buf();
    h.run_steps(2);
}

fn state_of(path: &Path) -> ugnis::flame::RenderState {
    ugnis::io::render_state::StateReader::open(path)
        .unwrap_or_else(|e| panic!("{e}"))
        .state
}

#[test]
fn export_refines_until_stopped_and_saves_its_state() {
    let mut h = open("sierpinski.flame");
    let out = example("sierpinski.flame").with_file_name("refined.png");
    let state = out.with_extension("ugnis-state");
    let _ = std::fs::remove_file(&out);
    let _ = std::fs::remove_file(&state);
    export_dialog_for(&mut h, &out, 20.0);
    h.get_by_label("keep refining until stopped").click();
    h.get_by_label("also save the render state").click();
    h.run_steps(2);
    let s = h.state().flame.export_dialog.clone().unwrap();
    assert!(s.refine && s.save_state, "{s:?}");
    h.get_by_role_and_label(Role::Button, "Render").click();
    h.run_steps(2);
    // One pass at quality 20 is 20 × 64 × 48 samples; wait for three times that.
    let first = 20 * 64 * 48;
    let t = std::time::Instant::now();
    loop {
        let st = h.state().flame.export_job.as_ref().unwrap().status();
        if st.samples_done > 3 * first && st.refining {
            assert!(st.quality_done > 60.0, "{st:?}");
            assert_eq!(st.asked, 20.0);
            break;
        }
        assert!(t.elapsed() < std::time::Duration::from_secs(60), "{st:?}");
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    assert!(
        h.query_by_label_contains("refining until stopped")
            .is_some(),
        "the window says it refines"
    );
    // Save now writes the picture while the render goes on.
    h.get_by_role_and_label(Role::Button, "Save now").click();
    let t = std::time::Instant::now();
    while h.state().flame.export_job.as_ref().unwrap().status().saves == 0 {
        assert!(t.elapsed() < std::time::Duration::from_secs(30));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    let saved = state_of(&state).samples_done;
    assert!(saved > 3 * first, "{saved}");
    assert!(h.state().flame.export_job.is_some(), "still refining");
    h.get_by_role_and_label(Role::Button, "Stop").click();
    let status = wait_for_export(&mut h);
    assert!(status.starts_with("Exported"), "{status}");
    let st = state_of(&state);
    assert!(st.samples_done >= saved, "{} < {saved}", st.samples_done);
    assert_eq!((st.flame.width, st.flame.height), (64, 48));
    assert!(status.contains(&st.samples_done.to_string()), "{status}");
    // The picture is exposed for the samples done: not black.
    let img = image::open(&out).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (64, 48));
    assert!(img.pixels().any(|p| p.0.iter().any(|&c| c > 40)));
    // Idle again once the export is over.
    h.run();
}

#[test]
fn export_a_saved_state_resumes_and_adds_samples() {
    let mut h = open("sierpinski.flame");
    let out = example("sierpinski.flame").with_file_name("resumed.png");
    let state = out.with_extension("ugnis-state");
    let _ = std::fs::remove_file(&state);
    export_dialog_for(&mut h, &out, 20.0);
    h.get_by_label("also save the render state").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Render").click();
    h.run_steps(2);
    let status = wait_for_export(&mut h);
    assert!(status.starts_with("Exported"), "{status}");
    let before = state_of(&state);
    assert_eq!(before.samples_done, 20 * 64 * 48);
    assert_eq!(before.flame.quality, 20.0);

    h.state_mut().flame.open_resume_dialog(&state);
    h.run_steps(2);
    assert!(
        h.query_by_label_contains("quality done 20 of 20 (61440 samples)")
            .is_some(),
        "the dialog describes the state"
    );
    let s = h.state_mut().flame.export_dialog.as_mut().unwrap();
    assert_eq!(s.path, out);
    assert!(s.refine && s.save_state);
    // Add quality 30 once, without refining further.
    s.quality = 30.0;
    s.refine = false;
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Render").click();
    h.run_steps(2);
    let status = wait_for_export(&mut h);
    assert!(status.starts_with("Exported"), "{status}");
    let after = state_of(&state);
    assert_eq!(after.flame.quality, 50.0);
    // The first state ended in a partial sub-batch of 1,440 samples: the continuation draws
    // its 30 × 3072 samples in whole sub-batches after it, none lost.
    assert_eq!(after.samples_done, before.samples_done + 30 * 64 * 48);
    assert_eq!(after.samples_done, 50 * 64 * 48);
    assert!(after.is_complete());
}

#[test]
fn export_a_corrupt_state_file_is_refused_naming_the_file() {
    let mut h = open("sierpinski.flame");
    let dir = example("sierpinski.flame").with_file_name("");
    let bad = dir.join("bad.ugnis-state");
    std::fs::write(&bad, b"not a render state at all").unwrap();
    h.state_mut().flame.open_resume_dialog(&bad);
    h.run_steps(2);
    assert!(h.state().flame.export_dialog.is_none());
    assert!(h.query_by_label("Cannot resume the render state").is_some());
    let note = h
        .query_by_label_contains("bad.ugnis-state")
        .expect("the message names the file");
    let _ = note;
    h.get_by_role_and_label(Role::Button, "OK").click();
    h.run_steps(2);
    // Another version: the reader's message says which.
    let old = dir.join("old.ugnis-state");
    let mut bytes = b"UGNISRS\x1a".to_vec();
    bytes.extend_from_slice(&99u32.to_le_bytes());
    std::fs::write(&old, bytes).unwrap();
    h.state_mut().flame.open_resume_dialog(&old);
    h.run_steps(2);
    assert!(h.query_by_label_contains("old.ugnis-state").is_some());
    assert!(h.query_by_label_contains("version 99").is_some());
    assert!(h.state().flame.export_dialog.is_none());
}

#[test]
fn export_cancel_writes_nothing_and_keeps_the_files_saved_before() {
    let mut h = open("sierpinski.flame");
    let out = example("sierpinski.flame").with_file_name("cancelled.png");
    let state = out.with_extension("ugnis-state");
    export_dialog_for(&mut h, &out, 20.0);
    h.get_by_label("keep refining until stopped").click();
    h.get_by_label("also save the render state").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Render").click();
    h.run_steps(2);
    let t = std::time::Instant::now();
    while h
        .state()
        .flame
        .export_job
        .as_ref()
        .unwrap()
        .status()
        .samples_done
        == 0
    {
        assert!(t.elapsed() < std::time::Duration::from_secs(30));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    // The last frame may have been drawn before the first samples arrived: draw one with them.
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Save now").click();
    while h.state().flame.export_job.as_ref().unwrap().status().saves == 0 {
        assert!(t.elapsed() < std::time::Duration::from_secs(30));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    let (png, st) = (std::fs::read(&out).unwrap(), std::fs::read(&state).unwrap());
    // Let it refine further, then Cancel: the files stay as Save now wrote them.
    std::thread::sleep(std::time::Duration::from_millis(100));
    h.run_steps(1);
    // The window's Cancel (the status bar has one too; both cancel the export).
    let cancels: Vec<_> = h
        .get_all_by_role_and_label(Role::Button, "Cancel")
        .collect();
    assert_eq!(cancels.len(), 2);
    cancels[0].click();
    let status = wait_for_export(&mut h);
    assert!(status.contains("cancelled"), "{status}");
    assert_eq!(std::fs::read(&out).unwrap(), png);
    assert_eq!(std::fs::read(&state).unwrap(), st);
    // No temporary file is left beside them.
    let dir = out.parent().unwrap();
    let tmp: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().ends_with(".ugnis-tmp"))
        .collect();
    assert!(tmp.is_empty(), "{tmp:?}");
}
