//! Escape-time view files (`.esc`): a small `key = value` text naming the family, its
//! parameters, the view, the size and the colouring, so a view can be saved, shared and
//! rendered again. Codes ESC001–ESC006.
//!
//! ```text
//! # ugnis escape-time view
//! kind = julia
//! c = -0.8, 0.156
//! center = 0, 0
//! width = 3
//! size = 800x600
//! max_iter = 500
//! coloring = smooth
//! gradient = ember
//! ```

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::diag::{Diagnostic, Parsed, Pos};
use crate::escape::{C, Coloring, Family, Fill, Sampling, Warp};
use crate::gradient::{self, Gradient};
use crate::noise::Fbm;

pub use super::escape_values::{
    family_from_name, format_center, parse_center, parse_complex, parse_poly, parse_width,
};
use super::escape_values::{fmt_c, fmt_poly, fmt_small};
pub use crate::escape::EscapeDoc;

/// Write a view file.
pub fn write(doc: &EscapeDoc) -> String {
    let p = &doc.params;
    let mut s = String::from("# ugnis escape-time view\n");
    let _ = writeln!(s, "kind = {}", p.family.name());
    match &p.family {
        Family::Mandelbrot { power } => {
            let _ = writeln!(s, "power = {power}");
        }
        Family::Julia { power, c } => {
            let _ = writeln!(s, "power = {power}\nc = {}", fmt_c(*c));
        }
        Family::Newton { coeffs } => {
            let _ = writeln!(s, "poly = {}", fmt_poly(coeffs));
        }
        Family::Logistic { z0, kose } => {
            let _ = writeln!(s, "z0 = {}\nkose = {kose}", fmt_c(*z0));
        }
        Family::Cubic { p } => {
            let _ = writeln!(s, "p = {}", fmt_c(*p));
        }
        Family::BurningShip => {}
        Family::WarpedJulia(w) => {
            let _ = writeln!(
                s,
                "c = {}\nalpha = {}\nturbulence = {}\noctaves = {}\nlacunarity = {}\ngain = {}\n\
                 frequency = {}\nseed = {}\nzero_mean = {}",
                fmt_c(w.c),
                fmt_c(w.alpha),
                w.lambda,
                w.fbm.octaves,
                w.fbm.lacunarity,
                w.fbm.gain,
                w.fbm.frequency,
                w.fbm.seed,
                w.zero_mean
            );
            let _ = match w.sampling {
                Sampling::Polar { radius } => writeln!(s, "sampling = polar\nradius = {radius}"),
                Sampling::Rect { scale } => writeln!(s, "sampling = rect\nscale = {scale}"),
            };
        }
    }
    let _ = writeln!(
        s,
        "center = {}\nwidth = {}\nsize = {}x{}\nmax_iter = {}\ncoloring = {}\ngradient = {}\n\
         offset = {}\nrepeat = {}\ninside = {} {} {}\nperiodicity = {}\nfill = {}",
        format_center(doc),
        fmt_small(doc.world_width_fx()),
        doc.width,
        doc.height,
        p.max_iter,
        p.coloring.name(),
        doc.gradient_source,
        p.palette.offset,
        p.palette.repeat,
        p.palette.inside[0],
        p.palette.inside[1],
        p.palette.inside[2],
        p.periodicity,
        match p.fill {
            Fill::Exact => "exact",
            Fill::Guess => "guess",
        }
    );
    if let Some(b) = p.bailout {
        let _ = writeln!(s, "bailout = {b}");
    }
    if p.bla_eps != crate::escape::bla::EPSILON {
        let _ = writeln!(s, "bla_tolerance = {:e}", p.bla_eps);
    }
    s
}

/// One `key = value` line of a view file: the key in lower case, the value trimmed.
struct Setting<'a> {
    file: &'a str,
    line: usize,
    key: String,
    value: &'a str,
}

type R<T> = Result<T, Diagnostic>;

