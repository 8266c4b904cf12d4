//! Where a save may go: the one rule every writer of ugnis follows (images, states, views,
//! scenes, flames, gradients, frames, thumbnails, videos).
//!
//! - A target is a regular file or a name that does not exist yet. Devices, named pipes,
//!   sockets and directories are refused: a save writes a new file and renames it over its
//!   target, which would turn a device node or a pipe into a regular file.
//! - A symbolic link at the target is itself replaced by the new file; what it points to is
//!   never written through. A link to a device, pipe, socket or directory is refused as the
//!   thing it points to is.
//! - An output may not be one of the inputs of the same command, nor another of its outputs:
//!   paths are compared resolved (links and `..` followed) and, for files that exist, by
//!   device and inode (so a hard link or a link to an input is the input).
//!
//! [`check_target`] is applied by [`crate::io::atomic`] before a temporary file is created and
//! again just before it is renamed over the target; commands check their outputs against their
//! inputs with [`check_distinct`] before any long work.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// What a file system entry is, for messages ("a named pipe").
fn kind_name(t: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a named pipe";
        }
        if t.is_socket() {
            return "a socket";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
    }
    if t.is_dir() {
        "a directory"
    } else if t.is_symlink() {
        "a symbolic link"
    } else {
        "not a regular file"
    }
}

/// The refusal of a target (the caller names the path: "cannot write 'x': it is a device; …").
fn refused(what: String) -> std::io::Error {
    let kind = if what.contains("directory") {
        std::io::ErrorKind::IsADirectory
    } else {
        std::io::ErrorKind::InvalidInput
    };
    std::io::Error::new(
        kind,
        format!(
            "it {what}; ugnis saves only to regular files or to new names (a save replaces its target)"
        ),
    )
}

/// Check that a save may replace `path`: it does not exist, is a regular file, or is a
/// symbolic link (dangling or to a regular file), which the save replaces by the new file.
pub fn check_target(path: &Path) -> std::io::Result<()> {
    let meta = match std::fs::symlink_metadata(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(e),
        Ok(m) => m,
    };
    let t = meta.file_type();
    if t.is_file() {
        return Ok(());
    }
    if !t.is_symlink() {
        return Err(refused(format!("is {}", kind_name(t))));
    }
    match std::fs::metadata(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
        Err(e) => Err(e),
        Ok(m) if m.is_file() => Ok(()),
        Ok(m) => Err(refused(format!(
            "is a link to {}",
            kind_name(m.file_type())
        ))),
    }
}

/// The names under which a path is known, to tell whether two paths are one file: the entry
/// itself (its directory resolved), what it resolves to, and its device and inode.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Key {
    Path(PathBuf),
    Inode(u64, u64),
}

/// An absolute path with `.` and `..` taken out as far as the file system resolves them.
fn resolved_entry(path: &Path) -> Option<PathBuf> {
    let abs = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir().ok()?.join(path)
    };
    let name = abs.file_name()?;
    let dir = abs.parent()?;
    let dir = std::fs::canonicalize(dir).unwrap_or_else(|_| dir.to_path_buf());
    Some(dir.join(name))
}

fn keys(path: &Path) -> Vec<Key> {
    let mut k = Vec::with_capacity(3);
    match resolved_entry(path) {
        Some(p) => k.push(Key::Path(p)),
        None => k.push(Key::Path(path.to_path_buf())),
    }
    if let Ok(p) = std::fs::canonicalize(path) {
        k.push(Key::Path(p));
    }
    #[cfg(unix)]
    if let Ok(m) = std::fs::metadata(path) {
        use std::os::unix::fs::MetadataExt;
        k.push(Key::Inode(m.dev(), m.ino()));
    }
    k.dedup();
    k
}

/// Two paths of one command that are the same file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Clash {
    /// An output is one of the inputs.
    Input {
        /// The output.
        output: PathBuf,
        /// The input it would replace.
        input: PathBuf,
    },
    /// Two outputs are one file.
    Outputs {
        /// The output named first.
        first: PathBuf,
        /// The output that would replace it.
        second: PathBuf,
    },
}

