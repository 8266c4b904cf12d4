//! The escape-time tab: the view rendered progressively in the background (coarse to fine),
//! wheel zoom at the cursor, drag to pan, right-drag rectangle zoom, back/forward history,
//! family and colouring choosers, a live Julia preview for the c under the cursor on the
//! Mandelbrot set (click opens it), export and view files.

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread::JoinHandle;
use std::time::Instant;

use eframe::egui::{self, Color32, Pos2, Rect, Sense, Stroke, Vec2};

use crate::escape::{
    C, Coloring, EscapeParams, EscapeRenderer, Family, Fill, Preset, Sampling, View, Warp,
};
use crate::gradient;
use crate::io::escape_view::{self, EscapeDoc, family_from_name};

/// A render request for the escape worker.
struct Job {
    params: EscapeParams,
    view: View,
    w: u32,
    h: u32,
    generation: u64,
}

/// A frame from the escape worker.
pub struct EscapeFrame {
    pub generation: u64,
    pub image: egui::ColorImage,
    pub fraction: f64,
    pub elapsed_ms: f64,
    pub done: bool,
    pub error: Option<String>,
}

/// Background renderer: the newest job wins; each pass sends a frame.
pub struct EscapeWorker {
    tx: Sender<Option<Job>>,
    rx: Receiver<EscapeFrame>,
    cancel: Arc<AtomicBool>,
    handle: Option<JoinHandle<()>>,
}

fn color_image(img: &image::RgbImage) -> egui::ColorImage {
    egui::ColorImage::from_rgb([img.width() as usize, img.height() as usize], img.as_raw())
}

impl EscapeWorker {
    pub fn new(repaint: impl Fn() + Send + 'static) -> EscapeWorker {
        let (tx, jobs) = mpsc::channel::<Option<Job>>();
        let (out, rx) = mpsc::channel();
        let cancel = Arc::new(AtomicBool::new(false));
        let c = cancel.clone();
        let handle = std::thread::Builder::new()
            .name("ugnis-escape".into())
            .spawn(move || {
                let mut pending: Option<Job> = None;
                loop {
                    let job = match pending.take() {
                        Some(j) => j,
                        None => match jobs.recv() {
                            Ok(Some(j)) => j,
                            _ => return,
                        },
                    };
                    // Only the newest queued job matters.
                    let mut job = job;
                    while let Ok(m) = jobs.try_recv() {
                        match m {
                            Some(j) => job = j,
                            None => return,
                        }
                    }
                    c.store(false, Ordering::SeqCst);
                    let t = Instant::now();
                    let mut r = match EscapeRenderer::new(&job.params, job.view, job.w, job.h) {
                        Ok(r) => r,
                        Err(e) => {
                            let _ = out.send(EscapeFrame {
                                generation: job.generation,
                                image: egui::ColorImage::new([1, 1], vec![Color32::BLACK]),
                                fraction: 0.0,
                                elapsed_ms: 0.0,
                                done: true,
                                error: Some(e.to_string()),
                            });
                            repaint();
                            continue;
                        }
                    };
                    while !r.is_done() {
                        if !r.run_pass(&c) {
                            break;
                        }
                        let frame = EscapeFrame {
                            generation: job.generation,
                            image: color_image(&r.image()),
                            fraction: r.fraction(),
                            elapsed_ms: t.elapsed().as_secs_f64() * 1000.0,
                            done: r.is_done(),
                            error: None,
                        };
                        if out.send(frame).is_err() {
                            return;
                        }
                        repaint();
                        // A newer job cancels the rest of this one.
                        if let Ok(m) = jobs.try_recv() {
                            match m {
                                Some(j) => {
                                    pending = Some(j);
                                    break;
                                }
                                None => return,
                            }
                        }
                    }
                }
            })
            .expect("spawn escape thread");
        EscapeWorker {
            tx,
            rx,
            cancel,
            handle: Some(handle),
        }
    }

    fn submit(&self, job: Job) {
        self.cancel.store(true, Ordering::SeqCst);
        let _ = self.tx.send(Some(job));
    }

    fn poll(&self) -> Vec<EscapeFrame> {
        self.rx.try_iter().collect()
    }
}

