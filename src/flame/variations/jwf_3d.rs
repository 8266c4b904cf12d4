//! JWildfire's 3-D variations: `exblur`, `glitchy1`, `pyramid`, `plane_wf`, the polar plots of
//! `polarplot3d_wf` and the diffusion-limited aggregate of `dla3d_wf`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: `atan_xy` is its `getPrecalcAtan`
//! (atan2(x, y)), weights multiply the output linearly, integer parameters are rounded (those it
//! truncates, `(int) value`, are stored as reals and truncated where used), and random numbers
//! are drawn in the order JWildfire draws them, so that the tests can replay JWildfire's own code
//! on the same stream.

use std::collections::HashMap;
use std::f64::consts::{PI, TAU};

use super::util::{Draw, Mwc, formula, wang_hash};
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("exblur", exblur)
        .params(&[
            p("exblur_dist", 0.5),
            p("exblur_r", 0.0),
            p("exblur_x_origin", 0.0),
            p("exblur_y_origin", 0.0),
            p("exblur_z_origin", 0.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::STATEFUL | flag::USES_Z | flag::WRITES_Z)
        .prepare(exblur_prepare),
    VarDef::new("glitchy1", glitchy1)
        .params(&[
            p("glitchy1_scale_x", 1.0),
            p("glitchy1_shift_x", 0.0),
            p_int("glitchy1_n_x", 2.0, 1.0, 100.0),
            p("glitchy1_scale_y", 1.0),
            p("glitchy1_shift_y", 0.0),
            p_int("glitchy1_n_y", 2.0, 1.0, 100.0),
            p("glitchy1_scale_z", 0.0),
            p("glitchy1_shift_z", 0.0),
            p_int("glitchy1_n_z", 2.0, 1.0, 100.0),
            p("glitchy1_width", 1.0),
            p_int("glitchy1_seed", 42.0, NEG_INF, INF),
            p("glitchy1_angle", 30.0),
            p("glitchy1_u", 1.0),
            p("glitchy1_v", 1.0),
            p("glitchy1_w", 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z)
        .prepare(glitchy1_prepare),
    VarDef::new("pyramid", pyramid).flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z),
    VarDef::new("plane_wf", plane_wf)
        .params(&[
            p("plane_wf_position", 3.0),
            p("plane_wf_size", 10.0),
            p_int("plane_wf_axis", 2.0, 0.0, 2.0),
            p_int("plane_wf_direct_color", 1.0, 0.0, 1.0),
            p_int("plane_wf_color_mode", 3.0, 0.0, 3.0),
            p_int("plane_wf_blend_colormap", 1.0, 0.0, 1.0),
            p("plane_wf_displ_amount", 0.1),
            p_int("plane_wf_blend_displ_map", 1.0, 0.0, 1.0),
            p_int("plane_wf_calc_color_idx", 0.0, 0.0, 1.0),
            p_int("plane_wf_receive_only_shadows", 0.0, 0.0, 1.0),
        ])
        .flags(
            flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::USES_COLOR,
        ),
    VarDef::new("polarplot3d_wf", polarplot3d_wf)
        .params(&[
            p_int("polarplot3d_wf_preset_id", 2.0, NEG_INF, INF),
            p("polarplot3d_wf_tmin", -PI),
            p("polarplot3d_wf_tmax", PI),
            p("polarplot3d_wf_umin", 0.0),
            p("polarplot3d_wf_umax", PI),
            p("polarplot3d_wf_rmin", -2.0),
            p("polarplot3d_wf_rmax", 2.0),
            p_int("polarplot3d_wf_cylindrical", 0.0, NEG_INF, INF),
            p_int("polarplot3d_wf_direct_color", 1.0, NEG_INF, INF),
            p_int("polarplot3d_wf_color_mode", 2.0, NEG_INF, INF),
            p_int("polarplot3d_wf_blend_colormap", 1.0, 0.0, 1.0),
            p("polarplot3d_wf_displ_amount", 0.1),
            p_int("polarplot3d_wf_blend_displ_map", 1.0, 0.0, 1.0),
            p("polarplot3d_wf_param_a", 0.0),
            p("polarplot3d_wf_param_b", 0.0),
            p("polarplot3d_wf_param_c", 0.0),
            p("polarplot3d_wf_param_d", 0.0),
            p("polarplot3d_wf_param_e", 0.0),
            p("polarplot3d_wf_param_f", 0.0),
        ])
        .flags(
            flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::USES_COLOR,
        )
        .texts(POLAR_TEXTS)
        .prepare(polarplot_prepare)
        .shared(&[], polar_formula),
    VarDef::new("dla3d_wf", dla3d_wf)
        .params(P_DLA)
        .flags(
            flag::JWILDFIRE
                | flag::RANDOM
                | flag::STATEFUL
                | flag::WRITES_Z
                | flag::SETS_COLOR
                | flag::HIDES,
        )
        .prepare(dla_prepare)
        .shared(&[0, 1, 6, 7, 8, 9], dla_nodes),
];

/// Seeds the four carried random values (JWildfire draws them from the render's generator when
/// the variation is initialised; any uniform values serve).
fn exblur_prepare(v: &mut Prepared) {
    let mut r = FastRng::new(0x6578_626c_7572);
    for i in 0..4 {
        v.state.set(i, r.f01());
    }
}

/// exblur: a 3-D blur around an origin: the point's direction (spherical angles about the
/// origin) scaled by |p - o|^(2·dist) times a smooth random factor (the sum of the last four
/// uniform draws, minus 2), plus a random sphere of relative radius r.
fn exblur(v: &Prepared, t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [dist, r, x_origin, y_origin, z_origin] = v.params();
    let ox = t.x - x_origin;
    let oy = t.y + y_origin;
    let oz = t.z - z_origin;
    let n = ox * ox + oy * oy + oz * oz;
    let (s0, s1, s2, s3) = (
        v.state.get(0),
        v.state.get(1),
        v.state.get(2),
        v.state.get(3),
    );
    let rr = v.w * n.powf(dist) * (s0 + s1 + s2 + s3 - 2.0);
    let theta = oy.atan2(ox);
    let phi = (oz / n.sqrt()).acos();
    let (su, cu) = theta.sin_cos();
    let (sv, cv) = phi.sin_cos();
    let (sru, cru) = (rng.f01() * TAU).sin_cos();
    let (srv, crv) = (rng.f01() * TAU).sin_cos();
    // The oldest of the four values gives way to a new draw.
    v.state.set(0, s1);
    v.state.set(1, s2);
    v.state.set(2, s3);
    v.state.set(3, rng.f01());
    let rsrv = r * srv;
    [
        rr * (sv * cu + rsrv * cru),
        rr * (sv * su + rsrv * sru),
        rr * (cv + r * crv),
    ]
}

fn glitchy1_prepare(v: &mut Prepared) {
    let [_, _, _, _, _, _, _, _, _, _, _, angle] = v.params();
    let a = angle.to_radians();
    v.p.push(a.sin());
    v.p.push(a.cos());
}

/// Mirrors `c` about `shift` in every `n`-th band of width 1/scale (glitchy1's folding).
fn glitch_fold(c: f64, scale: f64, shift: f64, n: f64) -> f64 {
    if scale == 0.0 {
        return c;
    }
    let band = ((c - shift) * scale).floor() as i32 as f64;
    let flip = if band >= 0.0 {
        band % n == n - 1.0
    } else {
        band % n == 0.0
    };
    if flip { 2.0 * shift - c } else { c }
}

/// glitchy1: folds x, y, z in periodic bands and scales the point by a hash of the rotated
/// block it falls in, giving blocky, glitch-like stretches.
fn glitchy1(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [
        scale_x,
        shift_x,
        n_x,
        scale_y,
        shift_y,
        n_y,
        scale_z,
        shift_z,
        n_z,
        width,
        seed,
        _angle,
        u,
        v_scale,
        w_scale,
    ] = v.params();
    let [h, k] = v.derived();
    let x = glitch_fold(t.x, scale_x, shift_x, n_x);
    let y = glitch_fold(t.y, scale_y, shift_y, n_y);
    let z = glitch_fold(t.z, scale_z, shift_z, n_z);
    let seed = seed as i32;
    let uu = u * t.x;
    let vv = v_scale * (k * uu + h * t.y);
    let ww = w_scale * (k * uu - h * t.y);
    let block = |c: f64| -> i32 {
        let b = (c * width).floor() as i32;
        (b as f64 + (2.0 - 4.0 * wang_hash(b.wrapping_mul(seed).wrapping_add(1)))) as i32
    };
    let (bu, bv, bw) = (block(uu), block(vv), block(ww));
    let base = bu.wrapping_add(bv);
    let len = wang_hash(base.wrapping_add(bw.wrapping_mul(seed.wrapping_neg())))
        + wang_hash(base.wrapping_add(bw.wrapping_mul(seed) / 2));
    let s = v.w * len;
    [s * x, s * y, s * z]
}

/// pyramid: cubes the coordinates (|z|³ for z) and normalises them by their L1 norm, pushing
/// points onto the surface of an octahedron-like pyramid.
fn pyramid(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let x = t.x * t.x * t.x;
    let y = t.y * t.y * t.y;
    let z = (t.z * t.z * t.z).abs();
    let r = v.w / (x.abs() + y.abs() + z + 1e-9);
    [x * r, y * r, z * r]
}

/// plane_wf: a uniformly filled square of side `size` in the xy, yz or zx plane, placed at
/// `position` along the remaining axis; the colour can follow the square's u, v or u·v
/// coordinate. (JWildfire's colour-map and displacement-map images are not supported.)
fn plane_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [position, size, axis, direct_color, color_mode] = v.params();
    let a = 0.5 - rng.f01();
    let b = 0.5 - rng.f01();
    // (u, v) of the colour modes and the output.
    let (u, w, out) = match axis as i32 {
        0 => (a, b, [a * size, b * size, position]),
        1 => (a, b, [position, a * size, b * size]),
        _ => (b, a, [a * size, position, b * size]),
    };
    if direct_color > 0.0 {
        let c = match color_mode as i32 {
            0 => acc.color,
            2 => w + 0.5,
            3 => (w + 0.5) * (u + 0.5),
            _ => u + 0.5,
        };
        acc.color = c.clamp(0.0, 1.0);
    }
    [v.w * out[0], v.w * out[1], v.w * out[2]]
}

fn polarplot_prepare(v: &mut Prepared) {
    let sorted = |a: f64, b: f64| if a > b { (b, a - b) } else { (a, b - a) };
    let [_, t0, t1, u0, u1, r0, r1] = v.params();
    let (tmin, dt) = sorted(t0, t1);
    let (umin, du) = sorted(u0, u1);
    let (rmin, dr) = sorted(r0, r1);
    v.p.extend_from_slice(&[tmin, dt, umin, du, rmin, dr]);
}

const POLAR_TEXTS: &[TextParam] = &[TextParam {
    name: "polarplot3d_wf_formula",
    default: "",
    max_len: 4000,
}];

/// The names a polarplot3d_wf formula reads, in the order [`polarplot3d_wf`] passes them.
const POLAR_VARS: &[&str] = &[
    "t", "u", "pi", "param_a", "param_b", "param_c", "param_d", "param_e", "param_f",
];

/// polarplot3d_wf's own formula compiled ([`formula::compile`]) after a leading 1; `[0]` when
/// it does not compile (JWildfire refuses it and the variation draws nothing); `[2]` without
/// one (the stock formula of the preset id applies).
fn polar_formula(_p: &[f64], texts: &[String]) -> Vec<f64> {
    let text = texts.first().map_or("", |t| t.trim());
    if text.is_empty() {
        return vec![2.0];
    }
    match formula::compile(text, POLAR_VARS) {
        Ok(code) => std::iter::once(1.0).chain(code).collect(),
        Err(_) => vec![0.0],
    }
}

/// The radius r(t, u) of polarplot3d_wf's stock formula `preset` (JWildfire's presets 0–9) with
/// parameters a, b, c; `None` for other ids (custom formulas, which ugnis cannot read).
fn polar_preset(preset: f64, t: f64, u: f64, a: f64, b: f64, c: f64) -> Option<f64> {
    Some(match preset as i32 {
        0 | 1 => (a * u).sin() + b,
        2 => u,
        3 => ((a * t).sin() + (b * u).cos()) + c,
        4 | 5 => (a * t + b * u).sin() + c,
        6 => (a * t).sin() + b * u,
        7 => t / (a + u) + b,
        8 => u * u + a,
        9 => (a * t + (b * u).sin()).cos() + c,
        _ => return None,
    })
}

/// polarplot3d_wf: a surface r = f(t, u) in spherical coordinates (t the azimuth, u the polar
/// angle) or cylindrical ones (r·cos t, r·sin t, u), sampled at uniformly random (t, u); the
/// colour can follow t, u, r or t·u. The formula is the flame's own text (a Java expression over
/// t, u, pi and param_a…param_f) or, without one, the stock formula of the preset id.
fn polarplot3d_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        preset_id,
        _tmin,
        _tmax,
        _umin,
        _umax,
        _rmin,
        _rmax,
        cylindrical,
        direct_color,
        color_mode,
        _blend_colormap,
        _displ_amount,
        _blend_displ_map,
        param_a,
        param_b,
        param_c,
        param_d,
        param_e,
        param_f,
    ] = v.params();
    let [tmin, dt, umin, du, rmin, dr] = v.derived();
    let rt = rng.f01();
    let ru = rng.f01();
    let t = tmin + rt * dt;
    let u = umin + ru * du;
    let r = match v.data() {
        [2.0] => polar_preset(preset_id, t, u, param_a, param_b, param_c),
        [1.0, code @ ..] => {
            let vars = [
                t, u, PI, param_a, param_b, param_c, param_d, param_e, param_f,
            ];
            Some(formula::run(code, &vars))
        }
        _ => None,
    };
    let Some(r) = r else {
        return [0.0; 3];
    };
    let (st, ct) = t.sin_cos();
    let out = if cylindrical == 0.0 {
        let (su, cu) = u.sin_cos();
        [r * su * ct, r * su * st, r * cu]
    } else {
        [r * ct, r * st, u]
    };
    if direct_color > 0.0 {
        let c = match color_mode as i32 {
            1 => (t - tmin) / dt,
            2 => (u - umin) / du,
            3 => (r - rmin) / dr,
            4 => (t - tmin) / dt * (u - umin) / du,
            _ => acc.color,
        };
        acc.color = c.clamp(0.0, 1.0);
    }
    [v.w * out[0], v.w * out[1], v.w * out[2]]
}

