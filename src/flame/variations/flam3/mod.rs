//! flam3's 99 classic variations (ids 0–98 in flam3's order), with the formulas of flam3 and
//! of the flame paper (Draves & Reckase, "The Fractal Flame Algorithm"). flam3's semantics are
//! kept: its guard `EPS` = 1e-10 in denominators and unclamped parameters.
//!
//! Every formula returns the *weighted* contribution that is added to the xform's variation sum,
//! exactly as flam3 accumulates it (a few variations use the weight non-linearly, e.g. `whorl`,
//! `loonie`, `lazysusan`, `scry`, `flux`).
//!
//! By file: `ids` (the variations' ids, in flam3's order), `formulas` (one match arm per
//! variation), `forms` (the batch loops of the `pre_`/`post_` forms) and this one (the
//! registry table, derived values, z and the batch loops).

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, PI};

use super::util::zeps;
use super::{Acc, Prepared, SoaAcc, SoaIn, V3, VarDef, VarIn, ZRule, flag, need, p, p_range};
#[cfg(target_arch = "x86_64")]
use crate::flame::fastmath::Simd;
use crate::flame::rng::FastRng;
pub(crate) use formulas::Draws;
use formulas::{Drawn, MAX_DRAWS, draws, formula, z_out};

mod forms;
mod formulas;
mod fresh;
mod ids;

pub use fresh::absent_params;
pub use ids::*;

/// Per-point quantities shared by many of the entries below: r² and r, plus an angle.
const R: u8 = need::SUMSQ | need::SQRT;
const R_XY: u8 = R | need::ATAN_XY;
const R_YX: u8 = R | need::ATAN_YX;
const R_UV: u8 = R | need::ANGLES;

/// flam3's variation `ID`, named `name`, reading the quantities `needs`, with the flags `extra`
/// besides [`flag::FLAM3`] (and `WRITES_Z` where it computes a z): its formula, its batch loop
/// and its derived values.
const fn classic<const ID: u16>(name: &'static str, needs: u8, extra: u32) -> VarDef {
    VarDef::new(name, eval::<ID>)
        .needs(needs)
        .flags(zf(ID) | flag::FLAM3 | extra)
        .prepare(prepare)
        .batch(batch::<ID>)
        .form_batch(forms::form_batch::<ID>)
}

