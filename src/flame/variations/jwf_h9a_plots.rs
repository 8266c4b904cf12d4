//! JWildfire's plots of formula text: `parplot2d_wf` (a parametric surface x, y, z of (u, v)),
//! `polarplot2d_wf` (a polar curve r(t), extruded along z), `yplot2d_wf` (a graph y(x),
//! extruded along z), `yplot3d_wf` (a height field y(x, z)) and `isosfplot3d_wf` (the points
//! where |f(x, y, z)| ≤ thickness, found by random sampling). Each formula is a Java expression
//! over the plot's coordinates, `pi` and `param_a` … `param_f`, compiled by
//! [`formula::compile`]; a new variation has the formulas, ranges and parameters of
//! JWildfire's preset 0 (the id a file names is kept, the file's own formula text is used).
//!
//! A formula that does not compile draws nothing (JWildfire refuses to render it); the reason
//! is reported when the flame is read ([`formula_problem`]). Colour maps and displacement maps
//! (images) are not supported. The formulas follow JWildfire's (Andreas Maschke and
//! contributors, LGPL-2.1) `ParPlot2DWFFunc`, `PolarPlot2DWFFunc`, `YPlot2DWFFunc`,
//! `YPlot3DWFFunc` and `IsoSFPlot3DWFFunc`, written anew; random numbers are drawn in the order
//! JWildfire draws them.

use std::f64::consts::PI;

use super::util::formula;
use super::*;

/// Most samples isosfplot3d_wf tries per call (its `max_iter`; each evaluates the formula once).
const ISO_MAX_ITER: f64 = 500.0;

/// The longest formula text read (bytes).
const MAX_TEXT: usize = 4000;

const FLAGS: u32 =
    flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::USES_COLOR;

/// A plot's parameters: `own`, then the six free parameters every plot passes to its formulas
/// (named for variation `$n`, the first three with defaults `$a`, `$b`, `$c`).
macro_rules! plot_params {
    // The colour settings every plot has after its own ranges: direct colour, colour mode (its
    // default given), colour-map blending and, with `displ`, the displacement map's.
    ($n:literal, [$($own:expr),* $(,)?], colour($mode:expr, displ), [$($after:expr),* $(,)?],
     $a:expr, $b:expr, $c:expr) => {
        plot_params!(
            $n,
            [
                $($own,)*
                p_int(concat!($n, "_direct_color"), 1.0, NEG_INF, INF),
                p_int(concat!($n, "_color_mode"), $mode, NEG_INF, INF),
                p_int(concat!($n, "_blend_colormap"), 1.0, 0.0, 1.0),
                p(concat!($n, "_displ_amount"), 0.1),
                p_int(concat!($n, "_blend_displ_map"), 1.0, 0.0, 1.0),
                $($after,)*
            ],
            $a,
            $b,
            $c
        )
    };
    ($n:literal, [$($own:expr),* $(,)?], colour($mode:expr), [$($after:expr),* $(,)?],
     $a:expr, $b:expr, $c:expr) => {
        plot_params!(
            $n,
            [
                $($own,)*
                p_int(concat!($n, "_direct_color"), 1.0, NEG_INF, INF),
                p_int(concat!($n, "_color_mode"), $mode, NEG_INF, INF),
                p_int(concat!($n, "_blend_colormap"), 1.0, 0.0, 1.0),
                $($after,)*
            ],
            $a,
            $b,
            $c
        )
    };
    ($n:literal, [$($own:expr),* $(,)?], $a:expr, $b:expr, $c:expr) => {
        &[
            $($own,)*
            p(concat!($n, "_param_a"), $a),
            p(concat!($n, "_param_b"), $b),
            p(concat!($n, "_param_c"), $c),
            p(concat!($n, "_param_d"), 0.0),
            p(concat!($n, "_param_e"), 0.0),
            p(concat!($n, "_param_f"), 0.0),
        ]
    };
}

const fn text(name: &'static str, default: &'static str) -> TextParam {
    TextParam {
        name,
        default,
        max_len: MAX_TEXT,
    }
}

