//! A small SVG reader for `svg_wf`: the shapes of an SVG document as flattened polygons in
//! image pixels, with their fill and stroke.
//!
//! It reads what drawings from editors such as Inkscape mostly hold: `svg` (width, height,
//! viewBox), `g`, `path` (every command of SVG 1.1's path data, [`super::jwf_aa_svgpath`]),
//! `rect`, `circle`, `ellipse`, `line`, `polyline`, `polygon`; `transform` (matrix,
//! translate, scale, rotate, skewX, skewY); fill, stroke and their opacities, `opacity`,
//! stroke width, caps, joins and miter limit, fill rule, `display` and `visibility`, as
//! attributes or in `style`, inherited through groups; colours as `#rgb`, `#rrggbb`,
//! `rgb(…)` and common names. `defs`, metadata and elements of other namespaces
//! (Inkscape's, Sodipodi's, RDF) draw nothing.
//! Anything else that would draw (text, images, `use`, gradients and patterns as paint,
//! dashes, clipping, masks, filters, rounded rectangle corners) is listed in
//! [`Doc::problems`] and left out (dashed strokes are drawn solid, rounded corners square).
//! A group's `opacity` multiplies the opacities of its shapes (SVG would compose the group
//! first: overlapping shapes in a translucent group come out a little denser here).

use quick_xml::Reader;
use quick_xml::events::{BytesStart, Event};

use super::jwf_aa_raster::{Cap, FillRule, Join, Pt, ellipse_arc};
use super::jwf_aa_svgpath::{Cursor, path_data};

/// Most outline points of a document in image pixels (further shapes are left out): a
/// stroke is drawn as a few polygons per point, so this bounds the memory drawing takes
/// (about 0.3 KB a point).
const MAX_POINTS: usize = 250_000;

/// Most elements read.
const MAX_ELEMENTS: usize = 200_000;

/// A colour and its opacity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Paint {
    pub rgb: [u8; 3],
    pub alpha: f64,
}

/// How a shape's outline is drawn, in image pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct StrokeStyle {
    pub paint: Paint,
    pub width: f64,
    pub cap: Cap,
    pub join: Join,
}

/// One shape: its subpaths (points in image pixels, and whether each is closed), its fill
/// and its stroke, painted in that order.
#[derive(Clone, Debug)]
pub(super) struct Shape {
    pub subpaths: Vec<(Vec<Pt>, bool)>,
    pub fill: Option<(Paint, FillRule)>,
    pub stroke: Option<StrokeStyle>,
}

/// A document read.
#[derive(Clone, Debug, Default)]
pub(super) struct Doc {
    /// Its width and height in user units (pixels), as single precision floats (as SVG
    /// Salamander, which JWildfire uses, gives them).
    pub width: f64,
    pub height: f64,
    pub shapes: Vec<Shape>,
    /// What was not drawn, once each.
    pub problems: Vec<String>,
}

impl Doc {
    pub(super) fn problem(&mut self, p: String) {
        if !self.problems.contains(&p) && self.problems.len() < 32 {
            self.problems.push(p);
        }
    }
}

/// An affine map x' = a·x + c·y + e, y' = b·x + d·y + f.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Mat(pub(super) [f64; 6]);

