//! Saving a scene: the scene file it came from (or the default scene's text), with the camera,
//! lights, materials and texture choices made in the tab written over it. Textures made in
//! the tab become texture entries the scene reader understands; the current flame and
//! escape-time view are written beside the scene file and referenced by name.

use std::path::{Path, PathBuf};

use toml::{Table, Value};

use super::SceneTab;
use crate::escape::EscapeDoc;
use crate::flame::Flame;
use crate::io;
use crate::surface::{Geometry, Projection, Renderer};

/// The default scene: the jug wearing an fBm texture (no files needed).
pub const DEFAULT_SCENE: &str = r#"# ugnis scene
[[texture]]
name = "fbm"
kind = "fbm"
size = [512, 256]
colors = [[0.35, 0.12, 0.05], [0.95, 0.75, 0.45]]

[[object]]
kind = "jug"
name = "jug"
texture = "fbm"
"#;

/// Where a texture made in the tab came from, for writing it back.
#[derive(Clone, Debug)]
pub enum Origin {
    Flame(Box<Flame>),
    Escape(Box<EscapeDoc>),
    Image(PathBuf),
}

fn num(v: f64) -> Value {
    Value::Float(v)
}

fn arr(v: &[f64]) -> Value {
    Value::Array(v.iter().map(|x| num(*x)).collect())
}

fn int_arr(v: &[u32]) -> Value {
    Value::Array(v.iter().map(|x| Value::Integer(*x as i64)).collect())
}

fn table(pairs: Vec<(&str, Value)>) -> Value {
    Value::Table(pairs.into_iter().map(|(k, v)| (k.to_string(), v)).collect())
}

/// `file` (relative to `from`) as written in a scene file in `to`: relative when it lies
/// under `to`, absolute otherwise.
fn rebase(file: &str, from: &Path, to: &Path) -> String {
    let abs = std::path::absolute(from.join(file)).unwrap_or_else(|_| from.join(file));
    let to_abs = std::path::absolute(to).unwrap_or_else(|_| to.to_path_buf());
    match abs.strip_prefix(&to_abs) {
        Ok(rel) => rel.display().to_string(),
        Err(_) => abs.display().to_string(),
    }
}

impl SceneTab {
    /// The scene as a scene file to be written at `path`; files it needs beside it (the
    /// current flame and escape-time view) are written too.
    pub fn scene_file(&self, path: &Path) -> Result<String, String> {
        let dir = path.parent().unwrap_or(Path::new("."));
        let stem = path
            .file_stem()
            .map_or("scene".into(), |s| s.to_string_lossy().into_owned());
        let mut t: Table = self.source.clone();
        let s = &self.scene;
        let mut image = t
            .get("image")
            .and_then(Value::as_table)
            .cloned()
            .unwrap_or_default();
        match s.renderer {
            Renderer::ZBuffer => {
                t.remove("render");
                // Shadows need ray casting: a file saying so would not open again.
                t.remove("shadows");
            }
            Renderer::RayCast => {
                t.insert("render".into(), "raycast".into());
            }
        }
        image.insert("size".into(), int_arr(&[s.width, s.height]));
        image.insert("supersample".into(), Value::Integer(s.supersample as i64));
        t.insert("image".into(), Value::Table(image));
        let c = &s.camera;
        let mut cam = vec![
            ("target", arr(&c.target.to_array())),
            ("distance", num(c.distance)),
            ("azimuth", num(c.azimuth_deg)),
            ("polar", num(c.polar_deg)),
            ("scale", num(c.scale)),
        ];
        match c.projection {
            Projection::Perspective => cam.push(("projection", "perspective".into())),
            Projection::Orthographic => cam.push(("projection", "orthographic".into())),
            Projection::Stereo => cam.push(("projection", "stereo".into())),
            Projection::Axonometric { phi, theta } => {
                cam.push(("projection", "axonometric".into()));
                cam.push(("phi", num(phi.to_degrees())));
                cam.push(("theta", num(theta.to_degrees())));
            }
        }
        t.insert("camera".into(), table(cam));
        let lights: Vec<Value> = s
            .lights
            .iter()
            .map(|l| {
                let i = l.intensity;
                let intensity = if i.x == i.y && i.y == i.z {
                    num(i.x as f64)
                } else {
                    arr(&[i.x as f64, i.y as f64, i.z as f64])
                };
                table(vec![
                    ("position", arr(&l.position.to_array())),
                    ("intensity", intensity),
                ])
            })
            .collect();
        t.insert("light".into(), Value::Array(lights));
        // Textures: the file's own (their files rebased), then the ones made here.
        let source_textures: Vec<Value> = t
            .get("texture")
            .and_then(Value::as_array)
            .cloned()
            .unwrap_or_default();
        let base = self.base_dir.clone().unwrap_or_else(|| dir.to_path_buf());
        let mut textures = Vec::new();
        for (i, name) in self.texture_names.iter().enumerate() {
            let spec = match source_textures.get(i) {
                Some(Value::Table(src)) => {
                    let mut src = src.clone();
                    if let Some(f) = src.get("file").and_then(Value::as_str) {
                        let f = rebase(f, &base, dir);
                        src.insert("file".into(), f.into());
                    }
                    Value::Table(src)
                }
                _ => self.made_texture(name, dir, &stem)?,
            };
            textures.push(spec);
        }
        t.insert("texture".into(), Value::Array(textures));
        // Objects: materials and textures as chosen here.
        let mut objects: Vec<Value> = t
            .get("object")
            .and_then(Value::as_array)
            .cloned()
            .unwrap_or_default();
        for (o, v) in s.objects.iter().zip(objects.iter_mut()) {
            let Some(ot) = v.as_table_mut() else {
                continue;
            };
            match o.texture.and_then(|i| self.texture_names.get(i)) {
                Some(n) => ot.insert("texture".into(), n.clone().into()),
                None => ot.remove("texture"),
            };
            let mut m = ot
                .get("material")
                .and_then(Value::as_table)
                .cloned()
                .unwrap_or_default();
            let mm = &o.material;
            for (k, x) in [
                ("ka", mm.ka),
                ("kd", mm.kd),
                ("ks", mm.ks),
                ("n", mm.shininess),
                ("bump", mm.bump),
            ] {
                m.insert(k.into(), num(x));
            }
            ot.insert("material".into(), Value::Table(m));
            if let Geometry::QuaternionJulia(q) = &o.geometry {
                ot.insert("c".into(), arr(&q.c));
                ot.insert("slice".into(), q.slice.name().into());
                ot.insert("slice_value".into(), num(q.slice_value));
                ot.insert("iterations".into(), Value::Integer(q.iterations as i64));
            }
        }
        t.insert("object".into(), Value::Array(objects));
        let body = toml::to_string(&t).map_err(|e| e.to_string())?;
        Ok(format!("# ugnis scene\n{body}"))
    }

