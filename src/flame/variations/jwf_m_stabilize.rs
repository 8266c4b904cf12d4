//! JWildfire's `pre_stabilize`: the xform starts from one of `n` fixed points (uniform in
//! [−1, 1]², drawn once from `seed` with Java's generator) on its first call and, with
//! probability p/1000, on each later one; otherwise the affine point passes through. With
//! `dc` the restart also sets the colour (½, then ¼, ¾, then ⅛, ⅜, …, one per point).
//!
//! The formula follows JWildfire's (LGPL-2.1) code, written anew.

use super::jwf_a_cuts::JavaRandom;
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("pre_stabilize", pre_stabilize)
    .params(&[
        p_int("pre_stabilize_n", 4.0, 1.0, 100_000.0),
        p_int("pre_stabilize_seed", 30398.0, -2147483648.0, 2147483647.0),
        p("pre_stabilize_p", 0.1),
        p_int("pre_stabilize_dc", 0.0, 0.0, 1.0),
    ])
    .flags(
        flag::JWILDFIRE
            | flag::PRE_ONLY
            | flag::RANDOM
            | flag::STATEFUL
            | flag::WRITES_Z
            | flag::SETS_COLOR,
    )
    .prepare(pre_stabilize_prepare)];

/// The state slot that holds whether the first call has been made.
const ST_STARTED: usize = 0;

/// The `n` start points and their colours, (x, y, colour) each.
fn pre_stabilize_prepare(v: &mut Prepared) {
    let [n, seed] = v.params();
    let mut r = JavaRandom::new(seed as i64);
    let (mut next, mut delta) = (0.5, 1.0);
    for _ in 0..n as usize {
        let x = r.next_f64() * 2.0 - 1.0;
        let y = r.next_f64() * 2.0 - 1.0;
        v.p.extend_from_slice(&[x, y, next]);
        next += delta;
        if next >= 1.0 {
            delta /= 2.0;
            next = delta / 2.0;
        }
    }
    v.state.set(ST_STARTED, 0.0);
}

/// pre_stabilize: a start point on the first call and at random restarts, else the point.
fn pre_stabilize(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [n, _, p, dc] = v.params();
    let first = v.state.get(ST_STARTED) == 0.0;
    let count = v.table(0).len() / 3;
    if count > 0 && (first || rng.f01() < p / 1000.0) {
        v.state.set(ST_STARTED, 1.0);
        let i = ((rng.f01() * n) as usize).min(count - 1);
        let [x, y, c] = [0, 1, 2].map(|k| v.table(3 * i)[k]);
        if dc != 0.0 {
            acc.color = c;
        }
        return [x, y, 0.0];
    }
    [t.x, t.y, t.z]
}