/// Values stored per aggregate node: x, y, z, relative depth, has-parent flag, then the
/// parent's x, y, z and relative depth.
const DLA_STRIDE: usize = 9;

/// Gives up growing after this many walkers in a row found nothing (a degenerate seed makes
/// every walker escape; JWildfire would loop forever).
const DLA_MAX_MISSES: usize = 100_000;

/// Gives up growing after this many walker steps in all (parameters that keep walkers
/// wandering, e.g. a force cancelling their moves, would otherwise take hours).
const DLA_MAX_STEPS: u64 = 10_000_000;

/// Most nodes of the aggregate (the node count is a table size; the step budget above ends the
/// growth long before a larger one).
const DLA_MAX_NODES: f64 = 20_000.0;

/// Largest drift per step: a walker drifting further than this leaves the cluster at once.
const DLA_MAX_FORCE: f64 = 1000.0;

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
        let most = (DLA_NEAR_CELLS as f64).cbrt().round() as i64;
        if want <= self.side || want > most {
            return;
        }
        // At least half as wide again: a cluster growing node by node marks its cells a few
        // times, not at every node (the grid only speeds the search up; any size finds the
        // same nodes).
        let want = want.max(self.side + self.side / 2).min(most);
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
/// dla3d_wf's own generator (state slot 0): JWildfire's Marsaglia generator seeded with
/// `seed` when the variation is initialised, so that the samples follow JWildfire's sequence.
fn dla_prepare(v: &mut Prepared) {
    let [_, seed] = v.params();
    v.state
        .set(0, f64::from_bits(Mwc::new(seed as i64).to_bits()));
}

