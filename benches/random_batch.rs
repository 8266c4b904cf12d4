//! Random batch speed: `ugnis random --count 100` with 128×128 thumbnails on 2
//! threads, as the user runs it (the release binary). Target: ≤ 20 s per batch.
//!
//! Run: `cargo bench --bench random_batch` (exits 1 if the target is missed).

use std::process::Command;
use std::time::Instant;

fn main() {
    let exe = env!("CARGO_BIN_EXE_ugnis");
    let dir = std::env::temp_dir().join(format!("ugnis-bench-batch-{}", std::process::id()));
    let mut worst = 0.0f64;
    println!("100 random flames + 128x128 thumbnails (quality 50), 2 threads");
    for seed in [1u64, 2, 3, 4, 5] {
        let _ = std::fs::remove_dir_all(&dir);
        let t = Instant::now();
        let out = Command::new(exe)
            .args([
                "random",
                "--count",
                "100",
                "--threads",
                "2",
                "--size",
                "128x128",
            ])
            .args(["--seed", &seed.to_string()])
            .arg("--thumbs")
            .arg(dir.join("thumbs"))
            .arg("-o")
            .arg(dir.join("batch.fla"))
            .output()
            .expect("run ugnis");
        let s = t.elapsed().as_secs_f64();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        println!(
            "seed {seed}: {s:.2} s  ({})",
            String::from_utf8_lossy(&out.stdout).trim()
        );
        worst = worst.max(s);
    }
    let _ = std::fs::remove_dir_all(&dir);
    let ok = worst <= 20.0;
    println!(
        "worst {worst:.2} s (target ≤ 20 s): {}",
        if ok { "OK" } else { "MISSED" }
    );
    if !ok {
        std::process::exit(1);
    }
}
