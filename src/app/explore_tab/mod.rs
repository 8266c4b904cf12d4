//! The Explore tab: the teaching material beside the three main views. A list of topics on
//! the left; for each, a live picture in the middle and, on the right, its parameters, a short
//! explanation and the numbers that matter, updated as the parameters change.
//!
//! Topics: classic constructions step by step, the chaos game, L-systems, fractal
//! interpolation, Julia sets by inverse iteration, the Lorenz attractor and fractal dimension.
//! Everything is computed by the engine in `crate::explore`; this folder only shows it.

pub(crate) mod chaos;
pub(crate) mod classic;
pub(crate) mod dimension;
pub(crate) mod fif;
pub(crate) mod julia;
pub(crate) mod lorenz;
pub(crate) mod lsys;

use std::hash::{Hash, Hasher};

use eframe::egui::{self, Color32, Pos2, Rect, Vec2};

use crate::app::notice::Notices;
use crate::app::worker::repaint_of;
use crate::escape::EscapeDoc;
use crate::explore::ifs::Ifs;
use crate::explore::raster::Framing;
use crate::explore::{P2, check_range};
use crate::flame::Flame;

/// Background of the pictures.
pub const BACKGROUND: [u8; 3] = [14, 14, 22];
/// Ink of the pictures.
pub const INK: [u8; 3] = [240, 196, 110];

/// A topic of the tab.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Topic {
    /// Classic constructions: Cantor, Koch, Sierpinski.
    Classic,
    /// The chaos game and textbook IFS.
    ChaosGame,
    /// L-systems and Fractint `.l` files.
    LSystems,
    /// Fractal interpolation functions.
    Interpolation,
    /// Julia sets by inverse iteration.
    Julia,
    /// The Lorenz attractor.
    Lorenz,
    /// Fractal dimension.
    Dimension,
}

impl Topic {
    /// Every topic, in the order of the list.
    pub const ALL: [Topic; 7] = [
        Topic::Classic,
        Topic::ChaosGame,
        Topic::LSystems,
        Topic::Interpolation,
        Topic::Julia,
        Topic::Lorenz,
        Topic::Dimension,
    ];

    /// The topic's title.
    pub fn name(self) -> &'static str {
        match self {
            Topic::Classic => "Classic constructions",
            Topic::ChaosGame => "Chaos game",
            Topic::LSystems => "L-systems",
            Topic::Interpolation => "Fractal interpolation",
            Topic::Julia => "Julia by inverse iteration",
            Topic::Lorenz => "Lorenz attractor",
            Topic::Dimension => "Dimension",
        }
    }

    /// What the topic is about, in a line (the tooltip of the list).
    pub fn hint(self) -> &'static str {
        match self {
            Topic::Classic => "Cantor, Koch, Sierpinski: step by step, with their numbers",
            Topic::ChaosGame => "random moves towards corners draw a fractal",
            Topic::LSystems => "rewriting rules drawn by a turtle; Fractint .l files",
            Topic::Interpolation => "a fractal curve through your data points",
            Topic::Julia => "the Julia set from preimages, beside the escape-time picture",
            Topic::Lorenz => "a chaotic flow in 3-D and its sensitivity to the start",
            Topic::Dimension => "similarity dimension, box counting, dividers, lacunarity",
        }
    }
}

/// What the tab asks the application to do (file dialogs and other tabs live in the app).
#[derive(Clone, Debug, PartialEq)]
pub enum ExploreRequest {
    /// Open this IFS as a flame in the flame tab (asking about unsaved changes first).
    OpenInFlameTab(Box<Ifs>),
    /// Show a Menger sponge of this step in the scene tab.
    MengerScene(u32),
    /// Choose a Fractint `.l` file to open.
    OpenLFile,
    /// Choose where to export the L-system picture (SVG or PNG).
    ExportLSystem,
    /// Choose an image to box-count.
    BoxCountImage,
}

