//! The timeline's playback and scrubbing, measured the way the editor drives them: every frame
//! the flame at the current frame is made from its keys (`Keyframes::apply`), submitted to the
//! [`PreviewWorker`] as one quick pass and waited for, as the timeline waits for the preview
//! to show a frame before it asks the next.
//!
//! * **play**: frames in order of a keyed loop (every transform turns once, the camera zooms
//!   in and out), at the animation quality (Options › Display, 1 sample per pixel by default).
//! * **scrub**: the same frames in a jumping order, as a drag over the ruler asks them, at the
//!   preview quality of a drag (Options › Display, 5 by default).
//!
//! Preview size 320×240, 2 threads. Target: ≥ 20 frames per second.
//!
//! Run: `cargo bench --bench timeline_playback` (prints a table; exits 1 if a target is
//! missed).

use std::path::Path;
use std::time::{Duration, Instant};

use ugnis::app::Options;
use ugnis::app::flame_tab::preview::{PreviewEvent, PreviewJob, PreviewWorker};
use ugnis::app::flame_tab::rotation_loop;
use ugnis::flame::Flame;
use ugnis::flame::keyframes::{FlameParam, Key, Target};

const W: u32 = 320;
const H: u32 = 240;
const THREADS: usize = 2;
const FRAMES: u32 = 120;

/// A flame of the examples with a rotation loop and a zoom that breathes.
fn keyed(name: &str) -> Flame {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut f = ugnis::io::read_flames(&dir.join(format!("{name}.flame")), &Default::default())
        .expect("example")
        .value
        .remove(0);
    f.keys = rotation_loop(&f, 1.0, FRAMES);
    let z = f.zoom;
    let c = f.keys.curve_mut(Target::Flame(FlameParam::Zoom));
    for (frame, v) in [(0.0, z), (60.0, z + 0.5)] {
        c.insert(Key::new(frame, v)).expect("finite keys");
    }
    f
}

/// Show `frames` of `f` one after another at quality `q`; frames per second.
fn show(worker: &PreviewWorker, f: &Flame, frames: &[u32], q: f64, generation: &mut u64) -> f64 {
    let t0 = Instant::now();
    for &k in frames {
        let at = f.keys.apply(f, k as f64);
        *generation += 1;
        worker.submit(PreviewJob {
            flame: at,
            width: W,
            height: H,
            first_quality: q,
            final_quality: q,
            noise_target: None,
            least_quality: 0.0,
            threads: THREADS,
            generation: *generation,
            motion: None,
        });
        loop {
            match worker.wait(Duration::from_secs(30)) {
                Some(PreviewEvent::Frame(fr)) if fr.generation == *generation => break,
                Some(PreviewEvent::Error { message, .. }) => panic!("preview failed: {message}"),
                Some(_) => {}
                None => panic!("no preview within 30 s"),
            }
        }
    }
    frames.len() as f64 / t0.elapsed().as_secs_f64()
}

fn main() {
    let filter: Option<String> = std::env::args().skip(1).find(|a| !a.starts_with('-'));
    let worker = PreviewWorker::new(|| {});
    let mut generation = 0;
    let mut worst = f64::MAX;
    let o = Options::default();
    let (play_q, scrub_q) = (o.animation_quality, o.preview_quality);
    println!(
        "timeline: {W}x{H}, {THREADS} threads, {FRAMES} frames; play at quality {play_q}, \
         scrub at quality {scrub_q}\n{:<14} {:>10} {:>10}",
        "flame", "play fps", "scrub fps"
    );
    let in_order: Vec<u32> = (0..FRAMES).collect();
    // A drag back and forth over the ruler, in uneven steps.
    let scrub: Vec<u32> = (0..FRAMES)
        .map(|k| (k * 37 + (k * k) % 11) % FRAMES)
        .collect();
    for name in [
        "orchid",
        "ember-swirl",
        "lagoon-post",
        "moss-classic",
        "sierpinski",
    ] {
        if filter.as_deref().is_some_and(|f| !name.contains(f)) {
            continue;
        }
        let f = keyed(name);
        // Warm the worker's threads and memory.
        show(&worker, &f, &in_order[..5], play_q, &mut generation);
        let play = show(&worker, &f, &in_order, play_q, &mut generation);
        let scrubbed = show(&worker, &f, &scrub, scrub_q, &mut generation);
        println!("{name:<14} {play:>10.1} {scrubbed:>10.1}");
        worst = worst.min(play).min(scrubbed);
    }
    let ok = worst >= 20.0;
    println!(
        "slowest {worst:.1} fps (target ≥ 20): {}",
        if ok { "OK" } else { "MISSED" }
    );
    if !ok {
        std::process::exit(1);
    }
}
