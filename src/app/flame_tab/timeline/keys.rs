//! Key edits as undo steps (add, delete, move, interpolation, easing, handles, the timeline's
//! length, rate and wrap), and the parameters of a flame a curve can drive, named for people.

use super::super::document::Document;
use crate::flame::Flame;
use crate::flame::keyframes::{
    Curve, FLAME_PARAMS, Key, MAX_CURVES, MAX_FRAMES, Target, VarParam, XFORM_PARAMS, XformRef,
};
use crate::flame::variations;

/// A target's name for people: `zoom`, `Transform 2: rotate`, `Final: weight`,
/// `Transform 1: julian power`, `Palette: hue`.
pub fn label(t: &Target) -> String {
    let xf = |r: &XformRef| match r {
        XformRef::Index(i) => format!("Transform {}", i + 1),
        XformRef::Final => "Final".to_string(),
    };
    let human = |s: &str| s.replace('_', " ");
    match t {
        Target::Flame(p) => FLAME_PARAMS
            .iter()
            .find(|(q, _)| q == p)
            .map_or_else(|| t.to_string(), |(_, n)| human(n)),
        Target::Xform(r, p) => {
            let name = XFORM_PARAMS
                .iter()
                .find(|(q, _)| q == p)
                .map_or("?", |x| x.1);
            format!("{}: {}", xf(r), human(name))
        }
        Target::Var {
            xform,
            var,
            form,
            param,
        } => {
            let p = match param {
                VarParam::Weight => "weight".to_string(),
                VarParam::Param(k) => variations::info(*var)
                    .params
                    .get(*k)
                    .map_or_else(|| "?".into(), |p| p.name.to_string()),
            };
            format!(
                "{}: {} {}",
                xf(xform),
                variations::attr_name(*var, *form),
                human(&p)
            )
        }
        Target::PaletteRotate => "Palette: rotate".into(),
        Target::PaletteHue => "Palette: hue".into(),
    }
}

/// The unit of a target's values, for the key inspector.
pub fn unit(t: &Target) -> &'static str {
    use crate::flame::keyframes::{FlameParam, XformParam};
    match t {
        Target::Flame(FlameParam::Rotate | FlameParam::CamPitch | FlameParam::CamYaw)
        | Target::Xform(_, XformParam::Rotate | XformParam::PostRotate)
        | Target::PaletteHue => "°",
        Target::Xform(_, XformParam::Scale | XformParam::PostScale) => "×",
        Target::PaletteRotate => "entries",
        _ => "",
    }
}

/// A group of parameters in the chooser.
pub struct Group {
    pub title: String,
    pub targets: Vec<Target>,
}

/// The parameters of `f` a curve can drive: those already animated, the flame's, the
/// transform `xform`'s and its variations', and the palette's.
pub fn groups(f: &Flame, xform: XformRef) -> Vec<Group> {
    let mut out = Vec::new();
    let animated: Vec<Target> = f
        .keys
        .curves
        .iter()
        .filter(|c| !c.keys().is_empty())
        .map(|c| c.target)
        .collect();
    if !animated.is_empty() {
        out.push(Group {
            title: "Animated".into(),
            targets: animated,
        });
    }
    out.push(Group {
        title: "Flame".into(),
        targets: FLAME_PARAMS
            .iter()
            .map(|(p, _)| Target::Flame(*p))
            .collect(),
    });
    let x = match xform {
        XformRef::Index(i) => f.xforms.get(i),
        XformRef::Final => f.final_xform.as_ref(),
    };
    if let Some(x) = x {
        let mut targets: Vec<Target> = XFORM_PARAMS
            .iter()
            .map(|(p, _)| Target::Xform(xform, *p))
            .collect();
        for v in &x.vars {
            let params = variations::info(v.id).params.len();
            targets.extend(
                std::iter::once(VarParam::Weight)
                    .chain((0..params).map(VarParam::Param))
                    .map(|param| Target::Var {
                        xform,
                        var: v.id,
                        form: v.form,
                        param,
                    }),
            );
        }
        let title = match xform {
            XformRef::Index(i) => format!("Transform {}", i + 1),
            XformRef::Final => "Final transform".into(),
        };
        out.push(Group { title, targets });
    }
    out.push(Group {
        title: "Palette".into(),
        targets: vec![Target::PaletteRotate, Target::PaletteHue],
    });
    out
}