pub(super) static DEFS: &[VarDef] = &[
    classic::<0>("linear", 0, 0),
    classic::<1>("sinusoidal", 0, 0),
    classic::<2>("spherical", R, 0),
    classic::<3>("swirl", R, 0),
    classic::<4>("horseshoe", R, 0),
    classic::<5>("polar", R_XY, 0),
    classic::<6>("handkerchief", R_XY, 0),
    classic::<7>("heart", R_XY, 0),
    classic::<8>("disc", R_XY, 0),
    classic::<9>("spiral", R_UV, 0),
    classic::<10>("hyperbolic", R_UV, 0),
    classic::<11>("diamond", R_UV, 0),
    classic::<12>("ex", R_XY, 0),
    classic::<13>("julia", R_XY, flag::RANDOM),
    classic::<14>("bent", 0, 0),
    classic::<15>("waves", 0, flag::USES_AFFINE),
    classic::<16>("fisheye", R, 0),
    classic::<17>("popcorn", 0, flag::USES_AFFINE),
    classic::<18>("exponential", 0, 0),
    classic::<19>("power", R_UV, 0),
    classic::<20>("cosine", 0, 0),
    classic::<21>("rings", R_UV, flag::USES_AFFINE),
    classic::<22>("fan", R_XY, flag::USES_AFFINE),
    classic::<23>("blob", R_XY | need::ANGLES, 0).params(&[
        p("blob_low", 0.0),
        p("blob_high", 1.0),
        p("blob_waves", 1.0),
    ]),
    classic::<24>("pdj", R, 0).params(&[
        p("pdj_a", 0.0),
        p("pdj_b", 0.0),
        p("pdj_c", 0.0),
        p("pdj_d", 0.0),
    ]),
    classic::<25>("fan2", R_XY, 0)
        .params(&[p("fan2_x", FRAC_1_SQRT_2), p("fan2_y", -FRAC_1_SQRT_2)]),
    classic::<26>("rings2", R_UV, 0).params(&[p("rings2_val", 1.0)]),
    classic::<27>("eyefish", R, 0),
    classic::<28>("bubble", R, 0),
    classic::<29>("cylinder", R, 0),
    classic::<30>("perspective", R, 0)
        .params(&[p("perspective_angle", 0.0), p("perspective_dist", 0.0)]),
    classic::<31>("noise", R, flag::RANDOM),
    classic::<32>("julian", R_YX, flag::RANDOM)
        .params(&[p("julian_power", 1.0), p("julian_dist", 1.0)]),
    classic::<33>("juliascope", R_YX, flag::RANDOM)
        .params(&[p("juliascope_power", 1.0), p("juliascope_dist", 1.0)]),
    classic::<34>("blur", R, flag::RANDOM).sum(),
    classic::<35>("gaussian_blur", R, flag::RANDOM).sum(),
    classic::<36>("radial_blur", R_YX, flag::RANDOM).params(&[p("radial_blur_angle", 0.0)]),
    classic::<37>("pie", R, flag::RANDOM)
        .params(&[
            p("pie_slices", 6.0),
            p("pie_rotation", 0.5),
            p("pie_thickness", 0.5),
        ])
        .sum(),
    classic::<38>("ngon", R_YX, 0).params(&[
        p("ngon_sides", 5.0),
        p("ngon_power", 3.0),
        p("ngon_circle", 1.0),
        p("ngon_corners", 2.0),
    ]),
    classic::<39>("curl", R, 0).params(&[p("curl_c1", 1.0), p("curl_c2", 0.0)]),
    classic::<40>("rectangles", R, 0).params(&[p("rectangles_x", 1.0), p("rectangles_y", 1.0)]),
    classic::<41>("arch", R, flag::RANDOM).sum(),
    classic::<42>("tangent", R, 0),
    classic::<43>("square", R, flag::RANDOM).sum(),
    classic::<44>("rays", R, flag::RANDOM),
    classic::<45>("blade", R, flag::RANDOM),
    classic::<46>("secant2", R, 0),
    classic::<47>("twintrian", R, flag::RANDOM),
    classic::<48>("cross", R, 0),
    classic::<49>("disc2", R_XY, 0).params(&[p("disc2_rot", 0.0), p("disc2_twist", 0.0)]),
    classic::<50>("super_shape", R_YX, flag::RANDOM).params(&[
        p("super_shape_rnd", 0.0),
        p("super_shape_m", 0.0),
        p("super_shape_n1", 1.0),
        p("super_shape_n2", 1.0),
        p("super_shape_n3", 1.0),
        p("super_shape_holes", 0.0),
    ]),
    classic::<51>("flower", R_YX, flag::RANDOM)
        .params(&[p("flower_petals", 0.0), p("flower_holes", 0.0)]),
    classic::<52>("conic", R, flag::RANDOM)
        .params(&[p("conic_eccentricity", 1.0), p("conic_holes", 0.0)]),
    classic::<53>("parabola", R, flag::RANDOM)
        .params(&[p("parabola_height", 0.0), p("parabola_width", 0.0)]),
    classic::<54>("bent2", R, 0).params(&[p("bent2_x", 1.0), p("bent2_y", 1.0)]),
    classic::<55>("bipolar", R, 0).params(&[p("bipolar_shift", 0.0)]),
    classic::<56>("boarders", R, flag::RANDOM),
    classic::<57>("butterfly", R, 0),
    classic::<58>("cell", R, 0).params(&[p("cell_size", 1.0)]),
    classic::<59>("cpow", R_YX, flag::RANDOM).params(&[
        p("cpow_r", 1.0),
        p("cpow_i", 0.0),
        p("cpow_power", 1.0),
    ]),
    classic::<60>("curve", R, 0).params(&[
        p("curve_xamp", 0.0),
        p("curve_yamp", 0.0),
        p("curve_xlength", 1.0),
        p("curve_ylength", 1.0),
    ]),
    classic::<61>("edisc", R, 0),
    classic::<62>("elliptic", R, 0),
    classic::<63>("escher", R_YX | need::ATAN_XY, 0).params(&[p("escher_beta", 3.0)]),
    classic::<64>("foci", R, 0),
    classic::<65>("lazysusan", R, 0).params(&[
        p("lazysusan_spin", PI),
        p("lazysusan_space", 0.0),
        p("lazysusan_twist", 0.0),
        p("lazysusan_x", 0.0),
        p("lazysusan_y", 0.0),
    ]),
    classic::<66>("loonie", R, 0),
    classic::<67>("pre_blur", R, flag::HIDDEN),
    classic::<68>("modulus", R, 0).params(&[p("modulus_x", 1.0), p("modulus_y", 1.0)]),
    classic::<69>("oscilloscope", R, 0).params(&[
        p("oscilloscope_separation", 1.0),
        p("oscilloscope_frequency", PI),
        p("oscilloscope_amplitude", 1.0),
        p("oscilloscope_damping", 0.0),
    ]),
    classic::<70>("polar2", R_XY, 0),
    classic::<71>("popcorn2", R, 0).params(&[
        p("popcorn2_x", 0.1),
        p("popcorn2_y", 0.1),
        p("popcorn2_c", 3.0),
    ]),
    classic::<72>("scry", R, 0),
    classic::<73>("separation", R, 0).params(&[
        p("separation_x", 1.0),
        p("separation_xinside", 0.0),
        p("separation_y", 1.0),
        p("separation_yinside", 0.0),
    ]),
    classic::<74>("split", R, 0).params(&[p("split_xsize", 0.5), p("split_ysize", 0.5)]),
    classic::<75>("splits", R, 0).params(&[p("splits_x", 0.0), p("splits_y", 0.0)]),
    classic::<76>("stripes", R, 0).params(&[p("stripes_space", 0.5), p("stripes_warp", 0.0)]),
    classic::<77>("wedge", R_YX, 0).params(&[
        p("wedge_angle", FRAC_PI_2),
        p("wedge_hole", 0.0),
        p("wedge_count", 2.0),
        p("wedge_swirl", 0.0),
    ]),
    classic::<78>("wedge_julia", R_YX, flag::RANDOM).params(&[
        p("wedge_julia_angle", 0.0),
        p("wedge_julia_count", 1.0),
        p("wedge_julia_power", 1.0),
        p("wedge_julia_dist", 0.0),
    ]),
    classic::<79>("wedge_sph", R_YX, 0).params(&[
        p("wedge_sph_angle", FRAC_PI_2),
        p("wedge_sph_count", 2.0),
        p("wedge_sph_hole", 0.0),
        p("wedge_sph_swirl", 0.0),
    ]),
    classic::<80>("whorl", R_YX, 0).params(&[p("whorl_inside", 1.0), p("whorl_outside", 1.0)]),
    classic::<81>("waves2", R, 0).params(&[
        p("waves2_freqx", 2.0),
        p("waves2_scalex", 0.0),
        p("waves2_freqy", 2.0),
        p("waves2_scaley", 0.0),
        p("waves2_freqz", 0.0),
        p("waves2_scalez", 0.0),
    ]),
    classic::<82>("exp", R, 0),
    classic::<83>("log", R_YX, 0).params(&[p_range(
        "log_base",
        std::f64::consts::E,
        f64::EPSILON,
        f64::INFINITY,
    )]),
    classic::<84>("sin", R, 0),
    classic::<85>("cos", R, 0),
    classic::<86>("tan", R, 0),
    classic::<87>("sec", R, 0),
    classic::<88>("csc", R, 0),
    classic::<89>("cot", R, 0),
    classic::<90>("sinh", R, 0),
    classic::<91>("cosh", R, 0),
    classic::<92>("tanh", R, 0),
    classic::<93>("sech", R, 0),
    classic::<94>("csch", R, 0),
    classic::<95>("coth", R, 0),
    classic::<96>("auger", R, 0).params(&[
        p("auger_freq", 5.0),
        p("auger_weight", 0.5),
        p("auger_sym", 0.0),
        p("auger_scale", 0.1),
    ]),
    classic::<97>("flux", R, 0).params(&[p("flux_spread", 0.0)]),
    classic::<98>("mobius", R, 0).params(&[
        p("mobius_re_a", 1.0),
        p("mobius_im_a", 0.0),
        p("mobius_re_b", 0.0),
        p("mobius_im_b", 0.0),
        p("mobius_re_c", 0.0),
        p("mobius_im_c", 0.0),
        p("mobius_re_d", 1.0),
        p("mobius_im_d", 0.0),
    ]),
];

