//! Scene files (`.toml`, documented in README): image, camera, lights, textures and objects of
//! a textured Bézier scene. Paths inside are relative to the scene file. Codes SCN001–SCN007.
//!
//! Parsing makes nothing: it checks the file, reads the files it names (pictures, flames,
//! escape-time views, gradients) and gives the engine's description of the scene
//! ([`ParsedScene`], [`SceneSpec`]); the textures (flame and escape-time renders, procedural
//! textures) and meshes are made by the engine when the scene is built
//! ([`ParsedScene::build`]). [`read`] and [`parse`] do both.
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

use std::ops::Range;
use std::path::Path;

use super::diag::{Diagnostic, Pos, SourceMap};
use crate::memory::{Budget, MemoryError};
use crate::surface::menger;
use crate::surface::{Geometry, GeometrySpec, ObjectSpec, Scene, SceneSpec, TextureSpec};

mod format;
mod objects;
mod settings;
#[cfg(test)]
mod tests;
mod textures;

pub use textures::texture_bytes;

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

/// A loaded scene with the names of its textures (by index).
pub struct LoadedScene {
    /// The scene, ready to render.
    pub scene: Scene,
    /// The name of each texture (by index), for messages.
    pub texture_names: Vec<String>,
    /// One line per generated object worth describing (e.g. a Menger sponge's numbers).
    pub notes: Vec<String>,
    /// Values that were changed to fit (clamped) and other remarks.
    pub warnings: Vec<Diagnostic>,
}

/// A parsed scene file: what the engine is to make, with the names and places of its
/// textures for messages. Nothing is rendered yet.
pub struct ParsedScene {
    /// The scene before its textures and meshes are made.
    pub spec: SceneSpec,
    /// The name of each texture (by index), for messages.
    pub texture_names: Vec<String>,
    /// One line per generated object worth describing (e.g. a Menger sponge's numbers).
    pub notes: Vec<String>,
    /// Values that were changed to fit (clamped) and other remarks.
    pub warnings: Vec<Diagnostic>,
    /// The files the scene reads (its textures' pictures, flames and views), as named
    /// from the scene's directory: a command writing beside them checks it replaces none.
    pub files: Vec<std::path::PathBuf>,
    /// The file's name and where each texture is defined in it.
    name: String,
    texture_pos: Vec<Pos>,
}

impl ParsedScene {
    /// Make the textures and meshes (the engine's [`SceneSpec::build`]): the scene ready to
    /// render. A texture that cannot be made is reported at its place in the file (SCN004).
    pub fn build(self) -> Result<LoadedScene, Diagnostic> {
        let ParsedScene {
            spec,
            texture_names,
            notes,
            warnings,
            name,
            texture_pos,
            ..
        } = self;
        let scene = spec.build().map_err(|e| {
            Diagnostic::error(
                &name,
                texture_pos[e.index].clone(),
                "SCN004",
                format!("texture '{}': {}", texture_names[e.index], e.message),
            )
        })?;
        Ok(LoadedScene {
            scene,
            texture_names,
            notes,
            warnings,
        })
    }
}

/// The memory the scene's textures and meshes will take, added up as they are described and
/// checked against what the system allows before anything is made.
struct Reservation {
    budget: Budget,
    bytes: u64,
}

impl Reservation {
    fn new() -> Reservation {
        Reservation {
            budget: crate::memory::budget(),
            bytes: 0,
        }
    }

    /// Add `bytes`; refused when the total is over the budget (`what` names it).
    fn add(&mut self, bytes: u64, what: &dyn Fn() -> String) -> Result<(), String> {
        self.bytes = self.bytes.saturating_add(bytes);
        if self.bytes > self.budget.bytes {
            return Err(MemoryError {
                what: what(),
                need: self.bytes,
                budget: self.budget,
                hint: "use smaller or fewer textures and mountains".into(),
            }
            .to_string());
        }
        Ok(())
    }
}

