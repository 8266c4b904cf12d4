//! Andreas Maschke's `metaballs3d_wf`: `mb_count` metaballs (some negative) placed in a box
//! from the seed `mb_seed` — uniformly, bunched towards the top, or in a ball — and each call
//! tries up to `max_iter` uniform points of the box, keeping the first where the field
//! Σ ±r²/d² exceeds `mb_sharpness` (the point is hidden when none does); coloured by its place
//! in the box.
//!
//! The formula follows JWildfire 9.00 (`Metaballs3DWFFunc`, LGPL-2.1), written anew; the balls
//! come from JWildfire's Marsaglia generator as there. The colour-map modes (0–2) need an image
//! file, which this variation never has: they leave the colour as it was (clamped to [0, 1]).

use std::f64::consts::PI;

use super::util::Mwc;
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("metaballs3d_wf", metaballs3d_wf)
    .params(&[
        p_int("metaballs3d_wf_mb_mode", 0.0, 0.0, 2.0),
        // At most 128 balls, each evaluated for every try (with at most 256 tries a call
        // costs at most 32,768 ball tests).
        p_int("metaballs3d_wf_mb_count", 64.0, 0.0, 128.0).limited(),
        p("metaballs3d_wf_mb_min_radius", 0.35),
        p("metaballs3d_wf_mb_max_radius", 0.75),
        p("metaballs3d_wf_mb_negative", 0.3),
        p_int(
            "metaballs3d_wf_mb_seed",
            699230.0,
            -2147483648.0,
            2147483647.0,
        ),
        p("metaballs3d_wf_mb_sharpness", 2.75),
        p("metaballs3d_wf_border_size", 0.42),
        p("metaballs3d_wf_xmin", -PI),
        p("metaballs3d_wf_xmax", PI),
        p("metaballs3d_wf_ymin", -PI),
        p("metaballs3d_wf_ymax", PI),
        p("metaballs3d_wf_zmin", -PI),
        p("metaballs3d_wf_zmax", PI),
        // At most 256 tries per call.
        p_int("metaballs3d_wf_max_iter", 160.0, 1.0, 256.0).limited(),
        p_int(
            "metaballs3d_wf_direct_color",
            1.0,
            -2147483648.0,
            2147483647.0,
        ),
        p_int(
            "metaballs3d_wf_color_mode",
            9.0,
            -2147483648.0,
            2147483647.0,
        ),
        p_int("metaballs3d_wf_blend_colormap", 1.0, 0.0, 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR | flag::HIDES | flag::WRITES_Z)
    .prepare(metaballs_prepare)];

/// The box's sides in order (low, high).
fn sorted(a: f64, b: f64) -> (f64, f64) {
    if a > b { (b, a) } else { (a, b) }
}

/// JWildfire's falloff 1/(x + 0.63) − 0.6, from about 0.99 at 0 to 0.01 at 1.
fn falloff(x: f64) -> f64 {
    1.0 / (x + 0.63) - 0.60
}

/// Derived values: the box (xmin, dx, ymin, dy, zmin, dz), then the balls (x, y, z, signed
/// radius).
fn metaballs_prepare(v: &mut Prepared) {
    let q: [f64; 18] = v.params();
    let [mode, count, rmin, rmax, negative, seed, _, border] =
        [q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]];
    let (x0, x1) = sorted(q[8], q[9]);
    let (y0, y1) = sorted(q[10], q[11]);
    let (z0, z1) = sorted(q[12], q[13]);
    v.p.extend_from_slice(&[x0, x1 - x0, y0, y1 - y0, z0, z1 - z0]);
    let (lo, hi) = (rmin.abs().min(rmax.abs()), rmin.abs().max(rmax.abs()));
    let dr = hi - lo;
    let (bx0, bx1) = (x0 + border, x1 - border);
    let (by0, by1) = (y0 + border, y1 - border);
    let (bz0, bz1) = (z0 + border, z1 - border);
    let (bdx, bdy, bdz) = (bx1 - bx0, by1 - by0, bz1 - bz0);
    let mut g = Mwc::new(seed as i64);
    for _ in 0..count.max(0.0) as usize {
        let (mut r, x, y, z) = match mode as i64 {
            1 => {
                let r = lo + dr * falloff(g.next_f64()) * 1.42;
                let x = bx0 + bdx * g.next_f64();
                let y = by1 - bdy * falloff(g.next_f64());
                (r, x, y, bz0 + bdz * g.next_f64())
            }
            2 => {
                let r = lo + dr * falloff(g.next_f64());
                // JWildfire takes the unbordered height here.
                let radius = falloff(g.next_f64()) * bdx.min(y1 - y0).min(bdz) * 0.85;
                let (sa, ca) = (g.next_f64() * 2.0 * PI).sin_cos();
                let (sb, cb) = (g.next_f64() * PI).sin_cos();
                (
                    r,
                    bx0 + bdx * 0.5 + radius * sb * ca,
                    by0 + bdy * 0.5 + radius * sb * sa,
                    bz0 + bdz * 0.5 + radius * cb,
                )
            }
            _ => {
                let r = lo + dr * g.next_f64();
                let x = bx0 + bdx * g.next_f64();
                let y = by0 + bdy * g.next_f64();
                (r, x, y, bz0 + bdz * g.next_f64())
            }
        };
        if g.next_f64() < negative {
            r = -r;
        }
        v.p.extend_from_slice(&[x, y, z, r]);
    }
}

/// metaballs3d_wf: the first of up to `max_iter` random points of the box inside the blobs,
/// hidden when none is.
fn metaballs3d_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 18] = v.params();
    let [x0, dx, y0, dy, z0, dz] = v.derived();
    let balls = v.table(6);
    let (sharpness, tries, direct, mode) = (q[6], q[14], q[15], q[16]);
    acc.hide = true;
    let (mut x, mut y, mut z) = (0.0, 0.0, 0.0);
    for _ in 0..tries.max(1.0) as usize {
        x = x0 + rng.f01() * dx;
        y = y0 + rng.f01() * dy;
        z = z0 + rng.f01() * dz;
        let field: f64 = balls
            .chunks_exact(4)
            .map(|b| {
                let d2 = (x - b[0]).powi(2) + (y - b[1]).powi(2) + (z - b[2]).powi(2);
                b[3] * b[3] / d2 * if b[3] < 0.0 { -1.0 } else { 1.0 }
            })
            .sum();
        if field > sharpness {
            acc.hide = false;
            break;
        }
    }
    if acc.hide {
        return [0.0; 3];
    }
    if direct > 0.0 {
        let (u, w, s) = ((x - x0) / dx, (y - y0) / dy, (z - z0) / dz);
        let c = match mode as i64 {
            0..=2 => acc.color,
            3 => u,
            4 => w,
            5 => s,
            6 => u * w,
            7 => w * s,
            8 => s * u,
            _ => u * w * s,
        };
        acc.color = c.clamp(0.0, 1.0);
    }
    [v.w * x, v.w * y, v.w * z]
}
