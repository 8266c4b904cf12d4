//! JWildfire's line drawings by Jesus Sosa, from the end of its alphabet: the H-tree
//! `htree_js`, the Koch curve `koch_js`, Heighway's dragon `dragon_js`, Gosper's island
//! `gosperisland_js` and the Brownian bridge `brownian_js`, each built once as segments and sampled as the other drawings are
//! (along a segment, jittered by the line thickness, or at its start).
//!
//! The figures follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) constructions,
//! written anew.

use super::jwf_a_cuts::JavaRandom;
use super::jwf_drawings::{la_eval, la_store};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("htree_js", drawing)
        .params(&[
            p_int("htree_js_level", 2.0, 1.0, 10.0),
            p("htree_js_size", 2.0),
            p("htree_js_show_lines", 1.0),
            p("htree_js_line_thickness", 0.5),
            p("htree_js_show_points", 0.0),
            p("htree_js_point_thickness", 3.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0, 1], htree_segments)
        .prepare(prep_htree),
    VarDef::new("koch_js", drawing)
        .params(&[
            p_int("koch_js_level", 2.0, 1.0, 7.0),
            p_int("koch_js_show_lines", 1.0, NEG_INF, INF),
            p("koch_js_line_thickness", 0.5),
            p_int("koch_js_show_points", 0.0, NEG_INF, INF),
            p("koch_js_point_thickness", 3.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0], koch_segments)
        .prepare(prep_koch),
    VarDef::new("dragon_js", drawing)
        .params(&[
            p_int("dragon_js_level", 2.0, 1.0, 21.0),
            p("dragon_js_line_thickness", 0.5),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0], dragon_segments)
        .prepare(prep_lines_only),
    VarDef::new("gosperisland_js", drawing)
        .params(&[
            p_int("gosperisland_js_level", 2.0, 1.0, 10.0),
            p("gosperisland_js_line_thickness", 0.5),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0], gosper_segments)
        .prepare(prep_lines_only),
    VarDef::new("brownian_js", drawing)
        .params(&[
            p_int("brownian_js_level", 10.0, 1.0, 15.0),
            p("brownian_js_variation", 3.0),
            // JWildfire draws this default at random; the value of its test vectors.
            p_int("brownian_js_seed", 744.0, NEG_INF, INF),
            p("brownian_js_line_thickness", 0.5),
            p("brownian_js_show_lines", 1.0),
            p("brownian_js_show_points", 0.0),
            p("brownian_js_point_thickness", 3.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM)
        .shared(&[0, 1, 2], brownian_segments)
        .prepare(prep_brownian),
];

/// A point of the drawing (a uniformly chosen segment; JWildfire walks them in order, which
/// covers them equally over many calls).
fn drawing(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let (x, y) = la_eval(v, rng);
    [v.w * x, v.w * y, 0.0]
}

fn prep_htree(v: &mut Prepared) {
    let [_, _, lines, lt, points, pt] = v.params();
    la_store(v, lines, lt, points, pt);
}

fn prep_koch(v: &mut Prepared) {
    let [_, lines, lt, points, pt] = v.params();
    la_store(v, lines, lt, points, pt);
}

/// The drawings of lines only: every draw on a segment.
fn prep_lines_only(v: &mut Prepared) {
    let [_, lt] = v.params();
    la_store(v, 1.0, lt, 0.0, 0.0);
}

/// An H of the given size at (x, y) (its two uprights and the bar), then the four H's of half
/// the size on its corners, `n` levels deep.
fn htree(segs: &mut Vec<f64>, n: i64, x: f64, y: f64, size: f64) {
    if n == 0 {
        return;
    }
    let (x0, x1, y0, y1) = (
        x - size / 2.0,
        x + size / 2.0,
        y - size / 2.0,
        y + size / 2.0,
    );
    segs.extend_from_slice(&[x0, y0, x0, y1, x1, y0, x1, y1, x0, y, x1, y]);
    for (cx, cy) in [(x0, y0), (x0, y1), (x1, y0), (x1, y1)] {
        htree(segs, n - 1, cx, cy, size / 2.0);
    }
}

fn htree_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let [level, size] = params_of(q);
    let mut segs = Vec::new();
    htree(&mut segs, level as i64, 0.0, 0.0, size);
    segs
}

/// A turtle recording each step as a segment; angles in degrees.
struct Pen {
    x: f64,
    y: f64,
    heading: f64,
    segs: Vec<f64>,
}

impl Pen {
    fn at(x: f64, y: f64) -> Pen {
        Pen {
            x,
            y,
            heading: 0.0,
            segs: Vec::new(),
        }
    }

    fn forward(&mut self, step: f64) {
        let (x0, y0) = (self.x, self.y);
        let a = self.heading.to_radians();
        self.x += step * a.cos();
        self.y += step * a.sin();
        self.segs.extend_from_slice(&[x0, y0, self.x, self.y]);
    }

    fn left(&mut self, degrees: f64) {
        self.heading += degrees;
    }

    /// The Koch curve of order n with steps of `step`.
    fn koch(&mut self, n: i64, step: f64) {
        if n == 0 {
            self.forward(step);
            return;
        }
        self.koch(n - 1, step);
        self.left(60.0);
        self.koch(n - 1, step);
        self.left(-120.0);
        self.koch(n - 1, step);
        self.left(60.0);
        self.koch(n - 1, step);
    }

    /// Heighway's dragon of order n (`turn` 90) or its mirror image (−90), unit steps.
    fn dragon(&mut self, n: i64, turn: f64) {
        if n == 0 {
            self.forward(1.0);
            return;
        }
        self.dragon(n - 1, 90.0);
        self.left(turn);
        self.dragon(n - 1, -90.0);
    }

    /// Gosper's curve of order n, unit steps.
    fn gosper(&mut self, n: i64) {
        // arccos(5·√7/14), in degrees.
        const ANGLE: f64 = 19.106_605_350_869_094;
        if n == 0 {
            self.forward(1.0);
            return;
        }
        self.left(-ANGLE);
        self.gosper(n - 1);
        self.left(60.0);
        self.gosper(n - 1);
        self.left(-60.0);
        self.gosper(n - 1);
        self.left(ANGLE);
    }
}

fn koch_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let [level] = params_of(q);
    let mut pen = Pen::at(0.0, 0.0);
    pen.koch(level as i64, 0.5);
    pen.segs
}

fn dragon_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let [level] = params_of(q);
    let mut pen = Pen::at(0.0, 0.0);
    pen.dragon(level as i64, 90.0);
    pen.segs
}

