//! The curve editor: the chosen parameter's value against the frame, its keys as handles to
//! drag in frame and value, the Bézier handles of Bézier keys, a double click adds a key on
//! the spot. The value range fits the curve, and stays put while something is dragged.

use eframe::egui::{self, Color32, Pos2, Rect, Sense, Stroke, Vec2};

use super::KeyDrag;
use super::ruler::{self, PAD};
use crate::app::a11y::named;
use crate::flame::keyframes::{Curve, Interp, Key};

/// Where the curve editor is and what it spans.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry {
    pub rect: Rect,
    pub frames: u32,
    /// The values at the bottom and the top.
    pub lo: f64,
    pub hi: f64,
}

/// How near (points) the pointer must be to grab a key or a handle.
const GRAB: f32 = 7.0;

impl Geometry {
    /// Frames run as on the ruler above.
    pub fn x_of(&self, frame: f64) -> f32 {
        ruler::x_of_frame(self.rect, self.frames, frame)
    }

    pub fn frame_of(&self, x: f32) -> f64 {
        ruler::frame_at_x(self.rect, self.frames, x)
    }

    pub fn y_of(&self, v: f64) -> f32 {
        let h = (self.rect.height() - 2.0 * PAD).max(1.0);
        let t = (v - self.lo) / (self.hi - self.lo);
        self.rect.bottom() - PAD - t as f32 * h
    }

    pub fn value_of(&self, y: f32) -> f64 {
        let h = (self.rect.height() - 2.0 * PAD).max(1.0);
        self.lo + ((self.rect.bottom() - PAD - y) / h) as f64 * (self.hi - self.lo)
    }

    pub fn pos(&self, frame: f64, v: f64) -> Pos2 {
        Pos2::new(self.x_of(frame), self.y_of(v))
    }
}

/// What the user did in the curve editor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Event {
    Select(Option<f64>),
    /// Move the key at `from` to this frame and value.
    Move {
        from: f64,
        frame: f64,
        value: f64,
    },
    /// Set the Bézier handles of the key at `frame` (before, after).
    Handles {
        frame: f64,
        handles: [[f64; 2]; 2],
    },
    DragEnd,
    /// Add a key here.
    Add {
        frame: f64,
        value: f64,
    },
    /// Go to this frame.
    Scrub(f64),
}

/// A curve in the editor's units: values or, for scale factors, their logarithms (Bézier
/// handles are offsets in those units).
struct Units {
    log: bool,
}

impl Units {
    fn to(&self, v: f64) -> f64 {
        if self.log { v.max(1e-300).ln() } else { v }
    }
    fn from(&self, v: f64) -> f64 {
        if self.log { v.exp() } else { v }
    }
}

/// The Bézier handles of key `i` as the curve uses them: its own, or flat a third of the way
/// to its neighbours.
pub fn handles_of(keys: &[Key], i: usize) -> [[f64; 2]; 2] {
    if let Some(h) = keys[i].handles {
        return h;
    }
    let before = i
        .checked_sub(1)
        .map_or(1.0, |j| keys[i].frame - keys[j].frame);
    let after = keys.get(i + 1).map_or(1.0, |k| k.frame - keys[i].frame);
    [[-before / 3.0, 0.0], [after / 3.0, 0.0]]
}

/// The handles shown for key `i`: the one before it when the key before is a Bézier, the one
/// after it when it is one.
fn shown_handles(keys: &[Key], i: usize) -> [bool; 2] {
    [
        i > 0 && keys[i - 1].interp == Interp::Bezier,
        keys[i].interp == Interp::Bezier && i + 1 < keys.len(),
    ]
}

/// The value range that shows the curve: its values over the timeline, its keys and the
/// shown handles, with a margin.
fn fit(curve: &Curve, frames: u32, wrap: Option<f64>) -> (f64, f64) {
    let u = Units {
        log: curve.target.is_logarithmic(),
    };
    let keys = curve.keys();
    let mut vals: Vec<f64> = (0..=200)
        .filter_map(|s| curve.eval(s as f64 / 200.0 * frames as f64, wrap))
        .chain(keys.iter().map(|k| k.value))
        .collect();
    for (i, k) in keys.iter().enumerate() {
        let h = handles_of(keys, i);
        for (side, on) in shown_handles(keys, i).into_iter().enumerate() {
            if on {
                vals.push(u.from(u.to(k.value) + h[side][1]));
            }
        }
    }
    let lo = vals.iter().cloned().fold(f64::INFINITY, f64::min);
    let hi = vals.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    if !(lo.is_finite() && hi.is_finite()) {
        return (-1.0, 1.0);
    }
    let span = (hi - lo).max(1e-6 * lo.abs().max(1.0)).max(1e-9);
    let m = if hi - lo < 1e-9 { 1.0 } else { 0.1 * span };
    (lo - m, hi + m)
}

