//! The editor driven through its real UI with egui_kittest: menus, shortcuts, triangle drags,
//! undo, the delete rule, Save → Open and the unsaved-changes question.
#![cfg(feature = "gui")]

use std::path::{Path, PathBuf};

use egui::accesskit::Role;
use egui::{Key, Modifiers, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::flame_tab::editor_state::Selected;
use ugnis::app::options::Options;
use ugnis::app::{MENU, Start, UgnisApp};
use ugnis::flame::{Affine, Flame};

use eframe::egui;

/// A private copy of an example (a test that saves must never touch the repository).
fn example(name: &str) -> PathBuf {
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

fn harness(start: Start) -> Harness<'static, UgnisApp> {
    let app = UgnisApp::new(Options::default(), start, None);
    let mut h = Harness::builder()
        .with_size(Vec2::new(1280.0, 860.0))
        .build_ui_state(|ui, app: &mut UgnisApp| app.ui(ui), app);
    h.run_steps(3);
    h
}

fn open(name: &str) -> Harness<'static, UgnisApp> {
    let h = harness(Start::File(example(name)));
    assert_eq!(h.state().flame.doc().name, name.trim_end_matches(".flame"));
    h
}

/// Drag with the primary button from `a` to `b` in a few moves.
fn drag(h: &mut Harness<'_, UgnisApp>, a: Pos2, b: Pos2) {
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

fn selected_coefs(app: &UgnisApp) -> Affine {
    match app.flame.editor.selected {
        Selected::Xform(i) => app.flame.doc().flame().xforms[i].coefs,
        Selected::Final => app.flame.doc().flame().final_xform.as_ref().unwrap().coefs,
    }
}

fn coefs(m: &Affine) -> [f64; 6] {
    [m.a, m.b, m.c, m.d, m.e, m.f]
}

#[test]
fn dragging_a_vertex_reshapes_by_the_affine_maths_and_undo_is_exact() {
    let mut h = open("sierpinski.flame");
    let original: Flame = h.state().flame.doc().flame().clone();
    assert!(!h.state().flame.doc().dirty);
    let before = selected_coefs(h.state());
    let tri = before.triangle();
    // Drag vertex B (the image of X = (1, 0)) by 30 px right and 20 px down.
    let st = &h.state().flame.editor;
    let from = st.screen_from_world(tri[1]);
    assert!(st.canvas.contains(from), "vertex B must be on the canvas");
    let to = from + Vec2::new(30.0, 20.0);
    let (w0, w1) = (st.world_from_screen(from), st.world_from_screen(to));
    drag(&mut h, from, to);

    let after = selected_coefs(h.state());
    let mut moved = tri;
    moved[1] = [tri[1][0] + (w1[0] - w0[0]), tri[1][1] + (w1[1] - w0[1])];
    let expect = Affine::from_triangle(moved);
    for (got, want) in coefs(&after).iter().zip(coefs(&expect)) {
        assert!((got - want).abs() < 1e-9, "{after:?} vs {expect:?}");
    }
    // Moving B changes only the first column: the origin (e, f) and C's column stay.
    assert!(after.a != before.a || after.c != before.c);
    assert_eq!(
        (after.b, after.d, after.e, after.f),
        (before.b, before.d, before.e, before.f)
    );
    assert!(h.state().flame.doc().dirty);

    // The whole drag is one undo step, and undo restores the exact flame.
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame(), &original);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Y);
    h.run_steps(2);
    assert_eq!(selected_coefs(h.state()), after);
}

#[test]
fn dragging_inside_a_triangle_moves_it() {
    let mut h = open("sierpinski.flame");
    let before = selected_coefs(h.state());
    let t = before.triangle();
    let c = [
        (t[0][0] + t[1][0] + t[2][0]) / 3.0,
        (t[0][1] + t[1][1] + t[2][1]) / 3.0,
    ];
    let st = &h.state().flame.editor;
    let from = st.screen_from_world(c);
    let to = from + Vec2::new(-25.0, 15.0);
    let (w0, w1) = (st.world_from_screen(from), st.world_from_screen(to));
    drag(&mut h, from, to);
    let after = selected_coefs(h.state());
    // Linear part unchanged, origin translated by the world delta (x' = a·x + b·y + e).
    assert_eq!(
        (after.a, after.b, after.c, after.d),
        (before.a, before.b, before.c, before.d)
    );
    let t2 = after.triangle();
    assert!((t2[0][0] - t[0][0] - (w1[0] - w0[0])).abs() < 1e-9);
    assert!((t2[0][1] - t[0][1] - (w1[1] - w0[1])).abs() < 1e-9);
}

fn context_menu_delete(h: &mut Harness<'_, UgnisApp>) {
    let p = h.state().flame.editor.canvas.center();
    h.event(egui::Event::PointerMoved(p));
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos: p,
            button: egui::PointerButton::Secondary,
            pressed,
            modifiers: Modifiers::NONE,
        });
    }
    h.run_steps(2);
    h.get_by_label("Delete triangle").click();
    h.run_steps(2);
}

#[test]
fn delete_is_refused_at_two_triangles() {
    // Three transforms plus the two its <symmetry kind="-2"/> adds.
    let mut h = open("sierpinski.flame");
    assert_eq!(h.state().flame.doc().flame().xforms.len(), 5);
    for n in [4, 3, 2, 2] {
        context_menu_delete(&mut h);
        assert_eq!(
            h.state().flame.doc().flame().xforms.len(),
            n,
            "delete below 2 must be refused"
        );
    }
    assert!(
        h.state().status().contains("refused"),
        "{}",
        h.state().status()
    );
    // Undo brings the third triangle back.
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame().xforms.len(), 3);
    assert!(h.state().flame.doc().can_undo());
}

