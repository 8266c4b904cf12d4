//! Editing an xform's map as it is shown at a frame of its animation. The map shown is the
//! base map turned and scaled by the xform's turn and scale curves there; an editor that draws
//! it (the triangle editor) hands back the map the user made, and this finds what to change:
//! with automatic keys, a turn or scaling of the shown map becomes keys of those curves at the
//! frame (as in Chaotica and JWildfire, where moving a keyed value keys it); any other change
//! (a corner dragged into a shear, or no automatic keys) goes to the base map, worked back
//! through the frame's turn and scale so that the map shown is the one made.

use crate::flame::keyframes::{CurveStyle, Key, Keyframes, Target, XformParam, XformRef};
use crate::flame::model::{Affine, Flame};

/// Relative tolerance for "the change is a turn and a uniform scaling".
const SIMILARITY_TOLERANCE: f64 = 1e-6;

/// The linear part of a map as the matrix whose columns are (a, c) and (b, d): a turn by θ is
/// R(θ)·L and a scaling by k is k·L.
fn linear(m: &Affine) -> [[f64; 2]; 2] {
    [[m.a, m.b], [m.c, m.d]]
}

fn with_linear(m: &Affine, l: [[f64; 2]; 2]) -> Affine {
    Affine {
        a: l[0][0],
        b: l[0][1],
        c: l[1][0],
        d: l[1][1],
        ..*m
    }
}

fn mul(p: [[f64; 2]; 2], q: [[f64; 2]; 2]) -> [[f64; 2]; 2] {
    let mut r = [[0.0; 2]; 2];
    for i in 0..2 {
        for j in 0..2 {
            r[i][j] = p[i][0] * q[0][j] + p[i][1] * q[1][j];
        }
    }
    r
}

/// k·R(θ) (θ in degrees).
fn turn_scale(degrees: f64, k: f64) -> [[f64; 2]; 2] {
    let (s, c) = degrees.to_radians().sin_cos();
    [[k * c, -k * s], [k * s, k * c]]
}

/// The turn (degrees) and scale factor taking `from` to `to`, when the change is one.
fn similarity(from: [[f64; 2]; 2], to: [[f64; 2]; 2]) -> Option<(f64, f64)> {
    let det = from[0][0] * from[1][1] - from[0][1] * from[1][0];
    if det.abs() < 1e-300 {
        return None;
    }
    let inv = [
        [from[1][1] / det, -from[0][1] / det],
        [-from[1][0] / det, from[0][0] / det],
    ];
    let m = mul(to, inv);
    let size = m.iter().flatten().map(|v| v.abs()).fold(0.0, f64::max);
    let close = |a: f64, b: f64| (a - b).abs() <= SIMILARITY_TOLERANCE * size.max(1e-12);
    if !(close(m[0][0], m[1][1]) && close(m[0][1], -m[1][0])) {
        return None;
    }
    let (p, q) = (0.5 * (m[0][0] + m[1][1]), 0.5 * (m[1][0] - m[0][1]));
    let k = p.hypot(q);
    // No turn or scaling at all (a move): exactly none, not rounding noise.
    let turn = q.atan2(p).to_degrees();
    let turn = if turn.abs() < 1e-9 { 0.0 } else { turn };
    let k = if (k - 1.0).abs() < 1e-12 { 1.0 } else { k };
    (k > 0.0).then_some((turn, k))
}

/// `t` has a curve of ugnis' own keys (a JWildfire curve is played, not keyed).
fn keyable(keys: &Keyframes, t: &Target) -> bool {
    keys.curve(t)
        .is_some_and(|c| c.style() == CurveStyle::Keys && !c.keys().is_empty())
}

