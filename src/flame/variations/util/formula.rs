//! Formula text as JWildfire's plot variations take it (`polarplot3d_wf_formula`, …): one Java
//! expression over named doubles, with the functions and constants of JWildfire's `MathLib`
//! (`sin`, `pow`, `sqr`, `fabs`, `M_PI`, …), which JWildfire compiles as the body of
//! `return …;`. Here it is compiled once into a small stack program stored as `f64` words (so
//! that it lives in a variation's shared data) and run per point by [`run`].
//!
//! Java's typing is kept where it changes a value: an integer literal is an `int`, and an
//! operation between two `int`s is integer arithmetic (`1/2` is 0, wrapping on overflow); such
//! parts hold no variable, so they are folded while compiling. `sign` (an `int` in Java) is
//! taken as a double. Comparisons (`<`, `<=`, `>`, `>=`, `==`, `!=`), `&&`, `||`, `!` and the
//! conditional `c ? a : b` are read too (a comparison is 1 or 0; both branches of a
//! conditional are evaluated, which is the same since nothing has side effects). What is not an
//! expression of this kind (statements, casts, unknown names) is refused with a message saying
//! where.

/// Most words of a compiled program.
const MAX_WORDS: usize = 4096;
/// Deepest nesting of parentheses and unary operators.
const MAX_NESTING: usize = 64;
/// Deepest operand stack of a program ([`run`] keeps it in an array of this size).
pub const MAX_STACK: usize = 32;

const OP_CONST: f64 = 0.0;
const OP_VAR: f64 = 1.0;
const OP_NEG: f64 = 2.0;
const OP_ADD: f64 = 3.0;
const OP_SUB: f64 = 4.0;
const OP_MUL: f64 = 5.0;
const OP_DIV: f64 = 6.0;
const OP_REM: f64 = 7.0;
const OP_F1: f64 = 8.0;
const OP_F2: f64 = 9.0;
const OP_LT: f64 = 10.0;
const OP_LE: f64 = 11.0;
const OP_GT: f64 = 12.0;
const OP_GE: f64 = 13.0;
const OP_EQ: f64 = 14.0;
const OP_NE: f64 = 15.0;
const OP_AND: f64 = 16.0;
const OP_OR: f64 = 17.0;
const OP_NOT: f64 = 18.0;
/// The conditional: pops the condition, the value if true and the value if false.
const OP_SEL: f64 = 19.0;

/// Functions of one argument, by index.
const F1: &[&str] = &[
    "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp", "log", "log10",
    "sqrt", "fabs", "abs", "sqr", "floor", "ceil", "round", "rint", "trunc", "frac", "sign",
    "acosh", "cbrt",
];
/// Functions of two arguments, by index.
const F2: &[&str] = &["atan2", "pow", "min", "max", "fmod", "hypot"];

fn f1(k: usize, a: f64) -> f64 {
    match k {
        0 => a.sin(),
        1 => a.cos(),
        2 => a.tan(),
        3 => a.asin(),
        4 => a.acos(),
        5 => a.atan(),
        6 => a.sinh(),
        7 => a.cosh(),
        8 => a.tanh(),
        9 => a.exp(),
        10 => a.ln(),
        11 => a.log10(),
        12 => a.sqrt(),
        13 | 14 => a.abs(),
        15 => a * a,
        16 => a.floor(),
        17 => a.ceil(),
        // Java's Math.round: ⌊a + ½⌋.
        18 => (a + 0.5).floor(),
        19 => a.round_ties_even(),
        20 => a.trunc(),
        21 => a - a.trunc(),
        22 => {
            if a > 0.0 {
                1.0
            } else if a < 0.0 {
                -1.0
            } else {
                0.0
            }
        }
        // MathLib's acosh: ln(√(d² − 1) + d).
        23 => ((a * a - 1.0).sqrt() + a).ln(),
        _ => a.cbrt(),
    }
}

fn f2(k: usize, a: f64, b: f64) -> f64 {
    match k {
        0 => a.atan2(b),
        1 => a.powf(b),
        // Java's Math.min/max: NaN wins.
        2 if a.is_nan() || b.is_nan() => f64::NAN,
        2 => a.min(b),
        3 if a.is_nan() || b.is_nan() => f64::NAN,
        3 => a.max(b),
        4 => a % b,
        _ => a.hypot(b),
    }
}

