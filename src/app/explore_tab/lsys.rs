//! L-systems: a Fractint `.l` text editor with live redraw (errors shown with their line),
//! the engine's presets, every entry of an opened file, an order slider, the derivation's
//! counts, and SVG or PNG export. The live view walks the derivation through the engine's
//! segment iterator (the string is never built) and stops at a segment cap.

use std::path::{Path, PathBuf};

use eframe::egui;

use super::{BACKGROUND, ExploreRequest, Picture, explanation, key_of, section};
use crate::app::notice::Notice;
use crate::app::worker::{Repaint, TaskWorker, task_worker};
use crate::explore::lsystem::{Compiled, Counts, LSystem, MAX_ORDER, Preset, presets};
use crate::explore::raster::{Canvas, Framing, palette_color};
use crate::explore::{Bounds, ExploreError};
use crate::io;
use crate::io::diag::{Diagnostic, Pos};

/// Most segments the live view draws.
pub const LIVE_SEGMENTS: f64 = 250_000.0;
/// Most symbol visits the live view walks (systems that delete or move a lot draw little
/// for much work).
pub const LIVE_VISITS: f64 = 4_000_000.0;
/// Largest export side.
pub const MAX_EXPORT_SIDE: f64 = 8192.0;

/// The L-system topic.
pub struct LSystemView {
    /// The editor's text (a Fractint `.l` file).
    pub text: String,
    /// The file it was opened from.
    pub file: Option<PathBuf>,
    /// The entries read from the text.
    pub entries: Vec<LSystem>,
    /// The entry drawn.
    pub entry: usize,
    pub order: u32,
    /// A preset drawn as built in (it uses features `.l` files cannot hold), until the text
    /// is edited.
    pub built_in: Option<LSystem>,
    /// What is wrong with the text, with its line: why it cannot be drawn, or what the reader
    /// skipped or ignored in it (the entries it could read are drawn).
    pub error: Option<String>,
    /// Why the picture is not drawn (too large for the live view).
    pub note: Option<String>,
    pub counts: Option<Counts>,
    /// Segments in the live picture.
    pub drawn: u64,
    pub export_size: [f64; 2],
    pub problem: Option<String>,
    presets: Vec<Preset>,
    parsed: Option<u64>,
    compiled: Option<Compiled>,
    picture: Picture,
    export: Option<TaskWorker<Result<String, String>>>,
    repaint: Repaint,
}

impl LSystemView {
    pub fn new(repaint: Repaint) -> LSystemView {
        let mut v = LSystemView {
            text: String::new(),
            file: None,
            entries: Vec::new(),
            entry: 0,
            order: 4,
            built_in: None,
            error: None,
            note: None,
            counts: None,
            drawn: 0,
            export_size: [1600.0, 1600.0],
            problem: None,
            presets: presets::all(),
            parsed: None,
            compiled: None,
            picture: Picture::default(),
            export: None,
            repaint,
        };
        v.choose_preset(0);
        v
    }

    /// Back to the first preset.
    pub fn reset(&mut self) {
        self.file = None;
        self.choose_preset(0);
    }

    /// Show preset `i`: as `.l` text in the editor when the format can hold it, otherwise
    /// drawn as built in.
    pub fn choose_preset(&mut self, i: usize) {
        let Some(p) = self.presets.get(i).cloned() else {
            return;
        };
        self.order = p.order;
        self.entry = 0;
        match io::lsystem::write(std::slice::from_ref(&p.system)) {
            Ok(t) => {
                self.text = t.replace("\r\n", "\n");
                self.built_in = None;
            }
            Err(why) => {
                self.text = format!(
                    "; '{}' is drawn as built in: {why}.\n; Type a system here to draw it instead.\n",
                    p.system.name
                );
                self.built_in = Some(p.system);
            }
        }
        self.parsed = None;
        self.file = None;
    }

    /// Replace the text (as the editor does).
    pub fn set_text(&mut self, text: &str) {
        self.text = text.to_string();
    }