impl Drop for EscapeWorker {
    fn drop(&mut self) {
        self.cancel.store(true, Ordering::SeqCst);
        let _ = self.tx.send(None);
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

/// What the tab asks the application to do (file dialogs live in the app).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EscapeRequest {
    OpenView,
    SaveView,
    Export,
}

struct Display {
    worker: EscapeWorker,
    texture: Option<egui::TextureHandle>,
    generation: u64,
    shown: u64,
    submitted: Option<(EscapeParams, View, [u32; 2])>,
    /// The view of the texture on screen (to draw it shifted/zoomed until the new frame).
    shown_view: Option<View>,
    fraction: f64,
    elapsed_ms: f64,
    error: Option<String>,
}

impl Display {
    fn new(ctx: &egui::Context) -> Display {
        let c = ctx.clone();
        Display {
            worker: EscapeWorker::new(move || c.request_repaint()),
            texture: None,
            generation: 0,
            shown: 0,
            submitted: None,
            shown_view: None,
            fraction: 0.0,
            elapsed_ms: 0.0,
            error: None,
        }
    }

    fn request(&mut self, params: &EscapeParams, view: View, size: [u32; 2]) {
        let key = (params.clone(), view, size);
        if self.submitted.as_ref() != Some(&key) {
            self.generation += 1;
            self.worker.submit(Job {
                params: params.clone(),
                view,
                w: size[0],
                h: size[1],
                generation: self.generation,
            });
            self.submitted = Some(key);
        }
    }

    fn poll(&mut self, ctx: &egui::Context, name: &str) {
        for f in self.worker.poll() {
            if f.generation != self.generation {
                continue;
            }
            self.error = f.error;
            if self.error.is_none() {
                match &mut self.texture {
                    Some(t) => t.set(f.image, egui::TextureOptions::NEAREST),
                    None => {
                        self.texture =
                            Some(ctx.load_texture(name, f.image, egui::TextureOptions::NEAREST))
                    }
                }
                self.shown = f.generation;
                self.shown_view = self.submitted.as_ref().map(|s| s.1);
            }
            self.fraction = f.fraction;
            self.elapsed_ms = f.elapsed_ms;
        }
    }
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
    pub status: String,
    /// Whether the background renderers may start (false in tests).
    pub render: bool,
    /// A parameter drag is in progress (one history step for all of it).
    editing: bool,
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
            status: String::new(),
            render: true,
            editing: false,
        }
    }
}

const KINDS: [(&str, &str); 7] = [
    ("mandelbrot", "Mandelbrot"),
    ("julia", "Julia"),
    ("multibrot", "z^m + c"),
    ("newton", "Newton"),
    ("logistic", "Logistic λz(1−z)"),
    ("cubic", "Cubic z³ + z + p"),
    ("warped-julia", "Warped Julia"),
];

impl EscapeTab {
    /// A new tab; `render`: start background renderers (false in tests).
    pub fn new(render: bool) -> EscapeTab {
        EscapeTab {
            render,
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
        self.status = format!("Julia set for c = {:.6} {:+.6}i", c.re, c.im);
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
            self.status = e.to_string();
            return;
        }
        self.push_history();
        self.doc.view = v;
    }

    pub fn load(&mut self, doc: EscapeDoc, path: Option<PathBuf>) {
        self.push_history();
        self.doc = doc;
        self.path = path;
    }

