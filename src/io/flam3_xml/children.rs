//! Reading a flame's children: xforms (with their `<motion>` elements) and the final xforms,
//! colours, symmetry, ugnis' keyframes, JWildfire's layers; anything else (`<edit>` histories, other programs'
//! elements) is kept verbatim.

use quick_xml::events::Event;

use super::MAX_XFORMS;
use super::anim::{keys_curve, keys_key, keys_timeline, motion_from};
use super::context::{Ctx, R};
use super::palette::{PaletteData, read_color, read_colors, read_palette};
use super::xform::{read_motion_attrs, read_xform};
use crate::flame::model::{Flame, Xform};
use crate::flame::symmetry::add_symmetry;
use crate::io::xml::{Attr, XmlCursor};

/// Read the children of a `<flame>` up to its end tag.
pub(super) fn read_flame_children(
    cx: &mut Ctx,
    cur: &mut XmlCursor,
    text: &str,
    f: &mut Flame,
    pal: &mut PaletteData,
) -> R<()> {
    let mut layers = 0;
    loop {
        let p = cur.next_event().map_err(|(o, m)| cx.err(o, "XML001", m))?;
        match &p.event {
            Event::End(_) => return Ok(()),
            Event::Eof => return Err(cx.err(p.start, "XML001", "end of file inside <flame>")),
            Event::Start(e) | Event::Empty(e) => {
                let is_empty = matches!(p.event, Event::Empty(_));
                let attrs = cx.attrs(e, p.start + 1)?;
                let tag = e.name();
                let (start, end) = (p.start, p.end);
                match tag.as_ref() {
                    "xform" | "finalxform" => {
                        let fin = tag.as_ref() == "finalxform";
                        let mut x = new_xform(cx, f, &attrs, fin, start)?;
                        if !is_empty {
                            read_xform_children(cx, cur, text, &mut x)?;
                        }
                        if fin && f.final_xform.is_some() {
                            // JWildfire's several final xforms, applied in order.
                            f.more_finals.push(x);
                        } else if fin {
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
                    "layer" => {
                        let first = layers == 0;
                        layers += 1;
                        super::layers::read_layer(
                            cx, cur, text, f, pal, &attrs, start, is_empty, first,
                        )?;
                    }
                    "ugnis_keys" => {
                        keys_timeline(cx, &attrs, &mut f.keys)?;
                        if !is_empty {
                            read_keys(cx, cur, f)?;
                        }
                    }
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

/// The attributes of an `<xform>` or `<finalxform>` (a bounded count of them).
fn new_xform(cx: &mut Ctx, f: &Flame, attrs: &[Attr], fin: bool, start: usize) -> R<Xform> {
    let finals = f.final_xform.is_some() as usize + f.more_finals.len();
    if f.xforms.len() + finals >= MAX_XFORMS {
        return Err(cx.err(start, "XML003", format!("more than {MAX_XFORMS} xforms")));
    }
    let parity = (f.xforms.len() + finals) % 2;
    read_xform(cx, attrs, fin, parity as f64)
}

/// The children of an xform up to its end tag: `<motion>` elements read, others kept verbatim.
fn read_xform_children(cx: &mut Ctx, cur: &mut XmlCursor, text: &str, x: &mut Xform) -> R<()> {
    loop {
        let c = cur.next_event().map_err(|(o, m)| cx.err(o, "XML001", m))?;
        match &c.event {
            Event::End(_) => return Ok(()),
            Event::Start(e) | Event::Empty(e) => {
                let is_empty = matches!(c.event, Event::Empty(_));
                let end = if is_empty {
                    c.end
                } else {
                    cur.skip_element()
                        .map_err(|(o, m)| cx.err(o, "XML001", m))?
                };
                if e.name().as_ref() == "motion" {
                    if x.motion.len() >= MAX_MOTIONS {
                        return Err(cx.err(
                            c.start,
                            "XML003",
                            format!("more than {MAX_MOTIONS} <motion> elements in one xform"),
                        ));
                    }
                    let attrs = cx.attrs(e, c.start + 1)?;
                    let delta = read_motion_attrs(cx, &attrs)?;
                    x.motion.push(motion_from(cx, &attrs, delta, c.start)?);
                } else {
                    x.extra_children.push(text[c.start..end].to_string());
                }
            }
            Event::Eof => {
                return Err(cx.err(c.start, "XML001", "end of file inside <xform>"));
            }
            _ => {}
        }
    }
}

/// Most `<motion>` elements of one xform.
const MAX_MOTIONS: usize = 1000;

/// The `<curve>` elements of `<ugnis_keys>`, with their `<key>` elements.
fn read_keys(cx: &mut Ctx, cur: &mut XmlCursor, f: &mut Flame) -> R<()> {
    // The curve being read (None inside a skipped curve), and the depth of elements.
    let mut curve: Option<Option<crate::flame::keyframes::Curve>> = None;
    loop {
        let c = cur.next_event().map_err(|(o, m)| cx.err(o, "XML001", m))?;
        match &c.event {
            Event::End(_) => match curve.take() {
                Some(done) => f.keys.curves.extend(done),
                None => return Ok(()),
            },
            Event::Start(e) | Event::Empty(e) => {
                let is_empty = matches!(c.event, Event::Empty(_));
                let attrs = cx.attrs(e, c.start + 1)?;
                match (e.name().as_ref(), &mut curve) {
                    ("curve", None) => {
                        let made = keys_curve(cx, &attrs, c.start, &f.keys)?;
                        if is_empty {
                            f.keys.curves.extend(made);
                        } else {
                            curve = Some(made);
                        }
                    }
                    ("key", Some(cv)) => {
                        if let Some(cv) = cv {
                            keys_key(cx, &attrs, c.start, cv)?;
                        }
                        if !is_empty {
                            cur.skip_element()
                                .map_err(|(o, m)| cx.err(o, "XML001", m))?;
                        }
                    }
                    _ => {
                        cx.ignore(e.name().as_ref());
                        if !is_empty {
                            cur.skip_element()
                                .map_err(|(o, m)| cx.err(o, "XML001", m))?;
                        }
                    }
                }
            }
            Event::Eof => return Err(cx.err(c.start, "XML001", "end of file inside <ugnis_keys>")),
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