    /// Open a Fractint `.l` file into the editor.
    pub fn open(&mut self, path: &Path) -> Notice {
        match io::read_lsystems(path) {
            Ok(_) => match std::fs::read(path) {
                Ok(bytes) => {
                    let (text, _) = io::diag::decode_text(&bytes, &path.display().to_string());
                    self.text = text.replace("\r\n", "\n");
                    self.file = Some(path.to_path_buf());
                    self.built_in = None;
                    self.entry = 0;
                    self.parsed = None;
                    self.sync();
                    Notice::Status(format!(
                        "Opened {}: {} entries",
                        path.display(),
                        self.entries.len()
                    ))
                }
                Err(e) => Notice::Message {
                    title: "Cannot open".into(),
                    text: format!("{}: {e}", path.display()),
                },
            },
            Err(d) => Notice::Message {
                title: "Cannot open".into(),
                text: d.to_string(),
            },
        }
    }

    /// Draw entry `i` of the text.
    pub fn choose_entry(&mut self, i: usize) {
        self.entry = i;
        self.parsed = None;
        self.sync();
    }

    /// The system drawn.
    pub fn system(&self) -> Option<&LSystem> {
        self.built_in
            .as_ref()
            .or_else(|| self.entries.get(self.entry))
    }

    fn source_name(&self) -> String {
        self.file.as_ref().map_or("editor".into(), |p| {
            p.file_name()
                .map_or("editor".into(), |n| n.to_string_lossy().into_owned())
        })
    }

    /// Parse and compile again when the text changed.
    pub fn sync(&mut self) {
        let k = key_of((&self.text, self.built_in.is_some()));
        if self.parsed == Some(k) {
            return;
        }
        self.parsed = Some(k);
        self.picture.invalidate();
        self.error = None;
        self.compiled = None;
        if let Some(b) = &self.built_in {
            match b.compile() {
                Ok(c) => self.compiled = Some(c),
                Err(e) => self.error = Some(e.to_string()),
            }
            return;
        }
        match io::lsystem::parse(&self.text, &self.source_name()) {
            Ok(p) => {
                self.error = p.warnings.first().map(describe);
                self.entries = p.value.entries;
                if self.entries.is_empty() {
                    self.error = Some("No entries: write Name { Angle n, Axiom …, rules }".into());
                    return;
                }
                self.entry = self.entry.min(self.entries.len() - 1);
                match self.entries[self.entry].compile() {
                    Ok(c) => self.compiled = Some(c),
                    Err(e) => {
                        self.error = Some(format!("Entry '{}': {e}", self.entries[self.entry].name))
                    }
                }
            }
            Err(d) => {
                self.entries.clear();
                self.error = Some(describe(&d));
            }
        }
    }

    pub fn status_text(&self) -> String {
        match (self.system(), &self.counts) {
            (Some(s), Some(c)) => {
                format!("{} order {}: {} segments", s.name, self.order, c.segments)
            }
            _ => "L-systems".into(),
        }
    }

    /// Export results.
    pub(super) fn poll(&mut self) -> Vec<Notice> {
        let mut out = Vec::new();
        if let Some(r) = self.export.as_ref().and_then(|w| w.poll().pop()) {
            self.export = None;
            out.push(match r {
                Ok(s) => Notice::Status(s),
                Err(e) => Notice::Message {
                    title: "Export failed".into(),
                    text: e,
                },
            });
        }
        out
    }

    /// Write the current system at the current order to `path` (SVG or PNG by its
    /// extension), in the background and atomically.
    pub fn export(&mut self, path: PathBuf) -> Notice {
        self.sync();
        let Some(c) = self.compiled.clone() else {
            return Notice::Message {
                title: "Export".into(),
                text: "There is no system to export; fix the text first.".into(),
            };
        };
        let order = self.order;
        let [w, h] = self.export_size.map(|v| v as u32);
        let svg = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
        let r = self.repaint.clone();
        let worker = task_worker("ugnis-lsystem-export", move || r());
        worker.submit(Box::new(move |_, _| {
            let counts = c.counts(order);
            if svg {
                io::svg::save_lsystem(&path, &c, order, w, h, Some(BACKGROUND))
                    .map_err(|e| e.to_string())?;
            } else {
                let img = c
                    .render(order, w, h, BACKGROUND)
                    .map_err(|e| e.to_string())?;
                io::png::save(
                    &path,
                    &image::DynamicImage::ImageRgb8(img),
                    &Default::default(),
                )
                .map_err(|e| format!("{}: {e}", path.display()))?;
            }
            Ok(format!(
                "Exported {} ({} segments)",
                path.display(),
                counts.segments
            ))
        }));
        self.export = Some(worker);
        Notice::Status("Exporting…".into())
    }

