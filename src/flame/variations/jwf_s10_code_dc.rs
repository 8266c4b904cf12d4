//! JWildfire's `dc_code`: a direct-colour stamp whose colour function is Java source in a
//! `code` resource, compiled at run time. Its `randomize` parameter (a seed, 10000 by default)
//! writes that source: a small escape-time iteration z ← f(z)·g(z) + h(c) of complex
//! functions picked with `java.util.Random` from the seed (JWildfire 9.00, `DC_CodeFunc`'s
//! `randomizeCode`), coloured by its step count times the modulus of one more function of
//! the last z; seed 0 leaves the class's default source, the Mandelbrot set of
//! `glslFuncRunner.fractal`. ugnis cannot run Java: it makes the same choices from the same
//! seed and evaluates them natively, with the complex functions of `glslFuncRunner`
//! (JWildfire's GLSL helpers, whose argument uses an approximate atan2). A flame whose code
//! was edited is drawn with the code its seed gives. Written anew (JWildfire is LGPL-2.1).

use super::jwf_direct_colour::{DC_FLAGS, dc_common, dc_tail};
use super::jwf_s10_code::glsl_fractal;
use super::util::atan2_approx;
use super::*;

const TAIL: [Param; 5] = dc_tail!("dc_code");

pub(super) static DEFS: &[VarDef] = &[VarDef::new("dc_code", dc_code)
    .params(&[
        p_int("dc_code_randomize", 10000.0, 0.0, 10_000_000.0),
        p_range("dc_code_PanX", 0.5, -2.0, 2.0),
        p_range("dc_code_PanY", 0.0, -2.0, 2.0),
        p_range("dc_code_zoom", 4.0, 0.0, 100.0),
        TAIL[0],
        TAIL[1],
        TAIL[2],
        TAIL[3],
        TAIL[4],
    ])
    .texts(&[TextParam {
        name: "dc_code_code",
        default: "",
        max_len: 1 << 16,
    }])
    .prepare(dc_code_prepare)
    .flags(DC_FLAGS)];

/// `java.util.Random`: a 48-bit linear congruential generator (Knuth, TAOCP vol. 2, §3.2.1,
/// with the multiplier and scrambling of the Java platform's documentation of the class).
struct JavaRandom(u64);

impl JavaRandom {
    const MUL: u64 = 0x5_DEEC_E66D;
    const MASK: u64 = (1 << 48) - 1;

    fn new(seed: i64) -> JavaRandom {
        JavaRandom((seed as u64 ^ Self::MUL) & Self::MASK)
    }

    fn next(&mut self, bits: u32) -> u64 {
        self.0 = (self.0.wrapping_mul(Self::MUL).wrapping_add(0xB)) & Self::MASK;
        self.0 >> (48 - bits)
    }