/// State of the Explore tab.
pub struct ExploreTab {
    pub topic: Topic,
    pub notices: Notices,
    pub classic: classic::ClassicView,
    pub chaos: chaos::ChaosView,
    pub lsystem: lsys::LSystemView,
    pub fif: fif::FifView,
    pub julia: julia::JuliaView,
    pub lorenz: lorenz::LorenzView,
    pub dimension: dimension::DimensionView,
}

impl ExploreTab {
    /// A new tab; `ctx` wakes the window when background work finishes (none in tests).
    pub fn new(ctx: Option<&egui::Context>) -> ExploreTab {
        let repaint = repaint_of(ctx);
        ExploreTab {
            topic: Topic::Classic,
            notices: Notices::default(),
            classic: classic::ClassicView::default(),
            chaos: chaos::ChaosView::default(),
            lsystem: lsys::LSystemView::new(repaint.clone()),
            fif: fif::FifView::default(),
            julia: julia::JuliaView::new(repaint.clone()),
            lorenz: lorenz::LorenzView::default(),
            dimension: dimension::DimensionView::new(repaint),
        }
    }

    /// File › New: the current topic back to its starting state.
    pub fn reset_topic(&mut self) {
        match self.topic {
            Topic::Classic => self.classic = classic::ClassicView::default(),
            Topic::ChaosGame => self.chaos = chaos::ChaosView::default(),
            Topic::LSystems => self.lsystem.reset(),
            Topic::Interpolation => self.fif = fif::FifView::default(),
            Topic::Julia => self.julia.reset(),
            Topic::Lorenz => self.lorenz = lorenz::LorenzView::default(),
            Topic::Dimension => self.dimension.reset(),
        }
        self.notices
            .status(format!("{}: back to the start", self.topic.name()));
    }

    /// This frame's step of the running animation (called before anything is drawn, so the
    /// status bar and the numbers show the same count).
    pub fn tick(&mut self) {
        if self.topic == Topic::ChaosGame {
            self.chaos.tick();
        }
    }

    /// Notices of a topic's background work: message boxes always, the status line only
    /// while that topic is shown (a line about another topic would be stale).
    fn take_notices(&mut self, from: Topic, notices: Vec<crate::app::notice::Notice>) {
        for n in notices {
            match n {
                crate::app::notice::Notice::Status(_) if from != self.topic => {}
                n => self.notices.push(n),
            }
        }
    }

    /// The line at the left of the status bar.
    pub fn status_text(&self) -> String {
        match self.topic {
            Topic::ChaosGame => self.chaos.status_text(),
            Topic::LSystems => self.lsystem.status_text(),
            Topic::Lorenz => self.lorenz.status_text(),
            t => t.name().to_string(),
        }
    }

    /// Draw the tab; `flame` is the flame tab's current flame (box counting can count it).
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        flame: &Flame,
        escape: &EscapeDoc,
    ) -> Option<ExploreRequest> {
        let mut req = None;
        // Background results first, so the numbers below are current.
        let from_lsystem = self.lsystem.poll();
        self.take_notices(Topic::LSystems, from_lsystem);
        let from_dimension = self.dimension.poll();
        self.take_notices(Topic::Dimension, from_dimension);
        self.julia.poll(ui.ctx());
        let width = ui.available_width();
        egui::Panel::left("explore-topics")
            .default_size(190.0f32.min(width * 0.2))
            .resizable(true)
            .show(ui, |ui| {
                ui.add_space(4.0);
                ui.strong("Topics");
                ui.add_space(2.0);
                for t in Topic::ALL {
                    if ui
                        .selectable_label(self.topic == t, t.name())
                        .on_hover_text(t.hint())
                        .clicked()
                    {
                        if self.topic != t {
                            // The status line spoke of the topic left behind.
                            self.notices.status.clear();
                        }
                        self.topic = t;
                    }
                }
            });
        egui::Panel::right("explore-controls")
            .default_size(340.0f32.min(width * 0.32))
            .max_size((width * 0.45).max(200.0))
            .resizable(true)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    ui.add_space(4.0);
                    ui.heading(self.topic.name());
                    let r = match self.topic {
                        Topic::Classic => self.classic.controls(ui),
                        Topic::ChaosGame => self.chaos.controls(ui),
                        Topic::LSystems => self.lsystem.controls(ui),
                        Topic::Interpolation => self.fif.controls(ui),
                        Topic::Julia => self.julia.controls(ui),
                        Topic::Lorenz => self.lorenz.controls(ui),
                        Topic::Dimension => self.dimension.controls(ui, flame, escape),
                    };
                    if r.is_some() {
                        req = r;
                    }
                });
            });
        egui::CentralPanel::default().show(ui, |ui| match self.topic {
            Topic::Classic => self.classic.canvas(ui),
            Topic::ChaosGame => self.chaos.canvas(ui),
            Topic::LSystems => self.lsystem.canvas(ui),
            Topic::Interpolation => self.fif.canvas(ui),
            Topic::Julia => self.julia.canvas(ui),
            Topic::Lorenz => self.lorenz.canvas(ui),
            Topic::Dimension => self.dimension.canvas(ui),
        });
        req
    }
}

