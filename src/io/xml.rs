//! Small helpers over quick-xml: events with byte positions and attribute scanning that keeps
//! the position of every value, so errors can name line and column.

use std::borrow::Cow;

use quick_xml::Reader;
use quick_xml::events::Event;

/// One attribute of a start tag.
#[derive(Clone, Debug, PartialEq)]
pub struct Attr<'a> {
    pub name: &'a str,
    /// Unescaped value.
    pub value: Cow<'a, str>,
    /// Byte offset of the value's first character in the source.
    pub offset: usize,
}

/// Scan the attributes of a tag. `content` is the text between `<` and `>` (or `/>`), which
/// starts at byte `base` of the source. Errors carry the byte offset and a message.
pub fn scan_attrs(content: &str, base: usize) -> Result<Vec<Attr<'_>>, (usize, String)> {
    scan(content, base, None)
}

/// [`scan_attrs`] as JWildfire's own reader takes a tag, for flame files: a name may hold
/// JWildfire's index of a variation used twice (`log#1#`), and a name without a value is
/// read together with the words after it up to the next `=`, as JWildfire's reader does (it
/// wrote parameter names with spaces, `glsl_apollonian_Density Pixels="…"`), or dropped at
/// the end of the tag.
/// Each such reading adds a note (byte offset, what was read) to `notes`.
pub fn scan_attrs_jwf<'a>(
    content: &'a str,
    base: usize,
    notes: &mut Vec<(usize, String)>,
) -> Result<Vec<Attr<'a>>, (usize, String)> {
    scan(content, base, Some(notes))
}

/// A name's end: the first `=`, blank or `/` from `i`; with `slash_inside`, a `/` that is not
/// the tag's closing one (only blanks after it) belongs to the name (JWildfire writes
/// parameter names such as `hamid_js_number_lines/circles` and `dc_booleans_^/&/|`).
fn name_end(b: &[u8], mut i: usize, slash_inside: bool) -> usize {
    let inside = |i: usize| slash_inside && b[i + 1..].iter().any(|c| !c.is_ascii_whitespace());
    while i < b.len() && b[i] != b'=' && !b[i].is_ascii_whitespace() && (b[i] != b'/' || inside(i))
    {
        i += 1;
    }
    i
}

fn skip_blanks(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && b[i].is_ascii_whitespace() {
        i += 1;
    }
    i
}

fn scan<'a>(
    content: &'a str,
    base: usize,
    mut notes: Option<&mut Vec<(usize, String)>>,
) -> Result<Vec<Attr<'a>>, (usize, String)> {
    let b = content.as_bytes();
    let mut i = 0;
    // Element name.
    while i < b.len() && !b[i].is_ascii_whitespace() && b[i] != b'/' {
        i += 1;
    }
    let mut out = Vec::new();
    let mut seen: std::collections::HashSet<&str> = std::collections::HashSet::new();
    loop {
        i = skip_blanks(b, i);
        if i >= b.len() || b[i] == b'/' {
            break;
        }
        let ns = i;
        i = name_end(b, i, notes.is_some());
        let first = &content[ns..i];
        let valid = if notes.is_some() {
            is_jwf_name
        } else {
            is_xml_name
        };
        if !valid(first)
            && let Some(notes) = notes.as_deref_mut()
            && !first.is_empty()
            && !first.contains(['"', '\'', '<', '>'])
        {
            // JWildfire's reader takes a name as all that stands before `="` (`Tools.
            // parseAttributes`); older JWildfire versions wrote names such as
            // `dc_booleans_^/&/|`. Kept as they stand, and written back so.
            notes.push((
                base + ns,
                format!("attribute name '{first}' is not XML; read as JWildfire reads it"),
            ));
        } else if !valid(first) {
            return Err((
                base + ns,
                format!("'{first}' is not an attribute name (letters, digits, '_', '-', '.', ':')"),
            ));
        }
        i = skip_blanks(b, i);
        if i >= b.len() || b[i] != b'=' {
            let Some(notes) = notes.as_deref_mut() else {
                return Err((base + ns, format!("attribute '{first}' has no value")));
            };
            // JWildfire's reader: the name runs on to the next `=`.
            let mut end = ns + first.len();
            while i < b.len() && b[i] != b'=' && b[i] != b'/' {
                end = name_end(b, i, true);
                i = skip_blanks(b, end);
            }
            let name = &content[ns..end];
            if i >= b.len() || b[i] != b'=' {
                notes.push((
                    base + ns,
                    format!("attribute '{name}' has no value; ignored"),
                ));
                continue;
            }
            // JWildfire's parameter names hold spaces, brackets, signs (`Size (N PowersOf 2)`,
            // `Pan -Re`); what could not be written back is refused.
            if let Some(c) = name
                .chars()
                .find(|c| matches!(c, '"' | '\'' | '<' | '>' | '&'))
            {
                return Err((base + ns, format!("'{c}' in the attribute name '{name}'")));
            }
            notes.push((
                base + ns,
                format!(
                    "attribute '{first}' has no value; read with what follows as '{name}', as \
                     JWildfire reads it"
                ),
            ));
        }
        let name = content[ns..i].trim_end();
        i += 1;
        i = skip_blanks(b, i);
        if i >= b.len() || (b[i] != b'"' && b[i] != b'\'') {
            return Err((
                base + i,
                format!("value of attribute '{name}' must be quoted"),
            ));
        }
        let q = b[i];
        i += 1;
        let vs = i;
        while i < b.len() && b[i] != q {
            i += 1;
        }
        if i >= b.len() {
            return Err((
                base + vs,
                format!("value of attribute '{name}' is not closed"),
            ));
        }
        let raw = &content[vs..i];
        i += 1;
        let value = quick_xml::escape::unescape(raw)
            .map_err(|e| (base + vs, format!("attribute '{name}': {e}")))?;
        // Duplicate check in linear time overall: a scan while the tag is small, a hash
        // set once it is not (files from other programs carry thousands of attributes).
        let dup = if out.len() < 16 {
            out.iter().any(|a: &Attr| a.name == name)
        } else {
            if seen.is_empty() {
                seen.extend(out.iter().map(|a: &Attr| a.name));
            }
            !seen.insert(name)
        };
        if dup {
            return Err((base + ns, format!("attribute '{name}' appears twice")));
        }
        out.push(Attr {
            name,
            value,
            offset: base + vs,
        });
    }
    Ok(out)
}