    fn controls(&mut self, ui: &mut egui::Ui) -> Option<EscapeRequest> {
        let mut req = None;
        let before = self.doc.clone();
        ui.horizontal(|ui| {
            if ui
                .add_enabled(!self.back.is_empty(), egui::Button::new("Back"))
                .on_hover_text("previous view (Alt+Left)")
                .clicked()
            {
                self.go_back();
            }
            if ui
                .add_enabled(!self.forward.is_empty(), egui::Button::new("Forward"))
                .on_hover_text("next view (Alt+Right)")
                .clicked()
            {
                self.go_forward();
            }
            if ui.button("Reset view").clicked() {
                let (c, hh) = self.doc.params.family.default_view();
                self.push_history();
                self.doc.view = View::new(c, hh);
            }
        });
        ui.separator();
        let current = self.doc.params.family.name();
        let mut chosen = None;
        egui::ComboBox::from_label("Fractal")
            .selected_text(
                KINDS
                    .iter()
                    .find(|k| k.0 == current)
                    .map_or(current, |k| k.1),
            )
            .show_ui(ui, |ui| {
                for (k, label) in KINDS {
                    if ui.selectable_label(k == current, label).clicked() {
                        chosen = Some(k);
                    }
                }
            });
        if let Some(k) = chosen
            && k != current
        {
            self.set_kind(k);
        }
        let mut doc = self.doc.clone();
        egui::Grid::new("escape-params")
            .num_columns(2)
            .show(ui, |ui| {
                let cpx = |ui: &mut egui::Ui, label: &str, c: &mut C| {
                    ui.label(label);
                    ui.horizontal(|ui| {
                        ui.add(egui::DragValue::new(&mut c.re).speed(0.001).max_decimals(8));
                        ui.add(egui::DragValue::new(&mut c.im).speed(0.001).max_decimals(8));
                        ui.label("i");
                    });
                    ui.end_row();
                };
                match &mut doc.params.family {
                    Family::Mandelbrot { power } => {
                        ui.label("Power m");
                        ui.add(egui::DragValue::new(power).range(2..=9));
                        ui.end_row();
                    }
                    Family::Julia { power, c } => {
                        ui.label("Power m");
                        ui.add(egui::DragValue::new(power).range(2..=9));
                        ui.end_row();
                        cpx(ui, "c", c);
                    }
                    Family::Newton { coeffs } => {
                        ui.label("Polynomial");
                        let r = ui.text_edit_singleline(&mut self.poly_text).on_hover_text(
                            "coefficients, highest degree first: 1 0 0 -1 is z³ − 1",
                        );
                        if r.lost_focus() {
                            match escape_view::parse_poly(&self.poly_text) {
                                Some(p) => *coeffs = p,
                                None => {
                                    self.status =
                                        "polynomial: give 2–33 numbers, highest degree first".into()
                                }
                            }
                        }
                        ui.end_row();
                    }
                    Family::Logistic { z0, kose } => {
                        cpx(ui, "z₀", z0);
                        ui.label("Köse λz(z − 1)");
                        ui.checkbox(kose, "");
                        ui.end_row();
                    }
                    Family::Cubic { p } => cpx(ui, "p", p),
                    Family::WarpedJulia(w) => {
                        let (mut c, mut alpha, mut lambda, mut polar) = (
                            w.c,
                            w.alpha,
                            w.lambda,
                            matches!(w.sampling, Sampling::Polar { .. }),
                        );
                        cpx(ui, "c", &mut c);
                        cpx(ui, "warp α", &mut alpha);
                        ui.label("Turbulence λ");
                        ui.add(egui::Slider::new(&mut lambda, 0.0..=1.0));
                        ui.end_row();
                        ui.label("Polar (seamless)");
                        ui.checkbox(&mut polar, "");
                        ui.end_row();
                        ui.label("Presets");
                        ui.horizontal(|ui| {
                            for (l, p) in [
                                ("Polar", Preset::PolarJulia),
                                ("Warped", Preset::WarpedJulia),
                                ("Galaxy", Preset::Galaxy),
                            ] {
                                if ui.small_button(l).clicked() {
                                    let pw = Warp::preset(p);
                                    (c, alpha, lambda, polar) = (pw.c, pw.alpha, pw.lambda, true);
                                }
                            }
                        });
                        ui.end_row();
                        let sampling = if polar {
                            Sampling::Polar { radius: 1.0 }
                        } else {
                            Sampling::Rect { scale: 3.0 }
                        };
                        if (c, alpha, lambda, sampling) != (w.c, w.alpha, w.lambda, w.sampling) {
                            match Warp::new(c, alpha, lambda, w.fbm, sampling, w.zero_mean) {
                                Ok(n) => *w = n,
                                Err(e) => self.status = e.to_string(),
                            }
                        }
                    }
                }
                ui.label("Max iterations");
                ui.add(
                    egui::DragValue::new(&mut doc.params.max_iter)
                        .range(1..=1_000_000)
                        .speed(10.0),
                );
                ui.end_row();
                ui.label("Colouring");
                egui::ComboBox::from_id_salt("escape-coloring")
                    .selected_text(doc.params.coloring.name())
                    .show_ui(ui, |ui| {
                        for c in Coloring::ALL {
                            ui.selectable_value(&mut doc.params.coloring, c, c.name());
                        }
                    });
                ui.end_row();
                ui.label("Gradient");
                egui::ComboBox::from_id_salt("escape-gradient")
                    .selected_text(doc.gradient_source.clone())
                    .show_ui(ui, |ui| {
                        for g in gradient::builtin() {
                            if ui
                                .selectable_label(doc.gradient_source == g.name, &g.name)
                                .clicked()
                            {
                                doc.gradient_source = g.name.clone();
                                doc.params.palette.gradient = g;
                            }
                        }
                    });
                ui.end_row();
                ui.label("Offset");
                ui.add(egui::Slider::new(&mut doc.params.palette.offset, 0.0..=1.0));
                ui.end_row();
                ui.label("Repeat");
                ui.add(
                    egui::DragValue::new(&mut doc.params.palette.repeat)
                        .range(0.01..=256.0)
                        .speed(0.05),
                );
                ui.end_row();
                ui.label("Block guessing");
                let mut guess = doc.params.fill == Fill::Guess;
                ui.checkbox(&mut guess, "")
                    .on_hover_text("Mariani–Silver: faster, may miss thin filaments");
                doc.params.fill = if guess { Fill::Guess } else { Fill::Exact };
                ui.end_row();
            });
        if doc != self.doc {
            // Parameter edits are history steps too; a slider drag is one step.
            if !self.editing {
                self.push_history();
            }
            self.editing = ui.ctx().input(|i| i.pointer.any_down());
            self.doc = doc;
        } else if !ui.ctx().input(|i| i.pointer.any_down()) {
            self.editing = false;
        }
        let _ = before;
        ui.separator();
        ui.horizontal(|ui| {
            ui.label("Export size");
            ui.add(egui::DragValue::new(&mut self.export_size[0]).range(16..=20000));
            ui.label("×");
            ui.add(egui::DragValue::new(&mut self.export_size[1]).range(16..=20000));
        });
        ui.horizontal(|ui| {
            if ui.button("Export image…").clicked() {
                req = Some(EscapeRequest::Export);
            }
            if ui.button("Open view…").clicked() {
                req = Some(EscapeRequest::OpenView);
            }
            if ui.button("Save view…").clicked() {
                req = Some(EscapeRequest::SaveView);
            }
        });
        ui.separator();
        ui.label("Wheel: zoom at the cursor · drag: pan · right-drag: zoom to a rectangle");
        if matches!(self.doc.params.family, Family::Mandelbrot { .. }) {
            ui.label("Click: open the Julia set of the point (preview below)");
        }
        req
    }

