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

/// The start of the name under which an image JWildfire wrote inline (its resource
/// `<variation>_inlined_image`) is handed over, followed by a hash of the image file's bytes.
/// The variation's `image_filename` holds this name while the flame is loaded; it is written
/// back empty, next to the inline image kept as it was read.
pub const INLINED_IMAGE: &str = "inlined_image:";

/// The suffix of JWildfire's resource holding an image file inline.
const INLINED_ATTR: &str = "_inlined_image";

/// Most hex digits of an inline image read (the size of [`MAX_IMAGE_FILE`] bytes).
const MAX_INLINED_HEX: usize = 2 * MAX_IMAGE_FILE as usize;

/// Load the images named by the variations of `flames`, read from the file `flame_path`
/// (shown as `file` in messages), and hand them over; one warning per image not loaded.
/// Images given inline (`<variation>_inlined_image`, kept among the xform's other
/// attributes) are decoded first and take the place of a named file, as in JWildfire.
pub fn load_variation_images(
    flames: &mut [Flame],
    flame_path: &Path,
    file: &str,
) -> Vec<Diagnostic> {
    let dir = flame_path.parent().unwrap_or(Path::new(""));
    let mut warnings = Vec::new();
    let mut done: Vec<String> = Vec::new();
    for x in flames.iter_mut().flat_map(all_xforms_mut) {
        take_inlined_images(x, file, &mut done, &mut warnings);
    }
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
                if !(image || mesh)
                    || name.is_empty()
                    || name.starts_with(INLINED_IMAGE)
                    || done.contains(name)
                {
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

/// Decode the images JWildfire wrote inline for the variations of `x` (JWildfire 9.00's
/// `AbstractFlameWriter` writes a resource as the hex digits of its bytes, two a byte, and
/// `Tools.hexStringToByteArray` reads them back), hand each over under [`INLINED_IMAGE`] and a
/// hash of its bytes, and name it in the variation's image text in place of a file, as
/// JWildfire's `setRessource` lets an inline image replace the file name. `done` holds the
/// names handed over already; an image that cannot be read is reported and the variation
/// keeps its file name or default image.
fn take_inlined_images(
    x: &mut Xform,
    file: &str,
    done: &mut Vec<String>,
    warnings: &mut Vec<Diagnostic>,
) {
    let mut found: Vec<(usize, usize, String)> = Vec::new();
    for (attr, hex) in &x.extra_attrs {
        let (plain, instance) =
            crate::io::xml::split_jwf_index(attr).unwrap_or_else(|| (attr.clone(), 0));
        let Some(stem) = plain.strip_suffix(INLINED_ATTR) else {
            continue;
        };
        let hex = hex.trim();
        if hex.is_empty() {
            continue;
        }
        let Some((id, form, index)) = variations::text_of(&format!("{stem}{IMAGE_TEXT}")) else {
            continue;
        };
        // The variation it belongs to: the `instance`-th of that name and form (JWildfire's
        // `#k#` counts the uses of a variation in an xform).
        let Some(v) = (0..x.vars.len())
            .filter(|&i| x.vars[i].id == id && x.vars[i].form == form)
            .nth(instance as usize)
        else {
            continue;
        };
        match inlined_image(hex) {
            Ok((key, img)) => {
                if !done.contains(&key) {
                    if !resources::put_image(&key, img) {
                        warnings.push(inline_warning(file, attr, "is empty"));
                        continue;
                    }
                    done.push(key.clone());
                }
                found.push((v, index, key));
            }
            Err(why) => warnings.push(inline_warning(file, attr, &why)),
        }
    }
    for (v, index, key) in found {
        if let Some(t) = x.vars[v].texts.get_mut(index) {
            *t = key;
        }
    }
}

fn inline_warning(file: &str, attr: &str, why: &str) -> Diagnostic {
    Diagnostic::warning(
        file,
        Pos::File,
        "IMG012",
        format!("{attr}: the image given inline {why}; it is not drawn"),
    )
}

/// The image whose file's bytes `hex` holds as hex digits, and the name to hand it over
/// under; why not, otherwise.
fn inlined_image(hex: &str) -> Result<(String, resources::ResourceImage), String> {
    if hex.len() > MAX_INLINED_HEX {
        return Err(format!("has more than {MAX_IMAGE_FILE} bytes"));
    }
    if !hex.len().is_multiple_of(2) || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err("is not an even number of hex digits".into());
    }
    let bytes: Vec<u8> = hex
        .as_bytes()
        .chunks_exact(2)
        .map(|p| (hex_digit(p[0]) << 4) | hex_digit(p[1]))
        .collect();
    // FNV-1a, 64 bits: names the image by its contents.
    let hash = bytes.iter().fold(0xcbf2_9ce4_8422_2325_u64, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    let img = decode_image(&bytes)?;
    Ok((format!("{INLINED_IMAGE}{hash:016x}"), img))
}

/// The value of an ASCII hex digit (0 for anything else).
fn hex_digit(c: u8) -> u8 {
    match c {
        b'0'..=b'9' => c - b'0',
        b'a'..=b'f' => c - b'a' + 10,
        b'A'..=b'F' => c - b'A' + 10,
        _ => 0,
    }
}

/// Every xform of a flame, to change: as [`all_xforms`].
fn all_xforms_mut(f: &mut Flame) -> impl Iterator<Item = &mut Xform> {
    let layers = f
        .more_layers
        .iter_mut()
        .flat_map(|l| l.xforms.iter_mut().chain(l.finals.iter_mut()));
    f.xforms
        .iter_mut()
        .chain(f.final_xform.as_mut())
        .chain(f.more_finals.iter_mut())
        .chain(layers)
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

    /// An image JWildfire wrote inline (the hex digits of a PNG file's bytes) is decoded and
    /// handed over in place of the (empty) file name; its pixels reach the variation. Written
    /// back, the file name stays empty and the image is kept; a bad one is reported.
    #[test]
    fn inlined_images_are_decoded_and_handed_over() {
        let dir = std::env::temp_dir().join(format!("ugnis-inline-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut png = Vec::new();
        let mut pic = image::RgbaImage::from_pixel(2, 2, image::Rgba([1, 2, 3, 255]));
        pic.put_pixel(1, 1, image::Rgba([200, 100, 50, 255]));
        pic.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .unwrap();
        let hex: String = png.iter().map(|b| format!("{b:02X}")).collect();
        let text = format!(
            r#"<flame name="a" version="JWildfire V6.00" size="10 10" center="0 0" scale="1"><xform weight="1" color="0" post_bumpmap_wf="1" post_bumpmap_wf_image_filename="" post_bumpmap_wf_inlined_image="{hex}" coefs="1 0 0 1 0 0"/><xform weight="1" color="0" colormap_wf="1" colormap_wf_inlined_image="0A1" coefs="1 0 0 1 0 0"/><palette count="1" format="RGB">000000</palette></flame>"#
        );
        let flame_path = dir.join("inline.flame");
        std::fs::write(&flame_path, &text).unwrap();
        let opts = crate::io::flam3_xml::ReadOptions::default();
        let parsed = crate::io::read_flame_file(&flame_path, &opts).unwrap();
        let f = &parsed.value.flames[0];
        let key = &f.xforms[0].vars[0].texts[0];
        assert!(key.starts_with(INLINED_IMAGE), "{key}");
        let img = resources::image(key).expect("handed over");
        assert_eq!((img.w, img.h), (2, 2));
        assert_eq!(img.rgba[0], [1, 2, 3, 255]);
        assert_eq!(img.rgba[3], [200, 100, 50, 255]);
        // The variation's own image data is that image (width, height, then 0xAARRGGBB).
        let v = &f.xforms[0].vars[0];
        let build = variations::info(v.id)
            .shared
            .expect("an image variation")
            .build;
        let data = build(&v.params, &v.texts);
        assert_eq!(&data[..2], [2.0, 2.0]);
        assert_eq!(data[5], f64::from(0xFFC8_6432_u32));
        // The odd number of digits is reported; that variation keeps its default image.
        let msgs: Vec<String> = parsed.warnings.iter().map(|w| w.message.clone()).collect();
        assert!(
            msgs.iter()
                .any(|m| m.contains("colormap_wf_inlined_image") && m.contains("even number")),
            "{msgs:?}"
        );
        assert_eq!(f.xforms[1].vars[0].texts[0], "");
        let out = crate::io::flam3_xml::write(&parsed.value);
        assert!(
            out.contains(r#"post_bumpmap_wf_image_filename="""#),
            "{out}"
        );
        assert!(out.contains(&format!(r#"post_bumpmap_wf_inlined_image="{hex}""#)));
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
