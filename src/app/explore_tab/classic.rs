//! Classic constructions step by step: the Cantor set, the Koch curve and snowflake, the
//! Sierpinski triangle and carpet, with a step slider and the numbers of the step; and a
//! Menger sponge sent to the scene tab.

use eframe::egui;

use super::{BACKGROUND, ExploreRequest, INK, Picture, explanation, key_of, section};
use crate::explore::classic::{Construction, Geometry, Stats};
use crate::explore::raster::{Canvas, Framing};
use crate::explore::{Bounds, P2};
use crate::surface::menger;

/// The classic constructions topic.
pub struct ClassicView {
    pub construction: Construction,
    pub step: u32,
    pub menger_step: u32,
    picture: Picture,
}

impl Default for ClassicView {
    fn default() -> Self {
        ClassicView {
            construction: Construction::KochCurve,
            step: 3,
            menger_step: 2,
            picture: Picture::default(),
        }
    }
}

/// What one piece of a construction is called.
fn piece_names(c: Construction) -> (&'static str, &'static str) {
    match c {
        Construction::Cantor | Construction::KochCurve | Construction::KochSnowflake => {
            ("Segments", "segment length")
        }
        Construction::SierpinskiTriangle => ("Triangles", "triangle side"),
        Construction::SierpinskiCarpet => ("Squares", "square side"),
    }
}

/// The closed form of the length or area after n steps, as the teacher writes it.
fn formula(c: Construction) -> (&'static str, &'static str) {
    match c {
        Construction::Cantor => ("2^n", "(2/3)^n"),
        Construction::KochCurve => ("4^n", "(4/3)^n"),
        Construction::KochSnowflake => ("3·4^n", "3·(4/3)^n"),
        Construction::SierpinskiTriangle => ("3^n", "(3/4)^n of the triangle"),
        Construction::SierpinskiCarpet => ("8^n", "(8/9)^n"),
    }
}

fn teaching(c: Construction) -> &'static str {
    match c {
        Construction::Cantor => {
            "Take a segment and throw away its open middle third; do the same to the two \
             pieces left, and again, for ever. What remains has no length at all, yet it has \
             as many points as the whole segment. Two copies at a third of the size make the \
             whole, so its dimension is log 2 / log 3 ≈ 0.63: more than a point, less than a line."
        }
        Construction::KochCurve => {
            "Put a tent over the middle third of a segment: four segments, each a third as \
             long. Repeat on every segment. Each step makes the curve 4/3 longer, so the limit \
             is infinitely long, although it stays in a small box and has no tangent anywhere. \
             Four copies at a third of the size give dimension log 4 / log 3 ≈ 1.26."
        }
        Construction::KochSnowflake => {
            "Three Koch curves on the sides of a triangle. The perimeter grows by 4/3 at every \
             step and becomes infinite, but the area only creeps up towards 8/5 of the \
             triangle's: an infinitely long border around a finite area."
        }
        Construction::SierpinskiTriangle => {
            "Join the midpoints of a triangle's sides and cut out the middle triangle; repeat \
             in the three triangles left. A quarter of the area goes at each step, so none is \
             left in the end. Three copies at half the size: dimension log 3 / log 2 ≈ 1.58."
        }
        Construction::SierpinskiCarpet => {
            "Cut a square into nine and remove the middle one; repeat in the eight left. The \
             area shrinks by 8/9 at each step and tends to zero, while the holes leave a net \
             of lines with dimension log 8 / log 3 ≈ 1.89, close to a surface."
        }
    }
}

impl ClassicView {
    /// The numbers of the current step.
    pub fn stats(&self) -> Option<Stats> {
        self.construction.stats(self.step).ok()
    }