// ---------------------------------------------------------------------------------------------
// Shared pieces of the topic views

/// The explanation of a topic: a few sentences in a muted colour.
pub(crate) fn explanation(ui: &mut egui::Ui, text: &str) {
    ui.add(egui::Label::new(egui::RichText::new(text).weak()).wrap());
    ui.add_space(4.0);
}

/// A section heading inside the controls.
pub(crate) fn section(ui: &mut egui::Ui, title: &str) {
    ui.add_space(6.0);
    ui.separator();
    ui.strong(title);
}

/// A problem with what was typed, in red.
pub(crate) fn problem_label(ui: &mut egui::Ui, problem: &Option<String>) {
    if let Some(p) = problem {
        ui.add(
            egui::Label::new(egui::RichText::new(p).color(Color32::from_rgb(255, 120, 100))).wrap(),
        );
    }
}

/// A number field with limits: a value outside `[min, max]` is brought back inside and the
/// reason is put in `problem` (the engine's range message). True when the value changed.
#[allow(clippy::too_many_arguments)]
pub(crate) fn checked_drag(
    ui: &mut egui::Ui,
    name: &str,
    value: &mut f64,
    what: &'static str,
    min: f64,
    max: f64,
    speed: f64,
    problem: &mut Option<String>,
) -> bool {
    let mut v = *value;
    let r = crate::app::a11y::named(
        ui.add(egui::DragValue::new(&mut v).speed(speed).max_decimals(9)),
        name,
    )
    .on_hover_text(format!("{what}: {min} to {max}"));
    if !r.changed() {
        return false;
    }
    match check_range(what, v, min, max) {
        Ok(()) => {
            *problem = None;
            let changed = v != *value;
            *value = v;
            changed
        }
        Err(e) => {
            *problem = Some(e.to_string());
            let back = if v.is_finite() {
                v.clamp(min, max)
            } else {
                *value
            };
            let changed = back != *value;
            *value = back;
            changed
        }
    }
}

/// A key for cached pictures from anything hashable.
pub(crate) fn key_of(h: impl Hash) -> u64 {
    let mut s = std::hash::DefaultHasher::new();
    h.hash(&mut s);
    s.finish()
}

/// Bits of floats, for keys.
pub(crate) fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// A picture shown as a texture and rebuilt only when its key changes.
#[derive(Default)]
pub(crate) struct Picture {
    key: Option<u64>,
    texture: Option<egui::TextureHandle>,
}

impl Picture {
    /// Rebuild with `make` when `key` differs from the last one; `make` may fail (nothing is
    /// shown then).
    pub fn update(
        &mut self,
        ctx: &egui::Context,
        name: &str,
        key: u64,
        make: impl FnOnce() -> Option<image::RgbImage>,
    ) {
        if self.key == Some(key) {
            return;
        }
        self.key = Some(key);
        match make() {
            Some(img) => self.set(ctx, name, &img),
            None => self.texture = None,
        }
    }