/// A setting: its key and what reading its value does (the value's type is the reader the
/// setter calls: [`Setting::real`], [`Setting::complex`], …).
struct Key<T> {
    name: &'static str,
    set: fn(&mut T, &Setting) -> R<()>,
}

const fn key<T>(name: &'static str, set: fn(&mut T, &Setting) -> R<()>) -> Key<T> {
    Key { name, set }
}

impl Setting<'_> {
    fn err(&self, code: &'static str, msg: String) -> Diagnostic {
        Diagnostic::error(self.file, Pos::LineCol(self.line, 1), code, msg)
    }

    /// `{key} '{value}': {expected}` (ESC003).
    fn expected(&self, what: &str) -> Diagnostic {
        self.err("ESC003", format!("{} '{}': {what}", self.key, self.value))
    }

    fn number<T: std::str::FromStr>(&self) -> R<T> {
        self.value.parse::<T>().map_err(|_| {
            self.err(
                "ESC003",
                format!("{} '{}' is not a valid number", self.key, self.value),
            )
        })
    }

    /// A whole number from `lo` to `hi` (ESC004 outside).
    fn count(&self, lo: u32, hi: u32) -> R<u32> {
        let n: u32 = self.number()?;
        if !(lo..=hi).contains(&n) {
            return Err(self.err(
                "ESC004",
                format!("{} {n} must be between {lo} and {hi}", self.key),
            ));
        }
        Ok(n)
    }

    /// A finite real number.
    fn real(&self) -> R<f64> {
        let v: f64 = self.number()?;
        if !v.is_finite() {
            return Err(self.err("ESC003", format!("{} must be finite", self.key)));
        }
        Ok(v)
    }

    /// A finite real number above 0 (ESC004 otherwise).
    fn positive(&self) -> R<f64> {
        let v = self.real()?;
        if v <= 0.0 {
            return Err(self.err("ESC004", format!("{} must be positive", self.key)));
        }
        Ok(v)
    }

    /// `re, im` (or a single real).
    fn complex(&self) -> R<C> {
        parse_complex(self.value).ok_or_else(|| self.expected("expected 're, im'"))
    }

    fn boolean(&self) -> R<bool> {
        match self.value.to_ascii_lowercase().as_str() {
            "true" | "1" | "yes" | "on" => Ok(true),
            "false" | "0" | "no" | "off" => Ok(false),
            _ => Err(self.expected("expected true or false")),
        }
    }
}

/// The lines of a view file as settings (blank lines and `#` comments skipped).
fn settings<'a>(text: &'a str, file: &'a str) -> R<Vec<Setting<'a>>> {
    let mut out = Vec::new();
    for (k, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let err = |msg: String| Diagnostic::error(file, Pos::LineCol(k + 1, 1), "ESC001", msg);
        let Some((key, value)) = line.split_once('=') else {
            return Err(err(format!("expected 'key = value', found '{line}'")));
        };
        out.push(Setting {
            file,
            line: k + 1,
            key: key.trim().to_ascii_lowercase(),
            value: value.trim(),
        });
        if out.len() > 200 {
            return Err(err("more than 200 settings".into()));
        }
    }
    Ok(out)
}

/// Apply the settings that `keys` know, in the table's order; a key given twice counts once,
/// with its last value.
fn apply<T>(keys: &[Key<T>], settings: &[Setting], target: &mut T) -> R<()> {
    for k in keys {
        if let Some(s) = settings.iter().rev().find(|s| s.key == k.name) {
            (k.set)(target, s)?;
        }
    }
    Ok(())
}

/// The parts of a warped Julia, built into a [`Warp`] once all are read.
struct WarpDraft {
    c: C,
    alpha: C,
    /// The line of `alpha`, where an invalid warp is reported (0 without one).
    alpha_line: usize,
    lambda: f64,
    fbm: Fbm,
    /// Given by `sampling`; the preset's otherwise (then `radius` and `scale` are not read).
    sampling: Option<Sampling>,
    zero_mean: bool,
    warnings: Vec<Diagnostic>,
}

