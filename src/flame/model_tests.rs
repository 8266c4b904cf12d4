//! Tests of the flame model: coefficient order, triangles, framing; and a test flame.

use super::*;

#[test]
fn coefs_order_is_a_c_b_d_e_f() {
    let m = Affine::new(0.85, 0.04, -0.04, 0.85, 0.0, 1.6);
    assert_eq!(m.to_coefs(), [0.85, -0.04, 0.04, 0.85, 0.0, 1.6]);
    assert_eq!(Affine::from_coefs(m.to_coefs()), m);
}

#[test]
fn triangle_round_trip() {
    let m = Affine::new(0.3, -0.7, 0.2, 0.9, 0.5, -0.25);
    let t = m.triangle();
    let want = [[0.5, -0.25], [0.8, -0.05], [1.2, -1.15]];
    for (p, q) in t.iter().zip(want) {
        assert!(
            (p[0] - q[0]).abs() < 1e-12 && (p[1] - q[1]).abs() < 1e-12,
            "{t:?}"
        );
    }
    let back = Affine::from_triangle(t);
    for (p, q) in [back.a, back.b, back.c, back.d, back.e, back.f]
        .iter()
        .zip([m.a, m.b, m.c, m.d, m.e, m.f])
    {
        assert!((p - q).abs() < 1e-15);
    }
    // Reference triangle is the identity.
    assert_eq!(
        Affine::from_triangle([[0.0, 0.0], [1.0, 0.0], [0.0, -1.0]]),
        Affine::IDENTITY
    );
}

#[test]
fn determinant_rule_oracles() {
    // Example (a) of Urbonavičius (2006).
    let a = [
        Affine::new(0.48, 0.01, -0.01, 0.47, 0.80, -0.34),
        Affine::new(0.47, 0.01, -0.01, 0.47, -1.01, -0.28),
        Affine::new(-0.28, 0.38, -0.96, -0.19, 0.03, -0.06),
    ];
    let w = Flame::determinant_weights(&a);
    for (p, q) in w.iter().zip([0.261015, 0.255580, 0.483405]) {
        assert!((p - q).abs() < 1e-6, "{w:?}");
    }
    let b = [
        Affine::new(-0.46, -0.50, 0.58, -0.58, 0.46, -0.24),
        Affine::new(0.52, -0.45, 0.45, 0.32, -0.85, 0.43),
    ];
    let w = Flame::determinant_weights(&b);
    for (p, q) in w.iter().zip([0.601491, 0.398509]) {
        assert!((p - q).abs() < 1e-6, "{w:?}");
    }
    let fern = [
        Affine::new(0.0, 0.0, 0.0, 0.16, 0.0, 0.0),
        Affine::new(0.85, 0.04, -0.04, 0.85, 0.0, 1.6),
        Affine::new(0.2, -0.26, 0.23, 0.22, 0.0, 1.6),
        Affine::new(-0.15, 0.28, 0.26, 0.24, 0.0, 0.44),
    ];
    let w = Flame::determinant_weights(&fern);
    for (p, q) in w.iter().zip([0.000999, 0.772261, 0.110704, 0.116036]) {
        assert!((p - q).abs() < 1e-6, "{w:?}");
    }
    assert_eq!(
        Flame::determinant_weights(&[Affine::new(0.0, 0.0, 0.0, 0.0, 1.0, 1.0); 4]),
        vec![0.25; 4]
    );
}

#[test]
fn compose_applies_right_first() {
    let p = Affine::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0);
    let q = Affine::new(0.5, -1.0, 0.25, 2.0, -3.0, 1.0);
    let (x, y) = (0.7, -1.3);
    let (qx, qy) = q.apply(x, y);
    let direct = p.apply(qx, qy);
    let comp = p.compose(&q).apply(x, y);
    assert!((direct.0 - comp.0).abs() < 1e-12 && (direct.1 - comp.1).abs() < 1e-12);
}

/// Test flame: the Sierpinski triangle (three half-size maps, colours 0, ½ and 1) framed on
/// the unit square, at this size and quality.
pub(crate) fn test_sierpinski(width: u32, height: u32, quality: f64) -> Flame {
    let mut f = Flame {
        width,
        height,
        center: [0.5, 0.5],
        scale: width.min(height) as f64 * 0.7,
        quality,
        ..Flame::default()
    };
    for (e, g, c) in [(0.0, 0.0, 0.0), (0.5, 0.0, 0.5), (0.25, 0.5, 1.0)] {
        f.xforms
            .push(Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, e, g), 1.0, c));
    }
    f
}
