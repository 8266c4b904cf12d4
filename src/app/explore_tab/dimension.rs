//! Dimension: the similarity-dimension solver (ratios typed in), box counting of the current
//! flame, of an IFS preset or of an image with its log-log plot, fitted line and fit range,
//! the divider method on the coastline data, and Voss's lacunarity.

use std::path::{Path, PathBuf};

use eframe::egui::{self, Rect, Vec2};

use super::{ExploreRequest, Plot, checked_drag, explanation, section};
use crate::app::notice::Notice;
use crate::app::worker::{Repaint, TaskWorker, task_worker};
use crate::escape::EscapeDoc;
use crate::explore::dimension::{
    self, BoxCount, COASTLINE_DATA, Ink, LineFit, MAX_RATIOS, MAX_SAMPLES, Mask, VossLevel,
};
use crate::explore::ifs::{Ifs, presets};
use crate::explore::{Bounds, ExploreError};
use crate::flame::Flame;

/// Points of the lacunarity sample.
const VOSS_POINTS: usize = 10_000;

/// What box counting counts.
#[derive(Clone, Debug, PartialEq)]
pub enum BoxSource {
    /// The flame tab's current flame.
    Flame,
    /// An IFS preset by index.
    Preset(usize),
    /// A picture file, thresholded.
    Image(PathBuf),
    /// The boundary of the escape-time tab's set (its inside pixels next to an outside one).
    Escape,
}

/// A finished count.
#[derive(Clone, Debug)]
pub struct BoxResult {
    pub source: String,
    pub count: BoxCount,
    /// Voss's levels and his dimension estimate (point sets only).
    pub voss: Option<(Vec<VossLevel>, Option<LineFit>)>,
}

/// The dimension topic.
pub struct DimensionView {
    /// The ratios typed for the solver.
    pub ratios: String,
    pub source: BoxSource,
    /// Points sampled from a flame or an IFS.
    pub points: f64,
    pub result: Option<BoxResult>,
    pub problem: Option<String>,
    presets: Vec<Ifs>,
    worker: Option<TaskWorker<Result<BoxResult, String>>>,
    started: bool,
    repaint: Repaint,
}

impl DimensionView {
    pub fn new(repaint: Repaint) -> DimensionView {
        DimensionView {
            ratios: "4 * 1/3".into(),
            source: BoxSource::Preset(0),
            points: 1_000_000.0,
            result: None,
            problem: None,
            presets: presets::all(),
            worker: None,
            started: false,
            repaint,
        }
    }

    pub fn reset(&mut self) {
        self.ratios = "4 * 1/3".into();
        self.source = BoxSource::Preset(0);
        self.points = 1_000_000.0;
        self.result = None;
        self.problem = None;
        self.started = false;
    }

    /// The solver's answer for the typed ratios.
    pub fn similarity(&self) -> Result<f64, String> {
        let r = parse_ratios(&self.ratios)?;
        dimension::similarity_dimension(&r).map_err(|e| e.to_string())
    }

    pub fn busy(&self) -> bool {
        self.worker.as_ref().is_some_and(|w| w.is_busy())
    }

    /// A finished count.
    pub(super) fn poll(&mut self) -> Vec<Notice> {
        let mut out = Vec::new();
        if let Some(r) = self.worker.as_ref().and_then(|w| w.poll().pop()) {
            match r {
                Ok(r) => {
                    out.push(Notice::Status(format!(
                        "Box counting of {}: D ≈ {}",
                        r.source,
                        r.count
                            .dimension()
                            .map_or("(no fit)".into(), |d| format!("{d:.4}"))
                    )));
                    self.result = Some(r);
                }
                Err(e) => self.problem = Some(e),
            }
        }
        out
    }

    /// Count an image file's boxes.
    pub fn count_image(&mut self, path: &Path) {
        self.source = BoxSource::Image(path.to_path_buf());
        self.start(None, None);
    }