#[test]
fn every_menu_item_exists_with_its_shortcut() {
    let mut h = open("sierpinski.flame");
    for menu in ugnis::app::actions::MENUS {
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
fn choosing_a_gradient_recolours_as_one_undo_step() {
    let mut h = open("sierpinski.flame");
    let before = h.state().flame.doc().flame().clone();
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    h.run_steps(2);
    h.get_by_label("glacier").click();
    h.run_steps(2);
    let f = h.state().flame.doc().flame();
    let glacier = ugnis::gradient::builtin_named("glacier").unwrap();
    assert_eq!(f.palette.colors, glacier.colors);
    assert_eq!(f.xforms, before.xforms, "only the colours change");
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame(), &before);
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
fn random_batch_is_browsed_beside_the_file_and_kept_into_it() {
    let mut h = open("sierpinski.flame");
    let data = std::env::temp_dir().join(format!("ugnis-gui-data-{}", std::process::id()));
    h.state_mut().flame.data_dir = Some(data.clone());
    let file_flames = h.state().flame.doc().flames.clone();
    h.key_press_modifiers(Modifiers::COMMAND, Key::B);
    let t = std::time::Instant::now();
    while h.state().flame.batch.as_ref().is_none() {
        assert!(t.elapsed().as_secs() < 120, "no batch after 2 minutes");
        std::thread::sleep(std::time::Duration::from_millis(50));
        h.step();
    }
    h.run_steps(2);
    let batch = h.state().flame.batch.as_ref().unwrap().flames.clone();
    assert_eq!(batch.len(), 100);
    assert_eq!(batch[1].name, "random-002");
    // Kept as the last batch in the data directory, and the open file is untouched.
    let saved = ugnis::io::read_flames(&data.join("last-batch.fla"), &Default::default())
        .unwrap()
        .value;
    assert_eq!(saved.len(), 100);
    assert_eq!(h.state().flame.file.flames, file_flames);
    assert!(!h.state().flame.file.dirty);

    // A click loads a batch flame into the editor.
    h.get_by_label("random-002").click();
    h.run_steps(2);
    assert!(h.state().flame.viewing_batch());
    assert_eq!(h.state().flame.doc().flame().name, "random-002");
    // Keep copies it (here the first visible one, random-001) into the open file.
    h.get_all_by_label("Keep").next().unwrap().click();
    h.run_steps(2);
    assert!(!h.state().flame.viewing_batch());
    let f = &h.state().flame.doc();
    assert_eq!(f.flames.len(), file_flames.len() + 1);
    assert_eq!(f.flame().name, "random-001");
    assert!(f.dirty);
    // Undo in the file removes it again.
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flames, file_flames);
    let _ = std::fs::remove_dir_all(&data);
}

#[test]
fn mutation_window_makes_a_mutant_current_and_undo_returns() {
    let mut h = open("sierpinski.flame");
    let before = h.state().flame.doc().flame().clone();
    h.key_press_modifiers(Modifiers::COMMAND, Key::U);
    h.run_steps(2);
    assert!(h.state().flame.mutations.open);
    let mutants = h.state().flame.mutations.mutants.clone();
    assert_eq!(mutants.len(), 8);
    assert!(mutants.iter().all(|m| m.xforms != before.xforms));
    h.get_by_role_and_label(Role::Button, "+ transform").click();
    h.run_steps(2);
    let now = h.state().flame.doc().flame().clone();
    assert_eq!(now.xforms.len(), before.xforms.len() + 1);
    assert_eq!(now, mutants[3]);
    // The grid moves on: new mutants around the new centre.
    assert_ne!(h.state().flame.mutations.mutants, mutants);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame(), &before);
}

#[test]
fn morph_plays_in_betweens_to_the_next_flame_without_editing() {
    let mut h = harness(Start::File(example("gallery.fla")));
    assert_eq!(h.state().flame.doc().flames.len(), 4);
    let before = h.state().flame.doc().flame().clone();
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::M);
    h.run_steps(2);
    let m = h
        .state()
        .flame
        .morph
        .as_ref()
        .expect("Ctrl+Shift+M starts the morph");
    assert_eq!(m.frames.len(), ugnis::app::MORPH_FRAMES);
    // The first frame is the current flame: its xforms, then the next flame's extra ones
    // faded out to weight 0.
    let n0 = before.xforms.len();
    assert!(m.frames[0].xforms[..n0] == before.xforms[..]);
    assert!(m.frames[0].xforms[n0..].iter().all(|x| x.weight == 0.0));
    let next = &h.state().flame.doc().flames[1];
    let last = &m.frames[m.frames.len() - 1];
    assert_eq!(
        last.xforms.len(),
        next.xforms.len().max(before.xforms.len())
    );
    assert_eq!(last.palette, next.palette);
    // The preview plays the frames (each waits for the previous one to be shown).
    let mut seen = 0;
    for _ in 0..400 {
        h.run_steps(1);
        seen = seen.max(h.state().flame.morph.as_ref().unwrap().index);
        if seen >= 3 {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(25));
    }
    assert!(seen >= 3, "the morph did not advance");
    assert!(h.state().status().contains("orchid -> ember-swirl"));
    // The document is untouched; any edit stops the morph.
    assert!(h.state().flame.doc().flame() == &before);
    assert!(!h.state().flame.doc().dirty);
    h.key_press_modifiers(Modifiers::COMMAND, Key::R);
    h.run_steps(3);
    assert!(h.state().flame.morph.is_none());
    // A single flame has nothing to morph to.
    let mut h = open("sierpinski.flame");
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::M);
    h.run_steps(2);
    assert!(h.state().flame.morph.is_none());
    assert!(h.state().status().contains("two or more flames"));
}

fn escape_tab() -> Harness<'static, UgnisApp> {
    let mut h = open("sierpinski.flame");
    h.get_by_role_and_label(Role::Button, "Escape-time").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Escape);
    h
}

/// Centre of the escape canvas in screen points (the right of the controls panel).
fn escape_canvas_point(h: &Harness<'_, UgnisApp>, fx: f32, fy: f32) -> Pos2 {
    // The canvas fills the central panel: right of the controls, between the bars.
    let back = h.get_by_role_and_label(Role::Button, "Reset view").rect();
    let left = back.right() + 120.0;
    let (top, bottom, right) = (80.0, 800.0, 1270.0);
    Pos2::new(left + (right - left) * fx, top + (bottom - top) * fy)
}

