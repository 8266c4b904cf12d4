//! Texture sources for scene objects: the current flame, the current escape-time view,
//! procedural textures (fBm, Markov random field, checker) and image files; the costly ones
//! are made in the background.

use glam::Vec3;

use super::save::Origin;
use super::{SceneTab, TextureSource};
use crate::app::worker::task_worker;
use crate::escape::EscapeDoc;
use crate::escape::Family;
use crate::flame::Flame;
use crate::noise::Fbm;
use crate::surface::texture::{self, MrfParams, Texture};

impl SceneTab {
    /// Use a texture (made in the background for flames and escape views) on the selected
    /// object.
    pub fn set_source(&mut self, src: TextureSource, flame: &Flame, escape: &EscapeDoc) {
        let slot = self.selected_object;
        let name = |n: &str| n.to_string();
        let task: crate::app::worker::Task<super::TextureResult> = match src {
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
                self.origins.insert(
                    "(current flame)".into(),
                    Origin::Flame(Box::new(flame.clone())),
                );
                let mut f = flame.clone();
                Box::new(move |_, _| {
                    f.resize_keep_framing(512, 384);
                    f.quality = f.quality.min(40.0);
                    crate::flame::render(
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
                    .map_err(|e| e.to_string())
                })
            }
            TextureSource::CurrentEscape => {
                self.origins.insert(
                    "(current escape view)".into(),
                    Origin::Escape(Box::new(escape.clone())),
                );
                let d = escape.clone();
                Box::new(move |_, _| {
                    let (w, h) = (1024u32, 512u32);
                    let mut d = d.clone();
                    if !matches!(d.params.family, Family::WarpedJulia(_)) {
                        d.resize(w, h);
                    }
                    crate::escape::render(&d.params, d.view.clone(), w, h)
                        .map(|(img, _)| {
                            (
                                slot,
                                Texture::from_image(&img),
                                name("(current escape view)"),
                            )
                        })
                        .map_err(|e| e.to_string())
                })
            }
            TextureSource::Fbm | TextureSource::Mrf | TextureSource::Checker => {
                Box::new(move |_, _| {
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
                    Ok((slot, t, name(n)))
                })
            }
        };
        let r = self.repaint.clone();
        let w = task_worker("ugnis-texture", move || r());
        w.submit(task);
        self.texture_job = Some(w);
        self.notices.status("Making the texture…");
    }

    /// Use an image file as the selected object's texture.
    pub fn set_image_texture(&mut self, path: &std::path::Path) {
        match image::open(path) {
            Ok(img) => {
                let n = path
                    .file_name()
                    .map_or("image".into(), |s| s.to_string_lossy().into_owned());
                self.origins
                    .insert(n.clone(), Origin::Image(path.to_path_buf()));
                self.install_texture(self.selected_object, Texture::from_image(&img.to_rgb8()), n);
            }
            Err(e) => self.notices.status = format!("{}: {e}", path.display()),
        }
    }

    pub(super) fn install_texture(&mut self, slot: usize, t: Texture, name: String) {
        // A texture of the same name is replaced: names stay unique, as scene files need.
        let i = match self.texture_names.iter().position(|n| *n == name) {
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
        self.notices.status = "Texture ready".into();
    }
}
