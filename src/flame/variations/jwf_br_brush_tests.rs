//! Checks of the brush strokes against independent oracles: the fallback brush's area, the
//! grid cell arithmetic, the spreading of weights into copies, JWildfire's random brush ids,
//! the image turning's identity and smoothing, and the drawn pixels' extent.

use super::super::jwf_br_raster::{Raster, rotate, smooth};
use super::*;

/// The default parameters of brush_stroke_wf, in registry order.
fn defaults() -> Vec<f64> {
    DEFS[0].params.iter().map(|p| p.default).collect()
}

fn texts(list: &str) -> Vec<String> {
    let mut t = vec![list.to_string()];
    t.resize(7, String::new());
    t
}

#[test]
fn the_fallback_brush_covers_its_disc() {
    let b = round_brush();
    assert_eq!((b.w, b.h), (320, 320));
    let drawn =
        b.px.iter()
            .filter(|&&p| channel_value(p, 0.0, true) >= 0.1)
            .count() as f64;
    // A disc of radius 120: its area within a perimeter's worth of pixels.
    let r = 120.0;
    let area = std::f64::consts::PI * r * r;
    assert!(
        (drawn - area).abs() < 2.0 * std::f64::consts::PI * r,
        "{drawn} vs {area}"
    );
    // Not inverted, the white outside is drawn instead.
    let outside =
        b.px.iter()
            .filter(|&&p| channel_value(p, 0.0, false) >= 0.1)
            .count() as f64;
    assert_eq!(drawn + outside, 320.0 * 320.0);
}

#[test]
fn grid_cells_are_cut_toward_zero() {
    // C's remainder keeps the dividend's sign: negative coordinates round up to a corner.
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    assert!(close(cell(0.037, 0.025), 0.025));
    assert!(close(cell(-0.037, 0.025), -0.025));
    assert!(close(cell(0.6, 0.25), 0.5));
    assert!(close(cell(-0.6, 0.25), -0.5));
    assert!(cell(1.0, 0.0).is_nan());
}

#[test]
fn weights_are_spread_over_64000_copies() {
    // 0.1, 1 and 0.5 of a sum of 1.6: 4000, 40000 and 20000 copies.
    assert_eq!(copies(&[0.1, 1.0, 0.5]), vec![4000, 40000, 20000]);
    // A negligible weight still gets one copy.
    assert_eq!(copies(&[1e-9, 1.0]), vec![1, 64000]);
    // More than 32000 pixels: twice their number in all.
    let c = copies(&vec![1.0; 40000]);
    assert!(c.iter().all(|&k| k == 2));
}

#[test]
fn random_brush_ids_follow_jwildfires_generator() {
    // Marsaglia's generator seeded 1 (2 to 6 brushes) and 2 (3 to 7), worked out by hand
    // from its recurrence: 5 and 4 brushes.
    let mut p = defaults();
    (p[17], p[18], p[19]) = (1.0, 2.0, 6.0);
    assert_eq!(
        brush_ids(&p, &texts("")),
        ["145", "126", "075", "194", "198"]
    );
    (p[17], p[18], p[19]) = (2.0, 3.0, 7.0);
    assert_eq!(brush_ids(&p, &texts("")), ["204", "241", "014", "240"]);
    // Seed 0: the list, empty pieces skipped and blanks trimmed.
    p[17] = 0.0;
    assert_eq!(
        brush_ids(&p, &texts("001,,005, 012 ")),
        ["001", "005", "012"]
    );
    assert_eq!(
        brush_resources(&p, &texts("001")),
        ["jwildfire:org/jwildfire/create/tina/variation/brush/brush001.png"]
    );
    assert!(is_jwildfire_brush("245") && !is_jwildfire_brush("246") && !is_jwildfire_brush("1"));
}

#[test]
fn turning_by_nothing_keeps_the_image_and_smoothing_softens_a_lone_pixel() {
    // A gentle ramp: no neighbour differs by more than 64, so smoothing leaves it.
    let (w, h) = (23, 17);
    let px = (0..w * h)
        .map(|i| {
            let v = ((i % w) * 5 + (i / w) * 3) as u8;
            [v, v, v, 255]
        })
        .collect();
    let img = Raster { w, h, px };
    assert_eq!(rotate(&img, 1.0, 0.0), img);
    // A white pixel on black differs from its upper and right neighbours by 765: it becomes
    // the mean of itself (255) and their weighted mean (0), in integers: 127.
    let mut dot = Raster {
        w: 5,
        h: 5,
        px: vec![[0, 0, 0, 255]; 25],
    };
    dot.px[12] = [255, 255, 255, 255];
    smooth(&mut dot);
    assert_eq!(dot.px[12], [127, 127, 127, 255]);
}

