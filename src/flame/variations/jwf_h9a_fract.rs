//! JWildfire's escape-time point sets of a formula: `fract_formula_julia_wf` (z ← f(z, seed))
//! and `fract_formula_mand_wf` (z ← f(z, start)), in the frame of the `fract_*_wf` family
//! ([`super::jwf_c_escape`]). The formula is JWildfire's small complex language: the names `z`,
//! `c` (the seed or start), `n` (the power), `i`, `x`/`y` (z's real part, z's imaginary part
//! times i), `a`/`b` (the same of c), decimal numbers, `+ - * / ^`, `²`, `³`, each operation in
//! its own parentheses, e.g. the default `((z^n)+c)`.
//!
//! As in JWildfire (9.00, `AbstractFractFormulaWFFunc`; LGPL-2.1, written anew here) the text is
//! turned into postfix order by moving each parenthesised group's first operator to its end,
//! then run on a stack of complex numbers. A text JWildfire cannot run (79 characters or more,
//! a group without an operator, other characters than Latin-1) draws nothing here; a
//! run that would overflow or empty its stack gives NaN (JWildfire throws).

use super::jwf_c_escape::{FLAGS, Step, fract};
use super::*;

/// Characters a formula may have (JWildfire's buffer holds 80 with the terminating 0).
pub(super) const FORM_LEN: usize = 80;

/// A formula in postfix order, 0-terminated.
pub(super) type Form = [u8; FORM_LEN];

/// Complex numbers the stack holds (JWildfire's 40 doubles).
const STACK: usize = 20;

/// Most iterations of the formula per starting point, and most starting points tried per
/// call: each step runs the compiled formula (about 50 ns), so that a call stays well under a
/// tenth of a millisecond in the usual cases.
const FORMULA_MAX_ITER: f64 = 1000.0;

/// Largest integer power `^` multiplies out as JWildfire does (one multiplication per unit of
/// the exponent); a larger one goes through the polar form, equal up to rounding, so that a
/// hostile exponent costs no more than a small one.
const MAX_POWER: f64 = 64.0;

/// The parameters of the family's frame, with the fractal's `own` after `buddhabrot_mode`.
macro_rules! formula_params {
    ($n:literal, [$($own:expr),*], $xmin:expr, $xmax:expr, $ymin:expr, $ymax:expr) => {
        &[
            p_int(concat!($n, "_max_iter"), 30.0, 1.0, FORMULA_MAX_ITER).limited(),
            p(concat!($n, "_xmin"), $xmin),
            p(concat!($n, "_xmax"), $xmax),
            p(concat!($n, "_ymin"), $ymin),
            p(concat!($n, "_ymax"), $ymax),
            p_int(concat!($n, "_buddhabrot_mode"), 0.0, NEG_INF, INF),
            $($own,)*
            p_int(concat!($n, "_direct_color"), 1.0, NEG_INF, INF),
            p(concat!($n, "_scalez"), 1.0),
            p_int(concat!($n, "_clip_iter_min"), 1.0, NEG_INF, INF),
            p_int(concat!($n, "_clip_iter_max"), -5.0, NEG_INF, INF),
            p_int(concat!($n, "_max_clip_iter"), 3.0, NEG_INF, FORMULA_MAX_ITER).limited(),
            p_int(concat!($n, "_buddhabrot_min_iter"), 7.0, NEG_INF, FORMULA_MAX_ITER).limited(),
            p(concat!($n, "_scale"), 3.8),
            p(concat!($n, "_offsetx"), 0.0),
            p(concat!($n, "_offsety"), 0.0),
            p(concat!($n, "_offsetz"), 0.0),
            p_range(concat!($n, "_z_fill"), 0.0, 0.0, 1.0),
            p_int(concat!($n, "_z_logscale"), 0.0, 0.0, 1.0),
            p_int(concat!($n, "_color_only"), 0.0, 0.0, 1.0),
        ]
    };
}

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("fract_formula_julia_wf", fract_formula_julia)
        .params(formula_params!(
            "fract_formula_julia_wf",
            [
                p_int("fract_formula_julia_wf_power", 3.0, 2.0, 10000.0),
                p("fract_formula_julia_wf_xseed", 0.1),
                p("fract_formula_julia_wf_yseed", 0.7)
            ],
            -1.4,
            1.4,
            -1.4,
            1.4
        ))
        .texts(&[TextParam {
            name: "fract_formula_julia_wf_formula",
            default: "((z^n)+c)",
            max_len: 4000,
        }])
        .flags(FLAGS)
        .shared(&[], compiled),
    VarDef::new("fract_formula_mand_wf", fract_formula_mand)
        .params(formula_params!(
            "fract_formula_mand_wf",
            [p_int("fract_formula_mand_wf_power", 2.0, 2.0, 10000.0)],
            -2.35,
            0.75,
            -1.2,
            1.2
        ))
        .texts(&[TextParam {
            name: "fract_formula_mand_wf_formula",
            default: "((z^n)+c)",
            max_len: 4000,
        }])
        .flags(FLAGS)
        .shared(&[], compiled),
];

