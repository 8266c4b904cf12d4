//! The frame ruler: frame numbers, the current frame (click or drag to scrub), the keys of
//! the chosen parameter as diamonds (click to select, drag to move, right-click for delete,
//! interpolation and easing) and the keys of the other animated parameters as ticks.

use eframe::egui::{self, Color32, Pos2, Rect, Sense, Stroke, Vec2};

use super::KeyDrag;
use crate::app::a11y::named;
use crate::flame::keyframes::{Ease, Interp, Key};

/// Where the ruler is on screen and what it spans.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry {
    pub rect: Rect,
    /// The ruler spans frames 0 to `frames` (the frame after the last).
    pub frames: u32,
}

/// Room left and right of the ruler's ends, so that keys there can be grabbed.
pub(super) const PAD: f32 = 12.0;
/// Height of the numbers band; the keys sit below it.
const NUMBERS: f32 = 16.0;
pub const HEIGHT: f32 = 44.0;
/// How near (points) the pointer must be to grab a key.
const GRAB: f32 = 7.0;

/// Where `frame` is across `rect`, which spans frames 0 to `frames` inside its margins (the
/// ruler's and the curve editor's frame axis).
pub(super) fn x_of_frame(rect: Rect, frames: u32, frame: f64) -> f32 {
    let w = (rect.width() - 2.0 * PAD).max(1.0);
    rect.left() + PAD + (frame / frames.max(1) as f64) as f32 * w
}

/// The frame (not rounded) at `x` across `rect` (see [`x_of_frame`]).
pub(super) fn frame_at_x(rect: Rect, frames: u32, x: f32) -> f64 {
    let w = (rect.width() - 2.0 * PAD).max(1.0);
    ((x - rect.left() - PAD) / w) as f64 * frames.max(1) as f64
}

impl Geometry {
    pub fn x_of(&self, frame: f64) -> f32 {
        x_of_frame(self.rect, self.frames, frame)
    }

    /// The whole frame nearest to `x`, within the ruler.
    pub fn frame_of(&self, x: f32) -> f64 {
        frame_at_x(self.rect, self.frames, x)
            .round()
            .clamp(0.0, self.frames as f64)
    }

    /// Where the key at `frame` is drawn.
    pub fn key_pos(&self, frame: f64) -> Pos2 {
        Pos2::new(
            self.x_of(frame),
            self.rect.top() + NUMBERS + (HEIGHT - NUMBERS) / 2.0,
        )
    }
}

/// What the user did on the ruler.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Event {
    /// Go to this frame.
    Scrub(f64),
    Select(Option<f64>),
    /// Move the key at `from` to frame `to` (while dragging).
    Move {
        from: f64,
        to: f64,
    },
    /// A drag of a key ended.
    DragEnd,
    Delete(f64),
    Interp(f64, Interp),
    Ease(f64, Ease),
}

/// Frames between labelled ticks (1, 2 or 5 times a power of ten) so that labels are at
/// least `min_px` apart.
fn tick_step(frames: u32, width: f32, min_px: f32) -> u32 {
    let per_frame = width / frames.max(1) as f32;
    let mut base = 1u64;
    loop {
        for m in [1, 2, 5] {
            let step = base * m;
            if step as f32 * per_frame >= min_px || step >= frames as u64 {
                return step.min(u32::MAX as u64) as u32;
            }
        }
        base *= 10;
    }
}

/// A diamond for a key.
fn diamond(p: &egui::Painter, c: Pos2, r: f32, fill: Color32, stroke: Stroke) {
    let pts = vec![
        c + Vec2::new(0.0, -r),
        c + Vec2::new(r, 0.0),
        c + Vec2::new(0.0, r),
        c + Vec2::new(-r, 0.0),
    ];
    p.add(egui::Shape::convex_polygon(pts, fill, stroke));
}

/// What the ruler shows.
pub struct Input<'a> {
    pub frames: u32,
    pub frame: f64,
    pub keys: &'a [Key],
    pub selected: Option<f64>,
    /// Frames of the keys of the other animated parameters.
    pub others: &'a [f64],
    /// The frame after the last equals the first.
    pub wrap: bool,
}

