//! JWildfire's direct-colour stamps whose patterns its `glsl_*` stamps also draw (Jesus
//! Sosa's shader ports): `dc_apollonian`, `dc_circlesblue`, `dc_fractaldots`, `dc_grid3D`,
//! `dc_hoshi`, `dc_hyperbolictile`, `dc_kaleidocomplex`, `dc_kaleidoscopic`, `dc_kaliset`,
//! `dc_kaliset2`, `dc_mandelbox2D` and `dc_squares`.
//!
//! Each scatters points over [−1, 1]² or [−½, ½]² (or colours the input with `ColorOnly`) and
//! colours them by the pattern, through `jwf_direct_colour`'s common part; the patterns are
//! those of `jwf_c_glsl` (and `jwf_b_dc`'s hoshi), here on the point itself, most with a zoom.
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use super::jwf_b_dc::hoshi_rgb;
use super::jwf_c_glsl::{
    apollonian_rgb, circlesblue_rgb, fractaldots_grey, grid3d_grey, hyperbolic_grey,
    kaleidocomplex_rgb, kaleidoscopic_rgb, kaliset_rgb, kaliset2_rgb, mandelbox2d_rgb, squares_rgb,
};
use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail};
use super::*;

/// The five shared trailing parameters of the dc_ stamps, appended to `head`.
macro_rules! with_tail {
    ($n:literal, [$($head:expr),* $(,)?]) => {{
        let tail = dc_tail!($n);
        [$($head,)* tail[0], tail[1], tail[2], tail[3], tail[4]]
    }};
}

const P_APOLLONIAN: &[Param] = &with_tail!(
    "dc_apollonian",
    [
        p_int("dc_apollonian_seed", 10000.0, NEG_INF, INF),
        p("dc_apollonian_time", 0.0),
    ]
);

const P_CIRCLESBLUE: &[Param] = &with_tail!(
    "dc_circlesblue",
    [
        p_int("dc_circlesblue_seed", 10000.0, NEG_INF, INF),
        p_range("dc_circlesblue_time", 1.0, 1.0, 1000.0),
        p_range("dc_circlesblue_zoom", 1.0, 0.01, 100.0),
        p_range("dc_circlesblue_radius", 0.04, 0.0, 1.0),
        p_int("dc_circlesblue_bubles", 40.0, 1.0, 100.0).limited(),
    ]
);

const P_FRACTALDOTS: &[Param] = &with_tail!(
    "dc_fractaldots",
    [
        p_int("dc_fractaldots_iterations", 9.0, 1.0, 100.0).limited(),
        p("dc_fractaldots_dotsize", 400.0),
        p("dc_fractaldots_maxiterations", 10.0),
        p("dc_fractaldots_complexity", 0.001245675),
        p("dc_fractaldots_pattern", 2.5),
        p("dc_fractaldots_spacing", 12.0),
        p("dc_fractaldots_rotate1", 1.5),
        p("dc_fractaldots_rotate2", 64.0),
        p("dc_fractaldots_zoom", 64.0),
    ]
);

const P_GRID3D: &[Param] = &with_tail!(
    "dc_grid3D",
    [
        p_range("dc_grid3D_zoom", 1.0, 0.01, 1000.0),
        p_int("dc_grid3D_Seed", 10000.0, NEG_INF, INF),
        p_range("dc_grid3D_time", 200.0, 1.0, 1000.0),
    ]
);

const P_HOSHI: &[Param] = &with_tail!(
    "dc_hoshi",
    [
        p_int("dc_hoshi_seed", 100000.0, NEG_INF, INF),
        p("dc_hoshi_time", 10.0),
        p_int("dc_hoshi_steps", 28.0, 1.0, 60.0).limited(),
        p_range("dc_hoshi_scale", 1.25, 1.0, 5.0),
        p_range("dc_hoshi_translate", 1.5, 0.0, 5.0),
    ]
);

const P_HYPERBOLIC: &[Param] = &with_tail!(
    "dc_hyperbolictile",
    [p_range("dc_hyperbolictile_zoom", 1.0, 0.01, 50.0)]
);

const P_KALEIDOCOMPLEX: &[Param] = &with_tail!(
    "dc_kaleidocomplex",
    [
        p_int("dc_kaleidocomplex_seed", 1000000.0, NEG_INF, INF),
        p("dc_kaleidocomplex_time", 0.0),
        p_int("dc_kaleidocomplex_iMax", 12.0, 1.0, 50.0).limited(),
        p("dc_kaleidocomplex_color", 2.0),
        p_range("dc_kaleidocomplex_redF", 1.0, 0.0, 5.0),
        p_range("dc_kaleidocomplex_greenF", 1.0, 0.0, 5.0),
        p_range("dc_kaleidocomplex_blueF", 1.0, 0.0, 5.0),
    ]
);

