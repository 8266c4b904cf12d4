//! Images and meshes that variations take from files (JWildfire's resources, e.g.
//! `colormap_wf`'s `image_filename`, `obj_mesh_wf`'s `obj_filename`), handed over by the file
//! readers: the engine reads no file itself. A reader that finds such a file decodes it and
//! stores it here under the name the flame gives it ([`put_image`], [`put_mesh`]); the
//! variation's shared data is then built from the stored resource, or from the variation's
//! default when none is stored under that name.
//!
//! At most [`MAX_IMAGES`] images and as many meshes are kept (the oldest stored is dropped
//! first), each image of at most [`MAX_IMAGE_PIXELS`] pixels, each mesh of at most
//! [`MAX_MESH_FACES`] triangles.
//!
//! JWildfire's *own* resources (its brush images, wang tiles, primitive meshes, the default
//! drawing of `svg_wf`) are not part of ugnis. They are read on demand from the user's
//! JWildfire installation by a reader the file layer installs ([`set_jwildfire_reader`]),
//! under names that start with [`JWILDFIRE`] followed by the resource's path inside
//! JWildfire's jar; each is read once and kept.

use std::collections::HashMap;
use std::sync::{Arc, LazyLock, Mutex};

/// The prefix of the names of JWildfire's own resources: `jwildfire:` + the path of the
/// resource inside JWildfire's jar, e.g.
/// `jwildfire:org/jwildfire/create/tina/variation/mesh/cone.obj`.
pub const JWILDFIRE: &str = "jwildfire:";

/// One of JWildfire's own resources, decoded.
#[derive(Clone, Debug, PartialEq)]
pub enum Builtin {
    /// An image (PNG, GIF, …).
    Image(Arc<ResourceImage>),
    /// A mesh (Wavefront OBJ).
    Mesh(Arc<ResourceMesh>),
    /// A text: a text file, or the longest string constant of a compiled Java class.
    Text(Arc<String>),
}

impl Builtin {
    /// About how many bytes it holds.
    fn bytes(&self) -> usize {
        match self {
            Builtin::Image(i) => i.rgba.len() * 4,
            Builtin::Mesh(m) => m.vertices.len() * 12 + m.faces.len() * 12,
            Builtin::Text(t) => t.len(),
        }
    }
}

/// Reads one of JWildfire's resources by its path inside JWildfire's jar (without the
/// [`JWILDFIRE`] prefix): `None` when it has none of that path or it cannot be decoded.
pub type JwildfireReader = Box<dyn Fn(&str) -> Option<Builtin> + Send + Sync>;

/// The installed reader of JWildfire's resources.
static READER: Mutex<Option<Arc<JwildfireReader>>> = Mutex::new(None);

/// JWildfire's resources read so far by path (also those it does not have: `None`), and
/// their total bytes.
type Read = (HashMap<String, Option<Builtin>>, usize);

/// JWildfire's resources read so far.
static BUILTINS: LazyLock<Mutex<Read>> = LazyLock::new(|| Mutex::new((HashMap::new(), 0)));

/// Most bytes of JWildfire's resources kept; past it, a resource is read again when asked.
const MAX_BUILTIN_BYTES: usize = 512 << 20;

/// Install the reader of JWildfire's resources (or remove it with `None`); forgets what the
/// previous reader read.
pub fn set_jwildfire_reader(reader: Option<JwildfireReader>) {
    *READER.lock().unwrap_or_else(|e| e.into_inner()) = reader.map(Arc::new);
    let mut b = BUILTINS.lock().unwrap_or_else(|e| e.into_inner());
    *b = (HashMap::new(), 0);
    drop(b);
    // What those variations built from the previous reader's resources (or their stand-ins).
    super::shared::forget(|id| READERS.contains(&super::info(id).name));
}

/// The variations whose shared data is built from JWildfire's own resources.
const READERS: [&str; 5] = [
    "brush_stroke_wf",
    "obj_mesh_primitive_wf",
    "post_brush_stroke_wf",
    "svg_wf",
    "wangtiles",
];

/// Whether a reader of JWildfire's resources is installed.
pub fn has_jwildfire_reader() -> bool {
    READER.lock().unwrap_or_else(|e| e.into_inner()).is_some()
}

/// JWildfire's resource `name` (a name starting with [`JWILDFIRE`]), read on first use.
fn builtin(name: &str) -> Option<Builtin> {
    let path = name.strip_prefix(JWILDFIRE)?;
    if let Some(known) = BUILTINS
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .0
        .get(path)
    {
        return known.clone();
    }
    let reader = READER.lock().unwrap_or_else(|e| e.into_inner()).clone()?;
    let got = reader(path);
    let mut b = BUILTINS.lock().unwrap_or_else(|e| e.into_inner());
    let size = got.as_ref().map_or(0, |g| g.bytes());
    if b.1 + size <= MAX_BUILTIN_BYTES {
        b.1 += size;
        b.0.insert(path.to_string(), got.clone());
    }
    got
}

/// The text stored as JWildfire's resource `name` (a name starting with [`JWILDFIRE`]).
pub fn text(name: &str) -> Option<Arc<String>> {
    match builtin(name)? {
        Builtin::Text(t) => Some(t),
        _ => None,
    }
}

/// Most images kept.
pub const MAX_IMAGES: usize = 16;

/// Most pixels of a stored image (4096 × 2048, a photograph of 1920 × 2560 fits): a
/// variation keeps 8 bytes per pixel.
pub const MAX_IMAGE_PIXELS: usize = 4096 * 2048;

/// An image given to a variation: `w` × `h` pixels, rows from the top, each `[r, g, b, a]`.
#[derive(Clone, Debug, PartialEq)]
pub struct ResourceImage {
    /// Width in pixels.
    pub w: u32,
    /// Height in pixels.
    pub h: u32,
    /// The pixels, `w` × `h` of them.
    pub rgba: Vec<[u8; 4]>,
}

