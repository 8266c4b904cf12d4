//! Command-line subcommands. Each returns `anyhow::Result`; `main` prints the one error message
//! and exits with status 1 (a signal ends a command at once with 128 + its number, see
//! [`signals`]).
//!
//! Shared here: messages on stderr that never panic ([`stderr!`]), progress on stderr (a bar
//! on a terminal, a plain line every few seconds otherwise), thread counts, output checks and
//! argument parsers.

/// `eprintln!` that never panics: a message that cannot be written to stderr (a full disk, a
/// closed pipe, `2>/dev/full`) is dropped. Every message of the command line goes through it.
macro_rules! stderr {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}

pub mod animate;
mod animate_sound;
pub mod convert;
pub mod dimension;
pub mod escape;
pub mod info;
pub mod lorenz;
pub mod lsystem;
pub mod merge;
pub mod random;
pub mod render;
pub mod scene;
pub mod signals;
pub mod thumbnail;
pub mod zoom_video;

use std::io::{IsTerminal, Write};
use std::path::Path;
use std::sync::Mutex;
use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::{Duration, Instant};

use anyhow::{Context, Result};
use clap::ValueEnum;
use indicatif::{ProgressBar, ProgressStyle};
use ugnis::io::diag::Parsed;
use ugnis::io::flam3_xml::{FlameFile, ReadOptions};
use ugnis::io::{self, View};

/// How progress is shown on stderr.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum ProgressMode {
    /// A bar when stderr is a terminal, plain lines otherwise
    #[default]
    Auto,
    /// Always a bar
    Bar,
    /// A line every few seconds ("rendering x: 42% …"), for logs and pipes
    Plain,
    /// Nothing
    None,
}

static PROGRESS_MODE: OnceLock<ProgressMode> = OnceLock::new();

/// Set the progress mode (once, from the command line).
pub fn set_progress_mode(m: ProgressMode) {
    let _ = PROGRESS_MODE.set(m);
}

/// Seconds between plain progress lines (`UGNIS_PROGRESS_SECONDS` overrides, e.g. for tests).
fn plain_interval() -> Duration {
    let s = std::env::var("UGNIS_PROGRESS_SECONDS")
        .ok()
        .and_then(|v| v.parse::<f64>().ok())
        .filter(|v| v.is_finite() && *v >= 0.0)
        .unwrap_or(5.0);
    Duration::from_secs_f64(s)
}

/// Progress of one piece of work, shown as the mode says.
pub struct Progress {
    inner: Inner,
}

enum Inner {
    Bar(ProgressBar),
    Plain(Plain),
    Hidden,
}

struct Plain {
    what: String,
    len: u64,
    pos: AtomicU64,
    start: Instant,
    interval: Duration,
    last: Mutex<Instant>,
}

impl Plain {
    fn report(&self, pos: u64) {
        let now = Instant::now();
        let Ok(mut last) = self.last.lock() else {
            return;
        };
        if now.duration_since(*last) < self.interval {
            return;
        }
        *last = now;
        let frac = pos as f64 / self.len.max(1) as f64;
        let el = now.duration_since(self.start).as_secs_f64();
        let eta = if frac > 0.0 {
            format!(", about {} left", clock(el / frac - el))
        } else {
            String::new()
        };
        stderr!(
            "{}: {:.0}% ({} elapsed{eta})",
            self.what,
            100.0 * frac.min(1.0),
            clock(el)
        );
    }
}

