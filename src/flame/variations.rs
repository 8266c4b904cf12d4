//! flam3's 99 variations (flame.md §4): registry (names, parameters, defaults) and formulas.
//!
//! Every formula returns the *weighted* contribution that is added to the xform's variation sum,
//! exactly as flam3 accumulates it (a few variations use the weight non-linearly, e.g. `whorl`,
//! `loonie`, `lazysusan`, `scry`, `flux`). Angles follow flam3: θ_F = atan2(x, y) ("atan"),
//! φ = atan2(y, x) ("atanyx"), sA = x/r, cA = y/r.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use crate::flame::fastmath as fm;
use crate::flame::model::Affine;
use crate::flame::rng::FastRng;

/// flam3's `EPS`.
pub const EPS: f64 = 1e-10;

/// A variation is identified by its flam3 index (0–98).
pub type VarId = u8;

/// Registry entry of one variation.
#[derive(Debug)]
pub struct VariationInfo {
    pub name: &'static str,
    /// Parameter suffixes (XML attribute `<name>_<param>`) and defaults.
    pub params: &'static [(&'static str, f64)],
}

impl VariationInfo {
    pub fn defaults(&self) -> Vec<f64> {
        self.params.iter().map(|p| p.1).collect()
    }
}

macro_rules! registry {
    ($($idx:literal $konst:ident $name:literal [$($p:literal = $d:expr),*]),* $(,)?) => {
        $(pub const $konst: VarId = $idx;)*
        /// All variations in flam3 order.
        pub static VARIATIONS: [VariationInfo; 99] = [
            $(VariationInfo { name: $name, params: &[$(($p, $d)),*] }),*
        ];
    };
}

registry! {
    0 LINEAR "linear" [],
    1 SINUSOIDAL "sinusoidal" [],
    2 SPHERICAL "spherical" [],
    3 SWIRL "swirl" [],
    4 HORSESHOE "horseshoe" [],
    5 POLAR "polar" [],
    6 HANDKERCHIEF "handkerchief" [],
    7 HEART "heart" [],
    8 DISC "disc" [],
    9 SPIRAL "spiral" [],
    10 HYPERBOLIC "hyperbolic" [],
    11 DIAMOND "diamond" [],
    12 EX "ex" [],
    13 JULIA "julia" [],
    14 BENT "bent" [],
    15 WAVES "waves" [],
    16 FISHEYE "fisheye" [],
    17 POPCORN "popcorn" [],
    18 EXPONENTIAL "exponential" [],
    19 POWER "power" [],
    20 COSINE "cosine" [],
    21 RINGS "rings" [],
    22 FAN "fan" [],
    23 BLOB "blob" ["low" = 0.0, "high" = 1.0, "waves" = 1.0],
    24 PDJ "pdj" ["a" = 0.0, "b" = 0.0, "c" = 0.0, "d" = 0.0],
    25 FAN2 "fan2" ["x" = 0.0, "y" = 0.0],
    26 RINGS2 "rings2" ["val" = 0.0],
    27 EYEFISH "eyefish" [],
    28 BUBBLE "bubble" [],
    29 CYLINDER "cylinder" [],
    30 PERSPECTIVE "perspective" ["angle" = 0.0, "dist" = 0.0],
    31 NOISE "noise" [],
    32 JULIAN "julian" ["power" = 1.0, "dist" = 1.0],
    33 JULIASCOPE "juliascope" ["power" = 1.0, "dist" = 1.0],
    34 BLUR "blur" [],
    35 GAUSSIAN_BLUR "gaussian_blur" [],
    36 RADIAL_BLUR "radial_blur" ["angle" = 0.0],
    37 PIE "pie" ["slices" = 6.0, "rotation" = 0.0, "thickness" = 0.5],
    38 NGON "ngon" ["sides" = 5.0, "power" = 3.0, "circle" = 1.0, "corners" = 2.0],
    39 CURL "curl" ["c1" = 1.0, "c2" = 0.0],
    40 RECTANGLES "rectangles" ["x" = 1.0, "y" = 1.0],
    41 ARCH "arch" [],
    42 TANGENT "tangent" [],
    43 SQUARE "square" [],
    44 RAYS "rays" [],
    45 BLADE "blade" [],
    46 SECANT2 "secant2" [],
    47 TWINTRIAN "twintrian" [],
    48 CROSS "cross" [],
    49 DISC2 "disc2" ["rot" = 0.0, "twist" = 0.0],
    50 SUPER_SHAPE "super_shape" ["rnd" = 0.0, "m" = 0.0, "n1" = 1.0, "n2" = 1.0, "n3" = 1.0, "holes" = 0.0],
    51 FLOWER "flower" ["petals" = 0.0, "holes" = 0.0],
    52 CONIC "conic" ["eccentricity" = 1.0, "holes" = 0.0],
    53 PARABOLA "parabola" ["height" = 0.0, "width" = 0.0],
    54 BENT2 "bent2" ["x" = 1.0, "y" = 1.0],
    55 BIPOLAR "bipolar" ["shift" = 0.0],
    56 BOARDERS "boarders" [],
    57 BUTTERFLY "butterfly" [],
    58 CELL "cell" ["size" = 1.0],
    59 CPOW "cpow" ["r" = 1.0, "i" = 0.0, "power" = 1.0],
    60 CURVE "curve" ["xamp" = 0.0, "yamp" = 0.0, "xlength" = 1.0, "ylength" = 1.0],
    61 EDISC "edisc" [],
    62 ELLIPTIC "elliptic" [],
    63 ESCHER "escher" ["beta" = 0.0],
    64 FOCI "foci" [],
    65 LAZYSUSAN "lazysusan" ["spin" = 0.0, "space" = 0.0, "twist" = 0.0, "x" = 0.0, "y" = 0.0],
    66 LOONIE "loonie" [],
    67 PRE_BLUR "pre_blur" [],
    68 MODULUS "modulus" ["x" = 0.0, "y" = 0.0],
    69 OSCILLOSCOPE "oscilloscope" ["separation" = 1.0, "frequency" = PI, "amplitude" = 1.0, "damping" = 0.0],
    70 POLAR2 "polar2" [],
    71 POPCORN2 "popcorn2" ["x" = 0.0, "y" = 0.0, "c" = 0.0],
    72 SCRY "scry" [],
    73 SEPARATION "separation" ["x" = 0.0, "xinside" = 0.0, "y" = 0.0, "yinside" = 0.0],
    74 SPLIT "split" ["xsize" = 0.0, "ysize" = 0.0],
    75 SPLITS "splits" ["x" = 0.0, "y" = 0.0],
    76 STRIPES "stripes" ["space" = 0.0, "warp" = 0.0],
    77 WEDGE "wedge" ["angle" = 0.0, "hole" = 0.0, "count" = 1.0, "swirl" = 0.0],
    78 WEDGE_JULIA "wedge_julia" ["angle" = 0.0, "count" = 1.0, "power" = 1.0, "dist" = 0.0],
    79 WEDGE_SPH "wedge_sph" ["angle" = 0.0, "count" = 1.0, "hole" = 0.0, "swirl" = 0.0],
    80 WHORL "whorl" ["inside" = 0.0, "outside" = 0.0],
    81 WAVES2 "waves2" ["freqx" = 0.0, "scalex" = 0.0, "freqy" = 0.0, "scaley" = 0.0],
    82 EXP "exp" [],
    83 LOG "log" [],
    84 SIN "sin" [],
    85 COS "cos" [],
    86 TAN "tan" [],
    87 SEC "sec" [],
    88 CSC "csc" [],
    89 COT "cot" [],
    90 SINH "sinh" [],
    91 COSH "cosh" [],
    92 TANH "tanh" [],
    93 SECH "sech" [],
    94 CSCH "csch" [],
    95 COTH "coth" [],
    96 AUGER "auger" ["freq" = 1.0, "weight" = 0.5, "sym" = 0.0, "scale" = 1.0],
    97 FLUX "flux" ["spread" = 0.0],
    98 MOBIUS "mobius" ["re_a" = 0.0, "im_a" = 0.0, "re_b" = 0.0, "im_b" = 0.0, "re_c" = 0.0, "im_c" = 0.0, "re_d" = 0.0, "im_d" = 0.0],
}

