//! JWildfire's tiling direct-colour stamps (Jesus Sosa's shader ports): `dc_truchet`
//! (Truchet tiles chosen by a sine hash), `dc_worley` (cellular noise from the three nearest
//! cell nodes), `dc_pentatiles` (a tiling by pentagons, tinted per tile, with borders) and
//! `dc_cairotiles` (the Cairo pentagonal tiling turning with time).
//!
//! Each scatters points over [−½, ½]² (or colours the input with `ColorOnly`) through
//! `jwf_direct_colour`'s common part. The formulas follow JWildfire's (Andreas Maschke and
//! contributors, LGPL-2.1) mathematics, written anew.

use std::f64::consts::PI;

use super::jwf_a_dc::rot;
use super::jwf_dc_maths::{glsl_random, length2, normalize2, step, truchet_tile};
use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail, gmod};
use super::util::{fract, signum_java, smoothstep};
use super::*;

const TRUCHET_TAIL: [Param; 5] = dc_tail!("dc_truchet");
const WORLEY_TAIL: [Param; 5] = dc_tail!("dc_worley");
const PENTA_TAIL: [Param; 5] = dc_tail!("dc_pentatiles");
const CAIRO_TAIL: [Param; 5] = dc_tail!("dc_cairotiles");

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("dc_truchet", dc_truchet)
        .params(&[
            p_int("dc_truchet_type", 0.0, 0.0, 2.0),
            p("dc_truchet_zoom", 10.0),
            TRUCHET_TAIL[0],
            TRUCHET_TAIL[1],
            TRUCHET_TAIL[2],
            TRUCHET_TAIL[3],
            TRUCHET_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_worley", dc_worley)
        .params(&[
            p_range("dc_worley_zoom", 7.0, 0.1, 50.0),
            p_range("dc_worley_pattern", 70.0, 0.1, 100.0),
            p_range("dc_worley_distort", 1.0, 0.0, 1.0),
            WORLEY_TAIL[0],
            WORLEY_TAIL[1],
            WORLEY_TAIL[2],
            WORLEY_TAIL[3],
            WORLEY_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_pentatiles", dc_pentatiles)
        .params(&[
            p_range("dc_pentatiles_zoom", 20.0, 1.0, 100.0),
            p_int("dc_pentatiles_border", 1.0, 0.0, 1.0),
            p_range("dc_pentatiles_width", 0.1, 0.01, 0.25),
            PENTA_TAIL[0],
            PENTA_TAIL[1],
            PENTA_TAIL[2],
            PENTA_TAIL[3],
            PENTA_TAIL[4],
        ])
        .flags(DC_FLAGS),
    VarDef::new("dc_cairotiles", dc_cairotiles)
        .params(&[
            p_range("dc_cairotiles_zoom", 7.0, 0.1, 50.0),
            p_int("dc_cairotiles_seed", 10000.0, 0.0, 10000.0),
            p("dc_cairotiles_time", 0.0),
            CAIRO_TAIL[0],
            CAIRO_TAIL[1],
            CAIRO_TAIL[2],
            CAIRO_TAIL[3],
            CAIRO_TAIL[4],
        ])
        .flags(DC_FLAGS),
];

/// dc_truchet: each cell of the zoomed plane a Truchet tile picked by the sine hash of its
/// corner, drawn as a soft diagonal (type 0), two rings (1) or a half (2).
fn dc_truchet(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [kind, zoom, tail @ ..] = v.params::<7>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let (sx, sy) = (x * zoom, y * zoom);
        let (ix, iy) = (sx.floor(), sy.floor());
        let (tx, ty) = truchet_tile(fract(sx), fract(sy), glsl_random(ix, iy));
        let c = match kind as i64 {
            0 => smoothstep(tx - 0.3, tx, ty) - smoothstep(tx, tx + 0.3, ty),
            1 => {
                let (l0, l1) = (length2(tx, ty), length2(tx - 1.0, ty - 1.0));
                (step(l0, 0.6) - step(l0, 0.4)) + (step(l1, 0.6) - step(l1, 0.4))
            }
            _ => step(tx, ty),
        };
        [c, c, c]
    })
}

/// dc_worley: Worley noise of the zoomed plane, from the squared distances to the nodes of
/// the 3 × 3 cells around (JWildfire's insertion keeps its slip: a new nearest moves the old
/// nearest into both the second and the third place), shaded from the three distances.
fn dc_worley(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, pattern, distort, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let (ux, uy) = (x * zoom, y * zoom);
        let node = |px: f64, py: f64| {
            let s = 1e4 * (px + py / (pattern * 0.01)).sin();
            let k = distort * 0.75;
            (fract(1.0 + s) * k + 0.3, fract(12.34 + s) * k + 0.3)
        };
        let mut o = [1e9; 3];
        for k in 0..9 {
            let px = ux.ceil() + (k - k / 3 * 3) as f64 - 2.0;
            let py = uy.ceil() + (k / 3) as f64 - 2.0;
            let (hx, hy) = node(px, py);
            let (cx, cy) = (hx + px - ux, hy + py - uy);
            let l = cx * cx + cy * cy;
            if l < o[0] {
                o[1] = o[0];
                o[2] = o[1];
                o[0] = l;
            } else if l < o[1] {
                o[2] = o[1];
                o[1] = l;
            } else if l < o[2] {
                o[2] = l;
            }
        }
        let o = o.map(|d| d.sqrt() * 5.0);
        let o = o.map(|d| d - o[0]);
        let s = 4.0 * (o[1] / (o[1] / o[2] + 1.0) - 0.5);
        o.map(|d| (d + s) - d)
    })
}