    /// Show `img` now.
    pub fn set(&mut self, ctx: &egui::Context, name: &str, img: &image::RgbImage) {
        let ci =
            egui::ColorImage::from_rgb([img.width() as usize, img.height() as usize], img.as_raw());
        match &mut self.texture {
            Some(t) => t.set(ci, egui::TextureOptions::LINEAR),
            None => self.texture = Some(ctx.load_texture(name, ci, egui::TextureOptions::LINEAR)),
        }
    }

    /// Forget the picture: the next update rebuilds it.
    pub fn invalidate(&mut self) {
        self.key = None;
    }

    pub fn paint(&self, painter: &egui::Painter, rect: Rect) {
        if let Some(t) = &self.texture {
            painter.image(
                t.id(),
                rect,
                Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                Color32::WHITE,
            );
        }
    }
}

/// A framing in device pixels, and the way to and from screen points.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ScreenFraming {
    pub f: Framing,
    pub rect: Rect,
    pub ppp: f32,
}

impl ScreenFraming {
    pub fn to_screen(self, p: P2) -> Pos2 {
        let q = self.f.pixel_from_world(p);
        self.rect.min + Vec2::new(q[0] as f32, q[1] as f32) / self.ppp
    }

    /// World units per screen point.
    pub fn world_per_point(self) -> f64 {
        self.ppp as f64 / self.f.scale
    }
}

/// A dark picture area filling the rest of the panel.
pub(crate) fn dark_canvas(
    ui: &mut egui::Ui,
) -> (Rect, egui::Response, f32, [u32; 2], egui::Painter) {
    let (rect, resp, ppp, size) = crate::app::widgets::canvas_area(ui);
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 0.0, rgb(BACKGROUND));
    (rect, resp, ppp, size, painter)
}

pub(crate) fn rgb(c: [u8; 3]) -> Color32 {
    Color32::from_rgb(c[0], c[1], c[2])
}

/// Log-density colours for hit counts: a table for small counts (the usual case) so a frame
/// of an animation does not spend its time in `powf`.
pub(crate) fn density_image(
    counts: &[u32],
    width: u32,
    height: u32,
    color: [u8; 3],
) -> image::RgbImage {
    let max = counts.iter().copied().max().unwrap_or(0).max(1);
    let lmax = (1.0 + max as f64).ln();
    let shade = |c: u32| -> [u8; 3] {
        // A single hit stays visible: every hit pixel is at least a third of the way up.
        let t = if c == 0 {
            0.0
        } else {
            0.35 + 0.65 * ((1.0 + c as f64).ln() / lmax).powf(0.6)
        };
        let mut p = [0u8; 3];
        for i in 0..3 {
            p[i] = (BACKGROUND[i] as f64 * (1.0 - t) + color[i] as f64 * t).round() as u8;
        }
        p
    };
    let table: Vec<[u8; 3]> = (0..=max.min(4096)).map(shade).collect();
    let mut img = image::RgbImage::new(width, height);
    for (px, &c) in img.pixels_mut().zip(counts) {
        px.0 = match table.get(c as usize) {
            Some(p) => *p,
            None => shade(c),
        };
    }
    img
}

/// A log-log (or any x-y) plot with its points, the fitted ones filled, and a fitted line.
pub(crate) struct Plot<'a> {
    pub title: &'a str,
    pub x_label: &'a str,
    pub y_label: &'a str,
    /// Points and whether each is in the fit.
    pub points: &'a [((f64, f64), bool)],
    /// y = slope·x + intercept, drawn over the x range of the fitted points.
    pub line: Option<(f64, f64)>,
    pub note: String,
}

