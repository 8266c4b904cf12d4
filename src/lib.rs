//! ugnis — a fractal editor's engine: fractal flames and IFS (flam3-compatible renderer),
//! escape-time fractals and textured Bezier scenes, plus readers and writers for the file
//! formats of Fractint, flam3, Apophysis and Ultra Fractal.
//!
//! The engine (`flame`, `escape`, `surface`, `gradient`, `noise`, `explore`, with `memory` and
//! `threads` for the limits every renderer checks) has no GUI dependency; `io` reads and writes
//! files on top of it; the egui application lives in `app` behind the `gui` feature.

#![warn(missing_docs)]

pub mod escape;
pub mod explore;
pub mod flame;
pub mod gradient;
pub mod io;
pub mod memory;
pub mod noise;
pub mod palette;
pub mod rng;
pub mod sound;
pub mod surface;
pub mod threads;

#[cfg(feature = "gui")]
pub mod app;

/// ugnis's version, as written into files.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