impl Mat {
    pub(super) const ID: Mat = Mat([1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);

    /// `self` after `m` (m applied first).
    fn then_local(&self, m: &Mat) -> Mat {
        let [a, b, c, d, e, f] = self.0;
        let [a2, b2, c2, d2, e2, f2] = m.0;
        Mat([
            a * a2 + c * b2,
            b * a2 + d * b2,
            a * c2 + c * d2,
            b * c2 + d * d2,
            a * e2 + c * f2 + e,
            b * e2 + d * f2 + f,
        ])
    }

    pub(super) fn apply(&self, p: Pt) -> Pt {
        let [a, b, c, d, e, f] = self.0;
        (a * p.0 + c * p.1 + e, b * p.0 + d * p.1 + f)
    }

    /// The mean scale of lengths (square root of the determinant's size).
    pub(super) fn scale(&self) -> f64 {
        let [a, b, c, d, _, _] = self.0;
        (a * d - b * c).abs().sqrt()
    }
}

/// The inherited style.
#[derive(Clone, Debug)]
struct Style {
    fill: Option<[u8; 3]>,
    fill_opacity: f64,
    fill_rule: FillRule,
    stroke: Option<[u8; 3]>,
    stroke_opacity: f64,
    stroke_width: f64,
    cap: Cap,
    join: &'static str,
    miter_limit: f64,
    opacity: f64,
    visible: bool,
}

impl Default for Style {
    fn default() -> Self {
        Style {
            fill: Some([0, 0, 0]),
            fill_opacity: 1.0,
            fill_rule: FillRule::NonZero,
            stroke: None,
            stroke_opacity: 1.0,
            stroke_width: 1.0,
            cap: Cap::Butt,
            join: "miter",
            miter_limit: 4.0,
            opacity: 1.0,
            visible: true,
        }
    }
}

/// Reads `svg`, placing its user units at `scale` image pixels each.
pub(super) fn read(svg: &str, scale: f64) -> Doc {
    let mut doc = Doc::default();
    let mut reader = Reader::from_str(svg);
    // (style, transform, draws) of each open element; `draws` false below defs and the like.
    let mut stack: Vec<(Style, Mat, bool)> = Vec::new();
    let mut points = 0usize;
    let mut elements = 0usize;
    let mut seen_root = false;
    loop {
        let (e, empty) = match reader.read_event() {
            Ok(Event::Start(e)) => (e, false),
            Ok(Event::Empty(e)) => (e, true),
            Ok(Event::End(_)) => {
                stack.pop();
                continue;
            }
            Ok(Event::Eof) => break,
            Ok(_) => continue,
            Err(err) => {
                doc.problem(format!("the SVG is not well-formed XML ({err})"));
                break;
            }
        };
        elements += 1;
        if elements > MAX_ELEMENTS {
            doc.problem(format!(
                "more than {MAX_ELEMENTS} elements: the rest is left out"
            ));
            break;
        }
        let attrs = attributes(&e);
        let name_raw = e.name().as_ref().to_string();
        let (parent_style, parent_mat, parent_draws) = match stack.last() {
            Some(s) => s.clone(),
            None => (Style::default(), Mat::ID, true),
        };
        let mut style = parent_style;
        let mut mat = parent_mat;
        let mut draws = parent_draws;
        let name = name_raw
            .strip_prefix("svg:")
            .unwrap_or(&name_raw)
            .to_string();
        if name.contains(':') {
            draws = false;
        }
        if draws {
            apply_style(&attrs, &mut style, &mut doc);
            if let Some(t) = get(&attrs, "transform") {
                match parse_transform(t) {
                    Some(m) => mat = mat.then_local(&m),
                    None => doc.problem(format!("transform '{t}' not understood: ignored")),
                }
            }
            for a in ["clip-path", "mask", "filter"] {
                if get(&attrs, a).is_some_and(|v| v != "none") {
                    doc.problem(format!("'{a}' is not supported: ignored"));
                }
            }
        }
        if draws && !seen_root && name == "svg" {
            seen_root = true;
            let (w, h, m) = root_size(&attrs, &mut doc);
            doc.width = w;
            doc.height = h;
            mat = Mat([scale, 0.0, 0.0, scale, 0.0, 0.0]).then_local(&m);
        } else if draws {
            match name.as_str() {
                "g" | "svg" | "a" | "switch" => {}
                "defs" | "metadata" | "title" | "desc" | "symbol" | "clipPath" | "mask"
                | "marker" | "linearGradient" | "radialGradient" | "pattern" | "filter" => {
                    draws = false
                }
                "path" | "rect" | "circle" | "ellipse" | "line" | "polyline" | "polygon" => {
                    if style.visible && points < MAX_POINTS {
                        let shape =
                            shape_of(&name, &attrs, &style, &mat, MAX_POINTS - points, &mut doc);
                        if let Some(s) = shape {
                            points += s.subpaths.iter().map(|p| p.0.len()).sum::<usize>();
                            doc.shapes.push(s);
                        }
                        if points >= MAX_POINTS {
                            doc.problem(format!(
                                "more than {MAX_POINTS} outline points: later shapes are left out"
                            ));
                        }
                    }
                }
                other => {
                    doc.problem(format!("<{other}> elements are not drawn"));
                    draws = false;
                }
            }
        }
        if !empty {
            stack.push((style, mat, draws));
        }
    }
    if !seen_root {
        doc.problem("no <svg> element".to_string());
    }
    doc
}

/// An element's attributes, names with their values unescaped.
fn attributes(e: &BytesStart) -> Vec<(String, String)> {
    e.attributes()
        .flatten()
        .map(|a| {
            let k = a.key.as_ref().to_string();
            let raw = a.value.to_string();
            let v = quick_xml::escape::unescape(&raw)
                .map(|c| c.into_owned())
                .unwrap_or(raw);
            (k, v)
        })
        .collect()
}

fn get<'a>(attrs: &'a [(String, String)], key: &str) -> Option<&'a str> {
    attrs.iter().find(|(k, _)| k == key).map(|(_, v)| v.trim())
}

