//! flam3's 99 classic variations (ids 0–98 in flam3's order), with the formulas of flam3 and
//! of the flame paper (Draves & Reckase, "The Fractal Flame Algorithm"). flam3's semantics are
//! kept: its guard `EPS` = 1e-10 in denominators and unclamped parameters.
//!
//! Every formula returns the *weighted* contribution that is added to the xform's variation sum,
//! exactly as flam3 accumulates it (a few variations use the weight non-linearly, e.g. `whorl`,
//! `loonie`, `lazysusan`, `scry`, `flux`).

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, FRAC_PI_4, PI};

use super::util::{rand_size, zeps};
use super::{Acc, EPS, Form, Prepared, SoaAcc, SoaIn, V3, VarDef, VarIn, flag, need, p, p_range};
use crate::flame::affine::Affine;
use crate::flame::fastmath as fm;
use crate::flame::rng::FastRng;

pub const LINEAR: u16 = 0;
pub const SINUSOIDAL: u16 = 1;
pub const SPHERICAL: u16 = 2;
pub const SWIRL: u16 = 3;
pub const HORSESHOE: u16 = 4;
pub const POLAR: u16 = 5;
pub const HANDKERCHIEF: u16 = 6;
pub const HEART: u16 = 7;
pub const DISC: u16 = 8;
pub const SPIRAL: u16 = 9;
pub const HYPERBOLIC: u16 = 10;
pub const DIAMOND: u16 = 11;
pub const EX: u16 = 12;
pub const JULIA: u16 = 13;
pub const BENT: u16 = 14;
pub const WAVES: u16 = 15;
pub const FISHEYE: u16 = 16;
pub const POPCORN: u16 = 17;
pub const EXPONENTIAL: u16 = 18;
pub const POWER: u16 = 19;
pub const COSINE: u16 = 20;
pub const RINGS: u16 = 21;
pub const FAN: u16 = 22;
pub const BLOB: u16 = 23;
pub const PDJ: u16 = 24;
pub const FAN2: u16 = 25;
pub const RINGS2: u16 = 26;
pub const EYEFISH: u16 = 27;
pub const BUBBLE: u16 = 28;
pub const CYLINDER: u16 = 29;
pub const PERSPECTIVE: u16 = 30;
pub const NOISE: u16 = 31;
pub const JULIAN: u16 = 32;
pub const JULIASCOPE: u16 = 33;
pub const BLUR: u16 = 34;
pub const GAUSSIAN_BLUR: u16 = 35;
pub const RADIAL_BLUR: u16 = 36;
pub const PIE: u16 = 37;
pub const NGON: u16 = 38;
pub const CURL: u16 = 39;
pub const RECTANGLES: u16 = 40;
pub const ARCH: u16 = 41;
pub const TANGENT: u16 = 42;
pub const SQUARE: u16 = 43;
pub const RAYS: u16 = 44;
pub const BLADE: u16 = 45;
pub const SECANT2: u16 = 46;
pub const TWINTRIAN: u16 = 47;
pub const CROSS: u16 = 48;
pub const DISC2: u16 = 49;
pub const SUPER_SHAPE: u16 = 50;
pub const FLOWER: u16 = 51;
pub const CONIC: u16 = 52;
pub const PARABOLA: u16 = 53;
pub const BENT2: u16 = 54;
pub const BIPOLAR: u16 = 55;
pub const BOARDERS: u16 = 56;
pub const BUTTERFLY: u16 = 57;
pub const CELL: u16 = 58;
pub const CPOW: u16 = 59;
pub const CURVE: u16 = 60;
pub const EDISC: u16 = 61;
pub const ELLIPTIC: u16 = 62;
pub const ESCHER: u16 = 63;
pub const FOCI: u16 = 64;
pub const LAZYSUSAN: u16 = 65;
pub const LOONIE: u16 = 66;
pub const PRE_BLUR: u16 = 67;
pub const MODULUS: u16 = 68;
pub const OSCILLOSCOPE: u16 = 69;
pub const POLAR2: u16 = 70;
pub const POPCORN2: u16 = 71;
pub const SCRY: u16 = 72;
pub const SEPARATION: u16 = 73;
pub const SPLIT: u16 = 74;
pub const SPLITS: u16 = 75;
pub const STRIPES: u16 = 76;
pub const WEDGE: u16 = 77;
pub const WEDGE_JULIA: u16 = 78;
pub const WEDGE_SPH: u16 = 79;
pub const WHORL: u16 = 80;
pub const WAVES2: u16 = 81;
pub const EXP: u16 = 82;
pub const LOG: u16 = 83;
pub const SIN: u16 = 84;
pub const COS: u16 = 85;
pub const TAN: u16 = 86;
pub const SEC: u16 = 87;
pub const CSC: u16 = 88;
pub const COT: u16 = 89;
pub const SINH: u16 = 90;
pub const COSH: u16 = 91;
pub const TANH: u16 = 92;
pub const SECH: u16 = 93;
pub const CSCH: u16 = 94;
pub const COTH: u16 = 95;
pub const AUGER: u16 = 96;
pub const FLUX: u16 = 97;
pub const MOBIUS: u16 = 98;

