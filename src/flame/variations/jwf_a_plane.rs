//! JWildfire's maps of the plane by formula: `flower_db`, `atan2_spirals`, Minkowski's
//! question-mark function `minkQM`, the cell shuffle `scrambly` and the colour-to-z map
//! `colorscale_wf`, the random mirrors `combimirror` and the torus-bulb crop of the sum so far
//! `post_bulbtorus_crop`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: weights multiply the output linearly,
//! integer parameters are rounded, and random numbers are drawn in the order JWildfire draws
//! them.

use std::f64::consts::PI;

use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("flower_db", flower_db)
        .params(&[
            p("flower_db_petals", 6.0),
            p("flower_db_petal_split", 0.0),
            p("flower_db_petal_spread", 1.0),
            p("flower_db_stem_thickness", 1.0),
            p("flower_db_stem_length", 0.0),
            p("flower_db_petal_fold_strength", 0.0),
            p("flower_db_petal_fold_radius", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_Z | flag::READS_ACC | flag::WRITES_ACC),
    VarDef::new("atan2_spirals", atan2_spirals)
        .params(&[
            p("atan2_spirals_r_mult", 1.5),
            p("atan2_spirals_r_add", 1.0),
            p("atan2_spirals_xy2_mult", 1.125),
            p("atan2_spirals_xy2_add", 0.132),
            p("atan2_spirals_x_mult", 2.0),
            p("atan2_spirals_x_add", 0.25),
            p("atan2_spirals_yx_div", 1.0),
            p("atan2_spirals_yx_add", 0.0),
            p("atan2_spirals_yy_div", 1.25),
            p("atan2_spirals_yy_add", 0.0),
            p("atan2_spirals_sin_add", 0.0),
            p("atan2_spirals_y_mult", 1.0),
            p("atan2_spirals_r_power", 0.5),
            p("atan2_spirals_x2y2_power", 1.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("minkQM", mink_qm)
        .params(&[
            p("minkQM_a", 1.0),
            p("minkQM_b", 1.0),
            p("minkQM_c", 1.0),
            p("minkQM_dd", 1.0),
            p("minkQM_e", 0.5),
            p_int("minkQM_f", 20.0, 1.0, 50.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("scrambly", scrambly)
        .params(&[
            p_int("scrambly_l", 3.0, NEG_INF, INF),
            p_int("scrambly_seed", 51.0, NEG_INF, INF),
            p_int("scrambly_byrows", 0.0, NEG_INF, INF),
            p_range("scrambly_cellsize", 0.1, 1e-20, 1e20),
        ])
        .flags(flag::JWILDFIRE)
        .prepare(scrambly_prepare),
    VarDef::new("colorscale_wf", colorscale_wf)
        .params(&[
            p("colorscale_wf_scale_x", 0.0),
            p("colorscale_wf_scale_y", 0.0),
            p("colorscale_wf_scale_z", 0.5),
            p("colorscale_wf_offset_z", 0.0),
            p("colorscale_wf_reset_z", 0.0),
            p("colorscale_wf_sides", 0.0),
        ])
        .flags(
            flag::JWILDFIRE | flag::WRITES_Z | flag::USES_COLOR | flag::RANDOM | flag::WRITES_ACC,
        ),
    VarDef::new("combimirror", combimirror)
        .params(&[
            p("combimirror_vmirror", 1.0),
            p("combimirror_vmove", 0.05),
            p("combimirror_hmirror", 0.5),
            p("combimirror_hmove", 0.35),
            p("combimirror_zmirror", 0.0),
            p("combimirror_zmove", 0.0),
            p("combimirror_pmirror", 0.0),
            p("combimirror_pmovex", 0.05),
            p("combimirror_pmovey", 0.0),
            p("combimirror_vcolorshift", 0.0),
            p("combimirror_hcolorshift", 0.0),
            p("combimirror_zcolorshift", 0.0),
            p("combimirror_pcolorshift", 0.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::USES_Z
                | flag::WRITES_Z
                | flag::SETS_COLOR
                | flag::USES_COLOR
                | flag::WRITES_ACC,
        ),
    VarDef::new("post_bulbtorus_crop", post_bulbtorus_crop)
        .params(&[
            p("post_bulbtorus_crop_power1", 9.0),
            p("post_bulbtorus_crop_power2", 9.0),
            p_int("post_bulbtorus_crop_iterations", 12.0, 0.0, 250.0),
            p("post_bulbtorus_crop_bailout", 16.0),
            p("post_bulbtorus_crop_scaleX", 1.0),
            p("post_bulbtorus_crop_scaleY", 1.0),
            p("post_bulbtorus_crop_ScaleZ", 1.0),
            p("post_bulbtorus_crop_color", 1.0),
        ])
        .flags(
            flag::JWILDFIRE
                | flag::WRITES_Z
                | flag::SETS_COLOR
                | flag::READS_ACC
                | flag::WRITES_ACC,
        ),
];

/// The xform's sum so far, taken out of `acc` (so that a formula that rewrites it returns the
/// new sum), for a regular variation; the origin for the pre_/post_ forms.
fn take_sum(v: &Prepared, acc: &mut Acc) -> V3 {
    if v.form == Form::Regular {
        let s = [acc.x, acc.y, acc.z];
        acc.x = 0.0;
        acc.y = 0.0;
        acc.z = 0.0;
        s
    } else {
        [0.0; 3]
    }
}

/// flower_db: petals r·|(spread + sin(petals·θ))·cos(split·petals·θ)| (x and y swapped), a
/// stem going down in z as 1/r, petals folded in z beyond `petal_fold_radius` of the summed
/// point, the stem cut at `stem_length`.
fn flower_db(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        petals,
        split,
        spread,
        stem_thickness,
        stem_length,
        fold_strength,
        fold_radius,
    ] = v.params();
    let [mut x, mut y, mut z] = take_sum(v, acc);
    let th = t.y.atan2(t.x);
    let r = v.w * (t.x * t.x + t.y * t.y).sqrt();
    let r = r * ((spread + (petals * th).sin()) * (split * petals * th).cos()).abs();
    x += th.sin() * r;
    y += th.cos() * r;
    z -= stem_thickness * ((2.0 / r) - 1.0);
    let rnew = (x * x + y * y).sqrt();
    if rnew > fold_radius {
        z += (rnew - fold_radius) * fold_strength;
    }
    if stem_length != 0.0 && z <= -stem_length {
        z = -stem_length;
    }
    [x, y, z]
}

/// atan2_spirals (Whittaker Courtney): x from the angle between powers of the radius, y from
/// the sine of the point's (scaled, shifted) angle.
fn atan2_spirals(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        r_mult,
        r_add,
        xy2_mult,
        xy2_add,
        x_mult,
        x_add,
        yx_div,
        yx_add,
        yy_div,
        yy_add,
        sin_add,
        y_mult,
        r_power,
        x2y2_power,
    ] = v.params();
    let (x, y) = (t.x, t.y);
    let s = x * x + y * y;
    let xy2 = s.powf(x2y2_power);
    let r = s.powf(r_power);
    let fx = x_mult * (r * r_mult + r_add).atan2(xy2 * xy2_mult + xy2_add) + x_add;
    let fy = ((y / yy_div + yy_add).atan2(x / yx_div + yx_add) + sin_add).sin() * y_mult;
    let ox = if x >= 0.0 { -fx + PI } else { fx - PI };
    [v.w * ox, v.w * fy, 0.0]
}

/// Minkowski's question-mark function on (0, 1) by `f` steps of the Stern–Brocot descent,
/// with JWildfire's free starting fractions (a, b, c) and step sizes (dd, e).
fn minkowski(x: f64, [a, b, c, dd, e, f]: [f64; 6]) -> f64 {
    let mut p = 0.0;
    let (mut q, mut r, mut s) = (a, p + b, c);
    let (mut d, mut y) = (dd, p);
    let mut it = 0.0;
    while it < f {
        d *= e;
        let m = p + r;
        let n = q + s;
        if x < m / n {
            r = m;
            s = n;
        } else {
            y += d;
            p = m;
            q = n;
        }
        it += 1.0;
    }
    y + d
}

/// minkQM: Minkowski's question-mark function of |x| and |y| where they lie in (0, 1), signs
/// kept; other values pass through.
fn mink_qm(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let q: [f64; 6] = v.params();
    let m = |c: f64| {
        let a = c.abs();
        let r = if a > 0.0 && a < 1.0 {
            minkowski(a, q)
        } else {
            a
        };
        if c < 0.0 { -r } else { r }
    };
    [v.w * m(t.x), v.w * m(t.y), 0.0]
}

/// The largest grid scrambly shuffles (25 × 25 cells).
const SCRAMBLY_MAX_L: i32 = 25;

/// Swaps each cell of `mx[lo..hi]` with a later one chosen by a byte-flipped linear
/// congruential sequence perturbed by `seed` (scrambly's shuffle; Java's 32-bit arithmetic).
fn scrambly_shuffle(mx: &mut [i32], lo: usize, hi: usize, seed: i32) {
    let mut prn: i32 = 1;
    let mut j = lo;
    loop {
        prn = prn.wrapping_mul(1103515245).wrapping_add(12345);
        prn = (prn & (0xFFFF_0000_u32 as i32)) | ((prn << 8) & 0xFF00) | ((prn >> 8) & 0x00FF);
        prn = if prn & 4 != 0 {
            prn.wrapping_sub(seed)
        } else {
            prn ^ seed
        };
        if prn < 0 {
            prn = prn.wrapping_neg();
        }
        let mut ridx = 1 + j;
        if hi > ridx {
            ridx += (prn % (hi - ridx) as i32) as usize;
        } else {
            break;
        }
        mx.swap(ridx, j);
        j += 1;
    }
}

/// scrambly's derived values: [L, cell, 1/cell, cellsize/2, then the L² cell permutation].
fn scrambly_prepare(v: &mut Prepared) {
    let [l, seed, byrows, cellsize] = v.params();
    let (l, seed, byrows) = (l as i32, seed as i32, byrows as i32);
    let ll = l.saturating_abs().clamp(3, SCRAMBLY_MAX_L);
    let ll2 = (ll * ll) as usize;
    let mut mx: Vec<i32> = (0..ll2 as i32).collect();
    if (0..=50).contains(&seed) {
        for (j, m) in mx.iter_mut().enumerate() {
            *m = (seed + j as i32 + 1) % ll2 as i32;
        }
    } else if byrows == 0 {
        scrambly_shuffle(&mut mx, 0, ll2, seed);
    } else {
        let n = ll as usize;
        for j in 0..n {
            scrambly_shuffle(&mut mx, n * j, n * (j + 1), seed.wrapping_add(j as i32));
        }
    }
    let cella = cellsize / ll as f64;
    v.p.extend_from_slice(&[ll as f64, cella, 1.0 / cella, 0.5 * cellsize]);
    v.p.extend(mx.iter().map(|&m| m as f64));
}

/// scrambly: cuts a square of side `cellsize` around the origin into an L × L grid and moves
/// its cells to shuffled places (a cyclic shift for seeds 0–50); points outside stay.
fn scrambly(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [l, cella, cellainv, mz] = v.derived();
    let mx = v.table(4);
    let vx = (t.x + mz) * cellainv;
    let vy = (t.y + mz) * cellainv;
    let ix = vx.floor() as i32;
    let iy = vy.floor() as i32;
    let li = l as i32;
    if ix < 0 || ix >= li || iy < 0 || iy >= li {
        return [v.w * t.x, v.w * t.y, 0.0];
    }
    let swp = mx[(ix + li * iy) as usize] as i32;
    let (ny, nx) = (swp / li, swp % li);
    let ox = (vx - ix as f64 + nx as f64) * cella - mz;
    let oy = (vy - iy as f64 + ny as f64) * cella - mz;
    [v.w * ox, v.w * oy, 0.0]
}

/// colorscale_wf: scales x and y, and sets z from the colour (colour·scale_z·weight +
/// offset_z), replacing the sum's z (`reset_z`), or adding it, times a uniform draw (`sides`).
fn colorscale_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [scale_x, scale_y, scale_z, offset_z, reset_z, sides] = v.params();
    let dz = t.color * scale_z * v.w + offset_z;
    let z = if reset_z > 0.0 {
        if v.form == Form::Regular {
            acc.z = 0.0;
        }
        dz
    } else if sides > 0.0 {
        dz * rng.f01()
    } else {
        dz
    };
    if v.form == Form::Post {
        // JWildfire's post_colorscale_wf scales the point it is given in place.
        let z = if reset_z > 0.0 { z } else { t.z + z };
        return [t.x + v.w * scale_x * t.x, t.y + v.w * scale_y * t.y, z];
    }
    [v.w * scale_x * t.x, v.w * scale_y * t.y, z]
}

/// combimirror: the point (x, y, z) scaled by the weight (z taken from (z, y)), then mirrored
/// about the centre (odds 1 − pmirror/2), the vertical, horizontal and z axes (odds
/// vmirror/2, hmirror/2, zmirror/2, one draw each), each mirror moving it and shifting the
/// colour; replaces the xform's sum so far.
fn combimirror(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        vmirror,
        vmove,
        hmirror,
        hmove,
        zmirror,
        zmove,
        pmirror,
        pmovex,
        pmovey,
        vshift,
        hshift,
        zshift,
        pshift,
    ] = v.params();
    take_sum(v, acc);
    let (mut x, mut y, mut z) = (t.x * v.w, t.y * v.w, t.z * v.w);
    let mut c = acc.color;
    if rng.f01() > pmirror / 2.0 {
        x = -x + pmovex;
        y = -y + pmovey;
        c = (c + pshift) % 1.0;
    }
    if rng.f01() < vmirror / 2.0 {
        x = -x + vmove;
        c = (c + vshift) % 1.0;
    }
    if rng.f01() < hmirror / 2.0 {
        y = -y + hmove;
        c = (c + hshift) % 1.0;
    }
    if rng.f01() < zmirror / 2.0 {
        z = -z + zmove;
        c = (c + zshift) % 1.0;
    }
    acc.color = c;
    [x, y, z]
}

/// post_bulbtorus_crop (Jesus Sosa): iterates a "torus bulb" (a Mandelbulb-like power map
/// about a ring of radius 1.5) on the xform's sum so far (scaled per axis); at every step
/// the sum is multiplied by the weight and the colour set to sin r·color while the orbit
/// stays within `bailout`, and the sum is zeroed once it does not.
fn post_bulbtorus_crop(v: &Prepared, _t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [power1, power2, iterations, bailout, sx, sy, sz, pcolor] = v.params();
    let [mut ox, mut oy, mut oz] = take_sum(v, acc);
    let (x1, y1, z1) = (ox * sx, oy * sy, oz * sz);
    let (mut x, mut y, mut z) = (x1, y1, z1);
    for _ in 0..iterations as i32 {
        let rh = (x * x + y * y).sqrt();
        let phi = y.atan2(x);
        let phipow = phi * power1;
        let theta = rh.atan2(z);
        let px = x - phi.cos() * 1.5;
        let py = y - phi.sin() * 1.5;
        let rhrad = (px * px + py * py + z * z).sqrt();
        let rh1 = rhrad.powf(power2);
        let rh2 = rhrad.powf(power1);
        let thetapow = theta * power2;
        let st = thetapow.sin() * rh2;
        x = st * phipow.cos() + x1;
        y = st * phipow.sin() + y1;
        z = thetapow.cos() * rh1 + z1;
        let r = (x * x + y * y + z * z).sqrt();
        if r < bailout {
            ox *= v.w;
            oy *= v.w;
            oz *= v.w;
            acc.color = r.sin() * pcolor;
        } else {
            (ox, oy, oz) = (0.0, 0.0, 0.0);
        }
    }
    [ox, oy, oz]
}
