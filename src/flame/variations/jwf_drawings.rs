//! JWildfire's drawings: points on line drawings built once (`hilbert_js`, `rsquares_js`,
//! `tree_js`), on curves (`rose_wf`, `epispiral_wf`, `chrysanthemum`) and in filled figures
//! (`xheart_blur_wf`, `szubieta`, `nsudoku`, `snowflake_wf`).
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: `atan_xy` is its `getPrecalcAtan`
//! (atan2(x, y)), weights multiply the output linearly, integer parameters are rounded (those it
//! truncates, `(int) value`, are stored as reals and truncated where used), and random numbers
//! are drawn in the order JWildfire draws them, so that the tests can replay JWildfire's own code
//! on the same stream.

use std::f64::consts::{FRAC_PI_4, PI, TAU};

use super::util::{Draw, Mwc};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("rose_wf", rose_wf)
        .params(&[
            p("rose_wf_amp", 0.5),
            p_int("rose_wf_waves", 4.0, NEG_INF, INF),
            p("rose_wf_filled", 0.85),
        ])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("chrysanthemum", chrysanthemum).flags(flag::JWILDFIRE | flag::RANDOM),
    VarDef::new("xheart_blur_wf", xheart_blur_wf)
        .params(&[
            p("xheart_blur_wf_angle", 0.0),
            p("xheart_blur_wf_ratio", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .prepare(xheart_blur_prepare),
    VarDef::new("epispiral_wf", epispiral_wf)
        .params(&[p("epispiral_wf_waves", 4.0)])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE),
    VarDef::new("szubieta", szubieta)
        .params(&[
            p_int("szubieta_width", 128.0, 32.0, 256.0),
            p_int("szubieta_height", 128.0, 32.0, 256.0),
            p_int("szubieta_type", 0.0, 0.0, 1.0),
            p_range("szubieta_scale", 0.5, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .prepare(szubieta_prepare),
    VarDef::new("nsudoku", nsudoku)
        .params(&[
            p_int("nsudoku_Level", 5.0, 1.0, 9.0),
            p_range("nsudoku_thickness", 0.5, 0.0, 1.0),
            p_range("nsudoku_size", 0.5, 0.3, 1.0),
            p("nsudoku_angle", 0.0),
            p_int("nsudoku_type", 4.0, 3.0, 6.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .prepare(nsudoku_prepare),
    VarDef::new("snowflake_wf", snowflake_wf)
        .params(&[
            p_int("snowflake_wf_buffer_size", 128.0, 1.0, 1024.0).limited(),
            p_int("snowflake_wf_max_iter", 500.0, 0.0, 100_000.0).limited(),
            p("snowflake_wf_bg_freeze_level", 0.5),
            p("snowflake_wf_fg_freeze_speed", 0.0005),
            p("snowflake_wf_diffusion_speed", 0.01),
            p("snowflake_wf_diffusion_asymmetry", 1.0),
            p("snowflake_wf_rnd_bg_noise", 0.25),
            p("snowflake_wf_threshold", 0.65),
            p_int("snowflake_wf_seed", 12345.0, NEG_INF, INF),
            p("snowflake_wf_scale", 1.0),
            p("snowflake_wf_jitter", 0.001),
            p_int("snowflake_wf_dc_color", 1.0, NEG_INF, INF),
            p("snowflake_wf_dc_color_scale", 2.0),
            p("snowflake_wf_dc_color_offset", 0.1),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .shared(&[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10], snowflake_points),
    VarDef::new("hilbert_js", hilbert_js)
        .params(P_HILBERT)
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0], hilbert_segments)
        .prepare(prep_la5),
    VarDef::new("rsquares_js", rsquares_js)
        .params(P_RSQUARES)
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0], rsquares_segments)
        .prepare(prep_la5),
    VarDef::new("tree_js", tree_js)
        .params(P_TREE)
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0, 3, 4, 5], tree_segments)
        .prepare(prep_tree),
];

/// rose_wf: the rose curve r = amp·cos(waves·θ) drawn along the input's direction (θ measured
/// from the y axis, JWildfire's atan2(x, y)); a share `filled` of the points falls inside.
fn rose_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [amp, waves, filled] = v.params();
    let a = t.atan_xy;
    let mut r = amp * (waves * a).cos();
    // A share `filled` of the points falls inside the petal (JWildfire 9.00; before, `filled`
    // was 0 or 1, which this reads the same way). A share of 1 or more needs no draw.
    if filled >= 1.0 || (filled > 0.0 && filled > rng.f01()) {
        r *= rng.f01();
    }
    let (s, c) = a.sin_cos();
    [v.w * s * r, v.w * c * r, 0.0]
}

/// epispiral_wf: the epispiral r = 0.5 / cos(waves·θ) along the input's direction (θ from the
/// y axis).
fn epispiral_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [waves] = v.params();
    let a = t.atan_xy;
    let d = (waves * a).cos();
    if d == 0.0 {
        return [0.0; 3];
    }
    let r = 0.5 / d;
    let (s, c) = a.sin_cos();
    [v.w * s * r, v.w * c * r, 0.0]
}

/// chrysanthemum: Paul Bourke's chrysanthemum curve, a point at a random parameter
/// u ∈ [0, 21π), at a tenth of the weight (the input point is ignored).
fn chrysanthemum(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let u = 21.0 * PI * rng.f01();
    let s4 = (17.0 * u / 3.0).sin();
    let s8 = (2.0 * (3.0 * u).cos() - 28.0 * u).sin();
    let s4_2 = s4 * s4;
    let s8_2 = s8 * s8;
    let s8_4 = s8_2 * s8_2;
    let r = 5.0 * (1.0 + (11.0 * u / 5.0).sin()) - 4.0 * (s4_2 * s4_2) * (s8_4 * s8_4);
    let r = r * v.w * 0.1;
    let (s, c) = u.sin_cos();
    [r * c, r * s, 0.0]
}

fn xheart_blur_prepare(v: &mut Prepared) {
    let [angle, ratio] = v.params();
    let ang = FRAC_PI_4 + 0.5 * FRAC_PI_4 * angle;
    let (s, c) = ang.sin_cos();
    let rat = 6.0 + 2.0 * ratio;
    v.p.extend_from_slice(&[s, c, rat]);
}

/// xheart_blur_wf: xheart applied to a uniformly random point of the square [-2, 2]², a heart
/// shape filled with points (the input point is ignored).
fn xheart_blur_wf(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [sina, cosa, rat] = v.derived();
    let dx = 2.0 - rng.f01() * 4.0;
    let dy = 2.0 - rng.f01() * 4.0;
    let mut r2_4 = dx * dx + dy * dy + 4.0;
    if r2_4 == 0.0 {
        r2_4 = 1.0;
    }
    let bx = 4.0 / r2_4 * dx;
    let by = rat / r2_4 * dy;
    let x = cosa * bx - sina * by;
    let y = sina * bx + cosa * by;
    let ys = if x > 0.0 { y } else { -y };
    [v.w * x, v.w * ys, 0.0]
}

/// Constants of the polygon sampler for `sides` sides, appended to `p`: [sides, mid angle,
/// tan(π/2 + mid/2), spread, spread normaliser, sin(mid/2), cos(mid/2)].
fn push_polygon(p: &mut Vec<f64>, sides: f64) {
    let n = sides.max(3.0);
    let mid = TAU / n;
    let spread = 13.0 / n.powf(1.3);
    let (s, c) = (mid / 2.0).sin_cos();
    p.extend_from_slice(&[
        n,
        mid,
        (PI / 2.0 + mid / 2.0).tan(),
        spread,
        2.0 * (spread / -2.0).atan(),
        s,
        c,
    ]);
}

/// A random point of the regular polygon described at `g` (see [`push_polygon`]) with unit
/// circumradius, uniform in area between the hole (relative size `hole`) and the edge. Draws
/// four numbers, as JWildfire does (one of them unused).
fn polygon_point(g: [f64; 7], hole: f64, rng: &mut FastRng) -> (f64, f64) {
    let [n, mid, tan90, spread, norm, s, c] = g;
    let jitter = rng.f01() - 0.5;
    let corner = ((rng.f01() * 32767.0) as i32).min(32766) as f64 % n;
    let mut ang = ((spread * jitter).atan() / norm + 0.5 + corner) * mid;
    let (dx, dy) = ang.sin_cos();
    while ang > mid {
        ang -= mid;
    }
    let ta = ang.tan();
    let ex = tan90 / (tan90 - ta);
    let ey = ex * ta;
    let outer = (ex * ex + ey * ey).sqrt();
    rng.f01();
    let inner = hole * outer;
    let len = inner + rng.f01().sqrt() * (outer - inner);
    let (x, y) = (dx * len, dy * len);
    (c * x - s * y, s * x + c * y)
}

fn szubieta_prepare(v: &mut Prepared) {
    push_polygon(&mut v.p, 20.0);
}

/// Grey level of cell (i, j) of Paul Bourke's "circle squares" (kind 0) or "square tile"
/// (kind 1) integer patterns, in [0, 1].
fn bourke_pattern(kind: f64, i: i32, j: i32) -> f64 {
    if kind == 0.0 {
        let x = i
            .wrapping_mul(i)
            .wrapping_sub(2 * (i | j))
            .wrapping_add(j.wrapping_mul(j));
        (x % 255).abs() as f64 / 255.0
    } else {
        let x = i & (j - 2 * (i ^ j) + j) & i;
        (x % 256).abs() as f64 / 255.0
    }
}

/// szubieta: a width × height grid of small filled 20-gons (radius `scale`, spacing 1, the
/// whole scaled by 0.1), coloured by one of Paul Bourke's integer patterns; the point lands in
/// a random cell (the input point is ignored).
fn szubieta(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [width, height, kind, scale] = v.params();
    let cells = width as usize * height as usize;
    let idx = ((rng.f01() * cells as f64) as usize).min(cells - 1);
    let (i, j) = (
        (idx / height as usize) as i32,
        (idx % height as usize) as i32,
    );
    let (px, py) = (i as f64 - width / 2.0, j as f64 - height / 2.0);
    let (ox, oy) = polygon_point(v.derived(), 0.0, rng);
    acc.color = bourke_pattern(kind, i, j);
    let k = v.w * 0.1;
    [k * (ox * scale + px), k * (oy * scale + py), 0.0]
}

/// Where nsudoku's layers start in its derived values: after the polygon (7 values, see
/// [`push_polygon`]), the rotation's cosine and sine, and the layer count.
const SUDOKU_LAYERS: usize = 10;

/// Per layer: polygon radius, hole size, then the 81 digits (cell i·9 + j).
const SUDOKU_LAYER_LEN: usize = 83;

/// A valid, randomly relabelled and shuffled 9×9 sudoku solution (digits 1–9).
fn random_sudoku(rng: &mut FastRng) -> [[u8; 9]; 9] {
    let shuffle = |rng: &mut FastRng, a: &mut [usize]| {
        for i in (1..a.len()).rev() {
            let k = rng.below(i as u64 + 1) as usize;
            a.swap(i, k);
        }
    };
    let mut digits = [0usize, 1, 2, 3, 4, 5, 6, 7, 8];
    shuffle(rng, &mut digits);
    // Row and column orders: bands (stacks) shuffled, rows (columns) shuffled within them.
    let order = |rng: &mut FastRng| {
        let mut bands = [0usize, 1, 2];
        shuffle(rng, &mut bands);
        let mut out = [0usize; 9];
        for (b, &band) in bands.iter().enumerate() {
            let mut within = [0usize, 1, 2];
            shuffle(rng, &mut within);
            for (k, &w) in within.iter().enumerate() {
                out[3 * b + k] = 3 * band + w;
            }
        }
        out
    };
    let rows = order(rng);
    let cols = order(rng);
    let mut g = [[0u8; 9]; 9];
    for (r, row) in g.iter_mut().enumerate() {
        for (c, cell) in row.iter_mut().enumerate() {
            let (rr, cc) = (rows[r], cols[c]);
            let base = (3 * (rr % 3) + rr / 3 + cc) % 9;
            *cell = digits[base] as u8 + 1;
        }
    }
    g
}

/// The 1296 row permutations that keep a sudoku valid (rows permuted within each band, bands
/// permuted), as 1-based row numbers.
fn sudoku_row_permutations() -> Vec<[u8; 9]> {
    const P3: [[u8; 3]; 6] = [
        [1, 2, 3],
        [1, 3, 2],
        [2, 1, 3],
        [2, 3, 1],
        [3, 1, 2],
        [3, 2, 1],
    ];
    let mut out = Vec::with_capacity(1296);
    for a in P3 {
        for b in P3 {
            for c in P3 {
                for bands in P3 {
                    let within = [a, b, c];
                    let mut row = [0u8; 9];
                    for k in 0..9 {
                        row[k] = within[k / 3][k % 3] + 3 * bands[k / 3] - 3;
                    }
                    out.push(row);
                }
            }
        }
    }
    out
}

fn nsudoku_prepare(v: &mut Prepared) {
    let [level, thickness, size, angle, sides] = v.params();
    let hole = 1.0 - thickness;
    push_polygon(&mut v.p, sides);
    let (s, c) = (angle * PI / 180.0).sin_cos();
    v.p.extend_from_slice(&[c, s]);
    let count_at = v.p.len();
    v.p.push(0.0);
    // JWildfire draws a fresh random sudoku each time; a fixed seed keeps renders repeatable.
    let mut rng = FastRng::new(0x7375_646f_6b75);
    let base = random_sudoku(&mut rng);
    let mut candidates = sudoku_row_permutations();
    let mut perm: [u8; 9] = [1, 2, 3, 4, 5, 6, 7, 8, 9];
    let mut layers = 0;
    let mut n = level;
    while n >= 1.0 {
        if n != level {
            if candidates.is_empty() {
                break;
            }
            let k = ((rng.f01() * candidates.len() as f64) as usize).min(candidates.len() - 1);
            perm = candidates[k];
        }
        v.p.push(size * (n / level) / 9.0);
        v.p.push(if 1.0 - 1.0 / n == 0.0 { 0.0 } else { hole });
        // Cell (i, j) shows row j, column i of the row-permuted grid.
        v.p.extend((0..9).flat_map(|i| {
            perm.iter()
                .map(move |&row| base[row as usize - 1][i] as f64)
        }));
        layers += 1;
        // Later layers use permutations sharing no row position with this one.
        candidates.retain(|c| c.iter().zip(&perm).all(|(a, b)| a != b));
        n -= 1.0;
    }
    v.p[count_at] = layers as f64;
}

/// nsudoku: `Level` stacked layers of a sudoku grid drawn as filled polygons on the unit square
/// (each layer's rows permuted, polygons shrinking layer by layer, hollow by `thickness`); the
/// colour is the cell's digit / 9 (the input point is ignored).
fn nsudoku(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, c, s, layers] = v.derived();
    let layers = layers as usize;
    let total = layers * 81;
    let idx = ((rng.f01() * total as f64) as usize).min(total - 1);
    let (layer, cell) = (idx / 81, idx % 81);
    let l = &v.table(SUDOKU_LAYERS)[layer * SUDOKU_LAYER_LEN..];
    let (radius, hole) = (l[0], l[1]);
    let (px, py) = ((cell / 9) as f64 / 9.0 - 0.5, (cell % 9) as f64 / 9.0 - 0.5);
    let (ox, oy) = polygon_point(v.derived(), hole, rng);
    acc.color = l[2 + cell] / 9.0;
    [
        v.w * (ox * radius * c + oy * radius * s + px),
        v.w * (-ox * radius * s + oy * radius * c + py),
        0.0,
    ]
}

