//! JWildfire's own resources, read from the user's JWildfire installation.
//!
//! Some of JWildfire's variations draw resources that ship inside JWildfire itself: the
//! brush images of `brush_stroke_wf`, the tiles of `wangtiles`, the meshes of
//! `obj_mesh_primitive_wf`, the default drawing of `svg_wf`. ugnis does not copy them. A user
//! who has JWildfire names its jar (`j-wildfire.jar`) or its unpacked resource folders in the
//! environment variable [`ENV`] (several paths separated as in `PATH`), and ugnis reads each
//! resource from there the first time a variation asks for it
//! ([`crate::flame::variations::resources`]).
//!
//! A jar is a zip archive: its central directory is read once (stored and deflated entries;
//! no zip64, no encryption), and an entry is inflated when it is asked for. A folder is looked
//! up by the resource's path below it. Images are decoded with the `image` crate, meshes as
//! Wavefront OBJ (as a flame's own mesh files), and a compiled Java class gives its longest
//! string constant (the default drawing of `svg_wf` is one).

use std::collections::HashMap;
use std::fs::File;
use std::io::{Read, Seek, SeekFrom};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use crate::flame::variations::resources::{self, Builtin};

/// The environment variable naming JWildfire's jar or resource folders.
pub const ENV: &str = "UGNIS_JWILDFIRE";

/// Largest resource read (bytes, before and after inflating).
const MAX_ENTRY: u64 = 64 << 20;

/// Most entries of a jar's directory.
const MAX_ENTRIES: usize = 200_000;

/// Where a zip entry's data is.
#[derive(Clone, Copy, Debug)]
struct Entry {
    /// 0 stored, 8 deflated.
    method: u16,
    /// Bytes in the archive.
    packed: u64,
    /// Bytes once inflated.
    size: u64,
    /// Offset of its local header.
    local: u64,
}

/// One place resources are read from.
enum Source {
    /// A folder: a resource's path is looked up below it.
    Dir(PathBuf),
    /// A jar (zip archive), its directory read.
    Jar {
        path: PathBuf,
        file: Mutex<File>,
        entries: HashMap<String, Entry>,
    },
}

/// A JWildfire installation: the jars and folders its resources are read from, in order.
pub struct Install {
    sources: Vec<Source>,
}

impl Install {
    /// Open the jars and folders `paths`; an error names the path and what is wrong with it.
    pub fn open(paths: &[PathBuf]) -> Result<Install, String> {
        let mut sources = Vec::new();
        for p in paths {
            if p.is_dir() {
                sources.push(Source::Dir(p.clone()));
            } else {
                let mut f = File::open(p).map_err(|e| format!("{}: {e}", p.display()))?;
                let entries = zip_directory(&mut f).map_err(|e| format!("{}: {e}", p.display()))?;
                sources.push(Source::Jar {
                    path: p.clone(),
                    file: Mutex::new(f),
                    entries,
                });
            }
        }
        if sources.is_empty() {
            return Err("no JWildfire jar or folder given".into());
        }
        Ok(Install { sources })
    }

    /// The bytes of the resource at `path` (inside the jar, `/`-separated), from the first
    /// source that has it; `Ok(None)` when none has it.
    pub fn bytes(&self, path: &str) -> Result<Option<Vec<u8>>, String> {
        let path = path.trim_start_matches('/');
        if path.split('/').any(|c| c == ".." || c.is_empty()) {
            return Ok(None);
        }
        for s in &self.sources {
            match s {
                Source::Dir(d) => {
                    let p = d.join(path);
                    if p.is_file() {
                        return crate::io::read_bytes_limited(&p, MAX_ENTRY)
                            .map(Some)
                            .map_err(|d| d.message);
                    }
                }
                Source::Jar {
                    path: jar,
                    file,
                    entries,
                } => {
                    if let Some(e) = entries.get(path) {
                        let mut f = file.lock().unwrap_or_else(|e| e.into_inner());
                        return zip_entry(&mut *f, e)
                            .map(Some)
                            .map_err(|why| format!("{} ({path}): {why}", jar.display()));
                    }
                }
            }
        }
        Ok(None)
    }

    /// The resource at `path`, decoded by its kind (image, mesh, class); `None` when no
    /// source has it or it cannot be decoded (reported on standard error once).
    pub fn resource(&self, path: &str) -> Option<Builtin> {
        let bytes = match self.bytes(path) {
            Ok(b) => b?,
            Err(e) => {
                eprintln!("warning: JWildfire resource {e}");
                return None;
            }
        };
        let ext = path.rsplit('.').next().unwrap_or("").to_ascii_lowercase();
        let got = match ext.as_str() {
            "obj" => crate::io::var_images::parse_obj(&String::from_utf8_lossy(&bytes))
                .map(|m| Builtin::Mesh(Arc::new(m))),
            "class" => longest_string_constant(&bytes)
                .map(|t| Builtin::Text(Arc::new(t)))
                .ok_or_else(|| "is not a Java class with a string constant".to_string()),
            "txt" | "svg" | "xml" => Ok(Builtin::Text(Arc::new(
                String::from_utf8_lossy(&bytes).into_owned(),
            ))),
            _ => crate::io::var_images::decode_image(&bytes).map(|i| Builtin::Image(Arc::new(i))),
        };
        match got {
            Ok(b) => Some(b),
            Err(why) => {
                eprintln!("warning: JWildfire resource {path} {why}");
                None
            }
        }
    }
}