/// Named constants of `MathLib` (and `Math.PI`, `Math.E`).
fn constant(name: &str) -> Option<f64> {
    use std::f64::consts::*;
    Some(match name {
        "M_PI" | "Math.PI" => PI,
        "M_PI_2" => PI * 0.5,
        "M_PI_4" => PI * 0.25,
        "M_1_PI" => 1.0 / PI,
        "M_2_PI" => 2.0 / PI,
        "M_2PI" => 2.0 * PI,
        "M_1_2PI" => 1.0 / PI / 2.0,
        "M_SQRT2" => SQRT_2,
        "M_E" | "Math.E" => E,
        _ => return None,
    })
}

/// A value while compiling: a Java `int` or `double` known at compile time, or code.
enum Val {
    Int(i32),
    Dbl(f64),
    Code(Vec<f64>, usize),
}

impl Val {
    /// Code that pushes the value, and the stack depth it needs.
    fn code(self) -> (Vec<f64>, usize) {
        match self {
            Val::Int(i) => (vec![OP_CONST, i as f64], 1),
            Val::Dbl(d) => (vec![OP_CONST, d], 1),
            Val::Code(c, d) => (c, d),
        }
    }
    fn num(&self) -> Option<f64> {
        match *self {
            Val::Int(i) => Some(i as f64),
            Val::Dbl(d) => Some(d),
            Val::Code(..) => None,
        }
    }
}

struct Parser<'a> {
    s: &'a [u8],
    at: usize,
    vars: &'a [&'a str],
    nesting: usize,
}

/// Compiles `src`, whose free names are `vars` (a variable's index is its place there).
pub fn compile(src: &str, vars: &[&str]) -> Result<Vec<f64>, String> {
    let mut p = Parser {
        s: src.as_bytes(),
        at: 0,
        vars,
        nesting: 0,
    };
    let v = p.ternary()?;
    p.skip_ws();
    // JWildfire's text is the body of `return …;`: a trailing semicolon is harmless.
    if p.peek() == Some(b';') {
        p.at += 1;
        p.skip_ws();
    }
    if p.at < p.s.len() {
        return Err(p.error("an operator or the end of the formula"));
    }
    let (code, depth) = v.code();
    if depth > MAX_STACK || code.len() > MAX_WORDS {
        return Err("the formula is too long or too deeply nested".into());
    }
    Ok(code)
}

/// Runs a program of [`compile`] on the variables' values.
pub fn run(code: &[f64], vars: &[f64]) -> f64 {
    let mut st = [0.0f64; MAX_STACK];
    let mut n = 0usize;
    let mut i = 0usize;
    while i < code.len() {
        let op = code[i];
        i += 1;
        if op == OP_CONST {
            st[n] = code[i];
            n += 1;
            i += 1;
        } else if op == OP_VAR {
            st[n] = vars.get(code[i] as usize).copied().unwrap_or(0.0);
            n += 1;
            i += 1;
        } else if op == OP_NEG {
            st[n - 1] = -st[n - 1];
        } else if op == OP_NOT {
            st[n - 1] = truth(st[n - 1] == 0.0);
        } else if op == OP_SEL {
            let (c, a, b) = (st[n - 3], st[n - 2], st[n - 1]);
            n -= 2;
            st[n - 1] = if c != 0.0 { a } else { b };
        } else if op == OP_F1 {
            st[n - 1] = f1(code[i] as usize, st[n - 1]);
            i += 1;
        } else {
            let (a, b) = (st[n - 2], st[n - 1]);
            n -= 1;
            st[n - 1] = if op == OP_F2 {
                i += 1;
                f2(code[i - 1] as usize, a, b)
            } else {
                binary(op, a, b)
            };
        }
    }
    if n == 1 { st[0] } else { f64::NAN }
}

fn truth(b: bool) -> f64 {
    if b { 1.0 } else { 0.0 }
}

fn binary(op: f64, a: f64, b: f64) -> f64 {
    if op >= OP_LT {
        return truth(match op {
            _ if op == OP_LT => a < b,
            _ if op == OP_LE => a <= b,
            _ if op == OP_GT => a > b,
            _ if op == OP_GE => a >= b,
            _ if op == OP_EQ => a == b,
            _ if op == OP_NE => a != b,
            _ if op == OP_AND => a != 0.0 && b != 0.0,
            _ => a != 0.0 || b != 0.0,
        });
    }
    if op == OP_ADD {
        a + b
    } else if op == OP_SUB {
        a - b
    } else if op == OP_MUL {
        a * b
    } else if op == OP_DIV {
        a / b
    } else {
        a % b
    }
}

