//! Tests of the batched xform application (`batch.rs`).

use super::*;
use crate::flame::chaos::{Chaos, Pt};
use crate::flame::model::{Affine, Flame, Xform};
use crate::flame::variations::{self, VarIn};

#[test]
fn pre_and_post_forms_wrap_the_regular_variations() {
    use crate::flame::model::Var;
    use crate::flame::variations::{Form, LINEAR, SINUSOIDAL, SPHERICAL};
    let mut x = Xform::linear(Affine::new(0.8, 0.2, -0.3, 0.9, 0.1, -0.2), 1.0, 0.0);
    x.vars = vec![
        Var::with_form(SINUSOIDAL, Form::Pre, 1.0),
        Var::new(LINEAR, 0.5),
        Var::with_form(SPHERICAL, Form::Post, 1.0),
    ];
    let f = Flame {
        xforms: vec![x.clone()],
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    let mut rng = FastRng::new(2);
    let p = Pt {
        x: 0.4,
        y: -0.7,
        z: 0.0,
        c: 0.5,
    };
    let (q, bad) = ch.xforms[0].apply(p, &mut rng);
    assert!(!bad);
    // affine → sin (replaces the point) → 0.5·linear → spherical of the sum.
    let (tx, ty) = x.coefs.apply(p.x, p.y);
    let (sx, sy) = (0.5 * tx.sin(), 0.5 * ty.sin());
    let r2 = sx * sx + sy * sy;
    assert!(
        (q.x - sx / r2).abs() < 1e-12 && (q.y - sy / r2).abs() < 1e-12,
        "{q:?}"
    );
    // The same through the batched lanes.
    let (mut gx, mut gy, mut gz, mut gc) = ([p.x], [p.y], [p.z], [p.c]);
    let mut s = Scratch::new();
    ch.xforms[0].apply_soa(&mut gx, &mut gy, &mut gz, &mut gc, None, &mut s, &mut rng);
    assert!((gx[0] - q.x).abs() < 1e-12 && (gy[0] - q.y).abs() < 1e-12);
}

/// An xform of `pre_` forms alone: flam3 and Apophysis sum no variation (the point goes
/// to the origin, then through the post map), Fractorium hands the moved point on; the
/// same in the point-by-point and the batched runs.
#[test]
fn pre_forms_alone_give_the_origin_under_flam3() {
    use crate::flame::model::{PaletteIndex, Var};
    use crate::flame::variations::{Form, SINUSOIDAL};
    let mut x = Xform::linear(Affine::new(0.8, 0.2, -0.3, 0.9, 0.1, -0.2), 1.0, 0.0);
    x.vars = vec![Var::with_form(SINUSOIDAL, Form::Pre, 1.0)];
    x.post = Affine::new(1.0, 0.0, 0.0, 1.0, 0.25, -0.5);
    let p = Pt {
        x: 0.4,
        y: -0.7,
        z: 0.0,
        c: 0.5,
    };
    let (tx, ty) = x.coefs.apply(p.x, p.y);
    for (rule, want) in [
        (PaletteIndex::Flam3, (0.25, -0.5)),
        (PaletteIndex::Apophysis, (0.25, -0.5)),
        (PaletteIndex::Fractorium, (tx.sin() + 0.25, ty.sin() - 0.5)),
    ] {
        let f = Flame {
            xforms: vec![x.clone()],
            palette_index: rule,
            ..Flame::default()
        };
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(3);
        let (q, bad) = ch.xforms[0].apply(p, &mut rng);
        assert!(!bad);
        assert!(
            (q.x - want.0).abs() < 1e-12 && (q.y - want.1).abs() < 1e-12,
            "{rule:?} {q:?}"
        );
        let (mut gx, mut gy, mut gz, mut gc) = ([p.x], [p.y], [p.z], [p.c]);
        let mut s = Scratch::new();
        ch.xforms[0].apply_soa(&mut gx, &mut gy, &mut gz, &mut gc, None, &mut s, &mut rng);
        assert!(
            (gx[0] - want.0).abs() < 1e-12 && (gy[0] - want.1).abs() < 1e-12,
            "{rule:?} batched {gx:?} {gy:?}"
        );
    }
}

/// JWildfire's post_depth reads the point the regular variations saw (the affine point)
/// besides their sum, in both the point-by-point and the batched runs; the same xform in
/// a flam3 flame runs flam3's post_ form of depth on the sum alone.
#[test]
fn a_post_form_can_read_the_affine_point() {
    use crate::flame::model::{PaletteIndex, Var};
    use crate::flame::variations::{Form, LINEAR};
    let depth = variations::by_name("depth").unwrap();
    let mut x = Xform::linear(Affine::new(0.8, 0.2, -0.3, 0.9, 0.1, -0.2), 1.0, 0.0);
    x.vars = vec![
        Var::new(LINEAR, 0.5),
        Var::with_form(depth, Form::Post, 0.7),
    ];
    let mut f = Flame {
        xforms: vec![x.clone()],
        palette_index: PaletteIndex::JWildfire,
        ..Flame::default()
    };
    let p = Pt {
        x: 0.4,
        y: -0.7,
        z: 0.3,
        c: 0.5,
    };
    let (tx, ty) = x.coefs.apply(p.x, p.y);
    // JWildfire's linear is 2-D: the sum's z is 0, so |z|^power is 0.
    let (sx, sy) = (0.5 * tx, 0.5 * ty);
    let want = [sx + 0.7 * tx, sy + 0.7 * ty];
    for jwildfire in [true, false] {
        if !jwildfire {
            f.palette_index = PaletteIndex::Flam3;
        }
        let ch = Chaos::new(&f).unwrap();
        let mut rng = FastRng::new(2);
        let (q, bad) = ch.xforms[0].apply(p, &mut rng);
        assert!(!bad);
        let (mut gx, mut gy, mut gz, mut gc) = ([p.x], [p.y], [p.z], [p.c]);
        let mut s = Scratch::new();
        ch.xforms[0].apply_soa(&mut gx, &mut gy, &mut gz, &mut gc, None, &mut s, &mut rng);
        assert!((gx[0] - q.x).abs() < 1e-12 && (gy[0] - q.y).abs() < 1e-12);
        let near = (q.x - want[0]).abs() < 1e-12 && (q.y - want[1]).abs() < 1e-12;
        assert_eq!(near, jwildfire, "{q:?} {want:?}");
    }
}

/// Own colours through a group: a direct-colour variation writes its pattern's colour
/// (as the scalar path computes it) and leaves the colour coordinate at its blend; an
/// xform without one gives the palette's colour back, unless it keeps colours.
#[test]
fn own_colours_are_written_kept_or_cleared() {
    use crate::flame::model::{PaletteIndex, Var};
    use crate::flame::variations::own_rgb;
    let dc = variations::by_name("dc_mandala").unwrap();
    let mut a = Xform::linear(Affine::IDENTITY, 1.0, 0.3);
    a.vars = vec![Var::new(dc, 1.0)];
    a.color_speed = 0.5;
    let b = Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 0.1, 0.0), 1.0, 0.9);
    let mut f = Flame {
        xforms: vec![a, b],
        palette_index: PaletteIndex::JWildfire,
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    assert!(ch.rgb && ch.xforms[0].own_rgb && !ch.xforms[1].own_rgb);
    let n = 8;
    let (mut x, mut y, mut z) = (vec![0.1; n], vec![-0.2; n], vec![0.0; n]);
    let (mut c, mut rgb) = (vec![0.7; n], vec![0u32; n]);
    let mut s = Scratch::new();
    let mut rng = FastRng::new(4);
    let xf = &ch.xforms[0];
    xf.apply_soa(
        &mut x,
        &mut y,
        &mut z,
        &mut c,
        Some(&mut rgb),
        &mut s,
        &mut rng,
    );
    for j in 0..n {
        assert_eq!(rgb[j] & own_rgb::OWN, own_rgb::OWN, "{j}");
        assert_eq!(c[j], 0.5 * 0.3 + 0.5 * 0.7);
    }
    // The scalar path gives the same colour for the same point (the pattern reads the
    // random point it draws: the same stream, the same draw).
    let mut r1 = FastRng::new(9);
    let mut r2 = FastRng::new(9);
    let mut one = [0u32];
    let (mut x1, mut y1, mut z1, mut c1) = ([0.1], [-0.2], [0.0], [0.7]);
    xf.apply_soa(
        &mut x1,
        &mut y1,
        &mut z1,
        &mut c1,
        Some(&mut one),
        &mut s,
        &mut r1,
    );
    let t = VarIn::new(0.1, -0.2, 0.0, 0.5, xf.needs, false);
    let mut acc = Acc::default();
    xf.vars[0].eval(&t, &mut acc, &mut r2);
    assert_eq!(Some(one[0]), acc.packed_rgb());
    // A palette xform clears the colours it is given …
    let kept = rgb.clone();
    let mut step = |xf: &CompiledXform, rgb: &mut [u32]| {
        let r = Some(rgb);
        xf.apply_soa(&mut x, &mut y, &mut z, &mut c, r, &mut s, &mut rng);
    };
    step(&ch.xforms[1], &mut rgb);
    assert!(rgb.iter().all(|&p| p == 0));
    // … unless it is of JWildfire's colour type NONE.
    f.xforms[1]
        .extra_attrs
        .push(("color_type".into(), "NONE".into()));
    let ch = Chaos::new(&f).unwrap();
    let mut rgb = kept.clone();
    step(&ch.xforms[1], &mut rgb);
    assert_eq!(rgb, kept);
    // Flames of other writers do not carry own colours.
    f.palette_index = PaletteIndex::Flam3;
    assert!(!Chaos::new(&f).unwrap().rgb);
}

