//! Automatic framing: trimmed bounds of a short orbit (Fraktalai's `GetBounds`
//! with its defects corrected).

use crate::flame::chaos::{Chaos, FUSE};
use crate::flame::model::Flame;
use crate::flame::rng::FastRng;

/// Points used by the framing orbit.
pub const FRAMING_POINTS: usize = 1000;

/// A camera found by automatic framing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Framing {
    pub center: [f64; 2],
    pub scale: f64,
    /// Bounds [lo, hi] per axis (5th and 95th percentiles).
    pub x_bounds: [f64; 2],
    pub y_bounds: [f64; 2],
}

/// Percentile bounds of one axis by Fraktalai's bisection (11 halvings).
pub fn trimmed_bounds(values: &[f64]) -> [f64; 2] {
    let n = values.len();
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let mut mn = (lo + hi) / 2.0;
    let mut mx = mn;
    let mut delta = (hi - lo) / 4.0;
    let limit = (0.05 * n as f64).round() as usize;
    for _ in 0..11 {
        let below = values.iter().filter(|&&p| p < mn).count();
        let above = values.iter().filter(|&&p| p > mx).count();
        mn += if below < limit { delta } else { -delta };
        mx += if above < limit { -delta } else { delta };
        delta /= 2.0;
    }
    [mn, mx]
}

/// Frame a point set for a W×H image: centre of the trimmed bounds, 70 % fill.
pub fn frame_points(xs: &[f64], ys: &[f64], width: u32, height: u32) -> Framing {
    if xs.is_empty() {
        return Framing {
            center: [0.0, 0.0],
            scale: 10.0,
            x_bounds: [0.0, 0.0],
            y_bounds: [0.0, 0.0],
        };
    }
    let xb = trimmed_bounds(xs);
    let yb = trimmed_bounds(ys);
    let wx = xb[1] - xb[0];
    let wy = yb[1] - yb[0];
    let scale = if wx > 0.001 && wy > 0.001 {
        0.7 * (width as f64 / wx).min(height as f64 / wy)
    } else {
        10.0
    };
    Framing {
        center: [(xb[0] + xb[1]) / 2.0, (yb[0] + yb[1]) / 2.0],
        scale,
        x_bounds: xb,
        y_bounds: yb,
    }
}

/// Run the framing orbit: exactly `n` good points of the chaos game (post and final xforms
/// included), from generator seed 12346. A bad value restarts the orbit with a new fuse.
pub fn framing_orbit(chaos: &Chaos, n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut rng = FastRng::new(12346);
    let mut xs = Vec::with_capacity(n);
    let mut ys = Vec::with_capacity(n);
    let mut bad = 0usize;
    let mut skipped = 0usize;
    'restart: while xs.len() < n && bad < 10 * n {
        let mut p = Chaos::start_point(&mut rng);
        let mut last = None;
        for _ in 0..FUSE {
            let i = chaos.choose(last, &mut rng);
            let (np, is_bad) = chaos.xforms[i].apply(p, &mut rng);
            if is_bad {
                bad += 1;
                continue 'restart;
            }
            (p, last) = (np, Some(i));
        }
        while xs.len() < n {
            let i = chaos.choose(last, &mut rng);
            let (np, is_bad, hidden) = chaos.xforms[i].apply_hiding(p, &mut rng);
            if is_bad {
                bad += 1;
                continue 'restart;
            }
            (p, last) = (np, Some(i));
            let (q, fin_hidden) = chaos.finalise_hiding(p, &mut rng);
            let q = chaos.project(q, &mut rng);
            let (px, py) = (q.x, q.y);
            // Hidden samples are not drawn, so they do not frame the picture either (and a
            // flame that hides everything ends the orbit, as too many bad values do).
            if hidden || fin_hidden {
                skipped += 1;
                if skipped >= 10 * n {
                    break 'restart;
                }
                continue;
            }
            if px.is_finite() && py.is_finite() {
                xs.push(px);
                ys.push(py);
            }
        }
    }
    if xs.len() < n {
        xs.clear();
        ys.clear();
    }
    (xs, ys)
}

