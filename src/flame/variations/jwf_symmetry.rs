//! JWildfire's symmetry groups `sym_ng1` … `sym_ng17` (wallpaper, "network" groups) and
//! `sym_bg1` … `sym_bg7` (frieze, "band" groups): each applies one isometry of its group,
//! picked at random, to the shifted point.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: `atan_xy` is its `getPrecalcAtan`
//! (atan2(x, y)), weights multiply the output linearly, integer parameters are rounded (those it
//! truncates, `(int) value`, are stored as reals and truncated where used), and random numbers
//! are drawn in the order JWildfire draws them, so that the tests can replay JWildfire's own code
//! on the same stream.

use super::util::Draw;
use super::*;

/// `NAME_stepx` and `NAME_stepy` (both 0 by default), after any leading parameters given.
macro_rules! sym_steps {
    ($name:literal $(, $lead:expr)*) => {
        &[$($lead,)* p(concat!($name, "_stepx"), 0.0), p(concat!($name, "_stepy"), 0.0)]
    };
}

pub(super) static DEFS: &[VarDef] = &[
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
];

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

const P_NG1: &[Param] = &[p("sym_ng1_stepx", 0.5), p("sym_ng1_stepy", 0.5)];

const P_NG2: &[Param] = &[p("sym_ng2_stepx", 2.0), p("sym_ng2_stepy", 2.0)];

const P_NG3: &[Param] = &[
    p("sym_ng3_sepx", 0.5),
    p("sym_ng3_sepy", 0.0),
    p("sym_ng3_step", 2.0),
];

const P_NG4: &[Param] = &[
    p("sym_ng4_sepx", 0.0),
    p("sym_ng4_sepy", 0.0),
    p("sym_ng4_stepx", 0.0),
    p("sym_ng4_stepy", 0.0),
];

const P_NG5: &[Param] = &[
    p("sym_ng5_sepx", 0.0),
    p("sym_ng5_sepy", 0.0),
    p("sym_ng5_stepx", 0.0),
];

const P_NG6: &[Param] = &[
    p("sym_ng6_sepy", 0.1),
    p("sym_ng6_stepx", 1.0),
    p("sym_ng6_stepy", 1.0),
];

const P_NG7: &[Param] = &[p("sym_ng7_sepx", 0.0), p("sym_ng7_sepy", 0.0)];

const P_NG8: &[Param] = &[
    p("sym_ng8_sepx", 0.0),
    p("sym_ng8_sepy", 0.0),
    p("sym_ng8_skewx", 0.0),
    p("sym_ng8_skewy", 0.0),
];

const P_NG9: &[Param] = &[p("sym_ng9_sepx", 0.0), p("sym_ng9_sepy", 0.0)];

const P_NG10: &[Param] = &[
    p("sym_ng10_space", 0.0),
    p("sym_ng10_spacex", 0.0),
    p("sym_ng10_spacey", 0.0),
];

const P_NG11: &[Param] = &[
    p("sym_ng11_space", 0.0),
    p("sym_ng11_spacex", 0.0),
    p("sym_ng11_spacey", 0.0),
    p("sym_ng11_stepx", 1.5),
    p("sym_ng11_stepy", 1.5),
];

const P_NG12: &[Param] = &[
    p("sym_ng12_space", 0.0),
    p("sym_ng12_spacex", 0.0),
    p("sym_ng12_spacey", 0.0),
];

// JWildfire 9 names the first parameter of sym_ng13 … sym_ng17 `radius`; earlier releases named
// it "Prop. Sep" (with a space, so a file carrying it is not well-formed XML), which ugnis
// wrote as `prop_sep` and still reads.
const P_NG13: &[Param] = sym_steps!("sym_ng13", p("sym_ng13_radius", 0.0));

const P_NG14: &[Param] = sym_steps!("sym_ng14", p("sym_ng14_radius", 0.0));

const P_NG15: &[Param] = sym_steps!("sym_ng15", p("sym_ng15_radius", 0.0));

const P_NG16: &[Param] = sym_steps!("sym_ng16", p("sym_ng16_radius", 0.0));

const P_NG17: &[Param] = sym_steps!("sym_ng17", p("sym_ng17_radius", 0.0));

const P_BG1: &[Param] = sym_steps!("sym_bg1");

const P_BG2: &[Param] = sym_steps!("sym_bg2");

const P_BG3: &[Param] = sym_steps!("sym_bg3");

const P_BG4: &[Param] = sym_steps!("sym_bg4");

const P_BG5: &[Param] = sym_steps!("sym_bg5");

const P_BG6: &[Param] = sym_steps!("sym_bg6");

const P_BG7: &[Param] = sym_steps!("sym_bg7");

const SYM: u32 = flag::JWILDFIRE | flag::RANDOM;

#[cfg(test)]
mod tests;
