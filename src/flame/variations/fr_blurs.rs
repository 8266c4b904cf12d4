//! Blurs from Fractorium's catalogue: random points filling a shape (disc, square, ball, cube,
//! heart, star, polygon) or scattered about the input point, independent of its distance.
//!
//! Each formula follows the mathematics of Fractorium's version (constants, branch conditions,
//! pole guards and integer conversions included) so that a flame renders the same; the code is
//! ugnis's own.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};

use super::util::{floor_f, floor_i64, rand_size, sign_nz, sqr, square_arc, trunc_i32, zeps};
use super::*;
use crate::flame::fastmath;
use crate::flame::fastmath::FastTrig;

/// Most edges (and stripes) of nBlur's polygon: each evaluation steps through the sectors one
/// by one, and a polygon of 1,000 edges is a circle to within a twentieth of a pixel at a
/// radius of 10,000 pixels.
const NBLUR_MAX: f64 = 1000.0;

pub(super) static DEFS: &[VarDef] = &[
    super::inlined_drawn!("blur3D", blur3d, 6)
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
    super::inlined_drawn!("blur_circle", blur_circle, 2)
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .sum(),
    super::inlined!("blur_heart", blur_heart)
        .params(&[
            p("blur_heart_p", 0.5),
            p("blur_heart_a", -0.6),
            p("blur_heart_b", 0.7),
        ])
        .flags(flag::RANDOM)
        .sum(),
    super::inlined!("blur_linear", blur_linear)
        .params(&[
            p("blur_linear_length", 0.0),
            p_cyclic("blur_linear_angle", 0.0, 0.0, TAU),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_blur_linear),
    super::inlined!("blur_pixelize", blur_pixelize)
        .params(&[
            p_range("blur_pixelize_size", 0.1, f64::EPSILON, f64::INFINITY),
            p("blur_pixelize_scale", 1.0),
        ])
        .flags(flag::RANDOM | flag::USES_Z | flag::WRITES_Z)
        .prepare(prep_blur_pixelize),
    super::inlined!("blur_square", blur_square)
        .flags(flag::RANDOM)
        .sum(),
    super::inlined!("circleblur", circleblur)
        .flags(flag::RANDOM)
        .sum(),
    super::inlined!("gaussian", gaussian).flags(flag::RANDOM),
    super::inlined!("nBlur", nblur)
        .params(&[
            p_int("nBlur_numEdges", 3.0, -NBLUR_MAX, NBLUR_MAX).limited(),
            p_int("nBlur_numStripes", 0.0, -NBLUR_MAX, NBLUR_MAX).limited(),
            p_range("nBlur_ratioStripes", 1.0, 0.0, 2.0),
            p_range("nBlur_ratioHole", 0.0, 0.0, 1.0),
            p_int("nBlur_circumCircle", 0.0, 0.0, 1.0),
            p_int("nBlur_adjustToLinear", 1.0, 0.0, 1.0),
            p_int("nBlur_equalBlur", 1.0, 0.0, 1.0),
            p_int("nBlur_exactCalc", 0.0, 0.0, 1.0),
            p("nBlur_highlightEdges", 1.0),
        ])
        .flags(flag::RANDOM)
        .prepare(prep_nblur),
    super::inlined!("sineblur", sineblur)
        .params(&[p_range("sineblur_power", 1.0, 0.0, INF)])
        .flags(flag::RANDOM)
        .sum(),
    super::inlined!("sphereblur", sphereblur)
        .params(&[p_range("sphereblur_power", 1.0, 0.0, INF)])
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
    super::inlined!("square3D", square3d)
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
    super::inlined!("starblur", starblur)
        .params(&[
            p("starblur_power", 5.0),
            p("starblur_range", 0.401_622_831_7),
        ])
        .flags(flag::RANDOM)
        .prepare(starblur_prep)
        .sum(),
    super::inlined!("starblur2", starblur2)
        .params(&[
            p("starblur2_power", 5.0),
            p("starblur2_range", 0.401_622_831_772_454_56),
            p("starblur2_hole", 0.5),
            p("starblur2_stripes", 5.0),
            p("starblur2_width", 0.2),
        ])
        .flags(flag::RANDOM)
        .prepare(starblur2_prep),
    super::inlined!("zblur", zblur)
        .flags(flag::RANDOM | flag::WRITES_Z)
        .sum(),
];

/// A random point of the ball of radius 2w (the sum of four uniforms sets the radius, two
/// random angles the direction).
#[inline(always)]
fn blur3d<R: Draws>(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut R) -> V3 {
    let azimuth = rng.f01() * TAU;
    let r = v.w * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
    let polar = rng.f01() * PI;
    let (sa, ca) = fastmath::sin_cos(azimuth);
    let (sp, cp) = fastmath::sin_cos(polar);
    [r * sp * ca, r * sp * sa, r * cp]
}

/// A uniform point of the square [−1, 1]² mapped onto the disc of radius w (squares of
/// half-side s go to circles of radius s); z is scaled.
#[inline(always)]
fn blur_circle<R: Draws>(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut R) -> V3 {
    let x = 2.0 * rng.f01() - 1.0;
    let y = 2.0 * rng.f01() - 1.0;
    let (side, per) = square_arc(x, y);
    let r = v.w * side;
    let (s, c) = (FRAC_PI_4 * per / side - FRAC_PI_4).fsin_cos();
    [r * c, r * s, v.w * t.z]
}

/// A random point inside a heart-shaped outline |x|^p, ±√(1 − x²) (scaled by a and b).
#[inline(always)]
fn blur_heart(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [pw, a, b] = v.params();
    let x = (rng.f01() - 0.5) * 2.0;
    let mut y = (rng.f01() - 0.5) * 2.0;
    let k = sign_nz(y);
    let lim =
        ((a * x.abs().powf(pw) + k * b * (1.0 - x * x).abs().sqrt()) - a) / zeps(a.abs() + b.abs());
    if k > 0.0 {
        if y > lim {
            y = lim;
        }
    } else if y < lim {
        y = lim;
    }
    [x * v.w, y * v.w, 0.0]
}

/// Derived values: sin and cos of the angle.
fn prep_blur_linear(v: &mut Prepared) {
    let [_, angle] = v.params();
    let (s, c) = angle.fsin_cos();
    v.p.push(s);
    v.p.push(c);
}

/// Motion blur: the point is pushed a random distance up to `length` along a fixed direction.
#[inline(always)]
fn blur_linear(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [length] = v.params();
    let [s, c] = v.derived();
    let d = length * rng.f01();
    [v.w * (t.x + d * c), v.w * (t.y + d * s), 0.0]
}

/// Derived values: w·size, 1/size.
fn prep_blur_pixelize(v: &mut Prepared) {
    let [size] = v.params();
    let size = zeps(size);
    v.p.push(v.w * size);
    v.p.push(1.0 / size);
}

/// Pixelation: the point goes to a random spot of the grid cell (of side `size`) it falls in,
/// the spot's spread set by `scale`.
#[inline(always)]
fn blur_pixelize(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, sc] = v.params();
    let [k, inv] = v.derived();
    let cx = floor_i64(t.x * inv) as f64;
    let cy = floor_i64(t.y * inv) as f64;
    [
        k * (cx + sc * (rng.f01() - 0.5) + 0.5),
        k * (cy + sc * (rng.f01() - 0.5) + 0.5),
        v.w * t.z,
    ]
}

