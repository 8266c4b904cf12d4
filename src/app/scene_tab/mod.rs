//! The scene tab: a textured Bézier scene rendered in the background; drag to orbit, wheel to
//! zoom, right-drag to pan, Ctrl+drag to move the selected light; texture source per object
//! (the scene's own, the current flame, the current escape-time view, procedural, an image);
//! materials, lights, projection; open scene files and export.

pub(crate) mod canvas;
pub(crate) mod controls;
pub(crate) mod save;
pub(crate) mod textures;

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use eframe::egui::{self, Vec2};
use glam::DVec3;

use crate::app::notice::Notices;
use crate::app::worker::{JobContext, Repaint, TaskWorker, Worker, repaint_of, task_worker};
use crate::escape::EscapeDoc;
use crate::flame::Flame;
use crate::io;
use crate::surface::{Object, Scene, Texture};

/// A scene to render.
pub struct SceneJob {
    scene: Scene,
    generation: u64,
}

/// A rendered scene.
pub struct SceneFrame {
    generation: u64,
    image: egui::ColorImage,
    ms: f64,
}

fn render(job: SceneJob, cx: &JobContext<SceneFrame>) {
    let t = Instant::now();
    if let Some(img) = crate::surface::render(&job.scene, Some(cx.cancel_flag())) {
        let image =
            egui::ColorImage::from_rgb([img.width() as usize, img.height() as usize], img.as_raw());
        cx.send(SceneFrame {
            generation: job.generation,
            image,
            ms: t.elapsed().as_secs_f64() * 1000.0,
        });
    }
}

/// What the tab asks the application to do (file dialogs live in the app).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneRequest {
    OpenScene,
    SaveScene,
    Export,
    TextureImage,
}

/// Where an object's texture comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureSource {
    /// One of the scene file's textures.
    Scene(usize),
    /// The flame tab's current flame, rendered.
    CurrentFlame,
    /// The escape-time tab's view, rendered.
    CurrentEscape,
    /// fBm noise with the default settings.
    Fbm,
    /// A Markov random field with the default settings.
    Mrf,
    /// A checkerboard.
    Checker,
    /// No texture: the material colour.
    None,
}

/// The default scene: the reference jug wearing an fBm texture (no files needed), with the
/// scene file it comes from.
pub fn default_scene() -> (Scene, Vec<String>, toml::Table) {
    let l = io::scene::parse(save::DEFAULT_SCENE, "default scene", Path::new("."))
        .expect("the default scene parses");
    let t = save::DEFAULT_SCENE
        .parse::<toml::Table>()
        .expect("the default scene parses");
    (l.scene, l.texture_names, t)
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
    pub notices: Notices,
    render: bool,
    worker: Option<Worker<SceneJob, SceneFrame>>,
    texture: Option<egui::TextureHandle>,
    generation: u64,
    submitted: Option<(u64, [u32; 2], bool)>,
    /// A change counter for the scene (cheaper than comparing scenes).
    version: u64,
    last_ms: f64,
    texture_job: Option<TaskWorker<TextureResult>>,
    export_job: Option<TaskWorker<Result<PathBuf, String>>>,
    repaint: Repaint,
    /// The scene file as read (or the default scene's), written over when saving.
    source: toml::Table,
    /// The folder its relative file names are relative to.
    base_dir: Option<PathBuf>,
    /// Where the textures made in the tab came from, by texture name.
    origins: HashMap<String, save::Origin>,
}

impl SceneTab {
    /// A new tab; with `ctx` the background renderer starts (none in tests).
    pub fn new(ctx: Option<&egui::Context>) -> SceneTab {
        let render = ctx.is_some();
        let (scene, texture_names, source) = default_scene();
        SceneTab {
            scene,
            texture_names,
            path: None,
            selected_object: 0,
            selected_light: 0,
            export_size: [1280, 960],
            notices: Notices::default(),
            render,
            worker: None,
            texture: None,
            generation: 0,
            submitted: None,
            version: 1,
            last_ms: 0.0,
            texture_job: None,
            export_job: None,
            repaint: repaint_of(ctx),
            source,
            base_dir: None,
            origins: HashMap::new(),
        }
    }