const PAR_TEXTS: &[TextParam] = &[
    text("parplot2d_wf_xformula", "cos(u)*(4.0+cos(v))"),
    text("parplot2d_wf_yformula", "sin(u)*(4.0+cos(v))"),
    text(
        "parplot2d_wf_zformula",
        "4.0*sin(2.0*u)+sin(v)*(1.2-sin(v))",
    ),
];
const POLAR2D_TEXTS: &[TextParam] = &[text("polarplot2d_wf_formula", "t*param_a")];
const Y2D_TEXTS: &[TextParam] = &[text("yplot2d_wf_formula", "(sin(x)+2*sin(2*x)+1*sin(4*x))")];
const Y3D_TEXTS: &[TextParam] = &[text("yplot3d_wf_formula", "sin(2*exp(-4*(x*x+z*z)))")];
const ISO_TEXTS: &[TextParam] = &[text(
    "isosfplot3d_wf_formula",
    "sin(param_a * x * y) + sin(param_b * y * z) + sin(param_c * z * x)",
)];

/// The names each plot's formulas read, in the order its call passes their values.
const PAR_VARS: &[&str] = &[
    "u", "v", "pi", "param_a", "param_b", "param_c", "param_d", "param_e", "param_f",
];
const POLAR2D_VARS: &[&str] = &[
    "t", "pi", "param_a", "param_b", "param_c", "param_d", "param_e", "param_f",
];
const Y2D_VARS: &[&str] = &[
    "x", "pi", "param_a", "param_b", "param_c", "param_d", "param_e", "param_f",
];
const Y3D_VARS: &[&str] = &[
    "x", "z", "pi", "param_a", "param_b", "param_c", "param_d", "param_e", "param_f",
];
const ISO_VARS: &[&str] = &[
    "x", "y", "z", "pi", "param_a", "param_b", "param_c", "param_d", "param_e", "param_f",
];

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("parplot2d_wf", parplot2d_wf)
        .params(plot_params!(
            "parplot2d_wf",
            [
                p_int("parplot2d_wf_preset_id", 0.0, NEG_INF, INF),
                p("parplot2d_wf_umin", 0.0),
                p("parplot2d_wf_umax", 2.0 * PI),
                p("parplot2d_wf_vmin", 0.0),
                p("parplot2d_wf_vmax", 2.0 * PI),
            ],
            colour(3.0, displ),
            [p_int("parplot2d_wf_solid", 1.0, NEG_INF, INF)],
            0.0,
            0.0,
            0.0
        ))
        .flags(FLAGS)
        .texts(PAR_TEXTS)
        .prepare(ranges_uv)
        .shared(&[], par_programs),
    VarDef::new("polarplot2d_wf", polarplot2d_wf)
        .params(plot_params!(
            "polarplot2d_wf",
            [
                p_int("polarplot2d_wf_preset_id", 0.0, NEG_INF, INF),
                p("polarplot2d_wf_tmin", 0.0),
                p("polarplot2d_wf_tmax", 6.0 * PI),
                p("polarplot2d_wf_rmin", 0.0),
                p("polarplot2d_wf_rmax", 2.0),
                p("polarplot2d_wf_zmin", -2.0),
                p("polarplot2d_wf_zmax", 2.0),
            ],
            colour(1.0, displ),
            [],
            0.25,
            0.0,
            0.0
        ))
        .flags(FLAGS)
        .texts(POLAR2D_TEXTS)
        .prepare(ranges_3)
        .shared(&[], polar2d_programs),
    VarDef::new("yplot2d_wf", yplot2d_wf)
        .params(plot_params!(
            "yplot2d_wf",
            [
                p_int("yplot2d_wf_preset_id", 0.0, NEG_INF, INF),
                p("yplot2d_wf_xmin", -3.0),
                p("yplot2d_wf_xmax", 2.0),
                p("yplot2d_wf_ymin", -4.0),
                p("yplot2d_wf_ymax", 4.0),
                p("yplot2d_wf_zmin", -2.0),
                p("yplot2d_wf_zmax", 2.0),
            ],
            colour(1.0, displ),
            [],
            0.0,
            0.0,
            0.0
        ))
        .flags(FLAGS)
        .texts(Y2D_TEXTS)
        .prepare(ranges_3)
        .shared(&[], y2d_programs),
    VarDef::new("yplot3d_wf", yplot3d_wf)
        .params(plot_params!(
            "yplot3d_wf",
            [
                p_int("yplot3d_wf_preset_id", 0.0, NEG_INF, INF),
                p("yplot3d_wf_xmin", -3.0),
                p("yplot3d_wf_xmax", 2.0),
                p("yplot3d_wf_ymin", -2.0),
                p("yplot3d_wf_ymax", 2.0),
                p("yplot3d_wf_zmin", -2.0),
                p("yplot3d_wf_zmax", 2.0),
            ],
            colour(3.0, displ),
            [],
            0.0,
            0.0,
            0.0
        ))
        .flags(FLAGS)
        .texts(Y3D_TEXTS)
        .prepare(ranges_3)
        .shared(&[], y3d_programs),
    VarDef::new("isosfplot3d_wf", isosfplot3d_wf)
        .params(plot_params!(
            "isosfplot3d_wf",
            [
                p_int("isosfplot3d_wf_preset_id", 0.0, NEG_INF, INF),
                p("isosfplot3d_wf_xmin", -PI),
                p("isosfplot3d_wf_xmax", PI),
                p("isosfplot3d_wf_ymin", -PI),
                p("isosfplot3d_wf_ymax", PI),
                p("isosfplot3d_wf_zmin", -PI),
                p("isosfplot3d_wf_zmax", PI),
                p_range("isosfplot3d_wf_thickness", 0.05, 1e-8, INF),
                p_int("isosfplot3d_wf_max_iter", 160.0, 1.0, ISO_MAX_ITER).limited(),
            ],
            colour(9.0),
            [],
            1.0,
            1.0,
            1.0
        ))
        .flags(FLAGS | flag::HIDES)
        .texts(ISO_TEXTS)
        .prepare(ranges_3)
        .shared(&[], iso_programs),
];