/// The derived values of the variations that have any, appended after the parameters.
fn prepare(v: &mut Prepared) {
    let (w, compat) = (v.w, v.compat);
    let derived: &[f64] = match v.id {
        PERSPECTIVE => {
            let [angle, dist] = v.params();
            let ang = angle * PI / 2.0;
            &[ang.sin(), dist * ang.cos()]
        }
        JULIAN | JULIASCOPE => {
            let [power, dist] = v.params();
            let power = zeps(power);
            v.p[0] = power;
            &[power.abs(), dist / power / 2.0]
        }
        RADIAL_BLUR => {
            let [angle] = v.params();
            let ang = angle * PI / 2.0;
            &[ang.sin(), ang.cos()]
        }
        DISC2 => {
            let [rot, twist] = v.params();
            let mut sinadd = twist.sin();
            let mut cosadd = twist.cos() - 1.0;
            if twist > 2.0 * PI {
                let k = 1.0 + twist - 2.0 * PI;
                cosadd *= k;
                sinadd *= k;
            }
            if twist < -2.0 * PI {
                let k = 1.0 + twist + 2.0 * PI;
                cosadd *= k;
                sinadd *= k;
            }
            &[rot * PI, sinadd, cosadd]
        }
        SUPER_SHAPE => {
            let [_, m, n1] = v.params();
            &[m / 4.0, -1.0 / n1]
        }
        NGON => {
            let [sides, power] = v.params();
            let sector = 2.0 * PI / sides;
            &[-0.5 * power, sector, 1.0 / sector]
        }
        CPOW => {
            let [r, i, power] = v.params();
            &[2.0 * PI / power, r / power, i / power]
        }
        CURVE => {
            let [_, _, xlength, ylength] = v.params();
            if compat {
                &[
                    1.0 / (xlength * xlength).max(1e-20),
                    1.0 / (ylength * ylength).max(1e-20),
                ]
            } else {
                &[1.0 / zeps(xlength), 1.0 / zeps(ylength)]
            }
        }
        ESCHER => {
            let [beta] = v.params();
            &[0.5 * (1.0 + beta.cos()), 0.5 * beta.sin()]
        }
        WEDGE_JULIA => {
            let [angle, count, power, dist] = v.params();
            &[
                1.0 - angle * count / (2.0 * PI),
                power.abs(),
                dist / power / 2.0,
            ]
        }
        FAN2 => {
            let [x] = v.params();
            let dx = PI * zeps(x * x);
            &[dx, 0.5 * dx]
        }
        RINGS2 => {
            let [val] = v.params();
            &[zeps(val * val)]
        }
        BIPOLAR => {
            let [shift] = v.params();
            let k = std::f64::consts::FRAC_2_PI;
            &[-FRAC_PI_2 * shift, w * k, w * 0.25 * k]
        }
        LOONIE => &[w * w],
        SCRY => &[1.0 / zeps(w)],
        WEDGE_SPH => {
            let [angle, count] = v.params();
            &[1.0 - angle * count * (1.0 / PI) * 0.5]
        }
        OSCILLOSCOPE => {
            let [_, frequency] = v.params();
            &[2.0 * PI * frequency]
        }
        // Natural logarithm of r for base e; another base scales it.
        LOG => {
            let [base] = v.params();
            &[w * 0.5 / base.ln()]
        }
        _ => &[],
    };
    v.p.extend_from_slice(derived);
}

