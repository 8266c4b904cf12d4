//! JWildfire's sub-flame variations (`subflame_wf`, `pre_subflame_wf`, `ringsubflame`,
//! `glynns3subfl`) embed a whole flame: their `flame` resource, the hex digits of the flame's
//! XML (`subflame_wf_flame="3C666C616D65…"`), kept as it stands for writing back. The engine
//! runs a sub-flame from a description of it (its xforms, one a line; see the engine's
//! sub-flame variations): this reads the embedded flame and fills the variation's
//! description with it. Nested sub-flames are read to a depth of [`MAX_DEPTH`].

use std::cell::Cell;
use std::fmt::Write;

use super::ReadOptions;
use crate::flame::model::{Flame, Xform};
use crate::flame::variations::{self, Dialect};

/// The variations with an embedded flame.
const SUBFLAME_VARS: [&str; 4] = [
    "subflame_wf",
    "pre_subflame_wf",
    "ringsubflame",
    "glynns3subfl",
];

/// How deep sub-flames inside sub-flames are read.
const MAX_DEPTH: u32 = 2;

thread_local! {
    /// The depth of the sub-flame being read.
    static DEPTH: Cell<u32> = const { Cell::new(0) };
}

/// Fills the description of every sub-flame variation of `flame` whose xform carries its
/// embedded flame (one that cannot be read keeps JWildfire's default).
pub(super) fn fill(flame: &mut Flame, opts: &ReadOptions) {
    let depth = DEPTH.get();
    if depth >= MAX_DEPTH {
        return;
    }
    let xforms = flame.xforms.iter_mut();
    let finals = flame
        .final_xform
        .iter_mut()
        .chain(flame.more_finals.iter_mut());
    for x in xforms.chain(finals) {
        for i in 0..x.vars.len() {
            let v = &x.vars[i];
            if !SUBFLAME_VARS.contains(&variations::info(v.id).name) || v.texts.is_empty() {
                continue;
            }
            let key = format!("{}_flame", v.attr_name());
            let Some((_, hex)) = x
                .extra_attrs
                .iter()
                .find(|(k, _)| k.eq_ignore_ascii_case(&key))
            else {
                continue;
            };
            let xml = from_hex(hex);
            DEPTH.set(depth + 1);
            let read = super::read(&xml, opts);
            DEPTH.set(depth);
            let Some(sub) = read.ok().and_then(|p| p.value.flames.into_iter().next()) else {
                continue;
            };
            let d = describe(&sub);
            let def = variations::info(x.vars[i].id);
            x.vars[i].texts[0] = def.texts[0].normalise(&d);
        }
    }
}

/// The bytes of a hex text (a text that is not hex digits, as it stands).
fn from_hex(v: &str) -> String {
    let v = v.trim();
    if !(v.len().is_multiple_of(2) && v.bytes().all(|b| b.is_ascii_hexdigit())) {
        return v.to_string();
    }
    let bytes: Vec<u8> = (0..v.len())
        .step_by(2)
        .filter_map(|i| u8::from_str_radix(&v[i..i + 2], 16).ok())
        .collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

/// The engine's description of a flame: its xforms and final xforms, one a line, its palette
/// and its "preserve Z".
pub(super) fn describe(f: &Flame) -> String {
    let mut s = String::new();
    for x in &f.xforms {
        line(&mut s, "xform", x);
    }
    for x in f.finals() {
        line(&mut s, "finalxform", x);
    }
    s.push_str("palette=");
    for c in f.render_colors().iter().take(256) {
        for ch in &c[..3] {
            let _ = write!(s, "{:02X}", (ch.clamp(0.0, 1.0) * 255.0).round() as u8);
        }
    }
    s.push('\n');
    if f.rules().preserve_z {
        s.push_str("preserve_z=1\n");
    }
    s
}

fn list(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|x| x.to_string()).collect();
    parts.join(",")
}

