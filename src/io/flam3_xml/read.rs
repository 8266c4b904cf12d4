//! Reading a document: the root, every `<flame>` at any depth, the `.fla` rules on names.

use std::collections::HashMap;

use quick_xml::events::{BytesStart, Event};

use super::context::{Ctx, R};
use super::flame::read_flame;
use super::{FLA_FORMAT, FlameFile, MAX_FLAMES, ReadOptions};
use crate::flame::model::Flame;
use crate::io::diag::{Diagnostic, Parsed, Pos};
use crate::io::xml::{Attr, XmlCursor};

/// Read every flame of a flam3/Apophysis/ugnis XML document.
pub fn read(text: &str, opts: &ReadOptions) -> R<Parsed<FlameFile>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut cx = Ctx::new(text, opts);
    let mut cur = XmlCursor::new(text);
    let mut out = FlameFile::default();
    let mut root_seen = false;
    // Names of the flames so far with their offsets (for the `.fla` rule of unique names).
    let mut names: HashMap<String, usize> = HashMap::new();
    loop {
        let p = cur.next_event().map_err(|(o, m)| cx.err(o, "XML001", m))?;
        match &p.event {
            Event::Eof => break,
            Event::Start(e) | Event::Empty(e) => {
                let is_empty = matches!(p.event, Event::Empty(_));
                let tag = e.name().as_ref().to_string();
                if !root_seen {
                    root_seen = true;
                    read_root(&mut cx, e, &tag, p.start, &mut out)?;
                }
                // flam3's <flame>, or JWildfire's <jwf-flame> (a flame of <layer> elements).
                if tag == "flame" || tag == "jwf-flame" {
                    if out.flames.len() >= MAX_FLAMES {
                        return Err(cx.err(
                            p.start,
                            "XML003",
                            format!("more than {MAX_FLAMES} flames in one file"),
                        ));
                    }
                    let mut flame = read_flame(&mut cx, &mut cur, text, e, p.start, is_empty)?;
                    super::subflame::fill(&mut flame, opts);
                    if opts.fla {
                        check_fla_name(&cx, &flame, p.start, &mut names)?;
                    }
                    out.flames.push(flame);
                }
            }
            _ => {}
        }
    }
    if out.flames.is_empty() {
        return Err(Diagnostic::error(
            &opts.file,
            Pos::File,
            "XML002",
            "no <flame> or <jwf-flame> element in the document",
        ));
    }
    Ok(Parsed {
        value: out,
        warnings: cx.finish(),
    })
}

/// The document's first element: a `<flames>` root gives the file's name and format revision;
/// a `.fla` file must have one.
fn read_root(cx: &mut Ctx, e: &BytesStart, tag: &str, start: usize, out: &mut FlameFile) -> R<()> {
    if tag == "flames" {
        let attrs = cx.attrs(e, start + 1)?;
        root_attrs(cx, &attrs, out)
    } else if cx.opts.fla {
        Err(cx.err(
            start,
            "FLA001",
            format!("a .fla file must have a <flames> root, not <{}>", tag),
        ))
    } else {
        Ok(())
    }
}

/// A `.fla` file's flames have non-empty names, each used once.
fn check_fla_name(
    cx: &Ctx,
    flame: &Flame,
    start: usize,
    names: &mut HashMap<String, usize>,
) -> R<()> {
    if flame.name.is_empty() {
        return Err(cx.err(
            start,
            "FLA002",
            "every flame in a .fla file needs a non-empty name",
        ));
    }
    if let Some(first) = names.get(&flame.name) {
        let Pos::LineCol(l, c) = cx.map.pos(*first) else {
            unreachable!()
        };
        return Err(cx.err(
            start,
            "FLA002",
            format!(
                "duplicate flame name '{}' (first used at {l}:{c})",
                flame.name
            ),
        ));
    }
    names.insert(flame.name.clone(), start);
    Ok(())
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
