//! JWildfire's brush strokes: `brush_stroke_wf` and `post_brush_stroke_wf` stamp a random
//! pixel of a brush image, turned, scaled and nudged per cell of a square grid, onto the
//! plane: the affine point (the summed point for the post form) picks its grid cell, the cell
//! (hashed) picks the brush variant, its angle, size and offset, and each call draws one dark
//! pixel of that brush, darker pixels more often.
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `AbstractBrushStrokeWFFunc`,
//! `BrushStrokeWFFunc` and `PostBrushStrokeWFFunc`, written anew:
//! * the brushes: the ids of `brush_list` (comma-separated, e.g. `001, 005, 012`), or, when
//!   `rnd_brush_seed` > 0, ids drawn from that seed (JWildfire's Marsaglia generator), then the
//!   images `image_filename1` … `image_filename6` (JWildfire reads `image_filename5` again in
//!   place of `image_filename6`; so does ugnis); with none at all, JWildfire's 256 × 256
//!   corner gradient;
//! * each image gives `variation_batch_size` / (number of images) variants plus the image
//!   itself (the first image takes the remainder): each variant is the image turned about its
//!   centre and zoomed by random amounts (JWildfire's `RotateTransformer`, bilinear from the
//!   rounded pixel, then its edge smoothing), shifted by a random offset and eroded (pixels
//!   dropped at random), all drawn from `variation_seed`;
//! * a pixel counts when its channel (`color_channel` 0 red, 1 green, 2 blue, 3 alpha), in
//!   [0, 1] and inverted when `invert` ≠ 0, reaches `threshold`; its weight is
//!   min(value² + threshold, 1), turned into a count of copies out of 64 000 (at least one);
//! * per call: the cell's variant from the colour coordinate and a hash of the cell; with
//!   probability about 1 − `blend` a copy is drawn, turned and scaled by the cell's hash, blurred
//!   by `antialias_radius`, placed at the cell's corner nudged by `grid_deform`; otherwise the
//!   point is left as it is. The point is hidden when it ends at the origin.
//!
//! JWildfire's brushes are PNG images in its jar. ugnis does not ship them: it takes them from
//! the resource store ([`super::resources`]) under the name
//! `jwildfire:org/jwildfire/create/tina/variation/brush/brushNNN.png` ([`BRUSH_PREFIX`]),
//! where the file readers put them when a JWildfire installation is configured. A brush of
//! JWildfire's (ids 001–245) missing from the store is replaced by [`round_brush`], a black
//! disc on white, so a flame still draws round dabs; an id JWildfire does not have, an image
//! narrower than 16 pixels or a named image file that was not handed over is skipped, as
//! JWildfire skips it.
//!
//! Images wider or taller than `image_max_size` (when that is above 64) are scaled down to it
//! first; JWildfire's `ScaleTransformer` is not followed pixel for pixel there (ugnis samples
//! bilinearly). None of JWildfire's brushes but `brush009` is larger than the default 320.
//!
//! Bounds (ugnis's, JWildfire has none): at most [`MAX_IMAGES`] images, [`MAX_VARIANTS`]
//! variants over all images (each image's share of them) and [`MAX_POINTS`] stored pixels
//! over all variants (later variants then stay empty, are not even drawn, and draw nothing).

use super::jwf_br_raster::{Raster, rotate, scale_to};
use super::jwf_h9b_images::{View, ftoi, gradient_map_of_size};
use super::util::{Mwc, lattice_noise};
use super::*;

/// JWildfire's `EPSILON`.
const EPS: f64 = 1e-8;

/// Java's `int` range.
const IMIN: f64 = -2_147_483_648.0;
const IMAX: f64 = 2_147_483_647.0;

/// The resource-store name of JWildfire's brush `NNN` is this, then `NNN.png`.
pub const BRUSH_PREFIX: &str = "jwildfire:org/jwildfire/create/tina/variation/brush/brush";

/// JWildfire's highest brush id (`PainterlyStyleMutation.MAX_BRUSH`).
const MAX_BRUSH: i32 = 245;

/// Most images a brush variation uses.
pub const MAX_IMAGES: usize = 64;
/// Most variants built over all images (besides the images themselves), shared out evenly.
pub const MAX_VARIANTS: i64 = 256;
/// Most pixels stored over all variants.
pub const MAX_POINTS: usize = 4_000_000;

/// Most bytes of the brush list and of an image file's name.
const MAX_TEXT: usize = 4096;

/// JWildfire's copies per variant: the pixels' weights are spread over this many entries.
const SPREAD: usize = 64_000;