    /// The view as an export at `export_size` (same centre and world width).
    pub fn export_doc(&self) -> EscapeDoc {
        let mut d = self.doc.clone();
        let width = d.world_width();
        d.width = self.export_size[0].max(1);
        d.height = self.export_size[1].max(1);
        d.view.half_height = width / 2.0 * d.height as f64 / d.width as f64;
        d
    }

    /// Draw the tab. Returns a request for the application.
    pub fn ui(&mut self, ui: &mut egui::Ui) -> Option<EscapeRequest> {
        let ctx = ui.ctx().clone();
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
        egui::Panel::left("escape-controls")
            .default_size(300.0)
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

    fn canvas(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        let avail = ui.available_size().max(Vec2::splat(32.0));
        let (rect, resp) = ui.allocate_exact_size(avail, Sense::click_and_drag());
        let ppp = ctx.pixels_per_point();
        let size = [
            ((rect.width() * ppp) as u32).max(16),
            ((rect.height() * ppp) as u32).max(16),
        ];
        let warped = matches!(self.doc.params.family, Family::WarpedJulia(_));
        // The document follows the panel's size, keeping the world width.
        if !warped && [self.doc.width, self.doc.height] != size {
            let width = self.doc.world_width();
            self.doc.width = size[0];
            self.doc.height = size[1];
            self.doc.view.half_height = width / 2.0 * size[1] as f64 / size[0] as f64;
        }
        let render_size = if warped {
            // Textures keep their own aspect (2:1 for a sky dome), fitted into the panel.
            let aspect = self.doc.width as f32 / self.doc.height.max(1) as f32;
            let w = (size[0] as f32).min(size[1] as f32 * aspect);
            [w.max(16.0) as u32, (w / aspect).max(16.0) as u32]
        } else {
            size
        };
        let to_px = |p: Pos2| {
            [
                ((p.x - rect.left()) * ppp) as f64,
                ((p.y - rect.top()) * ppp) as f64,
            ]
        };
        // Interaction (not for textures).
        if !warped {
            if let Some(hp) = resp.hover_pos() {
                let px = to_px(hp);
                self.hover = Some(self.doc.view.world_from_pixel(
                    px[0] - 0.5,
                    px[1] - 0.5,
                    self.doc.width,
                    self.doc.height,
                ));
                let scroll = ctx.input(|i| i.smooth_scroll_delta.y);
                if scroll != 0.0 {
                    let factor = (scroll as f64 * 0.004).exp();
                    self.zoom_at([px[0] + 0.5, px[1] + 0.5], factor);
                }
            } else if self.pan_start.is_none() {
                self.hover = None;
            }
            if resp.drag_started_by(egui::PointerButton::Primary) {
                self.push_history();
                self.pan_start = Some(self.doc.view);
            }
            if resp.dragged_by(egui::PointerButton::Primary)
                && let (Some(v0), Some(origin), Some(now)) = (
                    self.pan_start,
                    ctx.input(|i| i.pointer.press_origin()),
                    resp.interact_pointer_pos(),
                )
            {
                let d = (now - origin) * ppp;
                let px = self.doc.view.pixel_size(self.doc.height);
                self.doc.view = v0.shifted(-d.x as f64 * px, d.y as f64 * px);
            }
            if resp.drag_stopped_by(egui::PointerButton::Primary) {
                self.pan_start = None;
            }
            if resp.drag_started_by(egui::PointerButton::Secondary) {
                self.rect_start = ctx.input(|i| i.pointer.press_origin());
            }
            if resp.drag_stopped_by(egui::PointerButton::Secondary)
                && let (Some(a), Some(b)) = (self.rect_start.take(), resp.interact_pointer_pos())
            {
                let r = Rect::from_two_pos(a, b);
                if r.width() > 4.0 && r.height() > 4.0 {
                    let c = to_px(r.center());
                    let o = self.doc.view.offset_from_pixel(
                        c[0] - 0.5,
                        c[1] - 0.5,
                        self.doc.width,
                        self.doc.height,
                    );
                    let factor = (rect.width() / r.width()).min(rect.height() / r.height()) as f64;
                    let v = View {
                        half_height: self.doc.view.half_height / factor,
                        ..self.doc.view.shifted(o.re, o.im)
                    };
                    match crate::escape::render::check_view_for(
                        &self.doc.params.family,
                        &v,
                        self.doc.width,
                        self.doc.height,
                    ) {
                        Ok(()) => {
                            self.push_history();
                            self.doc.view = v;
                        }
                        Err(e) => self.status = e.to_string(),
                    }
                }
            }
            if resp.clicked()
                && matches!(self.doc.params.family, Family::Mandelbrot { .. })
                && let Some(c) = self.hover
            {
                self.open_julia(c);
            }
        }
        // Render and draw.
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(12));
        if let Some(d) = &mut self.main {
            d.request(&self.doc.params, self.doc.view, render_size);
            d.poll(&ctx, "escape-main");
            if let Some(t) = &d.texture {
                let img_rect = match (d.shown_view, warped) {
                    // Until the new frame arrives, draw the old one where its view now lies.
                    (Some(v), false) if v != self.doc.view => {
                        let corner =
                            |i: f64, j: f64| self.doc.view.pixel_of(&v, i, j, size[0], size[1]);
                        let a = corner(-0.5, -0.5);
                        let b = corner(size[0] as f64 - 0.5, size[1] as f64 - 0.5);
                        Rect::from_min_max(
                            rect.min + Vec2::new(a[0] as f32, a[1] as f32) / ppp,
                            rect.min + Vec2::new(b[0] as f32, b[1] as f32) / ppp,
                        )
                    }
                    _ => Rect::from_min_size(
                        rect.min,
                        Vec2::new(render_size[0] as f32, render_size[1] as f32) / ppp,
                    ),
                };
                painter.image(
                    t.id(),
                    img_rect,
                    Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                    Color32::WHITE,
                );
            }
            if let Some(e) = &d.error {
                painter.text(
                    rect.center(),
                    egui::Align2::CENTER_CENTER,
                    e,
                    egui::FontId::proportional(14.0),
                    Color32::from_rgb(240, 140, 100),
                );
            }
        }
        if let (Some(a), Some(b)) = (self.rect_start, resp.interact_pointer_pos())
            && resp.dragged_by(egui::PointerButton::Secondary)
        {
            painter.rect_stroke(
                Rect::from_two_pos(a, b),
                0.0,
                Stroke::new(1.0, Color32::WHITE),
                egui::StrokeKind::Middle,
            );
        }
    }

    /// Status-bar text: coordinates, view width, render progress.
    pub fn status_text(&self) -> String {
        let deep = crate::escape::render::is_deep(
            &self.doc.params.family,
            &self.doc.view,
            self.doc.height,
        );
        let mut s = if deep {
            // Pointer coordinates in f64 would all look alike here: show the exact centre.
            let [x, y] = self.doc.view.center_dd();
            format!("deep zoom, centre {x}, {y}")
        } else {
            match self.hover {
                Some(c) => format!("{:.10} {:+.10}i", c.re, c.im),
                None => "—".into(),
            }
        };
        s += &format!("   width {:.3e}", self.doc.world_width());
        if let Some(d) = &self.main {
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