/// A uniform point of the square [−w, w]².
#[inline(always)]
fn blur_square(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let k = 2.0 * v.w;
    [k * (rng.f01() - 0.5), k * (rng.f01() - 0.5), 0.0]
}

/// A uniform random point of the disc of radius w.
#[inline(always)]
fn circleblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let rad = rng.f01().sqrt();
    let (s, c) = (rng.f01() * TAU).fsin_cos();
    [v.w * c * rad, v.w * s * rad, 0.0]
}

/// Adds a roughly Gaussian offset (sum of four uniforms) in a random direction to the point.
#[inline(always)]
fn gaussian(v: &Prepared, t: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let ang = rng.f01() * TAU;
    let spread = rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0;
    let k = v.w * spread;
    let (s, c) = ang.fsin_cos();
    [k * c + t.x, k * s + t.y, 0.0]
}

/// Derived values: exact, circum, the sine and cosine of half a sector, the weight (adjusted to
/// linear), edges (at least 3), the hole ratio, the sector angle, the stripes' start and width,
/// has/negative stripes, the most stripes, tan(π/2 + sector/2), the two highlight arctangent
/// factors, the complement of the stripe ratio and the two stripe speeds.
fn prep_nblur(v: &mut Prepared) {
    let [
        edges,
        stripes,
        ratio_stripes,
        ratio_hole,
        circum,
        adjust,
        _,
        exact,
        highlight,
    ] = v.params();
    let edges = if edges < 3.0 { 3.0 } else { edges };
    let (mut ratio_hole, mut exact, mut highlight) = (ratio_hole, exact, highlight);
    let has_stripes = stripes != 0.0;
    let neg_stripes = stripes < 0.0;
    let abs_stripes = stripes.abs();
    let mid = TAU / edges;
    let (mut ang_stripes, mut ang_start, mut complement) = (0.0, 0.0, 0.0);
    if has_stripes {
        ang_stripes = mid / (2.0 * abs_stripes);
        ang_start = ang_stripes / 2.0;
        complement = 2.0 - ratio_stripes;
    }
    if ratio_hole > 0.95 && exact == 1.0 && circum == 0.0 {
        ratio_hole = 0.95;
    }
    let tan90m2 = (FRAC_PI_2 + mid / 2.0).tan();
    let (sin_h, cos_h) = ((mid / 2.0).fsin(), (mid / 2.0).fcos());
    if highlight <= 0.1 {
        highlight = 0.1;
    }
    let weight = if adjust == 1.0 {
        let steps = if (edges as i32) % 4 == 0 {
            edges / 2.0 - 1.0
        } else {
            (edges / 2.0).floor()
        };
        v.w / zeps((2.0 - 2.0 * (mid * steps).fcos()).sqrt() / 2.0)
    } else {
        v.w
    };
    if circum == 1.0 {
        exact = 0.0;
        highlight = 0.1;
    }
    let speed1 = complement * ang_start;
    let speed2 = ratio_stripes * ang_start;
    let max_stripes = 2.0 * abs_stripes;
    let spread = if neg_stripes { 7.5 } else { 13.0 };
    let atan1 = (spread / edges.powf(1.3)) * highlight;
    let atan2 = 2.0 * (atan1 / -2.0).atan();
    let flag = |b: bool| if b { 1.0 } else { 0.0 };
    v.p.extend_from_slice(&[
        exact,
        circum,
        sin_h,
        cos_h,
        weight,
        edges,
        ratio_hole,
        mid,
        ang_start,
        ang_stripes,
        flag(has_stripes),
        flag(neg_stripes),
        max_stripes,
        tan90m2,
        atan1,
        atan2,
        complement,
        speed1,
        speed2,
    ]);
}