    fn next_double(&mut self) -> f64 {
        let hi = self.next(26);
        let lo = self.next(27);
        ((hi << 27) + lo) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    fn prob(&mut self, p: f64) -> bool {
        self.next_double() < p
    }

    /// `randomPicker`: an index in 0..n by Math.round(ξ·n), kept below n (one draw unless n
    /// is 1).
    fn pick(&mut self, n: usize) -> usize {
        if n == 1 {
            return 0;
        }
        let i = (self.next_double() * n as f64 + 0.5).floor() as usize;
        i.min(n - 1)
    }
}

/// Complex functions, by the names the generated code calls them.
const ID: u8 = 0;
const SIN: u8 = 1;
const COS: u8 = 2;
const LN: u8 = 3;
const SQRT: u8 = 4;
const TAN: u8 = 5;
const ATAN: u8 = 6;
const TANH: u8 = 7;
const ASIN: u8 = 8;
const SINH: u8 = 9;
const EXP: u8 = 10;
const INV: u8 = 11;
const ASINH: u8 = 12;
const ACOSH: u8 = 13;

/// The generator's lists (`singleArgument`, `pArgFunctions`, `lengthFunc`; "" is no function).
const SINGLE: [u8; 8] = [ID, ID, ID, ID, ID, ID, SIN, COS];
const P_ARG: [u8; 6] = [ID, ID, ID, SIN, LN, SQRT];
const LENGTH: [u8; 22] = [
    ID, ID, ID, ID, ID, ID, ID, ID, TAN, ATAN, TANH, SIN, ASIN, SINH, EXP, LN, LN, INV, SINH, TANH,
    ASINH, ACOSH,
];
/// The colour divisors of t the generator picks from.
const COLOURS: [[f64; 3]; 5] = [
    [64.0, 32.0, 24.0],
    [64.0, 32.0, 16.0],
    [14.0, 42.0, 22.0],
    [32.0, 64.0, 24.0],
    [32.0, 48.0, 24.0],
];

/// How many values [`generate`] derives.
const PROGRAM: usize = 17;

/// The generated program for `seed` (`randomizeCode.generateRandom`), as values: t₀; the start
/// (0: z = p and c a constant, 1: z = 0, 2: z = 1, both with c = p); the constant c; whether
/// c is p turned by a; whether there is an angle a = 3.14·t₀/2; the two factors' functions
/// and multipliers (0 none, 1 sin a, 2 a); whether their product is inverted; the added
/// function of c and whether it is inverted; the function whose modulus scales the colour;
/// the three colour divisors. Every choice draws from the generator in JWildfire's order.
fn generate(seed: i64) -> [f64; PROGRAM] {
    let mut rnd = JavaRandom::new(seed);
    let mut arg_rotation = 0.9;
    let t0 = rnd.next_double() * 30.0;
    let mut first = (SINGLE[rnd.pick(SINGLE.len())], 0u8);
    let mut second = (SINGLE[rnd.pick(SINGLE.len())], 0u8);
    let p_arg = P_ARG[rnd.pick(P_ARG.len())];
    let invert_z = rnd.prob(0.2);
    let (start, cx, cy) = if rnd.prob(0.4) {
        let cx = rnd.next_double();
        (0.0, cx, rnd.next_double())
    } else if invert_z {
        (2.0, 0.0, 0.0)
    } else {
        (1.0, 0.0, 0.0)
    };
    let (mut rotated_c, mut angle) = (false, false);
    if rnd.prob(0.5) {
        angle = true;
        if rnd.prob(0.5) {
            rotated_c = true;
            arg_rotation = 0.2;
        }
        for f in [&mut first, &mut second] {
            if rnd.prob(arg_rotation) {
                arg_rotation = 0.1;
                f.1 = if rnd.prob(0.8) { 1 } else { 2 };
            }
        }
    }
    // `canInv`: not when the product's text holds "tan" or "sin" (c_sin, or the sin(a)
    // multiplier).
    let has_sin = |f: (u8, u8)| f.0 == SIN || f.1 == 1;
    let inv_product = invert_z && !has_sin(first) && !has_sin(second);
    let inv_p = rnd.prob(0.1);
    let length_f = LENGTH[rnd.pick(LENGTH.len())];
    let colour = COLOURS[rnd.pick(COLOURS.len())];
    let b = |x: bool| if x { 1.0 } else { 0.0 };
    [
        t0,
        start,
        cx,
        cy,
        b(rotated_c),
        b(angle),
        f64::from(first.0),
        f64::from(first.1),
        f64::from(second.0),
        f64::from(second.1),
        b(inv_product),
        f64::from(p_arg),
        b(inv_p),
        f64::from(length_f),
        colour[0],
        colour[1],
        colour[2],
    ]
}

/// The name the generated source calls function `f` by ("" for none).
fn name(f: u8) -> &'static str {
    match f {
        SIN => "c_sin",
        COS => "c_cos",
        LN => "c_ln",
        SQRT => "c_sqrt",
        TAN => "c_tan",
        ATAN => "c_atan",
        TANH => "c_tanh",
        ASIN => "c_asin",
        SINH => "c_sinh",
        EXP => "c_exp",
        INV => "c_inv",
        ASINH => "c_asinh",
        ACOSH => "c_acosh",
        _ => "",
    }
}