/// A name of JWildfire's files: an XML name, after removing JWildfire's index `#k#` of a
/// variation used more than once in an xform (`log#1#`, `log#1#_base`).
fn is_jwf_name(name: &str) -> bool {
    // JWildfire's parameter names may hold '/', '(' and ')' (`hamid_js_number_lines/circles`,
    // `glynns3subfl_show/hide(1/0)`): inside a name they count as name characters.
    let plain = |n: &str| is_xml_name(&n.replace(['/', '(', ')'], "_"));
    match split_jwf_index(name) {
        Some((base, _)) => plain(&base),
        None => plain(name),
    }
}

/// JWildfire's index of a repeated variation in an attribute name: `log#1#_base` →
/// (`log_base`, 1). None without a `#digits#` group (or with `#0#`, which JWildfire never
/// writes).
pub fn split_jwf_index(name: &str) -> Option<(String, u32)> {
    let s = name.find('#')?;
    let e = s + 1 + name[s + 1..].find('#')?;
    let k: u32 = name[s + 1..e]
        .bytes()
        .all(|c| c.is_ascii_digit())
        .then(|| name[s + 1..e].parse().ok())
        .flatten()?;
    (k > 0).then(|| (format!("{}{}", &name[..s], &name[e + 1..]), k))
}

/// An XML name: a letter, '_' or ':' (or any non-ASCII character), then those, digits, '-' and
/// '.'. Anything else (a quote, '<', '&' …) could not be written back as a name.
fn is_xml_name(name: &str) -> bool {
    let mut chars = name.chars();
    let start = |c: char| c.is_ascii_alphabetic() || c == '_' || c == ':' || !c.is_ascii();
    chars.next().is_some_and(start)
        && chars.all(|c| start(c) || c.is_ascii_digit() || c == '-' || c == '.')
}

/// An XML event with the byte range it occupies in the source.
pub struct Positioned<'a> {
    pub event: Event<'a>,
    pub start: usize,
    pub end: usize,
}

/// A quick-xml reader over a string that reports byte positions.
pub struct XmlCursor<'a> {
    reader: Reader<&'a [u8]>,
}

impl<'a> XmlCursor<'a> {
    pub fn new(text: &'a str) -> Self {
        let mut reader = Reader::from_str(text);
        let c = reader.config_mut();
        c.trim_text(false);
        c.check_end_names = true;
        c.expand_empty_elements = false;
        XmlCursor { reader }
    }

    /// The next event, or an error with its byte offset.
    pub fn next_event(&mut self) -> Result<Positioned<'a>, (usize, String)> {
        let start = self.reader.buffer_position() as usize;
        match self.reader.read_event() {
            Ok(event) => Ok(Positioned {
                event,
                start,
                end: self.reader.buffer_position() as usize,
            }),
            Err(e) => Err((self.reader.error_position() as usize, e.to_string())),
        }
    }

    /// Skip to the end of the element whose start tag was just read; returns the end offset.
    pub fn skip_element(&mut self) -> Result<usize, (usize, String)> {
        let mut depth = 1usize;
        loop {
            let p = self.next_event()?;
            match p.event {
                Event::Start(_) => depth += 1,
                Event::End(_) => {
                    depth -= 1;
                    if depth == 0 {
                        return Ok(p.end);
                    }
                }
                Event::Eof => {
                    return Err((p.start, "unexpected end of file inside an element".into()));
                }
                _ => {}
            }
        }
    }
}

