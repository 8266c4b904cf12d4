//! `msTruchet`, JWildfire's multi-scale Truchet tiles (JWildfire 9.00, `MSTruchetFunc` on
//! `AbstractBufferedImageWFFunc`; formulas and behaviour written anew).
//!
//! When it is set up, the variation builds a quadtree over a 1024-pixel square centred in a
//! 1706 × 1706 black image: the root and every new cell draw a motif (one of 15) from
//! `java.util.Random(seed)`, and 1 + `complexity` random points (x and y in [0, 1024)) each
//! split the leaf holding them into four (north-east, north-west, south-east, south-west).
//! It then draws, anti-aliased, the root's tile and then every leaf's tile, breadth first:
//! each tile is its square in one colour with its motif (quarter discs in the corners,
//! bars, half squares) in the other, discs of 2/3 of the half side in the first colour at
//! its corners and of 1/3 at the middles of its sides in the second; the colours are white
//! on black on even levels of the tree and swapped on odd ones.
//!
//! Each call moves the running sum by (weight·(ξ − ½), weight·(ξ − ½)) and looks the moved
//! point up in the image as JWildfire's image variations do (scale, offset, optional
//! tiling): the pixel becomes the point's own colour and, through the palette entry nearest
//! to it, its colour coordinate; its brightness times `scale_z` plus `offset_z` replaces z
//! (`reset_z` not 0) or adds to it.
//!
//! The image is drawn with ugnis' rasteriser ([`super::jwf_aa_raster`]), so the grey edge
//! pixels can differ from Java2D's by a step of coverage.

use super::jwf_a_cuts::JavaRandom;
use super::jwf_aa_raster::{FillRule, Pt, circle, ellipse_arc, fill};
use super::jwf_h9b_images::{image_axis, intensity};
use super::*;

/// JWildfire's `EPSILON`.
const EPS: f64 = 1e-8;

/// The image's side: 1024·5/3, truncated.
const SIDE: usize = 1706;

/// Java's `int` range, for the integer switches.
const IMIN: f64 = -2_147_483_648.0;
const IMAX: f64 = 2_147_483_647.0;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("msTruchet", ms_truchet)
    .params(&[
        p_int("msTruchet_seed", 0.0, IMIN, IMAX),
        p_int("msTruchet_complexity", 25.0, 1.0, 100.0),
        p("msTruchet_scale_x", 1.0),
        p("msTruchet_scale_y", 1.0),
        p("msTruchet_scale_z", 0.0),
        p("msTruchet_offset_x", 0.0),
        p("msTruchet_offset_y", 0.0),
        p("msTruchet_offset_z", 0.0),
        p_int("msTruchet_tile_x", 0.0, IMIN, IMAX),
        p_int("msTruchet_tile_y", 0.0, IMIN, IMAX),
        p_int("msTruchet_reset_z", 1.0, IMIN, IMAX),
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
    .shared(&[0, 1], truchet_image)];

/// msTruchet: the pixel under the moved sum.
fn ms_truchet(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
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
    let dx = v.w * (rng.f01() - 0.5);
    let dy = v.w * (rng.f01() - 0.5);
    let n = SIDE as i32;
    let place = ImagePlace {
        size: [n, n],
        offset: [offset_x, offset_y, offset_z],
        scale: [scale_x, scale_y, scale_z],
        tile: [tile_x, tile_y],
        reset_z,
    };
    place.step(v, t, acc, [dx, dy], |x, y| {
        [f64::from(grey_at(v.data(), x, y)); 3]
    })
}

/// Where a JWildfire image variation (msTruchet, wangtiles) finds the sum moved by (dx, dy)
/// on its image: the image's size, offsets and scales (x, y, z), tiling and `reset_z`.
pub(super) struct ImagePlace {
    pub size: [i32; 2],
    pub offset: [f64; 3],
    pub scale: [f64; 3],
    pub tile: [f64; 2],
    pub reset_z: f64,
}

impl ImagePlace {
    /// The step of the pixel under the sum moved by `d`: the pixel (`rgb_at` of its column
    /// and row; black outside the image) is the point's own colour and its nearest palette
    /// entry, its brightness the height; `reset_z` clears the sum's z.
    pub fn step(
        &self,
        v: &Prepared,
        t: &VarIn,
        acc: &mut Acc,
        [dx, dy]: [f64; 2],
        rgb_at: impl Fn(usize, usize) -> [f64; 3],
    ) -> V3 {
        let [w, h] = self.size;
        let (_, ix) = image_axis(
            acc.x + dx,
            self.offset[0],
            self.scale[0],
            w,
            self.tile[0],
            false,
        );
        let (_, iy) = image_axis(
            acc.y + dy,
            self.offset[1],
            self.scale[1],
            h,
            self.tile[1],
            false,
        );
        let [r, g, b] = if (0..w).contains(&ix) && (0..h).contains(&iy) {
            rgb_at(ix as usize, iy as usize)
        } else {
            [0.0; 3]
        };
        acc.rgb = Some([r, g, b]);
        if let Some(c) = v.palette_coordinate(r, g, b) {
            acc.color = c;
        }
        let mut dz = self.offset[2];
        if self.scale[2].abs() > EPS {
            dz += self.scale[2] * intensity(r, g, b) / 255.0;
        }
        if self.reset_z != 0.0 {
            acc.z = 0.0;
        }
        if v.zrule == ZRule::Weighted {
            // JWildfire's "preserve Z" adds the weighted input z after the image's height.
            dz += v.w * t.z;
        }
        [dx, dy, dz]
    }
}

/// The grey level of pixel (x, y) of the shared image (four pixels packed per value).
fn grey_at(d: &[f64], x: usize, y: usize) -> u8 {
    let k = y * SIDE + x;
    d.get(k / 4)
        .map_or(0, |&v| ((v as u32) >> (8 * (k % 4))) as u8)
}

/// A motif of JWildfire's list, in its order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Motif {
    /// `\`: quarter discs about the north-east and south-west corners.
    Back,
    /// `/`: about the north-west and south-east corners.
    Slash,
    Dash,
    Bar,
    Empty,
    Full,
    Plus,
    Fne,
    Fsw,
    Fnw,
    Fse,
    Tn,
    Ts,
    Te,
    Tw,
}