/// Most cell updates of a snow crystal's growth (four times those of the default 128-cell
/// grid grown 500 times: a few seconds).
const SNOW_MAX_WORK: usize = 1 << 27;

/// Ratio JWildfire uses to lay the hexagonal grid out on a square canvas.
const SNOW_STRETCH: f64 = 1.5 / 1.7321;

/// Clifford Reiter's local cellular model of snow crystal growth on a hexagonal grid of
/// `width` columns; returns the canvas of frozen values above the threshold (0 elsewhere).
fn snow_crystal(q: &[f64]) -> Vec<Vec<f32>> {
    let [
        size,
        max_iter,
        bg,
        freeze,
        diffusion,
        asym,
        noise,
        threshold,
        seed,
    ] = params_of(q);
    let w = size.max(1.0) as usize;
    let h = 2 * w - 1;
    let cells = w * h + (w - 1) * (h - 1);
    // The growth costs cells × iterations; a large grid gets fewer iterations.
    let iters = (max_iter.max(0.0) as usize).min(SNOW_MAX_WORK / cells.max(1));
    let (wi, ci) = (w as i64, cells as i64);
    let offsets = [-wi - (wi - 1), -(wi - 1), wi, wi + (wi - 1), wi - 1, -wi];
    let neighbour = |n: usize, k: usize| -> Option<usize> {
        let m = n as i64 + offsets[k];
        (m >= 0 && m < ci).then_some(m as usize)
    };
    let mut rnd = Mwc::new(seed as i64);
    let mut field: Vec<f64> = (0..cells)
        .map(|_| bg + (noise - 2.0 * noise * rnd.next_f64()))
        .collect();
    field[cells / 2] = 1.0;
    let mut diffusing = vec![0.0; cells];
    let mut spread = vec![0.0; cells];
    let mut frozen = vec![0.0; cells];
    let t_freeze = freeze / 1000.0;
    let t_diff = diffusion / 1000.0 + 1.0;
    let c_weight = 0.5 * asym / t_diff;
    let n_weight = (t_diff - c_weight) / 6.0;
    for _ in 0..iters {
        diffusing.copy_from_slice(&field);
        frozen.iter_mut().for_each(|f| *f = 0.0);
        for i in 0..cells {
            if field[i] >= 1.0 {
                frozen[i] = field[i];
                for k in 0..6 {
                    if let Some(m) = neighbour(i, k) {
                        diffusing[m] = 0.0;
                        frozen[m] = if field[m] > 0.0 {
                            field[m] + t_freeze
                        } else {
                            field[m]
                        };
                    }
                }
            }
        }
        for i in 0..cells {
            let mut s = diffusing[i] * c_weight;
            for k in 0..6 {
                if let Some(m) = neighbour(i, k) {
                    s += diffusing[m] * n_weight;
                }
            }
            spread[i] = s;
        }
        for i in 0..cells {
            field[i] = spread[i] + frozen[i];
        }
    }
    // Render the hexagonal cells onto a rectangular canvas.
    let cw = (2.0 * w as f64 * SNOW_STRETCH).floor() as usize;
    let mut canvas = vec![vec![0f32; cw]; h];
    let mut put = |value: f64, x: i64, y: usize| {
        if value > threshold + 1e-8 && x >= 0 && (x as usize) < cw {
            canvas[y][x as usize] = (value - threshold) as f32;
        }
    };
    for i in 0..h {
        for j in 0..w {
            let base = (2 * w - 1) * i + j;
            put(field[base], ((2 * j) as f64 * SNOW_STRETCH + 0.5) as i64, i);
            let (a, b) = (base as i64 - wi + 1, (base + w) as i64);
            if a >= 0 && a < ci && b < ci {
                let avg = (field[a as usize] + field[b as usize]) * 0.5;
                put(avg, ((2 * j + 1) as f64 * SNOW_STRETCH + 0.5) as i64, i);
            }
        }
    }
    canvas
}