/// Draw the ruler and read the pointer. `drag` is the key being dragged (kept between
/// frames); `menu_key` the key whose context menu is open.
pub fn show(
    ui: &mut egui::Ui,
    input: &Input,
    drag: &mut Option<KeyDrag>,
    menu_key: &mut Option<f64>,
) -> (Geometry, Vec<Event>, bool) {
    let size = Vec2::new(ui.available_width().max(120.0), HEIGHT);
    let (rect, resp) = ui.allocate_exact_size(size, Sense::click_and_drag());
    let resp = named(resp, "Timeline ruler").on_hover_text(
        "click or drag: go to a frame · drag a key: move it · right-click a key: delete, \
         interpolation, easing",
    );
    let g = Geometry {
        rect,
        frames: input.frames,
    };
    paint(ui, &g, input);
    let mut events = Vec::new();
    let key_near = |p: Pos2| {
        input
            .keys
            .iter()
            .map(|k| (k.frame, g.key_pos(k.frame).distance(p)))
            .filter(|(_, d)| *d <= GRAB)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(f, _)| f)
    };
    let pointer = resp.interact_pointer_pos();
    if resp.drag_started_by(egui::PointerButton::Primary)
        && let Some(p) = ui.input(|i| i.pointer.press_origin())
        && let Some(f) = key_near(p)
    {
        *drag = Some(KeyDrag::Key(f));
        events.push(Event::Select(Some(f)));
    }
    let mut scrubbing = false;
    match (*drag, pointer) {
        (Some(KeyDrag::Key(from)), Some(p)) if resp.dragged() => {
            let to = g.frame_of(p.x);
            if to != from {
                events.push(Event::Move { from, to });
            }
        }
        (None, Some(p)) if resp.dragged() || resp.clicked() => {
            scrubbing = resp.dragged();
            if resp.clicked()
                && let Some(f) = key_near(p)
            {
                events.push(Event::Select(Some(f)));
            }
            let last = input.frames.saturating_sub(1) as f64;
            events.push(Event::Scrub(g.frame_of(p.x).min(last)));
        }
        _ => {}
    }
    if resp.drag_stopped() && drag.take().is_some() {
        events.push(Event::DragEnd);
    }
    if let Some(p) = resp.hover_pos()
        && key_near(p).is_some()
    {
        ui.ctx().set_cursor_icon(egui::CursorIcon::ResizeHorizontal);
    }
    if resp.secondary_clicked() {
        *menu_key = resp.interact_pointer_pos().and_then(key_near);
        if let Some(f) = *menu_key {
            events.push(Event::Select(Some(f)));
        }
    }
    if let Some(f) = *menu_key
        && let Some(k) = input.keys.iter().find(|k| k.frame == f)
    {
        resp.context_menu(|ui| key_menu(ui, k, &mut events));
    }
    (g, events, scrubbing)
}

/// The context menu of a key.
fn key_menu(ui: &mut egui::Ui, k: &Key, events: &mut Vec<Event>) {
    ui.label(format!("Key at frame {}", k.frame));
    if ui.button("Delete key").clicked() {
        events.push(Event::Delete(k.frame));
        ui.close();
    }
    ui.separator();
    ui.label("Interpolation");
    for i in Interp::ALL {
        if ui.radio(k.interp == i, i.name()).clicked() {
            events.push(Event::Interp(k.frame, i));
            ui.close();
        }
    }
    ui.separator();
    ui.label("Easing");
    for e in Ease::ALL {
        if ui.radio(k.ease == e, e.name()).clicked() {
            events.push(Event::Ease(k.frame, e));
            ui.close();
        }
    }
}

