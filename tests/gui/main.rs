//! The editor driven through its real UI with egui_kittest, one module per tab and feature;
//! here the helpers they share (a harness, private copies of the examples, mouse drags).
#![cfg(feature = "gui")]

mod animation;
mod escape_tab;
mod explore_tab;
mod export;
mod file_values;
mod files;
mod flame_tab;
mod gradient;
mod left_panel;
mod opening;
mod preview;
mod scene_tab;
mod shell;
mod triangles;
mod windows;

use std::path::{Path, PathBuf};

use eframe::egui;
use egui::accesskit::Role;
use egui::{Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::Options;
use ugnis::app::{Start, UgnisApp};

/// A private copy of an example (a test that saves must never touch the repository).
pub fn example(name: &str) -> PathBuf {
    let src = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name);
    let dir = std::env::temp_dir().join(format!(
        "ugnis-gui-{}-{:?}",
        std::process::id(),
        std::thread::current().id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let dst = dir.join(name);
    std::fs::copy(&src, &dst).unwrap();
    dst
}

pub fn harness(start: Start) -> Harness<'static, UgnisApp> {
    let app = UgnisApp::new(Options::default(), start, None);
    let mut h = Harness::builder()
        .with_size(Vec2::new(1280.0, 860.0))
        .build_ui_state(|ui, app: &mut UgnisApp| app.ui(ui), app);
    h.run_steps(3);
    h
}

pub fn harness_sized(start: Start, w: f32, h: f32) -> Harness<'static, UgnisApp> {
    let app = UgnisApp::new(Options::default(), start, None);
    let mut h = Harness::builder()
        .with_size(Vec2::new(w, h))
        .build_ui_state(|ui, app: &mut UgnisApp| app.ui(ui), app);
    h.run_steps(3);
    h
}

pub fn open(name: &str) -> Harness<'static, UgnisApp> {
    let h = harness(Start::File(example(name)));
    assert_eq!(h.state().flame.doc().name, name.trim_end_matches(".flame"));
    h
}

/// Drag with the primary button from `a` to `b` in a few moves.
pub fn drag(h: &mut Harness<'_, UgnisApp>, a: Pos2, b: Pos2) {
    h.hover_at(a);
    h.step();
    h.drag_at(a);
    h.step();
    for k in 1..=4 {
        h.hover_at(a + (b - a) * (k as f32 / 4.0));
        h.step();
    }
    h.drop_at(b);
    h.run_steps(2);
}

pub fn section(h: &mut Harness<'_, UgnisApp>, name: &str) {
    h.get_by_role_and_label(Role::Button, name).click();
    h.run_steps(2);
}

pub fn set_number(h: &mut Harness<'_, UgnisApp>, name: &str, v: f64) {
    h.get_by_role_and_label(Role::SpinButton, name)
        .set_value_accesskit(v);
    h.run_steps(2);
}

/// Step the UI (every 20 ms, for at most a minute) until `done` holds for the app.
pub fn wait_until(h: &mut Harness<'_, UgnisApp>, done: impl Fn(&UgnisApp) -> bool) {
    let t = std::time::Instant::now();
    while !done(h.state()) {
        assert!(t.elapsed() < std::time::Duration::from_secs(60));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
}