#[test]
fn escape_tab_clicks_open_julia_sets_and_back_returns() {
    let mut h = escape_tab();
    let before = h.state().escape.doc.clone();
    assert_eq!(before.params.family.name(), "mandelbrot");
    let p = escape_canvas_point(&h, 0.3, 0.4);
    h.hover_at(p);
    h.run_steps(2);
    let c = h.state().escape.hover.expect("the cursor's c");
    h.event(egui::Event::PointerButton {
        pos: p,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    h.event(egui::Event::PointerButton {
        pos: p,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    h.run_steps(3);
    match &h.state().escape.doc.params.family {
        ugnis::escape::Family::Julia { c: jc, power } => {
            assert_eq!(*power, 2);
            assert!((jc.re - c.re).abs() < 1e-12 && (jc.im - c.im).abs() < 1e-12);
        }
        f => panic!("clicking the Mandelbrot set should open a Julia set, got {f:?}"),
    }
    h.get_by_role_and_label(Role::Button, "Back").click();
    h.run_steps(2);
    assert_eq!(h.state().escape.doc.params.family, before.params.family);
    assert_eq!(h.state().escape.doc.view.center, before.view.center);
}

#[test]
fn escape_tab_zooms_past_f64_by_perturbation() {
    let mut h = escape_tab();
    let c = ugnis::io::escape_view::parse_center(
        "-0.743643887037158704752191506114774, 0.131825904205311970493132056385139",
    )
    .unwrap();
    {
        let e = &mut h.state_mut().escape;
        e.doc.view = e.doc.view.with_center_dd(c);
        e.doc.view.half_height = 1e-11;
    }
    h.run_steps(2);
    let (w, ht) = (h.state().escape.doc.width, h.state().escape.doc.height);
    let mid = [w as f64 / 2.0, ht as f64 / 2.0];
    // Twenty doublings at the centre: 1e-11 → 1e-17, far past the f64 limit.
    for _ in 0..20 {
        h.state_mut().escape.zoom_at(mid, 2.0);
    }
    h.run_steps(2);
    let v1 = h.state().escape.doc.view;
    assert!(v1.half_height < 1e-16, "{v1:?}");
    assert!(
        !h.state().escape.notices.status.contains("limit"),
        "{}",
        h.state().escape.notices.status
    );
    assert!(
        h.state()
            .escape
            .status_text()
            .contains("deep zoom, centre -0.74364388703715870475")
    );
    // A drag pans by exactly the dragged pixels, although the f64 centre cannot move.
    let p = escape_canvas_point(&h, 0.5, 0.5);
    let q = p + Vec2::new(80.0, 0.0);
    drag(&mut h, p, q);
    h.run_steps(2);
    let v2 = h.state().escape.doc.view;
    assert_eq!(v2.center, v1.center);
    let moved = v1.pixel_of(&v2, 0.0, 0.0, w, ht)[0] - 0.5;
    let ppp = h.ctx.pixels_per_point() as f64;
    assert!((moved + 80.0 * ppp).abs() < 1.0, "moved {moved} pixels");
    // Past the double-double limit the zoom stops with a message.
    h.state_mut().escape.zoom_at(mid, 1e13);
    assert!(
        h.state().escape.notices.status.contains("deep-zoom limit"),
        "{}",
        h.state().escape.notices.status
    );
    assert_eq!(h.state().escape.doc.view, v2);
}

#[test]
fn escape_tab_rectangle_zoom_and_pan() {
    let mut h = escape_tab();
    let v0 = h.state().escape.doc.view;
    // Right-drag a rectangle: the view zooms to it.
    let a = escape_canvas_point(&h, 0.4, 0.4);
    let b = escape_canvas_point(&h, 0.6, 0.6);
    h.hover_at(a);
    h.step();
    h.event(egui::Event::PointerButton {
        pos: a,
        button: egui::PointerButton::Secondary,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    h.step();
    for k in 1..=4 {
        h.hover_at(a + (b - a) * (k as f32 / 4.0));
        h.step();
    }
    h.event(egui::Event::PointerButton {
        pos: b,
        button: egui::PointerButton::Secondary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    h.run_steps(3);
    let v1 = h.state().escape.doc.view;
    assert!(v1.half_height < v0.half_height * 0.3, "{v1:?}");
    // Dragging pans: the world point under the pointer follows it.
    let p = escape_canvas_point(&h, 0.5, 0.5);
    let q = p + Vec2::new(100.0, -50.0);
    h.hover_at(p);
    h.run_steps(2);
    let w_before = h.state().escape.hover.unwrap();
    h.drag_at(p);
    h.step();
    for k in 1..=4 {
        h.hover_at(p + (q - p) * (k as f32 / 4.0));
        h.step();
    }
    h.drop_at(q);
    h.run_steps(2);
    h.hover_at(q);
    h.run_steps(2);
    let w_after = h.state().escape.hover.unwrap();
    let px = h
        .state()
        .escape
        .doc
        .view
        .pixel_size(h.state().escape.doc.height);
    assert!(
        (w_after.re - w_before.re).abs() < 2.0 * px && (w_after.im - w_before.im).abs() < 2.0 * px,
        "{w_before:?} → {w_after:?}"
    );
    // Back twice returns to the start.
    h.get_by_role_and_label(Role::Button, "Back").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Back").click();
    h.run_steps(2);
    assert_eq!(h.state().escape.doc.view.center, v0.center);
}

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
        .set_source(ugnis::app::scene_tab::TextureSource::Checker, &flame, &esc);
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

// ---------------------------------------------------------------------------------------
// Issue 13: the fixes and the missing pieces.

fn harness_sized(start: Start, w: f32, h: f32) -> Harness<'static, UgnisApp> {
    let app = UgnisApp::new(Options::default(), start, None);
    let mut h = Harness::builder()
        .with_size(Vec2::new(w, h))
        .build_ui_state(|ui, app: &mut UgnisApp| app.ui(ui), app);
    h.run_steps(3);
    h
}

fn section(h: &mut Harness<'_, UgnisApp>, name: &str) {
    h.get_by_role_and_label(Role::Button, name).click();
    h.run_steps(2);
}

fn set_number(h: &mut Harness<'_, UgnisApp>, name: &str, v: f64) {
    h.get_by_role_and_label(Role::SpinButton, name)
        .set_value_accesskit(v);
    h.run_steps(2);
}

#[test]
fn the_triangle_editor_shows_y_up_everywhere() {
    let mut h = open("sierpinski.flame");
    // Corner C typed as y = +0.62 (up) is stored as world y = −0.62 and drawn above O.
    set_number(&mut h, "C y", 0.62);
    let m = selected_coefs(h.state());
    let t = m.triangle();
    assert!((t[2][1] + 0.62).abs() < 1e-12, "{t:?}");
    let st = &h.state().flame.editor;
    let axis = st.screen_from_world([t[2][0], 0.0]).y;
    assert!(
        st.screen_from_world(t[2]).y < axis,
        "drawn above the x axis"
    );
    // Over the reference triangle's Y corner the status bar reads y = +1.
    let y = st.screen_from_world([0.0, -1.0]);
    h.hover_at(y);
    h.run_steps(2);
    assert!(
        h.query_by_label_contains("y 1.0000").is_some(),
        "the status bar shows y up"
    );
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
fn one_drag_of_the_colour_slider_is_one_undo_step() {
    let mut h = open("sierpinski.flame");
    let before = h.state().flame.doc().undo_len();
    let c0 = h.state().flame.doc().flame().xforms[0].color;
    let r = h.get_by_role_and_label(Role::Slider, "Colour").rect();
    let a = r.left_center() + Vec2::new(4.0, 0.0);
    let b = r.right_center() - Vec2::new(4.0, 0.0);
    drag(&mut h, a, b);
    h.run_steps(2);
    let c1 = h.state().flame.doc().flame().xforms[0].color;
    assert!(c1 > c0 + 0.5, "{c0} → {c1}");
    assert_eq!(h.state().flame.doc().undo_len(), before + 1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame().xforms[0].color, c0);
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
fn find_narrows_the_variation_list_with_all_ticked() {
    let mut h = open("sierpinski.flame");
    section(&mut h, "Variations");
    h.get_by_role_and_label(Role::CheckBox, "all").click();
    h.run_steps(2);
    assert!(
        h.query_by_label("spherical").is_some(),
        "all lists every name"
    );
    h.get_by_role_and_label(Role::TextInput, "Find").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "Find")
        .type_text("julian");
    h.run_steps(3);
    assert!(
        h.query_by_role_and_label(Role::SpinButton, "julian")
            .is_some()
    );
    assert!(h.query_by_label("pre_julian").is_some());
    assert!(h.query_by_label("spherical").is_none(), "Find narrows");
    // A weight typed into a listed name adds it.
    set_number(&mut h, "julian", 0.5);
    let x = &h.state().flame.doc().flame().xforms[0];
    let j = ugnis::flame::variations::by_name("julian").unwrap();
    assert!(x.vars.iter().any(|v| v.id == j && v.weight == 0.5));
}

#[test]
fn the_palette_rule_is_chosen_in_the_flame_settings() {
    use ugnis::flame::PaletteIndex;
    // Tall enough for the whole Settings grid to be on screen.
    let mut h = harness_sized(Start::File(example("sierpinski.flame")), 1280.0, 1600.0);
    section(&mut h, "Settings");
    assert_eq!(
        h.state().flame.doc().flame().palette_index,
        PaletteIndex::Flam3
    );
    h.get_by_role_and_label(Role::ComboBox, "rule").click();
    h.run_steps(3);
    h.get_by_label("as Fractorium").click();
    h.run_steps(2);
    assert_eq!(
        h.state().flame.doc().flame().palette_index,
        PaletteIndex::Fractorium
    );
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(
        h.state().flame.doc().flame().palette_index,
        PaletteIndex::Flam3
    );
}

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
    let ugnis::surface::scene::Geometry::QuaternionJulia(q) = o.geometry else {
        panic!("the first object is the Julia set");
    };
    let ugnis::surface::scene::Geometry::QuaternionJulia(q0) = want.objects[0].geometry else {
        panic!("read back");
    };
    assert_eq!((q.c[0], q.slice_value), (-2.5, 3.0));
    assert_eq!(q, q0);
    assert_eq!((o.material.ks, o.material.shininess), (1.5, 300.0));
    assert_eq!(h.state().scene.scene.lights, want.lights);
}

#[test]
fn the_transform_list_selects_reorders_and_switches_off() {
    let mut h = open("sierpinski.flame");
    section(&mut h, "Transforms");
    h.get_by_label("Transform 2").click();
    h.run_steps(2);
    assert_eq!(h.state().flame.editor.selected, Selected::Xform(1));
    let before = h.state().flame.doc().flame().clone();
    h.get_all_by_role_and_label(Role::Button, "Down")
        .nth(1)
        .unwrap()
        .click();
    h.run_steps(2);
    let f = h.state().flame.doc().flame().clone();
    assert_eq!(f.xforms[2].coefs, before.xforms[1].coefs);
    assert_eq!(f.xforms[1].coefs, before.xforms[2].coefs);
    assert_eq!(h.state().flame.editor.selected, Selected::Xform(2));
    // Off: weight 0; on again: the old weight.
    let w = f.xforms[0].weight;
    h.get_all_by_role(Role::CheckBox).next().unwrap().click();
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame().xforms[0].weight, 0.0);
    h.get_all_by_role(Role::CheckBox).next().unwrap().click();
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame().xforms[0].weight, w);
    for _ in 0..3 {
        h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
        h.run_steps(2);
    }
    assert_eq!(h.state().flame.doc().flame(), &before);
}

#[test]
fn the_xaos_matrix_edits_the_chaos_rows() {
    let mut h = open("sierpinski.flame");
    section(&mut h, "Xaos");
    set_number(&mut h, "xaos 1 to 2", 0.0);
    let f = h.state().flame.doc().flame();
    assert_eq!(f.xforms[0].chaos.get(1), Some(&0.0));
    assert_eq!(f.xforms[0].chaos[0], 1.0);
    assert!(f.xforms[1].chaos.is_empty());
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert!(h.state().flame.doc().flame().xforms[0].chaos.is_empty());
}

#[test]
fn the_palette_editor_adjusts_the_gradient_as_one_undo_step() {
    let mut h = open("sierpinski.flame");
    let before = h.state().flame.doc().flame().palette.clone();
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::G);
    h.run_steps(3);
    assert!(h.state().flame.palette_editor.open);
    set_number(&mut h, "Saturation", -1.0);
    let g = &h.state().flame.doc().flame().palette;
    assert!(
        g.colors
            .iter()
            .all(|c| (c[0] - c[1]).abs() < 1e-9 && (c[1] - c[2]).abs() < 1e-9)
    );
    assert_ne!(g.colors, before.colors);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(3);
    assert_eq!(h.state().flame.doc().flame().palette.colors, before.colors);
}

#[test]
fn the_camera_moves_with_the_mouse_on_the_preview() {
    let mut h = open("sierpinski.flame");
    let f0 = h.state().flame.doc().flame().clone();
    let r = h.state().flame.preview_rect.unwrap();
    let k = f0.ppu() * r.width() as f64 / f0.width as f64;
    // Drag: the centre moves against the pointer by the dragged distance in world units.
    let a = r.center();
    drag(&mut h, a, a + Vec2::new(40.0, 0.0));
    let f1 = h.state().flame.doc().flame().clone();
    let (s, c) = f0.rotate.to_radians().sin_cos();
    let dx = 40.0 / k;
    assert!(
        (f1.center[0] - (f0.center[0] - c * dx)).abs() < 1e-6,
        "{:?}",
        f1.center
    );
    assert!((f1.center[1] - (f0.center[1] + s * dx)).abs() < 1e-6);
    assert_eq!(h.state().flame.doc().undo_len(), 1);
    // Wheel: zooms in at the pointer, one undo step.
    h.hover_at(a);
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: Vec2::new(0.0, 60.0),
        modifiers: Modifiers::NONE,
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
    });
    h.run_steps(30);
    let f2 = h.state().flame.doc().flame().clone();
    assert!(f2.zoom > f1.zoom, "{} → {}", f1.zoom, f2.zoom);
    assert_eq!(h.state().flame.doc().undo_len(), 2);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run_steps(2);
    assert_eq!(h.state().flame.doc().flame(), &f0);
}

#[test]
fn a_typed_weight_is_kept_and_says_why() {
    let mut h = harness(Start::Random(7));
    assert!(h.state().flame.auto_weights(&h.state().options));
    set_number(&mut h, "Weight", 0.3);
    let f = h.state().flame.doc().flame();
    assert_eq!(f.xforms[0].weight, 0.3);
    assert_eq!(
        f.auto_weights,
        Some(false),
        "typing a weight switches the rule off"
    );
}

#[test]
fn the_first_start_shows_a_colourful_flame() {
    use ugnis::app::flame_tab::first_flame::{colour_share, colourfulness};
    for seed in 1..=3u64 {
        let app = UgnisApp::new(Options::default(), Start::Random(seed), None);
        let f = app.flame.doc().flame();
        assert!(colourfulness(&f.palette) >= 0.45, "{}", f.palette.name);
        assert!(ugnis::flame::random::passes_render_test(f));
        let share = colour_share(f);
        assert!(share >= 0.3, "seed {seed}: {share}");
    }
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
        Some(ugnis::app::help::HelpPage::Shortcuts),
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

#[test]
fn random_flames_use_the_variations_filter() {
    let mut h = open("sierpinski.flame");
    h.state_mut().options.variation_filter = vec!["julia".into(), "bubble".into()];
    h.get_by_role_and_label(Role::Button, "Tools").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Random variations")
        .click();
    h.run_steps(2);
    h.get_by_label("From the variations filter").click();
    h.run_steps(2);
    assert!(h.state().options.use_variation_filter);
    h.key_press_modifiers(Modifiers::COMMAND, Key::R);
    h.run_steps(2);
    use ugnis::flame::variations;
    let ok = [
        variations::by_name("julia").unwrap(),
        variations::by_name("bubble").unwrap(),
        variations::LINEAR,
    ];
    for x in &h.state().flame.doc().flame().xforms {
        for v in &x.vars {
            assert!(ok.contains(&v.id), "{}", variations::info(v.id).name);
        }
    }
    // The filter window ticks and unticks names.
    h.state_mut().flame.variation_filter.open = true;
    h.run_steps(2);
    h.get_by_role_and_label(Role::TextInput, "Find").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "Find")
        .type_text("swirl");
    h.run_steps(3);
    h.get_by_role_and_label(Role::CheckBox, "swirl").click();
    h.run_steps(2);
    assert!(
        h.state()
            .options
            .variation_filter
            .contains(&"swirl".to_string())
    );
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
        .set_source(ugnis::app::scene_tab::TextureSource::Checker, &flame, &esc);
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

// ---------------------------------------------------------------------------------------------
// The Explore tab

fn explore_tab() -> Harness<'static, UgnisApp> {
    let mut h = open("sierpinski.flame");
    h.get_by_role_and_label(Role::Button, "Explore").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Explore);
    h
}

/// Choose a topic in the list at the left (the first widget with its name: the list is drawn
/// before the topic's heading).
fn explore_topic(h: &mut Harness<'_, UgnisApp>, name: &str) {
    h.get_all_by_label(name).next().unwrap().click();
    h.run_steps(3);
}

#[test]
fn explore_every_topic_shows_its_numbers() {
    use ugnis::app::explore_tab::Topic;
    let mut h = explore_tab();
    // The default topic: the Koch curve at step 3.
    assert_eq!(h.state().explore.topic, Topic::Classic);
    assert!(h.query_by_label("Similarity dimension: 1.26186").is_some());
    explore_topic(&mut h, "Chaos game");
    assert_eq!(h.state().explore.topic, Topic::ChaosGame);
    assert!(h.query_by_label_contains("Points plotted: ").is_some());
    assert!(h.query_by_label("Similarity dimension: 1.58496").is_some());
    explore_topic(&mut h, "L-systems");
    assert_eq!(h.state().explore.topic, Topic::LSystems);
    // The first preset: the Koch curve at order 4, 4⁴ segments.
    assert!(h.query_by_label("Segments: 256").is_some());
    assert!(h.query_by_label("Segments drawn here: 256").is_some());
    explore_topic(&mut h, "Fractal interpolation");
    // Equal spacing: D = 1 + log Σ|d| / log N with d = (0.5, −0.5, 0.5).
    let d = 1.0 + 1.5f64.ln() / 3f64.ln();
    assert!(
        h.query_by_label(&format!("Dimension D = {d:.5}")).is_some(),
        "{d}"
    );
    explore_topic(&mut h, "Julia by inverse iteration");
    assert!(
        h.query_by_label("c is in the Mandelbrot set: J_c is connected")
            .is_some()
    );
    assert!(h.state().explore.julia.covered > 1000, "no preimages drawn");
    explore_topic(&mut h, "Lorenz attractor");
    assert!(
        h.query_by_label("Equilibrium (8.4853, 8.4853, 27.0000)")
            .is_some()
    );
    // Two starts 1e-9 apart are more than 1 apart by t = 40.
    let l = &h.state().explore.lorenz;
    assert!(l.distance > 1.0 && l.apart_at.is_some_and(|t| t > 20.0 && t < 40.0));
    explore_topic(&mut h, "Dimension");
    assert!(h.query_by_label("Similarity dimension: 1.26186").is_some());
    assert!(
        h.query_by_label_contains("D = 1 − slope = 1.3712")
            .is_some()
    );
    // Box counting of the Sierpinski preset runs in the background.
    let t = std::time::Instant::now();
    while h.state().explore.dimension.result.is_none() {
        assert!(t.elapsed() < std::time::Duration::from_secs(60));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    let dim = h.state().explore.dimension.result.as_ref().unwrap();
    let d = dim.count.dimension().unwrap();
    assert!((d - 1.585).abs() < 0.05, "{d}");
    assert!(
        h.query_by_label_contains("Box-counting dimension ≈ ")
            .is_some()
    );
}

#[test]
fn explore_koch_step_3_has_64_segments_of_total_length_four_thirds_cubed() {
    use ugnis::explore::classic::Construction;
    let mut h = explore_tab();
    h.state_mut().explore.classic.construction = Construction::Cantor;
    h.get_by_label("Koch curve").click();
    h.run_steps(2);
    h.state_mut().explore.classic.step = 3;
    h.run_steps(2);
    assert_eq!(
        h.state().explore.classic.construction,
        Construction::KochCurve
    );
    assert!(h.query_by_label("Segments: 64 = 4^n").is_some());
    let len = (4.0f64 / 3.0).powi(3);
    assert!(
        h.query_by_label(&format!("Length: {len:.6} = (4/3)^n"))
            .is_some()
    );
    assert_eq!(format!("{len:.6}"), "2.370370");
    // Another construction, same step.
    h.get_by_label("Sierpinski carpet").click();
    h.run_steps(2);
    assert!(h.query_by_label("Squares: 512 = 8^n").is_some());
    assert!(h.query_by_label("Similarity dimension: 1.89279").is_some());
}

#[test]
fn explore_lsystem_editor_shows_a_bad_rule_with_its_line() {
    let mut h = explore_tab();
    explore_topic(&mut h, "L-systems");
    h.state_mut()
        .explore
        .lsystem
        .set_text("Bad {\n  Angle 6\n  Axiom F\n  F=F+@\n}\n");
    h.run_steps(2);
    let e = h.state().explore.lsystem.error.clone().unwrap();
    assert!(e.starts_with("Line 4, column "), "{e}");
    assert!(h.query_by_label(&e).is_some());
    assert!(h.query_by_label("(nothing drawn)").is_some());
    // Typing in the editor redraws: a good rule again.
    h.state_mut()
        .explore
        .lsystem
        .set_text("Good {\n  Angle 6\n  Axiom F\n  F=F+F--F+F\n}\n");
    h.run_steps(2);
    assert!(h.state().explore.lsystem.error.is_none());
    assert!(h.query_by_label("Segments: 256").is_some());
    let node = h.get_by_label("L-system text");
    node.focus();
    h.run_steps(1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.run_steps(1);
    h.get_by_label("L-system text")
        .type_text("T {\n Angle 4\n Axiom F\n F=F+F-F-FF+F+F-F\n}");
    h.run_steps(2);
    // 8 segments per F: 8⁴ at order 4.
    assert!(
        h.query_by_label("Segments: 4096").is_some(),
        "{:?} {:?}",
        h.state().explore.lsystem.text,
        h.state().explore.lsystem.error
    );
}

#[test]
fn explore_lsystem_over_the_live_cap_says_so_and_exports() {
    let mut h = explore_tab();
    explore_topic(&mut h, "L-systems");
    h.state_mut()
        .explore
        .lsystem
        .set_text("Koch {\n  Angle 6\n  Axiom F\n  F=F+F--F+F\n}\n");
    h.state_mut().explore.lsystem.order = 10;
    h.run_steps(3);
    let note = h.state().explore.lsystem.note.clone().unwrap();
    assert!(note.contains("1048576 segments"), "{note}");
    assert_eq!(h.state().explore.lsystem.drawn, 0);
    // Order 3 is drawn; its SVG export has one path point per segment.
    h.state_mut().explore.lsystem.order = 3;
    h.run_steps(2);
    assert!(h.state().explore.lsystem.note.is_none());
    assert_eq!(h.state().explore.lsystem.drawn, 64);
    let out = example("sierpinski.flame").with_file_name("koch.svg");
    h.state_mut().explore.lsystem.export(out.clone());
    let t = std::time::Instant::now();
    while !h.state().status().starts_with("Exported") {
        assert!(t.elapsed() < std::time::Duration::from_secs(30));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(
        svg.starts_with("<?xml") || svg.starts_with("<svg"),
        "{}",
        &svg[..40]
    );
}

#[test]
fn explore_chaos_game_adds_points_over_frames_and_stops_when_paused() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Chaos game");
    let a = h.state().explore.chaos.plotted;
    h.run_steps(5);
    let b = h.state().explore.chaos.plotted;
    assert!(b > a, "{a} -> {b}");
    let speed = h.state().explore.chaos.speed as u64;
    assert_eq!(speed, 20);
    assert_eq!((b - a) % speed, 0);
    assert!(h.query_by_label(&format!("Points plotted: {b}")).is_some());
    h.get_by_label("Pause").click();
    h.run_steps(2);
    let c = h.state().explore.chaos.plotted;
    h.run_steps(5);
    assert_eq!(
        h.state().explore.chaos.plotted,
        c,
        "paused, yet points were added"
    );
    h.get_by_label("Resume").click();
    h.run_steps(3);
    assert!(h.state().explore.chaos.plotted > c);
    h.get_by_label("Reset").click();
    h.run_steps(1);
    assert!(h.state().explore.chaos.plotted <= 2 * speed);
}

#[test]
fn explore_chaos_preset_opens_in_the_flame_tab_asking_about_unsaved_changes() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Chaos game");
    h.state_mut().flame.file.dirty = true;
    h.get_by_label("Open in Flame tab").click();
    h.run_steps(3);
    // The question comes first; Cancel keeps everything.
    h.get_by_label("Cancel").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Explore);
    assert_eq!(h.state().flame.doc().name, "sierpinski");
    h.get_by_label("Open in Flame tab").click();
    h.run_steps(3);
    h.get_by_label("Discard").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Flame);
    let f = h.state().flame.doc().flame();
    assert_eq!(f.xforms.len(), 3);
    assert!((f.xforms[0].coefs.a - 0.5).abs() < 1e-12);
}