/// The ruler's picture.
fn paint(ui: &egui::Ui, g: &Geometry, input: &Input) {
    let p = ui.painter_at(g.rect.expand(1.0));
    let v = ui.visuals();
    let rect = g.rect;
    p.rect_filled(rect, 3.0, v.extreme_bg_color);
    // The frame after the last (with wrap: the first again) is shaded.
    let last = input.frames.saturating_sub(1) as f64;
    let after = Rect::from_x_y_ranges(g.x_of(last)..=rect.right(), rect.y_range());
    p.rect_filled(after, 0.0, v.faint_bg_color);
    let text = v.text_color();
    let weak = v.weak_text_color();
    let step = tick_step(input.frames, rect.width() - 2.0 * PAD, 42.0);
    let minor = (step / 5).max(1);
    let per_frame = (rect.width() - 2.0 * PAD) / input.frames.max(1) as f32;
    let inc = if minor as f32 * per_frame >= 5.0 {
        minor
    } else {
        step
    };
    let font = egui::FontId::proportional(11.0);
    let mut labels: Vec<(f32, f32, String)> = Vec::new();
    let mut k = 0u32;
    while k <= input.frames {
        let x = g.x_of(k as f64);
        if k.is_multiple_of(step) {
            p.vline(
                x,
                rect.top() + NUMBERS - 4.0..=rect.bottom(),
                Stroke::new(1.0, weak),
            );
            let label = if k == input.frames && input.wrap {
                format!("{k} = 0")
            } else {
                k.to_string()
            };
            let width = ui
                .ctx()
                .fonts_mut(|f| f.layout_no_wrap(label.clone(), font.clone(), text))
                .size()
                .x;
            // Right of the tick, or left of it at the end of the ruler.
            let left = if x + 2.0 + width > rect.right() {
                x - 2.0 - width
            } else {
                x + 2.0
            };
            labels.push((left, width, label));
        } else {
            p.vline(
                x,
                rect.top() + NUMBERS..=rect.top() + NUMBERS + 5.0,
                Stroke::new(1.0, weak),
            );
        }
        match k.checked_add(inc) {
            Some(n) => k = n,
            None => break,
        }
    }
    // The last label always shows; one that would overlap the label after it does not.
    let mut next_left = f32::INFINITY;
    for (left, width, label) in labels.into_iter().rev() {
        if left + width + 4.0 <= next_left {
            p.text(
                Pos2::new(left, rect.top() + 1.0),
                egui::Align2::LEFT_TOP,
                label,
                font.clone(),
                text,
            );
            next_left = left;
        }
    }
    for &f in input.others {
        let c = g.key_pos(f);
        p.vline(c.x, c.y - 3.0..=c.y + 3.0, Stroke::new(1.0, weak));
    }
    let accent = v.selection.bg_fill;
    for key in input.keys {
        let sel = input.selected == Some(key.frame);
        let fill = if sel {
            Color32::from_rgb(255, 200, 60)
        } else {
            Color32::from_rgb(230, 230, 230)
        };
        diamond(
            &p,
            g.key_pos(key.frame),
            if sel { 6.5 } else { 5.5 },
            fill,
            Stroke::new(1.0, Color32::BLACK),
        );
    }
    let x = g.x_of(input.frame);
    p.vline(x, rect.y_range(), Stroke::new(2.0, accent));
    p.add(egui::Shape::convex_polygon(
        vec![
            Pos2::new(x - 5.0, rect.top()),
            Pos2::new(x + 5.0, rect.top()),
            Pos2::new(x, rect.top() + 6.0),
        ],
        accent,
        Stroke::NONE,
    ));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_and_positions_round_trip_and_ticks_stay_apart() {
        let g = Geometry {
            rect: Rect::from_min_size(Pos2::new(100.0, 0.0), Vec2::new(624.0, HEIGHT)),
            frames: 60,
        };
        for f in [0.0, 1.0, 30.0, 59.0, 60.0] {
            assert_eq!(g.frame_of(g.x_of(f)), f);
        }
        assert_eq!(g.frame_of(0.0), 0.0);
        assert_eq!(g.frame_of(5000.0), 60.0);
        // 600 points for 60 frames: 10 points a frame, labels every 5 frames.
        assert_eq!(tick_step(60, 600.0, 42.0), 5);
        assert_eq!(tick_step(1_000_000, 600.0, 42.0), 100_000);
        assert_eq!(tick_step(3, 600.0, 42.0), 1);
    }
}
