//! Reading a flame's colours: `<color>` entries, Apophysis' `<colors>`, `<palette>` blocks
//! (of any count, RGB or RGBA, or the old library form), and settling them into the flame's
//! gradient (inline colours, else flam3's library palette, else the default gradient).

use quick_xml::events::Event;

use super::MAX_PALETTE;
use super::context::{Ctx, R};
use crate::flame::model::Flame;
use crate::gradient::{Gradient, hue_rotate, resample_colors};
use crate::io::palettes::decode_hex_colors;
use crate::io::xml::{Attr, XmlCursor};

/// Raw palette data collected while reading a flame.
pub(super) struct PaletteData {
    colors: Vec<Option<[f64; 4]>>,
    any: bool,
    /// A `<palette>` of more than 256 colours.
    hires: Option<Vec<[f64; 4]>>,
}

impl PaletteData {
    /// No colours yet: 256 undefined entries.
    pub(super) fn new() -> Self {
        PaletteData {
            colors: vec![None; 256],
            any: false,
            hires: None,
        }
    }

    /// Whether any colour was read.
    pub(super) fn any(&self) -> bool {
        self.any
    }

    /// The 256-entry gradient of the colours read (missing entries interpolated, more than
    /// 256 resampled).
    pub(super) fn gradient(&self, name: String) -> Gradient {
        Gradient {
            name,
            colors: match &self.hires {
                Some(h) => resample_colors(h, 256),
                None => interpolate_missing(&self.colors),
            },
            stops: Vec::new(),
            map_entries: None,
        }
    }
}

/// The flame's gradient from what was read: inline colours win over a library palette (flam3
/// does the opposite; warn); without either, the default gradient (warn).
pub(super) fn resolve_palette(
    cx: &mut Ctx,
    f: &mut Flame,
    mut pal: PaletteData,
    gradient_name: String,
    library_palette: Option<(usize, usize)>,
    hue: f64,
    start: usize,
) -> R<()> {
    if pal.any {
        if library_palette.is_some() {
            cx.warn(
                start,
                "XML017",
                "flame has both inline colours and palette=\"N\"; using the inline colours",
            );
        }
        f.palette = pal.gradient(gradient_name);
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
    Ok(())
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

/// Apophysis' `<colors count="N" data="…">`: 8 hex digits per colour (the first pair unused).
pub(super) fn read_colors(cx: &mut Ctx, attrs: &[Attr], pal: &mut PaletteData) -> R<()> {
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
                    format!("colors count {n} but data holds {} colours", cols.len()),
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
    Ok(())
}

/// One `<color index="i" rgb="r g b"/>` (or `rgba`, or `a`), components 0–255.
pub(super) fn read_color(
    cx: &mut Ctx,
    attrs: &[Attr],
    start: usize,
    pal: &mut PaletteData,
) -> R<()> {
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

/// A `<palette>` element: hex colours (`count`, `format` RGB or RGBA), or the old library form
/// (`index0`, `hue0`, …).
pub(super) fn read_palette(
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
    let (content, content_off) = if is_empty {
        (String::new(), start)
    } else {
        palette_text(cx, cur, start)?
    };
    if legacy {
        return read_library_palette(cx, attrs, start, pal);
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
    let rgba = hex_palette(cx, &content, content_off, count, dpc)?;
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

/// The text content of a `<palette>` (child elements skipped) and the offset where it starts.
fn palette_text(cx: &Ctx, cur: &mut XmlCursor, start: usize) -> R<(String, usize)> {
    let mut content = String::new();
    let mut content_off = start;
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
    Ok((content, content_off))
}

/// `count` colours of `dpc` hex digits each (6: RGB, 8: RGBA), as fractions. Data that is not
/// whole colours between whitespace is read as flam3 reads it (see [`flam3_hex_colors`]),
/// with a warning: flam3 3.1 writes bytes below 0x10 padded with a space.
fn hex_palette(
    cx: &mut Ctx,
    content: &str,
    content_off: usize,
    count: usize,
    dpc: usize,
) -> R<Vec<[f64; 4]>> {
    let whole = content
        .split_whitespace()
        .all(|tok| tok.len().is_multiple_of(dpc) && tok.bytes().all(|c| c.is_ascii_hexdigit()));
    let cols = if whole {
        decode_hex_colors(content, dpc).unwrap_or_default()
    } else {
        let cols = flam3_hex_colors(content, count, dpc / 2).map_err(|at| {
            cx.err(
                content_off + at,
                "XML010",
                format!(
                    "palette data must be {count} hex colours of {dpc} digits (whitespace between \
                     colours, or flam3's bytes padded with a space)"
                ),
            )
        })?;
        // At the first word that is not whole colours.
        let at = content
            .split(|c: char| c.is_ascii_whitespace())
            .scan(0, |pos, w| {
                let here = *pos;
                *pos += w.len() + 1;
                Some((here, w))
            })
            .find(|(_, w)| !w.is_empty() && !w.len().is_multiple_of(dpc))
            .map_or(0, |(o, _)| o);
        cx.warn(
            content_off + at,
            "XML023",
            "palette bytes below 0x10 are padded with a space instead of a 0 (as flam3 3.1 \
             writes them); read as flam3 reads them",
        );
        cols
    };
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
    Ok(cols
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
        .collect())
}

/// C's `isspace`: what flam3's reader skips.
fn c_space(c: u8) -> bool {
    matches!(c, b' ' | b'\t' | b'\n' | 0x0b | 0x0c | b'\r')
}

/// `count` colours of `nbytes` bytes each, read as flam3's hex palette reader does: each byte
/// is a C `%2x` field (blanks skipped before it, then one or two hex digits), each colour
/// starts 2·`nbytes` characters after the previous one, and blanks between colours are
/// skipped. Data written with `%2x` (a space before a single digit) is read without error, a
/// colour whose first byte is padded shifts the ones after it by a character as it does in
/// flam3. Err: the byte offset where a byte or the end of the data was expected.
fn flam3_hex_colors(content: &str, count: usize, nbytes: usize) -> Result<Vec<[u8; 4]>, usize> {
    let b = content.as_bytes();
    let skip = |mut i: usize| {
        while i < b.len() && c_space(b[i]) {
            i += 1;
        }
        i
    };
    let mut out = Vec::with_capacity(count.min(b.len() / 2 + 1));
    let mut at = skip(0);
    for _ in 0..count {
        let mut c = [0u8, 0, 0, 255];
        let mut j = at;
        for v in c.iter_mut().take(nbytes) {
            j = skip(j);
            let s = j;
            while j < b.len() && j - s < 2 && b[j].is_ascii_hexdigit() {
                j += 1;
            }
            *v = u8::from_str_radix(content.get(s..j).ok_or(s)?, 16).map_err(|_| s)?;
        }
        out.push(c);
        at = skip((at + 2 * nbytes).min(b.len()));
    }
    if at < b.len() {
        return Err(at);
    }
    Ok(out)
}

/// The old `<palette index0=… hue0=…>`: a library palette, hue-rotated (the other attributes
/// of that form are not honoured; warn).
fn read_library_palette(
    cx: &mut Ctx,
    attrs: &[Attr],
    start: usize,
    pal: &mut PaletteData,
) -> R<()> {
    let get = |n: &str| attrs.iter().find(|a| a.name == n);
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
    Ok(())
}