#[test]
fn explore_fif_dimension_follows_the_vertical_scalings() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Fractal interpolation");
    let label = |d: f64| format!("Dimension D = {d:.5}");
    assert!(
        h.query_by_label(&label(1.0 + 1.5f64.ln() / 3f64.ln()))
            .is_some()
    );
    h.state_mut().explore.fif.set_scaling(1, 0.9);
    h.run_steps(2);
    let d = 1.0 + 1.9f64.ln() / 3f64.ln();
    assert!(h.query_by_label(&label(d)).is_some(), "{d}");
    assert!((h.state().explore.fif.fif.dimension() - d).abs() < 1e-9);
    h.get_by_label("All d = 0").click();
    h.run_steps(2);
    assert!(h.query_by_label(&label(1.0)).is_some());
    // A scaling of 1 is refused with the engine's reason.
    h.state_mut().explore.fif.set_scaling(2, 1.0);
    h.run_steps(2);
    assert!(
        h.query_by_label_contains("must lie strictly between")
            .is_some()
    );
}

#[test]
fn explore_lsystem_file_entries_are_all_selectable() {
    let mut h = explore_tab();
    explore_topic(&mut h, "L-systems");
    let path = example("sierpinski.flame").with_file_name("two.l");
    std::fs::write(
        &path,
        "Koch {\r\n  Angle 6\r\n  Axiom F\r\n  F=F+F--F+F\r\n}\r\n\
         Square { ; quadratic Koch island\r\n  Angle 4\r\n  Axiom F+F+F+F\r\n  F=F+F-F-FF+F+F-F\r\n}\r\n",
    )
    .unwrap();
    let n = h.state_mut().explore.lsystem.open(&path);
    assert!(format!("{n:?}").contains("2 entries"), "{n:?}");
    h.state_mut().explore.lsystem.order = 1;
    h.run_steps(3);
    assert_eq!(h.state().explore.lsystem.entries.len(), 2);
    assert!(h.query_by_label("Segments: 4").is_some());
    h.state_mut().explore.lsystem.choose_entry(1);
    h.run_steps(3);
    assert_eq!(h.state().explore.lsystem.system().unwrap().name, "Square");
    // Four sides of eight segments each.
    assert!(h.query_by_label("Segments: 32").is_some());
    assert_eq!(h.state().explore.lsystem.drawn, 32);
}