const MOTIFS: [Motif; 15] = [
    Motif::Slash,
    Motif::Back,
    Motif::Dash,
    Motif::Bar,
    Motif::Empty,
    Motif::Full,
    Motif::Plus,
    Motif::Fne,
    Motif::Fsw,
    Motif::Fnw,
    Motif::Fse,
    Motif::Tn,
    Motif::Ts,
    Motif::Te,
    Motif::Tw,
];

/// A cell of the quadtree: centre, half side, level, motif and children.
struct Cell {
    x: f64,
    y: f64,
    half: f64,
    tier: u32,
    motif: Motif,
    kids: Option<[usize; 4]>,
}

/// The quadtree of a seed and complexity (cells in an arena, the root first).
fn quadtree(seed: i64, complexity: usize) -> Vec<Cell> {
    let mut rnd = JavaRandom::new(seed);
    let motif = |r: &mut JavaRandom| MOTIFS[((15.0 * r.next_f64()) as usize).min(14)];
    let c = (SIDE / 2) as f64;
    let root_motif = motif(&mut rnd);
    let mut cells = vec![Cell {
        x: c,
        y: c,
        half: 512.0,
        tier: 0,
        motif: root_motif,
        kids: None,
    }];
    for _ in 0..=complexity {
        let px = 1024.0 * rnd.next_f64();
        let py = 1024.0 * rnd.next_f64();
        // Down to the leaf holding the point (cells hold their west and north edges).
        let holds = |cell: &Cell| {
            px >= cell.x - cell.half
                && px < cell.x + cell.half
                && py >= cell.y - cell.half
                && py < cell.y + cell.half
        };
        let mut at = 0;
        if !holds(&cells[0]) {
            continue;
        }
        while let Some(kids) = cells[at].kids {
            match kids.iter().find(|&&k| holds(&cells[k])) {
                Some(&k) => at = k,
                None => break,
            }
        }
        if cells[at].kids.is_some() {
            continue;
        }
        let (x, y, h, tier) = (
            cells[at].x,
            cells[at].y,
            cells[at].half / 2.0,
            cells[at].tier,
        );
        let mut kids = [0; 4];
        for (i, (sx, sy)) in [(1.0, -1.0), (-1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .into_iter()
            .enumerate()
        {
            kids[i] = cells.len();
            let m = motif(&mut rnd);
            cells.push(Cell {
                x: x + sx * h,
                y: y + sy * h,
                half: h,
                tier: tier + 1,
                motif: m,
                kids: None,
            });
        }
        cells[at].kids = Some(kids);
    }
    cells
}

/// The image of a seed and complexity: grey levels, four pixels packed per value.
fn truchet_image(p: &[f64], _texts: &[String]) -> Vec<f64> {
    let [seed, complexity] = params_of(p);
    let cells = quadtree(seed as i64, complexity.clamp(1.0, 100.0) as usize);
    let img = draw(&cells);
    img.chunks(4)
        .map(|c| {
            let v = c
                .iter()
                .enumerate()
                .fold(0u32, |v, (i, &g)| v | u32::from(g) << (8 * i));
            f64::from(v)
        })
        .collect()
}

/// The tiles drawn: the root's, then the leaves' breadth first.
fn draw(cells: &[Cell]) -> Vec<u8> {
    let mut img = vec![0u8; SIDE * SIDE];
    let mut order = vec![0usize];
    let mut queue = std::collections::VecDeque::from([0usize]);
    while let Some(i) = queue.pop_front() {
        match cells[i].kids {
            Some(k) => queue.extend(k),
            None => order.push(i),
        }
    }
    for i in order {
        draw_tile(&mut img, &cells[i]);
    }
    img
}

/// Paints `shape` in grey `level`, anti-aliased.
fn paint(img: &mut [u8], shape: Vec<Pt>, level: u8) {
    let src = f64::from(level);
    fill(
        &[shape],
        FillRule::NonZero,
        true,
        SIDE,
        SIDE,
        |x, y, cov| {
            let m = (cov * 255.0 + 0.5).floor();
            if m < 1.0 {
                return;
            }
            let a = m / 255.0;
            let px = &mut img[y * SIDE + x];
            *px = (src * a + f64::from(*px) * (1.0 - a) + 0.5).min(255.0) as u8;
        },
    );
}

/// The rectangle with centre (x, y) and half sides w, h.
fn rect(x: f64, y: f64, w: f64, h: f64) -> Vec<Pt> {
    vec![
        (x - w, y - h),
        (x + w, y - h),
        (x + w, y + h),
        (x - w, y + h),
    ]
}

/// A quarter disc (Java2D's pie arc) about (x, y) of radius r, from `start` degrees
/// (counter-clockwise on screen from east) over 90°.
fn quarter(x: f64, y: f64, r: f64, start: f64) -> Vec<Pt> {
    // On screen y points down: counter-clockwise is toward negative angles.
    let mut pts = ellipse_arc((x, y), r, r, -start.to_radians(), -90f64.to_radians());
    pts.push((x, y));
    pts
}

fn draw_tile(img: &mut [u8], c: &Cell) {
    let (x, y, w) = (c.x, c.y, c.half);
    let (small, big, arc_r) = (2.0 * w / 6.0, 2.0 * w / 3.0, 4.0 * w / 3.0);
    // Colour 0 is the motif's, colour 1 the ground's: white on black, swapped on odd levels.
    let (c0, c1) = if c.tier % 2 == 1 { (0, 255) } else { (255, 0) };
    paint(img, rect(x, y, w, w), c1);
    let mut motif: Vec<Vec<Pt>> = Vec::new();
    match c.motif {
        Motif::Back => {
            motif.push(quarter(x + w, y - w, arc_r, 180.0));
            motif.push(quarter(x - w, y + w, arc_r, 0.0));
        }
        Motif::Slash => {
            motif.push(quarter(x - w, y - w, arc_r, 270.0));
            motif.push(quarter(x + w, y + w, arc_r, 90.0));
        }
        Motif::Dash => motif.push(rect(x, y, w, small)),
        Motif::Bar => motif.push(rect(x, y, small, w)),
        Motif::Empty => {}
        Motif::Full => motif.push(rect(x, y, w, w)),
        Motif::Plus => {
            motif.push(rect(x, y, w, small));
            motif.push(rect(x, y, small, w));
        }
        Motif::Fne => motif.push(quarter(x + w, y - w, arc_r, 180.0)),
        Motif::Fsw => motif.push(quarter(x - w, y + w, arc_r, 0.0)),
        Motif::Fnw => motif.push(quarter(x - w, y - w, arc_r, 270.0)),
        Motif::Fse => motif.push(quarter(x + w, y + w, arc_r, 90.0)),
        Motif::Tn => motif.push(rect(x, y - small, w, big)),
        Motif::Ts => motif.push(rect(x, y + small, w, big)),
        Motif::Te => motif.push(rect(x + small, y, big, w)),
        Motif::Tw => motif.push(rect(x - small, y, big, w)),
    }
    for s in motif {
        paint(img, s, c0);
    }
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        paint(img, circle((x + sx * w, y + sy * w), big), c1);
    }
    for (px, py) in [(x, y - w), (x + w, y), (x, y + w), (x - w, y)] {
        paint(img, circle((px, py), small), c0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quarter_disc_covers_a_quarter_of_the_disc() {
        // About (100, 100), radius 80, from west over 90° counter-clockwise: the quarter
        // below and left of the centre.
        let q = quarter(100.0, 100.0, 80.0, 180.0);
        let (mut area, mut wrong) = (0.0, 0.0);
        fill(&[q], FillRule::NonZero, true, 200, 200, |x, y, c| {
            area += c;
            if x > 100 || y < 99 {
                wrong += c;
            }
        });
        let want = std::f64::consts::PI * 6400.0 / 4.0;
        assert!((area - want).abs() < 3e-3 * want, "{area} vs {want}");
        assert_eq!(wrong, 0.0);
    }

    #[test]
    fn the_leaves_tile_the_root_and_the_image_is_mostly_black_and_white() {
        for (seed, complexity) in [(0, 25), (1, 26), (2, 27), (-7, 100)] {
            let cells = quadtree(seed, complexity);
            let leaves: f64 = cells
                .iter()
                .filter(|c| c.kids.is_none())
                .map(|c| 4.0 * c.half * c.half)
                .sum();
            assert_eq!(leaves, 1024.0 * 1024.0);
            assert!(cells.len() <= 1 + 4 * (complexity + 1));
            let img = draw(&cells);
            let grey = img.iter().filter(|&&g| g != 0 && g != 255).count();
            let white = img.iter().filter(|&&g| g == 255).count();
            assert!(grey * 10 < white, "{grey} grey of {white} white");
            let d = truchet_image(&[seed as f64, complexity as f64], &[]);
            assert_eq!(grey_at(&d, 700, 900), img[900 * SIDE + 700]);
        }
    }
}