/// A sample of the aggregate drawn with the variation's own generator (JWildfire draws every
/// number of dla3d_wf from it, none from the render's).
fn dla3d_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, _, _, _, _, dc_color] = v.params();
    let mut g = Mwc::from_bits(v.state.get(0).to_bits());
    let sample = dla_sample(v, v.data(), &mut g);
    v.state.set(0, f64::from_bits(g.to_bits()));
    match sample {
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
    p_int("dla3d_wf_max_iter", 320.0, INT_ANY.0, DLA_MAX_NODES).limited(),
    p_int("dla3d_wf_seed", 1234.0, INT_ANY.0, INT_ANY.1),
    p("dla3d_wf_inner_blur_radius", 0.5),
    p("dla3d_wf_outer_blur_radius", 0.01),
    p("dla3d_wf_junction_scale", 1.4),
    p_int("dla3d_wf_dc_color", 1.0, INT_ANY.0, INT_ANY.1),
    p("dla3d_wf_glue_radius", 1.0),
    p_range("dla3d_wf_force_x", 0.0, -DLA_MAX_FORCE, DLA_MAX_FORCE),
    p_range("dla3d_wf_force_y", 0.0, -DLA_MAX_FORCE, DLA_MAX_FORCE),
    p_range("dla3d_wf_force_z", 0.0, -DLA_MAX_FORCE, DLA_MAX_FORCE),
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

#[cfg(test)]
mod tests;