/// Refuse more than the most objects, textures or lights by counting their headers, before
/// the text is turned into values (which would take memory per entry).
fn count_headers(text: &str, name: &str, map: &SourceMap) -> Result<(), Diagnostic> {
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
    Ok(())
}

/// Refuse more lights, textures or objects than a scene holds (however they were written).
fn count_limits(spec: &format::SceneSpec, name: &str) -> Result<(), Diagnostic> {
    for (what, n, max) in [
        (
            "lights",
            spec.light.as_ref().map_or(0, Vec::len),
            MAX_LIGHTS,
        ),
        (
            "textures",
            spec.texture.as_ref().map_or(0, Vec::len),
            MAX_TEXTURES,
        ),
        (
            "objects",
            spec.object.as_ref().map_or(0, Vec::len),
            MAX_OBJECTS,
        ),
    ] {
        if n > max {
            return Err(Diagnostic::error(
                name,
                Pos::File,
                "SCN007",
                format!("{n} {what}; a scene holds at most {max}"),
            ));
        }
    }
    Ok(())
}

/// Parse a scene into what the engine is to make, without making it. `base` is the directory
/// for relative files (read here: pictures, flames, escape-time views, gradients).
pub fn parse_spec(text: &str, name: &str, base: &Path) -> Result<ParsedScene, Diagnostic> {
    let map = SourceMap::new(text);
    let at = |span: Option<Range<usize>>| span.map_or(Pos::File, |s| map.pos(s.start));
    count_headers(text, name, &map)?;
    let spec: format::SceneSpec = toml::from_str(text)
        .map_err(|e| Diagnostic::error(name, at(e.span()), "SCN001", e.message().to_string()))?;
    if let Some((off, tok)) = format::non_finite_value(text) {
        return Err(Diagnostic::error(
            name,
            map.pos(off),
            "SCN001",
            format!("'{tok}' is not a finite number; expected a number"),
        ));
    }
    let mut warnings = Vec::new();
    let scene = settings::scene(&spec, name, &at, &mut warnings)?;
    count_limits(&spec, name)?;
    let mut c = Collect {
        name,
        base,
        // Textures and mountain meshes are made when the scene is built: their memory is
        // checked here, before each is described, against what the system allows.
        reserve: Reservation::new(),
        warnings,
        texture_names: Vec::new(),
        texture_pos: Vec::new(),
        notes: Vec::new(),
        patches: 0,
    };
    let mut textures = Vec::new();
    let mut files = Vec::new();
    for t in spec.texture.unwrap_or_default() {
        let pos = at(Some(t.span()));
        let t = t.into_inner();
        files.extend(t.file.as_ref().map(|f| base.join(f)));
        textures.push(c.texture(t, pos)?);
    }
    let mut objects = Vec::new();
    for (k, o) in spec.object.unwrap_or_default().into_iter().enumerate() {
        let pos = at(Some(o.span()));
        objects.push(c.object(&o.into_inner(), k, pos)?);
    }
    Ok(ParsedScene {
        spec: SceneSpec {
            scene,
            textures,
            objects,
        },
        texture_names: c.texture_names,
        notes: c.notes,
        warnings: c.warnings,
        files,
        name: name.to_string(),
        texture_pos: c.texture_pos,
    })
}

/// What parsing the textures and objects of a scene file collects as it goes.
struct Collect<'a> {
    /// The file's name, and the directory of its relative files.
    name: &'a str,
    base: &'a Path,
    reserve: Reservation,
    warnings: Vec<Diagnostic>,
    /// The textures so far, by name and place in the file.
    texture_names: Vec<String>,
    texture_pos: Vec<Pos>,
    notes: Vec<String>,
    /// Bézier patches so far.
    patches: usize,
}

