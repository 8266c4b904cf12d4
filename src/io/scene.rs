//! Scene files (`.toml`, documented in README): image, camera, lights, textures and objects of
//! a textured Bézier scene. Paths inside are relative to the scene file. Codes SCN001–SCN005.
//!
//! ```toml
//! render = "raycast"      # optional: "zbuffer" (default) or "raycast"
//! shadows = true          # ray casting only
//! [image]
//! size = [640, 480]
//! [camera]
//! target = [0, 1.2, 0]
//! distance = 7
//! azimuth = 35
//! polar = 75
//! [[light]]
//! position = [-5, 8, 6]
//! intensity = 8
//! [[texture]]
//! name = "wood"
//! kind = "fbm"
//! [[object]]
//! kind = "jug"
//! texture = "wood"
//! ```

use std::path::{Path, PathBuf};

use glam::{DVec3, Vec3};
use serde::Deserialize;
use toml::Spanned;

use super::diag::{Diagnostic, Pos, SourceMap};
use crate::noise::Fbm;
use crate::surface::menger;
use crate::surface::mesh::{self, SurfacePatch, TexMap};
use crate::surface::patch::Patch;
use crate::surface::texture::{self, MrfParams, Texture};
use crate::surface::transform::{self, Transform};
use crate::surface::{
    Camera, Geometry, Light, Material, Object, Projection, QuaternionJulia, Renderer, Scene,
    SliceAxis,
};