/// The formula in postfix order as JWildfire's `prepare_formula` leaves it, or why not.
pub(super) fn prepare(text: &str) -> Result<Form, String> {
    let mut form: Form = [0; FORM_LEN];
    let mut len = 0;
    for ch in text.chars() {
        let b = u8::try_from(u32::from(ch))
            .map_err(|_| format!("'{ch}' is not a character of the formula language"))?;
        if len + 1 >= FORM_LEN {
            return Err(format!("longer than {} characters", FORM_LEN - 1));
        }
        form[len] = b;
        len += 1;
    }
    let number = |c: u8| c == b'.' || c.is_ascii_digit();
    // Width of each token: the length of a number starting there, else 1.
    let mut offset = [0usize; FORM_LEN];
    for (i, o) in offset.iter_mut().enumerate().take(len) {
        *o = (i..len).take_while(|&k| number(form[k])).count().max(1);
    }
    let is_op = |c: u8| matches!(c, b'+' | b'-' | b'*' | b'/' | b'^');
    // Each pass blanks the innermost parentheses met and moves their first operator to the
    // group's end; at most one pass per pair.
    let mut ok = true;
    while offset[0] < len && ok {
        let (mut i, mut ka) = (0usize, None);
        ok = false;
        while i < len {
            if form[i] == b'(' {
                ka = Some(i);
            }
            if let (b')', Some(a)) = (form[i], ka) {
                let kz = i;
                form[a] = b' ';
                form[kz] = b' ';
                offset[a] = kz - a + 1;
                ok = true;
                let mut j = a + 1;
                while !is_op(form[j]) {
                    j += offset[j];
                    if offset[j.min(FORM_LEN - 1)] == 0 || j >= FORM_LEN {
                        return Err("a group in parentheses without an operator".into());
                    }
                }
                let op = form[j];
                for k in j..kz.saturating_sub(1) {
                    form[k] = form[k + 1];
                }
                form[kz - 1] = op;
                ka = None;
            }
            i += offset[i].max(1);
        }
    }
    // Blanks removed.
    let mut i = 0;
    while i < len {
        while form[i] == b' ' {
            form.copy_within(i + 1..len, i);
            form[len - 1] = 0;
            len -= 1;
        }
        i += 1;
    }
    Ok(form)
}

/// The shared data: 1 and the postfix formula, or 0 when it cannot run.
fn compiled(_p: &[f64], texts: &[String]) -> Vec<f64> {
    let text = texts.first().map_or("((z^n)+c)", |t| t.as_str());
    match prepare(text) {
        Ok(form) => std::iter::once(1.0)
            .chain(form.iter().map(|&b| f64::from(b)))
            .collect(),
        Err(_) => vec![0.0],
    }
}

