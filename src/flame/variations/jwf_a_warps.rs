//! JWildfire's warps of the plane: bubbles in a grid (`bwraps7`, and Xyrus02's `bwraps2`,
//! which JWildfire has as `pre_bwraps2` and `post_bwraps2` only), rings and waves (`rings3`,
//! `waves3_wf`), the grid shifts `gridout2` and `lazysensen`, polar rewrites (`pTransform`,
//! `spligon`, `c_symmetry`, `disc3`, `anamorphcyl`), `corners`, `tunnel`, `invsquircular`,
//! Clifford's attractor map `clifford_js` and the conic cut `chunk`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: `atan_xy` is its `getPrecalcAtan`
//! (atan2(x, y)), its `getPrecalcSqrt` adds 1e-300, weights multiply the output linearly, and
//! integer parameters are rounded.

use std::f64::consts::{PI, SQRT_2, TAU};

use super::*;

/// corners' default log base, e to 6 digits as JWildfire has it.
#[allow(clippy::approx_constant)]
const CORNERS_E: f64 = 2.71828;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("bwraps7", bwraps7)
        .params(&[
            p("bwraps7_cellsize", 1.0),
            p("bwraps7_space", 0.0),
            p("bwraps7_gain", 2.0),
            p("bwraps7_inner_twist", 0.0),
            p("bwraps7_outer_twist", 0.0),
        ])
        .flags(flag::JWILDFIRE)
        .prepare(bwraps7_prepare),
    VarDef::new("bwraps2", bwraps2)
        .params(&[
            p("bwraps2_cellsize", 1.0),
            p("bwraps2_space", 0.0),
            p("bwraps2_gain", 2.0),
            p("bwraps2_inner_twist", 0.0),
            p("bwraps2_outer_twist", 0.0),
        ])
        .flags(flag::JWILDFIRE)
        .prepare(bwraps2_prepare),
    VarDef::new("rings3", rings3)
        .params(&[p("rings3_val", 0.01), p("rings3_n", 0.0)])
        .flags(flag::JWILDFIRE),
    VarDef::new("waves3_wf", waves3_wf)
        .params(&[
            p("waves3_wf_scalex", 0.25),
            p("waves3_wf_scaley", 0.5),
            p("waves3_wf_freqx", PI / 2.0),
            p("waves3_wf_freqy", PI / 4.0),
            p_int("waves3_wf_use_cos_x", 1.0, NEG_INF, INF),
            p_int("waves3_wf_use_cos_y", 0.0, NEG_INF, INF),
            p("waves3_wf_dampx", 0.0),
            p("waves3_wf_dampy", 0.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("invsquircular", invsquircular).flags(flag::JWILDFIRE),
    VarDef::new("c_symmetry", c_symmetry)
        .params(&[p("c_symmetry_p1", 3.0), p("c_symmetry_p2", 3.0)])
        .flags(flag::JWILDFIRE | flag::WRITES_ACC),
    VarDef::new("tunnel", tunnel)
        .params(&[p("tunnel_Sx", 200.0), p("tunnel_Sy", 50.0)])
        .flags(flag::JWILDFIRE | flag::READS_ACC | flag::WRITES_ACC),
    VarDef::new("corners", corners)
        .params(&[
            p("corners_x", 1.0),
            p("corners_y", 1.0),
            p("corners_mult_x", 1.0),
            p("corners_mult_y", 1.0),
            p("corners_x_power", 0.75),
            p("corners_y_power", 0.75),
            p("corners_xy_power_add", 0.0),
            p("corners_log_mode", 0.0),
            p("corners_log_base", CORNERS_E),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("disc3", disc3)
        .params(&[
            p("disc3_a", 1.0),
            p("disc3_b", 1.0),
            p("disc3_c", 1.0),
            p("disc3_d", 1.0),
            p("disc3_e", 1.0),
            p("disc3_f", 1.0),
            p("disc3_g", 1.0),
            p("disc3_h", 1.0),
        ])
        .needs(need::ATAN_XY)
        .flags(flag::JWILDFIRE),
    VarDef::new("lazysensen", lazysensen)
        .params(&[
            p("lazysensen_scale_x", 1.0),
            p("lazysensen_scale_y", 1.0),
            p("lazysensen_scale_z", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("pTransform", ptransform)
        .params(&[
            p("pTransform_rotate", 0.3),
            p_int("pTransform_power", 2.0, 1.0, 2147483647.0),
            p("pTransform_move", 0.4),
            p("pTransform_split", 0.0),
            p_int("pTransform_use_log", 1.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("spligon", spligon)
        .params(&[
            p("spligon_sides", 3.0),
            p("spligon_r", 1.0),
            p("spligon_i", 1.0),
        ])
        .flags(flag::JWILDFIRE)
        .prepare(spligon_prepare),
    VarDef::new("anamorphcyl", anamorphcyl)
        .params(&[
            p("anamorphcyl_a", 1.0),
            p("anamorphcyl_b", 1.3),
            p("anamorphcyl_k", 3.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_ACC),
    VarDef::new("clifford_js", clifford_js)
        .params(&[
            p("clifford_js_a", -1.4),
            p("clifford_js_b", 1.6),
            p("clifford_js_c", 1.0),
            p("clifford_js_d", 0.7),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("gridout2", gridout2)
        .params(&[
            p("gridout2_a", 1.0),
            p("gridout2_b", 1.0),
            p("gridout2_c", 1.0),
            p("gridout2_d", 1.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("chunk", chunk)
        .params(&[
            p("chunk_a", 1.0),
            p("chunk_b", 0.0),
            p("chunk_c", 1.0),
            p("chunk_d", 0.0),
            p("chunk_e", 0.0),
            p("chunk_f", -1.0),
            p_int("chunk_mode", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE),
    VarDef::new("truchet2", truchet2)
        .params(&[
            p_range("truchet2_exponent1", 1.0, -1.0, 3.0),
            p_range("truchet2_exponent2", 2.0, -1.0, 3.0),
            p_range("truchet2_width1", 0.5, -1.0, 2.0),
            p_range("truchet2_width2", 0.5, -1.0, 2.0),
            p("truchet2_scale", 10.0),
            p("truchet2_seed", 50.0),
            p_int("truchet2_inverse", 0.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE),
];

fn bwraps7_prepare(v: &mut Prepared) {
    let [_, _, gain] = v.params();
    bubble_prepare(v, gain * gain + 1e-6);
}

/// bwraps2's gain is divided by the cell size.
fn bwraps2_prepare(v: &mut Prepared) {
    let [cellsize, _, gain] = v.params();
    bubble_prepare(v, gain * gain / cellsize + 1e-6);
}

/// The bubbles' derived values for the magnification `g2`: g2, the squared radius, the
/// radius over the largest bubble.
fn bubble_prepare(v: &mut Prepared, g2: f64) {
    let [cellsize, space] = v.params();
    let radius = 0.5 * (cellsize / (1.0 + space * space));
    let mut max_bubble = g2 * radius;
    if max_bubble > 2.0 {
        max_bubble = 1.0;
    } else {
        max_bubble *= 1.0 / ((max_bubble * max_bubble) / 4.0 + 1.0);
    }
    v.p.extend_from_slice(&[g2, radius * radius, radius / max_bubble]);
}

/// bwraps7: in each cell of a square grid, a bubble of radius cellsize/(2(1 + space²)) that
/// magnifies its centre (gain) and twists from `inner_twist` at the centre to `outer_twist` at
/// the rim; points outside the bubbles stay.
fn bwraps7(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [cellsize, _, _, inner_twist, outer_twist] = v.params();
    let [g2, r2, rfactor] = v.derived();
    let (vx, vy) = (t.x, t.y);
    if cellsize.abs() < 1e-300 {
        return [v.w * vx, v.w * vy, 0.0];
    }
    let cx = ((vx / cellsize).floor() + 0.5) * cellsize;
    let cy = ((vy / cellsize).floor() + 0.5) * cellsize;
    let (mut lx, mut ly) = (vx - cx, vy - cy);
    if lx * lx + ly * ly > r2 {
        return [v.w * vx, v.w * vy, 0.0];
    }
    lx *= g2;
    ly *= g2;
    let r = rfactor / ((lx * lx + ly * ly) / 4.0 + 1.0);
    lx *= r;
    ly *= r;
    let r = (lx * lx + ly * ly) / r2;
    let theta = inner_twist * (1.0 - r) + outer_twist * r;
    let (s, c) = theta.sin_cos();
    [
        v.w * (cx + c * lx + s * ly),
        v.w * (cy - s * lx + c * ly),
        0.0,
    ]
}

/// bwraps2: bwraps7's bubbles with the gain divided by the cell size; as JWildfire's
/// `pre_`/`post_` classes, the point's z is kept.
fn bwraps2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [x, y, _] = bwraps7(v, t, acc, rng);
    let z = if v.form == Form::Regular { 0.0 } else { t.z };
    [x, y, z]
}

/// rings3: Apophysis' rings2 with a ring-count term n: the radius is pulled towards ring
/// number k = ⌊(r/dx + 1)/2⌋ (integer division), dx = val² + 1e-8.
fn rings3(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [val, n] = v.params();
    let dx = val * val + 1e-8;
    let c = 2.0 * (dx - dx * dx);
    let l = (t.x * t.x + t.y * t.y).sqrt() + 1e-300;
    // Java: (int) (l / dx + 1) / 2, an integer division.
    let k = (((l / dx + 1.0) as i32) / 2) as f64;
    let r = v.w * (2.0 - dx * (k * 2.0 / l + 1.0) - n * (k * c - 1.0) / l);
    [r * t.x, r * t.y, 0.0]
}

/// waves3_wf: x displaced by scalex·cos²(freqx·y) (or sin² when `use_cos_x` is not 1), y by
/// scaley·sin²(freqy·x) (or cos² when `use_cos_y` is 1), both damped by e^damp.
fn waves3_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        scalex,
        scaley,
        freqx,
        freqy,
        use_cos_x,
        use_cos_y,
        dampx,
        dampy,
    ] = v.params();
    let damping = |d: f64| if d.abs() < 1e-8 { 1.0 } else { d.exp() };
    let (dx, dy) = (damping(dampx), damping(dampy));
    let wx = if use_cos_x == 1.0 {
        (t.y * freqx).cos()
    } else {
        (t.y * freqx).sin()
    };
    let wy = if use_cos_y == 1.0 {
        (t.x * freqy).cos()
    } else {
        (t.x * freqy).sin()
    };
    [
        v.w * (t.x + dx * scalex * wx * wx) * dx,
        v.w * (t.y + dy * scaley * wy * wy) * dy,
        0.0,
    ]
}

/// invsquircular: the inverse of the squircular map (disc to square), with the weight inside
/// the formula; nothing at weight 0.
fn invsquircular(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    if v.w == 0.0 {
        return [0.0; 3];
    }
    let (u, w) = (t.x, t.y);
    let r = u * u + w * w;
    let r2 = (r * (v.w * v.w * r - 4.0 * u * u * w * w) / v.w).sqrt();
    let r = (r - r2).sqrt() / SQRT_2;
    [r / u, r / w, 0.0]
}

/// c_symmetry: z ↦ |z|^p2·e^(i·p1·arg z) (a power with separate exponents for angle and
/// radius); replaces the xform's sum so far.
fn c_symmetry(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [p1, p2] = v.params();
    let a = p1 * t.y.atan2(t.x);
    let m = (t.x * t.x + t.y * t.y).sqrt().powf(p2);
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [v.w * a.cos() * m, v.w * a.sin() * m, 0.0]
}

/// tunnel: a shader's tunnel distortion of the xform's sum so far: it is shifted by amounts
/// that grow with the distance of the point from (−0.5, −0.5), then the whole is scaled by the
/// weight.
fn tunnel(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [sx, sy] = v.params();
    let (ux, uy) = (t.x + 0.5, t.y + 0.5);
    let deform = 0.1;
    let (distx, disty) = (0.5 - ux, 0.5 - uy);
    let distortion = -(0.25 - (uy * deform - deform * 0.5).powi(2)).sqrt() * deform + deform * 0.5;
    let shift_x = distortion * distx * sx;
    let shift_y = sy * (deform - distortion) * deform * disty;
    let (mut ax, mut ay) = (0.0, 0.0);
    if v.form == Form::Regular {
        (ax, ay) = (acc.x, acc.y);
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [v.w * (ax + shift_x), v.w * (ay + shift_y), 0.0]
}

/// corners (Whittaker Courtney): pushes each quadrant outwards to its corner (±x, ±y) by a
/// power (or, in log mode, a logarithm) of the squared coordinate.
fn corners(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        x,
        y,
        mult_x,
        mult_y,
        x_power,
        y_power,
        add,
        log_mode,
        log_base,
    ] = v.params();
    let (xs, ys) = (t.x * t.x, t.y * t.y);
    let (ex, ey) = if log_mode == 0.0 {
        (
            xs.powf(x_power + add) * mult_x,
            ys.powf(y_power + add) * mult_y,
        )
    } else {
        let lb = log_base.ln();
        (
            (((xs * mult_x) + 3.0).ln() / lb).powf(x_power + 2.25 + add) - 1.33,
            (((ys * mult_y) + 3.0).ln() / lb).powf(y_power + 2.25 + add) - 1.33,
        )
    };
    let ox = if t.x > 0.0 {
        v.w * ex + x
    } else {
        v.w * -ex - x
    };
    let oy = if t.y > 0.0 {
        v.w * ey + y
    } else {
        v.w * -ey - y
    };
    [ox, oy, 0.0]
}

/// disc3: disc with every factor a parameter: angle π·√(d·e·x² + f·g·y²), radius
/// atan2(x, y)/π·c, sine and cosine scaled by a and b.
fn disc3(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c, d, e, f, g, h] = v.params();
    let rpi = PI * (t.x * d * t.x * e + t.y * f * t.y * g).sqrt();
    let sinr = rpi.sin() * a;
    let cosr = rpi.cos() * b;
    let r = v.w * t.atan_xy / PI * c;
    [sinr * h * r, cosr * h * r, 0.0]
}

/// Mirrors `c` in every other band of width 1/scale (the band containing 0 is kept).
fn lazy_flip(c: f64, scale: f64) -> f64 {
    if scale == 0.0 {
        return c;
    }
    let nr = (c * scale).floor() as i32;
    let odd = nr % 2 != 0;
    if (nr >= 0 && odd) || (nr < 0 && !odd) {
        -c
    } else {
        c
    }
}

/// lazysensen: mirrors x, y and z in alternate bands of width 1/scale. (JWildfire also
/// changes the point that the xform's later variations see; here only this output is.)
fn lazysensen(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [sx, sy, sz] = v.params();
    [
        v.w * lazy_flip(t.x, sx),
        v.w * lazy_flip(t.y, sy),
        v.w * lazy_flip(t.z, sz),
    ]
}

/// pTransform: in log-polar coordinates, divides the log radius by `power`, moves it by
/// `move` (and ±`split` by the side of x), and rotates by `rotate`.
fn ptransform(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [rotate, power, mv, split, use_log] = v.params();
    let r = (t.x * t.x + t.y * t.y).sqrt() + 1e-300;
    let mut rho = if use_log != 0.0 {
        r.ln() / power + mv
    } else {
        r / power + mv
    };
    let theta = t.y.atan2(t.x) + rotate;
    if t.x >= 0.0 {
        rho += split;
    } else {
        rho -= split;
    }
    if use_log != 0.0 {
        rho = rho.exp();
    }
    [v.w * rho * theta.cos(), v.w * rho * theta.sin(), 0.0]
}

fn spligon_prepare(v: &mut Prepared) {
    let [sides, _, i] = v.params();
    // JWildfire takes a side count that rounds to 0 as 1.
    let sides = if sides.abs() < 0.5 { 1.0 } else { sides };
    let th = sides / TAU;
    v.p.extend_from_slice(&[th, 1.0 / th, PI * i / (-2.0 * sides)]);
}

/// spligon (DarkBeam): shifts each of `sides` angular sectors by r along its own direction,
/// splitting the plane into a polygon of pieces.
fn spligon(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [_, r] = v.params();
    let [th, thi, j] = v.derived();
    let a = thi * (t.y.atan2(t.x) * th).floor() + j;
    let (dx, dy) = a.sin_cos();
    [v.w * (t.x + dy * r), v.w * (t.y + dx * r), 0.0]
}

/// anamorphcyl: a cylindrical anamorphosis: (a(y + b)·cos kx, a(y + b)·sin kx); replaces the
/// xform's sum so far.
fn anamorphcyl(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, k] = v.params();
    let m = a * (t.y + b);
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [m * (k * t.x).cos() * v.w, m * (k * t.x).sin() * v.w, 0.0]
}

/// clifford_js: one step of Clifford Pickover's attractor map (sin(a·y) + c·cos(a·x),
/// sin(b·x) + d·cos(b·y)).
fn clifford_js(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c, d] = v.params();
    let x = (a * t.y).sin() + c * (a * t.x).cos();
    let y = (b * t.x).sin() + d * (b * t.y).cos();
    [x * v.w, y * v.w, 0.0]
}

/// gridout2 (Michael and Joel Faber's gridout with factors): shifts the point by ±a in x or
/// ±b in y, by which of the four triangles around the origin its rounded (c, d)-scaled cell
/// lies in.
fn gridout2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c, d] = v.params();
    let x = t.x.round_ties_even() * c;
    let y = t.y.round_ties_even() * d;
    let (ox, oy) = if y <= 0.0 {
        if x > 0.0 {
            if -y >= x { (a, 0.0) } else { (0.0, b) }
        } else if y <= x {
            (a, 0.0)
        } else {
            (0.0, -b)
        }
    } else if x > 0.0 {
        if y >= x { (-a, 0.0) } else { (0.0, b) }
    } else if y > -x {
        (-a, 0.0)
    } else {
        (0.0, -b)
    };
    [v.w * (t.x + ox), v.w * (t.y + oy), 0.0]
}

/// chunk: keeps the points inside (mode 0) or outside (mode 1) the conic
/// a·x² + b·xy + c·y² + d·x + e·y + f = 0 (all coefficients scaled by the weight), unscaled;
/// the others contribute nothing.
fn chunk(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c, d, e, f, mode] = v.params();
    let w = v.w;
    let (x, y) = (t.x, t.y);
    let r = w * a * x * x + w * b * x * y + w * c * y * y + w * d * x + w * e * y + w * f;
    let keep = if mode == 0.0 { r <= 0.0 } else { r > 0.0 };
    if keep { [x, y, 0.0] } else { [0.0; 3] }
}

/// Java's `Math.round`: ⌊x + ½⌋.
fn java_round(x: f64) -> f64 {
    (x + 0.5).floor()
}

/// truchet2 (Tatyana Zabanova): Truchet tiles of quarter "circles" in the n-norm, the norm
/// exponent and the arc width blended from `exponent1`/`width1` to `exponent2`/`width2`
/// across bands of width `scale`; tiles flipped by a hash of the cell. Points off the arcs are
/// thrown far away (+100, or +10000 with `inverse`), as JWildfire does.
fn truchet2(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [exponent1, exponent2, width1, width2, scale, seed, inverse] = v.params();
    let pass = [v.w * t.x, v.w * t.y, 0.0];
    let xp = ((t.x / scale - (t.x / scale).floor()) - 0.5).abs() * 2.0;
    let width = (width1 * (1.0 - xp) + xp * width2).min(1.0);
    if width <= 0.0 {
        return pass;
    }
    let xp2 = exponent1 * (1.0 - xp) + xp * exponent2;
    let n = xp2.min(2.0);
    if n <= 0.0 {
        return pass;
    }
    let onen = 1.0 / xp2;
    let seed = seed.abs();
    let seed2 = (seed + seed / 2.0 + 1e-300).sqrt() / (seed * 0.5 + 1e-300) * 0.25;
    let frac = |c: f64| {
        let r = c - java_round(c);
        if r < 0.0 { 1.0 + r } else { r }
    };
    let (x, y) = (frac(t.x), frac(t.y));
    let tiletype = if seed == 0.0 {
        0.0
    } else if seed == 1.0 {
        1.0
    } else {
        let xr = java_round(t.x) * seed2;
        let yr = java_round(t.y) * seed2;
        let niter = xr + yr + xr * yr;
        let randint = (niter + seed) * seed2 / 2.0;
        let randint = (randint * 32747.0 + 12345.0) % 65535.0;
        randint % 2.0
    };
    let norm = |a: f64, b: f64| (a.abs().powf(n) + b.abs().powf(n)).powf(onen);
    let (r0, r1) = if tiletype < 1.0 {
        (norm(x, y), norm(x - 1.0, y - 1.0))
    } else {
        (norm(x - 1.0, y), norm(x, y - 1.0))
    };
    let rmax = 0.5 * (2.0_f64.powf(onen) - 1.0) * width;
    let r00 = (r0 - 0.5).abs() / rmax;
    let r11 = (r1 - 0.5).abs() / rmax;
    let on = [(x + t.x.floor()) * v.w, (y + t.y.floor()) * v.w, 0.0];
    if inverse == 0.0 {
        if r00 < 1.0 || r11 < 1.0 {
            on
        } else {
            [100.0, 100.0, 0.0]
        }
    } else if r00 > 1.0 && r11 > 1.0 {
        on
    } else {
        [10000.0, 10000.0, 0.0]
    }
}