/// snowflake_wf's shared data: the count of points, then x, y and intensity per point (from
/// parameters 0–10: the crystal's growth, its seed, scale and jitter).
fn snowflake_points(q: &[f64], _: &[String]) -> Vec<f64> {
    let canvas = snow_crystal(q);
    let [_, _, _, _, _, _, _, _, seed, scale, jitter] = params_of(q);
    let jitter = jitter.clamp(0.0, 1.0);
    let mut rnd = Mwc::new(seed as i64);
    let mut out = vec![0.0];
    let rows = canvas.len() as f64;
    let mut count = 0;
    for (i, row) in canvas.iter().enumerate() {
        let cols = row.len() as f64;
        for (j, &val) in row.iter().enumerate() {
            // The jitter draw happens for every cell so that growth keeps earlier points fixed.
            let a = if jitter > 1e-8 { rnd.next_f64() } else { 0.0 };
            if (val as f64) > 1e-8 {
                let mut x = (i as f64 - rows * 0.5) * scale / rows;
                let mut y = (j as f64 - cols * 0.5) * scale / cols * SNOW_STRETCH;
                if jitter > 1e-8 {
                    let (s, c) = (a * 2.0 * PI).sin_cos();
                    x += jitter * c;
                    y += jitter * s;
                }
                out.extend_from_slice(&[x, y, val as f64]);
                count += 1;
            }
        }
    }
    out[0] = count as f64;
    out
}