    /// The lines of the numbers box (shown as labels; the tests read them).
    pub fn numbers(&self) -> Vec<String> {
        let Some(s) = self.stats() else {
            return vec!["(no numbers for this step)".into()];
        };
        let (pieces, size) = piece_names(self.construction);
        let (pf, lf) = formula(self.construction);
        let mut v = vec![
            format!("Step: {}", s.step),
            format!("{pieces}: {} = {pf}", s.pieces),
            format!("Each {size}: {:.6} = 3^-{}", s.piece_size, s.step),
        ];
        if self.construction == Construction::SierpinskiTriangle {
            v[2] = format!("Each {size}: {:.6} = 2^-{}", s.piece_size, s.step);
        }
        if let Some(l) = s.length {
            let what = if self.construction == Construction::KochSnowflake {
                "Perimeter"
            } else {
                "Length"
            };
            v.push(format!("{what}: {l:.6} = {lf}"));
        }
        if let Some(a) = s.area {
            let kept = s.initial_area.map_or(String::new(), |a0| {
                format!(" ({:.2} % of the start)", 100.0 * a / a0)
            });
            if self.construction == Construction::KochSnowflake {
                v.push(format!("Area: {a:.6}{kept}"));
            } else {
                v.push(format!("Area: {a:.6} = {lf}{kept}"));
            }
        }
        if let Some(l) = self.construction.limit_area() {
            v.push(format!("Limit of the area: {l:.6} (8/5 of the triangle)"));
        }
        v.push(format!("Similarity dimension: {:.5}", s.dimension));
        v
    }

    pub(super) fn controls(&mut self, ui: &mut egui::Ui) -> Option<ExploreRequest> {
        let mut req = None;
        explanation(ui, teaching(self.construction));
        section(ui, "Construction");
        for c in Construction::ALL {
            if ui
                .radio(self.construction == c, c.name())
                .on_hover_text(c.rule())
                .clicked()
            {
                self.construction = c;
                self.step = self.step.min(c.max_geometry_step());
            }
        }
        ui.add_space(4.0);
        let max = self.construction.max_geometry_step();
        ui.horizontal(|ui| {
            ui.label("Step");
            ui.add(egui::Slider::new(&mut self.step, 0..=max))
                .on_hover_text(format!(
                    "0 to {max}: beyond, the pieces are far below a pixel (about a million pieces)"
                ));
        });
        ui.label(egui::RichText::new(self.construction.rule()).italics());
        section(ui, "Numbers");
        for line in self.numbers() {
            ui.label(line);
        }
        section(ui, "Menger sponge (3-D)");
        let m = menger::numbers(self.menger_step);
        ui.horizontal(|ui| {
            ui.label("Step");
            ui.add(egui::Slider::new(
                &mut self.menger_step,
                0..=menger::MAX_STEP,
            ))
            .on_hover_text(format!("0 to {}", menger::MAX_STEP));
        });
        ui.label(format!(
            "{} cubes of side {:.5}, volume {:.5}, dimension log 20 / log 3 = {:.5}",
            m.cubes,
            m.side,
            m.volume,
            20f64.ln() / 3f64.ln()
        ));
        if ui
            .button("Open in Scene tab")
            .on_hover_text("replace the scene tab's scene by this sponge")
            .clicked()
        {
            req = Some(ExploreRequest::MengerScene(self.menger_step));
        }
        req
    }

    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let (rect, _resp, _ppp, size, painter) = super::dark_canvas(ui);
        let (c, n) = (self.construction, self.step);
        let key = key_of((c, n, size));
        self.picture
            .update(&ctx, "explore-classic", key, || draw(c, n, size).ok());
        self.picture.paint(&painter, rect);
    }
}

/// The picture of step `n` in `size` pixels. The Cantor set shows every step from 0 to n
/// stacked, as it is usually drawn.
fn draw(
    c: Construction,
    n: u32,
    size: [u32; 2],
) -> Result<image::RgbImage, crate::explore::ExploreError> {
    let [w, h] = size;
    let mut canvas = Canvas::new(w, h, BACKGROUND)?;
    let margin = 16.0 + 0.04 * w.min(h) as f64;
    match c {
        Construction::Cantor => {
            let rows = n + 1;
            let b = Bounds {
                min: [0.0, 0.0],
                max: [1.0, 0.0],
            };
            let f = Framing::fit(b, w, h, margin);
            let gap = ((h as f64 - 2.0 * margin) / rows as f64).min(60.0);
            let bar = (gap * 0.5).clamp(1.0, 24.0);
            let top = (h as f64 - gap * rows as f64) / 2.0;
            for k in 0..=n {
                if let Ok(Geometry::Segments(v)) = c.geometry(k) {
                    let y = top + gap * k as f64;
                    for [a, b] in v {
                        let (x0, x1) = (f.pixel_from_world(a)[0], f.pixel_from_world(b)[0]);
                        fill_rect(&mut canvas.image, x0, y, x1, y + bar);
                    }
                }
            }
        }
        _ => {
            let g = c.geometry(n)?;
            let bounds = match c {
                Construction::KochCurve => Bounds {
                    min: [0.0, 0.0],
                    max: [1.0, 0.3],
                },
                Construction::KochSnowflake => Bounds {
                    min: [0.0, -0.29],
                    max: [1.0, 0.87],
                },
                Construction::SierpinskiTriangle => Bounds {
                    min: [0.0, 0.0],
                    max: [1.0, 0.87],
                },
                _ => Bounds {
                    min: [0.0, 0.0],
                    max: [1.0, 1.0],
                },
            };
            let f = Framing::fit(bounds, w, h, margin);
            match g {
                Geometry::Polyline(p) => {
                    for s in p.windows(2) {
                        canvas.line(f.pixel_from_world(s[0]), f.pixel_from_world(s[1]), INK);
                    }
                }
                Geometry::Segments(v) => {
                    for [a, b] in v {
                        canvas.line(f.pixel_from_world(a), f.pixel_from_world(b), INK);
                    }
                }
                Geometry::Triangles(v) => {
                    for t in v {
                        let q = t.map(|p| f.pixel_from_world(p));
                        fill_triangle(&mut canvas.image, q);
                    }
                }
                Geometry::Squares(v) => {
                    for (o, s) in v {
                        let a = f.pixel_from_world(o);
                        let b = f.pixel_from_world([o[0] + s, o[1] + s]);
                        fill_rect(&mut canvas.image, a[0], b[1], b[0], a[1]);
                    }
                }
            }
        }
    }
    Ok(canvas.image)
}