/// The view being read, and what reading it said.
struct ViewDraft {
    doc: EscapeDoc,
    /// The directory relative gradient paths are resolved against.
    base: Option<PathBuf>,
    warnings: Vec<Diagnostic>,
}

/// Settings of the families; each applies to the families that have it.
const FAMILY_KEYS: &[Key<Family>] = &[
    key("power", |f, s| {
        let n = s.count(2, 9)?;
        if let Family::Mandelbrot { power } | Family::Julia { power, .. } = f {
            *power = n;
        }
        Ok(())
    }),
    key("c", |f, s| {
        if let Family::Julia { c, .. } = f {
            *c = s.complex()?;
        }
        Ok(())
    }),
    key("poly", |f, s| {
        if let Family::Newton { coeffs } = f {
            *coeffs = parse_poly(s.value).ok_or_else(|| {
                s.expected("expected 2–33 coefficients, highest degree first, e.g. '1 0 0 -1'")
            })?;
        }
        Ok(())
    }),
    key("z0", |f, s| {
        if let Family::Logistic { z0, .. } = f {
            *z0 = s.complex()?;
        }
        Ok(())
    }),
    key("kose", |f, s| {
        if let Family::Logistic { kose, .. } = f {
            *kose = s.boolean()?;
        }
        Ok(())
    }),
    key("p", |f, s| {
        if let Family::Cubic { p } = f {
            *p = s.complex()?;
        }
        Ok(())
    }),
];

/// Settings of the warped Julia family.
const WARP_KEYS: &[Key<WarpDraft>] = &[
    key("octaves", |w, s| {
        let n: u32 = s.number()?;
        if !(1..=16).contains(&n) {
            w.warnings.push(Diagnostic::warning(
                s.file,
                Pos::LineCol(s.line, 1),
                "ESC007",
                format!("octaves {n} is outside 1..16; using {}", n.clamp(1, 16)),
            ));
        }
        w.fbm.octaves = n.clamp(1, 16);
        Ok(())
    }),
    key("lacunarity", |w, s| {
        w.fbm.lacunarity = s.real()?;
        Ok(())
    }),
    key("gain", |w, s| {
        w.fbm.gain = s.real()?;
        Ok(())
    }),
    key("frequency", |w, s| {
        w.fbm.frequency = s.real()?;
        Ok(())
    }),
    key("seed", |w, s| {
        w.fbm.seed = s.number()?;
        Ok(())
    }),
    key("sampling", |w, s| {
        w.sampling = Some(match s.value.to_ascii_lowercase().as_str() {
            "polar" => Sampling::Polar { radius: 1.0 },
            "rect" | "rectangular" => Sampling::Rect { scale: 3.0 },
            other => {
                return Err(s.err(
                    "ESC003",
                    format!("sampling '{other}': expected polar or rect"),
                ));
            }
        });
        Ok(())
    }),
    key("radius", |w, s| {
        if let Some(Sampling::Polar { radius }) = &mut w.sampling {
            *radius = s.real()?;
        }
        Ok(())
    }),
    key("scale", |w, s| {
        if let Some(Sampling::Rect { scale }) = &mut w.sampling {
            *scale = s.real()?;
        }
        Ok(())
    }),
    key("c", |w, s| {
        w.c = s.complex()?;
        Ok(())
    }),
    key("alpha", |w, s| {
        w.alpha = s.complex()?;
        w.alpha_line = s.line;
        Ok(())
    }),
    key("turbulence", |w, s| {
        w.lambda = s.real()?;
        Ok(())
    }),
    key("zero_mean", |w, s| {
        w.zero_mean = s.boolean()?;
        Ok(())
    }),
];