/// The seven variations of the thesis program's menu, in menu order.
pub const THESIS_SEVEN: [VarId; 7] = [LINEAR, SINUSOIDAL, SPHERICAL, SWIRL, HORSESHOE, POLAR, BENT];

/// Number of variations in flam3's list.
pub const COUNT: usize = 99;

pub fn info(id: VarId) -> &'static VariationInfo {
    &VARIATIONS[id as usize]
}

/// Look a variation up by its flam3 name.
pub fn by_name(name: &str) -> Option<VarId> {
    VARIATIONS
        .iter()
        .position(|v| v.name == name)
        .map(|i| i as VarId)
}

/// True when ugnis renders this variation. All 99 of flam3's list are implemented; names of
/// variations from other programs (Apophysis plugins, JWildfire) are kept but not rendered.
pub fn is_implemented(_id: VarId) -> bool {
    true
}

/// Names of variations other flame programs write that ugnis keeps for round trip but cannot
/// render (a subset of well-known plugin names). Used to tell a variation from an arbitrary
/// unknown attribute.
const FOREIGN_VARIATIONS: &[&str] = &[
    "linear3D",
    "bubble2",
    "cross2",
    "epispiral",
    "hemisphere",
    "julia3D",
    "juliaN",
    "julia3Dz",
    "lissajous",
    "spirograph",
    "target",
    "truchet",
    "rose_wf",
    "polynomial",
    "splits3D",
    "checks",
    "circlize",
    "circlecrop",
    "collideoscope",
    "crackle",
    "dc_linear",
    "eclipse",
    "falloff2",
    "glynnia",
    "hypertile",
    "loonie2",
    "murl",
    "npolar",
    "ortho",
    "phoenix_julia",
    "post_mirror_wf",
    "pre_rotate_x",
    "spherical3D",
    "sphericalN",
    "supershape3d",
    "swirl3",
    "xheart",
    "zblur",
    "ztranslate",
    "zcone",
    "blur3D",
    "bwraps",
    "bwraps7",
    "cosh",
    "curl3D",
    "exblur",
    "flipcircle",
    "flipy",
    "gdoffs",
    "hexes",
    "julian2",
    "juliaq",
    "lazyjess",
    "mandelbrot",
    "nblur",
    "boarders2",
    "oscope",
    "pdj3d",
    "perspective2",
    "sinusoidal3d",
    "tile_hlp",
    "waves2_3D",
    "wedge_julia_3D",
    "whorl3D",
];

/// True for names of flam3 variations and well-known variations of other programs: attributes
/// that describe a variation weight rather than something else.
pub fn is_flam3_variation_name(name: &str) -> bool {
    by_name(name).is_some() || FOREIGN_VARIATIONS.contains(&name)
}

/// If `attr` is `<variation>_<param>` of a flam3 variation, the variation and parameter index.
pub fn param_of(attr: &str) -> Option<(VarId, usize)> {
    // Longest variation name first so that "wedge_julia_power" is not read as "wedge" + ….
    let mut best: Option<(VarId, usize, usize)> = None;
    for (i, v) in VARIATIONS.iter().enumerate() {
        if v.params.is_empty() {
            continue;
        }
        if let Some(rest) = attr.strip_prefix(v.name).and_then(|r| r.strip_prefix('_'))
            && let Some(pi) = v.params.iter().position(|p| p.0 == rest)
            && best.is_none_or(|b| v.name.len() > b.2)
        {
            best = Some((i as VarId, pi, v.name.len()));
        }
    }
    best.map(|b| (b.0, b.1))
}

/// Which derived quantities an xform's variations need (flam3 "precalc" flags).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Needs {
    pub sqrt: bool,
    pub atan: bool,
    pub atanyx: bool,
    pub sincos_a: bool,
}

impl Needs {
    pub fn of(id: VarId) -> Needs {
        let mut n = Needs {
            sqrt: true,
            ..Needs::default()
        };
        match id {
            // Formulas that read neither r² nor r: the batch path skips computing them.
            LINEAR | SINUSOIDAL | BENT | WAVES | POPCORN | EXPONENTIAL | COSINE => n.sqrt = false,
            POLAR | HANDKERCHIEF | HEART | DISC | EX | JULIA | FAN | FAN2 | DISC2 | POLAR2 => {
                n.atan = true;
            }
            BLOB => {
                n.atan = true;
                n.sincos_a = true;
            }
            SPIRAL | HYPERBOLIC | DIAMOND | POWER | RINGS | RINGS2 => n.sincos_a = true,
            JULIAN | JULIASCOPE | NGON | CPOW | ESCHER | LOG | WEDGE_JULIA | WHORL | WEDGE
            | WEDGE_SPH | SUPER_SHAPE | FLOWER | RADIAL_BLUR => n.atanyx = true,
            _ => {}
        }
        n
    }

    pub fn union(self, o: Needs) -> Needs {
        Needs {
            sqrt: self.sqrt || o.sqrt,
            atan: self.atan || o.atan,
            atanyx: self.atanyx || o.atanyx,
            sincos_a: self.sincos_a || o.sincos_a,
        }
    }
}

/// Per-point quantities shared by an xform's variations.
#[derive(Clone, Copy, Debug, Default)]
pub struct Pre {
    pub x: f64,
    pub y: f64,
    pub sumsq: f64,
    pub sqrt: f64,
    /// θ_F = atan2(x, y).
    pub atan: f64,
    /// φ = atan2(y, x).
    pub atanyx: f64,
    /// sA = x/r.
    pub sina: f64,
    /// cA = y/r.
    pub cosa: f64,
}

impl Pre {
    #[inline(always)]
    pub fn new(x: f64, y: f64, needs: Needs) -> Pre {
        let sumsq = x * x + y * y;
        let mut p = Pre {
            x,
            y,
            sumsq,
            ..Pre::default()
        };
        // flam3 always computes the radius; so do we.
        p.sqrt = sumsq.sqrt();
        if needs.atan {
            p.atan = fm::atan2(x, y);
        }
        if needs.atanyx {
            p.atanyx = fm::atan2(y, x);
        }
        if needs.sincos_a {
            p.sina = x / p.sqrt;
            p.cosa = y / p.sqrt;
        }
        p
    }

    /// All quantities (for tests and one-off evaluation).
    pub fn full(x: f64, y: f64) -> Pre {
        Pre::new(
            x,
            y,
            Needs {
                sqrt: true,
                atan: true,
                atanyx: true,
                sincos_a: true,
            },
        )
    }
}

/// A variation ready for the chaos game: weight, raw parameters (slots 0..8) and values derived
/// from them once (slots 8..12).
#[derive(Clone, Copy, Debug)]
pub struct Prepared {
    pub id: VarId,
    pub w: f64,
    pub p: [f64; 12],
    /// The variation's formula.
    pub f: VarFn,
    /// The variation's formula over a batch of points.
    pub batch: BatchFn,
}

