//! The transport buttons' icons, drawn as shapes (the interface font has no media symbols):
//! first, previous, play, pause, next and last frame.

use eframe::egui::{self, Pos2, Rect, Sense, Shape, Stroke, Vec2};

use crate::app::a11y::named;

/// Which icon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Icon {
    First,
    Previous,
    Play,
    Pause,
    Next,
    Last,
}

/// A triangle pointing right (`dir` 1) or left (−1) in `r`.
fn triangle(r: Rect, dir: f32, color: egui::Color32) -> Shape {
    let (l, rt) = if dir > 0.0 {
        (r.left(), r.right())
    } else {
        (r.right(), r.left())
    };
    Shape::convex_polygon(
        vec![
            Pos2::new(l, r.top()),
            Pos2::new(rt, r.center().y),
            Pos2::new(l, r.bottom()),
        ],
        color,
        Stroke::NONE,
    )
}

/// A button showing `icon`, named `name` for screen readers and tests.
pub fn button(ui: &mut egui::Ui, icon: Icon, name: &str) -> egui::Response {
    let size = Vec2::new(28.0, ui.spacing().interact_size.y.max(20.0));
    let (rect, resp) = ui.allocate_exact_size(size, Sense::click());
    let resp = named(resp, name);
    if ui.is_rect_visible(rect) {
        let v = ui.style().interact(&resp);
        ui.painter()
            .rect_filled(rect, v.corner_radius, v.weak_bg_fill);
        let c = v.fg_stroke.color;
        let g = Rect::from_center_size(rect.center(), Vec2::splat(10.0));
        let bar =
            |x: f32| Shape::rect_filled(Rect::from_x_y_ranges(x..=x + 2.0, g.y_range()), 0.0, c);
        let half = |from: f32, to: f32| Rect::from_x_y_ranges(from..=to, g.y_range());
        let shapes = match icon {
            Icon::Play => vec![triangle(half(g.left() + 1.0, g.right()), 1.0, c)],
            Icon::Pause => vec![bar(g.left() + 1.0), bar(g.right() - 3.0)],
            Icon::First => vec![
                bar(g.left()),
                triangle(half(g.left() + 3.0, g.right()), -1.0, c),
            ],
            Icon::Last => vec![
                triangle(half(g.left(), g.right() - 3.0), 1.0, c),
                bar(g.right() - 2.0),
            ],
            Icon::Previous => vec![
                triangle(half(g.left(), g.center().x), -1.0, c),
                triangle(half(g.center().x, g.right()), -1.0, c),
            ],
            Icon::Next => vec![
                triangle(half(g.left(), g.center().x), 1.0, c),
                triangle(half(g.center().x, g.right()), 1.0, c),
            ],
        };
        ui.painter().extend(shapes);
    }
    resp
}
