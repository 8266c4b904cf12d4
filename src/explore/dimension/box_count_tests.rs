//! Unit tests of box counting.

use super::*;
use crate::explore::dimension::testing::{close, random_points};

#[test]
fn box_counting_of_a_segment_and_a_square() {
    let seg = random_points(1_000_000, 1, |u, _| [u, 0.3 * u]);
    let b = box_count_points(&seg).unwrap();
    let d = b.dimension().unwrap();
    assert!(close(d, 1.0, 0.02), "segment {d}");
    assert_eq!(b.fit_range.unwrap().0, 3);
    let sq = random_points(1_000_000, 2, |u, v| [u, v]);
    let b = box_count_points(&sq).unwrap();
    let d = b.dimension().unwrap();
    assert!(close(d, 2.0, 0.02), "square {d}");
    // Counts at the fit range: every cell of a filled square is met; the fit stops where
    // N would exceed 10 % of the points.
    let (k0, k1) = b.fit_range.unwrap();
    assert_eq!((k0, k1), (3, 8));
    assert_eq!(b.levels[7].count, 4u64.pow(8));
    assert!(b.levels[8].count as f64 > 0.1e6);
}

#[test]
fn counting_matches_a_direct_count() {
    let pts = random_points(5000, 3, |u, v| [u * u, v * u]);
    let b = box_count_points(&pts).unwrap();
    for lvl in [1u32, 4, 7, 12] {
        let n = 1u64 << lvl;
        let mut cells: Vec<(u64, u64)> = pts
            .iter()
            .map(|p| {
                let ix = (((p[0] - b.origin[0]) / b.side * n as f64) as u64).min(n - 1);
                let iy = (((p[1] - b.origin[1]) / b.side * n as f64) as u64).min(n - 1);
                (ix, iy)
            })
            .collect();
        cells.sort_unstable();
        cells.dedup();
        assert_eq!(
            b.levels[lvl as usize - 1].count,
            cells.len() as u64,
            "k={lvl}"
        );
    }
}

#[test]
fn bitmap_and_sorted_keys_agree() {
    // A parabola arc of 500 000 points stays under the 10 % rule past level 13 (about
    // 1.5·2^k cells at level k), so the finer levels are counted from sorted keys; both
    // ways give the same counts up to 13.
    let pts = random_points(500_000, 4, |u, _| [u, 0.5 * u * u]);
    let b = box_count_points(&pts).unwrap();
    assert_eq!(b.levels.len(), MAX_LEVEL as usize);
    let g = Grid::new(Bounds::of(pts.iter().copied())).unwrap();
    let mut bm = Bitmap::new();
    for p in &pts {
        bm.mark(g.key(*p).unwrap());
    }
    let coarse = bm.counts();
    for (k, c) in coarse.iter().enumerate() {
        assert_eq!(b.levels[k].count, *c, "k={}", k + 1);
    }
    for lvl in [14u32, 16, 18] {
        let n = 1u64 << lvl;
        let mut cells: Vec<(u64, u64)> = pts
            .iter()
            .map(|p| {
                let ix = (((p[0] - b.origin[0]) / b.side * n as f64) as u64).min(n - 1);
                let iy = (((p[1] - b.origin[1]) / b.side * n as f64) as u64).min(n - 1);
                (ix, iy)
            })
            .collect();
        cells.sort_unstable();
        cells.dedup();
        assert_eq!(
            b.levels[lvl as usize - 1].count,
            cells.len() as u64,
            "k={lvl}"
        );
    }
    assert!(b.fit_range.unwrap().1 > COARSE);
    // The stream gives the same result as the slice.
    let s = box_count_stream(|sink| pts.iter().for_each(|p| sink(*p))).unwrap();
    assert_eq!(s, b);
    // Spread keys, and keys crowded into one bucket, come out sorted.
    for spread in [4u32, 40] {
        let keys: Vec<u64> = (0..50_000u64)
            .map(|i| i.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> spread)
            .collect();
        let mut want = keys.clone();
        want.sort_unstable();
        assert_eq!(sort_keys(keys), want);
    }
}

#[test]
fn box_counting_refuses_degenerate_sets() {
    assert!(box_count_points(&[[1.0, 1.0]; 500]).is_err());
    assert!(box_count_points(&[[0.0, 0.0], [1.0, 1.0]]).is_err());
    assert!(box_count_points(&[]).is_err());
    assert!(check_samples(10).is_err());
    assert!(check_samples(MAX_SAMPLES + 1).is_err());
}

#[test]
fn box_counting_of_images() {
    // A filled disc: D = 2; a one-pixel circle outline: D = 1.
    let n = 1024u32;
    let disc = image::GrayImage::from_fn(n, n, |x, y| {
        let (dx, dy) = (x as f64 - 512.0, y as f64 - 512.0);
        image::Luma([if dx.hypot(dy) < 500.0 { 255 } else { 0 }])
    });
    let m = Mask::from_luma(&disc, 128, Ink::Auto);
    let d = box_count_mask(&m).unwrap().dimension().unwrap();
    assert!(close(d, 2.0, 0.05), "disc {d}");
    // Dark ink on white: the mask picks the dark pixels automatically.
    let line = image::GrayImage::from_fn(n, n, |x, y| image::Luma([if x == y { 0 } else { 255 }]));
    let m = Mask::from_luma(&line, 128, Ink::Auto);
    assert_eq!(m.count(), n as u64);
    let b = box_count_mask(&m).unwrap();
    assert!(close(b.dimension().unwrap(), 1.0, 0.02), "{b:?}");
    let m = Mask::from_luma(&line, 128, Ink::Light);
    assert_eq!(m.count(), (n * n - n) as u64);
    let empty = image::GrayImage::new(8, 8);
    assert!(box_count_mask(&Mask::from_luma(&empty, 128, Ink::Light)).is_err());
}
