//! JWildfire's drawings built on its `DrawFunc` (a list of figures made once, one drawn at
//! random per call): `curliecue` (Jesus Sosa's curlicue: a path turning by a growing angle,
//! drawn as blurred dots or polygons joined by lines, mirrored) and `gpattern` (rows of
//! polygons of the sides a text lists, jittered), and `triantruchet` (Truchet tiles of half
//! squares, each tile's turn set by its row and column parity).
//!
//! The formulas follow JWildfire 9.00's (LGPL-2.1) `CurliecueFunc`, `GPatternFunc`,
//! `TrianTruchetFunc` and `DrawFunc`, written anew; the figures come from Java's generator
//! seeded as JWildfire seeds it, so a seed gives JWildfire's drawing. Polygons are sampled by
//! [`nblur_point`], as JWildfire's other drawings.

use std::f64::consts::PI;

use super::jwf_a_cuts::JavaRandom;
use super::jwf_m_draw::nblur_point;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("curliecue", curliecue)
        .params(&[
            // JWildfire's bound: at most 10 000 steps (240 000 figures).
            p_int("curliecue_Points", 500.0, 1.0, 10000.0),
            p_int("curliecue_seed", 1000.0, -2147483648.0, 2147483647.0),
            p_int("curliecue_type", 0.0, 0.0, 1.0),
            p_int("curliecue_sides", 4.0, 3.0, 20.0),
            p_range("curliecue_scale", 0.02, 0.0, 1.0),
            p_int("curliecue_symmetry", 1.0, 1.0, 4.0),
            p_range("curliecue_eccentricity", 0.0, 0.0, 1.0),
            p_int("curliecue_showlines", 1.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .shared(&[0, 1, 2, 3, 4, 5, 6, 7], curliecue_figures),
    VarDef::new("gpattern", gpattern)
        .params(&[
            p_int("gpattern_seed", 10000.0, -2147483648.0, 2147483647.0),
            // JWildfire's bounds: width and height up to 10, rows at least 0.01 apart (at most
            // about two million figures).
            p_range("gpattern_width", 4.0, 0.0, 10.0),
            p_range("gpattern_height", 2.0, 0.0, 10.0),
            p_range("gpattern_lineheight", 0.15, 0.01, 1.5),
            p("gpattern_angle", 0.0),
            p("gpattern_randPos", 0.0),
            p_range("gpattern_randSize", 0.0, -1.0, 1.0),
            p_int("gpattern_fill", 1.0, 0.0, 1.0),
            p_int("gpattern_ouline", 0.0, 0.0, 1.0),
            p_range("gpattern_fill color", 0.0, 0.0, 1.0),
            p_range("gpattern_fill color speed", 1.0, 0.0, 1.0),
            p_range("gpattern_outline color", 0.0, 0.0, 1.0),
        ])
        .texts(GPATTERN_TEXTS)
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .shared(&[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11], gpattern_figures),
    VarDef::new("triantruchet", triantruchet)
        .params(&[
            p_int("triantruchet_seed", 10000.0, -2147483648.0, 2147483647.0),
            p_range("triantruchet_Size", 2.0, 0.0, 10.0),
            p_int("triantruchet_TilesPerRow", 10.0, 2.0, 600.0),
            p_int("triantruchet_TilesPerColumn", 10.0, 2.0, 600.0),
        ])
        .texts(TRIANTRUCHET_TEXTS)
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::STATEFUL | flag::SETS_COLOR)
        .prepare(triantruchet_prepare),
];

/// gpattern's list of polygon side counts, comma-separated.
const GPATTERN_TEXTS: &[TextParam] = &[TextParam {
    name: "gpattern_string",
    default: "3,4,5,6,5,4,3",
    max_len: 4096,
}];

/// triantruchet's four tile turns (digits, quarter turns) used when the seed is 0.
const TRIANTRUCHET_TEXTS: &[TextParam] = &[TextParam {
    name: "triantruchet_string",
    default: "0132",
    max_len: 64,
}];

/// The values one figure takes in a figure table: its kind, then for a dot (1) x, y, colour;
/// a line (2) x1, y1, x2, y2, colour; a polygon (4) sides, size, cos and sin of its turn,
/// centre x, y, colour, hole.
const FIG: usize = 9;

fn push_dot(t: &mut Vec<f64>, x: f64, y: f64, color: f64) {
    t.extend_from_slice(&[1.0, x, y, color, 0.0, 0.0, 0.0, 0.0, 0.0]);
}

fn push_line(t: &mut Vec<f64>, (x1, y1): (f64, f64), (x2, y2): (f64, f64), color: f64) {
    t.extend_from_slice(&[2.0, x1, y1, x2, y2, color, 0.0, 0.0, 0.0]);
}

/// A polygon turned by `angle` degrees.
fn push_poly(
    t: &mut Vec<f64>,
    sides: f64,
    size: f64,
    angle: f64,
    (x, y): (f64, f64),
    color: f64,
    hole: f64,
) {
    let a = angle * PI / 180.0;
    t.extend_from_slice(&[4.0, sides, size, a.cos(), a.sin(), x, y, color, hole]);
}

/// Rounded to single precision, as JWildfire stores some coordinates.
fn f32r(x: f64) -> f64 {
    x as f32 as f64
}

/// A random point of the segment from (x1, y1) to (x2, y2), as JWildfire's `plotLine` draws it
/// (its slope capped at 10 000 for a vertical segment; no thickness: the drawings here never
/// set one).
pub(super) fn line_point(rng: &mut FastRng, x1: f64, y1: f64, x2: f64, y2: f64) -> (f64, f64) {
    let (dx, dy) = (x2 - x1, y2 - y1);
    let m = if dx == 0.0 { 10000.0 } else { dy / dx };
    let len = (dx * dx + dy * dy).sqrt();
    let d = rng.f01() * len;
    let mut xo = d / (1.0 + m * m).sqrt();
    if x2 < x1 {
        xo = -xo;
    }
    let mut yo = (m * xo).abs();
    if y2 < y1 {
        yo = -yo;
    }
    (x1 + xo, y1 + yo)
}

/// A random figure of `table` and a random point of it: (x, y, colour, whether it is a
/// polygon). Dots are blurred by `blur`; a polygon's point is placed and turned already.
fn draw(table: &[f64], rng: &mut FastRng, blur: f64) -> Option<(f64, f64, f64, bool)> {
    let count = table.len() / FIG;
    if count == 0 {
        return None;
    }
    let i = ((rng.f01() * count as f64) as usize).min(count - 1);
    let f: [f64; FIG] = table[i * FIG..(i + 1) * FIG].try_into().ok()?;
    Some(match f[0] as i32 {
        1 => {
            let a = rng.f01() * 2.0 * PI;
            let r = blur * rng.f01();
            (f[1] + r * a.cos(), f[2] + r * a.sin(), f[3], false)
        }
        2 => {
            let (x, y) = line_point(rng, f[1], f[2], f[3], f[4]);
            (x, y, f[5], false)
        }
        _ => {
            let [_, sides, size, cosa, sina, px, py, color, hole] = f;
            let (x, y) = nblur_point(rng, sides as i32, hole);
            (
                x * size * cosa + y * size * sina + px,
                -x * size * sina + y * size * cosa + py,
                color,
                true,
            )
        }
    })
}

/// curliecue's figures: the curlicue path of `Points` steps of length 0.01 from (e, e) (e the
/// eccentricity), its heading turning by θ and θ by 2π·s per step (s drawn from `seed`),
/// each step's two ends drawn as dots (`type` 0) or polygons (1), joined by a line with
/// `showlines`, in 1, 4, 4 or 8 mirror images (`symmetry` 1–4), coloured by the step.
fn curliecue_figures(p: &[f64], _texts: &[String]) -> Vec<f64> {
    let [size, seed, kind, sides, scale, symmetry, ecce, lines] = params_of(p);
    type Map = fn(f64, f64) -> (f64, f64);
    let maps: &[Map] = match symmetry as i32 {
        2 => &[
            |x, y| (x, -y),
            |x, y| (-x, y),
            |x, y| (y, x),
            |x, y| (-y, -x),
        ],
        3 => &[
            |x, y| (x, -y),
            |x, y| (-x, y),
            |x, y| (-x, -y),
            |x, y| (x, y),
        ],
        4 => &[
            |x, y| (x, -y),
            |x, y| (-x, y),
            |x, y| (y, x),
            |x, y| (-y, -x),
            |x, y| (x, y),
            |x, y| (-x, -y),
            |x, y| (y, -x),
            |x, y| (-y, x),
        ],
        _ => &[|x, y| (x, -y)],
    };
    let s = JavaRandom::new(seed as i64).next_f64();
    let (mut theta, mut phi) = (0.0f64, 0.0f64);
    let (mut x0, mut y0) = (ecce, ecce);
    let mut t = Vec::new();
    for i in 0..size.clamp(0.0, 10000.0) as i32 {
        let x1 = x0 + 0.01 * phi.cos();
        let y1 = y0 + 0.01 * phi.sin();
        let c = f64::from(i) / size;
        for map in maps {
            let (a, b) = (map(x0, y0), map(x1, y1));
            if kind == 0.0 {
                if symmetry == 1.0 {
                    push_dot(&mut t, f32r(a.0), f32r(a.1), c);
                    push_dot(&mut t, f32r(b.0), f32r(b.1), c);
                } else {
                    push_dot(&mut t, a.0, a.1, c);
                    push_dot(&mut t, b.0, b.1, c);
                }
            } else {
                push_poly(&mut t, sides, scale, 0.0, a, c, 0.0);
                push_poly(&mut t, sides, scale, 0.0, b, c, 0.0);
            }
            if lines == 1.0 {
                push_line(&mut t, (f32r(a.0), f32r(a.1)), (f32r(b.0), f32r(b.1)), c);
            }
        }
        (x0, y0) = (x1, y1);
        phi = (theta + phi) % (2.0 * PI);
        theta = (theta + 2.0 * PI * s) % (2.0 * PI);
    }
    t
}

/// curliecue: a random point of a random figure of the curlicue (dots blurred by `scale`),
/// weighted, with the figure's colour.
fn curliecue(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let scale = v.p[4];
    match draw(v.data(), rng, scale) {
        Some((x, y, c, _)) => {
            acc.color = c;
            [v.w * x, v.w * y, 0.0]
        }
        None => [0.0; 3],
    }
}

/// gpattern's figures: columns `lineheight` apart up to `width`, each a column of polygons
/// `lineheight` apart up to `height`, their side counts cycling through the text's list (3
/// for an entry that is not a number from 3 to 20), moved by up to `randPos` sideways and
/// sized `lineheight`/2 ± `randSize`; filled (colour `fill color` plus a random part of
/// `fill color speed`, mod 1) and/or outlined (`ouline`, colour `outline color`).
fn gpattern_figures(p: &[f64], texts: &[String]) -> Vec<f64> {
    let [
        seed,
        width,
        height,
        lh,
        angle,
        rand_pos,
        rand_size,
        fill,
        outline,
        color,
        speed,
        ocolor,
    ] = params_of(p);
    let text = texts
        .first()
        .map_or(GPATTERN_TEXTS[0].default, |s| s.as_str());
    let polys: Vec<f64> = text
        .split(',')
        .map(|s| match s.parse::<i32>() {
            Ok(n) if (3..=20).contains(&n) => f64::from(n),
            _ => 3.0,
        })
        .collect();
    let mut rnd = JavaRandom::new(seed as i64);
    let mut t = Vec::new();
    // Both loops are bounded by the parameters' ranges: at most 10 / 0.01 + 1 steps each.
    let lh = lh.max(0.01);
    let mut posj = 0.0;
    while posj <= width {
        let mut y = 0.0;
        let mut k = 0;
        while y <= height {
            let x = posj + (-rand_pos + 2.0 * rand_pos * rnd.next_f64());
            let r = f32r(lh / 2.0) + (-rand_size + 2.0 * rand_size * rnd.next_f64());
            let sides = polys[k % polys.len()];
            if outline == 1.0 {
                push_poly(&mut t, sides, r, angle, (x, y), ocolor, 1.0);
            }
            if fill == 1.0 {
                let c = (color + speed * rnd.next_f64()) % 1.0;
                push_poly(&mut t, sides, r, angle, (x, y), c, 0.0);
            }
            k = (k + 1) % polys.len();
            y += lh;
        }
        posj += lh;
    }
    t
}

/// gpattern: a random point of a random polygon of the pattern (not weighted: the pattern is
/// drawn where it lies), with the polygon's colour.
fn gpattern(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    match draw(v.data(), rng, 0.0) {
        Some((x, y, c, poly)) => {
            acc.color = c;
            if poly {
                [x, y, 0.0]
            } else {
                [v.w * x, v.w * y, 0.0]
            }
        }
        None => [0.0; 3],
    }
}

/// triantruchet's set-up: the four tile turns (quarter turns, for the even/odd rows and
/// columns) from Java's generator seeded with `seed` (the first draw skipped), or, for seed 0,
/// from the text's first four digits; the generator, which then picks the tiles call after
/// call, is carried in the state.
fn triantruchet_prepare(v: &mut Prepared) {
    let [seed] = v.params();
    let mut rnd = JavaRandom::new(seed as i64);
    rnd.next_f64();
    let mut n: [f64; 4] = std::array::from_fn(|_| (rnd.next_f64() * 4.0).floor());
    if seed == 0.0 {
        let digits: Vec<f64> = v
            .texts
            .first()
            .map_or("0132", |s| s.as_str())
            .chars()
            .take(4)
            .map(|c| c.to_digit(10).map_or(-1.0, f64::from))
            .collect();
        // JWildfire keeps its drawn turns when any of the four is missing or not a digit.
        if digits.len() == 4 && digits.iter().all(|&d| d >= 0.0) {
            n.copy_from_slice(&digits);
        }
    }
    v.p.extend_from_slice(&n);
    v.state.set(0, rnd.0 as f64);
}

/// triantruchet: a random point of a random tile (picked by the carried generator) of a
/// rows × columns grid of side `Size`, centred: the tile's half square (the triangle below
/// its diagonal) turned by the quarter turns of its row and column parity; coloured by the
/// tile's index. JWildfire computes the tiles in single precision, as here.
fn triantruchet(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, size, rows, cols] = v.params();
    let turns: [f64; 4] = v.derived();
    let mut rnd = JavaRandom(v.state.get(0) as u64);
    let i = (rnd.next_f64() * rows) as i32;
    let j = (rnd.next_f64() * cols) as i32;
    v.state.set(0, rnd.0 as f64);
    let ts = size as f32 / rows as i32 as f32;
    let cx = i as f32 * ts + ts / 2.0;
    let cy = j as f32 * ts + ts / 2.0;
    let k = match (i % 2 == 0, j % 2 == 0) {
        (true, true) => turns[0],
        (true, false) => turns[2],
        (false, true) => turns[1],
        (false, false) => turns[3],
    };
    let tilt = (k * PI / 2.0) as f32 as f64;
    let (s, c) = tilt.sin_cos();
    let h = f64::from(ts / 2.0);
    let corner = |x: f64, y: f64| {
        (
            f32r(x * c + y * s + f64::from(cx)),
            f32r(-x * s + y * c + f64::from(cy)),
        )
    };
    let (p1, p2, p3) = (corner(-h, -h), corner(-h, h), corner(h, h));
    let sr = rng.f01().sqrt();
    let r2 = rng.f01();
    let (a, b, cc) = (1.0 - sr, sr * (1.0 - r2), r2 * sr);
    let dx = a * p1.0 + b * p2.0 + cc * p3.0;
    let dy = a * p1.1 + b * p2.1 + cc * p3.1;
    acc.color = (rows * f64::from(j) + f64::from(i)) / (rows * cols);
    [
        v.w * (dx - f64::from(ts * rows as f32) / 2.0),
        v.w * (dy - f64::from(ts * cols as f32) / 2.0),
        0.0,
    ]
}
