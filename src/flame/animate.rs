//! Animation in the editor: Fraktalai's rotating triangles, and in-betweens of two or
//! more flames (flam3's interpolation).

use crate::flame::interpolate::interpolate_at;
use crate::flame::model::{Affine, Flame};
use crate::flame::rng::FastRng;

/// Angular step of the rotation animation, in degrees per frame.
pub const ROTATION_STEP_DEG: f64 = 2.0;
/// Frames in one turn of the rotation animation: 90 steps of [`ROTATION_STEP_DEG`] make
/// 180°, after which every xform draws its direction again.
pub const FRAMES_PER_TURN: u32 = 90;

/// Rotate an xform's triangle about its centroid: L′ = R·L, O′ = C + R(O − C).
/// Centroid and determinant are unchanged.
pub fn rotate_about_centroid(m: &Affine, angle: f64) -> Affine {
    let t = m.triangle();
    let c = [
        (t[0][0] + t[1][0] + t[2][0]) / 3.0,
        (t[0][1] + t[1][1] + t[2][1]) / 3.0,
    ];
    let (s, co) = angle.sin_cos();
    let r = t.map(|p| {
        let (dx, dy) = (p[0] - c[0], p[1] - c[1]);
        [c[0] + dx * co - dy * s, c[1] + dx * s + dy * co]
    });
    Affine::from_triangle(r)
}

/// Fraktalai's animation: every standard xform turns about its centroid, 2° a frame, in
/// 180° turns whose direction each xform draws at random at the start of every turn.
#[derive(Clone, Debug)]
pub struct RotationAnimation {
    rng: FastRng,
    dirs: Vec<f64>,
    frame: u32,
}

impl RotationAnimation {
    /// An animation at frame 0 whose turn directions are drawn from a generator seeded with
    /// `seed` (the same seed turns the same xforms the same way).
    pub fn new(seed: u64) -> RotationAnimation {
        RotationAnimation {
            rng: FastRng::new(seed),
            dirs: Vec::new(),
            frame: 0,
        }
    }

    /// Frames advanced so far.
    pub fn frame(&self) -> u32 {
        self.frame
    }

    /// Advance one frame: turn the triangles of `flame` by one step.
    pub fn step(&mut self, flame: &mut Flame) {
        if self.frame.is_multiple_of(FRAMES_PER_TURN) || self.dirs.len() != flame.xforms.len() {
            self.dirs = (0..flame.xforms.len())
                .map(|_| if self.rng.bit() { 1.0 } else { -1.0 })
                .collect();
        }
        let step = ROTATION_STEP_DEG.to_radians();
        for (x, d) in flame.xforms.iter_mut().zip(&self.dirs) {
            x.coefs = rotate_about_centroid(&x.coefs, d * step);
        }
        self.frame += 1;
    }
}

/// `frames` frames of the rotation animation, starting with the flame itself.
pub fn rotation_frames(flame: &Flame, frames: usize, seed: u64) -> Vec<Flame> {
    let mut anim = RotationAnimation::new(seed);
    let mut f = flame.clone();
    let mut out = Vec::with_capacity(frames);
    for _ in 0..frames {
        out.push(f.clone());
        anim.step(&mut f);
    }
    out
}

/// The flame a fraction `t` ∈ [0, 1] of the way from `a` to `b`, blended as flam3 blends two
/// control points (see [`crate::flame::interpolate`]): xforms paired by index and padded to
/// match, affine maps in polar form, palettes in HSV, camera and tone settings linearly.
pub fn interpolate(a: &Flame, b: &Flame, t: f64) -> Flame {
    let (mut a, mut b) = (a.clone(), b.clone());
    let name = format!("{}-{}-{:.3}", a.name, b.name, t);
    a.anim.time = 0.0;
    b.anim.time = 1.0;
    let mut f = interpolate_at(&[a, b], t.clamp(0.0, 1.0));
    f.name = name;
    f.seed = None;
    f
}