/// The postfix formula of the shared data.
fn form_of(data: &[f64]) -> Option<Form> {
    let [1.0, rest @ ..] = data else {
        return None;
    };
    let mut form: Form = [0; FORM_LEN];
    for (f, &d) in form.iter_mut().zip(rest) {
        *f = d as u8;
    }
    Some(form)
}

/// A stack of complex numbers that reports misuse instead of failing.
struct Stack {
    v: [(f64, f64); STACK],
    n: usize,
    broken: bool,
}

impl Stack {
    fn push(&mut self, z: (f64, f64)) {
        if self.n < STACK {
            self.v[self.n] = z;
            self.n += 1;
        } else {
            self.broken = true;
        }
    }
    fn pop(&mut self) -> (f64, f64) {
        if self.n == 0 {
            self.broken = true;
            return (f64::NAN, f64::NAN);
        }
        self.n -= 1;
        self.v[self.n]
    }
}

/// z^k for JWildfire's `^`: integer k up to [`MAX_POWER`] multiplied out (2 and 3 expanded;
/// any other integer, below 4 too, starts from the fourth power), other k through the polar
/// form.
fn power(s: (f64, f64), k: f64) -> (f64, f64) {
    let (sx, sy) = s;
    if k == k.trunc() && k.abs() < 9.2e18 && k <= MAX_POWER {
        if k == 2.0 {
            return (sx * sx - sy * sy, 2.0 * sx * sy);
        }
        if k == 3.0 {
            return (
                sx * sx * sx - 3.0 * sx * sy * sy,
                3.0 * sx * sx * sy - sy * sy * sy,
            );
        }
        let mut h = (
            sx * sx * sx * sx + sy * sy * sy * sy - 6.0 * sx * sx * sy * sy,
            4.0 * sx * sy * (sx * sx - sy * sy),
        );
        let mut j = 4.0;
        while j < k {
            h = (sx * h.0 - sy * h.1, sx * h.1 + h.0 * sy);
            j += 1.0;
        }
        return h;
    }
    let da = (sx * sx + sy * sy).powf(k / 2.0);
    let v = if sx == 0.0 {
        if sy >= 0.0 {
            std::f64::consts::FRAC_PI_2
        } else {
            -std::f64::consts::FRAC_PI_2
        }
    } else {
        sy.atan2(sx)
    };
    (da * (v * k).cos(), da * (v * k).sin())
}

/// Runs a postfix formula on z = (zx, zy), c = (cx, cy) and the power `n`.
pub(super) fn perform(form: &Form, n: f64, zx: f64, zy: f64, cx: f64, cy: f64) -> (f64, f64) {
    let mut st = Stack {
        v: [(0.0, 0.0); STACK],
        n: 0,
        broken: false,
    };
    let at = |i: usize| form.get(i).copied().unwrap_or(0);
    let mut i = 0;
    while at(i) != 0 {
        let (mut k, mut pnt, mut number) = (0.0, 0.0, false);
        while at(i) == b'.' || at(i).is_ascii_digit() {
            number = true;
            let c = at(i);
            i += 1;
            if c == b'.' {
                pnt = 0.1;
            } else if pnt == 0.0 {
                k = k * 10.0 + f64::from(c - b'0');
            } else {
                k += pnt * f64::from(c - b'0');
                pnt *= 0.1;
            }
        }
        if number {
            st.push((k, 0.0));
        }
        let c = at(i);
        i += 1;
        match c {
            b'z' => st.push((zx, zy)),
            b'c' => st.push((cx, cy)),
            b'i' => st.push((0.0, 1.0)),
            b'n' => st.push((n, 0.0)),
            b'x' => st.push((zx, 0.0)),
            b'y' => st.push((0.0, zy)),
            b'a' => st.push((cx, 0.0)),
            b'b' => st.push((0.0, cy)),
            b'+' | b'-' | b'*' | b'/' => {
                let (hx, hy) = st.pop();
                let (sx, sy) = st.pop();
                st.push(match c {
                    b'+' => (sx + hx, sy + hy),
                    b'-' => (sx - hx, sy - hy),
                    b'*' => (hx * sx - hy * sy, hx * sy + sx * hy),
                    _ => {
                        let da = hx * hx + hy * hy;
                        ((sx * hx + sy * hy) / da, (sy * hx - sx * hy) / da)
                    }
                });
            }
            b'^' => {
                let (k, _) = st.pop();
                let s = st.pop();
                st.push(power(s, k));
            }
            0xb2 => {
                let h = st.pop();
                st.push(power(h, 2.0));
            }
            0xb3 => {
                let h = st.pop();
                st.push(power(h, 3.0));
            }
            _ => {}
        }
    }
    let z = st.pop();
    if st.broken { (f64::NAN, f64::NAN) } else { z }
}