/// The curve of `t` in `f`, if it has keys.
pub fn curve<'a>(f: &'a Flame, t: &Target) -> Option<&'a Curve> {
    f.keys.curve(t).filter(|c| !c.keys().is_empty())
}

/// The index of the key at `frame` in the curve of `t`.
pub fn index_at(f: &Flame, t: &Target, frame: f64) -> Option<usize> {
    curve(f, t)?.keys().iter().position(|k| k.frame == frame)
}

/// The value a new key of `t` at `frame` gets: the curve's value there (adding a key does not
/// change the animation), or the flame's own value when the target has no keys yet.
fn value_for_new_key(f: &Flame, t: &Target, frame: f64) -> Option<f64> {
    let wrap = f.keys.wrap.then_some(f.keys.frames as f64);
    match curve(f, t) {
        Some(c) => c.eval(frame, wrap),
        None => {
            let mut probe = crate::flame::keyframes::Keyframes::default();
            probe.key_current(f, *t, frame).ok()?;
            Some(probe.curves[0].keys()[0].value)
        }
    }
}

/// Add a key of `t` at `frame` (one undo step). Err names what went wrong.
pub fn add(doc: &mut Document, t: Target, frame: f64) -> Result<(), String> {
    let v = value_for_new_key(doc.flame(), &t, frame)
        .ok_or_else(|| format!("'{}' is not in this flame", label(&t)))?;
    add_value(doc, t, frame, v)
}

/// Add a key of `t` at `frame` with `value` (one undo step), as the curve editor places it.
/// A key the curve refuses (not finite, a scale factor not positive) changes nothing.
pub fn add_value(doc: &mut Document, t: Target, frame: f64, value: f64) -> Result<(), String> {
    let keys = &doc.flame().keys;
    let mut c = match keys.curve(&t) {
        Some(c) => c.clone(),
        None if keys.curves.len() >= MAX_CURVES => {
            return Err(format!("a flame holds at most {MAX_CURVES} curves"));
        }
        None => Curve::new(t),
    };
    c.insert(Key::new(frame, value))?;
    doc.edit(|f| *f.keys.curve_mut(t) = c);
    Ok(())
}

/// Remove the key of `t` at `frame` (one undo step); a curve left without keys goes.
pub fn delete(doc: &mut Document, t: Target, frame: f64) -> bool {
    let Some(i) = index_at(doc.flame(), &t, frame) else {
        return false;
    };
    doc.edit(|f| {
        f.keys.curve_mut(t).remove(i);
        f.keys.curves.retain(|c| !c.keys().is_empty());
    });
    true
}

/// Change the key of `t` at `frame` with `change` (one undo step per click; while
/// `dragging`, one for the whole drag). Keys stay one per frame: a move onto another key's
/// frame is refused. Returns the key's frame afterwards.
pub fn change(
    doc: &mut Document,
    t: Target,
    frame: f64,
    dragging: bool,
    change: impl FnOnce(&mut Key),
) -> Result<f64, String> {
    let f = doc.flame();
    let i = index_at(f, &t, frame).ok_or("no key there")?;
    let c = curve(f, &t).ok_or("no key there")?;
    let mut k = c.keys()[i];
    change(&mut k);
    if !k.frame.is_finite() || !k.value.is_finite() {
        return Err("a key needs a finite frame and value".into());
    }
    if k.frame != frame && c.keys().iter().any(|q| q.frame == k.frame) {
        return Err(format!("frame {} has a key already", k.frame));
    }
    if k == c.keys()[i] {
        return Ok(frame);
    }
    let mut result = Ok(k.frame);
    doc.edit_while(dragging, |f| {
        let c = f.keys.curve_mut(t);
        if let Some(old) = c.remove(i)
            && let Err(e) = c.insert(k)
        {
            let _ = c.insert(old);
            result = Err(e);
        }
    });
    result
}