    /// Replace the scene (after opening a file) and the file it came from.
    pub fn load(
        &mut self,
        scene: Scene,
        names: Vec<String>,
        path: Option<PathBuf>,
        source: toml::Table,
    ) {
        self.scene = scene;
        self.texture_names = names;
        self.base_dir = path
            .as_ref()
            .and_then(|p| p.parent().map(Path::to_path_buf));
        self.path = path;
        self.source = source;
        self.origins.clear();
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
    /// File › New: the default scene.
    pub fn new_scene(&mut self) {
        let (scene, names, source) = default_scene();
        self.load(scene, names, None, source);
        self.notices.status("New scene");
    }

    /// Open a scene file; true when it opened.
    pub fn open(&mut self, path: &Path) -> bool {
        let source = std::fs::read_to_string(path)
            .ok()
            .and_then(|t| t.parse::<toml::Table>().ok());
        match (io::scene::read(path), source) {
            (Ok(l), Some(source)) => {
                self.load(l.scene, l.texture_names, Some(path.to_path_buf()), source);
                self.notices.status(format!("Opened {}", path.display()));
                true
            }
            (Err(e), _) => {
                self.notices.message("Cannot open", e.to_string());
                false
            }
            (Ok(_), None) => {
                self.notices.message(
                    "Cannot open",
                    format!("{}: cannot be read again", path.display()),
                );
                false
            }
        }
    }

    /// Render the scene at the export size into a PNG or BMP, in the background.
    pub fn export(&mut self, out: PathBuf) {
        let scene = self.export_scene();
        let r = self.repaint.clone();
        let w = task_worker("ugnis-scene-export", move || r());
        self.notices.status(format!("Exporting {}…", out.display()));
        w.submit(Box::new(move |cancel, _| {
            let img = crate::surface::render(&scene, Some(cancel)).ok_or("cancelled")?;
            let img = image::DynamicImage::ImageRgb8(img);
            let res = if io::kind_of(&out) == io::FileKind::Bmp {
                io::bmp::save(&out, &img)
            } else {
                io::png::save(&out, &img, &Default::default())
            };
            res.map_err(|e| format!("{}: {e}", out.display()))?;
            Ok(out)
        }));
        self.export_job = Some(w);
    }

    /// Collect finished textures and exports.
    fn poll_jobs(&mut self) {
        if let Some(r) = self.texture_job.as_ref().and_then(|w| w.poll().pop()) {
            self.texture_job = None;
            match r {
                Ok((slot, t, name)) => self.install_texture(slot, t, name),
                Err(e) => self.notices.status(format!("Cannot make the texture: {e}")),
            }
        }
        if let Some(r) = self.export_job.as_ref().and_then(|w| w.poll().pop()) {
            self.export_job = None;
            match r {
                Ok(p) => self.notices.status(format!("Exported {}", p.display())),
                Err(e) => self.notices.message("Export failed", e),
            }
        }
    }

    /// The scene at an export size (same framing).
    pub fn export_scene(&self) -> Scene {
        let mut s = self.scene.clone();
        s.width = self.export_size[0].max(1);
        s.height = self.export_size[1].max(1);
        s.supersample = s.supersample.max(2);
        s
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
            self.worker = Some(Worker::new(
                "ugnis-scene",
                move || c.request_repaint(),
                render,
            ));
        }
        self.poll_jobs();
        let mut req = None;
        let width = ui.available_width();
        egui::Panel::left("scene-controls")
            .default_size(320.0f32.min(width * 0.4))
            .max_size((width * 0.45).max(160.0))
            .resizable(true)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| req = self.controls(ui, flame, escape));
            });
        egui::CentralPanel::default().show(ui, |ui| self.canvas(ui));
        req
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
