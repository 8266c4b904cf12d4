//! A poster under a tight address-space limit: the strips are chosen from the same estimate
//! and budget each strip's check uses, and they fit.

use super::*;

#[test]
fn a_poster_under_an_address_space_limit_picks_strips_that_fit() {
    let dir = common::temp_dir("hard-strips-as");
    let f = small_flame(&dir, "1");
    let out = dir.join("poster.png");
    for (mib, threads) in [(512u64, "2"), (640, "4")] {
        let (code, _, err) = ugnis_ulimit(
            mib << 10,
            &[
                "render",
                s(&f),
                "-o",
                s(&out),
                "--size",
                "3000x2000",
                "--quality",
                "0.05",
                "--threads",
                threads,
                "--progress",
                "none",
            ],
        );
        assert_eq!(code, 0, "{mib} MiB, {threads} threads: {err}");
        assert!(err.contains("strips"), "{err}");
        let img = image::open(&out).unwrap();
        assert_eq!((img.width(), img.height()), (3000, 2000));
        std::fs::remove_file(&out).unwrap();
    }
    assert_eq!(listing(&dir), ["q.flame"]);
    std::fs::remove_dir_all(&dir).unwrap();
}
