//! `wangtiles`, JWildfire's Wang tiles (JWildfire 9.00, `WangTilesFunc`, by Jesus Sosa;
//! formulas and behaviour written anew).
//!
//! When it is set up, the variation lays out a tiling of 12 × 8 tiles of one of JWildfire's
//! 105 tile sets (`id`) from `java.util.Random(seed)` ([`super::jwf_wt_tiling`]) and puts the
//! tiles' images, 32 × 32 pixels each, side by side into a 384 × 256 image. Each call moves the
//! running sum by (weight·rect·(ξ − ½), weight·(ξ − ½)) (rect 1, or 1.5 when `square` is 0)
//! and looks the moved point up in that image as JWildfire's image variations do (scale,
//! offset, optional tiling; black outside): the pixel becomes the point's own colour and,
//! through the palette entry nearest to it, its colour coordinate; its brightness times
//! `scale_z` plus `offset_z` replaces z (`reset_z` not 0) or adds to it.
//!
//! The tile images are JWildfire's own GIF files, which ugnis does not ship: they are read
//! from the user's JWildfire installation and handed over in the resource store
//! ([`super::resources`]) under `jwildfire:org/jwildfire/icons/<kind>/<set>/<n>.gif`.
//! JWildfire draws each GIF onto a black opaque image, so a transparent pixel reads black
//! (here: a pixel's colour is blended onto black by its alpha). A tile whose image is not in
//! the store (no JWildfire installation, or a number the set has no file for, where
//! JWildfire's own set-up fails) is drawn from what the tiling knows about it, in grey levels
//! (dark for 0, light for the largest value): the edge sets' and twin sets' tiles as four
//! triangles, each side's in the colour of that edge; the corner sets' as four quarters in
//! their corners' colours; the blob sets' as a 3 × 3 grid of their corners, edges and a light
//! middle; the block and Truchet sets' in one grey for the tile's number. Neighbouring
//! tiles then still match along their shared edges and corners.

use super::jwf_aa_truchet::ImagePlace;
use super::jwf_wt_tiling::{HIGH, Kind, SET_COUNT, TileSet, Tiling, WIDE, tiling};
use super::resources::ResourceImage;
use super::*;
use std::sync::Arc;

/// A tile's side in pixels.
const TILE: usize = 32;
/// The image's width.
const IMG_W: usize = WIDE * TILE;
/// The image's height.
const IMG_H: usize = HIGH * TILE;

/// Java's `int` range, for the integer switches.
const IMIN: f64 = -2_147_483_648.0;
const IMAX: f64 = 2_147_483_647.0;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("wangtiles", wangtiles)
    .params(&[
        // JWildfire accepts ids up to 105, one past its last set (its set-up then fails).
        p_int("wangtiles_id", 0.0, 0.0, (SET_COUNT - 1) as f64),
        p_int("wangtiles_seed", 1000.0, IMIN, IMAX),
        p_int("wangtiles_square", 1.0, 0.0, 1.0),
        p("wangtiles_scale_x", 1.0),
        p("wangtiles_scale_y", 1.0),
        p("wangtiles_scale_z", 0.0),
        p("wangtiles_offset_x", 0.0),
        p("wangtiles_offset_y", 0.0),
        p("wangtiles_offset_z", 0.0),
        p_int("wangtiles_tile_x", 1.0, IMIN, IMAX),
        p_int("wangtiles_tile_y", 1.0, IMIN, IMAX),
        p_int("wangtiles_reset_z", 1.0, IMIN, IMAX),
    ])
    .flags(
        flag::JWILDFIRE
            | flag::RANDOM
            | flag::SETS_COLOR
            | flag::PALETTE
            | flag::READS_ACC
            | flag::WRITES_ACC
            | flag::WRITES_Z,
    )
    .shared(&[0, 1], tiles_image)];

