//! Atomic saves: write a temporary file in the target's directory, then rename it over the
//! target. A failed save never truncates or replaces an existing file.
//!
//! The temporary file is created exclusively (`O_CREAT | O_EXCL`, never following a symlink)
//! under an unpredictable name by the `tempfile` crate, so a link planted in the directory
//! cannot redirect the write. Every target is checked by the output rule of
//! [`crate::io::target`] before the temporary file is made and again just before the rename.
//!
//! Every temporary file is registered while it exists. A program that ends on a signal calls
//! [`close`] (no save starts or is renamed into place after it; the processes writing
//! temporary files, such as ffmpeg, are returned to be stopped) and then [`remove_pending`].
//! A command with several outputs can [`hold`] its saves and put them in place together, so
//! that a failure or a signal leaves every old output as it was.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

use crate::io::target::check_target;

/// The temporary files of this process and what may still be done with them.
struct Registry {
    /// Temporary files that exist now (being written, or held).
    pending: Vec<PathBuf>,
    /// Saves written but not yet renamed, while [`hold`] is in force.
    held: Option<Vec<(tempfile::TempPath, PathBuf)>>,
    /// Processes that write temporary files (an encoder), by process id.
    writers: Vec<u32>,
    /// Set by [`close`]: the process is ending; nothing more is created or renamed.
    closed: bool,
}

static REGISTRY: Mutex<Registry> = Mutex::new(Registry {
    pending: Vec::new(),
    held: None,
    writers: Vec::new(),
    closed: false,
});

fn registry() -> MutexGuard<'static, Registry> {
    // A panic while the lock was held leaves the lists as they were: still usable.
    REGISTRY.lock().unwrap_or_else(|e| e.into_inner())
}

fn closed_error() -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::Interrupted,
        "the program is stopping; nothing more is saved",
    )
}

/// Stop every save: after this no temporary file is created and none is renamed over its
/// target (those in progress fail). Returns the ids of the processes writing temporary files
/// now, for the caller to stop before it calls [`remove_pending`]. For a program about to
/// end on a signal.
pub fn close() -> Vec<u32> {
    let mut r = registry();
    r.closed = true;
    r.writers.clone()
}

/// Remove every temporary file that exists now (being written or held), for a program about
/// to end (destructors will not run). Returns how many were removed.
pub fn remove_pending() -> usize {
    remove_pending_where(|_| true)
}

fn remove_pending_where(select: impl Fn(&Path) -> bool) -> usize {
    let r = registry();
    r.pending
        .iter()
        .filter(|p| select(p) && std::fs::remove_file(p).is_ok())
        .count()
}

/// A process writing a temporary file (an encoder given the file's name), registered while
/// this value lives so that [`close`] can name it.
pub struct WriterProcess(u32);

impl WriterProcess {
    /// Register the process `id`.
    pub fn register(id: u32) -> WriterProcess {
        registry().writers.push(id);
        WriterProcess(id)
    }
}

impl Drop for WriterProcess {
    fn drop(&mut self) {
        let mut r = registry();
        if let Some(i) = r.writers.iter().position(|p| *p == self.0) {
            r.writers.swap_remove(i);
        }
    }
}

/// Saves held back by [`hold`]; dropped without [`Holding::commit`], they are removed.
#[must_use = "held saves are removed unless committed"]
pub struct Holding {
    active: bool,
}

/// Hold every save of this process from now on: each is written to its temporary file, and
/// all are renamed over their targets together by [`Holding::commit`] (or removed if the
/// holding is dropped). For a command with several outputs (an image and its render state,
/// a batch and its thumbnails): a failure or a signal before the commit leaves every old
/// output untouched and no new one. A second hold while one is in force holds nothing more.
pub fn hold() -> Holding {
    let mut r = registry();
    if r.held.is_some() {
        return Holding { active: false };
    }
    r.held = Some(Vec::new());
    Holding { active: true }
}

impl Holding {
    /// Rename every held save over its target. The targets are checked again first, all of
    /// them before any is replaced.
    pub fn commit(mut self) -> std::io::Result<()> {
        if !self.active {
            return Ok(());
        }
        self.active = false;
        let mut r = registry();
        let held = r.held.take().unwrap_or_default();
        if r.closed {
            drop(r);
            drop(held);
            return Err(closed_error());
        }
        let mut result = held.iter().try_for_each(|(_, target)| check_target(target));
        for (tmp, target) in held {
            let name = tmp.to_path_buf();
            if result.is_ok() {
                // A failed rename drops (removes) the temporary file with the error.
                result = tmp.persist(&target).map_err(|e| e.error);
            } else {
                let _ = tmp.close();
            }
            unregister(&mut r, &name);
        }
        result
    }
}