/// What the curve editor shows.
pub struct Input<'a> {
    pub curve: &'a Curve,
    pub frames: u32,
    pub frame: f64,
    pub selected: Option<f64>,
    pub wrap: bool,
    /// The range of the previous frame, kept while something is dragged.
    pub keep: Option<(f64, f64)>,
}

/// Draw the curve editor and read the pointer.
pub fn show(
    ui: &mut egui::Ui,
    input: &Input,
    height: f32,
    drag: &mut Option<KeyDrag>,
) -> (Geometry, Vec<Event>) {
    let size = Vec2::new(ui.available_width().max(120.0), height.max(60.0));
    let (rect, resp) = ui.allocate_exact_size(size, Sense::click_and_drag());
    let resp = named(resp, "Curve editor").on_hover_text(
        "drag a key: move it in frame and value · drag a handle: shape a Bézier key · \
         double-click: add a key · click: go to a frame",
    );
    let wrap = input.wrap.then_some(input.frames as f64);
    let (lo, hi) = input
        .keep
        .filter(|_| drag.is_some())
        .unwrap_or_else(|| fit(input.curve, input.frames, wrap));
    let g = Geometry {
        rect,
        frames: input.frames,
        lo,
        hi,
    };
    let u = Units {
        log: input.curve.target.is_logarithmic(),
    };
    let keys = input.curve.keys();
    paint(ui, &g, input, &u);
    let mut events = Vec::new();
    // What is under a point: a shown handle of the selected key, or a key.
    let grab = |p: Pos2| -> Option<KeyDrag> {
        if let Some(i) = input
            .selected
            .and_then(|f| keys.iter().position(|k| k.frame == f))
        {
            let h = handles_of(keys, i);
            for (side, on) in shown_handles(keys, i).into_iter().enumerate() {
                let k = &keys[i];
                let hp = g.pos(k.frame + h[side][0], u.from(u.to(k.value) + h[side][1]));
                if on && hp.distance(p) <= GRAB {
                    return Some(KeyDrag::Handle(k.frame, side));
                }
            }
        }
        keys.iter()
            .map(|k| (k.frame, g.pos(k.frame, k.value).distance(p)))
            .filter(|(_, d)| *d <= GRAB)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(f, _)| KeyDrag::Key(f))
    };
    if resp.drag_started_by(egui::PointerButton::Primary)
        && let Some(p) = ui.input(|i| i.pointer.press_origin())
    {
        *drag = grab(p);
        if let Some(KeyDrag::Key(f)) = *drag {
            events.push(Event::Select(Some(f)));
        }
    }
    let pointer = resp.interact_pointer_pos();
    if resp.dragged()
        && let Some(p) = pointer
    {
        let frame = g.frame_of(p.x).round().clamp(0.0, input.frames as f64);
        let mut value = g.value_of(p.y);
        if u.log {
            value = value.max(1e-9);
        }
        match *drag {
            Some(KeyDrag::Key(from)) => events.push(Event::Move { from, frame, value }),
            Some(KeyDrag::Handle(f, side)) => {
                if let Some(i) = keys.iter().position(|k| k.frame == f) {
                    let mut h = handles_of(keys, i);
                    let df = g.frame_of(p.x) - f;
                    h[side] = [
                        if side == 0 { df.min(0.0) } else { df.max(0.0) },
                        u.to(value) - u.to(keys[i].value),
                    ];
                    events.push(Event::Handles {
                        frame: f,
                        handles: h,
                    });
                }
            }
            None => events.push(Event::Scrub(frame.min((input.frames - 1) as f64))),
        }
    }
    if resp.drag_stopped() && drag.take().is_some() {
        events.push(Event::DragEnd);
    }
    if resp.double_clicked()
        && let Some(p) = pointer
    {
        let frame = g.frame_of(p.x).round().clamp(0.0, input.frames as f64);
        events.push(Event::Add {
            frame,
            value: g.value_of(p.y),
        });
    } else if resp.clicked()
        && let Some(p) = pointer
    {
        match grab(p) {
            Some(KeyDrag::Key(f)) => events.push(Event::Select(Some(f))),
            Some(KeyDrag::Handle(..)) => {}
            None => {
                let f = g
                    .frame_of(p.x)
                    .round()
                    .clamp(0.0, (input.frames - 1) as f64);
                events.push(Event::Scrub(f));
            }
        }
    }
    (g, events)
}