/// dc_pentatiles: the zoomed plane tiled by pentagons (eight to a supertile of side 2√3),
/// each tinted by cosines of its id, with soft borders of `width` when `border` is 1.
fn dc_pentatiles(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, border, width, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        penta_rgb(x * zoom, y * zoom, border, width)
    })
}

/// The pentagon tiling's colour at u (see [`dc_pentatiles`]).
fn penta_rgb(ux: f64, uy: f64, border: f64, width: f64) -> [f64; 3] {
    let sqrt3 = 3f64.sqrt();
    let h = (sqrt3 + 1.0) / 2.0;
    let c = sqrt3 - 1.0;
    let r = h + c / 2.0;
    // The line through the origin with normal (a, b) (signed distance), its soft stroke and
    // the region below it.
    let line = |x: f64, y: f64, a: f64, b: f64| {
        let (na, nb) = normalize2(a, b);
        x * na + y * nb
    };
    let stroke = |d: f64| smoothstep(width, 0.0, d.abs());
    let below = |x: f64, y: f64, a: f64, b: f64| step(line(x, y, a, b), 0.0);
    let (tx, ty) = (gmod(ux, r + r) - r, gmod(uy, r + r) - r);
    let (vx, vy) = (tx.abs(), ty.abs());
    let o_r = below(vx, vy - h, -(c / 2.0 - h), r);
    let o_g = below(vx - c / 2.0, vy, -sqrt3, 1.0);
    let mut sx = (ux / (r + r)).floor() * 2.0;
    let mut sy = (uy / (r + r)).floor() * 2.0;
    if o_r == 0.0 {
        sx += signum_java(tx);
        sy += signum_java(ty);
    }
    let i = (o_r + 2.0 * o_g + 4.0) + 8.0 * (sx + 12.0 * sy);
    let shade = 0.4 + 0.6 * fract(1234.0 * (43.0 * i).sin());
    let mut o = [0.0, 23.0, 21.0].map(|k: f64| ((k + i).cos() * 0.6 + 0.6) * shade);
    if border as i64 == 1 {
        let b = stroke(vx) * step(h, vy)
            + stroke(r - vx) * step(vy, c / 2.0)
            + stroke(line(vx, vy - h, -(c / 2.0 - h), r))
            + stroke(vy) * step(vx, c / 2.0)
            + stroke(r - vy) * step(r - vx, c / 2.0)
            + stroke(line(vx - c / 2.0, vy, -sqrt3, 1.0));
        o = o.map(|k| k * (1.0 - b));
    }
    o
}

/// dc_cairotiles: the Cairo tiling of the zoomed plane: squares of a grid breathing and
/// turning with time (half a cell shifted and inverted every other half turn), grey levels
/// of 0, 0.4 and 1 with gamma 1/2.2.
fn dc_cairotiles(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, _, time, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        let (mut px, mut py) = (x * zoom, y * zoom);
        let th = gmod(time * PI / 5.0, PI * 2.0);
        let grid = (0.5 + (th * 2.0).sin().abs() * (2f64.sqrt() / 2.0 - 0.5)) * 2.0;
        let flip = fract(th / PI + 0.25) > 0.5;
        if flip {
            px -= 0.5;
            py -= 0.5;
        }
        px *= grid;
        py *= grid;
        let (cx, cy) = ((px / grid).floor(), (py / grid).floor());
        px = gmod(px, grid) - grid / 2.0;
        py = gmod(py, grid) - grid / 2.0;
        px *= gmod(cx, 2.0) * 2.0 - 1.0;
        py *= gmod(cy, 2.0) * 2.0 - 1.0;
        (px, py) = rot(px, py, th);
        let w = zoom / 2000.0 * 1.5;
        let mut a = smoothstep(-w, w, px.abs().max(py.abs()) - 0.5);
        if flip {
            a = 1.0 - a;
        }
        let side = (px.abs() - py.abs()) * signum_java(fract(th / PI) - 0.5);
        if a < 0.5 && ((flip && side > 0.0) || (!flip && gmod(cx + cy, 2.0) - 0.5 > 0.0)) {
            a = 0.4;
        }
        [a.powf(1.0 / 2.2); 3]
    })
}