/// Most objects in a scene.
pub const MAX_OBJECTS: usize = 10_000;
/// Most textures in a scene.
pub const MAX_TEXTURES: usize = 256;
/// Most lights in a scene.
pub const MAX_LIGHTS: usize = 256;
/// Most Bézier patches in a scene (a jug has 20, the teapot 32).
pub const MAX_PATCHES: usize = 25_000;
/// Most cubic segments of a surface of revolution's profile (four patches each).
pub const MAX_PROFILE_SEGMENTS: usize = 1000;
/// Highest degree of a Bézier patch in either direction.
pub const MAX_BEZIER_DEGREE: usize = 30;
/// Largest texture side.
pub const MAX_TEXTURE_SIDE: u32 = 8192;

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct ImageSpec {
    size: Option<[u32; 2]>,
    background: Option<[f64; 3]>,
    supersample: Option<u32>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct CameraSpec {
    target: Option<[f64; 3]>,
    distance: Option<f64>,
    azimuth: Option<f64>,
    polar: Option<f64>,
    projection: Option<String>,
    scale: Option<f64>,
    /// Axonometric angles in degrees.
    phi: Option<f64>,
    theta: Option<f64>,
    /// Dimetric: the z foreshortening.
    fz: Option<f64>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct LightingSpec {
    ambient: Option<f64>,
    attenuation: Option<f64>,
    blinn: Option<bool>,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum Intensity {
    Grey(f64),
    Rgb([f64; 3]),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LightSpec {
    position: [f64; 3],
    intensity: Option<Intensity>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct TextureSpec {
    name: String,
    kind: String,
    file: Option<String>,
    size: Option<[u32; 2]>,
    quality: Option<f64>,
    colors: Option<Vec<[f64; 3]>>,
    octaves: Option<u32>,
    lacunarity: Option<f64>,
    gain: Option<f64>,
    frequency: Option<f64>,
    seed: Option<u64>,
    cells: Option<[u32; 2]>,
    alpha: Option<f64>,
    beta: Option<f64>,
    delta: Option<f64>,
    phi: Option<f64>,
    omega: Option<f64>,
    sweeps: Option<u32>,
    gradient: Option<String>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct MaterialSpec {
    ka: Option<f64>,
    kd: Option<f64>,
    ks: Option<f64>,
    n: Option<f64>,
    color: Option<[f64; 3]>,
    two_sided: Option<bool>,
    bump: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Step {
    translate: Option<[f64; 3]>,
    scale: Option<ScaleSpec>,
    rotate_x: Option<f64>,
    rotate_y: Option<f64>,
    rotate_z: Option<f64>,
    /// Rotation about an axis: [nx, ny, nz, degrees] (through the origin) or with `through`.
    rotate_axis: Option<[f64; 4]>,
    through: Option<[f64; 3]>,
    shear: Option<[f64; 6]>,
    reflect: Option<String>,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum ScaleSpec {
    Uniform(f64),
    Axes([f64; 3]),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ObjectSpec {
    kind: String,
    name: Option<String>,
    texture: Option<String>,
    bump_texture: Option<String>,
    material: Option<MaterialSpec>,
    transform: Option<Vec<Step>>,
    /// revolve: 3k + 1 profile points [r, y].
    profile: Option<Vec<[f64; 2]>>,
    /// tube: 4 spine points.
    spine: Option<Vec<[f64; 3]>>,
    radius: Option<f64>,
    /// bezier: degrees [n, m] and the (n + 1)(m + 1) net, rows along u.
    degree: Option<[usize; 2]>,
    net: Option<Vec<[f64; 3]>>,
    /// bilinear: p00, p01, p10, p11.
    corners: Option<Vec<[f64; 3]>>,
    /// mountain.
    levels: Option<u32>,
    size: Option<f64>,
    sigma: Option<f64>,
    h: Option<f64>,
    seed: Option<u64>,
    /// quaternion_julia: c = [c₀, c₁, c₂, c₃] (or [re, im]), the fixed component and its
    /// value, iterations.
    c: Option<Vec<f64>>,
    slice: Option<String>,
    slice_value: Option<f64>,
    iterations: Option<u32>,
    /// menger: construction step.
    step: Option<u32>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneSpec {
    /// "zbuffer" (default) or "raycast".
    render: Option<Spanned<String>>,
    /// Shadow rays (ray casting only; default on).
    shadows: Option<Spanned<bool>>,
    image: Option<ImageSpec>,
    camera: Option<CameraSpec>,
    lighting: Option<LightingSpec>,
    light: Option<Vec<LightSpec>>,
    texture: Option<Vec<Spanned<TextureSpec>>>,
    object: Option<Vec<Spanned<ObjectSpec>>>,
}

/// A loaded scene with the names of its textures (by index).
pub struct LoadedScene {
    pub scene: Scene,
    pub texture_names: Vec<String>,
    /// One line per generated object worth describing (e.g. a Menger sponge's numbers).
    pub notes: Vec<String>,
    /// Values that were changed to fit (clamped) and other remarks.
    pub warnings: Vec<Diagnostic>,
}

fn v3(a: [f64; 3]) -> DVec3 {
    DVec3::from_array(a)
}

fn c3(a: [f64; 3]) -> Vec3 {
    Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32)
}

/// Bytes a texture of w×h texels takes with its mipmaps (4/3 of the base level).
pub fn texture_bytes(w: usize, h: usize) -> u64 {
    (w as u64 * h as u64 * std::mem::size_of::<Vec3>() as u64) * 4 / 3
}

/// Build a texture from its spec; `base` resolves relative files. Values changed to fit are
/// reported in `warn`.
fn make_texture(t: &TextureSpec, base: &Path, warn: &mut Vec<String>) -> Result<Texture, String> {
    let [w, h] = t.size.unwrap_or([512, 512]);
    if w == 0 || h == 0 || w > MAX_TEXTURE_SIDE || h > MAX_TEXTURE_SIDE {
        return Err(format!(
            "size {w}x{h} must be between 1x1 and {MAX_TEXTURE_SIDE}x{MAX_TEXTURE_SIDE}"
        ));
    }
    let (w, h) = (w as usize, h as usize);
    let colors = t
        .colors
        .clone()
        .unwrap_or_else(|| vec![[0.1, 0.1, 0.12], [0.95, 0.9, 0.8]]);
    let Some(&first) = colors.first() else {
        return Err("colors needs at least one colour [r, g, b]".into());
    };
    let (a, b) = (c3(first), c3(*colors.get(1).unwrap_or(&first)));
    let file = || -> Result<PathBuf, String> {
        let f = t.file.as_ref().ok_or("needs file = \"…\"")?;
        let p = base.join(f);
        if !p.exists() {
            return Err(format!("file '{}' does not exist", p.display()));
        }
        Ok(p)
    };
    let octaves = t.octaves.unwrap_or(6);
    if !(1..=16).contains(&octaves) {
        warn.push(format!(
            "octaves {octaves} is outside 1..16; using {}",
            octaves.clamp(1, 16)
        ));
    }
    let fbm = || Fbm {
        octaves: octaves.clamp(1, 16),
        lacunarity: t.lacunarity.unwrap_or(2.0),
        gain: t.gain.unwrap_or(0.5),
        frequency: t.frequency.unwrap_or(4.0),
        seed: t.seed.unwrap_or(1),
    };
    let cells = |what: &str, warn: &mut Vec<String>| {
        let [n, m] = t.cells.unwrap_or([8, 8]);
        if n == 0 || m == 0 {
            warn.push(format!(
                "{what} cells {n}x{m}: at least 1 each; using {}x{}",
                n.max(1),
                m.max(1)
            ));
        }
        (n.max(1), m.max(1))
    };
    Ok(match t.kind.as_str() {
        "image" => {
            let p = file()?;
            let img = super::image_in::read_rgb(&p).map_err(|e| e.to_string())?;
            Texture::from_image(&img)
        }
        "flame" => {
            let p = file()?;
            let mut f = super::read_flames(&p, &Default::default())
                .map_err(|e| e.to_string())?
                .value
                .into_iter()
                .next()
                .ok_or_else(|| format!("{}: no flame", p.display()))?;
            f.resize_keep_framing(w as u32, h as u32);
            if let Some(q) = t.quality {
                f.quality = q;
            }
            // A fixed thread count keeps the texture (and the scene) identical on every machine.
            let opts = crate::flame::RenderOptions {
                threads: 2,
                ..Default::default()
            };
            let img = crate::flame::render(&f, &opts).map_err(|e| e.to_string())?;
            Texture::from_image(&img.to_rgb8())
        }
        "escape" => {
            let p = file()?;
            let d = super::escape_view::read(&p)
                .map_err(|e| e.to_string())?
                .value;
            let mut view = d.view;
            // Keep the view's world width at the texture's size.
            view.half_height = d.world_width() / 2.0 * h as f64 / w as f64;
            let (img, _) = crate::escape::render(&d.params, view, w as u32, h as u32)
                .map_err(|e| e.to_string())?;
            Texture::from_image(&img)
        }
        "fbm" => texture::fbm_texture(w, h, fbm(), a, b),
        "value" => {
            let (n, _) = cells("value", warn);
            texture::value_noise_texture(w, h, t.seed.unwrap_or(1), n, a, b)
        }
        "mrf" => {
            let d = MrfParams::default();
            let sweeps = t.sweeps.unwrap_or(d.sweeps);
            if sweeps > 1000 {
                warn.push(format!("sweeps {sweeps} is more than 1000; using 1000"));
            }
            if w > 1024 || h > 1024 {
                warn.push(format!(
                    "a Markov random field texture is at most 1024x1024; using {}x{}",
                    w.min(1024),
                    h.min(1024)
                ));
            }
            let p = MrfParams {
                alpha: t.alpha.unwrap_or(d.alpha),
                beta: t.beta.unwrap_or(d.beta),
                delta: t.delta.unwrap_or(d.delta),
                phi: t.phi.unwrap_or(d.phi),
                omega: t.omega.unwrap_or(d.omega),
                sweeps: sweeps.min(1000),
                seed: t.seed.unwrap_or(1),
            };
            texture::mrf_texture(w.min(1024), h.min(1024), &p, a, b)
        }
        "checker" => {
            let (n, m) = cells("checker", warn);
            texture::checker(w, h, n as usize, m as usize, a, b)
        }
        "grid" => {
            let (n, m) = cells("grid", warn);
            texture::grid(w, h, n as usize, m as usize, a, b)
        }
        "solid" => Texture::solid(a),
        "gradient" => {
            let name = t.gradient.as_deref().unwrap_or("ember");
            let g = super::escape_view::resolve_gradient_parsed(name, Some(base))?;
            warn.extend(g.warnings.iter().map(|w| w.to_string()));
            let g = g.value;
            // t runs along the gradient (e.g. a mountain's height).
            let rows: Vec<Vec3> = (0..256)
                .flat_map(|k| {
                    let c = g.colors[k];
                    std::iter::repeat_n(Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32), 4)
                })
                .collect();
            Texture::from_texels(4, 256, rows)
        }
        other => {
            return Err(format!(
                "unknown texture kind '{other}': expected image, flame, escape, fbm, value, mrf, checker, grid, solid or gradient"
            ));
        }
    })
}

/// Bytes a texture will take once made (with the buffers used while making it).
fn texture_need(t: &TextureSpec) -> u64 {
    let [w, h] = t.size.unwrap_or([512, 512]);
    let (w, h) = (w as usize, h as usize);
    match t.kind.as_str() {
        "solid" => 16,
        "gradient" => texture_bytes(4, 256),
        "mrf" => {
            let (w, h) = (w.min(1024), h.min(1024));
            texture_bytes(w, h) + (w * h * 8) as u64
        }
        // Flame and escape renders check their own memory; an image is checked by size when
        // it is decoded. Their textures are the size of the picture.
        _ => texture_bytes(w, h) + (w * h * 4) as u64,
    }
}

fn make_transform(steps: &[Step]) -> Result<Transform, String> {
    let mut t = Transform::IDENTITY;
    for s in steps {
        let mut any = 0;
        let mut add = |m: Transform| {
            any += 1;
            t = t.then(&m);
        };
        if let Some(v) = s.scale.as_ref() {
            add(match v {
                ScaleSpec::Uniform(k) => Transform::scale(*k, *k, *k),
                ScaleSpec::Axes(a) => Transform::scale(a[0], a[1], a[2]),
            });
        }
        if let Some(a) = s.shear {
            add(Transform::shear(a[0], a[1], a[2], a[3], a[4], a[5]));
        }
        if let Some(d) = s.rotate_x {
            add(Transform::rot_x(d.to_radians()));
        }
        if let Some(d) = s.rotate_y {
            add(Transform::rot_y(d.to_radians()));
        }
        if let Some(d) = s.rotate_z {
            add(Transform::rot_z(d.to_radians()));
        }
        if let Some(a) = s.rotate_axis {
            let n = DVec3::new(a[0], a[1], a[2]);
            if n.length_squared() == 0.0 {
                return Err("rotate_axis needs a non-zero axis".into());
            }
            let p = s.through.map_or(DVec3::ZERO, v3);
            add(Transform::rot_axis_through(p, n, a[3].to_radians()));
        }
        if let Some(r) = &s.reflect {
            add(match r.as_str() {
                "xy" => Transform::reflect_xy(),
                "yz" => Transform::reflect_yz(),
                "xz" => Transform::reflect_xz(),
                o => return Err(format!("reflect '{o}': expected xy, yz or xz")),
            });
        }
        if let Some(v) = s.translate {
            add(Transform::translate(v[0], v[1], v[2]));
        }
        if any != 1 {
            return Err("each transform step needs exactly one operation".into());
        }
    }
    Ok(t)
}

/// Subdivision levels of a mountain (1..10; the caller warns when clamped).
fn mountain_levels(o: &ObjectSpec) -> u32 {
    o.levels.unwrap_or(7).clamp(1, 10)
}

/// Bytes of a mountain's mesh: (2^levels + 1)² vertices, two triangles per cell.
fn mountain_bytes(levels: u32) -> u64 {
    let side = (1u64 << levels) + 1;
    side * side * (24 + 24 + 8 + 48 + 8) + 2 * (side - 1) * (side - 1) * 12
}

fn make_geometry(o: &ObjectSpec) -> Result<Geometry, String> {
    Ok(match o.kind.as_str() {
        "jug" => Geometry::Patches(mesh::jug()),
        "teapot" => Geometry::Patches(mesh::teapot()),
        "revolve" => {
            let p = o.profile.as_ref().ok_or("needs profile = [[r, y], …]")?;
            if p.len() > 3 * MAX_PROFILE_SEGMENTS + 1 {
                return Err(format!(
                    "profile has {} points: at most {} ({MAX_PROFILE_SEGMENTS} cubic segments)",
                    p.len(),
                    3 * MAX_PROFILE_SEGMENTS + 1
                ));
            }
            if p.len() < 4 || (p.len() - 1) % 3 != 0 {
                return Err(format!(
                    "profile has {} points: needs 3k + 1 (k ≥ 1 cubic segments)",
                    p.len()
                ));
            }
            Geometry::Patches(mesh::revolve(p))
        }
        "tube" => {
            let s = o.spine.as_ref().ok_or("needs spine = 4 points")?;
            let s: [[f64; 3]; 4] = s
                .clone()
                .try_into()
                .map_err(|_| "spine needs exactly 4 points")?;
            let r = o.radius.unwrap_or(0.1);
            if r <= 0.0 {
                return Err("radius must be positive".into());
            }
            Geometry::Patches(mesh::tube(s.map(v3), r))
        }
        "bezier" => {
            let [n, m] = o.degree.unwrap_or([3, 3]);
            if !(1..=MAX_BEZIER_DEGREE).contains(&n) || !(1..=MAX_BEZIER_DEGREE).contains(&m) {
                return Err(format!(
                    "degree [{n}, {m}]: each must be between 1 and {MAX_BEZIER_DEGREE}"
                ));
            }
            let net = o.net.as_ref().ok_or("needs net = [[x, y, z], …]")?;
            let p = Patch::bezier(n, m, net.iter().map(|p| v3(*p)).collect())
                .map_err(|e| e.to_string())?;
            Geometry::Patches(vec![SurfacePatch {
                patch: p,
                tex: TexMap::default(),
            }])
        }
        "bilinear" => {
            let c = o.corners.as_ref().ok_or("needs corners = 4 points")?;
            let c: [[f64; 3]; 4] = c
                .clone()
                .try_into()
                .map_err(|_| "corners needs exactly 4 points")?;
            Geometry::Patches(vec![SurfacePatch {
                patch: Patch::Bilinear { p: c.map(v3) },
                tex: TexMap::default(),
            }])
        }
        "mountain" => Geometry::Mesh(mesh::mountain(
            mountain_levels(o),
            o.size.unwrap_or(6.0),
            o.sigma.unwrap_or(1.0),
            o.h.unwrap_or(0.8),
            o.seed.unwrap_or(1),
        )),
        "menger" => {
            let step = o.step.unwrap_or(3);
            if step > menger::MAX_STEP {
                return Err(format!(
                    "step {step} is too deep: expected 0 to {} (step {} has {} cubes)",
                    menger::MAX_STEP,
                    menger::MAX_STEP,
                    menger::numbers(menger::MAX_STEP).cubes
                ));
            }
            let size = o.size.unwrap_or(2.0);
            if !(size > 0.0 && size <= 1e6) {
                return Err(format!("size {size} must be between 0 and 1e6"));
            }
            Geometry::Mesh(menger::mesh(step, size))
        }
        "quaternion_julia" | "qjulia" => {
            let d = QuaternionJulia::default();
            let c = match o.c.as_deref() {
                None => d.c,
                Some([re, im]) => [*re, *im, 0.0, 0.0],
                Some([a, b, c, e]) => [*a, *b, *c, *e],
                Some(v) => {
                    return Err(format!(
                        "c has {} numbers: expected [c0, c1, c2, c3] (or [re, im])",
                        v.len()
                    ));
                }
            };
            let slice = match o.slice.as_deref() {
                None => d.slice,
                Some(n) => SliceAxis::from_name(n).ok_or_else(|| {
                    format!(
                        "slice '{n}': expected the fixed component \"1\", \"i\", \"j\" or \"k\""
                    )
                })?,
            };
            let j = QuaternionJulia {
                c,
                slice,
                slice_value: o.slice_value.unwrap_or(d.slice_value),
                iterations: o.iterations.unwrap_or(d.iterations),
            };
            j.validate()?;
            Geometry::QuaternionJulia(j)
        }
        other => {
            return Err(format!(
                "unknown object kind '{other}': expected jug, teapot, revolve, tube, bezier, bilinear, mountain, menger or quaternion_julia"
            ));
        }
    })
}

/// The first bare `nan`/`inf` value of a TOML text (TOML allows them; no scene setting
/// does): its byte offset and spelling. Strings and comments are skipped.
fn non_finite_value(text: &str) -> Option<(usize, &str)> {
    const BAD: [&str; 6] = ["nan", "+nan", "-nan", "inf", "+inf", "-inf"];
    let b = text.as_bytes();
    let mut i = 0;
    // After '=', '[' or ',' a value may start.
    let mut value_pos = false;
    while i < b.len() {
        match b[i] {
            b'#' => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            q @ (b'"' | b'\'') => {
                i += 1;
                while i < b.len() && b[i] != q {
                    if q == b'"' && b[i] == b'\\' {
                        i += 1;
                    }
                    i += 1;
                }
                i += 1;
                value_pos = false;
            }
            b'=' | b'[' | b',' => {
                value_pos = true;
                i += 1;
            }
            b'{' | b'}' | b']' => {
                value_pos = false;
                i += 1;
            }
            c if c.is_ascii_whitespace() => i += 1,
            _ => {
                let start = i;
                while i < b.len()
                    && !b[i].is_ascii_whitespace()
                    && !matches!(b[i], b',' | b']' | b'}' | b'=' | b'[' | b'{' | b'#')
                {
                    i += 1;
                }
                let tok = &text[start..i];
                if value_pos && BAD.contains(&tok) {
                    return Some((start, tok));
                }
                value_pos = false;
            }
        }
    }
    None
}

/// Parse a scene. `base` is the directory for relative files.
pub fn parse(text: &str, name: &str, base: &Path) -> Result<LoadedScene, Diagnostic> {
    let map = SourceMap::new(text);
    let at = |span: Option<std::ops::Range<usize>>| span.map_or(Pos::File, |s| map.pos(s.start));
    // Counted before the text is turned into values, which would take memory per entry.
    for (header, what, max) in [
        ("[[object]]", "objects", MAX_OBJECTS),
        ("[[texture]]", "textures", MAX_TEXTURES),
        ("[[light]]", "lights", MAX_LIGHTS),
    ] {
        let mut n = 0;
        for (off, line) in super::diag::lines(text) {
            if line.trim_start().starts_with(header) {
                n += 1;
                if n > max {
                    return Err(Diagnostic::error(
                        name,
                        map.pos(off),
                        "SCN007",
                        format!("more than {max} {what}; a scene holds at most {max}"),
                    ));
                }
            }
        }
    }
    let spec: SceneSpec = toml::from_str(text)
        .map_err(|e| Diagnostic::error(name, at(e.span()), "SCN001", e.message().to_string()))?;
    if let Some((off, tok)) = non_finite_value(text) {
        return Err(Diagnostic::error(
            name,
            map.pos(off),
            "SCN001",
            format!("'{tok}' is not a finite number; expected a number"),
        ));
    }
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
    let img = spec.image.unwrap_or_default();
    if let Some([w, h]) = img.size {
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
    if let Some(b) = img.background {
        scene.background = c3(b);
    }
    let mut warnings = Vec::new();
    let ss = img.supersample.unwrap_or(1);
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
    let cam = spec.camera.unwrap_or_default();
    let d = Camera::default();
    scene.camera = Camera {
        target: cam.target.map_or(d.target, v3),
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
    if !(scene.camera.distance > 0.0 && scene.camera.scale > 0.0) {
        return Err(Diagnostic::error(
            name,
            Pos::File,
            "SCN002",
            "camera distance and scale must be positive",
        ));
    }
    let l = spec.lighting.unwrap_or_default();
    scene.ambient = l.ambient.unwrap_or(1.0);
    scene.attenuation_k = l.attenuation.unwrap_or(1.0);
    scene.blinn = l.blinn.unwrap_or(false);
    let count_limit = |what: &str, n: usize, max: usize| {
        if n > max {
            Err(Diagnostic::error(
                name,
                Pos::File,
                "SCN007",
                format!("{n} {what}; a scene holds at most {max}"),
            ))
        } else {
            Ok(())
        }
    };
    count_limit(
        "lights",
        spec.light.as_ref().map_or(0, Vec::len),
        MAX_LIGHTS,
    )?;
    count_limit(
        "textures",
        spec.texture.as_ref().map_or(0, Vec::len),
        MAX_TEXTURES,
    )?;
    count_limit(
        "objects",
        spec.object.as_ref().map_or(0, Vec::len),
        MAX_OBJECTS,
    )?;
    // Textures and mountain meshes are made while loading: their memory is checked before
    // each is made, against what the system allows.
    let budget = crate::memory::budget();
    let mut loaded_bytes: u64 = 0;
    let mut reserve = |bytes: u64, what: &dyn Fn() -> String| -> Result<(), String> {
        loaded_bytes = loaded_bytes.saturating_add(bytes);
        if loaded_bytes > budget.bytes {
            return Err(crate::memory::MemoryError {
                what: what(),
                need: loaded_bytes,
                budget,
                hint: "use smaller or fewer textures and mountains".into(),
            }
            .to_string());
        }
        Ok(())
    };
    if let Some(lights) = spec.light {
        scene.lights = lights
            .iter()
            .map(|l| Light {
                position: v3(l.position),
                intensity: match l.intensity {
                    None => Vec3::splat(8.0),
                    Some(Intensity::Grey(g)) => Vec3::splat(g as f32),
                    Some(Intensity::Rgb(c)) => c3(c),
                },
            })
            .collect();
    }
    let mut texture_names = Vec::new();
    for t in spec.texture.unwrap_or_default() {
        let pos = at(Some(t.span()));
        let t = t.into_inner();
        if texture_names.contains(&t.name) {
            return Err(Diagnostic::error(
                name,
                pos,
                "SCN003",
                format!("texture '{}' is defined twice", t.name),
            ));
        }
        let tex_err = |m: String| {
            Diagnostic::error(
                name,
                pos.clone(),
                "SCN004",
                format!("texture '{}': {m}", t.name),
            )
        };
        reserve(texture_need(&t), &|| {
            format!("the scene's textures up to '{}'", t.name)
        })
        .map_err(tex_err)?;
        let mut warn = Vec::new();
        let tex = make_texture(&t, base, &mut warn).map_err(tex_err)?;
        warnings.extend(warn.into_iter().map(|m| {
            Diagnostic::warning(
                name,
                pos.clone(),
                "SCN006",
                format!("texture '{}': {m}", t.name),
            )
        }));
        scene.textures.push(tex);
        texture_names.push(t.name);
    }
    let mut notes = Vec::new();
    let mut patches = 0usize;
    for (k, o) in spec.object.unwrap_or_default().into_iter().enumerate() {
        let pos = at(Some(o.span()));
        let o = o.into_inner();
        let label = o
            .name
            .clone()
            .unwrap_or_else(|| format!("{} {}", o.kind, k + 1));
        let err = |m: String| {
            Diagnostic::error(
                name,
                pos.clone(),
                "SCN005",
                format!("object '{label}': {m}"),
            )
        };
        let find = |n: &Option<String>| -> Result<Option<usize>, Diagnostic> {
            match n {
                None => Ok(None),
                Some(n) => texture_names
                    .iter()
                    .position(|x| x == n)
                    .map(Some)
                    .ok_or_else(|| err(format!("no texture named '{n}'"))),
            }
        };
        let m = o.material.as_ref();
        let dm = Material::default();
        let material = Material {
            ka: m.and_then(|m| m.ka).unwrap_or(dm.ka),
            kd: m.and_then(|m| m.kd).unwrap_or(dm.kd),
            ks: m.and_then(|m| m.ks).unwrap_or(dm.ks),
            shininess: m.and_then(|m| m.n).unwrap_or(dm.shininess),
            color: m.and_then(|m| m.color).map_or(dm.color, c3),
            two_sided: m.and_then(|m| m.two_sided).unwrap_or(dm.two_sided),
            bump: m.and_then(|m| m.bump).unwrap_or(0.0),
        };
        if o.kind == "menger" {
            let k = menger::numbers(o.step.unwrap_or(3).min(menger::MAX_STEP));
            notes.push(format!(
                "{label}: Menger sponge step {}: {} cubes of side 3^-{} = {:.6}, volume {:.6}, area {:.6} (unit cube), dimension ln 20/ln 3 = {:.5}",
                k.step, k.cubes, k.step, k.side, k.volume, k.area, k.dimension
            ));
        }
        if o.kind == "mountain" {
            let levels = o.levels.unwrap_or(7);
            if !(1..=10).contains(&levels) {
                warnings.push(Diagnostic::warning(
                    name,
                    pos.clone(),
                    "SCN006",
                    format!(
                        "object '{label}': levels {levels} is outside 1..10; using {}",
                        mountain_levels(&o)
                    ),
                ));
            }
            reserve(mountain_bytes(mountain_levels(&o)), &|| {
                format!("the scene's meshes up to object '{label}'")
            })
            .map_err(err)?;
        }
        let geometry = make_geometry(&o).map_err(err)?;
        if let Geometry::Patches(p) = &geometry {
            patches += p.len();
            if patches > MAX_PATCHES {
                return Err(Diagnostic::error(
                    name,
                    pos.clone(),
                    "SCN007",
                    format!(
                        "object '{label}' brings the scene to more than {MAX_PATCHES} patches, the most a scene holds"
                    ),
                ));
            }
        }
        scene.objects.push(Object {
            name: label.clone(),
            geometry,
            transform: make_transform(o.transform.as_deref().unwrap_or(&[])).map_err(err)?,
            material,
            texture: find(&o.texture)?,
            bump_texture: find(&o.bump_texture)?,
        });
    }
    Ok(LoadedScene {
        scene,
        texture_names,
        notes,
        warnings,
    })
}

/// Read a scene file.
pub fn read(path: &Path) -> Result<LoadedScene, Diagnostic> {
    let name = path.display().to_string();
    let bytes = super::read_bytes(path)?;
    let (text, _) = super::diag::decode_text(&bytes, &name);
    parse(&text, &name, path.parent().unwrap_or(Path::new(".")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_a_full_scene() {
        let text = r#"
[image]
size = [320, 240]
background = [0.1, 0.1, 0.1]
[camera]
target = [0, 1, 0]
distance = 6
azimuth = 20
polar = 70
projection = "isometric"
[lighting]
ambient = 0.8
[[light]]
position = [1, 5, 5]
intensity = [4, 4, 3]
[[texture]]
name = "noise"
kind = "fbm"
size = [64, 64]
[[texture]]
name = "cells"
kind = "mrf"
size = [32, 32]
sweeps = 5
[[object]]
kind = "jug"
texture = "noise"
material = { ks = 0.5, n = 40, bump = 0.01 }
transform = [{ rotate_y = 30 }, { translate = [0, 0.1, 0] }]
[[object]]
kind = "bezier"
degree = [1, 1]
net = [[0,0,0],[0,0,1],[1,0,0],[1,0,1]]
texture = "cells"
"#;
        let s = parse(text, "t.toml", Path::new(".")).unwrap();
        assert_eq!(s.scene.objects.len(), 2);
        assert_eq!(s.texture_names, vec!["noise", "cells"]);
        assert_eq!((s.scene.width, s.scene.height), (320, 240));
        assert!(matches!(
            s.scene.camera.projection,
            Projection::Axonometric { .. }
        ));
        assert_eq!(s.scene.objects[0].material.shininess, 40.0);
        assert_eq!(s.scene.lights[0].intensity, Vec3::new(4.0, 4.0, 3.0));
    }

    #[test]
    fn parses_ray_casting_menger_and_quaternion_julia() {
        let text = r#"
render = "raycast"
shadows = false
[[object]]
kind = "menger"
step = 2
size = 3
[[object]]
kind = "quaternion_julia"
c = [-0.2, 0.8, 0.1, 0.0]
slice = "j"
slice_value = 0.25
iterations = 9
[[object]]
kind = "qjulia"
c = [-1, 0.2]
"#;
        let s = parse(text, "t.toml", Path::new(".")).unwrap().scene;
        assert_eq!(s.renderer, Renderer::RayCast);
        assert!(!s.shadows);
        let Geometry::Mesh(m) = &s.objects[0].geometry else {
            panic!("menger is a mesh")
        };
        // Edge 3: the corners lie at ±1.5.
        let max = m
            .positions
            .iter()
            .map(|p| p.abs().max_element())
            .fold(0.0, f64::max);
        assert_eq!(max, 1.5);
        let Geometry::QuaternionJulia(j) = &s.objects[1].geometry else {
            panic!("quaternion julia")
        };
        assert_eq!(j.c, [-0.2, 0.8, 0.1, 0.0]);
        assert_eq!(
            (j.slice, j.slice_value, j.iterations),
            (SliceAxis::J, 0.25, 9)
        );
        let Geometry::QuaternionJulia(j) = &s.objects[2].geometry else {
            panic!("quaternion julia")
        };
        assert_eq!(j.c, [-1.0, 0.2, 0.0, 0.0]);
        // Defaults: the z-buffer, shadows on for when ray casting is chosen.
        let d = parse("", "d.toml", Path::new(".")).unwrap().scene;
        assert_eq!((d.renderer, d.shadows), (Renderer::ZBuffer, true));
        // A bad render value points at its line.
        let e = parse("\nrender = 3\n", "s.toml", Path::new("."))
            .err()
            .unwrap();
        assert_eq!(e.code, "SCN001");
        let e = parse("\n\nrender = \"x\"\n", "s.toml", Path::new("."))
            .err()
            .unwrap();
        assert_eq!(e.pos, Pos::LineCol(3, 10), "{e}");
    }

    #[test]
    fn bad_scenes_say_where_and_what() {
        for (text, code, want) in [
            ("[image]\nsize = [0, 10]\n", "SCN002", "size"),
            (
                "[[object]]\nkind = \"blob\"\n",
                "SCN005",
                "unknown object kind",
            ),
            (
                "[[object]]\nkind = \"jug\"\ntexture = \"nope\"\n",
                "SCN005",
                "no texture named",
            ),
            (
                "[[texture]]\nname = \"a\"\nkind = \"image\"\nfile = \"missing.png\"\n",
                "SCN004",
                "does not exist",
            ),
            (
                "[camera]\nprojection = \"fisheye\"\n",
                "SCN002",
                "projection",
            ),
            (
                "[[object]]\nkind = \"revolve\"\nprofile = [[0,0],[1,1]]\n",
                "SCN005",
                "3k + 1",
            ),
            ("[image]\nsize = [10, 10\n", "SCN001", ""),
            ("[image]\nbackground = [0, -inf, 0]\n", "SCN001", "'-inf'"),
            (
                "# nan = inf\n[[light]]\nposition = [1, 2, 3]\nintensity = nan\n",
                "SCN001",
                "'nan'",
            ),
            ("[image]\nsizes = [10, 10]\n", "SCN001", "sizes"),
            (
                "render = \"pathtrace\"\n",
                "SCN002",
                "expected \"zbuffer\" or \"raycast\"",
            ),
            ("shadows = true\n", "SCN002", "needs render = \"raycast\""),
            (
                "[[object]]\nkind = \"menger\"\nstep = 5\n",
                "SCN005",
                "step 5 is too deep: expected 0 to 4",
            ),
            (
                "[[object]]\nkind = \"menger\"\nsize = -1\n",
                "SCN005",
                "size -1",
            ),
            (
                "[[object]]\nkind = \"quaternion_julia\"\nc = [1, 2, 3]\n",
                "SCN005",
                "c has 3 numbers",
            ),
            (
                "[[object]]\nkind = \"qjulia\"\niterations = 0\n",
                "SCN005",
                "iterations 0 must be between 1 and 200",
            ),
            (
                "[[object]]\nkind = \"qjulia\"\nslice = \"w\"\n",
                "SCN005",
                "slice 'w'",
            ),
            (
                "[[object]]\nkind = \"qjulia\"\nc = [9, 0]\n",
                "SCN005",
                "|c| = 9",
            ),
        ] {
            let e = parse(text, "s.toml", Path::new("/nonexistent"))
                .err()
                .unwrap_or_else(|| panic!("{text}"));
            assert_eq!(e.code, code, "{text}: {e}");
            assert!(e.to_string().contains(want), "{text}: {e}");
            assert!(e.to_string().contains("s.toml"));
        }
        let e = parse("[image]\n\nsize = \"big\"\n", "s.toml", Path::new("."))
            .err()
            .unwrap();
        assert_eq!(e.pos, Pos::LineCol(3, 8), "{e}");
    }
}
