//! JWildfire's `natural_foam`: the point pushed out of `density` random bubbles (drawn once
//! from `seed` with Java's generator) `iterations` times, then blurred by a random walk that
//! stays inside the bubbles, optionally drawn towards its inversion in the nearest bubble, and
//! coloured by the nearest bubble's size, by how many bubbles hold it, or by the nearest
//! bubble's index.
//!
//! The formula follows JWildfire's (LGPL-2.1) code, written anew. The walk draws from the same
//! Java generator as the bubbles, continuing from call to call, as JWildfire's does; so the
//! variation is stateful. Counts are limited (density 500, iterations 10, blur quality 10)
//! to keep one evaluation fast; JWildfire's are unbounded.

use super::jwf_a_cuts::JavaRandom;
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("natural_foam", natural_foam)
    .params(&[
        p_int("natural_foam_density", 50.0, 0.0, 500.0),
        p_int("natural_foam_iterations", 3.0, 0.0, 10.0),
        p("natural_foam_scale", 0.8),
        p("natural_foam_spread", 1.0),
        p("natural_foam_minRadius", 0.1),
        p("natural_foam_maxRadius", 0.9),
        p_int("natural_foam_seed", 123.0, -2147483648.0, 2147483647.0),
        p("natural_foam_shapeAmount", 0.0),
        p("natural_foam_blur_radius", 0.1),
        p_int("natural_foam_blur_quality", 1.0, 0.0, 10.0),
        p_int("natural_foam_color_data", 0.0, 0.0, 3.0),
        p("natural_foam_zoom", 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::STATEFUL | flag::USES_Z | flag::WRITES_Z | flag::SETS_COLOR)
    .prepare(foam_prepare)];

/// The state slot holding the Java generator's state (its 48 bits as a double's bits).
const ST_RANDOM: usize = 0;

/// The bubbles (x, y, z, radius each), and the generator's state after drawing them.
fn foam_prepare(v: &mut Prepared) {
    let [density, _, _, spread, min_r, max_r, seed] = v.params();
    let mut r = JavaRandom::new(seed as i64);
    for _ in 0..density.max(0.0) as usize {
        let x = (2.0 * r.next_f64() - 1.0) * spread;
        let y = (2.0 * r.next_f64() - 1.0) * spread;
        let z = (2.0 * r.next_f64() - 1.0) * spread;
        let radius = min_r + (max_r - min_r) * r.next_f64();
        v.p.extend_from_slice(&[x, y, z, radius]);
    }
    v.state.set(ST_RANDOM, f64::from_bits(r.0));
}

/// The squared distance from p to bubble b.
fn dist2(p: [f64; 3], b: &[f64]) -> f64 {
    let (dx, dy, dz) = (p[0] - b[0], p[1] - b[1], p[2] - b[2]);
    dx * dx + dy * dy + dz * dz
}

/// The index of the bubble nearest to p (the first of equals).
fn nearest(bubbles: &[f64], p: [f64; 3]) -> Option<usize> {
    let mut best = (None, f64::MAX);
    for (j, b) in bubbles.chunks_exact(4).enumerate() {
        let d = dist2(p, b);
        if d < best.1 {
            best = (Some(j), d);
        }
    }
    best.0
}

/// The random walk inside the bubbles: `quality` steps of up to radius/quality, each undone
/// when it leaves every bubble.
fn foam_blur(
    v: &Prepared,
    bubbles: &[f64],
    mut p: [f64; 3],
    radius: f64,
    quality: f64,
) -> [f64; 3] {
    let mut r = JavaRandom(v.state.get(ST_RANDOM).to_bits());
    let step = radius / quality;
    for _ in 0..quality as i32 {
        let prev = p;
        p = p.map(|c| c + (r.next_f64() - 0.5) * 2.0 * step);
        let inside = bubbles.chunks_exact(4).any(|b| dist2(p, b) < b[3] * b[3]);
        if !inside {
            p = prev;
        }
    }
    v.state.set(ST_RANDOM, f64::from_bits(r.0));
    p
}

/// natural_foam: the input pushed out of the bubbles, blurred, shaped and coloured.
fn natural_foam(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        density,
        iterations,
        scale,
        _,
        min_r,
        max_r,
        _,
        shape,
        blur,
        quality,
        cdata,
        zoom,
    ] = v.params();
    let bubbles = v.table(0);
    let mut p = [t.x, t.y, t.z];
    for _ in 0..iterations as i32 {
        for b in bubbles.chunks_exact(4) {
            let d2 = dist2(p, b);
            if d2 < b[3] * b[3] {
                let d = d2.sqrt();
                if d > 1e-6 {
                    let push = (b[3] - d) / d;
                    p = [0, 1, 2].map(|k| p[k] + (p[k] - b[k]) * push * scale);
                }
            }
        }
    }
    if blur > 0.0 && quality > 0.0 {
        p = foam_blur(v, bubbles, p, blur, quality);
    }
    if shape > 0.0
        && let Some(j) = nearest(bubbles, p)
    {
        let b = &bubbles[4 * j..4 * j + 4];
        let l = [p[0] - b[0], p[1] - b[1], p[2] - b[2]];
        let inv = b[3] * b[3] / (l[0] * l[0] + l[1] * l[1] + l[2] * l[2] + 1e-9);
        p = [0, 1, 2].map(|k| p[k] * (1.0 - shape) + (l[k] * inv + b[k]) * shape);
    }
    if cdata > 0.0 {
        let mut index = 0.5;
        if let Some(j) = nearest(bubbles, p) {
            match cdata as i32 {
                1 if max_r - min_r > 1e-6 => index = (bubbles[4 * j + 3] - min_r) / (max_r - min_r),
                2 if density > 0.0 => {
                    let n = bubbles
                        .chunks_exact(4)
                        .filter(|b| dist2(p, b) < b[3] * b[3])
                        .count();
                    index = n as f64 / density;
                }
                3 if density > 1.0 => index = j as f64 / (density - 1.0),
                _ => {}
            }
        }
        acc.color = index.clamp(0.0, 1.0);
    }
    p.map(|c| c * zoom * v.w)
}