// Hash scales of the grid cell (JWildfire's `noiseSclGeneration`, `noiseSclX`, `noiseSclY`).
const NOISE_GEN: f64 = 32768.0 * 0.666;
const NOISE_X: f64 = 32768.0;
const NOISE_Y: f64 = NOISE_X * 0.42 + std::f64::consts::PI;

macro_rules! brush_params {
    ($n:literal) => {
        &[
            p(concat!($n, "_blend"), 0.25),
            p(concat!($n, "_grid_size"), 0.025),
            p(concat!($n, "_grid_deform"), 0.05),
            p(
                concat!($n, "_grid_brush_rotate"),
                2.0 * std::f64::consts::PI,
            ),
            p(concat!($n, "_grid_brush_scale"), 0.35),
            p(concat!($n, "_grid_brush_blend"), 0.15),
            p_int(concat!($n, "_color_channel"), 0.0, IMIN, IMAX),
            p(concat!($n, "_threshold"), 0.1),
            p_int(concat!($n, "_invert"), 1.0, IMIN, IMAX),
            p_int(concat!($n, "_variation_batch_size"), 12.0, IMIN, IMAX),
            p(concat!($n, "_variation_zoom"), 0.8),
            p(concat!($n, "_variation_position"), 0.5),
            p(
                concat!($n, "_variation_rotation"),
                2.0 * std::f64::consts::PI,
            ),
            p(concat!($n, "_variation_erosion"), 0.1),
            p_int(concat!($n, "_variation_seed"), 12345.0, IMIN, IMAX),
            p_int(concat!($n, "_image_max_size"), 320.0, IMIN, IMAX),
            p(concat!($n, "_antialias_radius"), 0.75),
            p_int(concat!($n, "_rnd_brush_seed"), 0.0, IMIN, IMAX),
            p_int(concat!($n, "_rnd_brush_min_count"), 1.0, IMIN, IMAX),
            p_int(concat!($n, "_rnd_brush_max_count"), 5.0, IMIN, IMAX),
        ]
    };
}

macro_rules! brush_texts {
    ($n:literal) => {
        &[
            TextParam {
                name: concat!($n, "_brush_list"),
                default: "001, 005, 012",
                max_len: MAX_TEXT,
            },
            TextParam {
                name: concat!($n, "_image_filename1"),
                default: "",
                max_len: MAX_TEXT,
            },
            TextParam {
                name: concat!($n, "_image_filename2"),
                default: "",
                max_len: MAX_TEXT,
            },
            TextParam {
                name: concat!($n, "_image_filename3"),
                default: "",
                max_len: MAX_TEXT,
            },
            TextParam {
                name: concat!($n, "_image_filename4"),
                default: "",
                max_len: MAX_TEXT,
            },
            TextParam {
                name: concat!($n, "_image_filename5"),
                default: "",
                max_len: MAX_TEXT,
            },
            TextParam {
                name: concat!($n, "_image_filename6"),
                default: "",
                max_len: MAX_TEXT,
            },
        ]
    };
}

/// The parameters the variants depend on: channel, threshold, invert, batch size, zoom,
/// position, rotation, erosion, seed, image size and the random brush choice.
const KEY: &[usize] = &[6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 17, 18, 19];

const FLAGS: u32 = flag::JWILDFIRE | flag::RANDOM | flag::USES_COLOR | flag::HIDES;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("brush_stroke_wf", brush_stroke_wf)
        .params(brush_params!("brush_stroke_wf"))
        .texts(brush_texts!("brush_stroke_wf"))
        .flags(FLAGS | flag::READS_ACC | flag::WRITES_ACC)
        .shared(KEY, build),
    VarDef::new("post_brush_stroke_wf", post_brush_stroke_wf)
        .params(brush_params!("post_brush_stroke_wf"))
        .texts(brush_texts!("post_brush_stroke_wf"))
        .flags(FLAGS | flag::POST_ONLY)
        .shared(KEY, build),
];

// ---------------------------------------------------------------------------------------------
// The brushes

/// The name under which JWildfire's brush with the list entry `id` (e.g. `001`) is stored.
pub fn brush_name(id: &str) -> String {
    format!("{BRUSH_PREFIX}{id}.png")
}

