//! Special functions: the error function, ln Γ, the Bessel function J₁, Jacobi's elliptic
//! functions (with Fractorium's coarse tolerance) and an accurate acosh.

use std::f64::consts::{FRAC_2_SQRT_PI, LN_2, PI, TAU};

/// The error function erf(x), to about 1e-15 relative (10 ulp at worst, near |x| = 2.5).
/// Below 2.5 the series erf a = 2/√π·e^(−a²)·Σ 2ⁿa^(2n+1) / (1·3·…·(2n+1)) (Abramowitz &
/// Stegun 7.1.6), whose terms are all positive, so nothing cancels; up to 6.5 the complementary
/// function by its continued fraction (A&S 7.1.14) evaluated bottom-up; beyond, 1 to double
/// precision. Odd by construction: erf(−x) = −erf(x) exactly.
#[inline]
pub fn erf(x: f64) -> f64 {
    if x.is_nan() {
        return x;
    }
    let a = x.abs();
    let r = if a < 2.5 {
        let a2 = a * a;
        let mut term = a;
        let mut sum = a;
        let mut k = 1.0;
        loop {
            k += 2.0;
            term *= 2.0 * a2 / k;
            sum += term;
            if term <= sum * 1e-17 {
                break;
            }
        }
        FRAC_2_SQRT_PI * (-a2).exp() * sum
    } else if a < 6.5 {
        // erfc(a) = e^(−a²)/√π · 1/(a + ½/(a + 1/(a + (3/2)/(a + …)))).
        let mut f = a;
        for n in (1..=60).rev() {
            f = a + (n as f64 * 0.5) / f;
        }
        1.0 - (-a * a).exp() * (FRAC_2_SQRT_PI * 0.5) / f
    } else {
        1.0
    };
    r.copysign(x)
}

/// ln Γ(x) for x ≥ 0 by the Lanczos approximation (g = 7, nine coefficients; Press et al.,
/// "Numerical Recipes", §6.1): about 1e-15 relative, and exactly 0 at the zeros 1 and 2; +∞
/// at 0 and for +∞, NaN for NaN. Negative arguments give +∞ (the variations that use it pass
/// a radius).
#[inline]
pub fn ln_gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x.is_nan() {
        return x;
    }
    if x <= 0.0 || x == f64::INFINITY {
        return f64::INFINITY;
    }
    if x < 0.5 {
        // Γ(x) = Γ(x + 1) / x.
        return ln_gamma(x + 1.0) - x.ln();
    }
    if x == 1.0 || x == 2.0 {
        return 0.0;
    }
    let z = x - 1.0;
    let mut series = C[0];
    for (k, c) in C.iter().enumerate().skip(1) {
        series += c / (z + k as f64);
    }
    let t = z + G + 0.5;
    0.5 * TAU.ln() + (z + 0.5) * t.ln() - t + series.ln()
}

/// Bessel function of the first kind of order 1, J₁(x): its power series
/// Σ (−1)ᵏ (x/2)^(2k+1) / (k!(k+1)!) up to |x| = 12, Hankel's asymptotic expansion
/// √(2/(πx))·(P cos χ − Q sin χ), χ = x − 3π/4, beyond (summed until its terms stop
/// shrinking; Abramowitz & Stegun 9.2.5).
#[inline]
pub fn bessel_j1(x: f64) -> f64 {
    let ax = x.abs();
    if ax < 12.0 {
        let h = 0.5 * x;
        let q = -h * h;
        let mut term = h;
        let mut sum = h;
        let mut k = 0.0;
        loop {
            k += 1.0;
            term *= q / (k * (k + 1.0));
            sum += term;
            if term.abs() <= 1e-17 * sum.abs().max(1e-300) {
                break;
            }
        }
        return sum;
    }
    // μ = 4ν² = 4 for ν = 1.
    let mu = 4.0;
    let z8 = 8.0 * ax;
    let mut p = 1.0;
    let mut q = 0.0;
    let mut term = 1.0;
    let mut k = 1.0;
    let mut best = f64::INFINITY;
    loop {
        let odd = 2.0 * k - 1.0;
        term *= (mu - odd * odd) / (k * z8);
        if term.abs() >= best {
            break;
        }
        best = term.abs();
        if (k as i32) % 2 == 1 {
            q += if (k as i32 / 2) % 2 == 0 { term } else { -term };
        } else {
            p += if (k as i32 / 2) % 2 == 1 { -term } else { term };
        }
        if best < 1e-17 || k > 60.0 {
            break;
        }
        k += 1.0;
    }
    let chi = ax - 0.75 * PI;
    let v = (2.0 / (PI * ax)).sqrt() * (p * chi.cos() - q * chi.sin());
    if x < 0.0 { -v } else { v }
}