/// The paths [`ENV`] names, if it is set and not empty.
pub fn paths_from_env() -> Option<Vec<PathBuf>> {
    let v = std::env::var_os(ENV)?;
    let paths: Vec<PathBuf> = std::env::split_paths(&v)
        .filter(|p| !p.as_os_str().is_empty())
        .collect();
    (!paths.is_empty()).then_some(paths)
}

/// Open the installation at `paths` and let the variations read JWildfire's resources from
/// it.
pub fn install(paths: &[PathBuf]) -> Result<(), String> {
    let inst = Install::open(paths)?;
    resources::set_jwildfire_reader(Some(Box::new(move |p| inst.resource(p))));
    Ok(())
}

/// Install the JWildfire installation [`ENV`] names, if it names one: `None` when it is not
/// set, else whether it could be opened.
pub fn install_from_env() -> Option<Result<(), String>> {
    let paths = paths_from_env()?;
    Some(install(&paths).map_err(|e| format!("{ENV}: {e}")))
}

/// Little-endian u16 at `at`.
fn le16(b: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_le_bytes(b.get(at..at + 2)?.try_into().ok()?))
}

/// Little-endian u32 at `at`.
fn le32(b: &[u8], at: usize) -> Option<u32> {
    Some(u32::from_le_bytes(b.get(at..at + 4)?.try_into().ok()?))
}

/// Read a zip archive's central directory: each file's name and where its data is.
fn zip_directory<R: Read + Seek>(f: &mut R) -> Result<HashMap<String, Entry>, String> {
    let bad = |what: &str| format!("not a zip archive (jar): {what}");
    let len = f.seek(SeekFrom::End(0)).map_err(|e| e.to_string())?;
    // The end record: 22 bytes and a comment of up to 65,535 bytes, at the end.
    let tail_len = len.min(22 + 65_535);
    let mut tail = vec![0u8; tail_len as usize];
    f.seek(SeekFrom::Start(len - tail_len))
        .and_then(|_| f.read_exact(&mut tail))
        .map_err(|e| e.to_string())?;
    let end = (0..tail.len().saturating_sub(21))
        .rev()
        .find(|&i| le32(&tail, i) == Some(0x0605_4b50))
        .ok_or_else(|| bad("no end of central directory"))?;
    let count = le16(&tail, end + 10).ok_or_else(|| bad("short end record"))? as usize;
    let dir_size = le32(&tail, end + 12).ok_or_else(|| bad("short end record"))?;
    let dir_at = le32(&tail, end + 16).ok_or_else(|| bad("short end record"))?;
    if count == 0xFFFF || dir_size == u32::MAX || dir_at == u32::MAX {
        return Err("a zip64 archive, which is not read".into());
    }
    if count > MAX_ENTRIES {
        return Err(format!("more than {MAX_ENTRIES} entries"));
    }
    if u64::from(dir_at) + u64::from(dir_size) > len {
        return Err(bad("central directory past the end"));
    }
    let mut dir = vec![0u8; dir_size as usize];
    f.seek(SeekFrom::Start(u64::from(dir_at)))
        .and_then(|_| f.read_exact(&mut dir))
        .map_err(|e| e.to_string())?;
    let mut entries = HashMap::with_capacity(count);
    let mut at = 0usize;
    for _ in 0..count {
        let short = || bad("short central directory");
        if le32(&dir, at) != Some(0x0201_4b50) {
            return Err(bad("bad central directory entry"));
        }
        let flags = le16(&dir, at + 8).ok_or_else(short)?;
        let method = le16(&dir, at + 10).ok_or_else(short)?;
        let packed = le32(&dir, at + 20).ok_or_else(short)?;
        let size = le32(&dir, at + 24).ok_or_else(short)?;
        let name_len = le16(&dir, at + 28).ok_or_else(short)? as usize;
        let extra_len = le16(&dir, at + 30).ok_or_else(short)? as usize;
        let comment_len = le16(&dir, at + 32).ok_or_else(short)? as usize;
        let local = le32(&dir, at + 42).ok_or_else(short)?;
        let name = dir.get(at + 46..at + 46 + name_len).ok_or_else(short)?;
        let name = String::from_utf8_lossy(name).into_owned();
        at += 46 + name_len + extra_len + comment_len;
        // Encrypted entries and folders are left out.
        if flags & 1 == 0 && !name.ends_with('/') {
            entries.insert(
                name,
                Entry {
                    method,
                    packed: u64::from(packed),
                    size: u64::from(size),
                    local: u64::from(local),
                },
            );
        }
    }
    Ok(entries)
}