/// snowflake_wf: a random cell of a simulated snow crystal (Reiter's cellular growth model);
/// with `dc_color` the colour follows the cell's frozen amount (the input point is ignored).
fn snowflake_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _buffer_size,
        _max_iter,
        _bg_freeze_level,
        _fg_freeze_speed,
        _diffusion_speed,
        _diffusion_asymmetry,
        _rnd_bg_noise,
        _threshold,
        _seed,
        _scale,
        _jitter,
        dc_color,
        dc_color_scale,
        dc_color_offset,
    ] = v.params();
    let pts = v.data();
    let count = pts[0] as usize;
    // With fewer than two cells JWildfire falls back to the origin with intensity 0.
    let pt = if count < 2 {
        &[0.0; 3][..]
    } else {
        // JWildfire rounds to the nearest index, so the first and last cells are half as likely.
        let k = (rng.f01() * (count - 1) as f64 + 0.5) as usize;
        &pts[1 + 3 * k..]
    };
    if dc_color > 0.0 {
        acc.color = pt[2] * dc_color_scale + dc_color_offset;
    }
    [v.w * pt[0], v.w * pt[1], 0.0]
}

/// Derived values of a line drawing, after its parameters: line threshold, point threshold,
/// line thickness, point thickness. The segments, (x1, y1, x2, y2) each, are its shared data.
const LA_HEAD: usize = 4;