impl Prepared {
    pub fn new(id: VarId, w: f64, params: &[f64]) -> Prepared {
        let mut p = [0.0; 12];
        let defaults = info(id).params;
        for (i, d) in defaults.iter().enumerate() {
            p[i] = params.get(i).copied().unwrap_or(d.1);
        }
        match id {
            PERSPECTIVE => {
                let ang = p[0] * PI / 2.0;
                p[8] = ang.sin();
                p[9] = p[1] * ang.cos();
            }
            JULIAN | JULIASCOPE => {
                p[8] = p[0].abs();
                p[9] = p[1] / p[0] / 2.0;
            }
            RADIAL_BLUR => {
                let ang = p[0] * PI / 2.0;
                p[8] = ang.sin();
                p[9] = ang.cos();
            }
            DISC2 => {
                let (rot, twist) = (p[0], p[1]);
                p[8] = rot * PI;
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
                p[9] = sinadd;
                p[10] = cosadd;
            }
            SUPER_SHAPE => {
                p[8] = p[1] / 4.0;
                p[9] = -1.0 / p[2];
            }
            NGON => {
                p[8] = p[1] / 2.0;
                p[9] = 2.0 * PI / p[0];
            }
            CPOW => {
                p[8] = 2.0 * PI / p[2];
                p[9] = p[0] / p[2];
                p[10] = p[1] / p[2];
            }
            CURVE => {
                p[8] = (p[2] * p[2]).max(1e-20);
                p[9] = (p[3] * p[3]).max(1e-20);
            }
            ESCHER => {
                p[8] = 0.5 * (1.0 + p[0].cos());
                p[9] = 0.5 * p[0].sin();
            }
            WEDGE_JULIA => {
                // params: angle, count, power, dist
                p[8] = 1.0 - p[0] * p[1] / (2.0 * PI);
                p[9] = p[2].abs();
                p[10] = p[3] / p[2] / 2.0;
            }
            OSCILLOSCOPE => {
                p[8] = 2.0 * PI * p[1];
            }
            _ => {}
        }
        Prepared {
            id,
            w,
            p,
            f: FORMULAS[id as usize],
            batch: BATCH_FORMULAS[id as usize],
        }
    }
}

#[inline(always)]
fn sincos(a: f64) -> (f64, f64) {
    fm::sin_cos(a)
}

/// Signature of one variation's formula.
pub type VarFn = fn(&Prepared, &Pre, &Affine, &mut FastRng) -> (f64, f64);

/// Per-point quantities of a batch of points, as parallel arrays (all of the same length).
/// Arrays of quantities the xform does not need may be empty.
pub struct Soa<'a> {
    pub x: &'a [f64],
    pub y: &'a [f64],
    pub sumsq: &'a [f64],
    pub sqrt: &'a [f64],
    pub atan: &'a [f64],
    pub atanyx: &'a [f64],
    pub sina: &'a [f64],
    pub cosa: &'a [f64],
}

/// Signature of one variation applied to a batch of points: adds to `px`, `py`.
pub type BatchFn = fn(&Prepared, &Soa, &Affine, &mut FastRng, &mut [f64], &mut [f64]);

/// One function per variation: the match below collapses to a single arm for a constant id.
/// (Inlining the whole match into the chaos-game loop lets LLVM speculate the transcendental
/// calls of other arms, which made every xform ~20× slower.)
fn var_impl<const ID: u8>(v: &Prepared, t: &Pre, aff: &Affine, rng: &mut FastRng) -> (f64, f64) {
    formula(ID, v, t, aff, rng)
}

/// The batch version: a loop the compiler can vectorise for variations without library calls.
fn batch_impl<const ID: u8>(
    v: &Prepared,
    s: &Soa,
    aff: &Affine,
    rng: &mut FastRng,
    px: &mut [f64],
    py: &mut [f64],
) {
    let n = px.len();
    let py = &mut py[..n];
    let (x, y) = (&s.x[..n], &s.y[..n]);
    let needs = Needs::of(ID);
    let sumsq = &s.sumsq[..n];
    let sqrt = &s.sqrt[..n];
    // Arrays a variation does not need are not read (and may be empty).
    let atan = if needs.atan { &s.atan[..n] } else { sqrt };
    let atanyx = if needs.atanyx { &s.atanyx[..n] } else { sqrt };
    let (sina, cosa) = if needs.sincos_a {
        (&s.sina[..n], &s.cosa[..n])
    } else {
        (sqrt, sqrt)
    };
    for j in 0..n {
        let t = Pre {
            x: x[j],
            y: y[j],
            sumsq: sumsq[j],
            sqrt: sqrt[j],
            atan: atan[j],
            atanyx: atanyx[j],
            sina: sina[j],
            cosa: cosa[j],
        };
        let (dx, dy) = formula(ID, v, &t, aff, rng);
        px[j] += dx;
        py[j] += dy;
    }
}

macro_rules! fn_tables {
    ($($i:literal)*) => {
        /// Formula functions in flam3 order.
        pub static FORMULAS: [VarFn; 99] = [$(var_impl::<$i> as VarFn),*];
        /// Batch formula functions in flam3 order.
        pub static BATCH_FORMULAS: [BatchFn; 99] = [$(batch_impl::<$i> as BatchFn),*];
    };
}

fn_tables!(
    0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33
    34 35 36 37 38 39 40 41 42 43 44 45 46 47 48 49 50 51 52 53 54 55 56 57 58 59 60 61 62 63 64
    65 66 67 68 69 70 71 72 73 74 75 76 77 78 79 80 81 82 83 84 85 86 87 88 89 90 91 92 93 94 95
    96 97 98
);

/// The weighted contribution of variation `v` at the pre-affine point `t`.
/// `aff` is the xform's pre-affine (dependent variations read b, d, e, f from it).
#[inline(always)]
pub fn apply(v: &Prepared, t: &Pre, aff: &Affine, rng: &mut FastRng) -> (f64, f64) {
    (v.f)(v, t, aff, rng)
}

