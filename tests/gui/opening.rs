//! Every format ugnis reads opens in the view that opens its kind, through every way in: the
//! file given at start, File › Open, File › Recent and a file dropped on the window (driven
//! through the UI), and the command line (the flame commands read every flame source; any
//! other file is refused with the command that reads it, and that command does).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::AtomicBool;

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::Topic;
use ugnis::app::{Start, Tab, UgnisApp};
use ugnis::flame::render::{RenderOptions, Renderer};
use ugnis::io::{self, View};

use crate::harness;

/// A private folder for this test's files.
fn folder(what: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ugnis-opening-{what}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// One file of every format ugnis reads, copied or written into `dir`, with the view that
/// opens it.
fn every_format(dir: &Path) -> Vec<(PathBuf, View)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let copy = |from: &str, to: &str| {
        let dst = dir.join(to);
        std::fs::copy(root.join(from), &dst).unwrap();
        dst
    };
    let flame_path = copy("examples/sierpinski.flame", "sierpinski.flame");
    let mut flame = io::read_flames(&flame_path, &Default::default())
        .unwrap()
        .value
        .remove(0);
    flame.resize_keep_framing(16, 12);
    flame.quality = 1.0;
    // A PNG that carries its flame.
    let png = dir.join("with-flame.png");
    let picture = image::DynamicImage::new_rgb8(16, 12);
    io::png::save(&png, &picture, &io::png::PngMeta::for_flame(&flame)).unwrap();
    // An image a gradient is made from.
    let bmp = dir.join("colours.bmp");
    image::RgbImage::from_fn(32, 4, |x, _| {
        image::Rgb([(x * 8) as u8, 90, 255 - (x * 8) as u8])
    })
    .save(&bmp)
    .unwrap();
    // A saved render state to continue.
    let state = dir.join("render.ugnis-state");
    let mut r = Renderer::new(&flame, &RenderOptions::default()).unwrap();
    assert!(r.run_all(1, &AtomicBool::new(false), |_| {}));
    let (st, hist) = r.into_state().unwrap();
    io::render_state::save(&state, &st, &hist).unwrap();
    vec![
        (flame_path, View::Flame),
        (
            copy("examples/sierpinski.flame", "sierpinski.flam3"),
            View::Flame,
        ),
        (
            copy("tests/fixtures/library.fla", "library.fla"),
            View::Flame,
        ),
        (png, View::Flame),
        (
            copy("tests/fixtures/library.ifs", "library.ifs"),
            View::Flame,
        ),
        (copy("tests/fixtures/explore.l", "explore.l"), View::LSystem),
        (copy("examples/galaxy.esc", "galaxy.esc"), View::Escape),
        (copy("examples/menger.toml", "menger.toml"), View::Scene),
        (copy("tests/fixtures/hand.ugr", "hand.ugr"), View::Gradients),
        (copy("tests/fixtures/hand.map", "hand.map"), View::Gradients),
        (copy("tests/fixtures/hand.ggr", "hand.ggr"), View::Gradients),
        (bmp, View::GradientFromImage),
        (state, View::RenderState),
    ]
}

/// The ways into the editor.
#[derive(Clone, Copy, Debug)]
enum Way {
    /// `ugnis FILE`.
    FileArgument,
    /// File › Open, the name typed into the file chooser.
    Open,
    /// File › Recent.
    Recent,
    /// Dropped on the window.
    Dropped,
}

/// A file dropped on the window, as the desktop hands it over.
#[derive(Debug)]
struct Dropped(PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

/// A window with a flame open, for the ways that open a file into a running editor.
fn running() -> Harness<'static, UgnisApp> {
    harness(Start::Flames(Vec::new()))
}

/// Open `path` in the editor the way `way` does.
fn open_by(way: Way, path: &Path) -> Harness<'static, UgnisApp> {
    let mut h = match way {
        Way::FileArgument => harness(Start::File(path.to_path_buf())),
        Way::Open => {
            let mut h = running();
            h.key_press_modifiers(Modifiers::COMMAND, Key::O);
            h.run_steps(2);
            assert!(
                h.state().file_browser().is_some(),
                "File › Open shows the chooser"
            );
            let name = h.get_by_role_and_label(Role::TextInput, "File name");
            name.focus();
            h.run_steps(1);
            h.get_by_role_and_label(Role::TextInput, "File name")
                .type_text(&path.display().to_string());
            h.run_steps(1);
            h.key_press(Key::Enter);
            h.run_steps(2);
            assert!(h.state().file_browser().is_none(), "the chooser closes");
            h
        }
        Way::Recent => {
            let mut h = running();
            h.state_mut().options.recent_files = vec![path.to_path_buf()];
            h.get_by_role_and_label(Role::Button, "File").click();
            h.run_steps(2);
            h.get_by_role_and_label(Role::Button, "Recent").click();
            h.run_steps(2);
            let name = path.file_name().unwrap().to_string_lossy();
            h.get_by_role_and_label(Role::Button, &name).click();
            h.run_steps(2);
            h
        }
        Way::Dropped => {
            let mut h = running();
            h.input_mut()
                .dropped_files
                .push(std::sync::Arc::new(Dropped(path.to_path_buf())));
            h.run_steps(2);
            h
        }
    };
    h.run_steps(2);
    h
}

