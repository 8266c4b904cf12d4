//! The flame tab's triangle editor: dragging a vertex or a whole triangle by the affine
//! maths with exact undo, the delete rule, y up everywhere, the transform list, the xaos matrix
//! and typed weights.

use eframe::egui;
use egui::accesskit::Role;
use egui::{Key, Modifiers, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::Selected;
use ugnis::app::{Start, UgnisApp};
use ugnis::flame::{Affine, Flame};

use crate::{drag, harness, harness_sized, open, section, set_number};

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
fn a_loaded_flame_keeps_its_weights_when_a_triangle_is_reshaped() {
    // Sierpinski's equal weights happen to follow its equal areas: still no request to
    // re-derive them.
    let mut h = open("sierpinski.flame");
    assert!(!h.state().flame.auto_weights(&h.state().options));
    let w0: Vec<f64> = h
        .state()
        .flame
        .doc()
        .flame()
        .xforms
        .iter()
        .map(|x| x.weight)
        .collect();
    let tri = selected_coefs(h.state()).triangle();
    let st = &h.state().flame.editor;
    let from = st.screen_from_world(tri[1]);
    drag(&mut h, from, from + Vec2::new(40.0, 25.0));
    let f = h.state().flame.doc().flame();
    assert_ne!(
        f.xforms[0].coefs,
        Affine::from_triangle(tri),
        "the triangle moved"
    );
    let w1: Vec<f64> = f.xforms.iter().map(|x| x.weight).collect();
    assert_eq!(w1, w0, "the weights are the file's");
    // Ticking "from areas" asks for the rule: the weights follow the areas from then on.
    h.get_by_role_and_label(Role::CheckBox, "from areas")
        .click();
    h.run_steps(2);
    let f = h.state().flame.doc().flame();
    assert_eq!(f.auto_weights, Some(true));
    let maps: Vec<Affine> = f.xforms.iter().map(|x| x.coefs).collect();
    let rule = Flame::determinant_weights(&maps);
    let total: f64 = f.xforms.iter().map(|x| x.weight).sum();
    for (x, r) in f.xforms.iter().zip(rule) {
        assert!((x.weight / total - r).abs() < 1e-9);
    }
}

#[test]
fn typed_amounts_turn_scale_and_move_as_single_undo_steps() {
    let mut h = harness_sized(
        Start::File(crate::example("sierpinski.flame")),
        1280.0,
        1400.0,
    );
    let original = h.state().flame.doc().flame().clone();
    let t0 = selected_coefs(h.state()).triangle();
    set_number(&mut h, "Rotate by", 90.0);
    h.get_by_role_and_label(Role::Button, "Rotate counter-clockwise")
        .click();
    h.run_steps(2);
    // A quarter turn about the centre: the centre stays, det stays.
    let m = selected_coefs(h.state());
    let c = |t: [[f64; 2]; 3]| {
        [
            (t[0][0] + t[1][0] + t[2][0]) / 3.0,
            (t[0][1] + t[1][1] + t[2][1]) / 3.0,
        ]
    };
    let (c0, c1) = (c(t0), c(m.triangle()));
    assert!((c0[0] - c1[0]).abs() < 1e-9 && (c0[1] - c1[1]).abs() < 1e-9);
    assert!((m.det() - Affine::from_triangle(t0).det()).abs() < 1e-9);
    assert_eq!(h.state().flame.doc().undo_len(), 1);
    // Grow by 50 %, then move up by 0.25 (y up: the world's f falls).
    set_number(&mut h, "Scale by", 50.0);
    h.get_by_role_and_label(Role::Button, "Grow").click();
    h.run_steps(2);
    assert!((selected_coefs(h.state()).det() - 2.25 * m.det()).abs() < 1e-9);
    let f_before = selected_coefs(h.state()).f;
    set_number(&mut h, "Move by", 0.25);
    h.get_by_role_and_label(Role::Button, "Move up").click();
    h.run_steps(2);
    assert!((selected_coefs(h.state()).f - (f_before - 0.25)).abs() < 1e-9);
    // All transforms, half a turn about the origin: every triangle is mirrored through it.
    let before_all = h.state().flame.doc().flame().clone();
    h.get_by_role_and_label(Role::CheckBox, "All transforms, about the origin")
        .click();
    set_number(&mut h, "Rotate by", 180.0);
    h.get_by_role_and_label(Role::Button, "Rotate clockwise")
        .click();
    h.run_steps(2);
    for (a, b) in h
        .state()
        .flame
        .doc()
        .flame()
        .xforms
        .iter()
        .zip(&before_all.xforms)
    {
        for (p, q) in a.coefs.triangle().iter().zip(b.coefs.triangle()) {
            assert!((p[0] + q[0]).abs() < 1e-9 && (p[1] + q[1]).abs() < 1e-9);
        }
    }
    for _ in 0..4 {
        h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
        h.run_steps(2);
    }
    assert_eq!(h.state().flame.doc().flame(), &original);
}