impl Plot<'_> {
    pub fn paint(&self, painter: &egui::Painter, rect: Rect) {
        let text = Color32::from_gray(210);
        let font = egui::FontId::proportional(13.0);
        painter.rect_stroke(
            rect,
            4.0,
            egui::Stroke::new(1.0, Color32::from_gray(60)),
            egui::StrokeKind::Inside,
        );
        painter.text(
            rect.left_top() + Vec2::new(8.0, 6.0),
            egui::Align2::LEFT_TOP,
            self.title,
            egui::FontId::proportional(14.0),
            text,
        );
        painter.text(
            rect.left_top() + Vec2::new(8.0, 24.0),
            egui::Align2::LEFT_TOP,
            &self.note,
            font.clone(),
            Color32::from_rgb(240, 196, 110),
        );
        let area = Rect::from_min_max(
            rect.min + Vec2::new(48.0, 48.0),
            rect.max - Vec2::new(16.0, 36.0),
        );
        if self.points.is_empty() || area.width() < 20.0 || area.height() < 20.0 {
            return;
        }
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for ((x, y), _) in self.points {
            x0 = x0.min(*x);
            x1 = x1.max(*x);
            y0 = y0.min(*y);
            y1 = y1.max(*y);
        }
        if !(x0.is_finite() && x1.is_finite() && y0.is_finite() && y1.is_finite()) {
            return;
        }
        let pad = |a: f64, b: f64| {
            let d = ((b - a) * 0.06).max(1e-9);
            (a - d, b + d)
        };
        let (x0, x1) = pad(x0, x1);
        let (y0, y1) = pad(y0, y1);
        let to = |x: f64, y: f64| {
            Pos2::new(
                area.left() + ((x - x0) / (x1 - x0)) as f32 * area.width(),
                area.bottom() - ((y - y0) / (y1 - y0)) as f32 * area.height(),
            )
        };
        let axis = egui::Stroke::new(1.0, Color32::from_gray(90));
        painter.line_segment([area.left_bottom(), area.right_bottom()], axis);
        painter.line_segment([area.left_bottom(), area.left_top()], axis);
        let small = egui::FontId::proportional(11.0);
        painter.text(
            area.left_bottom() + Vec2::new(0.0, 4.0),
            egui::Align2::LEFT_TOP,
            format!("{x0:.2}"),
            small.clone(),
            text,
        );
        painter.text(
            area.right_bottom() + Vec2::new(0.0, 4.0),
            egui::Align2::RIGHT_TOP,
            format!("{x1:.2}   {}", self.x_label),
            small.clone(),
            text,
        );
        painter.text(
            area.left_bottom() - Vec2::new(4.0, 0.0),
            egui::Align2::RIGHT_BOTTOM,
            format!("{y0:.1}"),
            small.clone(),
            text,
        );
        painter.text(
            area.left_top() - Vec2::new(4.0, 0.0),
            egui::Align2::RIGHT_TOP,
            format!("{y1:.1}"),
            small.clone(),
            text,
        );
        painter.text(
            area.left_top() + Vec2::new(6.0, 0.0),
            egui::Align2::LEFT_TOP,
            self.y_label,
            small,
            text,
        );
        if let Some((m, b)) = self.line {
            let fx: Vec<f64> = self.points.iter().filter(|p| p.1).map(|p| p.0.0).collect();
            let lo = fx.iter().copied().fold(f64::MAX, f64::min);
            let hi = fx.iter().copied().fold(f64::MIN, f64::max);
            if lo < hi {
                painter.line_segment(
                    [to(lo, m * lo + b), to(hi, m * hi + b)],
                    egui::Stroke::new(2.0, Color32::from_rgb(240, 196, 110)),
                );
            }
        }
        for ((x, y), fitted) in self.points {
            let p = to(*x, *y);
            if *fitted {
                painter.circle_filled(p, 4.0, Color32::from_rgb(120, 200, 255));
            } else {
                painter.circle_stroke(p, 4.0, egui::Stroke::new(1.5, Color32::from_gray(150)));
            }
        }
    }
}
