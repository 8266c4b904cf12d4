//! The scene tab's control panel: file buttons, objects and their textures and materials,
//! lights, camera and projection.

use eframe::egui;
use glam::{DVec3, Vec3};

use super::{SceneRequest, SceneTab, TextureSource};
use crate::app::a11y::named;
use crate::escape::EscapeDoc;
use crate::flame::Flame;
use crate::surface::{Geometry, Light, Material, Projection, QuaternionJulia, Renderer, SliceAxis};

impl SceneTab {
    pub(super) fn controls(
        &mut self,
        ui: &mut egui::Ui,
        flame: &Flame,
        escape: &EscapeDoc,
    ) -> Option<SceneRequest> {
        let mut req = self.file_buttons(ui);
        ui.separator();
        let before = (
            self.scene.camera,
            self.scene.lights.clone(),
            self.scene.supersample,
            self.scene.renderer,
        );
        egui::CollapsingHeader::new("Objects")
            .default_open(true)
            .show(ui, |ui| {
                if let Some(r) = self.objects_section(ui, flame, escape) {
                    req = Some(r);
                }
            });
        egui::CollapsingHeader::new("Lights")
            .default_open(true)
            .show(ui, |ui| self.lights_section(ui));
        egui::CollapsingHeader::new("Camera")
            .default_open(true)
            .show(ui, |ui| self.camera_section(ui));
        if (
            self.scene.camera,
            self.scene.lights.clone(),
            self.scene.supersample,
            self.scene.renderer,
        ) != before
        {
            self.version += 1;
        }
        ui.separator();
        ui.label("Drag: orbit · wheel: zoom · right-drag: pan");
        req
    }

    /// Open, Save and Export, and the export size.
    fn file_buttons(&mut self, ui: &mut egui::Ui) -> Option<SceneRequest> {
        let mut req = None;
        ui.horizontal_wrapped(|ui| {
            if ui
                .button("Open scene…")
                .on_hover_text("open a scene file (.toml)")
                .clicked()
            {
                req = Some(SceneRequest::OpenScene);
            }
            if ui
                .button("Save scene…")
                .on_hover_text("save the scene with its camera, lights, materials and textures")
                .clicked()
            {
                req = Some(SceneRequest::SaveScene);
            }
            if ui
                .button("Export image…")
                .on_hover_text("render the scene at the export size into a PNG or BMP")
                .clicked()
            {
                req = Some(SceneRequest::Export);
            }
        });
        ui.horizontal(|ui| {
            ui.label("Export size");
            named(
                ui.add(egui::DragValue::new(&mut self.export_size[0]).range(16..=16384)),
                "Export width",
            )
            .on_hover_text("width of the exported picture in pixels");
            ui.label("×");
            named(
                ui.add(egui::DragValue::new(&mut self.export_size[1]).range(16..=16384)),
                "Export height",
            )
            .on_hover_text("height of the exported picture in pixels");
        });
        req
    }

    /// The object list and the selected object's texture, quaternion parameters and material.
    fn objects_section(
        &mut self,
        ui: &mut egui::Ui,
        flame: &Flame,
        escape: &EscapeDoc,
    ) -> Option<SceneRequest> {
        for (i, o) in self.scene.objects.iter().enumerate() {
            if ui
                .selectable_label(i == self.selected_object, &o.name)
                .clicked()
            {
                self.selected_object = i;
            }
        }
        // Nothing more without a selected object.
        self.scene.objects.get(self.selected_object)?;
        let req = self
            .texture_choice(ui, flame, escape)
            .then_some(SceneRequest::TextureImage);
        if let Some(Geometry::QuaternionJulia(q)) = self
            .scene
            .objects
            .get_mut(self.selected_object)
            .map(|o| &mut o.geometry)
            && quaternion_controls(ui, q)
        {
            self.version += 1;
        }
        if let Some(o) = self.scene.objects.get_mut(self.selected_object)
            && material_controls(ui, &mut o.material)
        {
            self.version += 1;
        }
        req
    }