/// Escape text for an attribute value.
pub fn escape_attr(s: &str) -> Cow<'_, str> {
    if !s.contains(['&', '<', '>', '"', '\'']) {
        return Cow::Borrowed(s);
    }
    let mut o = String::with_capacity(s.len() + 8);
    for ch in s.chars() {
        match ch {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&apos;"),
            c => o.push(c),
        }
    }
    Cow::Owned(o)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn attrs_with_positions() {
        let src = r#"<xform weight="0.5" name='a &amp; b' coefs = "1 0 0 1 0 0"/>"#;
        let content = &src[1..src.len() - 2];
        let a = scan_attrs(content, 1).unwrap();
        assert_eq!(a.len(), 3);
        assert_eq!(a[0].name, "weight");
        assert_eq!(a[0].value, "0.5");
        assert_eq!(&src[a[0].offset..a[0].offset + 3], "0.5");
        assert_eq!(a[1].value, "a & b");
        assert_eq!(a[2].value, "1 0 0 1 0 0");
        assert!(scan_attrs("x a=1", 0).is_err());
        assert!(scan_attrs("x a", 0).is_err());
        assert!(scan_attrs("x a=\"1", 0).is_err());
        assert!(scan_attrs("x a=\"1\" a=\"2\"", 0).is_err());
        // Many attributes: duplicates are still found, far apart too.
        let many: String = (0..1000).map(|k| format!(" a{k}=\"{k}\"")).collect();
        assert_eq!(scan_attrs(&format!("x{many}"), 0).unwrap().len(), 1000);
        let e = scan_attrs(&format!("x{many} a3=\"again\""), 0).unwrap_err();
        assert!(e.1.contains("'a3' appears twice"), "{}", e.1);
    }

    /// A name that could not be written back (a quote in it, a digit first, none at all) is an
    /// error where it starts.
    #[test]
    fn attribute_names_are_xml_names() {
        let ok = scan_attrs(r#"x a-b.c_d:e="1" _x="2" é="3""#, 0).unwrap();
        assert_eq!(ok.len(), 3);
        for (src, at) in [
            (r#"x xyCo"ff="1""#, 2),
            (r#"x 1a="1""#, 2),
            (r#"x ="1""#, 2),
            (r#"x a="1" b<c="2""#, 8),
        ] {
            let (pos, msg) = scan_attrs(src, 0).unwrap_err();
            assert_eq!(pos, at, "{src}: {msg}");
            assert!(msg.contains("not an attribute name"), "{src}: {msg}");
        }
    }

    /// JWildfire's files: an index in a name (`log#1#`), names written with spaces (read
    /// whole, as JWildfire reads them), a name without a value at the end (dropped); each
    /// reported. The strict scanner refuses them all.
    #[test]
    fn jwildfire_names() {
        let src = r#"xform log#1#="0.5" log#1#_base="2" a_Density Pixels="800" b_Size (N PowersOf 2)="4" lone"#;
        let mut notes = Vec::new();
        let a = scan_attrs_jwf(src, 0, &mut notes).unwrap();
        let names: Vec<&str> = a.iter().map(|a| a.name).collect();
        assert_eq!(
            names,
            [
                "log#1#",
                "log#1#_base",
                "a_Density Pixels",
                "b_Size (N PowersOf 2)"
            ]
        );
        assert_eq!(a[2].value, "800");
        assert_eq!(notes.len(), 3, "{notes:?}");
        assert_eq!(notes[0].0, src.find("a_Density").unwrap());
        assert!(
            notes[2].1.contains("'lone' has no value; ignored"),
            "{notes:?}"
        );
        assert!(scan_attrs(src, 0).is_err());
        assert!(scan_attrs_jwf(r#"x a b"c="1""#, 0, &mut notes).is_err());
        assert!(scan_attrs_jwf(r#"x log#1#="1" log#1#="2""#, 0, &mut notes).is_err());
        assert_eq!(split_jwf_index("log#1#_base"), Some(("log_base".into(), 1)));
        assert_eq!(split_jwf_index("log#12#"), Some(("log".into(), 12)));
        for no in ["log", "log#0#", "log#x#", "log#1", "log##"] {
            assert_eq!(split_jwf_index(no), None, "{no}");
        }
    }

    #[test]
    fn escaping() {
        assert_eq!(escape_attr("plain"), "plain");
        assert_eq!(escape_attr("a<\"b\"&"), "a&lt;&quot;b&quot;&amp;");
    }
}
