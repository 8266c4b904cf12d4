//! Ray-casting speed: the ray-cast jug scene (jug, floor, fBm texture with bumps,
//! one shadow ray per lit pixel) at 1024×768 on 2 threads, target ≤ 2 s; for comparison the
//! same scene through the z-buffer, the quaternion Julia example and the step-3 Menger sponge
//! at 640×480. Textures are made when the scene loads; the timings are the renders.
//!
//! Run: `cargo bench --bench scene_raycast`. On a shared machine the wall times include
//! waiting for the cores; the closing line also prints the CPU time of a ray-cast render
//! (all threads), whose half is the wall time on two cores of its own.

use std::path::Path;
use std::time::{Duration, Instant};

use criterion::{Criterion, criterion_group, criterion_main};
use ugnis::surface::{Renderer, Scene, render};

fn load(name: &str, w: u32, h: u32) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name);
    let mut s = ugnis::io::scene::read(&path).expect("example scene").scene;
    s.width = w;
    s.height = h;
    s
}

fn benches(c: &mut Criterion) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let mut g = c.benchmark_group("scene_raycast");
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(20));
    let jug = load("jug-raycast.toml", 1024, 768);
    g.bench_function("jug 1024x768 raycast+shadows 2 threads (target 2 s)", |b| {
        b.iter(|| pool.install(|| render(&jug, None)).unwrap())
    });
    let mut zb = jug.clone();
    zb.renderer = Renderer::ZBuffer;
    g.bench_function("jug 1024x768 zbuffer 2 threads", |b| {
        b.iter(|| pool.install(|| render(&zb, None)).unwrap())
    });
    let julia = load("quaternion-julia.toml", 640, 480);
    g.bench_function("quaternion julia 640x480 raycast+shadows 2 threads", |b| {
        b.iter(|| pool.install(|| render(&julia, None)).unwrap())
    });
    let menger = load("menger.toml", 640, 480);
    g.bench_function("menger step 3 640x480 raycast+shadows 2 threads", |b| {
        b.iter(|| pool.install(|| render(&menger, None)).unwrap())
    });
    g.finish();
    // CPU time of the process (user + system, all threads) from /proc/self/stat, in clock
    // ticks of 1/100 s (Linux's USER_HZ).
    let cpu = || -> Option<f64> {
        let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
        let rest = &stat[stat.rfind(')')? + 1..];
        let f: Vec<&str> = rest.split_whitespace().collect();
        let ticks = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
        Some(ticks / 100.0)
    };
    let (c0, t0) = (cpu(), Instant::now());
    let n = 5;
    for _ in 0..n {
        pool.install(|| render(&jug, None)).unwrap();
    }
    let wall = t0.elapsed().as_secs_f64() / n as f64;
    if let (Some(a), Some(b)) = (c0, cpu()) {
        let per = (b - a) / n as f64;
        println!(
            "jug 1024x768 ray-cast: {wall:.3} s wall, {per:.3} s CPU per render (2 threads: \
             {:.3} s on two free cores; target 2 s)",
            per / 2.0
        );
    }
}

criterion_group!(scene_raycast, benches);
criterion_main!(scene_raycast);