#[test]
fn explore_menger_sponge_opens_in_the_scene_tab() {
    let mut h = explore_tab();
    h.get_by_label("Open in Scene tab").click();
    h.run_steps(3);
    assert_eq!(h.state().tab, ugnis::app::Tab::Scene);
    assert_eq!(h.state().scene.scene.objects.len(), 1);
    assert!(h.state().status().contains("Menger sponge, step 2"));
}

#[test]
fn explore_a_typed_number_out_of_range_is_refused_with_its_limits() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Julia by inverse iteration");
    h.get_by_label("c real part").click();
    h.run_steps(1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.get_by_label("c real part").type_text("5");
    h.key_press(Key::Enter);
    h.run_steps(3);
    assert_eq!(
        h.state().explore.julia.c[0],
        2.0,
        "brought back to the limit"
    );
    assert!(
        h.query_by_label("Re c is 5; it must be between -2 and 2")
            .is_some()
    );
}

#[test]
fn explore_fif_points_are_dragged_and_added_with_the_mouse() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Fractal interpolation");
    let p1 = h.state().explore.fif.fif.points()[1];
    let from = h.state().explore.fif.screen_of(p1).unwrap();
    let target = [p1[0], p1[1] + 0.5];
    let to = h.state().explore.fif.screen_of(target).unwrap();
    drag(&mut h, from, to);
    let q = h.state().explore.fif.fif.points()[1];
    assert!(
        (q[0] - target[0]).abs() < 0.01 && (q[1] - target[1]).abs() < 0.01,
        "{q:?}"
    );
    // A click away from the points adds one between its neighbours along x.
    let at = h.state().explore.fif.screen_of([0.5, -0.5]).unwrap();
    h.hover_at(at);
    h.step();
    h.get_by_label("Data points: 4");
    h.drag_at(at);
    h.step();
    h.drop_at(at);
    h.run_steps(3);
    let pts = h.state().explore.fif.fif.points().to_vec();
    assert_eq!(pts.len(), 5);
    assert!(
        (pts[2][0] - 0.5).abs() < 0.01 && (pts[2][1] + 0.5).abs() < 0.01,
        "{pts:?}"
    );
    assert_eq!(h.state().explore.fif.fif.scalings().len(), 4);
    assert!(h.query_by_label("Data points: 5").is_some());
}