/// A value on the axis, in at most five significant digits.
fn axis_number(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && !(1e-3..1e5).contains(&a) {
        return format!("{v:.3e}");
    }
    let digits = (4 - a.log10().floor().max(0.0) as i32).max(0) as usize;
    let s = format!("{v:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// The editor's picture: grid, the curve, keys and handles, the current frame.
fn paint(ui: &egui::Ui, g: &Geometry, input: &Input, u: &Units) {
    let p = ui.painter_at(g.rect);
    let v = ui.visuals();
    p.rect_filled(g.rect, 3.0, v.extreme_bg_color);
    let weak = v.weak_text_color();
    let grid = Stroke::new(1.0, v.faint_bg_color);
    for k in 0..=4 {
        let y = g.rect.bottom() - PAD - k as f32 / 4.0 * (g.rect.height() - 2.0 * PAD);
        p.hline(g.rect.x_range(), y, grid);
    }
    for (val, y) in [(g.hi, g.rect.top() + 1.0), (g.lo, g.rect.bottom() - 13.0)] {
        p.text(
            Pos2::new(g.rect.left() + 3.0, y),
            egui::Align2::LEFT_TOP,
            axis_number(val),
            egui::FontId::proportional(10.0),
            weak,
        );
    }
    let wrap = input.wrap.then_some(input.frames as f64);
    let n = ((g.rect.width() - 2.0 * PAD) / 2.0).max(2.0) as usize;
    let line: Vec<Pos2> = (0..=n)
        .filter_map(|s| {
            let f = s as f64 / n as f64 * input.frames as f64;
            input.curve.eval(f, wrap).map(|val| g.pos(f, val))
        })
        .collect();
    let accent = v.selection.bg_fill;
    p.add(egui::Shape::line(
        line,
        Stroke::new(1.5, Color32::from_rgb(120, 190, 255)),
    ));
    let x = g.x_of(input.frame);
    p.vline(x, g.rect.y_range(), Stroke::new(1.5, accent));
    let keys = input.curve.keys();
    for (i, k) in keys.iter().enumerate() {
        let c = g.pos(k.frame, k.value);
        let sel = input.selected == Some(k.frame);
        if sel {
            let h = handles_of(keys, i);
            for (side, on) in shown_handles(keys, i).into_iter().enumerate() {
                if on {
                    let hp = g.pos(k.frame + h[side][0], u.from(u.to(k.value) + h[side][1]));
                    p.line_segment([c, hp], Stroke::new(1.0, weak));
                    p.circle_filled(hp, 4.0, Color32::from_rgb(255, 200, 60));
                }
            }
        }
        let r = if sel { 5.0 } else { 4.0 };
        let fill = if sel {
            Color32::from_rgb(255, 200, 60)
        } else {
            Color32::from_rgb(230, 230, 230)
        };
        p.rect_filled(Rect::from_center_size(c, Vec2::splat(2.0 * r)), 1.0, fill);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::keyframes::{FlameParam, Target};

    #[test]
    fn values_and_positions_round_trip_and_the_range_holds_the_curve() {
        let mut c = Curve::new(Target::Flame(FlameParam::Zoom));
        c.insert(Key::new(0.0, 1.0)).unwrap();
        c.insert(Key::new(20.0, 3.0)).unwrap();
        let (lo, hi) = fit(&c, 40, None);
        assert!(lo < 1.0 && hi > 3.0 && hi - lo < 3.0, "{lo} {hi}");
        let g = Geometry {
            rect: Rect::from_min_size(Pos2::new(10.0, 50.0), Vec2::new(400.0, 120.0)),
            frames: 40,
            lo,
            hi,
        };
        let q = g.pos(20.0, 3.0);
        assert!((g.frame_of(q.x) - 20.0).abs() < 1e-4);
        assert!((g.value_of(q.y) - 3.0).abs() < 1e-4);
        // Default handles: flat, a third of the way to the neighbours.
        assert_eq!(
            handles_of(c.keys(), 0),
            [[-1.0 / 3.0, 0.0], [20.0 / 3.0, 0.0]]
        );
        assert_eq!(axis_number(0.5614442857142857), "0.5614");
        assert_eq!(axis_number(-0.0758871428571428), "-0.0759");
        assert_eq!(axis_number(360.0), "360");
        assert_eq!(axis_number(12345.678), "12346");
        assert_eq!(axis_number(2.5e-6), "2.500e-6");
        // A flat curve still gets a range.
        let mut flat = Curve::new(Target::Flame(FlameParam::Zoom));
        flat.insert(Key::new(0.0, 2.0)).unwrap();
        let (lo, hi) = fit(&flat, 10, None);
        assert!(lo < 2.0 && hi > 2.0);
    }
}
