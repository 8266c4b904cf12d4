//! JWildfire's `<layer>` elements (inside its `<jwf-flame>` root): the first layer's xforms,
//! final xforms and palette are the flame's own, the others become
//! [`crate::flame::layers::Layer`]s; each layer's `weight`, `density`, `visible` and `name`
//! are read, its other attributes kept. A flame with layers is written back as JWildfire
//! writes it: a `<jwf-flame>` of `<layer>` elements, which JWildfire reads.

use std::fmt::Write as _;

use super::children::read_flame_children;
use super::context::{Ctx, R};
use super::palette::PaletteData;
use crate::flame::layers::{Layer, LayerSettings};
use crate::flame::model::Flame;
use crate::io::diag::fmt_num;
use crate::io::xml::{Attr, XmlCursor, escape_attr};

/// Most layers of one flame.
pub const MAX_LAYERS: usize = 1000;

/// A `<layer>` element whose attributes are `attrs`: the first (`first`) fills the flame, the
/// others are added to its further layers.
#[allow(clippy::too_many_arguments)]
pub(super) fn read_layer(
    cx: &mut Ctx,
    cur: &mut XmlCursor,
    text: &str,
    f: &mut Flame,
    pal: &mut PaletteData,
    attrs: &[Attr],
    start: usize,
    is_empty: bool,
    first: bool,
) -> R<()> {
    let settings = layer_settings(cx, attrs)?;
    if first {
        f.layer = settings;
        if !is_empty {
            read_flame_children(cx, cur, text, f, pal)?;
        }
        return Ok(());
    }
    if f.more_layers.len() + 1 >= MAX_LAYERS {
        return Err(cx.err(start, "XML003", format!("more than {MAX_LAYERS} layers")));
    }
    let mut lf = Flame::default();
    let mut lpal = PaletteData::new();
    if !is_empty {
        read_flame_children(cx, cur, text, &mut lf, &mut lpal)?;
    }
    if !lf.more_layers.is_empty() {
        cx.warn(start, "XML025", "layers inside a <layer> are ignored");
    }
    let palette = if lpal.any() {
        lpal.gradient(String::new())
    } else {
        cx.warn(
            start,
            "XML018",
            "layer has no colour data; using the default gradient",
        );
        cx.opts.default_gradient.clone()
    };
    // What else the layer held is kept with the flame.
    f.extra_children.append(&mut lf.extra_children);
    let finals = lf.final_xform.into_iter().chain(lf.more_finals).collect();
    f.more_layers.push(Layer {
        settings,
        xforms: lf.xforms,
        finals,
        palette,
    });
    Ok(())
}

/// A `<layer>`'s attributes.
fn layer_settings(cx: &mut Ctx, attrs: &[Attr]) -> R<LayerSettings> {
    let mut s = LayerSettings::default();
    for a in attrs {
        match a.name {
            "weight" => s.weight = cx.num(a)?,
            "density" => s.density = cx.num(a)?,
            "visible" => s.visible = cx.int(a)? == 1,
            "name" => s.name = a.value.to_string(),
            other => s.extra_attrs.push((other.to_string(), a.value.to_string())),
        }
    }
    Ok(s)
}

/// A `<layer>` start tag of `s`.
fn layer_tag(out: &mut String, s: &LayerSettings, ind: &str) {
    let n = fmt_num;
    let _ = write!(
        out,
        "{ind}<layer weight=\"{}\" density=\"{}\" visible=\"{}\"",
        n(s.weight),
        n(s.density),
        s.visible as u8
    );
    if !s.name.is_empty() {
        let _ = write!(out, " name=\"{}\"", escape_attr(&s.name));
    }
    for (k, v) in &s.extra_attrs {
        let _ = write!(out, " {k}=\"{}\"", escape_attr(v));
    }
    out.push_str(">\n");
}

/// The layers of a flame that has them: the first layer (written by `first`, into the string
/// and with the indentation given) and the others, each a `<layer>` element.
pub(super) fn write_layers(
    out: &mut String,
    f: &Flame,
    ind: &str,
    first: impl FnOnce(&mut String, &str),
    mut layer: impl FnMut(&mut String, &Layer, &str),
) {
    let inner = format!("{ind}   ");
    layer_tag(out, &f.layer, ind);
    first(out, &inner);
    let _ = writeln!(out, "{ind}</layer>");
    for l in &f.more_layers {
        layer_tag(out, &l.settings, ind);
        layer(out, l, &inner);
        let _ = writeln!(out, "{ind}</layer>");
    }
}