fn fract_formula_julia(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [.., power, cx, cy] = v.params::<9>();
    let Some(form) = form_of(v.data()) else {
        return [0.0; 3];
    };
    let s = Step::Formula {
        form,
        power: power.max(2.0),
        seed: Some((cx, cy)),
    };
    fract(v, 3, s, t, acc, rng)
}

fn fract_formula_mand(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [.., power] = v.params::<7>();
    let Some(form) = form_of(v.data()) else {
        return [0.0; 3];
    };
    let s = Step::Formula {
        form,
        power: power.max(2.0),
        seed: None,
    };
    fract(v, 1, s, t, acc, rng)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(text: &str, z: (f64, f64), c: (f64, f64), n: f64) -> (f64, f64) {
        perform(&prepare(text).unwrap(), n, z.0, z.1, c.0, c.1)
    }

    #[test]
    fn formulas_compute_their_complex_expressions() {
        let (z, c) = ((0.3, -0.7), (0.1, 0.4));
        let sq = (z.0 * z.0 - z.1 * z.1, 2.0 * z.0 * z.1);
        assert_eq!(run("((z^n)+c)", z, c, 2.0), (sq.0 + c.0, sq.1 + c.1));
        let cube = (
            z.0 * z.0 * z.0 - 3.0 * z.0 * z.1 * z.1,
            3.0 * z.0 * z.0 * z.1 - z.1 * z.1 * z.1,
        );
        assert_eq!(run("((z^n)+c)", z, c, 3.0), (cube.0 + c.0, cube.1 + c.1));
        // z·c − 2.5 and z/c.
        let zc = (z.0 * c.0 - z.1 * c.1, z.0 * c.1 + z.1 * c.0);
        assert_eq!(run("((z*c)-2.5)", z, c, 2.0), (zc.0 - 2.5, zc.1));
        let q = run("(z/c)", z, c, 2.0);
        let back = (q.0 * c.0 - q.1 * c.1, q.0 * c.1 + q.1 * c.0);
        assert!((back.0 - z.0).abs() < 1e-12 && (back.1 - z.1).abs() < 1e-12);
        // The fifth power multiplied out.
        let z5 = run("(z^5)", z, c, 2.0);
        let m = (z.0 * z.0 + z.1 * z.1).powf(2.5);
        let a = 5.0 * z.1.atan2(z.0);
        assert!((z5.0 - m * a.cos()).abs() < 1e-12 && (z5.1 - m * a.sin()).abs() < 1e-12);
    }

    #[test]
    fn formulas_that_cannot_run_are_refused_or_give_nan() {
        assert!(prepare(&"z".repeat(90)).is_err());
        assert!(prepare("(z)").is_err());
        assert!(prepare("(z\u{263a}c)").is_err());
        assert!(run("(z+)", (1.0, 1.0), (0.0, 0.0), 2.0).0.is_nan());
        assert!(run("", (1.0, 1.0), (0.0, 0.0), 2.0).0.is_nan());
    }
}