/// wangtiles: the pixel under the moved sum.
fn wangtiles(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        square,
        scale_x,
        scale_y,
        scale_z,
        offset_x,
        offset_y,
        offset_z,
        tile_x,
        tile_y,
        reset_z,
    ] = v.params();
    let rect = if square == 0.0 { 1.5 } else { 1.0 };
    let dx = v.w * rect * (rng.f01() - 0.5);
    let dy = v.w * (rng.f01() - 0.5);
    let place = ImagePlace {
        size: [IMG_W as i32, IMG_H as i32],
        offset: [offset_x, offset_y, offset_z],
        scale: [scale_x, scale_y, scale_z],
        tile: [tile_x, tile_y],
        reset_z,
    };
    place.step(v, t, acc, [dx, dy], |x, y| {
        rgb_at(v.data(), x, y).map(f64::from)
    })
}

/// The colour of pixel (x, y) of the shared image (one packed 0xRRGGBB per value; black
/// where the data is short).
fn rgb_at(d: &[f64], x: usize, y: usize) -> [u8; 3] {
    let v = d.get(y * IMG_W + x).copied().unwrap_or(0.0) as u32;
    let [_, r, g, b] = v.to_be_bytes();
    [r, g, b]
}

/// The set and seed of parameters (`id`, `seed` first; rounded as the parameters are, NaN
/// taken as 0).
fn set_and_seed(p: &[f64]) -> (TileSet, i64) {
    let int = |v: f64, lo: f64, hi: f64| {
        if v.is_nan() {
            0.0
        } else {
            (v + 0.5).floor().clamp(lo, hi)
        }
    };
    let id = int(
        p.first().copied().unwrap_or(0.0),
        0.0,
        (SET_COUNT - 1) as f64,
    );
    let seed = int(p.get(1).copied().unwrap_or(1000.0), IMIN, IMAX);
    (TileSet::of(id as usize), seed as i64)
}

/// The resource names of the tile images a `wangtiles` with parameters `p` reads, each once,
/// in the order the tiling first uses them (row by row).
#[cfg(test)]
fn tile_names(p: &[f64]) -> Vec<String> {
    let (set, seed) = set_and_seed(p);
    let t = tiling(&set, seed);
    let mut seen = Vec::new();
    for row in 0..HIGH {
        for col in 0..WIDE {
            let n = t.tiles[col][row];
            if !seen.contains(&n) {
                seen.push(n);
            }
        }
    }
    seen.into_iter().map(|n| set.image_name(n)).collect()
}

/// Shared data: the 384 × 256 image of the tiling, one packed 0xRRGGBB per pixel, rows from
/// the top.
fn tiles_image(p: &[f64], _texts: &[String]) -> Vec<f64> {
    let (set, seed) = set_and_seed(p);
    compose(&set, &tiling(&set, seed), super::resources::image)
}

/// The image of tiling `t` of `set`, each tile's image looked up by its resource name.
fn compose(
    set: &TileSet,
    t: &Tiling,
    image: impl Fn(&str) -> Option<Arc<ResourceImage>>,
) -> Vec<f64> {
    let mut px = vec![0.0; IMG_W * IMG_H];
    for row in 0..HIGH {
        for col in 0..WIDE {
            let n = t.tiles[col][row];
            let img = image(&set.image_name(n));
            for y in 0..TILE {
                for x in 0..TILE {
                    let [r, g, b] = match &img {
                        Some(img) => image_pixel(img, x, y),
                        None => fallback_pixel(set, t, col, row, x, y),
                    };
                    px[(row * TILE + y) * IMG_W + col * TILE + x] =
                        f64::from(u32::from_be_bytes([0, r, g, b]));
                }
            }
        }
    }
    px
}

/// Pixel (x, y) of a stored tile image blended onto black by its alpha (black outside the
/// image: a tile of another size keeps its top-left 32 × 32 pixels).
fn image_pixel(img: &ResourceImage, x: usize, y: usize) -> [u8; 3] {
    if x >= img.w as usize || y >= img.h as usize {
        return [0; 3];
    }
    let [r, g, b, a] = img
        .rgba
        .get(y * img.w as usize + x)
        .copied()
        .unwrap_or([0; 4]);
    let over = |c: u8| ((u32::from(c) * u32::from(a) + 127) / 255) as u8;
    [over(r), over(g), over(b)]
}