/// Combines two values with a binary operator (or a two-argument function, `op` = OP_F2 and
/// `k` its index): folded when both are known, with Java's `int` arithmetic between `int`s.
fn combine(op: f64, k: usize, a: Val, b: Val) -> Result<Val, String> {
    if let (Val::Int(x), Val::Int(y)) = (&a, &b)
        && op != OP_F2
        && op < OP_LT
    {
        let (x, y) = (*x, *y);
        if (op == OP_DIV || op == OP_REM) && y == 0 {
            return Err("an integer division by zero".into());
        }
        return Ok(Val::Int(match op {
            _ if op == OP_ADD => x.wrapping_add(y),
            _ if op == OP_SUB => x.wrapping_sub(y),
            _ if op == OP_MUL => x.wrapping_mul(y),
            _ if op == OP_DIV => x.wrapping_div(y),
            _ => x.wrapping_rem(y),
        }));
    }
    if let (Some(x), Some(y)) = (a.num(), b.num()) {
        let v = if op == OP_F2 {
            f2(k, x, y)
        } else {
            binary(op, x, y)
        };
        return Ok(Val::Dbl(v));
    }
    let (mut ca, da) = a.code();
    let (cb, db) = b.code();
    ca.extend_from_slice(&cb);
    ca.push(op);
    if op == OP_F2 {
        ca.push(k as f64);
    }
    let depth = da.max(db + 1);
    if ca.len() > MAX_WORDS || depth > MAX_STACK {
        return Err("the formula is too long or too deeply nested".into());
    }
    Ok(Val::Code(ca, depth))
}