fn ranges_uv(v: &mut Prepared) {
    ranges(v, [1, 3]);
}

fn ranges_3(v: &mut Prepared) {
    ranges(v, [1, 3, 5]);
}

fn par_programs(_: &[f64], t: &[String]) -> Vec<f64> {
    compile_all(t, PAR_VARS, "0.0")
}

fn polar2d_programs(_: &[f64], t: &[String]) -> Vec<f64> {
    compile_all(t, POLAR2D_VARS, "")
}

fn y2d_programs(_: &[f64], t: &[String]) -> Vec<f64> {
    compile_all(t, Y2D_VARS, "")
}

fn y3d_programs(_: &[f64], t: &[String]) -> Vec<f64> {
    compile_all(t, Y3D_VARS, "")
}

fn iso_programs(_: &[f64], t: &[String]) -> Vec<f64> {
    compile_all(t, ISO_VARS, "")
}

/// Appends (min, max − min) of each (min, max) parameter pair starting at the given indices,
/// the pair ordered (JWildfire swaps a reversed range).
fn ranges<const N: usize>(v: &mut Prepared, at: [usize; N]) {
    for i in at {
        let (a, b) = (v.p[i], v.p[i + 1]);
        let (lo, hi) = if a > b { (b, a) } else { (a, b) };
        v.p.push(lo);
        v.p.push(hi - lo);
    }
}

/// The formulas of `texts` compiled over `vars`: `[1, len₀, code₀…, len₁, code₁…, …]`, or `[0]`
/// when one does not compile (the variation then draws nothing). An empty text is `empty`
/// (parplot2d_wf plots "0.0" for a missing coordinate); with `empty` itself empty, an empty
/// text draws nothing, as in JWildfire.
fn compile_all(texts: &[String], vars: &[&str], empty: &str) -> Vec<f64> {
    let mut out = vec![1.0];
    for t in texts {
        let t = t.trim();
        let t = if t.is_empty() { empty } else { t };
        if t.is_empty() {
            return vec![0.0];
        }
        match formula::compile(t, vars) {
            Ok(code) => {
                out.push(code.len() as f64);
                out.extend_from_slice(&code);
            }
            Err(_) => return vec![0.0],
        }
    }
    out
}

