//! 3-D variations from Fractorium's catalogue: surfaces the plane is wrapped onto (helicoid,
//! helix, hemisphere, sphere, torus, Enneper's and Möbius' surfaces), 3-D versions of classic
//! shapes (blade, blob, bubble, disc, popcorn, polar rose, sinusoidal, splits), the cube
//! lattices and a few other 3-D maps (`barycentroid`, `depth`, `heat`, `ho`, `octagon`).
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::util::{sign, sqr, zeps};
use super::*;
use crate::flame::fastmath::{self as fm, FastTrig};

pub(super) static DEFS: &[VarDef] = &[
    super::inlined!("barycentroid", barycentroid)
        .params(&[
            p("barycentroid_a", 1.0),
            p("barycentroid_b", 0.0),
            p("barycentroid_c", 0.0),
            p("barycentroid_d", 1.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("blade3D", blade3d)
        .needs(need::SUMSQ | need::SQRT)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z),
    super::inlined!("blob2", blob2)
        .params(&[
            p("blob2_mode", 0.5),
            p("blob2_n", 1.0),
            p("blob2_radius", 0.0),
            p("blob2_prescale", 1.0),
            p("blob2_postscale", 0.5),
            p_range("blob2_symmetry", 0.0, -1.0, 1.0),
            p("blob2_compensation", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_blob2),
    super::inlined!("blob3D", blob3d)
        .params(&[
            p("blob3D_low", 0.0),
            p("blob3D_high", 1.0),
            p("blob3D_waves", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES | need::ATAN_XY)
        .flags(flag::WRITES_Z),
    super::inlined!("bubble2", bubble2)
        .params(&[
            p("bubble2_x", 1.0),
            p("bubble2_y", 1.0),
            p("bubble2_z", 0.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("bubbleT3D", bubble_t3d)
        .params(&[
            // Each evaluation walks the stripes one by one.
            p_int("bubbleT3D_number_of_stripes", 0.0, -1000.0, 1000.0).limited(),
            p_range("bubbleT3D_ratio_of_stripes", 1.0, 0.0, 2.0),
            p_range("bubbleT3D_angle_of_hole", 0.0, -360.0, 360.0),
            p("bubbleT3D_exponentZ", 1.0),
            p_int("bubbleT3D_symmetryZ", 0.0, 0.0, 1.0),
            p_int("bubbleT3D_modusBlur", 0.0, 0.0, 1.0),
        ])
        .needs(need::SUMSQ)
        .flags(flag::WRITES_Z)
        .prepare(prep_bubble_t3d),
    super::inlined!("cubic3D", cubic3d)
        .params(&[p("cubic3D_xpand", 0.25), p("cubic3D_style", 0.0)])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::READS_ACC)
        .prepare(cubic3d_prepare),
    super::inlined!("cubicLattice_3D", cubic_lattice_3d)
        .params(&[
            p("cubicLattice_3D_xpand", 0.2),
            p_int("cubicLattice_3D_style", 1.0, 1.0, 2.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z | flag::READS_ACC)
        .prepare(cubic_lattice_3d_prepare),
    super::inlined!("depth", depth)
        .params(&[p("depth_power", 1.0)])
        .flags(flag::USES_Z | flag::WRITES_Z | flag::READS_AFFINE_POINT),
    super::inlined!("disc3d", disc3d)
        .params(&[p("disc3d_pi", PI)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("ennepers", ennepers),
    super::inlined!("heat", heat)
        .params(&[
            p("heat_theta_period", 1.0),
            p("heat_theta_phase", 0.0),
            p("heat_theta_amp", 1.0),
            p("heat_phi_period", 1.0),
            p("heat_phi_phase", 0.0),
            p("heat_phi_amp", 0.0),
            p("heat_r_period", 1.0),
            p("heat_r_phase", 0.0),
            p("heat_r_amp", 0.0),
        ])
        .needs(need::SUMSQ | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z)
        .prepare(heat_prepare),
    super::inlined!("helicoid", helicoid)
        .params(&[p("helicoid_frequency", 1.0)])
        .needs(need::SQRT | need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("helix", helix)
        .params(&[p("helix_frequency", 1.0), p("helix_width", 0.5)])
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("hemisphere", hemisphere)
        .needs(need::SUMSQ)
        .flags(flag::WRITES_Z),
    super::inlined!("ho", ho)
        .params(&[p("ho_xpow", 3.0), p("ho_ypow", 3.0), p("ho_zpow", 3.0)])
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("mobius_strip", mobius_strip)
        .params(&[
            p("mobius_strip_radius", 2.0),
            p("mobius_strip_width", 1.0),
            p("mobius_strip_rect_x", TAU),
            p("mobius_strip_rect_y", 1.0),
            p("mobius_strip_rotate_x", 0.0),
            p("mobius_strip_rotate_y", 0.0),
        ])
        .prepare(prep_mobius_strip),
    super::inlined!("octagon", octagon)
        .params(&[
            p("octagon_x", 0.0),
            p("octagon_y", 0.0),
            p("octagon_z", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("popcorn2_3D", popcorn2_3d)
        .params(&[
            p("popcorn2_3D_x", 0.1),
            p("popcorn2_3D_y", 0.1),
            p("popcorn2_3D_z", 0.1),
            p("popcorn2_3D_c", 3.0),
        ])
        .needs(need::ATAN_YX)
        .flags(flag::USES_Z | flag::WRITES_Z | flag::READS_ACC)
        .prepare(prep_popcorn2_3d),
    super::inlined!("pRose3D", prose3d)
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
            p("pRose3D_crvsc", 0.0),
            p("pRose3D_f", 3.0),
            p("pRose3D_wigsc", 0.0),
            p("pRose3D_offset", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(flag::WRITES_Z)
        .prepare(prose3d_prep),
    super::inlined!("psphere", psphere)
        .params(&[p("psphere_zscale", 0.0)])
        .flags(flag::WRITES_Z)
        .prepare(psphere_prep),
    super::inlined!("sinusoidal3D", sinusoidal3d).flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("splits3D", splits3d)
        .params(&[
            p("splits3D_x", 0.0),
            p("splits3D_y", 0.0),
            p("splits3D_z", 0.0),
        ])
        .flags(flag::USES_Z | flag::WRITES_Z),
    super::inlined!("svf", svf)
        .params(&[p("svf_n", 2.0)])
        .flags(flag::WRITES_Z),
    super::inlined!("taurus", taurus)
        .params(&[
            p("taurus_r", 3.0),
            p("taurus_n", 5.0),
            p("taurus_inv", 1.5),
            p("taurus_sor", 1.0),
        ])
        .flags(flag::WRITES_Z)
        .prepare(taurus_prep),
];

/// Barycentric coordinates (u, v) of the point in the basis (a, b), (c, d), each combined
/// in quadrature with the matching input coordinate (keeping the sign of u or v); z is scaled.
#[inline(always)]
fn barycentroid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [a, b, c, d] = v.params();
    let g00 = a * a + b * b;
    let g01 = a * c + b * d;
    let g11 = c * c + d * d;
    let p0 = a * t.x + b * t.y;
    let p1 = c * t.x + d * t.y;
    let inv = 1.0 / zeps(g00 * g11 - g01 * g01);
    let u = (g11 * p0 - g01 * p1) * inv;
    let w = (g00 * p1 - g01 * p0) * inv;
    let um = (u * u + t.x * t.x).sqrt() * sign(u);
    let wm = (w * w + t.y * t.y).sqrt() * sign(w);
    [v.w * um, v.w * wm, v.w * t.z]
}

/// 3-D blade: x drives all three coordinates through the sine and cosine of a random fraction
/// of w·r.
#[inline(always)]
fn blade3d(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let (s, c) = (rng.f01() * v.w * t.sqrt).fsin_cos();
    let wx = v.w * t.x;
    [wx * (c + s), wx * (c - s), v.w * t.z * (s - c)]
}

/// Derived value: the compensation divisor 1 + compensation·|symmetry|.
fn prep_blob2(v: &mut Prepared) {
    let [_, _, _, _, _, sym, comp] = v.params();
    let flip = if sym < 0.0 { -1.0 } else { 1.0 };
    v.p.push(1.0 + comp * sym * flip);
}

/// Blob with a hole: inside `radius` the point is kept; outside, its distance beyond the radius
/// is modulated by a power of the angular wave sin(n·θ) + symmetry.
#[inline(always)]
fn blob2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [mode, n, radius, pre, post, sym, _comp] = v.params();
    let [help] = v.derived();
    if t.sqrt < radius {
        // Fractorium leaves z unset on this branch; the point keeps its default z.
        return [v.w * t.x, v.w * t.y, v.default_z(t)];
    }
    let delta = ((t.atan_yx * n).fsin() + sym) / help;
    let sgn = if delta < 0.0 { -1.0 } else { 1.0 };
    let amp = ((delta * sgn).ln() * pre).exp() * post;
    let delta = if mode != 0.0 { amp * mode } else { amp * sgn };
    let rad = radius + (t.sqrt - radius) * delta;
    [v.w * rad * t.ux, v.w * rad * t.uy, v.w * t.z]
}

/// 3-D blob: the radius oscillates between `low` and `high` with the angle atan2(x, y), and the
/// same wave lifts the point in z.
#[inline(always)]
fn blob3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [low, high, waves] = v.params();
    let wave = (waves * t.atan_xy).fsin();
    let r = t.sqrt * (low + (high - low) * (0.5 + 0.5 * wave));
    [v.w * t.ux * r, v.w * t.uy * r, v.w * wave * r]
}

/// 3-D bubble with per-axis scales; z is pushed away from the plane by `z` as well.
#[inline(always)]
fn bubble2(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [sx, sy, sz] = v.params();
    let r = v.w / zeps(0.25 * (t.sumsq + t.z * t.z) + 1.0);
    let lift = if t.z >= 0.0 {
        v.w * (t.z + sz)
    } else {
        v.w * (t.z - sz)
    };
    [t.x * r * sx, t.y * r * sy, lift + t.z * r * sz]
}

fn prep_bubble_t3d(v: &mut Prepared) {
    let [stripes, ratio, hole, _, sym, _] = v.params();
    let abs_n = stripes.abs();
    let inv_stripes = if stripes < 0.0 { 1.0 } else { 0.0 };
    let (mut strip1, mut strip2, mut s, mut c, mut ratio) = (0.0, 0.0, 0.0, 0.0, ratio);
    if abs_n != 0.0 {
        let strip = PI / abs_n;
        strip2 = 2.0 * strip;
        (s, c) = strip.fsin_cos();
        ratio = ratio.clamp(0.01, 1.99);
        strip1 = zeps(ratio * strip);
    }
    let mut h = if sym == 1.0 {
        if hole < 0.0 {
            hole.abs()
        } else {
            hole.min(179.9)
        }
    } else {
        hole
    };
    let inv_hole;
    if h < 0.0 {
        inv_hole = 1.0;
        h = (hole.abs() / 360.0 * TAU) / 2.0;
    } else {
        inv_hole = 0.0;
        h = PI - (h / 360.0 * TAU) / 2.0;
    }
    v.p.extend_from_slice(&[
        abs_n,
        inv_stripes,
        strip1,
        strip2,
        s,
        c,
        h,
        inv_hole,
        PI - h,
        ratio,
    ]);
}

/// Rotates (x, y) by the angle with sine `s` and cosine `c`.
#[inline(always)]
fn rot(x: f64, y: f64, s: f64, c: f64) -> (f64, f64) {
    (c * x - s * y, s * x + c * y)
}

/// The bubble lifted onto a sphere, with optional stripes cut out of it (or, in blur mode,
/// rotated onto their neighbours) and a hole of a given angle at the pole (or at both poles
/// with z-symmetry), which blur mode squeezes the cap into instead of cutting.
#[inline(always)]
fn bubble_t3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, exp_z, sym_z, blur] = v.params();
    let [abs_n, inv_stripes, strip1, strip2, sin_ratio, cos_ratio] = v.derived();
    let [_, _, _, _, _, _, hole, inv_hole, comp, ratio] = v.derived();
    let (mut x, mut y) = (t.x, t.y);
    let rad = zeps(t.sumsq / 4.0 + 1.0);
    if abs_n != 0.0 {
        let mut ang = t.x.atan2(t.y);
        if ang < 0.0 {
            ang += TAU;
        }
        while ang > strip2 {
            ang -= strip2;
        }
        let outside = if inv_stripes == 0.0 {
            ang > strip1
        } else {
            ang < strip1
        };
        if outside {
            if blur == 0.0 {
                x = 0.0;
                y = 0.0;
            } else {
                let fixed = if inv_stripes == 0.0 {
                    ratio == 1.0
                } else {
                    abs_n == 1.0
                };
                let (s, c) = if fixed {
                    (sin_ratio, cos_ratio)
                } else if inv_stripes == 0.0 {
                    let f = (ang - strip1) / zeps(strip2 - strip1);
                    (ang - f * strip1).fsin_cos()
                } else {
                    let f = (ang - strip1) / strip1;
                    (ang - f * (strip2 - strip1)).fsin_cos()
                };
                (x, y) = rot(x, y, s, c);
            }
        }
    }
    x /= rad;
    y /= rad;
    let (mut z, ang_z) = if x != 0.0 || y != 0.0 {
        let z = 2.0 / rad.powf(exp_z) - 1.0;
        let a = if exp_z <= 2.0 {
            PI - (z / (x * x + y * y + z * z)).acos()
        } else {
            PI - sqr(x * x + y * y).atan2(z)
        };
        (z, a)
    } else {
        (0.0, 0.0)
    };
    let squeeze = blur != 0.0 && exp_z == 1.0;
    let bent = if sym_z == 0.0 {
        let inv = inv_hole != 0.0;
        let in_hole = if inv { ang_z < hole } else { ang_z > hole };
        if !in_hole {
            None
        } else if inv {
            Some(PI - ang_z / zeps(comp * hole - FRAC_PI_2))
        } else {
            Some((PI - ang_z) / zeps(comp * hole - FRAC_PI_2))
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
            let fac = a.fcos() / b.fcos();
            x *= fac;
            y *= fac;
            z *= a.fsin() / b.fsin();
        } else {
            x = 0.0;
            y = 0.0;
            z = 0.0;
        }
    }
    [v.w * x, v.w * y, v.w * z]
}

/// The sign pattern of corner `node` (0–7) of a cube: (±x, ±y, ±z).
#[inline(always)]
fn cube_corner(node: u32, h: f64) -> [f64; 3] {
    [
        if node & 4 != 0 { -h } else { h },
        if node & 1 != 0 { -h } else { h },
        if node & 2 != 0 { -h } else { h },
    ]
}

fn cubic_fill(xpand: f64) -> f64 {
    if xpand.abs() <= 1.0 {
        xpand * 0.5
    } else {
        xpand.sqrt() * 0.5
    }
}

fn cubic3d_prepare(v: &mut Prepared) {
    let [xpand, style] = v.params();
    let fill = cubic_fill(xpand);
    let smooth = if v.w.abs() <= 0.5 { v.w * 2.0 } else { 1.0 };
    let smooth_style = if style.abs() <= 1.0 {
        style
    } else if style > 1.0 {
        1.0 + (style - 1.0) * 0.25
    } else {
        (style + 1.0) * 0.25 - 1.0
    };
    v.p.extend_from_slice(&[
        smooth_style,
        smooth * fill,
        smooth * (1.0 - fill),
        v.w * 0.5,
    ]);
}

/// Copies the point to a random corner of a cube lattice, blending between the running sum and
/// the input (the blend is shaped by the point's direction with `cubic3D_style`).
#[inline(always)]
fn cubic3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [ss, sfill, s1mfill, half_w] = v.derived();
    let node = rng.u32() & 7;
    let ex = 1.0 - ss * (1.0 - t.x.atan2(t.z).fcos());
    let wy = 1.0 - ss * (1.0 - t.y.atan2(t.z).fsin());
    let zn = if ss > 1.0 {
        1.0 - ss * (1.0 - ((ex + wy) / 2.0 * ss))
    } else {
        1.0 - ss * (1.0 - ((ex + wy) * 0.5))
    };
    let (px, py, pz) = sum_or_input(v, t, acc);
    let a = (px - (s1mfill * px * ex)) + (t.x * sfill * ex);
    let b = (py - (s1mfill * py * wy)) + (t.y * sfill * wy);
    let c = (pz - (s1mfill * pz * zn)) + (t.z * sfill * zn);
    let k = cube_corner(node, half_w);
    [a + k[0], b + k[1], c + k[2]]
}

fn cubic_lattice_3d_prepare(v: &mut Prepared) {
    let [xpand] = v.params();
    let fill = cubic_fill(xpand);
    v.p.push(fill);
}

/// Copies the point (plus the running sum, scaled) to a random corner of a cube lattice of
/// half-size `weight`; style 2 shapes the copy by the point's direction.
#[inline(always)]
fn cubic_lattice_3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, style] = v.params();
    let [fill] = v.derived();
    let node = rng.u32() & 7;
    let (ex, wy, zn) = if style == 2.0 {
        let ex = t.x.atan2(t.z).fcos();
        let wy = t.y.atan2(t.z).fsin();
        (ex, wy, (ex + wy) * 0.5)
    } else {
        (1.0, 1.0, 1.0)
    };
    let (px, py, pz) = sum_or_input(v, t, acc);
    let a = (px + t.x) * fill * ex;
    let b = (py + t.y) * fill * wy;
    let c = (pz + t.z) * fill * zn;
    let k = cube_corner(node, v.w);
    [a + k[0], b + k[1], c + k[2]]
}

/// Adds to the point a copy scaled by |z|^power: a perspective-like depth push. The first term
/// is the xform's affine-transformed point (after its `pre_` forms), the scaled copy the
/// variation's input: the same point for the `pre_` and regular forms, the sum of the regular
/// variations for `post_depth` (Fractorium 1.0.0.19 `DepthVariation` reads `m_TransX` and
/// `In`, which differ in a post variation; [`flag::READS_AFFINE_POINT`] brings the affine point
/// as `t`, the sum in `acc`). JWildfire's `PostDepthFunc` adds the result to the sum.
#[inline(always)]
fn depth(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let post = v.form == Form::Post;
    let s = if post {
        [acc.x, acc.y, acc.z]
    } else {
        [t.x, t.y, t.z]
    };
    let mut k = s[2].abs();
    if k != 0.0 && power != 1.0 {
        k = (k.ln() * power).exp();
    }
    let o = [
        v.w * (t.x + s[0] * k),
        v.w * (t.y + s[1] * k),
        v.w * (t.z + s[2] * k),
    ];
    if post && v.dialect == Dialect::JWildfire {
        [s[0] + o[0], s[1] + o[1], s[2] + o[2]]
    } else {
        o
    }
}

/// disc with an adjustable "π" and a z from the radius and cos z.
#[inline(always)]
fn disc3d(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [pi] = v.params();
    let r = t.sqrt;
    let (sr, cr) = (r * pi).fsin_cos();
    let k = v.w * t.atan_xy / zeps(pi);
    [k * sr, k * cr, k * (r * t.z.fcos())]
}

/// The plane projection of Enneper's minimal surface (weight applies to the cubic part only).
#[inline(always)]
fn ennepers(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let (x2, y2) = (t.x * t.x, t.y * t.y);
    [
        v.w * (t.x - ((x2 * t.x) / 3.0)) + t.x * y2,
        v.w * (t.y - ((y2 * t.y) / 3.0)) + t.y * x2,
        0.0,
    ]
}

fn heat_prepare(v: &mut Prepared) {
    let [
        theta_period,
        theta_phase,
        theta_amp,
        phi_period,
        phi_phase,
        phi_amp,
        r_period,
        r_phase,
        r_amp,
    ] = v.params();
    let inv = |period: f64| if period == 0.0 { 0.0 } else { 1.0 / period };
    let (tx, px, rx) = (inv(theta_period), inv(phi_period), inv(r_period));
    let w = v.w;
    let derived = [
        w * theta_amp,
        TAU * tx,
        theta_phase * tx,
        w * phi_amp,
        TAU * px,
        phi_phase * px,
        w * r_amp,
        TAU * rx,
        r_phase * rx,
    ];
    v.p.extend_from_slice(&derived);
}

/// Spherical coordinates made wavy: the radius, azimuth and inclination each get a sine
/// ripple (period, phase, amplitude) driven by the radius.
#[inline(always)]
fn heat(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [at, bt, ct, ap, bp, cp, ar, br, cr] = v.derived();
    let mut r = (t.sumsq + t.z).abs().sqrt();
    r += ar * br.mul_add(r, cr).fsin();
    if r == 0.0 {
        r = f64::EPSILON;
    }
    let (st, ct_) = at.mul_add(bt.mul_add(r, ct).fsin(), t.atan_yx).fsin_cos();
    let incl = (t.z / r).clamp(-1.0, 1.0).acos();
    let (sp, cp_) = ap.mul_add(bp.mul_add(r, cp).fsin(), incl).fsin_cos();
    [r * ct_ * sp, r * st * sp, r * cp_]
}

/// A helicoid: the polar angle is advanced by 2π·frequency·z, the radius kept, z scaled.
#[inline(always)]
fn helicoid(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [frequency] = v.params();
    let ang = t.z * (frequency * TAU) + t.atan_yx;
    let k = v.w * t.sqrt;
    [k * ang.fcos(), k * ang.fsin(), v.w * t.z]
}

/// A helix: the point is shifted by a circle of radius `width` whose angle turns with z.
#[inline(always)]
fn helix(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [frequency, width] = v.params();
    let ang = t.z * (frequency * TAU);
    [
        v.w * (t.x + ang.fcos() * width),
        v.w * (t.y + ang.fsin() * width),
        v.w * t.z,
    ]
}

/// Projects the plane onto the upper unit hemisphere: (x, y, 1)/√(r² + 1).
#[inline(always)]
fn hemisphere(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let k = v.w / (t.sumsq + 1.0).sqrt();
    [t.x * k, t.y * k, k]
}

/// "ho": x, y and z become powers of products of sines and cosines of the input plus small
/// arctangent terms (a knotted 3-D surface).
#[inline(always)]
fn ho(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [px, py, pz] = v.params();
    let (xx, yy, zz) = (t.x * t.x, t.y * t.y, t.z * t.z);
    let om_x = yy.atan2(zz);
    let om_y = xx.atan2(zz);
    let (su, cu) = t.x.fsin_cos();
    let (sv, cv) = t.y.fsin_cos();
    let cucv = cu * cv;
    let sucv = su * cv;
    let x = cucv.abs().powf(px) + cucv * px + 0.25 * om_x;
    let y = sucv.abs().powf(py) + sucv * py + 0.25 * om_y;
    let z = sv.abs().powf(pz) + sv * pz;
    [v.w * x, v.w * y, v.w * z]
}

fn prep_mobius_strip(v: &mut Prepared) {
    let [_, _, _, _, rotate_x, rotate_y] = v.params();
    let (rx, ry) = (rotate_x * TAU, rotate_y * TAU);
    v.p.extend_from_slice(&[rx.fsin(), rx.fcos(), ry.fsin(), ry.fcos()]);
}

/// mobius_strip: wraps the rectangle [−rect_x, rect_x]×[−rect_y, rect_y] (tiled) onto a Möbius
/// band of the given radius and width, rotates it about x then y and projects onto the plane.
#[inline(always)]
fn mobius_strip(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [radius, width, rect_x, rect_y] = v.params();
    let [rx_sin, rx_cos, ry_sin, ry_cos] = v.derived();
    let u = if rect_x == 0.0 {
        0.0
    } else {
        let f = (t.x + rect_x) / (2.0 * rect_x);
        TAU * (f - f.floor())
    };
    let s = if rect_y == 0.0 {
        0.0
    } else {
        let f = (t.y + rect_y) / (2.0 * rect_y);
        2.0 * width * (f - f.floor()) - width
    };
    let half_c = (u / 2.0).fcos();
    let bx = (radius + s * half_c) * u.fcos();
    let by = (radius + s * half_c) * u.fsin();
    let bz = s * (u / 2.0).fsin();
    let y1 = by * ry_cos + bz * ry_sin;
    let z1 = bz * ry_cos - by * ry_sin;
    let x2 = bx * rx_cos - z1 * rx_sin;
    [v.w * x2, v.w * y1, 0.0]
}

/// octagon: a 3-D inversion in the "octagonal" norm x⁴ + y⁴ + 2z² where it is strong (factor
/// below 2); elsewhere the point is scaled and pushed away from the axes by (x, y, z).
#[inline(always)]
fn octagon(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [ox, oy, oz] = v.params();
    let (x2, y2, z2) = (t.x * t.x, t.y * t.y, t.z * t.z);
    let k = v.w / zeps(x2 * x2 + z2 + y2 * y2 + z2);
    if k < 2.0 {
        return [k * t.x, k * t.y, k * t.z];
    }
    let away = |u: f64, off: f64| {
        if u >= 0.0 {
            v.w * (u + off)
        } else {
            v.w * (u - off)
        }
    };
    [away(t.x, ox), away(t.y, oy), away(t.z, oz)]
}

fn prep_popcorn2_3d(v: &mut Prepared) {
    let [_, _, _, c] = v.params();
    let w = v.w;
    let vv = if w.abs() <= 1.0 { w.abs() * w } else { w };
    v.p.extend_from_slice(&[c.tan().fsin(), w * 0.5, vv]);
}

/// popcorn2_3D: popcorn2 (x + px·sin tan(c·y), y + py·sin tan(c·x)), halved, with a z made
/// from the input z (or the angle when z is 0) and, when the running z is still 0, the angle.
#[inline(always)]
fn popcorn2_3d(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [px, py, pz, c] = v.params();
    let [sin_tan_c, half_w, vv] = v.derived();
    let from_angle = vv * sin_tan_c * t.atan_yx;
    let z_in = if t.z == 0.0 { from_angle } else { t.z };
    let other_z = if v.form == Form::Pre { t.z } else { acc.z };
    let lift = if other_z == 0.0 { from_angle } else { 0.0 };
    [
        half_w * (t.x + px * (c * t.y).tan().fsin()),
        half_w * (t.y + py * (c * t.x).tan().fsin()),
        lift + vv * (pz * sin_tan_c * z_in),
    ]
}

/// A polar rose r = l·cos(kθ + c) lifted into 3-D: the height is a blend of radial waves
/// ("wag"), a spiral wiggle and an offset; with a negative option a random half of the points
/// form a scaled, mirrored "ghost" copy below.
#[inline(always)]
pub(super) fn prose3d(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        l,
        _k,
        c,
        z1,
        z2,
        ref_sc,
        _opt,
        _opt_sc,
        _opt3,
        _transp,
        dist,
        wagsc,
        crvsc,
        _f,
        _wigsc,
        offset,
    ] = v.params();
    let [
        cycle,
        petals,
        dir,
        ghost,
        freq,
        wig_scale,
        s12,
        s3,
        anti,
        abs_opt,
    ] = v.derived();

    let rad = t.sqrt;
    let c1 = rad / l;
    let c2 = c1 * c1;
    let c3 = (rad - l * 0.5) / l;
    let c4 = c2 * c2;
    let th = t.atan_yx;
    let (sth, cth) = fm::sin_cos_scalar(th);
    let lower = rng.f01() < 0.5;

    let wig = th / zeps(cycle) * freq * 0.5 + offset * cycle;
    // Radial waves: the sine terms of r/l, (r/l)² and (r/l)⁴, plus linear and curvature terms
    // (which of sin((r/l)²π) and cos((r/l - 1/2)π) goes where depends on the option's sign).
    let curve_a = crvsc * 0.5 * fm::sin_cos_scalar(c2 * PI).0;
    let curve_b = crvsc * 0.5 * fm::sin_cos_scalar(c3 * PI).1;
    let (first, last) = if dir < 0.0 {
        (curve_a, curve_b)
    } else {
        (curve_b, curve_a)
    };
    let lin = wagsc * 0.4 * rad;
    let wag = fm::sin_cos_scalar(c1 * PI * abs_opt).0 + lin + first;
    let wag12 = if s12 <= 1.0 {
        wag
    } else {
        let wag2 = fm::sin_cos_scalar(c2 * PI * abs_opt).0 + lin + curve_b;
        if s12 <= 2.0 {
            wag2 * (1.0 - anti) + wag * anti
        } else {
            wag2
        }
    };
    let waggle = if s3 == 0.0 {
        wag12
    } else if s3 > 0.0 {
        let wag3 = fm::sin_cos_scalar(c4 * PI * abs_opt).0 + wagsc * (rad * rad) * 0.4 + last;
        wag12 * (1.0 - s3) + wag3 * s3
    } else {
        0.0
    };

    let petal = l * fm::sin_cos_scalar(petals * th + c).1;
    let swirl = sqr(rad * 0.5) * fm::sin_cos_scalar(wig).0 * wig_scale;
    let is_ghost = rng.f01() < ghost && lower;
    if is_ghost {
        let k = v.w * 0.5 * ref_sc;
        [
            k * petal * cth,
            k * petal * sth,
            v.w * -0.5 * ((z2 * waggle + swirl) + dist),
        ]
    } else {
        let k = v.w * 0.5;
        [
            k * petal * cth,
            k * petal * sth,
            k * ((z1 * waggle + swirl) + dist),
        ]
    }
}

pub(super) fn prose3d_prep(v: &mut Prepared) {
    let [
        _l,
        k,
        _c,
        _z1,
        _z2,
        _ref_sc,
        opt,
        opt_sc,
        opt3,
        transp,
        _dist,
        _wagsc,
        _crvsc,
        f,
        wigsc,
    ] = v.params();
    let cycle = TAU / zeps(k);
    let mut petals = k;
    if petals.abs() < 0.0001 {
        petals = 0.0001 * 1f64.copysign(k);
    }
    let s12 = opt.abs().min(2.0);
    let s3 = opt3.abs().min(1.0);
    let mut dir = 1f64.copysign(opt);
    if opt3 < 0.0 {
        dir = -1.0;
    }
    let ghost = if dir > 0.0 { 0.0 } else { transp * transp };
    v.p.extend([
        cycle,
        petals,
        dir,
        ghost,
        f * TAU,
        wigsc * 0.5,
        s12,
        s3,
        2.0 - s12,
        opt_sc.abs(),
    ]);
}

/// Wraps the plane around a sphere: x and y become longitude and latitude (scaled by w·π),
/// z the height scaled by `zscale`.
#[inline(always)]
fn psphere(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [zscale] = v.params();
    let [k] = v.derived();
    let (s0, c0) = (t.x * k).fsin_cos();
    let (s1, c1) = (t.y * k).fsin_cos();
    [c0 * -s1, s0 * c1, c1 * zscale]
}

fn psphere_prep(v: &mut Prepared) {
    let k = v.w * PI;
    v.p.push(k);
}

/// sinusoidal in 3-D: sin x, sin y, and z from the angle of (x², y²) times cos z.
#[inline(always)]
fn sinusoidal3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    [
        v.w * t.x.fsin(),
        v.w * t.y.fsin(),
        v.w * ((t.x * t.x).atan2(t.y * t.y) * t.z.fcos()),
    ]
}

/// splits in 3-D: each octant is moved away from the coordinate planes by (x, y, z).
#[inline(always)]
fn splits3d(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [dx, dy, dz] = v.params();
    let away = |c: f64, d: f64| if c >= 0.0 { c + d } else { c - d };
    [
        v.w * away(t.x, dx),
        v.w * away(t.y, dy),
        v.w * away(t.z, dz),
    ]
}

/// svf: the plane wrapped onto a sphere-like surface whose latitude bands are modulated by
/// cos(n·y) (a 3-D output).
#[inline(always)]
fn svf(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [n] = v.params();
    let cn = (n * t.y).fcos();
    let (sx, cx) = t.x.fsin_cos();
    let (sy, cy) = t.y.fsin_cos();
    [
        v.w * (cy * (cn * cx)),
        v.w * (cy * (cn * sx)),
        v.w * (sy * cn),
    ]
}

/// Derived values of taurus: inv·r, 1 − inv, 1 − sor.
fn taurus_prep(v: &mut Prepared) {
    let [r, _, inv, sor] = v.params();
    v.p.extend_from_slice(&[inv * r, 1.0 - inv, 1.0 - sor]);
}

/// taurus: the plane wrapped onto a torus-like surface whose tube radius ripples n times
/// around (`inv` blends toward a plain torus, `sor` toward a surface of revolution).
#[inline(always)]
fn taurus(v: &Prepared, t: &VarIn, _: &mut Acc, _: &mut FastRng) -> V3 {
    let [r, n, _, sor] = v.params();
    let [inv_r, one_minus_inv, one_minus_sor] = v.derived();
    let (sx, cx) = t.x.fsin_cos();
    let (sy, cy) = t.y.fsin_cos();
    let ir = inv_r + (one_minus_inv * (r * (n * t.x).fcos()));
    [
        v.w * (cx * (ir + sy)),
        v.w * (sx * (ir + sy)),
        v.w * (sor * cy) + (one_minus_sor * t.y),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::affine::Affine;

    /// `post_depth` of weight 1, power 1, for a flame of `dialect`.
    fn post_depth(dialect: Dialect) -> Prepared {
        let (id, form) = parse_name("post_depth").expect("registered");
        let rules = Rules {
            dialect,
            ..Rules::default()
        };
        Prepared::for_flame(id, form, 1.0, &[1.0], &[], Affine::default(), rules)
    }

    /// Fractorium's post_depth adds to the xform's affine point T the sum of its variations V
    /// scaled by |V.z|: w·(T + V·|V.z|) replaces the point; JWildfire's adds that to V.
    #[test]
    fn post_depth_pushes_the_affine_point_by_the_sum() {
        let mut rng = FastRng::new(1);
        let affine = [1.0, 2.0, 3.0];
        let sum = || Acc {
            x: 0.5,
            y: -1.0,
            z: 2.0,
            ..Acc::default()
        };
        let close = |a: &Acc, b: [f64; 3]| {
            assert!(
                (a.x - b[0]).abs() + (a.y - b[1]).abs() + (a.z - b[2]).abs() < 1e-12,
                "{a:?} vs {b:?}"
            )
        };
        let mut acc = sum();
        post_depth(Dialect::Fractorium).apply_post_after(&affine, &mut acc, 0.5, &mut rng);
        close(&acc, [2.0, 0.0, 7.0]);
        let mut acc = sum();
        post_depth(Dialect::Flam3).apply_post_after(&affine, &mut acc, 0.5, &mut rng);
        close(&acc, [2.0, 0.0, 7.0]);
        let mut acc = sum();
        post_depth(Dialect::JWildfire).apply_post_after(&affine, &mut acc, 0.5, &mut rng);
        close(&acc, [2.5, -1.0, 9.0]);
    }
}