fn line(s: &mut String, kind: &str, x: &Xform) {
    let _ = write!(
        s,
        "{kind} weight={} color={} symmetry={} opacity={} coefs={} post={}",
        x.weight,
        x.color,
        1.0 - 2.0 * x.color_speed,
        x.opacity,
        list(&x.coefs.to_coefs()),
        list(&x.post.to_coefs()),
    );
    if !x.chaos.is_empty() {
        let _ = write!(s, " chaos={}", list(&x.chaos));
    }
    for v in &x.vars {
        let _ = write!(s, " {}={}", v.attr_name(), v.weight);
        let def = variations::def_in(Dialect::JWildfire, v.id, v.form);
        for (k, value) in v.params.iter().enumerate().take(def.params.len()) {
            let name = variations::param_attr_name_in(Dialect::JWildfire, v.id, v.form, k);
            let _ = write!(s, " {name}={value}");
        }
    }
    s.push('\n');
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::rng::FastRng;
    use crate::flame::variations::{Acc, Prepared, Rules, eval_prepared};

    fn hex(s: &str) -> String {
        s.bytes().map(|b| format!("{b:02X}")).collect()
    }

    /// A sub-flame of one contraction x ↦ x/2 + (1/2, 1/4) runs to its fixed point (1, 1/2):
    /// after the 42 starting steps every call returns it (to rounding).
    #[test]
    fn embedded_flame_is_read_into_the_description_and_run() {
        let sub = r#"<flame name="s" size="8 8" center="0 0" scale="4"><xform weight="1" color="0.5" symmetry="0" linear3D="1" coefs="0.5 0 0 0.5 0.5 0.25"/></flame>"#;
        let src = format!(
            r#"<flame name="t" size="8 8" center="0 0" scale="4"><xform weight="1" color="0" subflame_wf="1" subflame_wf_scale="2" subflame_wf_flame="{}" coefs="1 0 0 1 0 0"/></flame>"#,
            hex(sub)
        );
        let opts = ReadOptions::default();
        let f = read_first(&src, &opts);
        let v = &f.xforms[0].vars[0];
        assert!(v.texts[0].starts_with("xform weight=1 "), "{}", v.texts[0]);
        assert!(v.texts[0].contains("linear3D=1"), "{}", v.texts[0]);
        // The JWildfire attribute is kept for writing back.
        assert!(
            f.xforms[0]
                .extra_attrs
                .iter()
                .any(|(k, _)| k == "subflame_wf_flame")
        );
        let rules = Rules {
            dialect: Dialect::JWildfire,
            ..Rules::default()
        };
        let p = Prepared::for_flame(
            v.id,
            v.form,
            v.weight,
            &v.params,
            &v.texts,
            Default::default(),
            rules,
        );
        let mut rng = FastRng::new(3);
        for _ in 0..5 {
            let o = eval_prepared(&p, [0.0; 3], Acc::default(), false, &mut rng);
            // scale 2, unweighted: (2, 1).
            assert!(
                (o.x - 2.0).abs() < 1e-9 && (o.y - 1.0).abs() < 1e-9,
                "{o:?}"
            );
        }
    }

    fn read_first(src: &str, opts: &ReadOptions) -> Flame {
        let p = super::super::read(src, opts).expect("a flame");
        p.value.flames.into_iter().next().expect("one flame")
    }

    /// A sub-flame that is not a flame leaves the default description.
    #[test]
    fn unreadable_embedded_flame_keeps_the_default() {
        let src = r#"<flame name="t" size="8 8" center="0 0" scale="4"><xform weight="1" color="0" subflame_wf="1" subflame_wf_flame="3C6E6F" coefs="1 0 0 1 0 0"/></flame>"#;
        let f = read_first(src, &ReadOptions::default());
        let id = f.xforms[0].vars[0].id;
        assert_eq!(
            f.xforms[0].vars[0].texts[0],
            variations::info(id).texts[0].default
        );
    }
}
