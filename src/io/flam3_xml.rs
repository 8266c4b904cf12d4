//! flam3 / Apophysis flame XML (`.flame`, `.flam3`) and ugnis `.fla`.
//!
//! Reading accepts any well-formed document and takes every `<flame>` element at any depth.
//! Everything ugnis does not interpret — unknown attributes, `<edit>` histories, variations it
//! cannot render — is kept and written back, so a read/write round trip is lossless.

use std::cell::OnceCell;
use std::collections::HashSet;
use std::fmt::Write as _;
use std::path::PathBuf;

use quick_xml::events::Event;

use crate::flame::curves::{self, Curves};
use crate::flame::model::{
    Affine, FilterShape, Flame, FlameKind, PaletteIndex, PaletteMode, Var, Xform,
};
use crate::flame::symmetry::add_symmetry;
use crate::flame::variations::{self, Form};
use crate::gradient::{Gradient, hue_rotate, resample_colors};
use crate::io::diag::{Diagnostic, Parsed, Pos, SourceMap, fmt_num, parse_int, parse_number};
use crate::io::palettes::{self, PaletteLibrary, decode_hex_colors};
use crate::io::xml::{Attr, XmlCursor, escape_attr, scan_attrs};

/// Revision of the `.fla` format this version writes.
pub const FLA_FORMAT: u32 = 1;
/// Flames per file (sanity limit).
pub const MAX_FLAMES: usize = 10_000;
/// Xforms per flame (sanity limit).
pub const MAX_XFORMS: usize = 10_000;
/// Most colours in one `<palette>` (Fractorium writes up to a few thousand).
pub const MAX_PALETTE: i64 = 65_536;
/// Largest image side accepted from a file.
pub const MAX_SIDE: i64 = 1_000_000;
/// Warnings of one kind listed per file; the rest are counted in one line.
pub const MAX_WARNINGS_PER_CODE: usize = 20;

/// The contents of a flame file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FlameFile {
    /// `name` of the `<flames>` root, if any.
    pub name: String,
    pub flames: Vec<Flame>,
}

/// Where `palette="N"` looks up flam3's library.
#[derive(Clone, Debug, Default)]
pub enum LibrarySource<'a> {
    /// Search `$FLAM3_PALETTES` and the usual install paths.
    #[default]
    Search,
    /// These paths, in order.
    Paths(Vec<PathBuf>),
    /// An already loaded library.
    Loaded(&'a PaletteLibrary),
}

/// Reader options.
#[derive(Clone, Debug)]
pub struct ReadOptions<'a> {
    /// File name used in diagnostics.
    pub file: String,
    pub library: LibrarySource<'a>,
    /// Quality for flames without a `quality` attribute (the Options main density).
    pub default_quality: f64,
    /// Palette for flames without colour data.
    pub default_gradient: Gradient,
    /// Validate as a `.fla` file (`<flames>` root, unique non-empty names).
    pub fla: bool,
}

impl Default for ReadOptions<'_> {
    fn default() -> Self {
        Self {
            file: "<input>".to_string(),
            library: LibrarySource::Search,
            default_quality: 15.0,
            default_gradient: Gradient::default(),
            fla: false,
        }
    }
}

struct Ctx<'t, 'o> {
    file: &'t str,
    map: SourceMap<'t>,
    warnings: Vec<Diagnostic>,
    reported_vars: HashSet<String>,
    /// Attributes of other programs that ugnis keeps but does not interpret (reported once per
    /// file, in one line).
    ignored_attrs: Vec<String>,
    /// Hashes of all of them (for counting distinct names without keeping every name).
    ignored_set: HashSet<u64>,
    /// Warnings per code so far; past [`MAX_WARNINGS_PER_CODE`] they are only counted.
    warn_counts: std::collections::HashMap<&'static str, usize>,
    opts: &'o ReadOptions<'o>,
    library: OnceCell<Result<PaletteLibrary, String>>,
}

type R<T> = Result<T, Diagnostic>;

fn name_hash(name: &str) -> u64 {
    use std::hash::{BuildHasher, BuildHasherDefault};
    BuildHasherDefault::<std::collections::hash_map::DefaultHasher>::default().hash_one(name)
}

impl Ctx<'_, '_> {
    /// Counts `name` among the attributes kept but not interpreted (the first six are named in
    /// the file's summary line).
    fn ignore(&mut self, name: &str) {
        if self.ignored_set.insert(name_hash(name)) && self.ignored_attrs.len() < 6 {
            self.ignored_attrs.push(name.to_string());
        }
    }

    fn err(&self, off: usize, code: &'static str, msg: impl Into<String>) -> Diagnostic {
        Diagnostic::error(self.file, self.map.pos(off), code, msg)
    }

    fn warn(&mut self, off: usize, code: &'static str, msg: impl Into<String>) {
        let n = self.warn_counts.entry(code).or_insert(0);
        *n += 1;
        if *n > MAX_WARNINGS_PER_CODE {
            return;
        }
        let d = Diagnostic::warning(self.file, self.map.pos(off), code, msg);
        self.warnings.push(d);
    }

    fn num(&self, a: &Attr) -> R<f64> {
        parse_number(a.value.trim()).map_err(|e| {
            self.err(
                a.offset,
                "XML003",
                format!("attribute '{}': {}", a.name, e.describe(a.value.trim())),
            )
        })
    }

    fn nums(&self, a: &Attr, code: &'static str) -> R<Vec<f64>> {
        a.value
            .split_whitespace()
            .map(|t| {
                parse_number(t).map_err(|e| {
                    self.err(
                        a.offset,
                        code,
                        format!("attribute '{}': {}", a.name, e.describe(t)),
                    )
                })
            })
            .collect()
    }

    fn fixed<const N: usize>(&self, a: &Attr, code: &'static str, what: &str) -> R<[f64; N]> {
        let v = self.nums(a, code)?;
        v.try_into().map_err(|v: Vec<f64>| {
            self.err(
                a.offset,
                code,
                format!(
                    "attribute '{}' must hold {N} {what}, found {}",
                    a.name,
                    v.len()
                ),
            )
        })
    }

    fn int(&self, a: &Attr) -> R<i64> {
        parse_int(a.value.trim()).map_err(|_| {
            self.err(
                a.offset,
                "XML003",
                format!(
                    "attribute '{}': '{}' is not an integer",
                    a.name,
                    a.value.trim()
                ),
            )
        })
    }

