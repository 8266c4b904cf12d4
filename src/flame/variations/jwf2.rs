//! JWildfire variations (slice jwf2 of the registry): the `sym_*` symmetry groups (band and
//! network groups: random picks among a few isometries), the line-drawing `_js` variations
//! (Hilbert curve, recursive squares, tree), `svensson_js`, `dla3d_wf` (a diffusion-limited
//! aggregate built once per preparation) and six "dc_" pattern variations that colour the
//! points they scatter.
//!
//! Conventions shared by this file:
//! - JWildfire draws its random numbers as ⌊u·n⌋ for an index and `u` in [0, 1) for the rest;
//!   the formulas take them from a [`Draw`] so that tests can replay a scripted sequence.
//! - JWildfire's integer parameters that it truncates (`(int) value`) are stored as reals and
//!   truncated where they are used; those it rounds (`Tools.FTOI`) are [`p_int`] parameters.
//! - The dc_ variations compute an RGB colour. JWildfire either paints that RGB directly
//!   (`Gradient` 0), paints the nearest palette colour (1) or uses the colour's luminance as
//!   the palette index (2). ugnis colours through the palette only, so all three set the
//!   palette index to the luminance (exact for 2, a stand-in for 0 and 1).

use std::collections::HashMap;
use std::f64::consts::PI;

use super::util::{Mwc, atan2_approx, cpp_max, cpp_min, fract, signum_java};
use super::*;

// ---------------------------------------------------------------------------------------------
// Random numbers

/// Uniform numbers for the formulas: the chaos game's generator, or a scripted sequence in
/// tests.
trait Draw {
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64;
    /// Uniform index in 0..n (n > 0).
    fn index(&mut self, n: usize) -> usize;
}

impl Draw for FastRng {
    #[inline(always)]
    fn unit(&mut self) -> f64 {
        self.f01()
    }
    #[inline(always)]
    fn index(&mut self, n: usize) -> usize {
        self.below(n as u64) as usize
    }
}

/// Java's `(int) value` on a parameter already clamped to a small range.
#[inline(always)]
fn trunc_i(x: f64) -> i64 {
    x as i64
}

// ---------------------------------------------------------------------------------------------
// sym_*: wallpaper ("network") and frieze ("band") symmetry groups

/// Linear part (a, b, d, e) of one isometry: x' = a·x + b·y + c, y' = d·x + e·y + f.
type Lin = [f64; 4];

const ID: Lin = [1.0, 0.0, 0.0, 1.0];
const HALF_TURN: Lin = [-1.0, 0.0, 0.0, -1.0];
/// y → −y.
const MIRROR_Y: Lin = [1.0, 0.0, 0.0, -1.0];
/// x → −x.
const MIRROR_X: Lin = [-1.0, 0.0, 0.0, 1.0];
const QUARTER_CW: Lin = [0.0, 1.0, -1.0, 0.0];
const QUARTER_CCW: Lin = [0.0, -1.0, 1.0, 0.0];
const DIAG_NEG: Lin = [0.0, -1.0, -1.0, 0.0];
const DIAG_POS: Lin = [0.0, 1.0, 1.0, 0.0];
/// JWildfire's three- and six-fold groups use 0.866 for sin 60°, not √3/2.
const S60: f64 = 0.866;

/// Stores a group for [`sym_eval`]: the shift added to the input, then each map as
/// (a, b, c, d, e, f).
fn sym_store(v: &mut Prepared, shift: f64, maps: &[(Lin, f64, f64)]) {
    v.p.push(shift);
    for &(l, c, f) in maps {
        v.p.extend_from_slice(&[l[0], l[1], c, l[2], l[3], f]);
    }
}

/// Applies one map of the group, picked uniformly, to the shifted input.
fn sym_eval(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let tab = v.table(0);
    let count = (tab.len() - 1) / 6;
    let m = &tab[1 + 6 * rng.index(count)..];
    let x = t.x + tab[0];
    let y = t.y + tab[0];
    [
        v.w * (m[0] * x + m[1] * y + m[2]),
        v.w * (m[3] * x + m[4] * y + m[5]),
        0.0,
    ]
}

/// The same linear parts twice, the first copy moved by (−sx/2, −sy/2), the second by
/// (+sx/2, +sy/2): the lattice-step layout of sym_ng13 … sym_ng17.
fn sym_two_cells(v: &mut Prepared, lins: &[Lin]) {
    let [r, stepx, stepy] = v.params();
    let shift = (r * r / 2.0).sqrt();
    let (hx, hy) = (stepx / 2.0, stepy / 2.0);
    let mut maps: Vec<(Lin, f64, f64)> = lins.iter().map(|&l| (l, -hx, -hy)).collect();
    maps.extend(lins.iter().map(|&l| (l, hx, hy)));
    sym_store(v, shift, &maps);
}

/// sym_ng1: two translated copies, ±step/2 apart (a lattice translation).
fn prep_ng1(v: &mut Prepared) {
    let [sx, sy] = v.params();
    sym_store(
        v,
        0.0,
        &[(ID, -sx / 2.0, -sy / 2.0), (ID, sx / 2.0, sy / 2.0)],
    );
}

/// sym_ng2: the point and its mirror in the x axis, ±step/2 apart (a glide reflection).
fn prep_ng2(v: &mut Prepared) {
    let [sx, sy] = v.params();
    sym_store(
        v,
        0.0,
        &[(ID, -sx / 2.0, -sy / 2.0), (MIRROR_Y, sx / 2.0, sy / 2.0)],
    );
}

/// sym_ng3: the point and its half-turn, ±(separation + step/2) apart.
fn prep_ng3(v: &mut Prepared) {
    let [sepx, sepy, step] = v.params();
    sym_store(
        v,
        0.0,
        &[
            (ID, -sepx - step / 2.0, -sepy - step / 2.0),
            (HALF_TURN, sepx + step / 2.0, sepy + step / 2.0),
        ],
    );
}

/// sym_ng4: identity, half-turn and the two axis mirrors, at fixed cell offsets moved by separation and skew.
fn prep_ng4(v: &mut Prepared) {
    let [sep_x, sep_y, skew_x, skew_y] = v.params();
    let (sx, sy, kx, ky) = (sep_x / 2.0, sep_y / 2.0, skew_x / 2.0, skew_y / 2.0);
    sym_store(
        v,
        0.0,
        &[
            (ID, -sx - 2.0 - kx, sy - 1.5 - ky),
            (HALF_TURN, sx - kx, -sy - 0.5 - ky),
            (MIRROR_Y, -sx + kx, -sy + 0.5 + ky),
            (MIRROR_X, sx + 2.0 + kx, sy - 0.5 + ky),
        ],
    );
}

/// sym_ng5: identity, half-turn and the two axis mirrors laid out in a row.
fn prep_ng5(v: &mut Prepared) {
    let [sepx, sepy, k] = v.params();
    sym_store(
        v,
        0.0,
        &[
            (ID, -sepx - 2.0 - k / 2.0, sepy - 0.5),
            (HALF_TURN, sepx - k / 2.0, -sepy - 0.5),
            (MIRROR_Y, -sepx + k / 2.0, -sepy - 0.5),
            (MIRROR_X, 2.0 + sepx + k / 2.0, sepy - 0.5),
        ],
    );
}

/// sym_ng6: two copies and two x-axis mirrors on a skewed lattice (glide reflections).
fn prep_ng6(v: &mut Prepared) {
    let [sepy, kx, ky] = v.params();
    sym_store(
        v,
        0.0,
        &[
            (ID, -kx / 2.0, -ky / 2.0 + sepy / 2.0),
            (MIRROR_Y, -kx / 2.0, -ky / 2.0 - sepy / 2.0),
            (ID, kx / 2.0, ky / 2.0 + sepy / 2.0),
            (MIRROR_Y, kx / 2.0, ky / 2.0 - sepy / 2.0),
        ],
    );
}

/// sym_ng7: the point and its x-axis mirror, offset in opposite directions.
fn prep_ng7(v: &mut Prepared) {
    let [sx, sy] = v.params();
    sym_store(
        v,
        0.0,
        &[(ID, -sx / 2.0, sy / 2.0), (MIRROR_Y, sx / 2.0, -sy / 2.0)],
    );
}

/// sym_ng8: identity, half-turn and the two mirrors in two cells set apart by the skew.
fn prep_ng8(v: &mut Prepared) {
    let [sepx, sepy, skew_x, skew_y] = v.params();
    let (sx, sy, kx, ky) = (sepx / 2.0, sepy / 2.0, skew_x / 2.0, skew_y / 2.0);
    sym_store(
        v,
        0.0,
        &[
            (MIRROR_Y, -1.0 - sx - kx, -sy - ky),
            (MIRROR_X, 1.0 + sx - kx, sy - ky),
            (HALF_TURN, 1.0 + sx - kx, -sy - ky),
            (ID, -1.0 - sx - kx, sy - ky),
            (MIRROR_Y, -1.0 - sx + kx, -sy + ky),
            (MIRROR_X, 1.0 + sx + kx, sy + ky),
            (HALF_TURN, 1.0 + sx + kx, -sy + ky),
            (ID, -1.0 - sx + kx, sy + ky),
        ],
    );
}

/// sym_ng9: identity, half-turn and the two axis mirrors (the Klein four-group), ±separation/2 apart.
fn prep_ng9(v: &mut Prepared) {
    let [sepx, sepy] = v.params();
    let (sx, sy) = (sepx / 2.0, sepy / 2.0);
    sym_store(
        v,
        0.0,
        &[
            (MIRROR_Y, sx, -sy),
            (MIRROR_X, -sx, sy),
            (HALF_TURN, -sx, -sy),
            (ID, sx, sy),
        ],
    );
}

/// sym_ng10: the four rotations by quarter turns, after a diagonal shift of the input.
fn prep_ng10(v: &mut Prepared) {
    let [space, px, py] = v.params();
    let (px, py) = (px / 2.0, py / 2.0);
    sym_store(
        v,
        space,
        &[
            (HALF_TURN, -px, -py),
            (QUARTER_CW, -px, -py),
            (QUARTER_CCW, px, py),
            (ID, px, py),
        ],
    );
}

/// sym_ng11: the eight symmetries of the square, translated by step and spacing.
fn prep_ng11(v: &mut Prepared) {
    let [space, px, py, step_x, step_y] = v.params();
    let (hx, hy) = (step_x / 2.0, step_y / 2.0);
    sym_store(
        v,
        space,
        &[
            (ID, px + hx, py + hy),
            (HALF_TURN, -px + hx, -py + hy),
            (QUARTER_CW, px + hx, -py + hy),
            (QUARTER_CCW, -px + hx, py + hy),
            (MIRROR_X, -px - hx, py - hy),
            (DIAG_NEG, -px - hx, -py - hy),
            (DIAG_POS, px - hx, py - hy),
            (MIRROR_Y, px - hx, -py - hy),
        ],
    );
}

/// sym_ng12: the eight symmetries of the square, moved by ±spacing.
fn prep_ng12(v: &mut Prepared) {
    let [space, px, py] = v.params();
    sym_store(
        v,
        space,
        &[
            (ID, px, py),
            (HALF_TURN, -px, -py),
            (QUARTER_CW, px, -py),
            (QUARTER_CCW, -px, py),
            (MIRROR_X, -px, py),
            (DIAG_NEG, -px, -py),
            (DIAG_POS, px, py),
            (MIRROR_Y, px, -py),
        ],
    );
}

/// sym_ng13: three mirrors 60° apart, in two cells.
fn prep_ng13(v: &mut Prepared) {
    sym_two_cells(
        v,
        &[MIRROR_Y, [-0.5, -S60, -S60, 0.5], [-0.5, S60, S60, 0.5]],
    );
}

/// sym_ng14: identity, a mirror, the 120° turns and two more mirrors (order-3 dihedral pairs), in two cells.
fn prep_ng14(v: &mut Prepared) {
    sym_two_cells(
        v,
        &[
            ID,
            MIRROR_Y,
            [-0.5, -S60, S60, -0.5],
            [-0.5, S60, -S60, -0.5],
            [-0.5, -S60, -S60, 0.5],
            [-0.5, S60, S60, 0.5],
        ],
    );
}

/// sym_ng15: six maps mixing a quarter turn, a diagonal mirror and 30° rotations/mirrors, in two cells.
fn prep_ng15(v: &mut Prepared) {
    sym_two_cells(
        v,
        &[
            QUARTER_CW,
            DIAG_NEG,
            [S60, -0.5, 0.5, S60],
            [S60, 0.5, 0.5, -S60],
            [-S60, -0.5, 0.5, -S60],
            [-S60, 0.5, 0.5, S60],
        ],
    );
}

/// sym_ng16: the six rotations by multiples of 60°, in two cells.
fn prep_ng16(v: &mut Prepared) {
    sym_two_cells(
        v,
        &[
            ID,
            [0.5, -S60, S60, 0.5],
            [-0.5, -S60, S60, -0.5],
            HALF_TURN,
            [-0.5, S60, -S60, -0.5],
            [0.5, S60, -S60, 0.5],
        ],
    );
}

/// sym_ng17: the twelve rotations and mirrors of the hexagon, in two cells.
fn prep_ng17(v: &mut Prepared) {
    sym_two_cells(
        v,
        &[
            ID,
            MIRROR_Y,
            [0.5, -S60, S60, 0.5],
            [0.5, S60, S60, -0.5],
            [-0.5, -S60, S60, -0.5],
            [-0.5, S60, S60, 0.5],
            HALF_TURN,
            MIRROR_X,
            [-0.5, S60, -S60, -0.5],
            [-0.5, -S60, -S60, 0.5],
            [0.5, S60, -S60, 0.5],
            [0.5, -S60, -S60, -0.5],
        ],
    );
}

/// sym_bg1: a band of translated copies (frieze group p1).
fn prep_bg1(v: &mut Prepared) {
    let [step_x, step_y] = v.params();
    let (hx, hy) = (step_x / 2.0, step_y / 2.0);
    sym_store(v, 0.0, &[(ID, -hx - 1.0, -hy), (ID, hx, hy)]);
}

/// sym_bg2: a copy and a raised x-axis mirror (a glide-like frieze).
fn prep_bg2(v: &mut Prepared) {
    let [step_x, step_y] = v.params();
    let (hx, hy) = (step_x / 2.0, step_y / 2.0);
    sym_store(v, 0.0, &[(ID, -hx - 1.0, -hy), (MIRROR_Y, hx, hy + 1.0)]);
}

/// sym_bg3: a copy and its half-turn (frieze with two-fold centres).
fn prep_bg3(v: &mut Prepared) {
    let [step_x, step_y] = v.params();
    let (hx, hy) = (step_x / 2.0, step_y / 2.0);
    sym_store(
        v,
        0.0,
        &[(ID, -hx - 1.0, -hy - 0.5), (HALF_TURN, hx + 1.0, hy + 0.5)],
    );
}

/// sym_bg4: a copy and its mirror in a vertical line.
fn prep_bg4(v: &mut Prepared) {
    let [step_x, step_y] = v.params();
    let (hx, hy) = (step_x / 2.0, step_y / 2.0);
    sym_store(
        v,
        0.0,
        &[(ID, -hx - 1.0, -hy - 0.5), (MIRROR_X, hx + 1.0, hy + 0.5)],
    );
}

/// sym_bg5: a copy and its mirror in a horizontal line (glide reflection along the band).
fn prep_bg5(v: &mut Prepared) {
    let [step_x, step_y] = v.params();
    let (hx, hy) = (step_x / 2.0, step_y / 2.0);
    sym_store(
        v,
        0.0,
        &[(ID, -hx - 1.0, -hy - 0.5), (MIRROR_Y, hx - 1.0, hy + 0.5)],
    );
}

/// sym_bg6: a copy, both axis mirrors and the half-turn (frieze with both mirrors).
fn prep_bg6(v: &mut Prepared) {
    let [step_x, step_y] = v.params();
    let (hx, hy) = (step_x / 2.0, step_y / 2.0);
    sym_store(
        v,
        0.0,
        &[
            (ID, -hx - 1.0, -hy - 0.5),
            (MIRROR_X, hx + 1.0, hy - 0.5),
            (MIRROR_Y, -hx - 1.0, -hy + 0.5),
            (HALF_TURN, hx + 1.0, hy + 0.5),
        ],
    );
}

/// sym_bg7: the same four maps arranged as a glide-and-mirror frieze.
fn prep_bg7(v: &mut Prepared) {
    let [step_x, step_y] = v.params();
    let (hx, hy) = (step_x / 2.0, step_y / 2.0);
    sym_store(
        v,
        0.0,
        &[
            (ID, -hx - 2.0, -hy - 0.5),
            (MIRROR_X, hx + 2.0, hy - 0.5),
            (MIRROR_Y, hx, hy + 0.5),
            (HALF_TURN, -hx, -hy + 0.5),
        ],
    );
}

/// `NAME_StepX` and `NAME_StepY` (both 0 by default), after any leading parameters given.
macro_rules! sym_steps {
    ($name:literal $(, $lead:expr)*) => {
        &[$($lead,)* p(concat!($name, "_StepX"), 0.0), p(concat!($name, "_StepY"), 0.0)]
    };
}