#[inline(always)]
fn formula(id: VarId, v: &Prepared, t: &Pre, aff: &Affine, rng: &mut FastRng) -> (f64, f64) {
    let w = v.w;
    let p = &v.p;
    let (x, y) = (t.x, t.y);
    match id {
        LINEAR => (w * x, w * y),
        SINUSOIDAL => (w * fm::sin(x), w * fm::sin(y)),
        SPHERICAL => {
            let r2 = w / (t.sumsq + EPS);
            (r2 * x, r2 * y)
        }
        SWIRL => {
            let (s, c) = sincos(t.sumsq);
            (w * (s * x - c * y), w * (c * x + s * y))
        }
        HORSESHOE => {
            let r = w / (t.sqrt + EPS);
            ((x - y) * (x + y) * r, 2.0 * x * y * r)
        }
        POLAR => {
            // Guard of the thesis program kept by ugnis: θ = 0 at the origin.
            let a = if x.abs() <= EPS && y.abs() <= EPS {
                0.0
            } else {
                t.atan
            };
            (w * a / PI, w * (t.sqrt - 1.0))
        }
        HANDKERCHIEF => {
            let a = t.atan;
            let r = t.sqrt;
            (w * r * fm::sin(a + r), w * r * fm::cos(a - r))
        }
        HEART => {
            let a = t.sqrt * t.atan;
            let (s, c) = sincos(a);
            let r = w * t.sqrt;
            (r * s, -r * c)
        }
        DISC => {
            let a = t.atan / PI;
            let (s, c) = sincos(PI * t.sqrt);
            (w * s * a, w * c * a)
        }
        SPIRAL => {
            let r = t.sqrt + EPS;
            let r1 = w / r;
            let (s, c) = sincos(r);
            (r1 * (t.cosa + s), r1 * (t.sina - c))
        }
        HYPERBOLIC => {
            let r = t.sqrt + EPS;
            (w * t.sina / r, w * t.cosa * r)
        }
        DIAMOND => {
            let (s, c) = sincos(t.sqrt);
            (w * t.sina * c, w * t.cosa * s)
        }
        EX => {
            let a = t.atan;
            let r = t.sqrt;
            let n0 = fm::sin(a + r);
            let n1 = fm::cos(a - r);
            let m0 = n0 * n0 * n0 * r;
            let m1 = n1 * n1 * n1 * r;
            (w * (m0 + m1), w * (m0 - m1))
        }
        JULIA => {
            let mut a = 0.5 * t.atan;
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
            let dx2 = 1.0 / (aff.e * aff.e + EPS);
            let dy2 = 1.0 / (aff.f * aff.f + EPS);
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
            let dx = (3.0 * y).tan();
            let dy = (3.0 * x).tan();
            (w * (x + aff.e * fm::sin(dx)), w * (y + aff.f * fm::sin(dy)))
        }
        EXPONENTIAL => {
            let d = w * (x - 1.0).exp();
            let (s, c) = sincos(PI * y);
            (d * c, d * s)
        }
        POWER => {
            let r = w * t.sqrt.powf(t.sina);
            (r * t.cosa, r * t.sina)
        }
        COSINE => {
            let a = x * PI;
            let (s, c) = sincos(a);
            (w * c * y.cosh(), -w * s * y.sinh())
        }
        RINGS => {
            let dx = aff.e * aff.e + EPS;
            let r = t.sqrt;
            let r = w * ((r + dx) % (2.0 * dx) - dx + r * (1.0 - dx));
            (r * t.cosa, r * t.sina)
        }
        FAN => {
            let dx = PI * (aff.e * aff.e + EPS);
            let dx2 = 0.5 * dx;
            let mut a = t.atan;
            let r = w * t.sqrt;
            a += if (a + aff.f) % dx > dx2 { -dx2 } else { dx2 };
            let (s, c) = sincos(a);
            (r * c, r * s)
        }
        BLOB => {
            let (low, high, waves) = (p[0], p[1], p[2]);
            let r = t.sqrt * (low + (high - low) * (0.5 + 0.5 * fm::sin(waves * t.atan)));
            (w * t.sina * r, w * t.cosa * r)
        }
        PDJ => {
            let nx1 = fm::cos(p[1] * x);
            let nx2 = fm::sin(p[0] * y);
            let ny1 = fm::sin(p[2] * x);
            let ny2 = fm::cos(p[3] * y);
            (w * (nx2 - nx1), w * (ny1 - ny2))
        }
        FAN2 => {
            let dy = p[1];
            let dx = PI * (p[0] * p[0] + EPS);
            let dx2 = 0.5 * dx;
            let mut a = t.atan;
            let r = w * t.sqrt;
            let tt = a + dy - dx * ((a + dy) / dx).trunc();
            if tt > dx2 {
                a -= dx2;
            } else {
                a += dx2;
            }
            let (s, c) = sincos(a);
            (r * s, r * c)
        }
        RINGS2 => {
            let mut r = t.sqrt;
            let dx = p[0] * p[0] + EPS;
            r += -2.0 * dx * ((r + dx) / (2.0 * dx)).trunc() + r * (1.0 - dx);
            (w * t.sina * r, w * t.cosa * r)
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
            let tt = 1.0 / (p[1] - y * p[8]);
            (w * p[1] * x * tt, w * p[9] * y * tt)
        }
        NOISE => {
            let a = rng.f01() * 2.0 * PI;
            let (s, c) = sincos(a);
            let r = w * rng.f01();
            (x * r * c, y * r * s)
        }
        JULIAN => {
            let trnd = (p[8] * rng.f01()).trunc();
            let a = (t.atanyx + 2.0 * PI * trnd) / p[0];
            let r = w * t.sumsq.powf(p[9]);
            let (s, c) = sincos(a);
            (r * c, r * s)
        }
        JULIASCOPE => {
            let trnd = (p[8] * rng.f01()).trunc();
            let a = if (trnd as i64) & 1 == 0 {
                (2.0 * PI * trnd + t.atanyx) / p[0]
            } else {
                (2.0 * PI * trnd - t.atanyx) / p[0]
            };
            let r = w * t.sumsq.powf(p[9]);
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
            let rnd_g = w * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
            let ra = t.sqrt;
            let tmpa = t.atanyx + p[8] * rnd_g;
            let (s, c) = sincos(tmpa);
            let rz = p[9] * rnd_g - 1.0;
            (ra * c + rz * x, ra * s + rz * y)
        }
        PIE => {
            let (slices, rotation, thickness) = (p[0], p[1], p[2]);
            let sl = (rng.f01() * slices + 0.5).trunc();
            let a = rotation + 2.0 * PI * (sl + rng.f01() * thickness) / slices;
            let r = w * rng.f01();
            let (s, c) = sincos(a);
            (r * c, r * s)
        }
        NGON => {
            let (circle, corners) = (p[2], p[3]);
            let r_factor = t.sumsq.powf(p[8]);
            let b = p[9];
            let mut phi = t.atanyx - b * (t.atanyx / b).floor();
            if phi > b / 2.0 {
                phi -= b;
            }
            let amp = (corners * (1.0 / (fm::cos(phi) + EPS) - 1.0) + circle) / (r_factor + EPS);
            (w * x * amp, w * y * amp)
        }
        CURL => {
            let (c1, c2) = (p[0], p[1]);
            let re = 1.0 + c1 * x + c2 * (x * x - y * y);
            let im = c1 * y + 2.0 * c2 * x * y;
            let r = w / (re * re + im * im);
            ((x * re + y * im) * r, (y * re - x * im) * r)
        }
        RECTANGLES => {
            let (rx, ry) = (p[0], p[1]);
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
        TANGENT => (w * fm::sin(x) / fm::cos(y), w * y.tan()),
        SQUARE => (w * (rng.f01() - 0.5), w * (rng.f01() - 0.5)),
        RAYS => {
            let ang = w * rng.f01() * PI;
            let r = w / (t.sumsq + EPS);
            let tanr = w * ang.tan() * r;
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
            if !diff.is_finite() {
                diff = -30.0;
            }
            (w * x * diff, w * x * (diff - s * PI))
        }
        CROSS => {
            let s = x * x - y * y;
            let r = w * (1.0 / (s * s + EPS)).sqrt();
            (x * r, y * r)
        }
        DISC2 => {
            let tt = p[8] * (x + y);
            let (s, c) = sincos(tt);
            let r = w * t.atan / PI;
            ((s + p[10]) * r, (c + p[9]) * r)
        }
        SUPER_SHAPE => {
            let (rnd, n2, n3, holes) = (p[0], p[3], p[4], p[5]);
            let theta = p[8] * t.atanyx + FRAC_PI_4;
            let (st, ct) = sincos(theta);
            let t1 = ct.abs().powf(n2);
            let t2 = st.abs().powf(n3);
            let r = w * ((rnd * rng.f01() + (1.0 - rnd) * t.sqrt) - holes) * (t1 + t2).powf(p[9])
                / t.sqrt;
            (r * x, r * y)
        }
        FLOWER => {
            let (petals, holes) = (p[0], p[1]);
            let r = w * (rng.f01() - holes) * fm::cos(petals * t.atanyx) / t.sqrt;
            (r * x, r * y)
        }
        CONIC => {
            let (ecc, holes) = (p[0], p[1]);
            let ct = x / t.sqrt;
            let r = w * (rng.f01() - holes) * ecc / (1.0 + ecc * ct) / t.sqrt;
            (r * x, r * y)
        }
        PARABOLA => {
            let (height, width) = (p[0], p[1]);
            let (sr, cr) = sincos(t.sqrt);
            (height * w * sr * sr * rng.f01(), width * w * cr * rng.f01())
        }
        BENT2 => {
            let nx = if x < 0.0 { x * p[0] } else { x };
            let ny = if y < 0.0 { y * p[1] } else { y };
            (w * nx, w * ny)
        }
        BIPOLAR => {
            let x2y2 = t.sumsq;
            let tt = x2y2 + 1.0;
            let x2 = 2.0 * x;
            let ps = -FRAC_PI_2 * p[0];
            let mut ny = 0.5 * (2.0 * y).atan2(x2y2 - 1.0) + ps;
            if ny > FRAC_PI_2 {
                ny = -FRAC_PI_2 + (ny + FRAC_PI_2) % PI;
            } else if ny < -FRAC_PI_2 {
                ny = FRAC_PI_2 - (FRAC_PI_2 - ny) % PI;
            }
            (
                w * 0.25 * (2.0 / PI) * ((tt + x2) / (tt - x2)).ln(),
                w * (2.0 / PI) * ny,
            )
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
            let r = wx * ((y * x).abs() / (EPS + x * x + y2 * y2)).sqrt();
            (r * x, r * y2)
        }
        CELL => {
            let size = p[0];
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
            let a = t.atanyx;
            let lnr = 0.5 * t.sumsq.ln();
            let (va, vc, vd) = (p[8], p[9], p[10]);
            let ang = vc * a + vd * lnr + va * (p[2] * rng.f01()).floor();
            let m = w * (vc * lnr - vd * a).exp();
            let (s, c) = sincos(ang);
            (m * c, m * s)
        }
        CURVE => (
            w * (x + p[0] * (-y * y / p[8]).exp()),
            w * (y + p[1] * (-x * x / p[9]).exp()),
        ),
        EDISC => {
            let tmp = t.sumsq + 1.0;
            let tmp2 = 2.0 * x;
            let r1 = (tmp + tmp2).sqrt();
            let r2 = (tmp - tmp2).sqrt();
            let xmax = (r1 + r2) * 0.5;
            let a1 = (xmax + (xmax - 1.0).sqrt()).ln();
            let a2 = -(x / xmax).acos();
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
            let tmp = t.sumsq + 1.0;
            let x2 = 2.0 * x;
            let xmax = 0.5 * ((tmp + x2).sqrt() + (tmp - x2).sqrt());
            let a = x / xmax;
            let b = 1.0 - a * a;
            let ssx = xmax - 1.0;
            let ww = w / FRAC_PI_2;
            let b = if b < 0.0 { 0.0 } else { b.sqrt() };
            let ssx = if ssx < 0.0 { 0.0 } else { ssx.sqrt() };
            let ny = ww * (xmax + ssx).ln();
            (ww * a.atan2(b), if y > 0.0 { ny } else { -ny })
        }
        ESCHER => {
            let a = t.atanyx;
            let lnr = 0.5 * t.sumsq.ln();
            let m = w * (p[8] * lnr - p[9] * a).exp();
            let n = p[8] * a + p[9] * lnr;
            let (s, c) = sincos(n);
            (m * c, m * s)
        }
        FOCI => {
            let expx = x.exp() * 0.5;
            let expnx = 0.25 / expx;
            let (sn, cn) = sincos(y);
            let tmp = w / (expx + expnx - cn);
            (tmp * (expx - expnx), tmp * sn)
        }
        LAZYSUSAN => {
            let (spin, space, twist, lx, ly) = (p[0], p[1], p[2], p[3], p[4]);
            let xx = x - lx;
            let yy = y + ly;
            let r = (xx * xx + yy * yy).sqrt();
            if r < w {
                let a = yy.atan2(xx) + spin + twist * (w - r);
                let r = w * r;
                let (s, c) = sincos(a);
                (r * c + lx, r * s - ly)
            } else {
                let r = w * (1.0 + space / r);
                (r * xx + lx, r * yy - ly)
            }
        }
        LOONIE => {
            let r2 = t.sumsq;
            let w2 = w * w;
            if r2 < w2 {
                let r = w * (w2 / r2 - 1.0).sqrt();
                (r * x, r * y)
            } else {
                (w * x, w * y)
            }
        }
        // pre_blur moves the point before the other variations (see `pre_blur`); it adds
        // nothing to the sum itself.
        PRE_BLUR => (0.0, 0.0),
        MODULUS => {
            let (mx, my) = (p[0], p[1]);
            let (xr, yr) = (2.0 * mx, 2.0 * my);
            let nx = if x > mx {
                -mx + (x + mx) % xr
            } else if x < -mx {
                mx - (mx - x) % xr
            } else {
                x
            };
            let ny = if y > my {
                -my + (y + my) % yr
            } else if y < -my {
                my - (my - y) % yr
            } else {
                y
            };
            (w * nx, w * ny)
        }
        OSCILLOSCOPE => {
            let (sep, amp, damping) = (p[0], p[2], p[3]);
            let tt = if damping == 0.0 {
                amp * fm::cos(p[8] * x) + sep
            } else {
                amp * (-x.abs() * damping).exp() * fm::cos(p[8] * x) + sep
            };
            if y.abs() <= tt {
                (w * x, -w * y)
            } else {
                (w * x, w * y)
            }
        }
        POLAR2 => {
            let p2v = w / PI;
            (p2v * t.atan, p2v * 0.5 * t.sumsq.ln())
        }
        POPCORN2 => (
            w * (x + p[0] * fm::sin((y * p[2]).tan())),
            w * (y + p[1] * fm::sin((x * p[2]).tan())),
        ),
        SCRY => {
            let tt = t.sumsq;
            let r = 1.0 / (t.sqrt * (tt + 1.0 / (w + EPS)));
            (x * r, y * r)
        }
        SEPARATION => {
            let (sx, sxi, sy, syi) = (p[0], p[1], p[2], p[3]);
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
            let ny = if fm::cos(x * p[0] * PI) >= 0.0 {
                w * y
            } else {
                -w * y
            };
            let nx = if fm::cos(y * p[1] * PI) >= 0.0 {
                w * x
            } else {
                -w * x
            };
            (nx, ny)
        }
        SPLITS => {
            let nx = if x >= 0.0 {
                w * (x + p[0])
            } else {
                w * (x - p[0])
            };
            let ny = if y >= 0.0 {
                w * (y + p[1])
            } else {
                w * (y - p[1])
            };
            (nx, ny)
        }
        STRIPES => {
            let (space, warp) = (p[0], p[1]);
            let rx = (x + 0.5).floor();
            let ox = x - rx;
            (w * (ox * (1.0 - space) + rx), w * (y + ox * ox * warp))
        }
        WEDGE => {
            let (angle, hole, count, swirl) = (p[0], p[1], p[2], p[3]);
            let r = t.sqrt;
            let mut a = t.atanyx + swirl * r;
            let c = ((count * a + PI) * (1.0 / PI) * 0.5).floor();
            let comp_fac = 1.0 - angle * count * (1.0 / PI) * 0.5;
            a = a * comp_fac + c * angle;
            let r = w * (r + hole);
            let (s, co) = sincos(a);
            (r * co, r * s)
        }
        WEDGE_JULIA => {
            let (angle, count, power) = (p[0], p[1], p[2]);
            let r = w * t.sumsq.powf(p[10]);
            let trnd = (p[9] * rng.f01()).trunc();
            let mut a = (t.atanyx + 2.0 * PI * trnd) / power;
            let c = ((count * a + PI) * (1.0 / PI) * 0.5).floor();
            a = a * p[8] + c * angle;
            let (s, co) = sincos(a);
            (r * co, r * s)
        }
        WEDGE_SPH => {
            let (angle, count, hole, swirl) = (p[0], p[1], p[2], p[3]);
            let r = 1.0 / (t.sqrt + EPS);
            let mut a = t.atanyx + swirl * r;
            let c = ((count * a + PI) * (1.0 / PI) * 0.5).floor();
            let comp_fac = 1.0 - angle * count * (1.0 / PI) * 0.5;
            a = a * comp_fac + c * angle;
            let r = w * (r + hole);
            let (s, co) = sincos(a);
            (r * co, r * s)
        }
        WHORL => {
            let (inside, outside) = (p[0], p[1]);
            let r = t.sqrt;
            let a = if r < w {
                t.atanyx + inside / (w - r)
            } else {
                t.atanyx + outside / (w - r)
            };
            let (s, c) = sincos(a);
            (w * r * c, w * r * s)
        }
        WAVES2 => {
            let (freqx, scalex, freqy, scaley) = (p[0], p[1], p[2], p[3]);
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
        LOG => (w * 0.5 * t.sumsq.ln(), w * t.atanyx),
        SIN => {
            let (s, c) = sincos(x);
            (w * s * y.cosh(), w * c * y.sinh())
        }
        COS => {
            let (s, c) = sincos(x);
            (w * c * y.cosh(), -w * s * y.sinh())
        }
        TAN => {
            let (s, c) = sincos(2.0 * x);
            let den = 1.0 / (c + (2.0 * y).cosh());
            (w * den * s, w * den * (2.0 * y).sinh())
        }
        SEC => {
            let (s, c) = sincos(x);
            let den = 2.0 / (fm::cos(2.0 * x) + (2.0 * y).cosh());
            (w * den * c * y.cosh(), w * den * s * y.sinh())
        }
        CSC => {
            let (s, c) = sincos(x);
            let den = 2.0 / ((2.0 * y).cosh() - fm::cos(2.0 * x));
            (w * den * s * y.cosh(), -w * den * c * y.sinh())
        }
        COT => {
            let (s, c) = sincos(2.0 * x);
            let den = 1.0 / ((2.0 * y).cosh() - c);
            (w * den * s, -w * den * (2.0 * y).sinh())
        }
        SINH => {
            let (s, c) = sincos(y);
            (w * x.sinh() * c, w * x.cosh() * s)
        }
        COSH => {
            let (s, c) = sincos(y);
            (w * x.cosh() * c, w * x.sinh() * s)
        }
        TANH => {
            let (s, c) = sincos(2.0 * y);
            let den = 1.0 / (c + (2.0 * x).cosh());
            (w * den * (2.0 * x).sinh(), w * den * s)
        }
        SECH => {
            let (s, c) = sincos(y);
            let den = 2.0 / (fm::cos(2.0 * y) + (2.0 * x).cosh());
            (w * den * c * x.cosh(), -w * den * s * x.sinh())
        }
        CSCH => {
            let (s, c) = sincos(y);
            let den = 2.0 / ((2.0 * x).cosh() - fm::cos(2.0 * y));
            (w * den * x.sinh() * c, -w * den * x.cosh() * s)
        }
        COTH => {
            let (s, c) = sincos(2.0 * y);
            let den = 1.0 / ((2.0 * x).cosh() - c);
            (w * den * (2.0 * x).sinh(), w * den * s)
        }
        AUGER => {
            let (freq, aw, sym, scale) = (p[0], p[1], p[2], p[3]);
            let s = fm::sin(freq * x);
            let tt = fm::sin(freq * y);
            let dy = y + aw * (scale * s / 2.0 + y.abs() * s);
            let dx = x + aw * (scale * tt / 2.0 + x.abs() * tt);
            (w * (x + sym * (dx - x)), w * dy)
        }
        FLUX => {
            let spread = p[0];
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
            let (rea, ima, reb, imb, rec, imc, red, imd) =
                (p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]);
            let re_u = rea * x - ima * y + reb;
            let im_u = rea * y + ima * x + imb;
            let re_v = rec * x - imc * y + red;
            let im_v = rec * y + imc * x + imd;
            let rad_v = w / (re_v * re_v + im_v * im_v);
            (
                rad_v * (re_u * re_v + im_u * im_v),
                rad_v * (im_u * re_v - re_u * im_v),
            )
        }
        _ => (0.0, 0.0),
    }
}

/// pre_blur: a Gaussian jitter of the pre-affine point, applied before the other variations.
#[inline]
pub fn pre_blur(w: f64, x: f64, y: f64, rng: &mut FastRng) -> (f64, f64) {
    let rnd_g = w * (rng.f01() + rng.f01() + rng.f01() + rng.f01() - 2.0);
    let a = rng.f01() * 2.0 * PI;
    let (s, c) = sincos(a);
    (x + rnd_g * c, y + rnd_g * s)
}

/// Evaluate one variation at a point with unit weight (tests, the GUI's variation preview).
pub fn eval(
    id: VarId,
    weight: f64,
    params: &[f64],
    aff: &Affine,
    x: f64,
    y: f64,
    rng: &mut FastRng,
) -> (f64, f64) {
    let v = Prepared::new(id, weight, params);
    let t = Pre::full(x, y);
    apply(&v, &t, aff, rng)
}

#[cfg(test)]
mod tests {
    use super::*;

    const P: (f64, f64) = (0.3, 0.4);

    fn ev(id: VarId, params: &[f64], aff: &Affine, x: f64, y: f64) -> (f64, f64) {
        let mut rng = FastRng::new(1);
        eval(id, 1.0, params, aff, x, y, &mut rng)
    }

    fn at(id: VarId, x: f64, y: f64) -> (f64, f64) {
        ev(id, &[], &Affine::IDENTITY, x, y)
    }

    #[track_caller]
    fn close(got: (f64, f64), want: (f64, f64), tol: f64) {
        assert!(
            (got.0 - want.0).abs() <= tol && (got.1 - want.1).abs() <= tol,
            "got {got:?}, want {want:?}"
        );
    }

    #[test]
    fn registry_is_flam3_order() {
        assert_eq!(VARIATIONS.len(), 99);
        assert_eq!(info(14).name, "bent");
        assert_eq!(info(6).name, "handkerchief");
        assert_eq!(info(98).name, "mobius");
        assert_eq!(by_name("gaussian_blur"), Some(35));
        assert_eq!(param_of("wedge_julia_power"), Some((WEDGE_JULIA, 2)));
        assert_eq!(param_of("wedge_angle"), Some((WEDGE, 0)));
        assert_eq!(param_of("julian_dist"), Some((JULIAN, 1)));
        assert_eq!(param_of("linear_x"), None);
        // Names are unique.
        for (i, v) in VARIATIONS.iter().enumerate() {
            assert_eq!(by_name(v.name), Some(i as VarId));
        }
    }

    #[test]
    fn seven_thesis_variations_at_oracle_point() {
        let (x, y) = P;
        close(at(LINEAR, x, y), (0.3, 0.4), 1e-12);
        close(at(SINUSOIDAL, x, y), (0.295520, 0.389418), 1e-6);
        close(at(SPHERICAL, x, y), (1.2, 1.6), 1e-6);
        close(at(SWIRL, x, y), (-0.313344, 0.389635), 1e-6);
        close(at(HORSESHOE, x, y), (-0.14, 0.48), 1e-6);
        close(at(POLAR, x, y), (0.204833, -0.5), 1e-6);
        close(at(POLAR, -0.3, -0.4), (-0.795167, -0.5), 1e-6);
        close(at(BENT, x, y), (0.3, 0.4), 1e-12);
        close(at(BENT, -0.3, -0.4), (-0.6, -0.2), 1e-12);
    }

    #[test]
    fn thesis_variations_at_more_points() {
        // Each against its formula at several points.
        for &(x, y) in &[(1.5, -0.25), (-2.0, 0.75), (0.01, -3.0)] {
            let r2: f64 = x * x + y * y;
            let r = r2.sqrt();
            let th = f64::atan2(x, y);
            close(at(LINEAR, x, y), (x, y), 1e-12);
            close(at(SINUSOIDAL, x, y), (x.sin(), y.sin()), 1e-12);
            close(at(SPHERICAL, x, y), (x / (r2 + EPS), y / (r2 + EPS)), 1e-12);
            close(
                at(SWIRL, x, y),
                (x * r2.sin() - y * r2.cos(), x * r2.cos() + y * r2.sin()),
                1e-12,
            );
            close(
                at(HORSESHOE, x, y),
                ((x - y) * (x + y) / (r + EPS), 2.0 * x * y / (r + EPS)),
                1e-12,
            );
            close(at(POLAR, x, y), (th / PI, r - 1.0), 1e-12);
            close(
                at(BENT, x, y),
                (
                    if x < 0.0 { 2.0 * x } else { x },
                    if y < 0.0 { y / 2.0 } else { y },
                ),
                1e-12,
            );
        }
    }

    #[test]
    fn epsilon_and_seams() {
        close(at(SPHERICAL, 1e-3, 0.0), (999.9, 0.0), 0.01);
        assert_eq!(at(POLAR, 0.0, -1.0).0, 1.0);
        assert_eq!(at(POLAR, -1e-20, -1.0).0, -1.0);
        // Thesis guard: θ = 0 at the origin.
        close(at(POLAR, 0.0, 0.0), (0.0, -1.0), 0.0);
    }

    #[test]
    fn classic_variations_oracles() {
        let (x, y) = P;
        close(at(HANDKERCHIEF, x, y), (0.455045, 0.494861), 1e-6);
        close(at(HEART, x, y), (0.158114, -0.474342), 1e-6);
        close(at(DISC, x, y), (0.204833, 0.0), 1e-6);
        close(at(SPIRAL, x, y), (2.558851, -0.555165), 1e-6);
        close(at(HYPERBOLIC, x, y), (1.2, 0.4), 1e-6);
        close(at(DIAMOND, x, y), (0.526550, 0.383540), 1e-6);
        close(at(EX, x, y), (0.861637, -0.107843), 1e-6);
        let j = at(JULIA, x, y);
        assert!(
            ((j.0 - 0.670820).abs() < 1e-6 && (j.1 - 0.223607).abs() < 1e-6)
                || ((j.0 + 0.670820).abs() < 1e-6 && (j.1 + 0.223607).abs() < 1e-6),
            "{j:?}"
        );
        close(at(FISHEYE, x, y), (0.533333, 0.4), 1e-6);
        close(at(EYEFISH, x, y), (0.4, 0.533333), 1e-6);
        close(at(EXPONENTIAL, x, y), (0.153453, 0.472281), 1e-6);
        close(at(POWER, x, y), (0.527803, 0.395852), 1e-6);
        close(at(COSINE, x, y), (0.635438, -0.332306), 1e-6);
        close(at(BUBBLE, x, y), (0.282353, 0.376471), 1e-6);
        close(at(CYLINDER, x, y), (0.295520, 0.4), 1e-6);
        close(at(TANGENT, x, y), (0.320848, 0.422793), 1e-6);
        close(at(CROSS, x, y), (4.285714, 5.714286), 1e-6);
        let dep = Affine::new(1.0, 0.2, 0.0, -0.1, 0.5, 0.7);
        close(ev(WAVES, &[], &dep, x, y), (0.499915, 0.342529), 1e-6);
        close(ev(POPCORN, &[], &dep, x, y), (0.569581, 1.066497), 1e-6);
        close(ev(RINGS, &[], &dep, x, y), (0.3, 0.225), 1e-6);
        close(ev(FAN, &[], &dep, x, y), (0.484357, 0.124090), 1e-6);
        close(
            ev(BLOB, &[0.2, 1.0, 3.0], &Affine::IDENTITY, x, y),
            (0.292320, 0.389760),
            1e-6,
        );
        close(
            ev(CURL, &[0.5, 0.2], &Affine::IDENTITY, x, y),
            (0.325444, 0.281065),
            1e-6,
        );
    }

    /// Formulas of flame.md §4.2 evaluated independently at several points.
    #[test]
    fn classic_variations_match_formulas() {
        let pts = [(0.3, 0.4), (-1.2, 0.5), (0.7, -2.1), (-0.05, -0.3)];
        for &(x, y) in &pts {
            let r2: f64 = x * x + y * y;
            let r = r2.sqrt();
            let th = f64::atan2(x, y);
            let phi = f64::atan2(y, x);
            let (sa, ca) = (x / r, y / r);
            close(
                at(HANDKERCHIEF, x, y),
                (r * (th + r).sin(), r * (th - r).cos()),
                1e-12,
            );
            close(
                at(HEART, x, y),
                (r * (r * th).sin(), -r * (r * th).cos()),
                1e-12,
            );
            close(
                at(DISC, x, y),
                (th / PI * (PI * r).sin(), th / PI * (PI * r).cos()),
                1e-12,
            );
            let rho = r + EPS;
            close(
                at(SPIRAL, x, y),
                ((ca + rho.sin()) / rho, (sa - rho.cos()) / rho),
                1e-9,
            );
            close(at(HYPERBOLIC, x, y), (sa / rho, ca * rho), 1e-9);
            close(at(DIAMOND, x, y), (sa * r.cos(), ca * r.sin()), 1e-12);
            let n0 = (th + r).sin();
            let n1 = (th - r).cos();
            let (m0, m1) = (r * n0.powi(3), r * n1.powi(3));
            close(at(EX, x, y), (m0 + m1, m0 - m1), 1e-12);
            let k = 2.0 / (r + 1.0);
            close(at(FISHEYE, x, y), (k * y, k * x), 1e-12);
            close(at(EYEFISH, x, y), (k * x, k * y), 1e-12);
            close(
                at(EXPONENTIAL, x, y),
                (
                    (x - 1.0).exp() * (PI * y).cos(),
                    (x - 1.0).exp() * (PI * y).sin(),
                ),
                1e-12,
            );
            close(at(POWER, x, y), (r.powf(sa) * ca, r.powf(sa) * sa), 1e-12);
            close(
                at(COSINE, x, y),
                ((PI * x).cos() * y.cosh(), -(PI * x).sin() * y.sinh()),
                1e-12,
            );
            close(
                at(BUBBLE, x, y),
                (x / (r2 / 4.0 + 1.0), y / (r2 / 4.0 + 1.0)),
                1e-12,
            );
            close(at(CYLINDER, x, y), (x.sin(), y), 1e-12);
            close(at(TANGENT, x, y), (x.sin() / y.cos(), y.tan()), 1e-12);
            let s = x * x - y * y;
            let m = (1.0 / (s * s + EPS)).sqrt();
            close(at(CROSS, x, y), (x * m, y * m), 1e-9);
            // julia: either branch.
            let j = at(JULIA, x, y);
            let a = th / 2.0;
            let rr = r.sqrt();
            let c1 = (rr * a.cos(), rr * a.sin());
            assert!(
                ((j.0 - c1.0).abs() < 1e-12 && (j.1 - c1.1).abs() < 1e-12)
                    || ((j.0 + c1.0).abs() < 1e-12 && (j.1 + c1.1).abs() < 1e-12)
            );
            // pdj
            let (pa, pb, pc, pd) = (0.7, -1.3, 2.1, 0.4);
            close(
                ev(PDJ, &[pa, pb, pc, pd], &Affine::IDENTITY, x, y),
                (
                    (pa * y).sin() - (pb * x).cos(),
                    (pc * x).sin() - (pd * y).cos(),
                ),
                1e-12,
            );
            // blob
            let (lo, hi, wv) = (0.3, 1.2, 4.0);
            let rb = r * (lo + (hi - lo) * (0.5 + 0.5 * (wv * th).sin()));
            close(
                ev(BLOB, &[lo, hi, wv], &Affine::IDENTITY, x, y),
                (rb * sa, rb * ca),
                1e-12,
            );
            // rings2
            let val: f64 = 0.6;
            let dl = val * val + EPS;
            let rho2 = r - 2.0 * dl * ((r + dl) / (2.0 * dl)).trunc() + r * (1.0 - dl);
            close(
                ev(RINGS2, &[val], &Affine::IDENTITY, x, y),
                (rho2 * sa, rho2 * ca),
                1e-12,
            );
            // fan2
            let (fx, fy): (f64, f64) = (0.8, 0.3);
            let dl = PI * (fx * fx + EPS);
            let h = dl / 2.0;
            let tt = th + fy - dl * ((th + fy) / dl).trunc();
            let al = if tt > h { th - h } else { th + h };
            close(
                ev(FAN2, &[fx, fy], &Affine::IDENTITY, x, y),
                (r * al.sin(), r * al.cos()),
                1e-12,
            );
            // perspective
            let (ang, dist): (f64, f64) = (0.4, 2.5);
            let tp = 1.0 / (dist - y * (ang * PI / 2.0).sin());
            close(
                ev(PERSPECTIVE, &[ang, dist], &Affine::IDENTITY, x, y),
                (dist * x * tp, dist * (ang * PI / 2.0).cos() * y * tp),
                1e-12,
            );
            // waves, popcorn, rings, fan with a dependent affine
            let aff = Affine::new(0.9, -0.6, 0.1, 0.35, -0.4, 1.1);
            close(
                ev(WAVES, &[], &aff, x, y),
                (
                    x + aff.b * (y / (aff.e * aff.e + EPS)).sin(),
                    y + aff.d * (x / (aff.f * aff.f + EPS)).sin(),
                ),
                1e-12,
            );
            close(
                ev(POPCORN, &[], &aff, x, y),
                (
                    x + aff.e * (3.0 * y).tan().sin(),
                    y + aff.f * (3.0 * x).tan().sin(),
                ),
                1e-12,
            );
            let dl = aff.e * aff.e + EPS;
            let rr = (r + dl) % (2.0 * dl) - dl + r * (1.0 - dl);
            close(ev(RINGS, &[], &aff, x, y), (rr * ca, rr * sa), 1e-12);
            let dl = PI * (aff.e * aff.e + EPS);
            let h = dl / 2.0;
            let al = th + if (th + aff.f) % dl > h { -h } else { h };
            close(
                ev(FAN, &[], &aff, x, y),
                (r * al.cos(), r * al.sin()),
                1e-12,
            );
            // curl
            let (c1, c2) = (0.4, -0.3);
            let u = 1.0 + c1 * x + c2 * (x * x - y * y);
            let v = c1 * y + 2.0 * c2 * x * y;
            let d = u * u + v * v;
            close(
                ev(CURL, &[c1, c2], &Affine::IDENTITY, x, y),
                ((x * u + y * v) / d, (y * u - x * v) / d),
                1e-12,
            );
            // bent2
            close(
                ev(BENT2, &[3.0, -0.5], &Affine::IDENTITY, x, y),
                (
                    if x < 0.0 { 3.0 * x } else { x },
                    if y < 0.0 { -0.5 * y } else { y },
                ),
                1e-12,
            );
            // rectangles
            let (rx, ry) = (0.3, 0.7);
            close(
                ev(RECTANGLES, &[rx, ry], &Affine::IDENTITY, x, y),
                (
                    (2.0 * (x / rx).floor() + 1.0) * rx - x,
                    (2.0 * (y / ry).floor() + 1.0) * ry - y,
                ),
                1e-12,
            );
            // julian / juliascope: the result lies on one of the |p| branches.
            for id in [JULIAN, JULIASCOPE] {
                let (pw, ds) = (3.0, 0.7);
                let got = ev(id, &[pw, ds], &Affine::IDENTITY, x, y);
                let rad = r2.powf(ds / (2.0 * pw));
                assert!(((got.0.hypot(got.1)) - rad).abs() < 1e-12);
                let ok = (0..3).any(|k| {
                    let kf = k as f64;
                    let a1 = (phi + 2.0 * PI * kf) / pw;
                    let a2 = (2.0 * PI * kf - phi) / pw;
                    let cands = if id == JULIAN || k % 2 == 0 {
                        [a1, a1]
                    } else {
                        [a2, a2]
                    };
                    cands.iter().any(|a| {
                        (got.0 - rad * a.cos()).abs() < 1e-9 && (got.1 - rad * a.sin()).abs() < 1e-9
                    })
                });
                assert!(ok, "{id} at ({x},{y}) gave {got:?}");
            }
            // noise: inside the scaled box.
            let n = at(NOISE, x, y);
            assert!(n.0.abs() <= x.abs() + 1e-12 && n.1.abs() <= y.abs() + 1e-12);
            // mobius: (Az + B)/(Cz + D)
            let (a_, b_, c_, d_) = ((0.5, 0.2), (-0.3, 1.0), (0.1, -0.4), (1.0, 0.3));
            let mul = |p: (f64, f64), q: (f64, f64)| (p.0 * q.0 - p.1 * q.1, p.0 * q.1 + p.1 * q.0);
            let z = (x, y);
            let num = {
                let m = mul(a_, z);
                (m.0 + b_.0, m.1 + b_.1)
            };
            let den = {
                let m = mul(c_, z);
                (m.0 + d_.0, m.1 + d_.1)
            };
            let dd = den.0 * den.0 + den.1 * den.1;
            let q = (
                (num.0 * den.0 + num.1 * den.1) / dd,
                (num.1 * den.0 - num.0 * den.1) / dd,
            );
            close(
                ev(
                    MOBIUS,
                    &[a_.0, a_.1, b_.0, b_.1, c_.0, c_.1, d_.0, d_.1],
                    &Affine::IDENTITY,
                    x,
                    y,
                ),
                q,
                1e-12,
            );
        }
    }

    #[test]
    fn weight_scales_linear_variations() {
        let mut rng = FastRng::new(3);
        for id in [
            LINEAR, SINUSOIDAL, SPHERICAL, SWIRL, HORSESHOE, POLAR, BENT, DISC, SPIRAL,
        ] {
            let a = eval(id, 1.0, &[], &Affine::IDENTITY, 0.7, -0.2, &mut rng);
            let b = eval(id, -2.5, &[], &Affine::IDENTITY, 0.7, -0.2, &mut rng);
            close(b, (-2.5 * a.0, -2.5 * a.1), 1e-12);
        }
    }

    #[test]
    fn complex_function_variations() {
        // exp, log, sin, cos of z = x + iy against the complex formulas.
        let (x, y): (f64, f64) = (0.3, 0.4);
        close(at(EXP, x, y), (x.exp() * y.cos(), x.exp() * y.sin()), 1e-12);
        close(
            at(LOG, x, y),
            ((x * x + y * y).sqrt().ln(), y.atan2(x)),
            1e-12,
        );
        close(
            at(SIN, x, y),
            (x.sin() * y.cosh(), x.cos() * y.sinh()),
            1e-12,
        );
        close(
            at(COS, x, y),
            (x.cos() * y.cosh(), -x.sin() * y.sinh()),
            1e-12,
        );
        close(
            at(SINH, x, y),
            (x.sinh() * y.cos(), x.cosh() * y.sin()),
            1e-12,
        );
        close(
            at(COSH, x, y),
            (x.cosh() * y.cos(), x.sinh() * y.sin()),
            1e-12,
        );
        // tan z = sin z / cos z
        let (sr, si) = (x.sin() * y.cosh(), x.cos() * y.sinh());
        let (cr, ci) = (x.cos() * y.cosh(), -x.sin() * y.sinh());
        let d = cr * cr + ci * ci;
        close(
            at(TAN, x, y),
            ((sr * cr + si * ci) / d, (si * cr - sr * ci) / d),
            1e-12,
        );
        // sec z = 1 / cos z
        close(at(SEC, x, y), (cr / d, -ci / d), 1e-12);
        // csc z = 1/sin z
        let ds = sr * sr + si * si;
        close(at(CSC, x, y), (sr / ds, -si / ds), 1e-12);
    }
}