/// The brush ids a brush variation with parameters `p` (in [`VarDef::params`] order) and texts
/// `texts` uses, as the list entries JWildfire formats them (`001` …), in order.
pub fn brush_ids(p: &[f64], texts: &[String]) -> Vec<String> {
    let get = |i: usize| p.get(i).copied().unwrap_or(0.0);
    let (seed, lo, hi) = (get(17), get(18), get(19));
    if seed > 0.0 {
        let mut rng = Mwc::new(seed as i64);
        let count = ftoi(lo + rng.next_f64() * (hi - lo)).clamp(0, MAX_IMAGES as i32);
        return (0..count)
            .map(|_| {
                let id = ftoi(1.0 + rng.next_f64() * f64::from(MAX_BRUSH)).min(MAX_BRUSH);
                format!("{id:03}")
            })
            .collect();
    }
    // Java's StringTokenizer: empty pieces between commas are no tokens.
    texts
        .first()
        .map(|l| {
            l.split(',')
                .filter(|t| !t.is_empty())
                .take(MAX_IMAGES)
                .map(|t| t.trim().to_string())
                .collect()
        })
        .unwrap_or_default()
}

/// The JWildfire resources (store names) a brush variation with these parameters draws with.
pub fn brush_resources(p: &[f64], texts: &[String]) -> Vec<String> {
    brush_ids(p, texts).iter().map(|i| brush_name(i)).collect()
}

/// Whether `id` names one of JWildfire's own brushes (`001` … `245`).
fn is_jwildfire_brush(id: &str) -> bool {
    id.len() == 3
        && id.bytes().all(|b| b.is_ascii_digit())
        && id
            .parse::<i32>()
            .is_ok_and(|n| (1..=MAX_BRUSH).contains(&n))
}

/// The brush drawn in place of one of JWildfire's that is not in the store: a black disc of
/// radius 120 pixels centred in a white 320 × 320 image (JWildfire's brushes are dark strokes
/// on white, 320 pixels wide), a pixel black when its centre is inside the disc.
pub fn round_brush() -> Raster {
    const N: i32 = 320;
    const R: f64 = 120.0;
    let c = f64::from(N) / 2.0;
    let mut px = Vec::with_capacity((N * N) as usize);
    for row in 0..N {
        for col in 0..N {
            let (dx, dy) = (f64::from(col) + 0.5 - c, f64::from(row) + 0.5 - c);
            let v = if dx * dx + dy * dy <= R * R { 0 } else { 255 };
            px.push([v, v, v, 255]);
        }
    }
    Raster { w: N, h: N, px }
}

/// A stored image as a raster; opaque when `opaque` (JWildfire draws its brushes into an RGB
/// image).
fn stored(name: &str, opaque: bool) -> Option<Raster> {
    let img = super::resources::image(name)?;
    let px = if opaque {
        img.rgba
            .iter()
            .map(|&[r, g, b, _]| [r, g, b, 255])
            .collect()
    } else {
        img.rgba.clone()
    };
    Some(Raster {
        w: img.w as i32,
        h: img.h as i32,
        px,
    })
}

/// The images a brush variation draws with, in JWildfire's order.
fn images(p: &[f64], texts: &[String]) -> Vec<Raster> {
    let mut out = Vec::new();
    for id in brush_ids(p, texts) {
        match stored(&brush_name(&id), true) {
            Some(img) if img.w >= 16 => out.push(img),
            Some(_) => {}
            None if is_jwildfire_brush(&id) => out.push(round_brush()),
            None => {}
        }
    }
    let text = |i: usize| texts.get(i).map_or("", |t| t.as_str());
    for k in 1..=6 {
        // JWildfire reads the fifth name for the sixth.
        let name = text(if k == 6 { 5 } else { k });
        if !text(k).is_empty()
            && !name.is_empty()
            && let Some(img) = stored(name, false)
        {
            out.push(img);
        }
    }
    out.truncate(MAX_IMAGES);
    if out.is_empty() {
        let d = gradient_map_of_size(&[], 256, 256);
        let v = View::of(&d);
        let px = (0..v.h)
            .flat_map(|y| (0..v.w).map(move |x| (x, y)))
            .map(|(x, y)| v.at(x, y))
            .collect();
        out.push(Raster { w: v.w, h: v.h, px });
    }
    out
}

// ---------------------------------------------------------------------------------------------
// The variants: their pixels and weights

/// The value of a pixel's channel `channel`, in [0, 1], inverted when `invert`.
fn channel_value(px: [u8; 4], channel: f64, invert: bool) -> f64 {
    let c = match channel as i64 {
        1 => px[1],
        2 => px[2],
        3 => px[3],
        _ => px[0],
    };
    let v = f64::from(c) / 255.0;
    if invert { 1.0 - v } else { v }
}

