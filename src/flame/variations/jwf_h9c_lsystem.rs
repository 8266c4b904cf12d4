//! JWildfire's `lsystem_js` (JWildfire 9.00, `LsystemFunc`; LGPL-2.1, the behaviour written
//! anew): a Lindenmayer system in Fractint's `.l` form (`Angle n` for 360/n degrees, `Axiom`,
//! one rule `X=…` a line) expanded `iters` times and drawn once by a turtle into segments;
//! each call takes the next segment (in drawing order, round and round) and returns a random
//! point of it (a line, widened by `line_thickness`/100) or of a disc at its start (radius
//! `point_thickness_param`/100), in the ratio `show_lines_param` : `show_points_param`.
//!
//! Turtle commands: `F`/`D` draw a step, `G`/`M` move a step, `+`/`-` turn by the angle
//! (left/right), `|` turn round, `!` swap the turns, `[`/`]` push/pop the turtle, `\n`/`/n`
//! turn n degrees left/right, `@n` (`@Qn`, `@In`, `@IQn`, `@QIn`) scale the step by n (√n,
//! 1/n, …), `<n`/`>n`/`Cn` raise/lower/set the colour by n/256; the rest is skipped. A
//! command whose number is missing ends the drawing there, as JWildfire's does. The text is
//! read as JWildfire reads it: upper-cased, `;` ending a line (with the character before
//! it), lines with `{` or `}` skipped. An expansion longer than [`MAX_SYMBOLS`] is not made
//! (the previous one is drawn).
//!
//! `presetId` (1–25) picks one of JWildfire's built-in systems (classic ones from Fractint's
//! collection and *The Science of Fractal Images*); any other id but −1 the last one.

use std::f64::consts::PI;

use super::*;

/// Longest expansion kept (JWildfire's default `tinaLSystemMaxLength`).
pub const MAX_SYMBOLS: usize = 25_000;
/// Most expansion rounds (an expansion that no longer grows gives the same string each round).
const MAX_ITERS: usize = 10_000;
/// Most segments drawn (every `F` of the expansion, at most [`MAX_SYMBOLS`]).
const MAX_SEGMENTS: usize = MAX_SYMBOLS;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("lsystem_js", lsystem_js)
    .params(&[
        p_int("lsystem_js_iters", 3.0, -2147483648.0, 2147483647.0),
        p("lsystem_js_step", 0.1),
        p("lsystem_js_angle", 0.0),
        p_int("lsystem_js_presetId", -1.0, -2147483648.0, 2147483647.0),
        p_int("lsystem_js_show_lines_param", 1.0, -2147483648.0, 2147483647.0),
        p("lsystem_js_line_thickness", 0.5),
        p_int("lsystem_js_show_points_param", 0.0, -2147483648.0, 2147483647.0),
        p("lsystem_js_point_thickness_param", 3.0),
        p_int("lsystem_js_color_mode", 0.0, 0.0, 1.0),
    ])
    .texts(&[
        TextParam {
            name: "lsystem_js_grammar",
            default: DEFAULT_GRAMMAR,
            max_len: 1 << 16,
        },
        TextParam {
            name: "lsystem_js_presetId_reference",
            default: "org.jwildfire.create.tina.variation.reference.ReferenceFile lsystem-presets.pdf",
            max_len: 1024,
        },
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::STATEFUL | flag::SETS_COLOR)
    .shared(&[0, 1, 2, 3], lsystem_segments)];

/// JWildfire's default grammar: Anthony Hanmer's Cesaro variation (ADH155).
const DEFAULT_GRAMMAR: &str = "ADH155 { ; Anthony Hanmer 2000\nAngle 45 ; Cesaro variation\nAxiom f\nf=f++++++++++f--------------------f++++++++++f\n}\n";