/// One random point of nBlur's polygon: its (sin, cos)-ordered coordinates and the inner and
/// outer edge distances in its direction.
struct NbSample {
    x: f64,
    y: f64,
    inner: f64,
    outer: f64,
    len: f64,
}

/// Draw one point in nBlur's polygon (possibly striped, with a hole).
fn nblur_sample(v: &Prepared, rng: &mut FastRng) -> NbSample {
    let [_, _, ratio_stripes, _, _, _, equal] = v.params();
    let [
        exact,
        circum,
        _sin_h,
        _cos_h,
        _weight,
        edges,
        ratio_hole,
        mid,
        ang_start,
        ang_stripes,
        has_stripes,
        neg_stripes,
        max_stripes,
        tan90m2,
        atan1,
        atan2,
        ratio_complement,
        speed1,
        speed2,
    ] = v.derived();
    let exact = exact == 1.0;
    let circum = circum == 1.0;
    let equal = equal == 1.0;
    let mut ang = if exact {
        rng.f01() * TAU
    } else {
        ((atan1 * (rng.f01() - 0.5)).atan() / atan2 + 0.5 + rand_size(rng, edges)) * mid
    };
    // Note: x takes the sine and y the cosine of the direction.
    let (mut x, mut y) = (ang.fsin(), ang.fcos());
    let mut mem = ang;
    while ang > mid {
        ang -= mid;
    }
    if has_stripes == 1.0 {
        let neg = neg_stripes == 1.0;
        // The negative-stripe mode swaps the roles of the stripe ratio and its complement, and
        // of which stripe parity gets shifted and which gets rescaled.
        let (ratio, speed) = if neg {
            (ratio_complement, speed1)
        } else {
            (ratio_stripes, speed2)
        };
        let shifted = if neg { 0 } else { 1 };
        let mut count = 0i32;
        let mut edge = ang_start;
        while ang > edge {
            edge += ang_stripes;
            if edge > mid {
                edge = mid;
            }
            count += 1;
        }
        if edge != mid {
            edge -= ang_start;
        }
        let at_last = |count: i32| count as f64 == max_stripes;
        if count & 1 == shifted {
            let forward = ang > edge && (!neg || !at_last(count));
            if forward {
                ang += ang_start;
                mem += ang_start;
                edge += ang_stripes;
                count += 1;
            } else {
                ang -= ang_start;
                mem -= ang_start;
                edge -= ang_stripes;
                count -= 1;
            }
            (x, y) = (mem.fsin(), mem.fcos());
        }
        let rescaled = count & 1 != shifted;
        if rescaled && ratio > 1.0 {
            if ang > edge && !at_last(count) {
                mem = mem - ang + edge + (ang - edge) / ang_start * ratio * ang_start;
            } else {
                mem = mem - ang + edge - (edge - ang) / ang_start * ratio * ang_start;
            }
            ang = edge + (ang - edge) / ang_start * ratio * ang_start;
            (x, y) = (mem.fsin(), mem.fcos());
        }
        if rescaled && ratio < 1.0 {
            let squeeze_down = |ang: f64, edge: f64| {
                let num = (edge - speed - ang) * speed;
                num / (ang_start - speed)
            };
            if (ang - edge).abs() > speed && !at_last(count) {
                if ang - edge > speed {
                    let num = (ang - (edge + speed)) * speed;
                    let k = num / (ang_start - speed);
                    let a = mem - ang + edge + k;
                    (x, y) = (a.fsin(), a.fcos());
                    ang = edge + k;
                }
                if edge - ang > speed {
                    let k = squeeze_down(ang, edge);
                    let a = mem - ang + edge - k;
                    (x, y) = (a.fsin(), a.fcos());
                    ang = edge - k;
                }
            }
            if at_last(count) {
                if neg {
                    edge = mid;
                }
                if edge - ang > speed {
                    let k = squeeze_down(ang, edge);
                    let a = mem - ang + edge - k;
                    (x, y) = (a.fsin(), a.fcos());
                    ang = edge - k;
                }
            }
        }
    }
    let tan_ang = ang.tan();
    let ex = tan90m2 / (tan90m2 - tan_ang);
    let ey = ex * tan_ang;
    let outer = (ex * ex + ey * ey).sqrt();
    let draw = |rng: &mut FastRng| {
        if equal { rng.f01().sqrt() } else { rng.f01() }
    };
    let mut radius = if exact || circum {
        draw(rng)
    } else {
        draw(rng) * outer
    };
    let inner = ratio_hole * outer;
    if !exact && radius < inner {
        radius = if circum {
            inner + draw(rng) * (1.0 - inner + f64::EPSILON)
        } else {
            inner + draw(rng) * (outer - inner)
        };
    }
    x *= radius;
    y *= radius;
    NbSample {
        x,
        y,
        inner,
        outer,
        len: (x * x + y * y).sqrt(),
    }
}

