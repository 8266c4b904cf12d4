//! How much memory a render may use, and the refusal when it needs more.
//!
//! Every renderer (flames, escape-time fractals, scenes, batches of thumbnails, animation
//! frames) estimates the bytes of its buffers *before* allocating them and compares the
//! estimate with [`budget`]: the smallest of
//!
//! - the memory the system reports as available (Linux `MemAvailable` in `/proc/meminfo`:
//!   free memory plus the page cache and slabs that can be reclaimed without swapping),
//! - what is left of the process's address-space limit (`ulimit -v`, the soft `RLIMIT_AS` as
//!   shown in `/proc/self/limits`, minus the `VmSize` already mapped), and
//! - what is left under the memory limit of the process's cgroup and of each of its ancestors
//!   (cgroup v2 `memory.max` − `memory.current`, v1 `memory.limit_in_bytes` −
//!   `memory.usage_in_bytes`, both less the inactive page cache, which the kernel reclaims
//!   before it kills anything).
//!
//! A render that does not fit gets a [`MemoryError`] saying what it needs, what is available,
//! which limit binds and what to change. On systems without these files the budget is
//! [`FALLBACK`].

use std::fmt;
use std::path::{Path, PathBuf};

/// Budget used when the system tells nothing (not Linux, or /proc unreadable).
pub const FALLBACK: u64 = 8 << 30;

/// Address space kept free for code, thread stacks and allocator arenas when `ulimit -v` is
/// what binds (mapped address space counts against the limit even when never touched).
pub const ADDRESS_SPACE_HEADROOM: u64 = 256 << 20;

/// Which limit a budget comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// Memory the system reports as available.
    Available,
    /// The process's address-space limit (`ulimit -v`).
    AddressSpace,
    /// The cgroup (container) memory limit.
    Cgroup,
    /// A limit the caller gave (an option or a setting).
    Configured,
    /// Nothing known; [`FALLBACK`].
    Fallback,
}

impl fmt::Display for Source {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Source::Available => "memory available on this system",
            Source::AddressSpace => "address space left under the process limit (ulimit -v)",
            Source::Cgroup => "memory left under the cgroup (container) limit",
            Source::Configured => "the configured memory limit",
            Source::Fallback => "assumed memory (the system reports none)",
        })
    }
}

/// The bytes a render may allocate and where that number comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Budget {
    /// Bytes allowed.
    pub bytes: u64,
    /// Which limit set them.
    pub source: Source,
}

/// What the system reports, each part on its own (None: unknown or unlimited).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Limits {
    /// Memory the system reports as available, in bytes.
    pub available: Option<u64>,
    /// The address-space limit (`ulimit -v`), in bytes.
    pub address_space: Option<u64>,
    /// The cgroup (container) memory limit, in bytes.
    pub cgroup: Option<u64>,
}

impl Limits {
    /// Read the limits of this process from /proc and /sys.
    pub fn of_this_process() -> Limits {
        Limits {
            available: available_memory(),
            address_space: address_space_left(),
            cgroup: cgroup_memory_left(),
        }
    }

    /// The smallest of the known limits.
    pub fn budget(&self) -> Budget {
        [
            (self.available, Source::Available),
            (self.address_space, Source::AddressSpace),
            (self.cgroup, Source::Cgroup),
        ]
        .into_iter()
        .filter_map(|(b, s)| b.map(|bytes| Budget { bytes, source: s }))
        .min_by_key(|b| b.bytes)
        .unwrap_or(Budget {
            bytes: FALLBACK,
            source: Source::Fallback,
        })
    }
}

/// The memory budget of this process now.
pub fn budget() -> Budget {
    Limits::of_this_process().budget()
}

/// The budget, or `configured` when the caller sets one (the smaller of the two is not taken:
/// a configured limit is what tests and embedding programs ask for).
pub fn budget_or(configured: Option<u64>) -> Budget {
    match configured {
        Some(bytes) => Budget {
            bytes,
            source: Source::Configured,
        },
        None => budget(),
    }
}

/// A render that does not fit in memory.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MemoryError {
    /// What was to be made, e.g. "a 30000×30000 escape-time render".
    pub what: String,
    /// Bytes it would need.
    pub need: u64,
    /// Bytes allowed, and by which limit.
    pub budget: Budget,
    /// What to change, e.g. "reduce the size or the supersample".
    pub hint: String,
}