    pub(super) fn controls(&mut self, ui: &mut egui::Ui) -> Option<ExploreRequest> {
        let mut req = None;
        self.sync();
        explanation(
            ui,
            "An L-system is a word and rewriting rules: at every order each letter is replaced \
             by its rule, all at once, so the word grows like a plant grows cells. A turtle then \
             reads the word: F draws a step, + and − turn by the angle, [ and ] remember and \
             return to a place, which makes branches. Self-similar curves appear because every F \
             turns into a small copy of the whole rule.",
        );
        section(ui, "System");
        let mut chosen = None;
        egui::ComboBox::from_label("Presets")
            .selected_text("choose…")
            .show_ui(ui, |ui| {
                for (i, p) in self.presets.iter().enumerate() {
                    if ui
                        .selectable_label(false, p.system.name.as_str())
                        .on_hover_text(plain(p.note))
                        .clicked()
                    {
                        chosen = Some(i);
                    }
                }
            });
        if let Some(i) = chosen {
            self.choose_preset(i);
            self.sync();
        }
        ui.horizontal(|ui| {
            if ui
                .button("Open .l file…")
                .on_hover_text("a Fractint L-system file; every entry can be drawn")
                .clicked()
            {
                req = Some(ExploreRequest::OpenLFile);
            }
            if ui
                .add_enabled(self.compiled.is_some(), egui::Button::new("Export…"))
                .on_hover_text("SVG or PNG at the export size, by the file's extension")
                .clicked()
            {
                req = Some(ExploreRequest::ExportLSystem);
            }
        });
        if self.built_in.is_none() && self.entries.len() > 1 {
            let mut e = self.entry;
            egui::ComboBox::from_label("Entry")
                .selected_text(self.entries[e.min(self.entries.len() - 1)].name.clone())
                .show_ui(ui, |ui| {
                    for (i, s) in self.entries.iter().enumerate() {
                        ui.selectable_value(&mut e, i, s.name.as_str());
                    }
                });
            if e != self.entry {
                self.choose_entry(e);
            }
        }
        let mut order = self.order;
        ui.horizontal(|ui| {
            ui.label("Order");
            ui.add(egui::Slider::new(&mut order, 0..=MAX_ORDER))
                .on_hover_text(format!(
                    "0 to {MAX_ORDER}; the live view draws up to {LIVE_SEGMENTS} segments"
                ));
        });
        if order != self.order {
            self.order = order;
            self.picture.invalidate();
        }
        let name = self.source_name();
        ui.label(format!("Text ({name}):"));
        let edit = egui::TextEdit::multiline(&mut self.text)
            .code_editor()
            .desired_rows(10)
            .desired_width(f32::INFINITY);
        crate::app::a11y::named(ui.add(edit), "L-system text");
        if self.built_in.is_some() && key_of((&self.text, true)) != self.parsed.unwrap_or(0) {
            // Typing replaces the built-in preset by the text.
            self.built_in = None;
        }
        self.sync();
        if let Some(e) = &self.error {
            super::problem_label(ui, &Some(e.clone()));
        }
        section(ui, "Numbers");
        match (&self.compiled, self.counts.clone()) {
            (Some(c), Some(k)) => {
                ui.label(format!("Angle: {:.4}°", c.system.angle.degrees()));
                ui.label(format!("Segments: {}", k.segments));
                ui.label(format!("Length of the word: {}", k.symbols));
                ui.label(format!("Symbols the turtle visits: {}", k.visits));
                ui.label(format!("Segments drawn here: {}", self.drawn));
            }
            _ => {
                ui.label("(nothing drawn)");
            }
        }
        if let Some(n) = &self.note {
            super::problem_label(ui, &Some(n.clone()));
        }
        section(ui, "Export size");
        ui.horizontal(|ui| {
            super::checked_drag(
                ui,
                "export width",
                &mut self.export_size[0],
                "the export width",
                16.0,
                MAX_EXPORT_SIDE,
                4.0,
                &mut self.problem,
            );
            ui.label("×");
            super::checked_drag(
                ui,
                "export height",
                &mut self.export_size[1],
                "the export height",
                16.0,
                MAX_EXPORT_SIDE,
                4.0,
                &mut self.problem,
            );
        });
        self.export_size = self.export_size.map(f64::round);
        super::problem_label(ui, &self.problem);
        if self.export.as_ref().is_some_and(|w| w.is_busy()) {
            ui.label("Exporting…");
        }
        req
    }

    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        self.sync();
        let (rect, _resp, _ppp, size, painter) = super::dark_canvas(ui);
        let Some(c) = self.compiled.clone() else {
            self.counts = None;
            return;
        };
        let order = self.order;
        let k = key_of((self.parsed, order, size));
        let counts = c.counts(order);
        self.counts = Some(counts.clone());
        let mut result = None;
        self.picture.update(&ctx, "explore-lsystem", k, || {
            match draw(&c, order, size, &counts) {
                Ok((img, n)) => {
                    result = Some(Ok(n));
                    Some(img)
                }
                Err(e) => {
                    result = Some(Err(e));
                    None
                }
            }
        });
        match result {
            Some(Ok(n)) => {
                self.drawn = n;
                self.note = None;
            }
            Some(Err(e)) => {
                self.drawn = 0;
                self.note = Some(e);
            }
            None => {}
        }
        self.picture.paint(&painter, rect);
        if let Some(n) = &self.note {
            painter.text(
                rect.center(),
                egui::Align2::CENTER_CENTER,
                n,
                egui::FontId::proportional(15.0),
                egui::Color32::from_rgb(255, 160, 120),
            );
        }
    }
}

