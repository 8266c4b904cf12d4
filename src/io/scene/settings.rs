//! The scene-wide settings of a scene file: renderer and shadows, image size, background and
//! supersampling, camera and projection, lighting and lights.

use glam::Vec3;

use super::format::{CameraSpec, Intensity, SceneSpec};
use super::textures::c3;
use crate::io::diag::{Diagnostic, Pos};
use crate::surface::transform;
use crate::surface::{Camera, Light, Projection, Renderer, Scene};

/// The scene the settings describe (no textures or objects yet). `at` turns a byte span of
/// the text into a position; values changed to fit are reported in `warnings`.
pub(super) fn scene(
    spec: &SceneSpec,
    name: &str,
    at: &dyn Fn(Option<std::ops::Range<usize>>) -> Pos,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Scene, Diagnostic> {
    let mut scene = Scene::default();
    if let Some(r) = &spec.render {
        scene.renderer = match r.get_ref().as_str() {
            "zbuffer" | "z-buffer" => Renderer::ZBuffer,
            "raycast" | "ray-cast" => Renderer::RayCast,
            o => {
                return Err(Diagnostic::error(
                    name,
                    at(Some(r.span())),
                    "SCN002",
                    format!("render = '{o}': expected \"zbuffer\" or \"raycast\""),
                ));
            }
        };
    }
    if let Some(sh) = &spec.shadows {
        if *sh.get_ref() && scene.renderer != Renderer::RayCast {
            return Err(Diagnostic::error(
                name,
                at(Some(sh.span())),
                "SCN002",
                "shadows = true needs render = \"raycast\" (the z-buffer renderer casts no shadows)",
            ));
        }
        scene.shadows = *sh.get_ref();
    }
    let img = spec.image.as_ref();
    if let Some([w, h]) = img.and_then(|i| i.size) {
        if w == 0 || h == 0 || w > 16384 || h > 16384 {
            return Err(Diagnostic::error(
                name,
                Pos::File,
                "SCN002",
                format!("image size {w}x{h} must be between 1x1 and 16384x16384"),
            ));
        }
        (scene.width, scene.height) = (w, h);
    }
    if let Some(b) = img.and_then(|i| i.background) {
        scene.background = c3(b);
    }
    let ss = img.and_then(|i| i.supersample).unwrap_or(1);
    if !(1..=4).contains(&ss) {
        warnings.push(Diagnostic::warning(
            name,
            Pos::File,
            "SCN006",
            format!(
                "image supersample {ss} is outside 1..4; using {}",
                ss.clamp(1, 4)
            ),
        ));
    }
    scene.supersample = ss.clamp(1, 4);
    scene.camera = camera(spec.camera.as_ref(), name)?;
    let l = spec.lighting.as_ref();
    scene.ambient = l.and_then(|l| l.ambient).unwrap_or(1.0);
    scene.attenuation_k = l.and_then(|l| l.attenuation).unwrap_or(1.0);
    scene.blinn = l.and_then(|l| l.blinn).unwrap_or(false);
    if let Some(lights) = &spec.light {
        scene.lights = lights
            .iter()
            .map(|l| Light {
                position: glam::DVec3::from_array(l.position),
                intensity: match l.intensity {
                    None => Vec3::splat(8.0),
                    Some(Intensity::Grey(g)) => Vec3::splat(g as f32),
                    Some(Intensity::Rgb(c)) => c3(c),
                },
            })
            .collect();
    }
    Ok(scene)
}

/// The camera and its projection.
fn camera(cam: Option<&CameraSpec>, name: &str) -> Result<Camera, Diagnostic> {
    let d = Camera::default();
    let Some(cam) = cam else {
        return Ok(d);
    };
    let camera = Camera {
        target: cam.target.map_or(d.target, glam::DVec3::from_array),
        distance: cam.distance.unwrap_or(d.distance),
        azimuth_deg: cam.azimuth.unwrap_or(d.azimuth_deg),
        polar_deg: cam.polar.unwrap_or(d.polar_deg),
        scale: cam.scale.unwrap_or(d.scale),
        projection: match cam.projection.as_deref().unwrap_or("perspective") {
            "perspective" => Projection::Perspective,
            "orthographic" => Projection::Orthographic,
            "stereo" => Projection::Stereo,
            "isometric" => {
                let (phi, theta) = transform::isometric_angles();
                Projection::Axonometric { phi, theta }
            }
            "dimetric" => {
                let (phi, theta) = transform::dimetric_angles(cam.fz.unwrap_or(0.5));
                Projection::Axonometric { phi, theta }
            }
            "axonometric" => Projection::Axonometric {
                phi: cam.phi.unwrap_or(30.0).to_radians(),
                theta: cam.theta.unwrap_or(20.0).to_radians(),
            },
            o => {
                return Err(Diagnostic::error(
                    name,
                    Pos::File,
                    "SCN002",
                    format!(
                        "camera projection '{o}': expected perspective, orthographic, isometric, dimetric, axonometric or stereo"
                    ),
                ));
            }
        },
    };
    if !(camera.distance > 0.0 && camera.scale > 0.0) {
        return Err(Diagnostic::error(
            name,
            Pos::File,
            "SCN002",
            "camera distance and scale must be positive",
        ));
    }
    Ok(camera)
}
