//! The escape-time tab: the view rendered progressively in the background (coarse to fine),
//! wheel zoom at the cursor, drag to pan, right-drag rectangle zoom, back/forward history,
//! family and colouring choosers, a live Julia preview for the c under the cursor on the
//! Mandelbrot set (click opens it), export and view files.

pub(crate) mod canvas;
pub(crate) mod controls;
pub(crate) mod display;

use std::path::{Path, PathBuf};

use eframe::egui::{self, Pos2, Vec2};

use crate::app::notice::Notices;
use crate::app::worker::{Repaint, TaskWorker, repaint_of, task_worker};
use crate::escape::EscapeDoc;
use crate::escape::{C, Family, Fill, View};
use crate::io;
use crate::io::escape_view::{self, family_from_name};
use display::Display;

/// What the tab asks the application to do (file dialogs live in the app).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EscapeRequest {
    OpenView,
    SaveView,
    Export,
}

/// State of the escape-time tab.
pub struct EscapeTab {
    pub doc: EscapeDoc,
    back: Vec<EscapeDoc>,
    forward: Vec<EscapeDoc>,
    main: Option<Display>,
    julia: Option<Display>,
    /// World point under the mouse.
    pub hover: Option<C>,
    /// Right-drag rectangle zoom: start in screen coordinates.
    rect_start: Option<Pos2>,
    /// Pan in progress: the view when the drag started.
    pan_start: Option<View>,
    poly_text: String,
    pub export_size: [u32; 2],
    pub path: Option<PathBuf>,
    pub notices: Notices,
    /// A running export.
    export_job: Option<TaskWorker<Result<PathBuf, String>>>,
    repaint: Repaint,
    /// Whether the background renderers may start (false in tests).
    pub render: bool,
    /// A parameter drag is in progress (one history step for all of it).
    editing: bool,
    /// Max iterations follow the depth (until the user sets them).
    pub auto_iter: bool,
    /// Where the picture was drawn last (screen points).
    pub canvas_rect: Option<egui::Rect>,
}

impl Default for EscapeTab {
    fn default() -> Self {
        let doc = EscapeDoc::new(Family::Mandelbrot { power: 2 });
        EscapeTab {
            doc,
            back: Vec::new(),
            forward: Vec::new(),
            main: None,
            julia: None,
            hover: None,
            rect_start: None,
            pan_start: None,
            poly_text: "1 0 0 -1".into(),
            export_size: [1920, 1080],
            path: None,
            notices: Notices::default(),
            export_job: None,
            repaint: repaint_of(None),
            render: true,
            editing: false,
            auto_iter: true,
            canvas_rect: None,
        }
    }
}

/// The families, by file name and menu label.
pub(crate) const KINDS: [(&str, &str); 8] = [
    ("mandelbrot", "Mandelbrot"),
    ("julia", "Julia"),
    ("multibrot", "z^m + c"),
    ("burning-ship", "Burning Ship"),
    ("newton", "Newton"),
    ("logistic", "Logistic λz(1−z)"),
    ("cubic", "Cubic z³ + z + p"),
    ("warped-julia", "Warped Julia"),
];

impl EscapeTab {
    /// A new tab; with `ctx` the background renderers start (none in tests).
    pub fn new(ctx: Option<&egui::Context>) -> EscapeTab {
        EscapeTab {
            render: ctx.is_some(),
            repaint: repaint_of(ctx),
            ..EscapeTab::default()
        }
    }

    /// Remember the current view for Back.
    fn push_history(&mut self) {
        self.back.push(self.doc.clone());
        if self.back.len() > 200 {
            self.back.remove(0);
        }
        self.forward.clear();
    }

    pub fn go_back(&mut self) {
        if let Some(d) = self.back.pop() {
            self.forward.push(std::mem::replace(&mut self.doc, d));
        }
    }

    pub fn go_forward(&mut self) {
        if let Some(d) = self.forward.pop() {
            self.back.push(std::mem::replace(&mut self.doc, d));
        }
    }

    pub fn can_go_back(&self) -> bool {
        !self.back.is_empty()
    }

    pub fn can_go_forward(&self) -> bool {
        !self.forward.is_empty()
    }

    /// Switch to a family with its default view (one history step).
    pub fn set_kind(&mut self, kind: &str) {
        let Some(f) = family_from_name(kind) else {
            return;
        };
        self.push_history();
        let mut d = EscapeDoc::new(f);
        d.params.palette.gradient = self.doc.params.palette.gradient.clone();
        d.gradient_source = self.doc.gradient_source.clone();
        d.width = self.doc.width;
        d.height = self.doc.height;
        let (c, hh) = d.params.family.default_view();
        d.view = View::new(c, hh);
        if let Family::Newton { coeffs } = &d.params.family {
            self.poly_text = escape_view::write(&d)
                .lines()
                .find_map(|l| l.strip_prefix("poly = ").map(str::to_string))
                .unwrap_or_else(|| format!("{coeffs:?}"));
        }
        self.doc = d;
    }