/// `applyArgument`: `f(arg)`, or `arg` for no function.
fn call(f: u8, arg: &str) -> String {
    match name(f) {
        "" => arg.to_string(),
        n => format!("{n}({arg})"),
    }
}

/// DC_CodeFunc's own source, kept for seed 0.
const DEFAULT_SOURCE: &str = "public vec3 getRGBColor(double xp,double yp) { vec3 color=new vec3(0.0); \
     vec2 st=new vec2(xp,yp); vec2 c = st.multiply(zoom).minus(new vec2(stepX,stepY)); \
     color = fractal(c); return color; }";

/// The source `randomizeCode.generateRandom` writes for program `q` (numbers as Rust writes
/// them: compare through [`normalised`]).
fn source(q: &[f64; PROGRAM]) -> String {
    let mut s = String::from(
        "public vec3 getRGBColor(double xp,double yp) { vec2 p=new vec2(xp,yp); \
         p=p.multiply(zoom).minus(new vec2(stepX,stepY));",
    );
    s += &format!(" double t={}; vec3 color=new vec3(0.0);", q[0]);
    s += &match q[1] as i64 {
        0 => format!(" vec2 z= p; vec2 c = new vec2({},{});", q[2], q[3]),
        2 => " vec2 z = new vec2(1.0); vec2 c=p;".to_string(),
        _ => " vec2 z = new vec2(0.0); vec2 c=p;".to_string(),
    };
    if q[5] == 1.0 {
        s += " double a=3.14*t*0.5;";
    }
    if q[4] == 1.0 {
        s += " c = new vec2(p.x*cos(a) - p.y * sin(a), p.y*cos(a) + p.x * sin(a));";
    }
    let factor = |f: f64, m: f64| {
        let arg = call(f as u8, "z");
        match m as u8 {
            1 => format!("{arg}.multiply(sin(a))"),
            2 => format!("{arg}.multiply(a)"),
            _ => arg,
        }
    };
    let mut z_line = format!("c_mul({},{})", factor(q[6], q[7]), factor(q[8], q[9]));
    if q[10] == 1.0 {
        z_line = format!("c_inv({z_line})");
    }
    let mut p_arg = call(q[11] as u8, "c");
    if q[12] == 1.0 {
        p_arg = format!("c_inv({p_arg})");
    }
    s += &format!(
        " for(int k = 0; k < 32; ++k) {{ if (length(z) > 2.) break; z = c_add({z_line},{p_arg}); \
         t = (double)k; }}"
    );
    s += &format!(" double t1=length({});", call(q[13] as u8, "z"));
    let d = |x: f64| format!("{x}.");
    s += &format!(
        " color = new vec3(t/{}, t/{}, t/{}).multiply(t1); return color; }}",
        d(q[14]),
        d(q[15]),
        d(q[16])
    );
    s
}

/// `s` with each number literal written as Rust writes its value and each run of whitespace
/// made one space (so sources differing only in how they print numbers or lay out compare
/// equal).
fn normalised(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = String::with_capacity(s.len());
    let mut i = 0;
    while i < b.len() {
        let starts_number =
            b[i].is_ascii_digit() || (b[i] == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit));
        let after_word = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
        if starts_number && !after_word {
            let mut j = i;
            while j < b.len() {
                let c = b[j];
                let sign = (c == b'-' || c == b'+') && j > i && matches!(b[j - 1], b'e' | b'E');
                if !(c.is_ascii_digit() || c == b'.' || c == b'e' || c == b'E' || sign) {
                    break;
                }
                j += 1;
            }
            let lit = &s[i..j];
            match lit.parse::<f64>() {
                Ok(v) => out += &format!("{v}"),
                Err(_) => out += lit,
            }
            i = j;
            continue;
        }
        let ch = s[i..].chars().next().unwrap_or(' ');
        out.push(ch);
        i += ch.len_utf8();
    }
    out.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The reader's warning for a dc_code whose `code` is not the source its `randomize` seed