#[test]
fn explore_box_counting_of_the_current_flame() {
    use ugnis::app::explore_tab::dimension::BoxSource;
    // The flame tab holds the Sierpinski triangle as a flame (no symmetry transforms).
    let ifs = ugnis::explore::ifs::presets::kovacs_sierpinski();
    let flame = ifs.to_flame(&Options::default().new_flame());
    let mut h = harness(Start::Flames(vec![flame]));
    h.get_by_role_and_label(Role::Button, "Explore").click();
    h.run_steps(3);
    explore_topic(&mut h, "Dimension");
    // Wait for the automatic count of the first preset, then count the flame tab's flame.
    wait_until(&mut h, |a| {
        !a.explore.dimension.busy() && a.explore.dimension.result.is_some()
    });
    h.state_mut().explore.dimension.source = BoxSource::Flame;
    h.state_mut().explore.dimension.points = 300_000.0;
    h.run_steps(1);
    h.get_by_label("Count boxes").click();
    h.run_steps(1);
    wait_until(&mut h, |a| {
        a.explore
            .dimension
            .result
            .as_ref()
            .is_some_and(|r| r.source.contains("flame"))
    });
    let r = h.state().explore.dimension.result.clone().unwrap();
    assert_eq!(r.count.samples, 300_000);
    // log 3 / log 2.
    let d = r.count.dimension().unwrap();
    assert!((d - 1.585).abs() < 0.06, "{d}");
    assert!(h.state().status().contains("Box counting of the flame"));
}

