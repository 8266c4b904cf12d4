//! GLSL's small functions as the shader ports of JWildfire's `dc_*` stamps compute them
//! (its `js.glsl.G` helpers): `step`, the "random" sine hash with its own constant, a
//! normalised 2-vector and the Truchet tile flip. GLSL's `mod` is `jwf_direct_colour::gmod`,
//! `fract`, `smoothstep` and `mix` are in `util`.

use super::util::fract;

/// GLSL's step: 0 below the edge, else 1.
#[inline(always)]
pub(super) fn step(edge: f64, x: f64) -> f64 {
    if x < edge { 0.0 } else { 1.0 }
}

/// The shaders' `random(st)`: fract(sin(st·(12.9898, 78.233))·43758.5453123).
#[inline(always)]
pub(super) fn glsl_random(x: f64, y: f64) -> f64 {
    fract((x * 12.9898 + y * 78.233).sin() * 43758.5453123)
}

/// (a, b)/|(a, b)|.
#[inline(always)]
pub(super) fn normalize2(a: f64, b: f64) -> (f64, f64) {
    let l = (a * a + b * b).sqrt();
    (a / l, b / l)
}

/// |(x, y)|.
#[inline(always)]
pub(super) fn length2(x: f64, y: f64) -> f64 {
    (x * x + y * y).sqrt()
}

/// The Truchet tile of the shaders: the unit-square point (x, y) flipped by the quarter
/// fract(2·(index − ½)) falls in (both axes, x, y or none).
pub(super) fn truchet_tile(x: f64, y: f64, index: f64) -> (f64, f64) {
    let index = fract((index - 0.5) * 2.0);
    if index > 0.75 {
        (1.0 - x, 1.0 - y)
    } else if index > 0.5 {
        (1.0 - x, y)
    } else if index > 0.25 {
        (1.0 - (1.0 - x), 1.0 - y)
    } else {
        (x, y)
    }
}

/// A row vector times a 3 × 3 matrix given as the shaders' `mat3(a00, a10, a20, a01, a11,
/// a21, a02, a12, a22)` (column by column): every product summed, as the shaders do.
pub(super) fn row_times_mat3(v: [f64; 3], m: [f64; 9]) -> [f64; 3] {
    [0, 1, 2].map(|c| v[0] * m[3 * c] + v[1] * m[3 * c + 1] + v[2] * m[3 * c + 2])
}

/// GLSL's mix(x, y, a) = x·(1 − a) + y·a.
#[inline(always)]
pub(super) fn mix3(x: [f64; 3], y: [f64; 3], a: f64) -> [f64; 3] {
    [0, 1, 2].map(|k| x[k] * (1.0 - a) + y[k] * a)
}