/// Most triangles of a stored mesh (and of a mesh after subdivision).
pub const MAX_MESH_FACES: usize = 500_000;

/// A mesh given to a variation: vertices and triangles (three indices into `vertices`).
#[derive(Clone, Debug, PartialEq)]
pub struct ResourceMesh {
    /// The vertices.
    pub vertices: Vec<[f32; 3]>,
    /// The triangles.
    pub faces: Vec<[u32; 3]>,
}

/// Named resources, oldest first.
type Store<T> = LazyLock<Mutex<Vec<(String, Arc<T>)>>>;

static MESHES: Store<ResourceMesh> = LazyLock::new(|| Mutex::new(Vec::new()));

/// Store `mesh` under `name` (replacing a mesh of that name). A mesh without triangles, with
/// more than [`MAX_MESH_FACES`] or with an index outside its vertices is not stored: returns
/// whether it was.
pub fn put_mesh(name: &str, mesh: ResourceMesh) -> bool {
    let n = mesh.vertices.len();
    let ok = !mesh.faces.is_empty()
        && mesh.faces.len() <= MAX_MESH_FACES
        && mesh.faces.iter().flatten().all(|&i| (i as usize) < n);
    if !ok {
        return false;
    }
    let mut v = MESHES.lock().unwrap_or_else(|e| e.into_inner());
    v.retain(|(k, _)| k != name);
    if v.len() >= MAX_IMAGES {
        v.remove(0);
    }
    v.push((name.to_string(), Arc::new(mesh)));
    true
}

/// The mesh stored under `name`, or JWildfire's own mesh of that name.
pub fn mesh(name: &str) -> Option<Arc<ResourceMesh>> {
    let v = MESHES.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, m)) = v.iter().find(|(k, _)| k == name) {
        return Some(m.clone());
    }
    drop(v);
    match builtin(name)? {
        Builtin::Mesh(m) => Some(m),
        _ => None,
    }
}

static IMAGES: Store<ResourceImage> = LazyLock::new(|| Mutex::new(Vec::new()));

/// Store `img` under `name` (replacing an image of that name). An image whose pixel count
/// does not match its size, or that is empty or larger than [`MAX_IMAGE_PIXELS`], is not
/// stored: returns whether it was.
pub fn put_image(name: &str, img: ResourceImage) -> bool {
    let n = img.w as usize * img.h as usize;
    if n == 0 || n > MAX_IMAGE_PIXELS || img.rgba.len() != n {
        return false;
    }
    let mut v = IMAGES.lock().unwrap_or_else(|e| e.into_inner());
    v.retain(|(k, _)| k != name);
    if v.len() >= MAX_IMAGES {
        v.remove(0);
    }
    v.push((name.to_string(), Arc::new(img)));
    true
}

/// The image stored under `name`, or JWildfire's own image of that name.
pub fn image(name: &str) -> Option<Arc<ResourceImage>> {
    let v = IMAGES.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, i)) = v.iter().find(|(k, _)| k == name) {
        return Some(i.clone());
    }
    drop(v);
    match builtin(name)? {
        Builtin::Image(i) => Some(i),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn images_are_stored_by_name_within_the_bounds() {
        let img = ResourceImage {
            w: 2,
            h: 1,
            rgba: vec![[1, 2, 3, 255], [4, 5, 6, 255]],
        };
        assert!(put_image("resources-test-a", img.clone()));
        assert_eq!(image("resources-test-a").as_deref(), Some(&img));
        let bad = ResourceImage {
            w: 3,
            h: 1,
            rgba: vec![[0; 4]; 2],
        };
        assert!(!put_image("resources-test-b", bad));
        assert!(image("resources-test-b").is_none());
    }

    #[test]
    fn jwildfire_resources_are_read_once_on_demand() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static CALLS: AtomicUsize = AtomicUsize::new(0);
        let img = ResourceImage {
            w: 1,
            h: 1,
            rgba: vec![[9, 8, 7, 255]],
        };
        let given = img.clone();
        set_jwildfire_reader(Some(Box::new(move |path| {
            CALLS.fetch_add(1, Ordering::SeqCst);
            match path {
                "resources-test/a.png" => Some(Builtin::Image(Arc::new(given.clone()))),
                "resources-test/t.class" => Some(Builtin::Text(Arc::new("svg".into()))),
                _ => None,
            }
        })));
        assert!(has_jwildfire_reader());
        let name = "jwildfire:resources-test/a.png";
        assert_eq!(image(name).as_deref(), Some(&img));
        assert_eq!(image(name).as_deref(), Some(&img));
        assert_eq!(CALLS.load(Ordering::SeqCst), 1, "read once, then kept");
        // A name without the prefix never reaches the reader; a path it lacks is None,
        // asked once; a resource of another kind is not an image.
        assert!(image("resources-test/a.png").is_none());
        assert!(image("jwildfire:resources-test/none.png").is_none());
        assert!(image("jwildfire:resources-test/none.png").is_none());
        assert_eq!(CALLS.load(Ordering::SeqCst), 2);
        assert!(mesh(name).is_none());
        assert_eq!(
            text("jwildfire:resources-test/t.class").as_deref(),
            Some(&"svg".to_string())
        );
        // A stored image of the same name comes first.
        let mine = ResourceImage {
            w: 1,
            h: 1,
            rgba: vec![[1, 1, 1, 255]],
        };
        assert!(put_image(name, mine.clone()));
        assert_eq!(image(name).as_deref(), Some(&mine));
        set_jwildfire_reader(None);
        assert!(!has_jwildfire_reader());
    }
}