/// Why a formula text of one of these plots cannot be drawn, for the reader of a flame to
/// report: `None` when every text of `name` compiles (or `name` is none of these plots).
pub fn formula_problem(name: &str, texts: &[String]) -> Option<String> {
    let (vars, empty): (&[&str], &str) = match name {
        "parplot2d_wf" => (PAR_VARS, "0.0"),
        "polarplot2d_wf" => (POLAR2D_VARS, ""),
        "yplot2d_wf" => (Y2D_VARS, ""),
        "yplot3d_wf" => (Y3D_VARS, ""),
        "isosfplot3d_wf" => (ISO_VARS, ""),
        _ => return None,
    };
    let names = DEFS.iter().find(|d| d.name == name)?.texts;
    for (t, def) in texts.iter().zip(names) {
        let t = t.trim();
        let t = if t.is_empty() { empty } else { t };
        if t.is_empty() {
            return Some(format!(
                "{}: the formula is empty; the variation draws nothing",
                def.name
            ));
        }
        if let Err(e) = formula::compile(t, vars) {
            return Some(format!(
                "{}: the formula does not compile ({e}); the variation draws nothing",
                def.name
            ));
        }
    }
    None
}

/// The `N` programs of [`compile_all`]'s data, if they compiled.
fn programs<const N: usize>(data: &[f64]) -> Option<[&[f64]; N]> {
    let (&1.0, mut rest) = data.split_first()? else {
        return None;
    };
    let mut out: [&[f64]; N] = [&[]; N];
    for slot in out.iter_mut() {
        let (&len, tail) = rest.split_first()?;
        let len = len as usize;
        if len > tail.len() {
            return None;
        }
        (*slot, rest) = tail.split_at(len);
    }
    Some(out)
}

/// Sets the colour to `c` clamped to [0, 1] (JWildfire clamps whatever the colour mode left).
fn set_color(acc: &mut Acc, c: Option<f64>) {
    let c = c.unwrap_or(acc.color);
    acc.color = c.clamp(0.0, 1.0);
}

/// parplot2d_wf: the point (x(u, v), y(u, v), z(u, v)) of three formulas, at uniformly random
/// (u, v) of the ranges (or, with `solid` 0, at u, v given by the input point's x and y); the
/// colour can follow u, v or u·v.
fn parplot2d_wf(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        _,
        _,
        _,
        direct_color,
        color_mode,
        _,
        _,
        _,
        solid,
        a,
        b,
        c,
        d,
        e,
        f,
    ] = v.params();
    let [umin, du, vmin, dv] = v.derived();
    let Some([fx, fy, fz]) = programs::<3>(v.data()) else {
        return [0.0; 3];
    };
    let (ru, rv) = if solid == 0.0 {
        (t.x, t.y)
    } else {
        let ru = rng.f01();
        (ru, rng.f01())
    };
    let uu = umin + ru * du;
    let vv = vmin + rv * dv;
    let vars = [uu, vv, PI, a, b, c, d, e, f];
    let x = formula::run(fx, &vars);
    let y = formula::run(fy, &vars);
    let z = formula::run(fz, &vars);
    if direct_color > 0.0 {
        let cu = (uu - umin) / du;
        let cv = (vv - vmin) / dv;
        let col = match color_mode as i32 {
            0 => None,
            1 => Some(cu),
            2 => Some(cv),
            _ => Some((vv - vmin) / dv * (uu - umin) / du),
        };
        set_color(acc, col);
    }
    [v.w * x, v.w * y, v.w * z]
}

/// polarplot2d_wf: the polar curve r(t) at a uniformly random t of its range, at a uniformly
/// random height z; the colour can follow t or r.
fn polarplot2d_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        direct_color,
        color_mode,
        _,
        _,
        _,
        a,
        b,
        c,
        d,
        e,
        f,
    ] = v.params();
    let [tmin, dt, rmin, dr, zmin, dz] = v.derived();
    let Some([fr]) = programs::<1>(v.data()) else {
        return [0.0; 3];
    };
    let rt = rng.f01();
    let rz = rng.f01();
    let tt = tmin + rt * dt;
    let z = zmin + rz * dz;
    let r = formula::run(fr, &[tt, PI, a, b, c, d, e, f]);
    let (st, ct) = tt.sin_cos();
    if direct_color > 0.0 {
        let col = match color_mode as i32 {
            0 => None,
            2 => Some((r - rmin) / dr),
            _ => Some((tt - tmin) / dt),
        };
        set_color(acc, col);
    }
    [v.w * r * ct, v.w * r * st, v.w * z]
}