/// Settings of the view, the picture and the colouring (`width` after `size`: the width is
/// kept as the view's height for that aspect).
const VIEW_KEYS: &[Key<ViewDraft>] = &[
    key("size", |v, s| {
        let (w, h) = s
            .value
            .split_once(['x', 'X'])
            .and_then(|(a, b)| Some((a.trim().parse::<u32>().ok()?, b.trim().parse::<u32>().ok()?)))
            .filter(|(w, h)| (1..=30000).contains(w) && (1..=30000).contains(h))
            .ok_or_else(|| {
                s.err(
                    "ESC004",
                    format!(
                        "size '{}': expected WxH between 1x1 and 30000x30000",
                        s.value
                    ),
                )
            })?;
        (v.doc.width, v.doc.height) = (w, h);
        Ok(())
    }),
    key("center", |v, s| {
        let c = parse_center(s.value).map_err(|e| s.err("ESC003", format!("center: {e}")))?;
        v.doc.view = v.doc.view.with_centre(c);
        Ok(())
    }),
    key("width", |v, s| {
        let wd = parse_width(s.value).map_err(|e| s.err("ESC004", e))?;
        v.doc.set_world_width_fx(wd);
        Ok(())
    }),
    key("max_iter", |v, s| {
        v.doc.params.max_iter = s.count(1, 100_000_000)?;
        Ok(())
    }),
    key("coloring", |v, s| {
        v.doc.params.coloring = Coloring::from_name(s.value)
            .ok_or_else(|| s.expected("expected bands, smooth, distance, histogram or basins"))?;
        Ok(())
    }),
    key("gradient", |v, s| {
        let g =
            resolve_gradient_parsed(s.value, v.base.as_deref()).map_err(|m| s.err("ESC005", m))?;
        v.doc.params.palette.gradient = g.value;
        v.warnings.extend(g.warnings);
        v.doc.gradient_source = s.value.to_string();
        Ok(())
    }),
    key("offset", |v, s| {
        v.doc.params.palette.offset = s.real()?;
        Ok(())
    }),
    key("repeat", |v, s| {
        v.doc.params.palette.repeat = s.positive()?;
        Ok(())
    }),
    key("inside", |v, s| {
        let rgb: Vec<u8> = s
            .value
            .split_whitespace()
            .filter_map(|t| t.parse().ok())
            .collect();
        v.doc.params.palette.inside =
            <[u8; 3]>::try_from(rgb).map_err(|_| s.expected("expected three numbers 0–255"))?;
        Ok(())
    }),
    key("bailout", |v, s| {
        v.doc.params.bailout = Some(s.positive()?);
        Ok(())
    }),
    key("bla_tolerance", |v, s| {
        let e = s.positive()?;
        if !crate::escape::bla::EPSILON_RANGE.contains(&e) {
            return Err(s.err(
                "ESC004",
                format!("{} {e} must be between 1.1e-16 and 0.001", s.key),
            ));
        }
        v.doc.params.bla_eps = e;
        Ok(())
    }),
    key("periodicity", |v, s| {
        v.doc.params.periodicity = s.boolean()?;
        Ok(())
    }),
    key("fill", |v, s| {
        v.doc.params.fill = match s.value.to_ascii_lowercase().as_str() {
            "exact" => Fill::Exact,
            "guess" | "guessing" | "mariani-silver" => Fill::Guess,
            _ => return Err(s.expected("expected exact or guess")),
        };
        Ok(())
    }),
];

/// Settings that are read elsewhere (`kind`) or accepted and ignored.
const OTHER_KEYS: [&str; 4] = ["kind", "threads", "name", "comment"];

