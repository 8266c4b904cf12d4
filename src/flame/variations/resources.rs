//! Images and meshes that variations take from files (JWildfire's resources, e.g.
//! `colormap_wf`'s `image_filename`, `obj_mesh_wf`'s `obj_filename`), handed over by the file
//! readers: the engine reads no file itself. A reader that finds such a file decodes it and
//! stores it here under the name the flame gives it ([`put_image`], [`put_mesh`]); the
//! variation's shared data is then built from the stored resource, or from the variation's
//! default when none is stored under that name.
//!
//! At most [`MAX_IMAGES`] meshes are kept, and images of at most [`MAX_IMAGES`] ×
//! [`MAX_IMAGE_PIXELS`] pixels together, no more than [`MAX_IMAGE_COUNT`] of them (the oldest
//! stored is dropped first: as many small images, such as `wangtiles`' 32 × 32 tiles, fit as
//! 16 of the largest), each image of at most [`MAX_IMAGE_PIXELS`] pixels, each mesh of at
//! most [`MAX_MESH_FACES`] triangles.

use std::sync::{Arc, LazyLock, Mutex};

/// Most meshes kept, and most images of the largest size.
pub const MAX_IMAGES: usize = 16;

/// Most images kept, whatever their size.
pub const MAX_IMAGE_COUNT: usize = 4096;

/// Most pixels of a stored image (2048 × 2048): a variation keeps 8 bytes per pixel.
pub const MAX_IMAGE_PIXELS: usize = 2048 * 2048;

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

/// The mesh stored under `name`.
pub fn mesh(name: &str) -> Option<Arc<ResourceMesh>> {
    let v = MESHES.lock().unwrap_or_else(|e| e.into_inner());
    v.iter().find(|(k, _)| k == name).map(|(_, m)| m.clone())
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
    let mut pixels: usize = v.iter().map(|(_, i)| i.rgba.len()).sum();
    while !v.is_empty()
        && (v.len() >= MAX_IMAGE_COUNT || pixels + n > MAX_IMAGES * MAX_IMAGE_PIXELS)
    {
        pixels -= v.remove(0).1.rgba.len();
    }
    v.push((name.to_string(), Arc::new(img)));
    true
}

/// The image stored under `name`.
pub fn image(name: &str) -> Option<Arc<ResourceImage>> {
    let v = IMAGES.lock().unwrap_or_else(|e| e.into_inner());
    v.iter().find(|(k, _)| k == name).map(|(_, i)| i.clone())
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

    /// Small images are kept by the hundred (the store's pixel budget holds 16 of the
    /// largest; other tests' images may be in the store too, and all are small).
    #[test]
    fn many_small_images_are_kept() {
        let tile = ResourceImage {
            w: 32,
            h: 32,
            rgba: vec![[9, 8, 7, 255]; 32 * 32],
        };
        let name = |i: usize| format!("resources-test-small-{i}");
        for i in 0..300 {
            assert!(put_image(&name(i), tile.clone()));
        }
        assert!((0..300).all(|i| image(&name(i)).is_some()));
    }
}