/// writes (or, for seed 0, the class's own): ugnis draws the seed's program. `None` for an
/// empty text or a text that is that source.
pub fn code_problem(seed: f64, texts: &[String]) -> Option<String> {
    let text = texts.first()?;
    if text.trim().is_empty() {
        return None;
    }
    let want = if seed as i64 > 0 {
        source(&generate(seed as i64))
    } else {
        DEFAULT_SOURCE.to_string()
    };
    if normalised(text) == normalised(&want) {
        return None;
    }
    Some("dc_code: edited code is not supported; the code its randomize seed writes is used".into())
}

/// The program of the seed (start −1 for seed 0: the default source).
fn dc_code_prepare(v: &mut Prepared) {
    let [seed] = v.params();
    let program = if seed as i64 > 0 {
        generate(seed as i64)
    } else {
        let mut p = [0.0; PROGRAM];
        p[1] = -1.0;
        p
    };
    v.p.extend_from_slice(&program);
}

type C = (f64, f64);

fn add(a: C, b: C) -> C {
    (a.0 + b.0, a.1 + b.1)
}

fn sub(a: C, b: C) -> C {
    (a.0 - b.0, a.1 - b.1)
}

fn mul(a: C, b: C) -> C {
    (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0)
}

fn length(a: C) -> f64 {
    (a.0 * a.0 + a.1 * a.1).sqrt()
}

/// `c_div`: by the squared length, itself the square of a square root.
fn div(a: C, b: C) -> C {
    let n = length(b);
    let n2 = n * n;
    ((a.0 * b.0 + a.1 * b.1) / n2, (a.1 * b.0 - a.0 * b.1) / n2)
}

fn sinh(x: f64) -> f64 {
    let e = x.exp();
    (e - 1.0 / e) / 2.0
}

fn cosh(x: f64) -> f64 {
    let e = x.exp();
    (e + 1.0 / e) / 2.0
}

/// `c_to_polar`'s angle: the approximate atan2 of `glslFuncRunner`.
fn arg(a: C) -> f64 {
    atan2_approx(a.1, a.0)
}

fn from_polar(r: f64, theta: f64) -> C {
    (r * theta.cos(), r * theta.sin())
}

fn ln(a: C) -> C {
    (length(a).ln(), arg(a))
}

fn sqrt(a: C) -> C {
    from_polar(length(a).sqrt(), arg(a) / 2.0)
}

fn inv(a: C) -> C {
    let n = length(a);
    (a.0 / (n * n), -a.1 / (n * n))
}

/// `glslFuncRunner`'s complex function `f` of `a`.
fn apply(f: u8, a: C) -> C {
    const ONE: C = (1.0, 0.0);
    const I: C = (0.0, 1.0);
    let (x, y) = a;
    match f {
        SIN => (x.sin() * cosh(y), x.cos() * sinh(y)),
        COS => (x.cos() * cosh(y), -x.sin() * sinh(y)),
        LN => ln(a),
        SQRT => sqrt(a),
        TAN => {
            let d = (2.0 * x).cos() + cosh(2.0 * y);
            ((2.0 * x).sin() / d, sinh(2.0 * y) / d)
        }
        ATAN => {
            if a == I {
                (0.0, f64::INFINITY)
            } else if a == (0.0, -1.0) {
                (0.0, f64::NEG_INFINITY)
            } else {
                let iz = mul(I, a);
                div(sub(ln(add(ONE, iz)), ln(sub(ONE, iz))), mul((2.0, 0.0), I))
            }
        }
        TANH => {
            let d = cosh(2.0 * x) + (2.0 * y).cos();
            (sinh(2.0 * x) / d, (2.0 * y).sin() / d)
        }
        ASIN => {
            let s = sqrt(sub(ONE, mul(a, a)));
            mul((0.0, -1.0), ln(add(s, mul(I, a))))
        }
        SINH => (sinh(x) * y.cos(), cosh(x) * y.sin()),
        EXP => from_polar(x.exp(), y),
        INV => inv(a),
        ASINH => ln(add(a, sqrt(add(ONE, mul(a, a))))),
        ACOSH => {
            let two = (2.0, 0.0);
            let s = add(sqrt(div(add(a, ONE), two)), sqrt(div(sub(a, ONE), two)));
            mul(two, ln(s))
        }
        _ => a,
    }
}