    /// Start counting the current source (`flame` for the flame source).
    pub fn start(&mut self, flame: Option<&Flame>, escape: Option<&EscapeDoc>) {
        self.started = true;
        self.problem = None;
        let points = self.points as u64;
        if let Err(e) = dimension::check_samples(points) {
            self.problem = Some(e.to_string());
            return;
        }
        let job: Box<dyn FnOnce() -> Result<BoxResult, String> + Send> = match &self.source {
            BoxSource::Flame => {
                let Some(f) = flame.cloned() else {
                    self.problem = Some("There is no flame to count".into());
                    return;
                };
                Box::new(move || {
                    let count = dimension::box_count_flame(&f, points, 1).map_err(s)?;
                    Ok(BoxResult {
                        source: format!("the flame '{}'", f.name),
                        count,
                        voss: None,
                    })
                })
            }
            BoxSource::Preset(i) => {
                let ifs = self.presets[*i].clone();
                Box::new(move || {
                    let count = dimension::box_count_stream(|sink| {
                        let mut g = ifs.chaos_game([0.0, 0.0], 20, 1);
                        for _ in 0..points {
                            sink(g.next_point());
                        }
                    })
                    .map_err(s)?;
                    let sample = ifs.points(VOSS_POINTS, 2);
                    let b = Bounds::of(sample.iter().copied());
                    let side = b.width().max(b.height());
                    let gammas: Vec<f64> = (2..=6).map(|k| side / (1u32 << k) as f64).collect();
                    let voss = dimension::voss(&sample, &gammas).ok().map(|levels| {
                        let fit = dimension::voss_dimension(&levels);
                        (levels, fit)
                    });
                    Ok(BoxResult {
                        source: ifs.name.clone(),
                        count,
                        voss,
                    })
                })
            }
            BoxSource::Escape => {
                let Some(doc) = escape.cloned() else {
                    self.problem = Some("There is no escape-time picture to count".into());
                    return;
                };
                Box::new(move || {
                    let count = dimension::box_count_mask(&escape_boundary(&doc)?).map_err(s)?;
                    Ok(BoxResult {
                        source: "the boundary of the escape-time set".into(),
                        count,
                        voss: None,
                    })
                })
            }
            BoxSource::Image(p) => {
                let p = p.clone();
                Box::new(move || {
                    let img = image::open(&p).map_err(|e| format!("{}: {e}", p.display()))?;
                    let mask = Mask::from_image(&img, 128, Ink::Auto);
                    let count = dimension::box_count_mask(&mask).map_err(s)?;
                    Ok(BoxResult {
                        source: p
                            .file_name()
                            .map_or("the image".into(), |n| n.to_string_lossy().into_owned()),
                        count,
                        voss: None,
                    })
                })
            }
        };
        let r = self.repaint.clone();
        let w = self
            .worker
            .get_or_insert_with(|| task_worker("ugnis-explore-dimension", move || r()));
        w.submit(Box::new(move |_, _| job()));
    }

    fn source_name(&self) -> String {
        match &self.source {
            BoxSource::Flame => "The current flame".into(),
            BoxSource::Preset(i) => format!("IFS: {}", self.presets[*i].name),
            BoxSource::Escape => "The escape-time set's boundary".into(),
            BoxSource::Image(p) => format!(
                "Image: {}",
                p.file_name()
                    .map_or(String::new(), |n| n.to_string_lossy().into_owned())
            ),
        }
    }

    pub(super) fn controls(
        &mut self,
        ui: &mut egui::Ui,
        flame: &Flame,
        escape: &EscapeDoc,
    ) -> Option<ExploreRequest> {
        explanation(
            ui,
            "A dimension says how the amount of a set grows as you look closer. Cut a line \
             into pieces a third as long and you need 3 of them, a square needs 9, a cube 27: \
             3¹, 3², 3³. The Koch curve needs 4 = 3^1.26, so its dimension is 1.26. When a set \
             is made of shrunken copies of itself the ratios give the dimension exactly; \
             otherwise count the boxes of a grid the set touches, finer and finer, and read the \
             dimension off the slope of the log-log plot.",
        );
        self.similarity_section(ui);
        let req = self.box_counting_section(ui, flame, escape);
        super::problem_label(ui, &self.problem);
        self.box_counting_result(ui);
        divider_section(ui);
        req
    }