impl Drop for Holding {
    fn drop(&mut self) {
        if !self.active {
            return;
        }
        let mut r = registry();
        for (tmp, _) in r.held.take().unwrap_or_default() {
            let name = tmp.to_path_buf();
            let _ = tmp.close();
            unregister(&mut r, &name);
        }
    }
}

fn unregister(r: &mut Registry, p: &Path) {
    if let Some(i) = r.pending.iter().position(|q| q == p) {
        r.pending.swap_remove(i);
    }
}

/// The directory a file is saved in ("." for a bare name).
pub fn target_dir(path: &Path) -> PathBuf {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Check, before any long work, that `path` can be saved: it names a file that the output
/// rule allows ([`check_target`]: a regular file or a new name) in an existing directory
/// where files can be created. The check creates and removes one temporary file there,
/// exactly as the save will.
pub fn check_writable(path: &Path) -> std::io::Result<()> {
    let bad = |m: String| Err(std::io::Error::new(std::io::ErrorKind::InvalidInput, m));
    if path.file_name().is_none() {
        return bad(format!("'{}' does not name a file", path.display()));
    }
    check_target(path)?;
    let dir = target_dir(path);
    if !dir.is_dir() {
        return bad(format!("the directory '{}' does not exist", dir.display()));
    }
    create_temp(path).map(drop)
}

/// A temporary file being written for a save: registered while it exists, removed when
/// dropped unless it was put in place.
struct Temp {
    file: std::fs::File,
    path: Option<tempfile::TempPath>,
}

impl Temp {
    fn path(&self) -> &Path {
        self.path.as_deref().unwrap_or(Path::new(""))
    }

    /// Flush to disk and rename over `target` (or hand it to the [`hold`] in force).
    fn commit(mut self, target: &Path) -> std::io::Result<()> {
        self.file.flush()?;
        // A file that is replaced keeps its permissions.
        if let Ok(m) = std::fs::metadata(target)
            && m.is_file()
        {
            let _ = self.file.set_permissions(m.permissions());
        }
        self.file.sync_all()?;
        let mut r = registry();
        if r.closed {
            return Err(closed_error());
        }
        check_target(target)?;
        let tmp = self.path.take().expect("a temporary file until committed");
        if let Some(held) = r.held.as_mut() {
            held.push((tmp, target.to_path_buf()));
            return Ok(());
        }
        let name = tmp.to_path_buf();
        match tmp.persist(target) {
            Ok(()) => {
                unregister(&mut r, &name);
                Ok(())
            }
            Err(e) => {
                // Put back, so that dropping removes it.
                self.path = Some(e.path);
                Err(e.error)
            }
        }
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        if let Some(tmp) = self.path.take() {
            let mut r = registry();
            let name = tmp.to_path_buf();
            let _ = tmp.close();
            unregister(&mut r, &name);
        }
    }
}

/// Create the temporary file for a save of `path`: `.NAME.<random>.ugnis-tmp` in the same
/// directory (the rename must not cross file systems), registered at once.
fn create_temp(path: &Path) -> std::io::Result<Temp> {
    let name = path.file_name().ok_or_else(|| {
        std::io::Error::new(std::io::ErrorKind::InvalidInput, "path has no file name")
    })?;
    let prefix = format!(".{}.", name.to_string_lossy());
    let mut b = tempfile::Builder::new();
    b.prefix(&prefix).suffix(".ugnis-tmp").rand_bytes(12);
    // Ordinary file permissions (less the umask), not the temporary file's 0600.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        b.permissions(std::fs::Permissions::from_mode(0o666));
    }
    // Created and registered under the lock: a program ending on a signal never misses one.
    let mut r = registry();
    if r.closed {
        return Err(closed_error());
    }
    let (file, tmp) = b.tempfile_in(target_dir(path))?.into_parts();
    r.pending.push(tmp.to_path_buf());
    Ok(Temp {
        file,
        path: Some(tmp),
    })
}

/// Write `bytes` to `path` atomically.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_atomic_with(path, |f| f.write_all(bytes))
}