/// Read a view file; `base` is the directory relative gradient paths are resolved against.
pub fn parse(text: &str, name: &str, base: Option<&Path>) -> Result<Parsed<EscapeDoc>, Diagnostic> {
    let settings = settings(text, name)?;
    let kind = settings
        .iter()
        .rev()
        .find(|s| s.key == "kind")
        .ok_or_else(|| {
            Diagnostic::error(
                name,
                Pos::File,
                "ESC002",
                "missing 'kind = …' (mandelbrot, julia, …)",
            )
        })?;
    let mut family = family_from_name(kind.value).ok_or_else(|| {
        kind.err(
            "ESC002",
            format!(
                "unknown kind '{}': expected mandelbrot, multibrot, burning-ship, julia, newton, logistic, cubic or warped-julia",
                kind.value
            ),
        )
    })?;
    apply(FAMILY_KEYS, &settings, &mut family)?;
    let mut warnings = Vec::new();
    if let Family::WarpedJulia(w) = &mut family {
        let mut d = WarpDraft {
            c: w.c,
            alpha: w.alpha,
            alpha_line: 0,
            lambda: w.lambda,
            fbm: Fbm::default(),
            sampling: None,
            zero_mean: false,
            warnings: Vec::new(),
        };
        apply(WARP_KEYS, &settings, &mut d)?;
        *w = Warp::new(
            d.c,
            d.alpha,
            d.lambda,
            d.fbm,
            d.sampling.unwrap_or(w.sampling),
            d.zero_mean,
        )
        .map_err(|e| {
            Diagnostic::error(name, Pos::LineCol(d.alpha_line, 1), "ESC004", e.to_string())
        })?;
        warnings = d.warnings;
    }
    let mut view = ViewDraft {
        doc: EscapeDoc::new(family),
        base: base.map(Path::to_path_buf),
        warnings,
    };
    apply(VIEW_KEYS, &settings, &mut view)?;
    let known = |k: &str| {
        OTHER_KEYS.contains(&k)
            || FAMILY_KEYS.iter().any(|x| x.name == k)
            || WARP_KEYS.iter().any(|x| x.name == k)
            || VIEW_KEYS.iter().any(|x| x.name == k)
    };
    for s in settings.iter().filter(|s| !known(&s.key)) {
        view.warnings.push(Diagnostic::warning(
            name,
            Pos::LineCol(s.line, 1),
            "ESC006",
            format!("unknown setting '{}' ignored", s.key),
        ));
    }
    Ok(Parsed {
        value: view.doc,
        warnings: view.warnings,
    })
}

/// A gradient by built-in name or by file (.ugr, .map, .ggr, or an image), relative to `base`.
pub fn resolve_gradient(s: &str, base: Option<&Path>) -> Result<Gradient, String> {
    resolve_gradient_parsed(s, base).map(|p| p.value)
}

/// As [`resolve_gradient`], with the warnings of reading the gradient file.
pub fn resolve_gradient_parsed(s: &str, base: Option<&Path>) -> Result<Parsed<Gradient>, String> {
    if let Some(g) = gradient::builtin_named(s) {
        return Ok(Parsed {
            value: g,
            warnings: Vec::new(),
        });
    }
    let path = gradient_path(s, base);
    if !path.exists() {
        return Err(format!(
            "gradient '{s}' is neither a built-in gradient nor an existing file"
        ));
    }
    let p = super::read_gradients(&path).map_err(|e| e.to_string())?;
    let warnings = p.warnings;
    let value = p
        .value
        .into_iter()
        .next()
        .ok_or_else(|| format!("{}: holds no gradient", path.display()))?;
    Ok(Parsed { value, warnings })
}

/// The file a gradient source names: relative paths are tried against `base` first (the
/// view file's directory).
pub fn gradient_path(s: &str, base: Option<&Path>) -> std::path::PathBuf {
    let path = std::path::PathBuf::from(s);
    if path.is_relative()
        && let Some(b) = base
        && b.join(&path).exists()
    {
        return b.join(&path);
    }
    path
}

/// Read a view file from disk.
pub fn read(path: &Path) -> Result<Parsed<EscapeDoc>, Diagnostic> {
    let name = path.display().to_string();
    let bytes = super::read_bytes(path)?;
    let (text, w) = super::diag::decode_text(&bytes, &name);
    let mut p = parse(&text, &name, path.parent())?;
    p.warnings.extend(w);
    Ok(p)
}

/// Write a view file atomically.
pub fn save(path: &Path, doc: &EscapeDoc) -> std::io::Result<()> {
    super::atomic::write_atomic(path, write(doc).as_bytes())
}

#[cfg(test)]
#[path = "escape_view_tests.rs"]
mod tests;