/// Appends the thresholds that split the draws between segments and end-point dots (from the
/// truncated show_lines / show_points weights) and the thicknesses.
pub(super) fn la_store(v: &mut Prepared, lines: f64, lt: f64, points: f64, pt: f64) {
    let lines = lines.trunc();
    let points = points.trunc();
    let total = lines + points;
    let line_part = lines / total;
    v.p.extend_from_slice(&[
        line_part,
        line_part + points / total,
        lt / 100.0,
        pt / 100.0,
    ]);
}

/// One point of segment `seg` of `segs`: somewhere along it (jittered by the line thickness),
/// or near its start (within the point thickness), or the origin when neither is shown; `d`
/// holds the derived values ([`LA_HEAD`]).
fn la_sample<R: Draw>(d: [f64; LA_HEAD], segs: &[f64], seg: usize, r: &mut R) -> (f64, f64) {
    let [line_part, point_part, line_thick, point_thick] = d;
    let s = &segs[4 * seg..4 * seg + 4];
    let (x1, y1, x2, y2) = (s[0], s[1], s[2], s[3]);
    let pick = r.unit();
    if pick < line_part {
        let dx = x2 - x1;
        let dy = y2 - y1;
        // A vertical segment gets a steep finite slope, as in JWildfire.
        let slope = if dx == 0.0 { 10000.0 } else { dy / dx };
        let len = (dx * dx + dy * dy).sqrt();
        let along = r.unit() * len;
        let mut ox = along / (1.0 + slope * slope).sqrt();
        if x2 < x1 {
            ox = -ox;
        }
        let mut oy = (slope * ox).abs();
        if y2 < y1 {
            oy = -oy;
        }
        if line_thick != 0.0 {
            ox += (r.unit() - 0.5) * line_thick;
            oy += (r.unit() - 0.5) * line_thick;
        }
        (x1 + ox, y1 + oy)
    } else if pick <= point_part {
        if point_thick != 0.0 {
            let rad = r.unit() * point_thick;
            let ang = r.unit() * (2.0 * PI);
            (x1 + rad * ang.cos(), y1 + rad * ang.sin())
        } else {
            (x1, y1)
        }
    } else {
        (0.0, 0.0)
    }
}