    /// Open the Julia set for c (from the Mandelbrot view).
    pub fn open_julia(&mut self, c: C) {
        let power = match self.doc.params.family {
            Family::Mandelbrot { power } => power,
            _ => 2,
        };
        self.push_history();
        let mut d = self.doc.clone();
        d.params.family = Family::Julia { power, c };
        let (center, hh) = d.params.family.default_view();
        d.view = View::new(center, hh);
        self.doc = d;
        self.notices.status = format!("Julia set for c = {:.6} {:+.6}i", c.re, c.im);
    }

    /// Zoom by `factor` at a point given in image pixels (one history step).
    pub fn zoom_at(&mut self, px: [f64; 2], factor: f64) {
        if matches!(self.doc.params.family, Family::WarpedJulia(_)) {
            return;
        }
        let v = self
            .doc
            .view
            .zoomed_at(px[0], px[1], self.doc.width, self.doc.height, factor);
        if let Err(e) = crate::escape::render::check_view_for(
            &self.doc.params.family,
            &v,
            self.doc.width,
            self.doc.height,
        ) {
            self.notices.status = e.to_string();
            return;
        }
        self.push_history();
        self.doc.view = v;
    }

    pub fn load(&mut self, doc: EscapeDoc, path: Option<PathBuf>) {
        self.push_history();
        // A view file's iteration limit was chosen for it.
        self.auto_iter = false;
        self.doc = doc;
        self.path = path;
    }

    /// File › New: the Mandelbrot set's default view (one history step).
    pub fn new_view(&mut self) {
        self.set_kind("mandelbrot");
        self.path = None;
        self.notices.status("New view");
    }

    /// Open a view file; true when it opened.
    pub fn open(&mut self, path: &Path) -> bool {
        match io::escape_view::read(path) {
            Ok(p) => {
                if !p.warnings.is_empty() {
                    let w: Vec<String> = p.warnings.iter().map(|w| w.to_string()).collect();
                    self.notices.message("Warnings", w.join("\n"));
                }
                self.load(p.value, Some(path.to_path_buf()));
                self.notices.status(format!("Opened {}", path.display()));
                true
            }
            Err(e) => {
                self.notices.message("Cannot open", e.to_string());
                false
            }
        }
    }

    /// Save the view file; true when it was written.
    pub fn save(&mut self, path: &Path) -> bool {
        match io::escape_view::save(path, &self.doc) {
            Ok(()) => {
                self.notices.status(format!("Saved {}", path.display()));
                self.path = Some(path.to_path_buf());
                true
            }
            Err(e) => {
                self.notices
                    .message("Cannot save", format!("{}: {e}", path.display()));
                false
            }
        }
    }

    /// Render the view at the export size into a PNG (with the view embedded) or BMP, in
    /// the background.
    pub fn export(&mut self, out: PathBuf) {
        let doc = self.export_doc();
        let r = self.repaint.clone();
        let w = task_worker("ugnis-escape-export", move || r());
        self.notices.status(format!("Exporting {}…", out.display()));
        w.submit(Box::new(move |_, _| {
            let (img, _) =
                crate::escape::render(&doc.params, doc.view.clone(), doc.width, doc.height)
                    .map_err(|e| e.to_string())?;
            let img = image::DynamicImage::ImageRgb8(img);
            let res = if io::kind_of(&out) == io::FileKind::Bmp {
                io::bmp::save(&out, &img)
            } else {
                let meta = io::png::PngMeta {
                    text: vec![("ugnis_escape_view".into(), io::escape_view::write(&doc))],
                    ..Default::default()
                };
                io::png::save(&out, &img, &meta)
            };
            res.map_err(|e| format!("{}: {e}", out.display()))?;
            Ok(out)
        }));
        self.export_job = Some(w);
    }

    fn poll_export(&mut self) {
        let Some(w) = &self.export_job else {
            return;
        };
        match w.poll().pop() {
            Some(Ok(p)) => {
                self.export_job = None;
                self.notices.status(format!("Exported {}", p.display()));
            }
            Some(Err(e)) => {
                self.export_job = None;
                self.notices.message("Export failed", e);
            }
            None => {}
        }
    }
    /// The view as an export at `export_size` (same centre and world width).
    pub fn export_doc(&self) -> EscapeDoc {
        let mut d = self.doc.clone();
        d.resize(self.export_size[0].max(1), self.export_size[1].max(1));
        d
    }