/// JWildfire's built-in systems, by `presetId` 1–25: each the lines of a grammar.
const PRESETS: [&str; 25] = [
    "angle 4\naxiom X\nX=-YF+XFX+FY-\nY=+XF-YFY-FX+",
    "Angle 6\nAxiom F\nF=F+F--F+F",
    "angle 4\naxiom F+F+F+F\nF=F+F-F-FFF+F+F-F",
    "angle 6\naxiom F--F--F\nF=F-F++F-F",
    "angle 4\naxiom F\nF=FF+F+F+FF+F+F-F",
    "Angle 4\nAxiom F\nF=F+F-F-F-G+F+F+F-F\nG=GGG",
    "angle 6\naxiom FXF--FF--FF\nF=FF\nX=--FXF++FXF++FXF--",
    "Angle 16\nAxiom A\nA=f-[A+A]+f[+fA]-A\nf=ff",
    "Angle 45\nAxiom f\nf=f++++++++++f--------------------f++++++++++f",
    "angle 4\naxiom F+F+F+F\nF=FF+F++F+F",
    "Angle 4\nAxiom x\nx=fx+fy-fx-fxfy+\ny=-fxfy+fy+fx-fy\nf=3",
    "angle 4\naxiom -L\nL=LF+RFR+FL-F-LFLFL-FRFR+\nR=-LFLF+RFRFR+F+RF-LFL-FR",
    "angle 12\naxiom fx\nf=\nx=-f++f-x-f--f+y---f--f+y+f++f-x+++f++f-x-f++f-x+++f--f+y--\n\
     y=+f++f-x-f--f+y+f--f+y---f--f+y---f++f-x+++f++f-x+++f--f+y",
    "angle 4\naxiom F+F+F+F\nF = FF+F+F+F+FF",
    "Angle 6\nAxiom X\nX=+FF-YFF+FF--FFF|X|F--YFFFYFFF|\nY=-FF+XFF-FF++FFF|Y|F++XFFFXFFF|\nF=GG\nG=GG",
    "Angle 3\nAxiom D\\90D[A]\\90D[B]\\90D\nA=/67.38@.3846D[A]\\90D[B]\\90D\\90D\n\
     B=/157.38@.9231D\\90D[A]\\90D[B]\\90D",
    "Angle 22\nAxiom F\nX=-F[-X]-F[+X]\nF=F[-X]F",
    "Angle 15\nAxiom xy\nx=<1+F>1+<1F>1[+y][-y]<1F>1-<1F>1[+y][-y]\n\
     y=<1-F>1-<1F>1[+x][-x]<1F>1+<1F>1[+x][-x]\nf=<10F[+x][-x][+y][-y]F>10",
    "Angle 30\nAxiom f\nx=--<5F[X][y]++F>5[X][y]\ny=++<5F[X][y]--F>5[X][y]\nf=<10F[X][y]F>10",
    "Angle 15\nAxiom x\nx=>5F[-X][+X]>5F[--X][++X]>5F<5[---X][+++X]\n\
     x=F<5[----X][++++X]F<5[-----X][+++++X]\nf=c52f@0.9975c32f@0.9935c11F",
    "Angle 23\nAxiom X\nX=+F[-X]--F[+X]\nF=-F[+F]+F[-F]",
    "Angle 10\nAxiom F\nF=F[+X]F[-Y]\nX=S-T\nY=T+S\n\
     S=-<2F+<2F-<2FF+<2FF-<2FFF+<2FFF-FFF>2-FFFFF>2+FFFFF>2-FFFFF>2+FFFFF>2-FFFFF>2\n\
     T=+<2F-<2F+<2FF-<2FF+<2FFF-<2FFF+FFF>2+FFFFF>2-FFFFF>2+FFFFF>2-FFFFF>2+FFFFF>2",
    "Angle 15\nAxiom x\nx=+<18F[+x][-x]-F>18[+x][-x]\nf=<10ff>10",
    "Angle 50\nAxiom x\nx=@.95F[s][t]\ns=-<2F-<2F-<2FF-<2FFF[s][t]\n\
     s=-<2F[s][t]F[s][t]F[s][t]F[s][t]F>2[s][t]\ns=-@.95F[s][t]@.95F[s][t]@.95F[s][t]>2\n\
     s=-@.95F[s][t]@.95F[s][t]>2-@.95F[s][t]\nt=+<2F+<2F+<2FF+<2FFF[s][t]\n\
     t=+<2F[s][t]F[s][t]F[s][t]F[s][t]F>2[s][t]\nt=+@.95F[s][t]@.95F[s][t]@.95F[s][t]>2\n\
     t=+@.95F[s][t]@.95F[s][t]>2+@.95F[s][t]\nf=fffff",
    // The `;` in the second `x` rule ends the line, one character before it too (as
    // JWildfire reads it).
    "Angle 30\nAxiom x\nx=F[++++s][----t]@.9326F[+++s][---t]\n\
     x=@.8557F[++s][--t]@.7788F[+s][-t];@.7019F[x]\n\
     s=+<5F[++s][---s]-<5F[++s][---s]-<5@.9326F[++s][---s]\n\
     s=-@.8557F>5[++s][---s]-@.7788F>5[+s][--s]-@.7019F>5[s][-s]\n\
     t=-<5F[+++t][--t]+<5F[+++t][--t]+<5@.9326F[+++t][--t]\n\
     t=+@.8557F>5[+++t][--t]+@.7788F>5[++t][-t]+@.7019F>5[+t][t]\n\
     f=<10F<10F>10F>10      ;f=<10FFFF>10",
];

