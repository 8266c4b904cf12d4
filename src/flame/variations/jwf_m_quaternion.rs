//! Zephyrtronium's quaternion functions as Brad Stefanov combined them in JWildfire's
//! `quaternion`: the sum of cos, cosh, cot, coth, csc, csch, exp, log, sec, sech, tan, tanh,
//! sin and sinh of the point taken as the quaternion x + (y, z)·i (each with its power and
//! the detuning factors x1, x2, y1, y2, z1, z2 of its parts).
//!
//! JWildfire's table maths (`jwf_math`) throughout: near the origin |v| divides.
//!
//! The formulas follow JWildfire's (LGPL-2.1) code, written anew.

use std::f64::consts::E;

use super::util::jwf_math as jm;
use super::*;

/// The power and six detuning factors of one function, named `quaternion_<f>q…`.
macro_rules! q7 {
    ($f:literal) => {
        [
            p(concat!("quaternion_", $f, "qpow"), 0.0),
            p(concat!("quaternion_", $f, "qx1"), 1.0),
            p(concat!("quaternion_", $f, "qx2"), 1.0),
            p(concat!("quaternion_", $f, "qy1"), 1.0),
            p(concat!("quaternion_", $f, "qy2"), 1.0),
            p(concat!("quaternion_", $f, "qz1"), 1.0),
            p(concat!("quaternion_", $f, "qz2"), 1.0),
        ]
    };
}

/// The 92 parameters in JWildfire's order.
static PARAMS: [Param; 92] = {
    let groups: [[Param; 7]; 6] = [
        q7!("cos"),
        q7!("cosh"),
        q7!("cot"),
        q7!("coth"),
        q7!("csc"),
        q7!("csch"),
    ];
    let tail: [[Param; 7]; 6] = [
        q7!("sec"),
        q7!("sech"),
        q7!("sin"),
        q7!("sinh"),
        q7!("tan"),
        q7!("tanh"),
    ];
    let middle = [
        p("quaternion_estiqpow", 0.0),
        p("quaternion_estiqx1", 1.0),
        p("quaternion_estiqy1", 1.0),
        p("quaternion_estiqy2", 1.0),
        p("quaternion_estiqz1", 1.0),
        p("quaternion_estiqz2", 1.0),
        p("quaternion_logqpow", 0.0),
        p("quaternion_logqbase", E),
    ];
    let mut out = [p("", 0.0); 92];
    let mut i = 0;
    while i < 42 {
        out[i] = groups[i / 7][i % 7];
        i += 1;
    }
    while i < 50 {
        out[i] = middle[i - 42];
        i += 1;
    }
    while i < 92 {
        out[i] = tail[(i - 50) / 7][(i - 50) % 7];
        i += 1;
    }
    // JWildfire's default: the cosine alone.
    out[0] = p("quaternion_cosqpow", 1.0);
    out
};

pub(super) static DEFS: &[VarDef] = &[VarDef::new("quaternion", quaternion)
    .params(&PARAMS)
    .flags(flag::JWILDFIRE | flag::USES_Z | flag::WRITES_Z)];

/// Where each function's seven values start.
const COS: usize = 0;
const COSH: usize = 7;
const COT: usize = 14;
const COTH: usize = 21;
const CSC: usize = 28;
const CSCH: usize = 35;
const ESTI: usize = 42;
const LOG: usize = 48;
const SEC: usize = 50;
const SECH: usize = 57;
const SIN: usize = 64;
const SINH: usize = 71;
const TAN: usize = 78;
const TANH: usize = 85;

/// The parts a function needs: sin and cos of its "real" argument (x or |v|), sinh and cosh
/// of its other one, and |v|·z1.
struct Parts {
    s: f64,
    c: f64,
    sh: f64,
    ch: f64,
    abs_v: f64,
}

/// The circular functions: sin(x·x1), cos(x·x2), sinh(|v|·y1), cosh(|v|·y2).
fn circular(q: &[f64], (x, y, z): (f64, f64, f64)) -> Parts {
    let abs_v = jm::hypot(y, z) * q[5];
    Parts {
        s: jm::sin(x * q[1]),
        c: jm::cos(x * q[2]),
        sh: jm::sinh(abs_v * q[3]),
        ch: jm::cosh(abs_v * q[4]),
        abs_v,
    }
}

/// The hyperbolic functions: sin(|v|·y1), cos(|v|·y2), sinh(x·x1), cosh(x·x2).
fn hyperbolic(q: &[f64], (x, y, z): (f64, f64, f64)) -> Parts {
    let abs_v = jm::hypot(y, z) * q[5];
    Parts {
        s: jm::sin(abs_v * q[3]),
        c: jm::cos(abs_v * q[4]),
        sh: jm::sinh(x * q[1]),
        ch: jm::cosh(x * q[2]),
        abs_v,
    }
}

/// The cotangent-like quotient: (x-part, the factor of y and z) from its parts, with
/// sign `sy` for the vector part.
fn quotient(
    (stcv, ctcv, cc, b): (f64, f64, f64, f64),
    (x, y, z): (f64, f64, f64),
    w: f64,
    pw: f64,
    sy: f64,
) -> V3 {
    let sysz = y * y + z * z;
    let ni = w / (x * x + sysz);
    let n = -stcv;
    [
        pw * (stcv * ctcv + cc * b * sysz) * ni,
        sy * pw * (n * b * y + cc * y * ctcv) * ni,
        sy * pw * (n * b * z + cc * z * ctcv) * ni,
    ]
}