    /// With automatic iterations, the limit the view's depth asks for (the families that
    /// zoom deep; the others keep theirs).
    pub fn apply_auto_iter(&mut self) {
        if self.auto_iter && crate::escape::supports_deep_zoom(&self.doc.params.family) {
            self.doc.params.max_iter = crate::escape::auto_max_iter(self.doc.view.half_height_fx());
        }
    }

    /// The view's width as the depth a user reads ("width 3.2e-412").
    pub fn depth_text(&self) -> String {
        format!("width {:.2}", self.doc.world_width_fx())
    }

    /// Stop the picture's render (the reference orbit of a deep view or its passes).
    pub fn stop(&mut self) {
        if let Some(d) = &mut self.main {
            d.stop();
            self.notices.status("Stopped");
        }
    }

    /// Whether the picture is still being computed.
    pub fn busy(&self) -> bool {
        self.main.as_ref().is_some_and(|d| d.busy())
    }

    /// While a deep view computes its reference orbit: iterations done and the limit.
    pub fn orbit_progress(&self) -> Option<(u64, u64)> {
        self.main.as_ref().and_then(|d| d.orbit_progress())
    }

    /// The newest picture on screen shows more than one colour.
    pub fn picture_shows_something(&self) -> bool {
        self.main
            .as_ref()
            .and_then(|d| d.last_image.as_ref())
            .is_some_and(|img| {
                img.pixels.len() > 1 && img.pixels.iter().any(|p| *p != img.pixels[0])
            })
    }

    /// Draw the tab. Returns a request for the application.
    pub fn ui(&mut self, ui: &mut egui::Ui) -> Option<EscapeRequest> {
        let ctx = ui.ctx().clone();
        self.poll_export();
        self.apply_auto_iter();
        if self.render && self.main.is_none() {
            self.main = Some(Display::new(&ctx));
            self.julia = Some(Display::new(&ctx));
        }
        if ctx.input(|i| i.modifiers.alt && i.key_pressed(egui::Key::ArrowLeft)) {
            self.go_back();
        }
        if ctx.input(|i| i.modifiers.alt && i.key_pressed(egui::Key::ArrowRight)) {
            self.go_forward();
        }
        let mut req = None;
        let width = ui.available_width();
        egui::Panel::left("escape-controls")
            .default_size(300.0f32.min(width * 0.4))
            .max_size((width * 0.45).max(160.0))
            .resizable(true)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    req = self.controls(ui);
                    // Live Julia preview.
                    if let (Family::Mandelbrot { power }, Some(c)) =
                        (&self.doc.params.family, self.hover)
                    {
                        ui.separator();
                        ui.label(format!("Julia set of c = {:.5} {:+.5}i", c.re, c.im));
                        let mut jp = self.doc.params.clone();
                        jp.family = Family::Julia { power: *power, c };
                        jp.max_iter = jp.max_iter.min(300);
                        jp.fill = Fill::Exact;
                        let (jc, hh) = jp.family.default_view();
                        let size = [240u32, 180u32];
                        if let Some(d) = &mut self.julia {
                            d.request(&jp, View::new(jc, hh), size);
                            d.poll(&ctx, "escape-julia");
                            if let Some(t) = &d.texture {
                                ui.image((t.id(), Vec2::new(240.0, 180.0)));
                            }
                        }
                    }
                });
            });
        egui::CentralPanel::default().show(ui, |ui| self.canvas(ui));
        req
    }
    /// Status-bar text: coordinates, view width, render progress.
    pub fn status_text(&self) -> String {
        let deep = crate::escape::render::is_deep(
            &self.doc.params.family,
            &self.doc.view,
            self.doc.height,
        );
        let mut s = if deep {
            // Pointer coordinates in f64 would all look alike here: show the depth and the
            // start of the exact centre (Copy centre gives all of it).
            let [x, y] = self.doc.view.centre_text();
            let short = |t: &str| -> String {
                if t.len() > 40 {
                    format!("{}…", &t[..40])
                } else {
                    t.to_string()
                }
            };
            format!("deep zoom, centre {}, {}", short(&x), short(&y))
        } else {
            match self.hover {
                Some(c) => format!("{:.10} {:+.10}i", c.re, c.im),
                None => "—".into(),
            }
        };
        s += &format!("   {}", self.depth_text());
        if let Some((done, of)) = self.orbit_progress() {
            s += &format!(
                "   reference orbit {done} of {of} iterations ({:.0}%)",
                done as f64 * 100.0 / of.max(1) as f64
            );
        } else if let Some(d) = &self.main {
            s += &format!(
                "   {}×{}  {:.0}%  {:.0} ms",
                self.doc.width,
                self.doc.height,
                d.fraction * 100.0,
                d.elapsed_ms
            );
        }
        s
    }
}
