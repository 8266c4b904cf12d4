//! The parametric curves of JWildfire's `maurer_lines` (JWildfire 9.00, `MaurerLinesFunc`, by
//! Gregg Helt; see his "A Rose by Any Other Name…", Bridges 2016): nineteen closed or open
//! curves whose points, taken at equal steps of the curve parameter, the variation joins by
//! chords. Each curve reads up to eight shape values a…h; what they mean depends on the curve.

use std::f64::consts::{PI, TAU};

/// Java's `Math.signum`: 0 for ±0 (Rust's `signum` gives ±1 there), NaN for NaN.
fn signum(v: f64) -> f64 {
    if v == 0.0 || v.is_nan() {
        v
    } else {
        v.signum()
    }
}

/// Greatest common divisor of two integers, never negative (0 for 0 and 0), as Java's
/// `BigInteger.gcd`.
pub(super) fn gcd(a: i64, b: i64) -> i64 {
    let (mut a, mut b) = (a.unsigned_abs(), b.unsigned_abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    i64::try_from(a).unwrap_or(i64::MAX)
}

/// One of the curves with its shape values.
#[derive(Clone, Copy, Debug)]
pub(super) struct Curve {
    /// JWildfire's curve number (0 circle … 18 super-rhodonea; others draw the circle).
    pub mode: i32,
    /// The shape values a…h.
    pub s: [f64; 8],
}

impl Curve {
    /// The curve's point at parameter `t`.
    pub fn point(&self, t: f64) -> (f64, f64) {
        let [a, b, c, d, e, f, g, h] = self.s;
        let polar = |r: f64| (r * t.cos(), r * t.sin());
        match self.mode {
            // Polygon with ⌊a⌋ sides (its polar equation).
            1 => {
                let n = a.floor();
                let theta = (t % TAU).abs();
                let r = (PI / n).cos() / ((theta % (TAU / n)) - PI / n).cos();
                (r * theta.cos(), r * theta.sin())
            }
            // Ellipse with half-axes a and b.
            2 => (a * t.cos(), b * t.sin()),
            // Rhodonea (rose) r = cos(k·t) + c, k = a/b.
            3 => polar((a / b * t).cos() + c),
            // Epitrochoid: circle of radius b rolling outside one of radius a, pen at c.
            4 => {
                let q = (a + b) / b * t;
                (
                    (a + b) * t.cos() - c * q.cos(),
                    (a + b) * t.sin() - c * q.sin(),
                )
            }
            // Hypotrochoid: inside.
            5 => {
                let q = (a - b) / b * t;
                (
                    (a - b) * t.cos() + c * q.cos(),
                    (a - b) * t.sin() - c * q.sin(),
                )
            }
            // Lissajous figure.
            6 => ((a * t + c).sin(), (b * t).sin()),
            // Epispiral r = 1/cos(k·t) + c.
            7 => polar(1.0 / (a / b * t).cos() + c),
            // Gielis' supershape with m = a, n1 = b, n2 = c, n3 = d.
            8 => polar(supershape(t, a, b, c, d, 1.0, 1.0)),
            // Starr's curve.
            9 => {
                let r = 2.0 + (a * t).sin() / 2.0;
                let t2 = t + (b * t).sin() / c;
                (r * t2.cos(), r * t2.sin())
            }
            // Farris' mystery curve.
            10 => (
                t.cos() / a + (6.0 * t).cos() / b + (14.0 * t).sin() / c,
                t.sin() / a + (6.0 * t).sin() / b + (14.0 * t).cos() / c,
            ),
            // Wagon's fanciful curve.
            11 => ((a * t).sin() * (c * t).cos(), (b * t).sin() * (c * t).sin()),
            // Fay's butterfly, halved, turned a quarter.
            12 => {
                let r = 0.5 * ((t.cos()).exp() - 2.0 * (4.0 * t).cos() - (t / 12.0).sin().powi(5));
                (r * t.sin(), r * t.cos())
            }
            // Rigge's roses.
            13 => polar((1.0 - (a * t).cos()) + (1.0 - (a * b * t).cos())),
            14 => polar((1.0 - (a * t).cos()) - (1.0 - (a * b * t).cos())),
            // Rhodonea rigged with a second rose of c times its frequency.
            15 => {
                let k = a / b;
                polar(((k * t).cos() + (c * k * t).cos()) / 2.0)
            }
            16 => {
                let k = a / b;
                polar(((k * t).cos() - (c * k * t).cos()) / 2.0)
            }
            // Superellipse |x/a|^(2/c)… (exponents 2/c and 2/d).
            17 => (
                t.cos().abs().powf(2.0 / c) * a * signum(t.cos()),
                t.sin().abs().powf(2.0 / d) * b * signum(t.sin()),
            ),
            // Rose times supershape.
            18 => polar((a / b * t).cos() * supershape(t, c, d, e, f, g, h)),
            // Circle of radius a (curve 0 and unknown numbers).
            _ => polar(a),
        }
    }

    /// The curve's velocity at `t`, where JWildfire knows it (the rhodonea only).
    pub fn derivative(&self, t: f64) -> Option<(f64, f64)> {
        if self.mode != 3 {
            return None;
        }
        let [a, b, c, ..] = self.s;
        let k = a / b;
        let dr = -k * (k * t).sin();
        let r = (k * t).cos() + c;
        Some((dr * t.cos() - r * t.sin(), dr * t.sin() + r * t.cos()))
    }

    /// The speed |velocity| at `t` (0 where the velocity is unknown or NaN).
    pub fn speed(&self, t: f64) -> f64 {
        match self.derivative(t) {
            Some((x, y)) if !x.is_nan() && !y.is_nan() => (x * x + y * y).sqrt(),
            _ => 0.0,
        }
    }

    /// The turns of the parameter after which the curve closes, where JWildfire works it out
    /// (rhodonea with integer or rational k, Fay's butterfly); NaN otherwise.
    pub fn cycles_to_close(&self) -> f64 {
        match self.mode {
            3 => {
                let [a, b, c, ..] = self.s;
                let k = a / b;
                if k % 1.0 == 0.0 {
                    if k % 2.0 == 0.0 || c != 0.0 { 1.0 } else { 0.5 }
                } else if a % 1.0 == 0.0 && b % 1.0 == 0.0 {
                    // Relatively prime numerator and denominator: the rose closes after kd
                    // turns, or kd/2 when both are odd.
                    let g = gcd(a as i64, i64::from(b as i32)) as f64;
                    let (kn, kd) = if g != 1.0 { (a / g, b / g) } else { (a, b) };
                    if kn % 2.0 == 0.0 || kd % 2.0 == 0.0 {
                        kd
                    } else {
                        kd / 2.0
                    }
                } else {
                    f64::NAN
                }
            }
            12 => PI * PI,
            _ => f64::NAN,
        }
    }
}

/// Gielis' superformula radius at angle `t`.
fn supershape(t: f64, m: f64, n1: f64, n2: f64, n3: f64, a1: f64, b1: f64) -> f64 {
    let u = ((m * t / 4.0).cos() / a1).abs().powf(n2);
    let v = ((m * t / 4.0).sin() / b1).abs().powf(n3);
    (u + v).powf(-1.0 / n1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve(mode: i32, s: [f64; 8]) -> Curve {
        Curve { mode, s }
    }

    /// The rose r = cos 2t passes through (1, 0) at t = 0 and the origin at t = π/4; its
    /// derivative agrees with a central difference.
    #[test]
    fn rose_points_and_derivative() {
        let c = curve(3, [2.0, 1.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0]);
        let (x, y) = c.point(0.0);
        assert!((x - 1.0).abs() < 1e-15 && y.abs() < 1e-15);
        let (x, y) = c.point(PI / 4.0);
        assert!(x.abs() < 1e-15 && y.abs() < 1e-15);
        let t = 0.37;
        let h = 1e-6;
        let (xa, ya) = c.point(t - h);
        let (xb, yb) = c.point(t + h);
        let (dx, dy) = c.derivative(t).unwrap_or((f64::NAN, f64::NAN));
        assert!((dx - (xb - xa) / (2.0 * h)).abs() < 1e-6);
        assert!((dy - (yb - ya) / (2.0 * h)).abs() < 1e-6);
    }

    /// Closing turns: k = 2 closes after one turn, k = 3 (c = 0) after half, k = 2/3 after
    /// three, k = 3/5 after five halves; the butterfly after π² turns.
    #[test]
    fn closing_turns() {
        let rose = |a: f64, b: f64| curve(3, [a, b, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0]);
        assert_eq!(rose(2.0, 1.0).cycles_to_close(), 1.0);
        assert_eq!(rose(3.0, 1.0).cycles_to_close(), 0.5);
        assert_eq!(rose(2.0, 3.0).cycles_to_close(), 3.0);
        assert_eq!(rose(3.0, 5.0).cycles_to_close(), 2.5);
        assert_eq!(rose(4.0, 6.0).cycles_to_close(), 3.0);
        assert!(rose(2.5, 1.1).cycles_to_close().is_nan());
        assert_eq!(curve(12, [0.0; 8]).cycles_to_close(), PI * PI);
        assert_eq!(gcd(-12, 18), 6);
        assert_eq!(gcd(0, 0), 0);
    }

    /// The polygon's corners lie on the unit circle and its edge midpoints at cos(π/n); the
    /// superellipse with c = d = 2 (exponents 1) is the ellipse, and gives 0 (not ±a) where cos t
    /// is 0.
    #[test]
    fn polygon_and_superellipse() {
        let sq = curve(1, [4.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let (x, y) = sq.point(0.0);
        assert!((x.hypot(y) - 1.0).abs() < 1e-12);
        let (x, y) = sq.point(PI / 4.0);
        assert!((x.hypot(y) - (PI / 4.0).cos()).abs() < 1e-12);
        let se = curve(17, [2.0, 3.0, 2.0, 2.0, 0.0, 0.0, 0.0, 0.0]);
        let (x, y) = se.point(0.7);
        assert!((x - 2.0 * 0.7f64.cos()).abs() < 1e-12 && (y - 3.0 * 0.7f64.sin()).abs() < 1e-12);
        let (x, _) = se.point(PI / 2.0);
        assert!(x.abs() < 1e-12);
    }
}