    /// The similarity dimension of the typed contraction ratios, with examples.
    fn similarity_section(&mut self, ui: &mut egui::Ui) {
        section(ui, "Similarity dimension");
        ui.label("Contraction ratios (e.g. 4 * 1/3 or 0.5, 0.25, 0.25):");
        crate::app::a11y::named(
            ui.add(egui::TextEdit::singleline(&mut self.ratios).desired_width(f32::INFINITY)),
            "contraction ratios",
        );
        ui.horizontal_wrapped(|ui| {
            for (name, r) in [
                ("Cantor", "2 * 1/3"),
                ("Koch", "4 * 1/3"),
                ("Sierpinski", "3 * 1/2"),
                ("Carpet", "8 * 1/3"),
                ("Menger", "20 * 1/3"),
                ("Mixed", "1/2, 1/4, 1/4"),
            ] {
                if ui.small_button(name).on_hover_text(r).clicked() {
                    self.ratios = r.into();
                }
            }
        });
        match self.similarity() {
            Ok(d) => ui.label(format!("Similarity dimension: {d:.5}")),
            Err(e) => ui.colored_label(egui::Color32::from_rgb(255, 120, 100), e),
        };
    }

    /// What to box-count (the flame, the escape-time boundary, an IFS or an image), how many
    /// points, and Count boxes; counts once by itself at the first look.
    fn box_counting_section(
        &mut self,
        ui: &mut egui::Ui,
        flame: &Flame,
        escape: &EscapeDoc,
    ) -> Option<ExploreRequest> {
        let mut req = None;
        section(ui, "Box counting");
        let mut src = self.source.clone();
        egui::ComboBox::from_id_salt("explore-box-source")
            .selected_text(self.source_name())
            .width(260.0)
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut src, BoxSource::Flame, "The current flame");
                ui.selectable_value(
                    &mut src,
                    BoxSource::Escape,
                    "The escape-time set's boundary",
                );
                for (i, p) in self.presets.iter().enumerate() {
                    ui.selectable_value(&mut src, BoxSource::Preset(i), format!("IFS: {}", p.name));
                }
            });
        let changed = src != self.source;
        self.source = src;
        if !matches!(self.source, BoxSource::Image(_) | BoxSource::Escape) {
            ui.horizontal(|ui| {
                ui.label("Points");
                checked_drag(
                    ui,
                    "box counting points",
                    &mut self.points,
                    "the number of points",
                    1000.0,
                    (MAX_SAMPLES as f64).min(20_000_000.0),
                    10_000.0,
                    &mut self.problem,
                );
            });
            self.points = self.points.round();
        }
        ui.horizontal(|ui| {
            if ui
                .add_enabled(!self.busy(), egui::Button::new("Count boxes"))
                .clicked()
                || (changed && matches!(self.source, BoxSource::Preset(_)))
            {
                self.start(Some(flame), Some(escape));
            }
            if ui
                .button("Image…")
                .on_hover_text("box-count a picture file")
                .clicked()
            {
                req = Some(ExploreRequest::BoxCountImage);
            }
            if self.busy() {
                ui.spinner();
            }
        });
        if !self.started {
            self.start(Some(flame), Some(escape));
        }
        req
    }

    /// The box-counting dimension found, and the lacunarity when it was measured.
    fn box_counting_result(&self, ui: &mut egui::Ui) {
        if let Some(r) = &self.result {
            let c = &r.count;
            ui.label(format!("{}: {} samples", r.source, c.samples));
            match (c.fit, c.fit_range) {
                (Some(f), Some((a, b))) => {
                    ui.label(format!(
                        "Box-counting dimension ≈ {:.4} (levels {a}–{b}, r² = {:.5})",
                        f.slope, f.r2
                    ));
                }
                _ => {
                    ui.label("Too few levels to fit a line: use more points");
                }
            }
            if let Some((levels, fit)) = &r.voss {
                section(ui, "Lacunarity (Voss)");
                egui::Grid::new("explore-voss")
                    .num_columns(3)
                    .striped(true)
                    .show(ui, |ui| {
                        ui.strong("box Γ");
                        ui.strong("N(Γ)");
                        ui.strong("Λ(Γ)");
                        ui.end_row();
                        for l in levels {
                            ui.label(format!("{:.4}", l.gamma));
                            ui.label(format!("{:.4}", l.n));
                            ui.label(format!("{:.4}", l.lacunarity));
                            ui.end_row();
                        }
                    });
                if let Some(f) = fit {
                    ui.label(format!(
                        "Voss dimension (slope of −ln N against ln Γ): {:.4}",
                        f.slope
                    ));
                }
                ui.add(
                    egui::Label::new(
                        egui::RichText::new(
                            "Λ is small for an even, dense set and large for a gappy one.",
                        )
                        .weak(),
                    )
                    .wrap(),
                );
            }
        }
    }
}