impl fmt::Display for MemoryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} needs about {}, but only {} are available ({}); {}",
            self.what,
            fmt_bytes(self.need),
            fmt_bytes(self.budget.bytes),
            self.budget.source,
            self.hint
        )
    }
}

impl std::error::Error for MemoryError {}

/// Refuse `need` bytes when they exceed the budget (`configured`, or the system's).
pub fn check(
    need: u64,
    configured: Option<u64>,
    what: impl FnOnce() -> String,
    hint: impl FnOnce() -> String,
) -> Result<Budget, MemoryError> {
    let budget = budget_or(configured);
    if need > budget.bytes {
        return Err(MemoryError {
            what: what(),
            need,
            budget,
            hint: hint(),
        });
    }
    Ok(budget)
}

/// Bytes for people: "512 KiB", "340 MiB", "21.6 GiB".
pub fn fmt_bytes(b: u64) -> String {
    const K: f64 = 1024.0;
    let v = b as f64;
    if v >= K * K * K {
        format!("{:.1} GiB", v / (K * K * K))
    } else if v >= K * K {
        format!("{:.0} MiB", (v / (K * K)).ceil())
    } else {
        format!("{:.0} KiB", (v / K).ceil())
    }
}

/// Linux `MemAvailable`, in bytes.
pub fn available_memory() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/meminfo").ok()?;
    kib_field(&s, "MemAvailable:")
}

/// A "Key:  N kB" line of /proc/meminfo or /proc/self/status, in bytes.
fn kib_field(text: &str, key: &str) -> Option<u64> {
    let line = text.lines().find(|l| l.starts_with(key))?;
    let kb: u64 = line[key.len()..].split_whitespace().next()?.parse().ok()?;
    Some(kb.saturating_mul(1024))
}

/// The soft address-space limit from the text of /proc/self/limits (None: unlimited).
pub fn parse_address_space_limit(limits: &str) -> Option<u64> {
    let line = limits
        .lines()
        .find(|l| l.starts_with("Max address space"))?;
    let soft = line["Max address space".len()..]
        .split_whitespace()
        .next()?;
    soft.parse().ok()
}

/// Address space left under `ulimit -v` (None: unlimited or unknown).
pub fn address_space_left() -> Option<u64> {
    let limit = parse_address_space_limit(&std::fs::read_to_string("/proc/self/limits").ok()?)?;
    let used = std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| kib_field(&s, "VmSize:"))
        .unwrap_or(0);
    Some(
        limit
            .saturating_sub(used)
            .saturating_sub(ADDRESS_SPACE_HEADROOM),
    )
}

/// Limits at or above this are "no limit" (cgroup v1 writes 2^63 rounded down to a page).
const UNLIMITED: u64 = 1 << 60;

/// One cgroup hierarchy that holds the memory controller.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CgroupMemory {
    /// Directory of the process's own cgroup.
    pub dir: PathBuf,
    /// The hierarchy's mount point (the walk up stops there).
    pub mount: PathBuf,
    /// v2 (`memory.max`) or v1 (`memory.limit_in_bytes`).
    pub v2: bool,
}