fn add(a: &mut V3, b: V3) {
    a[0] += b[0];
    a[1] += b[1];
    a[2] += b[2];
}

/// The sum of the functions with nonzero power, in JWildfire's order.
fn quaternion(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let q = &v.p[..92];
    let w = v.w;
    let pt = (t.x, t.y, t.z);
    let (x, y, z) = pt;
    let r2 = x * x + y * y + z * z;
    let mut o = [0.0; 3];
    let g = |at: usize| &q[at..at + 7];
    if q[COS] != 0.0 {
        let a = circular(g(COS), pt);
        let cc = w * a.s * a.sh / a.abs_v * q[COS + 6];
        let pw = q[COS];
        add(&mut o, [pw * w * a.c * a.ch, pw * cc * y, pw * cc * z]);
    }
    if q[COSH] != 0.0 {
        let a = hyperbolic(g(COSH), pt);
        let cc = w * a.sh * a.s / a.abs_v * q[COSH + 6];
        let pw = q[COSH];
        add(&mut o, [pw * w * a.ch * a.c, pw * cc * y, pw * cc * z]);
    }
    if q[COT] != 0.0 {
        let a = circular(g(COT), pt);
        let cc = a.c * a.sh / a.abs_v * q[COT + 6];
        let b = -a.s * a.sh / a.abs_v;
        let parts = (a.s * a.ch, a.c * a.ch, cc, b);
        add(&mut o, quotient(parts, pt, w, q[COT], -1.0));
    }
    if q[COTH] != 0.0 {
        let a = hyperbolic(g(COTH), pt);
        let cc = a.ch * a.s / a.abs_v * q[COTH + 6];
        let b = a.sh * a.s / a.abs_v;
        let parts = (a.sh * a.c, a.ch * a.c, cc, b);
        add(&mut o, quotient(parts, pt, w, q[COTH], 1.0));
    }
    if q[CSC] != 0.0 {
        let a = circular(g(CSC), pt);
        let ni = w / r2;
        let cc = ni * a.c * a.sh / a.abs_v * q[CSC + 6];
        let pw = q[CSC];
        add(&mut o, [pw * a.s * a.ch * ni, -pw * cc * y, -pw * cc * z]);
    }
    if q[CSCH] != 0.0 {
        let a = hyperbolic(g(CSCH), pt);
        let ni = w / r2;
        let cc = ni * a.ch * a.s / a.abs_v * q[CSCH + 6];
        let pw = q[CSCH];
        add(&mut o, [pw * a.sh * a.c * ni, -pw * cc * y, -pw * cc * z]);
    }
    if q[ESTI] != 0.0 {
        let [pw, x1, y1, y2, z1, z2] = q[ESTI..ESTI + 6].try_into().expect("six values");
        let e = jm::exp(x * x1);
        let abs_v = jm::hypot(y, z) * z1;
        let (s, c) = (jm::sin(abs_v * y1), jm::cos(abs_v * y2));
        let a = e * s / abs_v * z2;
        add(&mut o, [pw * w * e * c, pw * w * a * y, pw * w * a * z]);
    }
    if q[LOG] != 0.0 {
        let (pw, base) = (q[LOG], q[LOG + 1]);
        let denom = 0.5 * w / base.ln();
        let abs_v = jm::hypot(y, z);
        let cc = w * jm::atan2(abs_v, x) / abs_v;
        let lx = pw * (x * x + abs_v * abs_v).ln() * denom;
        add(&mut o, [lx, pw * cc * y, pw * cc * z]);
    }
    if q[SEC] != 0.0 {
        let a = circular(g(SEC), (-x, y, z));
        let ni = w / r2;
        let cc = ni * a.s * a.sh / a.abs_v * q[SEC + 6];
        let pw = q[SEC];
        add(&mut o, [pw * a.c * a.ch * ni, -pw * cc * y, -pw * cc * z]);
    }
    if q[SECH] != 0.0 {
        let a = hyperbolic(g(SECH), pt);
        let ni = w / r2;
        let cc = ni * a.sh * a.s / a.abs_v * q[SECH + 6];
        let pw = q[SECH];
        add(&mut o, [pw * a.ch * a.c * ni, -pw * cc * y, -pw * cc * z]);
    }
    if q[TAN] != 0.0 {
        let a = circular(g(TAN), pt);
        let cc = a.c * a.sh / a.abs_v * q[TAN + 6];
        let b = -a.s * a.sh / a.abs_v;
        let parts = (a.s * a.ch, a.c * a.ch, cc, b);
        add(&mut o, quotient(parts, pt, w, q[TAN], 1.0));
    }
    if q[TANH] != 0.0 {
        let a = hyperbolic(g(TANH), pt);
        let cc = a.ch * a.s / a.abs_v * q[TANH + 6];
        let b = a.sh * a.s / a.abs_v;
        let parts = (a.sh * a.c, a.c * a.ch, cc, b);
        add(&mut o, quotient(parts, pt, w, q[TANH], 1.0));
    }
    if q[SIN] != 0.0 {
        let a = circular(g(SIN), pt);
        let cc = w * a.c * a.sh / a.abs_v * q[SIN + 6];
        let pw = q[SIN];
        add(&mut o, [pw * w * a.s * a.ch, pw * cc * y, pw * cc * z]);
    }
    if q[SINH] != 0.0 {
        let a = hyperbolic(g(SINH), pt);
        let cc = w * a.ch * a.s / a.abs_v * q[SINH + 6];
        let pw = q[SINH];
        add(&mut o, [pw * w * a.sh * a.c, pw * cc * y, pw * cc * z]);
    }
    o
}