/// A uniformly chosen segment of the drawing, sampled (JWildfire walks the segments in order,
/// one per call; over many calls both cover every segment equally).
#[inline]
pub(super) fn la_eval(v: &Prepared, rng: &mut FastRng) -> (f64, f64) {
    let segs = v.data();
    let count = segs.len() / 4;
    if count == 0 {
        return (0.0, 0.0);
    }
    let seg = rng.index(count);
    la_sample(v.derived(), segs, seg, rng)
}

/// Turtle that records each forward move as a segment; angles in degrees.
struct Turtle {
    x: f64,
    y: f64,
    heading: f64,
    /// Segments, (x1, y1, x2, y2) each.
    segs: Vec<f64>,
}

impl Turtle {
    fn forward(&mut self) {
        let (x0, y0) = (self.x, self.y);
        let a = self.heading.to_radians();
        self.x += a.cos();
        self.y += a.sin();
        self.segs.extend_from_slice(&[x0, y0, self.x, self.y]);
    }

    /// Hilbert curve of order n, entered turning left.
    fn hilbert(&mut self, n: i64) {
        if n == 0 {
            return;
        }
        self.heading += 90.0;
        self.hilbert_mirror(n - 1);
        self.forward();
        self.heading -= 90.0;
        self.hilbert(n - 1);
        self.forward();
        self.hilbert(n - 1);
        self.heading -= 90.0;
        self.forward();
        self.hilbert_mirror(n - 1);
        self.heading += 90.0;
    }