const P_NG1: &[Param] = &[p("sym_ng1_StepX", 0.5), p("sym_ng1_StepY", 0.5)];
const P_NG2: &[Param] = &[p("sym_ng2_StepX", 2.0), p("sym_ng2_StepY", 2.0)];
const P_NG3: &[Param] = &[
    p("sym_ng3_SepX", 0.5),
    p("sym_ng3_SepY", 0.0),
    p("sym_ng3_Step", 2.0),
];
const P_NG4: &[Param] = &[
    p("sym_ng4_SepX", 0.0),
    p("sym_ng4_SepY", 0.0),
    p("sym_ng4_SkewX", 0.0),
    p("sym_ng4_SkewY", 0.0),
];
const P_NG5: &[Param] = &[
    p("sym_ng5_SepX", 0.0),
    p("sym_ng5_SepY", 0.0),
    p("sym_ng5_SkewX", 0.0),
];
const P_NG6: &[Param] = &[
    p("sym_ng6_SepY", 0.1),
    p("sym_ng6_SkewX", 1.0),
    p("sym_ng6_SkewY", 1.0),
];
const P_NG7: &[Param] = &[p("sym_ng7_SepX", 0.0), p("sym_ng7_SepY", 0.0)];
const P_NG8: &[Param] = &[
    p("sym_ng8_sepx", 0.0),
    p("sym_ng8_sepy", 0.0),
    p("sym_ng8_SkewX", 0.0),
    p("sym_ng8_SkewY", 0.0),
];
const P_NG9: &[Param] = &[p("sym_ng9_sepx", 0.0), p("sym_ng9_sepy", 0.0)];
const P_NG10: &[Param] = &[
    p("sym_ng10_space", 0.0),
    p("sym_ng10_SpX", 0.0),
    p("sym_ng10_SpY", 0.0),
];
const P_NG11: &[Param] = &[
    p("sym_ng11_space", 0.0),
    p("sym_ng11_SpX", 0.0),
    p("sym_ng11_SpY", 0.0),
    p("sym_ng11_StepX", 1.5),
    p("sym_ng11_StepY", 1.5),
];
const P_NG12: &[Param] = &[
    p("sym_ng12_space", 0.0),
    p("sym_ng12_SpX", 0.0),
    p("sym_ng12_SpY", 0.0),
];
// JWildfire names the first parameter of sym_ng13 "Prop. Sep" and that of 14-17 "Prop. Sep."
// (with a space, so a file carrying them is not well-formed XML); ugnis writes `prop_sep`.
const P_NG13: &[Param] = sym_steps!("sym_ng13", p("sym_ng13_prop_sep", 0.0));
const P_NG14: &[Param] = sym_steps!("sym_ng14", p("sym_ng14_prop_sep", 0.0));
const P_NG15: &[Param] = sym_steps!("sym_ng15", p("sym_ng15_prop_sep", 0.0));
const P_NG16: &[Param] = sym_steps!("sym_ng16", p("sym_ng16_prop_sep", 0.0));
const P_NG17: &[Param] = sym_steps!("sym_ng17", p("sym_ng17_prop_sep", 0.0));
const P_BG1: &[Param] = sym_steps!("sym_bg1");
const P_BG2: &[Param] = sym_steps!("sym_bg2");
const P_BG3: &[Param] = sym_steps!("sym_bg3");
const P_BG4: &[Param] = sym_steps!("sym_bg4");
const P_BG5: &[Param] = sym_steps!("sym_bg5");
const P_BG6: &[Param] = sym_steps!("sym_bg6");
const P_BG7: &[Param] = sym_steps!("sym_bg7");

const SYM: u32 = flag::JWILDFIRE | flag::RANDOM;

// ---------------------------------------------------------------------------------------------
// Line drawings: hilbert_js, rsquares_js, tree_js

/// Derived values of a line drawing, after its parameters: line threshold, point threshold,
/// line thickness, point thickness. The segments, (x1, y1, x2, y2) each, are its shared data.
const LA_HEAD: usize = 4;

/// Appends the thresholds that split the draws between segments and end-point dots (from the
/// truncated show_lines / show_points weights) and the thicknesses.
fn la_store(v: &mut Prepared, lines: f64, lt: f64, points: f64, pt: f64) {
    let lines = lines.trunc();
    let points = points.trunc();
    let total = lines + points;
    let line_part = lines / total;
    v.p.extend_from_slice(&[
        line_part,
        line_part + points / total,
        lt / 100.0,
        pt / 100.0,
    ]);
}

/// One point of segment `seg` of `segs`: somewhere along it (jittered by the line thickness),
/// or near its start (within the point thickness), or the origin when neither is shown; `d`
/// holds the derived values ([`LA_HEAD`]).
fn la_sample<R: Draw>(d: [f64; LA_HEAD], segs: &[f64], seg: usize, r: &mut R) -> (f64, f64) {
    let [line_part, point_part, line_thick, point_thick] = d;
    let s = &segs[4 * seg..4 * seg + 4];
    let (x1, y1, x2, y2) = (s[0], s[1], s[2], s[3]);
    let pick = r.unit();
    if pick < line_part {
        let dx = x2 - x1;
        let dy = y2 - y1;
        // A vertical segment gets a steep finite slope, as in JWildfire.
        let slope = if dx == 0.0 { 10000.0 } else { dy / dx };
        let len = (dx * dx + dy * dy).sqrt();
        let along = r.unit() * len;
        let mut ox = along / (1.0 + slope * slope).sqrt();
        if x2 < x1 {
            ox = -ox;
        }
        let mut oy = (slope * ox).abs();
        if y2 < y1 {
            oy = -oy;
        }
        if line_thick != 0.0 {
            ox += (r.unit() - 0.5) * line_thick;
            oy += (r.unit() - 0.5) * line_thick;
        }
        (x1 + ox, y1 + oy)
    } else if pick <= point_part {
        if point_thick != 0.0 {
            let rad = r.unit() * point_thick;
            let ang = r.unit() * (2.0 * PI);
            (x1 + rad * ang.cos(), y1 + rad * ang.sin())
        } else {
            (x1, y1)
        }
    } else {
        (0.0, 0.0)
    }
}

/// A uniformly chosen segment of the drawing, sampled (JWildfire walks the segments in order,
/// one per call; over many calls both cover every segment equally).
#[inline]
fn la_eval(v: &Prepared, rng: &mut FastRng) -> (f64, f64) {
    let segs = v.data();
    let count = segs.len() / 4;
    if count == 0 {
        return (0.0, 0.0);
    }
    let seg = rng.index(count);
    la_sample(v.derived(), segs, seg, rng)
}

/// Turtle that records each forward move as a segment; angles in degrees.
struct Turtle {
    x: f64,
    y: f64,
    heading: f64,
    /// Segments, (x1, y1, x2, y2) each.
    segs: Vec<f64>,
}

impl Turtle {
    fn forward(&mut self) {
        let (x0, y0) = (self.x, self.y);
        let a = self.heading.to_radians();
        self.x += a.cos();
        self.y += a.sin();
        self.segs.extend_from_slice(&[x0, y0, self.x, self.y]);
    }

    /// Hilbert curve of order n, entered turning left.
    fn hilbert(&mut self, n: i64) {
        if n == 0 {
            return;
        }
        self.heading += 90.0;
        self.hilbert_mirror(n - 1);
        self.forward();
        self.heading -= 90.0;
        self.hilbert(n - 1);
        self.forward();
        self.hilbert(n - 1);
        self.heading -= 90.0;
        self.forward();
        self.hilbert_mirror(n - 1);
        self.heading += 90.0;
    }

    /// The mirror image of [`Turtle::hilbert`] (turns exchanged).
    fn hilbert_mirror(&mut self, n: i64) {
        if n == 0 {
            return;
        }
        self.heading -= 90.0;
        self.hilbert(n - 1);
        self.forward();
        self.heading += 90.0;
        self.hilbert_mirror(n - 1);
        self.forward();
        self.hilbert_mirror(n - 1);
        self.heading += 90.0;
        self.forward();
        self.hilbert(n - 1);
        self.heading -= 90.0;
    }
}

/// hilbert_js's segments (from the level, parameter 0).
fn hilbert_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let mut t = Turtle {
        x: 0.0,
        y: 0.0,
        heading: 0.0,
        segs: Vec::new(),
    };
    let [level] = params_of(q);
    t.hilbert(level as i64);
    t.segs
}

/// Derived values of hilbert_js and rsquares_js (same parameter layout).
fn prep_la5(v: &mut Prepared) {
    let [_, lines, lt, points, pt] = v.params();
    la_store(v, lines, lt, points, pt);
}

/// Squares of side `size` centred at (x, y), with four squares of side size/2.2 centred on
/// its corners, recursively, as segments (left side up, top, right side down, bottom).
fn rsquares(segs: &mut Vec<f64>, n: i64, x: f64, y: f64, size: f64) {
    if n == 0 {
        return;
    }
    let h = size / 2.0;
    let (l, r, b, t) = (x - h, x + h, y - h, y + h);
    for side in [[l, b, l, t], [l, t, r, t], [r, t, r, b], [r, b, l, b]] {
        segs.extend_from_slice(&side);
    }
    let s = size / 2.2;
    rsquares(segs, n - 1, l, b, s);
    rsquares(segs, n - 1, l, t, s);
    rsquares(segs, n - 1, r, b, s);
    rsquares(segs, n - 1, r, t, s);
}

/// rsquares_js's segments (from the level, parameter 0).
fn rsquares_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let mut segs = Vec::new();
    let [level] = params_of(q);
    rsquares(&mut segs, level as i64, 0.5, 0.5, 1.0);
    segs
}

/// Branch shape of tree_js: bend and branch angles in radians, length ratio of the side
/// branches (the middle one gets the rest).
struct TreeShape {
    bend: f64,
    branch: f64,
    ratio: f64,
}

/// A branch from (x, y) in direction `a` of length `len`, then (for n > 0) three sub-trees
/// from its tip.
fn tree(segs: &mut Vec<f64>, s: &TreeShape, n: i64, x: f64, y: f64, a: f64, len: f64) {
    let tx = x + a.cos() * len;
    let ty = y + a.sin() * len;
    segs.extend_from_slice(&[x, y, tx, ty]);
    if n == 0 {
        return;
    }
    tree(segs, s, n - 1, tx, ty, a + s.bend - s.branch, len * s.ratio);
    tree(segs, s, n - 1, tx, ty, a + s.bend + s.branch, len * s.ratio);
    tree(segs, s, n - 1, tx, ty, a + s.bend, len * (1.0 - s.ratio));
}

/// tree_js's segments (from the level and the bend, branch and ratio parameters 0, 3–5).
fn tree_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let [level, _, _, bend, branch, ratio] = params_of(q);
    let shape = TreeShape {
        bend: bend.to_radians(),
        branch: branch.to_radians(),
        ratio,
    };
    let mut segs = Vec::new();
    tree(&mut segs, &shape, level as i64, 0.0, 0.0, PI / 2.0, 2.0);
    segs
}

fn prep_tree(v: &mut Prepared) {
    let [_, lines, lt, _, _, _, points, pt] = v.params();
    la_store(v, lines, lt, points, pt);
}

/// hilbert_js: points along a Hilbert curve of the given order (unit steps from the origin),
/// optionally thickened, or dots at the segment starts.
fn hilbert_js(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = la_eval(v, rng);
    [v.w * x, v.w * y, 0.0]
}

/// rsquares_js: points on the outlines of recursively nested squares (unit square centred at
/// (0.5, 0.5), four smaller copies on each square's corners).
fn rsquares_js(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = la_eval(v, rng);
    [v.w * x, v.w * y, 0.0]
}

/// tree_js: points on the branches of a recursive three-way tree growing up from the origin.
/// JWildfire adds the sampled point twice, so the output is twice the weighted point.
fn tree_js(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = la_eval(v, rng);
    [2.0 * (v.w * x), 2.0 * (v.w * y), 0.0]
}

const P_HILBERT: &[Param] = &[
    p_int("hilbert_js_level", 2.0, 1.0, 10.0),
    p("hilbert_js_show_lines", 1.0),
    p("hilbert_js_line_thickness", 0.5),
    p("hilbert_js_show_points", 0.0),
    p("hilbert_js_point_thickness", 3.0),
];
const P_RSQUARES: &[Param] = &[
    p_int("rsquares_js_level", 2.0, 1.0, 9.0),
    p("rsquares_js_show_lines", 1.0),
    p("rsquares_js_line_thickness", 0.5),
    p("rsquares_js_show_points", 0.0),
    p("rsquares_js_point_thickness", 3.0),
];
const P_TREE: &[Param] = &[
    p_int("tree_js_level", 2.0, 1.0, 10.0),
    p("tree_js_show_lines", 1.0),
    p("tree_js_line_thickness", 0.5),
    p("tree_js_bend_angle", 15.0),
    p("tree_js_branch_angle", 37.0),
    p("tree_js_branch_ratio", 0.65),
    p("tree_js_show_points", 0.0),
    p("tree_js_point_thickness", 3.0),
];

// ---------------------------------------------------------------------------------------------
// svensson_js

/// svensson_js: one step of Johnny Svensson's attractor map,
/// (d·sin(a·x) − sin(b·y), c·cos(a·x) + cos(b·y)). Like JWildfire it replaces (rather than
/// adds to) the x and y its xform's earlier variations summed.
fn svensson_js(v: &Prepared, t: &VarIn, acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [a, b, c, d] = v.params();
    let x = d * (a * t.x).sin() - (b * t.y).sin();
    let y = c * (a * t.x).cos() + (b * t.y).cos();
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [x * v.w, y * v.w, 0.0]
}

const P_SVENSSON: &[Param] = &[
    p("svensson_js_a", 1.4),
    p("svensson_js_b", 1.56),
    p("svensson_js_c", 1.4),
    p("svensson_js_d", -6.56),
];

// ---------------------------------------------------------------------------------------------
// dla3d_wf: diffusion-limited aggregation in 3-D

impl Draw for Mwc {
    fn unit(&mut self) -> f64 {
        self.next_f64()
    }
    fn index(&mut self, n: usize) -> usize {
        let i = (self.next_f64() * n as f64) as usize;
        i.min(n - 1)
    }
}

/// Values stored per aggregate node: x, y, z, relative depth, has-parent flag, then the
/// parent's x, y, z and relative depth.
const DLA_STRIDE: usize = 9;

/// Gives up growing after this many walkers in a row found nothing (a degenerate seed makes
/// every walker escape; JWildfire would loop forever).
const DLA_MAX_MISSES: usize = 100_000;

/// Gives up growing after this many walker steps in all (parameters that keep walkers
/// wandering, e.g. a force cancelling their moves, would otherwise take hours).
const DLA_MAX_STEPS: u64 = 300_000_000;

struct DlaNode {
    x: f64,
    y: f64,
    z: f64,
    parent: Option<usize>,
    depth: u32,
}

/// Cells of the dense "near a node" grid at most (one byte each).
const DLA_NEAR_CELLS: usize = 1 << 24;

/// Finds the nearest aggregate node within the glue radius of a walker. Nodes are hashed by
/// cells a little wider than the glue radius (so every candidate lies in the 27 cells around
/// the walker); a dense grid around the origin flags the cells next to some node, so that a
/// walker far from the aggregate (most steps) needs a single array read.
struct DlaIndex {
    glue: f64,
    cell: f64,
    cells: HashMap<(i64, i64, i64), Vec<usize>>,
    /// Cells per side of the dense grid (centred on the origin); 0 when there is none.
    side: i64,
    near: Vec<bool>,
}

impl DlaIndex {
    fn new(glue: f64) -> DlaIndex {
        DlaIndex {
            glue,
            cell: glue * 1.01,
            cells: HashMap::new(),
            side: 0,
            near: Vec::new(),
        }
    }

    fn key(&self, x: f64, y: f64, z: f64) -> (i64, i64, i64) {
        (
            (x / self.cell).floor() as i64,
            (y / self.cell).floor() as i64,
            (z / self.cell).floor() as i64,
        )
    }

    /// Index of a cell in the dense grid, if it covers it.
    fn dense(&self, k: (i64, i64, i64)) -> Option<usize> {
        let h = self.side / 2;
        let (a, b, c) = (k.0 + h, k.1 + h, k.2 + h);
        let inside = |u: i64| (0..self.side).contains(&u);
        (inside(a) && inside(b) && inside(c))
            .then(|| ((a * self.side + b) * self.side + c) as usize)
    }

    fn mark(&mut self, k: (i64, i64, i64)) {
        for i in -1..=1 {
            for j in -1..=1 {
                for l in -1..=1 {
                    if let Some(d) = self.dense((k.0 + i, k.1 + j, k.2 + l)) {
                        self.near[d] = true;
                    }
                }
            }
        }
    }

    /// Makes the dense grid cover radius `r` (within the memory budget).
    fn cover(&mut self, r: f64) {
        let want = 2 * ((r * 1.25 + 2.0) / self.cell).ceil() as i64 + 4;
        if want <= self.side || (want as usize).pow(3) > DLA_NEAR_CELLS {
            return;
        }
        self.side = want;
        self.near = vec![false; (want as usize).pow(3)];
        let keys: Vec<_> = self.cells.keys().copied().collect();
        for k in keys {
            self.mark(k);
        }
    }

    fn insert(&mut self, n: usize, x: f64, y: f64, z: f64) {
        let k = self.key(x, y, z);
        self.cells.entry(k).or_default().push(n);
        self.mark(k);
    }

    /// The nearest node within the glue radius (the oldest among equally near ones).
    fn nearest(&self, nodes: &[DlaNode], x: f64, y: f64, z: f64) -> Option<usize> {
        let k = self.key(x, y, z);
        if let Some(d) = self.dense(k)
            && !self.near[d]
        {
            return None;
        }
        let mut best: Option<(f64, usize)> = None;
        for i in k.0 - 1..=k.0 + 1 {
            for j in k.1 - 1..=k.1 + 1 {
                for l in k.2 - 1..=k.2 + 1 {
                    let Some(list) = self.cells.get(&(i, j, l)) else {
                        continue;
                    };
                    for &n in list {
                        let m = &nodes[n];
                        let (dx, dy, dz) = (m.x - x, m.y - y, m.z - z);
                        let dist = (dx * dx + dy * dy + dz * dz).sqrt();
                        let better = match best {
                            None => true,
                            Some((bd, bn)) => dist < bd || (dist == bd && n < bn),
                        };
                        if dist <= self.glue && better {
                            best = Some((dist, n));
                        }
                    }
                }
            }
        }
        best.map(|b| b.1)
    }
}