/// The generated source's rounded π in its angle a = 3.14·t/2 (kept as written).
#[allow(clippy::approx_constant)]
const ROUGH_PI: f64 = 3.14;

/// The colour the program gives the point (xp, yp) of [−1, 1]² (see [`generate`]).
fn program_colour(q: &[f64], zoom: f64, step: C, xp: f64, yp: f64) -> [f64; 3] {
    let p = (xp * zoom - step.0, yp * zoom - step.1);
    let start = q[1];
    if start < 0.0 {
        return glsl_fractal(p.0, p.1);
    }
    let mut t = q[0];
    let (mut z, mut c) = if start == 0.0 {
        (p, (q[2], q[3]))
    } else if start == 2.0 {
        ((1.0, 1.0), p)
    } else {
        ((0.0, 0.0), p)
    };
    let a = ROUGH_PI * t * 0.5;
    if q[5] == 1.0 && q[4] == 1.0 {
        let (s, co) = (a.sin(), a.cos());
        c = (p.0 * co - p.1 * s, p.1 * co + p.0 * s);
    }
    let factor = |m: f64| match m as u8 {
        1 => a.sin(),
        2 => a,
        _ => 1.0,
    };
    let (f1, m1) = (q[6] as u8, factor(q[7]));
    let (f2, m2) = (q[8] as u8, factor(q[9]));
    let scale = |w: C, m: f64| if m == 1.0 { w } else { (w.0 * m, w.1 * m) };
    let mut h = apply(q[11] as u8, c);
    if q[12] == 1.0 {
        h = inv(h);
    }
    for k in 0..32 {
        if length(z) > 2.0 {
            break;
        }
        let mut zl = mul(scale(apply(f1, z), m1), scale(apply(f2, z), m2));
        if q[10] == 1.0 {
            zl = inv(zl);
        }
        z = add(zl, h);
        t = f64::from(k);
    }
    let t1 = length(apply(q[13] as u8, z));
    [q[14], q[15], q[16]].map(|d| t / d * t1)
}