/// Find the process's memory cgroup from the texts of /proc/self/cgroup and
/// /proc/self/mountinfo. v1's memory controller is preferred when both exist (on such hybrid
/// systems the limits are set there).
pub fn find_cgroup(cgroup: &str, mountinfo: &str) -> Option<CgroupMemory> {
    let mut v1_path = None;
    let mut v2_path = None;
    for line in cgroup.lines() {
        let mut parts = line.splitn(3, ':');
        let (Some(id), Some(ctrl), Some(path)) = (parts.next(), parts.next(), parts.next()) else {
            continue;
        };
        if id == "0" && ctrl.is_empty() {
            v2_path = Some(path.to_string());
        } else if ctrl.split(',').any(|c| c == "memory") {
            v1_path = Some(path.to_string());
        }
    }
    let mut v1_mount = None;
    let mut v2_mount = None;
    for line in mountinfo.lines() {
        // id parent major:minor root mount-point options [optional…] - fstype source super-options
        let Some((left, right)) = line.split_once(" - ") else {
            continue;
        };
        let l: Vec<&str> = left.split(' ').collect();
        let r: Vec<&str> = right.split(' ').collect();
        if l.len() < 5 || r.is_empty() {
            continue;
        }
        let (root, point) = (l[3], l[4]);
        match r[0] {
            "cgroup2" => v2_mount = Some((root.to_string(), point.to_string())),
            "cgroup"
                if r.get(2)
                    .is_some_and(|o| o.split(',').any(|c| c == "memory")) =>
            {
                v1_mount = Some((root.to_string(), point.to_string()))
            }
            _ => {}
        }
    }
    let pick = |path: Option<String>, mount: Option<(String, String)>, v2: bool| {
        let path = path?;
        let (root, point) = mount?;
        // The cgroup path is relative to the hierarchy's root; a mount of a sub-tree (as in
        // containers) shows only the part below its root.
        let rel = path
            .strip_prefix(root.trim_end_matches('/'))
            .unwrap_or(&path)
            .trim_start_matches('/');
        let mount = PathBuf::from(unescape_mount(&point));
        Some(CgroupMemory {
            dir: mount.join(rel),
            mount,
            v2,
        })
    };
    pick(v1_path, v1_mount, false).or_else(|| pick(v2_path, v2_mount, true))
}