impl Collect<'_> {
    /// The texture table at `pos`: its name checked against the ones before, its memory
    /// reserved, then what to make (SCN003, SCN004; SCN006 for values changed to fit).
    fn texture(&mut self, t: format::TextureSpec, pos: Pos) -> Result<TextureSpec, Diagnostic> {
        let name = self.name;
        if self.texture_names.contains(&t.name) {
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
        self.reserve
            .add(textures::texture_need(&t), &|| {
                format!("the scene's textures up to '{}'", t.name)
            })
            .map_err(tex_err)?;
        let mut warn = Vec::new();
        let tex = textures::texture_spec(&t, self.base, &mut warn).map_err(tex_err)?;
        self.warnings.extend(warn.into_iter().map(|m| {
            Diagnostic::warning(
                name,
                pos.clone(),
                "SCN006",
                format!("texture '{}': {m}", t.name),
            )
        }));
        self.texture_names.push(t.name);
        self.texture_pos.push(pos);
        Ok(tex)
    }

    /// The `k`-th object table, at `pos`: a mountain's memory reserved, its geometry, the
    /// scene's patches counted, its transform, material and textures (SCN005, SCN007; SCN006
    /// for values changed to fit).
    fn object(
        &mut self,
        o: &format::ObjectSpec,
        k: usize,
        pos: Pos,
    ) -> Result<ObjectSpec, Diagnostic> {
        let name = self.name;
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
        if o.kind == "menger" {
            self.notes.push(menger_note(&label, o.step));
        }
        if o.kind == "mountain" {
            let levels = o.levels.unwrap_or(7);
            if !(1..=10).contains(&levels) {
                self.warnings.push(Diagnostic::warning(
                    name,
                    pos.clone(),
                    "SCN006",
                    format!(
                        "object '{label}': levels {levels} is outside 1..10; using {}",
                        objects::mountain_levels(o)
                    ),
                ));
            }
            self.reserve
                .add(
                    objects::mountain_bytes(objects::mountain_levels(o)),
                    &|| format!("the scene's meshes up to object '{label}'"),
                )
                .map_err(err)?;
        }
        let geometry = objects::geometry_spec(o).map_err(err)?;
        if let GeometrySpec::Given(Geometry::Patches(p)) = &geometry {
            self.patches += p.len();
            if self.patches > MAX_PATCHES {
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
        let transform =
            objects::make_transform(o.transform.as_deref().unwrap_or(&[])).map_err(err)?;
        let find = |n: &Option<String>| -> Result<Option<usize>, Diagnostic> {
            match n {
                None => Ok(None),
                Some(n) => self
                    .texture_names
                    .iter()
                    .position(|x| x == n)
                    .map(Some)
                    .ok_or_else(|| err(format!("no texture named '{n}'"))),
            }
        };
        Ok(ObjectSpec {
            geometry,
            transform,
            material: objects::material(o.material.as_ref()),
            texture: find(&o.texture)?,
            bump_texture: find(&o.bump_texture)?,
            name: label.clone(),
        })
    }
}

/// The numbers of a Menger sponge object.
fn menger_note(label: &str, step: Option<u32>) -> String {
    let k = menger::numbers(step.unwrap_or(3).min(menger::MAX_STEP));
    format!(
        "{label}: Menger sponge step {}: {} cubes of side 3^-{} = {:.6}, volume {:.6}, area {:.6} (unit cube), dimension ln 20/ln 3 = {:.5}",
        k.step, k.cubes, k.step, k.side, k.volume, k.area, k.dimension
    )
}

/// Parse a scene and build it (textures and meshes made). `base` is the directory for
/// relative files.
pub fn parse(text: &str, name: &str, base: &Path) -> Result<LoadedScene, Diagnostic> {
    parse_spec(text, name, base)?.build()
}

/// Read a scene file into what the engine is to make, without making it.
pub fn read_spec(path: &Path) -> Result<ParsedScene, Diagnostic> {
    let name = path.display().to_string();
    let bytes = super::read_bytes(path)?;
    let (text, _) = super::diag::decode_text(&bytes, &name);
    parse_spec(&text, &name, path.parent().unwrap_or(Path::new(".")))
}

/// Read a scene file and build it (textures and meshes made).
pub fn read(path: &Path) -> Result<LoadedScene, Diagnostic> {
    read_spec(path)?.build()
}