/// A grammar read: the angle (degrees; 90 when the text gives none), the axiom, the rules.
struct Grammar {
    angle: f64,
    axiom: Vec<u8>,
    rules: Vec<(u8, Vec<u8>)>,
}

/// Reads a grammar as JWildfire's `LSystem.processFile` does; `None` where JWildfire's would
/// fail (a rule with nothing before its `=`, an angle that is not a number).
fn read_grammar(text: &str) -> Option<Grammar> {
    let mut g = Grammar {
        angle: 90.0,
        axiom: Vec::new(),
        rules: Vec::new(),
    };
    for raw in text.lines() {
        let mut line = raw.to_string();
        if let Some(c) = line.find(';') {
            if c == 0 {
                continue;
            }
            // The character before the `;` goes too.
            let mut end = c - 1;
            while !line.is_char_boundary(end) {
                end -= 1;
            }
            line.truncate(end);
        }
        let line = line.to_uppercase();
        if line.contains('{') || line.contains('}') {
            continue;
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        if line.contains('=') || line.contains("AXIOM") {
            let mut i = 0;
            while i < words.len() {
                if words[i] == "AXIOM" {
                    g.axiom = words.get(i + 1)?.bytes().collect();
                    i += 2;
                    continue;
                }
                // Every other word adds the line's rule (again).
                let (lhs, rhs) = line.split_once('=')?;
                let lhs: Vec<u8> = lhs.bytes().filter(|b| !b.is_ascii_whitespace()).collect();
                let rhs: Vec<u8> = rhs.bytes().filter(|b| !b.is_ascii_whitespace()).collect();
                g.rules.push((*lhs.first()?, rhs));
                i += 1;
            }
        } else if let Some(i) = words.iter().position(|w| *w == "ANGLE") {
            let mut v = words.get(i + 1)?;
            if *v == "=" {
                v = words.get(i + 2)?;
            }
            g.angle = 360.0 / v.parse::<f64>().ok()?;
        }
    }
    Some(g)
}

/// The expansion after `iters` rounds (each symbol replaced by its first rule), or after the
/// last round that stayed within [`MAX_SYMBOLS`]; empty when the first did not.
fn expand(g: &Grammar, iters: usize) -> Vec<u8> {
    let mut s = g.axiom.clone();
    let mut out = Vec::new();
    for _ in 0..iters.min(MAX_ITERS) {
        let mut next = Vec::with_capacity(s.len());
        for &c in &s {
            match g.rules.iter().find(|r| r.0 == c) {
                Some(r) => next.extend_from_slice(&r.1),
                None => next.push(c),
            }
            if next.len() > MAX_SYMBOLS {
                return out;
            }
        }
        let same = next == s;
        s = next;
        out.clone_from(&s);
        if same {
            break;
        }
    }
    out
}

/// The number starting at `s[i..]` (digits, a point, digits), and where it ends; `None` when
/// there is none (JWildfire's drawing stops there).
fn number_at(s: &[u8], i: usize) -> Option<(f64, usize)> {
    let mut j = i;
    while j < s.len() && s[j].is_ascii_digit() {
        j += 1;
    }
    if j < s.len() && s[j] == b'.' {
        j += 1;
        while j < s.len() && s[j].is_ascii_digit() {
            j += 1;
        }
    }
    let v = std::str::from_utf8(s.get(i..j)?)
        .ok()?
        .parse::<f64>()
        .ok()?;
    Some((v, j))
}

#[derive(Clone, Copy)]
struct Turtle {
    x: f64,
    y: f64,
    /// Heading, degrees counterclockwise from the x axis.
    a: f64,
    step: f64,
    color: f64,
}

/// Draws the expansion: segments (x1, y1, c, x2, y2, c), in drawing order.
fn draw(s: &[u8], angle: f64, step: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let mut t = Turtle {
        x: 0.0,
        y: 0.0,
        a: 0.0,
        step,
        color: 0.0,
    };
    let mut stack: Vec<Turtle> = Vec::new();
    let mut sign = 1.0;
    let mut i = 0;
    while i < s.len() {
        let c = s[i];
        match c {
            b'D' | b'F' | b'M' | b'G' => {
                let (x0, y0) = (t.x, t.y);
                let r = t.a * PI / 180.0;
                t.x += t.step * r.cos();
                t.y += t.step * r.sin();
                if (c == b'D' || c == b'F') && out.len() < 6 * MAX_SEGMENTS {
                    out.extend_from_slice(&[x0, y0, t.color, t.x, t.y, t.color]);
                }
                i += 1;
            }
            b'+' => {
                t.a += angle * sign;
                i += 1;
            }
            b'-' => {
                t.a -= angle * sign;
                i += 1;
            }
            b'|' => {
                t.a += 180.0;
                i += 1;
            }
            b'!' => {
                sign = -sign;
                i += 1;
            }
            b'[' => {
                stack.push(t);
                i += 1;
            }
            b']' => {
                let Some(top) = stack.pop() else {
                    break;
                };
                t = top;
                i += 1;
            }
            b'/' | b'\\' => {
                let Some((v, j)) = number_at(s, i + 1) else {
                    break;
                };
                t.a += if c == b'\\' { v * sign } else { -v * sign };
                i = j;
            }
            b'@' => {
                let mut k = i + 1;
                let mut how = Vec::new();
                for _ in 0..2 {
                    if let Some(&q) = s.get(k).filter(|q| **q == b'Q' || **q == b'I') {
                        how.push(q);
                        k += 1;
                    }
                }
                let Some((v, j)) = number_at(s, k) else {
                    break;
                };
                match &how[..] {
                    [] => t.step *= v,
                    [b'Q'] => t.step *= v.sqrt(),
                    [b'I'] => t.step *= 1.0 / v,
                    [b'I', b'Q'] => t.step *= 1.0 / v.sqrt(),
                    [b'Q', b'I'] => t.step *= v.sqrt() * (1.0 / v),
                    _ => {}
                }
                i = j;
            }
            b'<' | b'>' | b'C' => {
                let Some((v, j)) = number_at(s, i + 1) else {
                    break;
                };
                let v = v / 256.0;
                t.color = match c {
                    b'<' => t.color + v,
                    b'>' => t.color - v,
                    _ => v,
                };
                i = j;
            }
            _ => i += 1,
        }
    }
    out
}

/// The segments of the system the parameters and the grammar text give.
fn lsystem_segments(p: &[f64], texts: &[String]) -> Vec<f64> {
    let [iters, step, angle, preset] = [p[0], p[1], p[2], p[3]];
    let text = if preset == -1.0 {
        texts.first().map_or(DEFAULT_GRAMMAR, |t| t.as_str())
    } else {
        let k = if (1.0..=25.0).contains(&preset) {
            preset as usize
        } else {
            25
        };
        PRESETS[k - 1]
    };
    let Some(g) = read_grammar(text) else {
        return Vec::new();
    };
    let s = expand(&g, iters.max(0.0) as usize);
    let a = if angle == 0.0 { g.angle } else { angle };
    draw(&s, a, step)
}

/// lsystem_js: the next segment's random point (see the module's text), weighted.
fn lsystem_js(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        _,
        _,
        lines,
        line_thickness,
        points,
        point_thickness,
        color_mode,
    ] = v.params();
    let segs = v.data();
    let n = segs.len() / 6;
    if n == 0 {
        return [0.0, 0.0, v.default_z(t)];
    }
    let k = (v.state.get(0) as usize).min(n - 1);
    v.state.set(0, ((k + 1) % n) as f64);
    let [x1, y1, c, x2, y2, _] = std::array::from_fn(|i| segs[6 * k + i]);
    let sum = lines + points;
    let (line_at, point_at) = (lines / sum, 1.0);
    let u = rng.f01();
    let (x, y, col) = if u < line_at {
        // A point at a random distance along the segment, by JWildfire's slope arithmetic.
        let (dx, dy) = (x2 - x1, y2 - y1);
        let m = if dx == 0.0 { 10000.0 } else { dy / dx };
        let d = rng.f01() * (dx * dx + dy * dy).sqrt();
        let mut xo = d / (1.0 + m * m).sqrt();
        if x2 < x1 {
            xo = -xo;
        }
        let mut yo = (m * xo).abs();
        if y2 < y1 {
            yo = -yo;
        }
        let w = line_thickness / 100.0;
        if w != 0.0 {
            xo += (rng.f01() - 0.5) * w;
            yo += (rng.f01() - 0.5) * w;
        }
        (x1 + xo, y1 + yo, c)
    } else if u <= point_at && sum != 0.0 {
        let w = point_thickness / 100.0;
        let (mut xo, mut yo) = (0.0, 0.0);
        if w != 0.0 {
            let r = rng.f01() * w;
            let (s, co) = (rng.f01() * 2.0 * PI).sin_cos();
            (xo, yo) = (r * co, r * s);
        }
        (x1 + xo, y1 + yo, c)
    } else {
        (0.0, 0.0, 0.0)
    };
    if color_mode != 0.0 {
        acc.color = col;
    }
    [v.w * x, v.w * y, v.default_z(t)]
}
