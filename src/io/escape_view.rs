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
use std::path::Path;

use super::diag::{Diagnostic, Parsed, Pos};
use crate::escape::dd::Dd;
use crate::escape::{C, Coloring, EscapeParams, Family, Fill, Sampling, View, Warp};
use crate::gradient::{self, Gradient};
use crate::noise::Fbm;

/// A saved escape-time view.
#[derive(Clone, Debug, PartialEq)]
pub struct EscapeDoc {
    pub params: EscapeParams,
    pub view: View,
    pub width: u32,
    pub height: u32,
    /// How the gradient was named in the file (a built-in name or a file path), for writing
    /// it back.
    pub gradient_source: String,
}

impl EscapeDoc {
    /// A family's default document: its default view at 800×600, 256 iterations.
    pub fn new(family: Family) -> EscapeDoc {
        let (center, half_height) = family.default_view();
        let mut params = EscapeParams::new(family);
        params.palette.gradient = gradient::default_gradient();
        EscapeDoc {
            params,
            view: View::new(center, half_height),
            width: 800,
            height: 600,
            gradient_source: gradient::default_gradient().name,
        }
    }

    /// World width of the view.
    pub fn world_width(&self) -> f64 {
        2.0 * self.view.half_height * self.width as f64 / self.height.max(1) as f64
    }
}