#[test]
fn a_missing_brush_draws_the_round_one() {
    // Brush 244 is not in the store here: the round brush stands in for it.
    let p = defaults();
    let t = texts("244");
    assert!(super::super::resources::image(&brush_name("244")).is_none());
    let d = build(&p, &t);
    // One image, the default 12 variants plus the image itself.
    assert_eq!(d[0], 13.0);
    let first = variant(&d, 0).expect("the image itself");
    let disc = round_brush()
        .px
        .iter()
        .filter(|&&p| channel_value(p, 0.0, true) >= 0.1)
        .count();
    assert_eq!(first[0] as usize, disc);
    // Every pixel the image itself gives lies in the disc (radius 120 of 320, plus a pixel).
    let mut rng = FastRng::new(5);
    for _ in 0..2000 {
        let (x, y) = draw_pixel(first, &mut rng).expect("a pixel");
        assert!(x.hypot(y) <= 121.5 / 320.0, "{x} {y}");
    }
    // Each eroded, turned variant keeps no more pixels than the image has.
    for g in 1..13 {
        let b = variant(&d, g).expect("a variant");
        assert!(b[0] >= 0.0 && b[0] <= 320.0 * 320.0);
    }
    assert!(variant(&d, 13).is_none());
}

#[test]
fn no_brush_at_all_gives_the_gradient() {
    // An empty list and no files: JWildfire's 256 × 256 corner gradient.
    let d = build(&defaults(), &texts(""));
    let first = variant(&d, 0).expect("the image itself");
    assert_eq!((first[2], first[3], first[4]), (256.0, 256.0, 256.0));
}

/// JWildfire's brush `id` from its resource folder (UGNIS_JWILDFIRE, else this machine's copy)
/// into the store; false when the folder is absent.
fn put_brush(id: &str) -> bool {
    let dir = std::env::var("UGNIS_JWILDFIRE")
        .unwrap_or_else(|_| "/tmp/jwildfire/src/resources".to_string());
    let path = std::path::Path::new(&dir).join(brush_name(id).trim_start_matches("jwildfire:"));
    let Ok(img) = image::open(&path) else {
        eprintln!("{} absent: skipped", path.display());
        return false;
    };
    let img = img.to_rgba8();
    let (w, h) = img.dimensions();
    let rgba = img.pixels().map(|p| p.0).collect();
    super::super::resources::put_image(
        &brush_name(id),
        super::super::resources::ResourceImage { w, h, rgba },
    )
}

/// JWildfire 9.00's variants of its default brushes (001, 005, 012) with the default
/// parameters, as its `AbstractBrushStrokeWFFunc.createPointsMap` builds them (found by
/// running JWildfire's classes): per variant, the entries of its list (copies), the distinct
/// pixels, and the mean position of the entries (x, y, to six decimals).
const JWILDFIRE_VARIANTS: [(f64, usize, f64, f64); 15] = [
    (65022.0, 9726, -0.026425, -0.021285),
    (63344.0, 5513, 0.041475, -0.031444),
    (64720.0, 5782, 0.045275, -0.026699),
    (61986.0, 9153, -0.033351, 0.097968),
    (63830.0, 1990, 0.080791, -0.216983),
    (63775.0, 15153, -0.026490, 0.009994),
    (63881.0, 5286, 0.090087, -0.150979),
    (63953.0, 3421, 0.042060, 0.050026),
    (63978.0, 1798, 0.137424, 0.215921),
    (64420.0, 10760, 0.115614, 0.041375),
    (64303.0, 12062, -0.011060, 0.030212),
    (64010.0, 1193, -0.132957, 0.141811),
    (63982.0, 8093, -0.035515, -0.129954),
    (64294.0, 5373, -0.189505, -0.122442),
    (62814.0, 12784, 0.079166, -0.231369),
];

#[test]
fn jwildfires_default_brushes_give_its_variants() {
    if !["001", "005", "012"].iter().all(|i| put_brush(i)) {
        return;
    }
    let d = build(&defaults(), &texts("001, 005, 012"));
    assert_eq!(d[0] as usize, JWILDFIRE_VARIANTS.len());
    for (g, &(total, distinct, mx, my)) in JWILDFIRE_VARIANTS.iter().enumerate() {
        let b = variant(&d, g).unwrap();
        let m = b[0] as usize;
        let (w, h, side) = (b[2], b[3], b[4]);
        let mut prev = 0.0;
        let (mut sx, mut sy) = (0.0, 0.0);
        for k in 0..m {
            let (i, run) = (b[5 + 2 * k], b[6 + 2 * k]);
            let c = run - prev;
            prev = run;
            let (col, row) = ((i % w).floor(), (i / w).floor());
            sx += c * (col - w / 2.0) / side;
            sy += c * (row - h / 2.0) / side;
        }
        assert_eq!((b[1], m), (total, distinct), "variant {g}");
        assert!(
            (sx / total - mx).abs() < 1e-6 && (sy / total - my).abs() < 1e-6,
            "variant {g}: {} {}",
            sx / total,
            sy / total
        );
    }
}