/// Set the map of xform `x` (its post map when `post`) in `base` so that the map shown at
/// `frame` (the base with its curves applied) is `shown`. With `auto_key`, a turn and scaling
/// of the shown map keys the xform's turn and scale curves at `frame` where it has them (the
/// part without a curve goes to the base map); otherwise the base map changes. The
/// translation is set in the base, and with `auto_key` keyed where it has a curve. False when
/// the xform is missing.
pub fn set_shown_map(
    base: &mut Flame,
    x: XformRef,
    post: bool,
    frame: f64,
    shown: Affine,
    auto_key: bool,
) -> bool {
    let (turn_t, scale_t) = if post {
        (
            Target::Xform(x, XformParam::PostRotate),
            Target::Xform(x, XformParam::PostScale),
        )
    } else {
        (
            Target::Xform(x, XformParam::Rotate),
            Target::Xform(x, XformParam::Scale),
        )
    };
    let keys = &base.keys;
    let wrap = keys.wrap.then_some(keys.frames as f64);
    let value = |t: &Target, none: f64| {
        keys.curve(t)
            .and_then(|c| c.eval(frame, wrap))
            .unwrap_or(none)
    };
    let (turn_now, scale_now) = (value(&turn_t, 0.0), value(&scale_t, 1.0));
    let (has_turn, has_scale) = (keyable(keys, &turn_t), keyable(keys, &scale_t));
    let map_of = |f: &Flame| {
        let xf = match x {
            XformRef::Index(i) => f.xforms.get(i),
            XformRef::Final => f.final_xform.as_ref(),
        }?;
        Some(if post { xf.post } else { xf.coefs })
    };
    let Some(old_base) = map_of(base) else {
        return false;
    };
    let old_shown = with_linear(
        &old_base,
        mul(turn_scale(turn_now, scale_now), linear(&old_base)),
    );
    let mut new_base = old_base;
    new_base.e = shown.e;
    new_base.f = shown.f;
    let change = similarity(linear(&old_shown), linear(&shown));
    match change {
        Some((turn, k)) if auto_key && (has_turn || has_scale) => {
            // The part without a curve turns or scales the base.
            let rest = turn_scale(
                if has_turn { 0.0 } else { turn },
                if has_scale { 1.0 } else { k },
            );
            new_base = with_linear(&new_base, mul(rest, linear(&old_base)));
            if has_turn && turn != 0.0 {
                let _ = base
                    .keys
                    .curve_mut(turn_t)
                    .insert(Key::new(frame, turn_now + turn));
            }
            if has_scale && k != 1.0 {
                let _ = base
                    .keys
                    .curve_mut(scale_t)
                    .insert(Key::new(frame, scale_now * k));
            }
        }
        _ => {
            // The base that, turned and scaled as at this frame, is the map made.
            let back = turn_scale(-turn_now, 1.0 / scale_now);
            new_base = with_linear(&new_base, mul(back, linear(&shown)));
        }
    }
    if auto_key {
        // A keyed position is keyed where it was moved to.
        let (mx, my) = if post {
            (XformParam::PostMoveX, XformParam::PostMoveY)
        } else {
            (XformParam::MoveX, XformParam::MoveY)
        };
        for (p, v, was) in [(mx, shown.e, old_base.e), (my, shown.f, old_base.f)] {
            let t = Target::Xform(x, p);
            if v != was && keyable(&base.keys, &t) {
                let _ = base.keys.curve_mut(t).insert(Key::new(frame, v));
            }
        }
    }
    let xf = match x {
        XformRef::Index(i) => &mut base.xforms[i],
        XformRef::Final => base.final_xform.as_mut().expect("found above"),
    };
    if post {
        xf.post = new_base;
    } else {
        xf.coefs = new_base;
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::model::Xform;

    fn keyed() -> Flame {
        let mut f = Flame {
            xforms: vec![Xform::linear(
                Affine::new(0.5, 0.1, -0.2, 0.4, 0.3, -0.1),
                1.0,
                0.0,
            )],
            ..Flame::default()
        };
        f.keys.frames = 20;
        let r = Target::Xform(XformRef::Index(0), XformParam::Rotate);
        f.keys.curve_mut(r).insert(Key::new(0.0, 0.0)).unwrap();
        f.keys.curve_mut(r).insert(Key::new(20.0, 90.0)).unwrap();
        f
    }

    fn shown(f: &Flame, frame: f64) -> Affine {
        f.keys.apply(f, frame).xforms[0].coefs
    }

    fn near(a: &Affine, b: &Affine) -> bool {
        [
            a.a - b.a,
            a.b - b.b,
            a.c - b.c,
            a.d - b.d,
            a.e - b.e,
            a.f - b.f,
        ]
        .iter()
        .all(|d| d.abs() < 1e-9)
    }

    #[test]
    fn a_turn_of_the_shown_map_keys_the_turn_and_a_scaling_goes_to_the_base() {
        let mut f = keyed();
        let before = shown(&f, 10.0);
        // Turned by 30° and grown by 1.5 about the origin, moved.
        let mut made = with_linear(&before, mul(turn_scale(30.0, 1.5), linear(&before)));
        made.e += 0.25;
        assert!(set_shown_map(
            &mut f,
            XformRef::Index(0),
            false,
            10.0,
            made,
            true
        ));
        assert!(
            near(&shown(&f, 10.0), &made),
            "the map shown is the one made"
        );
        let r = Target::Xform(XformRef::Index(0), XformParam::Rotate);
        let c = f.keys.curve(&r).unwrap();
        assert_eq!(c.keys().len(), 3);
        assert!((c.eval(10.0, None).unwrap() - (45.0 + 30.0)).abs() < 1e-9);
        // The other frames keep their turn; the scaling (no curve) is in the base.
        assert!((c.eval(0.0, None).unwrap()).abs() < 1e-12);
        let b = f.xforms[0].coefs;
        assert!(
            (b.a - 0.75).abs() < 1e-9 && (b.d - 0.6).abs() < 1e-9,
            "{b:?}"
        );
    }

    #[test]
    fn a_move_keys_nothing_but_the_position_curves_it_has() {
        let mut f = keyed();
        let mx = Target::Xform(XformRef::Index(0), XformParam::MoveX);
        f.keys.curve_mut(mx).insert(Key::new(0.0, 0.3)).unwrap();
        let keys = f.keys.clone();
        let mut made = shown(&f, 10.0);
        made.e += 0.5;
        made.f -= 0.25;
        assert!(set_shown_map(
            &mut f,
            XformRef::Index(0),
            false,
            10.0,
            made,
            true
        ));
        let r = Target::Xform(XformRef::Index(0), XformParam::Rotate);
        assert_eq!(f.keys.curve(&r), keys.curve(&r), "no turn key");
        let c = f.keys.curve(&mx).unwrap();
        assert_eq!(c.keys().len(), 2);
        assert!((c.eval(10.0, None).unwrap() - (0.3 + 0.5)).abs() < 1e-12);
        assert!((f.xforms[0].coefs.f - (-0.1 - 0.25)).abs() < 1e-12);
    }

    #[test]
    fn without_auto_key_or_for_a_shear_the_base_changes_and_the_curves_stay() {
        for auto_key in [false, true] {
            let mut f = keyed();
            let keys = f.keys.clone();
            let before = shown(&f, 10.0);
            let made = if auto_key {
                // A corner dragged: a shear, which no turn or scale key can make.
                Affine {
                    b: before.b + 0.2,
                    ..before
                }
            } else {
                with_linear(&before, mul(turn_scale(30.0, 1.0), linear(&before)))
            };
            assert!(set_shown_map(
                &mut f,
                XformRef::Index(0),
                false,
                10.0,
                made,
                auto_key
            ));
            assert_eq!(f.keys, keys, "no key");
            assert!(near(&shown(&f, 10.0), &made));
        }
    }
}