#[test]
fn explore_box_counting_of_an_image_file() {
    let mut h = explore_tab();
    explore_topic(&mut h, "Dimension");
    // A white square on black: dimension 2.
    let path = example("sierpinski.flame").with_file_name("square.png");
    let img = image::RgbImage::from_fn(512, 512, |x, y| {
        let inside = (64..448).contains(&x) && (64..448).contains(&y);
        image::Rgb(if inside { [255; 3] } else { [0; 3] })
    });
    img.save(&path).unwrap();
    h.state_mut().explore.dimension.count_image(&path);
    let t = std::time::Instant::now();
    while h
        .state()
        .explore
        .dimension
        .result
        .as_ref()
        .is_none_or(|r| r.source != "square.png")
    {
        assert!(t.elapsed() < std::time::Duration::from_secs(60));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
    let r = h.state().explore.dimension.result.clone().unwrap();
    assert_eq!(r.count.samples, 384 * 384);
    let d = r.count.dimension().unwrap();
    assert!((d - 2.0).abs() < 0.05, "{d}");
    assert!(h.query_by_label("square.png: 147456 samples").is_some());
}

#[test]
fn scene_tab_switches_to_ray_casting_and_edits_a_quaternion_julia_set() {
    let mut h = harness(Start::Random(3));
    h.get_by_role_and_label(Role::Button, "Scene").click();
    h.run_steps(3);
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/quaternion-julia.toml");
    assert!(h.state_mut().scene.open(&file));
    h.run_steps(3);
    use ugnis::surface::scene::{Geometry, Renderer};
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

/// Step the UI (every 20 ms, for at most a minute) until `done` holds for the app.
fn wait_until(h: &mut Harness<'_, UgnisApp>, done: impl Fn(&UgnisApp) -> bool) {
    let t = std::time::Instant::now();
    while !done(h.state()) {
        assert!(t.elapsed() < std::time::Duration::from_secs(60));
        std::thread::sleep(std::time::Duration::from_millis(20));
        h.run_steps(1);
    }
}

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

fn state_of(path: &Path) -> ugnis::flame::state::RenderState {
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
    // The first state ended in a partial sub-batch of 1,440 samples: the continuation starts
    // at the next whole one, so it adds 50 × 3072 − 70,000 = 83,600 samples.
    assert_eq!(after.samples_done, before.samples_done + 83_600);
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

#[test]
fn explore_box_counting_of_the_escape_time_boundary() {
    use ugnis::app::explore_tab::dimension::BoxSource;
    use ugnis::escape::{C, EscapeDoc, Family};
    let mut h = explore_tab();
    // The Julia set of z² + 0 is the unit circle: its boundary has dimension 1.
    let mut doc = EscapeDoc::new(Family::Julia {
        power: 2,
        c: C { re: 0.0, im: 0.0 },
    });
    doc.view = ugnis::escape::View::new([0.0, 0.0], 1.2);
    h.state_mut().escape.doc = doc;
    explore_topic(&mut h, "Dimension");
    wait_until(&mut h, |a| {
        !a.explore.dimension.busy() && a.explore.dimension.result.is_some()
    });
    h.state_mut().explore.dimension.source = BoxSource::Escape;
    h.run_steps(1);
    h.get_by_label("Count boxes").click();
    h.run_steps(1);
    wait_until(&mut h, |a| {
        a.explore
            .dimension
            .result
            .as_ref()
            .is_some_and(|r| r.source.contains("escape-time"))
    });
    let d = h
        .state()
        .explore
        .dimension
        .result
        .as_ref()
        .unwrap()
        .count
        .dimension()
        .unwrap();
    assert!((d - 1.0).abs() < 0.1, "{d}");
}