/// The grey of value `k` of `levels` values: 48 for 0 up to 224 for the largest.
fn grey(k: i32, levels: i32) -> u8 {
    let top = (levels - 1).max(1);
    (48 + 176 * k.clamp(0, top) / top) as u8
}

/// Pixel (x, y) of the drawn stand-in for tile (col, row) (see the module documentation).
fn fallback_pixel(
    set: &TileSet,
    t: &Tiling,
    col: usize,
    row: usize,
    x: usize,
    y: usize,
) -> [u8; 3] {
    // The tile's middle in the field, and the cell at offset (dc, dr) from it.
    let (mc, mr) = (2 * col + 1, 2 * row + 1);
    let cell =
        |dc: isize, dr: isize| t.field[mc.wrapping_add_signed(dc)][mr.wrapping_add_signed(dr)];
    // Pixel centre relative to the tile's centre, in pixels (doubled to stay integral).
    let (u, v) = (
        2 * x as isize + 1 - TILE as isize,
        2 * y as isize + 1 - TILE as isize,
    );
    let k = match set.kind {
        Kind::Edge | Kind::Twin => {
            let levels = if set.kind == Kind::Edge { set.n } else { 2 };
            let side = if v.abs() >= u.abs() {
                if v < 0 { cell(0, -1) } else { cell(0, 1) }
            } else if u < 0 {
                cell(-1, 0)
            } else {
                cell(1, 0)
            };
            grey(side, levels)
        }
        Kind::Corn => grey(cell(u.signum(), v.signum()), set.n),
        Kind::Blob(_) => {
            let band = |w: isize| {
                if w < -(TILE as isize) / 2 {
                    -1
                } else if w > TILE as isize / 2 {
                    1
                } else {
                    0
                }
            };
            let (bc, br) = (band(u), band(v));
            if bc == 0 && br == 0 {
                grey(1, 2)
            } else {
                grey(cell(bc, br), 2)
            }
        }
        Kind::Block | Kind::Truch => grey(t.tiles[col][row], set.files() as i32),
    };
    [k; 3]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Parameters with set `id` and `seed`, the others at their defaults.
    fn params(id: f64, seed: f64) -> Vec<f64> {
        let mut p: Vec<f64> = DEFS[0].params.iter().map(|q| q.default).collect();
        p[0] = id;
        p[1] = seed;
        p
    }

    #[test]
    fn tile_names_are_distinct_and_of_the_set() {
        let names = tile_names(&params(31.0, 7.0));
        assert!(names.len() > 1);
        for (i, n) in names.iter().enumerate() {
            assert!(
                n.starts_with("jwildfire:org/jwildfire/icons/edge/angular/"),
                "{n}"
            );
            assert!(n.ends_with(".gif"));
            assert!(!names[..i].contains(n));
        }
        // Non-finite or out-of-range parameters still name a set.
        assert!(!tile_names(&[f64::NAN, f64::INFINITY]).is_empty());
        assert!(!tile_names(&[]).is_empty());
    }

    /// Without images the stand-in tiles of an edge set agree along every shared edge: the
    /// last pixel column of a tile and the first of its right neighbour have the same grey
    /// at the middle row, and likewise down.
    #[test]
    fn stand_in_tiles_match_across_edges() {
        let p = params(61.0, 1000.0);
        let img = tiles_image(&p, &[]);
        assert_eq!(img.len(), IMG_W * IMG_H);
        let at = |x: usize, y: usize| rgb_at(&img, x, y);
        let mid = TILE / 2;
        for row in 0..HIGH {
            for col in 0..WIDE - 1 {
                let y = row * TILE + mid;
                let x = (col + 1) * TILE;
                assert_eq!(at(x - 1, y), at(x, y), "tile ({col}, {row})");
            }
        }
        for row in 0..HIGH - 1 {
            for col in 0..WIDE {
                let x = col * TILE + mid;
                let y = (row + 1) * TILE;
                assert_eq!(at(x, y - 1), at(x, y), "tile ({col}, {row})");
            }
        }
        // The edges are random: both greys occur.
        let greys: std::collections::BTreeSet<[u8; 3]> = (0..IMG_W).map(|x| at(x, mid)).collect();
        assert!(greys.len() >= 2, "{greys:?}");
    }

    /// FNV-1a (64 bits) of the 384 × 256 pixels (as 0xAARRGGBB, row by row) of every set's
    /// tiling from seed 1000 as JWildfire 9.00's `WangTilesFunc.Tiles.render` draws it from
    /// its GIF files (read from the compiled class, headless).
    const JWILDFIRE_IMAGES: [u64; SET_COUNT] = [
        0x0a37249ba42380f1,
        0xa5d70d1622c781f5,
        0xc353d1aa02bbc0a1,
        0x759f5be4bb5a9f09,
        0xcec5144fbe3d0d25,
        0xae72ae0771e1d7a5,
        0xa11078d6d9e9e125,
        0xced8c46366c713b1,
        0xa3a8ed9917b74075,
        0x39f3b70537945c55,
        0xe0972c6797a71245,
        0xe7694c5349099b61,
        0x1f86b602522655bb,
        0xbafbbf43d6e31852,
        0xf26776616c0a0a7d,
        0x36e34f5d42f00c59,
        0x45a4d600d96bd525,
        0xd41f3207efb76285,
        0x4d8d90846c85a325,
        0x0e13502b78069325,
        0x3e4fab32e0548725,
        0xaf4834a92ab68271,
        0x23996dae4fbacdc5,
        0x393feb8424110e65,
        0x0ff5b22a85fd5115,
        0x86764d041ef2ecaa,
        0xd23abf7622e57d11,
        0x426e6733cc4393bb,
        0x8218209daa5a6c25,
        0xd0da2e821acce597,
        0xca87e540dfa807bd,
        0xcea6b01d52fe9ecd,
        0xd863175a62a05451,
        0xbbfe2623d19acf40,
        0xaaac46abb670145e,
        0xa9c5db0b9178877b,
        0x27ce9a64b3823ef7,
        0xe34a70213eb1c1f0,
        0xdb2f07d9bd71964d,
        0x84a3f9177e91e999,
        0x9eabcdbad676b273,
        0x4b529c3b06dade05,
        0x5d0f9b6fb7623d01,
        0xaee180266db1b51e,
        0xe427c1f591640112,
        0x568e9f25faf97210,
        0x1335a476f5da56ed,
        0x51911e02fb0088a1,
        0x6ed85cb51985a9e3,
        0x6e5592030b528dff,
        0xfbbec9e4724aa4dc,
        0xf827f60cf09b1244,
        0x40f8474d51e6d5d9,
        0x71f083f605958a17,
        0x40e97dcc24406c0e,
        0xe252f90cf70eff1a,
        0x225cc553168991d5,
        0x18e298ddc1f94213,
        0x9a4fd19d21770125,
        0x8c3f6676fd9f3050,
        0x5d62a88ed91ebe65,
        0xc2e716310674ed02,
        0x4205232e49893036,
        0xe635a3317ae5093f,
        0x777670c36bb4bed4,
        0xa1649231a6f568ee,
        0x6bc3d163ce1c0956,
        0x75fd4cae1b4d7a16,
        0x7d167285fc43b9e0,
        0xd51ea888c01524c0,
        0x6f74a41d60735377,
        0x3a859a494b0df694,
        0x93e52b12ba71ccb1,
        0x3885678e4f311773,
        0xb8e96b9845743acc,
        0x32ab4c857aadc7c3,
        0x7796d575281a5e2b,
        0x400ce926c801d05f,
        0x7286b9dd88d9d5ad,
        0xd210e8862db249e1,
        0x3121513c3dd1c90f,
        0xabd35b41d5036eb6,
        0x7e55069acb717912,
        0x7e55069acb717912,
        0xe54b8671e06df9a5,
        0x3addd5c7e2d8843f,
        0x8396250325ef41cd,
        0x9a3abf24acaadc44,
        0xd8897c7bae133fdb,
        0xfc4fda13626b20d8,
        0xa3d1369037277a9f,
        0x967044c1d1fc22cd,
        0x7cad97aa0ff6f97e,
        0xb49f2f3502d04a36,
        0x71e214bf81e119d7,
        0x7d19d5d306062f29,
        0x4a9cf8d0606cc39f,
        0x22ad67b3a6905c88,
        0xd414af6afb69d836,
        0x83e0aaa6f4d4632c,
        0x5d15a343dd9925a3,
        0x0e33a241515123c0,
        0x830c2a7c85e54e90,
        0x8f04cb05303abcb5,
        0xd96e3fa92ff823a8,
    ];

    /// Where JWildfire's resource files are (its `src/resources`): UGNIS_JWF_RESOURCES, else
    /// this machine's copy.
    fn resource_dir() -> Option<std::path::PathBuf> {
        let dir = std::env::var_os("UGNIS_JWF_RESOURCES").map_or_else(
            || "/tmp/jwildfire/src/resources".into(),
            std::path::PathBuf::from,
        );
        dir.is_dir().then_some(dir)
    }

    /// With JWildfire's GIF files decoded by the `image` crate, every set's image is
    /// JWildfire's, pixel for pixel.
    #[test]
    fn images_with_jwildfires_tiles_are_jwildfires() {
        let Some(dir) = resource_dir() else {
            eprintln!("skipped: JWildfire's resource files are not here (UGNIS_JWF_RESOURCES)");
            return;
        };
        let read = |name: &str| {
            let path = dir.join(name.trim_start_matches("jwildfire:"));
            let img = image::open(&path).ok()?.to_rgba8();
            let (w, h) = img.dimensions();
            let rgba = img.pixels().map(|p| p.0).collect();
            Some(Arc::new(ResourceImage { w, h, rgba }))
        };
        for (id, &want) in JWILDFIRE_IMAGES.iter().enumerate() {
            let (set, seed) = set_and_seed(&params(id as f64, 1000.0));
            let px = compose(&set, &tiling(&set, seed), read);
            let mut h: u64 = 0xcbf2_9ce4_8422_2325;
            for &v in &px {
                h = (h ^ (0xff00_0000 | v as u64)).wrapping_mul(0x100_0000_01b3);
            }
            assert_eq!(h, want, "set {id} ({set:?})");
        }
    }

    /// A stored tile image is copied pixel for pixel (blended onto black by its alpha).
    #[test]
    fn stored_tiles_are_copied() {
        // Set 9 (block2/1corn2a) with a seed whose tiling uses both of its images.
        let p = params(9.0, 17.0);
        let (set, seed) = set_and_seed(&p);
        let t = tiling(&set, seed);
        let mut rgba = vec![[10, 20, 30, 255]; TILE * TILE];
        rgba[1] = [200, 100, 50, 0];
        rgba[TILE + 2] = [255, 255, 255, 128];
        let img = super::super::resources::ResourceImage {
            w: TILE as u32,
            h: TILE as u32,
            rgba,
        };
        assert!(super::super::resources::put_image(&set.image_name(1), img));
        let data = tiles_image(&p, &[]);
        let ones: Vec<(usize, usize)> = (0..WIDE)
            .flat_map(|c| (0..HIGH).map(move |r| (c, r)))
            .filter(|&(c, r)| t.tiles[c][r] == 1)
            .collect();
        assert!(!ones.is_empty());
        for (c, r) in ones {
            let (x0, y0) = (c * TILE, r * TILE);
            assert_eq!(rgb_at(&data, x0, y0), [10, 20, 30]);
            assert_eq!(rgb_at(&data, x0 + 1, y0), [0, 0, 0]);
            assert_eq!(rgb_at(&data, x0 + 2, y0 + 1), [128, 128, 128]);
        }
    }
}
