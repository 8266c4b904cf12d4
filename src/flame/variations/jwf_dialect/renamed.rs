//! Variations of Fractorium's catalogue whose JWildfire twin has parameters JWildfire names
//! or limits its own way: `pRose3D`'s `srvsc` (Fractorium's `crvsc`; the same formula),
//! `bubbleT3D`'s `exponent_z`, `symmetry_z` and `modus_blur` (Fractorium's `exponentZ`,
//! `symmetryZ`, `modusBlur`; JWildfire's hole squeeze), `eScale`'s scale and angle (any value;
//! Fractorium keeps the scale in [0, 1]), `truchet_fill`'s exponent and arc width (clamped
//! where Fractorium wraps them). A flame JWildfire wrote reads and writes them by
//! JWildfire's names.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use crate::flame::variations::fr_3d::{prose3d, prose3d_prep};
use crate::flame::variations::fr_truchet::{truchet_fill, truchet_fill_prep};
use crate::flame::variations::*;

const INF: f64 = f64::INFINITY;

pub(in crate::flame::variations) const DEFS: &[VarDef] = &[
    VarDef::new("truchet_fill", truchet_fill)
        .params(&[
            p("truchet_fill_exponent", 0.0),
            p("truchet_fill_arc_width", 0.0),
            p("truchet_fill_seed", 0.0),
        ])
        .prepare(truchet_fill_prep),
    VarDef::new("eScale", super::tablemath::e_scale)
        .params(&[p("eScale_scale", 1.0), p("eScale_angle", 0.0)]),
    VarDef::new("bubbleT3D", bubble_t3d)
        .params(&[
            // Each evaluation walks the stripes one by one.
            p_int("bubbleT3D_number_of_stripes", 0.0, -1000.0, 1000.0).limited(),
            p_range("bubbleT3D_ratio_of_stripes", 1.0, 0.0, 2.0),
            p_range("bubbleT3D_angle_of_hole", 0.0, -360.0, 360.0),
            p("bubbleT3D_exponent_z", 1.0),
            p_int("bubbleT3D_symmetry_z", 0.0, 0.0, 1.0),
            p_int("bubbleT3D_modus_blur", 0.0, 0.0, 1.0),
        ])
        .flags(flag::WRITES_Z)
        .prepare(prep_bubble_t3d),
    VarDef::new("pRose3D", prose3d)
        .params(&[
            p_nonzero("pRose3D_l", 1.0, -INF, INF),
            p("pRose3D_k", 3.0),
            p("pRose3D_c", 0.0),
            p("pRose3D_z1", 1.0),
            p("pRose3D_z2", 1.0),
            p("pRose3D_refSc", 1.0),
            p("pRose3D_opt", 1.0),
            p("pRose3D_optSc", 1.0),
            p("pRose3D_opt3", 0.0),
            p("pRose3D_transp", 0.5),
            p("pRose3D_dist", 1.0),
            p("pRose3D_wagsc", 0.0),
            p("pRose3D_srvsc", 0.0),
            p("pRose3D_f", 3.0),
            p("pRose3D_wigsc", 0.0),
            p("pRose3D_offset", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(flag::WRITES_Z)
        .prepare(prose3d_prep),
];

fn prep_bubble_t3d(v: &mut Prepared) {
    let [stripes, ratio, hole, _, sym, _] = v.params();
    let n = stripes.abs();
    let inv_stripes = if stripes < 0.0 { 1.0 } else { 0.0 };
    let (mut strip, mut strip1, mut strip2) = (0.0, 0.0, 0.0);
    let mut ratio = ratio;
    if n != 0.0 {
        strip = PI / n;
        strip2 = 2.0 * strip;
        ratio = ratio.clamp(0.01, 1.99);
        strip1 = ratio * strip;
    }
    let mut hole = hole;
    if sym == 1.0 {
        hole = hole.abs().min(179.9);
    }
    let (inv_hole, hole) = if hole < 0.0 {
        (1.0, (hole.abs() / 360.0 * TAU) / 2.0)
    } else {
        (0.0, PI - (hole / 360.0 * TAU) / 2.0)
    };
    let (s, c) = strip.sin_cos();
    v.p.extend_from_slice(&[
        n,
        inv_stripes,
        strip1,
        strip2,
        s,
        c,
        hole,
        inv_hole,
        PI - hole,
        ratio,
    ]);
}

/// FractalDesire's bubbleT3D as JWildfire computes it: the bubble lifted onto a sphere, with
/// stripes cut out of it (or, in blur mode, turned onto their neighbours) and a hole at the
/// pole (or both poles with z-symmetry), which blur mode squeezes the cap into.
fn bubble_t3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, exp_z, sym_z, blur] = v.params();
    let [
        n,
        inv_stripes,
        strip1,
        strip2,
        s,
        c,
        hole,
        inv_hole,
        comp,
        ratio,
    ] = v.derived();
    let (mut x, mut y) = (t.x, t.y);
    let rad = (x * x + y * y) / 4.0 + 1.0;
    let blur = blur != 0.0;
    if n != 0.0 {
        let mut ang = x.atan2(y);
        if ang < 0.0 {
            ang += TAU;
        }
        while ang > strip2 {
            ang -= strip2;
        }
        let cut = if inv_stripes == 0.0 {
            ang > strip1
        } else {
            ang < strip1
        };
        if cut && !blur {
            (x, y) = (0.0, 0.0);
        } else if cut {
            let (s, c) = if ratio == 1.0 {
                (s, c)
            } else if inv_stripes == 0.0 {
                (ang - (ang - strip1) / (strip2 - strip1) * strip1).sin_cos()
            } else {
                (ang - (ang - strip1) / strip1 * (strip2 - strip1)).sin_cos()
            };
            (x, y) = (c * x - s * y, s * x + c * y);
        }
    }
    x /= rad;
    y /= rad;
    let (mut z, ang_z) = if x != 0.0 || y != 0.0 {
        let z = 2.0 / rad.powf(exp_z) - 1.0;
        let a = if exp_z <= 2.0 {
            PI - (z / (x * x + y * y + z * z)).acos()
        } else {
            PI - ((x * x + y * y) * (x * x + y * y)).atan2(z)
        };
        (z, a)
    } else {
        (0.0, 0.0)
    };
    let squeeze = blur && exp_z == 1.0;
    // The angle the cap is squeezed to, for points in the hole.
    let bent = if sym_z == 0.0 {
        if inv_hole == 0.0 && ang_z > hole {
            Some((PI - ang_z) / comp * hole - FRAC_PI_2)
        } else if inv_hole != 0.0 && ang_z < hole {
            Some(PI - ang_z / comp * hole - FRAC_PI_2)
        } else {
            None
        }
    } else if ang_z > hole || ang_z < PI - hole {
        Some(if ang_z > hole {
            (PI - ang_z) / comp * (PI - 2.0 * comp) + comp - FRAC_PI_2
        } else {
            FRAC_PI_2 - (ang_z / comp * (PI - 2.0 * comp) + comp)
        })
    } else {
        None
    };
    if let Some(a) = bent {
        if squeeze {
            let b = ang_z - FRAC_PI_2;
            let fac = a.cos() / b.cos();
            x *= fac;
            y *= fac;
            z *= a.sin() / b.sin();
        } else {
            (x, y, z) = (0.0, 0.0, 0.0);
        }
    }
    [v.w * x, v.w * y, v.w * z]
}