/// dc_code: a point of [−1, 1]² (or the input with ColorOnly = 1), coloured by the program
/// of `randomize` at that point times `zoom`, less (PanX, PanY); the dc_ variations' colour,
/// z and weight rules.
fn dc_code(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, pan_x, pan_y, zoom, tail @ ..] = v.params::<9>();
    let q = v.table(0);
    if q.len() < PROGRAM {
        return [0.0; 3];
    }
    dc_common(v, tail, t, acc, rng, 1.0, |x, y| {
        program_colour(q, zoom, (pan_x, pan_y), x, y)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn java_random_matches_the_platform() {
        // new Random(42).nextDouble() is 0.7275636800328681 (documented sequence of the
        // Java platform's generator).
        let mut r = JavaRandom::new(42);
        assert_eq!(r.next_double(), 0.7275636800328681);
        assert_eq!(r.next_double(), 0.6832234717598454);
    }

    #[test]
    fn complex_functions_agree_with_their_definitions() {
        let z = (0.3, -0.4);
        let close = |a: C, b: C| (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-12;
        // exp(ln z) = z where the approximate argument is exact (on the axes).
        assert!(close(apply(EXP, apply(LN, (0.0, 2.0))), (0.0, 2.0)));
        // sinh, sin: sin(iz) = i sinh(z).
        let s = apply(SIN, mul((0.0, 1.0), z));
        assert!(close(s, mul((0.0, 1.0), apply(SINH, z))));
        // 1/z · z = 1.
        assert!(close(mul(apply(INV, z), z), (1.0, 0.0)));
        // tanh(x) for real x.
        assert!(close(apply(TANH, (0.5, 0.0)), (0.5f64.tanh(), 0.0)));
    }

    #[test]
    fn sources_are_recognised() {
        // JWildfire 9.00's source for seed 10002 (printed by its `randomizeCode`).
        let jwf = "public vec3 getRGBColor(double xp,double yp)\n{\n  vec2 p=new vec2(xp,yp);\n  \
            p=p.multiply(zoom).minus(new vec2(stepX,stepY));\n  double t=26.52197521717507;\n  \
            vec3 color=new vec3(0.0);\n  vec2 z = new vec2(0.0);\n   vec2 c=p;\n   \
            for(int k = 0; k < 32; ++k) {\n      if (length(z) > 2.) break;\n          \
            z = c_add(c_mul(z,z),c);\n      t = (double)k;\n   }\n   \
            double t1=length(c_tanh(z));\n   \
            color =  new vec3(t/32., t/64., t/24.).multiply(t1);\n   return color;\n}\n";
        let t = |s: &str| vec![s.to_string()];
        assert_eq!(code_problem(10002.0, &t(jwf)), None);
        assert!(code_problem(10001.0, &t(jwf)).is_some());
        assert_eq!(code_problem(10001.0, &t(" ")), None);
        // 10000's source rotates z by sin(a) and adds sqrt(c).
        let s = source(&generate(10000));
        assert!(
            s.contains("c_add(c_mul(z,z.multiply(sin(a))),c_sqrt(c))"),
            "{s}"
        );
        assert!(normalised(&s).contains("double t=26.516600757877605;"));
        assert_eq!(normalised("x=2. +  1.50e1"), "x=2 + 15");
    }

    #[test]
    fn programs_are_the_ones_jwildfire_writes() {
        // The sources JWildfire 9.00's `randomizeCode` writes for these seeds (run on the
        // Java platform): 10000: z = p, c = (0.8289…, 0.6904…), z ← z·(z·sin a) + sqrt(c),
        // colour (t/32, t/48, t/24)·|z|; 10001: z = 0, c = p, z ← (z·sin a)·cos(z) + sin(c),
        // colour (t/64, t/32, t/24)·|exp z|; 10002: z ← z² + c, (t/32, t/64, t/24)·|tanh z|.
        let q = generate(10000);
        assert_eq!(q[0], 26.516600757877605);
        assert_eq!(q[1..4], [0.0, 0.8289341884405558, 0.6904257796594087]);
        assert_eq!(q[4..14], [0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 4.0, 0.0, 0.0]);
        assert_eq!(q[14..], [32.0, 48.0, 24.0]);
        let q = generate(10001);
        assert_eq!(q[0], 26.51391285767662);
        assert_eq!(q[1], 1.0);
        assert_eq!(
            q[4..14],
            [0.0, 1.0, 0.0, 1.0, 2.0, 0.0, 0.0, 1.0, 0.0, 10.0]
        );
        assert_eq!(q[14..], [64.0, 32.0, 24.0]);
        let q = generate(10002);
        assert_eq!(q[0], 26.52197521717507);
        assert_eq!(q[1], 1.0);
        assert_eq!(q[4..14], [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 7.0]);
        assert_eq!(q[14..], [32.0, 64.0, 24.0]);
        // Seed 0 keeps the default source (the Mandelbrot set).
        let id = super::super::parse_name("dc_code").expect("registered").0;
        let v = Prepared::new(id, Form::Regular, 1.0, &[0.0], Default::default(), true);
        assert_eq!(v.table(0)[1], -1.0);
        let c = program_colour(v.table(0), 4.0, (0.5, 0.0), 0.0, 0.0);
        assert_eq!(c, glsl_fractal(-0.5, 0.0));
    }
}
