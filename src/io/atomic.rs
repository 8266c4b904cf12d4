//! Atomic saves: write a temporary file in the target's directory, then rename it over the
//! target. A failed save never truncates or replaces an existing file.
//!
//! The temporary file is created exclusively (`O_CREAT | O_EXCL`, never following a symlink)
//! under an unpredictable name by the `tempfile` crate, so a link planted in the directory
//! cannot redirect the write. It is removed on every error; while it exists its path is
//! registered so that an interrupt handler can remove it before the process exits
//! ([`remove_pending`]).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Temporary files being written now.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Removes its path from [`PENDING`] when the save ends, whichever way.
struct Registered(PathBuf);

impl Registered {
    fn new(p: &Path) -> Registered {
        if let Ok(mut v) = PENDING.lock() {
            v.push(p.to_path_buf());
        }
        Registered(p.to_path_buf())
    }
}

impl Drop for Registered {
    fn drop(&mut self) {
        if let Ok(mut v) = PENDING.lock()
            && let Some(i) = v.iter().position(|p| *p == self.0)
        {
            v.swap_remove(i);
        }
    }
}

/// Remove every temporary file a save is writing now (for an interrupt handler that is about
/// to end the process, when destructors will not run). Returns how many were removed.
pub fn remove_pending() -> usize {
    remove_pending_where(|_| true)
}

fn remove_pending_where(select: impl Fn(&Path) -> bool) -> usize {
    let Ok(v) = PENDING.lock() else { return 0 };
    v.iter()
        .filter(|p| select(p) && std::fs::remove_file(p).is_ok())
        .count()
}

/// The directory a file is saved in ("." for a bare name).
pub fn target_dir(path: &Path) -> PathBuf {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Check, before any long work, that `path` can be saved: it names a file (not a directory)
/// in an existing directory where files can be created. The check creates and removes one
/// temporary file there, exactly as the save will.
pub fn check_writable(path: &Path) -> std::io::Result<()> {
    let bad = |m: String| Err(std::io::Error::new(std::io::ErrorKind::InvalidInput, m));
    if path.file_name().is_none() {
        return bad(format!("'{}' does not name a file", path.display()));
    }
    if path.is_dir() {
        return bad(format!("'{}' is a directory", path.display()));
    }
    let dir = target_dir(path);
    if !dir.is_dir() {
        return bad(format!("the directory '{}' does not exist", dir.display()));
    }
    create_temp(path).map(drop)
}

/// Create the temporary file for a save of `path`: `.NAME.<random>.ugnis-tmp` in the same
/// directory (the rename must not cross file systems).
fn create_temp(path: &Path) -> std::io::Result<tempfile::NamedTempFile> {
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
    b.tempfile_in(target_dir(path))
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
    if path.is_dir() {
        return Err(std::io::Error::new(
            std::io::ErrorKind::IsADirectory,
            format!("'{}' is a directory", path.display()),
        ));
    }
    let mut tmp = create_temp(path)?;
    let _registered = Registered::new(tmp.path());
    fill(tmp.as_file_mut())?;
    tmp.as_file_mut().flush()?;
    // A file that is replaced keeps its permissions.
    if let Ok(m) = std::fs::metadata(path)
        && m.is_file()
    {
        let _ = tmp.as_file().set_permissions(m.permissions());
    }
    tmp.as_file().sync_all()?;
    // On error the temporary file is dropped, which removes it.
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

/// A file written in place of `path` and put there only by [`AtomicFile::commit`] (dropped
/// uncommitted, it is removed): for saves written piece by piece, such as posters in strips.
pub struct AtomicFile {
    tmp: tempfile::NamedTempFile,
    _registered: Registered,
    path: PathBuf,
}

impl AtomicFile {
    /// A temporary file beside `path`, to become `path` when committed (fails for a directory).
    pub fn create(path: &Path) -> std::io::Result<AtomicFile> {
        if path.is_dir() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::IsADirectory,
                format!("'{}' is a directory", path.display()),
            ));
        }
        let tmp = create_temp(path)?;
        let registered = Registered::new(tmp.path());
        Ok(AtomicFile {
            tmp,
            _registered: registered,
            path: path.to_path_buf(),
        })
    }

    /// Where the temporary file is (for a program that writes it by name).
    pub fn temp_path(&self) -> &Path {
        self.tmp.path()
    }

    /// The temporary file (clone the handle to give a writer its own).
    pub fn file(&mut self) -> &mut std::fs::File {
        self.tmp.as_file_mut()
    }

    /// Flush to disk and rename over the target.
    pub fn commit(mut self) -> std::io::Result<()> {
        self.tmp.as_file_mut().flush()?;
        if let Ok(m) = std::fs::metadata(&self.path)
            && m.is_file()
        {
            let _ = self.tmp.as_file().set_permissions(m.permissions());
        }
        self.tmp.as_file().sync_all()?;
        self.tmp.persist(&self.path).map_err(|e| e.error)?;
        Ok(())
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
            let pending = PENDING.lock().unwrap().clone();
            let mine: Vec<_> = pending.iter().filter(|q| q.starts_with(&dir)).collect();
            assert_eq!(mine.len(), 1);
            assert!(mine[0].exists());
            f.write_all(b"x")
        })
        .unwrap();
        assert!(!PENDING.lock().unwrap().iter().any(|q| q.starts_with(&dir)));
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