/// Grows the aggregate: walkers start on a sphere around the cluster, step ±0.9 along one
/// axis at a time (plus the drift force) and stick to the nearest node within the glue
/// radius; a walker that strays beyond the outer radius is dropped.
fn dla_grow(max_nodes: usize, seed: i64, glue: f64, force: [f64; 3]) -> Vec<DlaNode> {
    let mut rnd = Mwc::new(seed);
    let mut nodes = vec![DlaNode {
        x: 0.0,
        y: 0.0,
        z: 0.0,
        parent: None,
        depth: 0,
    }];
    let mut index = DlaIndex::new(glue);
    index.insert(0, 0.0, 0.0, 0.0);
    let mut inner = 3.0;
    let mut outer = 3.0 * inner;
    index.cover(outer);
    let mut misses = 0;
    let mut steps_left = DLA_MAX_STEPS;
    while nodes.len() < max_nodes && misses < DLA_MAX_MISSES && steps_left > 0 {
        let phi = rnd.next_f64() * (PI + PI);
        let theta = rnd.next_f64() * (PI + PI);
        let (sp, cp) = phi.sin_cos();
        let (st, ct) = theta.sin_cos();
        let (mut x, mut y, mut z) = (inner * st * cp, inner * st * sp, inner * ct);
        let mut stuck = None;
        for _ in 0..1_000_000 {
            if steps_left == 0 {
                break;
            }
            steps_left -= 1;
            match (rnd.next_f64() * 6.0) as i32 {
                0 => x = x + 0.9 + force[0],
                1 => y = y - 0.9 + force[1],
                2 => x = x - 0.9 + force[0],
                3 => z = z - 0.9 + force[2],
                4 => z = z + 0.9 + force[2],
                5 => y = y + 0.9 + force[1],
                _ => {}
            }
            let radius = (x * x + y * y + z * z).sqrt();
            if let Some(parent) = index.nearest(&nodes, x, y, z) {
                if radius > inner {
                    inner = radius;
                    outer = 2.1 * inner;
                    index.cover(outer);
                }
                stuck = Some(DlaNode {
                    x,
                    y,
                    z,
                    parent: Some(parent),
                    depth: nodes[parent].depth + 1,
                });
                break;
            } else if radius > outer {
                break;
            }
        }
        match stuck {
            Some(node) => {
                misses = 0;
                index.insert(nodes.len(), node.x, node.y, node.z);
                nodes.push(node);
            }
            None => misses += 1,
        }
    }
    nodes
}

/// dla3d_wf's shared data: [`DLA_STRIDE`] values per node (from the node count, seed, glue
/// radius and force, parameters 0, 1 and 6–9).
fn dla_nodes(q: &[f64], _: &[String]) -> Vec<f64> {
    let [max_iter, seed, _, _, _, _, glue, force_x, force_y, force_z] = params_of(q);
    let max_nodes = max_iter.max(0.0) as usize;
    let seed = seed as i64;
    let glue = glue.max(0.1);
    let force = [force_x, force_y, force_z];
    let nodes = dla_grow(max_nodes, seed, glue, force);
    // Relative depth: a node's depth over the deepest depth below it (itself included).
    let mut deepest: Vec<u32> = nodes.iter().map(|n| n.depth).collect();
    for i in (0..nodes.len()).rev() {
        if let Some(par) = nodes[i].parent {
            deepest[par] = deepest[par].max(deepest[i]);
        }
    }
    let rel: Vec<f64> = nodes
        .iter()
        .zip(&deepest)
        .map(|(n, &d)| n.depth as f64 / d as f64)
        .collect();
    let mut out = Vec::with_capacity(nodes.len() * DLA_STRIDE);
    for (i, n) in nodes.iter().enumerate() {
        out.extend_from_slice(&[n.x, n.y, n.z, rel[i]]);
        match n.parent {
            Some(par) => {
                let q = &nodes[par];
                out.extend_from_slice(&[1.0, q.x, q.y, q.z, rel[par]]);
            }
            None => out.extend_from_slice(&[0.0; 5]),
        }
    }
    out
}

/// A point on a sphere of radius `r` around (x, y, z), JWildfire's way (θ drawn over a full
/// turn, so the poles are favoured).
fn dla_sphere<R: Draw>(r: &mut R, c: &[f64], radius: f64) -> [f64; 3] {
    let phi = r.unit() * (PI + PI);
    let theta = r.unit() * (PI + PI);
    let (sp, cp) = phi.sin_cos();
    let (st, ct) = theta.sin_cos();
    [
        c[0] + radius * st * cp,
        c[1] + radius * st * sp,
        c[2] + radius * ct,
    ]
}

/// One sample of the aggregate: position and colour, or None where JWildfire hides the point.
fn dla_sample<R: Draw>(v: &Prepared, nodes: &[f64], r: &mut R) -> Option<([f64; 3], f64)> {
    let [
        _,
        _,
        inner_r,
        outer_r,
        jscale,
        _,
        _,
        _,
        _,
        _,
        nodes_on,
        junctions_on,
    ] = v.params();
    let count = nodes.len() / DLA_STRIDE;
    if count == 0 {
        return None;
    }
    let n = &nodes[DLA_STRIDE * r.index(count)..];
    let n = &n[..DLA_STRIDE];
    let rnd = r.unit();
    let show_nodes = nodes_on > 0.0;
    let show_junctions = junctions_on > 0.0;
    let blur = outer_r > 1.0e-8;
    let rel = n[3];
    if n[4] == 0.0 {
        // The seed node: a sphere when nodes are shown blurred.
        if show_nodes && blur {
            return Some((dla_sphere(r, n, inner_r * jscale), 0.0));
        }
        return None;
    }
    let q = &n[5..9];
    if !blur {
        let pos = [
            n[0] + (q[0] - n[0]) * rnd,
            n[1] + (q[1] - n[1]) * rnd,
            n[2] + (q[2] - n[2]) * rnd,
        ];
        return Some((pos, rel + (q[3] - rel) * rnd));
    }
    let spread = outer_r - inner_r;
    let r_min = inner_r + spread * rel;
    let r_max = inner_r + spread * q[3];
    let node = |r: &mut R, radius: f64| Some((dla_sphere(r, n, radius * jscale), rel));
    let junction = |r: &mut R| {
        // A point on a ring around the segment to the parent, at the interpolated radius.
        let radius = r_min + (r_max - r_min) * rnd;
        let color = rel + (q[3] - rel) * rnd;
        let mut pos = [
            n[0] + (q[0] - n[0]) * rnd,
            n[1] + (q[1] - n[1]) * rnd,
            n[2] + (q[2] - n[2]) * rnd,
        ];
        let a = [q[0] - n[0], q[1] - n[1], q[2] - n[2]];
        for _ in 0..10 {
            let b = [0.5 - r.unit(), 0.5 - r.unit(), 0.5 - r.unit()];
            let c = [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ];
            let len = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
            if len > 0.001 {
                for k in 0..3 {
                    pos[k] += c[k] / len * radius;
                }
                break;
            }
        }
        Some((pos, color))
    };
    match (show_junctions, show_nodes) {
        (true, true) => {
            if r.unit() < 0.333 {
                node(r, r_min)
            } else {
                junction(r)
            }
        }
        (true, false) => junction(r),
        (false, true) => node(r, r_max),
        (false, false) => None,
    }
}

/// dla3d_wf: a 3-D diffusion-limited aggregate grown from JWildfire's seeded generator, drawn
/// as blurred spheres at the nodes and tubes along the links (or as bare links when the outer
/// blur radius is 0), coloured by relative depth when dc_color is on. Where nothing is drawn
/// the point is hidden (the sample counts, nothing is added).
fn dla3d_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, dc_color] = v.params();
    match dla_sample(v, v.data(), rng) {
        Some((pos, color)) => {
            if dc_color > 0.0 {
                acc.color = color.clamp(0.0, 1.0);
            }
            [v.w * pos[0], v.w * pos[1], v.w * pos[2]]
        }
        None => {
            acc.hide = true;
            [0.0; 3]
        }
    }
}

const INT_ANY: (f64, f64) = (f64::NEG_INFINITY, f64::INFINITY);

const P_DLA: &[Param] = &[
    p_int("dla3d_wf_max_iter", 320.0, INT_ANY.0, INT_ANY.1),
    p_int("dla3d_wf_seed", 1234.0, INT_ANY.0, INT_ANY.1),
    p("dla3d_wf_inner_blur_radius", 0.5),
    p("dla3d_wf_outer_blur_radius", 0.01),
    p("dla3d_wf_junction_scale", 1.4),
    p_int("dla3d_wf_dc_color", 1.0, INT_ANY.0, INT_ANY.1),
    p("dla3d_wf_glue_radius", 1.0),
    p("dla3d_wf_force_x", 0.0),
    p("dla3d_wf_force_y", 0.0),
    p("dla3d_wf_force_z", 0.0),
    p_int("dla3d_wf_display_nodes", 1.0, INT_ANY.0, INT_ANY.1),
    p_int("dla3d_wf_display_junctions", 1.0, INT_ANY.0, INT_ANY.1),
    p_int("dla3d_wf_single_thread", 0.0, INT_ANY.0, INT_ANY.1),
    p_int("dla3d_wf_node_sdiv_level", 0.0, 0.0, 6.0),
    p_int("dla3d_wf_node_sdiv_smooth_passes", 12.0, 0.0, 24.0),
    p("dla3d_wf_node_sdiv_smooth_lambda", 0.42),
    p("dla3d_wf_node_sdiv_smooth_mu", -0.45),
    p_int("dla3d_wf_node_blend_colormap", 1.0, 0.0, 1.0),
    p("dla3d_wf_node_mesh_scale", 1.0),
    p_int("dla3d_wf_junct_sdiv_level", 0.0, 0.0, 6.0),
    p_int("dla3d_wf_junct_sdiv_smooth_passes", 12.0, 0.0, 24.0),
    p("dla3d_wf_junct_sdiv_smooth_lambda", 0.42),
    p("dla3d_wf_junct_sdiv_smooth_mu", -0.45),
    p_int("dla3d_wf_junct_blend_colormap", 1.0, 0.0, 1.0),
    p("dla3d_wf_junct_mesh_scale", 1.0),
];

// ---------------------------------------------------------------------------------------------
// dc_*: pattern variations that scatter points over a square and colour them

/// GLSL `mod`: x − y·⌊x/y⌋.
#[inline(always)]
fn gmod(x: f64, y: f64) -> f64 {
    x - y * (x / y).floor()
}

/// Folds a point into the wedge [0, k] of a kaleidoscope with mirror angle k.
fn kaleido(x: f64, y: f64, k: f64) -> (f64, f64) {
    let ang = (gmod(atan2_approx(y, x), 2.0 * k) - k).abs();
    let len = (x * x + y * y).sqrt();
    (len * ang.cos(), len * ang.sin())
}

/// Colour channels in 0..=255 as JWildfire quantises them.
fn dc_bytes(rgb: [f64; 3]) -> [i64; 3] {
    rgb.map(|c| ((c * 256.0).floor() as i64).clamp(0, 255))
}

/// Luminance of quantised channels, in [0, 1].
fn dc_luma(c: [i64; 3]) -> f64 {
    let r = (c[0] as f64 * 0.299) as i64;
    let g = (c[1] as f64 * 0.587) as i64;
    let b = (c[2] as f64 * 0.114) as i64;
    (r + g + b) as f64 / 255.0
}

/// The part all dc_ variations share. The point is the input (ColorOnly = 1) or uniform in a
/// square of half-side `half` (1 or 0.5); its pattern colour sets the palette index, and the
/// colour's luminance, scaled and offset, gives z (which replaces the running z when reset_z
/// is 1). `tail` holds the five shared parameters, which come last (see `dc_tail!`).
#[inline(always)]
fn dc_common(
    v: &Prepared,
    tail: [f64; 5],
    t: &VarIn,
    acc: &mut Acc,
    rng: &mut FastRng,
    half: f64,
    pattern: impl FnOnce(f64, f64) -> [f64; 3],
) -> V3 {
    let [color_only, _gradient, scale_z, offset_z, reset_z] = tail;
    let (x, y) = if trunc_i(color_only) == 1 {
        (t.x, t.y)
    } else if half == 1.0 {
        let x = 2.0 * rng.f01() - 1.0;
        (x, 2.0 * rng.f01() - 1.0)
    } else {
        let x = rng.f01() - 0.5;
        (x, rng.f01() - 0.5)
    };
    let luma = dc_luma(dc_bytes(pattern(x, y)));
    acc.color = luma;
    let dz = luma * scale_z + offset_z;
    let z = if trunc_i(reset_z) == 1 {
        if v.form == Form::Regular {
            acc.z = 0.0;
        }
        dz
    } else if v.form == Form::Regular {
        dz
    } else {
        t.z + dz
    };
    [v.w * x, v.w * y, z]
}

/// Shared trailing parameters of the dc_ variations.
macro_rules! dc_tail {
    ($n:literal) => {
        [
            p_range(concat!($n, "_ColorOnly"), 0.0, 0.0, 1.0),
            p_range(concat!($n, "_Gradient"), 0.0, 0.0, 2.0),
            p(concat!($n, "_scale_z"), 0.0),
            p(concat!($n, "_offset_z"), 0.0),
            p_range(concat!($n, "_reset_z"), 1.0, 0.0, 1.0),
        ]
    };
}

const DC_FLAGS: u32 =
    flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::WRITES_ACC;

/// JWildfire's rounded 1/π in dc_mandala (kept: it is not the nearest double to 1/π).
#[allow(clippy::approx_constant)]
const MANDALA_INV_PI: f64 = 0.318309886183791;

/// dc_mandala's colour: a doubly folded kaleidoscope, an optional modular tiling, then an
/// absolute-value inversion map iterated up to 73 times on a 3-vector that becomes RGB.
fn mandala_rgb(v: &Prepared, x: f64, y: f64) -> [f64; 3] {
    let [mx, my, scale, sides, multiply, loops, inv_r, inv_g, inv_b] = v.params();
    let zoom = 5.5 - scale;
    let k = PI / sides.floor();
    let s = kaleido(zoom * x, zoom * y, k);
    let t = kaleido(s.0, s.1, k);
    let dot = t.0 * s.0 + t.1 * s.1;
    let c = dot.cos();
    let mut u = (s.0 * (1.0 - c) + t.0 * c, s.1 * (1.0 - c) + t.1 * c);
    if multiply > 0.001 {
        let m = multiply.floor();
        let ux = u.0 + gmod(gmod(u.0, m), -u.1);
        let uy = u.1 + gmod(gmod(u.1, m), -u.0);
        u = (ux, uy);
    }
    let mut p = [u.0, u.1, mx * dot];
    let shift = [1.0, 1.02, my * MANDALA_INV_PI];
    let gain = [1.3, 0.999, 0.678];
    let limit = loops.floor();
    for l in 0..73 {
        if l as f64 > limit {
            break;
        }
        let d = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        let w: [f64; 3] = std::array::from_fn(|i| gain[i] * (p[i].abs() / d - shift[i]).abs());
        p = [w[0], w[2], w[1]];
    }
    let flips = [inv_r, inv_g, inv_b];
    for i in 0..3 {
        if trunc_i(flips[i]) == 1 {
            p[i] = 1.0 - p[i];
        }
    }
    p
}

/// dc_mandala: a kaleidoscopic fractal stamp over [−1, 1]² (after a GLSL shader of the same
/// name).
fn dc_mandala(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, _, _, tail @ ..] = v.params::<14>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| mandala_rgb(v, x, y))
}