/// Copies per pixel of weight `w[i]`: its share of max(64 000, 2·count) entries, rounded as
/// JWildfire's `FTOI`, at least one.
fn copies(w: &[f64]) -> Vec<u64> {
    let total = SPREAD.max(2 * w.len()) as f64;
    let sum: f64 = w.iter().sum();
    w.iter()
        .map(|&x| ftoi(total * x / sum).max(1) as u64)
        .collect()
}

/// The shared data: the number of variants n, the n positions of their blocks, then each
/// variant's block — its pixel count m,
/// its total copies, the image's width, height and larger side, then m pairs (pixel index
/// column + row·width, running total of copies up to and including it).
fn build(p: &[f64], texts: &[String]) -> Vec<f64> {
    let get = |i: usize| p.get(i).copied().unwrap_or(0.0);
    let (channel, threshold, invert) = (get(6), get(7), get(8) != 0.0);
    let batch = get(9) as i64;
    let (zoom, position, rotation, erosion) = (get(10), get(11), get(12), get(13));
    let max_size = get(15);
    let mut rng = Mwc::new(get(14) as i64);
    let imgs = images(p, texts);
    let n = imgs.len() as i64;
    let mut blocks: Vec<Vec<f64>> = Vec::new();
    let mut stored_points = 0usize;
    for (k, img) in imgs.into_iter().enumerate() {
        let img = if max_size > 64.0 && (f64::from(img.w) > max_size || f64::from(img.h) > max_size)
        {
            scale_to(&img, max_size as i32)
        } else {
            img
        };
        let share = (batch / n).max(1);
        let count = if k == 0 {
            batch - share * (n - 1)
        } else {
            share
        };
        for generation in 0..=count.min((MAX_VARIANTS / n).max(1)) {
            if stored_points >= MAX_POINTS {
                blocks.push(vec![0.0, 0.0, 1.0, 1.0, 1.0]);
                continue;
            }
            let (map, dx, dy, erode) = if generation == 0 {
                (None, 0, 0, 0.0)
            } else {
                let z = (1.0 - zoom * rng.next_f64()).max(0.2);
                let angle = rotation * rng.next_f64() * 180.0 / std::f64::consts::PI;
                let dx = ftoi((0.5 - rng.next_f64()) * position * f64::from(img.w));
                let dy = ftoi((0.5 - rng.next_f64()) * position * f64::from(img.h));
                let erode = erosion * rng.next_f64();
                (Some(rotate(&img, z, angle)), dx, dy, erode)
            };
            let map = map.as_ref().unwrap_or(&img);
            let (w, h) = (map.w, map.h);
            let mut idx = Vec::new();
            let mut weight = Vec::new();
            // JWildfire shifts rows by the horizontal offset and columns by the vertical one.
            for row in 0..h {
                let mrow = row.saturating_add(dx);
                if !(0..h).contains(&mrow) {
                    continue;
                }
                for col in 0..w {
                    let mcol = col.saturating_add(dy);
                    if !(0..w).contains(&mcol) {
                        continue;
                    }
                    let c = channel_value(map.px[(mrow * w + mcol) as usize], channel, invert);
                    if c >= threshold
                        && (erode <= EPS || erode <= rng.next_f64())
                        && stored_points < MAX_POINTS
                    {
                        idx.push(f64::from(row * w + col));
                        weight.push((c * c + threshold).min(1.0));
                        stored_points += 1;
                    }
                }
            }
            let mut block = vec![idx.len() as f64, 0.0, f64::from(w), f64::from(h)];
            block.push(f64::from(w.max(h)));
            let mut run = 0u64;
            for (i, c) in idx.iter().zip(copies(&weight)) {
                run += c;
                block.push(*i);
                block.push(run as f64);
            }
            block[1] = run as f64;
            blocks.push(block);
        }
    }
    let n = blocks.len();
    let mut out = Vec::with_capacity(1 + n + blocks.iter().map(Vec::len).sum::<usize>());
    out.push(n as f64);
    let mut at = 1 + n;
    for b in &blocks {
        out.push(at as f64);
        at += b.len();
    }
    for b in blocks {
        out.extend(b);
    }
    out
}

/// The variant `g`'s block in the shared data (see [`build`]), or `None`.
fn variant(data: &[f64], g: usize) -> Option<&[f64]> {
    let n = *data.first()? as usize;
    if g >= n {
        return None;
    }
    let at = *data.get(1 + g)? as usize;
    let m = *data.get(at)? as usize;
    data.get(at..at + 5 + 2 * m)
}

