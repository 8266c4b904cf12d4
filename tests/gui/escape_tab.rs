//! The escape-time tab: clicks open Julia sets and Back returns, zooming past f64 by
//! perturbation, rectangle zoom and panning.

use eframe::egui;
use egui::accesskit::Role;
use egui::{Modifiers, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ugnis::app::UgnisApp;

use crate::{drag, open};

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
    assert_eq!(h.state().escape.doc.view.center(), before.view.center());
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
        e.doc.view = e.doc.view.with_centre(c);
        e.doc.view.set_half_height(1e-11);
    }
    h.run_steps(2);
    let (w, ht) = (h.state().escape.doc.width, h.state().escape.doc.height);
    let mid = [w as f64 / 2.0, ht as f64 / 2.0];
    // Twenty doublings at the centre: 1e-11 → 1e-17, far past the f64 limit.
    for _ in 0..20 {
        h.state_mut().escape.zoom_at(mid, 2.0);
    }
    h.run_steps(2);
    let v1 = h.state().escape.doc.view.clone();
    assert!(v1.half_height() < 1e-16, "{v1:?}");
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
    let v2 = h.state().escape.doc.view.clone();
    assert_eq!(v2.center(), v1.center());
    let moved = v1.pixel_of(&v2, 0.0, 0.0, w, ht)[0] - 0.5;
    let ppp = h.ctx.pixels_per_point() as f64;
    assert!((moved + 80.0 * ppp).abs() < 1.0, "moved {moved} pixels");
    // Past 1e-10000 the zoom stops with a message.
    for _ in 0..40 {
        h.state_mut().escape.zoom_at(mid, 1e300);
    }
    assert!(
        h.state().escape.notices.status.contains("deep-zoom limit"),
        "{}",
        h.state().escape.notices.status
    );
    let v3 = h.state().escape.doc.view.clone();
    assert!(v3.half_height_fx().log10() < -9700.0 && v3.half_height_fx().log10() > -10000.0);
}

#[test]
fn escape_tab_rectangle_zoom_and_pan() {
    let mut h = escape_tab();
    let v0 = h.state().escape.doc.view.clone();
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
    let v1 = h.state().escape.doc.view.clone();
    assert!(v1.half_height() < v0.half_height() * 0.3, "{v1:?}");
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
    assert_eq!(h.state().escape.doc.view.center(), v0.center());
}