/// `WRITES_Z` for the variations that compute their z.
const fn zf(id: u16) -> u32 {
    if writes_z(id) { flag::WRITES_Z } else { 0 }
}

/// Variations whose output z is not the framework's default.
const fn writes_z(id: u16) -> bool {
    matches!(
        id,
        LINEAR
            | SINUSOIDAL
            | SPHERICAL
            | SWIRL
            | HORSESHOE
            | POLAR
            | DISC
            | SPIRAL
            | HYPERBOLIC
            | PDJ
            | FAN2
            | RINGS2
            | EYEFISH
            | NOISE
            | JULIAN
            | JULIASCOPE
            | BLUR
            | GAUSSIAN_BLUR
            | RADIAL_BLUR
            | NGON
            | RECTANGLES
            | SQUARE
            | CROSS
            | ESCHER
            | FOCI
            | LAZYSUSAN
            | LOONIE
            | POLAR2
            | SEPARATION
            | SPLITS
            | WEDGE
            | LOG
            | AUGER
            | MOBIUS
            | BUBBLE
            | CYLINDER
            | WAVES2
            | FLUX
            | BIPOLAR
    )
}

fn eval<const ID: u16>(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = formula(ID, v, t, &v.aff, rng, v.compat);
    [x, y, z_out(ID, v, t)]
}