const P_KALEIDOSCOPIC: &[Param] = &with_tail!(
    "dc_kaleidoscopic",
    [
        p_int("dc_kaleidoscopic_seed", 10000.0, NEG_INF, INF),
        p("dc_kaleidoscopic_time", 0.0),
        p_int("dc_kaleidoscopic_sides", 8.0, 2.0, 20.0),
        p_range("dc_kaleidoscopic_zoom", 1.0, 0.0, 1.0),
        p_range("dc_kaleidoscopic_p1", 0.0, 0.0, 1.0),
        p_int("dc_kaleidoscopic_radial", 1.0, 0.0, 1.0),
    ]
);

const P_KALISET: &[Param] = &with_tail!(
    "dc_kaliset",
    [
        p_int("dc_kaliset_Seed", 10000.0, NEG_INF, INF),
        p_range("dc_kaliset_time", 200.0, 1.0, 1000.0),
        p_range("dc_kaliset_zoom", 0.5, 0.01, 1000.0),
        p_int("dc_kaliset_N", 60.0, 1.0, 100.0).limited(),
        p_range("dc_kaliset_shiftX", -0.22, -5.0, 5.0),
        p_range("dc_kaliset_shiftY", -0.21, -5.0, 5.0),
    ]
);

const P_KALISET2: &[Param] = &with_tail!(
    "dc_kaliset2",
    [
        p_int("dc_kaliset2_seed", 5000.0, NEG_INF, INF),
        p_range("dc_kaliset2_time", 85.5, 1.0, 1000.0),
        p_range("dc_kaliset2_zoom", 20.0, 1.0, 1000.0),
        p_int("dc_kaliset2_N", 100.0, 1.0, 100.0).limited(),
        p_range("dc_kaliset2_radio", 1.0, 0.1, 10.0),
        p_range("dc_kaliset2_shiftX", -0.356, -1.0, 1.0),
        p_range("dc_kaliset2_shiftY", 0.686, -1.0, 1.0),
        p_range("dc_kaliset2_redF", 1.8, 0.0, 5.0),
        p_range("dc_kaliset2_greenF", 1.9, 0.0, 5.0),
        p_range("dc_kaliset2_blueF", 2.2, 0.0, 5.0),
    ]
);

const P_MANDELBOX2D: &[Param] = &with_tail!(
    "dc_mandelbox2D",
    [
        p_range("dc_mandelbox2D_zoom", 7.0, 0.1, 50.0),
        p_int("dc_mandelbox2D_seed", 10000.0, 0.0, 10000.0),
        p("dc_mandelbox2D_time", 0.0),
    ]
);

const P_SQUARES: &[Param] = &with_tail!(
    "dc_squares",
    [
        p_int("dc_squares_seed", 5000.0, NEG_INF, INF),
        p_range("dc_squares_time", 85.5, 0.0, 1000.0),
        p_int("dc_squares_N", 3.0, 1.0, 20.0).limited(),
        p_int("dc_squares_direction", 1.0, 0.0, 1.0),
        p_range("dc_squares_redF", 1.8, 0.0, 5.0),
        p_range("dc_squares_greenF", 1.9, 0.0, 5.0),
        p_range("dc_squares_blueF", 2.2, 0.0, 5.0),
    ]
);

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("dc_apollonian", dc_apollonian)
        .params(P_APOLLONIAN)
        .flags(DC_FLAGS),
    VarDef::new("dc_circlesblue", dc_circlesblue)
        .params(P_CIRCLESBLUE)
        .flags(DC_FLAGS),
    VarDef::new("dc_fractaldots", dc_fractaldots)
        .params(P_FRACTALDOTS)
        .flags(DC_FLAGS),
    VarDef::new("dc_grid3D", dc_grid3d)
        .params(P_GRID3D)
        .flags(DC_FLAGS),
    VarDef::new("dc_hoshi", dc_hoshi)
        .params(P_HOSHI)
        .flags(DC_FLAGS),
    VarDef::new("dc_hyperbolictile", dc_hyperbolictile)
        .params(P_HYPERBOLIC)
        .flags(DC_FLAGS),
    VarDef::new("dc_kaleidocomplex", dc_kaleidocomplex)
        .params(P_KALEIDOCOMPLEX)
        .flags(DC_FLAGS),
    VarDef::new("dc_kaleidoscopic", dc_kaleidoscopic)
        .params(P_KALEIDOSCOPIC)
        .flags(DC_FLAGS),
    VarDef::new("dc_kaliset", dc_kaliset)
        .params(P_KALISET)
        .flags(DC_FLAGS),
    VarDef::new("dc_kaliset2", dc_kaliset2)
        .params(P_KALISET2)
        .flags(DC_FLAGS),
    VarDef::new("dc_mandelbox2D", dc_mandelbox2d)
        .params(P_MANDELBOX2D)
        .flags(DC_FLAGS),
    VarDef::new("dc_squares", dc_squares)
        .params(P_SQUARES)
        .flags(DC_FLAGS),
];