/// yplot2d_wf: the graph y(x) at a uniformly random x of its range, at a uniformly random
/// height z; the colour can follow x or y.
fn yplot2d_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        direct_color,
        color_mode,
        _,
        _,
        _,
        a,
        b,
        c,
        d,
        e,
        f,
    ] = v.params();
    let [xmin, dx, ymin, dy, zmin, dz] = v.derived();
    let Some([fy]) = programs::<1>(v.data()) else {
        return [0.0; 3];
    };
    let rx = rng.f01();
    let rz = rng.f01();
    let x = xmin + rx * dx;
    let z = zmin + rz * dz;
    let y = formula::run(fy, &[x, PI, a, b, c, d, e, f]);
    if direct_color > 0.0 {
        let col = match color_mode as i32 {
            0 => None,
            2 => Some((y - ymin) / dy),
            _ => Some((x - xmin) / dx),
        };
        set_color(acc, col);
    }
    [v.w * x, v.w * y, v.w * z]
}

/// yplot3d_wf: the height field y(x, z) at uniformly random (x, z) of the ranges; the colour
/// can follow x, y, z or x·z.
fn yplot3d_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        direct_color,
        color_mode,
        _,
        _,
        _,
        a,
        b,
        c,
        d,
        e,
        f,
    ] = v.params();
    let [xmin, dx, ymin, dy, zmin, dz] = v.derived();
    let Some([fy]) = programs::<1>(v.data()) else {
        return [0.0; 3];
    };
    let rx = rng.f01();
    let rz = rng.f01();
    let x = xmin + rx * dx;
    let z = zmin + rz * dz;
    let y = formula::run(fy, &[x, z, PI, a, b, c, d, e, f]);
    if direct_color > 0.0 {
        let col = match color_mode as i32 {
            0 => None,
            1 => Some((x - xmin) / dx),
            2 => Some((y - ymin) / dy),
            4 => Some((x - xmin) / dx * (z - zmin) / dz),
            _ => Some((z - zmin) / dz),
        };
        set_color(acc, col);
    }
    [v.w * x, v.w * y, v.w * z]
}

/// isosfplot3d_wf: up to `max_iter` uniformly random points of the box, the first where
/// |f(x, y, z)| ≤ thickness kept (hidden when none is); the colour can follow x, y, z or
/// products of them.
fn isosfplot3d_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        thickness,
        max_iter,
        direct_color,
        color_mode,
        _,
        a,
        b,
        c,
        d,
        e,
        f,
    ] = v.params();
    let [xmin, dx, ymin, dy, zmin, dz] = v.derived();
    let Some([fv]) = programs::<1>(v.data()) else {
        return [0.0; 3];
    };
    acc.hide = true;
    let (mut x, mut y, mut z) = (0.0, 0.0, 0.0);
    for _ in 0..max_iter.clamp(0.0, ISO_MAX_ITER) as usize {
        x = xmin + rng.f01() * dx;
        y = ymin + rng.f01() * dy;
        z = zmin + rng.f01() * dz;
        if formula::run(fv, &[x, y, z, PI, a, b, c, d, e, f]).abs() <= thickness {
            acc.hide = false;
            break;
        }
    }
    if acc.hide {
        return [0.0; 3];
    }
    if direct_color > 0.0 {
        let (cx, cy, cz) = ((x - xmin) / dx, (y - ymin) / dy, (z - zmin) / dz);
        let col = match color_mode as i32 {
            0..=2 => None,
            3 => Some(cx),
            4 => Some(cy),
            5 => Some(cz),
            6 => Some((x - xmin) / dx * (y - ymin) / dy),
            7 => Some((y - ymin) / dy * (z - zmin) / dz),
            8 => Some((z - zmin) / dz * (x - xmin) / dx),
            _ => Some((x - xmin) / dx * (y - ymin) / dy * (z - zmin) / dz),
        };
        set_color(acc, col);
    }
    [v.w * x, v.w * y, v.w * z]
}