/// The batch version: a loop the compiler can vectorise for variations without library calls.
/// (One function per variation: inlining every formula into one loop let LLVM speculate the
/// transcendental calls of other arms, which made every xform ~20x slower.)
///
/// Compiled three times, for the baseline CPU, with AVX2 and FMA (four points per
/// instruction instead of two) and with AVX-512F (eight), chosen at run time. Rust never fuses
/// a multiply and an add on its own, so every copy gives the same bits.
fn batch<const ID: u16>(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
    #[cfg(target_arch = "x86_64")]
    match crate::flame::fastmath::simd() {
        // SAFETY: the CPU has reported AVX-512F (and AVX2 and FMA).
        Simd::Avx512 if wider_is_faster(ID) => {
            return unsafe { batch_avx512::<ID>(v, s, acc, rng) };
        }
        // SAFETY: the CPU has reported AVX2 and FMA (AVX-512F implies them here).
        Simd::Avx512 | Simd::Avx2Fma => return unsafe { batch_avx2::<ID>(v, s, acc, rng) },
        Simd::Baseline => {}
    }
    batch_loop::<ID>(v, s, acc, rng)
}

/// The variations whose AVX-512 loop measured at least 10 % faster than their AVX2 loop
/// (benches/variation_speed.md); for the others (linear, spherical, polar, fisheye, juliascope
/// among them) the eight-lane loop was slower, so the four-lane one runs.
const fn wider_is_faster(id: u16) -> bool {
    matches!(
        id,
        BLUR | SPIRAL
            | DISC
            | NOISE
            | SWIRL
            | DIAMOND
            | EX
            | EXPONENTIAL
            | JULIA
            | SINUSOIDAL
            | ARCH
            | BLADE
            | HANDKERCHIEF
            | SECANT2
            | PIE
            | CYLINDER
    )
}

/// [`batch`] for CPUs with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn batch_avx2<const ID: u16>(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
    batch_loop::<ID>(v, s, acc, rng)
}

/// [`batch`] for CPUs with AVX-512F.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx2,fma")]
fn batch_avx512<const ID: u16>(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
    batch_loop::<ID>(v, s, acc, rng)
}