const P_DC_MANDALA: &[Param] = &{
    let tail = dc_tail!("dc_mandala");
    [
        p("dc_mandala_mX", 0.025),
        p("dc_mandala_mY", -0.001245675),
        p("dc_mandala_scale", 2.0),
        p("dc_mandala_sides", 12.0),
        p("dc_mandala_multiply", 1.5),
        p("dc_mandala_loops", 64.0),
        p_range("dc_mandala_iR", 0.0, 0.0, 1.0),
        p_range("dc_mandala_iG", 0.0, 0.0, 1.0),
        p_range("dc_mandala_iB", 1.0, 0.0, 1.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// dc_inversion's colour: the point folded (|x|), scaled, shifted and inverted in a circle,
/// repeatedly; brightness from the last and the smallest size reached.
fn inversion_rgb(v: &Prepared, x: f64, y: f64) -> [f64; 3] {
    let [_, time, iterations, sx, sy] = v.params();
    let iters = trunc_i(iterations);
    let (ox, oy) = ((time * 0.123).sin(), (time * 0.0567).atan());
    let (mut vx, mut vy) = (x, y);
    let mut l = 0.0;
    let mut l_min = 10000.0;
    for _ in 0..iters {
        vx = vx.abs();
        vx = vx * sx + ox;
        vy = vy * sy + oy;
        // Inversion in the circle of radius 0.9 around (0.5, 0.5), plus a faint warp.
        let (dx, dy) = (vx - 0.5, vy - 0.5);
        let f = 0.9 / (dx * dx + dy * dy);
        let mut ix = 0.5 - dx * 0.9 * f;
        let mut iy = 0.5 - dy * 0.9 * f;
        ix += (ix * 0.001).sin() / (iy * 0.001).cos();
        iy += (ix * 0.001).sin() * (iy * 0.001).cos();
        vx = ix;
        vy = iy;
        let (qx, qy) = (vx * vx, vy * vy);
        l = (qx * qx + qy * qy).sqrt();
        l_min = cpp_min(l, l_min);
    }
    let tt = 2.1 + time * 0.025;
    let base = [
        (tt * 1.790).sin() * 0.5 + 0.5,
        (tt * 1.345).sin() * 0.5 + 0.5,
        (tt * 1.123).sin() * 0.5 + 0.5,
    ];
    let norm = (base[0] * base[0] + base[1] * base[1] + base[2] * base[2]).sqrt();
    let bright = l * l * 11.0;
    let m = (3.0 * l_min * (1.0 - l_min)).powf(5.0) + 0.14;
    base.map(|c| 1.0 - (-((c / norm * bright) * m)).exp())
}

/// dc_inversion: an iterated circle-inversion fractal stamp over [−1, 1]².
fn dc_inversion(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, tail @ ..] = v.params::<10>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| inversion_rgb(v, x, y))
}

const P_DC_INVERSION: &[Param] = &{
    let tail = dc_tail!("dc_inversion");
    [
        p("dc_inversion_seed", 10000.0),
        p("dc_inversion_time", 0.0),
        p_range("dc_inversion_Iterations", 50.0, 0.0, 100.0),
        p_range("dc_inversion_ScaleX", 1.5, 1.1, 3.0),
        p_range("dc_inversion_ScaleY", 1.5, 1.1, 3.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// Derived values of dc_poincaredisc (after its parameters): the centre and radius of the
/// third folding circle and the normal of the second fold line.
fn prep_poincare(v: &mut Prepared) {
    let [_, _, n, p] = v.params();
    let n = trunc_i(n) as f64;
    let m = trunc_i(p) as f64;
    let a = PI / n;
    let mut b = PI / m;
    if a + b >= 0.5 * PI {
        b = 0.5 * PI - a - 0.01;
    }
    let (sa, ca) = a.sin_cos();
    let sb = b.sin();
    let s = (a + b).cos() / (1.0 - sa * sa - sb * sb).sqrt();
    let cx = (s * s + 1.0) / (2.0 * s * ca);
    let cr = (cx * cx - 1.0).sqrt();
    v.p.extend_from_slice(&[cx, cr, sa, -ca]);
}

/// dc_poincaredisc's colour: a hyperbolic (n, p) tiling of the unit disc by repeated folds
/// (a mirror, a line and a circle), shaded by the distance to the circle and checkered by the
/// parity of the line and circle folds.
fn poincare_rgb(v: &Prepared, x: f64, y: f64) -> [f64; 3] {
    let [zoom, max_iter, _, _, _, checkers1, checkers2] = v.params();
    let [cx, cr, nx, ny] = v.derived();
    let (mut zx, mut zy) = (x * zoom, y * zoom);
    if zx * zx + zy * zy > 1.0 {
        return [0.0; 3];
    }
    // JWildfire's mirror-fold counter never counts (it compares a point with itself), so
    // only the line and circle folds are counted.
    let mut line_folds = 0.0;
    let mut circle_folds = 0.0;
    for _ in 0..trunc_i(max_iter) {
        zy = zy.abs();
        let t = 2.0 * cpp_min(0.0, zx * nx + zy * ny);
        if t < 0.0 {
            line_folds += 1.0;
        }
        zx -= nx * t;
        zy -= ny * t;
        zx -= cx;
        let k = cpp_max(cr * cr / (zx * zx + zy * zy), 1.0);
        if k != 1.0 {
            circle_folds += 1.0;
        }
        zx *= k;
        zy *= k;
        zx += cx;
    }
    let dx = zx - cx;
    let r = ((dx * dx + zy * zy).sqrt() - cr).abs().powf(0.25);
    let c1 = if trunc_i(checkers1) == 1 { 1.0 } else { 0.0 };
    let c2 = if trunc_i(checkers2) == 1 { 1.0 } else { 0.0 };
    let k = gmod(c1 * line_folds + c2 * circle_folds, 2.0);
    [r * (0.5 * k + 0.5); 3]
}

/// dc_poincaredisc: a hyperbolic tiling of the Poincaré disc over [−0.5, 0.5]².
fn dc_poincaredisc(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, tail @ ..] = v.params::<12>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| poincare_rgb(v, x, y))
}

const P_DC_POINCARE: &[Param] = &{
    let tail = dc_tail!("dc_poincaredisc");
    [
        p("dc_poincaredisc_zoom", 2.0),
        p_range("dc_poincaredisc_MaxIter", 10.0, 0.0, 20.0),
        p_range("dc_poincaredisc_n", 4.0, 3.0, 20.0),
        p_range("dc_poincaredisc_p", 5.0, 3.0, 20.0),
        p_range("dc_poincaredisc_checkers0", 1.0, 0.0, 1.0),
        p_range("dc_poincaredisc_checkers1", 1.0, 0.0, 1.0),
        p_range("dc_poincaredisc_checkers2", 1.0, 0.0, 1.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// dc_circuits' running glow: JWildfire seeds it with (101 + 2)·0.9 from the default glow
/// and intensity (whatever the parameters say) and carries it from call to call.
const CIRCUITS_GLOW0: f64 = (101.0 + 2.0) * 0.9;

/// One orbit of dc_circuits' fold map: colour, and the glow it adds.
fn circuits_orbit(v: &Prepared, zx0: f64, zy0: f64, t: f64) -> ([f64; 3], f64) {
    let [_, _, _, intensity, _, pulse, _, loops, zoom] = v.params();
    let (mut zx, mut zy) = (zx0, zy0);
    let mut m = 0.0;
    let mut ot = 1000.0;
    let mut ot2 = 1000.0;
    let mut budget = (loops / 4.0 + (5.0 * zoom).floor()).floor();
    for i in 0..11 {
        let d = (zx * zx + zy * zy).clamp(0.1, 0.5);
        zx = zx.abs() / d - t;
        zy = zy.abs() / d - t;
        let l = (zx * zx + zy * zy).sqrt();
        let o = cpp_min(cpp_max(cpp_min(zx, zy).abs(), -l + 0.25), (l - 0.25).abs());
        ot = cpp_min(ot, o);
        ot2 = cpp_min(l * 0.1, ot2);
        m = cpp_max(m, i as f64 * (1.0 - signum_java(ot - o).abs()));
        if budget <= 0.0 {
            break;
        }
        budget -= 1.0;
    }
    m += 1.0;
    let w = intensity * zoom * m;
    let circ = (cpp_max(0.0, w - ot2) / w).powf(6.0);
    let glow = cpp_max((cpp_max(0.0, w - ot) / w).powf(0.25), circ);
    let base = [0.1 + 0.45, 0.1 + 0.75, 0.1 + m * 0.1];
    let len = (base[0] * base[0] + base[1] * base[1] + base[2] * base[2]).sqrt();
    let shade = 0.4 + gmod(m / 9.0 - t * pulse + ot2 * 2.0, 1.0);
    let hot = circ * (10.0 - m) * 3.0;
    let tint = [1.0, 0.7, 0.3];
    let col = std::array::from_fn(|i| base[i] / len * shade + tint[i] * hot);
    (col, glow)
}

/// dc_circuits' colour at (x, y), given the running glow; returns the colour and the new
/// glow.
fn circuits_rgb(v: &Prepared, x: f64, y: f64, glow0: f64) -> ([f64; 3], f64) {
    let [_, time, rate, _, focus, _, _, loops, zoom] = v.params();
    let mut n = time * 0.01 * rate;
    let mut tt = 2.0 * rate;
    if n > 6.0 * rate {
        n -= 8.0 * rate;
    }
    if n < 4.0 * rate {
        tt += n;
    } else {
        tt = 8.0 * rate - n;
    }
    let zz = 1.05 - zoom;
    let sph = (x * x + y * y).sqrt() * 0.1;
    let sph = (1.0 - sph * sph).sqrt() * 2.0;
    let a = tt * PI;
    let b = a + tt;
    let c = a.cos() + b.sin();
    let (sb, cb) = b.sin_cos();
    let (sa, ca) = a.sin_cos();
    let (ux, uy) = (cb * x + sb * y, x * -sb + y * cb);
    let (ux, uy) = (ca * ux + -sa * uy, ux * sa + uy * ca);
    let ux = (ux - c.sin() / PI) * zz;
    let uy = (uy - c.cos() / PI) * zz;
    let pix = 0.5 / 1000.0 * zz / sph;
    let dof = zoom * focus + tt * 0.25;
    let mut left = loops.floor();
    let mut glow = glow0;
    let mut col = [0.0; 3];
    for aa in 0..24 {
        let ax = (aa as f64 / 6.0).floor();
        let ay = gmod(aa as f64, 6.0).floor();
        let (c, g) = circuits_orbit(v, ux + ax * pix * dof, uy + ay * pix * dof, tt);
        col = c;
        glow += g;
        if left <= 0.0 {
            break;
        }
        left -= 1.0;
    }
    let fl = loops.floor();
    glow /= fl;
    let fade = 1.0 - (x * x + y * y).sqrt();
    let gain = [1.2, 1.1, 1.0];
    let rgb = std::array::from_fn(|i| (0.15 * (1.0 - glow) + col[i] / fl * glow) * fade * gain[i]);
    (rgb, glow)
}

/// dc_circuits: glowing circuit-like traces over [−1, 1]² (a kaliset-style fold fractal). The
/// glow level carries over from one point to the next, as in JWildfire (its state is shared
/// by the render threads).
fn dc_circuits(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, _, _, _, _, _, tail @ ..] = v.params::<14>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        let glow0 = if v.state.get(1) == 1.0 {
            v.state.get(0)
        } else {
            CIRCUITS_GLOW0
        };
        let (rgb, glow) = circuits_rgb(v, x, y, glow0);
        v.state.set(0, glow);
        v.state.set(1, 1.0);
        rgb
    })
}

const P_DC_CIRCUITS: &[Param] = &{
    let tail = dc_tail!("dc_circuits");
    [
        p("dc_circuits_Seed", 1000000.0),
        p("dc_circuits_time", 0.0),
        p("dc_circuits_rate", 0.8),
        p("dc_circuits_intensity", 0.9),
        p("dc_circuits_focus", 1.5),
        p("dc_circuits_pulse", 10.0),
        p("dc_circuits_glow", 2.0),
        p("dc_circuits_loops", 15.0),
        p("dc_circuits_zoom", 1.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// dc_turbulence's grey level: a few rounds of a sin/cos displacement of the zoomed point
/// (shifted by −20), accumulating inverse distances ("water caustics").
fn turbulence_rgb(v: &Prepared, x: f64, y: f64) -> [f64; 3] {
    let [_, time, zoom, level] = v.params();
    let level = trunc_i(level);
    let (px, py) = (x * zoom - 20.0, y * zoom - 20.0);
    let (mut ix, mut iy) = (px, py);
    let mut c = 1.0;
    let inten = 0.05;
    for n in 0..level {
        let t = time * (1.0 - 3.0 / (n + 1) as f64);
        let nx = px + ((t - ix).cos() + (t + iy).sin());
        let ny = py + ((t - iy).sin() + (t + ix).cos());
        ix = nx;
        iy = ny;
        let a = px / ((ix + t).sin() / inten);
        let b = py / ((iy + t).cos() / inten);
        c += 1.0 / (a * a + b * b).sqrt();
    }
    c /= level as f64;
    c = 1.5 - c.sqrt();
    [c * c * c * c; 3]
}

/// dc_turbulence: a grey caustic pattern over [−0.5, 0.5]².
fn dc_turbulence(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, _, tail @ ..] = v.params::<9>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| turbulence_rgb(v, x, y))
}

const P_DC_TURBULENCE: &[Param] = &{
    let tail = dc_tail!("dc_turbulence");
    [
        p("dc_turbulence_seed", 10000.0),
        p_range("dc_turbulence_time", 0.0, 1.0, 1000.0),
        p("dc_turbulence_zoom", 8.0),
        p_range("dc_turbulence_Level", 3.0, 1.0, 5.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

/// Number of kernel centres of dc_gabornoise.
const GABOR_N: usize = 100;

/// Derived values of dc_gabornoise: its 100 pseudo-random centres (a hash of the index,
/// turned by a time-dependent shear), as (x, y) pairs.
fn prep_gabor(v: &mut Prepared) {
    let [_, time] = v.params();
    let hash = |p: f64, k: f64| (fract((k * p).sin() * 43141.59265) * 2.0 - 1.0) * 30.0;
    for i in 0..GABOR_N {
        let i = i as f64;
        let (hx, hy, hz) = (hash(i, 63.31), hash(i, 395.467), hash(i, 1.0));
        let c = (hz / 1e2 * time).cos();
        v.p.push(c * hx + (33.0 + c) * hy);
        v.p.push(hx * (11.0 + c) + hy * c);
    }
}

/// dc_gabornoise's colour: the summed (approximate) angles from the mirrored, zoomed point to
/// the centres, through a cosine palette.
fn gabor_rgb(v: &Prepared, x: f64, y: f64) -> [f64; 3] {
    let [_, _, zoom] = v.params();
    let centres = v.table(0);
    let ux = (x * zoom).abs() * 45.0;
    let uy = (y * zoom) * 45.0;
    let mut a = 0.0;
    for c in centres.chunks_exact(2) {
        a += atan2_approx(ux - c[0], uy - c[1]);
    }
    [
        a.cos() * 0.6 + 0.6,
        (23.0 + a).cos() * 0.6 + 0.6,
        (21.0 + a).cos() * 0.6 + 0.6,
    ]
}

/// dc_gabornoise: a fingerprint-like angular pattern over [−0.5, 0.5]².
fn dc_gabornoise(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, _, _, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| gabor_rgb(v, x, y))
}

const P_DC_GABOR: &[Param] = &{
    let tail = dc_tail!("dc_gabornoise");
    [
        p_range("dc_gabornoise_seed", 10000.0, 0.0, 10000.0),
        p("dc_gabornoise_time", 0.0),
        p_range("dc_gabornoise_zoom", 20.0, 1.0, 100.0),
        tail[0],
        tail[1],
        tail[2],
        tail[3],
        tail[4],
    ]
};

// ---------------------------------------------------------------------------------------------
// Registry

pub(super) static DEFS: &[VarDef] = &[
    super::text::TEXT_WF,
    VarDef::new("sym_ng1", sym_eval)
        .params(P_NG1)
        .flags(SYM)
        .prepare(prep_ng1),
    VarDef::new("sym_ng2", sym_eval)
        .params(P_NG2)
        .flags(SYM)
        .prepare(prep_ng2),
    VarDef::new("sym_ng3", sym_eval)
        .params(P_NG3)
        .flags(SYM)
        .prepare(prep_ng3),
    VarDef::new("sym_ng4", sym_eval)
        .params(P_NG4)
        .flags(SYM)
        .prepare(prep_ng4),
    VarDef::new("sym_ng5", sym_eval)
        .params(P_NG5)
        .flags(SYM)
        .prepare(prep_ng5),
    VarDef::new("sym_ng6", sym_eval)
        .params(P_NG6)
        .flags(SYM)
        .prepare(prep_ng6),
    VarDef::new("sym_ng7", sym_eval)
        .params(P_NG7)
        .flags(SYM)
        .prepare(prep_ng7),
    VarDef::new("sym_ng8", sym_eval)
        .params(P_NG8)
        .flags(SYM)
        .prepare(prep_ng8),
    VarDef::new("sym_ng9", sym_eval)
        .params(P_NG9)
        .flags(SYM)
        .prepare(prep_ng9),
    VarDef::new("sym_ng10", sym_eval)
        .params(P_NG10)
        .flags(SYM)
        .prepare(prep_ng10),
    VarDef::new("sym_ng11", sym_eval)
        .params(P_NG11)
        .flags(SYM)
        .prepare(prep_ng11),
    VarDef::new("sym_ng12", sym_eval)
        .params(P_NG12)
        .flags(SYM)
        .prepare(prep_ng12),
    VarDef::new("sym_ng13", sym_eval)
        .params(P_NG13)
        .flags(SYM)
        .prepare(prep_ng13),
    VarDef::new("sym_ng14", sym_eval)
        .params(P_NG14)
        .flags(SYM)
        .prepare(prep_ng14),
    VarDef::new("sym_ng15", sym_eval)
        .params(P_NG15)
        .flags(SYM)
        .prepare(prep_ng15),
    VarDef::new("sym_ng16", sym_eval)
        .params(P_NG16)
        .flags(SYM)
        .prepare(prep_ng16),
    VarDef::new("sym_ng17", sym_eval)
        .params(P_NG17)
        .flags(SYM)
        .prepare(prep_ng17),
    VarDef::new("sym_bg1", sym_eval)
        .params(P_BG1)
        .flags(SYM)
        .prepare(prep_bg1),
    VarDef::new("sym_bg2", sym_eval)
        .params(P_BG2)
        .flags(SYM)
        .prepare(prep_bg2),
    VarDef::new("sym_bg3", sym_eval)
        .params(P_BG3)
        .flags(SYM)
        .prepare(prep_bg3),
    VarDef::new("sym_bg4", sym_eval)
        .params(P_BG4)
        .flags(SYM)
        .prepare(prep_bg4),
    VarDef::new("sym_bg5", sym_eval)
        .params(P_BG5)
        .flags(SYM)
        .prepare(prep_bg5),
    VarDef::new("sym_bg6", sym_eval)
        .params(P_BG6)
        .flags(SYM)
        .prepare(prep_bg6),
    VarDef::new("sym_bg7", sym_eval)
        .params(P_BG7)
        .flags(SYM)
        .prepare(prep_bg7),
    VarDef::new("hilbert_js", hilbert_js)
        .params(P_HILBERT)
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0], hilbert_segments)
        .prepare(prep_la5),
    VarDef::new("rsquares_js", rsquares_js)
        .params(P_RSQUARES)
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0], rsquares_segments)
        .prepare(prep_la5),
    VarDef::new("tree_js", tree_js)
        .params(P_TREE)
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0, 3, 4, 5], tree_segments)
        .prepare(prep_tree),
    VarDef::new("svensson_js", svensson_js)
        .params(P_SVENSSON)
        .flags(flag::JWILDFIRE | flag::WRITES_ACC),
    VarDef::new("dla3d_wf", dla3d_wf)
        .params(P_DLA)
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::HIDES)
        .shared(&[0, 1, 6, 7, 8, 9], dla_nodes),
    VarDef::new("dc_mandala", dc_mandala)
        .params(P_DC_MANDALA)
        .flags(DC_FLAGS),
    VarDef::new("dc_inversion", dc_inversion)
        .params(P_DC_INVERSION)
        .flags(DC_FLAGS),
    VarDef::new("dc_poincaredisc", dc_poincaredisc)
        .params(P_DC_POINCARE)
        .flags(DC_FLAGS)
        .prepare(prep_poincare),
    VarDef::new("dc_circuits", dc_circuits)
        .params(P_DC_CIRCUITS)
        .flags(DC_FLAGS | flag::STATEFUL),
    VarDef::new("dc_turbulence", dc_turbulence)
        .params(P_DC_TURBULENCE)
        .flags(DC_FLAGS),
    VarDef::new("dc_gabornoise", dc_gabornoise)
        .params(P_DC_GABOR)
        .flags(DC_FLAGS)
        .prepare(prep_gabor),
];

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        if a.is_nan() || b.is_nan() {
            return a.is_nan() && b.is_nan();
        }
        let d = (a - b).abs();
        d <= 1e-9 * a.abs().max(b.abs()) || d <= 1e-12
    }

    fn assert_all_close(what: &str, got: &[f64], want: &[f64]) {
        assert_eq!(got.len(), want.len(), "{what}: length");
        for (i, (g, w)) in got.iter().zip(want).enumerate() {
            assert!(close(*g, *w), "{what}[{i}]: got {g}, want {w}");
        }
    }

    fn prep(name: &str, params: &[f64]) -> Prepared {
        prep_w(name, params, 1.0)
    }

    fn prep_w(name: &str, params: &[f64], w: f64) -> Prepared {
        let id = by_name(name).unwrap_or_else(|| panic!("{name} not registered"));
        Prepared::new(id, Form::Regular, w, params, Affine::default(), true)
    }

    /// The six pattern points the dc_ oracle used.
    const DC_POINTS: [[f64; 2]; 6] = [
        [0.13, -0.27],
        [-0.41, 0.05],
        [0.33, 0.29],
        [-0.07, -0.45],
        [0.6, -0.1],
        [0.0021, 0.0017],
    ];

    #[test]
    fn registry_names_and_params() {
        for d in DEFS {
            let id = by_name(d.name).expect(d.name);
            assert_eq!(info(id).name, d.name);
            assert!(d.has(flag::JWILDFIRE));
            for (k, pa) in d.params.iter().enumerate() {
                assert!(pa.name.starts_with(d.name), "{}", pa.name);
                assert_eq!(
                    param_of(pa.name),
                    Some((id, Form::Regular, k)),
                    "{}",
                    pa.name
                );
            }
        }
        // Every sym_* class JWildfire registers.
        for i in 1..=17 {
            assert!(by_name(&format!("sym_ng{i}")).is_some());
        }
        for i in 1..=7 {
            assert!(by_name(&format!("sym_bg{i}")).is_some());
        }
    }

    #[test]
    fn sym_tables_match_jwildfire() {
        for (name, params, want) in SYM_CASES {
            let v = prep(name, params);
            assert_all_close(name, v.table(0), want);
        }
    }

    #[test]
    fn sym_outputs_are_the_group_maps_picked_uniformly() {
        let mut rng = FastRng::new(5);
        for (name, params, tab) in SYM_CASES {
            let v = prep_w(name, params, 0.7);
            let n = (tab.len() - 1) / 6;
            let mut hits = vec![0usize; n];
            let (x, y) = (0.31, -0.57);
            let calls = 4000 * n;
            for _ in 0..calls {
                let a = eval_prepared(&v, [x, y, 0.9], Acc::default(), true, &mut rng);
                assert_eq!(a.z, 0.0);
                let (sx, sy) = (x + tab[0], y + tab[0]);
                let k = (0..n)
                    .find(|&k| {
                        let m = &tab[1 + 6 * k..];
                        close(a.x, 0.7 * (m[0] * sx + m[1] * sy + m[2]))
                            && close(a.y, 0.7 * (m[3] * sx + m[4] * sy + m[5]))
                    })
                    .unwrap_or_else(|| panic!("{name}: output not one of the maps"));
                hits[k] += 1;
            }
            // Maps that coincide share their hits; count per distinct map.
            let mut distinct: Vec<(&[f64], usize)> = Vec::new();
            for k in 0..n {
                let m = &tab[1 + 6 * k..7 + 6 * k];
                match distinct.iter_mut().find(|(d, _)| *d == m) {
                    Some(e) => e.1 += hits[k],
                    None => distinct.push((m, hits[k])),
                }
            }
            let copies = |m: &[f64]| (0..n).filter(|&k| &tab[1 + 6 * k..7 + 6 * k] == m).count();
            for (m, h) in distinct {
                let expect = calls as f64 * copies(m) as f64 / n as f64;
                assert!(
                    (h as f64 - expect).abs() < 6.0 * expect.sqrt() + 1.0,
                    "{name}: {h} hits, expected about {expect}"
                );
            }
        }
    }

    #[test]
    fn line_drawings_match_jwildfire() {
        for (name, params, segs, samples) in LINE_CASES {
            let v = prep(name, params);
            let d = v.table(0);
            assert_eq!(d.len(), LA_HEAD);
            assert_all_close(name, v.data(), segs);
            let count = segs.len() / 4;
            let mut mwc = Mwc::new(777);
            let mut got = Vec::new();
            for k in 0..samples.len() / 2 {
                let (x, y) = la_sample(v.derived(), v.data(), k % count, &mut mwc);
                got.push(x);
                got.push(y);
            }
            assert_all_close(name, &got, samples);
        }
    }

    #[test]
    fn line_drawings_sizes_and_weighting() {
        // Segment counts: 4^n − 1 moves, 4 sides per square, (3^(n+1) − 1)/2 branches.
        for (name, level, count) in [
            ("hilbert_js", 5.0, 1023),
            ("rsquares_js", 4.0, 4 * 85),
            ("tree_js", 4.0, 121),
        ] {
            let v = prep(name, &[level]);
            assert_eq!(v.data().len() / 4, count, "{name}");
        }
        // Neither lines nor points: nothing drawn. tree_js doubles its output.
        let mut rng = FastRng::new(3);
        let v = prep("hilbert_js", &[2.0, 0.0, 0.5, 0.0, 3.0]);
        let a = eval_prepared(&v, [0.2, 0.1, 0.0], Acc::default(), true, &mut rng);
        assert_eq!((a.x, a.y), (0.0, 0.0));
        let v = prep_w("tree_js", &[1.0, 0.0, 0.5, 15.0, 37.0, 0.65, 1.0, 0.0], 0.5);
        let tips = v.data();
        for _ in 0..50 {
            let a = eval_prepared(&v, [0.2, 0.1, 0.0], Acc::default(), true, &mut rng);
            let hit = tips.chunks(4).any(|s| close(a.x, s[0]) && close(a.y, s[1]));
            assert!(hit, "tree_js dot ({}, {}) not at a segment start", a.x, a.y);
        }
    }

    #[test]
    fn svensson_formula_and_overwrite() {
        let v = prep_w("svensson_js", &[], 0.6);
        let mut rng = FastRng::new(1);
        let (x, y) = (0.4, -1.3);
        let start = Acc {
            x: 5.0,
            y: -7.0,
            z: 0.25,
            color: 0.5,
            hide: false,
        };
        let a = eval_prepared(&v, [x, y, 0.0], start, true, &mut rng);
        let ex = -6.56 * (1.4 * x).sin() - (1.56 * y).sin();
        let ey = 1.4 * (1.4 * x).cos() + (1.56 * y).cos();
        assert!(close(a.x, 0.6 * ex) && close(a.y, 0.6 * ey));
        assert_eq!(a.z, 0.25);
    }

    #[test]
    fn dla_growth_matches_jwildfire() {
        for (case, want) in DLA_GROW {
            let mut params = vec![case[0], case[1], 0.5, 0.01, 1.4, 1.0, case[2]];
            params.extend_from_slice(&case[3..6]);
            let v = prep("dla3d_wf", &params);
            let got = v.data();
            assert_eq!(got.len() / DLA_STRIDE, want.len() / 5, "node count");
            for (g, w) in got.chunks(DLA_STRIDE).zip(want.chunks(5)) {
                assert_all_close("node", &g[..4], &w[..4]);
                if w[4] < 0.0 {
                    assert_eq!(g[4], 0.0);
                } else {
                    let par = &want[5 * w[4] as usize..];
                    assert_eq!(g[4], 1.0);
                    assert_all_close("parent", &g[5..9], &par[..4]);
                }
            }
        }
    }

    #[test]
    fn dla_samples_match_jwildfire() {
        for (case, want) in DLA_SAMPLES {
            let params = [
                case[0], case[1], case[3], case[4], case[5], 1.0, case[2], 0.0, 0.0, 0.0, case[6],
                case[7],
            ];
            let v = prep("dla3d_wf", &params);
            let mut mwc = Mwc::new(case[1] as i64);
            for w in want.chunks(4) {
                match dla_sample(&v, v.data(), &mut mwc) {
                    Some((pos, c)) => assert_all_close("sample", &[pos[0], pos[1], pos[2], c], w),
                    None => assert!(w[0].is_nan(), "hidden where JWildfire draws"),
                }
            }
        }
    }

    #[test]
    fn dla_hidden_and_degenerate_cases() {
        // Neither nodes nor junctions: only the blurred seed node can show, and it is hidden
        // too; the variation then adds nothing.
        let v = prep(
            "dla3d_wf",
            &[40.0, 9.0, 0.5, 0.01, 1.4, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        );
        let mut rng = FastRng::new(2);
        for _ in 0..200 {
            let a = eval_prepared(&v, [0.3, 0.2, 0.1], Acc::default(), true, &mut rng);
            assert_eq!((a.x, a.y, a.z), (0.0, 0.0, 0.0));
        }
        // A seed whose generator is stuck at 0 grows nothing (JWildfire would hang).
        let v = prep("dla3d_wf", &[50.0, 65536.0]);
        assert_eq!(v.data().len(), DLA_STRIDE);
    }

    fn dc_rgb_of(name: &str, v: &Prepared, x: f64, y: f64, glow: &mut f64) -> [f64; 3] {
        match name {
            "dc_mandala" => mandala_rgb(v, x, y),
            "dc_inversion" => inversion_rgb(v, x, y),
            "dc_poincaredisc" => poincare_rgb(v, x, y),
            "dc_turbulence" => turbulence_rgb(v, x, y),
            "dc_gabornoise" => gabor_rgb(v, x, y),
            "dc_circuits" => {
                let (c, g) = circuits_rgb(v, x, y, *glow);
                *glow = g;
                c
            }
            _ => unreachable!(),
        }
    }

    #[test]
    fn dc_patterns_match_jwildfire() {
        for (name, params, want) in DC_RGB {
            let v = prep(name, params);
            let mut glow = CIRCUITS_GLOW0;
            let mut got = Vec::new();
            for [x, y] in DC_POINTS {
                got.extend(dc_rgb_of(name, &v, x, y, &mut glow));
            }
            assert_all_close(name, &got, want);
        }
    }

    #[test]
    fn dc_full_transform_matches_jwildfire() {
        let mut params = vec![0.025, -0.001245675, 2.0, 12.0, 1.5, 64.0, 0.0, 0.0, 1.0];
        params.extend_from_slice(&[1.0, 2.0, 0.7, 0.1, 1.0]);
        let v = prep_w("dc_mandala", &params, 0.8);
        let mut rng = FastRng::new(4);
        for (inp, want) in DC_FULL {
            let start = Acc {
                x: 0.2,
                y: 0.3,
                z: 0.5,
                color: 0.9,
                hide: false,
            };
            let a = eval_prepared(&v, [inp[0], inp[1], 0.4], start, true, &mut rng);
            assert_all_close("dc_mandala", &[a.x, a.y, a.z, a.color], want);
        }
    }

    #[test]
    fn dc_scatter_ranges_and_z_modes() {
        let mut rng = FastRng::new(8);
        for (name, half) in [
            ("dc_mandala", 1.0),
            ("dc_inversion", 1.0),
            ("dc_circuits", 1.0),
            ("dc_poincaredisc", 0.5),
            ("dc_turbulence", 0.5),
            ("dc_gabornoise", 0.5),
        ] {
            let v = prep_w(name, &[], 2.0);
            let mut sum = [0.0; 2];
            let n = 4000;
            for _ in 0..n {
                let start = Acc {
                    x: 1.0,
                    y: 1.0,
                    z: 3.0,
                    color: 0.5,
                    hide: false,
                };
                let a = eval_prepared(&v, [9.0, 9.0, 9.0], start, true, &mut rng);
                let (x, y) = ((a.x - 1.0) / 2.0, (a.y - 1.0) / 2.0);
                assert!(
                    (-half..half).contains(&x) && (-half..half).contains(&y),
                    "{name}"
                );
                assert!((0.0..=1.0).contains(&a.color), "{name}");
                // Default z: reset to luminance·0 + 0.
                assert_eq!(a.z, 0.0, "{name}");
                sum[0] += x;
                sum[1] += y;
            }
            for s in sum {
                assert!(
                    (s / n as f64).abs() < 0.05 * half,
                    "{name}: mean {}",
                    s / n as f64
                );
            }
        }
        // reset_z 0 adds to the running z.
        let params = [
            0.025,
            -0.001245675,
            2.0,
            12.0,
            1.5,
            64.0,
            0.0,
            0.0,
            1.0,
            1.0,
            2.0,
            0.5,
            0.25,
            0.0,
        ];
        let v = prep("dc_mandala", &params);
        let start = Acc {
            x: 0.0,
            y: 0.0,
            z: 3.0,
            color: 0.0,
            hide: false,
        };
        let a = eval_prepared(&v, [0.13, -0.27, 0.0], start, true, &mut rng);
        assert!(close(a.z, 3.0 + a.color * 0.5 + 0.25));
    }

    #[test]
    fn dc_circuits_carries_its_glow() {
        let v = prep(
            "dc_circuits",
            &[
                1000000.0, 0.0, 0.8, 0.9, 1.5, 10.0, 2.0, 15.0, 1.0, 1.0, 2.0,
            ],
        );
        let mut rng = FastRng::new(1);
        let mut glow = CIRCUITS_GLOW0;
        for [x, y] in DC_POINTS {
            let a = eval_prepared(&v, [x, y, 0.0], Acc::default(), true, &mut rng);
            let want = dc_luma(dc_bytes(circuits_rgb(&v, x, y, glow).0));
            glow = circuits_rgb(&v, x, y, glow).1;
            assert!(close(a.color, want));
            assert!(close(v.state.get(0), glow));
        }
    }

    #[test]
    fn mwc_matches_jwildfire_sequence_shape() {
        // Seeds whose low 16 bits are 0 leave the generator at 0 forever.
        let mut m = Mwc::new(65536 * 3);
        assert!((0..10).all(|_| m.next_f64() == 0.0));
        let mut m = Mwc::new(42);
        let xs: Vec<f64> = (0..1000).map(|_| m.next_f64()).collect();
        assert!(xs.iter().all(|x| (0.0..=1.000000001).contains(x)));
        let mean = xs.iter().sum::<f64>() / 1000.0;
        assert!((mean - 0.5).abs() < 0.05);
    }

    // Numbers below were printed by JWildfire's own code (its classes run under Java 17 with
    // stub framework classes, outside this project): facts to compare against.

    /// (name, parameters, derived table: shift, then a b c d e f per map).
    #[rustfmt::skip]
    const SYM_CASES: &[(&str, &[f64], &[f64])] = &[
        ("sym_ng1", &[0.5, 0.5], &[0.0, 1.0, 0.0, -0.25, 0.0, 1.0, -0.25, 1.0, 0.0, 0.25, 0.0, 1.0, 0.25]),
        ("sym_ng2", &[2.0, 2.0], &[0.0, 1.0, 0.0, -1.0, 0.0, 1.0, -1.0, 1.0, 0.0, 1.0, 0.0, -1.0, 1.0]),
        ("sym_ng3", &[0.5, 0.0, 2.0], &[0.0, 1.0, 0.0, -1.5, 0.0, 1.0, -1.0, -1.0, 0.0, 1.5, 0.0, -1.0, 1.0]),
        ("sym_ng4", &[0.0, 0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, -2.0, 0.0, 1.0, -1.5, -1.0, 0.0, 0.0, 0.0, -1.0, -0.5, 1.0, 0.0, 0.0, 0.0, -1.0, 0.5, -1.0, 0.0, 2.0, 0.0, 1.0, -0.5]),
        ("sym_ng5", &[0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, -2.0, 0.0, 1.0, -0.5, -1.0, 0.0, 0.0, 0.0, -1.0, -0.5, 1.0, 0.0, 0.0, 0.0, -1.0, -0.5, -1.0, 0.0, 2.0, 0.0, 1.0, -0.5]),
        ("sym_ng6", &[0.1, 1.0, 1.0], &[0.0, 1.0, 0.0, -0.5, 0.0, 1.0, -0.45, 1.0, 0.0, -0.5, 0.0, -1.0, -0.55, 1.0, 0.0, 0.5, 0.0, 1.0, 0.55, 1.0, 0.0, 0.5, 0.0, -1.0, 0.45]),
        ("sym_ng7", &[0.0, 0.0], &[0.0, 1.0, 0.0, -0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0, -0.0]),
        ("sym_ng8", &[0.0, 0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, -1.0, 0.0, -1.0, -0.0, -1.0, 0.0, 1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, -0.0, 1.0, 0.0, -1.0, 0.0, 1.0, 0.0, 1.0, 0.0, -1.0, 0.0, -1.0, 0.0, -1.0, 0.0, 1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 1.0, 0.0]),
        ("sym_ng9", &[0.0, 0.0], &[0.0, 1.0, 0.0, 0.0, 0.0, -1.0, -0.0, -1.0, 0.0, -0.0, 0.0, 1.0, 0.0, -1.0, 0.0, -0.0, 0.0, -1.0, -0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]),
        ("sym_ng10", &[0.0, 0.0, 0.0], &[0.0, -1.0, 0.0, -0.0, 0.0, -1.0, -0.0, 0.0, 1.0, -0.0, -1.0, -0.0, -0.0, -0.0, -1.0, 0.0, 1.0, -0.0, 0.0, 1.0, -0.0, 0.0, 0.0, 1.0, 0.0]),
        ("sym_ng11", &[0.0, 0.0, 0.0, 1.5, 1.5], &[0.0, 1.0, 0.0, 0.75, 0.0, 1.0, 0.75, -1.0, 0.0, 0.75, 0.0, -1.0, 0.75, -0.0, 1.0, 0.75, -1.0, -0.0, 0.75, -0.0, -1.0, 0.75, 1.0, -0.0, 0.75, -1.0, 0.0, -0.75, 0.0, 1.0, -0.75, -0.0, -1.0, -0.75, -1.0, -0.0, -0.75, -0.0, 1.0, -0.75, 1.0, -0.0, -0.75, 1.0, 0.0, -0.75, 0.0, -1.0, -0.75]),
        ("sym_ng12", &[0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0, -0.0, 0.0, -1.0, -0.0, -0.0, 1.0, 0.0, -1.0, -0.0, -0.0, -0.0, -1.0, -0.0, 1.0, -0.0, 0.0, -1.0, 0.0, -0.0, 0.0, 1.0, 0.0, -0.0, -1.0, -0.0, -1.0, -0.0, -0.0, -0.0, 1.0, 0.0, 1.0, -0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0, -0.0]),
        ("sym_ng13", &[0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, -0.0, 0.0, -1.0, -0.0, -0.5, -0.866, -0.0, -0.866, 0.5, -0.0, -0.5, 0.866, -0.0, 0.866, 0.5, -0.0, 1.0, 0.0, 0.0, 0.0, -1.0, 0.0, -0.5, -0.866, 0.0, -0.866, 0.5, 0.0, -0.5, 0.866, 0.0, 0.866, 0.5, 0.0]),
        ("sym_ng14", &[0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, -0.0, 0.0, 1.0, -0.0, 1.0, 0.0, -0.0, 0.0, -1.0, -0.0, -0.5, -0.866, -0.0, 0.866, -0.5, -0.0, -0.5, 0.866, -0.0, -0.866, -0.5, -0.0, -0.5, -0.866, -0.0, -0.866, 0.5, -0.0, -0.5, 0.866, -0.0, 0.866, 0.5, -0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0, 0.0, -0.5, -0.866, 0.0, 0.866, -0.5, 0.0, -0.5, 0.866, 0.0, -0.866, -0.5, 0.0, -0.5, -0.866, 0.0, -0.866, 0.5, 0.0, -0.5, 0.866, 0.0, 0.866, 0.5, 0.0]),
        ("sym_ng15", &[0.0, 0.0, 0.0], &[0.0, 0.0, 1.0, -0.0, -1.0, 0.0, -0.0, 0.0, -1.0, -0.0, -1.0, 0.0, -0.0, 0.866, -0.5, -0.0, 0.5, 0.866, -0.0, 0.866, 0.5, -0.0, 0.5, -0.866, -0.0, -0.866, -0.5, -0.0, 0.5, -0.866, -0.0, -0.866, 0.5, -0.0, 0.5, 0.866, -0.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 0.0, -1.0, 0.0, 0.0, 0.866, -0.5, 0.0, 0.5, 0.866, 0.0, 0.866, 0.5, 0.0, 0.5, -0.866, 0.0, -0.866, -0.5, 0.0, 0.5, -0.866, 0.0, -0.866, 0.5, 0.0, 0.5, 0.866, 0.0]),
        ("sym_ng16", &[0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, -0.0, 0.0, 1.0, -0.0, 0.5, -0.866, -0.0, 0.866, 0.5, -0.0, -0.5, -0.866, -0.0, 0.866, -0.5, -0.0, -1.0, 0.0, -0.0, 0.0, -1.0, -0.0, -0.5, 0.866, -0.0, -0.866, -0.5, -0.0, 0.5, 0.866, -0.0, -0.866, 0.5, -0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.5, -0.866, 0.0, 0.866, 0.5, 0.0, -0.5, -0.866, 0.0, 0.866, -0.5, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 0.0, -0.5, 0.866, 0.0, -0.866, -0.5, 0.0, 0.5, 0.866, 0.0, -0.866, 0.5, 0.0]),
        ("sym_ng17", &[0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, -0.0, 0.0, 1.0, -0.0, 1.0, 0.0, -0.0, 0.0, -1.0, -0.0, 0.5, -0.866, -0.0, 0.866, 0.5, -0.0, 0.5, 0.866, -0.0, 0.866, -0.5, -0.0, -0.5, -0.866, -0.0, 0.866, -0.5, -0.0, -0.5, 0.866, -0.0, 0.866, 0.5, -0.0, -1.0, 0.0, -0.0, 0.0, -1.0, -0.0, -1.0, 0.0, -0.0, 0.0, 1.0, -0.0, -0.5, 0.866, -0.0, -0.866, -0.5, -0.0, -0.5, -0.866, -0.0, -0.866, 0.5, -0.0, 0.5, 0.866, -0.0, -0.866, 0.5, -0.0, 0.5, -0.866, -0.0, -0.866, -0.5, -0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.5, -0.866, 0.0, 0.866, 0.5, 0.0, 0.5, 0.866, 0.0, 0.866, -0.5, 0.0, -0.5, -0.866, 0.0, 0.866, -0.5, 0.0, -0.5, 0.866, 0.0, 0.866, 0.5, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0, 0.0, -0.5, 0.866, 0.0, -0.866, -0.5, 0.0, -0.5, -0.866, 0.0, -0.866, 0.5, 0.0, 0.5, 0.866, 0.0, -0.866, 0.5, 0.0, 0.5, -0.866, 0.0, -0.866, -0.5, 0.0]),
        ("sym_bg1", &[0.0, 0.0], &[0.0, 1.0, 0.0, -1.0, 0.0, 1.0, -0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]),
        ("sym_bg2", &[0.0, 0.0], &[0.0, 1.0, 0.0, -1.0, 0.0, 1.0, -0.0, 1.0, 0.0, 0.0, 0.0, -1.0, 1.0]),
        ("sym_bg3", &[0.0, 0.0], &[0.0, 1.0, 0.0, -1.0, 0.0, 1.0, -0.5, -1.0, 0.0, 1.0, 0.0, -1.0, 0.5]),
        ("sym_bg4", &[0.0, 0.0], &[0.0, 1.0, 0.0, -1.0, 0.0, 1.0, -0.5, -1.0, 0.0, 1.0, 0.0, 1.0, 0.5]),
        ("sym_bg5", &[0.0, 0.0], &[0.0, 1.0, 0.0, -1.0, 0.0, 1.0, -0.5, 1.0, 0.0, -1.0, 0.0, -1.0, 0.5]),
        ("sym_bg6", &[0.0, 0.0], &[0.0, 1.0, 0.0, -1.0, 0.0, 1.0, -0.5, -1.0, 0.0, 1.0, 0.0, 1.0, -0.5, 1.0, 0.0, -1.0, 0.0, -1.0, 0.5, -1.0, 0.0, 1.0, 0.0, -1.0, 0.5]),
        ("sym_bg7", &[0.0, 0.0], &[0.0, 1.0, 0.0, -2.0, 0.0, 1.0, -0.5, -1.0, 0.0, 2.0, 0.0, 1.0, -0.5, 1.0, 0.0, 0.0, 0.0, -1.0, 0.5, -1.0, 0.0, -0.0, 0.0, -1.0, 0.5]),
        ("sym_ng1", &[0.3, -0.7], &[0.0, 1.0, 0.0, -0.15, 0.0, 1.0, 0.35, 1.0, 0.0, 0.15, 0.0, 1.0, -0.35]),
        ("sym_ng2", &[0.3, -0.7], &[0.0, 1.0, 0.0, -0.15, 0.0, 1.0, 0.35, 1.0, 0.0, 0.15, 0.0, -1.0, -0.35]),
        ("sym_ng3", &[0.3, -0.7, 1.1], &[0.0, 1.0, 0.0, -0.8500000000000001, 0.0, 1.0, 0.1499999999999999, -1.0, 0.0, 0.8500000000000001, 0.0, -1.0, -0.1499999999999999]),
        ("sym_ng4", &[0.3, -0.7, 1.1, 0.45], &[0.0, 1.0, 0.0, -2.7, 0.0, 1.0, -2.075, -1.0, 0.0, -0.4, 0.0, -1.0, -0.375, 1.0, 0.0, 0.4, 0.0, -1.0, 1.075, -1.0, 0.0, 2.7, 0.0, 1.0, -0.625]),
        ("sym_ng5", &[0.3, -0.7, 1.1], &[0.0, 1.0, 0.0, -2.8499999999999996, 0.0, 1.0, -1.2, -1.0, 0.0, -0.25000000000000006, 0.0, -1.0, 0.19999999999999996, 1.0, 0.0, 0.25000000000000006, 0.0, -1.0, 0.19999999999999996, -1.0, 0.0, 2.8499999999999996, 0.0, 1.0, -1.2]),
        ("sym_ng6", &[0.3, -0.7, 1.1], &[0.0, 1.0, 0.0, 0.35, 0.0, 1.0, -0.4, 1.0, 0.0, 0.35, 0.0, -1.0, -0.7000000000000001, 1.0, 0.0, -0.35, 0.0, 1.0, 0.7000000000000001, 1.0, 0.0, -0.35, 0.0, -1.0, 0.4]),
        ("sym_ng7", &[0.3, -0.7], &[0.0, 1.0, 0.0, -0.15, 0.0, 1.0, -0.35, 1.0, 0.0, 0.15, 0.0, -1.0, 0.35]),
        ("sym_ng8", &[0.3, -0.7, 1.1, 0.45], &[0.0, 1.0, 0.0, -1.7, 0.0, -1.0, 0.12499999999999997, -1.0, 0.0, 0.5999999999999999, 0.0, 1.0, -0.575, -1.0, 0.0, 0.5999999999999999, 0.0, -1.0, 0.12499999999999997, 1.0, 0.0, -1.7, 0.0, 1.0, -0.575, 1.0, 0.0, -0.5999999999999999, 0.0, -1.0, 0.575, -1.0, 0.0, 1.7, 0.0, 1.0, -0.12499999999999997, -1.0, 0.0, 1.7, 0.0, -1.0, 0.575, 1.0, 0.0, -0.5999999999999999, 0.0, 1.0, -0.12499999999999997]),
        ("sym_ng9", &[0.3, -0.7], &[0.0, 1.0, 0.0, 0.15, 0.0, -1.0, 0.35, -1.0, 0.0, -0.15, 0.0, 1.0, -0.35, -1.0, 0.0, -0.15, 0.0, -1.0, 0.35, 1.0, 0.0, 0.15, 0.0, 1.0, -0.35]),
        ("sym_ng10", &[0.3, -0.7, 1.1], &[0.3, -1.0, 0.0, 0.35, 0.0, -1.0, -0.55, 0.0, 1.0, 0.35, -1.0, -0.0, -0.55, -0.0, -1.0, -0.35, 1.0, -0.0, 0.55, 1.0, -0.0, -0.35, 0.0, 1.0, 0.55]),
        ("sym_ng11", &[0.3, -0.7, 1.1, 0.45, 0.2], &[0.3, 1.0, 0.0, -0.475, 0.0, 1.0, 1.2000000000000002, -1.0, 0.0, 0.9249999999999999, 0.0, -1.0, -1.0, -0.0, 1.0, -0.475, -1.0, -0.0, -1.0, -0.0, -1.0, 0.9249999999999999, 1.0, -0.0, 1.2000000000000002, -1.0, 0.0, 0.475, 0.0, 1.0, 1.0, -0.0, -1.0, 0.475, -1.0, -0.0, -1.2000000000000002, -0.0, 1.0, -0.9249999999999999, 1.0, -0.0, 1.0, 1.0, 0.0, -0.9249999999999999, 0.0, -1.0, -1.2000000000000002]),
        ("sym_ng12", &[0.3, -0.7, 1.1], &[0.3, 1.0, 0.0, -0.7, 0.0, 1.0, 1.1, -1.0, 0.0, 0.7, 0.0, -1.0, -1.1, -0.0, 1.0, -0.7, -1.0, -0.0, -1.1, -0.0, -1.0, 0.7, 1.0, -0.0, 1.1, -1.0, 0.0, 0.7, 0.0, 1.0, 1.1, -0.0, -1.0, 0.7, -1.0, -0.0, -1.1, -0.0, 1.0, -0.7, 1.0, -0.0, 1.1, 1.0, 0.0, -0.7, 0.0, -1.0, -1.1]),
        ("sym_ng13", &[0.3, -0.7, 1.1], &[0.21213203435596426, 1.0, 0.0, 0.35, 0.0, -1.0, -0.55, -0.5, -0.866, 0.35, -0.866, 0.5, -0.55, -0.5, 0.866, 0.35, 0.866, 0.5, -0.55, 1.0, 0.0, -0.35, 0.0, -1.0, 0.55, -0.5, -0.866, -0.35, -0.866, 0.5, 0.55, -0.5, 0.866, -0.35, 0.866, 0.5, 0.55]),
        ("sym_ng14", &[0.3, -0.7, 1.1], &[0.21213203435596426, 1.0, 0.0, 0.35, 0.0, 1.0, -0.55, 1.0, 0.0, 0.35, 0.0, -1.0, -0.55, -0.5, -0.866, 0.35, 0.866, -0.5, -0.55, -0.5, 0.866, 0.35, -0.866, -0.5, -0.55, -0.5, -0.866, 0.35, -0.866, 0.5, -0.55, -0.5, 0.866, 0.35, 0.866, 0.5, -0.55, 1.0, 0.0, -0.35, 0.0, 1.0, 0.55, 1.0, 0.0, -0.35, 0.0, -1.0, 0.55, -0.5, -0.866, -0.35, 0.866, -0.5, 0.55, -0.5, 0.866, -0.35, -0.866, -0.5, 0.55, -0.5, -0.866, -0.35, -0.866, 0.5, 0.55, -0.5, 0.866, -0.35, 0.866, 0.5, 0.55]),
        ("sym_ng15", &[0.3, -0.7, 1.1], &[0.21213203435596426, 0.0, 1.0, 0.35, -1.0, 0.0, -0.55, 0.0, -1.0, 0.35, -1.0, 0.0, -0.55, 0.866, -0.5, 0.35, 0.5, 0.866, -0.55, 0.866, 0.5, 0.35, 0.5, -0.866, -0.55, -0.866, -0.5, 0.35, 0.5, -0.866, -0.55, -0.866, 0.5, 0.35, 0.5, 0.866, -0.55, 0.0, 1.0, -0.35, -1.0, 0.0, 0.55, 0.0, -1.0, -0.35, -1.0, 0.0, 0.55, 0.866, -0.5, -0.35, 0.5, 0.866, 0.55, 0.866, 0.5, -0.35, 0.5, -0.866, 0.55, -0.866, -0.5, -0.35, 0.5, -0.866, 0.55, -0.866, 0.5, -0.35, 0.5, 0.866, 0.55]),
        ("sym_ng16", &[0.3, -0.7, 1.1], &[0.21213203435596426, 1.0, 0.0, 0.35, 0.0, 1.0, -0.55, 0.5, -0.866, 0.35, 0.866, 0.5, -0.55, -0.5, -0.866, 0.35, 0.866, -0.5, -0.55, -1.0, 0.0, 0.35, 0.0, -1.0, -0.55, -0.5, 0.866, 0.35, -0.866, -0.5, -0.55, 0.5, 0.866, 0.35, -0.866, 0.5, -0.55, 1.0, 0.0, -0.35, 0.0, 1.0, 0.55, 0.5, -0.866, -0.35, 0.866, 0.5, 0.55, -0.5, -0.866, -0.35, 0.866, -0.5, 0.55, -1.0, 0.0, -0.35, 0.0, -1.0, 0.55, -0.5, 0.866, -0.35, -0.866, -0.5, 0.55, 0.5, 0.866, -0.35, -0.866, 0.5, 0.55]),
        ("sym_ng17", &[0.3, -0.7, 1.1], &[0.21213203435596426, 1.0, 0.0, 0.35, 0.0, 1.0, -0.55, 1.0, 0.0, 0.35, 0.0, -1.0, -0.55, 0.5, -0.866, 0.35, 0.866, 0.5, -0.55, 0.5, 0.866, 0.35, 0.866, -0.5, -0.55, -0.5, -0.866, 0.35, 0.866, -0.5, -0.55, -0.5, 0.866, 0.35, 0.866, 0.5, -0.55, -1.0, 0.0, 0.35, 0.0, -1.0, -0.55, -1.0, 0.0, 0.35, 0.0, 1.0, -0.55, -0.5, 0.866, 0.35, -0.866, -0.5, -0.55, -0.5, -0.866, 0.35, -0.866, 0.5, -0.55, 0.5, 0.866, 0.35, -0.866, 0.5, -0.55, 0.5, -0.866, 0.35, -0.866, -0.5, -0.55, 1.0, 0.0, -0.35, 0.0, 1.0, 0.55, 1.0, 0.0, -0.35, 0.0, -1.0, 0.55, 0.5, -0.866, -0.35, 0.866, 0.5, 0.55, 0.5, 0.866, -0.35, 0.866, -0.5, 0.55, -0.5, -0.866, -0.35, 0.866, -0.5, 0.55, -0.5, 0.866, -0.35, 0.866, 0.5, 0.55, -1.0, 0.0, -0.35, 0.0, -1.0, 0.55, -1.0, 0.0, -0.35, 0.0, 1.0, 0.55, -0.5, 0.866, -0.35, -0.866, -0.5, 0.55, -0.5, -0.866, -0.35, -0.866, 0.5, 0.55, 0.5, 0.866, -0.35, -0.866, 0.5, 0.55, 0.5, -0.866, -0.35, -0.866, -0.5, 0.55]),
        ("sym_bg1", &[0.3, -0.7], &[0.0, 1.0, 0.0, -1.15, 0.0, 1.0, 0.35, 1.0, 0.0, 0.15, 0.0, 1.0, -0.35]),
        ("sym_bg2", &[0.3, -0.7], &[0.0, 1.0, 0.0, -1.15, 0.0, 1.0, 0.35, 1.0, 0.0, 0.15, 0.0, -1.0, 0.65]),
        ("sym_bg3", &[0.3, -0.7], &[0.0, 1.0, 0.0, -1.15, 0.0, 1.0, -0.15000000000000002, -1.0, 0.0, 1.15, 0.0, -1.0, 0.15000000000000002]),
        ("sym_bg4", &[0.3, -0.7], &[0.0, 1.0, 0.0, -1.15, 0.0, 1.0, -0.15000000000000002, -1.0, 0.0, 1.15, 0.0, 1.0, 0.15000000000000002]),
        ("sym_bg5", &[0.3, -0.7], &[0.0, 1.0, 0.0, -1.15, 0.0, 1.0, -0.15000000000000002, 1.0, 0.0, -0.85, 0.0, -1.0, 0.15000000000000002]),
        ("sym_bg6", &[0.3, -0.7], &[0.0, 1.0, 0.0, -1.15, 0.0, 1.0, -0.15000000000000002, -1.0, 0.0, 1.15, 0.0, 1.0, -0.85, 1.0, 0.0, -1.15, 0.0, -1.0, 0.85, -1.0, 0.0, 1.15, 0.0, -1.0, 0.15000000000000002]),
        ("sym_bg7", &[0.3, -0.7], &[0.0, 1.0, 0.0, -2.15, 0.0, 1.0, -0.15000000000000002, -1.0, 0.0, 2.15, 0.0, 1.0, -0.85, 1.0, 0.0, 0.15, 0.0, -1.0, 0.15000000000000002, -1.0, 0.0, -0.15, 0.0, -1.0, 0.85]),
    ];

    /// (name, parameters, segments as x1 y1 x2 y2, then 12 samples x y drawn from segment
    /// k for call k with the MWC generator seeded 777).
    type LineCase = (&'static str, &'static [f64], &'static [f64], &'static [f64]);

    #[rustfmt::skip]
    const LINE_CASES: &[LineCase] = &[
        ("hilbert_js", &[3.0, 1.0, 2.0, 1.0, 5.0], &[0.0, 0.0, 6.123233995736766e-17, 1.0, 6.123233995736766e-17, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 0.0, 2.0, 0.0, 2.0, 0.0, 3.0, 0.0, 3.0, 0.0, 3.0, 1.0, 3.0, 1.0, 2.0, 1.0000000000000002, 2.0, 1.0000000000000002, 2.0, 2.0, 2.0, 2.0, 3.0, 2.0, 3.0, 2.0, 3.0, 3.0, 3.0, 3.0, 2.0, 3.0, 2.0, 3.0, 1.0, 3.0, 1.0, 3.0, 0.9999999999999998, 2.0, 0.9999999999999998, 2.0, -2.220446049250313e-16, 2.0, -2.220446049250313e-16, 2.0, -1.6081226496766364e-16, 3.0, -1.6081226496766364e-16, 3.0, -9.957992501029598e-17, 4.0, -9.957992501029598e-17, 4.0, 0.9999999999999999, 4.0, 0.9999999999999999, 4.0, 1.0, 5.0, 1.0, 5.0, 0.0, 5.0, 0.0, 5.0, 6.123233995736766e-17, 6.0, 6.123233995736766e-17, 6.0, 1.2246467991473532e-16, 7.0, 1.2246467991473532e-16, 7.0, 1.0000000000000002, 7.0, 1.0000000000000002, 7.0, 1.0000000000000002, 6.0, 1.0000000000000002, 6.0, 2.0, 6.0, 2.0, 6.0, 2.0, 7.0, 2.0, 7.0, 3.0, 7.0, 3.0, 7.0, 3.0, 6.0, 3.0, 6.0, 3.0, 5.0, 3.0, 5.0, 2.0, 5.0, 2.0, 5.0, 2.0, 4.0, 2.0, 4.0, 3.0, 4.0, 3.0, 4.0, 4.0, 4.0, 4.0, 4.0, 5.0, 4.0, 5.0, 4.0, 5.0, 5.0, 5.0, 5.0, 4.0, 5.0, 4.0, 5.0, 4.0, 6.0, 4.0, 6.0, 4.0, 7.0, 4.0, 7.0, 5.0, 7.0, 5.0, 7.0, 5.0, 6.0, 5.0, 6.0, 6.0, 6.0, 6.0, 6.0, 6.0, 7.0, 6.0, 7.0, 7.0, 7.0, 7.0, 7.0, 7.0, 6.0, 7.0, 6.0, 7.0, 5.0, 7.0, 5.0, 6.0, 5.0, 6.0, 5.0, 6.0, 4.0, 6.0, 4.0, 7.0, 4.0, 7.0, 4.0, 7.0, 3.0, 7.0, 3.0, 7.0, 2.0, 7.0, 2.0, 6.0, 1.9999999999999998, 6.0, 1.9999999999999998, 6.0, 3.0, 6.0, 3.0, 5.0, 3.0, 5.0, 3.0, 4.0, 3.0, 4.0, 3.0, 4.0, 2.0, 4.0, 2.0, 5.0, 2.0, 5.0, 2.0, 5.0, 1.0, 5.0, 1.0, 4.0, 0.9999999999999999, 4.0, 0.9999999999999999, 4.0, -1.1102230246251565e-16, 4.0, -1.1102230246251565e-16, 5.0, -1.1102230246251565e-16, 5.0, -1.1102230246251565e-16, 6.0, -1.1102230246251565e-16, 6.0, -1.1102230246251565e-16, 6.0, 0.9999999999999999, 6.0, 0.9999999999999999, 7.0, 0.9999999999999999, 7.0, 0.9999999999999999, 7.0, -1.1102230246251565e-16], &[0.011530776175592146, -0.009871055462842712, 0.21995073109397237, 1.0026438161417115, 0.9920529216923506, 0.16292841826060778, 1.985204156411441, 0.008086519650223906, 2.041085879028518, -0.006958978813044104, 3.0025882417444834, 0.01585510150900865, 2.995838159246842, 0.9785167887467056, 2.0042860616129574, 1.7814113115150207, 2.2160033960295857, 1.9935778807213427, 2.996666557135689, 2.117553297262828, 2.7655999313926323, 3.0076949272387172, 1.6817938822190248, 2.9994042585927083]),
        ("rsquares_js", &[2.0, 2.0, 0.0, 1.0, 0.0], &[0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, -0.22727272727272727, -0.22727272727272727, -0.22727272727272727, 0.22727272727272727, -0.22727272727272727, 0.22727272727272727, 0.22727272727272727, 0.22727272727272727, 0.22727272727272727, 0.22727272727272727, 0.22727272727272727, -0.22727272727272727, 0.22727272727272727, -0.22727272727272727, -0.22727272727272727, -0.22727272727272727, -0.22727272727272727, 0.7727272727272727, -0.22727272727272727, 1.2272727272727273, -0.22727272727272727, 1.2272727272727273, 0.22727272727272727, 1.2272727272727273, 0.22727272727272727, 1.2272727272727273, 0.22727272727272727, 0.7727272727272727, 0.22727272727272727, 0.7727272727272727, -0.22727272727272727, 0.7727272727272727, 0.7727272727272727, -0.22727272727272727, 0.7727272727272727, 0.22727272727272727, 0.7727272727272727, 0.22727272727272727, 1.2272727272727273, 0.22727272727272727, 1.2272727272727273, 0.22727272727272727, 1.2272727272727273, -0.22727272727272727, 1.2272727272727273, -0.22727272727272727, 0.7727272727272727, -0.22727272727272727, 0.7727272727272727, 0.7727272727272727, 0.7727272727272727, 1.2272727272727273, 0.7727272727272727, 1.2272727272727273, 1.2272727272727273, 1.2272727272727273, 1.2272727272727273, 1.2272727272727273, 1.2272727272727273, 0.7727272727272727, 1.2272727272727273, 0.7727272727272727, 0.7727272727272727, 0.7727272727272727], &[3.0357637118732084e-5, 0.30357637118732084, 0.0, 1.0, 1.000022252443425, 0.7774755657495993, 0.36780919291442693, 0.0, -0.22723438967040935, 0.15610329590636138, 0.14444702851369792, 0.22727272727272727, 0.2273174617679624, -0.22007222507843946, -0.1837845375050888, -0.22727272727272727, -0.2272348444954601, 1.1515550453987629, -0.22727272727272727, 1.2272727272727273, 0.22727272727272727, 1.2272727272727273, 0.12534265528681812, 0.7727272727272727]),
        ("tree_js", &[2.0, 1.0, 1.0, 16.0, 67.0, 0.57, 0.0, 3.0], &[0.0, 0.0, 1.2246467991473532e-16, 2.0, 1.2246467991473532e-16, 2.0, 0.8859463960609469, 2.7174252457968144, 0.8859463960609469, 2.7174252457968144, 1.5215467070177737, 2.5823242291034343, 0.8859463960609469, 2.7174252457968144, 0.5416048581622105, 3.26848689867926, 0.8859463960609469, 2.7174252457968144, 1.1671135651602298, 3.118973577907278, 1.2246467991473532e-16, 2.0, -1.1315026128711068, 2.138931051481868, -1.1315026128711068, 2.138931051481868, -1.4758441507698432, 2.6899927043643137, -1.1315026128711068, 2.138931051481868, -1.2887034606317709, 1.5084328885477256, -1.1315026128711068, 2.138931051481868, -1.6156674374308433, 2.062246876719147, 1.2246467991473532e-16, 2.0, -0.2370481260026191, 2.8266850585069543, -0.2370481260026191, 2.8266850585069543, 0.04411904309666381, 3.228233390617418, -0.2370481260026191, 2.8266850585069543, -0.7212129505623557, 2.7500008837442333, -0.2370481260026191, 2.8266850585069543, -0.43301226991605823, 3.140293244465601], &[0.003873178762790402, 0.603193372589626, 0.3302869050167318, 2.263736600318391, 0.9516857008746434, 2.702422687600937, 0.6998226285333906, 3.0221436986870045, 1.1620538814138544, 3.106463762976397, -0.825385236659946, 2.10346345990789, -1.398481599181896, 2.5695384300799704, -1.1713695529211212, 1.993859394776805, -1.1858029976972366, 2.135022711822966, -0.056019438116900605, 2.1961909672776168, -0.14171448119593943, 2.957176906110449, -0.6255665442167895, 2.768628145240365]),
    ];

    /// ([max_iter, seed, glue, force x y z], nodes as x y z relative-depth parent-index).
    #[rustfmt::skip]
    const DLA_GROW: &[(&[f64], &[f64])] = &[
        (&[60.0, 42.0, 1.0, 0.0, 0.0, 0.0], &[0.0, 0.0, 0.0, 0.0, -1.0, 0.3803129976587324, 0.012385436364297009, 0.061350408515125965, 0.1, 0.0, 1.1710664653791203, -0.05287987627553847, 0.6671436571638271, 0.2, 1.0, -0.021927152742927447, 0.1423129903506627, 0.6329659386535214, 0.14285714285714285, 0.0, 1.3425390938834667, 0.38728203494594104, 0.8547318898153712, 0.3, 2.0, 1.9362753730960076, 0.17761577559367214, 0.6585613413327343, 0.5714285714285714, 4.0, 0.6565271497398397, -0.344327630787299, 0.8496454194691315, 0.5, 2.0, 0.6829864308315757, -0.8204362652654741, 0.9799609083601964, 0.6666666666666666, 6.0, 1.220399302088072, -0.2484803722506802, -0.02926419535909175, 0.6, 2.0, 2.522309223787544, 0.020478162814615564, 0.4618385256712434, 0.7142857142857143, 5.0, -0.5042767037820058, 0.5301582728951625, 0.8789927432102339, 0.2857142857142857, 3.0, 1.6320014387697324, 0.6954261522461745, 0.5692136300580454, 0.6666666666666666, 4.0, 1.0584835273813589, 0.48465926509279317, 1.6708289826213978, 0.4, 4.0, 0.45794835270435974, -0.889130859365519, 0.16852934227651128, 0.8333333333333334, 7.0, -1.3446415719088618, 0.02543993590608995, 1.006682122943341, 0.42857142857142855, 10.0, 1.4467625657516345, 1.3507049276065843, 0.655159022412793, 0.8333333333333334, 11.0, 0.3641736530934143, 0.24794702304675298, 2.0674736433799796, 0.5, 12.0, 0.5574035323751283, 1.5590621519893098, 0.7017247067433682, 1.0, 15.0, 0.6153533754328969, 1.237890514759211, 2.0167053713700835, 0.625, 12.0, -1.0488179059570686, -0.429066672630931, 0.6879372921384905, 1.0, 14.0, -0.09134809495122709, 0.5398541213860274, -0.694462807741025, 0.16666666666666666, 0.0, -0.23839456756162603, -0.06965853940094446, -1.189701610202201, 0.3333333333333333, 20.0, -0.49723726073358054, -0.21316741509943804, -1.9975715536561047, 0.5, 21.0, -1.4484051606551458, 0.2972750177756355, 0.08968391676524434, 0.5714285714285714, 14.0, -0.1958872016713169, 0.09617680447636773, -1.6332927490755655, 0.6, 21.0, -0.9150698249957584, 1.1576753822511718, 1.213051339254593, 0.75, 10.0, 0.930543695999625, -0.5597198213430186, -0.8236049565265108, 1.0, 8.0, -0.9628595723004093, -1.0070810795215737, -2.0974292846668967, 0.6666666666666666, 22.0, -1.167721158208332, 0.4152775470101264, 1.1590319262212843, 1.0, 14.0, -0.6448956966437541, 0.7962643444797827, -1.1873333774761257, 0.4, 20.0, 0.4413010586710814, -1.275473634673876, 0.22894114214435912, 1.0, 13.0, -2.1038830994101665, 0.5252639443742239, 0.6944587147001021, 0.7142857142857143, 23.0, 0.8444055165789109, 0.6662188417641417, 2.800559190313525, 0.6, 16.0, 3.0258001602645495, 0.29156667397578573, 0.03286593168224061, 0.8571428571428571, 9.0, -2.9286989269109944, 0.6729343297169922, 0.7827654064820025, 0.8571428571428571, 31.0, -0.2706862289719708, 1.39444591500679, -1.7343158289626033, 0.6, 29.0, 0.1885733396998111, -0.23972739391988618, -1.982412403055685, 0.8, 24.0, -0.21564267049917163, 0.26015387624627384, 2.608326792966196, 1.0, 16.0, 0.2752466755229125, 1.671904254681198, 1.6241402299351444, 0.75, 18.0, 0.9326933746751328, -0.019608713448100955, 3.105058186217364, 0.7, 32.0, 3.9498152229480428, 0.4364017939701334, -0.0976931300964794, 1.0, 33.0, -1.116312516879964, 0.8015059991744312, 1.8905274895254238, 1.0, 25.0, -0.9294281648011146, 2.108005292775617, -1.5916704134496933, 0.8, 35.0, 1.6004593268426535, -0.4445787659084529, -0.5285213946445294, 0.8, 8.0, -0.5308469691484801, 1.850510209139348, 2.042042054821304, 0.875, 38.0, 0.6712650016315779, 0.16936401615651364, -2.1648489125606325, 1.0, 36.0, -0.27902918524364795, 2.351392191971209, -1.9211049801587903, 1.0, 42.0, 0.9125031154137572, -0.25204117527069936, 3.9670328568028794, 0.8, 39.0, -1.0604348016660583, 2.083324743134809, 2.6651029234749197, 1.0, 44.0, 1.771812915567876, -0.4713387991487549, -1.4124867329490307, 1.0, 43.0, 2.9682850182192246, 0.9732088829496369, -0.04984009469166539, 1.0, 33.0, 0.7682640584796818, -0.3086692008389401, 3.9615192286592698, 0.9, 47.0, -3.4078688261677446, 0.9425837590763319, -0.011703411112426343, 1.0, 34.0, -1.6140746572246396, 2.0796668987873153, -2.0868630705861952, 1.0, 42.0, -1.434323251827244, 1.9890023873781435, -1.331263299563905, 1.0, 42.0, 1.7718798545370975, -0.27605112734629794, 2.763027973248593, 1.0, 39.0, -1.6633454786857826, -1.129064649398395, -2.6485252165709223, 1.0, 27.0, 0.03530708355007017, -0.47257194741662134, 3.665681523026788, 1.0, 51.0, -0.6277557070820874, -1.7936950857923373, -1.82340746384431, 0.8333333333333334, 27.0, -0.60040360434002, -2.443055737836567, -2.5368169386792117, 1.0, 58.0]),
        (&[45.0, 7.0, 1.3, 0.05, -0.02, 0.01], &[0.0, 0.0, 0.0, 0.0, -1.0, -0.516549078603333, 0.1701877111602265, -1.0624567433660388, 0.125, 0.0, -0.83412271647104, 0.07104924087471944, 0.5839147489908272, 0.16666666666666666, 0.0, -0.800974356441109, -0.6170930349683614, -1.3025766941610402, 0.3333333333333333, 1.0, -1.7154571877280507, -1.2639627100148088, -1.2017776646143858, 1.0, 3.0, 0.3993973516681882, 0.38456812577290067, 0.1439473549118766, 0.16666666666666666, 0.0, -1.6283626875246648, -0.7644110454183294, 0.9489762873876931, 0.3333333333333333, 2.0, 0.37965685246611464, 1.4291337480965853, 0.34037227506146184, 0.3333333333333333, 5.0, -0.25991287712168504, 0.15050446782661833, -1.815333441478445, 0.25, 1.0, 0.9294550266601299, 0.04582720819235865, -1.7738947738932638, 0.375, 8.0, -1.4738594654609416, -0.3765917455078265, -1.9549096645660782, 1.0, 3.0, -1.4984156240484963, -1.9838402951764937, 0.9233530809050617, 0.5, 6.0, 1.3545113630659984, 1.9662425127034768, 0.9263670742893929, 0.5, 7.0, -2.4549161333508676, -2.5725915437315314, 0.4922681868663231, 0.6666666666666666, 11.0, -0.45344480192310277, -1.2547856377543192, -2.317365175458808, 0.5, 3.0, 2.127912270235841, 2.028371527409329, 0.3177328485344364, 0.6666666666666666, 12.0, 1.791331857523373, -0.6578099309485302, -2.3313496864821097, 0.5, 9.0, 1.6449223278617884, 1.7314466333877014, 1.9143206560378345, 0.6666666666666666, 12.0, 1.0930248954351016, 1.6563583502795296, 3.003903850816306, 0.8333333333333334, 17.0, 0.4088581180683583, 1.3863066863014817, 1.266322559789575, 1.0, 7.0, 1.5673918661613866, -1.702525498627573, -1.9584456945139432, 0.625, 16.0, 1.5307203961774192, -1.6194064660700187, -2.9031715022752977, 0.8571428571428571, 20.0, 2.042866304367334, -0.06221957146213079, -2.240857040337358, 1.0, 16.0, 3.046952734548335, 2.057585298911026, -0.08183646322531991, 0.8333333333333334, 15.0, -0.02000709877489386, -1.0380763591849027, -2.6707045665479234, 1.0, 14.0, -1.139740891627891, -1.1265319077578426, -3.155190531630292, 0.6666666666666666, 14.0, 1.607902924473318, -2.5021528243850657, -1.593692873310064, 0.75, 20.0, -0.4619922375073972, -1.9082591694625202, -3.5120054701033343, 0.8333333333333334, 25.0, -3.24818103133472, -2.246859981216719, 0.006448126458192807, 0.8333333333333334, 13.0, 1.9384701452455613, -3.0510196262165294, -1.96780636983032, 0.875, 26.0, -1.7142803669701088, -0.3919927696825277, 1.696456640541517, 0.75, 6.0, -0.8342275207918456, -1.9459692139456437, -4.10740055057578, 1.0, 27.0, 2.2490663316704187, -3.119216657035492, -1.4211778000377482, 1.0, 29.0, 0.4245474195021049, 0.5963052325523809, -2.1073439305698813, 1.0, 9.0, -4.467871212252053, -2.033099841707119, 0.3906489396656682, 1.0, 28.0, 3.2449669603284566, 3.231044196950224, 0.20773717394085256, 1.0, 23.0, -2.1731255794799793, -0.4960124564448154, 0.9555253538244458, 0.75, 6.0, -2.591515535518317, -0.4642703419994698, -0.15841684018701574, 1.0, 36.0, -1.5473125334205198, -0.45391033771206646, -3.9068406920675947, 0.8333333333333334, 25.0, 1.4159973092608842, -0.05449650389670578, -3.1567323039899784, 1.0, 16.0, 1.8608508873874585, -2.176178171914095, -3.1486564496098155, 1.0, 21.0, -1.0336269770366702, 0.021335622944917216, -4.589387195463683, 1.0, 38.0, 1.0331579794758767, 0.4582138273967331, 2.953010922803574, 1.0, 18.0, -2.5835410240915935, -3.7842866968839544, 0.9134590936045482, 1.0, 13.0, -1.6686407186889098, 0.18481167574165505, 2.321562143486096, 1.0, 30.0]),
    ];

    /// ([max_iter, seed, glue, inner, outer, junction scale, nodes, junctions], successive
    /// samples x y z colour drawn with the MWC generator seeded like the aggregate).
    #[rustfmt::skip]
    const DLA_SAMPLES: &[(&[f64], &[f64])] = &[
        (&[60.0, 42.0, 1.0, 0.5, 0.01, 1.4, 1.0, 1.0], &[0.035899565149988905, -0.06754859062319014, -1.6234883757746918, 0.6735563009388541, -0.4679792303541239, 0.33998800850261657, -0.6475048100110128, 0.21753459904228084, 0.39232767454711104, 1.734731089715422, 1.6089622365023017, 0.7482009162186649, -0.928963805323159, -0.8071122132902002, -2.252106742623391, 0.6357290837769687, 2.434328799362226, 0.14039030851237014, 0.31358023001092833, 0.7142857142857143, 0.7462767085363134, 0.9341232047026944, 2.7584575353504803, 0.6, -2.921666737101005, 0.7013096168462134, 0.6549602758916162, 0.8733368259264793, 0.46669646866488124, 1.5189377426319746, 1.6232385907435374, 0.7142176200701937, 1.0374776707469806, 0.6979518057143111, 2.863885888001481, 0.6025514397782047, -0.8705060054732491, 2.1389046636546287, -1.6766027063900224, 0.8002354244702661, -3.100156238131055, 0.8028063704799497, 0.4060496452480916, 0.9208765968844119, 0.8964854683667912, 0.2629593693063993, 0.03725822215115454, 0.1378527695489362, -2.929428662023072, 0.6683916854710051, 0.6708599469640657, 0.8571428571428571, -0.08498850043808623, 0.04390787307053942, 0.693432803864734, 0.0]),
        (&[60.0, 42.0, 1.0, 0.3, 0.2, 1.1, 0.0, 1.0], &[-0.11350295430539539, -0.21844517740329217, -1.642830101203049, 0.6735563009388541, -0.17814637593594096, 0.7425515148508782, -1.1201310718700497, 0.2841977836335378, 1.0172839047864302, 0.04685130393800842, 0.203489038659366, 0.1589586437954375, -1.5236418036295087, -0.09589828798941796, 0.6986798556586855, 0.46994113824261, -1.0262232118397392, 2.038628904376759, 2.3144474883250665, 0.9572877359261214, 0.7770257025292825, -0.3719223557310524, 1.0693377232667984, 0.4891399909225944, 0.04520333196285748, -0.3222519964110485, -1.7486668266398189, 0.743007845311895, -1.006816075855161, 2.1645321254985923, -1.89979164217336, 0.8570711711687368]),
        (&[60.0, 42.0, 1.0, 0.3, 0.2, 1.1, 1.0, 0.0], &[0.33919321430174887, -0.19467992807325704, -2.1944981856901964, 0.8, -0.8738624086074119, 0.7958612591213385, 1.9399474440818665, 1.0, 1.7350725817619885, -0.40303303179660205, -0.7517907915110268, 0.8, 0.12805015402624054, 1.7224656430279572, 1.4143110313765834, 0.75, -1.1622741889557766, 2.176450612859808, -1.4877763944017266, 0.8, -1.181443200419666, 2.235557021787452, 2.5354057250961115, 1.0, 2.7321486790309795, 0.06904691928265569, 0.30380756338620446, 0.7142857142857143, -0.7155886167462918, -0.3983203327695741, -2.0614896798026874, 0.5]),
        (&[60.0, 42.0, 1.0, 0.5, 0.0, 1.4, 1.0, 1.0], &[-0.05448972527026957, -0.02736254704292934, -1.7616925007347168, 0.6735563009388541, 0.5555349907778928, 0.4146187098535083, 2.3595913506062045, 0.5398476969636268, -1.0181594463431287, 0.9752222134273582, 1.560098773123547, 0.8780662919758196, -0.21202447482085085, 0.5957529409092386, -0.8019112655033773, 0.21753459904228084, 1.2591741794231683, -0.2684869255960355, -0.08019993024322547, 0.620404607067073, 0.8465305179920656, -0.026094106837002227, 0.4185178921227225, 0.1589586437954375, 0.2801417191047641, 1.6656576380382362, 1.6297902905677293, 0.7482009162186649, 1.0460304397646798, -0.4357131443911308, -0.507116932765163, 0.8406285870078153]),
    ];

    /// (name, own parameters, RGB at the six points of DC_POINTS; dc_circuits' calls follow
    /// one another from a fresh state).
    #[rustfmt::skip]
    const DC_RGB: &[(&str, &[f64], &[f64])] = &[
        ("dc_mandala", &[0.025, -0.001245675, 2.0, 12.0, 1.5, 64.0, 0.0, 0.0, 1.0], &[0.5193156567049916, 1.087790660465649, 0.5429890890021405, 0.5918647824926692, 0.4457598167783171, 0.3243940875324218, 1.0005757335789243, 0.35739409396709076, 0.44054982347349725, 0.7024739614585732, 0.1709093212885147, 0.2810172990737041, 0.6507135986335295, 0.23616586663426373, 0.2983296415077279, 1.0195190822130227, 1.1656945976118507, 0.925246598046363, ]),
        ("dc_mandala", &[0.1, 0.3, 3.1, 7.6, 2.7, 20.5, 1.0, 1.0, 0.0], &[0.6211894243895166, 0.4385207989086224, 0.4546023477117367, 0.6244420419963772, 0.4887848310265054, 0.504138380120345, 0.6480390361966966, 0.474922443678489, 0.499717524258319, 0.6490834826026343, 0.3181459352415118, 0.3675136870811693, 0.6885206232436583, 0.43977455407819543, 0.5004218317529052, 0.464426059891181, 0.5731845189601885, 0.12309912505938815, ]),
        ("dc_inversion", &[10000.0, 0.0, 50.0, 1.5, 1.5], &[0.023210920181853112, 0.07055044829739743, 0.09074217607239587, 0.005342014112518223, 0.016548444519617123, 0.02146272104881486, 0.003061822274426307, 0.009507818886891783, 0.012344434342347665, 0.14857340463706736, 0.39412431572593054, 0.4787405872525963, 1.0, 1.0, 1.0, 0.003916899783177219, 0.012152067600470162, 0.015771279756131906, ]),
        ("dc_inversion", &[10000.0, 2.0, 49.0, 1.66, 1.82], &[0.29173997425581133, 0.7069549742711414, 0.8056860484476847, 0.1497669250866882, 0.43860050199400424, 0.5372492726114786, 0.036692597690176854, 0.12455284253287846, 0.16267731845060462, 1.0, 1.0, 1.0, 0.6970247562081632, 0.985721955072013, 0.9965565773084197, 0.4514260464797586, 0.8819382157977556, 0.9422540951708218, ]),
        ("dc_poincaredisc", &[2.0, 10.0, 4.0, 5.0, 1.0, 1.0, 1.0], &[0.2816409295709899, 0.2816409295709899, 0.2816409295709899, 0.20685363352801497, 0.20685363352801497, 0.20685363352801497, 0.35890661286644604, 0.35890661286644604, 0.35890661286644604, 0.12578497309620898, 0.12578497309620898, 0.12578497309620898, 0.0, 0.0, 0.0, 0.3553311799591342, 0.3553311799591342, 0.3553311799591342, ]),
        ("dc_poincaredisc", &[1.7, 14.0, 3.0, 7.0, 1.0, 0.0, 1.0], &[0.47439785462353384, 0.47439785462353384, 0.47439785462353384, 0.2348882000734963, 0.2348882000734963, 0.2348882000734963, 0.4124698157043211, 0.4124698157043211, 0.4124698157043211, 0.248210954891636, 0.248210954891636, 0.248210954891636, 0.0, 0.0, 0.0, 0.30422533312369976, 0.30422533312369976, 0.30422533312369976, ]),
        ("dc_poincaredisc", &[2.5, 20.0, 5.0, 4.0, 0.0, 1.0, 0.0], &[0.48930155261735037, 0.48930155261735037, 0.48930155261735037, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.7387830707997405, 0.7387830707997405, 0.7387830707997405, ]),
        ("dc_turbulence", &[10000.0, 1.0, 8.0, 3.0], &[0.47447705698871334, 0.47447705698871334, 0.47447705698871334, 0.11766174943766258, 0.11766174943766258, 0.11766174943766258, 0.10454107474133902, 0.10454107474133902, 0.10454107474133902, 0.24565317664249883, 0.24565317664249883, 0.24565317664249883, 0.46740229631642416, 0.46740229631642416, 0.46740229631642416, 0.3627042593337443, 0.3627042593337443, 0.3627042593337443, ]),
        ("dc_turbulence", &[10000.0, 3.7, 5.5, 5.0], &[0.4905678872893672, 0.4905678872893672, 0.4905678872893672, 0.39728739536127294, 0.39728739536127294, 0.39728739536127294, 0.22421009578738457, 0.22421009578738457, 0.22421009578738457, 0.2720566684486738, 0.2720566684486738, 0.2720566684486738, 0.253238450613889, 0.253238450613889, 0.253238450613889, 0.21662055381293796, 0.21662055381293796, 0.21662055381293796, ]),
        ("dc_gabornoise", &[10000.0, 0.0, 20.0], &[0.43916485851447984, 1.1748488456592892, 0.20447237376992994, 0.022538682209889194, 1.0455449992900843, 0.7799960787152005, 0.6895076263894553, 1.0543581761238223, 0.05459790138714016, 0.3787910402937039, 1.1898328597346812, 0.2545317879399289, 0.1836256691174747, 0.4562825344189832, 1.1895037901957166, 1.1610339684685163, 0.48105285283328875, 0.11474941930091481, ]),
        ("dc_gabornoise", &[10000.0, 1.3, 7.5], &[0.1344833934350218, 1.168372855615951, 0.5382674989990496, 0.04275546014893572, 0.708686985244357, 1.0913228812584763, 0.32017968201247343, 0.2999620180837874, 1.1973247182068025, 0.7031468691852851, 1.0452132735252695, 0.048983531854434825, 0.21301525925259074, 1.1942092765364563, 0.428337496962359, 1.188285220066897, 0.38638366586440775, 0.17906601560185442, ]),
        ("dc_circuits", &[1000000.0, 0.0, 0.8, 0.9, 1.5, 10.0, 2.0, 15.0, 1.0], &[6.367099907488526, 4.006920397783649, 1.2228488405180487, 0.9639026437444472, 0.6314940253832756, 0.23253733671619767, 0.7380344139450066, 0.4891300741657089, 0.19193948778560158, 0.5830979624131937, 0.3900527129014936, 0.15828725523953685, 0.6268024021987657, 0.41208603949920053, 0.15696472160163608, 1.2942699558610085, 0.858201450114091, 0.3389726459695416, ]),
        ("dc_circuits", &[1000000.0, 250.0, 0.6, 1.2, 0.8, 4.0, 7.0, 9.5, 0.7], &[14.823745646474922, 9.665597935223694, 3.17712462520279, 2.319415861986126, 1.53970336588326, 0.5747659245323049, 1.1837456918491105, 0.7676888229026871, 0.28990314470770895, 1.1020374142831946, 0.7148460483931611, 0.2734852734295533, 0.7616491038880732, 0.5143931135134304, 0.21222729170941226, 1.445698009703567, 0.9604560679608413, 0.3838223680803855, ]),
        ("dc_circuits", &[1000000.0, 700.0, 1.0, 0.9, 1.5, 10.0, 2.0, 30.0, 1.3], &[0.9654638282764428, 0.5618159013808, 0.07335339846383697, 0.012348775403223053, 0.013707009363913385, 0.014269477132061854, 0.07537148291177288, 0.05566063786245319, 0.033067444953457335, 0.020534534476710206, 0.020575638524359733, 0.02003263748732857, 0.29568531950592, 0.1968186527416251, 0.0821370111404087, 0.1346656946105796, 0.09928661151981279, 0.05888616747185152, ]),
    ];

    /// dc_mandala with ColorOnly 1, Gradient 2, scale_z 0.7, offset_z 0.1, reset_z 1, weight
    /// 0.8, running sum (0.2, 0.3, 0.5): (input x y, output x y z colour).
    #[rustfmt::skip]
    const DC_FULL: &[(&[f64], &[f64])] = &[
        (&[0.13, -0.27], &[0.30400000000000005, 0.08399999999999996, 0.6572549019607842, 0.796078431372549]),
        (&[-0.41, 0.05], &[-0.128, 0.33999999999999997, 0.4294117647058824, 0.47058823529411764]),
        (&[0.33, 0.29], &[0.464, 0.532, 0.48705882352941177, 0.5529411764705883]),
        (&[-0.07, -0.45], &[0.14400000000000002, -0.06000000000000005, 0.336078431372549, 0.33725490196078434]),
        (&[0.6, -0.1], &[0.6799999999999999, 0.21999999999999997, 0.35254901960784313, 0.3607843137254902]),
        (&[0.0021, 0.0017], &[0.20168, 0.30135999999999996, 0.7890196078431372, 0.984313725490196]),
    ];
}