/// nBlur: a blur filling a regular polygon (optionally striped, with a central hole,
/// highlighted edges, or its circumcircle), turned by half a sector.
#[inline(always)]
fn nblur(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [exact, circum, sn, cs, weight] = v.derived();
    let mut s = nblur_sample(v, rng);
    if exact == 1.0 && circum == 0.0 {
        while s.len < s.inner || s.len > s.outer {
            s = nblur_sample(v, rng);
        }
    }
    let x = cs * s.x - sn * s.y;
    let y = sn * s.x + cs * s.y;
    [weight * x, weight * y, 0.0]
}

/// A uniform number in [0, 1) raised to the power `pw` (drawn as e^(pw·ln u); u itself when
/// pw = 1): the radial profile of sineblur and sphereblur.
#[inline(always)]
fn powered_unit(rng: &mut FastRng, pw: f64) -> f64 {
    if pw == 1.0 {
        rng.f01()
    } else {
        (rng.f01().ln() * pw).exp()
    }
}

/// A disc of radius w filled with a density that follows acos (denser at the rim); `power`
/// reshapes the radial profile.
#[inline(always)]
fn sineblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let (s, c) = (rng.f01() * TAU).fsin_cos();
    let u = powered_unit(rng, power);
    let r = v.w * ((u * 2.0 - 1.0).acos() / PI);
    [r * c, r * s, 0.0]
}