/// h:mm:ss or m:ss.
fn clock(secs: f64) -> String {
    let s = secs.max(0.0).round() as u64;
    if s >= 3600 {
        format!("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
    } else {
        format!("{}:{:02}", s / 60, s % 60)
    }
}

impl Progress {
    pub fn set_position(&self, p: u64) {
        match &self.inner {
            Inner::Bar(b) => b.set_position(p),
            Inner::Plain(pl) => {
                pl.pos.store(p, Ordering::Relaxed);
                pl.report(p);
            }
            Inner::Hidden => {}
        }
    }

    pub fn inc(&self, d: u64) {
        match &self.inner {
            Inner::Bar(b) => b.inc(d),
            Inner::Plain(pl) => {
                let p = pl.pos.fetch_add(d, Ordering::Relaxed) + d;
                pl.report(p);
            }
            Inner::Hidden => {}
        }
    }

    /// A line on stderr above the bar (which is drawn again below it).
    pub fn note(&self, line: &str) {
        match &self.inner {
            Inner::Bar(b) => b.suspend(|| stderr!("{line}")),
            _ => stderr!("{line}"),
        }
    }

    pub fn finish_and_clear(&self) {
        if let Inner::Bar(b) = &self.inner {
            b.finish_and_clear();
        }
    }
}

/// Progress of `len` steps of `what`, on stderr as the progress mode says.
pub fn progress_bar(len: u64, what: &str) -> Progress {
    let mode = *PROGRESS_MODE.get().unwrap_or(&ProgressMode::Auto);
    let terminal = std::io::stderr().is_terminal();
    let inner = match mode {
        ProgressMode::None => Inner::Hidden,
        ProgressMode::Bar => Inner::Bar(bar(len, what)),
        ProgressMode::Auto if terminal => Inner::Bar(bar(len, what)),
        ProgressMode::Auto | ProgressMode::Plain => Inner::Plain(Plain {
            what: what.to_string(),
            len,
            pos: AtomicU64::new(0),
            start: Instant::now(),
            interval: plain_interval(),
            last: Mutex::new(Instant::now()),
        }),
    };
    Progress { inner }
}

fn bar(len: u64, what: &str) -> ProgressBar {
    let pb = ProgressBar::new(len);
    pb.set_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {percent:>3}% {elapsed_precise} eta {eta}")
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    pb.set_message(what.to_string());
    pb
}

/// The cancel flag given to renderers. Signals end a command from their own thread
/// ([`signals`]), so on the command line it is never raised.
static NEVER_CANCELLED: AtomicBool = AtomicBool::new(false);

/// The cancel flag for renderers that take one (never raised: see [`signals`]).
pub fn no_cancel() -> &'static AtomicBool {
    &NEVER_CANCELLED
}

/// The error of a render that stopped before its end although nothing cancelled it.
pub fn stopped_early() -> anyhow::Error {
    anyhow::anyhow!("the render stopped before its end")
}

/// Under an address-space limit (`ulimit -v`, `prlimit --as`), keep glibc to two malloc
/// arenas. glibc gives every thread that allocates an arena of its own, reserving 64 MiB of
/// address space apiece: with a few render threads that is the address space the memory
/// estimate counted for the render, and a render chosen to fit would fail to allocate. The
/// render threads allocate their buffers before they start, so two arenas cost nothing.
pub fn fit_allocator_to_address_limit() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: getrlimit fills the struct it is given; mallopt only sets a tuning value, and
    // runs before any other thread exists.
    unsafe {
        let mut r = libc::rlimit {
            rlim_cur: 0,
            rlim_max: 0,
        };
        if libc::getrlimit(libc::RLIMIT_AS, &mut r) == 0 && r.rlim_cur != libc::RLIM_INFINITY {
            libc::mallopt(libc::M_ARENA_MAX, 2);
        }
    }
}

/// Resolve a thread count (0: all cores), clamped to a sane maximum with a warning.
pub fn threads(requested: usize) -> usize {
    let t = ugnis::threads::Threads::resolve(requested);
    if let Some(w) = t.warning() {
        stderr!("warning: {w}");
    }
    t.count
}

/// A rayon pool of the thread count asked for (0: all cores), resolved by [`threads`].
pub fn pool(requested: usize) -> Result<rayon::ThreadPool> {
    pool_of(threads(requested))
}

/// A rayon pool of exactly `count` threads (a count [`threads`] has resolved).
pub fn pool_of(count: usize) -> Result<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(count)
        .build()
        .context("cannot start worker threads")
}

/// The command that reads `path`, by the view that opens its kind ([`io::view_of`]): for
/// messages about a file given to a command that does not read it.
pub fn command_for(path: &Path) -> String {
    let p = path.display();
    match io::view_of(io::kind_of(path)) {
        View::Flame => format!("ugnis render {p} -o OUT.png"),
        View::Escape => format!("ugnis escape --view {p} -o OUT.png"),
        View::Scene => format!("ugnis scene {p} -o OUT.png"),
        View::LSystem => format!("ugnis lsystem {p} -o OUT.svg"),
        View::Gradients => format!("ugnis info {p}"),
        View::GradientFromImage => format!("ugnis convert {p} OUT.ugr"),
        View::RenderState => format!("ugnis render --resume {p} -o OUT.png"),
    }
}