/// Most frames the editor's timeline offers (the engine allows more).
pub const MAX_TIMELINE_FRAMES: u32 = 1_000_000;

/// The timeline's length, rate and wrap (one undo step).
pub fn set_timeline(doc: &mut Document, frames: u32, fps: f64, wrap: bool) {
    let frames = frames.clamp(1, MAX_TIMELINE_FRAMES.min(MAX_FRAMES));
    let fps = fps.clamp(crate::io::video::MIN_FPS, crate::io::video::MAX_FPS);
    doc.edit(|f| {
        f.keys.frames = frames;
        f.keys.fps = fps;
        f.keys.wrap = wrap;
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::keyframes::Interp;

    /// Set how the curve leaves the key.
    fn set_interp(doc: &mut Document, t: Target, frame: f64, i: Interp) -> Result<f64, String> {
        change(doc, t, frame, false, |k| k.interp = i)
    }
    use crate::flame::keyframes::{FlameParam, XformParam};
    use crate::flame::{Affine, Xform};

    fn doc() -> Document {
        let f = Flame {
            xforms: vec![Xform::linear(
                Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0),
                1.0,
                0.0,
            )],
            zoom: 0.5,
            ..Flame::default()
        };
        Document::new(vec![f], None)
    }

    #[test]
    fn keys_are_added_moved_and_deleted_as_undo_steps() {
        let mut d = doc();
        let zoom = Target::Flame(FlameParam::Zoom);
        add(&mut d, zoom, 0.0).unwrap();
        assert_eq!(curve(d.flame(), &zoom).unwrap().keys()[0].value, 0.5);
        d.edit(|f| f.zoom = 2.0);
        add(&mut d, zoom, 10.0).unwrap();
        // A key added between keys takes the curve's value there: the animation is the same.
        let before = d.flame().keys.apply(d.flame(), 4.0).zoom;
        add(&mut d, zoom, 4.0).unwrap();
        assert_eq!(d.flame().keys.apply(d.flame(), 4.0).zoom, before);
        assert_eq!(curve(d.flame(), &zoom).unwrap().keys().len(), 3);
        // Moving onto another key is refused; elsewhere the key moves.
        assert!(change(&mut d, zoom, 4.0, false, |k| k.frame = 10.0).is_err());
        assert_eq!(change(&mut d, zoom, 4.0, false, |k| k.frame = 6.0), Ok(6.0));
        assert_eq!(set_interp(&mut d, zoom, 6.0, Interp::Step), Ok(6.0));
        assert_eq!(
            curve(d.flame(), &zoom).unwrap().keys()[1].interp,
            Interp::Step
        );
        assert!(delete(&mut d, zoom, 6.0));
        assert!(delete(&mut d, zoom, 0.0));
        assert!(delete(&mut d, zoom, 10.0));
        assert!(d.flame().keys.curves.is_empty(), "an empty curve goes");
        // Every step undoes: back to no keys at all.
        while d.undo() {}
        assert!(d.flame().keys.is_empty());
        assert_eq!(d.flame().zoom, 0.5);
    }

    #[test]
    fn the_chooser_lists_the_selected_transform_and_its_variations() {
        let d = doc();
        let g = groups(d.flame(), XformRef::Index(0));
        let names: Vec<&str> = g.iter().map(|g| g.title.as_str()).collect();
        assert_eq!(names, ["Flame", "Transform 1", "Palette"]);
        assert!(
            g[1].targets
                .contains(&Target::Xform(XformRef::Index(0), XformParam::Rotate))
        );
        assert!(g[1].targets.iter().any(|t| matches!(t, Target::Var { .. })));
        assert_eq!(label(&g[1].targets[6]), "Transform 1: rotate");
        assert_eq!(label(&Target::Flame(FlameParam::CenterX)), "center x");
        // Rotation keys start at no turn, whatever the map.
        let mut d = doc();
        let turn = Target::Xform(XformRef::Index(0), XformParam::Rotate);
        add(&mut d, turn, 3.0).unwrap();
        assert_eq!(curve(d.flame(), &turn).unwrap().keys()[0].value, 0.0);
    }
}