/// A solid ball of radius w in 3-D, random direction, with an acos radial profile shaped by
/// `power`.
#[inline(always)]
fn sphereblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let ang = rng.f01() * TAU;
    let polar = (rng.f01() * 2.0 - 1.0).acos();
    let u = powered_unit(rng, power);
    let r = v.w * (((u * 2.0 - 1.0).acos() / PI).ln() / 1.5).exp();
    let (s, c) = ang.fsin_cos();
    let (sz, cz) = polar.fsin_cos();
    [r * c * sz, r * s * sz, r * cz]
}

/// A uniformly filled cube of side w centred on the origin.
#[inline(always)]
fn square3d(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let x = v.w * (rng.f01() - 0.5);
    let y = v.w * (rng.f01() - 0.5);
    let z = v.w * (rng.f01() - 0.5);
    [x, y, z]
}

/// A filled star with `power` points (`range` sets how deep the notches are), drawn
/// independently of the input.
#[inline(always)]
fn starblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [power] = v.params();
    let [len, step, sin_a, cos_a] = v.derived();
    let f = rng.f01() * power * 2.0;
    let i = trunc_i32(f);
    let x = (f - i as f64) * len;
    let mut z = (1.0 + x * x - 2.0 * x * cos_a).sqrt();
    let turn = sin_a * x / z;
    let base = step * (i / 2) as f64;
    let angle = if i & 1 != 0 {
        base + turn.asin()
    } else {
        base - turn.asin()
    };
    z *= rng.f01().sqrt();
    let a = angle - FRAC_PI_2;
    [v.w * z * a.fcos(), v.w * z * a.fsin(), 0.0]
}

fn starblur_prep(v: &mut Prepared) {
    let [power, range] = v.params();
    let half = PI / power;
    let len = (1.0 + range * range - 2.0 * range * half.fcos()).sqrt();
    let alpha = (half.fsin() * range / len).asin();
    v.p.extend([len, TAU / power, alpha.fsin(), alpha.fcos()]);
}

/// starblur with a hole in the middle (`hole`) and each point's edge split into `stripes`
/// stripes of relative `width`.
#[inline(always)]
fn starblur2(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, width] = v.params();
    let [len, hole2, fill2, step, power2, sin_a, cos_a2, stripes] = v.derived();
    let k = rng.f01() * power2;
    let whole = floor_f(k);
    let f = k - whole;
    let ff = if stripes > 0.0 {
        let g = f * stripes;
        let fs = g.trunc();
        let dif = if whole % 2.0 == 0.0 {
            width * (g - fs)
        } else {
            1.0 - width * (g - fs)
        };
        (dif + fs) / stripes
    } else {
        f
    };
    let x = ff * len;
    let z = zeps((1.0 + x * x - x * cos_a2).sqrt());
    // The parity and half of the sector index, in 64-bit integer arithmetic.
    let wi = whole as i64;
    let odd = wi.wrapping_sub((floor_f(k / 2.0) as i64).wrapping_mul(2)) == 1;
    let sign = if odd { 1.0 } else { -1.0 };
    let angle = step * (wi / 2) as f64 + sign * (sin_a * x / z).asin() - FRAC_PI_2;
    let r = v.w * (z * (rng.f01() * fill2 + hole2).sqrt());
    [angle.fcos() * r, angle.fsin() * r, 0.0]
}

fn starblur2_prep(v: &mut Prepared) {
    let [power, range, hole, stripes] = v.params();
    let pz = zeps(power);
    let half = PI / pz;
    let len = (1.0 + range * range - 2.0 * range * half.fcos()).sqrt();
    let alpha = (half.fsin() * range / zeps(len)).asin();
    let hole2 = sqr(hole.abs().min(1.0));
    v.p.extend([
        len,
        hole2,
        1.0 - hole2,
        TAU / pz,
        power * 2.0,
        alpha.fsin(),
        alpha.fcos() * 2.0,
        zeps(stripes.abs()),
    ]);
}

/// zblur: a random z offset (sum of four uniforms, bell-shaped in [−2, 2]·weight).
#[inline(always)]
fn zblur(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let s = rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0;
    [0.0, 0.0, v.w * s]
}