impl std::fmt::Display for Clash {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Clash::Input { output, input } if output == input => write!(
                f,
                "'{}' is both an input and an output; saving would replace what is read \
                 (choose another output name)",
                output.display()
            ),
            Clash::Input { output, input } => write!(
                f,
                "the output '{}' is the input '{}' (the same file); saving would replace what \
                 is read (choose another output name)",
                output.display(),
                input.display()
            ),
            Clash::Outputs { first, second } if first == second => write!(
                f,
                "'{}' is named for two outputs; one save would replace the other",
                first.display()
            ),
            Clash::Outputs { first, second } => write!(
                f,
                "the outputs '{}' and '{}' are the same file; one save would replace the other",
                first.display(),
                second.display()
            ),
        }
    }
}

impl std::error::Error for Clash {}

/// Refuse outputs that are inputs of the same command or are named twice. Standard input
/// (`-`) is no file and is skipped.
pub fn check_distinct(inputs: &[&Path], outputs: &[&Path]) -> Result<(), Clash> {
    let mut seen: HashMap<Key, (bool, &Path)> = HashMap::new();
    for &i in inputs.iter().filter(|p| !crate::io::is_stdin(p)) {
        for k in keys(i) {
            seen.entry(k).or_insert((true, i));
        }
    }
    for &o in outputs {
        let ks = keys(o);
        if let Some((is_input, other)) = ks.iter().find_map(|k| seen.get(k)) {
            return Err(if *is_input {
                Clash::Input {
                    output: o.to_path_buf(),
                    input: other.to_path_buf(),
                }
            } else {
                Clash::Outputs {
                    first: other.to_path_buf(),
                    second: o.to_path_buf(),
                }
            });
        }
        for k in ks {
            seen.insert(k, (false, o));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(tag: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("ugnis-target-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::canonicalize(dir).unwrap()
    }

    #[test]
    fn only_regular_files_and_new_names_are_targets() {
        let dir = scratch("kind");
        let file = dir.join("a.png");
        std::fs::write(&file, b"x").unwrap();
        assert!(check_target(&file).is_ok());
        assert!(check_target(&dir.join("new.png")).is_ok());
        let e = check_target(&dir).unwrap_err();
        assert!(e.to_string().contains("is a directory"), "{e}");
        #[cfg(unix)]
        {
            let fifo = dir.join("p.png");
            let ok = std::process::Command::new("mkfifo")
                .arg(&fifo)
                .status()
                .is_ok_and(|s| s.success());
            if ok {
                let e = check_target(&fifo).unwrap_err();
                assert!(e.to_string().contains("is a named pipe"), "{e}");
                let link = dir.join("to-fifo.png");
                std::os::unix::fs::symlink(&fifo, &link).unwrap();
                let e = check_target(&link).unwrap_err();
                assert!(e.to_string().contains("is a link to a named pipe"), "{e}");
            }
            let link = dir.join("to-file.png");
            std::os::unix::fs::symlink(&file, &link).unwrap();
            assert!(check_target(&link).is_ok());
            let dangling = dir.join("dangling.png");
            std::os::unix::fs::symlink(dir.join("nothing"), &dangling).unwrap();
            assert!(check_target(&dangling).is_ok());
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn outputs_are_compared_with_inputs_and_each_other() {
        let dir = scratch("same");
        let input = dir.join("in.flame");
        std::fs::write(&input, b"<flame/>").unwrap();
        let sub = dir.join("sub");
        std::fs::create_dir_all(&sub).unwrap();
        let other = dir.join("out.png");
        assert!(check_distinct(&[&input], &[&other, &dir.join("s.ugs")]).is_ok());
        // The same file by another spelling.
        let dotted = sub.join("../in.flame");
        let e = check_distinct(&[&input], &[&other, &dotted]).unwrap_err();
        assert!(matches!(e, Clash::Input { .. }), "{e}");
        // Two outputs of one name (neither exists yet).
        let e = check_distinct(&[&input], &[&other, &other]).unwrap_err();
        assert!(e.to_string().contains("named for two outputs"), "{e}");
        #[cfg(unix)]
        {
            // A hard link and a symbolic link to the input are the input.
            let hard = dir.join("hard.flame");
            std::fs::hard_link(&input, &hard).unwrap();
            assert!(check_distinct(&[&input], &[&hard]).is_err());
            let soft = dir.join("soft.flame");
            std::os::unix::fs::symlink(&input, &soft).unwrap();
            assert!(check_distinct(&[&input], &[&soft]).is_err());
            // Read through a link, written under its real name.
            assert!(check_distinct(&[&soft], &[&input]).is_err());
        }
        // Standard input is not a file.
        assert!(check_distinct(&[Path::new("-")], &[&other]).is_ok());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
