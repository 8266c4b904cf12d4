//! Symmetry xforms (flam3 `flam3_add_symmetry`).

use crate::flame::model::{Affine, Flame, Xform};
use crate::flame::rng::FastRng;

fn round6(v: f64) -> f64 {
    (v * 1e6).round() / 1e6
}

/// Add the symmetry xforms of order `k` to a flame.
/// k = 0 or 1: nothing; k < 0: a mirror x → −x, then |k|; k ≥ 2: k − 1 rotations.
pub fn add_symmetry(flame: &mut Flame, k: i32) {
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
        let mut x = Xform::linear(
            Affine::new(round6(c), round6(-s), round6(s), round6(c), 0.0, 0.0),
            1.0,
            color,
        );
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

    #[test]
    fn random_orders_are_in_range() {
        let mut rng = FastRng::new(4);
        for _ in 0..10_000 {
            let k = random_symmetry(&mut rng);
            assert!((-25..=25).contains(&k));
        }
    }
}
