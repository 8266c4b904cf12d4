//! The formulas of flam3's variations, one match arm per variation, as flam3 computes them
//! (with the z that Fractorium's 3-D extension gives them).

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use super::ids::*;
use crate::flame::affine::Affine;
use crate::flame::fastmath as fm;
use crate::flame::rng::FastRng;
use crate::flame::variations::util::{rand_size, zeps};

use crate::flame::variations::{Dialect, EPS, Form, Prepared, VarIn};

/// Where a formula takes its random numbers: the generator itself, or the numbers a batch
/// loop drew for its whole batch beforehand ([`Drawn`], in the same order, so both give the
/// same bits). The defaults are [`FastRng`]'s own conversions. Fractorium's formulas that draw
/// a fixed number of numbers per point take it too (`batch_with_draws`).
pub(crate) trait Draws {
    fn u64(&mut self) -> u64;
    #[inline(always)]
    fn f01(&mut self) -> f64 {
        u64_to_f64(self.u64() >> 11) * (1.0 / (1u64 << 53) as f64)
    }
    /// Uniform in [−1, 1), as [`FastRng::f11`].
    #[inline(always)]
    fn f11(&mut self) -> f64 {
        self.f01() * 2.0 - 1.0
    }
    /// An integer in 0..n, as [`FastRng::below`] (the high half of the 128-bit product).
    #[inline(always)]
    fn below(&mut self, n: u64) -> u64 {
        mul_high(self.u64(), n)
    }
    #[inline(always)]
    fn bit(&mut self) -> bool {
        (self.u64() >> 63) != 0
    }
    /// [`rand_size`]: an integer in 0..n from one draw.
    #[inline(always)]
    fn rand_size(&mut self, n: f64) -> f64 {
        let (u, k) = (self.u64(), n as u64);
        // Both outcomes computed and one selected, without a 128-bit multiply: the loop over a
        // batch then vectorises.
        let below = u64_to_f64(mul_high(u, k));
        let full = u32_to_f64(u >> 32);
        if k == 0 { full } else { below }
    }
}

/// The high 64 bits of the 128-bit product a·b, from four 32×32→64 multiplies (which vector
/// units have; a 64×64→128 multiply they have not).
#[inline(always)]
fn mul_high(a: u64, b: u64) -> u64 {
    const M: u64 = 0xFFFF_FFFF;
    let (al, ah, bl, bh) = (a & M, a >> 32, b & M, b >> 32);
    // Wrapping operations only to keep overflow checks out of the loop: no product of two
    // 32-bit halves and no sum here exceeds 2⁶⁴.
    let (ll, lh) = (al.wrapping_mul(bl), al.wrapping_mul(bh));
    let (hl, hh) = (ah.wrapping_mul(bl), ah.wrapping_mul(bh));
    let mid = (ll >> 32).wrapping_add(lh & M).wrapping_add(hl & M);
    hh.wrapping_add(lh >> 32)
        .wrapping_add(hl >> 32)
        .wrapping_add(mid >> 32)
}

/// An integer below 2³² (held in a u64) as a double, exactly: its bits placed in the mantissa
/// of 2⁵², which is then subtracted. Vector units without AVX-512DQ cannot convert 64-bit
/// integers; this needs only bit operations and one subtraction.
#[inline(always)]
fn u32_to_f64(k: u64) -> f64 {
    const TWO_52: u64 = 0x4330_0000_0000_0000;
    f64::from_bits(TWO_52 | (k & 0xFFFF_FFFF)) - f64::from_bits(TWO_52)
}

/// A u64 as a double, rounded to nearest as `as f64` rounds: the two 32-bit halves convert
/// exactly, the high one's scaling by 2³² is exact, and their sum rounds once.
#[inline(always)]
fn u64_to_f64(k: u64) -> f64 {
    u32_to_f64(k >> 32) * 4_294_967_296.0 + u32_to_f64(k)
}

impl Draws for FastRng {
    #[inline(always)]
    fn u64(&mut self) -> u64 {
        FastRng::u64(self)
    }
    #[inline(always)]
    fn f01(&mut self) -> f64 {
        FastRng::f01(self)
    }
    #[inline(always)]
    fn bit(&mut self) -> bool {
        FastRng::bit(self)
    }
    #[inline(always)]
    fn rand_size(&mut self, n: f64) -> f64 {
        rand_size(self, n)
    }
}

/// The most raw draws one point of a flam3 variation takes (gaussian_blur's five).
pub(super) const MAX_DRAWS: usize = 5;

/// The raw 64-bit draws of one point, drawn beforehand, read in order.
pub(super) struct Drawn<'a> {
    pub(super) d: &'a [u64; MAX_DRAWS],
    pub(super) pos: usize,
}

impl Draws for Drawn<'_> {
    #[inline(always)]
    fn u64(&mut self) -> u64 {
        let u = self.d[self.pos];
        self.pos += 1;
        u
    }
}