#[test]
fn linear_only_xforms_take_the_short_path_with_the_same_bits() {
    let mut x = Xform::linear(Affine::new(0.5, -0.3, 0.2, 0.7, 0.1, -0.4), 1.0, 0.25);
    x.vars[0].weight = 0.8;
    x.post = Affine::new(0.9, 0.1, -0.2, 1.1, 0.05, 0.3);
    x.color_speed = 0.4;
    let f = Flame {
        xforms: vec![x],
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    assert_eq!(ch.xforms[0].linear_only, Some(0.8));
    let mut rng = FastRng::new(5);
    let pts: Vec<Pt> = (0..16).map(|_| Chaos::start_point(&mut rng)).collect();
    let mut gx: Vec<f64> = pts.iter().map(|p| p.x).collect();
    let mut gy: Vec<f64> = pts.iter().map(|p| p.y).collect();
    let mut gz: Vec<f64> = pts.iter().map(|p| p.z + 0.5).collect();
    let mut gc: Vec<f64> = pts.iter().map(|p| p.c).collect();
    let mut s = Scratch::new();
    ch.xforms[0].apply_soa(&mut gx, &mut gy, &mut gz, &mut gc, None, &mut s, &mut rng);
    for (j, p) in pts.iter().enumerate() {
        let (q, bad) = ch.xforms[0].apply(Pt { z: p.z + 0.5, ..*p }, &mut rng);
        assert!(!bad && !s.bad[j]);
        assert_eq!((q.x, q.y, q.z, q.c), (gx[j], gy[j], gz[j], gc[j]));
    }
    // Any other variation, or a pre_/post_ form, takes the general path.
    let mut f2 = f.clone();
    f2.xforms[0]
        .vars
        .push(crate::flame::model::Var::new(variations::SPHERICAL, 0.1));
    assert_eq!(Chaos::new(&f2).unwrap().xforms[0].linear_only, None);
}
