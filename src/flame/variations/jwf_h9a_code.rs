//! JWildfire's variations whose formula is Java source the user edits, which JWildfire
//! compiles at run time (Janino): `custom_wf` with its own `pre_custom_wf` and
//! `post_custom_wf` classes, and `custom_wf_full` (a whole variation class). ugnis cannot run
//! Java: each computes what JWildfire's built-in default code computes, written here natively.
//! A flame whose code differs from the default is still drawn, with the default; its reader
//! reports it ([`code_problem`]).
//!
//! The defaults (JWildfire 9.00, `CustomWFFunc`, `CustomFullVariationWrapperFunc`; LGPL-2.1):
//! custom_wf's code is the "bubble" map (x, y scaled by w/r, z = w·(2/r − 1) with
//! r = (x² + y²)/4 + 1), custom_wf_full's a `linear3D` that carries z only with "preserve Z".

use super::*;

/// The text parameters: the code, empty for JWildfire's default (a file holding the default's
/// text reads the same).
const fn code(name: &'static str) -> TextParam {
    TextParam {
        name,
        default: "",
        max_len: 1 << 16,
    }
}

/// The seven free parameters custom_wf's code may read (a … g), named for variation `$n`.
macro_rules! custom_params {
    ($n:literal) => {
        &[
            p(concat!($n, "_a"), 0.0),
            p(concat!($n, "_b"), 0.0),
            p(concat!($n, "_c"), 0.0),
            p(concat!($n, "_d"), 0.0),
            p(concat!($n, "_e"), 0.0),
            p(concat!($n, "_f"), 0.0),
            p(concat!($n, "_g"), 0.0),
        ]
    };
}

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("custom_wf", custom_wf)
        .params(custom_params!("custom_wf"))
        .texts(&[code("custom_wf_code")])
        .flags(flag::JWILDFIRE | flag::WRITES_Z),
    VarDef::new("custom_wf_full", custom_wf_full)
        .texts(&[code("custom_wf_full_code_full_variation")])
        .flags(flag::JWILDFIRE),
    VarDef::new("pre_custom_wf", pre_custom_wf)
        .params(custom_params!("pre_custom_wf"))
        .texts(&[code("pre_custom_wf_code")])
        .flags(flag::JWILDFIRE | flag::PRE_ONLY),
    VarDef::new("post_custom_wf", custom_wf)
        .params(custom_params!("post_custom_wf"))
        .texts(&[code("post_custom_wf_code")])
        .flags(flag::JWILDFIRE | flag::POST_ONLY | flag::WRITES_Z)
        .sum(),
];

/// FNV-1a (64 bits) of the default code of each variation, its whitespace runs made single
/// spaces and the ends trimmed ([`normalised_hash`]): computed from the default strings of
/// JWildfire 9.00's classes.
const DEFAULT_CODE: &[(&str, u64)] = &[
    ("custom_wf", 0x97d7_303a_584b_7967),
    ("pre_custom_wf", 0x97d7_303a_584b_7967),
    ("post_custom_wf", 0x97d7_303a_584b_7967),
    ("custom_wf_full", 0x4689_89a4_6575_a69f),
    ("glsl_code", 0x42a1_db57_c220_8e02),
    ("f_complex", 0x1e28_1dfe_9e08_30a3),
    ("ducks", 0x7e9d_1669_5b6c_49e8),
];

/// FNV-1a (64 bits) of `s` with every run of whitespace made one space and the ends trimmed.
fn normalised_hash(s: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut eat = |b: u8| {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    };
    for (i, word) in s.split_whitespace().enumerate() {
        if i > 0 {
            eat(b' ');
        }
        word.bytes().for_each(&mut eat);
    }
    h
}

/// The reader's warning for a code text of variation `name` that is not JWildfire's default
/// (compared with whitespace normalised): `None` for the default, an empty text, or a
/// variation not of this file.
pub fn code_problem(name: &str, texts: &[String]) -> Option<String> {
    let (_, want) = DEFAULT_CODE.iter().find(|(n, _)| *n == name)?;
    let text = texts.first()?;
    if text.trim().is_empty() || normalised_hash(text) == *want {
        return None;
    }
    Some(format!(
        "{name}: custom code is not supported; the default code is used"
    ))
}

/// JWildfire's default code of custom_wf: the bubble map.
fn bubble(v: &Prepared, t: &VarIn) -> V3 {
    let r = (t.x * t.x + t.y * t.y) / 4.0 + 1.0;
    let s = v.w / r;
    [s * t.x, s * t.y, v.w * (2.0 / r - 1.0)]
}

/// custom_wf (and post_custom_wf, added to the point): the default code's bubble.
fn custom_wf(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    bubble(v, t)
}

/// pre_custom_wf: the default code adds the bubble to the xform's sum (JWildfire's `pVarTP`),
/// which the regular variations then add to; the point the later variations see is left as
/// it is. ugnis' pre phase keeps no sum, so only the point is produced (unchanged).
fn pre_custom_wf(_v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [t.x, t.y, t.z]
}

/// custom_wf_full: the default class, a linear map (z with JWildfire's "preserve Z" only).
fn custom_wf_full(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    [v.w * t.x, v.w * t.y, v.default_z(t)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn code_other_than_the_default_is_reported() {
        let t = |s: &str| vec![s.to_string()];
        assert_eq!(code_problem("custom_wf", &t("  ")), None);
        assert_eq!(code_problem("linear", &t("x")), None);
        let w = code_problem("post_custom_wf", &t("pVarTP.x += 1;")).unwrap();
        assert!(w.contains("post_custom_wf") && w.contains("default code is used"));
        // Whitespace does not count.
        assert_eq!(normalised_hash(" a \r\n  b\t"), normalised_hash("a b"));
        assert_ne!(normalised_hash("a b"), normalised_hash("ab"));
    }
}