/// How many raw draws one point of variation `id` takes, for the variations that draw a fixed
/// number whatever the point (0 for the others and for those that draw none): their batch
/// loops draw them for the whole batch first, so that the formula's loop carries nothing from
/// point to point and vectorises.
pub(super) const fn draws(id: u16) -> usize {
    match id {
        JULIA | JULIAN | JULIASCOPE | ARCH | RAYS | BLADE | TWINTRIAN | SUPER_SHAPE | FLOWER
        | CONIC | BOARDERS | CPOW | WEDGE_JULIA => 1,
        NOISE | BLUR | SQUARE | PARABOLA => 2,
        PIE => 3,
        RADIAL_BLUR => 4,
        GAUSSIAN_BLUR => 5,
        _ => 0,
    }
}

#[inline(always)]
fn sincos(a: f64) -> (f64, f64) {
    fm::sin_cos(a)
}

/// √(1 + u) − 1 without cancellation for small u.
#[inline(always)]
fn sqrt1pm1(u: f64) -> f64 {
    u / ((1.0 + u).sqrt() + 1.0)
}

/// The output z (Fractorium extends flam3's variations to 3-D points): most carry w·z along,
/// a few compute a z of their own; the others leave it to the framework (0 for a regular
/// variation). A flame whose variations are all flam3's never feeds z back into x and y.
#[inline(always)]
pub(super) fn z_out(id: u16, v: &Prepared, t: &VarIn) -> f64 {
    match id {
        LINEAR | SINUSOIDAL | SPHERICAL | SWIRL | HORSESHOE | POLAR | DISC | SPIRAL
        | HYPERBOLIC | PDJ | FAN2 | RINGS2 | EYEFISH | NOISE | JULIAN | JULIASCOPE | BLUR
        | GAUSSIAN_BLUR | RADIAL_BLUR | NGON | RECTANGLES | SQUARE | CROSS | ESCHER | FOCI
        | LAZYSUSAN | LOONIE | POLAR2 | SEPARATION | SPLITS | WEDGE | LOG | AUGER | MOBIUS => {
            v.w * t.z
        }
        BUBBLE => v.w * (2.0 / zeps((0.25 * t.sumsq + 1.0) - 1.0)),
        CYLINDER => v.w * t.x.cos(),
        WAVES2 => {
            let [_, _, _, _, freqz, scalez] = v.params();
            v.w * (t.z + scalez * (t.sqrt * freqz).sin())
        }
        FLUX => t.z,
        BIPOLAR => {
            let g = t.sumsq + 1.0 - 2.0 * t.x;
            let fg = (t.sumsq + 1.0 + 2.0 * t.x) / zeps(g);
            if g == 0.0 || fg <= 0.0 {
                if v.compat && v.form == Form::Regular {
                    0.0
                } else {
                    t.z
                }
            } else {
                v.w * t.z
            }
        }
        _ => 0.0,
    }
}

