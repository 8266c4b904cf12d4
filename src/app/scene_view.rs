//! The scene tab: a textured Bézier scene rendered in the background; drag to orbit, wheel to
//! zoom, right-drag to pan, Ctrl+drag to move the selected light; texture source per object
//! (the scene's own, the current flame, the current escape-time view, procedural, an image);
//! materials, lights, projection; open scene files and export.

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread::JoinHandle;
use std::time::Instant;

use eframe::egui::{self, Color32, Pos2, Rect, Sense, Stroke, Vec2};
use glam::{DVec3, Vec3};

use crate::escape::Family;
use crate::flame::Flame;
use crate::io::escape_view::EscapeDoc;
use crate::noise::Fbm;
use crate::surface::texture::{self, MrfParams, Texture};
use crate::surface::{Geometry, Light, Material, Object, Projection, Scene, Transform, mesh};

struct Job {
    scene: Scene,
    generation: u64,
}

struct Frame {
    generation: u64,
    image: egui::ColorImage,
    ms: f64,
}

/// Background scene renderer: the newest job wins.
struct SceneWorker {
    tx: Sender<Option<Job>>,
    rx: Receiver<Frame>,
    cancel: Arc<AtomicBool>,
    handle: Option<JoinHandle<()>>,
}

impl SceneWorker {
    fn new(repaint: impl Fn() + Send + 'static) -> SceneWorker {
        let (tx, jobs) = mpsc::channel::<Option<Job>>();
        let (out, rx) = mpsc::channel();
        let cancel = Arc::new(AtomicBool::new(false));
        let c = cancel.clone();
        let handle = std::thread::Builder::new()
            .name("ugnis-scene".into())
            .spawn(move || {
                while let Ok(Some(mut job)) = jobs.recv() {
                    while let Ok(m) = jobs.try_recv() {
                        match m {
                            Some(j) => job = j,
                            None => return,
                        }
                    }
                    c.store(false, Ordering::SeqCst);
                    let t = Instant::now();
                    if let Some(img) = crate::surface::render(&job.scene, Some(&c)) {
                        let image = egui::ColorImage::from_rgb(
                            [img.width() as usize, img.height() as usize],
                            img.as_raw(),
                        );
                        let ms = t.elapsed().as_secs_f64() * 1000.0;
                        if out
                            .send(Frame {
                                generation: job.generation,
                                image,
                                ms,
                            })
                            .is_err()
                        {
                            return;
                        }
                        repaint();
                    }
                }
            })
            .expect("spawn scene thread");
        SceneWorker {
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
}

impl Drop for SceneWorker {
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
pub enum SceneRequest {
    OpenScene,
    Export,
    TextureImage,
}

/// Where an object's texture comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureSource {
    /// One of the scene file's textures.
    Scene(usize),
    CurrentFlame,
    CurrentEscape,
    Fbm,
    Mrf,
    Checker,
    None,
}

/// The default scene: the reference jug wearing an fBm texture (no files needed).
pub fn default_scene() -> (Scene, Vec<String>) {
    let mut s = Scene::default();
    s.textures.push(texture::fbm_texture(
        512,
        256,
        Fbm::default(),
        Vec3::new(0.35, 0.12, 0.05),
        Vec3::new(0.95, 0.75, 0.45),
    ));
    s.objects.push(Object {
        name: "jug".into(),
        geometry: Geometry::Patches(mesh::jug()),
        transform: Transform::IDENTITY,
        material: Material::default(),
        texture: Some(0),
        bump_texture: None,
    });
    (s, vec!["fbm".into()])
}

/// A texture made in the background: (object, texture, name) or an error.
type TextureResult = Result<(usize, Texture, String), String>;

/// State of the scene tab.
pub struct SceneTab {
    pub scene: Scene,
    pub texture_names: Vec<String>,
    pub path: Option<PathBuf>,
    pub selected_object: usize,
    pub selected_light: usize,
    pub export_size: [u32; 2],
    pub status: String,
    render: bool,
    worker: Option<SceneWorker>,
    texture: Option<egui::TextureHandle>,
    generation: u64,
    submitted: Option<(u64, [u32; 2], bool)>,
    /// A change counter for the scene (cheaper than comparing scenes).
    version: u64,
    last_ms: f64,
    texture_job: Option<Receiver<TextureResult>>,
}

impl SceneTab {
    pub fn new(render: bool) -> SceneTab {
        let (scene, texture_names) = default_scene();
        SceneTab {
            scene,
            texture_names,
            path: None,
            selected_object: 0,
            selected_light: 0,
            export_size: [1280, 960],
            status: String::new(),
            render,
            worker: None,
            texture: None,
            generation: 0,
            submitted: None,
            version: 1,
            last_ms: 0.0,
            texture_job: None,
        }
    }

    /// Replace the scene (after opening a file).
    pub fn load(&mut self, scene: Scene, names: Vec<String>, path: Option<PathBuf>) {
        self.scene = scene;
        self.texture_names = names;
        self.path = path;
        self.selected_object = 0;
        self.selected_light = 0;
        self.version += 1;
    }

    /// Orbit the camera by mouse motion (degrees per pixel 0.3).
    pub fn orbit(&mut self, d: Vec2) {
        let c = &mut self.scene.camera;
        c.azimuth_deg -= d.x as f64 * 0.3;
        c.polar_deg = (c.polar_deg - d.y as f64 * 0.3).clamp(1.0, 179.0);
        self.version += 1;
    }

    /// Pan the target in the view plane by a screen motion in pixels.
    pub fn pan(&mut self, d: Vec2, pixels_per_unit: f64) {
        let v = self.scene.camera.view();
        // View axes in world space are the columns of V's linear block.
        let x = DVec3::new(v.0[0][0], v.0[1][0], v.0[2][0]);
        let y = DVec3::new(v.0[0][1], v.0[1][1], v.0[2][1]);
        self.scene.camera.target -= (x * d.x as f64 - y * d.y as f64) / pixels_per_unit;
        self.version += 1;
    }

    /// Move the selected light in the view plane by a screen motion in pixels.
    pub fn move_light(&mut self, d: Vec2, pixels_per_unit: f64) {
        let v = self.scene.camera.view();
        let x = DVec3::new(v.0[0][0], v.0[1][0], v.0[2][0]);
        let y = DVec3::new(v.0[0][1], v.0[1][1], v.0[2][1]);
        if let Some(l) = self.scene.lights.get_mut(self.selected_light) {
            l.position += (x * d.x as f64 - y * d.y as f64) / pixels_per_unit;
            self.version += 1;
        }
    }

    fn source_of(&self, o: &Object) -> TextureSource {
        match o.texture {
            None => TextureSource::None,
            Some(i) => match self.texture_names.get(i).map(String::as_str) {
                Some("(current flame)") => TextureSource::CurrentFlame,
                Some("(current escape view)") => TextureSource::CurrentEscape,
                Some("(fbm)") => TextureSource::Fbm,
                Some("(mrf)") => TextureSource::Mrf,
                Some("(checker)") => TextureSource::Checker,
                _ => TextureSource::Scene(i),
            },
        }
    }

    /// Use a texture (made in the background for flames and escape views) on the selected
    /// object.
    pub fn set_source(&mut self, src: TextureSource, flame: &Flame, escape: &EscapeDoc) {
        let slot = self.selected_object;
        let (tx, rx) = mpsc::channel();
        let name = |n: &str| n.to_string();
        match src {
            TextureSource::Scene(i) => {
                if let Some(o) = self.scene.objects.get_mut(slot) {
                    o.texture = Some(i);
                    self.version += 1;
                }
                return;
            }
            TextureSource::None => {
                if let Some(o) = self.scene.objects.get_mut(slot) {
                    o.texture = None;
                    self.version += 1;
                }
                return;
            }
            TextureSource::CurrentFlame => {
                let mut f = flame.clone();
                std::thread::spawn(move || {
                    f.resize_keep_framing(512, 384);
                    f.quality = f.quality.min(40.0);
                    let r = crate::flame::render(
                        &f,
                        &crate::flame::RenderOptions {
                            threads: 2,
                            ..Default::default()
                        },
                    )
                    .map(|img| {
                        (
                            slot,
                            Texture::from_image(&img.to_rgb8()),
                            name("(current flame)"),
                        )
                    })
                    .map_err(|e| e.to_string());
                    let _ = tx.send(r);
                });
            }
            TextureSource::CurrentEscape => {
                let d = escape.clone();
                std::thread::spawn(move || {
                    let (w, h) = (1024u32, 512u32);
                    let mut view = d.view;
                    if !matches!(d.params.family, Family::WarpedJulia(_)) {
                        view.half_height = d.world_width() / 2.0 * h as f64 / w as f64;
                    }
                    let r = crate::escape::render(&d.params, view, w, h)
                        .map(|(img, _)| {
                            (
                                slot,
                                Texture::from_image(&img),
                                name("(current escape view)"),
                            )
                        })
                        .map_err(|e| e.to_string());
                    let _ = tx.send(r);
                });
            }
            TextureSource::Fbm | TextureSource::Mrf | TextureSource::Checker => {
                std::thread::spawn(move || {
                    let (a, b) = (Vec3::new(0.2, 0.15, 0.1), Vec3::new(0.9, 0.85, 0.7));
                    let (t, n) = match src {
                        TextureSource::Fbm => (
                            texture::fbm_texture(512, 256, Fbm::default(), a, b),
                            "(fbm)",
                        ),
                        TextureSource::Mrf => (
                            texture::mrf_texture(256, 256, &MrfParams::default(), a, b),
                            "(mrf)",
                        ),
                        _ => (
                            texture::checker(256, 256, 16, 8, Vec3::new(0.8, 0.25, 0.2), b),
                            "(checker)",
                        ),
                    };
                    let _ = tx.send(Ok((slot, t, name(n))));
                });
            }
        }
        self.texture_job = Some(rx);
        self.status = "Making the texture…".into();
    }

    /// Use an image file as the selected object's texture.
    pub fn set_image_texture(&mut self, path: &std::path::Path) {
        match image::open(path) {
            Ok(img) => {
                let n = path
                    .file_name()
                    .map_or("image".into(), |s| s.to_string_lossy().into_owned());
                self.install_texture(self.selected_object, Texture::from_image(&img.to_rgb8()), n);
            }
            Err(e) => self.status = format!("{}: {e}", path.display()),
        }
    }

    fn install_texture(&mut self, slot: usize, t: Texture, name: String) {
        let i = match self
            .texture_names
            .iter()
            .position(|n| *n == name && name.starts_with('('))
        {
            Some(i) => {
                self.scene.textures[i] = t;
                i
            }
            None => {
                self.scene.textures.push(t);
                self.texture_names.push(name);
                self.scene.textures.len() - 1
            }
        };
        if let Some(o) = self.scene.objects.get_mut(slot) {
            o.texture = Some(i);
        }
        self.version += 1;
        self.status = "Texture ready".into();
    }

    /// The scene at an export size (same framing).
    pub fn export_scene(&self) -> Scene {
        let mut s = self.scene.clone();
        s.width = self.export_size[0].max(1);
        s.height = self.export_size[1].max(1);
        s.supersample = s.supersample.max(2);
        s
    }

    fn controls(
        &mut self,
        ui: &mut egui::Ui,
        flame: &Flame,
        escape: &EscapeDoc,
    ) -> Option<SceneRequest> {
        let mut req = None;
        ui.horizontal(|ui| {
            if ui.button("Open scene…").clicked() {
                req = Some(SceneRequest::OpenScene);
            }
            if ui.button("Export image…").clicked() {
                req = Some(SceneRequest::Export);
            }
        });
        ui.horizontal(|ui| {
            ui.label("Export size");
            ui.add(egui::DragValue::new(&mut self.export_size[0]).range(16..=16384));
            ui.label("×");
            ui.add(egui::DragValue::new(&mut self.export_size[1]).range(16..=16384));
        });
        ui.separator();
        let before = (
            self.scene.camera,
            self.scene.lights.clone(),
            self.scene.supersample,
        );
        egui::CollapsingHeader::new("Objects")
            .default_open(true)
            .show(ui, |ui| {
                for (i, o) in self.scene.objects.iter().enumerate() {
                    if ui
                        .selectable_label(i == self.selected_object, &o.name)
                        .clicked()
                    {
                        self.selected_object = i;
                    }
                }
                let Some(o) = self.scene.objects.get(self.selected_object) else {
                    return;
                };
                let current = self.source_of(o);
                let label = |s: TextureSource, names: &[String]| match s {
                    TextureSource::Scene(i) => names.get(i).cloned().unwrap_or_default(),
                    TextureSource::CurrentFlame => "current flame".into(),
                    TextureSource::CurrentEscape => "current escape-time view".into(),
                    TextureSource::Fbm => "fBm noise".into(),
                    TextureSource::Mrf => "Markov random field".into(),
                    TextureSource::Checker => "checker".into(),
                    TextureSource::None => "none".into(),
                };
                let mut chosen = None;
                let mut image = false;
                egui::ComboBox::from_label("Texture")
                    .selected_text(label(current, &self.texture_names))
                    .show_ui(ui, |ui| {
                        let scene_ones: Vec<TextureSource> = (0..self.texture_names.len())
                            .filter(|i| !self.texture_names[*i].starts_with('('))
                            .map(TextureSource::Scene)
                            .collect();
                        for s in scene_ones.into_iter().chain([
                            TextureSource::CurrentFlame,
                            TextureSource::CurrentEscape,
                            TextureSource::Fbm,
                            TextureSource::Mrf,
                            TextureSource::Checker,
                            TextureSource::None,
                        ]) {
                            if ui
                                .selectable_label(s == current, label(s, &self.texture_names))
                                .clicked()
                            {
                                chosen = Some(s);
                            }
                        }
                        if ui.selectable_label(false, "image file…").clicked() {
                            image = true;
                        }
                    });
                if let Some(s) = chosen {
                    self.set_source(s, flame, escape);
                }
                if image {
                    req = Some(SceneRequest::TextureImage);
                }
                if let Some(o) = self.scene.objects.get_mut(self.selected_object) {
                    let m = o.material;
                    egui::Grid::new("material").num_columns(2).show(ui, |ui| {
                        let row =
                            |ui: &mut egui::Ui,
                             l: &str,
                             v: &mut f64,
                             r: std::ops::RangeInclusive<f64>| {
                                ui.label(l);
                                ui.add(egui::Slider::new(v, r));
                                ui.end_row();
                            };
                        row(ui, "Ambient K_a", &mut o.material.ka, 0.0..=1.0);
                        row(ui, "Diffuse K_d", &mut o.material.kd, 0.0..=1.0);
                        row(ui, "Specular k_s", &mut o.material.ks, 0.0..=1.0);
                        row(ui, "Shininess n", &mut o.material.shininess, 1.0..=200.0);
                        row(ui, "Bumps", &mut o.material.bump, 0.0..=0.05);
                    });
                    if o.material != m {
                        self.version += 1;
                    }
                }
            });
        egui::CollapsingHeader::new("Lights")
            .default_open(true)
            .show(ui, |ui| {
                for i in 0..self.scene.lights.len() {
                    ui.horizontal(|ui| {
                        if ui
                            .selectable_label(i == self.selected_light, format!("light {}", i + 1))
                            .clicked()
                        {
                            self.selected_light = i;
                        }
                        let l = &mut self.scene.lights[i];
                        for k in 0..3 {
                            ui.add(
                                egui::DragValue::new(&mut l.position[k])
                                    .speed(0.05)
                                    .max_decimals(2),
                            );
                        }
                        let mut g = l.intensity.x;
                        if ui
                            .add(egui::DragValue::new(&mut g).speed(0.1).range(0.0..=100.0))
                            .changed()
                        {
                            l.intensity = Vec3::splat(g);
                        }
                    });
                }
                ui.horizontal(|ui| {
                    if ui.button("Add light").clicked() {
                        self.scene.lights.push(Light {
                            position: self.scene.camera.eye() + DVec3::new(2.0, 3.0, 0.0),
                            intensity: Vec3::splat(4.0),
                        });
                    }
                    if ui
                        .add_enabled(self.scene.lights.len() > 1, egui::Button::new("Remove"))
                        .clicked()
                    {
                        self.scene
                            .lights
                            .remove(self.selected_light.min(self.scene.lights.len() - 1));
                        self.selected_light = 0;
                    }
                });
                ui.label("Ctrl+drag on the picture moves the selected light.");
            });
        egui::CollapsingHeader::new("Camera")
            .default_open(true)
            .show(ui, |ui| {
                let c = &mut self.scene.camera;
                egui::Grid::new("camera").num_columns(2).show(ui, |ui| {
                    ui.label("Projection");
                    let names = [
                        "perspective",
                        "orthographic",
                        "isometric",
                        "dimetric",
                        "stereo pair",
                    ];
                    let cur = match c.projection {
                        Projection::Perspective => 0,
                        Projection::Orthographic => 1,
                        Projection::Axonometric { phi, .. }
                            if (phi - std::f64::consts::FRAC_PI_4).abs() < 1e-9 =>
                        {
                            2
                        }
                        Projection::Axonometric { .. } => 3,
                        Projection::Stereo => 4,
                    };
                    let mut sel = cur;
                    egui::ComboBox::from_id_salt("projection")
                        .selected_text(names[cur])
                        .show_ui(ui, |ui| {
                            for (k, n) in names.iter().enumerate() {
                                ui.selectable_value(&mut sel, k, *n);
                            }
                        });
                    if sel != cur {
                        c.projection = match sel {
                            0 => Projection::Perspective,
                            1 => Projection::Orthographic,
                            2 => {
                                let (phi, theta) = crate::surface::transform::isometric_angles();
                                Projection::Axonometric { phi, theta }
                            }
                            3 => {
                                let (phi, theta) = crate::surface::transform::dimetric_angles(0.5);
                                Projection::Axonometric { phi, theta }
                            }
                            _ => Projection::Stereo,
                        };
                    }
                    ui.end_row();
                    ui.label("Distance ρ");
                    ui.add(
                        egui::DragValue::new(&mut c.distance)
                            .speed(0.05)
                            .range(0.5..=200.0),
                    );
                    ui.end_row();
                    ui.label("Azimuth θ°");
                    ui.add(egui::DragValue::new(&mut c.azimuth_deg).speed(0.5));
                    ui.end_row();
                    ui.label("Polar φ°");
                    ui.add(
                        egui::DragValue::new(&mut c.polar_deg)
                            .speed(0.5)
                            .range(1.0..=179.0),
                    );
                    ui.end_row();
                    ui.label("Scale");
                    ui.add(
                        egui::DragValue::new(&mut c.scale)
                            .speed(1.0)
                            .range(1.0..=5000.0),
                    );
                    ui.end_row();
                });
                ui.horizontal(|ui| {
                    ui.label("Supersampling");
                    ui.add(egui::DragValue::new(&mut self.scene.supersample).range(1..=4));
                });
            });
        if (
            self.scene.camera,
            self.scene.lights.clone(),
            self.scene.supersample,
        ) != before
        {
            self.version += 1;
        }
        ui.separator();
        ui.label("Drag: orbit · wheel: zoom · right-drag: pan");
        req
    }

    /// Draw the tab; `flame` and `escape` are the other views' current pictures (texture
    /// sources).
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        flame: &Flame,
        escape: &EscapeDoc,
    ) -> Option<SceneRequest> {
        let ctx = ui.ctx().clone();
        if self.render && self.worker.is_none() {
            let c = ctx.clone();
            self.worker = Some(SceneWorker::new(move || c.request_repaint()));
        }
        if let Some(rx) = &self.texture_job {
            match rx.try_recv() {
                Ok(Ok((slot, t, name))) => {
                    self.texture_job = None;
                    self.install_texture(slot, t, name);
                }
                Ok(Err(e)) => {
                    self.texture_job = None;
                    self.status = format!("Cannot make the texture: {e}");
                }
                Err(mpsc::TryRecvError::Empty) => {
                    ctx.request_repaint_after(std::time::Duration::from_millis(100))
                }
                Err(_) => self.texture_job = None,
            }
        }
        let mut req = None;
        egui::Panel::left("scene-controls")
            .default_size(320.0)
            .resizable(true)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| req = self.controls(ui, flame, escape));
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
        // Interaction.
        let px_per_unit = self.scene.camera.scale * size[1] as f64 / 480.0 / ppp as f64;
        let ctrl = ctx.input(|i| i.modifiers.command);
        let d = resp.drag_delta();
        if resp.dragged_by(egui::PointerButton::Primary) && d != Vec2::ZERO {
            if ctrl {
                self.move_light(d, px_per_unit);
            } else {
                self.orbit(d);
            }
        }
        if (resp.dragged_by(egui::PointerButton::Secondary)
            || resp.dragged_by(egui::PointerButton::Middle))
            && d != Vec2::ZERO
        {
            self.pan(d, px_per_unit);
        }
        if resp.hovered() {
            let scroll = ctx.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                self.scene.camera.scale =
                    (self.scene.camera.scale * (scroll as f64 * 0.003).exp()).clamp(1.0, 5000.0);
                self.version += 1;
            }
        }
        let dragging = resp.dragged();
        // Render: half resolution while the mouse moves the view, full when it stops.
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(12));
        if let Some(w) = &self.worker {
            let key = (self.version, size, dragging);
            if self.submitted != Some(key) {
                let mut s = self.scene.clone();
                let k = if dragging { 2 } else { 1 };
                s.width = size[0] / k;
                s.height = size[1] / k;
                if dragging {
                    s.supersample = 1;
                }
                self.generation += 1;
                w.submit(Job {
                    scene: s,
                    generation: self.generation,
                });
                self.submitted = Some(key);
            }
            for f in w.rx.try_iter().collect::<Vec<_>>() {
                if f.generation != self.generation {
                    continue;
                }
                self.last_ms = f.ms;
                match &mut self.texture {
                    Some(t) => t.set(f.image, egui::TextureOptions::LINEAR),
                    None => {
                        self.texture =
                            Some(ctx.load_texture("scene", f.image, egui::TextureOptions::LINEAR))
                    }
                }
            }
        }
        if let Some(t) = &self.texture {
            painter.image(
                t.id(),
                rect,
                Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                Color32::WHITE,
            );
        }
        // Light handles.
        let mut s = self.scene.clone();
        s.width = size[0];
        s.height = size[1];
        for (i, l) in self.scene.lights.iter().enumerate() {
            if let Some(p) = crate::surface::raster::project(&s, l.position) {
                let q = rect.min + Vec2::new(p[0] as f32, p[1] as f32) / ppp;
                if rect.contains(q) {
                    let col = if i == self.selected_light {
                        Color32::YELLOW
                    } else {
                        Color32::from_gray(200)
                    };
                    painter.circle_stroke(q, 6.0, Stroke::new(2.0, col));
                }
            }
        }
    }

    pub fn status_text(&self) -> String {
        let c = &self.scene.camera;
        format!(
            "θ {:.0}°  φ {:.0}°  ρ {:.2}  {} objects  last frame {:.0} ms",
            c.azimuth_deg,
            c.polar_deg,
            c.distance,
            self.scene.objects.len(),
            self.last_ms
        )
    }
}