/// dc_apollonian: the Apollonian fold over [−1, 1]².
fn dc_apollonian(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, tail @ ..] = v.params::<7>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| apollonian_rgb(x, y, time))
}

/// dc_circlesblue: rising bubbles over [−1, 1]², zoomed.
fn dc_circlesblue(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, zoom, radius, bubbles, tail @ ..] = v.params::<10>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        circlesblue_rgb(x * zoom, y * zoom, time, radius, bubbles)
    })
}

/// dc_fractaldots: dots of a folded, turned lattice over [−1, 1]² (the dot radius is the
/// one JWildfire computes from the default dot size, as glsl_fractaldots').
fn dc_fractaldots(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [q @ .., t0, t1, t2, t3, t4] = v.params::<14>();
    dc_common(v, [t0, t1, t2, t3, t4], t, acc, rng, 1.0, |x, y| {
        let c = fractaldots_grey((x, y), q);
        [c, c, c]
    })
}

/// dc_grid3D: a flight through a 3-D grid over [−1, 1]², zoomed, grey.
fn dc_grid3d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, _, time, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        let g = grid3d_grey(x * zoom, y * zoom, time);
        [g, g, g]
    })
}

/// dc_hoshi: the star-like folding fractal over [−1, 1]².
fn dc_hoshi(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, steps, scale, translate, tail @ ..] = v.params::<10>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        hoshi_rgb(x, y, time, steps, scale, translate)
    })
}

/// dc_hyperbolictile: the octagonal tiling of the Poincaré disc over [−1, 1]², zoomed.
fn dc_hyperbolictile(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, tail @ ..] = v.params::<6>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        let c = hyperbolic_grey(x * zoom, y * zoom);
        [c, c, c]
    })
}

/// dc_kaleidocomplex: the escape-time orbit of complex folds over [−½, ½]².
fn dc_kaleidocomplex(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, imax, fc, fr, fg, fb, tail @ ..] = v.params::<12>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        kaleidocomplex_rgb(x, y, time, imax, fc, [fr, fg, fb])
    })
}

/// dc_kaleidoscopic: the kaleidoscopic inversion fractal over [−1, 1]², zoomed.
fn dc_kaleidoscopic(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, sides, zoom, p1, radial, tail @ ..] = v.params::<11>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        kaleidoscopic_rgb((x * zoom, y * zoom), zoom, time, sides, p1, radial)
    })
}

/// dc_kaliset: Kali's circle inversions over [−1, 1]², zoomed.
fn dc_kaliset(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, zoom, n, sx, sy, tail @ ..] = v.params::<11>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        kaliset_rgb((x * zoom, y * zoom), time, [n, sx, sy])
    })
}

/// dc_kaliset2: Kali's second set over [−1, 1]², zoomed.
fn dc_kaliset2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, zoom, n, rad2, sx, sy, fr, fg, fb, tail @ ..] = v.params::<15>();
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        kaliset2_rgb(x * zoom, y * zoom, time, [n, rad2, sx, sy], [fr, fg, fb])
    })
}

/// dc_mandelbox2D: the 2-D Mandelbox's distance estimate over [−½, ½]², zoomed.
fn dc_mandelbox2d(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [zoom, _, time, tail @ ..] = v.params::<8>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        mandelbox2d_rgb(zoom * x, zoom * y, time)
    })
}

/// dc_squares: the colour flipped by four shifted Sierpiński carpets over [−½, ½]².
fn dc_squares(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, time, n, dir, fr, fg, fb, tail @ ..] = v.params::<12>();
    dc_common(v, tail, t, acc, rng, 0.5, |x, y| {
        squares_rgb(x, y, time, n, dir, [fr, fg, fb])
    })
}