/// Variation `id`'s contribution at `t`. `compat` is `v.compat`, passed apart so that a batch
/// loop can fix it for the whole loop (a branch on it inside the loop stops vectorisation).
#[inline(always)]
pub(super) fn formula(
    id: u16,
    v: &Prepared,
    t: &VarIn,
    aff: &Affine,
    rng: &mut impl Draws,
    compat: bool,
) -> (f64, f64) {
    let w = v.w;
    let (x, y) = (t.x, t.y);
    match id {
        LINEAR => (w * x, w * y),
        SINUSOIDAL => (w * fm::sin(x), w * fm::sin(y)),
        SPHERICAL => {
            let r2 = w / zeps(t.sumsq);
            (r2 * x, r2 * y)
        }
        SWIRL => {
            let (s, c) = sincos(t.sumsq);
            (w * (s * x - c * y), w * (c * x + s * y))
        }
        HORSESHOE => {
            let r = w / zeps(t.sqrt);
            ((x - y) * (x + y) * r, 2.0 * x * y * r)
        }
        POLAR => {
            // Guard of Fraktalai kept by ugnis: θ = 0 at the origin.
            let a = if x.abs() <= EPS && y.abs() <= EPS {
                0.0
            } else {
                t.atan_xy
            };
            (w * a / PI, w * (t.sqrt - 1.0))
        }
        HANDKERCHIEF => {
            let a = t.atan_xy;
            let r = t.sqrt;
            (w * r * fm::sin(a + r), w * r * fm::cos(a - r))
        }
        HEART => {
            let a = t.sqrt * t.atan_xy;
            let (s, c) = sincos(a);
            let r = w * t.sqrt;
            (r * s, -r * c)
        }
        DISC => {
            let a = t.atan_xy / PI;
            let (s, c) = sincos(PI * t.sqrt);
            (w * s * a, w * c * a)
        }
        SPIRAL => {
            let r = zeps(t.sqrt);
            let r1 = w / r;
            let (s, c) = sincos(r);
            (r1 * (t.uy + s), r1 * (t.ux - c))
        }
        HYPERBOLIC => {
            let r = zeps(t.sqrt);
            (w * t.ux / r, w * t.uy * r)
        }
        DIAMOND => {
            let (s, c) = sincos(t.sqrt);
            (w * t.ux * c, w * t.uy * s)
        }
        EX => {
            let a = t.atan_xy;
            let r = t.sqrt;
            let n0 = fm::sin(a + r);
            let n1 = fm::cos(a - r);
            let m0 = n0 * n0 * n0 * r;
            let m1 = n1 * n1 * n1 * r;
            (w * (m0 + m1), w * (m0 - m1))
        }
        JULIA => {
            let mut a = 0.5 * t.atan_xy;
            if rng.bit() {
                a += PI;
            }
            let r = w * t.sqrt.sqrt();
            let (s, c) = sincos(a);
            (r * c, r * s)
        }
        BENT => {
            let nx = if x < 0.0 { 2.0 * x } else { x };
            let ny = if y < 0.0 { y / 2.0 } else { y };
            (w * nx, w * ny)
        }
        WAVES => {
            let dx2 = 1.0 / zeps(aff.e * aff.e);
            let dy2 = 1.0 / zeps(aff.f * aff.f);
            (
                w * (x + aff.b * fm::sin(y * dx2)),
                w * (y + aff.d * fm::sin(x * dy2)),
            )
        }
        FISHEYE => {
            let r = 2.0 * w / (t.sqrt + 1.0);
            (r * y, r * x)
        }
        POPCORN => {
            let dx = fm::tan(3.0 * y);
            let dy = fm::tan(3.0 * x);
            (w * (x + aff.e * fm::sin(dx)), w * (y + aff.f * fm::sin(dy)))
        }
        EXPONENTIAL => {
            let d = w * (x - 1.0).exp();
            let (s, c) = sincos(PI * y);
            (d * c, d * s)
        }
        POWER => {
            let r = w * fm::pow_nonneg(t.sqrt, t.ux);
            (r * t.uy, r * t.ux)
        }
        COSINE => {
            let a = x * PI;
            let (s, c) = sincos(a);
            (w * c * fm::cosh(y), -w * s * fm::sinh(y))
        }
        RINGS => {
            let dx = zeps(aff.e * aff.e);
            let r = t.sqrt;
            let r = w * (fm::fmod(r + dx, 2.0 * dx) - dx + r * (1.0 - dx));
            (r * t.uy, r * t.ux)
        }
        FAN => {
            let dx = PI * zeps(aff.e * aff.e);
            let dx2 = 0.5 * dx;
            let mut a = t.atan_xy;
            let r = w * t.sqrt;
            a += if fm::fmod(a + aff.f, dx) > dx2 {
                -dx2
            } else {
                dx2
            };
            let (s, c) = sincos(a);
            (r * c, r * s)
        }
        BLOB => {
            let [low, high, waves] = v.params();
            let r = t.sqrt * (low + (high - low) * (0.5 + 0.5 * fm::sin(waves * t.atan_xy)));
            (w * t.ux * r, w * t.uy * r)
        }
        PDJ => {
            let [a, b, c, d] = v.params();
            let nx1 = fm::cos(b * x);
            let nx2 = fm::sin(a * y);
            let ny1 = fm::sin(c * x);
            let ny2 = fm::cos(d * y);
            (w * (nx2 - nx1), w * (ny1 - ny2))
        }
        FAN2 => {
            let [_, fan_y] = v.params();
            let [dx, dx2] = v.derived();
            let mut a = t.atan_xy;
            let r = w * t.sqrt;
            if fm::fmod(a + fan_y, dx) > dx2 {
                a -= dx2;
            } else {
                a += dx2;
            }
            let (s, c) = sincos(a);
            if compat {
                (r * s, r * c)
            } else {
                (r * c, r * s)
            }
        }
        RINGS2 => {
            let [dx] = v.derived();
            let mut r = t.sqrt;
            r += -2.0 * dx * ((r + dx) / (2.0 * dx)).trunc() + r * (1.0 - dx);
            (w * t.ux * r, w * t.uy * r)
        }
        EYEFISH => {
            let r = 2.0 * w / (t.sqrt + 1.0);
            (r * x, r * y)
        }
        BUBBLE => {
            let r = w / (0.25 * t.sumsq + 1.0);
            (r * x, r * y)
        }
        CYLINDER => (w * fm::sin(x), w * y),
        PERSPECTIVE => {
            let [_, dist] = v.params();
            let [vsin, vfcos] = v.derived();
            let d = w / zeps(dist - y * vsin);
            (d * dist * x, d * vfcos * y)
        }
        NOISE => {
            let a = rng.f01() * 2.0 * PI;
            let (s, c) = sincos(a);
            let r = w * rng.f01();
            (x * r * c, y * r * s)
        }
        JULIAN => {
            let [power] = v.params();
            let [abs_power, cn] = v.derived();
            let r = w * fm::pow_nonneg(t.sumsq, cn);
            let a = if compat {
                let k = rng.rand_size(abs_power);
                (t.atan_yx + 2.0 * PI * k) / power
            } else {
                let root = (power * rng.f01()).trunc();
                (t.atan_yx + root * 2.0 * PI) / power
            };
            let (s, c) = sincos(a);
            (r * c, r * s)
        }
        JULIASCOPE => {
            let [power] = v.params();
            let [abs_power, cn] = v.derived();
            let r = w * fm::pow_nonneg(t.sumsq, cn);
            let a = if compat {
                let k = (abs_power * rng.f01()).trunc();
                // k's parity in floating point (exact below 2⁵³), which vectorises.
                if k - 2.0 * (k * 0.5).floor() == 0.0 {
                    (2.0 * PI * k + t.atan_yx) / power
                } else {
                    (2.0 * PI * k - t.atan_yx) / power
                }
            } else {
                // Roots alternate between the angle and its mirror image.
                let root = (power * rng.f01()).floor();
                let odd = root - 2.0 * (root * 0.5).floor() == 1.0;
                let sgn = if odd { -1.0 } else { 1.0 };
                (t.atan_yx * sgn + root * 2.0 * PI) / zeps(power)
            };
            let (s, c) = sincos(a);
            (r * c, r * s)
        }
        BLUR => {
            let a = rng.f01() * 2.0 * PI;
            let (s, c) = sincos(a);
            let r = w * rng.f01();
            (r * c, r * s)
        }
        GAUSSIAN_BLUR => {
            let a = rng.f01() * 2.0 * PI;
            let (s, c) = sincos(a);
            let r = w * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
            (r * c, r * s)
        }
        RADIAL_BLUR => {
            let [spin, zoom] = v.derived();
            let rnd_g = w * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
            let ra = t.sqrt;
            let tmpa = t.atan_yx + spin * rnd_g;
            let (s, c) = sincos(tmpa);
            let rz = zoom * rnd_g - 1.0;
            (ra * c + rz * x, ra * s + rz * y)
        }
        PIE => {
            let [slices, rotation, thickness] = v.params();
            let sl = (rng.f01() * slices + 0.5).trunc();
            let a = rotation + 2.0 * PI * (sl + rng.f01() * thickness) / slices;
            let r = w * rng.f01();
            let (s, c) = sincos(a);
            (r * c, r * s)
        }
        NGON => {
            let [_, _, circle, corners] = v.params();
            let [half_neg_power, b, inv_sector] = v.derived();
            let r_factor = if x == 0.0 && y == 0.0 {
                0.0
            } else {
                t.sumsq.powf(half_neg_power)
            };
            let mut phi = t.atan_yx - b * (t.atan_yx * inv_sector).floor();
            if phi > 0.5 * b {
                phi -= b;
            }
            let amp = (corners * (1.0 / fm::cos(phi) - 1.0) + circle) * w * r_factor;
            (amp * x, amp * y)
        }
        CURL => {
            let [c1, c2] = v.params();
            let re = 1.0 + c1 * x + c2 * (x * x - y * y);
            let im = (c1 + 2.0 * c2 * x) * y;
            let r = w / zeps(re * re + im * im);
            ((x * re + y * im) * r, (y * re - x * im) * r)
        }
        RECTANGLES => {
            let [rx, ry] = v.params();
            let nx = if rx == 0.0 {
                x
            } else {
                (2.0 * (x / rx).floor() + 1.0) * rx - x
            };
            let ny = if ry == 0.0 {
                y
            } else {
                (2.0 * (y / ry).floor() + 1.0) * ry - y
            };
            (w * nx, w * ny)
        }
        ARCH => {
            let ang = rng.f01() * w * PI;
            let (s, c) = sincos(ang);
            (w * s, w * s * s / c)
        }
        TANGENT => (w * fm::sin(x) / fm::cos(y), w * fm::tan(y)),
        SQUARE => (w * (rng.f01() - 0.5), w * (rng.f01() - 0.5)),
        RAYS => {
            let ang = w * rng.f01() * PI;
            let r = w / zeps(t.sumsq);
            let tanr = w * fm::tan(ang) * r;
            (tanr * fm::cos(x), tanr * fm::sin(y))
        }
        BLADE => {
            let r = rng.f01() * w * t.sqrt;
            let (s, c) = sincos(r);
            (w * x * (c + s), w * x * (c - s))
        }
        SECANT2 => {
            let r = w * t.sqrt;
            let cr = fm::cos(r);
            let icr = 1.0 / cr;
            let ny = if cr < 0.0 { icr + 1.0 } else { icr - 1.0 };
            (w * x, w * ny)
        }
        TWINTRIAN => {
            let r = rng.f01() * w * t.sqrt;
            let (s, c) = sincos(r);
            let mut diff = (s * s).log10() + c;
            if diff.is_nan() {
                diff = -30.0;
            }
            (w * x * diff, w * x * (diff - s * PI))
        }
        CROSS => {
            let r = if compat {
                w / zeps(((x - y) * (x + y)).abs())
            } else {
                w / zeps(x * x - y * y)
            };
            (x * r, y * r)
        }
        DISC2 => {
            let [time_pi, sinadd, cosadd] = v.derived();
            let tt = time_pi * (x + y);
            let (s, c) = sincos(tt);
            let r = w * t.atan_xy / PI;
            ((s + cosadd) * r, (c + sinadd) * r)
        }
        SUPER_SHAPE => {
            let [rnd, _, _, n2, n3, holes] = v.params();
            let [m_4, neg_inv_n1] = v.derived();
            let theta = m_4 * t.atan_yx + FRAC_PI_4;
            let (st, ct) = sincos(theta);
            let t1 = ct.abs().powf(n2);
            let t2 = st.abs().powf(n3);
            let r =
                w * ((rnd * rng.f01() + (1.0 - rnd) * t.sqrt) - holes) * (t1 + t2).powf(neg_inv_n1)
                    / t.sqrt;
            (r * x, r * y)
        }
        FLOWER => {
            let [petals, holes] = v.params();
            let r = w * (rng.f01() - holes) * fm::cos(petals * t.atan_yx) / t.sqrt;
            (r * x, r * y)
        }
        CONIC => {
            let [ecc, holes] = v.params();
            let z = zeps(t.sqrt);
            let ct = x / z;
            let r = w * (rng.f01() - holes) * ecc / (1.0 + ecc * ct) / z;
            (r * x, r * y)
        }
        PARABOLA => {
            let [height, width] = v.params();
            let (sr, cr) = sincos(t.sqrt);
            (height * w * sr * sr * rng.f01(), width * w * cr * rng.f01())
        }
        BENT2 => {
            let [scale_x, scale_y] = v.params();
            let nx = if x < 0.0 { x * scale_x } else { x };
            let ny = if y < 0.0 { y * scale_y } else { y };
            (w * nx, w * ny)
        }
        BIPOLAR => {
            let [shift_angle, y_scale, x_scale] = v.derived();
            let x2y2 = t.sumsq;
            let tt = x2y2 + 1.0;
            let x2 = 2.0 * x;
            let mut ny = 0.5 * (2.0 * y).atan2(x2y2 - 1.0) + shift_angle;
            if ny > FRAC_PI_2 {
                ny = -FRAC_PI_2 + fm::fmod(ny + FRAC_PI_2, PI);
            } else if ny < -FRAC_PI_2 {
                ny = FRAC_PI_2 - fm::fmod(FRAC_PI_2 - ny, PI);
            }
            let f = tt + x2;
            let g = tt - x2;
            let fg = f / zeps(g);
            if g == 0.0 || fg <= 0.0 {
                // Off the map (on the poles): nothing, or the point itself for pre_/post_ forms
                // and without flam3 compatibility.
                if compat && v.form == Form::Regular {
                    (0.0, 0.0)
                } else {
                    (x, y)
                }
            } else {
                (x_scale * fg.ln(), y_scale * ny)
            }
        }
        BOARDERS => {
            let rx = x.round_ties_even();
            let ry = y.round_ties_even();
            let ox = x - rx;
            let oy = y - ry;
            if rng.f01() >= 0.75 {
                (w * (ox * 0.5 + rx), w * (oy * 0.5 + ry))
            } else if ox.abs() >= oy.abs() {
                if ox >= 0.0 {
                    (
                        w * (ox * 0.5 + rx + 0.25),
                        w * (oy * 0.5 + ry + 0.25 * oy / ox),
                    )
                } else {
                    (
                        w * (ox * 0.5 + rx - 0.25),
                        w * (oy * 0.5 + ry - 0.25 * oy / ox),
                    )
                }
            } else if oy >= 0.0 {
                (
                    w * (ox * 0.5 + rx + ox / oy * 0.25),
                    w * (oy * 0.5 + ry + 0.25),
                )
            } else {
                (
                    w * (ox * 0.5 + rx - ox / oy * 0.25),
                    w * (oy * 0.5 + ry - 0.25),
                )
            }
        }
        BUTTERFLY => {
            let wx = w * 1.302_940_031_741_119_8;
            let y2 = y * 2.0;
            let r = wx * ((y * x).abs() / zeps(x * x + y2 * y2)).sqrt();
            (r * x, r * y2)
        }
        CELL => {
            let [size] = v.params();
            let inv = 1.0 / size;
            let mut cx = (x * inv).floor();
            let mut cy = (y * inv).floor();
            let dx = x - cx * size;
            let dy = y - cy * size;
            if cy >= 0.0 {
                if cx >= 0.0 {
                    cy *= 2.0;
                    cx *= 2.0;
                } else {
                    cy *= 2.0;
                    cx = -(2.0 * cx + 1.0);
                }
            } else if cx >= 0.0 {
                cy = -(2.0 * cy + 1.0);
                cx *= 2.0;
            } else {
                cy = -(2.0 * cy + 1.0);
                cx = -(2.0 * cx + 1.0);
            }
            (w * (dx + cx * size), -w * (dy + cy * size))
        }
        CPOW => {
            let [_, _, power] = v.params();
            let [va, vc, vd] = v.derived();
            let a = t.atan_yx;
            let lnr = 0.5 * t.sumsq.ln();
            let ang = vc * a + vd * lnr + va * (power * rng.f01()).floor();
            let m = w * (vc * lnr - vd * a).exp();
            let (s, c) = sincos(ang);
            (m * c, m * s)
        }
        CURVE => {
            let [xamp, yamp] = v.params();
            let [inv_xlen2, inv_ylen2] = v.derived();
            (
                w * (x + xamp * (-y * y * inv_xlen2).exp()),
                w * (y + yamp * (-x * x * inv_ylen2).exp()),
            )
        }
        EDISC => {
            let tmp = t.sumsq + 1.0;
            let tmp2 = 2.0 * x;
            let r1 = (tmp + tmp2).sqrt();
            let r2 = (tmp - tmp2).sqrt();
            let xmax = zeps((r1 + r2) * 0.5);
            let a1 = (xmax + (xmax - 1.0).sqrt()).ln();
            let a2 = if compat {
                -(x / xmax).clamp(-1.0, 1.0).acos()
            } else {
                (x / xmax).acos()
            };
            let ww = w / 11.57034632;
            let (mut snv, csv) = sincos(a1);
            let snhu = fm::sinh(a2);
            let cshu = fm::cosh(a2);
            if y > 0.0 {
                snv = -snv;
            }
            (ww * cshu * csv, ww * snhu * snv)
        }
        ELLIPTIC => {
            // Written with √(1+u) − 1 and ln(1+u) so that points near the x axis keep their
            // precision.
            let x2 = 2.0 * x;
            let xmaxm1 = 0.5 * (sqrt1pm1(t.sumsq + x2) + sqrt1pm1(t.sumsq - x2));
            let a = x / (1.0 + xmaxm1);
            let ssx = if xmaxm1 < 0.0 { 0.0 } else { xmaxm1.sqrt() };
            let ww = w / FRAC_PI_2;
            let ny = ww * (xmaxm1 + ssx).ln_1p();
            (
                ww * a.clamp(-1.0, 1.0).asin(),
                if y > 0.0 { ny } else { -ny },
            )
        }
        ESCHER => {
            let [vc, vd] = v.derived();
            let a = if compat { t.atan_yx } else { t.atan_xy };
            let lnr = 0.5 * t.sumsq.ln();
            let m = w * (vc * lnr - vd * a).exp();
            let n = vc * a + vd * lnr;
            let (s, c) = sincos(n);
            (m * c, m * s)
        }
        FOCI => {
            let expx = x.exp() * 0.5;
            let expnx = 0.25 / zeps(expx);
            let (sn, cn) = sincos(y);
            let tmp = w / zeps(expx + expnx - cn);
            (tmp * (expx - expnx), tmp * sn)
        }
        LAZYSUSAN => {
            let [spin, space, twist, lx, ly] = v.params();
            let xx = x - lx;
            let yy = y + ly;
            let r = (xx * xx + yy * yy).sqrt();
            // flam3, Apophysis and JWildfire add the centre (x, −y) unweighted; Fractorium
            // weights it too, so that weight 0 collapses to the origin.
            let weighted = v.dialect == Dialect::Fractorium;
            if r < w {
                let a = yy.atan2(xx) + spin + twist * (w - r);
                let (s, c) = sincos(a);
                if weighted {
                    (w * (r * c + lx), w * (r * s - ly))
                } else {
                    (w * r * c + lx, w * r * s - ly)
                }
            } else if weighted {
                let r = 1.0 + space / zeps(r);
                (w * (r * xx + lx), w * (r * yy - ly))
            } else {
                let r = w * (1.0 + space / zeps(r));
                (r * xx + lx, r * yy - ly)
            }
        }
        LOONIE => {
            let [w2] = v.derived();
            let r2 = t.sumsq;
            if r2 < w2 && r2 != 0.0 {
                let r = w * (w2 / r2 - 1.0).sqrt();
                (r * x, r * y)
            } else {
                (w * x, w * y)
            }
        }
        PRE_BLUR => (0.0, 0.0),
        MODULUS => {
            let [mx, my] = v.params();
            let (xr, yr) = (2.0 * mx, 2.0 * my);
            let nx = if x > mx {
                -mx + fm::fmod(x + mx, xr)
            } else if x < -mx {
                mx - fm::fmod(mx - x, xr)
            } else {
                x
            };
            let ny = if y > my {
                -my + fm::fmod(y + my, yr)
            } else if y < -my {
                my - fm::fmod(my - y, yr)
            } else {
                y
            };
            (w * nx, w * ny)
        }
        OSCILLOSCOPE => {
            let [sep, _, amp, damping] = v.params();
            let [tpf] = v.derived();
            let tt = if damping == 0.0 {
                amp * fm::cos(tpf * x) + sep
            } else {
                amp * (-x.abs() * damping).exp() * fm::cos(tpf * x) + sep
            };
            if y.abs() <= tt {
                (w * x, -w * y)
            } else {
                (w * x, w * y)
            }
        }
        POLAR2 => {
            let p2v = w / PI;
            (p2v * t.atan_xy, p2v * 0.5 * t.sumsq.ln())
        }
        POPCORN2 => {
            let [amp_x, amp_y, c] = v.params();
            (
                w * (x + amp_x * fm::sin(fm::tan(y * c))),
                w * (y + amp_y * fm::sin(fm::tan(x * c))),
            )
        }
        SCRY => {
            let [inv_w] = v.derived();
            let r = 1.0 / zeps(t.sqrt * (t.sumsq + inv_w));
            (x * r, y * r)
        }
        SEPARATION => {
            let [sx, sxi, sy, syi] = v.params();
            let sx2 = sx * sx;
            let sy2 = sy * sy;
            let nx = if x > 0.0 {
                w * ((x * x + sx2).sqrt() - x * sxi)
            } else {
                -w * ((x * x + sx2).sqrt() + x * sxi)
            };
            let ny = if y > 0.0 {
                w * ((y * y + sy2).sqrt() - y * syi)
            } else {
                -w * ((y * y + sy2).sqrt() + y * syi)
            };
            (nx, ny)
        }
        SPLIT => {
            let [xsize, ysize] = v.params();
            let ny = if fm::cos(x * xsize * PI) >= 0.0 {
                w * y
            } else {
                -w * y
            };
            let nx = if fm::cos(y * ysize * PI) >= 0.0 {
                w * x
            } else {
                -w * x
            };
            (nx, ny)
        }
        SPLITS => {
            let [dx, dy] = v.params();
            let nx = if x >= 0.0 { w * (x + dx) } else { w * (x - dx) };
            let ny = if y >= 0.0 { w * (y + dy) } else { w * (y - dy) };
            (nx, ny)
        }
        STRIPES => {
            let [space, warp] = v.params();
            let rx = (x + 0.5).floor();
            let ox = x - rx;
            (w * (ox * (1.0 - space) + rx), w * (y + ox * ox * warp))
        }
        WEDGE => {
            let [angle, hole, count, swirl] = v.params();
            let r = t.sqrt;
            let mut a = t.atan_yx + swirl * r;
            let c = ((count * a + PI) * (1.0 / PI) * 0.5).floor();
            let comp_fac = 1.0 - angle * count * (1.0 / PI) * 0.5;
            a = a * comp_fac + c * angle;
            let r = w * (r + hole);
            let (s, co) = sincos(a);
            (r * co, r * s)
        }
        WEDGE_JULIA => {
            let [angle, count, power] = v.params();
            let [cf, abs_power, cn] = v.derived();
            let r = w * fm::pow_nonneg(t.sumsq, cn);
            let k = rng.rand_size(abs_power);
            let mut a = (t.atan_yx + 2.0 * PI * k) / power;
            let c = ((count * a + PI) * (1.0 / PI) * 0.5).floor();
            a = a * cf + c * angle;
            let (s, co) = sincos(a);
            (r * co, r * s)
        }
        WEDGE_SPH => {
            let [angle, count, hole, swirl] = v.params();
            let [cf] = v.derived();
            let r = 1.0 / zeps(t.sqrt);
            let mut a = t.atan_yx + swirl * r;
            let c = ((count * a + PI) * (1.0 / PI) * 0.5).floor();
            a = a * cf + c * angle;
            let r = w * (r + hole);
            // The angle is huge near the origin: the exact reduction of the std library.
            let (s, co) = a.sin_cos();
            (r * co, r * s)
        }
        WHORL => {
            let [inside, outside] = v.params();
            let r = t.sqrt;
            let a = if r < w {
                t.atan_yx + inside / (w - r)
            } else {
                t.atan_yx + outside / (w - r)
            };
            let (s, c) = sincos(a);
            (w * r * c, w * r * s)
        }
        WAVES2 => {
            let [freqx, scalex, freqy, scaley] = v.params();
            (
                w * (x + scalex * fm::sin(y * freqx)),
                w * (y + scaley * fm::sin(x * freqy)),
            )
        }
        EXP => {
            let e = x.exp();
            let (s, c) = sincos(y);
            (w * e * c, w * e * s)
        }
        LOG => {
            let [denom] = v.derived();
            (t.sumsq.ln() * denom, w * t.atan_yx)
        }
        SIN => {
            let (x, y) = if compat {
                (x, y)
            } else {
                (x * FRAC_PI_2, y * FRAC_PI_2)
            };
            let (s, c) = sincos(x);
            (w * s * fm::cosh(y), w * c * fm::sinh(y))
        }
        COS => {
            let (x, y) = if compat {
                (x, y)
            } else {
                (x * FRAC_PI_2, y * FRAC_PI_2)
            };
            let (s, c) = sincos(x);
            (w * c * fm::cosh(y), -(w * s * fm::sinh(y)))
        }
        TAN => {
            if compat {
                let (s, c) = sincos(2.0 * x);
                let den = 1.0 / zeps(c + fm::cosh(2.0 * y));
                (w * den * s, w * den * fm::sinh(2.0 * y))
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let den = w / zeps(fm::cos(x) + fm::cosh(y));
                (fm::sin(x) * den, fm::sinh(y) * den)
            }
        }
        SEC => {
            let (x, y) = if compat { (x, y) } else { (x * PI, y * PI) };
            let (s, c) = sincos(x);
            let den = w * (2.0 / zeps(fm::cos(2.0 * x) + fm::cosh(2.0 * y)));
            (den * c * fm::cosh(y), den * s * fm::sinh(y))
        }
        CSC => {
            if compat {
                let (s, c) = sincos(x);
                let den = 2.0 / zeps(fm::cosh(2.0 * y) - fm::cos(2.0 * x));
                (w * den * s * fm::cosh(y), -(w * den * c * fm::sinh(y)))
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let (s, c) = sincos(x);
                let sh = fm::sinh(y);
                let den = 2.0 * w / (1.0 + 2.0 * sh * sh - fm::cos(2.0 * x));
                (den * s * fm::cosh(y), den * c * sh)
            }
        }
        COT => {
            if compat {
                let (s, c) = sincos(2.0 * x);
                let den = 1.0 / zeps(fm::cosh(2.0 * y) - c);
                (w * den * s, w * den * -fm::sinh(2.0 * y))
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let (s, c) = sincos(x);
                let den = w / zeps(fm::cosh(y) - c);
                (den * s, den * fm::sinh(y))
            }
        }
        SINH => {
            let (x, y) = if compat {
                (x, y)
            } else {
                (x * FRAC_PI_4, y * FRAC_PI_4)
            };
            let (s, c) = sincos(y);
            (w * fm::sinh(x) * c, w * fm::cosh(x) * s)
        }
        COSH => {
            let (x, y) = if compat {
                (x, y)
            } else {
                (x * FRAC_PI_2, y * FRAC_PI_2)
            };
            let (s, c) = sincos(y);
            (w * fm::cosh(x) * c, w * fm::sinh(x) * s)
        }
        TANH => {
            if compat {
                let (s, c) = sincos(2.0 * y);
                let den = 1.0 / zeps(c + fm::cosh(2.0 * x));
                (w * den * fm::sinh(2.0 * x), w * den * s)
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let (s, c) = sincos(y);
                let den = w / zeps(c + fm::cosh(x));
                (den * fm::sinh(x), den * s)
            }
        }
        SECH => {
            if compat {
                let (s, c) = sincos(y);
                let den = 2.0 / zeps(fm::cos(2.0 * y) + fm::cosh(2.0 * x));
                (w * den * c * fm::cosh(x), -(w * den * s * fm::sinh(x)))
            } else {
                let (x, y) = (x * FRAC_PI_4, y * FRAC_PI_4);
                let (s, c) = sincos(y);
                let den = w * (2.0 / zeps(fm::cos(y * 2.0) + fm::cosh(x * 2.0)));
                (den * c * fm::cosh(x), den * s * fm::sinh(x))
            }
        }
        CSCH => {
            if compat {
                let (s, c) = sincos(y);
                let den = 2.0 / zeps(fm::cosh(2.0 * x) - fm::cos(2.0 * y));
                (w * den * fm::sinh(x) * c, -(w * den * fm::cosh(x) * s))
            } else {
                let (x, y) = (x * FRAC_PI_4, y * FRAC_PI_4);
                let (s, c) = sincos(y);
                let den = w * (2.0 / zeps(fm::cosh(2.0 * x) - fm::cos(2.0 * y)));
                (den * fm::sinh(x) * c, den * fm::cosh(x) * s)
            }
        }
        COTH => {
            if compat {
                let (s, c) = sincos(2.0 * y);
                let den = 1.0 / zeps(fm::cosh(2.0 * x) - c);
                (w * den * fm::sinh(2.0 * x), w * den * s)
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let (s, c) = sincos(y);
                let den = w / zeps(fm::cosh(x) - c);
                (den * fm::sinh(x), den * s)
            }
        }
        AUGER => {
            let [freq, aw, sym, scale] = v.params();
            let s = fm::sin(freq * x);
            let tt = fm::sin(freq * y);
            let dy = y + aw * (scale * s / 2.0 + y.abs() * s);
            let dx = x + aw * (scale * tt / 2.0 + x.abs() * tt);
            (w * (x + sym * (dx - x)), w * dy)
        }
        FLUX => {
            let [spread] = v.params();
            let xpw = x + w;
            let xmw = x - w;
            let avgr = w
                * (2.0 + spread)
                * ((y * y + xpw * xpw).sqrt() / (y * y + xmw * xmw).sqrt()).sqrt();
            let avga = (y.atan2(xmw) - y.atan2(xpw)) * 0.5;
            let (s, c) = sincos(avga);
            (avgr * c, avgr * s)
        }
        MOBIUS => {
            let [rea, ima, reb, imb, rec, imc, red, imd] = v.params();
            let re_u = rea * x - ima * y + reb;
            let im_u = rea * y + ima * x + imb;
            let re_v = rec * x - imc * y + red;
            let im_v = rec * y + imc * x + imd;
            let rad_v = w / zeps(re_v * re_v + im_v * im_v);
            (
                rad_v * (re_u * re_v + im_u * im_v),
                rad_v * (im_u * re_v - re_u * im_v),
            )
        }
        _ => (0.0, 0.0),
    }
}

#[cfg(test)]
mod conversion_tests {
    use super::*;

    /// The vectorisable multiply and conversions give the bits of the 128-bit multiply and of
    /// `as f64`, on random numbers and on the edges.
    #[test]
    fn halves_give_the_bits_of_the_wide_operations() {
        let mut rng = FastRng::new(11);
        let edges = [
            0,
            1,
            2,
            u32::MAX as u64,
            1 << 32,
            (1 << 53) + 1,
            u64::MAX - 1,
            u64::MAX,
        ];
        for i in 0..1_000_000 {
            let (a, b) = if i < 64 {
                (edges[i % 8], edges[i / 8])
            } else {
                (rng.u64(), rng.u64() >> (i % 64))
            };
            assert_eq!(
                mul_high(a, b),
                ((a as u128 * b as u128) >> 64) as u64,
                "{a} {b}"
            );
            assert_eq!(u64_to_f64(a).to_bits(), (a as f64).to_bits(), "{a}");
            assert_eq!(u32_to_f64(b >> 32).to_bits(), ((b >> 32) as f64).to_bits());
        }
    }
}