/// Mount points in mountinfo escape space, tab, newline and backslash as octal.
fn unescape_mount(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'\\'
            && i + 3 < b.len()
            && b[i + 1..i + 4].iter().all(|c| (b'0'..=b'7').contains(c))
        {
            out.push((b[i + 1] - b'0') * 64 + (b[i + 2] - b'0') * 8 + (b[i + 3] - b'0'));
            i += 4;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

fn read_u64(p: &Path) -> Option<u64> {
    std::fs::read_to_string(p).ok()?.trim().parse().ok()
}

/// Inactive page cache of a cgroup (reclaimable), from memory.stat.
fn inactive_file(dir: &Path, v2: bool) -> u64 {
    let key = if v2 {
        "inactive_file"
    } else {
        "total_inactive_file"
    };
    std::fs::read_to_string(dir.join("memory.stat"))
        .ok()
        .and_then(|s| {
            s.lines().find_map(|l| {
                let (k, v) = l.split_once(' ')?;
                (k == key).then(|| v.trim().parse().ok()).flatten()
            })
        })
        .unwrap_or(0)
}

/// Memory left under the limits of a cgroup and its ancestors up to the mount point.
pub fn cgroup_left(cg: &CgroupMemory) -> Option<u64> {
    let (limit_file, usage_file) = if cg.v2 {
        ("memory.max", "memory.current")
    } else {
        ("memory.limit_in_bytes", "memory.usage_in_bytes")
    };
    let mut best: Option<u64> = None;
    let mut dir = cg.dir.clone();
    loop {
        if let Some(limit) = read_u64(&dir.join(limit_file)).filter(|&l| l < UNLIMITED) {
            let usage = read_u64(&dir.join(usage_file)).unwrap_or(0);
            let used = usage.saturating_sub(inactive_file(&dir, cg.v2));
            let left = limit.saturating_sub(used);
            best = Some(best.map_or(left, |b| b.min(left)));
        }
        if dir == cg.mount || !dir.pop() || !dir.starts_with(&cg.mount) {
            break;
        }
    }
    best
}

/// Memory left under this process's cgroup limits (None: no limit or not Linux).
pub fn cgroup_memory_left() -> Option<u64> {
    // Where this process's cgroup is does not change while it runs; reading the mount table
    // was most of the cost of starting a preview render.
    static WHERE: std::sync::OnceLock<Option<CgroupMemory>> = std::sync::OnceLock::new();
    let dir = WHERE.get_or_init(|| {
        let cgroup = std::fs::read_to_string("/proc/self/cgroup").ok()?;
        let mountinfo = std::fs::read_to_string("/proc/self/mountinfo").ok()?;
        find_cgroup(&cgroup, &mountinfo)
    });
    cgroup_left(dir.as_ref()?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_smallest_limit_wins_and_is_named() {
        let l = Limits {
            available: Some(8 << 30),
            address_space: Some(1 << 30),
            cgroup: Some(2 << 30),
        };
        assert_eq!(
            l.budget(),
            Budget {
                bytes: 1 << 30,
                source: Source::AddressSpace
            }
        );
        let l = Limits {
            available: Some(8 << 30),
            address_space: None,
            cgroup: Some(2 << 30),
        };
        assert_eq!(l.budget().source, Source::Cgroup);
        assert_eq!(Limits::default().budget().source, Source::Fallback);
        let e = check(
            3 << 30,
            Some(1 << 30),
            || "a big render".into(),
            || "reduce the size".into(),
        )
        .unwrap_err();
        let m = e.to_string();
        assert!(
            m.contains("a big render needs about 3.0 GiB")
                && m.contains("only 1.0 GiB")
                && m.contains("configured")
                && m.ends_with("reduce the size"),
            "{m}"
        );
        assert!(check(1 << 20, Some(1 << 30), String::new, String::new).is_ok());
    }

    #[test]
    fn bytes_for_people() {
        assert_eq!(fmt_bytes(512), "1 KiB");
        assert_eq!(fmt_bytes(340 << 20), "340 MiB");
        assert_eq!(fmt_bytes(21_600_000_000), "20.1 GiB");
    }

    #[test]
    fn address_space_limit_from_proc_limits() {
        let text = "Limit                     Soft Limit           Hard Limit           Units     \n\
                    Max stack size            8388608              unlimited            bytes     \n\
                    Max address space         1073741824           unlimited            bytes     \n";
        assert_eq!(parse_address_space_limit(text), Some(1 << 30));
        let text =
            "Max address space         unlimited            unlimited            bytes     \n";
        assert_eq!(parse_address_space_limit(text), None);
    }

    #[test]
    fn cgroups_v1_and_v2_are_found() {
        // v1 memory controller inside a container (the mount shows a sub-tree).
        let cg = "9:name=systemd:/\n4:memory:/process_api/abc\n0::/\n";
        let mi = "31 23 0:28 / /sys/fs/cgroup rw,relatime - tmpfs tmpfs rw,mode=755\n\
                  35 31 0:32 / /sys/fs/cgroup/memory rw,relatime - cgroup cgroup rw,memory\n\
                  40 31 0:37 / /sys/fs/cgroup/unified rw,relatime - cgroup2 cgroup2 rw\n";
        let c = find_cgroup(cg, mi).unwrap();
        assert!(!c.v2);
        assert_eq!(
            c.dir,
            PathBuf::from("/sys/fs/cgroup/memory/process_api/abc")
        );
        assert_eq!(c.mount, PathBuf::from("/sys/fs/cgroup/memory"));
        // Pure v2 with the container's own cgroup mounted at the root of the hierarchy.
        let cg = "0::/user.slice/app.scope\n";
        let mi = "30 1 0:26 /user.slice /sys/fs/cgroup rw - cgroup2 cgroup2 rw,nsdelegate\n";
        let c = find_cgroup(cg, mi).unwrap();
        assert!(c.v2);
        assert_eq!(c.dir, PathBuf::from("/sys/fs/cgroup/app.scope"));
        assert!(find_cgroup("", mi).is_none());
    }

    #[test]
    fn cgroup_limits_are_read_up_the_tree() {
        let root = std::env::temp_dir().join(format!("ugnis-cg-{}", std::process::id()));
        let leaf = root.join("a/b");
        std::fs::create_dir_all(&leaf).unwrap();
        // The parent's limit is tighter than the leaf's; inactive cache does not count.
        std::fs::write(root.join("a/memory.max"), "1000000\n").unwrap();
        std::fs::write(root.join("a/memory.current"), "600000\n").unwrap();
        std::fs::write(root.join("a/memory.stat"), "anon 1\ninactive_file 100000\n").unwrap();
        std::fs::write(leaf.join("memory.max"), "max\n").unwrap();
        std::fs::write(leaf.join("memory.current"), "5\n").unwrap();
        let cg = CgroupMemory {
            dir: leaf.clone(),
            mount: root.clone(),
            v2: true,
        };
        assert_eq!(cgroup_left(&cg), Some(500_000));
        std::fs::remove_dir_all(&root).unwrap();
        assert_eq!(unescape_mount("/a\\040b"), "/a b");
    }

    #[test]
    fn this_process_has_a_budget() {
        let b = budget();
        assert!(b.bytes > 0);
        if cfg!(target_os = "linux") {
            assert!(available_memory().is_some());
            assert_ne!(b.source, Source::Fallback);
        }
    }
}