    /// The mirror image of [`Turtle::hilbert`] (turns exchanged).
    fn hilbert_mirror(&mut self, n: i64) {
        if n == 0 {
            return;
        }
        self.heading -= 90.0;
        self.hilbert(n - 1);
        self.forward();
        self.heading += 90.0;
        self.hilbert_mirror(n - 1);
        self.forward();
        self.hilbert_mirror(n - 1);
        self.heading += 90.0;
        self.forward();
        self.hilbert(n - 1);
        self.heading -= 90.0;
    }
}

/// hilbert_js's segments (from the level, parameter 0).
fn hilbert_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let mut t = Turtle {
        x: 0.0,
        y: 0.0,
        heading: 0.0,
        segs: Vec::new(),
    };
    let [level] = params_of(q);
    t.hilbert(level as i64);
    t.segs
}

/// Derived values of hilbert_js and rsquares_js (same parameter layout).
fn prep_la5(v: &mut Prepared) {
    let [_, lines, lt, points, pt] = v.params();
    la_store(v, lines, lt, points, pt);
}

/// Squares of side `size` centred at (x, y), with four squares of side size/2.2 centred on
/// its corners, recursively, as segments (left side up, top, right side down, bottom).
fn rsquares(segs: &mut Vec<f64>, n: i64, x: f64, y: f64, size: f64) {
    if n == 0 {
        return;
    }
    let h = size / 2.0;
    let (l, r, b, t) = (x - h, x + h, y - h, y + h);
    for side in [[l, b, l, t], [l, t, r, t], [r, t, r, b], [r, b, l, b]] {
        segs.extend_from_slice(&side);
    }
    let s = size / 2.2;
    rsquares(segs, n - 1, l, b, s);
    rsquares(segs, n - 1, l, t, s);
    rsquares(segs, n - 1, r, b, s);
    rsquares(segs, n - 1, r, t, s);
}