/// The divider (coastline) method on its sample data.
fn divider_section(ui: &mut egui::Ui) {
    section(ui, "Divider method (coastline)");
    match dimension::divider_dimension(&COASTLINE_DATA) {
        Ok((f, d)) => {
            ui.label(format!(
                "Slope of ln length against ln ruler: {:.6}; D = 1 − slope = {d:.4}",
                f.slope
            ));
        }
        Err(e) => {
            ui.label(e.to_string());
        }
    }
}

impl DimensionView {
    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let (rect, _resp, _ppp, _size, painter) = super::dark_canvas(ui);
        let wide = rect.width() >= rect.height();
        let (a, b) = if wide {
            let w = rect.width() * 0.58;
            (
                Rect::from_min_size(rect.min, Vec2::new(w - 4.0, rect.height())),
                Rect::from_min_max(rect.min + Vec2::new(w + 4.0, 0.0), rect.max),
            )
        } else {
            let h = rect.height() * 0.58;
            (
                Rect::from_min_size(rect.min, Vec2::new(rect.width(), h - 4.0)),
                Rect::from_min_max(rect.min + Vec2::new(0.0, h + 4.0), rect.max),
            )
        };
        let (pts, line, note) = match &self.result {
            Some(r) => {
                let (lo, hi) = r.count.fit_range.unwrap_or((0, 0));
                let pts: Vec<((f64, f64), bool)> = r
                    .count
                    .levels
                    .iter()
                    .map(|l| {
                        (
                            (l.ln_inv_size(), l.ln_count()),
                            l.k >= lo && l.k <= hi && lo > 0,
                        )
                    })
                    .collect();
                let note = match (r.count.fit, r.count.fit_range) {
                    (Some(f), Some((lo, hi))) => format!(
                        "D ≈ {:.4}, fitted on levels {lo}–{hi} (filled dots)",
                        f.slope
                    ),
                    _ => format!("{}: no fit", r.source),
                };
                (pts, r.count.fit.map(|f| (f.slope, f.intercept)), note)
            }
            None if self.busy() => (Vec::new(), None, "Counting…".into()),
            None => (Vec::new(), None, String::new()),
        };
        Plot {
            title: "Box counting: ln N(ε) against ln 1/ε",
            x_label: "ln 1/ε",
            y_label: "ln N",
            points: &pts,
            line,
            note,
        }
        .paint(&painter, a.shrink(6.0));
        let (fit, d) = match dimension::divider_dimension(&COASTLINE_DATA) {
            Ok((f, d)) => (Some(f), d),
            Err(_) => (None, f64::NAN),
        };
        let dpts: Vec<((f64, f64), bool)> = COASTLINE_DATA
            .iter()
            .map(|(s, u)| ((s.ln(), u.ln()), true))
            .collect();
        Plot {
            title: "Dividers: ln length against ln ruler (km)",
            x_label: "ln ruler",
            y_label: "ln length",
            points: &dpts,
            line: fit.map(|f| (f.slope, f.intercept)),
            note: format!("coastline data: D = 1 − slope = {d:.4}"),
        }
        .paint(&painter, b.shrink(6.0));
    }
}

