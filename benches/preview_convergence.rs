//! How fast the editor's preview becomes clean, measured the way the GUI drives it: the
//! [`PreviewWorker`] refines a still flame to the preview's noise target (Options › Display)
//! at 800×600 on 2 threads. For each of the seven benchmark flames (four examples, three
//! random flames) it reports
//!
//! * the time until the preview is as clean as a quality-100 render: its PSNR against a
//!   quality-1000 render reaches that of a quality-100 render (goal ≤ 2 s);
//! * when the preview stopped, at which quality and noise estimate, and its PSNR then;
//! * the process's CPU use in the second after it stopped (goal 0 %).
//!
//! References are rendered with another seed than the preview, so that their samples are
//! independent of it.
//!
//! Run: `cargo bench --bench preview_convergence` (an argument filters the flames by name).

use std::path::Path;
use std::time::{Duration, Instant};

use ugnis::app::Options;
use ugnis::app::flame_tab::preview::{PreviewEvent, PreviewJob, PreviewWorker};
use ugnis::flame::Flame;

#[path = "common/flames.rs"]
mod common_flames;
use common_flames::flames;
use ugnis::flame::render::{RenderOptions, render};

const W: u32 = 800;
const H: u32 = 600;
const THREADS: usize = 2;

/// The flame at the preview's size and this quality, rendered with `seed`, as RGB8.
fn reference(f: &Flame, quality: f64, seed: u64) -> Vec<u8> {
    let mut g = f.clone();
    g.resize_keep_framing(W, H);
    g.quality = quality;
    let o = RenderOptions {
        seed,
        threads: THREADS,
        ..RenderOptions::default()
    };
    render(&g, &o).expect("renders").to_rgb8().into_raw()
}

/// Peak signal-to-noise ratio of `a` against `b` in dB.
fn psnr(a: &[u8], b: &[u8]) -> f64 {
    let mse = a
        .iter()
        .zip(b)
        .map(|(x, y)| (*x as f64 - *y as f64).powi(2))
        .sum::<f64>()
        / a.len().max(1) as f64;
    if mse == 0.0 {
        return f64::INFINITY;
    }
    10.0 * (255.0f64 * 255.0 / mse).log10()
}

/// CPU seconds this process has used (user + system), from /proc.
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The fields after the command name (which may hold spaces) in parentheses.
    let rest = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

fn main() {
    let filter: Option<String> = std::env::args().skip(1).find(|a| !a.starts_with('-'));
    let mut options = Options::default();
    // Other targets, for calibrating the default: UGNIS_PREVIEW_NOISE, UGNIS_PREVIEW_MAX.
    let env = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<f64>().ok());
    if let Some(n) = env("UGNIS_PREVIEW_NOISE") {
        options.preview_noise = n;
    }
    if let Some(q) = env("UGNIS_PREVIEW_MAX") {
        options.preview_max_quality = q;
    }
    if let Some(q) = env("UGNIS_PREVIEW_LEAST") {
        options.preview_least_quality = q;
    }
    println!(
        "preview convergence: {W}x{H}, {THREADS} threads, noise target {} levels, preview \
         quality {} → at least {}, at most {}\n{:<13} {:>7} {:>7} {:>9} {:>8} {:>7} {:>7} {:>7} {:>7}",
        options.preview_noise,
        options.preview_quality,
        options.preview_least_quality,
        options.preview_max_quality,
        "flame",
        "q100 dB",
        "t→q100",
        "stopped s",
        "quality",
        "noise",
        "dB",
        "frames",
        "CPU %"
    );
    let worker = PreviewWorker::new(|| {});
    let mut worst = 0.0f64;
    let mut worst_cpu = 0.0f64;
    for (generation, (name, flame)) in flames().into_iter().enumerate() {
        if filter.as_deref().is_some_and(|f| !name.contains(f)) {
            continue;
        }
        let truth = reference(&flame, 1000.0, 7);
        if let Some(dir) = std::env::var_os("UGNIS_BENCH_DUMP") {
            image::RgbImage::from_raw(W, H, truth.clone())
                .expect("size")
                .save(Path::new(&dir).join(format!("{name}-ref.png")))
                .expect("writes");
        }
        let q100 = psnr(&reference(&flame, 100.0, 5), &truth);
        let t0 = Instant::now();
        worker.submit(PreviewJob {
            flame: flame.clone(),
            width: W,
            height: H,
            first_quality: options.preview_quality,
            final_quality: options.preview_max_quality,
            noise_target: Some(options.preview_noise),
            least_quality: options.preview_least_quality,
            threads: THREADS,
            generation: generation as u64 + 1,
            motion: None,
        });
        let mut reached = None;
        let mut frames = 0;
        let verbose = std::env::var_os("UGNIS_BENCH_VERBOSE").is_some();
        let last = loop {
            match worker.wait(Duration::from_secs(300)) {
                Some(PreviewEvent::Frame(f)) => {
                    frames += 1;
                    let t = t0.elapsed().as_secs_f64();
                    let rgb: Vec<u8> = f
                        .image
                        .pixels
                        .iter()
                        .flat_map(|c| [c.r(), c.g(), c.b()])
                        .collect();
                    let db = psnr(&rgb, &truth);
                    if let Some(dir) = std::env::var_os("UGNIS_BENCH_DUMP") {
                        let path = Path::new(&dir).join(format!("{name}-{:.0}.png", f.quality));
                        let [w, h] = f.image.size;
                        image::RgbImage::from_raw(w as u32, h as u32, rgb.clone())
                            .expect("size")
                            .save(path)
                            .expect("writes");
                    }
                    if verbose {
                        println!(
                            "    {t:6.2} s  quality {:8.1}  noise {:>6}  {db:5.1} dB",
                            f.quality,
                            f.noise.map_or("—".into(), |n| format!("{n:.2}"))
                        );
                    }
                    if reached.is_none() && db >= q100 {
                        reached = Some(t);
                    }
                    if f.done {
                        break (t, f, db);
                    }
                }
                Some(PreviewEvent::Error { message, .. }) => panic!("{name}: {message}"),
                None => panic!("{name}: no frame for 5 minutes"),
            }
        };
        let c0 = cpu_seconds();
        std::thread::sleep(Duration::from_secs(1));
        let cpu = match (c0, cpu_seconds()) {
            (Some(a), Some(b)) => (b - a) * 100.0,
            _ => f64::NAN,
        };
        let (stop_t, f, db) = last;
        let reach = reached.map_or("never".to_string(), |t| format!("{t:.2}"));
        println!(
            "{name:<13} {q100:>7.1} {reach:>7} {stop_t:>9.2} {:>8.0} {:>7} {db:>7.1} {frames:>7} {cpu:>7.1}",
            f.quality,
            f.noise.map_or("—".into(), |n| format!("{n:.2}")),
        );
        worst = worst.max(reached.unwrap_or(f64::INFINITY));
        worst_cpu = worst_cpu.max(cpu);
    }
    println!(
        "slowest time to a quality-100 picture {worst:.2} s (goal ≤ 2 s): {}; CPU after it \
         stopped at most {worst_cpu:.1} % (goal 0 %)",
        if worst <= 2.0 { "met" } else { "missed" }
    );
}