/// rsquares_js's segments (from the level, parameter 0).
fn rsquares_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let mut segs = Vec::new();
    let [level] = params_of(q);
    rsquares(&mut segs, level as i64, 0.5, 0.5, 1.0);
    segs
}

/// Branch shape of tree_js: bend and branch angles in radians, length ratio of the side
/// branches (the middle one gets the rest).
struct TreeShape {
    bend: f64,
    branch: f64,
    ratio: f64,
}

/// A branch from (x, y) in direction `a` of length `len`, then (for n > 0) three sub-trees
/// from its tip.
fn tree(segs: &mut Vec<f64>, s: &TreeShape, n: i64, x: f64, y: f64, a: f64, len: f64) {
    let tx = x + a.cos() * len;
    let ty = y + a.sin() * len;
    segs.extend_from_slice(&[x, y, tx, ty]);
    if n == 0 {
        return;
    }
    tree(segs, s, n - 1, tx, ty, a + s.bend - s.branch, len * s.ratio);
    tree(segs, s, n - 1, tx, ty, a + s.bend + s.branch, len * s.ratio);
    tree(segs, s, n - 1, tx, ty, a + s.bend, len * (1.0 - s.ratio));
}

/// tree_js's segments (from the level and the bend, branch and ratio parameters 0, 3–5).
fn tree_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let [level, _, _, bend, branch, ratio] = params_of(q);
    let shape = TreeShape {
        bend: bend.to_radians(),
        branch: branch.to_radians(),
        ratio,
    };
    let mut segs = Vec::new();
    tree(&mut segs, &shape, level as i64, 0.0, 0.0, PI / 2.0, 2.0);
    segs
}

fn prep_tree(v: &mut Prepared) {
    let [_, lines, lt, _, _, _, points, pt] = v.params();
    la_store(v, lines, lt, points, pt);
}

/// hilbert_js: points along a Hilbert curve of the given order (unit steps from the origin),
/// optionally thickened, or dots at the segment starts.
fn hilbert_js(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = la_eval(v, rng);
    [v.w * x, v.w * y, 0.0]
}

/// rsquares_js: points on the outlines of recursively nested squares (unit square centred at
/// (0.5, 0.5), four smaller copies on each square's corners).
fn rsquares_js(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = la_eval(v, rng);
    [v.w * x, v.w * y, 0.0]
}

/// tree_js: points on the branches of a recursive three-way tree growing up from the origin.
/// JWildfire adds the sampled point twice, so the output is twice the weighted point.
fn tree_js(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = la_eval(v, rng);
    [2.0 * (v.w * x), 2.0 * (v.w * y), 0.0]
}

const P_HILBERT: &[Param] = &[
    p_int("hilbert_js_level", 2.0, 1.0, 10.0),
    p("hilbert_js_show_lines", 1.0),
    p("hilbert_js_line_thickness", 0.5),
    p("hilbert_js_show_points", 0.0),
    p("hilbert_js_point_thickness", 3.0),
];

const P_RSQUARES: &[Param] = &[
    p_int("rsquares_js_level", 2.0, 1.0, 9.0),
    p("rsquares_js_show_lines", 1.0),
    p("rsquares_js_line_thickness", 0.5),
    p("rsquares_js_show_points", 0.0),
    p("rsquares_js_point_thickness", 3.0),
];

const P_TREE: &[Param] = &[
    p_int("tree_js_level", 2.0, 1.0, 10.0),
    p("tree_js_show_lines", 1.0),
    p("tree_js_line_thickness", 0.5),
    p("tree_js_bend_angle", 15.0),
    p("tree_js_branch_angle", 37.0),
    p("tree_js_branch_ratio", 0.65),
    p("tree_js_show_points", 0.0),
    p("tree_js_point_thickness", 3.0),
];

#[cfg(test)]
mod tests;