    /// The texture entry of a texture made in the tab.
    fn made_texture(&self, name: &str, dir: &Path, stem: &str) -> Result<Value, String> {
        let light = arr(&[0.9, 0.85, 0.7]);
        let dark = arr(&[0.2, 0.15, 0.1]);
        let spec = match (name, self.origins.get(name)) {
            ("(fbm)", _) => vec![
                ("kind", "fbm".into()),
                ("size", int_arr(&[512, 256])),
                ("colors", Value::Array(vec![dark, light])),
            ],
            ("(mrf)", _) => vec![
                ("kind", "mrf".into()),
                ("size", int_arr(&[256, 256])),
                ("colors", Value::Array(vec![dark, light])),
            ],
            ("(checker)", _) => vec![
                ("kind", "checker".into()),
                ("size", int_arr(&[256, 256])),
                ("cells", int_arr(&[16, 8])),
                ("colors", Value::Array(vec![arr(&[0.8, 0.25, 0.2]), light])),
            ],
            (_, Some(Origin::Flame(f))) => {
                let file = format!("{stem}-texture.flame");
                io::write_flames(&dir.join(&file), stem, std::slice::from_ref(f))
                    .map_err(|e| e.to_string())?;
                vec![
                    ("kind", "flame".into()),
                    ("file", file.into()),
                    ("size", int_arr(&[512, 384])),
                    ("quality", num(f.quality.min(40.0))),
                ]
            }
            (_, Some(Origin::Escape(d))) => {
                let file = format!("{stem}-texture.esc");
                io::escape_view::save(&dir.join(&file), d)
                    .map_err(|e| format!("{}: {e}", dir.join(&file).display()))?;
                vec![
                    ("kind", "escape".into()),
                    ("file", file.into()),
                    ("size", int_arr(&[1024, 512])),
                ]
            }
            (_, Some(Origin::Image(p))) => vec![
                ("kind", "image".into()),
                (
                    "file",
                    rebase(&p.display().to_string(), Path::new("."), dir).into(),
                ),
            ],
            (n, None) => return Err(format!("texture '{n}': where it came from is not known")),
        };
        let mut all = vec![("name", Value::from(name))];
        all.extend(spec);
        Ok(table(all))
    }

    /// Save the scene file (atomically); true when it was written.
    pub fn save(&mut self, path: &Path) -> bool {
        let r = self.scene_file(path).and_then(|text| {
            io::atomic::write_atomic(path, text.as_bytes())
                .map_err(|e| format!("{}: {e}", path.display()))
        });
        match r {
            Ok(()) => {
                self.path = Some(path.to_path_buf());
                self.notices.status(format!("Saved {}", path.display()));
                true
            }
            Err(e) => {
                self.notices.message("Cannot save", e);
                false
            }
        }
    }
}
