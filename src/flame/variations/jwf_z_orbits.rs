//! JWildfire's orbits and curves of the plane, from the end of its alphabet: the orbits
//! `gumowski_mira` (the Gumowski–Mira map), `starfractal` (a star IFS driven by Java's
//! generator) and `sphtiling3v2` (a spherical tiling's IFS), each carried from call to call,
//! the symmetric icons `iconattractor_js` and the harmonograph `harmonograph_js`.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew.

use std::f64::consts::PI;

use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("gumowski_mira", gumowski_mira)
        .params(&[
            p_int("gumowski_mira_random", 1.0, 0.0, 10_000_000.0),
            p_range("gumowski_mira_step", 0.001, 0.0, 1.0),
            p("gumowski_mira_a", 1e-6),
            p("gumowski_mira_b", 0.05),
        ])
        .flags(flag::JWILDFIRE | flag::STATEFUL | flag::OWN_ORBIT | flag::WRITES_ACC),
    VarDef::new("starfractal", starfractal)
        .params(&[p_int("starfractal_m", 3.0, 3.0, 10.0)])
        .flags(flag::JWILDFIRE | flag::STATEFUL | flag::OWN_ORBIT | flag::WRITES_ACC),
    VarDef::new("iconattractor_js", iconattractor_js)
        .params(&[
            p_int("iconattractor_js_presetId", 8.0, 0.0, INF),
            p_int("iconattractor_js_degree", 7.0, 3.0, 50.0),
            p("iconattractor_js_a", 1.0),
            p("iconattractor_js_b", -0.1),
            p("iconattractor_js_g", 0.167),
            p("iconattractor_js_o", 0.0),
            p("iconattractor_js_l", -2.08),
            p("iconattractor_js_centerx", 0.0),
            p("iconattractor_js_centery", 0.0),
            p("iconattractor_js_scale", 5.0),
        ])
        .flags(flag::JWILDFIRE | flag::WRITES_ACC | flag::SETS_COLOR),
    VarDef::new("sphtiling3v2", sphtiling3v2)
        .params(&[
            p("sphtiling3v2_a", 0.5),
            p("sphtiling3v2_b", 1.0),
            p("sphtiling3v2_c", 1.0),
            p("sphtiling3v2_d", 0.5),
            p("sphtiling3v2_e", 1.0),
            p("sphtiling3v2_f", 0.5),
            p_int("sphtiling3v2_dc", 1.0, 0.0, 1.0),
            p("sphtiling3v2_dc1", 0.3),
            p("sphtiling3v2_dc2", 0.5),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::STATEFUL | flag::SETS_COLOR),
    VarDef::new("harmonograph_js", harmonograph_js)
        .params(&[
            // JWildfire derives the pendulums from `seed` and draws the dampings at random;
            // the values of its test vectors.
            p_int("harmonograph_js_seed", 1234.0, NEG_INF, INF),
            p_int("harmonograph_js_time", 100.0, NEG_INF, INF),
            p_int("harmonograph_js_a1", 128.0, NEG_INF, INF),
            p("harmonograph_js_f1", 5.0),
            p_int("harmonograph_js_p1", 113.0, NEG_INF, INF),
            p("harmonograph_js_d1", 0.001452731521014341),
            p_int("harmonograph_js_a2", 0.0, NEG_INF, INF),
            p("harmonograph_js_f2", 3.0),
            p_int("harmonograph_js_p2", 33.0, NEG_INF, INF),
            p("harmonograph_js_d2", 0.0012305454649908978),
            p_int("harmonograph_js_a3", 49.0, NEG_INF, INF),
            p("harmonograph_js_f3", -4.0),
            p_int("harmonograph_js_p3", 57.0, NEG_INF, INF),
            p("harmonograph_js_d3", 0.001125847401961281),
            p_int("harmonograph_js_a4", 97.0, NEG_INF, INF),
            p("harmonograph_js_f4", 1.0),
            p_int("harmonograph_js_p4", 68.0, NEG_INF, INF),
            p("harmonograph_js_d4", 0.000813864334409786),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM),
];

/// gumowski_mira: the Gumowski–Mira map x' = y + a·(1 − b·y²)·y + f(x), y' = −x + f(x'),
/// f(x) = m·x + 2(1 − m)·x²/(1 + x²), from (5, 5), one step a call, replacing the sum so far.
/// m is −0.08 raised by JWildfire's parameter setting: twice (random > 1) or half (else) the
/// initial step 0.001, then the step itself.
fn gumowski_mira(v: &Prepared, _: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [random, step, a, b] = v.params();
    let m = -0.08 + if random > 1.0 { 0.002 } else { 0.0005 } + step;
    let mira = |x: f64| m * x + (2.0 * (1.0 - m) * x * x) / (1.0 + x * x);
    let st = &v.state;
    let (x0, y0) = if st.get(3) == 1.0 {
        (st.get(0), st.get(1))
    } else {
        (5.0, 5.0)
    };
    let xn = y0 + (a * (1.0 - b * y0 * y0) * y0) + mira(x0);
    let yn = -x0 + mira(xn);
    st.set(0, xn);
    st.set(1, yn);
    st.set(3, 1.0);
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [v.w * xn, v.w * yn, 0.0]
}

/// gumowski_mira's seed and `a` as JWildfire 9.00 renders a flame read from a file, from the
/// file's seed (`gumowski_mira_random`). `GumowskiMiraFunc.setParameter` ignores the `a` it is
/// given: it draws a = 10⁻⁶ + (10⁻⁶ − 10⁻⁸)·u with u the first `nextDouble()` of Java's
/// generator seeded with the seed, which it then raises by one, and a copy of the variation
/// is given the raised seed. JWildfire's file reader sets every parameter twice (the second
/// time from the file again), its command-line renderer renders a copy of the flame read and
/// each render thread a copy of that copy: the threads draw `a` with seed + 2 and hold
/// seed + 3. Returns (seed + 3, a); the seed as Java's `(int)` of the value limited to
/// [0, 10⁷].
pub fn gumowski_mira_rendered(random: f64) -> (f64, f64) {
    let seed = i64::from(super::util::trunc_i32(random.clamp(0.0, 10_000_000.0)));
    let u = super::jwf_a_cuts::JavaRandom::new(seed + 2).next_f64();
    ((seed + 3) as f64, 1e-6 + (1e-6 - 1e-8) * u)
}

/// Java's `java.util.Random` carried in a variation's state (slot 4 holds its 48 bits, slot 5
/// marks it seeded), for the variations whose sequence of draws is part of their picture.
struct JavaLcg(u64);

impl JavaLcg {
    const MULT: u64 = 0x5_DEEC_E66D;
    const MASK: u64 = (1 << 48) - 1;

    /// The generator in `v`'s state, or a new one seeded with `seed`.
    fn load(v: &Prepared, seed: i64) -> JavaLcg {
        if v.state.get(5) == 1.0 {
            JavaLcg(v.state.get(4).to_bits())
        } else {
            JavaLcg((seed as u64 ^ Self::MULT) & Self::MASK)
        }
    }

    fn store(&self, v: &Prepared) {
        v.state.set(4, f64::from_bits(self.0));
        v.state.set(5, 1.0);
    }

    /// `nextInt()`: 32 bits as a signed number.
    fn next_i32(&mut self) -> i32 {
        self.0 = (self.0.wrapping_mul(Self::MULT).wrapping_add(0xB)) & Self::MASK;
        (self.0 >> 16) as u32 as i32
    }
}

/// starfractal: an orbit of the "star" IFS of m-fold symmetry: from (1, 1), each call inverts
/// the point, scales it by 1/3 (conjugated), moves it to one of 2m targets (the m-th roots of
/// unity and the midpoints between them, picked by Java's generator seeded with 1000) and
/// inverts again; replaces the sum so far.
fn starfractal(v: &Prepared, _: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [m] = v.params();
    let st = &v.state;
    let (x, y) = if st.get(3) == 1.0 {
        (st.get(0), st.get(1))
    } else {
        (1.0, 1.0)
    };
    let mut g = JavaLcg::load(v, 1000);
    let c = (g.next_i32().unsigned_abs() % (2 * m as u32)) as usize;
    g.store(v);
    let i = (c / 2) as f64;
    let (a, b) = if c.is_multiple_of(2) {
        let ang = 2.0 * PI * (i + 1.0) / m;
        (ang.cos(), ang.sin())
    } else {
        let (a1, a0) = (2.0 * PI * (i + 1.0) / m, 2.0 * PI * i / m);
        (0.5 * (a1.cos() + a0.cos()), 0.5 * (a1.sin() + a0.sin()))
    };
    let x1 = (x / (x * x + y * y)) / 3.0 + a;
    let y1 = (-y / (x * x + y * y)) / 3.0 + b;
    let d = x1 * x1 + y1 * y1;
    let (x, y) = (x1 / d, y1 / d);
    st.set(0, x);
    st.set(1, y);
    st.set(3, 1.0);
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [v.w * x, v.w * y, 0.0]
}

/// Two damped pendulums a·sin(t·f + p°)·e^(−d·t) summed.
fn pendulums(t: f64, q: &[f64]) -> f64 {
    let swing =
        |a: f64, f: f64, ph: f64, d: f64| a * (t * f + ph * PI / 180.0).sin() * (-d * t).exp();
    swing(q[0], q[1], q[2], q[3]) + swing(q[4], q[5], q[6], q[7])
}

/// harmonograph_js (Jesus Sosa): the trace of a harmonograph at a uniform time in [0, time):
/// x from the first two pendulums, y from the other two (their phases a quarter turn on),
/// over 180.
fn harmonograph_js(v: &Prepared, _: &VarIn, _: &mut Acc, rng: &mut FastRng) -> V3 {
    let q: [f64; 18] = v.params();
    let t = rng.f01() * q[1].trunc();
    let mut qy: [f64; 8] = q[10..18].try_into().expect("8 values");
    qy[2] += 90.0;
    qy[6] += 90.0;
    let x = pendulums(t, &q[2..10]) / 180.0;
    let y = pendulums(t, &qy) / 180.0;
    [v.w * x, v.w * y, 0.0]
}

/// iconattractor_js: one step of Field and Golubitsky's symmetric icon map of `degree`
/// (z ↦ (l + a·|z|² + b·Re zⁿ)·z + g·conj(zⁿ⁻¹) + i·o·z), replacing the sum so far; the colour
/// is the result's squared distance from (−centerx, −centery) over `scale`, modulo 1.
fn iconattractor_js(v: &Prepared, t: &VarIn, acc: &mut Acc, _: &mut FastRng) -> V3 {
    let [_, degree, a, b, g, o, l, cx, cy, scale] = v.params();
    let (x, y) = (t.x, t.y);
    let mut p = a * (x * x + y * y) + l;
    let (mut zr, mut zi) = (x, y);
    for _ in 1..=(degree as i64 - 2) {
        (zr, zi) = (zr * x - zi * y, zi * x + zr * y);
    }
    p += b * (x * zr - y * zi);
    let ox = v.w * (p * x + g * zr - o * y);
    let oy = v.w * (p * y - g * zi + o * x);
    let bdcs = 1.0 / if scale == 0.0 { 10e-6 } else { scale };
    acc.color = (bdcs * ((ox + cx).powi(2) + (oy + cy).powi(2))).abs() % 1.0;
    if v.form == Form::Regular {
        acc.x = 0.0;
        acc.y = 0.0;
    }
    [ox, oy, 0.0]
}

/// sphtiling3v2: an orbit (carried from call to call, from the origin) of a spherical
/// tiling's IFS: with odds `a` a spherical inversion of weight c about one of three points at
/// distance b/(√3/2), else a spherical inversion of weight e followed by the skew map of d, f;
/// the colour tells the input's half-plane (dc1 right, dc2 left).
fn sphtiling3v2(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    const SQRT3_2: f64 = 0.866_025_403_784_438_6;
    let [a, b, c, d, e, f, dc, dc1, dc2] = v.params();
    let st = &v.state;
    let (x, y) = (st.get(0), st.get(1));
    let spherical = |x: f64, y: f64, w: f64| {
        let r = w / (x * x + y * y + 1e-300);
        (x * r, y * r)
    };
    let (ux, uy) = if rng.f01() < a {
        let n = (3.0 * rng.f01()).floor();
        let r = b / SQRT3_2;
        let ang = n * 2.0 * PI / 3.0;
        let (x0, y0) = (r * ang.cos(), r * ang.sin());
        let (sx, sy) = spherical(x - x0, y - y0, c);
        (sx + x0, sy + y0)
    } else {
        let (sx, sy) = spherical(x, y, e);
        (
            0.0411259 * (sx * f - sy * SQRT3_2),
            0.0411259 * (sx * SQRT3_2 + sy * d),
        )
    };
    if dc == 1.0 {
        acc.color = if t.x < 0.0 { dc2 } else { dc1 };
    }
    st.set(0, ux);
    st.set(1, uy);
    [v.w * ux, v.w * uy, 0.0]
}
