//! The values of escape-time view files (`.esc`) and of the command line: family names,
//! complex numbers, centres of any precision, widths down to extended exponents, polynomials;
//! read and written back exactly.

use crate::escape::centre::Centre;
use crate::escape::fx::Fx;
use crate::escape::{C, EscapeDoc, Family, Warp};

/// Parse a family name into its default family.
pub fn family_from_name(name: &str) -> Option<Family> {
    Some(match name.trim().to_ascii_lowercase().as_str() {
        "mandelbrot" => Family::Mandelbrot { power: 2 },
        "multibrot" => Family::Mandelbrot { power: 3 },
        "burning-ship" | "burningship" | "burning_ship" => Family::BurningShip,
        "julia" => Family::Julia {
            power: 2,
            c: C::new(-0.8, 0.156),
        },
        "newton" => Family::Newton {
            coeffs: vec![C::ONE, C::ZERO, C::ZERO, C::new(-1.0, 0.0)],
        },
        "logistic" => Family::Logistic {
            z0: C::new(0.5, 0.0),
            kose: false,
        },
        "cubic" => Family::Cubic {
            p: C::new(0.171, 0.0),
        },
        "warped-julia" | "warped" | "galaxy" => {
            Family::WarpedJulia(Warp::preset(crate::escape::Preset::WarpedJulia))
        }
        _ => return None,
    })
}

pub(super) fn fmt_c(c: C) -> String {
    format!("{}, {}", c.re, c.im)
}

/// Parse "re, im" (or "re,im", "re im", or a single real).
pub fn parse_complex(s: &str) -> Option<C> {
    let parts: Vec<&str> = s
        .split(|ch: char| ch == ',' || ch.is_whitespace())
        .filter(|t| !t.is_empty())
        .collect();
    let num = |t: &str| t.parse::<f64>().ok().filter(|v| v.is_finite());
    match parts.as_slice() {
        [re] => Some(C::new(num(re)?, 0.0)),
        [re, im] => Some(C::new(num(re)?, num(im)?)),
        _ => None,
    }
}

/// Parse a centre "re, im" (or "re,im", "re im", or a single real) to any number of digits
/// (up to [`crate::escape::centre::MAX_DIGITS`] after the point, for deep zooms).
pub fn parse_center(s: &str) -> Result<Centre, String> {
    let parts: Vec<&str> = s
        .split(|ch: char| ch == ',' || ch.is_whitespace())
        .filter(|t| !t.is_empty())
        .collect();
    match parts.as_slice() {
        [re] => Centre::parse(re, "0"),
        [re, im] => Centre::parse(re, im),
        _ => Err("expected 're, im'".into()),
    }
}

/// The centre as written in a view file: shortest f64 form, or the digits the zoom needs
/// when the view is a deep zoom.
pub fn format_center(doc: &EscapeDoc) -> String {
    if crate::escape::render::is_deep(&doc.params.family, &doc.view, doc.height) {
        let [x, y] = doc.view.centre_text();
        format!("{x}, {y}")
    } else {
        let [x, y] = doc.view.center();
        format!("{x}, {y}")
    }
}

/// Shortest round-trip form, and for deep-zoom widths (below 1e-4) an exponent with 14
/// significant digits.
pub(super) fn fmt_small(v: Fx) -> String {
    let f = v.to_f64();
    if f.abs() >= 1e-4 || v.is_zero() {
        format!("{f}")
    } else {
        // Fourteen significant digits: what survives the width's trip through the half-height
        // (and the extended number's arithmetic) unchanged.
        format!("{v:.14}")
    }
}

/// Parse a view width: a positive number of any decimal exponent down to the deep-zoom
/// limit (`3`, `1e-1000`).
pub fn parse_width(s: &str) -> Result<Fx, String> {
    let w = Fx::parse(s).ok_or_else(|| {
        format!(
            "width '{}' is not a number; expected a finite number",
            s.trim()
        )
    })?;
    if w.m <= 0.0 || w.m.is_nan() {
        return Err(format!("width '{}' must be positive", s.trim()));
    }
    if w.log10() < crate::escape::render::DEEP_LIMIT_EXP10 {
        return Err(format!(
            "width '{}' is below the deep-zoom limit of 1e-10000",
            s.trim()
        ));
    }
    if w.log10() > 15.0 {
        return Err(format!("width '{}' is too large (at most 1e15)", s.trim()));
    }
    Ok(w)
}

/// Parse polynomial coefficients, highest degree first: real numbers separated by spaces, or
/// complex ones as `re,im` tokens (e.g. "1 0 0 -1" is z³ − 1).
pub fn parse_poly(s: &str) -> Option<Vec<C>> {
    let v: Option<Vec<C>> = s
        .split_whitespace()
        .map(|t| {
            let mut it = t.split(',');
            let re = it.next()?.parse::<f64>().ok().filter(|v| v.is_finite())?;
            let im = match it.next() {
                Some(x) => x.parse::<f64>().ok().filter(|v| v.is_finite())?,
                None => 0.0,
            };
            it.next().is_none().then_some(C::new(re, im))
        })
        .collect();
    v.filter(|c| c.len() >= 2 && c.len() <= 33)
}

pub(super) fn fmt_poly(coeffs: &[C]) -> String {
    coeffs
        .iter()
        .map(|c| {
            if c.im == 0.0 {
                format!("{}", c.re)
            } else {
                format!("{},{}", c.re, c.im)
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}
