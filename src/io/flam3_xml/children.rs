//! Reading a flame's children: xforms and the final xform, colours, symmetry; anything else
//! (`<edit>` histories, other programs' elements) is kept verbatim.

use quick_xml::events::Event;

use super::MAX_XFORMS;
use super::context::{Ctx, R};
use super::palette::{PaletteData, read_color, read_colors, read_palette};
use super::xform::read_xform;
use crate::flame::model::{Flame, Xform};
use crate::flame::symmetry::add_symmetry;
use crate::io::xml::{Attr, XmlCursor, scan_attrs};

/// Read the children of a `<flame>` up to its end tag.
pub(super) fn read_flame_children(
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
                let tag = e.name();
                let (start, end) = (p.start, p.end);
                match tag.as_ref() {
                    "xform" | "finalxform" => {
                        let fin = tag.as_ref() == "finalxform";
                        let mut x = new_xform(cx, f, &attrs, fin, start)?;
                        if !is_empty {
                            read_xform_children(cx, cur, text, &mut x)?;
                        }
                        if fin {
                            f.final_xform = Some(x);
                        } else {
                            f.xforms.push(x);
                        }
                    }
                    "color" | "colors" | "symmetry" => {
                        match tag.as_ref() {
                            "color" => read_color(cx, &attrs, start, pal)?,
                            "colors" => read_colors(cx, &attrs, pal)?,
                            _ => read_symmetry(cx, f, &attrs, start)?,
                        }
                        if !is_empty {
                            cur.skip_element()
                                .map_err(|(o, m)| cx.err(o, "XML001", m))?;
                        }
                    }
                    "palette" => read_palette(cx, cur, &attrs, start, is_empty, pal)?,
                    _ => {
                        // <edit> and anything else: kept verbatim.
                        let end = if is_empty {
                            end
                        } else {
                            cur.skip_element()
                                .map_err(|(o, m)| cx.err(o, "XML001", m))?
                        };
                        f.extra_children.push(text[start..end].to_string());
                    }
                }
            }
            _ => {}
        }
    }
}

/// The attributes of an `<xform>` or `<finalxform>` (one final xform, a bounded count).
fn new_xform(cx: &mut Ctx, f: &Flame, attrs: &[Attr], fin: bool, start: usize) -> R<Xform> {
    if fin && f.final_xform.is_some() {
        return Err(cx.err(start, "XML006", "more than one <finalxform>"));
    }
    if f.xforms.len() >= MAX_XFORMS {
        return Err(cx.err(start, "XML003", format!("more than {MAX_XFORMS} xforms")));
    }
    let parity = (f.xforms.len() + f.final_xform.is_some() as usize) % 2;
    read_xform(cx, attrs, fin, parity as f64)
}

/// The children of an xform, kept verbatim up to its end tag.
fn read_xform_children(cx: &Ctx, cur: &mut XmlCursor, text: &str, x: &mut Xform) -> R<()> {
    loop {
        let c = cur.next_event().map_err(|(o, m)| cx.err(o, "XML001", m))?;
        match c.event {
            Event::End(_) => return Ok(()),
            Event::Start(_) => {
                let end = cur
                    .skip_element()
                    .map_err(|(o, m)| cx.err(o, "XML001", m))?;
                x.extra_children.push(text[c.start..end].to_string());
            }
            Event::Empty(_) => x.extra_children.push(text[c.start..c.end].to_string()),
            Event::Eof => {
                return Err(cx.err(c.start, "XML001", "end of file inside <xform>"));
            }
            _ => {}
        }
    }
}

/// `<symmetry kind="k"/>`: flam3's symmetry xforms added to the flame.
fn read_symmetry(cx: &mut Ctx, f: &mut Flame, attrs: &[Attr], start: usize) -> R<()> {
    let Some(k) = attrs.iter().find(|a| a.name == "kind") else {
        return Err(cx.err(start, "XML003", "<symmetry> needs a 'kind' attribute"));
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
    Ok(())
}