/// The bytes of one zip entry, inflated.
fn zip_entry<R: Read + Seek>(f: &mut R, e: &Entry) -> Result<Vec<u8>, String> {
    if e.size > MAX_ENTRY || e.packed > MAX_ENTRY {
        return Err(format!("larger than {MAX_ENTRY} bytes"));
    }
    let mut head = [0u8; 30];
    f.seek(SeekFrom::Start(e.local))
        .and_then(|_| f.read_exact(&mut head))
        .map_err(|e| e.to_string())?;
    if le32(&head, 0) != Some(0x0403_4b50) {
        return Err("bad local header".into());
    }
    let skip = u64::from(le16(&head, 26).unwrap_or(0)) + u64::from(le16(&head, 28).unwrap_or(0));
    let mut packed = vec![0u8; e.packed as usize];
    f.seek(SeekFrom::Start(e.local + 30 + skip))
        .and_then(|_| f.read_exact(&mut packed))
        .map_err(|e| e.to_string())?;
    match e.method {
        0 => Ok(packed),
        8 => miniz_oxide::inflate::decompress_to_vec_with_limit(&packed, e.size as usize)
            .map_err(|e| format!("cannot be inflated: {e}")),
        m => Err(format!("compressed with method {m}, which is not read")),
    }
}

/// The longest string constant of a compiled Java class (its constant pool's longest UTF-8
/// entry, decoded from Java's modified UTF-8); `None` when `b` is not a class file.
pub fn longest_string_constant(b: &[u8]) -> Option<String> {
    let be16 = |at: usize| Some(u16::from_be_bytes(b.get(at..at + 2)?.try_into().ok()?));
    if b.get(0..4)? != [0xCA, 0xFE, 0xBA, 0xBE] {
        return None;
    }
    let count = be16(8)? as usize;
    let mut at = 10;
    let mut best: Option<&[u8]> = None;
    let mut i = 1;
    while i < count {
        let tag = *b.get(at)?;
        at += 1;
        let len = match tag {
            1 => {
                let n = be16(at)? as usize;
                let s = b.get(at + 2..at + 2 + n)?;
                if best.is_none_or(|x| s.len() > x.len()) {
                    best = Some(s);
                }
                2 + n
            }
            3 | 4 | 9 | 10 | 11 | 12 | 17 | 18 => 4,
            5 | 6 => {
                // Longs and doubles take two slots.
                i += 1;
                8
            }
            7 | 8 | 16 | 19 | 20 => 2,
            15 => 3,
            _ => return None,
        };
        at += len;
        i += 1;
    }
    best.map(modified_utf8)
}

