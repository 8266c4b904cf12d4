//! Animation: the thesis program's rotating triangles, and in-betweens of two or more flames
//! (flam3's interpolation).

use crate::flame::model::{Affine, Flame, Var, Xform};
use crate::flame::rng::FastRng;
use crate::gradient::{Gradient, hsv_to_rgb, rgb_to_hsv};

/// Angular step of the rotation animation: 2° per frame, 90 frames per 180° turn.
pub const ROTATION_STEP_DEG: f64 = 2.0;
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

/// The thesis animation: every standard xform turns about its centroid, 2° a frame, in
/// 180° turns whose direction each xform draws at random at the start of every turn.
#[derive(Clone, Debug)]
pub struct RotationAnimation {
    rng: FastRng,
    dirs: Vec<f64>,
    frame: u32,
}

impl RotationAnimation {
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

fn lerp(a: f64, b: f64, t: f64) -> f64 {
    a + (b - a) * t
}

/// Interpolate one column (x, y) of a linear part in polar form: angle along the shorter
/// turn, magnitude logarithmically (flam3's "log" interpolation); linear when a column is 0.
fn lerp_column(a: [f64; 2], b: [f64; 2], t: f64) -> [f64; 2] {
    if a == b {
        return a;
    }
    let (ra, rb) = (a[0].hypot(a[1]), b[0].hypot(b[1]));
    if ra < 1e-12 || rb < 1e-12 {
        return [lerp(a[0], b[0], t), lerp(a[1], b[1], t)];
    }
    let (ta, mut tb) = (a[1].atan2(a[0]), b[1].atan2(b[0]));
    let pi = std::f64::consts::PI;
    if tb - ta > pi {
        tb -= 2.0 * pi;
    } else if tb - ta < -pi {
        tb += 2.0 * pi;
    }
    let r = (lerp(ra.ln(), rb.ln(), t)).exp();
    let th = lerp(ta, tb, t);
    [r * th.cos(), r * th.sin()]
}

/// Interpolate an affine map: linear part column by column in polar form, translation
/// linearly. t = 0 and t = 1 return the end points exactly.
pub fn lerp_affine(a: &Affine, b: &Affine, t: f64) -> Affine {
    if t <= 0.0 {
        return *a;
    }
    if t >= 1.0 {
        return *b;
    }
    let x = lerp_column([a.a, a.c], [b.a, b.c], t);
    let y = lerp_column([a.b, a.d], [b.b, b.d], t);
    Affine {
        a: x[0],
        c: x[1],
        b: y[0],
        d: y[1],
        e: lerp(a.e, b.e, t),
        f: lerp(a.f, b.f, t),
    }
}

fn lerp_vars(a: &[Var], b: &[Var], t: f64) -> Vec<Var> {
    let mut out: Vec<Var> = Vec::new();
    for v in a {
        let other = b.iter().find(|w| w.id == v.id && w.form == v.form);
        let (wb, pb) = match other {
            Some(w) => (w.weight, w.params.clone()),
            None => (0.0, v.params.clone()),
        };
        out.push(Var {
            id: v.id,
            form: v.form,
            weight: lerp(v.weight, wb, t),
            params: v
                .params
                .iter()
                .zip(pb.iter().chain(std::iter::repeat(&0.0)))
                .map(|(p, q)| lerp(*p, *q, t))
                .collect(),
            // Texts cannot be blended: the first flame's until the middle, then the second's.
            texts: match other {
                Some(w) if t >= 0.5 => w.texts.clone(),
                _ => v.texts.clone(),
            },
        });
    }
    for w in b
        .iter()
        .filter(|w| !a.iter().any(|v| v.id == w.id && v.form == w.form))
    {
        out.push(Var {
            id: w.id,
            form: w.form,
            weight: lerp(0.0, w.weight, t),
            params: w.params.clone(),
            texts: w.texts.clone(),
        });
    }
    out.retain(|v| v.weight != 0.0);
    out
}

fn lerp_xform(a: &Xform, b: &Xform, t: f64) -> Xform {
    Xform {
        weight: lerp(a.weight, b.weight, t),
        color: lerp(a.color, b.color, t),
        color_speed: lerp(a.color_speed, b.color_speed, t),
        opacity: lerp(a.opacity, b.opacity, t),
        coefs: lerp_affine(&a.coefs, &b.coefs, t),
        direct_color: lerp(a.direct_color, b.direct_color, t),
        post: lerp_affine(&a.post, &b.post, t),
        vars: lerp_vars(&a.vars, &b.vars, t),
        chaos: (0..a.chaos.len().max(b.chaos.len()))
            .map(|j| {
                lerp(
                    a.chaos.get(j).copied().unwrap_or(1.0),
                    b.chaos.get(j).copied().unwrap_or(1.0),
                    t,
                )
            })
            .collect(),
        extra_attrs: if t < 0.5 {
            a.extra_attrs.clone()
        } else {
            b.extra_attrs.clone()
        },
        extra_children: Vec::new(),
    }
}

/// A stand-in for a missing xform: the other flame's xform with weight 0, so that it fades in
/// (or out) by weight without changing shape.
fn absent(x: &Xform) -> Xform {
    Xform {
        weight: 0.0,
        ..x.clone()
    }
}

/// Palettes blend entry by entry in HSV, hue along the shorter way (flam3's
/// `palette_interpolation="hsv_circular"`).
pub fn lerp_palette(a: &Gradient, b: &Gradient, t: f64) -> Gradient {
    let colors = a
        .colors
        .iter()
        .zip(&b.colors)
        .map(|(ca, cb)| {
            let ha = rgb_to_hsv([ca[0], ca[1], ca[2]]);
            let hb = rgb_to_hsv([cb[0], cb[1], cb[2]]);
            let mut dh = hb[0] - ha[0];
            if dh > 3.0 {
                dh -= 6.0;
            } else if dh < -3.0 {
                dh += 6.0;
            }
            // A grey end keeps the other's hue.
            let h = if ha[1] < 1e-9 {
                hb[0]
            } else if hb[1] < 1e-9 {
                ha[0]
            } else {
                ha[0] + dh * t
            };
            let rgb = hsv_to_rgb([h, lerp(ha[1], hb[1], t), lerp(ha[2], hb[2], t)]);
            [rgb[0], rgb[1], rgb[2], lerp(ca[3], cb[3], t)]
        })
        .collect();
    Gradient {
        name: if t < 0.5 {
            a.name.clone()
        } else {
            b.name.clone()
        },
        colors,
        stops: Vec::new(),
        map_entries: None,
    }
}

/// The flame a fraction `t` of the way from `a` to `b` (flam3-style: xforms paired by index,
/// missing ones faded in by weight, affine maps in polar form, palettes in HSV, camera and
/// tone settings linearly). Size, quality and other render settings come from `a`.
pub fn interpolate(a: &Flame, b: &Flame, t: f64) -> Flame {
    let t = t.clamp(0.0, 1.0);
    let n = a.xforms.len().max(b.xforms.len());
    let xforms = (0..n)
        .map(|i| match (a.xforms.get(i), b.xforms.get(i)) {
            (Some(x), Some(y)) => lerp_xform(x, y, t),
            (Some(x), None) => lerp_xform(x, &absent(x), t),
            (None, Some(y)) => lerp_xform(&absent(y), y, t),
            (None, None) => unreachable!(),
        })
        .collect();
    let identity_final = Xform {
        weight: 0.0,
        color_speed: 0.0,
        ..Xform::default()
    };
    let final_xform = match (&a.final_xform, &b.final_xform) {
        (None, None) => None,
        (Some(x), Some(y)) => Some(lerp_xform(x, y, t)),
        // The identity (linear, x → x) final xform changes nothing: blend from or to it.
        (Some(x), None) => Some(lerp_xform(x, &identity_final, t)).filter(|_| t < 1.0),
        (None, Some(y)) => Some(lerp_xform(&identity_final, y, t)).filter(|_| t > 0.0),
    };
    let mut f = a.clone();
    f.name = format!("{}-{}-{:.3}", a.name, b.name, t);
    f.xforms = xforms;
    f.final_xform = final_xform;
    f.center = [
        lerp(a.center[0], b.center[0], t),
        lerp(a.center[1], b.center[1], t),
    ];
    // Scale geometrically, so that a zoom runs at a steady speed.
    f.scale = if a.scale > 0.0 && b.scale > 0.0 {
        (lerp(a.scale.ln(), b.scale.ln(), t)).exp()
    } else {
        lerp(a.scale, b.scale, t)
    };
    f.zoom = lerp(a.zoom, b.zoom, t);
    f.rotate = lerp(a.rotate, b.rotate, t);
    f.brightness = lerp(a.brightness, b.brightness, t);
    f.contrast = lerp(a.contrast, b.contrast, t);
    f.gamma = lerp(a.gamma, b.gamma, t);
    f.gamma_threshold = lerp(a.gamma_threshold, b.gamma_threshold, t);
    f.vibrancy = lerp(a.vibrancy, b.vibrancy, t);
    f.highlight_power = lerp(a.highlight_power, b.highlight_power, t);
    for k in 0..3 {
        f.background[k] = lerp(a.background[k], b.background[k], t);
    }
    f.palette = if t <= 0.0 {
        a.palette.clone()
    } else if t >= 1.0 {
        b.palette.clone()
    } else {
        lerp_palette(&a.palette, &b.palette, t)
    };
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
        (m, n) => (0..n)
            .map(|k| {
                let s = k as f64 * (m - 1) as f64 / (n - 1) as f64;
                let i = (s.floor() as usize).min(m - 2);
                interpolate(&flames[i], &flames[i + 1], s - i as f64)
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::variations;

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
        assert_eq!(f0.xforms[0].coefs, a.xforms[0].coefs);
        assert_eq!(f1.xforms[0].coefs, b.xforms[0].coefs);
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
        assert_eq!(h.xforms[2].coefs, Affine::IDENTITY);
        let mut c = tri_flame();
        c.center = [1.0, 2.0];
        let seq = interpolation_frames(&[a.clone(), b.clone(), c.clone()], 5);
        assert_eq!(seq.len(), 5);
        assert_eq!(seq[0].xforms[..2], a.xforms[..]);
        assert_eq!(
            seq[0].xforms[2].weight, 0.0,
            "b's extra xform is absent at the start"
        );
        assert_eq!(seq[2].xforms.len(), 3);
        assert_eq!(seq[4].center, c.center);
    }

    #[test]
    fn palettes_blend_through_hsv() {
        let red = Gradient::from_rgb("r", &[[1.0, 0.0, 0.0]; 256]);
        let green = Gradient::from_rgb("g", &[[0.0, 1.0, 0.0]; 256]);
        let mid = lerp_palette(&red, &green, 0.5);
        // Hue halfway between red (0) and green (2) is yellow (1), fully saturated.
        let c = mid.colors[10];
        assert!((c[0] - 1.0).abs() < 1e-12 && (c[1] - 1.0).abs() < 1e-12 && c[2].abs() < 1e-12);
    }
}
