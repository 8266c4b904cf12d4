//! Scene speed: the textured (flame), bump-mapped, Phong-lit reference jug at
//! 1024×768 on 2 threads. Textures are made when the scene loads; this times the render
//! (tessellation, rasterising, shading). Target ≤ 200 ms.
//!
//! Run: `cargo bench --bench scene_jug` (exits 1 if the target is missed).

use std::path::Path;
use std::time::Instant;

fn main() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/jug.toml");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let t = Instant::now();
    let mut loaded = ugnis::io::scene::read(&path).expect("jug scene");
    let load_ms = t.elapsed().as_secs_f64() * 1000.0;
    loaded.scene.width = 1024;
    loaded.scene.height = 768;
    let mut times = Vec::new();
    for _ in 0..15 {
        let t = Instant::now();
        let img = pool
            .install(|| ugnis::surface::render(&loaded.scene, None))
            .unwrap();
        times.push(t.elapsed().as_secs_f64() * 1000.0);
        assert_eq!(img.width(), 1024);
    }
    times.sort_by(f64::total_cmp);
    let med = times[times.len() / 2];
    println!(
        "jug 1024x768, flame texture + fBm bumps, Phong, 2 threads: median {med:.1} ms, \
         best {:.1} ms, worst {:.1} ms (scene load incl. textures {load_ms:.0} ms) — target ≤ 200 ms: {}",
        times[0],
        times[times.len() - 1],
        if med <= 200.0 { "OK" } else { "MISSED" }
    );
    if med > 200.0 {
        std::process::exit(1);
    }
}
