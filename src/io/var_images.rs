//! The files JWildfire's variations name in their resources: images
//! (`colormap_wf_image_filename` and the like) and Wavefront OBJ meshes
//! (`obj_mesh_wf_obj_filename`), read when a flame file is read and handed to the variations
//! ([`crate::flame::variations::resources`]). A name is looked up relative to the flame
//! file's folder (an absolute name as it stands); a file that is missing or cannot be decoded
//! is reported as a warning, and the variation then draws with its default image or mesh.

use std::path::Path;

use image::{ImageReader, Limits};

use crate::flame::model::{Flame, Xform};
use crate::flame::variations::{self, resources};
use crate::io::diag::{Diagnostic, Pos};

/// The suffix of the text parameters that name an image file.
const IMAGE_TEXT: &str = "_image_filename";

/// The suffix of the text parameters that name a mesh file.
const MESH_TEXT: &str = "_obj_filename";

/// Largest mesh file read (bytes).
const MAX_MESH_FILE: u64 = 256 << 20;

/// Load the images named by the variations of `flames`, read from the file `flame_path`
/// (shown as `file` in messages), and hand them over; one warning per image not loaded.
pub fn load_variation_images(flames: &[Flame], flame_path: &Path, file: &str) -> Vec<Diagnostic> {
    let dir = flame_path.parent().unwrap_or(Path::new(""));
    let mut warnings = Vec::new();
    let mut done: Vec<String> = Vec::new();
    let installed = resources::has_jwildfire_reader();
    for x in flames.iter().flat_map(all_xforms) {
        for v in &x.vars {
            let def = variations::info(v.id);
            if !installed
                && needs_jwildfire(def.name, &v.params)
                && !done.contains(&def.name.into())
            {
                done.push(def.name.into());
                warnings.push(Diagnostic::warning(
                    file,
                    Pos::File,
                    "IMG011",
                    format!(
                        "{}: draws resources that ship with JWildfire; name JWildfire's \
                         j-wildfire.jar (Options › General › JWildfire installation, or the \
                         environment variable {}) to draw it as JWildfire does; a stand-in is \
                         drawn",
                        def.name,
                        crate::io::jwf_install::ENV
                    ),
                ));
            }
            for (tp, name) in def.texts.iter().zip(&v.texts) {
                // `brush_stroke_wf_image_filename1` … `6` name images too.
                let image = tp
                    .name
                    .trim_end_matches(|c: char| c.is_ascii_digit())
                    .ends_with(IMAGE_TEXT);
                let mesh = tp.name.ends_with(MESH_TEXT);
                if !(image || mesh) || name.is_empty() || done.contains(name) {
                    continue;
                }
                done.push(name.clone());
                let (what, loaded) = if image {
                    ("image", load(dir, name))
                } else {
                    ("mesh", load_mesh(dir, name))
                };
                if let Err(why) = loaded {
                    let var = def.name;
                    warnings.push(Diagnostic::warning(
                        file,
                        Pos::File,
                        "IMG010",
                        format!("{var}: {what} '{name}' {why}; JWildfire's default {what} is used"),
                    ));
                }
            }
        }
    }
    warnings
}

/// Whether the variation `name` with parameters `params` draws one of JWildfire's own
/// resources that ugnis can only take from a JWildfire installation: the brush images, the
/// wang tiles, and the primitive meshes other than the ball and the capsule (which ugnis
/// builds exactly).
fn needs_jwildfire(name: &str, params: &[f64]) -> bool {
    match name {
        "brush_stroke_wf" | "post_brush_stroke_wf" | "wangtiles" => true,
        "obj_mesh_primitive_wf" => params.first().is_some_and(|&p| p != 0.0 && p != 1.0),
        _ => false,
    }
}

/// Every xform of a flame: its own, its final ones and those of its other layers.
fn all_xforms(f: &Flame) -> impl Iterator<Item = &Xform> {
    let layers = f
        .more_layers
        .iter()
        .flat_map(|l| l.xforms.iter().chain(&l.finals));
    f.xforms
        .iter()
        .chain(f.final_xform.as_ref())
        .chain(&f.more_finals)
        .chain(layers)
}

/// Where a resource named `name` is: relative to the flame's folder `dir`, unless absolute.
fn find(dir: &Path, name: &str) -> Result<std::path::PathBuf, String> {
    let p = Path::new(name);
    let path = if p.is_absolute() {
        p.to_path_buf()
    } else {
        dir.join(p)
    };
    if path.is_file() {
        Ok(path)
    } else {
        Err(format!("not found (looked for {})", path.display()))
    }
}

/// Read, parse and hand over the mesh `name`; why not, otherwise.
fn load_mesh(dir: &Path, name: &str) -> Result<(), String> {
    let path = find(dir, name)?;
    let bytes = crate::io::read_bytes_limited(&path, MAX_MESH_FILE).map_err(|d| d.message)?;
    let mesh = parse_obj(&String::from_utf8_lossy(&bytes))?;
    if resources::put_mesh(name, mesh) {
        Ok(())
    } else {
        Err("has no triangles".into())
    }
}