/// Superscripts written out (the interface font has no superscript n or minus).
fn plain(s: &str) -> String {
    s.replace("⁻ⁿ", "^-n").replace('ⁿ', "^n").replace('⁻', "^-")
}

/// "Line 3, column 7: message" for the editor.
fn describe(d: &Diagnostic) -> String {
    match d.pos {
        Pos::LineCol(l, c) => format!("Line {l}, column {c}: {}", d.message),
        _ => d.message.clone(),
    }
}

/// Draw the system at `order`, framed to fit, unless it is too large for the live view.
fn draw(
    c: &Compiled,
    order: u32,
    size: [u32; 2],
    counts: &Counts,
) -> Result<(image::RgbImage, u64), String> {
    if counts.segments > LIVE_SEGMENTS || counts.visits > LIVE_VISITS {
        return Err(format!(
            "Order {order} draws {} segments ({} symbol visits);\nthe live view stops at {} segments. \
             Lower the order, or export it.",
            counts.segments, counts.visits, LIVE_SEGMENTS
        ));
    }
    let err = |e: ExploreError| e.to_string();
    let mut b = Bounds::EMPTY;
    let mut segs = c.segments(order).map_err(err)?;
    for s in segs.by_ref() {
        b.add(s.a);
        b.add(s.b);
    }
    if let Some(e) = segs.error() {
        return Err(e.to_string());
    }
    let [w, h] = size;
    let f = Framing::fit(b, w, h, 12.0 + 0.03 * w.min(h) as f64);
    let mut canvas = Canvas::new(w, h, BACKGROUND).map_err(err)?;
    let mut segs = c.segments(order).map_err(err)?;
    for s in segs.by_ref() {
        // Fractint's white (colour 15) on our dark background reads better as the ink.
        let col = if s.color == crate::explore::lsystem::DEFAULT_COLOR {
            super::INK
        } else {
            palette_color(s.color)
        };
        canvas.line(f.pixel_from_world(s.a), f.pixel_from_world(s.b), col);
    }
    Ok((canvas.image, segs.drawn()))
}