/// The document's width and height (single precision, as SVG Salamander keeps them) and the
/// map from its user units to pixels (its viewBox).
fn root_size(attrs: &[(String, String)], doc: &mut Doc) -> (f64, f64, Mat) {
    let vb: Option<Vec<f64>> = get(attrs, "viewBox").map(numbers);
    let vb = vb.filter(|v| v.len() == 4 && v[2] > 0.0 && v[3] > 0.0);
    let size = |key: &str, k: usize, doc: &mut Doc| match get(attrs, key).and_then(length) {
        Some(v) => v,
        None => match &vb {
            Some(vb) => vb[k],
            None => {
                doc.problem(format!("the <svg> element has no usable {key}: 100 taken"));
                100.0
            }
        },
    };
    let w = f64::from(size("width", 2, doc) as f32);
    let h = f64::from(size("height", 3, doc) as f32);
    let m = match vb {
        // preserveAspectRatio's default, xMidYMid meet: one scale, centred.
        Some(vb) => {
            let s = (w / vb[2]).min(h / vb[3]);
            let (ex, ey) = ((w - vb[2] * s) / 2.0, (h - vb[3] * s) / 2.0);
            Mat([s, 0.0, 0.0, s, ex - vb[0] * s, ey - vb[1] * s])
        }
        None => Mat::ID,
    };
    (w, h, m)
}