/// Read the flames of any flame source ([`io::read_flame_file`]); a file that another view
/// opens is refused with the command that reads it, a flame without xforms with how a
/// template of render settings is used.
pub fn read_flame_file(path: &Path, opts: &ReadOptions) -> Result<Parsed<FlameFile>> {
    io::read_flame_file(path, opts).map_err(|e| {
        if e.code == "XML007" && e.message.contains("no <xform>") {
            let p = path.display();
            anyhow::anyhow!(
                "{e}\n  a flam3 template of render settings? apply it: ugnis render FLAME --template {p}"
            )
        } else if io::view_of(io::kind_of(path)) == View::Flame {
            e.into()
        } else {
            anyhow::anyhow!("{e}\n  try: {}", command_for(path))
        }
    })
}

/// Check before any long work that the outputs of a command can be saved, by the output rule
/// of [`io::target`]: each is a regular file or a new name in an existing directory that
/// accepts files, none is one of the command's `inputs`, and none is named twice (so a long
/// render does not end in "cannot write", and no save replaces what the command reads).
pub fn check_outputs(inputs: &[&Path], outputs: &[&Path]) -> Result<()> {
    let mut dirs = std::collections::HashSet::new();
    for o in outputs {
        // One trial save per directory; every name is checked against the rule.
        if dirs.insert(io::atomic::target_dir(o)) {
            io::atomic::check_writable(o)
        } else {
            io::target::check_target(o)
        }
        .with_context(|| format!("cannot write '{}'", o.display()))?;
    }
    io::target::check_distinct(inputs, outputs)?;
    Ok(())
}

/// Write to stdout; a closed pipe (`ugnis info … | head -1`) ends the output quietly.
pub fn print_stdout(text: &str) -> Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        r => r.context("cannot write to standard output"),
    }
}

/// Parse a finite number (as in files: no nan, inf, hexadecimal or decimal comma).
pub fn finite(s: &str) -> Result<f64, String> {
    ugnis::io::diag::parse_number(s.trim()).map_err(|e| match e {
        ugnis::io::diag::NumberError::Overflow => format!("'{s}' is too large"),
        e => format!("{}; expected a finite number", e.describe(s)),
    })
}

/// Parse a byte count: 1048576, 512K, 300M, 2G (binary units).
pub fn parse_bytes(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let (num, mult) = match t.char_indices().last() {
        Some((i, c)) if c.is_ascii_alphabetic() => {
            let m: u64 = match c.to_ascii_uppercase() {
                'K' => 1 << 10,
                'M' => 1 << 20,
                'G' => 1 << 30,
                'T' => 1 << 40,
                _ => return Err(format!("'{s}': unit must be K, M, G or T")),
            };
            (&t[..i], m)
        }
        _ => (t, 1),
    };
    let v: f64 = num
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a size such as 512M or 2G"))?;
    let bytes = v * mult as f64;
    if !(1.0..1e18).contains(&bytes) {
        return Err(format!("size '{s}' must be between 1 byte and 1e18 bytes"));
    }
    Ok(bytes as u64)
}

/// Parse "WxH".
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("size '{s}' must be WIDTHxHEIGHT, e.g. 640x480"))?;
    let w: u32 = w
        .trim()
        .parse()
        .map_err(|_| format!("width '{w}' is not a positive integer"))?;
    let h: u32 = h
        .trim()
        .parse()
        .map_err(|_| format!("height '{h}' is not a positive integer"))?;
    if w == 0 || h == 0 || w > 100_000 || h > 100_000 {
        return Err(format!(
            "size {w}x{h} must be between 1x1 and 100000x100000"
        ));
    }
    Ok((w, h))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finite_numbers_only() {
        assert_eq!(finite("0.25"), Ok(0.25));
        assert_eq!(finite("-3"), Ok(-3.0));
        for bad in [
            "nan", "NaN", "inf", "-inf", "infinity", "1e999", "0,5", "0x10", "",
        ] {
            assert!(finite(bad).is_err(), "{bad}");
        }
        assert!(finite("0,5").unwrap_err().contains("comma"));
    }

    #[test]
    fn clock_format() {
        assert_eq!(clock(5.4), "0:05");
        assert_eq!(clock(3725.0), "1:02:05");
    }
}