/// Jacobi's elliptic functions (sn, cn, dn) of `u` for the complementary parameter `mc`
/// (= 1 − m), by the descending Landen / arithmetic–geometric-mean scheme (Bulirsch's
/// algorithm, as in "Numerical Recipes" §6.11) with Fractorium's coarse tolerance: the AGM
/// stops once two means agree to 3·10⁻⁴ relative, after at most 8 steps, which the
/// variations' shapes depend on. mc = 0 is the hyperbolic limit (tanh u, sech u, sech u); a
/// negative mc is handled by the reciprocal-modulus transformation.
#[inline(always)]
pub fn jacobi_elliptic(u: f64, mc: f64) -> (f64, f64, f64) {
    if mc == 0.0 {
        let sech = 1.0 / u.cosh();
        return (u.tanh(), sech, sech);
    }
    const TOL: f64 = 0.0003;
    let negative = mc < 0.0;
    let mut m = mc;
    let mut arg = u;
    let mut scale = 1.0;
    if negative {
        scale = 1.0 - m;
        m = -m / scale;
        scale = scale.sqrt();
        arg *= scale;
    }
    let mut arith = [0.0f64; 8];
    let mut geom = [0.0f64; 8];
    let mut a = 1.0;
    let mut mean = 0.0;
    let mut steps = 0;
    for k in 0..8 {
        steps = k;
        arith[k] = a;
        m = m.sqrt();
        geom[k] = m;
        mean = 0.5 * (a + m);
        if (a - m).abs() <= TOL * a {
            break;
        }
        m *= a;
        a = mean;
    }
    arg *= mean;
    let (mut sn, mut cn) = (arg.sin(), arg.cos());
    let mut dn = 1.0;
    if sn != 0.0 {
        let mut ratio = cn / sn;
        let mut c = mean * ratio;
        for k in (0..=steps).rev() {
            let b = arith[k];
            ratio *= c;
            c *= dn;
            dn = (geom[k] + ratio) / (b + ratio);
            ratio = c / b;
        }
        let s = 1.0 / (c * c + 1.0).sqrt();
        sn = if sn < 0.0 { -s } else { s };
        cn = c * sn;
    }
    if negative {
        (sn / scale, dn, cn)
    } else {
        (sn, cn, dn)
    }
}

/// sn(u | 1 − mc) alone: [`jacobi_elliptic`]'s first value, without computing the others.
#[inline]
pub fn jacobi_sn(u: f64, mc: f64) -> f64 {
    jacobi_elliptic(u, mc).0
}

/// acosh(x), accurate near 1 where the textbook ln(x + √(x² − 1)) (and std's `acosh`) lose
/// digits: ln1p(t + √(2t + t²)) with t = x − 1 up to 2, ln(2x − 1/(x + √(x² − 1))) above, and
/// ln x + ln 2 from 2²⁸ on (where x + √(x² − 1) = 2x in double precision). NaN below 1.
#[inline]
pub fn acosh(x: f64) -> f64 {
    if x < 1.0 {
        f64::NAN
    } else if x >= 268435456.0 {
        if x.is_finite() { x.ln() + LN_2 } else { x }
    } else if x > 2.0 {
        (2.0 * x - 1.0 / (x + (x * x - 1.0).sqrt())).ln()
    } else {
        let t = x - 1.0;
        (t + (2.0 * t + t * t).sqrt()).ln_1p()
    }
}