/// Parse a family name into its default family.
pub fn family_from_name(name: &str) -> Option<Family> {
    Some(match name.trim().to_ascii_lowercase().as_str() {
        "mandelbrot" => Family::Mandelbrot { power: 2 },
        "multibrot" => Family::Mandelbrot { power: 3 },
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

fn fmt_c(c: C) -> String {
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

/// Parse a centre "re, im" to double-double precision (up to 32 significant digits each,
/// for deep zooms).
pub fn parse_center(s: &str) -> Option<[Dd; 2]> {
    let parts: Vec<&str> = s
        .split(|ch: char| ch == ',' || ch.is_whitespace())
        .filter(|t| !t.is_empty())
        .collect();
    match parts.as_slice() {
        [re] => Some([Dd::parse(re)?, Dd::ZERO]),
        [re, im] => Some([Dd::parse(re)?, Dd::parse(im)?]),
        _ => None,
    }
}

/// The centre as written in a view file: shortest f64 form, or all the digits of the
/// double-double centre when the view is a deep zoom.
pub fn format_center(doc: &EscapeDoc) -> String {
    if crate::escape::render::is_deep(&doc.params.family, &doc.view, doc.height) {
        let [x, y] = doc.view.center_dd();
        format!("{x}, {y}")
    } else {
        format!("{}, {}", doc.view.center[0], doc.view.center[1])
    }
}

/// Shortest round-trip form, with an exponent for tiny values (deep-zoom widths).
fn fmt_small(v: f64) -> String {
    if v != 0.0 && v.abs() < 1e-4 {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
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

fn fmt_poly(coeffs: &[C]) -> String {
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
        fmt_small(doc.world_width()),
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
    s
}

/// Read a view file; `base` is the directory relative gradient paths are resolved against.
pub fn parse(text: &str, name: &str, base: Option<&Path>) -> Result<Parsed<EscapeDoc>, Diagnostic> {
    let err = |line: usize, code: &'static str, msg: String| {
        Diagnostic::error(name, Pos::LineCol(line, 1), code, msg)
    };
    let mut entries: Vec<(usize, String, String)> = Vec::new();
    for (k, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let Some((key, value)) = line.split_once('=') else {
            return Err(err(
                k + 1,
                "ESC001",
                format!("expected 'key = value', found '{line}'"),
            ));
        };
        entries.push((
            k + 1,
            key.trim().to_ascii_lowercase(),
            value.trim().to_string(),
        ));
        if entries.len() > 200 {
            return Err(err(k + 1, "ESC001", "more than 200 settings".into()));
        }
    }
    let get = |key: &str| entries.iter().rev().find(|e| e.1 == key);
    let kind_line = get("kind").ok_or_else(|| {
        Diagnostic::error(
            name,
            Pos::File,
            "ESC002",
            "missing 'kind = …' (mandelbrot, julia, …)",
        )
    })?;
    let mut family = family_from_name(&kind_line.2).ok_or_else(|| {
        err(
            kind_line.0,
            "ESC002",
            format!(
                "unknown kind '{}': expected mandelbrot, multibrot, julia, newton, logistic, cubic or warped-julia",
                kind_line.2
            ),
        )
    })?;
    let mut warnings = Vec::new();
    let complex = |key: &str| -> Result<Option<C>, Diagnostic> {
        match get(key) {
            None => Ok(None),
            Some((l, _, v)) => parse_complex(v)
                .map(Some)
                .ok_or_else(|| err(*l, "ESC003", format!("{key} '{v}': expected 're, im'"))),
        }
    };
    fn number<T: std::str::FromStr>(
        e: Option<&(usize, String, String)>,
        what: &str,
        name: &str,
    ) -> Result<Option<T>, Diagnostic> {
        match e {
            None => Ok(None),
            Some((l, _, v)) => v.parse::<T>().map(Some).map_err(|_| {
                Diagnostic::error(
                    name,
                    Pos::LineCol(*l, 1),
                    "ESC003",
                    format!("{what} '{v}' is not a valid number"),
                )
            }),
        }
    }
    let real = |key: &str| -> Result<Option<f64>, Diagnostic> {
        let v: Option<f64> = number(get(key), key, name)?;
        match v {
            Some(x) if !x.is_finite() => Err(err(
                get(key).map_or(0, |e| e.0),
                "ESC003",
                format!("{key} must be finite"),
            )),
            v => Ok(v),
        }
    };
    let boolean = |key: &str| -> Result<Option<bool>, Diagnostic> {
        match get(key) {
            None => Ok(None),
            Some((l, _, v)) => match v.to_ascii_lowercase().as_str() {
                "true" | "1" | "yes" | "on" => Ok(Some(true)),
                "false" | "0" | "no" | "off" => Ok(Some(false)),
                _ => Err(err(
                    *l,
                    "ESC003",
                    format!("{key} '{v}': expected true or false"),
                )),
            },
        }
    };
    let power: Option<u32> = number(get("power"), "power", name)?;
    if let Some(pw) = power
        && !(2..=9).contains(&pw)
    {
        return Err(err(
            get("power").map_or(0, |e| e.0),
            "ESC004",
            format!("power {pw} must be between 2 and 9"),
        ));
    }
    match &mut family {
        Family::Mandelbrot { power: p } => {
            *p = power.unwrap_or(if kind_line.2.eq_ignore_ascii_case("multibrot") {
                3
            } else {
                2
            })
        }
        Family::Julia { power: p, c } => {
            *p = power.unwrap_or(2);
            if let Some(v) = complex("c")? {
                *c = v;
            }
        }
        Family::Newton { coeffs } => {
            if let Some((l, _, v)) = get("poly") {
                *coeffs = parse_poly(v).ok_or_else(|| {
                    err(*l, "ESC003", format!("poly '{v}': expected 2–33 coefficients, highest degree first, e.g. '1 0 0 -1'"))
                })?;
            }
        }
        Family::Logistic { z0, kose } => {
            if let Some(v) = complex("z0")? {
                *z0 = v;
            }
            if let Some(k) = boolean("kose")? {
                *kose = k;
            }
        }
        Family::Cubic { p } => {
            if let Some(v) = complex("p")? {
                *p = v;
            }
        }
        Family::WarpedJulia(w) => {
            let d = Fbm::default();
            let octaves: u32 = number(get("octaves"), "octaves", name)?.unwrap_or(d.octaves);
            if !(1..=16).contains(&octaves) {
                warnings.push(Diagnostic::warning(
                    name,
                    Pos::LineCol(get("octaves").map_or(0, |e| e.0), 1),
                    "ESC007",
                    format!(
                        "octaves {octaves} is outside 1..16; using {}",
                        octaves.clamp(1, 16)
                    ),
                ));
            }
            let fbm = Fbm {
                octaves: octaves.clamp(1, 16),
                lacunarity: real("lacunarity")?.unwrap_or(d.lacunarity),
                gain: real("gain")?.unwrap_or(d.gain),
                frequency: real("frequency")?.unwrap_or(d.frequency),
                seed: number(get("seed"), "seed", name)?.unwrap_or(d.seed),
            };
            let sampling = match get("sampling").map(|e| e.2.to_ascii_lowercase()) {
                None => w.sampling,
                Some(s) if s == "polar" => Sampling::Polar {
                    radius: real("radius")?.unwrap_or(1.0),
                },
                Some(s) if s == "rect" || s == "rectangular" => Sampling::Rect {
                    scale: real("scale")?.unwrap_or(3.0),
                },
                Some(s) => {
                    return Err(err(
                        get("sampling").map_or(0, |e| e.0),
                        "ESC003",
                        format!("sampling '{s}': expected polar or rect"),
                    ));
                }
            };
            let built = Warp::new(
                complex("c")?.unwrap_or(w.c),
                complex("alpha")?.unwrap_or(w.alpha),
                real("turbulence")?.unwrap_or(w.lambda),
                fbm,
                sampling,
                boolean("zero_mean")?.unwrap_or(false),
            )
            .map_err(|e| err(get("alpha").map_or(0, |e| e.0), "ESC004", e.to_string()))?;
            *w = built;
        }
    }
    let mut doc = EscapeDoc::new(family);
    if let Some((l, _, v)) = get("size") {
        let (w, h) = v
            .split_once(['x', 'X'])
            .and_then(|(a, b)| Some((a.trim().parse::<u32>().ok()?, b.trim().parse::<u32>().ok()?)))
            .filter(|(w, h)| (1..=30000).contains(w) && (1..=30000).contains(h))
            .ok_or_else(|| {
                err(
                    *l,
                    "ESC004",
                    format!("size '{v}': expected WxH between 1x1 and 30000x30000"),
                )
            })?;
        doc.width = w;
        doc.height = h;
    }
    if let Some((l, _, v)) = get("center") {
        let c = parse_center(v)
            .ok_or_else(|| err(*l, "ESC003", format!("center '{v}': expected 're, im'")))?;
        doc.view = doc.view.with_center_dd(c);
    }
    if let Some(wd) = real("width")? {
        if wd <= 0.0 {
            return Err(err(
                get("width").map_or(0, |e| e.0),
                "ESC004",
                "width must be positive".into(),
            ));
        }
        doc.view.half_height = wd / 2.0 * doc.height as f64 / doc.width as f64;
    }
    let p = &mut doc.params;
    if let Some(n) = number::<u32>(get("max_iter"), "max_iter", name)? {
        if n == 0 || n > 100_000_000 {
            return Err(err(
                get("max_iter").map_or(0, |e| e.0),
                "ESC004",
                format!("max_iter {n} must be between 1 and 100000000"),
            ));
        }
        p.max_iter = n;
    }
    if let Some((l, _, v)) = get("coloring") {
        p.coloring = Coloring::from_name(v).ok_or_else(|| {
            err(
                *l,
                "ESC003",
                format!("coloring '{v}': expected bands, smooth, distance, histogram or basins"),
            )
        })?;
    }
    if let Some((l, _, v)) = get("gradient") {
        let g = resolve_gradient_parsed(v, base).map_err(|m| err(*l, "ESC005", m))?;
        p.palette.gradient = g.value;
        warnings.extend(g.warnings);
        doc.gradient_source = v.clone();
    }
    if let Some(o) = real("offset")? {
        p.palette.offset = o;
    }
    if let Some(r) = real("repeat")? {
        p.palette.repeat = r;
    }
    if p.palette.repeat <= 0.0 {
        return Err(err(
            get("repeat").map_or(0, |e| e.0),
            "ESC004",
            "repeat must be positive".into(),
        ));
    }
    if let Some((l, _, v)) = get("inside") {
        let rgb: Vec<u8> = v
            .split_whitespace()
            .filter_map(|t| t.parse().ok())
            .collect();
        p.palette.inside = <[u8; 3]>::try_from(rgb).map_err(|_| {
            err(
                *l,
                "ESC003",
                format!("inside '{v}': expected three numbers 0–255"),
            )
        })?;
    }
    if let Some(b) = real("bailout")? {
        if b <= 0.0 {
            return Err(err(
                get("bailout").map_or(0, |e| e.0),
                "ESC004",
                "bailout must be positive".into(),
            ));
        }
        p.bailout = Some(b);
    }
    if let Some(v) = boolean("periodicity")? {
        p.periodicity = v;
    }
    if let Some((l, _, v)) = get("fill") {
        p.fill = match v.to_ascii_lowercase().as_str() {
            "exact" => Fill::Exact,
            "guess" | "guessing" | "mariani-silver" => Fill::Guess,
            _ => {
                return Err(err(
                    *l,
                    "ESC003",
                    format!("fill '{v}': expected exact or guess"),
                ));
            }
        };
    }
    const KNOWN: [&str; 33] = [
        "kind",
        "power",
        "c",
        "poly",
        "z0",
        "kose",
        "p",
        "alpha",
        "turbulence",
        "octaves",
        "lacunarity",
        "gain",
        "frequency",
        "seed",
        "zero_mean",
        "sampling",
        "radius",
        "scale",
        "center",
        "width",
        "size",
        "max_iter",
        "coloring",
        "gradient",
        "offset",
        "repeat",
        "inside",
        "periodicity",
        "fill",
        "bailout",
        "threads",
        "name",
        "comment",
    ];
    for (l, k, _) in &entries {
        if !KNOWN.contains(&k.as_str()) {
            warnings.push(Diagnostic {
                warning: true,
                ..Diagnostic::error(
                    name,
                    Pos::LineCol(*l, 1),
                    "ESC006",
                    format!("unknown setting '{k}' ignored"),
                )
            });
        }
    }
    Ok(Parsed {
        value: doc,
        warnings,
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
mod tests {
    use super::*;

    #[test]
    fn round_trip_every_kind() {
        for kind in [
            "mandelbrot",
            "multibrot",
            "julia",
            "newton",
            "logistic",
            "cubic",
            "warped-julia",
        ] {
            let mut d = EscapeDoc::new(family_from_name(kind).unwrap());
            d.params.max_iter = 777;
            d.params.coloring = Coloring::Histogram;
            d.view.center = [0.125, -0.25];
            d.gradient_source = "lagoon".into();
            d.params.palette.gradient = gradient::builtin_named("lagoon").unwrap();
            d.params.palette.offset = 0.5;
            let text = write(&d);
            let back = parse(&text, "t.esc", None).unwrap();
            assert!(back.warnings.is_empty(), "{kind}: {:?}", back.warnings);
            let b = back.value;
            assert_eq!(b.params.family, d.params.family, "{kind}");
            assert_eq!(b.params, d.params, "{kind}");
            assert_eq!((b.width, b.height), (d.width, d.height));
            assert!((b.view.half_height - d.view.half_height).abs() < 1e-12);
            assert_eq!(b.view.center, d.view.center);
        }
    }

    #[test]
    fn deep_zoom_views_keep_every_digit() {
        let mut d = EscapeDoc::new(Family::Mandelbrot { power: 2 });
        let c = parse_center(
            "-0.743643887037158704752191506114774, 0.131825904205311970493132056385139",
        )
        .unwrap();
        d.view = d.view.with_center_dd(c);
        d.view.half_height = 3e-21;
        let text = write(&d);
        assert!(
            text.contains("center = -0.7436438870371587047521915061147"),
            "{text}"
        );
        assert!(text.contains("width = 8e-21"), "{text}");
        let b = parse(&text, "deep.esc", None).unwrap().value;
        let [x, y] = b.view.center_dd();
        assert!((x - c[0]).to_f64().abs() < 1e-31 && (y - c[1]).to_f64().abs() < 1e-31);
        assert!((b.view.half_height / 3e-21 - 1.0).abs() < 1e-12);
        // Writing again gives the same text.
        assert_eq!(write(&b), text);
        // A shallow view is written as before (shortest f64).
        let mut s = d.clone();
        s.view.half_height = 0.5;
        assert!(write(&s).contains("center = -0.7436438870371587, 0.13182590420531198"));
    }

    #[test]
    fn bad_files_say_where() {
        let cases = [
            ("kind = mandelbrot\nmax_iter = lots\n", 2, "ESC003"),
            ("center = 0, 0\n", 0, "ESC002"),
            ("kind = snowflake\n", 1, "ESC002"),
            ("kind = julia\nc = 1, 2, 3\n", 2, "ESC003"),
            ("kind = mandelbrot\npower = 12\n", 2, "ESC004"),
            ("kind = warped-julia\nalpha = 0.6, 0.8\n", 2, "ESC004"),
            ("kind = mandelbrot\nno equals sign\n", 2, "ESC001"),
            (
                "kind = mandelbrot\ngradient = /no/such/file.map\n",
                2,
                "ESC005",
            ),
            ("kind = newton\npoly = 1\n", 2, "ESC003"),
            ("kind = mandelbrot\nsize = 0x10\n", 2, "ESC004"),
        ];
        for (text, line, code) in cases {
            let e = parse(text, "v.esc", None)
                .err()
                .unwrap_or_else(|| panic!("accepted {text:?}"));
            assert_eq!(e.code, code, "{text:?}: {e}");
            if line > 0 {
                assert_eq!(e.pos, Pos::LineCol(line, 1), "{text:?}");
            }
            assert!(e.to_string().contains("v.esc"));
        }
        let w = parse("kind = mandelbrot\nzoom = 3\n", "v.esc", None).unwrap();
        assert_eq!(w.warnings.len(), 1);
    }
}
