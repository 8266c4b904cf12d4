//! Symmetry xforms (flam3 `flam3_add_symmetry`).

use crate::flame::model::{Affine, Flame, Xform};
use crate::flame::rng::FastRng;

/// flam3's rounding to 6 decimals (half away from zero, scaled back by multiplying by 1e-6).
fn round6(v: f64) -> f64 {
    let mut x = v * 1e6;
    if x < 0.0 {
        x -= 1.0;
    }
    1e-6 * ((x + 0.5) as i64) as f64
}

/// Add the symmetry xforms of order `k` to a flame.
/// k = 0 or 1: nothing; k < 0: a mirror x → −x, then |k|; k ≥ 2: k − 1 rotations. The added
/// xforms keep their colour (colour speed 0), do not turn in loops (animate 0) and are sorted as
/// flam3 sorts them (by the determinant of their linear part, the mirror first), so that
/// in-betweens pair them with the xforms flam3 pairs them with.
pub fn add_symmetry(flame: &mut Flame, k: i32) {
    if k == 0 || k == 1 {
        return;
    }
    let first = flame.xforms.len();
    push_symmetry(flame, k);
    let det = |x: &Xform| x.coefs.a * x.coefs.d - x.coefs.b * x.coefs.c;
    // A stable sort, as glibc's qsort (a merge sort) is on flam3's machines.
    flame.xforms[first..].sort_by(|x, y| det(x).total_cmp(&det(y)));
    for x in &mut flame.xforms[first..] {
        x.animate = 0.0;
    }
}

fn push_symmetry(flame: &mut Flame, k: i32) {
    let mut k = k;
    if k < 0 {
        let mut m = Xform::linear(Affine::new(-1.0, 0.0, 0.0, 1.0, 0.0, 0.0), 1.0, 1.0);
        m.color_speed = 0.0;
        flame.xforms.push(m);
        k = -k;
    }
    if k < 2 {
        return;
    }
    for j in 1..k {
        let a = 2.0 * std::f64::consts::PI * j as f64 / k as f64;
        let (s, c) = a.sin_cos();
        let color = if k >= 3 {
            (j - 1) as f64 / (k - 2) as f64
        } else {
            0.0
        };
        // flam3's c[1][0] is the rounded value of minus the rounded sine.
        let (c, s) = (round6(c), round6(s));
        let mut x = Xform::linear(Affine::new(c, round6(-s), s, c, 0.0, 0.0), 1.0, color);
        x.color_speed = 0.0;
        flame.xforms.push(x);
    }
}

/// flam3's random symmetry order.
pub fn random_symmetry(rng: &mut FastRng) -> i32 {
    const SYM: [i32; 15] = [-4, -3, -2, -2, -2, -1, -1, -1, 2, 2, 2, 3, 3, 4, 4];
    if rng.bit() {
        SYM[rng.below(SYM.len() as u64) as usize]
    } else if rng.below(32) != 0 {
        rng.below(13) as i32 - 6
    } else {
        rng.below(51) as i32 - 25
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotations_and_mirror() {
        let mut f = Flame::default();
        add_symmetry(&mut f, 4);
        assert_eq!(f.xforms.len(), 3);
        let r = f.xforms[0].coefs;
        assert_eq!((r.a, r.b, r.c, r.d), (0.0, -1.0, 1.0, 0.0));
        assert_eq!(f.xforms[0].color, 0.0);
        assert_eq!(f.xforms[2].color, 1.0);
        assert!(f.xforms.iter().all(|x| x.color_speed == 0.0));
        let mut f = Flame::default();
        add_symmetry(&mut f, -2);
        assert_eq!(f.xforms.len(), 2);
        assert_eq!(f.xforms[0].coefs.a, -1.0);
        assert_eq!(f.xforms[1].coefs.a, -1.0);
        assert_eq!(f.xforms[1].color, 0.0);
        let mut f = Flame::default();
        add_symmetry(&mut f, 1);
        assert!(f.xforms.is_empty());
    }

    /// flam3 (3.1.1) reading `<symmetry kind="5"/>` writes the rotations by 144°, 216°, 72°
    /// and 288° in this order (sorted by the determinant of the rounded matrices).
    #[test]
    fn order_five_is_sorted_as_flam3_sorts_it() {
        let mut f = Flame::default();
        add_symmetry(&mut f, 5);
        let got: Vec<(f64, f64, f64)> = f
            .xforms
            .iter()
            .map(|x| (x.color, x.coefs.a, x.coefs.c))
            .collect();
        let want = [
            (1.0 / 3.0, -0.809017, 0.587785),
            (2.0 / 3.0, -0.809017, -0.587785),
            (0.0, 0.309017, 0.951057),
            (1.0, 0.309017, -0.951057),
        ];
        for (g, w) in got.iter().zip(&want) {
            assert!(
                (g.0 - w.0).abs() < 1e-12 && (g.1 - w.1).abs() < 1e-12,
                "{got:?}"
            );
            assert!((g.2 - w.2).abs() < 1e-12, "{got:?}");
        }
        assert!(f.xforms.iter().all(|x| x.animate == 0.0));
    }

    #[test]
    fn random_orders_are_in_range() {
        let mut rng = FastRng::new(4);
        for _ in 0..10_000 {
            let k = random_symmetry(&mut rng);
            assert!((-25..=25).contains(&k));
        }
    }
}