/// Gosper's island: six Gosper curves turned 60° apart, from (9/32, 1/8).
fn gosper_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let [level] = params_of(q);
    let mut pen = Pen::at(9.0 / 32.0, 1.0 / 8.0);
    for _ in 0..6 {
        pen.gosper(level as i64);
        pen.left(60.0);
    }
    pen.segs
}

/// brownian_js's sampling: its show_lines and show_points weights are not truncated.
fn prep_brownian(v: &mut Prepared) {
    let [_, _, _, lt, lines, points, pt] = v.params();
    let line_part = lines / (lines + points);
    let derived = [
        line_part,
        line_part + points / (lines + points),
        lt / 100.0,
        pt / 100.0,
    ];
    v.p.extend_from_slice(&derived);
}

/// A standard normal number by the polar Box–Muller method on Java's generator.
fn gaussian(g: &mut JavaRandom) -> f64 {
    loop {
        let x = -1.0 + g.next_f64() * 2.0;
        let y = -1.0 + g.next_f64() * 2.0;
        let r = x * x + y * y;
        if r < 1.0 && r != 0.0 {
            return x * (-2.0 * r.ln() / r).sqrt();
        }
    }
}

/// A Brownian bridge from (x0, y0) to (x1, y1) by midpoint displacement: the midpoint moved by
/// normal numbers of variance `var`, the halves refined with var/2.7, `n` levels deep.
fn midpoint(
    segs: &mut Vec<f64>,
    g: &mut JavaRandom,
    a: (f64, f64),
    b: (f64, f64),
    var: f64,
    n: i64,
) {
    if n == 0 {
        segs.extend_from_slice(&[a.0, a.1, b.0, b.1]);
        return;
    }
    let xm = 0.5 * (a.0 + b.0) + gaussian(g) * var.sqrt();
    let ym = 0.5 * (a.1 + b.1) + gaussian(g) * var.sqrt();
    midpoint(segs, g, a, (xm, ym), var / 2.7, n - 1);
    midpoint(segs, g, (xm, ym), b, var / 2.7, n - 1);
}

/// brownian_js's closed Brownian loop from the origin (Java's generator seeded with `seed`;
/// JWildfire seeds a seed of 0 with the clock, which this takes as 0).
fn brownian_segments(q: &[f64], _: &[String]) -> Vec<f64> {
    let [level, variation, seed] = params_of(q);
    let mut g = JavaRandom::new(seed as i64);
    let mut segs = Vec::new();
    let var = variation / 2f64.sqrt();
    midpoint(&mut segs, &mut g, (0.0, 0.0), (0.0, 0.0), var, level as i64);
    segs
}