/// A random pixel of a variant's block, a pixel as likely as its copies: its position
/// relative to the image's centre in units of its larger side.
fn draw_pixel(block: &[f64], rng: &mut FastRng) -> Option<(f64, f64)> {
    let [m, total, w, h, side, ..] = *block else {
        return None;
    };
    let m = m as usize;
    let pairs = block.get(5..5 + 2 * m)?;
    let k = ((rng.f01() * total) as u64).min((total as u64).saturating_sub(1)) as f64;
    // The first pixel whose running total exceeds k.
    let (mut lo, mut hi) = (0usize, m);
    while lo < hi {
        let mid = (lo + hi) / 2;
        if pairs[2 * mid + 1] > k {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    let i = *pairs.get(2 * lo.min(m.checked_sub(1)?))?;
    let (col, row) = ((i % w).floor(), (i / w).floor());
    Some(((col - w / 2.0) / side, (row - h / 2.0) / side))
}

// ---------------------------------------------------------------------------------------------
// The formula

/// JWildfire's grid-cell hash.
fn noise(v: f64) -> f64 {
    lattice_noise(ftoi(v))
}

/// The corner of the grid cell of `v`: v − fmod(v, size) (C's remainder; NaN for size 0).
fn cell(v: f64, size: f64) -> f64 {
    v - v % size
}

/// The brush stroke at the point (x, y) with colour coordinate `color`: the new point, or
/// `None` when the point is left as it is.
fn stroke(v: &Prepared, x: f64, y: f64, color: f64, rng: &mut FastRng) -> Option<(f64, f64)> {
    let [
        blend,
        grid_size,
        grid_deform,
        grid_rotate,
        grid_scale,
        grid_blend,
        _,
        _,
        _,
        batch,
        _,
        _,
        _,
        _,
        _,
        _,
        antialias,
    ] = v.params();
    let (gx, gy) = (cell(x, grid_size), cell(y, grid_size));
    let g = ftoi(
        ((batch as i32).saturating_add(1)) as f64
            * 0.5
            * (color + noise(NOISE_GEN * (gx + 1235.767 * gy))),
    );
    let g = g.min(batch as i32).max(0);
    let block = variant(v.data(), g as usize)?;
    let total = block.get(1).copied().unwrap_or(0.0);
    let total_blend = blend * (1.0 + (0.5 - noise(NOISE_Y * (gy + 17.85263 * gx))) * grid_blend);
    if !(total > 1.0 && (blend < EPS || rng.f01() > total_blend)) {
        return None;
    }
    let (mut rx, mut ry) = draw_pixel(block, rng)?;
    let alpha = noise(NOISE_X * (gx - 73.547321 * gy)) * grid_rotate;
    let scale = 1.0 + (0.5 - noise(NOISE_Y * (gy + 31.67891 * gx))) * grid_scale;
    let (s, c) = alpha.sin_cos();
    (rx, ry) = ((c * rx - s * ry) * scale, (s * rx + c * ry) * scale);
    if antialias > 0.01 {
        // 1 − u lies in (0, 1]: its logarithm is finite.
        let u = 1.0 - rng.f01();
        let dr = ((antialias * (-u.ln()).sqrt()).exp() - 1.0) * 0.001;
        let (s, c) = (rng.f01() * 2.0 * std::f64::consts::PI).sin_cos();
        rx += dr * c;
        ry += dr * s;
    }
    let w = v.w;
    if grid_size <= EPS {
        Some((w * rx, w * ry))
    } else {
        let dx = (0.5 - noise(NOISE_X * (gx - 17.236612 * gy))) * grid_deform;
        let dy = (0.5 - noise(NOISE_Y * (gy + 76.32561 * gx))) * grid_deform;
        Some((gx + dx + w * rx, gy + dy + w * ry))
    }
}

/// JWildfire hides a point that ends at the origin.
fn at_origin(x: f64, y: f64) -> bool {
    x.abs() < EPS && y.abs() < EPS
}

/// brush_stroke_wf: the stroke's point replaces the xform's sum so far; a point left as it
/// is leaves the sum.
fn brush_stroke_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let z = v.default_z(t);
    match stroke(v, t.x, t.y, t.color, rng) {
        Some((x, y)) => {
            acc.x = 0.0;
            acc.y = 0.0;
            acc.hide = at_origin(x, y);
            [x, y, z]
        }
        None => {
            acc.hide = at_origin(acc.x, acc.y);
            [0.0, 0.0, z]
        }
    }
}

/// post_brush_stroke_wf: the stroke of the summed point.
fn post_brush_stroke_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = stroke(v, t.x, t.y, t.color, rng).unwrap_or((t.x, t.y));
    acc.hide = at_origin(x, y);
    [x, y, v.default_z(t)]
}

#[cfg(test)]
#[path = "jwf_br_brush_tests.rs"]
mod tests;