/// The loop over the batch. A variation that draws a fixed number of random numbers per point
/// ([`draws`]) gets them drawn for the whole batch first, in the order the formula would draw
/// them (the same stream, the same bits): the formula's loop then vectorises. Fractorium's
/// compatibility switch is fixed for the loop (one copy of the loop for each setting, for the
/// variations that read it).
#[inline(always)]
fn batch_loop<const ID: u16>(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
    if reads_compat(ID) && !v.compat {
        batch_loop_as::<ID, false>(v, s, acc, rng)
    } else {
        batch_loop_as::<ID, true>(v, s, acc, rng)
    }
}

/// The variations whose formula reads [`Prepared::compat`].
const fn reads_compat(id: u16) -> bool {
    matches!(
        id,
        BIPOLAR
            | COS
            | COSH
            | COT
            | COTH
            | CROSS
            | CSC
            | CSCH
            | EDISC
            | ESCHER
            | FAN2
            | JULIAN
            | JULIASCOPE
            | SEC
            | SECH
            | SIN
            | SINH
            | TAN
            | TANH
    )
}

/// [`batch_loop`] with the compatibility switch `C`.
#[inline(always)]
fn batch_loop_as<const ID: u16, const C: bool>(
    v: &Prepared,
    s: &SoaIn,
    acc: &mut SoaAcc,
    rng: &mut FastRng,
) {
    let n = acc.x.len();
    let d = draws(ID);
    if d == 0 {
        return batch_span::<ID, _>(v, s, acc, 0, n, &mut Direct::<C> { v, rng });
    }
    let mut drawn = [[0u64; MAX_DRAWS]; 256];
    let mut start = 0;
    while start < n {
        let m = (n - start).min(drawn.len());
        let drawn = &mut drawn[..m];
        for p in drawn.iter_mut() {
            for u in p[..d].iter_mut() {
                *u = rng.u64();
            }
        }
        batch_span::<ID, _>(v, s, acc, start, m, &mut Predrawn::<C> { v, drawn });
        start += m;
    }
}

/// Variation `ID`'s formula at point `i` of a span. A trait with an always-inlined method
/// rather than a closure: a closure is a function of its own, which the compiler may leave
/// out of line — and a call in the loop stops it from vectorising.
trait SpanFormula<const ID: u16> {
    fn at(&mut self, i: usize, t: &VarIn) -> (f64, f64);
}

/// The formula drawing from the generator itself (variations that draw nothing, or a number
/// of draws that depends on the point), with the compatibility switch `C`.
struct Direct<'a, const C: bool> {
    v: &'a Prepared,
    rng: &'a mut FastRng,
}

impl<const ID: u16, const C: bool> SpanFormula<ID> for Direct<'_, C> {
    #[inline(always)]
    fn at(&mut self, _: usize, t: &VarIn) -> (f64, f64) {
        formula(ID, self.v, t, &self.v.aff, self.rng, C)
    }
}

/// The formula reading the numbers drawn for the span beforehand (point `i`'s row), with the
/// compatibility switch `C`.
struct Predrawn<'a, const C: bool> {
    v: &'a Prepared,
    drawn: &'a [[u64; MAX_DRAWS]],
}

impl<const ID: u16, const C: bool> SpanFormula<ID> for Predrawn<'_, C> {
    #[inline(always)]
    fn at(&mut self, i: usize, t: &VarIn) -> (f64, f64) {
        let mut r = Drawn {
            d: &self.drawn[i],
            pos: 0,
        };
        formula(ID, self.v, t, &self.v.aff, &mut r, C)
    }
}

