//! The scene tab's control panel: file buttons, objects and their textures and materials,
//! lights, camera and projection.

use eframe::egui;
use glam::{DVec3, Vec3};

use super::{SceneRequest, SceneTab, TextureSource};
use crate::escape::EscapeDoc;
use crate::flame::Flame;
use crate::surface::{Light, Projection};

impl SceneTab {
    pub(super) fn controls(
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
}