    fn library(&self) -> &Result<PaletteLibrary, String> {
        self.library.get_or_init(|| {
            let paths = match &self.opts.library {
                LibrarySource::Loaded(l) => return Ok((*l).clone()),
                LibrarySource::Search => palettes::default_paths(),
                LibrarySource::Paths(p) => p.clone(),
            };
            match palettes::find(Some(&paths)) {
                Some(p) => palettes::load(&p)
                    .map(|l| l.value)
                    .map_err(|d| d.to_string()),
                None => Err(format!(
                    "flam3-palettes.xml was not found (looked in {}); install flam3's palette file \
                     (Debian: flam3-palette), set FLAM3_PALETTES, or pass --palettes PATH",
                    paths
                        .iter()
                        .map(|p| p.display().to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                )),
            }
        })
    }
}

/// Read every flame of a flam3/Apophysis/ugnis XML document.
pub fn read(text: &str, opts: &ReadOptions) -> R<Parsed<FlameFile>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut cx = Ctx {
        file: &opts.file,
        map: SourceMap::new(text),
        warnings: Vec::new(),
        reported_vars: HashSet::new(),
        ignored_attrs: Vec::new(),
        ignored_set: HashSet::new(),
        warn_counts: Default::default(),
        opts,
        library: OnceCell::new(),
    };
    let mut cur = XmlCursor::new(text);
    let mut out = FlameFile::default();
    let mut depth = 0usize;
    let mut root_seen = false;
    let mut names: Vec<(String, usize)> = Vec::new();
    loop {
        let p = cur.next_event().map_err(|(o, m)| cx.err(o, "XML001", m))?;
        match &p.event {
            Event::Eof => break,
            Event::Start(e) | Event::Empty(e) => {
                let is_empty = matches!(p.event, Event::Empty(_));
                let tag = e.name().as_ref().to_string();
                if !root_seen {
                    root_seen = true;
                    if tag == "flames" {
                        let attrs =
                            scan_attrs(e, p.start + 1).map_err(|(o, m)| cx.err(o, "XML001", m))?;
                        root_attrs(&mut cx, &attrs, &mut out)?;
                    } else if opts.fla {
                        return Err(cx.err(
                            p.start,
                            "FLA001",
                            format!("a .fla file must have a <flames> root, not <{}>", tag),
                        ));
                    }
                }
                if tag == "flame" {
                    if out.flames.len() >= MAX_FLAMES {
                        return Err(cx.err(
                            p.start,
                            "XML003",
                            format!("more than {MAX_FLAMES} flames in one file"),
                        ));
                    }
                    let flame = read_flame(&mut cx, &mut cur, text, e, p.start, is_empty)?;
                    if opts.fla {
                        if flame.name.is_empty() {
                            return Err(cx.err(
                                p.start,
                                "FLA002",
                                "every flame in a .fla file needs a non-empty name",
                            ));
                        }
                        if let Some((_, first)) = names.iter().find(|(n, _)| *n == flame.name) {
                            let Pos::LineCol(l, c) = cx.map.pos(*first) else {
                                unreachable!()
                            };
                            return Err(cx.err(
                                p.start,
                                "FLA002",
                                format!(
                                    "duplicate flame name '{}' (first used at {l}:{c})",
                                    flame.name
                                ),
                            ));
                        }
                        names.push((flame.name.clone(), p.start));
                    }
                    out.flames.push(flame);
                } else if !is_empty {
                    depth += 1;
                }
            }
            Event::End(_) => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    if out.flames.is_empty() {
        return Err(Diagnostic::error(
            &opts.file,
            Pos::File,
            "XML002",
            "no <flame> element in the document",
        ));
    }
    let _ = depth;
    let mut hidden: Vec<(&str, usize)> = cx
        .warn_counts
        .iter()
        .filter(|(_, n)| **n > MAX_WARNINGS_PER_CODE)
        .map(|(c, n)| (*c, n - MAX_WARNINGS_PER_CODE))
        .collect();
    hidden.sort();
    for (code, n) in hidden {
        cx.warnings.push(Diagnostic::warning(
            &opts.file,
            Pos::File,
            code,
            format!("{n} more warnings like the above are not shown"),
        ));
    }
    if !cx.ignored_set.is_empty() {
        let n = cx.ignored_set.len();
        let mut shown: Vec<&str> = cx
            .ignored_attrs
            .iter()
            .take(6)
            .map(|s| s.as_str())
            .collect();
        if n > 6 {
            shown.push("…");
        }
        let d = Diagnostic::warning(
            &opts.file,
            Pos::File,
            "XML021",
            format!(
                "kept {n} attribute name{} of other programs that ugnis does not interpret ({}); \
                 they are written back unchanged",
                if n == 1 { "" } else { "s" },
                shown.join(", ")
            ),
        );
        cx.warnings.push(d);
    }
    Ok(Parsed {
        value: out,
        warnings: cx.warnings,
    })
}

fn root_attrs(cx: &mut Ctx, attrs: &[Attr], out: &mut FlameFile) -> R<()> {
    for a in attrs {
        match a.name {
            "name" => out.name = a.value.to_string(),
            "ugnis_format" => {
                let v = cx.int(a)?;
                if v > FLA_FORMAT as i64 {
                    cx.warn(
                        a.offset,
                        "FLA003",
                        format!("file format revision {v} is newer than this ugnis ({FLA_FORMAT}); some data may be ignored"),
                    );
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// Raw palette data collected while reading a flame.
struct PaletteData {
    colors: Vec<Option<[f64; 4]>>,
    any: bool,
    /// A `<palette>` of more than 256 colours.
    hires: Option<Vec<[f64; 4]>>,
}

fn read_flame(
    cx: &mut Ctx,
    cur: &mut XmlCursor,
    text: &str,
    e: &quick_xml::events::BytesStart,
    start: usize,
    is_empty: bool,
) -> R<Flame> {
    let attrs = scan_attrs(e, start + 1).map_err(|(o, m)| cx.err(o, "XML001", m))?;
    let mut f = Flame {
        // flam3 defaults for absent attributes.
        width: 100,
        height: 100,
        scale: 50.0,
        quality: cx.opts.default_quality,
        gamma: 4.0,
        has_camera: false,
        ..Flame::default()
    };
    f.palette.name.clear();
    let mut library_palette: Option<(usize, usize)> = None; // (number, offset)
    let mut hue = 0.0;
    let mut rotate_seen = false;
    let mut angle: Option<f64> = None;
    let mut contrast: Option<f64> = None;
    let mut est = (9.0, 0.0, 0.4, start);
    // The palette rule: ugnis' own attribute, else the writing program's (`version`).
    let mut palette_index: Option<PaletteIndex> = None;
    let mut version_index = PaletteIndex::Flam3;
    let mut palette_mode_seen = false;
    let mut smooth_gradient: Option<(String, usize)> = None;
    for a in &attrs {
        let v = &a.value;
        match a.name {
            "name" => {
                if v.len() > 64 {
                    cx.warn(
                        a.offset,
                        "XML016",
                        "flame name longer than 64 bytes (flam3 truncates it)",
                    );
                }
                f.name = v.to_string();
            }
            "version" => version_index = PaletteIndex::from_version(v),
            "new_linear" => {}
            "ugnis_palette_index" => match PaletteIndex::from_name(v.trim()) {
                Some(m) => palette_index = Some(m),
                None => {
                    return Err(cx.err(
                        a.offset,
                        "FLA004",
                        format!(
                            "ugnis_palette_index '{v}' must be 'flam3', 'apophysis', 'fractorium' or 'jwildfire'"
                        ),
                    ));
                }
            },
            // JWildfire's interpolated gradient; honoured for JWildfire's files (below) and
            // written back either way.
            "smooth_gradient" => {
                smooth_gradient = Some((v.trim().to_string(), a.offset));
                f.extra_attrs.push((a.name.to_string(), v.to_string()));
            }
            "size" => {
                let parts: Vec<&str> = v.split_whitespace().collect();
                let ok = parts.len() == 2
                    && parts
                        .iter()
                        .all(|p| parse_int(p).is_ok_and(|n| (1..=MAX_SIDE).contains(&n)));
                if !ok {
                    return Err(cx.err(
                        a.offset,
                        "XML003",
                        format!("size '{v}' must be two integers between 1 and {MAX_SIDE}"),
                    ));
                }
                f.width = parts[0].parse().unwrap_or(1);
                f.height = parts[1].parse().unwrap_or(1);
                f.has_camera = true;
            }
            "center" => {
                let c: [f64; 2] = cx.fixed(a, "XML003", "numbers")?;
                f.center = c;
                f.has_camera = true;
            }
            "scale" => {
                f.scale = cx.num(a)?;
                if f.scale <= 0.0 {
                    return Err(cx.err(
                        a.offset,
                        "XML013",
                        format!("scale {} must be positive", f.scale),
                    ));
                }
                f.has_camera = true;
            }
            "rotate" => {
                f.rotate = cx.num(a)?;
                rotate_seen = true;
            }
            "angle" => angle = Some(cx.num(a)?),
            "zoom" => f.zoom = cx.num(a)?,
            "cam_zoom" => {
                let z = cx.num(a)?;
                if !(z > 0.0 && z.is_finite()) {
                    return Err(cx.err(
                        a.offset,
                        "XML013",
                        format!("cam_zoom {z} must be positive"),
                    ));
                }
                f.cam_zoom = z;
            }
            "cam_pitch" => f.cam.pitch = cx.num(a)?,
            "cam_yaw" => f.cam.yaw = cx.num(a)?,
            "cam_perspective" | "cam_persp" => f.cam.perspective = cx.num(a)?,
            "cam_zpos" => f.cam.zpos = cx.num(a)?,
            "cam_dof" => f.cam.dof = cx.num(a)?,
            "blur_curve" => f.cam.blur_curve = cx.num(a)?,
            "curves" => {
                // Fractorium's older form: four curves of four (x, y, weight) points.
                let v = cx.nums(a, "XML003")?;
                if v.len() != 48 {
                    return Err(cx.err(
                        a.offset,
                        "XML003",
                        format!("curves must hold 48 numbers (4 curves of 4 x y weight points), found {}", v.len()),
                    ));
                }
                for (ci, c) in v.chunks(12).enumerate() {
                    let pts = c.chunks(3).map(|p| [p[0], p[1]]).collect();
                    f.curves.points[ci] = Curves::normalised(pts);
                }
            }
            "overall_curve" | "red_curve" | "green_curve" | "blue_curve" => {
                let v = cx.nums(a, "XML003")?;
                if v.len() % 2 != 0 || v.len() < 4 || v.len() > 2 * curves::MAX_POINTS {
                    return Err(cx.err(
                        a.offset,
                        "XML003",
                        format!(
                            "{} must hold 2 to {} x y pairs, found {} numbers",
                            a.name,
                            curves::MAX_POINTS,
                            v.len()
                        ),
                    ));
                }
                let ci = ["overall_curve", "red_curve", "green_curve", "blue_curve"]
                    .iter()
                    .position(|n| *n == a.name)
                    .unwrap_or(0);
                f.curves.points[ci] =
                    Curves::normalised(v.chunks(2).map(|p| [p[0], p[1]]).collect());
            }
            "supersample" | "oversample" => {
                let n = cx.int(a)?;
                if !(1..=16).contains(&n) {
                    return Err(cx.err(
                        a.offset,
                        "XML013",
                        format!("{} {n} must be between 1 and 16", a.name),
                    ));
                }
                f.supersample = n as u32;
            }
            "filter" => {
                f.filter = cx.num(a)?;
                if f.filter < 0.0 {
                    return Err(cx.err(a.offset, "XML013", "filter radius must not be negative"));
                }
            }
            "filter_shape" => match FilterShape::from_name(v.trim()) {
                Some(s) => f.filter_shape = s,
                None => cx.warn(
                    a.offset,
                    "XML014",
                    format!("unknown filter_shape '{v}'; using gaussian"),
                ),
            },
            "quality" => {
                f.quality = cx.num(a)?;
                if f.quality <= 0.0 {
                    return Err(cx.err(
                        a.offset,
                        "XML013",
                        format!("quality {} must be positive", f.quality),
                    ));
                }
            }
            "background" => {
                let b: [f64; 3] = cx.fixed(a, "XML003", "numbers")?;
                f.background = b;
            }
            "brightness" => f.brightness = cx.num(a)?,
            "gamma" => {
                f.gamma = cx.num(a)?;
                if f.gamma <= 0.0 {
                    return Err(cx.err(
                        a.offset,
                        "XML013",
                        format!("gamma {} must be positive", f.gamma),
                    ));
                }
            }
            "gamma_threshold" => f.gamma_threshold = cx.num(a)?,
            "vibrancy" => f.vibrancy = cx.num(a)?,
            "highlight_power" => f.highlight_power = cx.num(a)?,
            "hue" => hue = cx.num(a)?.rem_euclid(1.0),
            "estimator_radius" => est.0 = cx.num(a)?,
            "estimator_minimum" => est.1 = cx.num(a)?,
            "estimator_curve" => {
                est.2 = cx.num(a)?;
                est.3 = a.offset;
            }
            "palette_mode" => match PaletteMode::from_name(v.trim()) {
                Some(m) => {
                    f.palette_mode = m;
                    palette_mode_seen = true;
                }
                None => cx.warn(
                    a.offset,
                    "XML014",
                    format!("unknown palette_mode '{v}'; using step"),
                ),
            },
            "palette" => {
                let n = cx.int(a)?;
                if !(0..=700).contains(&n) {
                    return Err(cx.err(
                        a.offset,
                        "XML011",
                        format!("palette number {n} is outside 0..700"),
                    ));
                }
                library_palette = Some((n as usize, a.offset));
            }
            "soloxform" => {
                let n = cx.num(a)?;
                f.solo_xform = if n >= 0.0 { Some(n as usize) } else { None };
            }
            "contrast" => {
                if contrast.is_none() {
                    contrast = Some(cx.num(a)?);
                }
            }
            "ugnis_contrast" => contrast = Some(cx.num(a)?),
            "ugnis_seed" => {
                f.seed = Some(v.trim().parse::<u64>().map_err(|_| {
                    cx.err(
                        a.offset,
                        "FLA004",
                        format!("ugnis_seed '{v}' must be an unsigned 64-bit integer"),
                    )
                })?)
            }
            "ugnis_kind" => {
                f.kind = match v.trim() {
                    "flame" => FlameKind::Flame,
                    "ifs" => FlameKind::Ifs,
                    other => {
                        return Err(cx.err(
                            a.offset,
                            "FLA004",
                            format!("ugnis_kind '{other}' must be 'flame' or 'ifs'"),
                        ));
                    }
                }
            }
            "ugnis_auto_weights" => {
                f.auto_weights = match v.trim() {
                    "0" => Some(false),
                    "1" => Some(true),
                    other => {
                        return Err(cx.err(
                            a.offset,
                            "FLA004",
                            format!("ugnis_auto_weights '{other}' must be 0 or 1"),
                        ));
                    }
                }
            }
            "ugnis_gradient" => f.palette.name = v.to_string(),
            other => {
                if other.starts_with("ugnis_") {
                    cx.warn(
                        a.offset,
                        "FLA005",
                        format!("unknown attribute '{other}' kept"),
                    );
                } else {
                    cx.ignore(other);
                }
                f.extra_attrs.push((other.to_string(), v.to_string()));
            }
        }
    }
    if !rotate_seen && let Some(ang) = angle {
        f.rotate = -ang.to_degrees();
    }
    f.palette_index = palette_index.unwrap_or(version_index);
    if let Some((v, _)) = &smooth_gradient {
        if f.palette_index == PaletteIndex::JWildfire {
            if !palette_mode_seen && matches!(v.as_str(), "1" | "true") {
                f.palette_mode = PaletteMode::Linear;
            }
        } else {
            cx.ignore("smooth_gradient");
        }
    }
    if let Some(c) = contrast {
        if c <= 0.0 {
            return Err(cx.err(start, "XML013", format!("contrast {c} must be positive")));
        }
        f.contrast = c;
    }
    let (r, m, k, koff) = est;
    if !(r >= m && m >= 0.0 && k > 0.0) {
        return Err(cx.err(
            koff,
            "XML012",
            format!("estimator_radius {r} must be ≥ estimator_minimum {m} ≥ 0, and estimator_curve {k} > 0"),
        ));
    }
    (f.estimator_radius, f.estimator_minimum, f.estimator_curve) = (r, m, k);

    let mut pal = PaletteData {
        colors: vec![None; 256],
        any: false,
        hires: None,
    };
    let gradient_name = std::mem::take(&mut f.palette.name);
    if !is_empty {
        read_flame_children(cx, cur, text, &mut f, &mut pal)?;
    }
    // A xaos row has one multiplier per xform; longer rows (written for a flame that had
    // more xforms) are cut, with a word.
    let n = f.xforms.len();
    for (k, x) in f.xforms.iter_mut().enumerate() {
        if x.chaos.len() > n {
            let extra = x.chaos.len() - n;
            x.chaos.truncate(n);
            cx.warn(
                start,
                "XML022",
                format!(
                    "xaos row of xform {} has {} values for {n} xforms; the last {extra} are ignored",
                    k + 1,
                    n + extra
                ),
            );
        }
    }
    // Palette: inline colours win over a library palette (flam3 does the opposite; warn).
    if pal.any {
        if library_palette.is_some() {
            cx.warn(
                start,
                "XML017",
                "flame has both inline colours and palette=\"N\"; using the inline colours",
            );
        }
        f.palette = Gradient {
            name: gradient_name,
            colors: match &pal.hires {
                Some(h) => resample_colors(h, 256),
                None => interpolate_missing(&pal.colors),
            },
            stops: Vec::new(),
            map_entries: None,
        };
        f.palette_hires = pal.hires.take();
    } else if let Some((n, off)) = library_palette {
        let lib = cx.library();
        let g = match lib {
            Ok(l) => l.get(n).cloned().ok_or_else(|| {
                cx.err(
                    off,
                    "XML011",
                    format!("palette {n} is not in {}", l.path.display()),
                )
            })?,
            Err(m) => {
                return Err(cx.err(
                    off,
                    "XML011",
                    format!("flame uses library palette {n}, but {m}"),
                ));
            }
        };
        f.palette = hue_rotate(&g, hue);
    } else {
        cx.warn(
            start,
            "XML018",
            "flame has no colour data; using the default gradient",
        );
        f.palette = cx.opts.default_gradient.clone();
    }
    if f.xforms.is_empty() {
        return Err(cx.err(
            start,
            "XML007",
            "cannot iterate empty flame: it has no <xform>",
        ));
    }
    if f.xforms.iter().all(|x| x.weight == 0.0) {
        return Err(cx.err(
            start,
            "XML007",
            "cannot iterate empty flame: all xform weights are 0",
        ));
    }
    Ok(f)
}

/// Fill undefined palette entries by linear interpolation between the nearest defined ones,
/// wrapping around (flam3 `flam3_interp_missing_colors`).
fn interpolate_missing(colors: &[Option<[f64; 4]>]) -> Vec<[f64; 4]> {
    let n = colors.len();
    let defined: Vec<usize> = (0..n).filter(|&i| colors[i].is_some()).collect();
    (0..n)
        .map(|i| {
            if let Some(c) = colors[i] {
                return c;
            }
            // Nearest defined below (wrapping) and above (wrapping).
            let below = defined
                .iter()
                .rev()
                .find(|&&j| j < i)
                .or(defined.last())
                .copied()
                .unwrap_or(i);
            let above = defined
                .iter()
                .find(|&&j| j > i)
                .or(defined.first())
                .copied()
                .unwrap_or(i);
            let (cb, ca) = (
                colors[below].unwrap_or([0.0; 4]),
                colors[above].unwrap_or([0.0; 4]),
            );
            let dist_b = (i + n - below) % n;
            let span = (above + n - below) % n;
            let t = if span == 0 {
                0.0
            } else {
                dist_b as f64 / span as f64
            };
            [
                quantise(cb[0] + (ca[0] - cb[0]) * t),
                quantise(cb[1] + (ca[1] - cb[1]) * t),
                quantise(cb[2] + (ca[2] - cb[2]) * t),
                quantise(cb[3] + (ca[3] - cb[3]) * t),
            ]
        })
        .collect()
}

/// Palettes are stored with 8 bits per channel (the hex block ugnis writes), so values are
/// rounded to multiples of 1/255 on reading; a read/write/read round trip is then exact.
fn quantise(v: f64) -> f64 {
    (v.clamp(0.0, 1.0) * 255.0).round() / 255.0
}

fn read_flame_children(
    cx: &mut Ctx,
    cur: &mut XmlCursor,
    text: &str,
    f: &mut Flame,
    pal: &mut PaletteData,
) -> R<()> {
    loop {
        let p = cur.next_event().map_err(|(o, m)| cx.err(o, "XML001", m))?;
        match &p.event {
            Event::End(_) => return Ok(()),
            Event::Eof => return Err(cx.err(p.start, "XML001", "end of file inside <flame>")),
            Event::Start(e) | Event::Empty(e) => {
                let is_empty = matches!(p.event, Event::Empty(_));
                let attrs = scan_attrs(e, p.start + 1).map_err(|(o, m)| cx.err(o, "XML001", m))?;
                match e.name().as_ref() {
                    "xform" | "finalxform" => {
                        let fin = e.name().as_ref() == "finalxform";
                        if fin && f.final_xform.is_some() {
                            return Err(cx.err(p.start, "XML006", "more than one <finalxform>"));
                        }
                        if f.xforms.len() >= MAX_XFORMS {
                            return Err(cx.err(
                                p.start,
                                "XML003",
                                format!("more than {MAX_XFORMS} xforms"),
                            ));
                        }
                        let parity = (f.xforms.len() + f.final_xform.is_some() as usize) % 2;
                        let mut x = read_xform(cx, &attrs, fin, parity as f64, p.start)?;
                        if !is_empty {
                            // Children (flam3 <motion>) are kept verbatim.
                            loop {
                                let c =
                                    cur.next_event().map_err(|(o, m)| cx.err(o, "XML001", m))?;
                                match c.event {
                                    Event::End(_) => break,
                                    Event::Start(_) => {
                                        let end = cur
                                            .skip_element()
                                            .map_err(|(o, m)| cx.err(o, "XML001", m))?;
                                        x.extra_children.push(text[c.start..end].to_string());
                                    }
                                    Event::Empty(_) => {
                                        x.extra_children.push(text[c.start..c.end].to_string())
                                    }
                                    Event::Eof => {
                                        return Err(cx.err(
                                            c.start,
                                            "XML001",
                                            "end of file inside <xform>",
                                        ));
                                    }
                                    _ => {}
                                }
                            }
                        }
                        if fin {
                            f.final_xform = Some(x);
                        } else {
                            f.xforms.push(x);
                        }
                    }
                    "color" => {
                        read_color(cx, &attrs, p.start, pal)?;
                        if !is_empty {
                            cur.skip_element()
                                .map_err(|(o, m)| cx.err(o, "XML001", m))?;
                        }
                    }
                    "colors" => {
                        let count = attrs.iter().find(|a| a.name == "count");
                        let data = attrs.iter().find(|a| a.name == "data");
                        if let Some(d) = data {
                            let cols = decode_hex_colors(&d.value, 8).ok_or_else(|| {
                                cx.err(
                                    d.offset,
                                    "XML010",
                                    "colors data must be 8 hex digits per colour",
                                )
                            })?;
                            if let Some(c) = count {
                                let n = cx.int(c)?;
                                if n != cols.len() as i64 {
                                    return Err(cx.err(
                                        d.offset,
                                        "XML010",
                                        format!(
                                            "colors count {n} but data holds {} colours",
                                            cols.len()
                                        ),
                                    ));
                                }
                            }
                            for (i, c) in cols.iter().take(256).enumerate() {
                                pal.colors[i] = Some([
                                    c[1] as f64 / 255.0,
                                    c[2] as f64 / 255.0,
                                    c[3] as f64 / 255.0,
                                    1.0,
                                ]);
                                pal.any = true;
                            }
                        }
                        if !is_empty {
                            cur.skip_element()
                                .map_err(|(o, m)| cx.err(o, "XML001", m))?;
                        }
                    }
                    "palette" => read_palette(cx, cur, &attrs, p.start, is_empty, pal)?,
                    "symmetry" => {
                        let Some(k) = attrs.iter().find(|a| a.name == "kind") else {
                            return Err(cx.err(
                                p.start,
                                "XML003",
                                "<symmetry> needs a 'kind' attribute",
                            ));
                        };
                        let kind = cx.int(k)?;
                        if kind.abs() > 1000 {
                            return Err(cx.err(
                                k.offset,
                                "XML003",
                                format!("symmetry kind {kind} is out of range"),
                            ));
                        }
                        add_symmetry(f, kind as i32);
                        if !is_empty {
                            cur.skip_element()
                                .map_err(|(o, m)| cx.err(o, "XML001", m))?;
                        }
                    }
                    _ => {
                        // <edit> and anything else: kept verbatim.
                        let end = if is_empty {
                            p.end
                        } else {
                            cur.skip_element()
                                .map_err(|(o, m)| cx.err(o, "XML001", m))?
                        };
                        f.extra_children.push(text[p.start..end].to_string());
                    }
                }
            }
            _ => {}
        }
    }
}

fn read_color(cx: &mut Ctx, attrs: &[Attr], start: usize, pal: &mut PaletteData) -> R<()> {
    let mut index: Option<i64> = None;
    let mut rgb = [0.0; 3];
    let mut alpha = 255.0;
    let mut value_off = start;
    for a in attrs {
        match a.name {
            "index" => {
                index = Some(cx.int(a).map_err(|_| {
                    cx.err(
                        a.offset,
                        "XML009",
                        format!("color index '{}' is not an integer", a.value),
                    )
                })?)
            }
            "rgb" => {
                let v: [f64; 3] = cx.fixed(a, "XML009", "numbers")?;
                rgb = v;
                value_off = a.offset;
            }
            "rgba" => {
                let v: [f64; 4] = cx.fixed(a, "XML009", "numbers")?;
                rgb = [v[0], v[1], v[2]];
                alpha = v[3];
                value_off = a.offset;
            }
            "a" => alpha = cx.num(a)?,
            _ => {}
        }
    }
    let i = match index {
        Some(i) if (0..=255).contains(&i) => i as usize,
        Some(i) => {
            return Err(cx.err(
                start,
                "XML009",
                format!("color index {i} is outside 0..255"),
            ));
        }
        None => return Err(cx.err(start, "XML009", "<color> without an index")),
    };
    let mut clamp = |v: f64| {
        if !(0.0..=255.0).contains(&v) {
            cx.warn(
                value_off,
                "XML015",
                format!("colour component {v} is outside 0..255; clamped"),
            );
        }
        v.clamp(0.0, 255.0).round() / 255.0
    };
    let c = [clamp(rgb[0]), clamp(rgb[1]), clamp(rgb[2]), clamp(alpha)];
    pal.colors[i] = Some(c);
    pal.any = true;
    Ok(())
}

fn read_palette(
    cx: &mut Ctx,
    cur: &mut XmlCursor,
    attrs: &[Attr],
    start: usize,
    is_empty: bool,
    pal: &mut PaletteData,
) -> R<()> {
    let get = |n: &str| attrs.iter().find(|a| a.name == n);
    let legacy = ["index0", "index1", "hue0", "hue1", "blend"]
        .iter()
        .any(|n| get(n).is_some());
    let modern = get("count").is_some() || get("format").is_some();
    if legacy && modern {
        return Err(cx.err(
            start,
            "XML010",
            "mixing the old (index0/hue0) and new (count/format) palette syntax",
        ));
    }
    // Collect the text content.
    let mut content = String::new();
    let mut content_off = start;
    if !is_empty {
        loop {
            let p = cur.next_event().map_err(|(o, m)| cx.err(o, "XML001", m))?;
            match &p.event {
                Event::Text(t) => {
                    if content.is_empty() {
                        content_off = p.start;
                    }
                    content.push_str(t);
                }
                Event::End(_) => break,
                Event::Eof => {
                    return Err(cx.err(p.start, "XML001", "end of file inside <palette>"));
                }
                Event::Start(_) => {
                    cur.skip_element()
                        .map_err(|(o, m)| cx.err(o, "XML001", m))?;
                }
                _ => {}
            }
        }
    }
    if legacy {
        let idx = get("index0").map(|a| cx.int(a)).transpose()?.unwrap_or(0);
        let hue0 = get("hue0").map(|a| cx.num(a)).transpose()?.unwrap_or(0.0);
        cx.warn(
            start,
            "XML019",
            "old-style <palette index0=…>: using index0 with hue0 only",
        );
        let lib = cx.library();
        let g = match lib {
            Ok(l) => l.get(idx.max(0) as usize).cloned().ok_or_else(|| {
                cx.err(
                    start,
                    "XML011",
                    format!("palette {idx} is not in the library"),
                )
            })?,
            Err(m) => return Err(cx.err(start, "XML011", m.clone())),
        };
        let g = hue_rotate(&g, hue0);
        for (i, c) in g.colors.iter().enumerate() {
            pal.colors[i] = Some(*c);
        }
        pal.any = true;
        return Ok(());
    }
    let count = match get("count") {
        Some(a) => {
            let n = cx.int(a)?;
            if !(1..=MAX_PALETTE).contains(&n) {
                return Err(cx.err(
                    a.offset,
                    "XML010",
                    format!("palette count {n} is outside 1..{MAX_PALETTE}"),
                ));
            }
            n as usize
        }
        None => 256,
    };
    let dpc = match get("format").map(|a| (a.value.trim().to_string(), a.offset)) {
        None => 6,
        Some((f, _)) if f == "RGB" => 6,
        Some((f, _)) if f == "RGBA" => 8,
        Some((f, off)) => {
            return Err(cx.err(
                off,
                "XML010",
                format!("palette format '{f}' must be RGB or RGBA"),
            ));
        }
    };
    for tok in content.split_whitespace() {
        if !tok.len().is_multiple_of(dpc) || !tok.bytes().all(|c| c.is_ascii_hexdigit()) {
            return Err(cx.err(
                content_off,
                "XML010",
                format!("palette data must be hex colours of {dpc} digits (whitespace only between colours)"),
            ));
        }
    }
    let cols = decode_hex_colors(&content, dpc).unwrap_or_default();
    if cols.len() != count {
        return Err(cx.err(
            content_off,
            "XML010",
            format!(
                "palette count is {count} but the data holds {} colours",
                cols.len()
            ),
        ));
    }
    let rgba: Vec<[f64; 4]> = cols
        .iter()
        .map(|c| {
            let a = if dpc == 8 { c[3] as f64 / 255.0 } else { 1.0 };
            [
                c[0] as f64 / 255.0,
                c[1] as f64 / 255.0,
                c[2] as f64 / 255.0,
                a,
            ]
        })
        .collect();
    if rgba.len() > 256 {
        // Kept whole for rendering; the editor's 256-entry gradient is its resampling.
        for (i, c) in resample_colors(&rgba, 256).into_iter().enumerate() {
            pal.colors[i] = Some(c);
        }
        pal.hires = Some(rgba);
    } else {
        for (i, c) in rgba.into_iter().enumerate() {
            pal.colors[i] = Some(c);
        }
    }
    pal.any = true;
    Ok(())
}

/// Set the weight of a variation form (replacing an earlier attribute for the same form; weight
/// 0 removes it).
fn set_var(x: &mut Xform, id: variations::VarId, form: Form, w: f64) {
    x.vars.retain(|v| !(v.id == id && v.form == form));
    if w != 0.0 {
        x.vars.push(Var::with_form(id, form, w));
    }
}

fn read_xform(cx: &mut Ctx, attrs: &[Attr], fin: bool, parity: f64, start: usize) -> R<Xform> {
    let mut x = Xform {
        weight: 0.0,
        color: parity,
        vars: Vec::new(),
        ..Xform::default()
    };
    let mut color_speed: Option<f64> = None;
    let mut symmetry: Option<f64> = None;
    let mut params: Vec<(variations::VarId, Form, usize, f64, String, String)> = Vec::new();
    let mut texts: Vec<(variations::VarId, Form, usize, String, String, String)> = Vec::new();
    // JWildfire writes NAME_fx_priority beside every variation it writes; in other programs'
    // files a variation is followed by its NAME_parameters. Both sets are built once, so an
    // xform with very many attributes is still read in linear time.
    let fx_marked: HashSet<&str> = attrs
        .iter()
        .filter_map(|b| b.name.strip_suffix("_fx_priority"))
        .collect();
    let jwildfire = !fx_marked.is_empty();
    let marked_vars: HashSet<&str> = if jwildfire {
        fx_marked
    } else {
        attrs
            .iter()
            .flat_map(|b| {
                let n = b.name;
                n.match_indices('_')
                    .filter(move |(i, _)| *i > 0 && *i + 1 < n.len())
                    .map(move |(i, _)| &n[..i])
            })
            .collect()
    };
    for a in attrs {
        let v = a.value.trim();
        match a.name {
            "weight" => {
                let w = cx.num(a).map_err(|d| Diagnostic {
                    code: "XML005",
                    ..d
                })?;
                if w < 0.0 {
                    return Err(cx.err(
                        a.offset,
                        "XML005",
                        format!("weight {w} must not be negative"),
                    ));
                }
                if fin && w != 0.0 {
                    return Err(cx.err(a.offset, "XML005", "a <finalxform> has no weight"));
                }
                x.weight = w;
            }
            "color" => {
                let c = cx.nums(a, "XML003")?;
                if c.is_empty() || c.len() > 2 {
                    return Err(cx.err(
                        a.offset,
                        "XML003",
                        "color must be one number (or two, legacy)",
                    ));
                }
                x.color = c[0];
            }
            "color_speed" => color_speed = Some(cx.num(a)?),
            "symmetry" => symmetry = Some(cx.num(a)?),
            "opacity" => {
                let o = cx.num(a)?;
                if !(0.0..=1.0).contains(&o) {
                    return Err(cx.err(a.offset, "XML003", format!("opacity {o} must be in 0..1")));
                }
                x.opacity = o;
            }
            "plotmode" => {
                if v == "off" {
                    x.opacity = 0.0;
                }
            }
            "coefs" | "post" => {
                let c: [f64; 6] = cx.fixed(a, "XML004", "numbers").map_err(|d| Diagnostic {
                    code: "XML004",
                    ..d
                })?;
                let m = Affine::from_coefs(c);
                if a.name == "coefs" {
                    x.coefs = m;
                } else {
                    x.post = m;
                }
            }
            "chaos" => {
                let c = cx.nums(a, "XML008")?;
                if let Some(bad) = c.iter().find(|v| **v < 0.0) {
                    return Err(cx.err(
                        a.offset,
                        "XML008",
                        format!("xaos value {bad} must not be negative"),
                    ));
                }
                x.chaos = c;
            }
            "direct_color" => x.direct_color = cx.num(a)?,
            "var" => {
                let ws = cx.nums(a, "XML003")?;
                if ws.len() > variations::FLAM3_COUNT {
                    return Err(cx.err(
                        a.offset,
                        "XML003",
                        format!("var holds {} weights; at most 99", ws.len()),
                    ));
                }
                for (i, w) in ws.iter().enumerate() {
                    if *w != 0.0
                        && let Some((id, form)) = variations::from_flam3_index(i)
                    {
                        set_var(&mut x, id, form, *w);
                    }
                }
            }
            "var1" => {
                let i = cx.int(a)?;
                let Some((id, form)) = usize::try_from(i)
                    .ok()
                    .and_then(variations::from_flam3_index)
                else {
                    return Err(cx.err(
                        a.offset,
                        "XML003",
                        format!("var1 index {i} is outside 0..98"),
                    ));
                };
                x.vars.clear();
                set_var(&mut x, id, form, 1.0);
            }
            name => {
                if let Some((id, form)) = variations::parse_name(name) {
                    let w = cx.num(a)?;
                    set_var(&mut x, id, form, w);
                } else if let Some((id, form, pi)) = variations::param_of(name) {
                    let pv = cx.num(a)?;
                    params.push((id, form, pi, pv, name.to_string(), a.value.to_string()));
                } else if let Some((id, form, ti)) = variations::text_of(name) {
                    texts.push((
                        id,
                        form,
                        ti,
                        text_from_hex(v),
                        name.to_string(),
                        v.to_string(),
                    ));
                } else {
                    let numeric = parse_number(v).is_ok();
                    let marked = marked_vars.contains(name);
                    if numeric && (marked || variations::is_foreign_variation_name(name)) {
                        if cx.reported_vars.insert(name.to_string()) {
                            cx.warn(
                                a.offset,
                                "XML020",
                                format!("variation '{name}' (weight {v}) not supported; ignored"),
                            );
                        }
                    } else if !matches!(
                        name,
                        "animate" | "var_color" | "name" | "motion_frequency" | "motion_function"
                    ) {
                        cx.ignore(name);
                    }
                    x.extra_attrs.push((name.to_string(), a.value.to_string()));
                }
            }
        }
    }
    x.color_speed = match (color_speed, symmetry) {
        (Some(s), _) => s,
        (None, Some(sig)) => (1.0 - sig) / 2.0,
        (None, None) => 0.5,
    };
    // JWildfire marks a variation used before (< 0) or after (> 0) the others with
    // NAME_fx_priority.
    for a in attrs {
        if let Some(name) = a.name.strip_suffix("_fx_priority")
            && let Ok(p) = parse_number(a.value.trim())
            && p != 0.0
            && let Some((id, Form::Regular)) = variations::parse_name(name)
        {
            let form = if p < 0.0 { Form::Pre } else { Form::Post };
            for var in x
                .vars
                .iter_mut()
                .filter(|v| v.id == id && v.form == Form::Regular)
            {
                var.form = form;
            }
            for p in params
                .iter_mut()
                .filter(|p| p.0 == id && p.1 == Form::Regular)
            {
                p.1 = form;
            }
            for t in texts
                .iter_mut()
                .filter(|t| t.0 == id && t.1 == Form::Regular)
            {
                t.1 = form;
            }
        }
    }
    // Parameters go to their variation; parameters of absent variations are kept as-is.
    for (id, form, pi, pv, name, raw) in params {
        if let Some(var) = x.vars.iter_mut().find(|v| v.id == id && v.form == form) {
            var.params[pi] = pv;
        } else {
            x.extra_attrs.push((name, raw));
        }
    }
    for (id, form, ti, text, name, raw) in texts {
        if let Some(var) = x.vars.iter_mut().find(|v| v.id == id && v.form == form) {
            var.texts[ti] = variations::info(id).texts[ti].normalise(&text);
        } else {
            x.extra_attrs.push((name, raw));
        }
    }
    let _ = start;
    Ok(x)
}

/// A text parameter's value: JWildfire writes the hex digits of its bytes ("53594D" for
/// "SYM"); a value that is not an even number of hex digits is taken as it stands.
fn text_from_hex(v: &str) -> String {
    let v = v.trim();
    let hex = v.len().is_multiple_of(2) && v.bytes().all(|b| b.is_ascii_hexdigit());
    if !hex {
        return v.to_string();
    }
    let bytes: Vec<u8> = (0..v.len())
        .step_by(2)
        .filter_map(|i| u8::from_str_radix(&v[i..i + 2], 16).ok())
        .collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

/// The hex digits of a text parameter's bytes, as JWildfire writes them.
fn text_to_hex(t: &str) -> String {
    t.bytes().map(|b| format!("{b:02X}")).collect()
}

// ---------------------------------------------------------------------------------------------
// Writing

/// Write a whole `.fla`/`.flame` document.
pub fn write(file: &FlameFile) -> String {
    let mut s = String::new();
    s.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        s,
        "<flames name=\"{}\" ugnis_format=\"{FLA_FORMAT}\">",
        escape_attr(&file.name)
    );
    let mut used: Vec<String> = Vec::new();
    for (i, f) in file.flames.iter().enumerate() {
        // Every flame needs a unique non-empty name.
        let mut name = if f.name.trim().is_empty() {
            format!("flame-{:03}", i + 1)
        } else {
            f.name.clone()
        };
        if used.contains(&name) {
            let base = name.clone();
            let mut k = 2;
            while used.contains(&name) {
                name = format!("{base}-{k}");
                k += 1;
            }
        }
        used.push(name.clone());
        write_flame(&mut s, f, &name, "   ");
    }
    s.push_str("</flames>\n");
    s
}

/// One `<flame>…</flame>` element (no declaration, no root), as embedded in PNG files.
pub fn flame_element(f: &Flame) -> String {
    let mut s = String::new();
    let name = if f.name.is_empty() {
        "ugnis".to_string()
    } else {
        f.name.clone()
    };
    write_flame(&mut s, f, &name, "");
    s
}

fn write_flame(s: &mut String, f: &Flame, name: &str, ind: &str) {
    let n = fmt_num;
    let _ = write!(
        s,
        "{ind}<flame name=\"{}\" version=\"ugnis-{}\" size=\"{} {}\" center=\"{} {}\" scale=\"{}\" rotate=\"{}\" zoom=\"{}\" \
         supersample=\"{}\" filter=\"{}\" filter_shape=\"{}\" quality=\"{}\" background=\"{} {} {}\" brightness=\"{}\" \
         gamma=\"{}\" gamma_threshold=\"{}\" vibrancy=\"{}\" highlight_power=\"{}\" estimator_radius=\"{}\" \
         estimator_minimum=\"{}\" estimator_curve=\"{}\" palette_mode=\"{}\" new_linear=\"1\" ugnis_contrast=\"{}\"",
        escape_attr(name),
        crate::VERSION,
        f.width,
        f.height,
        n(f.center[0]),
        n(f.center[1]),
        n(f.scale),
        n(f.rotate),
        n(f.zoom),
        f.supersample,
        n(f.filter),
        f.filter_shape.name(),
        n(f.quality),
        n(f.background[0]),
        n(f.background[1]),
        n(f.background[2]),
        n(f.brightness),
        n(f.gamma),
        n(f.gamma_threshold),
        n(f.vibrancy),
        n(f.highlight_power),
        n(f.estimator_radius),
        n(f.estimator_minimum),
        n(f.estimator_curve),
        f.palette_mode.name(),
        n(f.contrast),
    );
    if let Some(seed) = f.seed {
        let _ = write!(s, " ugnis_seed=\"{seed}\"");
    }
    let _ = write!(s, " ugnis_kind=\"{}\"", f.kind.name());
    if f.palette_index != PaletteIndex::Flam3 {
        let _ = write!(s, " ugnis_palette_index=\"{}\"", f.palette_index.name());
    }
    if let Some(aw) = f.auto_weights {
        let _ = write!(s, " ugnis_auto_weights=\"{}\"", aw as u8);
    }
    if !f.palette.name.is_empty() {
        let _ = write!(s, " ugnis_gradient=\"{}\"", escape_attr(&f.palette.name));
    }
    if let Some(solo) = f.solo_xform {
        let _ = write!(s, " soloxform=\"{solo}\"");
    }
    if !f.curves.is_identity() {
        for (ci, name) in ["overall_curve", "red_curve", "green_curve", "blue_curve"]
            .iter()
            .enumerate()
        {
            let v: Vec<String> = f.curves.points[ci]
                .iter()
                .flat_map(|p| [n(p[0]), n(p[1])])
                .collect();
            let _ = write!(s, " {name}=\"{}\"", v.join(" "));
        }
    }
    if f.cam_zoom != 1.0 {
        let _ = write!(s, " cam_zoom=\"{}\"", n(f.cam_zoom));
    }
    let c = &f.cam;
    if !c.is_flat() || c.blur_curve != 0.0 {
        let _ = write!(
            s,
            " cam_pitch=\"{}\" cam_yaw=\"{}\" cam_perspective=\"{}\" cam_zpos=\"{}\" cam_dof=\"{}\"",
            n(c.pitch),
            n(c.yaw),
            n(c.perspective),
            n(c.zpos),
            n(c.dof)
        );
        if c.blur_curve != 0.0 {
            let _ = write!(s, " blur_curve=\"{}\"", n(c.blur_curve));
        }
    }
    for (k, v) in &f.extra_attrs {
        let _ = write!(s, " {k}=\"{}\"", escape_attr(v));
    }
    s.push_str(">\n");
    let inner = format!("{ind}   ");
    for x in &f.xforms {
        write_xform(s, x, "xform", &inner);
    }
    if let Some(fx) = &f.final_xform {
        write_xform(s, fx, "finalxform", &inner);
    }
    write_palette(s, f.render_colors(), &inner);
    for c in &f.extra_children {
        let _ = writeln!(s, "{inner}{}", c.trim());
    }
    let _ = writeln!(s, "{ind}</flame>");
}

fn write_xform(s: &mut String, x: &Xform, tag: &str, ind: &str) {
    let n = fmt_num;
    let _ = write!(s, "{ind}<{tag}");
    if tag == "xform" {
        let _ = write!(s, " weight=\"{}\"", n(x.weight));
    }
    let _ = write!(s, " color=\"{}\"", n(x.color));
    if x.color_speed != 0.5 {
        let _ = write!(s, " symmetry=\"{}\"", n(1.0 - 2.0 * x.color_speed));
    }
    let _ = write!(s, " color_speed=\"{}\"", n(x.color_speed));
    if x.opacity != 1.0 {
        let _ = write!(s, " opacity=\"{}\"", n(x.opacity));
    }
    if x.direct_color != 1.0 {
        let _ = write!(s, " direct_color=\"{}\"", n(x.direct_color));
    }
    for v in &x.vars {
        let _ = write!(s, " {}=\"{}\"", v.attr_name(), n(v.weight));
    }
    for v in &x.vars {
        for i in 0..variations::info(v.id).params.len() {
            let name = variations::param_attr_name(v.id, v.form, i);
            let _ = write!(s, " {name}=\"{}\"", n(v.params[i]));
        }
        for (i, t) in v.texts.iter().enumerate() {
            let name = variations::text_attr_name(v.id, v.form, i);
            let _ = write!(s, " {name}=\"{}\"", text_to_hex(t));
        }
    }
    let c = x.coefs.to_coefs();
    let _ = write!(
        s,
        " coefs=\"{} {} {} {} {} {}\"",
        n(c[0]),
        n(c[1]),
        n(c[2]),
        n(c[3]),
        n(c[4]),
        n(c[5])
    );
    if !x.post.is_identity() {
        let p = x.post.to_coefs();
        let _ = write!(
            s,
            " post=\"{} {} {} {} {} {}\"",
            n(p[0]),
            n(p[1]),
            n(p[2]),
            n(p[3]),
            n(p[4]),
            n(p[5])
        );
    }
    let mut chaos = x.chaos.clone();
    while chaos.last() == Some(&1.0) {
        chaos.pop();
    }
    if !chaos.is_empty() {
        let v: Vec<String> = chaos.iter().map(|c| n(*c)).collect();
        let _ = write!(s, " chaos=\"{}\"", v.join(" "));
    }
    for (k, v) in &x.extra_attrs {
        let _ = write!(s, " {k}=\"{}\"", escape_attr(v));
    }
    if x.extra_children.is_empty() {
        s.push_str("/>\n");
    } else {
        s.push_str(">\n");
        for c in &x.extra_children {
            let _ = writeln!(s, "{ind}   {}", c.trim());
        }
        let _ = writeln!(s, "{ind}</{tag}>");
    }
}

fn to8(v: f64) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

fn write_palette(s: &mut String, colors: &[[f64; 4]], ind: &str) {
    let rgba = colors.iter().any(|c| c[3] < 1.0);
    let fmt = if rgba { "RGBA" } else { "RGB" };
    let _ = writeln!(
        s,
        "{ind}<palette count=\"{}\" format=\"{fmt}\">",
        colors.len()
    );
    for line in colors.chunks(8) {
        s.push_str(ind);
        s.push_str("   ");
        for c in line {
            let _ = write!(s, "{:02X}{:02X}{:02X}", to8(c[0]), to8(c[1]), to8(c[2]));
            if rgba {
                let _ = write!(s, "{:02X}", to8(c[3]));
            }
        }
        s.push('\n');
    }
    let _ = writeln!(s, "{ind}</palette>");
}

#[cfg(test)]
mod tests {
    use super::*;

    fn opts() -> ReadOptions<'static> {
        ReadOptions {
            file: "t.flame".into(),
            library: LibrarySource::Paths(vec![]),
            ..ReadOptions::default()
        }
    }

    const SIMPLE: &str = r#"<flames name="test">
<flame name="a" size="64 48" center="0.5 -0.25" scale="20" quality="50" brightness="3" gamma="2.5">
  <xform weight="0.5" color="0" spherical="1" coefs="0.85 -0.04 0.04 0.85 0 1.6"/>
  <xform weight="0.25" color="1" symmetry="1" julian="0.5" julian_power="3" julian_dist="-1" coefs="1 0 0 1 0 0" post="0.5 0 0 0.5 0.1 0.2" chaos="1 0"/>
  <finalxform color="0.5" color_speed="0" linear="1" coefs="1 0 0 1 0 0"/>
  <color index="0" rgb="255 0 0"/>
  <color index="255" rgb="0 0 255"/>
  <edit date="today"><edit nick="x"/></edit>
</flame>
</flames>"#;

    /// A flame of other programs: 3-D camera, a 512-colour palette, pre_/post_ forms, JWildfire
    /// priorities, Apophysis' mobius names, attributes ugnis does not interpret.
    const FOREIGN: &str = r#"<flame name="f" size="64 48" scale="20" cam_pitch="1.0471975511966" cam_yaw="0.25" cam_perspective="0.3" cam_zpos="0.5" cam_dof="0.2" cam_zoom="2" overall_curve="0 0 0.5 0.7 1 1" mod_contrast="1" material="0">
  <xform weight="1" color="0" pre_blur="0.1" spherical3D="0.5" post_curl="0.7" post_curl_c1="0.3" Mobius="0.2" Re_A="2" Im_D="0.5" starblur="0.4" starblur_fx_priority="-1" starblur_power="6" mirror_pre_post_translations="0" xyCoeff00Curve_enabled="false" coefs="1 0 0 1 0 0"/>
  <palette count="512" format="RGB">PALETTE</palette>
</flame>"#;

    fn foreign() -> String {
        let mut data = String::new();
        for i in 0..512 {
            data.push_str(&format!("{:02X}00{:02X}", i / 2, 255 - i / 2));
        }
        FOREIGN.replace("PALETTE", &data)
    }

    #[test]
    fn reads_flames_of_other_programs() {
        let p = read(&foreign(), &opts()).unwrap();
        let f = &p.value.flames[0];
        assert!((f.cam.pitch - std::f64::consts::FRAC_PI_3).abs() < 1e-12);
        assert_eq!(
            (f.cam.yaw, f.cam.perspective, f.cam.zpos, f.cam.dof),
            (0.25, 0.3, 0.5, 0.2)
        );
        assert_eq!(f.cam_zoom, 2.0);
        assert_eq!(f.ppu(), 40.0);
        assert_eq!(f.curves.points[0], vec![[0.0, 0.0], [0.5, 0.7], [1.0, 1.0]]);
        assert!(f.curves.points[1..].iter().all(|c| c.len() == 5));
        let x = &f.xforms[0];
        let form = |name: &str| {
            let (id, form) = variations::parse_name(name).unwrap();
            x.vars
                .iter()
                .find(|v| v.id == id && v.form == form)
                .unwrap_or_else(|| panic!("{name} missing"))
        };
        assert_eq!(form("pre_blur").weight, 0.1);
        assert_eq!(form("spherical3D").weight, 0.5);
        let curl = form("post_curl");
        assert_eq!((curl.weight, curl.params[0]), (0.7, 0.3));
        let mobius = form("mobius");
        assert_eq!(mobius.param("mobius_re_a"), Some(2.0));
        assert_eq!(mobius.param("mobius_im_d"), Some(0.5));
        // JWildfire's priority −1: used before the other variations.
        assert_eq!(form("pre_starblur").weight, 0.4);
        assert_eq!(form("pre_starblur").param("starblur_power"), Some(6.0));
        // Attributes of other programs: kept, reported once, never as variations.
        let codes: Vec<&str> = p.warnings.iter().map(|w| w.code).collect();
        assert_eq!(codes, vec!["XML021"], "{:?}", p.warnings);
        assert!(p.warnings[0].to_string().contains("mod_contrast"));
        // The 512 colours render as they are; the editor sees 256.
        assert_eq!(f.render_colors().len(), 512);
        assert_eq!(f.palette.colors.len(), 256);
        assert_eq!(
            crate::flame::histogram::PlotPalette::new(f).colors.len(),
            512
        );
    }

    #[test]
    fn flames_of_other_programs_round_trip() {
        let f = read(&foreign(), &opts()).unwrap().value.flames[0].clone();
        let text = flame_element(&f);
        assert!(text.contains("<palette count=\"512\""), "{text}");
        for attr in [
            "cam_pitch=\"1.0471975511966\"",
            "cam_zoom=\"2\"",
            "pre_blur=\"0.1\"",
            "post_curl_c1=\"0.3\"",
            "mod_contrast=\"1\"",
            "xyCoeff00Curve_enabled=\"false\"",
        ] {
            assert!(text.contains(attr), "{attr} missing in {text}");
        }
        let back = read(&text, &opts()).unwrap().value.flames[0].clone();
        assert_eq!(back.cam, f.cam);
        assert_eq!(back.cam_zoom, f.cam_zoom);
        assert_eq!(back.curves, f.curves);
        assert_eq!(back.xforms[0].vars, f.xforms[0].vars);
        assert_eq!(back.render_colors(), f.render_colors());
        // An edited gradient replaces the file's 512 colours.
        let mut edited = f.clone();
        edited.palette.colors[0] = [1.0, 1.0, 1.0, 1.0];
        assert_eq!(edited.render_colors().len(), 256);
        assert!(flame_element(&edited).contains("<palette count=\"256\""));
    }

    /// Each file keeps the palette rule of the program that wrote it, through ugnis' own files.
    #[test]
    fn palette_rule_follows_the_writing_program() {
        use crate::flame::PaletteIndex;
        let flame = |head: &str| {
            format!(
                "<flame name=\"p\" {head} size=\"8 8\" center=\"0 0\" scale=\"4\">\
                 <xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/></flame>"
            )
        };
        let one = |head: &str| read(&flame(head), &opts()).unwrap().value.flames[0].clone();
        for (head, index, mode) in [
            (
                "version=\"EMBER-LNX-1.0.0.19\" palette_mode=\"linear\"",
                PaletteIndex::Fractorium,
                PaletteMode::Linear,
            ),
            (
                "version=\"JWildfire V5.60 (07.05.2020)\" smooth_gradient=\"0\"",
                PaletteIndex::JWildfire,
                PaletteMode::Step,
            ),
            (
                "version=\"JWildfire V5.60 (07.05.2020)\" smooth_gradient=\"1\"",
                PaletteIndex::JWildfire,
                PaletteMode::Linear,
            ),
            (
                "version=\"Apophysis 7x\"",
                PaletteIndex::Apophysis,
                PaletteMode::Step,
            ),
            (
                "version=\"FLAM3-LNX-3.1.1\"",
                PaletteIndex::Flam3,
                PaletteMode::Step,
            ),
            (
                "smooth_gradient=\"1\"",
                PaletteIndex::Flam3,
                PaletteMode::Step,
            ),
            (
                "version=\"ugnis-0.1.0\" ugnis_palette_index=\"jwildfire\"",
                PaletteIndex::JWildfire,
                PaletteMode::Step,
            ),
        ] {
            let f = one(head);
            assert_eq!((f.palette_index, f.palette_mode), (index, mode), "{head}");
            let text = flame_element(&f);
            assert_eq!(
                text.contains("ugnis_palette_index="),
                index != PaletteIndex::Flam3,
                "{text}"
            );
            let back = read(&text, &opts()).unwrap().value.flames[0].clone();
            assert_eq!(back, f, "{head}");
        }
        let e = read(&flame("ugnis_palette_index=\"xaos\""), &opts()).unwrap_err();
        assert!(
            e.to_string()
                .contains("must be 'flam3', 'apophysis', 'fractorium' or 'jwildfire'"),
            "{e}"
        );
    }

    /// JWildfire's text parameters: the hex digits of their bytes, read into the variation and
    /// written back the same way.
    #[test]
    fn text_parameters_round_trip_as_hex() {
        let src = r#"<flame name="t" size="8 8" center="0 0" scale="4">
<xform weight="1" color="0" text_wf="1" text_wf_font_size="100" text_wf_text="53594D20C3A9" text_wf_font_name="417269616C" coefs="1 0 0 1 0 0"/>
<xform weight="1" color="1" linear="1" text_wf_text="4142" coefs="1 0 0 1 0 0"/></flame>"#;
        let p = read(src, &opts()).unwrap();
        assert!(
            p.warnings.iter().all(|w| w.code == "XML018"), // no palette in this snippet
            "{:?}",
            p.warnings
        );
        let x = &p.value.flames[0].xforms;
        let v = &x[0].vars[0];
        assert_eq!(v.texts, ["SYM é", "Arial"]);
        assert_eq!(v.params[0], 100.0);
        // A text of an absent variation is kept as it was.
        assert!(
            x[1].extra_attrs
                .contains(&("text_wf_text".into(), "4142".into()))
        );
        let text = write(&p.value);
        assert!(text.contains("text_wf_text=\"53594D20C3A9\""), "{text}");
        assert!(text.contains("text_wf_font_name=\"417269616C\""), "{text}");
        let back = read(&text, &opts()).unwrap().value;
        assert_eq!(back.flames, p.value.flames);
        // Not hex digits: taken as written.
        let plain = src.replace("53594D20C3A9", "hello!");
        let q = read(&plain, &opts()).unwrap().value;
        assert_eq!(q.flames[0].xforms[0].vars[0].texts[0], "hello!");
    }

    #[test]
    fn reads_attributes_and_palette() {
        let p = read(SIMPLE, &opts()).unwrap();
        let ff = p.value;
        assert_eq!(ff.name, "test");
        let f = &ff.flames[0];
        assert_eq!((f.width, f.height), (64, 48));
        assert_eq!(f.center, [0.5, -0.25]);
        assert_eq!(f.quality, 50.0);
        assert_eq!(f.gamma, 2.5);
        assert_eq!(f.gamma_threshold, 0.01);
        assert_eq!(f.xforms.len(), 2);
        let x0 = &f.xforms[0];
        // coefs are "a c b d e f".
        assert_eq!(x0.coefs, Affine::new(0.85, 0.04, -0.04, 0.85, 0.0, 1.6));
        assert_eq!(x0.var_weight(variations::SPHERICAL), 0.5 * 2.0);
        let x1 = &f.xforms[1];
        assert_eq!(x1.color_speed, 0.0);
        let j = x1.var(variations::JULIAN).unwrap();
        assert_eq!(j.params, vec![3.0, -1.0]);
        assert_eq!(x1.chaos, vec![1.0, 0.0]);
        assert_eq!(x1.post.e, 0.1);
        let fx = f.final_xform.as_ref().unwrap();
        assert_eq!(fx.color_speed, 0.0);
        // Undefined palette entries are interpolated.
        assert_eq!(f.palette.colors[0][0], 1.0);
        assert_eq!(f.palette.colors[255][2], 1.0);
        assert!((f.palette.colors[128][0] - (127.0 / 255.0)).abs() < 1e-12);
        assert_eq!(f.extra_children.len(), 1);
        assert!(f.extra_children[0].starts_with("<edit date=\"today\">"));
    }

    #[test]
    fn round_trip_is_lossless() {
        let src = r#"<flame name="r" size="10 10" center="0 0" scale="5" foo="bar">
<xform weight="1" color="0.3" linear="0.7" waves="0.3" coefs="1 2 3 4 5 6" animate="0" my_plugin="2" my_plugin_amount="0.5"/>
<palette count="2" format="RGB">FF000000FF00</palette></flame>"#;
        let a = read(src, &opts()).unwrap();
        assert!(a.warnings.iter().any(|w| w.message.contains("my_plugin")));
        let text = write(&a.value);
        let b = read(&text, &opts()).unwrap().value;
        assert_eq!(a.value.flames, b.flames);
        let x = &b.flames[0].xforms[0];
        assert!(x.extra_attrs.contains(&("my_plugin".into(), "2".into())));
        assert!(
            b.flames[0]
                .extra_attrs
                .contains(&("foo".into(), "bar".into()))
        );
        // Writing again gives the same text.
        assert_eq!(write(&b), text);
    }

    #[test]
    fn hex_palette_and_errors_have_positions() {
        let bad = "<flame size=\"1 x\"><xform weight=\"1\" coefs=\"1 0 0 1 0 0\"/></flame>";
        let e = read(bad, &opts()).unwrap_err();
        assert_eq!(e.code, "XML003");
        assert_eq!(e.line(), Some(1));
        let e = read(
            "<flame><xform weight=\"-1\" coefs=\"1 0 0 1 0 0\"/></flame>",
            &opts(),
        )
        .unwrap_err();
        assert_eq!(e.code, "XML005");
        let e = read(
            "<flame>\n<xform weight=\"1\" coefs=\"1 0 0 1 0\"/></flame>",
            &opts(),
        )
        .unwrap_err();
        assert_eq!(e.code, "XML004");
        assert_eq!(e.pos, Pos::LineCol(2, 26));
        let e = read(
            "<flame><xform weight=\"0\" coefs=\"1 0 0 1 0 0\"/></flame>",
            &opts(),
        )
        .unwrap_err();
        assert_eq!(e.code, "XML007");
        let e = read(
            "<flame><xform weight=\"1\"/><finalxform/><finalxform/></flame>",
            &opts(),
        )
        .unwrap_err();
        assert_eq!(e.code, "XML006");
        let e = read("<flames/>", &opts()).unwrap_err();
        assert_eq!(e.code, "XML002");
        let e = read("<flame><xform weight='1'/>", &opts()).unwrap_err();
        assert_eq!(e.code, "XML001");
        let e = read("<flame palette=\"3\"><xform weight='1'/></flame>", &opts()).unwrap_err();
        assert_eq!(e.code, "XML011");
        assert!(e.message.contains("flam3-palettes.xml"), "{e}");
        let e = read(
            "<flame><xform weight='1'/><palette count=\"2\" format=\"RGB\">FF00 00FF0000</palette></flame>",
            &opts(),
        )
        .unwrap_err();
        assert_eq!(e.code, "XML010");
        let e = read(
            "<flame estimator_radius=\"1\" estimator_minimum=\"2\"><xform weight='1'/></flame>",
            &opts(),
        )
        .unwrap_err();
        assert_eq!(e.code, "XML012");
        let e = read("<flame quality=\"0\"><xform weight='1'/></flame>", &opts()).unwrap_err();
        assert_eq!(e.code, "XML013");
        let e = read("<flame><xform weight='1' chaos='1 -1'/></flame>", &opts()).unwrap_err();
        assert_eq!(e.code, "XML008");
        let e = read(
            "<flame><xform weight='1'/><color index='256' rgb='1 2 3'/></flame>",
            &opts(),
        )
        .unwrap_err();
        assert_eq!(e.code, "XML009");
        let e = read("<flame><xform weight='1' color='0,5'/></flame>", &opts()).unwrap_err();
        assert!(e.message.contains("decimal separator"), "{e}");
    }

    #[test]
    fn fla_rules() {
        let o = ReadOptions {
            fla: true,
            ..opts()
        };
        let e = read(
            "<pick><flame name='a'><xform weight='1'/></flame></pick>",
            &o,
        )
        .unwrap_err();
        assert_eq!(e.code, "FLA001");
        let e = read(
            "<flames>\n<flame name='a'><xform weight='1'/></flame>\n<flame name='a'><xform weight='1'/></flame></flames>",
            &o,
        )
        .unwrap_err();
        assert_eq!(e.code, "FLA002");
        assert!(e.message.contains("2:1"), "{e}");
        let e = read(
            "<flames><flame name='a' ugnis_kind='x'><xform weight='1'/></flame></flames>",
            &o,
        )
        .unwrap_err();
        assert_eq!(e.code, "FLA004");
    }

    #[test]
    fn several_roots_and_pick() {
        let src = "<pick><flame name='a'><xform weight='1' linear='1'/></flame><flame name='b'><xform weight='1'/></flame></pick>";
        let f = read(src, &opts()).unwrap().value;
        assert_eq!(f.flames.len(), 2);
        assert_eq!(f.flames[1].name, "b");
        // No colour data → default gradient with a warning.
        let p = read(src, &opts()).unwrap();
        assert!(p.warnings.iter().any(|w| w.code == "XML018"));
    }

    #[test]
    fn legacy_forms() {
        let src = "<flame angle=\"0.5\" oversample=\"2\" contrast=\"2\"><xform weight='1' var='0 0 1' coefs='1 0 0 1 0 0' plotmode='off'/><xform weight='1' var1='14'/><symmetry kind='3'/></flame>";
        let f = &read(src, &opts()).unwrap().value.flames[0];
        assert!((f.rotate + 0.5f64.to_degrees()).abs() < 1e-12);
        assert_eq!(f.supersample, 2);
        assert_eq!(f.contrast, 2.0);
        assert_eq!(f.xforms[0].var_weight(variations::SPHERICAL), 1.0);
        assert_eq!(f.xforms[0].opacity, 0.0);
        assert_eq!(f.xforms[1].var_weight(variations::BENT), 1.0);
        assert_eq!(f.xforms.len(), 4);
    }

    #[test]
    fn writer_follows_apophysis_line_rules() {
        let f = read(SIMPLE, &opts()).unwrap().value;
        let t = write(&f);
        for line in t.lines() {
            if line.contains("<flame ") {
                assert!(line.trim_start().starts_with("<flame ") && line.ends_with('>'));
            }
        }
        assert!(t.lines().any(|l| l.trim() == "</flame>"));
        assert!(t.contains("new_linear=\"1\""));
        // symmetry written before color_speed when s ≠ 0.5
        assert!(t.contains("symmetry=\"1\" color_speed=\"0\""));
        // Palette as zero-padded upper-case hex, 8 colours per line.
        assert!(t.contains("FF0000FE0001"), "{t}");
        assert!(!t.contains("ugnis_kind") || t.contains("ugnis_kind=\"flame\""));
    }
}