/// Fill the pixels whose centres lie in [x0, x1]×[y0, y1] (pixel coordinates); at least the
/// nearest pixel, so pieces below a pixel stay visible.
fn fill_rect(img: &mut image::RgbImage, x0: f64, y0: f64, x1: f64, y1: f64) {
    let (w, h) = (img.width() as i64, img.height() as i64);
    let (xa, xb) = (x0.min(x1), x0.max(x1));
    let (ya, yb) = (y0.min(y1), y0.max(y1));
    let mut ix0 = xa.ceil() as i64;
    let mut ix1 = xb.floor() as i64;
    let mut iy0 = ya.ceil() as i64;
    let mut iy1 = yb.floor() as i64;
    if ix1 < ix0 {
        ix0 = ((xa + xb) / 2.0).round() as i64;
        ix1 = ix0;
    }
    if iy1 < iy0 {
        iy0 = ((ya + yb) / 2.0).round() as i64;
        iy1 = iy0;
    }
    for y in iy0.max(0)..=iy1.min(h - 1) {
        for x in ix0.max(0)..=ix1.min(w - 1) {
            img.put_pixel(x as u32, y as u32, image::Rgb(INK));
        }
    }
}

/// Fill a triangle given in pixel coordinates (pixel centres inside it; the nearest pixel to
/// its centre when it is smaller than a pixel).
fn fill_triangle(img: &mut image::RgbImage, t: [P2; 3]) {
    let (w, h) = (img.width() as i64, img.height() as i64);
    let xs = t.map(|p| p[0]);
    let ys = t.map(|p| p[1]);
    let min = |v: [f64; 3]| v[0].min(v[1]).min(v[2]);
    let max = |v: [f64; 3]| v[0].max(v[1]).max(v[2]);
    let edge = |a: P2, b: P2, p: P2| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    let area = edge(t[0], t[1], t[2]);
    let mut any = false;
    if area.abs() > 1e-12 {
        for y in (min(ys).ceil() as i64).max(0)..=(max(ys).floor() as i64).min(h - 1) {
            for x in (min(xs).ceil() as i64).max(0)..=(max(xs).floor() as i64).min(w - 1) {
                let p = [x as f64, y as f64];
                let (a, b, c) = (
                    edge(t[0], t[1], p),
                    edge(t[1], t[2], p),
                    edge(t[2], t[0], p),
                );
                let inside = if area > 0.0 {
                    a >= 0.0 && b >= 0.0 && c >= 0.0
                } else {
                    a <= 0.0 && b <= 0.0 && c <= 0.0
                };
                if inside {
                    img.put_pixel(x as u32, y as u32, image::Rgb(INK));
                    any = true;
                }
            }
        }
    }
    if !any {
        let cx = ((xs[0] + xs[1] + xs[2]) / 3.0).round() as i64;
        let cy = ((ys[0] + ys[1] + ys[2]) / 3.0).round() as i64;
        if (0..w).contains(&cx) && (0..h).contains(&cy) {
            img.put_pixel(cx as u32, cy as u32, image::Rgb(INK));
        }
    }
}