/// Assert that `path` is open in `view` (and shown, for the views that are a tab's document).
fn assert_open(h: &Harness<'_, UgnisApp>, path: &Path, view: View, gradients_before: usize) {
    let app = h.state();
    let at = format!("{} by {view:?}", path.display());
    for title in [
        "Cannot open",
        "Cannot load gradient",
        "Cannot read the image",
    ] {
        assert!(h.query_by_label(title).is_none(), "{at}: {title}");
    }
    match view {
        View::Flame => {
            assert_eq!(app.tab, Tab::Flame, "{at}");
            assert_eq!(app.flame.file.path.as_deref(), Some(path), "{at}");
            assert!(!app.flame.file.flames.is_empty(), "{at}");
        }
        View::Escape => {
            assert_eq!(app.tab, Tab::Escape, "{at}");
            assert_eq!(app.escape.path.as_deref(), Some(path), "{at}");
        }
        View::Scene => {
            assert_eq!(app.tab, Tab::Scene, "{at}");
            assert_eq!(app.scene.path.as_deref(), Some(path), "{at}");
        }
        View::LSystem => {
            assert_eq!(app.tab, Tab::Explore, "{at}");
            assert_eq!(app.explore.topic, Topic::LSystems, "{at}");
            assert_eq!(app.explore.lsystem.file.as_deref(), Some(path), "{at}");
        }
        View::Gradients | View::GradientFromImage => {
            assert!(app.flame.gradients.open, "{at}");
            assert!(
                app.flame.gradients.library.len() > gradients_before,
                "{at}: no gradient added"
            );
        }
        View::RenderState => {
            assert_eq!(app.tab, Tab::Flame, "{at}");
            let resume = app
                .flame
                .export_dialog
                .as_ref()
                .and_then(|s| s.resume.as_ref());
            assert_eq!(resume.map(|r| r.path.as_path()), Some(path), "{at}");
        }
    }
}

#[test]
fn every_format_opens_in_its_view_from_every_way_into_the_editor() {
    let dir = folder("gui");
    let gradients_before = ugnis::gradient::builtin().len();
    for (path, view) in every_format(&dir) {
        assert_eq!(io::view_of(io::kind_of(&path)), view, "{}", path.display());
        for way in [Way::FileArgument, Way::Open, Way::Recent, Way::Dropped] {
            let h = open_by(way, &path);
            assert_open(&h, &path, view, gradients_before);
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Run the command line; its success and standard error.
fn ugnis(args: &[String]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ugnis"))
        .args(args)
        .arg("--progress")
        .arg("none")
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn every_format_is_read_by_the_command_line() {
    let dir = folder("cli");
    let out = dir.join("out");
    for (path, view) in every_format(&dir) {
        let file = path.display().to_string();
        let png = out.with_extension("png").display().to_string();
        let render = [
            "render",
            &file,
            "-o",
            &png,
            "--size",
            "32x24",
            "--quality",
            "1",
        ];
        let (ok, err) = ugnis(&render.map(String::from));
        if view == View::Flame {
            assert!(ok, "{file}: {err}");
            continue;
        }
        // Another view's file: refused, naming the command that reads it.
        assert!(!ok, "{file} rendered as a flame");
        let command = err
            .lines()
            .find_map(|l| l.trim().strip_prefix("try: "))
            .unwrap_or_else(|| panic!("{file}: no command named: {err}"));
        let mut args: Vec<String> = command
            .split(' ')
            .skip(1)
            .map(|a| a.replace("OUT", &out.display().to_string()))
            .collect();
        if matches!(args[0].as_str(), "escape" | "scene" | "lsystem") {
            args.extend(["--size", "32x24"].map(String::from));
        }
        let (ok, err) = ugnis(&args);
        assert!(ok, "{file}: `{command}`: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