/// A length in pixels (CSS units at 96 per inch); `None` for a percentage or garbage.
fn length(v: &str) -> Option<f64> {
    let v = v.trim();
    let end = v
        .find(|c: char| !(c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E')))
        .unwrap_or(v.len());
    let x: f64 = v[..end].parse().ok()?;
    let k = match v[end..].trim() {
        "" | "px" => 1.0,
        "pt" => 4.0 / 3.0,
        "pc" => 16.0,
        "mm" => 96.0 / 25.4,
        "cm" => 96.0 / 2.54,
        "in" => 96.0,
        _ => return None,
    };
    Some(x * k).filter(|v| v.is_finite() && *v > 0.0)
}

/// Every number in `s` (separated by spaces, commas or signs).
fn numbers(s: &str) -> Vec<f64> {
    let mut c = Cursor::new(s);
    let mut out = Vec::new();
    while let Some(x) = c.number() {
        out.push(x);
    }
    out
}

/// The style properties of an element, from its attributes and its `style`.
fn apply_style(attrs: &[(String, String)], st: &mut Style, doc: &mut Doc) {
    let mut props: Vec<(String, String)> = attrs.to_vec();
    if let Some(s) = get(attrs, "style") {
        for decl in s.split(';') {
            if let Some((k, v)) = decl.split_once(':') {
                props.push((k.trim().to_string(), v.trim().to_string()));
            }
        }
    }
    for (k, v) in &props {
        let v = v.trim();
        let num = || v.parse::<f64>().ok().filter(|x| x.is_finite());
        match k.as_str() {
            "fill" => st.fill = paint(v, "fill", doc),
            "stroke" => st.stroke = paint(v, "stroke", doc),
            "fill-opacity" => st.fill_opacity = num().unwrap_or(1.0).clamp(0.0, 1.0),
            "stroke-opacity" => st.stroke_opacity = num().unwrap_or(1.0).clamp(0.0, 1.0),
            "opacity" => st.opacity *= num().unwrap_or(1.0).clamp(0.0, 1.0),
            "stroke-width" => st.stroke_width = length(v).unwrap_or(1.0),
            "fill-rule" => {
                st.fill_rule = if v == "evenodd" {
                    FillRule::EvenOdd
                } else {
                    FillRule::NonZero
                }
            }
            "stroke-linecap" => {
                st.cap = match v {
                    "round" => Cap::Round,
                    "square" => Cap::Square,
                    _ => Cap::Butt,
                }
            }
            "stroke-linejoin" => {
                st.join = match v {
                    "round" => "round",
                    "bevel" => "bevel",
                    _ => "miter",
                }
            }
            "stroke-miterlimit" => st.miter_limit = num().unwrap_or(4.0).max(1.0),
            "display" if v == "none" => st.visible = false,
            "visibility" => st.visible = !(v == "hidden" || v == "collapse"),
            "stroke-dasharray" if v != "none" => {
                doc.problem("dashed strokes are drawn solid".to_string())
            }
            _ => {}
        }
    }
}

/// A paint: `None` for none (and for paints not supported, reported).
fn paint(v: &str, what: &str, doc: &mut Doc) -> Option<[u8; 3]> {
    if v == "none" {
        return None;
    }
    if v.starts_with("url(") {
        doc.problem(format!(
            "gradients and patterns are not supported: such a {what} is not drawn"
        ));
        return None;
    }
    match color(v) {
        Some(c) => Some(c),
        None => {
            doc.problem(format!("colour '{v}' not understood: black taken"));
            Some([0, 0, 0])
        }
    }
}

/// A colour: `#rgb`, `#rrggbb`, `rgb(r, g, b)` (numbers or percentages) or a common name.
fn color(v: &str) -> Option<[u8; 3]> {
    let v = v.trim().to_ascii_lowercase();
    if let Some(hex) = v.strip_prefix('#') {
        let d: Vec<u8> = hex
            .chars()
            .map(|c| c.to_digit(16).map(|x| x as u8))
            .collect::<Option<_>>()?;
        return match d.len() {
            3 => Some([d[0] * 17, d[1] * 17, d[2] * 17]),
            6 => Some([d[0] * 16 + d[1], d[2] * 16 + d[3], d[4] * 16 + d[5]]),
            _ => None,
        };
    }
    if let Some(inner) = v.strip_prefix("rgb(").and_then(|s| s.strip_suffix(')')) {
        let parts: Vec<&str> = inner.split(',').map(str::trim).collect();
        if parts.len() != 3 {
            return None;
        }
        let mut out = [0u8; 3];
        for (o, p) in out.iter_mut().zip(parts) {
            let x = match p.strip_suffix('%') {
                Some(q) => q.trim().parse::<f64>().ok()? * 2.55,
                None => p.parse::<f64>().ok()?,
            };
            *o = x.round().clamp(0.0, 255.0) as u8;
        }
        return Some(out);
    }
    const NAMES: &[(&str, [u8; 3])] = &[
        ("black", [0, 0, 0]),
        ("white", [255, 255, 255]),
        ("red", [255, 0, 0]),
        ("lime", [0, 255, 0]),
        ("green", [0, 128, 0]),
        ("blue", [0, 0, 255]),
        ("yellow", [255, 255, 0]),
        ("cyan", [0, 255, 255]),
        ("aqua", [0, 255, 255]),
        ("magenta", [255, 0, 255]),
        ("fuchsia", [255, 0, 255]),
        ("gray", [128, 128, 128]),
        ("grey", [128, 128, 128]),
        ("silver", [192, 192, 192]),
        ("maroon", [128, 0, 0]),
        ("olive", [128, 128, 0]),
        ("navy", [0, 0, 128]),
        ("purple", [128, 0, 128]),
        ("teal", [0, 128, 128]),
        ("orange", [255, 165, 0]),
        ("brown", [165, 42, 42]),
        ("pink", [255, 192, 203]),
    ];
    NAMES.iter().find(|(n, _)| *n == v).map(|(_, c)| *c)
}

/// A `transform` attribute as one map (the listed maps applied right to left).
fn parse_transform(s: &str) -> Option<Mat> {
    let mut m = Mat::ID;
    let mut rest = s.trim();
    while !rest.is_empty() {
        let open = rest.find('(')?;
        let close = rest.find(')')?;
        let name = rest[..open].trim().trim_start_matches(',').trim();
        let a = numbers(&rest[open + 1..close]);
        let t = match (name, a.len()) {
            ("matrix", 6) => Mat([a[0], a[1], a[2], a[3], a[4], a[5]]),
            ("translate", 1) => Mat([1.0, 0.0, 0.0, 1.0, a[0], 0.0]),
            ("translate", 2) => Mat([1.0, 0.0, 0.0, 1.0, a[0], a[1]]),
            ("scale", 1) => Mat([a[0], 0.0, 0.0, a[0], 0.0, 0.0]),
            ("scale", 2) => Mat([a[0], 0.0, 0.0, a[1], 0.0, 0.0]),
            ("rotate", 1 | 3) => {
                let (s, c) = a[0].to_radians().sin_cos();
                let r = Mat([c, s, -s, c, 0.0, 0.0]);
                if a.len() == 3 {
                    let (cx, cy) = (a[1], a[2]);
                    Mat([1.0, 0.0, 0.0, 1.0, cx, cy])
                        .then_local(&r)
                        .then_local(&Mat([1.0, 0.0, 0.0, 1.0, -cx, -cy]))
                } else {
                    r
                }
            }
            ("skewX", 1) => Mat([1.0, 0.0, a[0].to_radians().tan(), 1.0, 0.0, 0.0]),
            ("skewY", 1) => Mat([1.0, a[0].to_radians().tan(), 0.0, 1.0, 0.0, 0.0]),
            _ => return None,
        };
        m = m.then_local(&t);
        rest = rest[close + 1..].trim_start();
    }
    Some(m)
}

/// A shape element as polygons in image pixels with its paints; `None` when it draws
/// nothing.
fn shape_of(
    name: &str,
    attrs: &[(String, String)],
    st: &Style,
    mat: &Mat,
    budget: usize,
    doc: &mut Doc,
) -> Option<Shape> {
    let num = |k: &str| get(attrs, k).and_then(length).unwrap_or(0.0);
    let coord = |k: &str| {
        get(attrs, k)
            .and_then(|v| v.parse::<f64>().ok())
            .filter(|x| x.is_finite())
            .unwrap_or(0.0)
    };
    let tr = |p: Pt| mat.apply(p);
    let subpaths: Vec<(Vec<Pt>, bool)> = match name {
        "path" => path_data(get(attrs, "d").unwrap_or(""), mat, budget, doc),
        "rect" => {
            let (x, y, w, h) = (coord("x"), coord("y"), num("width"), num("height"));
            if w <= 0.0 || h <= 0.0 {
                return None;
            }
            if num("rx") > 0.0 || num("ry") > 0.0 {
                doc.problem("rounded rectangle corners are drawn square".to_string());
            }
            let pts = [(x, y), (x + w, y), (x + w, y + h), (x, y + h)];
            vec![(pts.iter().map(|&p| tr(p)).collect(), true)]
        }
        "circle" | "ellipse" => {
            let (cx, cy) = (coord("cx"), coord("cy"));
            let (rx, ry) = if name == "circle" {
                (num("r"), num("r"))
            } else {
                (num("rx"), num("ry"))
            };
            if rx <= 0.0 || ry <= 0.0 {
                return None;
            }
            // Enough points for the size in the image.
            let s = mat.scale().max(1e-9);
            let mut pts = ellipse_arc((0.0, 0.0), rx * s, ry * s, 0.0, std::f64::consts::TAU);
            pts.pop();
            let pts = pts
                .into_iter()
                .map(|(x, y)| tr((cx + x / s, cy + y / s)))
                .collect();
            vec![(pts, true)]
        }
        "line" => {
            let a = tr((coord("x1"), coord("y1")));
            let b = tr((coord("x2"), coord("y2")));
            vec![(vec![a, b], false)]
        }
        "polyline" | "polygon" => {
            let v = numbers(get(attrs, "points").unwrap_or(""));
            let pts: Vec<Pt> = v
                .chunks_exact(2)
                .take(budget)
                .map(|c| tr((c[0], c[1])))
                .collect();
            vec![(pts, name == "polygon")]
        }
        _ => return None,
    };
    let fill = match (st.fill, name) {
        (Some(rgb), n) if n != "line" => Some((
            Paint {
                rgb,
                alpha: st.fill_opacity * st.opacity,
            },
            st.fill_rule,
        )),
        _ => None,
    };
    let stroke = st.stroke.map(|rgb| StrokeStyle {
        paint: Paint {
            rgb,
            alpha: st.stroke_opacity * st.opacity,
        },
        width: st.stroke_width * mat.scale(),
        cap: st.cap,
        join: match st.join {
            "round" => Join::Round,
            "bevel" => Join::Bevel,
            _ => Join::Miter(st.miter_limit),
        },
    });
    if subpaths.is_empty() || (fill.is_none() && stroke.is_none()) {
        return None;
    }
    Some(Shape {
        subpaths,
        fill,
        stroke,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn styles_transforms_and_problems() {
        let svg = r##"<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100">
            <defs><rect width="5" height="5"/></defs>
            <g transform="translate(10,0) scale(2)" style="fill:#800080;stroke:#000">
              <rect x="1" y="2" width="3" height="4" stroke-width="0.5"/>
            </g>
            <text>hi</text>
            <circle cx="5" cy="5" r="1" fill="url(#g)"/>
          </svg>"##;
        let doc = read(svg, 2.0);
        assert_eq!((doc.width, doc.height), (200.0, 100.0));
        assert_eq!(doc.shapes.len(), 1);
        let s = &doc.shapes[0];
        // (1, 2) → scale 2 → (2, 4) → translate → (12, 4) → image scale 2 → (24, 8).
        assert_eq!(s.subpaths[0].0[0], (24.0, 8.0));
        assert_eq!(s.fill.unwrap().0.rgb, [128, 0, 128]);
        assert_eq!(s.stroke.unwrap().width, 2.0);
        assert_eq!(doc.problems.len(), 2, "{:?}", doc.problems);
        assert!(doc.problems[0].contains("<text>"));
        // Garbage gives problems, never a panic.
        let doc = read("<svg><path d='M 1 2 L x'/><g><", 1.0);
        assert!(!doc.problems.is_empty());
    }
}
