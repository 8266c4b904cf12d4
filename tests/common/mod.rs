//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod vectors;

use std::path::{Path, PathBuf};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

pub fn example(name: &str) -> PathBuf {
    root().join("examples").join(name)
}

pub fn fixture(name: &str) -> PathBuf {
    root().join("tests").join("fixtures").join(name)
}

/// RGB as f64 after a 3×3 box blur with clamped edges.
pub fn blurred_rgb(img: &image::RgbImage) -> Vec<f64> {
    let (w, h) = (img.width() as i64, img.height() as i64);
    let mut out = vec![0.0; (w * h * 3) as usize];
    for y in 0..h {
        for x in 0..w {
            for c in 0..3 {
                let mut s = 0.0;
                for dy in -1..=1 {
                    for dx in -1..=1 {
                        let xx = (x + dx).clamp(0, w - 1) as u32;
                        let yy = (y + dy).clamp(0, h - 1) as u32;
                        s += img.get_pixel(xx, yy).0[c] as f64;
                    }
                }
                out[((y * w + x) * 3 + c as i64) as usize] = s / 9.0;
            }
        }
    }
    out
}

/// PSNR over RGB after a 3×3 box blur (the comparison used against flam3's golden images).
pub fn psnr_blurred(a: &image::RgbImage, b: &image::RgbImage) -> f64 {
    assert_eq!(a.dimensions(), b.dimensions(), "image sizes differ");
    let (pa, pb) = (blurred_rgb(a), blurred_rgb(b));
    let mse: f64 = pa
        .iter()
        .zip(&pb)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        / pa.len() as f64;
    if mse == 0.0 {
        99.0
    } else {
        10.0 * (255.0f64 * 255.0 / mse).log10()
    }
}

pub fn load_rgb(p: &Path) -> image::RgbImage {
    image::open(p)
        .unwrap_or_else(|e| panic!("cannot open {}: {e}", p.display()))
        .to_rgb8()
}

/// A fresh temporary directory for one test.
/// Removes a test's temporary directory when the test ends well (a failed test leaves it,
/// to be looked at).
pub struct Cleanup(pub PathBuf);

impl Drop for Cleanup {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

pub fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ugnis-test-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Render options with this seed and thread count, the rest at their defaults.
pub fn opts(seed: u64, threads: usize) -> ugnis::flame::render::RenderOptions {
    ugnis::flame::render::RenderOptions {
        seed,
        threads,
        ..Default::default()
    }
}

/// Run a render to its end (never cancelled).
pub fn run(r: &mut ugnis::flame::render::Renderer) {
    assert!(r.run_all(3, &std::sync::atomic::AtomicBool::new(false), |_| {}));
}