/// `frames` frames through the flames in order (the first frame is the first flame, the last
/// frame the last flame), spread evenly over the segments between consecutive flames.
pub fn interpolation_frames(flames: &[Flame], frames: usize) -> Vec<Flame> {
    match (flames.len(), frames) {
        (0, _) | (_, 0) => Vec::new(),
        (1, n) => vec![flames[0].clone(); n],
        (_, 1) => vec![flames[0].clone()],
        (m, n) => {
            let keys: Vec<Flame> = flames
                .iter()
                .enumerate()
                .map(|(i, f)| {
                    let mut f = f.clone();
                    f.anim.time = i as f64;
                    f
                })
                .collect();
            (0..n)
                .map(|k| interpolate_at(&keys, k as f64 * (m - 1) as f64 / (n - 1) as f64))
                .collect()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::model::{Var, Xform};
    use crate::flame::variations;
    use crate::gradient::Gradient;

    fn tri_flame() -> Flame {
        Flame {
            name: "a".into(),
            xforms: vec![
                Xform::linear(Affine::new(0.5, -0.2, 0.3, 0.6, 0.1, -0.4), 0.5, 0.0),
                Xform::linear(Affine::new(-0.4, 0.1, 0.2, 0.5, 0.7, 0.2), 0.5, 1.0),
            ],
            ..Flame::default()
        }
    }

    #[test]
    fn a_full_turn_restores_the_coefficients() {
        // Oracle: 180 steps of 2° restore every coefficient within 1e-12 relative;
        // centroid and |det| are invariant at every step.
        let m = Affine::new(0.5, -0.2, 0.3, 0.6, 0.1, -0.4);
        let c0 = centroid(&m);
        let mut r = m;
        for _ in 0..180 {
            r = rotate_about_centroid(&r, 2f64.to_radians());
            let c = centroid(&r);
            assert!((c[0] - c0[0]).abs() < 1e-12 && (c[1] - c0[1]).abs() < 1e-12);
            assert!((r.det().abs() - m.det().abs()).abs() < 1e-12);
        }
        for (p, q) in r.to_coefs().iter().zip(m.to_coefs()) {
            assert!((p - q).abs() <= 1e-12 * q.abs().max(1.0), "{r:?} vs {m:?}");
        }
    }

    fn centroid(m: &Affine) -> [f64; 2] {
        let t = m.triangle();
        [
            (t[0][0] + t[1][0] + t[2][0]) / 3.0,
            (t[0][1] + t[1][1] + t[2][1]) / 3.0,
        ]
    }

    #[test]
    fn rotation_animation_turns_by_two_degrees_and_changes_direction_per_turn() {
        let f = tri_flame();
        let frames = rotation_frames(&f, 181, 7);
        assert_eq!(frames.len(), 181);
        assert_eq!(frames[0], f);
        // Each step turns column (a, c) of every xform by exactly ±2°.
        for w in frames.windows(2).take(5) {
            for (x, y) in w[0].xforms.iter().zip(&w[1].xforms) {
                let d = (y.coefs.c.atan2(y.coefs.a) - x.coefs.c.atan2(x.coefs.a)).to_degrees();
                assert!((d.abs() - 2.0).abs() < 1e-9, "{d}");
            }
        }
        // Determinants (and so determinant-rule weights) never change.
        for fr in &frames {
            for (x, y) in fr.xforms.iter().zip(&f.xforms) {
                assert!((x.coefs.det() - y.coefs.det()).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn interpolation_ends_and_polar_midpoint() {
        let a = tri_flame();
        let mut b = tri_flame();
        b.name = "b".into();
        // b: xform 0 turned by 90° and doubled (columns), translation moved.
        let m = a.xforms[0].coefs;
        b.xforms[0].coefs = Affine {
            a: -2.0 * m.c,
            c: 2.0 * m.a,
            b: -2.0 * m.d,
            d: 2.0 * m.b,
            e: 1.1,
            f: 0.6,
        };
        b.xforms[1].vars = vec![Var::new(variations::SWIRL, 1.0)];
        let f0 = interpolate(&a, &b, 0.0);
        let f1 = interpolate(&a, &b, 1.0);
        let near = |x: &Affine, y: &Affine| {
            x.to_coefs()
                .iter()
                .zip(y.to_coefs())
                .all(|(p, q)| (p - q).abs() < 1e-12)
        };
        assert!(near(&f0.xforms[0].coefs, &a.xforms[0].coefs));
        assert!(near(&f1.xforms[0].coefs, &b.xforms[0].coefs));
        assert_eq!(f1.xforms[1].vars, b.xforms[1].vars);
        let h = interpolate(&a, &b, 0.5);
        let g = h.xforms[0].coefs;
        // Column (a, c) turned by 45° with magnitude √2 times the original (log midpoint of 1, 2).
        let ra = m.a.hypot(m.c);
        assert!((g.a.hypot(g.c) - ra * 2f64.sqrt()).abs() < 1e-12);
        let turn = (g.c.atan2(g.a) - m.c.atan2(m.a)).to_degrees();
        assert!((turn - 45.0).abs() < 1e-9, "{turn}");
        assert!((g.e - (0.1 + 1.1) / 2.0).abs() < 1e-15);
        // Variations cross-fade: half linear, half swirl.
        let v = &h.xforms[1].vars;
        assert_eq!(v.len(), 2);
        assert!(v.iter().all(|v| (v.weight - 0.5).abs() < 1e-15));
    }

    #[test]
    fn missing_xforms_fade_in_by_weight_and_sequences_hit_every_key() {
        let a = tri_flame();
        let mut b = tri_flame();
        b.xforms.push(Xform::linear(Affine::IDENTITY, 0.25, 0.5));
        let h = interpolate(&a, &b, 0.5);
        assert_eq!(h.xforms.len(), 3);
        assert!((h.xforms[2].weight - 0.125).abs() < 1e-15);
        // The identity survives the polar blend up to rounding (cos 90° is 6e-17).
        let g = h.xforms[2].coefs.to_coefs();
        assert!(
            g.iter()
                .zip(Affine::IDENTITY.to_coefs())
                .all(|(p, q)| (p - q).abs() < 1e-15)
        );
        let mut c = tri_flame();
        c.center = [1.0, 2.0];
        let seq = interpolation_frames(&[a.clone(), b.clone(), c.clone()], 5);
        assert_eq!(seq.len(), 5);
        assert_eq!(seq[0].xforms[0].weight, a.xforms[0].weight);
        assert_eq!(seq[0].xforms[1].vars, a.xforms[1].vars);
        assert_eq!(
            seq[0].xforms[2].weight, 0.0,
            "b's extra xform is absent at the start"
        );
        assert_eq!(seq[2].xforms.len(), 3);
        assert_eq!(seq[4].center, c.center);
    }

    #[test]
    fn palettes_blend_through_hsv() {
        let mut red = tri_flame();
        red.palette = Gradient::from_rgb("r", &[[1.0, 0.0, 0.0]; 256]);
        let mut green = tri_flame();
        green.palette = Gradient::from_rgb("g", &[[0.0, 1.0, 0.0]; 256]);
        let mid = interpolate(&red, &green, 0.5).palette;
        // Hue halfway between red (0) and green (2) is yellow (1), fully saturated.
        let c = mid.colors[10];
        assert!((c[0] - 1.0).abs() < 1e-12 && (c[1] - 1.0).abs() < 1e-12 && c[2].abs() < 1e-12);
    }
}