fn s(e: ExploreError) -> String {
    e.to_string()
}

/// Ratios as typed: numbers or fractions separated by commas, semicolons or spaces, each
/// optionally repeated as `k * r` (or `k × r`, `k x r`).
pub fn parse_ratios(text: &str) -> Result<Vec<f64>, String> {
    let number = |t: &str| -> Result<f64, String> {
        let t = t.trim();
        let v = match t.split_once('/') {
            Some((a, b)) => {
                let a: f64 = a
                    .trim()
                    .parse()
                    .map_err(|_| format!("'{t}' is not a number"))?;
                let b: f64 = b
                    .trim()
                    .parse()
                    .map_err(|_| format!("'{t}' is not a number"))?;
                a / b
            }
            None => t.parse().map_err(|_| format!("'{t}' is not a number"))?,
        };
        if v.is_finite() {
            Ok(v)
        } else {
            Err(format!("'{t}' is not a finite number"))
        }
    };
    // Join "k * r" written with spaces into one item before splitting.
    let norm = text
        .replace('×', "*")
        .replace(" x ", "*")
        .replace(" * ", "*")
        .replace("* ", "*")
        .replace(" *", "*");
    let mut out = Vec::new();
    for item in norm
        .split([',', ';', ' ', '\n', '\t'])
        .filter(|s| !s.trim().is_empty())
    {
        let (k, r) = match item.split_once('*') {
            Some((k, r)) => {
                let k: usize = k
                    .trim()
                    .parse()
                    .map_err(|_| format!("'{k}' in '{item}' is not a whole number of copies"))?;
                (k, number(r)?)
            }
            None => (1, number(item)?),
        };
        if out.len() + k > MAX_RATIOS {
            return Err(format!("more than {MAX_RATIOS} ratios"));
        }
        out.extend(std::iter::repeat_n(r, k));
    }
    if out.is_empty() {
        return Err("Type at least one ratio between 0 and 1".into());
    }
    Ok(out)
}

/// The boundary of an escape-time document's set as a mask: rendered with the longer side at
/// most 1024 pixels, a pixel is set when it is inside and one of its four neighbours is not.
fn escape_boundary(doc: &EscapeDoc) -> Result<Mask, String> {
    let side = doc.width.max(doc.height).max(1) as f64;
    let k = (1024.0 / side).min(1.0);
    let w = ((doc.width as f64 * k).round() as u32).max(16);
    let h = ((doc.height as f64 * k).round() as u32).max(16);
    let (_, samples) = crate::escape::render::render(&doc.params, doc.view.clone(), w, h)
        .map_err(|e| e.to_string())?;
    let (wu, hu) = (w as usize, h as usize);
    let inside = |x: usize, y: usize| samples.get(y * wu + x).is_some_and(|s| s.inside);
    let mut bits = vec![false; wu * hu];
    for y in 0..hu {
        for x in 0..wu {
            if inside(x, y) {
                let out = (x > 0 && !inside(x - 1, y))
                    || (x + 1 < wu && !inside(x + 1, y))
                    || (y > 0 && !inside(x, y - 1))
                    || (y + 1 < hu && !inside(x, y + 1));
                bits[y * wu + x] = out;
            }
        }
    }
    Ok(Mask {
        width: w,
        height: h,
        bits,
    })
}

#[cfg(test)]
mod tests {
    use super::parse_ratios;

    #[test]
    fn ratios_parse_with_repetitions_and_fractions() {
        assert_eq!(parse_ratios("4 * 1/3").unwrap(), vec![1.0 / 3.0; 4]);
        assert_eq!(parse_ratios("0.5, 1/4 1/4").unwrap(), vec![0.5, 0.25, 0.25]);
        assert_eq!(parse_ratios("2×0.5").unwrap(), vec![0.5, 0.5]);
        assert!(parse_ratios("abc").unwrap_err().contains("'abc'"));
        assert!(parse_ratios("").is_err());
        assert!(
            parse_ratios("1000000 * 0.5")
                .unwrap_err()
                .contains("more than")
        );
    }
}