/// A Wavefront OBJ mesh as JWildfire takes it: the vertices (`v x y z`) its faces use, those
/// at the same place (to 10⁻⁴) merged, and the faces (`f`, indices from 1, negative ones
/// counted back from the last vertex read, texture and normal indices ignored) of three
/// corners, and of four split along their first diagonal; other faces are skipped.
pub(crate) fn parse_obj(text: &str) -> Result<resources::ResourceMesh, String> {
    let mut all: Vec<[f32; 3]> = Vec::new();
    let mut mesh = resources::ResourceMesh {
        vertices: Vec::new(),
        faces: Vec::new(),
    };
    let mut merged = std::collections::HashMap::new();
    for (n, line) in text.lines().enumerate() {
        let mut it = line.split_whitespace();
        match it.next() {
            Some("v") => {
                let c: Vec<f64> = it.take(3).filter_map(|t| t.parse().ok()).collect();
                if c.len() != 3 {
                    return Err(format!("has a bad vertex on line {}", n + 1));
                }
                all.push([c[0] as f32, c[1] as f32, c[2] as f32]);
            }
            Some("f") => {
                let mut corners = Vec::with_capacity(4);
                for t in it {
                    let i: i64 = t
                        .split('/')
                        .next()
                        .and_then(|i| i.parse().ok())
                        .ok_or_else(|| format!("has a bad face on line {}", n + 1))?;
                    let k = if i < 0 { all.len() as i64 + i } else { i - 1 };
                    let v = usize::try_from(k)
                        .ok()
                        .and_then(|k| all.get(k))
                        .ok_or_else(|| format!("names a missing vertex on line {}", n + 1))?;
                    let key = v.map(|c| {
                        let x = f64::from(c) * 1e4;
                        (x.abs() + 0.5).trunc().copysign(x) as i64
                    });
                    let id = *merged.entry(key).or_insert_with(|| {
                        mesh.vertices.push(*v);
                        (mesh.vertices.len() - 1) as u32
                    });
                    corners.push(id);
                }
                match corners[..] {
                    [a, b, c] => mesh.faces.push([a, b, c]),
                    [a, b, c, d] => mesh.faces.extend([[a, b, c], [a, c, d]]),
                    _ => {}
                }
                if mesh.faces.len() > resources::MAX_MESH_FACES {
                    return Err(format!(
                        "has more than {} triangles",
                        resources::MAX_MESH_FACES
                    ));
                }
            }
            _ => {}
        }
    }
    Ok(mesh)
}

/// Largest image file read (bytes).
const MAX_IMAGE_FILE: u64 = 256 << 20;

/// Read, decode and hand over the image `name`; why not, otherwise.
fn load(dir: &Path, name: &str) -> Result<(), String> {
    let path = find(dir, name)?;
    let bytes = crate::io::read_bytes_limited(&path, MAX_IMAGE_FILE).map_err(|d| d.message)?;
    if resources::put_image(name, decode_image(&bytes)?) {
        Ok(())
    } else {
        Err("is empty".into())
    }
}

/// Decode an image file's bytes as variations take it (RGBA, rows from the top), within the
/// size a variation takes; why not, otherwise.
pub(crate) fn decode_image(bytes: &[u8]) -> Result<resources::ResourceImage, String> {
    let mut r = ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| format!("cannot be read: {e}"))?;
    let mut limits = Limits::default();
    limits.max_image_width = Some(1 << 16);
    limits.max_image_height = Some(1 << 16);
    limits.max_alloc = Some(1 << 30);
    r.limits(limits);
    let img = r
        .decode()
        .map_err(|e| format!("cannot be decoded: {e}"))?
        .to_rgba8();
    let (w, h) = img.dimensions();
    if w as usize * h as usize > resources::MAX_IMAGE_PIXELS {
        return Err(format!(
            "has {w}×{h} pixels, more than the {} a variation takes",
            resources::MAX_IMAGE_PIXELS
        ));
    }
    let rgba = img.pixels().map(|p| p.0).collect();
    Ok(resources::ResourceImage { w, h, rgba })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn named_images_are_loaded_next_to_the_flame_or_reported() {
        let dir = std::env::temp_dir().join(format!("ugnis-var-images-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let png = dir.join("h9b-io-test.png");
        image::RgbaImage::from_pixel(3, 2, image::Rgba([7, 8, 9, 255]))
            .save(&png)
            .unwrap();
        let hex = |s: &str| s.bytes().map(|b| format!("{b:02X}")).collect::<String>();
        let text = format!(
            r#"<flame name="a" size="10 10" center="0 0" scale="1"><xform weight="1" color="0" colormap_wf="1" colormap_wf_image_filename="{}" coefs="1 0 0 1 0 0"/><xform weight="1" color="0" post_bumpmap_wf="1" post_bumpmap_wf_image_filename="{}" coefs="1 0 0 1 0 0"/><palette count="1" format="RGB">000000</palette></flame>"#,
            hex("h9b-io-test.png"),
            hex("h9b-missing.png")
        );
        let flame_path = dir.join("a.flame");
        std::fs::write(&flame_path, text).unwrap();
        let opts = crate::io::flam3_xml::ReadOptions::default();
        let parsed = crate::io::read_flames(&flame_path, &opts).unwrap();
        let img = resources::image("h9b-io-test.png").expect("loaded");
        assert_eq!((img.w, img.h), (3, 2));
        assert_eq!(img.rgba[5], [7, 8, 9, 255]);
        let msgs: Vec<String> = parsed.warnings.iter().map(|w| format!("{w:?}")).collect();
        assert!(
            msgs.iter()
                .any(|m| m.contains("post_bumpmap_wf") && m.contains("h9b-missing.png")),
            "{msgs:?}"
        );
        assert!(
            !msgs.iter().any(|m| m.contains("h9b-io-test.png")),
            "{msgs:?}"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn obj_faces_become_triangles_with_merged_vertices() {
        let m = parse_obj(
            "# a square and a triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.00001 0 0\n\
             f 1/1 2/2 3/3 4/4\nf -1 2 3\nf 1 2 3 4 5\n",
        )
        .unwrap();
        // The fifth vertex merges with the first; the five-cornered face is skipped.
        assert_eq!(m.vertices.len(), 4);
        assert_eq!(m.faces, vec![[0, 1, 2], [0, 2, 3], [0, 1, 2]]);
        assert!(parse_obj("v 0 0 0\nf 1 2 3\n").is_err());
    }
}