impl Parser<'_> {
    fn peek(&self) -> Option<u8> {
        self.s.get(self.at).copied()
    }

    fn skip_ws(&mut self) {
        while self.peek().is_some_and(|c| c.is_ascii_whitespace()) {
            self.at += 1;
        }
    }

    fn error(&self, wanted: &str) -> String {
        match self.peek() {
            Some(_) => {
                let rest = String::from_utf8_lossy(&self.s[self.at..]);
                let rest: String = rest.chars().take(20).collect();
                format!("expected {wanted} at character {}: '{rest}'", self.at + 1)
            }
            None => format!("expected {wanted} at the end of the formula"),
        }
    }

    fn eat(&mut self, c: u8) -> bool {
        self.skip_ws();
        if self.peek() == Some(c) {
            self.at += 1;
            true
        } else {
            false
        }
    }

    /// Eats the two-character operator `op` (not followed by `=` when it is one character
    /// long and could start `<=`, `>=`, `==` or `!=`).
    fn eat_op(&mut self, op: &[u8]) -> bool {
        self.skip_ws();
        if !self.s[self.at..].starts_with(op) {
            return false;
        }
        if op.len() == 1 && self.s.get(self.at + 1) == Some(&b'=') {
            return false;
        }
        self.at += op.len();
        true
    }

    /// `c ? a : b`, or a logical expression.
    fn ternary(&mut self) -> Result<Val, String> {
        self.nesting += 1;
        if self.nesting > MAX_NESTING {
            return Err("the formula is too deeply nested".into());
        }
        let c = self.logic_or()?;
        if !self.eat(b'?') {
            self.nesting -= 1;
            return Ok(c);
        }
        let a = self.ternary()?;
        if !self.eat(b':') {
            return Err(self.error("':' of the conditional"));
        }
        let b = self.ternary()?;
        self.nesting -= 1;
        if let Some(c) = c.num() {
            return Ok(if c != 0.0 { a } else { b });
        }
        let (mut code, dc) = c.code();
        let (ca, da) = a.code();
        let (cb, db) = b.code();
        code.extend_from_slice(&ca);
        code.extend_from_slice(&cb);
        code.push(OP_SEL);
        let depth = dc.max(da + 1).max(db + 2);
        if code.len() > MAX_WORDS || depth > MAX_STACK {
            return Err("the formula is too long or too deeply nested".into());
        }
        Ok(Val::Code(code, depth))
    }

    fn logic_or(&mut self) -> Result<Val, String> {
        let mut v = self.logic_and()?;
        while self.eat_op(b"||") {
            let r = self.logic_and()?;
            v = combine(OP_OR, 0, v, r)?;
        }
        Ok(v)
    }

    fn logic_and(&mut self) -> Result<Val, String> {
        let mut v = self.equality()?;
        while self.eat_op(b"&&") {
            let r = self.equality()?;
            v = combine(OP_AND, 0, v, r)?;
        }
        Ok(v)
    }

    fn equality(&mut self) -> Result<Val, String> {
        let mut v = self.relation()?;
        loop {
            let op = if self.eat_op(b"==") {
                OP_EQ
            } else if self.eat_op(b"!=") {
                OP_NE
            } else {
                return Ok(v);
            };
            let r = self.relation()?;
            v = combine(op, 0, v, r)?;
        }
    }

    fn relation(&mut self) -> Result<Val, String> {
        let mut v = self.expr()?;
        loop {
            let op = if self.eat_op(b"<=") {
                OP_LE
            } else if self.eat_op(b">=") {
                OP_GE
            } else if self.eat_op(b"<") {
                OP_LT
            } else if self.eat_op(b">") {
                OP_GT
            } else {
                return Ok(v);
            };
            let r = self.expr()?;
            v = combine(op, 0, v, r)?;
        }
    }

    fn expr(&mut self) -> Result<Val, String> {
        let mut v = self.term()?;
        loop {
            let op = if self.eat(b'+') {
                OP_ADD
            } else if self.eat(b'-') {
                OP_SUB
            } else {
                return Ok(v);
            };
            let r = self.term()?;
            v = combine(op, 0, v, r)?;
        }
    }

    fn term(&mut self) -> Result<Val, String> {
        let mut v = self.unary()?;
        loop {
            let op = if self.eat(b'*') {
                OP_MUL
            } else if self.eat(b'/') {
                OP_DIV
            } else if self.eat(b'%') {
                OP_REM
            } else {
                return Ok(v);
            };
            let r = self.unary()?;
            v = combine(op, 0, v, r)?;
        }
    }

    fn unary(&mut self) -> Result<Val, String> {
        self.nesting += 1;
        if self.nesting > MAX_NESTING {
            return Err("the formula is too deeply nested".into());
        }
        let v = if self.eat(b'-') {
            match self.unary()? {
                Val::Int(i) => Val::Int(i.wrapping_neg()),
                Val::Dbl(d) => Val::Dbl(-d),
                Val::Code(mut c, d) => {
                    c.push(OP_NEG);
                    Val::Code(c, d)
                }
            }
        } else if self.eat(b'+') {
            self.unary()?
        } else if self.eat_op(b"!") {
            match self.unary()? {
                Val::Code(mut c, d) => {
                    c.push(OP_NOT);
                    Val::Code(c, d)
                }
                v => Val::Int(i32::from(v.num() == Some(0.0))),
            }
        } else {
            self.primary()?
        };
        self.nesting -= 1;
        Ok(v)
    }

    fn primary(&mut self) -> Result<Val, String> {
        self.skip_ws();
        match self.peek() {
            Some(b'(') => {
                self.at += 1;
                let v = self.ternary()?;
                if !self.eat(b')') {
                    return Err(self.error("')'"));
                }
                Ok(v)
            }
            Some(c) if c.is_ascii_digit() || c == b'.' => self.number(),
            Some(c) if c.is_ascii_alphabetic() || c == b'_' => self.name(),
            _ => Err(self.error("a number, a name or '('")),
        }
    }

    fn number(&mut self) -> Result<Val, String> {
        let start = self.at;
        let mut real = false;
        while let Some(c) = self.peek() {
            if c.is_ascii_digit() {
                self.at += 1;
            } else if c == b'.' {
                real = true;
                self.at += 1;
            } else if c == b'e' || c == b'E' {
                real = true;
                self.at += 1;
                if matches!(self.peek(), Some(b'+' | b'-')) {
                    self.at += 1;
                }
            } else {
                break;
            }
        }
        let text = std::str::from_utf8(&self.s[start..self.at]).unwrap_or("");
        let suffix = self.peek().map(|c| c.to_ascii_lowercase());
        if matches!(suffix, Some(b'd' | b'f' | b'l')) {
            self.at += 1;
        }
        let bad = || format!("'{text}' is not a number (character {})", start + 1);
        match suffix {
            Some(b'f') => text
                .parse::<f32>()
                .map(|f| Val::Dbl(f as f64))
                .map_err(|_| bad()),
            Some(b'd') => text.parse::<f64>().map(Val::Dbl).map_err(|_| bad()),
            _ if real => text.parse::<f64>().map(Val::Dbl).map_err(|_| bad()),
            // An int literal (a long one is taken as a double of its value).
            Some(b'l') => text
                .parse::<i64>()
                .map(|i| Val::Dbl(i as f64))
                .map_err(|_| bad()),
            _ => text.parse::<i32>().map(Val::Int).map_err(|_| bad()),
        }
    }

    fn name(&mut self) -> Result<Val, String> {
        let start = self.at;
        while self
            .peek()
            .is_some_and(|c| c.is_ascii_alphanumeric() || c == b'_' || c == b'.')
        {
            self.at += 1;
        }
        let full = std::str::from_utf8(&self.s[start..self.at]).unwrap_or("");
        if let Some(c) = constant(full) {
            return Ok(Val::Dbl(c));
        }
        // `Math.sin` and `MathLib.sin` are the functions of the same name.
        let name = full
            .strip_prefix("Math.")
            .or_else(|| full.strip_prefix("MathLib."))
            .unwrap_or(full);
        if !self.eat(b'(') {
            return match self.vars.iter().position(|v| *v == name) {
                Some(i) => Ok(Val::Code(vec![OP_VAR, i as f64], 1)),
                None => Err(format!(
                    "unknown name '{full}' at character {} (the formula knows {})",
                    start + 1,
                    self.vars.join(", ")
                )),
            };
        }
        let mut args = vec![self.ternary()?];
        while self.eat(b',') {
            args.push(self.ternary()?);
        }
        if !self.eat(b')') {
            return Err(self.error("')' closing the arguments"));
        }
        let unknown = || format!("unknown function '{full}' at character {}", start + 1);
        match args.len() {
            1 => {
                let k = F1.iter().position(|f| *f == name).ok_or_else(unknown)?;
                let a = args.pop().expect("one argument");
                Ok(match a {
                    Val::Code(mut c, d) => {
                        c.extend_from_slice(&[OP_F1, k as f64]);
                        Val::Code(c, d)
                    }
                    v => Val::Dbl(f1(k, v.num().expect("a known value"))),
                })
            }
            2 => {
                let k = F2.iter().position(|f| *f == name).ok_or_else(unknown)?;
                let b = args.pop().expect("two arguments");
                let a = args.pop().expect("two arguments");
                combine(OP_F2, k, a, b)
            }
            n => Err(format!(
                "'{full}' at character {} takes 1 or 2 arguments, not {n}",
                start + 1
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn eval(src: &str, t: f64, u: f64) -> f64 {
        run(&compile(src, &["t", "u"]).unwrap(), &[t, u])
    }

    #[test]
    fn java_expressions_evaluate_as_java_does() {
        let (t, u) = (0.7, -1.3);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-15 * b.abs().max(1.0);
        assert!(close(
            eval("(sin(5*t) + cos(6.0*u)) + 0.25", t, u),
            (5.0 * t).sin() + (6.0 * u).cos() + 0.25
        ));
        assert!(close(eval("t / (2 + u) + 1", t, u), t / (2.0 + u) + 1.0));
        assert!(close(eval("sqr(u) + -t*-2", t, u), u * u + t * 2.0));
        assert!(close(
            eval("pow(fabs(u), 1.5) - M_PI", t, u),
            u.abs().powf(1.5) - std::f64::consts::PI
        ));
        assert!(close(eval("Math.atan2(u, t) % 1", t, u), u.atan2(t) % 1.0));
        // Java's int arithmetic between integer literals.
        assert_eq!(eval("1/2 * t", t, u), 0.0);
        assert_eq!(eval("7 % 4 + 1.0/2", t, u), 3.5);
        assert_eq!(eval("min(t, u);", t, u), u);
        assert_eq!(eval("1e-1f", t, u), 0.1f32 as f64);
        // Comparisons, logic and the conditional.
        assert_eq!(eval("t>0?pow(t,2.5):-pow(-t,2.5)", t, u), t.powf(2.5));
        assert_eq!(eval("u>0?pow(u,2.5):-pow(-u,2.5)", t, u), -(-u).powf(2.5));
        assert_eq!(eval("t >= 0.7 && !(u == -1.3) ? 1 : 2", t, u), 2.0);
        assert_eq!(eval("t <= 0.5 || u != 0 ? 3 : 4", t, u), 3.0);
        assert_eq!(eval("1 < 2 ? t : u", t, u), t);
        assert_eq!(eval("(t < u) + 0.5", t, u), 0.5);
        assert_eq!(eval("t > 0 ? u > 0 ? 1 : 2 : 3", t, u), 2.0);
    }

    #[test]
    fn bad_formulas_are_refused_with_where() {
        let c = |s: &str| compile(s, &["t", "u"]).unwrap_err();
        assert!(c("sin(t").contains("')'"), "{}", c("sin(t"));
        assert!(c("x + 1").contains("unknown name 'x'"));
        assert!(c("foo(t)").contains("unknown function 'foo'"));
        assert!(c("t +").contains("end of the formula"));
        assert!(c("t u").contains("character 3"));
        assert!(c("1/0").contains("division by zero"));
        assert!(c(&"(".repeat(500)).contains("nested"));
        assert!(c("t > 0 ? 1").contains("':'"));
        assert!(c(&"t?".repeat(200)).contains("nested"));
        let deep = (0..40).fold("t".to_string(), |s, _| format!("t + ({s})"));
        assert!(c(&deep).contains("nested"));
    }
}