/// Decode Java's modified UTF-8: one to three bytes per UTF-16 unit (NUL as two bytes,
/// characters past U+FFFF as two surrogates of three bytes each).
fn modified_utf8(b: &[u8]) -> String {
    let mut units = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        let c = b[i] as u16;
        let next = |k: usize| b.get(i + k).map_or(0, |&x| x as u16 & 0x3F);
        if c < 0x80 {
            units.push(c);
            i += 1;
        } else if c & 0xE0 == 0xC0 {
            units.push((c & 0x1F) << 6 | next(1));
            i += 2;
        } else {
            units.push((c & 0x0F) << 12 | next(1) << 6 | next(2));
            i += 3;
        }
    }
    String::from_utf16_lossy(&units)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A zip archive of `files`, each stored or deflated.
    fn zip(files: &[(&str, &[u8], bool)]) -> Vec<u8> {
        let mut out = Vec::new();
        let mut dir = Vec::new();
        for (name, data, deflate) in files {
            let packed = if *deflate {
                miniz_oxide::deflate::compress_to_vec(data, 6)
            } else {
                data.to_vec()
            };
            let method: u16 = if *deflate { 8 } else { 0 };
            let local = out.len() as u32;
            out.extend(0x0403_4b50u32.to_le_bytes());
            out.extend([20, 0, 0, 0]);
            out.extend(method.to_le_bytes());
            out.extend([0; 8]); // time, date, crc
            out.extend((packed.len() as u32).to_le_bytes());
            out.extend((data.len() as u32).to_le_bytes());
            out.extend((name.len() as u16).to_le_bytes());
            out.extend(0u16.to_le_bytes());
            out.extend(name.as_bytes());
            out.extend(&packed);
            dir.extend(0x0201_4b50u32.to_le_bytes());
            dir.extend([20, 0, 20, 0, 0, 0]);
            dir.extend(method.to_le_bytes());
            dir.extend([0; 8]);
            dir.extend((packed.len() as u32).to_le_bytes());
            dir.extend((data.len() as u32).to_le_bytes());
            dir.extend((name.len() as u16).to_le_bytes());
            dir.extend([0; 12]); // extra, comment, disk, attributes
            dir.extend(local.to_le_bytes());
            dir.extend(name.as_bytes());
        }
        let at = out.len() as u32;
        out.extend(&dir);
        out.extend(0x0605_4b50u32.to_le_bytes());
        out.extend([0; 4]);
        out.extend((files.len() as u16).to_le_bytes());
        out.extend((files.len() as u16).to_le_bytes());
        out.extend((dir.len() as u32).to_le_bytes());
        out.extend(at.to_le_bytes());
        out.extend(0u16.to_le_bytes());
        out
    }

    /// A class file whose constant pool holds a long and the strings `strings` (as modified
    /// UTF-8 bytes).
    fn class(strings: &[&[u8]]) -> Vec<u8> {
        let mut b = vec![0xCA, 0xFE, 0xBA, 0xBE, 0, 0, 0, 61];
        b.extend(((strings.len() + 3) as u16).to_be_bytes());
        b.push(5);
        b.extend([0; 8]);
        for s in strings {
            b.push(1);
            b.extend((s.len() as u16).to_be_bytes());
            b.extend(*s);
        }
        b
    }

    #[test]
    fn resources_are_read_from_a_jar_stored_or_deflated() {
        let dir = std::env::temp_dir().join(format!("ugnis-jwf-install-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut png = Vec::new();
        image::RgbaImage::from_pixel(3, 2, image::Rgba([10, 20, 30, 255]))
            .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .unwrap();
        let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        let long_text = "abc ".repeat(500);
        let jar = dir.join("j-wildfire.jar");
        std::fs::write(
            &jar,
            zip(&[
                ("org/x/brush001.png", &png, false),
                ("org/x/m.obj", obj, true),
                ("org/x/long.txt", long_text.as_bytes(), true),
                (
                    "org/x/C.class",
                    &class(&[b"short", b"<svg>\xC3\xA9</svg>"]),
                    true,
                ),
            ]),
        )
        .unwrap();
        let inst = Install::open(std::slice::from_ref(&jar)).unwrap();
        assert_eq!(
            inst.bytes("org/x/long.txt").unwrap().as_deref(),
            Some(long_text.as_bytes())
        );
        assert_eq!(inst.bytes("org/x/none.png").unwrap(), None);
        assert_eq!(inst.bytes("org/../x/m.obj").unwrap(), None);
        match inst.resource("org/x/brush001.png") {
            Some(Builtin::Image(i)) => {
                assert_eq!((i.w, i.h), (3, 2));
                assert!(i.rgba.iter().all(|p| *p == [10, 20, 30, 255]));
            }
            other => panic!("not an image: {other:?}"),
        }
        match inst.resource("org/x/m.obj") {
            Some(Builtin::Mesh(m)) => assert_eq!((m.vertices.len(), m.faces.len()), (3, 1)),
            other => panic!("not a mesh: {other:?}"),
        }
        match inst.resource("org/x/C.class") {
            Some(Builtin::Text(t)) => assert_eq!(t.as_str(), "<svg>é</svg>"),
            other => panic!("not a text: {other:?}"),
        }
        // A folder is read the same way, and comes first when named first.
        let folder = dir.join("res");
        std::fs::create_dir_all(folder.join("org/x")).unwrap();
        std::fs::write(folder.join("org/x/long.txt"), b"folder").unwrap();
        let both = Install::open(&[folder.clone(), jar.clone()]).unwrap();
        assert_eq!(
            both.bytes("org/x/long.txt").unwrap().as_deref(),
            Some(&b"folder"[..])
        );
        assert!(both.bytes("org/x/m.obj").unwrap().is_some());
        // Not a jar: the error names the file.
        let not = dir.join("not.jar");
        std::fs::write(&not, b"plain text, no zip").unwrap();
        let e = Install::open(std::slice::from_ref(&not)).err().unwrap();
        assert!(e.contains("not.jar") && e.contains("zip"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn class_files_give_their_longest_string() {
        // Modified UTF-8: NUL as C0 80, U+1F600 as two three-byte surrogates.
        let c = class(&[b"a\xC0\x80b", b"\xED\xA0\xBD\xED\xB8\x80 long"]);
        assert_eq!(
            longest_string_constant(&c).as_deref(),
            Some("\u{1F600} long")
        );
        assert_eq!(longest_string_constant(b"not a class"), None);
        // Cut short: no panic, no answer.
        assert_eq!(longest_string_constant(&c[..c.len() - 3]), None);
    }
}
