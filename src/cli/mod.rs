//! Command-line subcommands. Each returns `anyhow::Result`; `main` prints the one error message
//! and exits with status 1.

pub mod animate;
pub mod convert;
pub mod dimension;
pub mod escape;
pub mod info;
pub mod lorenz;
pub mod lsystem;
pub mod random;
pub mod render;
pub mod scene;

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressStyle};

/// A progress bar on stderr when it is a terminal, hidden otherwise.
pub fn progress_bar(len: u64, what: &str) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::new(len);
    pb.set_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {percent:>3}% {elapsed_precise} eta {eta}")
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    pb.set_message(what.to_string());
    pb
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