/// The seven variations of the thesis program's menu, in menu order.
pub const THESIS_SEVEN: [u16; 7] = [LINEAR, SINUSOIDAL, SPHERICAL, SWIRL, HORSESHOE, POLAR, BENT];

/// Number of variations in flam3's list.
pub const FLAM3_COUNT: usize = 99;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("linear", eval::<0>)
        .needs(0)
        .flags(zf(0) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<0>),
    VarDef::new("sinusoidal", eval::<1>)
        .needs(0)
        .flags(zf(1) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<1>),
    VarDef::new("spherical", eval::<2>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(2) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<2>),
    VarDef::new("swirl", eval::<3>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(3) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<3>),
    VarDef::new("horseshoe", eval::<4>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(4) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<4>),
    VarDef::new("polar", eval::<5>)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(5) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<5>),
    VarDef::new("handkerchief", eval::<6>)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(6) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<6>),
    VarDef::new("heart", eval::<7>)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(7) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<7>),
    VarDef::new("disc", eval::<8>)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(8) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<8>),
    VarDef::new("spiral", eval::<9>)
        .needs(need::SUMSQ | need::SQRT | need::ANGLES)
        .flags(zf(9) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<9>),
    VarDef::new("hyperbolic", eval::<10>)
        .needs(need::SUMSQ | need::SQRT | need::ANGLES)
        .flags(zf(10) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<10>),
    VarDef::new("diamond", eval::<11>)
        .needs(need::SUMSQ | need::SQRT | need::ANGLES)
        .flags(zf(11) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<11>),
    VarDef::new("ex", eval::<12>)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(12) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<12>),
    VarDef::new("julia", eval::<13>)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(13) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<13>),
    VarDef::new("bent", eval::<14>)
        .needs(0)
        .flags(zf(14) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<14>),
    VarDef::new("waves", eval::<15>)
        .needs(0)
        .flags(zf(15) | flag::FLAM3 | flag::USES_AFFINE)
        .prepare(prepare)
        .batch(batch::<15>),
    VarDef::new("fisheye", eval::<16>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(16) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<16>),
    VarDef::new("popcorn", eval::<17>)
        .needs(0)
        .flags(zf(17) | flag::FLAM3 | flag::USES_AFFINE)
        .prepare(prepare)
        .batch(batch::<17>),
    VarDef::new("exponential", eval::<18>)
        .needs(0)
        .flags(zf(18) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<18>),
    VarDef::new("power", eval::<19>)
        .needs(need::SUMSQ | need::SQRT | need::ANGLES)
        .flags(zf(19) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<19>),
    VarDef::new("cosine", eval::<20>)
        .needs(0)
        .flags(zf(20) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<20>),
    VarDef::new("rings", eval::<21>)
        .needs(need::SUMSQ | need::SQRT | need::ANGLES)
        .flags(zf(21) | flag::FLAM3 | flag::USES_AFFINE)
        .prepare(prepare)
        .batch(batch::<21>),
    VarDef::new("fan", eval::<22>)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(22) | flag::FLAM3 | flag::USES_AFFINE)
        .prepare(prepare)
        .batch(batch::<22>),
    VarDef::new("blob", eval::<23>)
        .params(&[
            p("blob_low", 0.0),
            p("blob_high", 1.0),
            p("blob_waves", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY | need::ANGLES)
        .flags(zf(23) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<23>),
    VarDef::new("pdj", eval::<24>)
        .params(&[
            p("pdj_a", 0.0),
            p("pdj_b", 0.0),
            p("pdj_c", 0.0),
            p("pdj_d", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(24) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<24>),
    VarDef::new("fan2", eval::<25>)
        .params(&[p("fan2_x", FRAC_1_SQRT_2), p("fan2_y", -FRAC_1_SQRT_2)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(25) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<25>),
    VarDef::new("rings2", eval::<26>)
        .params(&[p("rings2_val", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ANGLES)
        .flags(zf(26) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<26>),
    VarDef::new("eyefish", eval::<27>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(27) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<27>),
    VarDef::new("bubble", eval::<28>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(28) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<28>),
    VarDef::new("cylinder", eval::<29>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(29) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<29>),
    VarDef::new("perspective", eval::<30>)
        .params(&[p("perspective_angle", 0.0), p("perspective_dist", 0.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(30) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<30>),
    VarDef::new("noise", eval::<31>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(31) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<31>),
    VarDef::new("julian", eval::<32>)
        .params(&[p("julian_power", 1.0), p("julian_dist", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(32) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<32>),
    VarDef::new("juliascope", eval::<33>)
        .params(&[p("juliascope_power", 1.0), p("juliascope_dist", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(33) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<33>),
    VarDef::new("blur", eval::<34>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(34) | flag::FLAM3 | flag::RANDOM)
        .sum()
        .prepare(prepare)
        .batch(batch::<34>),
    VarDef::new("gaussian_blur", eval::<35>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(35) | flag::FLAM3 | flag::RANDOM)
        .sum()
        .prepare(prepare)
        .batch(batch::<35>),
    VarDef::new("radial_blur", eval::<36>)
        .params(&[p("radial_blur_angle", 0.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(36) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<36>),
    VarDef::new("pie", eval::<37>)
        .params(&[
            p("pie_slices", 6.0),
            p("pie_rotation", 0.5),
            p("pie_thickness", 0.5),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(37) | flag::FLAM3 | flag::RANDOM)
        .sum()
        .prepare(prepare)
        .batch(batch::<37>),
    VarDef::new("ngon", eval::<38>)
        .params(&[
            p("ngon_sides", 5.0),
            p("ngon_power", 3.0),
            p("ngon_circle", 1.0),
            p("ngon_corners", 2.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(38) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<38>),
    VarDef::new("curl", eval::<39>)
        .params(&[p("curl_c1", 1.0), p("curl_c2", 0.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(39) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<39>),
    VarDef::new("rectangles", eval::<40>)
        .params(&[p("rectangles_x", 1.0), p("rectangles_y", 1.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(40) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<40>),
    VarDef::new("arch", eval::<41>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(41) | flag::FLAM3 | flag::RANDOM)
        .sum()
        .prepare(prepare)
        .batch(batch::<41>),
    VarDef::new("tangent", eval::<42>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(42) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<42>),
    VarDef::new("square", eval::<43>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(43) | flag::FLAM3 | flag::RANDOM)
        .sum()
        .prepare(prepare)
        .batch(batch::<43>),
    VarDef::new("rays", eval::<44>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(44) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<44>),
    VarDef::new("blade", eval::<45>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(45) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<45>),
    VarDef::new("secant2", eval::<46>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(46) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<46>),
    VarDef::new("twintrian", eval::<47>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(47) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<47>),
    VarDef::new("cross", eval::<48>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(48) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<48>),
    VarDef::new("disc2", eval::<49>)
        .params(&[p("disc2_rot", 0.0), p("disc2_twist", 0.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(49) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<49>),
    VarDef::new("super_shape", eval::<50>)
        .params(&[
            p("super_shape_rnd", 0.0),
            p("super_shape_m", 0.0),
            p("super_shape_n1", 1.0),
            p("super_shape_n2", 1.0),
            p("super_shape_n3", 1.0),
            p("super_shape_holes", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(50) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<50>),
    VarDef::new("flower", eval::<51>)
        .params(&[p("flower_petals", 0.0), p("flower_holes", 0.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(51) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<51>),
    VarDef::new("conic", eval::<52>)
        .params(&[p("conic_eccentricity", 1.0), p("conic_holes", 0.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(52) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<52>),
    VarDef::new("parabola", eval::<53>)
        .params(&[p("parabola_height", 0.0), p("parabola_width", 0.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(53) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<53>),
    VarDef::new("bent2", eval::<54>)
        .params(&[p("bent2_x", 1.0), p("bent2_y", 1.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(54) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<54>),
    VarDef::new("bipolar", eval::<55>)
        .params(&[p("bipolar_shift", 0.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(55) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<55>),
    VarDef::new("boarders", eval::<56>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(56) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<56>),
    VarDef::new("butterfly", eval::<57>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(57) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<57>),
    VarDef::new("cell", eval::<58>)
        .params(&[p("cell_size", 1.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(58) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<58>),
    VarDef::new("cpow", eval::<59>)
        .params(&[p("cpow_r", 1.0), p("cpow_i", 0.0), p("cpow_power", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(59) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<59>),
    VarDef::new("curve", eval::<60>)
        .params(&[
            p("curve_xamp", 0.0),
            p("curve_yamp", 0.0),
            p("curve_xlength", 1.0),
            p("curve_ylength", 1.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(60) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<60>),
    VarDef::new("edisc", eval::<61>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(61) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<61>),
    VarDef::new("elliptic", eval::<62>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(62) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<62>),
    VarDef::new("escher", eval::<63>)
        .params(&[p("escher_beta", 3.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX | need::ATAN_XY)
        .flags(zf(63) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<63>),
    VarDef::new("foci", eval::<64>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(64) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<64>),
    VarDef::new("lazysusan", eval::<65>)
        .params(&[
            p("lazysusan_spin", PI),
            p("lazysusan_space", 0.0),
            p("lazysusan_twist", 0.0),
            p("lazysusan_x", 0.0),
            p("lazysusan_y", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(65) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<65>),
    VarDef::new("loonie", eval::<66>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(66) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<66>),
    VarDef::new("pre_blur", eval::<67>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(67) | flag::FLAM3 | flag::HIDDEN)
        .prepare(prepare)
        .batch(batch::<67>),
    VarDef::new("modulus", eval::<68>)
        .params(&[p("modulus_x", 1.0), p("modulus_y", 1.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(68) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<68>),
    VarDef::new("oscilloscope", eval::<69>)
        .params(&[
            p("oscilloscope_separation", 1.0),
            p("oscilloscope_frequency", PI),
            p("oscilloscope_amplitude", 1.0),
            p("oscilloscope_damping", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(69) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<69>),
    VarDef::new("polar2", eval::<70>)
        .needs(need::SUMSQ | need::SQRT | need::ATAN_XY)
        .flags(zf(70) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<70>),
    VarDef::new("popcorn2", eval::<71>)
        .params(&[
            p("popcorn2_x", 0.1),
            p("popcorn2_y", 0.1),
            p("popcorn2_c", 3.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(71) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<71>),
    VarDef::new("scry", eval::<72>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(72) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<72>),
    VarDef::new("separation", eval::<73>)
        .params(&[
            p("separation_x", 1.0),
            p("separation_xinside", 0.0),
            p("separation_y", 1.0),
            p("separation_yinside", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(73) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<73>),
    VarDef::new("split", eval::<74>)
        .params(&[p("split_xsize", 0.5), p("split_ysize", 0.5)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(74) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<74>),
    VarDef::new("splits", eval::<75>)
        .params(&[p("splits_x", 0.0), p("splits_y", 0.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(75) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<75>),
    VarDef::new("stripes", eval::<76>)
        .params(&[p("stripes_space", 0.5), p("stripes_warp", 0.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(76) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<76>),
    VarDef::new("wedge", eval::<77>)
        .params(&[
            p("wedge_angle", FRAC_PI_2),
            p("wedge_hole", 0.0),
            p("wedge_count", 2.0),
            p("wedge_swirl", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(77) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<77>),
    VarDef::new("wedge_julia", eval::<78>)
        .params(&[
            p("wedge_julia_angle", 0.0),
            p("wedge_julia_count", 1.0),
            p("wedge_julia_power", 1.0),
            p("wedge_julia_dist", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(78) | flag::FLAM3 | flag::RANDOM)
        .prepare(prepare)
        .batch(batch::<78>),
    VarDef::new("wedge_sph", eval::<79>)
        .params(&[
            p("wedge_sph_angle", FRAC_PI_2),
            p("wedge_sph_count", 2.0),
            p("wedge_sph_hole", 0.0),
            p("wedge_sph_swirl", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(79) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<79>),
    VarDef::new("whorl", eval::<80>)
        .params(&[p("whorl_inside", 1.0), p("whorl_outside", 1.0)])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(80) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<80>),
    VarDef::new("waves2", eval::<81>)
        .params(&[
            p("waves2_freqx", 2.0),
            p("waves2_scalex", 0.0),
            p("waves2_freqy", 2.0),
            p("waves2_scaley", 0.0),
            p("waves2_freqz", 0.0),
            p("waves2_scalez", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(81) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<81>),
    VarDef::new("exp", eval::<82>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(82) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<82>),
    VarDef::new("log", eval::<83>)
        .params(&[p_range(
            "log_base",
            std::f64::consts::E,
            f64::EPSILON,
            f64::INFINITY,
        )])
        .needs(need::SUMSQ | need::SQRT | need::ATAN_YX)
        .flags(zf(83) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<83>),
    VarDef::new("sin", eval::<84>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(84) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<84>),
    VarDef::new("cos", eval::<85>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(85) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<85>),
    VarDef::new("tan", eval::<86>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(86) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<86>),
    VarDef::new("sec", eval::<87>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(87) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<87>),
    VarDef::new("csc", eval::<88>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(88) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<88>),
    VarDef::new("cot", eval::<89>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(89) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<89>),
    VarDef::new("sinh", eval::<90>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(90) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<90>),
    VarDef::new("cosh", eval::<91>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(91) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<91>),
    VarDef::new("tanh", eval::<92>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(92) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<92>),
    VarDef::new("sech", eval::<93>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(93) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<93>),
    VarDef::new("csch", eval::<94>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(94) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<94>),
    VarDef::new("coth", eval::<95>)
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(95) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<95>),
    VarDef::new("auger", eval::<96>)
        .params(&[
            p("auger_freq", 5.0),
            p("auger_weight", 0.5),
            p("auger_sym", 0.0),
            p("auger_scale", 0.1),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(96) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<96>),
    VarDef::new("flux", eval::<97>)
        .params(&[p("flux_spread", 0.0)])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(97) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<97>),
    VarDef::new("mobius", eval::<98>)
        .params(&[
            p("mobius_re_a", 1.0),
            p("mobius_im_a", 0.0),
            p("mobius_re_b", 0.0),
            p("mobius_im_b", 0.0),
            p("mobius_re_c", 0.0),
            p("mobius_im_c", 0.0),
            p("mobius_re_d", 1.0),
            p("mobius_im_d", 0.0),
        ])
        .needs(need::SUMSQ | need::SQRT)
        .flags(zf(98) | flag::FLAM3)
        .prepare(prepare)
        .batch(batch::<98>),
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
fn z_out(id: u16, v: &Prepared, t: &VarIn) -> f64 {
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
    let (x, y) = formula(ID, v, t, &v.aff, rng);
    [x, y, z_out(ID, v, t)]
}

/// The batch version: a loop the compiler can vectorise for variations without library calls.
/// (One function per variation: inlining every formula into one loop let LLVM speculate the
/// transcendental calls of other arms, which made every xform ~20x slower.)
///
/// Compiled twice, for the baseline CPU and with AVX2 and FMA (four points per instruction
/// instead of two), chosen at run time. Rust never fuses a multiply and an add on its own, so
/// both copies give the same bits.
fn batch<const ID: u16>(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
    #[cfg(target_arch = "x86_64")]
    if crate::flame::fastmath::has_avx2_fma() {
        // SAFETY: the CPU has reported AVX2 and FMA.
        return unsafe { batch_avx2::<ID>(v, s, acc, rng) };
    }
    batch_loop::<ID>(v, s, acc, rng)
}

/// [`batch`] for CPUs with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn batch_avx2<const ID: u16>(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
    batch_loop::<ID>(v, s, acc, rng)
}

#[inline(always)]
fn batch_loop<const ID: u16>(v: &Prepared, s: &SoaIn, acc: &mut SoaAcc, rng: &mut FastRng) {
    let n = acc.x.len();
    let (ax, ay) = (&mut acc.x[..n], &mut acc.y[..n]);
    let (x, y, sumsq, sqrt) = (&s.x[..n], &s.y[..n], &s.sumsq[..n], &s.sqrt[..n]);
    let (ux, uy, atan_xy, atan_yx) = (&s.ux[..n], &s.uy[..n], &s.atan_xy[..n], &s.atan_yx[..n]);
    let (z, az) = (&s.z[..n], &mut acc.z[..n]);
    for j in 0..n {
        let t = VarIn {
            x: x[j],
            y: y[j],
            z: z[j],
            sumsq: sumsq[j],
            sqrt: sqrt[j],
            ux: ux[j],
            uy: uy[j],
            atan_xy: atan_xy[j],
            atan_yx: atan_yx[j],
            color: 0.0,
        };
        let (dx, dy) = formula(ID, v, &t, &v.aff, rng);
        ax[j] += dx;
        ay[j] += dy;
        if writes_z(ID) {
            az[j] += z_out(ID, v, &t);
        }
    }
}

#[inline(always)]
fn formula(id: u16, v: &Prepared, t: &VarIn, aff: &Affine, rng: &mut FastRng) -> (f64, f64) {
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
            // Guard of the thesis program kept by ugnis: θ = 0 at the origin.
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
            (w * c * y.cosh(), -w * s * y.sinh())
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
            if v.compat {
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
            let a = if v.compat {
                let k = rand_size(rng, abs_power);
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
            let a = if v.compat {
                let k = (abs_power * rng.f01()).trunc();
                if (k as i64) & 1 == 0 {
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
            let r = if v.compat {
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
                if v.compat && v.form == Form::Regular {
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
            let a2 = if v.compat {
                -(x / xmax).clamp(-1.0, 1.0).acos()
            } else {
                (x / xmax).acos()
            };
            let ww = w / 11.57034632;
            let (mut snv, csv) = sincos(a1);
            let snhu = a2.sinh();
            let cshu = a2.cosh();
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
            let a = if v.compat { t.atan_yx } else { t.atan_xy };
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
            if r < w {
                let a = yy.atan2(xx) + spin + twist * (w - r);
                let (s, c) = sincos(a);
                (w * (r * c + lx), w * (r * s - ly))
            } else {
                let r = 1.0 + space / zeps(r);
                (w * (r * xx + lx), w * (r * yy - ly))
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
            let k = rand_size(rng, abs_power);
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
            let (x, y) = if v.compat {
                (x, y)
            } else {
                (x * FRAC_PI_2, y * FRAC_PI_2)
            };
            let (s, c) = sincos(x);
            (w * s * y.cosh(), w * c * y.sinh())
        }
        COS => {
            let (x, y) = if v.compat {
                (x, y)
            } else {
                (x * FRAC_PI_2, y * FRAC_PI_2)
            };
            let (s, c) = sincos(x);
            (w * c * y.cosh(), -(w * s * y.sinh()))
        }
        TAN => {
            if v.compat {
                let (s, c) = sincos(2.0 * x);
                let den = 1.0 / zeps(c + (2.0 * y).cosh());
                (w * den * s, w * den * (2.0 * y).sinh())
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let den = w / zeps(fm::cos(x) + y.cosh());
                (fm::sin(x) * den, y.sinh() * den)
            }
        }
        SEC => {
            let (x, y) = if v.compat { (x, y) } else { (x * PI, y * PI) };
            let (s, c) = sincos(x);
            let den = w * (2.0 / zeps(fm::cos(2.0 * x) + (2.0 * y).cosh()));
            (den * c * y.cosh(), den * s * y.sinh())
        }
        CSC => {
            if v.compat {
                let (s, c) = sincos(x);
                let den = 2.0 / zeps((2.0 * y).cosh() - fm::cos(2.0 * x));
                (w * den * s * y.cosh(), -(w * den * c * y.sinh()))
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let (s, c) = sincos(x);
                let sh = y.sinh();
                let den = 2.0 * w / (1.0 + 2.0 * sh * sh - fm::cos(2.0 * x));
                (den * s * y.cosh(), den * c * sh)
            }
        }
        COT => {
            if v.compat {
                let (s, c) = sincos(2.0 * x);
                let den = 1.0 / zeps((2.0 * y).cosh() - c);
                (w * den * s, w * den * -(2.0 * y).sinh())
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let (s, c) = sincos(x);
                let den = w / zeps(y.cosh() - c);
                (den * s, den * y.sinh())
            }
        }
        SINH => {
            let (x, y) = if v.compat {
                (x, y)
            } else {
                (x * FRAC_PI_4, y * FRAC_PI_4)
            };
            let (s, c) = sincos(y);
            (w * x.sinh() * c, w * x.cosh() * s)
        }
        COSH => {
            let (x, y) = if v.compat {
                (x, y)
            } else {
                (x * FRAC_PI_2, y * FRAC_PI_2)
            };
            let (s, c) = sincos(y);
            (w * x.cosh() * c, w * x.sinh() * s)
        }
        TANH => {
            if v.compat {
                let (s, c) = sincos(2.0 * y);
                let den = 1.0 / zeps(c + (2.0 * x).cosh());
                (w * den * (2.0 * x).sinh(), w * den * s)
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let (s, c) = sincos(y);
                let den = w / zeps(c + x.cosh());
                (den * x.sinh(), den * s)
            }
        }
        SECH => {
            if v.compat {
                let (s, c) = sincos(y);
                let den = 2.0 / zeps(fm::cos(2.0 * y) + (2.0 * x).cosh());
                (w * den * c * x.cosh(), -(w * den * s * x.sinh()))
            } else {
                let (x, y) = (x * FRAC_PI_4, y * FRAC_PI_4);
                let (s, c) = sincos(y);
                let den = w * (2.0 / zeps(fm::cos(y * 2.0) + (x * 2.0).cosh()));
                (den * c * x.cosh(), den * s * x.sinh())
            }
        }
        CSCH => {
            if v.compat {
                let (s, c) = sincos(y);
                let den = 2.0 / zeps((2.0 * x).cosh() - fm::cos(2.0 * y));
                (w * den * x.sinh() * c, -(w * den * x.cosh() * s))
            } else {
                let (x, y) = (x * FRAC_PI_4, y * FRAC_PI_4);
                let (s, c) = sincos(y);
                let den = w * (2.0 / zeps((2.0 * x).cosh() - fm::cos(2.0 * y)));
                (den * x.sinh() * c, den * x.cosh() * s)
            }
        }
        COTH => {
            if v.compat {
                let (s, c) = sincos(2.0 * y);
                let den = 1.0 / zeps((2.0 * x).cosh() - c);
                (w * den * (2.0 * x).sinh(), w * den * s)
            } else {
                let (x, y) = (x * FRAC_PI_2, y * FRAC_PI_2);
                let (s, c) = sincos(y);
                let den = w / zeps(x.cosh() - c);
                (den * x.sinh(), den * s)
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