/// Frame a flame for its own image size. Returns `None` when the flame cannot be iterated.
pub fn auto_frame(flame: &Flame) -> Option<Framing> {
    if flame.ifs3d.is_some() {
        let (xs, ys) = crate::flame::ifs3d::framing_points(flame, FRAMING_POINTS)?;
        return Some(frame_points(&xs, &ys, flame.width, flame.height));
    }
    let chaos = Chaos::new(flame).ok()?;
    let (xs, ys) = framing_orbit(&chaos, FRAMING_POINTS);
    Some(frame_points(&xs, &ys, flame.width, flame.height))
}

/// Apply automatic framing to a flame: centre and scale set, zoom and rotate reset.
pub fn apply_auto_frame(flame: &mut Flame) {
    if let Some(f) = auto_frame(flame) {
        flame.center = f.center;
        flame.scale = f.scale;
        flame.zoom = 0.0;
        flame.rotate = 0.0;
        flame.has_camera = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::model::{Affine, Xform};

    #[test]
    fn thesis_oracle() {
        let xs: Vec<f64> = (0..1000).map(|k| k as f64).collect();
        let ys: Vec<f64> = (0..1000).map(|k| 2.0 * k as f64).collect();
        let f = frame_points(&xs, &ys, 640, 480);
        assert_eq!(f.x_bounds, [49.023193359375, 949.976806640625]);
        assert_eq!(f.y_bounds, [98.04638671875, 1899.95361328125]);
        assert_eq!(f.center, [499.5, 999.0]);
        assert!((f.scale - 0.1864691).abs() < 1e-7, "{}", f.scale);
    }

    #[test]
    fn hidden_samples_do_not_frame_and_a_flame_hiding_all_ends() {
        use crate::flame::variations::by_name;
        // crop_stars hides what its signed distance puts outside the star, the origin among
        // them, and a hidden point comes to the origin: once one is hidden, all are. The
        // translation keeps the first points outside.
        let crop = by_name("crop_stars").unwrap();
        let mut x = Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 2.0, 0.0), 1.0, 0.0);
        x.vars = vec![crate::flame::model::Var::new(crop, 1.0)];
        let fl = Flame {
            xforms: vec![x],
            ..Flame::default()
        };
        let ch = Chaos::new(&fl).unwrap();
        let (xs, _) = framing_orbit(&ch, 1000);
        assert!(xs.len() < 1000, "{}", xs.len());
        assert!(
            xs.iter().all(|&x| x != 0.0),
            "a hidden point framed the picture"
        );
    }

    #[test]
    fn sierpinski_is_framed_around_its_triangle() {
        let mut fl = Flame {
            width: 200,
            height: 200,
            ..Flame::default()
        };
        for (e, f) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)] {
            fl.xforms.push(Xform::linear(
                Affine::new(0.5, 0.0, 0.0, 0.5, e, f),
                1.0,
                0.0,
            ));
        }
        let fr = auto_frame(&fl).unwrap();
        // The attractor is the triangle (0,0), (2,0), (0,2).
        assert!(fr.x_bounds[0] > -0.01 && fr.x_bounds[1] < 2.01);
        assert!(fr.center[0] > 0.5 && fr.center[0] < 1.2);
        assert!(fr.scale > 60.0 && fr.scale < 120.0, "{}", fr.scale);
    }

    #[test]
    fn degenerate_flames_fall_back() {
        let f = frame_points(&[], &[], 100, 100);
        assert_eq!(f.center, [0.0, 0.0]);
        assert_eq!(f.scale, 10.0);
        // A single fixed point: zero width.
        let f = frame_points(&[1.0; 100], &[2.0; 100], 100, 100);
        assert_eq!(f.scale, 10.0);
        assert_eq!(f.center, [1.0, 2.0]);
    }
}
