//! Whatever ugnis writes, ugnis reads: every variation in every form it can be used in (plain,
//! `pre_`, `post_`, both forms of one variation on one transform, a variation whose own name
//! starts with `post_` used as `pre_` and `post_`), written to flam3 XML and read back equal,
//! with arbitrary weights and parameter values.

use proptest::prelude::*;
use ugnis::flame::variations::{self, Form, flag};
use ugnis::flame::{Flame, Var, Xform};
use ugnis::io::flam3_xml::{self, FlameFile, LibrarySource, ReadOptions};

fn read_back(flame: &Flame) -> Result<Flame, String> {
    let file = FlameFile {
        name: String::new(),
        flames: vec![flame.clone()],
    };
    let text = flam3_xml::write(&file);
    let opts = ReadOptions {
        library: LibrarySource::Paths(vec![]),
        ..ReadOptions::default()
    };
    let mut back = flam3_xml::read(&text, &opts)
        .map_err(|e| format!("{e}\n{text}"))?
        .value;
    Ok(back.flames.remove(0))
}

/// The forms variation `id` can be used in: its own for a `pre_`/`post_`-only variation, the
/// three otherwise.
fn forms(id: u16) -> &'static [Form] {
    let d = variations::info(id);
    if d.has(flag::POST_ONLY) {
        &[Form::Post]
    } else if d.has(flag::PRE_ONLY) {
        &[Form::Pre]
    } else {
        &[Form::Regular, Form::Pre, Form::Post]
    }
}

fn usable() -> Vec<u16> {
    (0..variations::count() as u16)
        .filter(|&id| !variations::info(id).has(flag::HIDDEN))
        .collect()
}

fn flame_of(xforms: Vec<Xform>) -> Flame {
    Flame {
        xforms,
        ..Flame::default()
    }
}

/// One transform per variation holding it in every form it has, twice over (the second use of
/// a form is JWildfire's `NAME#1#`), with parameters off their defaults.
#[test]
fn every_variation_in_every_form_reads_back_equal() {
    let ids = usable();
    for chunk in ids.chunks(64) {
        let xforms = chunk
            .iter()
            .map(|&id| {
                let mut vars = Vec::new();
                for (k, &form) in forms(id)
                    .iter()
                    .cycle()
                    .take(2 * forms(id).len())
                    .enumerate()
                {
                    let mut v = Var::with_form(id, form, 0.25 + k as f64 / 8.0);
                    // The parameters of its formula in a flam3 flame (a JWildfire twin's own
                    // trailing ones are written only in JWildfire flames).
                    let own = variations::info(id).params.len();
                    for (i, p) in v.params.iter_mut().take(own).enumerate() {
                        *p += 0.5 + i as f64;
                    }
                    vars.push(v);
                }
                Xform {
                    vars,
                    ..Xform::default()
                }
            })
            .collect();
        let f = flame_of(xforms);
        let back = read_back(&f).unwrap_or_else(|e| panic!("{e}"));
        for (a, b) in f.xforms.iter().zip(&back.xforms) {
            assert_eq!(a.vars, b.vars, "{}", variations::info(a.vars[0].id).name);
        }
        assert_eq!(back.xforms.len(), f.xforms.len());
    }
}

/// A variation whose own name starts with `post_` (a `post_`-only one forced into the other
/// form by the editor, or a regular one named so) used as `pre_` and `post_` on one transform.
#[test]
fn post_named_variations_as_pre_and_post_read_back() {
    for name in ["post_smartcrop", "post_mirror_wf"] {
        let (id, _) = variations::parse_name(name).unwrap();
        let x = Xform {
            vars: vec![
                Var::with_form(id, Form::Pre, 0.5),
                Var::with_form(id, Form::Post, 0.75),
            ],
            ..Xform::default()
        };
        let f = flame_of(vec![x]);
        let back = read_back(&f).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(back.xforms[0].vars.len(), 2, "{name}");
        let weights: Vec<f64> = back.xforms[0].vars.iter().map(|v| v.weight).collect();
        assert_eq!(weights, [0.5, 0.75], "{name}");
    }
}

fn var_strategy(ids: Vec<u16>) -> impl Strategy<Value = Var> {
    (
        proptest::sample::select(ids),
        0usize..3,
        prop_oneof![-1e6..1e6f64, Just(1.0), Just(-0.5)],
        proptest::collection::vec(
            prop_oneof![-1e9..1e9f64, -2.0..2.0f64, Just(0.0), Just(1e-300)],
            16,
        ),
    )
        .prop_map(|(id, f, weight, ps)| {
            let fs = forms(id);
            let weight = if weight == 0.0 { 1.0 } else { weight };
            let mut v = Var::with_form(id, fs[f % fs.len()], weight);
            let own = variations::info(id).params.len();
            for (p, q) in v.params.iter_mut().take(own).zip(ps.iter().cycle()) {
                *p = *q;
            }
            v
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Any mix of variations, forms, weights and parameter values on a transform is read back
    /// as it was written.
    #[test]
    fn any_mix_of_variations_reads_back_equal(
        vars in proptest::collection::vec(var_strategy(usable()), 1..12)
    ) {
        let f = flame_of(vec![Xform { vars, ..Xform::default() }]);
        let back = read_back(&f).map_err(TestCaseError::fail)?;
        prop_assert_eq!(&back.xforms[0].vars, &f.xforms[0].vars);
    }
}