/// Write to `path` atomically through a callback that fills the temporary file.
pub fn write_atomic_with(
    path: &Path,
    fill: impl FnOnce(&mut std::fs::File) -> std::io::Result<()>,
) -> std::io::Result<()> {
    check_target(path)?;
    let mut tmp = create_temp(path)?;
    fill(&mut tmp.file)?;
    // On error the temporary file is dropped, which removes it.
    tmp.commit(path)
}

/// A file written in place of `path` and put there only by [`AtomicFile::commit`] (dropped
/// uncommitted, it is removed): for saves written piece by piece, such as posters in strips.
pub struct AtomicFile {
    tmp: Temp,
    path: PathBuf,
}

impl AtomicFile {
    /// A temporary file beside `path`, to become `path` when committed (fails for a target
    /// the output rule refuses, see [`check_target`]).
    pub fn create(path: &Path) -> std::io::Result<AtomicFile> {
        check_target(path)?;
        Ok(AtomicFile {
            tmp: create_temp(path)?,
            path: path.to_path_buf(),
        })
    }

    /// Where the temporary file is (for a program that writes it by name).
    pub fn temp_path(&self) -> &Path {
        self.tmp.path()
    }

    /// The temporary file (clone the handle to give a writer its own).
    pub fn file(&mut self) -> &mut std::fs::File {
        &mut self.tmp.file
    }

    /// Flush to disk and rename over the target.
    pub fn commit(self) -> std::io::Result<()> {
        self.tmp.commit(&self.path)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(tag: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("ugnis-atomic-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn replaces_or_keeps_the_old_file() {
        let dir = scratch("keep");
        let p = dir.join("a.txt");
        write_atomic(&p, b"one").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"one");
        // A failing writer leaves the old content and no temporary file behind.
        let r = write_atomic_with(&p, |f| {
            f.write_all(b"partial")?;
            Err(std::io::Error::other("disk full"))
        });
        assert!(r.is_err());
        assert_eq!(std::fs::read(&p).unwrap(), b"one");
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        write_atomic(&p, b"two").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"two");
        // A directory that does not exist is an error, not a panic.
        assert!(write_atomic(&dir.join("missing/x.txt"), b"x").is_err());
        assert!(check_writable(&dir.join("missing/x.txt")).is_err());
        assert!(check_writable(&dir).is_err());
        assert!(check_writable(&dir.join("new.png")).is_ok());
        assert_eq!(
            std::fs::read_dir(&dir).unwrap().count(),
            1,
            "the check leaves nothing"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn a_planted_symlink_cannot_redirect_the_write() {
        use std::os::unix::fs::PermissionsExt;
        let dir = scratch("link");
        let victim = dir.join("victim.txt");
        std::fs::write(&victim, b"precious").unwrap();
        // The old, predictable temporary names, all pointing at the victim.
        let target = dir.join("out.txt");
        for pid in [std::process::id(), 1, 2] {
            std::os::unix::fs::symlink(&victim, dir.join(format!(".out.txt.ugnis-tmp-{pid}")))
                .unwrap();
        }
        write_atomic(&target, b"new picture").unwrap();
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
        assert_eq!(std::fs::read(&target).unwrap(), b"new picture");
        // Ordinary permissions (not 0600), and a replaced file keeps its own.
        let mode = std::fs::metadata(&target).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode & 0o600, 0o600);
        std::fs::set_permissions(&target, std::fs::Permissions::from_mode(0o640)).unwrap();
        write_atomic(&target, b"again").unwrap();
        let mode = std::fs::metadata(&target).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o640);
        // Only the target, the victim and the planted links: no temporary file left.
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 5);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn pending_files_are_registered_while_written() {
        let dir = scratch("pending");
        let p = dir.join("b.txt");
        write_atomic_with(&p, |f| {
            let pending = registry().pending.clone();
            let mine: Vec<_> = pending.iter().filter(|q| q.starts_with(&dir)).collect();
            assert_eq!(mine.len(), 1);
            assert!(mine[0].exists());
            f.write_all(b"x")
        })
        .unwrap();
        assert!(!registry().pending.iter().any(|q| q.starts_with(&dir)));
        // An interrupt handler removes the file being written; the save then fails cleanly
        // and the old file stays.
        let r = write_atomic_with(&p, |f| {
            f.write_all(b"half")?;
            // (Only this test's file: other tests may be saving at the same time.)
            assert_eq!(remove_pending_where(|q| q.starts_with(&dir)), 1);
            Ok(())
        });
        assert!(r.is_err());
        assert_eq!(std::fs::read(&p).unwrap(), b"x");
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