    /// The selected object's texture; true when an image file is asked for.
    fn texture_choice(&mut self, ui: &mut egui::Ui, flame: &Flame, escape: &EscapeDoc) -> bool {
        let Some(o) = self.scene.objects.get(self.selected_object) else {
            return false;
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
        let r = egui::ComboBox::from_label("Texture")
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
        r.response
            .on_hover_text("what the selected object wears: a picture mapped on it");
        if let Some(s) = chosen {
            self.set_source(s, flame, escape);
        }
        image
    }

    /// The lights: position and intensity of each, Add and Remove.
    fn lights_section(&mut self, ui: &mut egui::Ui) {
        for i in 0..self.scene.lights.len() {
            self.light_row(ui, i);
        }
        ui.horizontal(|ui| {
            if ui
                .button("Add light")
                .on_hover_text("a new light above and beside the camera")
                .clicked()
            {
                self.scene.lights.push(Light {
                    position: self.scene.camera.eye() + DVec3::new(2.0, 3.0, 0.0),
                    intensity: Vec3::splat(4.0),
                });
            }
            if ui
                .add_enabled(self.scene.lights.len() > 1, egui::Button::new("Remove"))
                .on_hover_text("remove the selected light (one stays)")
                .clicked()
            {
                self.scene
                    .lights
                    .remove(self.selected_light.min(self.scene.lights.len() - 1));
                self.selected_light = 0;
            }
        });
        ui.label("Ctrl+drag on the picture moves the selected light.");
    }

    /// Light `i`: select it, its position and its intensity.
    fn light_row(&mut self, ui: &mut egui::Ui, i: usize) {
        ui.horizontal(|ui| {
            if ui
                .selectable_label(i == self.selected_light, format!("light {}", i + 1))
                .on_hover_text("select this light (Ctrl+drag on the picture moves it)")
                .clicked()
            {
                self.selected_light = i;
            }
            let l = &mut self.scene.lights[i];
            for (k, axis) in ["x", "y", "z"].iter().enumerate() {
                named(
                    ui.add(
                        egui::DragValue::new(&mut l.position[k])
                            .speed(0.05)
                            .max_decimals(2),
                    ),
                    &format!("light {} {axis}", i + 1),
                )
                .on_hover_text(format!("{axis} of the light's position"));
            }
            let mut g = l.intensity.x;
            if named(
                ui.add(
                    egui::DragValue::new(&mut g)
                        .speed(0.1)
                        .range(0.0..=100.0)
                        .clamp_existing_to_range(false),
                ),
                &format!("light {} intensity", i + 1),
            )
            .on_hover_text("brightness of the light")
            .changed()
            {
                l.intensity = Vec3::splat(g);
            }
        });
    }

    /// The camera: projection, distance, angles and scale, supersampling and the renderer.
    fn camera_section(&mut self, ui: &mut egui::Ui) {
        let c = &mut self.scene.camera;
        egui::Grid::new("camera").num_columns(2).show(ui, |ui| {
            projection_row(ui, &mut c.projection);
            let lb = ui.label("Distance ρ");
            ui.add(
                egui::DragValue::new(&mut c.distance)
                    .speed(0.05)
                    .range(0.5..=200.0)
                    .clamp_existing_to_range(false),
            )
            .labelled_by(lb.id)
            .on_hover_text("distance of the camera from its target");
            ui.end_row();
            let lb = ui.label("Azimuth θ°");
            ui.add(egui::DragValue::new(&mut c.azimuth_deg).speed(0.5))
                .labelled_by(lb.id)
                .on_hover_text("the camera's angle around the vertical axis");
            ui.end_row();
            let lb = ui.label("Polar φ°");
            ui.add(
                egui::DragValue::new(&mut c.polar_deg)
                    .speed(0.5)
                    .range(1.0..=179.0)
                    .clamp_existing_to_range(false),
            )
            .labelled_by(lb.id)
            .on_hover_text("the camera's angle from straight above");
            ui.end_row();
            let lb = ui.label("Scale");
            ui.add(
                egui::DragValue::new(&mut c.scale)
                    .speed(1.0)
                    .range(1.0..=5000.0)
                    .clamp_existing_to_range(false),
            )
            .labelled_by(lb.id)
            .on_hover_text("magnification of the picture");
            ui.end_row();
        });
        ui.horizontal(|ui| {
            let lb = ui.label("Supersampling");
            ui.add(egui::DragValue::new(&mut self.scene.supersample).range(1..=4))
                .labelled_by(lb.id)
                .on_hover_text("samples per pixel side (smoother edges, slower)");
        });
        ui.horizontal(|ui| {
            ui.label("Renderer");
            let r = egui::ComboBox::from_id_salt("renderer")
                .selected_text(match self.scene.renderer {
                    Renderer::ZBuffer => "z-buffer",
                    Renderer::RayCast => "ray casting",
                })
                .show_ui(ui, |ui| {
                    ui.selectable_value(&mut self.scene.renderer, Renderer::ZBuffer, "z-buffer");
                    ui.selectable_value(&mut self.scene.renderer, Renderer::RayCast, "ray casting");
                });
            named(r.response, "Renderer").on_hover_text(
                "z-buffer: fast, over a tessellation; ray casting: exact surfaces and \
                 shadows",
            );
        });
    }
}

/// The projection row of the camera grid.
fn projection_row(ui: &mut egui::Ui, projection: &mut Projection) {
    ui.label("Projection");
    let names = [
        "perspective",
        "orthographic",
        "isometric",
        "dimetric",
        "stereo pair",
    ];
    let cur = match *projection {
        Projection::Perspective => 0,
        Projection::Orthographic => 1,
        Projection::Axonometric { phi, .. } if (phi - std::f64::consts::FRAC_PI_4).abs() < 1e-9 => {
            2
        }
        Projection::Axonometric { .. } => 3,
        Projection::Stereo => 4,
    };
    let mut sel = cur;
    let r = egui::ComboBox::from_id_salt("projection")
        .selected_text(names[cur])
        .show_ui(ui, |ui| {
            for (k, n) in names.iter().enumerate() {
                ui.selectable_value(&mut sel, k, *n);
            }
        });
    named(r.response, "Projection").on_hover_text("how the 3-D scene is drawn on the flat picture");
    if sel != cur {
        *projection = match sel {
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
}

/// The material of an object: the Phong coefficients and the bump depth. Returns whether any
/// changed.
fn material_controls(ui: &mut egui::Ui, m: &mut Material) -> bool {
    let before = *m;
    egui::Grid::new("material").num_columns(2).show(ui, |ui| {
        material_row(
            ui,
            "Ambient K_a",
            "light everywhere, without direction",
            &mut m.ka,
            0.0..=1.0,
        );
        material_row(
            ui,
            "Diffuse K_d",
            "matte light from the lamps",
            &mut m.kd,
            0.0..=1.0,
        );
        material_row(
            ui,
            "Specular k_s",
            "shine of the highlights",
            &mut m.ks,
            0.0..=1.0,
        );
        material_row(
            ui,
            "Shininess n",
            "how small and sharp the highlights are",
            &mut m.shininess,
            1.0..=200.0,
        );
        material_row(
            ui,
            "Bumps",
            "depth of the bumps the texture makes",
            &mut m.bump,
            0.0..=0.05,
        );
    });
    *m != before
}

/// One row of the material grid: a slider and the number beside it.
fn material_row(
    ui: &mut egui::Ui,
    label: &str,
    tip: &str,
    v: &mut f64,
    range: std::ops::RangeInclusive<f64>,
) {
    let lb = ui.label(label);
    ui.horizontal(|ui| {
        ui.add(
            egui::Slider::new(v, range.clone())
                .show_value(false)
                .clamping(egui::SliderClamping::Edits),
        )
        .labelled_by(lb.id)
        .on_hover_text(tip);
        ui.add(
            egui::DragValue::new(v)
                .range(range)
                .clamp_existing_to_range(false)
                .speed(0.01),
        )
        .labelled_by(lb.id)
        .on_hover_text(tip);
    });
    ui.end_row();
}

/// The parameters of a quaternion Julia object: c, the slice and the iterations. Returns
/// whether any changed.
fn quaternion_controls(ui: &mut egui::Ui, q: &mut QuaternionJulia) -> bool {
    let before = *q;
    ui.label("Quaternion Julia set");
    egui::Grid::new("quaternion").num_columns(2).show(ui, |ui| {
        for (k, name) in ["c (real)", "c (i)", "c (j)", "c (k)"].iter().enumerate() {
            let lb = ui.label(*name);
            ui.add(
                egui::DragValue::new(&mut q.c[k])
                    .speed(0.005)
                    .range(-2.0..=2.0)
                    .clamp_existing_to_range(false),
            )
            .labelled_by(lb.id)
            .on_hover_text("the constant of z ← z² + c, one quaternion component");
            ui.end_row();
        }
        ui.label("Slice");
        let names = ["real = v", "i = v", "j = v", "k = v"];
        let axes = [SliceAxis::Real, SliceAxis::I, SliceAxis::J, SliceAxis::K];
        let cur = axes.iter().position(|&a| a == q.slice).unwrap_or(3);
        let r = egui::ComboBox::from_id_salt("slice")
            .selected_text(names[cur])
            .show_ui(ui, |ui| {
                for (a, n) in axes.iter().zip(names) {
                    ui.selectable_value(&mut q.slice, *a, n);
                }
            });
        named(r.response, "Slice axis")
            .on_hover_text("which quaternion component is held fixed to cut a 3-D slice");
        ui.end_row();
        let lb = ui.label("Slice value v");
        ui.add(
            egui::DragValue::new(&mut q.slice_value)
                .speed(0.01)
                .range(-2.0..=2.0)
                .clamp_existing_to_range(false),
        )
        .labelled_by(lb.id)
        .on_hover_text("the value of the fixed component");
        ui.end_row();
        let lb = ui.label("Iterations");
        ui.add(egui::DragValue::new(&mut q.iterations).range(1..=200))
            .labelled_by(lb.id)
            .on_hover_text("iterations per distance estimate: finer detail, slower");
        ui.end_row();
    });
    *q != before
}