/// The formula `f` over the `m` points of the batch from `start` on (`i` counts from 0).
#[inline(always)]
fn batch_span<const ID: u16, F: SpanFormula<ID>>(
    v: &Prepared,
    s: &SoaIn,
    acc: &mut SoaAcc,
    start: usize,
    m: usize,
    f: &mut F,
) {
    let r = start..start + m;
    let (ax, ay) = (&mut acc.x[r.clone()], &mut acc.y[r.clone()]);
    let (x, y, sumsq, sqrt) = (
        &s.x[r.clone()],
        &s.y[r.clone()],
        &s.sumsq[r.clone()],
        &s.sqrt[r.clone()],
    );
    let (ux, uy) = (&s.ux[r.clone()], &s.uy[r.clone()]);
    let (atan_xy, atan_yx) = (&s.atan_xy[r.clone()], &s.atan_yx[r.clone()]);
    let (z, az) = (&s.z[r.clone()], &mut acc.z[r]);
    // The formula's own z, or the framework's where the flame's program gives the variation
    // none (JWildfire's 2-D twins: 0, or the weighted z with "preserve Z").
    let own_z = writes_z(ID) && v.def.flags & flag::WRITES_Z != 0;
    let weighted_z = !own_z && v.zrule == ZRule::Weighted;
    for i in 0..m {
        let t = VarIn {
            x: x[i],
            y: y[i],
            z: z[i],
            sumsq: sumsq[i],
            sqrt: sqrt[i],
            ux: ux[i],
            uy: uy[i],
            atan_xy: atan_xy[i],
            atan_yx: atan_yx[i],
            color: 0.0,
        };
        let (dx, dy) = f.at(i, &t);
        ax[i] += dx;
        ay[i] += dy;
        if own_z {
            az[i] += z_out(ID, v, &t);
        } else if weighted_z {
            az[i] += v.w * t.z;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::affine::Affine;
    use crate::flame::variations::{Dialect, Form, VarId, eval_prepared};

    /// lazysusan adds its centre unweighted in flam3 and JWildfire, weighted in Fractorium:
    /// rows of each program's own numeric vectors (JWildfire 9.00, Fractorium 25.25.12.1),
    /// as (weight, spin, space, twist, x, y, input, output).
    #[test]
    fn lazysusan_follows_the_writer() {
        type Row = (f64, [f64; 5], [f64; 2], [f64; 2]);
        let jwf = [0.1, 0.4, 0.2, 0.1, 0.2];
        let jwildfire: [Row; 4] = [
            (
                0.7,
                jwf,
                [-0.1125, 0.3975],
                [-0.09502981922398035, 0.1987768732179206],
            ),
            (
                0.7,
                jwf,
                [0.625, 0.125],
                [0.43856263280855756, 0.06867795530288268],
            ),
            (
                -1.3,
                jwf,
                [-0.1125, 0.3975],
                [0.5504954683235146, -1.4666872579919998],
            ),
            (
                -1.3,
                jwf,
                [0.625, 0.125],
                [-1.0246378762776882, -0.8962043996004736],
            ),
        ];
        let fr = [2.8132741228718343, 0.3, 0.3, 0.3, 0.3];
        let fractorium: [Row; 2] = [
            (
                0.7,
                fr,
                [-0.1125, 0.3975],
                [-0.18564863008924068, 0.45900586542362515],
            ),
            (
                0.7,
                fr,
                [0.625, 0.125],
                [-0.09059375503098684, -0.43339627220786625],
            ),
        ];
        let run = |d: Dialect, (w, p, t, _): &Row| {
            let mut v = Prepared::new(
                LAZYSUSAN as VarId,
                Form::Regular,
                *w,
                p,
                Affine::default(),
                true,
            );
            v.dialect = d;
            let o = eval_prepared(
                &v,
                [t[0], t[1], 0.0],
                Acc::default(),
                false,
                &mut FastRng::new(1),
            );
            [o.x, o.y]
        };
        for (rows, mine, other) in [
            (&jwildfire[..], Dialect::JWildfire, Dialect::Fractorium),
            (&jwildfire[..], Dialect::Flam3, Dialect::Fractorium),
            (&fractorium[..], Dialect::Fractorium, Dialect::Flam3),
        ] {
            for row in rows {
                let got = run(mine, row);
                for k in 0..2 {
                    assert!(
                        (got[k] - row.3[k]).abs() < 1e-9,
                        "{mine:?} {row:?}: {got:?}"
                    );
                }
                let theirs = run(other, row);
                assert!(
                    (theirs[0] - row.3[0]).abs() > 1e-3,
                    "{other:?} agrees on {row:?}"
                );
            }
        }
    }
}
